// Kinematics: fold motions (closed-form spherical 4R and numeric continuation), the thesis'
// open corner (first and second fold, Frame A / Frame B, the mirrored branch), Miura-ori
// against closed forms, the square twist, verdicts, transfer functions, bad input.
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <orikin/arrangement.h>
#include <orikin/formats.h>

#include "kinematics/kinematics_internal.h"
#include "support.h"

TestSuite(kinematics, .init = test_leak_setup, .fini = test_leak_check);

#define DEG (ORI_PI / 180.0)

// --- helpers ---------------------------------------------------------------------------

// Every frame closes, keeps edge lengths and keeps the fixed face where its pose puts it.
static void check_frames(const ori_mechanism *m, const ori_pattern *p, const ori_motion *mo)
{
    int V = ori_pattern_vertex_count(p), F = ori_motion_frame_count(mo);
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)V);
    int fixed = ori_motion_fixed_face(mo);
    ori_rigid G = ori_motion_fixed_pose(mo);
    double diag = ori_pattern_diagonal(p);
    for (int k = 0; k < F; ++k) {
        cr_assert_leq(ori_motion_frame_residual(mo, k), ORI_TOL_RESIDUAL);
        cr_assert_leq(ori_mechanism_residual(m, ori_motion_frame_angles(mo, k)), ORI_TOL_RESIDUAL);
        ori_motion_frame_vertices(mo, k, pos);
        for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
            ori_edge E = ori_pattern_edge(p, e);
            double l0 = ori_v3_norm(ori_v3_sub(ori_pattern_vertex(p, E.v[0]), ori_pattern_vertex(p, E.v[1])));
            double l1 = ori_v3_norm(ori_v3_sub(pos[E.v[0]], pos[E.v[1]]));
            cr_assert_float_eq(l1, l0, 1e-12 * l0, "frame %d edge %d", k, e);
        }
        int vs[64];
        int n = ori_pattern_face_vertices(p, fixed, vs, 64);
        for (int i = 0; i < n; ++i) {
            ori_v3 want = ori_rigid_apply(G, ori_pattern_vertex(p, vs[i]));
            cr_assert_float_eq(pos[vs[i]].x, want.x, 1e-12 * diag);
            cr_assert_float_eq(pos[vs[i]].y, want.y, 1e-12 * diag);
            cr_assert_float_eq(pos[vs[i]].z, want.z, 1e-12 * diag);
        }
    }
    free(pos);
}

// --- the open corner, first fold -------------------------------------------------------------

static void check_first_fold_at_90(const test_open_corner *c, const ori_motion *mo)
{
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_VALID, "%s", ori_motion_reason(mo));
    int F = ori_motion_frame_count(mo);
    cr_assert_eq(F, 10); // 0, 10, …, 90
    cr_assert_eq(ori_motion_frame_drive(mo, F - 1), 90 * DEG);
    const double *a = ori_motion_frame_angles(mo, F - 1);
    double t4 = asin(1.0 / sqrt(3.0)); // 35.2643896827546°
    cr_assert_float_eq(a[c->right] / DEG, t4 / DEG, 1e-9);
    cr_assert_float_eq(a[c->up] / DEG, 60.0, 1e-9);
    cr_assert_float_eq(a[c->left] / DEG, -t4 / DEG, 1e-9);
    cr_assert_eq(a[c->down], 0.0);
    ori_v3 ea, eb;
    cr_assert(ori_motion_frame_end_effector(mo, F - 1, &ea, &eb));
    cr_assert_float_eq(ea.x, 0.5, 1e-12);
    cr_assert_float_eq(ea.y, 0.5, 1e-12);
    cr_assert_float_eq(ea.z, 1.0 / sqrt(2.0), 1e-12);
    cr_assert_float_eq(eb.x, -1.5, 1e-12);
    cr_assert_float_eq(eb.y, -0.5, 1e-12);
    cr_assert_float_eq(eb.z, 1.0 / sqrt(2.0), 1e-12);
}

Test(kinematics, open_corner_first_fold_closed_form)
{
    test_open_corner c = test_open_corner_load();
    ori_motion_def d = test_open_corner_first_fold(&c, ORI_SOLVER_ANALYTIC, 90);
    ori_motion *mo = test_solve(c.m, &d);
    cr_assert(ori_motion_stats_of(mo).analytic);
    check_first_fold_at_90(&c, mo);
    // Every branch: the spherical 4R's other solution at Θ1 = 90° has up = −60° and right,
    // left = ∓(180° − asin(1/√3)) (the thesis' second pair (−60°, −35.5°) in its own angle
    // convention for Θ4); it folds the valleys up and right as mountains: rejected.
    double other[13];
    cr_assert_not(ori_motion_frame_other_branch(mo, 0, other));
    cr_assert(ori_motion_frame_other_branch(mo, ori_motion_frame_count(mo) - 1, other));
    double t4 = 180.0 - asin(1.0 / sqrt(3.0)) / DEG;
    cr_assert_float_eq(other[c.up] / DEG, -60.0, 1e-9);
    cr_assert_float_eq(other[c.right] / DEG, -t4, 1e-9);
    cr_assert_float_eq(other[c.left] / DEG, t4, 1e-9);
    cr_assert_float_eq(other[c.diag] / DEG, 90.0, 1e-12);
    cr_assert_leq(ori_mechanism_residual(c.m, other), ORI_TOL_RESIDUAL);
    check_frames(c.m, c.p, mo);
    cr_assert_eq(ori_motion_dof(mo), 2);
    ori_motion_destroy(mo);
    test_open_corner_free(&c);
}

Test(kinematics, open_corner_first_fold_numeric_agrees_with_closed_form)
{
    test_open_corner c = test_open_corner_load();
    ori_motion_def da = test_open_corner_first_fold(&c, ORI_SOLVER_ANALYTIC, 180);
    ori_motion_def dn = test_open_corner_first_fold(&c, ORI_SOLVER_NUMERIC, 180);
    ori_motion *ma = test_solve(c.m, &da), *mn = test_solve(c.m, &dn);
    cr_assert_not(ori_motion_stats_of(mn).analytic);
    cr_assert_eq(ori_motion_verdict_of(mn), ORI_MOTION_VALID);
    cr_assert_eq(ori_motion_frame_count(ma), ori_motion_frame_count(mn));
    for (int k = 0; k < ori_motion_frame_count(ma); ++k) {
        const double *x = ori_motion_frame_angles(ma, k), *y = ori_motion_frame_angles(mn, k);
        for (int e = 0; e < ori_pattern_edge_count(c.p); ++e) cr_assert_float_eq(x[e] / DEG, y[e] / DEG, 1e-9);
        ori_v3 a1, b1, a2, b2;
        ori_motion_frame_end_effector(ma, k, &a1, &b1);
        ori_motion_frame_end_effector(mn, k, &a2, &b2);
        cr_assert_float_eq(a1.z, a2.z, 1e-12);
        cr_assert_float_eq(b1.x, b2.x, 1e-12);
    }
    // At Θ1 = 180°: right 90, up 90, left −90.
    const double *last = ori_motion_frame_angles(mn, ori_motion_frame_count(mn) - 1);
    cr_assert_float_eq(last[c.right] / DEG, 90.0, 1e-9);
    cr_assert_float_eq(last[c.up] / DEG, 90.0, 1e-9);
    cr_assert_float_eq(last[c.left] / DEG, -90.0, 1e-9);
    check_frames(c.m, c.p, mn);
    ori_motion_destroy(ma);
    ori_motion_destroy(mn);
    // The 90° reference values from the numeric path as well.
    ori_motion_def d90 = test_open_corner_first_fold(&c, ORI_SOLVER_NUMERIC, 90);
    ori_motion *m90 = test_solve(c.m, &d90);
    check_first_fold_at_90(&c, m90);
    ori_motion_destroy(m90);
    test_open_corner_free(&c);
}

Test(kinematics, open_corner_frame_a_frame_b_split)
{
    test_open_corner c = test_open_corner_load();
    ori_motion_def d = test_open_corner_first_fold(&c, ORI_SOLVER_AUTO, 90);
    ori_motion *mo = test_solve(c.m, &d);
    ori_vertex_split s;
    cr_assert(ori_motion_split(mo, &s));
    cr_assert_eq(s.vertex, test_vertex_at(c.p, 1, 1));
    cr_assert_eq(s.frame_a[0], c.diag);
    cr_assert_eq(s.frame_a[1], c.left);
    cr_assert_eq(s.frame_b_count, 3);
    cr_assert_eq(s.frame_b[0], c.right);
    cr_assert_eq(s.frame_b[1], c.up);
    cr_assert_eq(s.frame_b[2], c.left);
    cr_assert_eq(s.surrounding_count, 1);
    cr_assert_eq(s.surrounding[0], c.down);
    cr_assert_eq(s.end_effector_vertex, test_vertex_at(c.p, 0, 1));
    cr_assert_float_eq(s.d.x, 2.0, 1e-15);
    cr_assert_float_eq(s.d.y, 1.0, 1e-15);
    cr_assert_float_eq(s.d.z, 0.0, 1e-15);
    // Thesis Fig. 5-3: Frame A q1 = 0, ω1 = (1,1,0)/√2, q2 = (0,1,0), ω2 = (1,0,0); Frame B
    // q4 = 0, ω4 = (1,0,0), q3 = (−1,1,0), ω3 = (0,1,0).
    cr_assert_float_eq(ori_v3_norm(s.q_a[0]), 0.0, 1e-15);
    cr_assert_float_eq(s.omega_a[0].x, 1.0 / sqrt(2.0), 1e-15);
    cr_assert_float_eq(s.omega_a[0].y, 1.0 / sqrt(2.0), 1e-15);
    cr_assert_float_eq(s.q_a[1].y, 1.0, 1e-15);
    cr_assert_float_eq(s.omega_a[1].x, 1.0, 1e-15);
    cr_assert_float_eq(ori_v3_norm(s.q_b[0]), 0.0, 1e-15);
    cr_assert_float_eq(s.omega_b[0].x, 1.0, 1e-15);
    cr_assert_float_eq(s.q_b[1].x, -1.0, 1e-15);
    cr_assert_float_eq(s.q_b[1].y, 1.0, 1e-15);
    cr_assert_float_eq(s.omega_b[1].y, 1.0, 1e-15);
    // Frame 0: the end effector (0,1) in both frames.
    ori_v3 ea, eb;
    cr_assert(ori_motion_frame_end_effector(mo, 0, &ea, &eb));
    cr_assert_float_eq(ea.y, 1.0, 1e-15);
    cr_assert_float_eq(eb.x, -2.0, 1e-15);
    ori_motion_destroy(mo);
    test_open_corner_free(&c);
}

