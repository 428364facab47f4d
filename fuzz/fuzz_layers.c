// libFuzzer target for the layer solver: a FOLD document's frame 0 (small patterns only, so
// that every input runs in bounded time), set-up, a count limited per component, and — when a
// state exists and the count is exact — state 0's face orders, its FOLD frame and its drawing.
// Any crash, leak or sanitizer report is a bug; an error status is an answer.
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
    ori_pattern *p = NULL;
    if (ori_fold_get_pattern(doc, 0, NULL, &p, &err) == ORI_OK && ori_pattern_face_count(p) <= 48 &&
        ori_pattern_edge_count(p) <= 160) {
        ori_layers_def def = ori_default_layers_def();
        def.limit = 64;
        ori_layers *L = NULL;
        if (ori_layers_create(p, &def, &L, &err) == ORI_OK && ori_layers_count(L, &err) == ORI_OK) {
            ori_layers_info in = ori_layers_get_info(L);
            char *n = ori_layers_state_count(L);
            ori_buffer_free(n);
            ori_layers_conflict c;
            int faces[64];
            if (ori_layers_get_conflict(L, &c)) ori_layers_conflict_faces(L, faces, 64);
            if (in.satisfiable && !in.limited && ori_layers_select_state(L, "0", &err) == ORI_OK) {
                int nv = ori_layers_face_orders(L, NULL, 0);
                int *fo = malloc(sizeof(int) * 3 * (size_t)(nv ? nv : 1));
                ori_layers_face_orders(L, fo, nv);
                free(fo);
                ori_layers_append_frame(L, p, doc, 0, &err);
                char *svg = NULL;
                size_t len = 0;
                if (ori_layers_svg(L, p, &svg, &len, &err) == ORI_OK && strlen(svg) != len) abort();
                ori_buffer_free(svg);
            }
        }
        ori_layers_destroy(L);
    }
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
