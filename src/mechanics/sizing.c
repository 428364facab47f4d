// Quasi-static sizing of the hinges and the Lorentz actuation along a fold or a fold sequence
// (SPEC capability 12). At every recorded state of the motion:
//   - the Lorentz moment per ampere of each wire about its own hinge, from the posed wire (its
//     direction and lever arm turn with the panel, so the thesis' cos Θ comes from the pose);
//   - the gravity moment of the panels beyond each hinge about its axis;
//   - the moment each hinge must supply: its fully plastic moment M_p (the thesis' M_req) in
//     the direction it turns, plus what gravity takes away;
//   - hence the current, the power I²R and the current density each wire needs;
//   - and, for the whole mechanism, the common current that folds it by virtual work: the
//     wires' power along the motion's tangent must cover the plastic work of every hinge that
//     turns and the work against gravity (closed loops included).
// The field orientation schedule: with a field of fixed magnitude |B| and the orientation b
// chosen per segment of the motion, a wire needs I = R/(|B| m·b) (R the required moment, m the
// moment per ampere and tesla), so a segment is best served by the b that maximises
// min_i a_i·b over its points a_i = m_i/R_i: the direction of the point of their convex hull
// nearest the origin (minimax duality), found by Wolfe's algorithm. Dynamic programming over the
// segment boundaries then gives the schedule with at most K reorientations that keeps the
// largest current lowest.
#include <stdlib.h>

#include "mechanics_internal.h"

// --- minimum-norm point of a convex hull (Wolfe 1976) ---------------------------------------

// Affine minimum-norm point of the corral points p[S[0..k−1]] (k ≤ 4): y = p_0 + D c with D the
// differences p_i − p_0, (DᵀD) c = −Dᵀp_0; alpha = (1 − Σc, c). False when the points are
// affinely dependent.
static bool affine_min(const ori_v3 *p, const int *S, int k, double *alpha)
{
    if (k == 1) {
        alpha[0] = 1.0;
        return true;
    }
    int m = k - 1;
    ori_v3 p0 = p[S[0]], d[3];
    double a[3][4];
    for (int i = 0; i < m; ++i) d[i] = ori_v3_sub(p[S[i + 1]], p0);
    double scale = 0.0;
    for (int i = 0; i < m; ++i) {
        for (int j = 0; j < m; ++j) a[i][j] = ori_v3_dot(d[i], d[j]);
        a[i][m] = -ori_v3_dot(d[i], p0);
        scale = fmax(scale, a[i][i]);
    }
    for (int c = 0; c < m; ++c) {
        int piv = c;
        for (int r = c + 1; r < m; ++r)
            if (fabs(a[r][c]) > fabs(a[piv][c])) piv = r;
        if (!(fabs(a[piv][c]) > ORI_ACT_MINNORM_TOL * scale)) return false;
        for (int j = 0; j <= m; ++j) {
            double t = a[c][j];
            a[c][j] = a[piv][j];
            a[piv][j] = t;
        }
        for (int r = 0; r < m; ++r) {
            if (r == c) continue;
            double f = a[r][c] / a[c][c];
            for (int j = c; j <= m; ++j) a[r][j] -= f * a[c][j];
        }
    }
    double sum = 0.0;
    for (int i = 0; i < m; ++i) {
        alpha[i + 1] = a[i][m] / a[i][i];
        sum += alpha[i + 1];
    }
    alpha[0] = 1.0 - sum;
    return true;
}

static ori_v3 combination(const ori_v3 *p, const int *S, const double *w, int k)
{
    ori_v3 x = ori_v3_make(0, 0, 0);
    for (int i = 0; i < k; ++i) x = ori_v3_add(x, ori_v3_scale(p[S[i]], w[i]));
    return x;
}

ori_v3 ori__min_norm_point(const ori_v3 *p, int n)
{
    ori_v3 zero = ori_v3_make(0, 0, 0);
    if (n <= 0) return zero;
    double big = 0.0;
    int best = 0;
    for (int i = 0; i < n; ++i) {
        double d = ori_v3_dot(p[i], p[i]);
        big = fmax(big, d);
        if (d < ori_v3_dot(p[best], p[best])) best = i;
    }
    if (big == 0.0) return zero;
    int S[4] = {best}, k = 1;
    double w[4] = {1.0};
    ori_v3 x = p[best];
    for (int major = 0; major < 4 * n + 100; ++major) {
        // Major cycle: the point most in the direction of −x.
        int j = 0;
        double dmin = INFINITY;
        for (int i = 0; i < n; ++i) {
            double d = ori_v3_dot(x, p[i]);
            if (d < dmin) dmin = d, j = i;
        }
        double xx = ori_v3_dot(x, x);
        if (xx - dmin <= ORI_ACT_MINNORM_TOL * big || xx <= ORI_ACT_MINNORM_TOL * ORI_ACT_MINNORM_TOL * big) return x;
        bool in = false;
        for (int i = 0; i < k; ++i) in |= S[i] == j;
        if (in || k == 4) return x; // no progress possible in floating point
        S[k] = j;
        w[k++] = 0.0;
        // Minor cycles: move toward the affine minimiser until it lies inside the corral's hull,
        // dropping the points whose weight reaches zero.
        for (;;) {
            double al[4];
            if (!affine_min(p, S, k, al)) {
                k--; // the new point is affinely dependent: it cannot improve x
                return x;
            }
            bool interior = true;
            for (int i = 0; i < k; ++i) interior &= al[i] > 0.0;
            if (interior) {
                for (int i = 0; i < k; ++i) w[i] = al[i];
                break;
            }
            double th = 1.0;
            int drop = -1;
            for (int i = 0; i < k; ++i)
                if (al[i] <= 0.0 && w[i] - al[i] > 0.0 && w[i] / (w[i] - al[i]) < th) {
                    th = w[i] / (w[i] - al[i]);
                    drop = i;
                }
            int kk = 0;
            for (int i = 0; i < k; ++i) {
                double wi = th * al[i] + (1.0 - th) * w[i];
                if (i == drop || !(wi > 0.0)) continue;
                S[kk] = S[i];
                w[kk++] = wi;
            }
            k = kk;
            if (k == 0) return zero;
        }
        double sw = 0.0;
        for (int i = 0; i < k; ++i) sw += w[i];
        for (int i = 0; i < k; ++i) w[i] /= sw;
        x = combination(p, S, w, k);
    }
    return x;
}

// --- the sizing -----------------------------------------------------------------------------

