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
// LOCKSET_ROUNDS rounds). The set is verified by folding the drives 0.3 rad with it (the
// ordinary fold for one drive, else the several-drive solver); other probe lengths and
// unweighted columns are tried until a set folds every crease as assigned, else the best one
// that moves at all is returned.
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

// Move the drives by `total` from th (rate: +1 or −1 per driven joint) in substeps of at most
// ORI_LOCKSET_SUBSTEP_RAD, the joints without a solved variable held, the others solved (minimum-norm tangent;
// on the first substep plus the part of the assignment's direction that first order allows, to
// leave a singular start on the assigned branch). out receives the state, vel (per variable of
// sys_var) the minimum-norm tangent there. False when some substep cannot be closed without a
// jump.
static bool drive_probe(const ori_mechanism *m, const int *sys_var, int nsys, const double *rate, const double *th,
                        double total, double *out, double *vel)
{
    int J = m->joint_count;
    mf_system s;
    ori__mf_init(&s, m, sys_var, nsys);
    double *b = ori__alloc(sizeof(double) * (size_t)(m->rows + 1));
    double *jx = ori__alloc(sizeof(double) * (size_t)(m->rows + 1));
    double *x = ori__alloc(sizeof(double) * (size_t)(nsys + 1));
    double *sg = ori__alloc(sizeof(double) * (size_t)(nsys + 1));
    double *nx = ori__alloc(sizeof(double) * (size_t)(nsys + 1));
    double *cur = ori__alloc(sizeof(double) * (size_t)(J + 1));
    memcpy(cur, th, sizeof(double) * (size_t)J);
    int steps = (int)ceil(total / ORI_LOCKSET_SUBSTEP_RAD);
    bool ok = true;
    for (int k = 0; k <= steps && ok; ++k) {
        ok = ori__mf_linearize(&s, cur);
        if (ok) {
            ori__mf_joint_rate(&s, rate, b);
            for (int r = 0; r < m->rows; ++r) b[r] = -b[r];
            ok = ori__mf_minnorm(&s, b, x);
        }
        if (!ok || k == steps) break; // the last pass only computes the tangent
        if (k == 0) {
            for (int v = 0; v < nsys; ++v) sg[v] = 0.0;
            for (int j = 0; j < J; ++j) {
                ori_assignment as = m->joints[j].assignment;
                if (sys_var[j] >= 0) sg[sys_var[j]] += as == ORI_ASSIGN_VALLEY ? 1.0 : as == ORI_ASSIGN_MOUNTAIN ? -1.0 : 0.0;
            }
            ori__mf_jv(&s, sg, jx);
            if (ori__mf_minnorm(&s, jx, nx))
                for (int v = 0; v < nsys; ++v) x[v] += sg[v] - nx[v];
        }
        double xmax = 1.0;
        for (int v = 0; v < nsys; ++v) xmax = fmax(xmax, fabs(x[v]));
        bool found = false;
        for (double h = total / steps; h > ORI_LOCKSET_MIN_SUBSTEP_RAD && !found; h *= 0.25) {
            for (int j = 0; j < J; ++j) out[j] = cur[j] + h * (sys_var[j] >= 0 ? x[sys_var[j]] : rate[j]);
            int its;
            double res, move = 0.0;
            bool conv = ori__mf_correct(&s, out, &its, &res);
            for (int j = 0; j < J && conv; ++j)
                if (sys_var[j] >= 0) move = fmax(move, fabs(out[j] - cur[j] - h * x[sys_var[j]]));
            // A correction much larger than the step is a jump, not the motion.
            found = conv && move <= ORI_MULTIFOLD_MAX_CORRECTION * h * xmax;
        }
        ok = ok && found;
        if (ok) memcpy(cur, out, sizeof(double) * (size_t)J);
    }
    if (ok) {
        memcpy(out, cur, sizeof(double) * (size_t)J);
        for (int v = 0; v < nsys; ++v) vel[v] = x[v];
    }
    ori__free(b);
    ori__free(jx);
    ori__free(x);
    ori__free(sg);
    ori__free(nx);
    ori__free(cur);
    ori__mf_free(&s);
    return ok;
}

