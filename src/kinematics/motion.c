// Fold motions: a fold specification (fixed face, locked creases, driven crease and range) is
// solved by the closed-form spherical 4R (single vertex) or by numeric continuation, the branch
// chosen by the MV assignment, and the answer classified (valid / invalid assignment / not
// rigidly foldable / underdetermined / blocked).
//
// Continuation: from an accepted state (s, θ) the predictor extrapolates along the curve's
// tangent dθ/ds (a cubic Hermite extrapolation through the previous state and tangent once one
// exists), the driven crease is set exactly to s + h, and the corrector (solver.c) pulls the
// prediction back onto the loop-closure manifold. A step is rejected, and halved, when the
// corrector fails or moves the prediction by more than half the step (a jump to another
// branch); easy steps (≤ 3 iterations) double the step up to ORI_KIN_MAX_STEP_RAD. Output
// states land exactly on the requested drive values. At a singular start (the flat sheet) the
// tangent comes from the second-order cone analysis (cone.c), which also selects the branch.
#include <math.h>
#include <stdio.h>

#include "kinematics_internal.h"

struct ori_motion {
    const ori_mechanism *m;
    int edge_count;
    int fixed_face;
    ori_rigid fixed_pose;
    int driven_edge;
    ori_motion_verdict verdict;
    char reason[1024];
    ori_crease_violation *viol;
    int nviol;
    int nframes, frame_cap;
    double *drive;
    double *angles; // nframes × edge_count
    double *residual;
    double *alt;    // nframes × edge_count: the other closed-form branch, when has_alt[k]
    bool *has_alt;
    bool has_split;
    ori_vertex_split split;
    ori_v3 *ee_a, *ee_b;
    ori_motion_stats stats;
    int dof;
};

ori_motion_def ori_default_motion_def(void)
{
    ori_motion_def d;
    d.fixed_face = 0;
    d.fixed_pose = ori_rigid_identity();
    d.start_angles_rad = NULL;
    d.driven_edge = ORI_NULL_INDEX;
    d.has_from = false;
    d.from_rad = 0.0;
    d.to_rad = 0.0;
    d.step_rad = ORI_PI / 180.0;
    d.locked_edges = NULL;
    d.locked_count = 0;
    d.solver = ORI_SOLVER_AUTO;
    d.linear = ORI_LINEAR_AUTO;
    d.internal_value = ORI__DEF_COOKIE;
    return d;
}

void ori_motion_destroy(ori_motion *mo)
{
    if (!mo) return;
    ori__free(mo->viol);
    ori__free(mo->drive);
    ori__free(mo->angles);
    ori__free(mo->residual);
    ori__free(mo->alt);
    ori__free(mo->has_alt);
    ori__free(mo->ee_a);
    ori__free(mo->ee_b);
    ori__free(mo);
}

// --- the path-following context ---------------------------------------------------------

typedef enum leg_result { LEG_OK, LEG_BLOCKED, LEG_NONE, LEG_UNDER } leg_result;

typedef struct ctx {
    const ori_mechanism *m;
    ori_motion *mo;
    int *col;
    int ncols;
    int jd; // driven joint
    double *th;
    bool analytic;
    kin_spherical sp;
    kin_solver *solver;
    // violations: worst wrong-sign angle per joint
    double *worst;
    double *worst_at;
    int extra_dof;
    bool cone_violating;
    double blocked_at;
    double last_residual; // residual of the last accepted state (numeric), or -1
    bool incompatible;    // NONE because the vertices' assigned branches contradict each other
    bool has_alt;         // closed form: the other branch at the current drive value
    double alt[3];
} ctx;

static int assigned_sign(const ori_mechanism *m, int j)
{
    ori_assignment a = m->joints[j].assignment;
    return a == ORI_ASSIGN_VALLEY ? 1 : a == ORI_ASSIGN_MOUNTAIN ? -1 : 0;
}

static void check_signs(ctx *c)
{
    const ori_mechanism *m = c->m;
    for (int j = 0; j < m->joint_count; ++j) {
        if (j == c->jd || c->col[j] < 0) continue;
        int s = assigned_sign(m, j);
        double t = c->th[j];
        if (s == 0 || !(fabs(t) > ORI_TOL_FOLD_SIGN_RAD) || t * s > 0.0) continue;
        if (fabs(t) > fabs(c->worst[j])) {
            c->worst[j] = t;
            c->worst_at[j] = c->th[c->jd];
        }
    }
}

// Room for cap frames (a fold's frame count is known up front: no copies of growing arrays).
static void reserve_frames(ctx *c, int cap)
{
    ori_motion *mo = c->mo;
    const ori_mechanism *m = c->m;
    if (cap <= mo->frame_cap) return;
    mo->drive = ori__realloc(mo->drive, sizeof(double) * (size_t)cap);
    mo->residual = ori__realloc(mo->residual, sizeof(double) * (size_t)cap);
    mo->angles = ori__realloc(mo->angles, sizeof(double) * (size_t)cap * (size_t)(m->edge_count + 1));
    if (c->analytic) mo->alt = ori__realloc(mo->alt, sizeof(double) * (size_t)cap * (size_t)(m->edge_count + 1));
    mo->has_alt = ori__realloc(mo->has_alt, sizeof(bool) * (size_t)cap);
    mo->frame_cap = cap;
}

