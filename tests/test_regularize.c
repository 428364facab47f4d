// Rounded drawings: snapping a vertex to the exact one it means (check --tolerance) and moving
// vertices the least so that a pattern is exactly flat-foldable and, with --rigid, rigidly
// foldable (ori_regularize).
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "support.h"

TestSuite(regularize, .init = test_leak_setup, .fini = test_leak_check);

static double deg(double d) { return ori_deg_to_rad(d); }

// A deterministic uniform number in [−1, 1] (LCG), so that the perturbations are reproducible.
static double noise(unsigned *state)
{
    *state = *state * 1664525u + 1013904223u;
    return ((double)(*state >> 8) / (double)(1u << 24)) * 2.0 - 1.0;
}

// The pattern with every vertex moved by up to amplitude × the diagonal (boundary vertices along
// the x or y axis only, so the sheet stays a rectangle; corners kept), as a drawing tool's
// rounding would; built.
static ori_pattern *perturbed(const ori_pattern *p, double amplitude, unsigned seed)
{
    ori_pattern *q = ori_pattern_clone(p);
    double L = ori_pattern_diagonal(p);
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        ori_v3 a = ori_pattern_vertex(p, v);
        xmin = fmin(xmin, a.x), xmax = fmax(xmax, a.x), ymin = fmin(ymin, a.y), ymax = fmax(ymax, a.y);
    }
    unsigned s = seed;
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        ori_v3 a = ori_pattern_vertex(p, v);
        double dx = noise(&s) * amplitude * L, dy = noise(&s) * amplitude * L;
        bool on_x = a.x == xmin || a.x == xmax, on_y = a.y == ymin || a.y == ymax;
        if (on_x) dx = 0.0;
        if (on_y) dy = 0.0;
        ori_pattern_set_vertex(q, v, ori_v3_make(a.x + dx, a.y + dy, 0.0));
    }
    ori_error err;
    cr_assert_eq(ori_pattern_build(q, NULL, &err), ORI_OK, "%s", err.message);
    return q;
}

static double max_kawasaki(const ori_pattern *p)
{
    double worst = 0.0, sec[64];
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        if (!ori_pattern_vertex_is_interior(p, v)) continue;
        int n = ori_flat_vertex_creases(p, v, NULL, sec, 64);
        worst = fmax(worst, fabs(ori_flat_kawasaki_sum(sec, n)));
    }
    return worst;
}

// --- snapping one vertex --------------------------------------------------------------------

// Sectors 100°, 80°, 80°, 100° rounded by up to 3e-6 rad: the snap makes the two classes exact
// (equal within each class to the last bit), Kawasaki and the 360° sum hold to a few ulps, and
// no sector moves more than the rounding.
Test(regularize, snap_restores_the_exact_vertex)
{
    double s[4] = {deg(100) + 3e-6, deg(80) - 1e-6, deg(80) + 2.5e-6, deg(100) - 2e-6};
    double out[4];
    double dev = ori_flat_snap_sectors(s, 4, 1e-4, out);
    cr_assert_leq(dev, 3.5e-6, "deviation %.3g", dev);
    cr_assert_eq(out[0], out[3]);
    cr_assert_eq(out[1], out[2]);
    cr_assert_leq(fabs(ori_flat_kawasaki_sum(out, 4)), 1e-15);
    cr_assert_leq(fabs(out[0] + out[1] + out[2] + out[3] - 2.0 * ORI_PI), 4e-15);
    // The least-squares answer: each class takes its mean, shifted equally to close the sum.
    double shift = (2.0 * ORI_PI - (s[0] + s[1] + s[2] + s[3])) / 4.0;
    cr_assert_leq(fabs(out[0] - ((s[0] + s[3]) / 2.0 + shift)), 1e-15);
    cr_assert_leq(fabs(out[1] - ((s[1] + s[2]) / 2.0 + shift)), 1e-15);
}

// With a tolerance below the rounding, 80° + 1e-5 and 80° stay apart: Kawasaki and the sum are
// imposed by least squares, which moves the first by 0.75e-5 and the last by 0.25e-5 (making
// them equal again); odd degree has no exact vertex.
Test(regularize, snap_without_merging_and_odd_degree)
{
    double s[4] = {deg(80) + 1e-5, deg(100), deg(100), deg(80)};
    double out[4];
    double dev = ori_flat_snap_sectors(s, 4, 1e-7, out);
    cr_assert_leq(fabs(ori_flat_kawasaki_sum(out, 4)), 1e-15);
    cr_assert_leq(fabs(out[0] + out[1] + out[2] + out[3] - 2.0 * ORI_PI), 4e-15);
    cr_assert_leq(fabs(dev - 0.75e-5), 1e-12, "dev %.17g", dev);
    cr_assert_leq(fabs(out[0] - s[0] + 0.75e-5), 1e-12);
    cr_assert_leq(fabs(out[3] - s[3] - 0.25e-5), 1e-12);
    double odd[3] = {deg(120), deg(120), deg(120)};
    cr_assert(isinf(ori_flat_snap_sectors(odd, 3, 1e-3, out)));
}

// --- check with a tolerance -------------------------------------------------------------------

