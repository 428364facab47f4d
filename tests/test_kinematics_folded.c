// Kinematics from a fully folded start (docs/kinematics.md §6.3, "A fully folded start"): a
// state with every moving crease at 0 or ±180° is a singular point like the flat sheet; the
// branch analysis lets a crease at ±180° move only toward 0. Miura-ori folded flat and unfolded
// again (the reverse path), a single degree-4 vertex with both solvers, a crease at ±180°
// never driven past it.
#define _DEFAULT_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "support.h"

TestSuite(kinematics_folded, .init = test_leak_setup, .fini = test_leak_check);

#define DEG (ORI_PI / 180.0)

// The frame of mo whose drive is s (exactly, as both walks land on the grid), or -1.
static int frame_at(const ori_motion *mo, double s)
{
    for (int k = 0; k < ori_motion_frame_count(mo); ++k)
        if (fabs(ori_motion_frame_drive(mo, k) - s) <= 1e-12) return k;
    return -1;
}

// Every frame of back lies on fwd's path: the state of fwd at the same drive value to tol
// (radians); every angle within [−π, π]; and no crease turns away from 0 on the way (|θ| never
// grows: the creases at ±180° can only unfold).
static void assert_reverse_path(const ori_motion *fwd, const ori_motion *back, int edges, double tol)
{
    for (int k = 0; k < ori_motion_frame_count(back); ++k) {
        double s = ori_motion_frame_drive(back, k);
        int f = frame_at(fwd, s);
        cr_assert_geq(f, 0, "frame %d at %.12g deg has no forward frame", k, s / DEG);
        const double *a = ori_motion_frame_angles(back, k), *b = ori_motion_frame_angles(fwd, f);
        for (int e = 0; e < edges; ++e) {
            cr_assert_leq(fabs(a[e]), ORI_PI, "frame %d edge %d at %.17g", k, e, a[e]);
            cr_assert_float_eq(a[e], b[e], tol, "frame %d (drive %.6f deg) edge %d: %.17g, forward %.17g", k, s / DEG, e,
                               a[e], b[e]);
            if (k > 0) {
                const double *p = ori_motion_frame_angles(back, k - 1);
                cr_assert_leq(fabs(a[e]), fabs(p[e]) + 1e-12, "frame %d edge %d turns away from 0", k, e);
            }
        }
    }
}

