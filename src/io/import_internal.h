// Shared pieces of the drawing importers (svg.c, oripa.c, import.c): the growing segment list
// and statistics, number scanning that never accepts "inf", "nan" or hexadecimal, and the XML
// entry point. (The writers' text buffer is in io_internal.h.)
#ifndef ORI_IMPORT_INTERNAL_H
#define ORI_IMPORT_INTERNAL_H

#include <orikin/formats.h>

#include "../core/core_internal.h"

typedef struct ori__seg_list {
    ori_segment *items;
    int count, cap;
} ori__seg_list;

// Append segment a→b given in drawing coordinates (y down): stored with y flipped (y up).
// Exactly coincident end points (nothing drawn) are dropped.
void ori__seg_push(ori__seg_list *list, double ax, double ay, double bx, double by, ori_assignment asg,
                   double fold_angle_rad);

// Scan a decimal number (sign, digits, fraction, exponent; no inf/nan/hex) at s. Returns the
// number of characters consumed (0 when there is no number) and the value in *out.
size_t ori__scan_number(const char *s, double *out);

// The start of a reader ori_X_read_segments: its outputs cleared (stats may be NULL).
void ori__reader_begin(ori_segment **segments, int *count, ori_import_stats *stats, ori_error *error);
// The end of a reader: on success the segments and the statistics found (their segment count
// set) are handed out; on failure the list is freed. Returns st.
ori_status ori__reader_end(ori_status st, ori__seg_list *segs, ori_import_stats *found, ori_segment **segments,
                           int *count, ori_import_stats *stats);

// Parse XML text into a tree without network access or entity substitution; the first error
// with its line and column (svg.c). *doc is NULL on failure; free it with xmlFreeDoc.
struct _xmlDoc;
ori_status ori__xml_parse(const char *text, size_t size, const char *what, struct _xmlDoc **doc, ori_error *error);

#endif