// Does the lock set let the drives move 0.3 rad? 2: yes, folding every crease as assigned; 1:
// yes, against the assignment somewhere; 0: no. One drive without groups is checked by the
// ordinary fold (ori_motion_solve: its second-order analysis leaves a flat start reliably),
// otherwise by the several-drive solver.
static int verify(const ori_mechanism *m, const double *angles, const int *drives, int count, const double *to,
                  const int *locks, int nlocks, const int *edge_group)
{
    ori_error e;
    if (count == 1 && !edge_group) {
        ori_motion_def d = ori_default_motion_def();
        d.start_angles_rad = angles;
        d.driven_edge = drives[0];
        d.to_rad = to[0];
        d.step_rad = ORI_LOCKSET_VERIFY_STEP_RAD;
        d.locked_edges = locks;
        d.locked_count = nlocks;
        ori_motion *mo = NULL;
        if (ori_motion_solve(m, &d, &mo, &e) != ORI_OK) return 0;
        ori_motion_verdict v = ori_motion_verdict_of(mo);
        int score = v == ORI_MOTION_VALID ? 2 : v == ORI_MOTION_INVALID_ASSIGNMENT && ori_motion_frame_count(mo) > 1 ? 1 : 0;
        ori_motion_destroy(mo);
        return score;
    }
    ori_drives_fold_def d = ori_default_drives_fold_def();
    d.start_angles_rad = angles;
    d.driven_edges = drives;
    d.to_rad = to;
    d.driven_count = count;
    d.locked_edges = locks;
    d.locked_count = nlocks;
    d.edge_group = edge_group;
    ori_multifold *mf = NULL;
    if (ori_drives_fold_solve(m, &d, &mf, &e) != ORI_OK) return 0;
    int score = 0;
    // A motion against the assignment reached the drives all the same: the set works (score 1).
    if (ori_multifold_verdict_of(mf) == ORI_MULTIFOLD_INVALID_ASSIGNMENT && mf->motion_verdict == ORI_MULTIFOLD_REACHED) {
        score = 1;
    } else if (ori_multifold_verdict_of(mf) == ORI_MULTIFOLD_REACHED) {
        score = 2;
        for (int f = 0; f < ori_multifold_frame_count(mf) && score == 2; ++f) {
            const double *a = ori_multifold_frame_angles(mf, f);
            for (int x = 0; x < m->edge_count; ++x) {
                int sg = m->edges[x].assignment == ORI_ASSIGN_VALLEY ? 1 : m->edges[x].assignment == ORI_ASSIGN_MOUNTAIN ? -1 : 0;
                if (sg && a[x] * sg < 0.0 && fabs(a[x]) > ORI_TOL_FOLD_SIGN_RAD) score = 1;
            }
        }
    }
    ori_multifold_destroy(mf);
    return score;
}

static int lock_set(const ori_mechanism *m, const double *angles, const int *drive_edges, int drive_count,
                    const int *locked_edges, int locked_count, const int *edge_group, int *out, int cap, int method,
                    ori_progress_fn *progress, void *user, ori_error *error);

int ori_mechanism_lock_set(const ori_mechanism *m, const double *angles, const int *drive_edges, int drive_count,
                           const int *locked_edges, int locked_count, const int *edge_group, int *out, int cap,
                           ori_error *error)
{
    return lock_set(m, angles, drive_edges, drive_count, locked_edges, locked_count, edge_group, out, cap, 0, NULL, NULL,
                    error);
}

int ori_mechanism_lock_set_progress(const ori_mechanism *m, const double *angles, const int *drive_edges,
                                    int drive_count, const int *locked_edges, int locked_count, const int *edge_group,
                                    int *out, int cap, ori_progress_fn *progress, void *progress_user, ori_error *error)
{
    return lock_set(m, angles, drive_edges, drive_count, locked_edges, locked_count, edge_group, out, cap, 0, progress,
                    progress_user, error);
}

