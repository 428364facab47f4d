// Rotations, twist exponentials, the robust orientation predicate and the segment predicates
// behind geometry_internal.h.
#include <orikin/math.h>
#include <orikin/tolerance.h>

#include <float.h>

#include "geometry_internal.h"

ori_m3 ori_m3_rotation(ori_v3 k, double angle_rad)
{
    // Rodrigues: R = I + sin θ K + (1 − cos θ) K², K the cross-product matrix of k.
    double c = cos(angle_rad), s = sin(angle_rad), t = 1.0 - c;
    ori_m3 r;
    r.m[0][0] = c + k.x * k.x * t;
    r.m[0][1] = k.x * k.y * t - k.z * s;
    r.m[0][2] = k.x * k.z * t + k.y * s;
    r.m[1][0] = k.y * k.x * t + k.z * s;
    r.m[1][1] = c + k.y * k.y * t;
    r.m[1][2] = k.y * k.z * t - k.x * s;
    r.m[2][0] = k.z * k.x * t - k.y * s;
    r.m[2][1] = k.z * k.y * t + k.x * s;
    r.m[2][2] = c + k.z * k.z * t;
    return r;
}

ori_twist ori_twist_from_axis(ori_v3 q, ori_v3 w)
{
    ori_twist xi;
    xi.w = ori_v3_normalize(w);
    xi.v = ori_v3_scale(ori_v3_cross(xi.w, q), -1.0);
    return xi;
}

ori_rigid ori_twist_exp(ori_twist xi, double angle_rad)
{
    // Murray–Li–Sastry (2.36): translation (I − R)(ω × v) + ω ωᵀ v θ.
    ori_rigid g;
    g.r = ori_m3_rotation(xi.w, angle_rad);
    ori_v3 wxv = ori_v3_cross(xi.w, xi.v);
    ori_v3 a = ori_v3_sub(wxv, ori_m3_apply(g.r, wxv));
    ori_v3 b = ori_v3_scale(xi.w, ori_v3_dot(xi.w, xi.v) * angle_rad);
    g.t = ori_v3_add(a, b);
    return g;
}

// --- exact orientation -------------------------------------------------------------------
// Fast path with a forward error bound (Shewchuk 1997, ccwerrboundA); otherwise the
// determinant is expanded into six products, each split exactly with fma, and summed exactly
// as a non-overlapping expansion whose most significant component carries the sign.

static void two_sum(double a, double b, double *s, double *e)
{
    double x = a + b;
    double bv = x - a;
    double av = x - bv;
    *s = x;
    *e = (a - av) + (b - bv);
}

static double exact_orient(ori_v2 a, ori_v2 b, ori_v2 c)
{
    const double f[6][2] = {{b.x, c.y}, {-b.x, a.y}, {-a.x, c.y}, {-b.y, c.x}, {b.y, a.x}, {a.y, c.x}};
    double e[13];
    int m = 0;
    for (int i = 0; i < 6; ++i) {
        double hi = f[i][0] * f[i][1];
        double lo = fma(f[i][0], f[i][1], -hi);
        double terms[2] = {lo, hi};
        for (int t = 0; t < 2; ++t) {
            double q = terms[t];
            for (int k = 0; k < m; ++k) {
                double s, err;
                two_sum(q, e[k], &s, &err);
                e[k] = err;
                q = s;
            }
            e[m++] = q;
        }
    }
    for (int k = m - 1; k >= 0; --k)
        if (e[k] != 0.0) return e[k];
    return 0.0;
}

double ori_orient2d(ori_v2 a, ori_v2 b, ori_v2 c)
{
    double left = (b.x - a.x) * (c.y - a.y);
    double right = (b.y - a.y) * (c.x - a.x);
    double det = left - right;
    double sum = fabs(left) + fabs(right);
    const double bound = (3.0 + 16.0 * DBL_EPSILON / 2.0) * (DBL_EPSILON / 2.0);
    if (fabs(det) > bound * sum) return det;
    if (sum == 0.0) return 0.0;
    double s = exact_orient(a, b, c);
    // Keep the fast value's magnitude when it has the right sign; otherwise a tiny signed value.
    if ((s > 0.0 && det > 0.0) || (s < 0.0 && det < 0.0)) return det;
    return s;
}

int ori_orient2d_sign(ori_v2 a, ori_v2 b, ori_v2 c)
{
    double d = ori_orient2d(a, b, c);
    return (d > 0.0) - (d < 0.0);
}

bool ori__in_segment_box(ori_v2 a, ori_v2 b, ori_v2 c)
{
    return fmin(a.x, b.x) <= c.x && c.x <= fmax(a.x, b.x) && fmin(a.y, b.y) <= c.y && c.y <= fmax(a.y, b.y);
}

bool ori__overlap_beyond(ori_v2 s, ori_v2 x, ori_v2 y)
{
    return ori_orient2d_sign(s, x, y) == 0 && ori_v2_dot(ori_v2_sub(x, s), ori_v2_sub(y, s)) > 0.0;
}

bool ori__corner_contains(ori_v2 u, ori_v2 next, ori_v2 prev, ori_v2 x)
{
    int a = ori_orient2d_sign(u, next, x); // > 0: x counter-clockwise of next
    int b = ori_orient2d_sign(u, x, prev); // > 0: prev counter-clockwise of x
    int o = ori_orient2d_sign(u, next, prev);
    if (o > 0) return a > 0 && b > 0;
    if (o < 0) return a > 0 || b > 0;
    if (ori_v2_dot(ori_v2_sub(next, u), ori_v2_sub(prev, u)) < 0.0) return a > 0; // straight corner (180°)
    return !(a == 0 && ori_v2_dot(ori_v2_sub(x, u), ori_v2_sub(next, u)) > 0.0);    // zero angle
}

double ori_angle_ccw_v2(ori_v2 a, ori_v2 b)
{
    if ((a.x == 0.0 && a.y == 0.0) || (b.x == 0.0 && b.y == 0.0)) return 0.0;
    double ang = atan2(ori_v2_cross(a, b), ori_v2_dot(a, b));
    if (ang < 0.0) ang += 2.0 * ORI_PI;
    if (ang >= 2.0 * ORI_PI) ang = 0.0;
    return ang;
}

double ori_angle_between_v3(ori_v3 a, ori_v3 b)
{
    double n = ori_v3_norm(ori_v3_cross(a, b));
    double d = ori_v3_dot(a, b);
    if (n == 0.0 && d == 0.0) return 0.0;
    return atan2(n, d);
}

double ori_wrap_angle(double angle_rad)
{
    double a = fmod(angle_rad, 2.0 * ORI_PI);
    if (a > ORI_PI) a -= 2.0 * ORI_PI;
    else if (a <= -ORI_PI) a += 2.0 * ORI_PI;
    return a;
}

double ori_rad_to_deg_output(double angle_rad)
{
    double d = ori_rad_to_deg(angle_rad), r = round(d);
    if (fabs(d - r) <= ORI_TOL_PRINT_DEG) d = r;
    return d == 0.0 ? 0.0 : d;
}
