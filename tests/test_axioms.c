// Huzita–Hatori axioms: hand-worked reference cases, Beloch's cube root of 2, the three
// solutions of axiom 6, degenerate inputs, and round-trip properties on random inputs.
#include <float.h>
#include <orikin/axioms.h>

#include "support.h"

TestSuite(axioms, .init = test_leak_setup, .fini = test_leak_check);

static ori_line L(double x, double y, double dx, double dy)
{
    ori_line l = {{x, y}, {dx, dy}};
    return l;
}

static void assert_line(ori_line got, double px, double py, double dx, double dy, double tol)
{
    cr_assert_float_eq(got.point.x, px, tol, "point.x %.17g vs %.17g", got.point.x, px);
    cr_assert_float_eq(got.point.y, py, tol, "point.y %.17g vs %.17g", got.point.y, py);
    cr_assert_float_eq(got.dir.x, dx, tol, "dir.x %.17g vs %.17g", got.dir.x, dx);
    cr_assert_float_eq(got.dir.y, dy, tol, "dir.y %.17g vs %.17g", got.dir.y, dy);
}

// Signed distance of x from line l (any direction length).
static double dist_line(ori_line l, ori_v2 x)
{
    return ori_v2_cross(ori_v2_normalize(l.dir), ori_v2_sub(x, l.point));
}

static bool finite_line(ori_line l)
{
    return isfinite(l.point.x) && isfinite(l.point.y) && isfinite(l.dir.x) && isfinite(l.dir.y);
}

static void assert_canonical(ori_line l)
{
    cr_assert(finite_line(l));
    cr_assert_float_eq(ori_v2_norm(l.dir), 1.0, 4 * DBL_EPSILON);
    cr_assert(l.dir.x > 0.0 || (l.dir.x == 0.0 && l.dir.y > 0.0), "canonical direction");
    // point nearest the origin: perpendicular to dir
    cr_assert_float_eq(ori_v2_dot(l.point, l.dir), 0.0, 1e-12 * fmax(1.0, ori_v2_norm(l.point)));
}

Test(axioms, line_make_is_canonical)
{
    assert_line(ori_line_make(ori_v2_make(5, 3), ori_v2_make(-2, 0)), 0, 3, 1, 0, 0.0);
    assert_line(ori_line_make(ori_v2_make(4, -7), ori_v2_make(0, -3)), 4, 0, 0, 1, 0.0);
    ori_line z = ori_line_make(ori_v2_make(1, 1), ori_v2_make(0, 0));
    assert_line(z, 0, 0, 0, 0, 0.0);
    ori_line d = ori_line_make(ori_v2_make(0, 2), ori_v2_make(-1, 1));
    assert_line(d, 1, 1, sqrt(0.5), -sqrt(0.5), 1e-15);
    ori_v2 r = ori_line_reflect(L(0, 1, 1, 0), ori_v2_make(3, 5));
    cr_assert_float_eq(r.x, 3.0, 1e-15);
    cr_assert_float_eq(r.y, -3.0, 1e-15);
    cr_assert_eq(ori_axiom_max_solutions(6), 3);
    cr_assert_eq(ori_axiom_max_solutions(8), 0);
}

Test(axioms, axiom1_through_two_points)
{
    ori_line_set s = ori_axiom_1(ori_v2_make(0, 0), ori_v2_make(2, 2));
    cr_assert_eq(s.count, 1);
    assert_line(s.lines[0], 0, 0, sqrt(0.5), sqrt(0.5), 1e-15);
    s = ori_axiom_1(ori_v2_make(1, 5), ori_v2_make(1, 0));
    cr_assert_eq(s.count, 1);
    assert_line(s.lines[0], 1, 0, 0, 1, 0.0);
    cr_assert_eq(ori_axiom_1(ori_v2_make(1, 1), ori_v2_make(1, 1)).count, 0);
}

