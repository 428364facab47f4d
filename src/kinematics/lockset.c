// Which creases to lock so that a fold with several degrees of freedom keeps one per drive.
//
// At a regular state the motions are the null space of the loop-closure Jacobian J. Driving the
// creases D and locking L leaves the motion unique (to first order) when the columns of J
// outside D ∪ L are independent and span the column space of J: then J_free ẋ = −J_D ṡ has
// exactly one solution. A rank-revealing QR with column pivoting (LAPACK dgeqp3) of the
// non-driven columns picks such a basis greedily, best conditioned first; the columns it leaves
// out are the lock set. The flat sheet is singular (its out-of-plane rows vanish), so the rank
// is taken at the flat state and at a nearby regular state reached along the assignment's
// direction (the first step of a fold toward the targets), and the higher one is used.
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

// Step from th along the assignment's direction projected onto the first-order motions, and
// close the loops: a nearby state on the free motion (false when none is found).
static bool probe(const ori_mechanism *m, const int *joint_var, int nvar, const double *th, double *out)
{
    mf_system s;
    ori__mf_init(&s, m, joint_var, nvar);
    double *d = ori__calloc((size_t)nvar + 1, sizeof(double));
    double *p = ori__alloc(sizeof(double) * (size_t)(nvar + 1));
    double *jd = ori__alloc(sizeof(double) * (size_t)(m->rows + 1));
    for (int j = 0; j < m->joint_count; ++j) {
        int v = joint_var[j];
        if (v < 0) continue;
        ori_assignment a = m->joints[j].assignment;
        // The assignment's sign; unassigned creases get a small deterministic pseudo-random value.
        d[v] += a == ORI_ASSIGN_VALLEY ? 1.0 : a == ORI_ASSIGN_MOUNTAIN ? -1.0 : 0.1 * sin(1.0 + j);
    }
    bool found = false;
    if (ori__mf_linearize(&s, th)) {
        ori__mf_jv(&s, d, jd);
        if (ori__mf_minnorm(&s, jd, p)) {
            double pmax = 0.0;
            for (int v = 0; v < nvar; ++v) {
                p[v] = d[v] - p[v];
                pmax = fmax(pmax, fabs(p[v]));
            }
            for (double h = 0.05; pmax > 0.0 && h > 1e-4 && !found; h *= 0.5) {
                memcpy(out, th, sizeof(double) * (size_t)m->joint_count);
                for (int j = 0; j < m->joint_count; ++j)
                    if (joint_var[j] >= 0) out[j] += h / pmax * p[joint_var[j]];
                int its;
                double res;
                found = ori__mf_correct(&s, out, &its, &res);
            }
        }
    }
    ori__free(d);
    ori__free(p);
    ori__free(jd);
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
    bool *is_drive = ori__calloc((size_t)nvar + 1, sizeof(bool));
    for (int i = 0; i < drive_count; ++i) {
        int e = drive_edges[i];
        int j = e >= 0 && e < m->edge_count ? m->edge_joint[e] : ORI_NULL_INDEX;
        if (j == ORI_NULL_INDEX || joint_var[j] < 0) {
            ori__free(joint_var);
            ori__free(is_drive);
            ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_vertices", e, "edge %d is not a free crease to drive", e);
            return -1;
        }
        is_drive[joint_var[j]] = true;
    }
    double *th = ori__alloc(sizeof(double) * (size_t)(J + 1));
    double *th2 = ori__alloc(sizeof(double) * (size_t)(J + 1));
    ori__kin_edges_to_joints(m, angles, th);
    // Columns: the non-driven variables first (candidates), then the drives.
    int *col = ori__alloc(sizeof(int) * (size_t)(nvar + 1));
    int *var_of_col = ori__alloc(sizeof(int) * (size_t)(nvar + 1));
    int nc = 0;
    for (int v = 0; v < nvar; ++v)
        if (!is_drive[v]) {
            var_of_col[nc] = v;
            col[v] = nc++;
        }
    int ncand = nc;
    for (int v = 0; v < nvar; ++v)
        if (is_drive[v]) {
            var_of_col[nc] = v;
            col[v] = nc++;
        }
    int *col_of_joint = ori__alloc(sizeof(int) * (size_t)(J + 1));
    for (int j = 0; j < J; ++j) col_of_joint[j] = joint_var[j] >= 0 ? col[joint_var[j]] : -1;
    double *a = ori__alloc(sizeof(double) * ((size_t)R * (size_t)(nc > 0 ? nc : 1) + 1));
    int *jpvt = ori__alloc(sizeof(int) * (size_t)(nc + 1));
    // The state with the higher rank of the whole Jacobian (the regular one).
    const double *state = th;
    ori__mf_dense_jacobian(m, th, col_of_joint, nc, a);
    int r0 = qr_rank(a, R, nc, jpvt);
    if (probe(m, joint_var, nvar, th, th2)) {
        ori__mf_dense_jacobian(m, th2, col_of_joint, nc, a);
        int r1 = qr_rank(a, R, nc, jpvt);
        if (r1 > r0) state = th2;
    }
    int n = -1;
    ori__mf_dense_jacobian(m, state, col_of_joint, nc, a);
    int rall = qr_rank(a, R, nc, jpvt);
    ori__mf_dense_jacobian(m, state, col_of_joint, nc, a);
    int rc = qr_rank(a, R, ncand, jpvt); // the candidates alone: their columns come first
    if (rall < 0 || rc < 0) {
        ori__fail(error, ORI_ERR_INTERNAL, "LAPACK dgeqp3 failed");
    } else if (rc < rall) {
        ori__fail(error, ORI_ERR_ARGUMENT,
                  "the driven creases cannot move at first order however the others are locked (their columns of the "
                  "loop-closure Jacobian are independent of the others')");
    } else {
        n = 0;
        for (int k = rc; k < ncand; ++k) {
            int v = var_of_col[jpvt[k] - 1];
            if (n < cap) {
                for (int j = 0; j < J; ++j)
                    if (joint_var[j] == v) {
                        out[n] = m->joints[j].edge;
                        break;
                    }
            }
            n++;
        }
        if (n > cap) n = cap;
        // Ascending edge order reads better.
        for (int i = 1; i < n; ++i)
            for (int k = i; k > 0 && out[k - 1] > out[k]; --k) {
                int t = out[k];
                out[k] = out[k - 1];
                out[k - 1] = t;
            }
    }
    ori__free(joint_var);
    ori__free(is_drive);
    ori__free(th);
    ori__free(th2);
    ori__free(col);
    ori__free(var_of_col);
    ori__free(col_of_joint);
    ori__free(a);
    ori__free(jpvt);
    return n;
}
