// libFuzzer target for the DOF analysis (ori_mechanism_dof): fuzzed patterns (fuzz_kin.h) at the
// flat state and at a folded state reached by a fuzzed fold, with fuzzed locks. Invariants: no
// crash, leak or sanitizer report; 0 ≤ rank ≤ min(equations, unknowns), dof = unknowns − rank,
// a generic DOF (when probed) at most the DOF at the state, singular values finite.
#include "fuzz_kin.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void dof_at(fk_bytes *b, const ori_mechanism *m, const double *angles)
{
    ori_dof_def dd = ori_default_dof_def();
    dd.angles_rad = angles;
    int locks[8], E = ori_mechanism_edge_count(m);
    int nl = fk_u8(b) % 9;
    for (int i = 0; i < nl; ++i) locks[i] = E > 0 ? fk_u8(b) % E : 0;
    dd.locked_edges = locks;
    dd.locked_count = nl;
    dd.probe_generic = fk_u8(b) & 1;
    ori_dof_result r;
    ori_error err;
    if (ori_mechanism_dof(m, &dd, &r, &err) != ORI_OK) return;
    if (r.rank < 0 || r.rank > r.unknowns || r.rank > r.equations) abort();
    if (r.dof != r.unknowns - r.rank) abort();
    if (r.generic_dof > r.dof) abort();
    if (!isfinite(r.sigma_max) || !isfinite(r.sigma_cut) || r.sigma_cut > r.sigma_max) abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fk_bytes b = {data, size, 0};
    ori_pattern *p = NULL;
    ori_mechanism *m = NULL;
    if (fk_mechanism(&b, &p, &m)) {
        ori_error err;
        dof_at(&b, m, NULL);
        int locks[8];
        ori_motion_def d = fk_fold(&b, m, locks);
        ori_motion *mo = NULL;
        if (ori_motion_solve(m, &d, &mo, &err) == ORI_OK) {
            int n = ori_motion_frame_count(mo);
            if (n > 0) dof_at(&b, m, ori_motion_frame_angles(mo, n - 1));
            ori_motion_destroy(mo);
        }
        ori_mechanism_destroy(m);
        ori_pattern_destroy(p);
    }
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
