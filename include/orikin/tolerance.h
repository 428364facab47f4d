/// orikin tolerances: every numeric threshold of the library, each defined once, with its unit
/// and what it decides. Lengths are relative to the pattern's size (bounding-box diagonal);
/// angles are absolute radians; rank decisions are relative to the largest singular value.
#ifndef ORIKIN_TOLERANCE_H
#define ORIKIN_TOLERANCE_H

/// Two points closer than this × the bounding-box diagonal are the same point (weld/snap),
/// and an edge shorter than this × the diagonal is degenerate. Unitless (relative length).
#define ORI_TOL_LENGTH_REL 1e-9

/// A point is on a line when its distance is below this × the bounding-box diagonal; used
/// where a decision on computed (not input) coordinates cannot be exact. Unitless.
#define ORI_TOL_ON_LINE_REL 1e-9

/// Coordinates |z| below this × the bounding-box diagonal count as lying in the plane z = 0
/// (a "3D" file whose z are all ~0 is a 2D crease pattern). Unitless.
#define ORI_TOL_PLANAR_REL 1e-9

/// Kawasaki: |alternating sector sum| at or below this holds. Radians. Crease patterns
/// written with 12+ significant digits stay below 1e-10; 1e-8 leaves room for 9-digit data.
#define ORI_TOL_KAWASAKI_RAD 1e-8

/// Two sector angles that differ by at most this are equal (Hull's recursion, big-little-big
/// ties) and a sector at or below it is empty. Radians.
#define ORI_TOL_ANGLE_EQUAL_RAD 1e-8

/// Sector angles at a vertex must sum to 2π within this for the vertex to be flat (not a
/// cone). Radians.
#define ORI_TOL_ANGLE_SUM_RAD 1e-8

/// Loop-closure residual every kinematic output state must meet (max norm of the rotation
/// and translation mismatch of a vertex loop). Unitless (translations relative to the
/// bounding-box diagonal).
#define ORI_TOL_RESIDUAL 1e-10

/// Newton corrector stops when the residual max-norm is below this. Unitless.
#define ORI_TOL_NEWTON 1e-13

/// Numerical rank: a singular value below this × the largest one counts as zero (true DOF
/// by SVD of the loop-closure Jacobian). Unitless.
#define ORI_TOL_RANK_REL 1e-9

/// Fold-direction decisions: a crease angle within this of zero has no direction yet
/// (it is not counted as folding against its assignment). Radians.
#define ORI_TOL_FOLD_SIGN_RAD 1e-9

/// Start states read from files (rounded fold angles) whose loops close within this are
/// projected onto the exact loop-closure manifold before solving; beyond it they are rejected.
/// Unitless (max-norm of P − I, translations relative to the diagonal).
#define ORI_TOL_START_RESIDUAL 1e-6

/// Sparse rank decisions (DOF of large patterns, singular-start test of the sparse solver): a
/// singular value below this × the largest counts as zero. Coarser than ORI_TOL_RANK_REL because
/// the sparse methods work with JᵀJ, whose condition is the square of J's. Unitless.
#define ORI_TOL_RANK_REL_SPARSE 1e-7

/// Branch analysis at singular states (second-order cone): a coefficient of a quadratic form
/// below this × its largest coefficient is zero, and the tangent equations hold when their
/// residual is below this × |v|². Unitless.
#define ORI_TOL_CONE_REL 1e-9

/// Closed-form spherical 4R: a projection of unit axes shorter than this is degenerate (the
/// angle it would define is indeterminate and the predicted value stands in). Unitless.
#define ORI_TOL_AXIS_DEGENERATE 1e-12

/// Closed-form spherical 4R: |C/√(A²+B²)| up to 1 + this is a double root (clamped to ±1),
/// beyond it the drive value is unreachable. Unitless.
#define ORI_TOL_BRANCH_MERGE 1e-9

/// A face whose vertices a rigid motion of the flat face misses by more than this × the
/// diagonal is not rigidly placed (pose of the fixed face from folded coordinates). Unitless.
#define ORI_TOL_POSE_FIT_REL 1e-6

/// Geometric constructions (axioms): a discriminant or denominator below this × the square
/// of the input scale counts as zero (parallel lines, tangency). Unitless.
#define ORI_TOL_CONSTRUCTION_REL 1e-12

/// Largest coordinate magnitude accepted anywhere (files, drawings, creases, sheets): beyond it
/// squared lengths overflow double precision. Unitless (same unit as the coordinates).
#define ORI_COORD_MAX 1e100

/// Spatial grids (crossing checks, planarisation) never get thinner than this × the diagonal
/// in x or y, so that a sheet of collinear points still has a finite cell size. Unitless.
#define ORI_GRID_MIN_EXTENT_REL 1e-6

/// Segment insertion (arrangement): at most this many rounds refine a segment's polyline after
/// snapping (vertices within the length tolerance join it, edges it passes are split there);
/// two rounds settle nearly every segment. What is still inconsistent after them is refused.
#define ORI_INSERT_MAX_ROUNDS 8