struct ori_sizing {
    int H, S;
    ori_hinge_sizing *hinges;
    ori_sizing_step *steps; // H × S
    ori_v3 *field;
    double *drive;
    int *drive_edge;
    int nsched;
    ori_field_change sched[ORI_SCHEDULE_MAX];
    ori_sizing_summary sum;
};

ori_sizing_def ori_default_sizing_def(void)
{
    ori_sizing_def d;
    memset(&d, 0, sizeof d);
    d.driven_edge = ORI_NULL_INDEX;
    d.schedule = ORI_SCHEDULE_AUTO;
    d.reorientations = -1;
    d.internal_value = ORI__DEF_COOKIE;
    return d;
}

void ori_sizing_destroy(ori_sizing *z)
{
    if (!z) return;
    ori__free(z->hinges);
    ori__free(z->steps);
    ori__free(z->field);
    ori__free(z->drive);
    ori__free(z->drive_edge);
    ori__free(z);
}

// Per-frame data gathered in the first pass.
typedef struct sz_frame {
    const double *angles;
    int fold, fixed, edge;
    double drive;
    ori_rigid pose;
} sz_frame;

typedef struct sz_ctx {
    const ori_sizing_def *def;
    const ori_design *d;
    const ori_mechanism *m;
    int E, F, S, H, W;
    sz_frame *fr;
    int *hedge;        // edge of hinge h
    int *hwire;        // wire index of hinge h, or −1
    int *wface;        // face of wire w
    int *wh;           // hinge of wire w
    hinge_section *sec;
    // per hinge × frame
    double *rate, *grav;
    ori_v3 *mvec;      // moment per ampere and tesla (wired hinges only)
    // per wire × frame: power per ampere and tesla along the tangent
    ori_v3 *pvec;
    double *res;       // per frame: plastic + gravity work rate the wires must supply
    double bmag;
    bool mech_points;  // the segments' points include the mechanism's virtual-work requirement
    int *sigma;        // polarity per wire
    double *A, *G2;    // scratch
} sz_ctx;

static int sgn(double x) { return (x > 0) - (x < 0); }

// Frames of the motion.
static ori_status gather(sz_ctx *c, ori_error *error)
{
    const ori_sizing_def *def = c->def;
    if (def->motion) {
        if (ori_motion_verdict_of(def->motion) != ORI_MOTION_VALID)
            return ori__fail(error, ORI_ERR_ARGUMENT, "the fold is not valid (%s): nothing to size",
                             ori_motion_verdict_name(ori_motion_verdict_of(def->motion)));
        if (def->driven_edge < 0 || def->driven_edge >= c->E)
            return ori__fail(error, ORI_ERR_ARGUMENT, "the sizing of a fold needs its driven crease");
        c->S = ori_motion_frame_count(def->motion);
        c->fr = ori__calloc((size_t)c->S + 1, sizeof(sz_frame));
        for (int f = 0; f < c->S; ++f) {
            sz_frame *x = &c->fr[f];
            x->angles = ori_motion_frame_angles(def->motion, f);
            x->fold = 0;
            x->fixed = ori_motion_fixed_face(def->motion);
            x->pose = ori_motion_fixed_pose(def->motion);
            x->edge = def->driven_edge;
            x->drive = ori_motion_frame_drive(def->motion, f);
        }
    } else {
        if (ori_record_verdict(def->record) != ORI_MOTION_VALID)
            return ori__fail(error, ORI_ERR_ARGUMENT, "fold %d of the sequence is not valid (%s): nothing to size",
                             ori_record_failed_fold(def->record) + 1, ori_motion_verdict_name(ori_record_verdict(def->record)));
        c->S = ori_record_frame_count(def->record);
        c->fr = ori__calloc((size_t)c->S + 1, sizeof(sz_frame));
        for (int f = 0; f < c->S; ++f) {
            sz_frame *x = &c->fr[f];
            x->angles = ori_record_frame_angles(def->record, f);
            x->fold = ori_record_frame_fold(def->record, f);
            ori_sequence_fold sf = ori_sequence_fold_at(def->sequence, x->fold);
            x->fixed = sf.fixed_face;
            x->edge = sf.driven_edge;
            x->drive = ori_record_frame_drive(def->record, f);
            ori_status st = ori_mechanism_face_pose_from_coords(c->m, x->fixed, ori_record_frame_vertices(def->record, f),
                                                                &x->pose, error);
            if (st != ORI_OK) return st;
        }
    }
    if (c->S < 2) return ori__fail(error, ORI_ERR_ARGUMENT, "the motion has a single state: nothing moves");
    for (int f = 0; f < c->S; ++f) {
        int e = c->fr[f].edge;
        if (!c->d->has_hinge[e])
            return ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_orikin:hinge", e,
                                "crease %d is driven (actuated) but has no hinge data", e);
    }
    return ORI_OK;
}

