// libFuzzer target for the FOLD reader: parse, read every frame's pattern (with validation),
// write it back and re-read the output. Any crash, leak or sanitizer report is a bug.
#include <orikin/orikin.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    ori_fold *doc = NULL;
    ori_error err;
    if (ori_fold_load_string((const char *)data, size, &doc, &err) != ORI_OK) return 0;
    int frames = ori_fold_frame_count(doc);
    for (int f = 0; f < frames && f < 8; ++f) {
        ori_pattern *p = NULL;
        if (ori_fold_get_pattern(doc, f, NULL, &p, &err) != ORI_OK) continue;
        for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
            double sectors[64];
            int edges[64];
            ori_pattern_vertex_sectors(p, v, edges, sectors, 64);
            (void)ori_pattern_vertex_is_interior(p, v);
        }
        ori_fold_set_pattern(doc, f, p, &err);
        ori_pattern_destroy(p);
    }
    char *text = ori_fold_to_string(doc);
    ori_fold *again = NULL;
    if (ori_fold_load_string(text, strlen(text), &again, &err) != ORI_OK) abort(); // our output must parse
    ori_fold_destroy(again);
    ori_buffer_free(text);
    ori_fold_destroy(doc);
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
