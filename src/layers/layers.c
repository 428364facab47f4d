// Public API of the layer solver: set-up in stages (local check, fold, overlap, constraints,
// propagation and components), counting, state selection, queries and FOLD output.
#include "layers_internal.h"

#include <orikin/flat.h>
#include <stdio.h>
#include <stdlib.h>

ori_layers_def ori_default_layers_def(void)
{
    ori_layers_def d;
    memset(&d, 0, sizeof d);
    d.face_transforms = NULL;
    d.face_transform_count = 0;
    d.limit = ORI_LAYERS_NO_LIMIT;
    d.threads = 1;
    d.snap_rel = ORI_LAYERS_SNAP_AUTO;
    d.progress = NULL;
    d.progress_user = NULL;
    d.internal_value = ORI__DEF_COOKIE;
    return d;
}

const char *ori_layers_constraint_name(ori_layers_constraint c)
{
    static const char *names[] = {"taco_taco",  "taco_tortilla", "tortilla_tortilla", "transitivity",
                                  "assignment", "local",         "exhausted"};
    return (c >= 0 && c < ORI_LAYERS_CONSTRAINT_COUNT) ? names[c] : "unknown";
}

void ori_layers_destroy(ori_layers *L)
{
    if (!L) return;
    ori__free(L->ev);
    ori__free(L->ef);
    ori__free(L->asg);
    ori__csr_free(&L->face_edges);
    ori__free(L->vf);
    ori__free(L->xf);
    ori__free(L->flip);
    ori__free(L->pts);
    ori__free(L->seg_pts);
    ori__free(L->seg_cells);
    ori__csr_free(&L->seg_edges);
    ori__csr_free(&L->edge_segs);
    ori__csr_free(&L->cell_segs);
    ori__csr_free(&L->cell_faces);
    ori__csr_free(&L->face_cells);
    ori__free(L->var_faces);
    ori__csr_free(&L->face_nbrs);
    ori__free(L->face_nbr_var);
    ori__free(L->equiv);
    ori__free(L->taco);
    ori__csr_free(&L->var_tacos);
    ori__free(L->stacks);
    ori__free(L->stack_faces);
    ori__free(L->stack_vars);
    ori__free(L->slots);
    ori__free(L->var_slot_off);
    ori__free(L->fslots);
    ori__free(L->var_fslot_off);
    ori__free(L->var_class);
    ori__free(L->var_par);
    ori__free(L->class_weight);
    ori__free(L->class_tied);
    ori__free(L->cc_node);
    ori__csr_free(&L->class_vars);
    ori__free(L->class_val);
    ori__free(L->var_val);
    ori__csr_free(&L->comp_classes);
    ori__free(L->comp_vars);
    if (L->comp_count) {
        for (int j = 0; j < L->n_comp; ++j) ori__nat_free(&L->comp_count[j]);
        ori__free(L->comp_count);
    }
    ori__nat_free(&L->total);
    ori__free(L->conflict_faces);
    ori__free(L->state);
    ori__free(L->state_k);
    ori__free(L);
}

