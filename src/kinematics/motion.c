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
// branch); easy steps (≤ 3 iterations) double the step up to ORI_KIN_MAX_STEP_RAD, and no moving
// crease turns more than ORI_KIN_MAX_TURN_RAD in a step (a steep branch is followed in steps
// short against its turn, whatever the output step). Output states land exactly on the
// requested drive values. At a singular start (the flat sheet) the
// tangent comes from the second-order cone analysis (cone.c), which also selects the branch.
#include <lapacke.h>
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
    bool last_only; // def.last_frame_only: every frame overwrites frame 0
    double *drive;
    double *angles; // nframes × edge_count
    double *residual;
    double *alt;    // nframes × edge_count: the other closed-form branch, when has_alt[k]
    bool *has_alt;
    bool has_split;
    ori_vertex_split split;
    ori_v3 *ee_a, *ee_b;
    ori_v3 *vertices; // every frame's vertex positions, computed by the first ori_motion_vertices
    ori_motion_stats stats;
    int dof;
    ori_motion_block block;
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
    d.progress = NULL;
    d.progress_user = NULL;
    d.last_frame_only = false;
    d.max_steps = ORI_KIN_MAX_WALK_STEPS;
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
    ori__free(mo->vertices);
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
    ori_block_kind block_kind; // what stopped a BLOCKED leg
    int block_joint;           // ORI_BLOCK_CREASE_LIMIT: the crease at ±π
    // progress of the output leg: fraction |drive − prog_from| / |prog_to − prog_from| per frame
    ori_progress_fn *progress;
    void *progress_user;
    bool progress_on;
    double prog_from, prog_to;
    bool cancelled; // the progress callback returned false: the walks stop at their next step
    // A leg walked in pieces (through a singular point, cross_flat): the output grid is
    // grid0 + k·step up to grid_end, whatever piece is walking; a piece's own end is no output.
    bool grid_set;
    double grid0, grid_end;
    // Walking towards the flat state (drive 0) to cross it: no step longer than half the
    // remaining distance, so that no step lands near the crossing from afar.
    bool approach_flat;
    double approach_floor; // … nor need be shorter than this, and within 16 × this of it no longer (radians)
    int label; // closed form: the branch label followed (±1), 0 until known
    double leg_end; // the end of the leg being walked (a stop is never located beyond it)
    long max_steps;       // the step budget (def->max_steps and twice the output's steps)
} ctx;

static int assigned_sign(const ori_mechanism *m, int j)
{
    ori_assignment a = m->joints[j].assignment;
    return a == ORI_ASSIGN_VALLEY ? 1 : a == ORI_ASSIGN_MOUNTAIN ? -1 : 0;
}

static void check_signs_within(ctx *c, double tol);
static void check_signs(ctx *c) { check_signs_within(c, ORI_TOL_FOLD_SIGN_RAD); }

