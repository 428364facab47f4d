// The body shared by the drawing-reader fuzz targets (fuzz_svg.c, fuzz_opx.c, fuzz_cp.c): read
// segments; when they read, planarise them (small inputs), export the pattern in the same format
// and re-import the export, which must give the same pattern: the same vertices (exact
// coordinates), the same edges with their assignments (CP and OPX: C comes back as B) and fold
// angles (SVG: to the last bit; a crease at 0 is written folded flat), the same number of faces.
// CP and OPX have no F and U creases (ori_export_file refuses such patterns) and turn C into B
// (which may then merge with a collinear B): those patterns are only checked to read back, as
// are patterns with features closer than twice the weld tolerance (where snapping depends on the
// order of the segments). Any crash, leak, difference or sanitizer report is a bug.
#ifndef ORI_FUZZ_IMPORT_H
#define ORI_FUZZ_IMPORT_H

#include <math.h>
#include <orikin/formats.h>
#include <orikin/math.h>
#include <orikin/tolerance.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef ori_status (*fuzz_reader)(const char *text, size_t size, ori_segment **segments, int *count,
                                  ori_import_stats *stats, ori_error *error);

// An edge by its end points (ordered), assignment and fold angle, for comparing as sets.
typedef struct fuzz_edge {
    double x0, y0, x1, y1;
    int asg;
    double angle;
} fuzz_edge;

static int fuzz_edge_cmp(const void *pa, const void *pb)
{
    const fuzz_edge *a = pa, *b = pb;
    const double ka[4] = {a->x0, a->y0, a->x1, a->y1}, kb[4] = {b->x0, b->y0, b->x1, b->y1};
    for (int k = 0; k < 4; ++k)
        if (ka[k] != kb[k]) return ka[k] < kb[k] ? -1 : 1;
    return 0;
}

// The edges of p as a sorted list; as the format's reader gives them back (svg: the angle a crease
// at 0 is written with; oripa: C as B, angles ±π by assignment).
static fuzz_edge *fuzz_edges(const ori_pattern *p, bool svg, bool as_written)
{
    int n = ori_pattern_edge_count(p);
    fuzz_edge *list = malloc(sizeof *list * (size_t)(n ? n : 1));
    for (int e = 0; e < n; ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        ori_v3 a = ori_pattern_vertex(p, ed.v[0]), b = ori_pattern_vertex(p, ed.v[1]);
        bool swap = a.x > b.x || (a.x == b.x && a.y > b.y);
        fuzz_edge f = {swap ? b.x : a.x, swap ? b.y : a.y, swap ? a.x : b.x, swap ? a.y : b.y, (int)ed.assignment,
                       ed.fold_angle_rad};
        if (as_written) {
            bool mv = ed.assignment == ORI_ASSIGN_MOUNTAIN || ed.assignment == ORI_ASSIGN_VALLEY;
            double full = ed.assignment == ORI_ASSIGN_MOUNTAIN ? -ORI_PI : ORI_PI;
            if (svg && mv && ed.fold_angle_rad == 0.0) f.angle = full;
            if (!svg) {
                if (ed.assignment == ORI_ASSIGN_CUT) f.asg = ORI_ASSIGN_BOUNDARY;
                f.angle = mv ? full : 0.0;
            }
            if (svg && !mv) f.angle = 0.0;
        }
        list[e] = f;
    }
    qsort(list, (size_t)n, sizeof *list, fuzz_edge_cmp);
    return list;
}