static void record(ctx *c)
{
    ori_motion *mo = c->mo;
    const ori_mechanism *m = c->m;
    if (mo->nframes == mo->frame_cap) reserve_frames(c, mo->frame_cap ? 2 * mo->frame_cap : 16);
    int k = mo->nframes++;
    mo->drive[k] = c->th[c->jd];
    ori__kin_joints_to_edges(m, c->th, mo->angles + (size_t)k * (size_t)(m->edge_count + 1));
    mo->has_alt[k] = c->analytic && c->has_alt;
    if (mo->has_alt[k]) {
        double *th = ori__alloc(sizeof(double) * (size_t)(m->joint_count + 1));
        memcpy(th, c->th, sizeof(double) * (size_t)m->joint_count);
        const kin_loop *L = &m->loops[c->sp.loop];
        for (int i = 0; i < 3; ++i) th[m->entries[L->first + c->sp.free_entry[i]].joint] = c->alt[i];
        ori__kin_joints_to_edges(m, th, mo->alt + (size_t)k * (size_t)(m->edge_count + 1));
        ori__free(th);
    }
    // The corrector measured the accepted state's residual; the closed form is measured here.
    double r = c->last_residual >= 0.0 ? c->last_residual : ori__kin_residual(m, c->th);
    c->last_residual = -1.0;
    mo->residual[k] = r;
    if (r > mo->stats.max_residual) mo->stats.max_residual = r;
}

// Cubic Hermite extrapolation of the curve through (s0, y0, y0') and (s1, y1, y1') to s.
static double hermite(double s0, double y0, double d0, double s1, double y1, double d1, double s)
{
    double H = s1 - s0;
    double u = (s - s0) / H;
    double u2 = u * u, u3 = u2 * u;
    return (2 * u3 - 3 * u2 + 1) * y0 + (u3 - 2 * u2 + u) * H * d0 + (-2 * u3 + 3 * u2) * y1 + (u3 - u2) * H * d1;
}

// Weights of the Lagrange extrapolation through the last `n` accepted states (abscissae xs) to
// x: the prediction of each joint is Σ w_i y_i.
static void lagrange_weights(const double *xs, int n, double x, double *w)
{
    for (int i = 0; i < n; ++i) {
        w[i] = 1.0;
        for (int k = 0; k < n; ++k)
            if (k != i) w[i] *= (x - xs[k]) / (xs[i] - xs[k]);
    }
}