Test(kinematics, open_corner_mirrored_branch_is_rejected_by_the_assignment)
{
    test_open_corner c = test_open_corner_load();
    // The thesis' invalid structure: the first axis negatively oriented (diagonal mountain),
    // driven in its own direction to −90°.
    ori_pattern_set_assignment(c.p, c.diag, ORI_ASSIGN_MOUNTAIN);
    ori_mechanism_destroy(c.m);
    c.m = test_mechanism_of(c.p);
    for (int s = ORI_SOLVER_ANALYTIC; s <= ORI_SOLVER_NUMERIC; ++s) {
        ori_motion_def d = test_open_corner_first_fold(&c, (ori_solver)s, -90);
        ori_motion *mo = test_solve(c.m, &d);
        cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_INVALID_ASSIGNMENT);
        const char *why = ori_motion_reason(mo);
        char want[96];
        snprintf(want, sizeof want, "crease %d (assigned valley) would fold to -60°", c.up);
        cr_assert(strstr(why, want), "%s", why);
        cr_assert_eq(ori_motion_violation_count(mo), 3);
        for (int i = 0; i < 3; ++i) {
            ori_crease_violation v = ori_motion_violation(mo, i);
            double want_deg = v.edge == c.up ? -60.0 : v.edge == c.right ? -asin(1 / sqrt(3.0)) / DEG : asin(1 / sqrt(3.0)) / DEG;
            cr_assert(v.edge == c.up || v.edge == c.right || v.edge == c.left);
            cr_assert_float_eq(v.angle_rad / DEG, want_deg, 1e-9);
            cr_assert_float_eq(v.drive_rad / DEG, -90.0, 1e-12);
        }
        cr_assert_eq(ori_motion_frame_count(mo), 10); // the motion itself exists
        ori_motion_destroy(mo);
    }
    test_open_corner_free(&c);
}

Test(kinematics, driving_a_crease_against_its_own_assignment_is_invalid)
{
    test_open_corner c = test_open_corner_load();
    ori_motion_def d = test_open_corner_first_fold(&c, ORI_SOLVER_AUTO, -30);
    ori_motion *mo = test_solve(c.m, &d);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_INVALID_ASSIGNMENT);
    char want[96];
    snprintf(want, sizeof want, "the driven crease %d is assigned valley but is driven to -30°", c.diag);
    cr_assert(strstr(ori_motion_reason(mo), want), "%s", ori_motion_reason(mo));
    ori_motion_destroy(mo);
    test_open_corner_free(&c);
}

Test(kinematics, open_corner_without_a_lock_is_underdetermined)
{
    test_open_corner c = test_open_corner_load();
    ori_motion_def d = test_open_corner_first_fold(&c, ORI_SOLVER_AUTO, 90);
    d.locked_count = 0;
    ori_motion *mo = test_solve(c.m, &d);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_UNDERDETERMINED);
    cr_assert(strstr(ori_motion_reason(mo), "lock 1 more crease"), "%s", ori_motion_reason(mo));
    cr_assert_eq(ori_motion_frame_count(mo), 0);
    ori_motion_destroy(mo);
    test_open_corner_free(&c);
}

// --- the second fold: the corner cube -----------------------------------------------------

static void second_fold(ori_solver solver)
{
    test_open_corner c = test_open_corner_load();
    ori_motion_def d1 = test_open_corner_first_fold(&c, solver, 180);
    ori_motion *m1 = test_solve(c.m, &d1);
    cr_assert_eq(ori_motion_verdict_of(m1), ORI_MOTION_VALID);
    const double *state = ori_motion_frame_angles(m1, ori_motion_frame_count(m1) - 1);
    ori_motion_def d2 = ori_default_motion_def();
    d2.fixed_face = c.t2;
    d2.start_angles_rad = state;
    d2.driven_edge = c.down;
    d2.to_rad = 90 * DEG;
    d2.step_rad = 15 * DEG;
    d2.locked_edges = &c.diag;
    d2.locked_count = 1;
    d2.solver = solver;
    ori_motion *m2 = test_solve(c.m, &d2);
    cr_assert_eq(ori_motion_verdict_of(m2), ORI_MOTION_VALID, "%s", ori_motion_reason(m2));
    for (int k = 0; k < ori_motion_frame_count(m2); ++k) {
        const double *a = ori_motion_frame_angles(m2, k);
        double t = ori_motion_frame_drive(m2, k);
        cr_assert_float_eq(a[c.diag] / DEG, 180.0, 1e-12);
        cr_assert_float_eq(a[c.right] / DEG, 90.0, 1e-9);
        cr_assert_float_eq(a[c.up] / DEG, 90.0, 1e-9);
        cr_assert_float_eq(a[c.left] / DEG, -90.0 - t / DEG, 1e-9);
    }
    // The corner cube: LR, UR, UL mutually perpendicular; the flap T1 flat against UL.
    ori_rigid g[5];
    ori_motion_frame_face_poses(m2, ori_motion_frame_count(m2) - 1, g);
    ori_v3 z = ori_v3_make(0, 0, 1);
    ori_v3 n_lr = ori_m3_apply(g[c.lr].r, z), n_ur = ori_m3_apply(g[c.ur].r, z), n_ul = ori_m3_apply(g[c.ul].r, z);
    cr_assert_float_eq(ori_v3_dot(n_lr, n_ur), 0.0, 1e-9);
    cr_assert_float_eq(ori_v3_dot(n_ur, n_ul), 0.0, 1e-9);
    cr_assert_float_eq(ori_v3_dot(n_ul, n_lr), 0.0, 1e-9);
    cr_assert_float_eq(ori_v3_dot(ori_m3_apply(g[c.t1].r, z), n_ul), -1.0, 1e-9);
    // Four valleys and one mountain.
    const double *a = ori_motion_frame_angles(m2, ori_motion_frame_count(m2) - 1);
    cr_assert_gt(a[c.diag], 0.0);
    cr_assert_gt(a[c.down], 0.0);
    cr_assert_gt(a[c.right], 0.0);
    cr_assert_gt(a[c.up], 0.0);
    cr_assert_lt(a[c.left], 0.0);
    check_frames(c.m, c.p, m2);
    ori_motion_destroy(m1);
    ori_motion_destroy(m2);
    test_open_corner_free(&c);
}

Test(kinematics, open_corner_second_fold_reaches_the_corner_cube_closed_form) { second_fold(ORI_SOLVER_ANALYTIC); }
Test(kinematics, open_corner_second_fold_reaches_the_corner_cube_numeric) { second_fold(ORI_SOLVER_NUMERIC); }

Test(kinematics, a_fold_from_any_state_keeps_the_fixed_face_in_its_world_pose)
{
    // What a fold sequence does: after the first fold, fix another face (LR) where the first
    // fold left it, and fold again. The result is the same shape as with T2 fixed, moved by
    // the rigid motion that maps one onto the other; LR does not move.
    test_open_corner c = test_open_corner_load();
    ori_motion_def d1 = test_open_corner_first_fold(&c, ORI_SOLVER_AUTO, 120);
    ori_motion *m1 = test_solve(c.m, &d1);
    int last = ori_motion_frame_count(m1) - 1;
    ori_rigid g[5];
    ori_motion_frame_face_poses(m1, last, g);
    ori_motion_def d2 = ori_default_motion_def();
    d2.fixed_face = c.lr;
    d2.fixed_pose = g[c.lr];
    d2.start_angles_rad = ori_motion_frame_angles(m1, last);
    d2.driven_edge = c.diag;
    d2.to_rad = 150 * DEG;
    d2.step_rad = 10 * DEG;
    d2.locked_edges = &c.down;
    d2.locked_count = 1;
    for (int s = ORI_SOLVER_ANALYTIC; s <= ORI_SOLVER_NUMERIC; ++s) {
        d2.solver = (ori_solver)s;
        ori_motion *m2 = test_solve(c.m, &d2);
        cr_assert_eq(ori_motion_verdict_of(m2), ORI_MOTION_VALID);
        cr_assert_eq(ori_motion_frame_count(m2), 4);
        check_frames(c.m, c.p, m2);
        // Frame 0 of the second fold is the last state of the first, in the same place.
        ori_v3 p1[9], p2[9];
        ori_motion_frame_vertices(m1, last, p1);
        ori_motion_frame_vertices(m2, 0, p2);
        for (int v = 0; v < 9; ++v) cr_assert_float_eq(ori_v3_norm(ori_v3_sub(p1[v], p2[v])), 0.0, 1e-12);
        ori_motion_destroy(m2);
    }
    ori_motion_destroy(m1);
    test_open_corner_free(&c);
}

