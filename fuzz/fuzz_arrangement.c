// libFuzzer target for the planar arrangement. The first byte picks a mode, the rest are read
// as creases of five bytes each (four coordinates on a coarse grid, so that they often pass
// through vertices, overlap and touch, and a flag byte):
//   0: creases applied to a square sheet one after the other (authoring, default tolerance);
//   1: the same with a coarse snap tolerance (up to 0.4 grid steps) and jittered end points;
//   2: a segment soup planarised at once with a coarse tolerance (the importers' path).
// Sheets must stay planar with consistent faces: every insertion either fails cleanly (nothing
// changed) or builds with the planarity check; the faces tile the sheet and are the faces of the
// planar graph. A soup must always planarise into a pattern that builds, with V − E + F equal to
// the number of its connected parts.
#include <orikin/arrangement.h>
#include <orikin/authoring.h>
#include <orikin/orikin.h>
#include <stdint.h>
#include <stdlib.h>

#include "pattern/pattern_internal.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

enum { MAX_CREASES = 48 };

// Coordinate k of crease i: [−1, 17] in steps of 1/4 (a grid that makes degenerate cases common).
static double coord(const uint8_t *data, size_t i, int k) { return (double)(data[i + k] % 73) / 4.0 - 1.0; }

// The jitter of an end point from two bits of the flag byte: under the tolerance in each axis.
static double jitter(uint8_t flags, int shift, double tol) { return ((double)((flags >> shift) & 3) - 1.5) / 2.5 * tol; }

static double clamp16(double x) { return x < 0.0 ? 0.0 : (x > 16.0 ? 16.0 : x); }

static void check_sheet(ori_pattern *p)
{
    ori_error err;
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
}

static void sheet(const uint8_t *data, size_t size, bool coarse)
{
    ori_v2 sq[4] = {{0, 0}, {16, 0}, {16, 16}, {0, 16}};
    ori_pattern *p = NULL;
    ori_error err;
    if (ori_pattern_create_sheet(sq, 4, &p, &err) != ORI_OK) abort();
    double tol = coarse && size > 0 ? 0.05 * (1 + data[0] % 8) : 0.0;
    ori_insert_def def = ori_default_insert_def();
    if (coarse) def.length_scale = tol / ORI_TOL_LENGTH_REL;
    for (size_t i = 1; i + 5 <= size && i < 5 * MAX_CREASES; i += 5) {
        uint8_t flags = data[i + 4];
        int faces_before = ori_pattern_face_count(p), edges_before = ori_pattern_edge_count(p);
        ori_status st;
        if (coarse) {
            ori_v2 a = {clamp16(coord(data, i, 0) + jitter(flags, 0, tol)), clamp16(coord(data, i, 1) + jitter(flags, 2, tol))};
            ori_v2 b = {clamp16(coord(data, i, 2) + jitter(flags, 4, tol)), clamp16(coord(data, i, 3) + jitter(flags, 6, tol))};
            st = ori_pattern_insert_segment(p, a, b, (ori_assignment)(1 + flags % 2), 0.0, &def, NULL, &err);
            if (st == ORI_OK && ori_pattern_build(p, NULL, &err) != ORI_OK) abort();
        } else {
            ori_crease c = {{coord(data, i, 0), coord(data, i, 1)}, {coord(data, i, 2), coord(data, i, 3)}, (flags & 1) != 0,
                            (ori_assignment)(1 + (flags >> 1) % 2), 0.0};
            int face = (flags & 4) ? (int)((flags >> 3) % (unsigned)ori_pattern_face_count(p)) : ORI_NULL_INDEX;
            st = ori_pattern_apply_crease(p, &c, face, NULL, &err);
            if (!ori_pattern_is_built(p)) abort();
        }
        // failures change nothing
        if (st != ORI_OK && (ori_pattern_face_count(p) != faces_before || ori_pattern_edge_count(p) != edges_before))
            abort();
        if (!coarse && (flags & 0xC0) == 0xC0 && ori_pattern_edge_count(p) > 4) {
            int e = 4 + (int)(flags % (unsigned)(ori_pattern_edge_count(p) - 4));
            ori_pattern_remove_crease(p, e, NULL, &err);
            if (!ori_pattern_is_built(p)) abort();
        }
    }
    check_sheet(p);
    ori_pattern_destroy(p);
}

static void soup(const uint8_t *data, size_t size)
{
    if (size < 1) return;
    double tol = 0.05 * (1 + data[0] % 8);
    ori_segment segs[MAX_CREASES];
    int n = 0;
    for (size_t i = 1; i + 5 <= size && n < MAX_CREASES; i += 5) {
        uint8_t flags = data[i + 4];
        segs[n].a = ori_v2_make(coord(data, i, 0) + jitter(flags, 0, tol), coord(data, i, 1) + jitter(flags, 2, tol));
        segs[n].b = ori_v2_make(coord(data, i, 2) + jitter(flags, 4, tol), coord(data, i, 3) + jitter(flags, 6, tol));
        segs[n].assignment = (ori_assignment)(flags % ORI_ASSIGN_COUNT);
        segs[n].fold_angle_rad = 0.0;
        n++;
    }
    ori_insert_def def = ori_default_insert_def();
    def.length_scale = tol / ORI_TOL_LENGTH_REL;
    ori_pattern *p = NULL;
    ori_insert_result r;
    ori_error err;
    if (ori_pattern_from_segments(segs, n, &def, &p, &r, &err) != ORI_OK) abort(); // always planarises and builds
    int V = ori_pattern_vertex_count(p), *part = malloc(sizeof(int) * (size_t)(V + 1));
    int parts = ori__pattern_parts(p, part);
    free(part);
    if (V - ori_pattern_edge_count(p) + ori_pattern_face_count(p) != parts) abort();
    ori_pattern_destroy(p);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1) return 0;
    int mode = data[0] % 3;
    if (mode == 2) soup(data + 1, size - 1);
    else sheet(data + 1, size - 1, mode == 1);
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
