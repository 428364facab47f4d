// Generic-DOF probe: from a (possibly singular) state, follow the free mechanism a little along
// a second-order tangent (cone.c) with minimum-norm corrections (solver.c) to a nearby regular
// state. Used by dof.c; above cone.c and solver.c.
#include "kinematics_internal.h"

kin_probe_result ori__kin_probe_generic(const ori_mechanism *m, const double *th, const int *col_of_joint, int ncols,
                                        double *th_out, long *budget)
{
    int J = m->joint_count;
    int *col = ori__alloc(sizeof(int) * (size_t)(J + 1));
    double *v = ori__alloc(sizeof(double) * (size_t)(J + 1));
    bool found = false, exhausted = false;
    int tried = 0;
    (void)ncols;
    for (int jd = 0; jd < J && !found && !exhausted && tried < 16; ++jd) {
        if (col_of_joint[jd] < 0) continue;
        tried++;
        int n = 0;
        for (int j = 0; j < J; ++j) col[j] = j == jd ? KIN_DRIVE : col_of_joint[j] >= 0 ? n++ : KIN_FIXED;
        for (int sgi = 0; sgi < 2 && !found && !exhausted; ++sgi) {
            double sg = sgi == 0 ? 1.0 : -1.0;
            int extra;
            kin_cone_result cr = ori__kin_cone_budget(m, th, col, n, jd, sg, true, v, &extra, budget);
            if (cr == KIN_CONE_EXHAUSTED) exhausted = true;
            if (cr != KIN_CONE_FOUND && cr != KIN_CONE_VIOLATING) continue;
            kin_solver_opts opts = {ORI_LINEAR_AUTO, true};
            kin_solver *s = ori__kin_solver_create(m, col, n, jd, &opts);
            for (double h = ORI_KIN_PROBE_STEP_RAD; h > ORI_KIN_PROBE_MIN_STEP_RAD && !found; h *= 0.5) {
                for (int j = 0; j < J; ++j) th_out[j] = th[j] + h * v[j];
                int its;
                double res;
                if (ori__kin_correct(s, th_out, ORI_KIN_NEWTON_MAX, &its, &res)) found = true;
            }
            ori__kin_solver_destroy(s);
        }
    }
    ori__free(col);
    ori__free(v);
    return found ? KIN_PROBE_MOVED : exhausted ? KIN_PROBE_EXHAUSTED : KIN_PROBE_RIGID;
}