// Tangents dθ/dτ of every frame (τ: progress of the driven crease toward its target), for each
// fold: the exact solution of Φ_θ θ' = 0 with the driven rate ±1 and the creases that do not
// move in the fold held, where it agrees with the finite difference of the recorded states;
// the finite difference at singular states (where the exact tangent is not unique).
static void tangents(sz_ctx *c, const mech_loops *L, double *tan)
{
    int S = c->S, E = c->E;
    double *jac = ori__alloc(sizeof(double) * 6 * (size_t)(L->count ? L->first[L->count - 1] + L->size[L->count - 1] + 1 : 1));
    double *fd = ori__alloc(sizeof(double) * (size_t)(E + 1));
    int *col = ori__alloc(sizeof(int) * (size_t)(E + 1));
    double *b = ori__alloc(sizeof(double) * (size_t)(E + 1)), *x = ori__alloc(sizeof(double) * (size_t)(E + 1));
    double *r = ori__alloc(sizeof(double) * (size_t)(L->rows + 1));
    for (int f0 = 0; f0 < S;) {
        int f1 = f0;
        while (f1 + 1 < S && c->fr[f1 + 1].fold == c->fr[f0].fold) f1++;
        // A fold's first recorded state is also the previous fold's last: extend back by one.
        int a = f0 > 0 ? f0 - 1 : f0;
        int drv = c->fr[f0].edge;
        // Progress is measured on the driven crease's own angle (the drive of the state before the
        // fold is another crease's).
        int dir = sgn(c->fr[f1].angles[drv] - c->fr[a].angles[drv]);
        int n = 0;
        for (int e = 0; e < E; ++e) {
            col[e] = -1;
            if (e == drv) continue;
            int j = ori_mechanism_edge_joint(c->m, e);
            if (j == ORI_NULL_INDEX || ori_mechanism_joint(c->m, j).kind != ORI_JOINT_REVOLUTE) continue;
            bool moves = false;
            for (int f = a + 1; f <= f1 && !moves; ++f) moves = c->fr[f].angles[e] != c->fr[a].angles[e];
            if (moves) col[e] = n++;
        }
        int pairs = 0, cap = 16;
        int *pi = ori__alloc(sizeof(int) * (size_t)cap), *pj = ori__alloc(sizeof(int) * (size_t)cap);
        for (int k = 0; k < L->count; ++k)
            for (int i = L->first[k]; i < L->first[k] + L->size[k]; ++i)
                for (int j = L->first[k]; j < L->first[k] + L->size[k]; ++j) {
                    int ci = col[L->edge[i]], cj = col[L->edge[j]];
                    if (ci < 0 || cj < ci) continue;
                    if (pairs == cap) {
                        cap *= 2;
                        pi = ori__realloc(pi, sizeof(int) * (size_t)cap);
                        pj = ori__realloc(pj, sizeof(int) * (size_t)cap);
                    }
                    pi[pairs] = ci;
                    pj[pairs++] = cj;
                }
        mech_spd *spd = n ? ori__spd_create(n, pairs, pi, pj) : NULL;
        ori__free(pi);
        ori__free(pj);
        for (int f = f0; f <= f1; ++f) {
            double *t = tan + (size_t)f * (size_t)E;
            // Finite difference over the neighbouring states of the same fold.
            int lo = f > a ? f - 1 : f, hi = f < f1 ? f + 1 : f;
            double ds = fabs(c->fr[hi].angles[drv] - c->fr[lo].angles[drv]);
            for (int e = 0; e < E; ++e) fd[e] = ds > 0 ? (c->fr[hi].angles[e] - c->fr[lo].angles[e]) / ds : 0.0;
            for (int e = 0; e < E; ++e) t[e] = col[e] >= 0 ? fd[e] : 0.0;
            t[drv] = dir;
            if (!n) continue;
            // Normal equations (Φ_Uᵀ Φ_U + μI) x = −Φ_Uᵀ Φ_d·dir.
            ori__loops_jacobian(L, c->fr[f].angles, NULL, jac, NULL);
            ori__spd_zero(spd);
            for (int i = 0; i < n; ++i) b[i] = 0.0;
            double diag = 0.0;
            for (int k = 0; k < L->count; ++k) {
                int nr = L->nrows[k];
                for (int i = L->first[k]; i < L->first[k] + L->size[k]; ++i) {
                    int ci = col[L->edge[i]];
                    if (ci < 0) continue;
                    for (int j = L->first[k]; j < L->first[k] + L->size[k]; ++j) {
                        int cj = col[L->edge[j]];
                        double dot = 0.0;
                        for (int q = 0; q < nr; ++q) dot += jac[6 * (size_t)i + q] * jac[6 * (size_t)j + q];
                        if (L->edge[j] == drv) b[ci] -= dot * dir;
                        if (cj < ci) continue;
                        ori__spd_add(spd, ci, cj, dot);
                        if (ci == cj) diag = fmax(diag, dot);
                    }
                }
            }
            for (int i = 0; i < n; ++i) ori__spd_add(spd, i, i, ORI_ACT_TANGENT_SHIFT * (diag > 0 ? diag : 1.0));
            if (!ori__spd_factor(spd) || !ori__spd_solve(spd, b, x)) continue;
            // Residual of the tangent equations and agreement with the finite difference.
            for (int k = 0; k < L->rows; ++k) r[k] = 0.0;
            for (int k = 0; k < L->count; ++k)
                for (int i = L->first[k]; i < L->first[k] + L->size[k]; ++i) {
                    int e = L->edge[i];
                    double v = e == drv ? dir : col[e] >= 0 ? x[col[e]] : 0.0;
                    for (int q = 0; q < L->nrows[k]; ++q) r[L->row0[k] + q] += jac[6 * (size_t)i + q] * v;
                }
            double rn = 0.0, dot = 0.0, nx = 0.0, nf = 0.0;
            for (int k = 0; k < L->rows; ++k) rn = fmax(rn, fabs(r[k]));
            for (int e = 0; e < E; ++e)
                if (col[e] >= 0) {
                    dot += x[col[e]] * fd[e];
                    nx += x[col[e]] * x[col[e]];
                    nf += fd[e] * fd[e];
                }
            bool agree = nf == 0.0 || dot >= ORI_ACT_TANGENT_AGREE * sqrt(nx * nf);
            if (rn <= ORI_ACT_TANGENT_RESIDUAL && agree)
                for (int e = 0; e < E; ++e)
                    if (col[e] >= 0) t[e] = x[col[e]];
        }
        ori__spd_destroy(spd);
        f0 = f1 + 1;
    }
    ori__free(jac);
    ori__free(fd);
    ori__free(col);
    ori__free(b);
    ori__free(x);
    ori__free(r);
}

