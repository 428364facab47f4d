/// orikin kinematics: the substituted mechanical system of a crease pattern (faces → rigid
/// bodies, creases → revolute joints), poses by product of exponentials, loop closure,
/// degrees of freedom, fold motions (analytic single-vertex inverse kinematics and numeric
/// continuation) with branch selection by the MV assignment, and transfer-function fitting.
///
/// Functions: ori_default_mechanism_def, ori_mechanism_create, ori_mechanism_destroy,
/// ori_mechanism_vertex_count, ori_mechanism_edge_count, ori_mechanism_face_count,
/// ori_mechanism_joint_count, ori_mechanism_joint, ori_mechanism_edge_joint,
/// ori_mechanism_loop_count, ori_mechanism_loop, ori_mechanism_loop_edges,
/// ori_mechanism_loop_faces, ori_mechanism_vertex_faces, ori_mechanism_grubler,
/// ori_mechanism_bone_count, ori_mechanism_bone, ori_mechanism_spanning_tree,
/// ori_mechanism_face_poses, ori_mechanism_vertex_positions, ori_mechanism_residual,
/// ori_mechanism_face_pose_from_coords, ori_mechanism_pose_state, ori_default_dof_def, ori_mechanism_dof,
/// ori_default_motion_def, ori_motion_solve, ori_motion_destroy, ori_motion_verdict_of,
/// ori_motion_verdict_name, ori_motion_reason, ori_motion_violation_count,
/// ori_motion_violation, ori_motion_frame_count, ori_motion_frame_drive,
/// ori_motion_frame_angles, ori_motion_frame_residual, ori_motion_frame_face_poses,
/// ori_motion_frame_vertices, ori_motion_angles, ori_motion_vertices, ori_motion_frame_other_branch, ori_motion_frame_end_effector, ori_motion_fixed_face,
/// ori_motion_fixed_pose, ori_motion_split, ori_motion_stats_of, ori_motion_block_of, ori_motion_dof,
/// ori_default_fit_def, ori_fit_solve, ori_fit_destroy, ori_fit_crease_count,
/// ori_fit_crease_of, ori_fit_sample_count, ori_fit_coefficients, ori_fit_eval,
/// ori_default_target_fold_def, ori_target_angles_default, ori_target_fold_solve,
/// ori_default_drives_fold_def, ori_drives_fold_solve, ori_multifold_* (result getters, ori_multifold_angles,
/// ori_multifold_vertices, ori_multifold_at),
/// ori_mechanism_lock_set, ori_mechanism_symmetries, ori_mechanism_symmetry_orbits.
///
/// Frames and signs. The reference configuration is the flat sheet in z = 0 with faces
/// counter-clockwise seen from +z. Joint angles are FOLD fold angles in radians (positive =
/// valley, negative = mountain). A joint's axis ω runs along its edge from v[0] to v[1]
/// through q = v[0]; face_left lies on the left of ω, and e^{ξθ} (ξ = (−ω×q, ω)) is the motion
/// of face_left relative to face_right: θ > 0 lifts it to +z (valley), seen from either side.
/// State vectors hold one angle per FOLD edge (edge_count entries, boundary edges ignored).
/// Face poses map flat-sheet coordinates to world coordinates.
#ifndef ORIKIN_KINEMATICS_H
#define ORIKIN_KINEMATICS_H

#include "base.h"
#include "math.h"
#include "pattern.h"