// Local flat-foldability first: a vertex that cannot fold flat by itself is the clearest
// reason there is no state (and without Kawasaki the sheet does not even fold consistently).
// Kawasaki is held to ORI_TOL_KAWASAKI_RAD (as orikin check does), or to the snapping
// tolerance when the caller loosened it for an imprecise drawing; the exact test of the M/V
// assignment then runs on the nearest sectors that satisfy Kawasaki exactly (the alternating
// sum's error spread evenly, which keeps their total).
static void local_fail(ori_layers *L, const ori_pattern *p, int v, const char *rule, const char *detail)
{
    L->unsat = true;
    L->conflict.constraint = ORI_LAYERS_LOCAL;
    L->conflict.face_count = 0;
    for (int i = 0; i < 4; ++i) L->conflict.faces[i] = -1;
    L->conflict.vertex = v;
    L->conflict.component = -1;
    snprintf(L->conflict.detail, sizeof L->conflict.detail, "vertex %d is not locally flat-foldable (%s): %.120s", v,
             rule, detail);
    int deg = ori_pattern_vertex_degree(p, v);
    int *edges = ori__alloc(sizeof(int) * (size_t)(deg ? deg : 1));
    ori_pattern_vertex_edges(p, v, edges, deg);
    uint8_t *mark = ori__calloc((size_t)(L->nf ? L->nf : 1), 1);
    for (int i = 0; i < deg; ++i) {
        int fc[2];
        ori_pattern_edge_faces(p, edges[i], fc);
        for (int k = 0; k < 2; ++k)
            if (fc[k] >= 0) mark[fc[k]] = 1;
    }
    int n = 0;
    for (int f = 0; f < L->nf; ++f) n += mark[f];
    L->conflict_faces = ori__alloc(sizeof(int) * (size_t)(n ? n : 1));
    for (int f = 0; f < L->nf; ++f)
        if (mark[f]) L->conflict_faces[L->n_conflict_faces++] = f;
    ori__free(mark);
    ori__free(edges);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static bool local_check(ori_layers *L, const ori_pattern *p)
{
    // Loosened (--tolerance above the default, or a tolerance chosen from the drawing): Kawasaki
    // holds within the tolerance in radians, or when moving the vertex by the tolerance (× the
    // diagonal) would fix it — the sum times the vertex's shortest crease.
    bool loose = L->snap_rel > ORI_TOL_LAYERS_SNAP_REL || L->snap_auto;
    double lo_x = 1e300, lo_y = 1e300, hi_x = -1e300, hi_y = -1e300;
    for (int v = 0; v < L->nv; ++v) {
        ori_v3 q = ori_pattern_vertex(p, v);
        lo_x = fmin(lo_x, q.x), hi_x = fmax(hi_x, q.x), lo_y = fmin(lo_y, q.y), hi_y = fmax(hi_y, q.y);
    }
    double diag = L->nv ? hypot(hi_x - lo_x, hi_y - lo_y) : 1.0;
    if (!(diag > 0.0)) diag = 1.0;
    double kaw_tol = loose ? fmax(L->snap_rel, ORI_TOL_KAWASAKI_RAD) : ORI_TOL_KAWASAKI_RAD;
    int cap = 0;
    int *edges = NULL;
    double *sec = NULL, *snap = NULL, *sorted = NULL;
    ori_assignment *asg = NULL;
    bool ok = true;
    char detail[160];
    for (int v = 0; v < L->nv && ok; ++v) {
        if (!ori_pattern_vertex_is_interior(p, v)) continue;
        int deg = ori_pattern_vertex_degree(p, v);
        if (deg > cap) {
            cap = deg;
            edges = ori__realloc(edges, sizeof(int) * (size_t)cap);
            sec = ori__realloc(sec, sizeof(double) * (size_t)cap);
            snap = ori__realloc(snap, sizeof(double) * (size_t)cap);
            sorted = ori__realloc(sorted, sizeof(double) * (size_t)cap);
            asg = ori__realloc(asg, sizeof(ori_assignment) * (size_t)cap);
        }
        int n = ori_flat_vertex_creases(p, v, edges, sec, cap);
        if (n <= 0) continue;
        if (n % 2) {
            snprintf(detail, sizeof detail, "%d creases meet there; a flat vertex has an even number", n);
            local_fail(L, p, v, "kawasaki", detail);
            ok = false;
            break;
        }
        double K = ori_flat_kawasaki_sum(sec, n);
        // The shortest crease there: an angle error θ is a displacement of about θ × its length.
        double lmin = 1e300;
        for (int i = 0; i < n; ++i) {
            ori_edge ed = ori_pattern_edge(p, edges[i]);
            ori_v3 a = ori_pattern_vertex(p, ed.v[0]), b = ori_pattern_vertex(p, ed.v[1]);
            lmin = fmin(lmin, hypot(b.x - a.x, b.y - a.y));
        }
        if (!(fabs(K) <= kaw_tol) && !(loose && fabs(K) * lmin / diag <= L->snap_rel)) {
            if (loose)
                snprintf(detail, sizeof detail,
                         "alternating sector sum is %g deg (%.3g rad), beyond %.3g rad and a move of %.3g of the sheet",
                         ori_rad_to_deg_output(K), K, kaw_tol, L->snap_rel);
            else
                snprintf(detail, sizeof detail, "alternating sector sum is %g deg (%.3g rad), beyond %.3g rad",
                         ori_rad_to_deg_output(K), K, kaw_tol);
            local_fail(L, p, v, "kawasaki", detail);
            L->conflict.kawasaki_rad = K;
            L->fail_need = fmin(fabs(K), fabs(K) * lmin / diag);
            ok = false;
            break;
        }
        double vnoise = fabs(K), vgap = 0.0;
        // The nearest Kawasaki-exact sectors: with the tolerance loosened for a rounded drawing,
        // sectors within it of each other are the equal sectors the drawing meant (else
        // big-little-big would see a strictly smallest one among them); otherwise the sum's
        // error is spread evenly.
        double snapped = loose ? ori_flat_snap_sectors(sec, n, kaw_tol, snap) : INFINITY;
        if (snapped <= fmax(kaw_tol, fabs(K))) {
            // The gaps taken for equal: between consecutive sorted sectors, at most the tolerance.
            memcpy(sorted, sec, sizeof(double) * (size_t)n);
            qsort(sorted, (size_t)n, sizeof(double), cmp_double);
            for (int i = 0; i + 1 < n; ++i) {
                double gap = sorted[i + 1] - sorted[i];
                if (gap <= kaw_tol && gap > vgap) vgap = gap;
            }
            memcpy(sec, snap, sizeof(double) * (size_t)n);
        } else
            for (int i = 0; i < n; ++i) sec[i] -= (i % 2 == 0 ? K : -K) / n;
        if (vgap > L->noise_gap) L->noise_gap = vgap;
        vnoise = fmax(vnoise, vgap);
        if (vnoise > L->noise_ang) L->noise_ang = vnoise;
        if (vnoise * lmin / diag > L->noise_ang_len) L->noise_ang_len = vnoise * lmin / diag;
        int nm = 0, nvv = 0, nu = 0;
        for (int i = 0; i < n; ++i) {
            asg[i] = L->asg[edges[i]];
            nm += asg[i] == ORI_ASSIGN_MOUNTAIN;
            nvv += asg[i] == ORI_ASSIGN_VALLEY;
            nu += asg[i] == ORI_ASSIGN_UNASSIGNED;
        }
        ori_mv_count c = ori_flat_count_completions(sec, asg, n);
        if (c.count > 0 || c.overflow) continue;
        ok = false;
        int run = 0;
        int first = ori_flat_big_little_big(sec, asg, n, &run);
        if (nu == 0 && abs(nm - nvv) != 2) {
            snprintf(detail, sizeof detail, "%d mountain and %d valley creases; Maekawa needs M - V = +-2", nm, nvv);
            local_fail(L, p, v, "maekawa", detail);
        } else if (first != ORI_NULL_INDEX) {
            snprintf(detail, sizeof detail,
                     "the %d creases from edge %d around the smallest sectors there break big-little-big", run,
                     edges[first]);
            local_fail(L, p, v, "big_little_big", detail);
        } else {
            snprintf(detail, sizeof detail, "no crimp sequence folds its %d creases flat with their assignment", n);
            local_fail(L, p, v, "assignment", detail);
        }
    }
    ori__free(edges);
    ori__free(sec);
    ori__free(snap);
    ori__free(sorted);
    ori__free(asg);
    return ok;
}

// The set-up at one snapping length.
static ori_status create_at(const ori_pattern *p, const ori_layers_def *def, double snap_rel, bool from_drawing,
                            ori_layers **out, ori_error *error, double *fail_amb, double *fail_need)
{
    *out = NULL;
    int nf = ori_pattern_face_count(p);
    ori_layers *L = ori__calloc(1, sizeof *L);
    L->nv = ori_pattern_vertex_count(p);
    L->ne = ori_pattern_edge_count(p);
    L->nf = nf;
    L->limit = def->limit;
    L->threads = def->threads;
    L->snap_rel = snap_rel;
    L->snap_auto = from_drawing;
    L->progress = def->progress;
    L->progress_user = def->progress_user;
    L->transforms_known = def->face_transforms != NULL || !ori_pattern_is_folded_form(p);
    ori__nat_init(&L->total);
    L->ev = ori__alloc(sizeof(*L->ev) * (size_t)(L->ne ? L->ne : 1));
    L->ef = ori__alloc(sizeof(*L->ef) * (size_t)(L->ne ? L->ne : 1));
    L->asg = ori__alloc(sizeof(ori_assignment) * (size_t)(L->ne ? L->ne : 1));
    for (int e = 0; e < L->ne; ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        L->ev[e][0] = ed.v[0];
        L->ev[e][1] = ed.v[1];
        L->asg[e] = ed.assignment;
        ori_pattern_edge_faces(p, e, L->ef[e]);
    }
    L->face_edges.rows = nf;
    L->face_edges.off = ori__alloc(sizeof(int64_t) * (size_t)(nf + 1));
    int64_t total = 0;
    for (int f = 0; f < nf; ++f) {
        L->face_edges.off[f] = total;
        total += ori_pattern_face_size(p, f);
    }
    L->face_edges.off[nf] = total;
    L->face_edges.items = ori__alloc(sizeof(int) * (size_t)(total ? total : 1));
    for (int f = 0; f < nf; ++f)
        ori_pattern_face_edges(p, f, L->face_edges.items + L->face_edges.off[f], ori_pattern_face_size(p, f));
    ori__layers_tables(L);

    ori_status st = ORI_OK;
    if (!local_check(L, p)) {
        if (fail_need) *fail_need = L->fail_need;
        // No state; the geometry is not needed (and may not exist).
        L->counted = true;
        *out = L;
        return ORI_OK;
    }
    st = ori__layers_fold(L, p, def, error);
    if (st == ORI_OK) st = ori__layers_overlap(L, error);
    if (st == ORI_OK) st = ori__layers_constraints(L, error);
    if (st == ORI_OK) st = ori__layers_presolve(L, error);
    if (st != ORI_OK) {
        if (fail_amb) *fail_amb = L->fail_amb;
        if (fail_need) *fail_need = L->fail_need;
        ori_layers_destroy(L);
        return st;
    }
    if (L->unsat) {
        L->counted = true;
        if (L->conflict.detail[0] == '\0') {
            const int *F = L->conflict.faces;
            switch (L->conflict.constraint) {
            case ORI_LAYERS_TACO_TACO:
                snprintf(L->conflict.detail, sizeof L->conflict.detail,
                         "taco-taco: the folds of faces %d|%d and %d|%d would cross", F[0], F[1], F[2], F[3]);
                break;
            case ORI_LAYERS_TACO_TORTILLA:
                snprintf(L->conflict.detail, sizeof L->conflict.detail,
                         "taco-tortilla: face %d would have to lie between faces %d and %d across their fold", F[2],
                         F[0], F[1]);
                break;
            case ORI_LAYERS_TORTILLA_TORTILLA:
                snprintf(L->conflict.detail, sizeof L->conflict.detail,
                         "tortilla-tortilla: faces %d, %d and %d, %d cannot keep one order across their common line",
                         F[0], F[1], F[2], F[3]);
                break;
            case ORI_LAYERS_TRANSITIVITY:
                snprintf(L->conflict.detail, sizeof L->conflict.detail,
                         "transitivity: faces %d, %d and %d would form a cycle", F[0], F[1], F[2]);
                break;
            default: break;
            }
        }
    }
    *out = L;
    return ORI_OK;
}

// Two set-ups took the same decisions (same overlap structure, variables, constraints, verdict).
static bool same_setup(const ori_layers *a, const ori_layers *b)
{
    return a->np == b->np && a->ns == b->ns && a->nc == b->nc && a->nvar == b->nvar && a->n_equiv == b->n_equiv &&
           a->n_taco == b->n_taco && a->unsat == b->unsat && a->n_comp == b->n_comp &&
           a->count_kind[ORI_LAYERS_TRANSITIVITY] == b->count_kind[ORI_LAYERS_TRANSITIVITY];
}

#define ORI__TIGHT_RERUN_VARS 100000

ori_status ori_layers_create(const ori_pattern *p, const ori_layers_def *def, ori_layers **out, ori_error *error)
{
    ORI_ASSERT(p && out);
    *out = NULL;
    ori_layers_def dd = ori_default_layers_def();
    if (!def) def = &dd;
    ORI_ASSERT(def->internal_value == ORI__DEF_COOKIE);
    ORI_ASSERT(def->threads >= 1 && def->snap_rel >= 0.0);
    if (!ori_pattern_is_built(p)) return ori__fail(error, ORI_ERR_ARGUMENT, "the pattern is not built");
    int nf = ori_pattern_face_count(p);
    if (def->face_transforms && def->face_transform_count != nf)
        return ori__fail_at(error, ORI_ERR_ARGUMENT, "faces_flatFoldTransform", def->face_transform_count,
                            "%d transforms for %d faces", def->face_transform_count, nf);
    if (nf == 0) return ori__fail(error, ORI_ERR_TOPOLOGY, "the pattern has no faces");
    if (def->snap_rel > 0.0) return create_at(p, def, def->snap_rel, false, out, error, NULL, NULL);

    // A tolerance from the drawing's own precision (in the spirit of Flat-Folder, which shrinks
    // its epsilon from the shortest edge / 8 until the feature counts stop changing): from the
    // coarsest snapping length below the shortest edge / 8, the first one at which the set-up
    // decides everything (no distance between it and ORI_LAYERS_AMBIGUITY_FACTOR times it, the
    // sheet folds consistently, every vertex is locally flat-foldable) and everything it took for
    // "the same" (lengths relative to the diagonal, angles in radians) lies at most a quarter of
    // it: a gap in the drawing's distances from that noise to 10 times the length, so every
    // length in between decides alike. None such: the default ORI_TOL_LAYERS_SNAP_REL.
    double lo_x = 1e300, lo_y = 1e300, hi_x = -1e300, hi_y = -1e300, shortest = 1e300;
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        ori_v3 q = ori_pattern_vertex(p, v);
        lo_x = fmin(lo_x, q.x), hi_x = fmax(hi_x, q.x), lo_y = fmin(lo_y, q.y), hi_y = fmax(hi_y, q.y);
    }
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        ori_v3 a = ori_pattern_vertex(p, ed.v[0]), b = ori_pattern_vertex(p, ed.v[1]);
        shortest = fmin(shortest, hypot(b.x - a.x, b.y - a.y));
    }
    double diag = hypot(hi_x - lo_x, hi_y - lo_y);
    double top = diag > 0.0 && shortest < 1e300 ? fmin(1e-2, shortest / diag / 8.0) : ORI_TOL_LAYERS_SNAP_REL;
    // The search keeps the lengths that may work in [lo, hi): a distance d met in the ambiguous
    // band wants a length below d / 10, one that must be reached (a vertex folded apart, a
    // Kawasaki sum as a move) a length above it, and noise too close to the length (above a
    // quarter of it) either a length 4 times it or one below a tenth of it. It tries the coarsest
    // length first and then halves (at least), as Flat-Folder does.
    double lo = 0.0, hi = top * 1.0000001, r = top;
    for (int it = 0; it < 48 && r >= ORI_TOL_LAYERS_SNAP_REL && lo < hi; ++it) {
        ori_layers *L = NULL;
        ori_error e2;
        ori_error_clear(&e2);
        double amb = 0.0, need = 0.0;
        ori_status st = create_at(p, def, r, true, &L, &e2, &amb, &need);
        bool decided = st == ORI_OK && !(L->unsat && L->conflict.constraint == ORI_LAYERS_LOCAL);
        double noise = decided ? fmax(L->noise_len, L->noise_ang_len) : 0.0;
        if (decided && noise <= 0.25 * r) {
            // Every length from the noise up to r decides alike; report (and run at) the
            // tightest one with a margin: 4 × the noise (and the sector gaps taken for equal),
            // at least the default. Above ORI__TIGHT_RERUN_VARS variables the second set-up
            // costs seconds for the same decisions: r itself is kept.
            double tight = fmin(r, fmax(ORI_TOL_LAYERS_SNAP_REL, 4.0 * fmax(noise, L->noise_gap)));
            ori_layers *T = NULL;
            if (tight < r && L->nvar <= ORI__TIGHT_RERUN_VARS && create_at(p, def, tight, true, &T, &e2, NULL, NULL) == ORI_OK && same_setup(L, T)) {
                ori_layers_destroy(L);
                L = T;
            } else
                ori_layers_destroy(T);
            *out = L;
            return ORI_OK;
        }
        ori_layers_destroy(L);
        if (decided) {
            if (4.04 * noise < hi) lo = fmax(lo, 4.04 * noise);
            else hi = fmin(hi, 0.1 * noise);
        } else if (amb > 0.0)
            hi = fmin(hi, 0.099 * amb);
        else if (need > 0.0)
            lo = fmax(lo, 1.05 * need);
        else
            hi = fmin(hi, r); // any other refusal: a finer length
        double next = r < lo ? lo : fmin(0.99 * hi, 0.5 * r);
        r = next < lo ? lo : next;
    }
    // Nothing accepted: the strict default (its Kawasaki in radians), reported as chosen.
    ori_status st = create_at(p, def, ORI_TOL_LAYERS_SNAP_REL, false, out, error, NULL, NULL);
    if (st == ORI_OK) (*out)->snap_auto = true;
    return st;
}

