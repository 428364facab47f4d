// What the language bindings (python/) use: the whole-motion blocks they view without copying
// (ori_motion_angles, ori_motion_vertices, ori_multifold_angles, ori_multifold_vertices,
// ori_record_angles, ori_record_vertices) — each holds exactly what the per-frame getters give —,
// the state between a multifold's frames (ori_multifold_at), which closes, and the bound on a
// target fold's steps (ori_target_fold_def.max_steps) that keeps a design-search step short.
#include <math.h>
#include <string.h>

#include "support.h"

// Every frame k of the block equals the per-frame getters bit for bit.
static void check_blocks(const double *angles, int stride, const ori_v3 *vertices, int frames, int E, int V,
                         const double *(*frame_angles)(const void *, int), void (*frame_vertices)(const void *, int, ori_v3 *),
                         const void *src)
{
    cr_assert(angles && vertices && stride >= E);
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)(V + 1));
    for (int k = 0; k < frames; ++k) {
        cr_assert_eq(memcmp(angles + (size_t)k * (size_t)stride, frame_angles(src, k), sizeof(double) * (size_t)E), 0,
                     "frame %d angles", k);
        frame_vertices(src, k, pos);
        cr_assert_eq(memcmp(vertices + (size_t)k * (size_t)V, pos, sizeof(ori_v3) * (size_t)V), 0, "frame %d vertices", k);
    }
    free(pos);
}

static const double *motion_frame_angles(const void *m, int k) { return ori_motion_frame_angles(m, k); }
static void motion_frame_vertices(const void *m, int k, ori_v3 *p) { ori_motion_frame_vertices(m, k, p); }
static const double *multifold_frame_angles(const void *m, int k) { return ori_multifold_frame_angles(m, k); }
static void multifold_frame_vertices(const void *m, int k, ori_v3 *p) { ori_multifold_frame_vertices(m, k, p); }
Test(bindings, motion_blocks_match_the_frames, .init = test_leak_setup, .fini = test_leak_check)
{
    test_open_corner c = test_open_corner_load();
    ori_motion_def d = ori_default_motion_def();
    d.fixed_face = c.t2;
    d.driven_edge = c.diag;
    d.to_rad = ORI_PI;
    d.step_rad = ORI_PI / 6;
    d.locked_edges = &c.down;
    d.locked_count = 1;
    ori_motion *mo = test_solve(c.m, &d);
    int F = ori_motion_frame_count(mo), E = ori_pattern_edge_count(c.p), V = ori_pattern_vertex_count(c.p);
    cr_assert_eq(F, 7);
    int stride = -1;
    const double *a = ori_motion_angles(mo, &stride);
    const ori_v3 *v = ori_motion_vertices(mo);
    cr_assert_eq(ori_motion_vertices(mo), v, "computed once, then kept");
    check_blocks(a, stride, v, F, E, V, motion_frame_angles, motion_frame_vertices, mo);
    // The thesis' values at 90° (frame 3): right 35.26°, up 60° (asin(1/√3) exactly, 1e-12 rad).
    cr_assert_float_eq(a[3 * stride + c.up], ORI_PI / 3, 1e-12);
    cr_assert_float_eq(a[3 * stride + c.right], asin(1 / sqrt(3.0)), 1e-12);
    ori_motion_destroy(mo);
    // No frames: NULL blocks.
    d.solver = ORI_SOLVER_NUMERIC;
    d.locked_count = 0; // two degrees of freedom: underdetermined, no frames
    mo = test_solve(c.m, &d);
    cr_assert_eq(ori_motion_frame_count(mo), 0);
    cr_assert_null(ori_motion_angles(mo, NULL));
    cr_assert_null(ori_motion_vertices(mo));
    ori_motion_destroy(mo);
    test_open_corner_free(&c);
}

