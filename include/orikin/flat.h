/// orikin flat: local flat-foldability of crease-pattern vertices (thesis ch. 4.3) — Kawasaki,
/// Maekawa, the generalised big-little-big rule, Hull's count C(α1…α2n) of valid mountain-valley
/// assignments, their enumeration, an exact test of a given assignment (crimp reduction), the
/// valid completions of unassigned (U) creases, and a whole-pattern check with a report.
///
/// Functions: ori_flat_kawasaki_sum, ori_flat_kawasaki, ori_flat_maekawa,
/// ori_flat_big_little_big, ori_flat_count_assignments, ori_flat_enumerate,
/// ori_flat_assignment_valid, ori_flat_count_completions, ori_flat_enumerate_completions,
/// ori_flat_rule_name, ori_flat_vertex_creases, ori_flat_check_vertex, ori_flat_snap_sectors,
/// ori_default_flat_check_def, ori_flat_check_pattern, ori_flat_report_destroy,
/// ori_flat_report_flat_foldable, ori_flat_report_interior_count, ori_flat_report_failed_count,
/// ori_flat_report_within_count, ori_flat_report_max_deviation,
/// ori_flat_report_vertex_count, ori_flat_report_vertex, ori_flat_report_vertex_creases,
/// ori_flat_report_violation_count, ori_flat_report_violation.
///
/// Single-vertex conventions: a vertex of degree n has creases 0…n−1 in counter-clockwise
/// cyclic order and sectors 0…n−1, sector i running from crease i to crease i+1 (crease 0
/// follows sector n−1). Angles are radians, each sector ≥ 0. Assignments are M or V (U where
/// stated); an assignment string holds one FOLD letter per crease, crease 0 first.
/// Equal-angle decisions use ORI_TOL_ANGLE_EQUAL_RAD, Kawasaki ORI_TOL_KAWASAKI_RAD, the
/// flat-sheet (not cone) test ORI_TOL_ANGLE_SUM_RAD. Counts are exact unsigned 64-bit integers;
/// a count that does not fit is reported with overflow = true, never wrapped.
#ifndef ORIKIN_FLAT_H
#define ORIKIN_FLAT_H

#include "base.h"
#include "pattern.h"