Test(kinematics, from_reaches_the_start_silently)
{
    test_open_corner c = test_open_corner_load();
    ori_motion_def d = test_open_corner_first_fold(&c, ORI_SOLVER_AUTO, 90);
    d.has_from = true;
    d.from_rad = 30 * DEG;
    d.step_rad = 20 * DEG;
    ori_motion *mo = test_solve(c.m, &d);
    cr_assert_eq(ori_motion_frame_count(mo), 4); // 30, 50, 70, 90
    cr_assert_eq(ori_motion_frame_drive(mo, 0), 30 * DEG);
    cr_assert_float_eq(ori_motion_frame_angles(mo, 0)[c.right] / DEG, 10.728583121609052, 1e-9);
    cr_assert_eq(ori_motion_frame_drive(mo, ori_motion_frame_count(mo) - 1), 90 * DEG);
    ori_motion_destroy(mo);
    test_open_corner_free(&c);
}

// --- Miura-ori ------------------------------------------------------------------------------

// The Miura-ori comes from the library's generator (test_miura → ori_generate). Its parameters
// are the closed forms' names: a = the straight edge (generator width, along x), b = the zig-zag
// edge (generator height), γ = the acute cell angle between them (generator angle). The sheet of
// these tests has its vertex rows 0.9 apart and shifted by 0.4 on odd rows: b = √(0.4² + 0.9²),
// γ = atan2(0.9, 0.4), so cos γ = 0.4 / b. Vertex (i, j) is j(C+1) + i (docs/generators.md).
#define MIURA_A 1.0
#define MIURA_B sqrt(0.4 * 0.4 + 0.9 * 0.9)
#define MIURA_GAMMA atan2(0.9, 0.4)

static void miura_case(int n, ori_linear linear)
{
    const double a = MIURA_A, b = MIURA_B, gamma = MIURA_GAMMA, cg = cos(gamma);
    ori_edge_class *cls = NULL;
    ori_pattern *p = test_miura(n, n, a, b, gamma, &cls);
    ori_mechanism *m = test_mechanism_of(p);
    int i0 = n / 2, j0 = n / 2;
#define VID(i, j) ((j) * (n + 1) + (i))
    int drive = ori_pattern_find_edge(p, VID(i0, j0), VID(i0, j0 + 1));
    cr_assert_eq(cls[drive], ORI_EDGE_CLASS_ZIGZAG);
    double sg = ori_pattern_edge(p, drive).assignment == ORI_ASSIGN_VALLEY ? 1.0 : -1.0;
    ori_motion_def md = ori_default_motion_def();
    md.driven_edge = drive;
    md.to_rad = sg * 170 * DEG;
    md.step_rad = 17 * DEG;
    md.linear = linear;
    ori_motion *mo = test_solve(m, &md);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_VALID, "%dx%d: %s", n, n, ori_motion_reason(mo));
    cr_assert_eq(ori_motion_frame_count(mo), 11);
    cr_assert_eq(ori_motion_dof(mo), 1, "%dx%d", n, n); // 1 DOF away from the flat state
    check_frames(m, p, mo);
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)ori_pattern_vertex_count(p));
    for (int k = 1; k < ori_motion_frame_count(mo); ++k) {
        const double *ang = ori_motion_frame_angles(mo, k);
        ori_motion_frame_vertices(mo, k, pos);
        for (int j = 1; j < n; ++j)
            for (int i = 1; i < n; ++i) {
                int v = VID(i, j);
                int zu = ori_pattern_find_edge(p, v, VID(i, j + 1)), zd = ori_pattern_find_edge(p, v, VID(i, j - 1));
                int sl = ori_pattern_find_edge(p, v, VID(i - 1, j)), sr = ori_pattern_find_edge(p, v, VID(i + 1, j));
                cr_assert(cls[zu] == ORI_EDGE_CLASS_ZIGZAG && cls[zd] == ORI_EDGE_CLASS_ZIGZAG);
                cr_assert(cls[sl] == ORI_EDGE_CLASS_STRAIGHT && cls[sr] == ORI_EDGE_CLASS_STRAIGHT);
                // The zigzag pair folds equally; each straight crease: |tan(ρs/2)| = cos γ |tan(ρz/2)|.
                cr_assert_float_eq(ang[zu], ang[zd], 1e-9);
                double tz = fabs(tan(0.5 * ang[zu]));
                cr_assert_float_eq(fabs(tan(0.5 * ang[sl])), cg * tz, 1e-9 * (1 + tz));
                cr_assert_float_eq(fabs(tan(0.5 * ang[sr])), cg * tz, 1e-9 * (1 + tz));
                // Schenk & Guest 2013: facets at θ = |ρz|/2 to the plane of the zigzag creases;
                // straight edge a, zigzag edge b, angle γ between them.
                double th = 0.5 * fabs(ang[zu]);
                ori_v3 u1 = ori_v3_sub(pos[VID(i, j + 1)], pos[v]), u2 = ori_v3_sub(pos[VID(i, j - 1)], pos[v]);
                ori_v3 nrm = ori_v3_normalize(ori_v3_cross(u1, u2));
                ori_v3 s = ori_v3_sub(pos[VID(i + 1, j)], pos[v]);
                double H = fabs(ori_v3_dot(s, nrm));
                ori_v3 sh = ori_v3_sub(s, ori_v3_scale(nrm, ori_v3_dot(s, nrm)));
                double L = ori_v3_norm(sh);
                ori_v3 yh = ori_v3_normalize(sh), xh = ori_v3_cross(nrm, yh);
                double V = fabs(ori_v3_dot(u1, yh)), S = fabs(ori_v3_dot(u1, xh));
                double root = sqrt(1.0 + pow(cos(th) * tan(gamma), 2));
                cr_assert_float_eq(H, a * sin(th) * sin(gamma), 1e-9);
                cr_assert_float_eq(L, a * sqrt(1.0 - pow(sin(th) * sin(gamma), 2)), 1e-9);
                cr_assert_float_eq(S, b * cos(th) * tan(gamma) / root, 1e-9);
                cr_assert_float_eq(V, b / root, 1e-9);
            }
    }
#undef VID
    // The sweep (docs/kinematics.md §6.1) is used by default above ORI_MOTION_DENSE_MAX_UNKNOWNS
    // free creases (2n(n − 1) − 1 here), or when asked; it covers every crease of a Miura sheet.
    ori_motion_stats st = ori_motion_stats_of(mo);
    bool sweep = linear == ORI_LINEAR_SWEEP ||
                 (linear == ORI_LINEAR_AUTO && 2 * n * (n - 1) - 1 > ORI_MOTION_DENSE_MAX_UNKNOWNS);
    cr_assert_eq(st.sweep, sweep, "%dx%d", n, n);
    if (sweep) cr_assert_gt(st.sweep_iterations, 0);
    else cr_assert_eq(st.sweep_iterations, 0);
    free(pos);
    ori_motion_destroy(mo);
    ori_buffer_free(cls);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

Test(kinematics, miura_2x2) { miura_case(2, ORI_LINEAR_AUTO); }
Test(kinematics, miura_3x3) { miura_case(3, ORI_LINEAR_AUTO); }
Test(kinematics, miura_4x4) { miura_case(4, ORI_LINEAR_AUTO); }
Test(kinematics, miura_5x5_sparse) { miura_case(5, ORI_LINEAR_SPARSE); }
Test(kinematics, miura_5x5_sweep) { miura_case(5, ORI_LINEAR_SWEEP); }
Test(kinematics, miura_6x6) { miura_case(6, ORI_LINEAR_AUTO); }
Test(kinematics, miura_6x6_sparse) { miura_case(6, ORI_LINEAR_SPARSE); }
Test(kinematics, miura_6x6_sweep) { miura_case(6, ORI_LINEAR_SWEEP); }

Test(kinematics, miura_with_a_flipped_crease_is_invalid_and_names_it)
{
    ori_pattern *p = test_miura(4, 4, MIURA_A, MIURA_B, MIURA_GAMMA, NULL);
    // Flip one straight crease of the second row.
    int e = ori_pattern_find_edge(p, 1 * 5 + 1, 1 * 5 + 2);
    ori_assignment a = ori_pattern_edge(p, e).assignment;
    ori_pattern_set_assignment(p, e, a == ORI_ASSIGN_VALLEY ? ORI_ASSIGN_MOUNTAIN : ORI_ASSIGN_VALLEY);
    ori_mechanism *m = test_mechanism_of(p);
    int drive = ori_pattern_find_edge(p, 2 * 5 + 2, 3 * 5 + 2);
    double sg = ori_pattern_edge(p, drive).assignment == ORI_ASSIGN_VALLEY ? 1.0 : -1.0;
    ori_motion_def md = ori_default_motion_def();
    md.driven_edge = drive;
    md.to_rad = sg * 60 * DEG;
    md.step_rad = 30 * DEG;
    ori_motion *mo = test_solve(m, &md);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_INVALID_ASSIGNMENT, "%s: %s",
                 ori_motion_verdict_name(ori_motion_verdict_of(mo)), ori_motion_reason(mo));
    char want[32];
    snprintf(want, sizeof want, "crease %d ", e);
    cr_assert(strstr(ori_motion_reason(mo), want), "%s", ori_motion_reason(mo));
    ori_motion_destroy(mo);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

// --- the square twist -----------------------------------------------------------------------

