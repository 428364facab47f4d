/// orikin axioms: the Huzita–Hatori origami constructions 1–7 (thesis ch. 4.2), each returning
/// every solution as a bounded set of infinite fold lines.
///
/// Functions: ori_line_make, ori_line_reflect, ori_axiom_max_solutions, ori_axiom_1 …
/// ori_axiom_7, ori_axiom_solve.
///
/// Degenerate inputs (coincident points, a zero direction, parallel or coincident lines where
/// the construction needs them to meet, no real solution, infinitely many solutions) give zero
/// solutions; no output is ever NaN. Lines come out canonical (ori_line_make). Decisions are
/// relative to the input scale L (the largest coordinate magnitude of the points involved):
/// points closer than ORI_TOL_LENGTH_REL × L coincide; a discriminant below
/// ORI_TOL_CONSTRUCTION_REL × L² is zero (tangency: one solution); unit directions whose cross
/// product is below ORI_TOL_CONSTRUCTION_REL are parallel.
#ifndef ORIKIN_AXIOMS_H
#define ORIKIN_AXIOMS_H

#include "base.h"
#include "math.h"

#ifdef __cplusplus
extern "C" {
#endif

/// An infinite line: a point on it and a direction. As output: dir is a unit vector with
/// dir.x > 0, or dir = (0, 1) when vertical; point is the line's point nearest the origin.
typedef struct ori_line {
    ori_v2 point;
    ori_v2 dir;
} ori_line;

/// Every solution of a construction (at most 3), in the order documented per axiom.
typedef struct ori_line_set {
    ori_line lines[3];
    int count;
} ori_line_set;

/// The canonical line through point with direction dir (see ori_line); a zero or non-finite
/// direction gives the zero line (point and dir zero).
ORI_API ori_line ori_line_make(ori_v2 point, ori_v2 dir);
/// Mirror image of x in the line (dir need not be unit; a zero dir returns x).
ORI_API ori_v2 ori_line_reflect(ori_line line, ori_v2 x);

/// Largest number of solutions of axiom n (1: 1, 2: 1, 3: 2, 4: 1, 5: 2, 6: 3, 7: 1); 0 for
/// an n outside 1…7.
ORI_API int ori_axiom_max_solutions(int axiom);

/// Axiom 1: the fold through p1 and p2. 0 solutions when they coincide.
ORI_API ori_line_set ori_axiom_1(ori_v2 p1, ori_v2 p2);
/// Axiom 2: the fold placing p1 onto p2 (their perpendicular bisector). 0 when they coincide.
ORI_API ori_line_set ori_axiom_2(ori_v2 p1, ori_v2 p2);
/// Axiom 3: the folds placing l1 onto l2: for crossing lines both angle bisectors, first the
/// one mapping l1's direction onto l2's direction, then the other; for parallel lines the
/// midline (1 solution); 0 for coincident lines.
ORI_API ori_line_set ori_axiom_3(ori_line l1, ori_line l2);
/// Axiom 4: the fold through p1 perpendicular to l1.
ORI_API ori_line_set ori_axiom_4(ori_v2 p1, ori_line l1);
/// Axiom 5: the folds through p2 placing p1 onto l1 (0–2), ordered by where p1 lands along
/// l1's direction. When p1 lies on l1 the fold through p1 and p2 (p1 stays put) is one of them.
ORI_API ori_line_set ori_axiom_5(ori_v2 p1, ori_v2 p2, ori_line l1);
/// Axiom 6: the folds placing p1 onto l1 and p2 onto l2 (0–3): the real roots of a cubic,
/// ordered by where p1 lands along l1's direction. Folds leaving p1 in place (p1 on l1) are
/// not reported; identical constraints (infinitely many folds) give 0.
ORI_API ori_line_set ori_axiom_6(ori_v2 p1, ori_line l1, ori_v2 p2, ori_line l2);
/// Axiom 7: the fold placing p1 onto l1, perpendicular to l2. 0 when l1 ∥ l2.
ORI_API ori_line_set ori_axiom_7(ori_v2 p1, ori_line l1, ori_line l2);

/// Inputs of ori_axiom_solve; each axiom reads the fields its function takes.
typedef struct ori_axiom_input {
    int axiom; ///< 1…7
    ori_v2 p1, p2;
    ori_line l1, l2;
} ori_axiom_input;

/// Dispatch to ori_axiom_<n>; an axiom outside 1…7 gives 0 solutions.
ORI_API ori_line_set ori_axiom_solve(const ori_axiom_input *in);

#ifdef __cplusplus
}
#endif

#endif
