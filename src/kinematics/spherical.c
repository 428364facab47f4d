// Closed-form inverse kinematics of a single vertex with four moving creases: a spherical 4R
// linkage (thesis ch. 4.6, 5.1). Locked creases are merged into the rigid links between the
// moving ones; their rotations are constants of the loop equation.
//
// With the loop rotated to start at the driven crease d and the free creases 1, 2, 3 in loop
// order, the closure R(a_d, x_d) C1 R(a_1, x_1) C2 R(a_2, x_2) C3 R(a_3, x_3) C4 = I (C_k products
// of locked rotations, which carry the links' current geometry) becomes, after moving the
// constants through the rotations (X R(a, x) = R(X a, x) X),
//     R(u1, x1) R(u2, x2) R(u3, x3) = G,   u1 = a_1, u2 = C2 a_2, u3 = C2 C3 a_3,
//     G = C1ᵀ R(a_d, −x_d) C4ᵀ (C2 C3)ᵀ.
// Applied to u3 (fixed by R(u3, ·)) and projected on u1 (fixed by R(u1, ·)):
//     u1 · R(u2, x2) p = u1 · q,  p = u3, q = G u3,
// i.e. the classical input–output equation A cos x2 + B sin x2 = C with
//     A = u1 · (p − (u2·p) u2),  B = u1 · (u2 × p),  C = u1 · q − (u2·p)(u1·u2),
// whose solutions x2 = atan2(B, A) ± acos(C / √(A² + B²)) are the (at most two) branches. x1
// then rotates R(u2, x2) p onto q about u1, and x3 is the angle of the remaining rotation
// (R(u1,x1) R(u2,x2))ᵀ G about u3. Where a step is indeterminate (A = B = 0: u1 ∥ u2 or
// p ∥ u2; or R(u2,x2) p ∥ u1: a hinge family through the flat state) the predicted value
// stands in; every candidate is verified by its loop residual.
#include <lapacke.h>
#include <math.h>
#include <string.h>

#include "kinematics_internal.h"

bool ori__kin_spherical_applicable(const ori_mechanism *m, const int *col_of_joint, int drive_joint,
                                   kin_spherical *sp)
{
    int loop = -1;
    for (int l = 0; l < m->loop_count; ++l) {
        const kin_loop *L = &m->loops[l];
        bool moving = false;
        for (int c = 0; c < L->col_count; ++c) {
            int j = m->loop_cols[L->col_first + c];
            if (j == drive_joint || col_of_joint[j] >= 0) moving = true;
        }
        if (!moving) continue;
        if (loop >= 0) return false; // a second loop moves
        loop = l;
    }
    if (loop < 0) return false;
    const kin_loop *L = &m->loops[loop];
    if (L->rows != 3) return false;
    int d = -1, nfree = 0;
    for (int i = 0; i < L->count; ++i) {
        int j = m->entries[L->first + i].joint;
        if (j == drive_joint) d = i;
    }
    if (d < 0) return false;
    int total_free = 0;
    for (int j = 0; j < m->joint_count; ++j) total_free += col_of_joint[j] >= 0;
    sp->loop = loop;
    sp->drive_entry = d;
    for (int k = 1; k < L->count; ++k) {
        int i = (d + k) % L->count;
        int j = m->entries[L->first + i].joint;
        if (col_of_joint[j] >= 0) {
            if (nfree >= 3) return false;
            sp->free_entry[nfree++] = i;
        }
    }
    return nfree == 3 && total_free == 3;
}

// Angle of the rotation that takes c to q about the unit axis u (both projected on the plane
// ⊥ u); *ok is false when either projection vanishes.
static double angle_about(ori_v3 u, ori_v3 c, ori_v3 q, bool *ok)
{
    ori_v3 cp = ori_v3_sub(c, ori_v3_scale(u, ori_v3_dot(u, c)));
    ori_v3 qp = ori_v3_sub(q, ori_v3_scale(u, ori_v3_dot(u, q)));
    double nc = ori_v3_norm(cp), nq = ori_v3_norm(qp);
    *ok = nc > ORI_TOL_AXIS_DEGENERATE && nq > ORI_TOL_AXIS_DEGENERATE;
    if (!*ok) return 0.0;
    return atan2(ori_v3_dot(u, ori_v3_cross(cp, qp)), ori_v3_dot(cp, qp));
}

// A unit vector perpendicular to u.
static ori_v3 any_perp(ori_v3 u)
{
    ori_v3 t = fabs(u.x) < 0.6 ? ori_v3_make(1, 0, 0) : fabs(u.y) < 0.6 ? ori_v3_make(0, 1, 0) : ori_v3_make(0, 0, 1);
    return ori_v3_normalize(ori_v3_cross(u, t));
}

// The representative of angle x (mod 2π) nearest to reference.
static double near_to(double x, double reference)
{
    return reference + ori_wrap_angle(x - reference);
}

