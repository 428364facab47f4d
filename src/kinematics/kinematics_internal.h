// Kinematics internals. Layers, each calling only those below it:
//   motion.c (fold orchestration), dof.c (ori_mechanism_dof), fit.c, pose.c
//   probe.c (generic-DOF probe: follows the free mechanism off a singular state)
//   cone.c (branch analysis at singular states), solver.c (corrector), spherical.c (closed-form 4R)
//   rank.c (dense SVD rank, sparse nullity)
//   jacobian.c (loop-closure Jacobian assembly, dense or sparse)
//   mechanism.c (model, poses, loop evaluation), sparse.c (CHOLMOD least squares)
#ifndef ORI_KINEMATICS_INTERNAL_H
#define ORI_KINEMATICS_INTERNAL_H

#include <orikin/kinematics.h>
#include <orikin/tolerance.h>

#include "../core/core_internal.h"

// One crossing of a loop: the motion of the next face relative to the previous one is
// exp(ξ θ_joint) with ξ the twist of the unit axis through point (flat frame).
typedef struct kin_entry {
    int joint;
    int col;        // index of the joint in the loop's column list (a joint may recur in a hole loop)
    int sign;       // +1 when axis is the joint's omega, -1 when it is the opposite direction
    ori_v3 axis;    // unit direction (vertex loops: the crease direction out of the vertex)
    ori_v3 point;   // a point on the axis
} kin_entry;

typedef struct kin_loop {
    int vertex;       // interior vertex, or ORI_NULL_INDEX for a hole loop
    int first, count; // entries[first .. first+count)
    int col_first, col_count; // loop_cols[col_first ..): distinct joints of the loop
    int rows;         // 3 (rotation) or 6 (translation then rotation)
    int row0;         // first row in the stacked residual
} kin_loop;

struct ori_mechanism {
    int vertex_count, edge_count, face_count;
    ori_v3 *vertices;
    ori_edge *edges;
    int *edge_faces;   // 2 per edge: left, right of v[0]→v[1]
    int *face_offsets; // face_count + 1
    int *face_verts;
    int *vert_offsets; // vertex_count + 1
    int *vert_edges;   // CCW
    int *vert_faces;   // face after each edge (left of the outward direction), parallel to vert_edges
    double diagonal;

    int joint_count;
    ori_joint *joints;
    int *edge_joint;    // edge → joint or ORI_NULL_INDEX
    int *adj_offsets;   // face → (joint, neighbour) list, face_count + 1
    int *adj_joint;
    int *adj_face;

    int loop_count, vertex_loop_count;
    kin_loop *loops;
    int entry_count;
    kin_entry *entries;
    int *entry_face;    // face reached after crossing each entry (F(i)); F0 = entry_face of the loop's last entry
    int *loop_cols;     // distinct joints per loop
    int loop_col_total;
    int rows;           // total residual rows

    int grubler;
    int bone_count;
    ori_bone *bones;
};

// Joint-space helpers. Angles inside the solvers are per joint; the API speaks per edge.
void ori__kin_edges_to_joints(const ori_mechanism *m, const double *edge_angles, double *joint_angles);
void ori__kin_joints_to_edges(const ori_mechanism *m, const double *joint_angles, double *edge_angles);

// Rotation vector of a rotation matrix (log map), robust near 0 and π, never NaN.
ori_v3 ori__kin_rotvec(ori_m3 r);

// Evaluate every loop at joint angles th: the stacked residual res (m->rows entries: rotation
// vector for vertex loops; translation/diagonal then rotation vector for hole loops) and, when
// cols is not NULL, the Jacobian block of each loop column (loop_col_total blocks of 6 values:
// 3 rotation rows for vertex loops, or 6 rows; accumulated over recurring joints). Returns the
// residual max-norm of P − I (translations divided by the diagonal).
// half (optional, 2 × joint_count doubles) is scratch for the joints' half-angle cosines and
// sines: each is then computed once instead of once per loop.
double ori__kin_eval(const ori_mechanism *m, const double *th, double *res, double *cols, double *half);

// Residual only (max-norm of P − I), joint angles.
double ori__kin_residual(const ori_mechanism *m, const double *th);
// One vertex loop L (3 rows) at the joint angles th, as ori__kin_eval evaluates it: rot (3
// values) receives the rotation vector of P, axes (L->count, may be NULL) the spatial axis of each
// crossing (the Jacobian's columns). Returns max |P − I| (NaN when not finite).
double ori__kin_vertex_loop_eval(const ori_mechanism *m, const kin_loop *L, const double *th, double rot[3], ori_v3 *axes);

// Second-order term of every loop along direction v (joint space): for each loop, the vector
// ½ Σ_{i<j} v_i v_j [ξ_i, ξ_j] with spatial twists at state th (rows like res).
void ori__kin_second_order(const ori_mechanism *m, const double *th, const double *v, double *out);

