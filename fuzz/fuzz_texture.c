// libFuzzer target for PNG textures of the 3D view (ori_render_def.texture_png, read with
// libpng): the input is the PNG, mapped on a small folded open corner drawn at 48 × 36 pixels.
// Invariants: no crash, leak or sanitizer report; a texture that is not a readable PNG is
// ORI_ERR_PARSE with a message; a drawing that succeeds is a PNG (its signature).
#include <orikin/orikin.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static ori_pattern *sheet(void)
{
    static const char text[] = "{\"vertices_coords\":[[0,0],[1,0],[1,1],[0,1],[0.5,0.5]],"
                               "\"edges_vertices\":[[0,1],[1,2],[2,3],[3,0],[0,4],[1,4],[2,4],[3,4]],"
                               "\"edges_assignment\":[\"B\",\"B\",\"B\",\"B\",\"V\",\"M\",\"V\",\"V\"],"
                               "\"edges_foldAngle\":[0,0,0,0,60,-60,60,60]}";
    ori_fold *doc = NULL;
    ori_pattern *p = NULL;
    ori_error err;
    if (ori_fold_load_string(text, sizeof text - 1, &doc, &err) != ORI_OK ||
        ori_fold_get_pattern(doc, 0, NULL, &p, &err) != ORI_OK)
        abort(); // our own text
    ori_fold_destroy(doc);
    return p;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    ori_pattern *p = sheet();
    ori_state_view view = {p, NULL, NULL};
    ori_render_def def = ori_default_render_def();
    def.view = ORI_RENDER_3D;
    def.format = ORI_IMAGE_PNG;
    def.width = 48;
    def.height = 36;
    def.texture_png = data;
    def.texture_size = size;
    void *img = NULL;
    size_t n = 0;
    ori_error err;
    ori_status st = ori_render_image(&view, &def, &img, &n, &err);
    if (st == ORI_OK) {
        static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
        if (n < 8 || memcmp(img, sig, 8) != 0) abort();
        ori_buffer_free(img);
    } else if (st != ORI_ERR_PARSE || !err.message[0]) {
        abort(); // a bad texture is a parse error that says why
    }
    ori_pattern_destroy(p);
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
