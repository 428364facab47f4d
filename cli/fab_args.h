// Shared pieces of the fabrication commands (fab, tolerance): lengths with a unit on the
// command line and the length unit of a FOLD file.
#ifndef ORI_CLI_FAB_ARGS_H
#define ORI_CLI_FAB_ARGS_H

#include <orikin/fab.h>

#include "cli.h"

// A length "20", "20um", "0.5mm", "1e-6m" (m, cm, mm, um, µm, nm, in, pt): *value the number,
// *unit_m the metres of its unit (0 for a bare number). False when malformed or negative.
bool fab_parse_length(const char *s, double *value, double *unit_m);
// A parsed length in metres: with a unit as given, bare in the fallback unit (metres per unit).
double fab_length_m(double value, double unit_m, double fallback_m);
// Metres per coordinate unit of frame 0 of doc (frame_unit); false when unitless or unknown.
bool fab_file_unit(const ori_fold *doc, double *meters);

#endif
