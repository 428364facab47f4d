// libFuzzer target for the planar arrangement: the input bytes are read as creases (four
// coordinates each, on a coarse grid so that they often pass through vertices, overlap and
// touch) applied to a square sheet one after the other. The pattern must stay planar with
// consistent faces: every application either fails cleanly or builds with the planarity check.
#include <orikin/authoring.h>
#include <orikin/orikin.h>
#include <stdint.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    ori_v2 sq[4] = {{0, 0}, {16, 0}, {16, 16}, {0, 16}};
    ori_pattern *p = NULL;
    ori_error err;
    if (ori_pattern_create_sheet(sq, 4, &p, &err) != ORI_OK) abort();
    for (size_t i = 0; i + 5 <= size && i < 5 * 48; i += 5) {
        // coordinates in [−1, 17] in steps of 1/4 (a grid that makes degenerate cases common)
        double x[4];
        for (int k = 0; k < 4; ++k) x[k] = (double)(data[i + k] % 73) / 4.0 - 1.0;
        uint8_t flags = data[i + 4];
        ori_crease c = {{x[0], x[1]}, {x[2], x[3]}, (flags & 1) != 0, (ori_assignment)(1 + (flags >> 1) % 2), 0.0};
        int face = (flags & 4) ? (int)((flags >> 3) % (unsigned)ori_pattern_face_count(p)) : ORI_NULL_INDEX;
        int faces_before = ori_pattern_face_count(p);
        ori_status st = ori_pattern_apply_crease(p, &c, face, NULL, &err);
        if (st != ORI_OK && ori_pattern_face_count(p) != faces_before) abort(); // failures change nothing
        if (!ori_pattern_is_built(p)) abort();
        if ((flags & 0xC0) == 0xC0 && ori_pattern_edge_count(p) > 4) {
            int e = 4 + (int)(flags % (unsigned)(ori_pattern_edge_count(p) - 4));
            ori_pattern_remove_crease(p, e, NULL, &err);
            if (!ori_pattern_is_built(p)) abort();
        }
    }
    // Faces must tile the sheet.
    double area = 0.0;
    for (int f = 0; f < ori_pattern_face_count(p); ++f) {
        int n = ori_pattern_face_size(p, f);
        int *fv = malloc(sizeof(int) * (size_t)n);
        ori_pattern_face_vertices(p, f, fv, n);
        for (int k = 0; k < n; ++k) {
            ori_v3 a = ori_pattern_vertex(p, fv[k]), b = ori_pattern_vertex(p, fv[(k + 1) % n]);
            area += 0.5 * (a.x * b.y - a.y * b.x);
        }
        free(fv);
    }
    if (!(area > 256.0 - 1e-6 && area < 256.0 + 1e-6)) abort();
    // and be the faces of the planar graph: tracing them from scratch finds as many.
    ori_pattern *q = ori_pattern_clone(p);
    ori_pattern_clear_faces(q);
    if (ori_pattern_build(q, NULL, &err) != ORI_OK) abort();
    if (ori_pattern_face_count(q) != ori_pattern_face_count(p)) abort();
    ori_pattern_destroy(q);
    ori_pattern_destroy(p);
    return 0;
}