// Face poses for joint angles (spanning tree from fixed_face).
void ori__kin_face_poses(const ori_mechanism *m, const double *th, int fixed_face, ori_rigid fixed_pose,
                         ori_rigid *poses);

// Breadth-first order of faces from root with parent face/joint; order has face_count entries.
void ori__kin_bfs(const ori_mechanism *m, int root, int *order, int *parent_face, int *parent_joint);

// --- Jacobian assembly (jacobian.c) ------------------------------------------------------

// The loop-closure Jacobian at joint state th restricted to the columns col_of_joint ≥ 0, dense
// column-major (m->rows × ncols, zeros outside the loops' blocks); caller frees (ori__free).
double *ori__kin_jacobian_dense(const ori_mechanism *m, const int *col_of_joint, int ncols, const double *th);

// --- dense / sparse rank (rank.c) --------------------------------------------------------

// Numerical rank of a dense column-major rows × cols matrix (destroyed) by SVD; fills
// sigma_max and the smallest singular value kept (sigma_cut). Returns -1 on LAPACK failure.
int ori__dense_rank(double *a, int rows, int cols, double rel_tol, double *sigma_max, double *sigma_cut);

// Nullity of the Jacobian restricted to the columns with col_of_joint ≥ 0 at joint state th.
// Dense SVD or sparse inverse iteration; fills *out (rank, dof, sigma, dense).
ori_status ori__kin_nullity(const ori_mechanism *m, const double *th, const int *col_of_joint, int ncols,
                            ori_dof_result *out, ori_error *error);
// The sparse method whatever the size (tests compare it with the dense SVD).
ori_status ori__kin_nullity_sparse(const ori_mechanism *m, const double *th, const int *col_of_joint, int ncols,
                                   ori_dof_result *out, ori_error *error);

// --- sparse least squares (sparse.c, CHOLMOD) -------------------------------------------

// Normal equations of a fixed sparsity pattern, given as Jᵀ: n unknowns × m equations in
// compressed columns (colptr m + 1 entries, sorted row indices).
typedef struct kin_sls kin_sls;
kin_sls *ori__sls_create(int n, int m, const int *colptr, const int *rowind);
// A symmetric matrix (upper triangle, n × n, compressed columns, sorted rows) instead: then
// ori__sls_values are its entries, ori__sls_factor factors it + λI and the products are unused.
kin_sls *ori__sls_create_sym(int n, const int *colptr, const int *rowind);
void ori__sls_destroy(kin_sls *s);
double *ori__sls_values(kin_sls *s);           // the nnz values of Jᵀ to fill
void ori__sls_clear_values(kin_sls *s);
bool ori__sls_factor(kin_sls *s, double lambda); // JᵀJ + λI; false when not positive definite
bool ori__sls_solve(kin_sls *s, const double *rhs, double *out); // (JᵀJ + λI) out = rhs
// k right-hand sides at once (n × k, column-major; out may alias rhs): one pass over the factor
// instead of k. False (out untouched) when not factored or a solution is not finite.
bool ori__sls_solve_many(kin_sls *s, int k, const double *rhs, double *out);
void ori__sls_mult_t(const kin_sls *s, const double *y, double *out); // out = Jᵀ y (n)
void ori__sls_mult(const kin_sls *s, const double *v, double *out);   // out = J v (m)
double ori__sls_rcond(kin_sls *s);              // CHOLMOD's min(diag L)/max(diag L) estimate
int ori__sls_factorizations(const kin_sls *s);
size_t ori__sls_factor_nnz(const kin_sls *s);

// (jacobian.c) The loop-closure Jacobian restricted to the columns col_of_joint ≥ 0, at th, as a
// sparse least-squares object in Jᵀ form (for products J x, Jᵀ y and factorizations of JᵀJ + λI).
kin_sls *ori__kin_jacobian_sls(const ori_mechanism *m, const int *col_of_joint, int ncols, const double *th);
// The same, also handing over the compressed Jᵀ it was made from (colptr m->rows + 1 entries,
// rowind and vals colptr[m->rows]); the caller frees the three arrays (ori__free).
kin_sls *ori__kin_jacobian_sls_parts(const ori_mechanism *m, const int *col_of_joint, int ncols, const double *th,
                                     int **colptr, int **rowind, double **vals);

// --- numeric continuation -------------------------------------------------------------

// Which joints move: col_of_joint[j] = free column (≥ 0), KIN_FIXED or KIN_DRIVE.
enum { KIN_FIXED = -1, KIN_DRIVE = -2 };

typedef struct kin_solver kin_solver;

