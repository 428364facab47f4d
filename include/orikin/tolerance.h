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

#endif