ori_status ori_layers_count(ori_layers *L, ori_error *error)
{
    ORI_ASSERT(L);
    if (L->counted) return ORI_OK;
    return ori__layers_solve(L, error);
}

ori_layers_info ori_layers_get_info(const ori_layers *L)
{
    ORI_ASSERT(L);
    ori_layers_info in;
    memset(&in, 0, sizeof in);
    in.faces = L->nf;
    in.variables = L->nvar;
    in.taco_taco = L->count_kind[ORI_LAYERS_TACO_TACO];
    in.taco_tortilla = L->count_kind[ORI_LAYERS_TACO_TORTILLA];
    in.tortilla_tortilla = L->count_kind[ORI_LAYERS_TORTILLA_TORTILLA];
    in.transitivity = L->count_kind[ORI_LAYERS_TRANSITIVITY];
    in.points = L->np;
    in.segments = L->ns;
    in.cells = L->nc;
    in.classes = L->n_class;
    in.fixed_variables = L->n_comp > 0 ? L->comp_vars[0] : 0;
    in.components = L->n_comp;
    in.counted = L->counted;
    in.limited = L->limited;
    in.stopped = L->stopped;
    in.satisfiable = !L->unsat;
    in.tolerance = L->snap_rel;
    in.tolerance_from_drawing = L->snap_auto;
    in.noise_length = L->noise_len;
    in.noise_angle = L->noise_ang;
    return in;
}

