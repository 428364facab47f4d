// Fold toward target angles (the rigid, exact counterpart of Origami Simulator's "fold percent"),
// and the minimum-norm engine shared with drives.c.
//
// Method (Tachi, "Simulation of rigid origami", 2009): at a state θ on the loop-closure manifold
// the remaining change toward the goal, d = θ_goal − θ, is projected onto the null space of the
// Jacobian, p = (I − J⁺J) d = d − Jᵀ (J Jᵀ)⁻¹ J d; a step along p (at most
// ORI_MULTIFOLD_MAX_STEP_RAD on any crease) is then pulled back onto the manifold by Newton's
// method with minimum-norm corrections, to ORI_TOL_RESIDUAL. J Jᵀ is factored by CHOLMOD with a
// Tikhonov term λ = ORI_MULTIFOLD_LAMBDA: rows the state makes zero (the flat sheet's
// out-of-plane rows) or dependent then carry no weight, and Jᵀ removes their components.
// Since d · p = |p|² ≥ 0, each step brings the state nearer to the goal to first order; the fold
// ends when the goal is reached, when p vanishes (stationary: what remains is normal to every
// rigid motion), when a crease would pass ±180° (limit; a crease whose own target is ±180° is
// held there instead, and the others go on), or when no step, however small, can be corrected
// (singular).
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "multifold_internal.h"

// --- engine --------------------------------------------------------------------------------

typedef struct mf_triple {
    int var, loop, lc;
} mf_triple;

static int cmp_triple(const void *a, const void *b)
{
    const mf_triple *x = a, *y = b;
    if (x->var != y->var) return x->var < y->var ? -1 : 1;
    if (x->loop != y->loop) return x->loop < y->loop ? -1 : 1;
    return x->lc < y->lc ? -1 : x->lc > y->lc;
}

void ori__mf_init(mf_system *s, const ori_mechanism *m, const int *var_of_joint, int nvar)
{
    memset(s, 0, sizeof *s);
    s->m = m;
    s->var_of_joint = var_of_joint;
    s->nvar = nvar;
    int nt = 0;
    mf_triple *t = ori__alloc(sizeof(mf_triple) * (size_t)(m->loop_col_total + 1));
    for (int l = 0; l < m->loop_count; ++l) {
        const kin_loop *L = &m->loops[l];
        for (int c = 0; c < L->col_count; ++c) {
            int lc = L->col_first + c;
            int v = var_of_joint[m->loop_cols[lc]];
            if (v >= 0) t[nt++] = (mf_triple){v, l, lc};
        }
    }
    qsort(t, (size_t)nt, sizeof *t, cmp_triple);
    // Groups: distinct (variable, loop); loops are numbered in row order, so rows come sorted.
    int ng = 0;
    for (int i = 0; i < nt; ++i)
        if (i == 0 || t[i].var != t[i - 1].var || t[i].loop != t[i - 1].loop) ng++;
    s->ngroups = ng;
    s->group_pos = ori__alloc(sizeof(int) * (size_t)(ng + 1));
    s->group_loop = ori__alloc(sizeof(int) * (size_t)(ng + 1));
    s->group_lc0 = ori__alloc(sizeof(int) * (size_t)(ng + 1));
    s->lc_list = ori__alloc(sizeof(int) * (size_t)(nt + 1));
    int *colptr = ori__calloc((size_t)nvar + 1, sizeof(int));
    int g = -1, nnz = 0;
    for (int i = 0; i < nt; ++i) {
        if (i == 0 || t[i].var != t[i - 1].var || t[i].loop != t[i - 1].loop) {
            g++;
            s->group_pos[g] = nnz;
            s->group_loop[g] = t[i].loop;
            s->group_lc0[g] = i;
            nnz += m->loops[t[i].loop].rows;
            colptr[t[i].var + 1] += m->loops[t[i].loop].rows;
        }
        s->lc_list[i] = t[i].lc;
    }
    s->group_lc0[ng] = nt;
    for (int v = 0; v < nvar; ++v) colptr[v + 1] += colptr[v];
    int *rowind = ori__alloc(sizeof(int) * (size_t)(nnz + 1));
    for (int k = 0; k < ng; ++k) {
        const kin_loop *L = &m->loops[s->group_loop[k]];
        for (int r = 0; r < L->rows; ++r) rowind[s->group_pos[k] + r] = L->row0 + r;
    }
    // The stored matrix is J itself (rows × variables): sparse.c then factors J Jᵀ + λI.
    s->sls = ori__sls_create(m->rows, nvar, colptr, rowind);
    ori__free(colptr);
    ori__free(rowind);
    ori__free(t);
    s->res = ori__alloc(sizeof(double) * (size_t)(m->rows + 1));
    s->y = ori__alloc(sizeof(double) * (size_t)(m->rows + 1));
    s->x = ori__alloc(sizeof(double) * (size_t)(nvar + 1));
    s->cols = ori__alloc(sizeof(double) * 6 * (size_t)(m->loop_col_total + 1));
    s->half = ori__alloc(sizeof(double) * 2 * (size_t)(m->joint_count + 1));
}

void ori__mf_free(mf_system *s)
{
    ori__sls_destroy(s->sls);
    ori__free(s->group_pos);
    ori__free(s->group_loop);
    ori__free(s->group_lc0);
    ori__free(s->lc_list);
    ori__free(s->res);
    ori__free(s->y);
    ori__free(s->x);
    ori__free(s->cols);
    ori__free(s->half);
    memset(s, 0, sizeof *s);
}

bool ori__mf_linearize(mf_system *s, const double *th)
{
    const ori_mechanism *m = s->m;
    s->worst = ori__kin_eval(m, th, s->res, s->cols, s->half);
    double *val = ori__sls_values(s->sls);
    for (int g = 0; g < s->ngroups; ++g) {
        int rows = m->loops[s->group_loop[g]].rows;
        double *v = val + s->group_pos[g];
        for (int r = 0; r < rows; ++r) v[r] = 0.0;
        for (int i = s->group_lc0[g]; i < s->group_lc0[g + 1]; ++i) {
            const double *c = s->cols + 6 * (size_t)s->lc_list[i];
            for (int r = 0; r < rows; ++r) v[r] += c[r];
        }
    }
    s->factored = isfinite(s->worst) && ori__sls_factor(s->sls, ORI_MULTIFOLD_LAMBDA);
    return s->factored;
}

bool ori__mf_minnorm(mf_system *s, const double *b, double *x)
{
    if (!ori__sls_solve(s->sls, b, s->y)) return false;
    ori__sls_mult(s->sls, s->y, x);
    return true;
}

void ori__mf_jv(const mf_system *s, const double *v, double *out) { ori__sls_mult_t(s->sls, v, out); }