// Numeric leg from the current drive value to s1, recording at each output value.
//
// Predictor: with fewer than ORI_KIN_HISTORY accepted states, the tangent (one linear solve)
// with a cubic Hermite extrapolation through the previous state and tangent; then a quintic
// Lagrange extrapolation through the last six states, which needs no linear solve and is
// accurate enough (≈ 1e-9 on the Miura sheet at 1.7° steps) for one corrector iteration to
// reach ORI_TOL_NEWTON. The history is a ring: slot (hist0 + i) % ORI_KIN_HISTORY holds the
// i-th oldest state.
#define ORI_KIN_HISTORY 6
static leg_result numeric_leg(ctx *c, double s1, double step_out, bool rec)
{
    const ori_mechanism *m = c->m;
    int J = m->joint_count;
    double s = c->th[c->jd];
    if (s1 == s) return LEG_OK;
    double sg = s1 > s ? 1.0 : -1.0;
    double *t = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *tp = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *thp = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *pred = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *trial = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *hist = ori__alloc(sizeof(double) * (size_t)(J + 1) * ORI_KIN_HISTORY);
    double hs[ORI_KIN_HISTORY]; // drive values, oldest first
    int nh = 0, hist0 = 0;
#define HIST(i) (hist + (size_t)(((hist0) + (i)) % ORI_KIN_HISTORY) * (size_t)J)
    double sp = 0.0;
    bool have_prev = false;
    leg_result result = LEG_OK;
    bool singular_first = false;
    // A regular start has a unique first-order motion of the drive and loops whose equations
    // are independent there. Otherwise (rank-deficient, the drive cannot move at first order,
    // or some loop has equations that first order cannot satisfy — a flat vertex, a hole loop)
    // the second-order analysis decides.
    int nul = ori__kin_solver_nullity(c->solver, c->th);
    if (nul == 0 && ori__kin_tangent(c->solver, c->th, t) &&
        ori__kin_tangent_defect(c->solver, c->th, t) > ORI_TOL_CONE_REL)
        nul = 1;
    if (nul == 0 && ori__kin_loops_deficient(m, c->th, c->col, c->jd)) nul = 1;
    if (nul > 0) {
        int extra = 0;
        kin_cone_result cr = ori__kin_cone(m, c->th, c->col, c->ncols, c->jd, sg, false, t, &extra);

        if (cr == KIN_CONE_NONE || cr == KIN_CONE_INCOMPATIBLE) {
            c->incompatible = cr == KIN_CONE_INCOMPATIBLE;
            result = LEG_NONE;
            goto done;
        }
        if (cr == KIN_CONE_UNDERDETERMINED) {
            c->extra_dof = extra;
            result = LEG_UNDER;
            goto done;
        }
        if (cr == KIN_CONE_VIOLATING) c->cone_violating = true;
        // Per unit drive: v has v[jd] = ±1.
        for (int j = 0; j < J; ++j) t[j] *= sg;
        singular_first = true;
    }
    memcpy(HIST(0), c->th, sizeof(double) * (size_t)J);
    hs[0] = s;
    nh = 1;
    double h_max = fmin(step_out, ORI_KIN_MAX_STEP_RAD);
    double h = singular_first ? fmin(h_max, ORI_KIN_SINGULAR_STEP_RAD) : h_max;
    int k_out = 1;
    double s_start = c->th[c->jd];
    double target = s_start + sg * step_out;
    if ((target - s1) * sg >= 0.0 || !rec) target = s1;
    bool first = true;
    for (;;) {
        s = c->th[c->jd];
        if (s == s1 && (!rec || target == s1)) break;
        double dist = fabs(target - s);
        double hh = fmin(h, dist);
        // A near-complete remainder is taken whole rather than left as a sliver.
        if (dist - hh < 0.25 * hh) hh = dist;
        double snew = hh == dist ? target : s + sg * hh;
        bool secant = nh >= ORI_KIN_HISTORY && fabs(snew - s) <= 2.0 * fabs(s - hs[nh - 2]);
        double tn = 1.0;
        if (secant) {
            double w[ORI_KIN_HISTORY];
            lagrange_weights(hs, nh, snew, w);
            const double *hp[ORI_KIN_HISTORY];
            for (int i = 0; i < nh; ++i) hp[i] = HIST(i);
            const double *y1 = hp[nh - 1], *y0 = hp[nh - 2];
            double inv_ds = 1.0 / (hs[nh - 1] - hs[nh - 2]);
            for (int j = 0; j < J; ++j) {
                if (c->col[j] < 0) {
                    pred[j] = c->th[j];
                    continue;
                }
                double y = 0.0;
                for (int i = 0; i < nh; ++i) y += w[i] * hp[i][j];
                pred[j] = y;
                tn = fmax(tn, fabs((y1[j] - y0[j]) * inv_ds));
            }
        } else {
            if (!(singular_first && first) && !ori__kin_tangent(c->solver, c->th, t)) {
                bool at_start = singular_first && fabs(s - s_start) < ORI_KIN_ESCAPE_RAD;
                result = first || at_start ? LEG_NONE : LEG_BLOCKED;
                c->blocked_at = s;
                break;
            }
            for (int j = 0; j < J; ++j) {
                double lin = c->th[j] + (snew - s) * t[j];
                if (have_prev && fabs(snew - s) <= 2.0 * fabs(s - sp) && c->col[j] >= 0)
                    lin = hermite(sp, thp[j], tp[j], s, c->th[j], t[j], snew);
                pred[j] = lin;
                tn = fmax(tn, fabs(t[j]));
            }
        }
        for (int j = 0; j < J; ++j) trial[j] = pred[j];
        trial[c->jd] = snew;
        pred[c->jd] = snew;
        int its = 0;
        double res = 0.0;
        bool ok = ori__kin_correct(c->solver, trial, ORI_KIN_NEWTON_MAX, &its, &res);
        c->mo->stats.newton_iterations += its;
        double move = 0.0;
        for (int j = 0; j < J; ++j) move = fmax(move, fabs(trial[j] - pred[j]));
        bool accept = ok && move <= ORI_KIN_MAX_CORRECTION * hh * tn + ORI_KIN_CORRECTION_SLACK_RAD;
        for (int j = 0; j < J && accept; ++j)
            if (!(fabs(trial[j]) <= ORI_PI + ORI_TOL_FOLD_SIGN_RAD) && c->col[j] >= 0) accept = false;
        if (!accept) {
            c->mo->stats.rejected_steps++;
            h = 0.5 * hh;
            nh = 1; // restart the history from the current state
            hist0 = 0;
            memcpy(HIST(0), c->th, sizeof(double) * (size_t)J);
            hs[0] = s;
            if (h < ORI_KIN_MIN_STEP_RAD) {
                // Stuck right at a singular start: the second-order tangent was spurious (the
                // motion does not exist beyond second order), so there is no motion at all.
                bool at_start = singular_first && fabs(s - s_start) < ORI_KIN_ESCAPE_RAD;
                result = first || at_start ? LEG_NONE : LEG_BLOCKED;
                c->blocked_at = s;
                break;
            }
            continue;
        }
        // Accepted.
        if (!secant) {
            for (int j = 0; j < J; ++j) {
                thp[j] = c->th[j];
                tp[j] = t[j];
            }
            sp = s;
            have_prev = true;
        }
        for (int j = 0; j < J; ++j) c->th[j] = trial[j];
        if (nh == ORI_KIN_HISTORY) {
            hist0 = (hist0 + 1) % ORI_KIN_HISTORY;
            memmove(hs, hs + 1, sizeof(double) * (ORI_KIN_HISTORY - 1));
            nh--;
        }
        memcpy(HIST(nh), c->th, sizeof(double) * (size_t)J);
        hs[nh++] = snew;
        c->mo->stats.steps++;
        c->last_residual = res;
        check_signs(c);
        if (first && singular_first) {
            // Out of the singular start: the constrained Jacobian must now be regular, else
            // the fold leaves freedom the drive does not fix.
            int n2 = ori__kin_solver_nullity(c->solver, c->th);
            if (n2 > 0) {
                c->extra_dof = n2;
                result = LEG_UNDER;
                break;
            }
        }
        first = false;
        if (its <= 3) h = fmin(2.0 * h, h_max);
        if (snew == target) {
            if (rec) record(c);
            if (target == s1) break;
            k_out++;
            target = s_start + sg * step_out * k_out; // the grid from + k·step, no drift
            if ((target - s1) * sg >= 0.0 || fabs(target - s1) < ORI_KIN_GRID_MERGE * step_out) target = s1;
        }
    }
done:
    ori__free(t);
    ori__free(tp);
    ori__free(thp);
    ori__free(pred);
    ori__free(trial);
    ori__free(hist);
#undef HIST
    return result;
}