Test(bindings, multifold_blocks_and_states_between_frames, .init = test_leak_setup, .fini = test_leak_check)
{
    ori_pattern *p = test_load_pattern(test_repo_path("tests/data/waterbomb-base.fold"), 0);
    ori_mechanism *m = test_mechanism_of(p);
    ori_target_fold_def d = ori_default_target_fold_def();
    d.step_rad = ori_deg_to_rad(20);
    ori_multifold *mf = NULL;
    ori_error err;
    cr_assert_eq(ori_target_fold_solve(m, &d, &mf, &err), ORI_OK, "%s", err.message);
    int F = ori_multifold_frame_count(mf), E = ori_pattern_edge_count(p), V = ori_pattern_vertex_count(p);
    cr_assert_gt(F, 2);
    int stride;
    const double *a = ori_multifold_angles(mf, &stride);
    const ori_v3 *v = ori_multifold_vertices(mf);
    check_blocks(a, stride, v, F, E, V, multifold_frame_angles, multifold_frame_vertices, mf);
    double *at = malloc(sizeof(double) * (size_t)(E + 1));
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)(V + 1));
    // At a frame's progress: that frame exactly.
    double p1 = ori_multifold_frame_progress(mf, 1);
    cr_assert_eq(ori_multifold_at(mf, NULL, 0, p1, at, pos, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(memcmp(at, a + stride, sizeof(double) * (size_t)E), 0);
    // Between two frames: a closed state (residual at the solver's tolerance) between them.
    double mid = 0.5 * (ori_multifold_frame_progress(mf, 1) + ori_multifold_frame_progress(mf, 2));
    cr_assert_eq(ori_multifold_at(mf, NULL, 0, mid, at, pos, &err), ORI_OK, "%s", err.message);
    cr_assert_leq(ori_mechanism_residual(m, at), ORI_TOL_RESIDUAL);
    for (int e = 0; e < E; ++e) {
        double lo = fmin(a[stride + e], a[2 * stride + e]), hi = fmax(a[stride + e], a[2 * stride + e]);
        cr_assert(at[e] >= lo - 1e-3 && at[e] <= hi + 1e-3, "edge %d: %g not near [%g, %g]", e, at[e], lo, hi);
    }
    ori_v3 *want = malloc(sizeof(ori_v3) * (size_t)(V + 1));
    ori_mechanism_vertex_positions(m, at, 0, ori_rigid_identity(), want);
    cr_assert_eq(memcmp(want, pos, sizeof(ori_v3) * (size_t)V), 0);
    // Outside the frames: a range error.
    cr_assert_eq(ori_multifold_at(mf, NULL, 0, 1.5, at, NULL, &err), ORI_ERR_RANGE);
    cr_assert_eq(ori_multifold_at(mf, NULL, 0, -0.1, at, NULL, &err), ORI_ERR_RANGE);
    free(want);
    free(pos);
    free(at);
    ori_multifold_destroy(mf);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

Test(bindings, record_blocks_match_the_states, .init = test_leak_setup, .fini = test_leak_check)
{
    char *text = test_read_text(test_repo_path("examples/open-corner.seq.json"));
    cr_assert(text);
    ori_sequence *s = NULL;
    ori_error err;
    cr_assert_eq(ori_sequence_parse(text, strlen(text), &s, &err), ORI_OK, "%s", err.message);
    free(text);
    test_open_corner c = test_open_corner_load();
    cr_assert_eq(ori_sequence_resolve(s, c.p, &err), ORI_OK, "%s", err.message);
    ori_record *r = NULL;
    cr_assert_eq(ori_sequence_run(s, c.m, NULL, ori_rigid_identity(), &r, &err), ORI_OK, "%s", err.message);
    int F = ori_record_frame_count(r), E = ori_pattern_edge_count(c.p), V = ori_pattern_vertex_count(c.p);
    cr_assert_gt(F, 2);
    int stride;
    const double *a = ori_record_angles(r, &stride);
    const ori_v3 *v = ori_record_vertices(r);
    cr_assert(a && v && stride >= E);
    for (int k = 0; k < F; ++k) {
        cr_assert_eq(a + (size_t)k * (size_t)stride, ori_record_frame_angles(r, k), "state %d", k);
        cr_assert_eq(v + (size_t)k * (size_t)V, ori_record_frame_vertices(r, k), "state %d", k);
    }
    ori_record_destroy(r);
    ori_sequence_destroy(s);
    test_open_corner_free(&c);
}

Test(bindings, target_fold_max_steps_bounds_the_continuation, .init = test_leak_setup, .fini = test_leak_check)
{
    ori_pattern *p = test_load_pattern(test_repo_path("tests/data/waterbomb-base.fold"), 0);
    ori_mechanism *m = test_mechanism_of(p);
    ori_target_fold_def d = ori_default_target_fold_def();
    cr_assert_eq(d.max_steps, 0, "default: the library's bound");
    ori_multifold *mf = NULL;
    ori_error err;
    cr_assert_eq(ori_target_fold_solve(m, &d, &mf, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_multifold_verdict_of(mf), ORI_MULTIFOLD_REACHED, "%s", ori_multifold_reason(mf));
    int steps;
    ori_multifold_stats(mf, &steps, NULL, NULL);
    cr_assert_gt(steps, 3);
    ori_multifold_destroy(mf);
    d.max_steps = 3;
    cr_assert_eq(ori_target_fold_solve(m, &d, &mf, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_multifold_verdict_of(mf), ORI_MULTIFOLD_STATIONARY);
    cr_assert(strstr(ori_multifold_reason(mf), "within 3 steps"), "%s", ori_multifold_reason(mf));
    int bounded;
    ori_multifold_stats(mf, &bounded, NULL, NULL);
    cr_assert_eq(bounded, 3);
    int F = ori_multifold_frame_count(mf);
    cr_assert_geq(F, 1);
    double pr = ori_multifold_frame_progress(mf, F - 1);
    cr_assert(pr > 0.0 && pr < 1.0, "progress %g", pr);
    cr_assert_leq(ori_multifold_frame_residual(mf, F - 1), ORI_TOL_RESIDUAL);
    ori_multifold_destroy(mf);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}
