// Shared by the kinematics fuzz targets (fuzz_motion.c, fuzz_dof.c, fuzz_fit.c): turn the fuzzer's
// bytes into a small crease pattern (a single vertex of degree 4–8 with random sector angles and
// assignments, or a generated Miura, Yoshimura, waterbomb or square twist of at most 2 × 2 cells
// with a random angle) and into fold specifications (fixed face, driven crease, locked creases,
// from, target, step, solver). Everything stays small and the steps coarse (≥ 1°), so that one
// input runs in well under fuzz/run.sh's -timeout. And the invariants every kinematic output
// must keep: fold angles in [−180°, 180°], residual ≤ 1e-9, and the frames written as FOLD read
// back as patterns with the same angles.
#ifndef ORI_FUZZ_KIN_H
#define ORI_FUZZ_KIN_H

#include <math.h>
#include <stdbool.h>
#include <orikin/orikin.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_bytes.h"

#define FK_DEG (ORI_PI / 180.0)


// A single vertex at the origin with n creases to the unit circle, every sector between 12° and
// 170° (so that the sector triangles are proper faces), and boundary chords.
static ori_pattern *fk_vertex(fk_bytes *b)
{
    int n = 4 + fk_u8(b) % 5;
    double w[8], sum = 0.0;
    for (int i = 0; i < n; ++i) sum += w[i] = 1.0 + fk_u8(b);
    double t = fk_range(b, 0.0, 2.0 * ORI_PI);
    char text[4096];
    size_t len = 0;
    len += (size_t)snprintf(text + len, sizeof text - len, "{\"vertices_coords\":[[0,0]");
    for (int i = 0; i < n; ++i) {
        double gap = 2.0 * ORI_PI * w[i] / sum;
        if (gap < 12.0 * FK_DEG || gap > 170.0 * FK_DEG) return NULL;
        len += (size_t)snprintf(text + len, sizeof text - len, ",[%.17g,%.17g]", cos(t), sin(t));
        t += gap;
    }
    len += (size_t)snprintf(text + len, sizeof text - len, "],\"edges_vertices\":[");
    for (int i = 0; i < n; ++i) len += (size_t)snprintf(text + len, sizeof text - len, "%s[0,%d]", i ? "," : "", i + 1);
    for (int i = 0; i < n; ++i) len += (size_t)snprintf(text + len, sizeof text - len, ",[%d,%d]", i + 1, (i + 1) % n + 1);
    len += (size_t)snprintf(text + len, sizeof text - len, "],\"edges_assignment\":[");
    uint8_t mv = fk_u8(b);
    for (int i = 0; i < n; ++i) len += (size_t)snprintf(text + len, sizeof text - len, "%s\"%c\"", i ? "," : "", (mv >> i) & 1 ? 'M' : 'V');
    for (int i = 0; i < n; ++i) len += (size_t)snprintf(text + len, sizeof text - len, ",\"B\"");
    snprintf(text + len, sizeof text - len, "]}");
    ori_fold *doc = NULL;
    ori_error err;
    if (ori_fold_load_string(text, strlen(text), &doc, &err) != ORI_OK) abort(); // our own text
    ori_pattern *p = NULL;
    ori_fold_get_pattern(doc, 0, NULL, &p, &err);
    ori_fold_destroy(doc);
    return p;
}

// A generated tessellation of at most 2 × 2 cells (NULL when the parameters are refused).
static ori_pattern *fk_generated(fk_bytes *b)
{
    static const ori_tessellation kinds[] = {ORI_TESS_MIURA, ORI_TESS_YOSHIMURA, ORI_TESS_WATERBOMB, ORI_TESS_SQUARE_TWIST};
    ori_generate_def g = ori_default_generate_def(kinds[fk_u8(b) % 4]);
    g.rows = 1 + fk_u8(b) % 2;
    g.cols = 1 + fk_u8(b) % 2;
    // The cone analysis at the flat state of a square twist is exponential in its branching
    // loops (issue 14 item 4, bounded by a separate change): one twist only, until then.
    if (g.kind == ORI_TESS_SQUARE_TWIST) g.rows = g.cols = 1;
    if (fk_u8(b) & 1) g.angle_rad = fk_range(b, 5.0, 85.0) * FK_DEG;
    ori_pattern *p = NULL;
    ori_error err;
    if (ori_generate(&g, &p, NULL, &err) != ORI_OK) return NULL;
    return p;
}

// The pattern of an input: byte 0 chooses.
static ori_pattern *fk_pattern(fk_bytes *b) { return fk_u8(b) & 1 ? fk_generated(b) : fk_vertex(b); }

