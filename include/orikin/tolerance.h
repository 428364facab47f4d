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

/// Geometric constructions (axioms): a discriminant or denominator below this × the square
/// of the input scale counts as zero (parallel lines, tangency). Unitless.
#define ORI_TOL_CONSTRUCTION_REL 1e-12

/// Axiom 6: a root of the cubic is kept only when the fold it gives maps p2 to within this ×
/// the input scale of l2 (rejects roots the closed form or a dropped leading term got wrong).
/// Two roots closer than sqrt(ORI_TOL_CONSTRUCTION_REL) (in units of the input scale) are one
/// double root (tangency), since a double root is only accurate to the square root of the
/// equation's precision. Unitless.
#define ORI_TOL_CONSTRUCTION_CHECK_REL 1e-6

/// Output only: a degree value within this of an integer is written as that integer, so that
/// radian↔degree round-off (90.00000000000001) does not show in files. Degrees.
#define ORI_TOL_PRINT_DEG 1e-10

#endif
