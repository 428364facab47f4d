/// orikin formats: crease patterns in other tools' formats. Import SVG (Origami Simulator colour
/// convention), ORIPA .opx and .cp into a list of segments and planarise them into a pattern;
/// export a pattern as SVG, .cp or .opx; write a pattern as a new FOLD document directly (no
/// JSON tree, for big patterns). docs/formats.md has the conventions and limitations.
///
/// Functions: ori_format_table, ori_format_find, ori_format_from_path, ori_format_name,
/// ori_format_is_drawing, ori_default_import_def, ori_svg_read_segments,
/// ori_opx_read_segments, ori_cp_read_segments, ori_read_segments, ori_segments_to_pattern,
/// ori_import_file, ori_import_text, ori_default_svg_write_def, ori_svg_write, ori_cp_write,
/// ori_opx_write, ori_export_file, ori_pattern_to_fold_text, ori_pattern_save_fold.
///
/// Coordinates: SVG, .opx and .cp are drawn with y growing downwards; every importer maps
/// (x, y) to (x, −y) (exact) so that the FOLD pattern (y up) looks as the drawing did and
/// counter-clockwise stays counter-clockwise; every exporter maps back.
#ifndef ORIKIN_FORMATS_H
#define ORIKIN_FORMATS_H

#include "arrangement.h"
#include "base.h"
#include "pattern.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Largest input file the importers accept (bytes); larger files fail with ORI_ERR_LIMIT.
#define ORI_IMPORT_MAX_BYTES ((size_t)1 << 28)

/// File formats known by extension.
typedef enum ori_format {
    ORI_FORMAT_UNKNOWN = 0, ///< none of the below
    ORI_FORMAT_FOLD,        ///< ".fold": FOLD JSON
    ORI_FORMAT_SVG,         ///< ".svg": Origami Simulator colour convention
    ORI_FORMAT_OPX,         ///< ".opx": ORIPA XML
    ORI_FORMAT_CP,          ///< ".cp": ORIPA text, "type x1 y1 x2 y2" per line
} ori_format;

/// Image file formats (ori_render_image_file).
typedef enum ori_image_format {
    ORI_IMAGE_UNKNOWN = 0,
    ORI_IMAGE_SVG, ///< vector (Cairo's SVG surface)
    ORI_IMAGE_PDF, ///< vector (Cairo's PDF surface), one page
    ORI_IMAGE_PNG, ///< raster, 8-bit RGBA, antialiased
} ori_image_format;

/// Mesh file formats (ori_mesh_export).
typedef enum ori_mesh_format {
    ORI_MESH_UNKNOWN = 0,
    ORI_MESH_OBJ,  ///< Wavefront OBJ (text)
    ORI_MESH_STL,  ///< STL (text, 17 significant digits)
    ORI_MESH_PLY,  ///< PLY (text, doubles, vertex colours, FOLD indices)
    ORI_MESH_GLTF, ///< glTF 2.0 JSON with the buffer embedded (base64)
    ORI_MESH_GLB,  ///< glTF 2.0 binary
} ori_mesh_format;

/// What a file format holds.
typedef enum ori_format_kind {
    ORI_FORMAT_KIND_ANY = 0,  ///< in ori_format_find: any kind
    ORI_FORMAT_KIND_PATTERN,  ///< a FOLD document (code: ori_format)
    ORI_FORMAT_KIND_DRAWING,  ///< a crease-pattern drawing of another tool (code: ori_format)
    ORI_FORMAT_KIND_IMAGE,    ///< a picture (code: ori_image_format)
    ORI_FORMAT_KIND_MESH,     ///< a 3D surface (code: ori_mesh_format)
    ORI_FORMAT_KIND_DOCUMENT, ///< in ori_format_find: a pattern or a drawing
} ori_format_kind;

/// A row of the table of file formats: the lower-case extension (no dot), what it holds, the
/// format's code in the enum of its kind, and whether orikin reads and writes it.
typedef struct ori_format_info {
    const char *extension;
    ori_format_kind kind;
    int code;
    bool can_read, can_write;
} ori_format_info;