// Choose among closed-form candidates: nearest to the prediction; among candidates about as
// near (branches crossing, e.g. at the flat state), the one the assignment admits.
static int choose_candidate(const ctx *c, double cand[2][3], int nc, const double pred[3], double dh)
{
    const kin_loop *L = &c->m->loops[c->sp.loop];
    double d[2];
    int bad[2];
    for (int k = 0; k < nc; ++k) {
        d[k] = 0.0;
        bad[k] = 0;
        for (int i = 0; i < 3; ++i) {
            d[k] = fmax(d[k], fabs(cand[k][i] - pred[i]));
            int j = c->m->entries[L->first + c->sp.free_entry[i]].joint;
            int s = assigned_sign(c->m, j);
            if (s != 0 && fabs(cand[k][i]) > ORI_TOL_FOLD_SIGN_RAD && cand[k][i] * s < 0.0) bad[k]++;
        }
    }
    if (nc == 1) return 0;
    int near = d[0] <= d[1] ? 0 : 1, other = 1 - near;
    bool both_near = d[other] <= fmax(3.0 * d[near], 4.0 * dh);
    if (both_near && bad[other] < bad[near]) return other;
    return near;
}

static leg_result analytic_leg(ctx *c, double s1, double step_out, bool rec)
{
    const ori_mechanism *m = c->m;
    const kin_loop *L = &m->loops[c->sp.loop];
    int fj[3];
    for (int i = 0; i < 3; ++i) fj[i] = m->entries[L->first + c->sp.free_entry[i]].joint;
    double s = c->th[c->jd];
    if (s1 == s) return LEG_OK;
    double sg = s1 > s ? 1.0 : -1.0;
    double prev[3], prev_s = s;
    bool have_prev = false;
    double s_start = s;
    int k_out = 1;
    double target = s + sg * step_out;
    if ((target - s1) * sg >= 0.0 || !rec) target = s1;
    double h = ORI_KIN_TRACK_STEP_RAD;
    bool first = true;
    for (;;) {
        s = c->th[c->jd];
        if (s == s1 && (!rec || target == s1)) break;
        double dist = fabs(target - s);
        double hh = fmin(h, dist);
        if (dist - hh < 0.25 * hh) hh = dist;
        double snew = hh == dist ? target : s + sg * hh;
        double pred[3];
        for (int i = 0; i < 3; ++i) {
            pred[i] = c->th[fj[i]];
            if (have_prev && s != prev_s) pred[i] += (c->th[fj[i]] - prev[i]) * (snew - s) / (s - prev_s);
        }
        double cand[2][3];
        int nc = ori__kin_spherical_solve(m, &c->sp, c->th, snew, pred, cand);
        if (nc == 0) {
            h = 0.5 * hh;
            c->mo->stats.rejected_steps++;
            if (h < ORI_KIN_MIN_STEP_RAD) {
                c->blocked_at = s;
                return first ? LEG_NONE : LEG_BLOCKED;
            }
            continue;
        }
        int k = choose_candidate(c, cand, nc, pred, hh);
        c->has_alt = nc == 2;
        if (nc == 2)
            for (int i = 0; i < 3; ++i) c->alt[i] = cand[1 - k][i];
        for (int i = 0; i < 3; ++i) prev[i] = c->th[fj[i]];
        prev_s = s;
        have_prev = true;
        for (int i = 0; i < 3; ++i) c->th[fj[i]] = cand[k][i];
        c->th[c->jd] = snew;
        c->mo->stats.steps++;
        first = false;
        check_signs(c);
        h = ORI_KIN_TRACK_STEP_RAD;
        if (snew == target) {
            if (rec) record(c);
            if (target == s1) break;
            k_out++;
            target = s_start + sg * step_out * k_out;
            if ((target - s1) * sg >= 0.0 || fabs(target - s1) < ORI_KIN_GRID_MERGE * step_out) target = s1;
        }
    }
    return LEG_OK;
}

static leg_result run_leg(ctx *c, double s1, double step_out, bool rec)
{
    return c->analytic ? analytic_leg(c, s1, step_out, rec) : numeric_leg(c, s1, step_out, rec);
}

// --- the single-vertex split ---------------------------------------------------------------