// An n × n Miura-ori folded flat (the drive to ±180° by 1°: every crease at ±180°) and unfolded
// from that last state to 0 by 1°, 10° and 60°: valid, and each frame is the forward fold's
// state at the same drive (the reverse path) to 1e-9 rad, with both ends exact.
static void miura_unfolds(int n)
{
    ori_pattern *p = test_miura(n, n, 1.0, 1.0, 60 * DEG, NULL);
    ori_mechanism *m = test_mechanism_of(p);
    int E = ori_pattern_edge_count(p);
    double sg;
    ori_motion_def d = ori_default_motion_def();
    d.driven_edge = test_miura_drive(p, n, &sg);
    d.to_rad = sg * ORI_PI;
    d.step_rad = 1 * DEG;
    ori_motion *fwd = test_solve(m, &d);
    cr_assert_eq(ori_motion_verdict_of(fwd), ORI_MOTION_VALID, "%s", ori_motion_reason(fwd));
    int F = ori_motion_frame_count(fwd);
    cr_assert_eq(F, 181);
    // The forward fold ends within 1e-9 rad of ±180° (the corrector at a singular point); the
    // unfold starts from the exact flat-folded state (as read back from a file: ±180).
    const double *end = ori_motion_frame_angles(fwd, F - 1);
    double *folded = malloc(sizeof(double) * (size_t)E);
    int creases = 0;
    for (int e = 0; e < E; ++e) {
        folded[e] = end[e];
        if (ori_pattern_edge(p, e).assignment == ORI_ASSIGN_BOUNDARY) continue;
        creases++;
        cr_assert_geq(fabs(end[e]), ORI_PI - 1e-8, "edge %d at %.17g: not fully folded", e, end[e]);
        folded[e] = end[e] > 0.0 ? ORI_PI : -ORI_PI;
    }
    cr_assert_gt(creases, 0);

    const double steps[3] = {1, 10, 60};
    for (int i = 0; i < 3; ++i) {
        ori_motion_def u = d;
        u.start_angles_rad = folded;
        u.to_rad = 0.0;
        u.step_rad = steps[i] * DEG;
        ori_motion *back = test_solve(m, &u);
        cr_assert_eq(ori_motion_verdict_of(back), ORI_MOTION_VALID, "%d x %d, step %g: %s", n, n, steps[i],
                     ori_motion_reason(back));
        int B = ori_motion_frame_count(back);
        cr_assert_eq(B, (int)lround(180.0 / steps[i]) + 1, "step %g: %d frames", steps[i], B);
        assert_reverse_path(fwd, back, E, 1e-9);
        const double *flat = ori_motion_frame_angles(back, B - 1);
        for (int e = 0; e < E; ++e) cr_assert_leq(fabs(flat[e]), 1e-9, "edge %d ends at %.3g", e, flat[e]);
        for (int k = 0; k < B; ++k) cr_assert_leq(ori_motion_frame_residual(back, k), ORI_TOL_RESIDUAL);
        ori_motion_destroy(back);
    }
    free(folded);
    ori_motion_destroy(fwd);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

Test(kinematics_folded, miura_3x3_folded_flat_unfolds_along_the_reverse_path) { miura_unfolds(3); }

Test(kinematics_folded, miura_4x4_folded_flat_unfolds_along_the_reverse_path) { miura_unfolds(4); }

// One Miura vertex (a 2 × 2 Miura-ori: degree 4, every crease folds) folded flat by the closed
// form, then unfolded from there by the closed form and by continuation: both valid, the same
// frames to 1e-9°, on the forward path, every crease at 0 at the end.
Test(kinematics_folded, degree4_vertex_folded_flat_unfolds_alike_with_both_solvers)
{
    ori_pattern *p = test_miura(2, 2, 1.0, 1.0, 60 * DEG, NULL);
    ori_mechanism *m = test_mechanism_of(p);
    int E = ori_pattern_edge_count(p);
    double sg;
    ori_motion_def d = ori_default_motion_def();
    d.driven_edge = test_miura_drive(p, 2, &sg);
    d.to_rad = sg * ORI_PI;
    d.step_rad = 10 * DEG;
    d.solver = ORI_SOLVER_ANALYTIC;
    ori_motion *fwd = test_solve(m, &d);
    cr_assert_eq(ori_motion_verdict_of(fwd), ORI_MOTION_VALID, "%s", ori_motion_reason(fwd));
    const double *folded = ori_motion_frame_angles(fwd, ori_motion_frame_count(fwd) - 1);
    for (int e = 0; e < E; ++e)
        if (ori_pattern_edge(p, e).assignment != ORI_ASSIGN_BOUNDARY) cr_assert_eq(fabs(folded[e]), ORI_PI);

    ori_motion_def u = d;
    u.start_angles_rad = folded;
    u.to_rad = 0.0;
    ori_motion *an = test_solve(m, &u);
    u.solver = ORI_SOLVER_NUMERIC;
    ori_motion *nu = test_solve(m, &u);
    cr_assert_eq(ori_motion_verdict_of(an), ORI_MOTION_VALID, "%s", ori_motion_reason(an));
    cr_assert_eq(ori_motion_verdict_of(nu), ORI_MOTION_VALID, "%s", ori_motion_reason(nu));
    cr_assert(ori_motion_stats_of(an).analytic);
    cr_assert(!ori_motion_stats_of(nu).analytic);
    cr_assert_eq(ori_motion_frame_count(an), 19);
    cr_assert_eq(ori_motion_frame_count(nu), 19);
    for (int k = 0; k < 19; ++k) {
        cr_assert_eq(ori_motion_frame_drive(an, k), ori_motion_frame_drive(nu, k));
        const double *a = ori_motion_frame_angles(an, k), *b = ori_motion_frame_angles(nu, k);
        for (int e = 0; e < E; ++e) cr_assert_float_eq(a[e], b[e], 1e-9 * DEG, "frame %d edge %d", k, e);
    }
    assert_reverse_path(fwd, an, E, 1e-9 * DEG);
    assert_reverse_path(fwd, nu, E, 1e-9 * DEG);
    ori_motion_destroy(an);
    ori_motion_destroy(nu);
    ori_motion_destroy(fwd);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

// Miura vertices of cell angle γ = 15°, 30°, …, 85° and aspect b/a = 0.5, 1, 2, each folded flat
// (closed form, 15° steps) and unfolded from there by both solvers: valid alike, frames to 1e-9°.
Test(kinematics_folded, miura_vertices_of_every_angle_unfold_alike_with_both_solvers)
{
    const double gammas[6] = {15, 30, 45, 60, 75, 85}, aspects[3] = {0.5, 1.0, 2.0};
    for (int g = 0; g < 6; ++g)
        for (int q = 0; q < 3; ++q) {
            ori_pattern *p = test_miura(2, 2, 1.0, aspects[q], gammas[g] * DEG, NULL);
            ori_mechanism *m = test_mechanism_of(p);
            int E = ori_pattern_edge_count(p);
            double sg;
            ori_motion_def d = ori_default_motion_def();
            d.driven_edge = test_miura_drive(p, 2, &sg);
            d.to_rad = sg * ORI_PI;
            d.step_rad = 15 * DEG;
            d.solver = ORI_SOLVER_ANALYTIC;
            ori_motion *fwd = test_solve(m, &d);
            cr_assert_eq(ori_motion_verdict_of(fwd), ORI_MOTION_VALID, "γ %g: %s", gammas[g], ori_motion_reason(fwd));
            ori_motion_def u = d;
            u.start_angles_rad = ori_motion_frame_angles(fwd, ori_motion_frame_count(fwd) - 1);
            u.to_rad = 0.0;
            ori_motion *an = test_solve(m, &u);
            u.solver = ORI_SOLVER_NUMERIC;
            ori_motion *nu = test_solve(m, &u);
            cr_assert_eq(ori_motion_verdict_of(an), ORI_MOTION_VALID, "γ %g b %g: %s", gammas[g], aspects[q],
                         ori_motion_reason(an));
            cr_assert_eq(ori_motion_verdict_of(nu), ORI_MOTION_VALID, "γ %g b %g: %s", gammas[g], aspects[q],
                         ori_motion_reason(nu));
            cr_assert_eq(ori_motion_frame_count(an), 13);
            cr_assert_eq(ori_motion_frame_count(nu), 13);
            for (int k = 0; k < 13; ++k) {
                const double *a = ori_motion_frame_angles(an, k), *b = ori_motion_frame_angles(nu, k);
                for (int e = 0; e < E; ++e)
                    cr_assert_float_eq(a[e], b[e], 1e-9 * DEG, "γ %g b %g frame %d edge %d: %.17g vs %.17g", gammas[g],
                                       aspects[q], k, e, a[e], b[e]);
            }
            assert_reverse_path(fwd, an, E, 1e-9 * DEG);
            ori_motion_destroy(an);
            ori_motion_destroy(nu);
            ori_motion_destroy(fwd);
            ori_mechanism_destroy(m);
            ori_pattern_destroy(p);
        }
}

// A single vertex at the origin with four creases to the unit circle at the angles t[] and
// boundary chords between their ends (FOLD text, as in test_solver_agree.c).
static ori_pattern *vertex4(const double t[4], const char *assign, char *text, size_t size)
{
    size_t len = 0;
    len += (size_t)snprintf(text + len, size - len, "{\"vertices_coords\":[[0,0]");
    for (int i = 0; i < 4; ++i) len += (size_t)snprintf(text + len, size - len, ",[%.17g,%.17g]", cos(t[i]), sin(t[i]));
    len += (size_t)snprintf(text + len, size - len,
                            "],\"edges_vertices\":[[0,1],[0,2],[0,3],[0,4],[1,2],[2,3],[3,4],[4,1]],\"edges_assignment\":[");
    for (int i = 0; i < 4; ++i) len += (size_t)snprintf(text + len, size - len, "\"%c\",", assign[i]);
    snprintf(text + len, size - len, "\"B\",\"B\",\"B\",\"B\"]}");
    ori_pattern *p = test_pattern_of_text(text);
    return p;
}

// Random flat-foldable degree-4 vertices (Kawasaki: sectors α, β, π − α, π − β, each 10°–170°)
// with every 3–1 assignment: those the closed form folds flat (every crease at ±180°, crease 0
// driven) are unfolded from there, each crease in turn driven to 0, by both solvers: the same
// verdict (valid), the same frames to 1e-9° (measured: 9.5e-13 rad), the flat end to 1e-9 rad
// (measured: 7.1e-11 rad), no |θ| growing; driving crease 0 retraces the forward path (1e-9°).
// And driving crease 0 on through the flat state to the other side: the same verdict and frames
// (exactly flat at 0; the fully folded end to 1e-5 rad). 40 vertices, 160 fold flat.
Test(kinematics_folded, random_flat_foldable_vertices_unfold_alike_with_both_solvers)
{
    srand48(20261123);
    int flat = 0, legs = 0;
    char text[2048];
    for (int trial = 0; trial < 40; ++trial) {
        double a = (10 + 160 * drand48()) * DEG, b = (10 + 160 * drand48()) * DEG;
        double t[4] = {0.0, a, a + b, ORI_PI + b};
        for (int odd = 0; odd < 8; ++odd) {
            char as[4];
            for (int i = 0; i < 4; ++i) as[i] = (i == odd % 4) == (odd < 4) ? 'M' : 'V';
            ori_pattern *p = vertex4(t, as, text, sizeof text);
            ori_mechanism *m = test_mechanism_of(p);
            int E = ori_pattern_edge_count(p);
            ori_motion_def d = ori_default_motion_def();
            d.driven_edge = 0;
            d.to_rad = as[0] == 'V' ? ORI_PI : -ORI_PI;
            d.step_rad = 15 * DEG;
            d.solver = ORI_SOLVER_ANALYTIC;
            ori_motion *fwd = test_solve(m, &d);
            const double *end = ori_motion_frame_angles(fwd, ori_motion_frame_count(fwd) - 1);
            bool folded = ori_motion_verdict_of(fwd) == ORI_MOTION_VALID;
            for (int e = 0; e < 4 && folded; ++e) folded = fabs(end[e]) >= ORI_PI - 1e-9;
            if (folded) {
                flat++;
                for (int drive = 0; drive < 4; ++drive) {
                    ori_motion_def u = d;
                    u.start_angles_rad = end;
                    u.driven_edge = drive;
                    u.to_rad = 0.0;
                    ori_motion *an = test_solve(m, &u);
                    u.solver = ORI_SOLVER_NUMERIC;
                    ori_motion *nu = test_solve(m, &u);
                    cr_assert_eq(ori_motion_verdict_of(an), ORI_MOTION_VALID, "%s drive %d: %s", text, drive,
                                 ori_motion_reason(an));
                    cr_assert_eq(ori_motion_verdict_of(nu), ORI_MOTION_VALID, "%s drive %d: %s", text, drive,
                                 ori_motion_reason(nu));
                    int F = ori_motion_frame_count(an);
                    cr_assert_eq(ori_motion_frame_count(nu), F, "%s drive %d", text, drive);
                    for (int k = 0; k < F; ++k) {
                        cr_assert_eq(ori_motion_frame_drive(an, k), ori_motion_frame_drive(nu, k));
                        const double *x = ori_motion_frame_angles(an, k), *y = ori_motion_frame_angles(nu, k);
                        for (int e = 0; e < E; ++e) {
                            // The last frame is the flat state, a singular point: there the
                            // corrector converges only linearly (up to 7.1e-11 rad off).
                            double tol = k == F - 1 ? 1e-9 : 1e-9 * DEG;
                            cr_assert_float_eq(x[e], y[e], tol, "%s drive %d frame %d edge %d: %.17g vs %.17g", text,
                                               drive, k, e, x[e], y[e]);
                            if (k > 0)
                                cr_assert_leq(fabs(x[e]), fabs(ori_motion_frame_angles(an, k - 1)[e]) + 1e-12,
                                              "%s drive %d frame %d edge %d turns away from 0", text, drive, k, e);
                        }
                    }
                    if (drive == 0) assert_reverse_path(fwd, an, E, 1e-9 * DEG);
                    legs++;
                    ori_motion_destroy(an);
                    ori_motion_destroy(nu);
                }
                // On through the flat state to the other side (against the assignment): the
                // same verdict, and the same frames (exactly flat at 0) to 1e-9° with both.
                ori_motion_def w = d;
                w.start_angles_rad = end;
                w.to_rad = -d.to_rad;
                ori_motion *an = test_solve(m, &w);
                w.solver = ORI_SOLVER_NUMERIC;
                ori_motion *nu = test_solve(m, &w);
                cr_assert_eq(ori_motion_verdict_of(an), ori_motion_verdict_of(nu), "%s through flat: %s / %s", text,
                             ori_motion_reason(an), ori_motion_reason(nu));
                int F = ori_motion_frame_count(an);
                cr_assert_eq(F, 25, "%s through flat: %d frames", text, F);
                cr_assert_eq(ori_motion_frame_count(nu), F);
                for (int k = 0; k < F; ++k) {
                    const double *x = ori_motion_frame_angles(an, k), *y = ori_motion_frame_angles(nu, k);
                    for (int e = 0; e < E; ++e) {
                        // The end is fully folded again, a singular point that the continuation
                        // reaches after a crossing only to about 1e-6 rad (1.33e-6 rad measured;
                        // the same from a regular start, e.g. 165°: docs/kinematics.md §15).
                        double tol = k == F - 1 ? 1e-5 : 1e-9 * DEG;
                        cr_assert_float_eq(x[e], y[e], tol, "%s through flat frame %d edge %d: %.17g vs %.17g", text, k,
                                           e, x[e], y[e]);
                        if (k == 12) cr_assert_eq(x[e], 0.0);
                    }
                }
                ori_motion_destroy(an);
                ori_motion_destroy(nu);
            }
            ori_motion_destroy(fwd);
            ori_mechanism_destroy(m);
            ori_pattern_destroy(p);
        }
    }
    // Each vertex folds flat with four of its eight 3–1 assignments.
    cr_assert_eq(flat, 160, "%d vertices folded flat", flat);
    cr_assert_eq(legs, 4 * flat);
}

// A partly fully folded start: examples/patterns/degree4-vertex.fold folded along its straight
// line (creases (0,0)–(1,0) and (0,0)–(−1,0) at +180°, the other two flat; the sheet in one
// plane, a singular start). From there (a) the other line folds — its creases to ±180° while
// the folded pair stays at exactly +180°, never beyond; (b) the folded pair unfolds to 0. Both
// solvers: the same verdicts and frames to 1e-9°.
Test(kinematics_folded, degree4_vertex_half_folded_folds_on_or_back_alike_with_both_solvers)
{
    ori_pattern *p = test_load_pattern(test_repo_path("examples/patterns/degree4-vertex.fold"), 0);
    ori_mechanism *m = test_mechanism_of(p);
    int E = ori_pattern_edge_count(p);
    int right = test_edge_at(p, 0, 0, 1, 0), left = test_edge_at(p, 0, 0, -1, 0);
    int up = ori_pattern_find_edge_at(p, ori_v2_make(0.2, 0.2 * sqrt(3.0))); // (0,0)–(1/√3, 1)
    cr_assert_neq(up, ORI_NULL_INDEX);
    ori_motion_def d = ori_default_motion_def();
    d.fixed_face = test_face_at(p, 0.5, 0.5);
    d.driven_edge = right;
    d.to_rad = ORI_PI;
    d.step_rad = 30 * DEG;
    ori_motion *half = test_solve(m, &d);
    cr_assert_eq(ori_motion_verdict_of(half), ORI_MOTION_VALID, "%s", ori_motion_reason(half));
    const double *start = ori_motion_frame_angles(half, ori_motion_frame_count(half) - 1);
    cr_assert_eq(start[right], ORI_PI);
    cr_assert_eq(start[left], ORI_PI);
    cr_assert_leq(fabs(start[up]), 1e-12);

    for (int leg = 0; leg < 2; ++leg) {
        ori_motion_def u = d;
        u.start_angles_rad = start;
        u.driven_edge = leg == 0 ? up : right;
        u.to_rad = leg == 0 ? ORI_PI : 0.0;
        u.solver = ORI_SOLVER_ANALYTIC;
        ori_motion *an = test_solve(m, &u);
        u.solver = ORI_SOLVER_NUMERIC;
        ori_motion *nu = test_solve(m, &u);
        cr_assert_eq(ori_motion_verdict_of(an), ORI_MOTION_VALID, "leg %d: %s", leg, ori_motion_reason(an));
        cr_assert_eq(ori_motion_verdict_of(nu), ORI_MOTION_VALID, "leg %d: %s", leg, ori_motion_reason(nu));
        int F = ori_motion_frame_count(an);
        cr_assert_eq(F, 7);
        cr_assert_eq(ori_motion_frame_count(nu), F);
        for (int k = 0; k < F; ++k) {
            const double *a = ori_motion_frame_angles(an, k), *b = ori_motion_frame_angles(nu, k);
            for (int e = 0; e < E; ++e) {
                cr_assert_float_eq(a[e], b[e], 1e-9 * DEG, "leg %d frame %d edge %d", leg, k, e);
                cr_assert_leq(fabs(a[e]), ORI_PI);
            }
            if (leg == 0) {
                // The folded pair holds at +180° exactly; the other line folds as the drive.
                cr_assert_eq(a[right], ORI_PI, "frame %d: %.17g", k, a[right]);
                cr_assert_eq(a[left], ORI_PI);
                cr_assert_float_eq(fabs(a[up]), k * 30 * DEG, 1e-12);
            } else {
                // Unfolding: the pair together, the other line flat.
                cr_assert_float_eq(a[left], a[right], 1e-12);
                cr_assert_float_eq(a[right], ORI_PI - k * 30 * DEG, 1e-12);
                cr_assert_leq(fabs(a[up]), 1e-12);
            }
        }
        ori_motion_destroy(an);
        ori_motion_destroy(nu);
    }
    ori_motion_destroy(half);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

// The modes from a flat-folded state: the 1 × 1 waterbomb base folded to its targets (every crease
// at ±180°), then (a) `--percent 0` from there is the start itself (the goal is P % of the way
// from the start: reached, one frame, nothing moves); (b) three creases driven together to 0
// (its first mountain and first two valleys) unfold it: reached, every angle within [−π, π] on the
// way. It used to stop `limit` at once: the start's bias toward the assignment pushed the valleys
// at +180° outward.
Test(kinematics_folded, waterbomb_base_folded_flat_unfolds_by_drives_and_stays_at_percent_0)
{
    ori_pattern *p = test_generated(ORI_TESS_WATERBOMB, 1, 1);
    ori_error err;
    ori_mechanism *m = test_mechanism_of(p);
    int E = ori_pattern_edge_count(p);
    ori_target_fold_def t = ori_default_target_fold_def();
    ori_multifold *full = NULL;
    cr_assert_eq(ori_target_fold_solve(m, &t, &full, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_multifold_verdict_of(full), ORI_MULTIFOLD_REACHED, "%s", ori_multifold_reason(full));
    const double *folded = ori_multifold_frame_angles(full, ori_multifold_frame_count(full) - 1);
    int drives[3], nm = 0, nv = 0, nd = 0;
    for (int e = 0; e < E; ++e) {
        ori_assignment a = ori_pattern_edge(p, e).assignment;
        if (a == ORI_ASSIGN_BOUNDARY) continue;
        cr_assert_float_eq(fabs(folded[e]), ORI_PI, 1e-9, "edge %d", e);
        if (a == ORI_ASSIGN_MOUNTAIN && nm++ == 0) drives[nd++] = e;
        if (a == ORI_ASSIGN_VALLEY && nv++ < 2) drives[nd++] = e;
    }
    cr_assert_eq(nd, 3);

    t.start_angles_rad = folded;
    t.fraction = 0.0;
    ori_multifold *stay = NULL;
    cr_assert_eq(ori_target_fold_solve(m, &t, &stay, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_multifold_verdict_of(stay), ORI_MULTIFOLD_REACHED, "%s", ori_multifold_reason(stay));
    cr_assert_eq(ori_multifold_frame_count(stay), 1);
    for (int e = 0; e < E; ++e) cr_assert_float_eq(ori_multifold_frame_angles(stay, 0)[e], folded[e], 1e-12);

    const double zero[3] = {0, 0, 0};
    ori_drives_fold_def d = ori_default_drives_fold_def();
    d.start_angles_rad = folded;
    d.driven_edges = drives;
    d.to_rad = zero;
    d.driven_count = 3;
    ori_multifold *un = NULL;
    cr_assert_eq(ori_drives_fold_solve(m, &d, &un, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_multifold_verdict_of(un), ORI_MULTIFOLD_REACHED, "%s", ori_multifold_reason(un));
    int F = ori_multifold_frame_count(un);
    cr_assert_eq(F, 19);
    for (int k = 0; k < F; ++k) {
        const double *a = ori_multifold_frame_angles(un, k);
        // (The target fold ends a rounding beyond ±π: 8.8e-14 rad on one crease; frame 0 is that start.)
        for (int e = 0; e < E; ++e)
            cr_assert_leq(fabs(a[e]), ORI_PI + 1e-12, "frame %d edge %d: %.17g (start %.17g)", k, e, a[e], folded[e]);
        cr_assert_leq(ori_multifold_frame_residual(un, k), ORI_TOL_RESIDUAL);
        // The drives move linearly from ±π to 0.
        for (int i = 0; i < 3; ++i)
            cr_assert_float_eq(a[drives[i]], folded[drives[i]] * (1.0 - k / 18.0), 1e-12, "frame %d drive %d", k, i);
    }
    // At the end the drives are flat and so (to the continuation's accuracy at the flat state,
    // a singular point: §16.2) is the rest.
    const double *last = ori_multifold_frame_angles(un, F - 1);
    for (int e = 0; e < E; ++e) cr_assert_leq(fabs(last[e]), 1e-5, "edge %d at %.3g", e, last[e]);
    ori_multifold_destroy(un);
    ori_multifold_destroy(stay);
    ori_multifold_destroy(full);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}
