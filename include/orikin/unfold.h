/// orikin unfold: unfolding without self-intersection (SPEC capability 13, thesis ch. 6).
/// Planar linkages (an open chain or a simple polygon) are straightened or convexified by
/// Streinu's expansive motions of pointed pseudo-triangulations; polyhedral surfaces are cut
/// into edge-unfolded nets (one piece when one is found) that fold back into the shape, or, when
/// they are folded forms of a flat sheet, developed without cuts into their crease pattern.
/// docs/unfolding.md has the methods, the limits and the validation figures.
///
/// Functions: ori_default_linkage_def, ori_linkage_unfold, ori_linkage_motion_destroy,
/// ori_linkage_motion_result, ori_linkage_motion_vertex_count, ori_linkage_motion_frame_count,
/// ori_linkage_motion_frame, ori_linkage_motion_frame_is_event, ori_unfold_mesh_create,
/// ori_unfold_load_mesh, ori_unfold_mesh_convex_hull, ori_unfold_mesh_destroy,
/// ori_unfold_mesh_face_count, ori_unfold_mesh_vertex_count, ori_default_unfold_def,
/// ori_unfold_solve, ori_unfold_net_destroy, ori_unfold_net_result, ori_unfold_net_pattern,
/// ori_unfold_net_face_source, ori_unfold_net_glue, ori_unfold_net_vertex_source,
/// ori_unfold_net_vertex_position, ori_unfold_develop.
#ifndef ORIKIN_UNFOLD_H
#define ORIKIN_UNFOLD_H

#include "base.h"
#include "math.h"
#include "pattern.h"

