// JSON documents read with jansson (FOLD files in src/io, crease collections in src/axioms,
// fold sequences in src/sequence): one parse entry point with the library's error reporting.
#ifndef ORI_JSON_INTERNAL_H
#define ORI_JSON_INTERNAL_H

#include <jansson.h>

#include "core_internal.h"

// Parse size bytes of JSON text, a leading UTF-8 byte-order mark skipped (flags as for
// json_loadb: JSON_REJECT_DUPLICATES, JSON_DECODE_ANY ...). Returns the root (json_decref it),
// or NULL after filling *error with ORI_ERR_PARSE, jansson's message and the line and column of
// the first error (1-based).
json_t *ori__json_parse(const char *text, size_t size, size_t flags, ori_error *error);

#endif
