/// orikin pattern: the in-memory crease pattern (or folded form) — vertices, edges with
/// assignment and fold angle, faces as vertex cycles, derived topology (vertex → edges in
/// cyclic order, edge → faces, interior vertices, sector angles), face names and face tree.
///
/// Functions: ori_assignment_to_char, ori_assignment_from_char, ori_assignment_name,
/// ori_assignment_is_fold, ori_default_pattern_def, ori_pattern_create, ori_pattern_destroy,
/// ori_pattern_clone, ori_pattern_add_vertex, ori_pattern_add_edge, ori_pattern_add_face,
/// ori_pattern_set_vertex, ori_pattern_set_assignment, ori_pattern_set_fold_angle,
/// ori_pattern_clear_faces, ori_default_build_def, ori_pattern_build, ori_pattern_is_built,
/// ori_pattern_absent_fold_angle_count, ori_pattern_planarized_from, counts and element getters, topology queries, face names and the face tree.
///
/// Indices are FOLD indices: loading never reorders vertices, edges or faces. Mutating a
/// pattern invalidates its derived topology until the next ori_pattern_build.
#ifndef ORIKIN_PATTERN_H
#define ORIKIN_PATTERN_H

#include "base.h"
#include "math.h"

#ifdef __cplusplus
extern "C" {
#endif

/// FOLD edge assignment.
typedef enum ori_assignment {
    ORI_ASSIGN_BOUNDARY = 0, ///< B: sheet boundary
    ORI_ASSIGN_MOUNTAIN,     ///< M: mountain crease (negative fold angle)
    ORI_ASSIGN_VALLEY,       ///< V: valley crease (positive fold angle)
    ORI_ASSIGN_FLAT,         ///< F: flat crease, stays at 0
    ORI_ASSIGN_UNASSIGNED,   ///< U: crease of unknown direction
    ORI_ASSIGN_CUT,          ///< C: cut (acts as boundary on both sides)
    ORI_ASSIGN_JOIN,         ///< J: join, not a crease (faces are one)
    ORI_ASSIGN_COUNT
} ori_assignment;

/// FOLD letter of an assignment ('B', 'M', 'V', 'F', 'U', 'C', 'J').
ORI_API char ori_assignment_to_char(ori_assignment a);
/// Parse a FOLD assignment letter (either case). Returns false for any other character.
ORI_API bool ori_assignment_from_char(char c, ori_assignment *out);
/// English name ("mountain"); static string.
ORI_API const char *ori_assignment_name(ori_assignment a);
/// True for creases that may fold: M, V, U.
ORI_API bool ori_assignment_is_fold(ori_assignment a);

/// An edge: endpoints (vertex indices), assignment and fold angle in radians (FOLD sign:
/// positive valley, negative mountain, ±π folded flat).
typedef struct ori_edge {
    int v[2];
    ori_assignment assignment;
    double fold_angle_rad;
} ori_edge;

/// Longest face or tree-node name, including the terminating NUL.
#define ORI_NAME_MAX 64

/// A node of the face tree (crease history): a face named name was split by a crease into
/// children (names with one more digit). parent is a node index or ORI_NULL_INDEX for the root.
typedef struct ori_tree_node {
    char name[ORI_NAME_MAX];
    int parent;
} ori_tree_node;

/// Creation parameters; get them from ori_default_pattern_def().
typedef struct ori_pattern_def {
    int vertex_capacity; ///< initial capacity hint (≥ 0)
    int edge_capacity;   ///< initial capacity hint (≥ 0)
    int internal_value;  ///< set by ori_default_pattern_def; do not change
} ori_pattern_def;

/// Defaults: no capacity hints.
ORI_API ori_pattern_def ori_default_pattern_def(void);

/// Opaque crease pattern.
typedef struct ori_pattern ori_pattern;

/// Create an empty pattern. Destroy with ori_pattern_destroy.
ORI_API ori_pattern *ori_pattern_create(const ori_pattern_def *def);
/// Destroy a pattern; NULL is a no-op.
ORI_API void ori_pattern_destroy(ori_pattern *pattern);
/// Deep copy (including names, tree and built topology). Destroy with ori_pattern_destroy.
ORI_API ori_pattern *ori_pattern_clone(const ori_pattern *pattern);

/// Append a vertex (z = 0 for a flat sheet); returns its index.
ORI_API int ori_pattern_add_vertex(ori_pattern *pattern, ori_v3 position);
/// Append an edge between existing vertices; returns its index.
ORI_API int ori_pattern_add_edge(ori_pattern *pattern, int v0, int v1, ori_assignment a,
                                 double fold_angle_rad);
/// Append a face given as a cycle of count ≥ 3 vertex indices (copied); returns its index.
ORI_API int ori_pattern_add_face(ori_pattern *pattern, const int *vertices, int count);
/// Move a vertex.
ORI_API void ori_pattern_set_vertex(ori_pattern *pattern, int vertex, ori_v3 position);
/// Change an edge's assignment (keeps the topology built).
ORI_API void ori_pattern_set_assignment(ori_pattern *pattern, int edge, ori_assignment a);
/// Change an edge's fold angle in radians (keeps the topology built).
ORI_API void ori_pattern_set_fold_angle(ori_pattern *pattern, int edge, double fold_angle_rad);
/// Remove all faces (they are recomputed from the planar graph by the next build).
ORI_API void ori_pattern_clear_faces(ori_pattern *pattern);
/// Mark the pattern as a folded form (vertices are folded positions, not a flat sheet) or not.
ORI_API void ori_pattern_set_folded_form(ori_pattern *pattern, bool folded_form);
/// Whether edges carry explicit fold angles (FOLD edges_foldAngle present).
ORI_API void ori_pattern_set_has_fold_angles(ori_pattern *pattern, bool has);

/// Build parameters; get them from ori_default_build_def().
typedef struct ori_build_def {
    bool weld;             ///< merge vertices closer than the length tolerance instead of failing
    bool check_planarity;  ///< flat sheets: reject coincident vertices and crossing edges
    bool compute_faces;    ///< compute faces from the planar graph when none are given
    bool planarize;        ///< ori_fold_get_pattern: a flat frame whose edges cross or overlap is planarised (split at
                           ///< crossings, overlaps merged, faces retraced) instead of refused; default false
    int internal_value;    ///< set by ori_default_build_def; do not change
} ori_build_def;

/// Defaults: no welding, planarity checked, faces computed when missing, no planarising.
ORI_API ori_build_def ori_default_build_def(void);

/// Validate the pattern and build its derived topology. Fails (status and error naming the
/// element) on out-of-range indices, zero-length edges, coincident vertices and crossing
/// edges (flat sheets only), faces whose sides are not edges, non-manifold edges.
/// Welding renumbers vertices (and so changes indices).
ORI_API ori_status ori_pattern_build(ori_pattern *pattern, const ori_build_def *def, ori_error *error);
/// True after a successful build and before the next topology change.
ORI_API bool ori_pattern_is_built(const ori_pattern *pattern);

/// Number of vertices (FOLD vertices_coords entries).
ORI_API int ori_pattern_vertex_count(const ori_pattern *pattern);
/// Number of edges (FOLD edges_vertices entries).
ORI_API int ori_pattern_edge_count(const ori_pattern *pattern);
/// Number of faces (given, or traced by the last build).
ORI_API int ori_pattern_face_count(const ori_pattern *pattern);
/// Position of a vertex.
ORI_API ori_v3 ori_pattern_vertex(const ori_pattern *pattern, int vertex);
/// An edge by value.
ORI_API ori_edge ori_pattern_edge(const ori_pattern *pattern, int edge);
/// Number of vertices of a face.
ORI_API int ori_pattern_face_size(const ori_pattern *pattern, int face);
/// Copy a face's vertex cycle into out (capacity cap); returns the face size.
ORI_API int ori_pattern_face_vertices(const ori_pattern *pattern, int face, int *out, int cap);
/// Copy a face's edges into out (edge k joins vertex k and k+1 of the cycle); needs a build.
ORI_API int ori_pattern_face_edges(const ori_pattern *pattern, int face, int *out, int cap);
/// True when the pattern is a folded form (3D or flagged foldedForm) rather than a flat sheet.
ORI_API bool ori_pattern_is_folded_form(const ori_pattern *pattern);
/// True when any vertex lies off the plane z = 0.
ORI_API bool ori_pattern_is_3d(const ori_pattern *pattern);
/// Whether edges carry explicit fold angles.
ORI_API bool ori_pattern_has_fold_angles(const ori_pattern *pattern);
/// Edges whose FOLD edges_foldAngle entry was null (Origami Simulator writes null on boundary
/// edges): read as absent, angle 0. 0 for patterns not read from FOLD.
ORI_API int ori_pattern_absent_fold_angle_count(const ori_pattern *pattern);
/// A FOLD frame planarised on reading (ori_build_def.planarize): the number of edges the file
/// gave (the pattern's own edges are the planarised ones); 0 when it was read as it is.
ORI_API int ori_pattern_planarized_from(const ori_pattern *pattern);
/// Length of the bounding-box diagonal (the length scale of every relative tolerance); 1 for
/// an empty or single-point pattern.
ORI_API double ori_pattern_diagonal(const ori_pattern *pattern);
/// Number of edges with assignment a.
ORI_API int ori_pattern_count_assignment(const ori_pattern *pattern, ori_assignment a);

/// Edge joining v0 and v1 (either order), or ORI_NULL_INDEX. Needs a build.
ORI_API int ori_pattern_find_edge(const ori_pattern *pattern, int v0, int v1);
/// Number of edges at a vertex. Needs a build.
ORI_API int ori_pattern_vertex_degree(const ori_pattern *pattern, int vertex);
/// Copy the edges at a vertex in counter-clockwise cyclic order (seen from the front side of
/// the sheet) into out; returns the degree. Needs a build.
ORI_API int ori_pattern_vertex_edges(const ori_pattern *pattern, int vertex, int *out, int cap);
/// Faces on the left (faces[0]) and right (faces[1]) of edge v[0]→v[1]; ORI_NULL_INDEX where
/// there is none. Needs a build.
ORI_API void ori_pattern_edge_faces(const ori_pattern *pattern, int edge, int faces[2]);
/// True when every edge at the vertex has a face on both sides and none is a boundary or cut:
/// the paper surrounds the vertex. Needs a build.
ORI_API bool ori_pattern_vertex_is_interior(const ori_pattern *pattern, int vertex);
/// Number of interior vertices. Needs a build.
ORI_API int ori_pattern_interior_vertex_count(const ori_pattern *pattern);
/// Edges at a vertex in cyclic order (as ori_pattern_vertex_edges) and sectors_rad[i] = the
/// paper angle from edge i to edge i+1 (counter-clockwise, the last wraps to edge 0), measured
/// in the flat sheet or, for a folded form, as the face corner in 3D. Either output may be
/// NULL. Returns the degree. Needs a build.
ORI_API int ori_pattern_vertex_sectors(const ori_pattern *pattern, int vertex, int *edges,
                                       double *sectors_rad, int cap);

/// Name of a face (e.g. "Obj121"), or NULL when it has none. Valid until the name changes.
ORI_API const char *ori_pattern_face_name(const ori_pattern *pattern, int face);
/// Set (copy) or clear (NULL) a face's name; names longer than ORI_NAME_MAX−1 are rejected.
ORI_API ori_status ori_pattern_set_face_name(ori_pattern *pattern, int face, const char *name);
/// Face whose name equals name, or ORI_NULL_INDEX.
ORI_API int ori_pattern_find_face_by_name(const ori_pattern *pattern, const char *name);
/// Number of nodes in the face tree (0 when the pattern has no crease history).
ORI_API int ori_pattern_tree_node_count(const ori_pattern *pattern);
/// A face-tree node by value.
ORI_API ori_tree_node ori_pattern_tree_node(const ori_pattern *pattern, int node);
/// Append a face-tree node; returns its index, or ORI_NULL_INDEX for a bad name or parent.
ORI_API int ori_pattern_add_tree_node(ori_pattern *pattern, const char *name, int parent);
/// Remove every face-tree node.
ORI_API void ori_pattern_clear_tree(ori_pattern *pattern);
/// Node whose name equals name, or ORI_NULL_INDEX.
ORI_API int ori_pattern_find_tree_node(const ori_pattern *pattern, const char *name);

#ifdef __cplusplus
}
#endif

#endif
