// Degrees of freedom: the nullity of the loop-closure Jacobian (the true DOF of
// overconstrained mechanisms, where the Grübler–Kutzbach count fails), dense by SVD or sparse
// by inverse subspace iteration with a CHOLMOD factor; and, at singular states such as the
// flat sheet, the nullity at a nearby regular state on the motion.
#include <math.h>
#include <string.h>

#include "kinematics_internal.h"

// A crease of the probe's nearby state counts as folded against its assignment when its angle has
// the wrong sign by more than this fraction of the largest change the probe made (and more than
// ORI_TOL_FOLD_SIGN_RAD): second-order drift of creases the motion does not use is not counted.
#define ORI_DOF_AGAINST_REL 1e-3

ori_dof_def ori_default_dof_def(void)
{
    ori_dof_def def;
    def.angles_rad = NULL;
    def.locked_edges = NULL;
    def.locked_count = 0;
    def.probe_generic = true;
    def.probe_budget = 0;
    def.progress = NULL;
    def.progress_user = NULL;
    def.internal_value = ORI__DEF_COOKIE;
    return def;
}

// True when some M/V crease, driven the way it is assigned from th with the creases of col free
// (col[j] >= 0), has a tangent that folds every assigned crease its way (or a family of them);
// bounded by ORI_KIN_PROBE_BUDGET line combinations in all.
static bool assigned_motion_exists(const ori_mechanism *m, const double *th, const int *col_of_joint)
{
    int J = m->joint_count;
    int *col = ori__alloc(sizeof(int) * (size_t)(J + 1));
    double *v = ori__alloc(sizeof(double) * (size_t)(J + 1));
    long budget = ORI_KIN_PROBE_BUDGET;
    bool found = false;
    for (int jd = 0; jd < J && !found && budget > 0; ++jd) {
        ori_assignment as = m->joints[jd].assignment;
        if (col_of_joint[jd] < 0 || (as != ORI_ASSIGN_VALLEY && as != ORI_ASSIGN_MOUNTAIN)) continue;
        int n = 0;
        for (int j = 0; j < J; ++j) col[j] = j == jd ? KIN_DRIVE : col_of_joint[j] >= 0 ? n++ : KIN_FIXED;
        int extra;
        kin_cone_result cr = ori__kin_cone_budget(m, th, col, n, jd, as == ORI_ASSIGN_VALLEY ? 1.0 : -1.0, false, v,
                                                  &extra, &budget);
        found = cr == KIN_CONE_FOUND || cr == KIN_CONE_UNDERDETERMINED;
    }
    ori__free(col);
    ori__free(v);
    return found;
}