// Record the creases folded against their assignment by more than tol at the current state.
static void check_signs_within(ctx *c, double tol)
{
    const ori_mechanism *m = c->m;
    for (int j = 0; j < m->joint_count; ++j) {
        if (j == c->jd || c->col[j] < 0) continue;
        int s = assigned_sign(m, j);
        double t = c->th[j];
        if (s == 0 || !(fabs(t) > tol) || t * s > 0.0) continue;
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
    mo->stats.frames++;
    if (mo->last_only && mo->nframes > 0) mo->nframes = 0;
    if (mo->nframes == mo->frame_cap) reserve_frames(c, mo->frame_cap ? 2 * mo->frame_cap : 16);
    int k = mo->nframes++;
    mo->drive[k] = c->th[c->jd];
    if (c->progress_on && !c->cancelled) {
        double span = fabs(c->prog_to - c->prog_from);
        double f = span > 0.0 ? fmin(1.0, fabs(c->th[c->jd] - c->prog_from) / span) : 1.0;
        if (!c->progress(f, c->progress_user)) c->cancelled = true;
    }
    double *ang = mo->angles + (size_t)k * (size_t)(m->edge_count + 1);
    ori__kin_joints_to_edges(m, c->th, ang);
    // A crease may end a hair beyond ±π (a fully folded state, within ORI_TOL_FOLD_SIGN_RAD):
    // stored exactly at ±π so that every output stays in [−π, π] and reads back.
    for (int e = 0; e < m->edge_count; ++e)
        if (fabs(ang[e]) > ORI_PI) ang[e] = ang[e] > 0.0 ? ORI_PI : -ORI_PI;
    mo->has_alt[k] = c->analytic && c->has_alt;
    if (mo->has_alt[k]) {
        double *th = ori__alloc(sizeof(double) * (size_t)(m->joint_count + 1));
        memcpy(th, c->th, sizeof(double) * (size_t)m->joint_count);
        const kin_loop *L = &m->loops[c->sp.loop];
        for (int i = 0; i < 3; ++i) th[m->entries[L->first + c->sp.free_entry[i]].joint] = c->alt[i];
        double *alt = mo->alt + (size_t)k * (size_t)(m->edge_count + 1);
        ori__kin_joints_to_edges(m, th, alt);
        ori__free(th);
        // The other branch as angles in [−π, π] (the closed form tracks representatives near
        // the prediction, which may lie a turn away).
        for (int e = 0; e < m->edge_count; ++e) alt[e] = ori_wrap_angle(alt[e]);
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

// The k-th output value of a walk to s1 from the grid origin s_start (s_start + k·step, no drift),
// merged into the leg's end when within ORI_KIN_GRID_MERGE steps of it (merge), and capped at
// s1. *out is false when the value is only the end of a piece of the leg (c->grid_set), not an
// output value.
static double grid_target(const ctx *c, double s_start, double s1, double sg, double step_out, int k, bool merge,
                          bool *out)
{
    double end = c->grid_set ? c->grid_end : s1;
    double t = s_start + sg * step_out * k;
    if ((t - end) * sg >= 0.0 || (merge && fabs(t - end) < ORI_KIN_GRID_MERGE * step_out)) t = end;
    *out = true;
    if ((t - s1) * sg >= 0.0) {
        *out = t == s1;
        t = s1;
    }
    return t;
}

// The first grid index beyond the drive value s (1 for a walk that starts the grid).
static int grid_first(const ctx *c, double s, double sg, double step_out)
{
    if (!c->grid_set) return 1;
    int k = (int)floor((s - c->grid0) * sg / step_out) + 1;
    while ((c->grid0 + sg * step_out * k - s) * sg <= ORI_TOL_KIN_GRID_REL * step_out) k++;
    return k < 1 ? 1 : k;
}

// --- where a motion stops ------------------------------------------------------------------

// The largest |angle| over the moving (free) creases of th; *joint receives which.
static double max_free_angle(const ctx *c, const double *th, int *joint)
{
    double best = -1.0;
    int bj = -1;
    for (int j = 0; j < c->m->joint_count; ++j)
        if (c->col[j] >= 0 && fabs(th[j]) > best) {
            best = fabs(th[j]);
            bj = j;
        }
    if (joint) *joint = bj;
    return best;
}

// Some moving crease has turned past ±π: its faces would pass through each other.
static bool beyond_limit(const ctx *c, const double *th)
{
    return max_free_angle(c, th, NULL) > ORI_PI + ORI_TOL_FOLD_SIGN_RAD;
}

// The joints of a spherical split's three free crossings, in its order.
static void free_joints(const ori_mechanism *m, const kin_spherical *sp, int fj[3])
{
    const kin_loop *L = &m->loops[sp->loop];
    for (int i = 0; i < 3; ++i) fj[i] = m->entries[L->first + sp->free_entry[i]].joint;
}

static double cand_distance(const double a[3], const double b[3])
{
    return fmax(fabs(a[0] - b[0]), fmax(fabs(a[1] - b[1]), fabs(a[2] - b[2])));
}

// Choose among closed-form candidates: the one nearest to the prediction, i.e. the smooth
// continuation of the branch followed so far (as the numeric corrector does). Where the branch
// starts (a singular start) the cone analysis chose it (by_cone below).
// Along a branch the closed form's label (the sign of ±acos, see ori__kin_spherical_solve) does
// not change between singular points: once known (c->label) it decides, whatever the step, so
// that near a turning point or where the branches pass close the closed form cannot switch.
static int choose_candidate(const ctx *c, double cand[2][3], const int label[2], int nc, const double pred[3])
{
    if (nc == 2 && c->label != 0 && label[0] != 0 && label[0] == -label[1]) return label[0] == c->label ? 0 : 1;
    return nc == 2 && cand_distance(cand[1], pred) < cand_distance(cand[0], pred) ? 1 : 0;
}

// The state at drive value s_new continued from the accepted state c->th by a short step: the
// closed-form branch nearest to it, or a tangent prediction and the corrector. False when there
// is none (or the corrector jumped to another branch).
static bool state_at(ctx *c, double s_new, double *out)
{
    const ori_mechanism *m = c->m;
    int J = m->joint_count;
    double s = c->th[c->jd];
    memcpy(out, c->th, sizeof(double) * (size_t)J);
    out[c->jd] = s_new;
    if (c->analytic) {
        int fj[3];
        double pred[3], cand[2][3];
        free_joints(m, &c->sp, fj);
        for (int i = 0; i < 3; ++i) pred[i] = c->th[fj[i]];
        int lab[2];
        int nc = ori__kin_spherical_solve(m, &c->sp, c->th, s_new, pred, cand, lab);
        if (nc == 0) return false;
        int k = choose_candidate(c, cand, lab, nc, pred);
        for (int i = 0; i < 3; ++i) out[fj[i]] = cand[k][i];
        return true;
    }
    double *t = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *pred = ori__alloc(sizeof(double) * (size_t)(J + 1));
    bool ok = ori__kin_tangent(c->solver, c->th, t);
    if (ok) {
        double tn = 1.0;
        for (int j = 0; j < J; ++j)
            if (c->col[j] >= 0) {
                out[j] = c->th[j] + (s_new - s) * t[j];
                tn = fmax(tn, fabs(t[j]));
            }
        memcpy(pred, out, sizeof(double) * (size_t)J);
        int its = 0;
        double res = 0.0;
        ok = ori__kin_correct(c->solver, out, ORI_KIN_NEWTON_MAX, &its, &res);
        c->mo->stats.newton_iterations += its;
        double move = 0.0;
        for (int j = 0; j < J; ++j) move = fmax(move, fabs(out[j] - pred[j]));
        ok = ok && move <= ORI_KIN_MAX_CORRECTION * fabs(s_new - s) * tn + ORI_KIN_CORRECTION_SLACK_RAD;
    }
    ori__free(t);
    ori__free(pred);
    return ok;
}

// --- a stop located on a regular parametrisation ------------------------------------------
//
// Near a turning point of the drive (dθ/ds unbounded) the drive is no parameter of the branch:
// a state at a drive value is known only to about √ of its resolution, and the numeric stop found
// by bisecting the drive lies up to about 1e-4 rad short of the closed form's. The branch is
// regular in the crease u = θ_k that moves fastest there, so both solvers continue it in u from
// the bisection's last state (closed form: the 4R solved for u; numeric: the corrector with θ_k
// held) until the first of two events: the drive turns back (ds/du changes sign: a turning point,
// ORI_BLOCK_SINGULAR) or a moving crease passes ±π (ORI_BLOCK_CREASE_LIMIT); the event is then
// bisected in u. The stop is a crease limit when a moving crease is within
// ORI_TOL_KIN_STOP_AT_LIMIT_RAD of ±π there (a turning point at the limit included).

// The branch parametrised by the joint k instead of the drive.
typedef struct stop_param {
    int k;
    int *col;          // the columns with k held and the drive free
    kin_solver *solver; // numeric corrector and tangent in that parametrisation
    kin_spherical sp;  // closed form in that parametrisation (c->analytic)
} stop_param;

// The state at u = θ_k continued from the state x (its tangent tx = dθ/du) by one step: the
// closed-form solution nearest to the linear prediction, or the corrector from it, with the
// continuation's jump test. False when there is none.
static bool state_at_u(ctx *c, stop_param *p, const double *x, const double *tx, double u, double *out)
{
    const ori_mechanism *m = c->m;
    int J = m->joint_count;
    double du = u - x[p->k], tn = 1.0;
    for (int j = 0; j < J; ++j) {
        out[j] = x[j];
        if (p->col[j] >= 0) {
            out[j] = x[j] + du * tx[j];
            tn = fmax(tn, fabs(tx[j]));
        }
    }
    out[p->k] = u;
    double move = 0.0;
    if (c->analytic) {
        int fj[3];
        double pred[3], cand[2][3];
        free_joints(m, &p->sp, fj);
        for (int i = 0; i < 3; ++i) pred[i] = out[fj[i]];
        int nc = ori__kin_spherical_solve(m, &p->sp, x, u, pred, cand, NULL);
        if (nc == 0) return false;
        int q = nc == 2 && cand_distance(cand[1], pred) < cand_distance(cand[0], pred) ? 1 : 0;
        move = cand_distance(cand[q], pred);
        for (int i = 0; i < 3; ++i) out[fj[i]] = cand[q][i];
    } else {
        double *pred = ori__alloc(sizeof(double) * (size_t)(J + 1));
        memcpy(pred, out, sizeof(double) * (size_t)J);
        int its = 0;
        double res = 0.0;
        bool ok = ori__kin_correct(p->solver, out, ORI_KIN_NEWTON_MAX, &its, &res);
        c->mo->stats.newton_iterations += its;
        for (int j = 0; j < J; ++j) move = fmax(move, fabs(out[j] - pred[j]));
        ori__free(pred);
        if (!ok) return false;
    }
    return move <= ORI_KIN_MAX_CORRECTION * fabs(du) * tn + ORI_KIN_CORRECTION_SLACK_RAD;
}

// Whether the stop's event lies at or before the state y (tangent ty in u): a moving crease past
// ±π, or the drive turned back (ds/du of the other sign than g0); false with *ok = false when y
// has no tangent.
static bool stop_event(ctx *c, stop_param *p, const double *y, double *ty, double g0, bool *ok)
{
    *ok = ori__kin_tangent(p->solver, y, ty);
    if (!*ok) return false;
    return beyond_limit(c, y) || ty[c->jd] * g0 <= 0.0;
}

// Locate the stop near the state c->th (the bisection's last) on the branch parametrised by its
// fastest crease, towards s_out (the end of the step that failed, which may lie short of the stop
// when the steps shrank below the minimum); true with c->th at the stop, false (c->th untouched)
// when the branch cannot be followed there, no event lies within ORI_TOL_KIN_STOP_LIMIT_RAD of u,
// or the branch reaches the leg's end first (no stop before it).
static bool refine_stop(ctx *c, double s_out)
{
    const ori_mechanism *m = c->m;
    int J = m->joint_count;
    double *t = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *x = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *tx = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *y = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *ty = ori__alloc(sizeof(double) * (size_t)(J + 1));
    stop_param p = {-1, NULL, NULL, {0, 0, {0, 0, 0}}};
    bool found = false;
    if (!ori__kin_tangent(c->solver, c->th, t)) goto done;
    double big = 0.0;
    for (int j = 0; j < J; ++j)
        if (c->col[j] >= 0 && fabs(t[j]) > big) {
            big = fabs(t[j]);
            p.k = j;
        }
    if (p.k < 0) goto done;
    p.col = ori__alloc(sizeof(int) * (size_t)(J + 1));
    memcpy(p.col, c->col, sizeof(int) * (size_t)J);
    p.col[c->jd] = c->col[p.k];
    p.col[p.k] = KIN_DRIVE;
    kin_solver_opts opts = {ORI_LINEAR_AUTO, false};
    p.solver = ori__kin_solver_create(m, p.col, c->ncols, p.k, &opts);
    if (c->analytic && !ori__kin_spherical_applicable(m, p.col, p.k, &p.sp)) goto done;
    // The bisection's last state, on the branch at its own u (the closed form's may be a double
    // root just beyond a turning point, which closes its loop only to about 1e-10).
    memset(tx, 0, sizeof(double) * (size_t)J);
    if (!state_at_u(c, &p, c->th, tx, c->th[p.k], x) || !ori__kin_tangent(p.solver, x, tx)) goto done;
    double g0 = tx[c->jd], sg = s_out > c->th[c->jd] ? 1.0 : -1.0;
    if (g0 == 0.0) {
        memcpy(c->th, x, sizeof(double) * (size_t)J); // exactly at the turning point
        found = true;
        goto done;
    }
    // Walk in u, the drive advancing (ds = g0 du towards sg), until the event is passed.
    double d = g0 * sg > 0.0 ? 1.0 : -1.0, h = ORI_KIN_STOP_REFINE_FIRST_RAD, walked = 0.0, ub = 0.0;
    bool bracket = false;
    while (walked < ORI_TOL_KIN_STOP_LIMIT_RAD) {
        double u = x[p.k] + d * h;
        bool ok = true;
        if (!state_at_u(c, &p, x, tx, u, y)) {
            h *= 0.5;
            if (h < ORI_TOL_KIN_STOP_DRIVE_RAD) goto done;
            continue;
        }
        bool ev = stop_event(c, &p, y, ty, g0, &ok);
        if (!ok) goto done;
        if (ev) {
            ub = u;
            bracket = true;
            break;
        }
        if ((y[c->jd] - c->leg_end) * sg >= 0.0) goto done;
        memcpy(x, y, sizeof(double) * (size_t)J);
        memcpy(tx, ty, sizeof(double) * (size_t)J);
        walked += h;
        h = fmin(2.0 * h, ORI_KIN_STOP_REFINE_MAX_RAD);
    }
    if (!bracket) goto done;
    // Bisect the event in u: x stays before it.
    for (int it = 0; it < ORI_KIN_STOP_BISECTIONS && fabs(ub - x[p.k]) > ORI_TOL_KIN_STOP_DRIVE_RAD; ++it) {
        double mid = 0.5 * (x[p.k] + ub);
        if (mid == x[p.k] || mid == ub) break;
        bool ok = true;
        if (!state_at_u(c, &p, x, tx, mid, y) || stop_event(c, &p, y, ty, g0, &ok) || !ok) {
            ub = mid;
            continue;
        }
        memcpy(x, y, sizeof(double) * (size_t)J);
        memcpy(tx, ty, sizeof(double) * (size_t)J);
    }
    if ((x[c->jd] - c->leg_end) * sg >= 0.0) goto done;
    memcpy(c->th, x, sizeof(double) * (size_t)J);
    found = true;
done:
    if (p.solver) ori__kin_solver_destroy(p.solver);
    ori__free(p.col);
    ori__free(t);
    ori__free(x);
    ori__free(tx);
    ori__free(y);
    ori__free(ty);
    return found;
}

// A step from the accepted state c->th towards s_out failed: it took a moving crease past ±π,
// or found no state (a limit of the drive, a singular point). Bisect the drive between the two
// for the last state that exists within [−π, π], then locate the stop from there on the branch
// (refine_stop: where the drive turns back or a crease reaches ±π); c->th ends there and the stop
// is classified: ORI_BLOCK_CREASE_LIMIT when a moving crease is then at ±π (within
// ORI_TOL_KIN_STOP_AT_LIMIT_RAD; within ORI_TOL_KIN_STOP_LIMIT_RAD of the bisection's state when
// the branch cannot be followed there, e.g. at a bifurcation), else ORI_BLOCK_SINGULAR. The same
// search serves both solvers, so that they stop at the same place.
static void locate_stop(ctx *c, double s_out)
{
    int J = c->m->joint_count;
    double s0 = c->th[c->jd], lo = s0, hi = s_out;
    double *x = ori__alloc(sizeof(double) * (size_t)(J + 1));
    for (int it = 0; it < ORI_KIN_STOP_BISECTIONS && fabs(hi - lo) > ORI_TOL_KIN_STOP_DRIVE_RAD; ++it) {
        double mid = 0.5 * (lo + hi);
        if (mid == lo || mid == hi) break;
        if (!state_at(c, mid, x) || beyond_limit(c, x)) {
            hi = mid;
            continue;
        }
        memcpy(c->th, x, sizeof(double) * (size_t)J);
        c->last_residual = -1.0;
        // Close to a singular stop the states are accurate to about √ of the drive's resolution
        // only: a crease touching 0 there is not a violation.
        check_signs_within(c, ORI_TOL_KIN_STOP_SIGN_RAD);
        lo = mid;
    }
    ori__free(x);
    c->blocked_at = lo;
    int j;
    double a = max_free_angle(c, c->th, &j);
    // The limit margin of a stop found by the bisection alone, whose state may lie short of the
    // stop (near a turning point, or on a very steep branch).
    double margin = ORI_TOL_KIN_STOP_LIMIT_RAD;
    if (a < ORI_PI - ORI_TOL_KIN_STOP_AT_LIMIT_RAD && lo != s0 && refine_stop(c, s_out)) {
        // Located on the branch: the crease limit needs a crease at ±π to the stop's accuracy.
        c->blocked_at = c->th[c->jd];
        check_signs_within(c, ORI_TOL_KIN_STOP_SIGN_RAD);
        a = max_free_angle(c, c->th, &j);
        margin = ORI_TOL_KIN_STOP_AT_LIMIT_RAD;
    }
    c->block_kind = a >= ORI_PI - margin ? ORI_BLOCK_CREASE_LIMIT : ORI_BLOCK_SINGULAR;
    c->block_joint = c->block_kind == ORI_BLOCK_CREASE_LIMIT ? j : -1;
}

// The start state is singular when the constrained Jacobian has a null space, the ordinary
// tangent does not move the drive (defect), or some loop's equations are rank deficient (a flat
// vertex, a hole loop): then only the second-order analysis can tell the motion. *t receives
// the regular tangent when it is not singular.
static bool start_singular(ctx *c, double *t)
{
    int nul = ori__kin_solver_nullity(c->solver, c->th);
    if (nul == 0) {
        if (!ori__kin_tangent(c->solver, c->th, t)) memset(t, 0, sizeof(double) * (size_t)c->m->joint_count);
        else if (ori__kin_tangent_defect(c->solver, c->th, t) > ORI_TOL_CONE_REL) nul = 1;
    }
    if (nul == 0 && ori__kin_loops_deficient(c->m, c->th, c->col, c->jd)) nul = 1;
    return nul > 0;
}

// The escape from a singular start: the start (s0, th0, its cone tangent t0 per unit drive)
// and a regular state a fixed distance away (s1, th1, t1), found before any output. States in
// between are the cubic Hermite interpolation of the two, corrected: close to the start the
// residual no longer tells a state on the branch from one beside it (every state within δ of
// a flat vertex closes to O(δ²)), so the branch there is fixed by the escape, not by the
// output step.
typedef struct kin_escape {
    double s0, s1;
    double *th0, *t0, *th1, *t1;
} kin_escape;

// Whether the branch from the escape's start (s0, th0, t0) to its node (s1, th1, t1) is nearly
// straight: the state's change over the escape (the drive's included) differs from either
// tangent's linear prediction by at most a quarter of it (then the cubic Hermite interpolation of
// the two is accurate within).
static bool escape_straight(const ctx *c, const kin_escape *e)
{
    double ds = e->s1 - e->s0, big = fabs(ds), off = 0.0;
    for (int j = 0; j < c->m->joint_count; ++j)
        if (c->col[j] >= 0) {
            double d = e->th1[j] - e->th0[j];
            big = fmax(big, fabs(d));
            off = fmax(off, fmax(fabs(d - ds * e->t0[j]), fabs(d - ds * e->t1[j])));
        }
    return off <= ORI_KIN_ESCAPE_STRAIGHT_REL * big + ORI_TOL_RESIDUAL;
}

// Numeric walk from the current drive value to s1, recording at each output value.
//
// Predictor: with fewer than ORI_KIN_HISTORY accepted states, the tangent (one linear solve)
// with a cubic Hermite extrapolation through the previous state and tangent; then a quintic
// Lagrange extrapolation through the last six states, which needs no linear solve and is
// accurate enough (≈ 1e-9 on the Miura sheet at 1.7° steps) for one corrector iteration to
// reach ORI_TOL_NEWTON. The history is a ring: slot (hist0 + i) % ORI_KIN_HISTORY holds the
// i-th oldest state. t_first (per unit drive, in the direction of motion) replaces the tangent
// of the first step out of a singular start; esc (may be NULL) supplies the states up to the
// escape.
//
// Step: at most min(output step, ORI_KIN_MAX_STEP_RAD) of drive, and at most ORI_KIN_MAX_TURN_RAD
// over the last step's rate max |Δθ|/Δs, so that no moving crease turns further; a prediction
// that still turns one further is shortened before it is corrected (outside the escape).
#define ORI_KIN_HISTORY 6

// The motion's step budget (ORI_KIN_MAX_WALK_STEPS) is spent: the walk stops where it is, a stop
// of kind ORI_BLOCK_STEP_LIMIT (not located: the branch goes on, the budget ended it).
static bool step_budget_spent(ctx *c)
{
    if ((long)c->mo->stats.steps + c->mo->stats.rejected_steps < c->max_steps) return false;
    c->blocked_at = c->th[c->jd];
    c->block_kind = ORI_BLOCK_STEP_LIMIT;
    c->block_joint = -1;
    return true;
}

// Whether an accepted step from th to x over the drive change ds folds back: the tangent at x
// (per unit drive), taken in the walk's direction, points against the step's secant in (drive,
// angles) space. The step then crossed a turning point of the drive onto the neighbouring
// branch (ORI_KIN_FOLDBACK_RATE). A state without a tangent (singular) is left to the stop logic.
static bool folds_back(ctx *c, const double *th, const double *x, double ds, double *tbuf)
{
    const ori_mechanism *m = c->m;
    if (!ori__kin_tangent(c->solver, x, tbuf)) return false;
    double dot = ds * ds;
    for (int j = 0; j < m->joint_count; ++j)
        if (j != c->jd) dot += (x[j] - th[j]) * ds * tbuf[j];
    return dot < 0.0;
}

static leg_result numeric_walk(ctx *c, double s1, double step_out, bool rec, const double *t_first,
                               const kin_escape *esc)
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
    double *scratch_t = ori__alloc(sizeof(double) * (size_t)(J + 1)); // the fold-back test's tangent
    double *hist = ori__alloc(sizeof(double) * (size_t)(J + 1) * ORI_KIN_HISTORY);
    double hs[ORI_KIN_HISTORY]; // drive values, oldest first
    int nh = 0, hist0 = 0;
#define HIST(i) (hist + (size_t)(((hist0) + (i)) % ORI_KIN_HISTORY) * (size_t)J)
    double sp = 0.0;
    bool have_prev = false;
    bool t_here = false; // t is the tangent at c->th (kept through a shortened prediction)
    double rate = 0.0;   // max |Δθ| / Δs of the last accepted step (0: none yet)
    leg_result result = LEG_OK;
    bool singular_first = t_first != NULL && esc == NULL;
    if (t_first) memcpy(t, t_first, sizeof(double) * (size_t)J);
    memcpy(HIST(0), c->th, sizeof(double) * (size_t)J);
    hs[0] = s;
    nh = 1;
    double h_max = fmin(step_out, ORI_KIN_MAX_STEP_RAD);
    double h = singular_first ? fmin(h_max, ORI_KIN_SINGULAR_STEP_RAD) : h_max;
    double s_start = c->grid_set ? c->grid0 : c->th[c->jd];
    int k_out = grid_first(c, c->th[c->jd], sg, step_out);
    bool out_here = true;
    double target = rec ? grid_target(c, s_start, s1, sg, step_out, k_out, c->grid_set, &out_here) : s1;
    bool first = true;
    for (;;) {
        s = c->th[c->jd];
        if (c->cancelled) break; // the progress callback asked to stop (ori_motion_solve fails)
        if (s == s1 && (!rec || target == s1)) break;
        if (step_budget_spent(c)) {
            result = LEG_BLOCKED;
            break;
        }
        double dist = fabs(target - s);
        // Within the escape the prediction does not depend on the step: go straight to the
        // next output value, but through the escape's end (beyond it the tangent takes over);
        // after a rejection no longer than the halved step h (else the same step is retried).
        bool in_esc = esc && (s - esc->s1) * sg < 0.0;
        // No crease turns more than ORI_KIN_MAX_TURN_RAD in a step, at the rate of the last one.
        if (!in_esc && rate > 0.0) h = fmin(h, ORI_KIN_MAX_TURN_RAD / rate);
        double hh = in_esc ? fmin(h, fmin(dist, fabs(esc->s1 - s))) : fmin(h, dist);
        if (c->approach_flat) hh = fmin(hh, fmax(0.5 * (fabs(s) - 16.0 * c->approach_floor), c->approach_floor));
        // A near-complete remainder is taken whole rather than left as a sliver.
        if (!in_esc && dist - hh < 0.25 * hh) hh = dist;
        double snew = hh == dist ? target : in_esc && hh == fabs(esc->s1 - s) ? esc->s1 : s + sg * hh;
        bool secant = !in_esc && nh >= ORI_KIN_HISTORY && fabs(snew - s) <= 2.0 * fabs(s - hs[nh - 2]);
        bool from_history = secant; // the prediction extrapolates earlier states
        double tn = 1.0;
        if (in_esc) {
            for (int j = 0; j < J; ++j) {
                if (c->col[j] < 0) {
                    pred[j] = c->th[j];
                    continue;
                }
                pred[j] = hermite(esc->s0, esc->th0[j], esc->t0[j], esc->s1, esc->th1[j], esc->t1[j], snew);
                tn = fmax(tn, fmax(fabs(esc->t0[j]), fabs(esc->t1[j])));
            }
        } else if (secant) {
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
            if (!(singular_first && first) && !t_here && !ori__kin_tangent(c->solver, c->th, t)) {
                // No tangent: the state is singular (a limit of the drive, a bifurcation).
                locate_stop(c, snew);
                result = LEG_BLOCKED;
                break;
            }
            t_here = !(singular_first && first);
            from_history = have_prev && fabs(snew - s) <= 2.0 * fabs(s - sp);
            for (int j = 0; j < J; ++j) {
                double lin = c->th[j] + (snew - s) * t[j];
                if (from_history && c->col[j] >= 0) lin = hermite(sp, thp[j], tp[j], s, c->th[j], t[j], snew);
                pred[j] = lin;
                tn = fmax(tn, fabs(t[j]));
            }
        }
        pred[c->jd] = snew;
        // The predicted state turns some crease by more than ORI_KIN_MAX_TURN_RAD (the branch
        // steepens): shorten the step before correcting. A steep branch is followed in steps
        // short against its turn, whatever the output step: a step across it could be corrected
        // onto another branch that passes within half the predicted change.
        if (!in_esc) {
            double turn = 0.0;
            for (int j = 0; j < J; ++j)
                if (c->col[j] >= 0) turn = fmax(turn, fabs(pred[j] - c->th[j]));
            // (Down to ORI_KIN_MIN_STEP_RAD: a step that short is corrected and judged as any.)
            if (turn > ORI_KIN_MAX_TURN_RAD && h > ORI_KIN_MIN_STEP_RAD) {
                h = fmax(ORI_KIN_TURN_SHRINK * hh * ORI_KIN_MAX_TURN_RAD / turn, ORI_KIN_MIN_STEP_RAD);
                continue;
            }
        }
        for (int j = 0; j < J; ++j) trial[j] = pred[j];
        trial[c->jd] = snew;
        int its = 0;
        double res = 0.0;
        bool ok = ori__kin_correct(c->solver, trial, ORI_KIN_NEWTON_MAX, &its, &res);
        c->mo->stats.newton_iterations += its;
        double move = 0.0;
        for (int j = 0; j < J; ++j) move = fmax(move, fabs(trial[j] - pred[j]));
        // Within the escape the prediction is the escape's interpolation, not a step's: its
        // correction is measured against the change from the singular start.
        double hj = in_esc ? fabs(snew - esc->s0) : hh;
        bool accept = ok && move <= ORI_KIN_MAX_CORRECTION * hj * tn + ORI_KIN_CORRECTION_SLACK_RAD;
        // A moving crease turned past ±π within this step (or only seems to, near a fully folded
        // state): halve; a stop there is located by locate_stop.
        if (accept && beyond_limit(c, trial)) accept = false;
        // A steep step that folded back onto the neighbouring branch (tangent reversed).
        if (accept && !in_esc && tn > ORI_KIN_FOLDBACK_RATE && folds_back(c, c->th, trial, snew - s, scratch_t))
            accept = false;
        if (!accept) {
            c->mo->stats.rejected_steps++;
            t_here = false; // as before the turn bound: the tangent is computed afresh after a correction
            h = 0.5 * hh;
            nh = 1; // restart the history from the current state
            hist0 = 0;
            memcpy(HIST(0), c->th, sizeof(double) * (size_t)J);
            hs[0] = s;
            if (h < ORI_KIN_MIN_STEP_RAD && from_history) {
                // Extrapolations of earlier states failed down to the shortest step (the branch
                // bends sharply: a steep turn out of a flat state): the tangent alone gets that
                // step once more before the walk stops.
                have_prev = false;
                h = hh;
                continue;
            }
            if (h < ORI_KIN_MIN_STEP_RAD) {
                locate_stop(c, snew);
                result = LEG_BLOCKED;
                break;
            }
            continue;
        }
        // Accepted.
        if (!secant && !in_esc) {
            for (int j = 0; j < J; ++j) {
                thp[j] = c->th[j];
                tp[j] = t[j];
            }
            sp = s;
            have_prev = true;
        }
        rate = 0.0;
        for (int j = 0; j < J; ++j)
            if (c->col[j] >= 0) rate = fmax(rate, fabs(trial[j] - c->th[j]));
        rate /= hh;
        for (int j = 0; j < J; ++j) c->th[j] = trial[j];
        t_here = false;
        if (nh == ORI_KIN_HISTORY) {
            hist0 = (hist0 + 1) % ORI_KIN_HISTORY;
            memmove(hs, hs + 1, sizeof(double) * (ORI_KIN_HISTORY - 1));
            nh--;
        }
        // States within the escape are fixed by its interpolation only to O(δ²) off the branch
        // (they close, but so does every state near a flat vertex): no extrapolation through
        // them; the history starts afresh at the escape's end (its tangent is exact).
        if (in_esc) nh = 0, hist0 = 0;
        memcpy(HIST(nh), c->th, sizeof(double) * (size_t)J);
        hs[nh++] = snew;
        c->mo->stats.steps++;
        c->last_residual = res;
        check_signs(c);
        first = false;
        if (its - ori__kin_solver_polish_iterations(c->solver) <= 3) h = fmin(2.0 * h, h_max);
        if (snew == target) {
            if (rec && out_here) record(c);
            if (target == s1) break;
            k_out++;
            target = grid_target(c, s_start, s1, sg, step_out, k_out, true, &out_here);
        }
    }
    ori__free(t);
    ori__free(tp);
    ori__free(thp);
    ori__free(pred);
    ori__free(trial);
    ori__free(scratch_t);
    ori__free(hist);
#undef HIST
    return result;
}

// Closed-form walk from the current drive value to s1, recording at each output value; esc
// (may be NULL) supplies the states up to the escape from a singular start (there the closed
// form loses half its digits: the state is the escape's interpolation, polished on the loop).
static leg_result analytic_walk(ctx *c, double s1, double step_out, bool rec, const double *t_first,
                                const kin_escape *esc)
{
    const ori_mechanism *m = c->m;
    int J = m->joint_count;
    int fj[3];
    free_joints(m, &c->sp, fj);
    double s = c->th[c->jd];
    const double s_walk0 = s; // a singular start when t_first
    bool steep_start = false;     // … out of which the branch turns very fast
    for (int i = 0; i < 3 && t_first; ++i) steep_start = steep_start || fabs(t_first[fj[i]]) > ORI_KIN_STEEP_START_RATE;
    if (s1 == s) return LEG_OK;
    double *scratch = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *fb_t = ori__alloc(sizeof(double) * (size_t)(J + 1)); // the fold-back test's tangent
    double sg = s1 > s ? 1.0 : -1.0;
    // The last accepted states (drive, three free angles), oldest first: the prediction is their
    // Lagrange extrapolation (as the numeric solver's), which also stands in where the closed
    // form is indeterminate (a family of states at one drive value, e.g. a branch crossing).
    double hs[ORI_KIN_HISTORY], hx[ORI_KIN_HISTORY][3];
    int nh = 1;
    hs[0] = s;
    for (int i = 0; i < 3; ++i) hx[0][i] = c->th[fj[i]];
    if (c->label == 0) {
        // The start's own label: the candidate at the start's drive value that is the start.
        double x0[3], cand0[2][3];
        int lab0[2];
        for (int i = 0; i < 3; ++i) x0[i] = c->th[fj[i]];
        int nc0 = ori__kin_spherical_solve(m, &c->sp, c->th, s, x0, cand0, lab0);
        for (int k = 0; k < nc0; ++k)
            if (cand_distance(cand0[k], x0) <= ORI_KIN_LABEL_MATCH_RAD && (nc0 == 1 || cand_distance(cand0[1 - k], x0) > ORI_KIN_LABEL_MATCH_RAD))
                c->label = lab0[k];
    }
    double s_start = c->grid_set ? c->grid0 : s;
    int k_out = grid_first(c, s, sg, step_out);
    bool out_here = true;
    double target = rec ? grid_target(c, s_start, s1, sg, step_out, k_out, c->grid_set, &out_here) : s1;
    double h = ORI_KIN_TRACK_STEP_RAD;
    double rate = 0.0; // max |Δθ| / Δs of the last accepted step (0: none yet)
    leg_result result = LEG_OK;
    bool first = true;
    for (;;) {
        s = c->th[c->jd];
        if (c->cancelled) break; // the progress callback asked to stop (ori_motion_solve fails)
        if (s == s1 && (!rec || target == s1)) break;
        if (step_budget_spent(c)) {
            result = LEG_BLOCKED;
            break;
        }
        double dist = fabs(target - s);
        bool in_esc = esc && (s - esc->s1) * sg < 0.0;
        // Out of the start the branch is the tangent's (the cone's at a singular start), as for
        // the numeric solver.
        bool by_cone = first && t_first && !esc;
        // The numeric solver's step control along a steep branch (ORI_KIN_MAX_TURN_RAD).
        if (!in_esc && rate > 0.0) h = fmin(h, ORI_KIN_MAX_TURN_RAD / rate);
        double hh = in_esc ? fmin(h, fmin(dist, fabs(esc->s1 - s))) : fmin(h, dist);
        if (c->approach_flat) hh = fmin(hh, fmax(0.5 * (fabs(s) - 16.0 * c->approach_floor), c->approach_floor));
        if (!in_esc && dist - hh < 0.25 * hh) hh = dist;
        double snew = hh == dist ? target : in_esc && hh == fabs(esc->s1 - s) ? esc->s1 : s + sg * hh;
        double pred[3];
        // One state known (the escape's end; a start without a tangent): the tangent there.
        bool by_tangent = !in_esc && !by_cone && nh == 1 && ori__kin_tangent(c->solver, c->th, scratch);
        double tan_here[3] = {0.0, 0.0, 0.0};
        if (by_tangent)
            for (int i = 0; i < 3; ++i) tan_here[i] = scratch[fj[i]];
        for (int i = 0; i < 3; ++i) {
            pred[i] = c->th[fj[i]];
            if (by_tangent)
                pred[i] += (snew - s) * tan_here[i];
            else if (in_esc)
                pred[i] = hermite(esc->s0, esc->th0[fj[i]], esc->t0[fj[i]], esc->s1, esc->th1[fj[i]], esc->t1[fj[i]], snew);
            else if (by_cone)
                pred[i] += (snew - s) * t_first[fj[i]];
            else if (nh > 1) {
                double w[ORI_KIN_HISTORY];
                lagrange_weights(hs, nh, snew, w);
                pred[i] = 0.0;
                for (int q = 0; q < nh; ++q) pred[i] += w[q] * hx[q][i];
            }
        }
        if (!in_esc) {
            double turn = 0.0;
            for (int i = 0; i < 3; ++i) turn = fmax(turn, fabs(pred[i] - c->th[fj[i]]));
            // (Down to ORI_KIN_MIN_STEP_RAD: a step that short is corrected and judged as any.)
            if (turn > ORI_KIN_MAX_TURN_RAD && h > ORI_KIN_MIN_STEP_RAD) {
                h = fmax(ORI_KIN_TURN_SHRINK * hh * ORI_KIN_MAX_TURN_RAD / turn, ORI_KIN_MIN_STEP_RAD);
                continue;
            }
        }
        double cand[2][3];
        int lab[2] = {0, 0};
        bool reachable = false;
        int nc = ori__kin_spherical_solve_ex(m, &c->sp, c->th, snew, pred, cand, lab, &reachable);
        int k = choose_candidate(c, cand, lab, nc, pred);
        if (in_esc) {
            // The branch is the escape's: its interpolation, polished.
            double x[3] = {pred[0], pred[1], pred[2]};
            if (ori__kin_spherical_polish(m, &c->sp, c->th, snew, x) <= 0.5 * ORI_TOL_RESIDUAL) {
                if (nc == 0) nc = 1;
                if (nc == 2 && cand_distance(cand[1 - k], x) < cand_distance(cand[k], x)) k = 1 - k;
                for (int i = 0; i < 3; ++i) cand[k][i] = x[i];
            } else {
                nc = 0;
            }
        }
        if (nc == 0 && reachable && !in_esc && steep_start && fabs(snew - s_walk0) < ORI_KIN_ESCAPE_RAD) {
            // Out of a singular start on a branch turning more than ORI_KIN_STEEP_START_RATE times
            // as fast as the drive, the input–output equation has roots but the polish closed none
            // of them (two creases within about 1e-5° of collinear, next to the flat state: the
            // equation has lost the digits): the corrector on the loop equations from the
            // prediction, judged as any. (No roots: beyond a limit of the drive, no state. Else the
            // closed form is left on its own: near a turning point the corrector would find states
            // beyond it.)
            memcpy(scratch, c->th, sizeof(double) * (size_t)J);
            for (int i = 0; i < 3; ++i) scratch[fj[i]] = pred[i];
            scratch[c->jd] = snew;
            int its = 0;
            double res = 0.0;
            if (ori__kin_correct(c->solver, scratch, ORI_KIN_NEWTON_MAX, &its, &res)) {
                for (int i = 0; i < 3; ++i) cand[0][i] = scratch[fj[i]];
                lab[0] = 0;
                nc = 1;
                k = 0;
            }
        }
        if (nc > 0) {
            memcpy(scratch, c->th, sizeof(double) * (size_t)J);
            for (int i = 0; i < 3; ++i) scratch[fj[i]] = cand[k][i];
            scratch[c->jd] = snew;
        }
        // The chosen solution is far from the prediction (the branch turns faster than the step
        // resolves, and the nearest candidate may be the other branch): the numeric solver's
        // test of a jump, then halve as it does.
        bool jump = false;
        if (nc > 0 && !in_esc) {
            double tn = 1.0, move = 0.0;
            for (int i = 0; i < 3; ++i) {
                tn = fmax(tn, fabs(pred[i] - c->th[fj[i]]) / hh);
                move = fmax(move, fabs(cand[k][i] - pred[i]));
            }
            jump = move > ORI_KIN_MAX_CORRECTION * hh * tn + ORI_KIN_CORRECTION_SLACK_RAD;
            // (a steep step onto the neighbouring branch: the tangent there reversed)
            if (!jump && tn > ORI_KIN_FOLDBACK_RATE && folds_back(c, c->th, scratch, snew - s, fb_t)) jump = true;
        }
        // No solution, a jump, or a moving crease turned past ±π within this step (or only seems
        // to, near a fully folded state): halve; a stop there is located by locate_stop.
        if (nc == 0 || jump || beyond_limit(c, scratch)) {
            // As in the numeric walk: where extrapolations of earlier states failed down to the
            // shortest step, the tangent gets that step once more before the walk stops.
            bool from_history = !in_esc && !by_cone && !by_tangent && nh > 1;
            c->mo->stats.rejected_steps++;
            // Restart the history from the current state (the tangent predicts the next try).
            hs[0] = s;
            for (int i = 0; i < 3; ++i) hx[0][i] = c->th[fj[i]];
            nh = 1;
            h = 0.5 * hh;
            if (h < ORI_KIN_MIN_STEP_RAD && from_history) {
                h = hh;
                continue;
            }
            if (h < ORI_KIN_MIN_STEP_RAD) {
                locate_stop(c, snew);
                result = LEG_BLOCKED;
                break;
            }
            continue;
        }
        c->has_alt = nc == 2;
        if (nc == 2)
            for (int i = 0; i < 3; ++i) c->alt[i] = cand[1 - k][i];
        if (lab[k] != 0) c->label = lab[k];
        rate = 0.0;
        for (int i = 0; i < 3; ++i) rate = fmax(rate, fabs(cand[k][i] - c->th[fj[i]]));
        rate /= hh;
        for (int i = 0; i < 3; ++i) c->th[fj[i]] = cand[k][i];
        c->th[c->jd] = snew;
        if (nh == ORI_KIN_HISTORY) {
            memmove(hs, hs + 1, sizeof(double) * (ORI_KIN_HISTORY - 1));
            memmove(hx, hx + 1, sizeof(hx[0]) * (ORI_KIN_HISTORY - 1));
            nh--;
        }
        hs[nh] = snew;
        for (int i = 0; i < 3; ++i) hx[nh][i] = cand[k][i];
        nh++;
        // The singular start is no point to extrapolate through (the branch need not be smooth
        // there): out of the escape the history starts afresh.
        if (in_esc && snew == esc->s1) {
            hs[0] = snew;
            for (int i = 0; i < 3; ++i) hx[0][i] = cand[k][i];
            nh = 1;
        }
        c->mo->stats.steps++;
        check_signs(c);
        first = false;
        h = fmin(2.0 * h, ORI_KIN_TRACK_STEP_RAD);
        if (snew == target) {
            if (rec && out_here) record(c);
            if (target == s1) break;
            k_out++;
            target = grid_target(c, s_start, s1, sg, step_out, k_out, true, &out_here);
        }
    }
    ori__free(scratch);
    ori__free(fb_t);
    return result;
}

static leg_result walk(ctx *c, double s1, double step_out, bool rec, const double *t_first, const kin_escape *esc)
{
    return c->analytic ? analytic_walk(c, s1, step_out, rec, t_first, esc) : numeric_walk(c, s1, step_out, rec, t_first, esc);
}

// A stop within ORI_KIN_ESCAPE_RAD of a singular start (or before any step) is no motion at all,
// unless a moving crease reached ±180° there: a steep branch out of the flat state (two creases
// within about 5e-4° of collinear) that folds a crease flat within that much drive is a motion.
static leg_result classify_stop(const ctx *c, leg_result r, double s_start, bool singular)
{
    if (r != LEG_BLOCKED) return r;
    double moved = fabs(c->blocked_at - s_start);
    if (moved == 0.0 || (singular && moved < ORI_KIN_ESCAPE_RAD && c->block_kind != ORI_BLOCK_CREASE_LIMIT)) return LEG_NONE;
    return LEG_BLOCKED;
}

// --- through the flat state -----------------------------------------------------------------

// The state at drive value snew nearest to the prediction pred (all joints; its free creases
// matter), from the state c->th: the closed-form candidate nearest to it (*alt, *has_alt: the
// other one), or the corrector from it. The numeric solver's jump test on the correction (a step
// of size hh): false when the state found is not the one predicted, or is beyond ±π.
static bool state_near(ctx *c, double snew, const double *pred, double hh, double *out, double *res, bool *has_alt,
                       double alt[3])
{
    const ori_mechanism *m = c->m;
    int J = m->joint_count;
    memcpy(out, pred, sizeof(double) * (size_t)J);
    out[c->jd] = snew;
    *has_alt = false;
    *res = -1.0;
    double tn = 1.0;
    for (int j = 0; j < J; ++j)
        if (c->col[j] >= 0) tn = fmax(tn, fabs(pred[j] - c->th[j]) / fmax(hh, 1e-300));
    if (c->analytic) {
        int fj[3];
        double p3[3], cand[2][3];
        free_joints(m, &c->sp, fj);
        for (int i = 0; i < 3; ++i) p3[i] = pred[fj[i]];
        int lab[2];
        int nc = ori__kin_spherical_solve(m, &c->sp, c->th, snew, p3, cand, lab);
        if (nc == 0) return false;
        // Nearest to the prediction (a crossing: the label changes there), which sets the label.
        int k = nc == 2 && cand_distance(cand[1], p3) < cand_distance(cand[0], p3) ? 1 : 0;
        c->label = lab[k];
        for (int i = 0; i < 3; ++i) out[fj[i]] = cand[k][i];
        *has_alt = nc == 2;
        if (nc == 2)
            for (int i = 0; i < 3; ++i) alt[i] = cand[1 - k][i];
    } else {
        int its = 0;
        bool ok = ori__kin_correct(c->solver, out, ORI_KIN_NEWTON_MAX, &its, res);
        c->mo->stats.newton_iterations += its;
        if (!ok) return false;
    }
    double move = 0.0;
    for (int j = 0; j < J; ++j)
        if (c->col[j] >= 0) move = fmax(move, fabs(out[j] - pred[j]));
    return move <= ORI_KIN_MAX_CORRECTION * hh * tn + ORI_KIN_CORRECTION_SLACK_RAD && !beyond_limit(c, out);
}

// Whether a leg from s to s1 may pass through the flat state: the drive changes sign and every
// crease that does not move (locked, F, J) is flat, so the flat sheet is a state of the motion.
static bool flat_locks(const ctx *c)
{
    for (int j = 0; j < c->m->joint_count; ++j)
        if (c->col[j] < 0 && j != c->jd && c->th[j] != 0.0) return false;
    return true;
}
static bool may_cross_flat(const ctx *c, double s, double s1) { return s * s1 < 0.0 && flat_locks(c); }

// Descending order of doubles (qsort).
static int cmp_desc(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x < y) - (x > y);
}

// The output states of a crossing (cross_flat) strictly between s_a (state tha, tangent ta per
// unit drive) and s_b = −s_a, and the leg's end s1 when it lies there (s_end: s1 then, else s_b),
// recorded in order when rec. Next to the flat state neither solver tells the two branches apart
// (they separate in proportion to the drive: the closed form's double root merges them within
// about 1e-6 rad, and the corrector's error grows as 1/σ_min there), and a prediction corrected
// there may land between them. So: the output value v with |v| ≥ s_n is the state of the
// incoming branch walked from s_a towards 0 to ±|v| (the same walk as any, the drive's sign
// that of s_a), mirrored when v lies beyond 0 (θ(−v) = −θ(v)); within s_n of 0 it is the odd
// cubic through the node (s_n, θ_n, t_n) and its mirror, exactly flat at 0. The node is s_a
// halved ORI_KIN_CROSS_NODE_HALVINGS times, not nearer than ORI_KIN_MIN_APPROACH_RAD (nor farther
// than s_a): walked only when some output value lies within it. c->th ends at the last value's
// state; LEG_BLOCKED (c->th at the stop, the values before it recorded) when a walk stops.
static leg_result cross_flat_outputs(ctx *c, double s1, double s_end, double step_out, bool rec, const double *tha,
                                     const double *ta)
{
    const ori_mechanism *m = c->m;
    int J = m->joint_count, jd = c->jd;
    size_t bytes = sizeof(double) * (size_t)J;
    double sa = tha[jd], sg = sa < 0.0 ? 1.0 : -1.0, sb = -sa;
    // The output values, in order.
    int nv = 0, cap = 8;
    double *gv = ori__alloc(sizeof(double) * (size_t)cap);
    for (int k = grid_first(c, sa, sg, step_out);; ++k) {
        bool out = true;
        double g = rec ? grid_target(c, c->grid0, s_end, sg, step_out, k, true, &out) : s1;
        if (!out || g == sb) break;
        if (nv == cap) gv = ori__realloc(gv, sizeof(double) * (size_t)(cap *= 2));
        gv[nv++] = g;
        if (g == s1 || !rec) break;
    }
    // The distances from 0 walked to on the incoming branch, farthest first: the output values'
    // beyond the node, and the node's when some value lies within it.
    double sn = fmin(fabs(sa), fmax(ldexp(fabs(sa), -ORI_KIN_CROSS_NODE_HALVINGS), ORI_KIN_MIN_APPROACH_RAD));
    double *wv = ori__alloc(sizeof(double) * (size_t)(nv + 1));
    int nw = 0;
    bool inner = false;
    for (int i = 0; i < nv; ++i) {
        if (fabs(gv[i]) >= sn) wv[nw++] = fabs(gv[i]);
        else inner = true;
    }
    if (inner) wv[nw++] = sn;
    qsort(wv, (size_t)nw, sizeof(double), cmp_desc);
    int nu = 0;
    for (int i = 0; i < nw; ++i)
        if (nu == 0 || wv[i] != wv[nu - 1]) wv[nu++] = wv[i];
    nw = nu;
    double *ws = ori__alloc(bytes * (size_t)(nw + 1));
    double *walt = ori__alloc(sizeof(double) * 3 * (size_t)(nw + 1));
    bool *whas = ori__alloc(sizeof(bool) * (size_t)(nw + 1));
    double *x = ori__alloc(bytes + sizeof(double)), *tn = ori__alloc(bytes + sizeof(double));
    leg_result r = LEG_OK;
    int walked = 0;
    memcpy(c->th, tha, bytes);
    for (int i = 0; i < nw && !c->cancelled; ++i) {
        double v = sa < 0.0 ? -wv[i] : wv[i];
        if (v != c->th[jd]) {
            c->approach_flat = true;
            c->approach_floor = ORI_KIN_MIN_APPROACH_RAD;
            r = walk(c, v, step_out, false, NULL, NULL);
            c->approach_flat = false;
            if (r != LEG_OK) break;
        }
        memcpy(ws + (size_t)i * (size_t)J, c->th, bytes);
        whas[i] = c->analytic && c->has_alt;
        if (whas[i]) memcpy(walt + 3 * i, c->alt, sizeof c->alt);
        walked = i + 1;
    }
    // The odd cubic θ(v) = α v + β v³ through the node (v_n, θ_n, t_n) and its mirror.
    bool node = inner && walked == nw && r == LEG_OK;
    if (node) {
        const double *thn = ws + (size_t)(nw - 1) * (size_t)J;
        double vn = thn[jd];
        if (vn == tha[jd]) memcpy(tn, ta, bytes);
        else if (!ori__kin_tangent(c->solver, thn, tn))
            for (int j = 0; j < J; ++j) tn[j] = thn[j] / vn; // (not expected: a regular state)
        for (int j = 0; j < J; ++j) {
            double q = thn[j] / vn;
            x[j] = 0.5 * (3.0 * q - tn[j]);                // α
            tn[j] = (tn[j] - q) / (2.0 * vn * vn);        // β
        }
    }
    double *stop = NULL;
    if (r != LEG_OK) {
        stop = ori__alloc(bytes + sizeof(double));
        memcpy(stop, c->th, bytes);
    }
    double *alpha = x, *beta = tn, *y = ori__alloc(bytes + sizeof(double));
    for (int i = 0; i < nv && !c->cancelled; ++i) {
        double g = gv[i], a = fabs(g);
        bool mirror = g * sa < 0.0, has_alt = false;
        double alt[3] = {0.0, 0.0, 0.0};
        if (a >= sn) {
            int w = 0;
            while (w < nw && wv[w] != a) ++w;
            if (w >= walked || (mirror && r != LEG_OK)) break;
            const double *src = ws + (size_t)w * (size_t)J;
            for (int j = 0; j < J; ++j) y[j] = mirror && c->col[j] >= 0 ? -src[j] : src[j];
            has_alt = whas[w];
            for (int q = 0; q < 3 && has_alt; ++q) alt[q] = mirror ? -walt[3 * w + q] : walt[3 * w + q];
        } else {
            if (!node) break;
            for (int j = 0; j < J; ++j) y[j] = c->col[j] >= 0 ? (g == 0.0 ? 0.0 : (alpha[j] + beta[j] * g * g) * g) : tha[j];
        }
        y[jd] = g;
        memcpy(c->th, y, bytes);
        c->last_residual = -1.0; // measured by record
        c->has_alt = has_alt;
        if (has_alt) memcpy(c->alt, alt, sizeof alt);
        check_signs(c);
        if (rec) record(c);
    }
    if (stop) memcpy(c->th, stop, bytes);
    ori__free(stop);
    ori__free(y);
    ori__free(x);
    ori__free(tn);
    ori__free(ws);
    ori__free(walt);
    ori__free(whas);
    ori__free(wv);
    ori__free(gv);
    return r;
}

// A leg from a folded state through the flat state (drive 0) to s1 on the other side. The flat
// state is a singular point: the two branches of a degree-4 vertex cross there (in general a
// bifurcation), and close to it a corrector started from a large step cannot tell them apart.
// The rule: the motion continues on the branch whose tangent continues the incoming one. With
// every non-moving crease flat, the mirror image of a state (every angle negated) is a state (the
// axes lie in the plane of the sheet, and M R(a, θ) M = R(a, −θ) for the reflection M in it), and
// a smooth branch through the flat state is its own mirror image (same tangent line there): its
// state at −s is exactly −θ(s). Both solvers: walk to s_a = ∓ORI_KIN_SINGULAR_STEP_RAD before the
// crossing (or start there when nearer), state θ_a, tangent t_a; the departure is (−s_a, −θ_a,
// t_a), exactly; the output states in between are the cubic Hermite interpolation of the two (odd,
// so through the flat state, exactly flat at 0), corrected; the walk goes on from −s_a. The
// branch must reach the flat state: |θ_a| of the order of |s_a t_a|, and the interpolation at
// s_a/2 corrects within the jump test; else the leg is walked as usual.
static leg_result cross_flat(ctx *c, double s1, double step_out, bool rec)
{
    const ori_mechanism *m = c->m;
    int J = m->joint_count;
    double s = c->th[c->jd];
    double sg = s1 > s ? 1.0 : -1.0;
    bool had_grid = c->grid_set;
    double g0 = c->grid0, gend = c->grid_end;
    if (!had_grid) {
        c->grid_set = true;
        c->grid0 = s;
        c->grid_end = s1;
    }
    size_t bytes = sizeof(double) * (size_t)J;
    double *tha = ori__alloc(bytes + sizeof(double)), *ta = ori__alloc(bytes + sizeof(double));
    double *thb = ori__alloc(bytes + sizeof(double)), *pred = ori__alloc(bytes + sizeof(double));
    double *x = ori__alloc(bytes + sizeof(double));
    leg_result r = LEG_OK;
    double sa = fabs(s) > ORI_KIN_SINGULAR_STEP_RAD ? -sg * ORI_KIN_SINGULAR_STEP_RAD : s, sb = -sa;
    // Approach until the branch is nearly straight: its linear extrapolation to the flat state
    // lands within a quarter of the state's size of it (a steep branch, as where two creases are
    // nearly collinear, is approached closer: s_a halves, at most ORI_KIN_CROSS_HALVINGS times).
    bool heads = false;
    double big = 0.0;
    for (int halving = 0;; ++halving, sa *= 0.5) {
        if (sa != c->th[c->jd]) {
            c->approach_flat = true;
            c->approach_floor = ORI_KIN_MIN_APPROACH_RAD;
            r = walk(c, sa, step_out, rec, NULL, NULL);
            c->approach_flat = false;
            if (r != LEG_OK || c->cancelled) goto done;
        }
        memcpy(tha, c->th, bytes);
        if (!ori__kin_tangent(c->solver, tha, ta)) break;
        big = 0.0;
        double off = 0.0;
        for (int j = 0; j < J; ++j)
            if (c->col[j] >= 0) {
                big = fmax(big, fabs(tha[j]));
                off = fmax(off, fabs(tha[j] - sa * ta[j]));
            }
        if (off <= 0.25 * big + ORI_TOL_RESIDUAL) {
            heads = true;
            break;
        }
        if (halving == ORI_KIN_CROSS_HALVINGS) break;
    }
    sb = -sa;
    for (int j = 0; j < J; ++j) thb[j] = c->col[j] >= 0 ? -tha[j] : tha[j];
    thb[c->jd] = sb;
    ta[c->jd] = 1.0;
    bool ha = false;
    double al[3], res = -1.0;
    if (heads) {
        for (int j = 0; j < J; ++j) pred[j] = c->col[j] >= 0 ? hermite(sa, tha[j], ta[j], sb, thb[j], ta[j], 0.5 * sa) : tha[j];
        heads = state_near(c, 0.5 * sa, pred, 0.5 * fabs(sa), x, &res, &ha, al);
    }
    if (!heads) {
        r = walk(c, s1, step_out, rec, NULL, NULL);
        goto done;
    }
    // The output values strictly between s_a and s_b (and the leg's end, when it lies there).
    bool ends_here = (sb - s1) * sg > 0.0;
    double s_end = ends_here ? s1 : sb;
    if (rec || ends_here) {
        r = cross_flat_outputs(c, s1, s_end, step_out, rec, tha, ta);
        if (r != LEG_OK) goto done;
    }
    if (ends_here || c->cancelled) goto done; // c->th is the state at s1
    // The departure, exactly the mirror image (the closed form's candidate nearest to it, or
    // the corrector from it, to the same rounding).
    memcpy(c->th, tha, bytes);
    if (!state_near(c, sb, thb, fabs(sb - sa), x, &res, &ha, al)) {
        locate_stop(c, sb);
        r = LEG_BLOCKED;
        goto done;
    }
    memcpy(c->th, x, bytes);
    c->last_residual = res;
    c->has_alt = ha;
    if (ha) memcpy(c->alt, al, sizeof al);
    check_signs(c);
    if (sb == s1) {
        if (rec) record(c);
        goto done;
    }
    r = walk(c, s1, step_out, rec, NULL, NULL);
done:
    c->grid_set = had_grid;
    c->grid0 = g0;
    c->grid_end = gend;
    ori__free(tha);
    ori__free(ta);
    ori__free(thb);
    ori__free(pred);
    ori__free(x);
    return r;
}

// Towards the flat state (a singular point) no step lands near it from afar; with the
// non-moving creases nearly flat (within λ) the two branches pass within about λ of each other
// near drive 0: steps no longer than half the distance to the band |s| ≤ 2λ, and λ/8 within it,
// towards it and through it (a leg from s to s1).
static void approach_flat(ctx *c, double s, double s1)
{
    double lam = 0.0;
    for (int j = 0; j < c->m->joint_count; ++j)
        if (c->col[j] < 0 && j != c->jd) lam = fmax(lam, fabs(c->th[j]));
    c->approach_flat = lam <= ORI_KIN_NEAR_FLAT_RAD && (s * s1 < 0.0 || fabs(s1) < fabs(s));
    c->approach_floor = fmax(ORI_KIN_MIN_APPROACH_RAD, 0.125 * lam);
}

// A leg from the current drive value to s1 (closed form or numeric). At a singular start, the cone analysis gives
// the branch's tangent; the walk first escapes silently a fixed ORI_KIN_SINGULAR_STEP_RAD
// along it (whatever the output step and the target), the rank is judged there, and the
// output walk then interpolates the escape: the verdict depends on neither --step nor a tiny
// target.
static leg_result run_leg(ctx *c, double s1, double step_out, bool rec)
{
    const ori_mechanism *m = c->m;
    int J = m->joint_count;
    double s = c->th[c->jd];
    if (s1 == s) return LEG_OK;
    c->label = 0;
    c->leg_end = s1;
    double sg = s1 > s ? 1.0 : -1.0;
    double *t = ori__alloc(sizeof(double) * (size_t)(J + 1));
    leg_result r;
    if (!start_singular(c, t)) {
        // The closed form takes its first step along the tangent too (its own candidates are
        // told apart by nearness to the prediction).
        if (may_cross_flat(c, s, s1)) {
            r = classify_stop(c, cross_flat(c, s1, step_out, rec), s, false);
        } else {
            approach_flat(c, s, s1);
            r = classify_stop(c, c->analytic ? analytic_walk(c, s1, step_out, rec, t, NULL) : walk(c, s1, step_out, rec, NULL, NULL), s, false);
            c->approach_flat = false;
        }
        ori__free(t);
        return r;
    }
    int extra = 0;
    kin_cone_result cr = ori__kin_cone(m, c->th, c->col, c->ncols, c->jd, sg, false, t, &extra);
    if (cr == KIN_CONE_NONE || cr == KIN_CONE_INCOMPATIBLE) {
        c->incompatible = cr == KIN_CONE_INCOMPATIBLE;
        ori__free(t);
        return LEG_NONE;
    }
    if (cr == KIN_CONE_UNDERDETERMINED) {
        c->extra_dof = extra;
        ori__free(t);
        return LEG_UNDER;
    }
    if (cr == KIN_CONE_VIOLATING) c->cone_violating = true;
    for (int j = 0; j < J; ++j) t[j] *= sg; // per unit drive: v has v[jd] = ±1
    kin_escape esc;
    esc.s0 = s;
    esc.t0 = t;
    esc.th0 = ori__alloc(sizeof(double) * (size_t)(J + 1));
    esc.th1 = ori__alloc(sizeof(double) * (size_t)(J + 1));
    esc.t1 = ori__alloc(sizeof(double) * (size_t)(J + 1));
    memcpy(esc.th0, c->th, sizeof(double) * (size_t)J);
    double se = s + sg * ORI_KIN_SINGULAR_STEP_RAD;
    if (fabs(se) > ORI_PI) se = sg * ORI_PI;
    // The worst wrong-sign angles of the escape count only where the output reaches.
    double *worst = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *worst_at = ori__alloc(sizeof(double) * (size_t)(J + 1));
    memcpy(worst, c->worst, sizeof(double) * (size_t)J);
    memcpy(worst_at, c->worst_at, sizeof(double) * (size_t)J);
    r = classify_stop(c, walk(c, se, ORI_KIN_SINGULAR_STEP_RAD, false, t, NULL), s, true);
    if (r == LEG_OK) {
        // Out of the singular start the constrained Jacobian must be regular, else the fold
        // leaves freedom the drive does not fix.
        int n2 = ori__kin_solver_nullity(c->solver, c->th);
        if (n2 > 0) {
            c->extra_dof = n2;
            r = LEG_UNDER;
        }
    }
    if ((r == LEG_OK || r == LEG_BLOCKED) && !c->cancelled) {
        // The escape's first node: its end, where the branch is nearly straight from the start;
        // else (a steep branch: two creases nearly collinear turn by 170° within 0.1° of drive)
        // the state at half the distance, walked afresh from the start along the cone tangent.
        esc.s1 = c->th[c->jd];
        memcpy(esc.th1, c->th, sizeof(double) * (size_t)J);
        bool straight = r == LEG_OK && ori__kin_tangent(c->solver, c->th, esc.t1) && escape_straight(c, &esc);
        if (!straight)
            for (int j = 0; j < J; ++j) esc.t1[j] = (esc.th1[j] - esc.th0[j]) / (esc.s1 - esc.s0);
        double delta = fabs(esc.s1 - s);
        double *tk = ori__alloc(sizeof(double) * (size_t)(J + 1));
        for (int k = 0; !straight && k < ORI_KIN_ESCAPE_HALVINGS && !c->cancelled; ++k) {
            delta *= 0.5;
            memcpy(c->th, esc.th0, sizeof(double) * (size_t)J);
            c->label = 0;
            if (walk(c, s + sg * delta, delta, false, t, NULL) != LEG_OK) break; // keep the node before
            if (!ori__kin_tangent(c->solver, c->th, tk)) continue;
            esc.s1 = c->th[c->jd];
            memcpy(esc.th1, c->th, sizeof(double) * (size_t)J);
            memcpy(esc.t1, tk, sizeof(double) * (size_t)J);
            straight = escape_straight(c, &esc);
        }
        ori__free(tk);
    }
    memcpy(c->worst, worst, sizeof(double) * (size_t)J);
    memcpy(c->worst_at, worst_at, sizeof(double) * (size_t)J);
    ori__free(worst);
    ori__free(worst_at);
    if ((r == LEG_OK || r == LEG_BLOCKED) && !c->cancelled) {
        memcpy(c->th, esc.th0, sizeof(double) * (size_t)J);
        c->label = 0;
        c->block_kind = ORI_BLOCK_NONE;
        c->block_joint = -1;
        if (r == LEG_OK && may_cross_flat(c, s, s1) && esc.s1 * s > 0.0) {
            // From a fully folded start through the flat state to the other side: the escape
            // (as below), then the crossing as from any folded state (cross_flat: the branch
            // goes on as its own mirror image), on one output grid from s.
            bool had_grid = c->grid_set;
            double g0 = c->grid0, gend = c->grid_end;
            if (!had_grid) {
                c->grid_set = true;
                c->grid0 = s;
                c->grid_end = s1;
            }
            r = walk(c, esc.s1, step_out, rec, t, &esc);
            if (r == LEG_OK && !c->cancelled) r = cross_flat(c, s1, step_out, rec);
            c->grid_set = had_grid;
            c->grid0 = g0;
            c->grid_end = gend;
            r = classify_stop(c, r, s, true);
        } else {
            // From a fully folded start the leg may head for the flat state (unfolding).
            approach_flat(c, s, s1);
            r = classify_stop(c, walk(c, s1, step_out, rec, t, &esc), s, true);
            c->approach_flat = false;
        }
    }
    ori__free(esc.th0);
    ori__free(esc.th1);
    ori__free(esc.t1);
    ori__free(t);
    return r;
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

static double deg(double rad) { return ori_rad_to_deg_output(rad); }

// The creases that move without the drive at a singular stop: the right singular vector of the
// smallest singular value of the Jacobian over the free creases (dense SVD; skipped above
// ORI_KIN_SINGULAR_SET_MAX_COLS free creases or ORI_DOF_DENSE_MAX_ENTRIES entries).
static void singular_set(const ctx *c, ori_motion_block *b)
{
    const ori_mechanism *m = c->m;
    int n = c->ncols, rows = m->rows;
    b->singular_count = 0;
    if (n == 0 || rows == 0 || n > ORI_KIN_SINGULAR_SET_MAX_COLS ||
        (size_t)rows * (size_t)n > (size_t)ORI_DOF_DENSE_MAX_ENTRIES)
        return;
    double *blocks = ori__calloc((size_t)(6 * m->loop_col_total) + 1, sizeof(double));
    ori__kin_eval(m, c->th, NULL, blocks, NULL);
    int ld = rows > n ? rows : n; // at least n rows so that every right singular vector exists
    double *a = ori__calloc((size_t)ld * (size_t)n, sizeof(double));
    for (int l = 0; l < m->loop_count; ++l) {
        const kin_loop *L = &m->loops[l];
        for (int k = 0; k < L->col_count; ++k) {
            int col = c->col[m->loop_cols[L->col_first + k]];
            if (col < 0) continue;
            for (int r = 0; r < L->rows; ++r) a[(size_t)(L->row0 + r) + (size_t)ld * (size_t)col] = blocks[6 * (L->col_first + k) + r];
        }
    }
    double *sv = ori__alloc(sizeof(double) * (size_t)(n + 1));
    double *vt = ori__alloc(sizeof(double) * (size_t)n * (size_t)n);
    double *sup = ori__alloc(sizeof(double) * (size_t)(n + 1));
    lapack_int info = LAPACKE_dgesvd(LAPACK_COL_MAJOR, 'N', 'A', ld, n, a, ld, sv, NULL, 1, vt, n, sup);
    if (info == 0) {
        // Row n − 1 of Vᵀ: the direction of the smallest singular value.
        double big = 0.0;
        for (int k = 0; k < n; ++k) big = fmax(big, fabs(vt[(n - 1) + (size_t)n * (size_t)k]));
        for (int j = 0; j < m->joint_count && big > 0.0; ++j) {
            int k = c->col[j];
            if (k < 0 || fabs(vt[(n - 1) + (size_t)n * (size_t)k]) < ORI_KIN_SINGULAR_SET_REL * big) continue;
            if (b->singular_count < 32) b->singular_edges[b->singular_count] = m->joints[j].edge;
            b->singular_count++;
        }
        if (b->singular_count > 32) b->singular_count = 32;
    }
    ori__free(blocks);
    ori__free(a);
    ori__free(sv);
    ori__free(vt);
    ori__free(sup);
}

// The reason of a stop: "the motion stops at crease D = X°: …".
static void describe_stop(ori_motion *mo, const ori_motion_block *b, int driven_edge)
{
    size_t len = strlen(mo->reason);
    char *p = mo->reason + len;
    size_t room = sizeof mo->reason - len;
    if (b->kind == ORI_BLOCK_CREASE_LIMIT) {
        snprintf(p, room,
                 "the motion stops at crease %d = %.10g°, where crease %d reaches %.10g° (the limit %s180°: beyond, "
                 "its faces would pass through each other)",
                 driven_edge, deg(b->drive_rad), b->edge, deg(b->edge_angle_rad), b->edge_angle_rad < 0 ? "-" : "");
        return;
    }
    if (b->kind == ORI_BLOCK_STEP_LIMIT) {
        snprintf(p, room,
                 "the motion stopped at crease %d = %.10g° after %d continuation steps (the budget): the drive barely "
                 "moves along this branch there, the motion beyond is undetermined",
                 driven_edge, deg(b->drive_rad), mo->stats.steps + mo->stats.rejected_steps);
        return;
    }
    int w = snprintf(p, room, "the motion stops at crease %d = %.10g°, a singular point (a limit of the drive or a "
                              "bifurcation)",
                     driven_edge, deg(b->drive_rad));
    if (w < 0 || (size_t)w >= room || b->singular_count == 0) return;
    p += w;
    room -= (size_t)w;
    w = snprintf(p, room, " where crease%s", b->singular_count == 1 ? "" : "s");
    for (int i = 0; i < b->singular_count && w >= 0 && (size_t)w < room; ++i) {
        p += w;
        room -= (size_t)w;
        w = snprintf(p, room, "%s%d", i == 0 ? " " : i + 1 == b->singular_count ? " and " : ", ", b->singular_edges[i]);
    }
    if (w >= 0 && (size_t)w < room) snprintf(p + w, room - (size_t)w, " can move with the drive held");
}

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
    {
        // The budget is on top of the steps the output asks for (every output state is a step's
        // end): twice the planned output steps of the whole way (from, then to).
        double s0 = def->start_angles_rad ? def->start_angles_rad[def->driven_edge] : 0.0, way = 0.0;
        if (def->has_from) way = fabs(def->from_rad - s0) + fabs(def->to_rad - def->from_rad);
        else way = fabs(def->to_rad - s0);
        double planned = def->step_rad > 0.0 ? way / def->step_rad : 0.0;
        double budget = (def->max_steps > 0 ? def->max_steps : ORI_KIN_MAX_WALK_STEPS) + 2.0 * fmin(planned, 1e9);
        c.max_steps = budget < 2e9 ? (long)budget : 2000000000L;
    }
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
    mo->last_only = def->last_frame_only;
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
    // The start is a state of the motion: a crease already against its assignment there counts
    // (else whether it is caught would depend on where the first steps land).
    check_signs(&c);

    // Leg 1 (silent) to from, leg 2 from → to with output.
    leg_result lr = LEG_OK;
    if (def->has_from && def->from_rad != c.th[jd]) lr = run_leg(&c, def->from_rad, fabs(def->from_rad - c.th[jd]), false);
    if (lr == LEG_OK) {
        // Frames: the start, one per step, the target (capped: a tiny step grows the arrays).
        double span = fabs(def->to_rad - c.th[jd]) / def->step_rad;
        reserve_frames(&c, mo->last_only ? 1 : span < ORI_KIN_RESERVE_FRAMES ? (int)span + 3 : ORI_KIN_RESERVE_FRAMES);
        c.progress = def->progress;
        c.progress_user = def->progress_user;
        c.progress_on = def->progress != NULL;
        c.prog_from = c.th[jd];
        c.prog_to = def->to_rad;
        record(&c);
        lr = run_leg(&c, def->to_rad, def->step_rad, true);
        c.progress_on = false;
    }
    if (c.cancelled) {
        st = ori__fail(error, ORI_ERR_LIMIT, "cancelled");
        goto fail;
    }
    mo->block.kind = ORI_BLOCK_NONE;
    mo->block.edge = ORI_NULL_INDEX;
    if (lr == LEG_BLOCKED) {
        // The stop itself closes the output (partial: up to the stop).
        if (mo->nframes > 0 && mo->drive[mo->nframes - 1] != c.th[jd]) record(&c);
        ori_motion_block *b = &mo->block;
        b->kind = c.block_kind == ORI_BLOCK_NONE ? ORI_BLOCK_SINGULAR : c.block_kind;
        b->drive_rad = c.th[jd];
        if (b->kind == ORI_BLOCK_CREASE_LIMIT) {
            b->edge = m->joints[c.block_joint].edge;
            b->edge_angle_rad = fmax(-ORI_PI, fmin(ORI_PI, c.th[c.block_joint]));
        } else if (b->kind == ORI_BLOCK_SINGULAR) {
            singular_set(&c, b);
        }
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
                v.angle_rad = fmax(-ORI_PI, fmin(ORI_PI, c.worst[j]));
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
        if (lr == LEG_BLOCKED) {
            size_t len = strlen(mo->reason);
            if (len + 3 < sizeof mo->reason) memcpy(mo->reason + len, "; ", 3);
            describe_stop(mo, &mo->block, def->driven_edge);
        }
    } else if (lr == LEG_BLOCKED) {
        mo->verdict = ORI_MOTION_BLOCKED;
        mo->reason[0] = '\0';
        describe_stop(mo, &mo->block, def->driven_edge);
    } else {
        mo->verdict = ORI_MOTION_VALID;
    }

    if (mo->nframes == 0) mo->stats.frames = 0;
    // The solver (its CHOLMOD factor) is done: freed before the DOF's own factorization, so that
    // one factor less is alive at the peak of a large fold.
    ori__kin_solver_destroy(c.solver);
    c.solver = NULL;
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
    ori__free(c.col);
    ori__free(c.th);
    ori__free(c.worst);
    ori__free(c.worst_at);
    if (def->progress && !def->progress(1.0, def->progress_user)) {
        ori_motion_destroy(mo);
        return ori__fail(error, ORI_ERR_LIMIT, "cancelled");
    }
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

bool ori_motion_block_of(const ori_motion *mo, ori_motion_block *out)
{
    ORI_ASSERT(mo);
    if (mo->block.kind == ORI_BLOCK_NONE) return false;
    if (out) *out = mo->block;
    return true;
}
int ori_motion_dof(const ori_motion *mo) { ORI_ASSERT(mo); return mo->dof; }

const double *ori_motion_angles(const ori_motion *mo, int *frame_stride)
{
    ORI_ASSERT(mo);
    if (frame_stride) *frame_stride = mo->edge_count + 1;
    return mo->nframes > 0 ? mo->angles : NULL;
}

const ori_v3 *ori_motion_vertices(ori_motion *mo)
{
    ORI_ASSERT(mo);
    if (mo->nframes == 0) return NULL;
    if (!mo->vertices) {
        size_t V = (size_t)ori_mechanism_vertex_count(mo->m);
        mo->vertices = ori__alloc(sizeof(ori_v3) * ((size_t)mo->nframes * V + 1));
        for (int k = 0; k < mo->nframes; ++k) ori_motion_frame_vertices(mo, k, mo->vertices + (size_t)k * V);
    }
    return mo->vertices;
}
