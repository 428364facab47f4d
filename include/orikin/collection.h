/// orikin collection: reusable crease patterns ("composites") defined in a face's normalised
/// coordinates and applied to any face (thesis ch. 7.2.1, 9.3: DiagonalL, DiagonalR, MiddleH,
/// MiddleV and user composites saved as files).
///
/// Functions: ori_collection_builtin_count, ori_collection_builtin_name,
/// ori_collection_builtin_summary, ori_composite_builtin, ori_composite_load_string,
/// ori_composite_load_file, ori_composite_destroy, ori_composite_name,
/// ori_composite_crease_count, ori_composite_crease_at, ori_pattern_apply_composite.
///
/// Normalised coordinates: (0, 0) is the lower-left and (1, 1) the upper-right corner of the
/// target face's axis-aligned bounding box, so a pattern scales to any face.
#ifndef ORIKIN_COLLECTION_H
#define ORIKIN_COLLECTION_H

#include "authoring.h"
#include "base.h"
#include "math.h"
#include "pattern.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Opaque composite: a named list of creases in normalised coordinates.
typedef struct ori_composite ori_composite;

/// One crease of a composite, in normalised coordinates, directed a→b (child 1 of a split
/// face lies left of it).
typedef struct ori_composite_crease {
    ori_v2 a, b;
    bool infinite;             ///< the whole line through a and b (clipped to the face) or the segment
    bool has_assignment;       ///< false: the caller's assignment (or U) applies
    ori_assignment assignment; ///< M, V, F or U when has_assignment
} ori_composite_crease;

/// Number of built-in composites.
ORI_API int ori_collection_builtin_count(void);
/// Name of built-in i ("diagonal-left", …); static string.
ORI_API const char *ori_collection_builtin_name(int i);
/// One-line description of built-in i; static string.
ORI_API const char *ori_collection_builtin_summary(int i);

/// The built-in composite called name. ORI_ERR_NOT_FOUND for an unknown name. Destroy with
/// ori_composite_destroy.
ORI_API ori_status ori_composite_builtin(const char *name, ori_composite **out, ori_error *error);
/// Parse a composite from JSON text (format in docs/authoring.md). Errors carry the line and
/// column of the offending value. *out is NULL on failure.
ORI_API ori_status ori_composite_load_string(const char *text, size_t size, ori_composite **out,
                                             ori_error *error);
/// Parse a composite from a JSON file.
ORI_API ori_status ori_composite_load_file(const char *path, ori_composite **out, ori_error *error);
/// Destroy a composite; NULL is a no-op.
ORI_API void ori_composite_destroy(ori_composite *composite);

/// The composite's name ("" when the file gives none); valid while the composite lives.
ORI_API const char *ori_composite_name(const ori_composite *composite);
/// Number of creases (after expanding references to built-ins).
ORI_API int ori_composite_crease_count(const ori_composite *composite);
/// Crease i by value.
ORI_API ori_composite_crease ori_composite_crease_at(const ori_composite *composite, int i);

/// Apply a composite to face `face`: its creases are mapped from normalised coordinates to the
/// face's bounding box and applied to the face's region in order (ori_pattern_apply_creases).
/// assignment, when not NULL, overrides every crease's own; creases without one get U.
/// Creases start flat (fold angle 0).
ORI_API ori_status ori_pattern_apply_composite(ori_pattern *pattern, const ori_composite *composite, int face,
                                               const ori_assignment *assignment, ori_apply_result *out,
                                               ori_error *error);

#ifdef __cplusplus
}
#endif

#endif