Test(axioms, axiom2_perpendicular_bisector)
{
    ori_line_set s = ori_axiom_2(ori_v2_make(0, 0), ori_v2_make(2, 0));
    cr_assert_eq(s.count, 1);
    assert_line(s.lines[0], 1, 0, 0, 1, 0.0);
    s = ori_axiom_2(ori_v2_make(0, 0), ori_v2_make(2, 2)); // x + y = 2
    assert_line(s.lines[0], 1, 1, sqrt(0.5), -sqrt(0.5), 1e-15);
    cr_assert_eq(ori_axiom_2(ori_v2_make(3, 4), ori_v2_make(3, 4 + 1e-12)).count, 0);
}

Test(axioms, axiom3_bisectors_midline_and_coincident)
{
    ori_line_set s = ori_axiom_3(L(0, 0, 1, 0), L(5, 5, 0, 1)); // x-axis and x = 5
    cr_assert_eq(s.count, 2);
    // first the bisector mapping (1,0) onto (0,1): direction (1,1), through (5,0)
    assert_line(s.lines[0], 2.5, -2.5, sqrt(0.5), sqrt(0.5), 1e-14);
    assert_line(s.lines[1], 2.5, 2.5, sqrt(0.5), -sqrt(0.5), 1e-14);
    s = ori_axiom_3(L(0, 0, 1, 0), L(3, 2, -4, 0)); // y = 0 and y = 2: the midline y = 1
    cr_assert_eq(s.count, 1);
    assert_line(s.lines[0], 0, 1, 1, 0, 0.0);
    cr_assert_eq(ori_axiom_3(L(0, 1, 1, 0), L(7, 1, 2, 0)).count, 0, "coincident lines: infinitely many");
    cr_assert_eq(ori_axiom_3(L(0, 1, 0, 0), L(7, 1, 2, 0)).count, 0, "zero direction");
}

// Nearly antiparallel directions (found by fuzz_axioms): u1 + u2 is almost zero, and the
// bisector built from it was off by ~1e-9 rad, so that near the inputs (scale 8, the lines
// meeting 7e7 away) l1 reflected 0.11 away from l2.
Test(axioms, axiom3_nearly_antiparallel_lines_stay_accurate)
{
    ori_line l1 = L(-8, -8, 0, -7.25), l2 = L(0, 0, -1e-7, 0.875);
    ori_line_set s = ori_axiom_3(l1, l2);
    cr_assert_eq(s.count, 2);
    for (int k = 0; k < s.count; ++k) {
        // canonical up to the rounding of the crossing 7e7 away (eps × 7e7 ≈ 1.5e-8)
        cr_assert(finite_line(s.lines[k]));
        cr_assert_float_eq(ori_v2_norm(s.lines[k].dir), 1.0, 4 * DBL_EPSILON);
        cr_assert_float_eq(ori_v2_dot(s.lines[k].point, s.lines[k].dir), 0.0, 3e-8);
        ori_v2 a = ori_line_reflect(s.lines[k], l1.point);
        ori_v2 b = ori_line_reflect(s.lines[k], ori_v2_make(-8, 0));
        cr_assert_float_eq(dist_line(l2, a), 0.0, 1e-6, "line %d: %g", k, dist_line(l2, a));
        cr_assert_float_eq(dist_line(l2, b), 0.0, 1e-6, "line %d: %g", k, dist_line(l2, b));
    }
}

Test(axioms, axiom4_perpendicular_through_point)
{
    ori_line_set s = ori_axiom_4(ori_v2_make(1, 2), L(0, 0, 1, 0));
    cr_assert_eq(s.count, 1);
    assert_line(s.lines[0], 1, 0, 0, 1, 0.0);
    s = ori_axiom_4(ori_v2_make(0, 0), L(0, 2, 1, -1)); // through the origin along (1,1)
    assert_line(s.lines[0], 0, 0, sqrt(0.5), sqrt(0.5), 1e-15);
}