// First pass: per frame, the poses, gravity moments, Lorentz moments per ampere and tesla, the
// tangent, and the work rates.
static ori_status measure(sz_ctx *c, ori_error *error)
{
    const ori_design *d = c->d;
    int S = c->S, E = c->E, F = c->F, H = c->H;
    mech_loops L;
    ori__loops_init(&L, c->m, d->diagonal);
    double *tan = ori__calloc((size_t)S * (size_t)E + 1, sizeof(double));
    tangents(c, &L, tan);
    ori__loops_free(&L);
    mech_tree t;
    memset(&t, 0, sizeof t);
    int tree_fixed = ORI_NULL_INDEX;
    ori_rigid *poses = ori__alloc(sizeof(ori_rigid) * (size_t)(F + 1));
    body_inertia *sub = ori__alloc(sizeof(body_inertia) * (size_t)(F + 1));
    sv6 *V = ori__alloc(sizeof(sv6) * (size_t)(F + 1));
    ori_v3 ex[3] = {ori_v3_make(1, 0, 0), ori_v3_make(0, 1, 0), ori_v3_make(0, 0, 1)};
    ori_v3 g = d->act.gravity_m_s2;
    double mpu = d->meters_per_unit;
    ori_status st = ORI_OK;
    for (int f = 0; f < S; ++f) {
        const sz_frame *x = &c->fr[f];
        if (x->fixed != tree_fixed) {
            ori__tree_free(&t);
            ori__tree_init(&t, c->m, x->fixed);
            tree_fixed = x->fixed;
        }
        ori__tree_poses(&t, x->angles, x->pose, poses);
        for (int k = 0; k < F; ++k) sub[k] = ori__body_world(&d->mass[k], poses[k], mpu);
        for (int k = F - 1; k >= 0; --k) {
            int a = t.order[k];
            if (t.parent[a] != ORI_NULL_INDEX) ori__body_add(&sub[t.parent[a]], &sub[a]);
        }
        // Face twists along the tangent, and the gravity power.
        const double *th = tan + (size_t)f * (size_t)E;
        double gpow = 0.0;
        for (int k = 0; k < F; ++k) {
            int a = t.order[k], p = t.parent[a];
            if (p == ORI_NULL_INDEX) {
                V[a] = sv6_zero();
                continue;
            }
            int e = t.pedge[a];
            V[a] = V[p];
            if (t.col_of_edge[e] >= 0 && th[e] != 0.0) V[a] = sv6_add(V[p], sv6_scale(ori__tree_twist(&t, a, poses, mpu), th[e]));
            body_inertia b = ori__body_world(&d->mass[a], poses[a], mpu);
            ori_v3 fg = ori_v3_scale(g, b.m);
            gpow += ori_v3_dot(fg, V[a].v) + ori_v3_dot(ori_v3_cross(b.h, g), V[a].w);
        }
        double plastic = 0.0;
        for (int h = 0; h < H; ++h) {
            int e = c->hedge[h];
            size_t i = (size_t)h * (size_t)S + (size_t)f;
            c->rate[i] = th[e];
            if (fabs(th[e]) > ORI_ACT_RATE_MIN) plastic += c->sec[h].m_p * fabs(th[e]);
            // Gravity of the panels beyond the hinge, about its axis (positive = valley).
            int fa = d->edge_faces[e][0], fb = d->edge_faces[e][1];
            int D = t.depth[fa] >= t.depth[fb] ? fa : fb;
            ori_v3 q = ori_v3_scale(ori_rigid_apply(poses[D], d->vertices[d->edges[e][0]]), mpu);
            ori_v3 w = ori_v3_normalize(ori_rigid_apply_dir(poses[D], ori_v3_sub(d->vertices[d->edges[e][1]], d->vertices[d->edges[e][0]])));
            ori_v3 lever = ori_v3_sub(sub[D].h, ori_v3_scale(q, sub[D].m));
            double gm = ori_v3_dot(w, ori_v3_cross(lever, g));
            c->grav[i] = D == fa ? gm : -gm;
            int wi = c->hwire[h];
            if (wi < 0) continue;
            int wf = c->wface[wi];
            c->mvec[i] = ori_v3_make(ori__wire_moment(d, e, wf, poses, 1.0, ex[0]), ori__wire_moment(d, e, wf, poses, 1.0, ex[1]),
                                     ori__wire_moment(d, e, wf, poses, 1.0, ex[2]));
            wire_segments ws;
            ori__wire_segments(d, e, wf, &ws);
            double pw[3];
            for (int k = 0; k < 3; ++k) {
                ori_v3 fo, mo, fc, mc;
                ori__wire_wrench(d, &ws, 0, 3, poses[wf], 1.0, ex[k], &fo, &mo);
                ori__wire_wrench(d, &ws, 3, 4, poses[ws.other], 1.0, ex[k], &fc, &mc);
                pw[k] = sv6_dot(sv6_make(fo, mo), V[wf]) + sv6_dot(sv6_make(fc, mc), V[ws.other]);
            }
            c->pvec[(size_t)wi * (size_t)S + (size_t)f] = ori_v3_make(pw[0], pw[1], pw[2]);
        }
        c->res[f] = plastic - gpow;
        if (c->def->progress && !c->def->progress(0.8 * (double)(f + 1) / (double)S, c->def->progress_user)) {
            st = ori__fail(error, ORI_ERR_LIMIT, "cancelled");
            break;
        }
    }
    ori__tree_free(&t);
    ori__free(tan);
    ori__free(poses);
    ori__free(sub);
    ori__free(V);
    return st;
}

// Moment a hinge's wire must supply at a frame where the hinge turns: M_p in the direction it
// turns, minus what gravity contributes. A hinge that does not turn holds its panels
// elastically (gravity_ratio says whether it can) and needs no current.
static double required(const sz_ctx *c, int h, int f, double m_p)
{
    size_t i = (size_t)h * (size_t)c->S + (size_t)f;
    double r = c->rate[i];
    if (!(fabs(r) > ORI_ACT_RATE_MIN)) return 0.0;
    return (r > 0 ? m_p : -m_p) - c->grav[i];
}

// Points a = σ·m/R of the wired hinges over frames [f0, f1] (those with a requirement), and of
// the mechanism: the wires' common power per ampere and tesla over the work rate they must supply.
static int segment_points(const sz_ctx *c, int f0, int f1, ori_v3 *out)
{
    int k = 0;
    if (c->mech_points)
        for (int f = f0; f <= f1; ++f) {
            if (!(c->res[f] > 0.0)) continue;
            ori_v3 p = ori_v3_make(0, 0, 0);
            for (int w = 0; w < c->W; ++w) p = ori_v3_add(p, ori_v3_scale(c->pvec[(size_t)w * (size_t)c->S + (size_t)f], c->sigma[w]));
            out[k++] = ori_v3_scale(p, 1.0 / c->res[f]);
        }
    for (int w = 0; w < c->W; ++w) {
        int h = c->wh[w];
        if (!c->sigma[w]) continue; // left out (choosing polarities one wire at a time)
        for (int f = f0; f <= f1; ++f) {
            double R = required(c, h, f, c->sec[h].m_p);
            if (fabs(R) <= ORI_ACT_RATE_MIN * c->sec[h].m_p) continue;
            out[k++] = ori_v3_scale(c->mvec[(size_t)h * (size_t)c->S + (size_t)f], (double)c->sigma[w] / R);
        }
    }
    return k;
}

// Best orientation of a segment: value = |min-norm point| (INFINITY with no requirement).
static double segment_value(const sz_ctx *c, int f0, int f1, ori_v3 *pts, ori_v3 *dir)
{
    int k = segment_points(c, f0, f1, pts);
    if (k == 0) {
        *dir = ori_v3_make(0, 0, 0);
        return INFINITY;
    }
    ori_v3 x = ori__min_norm_point(pts, k);
    *dir = ori_v3_normalize(x);
    return ori_v3_norm(x);
}

