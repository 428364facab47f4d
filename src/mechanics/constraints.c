// Loop-closure constraints assembled from the public mechanism data (loops, their creases and
// faces, the joints' flat axes): for each loop the product of the crease motions around it,
// P = Π e^{s_i ξ_i θ_i}, must be the identity. Its residual is log P (the rotation vector, and
// for a hole loop the translation over the pattern diagonal); its Jacobian column for crease i
// is the crease's twist carried by the motions before it, s_i·Ad_{P_<i} ξ_i; and differentiating
// Σ s_i ξ'_i θ̇_i = 0 once more in time gives the constraint acceleration term
// γ = −Σ_i s_i θ̇_i [V_<i, ξ'_i], V_<i = Σ_{k<i} s_k ξ'_k θ̇_k.
#include "mechanics_internal.h"

void ori__loops_init(mech_loops *l, const ori_mechanism *m, double diagonal)
{
    memset(l, 0, sizeof *l);
    int L = l->count = ori_mechanism_loop_count(m);
    l->first = ori__alloc(sizeof(int) * (size_t)(L + 1));
    l->size = ori__alloc(sizeof(int) * (size_t)(L + 1));
    l->nrows = ori__alloc(sizeof(int) * (size_t)(L + 1));
    l->row0 = ori__alloc(sizeof(int) * (size_t)(L + 1));
    int total = 0;
    for (int k = 0; k < L; ++k) total += ori_mechanism_loop(m, k).crease_count;
    l->edge = ori__alloc(sizeof(int) * (size_t)(total + 1));
    l->sign = ori__alloc(sizeof(int) * (size_t)(total + 1));
    l->q = ori__alloc(sizeof(ori_v3) * (size_t)(total + 1));
    l->w = ori__alloc(sizeof(ori_v3) * (size_t)(total + 1));
    int *faces = ori__alloc(sizeof(int) * (size_t)(total + 1));
    l->inv_diag = diagonal > 0 ? 1.0 / diagonal : 1.0;
    int at = 0;
    for (int k = 0; k < L; ++k) {
        ori_loop lp = ori_mechanism_loop(m, k);
        l->first[k] = at;
        l->size[k] = lp.crease_count;
        l->nrows[k] = lp.rows;
        l->row0[k] = l->rows;
        l->rows += lp.rows;
        ori_mechanism_loop_edges(m, k, l->edge + at, lp.crease_count);
        ori_mechanism_loop_faces(m, k, faces, lp.crease_count);
        for (int i = 0; i < lp.crease_count; ++i) {
            ori_joint J = ori_mechanism_joint(m, ori_mechanism_edge_joint(m, l->edge[at + i]));
            // Crease i lies between faces F(i−1) and F(i): F(i) = F(i−1)·e^{s ξ θ}.
            l->sign[at + i] = J.face_left == faces[i] ? 1 : -1;
            l->q[at + i] = J.q;
            l->w[at + i] = J.omega;
        }
        at += lp.crease_count;
    }
    ori__free(faces);
}

void ori__loops_free(mech_loops *l)
{
    ori__free(l->first);
    ori__free(l->size);
    ori__free(l->nrows);
    ori__free(l->row0);
    ori__free(l->edge);
    ori__free(l->sign);
    ori__free(l->q);
    ori__free(l->w);
    memset(l, 0, sizeof *l);
}

// Rotation vector of a rotation matrix (log map), accurate near the identity and near π.
static ori_v3 rotvec(ori_m3 r)
{
    ori_v3 s = ori_v3_make(0.5 * (r.m[2][1] - r.m[1][2]), 0.5 * (r.m[0][2] - r.m[2][0]), 0.5 * (r.m[1][0] - r.m[0][1]));
    double c = 0.5 * (r.m[0][0] + r.m[1][1] + r.m[2][2] - 1.0);
    double sn = ori_v3_norm(s);
    double phi = atan2(sn, c);
    if (phi < 0.5 * ORI_PI) return sn > 0.0 ? ori_v3_scale(s, phi / sn) : s;
    // Near π: the axis from the symmetric part, its sign from s.
    double d[3] = {r.m[0][0] - c, r.m[1][1] - c, r.m[2][2] - c};
    int k = d[0] >= d[1] && d[0] >= d[2] ? 0 : d[1] >= d[2] ? 1 : 2;
    ori_v3 col = ori_v3_make(0.5 * (r.m[0][k] + r.m[k][0]) - (k == 0 ? c : 0.0),
                             0.5 * (r.m[1][k] + r.m[k][1]) - (k == 1 ? c : 0.0),
                             0.5 * (r.m[2][k] + r.m[k][2]) - (k == 2 ? c : 0.0));
    ori_v3 axis = ori_v3_normalize(col);
    if (ori_v3_dot(axis, s) < 0.0) axis = ori_v3_scale(axis, -1.0);
    return ori_v3_scale(axis, phi);
}

void ori__loops_residual(const mech_loops *l, const double *th, double *phi)
{
    for (int k = 0; k < l->count; ++k) {
        ori_rigid P = ori_rigid_identity();
        for (int i = l->first[k]; i < l->first[k] + l->size[k]; ++i) {
            double a = th[l->edge[i]];
            if (a == 0.0) continue;
            P = ori_rigid_compose(P, ori_twist_exp(ori_twist_from_axis(l->q[i], l->w[i]), l->sign[i] * a));
        }
        ori_v3 r = rotvec(P.r);
        double *o = phi + l->row0[k];
        o[0] = r.x, o[1] = r.y, o[2] = r.z;
        if (l->nrows[k] == 6) {
            o[3] = P.t.x * l->inv_diag, o[4] = P.t.y * l->inv_diag, o[5] = P.t.z * l->inv_diag;
        }
    }
}

void ori__loops_jacobian(const mech_loops *l, const double *th, const double *rates, double *jac, double *gamma)
{
    for (int k = 0; k < l->count; ++k) {
        ori_rigid P = ori_rigid_identity();
        sv6 acc = sv6_zero(), g = sv6_zero();
        bool hole = l->nrows[k] == 6;
        for (int i = l->first[k]; i < l->first[k] + l->size[k]; ++i) {
            ori_v3 w = ori_m3_apply(P.r, l->w[i]);
            ori_v3 q = ori_rigid_apply(P, l->q[i]);
            sv6 xi = sv6_make(ori_v3_scale(ori_v3_cross(q, w), l->inv_diag), w);
            xi = sv6_scale(xi, (double)l->sign[i]);
            double *c = jac + 6 * (size_t)i;
            c[0] = xi.w.x, c[1] = xi.w.y, c[2] = xi.w.z;
            c[3] = xi.v.x, c[4] = xi.v.y, c[5] = xi.v.z;
            if (rates) {
                double r = rates[l->edge[i]];
                if (r != 0.0) {
                    g = sv6_add(g, sv6_scale(sv6_ad(acc, xi), -r));
                    acc = sv6_add(acc, sv6_scale(xi, r));
                }
            }
            double a = th[l->edge[i]];
            if (a != 0.0) P = ori_rigid_compose(P, ori_twist_exp(ori_twist_from_axis(l->q[i], l->w[i]), l->sign[i] * a));
        }
        if (gamma) {
            double *o = gamma + l->row0[k];
            o[0] = g.w.x, o[1] = g.w.y, o[2] = g.w.z;
            if (hole) o[3] = g.v.x, o[4] = g.v.y, o[5] = g.v.z;
        }
    }
}