// The smallest distance between a vertex and an edge not at it, relative to the diagonal. Near
// the weld tolerance the planarisation's snapping depends on the order of the segments, so a
// re-import of such a pattern may weld differently: only patterns whose features are at least
// twice the weld apart are compared.
static double fuzz_min_feature(const ori_pattern *p)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY}, best = INFINITY;
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        ori_v3 x = ori_pattern_vertex(p, v);
        lo[0] = fmin(lo[0], x.x), lo[1] = fmin(lo[1], x.y), hi[0] = fmax(hi[0], x.x), hi[1] = fmax(hi[1], x.y);
        for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
            ori_edge ed = ori_pattern_edge(p, e);
            if (ed.v[0] == v || ed.v[1] == v) continue;
            ori_v3 a = ori_pattern_vertex(p, ed.v[0]), b = ori_pattern_vertex(p, ed.v[1]);
            double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
            double t = l2 > 0 ? ((x.x - a.x) * dx + (x.y - a.y) * dy) / l2 : 0;
            t = t < 0 ? 0 : (t > 1 ? 1 : t);
            best = fmin(best, hypot(x.x - a.x - t * dx, x.y - a.y - t * dy));
        }
    }
    // A vertex of two edges near the chord of its neighbours: collinear merging (within the weld)
    // decides it, in an order of its own, so such patterns are near the weld too.
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        if (ori_pattern_vertex_degree(p, v) != 2) continue;
        int ed[2];
        ori_pattern_vertex_edges(p, v, ed, 2);
        ori_edge e0 = ori_pattern_edge(p, ed[0]), e1 = ori_pattern_edge(p, ed[1]);
        ori_v3 x = ori_pattern_vertex(p, v), a = ori_pattern_vertex(p, e0.v[0] == v ? e0.v[1] : e0.v[0]),
               b = ori_pattern_vertex(p, e1.v[0] == v ? e1.v[1] : e1.v[0]);
        double dx = b.x - a.x, dy = b.y - a.y, l = hypot(dx, dy);
        if (l > 0) best = fmin(best, fabs(dx * (x.y - a.y) - dy * (x.x - a.x)) / l);
    }
    double diag = hypot(hi[0] - lo[0], hi[1] - lo[1]);
    return diag > 0 ? best / diag : 0.0;
}

static bool fuzz_same_angle(double a, double b) { return a == b || a == nextafter(b, 4.0) || a == nextafter(b, -4.0); }

// write: the pattern in the reader's format (a buffer for ori_buffer_free); svg: the format is SVG.
static inline int fuzz_import(const uint8_t *data, size_t size, fuzz_reader read, char *(*write)(const ori_pattern *),
                              bool svg)
{
    ori_segment *segs = NULL;
    int n = 0;
    ori_error err;
    if (read((const char *)data, size, &segs, &n, NULL, &err) == ORI_OK) {
        ori_pattern *p = NULL;
        if (n <= 256 && ori_segments_to_pattern(segs, n, NULL, &p, &err) == ORI_OK) {
            bool oripa_refuses = !svg && (ori_pattern_count_assignment(p, ORI_ASSIGN_FLAT) > 0 ||
                                          ori_pattern_count_assignment(p, ORI_ASSIGN_UNASSIGNED) > 0 ||
                                          ori_pattern_count_assignment(p, ORI_ASSIGN_CUT) > 0);
            bool separated = fuzz_min_feature(p) > 2.0 * ORI_TOL_IMPORT_WELD_REL;
            char *text = write(p);
            ori_segment *again = NULL;
            int m = 0;
            if (read(text, strlen(text), &again, &m, NULL, &err) != ORI_OK) abort(); // our output must parse
            ori_pattern *q = NULL;
            if (!oripa_refuses) {
                if (m == 0 || ori_segments_to_pattern(again, m, NULL, &q, &err) != ORI_OK) abort(); // and re-import
                int ne = ori_pattern_edge_count(p);
                if (!separated) ne = -1;
                if (ne >= 0) {
                    if (ori_pattern_vertex_count(q) != ori_pattern_vertex_count(p) || ori_pattern_edge_count(q) != ne ||
                        ori_pattern_face_count(q) != ori_pattern_face_count(p))
                        abort();
                    fuzz_edge *a = fuzz_edges(p, svg, true), *b = fuzz_edges(q, svg, false);
                    for (int e = 0; e < ne; ++e)
                        if (fuzz_edge_cmp(&a[e], &b[e]) != 0 || a[e].asg != b[e].asg ||
                            !fuzz_same_angle(a[e].angle, b[e].angle))
                            abort();
                    free(a);
                    free(b);
                }
                ori_pattern_destroy(q);
            }
            ori_buffer_free(again);
            ori_buffer_free(text);
            ori_pattern_destroy(p);
            // Closing gaps (a width the drawing's lines might have): must planarise or fail cleanly.
            ori_import_def def = ori_default_import_def();
            def.gap_rel = 1e-3 * (1 + size % 8);
            if (ori_segments_to_pattern(segs, n, &def, &p, &err) == ORI_OK) {
                if (!ori_pattern_is_built(p)) abort();
                ori_pattern_destroy(p);
            }
        }
        ori_buffer_free(segs);
    }
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}

#endif