// Polarity of each wire: its own best direction over the whole motion, aligned with that of
// the hardest wire (a single wire is +1: flipping the current is flipping the field).
static void choose_polarity(sz_ctx *c, ori_v3 *pts)
{
    ori_v3 *own = ori__alloc(sizeof(ori_v3) * (size_t)(c->W + 1));
    double *val = ori__alloc(sizeof(double) * (size_t)(c->W + 1));
    int hardest = 0;
    for (int w = 0; w < c->W; ++w) c->sigma[w] = 0;
    for (int w = 0; w < c->W; ++w) {
        for (int v = 0; v < c->W; ++v) c->sigma[v] = v == w ? 1 : 0;
        val[w] = segment_value(c, 0, c->S - 1, pts, &own[w]);
        if (val[w] < val[hardest]) hardest = w;
    }
    for (int w = 0; w < c->W; ++w) c->sigma[w] = ori_v3_dot(own[w], own[hardest]) < 0.0 ? -1 : 1;
    ori__free(own);
    ori__free(val);
}

// Dynamic programming over segment boundaries: at most K reorientations, maximising the
// smallest segment value (= minimising the largest current); fewer segments on ties.
static void optimize_schedule(sz_ctx *c, int K, ori_sizing *z, ori_v3 *pts)
{
    int S = c->S;
    if (K > S - 1) K = S - 1;
    double *val = ori__alloc(sizeof(double) * (size_t)S * (size_t)S);
    ori_v3 *dir = ori__alloc(sizeof(ori_v3) * (size_t)S * (size_t)S);
    for (int i = 0; i < S; ++i)
        for (int j = i; j < S; ++j) val[(size_t)i * S + j] = segment_value(c, i, j, pts, &dir[(size_t)i * S + j]);
    // best[k][j]: the best value for frames 0..j in k + 1 segments; from[k][j]: start of the last.
    double *best = ori__alloc(sizeof(double) * (size_t)(K + 1) * (size_t)S);
    int *from = ori__alloc(sizeof(int) * (size_t)(K + 1) * (size_t)S);
    for (int j = 0; j < S; ++j) {
        best[j] = val[j];
        from[j] = 0;
    }
    for (int k = 1; k <= K; ++k)
        for (int j = 0; j < S; ++j) {
            double b = best[(size_t)(k - 1) * S + j];
            int fr = -1;
            for (int i = 1; i <= j; ++i) {
                double v = fmin(best[(size_t)(k - 1) * S + i - 1], val[(size_t)i * S + j]);
                if (v > b) b = v, fr = i;
            }
            best[(size_t)k * S + j] = b;
            from[(size_t)k * S + j] = fr;
        }
    int k = K;
    while (k > 0 && !(best[(size_t)k * S + S - 1] > best[(size_t)(k - 1) * S + S - 1])) k--;
    int starts[ORI_SCHEDULE_MAX + 1], ns = 0, j = S - 1;
    for (int kk = k; kk >= 0; --kk) {
        int i = kk == 0 ? 0 : from[(size_t)kk * S + j];
        if (i < 0) continue; // this level kept the previous segmentation
        starts[ns++] = i;
        j = i - 1;
        if (j < 0) break;
    }
    if (ns == 0 || starts[ns - 1] != 0) starts[ns++] = 0;
    ori_v3 prev = c->d->act.has_field ? ori_v3_normalize(c->d->act.field_t) : ori_v3_make(1, 0, 0);
    z->nsched = 0;
    for (int s = ns - 1; s >= 0 && z->nsched < ORI_SCHEDULE_MAX; --s) {
        int i = starts[s], e = s > 0 ? starts[s - 1] - 1 : S - 1;
        ori_v3 dv = dir[(size_t)i * S + e];
        if (ori_v3_norm(dv) == 0.0) dv = prev;
        prev = dv;
        ori_field_change *fc = &z->sched[z->nsched++];
        fc->edge = c->fr[i].edge;
        fc->fold = c->fr[i].fold;
        // At the first state of a fold the change is due when the fold starts: at the driven
        // crease's angle in the state before.
        fc->from_rad = i > 0 && c->fr[i - 1].fold != fc->fold ? c->fr[i - 1].angles[fc->edge] : c->fr[i].drive;
        fc->field_t = ori_v3_scale(dv, c->bmag);
        for (int f = i; f <= e; ++f) z->field[f] = fc->field_t;
    }
    ori__free(val);
    ori__free(dir);
    ori__free(best);
    ori__free(from);
}

// The design's schedule (or its field alone) replayed along the motion: an entry takes over
// once its crease passes its angle in the direction that crease moves over the motion.
static void design_schedule(sz_ctx *c, ori_sizing *z, bool fixed)
{
    const ori_actuation *a = &c->d->act;
    z->nsched = 0;
    if (fixed || a->schedule_count == 0) {
        ori_field_change fc = {c->fr[0].edge, c->fr[0].drive, a->has_field ? a->field_t : a->schedule[0].field_t, 0};
        z->sched[z->nsched++] = fc;
        for (int f = 0; f < c->S; ++f) z->field[f] = fc.field_t;
        return;
    }
    for (int i = 0; i < a->schedule_count; ++i) {
        z->sched[i] = a->schedule[i];
        if (z->sched[i].edge == ORI_NULL_INDEX)
            z->sched[i].edge = a->reference_edge != ORI_NULL_INDEX ? a->reference_edge : c->fr[0].edge;
    }
    z->nsched = a->schedule_count;
    int next = 1;
    ori_v3 B = z->sched[0].field_t;
    for (int f = 0; f < c->S; ++f) {
        while (next < z->nsched) {
            const ori_field_change *fc = &z->sched[next];
            if (c->fr[f].fold < fc->fold) break;
            int e = fc->edge;
            double first = c->fr[0].angles[e], last = c->fr[c->S - 1].angles[e];
            int dir = sgn(last - first);
            if (!dir) dir = sgn(fc->from_rad - first);
            if (c->fr[f].fold == fc->fold && (c->fr[f].angles[e] - fc->from_rad) * dir < -ORI_TOL_FOLD_SIGN_RAD) break;
            B = fc->field_t;
            next++;
        }
        z->field[f] = B;
    }
}

