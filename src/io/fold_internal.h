// The FOLD document in memory (fold_doc.c), its reader (fold_parse.c) and its users (fold.c).
//
// A FOLD file is mostly a few big arrays of numbers (vertices_coords, edges_vertices,
// faces_vertices, edges_foldAngle, …) and strings (edges_assignment). Held as a general JSON
// tree they cost 20–45 times the file (one allocated node per number); here each top-level or
// frame field that is an array of numbers, an array of arrays of numbers or an array of strings
// is packed into flat typed arrays (4 or 8 bytes a number), and everything else stays a jansson
// value, so that every field orikin does not interpret survives a round trip.
//
// The document is a list of frames (frame 0 = the top level without file_frames); each frame is
// an ordered list of fields. Frame 0 holds a marker field "file_frames" (no value) where the
// key stood, so that the key order of the file is kept on output.
#ifndef ORI_FOLD_INTERNAL_H
#define ORI_FOLD_INTERNAL_H

#include <orikin/fold.h>

#include "io_internal.h"

typedef enum ori__pk_kind {
    ORI__PK_NUMS, // [n, n, …]
    ORI__PK_ROWS, // [[n, …], [n, …], …]
    ORI__PK_STRS, // ["s", "s", …]
} ori__pk_kind;

// A packed array. Entries are numbers (NUMS), rows of numbers (ROWS) or strings (STRS).
typedef struct ori__packed {
    ori__pk_kind kind;
    int64_t count;      // entries
    int64_t width;      // ROWS/STRS: the length of every entry when they are all alike, else -1
    int64_t *off;       // ROWS/STRS with width < 0: count + 1 offsets into the values / chars
    int64_t nvals;      // numbers held (NUMS: count)
    int32_t *i32;       // the numbers when every one is an integer token within int32, else
    double *f64;        // the numbers as doubles (integer tokens within ±2^53 only)
    int64_t first_real; // first entry holding a number written with a fraction or exponent, or -1
    char *chars;        // STRS: the bytes of every string, one after the other (valid UTF-8, no NUL)
    int64_t nchars;
} ori__packed;

// One field of a frame: a packed array, a JSON value, or (frame 0's "file_frames") neither.
typedef struct ori__field {
    char *key;
    json_t *json;
    ori__packed *pk;
} ori__field;

typedef struct ori__frame {
    ori__field *fields;
    int count, cap;
} ori__frame;

struct ori_fold {
    ori__frame *frames; // frame 0 is the top level
    int frame_count, frame_cap;
};

// --- packed arrays (fold_doc.c) ---------------------------------------------------------------

void ori__packed_free(ori__packed *pk);
// Number k (0 ≤ k < nvals) as a double.
static inline double ori__pk_num(const ori__packed *pk, int64_t k) { return pk->i32 ? (double)pk->i32[k] : pk->f64[k]; }
// Row / string i: its first value (or byte) and its length.
static inline int64_t ori__pk_start(const ori__packed *pk, int64_t i) { return pk->width >= 0 ? i * pk->width : pk->off[i]; }
static inline int64_t ori__pk_len(const ori__packed *pk, int64_t i)
{
    return pk->width >= 0 ? pk->width : pk->off[i + 1] - pk->off[i];
}
// A new empty array with room for `values` numbers (STRS: bytes), grown as the pushes need;
// ints: numbers held as int32 until the first real (then all become doubles).
ori__packed *ori__pk_new(ori__pk_kind kind, bool ints, int64_t values);
// Append a number (to NUMS, or to the open row of ROWS).
void ori__pk_push_int(ori__packed *pk, int32_t x);
void ori__pk_push_real(ori__packed *pk, double x);
// ROWS: close the row of the numbers pushed since the last call. STRS: append a string.
void ori__pk_end_row(ori__packed *pk);
void ori__pk_push_string(ori__packed *pk, const char *s, size_t n);
// Give the arrays their final sizes (after the last push).
void ori__pk_shrink(ori__packed *pk);
// A copy.
ori__packed *ori__pk_copy(const ori__packed *pk);
// The same content as a jansson value (for fields that must become general JSON).
json_t *ori__pk_to_json(const ori__packed *pk);

// --- frames and fields (fold_doc.c) -----------------------------------------------------------

ori_fold *ori__doc_new(void);
// Append an empty frame; returns its number.
int ori__doc_add_frame(ori_fold *doc);
ori__field *ori__frame_find(const ori__frame *fr, const char *key);
// Set a field (replacing one of the same key in place, else appended); takes ownership of the
// value (exactly one of json and pk; both NULL only for frame 0's "file_frames" marker).
void ori__frame_set(ori__frame *fr, const char *key, json_t *json, ori__packed *pk);
void ori__frame_del(ori__frame *fr, const char *key);
// Remove frames 1 … and the file_frames marker.
void ori__doc_drop_frames(ori_fold *doc);

// --- text -------------------------------------------------------------------------------------

// The document as FOLD text (one key per line, arrays of arrays one entry per line, numbers in
// shortest exact form): the layout of ori__json_write_pretty.
void ori__doc_write(const ori_fold *doc, ori__text *t);
// One field's value (or the file_frames array, for frame 0's marker) as compact JSON.
void ori__field_write_compact(const ori_fold *doc, const ori__field *f, ori__text *t);
// A jansson value as compact JSON.
void ori__json_write_compact_to(ori__text *t, const json_t *v);
// A jansson value in the pretty layout at indentation depth (json_write.c).
void ori__json_write_value_pretty(ori__text *t, const char *key, const json_t *v, int depth);

// Parse FOLD text (a UTF-8 byte-order mark skipped): JSON syntax errors with line and column,
// duplicate keys refused, the top level an object and file_frames an array of objects.
ori_status ori__doc_parse(const char *text, size_t size, ori_fold **out, ori_error *error);
// Parse one JSON value (ori_fold_set_custom): an array that packs into *pk, else into *json.
ori_status ori__doc_parse_value(const char *text, size_t size, json_t **json, ori__packed **pk, ori_error *error);

#endif