/// The table of every file format orikin knows (static, count rows into *count, may be NULL).
/// An extension may stand in several rows of different kinds (.svg: drawing and image).
ORI_API const ori_format_info *ori_format_table(int *count);
/// The row of the table for path's extension (after the last '.' of the last component, any
/// case) of the given kind; NULL when none. The *_from_path functions are this lookup.
ORI_API const ori_format_info *ori_format_find(const char *path, ori_format_kind kind);
/// The format of a path by its extension (case-insensitive); ORI_FORMAT_UNKNOWN otherwise.
ORI_API ori_format ori_format_from_path(const char *path);
/// Lower-case name of a format ("svg"); static string.
ORI_API const char *ori_format_name(ori_format format);
/// True for the drawings of other tools (SVG, OPX, CP), which ori_import_text reads.
ORI_API bool ori_format_is_drawing(ori_format format);

/// ori_import_def.gap_rel: close the gaps the drawing's own line width hides (see gap_rel).
#define ORI_IMPORT_GAP_AUTO (-1.0)

/// Import parameters; get them from ori_default_import_def().
typedef struct ori_import_def {
    double weld_rel;       ///< end points (and points on segments) closer than weld_rel × the drawing's diagonal are one point; > 0, default ORI_TOL_IMPORT_WELD_REL
    double gap_rel;        ///< a crease end touching nothing (dangling) within gap_rel × the diagonal of another line is extended onto it (a dangling piece shorter than that, an overshoot, is dropped); 0 = off, at most ORI_IMPORT_GAP_MAX_REL; default ORI_IMPORT_GAP_AUTO: the drawing's line width where the reader knows it (SVG stroke-width: lines that touch on the page are joined; capped to ORI_IMPORT_GAP_MAX_REL), else off
    bool merge_collinear;  ///< remove vertices joining just two collinear edges of the same assignment and angle (drawing artefacts); default true
    bool remove_holes;     ///< drop faces bounded only by B/C edges that have paper on their other side (holes); default true
    bool heal_splits;      ///< when the paper comes out in pieces that lines drawn to meet keep apart (ori_import_stats split_vertex), import again with the smallest doubling of weld_rel up to the drawn line width that joins them (healed_weld_rel); default true (give false with an explicit tolerance)
    int curve_segments;    ///< SVG curves, arcs, circles, ellipses in crease colours: 0 (default) refuses them (a crease is straight); N > 0 flattens each into N straight creases (at most ORI_IMPORT_CURVE_SEGMENTS_MAX), to view and check a curved-crease drawing
    int internal_value;    ///< set by ori_default_import_def; do not change
} ori_import_def;

/// Defaults: weld ORI_TOL_IMPORT_WELD_REL, gaps up to the line width closed, merge collinear,
/// remove holes, split sheets healed within the line width, curves refused.
ORI_API ori_import_def ori_default_import_def(void);

/// What a reader found besides its segments, and (ori_import_file) what planarising them gave:
/// for warnings that say what went wrong and what would fix it.
typedef struct ori_import_stats {
    int segments;            ///< segments returned
    int ignored_elements;    ///< SVG elements with a stroke that is no crease colour; ORIPA aux/cut-model lines
    char ignored_colour[32]; ///< SVG: the first such stroke, as written ("" when none)
    int unsupported_elements;///< SVG elements skipped because orikin does not read them (use, image, text…)
    int flattened_curves;    ///< SVG: curves, arcs, circles and ellipses flattened into straight segments (ori_import_def curve_segments)
    int degenerate_aux;      ///< ORIPA auxiliary lines with a coordinate that is no number (NaN, Infinity): skipped (also in ignored_elements)
    double stroke_width;     ///< SVG: the median drawn width of the crease lines, in drawing units (0: unknown)
    double gap_rel;          ///< ori_import_file: the gap closed (def gap_rel, resolved), × the diagonal
    int gaps_closed;         ///< dangling crease ends extended onto a line (or overshoots dropped)
    double largest_gap_rel;  ///< the largest gap closed, × the diagonal
    int dangling;            ///< crease ends still touching nothing after the import (degree-1 vertices)
    int dangling_example;    ///< one of them (vertex index), ORI_NULL_INDEX when none
    double dangling_gap_rel; ///< how far the farthest of them is from another line, × the diagonal (0 when none within ORI_IMPORT_GAP_MAX_REL)
    int parts;               ///< separate pieces of the result (connected components; 1 is one sheet)
    int part_example;        ///< a vertex of a piece other than the one holding vertex 0, ORI_NULL_INDEX when one piece
    int clipped;             ///< crease edges dropped outside the sheet: drawn past a border (B/C edges) that encloses the rest
    int clipped_faces;       ///< faces those creases made outside the sheet (dropped with them)
    int sheets;              ///< pieces of paper: faces joined across creases (1 for one sheet)
    int split_vertex;        ///< a vertex of a piece that is joined to another by lines but by no crease (the sheet is split and falls apart when folded), ORI_NULL_INDEX when none
    double healed_weld_rel;  ///< the weld tolerance the import used instead of def's to join a split sheet (def heal_splits; within the drawn line width), 0 when not
    int healed_sheets;       ///< the pieces the paper was in before (when healed)
    double split_tolerance_rel; ///< ori_import_file: the smallest weld tolerance (a doubling of def's, up to the line width) that joins the split pieces; 0 when none or not split
    int short_creases_merged;   ///< creases shorter than the gap (the drawn line width) contracted: their two ends made one vertex
} ori_import_stats;

