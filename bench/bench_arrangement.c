// Arrangement scenarios: bulk planarisation of many segments (the importers' path) and
// authoring one crease at a time into a sheet with faces and names.
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <orikin/arrangement.h>
#include <orikin/authoring.h>

#include "bench.h"

static double rnd(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return (double)(*s >> 8) / 16777216.0;
}

static int run(void)
{
    // 1. Bulk: 50 000 segments, half on a 200 × 200 lattice (duplicates, collinear overlaps),
    //    half random short ones crossing them.
    const int n = 50000;
    ori_segment *segs = malloc(sizeof *segs * (size_t)n);
    unsigned s = 5;
    for (int i = 0; i < n; ++i) {
        if (i % 2) {
            double x = floor(rnd(&s) * 200) / 200, y = floor(rnd(&s) * 200) / 200, l = 0.005 * (1 + floor(rnd(&s) * 4));
            segs[i].a = ori_v2_make(x, y);
            segs[i].b = rnd(&s) < 0.5 ? ori_v2_make(x + l, y) : ori_v2_make(x, y + l);
        } else {
            double a = 2 * ORI_PI * rnd(&s);
            segs[i].a = ori_v2_make(rnd(&s), rnd(&s));
            segs[i].b = ori_v2_make(segs[i].a.x + 0.01 * cos(a), segs[i].a.y + 0.01 * sin(a));
        }
        segs[i].assignment = (ori_assignment)(1 + i % 2);
        segs[i].fold_angle_rad = 0.0;
    }
    ori_pattern *p = NULL;
    ori_insert_result r;
    ori_error err;
    double t0 = bench_now();
    if (ori_pattern_from_segments(segs, n, NULL, &p, &r, &err) != ORI_OK) return 1;
    double t1 = bench_now();
    printf("   bulk: %d segments -> %d vertices, %d edges, %d faces (%d splits, %d overlaps) in %.3f s\n", n,
           ori_pattern_vertex_count(p), ori_pattern_edge_count(p), ori_pattern_face_count(p), r.edges_split,
           r.edges_overlapped, t1 - t0);
    ori_pattern_destroy(p);
    free(segs);

    // 2. Authoring: 200 random chords, one at a time, each applied to the whole sheet.
    const int chords = 200;
    ori_v2 sq[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    if (ori_pattern_create_sheet(sq, 4, &p, &err) != ORI_OK) return 1;
    t0 = bench_now();
    for (int i = 0; i < chords; ++i) {
        double a = ORI_PI * rnd(&s);
        ori_crease c = {{rnd(&s), rnd(&s)}, {0, 0}, true, ORI_ASSIGN_VALLEY, 0.0};
        c.b = ori_v2_make(c.a.x + cos(a), c.a.y + sin(a));
        if (ori_pattern_apply_crease(p, &c, ORI_NULL_INDEX, NULL, &err) != ORI_OK) return 1;
    }
    t1 = bench_now();
    printf("   authoring: %d full-sheet creases -> %d faces, %d edges in %.3f s (%.2f ms per crease)\n", chords,
           ori_pattern_face_count(p), ori_pattern_edge_count(p), t1 - t0, (t1 - t0) / chords * 1e3);
    ori_pattern_destroy(p);

    // 3. 512 random chords applied at once (orikin apply with a composite of 512 lines): ~90,000
    //    faces. Finding a face-tree node by name was linear, which made this quadratic in the
    //    output (31 s); it is a hash lookup now.
    const int many = 512;
    ori_crease *cs = malloc(sizeof *cs * (size_t)many);
    for (int i = 0; i < many; ++i) {
        double a = ORI_PI * rnd(&s);
        cs[i] = (ori_crease){{rnd(&s), rnd(&s)}, {0, 0}, true, ORI_ASSIGN_VALLEY, 0.0};
        cs[i].b = ori_v2_make(cs[i].a.x + cos(a), cs[i].a.y + sin(a));
    }
    if (ori_pattern_create_sheet(sq, 4, &p, &err) != ORI_OK) return 1;
    t0 = bench_now();
    if (ori_pattern_apply_creases(p, cs, many, 0, NULL, &err) != ORI_OK) return 1;
    t1 = bench_now();
    printf("   apply at once: %d creases -> %d faces, %d tree nodes in %.3f s\n", many, ori_pattern_face_count(p),
           ori_pattern_tree_node_count(p), t1 - t0);
    ori_pattern_destroy(p);
    free(cs);
    return 0;
}

const bench_scenario bench_arrangement = {"arrangement", "bulk planarisation of 50k segments; 200 creases authored one by one; 512 applied at once", run};
