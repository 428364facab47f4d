/// orikin layers: global flat-foldability. Every flat-folded state of a crease pattern (the
/// stacking order of its faces, FOLD faceOrders), counted exactly, with the conflicting
/// constraint named when there is none. The model is Flat-Folder's (J. Ku): one Boolean
/// variable per pair of faces that overlap when folded, taco-taco, taco-tortilla,
/// tortilla-tortilla and transitivity constraints, propagation from the M/V assignment
/// (U creases are free), independent components, and a count per component. docs/layers.md
/// describes the algorithm, its improvements and its limits.
///
/// Functions: ori_default_layers_def, ori_layers_create, ori_layers_count, ori_layers_destroy,
/// ori_layers_get_info, ori_layers_constraint_name, ori_layers_get_conflict,
/// ori_layers_conflict_faces, ori_layers_state_count, ori_layers_component_count,
/// ori_layers_component_states, ori_layers_component_variables, ori_layers_select_state,
/// ori_layers_face_orders, ori_layers_face_above, ori_layers_folded_vertex,
/// ori_layers_face_flipped, ori_layers_face_transform, ori_layers_cell_count,
/// ori_layers_cell_polygon, ori_layers_cell_stack, ori_layers_append_frame, ori_layers_svg.
///
/// Conventions: faces, edges and vertices are FOLD indices of the pattern. The folded state
/// lies in the plane of the folded frame; "above" means towards +z of that frame, and the
/// fixed face (the root, face 0 unless transforms are given) keeps its place and its front
/// side up. A face is flipped when its front side (counter-clockwise in the crease pattern)
/// faces −z. A valley crease brings the front sides together, so across a valley the moving
/// face lies on the fixed face's front side. Counts are exact natural numbers handed out as
/// decimal strings (free them with ori_buffer_free).
#ifndef ORIKIN_LAYERS_H
#define ORIKIN_LAYERS_H

#include "base.h"
#include "fold.h"
#include "math.h"
#include "pattern.h"

