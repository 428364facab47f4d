// Internals shared by the folding modes for patterns with several degrees of freedom:
// targets.c (fold toward target angles, and the engine below), drives.c (several drives),
// lockset.c (rank-revealing lock sets) and symmetry.c (symmetry orbits).
//
// The engine works on variables: each free revolute joint belongs to one variable (joints of
// one symmetry orbit share it), the others are fixed (locked, flat-locked, rigid, or driven
// and set by the caller). The loop-closure Jacobian restricted to the variables, J (rows ×
// variables, a variable's column the sum of its joints' columns), is kept as a CHOLMOD object
// that factors J Jᵀ + λI, the normal matrix of minimum-norm solves: x = Jᵀ (J Jᵀ + λI)⁻¹ b.
#ifndef ORI_MULTIFOLD_INTERNAL_H
#define ORI_MULTIFOLD_INTERNAL_H

#include "kinematics_internal.h"

// A fold toward the targets that stops part of the way (fraction < 1) locates the stop on the
// step that crosses it: the progress 1 − D/D₀ there equals the fraction within this (relative to
// D₀), by at most this many bisections of the step.
#define ORI_TOL_MULTIFOLD_PROGRESS 1e-13
#define ORI_MULTIFOLD_STOP_BISECTIONS 80
// A stop short of the fraction by more than ORI_TOL_MULTIFOLD_LAND × D₀ (the bisection found no
// closer state on the corrected chord) retakes the step shorter, down to
// ORI_MULTIFOLD_LAND_MIN_STEP_RAD, below which the closest state found is the stop. Unitless; radians.
#define ORI_TOL_MULTIFOLD_LAND 1e-11
#define ORI_MULTIFOLD_LAND_MIN_STEP_RAD 1e-8

typedef struct mf_system {
    const ori_mechanism *m;
    const int *var_of_joint; // joint_count entries: variable ≥ 0, or < 0 (fixed)
    int nvar;
    int ngroups;     // (variable, loop) pairs
    int *group_pos;  // first value of each group in the CSC values
    int *group_loop; // its loop
    int *group_lc0;  // lc_list[group_lc0[g] .. group_lc0[g + 1]): the loop columns summed
    int *lc_list;
    kin_sls *sls;
    double *res;   // rows
    double *cols;  // 6 × loop_col_total
    double *half;  // 2 × joint_count
    double *y;     // rows scratch
    double *x;     // nvar scratch
    double worst;  // residual of the last evaluation
    bool factored; // the CHOLMOD factor holds a linearization (the chord corrector may reuse it)
    int newton_iterations;
} mf_system;

// Build the sparse structure for the given variable map (var_of_joint is kept, not copied).
void ori__mf_init(mf_system *s, const ori_mechanism *m, const int *var_of_joint, int nvar);
void ori__mf_free(mf_system *s);
// Evaluate residual and Jacobian at joint angles th and factor J Jᵀ + λI. Returns false when
// the factorization fails.
bool ori__mf_linearize(mf_system *s, const double *th);
// After ori__mf_linearize: minimum-norm x (nvar) with J x = b (rows).
bool ori__mf_minnorm(mf_system *s, const double *b, double *x);
// After ori__mf_linearize: out (rows) = J v for a variable vector v.
void ori__mf_jv(const mf_system *s, const double *v, double *out);
// After ori__mf_linearize: out (rows) = Σ over joints of the full Jacobian column × rate[joint]
// (rate per joint; used for driven joints that are not variables).
void ori__mf_joint_rate(const mf_system *s, const double *rate, double *out);
// Newton (minimum-norm) corrector on the variables, fixed joints held: th updated in place.
// Starts from the last factor when there is one (chord iterations), and refactors when an
// iteration contracts the residual by less than ORI_KIN_CHORD_RATE.
// True when the residual reaches ORI_TOL_RESIDUAL; *residual the final max-norm of P − I.
bool ori__mf_correct(mf_system *s, double *th, int *iterations, double *residual);
// Joint angles from variables (free joints) over th.
void ori__mf_apply(const mf_system *s, const double *phi, double *th);
// Number of residual rows.
static inline int ori__mf_rows(const mf_system *s) { return s->m->rows; }