static void compute_split(ctx *c, ori_motion *mo)
{
    const ori_mechanism *m = c->m;
    // The moving joints must all lie in one vertex loop.
    int loop = -1;
    for (int l = 0; l < m->loop_count && loop < 0; ++l) {
        const kin_loop *L = &m->loops[l];
        if (L->rows != 3) continue;
        bool has_drive = false;
        for (int i = 0; i < L->count; ++i) has_drive |= m->entries[L->first + i].joint == c->jd;
        if (has_drive) loop = l;
    }
    if (loop < 0) return;
    const kin_loop *L = &m->loops[loop];
    int n = L->count;
    int in_loop = 0, total = 0;
    for (int j = 0; j < m->joint_count; ++j) total += c->col[j] >= 0;
    for (int i = 0; i < n; ++i) in_loop += c->col[m->entries[L->first + i].joint] >= 0;
    if (in_loop != total || n > 16) return;
    // Position of the fixed face: F(p) = face after entry p.
    int p = -1;
    for (int i = 0; i < n; ++i)
        if (m->entry_face[L->first + i] == mo->fixed_face) p = i;
    if (p < 0) return;
    int v = L->vertex;
#define ACTIVE(i) (m->entries[L->first + (i)].joint == c->jd || c->col[m->entries[L->first + (i)].joint] >= 0)
    // Direction (+1 CCW: entries p+1, p+2, …; −1 CW: entries p, p−1, …) reaching the drive first.
    int dir = 0, d = -1;
    for (int s = 0; s < 2 && dir == 0; ++s) {
        int step = s == 0 ? 1 : -1;
        int i = s == 0 ? (p + 1) % n : p;
        for (int k = 0; k < n; ++k, i = ((i + step) % n + n) % n) {
            if (!ACTIVE(i)) continue;
            if (m->entries[L->first + i].joint == c->jd) {
                dir = step;
                d = i;
            }
            break;
        }
    }
    if (dir == 0) return;
    int e = -1;
    for (int k = 1, i = ((d + dir) % n + n) % n; k < n; ++k, i = ((i + dir) % n + n) % n)
        if (ACTIVE(i)) {
            e = i;
            break;
        }
    if (e < 0) return;
    // World geometry at the start state.
    ori_v3 *pos = ori__alloc(sizeof(ori_v3) * (size_t)m->vertex_count);
    double *ang = ori__alloc(sizeof(double) * (size_t)(m->edge_count + 1));
    ori__kin_joints_to_edges(m, c->th, ang);
    ori_mechanism_vertex_positions(m, ang, mo->fixed_face, mo->fixed_pose, pos);
    ori_vertex_split *S = &mo->split;
    memset(S, 0, sizeof *S);
    S->vertex = v;
    // Far end of the crease of entry i, and its world direction in walking direction w.
#define EDGE_OF(i) (m->joints[m->entries[L->first + (i)].joint].edge)
#define FAR(i) (m->edges[EDGE_OF(i)].v[0] == v ? m->edges[EDGE_OF(i)].v[1] : m->edges[EDGE_OF(i)].v[0])
    S->frame_a[0] = EDGE_OF(d);
    S->frame_a[1] = EDGE_OF(e);
    S->origin_a = pos[FAR(d)];
    S->end_effector_vertex = FAR(e);
    for (int k = 0; k < 2; ++k) {
        int i = k == 0 ? d : e;
        ori_v3 axis = ori_v3_normalize(ori_v3_sub(pos[FAR(i)], pos[v]));
        S->omega_a[k] = ori_v3_scale(axis, dir > 0 ? 1.0 : -1.0);
        S->q_a[k] = ori_v3_sub(pos[FAR(i)], S->origin_a);
    }
    // Frame B: from the fixed face the other way round, up to and including e.
    int bdir = -dir;
    int i = bdir > 0 ? (p + 1) % n : p;
    for (int k = 0; k < n; ++k, i = ((i + bdir) % n + n) % n) {
        if (!ACTIVE(i)) {
            if (S->surrounding_count < 16) S->surrounding[S->surrounding_count++] = EDGE_OF(i);
            continue;
        }
        if (S->frame_b_count < 16) {
            int q = S->frame_b_count++;
            S->frame_b[q] = EDGE_OF(i);
            if (q == 0) S->origin_b = pos[FAR(i)];
            ori_v3 axis = ori_v3_normalize(ori_v3_sub(pos[FAR(i)], pos[v]));
            S->omega_b[q] = ori_v3_scale(axis, bdir > 0 ? 1.0 : -1.0);
            S->q_b[q] = ori_v3_sub(pos[FAR(i)], S->origin_b);
        }
        if (i == e) break;
    }
    // Locked creases on the A side (between the fixed face and the drive) are surrounding too.
    for (int k = 0, j = dir > 0 ? (p + 1) % n : p; k < n && j != d; ++k, j = ((j + dir) % n + n) % n)
        if (!ACTIVE(j) && S->surrounding_count < 16) S->surrounding[S->surrounding_count++] = EDGE_OF(j);
    S->d = ori_v3_sub(S->origin_b, S->origin_a);
    mo->has_split = true;
#undef ACTIVE
#undef EDGE_OF
#undef FAR
    ori__free(pos);
    ori__free(ang);
}

// --- validation ----------------------------------------------------------------------------

static ori_status check_crease(const ori_mechanism *m, int e, const char *role, ori_error *error)
{
    if (e < 0 || e >= m->edge_count)
        return ori__fail_at(error, ORI_ERR_RANGE, "edges_vertices", e, "no edge %d (the %s crease)", e, role);
    int j = m->edge_joint[e];
    if (j == ORI_NULL_INDEX)
        return ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_vertices", e,
                            "edge %d is not a crease (assignment %c, or no face on one side)", e,
                            ori_assignment_to_char(m->edges[e].assignment));
    return ORI_OK;
}

static void append_reason(ori_motion *mo, const char *fmt, double a, double b)
{
    size_t len = strlen(mo->reason);
    if (len + 1 >= sizeof mo->reason) return;
    snprintf(mo->reason + len, sizeof mo->reason - len, fmt, a, b);
}

static double deg(double rad) { return ori_rad_to_deg_output(rad); }