void ori__mf_joint_rate(const mf_system *s, const double *rate, double *out)
{
    const ori_mechanism *m = s->m;
    for (int r = 0; r < m->rows; ++r) out[r] = 0.0;
    for (int l = 0; l < m->loop_count; ++l) {
        const kin_loop *L = &m->loops[l];
        for (int c = 0; c < L->col_count; ++c) {
            int lc = L->col_first + c;
            double a = rate[m->loop_cols[lc]];
            if (a == 0.0) continue;
            for (int r = 0; r < L->rows; ++r) out[L->row0 + r] += a * s->cols[6 * (size_t)lc + (size_t)r];
        }
    }
}

void ori__mf_apply(const mf_system *s, const double *phi, double *th)
{
    for (int j = 0; j < s->m->joint_count; ++j)
        if (s->var_of_joint[j] >= 0) th[j] = phi[s->var_of_joint[j]];
}

bool ori__mf_correct(mf_system *s, double *th, int *iterations, double *residual)
{
    const ori_mechanism *m = s->m;
    double first = -1.0, prev = INFINITY, r = INFINITY;
    int it = 0;
    // Chord iterations: the factor of the last linearization (the projection's, at the state the
    // step left) is reused while it contracts the residual by ORI_KIN_CHORD_RATE or better.
    bool fresh = !s->factored;
    for (;; ++it) {
        bool ok = true;
        if (fresh) {
            ok = ori__mf_linearize(s, th);
            r = s->worst;
        } else {
            r = ori__kin_eval(m, th, s->res, NULL, s->half);
        }
        if (first < 0.0) first = r;
        if (!isfinite(r)) break;
        if (r <= ORI_TOL_NEWTON) break;
        // Converged as far as rounding allows: no more progress below the residual tolerance.
        if (r <= ORI_TOL_RESIDUAL && r > 0.25 * prev && fresh) break;
        if (it >= 2 * ORI_KIN_NEWTON_MAX || !ok) break;
        if (r > ORI_KIN_GROWTH_STEP * prev || r > ORI_KIN_GROWTH_TOTAL * fmax(first, ORI_TOL_RESIDUAL)) {
            if (fresh) break;
            fresh = true; // the old factor diverges: retry from here with a new one
            continue;
        }
        bool next_fresh = prev < INFINITY && r > ORI_KIN_CHORD_RATE * prev;
        if (next_fresh && !fresh) {
            fresh = true; // slow chord: linearize here and solve again
            prev = INFINITY;
            continue;
        }
        prev = r;
        for (int k = 0; k < m->rows; ++k) s->res[k] = -s->res[k];
        if (!ori__mf_minnorm(s, s->res, s->x)) break;
        for (int j = 0; j < m->joint_count; ++j)
            if (s->var_of_joint[j] >= 0) th[j] += s->x[s->var_of_joint[j]];
        fresh = next_fresh;
    }
    s->newton_iterations += it;
    if (iterations) *iterations = it;
    if (residual) *residual = r;
    return r <= ORI_TOL_RESIDUAL;
}

void ori__mf_dense_jacobian(const ori_mechanism *m, const double *th, const int *col_of_joint, int ncols, double *a)
{
    double *res = ori__alloc(sizeof(double) * (size_t)(m->rows + 1));
    double *cols = ori__alloc(sizeof(double) * 6 * (size_t)(m->loop_col_total + 1));
    ori__kin_eval(m, th, res, cols, NULL);
    memset(a, 0, sizeof(double) * (size_t)m->rows * (size_t)ncols);
    for (int l = 0; l < m->loop_count; ++l) {
        const kin_loop *L = &m->loops[l];
        for (int c = 0; c < L->col_count; ++c) {
            int lc = L->col_first + c;
            int col = col_of_joint[m->loop_cols[lc]];
            if (col < 0) continue;
            for (int r = 0; r < L->rows; ++r)
                a[(size_t)col * (size_t)m->rows + (size_t)(L->row0 + r)] += cols[6 * (size_t)lc + (size_t)r];
        }
    }
    ori__free(res);
    ori__free(cols);
}

int ori__mf_variables(const ori_mechanism *m, const int *locked_edges, int locked_count, const int *edge_group,
                      int *joint_var, ori_error *error)
{
    int J = m->joint_count;
    for (int j = 0; j < J; ++j) joint_var[j] = m->joints[j].kind == ORI_JOINT_REVOLUTE ? 0 : -1;
    for (int i = 0; i < locked_count; ++i) {
        int e = locked_edges[i];
        if (e < 0 || e >= m->edge_count) {
            ori__fail_at(error, ORI_ERR_RANGE, "edges_vertices", e, "no edge %d to lock", e);
            return -1;
        }
        if (m->edge_joint[e] != ORI_NULL_INDEX) joint_var[m->edge_joint[e]] = -1;
        // Locking a crease of a group locks the group (its creases share one angle).
        if (edge_group && edge_group[e] >= 0)
            for (int j = 0; j < J; ++j)
                if (edge_group[m->joints[j].edge] == edge_group[e]) joint_var[j] = -1;
    }
    // One variable per group (the group's first free joint numbers it), else per joint.
    int *var_of_group = NULL;
    if (edge_group) {
        var_of_group = ori__alloc(sizeof(int) * (size_t)(m->edge_count + 1));
        for (int e = 0; e < m->edge_count; ++e) {
            if (edge_group[e] >= m->edge_count) {
                ori__free(var_of_group);
                ori__fail_at(error, ORI_ERR_RANGE, "edges_vertices", e, "edge %d: group %d out of range", e, edge_group[e]);
                return -1;
            }
            var_of_group[e] = -1;
        }
    }
    int n = 0;
    for (int j = 0; j < J; ++j) {
        if (joint_var[j] < 0) continue;
        int gi = edge_group ? edge_group[m->joints[j].edge] : -1;
        if (gi >= 0) {
            if (var_of_group[gi] < 0) var_of_group[gi] = n++;
            joint_var[j] = var_of_group[gi];
        } else {
            joint_var[j] = n++;
        }
    }
    ori__free(var_of_group);
    return n;
}

ori_status ori__mf_close(const ori_mechanism *m, const int *locked_edges, int locked_count, double *edge_angles,
                         ori_error *error)
{
    int J = m->joint_count;
    int *var = ori__alloc(sizeof(int) * (size_t)(J + 1));
    double *th = ori__alloc(sizeof(double) * (size_t)(J + 1));
    int n = ori__mf_variables(m, locked_edges, locked_count, NULL, var, error);
    ori_status st = n < 0 ? ORI_ERR_RANGE : ORI_OK;
    if (st == ORI_OK) {
        mf_system s;
        ori__mf_init(&s, m, var, n);
        ori__kin_edges_to_joints(m, edge_angles, th);
        int its;
        double res;
        if (ori__mf_correct(&s, th, &its, &res)) ori__kin_joints_to_edges(m, th, edge_angles);
        else st = ori__fail(error, ORI_ERR_NOT_CONVERGED, "the state could not be closed (residual %.3g)", res);
        ori__mf_free(&s);
    }
    ori__free(var);
    ori__free(th);
    return st;
}

// --- result ----------------------------------------------------------------------------------