#ifdef __cplusplus
extern "C" {
#endif

// --- planar linkages (carpenter's rule) ------------------------------------------------------

/// A planar linkage to straighten or convexify; get it from ori_default_linkage_def().
typedef struct ori_linkage_def {
    const ori_v2 *coords;  ///< vertex positions (vertex_count entries), any length unit
    int vertex_count;
    const int *edges;      ///< bars as vertex pairs (2 × edge_count entries)
    int edge_count;
    int steps_per_event;   ///< frames kept between two events (≥ 1), 0 = every integration step
    int max_events;        ///< stop (ORI_ERR_LIMIT) when this many events happened and more motion is needed (checked before each motion segment); 0 = 100 × vertices
    ori_progress_fn *progress; ///< called before each motion segment with the fraction done (a chain: its ends' distance over its
                           ///< length; a polygon: the share of max_events), may be NULL; returning false cancels: ORI_ERR_LIMIT
    void *progress_user;   ///< passed to progress
    bool keep_partial;     ///< on ORI_ERR_LIMIT (max_events or cancelled), *out receives the motion so far (result.stopped,
                           ///< final_ok false), its last frame the state at the stop; false (default): nothing
    int internal_value;    ///< set by ori_default_linkage_def; do not change
} ori_linkage_def;

/// Defaults: no linkage (set one), 8 frames per event, automatic event limit, no progress, no partial motion.
ORI_API ori_linkage_def ori_default_linkage_def(void);

/// What kind of linkage was unfolded.
typedef enum ori_linkage_kind {
    ORI_LINKAGE_CHAIN = 0, ///< an open chain: ends straight
    ORI_LINKAGE_POLYGON,   ///< a closed simple polygon: ends convex
} ori_linkage_kind;

/// Summary of a linkage motion.
typedef struct ori_linkage_result {
    ori_linkage_kind kind;
    int events;                 ///< events met: flips plus joints straightened
    int flips;                  ///< pseudo-triangulation flips
    int straightened;           ///< joints that reached 180° (then kept straight)
    int steps;                  ///< accepted integration steps
    int frames;                 ///< frames kept
    bool final_ok;              ///< the last frame is straight (chain) or convex (polygon)
    double max_length_error;    ///< max over kept frames and bars of |length − L| / L
    double min_distance_change; ///< least change of any vertex–vertex distance between consecutive kept frames (length)
    double max_event_residual;  ///< largest |sin| of the aligned angle at the located events (unitless)
    bool stopped;               ///< the motion stopped at max_events or a cancel: a partial motion (keep_partial)
} ori_linkage_result;

/// Opaque linkage motion (frames of vertex positions).
typedef struct ori_linkage_motion ori_linkage_motion;

/// Validate the linkage (one simple chain or one simple polygon: no vertex with three bars
/// — trees can lock —, no coincident vertices, no crossing bars; errors name the element:
/// field "vertices_coords" or "edges_vertices") and follow Streinu's expansive motion to the
/// straight chain or the convex polygon. Fails with ORI_ERR_NOT_CONVERGED when the kept frames
/// break the motion's guarantees (a bar length off by 1e-9 relative, a distance decreasing by
/// 1e-9 of the size), with ORI_ERR_LIMIT past max_events or when progress cancels (then, with
/// keep_partial, *out holds the motion so far, checked the same way). Destroy with ori_linkage_motion_destroy.
ORI_API ori_status ori_linkage_unfold(const ori_linkage_def *def, ori_linkage_motion **out, ori_error *error);
/// Destroy a motion; NULL is a no-op.
ORI_API void ori_linkage_motion_destroy(ori_linkage_motion *motion);
/// The summary by value.
ORI_API ori_linkage_result ori_linkage_motion_result(const ori_linkage_motion *motion);
/// Number of vertices of every frame.
ORI_API int ori_linkage_motion_vertex_count(const ori_linkage_motion *motion);
/// Number of frames kept (the first is the input, the last is straight or convex).
ORI_API int ori_linkage_motion_frame_count(const ori_linkage_motion *motion);
/// Positions of frame k (vertex_count entries, owned by the motion).
ORI_API const ori_v2 *ori_linkage_motion_frame(const ori_linkage_motion *motion, int frame);
/// True when frame k is the configuration of an event (an alignment located by root-finding).
ORI_API bool ori_linkage_motion_frame_is_event(const ori_linkage_motion *motion, int frame);

// --- polyhedral surfaces to nets ---------------------------------------------------------------

/// A polyhedral surface: vertices and faces (consistently oriented, manifold), coplanar
/// neighbours merged into one polygon face.
typedef struct ori_mesh ori_mesh;

/// Make a surface from arrays: coords (vertex_count entries), faces as vertex cycles
/// face_vertices[face_start[f] .. face_start[f + 1]) (face_start has face_count + 1 entries).
/// Fails (error names the face, field "faces_vertices") on degenerate faces (fewer than three
/// distinct vertices, zero area), polygons off their plane by more than 1e-6 × the diagonal,
/// edges shared by more than two faces (non-manifold) and inconsistently oriented neighbours.
/// Destroy with ori_unfold_mesh_destroy.
ORI_API ori_status ori_unfold_mesh_create(const ori_v3 *coords, int vertex_count, const int *face_start,
                                          const int *face_vertices, int face_count, ori_mesh **out, ori_error *error);
/// Load a surface from an OBJ (v, f), STL (ASCII or binary; vertices welded by equal
/// coordinates) or FOLD (frame 0's 3D vertices_coords and faces_vertices) file, by extension. In
/// OBJ and STL a face that repeats an earlier one reversed is dropped (two-sided sheets). An
/// orikin thick export (ORI_THICK_PANEL_TAG: separate panel solids) fails with ORI_ERR_UNSUPPORTED.
ORI_API ori_status ori_unfold_load_mesh(const char *path, ori_mesh **out, ori_error *error);
/// The convex hull of count ≥ 4 points (qhull, triangulated; coplanar facets then merged) as a
/// surface. Fails with ORI_ERR_DEGENERATE when qhull cannot build it (all points coplanar).
ORI_API ori_status ori_unfold_mesh_convex_hull(const ori_v3 *points, int count, ori_mesh **out, ori_error *error);
/// Destroy a surface; NULL is a no-op.
ORI_API void ori_unfold_mesh_destroy(ori_mesh *mesh);
/// Number of faces after merging coplanar neighbours.
ORI_API int ori_unfold_mesh_face_count(const ori_mesh *mesh);
/// Number of vertices.
ORI_API int ori_unfold_mesh_vertex_count(const ori_mesh *mesh);

/// Parameters of an unfolding; get them from ori_default_unfold_def().
typedef struct ori_unfold_def {
    int tries;          ///< spanning trees tried (steepest edge, random, flattest first in turn), ≥ 1
    unsigned seed;      ///< seed of the random directions and weights
    bool all;           ///< also enumerate every spanning tree and count the distinct nets
    long long max_trees; ///< with all: stop after this many spanning trees (all_complete false), ≥ 1
    ori_progress_fn *progress; ///< with all: called with the fraction of trees enumerated; false cancels (a partial count)
    void *progress_user; ///< passed to progress
    int internal_value; ///< set by ori_default_unfold_def; do not change
} ori_unfold_def;

/// Defaults: 50 tries, seed 1, no enumeration, at most 10^7 spanning trees, no progress.
ORI_API ori_unfold_def ori_default_unfold_def(void);

/// How the net is folded back without collision.
typedef enum ori_fold_order {
    ORI_FOLD_ORDER_NONE = -1,      ///< not refolded, or every order tried collides
    ORI_FOLD_ORDER_TOGETHER = 0,   ///< every crease driven together (angles scaled alike)
    ORI_FOLD_ORDER_LEAVES_FIRST,   ///< one crease at a time, deepest in the face tree first
    ORI_FOLD_ORDER_ROOT_FIRST,     ///< one crease at a time, nearest the fixed face first
} ori_fold_order;

/// Summary of an unfolding.
typedef struct ori_unfold_result {
    int pieces;               ///< 1 when a net without overlap was found, else the pieces of the split
    int faces;                ///< faces of the net (merged)
    int input_faces;          ///< faces of the input
    int overlaps;             ///< overlapping face pairs within a piece (0 on success)
    int tries;                ///< trees tried
    int best_try;             ///< the try that gave the net (0-based)
    bool refolded;            ///< the net was folded back (one piece)
    double max_refold_error;  ///< largest vertex distance of the refolded net to the shape / the diagonal; −1 when not refolded
    bool motion_collides;     ///< every fold order tried made faces penetrate (checked in steps)
    ori_fold_order fold_order; ///< the first collision-free order: together, else leaves first, else root first
    int distinct_nets;        ///< with all: overlap-free nets up to congruence (rotations, reflections), a lower bound when !all_complete; −1 otherwise
    long long spanning_trees; ///< with all: spanning trees enumerated
    long long overlap_free_trees; ///< with all: of which without overlap
    double spanning_trees_total; ///< with all: spanning trees of the face graph (Kirchhoff's theorem; exact below 2^53)
    bool all_complete;        ///< with all: every spanning tree was enumerated (else stopped by max_trees or progress)
    int cuts;                 ///< interior edges of the shape cut open (0 when developed; a cut whose sides meet again is a crease)
    bool developed;           ///< developed without cuts into a crease pattern (ori_unfold_develop)
    int interior_vertices;    ///< developed: interior vertices of the sheet; −1 for nets
    double max_angle_defect_rad; ///< developed: largest |2π − face angle sum| at an interior vertex (radians); −1 for nets
    double max_length_error;  ///< developed: largest |flat − 3D length| / 3D length of an edge; −1 for nets
    double max_closing_error; ///< developed: largest gap between the two laid-out copies of an edge off the layout tree / the diagonal; −1 for nets
    double fold_residual;     ///< developed: loop-closure residual of the crease pattern at its fold angles (ori_mechanism_residual); −1 for nets
} ori_unfold_result;

/// Opaque net: the crease pattern and its relation to the shape.
typedef struct ori_unfold_net ori_unfold_net;

/// Unfold a surface: try spanning trees of the face graph until one lays out without overlap
/// (else split the best into pieces), make the crease pattern (cut edges B, creases M or V with
/// the fold angles of the shape) and fold it back. Destroy with ori_unfold_net_destroy.
ORI_API ori_status ori_unfold_solve(const ori_mesh *mesh, const ori_unfold_def *def, ori_unfold_net **out,
                                    ori_error *error);
/// Destroy a net; NULL is a no-op.
ORI_API void ori_unfold_net_destroy(ori_unfold_net *net);
/// The summary by value.
ORI_API ori_unfold_result ori_unfold_net_result(const ori_unfold_net *net);
/// The net as a built flat crease pattern (owned by the net): face f is merged face f.
ORI_API const ori_pattern *ori_unfold_net_pattern(const ori_unfold_net *net);
/// Input faces making up net face `face` into out (capacity cap); returns their count.
ORI_API int ori_unfold_net_face_source(const ori_unfold_net *net, int face, int *out, int cap);
/// The cut edge glued to net edge `edge` when folded, or −1 (creases and open boundary).
ORI_API int ori_unfold_net_glue(const ori_unfold_net *net, int edge);
/// The input vertex a net vertex folds onto.
ORI_API int ori_unfold_net_vertex_source(const ori_unfold_net *net, int vertex);
/// The position in the shape (3D, the input's units) that a net vertex folds onto.
ORI_API ori_v3 ori_unfold_net_vertex_position(const ori_unfold_net *net, int vertex);

// --- folded forms back to their crease pattern (no cuts) ----------------------------------------

/// Develop a surface that is a folded flat sheet (every interior vertex's face angles sum to
/// 360° within tolerance_rad; 0 = ORI_TOL_DEVELOP_ANGLE_RAD; at most 0.5) isometrically into the
/// plane without cuts: the faces are laid out along a breadth-first tree, every other edge's two
/// copies must meet (within max(ORI_TOL_DEVELOP_CLOSE_REL, tolerance_rad) × the diagonal, so holes
/// are fine when the sheet closes around them; vertices then take the mean of their copies) and the sheet must not overlap itself. The net is the crease pattern: every interior
/// edge a crease (M/V from the dihedral sign, fold angle of the shape), the boundary B; it is
/// folded back by the kinematics (result.max_refold_error). Fails with ORI_ERR_NOT_FOUND when
/// the surface does not develop (message and element name the vertex, field "vertices_coords",
/// or the overlapping face, "faces_vertices"). Destroy with ori_unfold_net_destroy.
ORI_API ori_status ori_unfold_develop(const ori_mesh *mesh, double tolerance_rad, ori_unfold_net **out,
                                      ori_error *error);

#ifdef __cplusplus
}
#endif
#endif
