// The trajectory view (include/orikin/trajectory.h) over the three motion results: its frames are
// the result's own (angles and vertices to 0 difference), its states between frames those the
// result restores itself (to 1e-12), and an instant outside the frames is an error.
#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <orikin/orikin.h>

#include "kinematics/multifold_internal.h" // ori__mf_close: the collision check's old interpolation
#include "support.h"

#define DEG (ORI_PI / 180.0)

static double max_diff(const double *a, const double *b, int n)
{
    double m = 0.0;
    for (int i = 0; i < n; ++i) m = fmax(m, fabs(a[i] - b[i]));
    return m;
}

static double max_diff_v3(const ori_v3 *a, const ori_v3 *b, int n)
{
    double m = 0.0;
    for (int i = 0; i < n; ++i) m = fmax(m, ori_v3_norm(ori_v3_sub(a[i], b[i])));
    return m;
}

// Every frame of the view against the result's own accessors (passed as the frame's angles and
// vertices): the same pointer for the angles, bit-equal vertices.
typedef const double *angles_fn(const void *r, int k);
typedef void vertices_fn(const void *r, int k, ori_v3 *out);

static void check_frames(const ori_trajectory *t, const void *r, int n, angles_fn *angles, vertices_fn *vertices)
{
    cr_assert_eq(ori_trajectory_frame_count(t), n);
    int V = ori_trajectory_vertex_count(t);
    ori_v3 *a = malloc(sizeof(ori_v3) * (size_t)V), *b = malloc(sizeof(ori_v3) * (size_t)V);
    for (int k = 0; k < n; ++k) {
        cr_assert_eq(ori_trajectory_frame_angles(t, k), angles(r, k), "frame %d: the result's own angles", k);
        ori_trajectory_frame_vertices(t, k, a);
        vertices(r, k, b);
        cr_assert_eq(max_diff_v3(a, b, V), 0.0, "frame %d", k);
        // A frame's own parameter gives its own state.
        double *at = malloc(sizeof(double) * (size_t)ori_trajectory_edge_count(t));
        ori_error err;
        cr_assert_eq(ori_trajectory_at(t, ori_trajectory_frame_param(t, k), at, a, NULL, &err), ORI_OK, "%s", err.message);
        cr_assert_lt(max_diff(at, angles(r, k), ori_trajectory_edge_count(t)), 1e-12, "frame %d at its parameter", k);
        free(at);
    }
    free(a);
    free(b);
}

static const double *motion_angles(const void *r, int k) { return ori_motion_frame_angles(r, k); }
static void motion_vertices(const void *r, int k, ori_v3 *out) { ori_motion_frame_vertices(r, k, out); }
static const double *multifold_angles(const void *r, int k) { return ori_multifold_frame_angles(r, k); }
static void multifold_vertices(const void *r, int k, ori_v3 *out) { ori_multifold_frame_vertices(r, k, out); }
static const double *record_angles(const void *r, int k) { return ori_record_frame_angles(r, k); }
static int record_vertex_count; // the record's mechanism's (set by the test)
static void record_vertices(const void *r, int k, ori_v3 *out)
{
    memcpy(out, ori_record_frame_vertices(r, k), sizeof(ori_v3) * (size_t)record_vertex_count);
}

static void assert_out_of_range(const ori_trajectory *t, double x)
{
    double *a = malloc(sizeof(double) * (size_t)(ori_trajectory_edge_count(t) + 1));
    ori_error err;
    cr_assert_eq(ori_trajectory_at(t, x, a, NULL, NULL, &err), ORI_ERR_RANGE, "x = %g", x);
    cr_assert_gt(strlen(err.message), 0);
    free(a);
}

