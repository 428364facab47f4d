// The Huzita–Hatori axioms. Each construction returns every solution; degenerate inputs give
// none. Axiom 6 reduces to a cubic in the position of p1's image along l1, solved in closed
// form (trigonometric or Cardano branch of the depressed cubic) and polished by Newton.
#include <orikin/axioms.h>

#include <float.h>

#include "../core/core_internal.h"

static ori_v2 v2(double x, double y) { return ori_v2_make(x, y); }

static bool finite2(ori_v2 a) { return isfinite(a.x) && isfinite(a.y); }

ori_line ori_line_make(ori_v2 point, ori_v2 dir)
{
    ori_line l = {{0.0, 0.0}, {0.0, 0.0}};
    // A subnormal direction loses its digits in the norm: scaled up first (exactly, by a power
    // of two), its unit vector is a unit vector (found by fuzz_axioms).
    double big = fmax(fabs(dir.x), fabs(dir.y));
    if (big > 0.0 && big < 1e-290) dir = v2(ldexp(dir.x, 600), ldexp(dir.y, 600));
    ori_v2 d = ori_v2_normalize(dir);
    if ((d.x == 0.0 && d.y == 0.0) || !finite2(point)) return l;
    // Canonical sign: pointing to x > 0, or straight up when vertical.
    if (d.x < 0.0 || (d.x == 0.0 && d.y < 0.0)) d = ori_v2_scale(d, -1.0);
    ori_v2 p = ori_v2_sub(point, ori_v2_scale(d, ori_v2_dot(point, d)));
    l.dir = v2(d.x + 0.0, d.y + 0.0); // + 0.0 turns −0 into 0
    l.point = v2(p.x + 0.0, p.y + 0.0);
    return l;
}

ori_v2 ori_line_reflect(ori_line l, ori_v2 x)
{
    ori_v2 d = ori_v2_normalize(l.dir);
    ori_v2 r = ori_v2_sub(x, l.point);
    ori_v2 along = ori_v2_scale(d, ori_v2_dot(r, d));
    return ori_v2_add(l.point, ori_v2_sub(ori_v2_scale(along, 2.0), r));
}

int ori_axiom_max_solutions(int axiom)
{
    static const int n[8] = {0, 1, 1, 2, 1, 2, 3, 1};
    return axiom >= 1 && axiom <= 7 ? n[axiom] : 0;
}

static ori_line_set empty_set(void)
{
    ori_line_set s;
    memset(&s, 0, sizeof s);
    return s;
}

// Input scale: the largest coordinate magnitude among the points (1 when all are 0).
static double scale_of(const ori_v2 *pts, int n)
{
    double s = 0.0;
    for (int i = 0; i < n; ++i) s = fmax(s, fmax(fabs(pts[i].x), fabs(pts[i].y)));
    return s > 0.0 ? s : 1.0;
}

// Add a canonical line unless it is not finite or repeats one already in the set.
static void add_line(ori_line_set *s, ori_v2 point, ori_v2 dir, double scale)
{
    ori_line l = ori_line_make(point, dir);
    if (!finite2(l.point) || !finite2(l.dir) || (l.dir.x == 0.0 && l.dir.y == 0.0)) return;
    for (int i = 0; i < s->count; ++i) {
        const ori_line *o = &s->lines[i];
        if (fabs(ori_v2_cross(o->dir, l.dir)) <= ORI_TOL_LENGTH_REL &&
            fabs(ori_v2_cross(o->dir, ori_v2_sub(l.point, o->point))) <= ORI_TOL_LENGTH_REL * scale)
            return;
    }
    if (s->count < 3) s->lines[s->count++] = l;
}

static bool unit_dir(ori_line l, ori_v2 *u)
{
    if (!finite2(l.point) || !finite2(l.dir)) return false;
    *u = ori_v2_normalize(l.dir);
    return !(u->x == 0.0 && u->y == 0.0);
}

// Two finite points farther apart than the length tolerance of their scale: their difference
// p2 − p1 and the scale; false otherwise (axioms 1 and 2 then have no line).
static bool two_points(ori_v2 p1, ori_v2 p2, ori_v2 *d, double *L)
{
    if (!finite2(p1) || !finite2(p2)) return false;
    ori_v2 pts[2] = {p1, p2};
    *L = scale_of(pts, 2);
    *d = ori_v2_sub(p2, p1);
    return ori_v2_norm(*d) > ORI_TOL_LENGTH_REL * *L;
}

