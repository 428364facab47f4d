// Several creases driven together: crease i of the drive set follows θ_i(t) = θ_i(0) + t·r_i,
// t from 0 to 1, and the other unlocked creases are solved. Continuation in t: the predictor
// follows the minimum-norm tangent J_free ẋ = −J_drive r (CHOLMOD on J Jᵀ + λI, shared with
// targets.c), the drives are set exactly, Newton (minimum-norm) closes the loops on the free
// creases. The fold is underdetermined when the free creases keep freedom at the first state
// past the start (the flat start is singular and says nothing), overdetermined when the
// tangent equation has no solution (relative defect above ORI_TOL_DRIVES_DEFECT) where the
// motion stops.
#include <lapacke.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "multifold_internal.h"

ori_drives_fold_def ori_default_drives_fold_def(void)
{
    ori_drives_fold_def d;
    memset(&d, 0, sizeof d);
    d.fixed_face = 0;
    d.fixed_pose = ori_rigid_identity();
    d.step_rad = ORI_PI / 18.0;
    d.internal_value = ORI__DEF_COOKIE;
    return d;
}

// Nullity of the free columns at th (dense SVD; above ORI_LOCKSET_DENSE_MAX_ENTRIES entries the
// sparse null-space basis of lockset_sparse.c; -1 when neither can tell).
static int free_nullity(const ori_mechanism *m, const int *var, int nvar, const double *th)
{
    int R = m->rows;
    if (nvar == 0) return 0;
    if ((double)R * (double)nvar > ORI_LOCKSET_DENSE_MAX_ENTRIES) {
        mf_system fs;
        ori__mf_init(&fs, m, var, nvar);
        int d = ori__mf_linearize(&fs, th) ? ori__mf_freedom(&fs, NULL, NULL) : -1;
        ori__mf_free(&fs);
        return d < 0 ? -1 : d;
    }
    double *a = ori__alloc(sizeof(double) * ((size_t)R * (size_t)nvar + 1));
    ori__mf_dense_jacobian(m, th, var, nvar, a);
    int k = R < nvar ? R : nvar;
    double *sv = ori__alloc(sizeof(double) * (size_t)(k + 1));
    double *superb = ori__alloc(sizeof(double) * (size_t)(k + 1));
    int rank = -1;
    if (R == 0) {
        rank = 0;
    } else if (LAPACKE_dgesvd(LAPACK_COL_MAJOR, 'N', 'N', R, nvar, a, R, sv, NULL, 1, NULL, 1, superb) == 0) {
        rank = 0;
        for (int i = 0; i < k; ++i)
            if (sv[i] > ORI_TOL_RANK_REL * sv[0]) rank++;
    }
    ori__free(a);
    ori__free(sv);
    ori__free(superb);
    return rank < 0 ? -1 : nvar - rank;
}

