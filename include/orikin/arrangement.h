/// orikin arrangement: insert straight segments into a flat crease pattern so that it stays a
/// planar straight-line graph. Crossed edges are split at the crossing, points near existing
/// vertices snap to them, the segment is split at every vertex it passes through, collinear
/// overlaps merge with the edges they run along, and faces are split (and named) in place.
/// Every existing index stays valid: new vertices, edges and faces are appended; a split edge
/// keeps its index for the part at its first vertex (without faces, where snapping can lay that
/// part onto another edge: for a part of its own); a split face keeps its index for the part
/// left of the segment.
///
/// Functions: ori_default_insert_def, ori_pattern_insert_segment, ori_pattern_insert_segments,
/// ori_pattern_from_segments, ori_pattern_find_edge_at, ori_pattern_find_face_at,
/// ori_pattern_center_face, ori_pattern_edges_on_segment.
///
/// Robustness: every topological decision (which side of a line, crossing or not, collinear,
/// inside a face corner) is an exact ori_orient2d_sign on stored coordinates; crossing points
/// are computed in floating point from the (adaptive) orientation values and clamped to both
/// segments' bounding boxes; points closer than ORI_TOL_LENGTH_REL × scale to a vertex become
/// that vertex, the segment is routed through every vertex within that distance of it, and an
/// edge passing that close to one of its points is split there. No two edges ever join the same
/// two vertices: an edge part that snapping lays onto another edge merges with it. The result is
/// checked exactly before anything changes; an insertion that snapping cannot make planar is
/// refused. docs/authoring.md has the details.
#ifndef ORIKIN_ARRANGEMENT_H
#define ORIKIN_ARRANGEMENT_H

#include "base.h"
#include "math.h"
#include "pattern.h"

