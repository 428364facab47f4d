/// orikin regularize: the nearest exact crease pattern to a rounded drawing. Vertices move as
/// little as possible (least squares on the coordinates, sparse Gauss–Newton with CHOLMOD) so
/// that every interior vertex satisfies Kawasaki exactly and, on request, so that the pattern
/// is rigidly foldable from the flat state: a vector of fold rates exists whose rotations close
/// at every vertex to first order (Σ ρ'_i u_i = 0, a reciprocal diagram); a degree-4 vertex
/// with a three-to-one assignment is held to the mode the assignment picks (opposite creases of
/// like sign fold equally, the odd one opposite to the one across), which makes the whole
/// motion exist (Tachi 2009; Evans et al. 2015); other vertices close to second order
/// (Σ_{i<j} ρ'_i ρ'_j u_i × u_j = 0, a zero-area reciprocal diagram: Demaine, Demaine, Huffman,
/// Hull, Koschitz, Tachi 2016). docs/verification.md explains it.
///
/// Functions: ori_default_regularize_def, ori_regularize.
#ifndef ORIKIN_REGULARIZE_H
#define ORIKIN_REGULARIZE_H

#include "base.h"
#include "flat.h"
#include "pattern.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Parameters of ori_regularize; get them from ori_default_regularize_def().
typedef struct ori_regularize_def {
    bool rigid;             ///< also require rigid foldability from the flat state (assigned
                            ///< modes at degree-4 vertices, second order elsewhere)
    bool rigid_only;        ///< rigid foldability alone, without Kawasaki (designs that fold
                            ///< rigidly but not flat: odd degrees allowed, no flat check)
    double max_move_rel;    ///< refuse (result.refused) when a vertex must move farther than this
                            ///< × the sheet's bounding-box diagonal
    int max_iterations;     ///< Gauss–Newton iterations at most per attempt (≥ 1): the budget; reaching it
                            ///< while the defect still shrinks sets result.stopped
    ori_progress_fn *progress; ///< called per Gauss–Newton iteration with the share of the defect removed
                            ///< (log scale from the input's to the tolerance, monotone), may be NULL;
                            ///< returning false cancels: ORI_ERR_LIMIT ("cancelled"), result.stopped set
    void *progress_user;    ///< passed to progress
    bool keep_partial;      ///< when stopped (budget or cancel): *out receives the best pattern found, not
                            ///< exact (result.converged false), if its moves stay within max_move_rel and
                            ///< keep the edges from crossing; false (default): nothing
    int internal_value;     ///< set by ori_default_regularize_def; do not change
} ori_regularize_def;

/// Defaults: Kawasaki only (not rigid, not rigid only), max_move_rel = ORI_REGULARIZE_MAX_MOVE_REL, 100 iterations,
/// no progress, no partial answer.
ORI_API ori_regularize_def ori_default_regularize_def(void);

/// What regularization did. Displacements are relative to the sheet's bounding-box diagonal.
typedef struct ori_regularize_result {
    bool converged;             ///< every condition holds to its tolerance
    bool refused;               ///< the nearest exact pattern is farther than max_move_rel
    int odd_vertex;             ///< an interior vertex of odd degree (no move helps), or ORI_NULL_INDEX
    int interior_vertices;      ///< interior vertices constrained
    int moved_vertices;         ///< vertices that moved at all
    int unknowns, equations;    ///< size of the least-squares problem
    int iterations;             ///< Gauss–Newton iterations done
    bool stopped;               ///< the budget ended the search: max_iterations reached while the defect still
                                ///< shrank, or progress cancelled (kawasaki_after_rad, rigid_after: the best found)
    double max_move_rel;        ///< largest vertex displacement
    int max_move_vertex;        ///< the vertex that moved most (ORI_NULL_INDEX when none moved)
    double rms_move_rel;        ///< root mean square displacement over all vertices
    double kawasaki_before_rad; ///< largest |alternating sector sum| before
    double kawasaki_after_rad;  ///< and after (≤ ORI_TOL_REGULARIZE_KAWASAKI_RAD when converged)
    double rigid_before;        ///< rigid only: largest defect of the rigid rows (closure, modes) of the
                                ///< best fold rates for the input (radians; 0 without rigid)
    double rigid_after;         ///< and after (≤ ORI_TOL_REGULARIZE_RIGID when converged)
    int mode_vertices;          ///< rigid only: degree-4 vertices held to the mode their
                                ///< assignment picks (the finite condition), not second order
    int crossing_edge;          ///< an edge that the moves made cross another (no pattern was
                                ///< built), or ORI_NULL_INDEX
    char crossing[160];         ///< what crosses, when crossing_edge is set
    int against_edge;           ///< rigid only: a crease of a degree-4 vertex whose assigned mode
                                ///< folds it against its assignment (not converged), or ORI_NULL_INDEX
    double equal_tolerance_rad; ///< the drawing's precision: angles within it are taken as equal
                                ///< (4 × its largest Kawasaki miss, see ORI_REGULARIZE_EQUAL_MAX_RAD)
    int ties;                   ///< equalities kept exactly: equal sectors at a vertex, creases of one
                                ///< straight line, parallel edges (fewer when all of them cannot hold)
    bool parallels_kept;        ///< the parallel edges are among the equalities kept
    bool sides_moved;           ///< the drawing's corners and sides had to move too (slightly, as
                                ///< every vertex) for its equalities to hold: they were off by its precision
    bool flat_foldable;         ///< the result passes the full local check (Kawasaki, Maekawa,
                                ///< big-little-big, the exact test with its assignment)
    int check_failed;           ///< vertices of the result that fail it (0 when flat_foldable)
    int check_vertex;           ///< the first of them, or ORI_NULL_INDEX
    int check_rule;             ///< its broken rule (an ori_flat_rule; ORI_FLAT_RULE_COUNT when none)
    char check_detail[160];     ///< what fails there, as the check says it
} ori_regularize_result;

/// Largest angle (radians) regularize takes as the drawing's precision: angles closer than that
/// (and than 4 × the drawing's largest Kawasaki miss) are equalities of the design, kept exactly.
#define ORI_REGULARIZE_EQUAL_MAX_RAD 1e-3

/// Regularize a built flat crease pattern: a new built pattern with the same vertices, edges,
/// assignments, fold angles, faces and names, whose vertices are moved the least (interior
/// and free vertices in the plane, boundary vertices along their straight boundary line,
/// corners fixed). Equalities the drawing holds within its precision (equal_tolerance_rad) stay
/// exact: equal sectors at a vertex, creases continuing each other straight, parallel edges
/// (tried in turn until one result passes: all, without the parallels; both again with the
/// corners and sides moving too, sides kept straight; none). Without rigid_only the
/// result must pass the full local flat-foldability check (flat_foldable; else not converged,
/// check_* say why). F and J edges are not creases (their sectors merge). Fold rates for the
/// rigid conditions start from the assignment and the targets (edges_foldAngle, else ±π).
/// *out receives the pattern only when the result is converged, not refused and the moves
/// keep the edges from crossing (else NULL: the result says why), or, with keep_partial, the
/// best found when stopped at the budget; destroy it with ori_pattern_destroy. A stopped search
/// tries no further set of equalities. Fails with ORI_ERR_ARGUMENT for a folded form or an
/// unbuilt pattern, ORI_ERR_LIMIT when progress cancels (result and, with keep_partial, *out set).
ORI_API ori_status ori_regularize(const ori_pattern *pattern, const ori_regularize_def *def,
                                  ori_pattern **out, ori_regularize_result *result, ori_error *error);

#ifdef __cplusplus
}
#endif

#endif