// The loop at drive value `drive` and free angles x (the other creases at th), evaluated by the
// mechanism's own loop evaluation (ori__kin_vertex_loop_eval: a product of unit quaternions, P − I
// and the rotation vector without cancellation against the identity, so that near the flat state
// they keep their relative precision; a matrix product's P − I has an absolute floor of 1e-16,
// which left 5e-12 rad in the angles where σ_min is 1e-5). Fills the rotation vector r of P and,
// when w is not NULL, the spatial axes of the three free rotations (the Jacobian's columns);
// returns max |P − I|, INFINITY when not finite.
static double loop_eval(const ori_mechanism *m, const kin_spherical *sp, const double *th, double drive, const double x[3],
                        double r[3], ori_v3 w[3])
{
    const kin_loop *L = &m->loops[sp->loop];
    double *t = ori__alloc(sizeof(double) * (size_t)(m->joint_count + 1));
    memcpy(t, th, sizeof(double) * (size_t)m->joint_count);
    t[m->entries[L->first + sp->drive_entry].joint] = drive;
    for (int f = 0; f < 3; ++f) t[m->entries[L->first + sp->free_entry[f]].joint] = x[f];
    ori_v3 *axes = w ? ori__alloc(sizeof(ori_v3) * (size_t)L->count) : NULL;
    double dev = ori__kin_vertex_loop_eval(m, L, t, r, axes);
    if (w)
        for (int f = 0; f < 3; ++f) w[f] = axes[sp->free_entry[f]];
    ori__free(axes);
    ori__free(t);
    return isfinite(dev) && isfinite(r[0]) && isfinite(r[1]) && isfinite(r[2]) ? dev : INFINITY;
}

// Newton polish of a candidate on the loop equation itself (minimum-norm steps: near the flat
// state the three free axes are almost coplanar). The input–output equation loses half the
// digits where its two roots merge (acos near ±1: the flat state, a turning point), so the
// closed form is the start and the loop equation the judge. Like the numeric corrector
// (solver.c), it goes on from a deviation within ORI_TOL_NEWTON until |r|₂ / σ_min is within
// ORI_TOL_NEWTON_STATE_RAD or a step no longer halves |r|₂ (the round-off floor). Returns the
// final deviation of P from I.
static double polish(const ori_mechanism *m, const kin_spherical *sp, const double *th, double drive, double x[3])
{
    ori_v3 w[3];
    double r[3], r2[3];
    double dev = loop_eval(m, sp, th, drive, x, r, w);
    double rn = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (int it = 0; it < ORI_KIN_SPHERICAL_POLISH_MAX && isfinite(dev); ++it) {
        double A[9] = {w[0].x, w[0].y, w[0].z, w[1].x, w[1].y, w[1].z, w[2].x, w[2].y, w[2].z};
        double b[3] = {-r[0], -r[1], -r[2]}, sv[3];
        lapack_int rank;
        if (LAPACKE_dgelss(LAPACK_COL_MAJOR, 3, 3, 1, A, 3, b, 3, sv, ORI_TOL_RANK_REL, &rank) != 0) break;
        bool close = dev <= ORI_TOL_NEWTON;
        if (close && rank > 0 && rn <= ORI_TOL_NEWTON_STATE_RAD * sv[rank - 1]) break;
        double y[3] = {x[0] + b[0], x[1] + b[1], x[2] + b[2]};
        ori_v3 wy[3];
        double d2 = loop_eval(m, sp, th, drive, y, r2, wy);
        double rn2 = sqrt(r2[0] * r2[0] + r2[1] * r2[1] + r2[2] * r2[2]);
        if (close ? !(rn2 < rn) : !(d2 < dev)) break;
        bool halved = rn2 <= 0.5 * rn;
        dev = d2;
        rn = rn2;
        for (int k = 0; k < 3; ++k) {
            x[k] = y[k];
            r[k] = r2[k];
            w[k] = wy[k];
        }
        if (close && !halved) break;
    }
    return dev;
}

// The loop's axes (drive, free 1–3) and the constant rotations between them (locked creases
// at their angle in th), in loop order from the drive.
static void loop_setup(const ori_mechanism *m, const kin_spherical *sp, const double *th, ori_v3 a[4], ori_m3 C[4])
{
    const kin_loop *L = &m->loops[sp->loop];
    int n = L->count;
    for (int k = 0; k < 4; ++k) C[k] = ori_m3_identity();
    a[0] = m->entries[L->first + sp->drive_entry].axis;
    int seg = 0; // constants between drive (0) and free 1 → C[0]; free1..free2 → C[1]; …
    for (int k = 1; k < n; ++k) {
        int i = (sp->drive_entry + k) % n;
        const kin_entry *en = &m->entries[L->first + i];
        if (seg < 3 && i == sp->free_entry[seg]) {
            a[seg + 1] = en->axis;
            seg++;
            continue;
        }
        C[seg] = ori_m3_mul(C[seg], ori_m3_rotation(en->axis, th[en->joint]));
    }
}