/// Axiom 6: a root of the cubic is kept only when the fold it gives maps p2 to within this ×
/// the input scale of l2 (rejects roots the closed form or a dropped leading term got wrong).
/// Two roots closer than sqrt(ORI_TOL_CONSTRUCTION_REL) (in units of the input scale) are one
/// double root (tangency), since a double root is only accurate to the square root of the
/// equation's precision. Unitless.
#define ORI_TOL_CONSTRUCTION_CHECK_REL 1e-6

/// Output only: a degree value within this of an integer is written as that integer, so that
/// radian↔degree round-off (90.00000000000001) does not show in files. Degrees.
#define ORI_TOL_PRINT_DEG 1e-10

/// Import (SVG, .opx, .cp): end points, crossings and T-junctions closer than this × the
/// drawing's bounding-box diagonal are the same point. Drawings are saved with 3–4 decimals and
/// relative path commands accumulate the rounding: the Origami Simulator examples miss by up to
/// 3e-5 of their size. 5e-5 welds that, and stays far below the feature size of a pattern a
/// thousand cells across (a vertex is about 1e-3 of the diagonal from any edge not its own).
/// Unitless (relative length); orikin convert --tolerance overrides it.
#define ORI_TOL_IMPORT_WELD_REL 5e-5

// --- continuation solver parameters (src/kinematics) -------------------------------------

/// Largest internal continuation step (radians): the predictor stays accurate and branch jumps
/// are caught. Output steps larger than this are subdivided.
#define ORI_KIN_MAX_STEP_RAD 0.1
/// First step out of a singular start (radians).
#define ORI_KIN_SINGULAR_STEP_RAD 0.0175
/// A motion from a singular start that stops before the drive has moved this far (radians)
/// counts as no motion (not rigidly foldable) rather than a blocked one.
#define ORI_KIN_ESCAPE_RAD (0.5 * ORI_KIN_SINGULAR_STEP_RAD)
/// Substep of the closed-form solver's branch tracking (radians).
#define ORI_KIN_TRACK_STEP_RAD 0.0175
/// Steps are halved down to this before the motion counts as blocked (radians).
#define ORI_KIN_MIN_STEP_RAD 1e-7
/// Corrector iteration budget per step.
#define ORI_KIN_NEWTON_MAX 25
/// Probe step for the generic DOF (radians), halved down to the minimum when the corrector fails.
#define ORI_KIN_PROBE_STEP_RAD 0.02
#define ORI_KIN_PROBE_MIN_STEP_RAD 1e-4
/// A corrected step is rejected (as a jump to another branch) when the corrector moved the
/// prediction by more than this fraction of the predicted change, plus a slack (radians) for
/// tiny steps.
#define ORI_KIN_MAX_CORRECTION 0.5
#define ORI_KIN_CORRECTION_SLACK_RAD 1e-7
/// An output value closer than this fraction of a step to the target merges into it.
#define ORI_KIN_GRID_MERGE 1e-3

/// sin φ below which the two-term series of φ/sin φ is exact in double precision (the next term,
/// 3 sin⁴φ/40, is below 1e-17); likewise for φ/sin(φ/2) = 2(1 + sin²(φ/2)/6 + …) of a loop's
/// quaternion.
#define ORI_KIN_ROTVEC_SERIES_MAX 1e-4

/// Sweep corrector: a loop's block of undetermined columns counts as singular when a diagonal
/// entry of its QR factor is below this × its largest column norm (unitless; the columns are
/// unit axes for vertex loops). The sparse least-squares corrector then takes over.
#define ORI_KIN_SWEEP_PIVOT_REL 1e-6


// --- regularization (check --tolerance, regularize) -----------------------------------------

/// A regularized vertex satisfies Kawasaki to this (|alternating sector sum|, radians).
#define ORI_TOL_REGULARIZE_KAWASAKI_RAD 1e-12

/// The rigid conditions of a regularized pattern (first- and second-order closure of the fold
/// rates, in units of the largest rate) hold to this. Unitless.
#define ORI_TOL_REGULARIZE_RIGID 1e-12

/// regularize refuses (exit 1) when a vertex would move farther than this × the sheet's
/// bounding-box diagonal: beyond it the drawing is not a rounded exact pattern but a
/// different one. Unitless (relative length); --max-move overrides it.
#define ORI_REGULARIZE_MAX_MOVE_REL 1e-3

/// Weight of the fold-rate changes against the coordinate changes in regularize --rigid's
/// least squares: small, so that the rates adapt freely and the coordinates move the least.
/// Unitless (rates in units of the largest rate, coordinates in units of the diagonal).
#define ORI_REGULARIZE_RATE_WEIGHT 1e-6

/// Tikhonov damping of regularize's normal equations, relative to their largest diagonal entry:
/// lets dependent (consistent) conditions factor; the iteration removes its small bias.
#define ORI_REGULARIZE_DAMPING_REL 1e-14

/// A boundary vertex whose two boundary edges turn by at most this is on a straight side and
/// slides along it; a larger turn is a corner, which stays. Radians (rounded drawings bend
/// straight sides by ~1e-5).
#define ORI_REGULARIZE_BOUNDARY_STRAIGHT_RAD 1e-4

/// Gauss–Newton passes over the fold rates alone (coordinates held) that measure how far the
/// input is from rigid before regularizing.
#define ORI_REGULARIZE_RATE_PASSES 20

