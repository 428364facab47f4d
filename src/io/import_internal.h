// Shared pieces of the importers (svg.c, oripa.c, import.c): the growing segment list and
// statistics, and number scanning that never accepts "inf", "nan" or hexadecimal.
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

#endif