/// Read an SVG document (text of size bytes) into segments: stroke colour → assignment, stroke
/// opacity → fold angle (opacity 1 = ±π, mountain negative). Segments are in FOLD coordinates
/// (y flipped). *segments is library-owned (ori_buffer_free); stats may be NULL. Fails with
/// ORI_ERR_PARSE (XML syntax, bad path/points/number/transform: line of the element) or
/// ORI_ERR_UNSUPPORTED (curves and arcs in a crease-coloured element, with its line).
ORI_API ori_status ori_svg_read_segments(const char *text, size_t size, ori_segment **segments, int *count,
                                         ori_import_stats *stats, ori_error *error);
/// Most straight pieces per curve ori_svg_read_curves and ori_import_def.curve_segments accept.
#define ORI_IMPORT_CURVE_SEGMENTS_MAX 10000
/// ori_svg_read_segments, but with curve_segments > 0 every curve and arc of a crease-coloured
/// path (C S Q T A), circle, ellipse and rounded rect corner becomes curve_segments straight
/// segments of its assignment (an approximation, counted in stats flattened_curves); 0 refuses
/// them as ori_svg_read_segments does. ORI_ERR_ARGUMENT beyond ORI_IMPORT_CURVE_SEGMENTS_MAX.
ORI_API ori_status ori_svg_read_curves(const char *text, size_t size, int curve_segments, ori_segment **segments,
                                       int *count, ori_import_stats *stats, ori_error *error);
/// Read ORIPA .opx (XML) into segments (type 1 → B, 2 → M, 3 → V at ±π; aux and cut-model lines
/// skipped; missing coordinates are 0). Same ownership and errors as ori_svg_read_segments.
ORI_API ori_status ori_opx_read_segments(const char *text, size_t size, ori_segment **segments, int *count,
                                         ori_import_stats *stats, ori_error *error);
/// Read ORIPA .cp text ("type x1 y1 x2 y2" per line; type 0 and 4 are auxiliary and skipped).
/// Fails with ORI_ERR_PARSE naming the line for anything else.
ORI_API ori_status ori_cp_read_segments(const char *text, size_t size, ori_segment **segments, int *count,
                                        ori_import_stats *stats, ori_error *error);
/// Read a file's segments with the reader of its format (SVG, OPX or CP).
ORI_API ori_status ori_read_segments(const char *path, ori_format format, ori_segment **segments, int *count,
                                     ori_import_stats *stats, ori_error *error);

/// Planarise segments into a new flat pattern: overlapping and crossing segments are split and
/// merged (ori_pattern_from_segments) with the weld tolerance of def (NULL = defaults), gaps are
/// closed (an explicit def gap_rel; segments carry no line width, so ORI_IMPORT_GAP_AUTO is off
/// here), collinear pass-through vertices are merged and holes removed as def says, and the
/// pattern is built with faces. *out is NULL on failure; destroy with ori_pattern_destroy.
ORI_API ori_status ori_segments_to_pattern(const ori_segment *segments, int count, const ori_import_def *def,
                                           ori_pattern **out, ori_error *error);
/// Read and planarise a file (format by extension unless format is given); def may be NULL.
/// stats (may be NULL) receives the reader's findings and the diagnosis of the result: gaps
/// closed, crease ends left dangling and separate pieces, each with an example.
ORI_API ori_status ori_import_file(const char *path, ori_format format, const ori_import_def *def,
                                   ori_pattern **out, ori_import_stats *stats, ori_error *error);