int ori__mechanism_lock_set_method(const ori_mechanism *m, const double *angles, const int *drive_edges,
                                   int drive_count, const int *locked_edges, int locked_count, const int *edge_group,
                                   int *out, int cap, int method, ori_error *error)
{
    return lock_set(m, angles, drive_edges, drive_count, locked_edges, locked_count, edge_group, out, cap, method, NULL,
                    NULL, error);
}

static int lock_set(const ori_mechanism *m, const double *angles, const int *drive_edges, int drive_count,
                    const int *locked_edges, int locked_count, const int *edge_group, int *out, int cap, int method,
                    ori_progress_fn *progress, void *user, ori_error *error)
{
    ORI_ASSERT(m && (drive_edges || drive_count == 0) && (out || cap == 0));
    int J = m->joint_count, R = m->rows;
    int *joint_var = ori__alloc(sizeof(int) * (size_t)(J + 1));
    int nvar = ori__mf_variables(m, locked_edges, locked_count, edge_group, joint_var, error);
    if (nvar < 0) {
        ori__free(joint_var);
        return -1;
    }
    // Dense QR of the Jacobian's columns up to ORI_LOCKSET_DENSE_MAX_ENTRIES, else the sparse
    // null-space basis (lockset_sparse.c).
    bool sparse = method == 2 || (method == 0 && (double)R * (double)nvar > ORI_LOCKSET_DENSE_MAX_ENTRIES);
    bool too_free = false; // the sparse path's null space is too large for a dense basis
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
    double *a = sparse ? NULL : ori__alloc(sizeof(double) * ((size_t)R * (size_t)(nvar + 2) + 1));
    double *wts = ori__alloc(sizeof(double) * (size_t)(nvar + 1));
    int *jpvt = ori__alloc(sizeof(int) * (size_t)(nvar + 1));
    int n = -1;
    int *cand = ori__alloc(sizeof(int) * (size_t)(nvar + 1));
    int *all_locks = ori__alloc(sizeof(int) * (size_t)(locked_count + nvar + 1));
    double *to = ori__alloc(sizeof(double) * (size_t)(drive_count + 1));
    bool probed = false;
    // Strategies (tried until one verifies): the probe 0.1 or 0.3 rad from the start, columns
    // weighted by the creases' speed or unweighted.
    int best = 0;
    bool cancelled = false;
    for (int strategy = 0; strategy < 4 && best < 2 && !cancelled; ++strategy) {
        double total = strategy < 2 ? ORI_LOCKSET_PROBE_RAD : ORI_LOCKSET_VERIFY_RAD;
        for (int v = 0; v < nvar; ++v) lock[v] = false;
        for (int round = 0; round < LOCKSET_ROUNDS; ++round) {
            // Progress: the (strategy, round) pairs, at most 4 × LOCKSET_ROUNDS of them.
            if (progress && !progress((strategy * LOCKSET_ROUNDS + round) / (4.0 * LOCKSET_ROUNDS), user)) {
                cancelled = true;
                break;
            }
            int nsys = 0;
            for (int v = 0; v < nvar; ++v) sys_of_var[v] = is_drive[v] || lock[v] ? -1 : nsys++;
            for (int j = 0; j < J; ++j) sys_var[j] = joint_var[j] >= 0 ? sys_of_var[joint_var[j]] : -1;
            if (!drive_probe(m, sys_var, nsys, rate, th, total, th2, vel)) break;
            probed = true;
            double vmax = 0.0;
            for (int k = 0; k < nsys; ++k) vmax = fmax(vmax, fabs(vel[k]));
            int ncand = 0;
            for (int v = 0; v < nvar; ++v)
                if (sys_of_var[v] >= 0) var_of_col[ncand++] = v;
            for (int c = 0; c < ncand; ++c)
                wts[c] = strategy % 2 == 0 ? fabs(vel[sys_of_var[var_of_col[c]]]) + ORI_LOCKSET_SPEED_FLOOR * vmax : 1.0;
            if (sparse) {
                // The null space of the free columns: lock d creases that leave none of it.
                mf_system fs;
                ori__mf_init(&fs, m, sys_var, nsys);
                int d = ori__mf_linearize(&fs, th2) ? ori__mf_freedom(&fs, wts, jpvt) : -1;
                ori__mf_free(&fs);
                too_free = too_free || d == -2;
                if (d < 0) break;
                if (d > 0) {
                    for (int k = 0; k < d; ++k) lock[var_of_col[jpvt[k]]] = true;
                    continue;
                }
            } else {
                for (int j = 0; j < J; ++j) col_of_joint[j] = joint_var[j] >= 0 ? sys_of_var[joint_var[j]] : -1;
                ori__mf_dense_jacobian(m, th2, col_of_joint, ncand, a);
                for (int c = 0; c < ncand; ++c)
                    for (int r = 0; r < R; ++r) a[(size_t)c * (size_t)R + (size_t)r] *= wts[c];
                int rc = qr_rank(a, R, ncand, jpvt);
                if (rc < 0) break;
                if (rc < ncand) { // lock the columns the basis leaves out, and probe again
                    for (int k = rc; k < ncand; ++k) lock[var_of_col[jpvt[k] - 1]] = true;
                    continue;
                }
            }
            // No freedom left beside the drives: verify by folding the drives by 0.3 rad.
            int nc = 0;
            for (int v = 0; v < nvar; ++v)
                if (lock[v])
                    for (int j = 0; j < J; ++j)
                        if (joint_var[j] == v) {
                            cand[nc++] = m->joints[j].edge;
                            break;
                        }
            for (int i = 0; i < locked_count; ++i) all_locks[i] = locked_edges[i];
            for (int i = 0; i < nc; ++i) all_locks[locked_count + i] = cand[i];
            for (int i = 0; i < drive_count; ++i) {
                int j = m->edge_joint[drive_edges[i]];
                to[i] = fmax(-ORI_PI, fmin(ORI_PI, th[j] + ORI_LOCKSET_VERIFY_RAD * rate[j]));
            }
            int score = verify(m, angles, drive_edges, drive_count, to, all_locks, locked_count + nc, edge_group);
            if (score > best) {
                best = score;
                n = nc < cap ? nc : cap;
                for (int i = 0; i < n; ++i) out[i] = cand[i];
                for (int i = 1; i < n; ++i) // ascending edge order
                    for (int k = i; k > 0 && out[k - 1] > out[k]; --k) {
                        int t = out[k];
                        out[k] = out[k - 1];
                        out[k - 1] = t;
                    }
            }
            break;
        }
    }
    if (cancelled) {
        n = -1;
        ori__fail(error, ORI_ERR_LIMIT, "cancelled");
    } else if (progress && !progress(1.0, user)) {
        n = -1;
        ori__fail(error, ORI_ERR_LIMIT, "cancelled");
    } else if (n < 0 && too_free)
        ori__fail(error, ORI_ERR_UNSUPPORTED,
                  "the fold leaves too much freedom for a lock set (a null-space basis above %.0e entries): lock "
                  "creases by hand",
                  (double)ORI_LOCKSET_SPARSE_MAX_BASIS);
    else if (n < 0)
        ori__fail(error, ORI_ERR_ARGUMENT,
                  probed ? "no lock set found that keeps the motion (each candidate left the drives stuck or free): "
                           "lock creases by hand"
                         : "no rigid motion moves the driven creases from this state: no lock set helps");
    ori__free(cand);
    ori__free(all_locks);
    ori__free(to);
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
    ori__free(wts);
    ori__free(jpvt);
    return n;
}