// Margin of hinge h at frame f for wire current capability imax and plastic moment m_p, in the
// direction the hinge must be driven: imax·(moment per ampere that way) − |requirement|.
static double margin_at(const sz_ctx *c, const ori_sizing *z, int h, int f, double imax, double m_p)
{
    size_t i = (size_t)h * (size_t)c->S + (size_t)f;
    double R = required(c, h, f, m_p);
    if (fabs(R) <= ORI_ACT_RATE_MIN * m_p) return INFINITY;
    double per_amp = (double)c->sigma[c->hwire[h]] * ori_v3_dot(c->mvec[i], z->field[f]);
    return imax * per_amp * (R > 0 ? 1.0 : -1.0) - fabs(R);
}

static double min_margin(const sz_ctx *c, const ori_sizing *z, int h, double imax, double m_p)
{
    double m = INFINITY;
    for (int f = 0; f < c->S; ++f) m = fmin(m, margin_at(c, z, h, f, imax, m_p));
    return m;
}

// Golden-section maximum of a concave function on [lo, hi].
typedef double (*concave_fn)(const sz_ctx *, const ori_sizing *, int, double);
static double golden_max(concave_fn fn, const sz_ctx *c, const ori_sizing *z, int h, double lo, double hi)
{
    const double r = 0.5 * (sqrt(5.0) - 1.0);
    double a = lo, b = hi, x1 = b - r * (b - a), x2 = a + r * (b - a);
    double f1 = fn(c, z, h, x1), f2 = fn(c, z, h, x2);
    for (int it = 0; it < 300 && (b - a) > ORI_ACT_THICKNESS_TOL * hi; ++it) {
        if (f1 < f2) {
            a = x1, x1 = x2, f1 = f2;
            x2 = a + r * (b - a);
            f2 = fn(c, z, h, x2);
        } else {
            b = x2, x2 = x1, f2 = f1;
            x1 = b - r * (b - a);
            f1 = fn(c, z, h, x1);
        }
    }
    return 0.5 * (a + b);
}

// The conductor's current capability and the hinge's plastic moment for thickness t or width w.
static void hinge_scaled(const sz_ctx *c, int h, double w, double t, double *imax, double *m_p, double *m_y)
{
    const ori_hinge *hg = &c->d->hinges[c->hedge[h]];
    const ori_material *mat = ori__materials_get(c->d->materials, hg->material);
    bool same_w = hg->wire.width_m == hg->width_m, same_t = hg->wire.thickness_m == hg->thickness_m;
    double ww = same_w ? w : hg->wire.width_m, wt = same_t ? t : hg->wire.thickness_m;
    double area = fmin(w * t, ww * wt);
    const ori_actuation *a = &c->d->act;
    *imax = INFINITY;
    if (a->has_current_limit) *imax = a->current_limit_a;
    if (mat->has_current_density_max) *imax = fmin(*imax, mat->current_density_max_a_m2 * area);
    *m_p = ori_hinge_plastic_moment(mat->yield_strength_pa, w, t);
    if (m_y) *m_y = ori_hinge_yield_moment(mat->yield_strength_pa, w, t);
}

static double margin_of_thickness(const sz_ctx *c, const ori_sizing *z, int h, double t)
{
    double imax, mp;
    hinge_scaled(c, h, c->d->hinges[c->hedge[h]].width_m, t, &imax, &mp, NULL);
    return min_margin(c, z, h, imax, mp);
}

static double margin_of_width(const sz_ctx *c, const ori_sizing *z, int h, double w)
{
    double imax, mp;
    hinge_scaled(c, h, w, c->d->hinges[c->hedge[h]].thickness_m, &imax, &mp, NULL);
    return min_margin(c, z, h, imax, mp);
}

// Root of a monotone function between a (sign sa) and b by bisection.
static double bisect(concave_fn fn, const sz_ctx *c, const ori_sizing *z, int h, double a, double b)
{
    double fa = fn(c, z, h, a);
    for (int it = 0; it < 200 && fabs(b - a) > ORI_ACT_THICKNESS_TOL * fmax(fabs(a), fabs(b)); ++it) {
        double m = 0.5 * (a + b), fm = fn(c, z, h, m);
        if ((fm >= 0) == (fa >= 0)) a = m, fa = fm;
        else b = m;
    }
    return 0.5 * (a + b);
}

// Optimal thickness and width range of a wired hinge (the schedule held fixed).
static void design_limits(const sz_ctx *c, const ori_sizing *z, int h, ori_hinge_sizing *hs)
{
    const ori_hinge *hg = &c->d->hinges[c->hedge[h]];
    const ori_material *mat = ori__materials_get(c->d->materials, hg->material);
    const ori_actuation *a = &c->d->act;
    double amax = 0.0, gmax = 0.0;
    for (int f = 0; f < c->S; ++f) {
        size_t i = (size_t)h * (size_t)c->S + (size_t)f;
        amax = fmax(amax, fabs(ori_v3_dot(c->mvec[i], z->field[f])));
        gmax = fmax(gmax, fabs(c->grav[i]));
    }
    // Thickness: the margin grows with t while the film's current-density limit caps the current,
    // and falls once the supply's limit does (M_p ∝ t²); without a density limit the thinnest hinge wins.
    if (mat->has_current_density_max && amax > 0.0) {
        double w = hg->width_m, sy = mat->yield_strength_pa, j = mat->current_density_max_a_m2;
        double t_hi = 4.0 * j * amax / sy;
        if (a->has_current_limit) t_hi = fmax(t_hi, 2.0 * a->current_limit_a / (j * fmin(w, hg->wire.width_m)));
        hs->optimal_thickness_m = golden_max(margin_of_thickness, c, z, h, 0.0, t_hi);
        hs->has_optimal_thickness = true;
    }
    // Width: [latching against gravity, folding within the limit].
    if (a->has_current_limit && amax > 0.0) {
        double t = hg->thickness_m, imax0, mp1, my1;
        hinge_scaled(c, h, 1.0, t, &imax0, &mp1, &my1); // per metre of width
        double w_hi = 4.0 * (a->current_limit_a * amax + gmax) / mp1 + hg->width_m;
        double w_best = golden_max(margin_of_width, c, z, h, 0.0, w_hi);
        if (margin_of_width(c, z, h, w_best) >= 0.0) {
            double lo = margin_of_width(c, z, h, 0.0) >= 0.0 ? 0.0 : bisect(margin_of_width, c, z, h, 0.0, w_best);
            double hi = margin_of_width(c, z, h, w_hi) >= 0.0 ? w_hi : bisect(margin_of_width, c, z, h, w_best, w_hi);
            double latch = gmax / my1; // M_y(w) ≥ the largest gravity moment: the fold holds when the current stops
            lo = fmax(lo, latch);
            if (lo <= hi) {
                hs->has_width_range = true;
                hs->width_min_m = lo;
                hs->width_max_m = hi;
            }
        }
    }
}