// A 6 × 6 Miura-ori rounded at 1e-6 of its size fails the exact check at some vertices; with a
// tolerance of 0.01° every one of them passes "within tolerance", with a deviation above 0 and
// at most the tolerance; an exact pattern has no within-tolerance vertex.
Test(regularize, check_with_tolerance_explains_rounding)
{
    ori_pattern *m = test_miura(6, 6, 1.0, 1.0, deg(60), NULL);
    ori_pattern *q = perturbed(m, 1e-6, 7);
    ori_flat_report *exact = ori_flat_check_pattern(q, NULL);
    int failed = ori_flat_report_failed_count(exact);
    cr_assert_gt(failed, 0, "the rounding must break Kawasaki somewhere");
    ori_flat_check_def d = ori_default_flat_check_def();
    d.tolerance_rad = deg(0.01);
    ori_flat_report *tol = ori_flat_check_pattern(q, &d);
    cr_assert(ori_flat_report_flat_foldable(tol));
    cr_assert_eq(ori_flat_report_within_count(tol), failed);
    cr_assert_gt(ori_flat_report_max_deviation(tol), 0.0);
    cr_assert_leq(ori_flat_report_max_deviation(tol), deg(0.01));
    for (int i = 0; i < ori_flat_report_vertex_count(tol); ++i) {
        ori_vertex_report r = ori_flat_report_vertex(tol, i);
        cr_assert(r.flat_foldable);
        if (r.within_tolerance) cr_assert_gt(r.deviation_rad, 0.0);
    }
    ori_flat_report *clean = ori_flat_check_pattern(m, &d);
    cr_assert_eq(ori_flat_report_within_count(clean), 0);
    ori_flat_report_destroy(exact);
    ori_flat_report_destroy(tol);
    ori_flat_report_destroy(clean);
    ori_pattern_destroy(q);
    ori_pattern_destroy(m);
}

// A tolerance never rescues a wrong assignment: a degree-4 vertex with Maekawa broken fails
// with and without it.
Test(regularize, tolerance_does_not_excuse_the_assignment)
{
    ori_pattern *p = test_load_pattern(test_repo_path("examples/patterns/non-flat-foldable-vertex.fold"), 0);
    ori_flat_check_def d = ori_default_flat_check_def();
    d.tolerance_rad = deg(0.5);
    ori_flat_report *r = ori_flat_check_pattern(p, &d);
    cr_assert_not(ori_flat_report_flat_foldable(r));
    ori_flat_report_destroy(r);
    ori_pattern_destroy(p);
}

// --- regularize -------------------------------------------------------------------------------

// Kawasaki only: the rounded Miura-ori becomes exact (≤ 1e-12 rad at every vertex, measured on
// the new pattern), no vertex moves more than a few times the rounding, corners stay, boundary
// vertices stay on their side, and the exact check passes. Topology and assignment are kept.
Test(regularize, kawasaki_exact_with_least_moves)
{
    ori_pattern *m = test_miura(6, 6, 1.0, 1.0, deg(60), NULL);
    ori_pattern *q = perturbed(m, 1e-6, 11);
    cr_assert_gt(max_kawasaki(q), 1e-9);
    ori_regularize_def d = ori_default_regularize_def();
    ori_regularize_result r;
    ori_pattern *out = NULL;
    ori_error err;
    cr_assert_eq(ori_regularize(q, &d, &out, &r, &err), ORI_OK, "%s", err.message);
    cr_assert(r.converged);
    cr_assert_not(r.refused);
    cr_assert_not_null(out);
    cr_assert_leq(r.kawasaki_after_rad, 1e-12);
    cr_assert_leq(max_kawasaki(out), 1e-12);
    cr_assert_gt(r.max_move_rel, 0.0);
    cr_assert_leq(r.max_move_rel, 5e-6, "moved %.3g", r.max_move_rel);
    cr_assert_leq(r.rms_move_rel, r.max_move_rel);
    cr_assert_eq(ori_pattern_edge_count(out), ori_pattern_edge_count(q));
    cr_assert_eq(ori_pattern_face_count(out), ori_pattern_face_count(q));
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (int v = 0; v < ori_pattern_vertex_count(q); ++v) {
        ori_v3 a = ori_pattern_vertex(q, v);
        xmin = fmin(xmin, a.x), xmax = fmax(xmax, a.x), ymin = fmin(ymin, a.y), ymax = fmax(ymax, a.y);
    }
    for (int v = 0; v < ori_pattern_vertex_count(q); ++v) {
        ori_v3 a = ori_pattern_vertex(q, v), b = ori_pattern_vertex(out, v);
        bool on_x = a.x == xmin || a.x == xmax, on_y = a.y == ymin || a.y == ymax;
        if (on_x) cr_assert_leq(fabs(b.x - a.x), 1e-15 * fabs(a.x) + 1e-300, "vertex %d left its side", v);
        if (on_y) cr_assert_leq(fabs(b.y - a.y), 1e-15 * fabs(a.y) + 1e-300, "vertex %d left its side", v);
        if (on_x && on_y) cr_assert(b.x == a.x && b.y == a.y, "corner %d moved", v);
    }
    for (int e = 0; e < ori_pattern_edge_count(q); ++e)
        cr_assert_eq(ori_pattern_edge(out, e).assignment, ori_pattern_edge(q, e).assignment);
    ori_flat_report *rep = ori_flat_check_pattern(out, NULL);
    cr_assert(ori_flat_report_flat_foldable(rep));
    ori_flat_report_destroy(rep);
    ori_pattern_destroy(out);
    ori_pattern_destroy(q);
    ori_pattern_destroy(m);
}