Test(axioms, axiom5_circle_meets_line)
{
    // Circle of radius 2 about p2 = 0 meets y = 1 at (±√3, 1): two folds through the origin.
    ori_line_set s = ori_axiom_5(ori_v2_make(0, 2), ori_v2_make(0, 0), L(0, 1, 1, 0));
    cr_assert_eq(s.count, 2);
    assert_line(s.lines[0], 0, 0, 0.5, -sqrt(3.0) / 2, 1e-15); // p1 lands at (−√3, 1) first
    assert_line(s.lines[1], 0, 0, 0.5, sqrt(3.0) / 2, 1e-15);
    // Tangent: radius 1 = distance: one fold (p1 already lies on l1, the fold through p1, p2).
    s = ori_axiom_5(ori_v2_make(0, 1), ori_v2_make(0, 0), L(0, 1, 1, 0));
    cr_assert_eq(s.count, 1);
    assert_line(s.lines[0], 0, 0, 0, 1, 0.0);
    // p1 on l1: the fold through p1 and p2, and x = 1 (p1 onto (2, 1)).
    s = ori_axiom_5(ori_v2_make(0, 1), ori_v2_make(1, 0), L(0, 1, 1, 0));
    cr_assert_eq(s.count, 2);
    assert_line(s.lines[0], 0.5, 0.5, sqrt(0.5), -sqrt(0.5), 1e-15);
    assert_line(s.lines[1], 1, 0, 0, 1, 1e-15);
    cr_assert_eq(ori_axiom_5(ori_v2_make(0, 0.5), ori_v2_make(0, 0), L(0, 1, 1, 0)).count, 0, "circle misses");
    cr_assert_eq(ori_axiom_5(ori_v2_make(2, 2), ori_v2_make(2, 2), L(0, 1, 1, 0)).count, 0, "p1 = p2");
}

Test(axioms, axiom6_beloch_cube_root_of_two)
{
    // p1 = (0, −1) onto y = 1 and p2 = (2, 0) onto x = −2: the fold is a common tangent of the
    // parabolas x² = −4y and y² = 8x, y = m x + m² with m³ = 2.
    ori_line_set s = ori_axiom_6(ori_v2_make(0, -1), L(0, 1, 1, 0), ori_v2_make(2, 0), L(-2, 0, 0, 1));
    cr_assert_eq(s.count, 1);
    double m = s.lines[0].dir.y / s.lines[0].dir.x;
    cr_assert_float_eq(m, cbrt(2.0), 1e-12);
    cr_assert_float_eq(m * m * m, 2.0, 1e-12);
    // its intercept is m²
    double b = s.lines[0].point.y - m * s.lines[0].point.x;
    cr_assert_float_eq(b, m * m, 1e-12);
}

Test(axioms, axiom6_three_solutions)
{
    // p1 = (0, 1) onto y = 0 and p2 = (0, −1) onto y = x. Folds y = m x + (1 − m²)/2 (tangents
    // of the parabola with focus p1), with m³ + 2m² − 3m − 2 = 0 (worked by hand).
    ori_v2 p1 = ori_v2_make(0, 1), p2 = ori_v2_make(0, -1);
    ori_line l1 = L(0, 0, 1, 0), l2 = L(0, 0, 1, 1);
    ori_line_set s = ori_axiom_6(p1, l1, p2, l2);
    cr_assert_eq(s.count, 3);
    double prev = -INFINITY;
    for (int i = 0; i < 3; ++i) {
        ori_line f = s.lines[i];
        double m = f.dir.y / f.dir.x, b = f.point.y - m * f.point.x;
        cr_assert_float_eq(m * m * m + 2 * m * m - 3 * m - 2, 0.0, 1e-12, "slope %.17g", m);
        cr_assert_float_eq(b, (1 - m * m) / 2, 1e-12);
        // ordered by where p1 lands on l1 (along +x)
        double land = ori_line_reflect(f, p1).x;
        cr_assert_gt(land, prev);
        prev = land;
    }
}

Test(axioms, axiom6_double_root_counts_once)
{
    // p1 = (0,1) onto the x-axis and p2 = (1,0) onto the y-axis: slopes (m − 1)²(m + 1) = 0.
    ori_line_set s = ori_axiom_6(ori_v2_make(0, 1), L(0, 0, 1, 0), ori_v2_make(1, 0), L(0, 0, 0, 1));
    cr_assert_eq(s.count, 2);
    assert_line(s.lines[0], 0, 0, sqrt(0.5), -sqrt(0.5), 1e-12); // p1 lands at (−1, 0)
    assert_line(s.lines[1], 0, 0, sqrt(0.5), sqrt(0.5), 1e-12);  // p1 lands at (1, 0)
}