bool ori_layers_get_conflict(const ori_layers *L, ori_layers_conflict *out)
{
    ORI_ASSERT(L);
    if (!L->unsat) return false;
    if (out) *out = L->conflict;
    return true;
}

int ori_layers_conflict_faces(const ori_layers *L, int *out, int cap)
{
    ORI_ASSERT(L);
    if (!L->unsat) return 0;
    if (L->conflict_faces) {
        for (int i = 0; i < L->n_conflict_faces && i < cap; ++i) out[i] = L->conflict_faces[i];
        return L->n_conflict_faces;
    }
    int f[4], n = L->conflict.face_count;
    memcpy(f, L->conflict.faces, sizeof f);
    for (int i = 1; i < n; ++i)
        for (int j = i; j > 0 && f[j] < f[j - 1]; --j) {
            int t = f[j];
            f[j] = f[j - 1];
            f[j - 1] = t;
        }
    int m = 0;
    for (int i = 0; i < n; ++i)
        if (i == 0 || f[i] != f[i - 1]) {
            if (m < cap) out[m] = f[i];
            m++;
        }
    return m;
}

char *ori_layers_state_count(const ori_layers *L)
{
    ORI_ASSERT(L && L->counted);
    if (L->unsat) return ori__strdup("0");
    return ori__nat_to_decimal(&L->total);
}