Test(kinematics, single_square_twist_is_not_rigidly_foldable)
{
    const char *path = test_require_shared("rabbit-ear/fold_square-twist.fold");
    ori_pattern *p = test_load_pattern(path, 0);
    ori_mechanism *m = test_mechanism_of(p);
    cr_assert_eq(ori_mechanism_loop_count(m), 4);
    // Whichever assigned crease is driven (in its direction) there is no rigid motion.
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_assignment a = ori_pattern_edge(p, e).assignment;
        if (a != ORI_ASSIGN_MOUNTAIN && a != ORI_ASSIGN_VALLEY) continue;
        ori_motion_def md = ori_default_motion_def();
        md.driven_edge = e;
        md.to_rad = (a == ORI_ASSIGN_VALLEY ? 1 : -1) * 90 * DEG;
        md.step_rad = 10 * DEG;
        ori_motion *mo = test_solve(m, &md);
        cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_NOT_RIGIDLY_FOLDABLE, "drive %d: %s", e,
                     ori_motion_reason(mo));
        cr_assert_eq(ori_motion_frame_count(mo), 0);
        cr_assert(strstr(ori_motion_reason(mo), "contradict each other"));
        ori_motion_destroy(mo);
    }
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

// --- transfer functions ------------------------------------------------------------------

Test(kinematics, transfer_functions_of_the_first_fold)
{
    test_open_corner c = test_open_corner_load();
    ori_fit_def fd = ori_default_fit_def();
    fd.motion = test_open_corner_first_fold(&c, ORI_SOLVER_AUTO, 90);
    fd.degree = 4;
    ori_fit *fit = NULL;
    ori_error err;
    cr_assert_eq(ori_fit_solve(c.m, &fd, &fit, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_fit_sample_count(fit), 10);
    cr_assert_eq(ori_fit_crease_count(fit), 3); // right, up, left
    ori_motion_def exact = test_open_corner_first_fold(&c, ORI_SOLVER_AUTO, 90);
    exact.step_rad = 1 * DEG;
    ori_motion *mo = test_solve(c.m, &exact);
    for (int i = 0; i < 3; ++i) {
        ori_fit_crease fc = ori_fit_crease_of(fit, i);
        cr_assert(fc.edge == c.right || fc.edge == c.up || fc.edge == c.left);
        // Measured: 0.00018° (right, left) and 0.0010° (up).
        cr_assert_lt(fc.max_error_rad / DEG, 0.002);
        double coef[5];
        cr_assert_eq(ori_fit_coefficients(fit, i, coef, 5), 5);
        for (int k = 0; k < ori_motion_frame_count(mo); ++k) {
            double x = ori_motion_frame_drive(mo, k);
            double poly = coef[0] + x * (coef[1] + x * (coef[2] + x * (coef[3] + x * coef[4])));
            cr_assert_float_eq(poly, ori_fit_eval(fit, i, x), 1e-12);
            cr_assert_leq(fabs(poly - ori_motion_frame_angles(mo, k)[fc.edge]), fc.max_error_rad * (1 + 1e-9) + 1e-12);
        }
    }
    ori_motion_destroy(mo);
    ori_fit_destroy(fit);
    // An invalid fold cannot be fitted.
    fd.motion.to_rad = -90 * DEG;
    cr_assert_eq(ori_fit_solve(c.m, &fd, &fit, &err), ORI_ERR_ARGUMENT);
    cr_assert(strstr(err.message, "the fold is invalid assignment"), "%s", err.message);
    test_open_corner_free(&c);
}

// --- bad input ---------------------------------------------------------------------------------

Test(kinematics, bad_fold_specifications_are_errors_naming_the_index)
{
    test_open_corner c = test_open_corner_load();
    ori_motion *mo = NULL;
    ori_error err;
    ori_motion_def d = test_open_corner_first_fold(&c, ORI_SOLVER_AUTO, 90);
    d.fixed_face = 7;
    cr_assert_eq(ori_motion_solve(c.m, &d, &mo, &err), ORI_ERR_RANGE);
    cr_assert_eq(err.element, 7);
    cr_assert_null(mo);
    d = test_open_corner_first_fold(&c, ORI_SOLVER_AUTO, 90);
    d.driven_edge = 0; // a boundary edge
    cr_assert_eq(ori_motion_solve(c.m, &d, &mo, &err), ORI_ERR_ARGUMENT);
    cr_assert_eq(err.element, 0);
    cr_assert(strstr(err.message, "not a crease"));
    d = test_open_corner_first_fold(&c, ORI_SOLVER_AUTO, 90);
    d.driven_edge = 99;
    cr_assert_eq(ori_motion_solve(c.m, &d, &mo, &err), ORI_ERR_RANGE);
    d = test_open_corner_first_fold(&c, ORI_SOLVER_AUTO, 90);
    d.locked_edges = &c.diag;
    cr_assert_eq(ori_motion_solve(c.m, &d, &mo, &err), ORI_ERR_ARGUMENT);
    cr_assert(strstr(err.message, "both driven and locked"));
    d = test_open_corner_first_fold(&c, ORI_SOLVER_AUTO, 190);
    cr_assert_eq(ori_motion_solve(c.m, &d, &mo, &err), ORI_ERR_RANGE);
    d = test_open_corner_first_fold(&c, ORI_SOLVER_AUTO, 90);
    d.step_rad = 0.0;
    cr_assert_eq(ori_motion_solve(c.m, &d, &mo, &err), ORI_ERR_RANGE);
    d = test_open_corner_first_fold(&c, ORI_SOLVER_AUTO, 90);
    d.has_from = true;
    d.from_rad = -200 * DEG;
    cr_assert_eq(ori_motion_solve(c.m, &d, &mo, &err), ORI_ERR_RANGE);
    // Start angles that do not close the loop.
    double bad[13] = {0};
    bad[c.right] = 0.3;
    d = test_open_corner_first_fold(&c, ORI_SOLVER_AUTO, 90);
    d.start_angles_rad = bad;
    cr_assert_eq(ori_motion_solve(c.m, &d, &mo, &err), ORI_ERR_ARGUMENT);
    cr_assert(strstr(err.message, "do not close"));
    // The closed form needs four moving creases at one vertex.
    d = test_open_corner_first_fold(&c, ORI_SOLVER_ANALYTIC, 90);
    d.locked_count = 0;
    cr_assert_eq(ori_motion_solve(c.m, &d, &mo, &err), ORI_ERR_UNSUPPORTED);
    // A flat (F) crease cannot be driven.
    ori_pattern_set_assignment(c.p, c.diag, ORI_ASSIGN_FLAT);
    ori_mechanism *m2 = test_mechanism_of(c.p);
    d = test_open_corner_first_fold(&c, ORI_SOLVER_AUTO, 90);
    cr_assert_eq(ori_motion_solve(m2, &d, &mo, &err), ORI_ERR_ARGUMENT);
    cr_assert(strstr(err.message, "cannot be driven"));
    ori_mechanism_destroy(m2);
    test_open_corner_free(&c);
}

Test(kinematics, slightly_rounded_start_states_are_projected)
{
    test_open_corner c = test_open_corner_load();
    ori_motion_def d = test_open_corner_first_fold(&c, ORI_SOLVER_AUTO, 90);
    ori_motion *m1 = test_solve(c.m, &d);
    double st[13];
    memcpy(st, ori_motion_frame_angles(m1, 5), sizeof st);
    for (int e = 0; e < 13; ++e) st[e] = nearbyint(st[e] / DEG * 1e6) / 1e6 * DEG; // 6 decimals
    cr_assert_gt(ori_mechanism_residual(c.m, st), ORI_TOL_RESIDUAL);
    ori_motion_def d2 = test_open_corner_first_fold(&c, ORI_SOLVER_NUMERIC, 90);
    d2.start_angles_rad = st;
    ori_motion *m2 = test_solve(c.m, &d2);
    cr_assert_eq(ori_motion_verdict_of(m2), ORI_MOTION_VALID);
    check_frames(c.m, c.p, m2);
    ori_motion_destroy(m1);
    ori_motion_destroy(m2);
    test_open_corner_free(&c);
}

// --- the command line: FOLD output and chaining -----------------------------------------

Test(kinematics, cli_writes_folded_frames_and_the_second_fold_starts_from_them)
{
    char *dir = test_tmpdir();
    char args[2200], *out = NULL;
    snprintf(args, sizeof args,
             "fold tests/data/kin-open-corner.fold --fix 0 --drive 8 --lock 9 --to 180 --step 30 -o '%s/first.fold'", dir);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    free(out);
    char path[1024];
    snprintf(path, sizeof path, "%s/first.fold", dir);
    ori_fold *doc = NULL;
    ori_error err;
    cr_assert_eq(ori_fold_load_file(path, &doc, &err), ORI_OK);
    cr_assert_eq(ori_fold_frame_count(doc), 8); // frame 0 + 7 steps (0, 30, …, 180)
    cr_assert(ori_fold_frame_is_folded_form(doc, 7));
    ori_pattern *last = NULL;
    cr_assert_eq(ori_fold_get_pattern(doc, 7, NULL, &last, &err), ORI_OK, "%s", err.message);
    cr_assert(ori_pattern_is_3d(last));
    cr_assert_float_eq(ori_pattern_edge(last, 8).fold_angle_rad, ORI_PI, 1e-12);
    cr_assert_float_eq(ori_pattern_edge(last, 12).fold_angle_rad, -ORI_PI / 2, 1e-12);
    ori_pattern_destroy(last);
    ori_fold_destroy(doc);
    // The second fold from the last frame: the corner cube.
    snprintf(args, sizeof args, "fold '%s' --frame 7 --fix 0 --drive 9 --lock 8 --to 90 --step 45 --json", path);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    cr_assert(strstr(out, "\"fold_angles_deg\":[0,0,0,0,0,0,0,0,180,90,90,90,-180]"), "%s", out);
    free(out);
    // An invalid fold writes nothing.
    snprintf(args, sizeof args,
             "fold tests/data/kin-open-corner-wrong-axis.fold --fix 0 --drive 8 --lock 9 --to -90 -o '%s/bad.fold'", dir);
    cr_assert_eq(test_run_cli(args, &out), 1, "%s", out);
    free(out);
    snprintf(path, sizeof path, "%s/bad.fold", dir);
    cr_assert_null(test_read_text(path));
    // A bad command line (a boundary edge as the drive: usage, naming --drive) writes nothing either.
    snprintf(args, sizeof args, "fold tests/data/kin-open-corner.fold --fix 0 --drive 3 --to 90 -o '%s/bad.fold'", dir);
    cr_assert_eq(test_run_cli(args, &out), 2, "%s", out);
    cr_assert(strstr(out, "--drive: edge 3 is not a crease"), "%s", out);
    free(out);
    cr_assert_null(test_read_text(path));
    test_tmpdir_remove(dir);
}

Test(kinematics, cli_square_twist_is_not_rigidly_foldable)
{
    const char *path = test_require_shared("rabbit-ear/fold_square-twist.fold");
    char args[2200], *out = NULL;
    snprintf(args, sizeof args, "fold '%s' --fix 6 --drive 6 --to -60 --json", path);
    cr_assert_eq(test_run_cli(args, &out), 1, "%s", out);
    cr_assert(strstr(out, "\"verdict\":\"not rigidly foldable\""), "%s", out);
    cr_assert(strstr(out, "\"rigidly_foldable\":false"), "%s", out);
    free(out);
}

// --- holes -------------------------------------------------------------------------------

// A 3×3 square with a 1×1 hole: four creases from the hole's test_open_corners, either to the outer
// corners (diagonals: all axes meet at the centre, a spherical loop) or pinwheel-wise.
static ori_pattern *ring(bool diagonal)
{
    ori_pattern_def pd = ori_default_pattern_def();
    ori_pattern *p = ori_pattern_create(&pd);
    ori_error err;
    if (diagonal) {
        double pts[][2] = {{0, 0}, {3, 0}, {3, 3}, {0, 3}, {1, 1}, {2, 1}, {2, 2}, {1, 2}};
        for (int i = 0; i < 8; ++i) ori_pattern_add_vertex(p, ori_v3_make(pts[i][0], pts[i][1], 0));
        for (int i = 0; i < 4; ++i) ori_pattern_add_edge(p, i, (i + 1) % 4, ORI_ASSIGN_BOUNDARY, 0);
        for (int i = 0; i < 4; ++i) ori_pattern_add_edge(p, 4 + i, 4 + (i + 1) % 4, ORI_ASSIGN_BOUNDARY, 0);
        for (int i = 0; i < 4; ++i) ori_pattern_add_edge(p, i, 4 + i, i % 2 ? ORI_ASSIGN_MOUNTAIN : ORI_ASSIGN_VALLEY, 0);
        for (int i = 0; i < 4; ++i) {
            int f[4] = {i, (i + 1) % 4, 4 + (i + 1) % 4, 4 + i};
            ori_pattern_add_face(p, f, 4);
        }
    } else {
        double pts[][2] = {{0, 0}, {1, 0}, {3, 0}, {3, 1}, {3, 3}, {2, 3}, {0, 3}, {0, 2}, {1, 1}, {2, 1}, {2, 2}, {1, 2}};
        for (int i = 0; i < 12; ++i) ori_pattern_add_vertex(p, ori_v3_make(pts[i][0], pts[i][1], 0));
        for (int i = 0; i < 8; ++i) ori_pattern_add_edge(p, i, (i + 1) % 8, ORI_ASSIGN_BOUNDARY, 0);
        for (int i = 0; i < 4; ++i) ori_pattern_add_edge(p, 8 + i, 8 + (i + 1) % 4, ORI_ASSIGN_BOUNDARY, 0);
        int outer[4] = {1, 3, 5, 7};
        for (int i = 0; i < 4; ++i) ori_pattern_add_edge(p, 8 + i, outer[i], ORI_ASSIGN_VALLEY, 0);
        int f0[] = {1, 2, 3, 9, 8}, f1[] = {3, 4, 5, 10, 9}, f2[] = {5, 6, 7, 11, 10}, f3[] = {7, 0, 1, 8, 11};
        ori_pattern_add_face(p, f0, 5);
        ori_pattern_add_face(p, f1, 5);
        ori_pattern_add_face(p, f2, 5);
        ori_pattern_add_face(p, f3, 5);
    }
    cr_assert_eq(ori_pattern_build(p, NULL, &err), ORI_OK, "%s", err.message);
    return p;
}

Test(kinematics, a_ring_around_a_hole_folds_along_its_diagonal)
{
    ori_pattern *p = ring(true);
    ori_mechanism *m = test_mechanism_of(p);
    cr_assert_eq(ori_mechanism_loop(m, 0).rows, 6);
    int e0 = ori_pattern_find_edge(p, 0, 4), e2 = ori_pattern_find_edge(p, 2, 6);
    ori_motion_def d = ori_default_motion_def();
    d.driven_edge = e0;
    d.to_rad = 120 * DEG;
    d.step_rad = 30 * DEG;
    ori_motion *mo = test_solve(m, &d);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_VALID, "%s", ori_motion_reason(mo));
    for (int k = 0; k < ori_motion_frame_count(mo); ++k) {
        const double *a = ori_motion_frame_angles(mo, k);
        cr_assert_float_eq(a[e2], a[e0], 1e-9); // the opposite crease continues the line
    }
    check_frames(m, p, mo);
    ori_motion_destroy(mo);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

Test(kinematics, a_pinwheel_ring_around_a_hole_is_rigid)
{
    ori_pattern *p = ring(false);
    ori_mechanism *m = test_mechanism_of(p);
    ori_motion_def d = ori_default_motion_def();
    d.driven_edge = 12;
    d.to_rad = 60 * DEG;
    d.step_rad = 30 * DEG;
    ori_motion *mo = test_solve(m, &d);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_NOT_RIGIDLY_FOLDABLE, "%s", ori_motion_reason(mo));
    ori_motion_destroy(mo);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

Test(kinematics, a_ring_around_a_hole_folds_with_the_sweep)
{
    // The hole loop (6 rows) determines its three free creases from the drive by least squares.
    ori_pattern *p = ring(true);
    ori_mechanism *m = test_mechanism_of(p);
    int e0 = ori_pattern_find_edge(p, 0, 4), e2 = ori_pattern_find_edge(p, 2, 6);
    ori_motion_def d = ori_default_motion_def();
    d.driven_edge = e0;
    d.to_rad = 120 * DEG;
    d.step_rad = 30 * DEG;
    d.linear = ORI_LINEAR_SWEEP;
    ori_motion *mo = test_solve(m, &d);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_VALID, "%s", ori_motion_reason(mo));
    ori_motion_stats st = ori_motion_stats_of(mo);
    cr_assert(st.sweep);
    cr_assert_gt(st.sweep_iterations, 0);
    for (int k = 0; k < ori_motion_frame_count(mo); ++k) {
        const double *a = ori_motion_frame_angles(mo, k);
        cr_assert_float_eq(a[e2], a[e0], 1e-9);
    }
    check_frames(m, p, mo);
    ori_motion_destroy(mo);
    d.driven_edge = 12;
    d.to_rad = 60 * DEG;
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
    // The pinwheel ring stays rigid whichever linear algebra corrects.
    p = ring(false);
    m = test_mechanism_of(p);
    mo = test_solve(m, &d);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_NOT_RIGIDLY_FOLDABLE, "%s", ori_motion_reason(mo));
    ori_motion_destroy(mo);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