ori_multifold *ori__mf_result_create(const ori_mechanism *m, int fixed_face, ori_rigid fixed_pose)
{
    ori_multifold *mo = ori__calloc(1, sizeof *mo);
    mo->m = m;
    mo->edge_count = m->edge_count;
    mo->fixed_face = fixed_face;
    mo->fixed_pose = fixed_pose;
    mo->stop_edge = ORI_NULL_INDEX;
    mo->goal = ori__calloc((size_t)m->edge_count + 1, sizeof(double));
    return mo;
}

void ori__mf_record(ori_multifold *mo, const double *th, double residual, double progress)
{
    if (mo->nframes == mo->cap) {
        mo->cap = mo->cap ? 2 * mo->cap : 16;
        mo->angles = ori__realloc(mo->angles, sizeof(double) * (size_t)mo->cap * (size_t)(mo->edge_count + 1));
        mo->residual = ori__realloc(mo->residual, sizeof(double) * (size_t)mo->cap);
        mo->progress = ori__realloc(mo->progress, sizeof(double) * (size_t)mo->cap);
    }
    int k = mo->nframes++;
    double *a = mo->angles + (size_t)k * (size_t)(mo->edge_count + 1);
    ori__kin_joints_to_edges(mo->m, th, a);
    // The steps accept a crease up to ORI_TOL_NEWTON beyond ±π (the corrector's precision); the
    // frames hold it at ±π, so that no output angle leaves [−180°, 180°].
    for (int e = 0; e < mo->edge_count; ++e)
        if (fabs(a[e]) > ORI_PI && fabs(a[e]) <= ORI_PI + ORI_TOL_NEWTON) a[e] = a[e] > 0.0 ? ORI_PI : -ORI_PI;
    mo->residual[k] = residual;
    mo->progress[k] = progress;
}

void ori_multifold_destroy(ori_multifold *mo)
{
    if (!mo) return;
    ori__free(mo->angles);
    ori__free(mo->residual);
    ori__free(mo->progress);
    ori__free(mo->goal);
    ori__free(mo->watch_a0);
    ori__free(mo->watch_worst);
    ori__free(mo->watch_at);
    ori__free(mo->watch_buf);
    ori__free(mo->vertices);
    ori__free(mo->off_edge);
    ori__free(mo->off_angle);
    ori__free(mo->off_progress);
    ori__free(mo);
}

int ori_multifold_offending_count(const ori_multifold *mo)
{
    ORI_ASSERT(mo);
    return mo->noff;
}

void ori_multifold_offending(const ori_multifold *mo, int i, int *edge, double *angle_rad, double *progress)
{
    ORI_ASSERT(mo && i >= 0 && i < mo->noff);
    if (edge) *edge = mo->off_edge[i];
    if (angle_rad) *angle_rad = mo->off_angle[i];
    if (progress) *progress = mo->off_progress[i];
}

// How many offending creases a reason names (the worst first).
#define MF_OFFENDING_NAMED 5

// The sign an M/V crease must keep (+1 valley, −1 mountain; 0: no constraint) and how far it may
// go against it: the tolerance of the states near a stop (1e-4 rad) — minimum-norm continuation
// leaves creases of order 1e-5 rad on the wrong side where its first-order projection is not
// sign-constrained (the flat sheet) and where an unfold ends at the flat state — plus, for a
// start already against the assignment (a frame read from a file), that start.
static int mf_sign(const ori_multifold *mo, int e, double a0, double *allowed)
{
    const ori_mechanism *m = mo->m;
    int j = m->edge_joint[e];
    if (j == ORI_NULL_INDEX || m->joints[j].kind != ORI_JOINT_REVOLUTE) return 0;
    ori_assignment as = m->edges[e].assignment;
    int sg = as == ORI_ASSIGN_VALLEY ? 1 : as == ORI_ASSIGN_MOUNTAIN ? -1 : 0;
    *allowed = ORI_TOL_KIN_STOP_SIGN_RAD + (a0 * sg < 0.0 ? fabs(a0) : 0.0);
    return sg;
}

void ori__mf_watch(ori_multifold *mo, const double *th, double progress)
{
    int E = mo->edge_count;
    if (!mo->watch_a0) {
        mo->watch_a0 = ori__alloc(sizeof(double) * (size_t)(E + 1));
        mo->watch_worst = ori__calloc((size_t)E + 1, sizeof(double));
        mo->watch_at = ori__calloc((size_t)E + 1, sizeof(double));
        mo->watch_buf = ori__alloc(sizeof(double) * (size_t)(E + 1));
        ori__kin_joints_to_edges(mo->m, th, mo->watch_a0);
        return;
    }
    double *a = mo->watch_buf;
    ori__kin_joints_to_edges(mo->m, th, a);
    for (int e = 0; e < E; ++e) {
        double allowed;
        int sg = mf_sign(mo, e, mo->watch_a0[e], &allowed);
        if (sg && a[e] * sg < 0.0 && fabs(a[e]) > allowed && fabs(a[e]) > fabs(mo->watch_worst[e])) {
            mo->watch_worst[e] = a[e];
            mo->watch_at[e] = progress;
        }
    }
}

bool ori__mf_against(ori_multifold *mo, const double *th)
{
    if (!mo->watch_a0) return false;
    double *a = mo->watch_buf;
    ori__kin_joints_to_edges(mo->m, th, a);
    for (int e = 0; e < mo->edge_count; ++e) {
        double allowed;
        int sg = mf_sign(mo, e, mo->watch_a0[e], &allowed);
        if (sg && a[e] * sg < 0.0 && fabs(a[e]) > allowed) return true;
    }
    return false;
}

