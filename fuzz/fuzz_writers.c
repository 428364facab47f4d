// libFuzzer target for every writer, read back (issue: orikin never writes what it refuses to
// read): a small pattern from the fuzzer's bytes (fuzz_kin.h: a vertex or a generated
// tessellation) is written as FOLD, SVG, CP and OPX and read back with orikin's own readers,
// and its mesh is exported as OBJ, STL, PLY, glTF and GLB. Invariants: FOLD reads back with the
// same vertices, edges, assignments and angles; SVG reads back with the same number of crease
// and boundary lengths; CP and OPX read back (or are refused up front for F/U creases); the
// glTF is JSON; every mesh export is non-empty; no crash, leak or sanitizer report.
#include <jansson.h>

#include "fuzz_kin.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

// Total length of the segments by assignment class: boundary (B, C) and folds (M, V, F, U).
static void lengths_of(const ori_pattern *p, double *boundary, double *folds)
{
    *boundary = *folds = 0.0;
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        ori_v3 a = ori_pattern_vertex(p, ed.v[0]), b = ori_pattern_vertex(p, ed.v[1]);
        double l = hypot(a.x - b.x, a.y - b.y);
        if (ed.assignment == ORI_ASSIGN_BOUNDARY || ed.assignment == ORI_ASSIGN_CUT) *boundary += l;
        else if (ed.assignment != ORI_ASSIGN_JOIN) *folds += l;
    }
}

static void read_back(ori_status (*reader)(const char *, size_t, ori_segment **, int *, ori_import_stats *, ori_error *),
                      const char *text, const ori_pattern *p, bool angles)
{
    ori_segment *seg = NULL;
    int n = 0;
    ori_import_stats stats;
    ori_error err;
    if (reader(text, strlen(text), &seg, &n, &stats, &err) != ORI_OK) abort(); // our own output reads
    ori_pattern *q = NULL;
    if (ori_segments_to_pattern(seg, n, NULL, &q, &err) != ORI_OK) abort();
    double b0, f0, b1, f1;
    lengths_of(p, &b0, &f0);
    lengths_of(q, &b1, &f1);
    double scale = 1e-9 * (1.0 + b0 + f0);
    if (fabs(b0 - b1) > scale || fabs(f0 - f1) > scale) abort();
    (void)angles;
    ori_pattern_destroy(q);
    ori_buffer_free(seg);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fk_bytes b = {data, size, 0};
    ori_pattern *p = fk_pattern(&b);
    if (p) {
        ori_error err;
        // FOLD
        size_t n = 0;
        char *fold = ori_pattern_to_fold_text(p, NULL, 0, &n);
        ori_fold *doc = NULL;
        ori_pattern *q = NULL;
        if (ori_fold_load_string(fold, n, &doc, &err) != ORI_OK || ori_fold_get_pattern(doc, 0, NULL, &q, &err) != ORI_OK)
            abort();
        if (ori_pattern_vertex_count(q) != ori_pattern_vertex_count(p) || ori_pattern_edge_count(q) != ori_pattern_edge_count(p))
            abort();
        for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
            ori_edge x = ori_pattern_edge(p, e), y = ori_pattern_edge(q, e);
            if (x.assignment != y.assignment || x.v[0] != y.v[0] || x.v[1] != y.v[1] || x.fold_angle_rad != y.fold_angle_rad)
                abort();
        }
        ori_pattern_destroy(q);
        ori_fold_destroy(doc);
        ori_buffer_free(fold);
        // drawings
        char *svg = ori_svg_write(p, NULL);
        read_back(ori_svg_read_segments, svg, p, true);
        ori_buffer_free(svg);
        bool aux = false; // ORIPA has no F or U type: ori_export_file refuses such patterns
        for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
            ori_assignment a = ori_pattern_edge(p, e).assignment;
            aux = aux || a == ORI_ASSIGN_FLAT || a == ORI_ASSIGN_UNASSIGNED;
        }
        if (!aux) {
            char *cp = ori_cp_write(p), *opx = ori_opx_write(p);
            read_back(ori_cp_read_segments, cp, p, false);
            read_back(ori_opx_read_segments, opx, p, false);
            ori_buffer_free(cp);
            ori_buffer_free(opx);
        }
        // meshes of the flat state
        ori_state_view view = {p, NULL, NULL};
        ori_mesh *mesh = NULL;
        if (ori_mesh_create(&view, &mesh, &err) != ORI_OK) abort();
        static const ori_mesh_format formats[] = {ORI_MESH_OBJ, ORI_MESH_STL, ORI_MESH_PLY, ORI_MESH_GLTF, ORI_MESH_GLB};
        for (size_t i = 0; i < sizeof formats / sizeof formats[0]; ++i) {
            ori_export_def ed = ori_default_export_def();
            ed.format = formats[i];
            ed.thickness = fk_u8(&b) & 1 ? 0.01 : 0.0;
            void *out = NULL;
            size_t m = 0;
            if (ori_mesh_export(mesh, &ed, &out, &m, &err) != ORI_OK || m == 0) abort();
            if (formats[i] == ORI_MESH_GLTF) {
                json_error_t je;
                json_t *j = json_loadb(out, m, 0, &je);
                if (!json_is_object(j) || !json_object_get(j, "asset")) abort();
                json_decref(j);
            }
            ori_buffer_free(out);
        }
        ori_mesh_destroy(mesh);
        ori_pattern_destroy(p);
    }
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
