// Shared pieces of the importers and exporters (svg.c, oripa.c, import.c, export.c,
// fold_text.c): the growing segment list and statistics, number scanning that never accepts
// "inf", "nan" or hexadecimal, the XML entry point and a text buffer.
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

// Reset stats (may be NULL).
void ori__stats_clear(ori_import_stats *stats);

// Parse XML text into a tree without network access or entity substitution; the first error
// with its line and column (svg.c). *doc is NULL on failure; free it with xmlFreeDoc.
struct _xmlDoc;
ori_status ori__xml_parse(const char *text, size_t size, const char *what, struct _xmlDoc **doc, ori_error *error);

// A growing text buffer for the writers (text.c); data is NUL-terminated once anything (or
// nothing, via ori__text_reserve) was written, and owned by the caller.
typedef struct ori__text {
    char *data;
    size_t len, cap;
} ori__text;
void ori__text_reserve(ori__text *t, size_t extra);
void ori__text_put(ori__text *t, const char *s, size_t n);
void ori__text_puts(ori__text *t, const char *s);
void ori__text_printf(ori__text *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
// A number in the shortest decimal that reads back exactly (the FOLD writer's format).
void ori__text_real(ori__text *t, double x);

#endif