// The input's pattern and its mechanism; false (both NULL) when either is refused. The caller
// destroys both.
static bool fk_mechanism(fk_bytes *b, ori_pattern **p, ori_mechanism **m)
{
    *m = NULL;
    *p = fk_pattern(b);
    if (!*p) return false;
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = *p;
    ori_error err;
    if (ori_mechanism_create(&md, m, &err) == ORI_OK) return true;
    ori_pattern_destroy(*p);
    *p = NULL;
    return false;
}

// A fold specification on mechanism m; locks has room for 8. Starting flat; the target and
// from (when set) on one side of the flat state.
static ori_motion_def fk_fold(fk_bytes *b, const ori_mechanism *m, int *locks)
{
    ori_motion_def d = ori_default_motion_def();
    int E = ori_mechanism_edge_count(m), F = ori_mechanism_face_count(m);
    d.fixed_face = F > 0 ? fk_u8(b) % F : 0;
    d.driven_edge = E > 0 ? fk_u8(b) % E : 0;
    int nl = fk_u8(b) % 9;
    for (int i = 0; i < nl; ++i) locks[i] = E > 0 ? fk_u8(b) % E : 0;
    d.locked_edges = locks;
    d.locked_count = nl;
    double sign = fk_u8(b) & 1 ? 1.0 : -1.0;
    d.to_rad = sign * fk_range(b, 0.0, 180.0) * FK_DEG;
    if (fk_u8(b) & 1) {
        d.has_from = true;
        d.from_rad = sign * fk_range(b, 0.0, 180.0) * FK_DEG;
    }
    d.step_rad = fk_range(b, 1.0, 90.0) * FK_DEG;
    uint8_t s = fk_u8(b) % 3;
    d.solver = s == 0 ? ORI_SOLVER_AUTO : s == 1 ? ORI_SOLVER_ANALYTIC : ORI_SOLVER_NUMERIC;
    return d;
}

// The invariants of one motion: angles in [−π, π], residual ≤ 1e-9, frames finite.
static void fk_check_motion(const ori_mechanism *m, const ori_motion *mo)
{
    int E = ori_mechanism_edge_count(m);
    for (int f = 0; f < ori_motion_frame_count(mo); ++f) {
        const double *a = ori_motion_frame_angles(mo, f);
        for (int e = 0; e < E; ++e)
            if (!(fabs(a[e]) <= ORI_PI)) abort(); // outside [−180°, 180°] or NaN
        if (!(ori_motion_frame_residual(mo, f) <= 1e-9)) abort();
        if (!(fabs(ori_motion_frame_drive(mo, f)) <= ORI_PI)) abort();
    }
    ori_motion_block blk;
    if (ori_motion_block_of(mo, &blk)) {
        if (ori_motion_verdict_of(mo) == ORI_MOTION_VALID) abort();
        if (!(fabs(blk.drive_rad) <= ORI_PI)) abort();
    }
    for (int i = 0; i < ori_motion_violation_count(mo); ++i)
        if (!(fabs(ori_motion_violation(mo, i).angle_rad) <= ORI_PI)) abort();
}

// Frames (edge_count angles each, positions from the mechanism) written as FOLD text read back
// as patterns with the same fold angles (to the writer's shortest exact decimals, and its snapping
// of degrees within ORI_TOL_PRINT_DEG of an integer).
static void fk_check_written(const ori_pattern *p, const ori_mechanism *m, int frames, const double *const *angles)
{
    ori_fold *doc = ori_fold_create();
    ori_error err;
    if (ori_fold_set_pattern(doc, 0, p, &err) != ORI_OK) abort();
    int V = ori_mechanism_vertex_count(m), E = ori_mechanism_edge_count(m);
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)(V + 1));
    for (int f = 0; f < frames; ++f) {
        ori_mechanism_vertex_positions(m, angles[f], 0, ori_rigid_identity(), pos);
        ori_fold_append_state(doc, 0, V, pos, E, angles[f], NULL);
    }
    free(pos);
    char *text = ori_fold_to_string(doc);
    ori_fold_destroy(doc);
    ori_fold *again = NULL;
    if (ori_fold_load_string(text, strlen(text), &again, &err) != ORI_OK) abort(); // our output must read
    ori_buffer_free(text);
    for (int f = 0; f < frames; ++f) {
        ori_pattern *q = NULL;
        ori_build_def bd = ori_default_build_def();
        bd.check_planarity = false;
        if (ori_fold_get_pattern(again, f + 1, &bd, &q, &err) != ORI_OK) abort();
        for (int e = 0; e < E; ++e)
            if (fabs(ori_pattern_edge(q, e).fold_angle_rad - angles[f][e]) > 1e-12 + ori_deg_to_rad(ORI_TOL_PRINT_DEG))
                abort(); // files snap degrees within ORI_TOL_PRINT_DEG of an integer (1.7e-12 rad)
        ori_pattern_destroy(q);
    }
    ori_fold_destroy(again);
}

#endif