// The iteration bound (docs/conventions.md, "Bounded work"): the perturbed Miura needs a few
// Gauss-Newton iterations; with max_iterations = 1 the run stops there, says it did not converge,
// counts one iteration, improves nothing beyond what one step does and hands out no pattern.
Test(regularize, iteration_bound_stops_without_a_pattern)
{
    ori_pattern *m = test_miura(6, 6, 1.0, 1.0, deg(60), NULL);
    ori_pattern *q = perturbed(m, 1e-3, 11);
    ori_regularize_def d = ori_default_regularize_def();
    ori_regularize_result r;
    ori_pattern *out = NULL;
    ori_error err;
    cr_assert_eq(ori_regularize(q, &d, &out, &r, &err), ORI_OK, "%s", err.message);
    cr_assert(r.converged);
    int needed = r.iterations;
    cr_assert_gt(needed, 1, "converged in %d iteration(s): the bound is not reached", needed);
    ori_pattern_destroy(out);
    out = NULL;
    d.max_iterations = 1;
    cr_assert_eq(ori_regularize(q, &d, &out, &r, &err), ORI_OK, "%s", err.message);
    cr_assert_not(r.converged);
    cr_assert_eq(r.iterations, 1);
    cr_assert_null(out);
    cr_assert_gt(r.kawasaki_after_rad, 1e-12);
    cr_assert(r.stopped, "the bound, not a stall, ended it");
    // With keep_partial the best found comes back: better than the input, not exact, and a
    // second run from it (the CLI's "regularize it again") converges to an exact pattern.
    d.keep_partial = true;
    cr_assert_eq(ori_regularize(q, &d, &out, &r, &err), ORI_OK, "%s", err.message);
    cr_assert(r.stopped && !r.converged);
    cr_assert_not_null(out);
    double before = r.kawasaki_before_rad, after = r.kawasaki_after_rad;
    cr_assert_lt(after, 0.1 * before, "one step removes most of the miss: %g -> %g", before, after);
    cr_assert_gt(after, 1e-12);
    ori_regularize_def d2 = ori_default_regularize_def();
    ori_pattern *again = NULL;
    cr_assert_eq(ori_regularize(out, &d2, &again, &r, &err), ORI_OK, "%s", err.message);
    cr_assert(r.converged && !r.stopped);
    cr_assert_not_null(again);
    cr_assert_leq(r.kawasaki_after_rad, ORI_TOL_REGULARIZE_KAWASAKI_RAD);
    cr_assert_float_eq(r.kawasaki_before_rad, after, 1e-15);
    ori_pattern_destroy(again);
    ori_pattern_destroy(out);
    ori_pattern_destroy(q);
    ori_pattern_destroy(m);
}

// The progress callback: fractions in [0, 1], never decreasing, one per iteration; returning
// false cancels with ORI_ERR_LIMIT and the result says stopped (the best found with keep_partial).
typedef struct fractions {
    double f[256];
    int n, cancel_at;
} fractions;
static bool record_fraction(double f, void *user)
{
    fractions *F = user;
    if (F->n < 256) F->f[F->n] = f;
    return ++F->n != F->cancel_at;
}
Test(regularize, progress_is_monotone_and_cancels)
{
    ori_pattern *m = test_miura(6, 6, 1.0, 1.0, deg(60), NULL);
    ori_pattern *q = perturbed(m, 1e-3, 11);
    ori_regularize_def d = ori_default_regularize_def();
    fractions F = {.n = 0, .cancel_at = -1};
    d.progress = record_fraction, d.progress_user = &F;
    ori_regularize_result r;
    ori_pattern *out = NULL;
    ori_error err;
    cr_assert_eq(ori_regularize(q, &d, &out, &r, &err), ORI_OK, "%s", err.message);
    cr_assert(r.converged && !r.stopped);
    cr_assert_geq(F.n, r.iterations, "%d calls for %d iterations", F.n, r.iterations);
    cr_assert_leq(F.n, 256);
    cr_assert_geq(F.f[0], 0.0);
    for (int i = 1; i < F.n; ++i) cr_assert_geq(F.f[i], F.f[i - 1], "fraction %d: %g after %g", i, F.f[i], F.f[i - 1]);
    cr_assert_leq(F.f[F.n - 1], 1.0);
    cr_assert_gt(F.f[F.n - 1], 0.3, "the last iteration before convergence removed most of the miss (log scale)");
    ori_pattern_destroy(out);
    out = NULL;
    F.n = 0, F.cancel_at = 2;
    d.keep_partial = true;
    cr_assert_eq(ori_regularize(q, &d, &out, &r, &err), ORI_ERR_LIMIT);
    cr_assert(strstr(err.message, "cancelled") != NULL, "%s", err.message);
    cr_assert(r.stopped && !r.converged);
    cr_assert_eq(F.n, 2);
    cr_assert_eq(r.iterations, 1, "cancelled at the second iteration's report: one step done");
    cr_assert_not_null(out);
    cr_assert_lt(r.kawasaki_after_rad, r.kawasaki_before_rad);
    ori_pattern_destroy(out);
    ori_pattern_destroy(q);
    ori_pattern_destroy(m);
}

// An exact pattern is left where it is.
Test(regularize, exact_pattern_does_not_move)
{
    ori_pattern *m = test_miura(4, 4, 1.0, 1.0, deg(70), NULL);
    ori_regularize_def d = ori_default_regularize_def();
    d.rigid = true;
    ori_regularize_result r;
    ori_pattern *out = NULL;
    cr_assert_eq(ori_regularize(m, &d, &out, &r, NULL), ORI_OK);
    cr_assert(r.converged);
    cr_assert_leq(r.max_move_rel, 1e-15);
    cr_assert_leq(r.rigid_before, 1e-12);
    ori_pattern_destroy(out);
    ori_pattern_destroy(m);
}

// Fold a regularized Miura-ori from flat to 170° by driving one zig-zag crease with the
// numeric solver; returns the verdict and the largest residual.
static ori_motion_verdict fold_miura(const ori_pattern *p, double *max_res)
{
    ori_mechanism *mech = test_mechanism_of(p);
    int drive = ORI_NULL_INDEX;
    for (int e = 0; e < ori_pattern_edge_count(p) && drive == ORI_NULL_INDEX; ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        if (ed.assignment == ORI_ASSIGN_MOUNTAIN && ori_pattern_vertex_is_interior(p, ed.v[0]) &&
            ori_pattern_vertex_is_interior(p, ed.v[1]))
            drive = e;
    }
    cr_assert_neq(drive, ORI_NULL_INDEX);
    int faces[2];
    ori_pattern_edge_faces(p, drive, faces);
    ori_motion_def d = ori_default_motion_def();
    d.fixed_face = faces[0];
    d.driven_edge = drive;
    d.to_rad = deg(-170);
    d.step_rad = deg(10);
    ori_motion *mo = NULL;
    ori_error err;
    cr_assert_eq(ori_motion_solve(mech, &d, &mo, &err), ORI_OK, "%s", err.message);
    ori_motion_verdict v = ori_motion_verdict_of(mo);
    *max_res = 0.0;
    for (int k = 0; k < ori_motion_frame_count(mo); ++k) *max_res = fmax(*max_res, ori_motion_frame_residual(mo, k));
    ori_motion_destroy(mo);
    ori_mechanism_destroy(mech);
    return v;
}