// The result object shared by targets.c and drives.c.
struct ori_multifold {
    const ori_mechanism *m;
    int edge_count;
    int fixed_face;
    ori_rigid fixed_pose;
    ori_multifold_verdict verdict;
    char reason[1024];
    int stop_edge;
    int extra_dof;
    int nframes, cap;
    double *angles; // nframes × (edge_count + 1)
    double *residual;
    double *progress;
    double *goal;   // edge_count + 1
    int steps, rejected, newton;
    int pinned; // creases held at ±180° (their own target) while the others went on
    ori_v3 *vertices; // every frame's vertex positions, computed by the first ori_multifold_vertices
    int noff;         // creases folded against their assignment (ori__mf_check_assignment)
    ori_multifold_verdict motion_verdict; // how the motion itself ended (verdict before that check)
    int *off_edge;
    double *off_angle, *off_progress;
    // The assignment watch over the solver's accepted states (ori__mf_watch), whatever the output
    // spacing: the start's edge angles, each crease's worst angle against its assignment and the
    // progress there (edge_count + 1 each; NULL until the first watched state).
    double *watch_a0, *watch_worst, *watch_at, *watch_buf;
};

ori_multifold *ori__mf_result_create(const ori_mechanism *m, int fixed_face, ori_rigid fixed_pose);
// The verdict INVALID_ASSIGNMENT, with the creases named in the reason, when some frame folds
// an M/V crease against its assignment beyond ORI_TOL_KIN_STOP_SIGN_RAD and further than frame 0.
void ori__mf_check_assignment(ori_multifold *mo);
// Watch one accepted solver state (joint angles th, its progress) for creases against their
// assignment; the first call is the start. ori__mf_check_assignment then judges the watched
// states, not the output frames, so that the verdict does not depend on the output spacing.
void ori__mf_watch(ori_multifold *mo, const double *th, double progress);
// True when joint angles th fold an M/V crease against its assignment beyond what the check
// allows (after the start was watched): an interpolated output frame that does so is not kept.
bool ori__mf_against(ori_multifold *mo, const double *th);
// Append a frame from joint angles.
void ori__mf_record(ori_multifold *mo, const double *th, double residual, double progress);

// Variable map of a fold: revolute joints not locked get a variable (edges of one group share
// one); returns the variable count, or -1 with *error set for a bad lock or group entry.
// joint_var receives joint_count entries.
int ori__mf_variables(const ori_mechanism *m, const int *locked_edges, int locked_count, const int *edge_group,
                      int *joint_var, ori_error *error);

// Validate a fold's fixed face and start angles (edge angles, NULL = flat) and convert them to
// joint angles th; the start must close within ORI_TOL_START_RESIDUAL.
ori_status ori__mf_check_start(const ori_mechanism *m, int fixed_face, const double *start, double *th,
                               ori_error *error);
// Variable values phi from joint angles th; the joints of one variable must start at equal angles.
ori_status ori__mf_group_start(const ori_mechanism *m, const int *joint_var, int nvar, const double *th, double *phi,
                               ori_error *error);

// Close edge angles (edge_count entries, in place) onto the loop-closure manifold by minimum-norm
// Newton on the revolute creases that are not locked: ORI_OK, or ORI_ERR_NOT_CONVERGED.
ori_status ori__mf_close(const ori_mechanism *m, const int *locked_edges, int locked_count, double *edge_angles,
                         ori_error *error);

// The freedom of the variables of s at its last linearization (ori__mf_linearize first),
// without forming J densely (lockset_sparse.c): the nullity d of J, and when lock is not NULL d
// variables (into lock) whose locking leaves no freedom, chosen by column-pivoted QR of the
// null-space basis's transpose, rows scaled by 1/weight (NULL: unweighted). Returns d, -1 when a
// factorization fails, -2 when the null space is too large for a dense basis
// (ORI_LOCKSET_SPARSE_MAX_BASIS entries).
int ori__mf_freedom(mf_system *s, const double *weight, int *lock);

// ori_mechanism_lock_set with the method chosen: 0 by size (dense up to
// ORI_LOCKSET_DENSE_MAX_ENTRIES Jacobian entries, else sparse), 1 dense, 2 sparse (tests compare
// the two).
int ori__mechanism_lock_set_method(const ori_mechanism *m, const double *angles, const int *drive_edges,
                                   int drive_count, const int *locked_edges, int locked_count, const int *edge_group,
                                   int *out, int cap, int method, ori_error *error);

// Dense loop-closure Jacobian at joint angles th restricted to the columns col_of_joint ≥ 0
// (ncols columns; joints sharing a column are summed), column-major rows × ncols.
void ori__mf_dense_jacobian(const ori_mechanism *m, const double *th, const int *col_of_joint, int ncols, double *a);

#endif
