/// orikin FOLD I/O: read and write FOLD 1.2 documents (JSON) with every unknown and custom
/// field preserved, frames (file_frames with frame_inherit/frame_parent), and conversion to
/// and from ori_pattern. Angles in files are degrees; patterns hold radians.
///
/// Functions: ori_fold_load_file, ori_fold_load_string, ori_fold_create, ori_fold_destroy,
/// ori_fold_frame_count, ori_fold_frame_is_folded_form, ori_fold_get_pattern,
/// ori_fold_set_pattern, ori_fold_extract_frame, ori_fold_append_frame, ori_fold_append_state,
/// ori_fold_get_custom, ori_fold_set_custom, ori_fold_set_string, ori_fold_to_string,
/// ori_json_normalize, ori_format_real, ori_fold_save_file.
///
/// Frame numbers follow FOLD: frame 0 is the top level, frame k ≥ 1 is file_frames[k − 1].
#ifndef ORIKIN_FOLD_H
#define ORIKIN_FOLD_H

#include "base.h"
#include "pattern.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Largest FOLD file the loader accepts (bytes); larger files fail with ORI_ERR_LIMIT.
#define ORI_FOLD_MAX_BYTES ((size_t)1 << 31)

/// Opaque FOLD document (the whole JSON tree, including fields orikin does not interpret).
typedef struct ori_fold ori_fold;

/// Parse a FOLD file. On a JSON syntax error the error has the line and column. Destroy the
/// document with ori_fold_destroy (*out is NULL on failure).
ORI_API ori_status ori_fold_load_file(const char *path, ori_fold **out, ori_error *error);
/// Parse FOLD text of length size (need not be NUL-terminated).
ORI_API ori_status ori_fold_load_string(const char *text, size_t size, ori_fold **out,
                                        ori_error *error);
/// A new document with file_spec 1.2 and file_creator "orikin"; frame 0 is empty.
ORI_API ori_fold *ori_fold_create(void);
/// Destroy a document; NULL is a no-op.
ORI_API void ori_fold_destroy(ori_fold *doc);

/// Number of frames (1 + the length of file_frames).
ORI_API int ori_fold_frame_count(const ori_fold *doc);
/// True when the frame (with inheritance) lists "foldedForm" in frame_classes.
ORI_API bool ori_fold_frame_is_folded_form(const ori_fold *doc, int frame);

/// Build the pattern of a frame (inherited fields resolved): vertices_coords, edges_vertices,
/// edges_assignment (default U), edges_foldAngle (degrees → radians), faces_vertices,
/// orikin:faces_name and orikin:face_tree; then ori_pattern_build with def (NULL = default;
/// planarity is never checked on folded forms). Errors name the field and the FOLD index.
/// With def->planarize, a flat frame whose edges cross or overlap is planarised instead (see
/// ori_pattern_planarized_from): refused when the frame holds other index-tied fields it would
/// lose, or when overlapping creases disagree (M over V; a boundary wins over a crease and an
/// assigned crease over U).
ORI_API ori_status ori_fold_get_pattern(const ori_fold *doc, int frame, const ori_build_def *def,
                                        ori_pattern **out, ori_error *error);
/// Write a pattern's fields into a frame (0 = top level), keeping every other field. When the
/// vertex, edge or face counts change, FOLD's derived index fields (vertices_vertices,
/// faces_edges, edges_faces, …) of that frame are dropped, since they would be stale. A frame
/// that inherits a field that must go (stale, or one the pattern does not have) first takes its
/// inherited fields in and stops inheriting (frame_inherit false).
ORI_API ori_status ori_fold_set_pattern(ori_fold *doc, int frame, const ori_pattern *pattern,
                                        ori_error *error);
/// A new document holding frame `frame` alone as its top level (a real extraction): the frame's
/// fields with inheritance resolved (its own first), the top level's file metadata (file_title,
/// file_author, …) and file_classes ["singleModel"]; frame_parent, frame_inherit and file_frames
/// are dropped. Destroy with ori_fold_destroy (*out is NULL on failure: ORI_ERR_RANGE).
ORI_API ori_status ori_fold_extract_frame(const ori_fold *doc, int frame, ori_fold **out, ori_error *error);

/// Append a frame to file_frames with the given frame_classes entry (e.g. "foldedForm") and
/// title (either may be NULL). The document becomes an animation: file_classes "singleModel"
/// is replaced by "animation" (ori_fold_append_state likewise). With parent = ORI_NULL_INDEX the frame holds all the pattern's
/// fields; with a parent frame number it inherits from it (frame_inherit) and holds only
/// vertices_coords and edges_foldAngle (a folded state of the same pattern). Returns the new
/// frame number.
ORI_API int ori_fold_append_frame(ori_fold *doc, const ori_pattern *pattern,
                                  const char *frame_class, const char *title, int parent);

/// Append a folded state of the parent frame's pattern: a "foldedForm" frame inheriting from
/// parent with 3D vertices_coords = positions (vertex_count entries) and edges_foldAngle =
/// angles_rad (edge_count entries, written in degrees), and an optional title. Returns the
/// new frame number.
ORI_API int ori_fold_append_state(ori_fold *doc, int parent, int vertex_count, const ori_v3 *positions,
                                  int edge_count, const double *angles_rad, const char *title);

/// A field of a frame as JSON text (e.g. key "orikin:sequence"), or NULL when absent. Free
/// with ori_buffer_free.
ORI_API char *ori_fold_get_custom(const ori_fold *doc, int frame, const char *key);
/// Set a field of a frame from JSON text (NULL json removes the field). Fails with
/// ORI_ERR_PARSE when json is not valid JSON.
ORI_API ori_status ori_fold_set_custom(ori_fold *doc, int frame, const char *key, const char *json,
                                       ori_error *error);
/// Set a string field of a frame (e.g. "file_title").
ORI_API void ori_fold_set_string(ori_fold *doc, int frame, const char *key, const char *value);

/// Serialise the document as FOLD JSON text (numbers in their shortest exact form). Free with
/// ori_buffer_free.
ORI_API char *ori_fold_to_string(const ori_fold *doc);
/// Re-emit JSON text with every number in its shortest exact decimal form: compact (one line)
/// or, with pretty, one key per line. Returns NULL (and sets error) for invalid JSON. Free with
/// ori_buffer_free. The CLI uses it for --json output.
ORI_API char *ori_json_normalize(const char *json_text, bool pretty, ori_error *error);
/// A number as every orikin writer prints it: the shortest decimal that reads back as exactly x
/// (the first of %.15g, %.16g, %.17g that does; ±0 as "0"). size ≥ 32; buf is terminated.
ORI_API void ori_format_real(double x, char *buf, size_t size);

/// Write the document to path atomically (temporary file, then rename).
ORI_API ori_status ori_fold_save_file(const ori_fold *doc, const char *path, ori_error *error);

#ifdef __cplusplus
}
#endif

#endif
