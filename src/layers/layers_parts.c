// The count of one crease pattern in parts, for a distributed count (cli/sweep/layers_mpi.c):
// count one component alone, and install every component's count computed elsewhere, which
// finishes the solver exactly as ori_layers_count does (the total, an exhausted component).
#include "layers_internal.h"

#include <stdio.h>

ori_status ori_layers_count_component(const ori_layers *L, int c, char **states, bool *limited, ori_error *error)
{
    ORI_ASSERT(L && states);
    *states = NULL;
    if (limited) *limited = false;
    if (c < 0 || c >= L->n_comp)
        return ori__fail(error, ORI_ERR_RANGE, "component %d does not exist (%d components)", c, L->n_comp);
    ori__nat res;
    ori__nat_init(&res);
    bool exact = true;
    if (c == 0) ori__nat_set_u64(&res, 1);
    else ori__layers_count_one(L, c, &res, &exact);
    *states = ori__nat_to_decimal(&res);
    ori__nat_free(&res);
    if (limited) *limited = !exact;
    return ORI_OK;
}

// An exhausted component (no state although propagation found no conflict): the verdict and
// its faces, as ori__layers_solve records them.
void ori__layers_set_exhausted(ori_layers *L, int j)
{
    L->unsat = true;
    L->conflict.constraint = ORI_LAYERS_EXHAUSTED;
    L->conflict.face_count = 0;
    for (int k = 0; k < 4; ++k) L->conflict.faces[k] = -1;
    L->conflict.vertex = ORI_NULL_INDEX;
    L->conflict.component = j;
    uint8_t *mark = ori__calloc((size_t)(L->nf ? L->nf : 1), 1);
    for (int64_t i = L->comp_classes.off[j]; i < L->comp_classes.off[j + 1]; ++i) {
        int c = L->comp_classes.items[i];
        for (int64_t k = L->class_vars.off[c]; k < L->class_vars.off[c + 1]; ++k) {
            int v = L->class_vars.items[k];
            mark[L->var_faces[v][0]] = mark[L->var_faces[v][1]] = 1;
        }
    }
    int cnt = 0;
    for (int f = 0; f < L->nf; ++f) cnt += mark[f];
    ori__free(L->conflict_faces);
    L->conflict_faces = ori__alloc(sizeof(int) * (size_t)(cnt ? cnt : 1));
    L->n_conflict_faces = 0;
    for (int f = 0; f < L->nf; ++f)
        if (mark[f]) L->conflict_faces[L->n_conflict_faces++] = f;
    ori__free(mark);
    snprintf(L->conflict.detail, sizeof L->conflict.detail,
             "no constraint conflicts by propagation, but no order of component %d's %d face pairs (over %d faces) "
             "satisfies them all",
             j, L->comp_vars[j], L->n_conflict_faces);
}

ori_status ori_layers_set_counts(ori_layers *L, const char *const *states, bool limited, ori_error *error)
{
    ORI_ASSERT(L && (states || L->n_comp == 0));
    if (L->counted) return ORI_OK;
    ori__nat *cnt = ori__alloc(sizeof(ori__nat) * (size_t)(L->n_comp ? L->n_comp : 1));
    for (int j = 0; j < L->n_comp; ++j) ori__nat_init(&cnt[j]);
    for (int j = 0; j < L->n_comp; ++j)
        if (!states[j] || !ori__nat_from_decimal(&cnt[j], states[j]) || (j == 0 && ori__nat_cmp_u64(&cnt[j], 1) != 0)) {
            for (int i = 0; i < L->n_comp; ++i) ori__nat_free(&cnt[i]);
            ori__free(cnt);
            return ori__fail(error, ORI_ERR_ARGUMENT, "component %d: '%.40s' is not a state count%s", j,
                             states[j] ? states[j] : "(null)", j == 0 ? " (the fixed part has 1)" : "");
        }
    L->comp_count = cnt;
    L->limited = limited;
    ori__nat_set_u64(&L->total, 1);
    for (int j = 0; j < L->n_comp; ++j) ori__nat_mul(&L->total, &L->comp_count[j]);
    for (int j = 1; j < L->n_comp; ++j)
        if (ori__nat_is_zero(&L->comp_count[j])) {
            ori__layers_set_exhausted(L, j);
            break;
        }
    L->counted = true;
    return ORI_OK;
}