/// regularize's Gauss–Newton iteration counts as progressing while each step divides the
/// largest defect by at least 1 / this; it stops after ORI_REGULARIZE_STALL_STEPS steps without
/// progress (inconsistent conditions), and halves a step at most ORI_REGULARIZE_BACKTRACK_MAX
/// times when it would increase the defect.
#define ORI_REGULARIZE_PROGRESS 0.5
#define ORI_REGULARIZE_STALL_STEPS 5
#define ORI_REGULARIZE_BACKTRACK_MAX 30

/// Once regularize's largest defect is below this, the last Newton steps weight coordinates and
/// rates alike and start from the current state (polish): the moves left are too small to
/// change the answer, and the disparate weights would limit the precision. Radians.
#define ORI_REGULARIZE_POLISH 1e-8

/// check: without --tolerance, failures that would all pass within this are reported as the
/// rounding of a drawing, with a hint to use --tolerance or regularize. Radians (0.01°).
#define ORI_FLAT_ROUNDING_HINT_RAD 1.7453292519943295e-4
// --- rendering and mesh export (src/render, src/io/mesh_write*) ---------------------------

/// Depth order: two faces whose depths at a point of their overlap in the image differ by less
/// than this × the scene's diagonal lie in one plane (folded flat onto each other), and are
/// ordered by stacking instead; a depth difference that changes sign by more than it over the
/// overlap means the faces cross (they are split). Unitless (relative length).
#define ORI_TOL_RENDER_DEPTH_REL 1e-9

/// Depth order: images of two triangles overlapping by less than this × the smaller one's image
/// area only touch (a shared edge, a vertex): no order is needed between them. Unitless.
#define ORI_TOL_RENDER_OVERLAP_REL 1e-9

/// BSP splitting: a point within this × the scene's diagonal of a face's plane lies on it.
/// Unitless (relative length).
#define ORI_TOL_RENDER_PLANE_REL 1e-9

/// Stacking: a crease whose two faces' normals are opposite within this angle is folded flat
/// (the faces lie on each other and the fold angle's sign says which is on top). Radians.
#define ORI_TOL_RENDER_FLAT_FOLD_RAD 1e-6

/// Thick solid: two faces joined by a crease whose normals differ by at most this angle share
/// their offset points, and belong to one slab (a flat region of the sheet). Radians.
#define ORI_TOL_MESH_NORMAL_RAD 1e-9
// --- self-collision (src/collision) -------------------------------------------------------

/// Two faces closer than this × the pattern's diagonal touch (contact, not a collision unless a
/// clearance is asked for), and two faces each within this of the other's plane are coplanar
/// layers (stacked when they overlap by a width above it). Coarser than the penetration
/// tolerance: a state solved near a singular flat fold (±180°) is only accurate to about the
/// square root of the solver's tolerance, and its layers must still read as touching.
/// Unitless (relative length).
#define ORI_TOL_CONTACT_REL 1e-6

/// Faces penetrate when they cross each other along a segment longer than this × the
/// diagonal, and a vertex within this of the other face's plane lies on it (it touches, it does
/// not cross); along a motion, a face is above or below another when it lies beyond this from
/// its plane. Small, so that the first contact of a motion is located to well below 1e-6°.
/// Unitless (relative length).
#define ORI_TOL_PENETRATION_REL 1e-9

/// A face whose vertices lie off their best plane by more than this × the diagonal is not
/// planar: bad input. Admits folded forms written with 6 significant digits (the FOLD
/// specification's square twist is off by 1.3e-7). Unitless (relative length).
#define ORI_TOL_FACE_PLANAR_REL 1e-5

/// The penetration and contact tolerances of a state are at least this × its faces' largest
/// distance from their own planes: a rounded folded form cannot resolve contact more finely
/// than its rounding, and adjacent faces must not cross at their shared vertices. Unitless.
#define ORI_COLLISION_PLANAR_SLACK 4.0

/// The first contact along a motion is located by bisection on the drive angle until the
/// bracket is this narrow: 1e-6 degree. Radians.
#define ORI_TOL_CONTACT_DRIVE_RAD (1e-6 * 3.14159265358979323846 / 180.0)

/// Two faces whose unit normals have a cross product shorter than this are parallel planes
/// (their intersection line is not computed; coplanar ones are handled as layers). Unitless.
#define ORI_COLLISION_PARALLEL_SIN 1e-14
// --- actuation and dynamics (src/mechanics) -----------------------------------------------

/// Fibres through the thickness of an elastoplastic hinge (even). The section's elastic
/// stiffness and fully plastic moment are exact; the yield transition is within about
/// 1/ORI_HINGE_LAYERS of the continuum rectangular section.
#define ORI_HINGE_LAYERS 64

/// Default bending span of a hinge across its crease when the design gives none: this many
/// hinge thicknesses. Unitless.
#define ORI_HINGE_SPAN_PER_THICKNESS 20.0

/// Gravity classification of a hinge by gravity moment / M_p: below MINOR it is negligible,
/// at or above 1 it is decisive (the hinge cannot hold its panels). Unitless.
#define ORI_ACT_GRAVITY_MINOR 0.1