// Rigid: the rounded Miura-ori does not fold at all (its vertices' fold-angle relations
// contradict each other around the faces); after regularize --rigid it folds from flat to 170°
// with every state closing to 1e-10, and the second-order conditions hold to 1e-12.
Test(regularize, rigid_makes_a_rounded_miura_fold)
{
    ori_pattern *m = test_miura(5, 5, 1.0, 1.2, deg(55), NULL);
    ori_pattern *q = perturbed(m, 1e-6, 3);
    double res;
    cr_assert_neq(fold_miura(q, &res), ORI_MOTION_VALID, "the rounded drawing should not fold");
    ori_regularize_def d = ori_default_regularize_def();
    d.rigid = true;
    ori_regularize_result r;
    ori_pattern *out = NULL;
    ori_error err;
    cr_assert_eq(ori_regularize(q, &d, &out, &r, &err), ORI_OK, "%s", err.message);
    cr_assert(r.converged);
    cr_assert_gt(r.rigid_before, 1e-9);
    cr_assert_leq(r.rigid_after, 1e-12);
    cr_assert_leq(r.kawasaki_after_rad, 1e-12);
    cr_assert_leq(r.max_move_rel, 1e-5, "moved %.3g", r.max_move_rel);
    cr_assert_eq(fold_miura(out, &res), ORI_MOTION_VALID);
    cr_assert_leq(res, 1e-10);
    ori_pattern_destroy(out);
    ori_pattern_destroy(q);
    ori_pattern_destroy(m);
}

// Far from exact: a degree-4 vertex whose sectors miss Kawasaki by 20° needs a large move and is
// refused at the default limit (no pattern handed back) but accepted with a generous one.
Test(regularize, far_patterns_are_refused)
{
    ori_pattern *p = test_load_pattern(test_repo_path("examples/patterns/non-flat-foldable-vertex.fold"), 0);
    ori_regularize_def d = ori_default_regularize_def();
    ori_regularize_result r;
    ori_pattern *out = NULL;
    cr_assert_eq(ori_regularize(p, &d, &out, &r, NULL), ORI_OK);
    cr_assert(r.kawasaki_before_rad > deg(1));
    cr_assert(r.refused);
    cr_assert_null(out);
    cr_assert_gt(r.max_move_rel, ORI_REGULARIZE_MAX_MOVE_REL);
    d.max_move_rel = 0.5;
    cr_assert_eq(ori_regularize(p, &d, &out, &r, NULL), ORI_OK);
    cr_assert(r.converged);
    cr_assert_not_null(out);
    cr_assert_leq(max_kawasaki(out), 1e-12);
    ori_pattern_destroy(out);
    ori_pattern_destroy(p);
}

// Origami Simulator's Miura-ori drawings (shared): rounded by ~0.005°, they do not fold; after
// regularize --rigid, with moves under 1e-4 of the sheet, both fold from flat to 170°.
Test(regularize, origami_simulator_miura_drawings_fold)
{
    const char *names[2] = {"origamisimulator/Tessellations_miura-ori.svg",
                            "origamisimulator/Tessellations_miura_sharpangle.svg"};
    for (int i = 0; i < 2; ++i) {
        const char *path = test_require_shared(names[i]);
        ori_import_def id = ori_default_import_def();
        ori_pattern *p = NULL;
        ori_error err;
        cr_assert_eq(ori_import_file(path, ORI_FORMAT_SVG, &id, &p, NULL, &err), ORI_OK, "%s", err.message);
        ori_regularize_def d = ori_default_regularize_def();
        d.rigid = true;
        ori_regularize_result r;
        ori_pattern *out = NULL;
        cr_assert_eq(ori_regularize(p, &d, &out, &r, &err), ORI_OK, "%s", err.message);
        cr_assert(r.converged, "%s", names[i]);
        cr_assert_lt(r.max_move_rel, 1e-4, "%s moved %.3g", names[i], r.max_move_rel);
        double res;
        cr_assert_eq(fold_miura(out, &res), ORI_MOTION_VALID, "%s", names[i]);
        cr_assert_leq(res, 1e-10);
        ori_pattern_destroy(out);
        ori_pattern_destroy(p);
    }
}

// --- the assigned mode of degree-4 vertices -------------------------------------------------

// The pattern with every coordinate jittered by up to `jitter` (absolute; boundary vertices along
// their side only) and then rounded to `digits` decimals, as a drawing tool saves it; built.
static ori_pattern *rounded(const ori_pattern *p, double jitter, int digits, unsigned seed)
{
    ori_pattern *q = perturbed(p, jitter / ori_pattern_diagonal(p), seed);
    double scale = pow(10.0, digits);
    for (int v = 0; v < ori_pattern_vertex_count(q); ++v) {
        ori_v3 a = ori_pattern_vertex(q, v);
        ori_pattern_set_vertex(q, v, ori_v3_make(round(a.x * scale) / scale, round(a.y * scale) / scale, 0.0));
    }
    ori_error err;
    cr_assert_eq(ori_pattern_build(q, NULL, &err), ORI_OK, "%s", err.message);
    return q;
}

