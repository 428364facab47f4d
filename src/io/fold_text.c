// A pattern written straight to FOLD text, without building a JSON tree: the layout and number
// formatting of json_write.c (one key per line, arrays of arrays one entry per line, numbers in
// shortest exact form), so that a generated or imported million-face pattern costs its text
// and nothing more. tests/test_formats.c compares it byte for byte with the jansson path.
#include <orikin/formats.h>

#include "../pattern/pattern_internal.h"
#include "io_internal.h"

static void puts_(ori__text *b, const char *s) { ori__text_puts(b, s); }
static void put_string(ori__text *b, const char *s) { ori__text_json_string(b, s, strlen(s)); }

static void key(ori__text *b, const char *k, bool *first)
{
    puts_(b, *first ? "  " : ",\n  ");
    *first = false;
    put_string(b, k);
    puts_(b, ": ");
}

// Arrays of arrays: "[\n    item,\n    item\n  ]", or "[]" when empty.
static void rows_open(ori__text *b, int n) { puts_(b, n ? "[\n    " : "[]"); }
static void rows_next(ori__text *b, int row, int n) { puts_(b, row + 1 < n ? ",\n    " : "\n  ]"); }

static void put_coords(ori__text *b, const ori_pattern *p, int v, bool three)
{
    puts_(b, "[");
    ori__text_real(b, p->vertices[v].x);
    puts_(b, ",");
    ori__text_real(b, p->vertices[v].y);
    if (three) {
        puts_(b, ",");
        ori__text_real(b, p->vertices[v].z);
    }
    puts_(b, "]");
}

static void put_face(ori__text *b, const ori_pattern *p, int f)
{
    puts_(b, "[");
    for (int k = p->face_offsets[f]; k < p->face_offsets[f + 1]; ++k) {
        if (k > p->face_offsets[f]) puts_(b, ",");
        ori__text_int(b, p->face_vertices[k]);
    }
    puts_(b, "]");
}

static bool any_face_name(const ori_pattern *p)
{
    if (!p->face_names) return false;
    for (int f = 0; f < p->face_count; ++f)
        if (p->face_names[f][0]) return true;
    return false;
}

char *ori_pattern_to_fold_text(const ori_pattern *p, const ori_fold_field *extra, int extra_count, size_t *size)
{
    ORI_ASSERT(p && extra_count >= 0 && (extra || extra_count == 0));
    ori__text b = {NULL, 0, 0};
    // Generous sizes (17-digit coordinates, 7-digit indices) so that one allocation is enough.
    size_t guess = 512 + 52 * (size_t)p->vertex_count + 36 * (size_t)p->edge_count +
                   8 * ((size_t)p->face_vertex_count + (size_t)p->face_count);
    for (int i = 0; i < extra_count; ++i) guess += strlen(extra[i].key) + strlen(extra[i].json) + 8;
    ori__text_reserve(&b, guess);
    bool first = true;
    puts_(&b, "{\n");
    key(&b, "file_spec", &first);
    ori__text_real(&b, 1.2);
    key(&b, "file_creator", &first);
    put_string(&b, "orikin");
    key(&b, "file_classes", &first);
    puts_(&b, "[\"singleModel\"]");
    for (int i = 0; i < extra_count; ++i) {
        ORI_ASSERT(extra[i].key && extra[i].json && extra[i].json[0]);
        key(&b, extra[i].key, &first);
        puts_(&b, extra[i].json);
    }
    bool three = ori_pattern_is_3d(p);
    key(&b, "vertices_coords", &first);
    rows_open(&b, p->vertex_count);
    for (int v = 0; v < p->vertex_count; ++v) {
        put_coords(&b, p, v, three);
        rows_next(&b, v, p->vertex_count);
    }
    key(&b, "edges_vertices", &first);
    rows_open(&b, p->edge_count);
    for (int e = 0; e < p->edge_count; ++e) {
        puts_(&b, "[");
        ori__text_int(&b, p->edges[e].v[0]);
        puts_(&b, ",");
        ori__text_int(&b, p->edges[e].v[1]);
        puts_(&b, "]");
        rows_next(&b, e, p->edge_count);
    }
    key(&b, "edges_assignment", &first);
    puts_(&b, "[");
    for (int e = 0; e < p->edge_count; ++e) {
        char s[6] = {',', '"', ori_assignment_to_char(p->edges[e].assignment), '"', '\0', '\0'};
        puts_(&b, e ? s : s + 1);
    }
    puts_(&b, "]");
    if (p->has_fold_angles) {
        key(&b, "edges_foldAngle", &first);
        puts_(&b, "[");
        for (int e = 0; e < p->edge_count; ++e) {
            if (e) puts_(&b, ",");
            ori__text_real(&b, ori_rad_to_deg_output(p->edges[e].fold_angle_rad));
        }
        puts_(&b, "]");
    }
    if (p->face_count > 0) {
        key(&b, "faces_vertices", &first);
        rows_open(&b, p->face_count);
        for (int f = 0; f < p->face_count; ++f) {
            put_face(&b, p, f);
            rows_next(&b, f, p->face_count);
        }
    }
    if (any_face_name(p)) {
        key(&b, ORI__KEY_FACES_NAME, &first);
        puts_(&b, "[");
        for (int f = 0; f < p->face_count; ++f) {
            if (f) puts_(&b, ",");
            if (p->face_names[f][0]) put_string(&b, p->face_names[f]);
            else puts_(&b, "null");
        }
        puts_(&b, "]");
    }
    if (p->tree_count > 0) {
        key(&b, ORI__KEY_FACE_TREE, &first);
        rows_open(&b, p->tree_count);
        for (int i = 0; i < p->tree_count; ++i) {
            puts_(&b, "{\"name\":");
            put_string(&b, p->tree[i].name);
            puts_(&b, ",\"parent\":");
            ori__text_int(&b, p->tree[i].parent);
            puts_(&b, "}");
            rows_next(&b, i, p->tree_count);
        }
    }
    puts_(&b, "\n}\n");
    if (size) *size = b.len;
    return b.data;
}

ori_status ori_pattern_save_fold(const ori_pattern *p, const ori_fold_field *extra, int extra_count, const char *path,
                                 ori_error *error)
{
    ORI_ASSERT(p && path);
    size_t n;
    char *text = ori_pattern_to_fold_text(p, extra, extra_count, &n);
    ori_status st = ori_file_write_atomic(path, text, n, error);
    ori__free(text);
    return st;
}