/// A wire's centre may lie this far (× the pattern diagonal) outside its panel: on its
/// boundary counts as inside. Unitless.
#define ORI_ACT_WIRE_INSIDE_REL 1e-9

/// A hinge needs no moment at a frame where it turns slower than this (radians of crease per
/// radian of drive) and gravity loads it by less than this × M_p.
#define ORI_ACT_RATE_MIN 1e-9

/// Sizing tangents: the exact tangent of a state (normal equations shifted by
/// ORI_ACT_TANGENT_SHIFT × their largest diagonal entry) is used when its loop-closure residual
/// is below ORI_ACT_TANGENT_RESIDUAL (radians per radian of drive) and it makes a cosine of at
/// least ORI_ACT_TANGENT_AGREE with the finite difference of the recorded states; otherwise
/// (singular states such as the flat sheet, where it is not unique) the finite difference.
#define ORI_ACT_TANGENT_SHIFT 1e-9
#define ORI_ACT_TANGENT_RESIDUAL 1e-6
#define ORI_ACT_TANGENT_AGREE 0.9

/// Field schedule: the minimum-norm point of a convex hull (Wolfe's algorithm) stops when no
/// point improves the distance by more than this × the largest point norm squared. Unitless.
#define ORI_ACT_MINNORM_TOL 1e-13

/// Optimal hinge thickness and the width range: golden-section search and bisection to this
/// relative width of the bracket. Unitless.
#define ORI_ACT_THICKNESS_TOL 1e-10

/// Linear systems with at most this many unknowns use dense LAPACK (Cholesky); larger ones
/// sparse CHOLMOD.
#define ORI_MECH_DENSE_MAX 64

/// Automatic time step: this many steps per shortest natural period (hinge stiffness or
/// Lorentz moment against the lightest panel's inertia).
#define ORI_DYN_STEPS_PER_PERIOD 64

/// Implicit midpoint iteration: converged when the change of the midpoint acceleration moves
/// the velocity by less than this × (its size + the velocity scale). Unitless.
#define ORI_DYN_ITER_TOL 1e-14
/// With constraints the midpoint acceleration is only as exact as the constrained solve (about
/// ORI_DYN_ALM_PENALTY × machine epsilon): an iteration that stops improving below this × the
/// velocity scale has converged. Unitless.
#define ORI_DYN_ITER_STALL 1e-8
/// … "stops improving": the change shrank by less than this factor over the last iteration.
#define ORI_DYN_ITER_STALL_RATIO 0.5
/// Iteration budget per step; a step that does not converge is halved.
#define ORI_DYN_ITER_MAX 60
/// A step whose iteration does not converge is halved at most this many times; at the smallest
/// step the iterate that changed least is taken (explicit midpoint), as at a singular start.
#define ORI_DYN_MAX_HALVINGS 3

/// Augmented Lagrangian: penalty = this × the largest diagonal entry of the mass matrix, and
/// the multiplier iteration stops when the constraint residual is below
/// ORI_DYN_ALM_TOL × (its right-hand side + 1) or after ORI_DYN_ALM_MAX iterations.
#define ORI_DYN_ALM_PENALTY 1e6
#define ORI_DYN_ALM_TOL 1e-13
#define ORI_DYN_ALM_MAX 30

/// Position projection onto the loop-closure manifold after each step: Gauss–Newton until the
/// constraint residual (rotation vectors, radians) is below this.
#define ORI_DYN_PROJECT_TOL 1e-14
#define ORI_DYN_PROJECT_MAX 20
/// Levenberg shift of that projection's normal equations, relative to their largest diagonal
/// entry: small enough that the steps are minimum-norm wherever the Jacobian's singular values
/// exceed 1e-6, large enough to keep the flat sheet's rank-deficient system solvable.
#define ORI_DYN_PROJECT_SHIFT 1e-12

/// A crease has reached its target (or a stop at ±180°) within this. Radians.
#define ORI_DYN_TARGET_RAD 1e-9

/// Settling for the latched angles: at most this many of the longest hinge periods, stopping
/// once the kinetic energy is below ORI_DYN_SETTLE_KINETIC × the largest seen.
#define ORI_DYN_SETTLE_PERIODS 40
#define ORI_DYN_SETTLE_KINETIC 1e-16

/// A simulation keeps at most this many values per history (output frames × edges): about 0.4 GB
/// for its angles, currents and plastic rotations.
#define ORI_DYN_MAX_FRAME_VALUES 2e7
/// Dynamics: a simulation takes at most ORI_DYN_MAX_STEPS integration steps (duration / time
/// step, a count) unless its def sets a lower max_steps; more is refused before it starts
/// (ORI_ERR_LIMIT, naming the least time step), and settling stops at the steps left.
#define ORI_DYN_MAX_STEPS 1e8
// --- files and imports (io) ---------------------------------------------------------------------

/// A fold angle read from a file that lies beyond ±π by at most this is read as ±π: the
/// rounding of a fully folded state written by orikin (−180.00000000286695°) or another tool.
/// Beyond it the angle is refused. Radians (files hold degrees: 5.7e-7°).
#define ORI_TOL_FILE_ANGLE_RAD 1e-8

