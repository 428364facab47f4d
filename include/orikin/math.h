/// orikin math: double-precision 2D/3D vectors, 3×3 matrices, rigid transforms, twists and
/// their exponential (Rodrigues), robust 2D orientation.
///
/// Inline: ori_v2_*, ori_v3_*, ori_m3_*, ori_rigid_* (add, sub, scale, dot, cross, norm,
/// normalize, mul, transpose, apply, compose, inverse).
/// Functions: ori_m3_rotation, ori_twist_from_axis, ori_twist_exp, ori_orient2d,
/// ori_orient2d_sign, ori_angle_ccw_v2, ori_angle_between_v3, ori_wrap_angle, ori_rad_to_deg_output.
/// Angles are radians; rotations follow the right-hand rule.
#ifndef ORIKIN_MATH_H
#define ORIKIN_MATH_H

#include <math.h>

#include "base.h"

#ifdef __cplusplus
extern "C" {
#endif

/// π to double precision (M_PI is not part of C17).
#define ORI_PI 3.14159265358979323846

/// A 2D point or direction.
typedef struct ori_v2 {
    double x, y;
} ori_v2;

/// A 3D point or direction.
typedef struct ori_v3 {
    double x, y, z;
} ori_v3;

/// A 3×3 matrix, row-major: m[row][col].
typedef struct ori_m3 {
    double m[3][3];
} ori_m3;

/// A rigid transform p ↦ r·p + t (r a rotation).
typedef struct ori_rigid {
    ori_m3 r;
    ori_v3 t;
} ori_rigid;

/// A twist ξ = (v, ω) of a revolute joint: ω unit axis direction, v = −ω × q for a point q on
/// the axis (Murray, Li, Sastry 1994, ch. 2).
typedef struct ori_twist {
    ori_v3 v;
    ori_v3 w;
} ori_twist;

static inline ori_v2 ori_v2_make(double x, double y) { ori_v2 r = {x, y}; return r; }
static inline ori_v2 ori_v2_add(ori_v2 a, ori_v2 b) { return ori_v2_make(a.x + b.x, a.y + b.y); }
static inline ori_v2 ori_v2_sub(ori_v2 a, ori_v2 b) { return ori_v2_make(a.x - b.x, a.y - b.y); }
static inline ori_v2 ori_v2_scale(ori_v2 a, double s) { return ori_v2_make(a.x * s, a.y * s); }
static inline double ori_v2_dot(ori_v2 a, ori_v2 b) { return a.x * b.x + a.y * b.y; }
/// z component of the 3D cross product (a.x, a.y, 0) × (b.x, b.y, 0).
static inline double ori_v2_cross(ori_v2 a, ori_v2 b) { return a.x * b.y - a.y * b.x; }
static inline double ori_v2_norm(ori_v2 a) { return hypot(a.x, a.y); }
/// Unit vector along a; the zero vector for a zero (or non-finite-length) input, never NaN.
static inline ori_v2 ori_v2_normalize(ori_v2 a)
{
    double n = ori_v2_norm(a);
    if (!(n > 0.0) || !isfinite(n)) return ori_v2_make(0.0, 0.0);
    return ori_v2_make(a.x / n, a.y / n);
}
/// a rotated by +90° (counter-clockwise).
static inline ori_v2 ori_v2_perp(ori_v2 a) { return ori_v2_make(-a.y, a.x); }

static inline ori_v3 ori_v3_make(double x, double y, double z) { ori_v3 r = {x, y, z}; return r; }
static inline ori_v3 ori_v3_add(ori_v3 a, ori_v3 b) { return ori_v3_make(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline ori_v3 ori_v3_sub(ori_v3 a, ori_v3 b) { return ori_v3_make(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline ori_v3 ori_v3_scale(ori_v3 a, double s) { return ori_v3_make(a.x * s, a.y * s, a.z * s); }
static inline double ori_v3_dot(ori_v3 a, ori_v3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline ori_v3 ori_v3_cross(ori_v3 a, ori_v3 b)
{
    return ori_v3_make(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double ori_v3_norm(ori_v3 a) { return sqrt(ori_v3_dot(a, a)); }
/// Unit vector along a; the zero vector for a zero (or non-finite-length) input, never NaN.
static inline ori_v3 ori_v3_normalize(ori_v3 a)
{
    double n = ori_v3_norm(a);
    if (!(n > 0.0) || !isfinite(n)) return ori_v3_make(0.0, 0.0, 0.0);
    return ori_v3_scale(a, 1.0 / n);
}
static inline ori_v3 ori_v3_from_v2(ori_v2 a) { return ori_v3_make(a.x, a.y, 0.0); }

static inline ori_m3 ori_m3_identity(void)
{
    ori_m3 r = {{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}};
    return r;
}
static inline ori_m3 ori_m3_mul(ori_m3 a, ori_m3 b)
{
    ori_m3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
    return r;
}
static inline ori_m3 ori_m3_transpose(ori_m3 a)
{
    ori_m3 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r.m[i][j] = a.m[j][i];
    return r;
}
static inline ori_v3 ori_m3_apply(ori_m3 a, ori_v3 p)
{
    return ori_v3_make(a.m[0][0] * p.x + a.m[0][1] * p.y + a.m[0][2] * p.z,
                       a.m[1][0] * p.x + a.m[1][1] * p.y + a.m[1][2] * p.z,
                       a.m[2][0] * p.x + a.m[2][1] * p.y + a.m[2][2] * p.z);
}

static inline ori_rigid ori_rigid_identity(void)
{
    ori_rigid g;
    g.r = ori_m3_identity();
    g.t = ori_v3_make(0.0, 0.0, 0.0);
    return g;
}
/// a ∘ b: first b, then a.
static inline ori_rigid ori_rigid_compose(ori_rigid a, ori_rigid b)
{
    ori_rigid g;
    g.r = ori_m3_mul(a.r, b.r);
    g.t = ori_v3_add(ori_m3_apply(a.r, b.t), a.t);
    return g;
}
static inline ori_rigid ori_rigid_inverse(ori_rigid a)
{
    ori_rigid g;
    g.r = ori_m3_transpose(a.r);
    g.t = ori_v3_scale(ori_m3_apply(g.r, a.t), -1.0);
    return g;
}
static inline ori_v3 ori_rigid_apply(ori_rigid g, ori_v3 p) { return ori_v3_add(ori_m3_apply(g.r, p), g.t); }
static inline ori_v3 ori_rigid_apply_dir(ori_rigid g, ori_v3 d) { return ori_m3_apply(g.r, d); }

/// Rotation by angle_rad about the unit axis (Rodrigues: I + ŵ sin θ + ŵ² (1 − cos θ)).
ORI_API ori_m3 ori_m3_rotation(ori_v3 axis_unit, double angle_rad);

/// Twist of a revolute joint through point q with direction w (normalized here; a zero w gives
/// the zero twist).
ORI_API ori_twist ori_twist_from_axis(ori_v3 q, ori_v3 w);

/// Exponential e^{ξ̂θ} of a revolute twist (|ω| = 1): rotation R = e^{ω̂θ}, translation
/// (I − R)(ω × v) + ω ωᵀ v θ, i.e. (I − R) q for a pure rotation about the axis through q.
ORI_API ori_rigid ori_twist_exp(ori_twist xi, double angle_rad);

/// Twice the signed area of triangle abc: > 0 when a, b, c turn counter-clockwise, < 0
/// clockwise, exactly 0 when collinear. The sign is exact (adaptive, exact fallback).
ORI_API double ori_orient2d(ori_v2 a, ori_v2 b, ori_v2 c);
/// Sign of ori_orient2d: +1, 0 or −1, exact.
ORI_API int ori_orient2d_sign(ori_v2 a, ori_v2 b, ori_v2 c);

/// Counter-clockwise angle from a to b in [0, 2π); 0 when either vector is zero.
ORI_API double ori_angle_ccw_v2(ori_v2 a, ori_v2 b);
/// Unsigned angle between a and b in [0, π]; 0 when either vector is zero.
ORI_API double ori_angle_between_v3(ori_v3 a, ori_v3 b);
/// An angle wrapped into (−π, π].
ORI_API double ori_wrap_angle(double angle_rad);

/// Radians → degrees for output (files, messages, the CLI): a value within ORI_TOL_PRINT_DEG
/// of an integer becomes that integer (90.00000000000001 → 90) and −0 becomes 0.
ORI_API double ori_rad_to_deg_output(double angle_rad);

/// Degrees → radians and back (I/O and CLI only; the library works in radians).
static inline double ori_deg_to_rad(double deg) { return deg * (ORI_PI / 180.0); }
static inline double ori_rad_to_deg(double rad) { return rad * (180.0 / ORI_PI); }

#ifdef __cplusplus
}
#endif

#endif