/// ori_import_file of a drawing already in memory (text of size bytes, not necessarily
/// NUL-terminated) in the given format (a drawing: ori_format_is_drawing, else
/// ORI_ERR_UNSUPPORTED); the same pattern, stats and errors as reading it from a file.
ORI_API ori_status ori_import_text(const char *text, size_t size, ori_format format, const ori_import_def *def,
                                   ori_pattern **out, ori_import_stats *stats, ori_error *error);

/// SVG export parameters; get them from ori_default_svg_write_def().
typedef struct ori_svg_write_def {
    double stroke_width_rel; ///< stroke width as a fraction of the larger side of the drawing; default 1/300
    double margin_rel;       ///< blank margin around the drawing, fraction of the larger side; default 0.05
    bool full_fold;          ///< write every M and V at opacity 1 (fold flat) whatever its angle; default false
    bool label_faces;        ///< write each face's index (and name) at its centroid, as <text> in a group the reader skips; default false
    bool label_edges;        ///< write each edge's index at its middle (same group); default false
    int internal_value;      ///< set by ori_default_svg_write_def; do not change
} ori_svg_write_def;

/// Defaults: stroke width 1/300 of the drawing, 5 % margin, opacity from the fold angles, no labels.
ORI_API ori_svg_write_def ori_default_svg_write_def(void);

/// The pattern (flat, x and y) as an SVG document that Origami Simulator opens: one <line> per
/// edge in FOLD index order (J edges left out), coloured by assignment, stroke-opacity =
/// |fold angle| / π for M and V (read back as opacity × π: the angle or its neighbouring double;
/// omitted when 1; a crease at 0, e.g. of a generated pattern, has no target and is written
/// at 1, fold flat, so that it shows), y flipped back, a viewBox around the drawing, labels as
/// def says. def may be NULL. Free with ori_buffer_free.
ORI_API char *ori_svg_write(const ori_pattern *pattern, const ori_svg_write_def *def);
/// The pattern as ORIPA .cp text: B → 1, M → 2, V → 3, C → 1, F and U → 4 (auxiliary, which
/// ORIPA and orikin do not read as creases: ori_export_file refuses such patterns); J edges are
/// left out. y flipped back. Free with ori_buffer_free.
ORI_API char *ori_cp_write(const ori_pattern *pattern);
/// The pattern as ORIPA .opx XML with the same type mapping as ori_cp_write (F and U → 0, aux).
/// Free with ori_buffer_free.
ORI_API char *ori_opx_write(const ori_pattern *pattern);
/// Write a flat pattern as SVG (with svg_def, may be NULL), CP or OPX to path atomically (format
/// by extension unless given); what it writes reads back as the same pattern (CP and OPX: C as
/// B). Fails with ORI_ERR_UNSUPPORTED for a folded form, and for CP and OPX when the pattern
/// has F or U creases (ORIPA has no such type; the first one is named).
ORI_API ori_status ori_export_file(const ori_pattern *pattern, ori_format format, const ori_svg_write_def *svg_def,
                                   const char *path, ori_error *error);

/// An extra top-level field for ori_pattern_to_fold_text: its key and its value as JSON text,
/// written verbatim (the caller guarantees valid JSON, e.g. from its own serialiser).
typedef struct ori_fold_field {
    const char *key;  ///< field name, e.g. "orikin:edges_class"
    const char *json; ///< its value as JSON text (non-empty, valid JSON)
} ori_fold_field;

/// A pattern as the text of a new FOLD document, written directly (no JSON tree: time and
/// memory linear in the output): file_spec, file_creator, file_classes, then the extra fields
/// in order, then the pattern's fields. Byte for byte what ori_fold_create, ori_fold_set_custom
/// of the extras and ori_fold_set_pattern followed by ori_fold_to_string give. Free with
/// ori_buffer_free; *size (may be NULL) receives the length.
ORI_API char *ori_pattern_to_fold_text(const ori_pattern *pattern, const ori_fold_field *extra, int extra_count,
                                       size_t *size);
/// ori_pattern_to_fold_text written to path atomically.
ORI_API ori_status ori_pattern_save_fold(const ori_pattern *pattern, const ori_fold_field *extra, int extra_count,
                                         const char *path, ori_error *error);

#ifdef __cplusplus
}
#endif

#endif
