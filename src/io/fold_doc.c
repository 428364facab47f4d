// The FOLD document's container (fold_internal.h): packed arrays, frames of ordered fields, and
// the writers (FOLD layout and compact JSON).
#include "fold_internal.h"

// --- packed arrays -----------------------------------------------------------------------------

static int64_t grow_to(int64_t have, int64_t need)
{
    int64_t cap = have > 16 ? have : 16;
    while (cap < need) cap *= 2;
    return cap;
}

// A packed array with the capacities of its arrays while it is built (the allocation is one of
// these; ori__packed is its first member).
typedef struct ori__pk_full {
    ori__packed pk;
    int64_t val_cap, off_cap, char_cap;
} ori__pk_full;

static ori__pk_full *full(ori__packed *pk) { return (ori__pk_full *)pk; }

ori__packed *ori__pk_new(ori__pk_kind kind, bool ints, int64_t values)
{
    ori__pk_full *f = ori__calloc(1, sizeof *f);
    ori__packed *pk = &f->pk;
    pk->kind = kind;
    pk->width = kind == ORI__PK_NUMS ? 1 : -2; // -2: no entry yet (the first one sets the width)
    pk->first_real = -1;
    int64_t cap = values > 16 ? values : 16;
    if (kind == ORI__PK_STRS) {
        f->char_cap = cap;
        pk->chars = ori__alloc((size_t)cap);
    } else {
        f->val_cap = cap;
        if (ints) pk->i32 = ori__alloc(sizeof(int32_t) * (size_t)cap);
        else pk->f64 = ori__alloc(sizeof(double) * (size_t)cap);
    }
    return pk;
}

static void reserve_values(ori__packed *pk, int64_t need)
{
    ori__pk_full *f = full(pk);
    if (need <= f->val_cap) return;
    f->val_cap = grow_to(f->val_cap, need);
    if (pk->i32) pk->i32 = ori__realloc(pk->i32, sizeof(int32_t) * (size_t)f->val_cap);
    else pk->f64 = ori__realloc(pk->f64, sizeof(double) * (size_t)f->val_cap);
}

void ori__pk_push_int(ori__packed *pk, int32_t x)
{
    reserve_values(pk, pk->nvals + 1);
    if (pk->i32) pk->i32[pk->nvals++] = x;
    else pk->f64[pk->nvals++] = (double)x;
    if (pk->kind == ORI__PK_NUMS) pk->count++;
}

void ori__pk_push_real(ori__packed *pk, double x)
{
    if (pk->i32) { // the first real: the values become doubles
        ori__pk_full *f = full(pk);
        double *d = ori__alloc(sizeof(double) * (size_t)(f->val_cap ? f->val_cap : 1));
        for (int64_t k = 0; k < pk->nvals; ++k) d[k] = pk->i32[k];
        ori__free(pk->i32);
        pk->i32 = NULL;
        pk->f64 = d;
    }
    reserve_values(pk, pk->nvals + 1);
    pk->f64[pk->nvals++] = x;
    if (pk->kind == ORI__PK_NUMS) pk->count++;
}

// Record the end of entry `count` at `end` (values or chars): keeps the uniform width while
// every entry has the same length, else switches to offsets.
static void end_entry(ori__packed *pk, int64_t end)
{
    ori__pk_full *f = full(pk);
    int64_t start = pk->count == 0 ? 0 : (pk->width >= 0 ? pk->count * pk->width : pk->off[pk->count]);
    int64_t len = end - start;
    if (pk->width == -2) pk->width = len;
    if (pk->width >= 0 && len != pk->width) {
        // switch to offsets: count + 1 entries so far, and room for more
        f->off_cap = grow_to(0, pk->count + 2);
        pk->off = ori__alloc(sizeof(int64_t) * (size_t)f->off_cap);
        for (int64_t i = 0; i <= pk->count; ++i) pk->off[i] = i * pk->width;
        pk->width = -1;
    }
    if (pk->width < 0) {
        if (pk->count + 2 > f->off_cap) {
            f->off_cap = grow_to(f->off_cap, pk->count + 2);
            pk->off = ori__realloc(pk->off, sizeof(int64_t) * (size_t)f->off_cap);
        }
        pk->off[pk->count + 1] = end;
    }
    pk->count++;
}