// Regularize --rigid, assert the result is exact and close, and fold it from flat to 170°.
static void regularize_and_fold(const ori_pattern *q, const char *what)
{
    ori_regularize_def d = ori_default_regularize_def();
    d.rigid = true;
    ori_regularize_result r;
    ori_pattern *out = NULL;
    ori_error err;
    cr_assert_eq(ori_regularize(q, &d, &out, &r, &err), ORI_OK, "%s: %s", what, err.message);
    cr_assert(r.converged, "%s: not converged (rigid %.3g)", what, r.rigid_after);
    cr_assert_not_null(out);
    cr_assert_eq(r.mode_vertices, r.interior_vertices, "%s: every Miura vertex is degree 4 and Maekawa", what);
    cr_assert_eq(r.against_edge, ORI_NULL_INDEX);
    cr_assert_leq(r.rigid_after, 1e-12, "%s", what);
    cr_assert_leq(max_kawasaki(out), 1e-12, "%s", what);
    cr_assert_lt(r.max_move_rel, 1e-4, "%s moved %.3g", what, r.max_move_rel);
    double res;
    ori_motion_verdict v = fold_miura(out, &res);
    cr_assert_eq(v, ORI_MOTION_VALID, "%s: fold verdict %d after regularize --rigid (moved %.3g)", what, (int)v,
                 r.max_move_rel);
    cr_assert_leq(res, 1e-10, "%s: residual %.3g", what, res);
    ori_pattern_destroy(out);
}

// tests/data/rounded-miura.fold (a 3 × 4 Miura-ori jittered by 6e-5 and rounded to 4 decimals):
// the second-order conditions alone let the rates of two vertices settle on their other mode
// (the straight crease line folding alone), a motion to first and second order but not along the
// assignment, and `fold` stopped at 0.13°. Held to the assigned modes it folds to 170°.
Test(regularize, rounded_miura_file_folds_along_its_assignment)
{
    ori_pattern *q = test_load_pattern(test_repo_path("tests/data/rounded-miura.fold"), 0);
    double res;
    cr_assert_neq(fold_miura(q, &res), ORI_MOTION_VALID, "the rounded drawing should not fold");
    regularize_and_fold(q, "rounded-miura.fold");
    ori_pattern_destroy(q);
}

// Generated Miura-ori of several sizes and cell angles, jittered by 6e-5 of a unit cell and
// rounded to 4 decimals with several seeds: none folds as drawn; every one folds from flat to
// 170° after regularize --rigid, moving under 1e-4 of the sheet.
Test(regularize, jittered_rounded_miuras_fold, .timeout = 60)
{
    struct {
        int rows, cols;
        double angle_deg, b;
    } sizes[] = {{3, 4, 65, 1.0}, {4, 4, 65, 1.0}, {5, 3, 60, 1.0}, {6, 5, 55, 1.2}};
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; ++i) {
        ori_pattern *m = test_miura(sizes[i].rows, sizes[i].cols, 1.0, sizes[i].b, deg(sizes[i].angle_deg), NULL);
        for (unsigned seed = 1; seed <= 3; ++seed) {
            ori_pattern *q = rounded(m, 6e-5, 4, seed);
            char what[80];
            snprintf(what, sizeof what, "%d x %d Miura, %g deg, seed %u", sizes[i].rows, sizes[i].cols,
                     sizes[i].angle_deg, seed);
            double res;
            cr_assert_neq(fold_miura(q, &res), ORI_MOTION_VALID, "%s: the rounded drawing should not fold", what);
            regularize_and_fold(q, what);
            ori_pattern_destroy(q);
        }
        ori_pattern_destroy(m);
    }
}

// A degree-4 vertex whose odd crease does not bound the smallest sector (Kawasaki and Maekawa
// hold, big-little-big fails): the mode its assignment picks folds creases 1 and 3 against their
// mountain assignment, so no motion follows the assignment; regularize --rigid says so instead of
// handing back a pattern, and `fold` agrees (invalid).
Test(regularize, assignment_against_the_mode_is_refused)
{
    ori_pattern *p = test_load_pattern(test_repo_path("tests/data/degree4-wrong-odd-crease.fold"), 0);
    ori_regularize_def d = ori_default_regularize_def();
    d.rigid = true;
    ori_regularize_result r;
    ori_pattern *out = NULL;
    cr_assert_eq(ori_regularize(p, &d, &out, &r, NULL), ORI_OK);
    cr_assert_not(r.converged);
    cr_assert_null(out);
    cr_assert_eq(r.mode_vertices, 1);
    cr_assert(r.against_edge == 1 || r.against_edge == 3, "against edge %d", r.against_edge);
    cr_assert_leq(r.rigid_after, 1e-12, "the mode itself closes");
    cr_assert_leq(r.max_move_rel, 1e-15, "nothing needed to move");
    ori_mechanism *mech = test_mechanism_of(p);
    int faces[2];
    ori_pattern_edge_faces(p, 0, faces);
    ori_motion_def md = ori_default_motion_def();
    md.fixed_face = faces[0];
    md.driven_edge = 0;
    md.to_rad = deg(-90);
    ori_motion *mo = NULL;
    cr_assert_eq(ori_motion_solve(mech, &md, &mo, NULL), ORI_OK);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_INVALID_ASSIGNMENT);
    ori_motion_destroy(mo);
    ori_mechanism_destroy(mech);
    ori_pattern_destroy(p);
}

// What the assigned modes cover: a generated waterbomb tessellation has only degree-6 interior
// vertices, so a jittered, rounded one is regularized to second order alone (no vertex held to a
// mode), still exactly and with moves under 1e-4 of the sheet.
Test(regularize, degree_six_vertices_stay_second_order)
{
    ori_pattern *w = test_generated(ORI_TESS_WATERBOMB, 3, 4);
    ori_error err;
    ori_pattern *q = rounded(w, 6e-5, 4, 2);
    cr_assert_gt(max_kawasaki(q), 1e-6);
    ori_regularize_def d = ori_default_regularize_def();
    d.rigid = true;
    ori_regularize_result r;
    ori_pattern *out = NULL;
    cr_assert_eq(ori_regularize(q, &d, &out, &r, &err), ORI_OK, "%s", err.message);
    cr_assert(r.converged);
    cr_assert_gt(r.interior_vertices, 0);
    cr_assert_eq(r.mode_vertices, 0);
    cr_assert_leq(r.rigid_after, 1e-12);
    cr_assert_leq(max_kawasaki(out), 1e-12);
    cr_assert_lt(r.max_move_rel, 1e-4);
    ori_pattern_destroy(out);
    ori_pattern_destroy(q);
    ori_pattern_destroy(w);
}