ori_line_set ori_axiom_1(ori_v2 p1, ori_v2 p2)
{
    ori_line_set s = empty_set();
    ori_v2 d;
    double L;
    if (two_points(p1, p2, &d, &L)) add_line(&s, p1, d, L);
    return s;
}

ori_line_set ori_axiom_2(ori_v2 p1, ori_v2 p2)
{
    ori_line_set s = empty_set();
    ori_v2 d;
    double L;
    if (two_points(p1, p2, &d, &L)) add_line(&s, ori_v2_scale(ori_v2_add(p1, p2), 0.5), ori_v2_perp(d), L);
    return s;
}

ori_line_set ori_axiom_3(ori_line l1, ori_line l2)
{
    ori_line_set s = empty_set();
    ori_v2 u1, u2;
    if (!unit_dir(l1, &u1) || !unit_dir(l2, &u2)) return s;
    ori_v2 pts[2] = {l1.point, l2.point};
    double L = scale_of(pts, 2);
    double c = ori_v2_cross(u1, u2);
    ori_v2 q = ori_v2_sub(l2.point, l1.point);
    if (fabs(c) <= ORI_TOL_CONSTRUCTION_REL) {
        // Parallel: the midline, unless the lines coincide (every perpendicular works).
        ori_v2 n1 = ori_v2_perp(u1);
        double h = ori_v2_dot(n1, q);
        if (!(fabs(h) > ORI_TOL_LENGTH_REL * L)) return s;
        add_line(&s, ori_v2_add(l1.point, ori_v2_scale(n1, 0.5 * h)), u1, L);
        return s;
    }
    ori_v2 x = ori_v2_add(l1.point, ori_v2_scale(u1, ori_v2_cross(q, u2) / c));
    // The bisectors are perpendicular: take the longer of u1 ± u2 and the other as its
    // perpendicular, since the shorter one loses its direction to cancellation when the lines
    // are nearly (anti)parallel (an angle error of ~1e-9 rad, found by fuzz_axioms).
    ori_v2 a = ori_v2_add(u1, u2), b = ori_v2_sub(u1, u2);
    if (ori_v2_dot(a, a) >= ori_v2_dot(b, b)) b = ori_v2_perp(a);
    else a = ori_v2_perp(b);
    add_line(&s, x, a, L);
    add_line(&s, x, b, L);
    return s;
}

ori_line_set ori_axiom_4(ori_v2 p1, ori_line l1)
{
    ori_line_set s = empty_set();
    ori_v2 u1;
    if (!finite2(p1) || !unit_dir(l1, &u1)) return s;
    ori_v2 pts[2] = {p1, l1.point};
    add_line(&s, p1, ori_v2_perp(u1), scale_of(pts, 2));
    return s;
}

ori_line_set ori_axiom_5(ori_v2 p1, ori_v2 p2, ori_line l1)
{
    ori_line_set s = empty_set();
    ori_v2 u1;
    if (!finite2(p1) || !finite2(p2) || !unit_dir(l1, &u1)) return s;
    ori_v2 pts[3] = {p1, p2, l1.point};
    double L = scale_of(pts, 3);
    double tol = ORI_TOL_LENGTH_REL * L;
    double r = ori_v2_norm(ori_v2_sub(p1, p2));
    if (!(r > tol)) return s; // p1 = p2: every fold through it keeps it fixed
    // Images of p1: where the circle about p2 through p1 meets l1.
    ori_v2 w = ori_v2_sub(p2, l1.point);
    double along = ori_v2_dot(w, u1), h = fabs(ori_v2_cross(u1, w));
    ori_v2 foot = ori_v2_add(l1.point, ori_v2_scale(u1, along));
    double disc = (r - h) * (r + h);
    double tol_disc = ORI_TOL_CONSTRUCTION_REL * L * L;
    if (disc < -tol_disc) return s;
    double half = disc > tol_disc ? sqrt(disc) : 0.0;
    for (int k = 0; k < (half > 0.0 ? 2 : 1); ++k) {
        ori_v2 x = ori_v2_add(foot, ori_v2_scale(u1, k == 0 ? -half : half));
        ori_v2 d = ori_v2_sub(x, p1);
        if (ori_v2_norm(d) <= tol) add_line(&s, p2, ori_v2_sub(p1, p2), L); // p1 already on l1
        else add_line(&s, p2, ori_v2_perp(d), L);
    }
    return s;
}