Test(axioms, axiom6_degenerate)
{
    // Same point onto the same line twice: infinitely many folds.
    cr_assert_eq(ori_axiom_6(ori_v2_make(1, 2), L(0, 0, 1, 0), ori_v2_make(1, 2), L(5, 0, -1, 0)).count, 0);
    cr_assert_eq(ori_axiom_6(ori_v2_make(1, 2), L(0, 0, 0, 0), ori_v2_make(3, 2), L(5, 0, -1, 0)).count, 0);
    ori_line_set s = ori_axiom_6(ori_v2_make(NAN, 2), L(0, 0, 1, 0), ori_v2_make(3, 2), L(5, 0, 0, 1));
    cr_assert_eq(s.count, 0);
    // Parallel lines, both points the same side: a quadratic (here 2 real roots, or none).
    s = ori_axiom_6(ori_v2_make(0, 1), L(0, 0, 1, 0), ori_v2_make(3, 1), L(0, 0, 1, 0));
    for (int i = 0; i < s.count; ++i) cr_assert(finite_line(s.lines[i]));
}

Test(axioms, axiom7_perpendicular_to_l2)
{
    ori_line_set s = ori_axiom_7(ori_v2_make(1, 2), L(0, 0, 1, 0), L(0, 0, 1, 1));
    cr_assert_eq(s.count, 1);
    assert_line(s.lines[0], 0.5, 0.5, sqrt(0.5), -sqrt(0.5), 1e-15); // x + y = 1
    cr_assert_eq(ori_axiom_7(ori_v2_make(1, 2), L(0, 0, 1, 0), L(0, 4, -3, 0)).count, 0, "l1 ∥ l2");
}

Test(axioms, solve_dispatches)
{
    ori_axiom_input in;
    memset(&in, 0, sizeof in);
    in.axiom = 2;
    in.p1 = ori_v2_make(0, 0);
    in.p2 = ori_v2_make(2, 0);
    cr_assert_eq(ori_axiom_solve(&in).count, 1);
    in.axiom = 0;
    cr_assert_eq(ori_axiom_solve(&in).count, 0);
    in.axiom = 9;
    cr_assert_eq(ori_axiom_solve(&in).count, 0);
}

// --- random round trips ------------------------------------------------------------------

static double rnd(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return (double)(*s >> 8) / 16777216.0;
}

static ori_v2 rpoint(unsigned *s) { return ori_v2_make(20 * rnd(s) - 10, 20 * rnd(s) - 10); }

static ori_line rline(unsigned *s)
{
    double a = 2 * ORI_PI * rnd(s), len = 0.1 + 3 * rnd(s);
    ori_line l = {rpoint(s), {len * cos(a), len * sin(a)}};
    return l;
}

#define RT_TOL 1e-9 // relative to the input scale (~10)