// Sparse corrector: a chord step (old factor) whose residual ratio exceeds this renews the
// factor (Newton) for the next iteration.
#define ORI_KIN_CHORD_RATE 0.2
// The corrector gives up when a Newton iteration multiplies the residual by more than
// ORI_KIN_GROWTH_STEP, or the residual exceeds ORI_KIN_GROWTH_TOTAL × its starting value.
#define ORI_KIN_GROWTH_STEP 4.0
#define ORI_KIN_GROWTH_TOTAL 1e2
// When an old factor failed, the corrector factors afresh at each call, retrying an old one
// every this many calls.
#define ORI_KIN_STALE_RETRY 8
// After the sweep corrector failed (a singular block, or a step that did not reduce the
// residual), the sparse corrector is used for this many calls before the sweep is tried again.
#define ORI_KIN_SWEEP_RETRY 8
// A sweep iteration must multiply the residual by at most this, else least squares takes over.
#define ORI_KIN_SWEEP_RATE 0.5

typedef struct kin_solver_opts {
    ori_linear linear;
    bool min_norm;  // allow rank-deficient corrections (underdetermined probes)
} kin_solver_opts;

kin_solver *ori__kin_solver_create(const ori_mechanism *m, const int *col_of_joint, int ncols, int drive_joint,
                                   const kin_solver_opts *opts);
void ori__kin_solver_destroy(kin_solver *s);
// Newton/Gauss–Newton corrector with the drive held: th is updated in place. Returns true
// when the residual max-norm reaches ORI_TOL_RESIDUAL (iterating on towards ORI_TOL_NEWTON).
// *iterations receives the corrector iterations; *residual the final max-norm of P − I.
bool ori__kin_correct(kin_solver *s, double *th, int max_iter, int *iterations, double *residual);
// Of the last call's iterations, those taken after the residual reached ORI_TOL_NEWTON (the
// dense polish towards ORI_TOL_NEWTON_STATE_RAD): no measure of the prediction's quality.
int ori__kin_solver_polish_iterations(const kin_solver *s);
// Tangent dθ/d(drive) of the constrained curve at th (joint space, drive component 1). False
// when the linear solve fails.
bool ori__kin_tangent(kin_solver *s, const double *th, double *t);
// Relative defect max|J t| / max|J_drive| of a tangent t at th: 0 for a true tangent, large
// when the drive cannot move at first order (the least-squares "tangent" is no tangent).
double ori__kin_tangent_defect(kin_solver *s, const double *th, const double *t);
// Statistics of the solver.
int ori__kin_solver_factorizations(const kin_solver *s);
bool ori__kin_solver_sparse(const kin_solver *s);
// The sweep ordering exists (and is used first by the corrector and the tangent).
bool ori__kin_solver_sweep(const kin_solver *s);
int ori__kin_solver_sweep_iterations(const kin_solver *s);
// Smallest singular value / rank test of the constrained Jacobian (free columns) at th:
// returns the nullity (dense: SVD; sparse: 0 or 1 from the factorization's condition).
int ori__kin_solver_nullity(kin_solver *s, const double *th);


// Where a motion stops: the drive is bisected at most this many times, and so is the event of
// the stop located on the branch in its fastest crease (tolerances: ORI_TOL_KIN_STOP_* in
// tolerance.h). (A crease folded flat onto its neighbour is often also a turning point of the
// drive, where a state at a drive value is known only to about √ of the drive's resolution.)
#define ORI_KIN_STOP_BISECTIONS 200
// Creases whose component in the null vector at a singular stop is at least this fraction of
// the largest are named as the singular set (the Jacobian is decomposed densely up to
// ORI_KIN_SINGULAR_SET_MAX_COLS free creases).
#define ORI_KIN_SINGULAR_SET_REL 0.1
#define ORI_KIN_SINGULAR_SET_MAX_COLS 500

// Output frames reserved up front at most (more grow the arrays by doubling).
#define ORI_KIN_RESERVE_FRAMES 4096

// Rayleigh–Ritz blocks of the sparse nullity up to this size use Jacobi rotations, larger ones
// LAPACK's dsyev.
#define ORI_KIN_JACOBI_MAX 32

// Inverse iterations at most for the smallest singular value of a full-rank sparse Jacobian
// (the sparse nullity's full-rank shortcut); they stop once it changes by under 0.1 %.
#define ORI_KIN_INVERSE_ITERATIONS 30

// Successive probe steps of the generic DOF (each from the state the previous one reached).
#define ORI_KIN_PROBE_ROUNDS 4

// --- cone analysis at singular starts --------------------------------------------------

// Line choices enumerated at most over this many branching loops (2^n combinations).
#define ORI_KIN_CONE_ENUMERATE_MAX 12

