/// orikin authoring: the virtual sheet, creases applied to faces like a perforation (a crease
/// line F(s) = a + s·(b − a) clipped to the target face or faces), the face tree of names
/// (Obj1 → Obj11, Obj12 → …) and edits of existing creases (assign, flip, remove, move).
///
/// Functions: ori_pattern_create_sheet, ori_pattern_apply_crease, ori_pattern_apply_creases,
/// ori_pattern_clip_crease,
/// ori_pattern_assign_crease, ori_pattern_flip_crease, ori_pattern_remove_crease,
/// ori_remove_result_map_edge, ori_pattern_move_crease, ori_pattern_face_node,
/// ori_pattern_node_child_count.
///
/// Every function here works on a flat pattern with faces, leaves it built on success and
/// unchanged on failure. Names of faces live in the pattern (ori_pattern_face_name) and are
/// saved in FOLD as orikin:faces_name / orikin:face_tree.
#ifndef ORIKIN_AUTHORING_H
#define ORIKIN_AUTHORING_H

#include "arrangement.h"
#include "base.h"
#include "math.h"
#include "pattern.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Name of the uncreased sheet's one face (and the root of the face tree).
#define ORI_SHEET_NAME "Obj1"

/// A new sheet from a simple polygon of count ≥ 3 points (clockwise input is reversed to
/// counter-clockwise, keeping the first point first): vertices = the polygon, boundary edges B
/// (edge k joins vertex k and k + 1), one face named "Obj1", the face-tree root "Obj1". Fails
/// with ORI_ERR_DEGENERATE (zero area, coincident points) or ORI_ERR_CROSSING (sides cross or
/// overlap; error.element is the side index). *out is NULL on failure.
ORI_API ori_status ori_pattern_create_sheet(const ori_v2 *polygon, int count, ori_pattern **out,
                                            ori_error *error);

/// A crease to apply: the line (or only the segment) through a and b, directed a→b. The part
/// of a split face left of a→b (cross(b − a, x − a) > 0) is named child 1 (N → N1), the right
/// part child 2 (N2).
typedef struct ori_crease {
    ori_v2 a, b;               ///< two distinct points on the crease, sheet coordinates
    bool infinite;             ///< true: the whole line through a and b; false: the segment ab only
    ori_assignment assignment; ///< M, V, F or U (B, C, J are refused)
    double fold_angle_rad;     ///< fold angle (FOLD sign: valley > 0); 0 for a flat sheet
} ori_crease;

/// What applying a crease did.
typedef struct ori_apply_result {
    int segments;       ///< pieces of the crease inside the target (one per convex face)
    int faces_split;    ///< faces split
    int vertices_added; ///< vertices appended
    int edges_added;    ///< edges appended
    int first_edge;     ///< the edge count before the call: new edges are first_edge … count − 1
} ori_apply_result;

/// Clip a crease to face `face` (or, with ORI_NULL_INDEX, to every face) without changing the
/// pattern: writes up to cap pieces as parameter intervals [t0, t1] along a→b (t = 0 at a,
/// 1 at b) into t_out (2 per piece) and returns the number of pieces (0: the crease misses).
/// Pieces shorter than the length tolerance and pieces along the face's boundary are dropped.
ORI_API int ori_pattern_clip_crease(const ori_pattern *pattern, const ori_crease *crease, int face,
                                    double *t_out, int cap);

/// Apply a crease to face `face` (ORI_NULL_INDEX: every face it crosses): the pieces inside
/// the target are inserted (ori_pattern_insert_segment), splitting and naming the faces they
/// cross. Fails with ORI_ERR_NOT_FOUND when the crease misses the target, ORI_ERR_RANGE for a
/// bad face index or non-finite input, ORI_ERR_DEGENERATE when a = b, ORI_ERR_ARGUMENT for a B,
/// C or J assignment or a pattern without faces. out may be NULL.
ORI_API ori_status ori_pattern_apply_crease(ori_pattern *pattern, const ori_crease *crease, int face,
                                            ori_apply_result *out, ori_error *error);