/// The widest gap an import closes between a crease end and another line (ori_import_def
/// gap_rel is capped to it: a line drawn wider than this is no gap to hide), and how far the
/// diagnosis looks for the line a dangling crease end missed. Unitless (× the drawing's diagonal).
#define ORI_IMPORT_GAP_MAX_REL 0.01

/// Library messages show a number rounded to 6 digits (%g) only when that is within this of the
/// value relative to its size, else with more digits, so a value just outside a bound is never
/// shown as the bound. Unitless (4 ulps).
#define ORI_TOL_MESSAGE_REL 8.881784197001252e-16
// --- global layer order (src/layers) ------------------------------------------------------

/// Overlap structure of a folded state: folded points closer than this × the folded image's
/// diagonal are one point, and a point closer than this to an edge's folded segment lies on
/// it. It also bounds how far the images of one vertex through different faces may disagree
/// (otherwise the sheet does not fold consistently). When a caller loosens it (orikin layers
/// --tolerance), the local Kawasaki check accepts the same number in radians instead of
/// ORI_TOL_KAWASAKI_RAD. Unitless (relative length).
#define ORI_TOL_LAYERS_SNAP_REL 1e-8

/// Distances between ORI_TOL_LAYERS_SNAP_REL and this many times it are ambiguous: the
/// coordinates do not say whether the two features meet, so the overlap structure is refused
/// (naming the element) instead of guessed. Unitless factor.
#define ORI_LAYERS_AMBIGUITY_FACTOR 10.0

/// A given faces_flatFoldTransform row is an isometry when its 2 × 2 part has orthonormal
/// columns within this (files may hold them rounded to 6 or more digits). Unitless.
#define ORI_TOL_LAYERS_TRANSFORM 1e-6

// --- folding with several degrees of freedom (src/kinematics/targets.c, drives.c, lockset.c, symmetry.c)

/// A fold toward targets has reached its goal when every moving crease is within this of it;
/// it is stationary when the projected change (what the rigid motion can still do toward the
/// goal) is below this. Radians.
#define ORI_TOL_TARGET_RAD 1e-9
/// Largest change of any crease in one continuation step of a target or several-drive fold;
/// steps shrink by halves to ORI_MULTIFOLD_MIN_STEP_RAD before the fold is declared stopped. Radians.
#define ORI_MULTIFOLD_MAX_STEP_RAD 0.035
#define ORI_MULTIFOLD_MIN_STEP_RAD 1e-9
/// Tikhonov term λ of the minimum-norm solves with J Jᵀ + λI (CHOLMOD): rows the state makes
/// zero (the flat sheet's out-of-plane rows) or dependent get no weight. Unitless (J has unit-axis columns).
#define ORI_MULTIFOLD_LAMBDA 1e-12
/// A crease within this of ±180° when the motion stops at that limit, and whose target is ±180°,
/// is held at ±180° exactly while the other creases go on toward theirs. Radians.
#define ORI_MULTIFOLD_PIN_RAD 1e-6
/// A target fold gives up after this many continuation steps (the verdict is then stationary).
#define ORI_MULTIFOLD_MAX_STEPS 200000
/// A target fold is stationary, stopped early, when at the pace of its last
/// ORI_MULTIFOLD_STALL_STEPS accepted steps (the distance to the goal, 2-norm over the moving
/// creases, fell by ΔD while the step length did not grow) the distance D left would take more
/// than the ORI_MULTIFOLD_MAX_STEPS it may take: ΔD · (steps left) < ORI_MULTIFOLD_STALL_STEPS · D.
/// Such a fold creeps (on the flat-folder grids: 50 Newton iterations a step at 2e-5 rad).
/// Steps.
#define ORI_MULTIFOLD_STALL_STEPS 50
/// A corrector step that moves the prediction by more than this × the step (plus 1e-9 rad) is
/// rejected as a jump to another branch. Unitless.
#define ORI_MULTIFOLD_MAX_CORRECTION 2.0
/// Several drives: the minimum-norm tangent must satisfy J t = −J_drive ṙ to this relative
/// defect, else the drives cannot move together (overdetermined). Unitless.
#define ORI_TOL_DRIVES_DEFECT 1e-6
/// Several drives: the freedom left to the solved creases is judged once the drives have moved
/// by this (the first steps from the flat sheet are too near its singularity to tell). Radians.
#define ORI_DRIVES_CHECK_RAD 0.0873
/// Output frames of a target or several-drive fold lie on a grid; a grid value within this
/// (relative to the spacing) of the end or of the distance travelled merges with it. Unitless.
#define ORI_MULTIFOLD_GRID_REL 1e-9
/// Lock sets: the probe moves the drives ORI_LOCKSET_PROBE_RAD (then ORI_LOCKSET_VERIFY_RAD) in
/// substeps of at most ORI_LOCKSET_SUBSTEP_RAD, shortened down to ORI_LOCKSET_MIN_SUBSTEP_RAD;
/// a set is verified by folding the drives ORI_LOCKSET_VERIFY_RAD (output every
/// ORI_LOCKSET_VERIFY_STEP_RAD). Radians.
#define ORI_LOCKSET_PROBE_RAD 0.1
#define ORI_LOCKSET_VERIFY_RAD 0.3
#define ORI_LOCKSET_VERIFY_STEP_RAD 0.1
#define ORI_LOCKSET_SUBSTEP_RAD 0.02
#define ORI_LOCKSET_MIN_SUBSTEP_RAD 1e-5
/// Lock-set columns are weighted by their crease's speed plus this × the fastest (a crease at
/// rest still counts a little). Unitless.
#define ORI_LOCKSET_SPEED_FLOOR 1e-3
/// Rank decisions of the lock set (dgeqp3): |R_kk| ≤ this × |R_11| counts as dependent. Unitless.
#define ORI_TOL_LOCKSET_RANK_REL 1e-9
/// Symmetries of the flat sheet map vertices onto vertices within this × the diagonal. Unitless.
#define ORI_TOL_SYMMETRY_REL 1e-8
/// Along a motion, a step whose sweep leaves a pair of faces undecided (near each other, not
/// lying over each other on one side at both ends) is checked in halves down to a drive bracket
/// of this: 1e-3 degree. Radians.
#define ORI_TOL_SWEEP_SPLIT_RAD (1e-3 * 3.14159265358979323846 / 180.0)