ori_status ori_motion_solve(const ori_mechanism *m, const ori_motion_def *def, ori_motion **out, ori_error *error)
{
    ORI_ASSERT(m && def && def->internal_value == ORI__DEF_COOKIE && out);
    *out = NULL;
    int J = m->joint_count;
    if (def->fixed_face < 0 || def->fixed_face >= m->face_count)
        return ori__fail_at(error, ORI_ERR_RANGE, "faces_vertices", def->fixed_face, "no face %d (the fixed face)",
                            def->fixed_face);
    ori_status st = check_crease(m, def->driven_edge, "driven", error);
    if (st != ORI_OK) return st;
    int jd = m->edge_joint[def->driven_edge];
    if (m->joints[jd].kind != ORI_JOINT_REVOLUTE)
        return ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_vertices", def->driven_edge,
                            "edge %d is a %s edge: it stays at 0 and cannot be driven", def->driven_edge,
                            ori_assignment_name(m->edges[def->driven_edge].assignment));
    for (int i = 0; i < def->locked_count; ++i) {
        int e = def->locked_edges[i];
        st = check_crease(m, e, "locked", error);
        if (st != ORI_OK) return st;
        if (e == def->driven_edge)
            return ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_vertices", e, "edge %d is both driven and locked", e);
    }
    if (!isfinite(def->to_rad) || fabs(def->to_rad) > ORI_PI + ORI_TOL_FOLD_SIGN_RAD)
        return ori__fail_at(error, ORI_ERR_RANGE, "edges_foldAngle", def->driven_edge,
                            "target angle %g° is outside [-180°, 180°]", ori_rad_to_deg(def->to_rad));
    if (def->has_from && (!isfinite(def->from_rad) || fabs(def->from_rad) > ORI_PI + ORI_TOL_FOLD_SIGN_RAD))
        return ori__fail_at(error, ORI_ERR_RANGE, "edges_foldAngle", def->driven_edge,
                            "start angle %g° is outside [-180°, 180°]", ori_rad_to_deg(def->from_rad));
    if (!(def->step_rad > 0.0) || !isfinite(def->step_rad))
        return ori__fail(error, ORI_ERR_RANGE, "the step must be a positive angle (got %g°)", ori_rad_to_deg(def->step_rad));
    const ori_rigid *G = &def->fixed_pose;
    for (int i = 0; i < 3; ++i) {
        bool fin = isfinite(G->t.x) && isfinite(G->t.y) && isfinite(G->t.z);
        for (int k = 0; k < 3; ++k) fin = fin && isfinite(G->r.m[i][k]);
        if (!fin) return ori__fail(error, ORI_ERR_RANGE, "the fixed face's pose is not finite");
    }
    if (def->start_angles_rad)
        for (int e = 0; e < m->edge_count; ++e)
            if (!isfinite(def->start_angles_rad[e]))
                return ori__fail_at(error, ORI_ERR_RANGE, "edges_foldAngle", e, "fold angle is not finite");

    ctx c;
    memset(&c, 0, sizeof c);
    c.m = m;
    c.jd = jd;
    c.last_residual = -1.0;
    c.col = ori__alloc(sizeof(int) * (size_t)(J + 1));
    c.th = ori__alloc(sizeof(double) * (size_t)(J + 1));
    c.worst = ori__calloc((size_t)J + 1, sizeof(double));
    c.worst_at = ori__calloc((size_t)J + 1, sizeof(double));
    for (int j = 0; j < J; ++j) c.col[j] = m->joints[j].kind == ORI_JOINT_REVOLUTE ? 0 : KIN_FIXED;
    for (int i = 0; i < def->locked_count; ++i) c.col[m->edge_joint[def->locked_edges[i]]] = KIN_FIXED;
    c.col[jd] = KIN_DRIVE;
    for (int j = 0; j < J; ++j)
        if (c.col[j] >= 0) c.col[j] = c.ncols++;
    ori__kin_edges_to_joints(m, def->start_angles_rad, c.th);

    ori_motion *mo = ori__calloc(1, sizeof *mo);
    mo->m = m;
    mo->edge_count = m->edge_count;
    mo->fixed_face = def->fixed_face;
    mo->fixed_pose = def->fixed_pose;
    mo->driven_edge = def->driven_edge;
    mo->dof = -1;
    c.mo = mo;

    bool sph = ori__kin_spherical_applicable(m, c.col, jd, &c.sp);
    if (def->solver == ORI_SOLVER_ANALYTIC && !sph) {
        st = ori__fail_at(error, ORI_ERR_UNSUPPORTED, "edges_vertices", def->driven_edge,
                          "the closed-form solver needs one vertex with four moving creases (the driven one and three "
                          "free); lock the others or use the numeric solver");
        goto fail;
    }
    c.analytic = sph && def->solver != ORI_SOLVER_NUMERIC;
    kin_solver_opts opts = {def->linear, false};
    c.solver = ori__kin_solver_create(m, c.col, c.ncols, jd, &opts);
    mo->stats.analytic = c.analytic;
    mo->stats.sparse = !c.analytic && ori__kin_solver_sparse(c.solver);
    mo->stats.sweep = !c.analytic && ori__kin_solver_sweep(c.solver);

    // The start state must close; states read from files (rounded angles) are projected.
    double r0 = ori__kin_residual(m, c.th);
    if (!(r0 <= ORI_TOL_START_RESIDUAL)) {
        st = ori__fail(error, ORI_ERR_ARGUMENT,
                       "the start fold angles do not close the loops (residual %.3g above %.0e)", r0, ORI_TOL_START_RESIDUAL);
        goto fail;
    }
    if (r0 > ORI_TOL_RESIDUAL) {
        int its;
        double res;
        if (!ori__kin_correct(c.solver, c.th, ORI_KIN_NEWTON_MAX, &its, &res)) {
            st = ori__fail(error, ORI_ERR_NOT_CONVERGED, "the start state could not be closed (residual %.3g)", res);
            goto fail;
        }
    }
    compute_split(&c, mo);

    // Leg 1 (silent) to from, leg 2 from → to with output.
    leg_result lr = LEG_OK;
    if (def->has_from && def->from_rad != c.th[jd]) lr = run_leg(&c, def->from_rad, fabs(def->from_rad - c.th[jd]), false);
    if (lr == LEG_OK) {
        // Frames: the start, one per step, the target (capped: a tiny step grows the arrays).
        double span = fabs(def->to_rad - c.th[jd]) / def->step_rad;
        reserve_frames(&c, span < ORI_KIN_RESERVE_FRAMES ? (int)span + 3 : ORI_KIN_RESERVE_FRAMES);
        record(&c);
        lr = run_leg(&c, def->to_rad, def->step_rad, true);
    }
    mo->stats.factorizations = c.analytic ? 0 : ori__kin_solver_factorizations(c.solver);
    mo->stats.sweep_iterations = c.analytic ? 0 : ori__kin_solver_sweep_iterations(c.solver);

    // Verdict.
    double s_to = def->to_rad;
    int ds = assigned_sign(m, jd);
    bool drive_wrong = ds != 0 && fabs(s_to) > ORI_TOL_FOLD_SIGN_RAD && s_to * ds < 0.0;
    for (int j = 0; j < J; ++j)
        if (c.worst[j] != 0.0) mo->nviol++;
    if (mo->nviol) {
        mo->viol = ori__alloc(sizeof(ori_crease_violation) * (size_t)mo->nviol);
        int k = 0;
        for (int j = 0; j < J; ++j)
            if (c.worst[j] != 0.0) {
                ori_crease_violation v;
                v.edge = m->joints[j].edge;
                v.assignment = m->joints[j].assignment;
                v.angle_rad = c.worst[j];
                v.drive_rad = c.worst_at[j];
                mo->viol[k++] = v;
            }
        // Sort by edge index (joints are in edge order already).
    }
    if (drive_wrong && (lr == LEG_NONE || lr == LEG_UNDER)) {
        // Driving a crease against its own assignment is invalid whatever the motion would be.
        mo->verdict = ORI_MOTION_INVALID_ASSIGNMENT;
        snprintf(mo->reason, sizeof mo->reason, "the driven crease %d is assigned %s but is driven to %g°",
                 def->driven_edge, ori_assignment_name(m->joints[jd].assignment), deg(s_to));
        mo->nframes = 0;
    } else if (lr == LEG_NONE) {
        mo->verdict = ORI_MOTION_NOT_RIGIDLY_FOLDABLE;
        if (c.incompatible)
            snprintf(mo->reason, sizeof mo->reason,
                     "no rigid motion folds the creases as assigned: each vertex can fold as assigned on its own, "
                     "but their fold-angle relations contradict each other around a closed loop of faces");
        else
            snprintf(mo->reason, sizeof mo->reason,
                     "no rigid motion moves crease %d from the start state: the loop-closure conditions (to "
                     "second order) admit no motion of it in this direction",
                     def->driven_edge);
        mo->nframes = 0;
    } else if (lr == LEG_UNDER) {
        mo->verdict = ORI_MOTION_UNDERDETERMINED;
        snprintf(mo->reason, sizeof mo->reason,
                 "the fold leaves %d more degree%s of freedom than the driven crease fixes: lock %d more crease%s",
                 c.extra_dof, c.extra_dof == 1 ? "" : "s", c.extra_dof, c.extra_dof == 1 ? "" : "s");
        mo->nframes = 0;
    } else if (drive_wrong || mo->nviol) {
        mo->verdict = ORI_MOTION_INVALID_ASSIGNMENT;
        mo->reason[0] = '\0';
        if (drive_wrong)
            snprintf(mo->reason, sizeof mo->reason, "the driven crease %d is assigned %s but is driven to %g°",
                     def->driven_edge, ori_assignment_name(m->joints[jd].assignment), deg(s_to));
        for (int k = 0; k < mo->nviol; ++k) {
            const ori_crease_violation *v = &mo->viol[k];
            char buf[200];
            snprintf(buf, sizeof buf, "%screase %d (assigned %s) would fold to %.10g°", mo->reason[0] ? "; " : "",
                     v->edge, ori_assignment_name(v->assignment), deg(v->angle_rad));
            size_t len = strlen(mo->reason);
            if (len + strlen(buf) + 1 < sizeof mo->reason) memcpy(mo->reason + len, buf, strlen(buf) + 1);
        }
        if (lr == LEG_BLOCKED)
            append_reason(mo, "; the motion also stops at %.10g°%.0s", deg(c.blocked_at), 0.0);
    } else if (lr == LEG_BLOCKED) {
        mo->verdict = ORI_MOTION_BLOCKED;
        snprintf(mo->reason, sizeof mo->reason,
                 "the motion stops at crease %d = %.10g°: no rigid configuration beyond (a limit of the motion or a "
                 "singular point)",
                 def->driven_edge, deg(c.blocked_at));
    } else {
        mo->verdict = ORI_MOTION_VALID;
    }

    // Free-mechanism DOF at the last frame.
    if (mo->nframes > 0) {
        double *ang = mo->angles + (size_t)(mo->nframes - 1) * (size_t)(m->edge_count + 1);
        double *th = ori__alloc(sizeof(double) * (size_t)(J + 1));
        int *col = ori__alloc(sizeof(int) * (size_t)(J + 1));
        int n = 0;
        for (int j = 0; j < J; ++j) col[j] = m->joints[j].kind == ORI_JOINT_REVOLUTE ? n++ : KIN_FIXED;
        ori__kin_edges_to_joints(m, ang, th);
        ori_dof_result dr;
        ori_error e2;
        if (ori__kin_nullity(m, th, col, n, &dr, &e2) == ORI_OK) mo->dof = dr.dof;
        ori__free(th);
        ori__free(col);
    }
    // End effector per frame.
    if (mo->has_split && mo->nframes > 0) {
        mo->ee_a = ori__alloc(sizeof(ori_v3) * (size_t)mo->nframes);
        mo->ee_b = ori__alloc(sizeof(ori_v3) * (size_t)mo->nframes);
        ori_v3 *pos = ori__alloc(sizeof(ori_v3) * (size_t)m->vertex_count);
        for (int k = 0; k < mo->nframes; ++k) {
            ori_mechanism_vertex_positions(m, mo->angles + (size_t)k * (size_t)(m->edge_count + 1), mo->fixed_face,
                                           mo->fixed_pose, pos);
            ori_v3 p = pos[mo->split.end_effector_vertex];
            mo->ee_a[k] = ori_v3_sub(p, mo->split.origin_a);
            mo->ee_b[k] = ori_v3_sub(p, mo->split.origin_b);
        }
        ori__free(pos);
    }
    ori__kin_solver_destroy(c.solver);
    ori__free(c.col);
    ori__free(c.th);
    ori__free(c.worst);
    ori__free(c.worst_at);
    *out = mo;
    return ORI_OK;