int ori_layers_component_count(const ori_layers *L)
{
    ORI_ASSERT(L);
    return L->n_comp;
}

char *ori_layers_component_states(const ori_layers *L, int c)
{
    ORI_ASSERT(L && L->counted && c >= 0 && c < L->n_comp && L->comp_count);
    return ori__nat_to_decimal(&L->comp_count[c]);
}

int ori_layers_component_variables(const ori_layers *L, int c)
{
    ORI_ASSERT(L && c >= 0 && c < L->n_comp);
    return L->comp_vars[c];
}

ori_status ori_layers_select_state(ori_layers *L, const char *k, ori_error *error)
{
    ORI_ASSERT(L && k);
    ori_status st = ori_layers_count(L, error);
    if (st != ORI_OK) return st;
    if (L->unsat) return ori__fail(error, ORI_ERR_RANGE, "there is no state to select");
    if (L->limited) return ori__fail(error, ORI_ERR_UNSUPPORTED, "the count is limited: states cannot be numbered");
    ori__nat kk, q, r;
    ori__nat_init(&kk);
    ori__nat_init(&q);
    ori__nat_init(&r);
    if (!ori__nat_from_decimal(&kk, k)) {
        ori__nat_free(&kk);
        return ori__fail(error, ORI_ERR_RANGE, "state \"%s\" is not a decimal number", k);
    }
    if (ori__nat_cmp(&kk, &L->total) >= 0) {
        ori__nat_free(&kk);
        char *n = ori__nat_to_decimal(&L->total);
        st = ori__fail(error, ORI_ERR_RANGE, "state %s is out of range (there are %s)", k, n);
        ori__free(n);
        return st;
    }
    if (!L->state) L->state = ori__alloc((size_t)(L->nvar ? L->nvar : 1));
    memcpy(L->state, L->var_val, (size_t)L->nvar);
    // Component 1 is the most significant digit.
    ori__nat rest;
    ori__nat_init(&rest);
    ori__nat_copy(&rest, &kk);
    for (int j = L->n_comp - 1; j >= 1 && st == ORI_OK; --j) {
        ori__nat_divmod(&q, &r, &rest, &L->comp_count[j]);
        ori__nat_copy(&rest, &q);
        st = ori__layers_unrank(L, j, &r, L->state, error);
    }
    ori__nat_free(&rest);
    ori__nat_free(&kk);
    ori__nat_free(&q);
    ori__nat_free(&r);
    if (st != ORI_OK) return st;
    L->has_state = true;
    ori__free(L->state_k);
    L->state_k = ori__strdup(k);
    return ORI_OK;
}