/// Linkage unfolding (Streinu): an event is bracketed to ORI_TOL_LINKAGE_EVENT_REL × the
/// linkage's diagonal on the curve parameter (arc length) and, while the bracket allows, to
/// ORI_TOL_LINKAGE_EVENT_SINE on the sine of the aligned angle. Unitless.
#define ORI_TOL_LINKAGE_EVENT_REL 1e-12
#define ORI_TOL_LINKAGE_EVENT_SINE 1e-12
/// Linkage unfolding: bar lengths are projected back to this relative residual; Newton stalling
/// at the rounding floor is accepted below ORI_TOL_LINKAGE_NEWTON_FLOOR. Unitless.
#define ORI_TOL_LINKAGE_NEWTON 1e-14
#define ORI_TOL_LINKAGE_NEWTON_FLOOR 1e-12
/// Nets (orikin unfold): a polygon's vertices are coplanar within ORI_TOL_UNFOLD_PLANAR_REL ×
/// the shape's diagonal; neighbours whose normals differ by less than ORI_TOL_UNFOLD_MERGE_RAD
/// (radians) are one face; a penetration deeper than ORI_TOL_UNFOLD_OVERLAP_REL × the diagonal
/// is an overlap of the flat net.
#define ORI_TOL_UNFOLD_PLANAR_REL 1e-6
#define ORI_TOL_UNFOLD_MERGE_RAD 1e-9
#define ORI_TOL_UNFOLD_OVERLAP_REL 1e-9
/// Nets: a corner closer than ORI_TOL_UNFOLD_CONTACT_REL × the diagonal to another part of the
/// net's boundary (but its own vertex) is a contact: the net would touch itself, which a FOLD
/// file cannot hold (two vertices at one point), so such a tree is avoided or split into pieces.
#define ORI_TOL_UNFOLD_CONTACT_REL 1e-6
/// Nets: a net without overlap that touches itself is mended by up to
/// ORI_UNFOLD_UNTOUCH_SWAPS_PER_TRY × tries swaps of a tree edge for a cut (a count, no unit).
#define ORI_UNFOLD_UNTOUCH_SWAPS_PER_TRY 20
/// Nets (--all): lengths are compared in units of 1/ORI_UNFOLD_NET_QUANTA of the shape's
/// diagonal and turns of 1/ORI_UNFOLD_NET_QUANTA of π, so congruent nets have equal forms.
#define ORI_UNFOLD_NET_QUANTA 1e6
/// Where a motion stops (a moving crease reaching ±π, no state beyond): the drive is bisected
/// down to ORI_TOL_KIN_STOP_DRIVE_RAD; a stop that cannot be located on the branch from there
/// (ORI_TOL_KIN_STOP_AT_LIMIT_RAD below) with a moving crease within
/// ORI_TOL_KIN_STOP_LIMIT_RAD of ±π is the crease limit, any other a singular point; states found
/// by that bisection fold a crease against its assignment only beyond ORI_TOL_KIN_STOP_SIGN_RAD
/// (near a singular stop the numeric corrector leaves up to about 1e-5 rad: a crease reaching 0
/// there was at −4.5e-6 rad). Radians.
#define ORI_TOL_KIN_STOP_DRIVE_RAD 1e-13
#define ORI_TOL_KIN_STOP_LIMIT_RAD 1e-2
#define ORI_TOL_KIN_STOP_SIGN_RAD 1e-4
/// Closed-form 4R: |c| of the input–output equation within this of 1 is a double root (acos(c)
/// ≈ √(2(1 − |c|)) magnifies the rounding of A, B, C, about 1e-13 relative, to 1e-6 rad). Unitless.
#define ORI_TOL_KIN_DOUBLE_ROOT 1e-12
/// Sparse lock sets (src/kinematics/lockset_sparse.c): the null space of the loop-closure
/// Jacobian is found from ORI_LOCKSET_SPARSE_BLOCK random vectors (doubling while they are all
/// in it), each projected onto it ORI_LOCKSET_PROJECTIONS times; the dense basis (variables ×
/// vectors) is refused above ORI_LOCKSET_SPARSE_MAX_BASIS entries. Counts.
#define ORI_LOCKSET_SPARSE_BLOCK 16
#define ORI_LOCKSET_PROJECTIONS 3
#define ORI_LOCKSET_SPARSE_MAX_BASIS 5e7
/// Sparse lock sets: a projected random vector's component counts as null-space direction above
/// this fraction of the vector's norm (what the projections leave of the other directions is
/// (λ/(σ² + λ))³, far below it for σ ≥ 1e-4). Unitless.
#define ORI_TOL_LOCKSET_NULL_REL 1e-7