#ifdef __cplusplus
extern "C" {
#endif

/// What an existing edge that the new segment runs along ends up with.
typedef enum ori_overlap_rule {
    ORI_OVERLAP_KEEP_BOUNDARY = 0, ///< B and C edges keep theirs; other edges take the new assignment and angle
    ORI_OVERLAP_KEEP_EXISTING,     ///< every overlapped edge keeps its assignment and angle
    ORI_OVERLAP_REPLACE,           ///< every overlapped edge takes the new assignment and angle
} ori_overlap_rule;

/// ori_insert_def.length_scale value meaning "the bounding-box diagonal of the pattern's
/// vertices together with the segment's end points".
#define ORI_INSERT_AUTO_SCALE (-1.0)

/// Insertion parameters; get them from ori_default_insert_def().
typedef struct ori_insert_def {
    ori_overlap_rule overlap; ///< rule for overlapped edges; default ORI_OVERLAP_KEEP_BOUNDARY
    bool name_faces;          ///< a split face named N gives N1 (left part) and N2 (right part), recorded in the face tree; default true
    double length_scale;      ///< snapping length scale (tolerance = ORI_TOL_LENGTH_REL × scale); > 0, or ORI_INSERT_AUTO_SCALE (default)
    int internal_value;       ///< set by ori_default_insert_def; do not change
} ori_insert_def;

/// Defaults: overlap rule KEEP_BOUNDARY, faces named, automatic scale.
ORI_API ori_insert_def ori_default_insert_def(void);

/// What an insertion did. Counts; appended elements start at the counts the pattern had before.
typedef struct ori_insert_result {
    int vertices_added;   ///< new vertices (crossings, T-junctions, free end points)
    int edges_added;      ///< new edges (segment pieces and the far parts of split edges)
    int faces_added;      ///< new faces (the right parts of split faces)
    int edges_split;      ///< existing edges cut (each keeps its index for its first part)
    int edges_overlapped; ///< existing edges (or parts) the segment runs along
    int faces_split;      ///< face splits performed
    int segment_edges;    ///< edges that now cover the segment (new pieces + overlapped edges)
    int segments_skipped; ///< bulk insertion: segments refused as ori_pattern_insert_segment would (ignored)
    int edges_merged;     ///< pattern without faces: parts of split edges that snapping laid onto another edge (one edge remains)
} ori_insert_result;

/// One segment for bulk insertion: end points, assignment and fold angle (radians, FOLD sign).
typedef struct ori_segment {
    ori_v2 a, b;
    ori_assignment assignment;
    double fold_angle_rad;
} ori_segment;

/// Insert the segment a→b (its direction defines "left" for face names) into a flat pattern
/// with assignment asg and fold angle fold_angle_rad. def may be NULL (defaults); out may be
/// NULL. The pattern need not be built and is left unbuilt (call ori_pattern_build). Fails,
/// leaving the pattern unchanged, with ORI_ERR_RANGE for non-finite points; ORI_ERR_DEGENERATE
/// when the snapped end points coincide, when snapping would merge two existing edges of a
/// pattern with faces (the face between them would collapse) or make an edge vanish into
/// others, or when it cannot be made planar at the tolerance (element: an edge concerned, or
/// ORI_NULL_INDEX); ORI_ERR_UNSUPPORTED on a folded form or when the pattern has faces and a
/// piece would float inside one (touching neither its boundary nor a crease: a face is one cycle
/// and cannot have a hole; a free end hanging from the boundary, a slit, is fine).
ORI_API ori_status ori_pattern_insert_segment(ori_pattern *pattern, ori_v2 a, ori_v2 b, ori_assignment asg,
                                              double fold_angle_rad, const ori_insert_def *def,
                                              ori_insert_result *out, ori_error *error);

/// Insert count segments in order (a uniform grid keeps each insertion local, so tens of
/// thousands of segments planarise in near-linear time when the pattern has no faces yet).
/// With an automatic scale the scale is the diagonal of the pattern and all segments together,
/// fixed for the whole call. Segments that ori_pattern_insert_segment would refuse (shorter than
/// the tolerance, floating inside a face, not insertable consistently) are skipped and counted;
/// a non-finite coordinate fails (field "segments", element = segment index) before any change.
ORI_API ori_status ori_pattern_insert_segments(ori_pattern *pattern, const ori_segment *segments, int count,
                                               const ori_insert_def *def, ori_insert_result *out,
                                               ori_error *error);

/// A new planar pattern from segments (overlapping and crossing ones are planarised), built
/// with faces traced from the planar graph. As its indices are new, an edge that snapping lays
/// entirely onto others is removed rather than the segment refused. *out is NULL on failure;
/// destroy with ori_pattern_destroy.
ORI_API ori_status ori_pattern_from_segments(const ori_segment *segments, int count, const ori_insert_def *def,
                                             ori_pattern **out, ori_insert_result *result, ori_error *error);

/// The edge passing within ORI_TOL_ON_LINE_REL × diagonal of point (the nearest one), or
/// ORI_NULL_INDEX. Works on an unbuilt pattern; flat patterns only (uses x, y).
ORI_API int ori_pattern_find_edge_at(const ori_pattern *pattern, ori_v2 point);

/// The face containing point (crossing-number test on the flat pattern's x, y), or
/// ORI_NULL_INDEX. A point within ORI_TOL_ON_LINE_REL × diagonal of a face's boundary returns that
/// face with *on_edge true (on_edge may be NULL); the lowest such face index wins.
ORI_API int ori_pattern_find_face_at(const ori_pattern *pattern, ori_v2 point, bool *on_edge);

/// The face a fold holds fixed when none is named (the CLI's default --fix, the Python binding's
/// default fix): the face containing the centroid of the sheet's area (the faces' area centroids
/// weighted by area), else (the centroid on a crease, in a hole or outside the sheet) the face
/// whose outline is nearest to it, then the one whose area centroid is nearest, then the lowest
/// index (ties within ORI_TOL_ON_LINE_REL × diagonal); 0 for a pattern without faces.
ORI_API int ori_pattern_center_face(const ori_pattern *pattern);

/// Edges lying along the segment ab (both end points within ORI_TOL_ON_LINE_REL × diagonal of
/// it), in order of their index; writes up to cap into out and returns the total count.
ORI_API int ori_pattern_edges_on_segment(const ori_pattern *pattern, ori_v2 a, ori_v2 b, int *out, int cap);

#ifdef __cplusplus
}
#endif

#endif