ori_status ori_mechanism_dof(const ori_mechanism *m, const ori_dof_def *def, ori_dof_result *out, ori_error *error)
{
    ORI_ASSERT(m && def && def->internal_value == ORI__DEF_COOKIE && out);
    memset(out, 0, sizeof *out);
    out->nearby_against_edge = ORI_NULL_INDEX;
    out->grubler = m->grubler;
    out->generic_dof = -1;
    int J = m->joint_count;
    if (def->angles_rad)
        for (int e = 0; e < m->edge_count; ++e)
            if (!isfinite(def->angles_rad[e]))
                return ori__fail_at(error, ORI_ERR_RANGE, "edges_foldAngle", e, "fold angle is not finite");
    int *col = ori__alloc(sizeof(int) * (size_t)(J + 1));
    for (int j = 0; j < J; ++j) col[j] = m->joints[j].kind == ORI_JOINT_REVOLUTE ? 0 : KIN_FIXED;
    for (int i = 0; i < def->locked_count; ++i) {
        int e = def->locked_edges[i];
        if (e < 0 || e >= m->edge_count) {
            ori__free(col);
            return ori__fail_at(error, ORI_ERR_RANGE, "edges_vertices", e, "no edge %d", e);
        }
        if (m->edge_joint[e] != ORI_NULL_INDEX) col[m->edge_joint[e]] = KIN_FIXED;
    }
    int n = 0;
    for (int j = 0; j < J; ++j)
        if (col[j] >= 0) col[j] = n++;
    double *th = ori__alloc(sizeof(double) * (size_t)(J + 1));
    ori__kin_edges_to_joints(m, def->angles_rad, th);
    double res = ori__kin_residual(m, th);
    if (!(res <= ORI_TOL_START_RESIDUAL)) {
        ori__free(col);
        ori__free(th);
        return ori__fail(error, ORI_ERR_ARGUMENT,
                         "the fold angles do not close the loops (residual %.3g above %.0e)", res,
                         ORI_TOL_START_RESIDUAL);
    }
    if (def->progress && !def->progress(0.0, def->progress_user)) {
        ori__free(col);
        ori__free(th);
        return ori__fail(error, ORI_ERR_LIMIT, "cancelled");
    }
    ori_status st = ori__kin_nullity(m, th, col, n, out, error);
    out->grubler = m->grubler;
    out->generic_dof = -1;
    out->nearby_against = 0;
    out->nearby_against_edge = ORI_NULL_INDEX;
    out->nearby_against_rad = 0.0;
    bool probe = st == ORI_OK && def->probe_generic && out->dof > 0 && m->rows > 0;
    // Fractions: the rank at the state, then each probe round with its rank.
    if (st == ORI_OK && def->progress &&
        !def->progress(probe ? 1.0 / (ORI_KIN_PROBE_ROUNDS + 1) : 1.0, def->progress_user))
        st = ori__fail(error, ORI_ERR_LIMIT, "cancelled");
    if (st == ORI_OK && probe) {
        // Step along a motion and measure there; a single step may leave some vertices flat
        // (still singular), so step again from the new state while the nullity drops. The
        // branch enumeration of the probe is bounded by the budget (exponential otherwise).
        long budget = def->probe_budget > 0 ? def->probe_budget : ORI_KIN_PROBE_BUDGET;
        long start_budget = budget;
        double *cur = ori__alloc(sizeof(double) * (size_t)(J + 1));
        double *next = ori__alloc(sizeof(double) * (size_t)(J + 1));
        memcpy(cur, th, sizeof(double) * (size_t)J);
        int best = -1;
        kin_probe_result pr = KIN_PROBE_RIGID;
        for (int round = 0; round < ORI_KIN_PROBE_ROUNDS && st == ORI_OK; ++round) {
            pr = ori__kin_probe_generic(m, cur, col, n, next, &budget);
            if (pr != KIN_PROBE_MOVED) break;
            ori_dof_result near;
            st = ori__kin_nullity(m, next, col, n, &near, error);
            if (st == ORI_OK && def->progress &&
                !def->progress((double)(round + 2) / (ORI_KIN_PROBE_ROUNDS + 1), def->progress_user))
                st = ori__fail(error, ORI_ERR_LIMIT, "cancelled");
            if (st != ORI_OK || (best >= 0 && near.dof >= best)) break;
            best = near.dof;
            memcpy(cur, next, sizeof(double) * (size_t)J);
            if (best == 0) break;
        }
        out->probe_solves = (int)(start_budget - budget);
        if (best >= 0) {
            out->generic_dof = best;
            // Does the motion found keep the assignment? The probe takes any branch (the free
            // mechanism's), so a nearby DOF may belong to motions no assigned fold can use.
            double moved = 0.0;
            for (int j = 0; j < J; ++j) moved = fmax(moved, fabs(cur[j] - th[j]));
            for (int j = 0; j < J; ++j) {
                if (col[j] < 0 || m->joints[j].kind != ORI_JOINT_REVOLUTE) continue;
                ori_assignment as = m->joints[j].assignment;
                int sg = as == ORI_ASSIGN_VALLEY ? 1 : as == ORI_ASSIGN_MOUNTAIN ? -1 : 0;
                double x = cur[j];
                if (!sg || !(x * sg < 0.0) || fabs(x) <= fmax(ORI_TOL_FOLD_SIGN_RAD, ORI_DOF_AGAINST_REL * moved)) continue;
                if (th[j] * sg < 0.0 && fabs(x) <= fabs(th[j])) continue; // no further than the state itself
                if (out->nearby_against == 0 || fabs(x) > fabs(out->nearby_against_rad)) {
                    out->nearby_against_edge = m->joints[j].edge;
                    out->nearby_against_rad = x;
                }
                out->nearby_against++;
            }
            // The probe takes the first branch it finds. When that one ignores the assignment,
            // look for one that keeps it: an assigned crease driven its own way whose tangent cone
            // has a direction folding every crease as assigned (cone.c). Found: no note.
            if (out->nearby_against > 0 && assigned_motion_exists(m, th, col))
                out->nearby_against = 0, out->nearby_against_edge = ORI_NULL_INDEX, out->nearby_against_rad = 0.0;
        } else if (pr == KIN_PROBE_EXHAUSTED) {
            out->undetermined = true; // neither a motion nor a proof that there is none
        } else {
            out->generic_dof = 0;
            out->rigid = true;
        }
        ori__free(cur);
        ori__free(next);
        if (st == ORI_OK) out->singular = out->generic_dof >= 0 && out->dof > out->generic_dof;
    } else if (st == ORI_OK && out->dof == 0) {
        out->generic_dof = 0;
    }
    if (st == ORI_OK && def->progress) def->progress(1.0, def->progress_user);
    ori__free(col);
    ori__free(th);
    return st;
}
