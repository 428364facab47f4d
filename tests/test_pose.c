// Posing a state from fold angles (ori_mechanism_pose_state): rounded angles are closed exactly,
// the pose keeps every edge length, and angles that are not a state are refused.
#include <math.h>

#include "support.h"

TestSuite(pose, .init = test_leak_setup, .fini = test_leak_check);

// The open corner's first fold at 60°, its angles rounded to 6 decimals of a degree (as a FOLD
// file stores them): posing closes them to the residual tolerance, moves them by less than the
// rounding, and keeps every edge length to 1e-12 relative.
Test(pose, rounded_angles_are_closed_exactly)
{
    test_open_corner c = test_open_corner_load();
    ori_motion_def d = ori_default_motion_def();
    d.fixed_face = c.t2;
    d.driven_edge = c.diag;
    d.to_rad = ori_deg_to_rad(60.0);
    d.step_rad = ori_deg_to_rad(10.0);
    int lock[1] = {c.down};
    d.locked_edges = lock;
    d.locked_count = 1;
    ori_motion *mo = NULL;
    ori_error err;
    cr_assert_eq(ori_motion_solve(c.m, &d, &mo, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_VALID);
    int ne = ori_pattern_edge_count(c.p), nv = ori_pattern_vertex_count(c.p);
    const double *exact = ori_motion_frame_angles(mo, ori_motion_frame_count(mo) - 1);
    double rounded[16], closed[16];
    for (int e = 0; e < ne; ++e) rounded[e] = ori_deg_to_rad(round(ori_rad_to_deg(exact[e]) * 1e6) / 1e6);
    cr_assert_gt(ori_mechanism_residual(c.m, rounded), 1e-10, "rounding must open the loops for this test");
    ori_v3 pos[16];
    ori_rigid poses[8];
    cr_assert_eq(ori_mechanism_pose_state(c.m, rounded, c.t2, ori_rigid_identity(), closed, pos, poses, &err), ORI_OK,
                 "%s", err.message);
    cr_assert_leq(ori_mechanism_residual(c.m, closed), 1e-10);
    for (int e = 0; e < ne; ++e) cr_assert_leq(fabs(closed[e] - rounded[e]), ori_deg_to_rad(1e-5), "edge %d", e);
    for (int e = 0; e < ne; ++e) {
        ori_edge ed = ori_pattern_edge(c.p, e);
        double flat = ori_v3_norm(ori_v3_sub(ori_pattern_vertex(c.p, ed.v[1]), ori_pattern_vertex(c.p, ed.v[0])));
        double posed = ori_v3_norm(ori_v3_sub(pos[ed.v[1]], pos[ed.v[0]]));
        cr_assert_leq(fabs(posed - flat), 1e-12 * flat, "edge %d: %.17g vs %.17g", e, posed, flat);
    }
    (void)nv;
    ori_motion_destroy(mo);
    test_open_corner_free(&c);
}

// Fold angles that do not close (the diagonal alone at 90°) are not a state: ORI_ERR_ARGUMENT;
// an angle beyond 180° is out of range and names its edge.
Test(pose, angles_that_do_not_close_are_refused)
{
    test_open_corner c = test_open_corner_load();
    double a[16] = {0};
    a[c.diag] = ori_deg_to_rad(90.0);
    ori_error err;
    ori_v3 pos[16];
    cr_assert_eq(ori_mechanism_pose_state(c.m, a, c.t2, ori_rigid_identity(), NULL, pos, NULL, &err), ORI_ERR_ARGUMENT);
    a[c.diag] = ori_deg_to_rad(190.0);
    cr_assert_eq(ori_mechanism_pose_state(c.m, a, c.t2, ori_rigid_identity(), NULL, pos, NULL, &err), ORI_ERR_RANGE);
    cr_assert_eq(err.element, c.diag);
    test_open_corner_free(&c);
}