void ori__mf_check_assignment(ori_multifold *mo)
{
    int E = mo->edge_count, F = mo->nframes;
    mo->motion_verdict = mo->verdict;
    // Drives that cannot move (as prescribed, or alone) say so: their frames are no motion.
    if (F < 2 || mo->verdict == ORI_MULTIFOLD_UNDERDETERMINED || mo->verdict == ORI_MULTIFOLD_OVERDETERMINED) return;
    const double *a0 = mo->watch_a0 ? mo->watch_a0 : ori_multifold_frame_angles(mo, 0);
    ori__free(mo->off_edge);
    ori__free(mo->off_angle);
    ori__free(mo->off_progress);
    mo->off_edge = ori__alloc(sizeof(int) * (size_t)(E + 1));
    mo->off_angle = ori__alloc(sizeof(double) * (size_t)(E + 1));
    mo->off_progress = ori__alloc(sizeof(double) * (size_t)(E + 1));
    mo->noff = 0;
    double worst_all = 0.0;
    for (int e = 0; e < E; ++e) {
        double allowed;
        int sg = mf_sign(mo, e, a0[e], &allowed);
        if (!sg) continue;
        // The solver's accepted states when they were watched (the output frames between them
        // are interpolations that keep the assignment: ori__mf_against); else the frames.
        double worst = mo->watch_a0 ? mo->watch_worst[e] : 0.0, at = mo->watch_a0 ? mo->watch_at[e] : 0.0;
        for (int k = 1; k < F && !mo->watch_a0; ++k) {
            double x = ori_multifold_frame_angles(mo, k)[e];
            if (x * sg < 0.0 && fabs(x) > allowed && fabs(x) > fabs(worst)) {
                worst = x;
                at = mo->progress[k];
            }
        }
        if (worst == 0.0) continue;
        mo->off_edge[mo->noff] = e;
        mo->off_angle[mo->noff] = worst;
        mo->off_progress[mo->noff++] = at;
        worst_all = fmax(worst_all, fabs(worst));
    }
    if (mo->noff == 0) return;
    // The reason: the count, the worst creases, and where the motion itself ended.
    int order[MF_OFFENDING_NAMED], named = 0;
    for (int i = 0; i < mo->noff; ++i) {
        int pos = named < MF_OFFENDING_NAMED ? named++ : MF_OFFENDING_NAMED;
        if (pos == MF_OFFENDING_NAMED) {
            if (fabs(mo->off_angle[i]) <= fabs(mo->off_angle[order[named - 1]])) continue;
            pos = named - 1;
        }
        while (pos > 0 && fabs(mo->off_angle[order[pos - 1]]) < fabs(mo->off_angle[i])) {
            order[pos] = order[pos - 1];
            pos--;
        }
        order[pos] = i;
    }
    const ori_mechanism *m = mo->m;
    char before[1024];
    snprintf(before, sizeof before, "%s", mo->reason);
    ori_multifold_verdict was = mo->verdict;
    size_t w = (size_t)snprintf(mo->reason, sizeof mo->reason, "%d crease%s against %s assignment (up to %.6g°):", mo->noff,
                                mo->noff == 1 ? " folds" : "s fold", mo->noff == 1 ? "its" : "their",
                                ori_rad_to_deg(worst_all));
    for (int k = 0; k < named && w < sizeof mo->reason; ++k) {
        int i = order[k], e = mo->off_edge[i];
        w += (size_t)snprintf(mo->reason + w, sizeof mo->reason - w, "%s crease %d (assigned %s) folds to %.10g° at %.4g %% of the way",
                              k ? ";" : "", e, m->edges[e].assignment == ORI_ASSIGN_VALLEY ? "valley" : "mountain",
                              ori_rad_to_deg(mo->off_angle[i]), 100.0 * mo->off_progress[i]);
    }
    if (mo->noff > named && w < sizeof mo->reason)
        w += (size_t)snprintf(mo->reason + w, sizeof mo->reason - w, "; and %d more", mo->noff - named);
    if (w < sizeof mo->reason)
        snprintf(mo->reason + w, sizeof mo->reason - w, " (the motion itself: %s, %.400s)", ori_multifold_verdict_name(was),
                 before);
    mo->verdict = ORI_MULTIFOLD_INVALID_ASSIGNMENT;
}

ori_multifold_verdict ori_multifold_verdict_of(const ori_multifold *mo)
{
    ORI_ASSERT(mo);
    return mo->verdict;
}

const char *ori_multifold_verdict_name(ori_multifold_verdict v)
{
    switch (v) {
    case ORI_MULTIFOLD_REACHED: return "reached";
    case ORI_MULTIFOLD_STATIONARY: return "stationary";
    case ORI_MULTIFOLD_LIMIT: return "limit";
    case ORI_MULTIFOLD_SINGULAR: return "singular";
    case ORI_MULTIFOLD_UNDERDETERMINED: return "underdetermined";
    case ORI_MULTIFOLD_OVERDETERMINED: return "overdetermined";
    case ORI_MULTIFOLD_INVALID_ASSIGNMENT: return "invalid assignment";
    }
    return "unknown";
}

const char *ori_multifold_reason(const ori_multifold *mo)
{
    ORI_ASSERT(mo);
    return mo->reason;
}

int ori_multifold_stop_edge(const ori_multifold *mo)
{
    ORI_ASSERT(mo);
    return mo->stop_edge;
}

int ori_multifold_extra_dof(const ori_multifold *mo)
{
    ORI_ASSERT(mo);
    return mo->extra_dof;
}

int ori_multifold_frame_count(const ori_multifold *mo)
{
    ORI_ASSERT(mo);
    return mo->nframes;
}

const double *ori_multifold_frame_angles(const ori_multifold *mo, int k)
{
    ORI_ASSERT(mo && k >= 0 && k < mo->nframes);
    return mo->angles + (size_t)k * (size_t)(mo->edge_count + 1);
}

double ori_multifold_frame_residual(const ori_multifold *mo, int k)
{
    ORI_ASSERT(mo && k >= 0 && k < mo->nframes);
    return mo->residual[k];
}

double ori_multifold_frame_progress(const ori_multifold *mo, int k)
{
    ORI_ASSERT(mo && k >= 0 && k < mo->nframes);
    return mo->progress[k];
}

void ori_multifold_frame_vertices(const ori_multifold *mo, int k, ori_v3 *positions)
{
    ORI_ASSERT(mo && positions);
    ori_mechanism_vertex_positions(mo->m, ori_multifold_frame_angles(mo, k), mo->fixed_face, mo->fixed_pose,
                                   positions);
}

const double *ori_multifold_angles(const ori_multifold *mo, int *frame_stride)
{
    ORI_ASSERT(mo);
    if (frame_stride) *frame_stride = mo->edge_count + 1;
    return mo->nframes > 0 ? mo->angles : NULL;
}

const ori_v3 *ori_multifold_vertices(ori_multifold *mo)
{
    ORI_ASSERT(mo);
    if (mo->nframes == 0) return NULL;
    if (!mo->vertices) {
        size_t V = (size_t)ori_mechanism_vertex_count(mo->m);
        mo->vertices = ori__alloc(sizeof(ori_v3) * ((size_t)mo->nframes * V + 1));
        for (int k = 0; k < mo->nframes; ++k) ori_multifold_frame_vertices(mo, k, mo->vertices + (size_t)k * V);
    }
    return mo->vertices;
}

ori_status ori_multifold_at(const ori_multifold *mo, const int *locked_edges, int locked_count, double progress,
                            double *angles_rad, ori_v3 *positions, ori_error *error)
{
    ORI_ASSERT(mo && angles_rad && (locked_count == 0 || locked_edges));
    ori_error_clear(error);
    int n = mo->nframes;
    if (n == 0 || !(progress >= mo->progress[0] && progress <= mo->progress[n - 1]))
        return ori__fail(error, ORI_ERR_RANGE, "progress %g is outside the frames' [%g, %g]", progress,
                         n ? mo->progress[0] : 0.0, n ? mo->progress[n - 1] : 0.0);
    // The frames' progress increases: the bracket is the last frame at or before the progress.
    int k = 0;
    while (k + 1 < n && mo->progress[k + 1] <= progress) k++;
    const double *a0 = ori_multifold_frame_angles(mo, k);
    if (k + 1 == n || mo->progress[k] == progress) {
        memcpy(angles_rad, a0, sizeof(double) * (size_t)mo->edge_count);
    } else {
        const double *a1 = ori_multifold_frame_angles(mo, k + 1);
        double w = (progress - mo->progress[k]) / (mo->progress[k + 1] - mo->progress[k]);
        for (int e = 0; e < mo->edge_count; ++e) angles_rad[e] = a0[e] + w * (a1[e] - a0[e]);
        ori_status st = ori__mf_close(mo->m, locked_edges, locked_count, angles_rad, error);
        if (st != ORI_OK) return st;
    }
    if (positions) ori_mechanism_vertex_positions(mo->m, angles_rad, mo->fixed_face, mo->fixed_pose, positions);
    return ORI_OK;
}

