// Which creases to lock so that a fold with several degrees of freedom keeps one per drive.
//
// At a regular state the motions are the null space of the loop-closure Jacobian J. Driving the
// creases D and locking L leaves the motion unique (to first order) when the columns of J
// outside D ∪ L are independent and span the column space of J: then J_free ẋ = −J_D ṡ has
// exactly one solution. A rank-revealing QR with column pivoting (LAPACK dgeqp3) of the
// non-driven columns picks such a basis greedily, best conditioned first; the columns it leaves
// out are the lock set. The flat sheet is singular (its out-of-plane rows vanish), so the rank
// is taken at a nearby state on the motion: the drives moved a little (in the direction their
// assignment folds them) with the locked creases held at their angles, the others solved with
// minimum-norm corrections. The columns are weighted by how fast their creases move there, so
// that the creases the motion uses stay free and those it barely moves are locked; then the
// probe is repeated with the new locks, until the drives leave no freedom (at most
// LOCKSET_ROUNDS rounds).
#include <lapacke.h>
#include <math.h>
#include <string.h>

#include "multifold_internal.h"

// Numerical rank by dgeqp3 of a (rows × cols, column-major, destroyed); jpvt (cols, 1-based
// on return) gives the pivot order. -1 on LAPACK failure.
static int qr_rank(double *a, int rows, int cols, int *jpvt)
{
    if (cols == 0) return 0;
    if (rows == 0) {
        for (int k = 0; k < cols; ++k) jpvt[k] = k + 1;
        return 0;
    }
    for (int k = 0; k < cols; ++k) jpvt[k] = 0;
    int kmin = rows < cols ? rows : cols;
    double *tau = ori__alloc(sizeof(double) * (size_t)(kmin + 1));
    lapack_int info = LAPACKE_dgeqp3(LAPACK_COL_MAJOR, rows, cols, a, rows, jpvt, tau);
    ori__free(tau);
    if (info != 0) return -1;
    double r11 = fabs(a[0]);
    int r = 0;
    for (int k = 0; k < kmin; ++k)
        if (fabs(a[(size_t)k * (size_t)rows + (size_t)k]) > ORI_TOL_LOCKSET_RANK_REL * r11 && r11 > 0.0) r++;
    return r;
}

#define LOCKSET_ROUNDS 6

// Move the drives by δ from th (rate: +1 or −1 per driven joint) with the joints that have no
// solved variable held; the others solved. out receives the state, vel (per variable of
// sys_var) the velocity estimate. False when no δ gives a closed state.
static bool drive_probe(const ori_mechanism *m, const int *sys_var, int nsys, const double *rate, const double *th,
                        double *out, double *vel)
{
    int J = m->joint_count;
    mf_system s;
    ori__mf_init(&s, m, sys_var, nsys);
    double *b = ori__alloc(sizeof(double) * (size_t)(m->rows + 1));
    double *x = ori__alloc(sizeof(double) * (size_t)(nsys + 1));
    bool found = false;
    if (ori__mf_linearize(&s, th)) {
        ori__mf_joint_rate(&s, rate, b);
        for (int r = 0; r < m->rows; ++r) b[r] = -b[r];
        if (ori__mf_minnorm(&s, b, x))
            for (double h = 0.02; h > 1e-4 && !found; h *= 0.25) {
                for (int j = 0; j < J; ++j)
                    out[j] = th[j] + h * (sys_var[j] >= 0 ? x[sys_var[j]] : rate[j]);
                int its;
                double res;
                if (ori__mf_correct(&s, out, &its, &res)) {
                    found = true;
                    for (int j = 0; j < J; ++j)
                        if (sys_var[j] >= 0) vel[sys_var[j]] = (out[j] - th[j]) / h;
                }
            }
    }
    ori__free(b);
    ori__free(x);
    ori__mf_free(&s);
    return found;
}