Test(axioms, random_round_trips)
{
    unsigned s = 2024;
    int counts[8][4] = {{0}};
    for (int it = 0; it < 3000; ++it) {
        ori_v2 p1 = rpoint(&s), p2 = rpoint(&s);
        ori_line l1 = rline(&s), l2 = rline(&s);
        double tol = RT_TOL * 10;
        ori_line_set r;

        r = ori_axiom_1(p1, p2);
        cr_assert_eq(r.count, 1);
        assert_canonical(r.lines[0]);
        cr_assert_float_eq(dist_line(r.lines[0], p1), 0.0, tol);
        cr_assert_float_eq(dist_line(r.lines[0], p2), 0.0, tol);

        r = ori_axiom_2(p1, p2);
        cr_assert_eq(r.count, 1);
        ori_v2 q = ori_line_reflect(r.lines[0], p1);
        cr_assert_float_eq(q.x, p2.x, tol);
        cr_assert_float_eq(q.y, p2.y, tol);

        r = ori_axiom_3(l1, l2);
        cr_assert_eq(r.count, 2);
        for (int k = 0; k < r.count; ++k) {
            assert_canonical(r.lines[k]);
            ori_v2 a = ori_line_reflect(r.lines[k], l1.point);
            ori_v2 b = ori_line_reflect(r.lines[k], ori_v2_add(l1.point, l1.dir));
            cr_assert_float_eq(dist_line(l2, a), 0.0, tol * 10);
            cr_assert_float_eq(dist_line(l2, b), 0.0, tol * 10);
        }

        r = ori_axiom_4(p1, l1);
        cr_assert_eq(r.count, 1);
        cr_assert_float_eq(dist_line(r.lines[0], p1), 0.0, tol);
        cr_assert_float_eq(ori_v2_dot(r.lines[0].dir, ori_v2_normalize(l1.dir)), 0.0, 1e-15);

        r = ori_axiom_5(p1, p2, l1);
        double rad = ori_v2_norm(ori_v2_sub(p1, p2)), h = fabs(dist_line(l1, p2));
        if (rad > h * (1 + 1e-6)) cr_assert_eq(r.count, 2);
        if (rad < h * (1 - 1e-6)) cr_assert_eq(r.count, 0);
        counts[5][r.count]++;
        for (int k = 0; k < r.count; ++k) {
            assert_canonical(r.lines[k]);
            cr_assert_float_eq(dist_line(r.lines[k], p2), 0.0, tol);
            cr_assert_float_eq(dist_line(l1, ori_line_reflect(r.lines[k], p1)), 0.0, tol);
        }

        r = ori_axiom_6(p1, l1, p2, l2);
        cr_assert_geq(r.count, 1, "a cubic has a real root");
        counts[6][r.count]++;
        for (int k = 0; k < r.count; ++k) {
            assert_canonical(r.lines[k]);
            cr_assert_float_eq(dist_line(l1, ori_line_reflect(r.lines[k], p1)), 0.0, 1e-7,
                               "it %d solution %d", it, k);
            cr_assert_float_eq(dist_line(l2, ori_line_reflect(r.lines[k], p2)), 0.0, 1e-7,
                               "it %d solution %d", it, k);
            for (int j = 0; j < k; ++j)
                cr_assert(fabs(ori_v2_cross(r.lines[j].dir, r.lines[k].dir)) > 1e-9 ||
                              fabs(dist_line(r.lines[j], r.lines[k].point)) > 1e-9,
                          "duplicate solution");
        }

        r = ori_axiom_7(p1, l1, l2);
        cr_assert_eq(r.count, 1);
        cr_assert_float_eq(dist_line(l1, ori_line_reflect(r.lines[0], p1)), 0.0, tol * 10);
        cr_assert_float_eq(ori_v2_dot(r.lines[0].dir, ori_v2_normalize(l2.dir)), 0.0, 1e-15);
    }
    // Both outcomes of axiom 5 and more than one solution of axiom 6 occur in the sample.
    cr_assert_gt(counts[5][0], 100);
    cr_assert_gt(counts[5][2], 100);
    cr_assert_gt(counts[6][3], 100);
    cr_assert_gt(counts[6][1], 100);
}

// Axiom 6 solution count against an independent count: sign changes of the residual of
// "p2's image lies on l2" along the family of folds placing p1 onto l1 (sampled finely).
static double residual(ori_v2 p1, ori_line l1, ori_v2 p2, ori_line l2, double t)
{
    ori_v2 u1 = ori_v2_normalize(l1.dir);
    ori_v2 img = ori_v2_add(l1.point, ori_v2_scale(u1, t));
    ori_v2 d = ori_v2_sub(img, p1);
    ori_line f = {ori_v2_scale(ori_v2_add(p1, img), 0.5), ori_v2_perp(d)};
    return dist_line(l2, ori_line_reflect(f, p2)) * ori_v2_dot(d, d); // cleared of the 1/|d|² pole
}