ori_status ori_sizing_solve(const ori_sizing_def *def, ori_sizing **out, ori_error *error)
{
    ORI_ASSERT(def && out && def->internal_value == ORI__DEF_COOKIE && def->design && def->mechanism);
    *out = NULL;
    if (!def->motion == !def->record || (def->record && !def->sequence))
        return ori__fail(error, ORI_ERR_ARGUMENT, "size either a fold (motion) or a sequence run (record and sequence)");
    if (def->reorientations > ORI_SCHEDULE_MAX - 1)
        return ori__fail(error, ORI_ERR_RANGE, "reorientations: 0 to %d", ORI_SCHEDULE_MAX - 1);
    const ori_design *d = def->design;
    sz_ctx c;
    memset(&c, 0, sizeof c);
    c.def = def;
    c.d = d;
    c.m = def->mechanism;
    c.E = ori_mechanism_edge_count(c.m);
    c.F = ori_mechanism_face_count(c.m);
    if (c.E != d->edge_count || c.F != d->face_count)
        return ori__fail(error, ORI_ERR_ARGUMENT, "the design and the mechanism are not of the same pattern");
    ori_sizing *z = NULL;
    ori_v3 *pts = NULL;
    ori_status st = gather(&c, error);
    if (st != ORI_OK) goto done;
    const ori_actuation *a = &d->act;
    if (!a->has_field && a->schedule_count == 0) {
        st = ori__fail_at(error, ORI_ERR_ARGUMENT, "orikin:actuation", ORI_NULL_INDEX, "field: no magnetic field given");
        goto done;
    }
    c.bmag = ori_v3_norm(a->has_field ? a->field_t : a->schedule[0].field_t);
    // Hinges (edges with hinge data that are free creases) and their wires.
    int E = c.E, S = c.S;
    c.hedge = ori__alloc(sizeof(int) * (size_t)(E + 1));
    c.hwire = ori__alloc(sizeof(int) * (size_t)(E + 1));
    c.wface = ori__alloc(sizeof(int) * (size_t)(E + 1));
    c.wh = ori__alloc(sizeof(int) * (size_t)(E + 1));
    c.sigma = ori__alloc(sizeof(int) * (size_t)(E + 1));
    c.sec = ori__alloc(sizeof(hinge_section) * (size_t)(E + 1));
    for (int e = 0; e < E; ++e) {
        int j = ori_mechanism_edge_joint(c.m, e);
        if (!d->has_hinge[e] || j == ORI_NULL_INDEX || ori_mechanism_joint(c.m, j).kind != ORI_JOINT_REVOLUTE) continue;
        int h = c.H++;
        c.hedge[h] = e;
        c.hwire[h] = -1;
        ori__design_section(d, e, &c.sec[h]);
        if (!d->hinges[e].has_wire) continue;
        int w = c.W++;
        c.hwire[h] = w;
        c.wh[w] = h;
        c.sigma[w] = 1;
        c.wface[w] = ori_design_wire_face(d, c.m, e, c.fr[0].fixed);
        wire_segments ws;
        if (!ori__wire_segments(d, e, c.wface[w], &ws)) {
            st = ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_orikin:hinge", e,
                              "the wire lies outside face %d, the panel that moves", c.wface[w]);
            goto done;
        }
    }
    if (c.W == 0) {
        st = ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_orikin:hinge", ORI_NULL_INDEX,
                          "no hinge has a wire: nothing actuates the fold");
        goto done;
    }
    size_t HS = (size_t)c.H * (size_t)S + 1;
    c.rate = ori__calloc(HS, sizeof(double));
    c.grav = ori__calloc(HS, sizeof(double));
    c.mvec = ori__calloc(HS, sizeof(ori_v3));
    c.pvec = ori__calloc((size_t)c.W * (size_t)S + 1, sizeof(ori_v3));
    c.res = ori__calloc((size_t)S + 1, sizeof(double));
    if ((st = measure(&c, error)) != ORI_OK) goto done;

    z = ori__calloc(1, sizeof *z);
    z->H = c.H;
    z->S = S;
    z->hinges = ori__calloc((size_t)c.H + 1, sizeof(ori_hinge_sizing));
    z->steps = ori__calloc(HS, sizeof(ori_sizing_step));
    z->field = ori__calloc((size_t)S + 1, sizeof(ori_v3));
    z->drive = ori__calloc((size_t)S + 1, sizeof(double));
    z->drive_edge = ori__calloc((size_t)S + 1, sizeof(int));
    for (int f = 0; f < S; ++f) {
        z->drive[f] = c.fr[f].drive;
        z->drive_edge[f] = c.fr[f].edge;
    }
    // The field schedule.
    pts = ori__alloc(sizeof(ori_v3) * ((size_t)(c.W + 1) * (size_t)S + 1));
    ori_schedule_mode mode = def->schedule;
    if (mode == ORI_SCHEDULE_AUTO) mode = a->schedule_count ? ORI_SCHEDULE_DESIGN : ORI_SCHEDULE_OPTIMIZE;
    if (mode == ORI_SCHEDULE_OPTIMIZE) {
        choose_polarity(&c, pts);
        c.mech_points = true;
        int K = def->reorientations;
        if (K < 0) K = c.fr[S - 1].fold + 1 < ORI_SCHEDULE_MAX ? c.fr[S - 1].fold + 1 : ORI_SCHEDULE_MAX - 1;
        optimize_schedule(&c, K, z, pts);
    } else {
        design_schedule(&c, z, mode == ORI_SCHEDULE_FIXED);
    }
    z->sum.optimized = mode == ORI_SCHEDULE_OPTIMIZE;
    z->sum.reorientations = z->nsched - 1;
    // Currents per hinge and frame.
    if (mode != ORI_SCHEDULE_OPTIMIZE)
        for (int w = 0; w < c.W; ++w) {
            // Polarity: the sign of the current the first frame with a requirement asks for.
            int h = c.wh[w];
            for (int f = 0; f < S; ++f) {
                double R = required(&c, h, f, c.sec[h].m_p), P = ori_v3_dot(c.mvec[(size_t)h * S + f], z->field[f]);
                if (fabs(R) > ORI_ACT_RATE_MIN * c.sec[h].m_p && P != 0.0) {
                    c.sigma[w] = R * P > 0 ? 1 : -1;
                    break;
                }
            }
        }
    z->sum.worst_edge = ORI_NULL_INDEX;
    z->sum.feasible = true;
    for (int h = 0; h < c.H; ++h) {
        int e = c.hedge[h], w = c.hwire[h];
        ori_hinge_sizing *hs = &z->hinges[h];
        hs->edge = e;
        ori_design_hinge_mechanics(d, e, &hs->mechanics);
        hs->actuated = w >= 0;
        hs->worst_frame = 0;
        double th0 = c.fr[0].angles[e];
        for (int f = 0; f < S; ++f) {
            size_t i = (size_t)h * (size_t)S + (size_t)f;
            ori_sizing_step *sp = &z->steps[i];
            sp->angle_rad = c.fr[f].angles[e];
            sp->rate = c.rate[i];
            sp->gravity_moment_nm = c.grav[i];
            sp->required_moment_nm = required(&c, h, f, c.sec[h].m_p);
            hs->travel_rad = fmax(hs->travel_rad, fabs(sp->angle_rad - th0));
            hs->gravity_moment_max_nm = fmax(hs->gravity_moment_max_nm, fabs(c.grav[i]));
            if (w < 0) continue;
            double P = ori_v3_dot(c.mvec[i], z->field[f]);
            sp->lorentz_moment_per_amp = P;
            double R = sp->required_moment_nm, I = 0.0;
            if (fabs(R) > ORI_ACT_RATE_MIN * c.sec[h].m_p) {
                I = P != 0.0 ? R / P : (R > 0 ? INFINITY : -INFINITY);
                if (I * c.sigma[w] < 0.0) I = c.sigma[w] * INFINITY; // the field pushes the wrong way
            }
            sp->current_a = I;
            sp->power_w = isfinite(I) ? I * I * hs->mechanics.resistance_ohm : INFINITY;
            sp->current_density_a_m2 = fabs(I) / hs->mechanics.conductor_area_m2;
            if (fabs(I) > fabs(hs->current_needed_a) || f == 0) {
                hs->current_needed_a = fabs(I);
                hs->worst_frame = f;
            }
        }
        double phi = c.fr[S - 1].angles[e] - th0;
        double mend = ori_hinge_monotonic_moment(c.sec[h].k, c.sec[h].m_y, phi);
        hs->springback_rad = fabs(mend) / c.sec[h].k;
        hs->plastic_rotation_rad = phi - mend / c.sec[h].k;
        hs->gravity_ratio = hs->gravity_moment_max_nm / c.sec[h].m_p;
        z->sum.gravity_ratio_max = fmax(z->sum.gravity_ratio_max, hs->gravity_ratio);
        hs->feasible = true;
        if (w < 0) continue;
        hs->power_peak_w = hs->current_needed_a * hs->current_needed_a * hs->mechanics.resistance_ohm;
        hs->current_density_peak_a_m2 = hs->current_needed_a / hs->mechanics.conductor_area_m2;
        hs->feasible = isfinite(hs->current_needed_a) && (!a->has_current_limit || hs->current_needed_a <= a->current_limit_a) &&
                       (!hs->mechanics.has_current_density_max || hs->current_needed_a <= hs->mechanics.current_max_a);
        design_limits(&c, z, h, hs);
        z->sum.feasible &= hs->feasible;
        if (z->sum.worst_edge == ORI_NULL_INDEX || hs->current_needed_a > z->sum.current_needed_a) {
            z->sum.worst_edge = e;
            z->sum.current_needed_a = hs->current_needed_a;
        }
    }
    // The mechanism by virtual work: a common current in every wire (each with its polarity).
    z->sum.mechanism_current_a = 0.0;
    for (int f = 0; f < S; ++f) {
        double drive = 0.0;
        for (int w = 0; w < c.W; ++w) drive += c.sigma[w] * ori_v3_dot(c.pvec[(size_t)w * S + f], z->field[f]);
        double need = c.res[f] <= 0.0 ? 0.0 : drive > 0.0 ? c.res[f] / drive : INFINITY;
        if (need > z->sum.mechanism_current_a || f == 0) {
            z->sum.mechanism_current_a = need;
            z->sum.mechanism_worst_frame = f;
        }
    }
    z->sum.feasible &= isfinite(z->sum.mechanism_current_a) &&
                       (!a->has_current_limit || z->sum.mechanism_current_a <= a->current_limit_a);
    if (def->progress) def->progress(1.0, def->progress_user);
    *out = z;
    z = NULL;