ori_status ori_drives_fold_solve(const ori_mechanism *m, const ori_drives_fold_def *def, ori_multifold **out,
                                 ori_error *error)
{
    ORI_ASSERT(m && def && def->internal_value == ORI__DEF_COOKIE && out);
    *out = NULL;
    int J = m->joint_count, R = m->rows;
    if (def->driven_count <= 0 || !def->driven_edges || !def->to_rad)
        return ori__fail(error, ORI_ERR_ARGUMENT, "no driven crease");
    if (!(def->step_rad > 0.0) || !isfinite(def->step_rad))
        return ori__fail(error, ORI_ERR_RANGE, "the step must be a positive angle (got %g°)", ori_rad_to_deg(def->step_rad));
    double *th = ori__alloc(sizeof(double) * (size_t)(J + 1));
    int *var = ori__alloc(sizeof(int) * (size_t)(J + 1));
    int *sys_var = ori__alloc(sizeof(int) * (size_t)(J + 1));
    double *rate = ori__calloc((size_t)J + 1, sizeof(double));
    double *phi = NULL;
    int *drive_of_var = NULL, *newv = NULL;
    double *dv_to = NULL;
    ori_status st = ori__mf_check_start(m, def->fixed_face, def->start_angles_rad, th, error);
    int nvar = st == ORI_OK ? ori__mf_variables(m, def->locked_edges, def->locked_count, def->edge_group, var, error) : 0;
    if (st == ORI_OK && nvar < 0) st = ORI_ERR_RANGE;
    if (st == ORI_OK) {
        phi = ori__alloc(sizeof(double) * (size_t)(nvar + 1));
        st = ori__mf_group_start(m, var, nvar, th, phi, error);
    }
    if (st == ORI_OK) {
        drive_of_var = ori__alloc(sizeof(int) * (size_t)(nvar + 1));
        dv_to = ori__alloc(sizeof(double) * (size_t)(nvar + 1));
        for (int v = 0; v < nvar; ++v) drive_of_var[v] = -1;
        for (int i = 0; i < def->driven_count && st == ORI_OK; ++i) {
            int e = def->driven_edges[i];
            double to = def->to_rad[i];
            int j = e >= 0 && e < m->edge_count ? m->edge_joint[e] : ORI_NULL_INDEX;
            if (e < 0 || e >= m->edge_count)
                st = ori__fail_at(error, ORI_ERR_RANGE, "edges_vertices", e, "no edge %d (a driven crease)", e);
            else if (j == ORI_NULL_INDEX || m->joints[j].kind != ORI_JOINT_REVOLUTE)
                st = ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_vertices", e,
                                  "edge %d is not a crease that can be driven (assignment %c, or no face on one side)", e,
                                  ori_assignment_to_char(m->edges[e].assignment));
            else if (var[j] < 0)
                st = ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_vertices", e, "edge %d is both driven and locked", e);
            else if (!isfinite(to) || fabs(to) > ORI_PI + ORI_TOL_FOLD_SIGN_RAD)
                st = ori__fail_at(error, ORI_ERR_RANGE, "edges_foldAngle", e, "target angle %g° is outside [-180°, 180°]",
                                  ori_rad_to_deg(to));
            else if (drive_of_var[var[j]] >= 0 && fabs(dv_to[var[j]] - to) > ORI_TOL_FOLD_SIGN_RAD)
                st = ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_vertices", e,
                                  "edge %d is driven twice (directly or through its symmetry group) to different angles", e);
            else {
                drive_of_var[var[j]] = i;
                dv_to[var[j]] = to;
            }
        }
    }
    if (st != ORI_OK) {
        ori__free(th);
        ori__free(var);
        ori__free(sys_var);
        ori__free(rate);
        ori__free(phi);
        ori__free(drive_of_var);
        ori__free(dv_to);
        return st;
    }
    // The solved variables: every variable that is not driven, renumbered.
    newv = ori__alloc(sizeof(int) * (size_t)(nvar + 1));
    int nfree = 0;
    double rmax = 0.0;
    for (int v = 0; v < nvar; ++v) newv[v] = drive_of_var[v] >= 0 ? -1 : nfree++;
    for (int j = 0; j < J; ++j) {
        sys_var[j] = var[j] >= 0 ? newv[var[j]] : -1;
        if (var[j] >= 0 && drive_of_var[var[j]] >= 0) {
            rate[j] = dv_to[var[j]] - phi[var[j]];
            rmax = fmax(rmax, fabs(rate[j]));
        }
    }
    ori_multifold *mo = ori__mf_result_create(m, def->fixed_face, def->fixed_pose);
    for (int j = 0; j < J; ++j) {
        mo->goal[m->joints[j].edge] = th[j] + rate[j];
    }
    mf_system s;
    ori__mf_init(&s, m, sys_var, nfree);
    int its;
    double res = ori__kin_residual(m, th);
    if (res > ORI_TOL_RESIDUAL && !ori__mf_correct(&s, th, &its, &res)) {
        st = ori__fail(error, ORI_ERR_NOT_CONVERGED, "the start state could not be closed (residual %.3g)", res);
        ori__mf_free(&s);
        ori_multifold_destroy(mo);
        mo = NULL;
    }
    double *th0 = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *x = ori__alloc(sizeof(double) * (size_t)(nfree + 1));
    double *b = ori__alloc(sizeof(double) * (size_t)(R + 1));
    double *jx = ori__alloc(sizeof(double) * (size_t)(R + 1));
    double *trial = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *pred = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *sgn = ori__alloc(sizeof(double) * (size_t)(nfree + 1));
    double *nx = ori__alloc(sizeof(double) * (size_t)(nfree + 1));
    bool cancelled = false; // the progress callback returned false
    if (mo) {
        memcpy(th0, th, sizeof(double) * (size_t)J);
        ori__mf_record(mo, th, ori__kin_residual(m, th), 0.0);
        ori__mf_watch(mo, th, 0.0);
        double dt_out = rmax > 0.0 ? fmin(1.0, def->step_rad / rmax) : 1.0;
        double dt_max = rmax > 0.0 ? ORI_MULTIFOLD_MAX_STEP_RAD / rmax : 1.0;
        double h = fmin(dt_out, dt_max), t = 0.0, defect = 0.0;
        bool bias = true; // the assignment's direction at the start; dropped when it leads nowhere
        int k_out = 1;
        double t_next = fmin(1.0, dt_out);
        bool first = true;
        int why_joint = -1;
        if (rmax == 0.0) {
            mo->verdict = ORI_MULTIFOLD_REACHED;
            snprintf(mo->reason, sizeof mo->reason, "the drives are at their targets already");
        }
        while (rmax > 0.0) {
            // Tangent at the current state.
            bool ok = ori__mf_linearize(&s, th);
            ori__mf_joint_rate(&s, rate, b);
            double bmax = 0.0;
            for (int r = 0; r < R; ++r) {
                b[r] = -b[r];
                bmax = fmax(bmax, fabs(b[r]));
            }
            ok = ok && ori__mf_minnorm(&s, b, x);
            if (ok) {
                ori__mf_jv(&s, x, jx);
                defect = 0.0;
                for (int r = 0; r < R; ++r) defect = fmax(defect, fabs(jx[r] - b[r]));
                defect = bmax > 0.0 ? defect / bmax : 0.0;
            } else {
                for (int v = 0; v < nfree; ++v) x[v] = 0.0;
            }
            // At the start, which may be singular (the flat sheet, where many branches meet), add the
            // part of the assignment's direction that the first-order motions allow: the predictor
            // then heads for the branch that folds the creases as assigned. A crease at ±180° (a
            // fully folded start) can only turn toward 0, whatever its assignment.
            if (ok && t == 0.0 && bias) {
                for (int v = 0; v < nfree; ++v) sgn[v] = 0.0;
                for (int j = 0; j < J; ++j) {
                    ori_assignment as = m->joints[j].assignment;
                    int dir = as == ORI_ASSIGN_VALLEY ? 1 : as == ORI_ASSIGN_MOUNTAIN ? -1 : 0;
                    if (fabs(th[j]) >= ORI_PI - ORI_TOL_KIN_FOLDED_RAD) dir = th[j] > 0.0 ? -1 : 1;
                    if (sys_var[j] >= 0) sgn[sys_var[j]] += dir * rmax;
                }
                ori__mf_jv(&s, sgn, jx);
                if (ori__mf_minnorm(&s, jx, nx))
                    for (int v = 0; v < nfree; ++v) x[v] += sgn[v] - nx[v];
            }
            double tn = fmin(t_next, t + h);
            if (t_next - tn < 0.25 * h) tn = t_next;
            double dt = tn - t;
            memcpy(trial, th, sizeof(double) * (size_t)J);
            for (int j = 0; j < J; ++j) {
                if (sys_var[j] >= 0) trial[j] += dt * x[sys_var[j]];
                else if (rate[j] != 0.0) trial[j] = th0[j] + tn * rate[j];
            }
            memcpy(pred, trial, sizeof(double) * (size_t)J);
            bool conv = ori__mf_correct(&s, trial, &its, &res);
            double move = 0.0, step = dt * rmax;
            int over = -1;
            for (int j = 0; j < J; ++j) {
                if (sys_var[j] < 0) continue;
                move = fmax(move, fabs(trial[j] - pred[j]));
                step = fmax(step, fabs(pred[j] - th[j]));
                if (!(fabs(trial[j]) <= ORI_PI + ORI_TOL_NEWTON) && (over < 0 || fabs(trial[j]) > fabs(trial[over])))
                    over = j;
            }
            bool accept = conv && move <= ORI_MULTIFOLD_MAX_CORRECTION * step + ORI_MULTIFOLD_MIN_STEP_RAD && over < 0;
            if (conv && over >= 0) why_joint = over;
            if (!accept) {
                mo->rejected++;
                h *= 0.5;
                if (h * rmax >= ORI_MULTIFOLD_MIN_STEP_RAD) continue;
                if (t == 0.0 && bias) { // the assigned branch does not exist: any motion of the drives
                    bias = false;
                    h = fmin(dt_out, dt_max);
                    continue;
                }
                if (why_joint >= 0) {
                    mo->verdict = ORI_MULTIFOLD_LIMIT;
                    mo->stop_edge = m->joints[why_joint].edge;
                    snprintf(mo->reason, sizeof mo->reason,
                             "crease %d reached %.6g° at %.6g %% of the way and the drives would fold it beyond",
                             mo->stop_edge, th[why_joint] >= 0.0 ? 180.0 : -180.0, 100.0 * t);
                } else if (defect > ORI_TOL_DRIVES_DEFECT || t * rmax < ORI_DRIVES_CHECK_RAD) {
                    mo->verdict = ORI_MULTIFOLD_OVERDETERMINED;
                    snprintf(mo->reason, sizeof mo->reason,
                             t * rmax < ORI_DRIVES_CHECK_RAD ? "no rigid motion moves the drives together as prescribed from the start (too "
                                        "many creases driven or locked, or the ratio is not one the pattern allows)"
                                      : "the drives cannot keep moving together beyond %.6g %% of the way: no rigid "
                                        "motion follows the prescribed ratio further",
                             100.0 * t);
                } else {
                    mo->verdict = ORI_MULTIFOLD_SINGULAR;
                    snprintf(mo->reason, sizeof mo->reason,
                             "the motion reaches a singular configuration at %.6g %% of the way: no step beyond closes the "
                             "loops",
                             100.0 * t);
                }
                break;
            }
            memcpy(th, trial, sizeof(double) * (size_t)J);
            t = tn;
            mo->steps++;
            ori__mf_watch(mo, th, fmin(t, 1.0));
            if (def->progress && !def->progress(fmin(t, 1.0), def->progress_user)) { // t only grows
                cancelled = true;
                break;
            }
            // Freedom left to the solved creases: judged once the drives have moved by
            // ORI_DRIVES_CHECK_RAD (nearer the flat start the singular values are too small to tell).
            if (first && (t * rmax >= ORI_DRIVES_CHECK_RAD || t >= 1.0)) {
                first = false;
                int nul = free_nullity(m, sys_var, nfree, th);
                if (nul > 0) {
                    mo->verdict = ORI_MULTIFOLD_UNDERDETERMINED;
                    mo->extra_dof = nul;
                    snprintf(mo->reason, sizeof mo->reason,
                             "the fold leaves %d more degree%s of freedom than the %d driven crease%s fix%s", nul,
                             nul == 1 ? "" : "s", def->driven_count, def->driven_count == 1 ? "" : "s",
                             def->driven_count == 1 ? "es" : "");
                    mo->nframes = 0;
                    break;
                }
            }
            if (its <= 5) h = fmin(2.0 * h, dt_max);
            if (t == t_next) {
                ori__mf_record(mo, th, res, t);
                if (t >= 1.0) {
                    mo->verdict = ORI_MULTIFOLD_REACHED;
                    snprintf(mo->reason, sizeof mo->reason, "the drives reached their targets");
                    break;
                }
                k_out++;
                t_next = fmin(1.0, k_out * dt_out);
                if (1.0 - t_next < ORI_MULTIFOLD_GRID_REL) t_next = 1.0;
            }
        }
        if (mo->verdict != ORI_MULTIFOLD_REACHED && mo->verdict != ORI_MULTIFOLD_UNDERDETERMINED && mo->nframes > 0) {
            // The motion up to the stop: the last accepted state as the final frame.
            const double *last = ori_multifold_frame_angles(mo, mo->nframes - 1);
            double diff = 0.0;
            for (int j = 0; j < J; ++j) diff = fmax(diff, fabs(last[m->joints[j].edge] - th[j]));
            if (diff > 0.0) ori__mf_record(mo, th, ori__kin_residual(m, th), t);
        }
        mo->newton = s.newton_iterations;
        ori__mf_free(&s);
    }
    ori__free(th);
    ori__free(th0);
    ori__free(var);
    ori__free(sys_var);
    ori__free(rate);
    ori__free(phi);
    ori__free(drive_of_var);
    ori__free(dv_to);
    ori__free(newv);
    ori__free(x);
    ori__free(b);
    ori__free(jx);
    ori__free(trial);
    ori__free(pred);
    ori__free(sgn);
    ori__free(nx);
    if (!mo) return st;
    if (!cancelled) ori__mf_check_assignment(mo);
    if (!cancelled && def->progress) cancelled = !def->progress(1.0, def->progress_user);
    if (cancelled) {
        ori_multifold_destroy(mo);
        return ori__fail(error, ORI_ERR_LIMIT, "cancelled");
    }
    *out = mo;
    return ORI_OK;
}
