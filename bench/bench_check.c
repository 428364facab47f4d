// Check scenario: a Miura-ori crease pattern of about 10^6 edges built in memory, then the full
// local flat-foldability check (every interior vertex: Kawasaki, Maekawa, big-little-big, Hull's
// count, exact crimp test). Prints vertices per second for the verification alone and for
// build + verification, and the peak memory; a smaller run shows that memory grows linearly.
#include <orikin/flat.h>
#include <stdio.h>

#include "bench.h"

// Miura-ori on an nx × ny grid: straight horizontal creases, vertical zigzags (x shifted by
// 0.3 on odd rows), so every interior vertex has sectors θ, 180° − θ, 180° − θ, θ with
// θ = atan2(1, 0.3) ≈ 73.3°. Zigzag column i is M for even i, V for odd i; a horizontal edge
// takes the letter of the zigzag on the side away from the vertex's two small sectors. That is
// the Miura assignment: valid at every vertex (Maekawa 3:1, big-little-big on the θ pair).
static ori_pattern *miura(int nx, int ny)
{
    ori_pattern_def def = ori_default_pattern_def();
    def.vertex_capacity = (nx + 1) * (ny + 1);
    def.edge_capacity = 2 * nx * ny + nx + ny;
    ori_pattern *p = ori_pattern_create(&def);
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) ori_pattern_add_vertex(p, ori_v3_make(i + (j % 2) * 0.3, j, 0));
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            int v = j * (nx + 1) + i;
            if (i < nx) {
                ori_assignment a;
                if (j == 0 || j == ny) a = ORI_ASSIGN_BOUNDARY;
                else {
                    int zig = (j % 2 == 0) ? i + 1 : i;
                    a = zig % 2 == 0 ? ORI_ASSIGN_MOUNTAIN : ORI_ASSIGN_VALLEY;
                }
                ori_pattern_add_edge(p, v, v + 1, a, 0.0);
            }
            if (j < ny) {
                ori_assignment a = (i == 0 || i == nx) ? ORI_ASSIGN_BOUNDARY
                                   : (i % 2 == 0)      ? ORI_ASSIGN_MOUNTAIN
                                                       : ORI_ASSIGN_VALLEY;
                ori_pattern_add_edge(p, v, v + nx + 1, a, 0.0);
            }
        }
    return p;
}

static int one_size(int n, bool main_run)
{
    ori_pattern *p = miura(n, n);
    int64_t base = ori_alloc_live_bytes();
    ori_alloc_reset_peak();
    ori_error err;
    double t0 = bench_now();
    if (ori_pattern_build(p, NULL, &err) != ORI_OK) {
        char msg[300];
        printf("   build failed: %s\n", ori_error_format(&err, msg, sizeof msg));
        ori_pattern_destroy(p);
        return 1;
    }
    double t1 = bench_now();
    ori_flat_report *rep = ori_flat_check_pattern(p, NULL);
    double t2 = bench_now();
    int64_t peak = ori_alloc_peak_bytes() - base;
    int interior = ori_flat_report_interior_count(rep);
    bool ok = ori_flat_report_flat_foldable(rep) && interior == (n - 1) * (n - 1);
    int edges = ori_pattern_edge_count(p), vertices = ori_pattern_vertex_count(p);
    if (main_run) {
        printf("   Miura-ori %dx%d: %d vertices (%d interior), %d edges; verdict %s\n", n, n, vertices,
               interior, edges, ok ? "locally flat-foldable" : "WRONG");
        printf("   build %.3f s, verify %.3f s\n", t1 - t0, t2 - t1);
        printf("   verification alone: %.2f M interior vertices/s\n", interior / (t2 - t1) / 1e6);
        printf("   build + verification: %.2f M interior vertices/s\n", interior / (t2 - t0) / 1e6);
        printf("   library peak %.1f MB (%.0f bytes/edge), process peak RSS %.1f MB\n", (double)peak / 1e6,
               (double)peak / edges, (double)bench_peak_rss() / 1e6);
    } else {
        printf("   (linearity) %dx%d: %d edges, library peak %.1f MB (%.0f bytes/edge), verify %.3f s\n", n, n,
               edges, (double)peak / 1e6, (double)peak / edges, t2 - t1);
    }
    ori_flat_report_destroy(rep);
    ori_pattern_destroy(p);
    return ok ? 0 : 1;
}

static int run(void)
{
    int rc = one_size(354, false); // ~2.5·10^5 edges
    rc |= one_size(707, true);     // ~10^6 edges
    return rc;
}

const bench_scenario bench_check = {"check", "build + local flat-foldability check of a ~10^6-edge Miura-ori", run};