typedef enum kin_cone_result {
    KIN_CONE_REGULAR = 0,  // the start is not singular: use the ordinary tangent
    KIN_CONE_FOUND,        // a tangent direction respecting the assignment was found
    KIN_CONE_VIOLATING,    // tangents exist but each folds some crease against its assignment
    KIN_CONE_NONE,         // no tangent moves the drive: not rigidly foldable from here
    KIN_CONE_INCOMPATIBLE, // each vertex can fold as assigned, but not all of them together
    KIN_CONE_UNDERDETERMINED, // tangents form a family of dimension > 1 (more DOF than the drive)
    KIN_CONE_EXHAUSTED,    // the solve budget ran out before a tangent was found (nothing proved)
} kin_cone_result;

// True when some loop's equations restricted to the moving creases (free and driven) are rank
// deficient at th: first order cannot satisfy them all (a flat vertex, most hole loops).
bool ori__kin_loops_deficient(const ori_mechanism *m, const double *th, const int *col_of_joint, int drive_joint);

// Tangent cone of the constrained system at a singular start th (joint space): a direction v
// with v[drive] = sign, fixed joints 0, satisfying the first-order and the second-order loop
// conditions. enumerate_limit bounds the branch combinations tried. *extra_dof receives the
// excess dimension when UNDERDETERMINED.
kin_cone_result ori__kin_cone(const ori_mechanism *m, const double *th, const int *col_of_joint, int ncols,
                              int drive_joint, double sign, bool probe, double *v, int *extra_dof);
// The same with a budget: each line combination tried costs one from *budget (NULL: no limit);
// KIN_CONE_EXHAUSTED when it reaches 0 before a tangent was found.
kin_cone_result ori__kin_cone_budget(const ori_mechanism *m, const double *th, const int *col_of_joint, int ncols,
                                     int drive_joint, double sign, bool probe, double *v, int *extra_dof,
                                     long *budget);

// --- generic-DOF probe (probe.c) --------------------------------------------------------

// Follow the free mechanism (drive any crease a little along a second-order tangent, minimum-
// norm corrections) from a singular state to a nearby regular one; th_out receives it. False
// when no motion is found (the state is rigid).
typedef enum kin_probe_result {
    KIN_PROBE_MOVED = 0, // th_out is a state reached along a motion
    KIN_PROBE_RIGID,     // every crease tried, both ways: no motion (the state is rigid)
    KIN_PROBE_EXHAUSTED, // the budget ran out first: undetermined
} kin_probe_result;
// budget: cone line combinations the probe may still try (decremented; NULL: no limit).
kin_probe_result ori__kin_probe_generic(const ori_mechanism *m, const double *th, const int *col_of_joint, int ncols,
                                        double *th_out, long *budget);

// Cone line combinations one ori_mechanism_dof call may try in its generic probe by default:
// the enumeration is exponential in the branching loops (2^ORI_KIN_CONE_ENUMERATE_MAX per
// crease and sign), so the probe stops there and answers "undetermined".
#define ORI_KIN_PROBE_BUDGET 256

// --- closed-form single vertex -----------------------------------------------------------

typedef struct kin_spherical {
    int loop;          // the vertex loop
    int drive_entry;   // entry index (within the loop) of the driven joint
    int free_entry[3]; // entries of the three free joints, in loop order after the drive
} kin_spherical;

// True when the motion is a spherical 4R: one loop holds the drive and exactly three free
// joints, and no other joint is free. Fills *sp.
bool ori__kin_spherical_applicable(const ori_mechanism *m, const int *col_of_joint, int drive_joint,
                                   kin_spherical *sp);

// Newton iterations polishing each closed-form candidate on the loop equation itself.
#define ORI_KIN_SPHERICAL_POLISH_MAX 4

// All (≤ 2) closed-form solutions for the drive value: cand[k][0..2] = angles of the three free
// joints, label[k] (may be NULL) their branch label: +1 or −1, the sign of ±acos in the
// input–output equation's x2 = ψ ± acos(C/r), continuous along a branch between singular points;
// 0 at a double root. pred supplies values where the closed form is indeterminate (degenerate
// axes). Returns the number of solutions.
int ori__kin_spherical_solve(const ori_mechanism *m, const kin_spherical *sp, const double *th,
                             double drive, const double pred[3], double cand[2][3], int label[2]);
// The same; *reachable (may be NULL) tells whether the input–output equation has roots at the
// drive value (false beyond a limit of the drive), so that no solution with *reachable means
// that the polish closed none of them.
int ori__kin_spherical_solve_ex(const ori_mechanism *m, const kin_spherical *sp, const double *th, double drive,
                                const double pred[3], double cand[2][3], int label[2], bool *reachable);
// Newton polish (minimum-norm steps) of the three free angles x at the drive value on the loop
// equation; returns the final max-norm of P − I.
double ori__kin_spherical_polish(const ori_mechanism *m, const kin_spherical *sp, const double *th, double drive,
                                 double x[3]);

#endif