Test(trajectory, motion_frames_and_states_between_them, .init = test_leak_setup, .fini = test_leak_check)
{
    test_open_corner c = test_open_corner_load();
    ori_motion_def d = test_open_corner_first_fold(&c, ori_default_motion_def().solver, 90);
    ori_motion *mo = test_solve(c.m, &d);
    ori_trajectory t = ori_trajectory_of_motion(c.m, &d, mo);
    cr_assert_eq(t.kind, ORI_TRAJECTORY_MOTION);
    int n = ori_motion_frame_count(mo), E = ori_mechanism_edge_count(c.m), V = ori_mechanism_vertex_count(c.m);
    cr_assert_eq(n, 10); // 0°, 10°, …, 90°
    cr_assert_eq(ori_trajectory_vertex_count(&t), V);
    cr_assert_eq(ori_trajectory_edge_count(&t), E);
    check_frames(&t, mo, n, motion_angles, motion_vertices);
    for (int k = 0; k < n; ++k) {
        cr_assert_eq(ori_trajectory_frame_param(&t, k), ori_motion_frame_drive(mo, k));
        cr_assert_eq(ori_trajectory_frame_drive_rad(&t, k), ori_motion_frame_drive(mo, k));
        cr_assert_eq(ori_trajectory_frame_fold(&t, k), 0);
    }
    double first, last;
    cr_assert(ori_trajectory_param_range(&t, &first, &last));
    cr_assert_float_eq(first, 0.0, 1e-15);
    cr_assert_float_eq(last, 90 * DEG, 1e-12);
    // 45°: solved again from the 40° frame in one step, as the collision check's trial states are.
    double x = 45 * DEG, *a = malloc(sizeof(double) * (size_t)E), drive;
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)V), *want_pos = malloc(sizeof(ori_v3) * (size_t)V);
    ori_error err;
    cr_assert_eq(ori_trajectory_at(&t, x, a, pos, &drive, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(drive, x);
    ori_motion_def d2 = d;
    d2.start_angles_rad = ori_motion_frame_angles(mo, 4);
    d2.to_rad = x;
    d2.step_rad = x - ori_motion_frame_drive(mo, 4);
    ori_motion *m2 = test_solve(c.m, &d2);
    int n2 = ori_motion_frame_count(m2);
    cr_assert_eq(n2, 2);
    cr_assert_lt(max_diff(a, ori_motion_frame_angles(m2, n2 - 1), E), 1e-12);
    ori_motion_frame_vertices(m2, n2 - 1, want_pos);
    cr_assert_lt(max_diff_v3(pos, want_pos, V), 1e-12);
    cr_assert_float_eq(a[c.diag], x, 1e-12);
    // Strictly between the 40° and 50° frames' angles of the moving creases.
    for (int e = 0; e < E; ++e) {
        double a0 = ori_motion_frame_angles(mo, 4)[e], a1 = ori_motion_frame_angles(mo, 5)[e];
        cr_assert(a[e] >= fmin(a0, a1) - 1e-12 && a[e] <= fmax(a0, a1) + 1e-12, "edge %d", e);
    }
    assert_out_of_range(&t, -1 * DEG);
    assert_out_of_range(&t, 91 * DEG);
    assert_out_of_range(&t, NAN);
    ori_motion_destroy(m2);
    free(a);
    free(pos);
    free(want_pos);
    ori_motion_destroy(mo);
    test_open_corner_free(&c);
}

Test(trajectory, motion_toward_a_smaller_angle, .init = test_leak_setup, .fini = test_leak_check)
{
    test_open_corner c = test_open_corner_load();
    ori_motion_def d = test_open_corner_first_fold(&c, ori_default_motion_def().solver, -60); // parameters decrease along the frames
    ori_motion *mo = test_solve(c.m, &d);
    ori_trajectory t = ori_trajectory_of_motion(c.m, &d, mo);
    int n = ori_trajectory_frame_count(&t), E = ori_mechanism_edge_count(c.m);
    cr_assert_eq(n, 7);
    cr_assert_lt(ori_trajectory_frame_param(&t, n - 1), ori_trajectory_frame_param(&t, 0));
    double *a = malloc(sizeof(double) * (size_t)E);
    ori_error err;
    cr_assert_eq(ori_trajectory_at(&t, -25 * DEG, a, NULL, NULL, &err), ORI_OK, "%s", err.message);
    cr_assert_float_eq(a[c.diag], -25 * DEG, 1e-12);
    assert_out_of_range(&t, 1 * DEG);
    assert_out_of_range(&t, -61 * DEG);
    free(a);
    ori_motion_destroy(mo);
    test_open_corner_free(&c);
}

Test(trajectory, empty_and_one_frame_motions, .init = test_leak_setup, .fini = test_leak_check)
{
    test_open_corner c = test_open_corner_load();
    // No lock: the open corner has two degrees of freedom, the fold is underdetermined, no frames.
    ori_motion_def d = test_open_corner_first_fold(&c, ori_default_motion_def().solver, 90);
    d.locked_count = 0;
    ori_motion *mo = test_solve(c.m, &d);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_UNDERDETERMINED);
    ori_trajectory t = ori_trajectory_of_motion(c.m, &d, mo);
    cr_assert_eq(ori_trajectory_frame_count(&t), 0);
    cr_assert_not(ori_trajectory_param_range(&t, NULL, NULL));
    assert_out_of_range(&t, 0.0);
    ori_motion_destroy(mo);
    // A fold to where it starts: one frame, the flat start, and only its own instant.
    d = test_open_corner_first_fold(&c, ori_default_motion_def().solver, 0);
    mo = test_solve(c.m, &d);
    t = ori_trajectory_of_motion(c.m, &d, mo);
    cr_assert_eq(ori_trajectory_frame_count(&t), 1);
    check_frames(&t, mo, 1, motion_angles, motion_vertices);
    assert_out_of_range(&t, 1e-9);
    assert_out_of_range(&t, -1e-9);
    ori_motion_destroy(mo);
    test_open_corner_free(&c);
}