// --- the sweep corrector ----------------------------------------------------------------------


Test(kinematics, sweep_and_cholmod_agree_on_a_large_miura_sheet)
{
    // 12 × 12 cells, 263 free creases: the default (sweep) and CHOLMOD alone, from 5° to 150°.
    const int n = 12;
    ori_pattern *p = test_miura(n, n, MIURA_A, MIURA_B, MIURA_GAMMA, NULL);
    ori_mechanism *m = test_mechanism_of(p);
    double sg;
    ori_motion_def d = ori_default_motion_def();
    d.driven_edge = test_miura_drive(p, n, &sg);
    d.to_rad = sg * 5 * DEG;
    d.step_rad = 5 * DEG;
    ori_motion *start = test_solve(m, &d);
    cr_assert_eq(ori_motion_verdict_of(start), ORI_MOTION_VALID);
    d.start_angles_rad = ori_motion_frame_angles(start, ori_motion_frame_count(start) - 1);
    d.to_rad = sg * 150 * DEG;
    d.step_rad = 5 * DEG;
    ori_motion *sw = test_solve(m, &d);
    d.linear = ORI_LINEAR_SPARSE;
    ori_motion *ch = test_solve(m, &d);
    cr_assert_eq(ori_motion_verdict_of(sw), ORI_MOTION_VALID, "%s", ori_motion_reason(sw));
    cr_assert_eq(ori_motion_verdict_of(ch), ORI_MOTION_VALID, "%s", ori_motion_reason(ch));
    cr_assert_eq(ori_motion_frame_count(sw), 30);
    cr_assert_eq(ori_motion_frame_count(ch), 30);
    int E = ori_pattern_edge_count(p);
    for (int k = 0; k < 30; ++k) {
        cr_assert_eq(ori_motion_frame_drive(sw, k), ori_motion_frame_drive(ch, k));
        const double *a = ori_motion_frame_angles(sw, k), *b = ori_motion_frame_angles(ch, k);
        for (int e = 0; e < E; ++e) cr_assert_float_eq(a[e], b[e], 1e-10, "frame %d edge %d", k, e);
    }
    check_frames(m, p, sw);
    ori_motion_stats s1 = ori_motion_stats_of(sw), s2 = ori_motion_stats_of(ch);
    // Every corrector iteration by the sweep: the only factorization is the rank test of the
    // start state. CHOLMOD alone factors at least once per step.
    cr_assert(s1.sweep && s1.sparse);
    cr_assert_eq(s1.sweep_iterations, s1.newton_iterations);
    cr_assert_eq(s1.factorizations, 1);
    cr_assert(!s2.sweep && s2.sparse);
    cr_assert_eq(s2.sweep_iterations, 0);
    cr_assert_geq(s2.factorizations, s2.steps);
    cr_assert_eq(ori_motion_dof(sw), 1);
    ori_motion_destroy(sw);
    ori_motion_destroy(ch);
    ori_motion_destroy(start);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

// Free columns of every revolute joint but the drive (the motion's unknowns).
static int free_columns(const ori_mechanism *m, int drive_joint, int *col)
{
    int n = 0;
    for (int j = 0; j < m->joint_count; ++j)
        col[j] = j == drive_joint ? KIN_DRIVE : m->joints[j].kind == ORI_JOINT_REVOLUTE ? n++ : KIN_FIXED;
    return n;
}

Test(kinematics, sweep_exists_for_degree_four_vertices_from_any_drive_but_not_for_degree_six)
{
    kin_solver_opts opts = {ORI_LINEAR_SWEEP, false};
    ori_pattern *p = test_miura(4, 4, MIURA_A, MIURA_B, MIURA_GAMMA, NULL);
    ori_mechanism *m = test_mechanism_of(p);
    int *col = malloc(sizeof(int) * (size_t)m->joint_count);
    for (int jd = 0; jd < m->joint_count; ++jd) {
        int n = free_columns(m, jd, col);
        kin_solver *s = ori__kin_solver_create(m, col, n, jd, &opts);
        cr_assert(ori__kin_solver_sweep(s), "drive joint %d", jd);
        ori__kin_solver_destroy(s);
    }
    free(col);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
    // Yoshimura: degree-6 vertices, five or six undetermined creases for three equations.
    p = test_generated(ORI_TESS_YOSHIMURA, 3, 3);
    m = test_mechanism_of(p);
    col = malloc(sizeof(int) * (size_t)m->joint_count);
    int n = free_columns(m, 0, col);
    kin_solver *s = ori__kin_solver_create(m, col, n, 0, &opts);
    cr_assert_not(ori__kin_solver_sweep(s));
    ori__kin_solver_destroy(s);
    free(col);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

Test(kinematics, sweep_hands_a_singular_state_to_cholmod)
{
    // Next to the flat sheet every vertex block is (nearly) rank 2: the sweep refuses it and the
    // least-squares corrector closes the loops.
    ori_pattern *p = test_miura(4, 4, MIURA_A, MIURA_B, MIURA_GAMMA, NULL);
    ori_mechanism *m = test_mechanism_of(p);
    double sg;
    int drive = test_miura_drive(p, 4, &sg);
    int jd = ori_mechanism_edge_joint(m, drive);
    int *col = malloc(sizeof(int) * (size_t)m->joint_count);
    double *th = calloc((size_t)m->joint_count, sizeof(double));
    int n = free_columns(m, jd, col);
    for (int j = 0; j < m->joint_count; ++j)
        if (col[j] >= 0) th[j] = 1e-9 * (j % 3 - 1);
    cr_assert_gt(ori__kin_residual(m, th), ORI_TOL_NEWTON);
    kin_solver_opts opts = {ORI_LINEAR_SWEEP, false};
    kin_solver *s = ori__kin_solver_create(m, col, n, jd, &opts);
    cr_assert(ori__kin_solver_sweep(s));
    int its;
    double res;
    cr_assert(ori__kin_correct(s, th, ORI_KIN_NEWTON_MAX, &its, &res));
    cr_assert_leq(res, ORI_TOL_RESIDUAL);
    cr_assert_leq(ori__kin_residual(m, th), ORI_TOL_RESIDUAL);
    cr_assert_eq(ori__kin_solver_sweep_iterations(s), 0);
    cr_assert_geq(ori__kin_solver_factorizations(s), 1);
    ori__kin_solver_destroy(s);
    free(th);
    free(col);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

Test(kinematics, rank_test_factors_the_normal_matrix_of_the_state_itself)
{
    // A folded Miura state is regular for the drive, the flat sheet is not, whatever was
    // factored before (a new solver's first test used to see an all-zero matrix).
    ori_pattern *p = test_miura(6, 6, MIURA_A, MIURA_B, MIURA_GAMMA, NULL);
    ori_mechanism *m = test_mechanism_of(p);
    double sg;
    ori_motion_def d = ori_default_motion_def();
    d.driven_edge = test_miura_drive(p, 6, &sg);
    d.to_rad = sg * 60 * DEG;
    d.step_rad = 60 * DEG;
    ori_motion *mo = test_solve(m, &d);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_VALID);
    int jd = ori_mechanism_edge_joint(m, d.driven_edge);
    int *col = malloc(sizeof(int) * (size_t)m->joint_count);
    double *th = malloc(sizeof(double) * (size_t)m->joint_count);
    double *flat = calloc((size_t)m->joint_count, sizeof(double));
    ori__kin_edges_to_joints(m, ori_motion_frame_angles(mo, ori_motion_frame_count(mo) - 1), th);
    int n = free_columns(m, jd, col);
    kin_solver_opts opts = {ORI_LINEAR_SPARSE, false};
    kin_solver *s = ori__kin_solver_create(m, col, n, jd, &opts);
    cr_assert_eq(ori__kin_solver_nullity(s, th), 0);
    cr_assert_gt(ori__kin_solver_nullity(s, flat), 0);
    cr_assert_eq(ori__kin_solver_nullity(s, th), 0);
    ori__kin_solver_destroy(s);
    free(flat);
    free(th);
    free(col);
    ori_motion_destroy(mo);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

// Origami Simulator's Miura-ori is drawn with 3-decimal coordinates: Kawasaki misses by up to
// 8e-5 rad at many vertices, and the exact rigid sheet does not fold. The fold says so, and the
// CLI adds the likely cause.
Test(kinematics, rounded_drawing_is_rigid_and_the_cli_says_why)
{
    const char *svg = test_require_shared("origamisimulator/Tessellations_miura-ori.svg");
    char *dir = test_tmpdir();
    char args[2048], *out = NULL;
    snprintf(args, sizeof args, "convert '%s' %s/miura.fold", svg, dir);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    free(out);
    snprintf(args, sizeof args, "fold %s/miura.fold --fix 0 --drive 10 --to -60 --step 20", dir);
    cr_assert_eq(test_run_cli(args, &out), 1, "%s", out);
    cr_assert(strstr(out, "verdict: not rigidly foldable"), "%s", out);
    cr_assert(strstr(out, "note: 69 interior vertices miss Kawasaki by up to 8.2e-05 rad (rounded coordinates?)"), "%s", out);
    free(out);
    test_tmpdir_remove(dir);
}

// Progress of a fold (ori_motion_def.progress): on a 20 × 20 Miura sheet from 5° to 150° the
// callback sees monotone fractions in [0, 1], one per output frame at least, the last exactly 1;
// the fraction at each frame is the drive range done. Returning false cancels: ORI_ERR_LIMIT,
// no motion, nothing leaked (the suite's leak check).
typedef struct progress_log {
    double f[512];
    int n;
    int cancel_after; // return false at this call (−1: never)
} progress_log;

static bool log_progress(double f, void *user)
{
    progress_log *l = user;
    if (l->n < 512) l->f[l->n] = f;
    l->n++;
    return l->cancel_after < 0 || l->n < l->cancel_after;
}

Test(kinematics, progress_is_monotone_and_cancels)
{
    const int n = 20;
    ori_pattern *p = test_miura(n, n, MIURA_A, MIURA_B, MIURA_GAMMA, NULL);
    ori_mechanism *m = test_mechanism_of(p);
    double sg;
    ori_motion_def d = ori_default_motion_def();
    d.driven_edge = test_miura_drive(p, n, &sg);
    d.to_rad = sg * 5 * DEG;
    d.step_rad = 5 * DEG;
    ori_motion *start = test_solve(m, &d);
    cr_assert_eq(ori_motion_verdict_of(start), ORI_MOTION_VALID, "%s", ori_motion_reason(start));
    d.start_angles_rad = ori_motion_frame_angles(start, ori_motion_frame_count(start) - 1);
    d.to_rad = sg * 150 * DEG;
    progress_log log = {.n = 0, .cancel_after = -1};
    d.progress = log_progress;
    d.progress_user = &log;
    ori_motion *mo = NULL;
    ori_error err;
    cr_assert_eq(ori_motion_solve(m, &d, &mo, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_VALID, "%s", ori_motion_reason(mo));
    int F = ori_motion_frame_count(mo);
    cr_assert_eq(F, 30);
    cr_assert_geq(log.n, F);
    cr_assert_leq(log.n, 512);
    cr_assert_eq(log.f[0], 0.0);
    for (int i = 1; i < log.n; ++i) {
        cr_assert_geq(log.f[i], log.f[i - 1], "call %d: %g after %g", i, log.f[i], log.f[i - 1]);
        cr_assert_leq(log.f[i], 1.0);
    }
    cr_assert_eq(log.f[log.n - 1], 1.0);
    // frame k's call reports the drive range done: (5° + 5° k − 5°) / 145°, to rounding
    cr_assert_float_eq(log.f[F / 2], (ori_motion_frame_drive(mo, F / 2) - sg * 5 * DEG) / (sg * 145 * DEG), 1e-12);
    ori_motion_destroy(mo);

    // cancelled a third of the way: ORI_ERR_LIMIT, no motion
    progress_log stop = {.n = 0, .cancel_after = 10};
    d.progress_user = &stop;
    mo = NULL;
    cr_assert_eq(ori_motion_solve(m, &d, &mo, &err), ORI_ERR_LIMIT);
    cr_assert_str_eq(err.message, "cancelled");
    cr_assert_null(mo);
    cr_assert_eq(stop.n, 10, "no call after the cancel (got %d)", stop.n);

    // a sequence of two folds: its fractions run over both, monotone, ending at 1; cancel too
    const char *text = "{\"pattern\": \"x.fold\", \"folds\": [{\"fix\": 0, \"drive\": %d, \"to\": %g, \"step\": 10},"
                       " {\"fix\": 0, \"drive\": %d, \"to\": %g, \"step\": 10}]}";
    char seq[512];
    snprintf(seq, sizeof seq, text, d.driven_edge, sg * 60.0, d.driven_edge, sg * 120.0);
    ori_sequence *s = NULL;
    cr_assert_eq(ori_sequence_parse(seq, strlen(seq), &s, &err), ORI_OK, "%s", err.message);
    progress_log sl = {.n = 0, .cancel_after = -1};
    ori_record *r = NULL;
    cr_assert_eq(ori_sequence_run_progress(s, m, d.start_angles_rad, ori_rigid_identity(), log_progress, &sl, &r, &err),
                 ORI_OK, "%s", err.message);
    cr_assert_eq(ori_record_verdict(r), ORI_MOTION_VALID);
    cr_assert_geq(sl.n, ori_record_frame_count(r));
    bool half = false;
    for (int i = 1; i < sl.n && i < 512; ++i) {
        cr_assert_geq(sl.f[i], sl.f[i - 1]);
        half = half || sl.f[i] == 0.5; // fold 2 starts at 1/2
    }
    cr_assert(half);
    cr_assert_eq(sl.f[(sl.n < 512 ? sl.n : 512) - 1], 1.0);
    ori_record_destroy(r);
    progress_log sc = {.n = 0, .cancel_after = 8};
    r = NULL;
    cr_assert_eq(ori_sequence_run_progress(s, m, d.start_angles_rad, ori_rigid_identity(), log_progress, &sc, &r, &err),
                 ORI_ERR_LIMIT);
    cr_assert_null(r);
    ori_sequence_destroy(s);
    ori_motion_destroy(start);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

// --- large folds: frames kept, factorizations (docs/kinematics.md §14) ----------------------

// A 30 × 30 Miura-ori (the benchmark's generator: a = 1, b = √1.25, γ = atan2(1, 0.5)) folded by
// its middle zigzag crease 5° → 175° in 100 steps of 1.7°. Its frames are compared with a
// fingerprint written by the release before the performance work of issue 7 §5 (CHOLMOD
// supernodal above a size, block solves in the sparse nullity, frames not kept): per frame the
// drive, Σθ, Σθ², Σθ·(e mod 7 + 1) and θ of edge E/3, to 1e-12. Then the same fold keeping only
// its last frame: that frame, the verdict, the DOF and the statistics are bit for bit the same.
Test(kinematics, miura_30x30_fold_matches_its_fingerprint_and_last_frame_only_keeps_the_same_end)
{
    const int n = 30;
    ori_pattern *p = test_miura(n, n, 1.0, sqrt(1.25), atan2(1.0, 0.5), NULL);
    ori_mechanism *m = test_mechanism_of(p);
    double sg;
    ori_motion_def d = ori_default_motion_def();
    d.driven_edge = test_miura_drive(p, n, &sg);
    d.to_rad = sg * ori_deg_to_rad(5.0);
    d.step_rad = ori_deg_to_rad(5.0);
    ori_motion *start = test_solve(m, &d);
    cr_assert_eq(ori_motion_verdict_of(start), ORI_MOTION_VALID, "%s", ori_motion_reason(start));
    d.start_angles_rad = ori_motion_frame_angles(start, ori_motion_frame_count(start) - 1);
    d.to_rad = sg * ori_deg_to_rad(175.0);
    d.step_rad = ori_deg_to_rad(170.0 / 100.0);
    ori_motion *mo = test_solve(m, &d);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_VALID, "%s", ori_motion_reason(mo));
    cr_assert_eq(ori_motion_dof(mo), 1);
    int F = ori_motion_frame_count(mo), E = ori_pattern_edge_count(p);
    cr_assert_eq(F, 101);
    cr_assert_eq(ori_motion_stats_of(mo).frames, 101);
    FILE *f = fopen(test_repo_path("tests/data/kin-miura30-fold-fingerprint.txt"), "r");
    cr_assert_not_null(f);
    char line[512];
    int rows = 0;
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#') continue;
        int k;
        double ref[5];
        cr_assert_eq(sscanf(line, "%d %lf %lf %lf %lf %lf", &k, &ref[0], &ref[1], &ref[2], &ref[3], &ref[4]), 6);
        cr_assert(k >= 0 && k < F);
        const double *a = ori_motion_frame_angles(mo, k);
        double got[5] = {ori_motion_frame_drive(mo, k), 0.0, 0.0, 0.0, a[E / 3]};
        for (int e = 0; e < E; ++e) {
            got[1] += a[e];
            got[2] += a[e] * a[e];
            got[3] += a[e] * (double)(e % 7 + 1);
        }
        for (int i = 0; i < 5; ++i)
            cr_assert_float_eq(got[i], ref[i], 1e-12 * fmax(1.0, fabs(ref[i])), "frame %d value %d: %.17g, reference %.17g",
                               k, i, got[i], ref[i]);
        rows++;
    }
    fclose(f);
    cr_assert_eq(rows, F);
    for (int k = 0; k < F; ++k) cr_assert_leq(ori_mechanism_residual(m, ori_motion_frame_angles(mo, k)), ORI_TOL_RESIDUAL);

    d.last_frame_only = true;
    ori_motion *last = test_solve(m, &d);
    cr_assert_eq(ori_motion_verdict_of(last), ORI_MOTION_VALID);
    cr_assert_eq(ori_motion_frame_count(last), 1);
    ori_motion_stats s1 = ori_motion_stats_of(mo), s2 = ori_motion_stats_of(last);
    cr_assert_eq(s2.frames, 101);
    cr_assert_eq(s2.steps, s1.steps);
    cr_assert_eq(s2.newton_iterations, s1.newton_iterations);
    cr_assert_eq(s2.factorizations, s1.factorizations);
    cr_assert_eq(s2.max_residual, s1.max_residual);
    cr_assert_eq(ori_motion_dof(last), 1);
    cr_assert_eq(ori_motion_frame_drive(last, 0), ori_motion_frame_drive(mo, F - 1));
    cr_assert_eq(ori_motion_frame_residual(last, 0), ori_motion_frame_residual(mo, F - 1));
    cr_assert_eq(memcmp(ori_motion_frame_angles(last, 0), ori_motion_frame_angles(mo, F - 1), sizeof(double) * (size_t)E), 0);
    ori_motion_destroy(last);
    ori_motion_destroy(mo);
    ori_motion_destroy(start);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

// The verdict does not depend on the output step past the escape from the flat state (issue 7
// §3): a 3 × 3 Miura-ori folded from flat to just past the escape's end (1.0028°, the escape
// ends at ORI_KIN_SINGULAR_STEP_RAD = 1.00268°) with output steps of 1e-5° used to be "blocked"
// at the escape's end: the first step out extrapolated through the escape's states (fixed only
// to O(δ²) off the branch), was rejected, and the halved step fell below ORI_KIN_MIN_STEP_RAD.
// Every step now gives a valid fold to the same state.
Test(kinematics, miura_past_the_escape_is_valid_for_every_output_step)
{
    const int n = 3;
    ori_pattern *p = test_miura(n, n, 1.0, sqrt(1.25), atan2(1.0, 0.5), NULL);
    ori_mechanism *m = test_mechanism_of(p);
    double sg;
    int E = ori_pattern_edge_count(p);
    ori_motion_def d = ori_default_motion_def();
    d.driven_edge = test_miura_drive(p, n, &sg);
    d.to_rad = sg * ori_deg_to_rad(1.0028);
    d.last_frame_only = true;
    const double steps_deg[] = {1e-5, 3e-5, 1e-4, 1e-2, 1.0, 30.0};
    double *ref = malloc(sizeof(double) * (size_t)E);
    for (size_t i = 0; i < sizeof steps_deg / sizeof steps_deg[0]; ++i) {
        d.step_rad = ori_deg_to_rad(steps_deg[i]);
        ori_motion *mo = test_solve(m, &d);
        cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_VALID, "step %g°: %s", steps_deg[i], ori_motion_reason(mo));
        const double *a = ori_motion_frame_angles(mo, ori_motion_frame_count(mo) - 1);
        cr_assert_float_eq(a[d.driven_edge], d.to_rad, 1e-12);
        if (i == 0) memcpy(ref, a, sizeof(double) * (size_t)E);
        for (int e = 0; e < E; ++e)
            cr_assert_float_eq(a[e] / DEG, ref[e] / DEG, 1e-9, "step %g°, crease %d", steps_deg[i], e);
        ori_motion_destroy(mo);
    }
    free(ref);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

// --- the default fixed face ------------------------------------------------------------------

// A net of squares from unit cells (x, y): every cell edge, boundary where only one cell has it,
// else a valley crease.
static ori_pattern *net_of_cells(const int (*cells)[2], int n)
{
    ori_segment segs[64];
    int ns = 0;
    for (int i = 0; i < n; ++i) {
        int x = cells[i][0], y = cells[i][1];
        int ends[4][4] = {{x, y, x + 1, y}, {x + 1, y, x + 1, y + 1}, {x, y + 1, x + 1, y + 1}, {x, y, x, y + 1}};
        int nb[4][2] = {{x, y - 1}, {x + 1, y}, {x, y + 1}, {x - 1, y}};
        for (int k = 0; k < 4; ++k) {
            int shared = -1;
            for (int j = 0; j < n; ++j)
                if (cells[j][0] == nb[k][0] && cells[j][1] == nb[k][1]) shared = j;
            if (shared >= 0 && shared < i) continue; // inserted with the other cell
            segs[ns++] = (ori_segment){ori_v2_make(ends[k][0], ends[k][1]), ori_v2_make(ends[k][2], ends[k][3]),
                                       shared >= 0 ? ORI_ASSIGN_VALLEY : ORI_ASSIGN_BOUNDARY, 0.0};
        }
    }
    ori_pattern *p = NULL;
    ori_error err;
    cr_assert_eq(ori_pattern_from_segments(segs, ns, NULL, &p, NULL, &err), ORI_OK, "%s", err.message);
    return p;
}

Test(kinematics, the_default_fixed_face_of_a_cross_net_is_its_middle_square)
{
    // The cube's cross: a column of four squares, arms left and right of the second from the top.
    // Its bounding box [-1, 2] x [0, 4] has its centre (0.5, 2) on the crease between two squares
    // of the column; the area centroid (0.5, 13/6) lies inside the square with the arms.
    const int cross[6][2] = {{0, 0}, {0, 1}, {0, 2}, {0, 3}, {-1, 2}, {1, 2}};
    ori_pattern *p = net_of_cells(cross, 6);
    cr_assert_eq(ori_pattern_face_count(p), 6);
    cr_assert_eq(ori_pattern_center_face(p), test_face_at(p, 0.5, 2.5));
    ori_pattern_destroy(p);
    // Upside down (arms below the middle): the middle square again, not the column's neighbour.
    const int down[6][2] = {{0, 0}, {0, 1}, {0, 2}, {0, 3}, {-1, 1}, {1, 1}};
    p = net_of_cells(down, 6);
    cr_assert_eq(ori_pattern_center_face(p), test_face_at(p, 0.5, 1.5));
    ori_pattern_destroy(p);
    // An L (three squares): the centroid (5/6, 5/6) lies in the corner square.
    const int ell[3][2] = {{0, 0}, {1, 0}, {0, 1}};
    p = net_of_cells(ell, 3);
    cr_assert_eq(ori_pattern_center_face(p), test_face_at(p, 0.5, 0.5));
    ori_pattern_destroy(p);
    // A U of seven squares: the centroid (1.5, 19/14) lies in the notch, outside the sheet, 5/14
    // from the bottom middle square and 1/2 from the arms: the bottom middle square is chosen.
    const int u[7][2] = {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {2, 1}, {0, 2}, {2, 2}};
    p = net_of_cells(u, 7);
    cr_assert_eq(ori_pattern_face_count(p), 7);
    cr_assert_eq(ori_pattern_center_face(p), test_face_at(p, 1.5, 0.5));
    ori_pattern_destroy(p);
}

// --- dof: a nearby motion that ignores the assignment is said so ------------------------------------

static ori_dof_result dof_flat(const ori_pattern *p)
{
    ori_mechanism *m = test_mechanism_of(p);
    ori_dof_def d = ori_default_dof_def();
    ori_dof_result r;
    ori_error err;
    cr_assert_eq(ori_mechanism_dof(m, &d, &r, &err), ORI_OK, "%s", err.message);
    ori_mechanism_destroy(m);
    return r;
}

// Rabbit Ear's windmill base: the free mechanism moves near the flat sheet (nearby DOF 1), but
// only against the assignment (every assigned fold is not rigidly foldable): dof says so, naming
// a crease. The waterbomb base, the open corner and a Miura-ori keep theirs: no note.
Test(kinematics, dof_says_when_its_nearby_motion_ignores_the_assignment)
{
    const char *path = test_require_shared("rabbit-ear/cp_windmill.cp");
    ori_pattern *p = NULL;
    ori_error err;
    cr_assert_eq(ori_import_file(path, ORI_FORMAT_CP, NULL, &p, NULL, &err), ORI_OK, "%s", err.message);
    ori_dof_result r = dof_flat(p);
    cr_assert_eq(r.generic_dof, 1);
    cr_assert_gt(r.nearby_against, 0);
    cr_assert_neq(r.nearby_against_edge, ORI_NULL_INDEX);
    ori_assignment as = ori_pattern_edge(p, r.nearby_against_edge).assignment;
    cr_assert(as == ORI_ASSIGN_MOUNTAIN || as == ORI_ASSIGN_VALLEY);
    cr_assert_lt(r.nearby_against_rad * (as == ORI_ASSIGN_VALLEY ? 1.0 : -1.0), 0.0);
    // ... and indeed no assigned crease driven its way folds.
    ori_mechanism *m = test_mechanism_of(p);
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_assignment a = ori_pattern_edge(p, e).assignment;
        if (a != ORI_ASSIGN_MOUNTAIN && a != ORI_ASSIGN_VALLEY) continue;
        ori_motion_def d = ori_default_motion_def();
        d.driven_edge = e;
        d.to_rad = (a == ORI_ASSIGN_VALLEY ? 1.0 : -1.0) * ORI_PI / 3;
        d.step_rad = ORI_PI / 18;
        ori_motion *mo = test_solve(m, &d);
        cr_assert_neq(ori_motion_verdict_of(mo), ORI_MOTION_VALID, "crease %d", e);
        ori_motion_destroy(mo);
    }
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
    const char *keep[] = {"tests/data/waterbomb-base.fold", "examples/patterns/open-corner.fold", "tests/data/miura-4x4.fold"};
    for (int i = 0; i < 3; ++i) {
        p = test_load_pattern(test_repo_path(keep[i]), 0);
        r = dof_flat(p);
        cr_assert_gt(r.generic_dof, 0, "%s", keep[i]);
        cr_assert_eq(r.nearby_against, 0, "%s: crease %d", keep[i], r.nearby_against_edge);
        cr_assert_eq(r.nearby_against_edge, ORI_NULL_INDEX);
        ori_pattern_destroy(p);
    }
}

// The step budget (ori_motion_def.max_steps, default ORI_KIN_MAX_WALK_STEPS): the 2 × 2 waterbomb
// from flat with the lock set --lock auto proposes for crease 20 is a branch the drive barely
// moves along (steps of ~4e-7 rad, one rejected per accepted): before the budget, `fold
// --lock auto` ran past ten minutes in the proposal's trial folds. The motion stops when the
// budget is spent, the stop of kind ORI_BLOCK_STEP_LIMIT, its frames closed up to there.
Test(kinematics, a_creeping_motion_stops_at_its_step_budget, .init = test_leak_setup, .fini = test_leak_check)
{
    ori_pattern *p = test_load_pattern(test_repo_path("tests/data/waterbomb-2x2.fold"), 0);
    ori_mechanism *m = test_mechanism_of(p);
    int locks[] = {4, 15, 16, 17, 19, 23, 31, 36, 37, 39, 41, 42};
    ori_motion_def d = ori_default_motion_def();
    cr_assert_eq(d.max_steps, ORI_KIN_MAX_WALK_STEPS);
    d.fixed_face = 0, d.driven_edge = 20, d.to_rad = ORI_PI / 2, d.step_rad = 10.0 * ORI_PI / 180.0;
    d.locked_edges = locks, d.locked_count = 12;
    d.max_steps = 2000;
    ori_motion *mo = NULL;
    ori_error err;
    cr_assert_eq(ori_motion_solve(m, &d, &mo, &err), ORI_OK, "%s", err.message);
    ori_motion_block b;
    cr_assert(ori_motion_block_of(mo, &b), "%s", ori_motion_reason(mo));
    cr_assert_eq(b.kind, ORI_BLOCK_STEP_LIMIT, "%s", ori_motion_reason(mo));
    ori_motion_stats st = ori_motion_stats_of(mo);
    cr_assert_eq(st.steps + st.rejected_steps, 2000 + 2 * 9); // (the budget beyond twice the 9 output steps)
    cr_assert(strstr(ori_motion_reason(mo), "after 2018 continuation steps (the budget)") != NULL, "%s", ori_motion_reason(mo));
    int n = ori_motion_frame_count(mo);
    cr_assert_geq(n, 2);
    cr_assert_gt(b.drive_rad, 0.0);
    cr_assert_lt(b.drive_rad, d.to_rad);
    cr_assert_float_eq(ori_motion_frame_drive(mo, n - 1), b.drive_rad, 1e-15);
    for (int f = 0; f < n; ++f) cr_assert_leq(ori_mechanism_residual(m, ori_motion_frame_angles(mo, f)), 1e-9);
    ori_motion_destroy(mo);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}