ori_line_set ori_axiom_7(ori_v2 p1, ori_line l1, ori_line l2)
{
    ori_line_set s = empty_set();
    ori_v2 u1, u2;
    if (!finite2(p1) || !unit_dir(l1, &u1) || !unit_dir(l2, &u2)) return s;
    ori_v2 pts[3] = {p1, l1.point, l2.point};
    double L = scale_of(pts, 3);
    double c = ori_v2_cross(u1, u2);
    if (fabs(c) <= ORI_TOL_CONSTRUCTION_REL) return s; // p1 moves along l2's direction: never onto l1
    // The fold is perpendicular to l2, so p1 moves along u2: p1 + t·u2 on l1.
    double t = ori_v2_cross(u1, ori_v2_sub(l1.point, p1)) / c;
    add_line(&s, ori_v2_add(p1, ori_v2_scale(u2, 0.5 * t)), ori_v2_perp(u2), L);
    return s;
}

// --- axiom 6 ------------------------------------------------------------------------------

static double poly_eval(const double *c, int deg, double t)
{
    double v = c[deg];
    for (int i = deg - 1; i >= 0; --i) v = v * t + c[i];
    return v;
}

static double poly_deriv(const double *c, int deg, double t)
{
    double v = deg * c[deg];
    for (int i = deg - 1; i >= 1; --i) v = v * t + i * c[i];
    return v;
}

// Newton steps while they reduce |f|.
static double polish(const double *c, int deg, double t)
{
    double f = poly_eval(c, deg, t);
    for (int it = 0; it < 8 && f != 0.0; ++it) {
        double df = poly_deriv(c, deg, t);
        if (df == 0.0 || !isfinite(df)) break;
        double tn = t - f / df, fn = poly_eval(c, deg, tn);
        if (!isfinite(fn) || fabs(fn) >= fabs(f)) break;
        t = tn;
        f = fn;
    }
    return t;
}

// Real roots of c[0] + c[1] t + c[2] t² + c[3] t³ (coefficients of a problem scaled to 1);
// leading coefficients negligible against the largest one are dropped. Returns the count
// (−1: the polynomial vanishes identically).
static int real_roots(const double *c_in, double *roots)
{
    double cmax = fmax(fmax(fabs(c_in[0]), fabs(c_in[1])), fmax(fabs(c_in[2]), fabs(c_in[3])));
    if (!(cmax > 0.0)) return -1;
    double c[4];
    for (int i = 0; i < 4; ++i) c[i] = c_in[i] / cmax;
    int deg = 3;
    while (deg > 0 && fabs(c[deg]) <= ORI_TOL_CONSTRUCTION_REL) --deg;
    if (deg == 0) return 0;
    int n = 0;
    if (deg == 1) {
        roots[n++] = -c[0] / c[1];
    } else if (deg == 2) {
        double a = c[2], b = c[1], cc = c[0];
        double disc = b * b - 4.0 * a * cc;
        double tol = ORI_TOL_CONSTRUCTION_REL * fmax(b * b, fabs(4.0 * a * cc));
        if (disc < -tol) return 0;
        if (disc <= tol) {
            roots[n++] = -b / (2.0 * a);
        } else {
            double q = -0.5 * (b + copysign(sqrt(disc), b)); // no cancellation
            roots[n++] = q / a;
            if (q != 0.0) roots[n++] = cc / q;
            else roots[n++] = -q / a;
        }
    } else {
        double A = c[2] / c[3], B = c[1] / c[3], C = c[0] / c[3];
        double p = B - A * A / 3.0, q = 2.0 * A * A * A / 27.0 - A * B / 3.0 + C;
        double h = 0.5 * q, k = p / 3.0;
        double disc = h * h + k * k * k;
        double tol = ORI_TOL_CONSTRUCTION_REL * fmax(h * h, fabs(k * k * k));
        double shift = -A / 3.0;
        if (disc > tol) {
            // One real root (Cardano, the larger cube root first: no cancellation).
            double u = cbrt(-h - copysign(sqrt(disc), h));
            double y = u != 0.0 ? u - k / u : 0.0;
            roots[n++] = y + shift;
        } else if (k < 0.0) {
            // Three real roots (two may coincide): trigonometric form.
            double r = 2.0 * sqrt(-k);
            double arg = -h / (-k * sqrt(-k));
            arg = fmin(1.0, fmax(-1.0, arg));
            double phi = acos(arg) / 3.0;
            for (int i = 0; i < 3; ++i) roots[n++] = r * cos(phi - 2.0 * ORI_PI * i / 3.0) + shift;
        } else {
            roots[n++] = cbrt(-q) + shift; // p ≈ 0 and q ≈ 0: a triple root
        }
    }
    for (int i = 0; i < n; ++i) roots[i] = polish(c, deg, roots[i]);
    // ascending
    for (int i = 1; i < n; ++i)
        for (int j = i; j > 0 && roots[j] < roots[j - 1]; --j) {
            double t = roots[j];
            roots[j] = roots[j - 1];
            roots[j - 1] = t;
        }
    // A double root comes out as two nearby roots: keep one.
    int m = 0;
    double merge = sqrt(ORI_TOL_CONSTRUCTION_REL);
    for (int i = 0; i < n; ++i)
        if (m == 0 || roots[i] - roots[m - 1] > merge * fmax(1.0, fabs(roots[i]))) roots[m++] = roots[i];
    return m;
}