fail:
    ori__kin_solver_destroy(c.solver);
    ori__free(c.col);
    ori__free(c.th);
    ori__free(c.worst);
    ori__free(c.worst_at);
    ori_motion_destroy(mo);
    return st;
}

// --- getters -----------------------------------------------------------------------------

ori_motion_verdict ori_motion_verdict_of(const ori_motion *mo) { ORI_ASSERT(mo); return mo->verdict; }

const char *ori_motion_verdict_name(ori_motion_verdict v)
{
    switch (v) {
    case ORI_MOTION_VALID: return "valid";
    case ORI_MOTION_INVALID_ASSIGNMENT: return "invalid assignment";
    case ORI_MOTION_NOT_RIGIDLY_FOLDABLE: return "not rigidly foldable";
    case ORI_MOTION_UNDERDETERMINED: return "underdetermined";
    case ORI_MOTION_BLOCKED: return "blocked";
    }
    return "unknown";
}

const char *ori_motion_reason(const ori_motion *mo)
{
    ORI_ASSERT(mo);
    return mo->verdict == ORI_MOTION_VALID ? NULL : mo->reason;
}

int ori_motion_violation_count(const ori_motion *mo) { ORI_ASSERT(mo); return mo->nviol; }

ori_crease_violation ori_motion_violation(const ori_motion *mo, int i)
{
    ORI_ASSERT(mo && i >= 0 && i < mo->nviol);
    return mo->viol[i];
}