double ori__kin_spherical_polish(const ori_mechanism *m, const kin_spherical *sp, const double *th, double drive,
                                 double x[3])
{
    return polish(m, sp, th, drive, x);
}

int ori__kin_spherical_solve(const ori_mechanism *m, const kin_spherical *sp, const double *th, double drive,
                             const double pred[3], double cand[2][3], int label[2])
{
    return ori__kin_spherical_solve_ex(m, sp, th, drive, pred, cand, label, NULL);
}

int ori__kin_spherical_solve_ex(const ori_mechanism *m, const kin_spherical *sp, const double *th, double drive,
                                const double pred[3], double cand[2][3], int label[2], bool *reachable)
{
    int lab[2];
    bool reach_dummy;
    if (!label) label = lab;
    if (!reachable) reachable = &reach_dummy;
    *reachable = false;
    ori_m3 C[4];
    ori_v3 a[4];
    loop_setup(m, sp, th, a, C);
    // R(a0,xd) C0 R(a1,x1) C1 R(a2,x2) C2 R(a3,x3) C3 = I.
    ori_m3 C12 = ori_m3_mul(C[1], C[2]);
    ori_v3 u1 = a[1];
    ori_v3 u2 = ori_m3_apply(C[1], a[2]);
    ori_v3 u3 = ori_m3_apply(C12, a[3]);
    ori_m3 G = ori_m3_mul(ori_m3_mul(ori_m3_transpose(C[0]), ori_m3_rotation(a[0], -drive)),
                          ori_m3_mul(ori_m3_transpose(C[3]), ori_m3_transpose(C12)));
    ori_v3 p = u3, q = ori_m3_apply(G, u3);
    double up = ori_v3_dot(u2, p);
    double A = ori_v3_dot(u1, ori_v3_sub(p, ori_v3_scale(u2, up)));
    double B = ori_v3_dot(u1, ori_v3_cross(u2, p));
    double Cc = ori_v3_dot(u1, q) - up * ori_v3_dot(u1, u2);
    double r = hypot(A, B);
    double x2s[2];
    int nx2;
    if (!(r > ORI_TOL_AXIS_DEGENERATE)) {
        // Degenerate: the equation does not involve x2 (it holds or fails for all x2).
        if (fabs(Cc) > ORI_TOL_AXIS_DEGENERATE) return 0;
        *reachable = true;
        x2s[0] = pred[1];
        nx2 = 1;
    } else {
        double c = Cc / r;
        if (c > 1.0 + ORI_TOL_BRANCH_MERGE || c < -1.0 - ORI_TOL_BRANCH_MERGE) return 0; // unreachable
        *reachable = true;
        if (c > 1.0) c = 1.0;
        if (c < -1.0) c = -1.0;
        // Within rounding of a double root (the branches crossing, e.g. at the flat state of a
        // flat-foldable vertex) the computed acos(c) is √ of the rounding, not 0: the root is
        // double.
        if (1.0 - fabs(c) <= ORI_TOL_KIN_DOUBLE_ROOT) c = c > 0.0 ? 1.0 : -1.0;
        double psi = atan2(B, A), delta = acos(c);
        x2s[0] = psi + delta;
        x2s[1] = psi - delta;
        nx2 = 2;
    }
    int count = 0;
    for (int b = 0; b < nx2; ++b) {
        double x2 = near_to(x2s[b], pred[1]);
        ori_v3 cvec = ori_m3_apply(ori_m3_rotation(u2, x2), p);
        bool ok;
        double x1 = angle_about(u1, cvec, q, &ok);
        x1 = ok ? near_to(x1, pred[0]) : pred[0];
        ori_m3 H = ori_m3_mul(ori_m3_transpose(ori_m3_mul(ori_m3_rotation(u1, x1), ori_m3_rotation(u2, x2))), G);
        ori_v3 w = any_perp(u3);
        double x3 = angle_about(u3, w, ori_m3_apply(H, w), &ok);
        x3 = near_to(ok ? x3 : pred[2], pred[2]);
        double x[3] = {x1, x2, x3};
        // Verify the loop with every crease at its value (after the polish).
        double dev = polish(m, sp, th, drive, x);
        if (!(dev <= 0.5 * ORI_TOL_RESIDUAL)) continue; // half: the mechanism measures the loop its own way
        // The branch label: the sign of ±acos in x2 = ψ ± acos(C/r), 0 at a double root or where
        // the equation does not involve x2.
        label[count] = nx2 == 2 && x2s[0] != x2s[1] ? (b == 0 ? 1 : -1) : 0;
        x1 = x[0];
        x2 = x[1];
        x3 = x[2];
        cand[count][0] = x1;
        cand[count][1] = x2;
        cand[count][2] = x3;
        // Drop an exact duplicate (double root).
        if (count == 1 && fabs(cand[0][0] - x1) + fabs(cand[0][1] - x2) + fabs(cand[0][2] - x3) == 0.0) {
            label[0] = 0;
            continue;
        }
        count++;
    }
    return count;
}
