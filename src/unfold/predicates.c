// Exact planar predicates over the library's one exact orientation (ori_orient2d_sign), and the
// perturbed orientation's degree terms in GMP rational arithmetic (exact for any doubles).
#include <gmp.h>
#include <math.h>

#include "unfold_internal.h"

// The one exact orientation of the library (src/geometry/math.c: Shewchuk's filter, then an exact
// expansion of the determinant); kept under this name for the unfolding's predicates.
int ori__orient2d_exact(ori_v2 a, ori_v2 b, ori_v2 c) { return ori_orient2d_sign(a, b, c); }

static bool on_segment(ori_v2 a, ori_v2 b, ori_v2 p)
{
    // p collinear with ab: inside the closed box of ab.
    return fmin(a.x, b.x) <= p.x && p.x <= fmax(a.x, b.x) && fmin(a.y, b.y) <= p.y && p.y <= fmax(a.y, b.y);
}

bool ori__segments_intersect(ori_v2 a, ori_v2 b, ori_v2 c, ori_v2 d)
{
    int o1 = ori__orient2d_exact(a, b, c), o2 = ori__orient2d_exact(a, b, d);
    int o3 = ori__orient2d_exact(c, d, a), o4 = ori__orient2d_exact(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    if (o1 == 0 && on_segment(a, b, c)) return true;
    if (o2 == 0 && on_segment(a, b, d)) return true;
    if (o3 == 0 && on_segment(c, d, a)) return true;
    if (o4 == 0 && on_segment(c, d, b)) return true;
    return false;
}

bool ori__segments_cross_properly(ori_v2 a, ori_v2 b, ori_v2 c, ori_v2 d)
{
    int o1 = ori__orient2d_exact(a, b, c), o2 = ori__orient2d_exact(a, b, d);
    int o3 = ori__orient2d_exact(c, d, a), o4 = ori__orient2d_exact(c, d, b);
    return o1 * o2 < 0 && o3 * o4 < 0;
}

// Exact sign of a polynomial coefficient cross(u, w) + cross(x, y) with u, w, x, y differences of
// doubles (given as their endpoints).
static int cross_sum_gmp(const ori_v2 *u0, const ori_v2 *u1, const ori_v2 *w0, const ori_v2 *w1, int terms)
{
    mpq_t a, b, c, d, t, sum;
    mpq_inits(a, b, c, d, t, sum, NULL);
    for (int k = 0; k < terms; ++k) {
        // (u1 − u0) × (w1 − w0)
        mpq_set_d(a, u1[k].x), mpq_set_d(t, u0[k].x), mpq_sub(a, a, t);
        mpq_set_d(b, u1[k].y), mpq_set_d(t, u0[k].y), mpq_sub(b, b, t);
        mpq_set_d(c, w1[k].x), mpq_set_d(t, w0[k].x), mpq_sub(c, c, t);
        mpq_set_d(d, w1[k].y), mpq_set_d(t, w0[k].y), mpq_sub(d, d, t);
        mpq_mul(a, a, d), mpq_mul(b, b, c), mpq_sub(a, a, b), mpq_add(sum, sum, a);
    }
    int s = mpq_sgn(sum);
    mpq_clears(a, b, c, d, t, sum, NULL);
    return s;
}

int ori__orient2d_perturbed(ori_v2 a, ori_v2 b, ori_v2 c, const ori_v2 *d, const ori_v2 *e)
{
    int s = ori__orient2d_exact(a, b, c);
    if (s != 0) return s;
    // point k is p_k + ε d_k + ε² e_k; the coefficients of ε¹ … ε⁴, each a sum of cross products
    // of differences, in turn
    ori_v2 p[3] = {a, b, c};
    const ori_v2 *lv[3] = {p, d, e};
    static const int terms[4][3][2] = {{{0, 1}, {1, 0}, {-1, -1}},
                                       {{1, 1}, {0, 2}, {2, 0}},
                                       {{1, 2}, {2, 1}, {-1, -1}},
                                       {{2, 2}, {-1, -1}, {-1, -1}}};
    for (int o = 0; o < 4; ++o) {
        ori_v2 u0[3], u1[3], w0[3], w1[3];
        int k = 0;
        for (int t = 0; t < 3 && terms[o][t][0] >= 0; ++t, ++k) {
            const ori_v2 *x = lv[terms[o][t][0]], *y = lv[terms[o][t][1]];
            u0[k] = x[0], u1[k] = x[1], w0[k] = y[0], w1[k] = y[2];
        }
        s = cross_sum_gmp(u0, u1, w0, w1, k);
        if (s != 0) return s;
    }
    return 0;
}