Test(trajectory, multifold_frames_and_states_between_them, .init = test_leak_setup, .fini = test_leak_check)
{
    ori_pattern *p = test_load_pattern(test_repo_path("tests/data/waterbomb-base.fold"), 0);
    ori_mechanism *m = test_mechanism_of(p);
    ori_target_fold_def d = ori_default_target_fold_def();
    d.step_rad = 20 * DEG;
    ori_multifold *mf = NULL;
    ori_error err;
    cr_assert_eq(ori_target_fold_solve(m, &d, &mf, &err), ORI_OK, "%s", err.message);
    int n = ori_multifold_frame_count(mf), E = ori_pattern_edge_count(p), V = ori_pattern_vertex_count(p);
    cr_assert_gt(n, 2);
    ori_trajectory t = ori_trajectory_of_multifold(mf, NULL, 0);
    cr_assert_eq(t.kind, ORI_TRAJECTORY_MULTIFOLD);
    check_frames(&t, mf, n, multifold_angles, multifold_vertices);
    for (int k = 0; k < n; ++k) {
        cr_assert_eq(ori_trajectory_frame_param(&t, k), ori_multifold_frame_progress(mf, k));
        cr_assert_eq(ori_trajectory_frame_drive(&t, k), ori_multifold_frame_progress(mf, k));
        cr_assert(isnan(ori_trajectory_frame_drive_rad(&t, k)), "a target fold's drive is its progress");
    }
    // Halfway between frames 1 and 2: their angles interpolated in the progress and closed (the
    // collision check's former interpolation, written out here).
    double x0 = ori_multifold_frame_progress(mf, 1), x1 = ori_multifold_frame_progress(mf, 2), x = 0.5 * (x0 + x1);
    double *a = malloc(sizeof(double) * (size_t)E), *want = malloc(sizeof(double) * (size_t)E), drive;
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)V), *want_pos = malloc(sizeof(ori_v3) * (size_t)V);
    cr_assert_eq(ori_trajectory_at(&t, x, a, pos, &drive, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(drive, x);
    double w = (x - x0) / (x1 - x0);
    const double *a0 = ori_multifold_frame_angles(mf, 1), *a1 = ori_multifold_frame_angles(mf, 2);
    for (int e = 0; e < E; ++e) want[e] = a0[e] + w * (a1[e] - a0[e]);
    cr_assert_eq(ori__mf_close(m, NULL, 0, want, &err), ORI_OK, "%s", err.message);
    cr_assert_lt(max_diff(a, want, E), 1e-12);
    ori_mechanism_vertex_positions(m, want, d.fixed_face, d.fixed_pose, want_pos);
    cr_assert_lt(max_diff_v3(pos, want_pos, V), 1e-12);
    cr_assert_gt(max_diff(a, a0, E), 1e-3, "a state between frames, not a frame");
    assert_out_of_range(&t, -0.01);
    assert_out_of_range(&t, ori_multifold_frame_progress(mf, n - 1) + 0.01);
    free(a);
    free(want);
    free(pos);
    free(want_pos);
    ori_multifold_destroy(mf);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

Test(trajectory, record_frames_and_states_between_them, .init = test_leak_setup, .fini = test_leak_check)
{
    test_open_corner c = test_open_corner_load();
    char json[512];
    snprintf(json, sizeof json,
             "{\"pattern\": \"patterns/open-corner.fold\", \"folds\": ["
             "{\"fix\": %d, \"lock\": [%d], \"drive\": %d, \"to\": 90, \"step\": 10},"
             "{\"fix\": %d, \"lock\": [%d], \"drive\": %d, \"to\": 45, \"step\": 15}]}",
             c.t2, c.down, c.diag, c.t2, c.diag, c.down);
    ori_sequence *s = NULL;
    ori_record *r = NULL;
    ori_error err;
    cr_assert_eq(ori_sequence_parse(json, strlen(json), &s, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_sequence_run(s, c.m, NULL, ori_rigid_identity(), &r, &err), ORI_OK, "%s", err.message);
    int n = ori_record_frame_count(r), E = ori_mechanism_edge_count(c.m), V = ori_mechanism_vertex_count(c.m);
    cr_assert_eq(n, 1 + 9 + 3);
    ori_trajectory t = ori_trajectory_of_record(r);
    cr_assert_eq(t.kind, ORI_TRAJECTORY_RECORD);
    cr_assert_eq(ori_trajectory_vertex_count(&t), V);
    cr_assert_eq(ori_trajectory_edge_count(&t), E);
    record_vertex_count = V;
    check_frames(&t, r, n, record_angles, record_vertices);
    for (int k = 0; k < n; ++k) {
        cr_assert_eq(ori_trajectory_frame_param(&t, k), ori_record_frame_time(r, k));
        cr_assert_eq(ori_trajectory_frame_drive(&t, k), ori_record_frame_drive(r, k));
        cr_assert_eq(ori_trajectory_frame_drive_rad(&t, k), ori_record_frame_drive(r, k));
        cr_assert_eq(ori_trajectory_frame_fold(&t, k), ori_record_frame_fold(r, k));
    }
    cr_assert_eq(ori_trajectory_frame_fold(&t, n - 1), 1);
    // T = 1.5: halfway through the second fold, the down crease at 22.5°.
    double *a = malloc(sizeof(double) * (size_t)E), *want = malloc(sizeof(double) * (size_t)E), drive, want_drive;
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)V), *want_pos = malloc(sizeof(ori_v3) * (size_t)V);
    cr_assert_eq(ori_trajectory_at(&t, 1.5, a, pos, &drive, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_record_at(r, 1.5, want, want_pos, &want_drive, NULL, NULL, &err), ORI_OK, "%s", err.message);
    cr_assert_lt(max_diff(a, want, E), 1e-12);
    cr_assert_lt(max_diff_v3(pos, want_pos, V), 1e-12);
    cr_assert_eq(drive, want_drive);
    cr_assert_float_eq(a[c.down], 22.5 * DEG, 1e-9);
    assert_out_of_range(&t, -0.5);
    assert_out_of_range(&t, 2.01);
    free(a);
    free(want);
    free(pos);
    free(want_pos);
    ori_record_destroy(r);
    ori_sequence_destroy(s);
    test_open_corner_free(&c);
}

Test(trajectory, a_record_fold_toward_targets_has_no_drive_angle, .init = test_leak_setup, .fini = test_leak_check)
{
    test_open_corner c = test_open_corner_load();
    char json[512];
    snprintf(json, sizeof json,
             "{\"pattern\": \"patterns/open-corner.fold\", \"folds\": ["
             "{\"fix\": %d, \"lock\": [%d], \"drive\": %d, \"to\": 30, \"step\": 10},"
             "{\"fix\": %d, \"percent\": 50, \"step\": 10}]}",
             c.t2, c.down, c.diag, c.t2);
    ori_sequence *s = NULL;
    ori_record *r = NULL;
    ori_error err;
    cr_assert_eq(ori_sequence_parse(json, strlen(json), &s, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_sequence_run(s, c.m, NULL, ori_rigid_identity(), &r, &err), ORI_OK, "%s", err.message);
    ori_trajectory t = ori_trajectory_of_record(r);
    int n = ori_trajectory_frame_count(&t);
    cr_assert_gt(n, 4);
    cr_assert(ori_record_fold_is_targets(r, 1));
    cr_assert_eq(ori_trajectory_frame_drive_rad(&t, 1), ori_record_frame_drive(r, 1), "fold 1 drives a crease");
    cr_assert(isnan(ori_trajectory_frame_drive_rad(&t, n - 1)), "fold 2 drives the progress");
    cr_assert_eq(ori_trajectory_frame_drive(&t, n - 1), ori_record_frame_drive(r, n - 1));
    ori_record_destroy(r);
    ori_sequence_destroy(s);
    test_open_corner_free(&c);
}