ori_line_set ori_axiom_6(ori_v2 p1, ori_line l1, ori_v2 p2, ori_line l2)
{
    ori_line_set s = empty_set();
    ori_v2 u1, u2;
    if (!finite2(p1) || !finite2(p2) || !unit_dir(l1, &u1) || !unit_dir(l2, &u2)) return s;
    ori_v2 pts[4] = {p1, p2, l1.point, l2.point};
    double L = scale_of(pts, 4);
    // Work relative to p1 in units of L (coefficients of comparable size).
    ori_v2 o = p1;
    ori_v2 P2 = ori_v2_scale(ori_v2_sub(p2, o), 1.0 / L);
    ori_v2 Q1 = ori_v2_scale(ori_v2_sub(l1.point, o), 1.0 / L);
    ori_v2 Q2 = ori_v2_scale(ori_v2_sub(l2.point, o), 1.0 / L);
    // Q1 moved to the foot of p1 on l1, so t is the signed distance of p1's image from it.
    Q1 = ori_v2_sub(Q1, ori_v2_scale(u1, ori_v2_dot(Q1, u1)));
    ori_v2 n2 = ori_v2_perp(u2);
    // p1' = Q1 + t·u1, d = p1' − p1 (p1 = 0 here). The fold (bisector of p1, p1') reflects p2
    // onto l2 iff |d|² (k + n2·d) − 2 (p2·d)(n2·d) = 0 with k = n2·(p2 − q2).
    ori_v2 E = Q1;
    double a = ori_v2_dot(E, u1), b = ori_v2_dot(E, E);
    double alpha = ori_v2_dot(n2, E), beta = ori_v2_dot(n2, u1);
    double gamma = ori_v2_dot(P2, E), delta = ori_v2_dot(P2, u1);
    double k = ori_v2_dot(n2, ori_v2_sub(P2, Q2));
    double c[4];
    c[3] = beta;
    c[2] = (k + alpha) + 2.0 * a * beta - 2.0 * delta * beta;
    c[1] = 2.0 * a * (k + alpha) + b * beta - 2.0 * (gamma * beta + delta * alpha);
    c[0] = b * (k + alpha) - 2.0 * gamma * alpha;
    double roots[3];
    int n = real_roots(c, roots);
    if (n < 0) return s; // identically satisfied: infinitely many folds
    for (int i = 0; i < n; ++i) {
        if (!isfinite(roots[i])) continue;
        ori_v2 d = ori_v2_add(E, ori_v2_scale(u1, roots[i]));
        double dn = ori_v2_norm(d);
        if (!(dn > ORI_TOL_LENGTH_REL)) continue; // p1 already on l1 and left in place
        ori_line fold = {ori_v2_scale(d, 0.5), ori_v2_perp(d)};
        // Check the root really is a solution (guards the dropped-degree and tangent cases).
        ori_v2 r2 = ori_line_reflect(fold, P2);
        if (fabs(ori_v2_dot(n2, ori_v2_sub(r2, Q2))) > ORI_TOL_CONSTRUCTION_CHECK_REL * fmax(1.0, dn)) continue;
        add_line(&s, ori_v2_add(o, ori_v2_scale(fold.point, L)), fold.dir, L);
    }
    return s;
}

ori_line_set ori_axiom_solve(const ori_axiom_input *in)
{
    ORI_ASSERT(in);
    switch (in->axiom) {
    case 1: return ori_axiom_1(in->p1, in->p2);
    case 2: return ori_axiom_2(in->p1, in->p2);
    case 3: return ori_axiom_3(in->l1, in->l2);
    case 4: return ori_axiom_4(in->p1, in->l1);
    case 5: return ori_axiom_5(in->p1, in->p2, in->l1);
    case 6: return ori_axiom_6(in->p1, in->l1, in->p2, in->l2);
    case 7: return ori_axiom_7(in->p1, in->l1, in->l2);
    default: return empty_set();
    }
}