int ori_mechanism_lock_set(const ori_mechanism *m, const double *angles, const int *drive_edges, int drive_count,
                           const int *locked_edges, int locked_count, const int *edge_group, int *out, int cap,
                           ori_error *error)
{
    ORI_ASSERT(m && (drive_edges || drive_count == 0) && (out || cap == 0));
    int J = m->joint_count, R = m->rows;
    int *joint_var = ori__alloc(sizeof(int) * (size_t)(J + 1));
    int nvar = ori__mf_variables(m, locked_edges, locked_count, edge_group, joint_var, error);
    if (nvar < 0) {
        ori__free(joint_var);
        return -1;
    }
    if ((double)R * (double)nvar > ORI_LOCKSET_DENSE_MAX_ENTRIES) {
        ori__free(joint_var);
        ori__fail(error, ORI_ERR_UNSUPPORTED,
                  "the lock set needs the dense Jacobian (%d x %d entries, above %d): lock creases by hand", R, nvar,
                  ORI_LOCKSET_DENSE_MAX_ENTRIES);
        return -1;
    }
    double *rate = ori__calloc((size_t)J + 1, sizeof(double));
    bool *is_drive = ori__calloc((size_t)nvar + 1, sizeof(bool));
    for (int i = 0; i < drive_count; ++i) {
        int e = drive_edges[i];
        int j = e >= 0 && e < m->edge_count ? m->edge_joint[e] : ORI_NULL_INDEX;
        if (j == ORI_NULL_INDEX || joint_var[j] < 0) {
            ori__free(joint_var);
            ori__free(is_drive);
            ori__free(rate);
            ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_vertices", e, "edge %d is not a free crease to drive", e);
            return -1;
        }
        is_drive[joint_var[j]] = true;
    }
    for (int j = 0; j < J; ++j)
        if (joint_var[j] >= 0 && is_drive[joint_var[j]])
            rate[j] = m->joints[j].assignment == ORI_ASSIGN_MOUNTAIN ? -1.0 : 1.0;
    double *th = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *th2 = ori__alloc(sizeof(double) * (size_t)(J + 1));
    ori__kin_edges_to_joints(m, angles, th);
    bool *lock = ori__calloc((size_t)nvar + 1, sizeof(bool)); // variables locked by the set
    int *sys_var = ori__alloc(sizeof(int) * (size_t)(J + 1));
    int *sys_of_var = ori__alloc(sizeof(int) * (size_t)(nvar + 1));
    int *var_of_col = ori__alloc(sizeof(int) * (size_t)(nvar + 1));
    int *col_of_joint = ori__alloc(sizeof(int) * (size_t)(J + 1));
    double *vel = ori__alloc(sizeof(double) * (size_t)(nvar + 1));
    double *a = ori__alloc(sizeof(double) * ((size_t)R * (size_t)(nvar + 2) + 1));
    int *jpvt = ori__alloc(sizeof(int) * (size_t)(nvar + 1));
    int n = -1;
    for (int round = 0; round < LOCKSET_ROUNDS; ++round) {
        int nsys = 0;
        for (int v = 0; v < nvar; ++v) sys_of_var[v] = is_drive[v] || lock[v] ? -1 : nsys++;
        for (int j = 0; j < J; ++j) sys_var[j] = joint_var[j] >= 0 ? sys_of_var[joint_var[j]] : -1;
        if (!drive_probe(m, sys_var, nsys, rate, th, th2, vel)) {
            ori__fail(error, ORI_ERR_ARGUMENT,
                      round == 0 ? "no rigid motion moves the driven creases from this state: no lock set helps"
                                 : "no lock set found that keeps the motion: lock creases by hand");
            break;
        }
        // Columns: the solved variables, weighted by their speed on the probe's motion.
        double vmax = 0.0;
        for (int k = 0; k < nsys; ++k) vmax = fmax(vmax, fabs(vel[k]));
        int ncand = 0;
        for (int v = 0; v < nvar; ++v)
            if (sys_of_var[v] >= 0) var_of_col[ncand++] = v;
        for (int j = 0; j < J; ++j) col_of_joint[j] = joint_var[j] >= 0 ? sys_of_var[joint_var[j]] : -1;
        ori__mf_dense_jacobian(m, th2, col_of_joint, ncand, a);
        for (int c = 0; c < ncand; ++c) {
            double w = fabs(vel[sys_of_var[var_of_col[c]]]) + 1e-3 * vmax;
            for (int r = 0; r < R; ++r) a[(size_t)c * (size_t)R + (size_t)r] *= w;
        }
        int rc = qr_rank(a, R, ncand, jpvt);
        // (That the drives can move at all was shown by the probe.)
        if (rc < 0) {
            ori__fail(error, ORI_ERR_INTERNAL, "LAPACK dgeqp3 failed");
            break;
        }
        if (rc == ncand) { // no freedom left beside the drives
            n = 0;
            for (int v = 0; v < nvar; ++v) {
                if (!lock[v]) continue;
                if (n < cap)
                    for (int j = 0; j < J; ++j)
                        if (joint_var[j] == v) {
                            out[n] = m->joints[j].edge;
                            break;
                        }
                n++;
            }
            if (n > cap) n = cap;
            for (int i = 1; i < n; ++i) // ascending edge order
                for (int k = i; k > 0 && out[k - 1] > out[k]; --k) {
                    int t = out[k];
                    out[k] = out[k - 1];
                    out[k - 1] = t;
                }
            break;
        }
        for (int k = rc; k < ncand; ++k) lock[var_of_col[jpvt[k] - 1]] = true;
        if (round == LOCKSET_ROUNDS - 1)
            ori__fail(error, ORI_ERR_ARGUMENT, "no lock set found that keeps the motion: lock creases by hand");
    }
    ori__free(joint_var);
    ori__free(is_drive);
    ori__free(rate);
    ori__free(th);
    ori__free(th2);
    ori__free(lock);
    ori__free(sys_var);
    ori__free(sys_of_var);
    ori__free(var_of_col);
    ori__free(col_of_joint);
    ori__free(vel);
    ori__free(a);
    ori__free(jpvt);
    return n;
}
