// libFuzzer target for the FOLD reader: parse, read every frame's pattern (with validation, and
// planarised where its edges cross or overlap, as the CLI reads it), write it back and re-read
// the output without planarising (what orikin writes is planar). The reader is checked against jansson as an independent
// JSON parser: they agree on what is valid JSON, and what orikin writes back is the same JSON
// (numbers compared by value). Any crash, leak, disagreement or sanitizer report is a bug.
#include <jansson.h>
#include <orikin/orikin.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

// JSON equality with numbers compared by value (orikin writes 1.0 as 1).
static bool same_json(const json_t *a, const json_t *b)
{
    if (json_is_number(a) && json_is_number(b)) return json_number_value(a) == json_number_value(b);
    if (json_typeof(a) != json_typeof(b)) return false;
    if (json_is_array(a)) {
        if (json_array_size(a) != json_array_size(b)) return false;
        for (size_t i = 0; i < json_array_size(a); ++i)
            if (!same_json(json_array_get(a, i), json_array_get(b, i))) return false;
        return true;
    }
    if (json_is_object(a)) {
        if (json_object_size(a) != json_object_size(b)) return false;
        const char *key;
        json_t *v;
        json_object_foreach((json_t *)a, key, v)
        {
            json_t *w = json_object_get(b, key);
            if (!w || !same_json(v, w)) return false;
        }
        return true;
    }
    return json_equal((json_t *)a, (json_t *)b);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    ori_fold *doc = NULL;
    ori_error err;
    ori_status st = ori_fold_load_string((const char *)data, size, &doc, &err);
    if (st != ORI_OK && (err.line < 1 || err.column < 1) && st == ORI_ERR_PARSE) abort(); // syntax errors have a position
    // The same verdict on the JSON as jansson (a byte-order mark is not JSON to jansson; jansson
    // lets a NUL byte pass after a number, which RFC 8259 and orikin do not).
    size_t skip = size >= 3 && memcmp(data, "\xEF\xBB\xBF", 3) == 0 ? 3 : 0;
    json_error_t je;
    json_t *ref = json_loadb((const char *)data + skip, size - skip, JSON_REJECT_DUPLICATES, &je);
    bool nul = memchr(data, 0, size) != NULL;
    if (!nul && (ref != NULL) == (st == ORI_ERR_PARSE)) abort();
    if (st != ORI_OK || !ref) {
        json_decref(ref);
        ori_fold_destroy(doc);
        return 0;
    }
    // Written back unchanged, it is the same JSON.
    char *text = ori_fold_to_string(doc);
    json_t *back = json_loads(text, 0, &je);
    if (!back || !same_json(ref, back)) abort();
    json_decref(back);
    json_decref(ref);
    ori_buffer_free(text);
    int frames = ori_fold_frame_count(doc);
    ori_build_def planar = ori_default_build_def();
    planar.planarize = true;
    for (int f = 0; f < frames && f < 8; ++f) {
        ori_pattern *p = NULL;
        if (ori_fold_get_pattern(doc, f, &planar, &p, &err) != ORI_OK) continue;
        for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
            double sectors[64];
            int edges[64];
            ori_pattern_vertex_sectors(p, v, edges, sectors, 64);
            (void)ori_pattern_vertex_is_interior(p, v);
        }
        ori_fold_set_pattern(doc, f, p, &err);
        // What orikin wrote reads back as the same pattern.
        text = ori_fold_to_string(doc);
        ori_fold *again = NULL;
        ori_pattern *q = NULL;
        if (ori_fold_load_string(text, strlen(text), &again, &err) != ORI_OK) abort(); // our output must parse
        if (ori_fold_get_pattern(again, f, NULL, &q, &err) != ORI_OK) abort();
        if (ori_pattern_vertex_count(q) != ori_pattern_vertex_count(p) || ori_pattern_edge_count(q) != ori_pattern_edge_count(p) ||
            ori_pattern_face_count(q) != ori_pattern_face_count(p))
            abort();
        for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
            ori_edge a = ori_pattern_edge(p, e), b = ori_pattern_edge(q, e);
            if (a.v[0] != b.v[0] || a.v[1] != b.v[1] || a.assignment != b.assignment || a.fold_angle_rad != b.fold_angle_rad)
                abort();
        }
        for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
            ori_v3 a = ori_pattern_vertex(p, v), b = ori_pattern_vertex(q, v);
            if (a.x != b.x || a.y != b.y || a.z != b.z) abort();
        }
        ori_pattern_destroy(q);
        ori_fold_destroy(again);
        ori_buffer_free(text);
        ori_pattern_destroy(p);
    }
    ori_fold_destroy(doc);
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