Test(axioms, axiom6_count_matches_sampling)
{
    unsigned s = 77;
    int checked = 0;
    for (int it = 0; it < 120; ++it) {
        ori_v2 p1 = rpoint(&s), p2 = rpoint(&s);
        ori_line l1 = rline(&s), l2 = rline(&s);
        int changes = 0;
        double prev = residual(p1, l1, p2, l2, -1e3);
        bool close = false;
        for (int k = 1; k <= 200000; ++k) { // step 0.01
            double t = -1e3 + 2e3 * k / 200000.0;
            double r = residual(p1, l1, p2, l2, t);
            if ((r > 0) != (prev > 0)) changes++;
            if (fabs(r) < 1e-6) close = true; // near-tangency: sampling cannot decide
            prev = r;
        }
        if (close) continue;
        ori_line_set sol = ori_axiom_6(p1, l1, p2, l2);
        // roots beyond ±1e3 are outside the sample
        int inside = 0;
        for (int k = 0; k < sol.count; ++k) {
            ori_v2 img = ori_line_reflect(sol.lines[k], p1);
            double t = ori_v2_dot(ori_v2_sub(img, l1.point), ori_v2_normalize(l1.dir));
            inside += fabs(t) < 1e3;
        }
        cr_assert_eq(inside, changes, "iteration %d", it);
        checked++;
    }
    cr_assert_gt(checked, 80);
}

Test(axioms, never_nan_on_degenerate_or_huge_input)
{
    ori_v2 pts[] = {{0, 0}, {1e-300, 0}, {1e300, 1e300}, {NAN, 0}, {INFINITY, 1}, {1, 1}};
    ori_line lines[] = {L(0, 0, 0, 0), L(0, 0, 1, 0), L(1e300, 0, 1, 1e-300), L(0, 0, NAN, 1), L(1, 1, 1, 0)};
    for (size_t a = 0; a < sizeof pts / sizeof *pts; ++a)
        for (size_t b = 0; b < sizeof pts / sizeof *pts; ++b)
            for (size_t c = 0; c < sizeof lines / sizeof *lines; ++c)
                for (size_t d = 0; d < sizeof lines / sizeof *lines; ++d)
                    for (int ax = 1; ax <= 7; ++ax) {
                        ori_axiom_input in = {ax, pts[a], pts[b], lines[c], lines[d]};
                        ori_line_set s = ori_axiom_solve(&in);
                        cr_assert(s.count >= 0 && s.count <= ori_axiom_max_solutions(ax));
                        for (int k = 0; k < s.count; ++k) cr_assert(finite_line(s.lines[k]), "axiom %d", ax);
                    }
}

// A subnormal direction (fuzz_axioms): its norm lost the digits, so the "unit" vector of
// ori_line_make was off unit by up to 20 %; scaled up first it is a unit vector, pointing the
// same way and canonical.
Test(axioms, a_line_from_a_subnormal_direction_is_unit)
{
    const ori_v2 dirs[] = {{3e-324, 5e-324}, {-1e-310, 4e-311}, {0.0, -7e-320}, {2.5e-300, 1e-300}};
    for (size_t i = 0; i < sizeof dirs / sizeof dirs[0]; ++i) {
        ori_line l = ori_line_make(ori_v2_make(1.0, 2.0), dirs[i]);
        cr_assert_float_eq(hypot(l.dir.x, l.dir.y), 1.0, 1e-15, "direction %zu: |dir| = %.17g", i, hypot(l.dir.x, l.dir.y));
        cr_assert(l.dir.x > 0.0 || (l.dir.x == 0.0 && l.dir.y > 0.0), "direction %zu not canonical", i);
        // parallel to the input (the cross product of the unit vectors vanishes)
        double nx = dirs[i].x / fmax(fabs(dirs[i].x), fabs(dirs[i].y)), ny = dirs[i].y / fmax(fabs(dirs[i].x), fabs(dirs[i].y));
        cr_assert_leq(fabs(l.dir.x * ny - l.dir.y * nx), 1e-15 * hypot(nx, ny), "direction %zu turned", i);
    }
}