#ifdef __cplusplus
extern "C" {
#endif

/// An exact count. When overflow is true the true value exceeds UINT64_MAX and count is
/// UINT64_MAX.
typedef struct ori_mv_count {
    uint64_t count; ///< the exact count (UINT64_MAX when overflow)
    bool overflow;  ///< the true count does not fit in 64 bits
} ori_mv_count;

/// Alternating sector sum α0 − α1 + α2 − … (radians); 0 for a Kawasaki vertex.
ORI_API double ori_flat_kawasaki_sum(const double *sectors_rad, int n);
/// Kawasaki's theorem: n even and |alternating sum| ≤ ORI_TOL_KAWASAKI_RAD. True for n = 0.
ORI_API bool ori_flat_kawasaki(const double *sectors_rad, int n);
/// Maekawa's theorem over M/V creases: #M − #V = ±2 (true for n = 0: no fold). Every crease
/// must be M or V.
ORI_API bool ori_flat_maekawa(const ori_assignment *creases, int n);
/// Generalised big-little-big rule: for every maximal run of k+1 equal sectors strictly smaller
/// than both neighbouring sectors, its k+2 bounding creases have #M = #V (k even) or
/// |#M − #V| = 1 (k odd); a run containing U creases passes when some completion of them
/// would. Returns ORI_NULL_INDEX when the rule holds, else the first crease of the first
/// violating run (its creases are that one and the next *run_creases − 1, cyclically).
/// run_creases may be NULL.
ORI_API int ori_flat_big_little_big(const double *sectors_rad, const ori_assignment *creases,
                                    int n, int *run_creases);

/// C(α0…αn−1): the number of M/V assignments that fold the vertex flat (Hull's recursion,
/// thesis Theorems 3 and 4). 0 when Kawasaki fails (odd n included); 1 for n = 0. Valid for
/// cones too (sector sum ≠ 2π).
ORI_API ori_mv_count ori_flat_count_assignments(const double *sectors_rad, int n);
/// Enumerate the valid assignments into out, max_assignments rows of n + 1 chars each (n
/// letters M/V and a NUL). Returns the number of rows written; *truncated (may be NULL) is
/// true when more exist. Rows are in lexicographic order (M before V) when not truncated.
ORI_API int ori_flat_enumerate(const double *sectors_rad, int n, char *out, int max_assignments,
                               bool *truncated);
/// Exact local flat-foldability of one M/V assignment: Kawasaki holds and crimp reduction
/// (repeatedly folding a locally smallest sector between opposite creases) ends in two equal
/// sectors between two creases of the same letter. Every crease must be M or V.
ORI_API bool ori_flat_assignment_valid(const double *sectors_rad, const ori_assignment *creases,
                                       int n);
/// Number of ways to assign M/V to the U creases of creases (M and V ones kept) so that the
/// vertex folds flat. Without U creases: 1 when the assignment is valid, else 0.
ORI_API ori_mv_count ori_flat_count_completions(const double *sectors_rad,
                                                const ori_assignment *creases, int n);
/// Enumerate those completions as full assignment rows (as ori_flat_enumerate). Returns the
/// number written; *truncated (may be NULL) is true when more exist.
ORI_API int ori_flat_enumerate_completions(const double *sectors_rad, const ori_assignment *creases,
                                           int n, char *out, int max_assignments, bool *truncated);

/// A local flat-foldability rule a vertex can break.
typedef enum ori_flat_rule {
    ORI_FLAT_RULE_KAWASAKI = 0,   ///< alternating sector sum ≠ 0, or odd degree
    ORI_FLAT_RULE_MAEKAWA,        ///< #M − #V ≠ ±2
    ORI_FLAT_RULE_BIG_LITTLE_BIG, ///< a locally smallest run of sectors has wrong bounding creases
    ORI_FLAT_RULE_ASSIGNMENT,     ///< the exact test fails (no completion folds flat)
    ORI_FLAT_RULE_CONE,           ///< sectors do not sum to 2π: not a flat sheet there
    ORI_FLAT_RULE_COUNT
} ori_flat_rule;

/// Name of a rule as used in reports: "kawasaki", "maekawa", "big_little_big", "assignment",
/// "cone"; static string.
ORI_API const char *ori_flat_rule_name(ori_flat_rule rule);

/// A yes/no answer that may be undetermined (Maekawa with U creases present).
typedef enum ori_flat_truth {
    ORI_FLAT_NO = 0,           ///< the rule fails
    ORI_FLAT_YES = 1,          ///< the rule holds
    ORI_FLAT_UNDETERMINED = 2, ///< cannot be decided yet (unassigned creases)
} ori_flat_truth;

/// The local flat-foldability of one vertex.
typedef struct ori_vertex_report {
    int vertex;              ///< FOLD vertex index
    int degree;              ///< creases considered: M, V, U (F and J edges are dropped)
    int mountains, valleys, unassigned; ///< crease counts by assignment
    double sector_sum_rad;   ///< sum of the sectors (2π on a flat sheet)
    double kawasaki_rad;     ///< alternating sector sum (computed for odd degree too)
    bool cone;               ///< |sector sum − 2π| > ORI_TOL_ANGLE_SUM_RAD
    bool kawasaki;           ///< ori_flat_kawasaki
    ori_flat_truth maekawa;  ///< undetermined when U creases are present
    bool big_little_big;     ///< ori_flat_big_little_big holds
    int blb_crease;          ///< first crease (position in the cyclic list) of the violating run, or −1
    int blb_run_creases;     ///< number of creases of that run (0 when none)
    ori_mv_count mv_count;   ///< Hull's C of the sectors (0 when Kawasaki fails)
    bool assignment_valid;   ///< exact test; with U creases: some completion is valid
    ori_mv_count completions; ///< valid completions of the U creases (1/0 without U creases)
    bool flat_foldable;      ///< locally flat-foldable: not a cone and assignment_valid (possibly
                             ///< only within the check's tolerance, see within_tolerance)
    bool within_tolerance;   ///< fails the exact test but passes once its sectors are moved by at
                             ///< most the check's tolerance (ori_flat_snap_sectors); the rule
                             ///< fields then describe the snapped sectors
    double deviation_rad;    ///< largest sector change that snapping needed (0 when exact)
} ori_vertex_report;

/// The creases of a vertex as verification sees them: edges in counter-clockwise order with F
/// and J edges dropped, and sectors_rad[i] = paper angle from crease i to crease i+1 (merged
/// across dropped edges; from 3D face corners for folded forms). Either output may be NULL;
/// at most cap entries are written. Returns the number of creases. Needs a built pattern.
ORI_API int ori_flat_vertex_creases(const ori_pattern *pattern, int vertex, int *edges,
                                    double *sectors_rad, int cap);
/// Check one vertex (meant for interior vertices, ori_pattern_vertex_is_interior) into *out,
/// exactly (tolerance 0).
ORI_API void ori_flat_check_vertex(const ori_pattern *pattern, int vertex, ori_vertex_report *out);

/// The exact vertex a rounded drawing most likely meant: sectors within tolerance_rad of each
/// other (chained in sorted order) become equal, and Kawasaki (alternating sum 0) and the flat
/// sum 2π hold exactly, with the least squared change (closed form: two Lagrange multipliers
/// over the equality classes). Writes n sectors to out (may alias sectors_rad) and returns the
/// largest change (radians); returns +inf when no such vertex exists (odd n, or the classes
/// make the two conditions contradictory).
ORI_API double ori_flat_snap_sectors(const double *sectors_rad, int n, double tolerance_rad, double *out);

/// One broken rule at one vertex. detail is a readable sentence (angles in degrees, crease
/// edges by FOLD index).
typedef struct ori_flat_violation {
    int vertex;       ///< FOLD vertex index
    ori_flat_rule rule;
    int edge;         ///< FOLD edge index the rule points at (first crease of a run), or −1
    double value;     ///< rule-specific: alternating sum or sector-sum error (rad), #M − #V
    char detail[160];
} ori_flat_violation;

/// Pattern-check parameters; get them from ori_default_flat_check_def().
typedef struct ori_flat_check_def {
    bool record_vertices; ///< keep a report (and crease list) per interior vertex
    double tolerance_rad; ///< ≥ 0: a vertex that fails only because its sectors miss Kawasaki,
                          ///< the 2π sum or an equality by at most this is "within tolerance"
                          ///< (flat-foldable, with its deviation); 0 = exact (rounding only)
    int internal_value;   ///< set by ori_default_flat_check_def; do not change
} ori_flat_check_def;

/// Defaults: per-vertex reports recorded, exact check (tolerance 0).
ORI_API ori_flat_check_def ori_default_flat_check_def(void);

/// Opaque result of a pattern check.
typedef struct ori_flat_report ori_flat_report;

/// Check every interior vertex of a built pattern (ascending vertex index). Never fails;
/// destroy the report with ori_flat_report_destroy. def may be NULL (defaults).
ORI_API ori_flat_report *ori_flat_check_pattern(const ori_pattern *pattern,
                                                const ori_flat_check_def *def);
/// Destroy a report; NULL is a no-op.
ORI_API void ori_flat_report_destroy(ori_flat_report *report);
/// True when every interior vertex is locally flat-foldable with its assignment.
ORI_API bool ori_flat_report_flat_foldable(const ori_flat_report *report);
/// Number of interior vertices checked.
ORI_API int ori_flat_report_interior_count(const ori_flat_report *report);
/// Number of interior vertices that are not locally flat-foldable.
ORI_API int ori_flat_report_failed_count(const ori_flat_report *report);
/// Number of interior vertices that pass only within the check's tolerance.
ORI_API int ori_flat_report_within_count(const ori_flat_report *report);
/// Largest deviation (radians) of the vertices that pass within tolerance (0 when none).
ORI_API double ori_flat_report_max_deviation(const ori_flat_report *report);
/// Number of recorded vertex reports (the interior count, or 0 without record_vertices).
ORI_API int ori_flat_report_vertex_count(const ori_flat_report *report);
/// Recorded vertex report i (0 ≤ i < ori_flat_report_vertex_count) by value.
ORI_API ori_vertex_report ori_flat_report_vertex(const ori_flat_report *report, int i);
/// Creases (edge indices) and sectors of recorded vertex i, as ori_flat_vertex_creases.
ORI_API int ori_flat_report_vertex_creases(const ori_flat_report *report, int i, int *edges,
                                           double *sectors_rad, int cap);
/// Number of violations (a vertex may break several rules).
ORI_API int ori_flat_report_violation_count(const ori_flat_report *report);
/// Violation i by value, in ascending vertex order, rules in ori_flat_rule order.
ORI_API ori_flat_violation ori_flat_report_violation(const ori_flat_report *report, int i);

#ifdef __cplusplus
}
#endif

#endif