// The finite form behind the assigned modes: along the whole motion of the regularized
// rounded-miura.fold (flat to −170°, 17 states), tan(ρ_e/2) / tan(ρ_drive/2) stays what it is
// at the first step for every crease (the multipliers of the degree-4 vertices are constant and
// close around the faces), to 1e-9.
Test(regularize, regularized_miura_keeps_its_multipliers)
{
    ori_pattern *q = test_load_pattern(test_repo_path("tests/data/rounded-miura.fold"), 0);
    ori_regularize_def d = ori_default_regularize_def();
    d.rigid = true;
    ori_regularize_result r;
    ori_pattern *out = NULL;
    ori_error err;
    cr_assert_eq(ori_regularize(q, &d, &out, &r, &err), ORI_OK, "%s", err.message);
    cr_assert_not_null(out);
    ori_mechanism *mech = test_mechanism_of(out);
    int drive = 5; // a mountain "straight" crease between two interior vertices
    cr_assert_eq(ori_pattern_edge(out, drive).assignment, ORI_ASSIGN_MOUNTAIN);
    int faces[2];
    ori_pattern_edge_faces(out, drive, faces);
    ori_motion_def md = ori_default_motion_def();
    md.fixed_face = faces[0];
    md.driven_edge = drive;
    md.to_rad = deg(-170);
    md.step_rad = deg(10);
    ori_motion *mo = NULL;
    cr_assert_eq(ori_motion_solve(mech, &md, &mo, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_VALID);
    int nf = ori_motion_frame_count(mo), ne = ori_pattern_edge_count(out);
    cr_assert_eq(nf, 18);
    const double *first = ori_motion_frame_angles(mo, 1);
    double worst = 0.0;
    int moving = 0;
    for (int e = 0; e < ne; ++e) {
        if (first[e] == 0.0) continue;
        moving++;
        double mu = tan(first[e] / 2.0) / tan(first[drive] / 2.0);
        for (int k = 2; k < nf; ++k) {
            const double *a = ori_motion_frame_angles(mo, k);
            double m = tan(a[e] / 2.0) / tan(a[drive] / 2.0);
            worst = fmax(worst, fabs(m - mu) / fabs(mu));
        }
    }
    cr_assert_eq(moving, 17, "every crease folds");
    cr_assert_leq(worst, 1e-9, "multiplier drift %.3g", worst);
    ori_motion_destroy(mo);
    ori_mechanism_destroy(mech);
    ori_pattern_destroy(out);
    ori_pattern_destroy(q);
}

// --- equalities of the drawing kept (issue 21 §2) ---------------------------------------------

// A flat pattern from vertices and edges (y up), built with faces.
static ori_pattern *pattern_of(const double (*xy)[2], int nv, const int (*ev)[2], const char *asg, int ne)
{
    ori_pattern_def pd = ori_default_pattern_def();
    ori_pattern *p = ori_pattern_create(&pd);
    for (int v = 0; v < nv; ++v) ori_pattern_add_vertex(p, ori_v3_make(xy[v][0], xy[v][1], 0.0));
    for (int e = 0; e < ne; ++e) {
        ori_assignment a;
        cr_assert(ori_assignment_from_char(asg[e], &a));
        ori_pattern_add_edge(p, ev[e][0], ev[e][1], a, 0.0);
    }
    ori_build_def bd = ori_default_build_def();
    ori_error err;
    cr_assert_eq(ori_pattern_build(p, &bd, &err), ORI_OK, "%s", err.message);
    return p;
}

// Origami Simulator's open sink base, exact: a square of side 4, the inner square (1..3)², the
// diagonals and the vertical midline.
static ori_pattern *open_sink_base(void)
{
    static const double xy[13][2] = {{0, 4}, {4, 4}, {0, 0}, {4, 0}, {1, 1}, {3, 1}, {1, 3},
                                     {3, 3}, {2, 2}, {2, 4}, {2, 3}, {2, 1}, {2, 0}};
    static const int ev[24][2] = {{0, 9}, {2, 12}, {2, 0}, {3, 1},  {4, 11}, {6, 10}, {0, 6},  {1, 7},
                                  {3, 5}, {2, 4},  {6, 4}, {7, 5},  {4, 8},  {8, 7},  {6, 8},  {8, 5},
                                  {9, 1}, {10, 7}, {9, 10}, {11, 5}, {10, 8}, {8, 11}, {12, 3}, {11, 12}};
    return pattern_of(xy, 13, ev, "BBBBMMMMMMMMVVVVBMVMMMBV", 24);
}

// The waterbomb base: a square with both diagonals valley and the horizontal midline mountain
// (sectors 45, 90, 45, 45, 90, 45).
static ori_pattern *waterbomb_base(void)
{
    static const double xy[9][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, 0}, {1, 0}, {-1, 0}, {0, -1}, {0, 1}};
    static const int ev[14][2] = {{0, 7}, {7, 1}, {1, 5}, {5, 2}, {2, 8}, {8, 3}, {3, 6},
                                  {6, 0}, {4, 0}, {4, 1}, {4, 2}, {4, 3}, {4, 5}, {4, 6}};
    return pattern_of(xy, 9, ev, "BBBBBBBBVVVVMM", 14);
}

// The map fold's 2 × 2: a square with its midlines, one half of the vertical one a valley.
static ori_pattern *map_fold(void)
{
    static const double xy[9][2] = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}, {1, 1}};
    static const int ev[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6},
                                  {6, 7}, {7, 0}, {8, 1}, {8, 3}, {8, 5}, {8, 7}};
    return pattern_of(xy, 9, ev, "BBBBBBBBMMVM", 12);
}