int ori_layers_face_above(const ori_layers *L, int f, int g)
{
    ORI_ASSERT(L && f >= 0 && f < L->nf && g >= 0 && g < L->nf);
    if (!L->has_state || f == g || !L->nvar) return 0;
    int v = ori__layers_var(L, f, g);
    if (v < 0) return 0;
    int x = L->state[v];
    return f < g ? x : -x;
}

int ori_layers_face_orders(const ori_layers *L, int *out, int cap)
{
    ORI_ASSERT(L);
    if (!L->has_state) return 0;
    for (int v = 0; v < L->nvar && v < cap; ++v) {
        int f = L->var_faces[v][0], g = L->var_faces[v][1];
        // +1: f lies on the side g's normal points to.
        int s = L->state[v] * (L->flip[g] ? -1 : 1);
        out[3 * v] = f;
        out[3 * v + 1] = g;
        out[3 * v + 2] = s;
    }
    return L->nvar;
}

ori_v2 ori_layers_folded_vertex(const ori_layers *L, int v)
{
    ORI_ASSERT(L && v >= 0 && v < L->nv);
    return L->vf ? L->vf[v] : ori_v2_make(0.0, 0.0);
}

bool ori_layers_face_flipped(const ori_layers *L, int f)
{
    ORI_ASSERT(L && f >= 0 && f < L->nf);
    return L->flip ? L->flip[f] != 0 : false;
}

