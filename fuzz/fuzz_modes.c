// libFuzzer target for the folds of several degrees of freedom (ori_target_fold_solve: toward the
// targets, with a fraction, locks and symmetry orbits; ori_drives_fold_solve: several drives) on
// fuzzed patterns (fuzz_kin.h). Invariants: no crash, leak or sanitizer report; every frame's
// angles in [−180°, 180°], its loops closed (residual ≤ 1e-9, measured afresh), its progress in
// [0, 1]; a fold that reached its goal ends on it (1e-9 rad); creases in one symmetry orbit at
// one angle; and for the targets, a second solve with another output step ends with the same
// verdict in the same state (the solver's steps do not depend on the output spacing,
// docs/kinematics.md §16.1). A fold is cancelled after FM_MAX_STEPS accepted steps (its budget).
#include "fuzz_kin.h"

#include <stdbool.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

// One input's work is bounded through the progress callback (called once per accepted step): a
// fold that creeps (every step at the corrector's limit) is cancelled after FM_MAX_STEPS steps.
#define FM_MAX_STEPS 1000
static bool budget(double fraction, void *user)
{
    (void)fraction;
    return ++*(int *)user <= FM_MAX_STEPS;
}

static void check_frames(const ori_mechanism *m, const ori_multifold *mf, const int *group, bool targets, double fraction)
{
    int E = ori_mechanism_edge_count(m);
    for (int f = 0; f < ori_multifold_frame_count(mf); ++f) {
        const double *a = ori_multifold_frame_angles(mf, f);
        for (int e = 0; e < E; ++e) {
            if (!(fabs(a[e]) <= ORI_PI)) abort(); // outside [−180°, 180°] or NaN
            if (group && group[e] >= 0 && fabs(a[e] - a[group[e]]) > 1e-9) abort();
        }
        if (!(ori_multifold_frame_residual(mf, f) <= 1e-9)) abort();
        if (!(ori_mechanism_residual(m, a) <= 1e-9)) abort();
        double pr = ori_multifold_frame_progress(mf, f);
        if (!(pr >= -1e-12 && pr <= 1.0 + 1e-12)) abort();
    }
    // Reached: the targets' goal (the 100 % state) is every crease's; the drives' only theirs
    // (drives()). A fraction below 1 is the way along the motion: the last frame's progress (a
    // start that is the goal already, one frame, has progress 1).
    int n = ori_multifold_frame_count(mf);
    if (targets && fraction < 1.0 && ori_multifold_verdict_of(mf) == ORI_MULTIFOLD_REACHED && n > 1 &&
        !(fabs(ori_multifold_frame_progress(mf, n - 1) - fraction) <= 1e-9))
        abort();
    if (targets && fraction >= 1.0 && ori_multifold_verdict_of(mf) == ORI_MULTIFOLD_REACHED && n > 0) {
        const double *last = ori_multifold_frame_angles(mf, n - 1);
        const double *goal = ori_multifold_goal(mf);
        for (int e = 0; goal && e < E; ++e)
            if (ori_mechanism_edge_joint(m, e) != ORI_NULL_INDEX && fabs(last[e] - goal[e]) > 1e-9) abort();
    }
}

static void targets(fk_bytes *b, const ori_mechanism *m)
{
    int E = ori_mechanism_edge_count(m), F = ori_mechanism_face_count(m);
    ori_target_fold_def d = ori_default_target_fold_def();
    d.fixed_face = F > 0 ? fk_u8(b) % F : 0;
    d.fraction = fk_u8(b) & 1 ? 1.0 : fk_range(b, 0.0, 1.0);
    d.step_rad = fk_range(b, 0.5, 60.0) * FK_DEG;
    int locks[3], nl = fk_u8(b) % 4;
    for (int i = 0; i < nl; ++i) locks[i] = E > 0 ? fk_u8(b) % E : 0;
    d.locked_edges = locks;
    d.locked_count = nl;
    int *group = NULL;
    if (fk_u8(b) & 1) {
        group = malloc(sizeof(int) * (size_t)(E + 1));
        ori_mechanism_symmetry_orbits(m, group);
        d.edge_group = group;
    }
    int spent = 0;
    d.progress = budget;
    d.progress_user = &spent;
    ori_multifold *mf = NULL;
    ori_error err;
    if (ori_target_fold_solve(m, &d, &mf, &err) == ORI_OK) {
        check_frames(m, mf, group, true, d.fraction);
        // Another output step: the same path, so the same verdict and end state.
        ori_target_fold_def d2 = d;
        d2.step_rad = fk_range(b, 0.5, 60.0) * FK_DEG;
        int spent2 = 0;
        d2.progress_user = &spent2;
        ori_multifold *mf2 = NULL;
        if (ori_target_fold_solve(m, &d2, &mf2, &err) != ORI_OK) abort(); // the same steps: not cancelled either
        check_frames(m, mf2, group, true, d2.fraction);
        if (ori_multifold_verdict_of(mf) != ori_multifold_verdict_of(mf2)) abort();
        int n1 = ori_multifold_frame_count(mf), n2 = ori_multifold_frame_count(mf2);
        if ((n1 > 0) != (n2 > 0)) abort();
        if (n1 > 0) {
            const double *a = ori_multifold_frame_angles(mf, n1 - 1), *c = ori_multifold_frame_angles(mf2, n2 - 1);
            for (int e = 0; e < E; ++e)
                if (fabs(a[e] - c[e]) > 1e-9) abort();
        }
        ori_multifold_destroy(mf2);
        ori_multifold_destroy(mf);
    }
    free(group);
}

static void drives(fk_bytes *b, const ori_mechanism *m)
{
    int E = ori_mechanism_edge_count(m), F = ori_mechanism_face_count(m);
    ori_drives_fold_def d = ori_default_drives_fold_def();
    d.fixed_face = F > 0 ? fk_u8(b) % F : 0;
    int drv[3], n = 1 + fk_u8(b) % 3;
    double to[3];
    for (int i = 0; i < n; ++i) {
        drv[i] = E > 0 ? fk_u8(b) % E : 0;
        to[i] = fk_range(b, -180.0, 180.0) * FK_DEG;
    }
    d.driven_edges = drv;
    d.to_rad = to;
    d.driven_count = n;
    d.step_rad = fk_range(b, 1.0, 60.0) * FK_DEG;
    int locks[3], nl = fk_u8(b) % 4;
    for (int i = 0; i < nl; ++i) locks[i] = E > 0 ? fk_u8(b) % E : 0;
    d.locked_edges = locks;
    d.locked_count = nl;
    int spent = 0;
    d.progress = budget;
    d.progress_user = &spent;
    ori_multifold *mf = NULL;
    ori_error err;
    if (ori_drives_fold_solve(m, &d, &mf, &err) == ORI_OK) {
        check_frames(m, mf, NULL, false, 1.0);
        int k = ori_multifold_frame_count(mf);
        if (ori_multifold_verdict_of(mf) == ORI_MULTIFOLD_REACHED && k > 0)
            for (int i = 0; i < n; ++i)
                if (fabs(ori_multifold_frame_angles(mf, k - 1)[drv[i]] - to[i]) > 1e-9) abort();
        ori_multifold_destroy(mf);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fk_bytes b = {data, size, 0};
    ori_pattern *p = NULL;
    ori_mechanism *m = NULL;
    if (fk_mechanism(&b, &p, &m)) {
        if (fk_u8(&b) & 1) drives(&b, m);
        else targets(&b, m);
        ori_mechanism_destroy(m);
        ori_pattern_destroy(p);
    }
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