#ifdef __cplusplus
extern "C" {
#endif

// --- mechanism --------------------------------------------------------------------------

/// How a crease joins its two faces.
typedef enum ori_joint_kind {
    ORI_JOINT_REVOLUTE = 0, ///< M, V or U crease: a revolute joint (one degree of freedom)
    ORI_JOINT_FLAT,         ///< F crease: a revolute joint locked at 0
    ORI_JOINT_RIGID,        ///< J edge: the two faces are one rigid body (angle 0)
} ori_joint_kind;

/// A joint: the crease of FOLD edge `edge` between face_left and face_right (flat frame).
typedef struct ori_joint {
    int edge;                  ///< FOLD edge index
    int face_left;             ///< face on the left of omega (moves by e^{ξθ} relative to face_right)
    int face_right;            ///< face on the right of omega
    ori_v3 q;                  ///< point on the axis: the edge's vertex v[0], flat frame
    ori_v3 omega;              ///< unit axis direction from v[0] to v[1], flat frame
    ori_joint_kind kind;       ///< revolute, flat-locked or rigid
    ori_assignment assignment; ///< the edge's FOLD assignment
} ori_joint;

/// A loop-closure constraint: the faces around an interior vertex (3 rotation equations), or
/// around a hole or internal slit of the sheet (6 equations: rotation and translation).
typedef struct ori_loop {
    int vertex;     ///< interior vertex, or ORI_NULL_INDEX for a hole loop
    int crease_count; ///< number of joints crossed by the loop
    int rows;       ///< equations contributed: 3 (vertex) or 6 (hole)
} ori_loop;

/// A bone of the thesis' bone structure: the segment from a face's area centroid to the
/// midpoint of one of its joint creases (flat frame). For display.
typedef struct ori_bone {
    int face;
    int edge;
    ori_v3 from; ///< face centroid
    ori_v3 to;   ///< crease midpoint
} ori_bone;

/// Creation parameters; get them from ori_default_mechanism_def().
typedef struct ori_mechanism_def {
    const ori_pattern *pattern; ///< built flat crease pattern (z = 0); copied, not kept
    int internal_value;         ///< set by ori_default_mechanism_def; do not change
} ori_mechanism_def;

/// Defaults: no pattern (set one).
ORI_API ori_mechanism_def ori_default_mechanism_def(void);

/// Opaque substituted mechanical system of a crease pattern.
typedef struct ori_mechanism ori_mechanism;

/// Build the mechanism of a built flat crease pattern: faces → bodies, creases → joints, one
/// loop per interior vertex, one 6-equation loop per hole or internal slit. Fails with
/// ORI_ERR_ARGUMENT for a 3D or folded-form pattern, ORI_ERR_TOPOLOGY (element = a face) when
/// the faces are not all connected through creases. *out is NULL on failure; destroy the
/// mechanism with ori_mechanism_destroy.
ORI_API ori_status ori_mechanism_create(const ori_mechanism_def *def, ori_mechanism **out,
                                        ori_error *error);
/// Destroy a mechanism; NULL is a no-op.
ORI_API void ori_mechanism_destroy(ori_mechanism *mechanism);

/// Kirigami: a copy (*out, destroy with ori_pattern_destroy) of a built flat pattern with its
/// cuts opened — a vertex where cuts (C, or B between two faces) divide the paper around it into
/// several fans gets one vertex per fan (the first keeps its index, the copies follow the old
/// vertices), and a cut whose two sides then differ gets a second edge for its right side (after
/// the old edges; old indices and face indices are kept). A folded state then has one position
/// per vertex on either side of a cut. *opened (may be NULL) = the vertices added; 0 and a plain
/// copy when nothing is cut. Fails with ORI_ERR_ARGUMENT for a pattern that is not built.
ORI_API ori_status ori_pattern_open_cuts(const ori_pattern *flat, ori_pattern **out, int *opened, ori_error *error);

/// Number of vertices and edges (those of the pattern).
ORI_API int ori_mechanism_vertex_count(const ori_mechanism *mechanism);
ORI_API int ori_mechanism_edge_count(const ori_mechanism *mechanism);
/// Number of faces = number of rigid bodies.
ORI_API int ori_mechanism_face_count(const ori_mechanism *mechanism);
/// Number of joints (creases with a face on each side: M, V, U, F and J edges).
ORI_API int ori_mechanism_joint_count(const ori_mechanism *mechanism);
/// A joint by value.
ORI_API ori_joint ori_mechanism_joint(const ori_mechanism *mechanism, int joint);
/// Joint of a FOLD edge, or ORI_NULL_INDEX for boundary, cut and dangling edges.
ORI_API int ori_mechanism_edge_joint(const ori_mechanism *mechanism, int edge);
/// Number of loop-closure constraints (interior vertices, then holes).
ORI_API int ori_mechanism_loop_count(const ori_mechanism *mechanism);
/// A loop by value.
ORI_API ori_loop ori_mechanism_loop(const ori_mechanism *mechanism, int loop);
/// The loop's creases (FOLD edges) in order: counter-clockwise around a vertex, starting
/// after face F0; crease i lies between faces F(i−1) and F(i). Returns the count.
ORI_API int ori_mechanism_loop_edges(const ori_mechanism *mechanism, int loop, int *out, int cap);
/// The loop's faces F0, F1, … (same count as its creases). Returns the count.
ORI_API int ori_mechanism_loop_faces(const ori_mechanism *mechanism, int loop, int *out, int cap);
/// Faces around a vertex in counter-clockwise order (the face after each edge of
/// ori_pattern_vertex_edges; ORI_NULL_INDEX outside the sheet). Returns the vertex degree.
ORI_API int ori_mechanism_vertex_faces(const ori_mechanism *mechanism, int vertex, int *out, int cap);
/// Grübler–Kutzbach mobility M = 6(n_B − 1) − Σ(6 − f_i), revolute creases f = 1, F and J
/// edges f = 0. Wrong for overconstrained mechanisms (the open corner gives −1).
ORI_API int ori_mechanism_grubler(const ori_mechanism *mechanism);
/// Number of bones (one per face and joint crease of that face).
ORI_API int ori_mechanism_bone_count(const ori_mechanism *mechanism);
/// A bone by value.
ORI_API ori_bone ori_mechanism_bone(const ori_mechanism *mechanism, int bone);
/// Breadth-first spanning tree of the face graph rooted at root_face: parent_face[f] and
/// parent_edge[f] (the crease to the parent) per face, ORI_NULL_INDEX for the root. Either
/// output may be NULL; each holds face_count entries.
ORI_API void ori_mechanism_spanning_tree(const ori_mechanism *mechanism, int root_face,
                                         int *parent_face, int *parent_edge);

/// Pose of every face for fold angles angles_rad (edge_count entries): the product of
/// exponentials along the spanning tree from fixed_face, g_f = G·e^{ξ1θ1}···e^{ξkθk}, with G =
/// fixed_pose the world pose of the fixed face. poses holds face_count entries.
ORI_API void ori_mechanism_face_poses(const ori_mechanism *mechanism, const double *angles_rad,
                                      int fixed_face, ori_rigid fixed_pose, ori_rigid *poses);
/// World position of every vertex (vertex_count entries) for fold angles angles_rad; each
/// vertex takes the pose of its face nearest to fixed_face in the spanning tree.
ORI_API void ori_mechanism_vertex_positions(const ori_mechanism *mechanism, const double *angles_rad,
                                            int fixed_face, ori_rigid fixed_pose, ori_v3 *positions);
/// Loop-closure residual of fold angles: max over loops of the max-norm of P − I, P the loop
/// product (translations of hole loops divided by the pattern diagonal). Unitless.
ORI_API double ori_mechanism_residual(const ori_mechanism *mechanism, const double *angles_rad);
/// The rigid pose mapping a face's flat vertices onto world coordinates coords (vertex_count
/// entries, e.g. the 3D vertices_coords of a folded frame): least-squares fit (Kabsch).
/// Fails with ORI_ERR_DEGENERATE when the face's vertices are not rigidly placed (the fit
/// error exceeds ORI_TOL_POSE_FIT_REL × the diagonal).
ORI_API ori_status ori_mechanism_face_pose_from_coords(const ori_mechanism *mechanism, int face,
                                                       const ori_v3 *coords, ori_rigid *out,
                                                       ori_error *error);

/// Pose a state given by fold angles (edge_count entries, radians, e.g. a FOLD frame's
/// edges_foldAngle): angles whose loops close within ORI_TOL_START_RESIDUAL are first projected
/// exactly onto the loop-closure manifold (minimum-norm Gauss–Newton; residual ≤
/// ORI_TOL_RESIDUAL), then posed by forward kinematics from fixed_face at fixed_pose. Outputs,
/// each optional (NULL): the closed angles (edge_count), world vertex positions (vertex_count)
/// and face poses (face_count). Fails with ORI_ERR_RANGE (element = edge) for an angle outside
/// [−π, π], ORI_ERR_ARGUMENT when the loops do not close, ORI_ERR_NOT_CONVERGED when the
/// projection fails.
ORI_API ori_status ori_mechanism_pose_state(const ori_mechanism *mechanism, const double *angles_rad,
                                            int fixed_face, ori_rigid fixed_pose, double *closed_angles_rad,
                                            ori_v3 *positions, ori_rigid *poses, ori_error *error);

// --- degrees of freedom -----------------------------------------------------------------

/// Parameters of a DOF analysis; get them from ori_default_dof_def().
typedef struct ori_dof_def {
    const double *angles_rad; ///< state (edge_count entries), NULL = flat
    const int *locked_edges;  ///< creases held fixed (removed from the unknowns), may be NULL
    int locked_count;
    bool probe_generic;       ///< at a singular state, also find the nullity at a nearby regular state
    int probe_budget;         ///< branch combinations the probe may try (≤ 0: 256); beyond it "undetermined"
    ori_progress_fn *progress; ///< called with the fraction done (may be NULL); returning false cancels
    void *progress_user;      ///< passed to progress
    int internal_value;       ///< set by ori_default_dof_def; do not change
} ori_dof_def;

/// Defaults: flat state, nothing locked, generic probe on with the default budget, no progress.
ORI_API ori_dof_def ori_default_dof_def(void);

/// Degrees of freedom of the mechanism at a state.
typedef struct ori_dof_result {
    int grubler;       ///< Grübler–Kutzbach count (ignores locks)
    int unknowns;      ///< revolute creases not locked (Jacobian columns)
    int equations;     ///< loop-closure equations (Jacobian rows)
    int rank;          ///< numerical rank of the loop-closure Jacobian at the state
    int dof;           ///< unknowns − rank: infinitesimal DOF at the state
    int generic_dof;   ///< DOF at a nearby regular state on the motion; −1 when not probed
    bool singular;     ///< dof > generic_dof: the state inflates the nullity (e.g. the flat state)
    bool rigid;        ///< the probe found no motion at all from this state (generic_dof = 0)
    bool undetermined; ///< the probe ran out of its budget first: generic_dof is −1, nothing proved
    int probe_solves;  ///< branch combinations the probe tried (each one least-squares solve)
    bool dense;        ///< dense SVD (true) or sparse CHOLMOD inverse iteration (false)
    double sigma_max;  ///< largest singular value of the Jacobian
    double sigma_cut;  ///< smallest singular value counted in the rank (0 when rank is 0)
    int nearby_against;        ///< M/V creases the probe's nearby motion folds against their assignment (0: it keeps
                               ///< it, or no probe): generic_dof then counts motions the assignment does not admit
    int nearby_against_edge;   ///< the one of them folded most (FOLD edge), ORI_NULL_INDEX when none
    double nearby_against_rad; ///< its angle at the nearby state (the wrong sign)
} ori_dof_result;

/// Rank and nullity of the loop-closure Jacobian (one column per unlocked revolute crease,
/// 3 rows per vertex loop, 6 per hole loop) at a state; rank tolerance ORI_TOL_RANK_REL
/// relative to the largest singular value (dense, up to ORI_DOF_DENSE_MAX_ENTRIES entries)
/// or ORI_TOL_RANK_REL_SPARSE (sparse: a full-rank certificate by Cholesky of J'J'ᵀ or JᵀJ,
/// J' without its zero rows, else inverse subspace iteration). The generic probe's work is
/// bounded by probe_budget. Fails on NaN angles or when the state does not close (residual
/// above ORI_TOL_START_RESIDUAL), ORI_ERR_LIMIT when progress cancels.
ORI_API ori_status ori_mechanism_dof(const ori_mechanism *mechanism, const ori_dof_def *def,
                                     ori_dof_result *out, ori_error *error);

/// Dense SVD is used while rows × columns ≤ this; larger Jacobians use the sparse method.
#define ORI_DOF_DENSE_MAX_ENTRIES 4000000

// --- fold motions ----------------------------------------------------------------------

/// Which solver computes a motion.
typedef enum ori_solver {
    ORI_SOLVER_AUTO = 0, ///< analytic when the motion is a single spherical 4R loop, else numeric
    ORI_SOLVER_ANALYTIC, ///< closed-form spherical 4R; ORI_ERR_UNSUPPORTED when not applicable
    ORI_SOLVER_NUMERIC,  ///< predictor–corrector continuation
} ori_solver;

/// Linear algebra of the numeric solver.
typedef enum ori_linear {
    ORI_LINEAR_AUTO = 0, ///< dense up to ORI_MOTION_DENSE_MAX_UNKNOWNS free creases, else sweep
    ORI_LINEAR_DENSE,    ///< LAPACK SVD least squares
    ORI_LINEAR_SPARSE,   ///< CHOLMOD Cholesky of JᵀJ (+λI) only
    ORI_LINEAR_SWEEP,    ///< block substitution loop by loop (docs/kinematics.md §6.1), CHOLMOD where it fails
} ori_linear;

/// The numeric solver switches to sparse linear algebra above this many free creases.
#define ORI_MOTION_DENSE_MAX_UNKNOWNS 64

/// A fold: fix a face, lock creases, drive one crease from its current angle (or from_rad) to
/// to_rad, output a state every step_rad. Get it from ori_default_motion_def().
typedef struct ori_motion_def {
    int fixed_face;                 ///< face held in place (FOLD index)
    ori_rigid fixed_pose;           ///< world pose of the fixed face (identity: where the flat sheet has it)
    const double *start_angles_rad; ///< start state, edge_count fold angles (NULL = flat); copied
    int driven_edge;                ///< the driven (twist) crease
    bool has_from;                  ///< start the output at from_rad (reached silently first)
    double from_rad;                ///< used when has_from
    double to_rad;                  ///< target angle of the driven crease, |to| ≤ π
    double step_rad;                ///< output spacing (> 0); the last step lands on to_rad
    const int *locked_edges;        ///< creases held at their start angle (copied), may be NULL
    int locked_count;
    ori_solver solver;
    ori_linear linear;
    ori_progress_fn *progress;      ///< called per output step with the fraction of the drive range done (monotone, 1 at the
                                    ///< end), may be NULL; returning false cancels: ORI_ERR_LIMIT ("cancelled"), nothing out
    void *progress_user;
    bool last_frame_only;           ///< keep only the last output frame (frame count ≤ 1; stats.frames counts them all):
                                    ///< a 1000 × 1000 sheet's 101 frames would be 1.6 GB. Default false
    int max_steps;                  ///< continuation steps at most, accepted and rejected, beyond twice the output steps
                                    ///< the range asks for (the budget; past it the motion stops with
                                    ///< ORI_BLOCK_STEP_LIMIT); default ORI_KIN_MAX_WALK_STEPS
    int internal_value;             ///< set by ori_default_motion_def; do not change
} ori_motion_def;

/// Defaults: face 0 at identity, flat start, no drive (set one), step 1°, auto solver.
ORI_API ori_motion_def ori_default_motion_def(void);

/// The answer of a fold.
typedef enum ori_motion_verdict {
    ORI_MOTION_VALID = 0,              ///< the motion exists and respects every assignment
    ORI_MOTION_INVALID_ASSIGNMENT,     ///< every motion folds some crease against its assignment
    ORI_MOTION_NOT_RIGIDLY_FOLDABLE,   ///< no rigid motion moves the driven crease from the start
    ORI_MOTION_UNDERDETERMINED,        ///< the fold leaves more than one degree of freedom
    ORI_MOTION_BLOCKED,                ///< the motion stops (limit or singularity) before the target
} ori_motion_verdict;

/// A crease folding against its assignment: the worst angle it reaches and where.
typedef struct ori_crease_violation {
    int edge;
    ori_assignment assignment;
    double angle_rad; ///< the angle of largest magnitude with the wrong sign
    double drive_rad; ///< driven-crease angle at which it occurs
} ori_crease_violation;

/// The thesis' split of a single-vertex fold (ch. 4.6, 9.4): Frame A = [driven crease, the
/// end-effector crease] (forward chain), Frame B = the inverse chain from the ground to the
/// end-effector crease, surrounding = locked creases. Frames are translations of the world
/// frame: origin A = far end of the driven crease, origin B = far end of Frame B's first crease,
/// end effector = far end of the end-effector crease. q and ω at the start state, relative to
/// the frame origin (ω oriented so that the next body of the chain lies on its left).
typedef struct ori_vertex_split {
    int vertex;
    int frame_a[2];
    int frame_b_count;
    int frame_b[16];
    int surrounding_count;
    int surrounding[16];
    int end_effector_vertex;   ///< vertex index of the end effector point
    ori_v3 origin_a, origin_b; ///< world coordinates of the frame origins
    ori_v3 d;                  ///< origin_b − origin_a
    ori_v3 q_a[2], omega_a[2]; ///< Frame A chain creases
    ori_v3 q_b[16], omega_b[16]; ///< Frame B chain creases
} ori_vertex_split;

/// Work done by the solver.
typedef struct ori_motion_stats {
    bool analytic;            ///< closed-form single-vertex solver used
    bool sparse;              ///< sparse linear algebra (sweep and/or CHOLMOD) or dense LAPACK for the numeric solver
    bool sweep;               ///< the sweep (block substitution along the loops) was available
    int steps;                ///< accepted continuation steps
    int rejected_steps;       ///< steps halved after a failed correction
    int newton_iterations;    ///< corrector iterations in total
    int factorizations;       ///< sparse numeric factorizations
    int sweep_iterations;     ///< corrector iterations done by the sweep (the rest by factorizations)
    double max_residual;      ///< largest residual over the output frames
    int frames;               ///< output frames produced (kept or not: see last_frame_only)
} ori_motion_stats;

/// What stopped a BLOCKED fold.
typedef enum ori_block_kind {
    ORI_BLOCK_NONE = 0,        ///< not blocked
    ORI_BLOCK_CREASE_LIMIT,    ///< a moving crease reached ±180° (its faces would pass through each other beyond)
    ORI_BLOCK_SINGULAR,        ///< no state beyond: a limit of the drive or a bifurcation (singular Jacobian)
    ORI_BLOCK_STEP_LIMIT,      ///< the budget: ORI_KIN_MAX_WALK_STEPS steps spent (the drive barely moves along the branch);
                               ///< the motion beyond is undetermined (a partial answer, not a verdict on it)
} ori_block_kind;

/// Where and why a fold stopped before its target (ori_motion_block).
typedef struct ori_motion_block {
    ori_block_kind kind;
    double drive_rad;        ///< driven-crease angle at the stop (the last output frame)
    int edge;                ///< CREASE_LIMIT: the crease at ±180°, else ORI_NULL_INDEX
    double edge_angle_rad;   ///< CREASE_LIMIT: its angle at the stop
    int singular_count;      ///< SINGULAR: creases that move without the drive there (the null vector), 0 when unknown
    int singular_edges[32];  ///< the first (at most 32) of them, by edge index
} ori_motion_block;

/// Opaque result of a fold.
typedef struct ori_motion ori_motion;

/// Solve a fold. Run-time errors (bad face/edge index in element, locked driven crease, angle
/// out of range, step ≤ 0, start state not closing) return a status; a solved fold returns
/// ORI_OK with a verdict (a domain answer, possibly negative). The motion refers to the
/// mechanism (poses, vertices): destroy it first. Destroy with ori_motion_destroy.
ORI_API ori_status ori_motion_solve(const ori_mechanism *mechanism, const ori_motion_def *def,
                                    ori_motion **out, ori_error *error);
/// Destroy a motion; NULL is a no-op.
ORI_API void ori_motion_destroy(ori_motion *motion);

/// The verdict of a solved fold.
ORI_API ori_motion_verdict ori_motion_verdict_of(const ori_motion *motion);
/// "valid", "invalid assignment", "not rigidly foldable", "underdetermined", "blocked".
ORI_API const char *ori_motion_verdict_name(ori_motion_verdict verdict);
/// Why the fold is not valid (one line naming creases by FOLD index), or NULL when valid.
ORI_API const char *ori_motion_reason(const ori_motion *motion);
/// Creases that fold against their assignment (invalid motions), worst first by edge index.
ORI_API int ori_motion_violation_count(const ori_motion *motion);
/// A violation by value (index < ori_motion_violation_count).
ORI_API ori_crease_violation ori_motion_violation(const ori_motion *motion, int index);

/// Output frames: the start (from) state, one per step, the last at to_rad. When the verdict is
/// BLOCKED they run up to the stop, the last frame at the stop itself (partial, see
/// ori_motion_block); 0 for NOT_RIGIDLY_FOLDABLE and UNDERDETERMINED. Every angle lies in [−π, π].
ORI_API int ori_motion_frame_count(const ori_motion *motion);
/// Driven-crease angle of a frame (radians).
ORI_API double ori_motion_frame_drive(const ori_motion *motion, int frame);
/// Fold angles of a frame (edge_count entries, radians; 0 on boundary edges). Owned by the motion.
ORI_API const double *ori_motion_frame_angles(const ori_motion *motion, int frame);
/// Loop-closure residual of a frame (ori_mechanism_residual).
ORI_API double ori_motion_frame_residual(const ori_motion *motion, int frame);
/// Face poses of a frame (face_count entries), the fixed face at the motion's fixed pose.
ORI_API void ori_motion_frame_face_poses(const ori_motion *motion, int frame, ori_rigid *poses);
/// World vertex positions of a frame (vertex_count entries).
ORI_API void ori_motion_frame_vertices(const ori_motion *motion, int frame, ori_v3 *positions);
/// Fold angles of every frame in one block owned by the motion: frame k's edge_count angles start
/// at the result + k × *frame_stride (frame_stride ≥ edge_count, may be NULL). Valid until the
/// motion is destroyed; NULL when there are no frames. For bindings that view, not copy.
ORI_API const double *ori_motion_angles(const ori_motion *motion, int *frame_stride);
/// World vertex positions of every frame in one block owned by the motion: frame_count ×
/// vertex_count entries, frame-major (frame k as ori_motion_frame_vertices gives it). Computed on
/// the first call (not safe against a concurrent first call on the same motion), then kept until
/// the motion is destroyed; NULL when there are no frames.
ORI_API const ori_v3 *ori_motion_vertices(ori_motion *motion);
/// Closed-form folds return every branch: the fold angles (edge_count entries) of the spherical
/// 4R's other solution at the frame's drive value. False when there is none (a double root,
/// the start frame, or the numeric solver).
ORI_API bool ori_motion_frame_other_branch(const ori_motion *motion, int frame, double *angles_rad);
/// End effector of a single-vertex fold in Frame A and Frame B coordinates; false when the
/// motion has no split.
ORI_API bool ori_motion_frame_end_effector(const ori_motion *motion, int frame, ori_v3 *in_a,
                                           ori_v3 *in_b);
/// The fixed face of the fold and its world pose (as given in the def).
ORI_API int ori_motion_fixed_face(const ori_motion *motion);
ORI_API ori_rigid ori_motion_fixed_pose(const ori_motion *motion);
/// The Frame A / Frame B / surrounding split of a single-vertex fold; false when there is none.
ORI_API bool ori_motion_split(const ori_motion *motion, ori_vertex_split *out);
/// Solver statistics.
ORI_API ori_motion_stats ori_motion_stats_of(const ori_motion *motion);
/// Where and why the motion stopped: true (and *out filled, may be NULL) when the fold was
/// stopped before its target (verdict BLOCKED, or an invalid fold that also stops).
ORI_API bool ori_motion_block_of(const ori_motion *motion, ori_motion_block *out);
/// DOF of the free mechanism (no locks, no drive) at the last frame (dense or sparse rank);
/// −1 when there is no frame.
ORI_API int ori_motion_dof(const ori_motion *motion);

// --- transfer functions --------------------------------------------------------------

/// Parameters of a transfer-function fit: the fold (motion.step_rad = sampling step) and the
/// polynomial degree. Get them from ori_default_fit_def().
typedef struct ori_fit_def {
    ori_motion_def motion; ///< the fold to sample (has_from/from_rad, to_rad, step_rad)
    int degree;            ///< polynomial degree, 0 … 12
    int refine;            ///< error grid: step_rad / refine (≥ 1)
    int internal_value;    ///< set by ori_default_fit_def; do not change
} ori_fit_def;

/// Defaults: degree 4 (as the thesis), refine 10.
ORI_API ori_fit_def ori_default_fit_def(void);

/// One fitted crease.
typedef struct ori_fit_crease {
    int edge;             ///< the constrained crease
    double max_error_rad; ///< max |fit − exact| on the refined grid (radians)
} ori_fit_crease;

/// Opaque set of transfer functions.
typedef struct ori_fit ori_fit;

/// Sample the fold at its step, fit every constrained crease (one whose angle changes) by a
/// polynomial in the driven angle (least squares by QR in a scaled variable, then converted
/// to monomials), and measure the error against exact solutions on the refined grid. The
/// fold must be valid: otherwise ORI_ERR_ARGUMENT with the verdict's reason in the message.
ORI_API ori_status ori_fit_solve(const ori_mechanism *mechanism, const ori_fit_def *def,
                                 ori_fit **out, ori_error *error);
/// Destroy a fit; NULL is a no-op.
ORI_API void ori_fit_destroy(ori_fit *fit);
/// Number of fitted (constrained) creases.
ORI_API int ori_fit_crease_count(const ori_fit *fit);
/// A fitted crease by value.
ORI_API ori_fit_crease ori_fit_crease_of(const ori_fit *fit, int index);
/// Samples used for the fit.
ORI_API int ori_fit_sample_count(const ori_fit *fit);
/// Monomial coefficients c0 … c_degree of crease index: θ(x) = Σ c_k x^k, x the driven angle
/// (radians in, radians out). Returns degree + 1.
ORI_API int ori_fit_coefficients(const ori_fit *fit, int index, double *out, int cap);
/// Evaluate the fitted angle (radians) of crease index at driven angle drive_rad.
ORI_API double ori_fit_eval(const ori_fit *fit, int index, double drive_rad);

// --- folding patterns with several degrees of freedom (targets, drives, lock sets, symmetry) --

/// How a fold toward targets or with several drives ended.
typedef enum ori_multifold_verdict {
    ORI_MULTIFOLD_REACHED = 0,      ///< every crease reached its goal (targets) / the drives reached theirs
    ORI_MULTIFOLD_STATIONARY,       ///< targets: the rigid motion gets no nearer to the goals (what remains is normal to every motion)
    ORI_MULTIFOLD_LIMIT,            ///< a crease reached ±180° and the motion would take it beyond (stop_edge)
    ORI_MULTIFOLD_SINGULAR,         ///< the corrector fails at every step size: a singular configuration (or no motion at all)
    ORI_MULTIFOLD_UNDERDETERMINED,  ///< drives: the free creases keep freedom the drives do not fix (lock or drive more)
    ORI_MULTIFOLD_OVERDETERMINED,   ///< drives: the drives cannot move together as prescribed (no rigid motion does it)
    ORI_MULTIFOLD_INVALID_ASSIGNMENT, ///< the motion folds creases against their M/V assignment (beyond ORI_TOL_KIN_STOP_SIGN_RAD,
                                      ///< further than at the start): an invalid fold, as for a single drive; the creases are
                                      ///< named (ori_multifold_offending), the frames kept
} ori_multifold_verdict;

/// Opaque result of ori_target_fold_solve or ori_drives_fold_solve: frames of fold angles on the
/// loop-closure manifold (residual ≤ ORI_TOL_RESIDUAL each), verdict, reason, stop crease.
typedef struct ori_multifold ori_multifold;

/// A fold toward target angles (Origami Simulator's "fold percent", rigid and exact): every
/// unlocked crease is driven from its start angle θ0 toward its target by projecting the
/// remaining change onto the null space of the loop-closure Jacobian (Δθ = (I − J⁺J) Δθ_goal,
/// Tachi 2009) and correcting back onto the manifold by Newton; the fold stops `fraction` of the
/// way along that motion, at progress 1 − D/D₀ = fraction (D = |θ − θ_target| over the moving
/// creases, D₀ at the start; monotone along the path), every frame's progress in [0, fraction].
/// Get it from ori_default_target_fold_def().
typedef struct ori_target_fold_def {
    int fixed_face;                  ///< face held in place (FOLD index)
    ori_rigid fixed_pose;            ///< world pose of the fixed face
    const double *start_angles_rad;  ///< start state, edge_count angles (NULL = flat); copied
    const double *target_angles_rad; ///< targets at 100 %, edge_count angles (NULL: ori_target_angles_default of the mechanism's pattern); copied
    double fraction;                 ///< how far along the motion toward the targets, 0 … 1 (percent / 100; progress 1 − D/D₀)
    double step_rad;                 ///< output spacing: largest crease change between frames (> 0)
    const int *locked_edges;         ///< creases held at their start angle, may be NULL
    int locked_count;
    const int *edge_group;           ///< NULL, or edge_count entries: creases with the same group ≥ 0 are kept at equal angles (e.g. symmetry orbits)
    int max_steps;                   ///< most continuation steps (≤ 0: ORI_MULTIFOLD_MAX_STEPS), the bound of the pace test too;
                                     ///< beyond: verdict STATIONARY, frames kept (a design search bounds each judgement so)
    ori_progress_fn *progress;       ///< called per accepted step with the share of the requested way done, (1 − D/D₀)/fraction
                                     ///< (monotone, 1 at the end), may be NULL; returning false cancels: ORI_ERR_LIMIT ("cancelled"), nothing out
    void *progress_user;
    int internal_value;              ///< set by ori_default_target_fold_def; do not change
} ori_target_fold_def;

/// Defaults: face 0 fixed at identity, flat start, file targets, fraction 1, step 10°, ORI_MULTIFOLD_MAX_STEPS steps.
ORI_API ori_target_fold_def ori_default_target_fold_def(void);

/// Target angles of a flat crease pattern (edge_count entries, radians): the pattern's fold angle
/// (FOLD edges_foldAngle, SVG opacity) where it is not 0, else +π for a valley, −π for a
/// mountain and 0 for other edges. Returns how many creases had a target of their own.
ORI_API int ori_target_angles_default(const ori_pattern *pattern, double *out);

/// Fold toward the targets until the goal is reached, the motion reaches a crease limit (±π) or a
/// singularity, or it gets no nearer (the verdict says which; the frames go up to the stop).
/// Fails (*out NULL) with ORI_ERR_RANGE for a bad face, crease, fraction, step or angle, and
/// ORI_ERR_ARGUMENT when the start state does not close. Destroy with ori_multifold_destroy.
ORI_API ori_status ori_target_fold_solve(const ori_mechanism *mechanism, const ori_target_fold_def *def,
                                         ori_multifold **out, ori_error *error);

/// Several creases driven together: crease driven_edges[i] moves linearly from its start angle
/// to to_rad[i] (all reach their targets at the same time); the other unlocked creases are
/// solved. Get it from ori_default_drives_fold_def().
typedef struct ori_drives_fold_def {
    int fixed_face;                 ///< face held in place
    ori_rigid fixed_pose;           ///< world pose of the fixed face
    const double *start_angles_rad; ///< start state (NULL = flat); copied
    const int *driven_edges;        ///< the driven creases
    const double *to_rad;           ///< their final angles, |to| ≤ π
    int driven_count;
    double step_rad;                ///< output spacing: largest drive change between frames (> 0)
    const int *locked_edges;        ///< creases held at their start angle, may be NULL
    int locked_count;
    const int *edge_group;          ///< as in ori_target_fold_def (a driven crease drives its group)
    ori_progress_fn *progress;      ///< called per accepted step with the fraction of the drives' way done (monotone, 1 at
                                    ///< the end), may be NULL; returning false cancels: ORI_ERR_LIMIT ("cancelled"), nothing out
    void *progress_user;
    int internal_value;             ///< set by ori_default_drives_fold_def; do not change
} ori_drives_fold_def;

/// Defaults: face 0 fixed, flat start, no drives, step 10°.
ORI_API ori_drives_fold_def ori_default_drives_fold_def(void);

/// Move the drives together (predictor along the minimum-norm tangent, Newton corrector on the
/// free creases). Verdicts: REACHED, UNDERDETERMINED (free creases left with freedom at the
/// first regular state; no frames), OVERDETERMINED (the drives cannot move together), LIMIT,
/// SINGULAR. Fails like ori_target_fold_solve, and with ORI_ERR_ARGUMENT for a driven crease
/// that is locked, driven twice or not a crease.
ORI_API ori_status ori_drives_fold_solve(const ori_mechanism *mechanism, const ori_drives_fold_def *def,
                                         ori_multifold **out, ori_error *error);

/// Destroy a result; NULL is a no-op.
ORI_API void ori_multifold_destroy(ori_multifold *fold);
/// Creases the motion folds against their M/V assignment (verdict INVALID_ASSIGNMENT): their
/// number; entry i (in edge order) gives the crease, its worst angle with the wrong sign
/// (radians) and the frame progress where it is reached (any pointer may be NULL).
ORI_API int ori_multifold_offending_count(const ori_multifold *fold);
ORI_API void ori_multifold_offending(const ori_multifold *fold, int i, int *edge, double *angle_rad, double *progress);
/// The verdict.
ORI_API ori_multifold_verdict ori_multifold_verdict_of(const ori_multifold *fold);
/// Short name of a verdict ("reached", "stationary", "limit", "singular", "underdetermined", "overdetermined").
ORI_API const char *ori_multifold_verdict_name(ori_multifold_verdict verdict);
/// One-sentence explanation of the verdict (owned by the result).
ORI_API const char *ori_multifold_reason(const ori_multifold *fold);
/// The crease that stopped the motion (LIMIT), or ORI_NULL_INDEX.
ORI_API int ori_multifold_stop_edge(const ori_multifold *fold);
/// Additional freedom when UNDERDETERMINED (0 otherwise).
ORI_API int ori_multifold_extra_dof(const ori_multifold *fold);
/// Number of frames (the start state first; 0 when UNDERDETERMINED or OVERDETERMINED at the start).
ORI_API int ori_multifold_frame_count(const ori_multifold *fold);
/// Fold angles of frame k (edge_count entries, radians; owned by the result).
ORI_API const double *ori_multifold_frame_angles(const ori_multifold *fold, int k);
/// Loop-closure residual of frame k (max-norm of P − I, ≤ ORI_TOL_RESIDUAL).
ORI_API double ori_multifold_frame_residual(const ori_multifold *fold, int k);
/// Progress of frame k, 0 at the start and 1 at the goal: for targets 1 − |θ − θ_goal| / |θ0 − θ_goal|
/// (2-norm over the moving creases), for drives the common drive parameter.
ORI_API double ori_multifold_frame_progress(const ori_multifold *fold, int k);
/// World vertex positions of frame k (vertex_count entries).
ORI_API void ori_multifold_frame_vertices(const ori_multifold *fold, int k, ori_v3 *positions);
/// Fold angles of every frame in one block owned by the result, as ori_motion_angles: frame k
/// starts at the result + k × *frame_stride (may be NULL). NULL when there are no frames.
ORI_API const double *ori_multifold_angles(const ori_multifold *fold, int *frame_stride);
/// World vertex positions of every frame in one block owned by the result (frame_count ×
/// vertex_count, frame-major), computed on the first call as ori_motion_vertices; NULL without frames.
ORI_API const ori_v3 *ori_multifold_vertices(ori_multifold *fold);
/// The state at progress (between the first and the last frame's, ori_multifold_frame_progress):
/// the two frames around it interpolated linearly in the progress and closed onto the
/// loop-closure manifold with locked_edges held (the fold's locks; may be NULL when
/// locked_count is 0), as the collision check and ori_record_at do between frames. Writes
/// angles_rad (edge_count) and, when not NULL, positions (vertex_count). Fails with ORI_ERR_RANGE
/// outside the frames' progress or without frames, ORI_ERR_NOT_CONVERGED when the state does not close.
ORI_API ori_status ori_multifold_at(const ori_multifold *fold, const int *locked_edges, int locked_count,
                                    double progress, double *angles_rad, ori_v3 *positions, ori_error *error);
/// The goal angles (edge_count entries, radians; owned): the targets themselves (the 100 % state;
/// the fraction says how far along the way to them the fold goes), or the drives' final angles
/// (other creases: their start angle).
ORI_API const double *ori_multifold_goal(const ori_multifold *fold);
/// Creases a target fold held at ±180° (their own target) when they reached it first.
ORI_API int ori_multifold_held_count(const ori_multifold *fold);
/// Corrector iterations and accepted / rejected steps over the whole fold.
ORI_API void ori_multifold_stats(const ori_multifold *fold, int *steps, int *rejected, int *newton_iterations);

/// A lock set that leaves one degree of freedom per driven crease: the drives are moved a little
/// from angles_rad (NULL = flat; toward their assignment) with the others solved, and at the state
/// reached the rank-revealing QR (LAPACK dgeqp3, column pivoting) of the loop-closure Jacobian's
/// free columns (weighted by their creases' speed) picks a basis of its column space; the other
/// creases are locked, and the probe is repeated with them until no freedom is left. Each set is
/// verified by folding the drives 0.3 rad with it; the first that folds every crease as assigned
/// is returned, else the best that moves. edge_group (NULL or edge_count entries) ties creases as
/// in ori_target_fold_def (one edge per group is named). Writes up to cap edges (ascending) to
/// out and returns the count (≥ 0), or −1 with *error set: ORI_ERR_ARGUMENT when a drive is not a
/// free crease or no set lets the drives move, ORI_ERR_UNSUPPORTED when the freedom is too large
/// for the sparse path's null-space basis (ORI_LOCKSET_SPARSE_MAX_BASIS).
ORI_API int ori_mechanism_lock_set(const ori_mechanism *mechanism, const double *angles_rad, const int *drive_edges,
                                   int drive_count, const int *locked_edges, int locked_count, const int *edge_group,
                                   int *out, int cap, ori_error *error);

/// ori_mechanism_lock_set with progress: progress (may be NULL) is called before each probe round
/// with the fraction of the rounds the search may take (monotone, 1 at the end); returning false
/// cancels: −1 with ORI_ERR_LIMIT ("cancelled").
ORI_API int ori_mechanism_lock_set_progress(const ori_mechanism *mechanism, const double *angles_rad,
                                            const int *drive_edges, int drive_count, const int *locked_edges,
                                            int locked_count, const int *edge_group, int *out, int cap,
                                            ori_progress_fn *progress, void *progress_user, ori_error *error);

/// The dense rank-revealing QR of ori_mechanism_lock_set is used up to this many Jacobian entries;
/// above, a null-space basis from CHOLMOD projections and a QR of its transpose (sparse path).
#define ORI_LOCKSET_DENSE_MAX_ENTRIES 4000000

/// A symmetry of the flat sheet: x ↦ R x + t in the plane (R a rotation or a reflection).
typedef struct ori_symmetry {
    double r[2][2];  ///< orthogonal 2 × 2 matrix
    double t[2];     ///< translation
    bool reflection; ///< det R = −1
} ori_symmetry;

/// The symmetry group of the flat pattern: the reflections and rotations of the plane (identity
/// included) that map vertices onto vertices and edges onto edges of the same assignment, within
/// ORI_TOL_SYMMETRY_REL × the pattern diagonal. Writes up to cap of them; returns the group order.
ORI_API int ori_mechanism_symmetries(const ori_mechanism *mechanism, ori_symmetry *out, int cap);

/// Orbits of the edges under the symmetry group: orbit[e] = the smallest edge index the group
/// maps e to (edge_count entries). Returns the number of orbits that hold a revolute crease.
ORI_API int ori_mechanism_symmetry_orbits(const ori_mechanism *mechanism, int *orbit);

#ifdef __cplusplus
}
#endif

#endif