void ori_layers_face_transform(const ori_layers *L, int f, double out[6])
{
    ORI_ASSERT(L && f >= 0 && f < L->nf);
    if (L->xf) memcpy(out, L->xf[f], sizeof(double) * 6);
    else {
        double id[6] = {1, 0, 0, 0, 1, 0};
        memcpy(out, id, sizeof id);
    }
}

int ori_layers_cell_count(const ori_layers *L)
{
    ORI_ASSERT(L);
    return L->nc;
}

int ori_layers_cell_polygon(const ori_layers *L, int c, ori_v2 *out, int cap)
{
    ORI_ASSERT(L && c >= 0 && c < L->nc);
    int n = 0;
    for (int64_t k = L->cell_segs.off[c]; k < L->cell_segs.off[c + 1]; ++k, ++n) {
        int h = L->cell_segs.items[k];
        if (n < cap) out[n] = L->pts[L->seg_pts[h >> 1][h & 1]];
    }
    return n;
}

int ori_layers_cell_stack(const ori_layers *L, int c, int *out, int cap)
{
    ORI_ASSERT(L && c >= 0 && c < L->nc);
    const int *F = L->cell_faces.items + L->cell_faces.off[c];
    int n = (int)(L->cell_faces.off[c + 1] - L->cell_faces.off[c]);
    if (!L->has_state) {
        for (int i = 0; i < n && i < cap; ++i) out[i] = F[i];
        return n;
    }
    // In a valid state the faces over a cell are totally ordered: the number of them below a
    // face is its height.
    int *below = ori__calloc((size_t)(n ? n : 1), sizeof(int));
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            if (ori_layers_face_above(L, F[i], F[j]) > 0) below[i]++;
            else below[j]++;
        }
    for (int h = n - 1, m = 0; h >= 0; --h)
        for (int i = 0; i < n; ++i)
            if (below[i] == h) {
                if (m < cap) out[m] = F[i];
                m++;
            }
    ori__free(below);
    return n;
}

// --- FOLD output ----------------------------------------------------------------------------

typedef struct text {
    char *s;
    size_t n, cap;
} text;