// The flat states of a pattern whose lengths are as precise as the perturbations below (1e-6
// of the sheet: regularize makes the angles exact, not the lengths), as `layers --tolerance 1e-5`.
static char *layer_count(const ori_pattern *p)
{
    ori_layers_def ld = ori_default_layers_def();
    ld.snap_rel = 1e-5;
    ori_layers *L = NULL;
    ori_error err;
    cr_assert_eq(ori_layers_create(p, &ld, &L, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_layers_count(L, &err), ORI_OK);
    char *n = ori_layers_state_count(L);
    ori_layers_destroy(L);
    return n;
}

// Random perturbations of patterns with equal sectors (the open sink base, the waterbomb base,
// the map fold, a 3 × 3 Miura-ori with two pairs of equal sectors per vertex), by up to 1e-6 of
// the sheet: after regularize every pair of sectors equal in the exact pattern is equal to
// 1e-11 rad at that vertex (the big-little-big rule compares them within 1e-8), the result
// passes the full local check, and the layer orders count as many flat states as the exact
// pattern's. (Kawasaki alone made 90/90/90/90 into 90.0001/90/89.9999/90: 0 states.) Lengths
// stay as precise as the drawing: the layer orders are counted at that precision.
Test(regularize, equal_sectors_stay_equal_and_layers_count_as_the_exact_pattern, .timeout = 120)
{
    ori_pattern *exact[4] = {open_sink_base(), waterbomb_base(), map_fold(), test_miura(3, 3, 1.0, 1.0, deg(65), NULL)};
    static const char *const names[4] = {"open sink base", "waterbomb base", "map fold", "Miura-ori 3 x 3"};
    int kawasaki_only_broke = 0;
    for (int k = 0; k < 4; ++k) {
        ori_pattern *m = exact[k];
        char *want = layer_count(m);
        cr_assert_str_neq(want, "0", "%s", names[k]);
        for (unsigned seed = 1; seed <= 6; ++seed) {
            ori_pattern *q = perturbed(m, 1e-6, seed * 7919u + (unsigned)k);
            ori_regularize_def d = ori_default_regularize_def();
            ori_regularize_result r;
            ori_pattern *out = NULL;
            ori_error err;
            cr_assert_eq(ori_regularize(q, &d, &out, &r, &err), ORI_OK, "%s", err.message);
            cr_assert(r.converged && r.flat_foldable, "%s seed %u: %s", names[k], seed, r.check_detail);
            cr_assert_not_null(out);
            cr_assert_gt(r.ties, 0);
            cr_assert_leq(r.max_move_rel, 1e-5, "%s seed %u moved %.3g", names[k], seed, r.max_move_rel);
            for (int v = 0; v < ori_pattern_vertex_count(m); ++v) {
                if (!ori_pattern_vertex_is_interior(m, v)) continue;
                double a[64], b[64];
                int ea[64], eb[64], n = ori_flat_vertex_creases(m, v, ea, a, 64), s = 0;
                cr_assert_eq(ori_flat_vertex_creases(out, v, eb, b, 64), n);
                while (s < n && eb[s] != ea[0]) ++s; // (the lists may start at another crease)
                cr_assert_lt(s, n);
                for (int i = 0; i < n; ++i)
                    for (int j = i + 1; j < n; ++j)
                        if (fabs(a[i] - a[j]) <= 1e-12)
                            cr_assert_leq(fabs(b[(i + s) % n] - b[(j + s) % n]), 1e-11,
                                          "%s seed %u vertex %d: sectors %d, %d: %.17g, %.17g", names[k], seed, v, i, j,
                                          b[(i + s) % n], b[(j + s) % n]);
            }
            char *got = layer_count(out);
            cr_assert_str_eq(got, want, "%s seed %u: %s states, the exact pattern %s", names[k], seed, got, want);
            ori_buffer_free(got);
            // The perturbed drawing itself fails the exact check (so the test can fail).
            ori_flat_report *rep = ori_flat_check_pattern(q, NULL);
            kawasaki_only_broke += !ori_flat_report_flat_foldable(rep);
            ori_flat_report_destroy(rep);
            ori_pattern_destroy(out);
            ori_pattern_destroy(q);
        }
        ori_buffer_free(want);
        ori_pattern_destroy(m);
    }
    cr_assert_gt(kawasaki_only_broke, 0, "the perturbations break the exact check");
}

// regularize says flat-foldable only after the full check: a vertex that Kawasaki alone would
// accept but whose assignment cannot fold (the map fold's vertex with four mountains) is refused
// with the check's reason, and nothing is handed back.
Test(regularize, the_full_local_check_decides_flat_foldable)
{
    static const double xy[9][2] = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}, {1.00001, 1}};
    static const int ev[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6},
                                  {6, 7}, {7, 0}, {8, 1}, {8, 3}, {8, 5}, {8, 7}};
    ori_pattern *p = pattern_of(xy, 9, ev, "BBBBBBBBMMMM", 12);
    ori_regularize_def d = ori_default_regularize_def();
    ori_regularize_result r;
    ori_pattern *out = NULL;
    cr_assert_eq(ori_regularize(p, &d, &out, &r, NULL), ORI_OK);
    cr_assert_null(out);
    cr_assert_not(r.converged);
    cr_assert_not(r.flat_foldable);
    cr_assert_leq(r.kawasaki_after_rad, 1e-12, "Kawasaki itself holds");
    cr_assert_eq(r.check_vertex, 8);
    cr_assert_eq(r.check_rule, ORI_FLAT_RULE_MAEKAWA, "%d: %s", r.check_rule, r.check_detail);
    cr_assert_eq(r.check_failed, 1);
    ori_pattern_destroy(p);
}