void ori__pk_end_row(ori__packed *pk)
{
    ORI_ASSERT(pk->kind == ORI__PK_ROWS);
    end_entry(pk, pk->nvals);
}

void ori__pk_push_string(ori__packed *pk, const char *s, size_t n)
{
    ORI_ASSERT(pk->kind == ORI__PK_STRS);
    ori__pk_full *f = full(pk);
    if (pk->nchars + (int64_t)n > f->char_cap) {
        f->char_cap = grow_to(f->char_cap, pk->nchars + (int64_t)n);
        pk->chars = ori__realloc(pk->chars, (size_t)f->char_cap);
    }
    if (n) memcpy(pk->chars + pk->nchars, s, n);
    pk->nchars += (int64_t)n;
    end_entry(pk, pk->nchars);
}

void ori__pk_shrink(ori__packed *pk)
{
    ori__pk_full *f = full(pk);
    if (pk->width == -2) pk->width = 0; // no entries
    if (pk->i32 && f->val_cap > pk->nvals) {
        f->val_cap = pk->nvals ? pk->nvals : 1;
        pk->i32 = ori__realloc(pk->i32, sizeof(int32_t) * (size_t)f->val_cap);
    }
    if (pk->f64 && f->val_cap > pk->nvals) {
        f->val_cap = pk->nvals ? pk->nvals : 1;
        pk->f64 = ori__realloc(pk->f64, sizeof(double) * (size_t)f->val_cap);
    }
    if (pk->off && f->off_cap > pk->count + 1) {
        f->off_cap = pk->count + 1;
        pk->off = ori__realloc(pk->off, sizeof(int64_t) * (size_t)f->off_cap);
    }
    if (pk->chars && f->char_cap > pk->nchars) {
        f->char_cap = pk->nchars ? pk->nchars : 1;
        pk->chars = ori__realloc(pk->chars, (size_t)f->char_cap);
    }
}

void ori__packed_free(ori__packed *pk)
{
    if (!pk) return;
    ori__free(pk->off);
    ori__free(pk->i32);
    ori__free(pk->f64);
    ori__free(pk->chars);
    ori__free(full(pk));
}

static json_t *pk_number_json(const ori__packed *pk, int64_t k)
{
    if (pk->i32) return json_integer(pk->i32[k]);
    double x = pk->f64[k];
    // Integer tokens were packed as doubles only within ±2^53, where they are exact.
    if (pk->first_real < 0) return json_integer((json_int_t)x);
    return json_real(x);
}

ori__packed *ori__pk_copy(const ori__packed *pk)
{
    ori__pk_full *f = ori__calloc(1, sizeof *f);
    f->pk = *pk;
    f->pk.off = NULL, f->pk.i32 = NULL, f->pk.f64 = NULL, f->pk.chars = NULL;
    if (pk->off) {
        f->off_cap = pk->count + 1;
        f->pk.off = ori__alloc(sizeof(int64_t) * (size_t)f->off_cap);
        memcpy(f->pk.off, pk->off, sizeof(int64_t) * (size_t)f->off_cap);
    }
    f->val_cap = pk->nvals ? pk->nvals : 1;
    if (pk->i32) {
        f->pk.i32 = ori__alloc(sizeof(int32_t) * (size_t)f->val_cap);
        memcpy(f->pk.i32, pk->i32, sizeof(int32_t) * (size_t)pk->nvals);
    } else if (pk->f64) {
        f->pk.f64 = ori__alloc(sizeof(double) * (size_t)f->val_cap);
        memcpy(f->pk.f64, pk->f64, sizeof(double) * (size_t)pk->nvals);
    }
    if (pk->chars) {
        f->char_cap = pk->nchars ? pk->nchars : 1;
        f->pk.chars = ori__alloc((size_t)f->char_cap);
        memcpy(f->pk.chars, pk->chars, (size_t)pk->nchars);
    }
    return &f->pk;
}