done:
    ori_sizing_destroy(z);
    ori__free(pts);
    ori__free(c.fr);
    ori__free(c.hedge);
    ori__free(c.hwire);
    ori__free(c.wface);
    ori__free(c.wh);
    ori__free(c.sigma);
    ori__free(c.sec);
    ori__free(c.rate);
    ori__free(c.grav);
    ori__free(c.mvec);
    ori__free(c.pvec);
    ori__free(c.res);
    return st;
}

int ori_sizing_hinge_count(const ori_sizing *z) { return z->H; }

ori_hinge_sizing ori_sizing_hinge(const ori_sizing *z, int h)
{
    ORI_ASSERT(z && h >= 0 && h < z->H);
    return z->hinges[h];
}

int ori_sizing_frame_count(const ori_sizing *z) { return z->S; }

ori_sizing_step ori_sizing_step_at(const ori_sizing *z, int h, int f)
{
    ORI_ASSERT(z && h >= 0 && h < z->H && f >= 0 && f < z->S);
    return z->steps[(size_t)h * (size_t)z->S + (size_t)f];
}

ori_v3 ori_sizing_frame_field(const ori_sizing *z, int f)
{
    ORI_ASSERT(z && f >= 0 && f < z->S);
    return z->field[f];
}

double ori_sizing_frame_drive(const ori_sizing *z, int f, int *edge)
{
    ORI_ASSERT(z && f >= 0 && f < z->S);
    if (edge) *edge = z->drive_edge[f];
    return z->drive[f];
}

int ori_sizing_schedule_count(const ori_sizing *z) { return z->nsched; }

ori_field_change ori_sizing_schedule_at(const ori_sizing *z, int i)
{
    ORI_ASSERT(z && i >= 0 && i < z->nsched);
    return z->sched[i];
}

ori_sizing_summary ori_sizing_summary_of(const ori_sizing *z)
{
    ORI_ASSERT(z);
    return z->sum;
}