#ifdef __cplusplus
extern "C" {
#endif

/// ori_layers_def.limit value meaning "count every state".
#define ORI_LAYERS_NO_LIMIT UINT64_MAX

/// Solver parameters; get them from ori_default_layers_def().
typedef struct ori_layers_def {
    /// Optional folded placement of each face (FOLD faces_flatFoldTransform): 6 numbers per
    /// face, x' = t[0] x + t[1] y + t[2], y' = t[3] x + t[4] y + t[5]; NULL (default) folds
    /// the crease pattern through a spanning tree of its faces.
    const double *face_transforms;
    int face_transform_count;  ///< number of faces given in face_transforms
    /// Flat-Folder's "limit": stop counting a component at this many states (its count is
    /// then a lower bound and the result says limited). Default ORI_LAYERS_NO_LIMIT.
    uint64_t limit;
    int threads;               ///< worker threads for independent components (≥ 1); default 1
    /// Snapping length of the overlap structure relative to the folded image's diagonal (a
    /// value above ORI_TOL_LAYERS_SNAP_REL also accepts Kawasaki sums and takes sectors for equal
    /// up to that many radians); ORI_LAYERS_SNAP_AUTO (the default) chooses it from the
    /// drawing's own precision (docs/layers.md; ori_layers_info.tolerance tells the value).
    double snap_rel;
    ori_progress_fn *progress; ///< optional progress/cancel callback for ori_layers_count
    void *progress_user;       ///< passed back to progress
    int internal_value;        ///< set by ori_default_layers_def; do not change
} ori_layers_def;

/// ori_layers_def.snap_rel value meaning "from the drawing's precision".
#define ORI_LAYERS_SNAP_AUTO 0.0

/// Defaults: fold from the crease pattern, no limit, one thread, ORI_LAYERS_SNAP_AUTO.
ORI_API ori_layers_def ori_default_layers_def(void);

/// Opaque solver and result.
typedef struct ori_layers ori_layers;

/// Set up the layer problem of a built pattern (a flat crease pattern, or a flat folded form
/// whose faces' winding tells their side): fold it, build the overlap structure, variables and
/// constraints, propagate the M/V assignment and split into independent components. Fails with
/// ORI_ERR_DEGENERATE when the folded coordinates do not determine the overlap structure at the
/// snapping length (element: a vertex or edge), ORI_ERR_TOPOLOGY when the sheet does not fold
/// consistently (element: a vertex), ORI_ERR_UNSUPPORTED for a 3D (not flat) folded form or
/// a sheet whose faces are not connected by creases. A pattern that is not locally
/// flat-foldable or whose constraints conflict is a result (ori_layers_get_conflict), not a
/// failure. Destroy with ori_layers_destroy (*out is NULL on failure).
ORI_API ori_status ori_layers_create(const ori_pattern *pattern, const ori_layers_def *def, ori_layers **out,
                                     ori_error *error);
/// Count the states of every component (exactly, or up to the limit). Fails only when the
/// progress callback cancels (ORI_ERR_LIMIT); the solver then holds a partial answer: every
/// count is a lower bound (the states counted so far; a component not reached gets the first
/// state a short search finds, else 0), info.limited and info.stopped are true, and no
/// component is declared without states. A no-op when already counted (or stopped).
ORI_API ori_status ori_layers_count(ori_layers *layers, ori_error *error);
/// Destroy a solver; NULL is a no-op.
ORI_API void ori_layers_destroy(ori_layers *layers);

/// Sizes of the problem and the verdict so far.
typedef struct ori_layers_info {
    int faces;                 ///< faces of the pattern
    int variables;             ///< overlapping face pairs
    int64_t taco_taco;         ///< taco-taco constraints
    int64_t taco_tortilla;     ///< taco-tortilla constraints
    int64_t tortilla_tortilla; ///< tortilla-tortilla constraints
    int64_t transitivity;      ///< face triples over a common cell
    int points, segments, cells; ///< overlap structure of the folded image
    int classes;               ///< variables after merging the binary constraints
    int fixed_variables;       ///< variables the M/V assignment fixes (with propagation)
    int components;            ///< independent components, the fixed part (component 0) included
    bool counted;              ///< ori_layers_count has run
    bool limited;              ///< some component reached the limit (its count is a lower bound)
    bool stopped;              ///< the progress callback cancelled the count (every count a lower bound)
    bool satisfiable;          ///< false once no state is known to exist
    double tolerance;          ///< the snapping length used (relative to the folded image's diagonal)
    bool tolerance_from_drawing; ///< it was chosen from the drawing (ORI_LAYERS_SNAP_AUTO)
    /// The drawing's precision as the set-up saw it (0 for exact coordinates): the largest
    /// distance, relative to the diagonal, it took for zero (points snapped together, a point
    /// on an edge, a vertex two faces fold to different places) …
    double noise_length;
    /// … and the largest angle in radians (a vertex's Kawasaki sum, sectors taken for equal).
    double noise_angle;
} ori_layers_info;

/// Sizes and verdict by value.
ORI_API ori_layers_info ori_layers_get_info(const ori_layers *layers);

/// Why there is no state.
typedef enum ori_layers_constraint {
    ORI_LAYERS_TACO_TACO = 0,      ///< two creases folded over each other would cross
    ORI_LAYERS_TACO_TORTILLA,      ///< a face would pass through a crease's fold
    ORI_LAYERS_TORTILLA_TORTILLA,  ///< a face would pass between two coplanar neighbours
    ORI_LAYERS_TRANSITIVITY,       ///< three faces over one cell would form a cycle
    ORI_LAYERS_ASSIGNMENT,         ///< two creases' M/V assignments force opposite orders
    ORI_LAYERS_LOCAL,              ///< a vertex is not locally flat-foldable
    ORI_LAYERS_EXHAUSTED,          ///< propagation found no conflict, but a component has no state
    ORI_LAYERS_CONSTRAINT_COUNT
} ori_layers_constraint;

/// Name used in reports: "taco_taco", "taco_tortilla", "tortilla_tortilla", "transitivity",
/// "assignment", "local", "exhausted"; static string.
ORI_API const char *ori_layers_constraint_name(ori_layers_constraint c);

/// The conflict that leaves no state.
typedef struct ori_layers_conflict {
    ori_layers_constraint constraint;
    int faces[4];        ///< the constraint's faces (taco-taco a, b, c, d: creases a|b and c|d)
    int face_count;      ///< 2, 3 or 4 (0 for LOCAL and EXHAUSTED)
    int vertex;          ///< LOCAL: the vertex; else ORI_NULL_INDEX
    int component;       ///< EXHAUSTED: the component; else -1
    double kawasaki_rad; ///< LOCAL by Kawasaki: the vertex's alternating sector sum (radians); else 0
    char detail[200];    ///< one readable sentence
} ori_layers_conflict;

/// When no state exists (as far as known: call ori_layers_count first for the whole answer),
/// write the conflict into *out and return true; false when states may exist.
ORI_API bool ori_layers_get_conflict(const ori_layers *layers, ori_layers_conflict *out);
/// Every face the conflict involves (the constraint's faces, the faces whose orders forced it,
/// or the faces of an exhausted component), ascending, into out (capacity cap); returns the
/// total number.
ORI_API int ori_layers_conflict_faces(const ori_layers *layers, int *out, int cap);

/// Number of states (decimal string; "0" when unsatisfiable). Needs ori_layers_count. Free
/// with ori_buffer_free.
ORI_API char *ori_layers_state_count(const ori_layers *layers);
/// Number of components, the fixed part (component 0, one state) included; Flat-Folder's
/// order: component 0, then the others by ascending number of variables.
ORI_API int ori_layers_component_count(const ori_layers *layers);
/// States of component c (decimal string). Needs ori_layers_count. Free with ori_buffer_free.
ORI_API char *ori_layers_component_states(const ori_layers *layers, int c);
/// Variables (face pairs) of component c.
ORI_API int ori_layers_component_variables(const ori_layers *layers, int c);

/// Select state k (decimal string, 0 ≤ k < the state count): the state's components are the
/// digits of k in the mixed radix of the component counts, component 1 most significant, and
/// each component's states are ranked by a fixed search order. Fails with ORI_ERR_RANGE for k
/// out of range or not a decimal number, ORI_ERR_UNSUPPORTED when the count is limited.
ORI_API ori_status ori_layers_select_state(ori_layers *layers, const char *k, ori_error *error);
/// FOLD faceOrders of the selected state: triples (f, g, s), s = +1 when f lies on the side
/// of g that f's normal points to, −1 otherwise; one triple per variable, f < g. Writes up to
/// cap triples (3·cap ints) into out; returns the number of variables.
ORI_API int ori_layers_face_orders(const ori_layers *layers, int *out, int cap);
/// In the selected state: +1 when face f lies above face g (+z of the folded frame), −1 when
/// below, 0 when they do not overlap.
ORI_API int ori_layers_face_above(const ori_layers *layers, int f, int g);

/// Folded position of vertex v (in the folded frame's plane).
ORI_API ori_v2 ori_layers_folded_vertex(const ori_layers *layers, int v);
/// Whether face f lies face-down when folded.
ORI_API bool ori_layers_face_flipped(const ori_layers *layers, int f);
/// The folded placement of face f as FOLD's faces_flatFoldTransform row (6 numbers).
ORI_API void ori_layers_face_transform(const ori_layers *layers, int f, double out[6]);

/// Number of cells of the overlap structure (regions of the folded image covered by the same
/// faces).
ORI_API int ori_layers_cell_count(const ori_layers *layers);
/// Corners of cell c, counter-clockwise, into out (capacity cap); returns their number.
ORI_API int ori_layers_cell_polygon(const ori_layers *layers, int c, ori_v2 *out, int cap);
/// Faces over cell c from top to bottom in the selected state (or ascending when no state is
/// selected) into out (capacity cap); returns their number.
ORI_API int ori_layers_cell_stack(const ori_layers *layers, int c, int *out, int cap);

/// Append the selected state to doc as a "foldedForm" frame inheriting from frame parent:
/// folded vertices_coords (z = 0), edges_foldAngle ±180 on folded creases (U creases take the
/// direction the state gives them) and 0 elsewhere, edges_assignment likewise resolved,
/// faces_vertices, faces_flatFoldTransform (crease-pattern input), faces_flatFoldOrientation and
/// faceOrders. pattern is the one the solver was created from.
/// Returns the new frame number, or -1 (error set) when no state is selected.
ORI_API int ori_layers_append_frame(const ori_layers *layers, const ori_pattern *pattern, ori_fold *doc, int parent,
                                    ori_error *error);

/// Draw the crease pattern (left: mountain red dash-dot, valley blue dashed, unassigned
/// purple, flat grey, boundary black) and the selected folded state seen from above (right:
/// each cell in the colour of its top face's visible side, darker with more layers below,
/// visible folded edges) as SVG text into *out (size bytes; free with ori_buffer_free).
ORI_API ori_status ori_layers_svg(const ori_layers *layers, const ori_pattern *pattern, char **out, size_t *size,
                                  ori_error *error);

/// --- a count in parts (a distributed count: orikin-layers-mpi, docs/sweep.md) ---------------
/// Functions: ori_layers_count_component, ori_layers_set_counts. ori_layers_create the same
/// pattern with the same def on every worker (the components come out the same), count some
/// components on each, then install them all on one solver.

/// Count component c alone (0 ≤ c < ori_layers_component_count; component 0 has 1 state) with
/// a fresh search, up to the def's limit, without recording it in layers: *states gets the
/// decimal count (free with ori_buffer_free), *limited (optional) whether the limit stopped it.
/// Reads layers only, so calls on different components may run on several threads at once.
/// Fails with ORI_ERR_RANGE for c out of range.
ORI_API ori_status ori_layers_count_component(const ori_layers *layers, int c, char **states, bool *limited,
                                              ori_error *error);
/// Install the count of every component (states[c] decimal, c < ori_layers_component_count;
/// limited: some count is a lower bound) and finish as ori_layers_count: the total and, for a
/// component with no state, the EXHAUSTED conflict. A no-op when already counted. Fails with
/// ORI_ERR_ARGUMENT (nothing changed) for a count that is not decimal or a fixed part other than 1.
ORI_API ori_status ori_layers_set_counts(ori_layers *layers, const char *const *states, bool limited,
                                         ori_error *error);

#ifdef __cplusplus
}
#endif

#endif