json_t *ori__pk_to_json(const ori__packed *pk)
{
    json_t *arr = json_array();
    for (int64_t i = 0; i < pk->count; ++i) {
        if (pk->kind == ORI__PK_NUMS) {
            json_array_append_new(arr, pk_number_json(pk, i));
        } else if (pk->kind == ORI__PK_ROWS) {
            json_t *row = json_array();
            int64_t s = ori__pk_start(pk, i), n = ori__pk_len(pk, i);
            for (int64_t k = 0; k < n; ++k) json_array_append_new(row, pk_number_json(pk, s + k));
            json_array_append_new(arr, row);
        } else {
            json_array_append_new(arr, json_stringn(pk->chars + ori__pk_start(pk, i), (size_t)ori__pk_len(pk, i)));
        }
    }
    return arr;
}

// --- frames and fields -------------------------------------------------------------------------

ori_fold *ori__doc_new(void)
{
    ori_fold *doc = ori__calloc(1, sizeof *doc);
    ori__doc_add_frame(doc);
    return doc;
}

int ori__doc_add_frame(ori_fold *doc)
{
    ORI__RESERVE(doc->frames, doc->frame_cap, doc->frame_count + 1);
    memset(&doc->frames[doc->frame_count], 0, sizeof doc->frames[0]);
    return doc->frame_count++;
}

ori__field *ori__frame_find(const ori__frame *fr, const char *key)
{
    for (int i = 0; i < fr->count; ++i)
        if (strcmp(fr->fields[i].key, key) == 0) return &fr->fields[i];
    return NULL;
}

static void field_clear_value(ori__field *f)
{
    json_decref(f->json);
    ori__packed_free(f->pk);
    f->json = NULL;
    f->pk = NULL;
}

void ori__frame_set(ori__frame *fr, const char *key, json_t *json, ori__packed *pk)
{
    ori__field *f = ori__frame_find(fr, key);
    if (!f) {
        ORI__RESERVE(fr->fields, fr->cap, fr->count + 1);
        f = &fr->fields[fr->count++];
        f->key = ori__strdup(key);
        f->json = NULL;
        f->pk = NULL;
    } else {
        field_clear_value(f);
    }
    f->json = json;
    f->pk = pk;
}

void ori__frame_del(ori__frame *fr, const char *key)
{
    ori__field *f = ori__frame_find(fr, key);
    if (!f) return;
    field_clear_value(f);
    ori__free(f->key);
    int i = (int)(f - fr->fields);
    memmove(fr->fields + i, fr->fields + i + 1, sizeof *f * (size_t)(fr->count - i - 1));
    fr->count--;
}

static void frame_free(ori__frame *fr)
{
    for (int i = 0; i < fr->count; ++i) {
        field_clear_value(&fr->fields[i]);
        ori__free(fr->fields[i].key);
    }
    ori__free(fr->fields);
    memset(fr, 0, sizeof *fr);
}

void ori__doc_drop_frames(ori_fold *doc)
{
    for (int k = 1; k < doc->frame_count; ++k) frame_free(&doc->frames[k]);
    doc->frame_count = 1;
    ori__frame_del(&doc->frames[0], "file_frames");
}

void ori_fold_destroy(ori_fold *doc)
{
    if (!doc) return;
    for (int k = 0; k < doc->frame_count; ++k) frame_free(&doc->frames[k]);
    ori__free(doc->frames);
    ori__free(doc);
}

// --- writers -------------------------------------------------------------------------------------

static void indent(ori__text *t, int n)
{
    for (int i = 0; i < n; ++i) ori__text_puts(t, "  ");
}

static void pk_write_number(ori__text *t, const ori__packed *pk, int64_t k)
{
    if (pk->i32) {
        ori__text_int(t, pk->i32[k]);
        return;
    }
    // Integral values below 2^53 as integers: integer tokens beyond int32 stay integers, and
    // the rest is what the shortest form writes anyway.
    double x = pk->f64[k];
    if (x == floor(x) && fabs(x) < 9007199254740992.0) ori__text_int(t, (long long)x);
    else ori__text_real(t, x);
}

static void pk_write_entry(ori__text *t, const ori__packed *pk, int64_t i)
{
    if (pk->kind == ORI__PK_NUMS) {
        pk_write_number(t, pk, i);
    } else if (pk->kind == ORI__PK_ROWS) {
        int64_t s = ori__pk_start(pk, i), n = ori__pk_len(pk, i);
        ori__text_puts(t, "[");
        for (int64_t k = 0; k < n; ++k) {
            if (k) ori__text_puts(t, ",");
            pk_write_number(t, pk, s + k);
        }
        ori__text_puts(t, "]");
    } else {
        ori__text_json_string(t, pk->chars + ori__pk_start(pk, i), (size_t)ori__pk_len(pk, i));
    }
}