int ori_motion_frame_count(const ori_motion *mo) { ORI_ASSERT(mo); return mo->nframes; }

double ori_motion_frame_drive(const ori_motion *mo, int k)
{
    ORI_ASSERT(mo && k >= 0 && k < mo->nframes);
    return mo->drive[k];
}

const double *ori_motion_frame_angles(const ori_motion *mo, int k)
{
    ORI_ASSERT(mo && k >= 0 && k < mo->nframes);
    return mo->angles + (size_t)k * (size_t)(mo->edge_count + 1);
}

double ori_motion_frame_residual(const ori_motion *mo, int k)
{
    ORI_ASSERT(mo && k >= 0 && k < mo->nframes);
    return mo->residual[k];
}

void ori_motion_frame_face_poses(const ori_motion *mo, int k, ori_rigid *poses)
{
    ORI_ASSERT(mo && k >= 0 && k < mo->nframes && poses);
    ori_mechanism_face_poses(mo->m, ori_motion_frame_angles(mo, k), mo->fixed_face, mo->fixed_pose, poses);
}

void ori_motion_frame_vertices(const ori_motion *mo, int k, ori_v3 *positions)
{
    ORI_ASSERT(mo && k >= 0 && k < mo->nframes && positions);
    ori_mechanism_vertex_positions(mo->m, ori_motion_frame_angles(mo, k), mo->fixed_face, mo->fixed_pose, positions);
}

bool ori_motion_frame_other_branch(const ori_motion *mo, int k, double *angles_rad)
{
    ORI_ASSERT(mo && k >= 0 && k < mo->nframes);
    if (!mo->has_alt || !mo->has_alt[k]) return false;
    if (angles_rad) memcpy(angles_rad, mo->alt + (size_t)k * (size_t)(mo->edge_count + 1), sizeof(double) * (size_t)mo->edge_count);
    return true;
}

bool ori_motion_frame_end_effector(const ori_motion *mo, int k, ori_v3 *in_a, ori_v3 *in_b)
{
    ORI_ASSERT(mo && k >= 0 && k < mo->nframes);
    if (!mo->has_split || !mo->ee_a) return false;
    if (in_a) *in_a = mo->ee_a[k];
    if (in_b) *in_b = mo->ee_b[k];
    return true;
}

int ori_motion_fixed_face(const ori_motion *mo) { ORI_ASSERT(mo); return mo->fixed_face; }
ori_rigid ori_motion_fixed_pose(const ori_motion *mo) { ORI_ASSERT(mo); return mo->fixed_pose; }

bool ori_motion_split(const ori_motion *mo, ori_vertex_split *out)
{
    ORI_ASSERT(mo);
    if (!mo->has_split) return false;
    if (out) *out = mo->split;
    return true;
}

ori_motion_stats ori_motion_stats_of(const ori_motion *mo) { ORI_ASSERT(mo); return mo->stats; }
int ori_motion_dof(const ori_motion *mo) { ORI_ASSERT(mo); return mo->dof; }