const double *ori_multifold_goal(const ori_multifold *mo)
{
    ORI_ASSERT(mo);
    return mo->goal;
}

int ori_multifold_held_count(const ori_multifold *mo)
{
    ORI_ASSERT(mo);
    return mo->pinned;
}

void ori_multifold_stats(const ori_multifold *mo, int *steps, int *rejected, int *newton_iterations)
{
    ORI_ASSERT(mo);
    if (steps) *steps = mo->steps;
    if (rejected) *rejected = mo->rejected;
    if (newton_iterations) *newton_iterations = mo->newton;
}

// --- fold toward targets ---------------------------------------------------------------------

ori_target_fold_def ori_default_target_fold_def(void)
{
    ori_target_fold_def d;
    memset(&d, 0, sizeof d);
    d.fixed_face = 0;
    d.fixed_pose = ori_rigid_identity();
    d.fraction = 1.0;
    d.step_rad = ORI_PI / 18.0;
    d.internal_value = ORI__DEF_COOKIE;
    return d;
}

int ori_target_angles_default(const ori_pattern *p, double *out)
{
    ORI_ASSERT(p && out);
    int own = 0;
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        if (ed.fold_angle_rad != 0.0 && isfinite(ed.fold_angle_rad)) {
            out[e] = ed.fold_angle_rad;
            own++;
        } else {
            out[e] = ed.assignment == ORI_ASSIGN_VALLEY ? ORI_PI : ed.assignment == ORI_ASSIGN_MOUNTAIN ? -ORI_PI : 0.0;
        }
    }
    return own;
}

// Common validation of a fold's start: face, pose, angles. th receives the joint angles.
static ori_status check_start(const ori_mechanism *m, int fixed_face, const double *start, double *th, ori_error *error)
{
    if (fixed_face < 0 || fixed_face >= m->face_count)
        return ori__fail_at(error, ORI_ERR_RANGE, "faces_vertices", fixed_face, "no face %d (the fixed face)", fixed_face);
    if (start)
        for (int e = 0; e < m->edge_count; ++e)
            if (!isfinite(start[e]) || fabs(start[e]) > ORI_PI + ORI_TOL_FOLD_SIGN_RAD)
                return ori__fail_at(error, ORI_ERR_RANGE, "edges_foldAngle", e, "start angle is not in [-180°, 180°]");
    ori__kin_edges_to_joints(m, start, th);
    double r0 = ori__kin_residual(m, th);
    if (!(r0 <= ORI_TOL_START_RESIDUAL))
        return ori__fail(error, ORI_ERR_ARGUMENT,
                         "the start fold angles do not close the loops (residual %.3g above %.0e)", r0,
                         ORI_TOL_START_RESIDUAL);
    return ORI_OK;
}

ori_status ori__mf_check_start(const ori_mechanism *m, int fixed_face, const double *start, double *th,
                               ori_error *error)
{
    return check_start(m, fixed_face, start, th, error);
}

ori_status ori__mf_group_start(const ori_mechanism *m, const int *joint_var, int nvar, const double *th, double *phi,
                               ori_error *error)
{
    int *first = ori__alloc(sizeof(int) * (size_t)(nvar + 1));
    for (int v = 0; v < nvar; ++v) first[v] = -1;
    ori_status st = ORI_OK;
    for (int j = 0; j < m->joint_count && st == ORI_OK; ++j) {
        int v = joint_var[j];
        if (v < 0) continue;
        if (first[v] < 0) {
            first[v] = j;
            phi[v] = th[j];
        } else if (fabs(th[j] - phi[v]) > ORI_TOL_FOLD_SIGN_RAD) {
            st = ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_foldAngle", m->joints[j].edge,
                              "creases %d and %d are kept at equal angles but start at %g° and %g°",
                              m->joints[first[v]].edge, m->joints[j].edge, ori_rad_to_deg(phi[v]),
                              ori_rad_to_deg(th[j]));
        }
    }
    ori__free(first);
    return st;
}

static double goal_distance(const ori_mechanism *m, const int *joint_var, const double *th, const double *goal)
{
    double s = 0.0;
    for (int j = 0; j < m->joint_count; ++j)
        if (joint_var[j] >= 0) s += (th[j] - goal[j]) * (th[j] - goal[j]);
    return sqrt(s);
}