/// Apply count creases to the region of face `face` (ORI_NULL_INDEX: the whole sheet) as it is
/// before the call: every crease is clipped to that region first, then they are inserted in
/// order, so later creases split the parts earlier ones made (a cross on Obj1 gives Obj11,
/// Obj12, then Obj111 … Obj122). Fails like ori_pattern_apply_crease; the error of a crease
/// that misses the region names its index (error.field "creases").
ORI_API ori_status ori_pattern_apply_creases(ori_pattern *pattern, const ori_crease *creases, int count, int face,
                                             ori_apply_result *out, ori_error *error);

/// Re-assign crease `edge` to M, V, F or U. A fold angle of the wrong sign is negated (M ≤ 0,
/// V ≥ 0) and F sets it to 0. Boundary, cut and join edges are refused (ORI_ERR_ARGUMENT).
ORI_API ori_status ori_pattern_assign_crease(ori_pattern *pattern, int edge, ori_assignment a,
                                             ori_error *error);

/// Flip a mountain to a valley or back (reversing its joint axis by the right-hand rule) and
/// negate its fold angle. Other assignments are refused (ORI_ERR_ARGUMENT).
ORI_API ori_status ori_pattern_flip_crease(ori_pattern *pattern, int edge, ori_error *error);

/// What removing a crease deleted. All indices are in the numbering before the call; deleting
/// index k moves every later index down by one (see ori_remove_result_map_edge).
typedef struct ori_remove_result {
    int removed_edges[3];     ///< ascending: the crease, and edges merged into a neighbour
    int merged_into[3];       ///< per removed edge: the edge that now covers it, or ORI_NULL_INDEX
    int removed_edge_count;
    int removed_vertices[2];  ///< ascending: crease ends left with no edge or two collinear ones
    int removed_vertex_count;
    int kept_face;            ///< the merged face (ORI_NULL_INDEX when the crease had no faces)
    int removed_face;         ///< the face merged into kept_face, or ORI_NULL_INDEX
    bool name_restored;       ///< the merged face took its parent's name (children dropped from the tree)
} ori_remove_result;

/// Remove crease `edge`: the faces on its two sides merge (the lower index stays); when they
/// are the two children N1, N2 of tree node N (and leaves), the merged face is named N and the
/// two nodes are dropped, else it keeps the kept face's name. An end vertex left with no edge,
/// or with exactly two collinear edges of equal assignment and angle (a crossing the crease
/// had split), is dissolved. Refused (ORI_ERR_ARGUMENT): boundary/cut edges, edges with a face
/// on one side only, and removals that would leave a face with a hole. out may be NULL.
ORI_API ori_status ori_pattern_remove_crease(ori_pattern *pattern, int edge, ori_remove_result *out,
                                             ori_error *error);

/// Index after a removal of an element index (edge) from before it: the new index,
/// the covering edge's new index for a merged edge, ORI_NULL_INDEX for the removed crease.
ORI_API int ori_remove_result_map_edge(const ori_remove_result *r, int edge);

/// Move crease `edge` onto the segment ab: remove it (as ori_pattern_remove_crease, reported
/// in removed), then apply the segment clipped to the sheet with the crease's assignment and
/// fold angle (reported in out). Fails (pattern unchanged) like both; ORI_ERR_NOT_FOUND when
/// ab lies outside the sheet. removed and out may be NULL.
ORI_API ori_status ori_pattern_move_crease(ori_pattern *pattern, int edge, ori_v2 a, ori_v2 b,
                                           ori_remove_result *removed, ori_apply_result *out,
                                           ori_error *error);

/// Tree node of a face (the node with the face's name), or ORI_NULL_INDEX.
ORI_API int ori_pattern_face_node(const ori_pattern *pattern, int face);
/// Number of children of a tree node (0 for a leaf).
ORI_API int ori_pattern_node_child_count(const ori_pattern *pattern, int node);

#ifdef __cplusplus
}
#endif

#endif