/// regularize --rigid: a crease of a degree-4 vertex held to its assigned mode folds against its
/// assignment when its rate has the other sign and exceeds this (units of the largest rate; a
/// smaller rate is a crease the motion leaves flat, as at a vertex of two straight lines).
#define ORI_TOL_REGULARIZE_AGAINST_RATE 1e-9

/// Linkage unfolding: a flip is decided where the aligned angle has turned this (its sine) past
/// π along the old motion, so that no new edge makes a sliver thinner than that. Unitless.
#define ORI_TOL_LINKAGE_FLIP_SINE 1e-7
/// Linkage unfolding: a motion whose kept frames change a bar length by more than this
/// (relative) or decrease a distance by more than this × the size fails. Unitless.
#define ORI_TOL_LINKAGE_CHECK_REL 1e-9
/// Linkage unfolding, choice of the drive by looking ahead: a candidate hull edge whose motion
/// meets its nearest event no sooner than this × the linkage's size is taken at once (the
/// others are not tried). Unitless.
#define ORI_TOL_LINKAGE_DRIVE_AHEAD_REL 1e-6
/// Linkage unfolding, adaptive step: the arc length along the unit tangent over which no edge
/// turns by more than ORI_LINKAGE_STEP_TURN_RAD to first order (radians), and at most
/// ORI_LINKAGE_STEP_MAX_REL × the linkage's size (unitless).
#define ORI_LINKAGE_STEP_TURN_RAD 0.1
#define ORI_LINKAGE_STEP_MAX_REL 0.05
/// Developing a folded form without cuts (ori_unfold_develop): an interior vertex is flat when
/// its face angles sum to 2π within ORI_TOL_DEVELOP_ANGLE_RAD (radians); the two laid-out copies
/// of every edge off the layout tree meet within ORI_TOL_DEVELOP_CLOSE_REL × the diagonal. Loose
/// enough for coordinates rounded to 6 digits (FOLD files of other tools: defects up to ~1e-6),
/// far above the ~1e-15 of exact inputs.
#define ORI_TOL_DEVELOP_ANGLE_RAD 1e-5
#define ORI_TOL_DEVELOP_CLOSE_REL 1e-5
/// A crease of a shape whose faces' normals are within this of opposite (radians) is flat-folded:
/// the geometry cannot tell mountain from valley, so a FOLD input's assignment (or the sign of its
/// edges_foldAngle) gives the sign of its fold angle (nets and developed crease patterns alike).
#define ORI_TOL_UNFOLD_FLAT_FOLD_RAD 1e-6

/// Through the flat state (docs/kinematics.md §7.3): a steep branch is approached from
/// ORI_KIN_SINGULAR_STEP_RAD before the crossing, halving at most this many times (to 1/1024 of
/// it, 0.001°) until it is nearly straight there. Count.
#define ORI_KIN_CROSS_HALVINGS 10
/// Walking towards the flat state no step is longer than half the remaining drive, nor need
/// be shorter than this (the last step lands on it). Radians (0.001°).
#define ORI_KIN_MIN_APPROACH_RAD (ORI_KIN_SINGULAR_STEP_RAD / 1024.0)
/// Non-moving creases all within this of flat make the flat state's neighbourhood a near-singular
/// region (the branches pass within about their largest angle λ of each other near drive 0):
/// towards and through drive 0 steps are at most max((|drive| − 2λ) / 2, λ / 8). Radians (10°).
#define ORI_KIN_NEAR_FLAT_RAD 0.1745
/// Closed form: the start of a walk has the branch label of the candidate within this of it (and
/// none when both are: at or next to a double root the nearest-to-prediction rule stands). Radians.
#define ORI_KIN_LABEL_MATCH_RAD 1e-9

/// Output grid of a fold: a grid drive within this fraction of the step past the current drive
/// counts as reached (the next output frame is the one after it). Unitless.
#define ORI_TOL_KIN_GRID_REL 1e-9