static void pk_write(ori__text *t, const ori__packed *pk, bool pretty, int depth)
{
    if (pretty && pk->kind == ORI__PK_ROWS && pk->count > 0) { // arrays of arrays: one entry per line
        ori__text_puts(t, "[\n");
        for (int64_t i = 0; i < pk->count; ++i) {
            indent(t, depth + 1);
            pk_write_entry(t, pk, i);
            ori__text_puts(t, i + 1 < pk->count ? ",\n" : "\n");
        }
        indent(t, depth);
        ori__text_puts(t, "]");
        return;
    }
    ori__text_puts(t, "[");
    for (int64_t i = 0; i < pk->count; ++i) {
        if (i) ori__text_puts(t, ",");
        pk_write_entry(t, pk, i);
    }
    ori__text_puts(t, "]");
}

static void frame_write(const ori_fold *doc, int k, ori__text *t, int depth);

static void frames_write(const ori_fold *doc, ori__text *t, int depth, bool pretty)
{
    if (doc->frame_count <= 1) {
        ori__text_puts(t, "[]");
        return;
    }
    ori__text_puts(t, pretty ? "[\n" : "[");
    for (int k = 1; k < doc->frame_count; ++k) {
        if (pretty) {
            indent(t, depth + 1);
            frame_write(doc, k, t, depth + 1);
            ori__text_puts(t, k + 1 < doc->frame_count ? ",\n" : "\n");
        } else {
            if (k > 1) ori__text_puts(t, ",");
            ori__text_puts(t, "{");
            const ori__frame *fr = &doc->frames[k];
            for (int i = 0; i < fr->count; ++i) {
                if (i) ori__text_puts(t, ",");
                ori__text_json_string(t, fr->fields[i].key, strlen(fr->fields[i].key));
                ori__text_puts(t, ":");
                ori__field_write_compact(doc, &fr->fields[i], t);
            }
            ori__text_puts(t, "}");
        }
    }
    if (pretty) indent(t, depth);
    ori__text_puts(t, "]");
}

static void frame_write(const ori_fold *doc, int k, ori__text *t, int depth)
{
    const ori__frame *fr = &doc->frames[k];
    if (fr->count == 0) {
        ori__text_puts(t, "{}");
        return;
    }
    ori__text_puts(t, "{\n");
    for (int i = 0; i < fr->count; ++i) {
        const ori__field *f = &fr->fields[i];
        indent(t, depth + 1);
        ori__text_json_string(t, f->key, strlen(f->key));
        ori__text_puts(t, ": ");
        if (f->pk) pk_write(t, f->pk, true, depth + 1);
        else if (f->json) ori__json_write_value_pretty(t, f->key, f->json, depth + 1);
        else frames_write(doc, t, depth + 1, true);
        ori__text_puts(t, i + 1 < fr->count ? ",\n" : "\n");
    }
    indent(t, depth);
    ori__text_puts(t, "}");
}

// A generous size of the packed arrays' text (digits and separators), reserved at once so that
// a million-entry document is not copied by the buffer's doublings.
static size_t doc_text_guess(const ori_fold *doc)
{
    size_t n = 4096;
    for (int k = 0; k < doc->frame_count; ++k)
        for (int i = 0; i < doc->frames[k].count; ++i) {
            const ori__packed *pk = doc->frames[k].fields[i].pk;
            if (!pk) continue;
            n += (size_t)pk->nvals * (pk->i32 ? 8 : 20) + (size_t)pk->count * 8 + (size_t)pk->nchars * 2;
        }
    return n;
}

void ori__doc_write(const ori_fold *doc, ori__text *t)
{
    ori__text_reserve(t, doc_text_guess(doc));
    frame_write(doc, 0, t, 0);
    ori__text_puts(t, "\n");
}

void ori__field_write_compact(const ori_fold *doc, const ori__field *f, ori__text *t)
{
    if (f->pk) pk_write(t, f->pk, false, 0);
    else if (f->json) ori__json_write_compact_to(t, f->json);
    else frames_write(doc, t, 0, false);
}
