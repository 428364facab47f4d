/// orikin unfold: unfolding without self-intersection (SPEC capability 13, thesis ch. 6).
/// Planar linkages (an open chain or a simple polygon) are straightened or convexified by
/// Streinu's expansive motions of pointed pseudo-triangulations; polyhedral surfaces are cut
/// into edge-unfolded nets (one piece when one is found) that fold back into the shape.
/// docs/unfolding.md has the methods, the limits and the validation figures.
///
/// Functions: ori_default_linkage_def, ori_linkage_unfold, ori_linkage_motion_destroy,
/// ori_linkage_motion_result, ori_linkage_motion_vertex_count, ori_linkage_motion_frame_count,
/// ori_linkage_motion_frame, ori_linkage_motion_frame_is_event, ori_default_unfold_def,
/// ori_unfold_load_mesh, ori_unfold_mesh_destroy, ori_unfold_mesh_face_count, ori_unfold_solve,
/// ori_unfold_net_destroy, ori_unfold_net_result, ori_unfold_net_pattern,
/// ori_unfold_net_face_source, ori_unfold_net_glue, ori_unfold_net_refold_error.
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
    int max_events;        ///< give up (ORI_ERR_LIMIT) after this many events; 0 = 100 × vertices
    int internal_value;    ///< set by ori_default_linkage_def; do not change
} ori_linkage_def;

/// Defaults: no linkage (set one), 8 frames per event, automatic event limit.
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
} ori_linkage_result;

/// Opaque linkage motion (frames of vertex positions).
typedef struct ori_linkage_motion ori_linkage_motion;

/// Validate the linkage (one simple chain or one simple polygon: no vertex with three bars
/// — trees can lock —, no coincident vertices, no crossing bars; errors name the element:
/// field "vertices_coords" or "edges_vertices") and follow Streinu's expansive motion to the
/// straight chain or the convex polygon. Destroy with ori_linkage_motion_destroy.
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

#ifdef __cplusplus
}
#endif
#endif