static void put(text *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void put(text *t, const char *fmt, ...)
{
    for (;;) {
        va_list ap;
        va_start(ap, fmt);
        int need = vsnprintf(t->s ? t->s + t->n : NULL, t->s ? t->cap - t->n : 0, fmt, ap);
        va_end(ap);
        if (t->s && (size_t)need < t->cap - t->n) {
            t->n += (size_t)need;
            return;
        }
        size_t cap = t->cap ? t->cap : 256;
        while (cap < t->n + (size_t)need + 1) cap *= 2;
        t->s = ori__realloc(t->s, cap);
        t->cap = cap;
    }
}

int ori_layers_append_frame(const ori_layers *L, const ori_pattern *p, ori_fold *doc, int parent, ori_error *error)
{
    ORI_ASSERT(L && p && doc);
    if (!L->has_state) {
        ori__fail(error, ORI_ERR_ARGUMENT, "no state selected");
        return -1;
    }
    ori_v3 *pos = ori__alloc(sizeof(ori_v3) * (size_t)(L->nv ? L->nv : 1));
    for (int v = 0; v < L->nv; ++v) pos[v] = ori_v3_make(L->vf[v].x, L->vf[v].y, 0.0);
    double *ang = ori__alloc(sizeof(double) * (size_t)(L->ne ? L->ne : 1));
    char *letters = ori__alloc((size_t)(L->ne ? L->ne : 1));
    for (int e = 0; e < L->ne; ++e) {
        ori_assignment a = L->asg[e];
        int l = L->ef[e][0], r = L->ef[e][1];
        ang[e] = 0.0;
        letters[e] = ori_assignment_to_char(a);
        bool folded = a == ORI_ASSIGN_MOUNTAIN || a == ORI_ASSIGN_VALLEY || a == ORI_ASSIGN_UNASSIGNED;
        if (!folded || l < 0 || r < 0) continue;
        // Valley exactly when the right face lies on the left face's front side.
        bool r_above = ori_layers_face_above(L, r, l) > 0;
        bool valley = r_above != (L->flip[l] != 0);
        ang[e] = valley ? ORI_PI : -ORI_PI;
        letters[e] = valley ? 'V' : 'M';
    }
    char title[96];
    snprintf(title, sizeof title, "flat-folded state %.60s", L->state_k ? L->state_k : "0");
    int frame = ori_fold_append_state(doc, parent, L->nv, pos, L->ne, ang, title);
    ori__free(pos);
    ori__free(ang);
    text t = {0};
    put(&t, "[");
    for (int e = 0; e < L->ne; ++e) put(&t, "%s\"%c\"", e ? "," : "", letters[e]);
    put(&t, "]");
    ori__free(letters);
    ori_status st = ori_fold_set_custom(doc, frame, "edges_assignment", t.s, error);
    // The faces too: a folded form needs them (they cannot be traced from folded coordinates),
    // and the parent may have had none (traced on load).
    t.n = 0;
    put(&t, "[");
    int fv[1024];
    for (int f = 0; f < L->nf; ++f) {
        int n = ori_pattern_face_vertices(p, f, fv, 1024);
        put(&t, "%s[", f ? "," : "");
        for (int k = 0; k < n && k < 1024; ++k) put(&t, "%s%d", k ? "," : "", fv[k]);
        put(&t, "]");
    }
    put(&t, "]");
    if (st == ORI_OK) st = ori_fold_set_custom(doc, frame, "faces_vertices", t.s, error);
    t.n = 0;
    put(&t, "[");
    for (int v = 0; v < L->nvar; ++v) {
        int f = L->var_faces[v][0], g = L->var_faces[v][1];
        put(&t, "%s[%d,%d,%d]", v ? "," : "", f, g, L->state[v] * (L->flip[g] ? -1 : 1));
    }
    put(&t, "]");
    if (st == ORI_OK) st = ori_fold_set_custom(doc, frame, "faceOrders", t.s, error);
    if (st == ORI_OK && L->transforms_known) {
        t.n = 0;
        put(&t, "[");
        for (int f = 0; f < L->nf; ++f)
            put(&t, "%s[[%.17g,%.17g,%.17g],[%.17g,%.17g,%.17g]]", f ? "," : "", L->xf[f][0], L->xf[f][1],
                L->xf[f][2], L->xf[f][3], L->xf[f][4], L->xf[f][5]);
        put(&t, "]");
        st = ori_fold_set_custom(doc, frame, "faces_flatFoldTransform", t.s, error);
    }
    if (st == ORI_OK) {
        t.n = 0;
        put(&t, "[");
        for (int f = 0; f < L->nf; ++f) put(&t, "%s%d", f ? "," : "", L->flip[f] ? -1 : 1);
        put(&t, "]");
        st = ori_fold_set_custom(doc, frame, "faces_flatFoldOrientation", t.s, error);
    }
    ori__free(t.s);
    return st == ORI_OK ? frame : -1;
}
