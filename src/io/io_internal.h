// Helpers shared by the file formats in src/io: the custom FOLD keys, the text buffer and
// number writers behind every text output (FOLD, JSON, SVG, CP, OPX), and the JSON layout.
#ifndef ORI_IO_INTERNAL_H
#define ORI_IO_INTERNAL_H

#include <orikin/formats.h>

#include "../core/json_internal.h"

// Custom FOLD keys written by orikin.
#define ORI__KEY_FACES_NAME "orikin:faces_name"
#define ORI__KEY_FACE_TREE "orikin:face_tree"

// A growing text buffer (text.c); data is NUL-terminated once anything (or nothing, via
// ori__text_reserve) was written, and owned by the caller (ori__free).
// The extension ("png") of the table's row of that kind and code (formats.c); "unknown".
const char *ori__format_name(ori_format_kind kind, int code);

typedef struct ori__text {
    char *data;
    size_t len, cap;
} ori__text;
void ori__text_reserve(ori__text *t, size_t extra);
// Appends n bytes (inline: the writers append a few bytes at a time, millions of times).
static inline void ori__text_put(ori__text *t, const char *s, size_t n)
{
    if (t->len + n + 1 > t->cap) ori__text_reserve(t, n);
    memcpy(t->data + t->len, s, n);
    t->len += n;
    t->data[t->len] = '\0';
}
// Appends a NUL-terminated string (a literal's length is known at compile time once inlined).
static inline void ori__text_puts(ori__text *t, const char *s) { ori__text_put(t, s, strlen(s)); }
void ori__text_printf(ori__text *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
// An integer in decimal.
void ori__text_int(ori__text *t, long long x);
// A number in the shortest decimal that reads back exactly (ori__format_double).
void ori__text_real(ori__text *t, double x);
// A JSON string literal of the n bytes at s: quoted, with '"', '\\' and control characters escaped.
void ori__text_json_string(ori__text *t, const char *s, size_t n);

// Shortest decimal text that reads back as exactly x (at most 17 significant digits; ±0 is "0").
// Returns the text's length.
size_t ori__format_double(double x, char *buf, size_t size);
// The shortest digits of a finite nonzero x that read back exactly (shortest.cc, double-
// conversion): digits (18 bytes, not terminated) d1…dn with *length = n, x = ±0.d1…dn × 10^*point.
// Returns 1 when x is negative.
int ori__shortest_digits(double x, char *digits, int *length, int *point);

// A JSON real for a finite double (−0 written as 0).
json_t *ori__json_number(double x);
// FOLD-style JSON text: one key per line at the top level and in frames, arrays of arrays one
// entry per line, everything else compact. Allocated with ori__alloc.
char *ori__json_write_pretty(const json_t *root);
// One-line JSON text with a trailing newline. Allocated with ori__alloc.
char *ori__json_write_compact(const json_t *root);

#endif