ori_status ori_target_fold_solve(const ori_mechanism *m, const ori_target_fold_def *def, ori_multifold **out,
                                 ori_error *error)
{
    ORI_ASSERT(m && def && def->internal_value == ORI__DEF_COOKIE && out);
    *out = NULL;
    if (!(def->fraction >= 0.0 && def->fraction <= 1.0))
        return ori__fail(error, ORI_ERR_RANGE, "the fold fraction must lie in [0, 1] (got %g)", def->fraction);
    if (!(def->step_rad > 0.0) || !isfinite(def->step_rad))
        return ori__fail(error, ORI_ERR_RANGE, "the step must be a positive angle (got %g°)", ori_rad_to_deg(def->step_rad));
    int J = m->joint_count, E = m->edge_count;
    double *th = ori__alloc(sizeof(double) * (size_t)(J + 1));
    ori_status st = check_start(m, def->fixed_face, def->start_angles_rad, th, error);
    if (st != ORI_OK) {
        ori__free(th);
        return st;
    }
    double *target = ori__alloc(sizeof(double) * (size_t)(E + 1));
    if (def->target_angles_rad) {
        for (int e = 0; e < E; ++e) {
            target[e] = def->target_angles_rad[e];
            if (!isfinite(target[e]) || fabs(target[e]) > ORI_PI + ORI_TOL_FOLD_SIGN_RAD) {
                ori__free(th);
                ori__free(target);
                return ori__fail_at(error, ORI_ERR_RANGE, "edges_foldAngle", e, "target angle is not in [-180°, 180°]");
            }
        }
    } else {
        for (int e = 0; e < E; ++e) {
            ori_assignment a = m->edges[e].assignment;
            double f = m->edges[e].fold_angle_rad;
            target[e] = f != 0.0 && isfinite(f) ? f : a == ORI_ASSIGN_VALLEY ? ORI_PI : a == ORI_ASSIGN_MOUNTAIN ? -ORI_PI : 0.0;
        }
    }
    int *joint_var = ori__alloc(sizeof(int) * (size_t)(J + 1));
    int nvar = ori__mf_variables(m, def->locked_edges, def->locked_count, def->edge_group, joint_var, error);
    if (nvar < 0) {
        ori__free(th);
        ori__free(target);
        ori__free(joint_var);
        return ORI_ERR_RANGE;
    }
    double *phi = ori__alloc(sizeof(double) * (size_t)(nvar + 1));
    st = ori__mf_group_start(m, joint_var, nvar, th, phi, error);
    if (st != ORI_OK) {
        ori__free(th);
        ori__free(target);
        ori__free(joint_var);
        ori__free(phi);
        return st;
    }

    ori_multifold *mo = ori__mf_result_create(m, def->fixed_face, def->fixed_pose);
    mf_system sys;
    ori__mf_init(&sys, m, joint_var, nvar);
    // Close a start read from a file (rounded angles) exactly.
    int its;
    double res = ori__kin_residual(m, th);
    if (res > ORI_TOL_RESIDUAL && !ori__mf_correct(&sys, th, &its, &res)) {
        st = ori__fail(error, ORI_ERR_NOT_CONVERGED, "the start state could not be closed (residual %.3g)", res);
        ori__mf_free(&sys);
        ori_multifold_destroy(mo);
        ori__free(th);
        ori__free(target);
        ori__free(joint_var);
        ori__free(phi);
        return st;
    }
    // Goals: per joint, then per variable (the mean of its joints').
    double *goal = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *gvar = ori__calloc((size_t)nvar + 1, sizeof(double));
    int *nj = ori__calloc((size_t)nvar + 1, sizeof(int));
    for (int j = 0; j < J; ++j) {
        goal[j] = th[j];
        if (joint_var[j] < 0) continue;
        // The goal is the targets themselves (the 100 % state); def->fraction says how far along
        // the motion toward it the fold stops (progress 1 − D/D₀, below).
        goal[j] = target[m->joints[j].edge];
        gvar[joint_var[j]] += goal[j];
        nj[joint_var[j]]++;
    }
    for (int v = 0; v < nvar; ++v) gvar[v] /= nj[v] ? nj[v] : 1;
    for (int j = 0; j < J; ++j)
        if (joint_var[j] >= 0) goal[j] = gvar[joint_var[j]];
    ori__kin_joints_to_edges(m, goal, mo->goal);

    int R = m->rows;
    double *d = ori__alloc(sizeof(double) * (size_t)(nvar + 1));
    double *p = ori__alloc(sizeof(double) * (size_t)(nvar + 1));
    double *jd = ori__alloc(sizeof(double) * (size_t)(R + 1));
    double *trial = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *pred = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double D0 = goal_distance(m, joint_var, th, goal);
    ori__mf_record(mo, th, ori__kin_residual(m, th), D0 > 0.0 ? 0.0 : 1.0);
    ori__mf_watch(mo, th, D0 > 0.0 ? 0.0 : 1.0);
    // The solver's steps do not depend on the output spacing (a fold's path and verdict are the
    // same for every --step): frames between two steps are interpolated (below).
    double hmax = ORI_MULTIFOLD_MAX_STEP_RAD;
    double *mid = NULL; // the frames inside one step: J angles, residual, progress each
    int mid_cap = 0;
    double h = hmax, since = 0.0;
    enum { WHY_NONE, WHY_NEWTON, WHY_LIMIT, WHY_FARTHER } why = WHY_NONE;
    int why_joint = -1;
    bool recorded = true, done = false, finished = false;
    double last_res = 0.0;
    int *all_locks = ori__alloc(sizeof(int) * (size_t)(def->locked_count + m->edge_count + 1));
    int nlocks = def->locked_count;
    for (int i = 0; i < nlocks; ++i) all_locks[i] = def->locked_edges[i];
    double reported = 0.0; // the progress fraction last reported (kept monotone)
    bool cancelled = false;
    // The distance to the goal after each of the last ORI_MULTIFOLD_STALL_STEPS accepted steps
    // (a ring): a fold that creeps without approaching the goal stops on it.
    double stall_ring[ORI_MULTIFOLD_STALL_STEPS], path_ring[ORI_MULTIFOLD_STALL_STEPS], h_ring[ORI_MULTIFOLD_STALL_STEPS];
    double path = 0.0; // length of the path so far (2-norm over the variables' joints)
    int stall_n = 0;
    const int max_steps = def->max_steps > 0 ? def->max_steps : ORI_MULTIFOLD_MAX_STEPS;
    // Origami Simulator's slider: P % is P % of the way along the motion toward the 100 % goal,
    // measured by the progress 1 − D/D₀ (D the distance to the goal, which every accepted step
    // decreases: monotone along the path). The fold stops where it reaches the fraction.
    const double stop_distance = (1.0 - def->fraction) * D0;
    bool partway = def->fraction < 1.0 && D0 > 0.0;
    if (partway && def->fraction <= 0.0) { // 0 %: the start itself
        mo->verdict = ORI_MULTIFOLD_REACHED;
        snprintf(mo->reason, sizeof mo->reason, "0 %% of the way: the start state");
        done = true;
    }
    while (!done && !cancelled) {
        for (int j = 0; j < J; ++j)
            if (joint_var[j] >= 0) phi[joint_var[j]] = th[j];
        double dmax = 0.0;
        for (int v = 0; v < nvar; ++v) {
            d[v] = gvar[v] - phi[v];
            dmax = fmax(dmax, fabs(d[v]));
        }
        if (dmax <= ORI_TOL_TARGET_RAD) {
            mo->verdict = ORI_MULTIFOLD_REACHED;
            snprintf(mo->reason, sizeof mo->reason, "every crease reached its goal (within %.0e rad)", ORI_TOL_TARGET_RAD);
            break;
        }
        if (mo->steps >= max_steps) {
            mo->verdict = ORI_MULTIFOLD_STATIONARY;
            snprintf(mo->reason, sizeof mo->reason,
                     "the motion came no nearer to the goal within %d steps (it creeps along a valley of the distance)",
                     max_steps);
            break;
        }
        if (!ori__mf_linearize(&sys, th)) {
            mo->verdict = ORI_MULTIFOLD_SINGULAR;
            snprintf(mo->reason, sizeof mo->reason, "the Jacobian could not be factored at this state");
            break;
        }
        ori__mf_jv(&sys, d, jd);
        if (!ori__mf_minnorm(&sys, jd, p)) {
            mo->verdict = ORI_MULTIFOLD_SINGULAR;
            snprintf(mo->reason, sizeof mo->reason, "the projection onto the rigid motions failed at this state");
            break;
        }
        double pmax = 0.0;
        for (int v = 0; v < nvar; ++v) {
            p[v] = d[v] - p[v];
            pmax = fmax(pmax, fabs(p[v]));
        }
        if (pmax <= ORI_TOL_TARGET_RAD) {
            mo->verdict = ORI_MULTIFOLD_STATIONARY;
            snprintf(mo->reason, sizeof mo->reason,
                     "the rigid motion gets no nearer to the goal: the remaining change (up to %.6g°) is normal to "
                     "every rigid motion from this state",
                     ori_rad_to_deg(dmax));
            break;
        }
        double D = goal_distance(m, joint_var, th, goal);
        if (stall_n >= ORI_MULTIFOLD_STALL_STEPS) {
            int old = stall_n % ORI_MULTIFOLD_STALL_STEPS; // ORI_MULTIFOLD_STALL_STEPS steps ago
            double before = stall_ring[old], walked = path - path_ring[old], fell = before - D;
            // At the pace of the last steps (the step length not growing), the goal lies beyond
            // the steps a fold may take: stop now rather than after them.
            double left = (double)(max_steps - mo->steps);
            if (h <= h_ring[old] && fell * left < (double)ORI_MULTIFOLD_STALL_STEPS * D) {
                mo->verdict = ORI_MULTIFOLD_STATIONARY;
                snprintf(mo->reason, sizeof mo->reason,
                         "the motion comes no nearer to the goal at a pace that could reach it: over the last %d "
                         "steps it moved %.3g rad and its distance to the goal fell by %.3g rad (%.2g %%), so the "
                         "%.4g rad left would take about %.3g more steps (a fold may take %d); it got %.4g %% of the way",
                         ORI_MULTIFOLD_STALL_STEPS, walked, fell, before > 0.0 ? 100.0 * fell / before : 0.0, D,
                         fell > 0.0 ? D / fell * ORI_MULTIFOLD_STALL_STEPS : INFINITY, max_steps,
                         D0 > 0.0 ? 100.0 * (1.0 - D / D0) : 100.0);
                break;
            }
        }
        for (;;) {
            double sc = fmin(1.0, h / pmax);
            memcpy(trial, th, sizeof(double) * (size_t)J);
            for (int j = 0; j < J; ++j)
                if (joint_var[j] >= 0) trial[j] += sc * p[joint_var[j]];
            memcpy(pred, trial, sizeof(double) * (size_t)J);
            bool ok = ori__mf_correct(&sys, trial, &its, &res);
            double move = 0.0;
            int over = -1;
            for (int j = 0; j < J; ++j) {
                if (joint_var[j] < 0) continue;
                move = fmax(move, fabs(trial[j] - pred[j]));
                if (!(fabs(trial[j]) <= ORI_PI + ORI_TOL_NEWTON) && (over < 0 || fabs(trial[j]) > fabs(trial[over])))
                    over = j;
            }
            bool accept = ok && move <= ORI_MULTIFOLD_MAX_CORRECTION * sc * pmax + ORI_MULTIFOLD_MIN_STEP_RAD;
            if (accept && over >= 0) {
                accept = false;
                why = WHY_LIMIT;
                why_joint = over;
            } else if (!accept) {
                why = WHY_NEWTON;
            }
            double Dn = accept ? goal_distance(m, joint_var, trial, goal) : INFINITY;
            if (accept && !(Dn < D)) {
                accept = false;
                why = WHY_FARTHER;
            }
            if (accept && partway && Dn <= stop_distance) {
                // The fraction falls inside this step: the state on it (the chord from th to
                // trial, corrected) where the distance is (1 − fraction)·D₀, by bisection.
                double lo = 0.0, hi = 1.0, best = Dn, best_res = res;
                memcpy(pred, trial, sizeof(double) * (size_t)J); // the step's end
                double *x = ori__alloc(sizeof(double) * (size_t)(J + 1));
                for (int it = 0; it < ORI_MULTIFOLD_STOP_BISECTIONS; ++it) {
                    double u = 0.5 * (lo + hi), rm = 0.0;
                    int im = 0;
                    for (int j = 0; j < J; ++j) x[j] = th[j] + u * (pred[j] - th[j]);
                    bool closed = ori__mf_correct(&sys, x, &im, &rm);
                    for (int j = 0; j < J && closed; ++j)
                        if (joint_var[j] >= 0 && !(fabs(x[j]) <= ORI_PI + ORI_TOL_NEWTON)) closed = false;
                    if (!closed) {
                        hi = u;
                        continue;
                    }
                    double Dx = goal_distance(m, joint_var, x, goal);
                    if (Dx <= stop_distance) hi = u;
                    else lo = u;
                    if (fabs(Dx - stop_distance) < fabs(best - stop_distance) && Dx < D) {
                        best = Dx;
                        best_res = rm;
                        memcpy(trial, x, sizeof(double) * (size_t)J);
                    }
                    if (fabs(Dx - stop_distance) <= ORI_TOL_MULTIFOLD_PROGRESS * D0) break;
                }
                ori__free(x);
                Dn = best;
                res = best_res;
                // Near a singular state (the flat sheet) the corrected chord can jump across the
                // fraction: the corrector lands on one sheet of the constraints for part of the
                // chord and on another beyond it, so no point of it is at the stop distance. Then
                // the step is taken again shorter (the path from th is continuous) until it
                // lands; a fuzzed waterbomb at 0.78 % stopped at 0.84 % before.
                if (fabs(best - stop_distance) > ORI_TOL_MULTIFOLD_LAND * D0 && h > ORI_MULTIFOLD_LAND_MIN_STEP_RAD)
                    accept = false;
                else
                    finished = true;
            }
            // Frames every def->step_rad of the largest crease change: those that fall inside this
            // step are the chord from th to trial at that change, corrected onto the constraints;
            // one that falls on its end is trial. The output never steers the solver: an
            // interpolation that does not close, or closes beyond ±π, is replaced by the step's
            // end (that frame then lies up to one step further on).
            double moved = 0.0;
            for (int j = 0; j < J; ++j) moved = fmax(moved, fabs(trial[j] - th[j]));
            int nmid = 0, k = 1;
            bool at_end = false;
            for (; accept; ++k) {
                double c = (double)k * def->step_rad - since; // the change from th where frame k falls
                if (c > moved * (1.0 + ORI_MULTIFOLD_GRID_REL)) break;
                if (c >= moved * (1.0 - ORI_MULTIFOLD_GRID_REL)) {
                    at_end = true;
                    break;
                }
                if (nmid == mid_cap) {
                    mid_cap = 2 * mid_cap + 4;
                    mid = ori__realloc(mid, sizeof(double) * (size_t)mid_cap * (size_t)(J + 2));
                }
                double *x = mid + (size_t)nmid * (size_t)(J + 2), u = c / moved, rm = 0.0;
                for (int j = 0; j < J; ++j) x[j] = th[j] + u * (trial[j] - th[j]);
                int im = 0;
                bool closed = ori__mf_correct(&sys, x, &im, &rm) && rm <= ORI_TOL_RESIDUAL;
                for (int j = 0; j < J && closed; ++j)
                    if (joint_var[j] >= 0 && !(fabs(x[j]) <= ORI_PI + ORI_TOL_NEWTON)) closed = false;
                // (nor one against the assignment: the verdict judges the solver's states)
                if (closed && ori__mf_against(mo, x)) closed = false;
                if (!closed) {
                    at_end = true;
                    break;
                }
                x[J] = rm;
                x[J + 1] = D0 > 0.0 ? 1.0 - goal_distance(m, joint_var, x, goal) / D0 : 1.0;
                nmid++;
            }
            if (accept) {
                for (int i = 0; i < nmid; ++i) {
                    const double *x = mid + (size_t)i * (size_t)(J + 2);
                    ori__mf_record(mo, x, x[J], x[J + 1]);
                }
                h_ring[stall_n % ORI_MULTIFOLD_STALL_STEPS] = h; // the step length, path and distance before this step
                path_ring[stall_n % ORI_MULTIFOLD_STALL_STEPS] = path;
                stall_ring[stall_n++ % ORI_MULTIFOLD_STALL_STEPS] = D;
                double len = 0.0;
                for (int j = 0; j < J; ++j)
                    if (joint_var[j] >= 0) len += (trial[j] - th[j]) * (trial[j] - th[j]);
                path += sqrt(len);
                since = at_end ? 0.0 : since + moved - (double)(k - 1) * def->step_rad;
                memcpy(th, trial, sizeof(double) * (size_t)J);
                mo->steps++;
                ori__mf_watch(mo, th, D0 > 0.0 ? 1.0 - Dn / D0 : 1.0);
                last_res = res;
                recorded = at_end;
                if (at_end) ori__mf_record(mo, th, res, D0 > 0.0 ? 1.0 - Dn / D0 : 1.0);
                if (its <= 5) h = fmin(2.0 * h, hmax);
                if (def->progress) { // the distance to the goal only shrinks: 1 − D/D0 grows
                    double got = D0 > 0.0 ? 1.0 - Dn / D0 : 1.0;
                    reported = fmax(reported, fmin(1.0, def->fraction > 0.0 ? got / def->fraction : 1.0));
                    cancelled = !def->progress(reported, def->progress_user);
                }
                break;
            }
            finished = false;
            mo->rejected++;
            h *= 0.5;
            if (h < ORI_MULTIFOLD_MIN_STEP_RAD) {
                done = true;
                break;
            }
        }
        if (cancelled) break;
        if (finished) {
            mo->verdict = ORI_MULTIFOLD_REACHED;
            snprintf(mo->reason, sizeof mo->reason,
                     "the fold reached %.6g %% of the way toward the targets (progress 1 - D/D0, D the distance to them)",
                     100.0 * def->fraction);
            break;
        }
        // A crease stopped at ±180° that is its own goal is held there, and the others go on.
        if (done && why == WHY_LIMIT && fabs(goal[why_joint]) >= ORI_PI - ORI_TOL_TARGET_RAD &&
            fabs(th[why_joint]) >= ORI_PI - ORI_MULTIFOLD_PIN_RAD) {
            int v0 = joint_var[why_joint];
            all_locks[nlocks++] = m->joints[why_joint].edge;
            memcpy(trial, th, sizeof(double) * (size_t)J);
            for (int j = 0; j < J; ++j)
                if (joint_var[j] == v0) trial[j] = goal[j] > 0.0 ? ORI_PI : -ORI_PI;
            int nv2 = ori__mf_variables(m, all_locks, nlocks, def->edge_group, joint_var, NULL);
            mo->newton += sys.newton_iterations;
            ori__mf_free(&sys);
            ori__mf_init(&sys, m, joint_var, nv2);
            if (nv2 >= 0 && ori__mf_correct(&sys, trial, &its, &res)) {
                memcpy(th, trial, sizeof(double) * (size_t)J);
                ori__mf_watch(mo, th, D0 > 0.0 ? 1.0 - goal_distance(m, joint_var, th, goal) / D0 : 1.0);
                nvar = nv2;
                for (int v = 0; v < nvar; ++v) {
                    gvar[v] = 0.0;
                    nj[v] = 0;
                }
                for (int j = 0; j < J; ++j)
                    if (joint_var[j] >= 0) {
                        gvar[joint_var[j]] += goal[j];
                        nj[joint_var[j]]++;
                    }
                for (int v = 0; v < nvar; ++v) gvar[v] /= nj[v] ? nj[v] : 1;
                mo->pinned++;
                stall_n = 0; // new variables: a new distance
                last_res = res;
                recorded = false;
                done = false;
                why = WHY_NONE;
                h = hmax;
                continue;
            }
            // The others cannot close with it at ±180°: stop here (the state before the pin).
            nlocks--;
            ori__mf_variables(m, all_locks, nlocks, def->edge_group, joint_var, NULL);
        }
        if (done) {
            // Classify the stop by why the last, smallest steps failed.
            if (why == WHY_LIMIT) {
                mo->verdict = ORI_MULTIFOLD_LIMIT;
                mo->stop_edge = m->joints[why_joint].edge;
                snprintf(mo->reason, sizeof mo->reason,
                         "crease %d reached %.6g° and the motion toward the goal would fold it beyond",
                         mo->stop_edge, th[why_joint] >= 0.0 ? 180.0 : -180.0);
            } else if (why == WHY_FARTHER) {
                mo->verdict = ORI_MULTIFOLD_STATIONARY;
                snprintf(mo->reason, sizeof mo->reason,
                         "the rigid motion gets no nearer to the goal from this state (every step that closes the "
                         "loops moves away from it)");
            } else {
                mo->verdict = ORI_MULTIFOLD_SINGULAR;
                snprintf(mo->reason, sizeof mo->reason,
                         mo->steps == 0 ? "no rigid motion moves the creases toward the goal from the start: the "
                                          "loop-closure conditions admit no motion in that direction (rigid here, or a "
                                          "singular point whose branches all lead away)"
                                        : "the motion reaches a singular configuration: no step toward the goal, "
                                          "however small, closes the loops");
            }
        }
    }
    if (!recorded) ori__mf_record(mo, th, last_res, D0 > 0.0 ? 1.0 - goal_distance(m, joint_var, th, goal) / D0 : 1.0);
    mo->newton += sys.newton_iterations;
    ori__mf_free(&sys);
    ori__free(all_locks);
    ori__free(th);
    ori__free(target);
    ori__free(joint_var);
    ori__free(phi);
    ori__free(goal);
    ori__free(gvar);
    ori__free(nj);
    ori__free(d);
    ori__free(p);
    ori__free(jd);
    ori__free(trial);
    ori__free(pred);
    ori__free(mid);
    if (!cancelled) ori__mf_check_assignment(mo);
    if (!cancelled && def->progress) cancelled = !def->progress(1.0, def->progress_user);
    if (cancelled) {
        ori_multifold_destroy(mo);
        return ori__fail(error, ORI_ERR_LIMIT, "cancelled");
    }
    *out = mo;
    return ORI_OK;
}