// Origami Simulator's open sink base (a 90/90/90/90 vertex) and the BYU flasher (43 of 90
// vertices broke): regularized, every vertex passes the exact check; the sink base has its one
// flat state.
Test(regularize, shared_drawings_keep_their_equal_sectors)
{
    static const char *const names[2] = {"origamisimulator/Bases_openSinkBase.svg",
                                         "origamisimulator/needsCollisions_byu_solar_driven.svg"};
    for (int k = 0; k < 2; ++k) {
        const char *path = test_shared_path(names[k]);
        if (!path) cr_skip("../shared is absent");
        ori_pattern *p = NULL;
        ori_error err;
        cr_assert_eq(ori_import_file(path, ORI_FORMAT_UNKNOWN, NULL, &p, NULL, &err), ORI_OK, "%s", err.message);
        ori_regularize_def d = ori_default_regularize_def();
        ori_regularize_result r;
        ori_pattern *out = NULL;
        cr_assert_eq(ori_regularize(p, &d, &out, &r, &err), ORI_OK);
        cr_assert(r.converged && r.flat_foldable, "%s: %s", names[k], r.check_detail);
        cr_assert_lt(r.max_move_rel, 1e-5);
        ori_flat_report *rep = ori_flat_check_pattern(out, NULL);
        cr_assert(ori_flat_report_flat_foldable(rep), "%s: %d vertices fail", names[k], ori_flat_report_failed_count(rep));
        ori_flat_report_destroy(rep);
        if (k == 0) {
            char *n = layer_count(out);
            cr_assert_str_eq(n, "1");
            ori_buffer_free(n);
        }
        ori_pattern_destroy(out);
        ori_pattern_destroy(p);
    }
}

// --- rigid only (issue 21 §2) -----------------------------------------------------------------

// Rigid designs that do not fold flat: --rigid refuses them (a vertex of odd degree cannot
// satisfy Kawasaki), rigid_only makes them rigidly foldable without Kawasaki. Random single
// vertices of degree 5 (sectors 40°–100°, three mountains and two valleys) on a pentagon: the
// rates close to first and second order to 1e-12, no flat check is asked, and vertices barely
// move (the rates adapt).
Test(regularize, rigid_only_accepts_rigid_designs_that_do_not_fold_flat)
{
    unsigned st = 5;
    for (int trial = 0; trial < 8; ++trial) {
        double a[5], sum = 0.0, xy[6][2] = {{0, 0}};
        for (int k = 0; k < 5; ++k) a[k] = 40.0 + 30.0 * (noise(&st) + 1.0), sum += a[k];
        double t = 360.0 * noise(&st);
        for (int k = 0; k < 5; ++k) {
            xy[k + 1][0] = cos(deg(t)), xy[k + 1][1] = sin(deg(t));
            t += a[k] * 360.0 / sum;
        }
        static const int ev[10][2] = {{1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 1}, {0, 1}, {0, 2}, {0, 3}, {0, 4}, {0, 5}};
        ori_pattern *p = pattern_of(xy, 6, ev, "BBBBBMVMMV", 10);
        ori_regularize_def d = ori_default_regularize_def();
        ori_regularize_result r;
        ori_pattern *out = NULL;
        d.rigid = true;
        cr_assert_eq(ori_regularize(p, &d, &out, &r, NULL), ORI_OK);
        cr_assert_null(out);
        cr_assert_eq(r.odd_vertex, 0, "trial %d", trial);
        d.rigid = false;
        d.rigid_only = true;
        cr_assert_eq(ori_regularize(p, &d, &out, &r, NULL), ORI_OK);
        cr_assert(r.converged, "trial %d: rigid defect %g", trial, r.rigid_after);
        cr_assert_not_null(out);
        cr_assert_eq(r.odd_vertex, ORI_NULL_INDEX);
        cr_assert_leq(r.rigid_after, 1e-12);
        cr_assert_eq(r.mode_vertices, 0);
        cr_assert_leq(r.max_move_rel, 1e-9, "trial %d moved %g", trial, r.max_move_rel);
        ori_pattern_destroy(out);
        ori_pattern_destroy(p);
    }
    // A pattern without interior vertices (cuts between its creases: a kirigami strip) has
    // nothing to regularize, rigid or not: converged, no contradiction.
    static const double kxy[8][2] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {2, 1}, {1, 1}, {0, 1}};
    static const int kev[9][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6}, {6, 7}, {7, 0}, {1, 6}};
    ori_pattern *k = pattern_of(kxy, 8, kev, "BBBBBCBBM", 9);
    for (int mode = 0; mode < 3; ++mode) {
        ori_regularize_def d = ori_default_regularize_def();
        d.rigid = mode == 1, d.rigid_only = mode == 2;
        ori_regularize_result r;
        ori_pattern *out = NULL;
        cr_assert_eq(ori_regularize(k, &d, &out, &r, NULL), ORI_OK);
        cr_assert(r.converged && !r.refused, "mode %d", mode);
        cr_assert_not_null(out);
        cr_assert_eq(r.moved_vertices, 0);
        ori_pattern_destroy(out);
    }
    ori_pattern_destroy(k);
}

// Origami Simulator's Resch tessellation (degree-6 vertices of three mountains and three
// valleys: rigid, never flat) and anti-symmetric 6-point hypar: --rigid-only regularizes them;
// --rigid refuses the Resch pattern now that the full check runs (it was called flat-foldable).
Test(regularize, shared_rigid_designs_with_rigid_only)
{
    static const char *const names[2] = {"origamisimulator/Tessellations_reschTriTessellation.svg",
                                         "origamisimulator/Origami_6ptHypar-anti.svg"};
    for (int k = 0; k < 2; ++k) {
        const char *path = test_shared_path(names[k]);
        if (!path) cr_skip("../shared is absent");
        char args[1024], *out = NULL;
        snprintf(args, sizeof args, "regularize '%s' --rigid-only", path);
        cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
        cr_assert(strstr(out, "flat-foldability not required"), "%s", out);
        free(out);
        if (k == 0) {
            snprintf(args, sizeof args, "regularize '%s' --rigid", path);
            cr_assert_eq(test_run_cli(args, &out), 1, "%s", out);
            cr_assert(strstr(out, "is not flat-foldable (maekawa)"), "%s", out);
            free(out);
        }
    }
    char *out = NULL;
    cr_assert_eq(test_run_cli("regularize tests/data/rounded-miura.fold --rigid --rigid-only", &out), 2, "%s", out);
    free(out);
}
