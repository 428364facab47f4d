// Helpers shared by the file formats in src/io.
#ifndef ORI_IO_INTERNAL_H
#define ORI_IO_INTERNAL_H

#include <jansson.h>

#include "../core/core_internal.h"

// Custom FOLD keys written by orikin.
#define ORI__KEY_FACES_NAME "orikin:faces_name"
#define ORI__KEY_FACE_TREE "orikin:face_tree"

// A JSON real for a finite double (−0 written as 0).
json_t *ori__json_number(double x);
// Degrees within ORI_TOL_PRINT_DEG of an integer become that integer; −0 becomes 0.
double ori__clean_degrees(double deg);
// Shortest decimal text that reads back as exactly x (at most 17 significant digits).
void ori__format_double(double x, char *buf, size_t size);
// FOLD-style JSON text: one key per line at the top level and in frames, arrays of arrays one
// entry per line, everything else compact. Allocated with ori__alloc.
char *ori__json_write_pretty(const json_t *root);
// One-line JSON text with a trailing newline. Allocated with ori__alloc.
char *ori__json_write_compact(const json_t *root);

#endif