/// Leaving a singular start (docs/kinematics.md §6.3): the output states between the start and the
/// escape's first node are the cubic Hermite interpolation of the two, corrected. The node is the
/// escape's end, or (a steep branch, not yet nearly straight there) the state at half the distance,
/// halving at most this many times (to 1/16384 of ORI_KIN_SINGULAR_STEP_RAD, 1.1e-6 rad). Count.
#define ORI_KIN_ESCAPE_HALVINGS 14
/// The escape's node is "nearly straight" when the state's change over it differs from either
/// end tangent's linear prediction by at most this fraction of the change. Unitless.
#define ORI_KIN_ESCAPE_STRAIGHT_REL 0.25
/// Step control of both fold solvers along a steep branch: no moving crease turns by more than
/// ORI_KIN_MAX_TURN_RAD in one internal step (radians; ORI_KIN_MAX_STEP_RAD bounds the drive).
/// The step is capped at that turn over the last step's rate max |Δθ|/Δs, and a prediction that
/// still turns a crease further is shortened to ORI_KIN_TURN_SHRINK × the bound before it is
/// corrected (unitless; below the 0.8 at which a step merges into a near remainder, so that the
/// shortening ends). An arc-length bound in the max norm: a step across a steep turn could
/// otherwise be corrected onto another branch within half its predicted change
/// (docs/kinematics.md §6.2).
#define ORI_KIN_MAX_TURN_RAD 0.1
#define ORI_KIN_TURN_SHRINK 0.75
/// A step whose predicted rate max |Δθ|/Δs exceeds this (unitless) is checked for folding back:
/// the tangent at its end, in the walk's direction, must not point against its secant. Near a
/// turning point of the drive by a perturbed bifurcation the neighbouring branch can pass within
/// the correction a steep step allows; a step onto it reverses the tangent (fuzz_motion finding 4,
/// docs/kinematics.md §6.2). Both solvers; halved like any rejected step.
#define ORI_KIN_FOLDBACK_RATE 4.0
/// Budget of one fold motion: continuation steps (accepted and rejected, both solvers) at most. A
/// branch the drive barely moves along (a crease turning 10⁵ times as fast, near a limit the
/// drive creeps towards) is walked in steps of 1e-7 rad; past this many the motion stops
/// (ORI_BLOCK_STEP_LIMIT), its frames up to there a partial answer. A 100 × 100 Miura-ori takes
/// 100 steps; no fold of the test suite comes near it.
#define ORI_KIN_MAX_WALK_STEPS 50000

/// A fully folded start (docs/kinematics.md §6.3): a moving crease within this of ±π is at the
/// limit; the branch analysis lets it move only toward 0 (its admitted fold direction is −sign θ,
/// whatever its assignment). Radians.
#define ORI_TOL_KIN_FOLDED_RAD 1e-6

/// Through the flat state (docs/kinematics.md §7.3): the output states within s_n of drive 0 are
/// the odd cubic through the incoming branch's state at s_n (and its mirror image), where s_n is
/// the crossing's s_a halved this many times (1/256 of it: 0.0039° from 1°), not below
/// ORI_KIN_MIN_APPROACH_RAD; nearer to the flat state neither solver tells the branches apart.
/// Count.
#define ORI_KIN_CROSS_NODE_HALVINGS 8

/// A stop located on the branch (docs/kinematics.md §7.1): from the bisection's last state both
/// solvers continue the branch parametrised by its fastest crease, in steps from
/// ORI_KIN_STOP_REFINE_FIRST_RAD doubling up to ORI_KIN_STOP_REFINE_MAX_RAD, at most
/// ORI_TOL_KIN_STOP_LIMIT_RAD in all, until the drive turns back or a crease passes ±π; the event
/// is bisected there. The stop is then a crease limit when a moving crease is within
/// ORI_TOL_KIN_STOP_AT_LIMIT_RAD of ±π (the located state's accuracy, not a margin). Radians.
#define ORI_KIN_STOP_REFINE_FIRST_RAD 1e-7
#define ORI_KIN_STOP_REFINE_MAX_RAD 1e-3
#define ORI_TOL_KIN_STOP_AT_LIMIT_RAD 1e-8
/// The dense corrector (small patterns: a single vertex) goes on from a residual within
/// ORI_TOL_NEWTON until its state is this close to the closing one, |r|₂ / σ_min(J_F) (or a
/// step no longer halves the residual: the round-off floor). The residual alone left 2e-11 rad
/// (1.1e-9°) where a vertex's free creases are nearly coplanar (σ_min 2e-3); the closed form's
/// polish follows the same rule (docs/kinematics.md §5, §6.1). Radians.
#define ORI_TOL_NEWTON_STATE_RAD 1e-14


/// Out of a singular start on a branch whose tangent turns a crease faster than this many times
/// the drive (two creases within about 1e-4° of collinear: 2.3e5 at 1e-4°), the closed-form walk
/// takes the corrector's state where the input–output equation has roots but its polish closes
/// none (docs/kinematics.md §15, extremely steep branches). Unitless.
#define ORI_KIN_STEEP_START_RATE 1e4

/// Fabrication tolerance (ori_tolerance_run): two vertices of the nominal folded state closer
/// than this × the sheet's diagonal meet there (a closing seam); their distance in a perturbed
/// sample is that sample's seam gap. Unitless (relative length).
#define ORI_TOL_FAB_CONTACT_REL 1e-6

/// Colour bar labels (ori_value_map_ticks): a tick nearer zero than this × the bar's range
/// (max − min) is zero (an interior tick computed as min + k·(max − min)/4 misses it by
/// roundoff). Unitless (relative).
#define ORI_TOL_BAR_ZERO_REL 1e-9

#endif
