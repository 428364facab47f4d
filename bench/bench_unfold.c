// Unfolding: a random simple 200-gon convexified by Streinu's motion (events, wall time; then a
// 200-vertex chain straightened and a 500-gon convexified), and
// nets of qhull convex hulls of random points on a sphere with 100, 1,000 and 10,000 faces
// (time, tries, how often one piece). docs/unfolding.md quotes these figures.
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"
#include "unfold/unfold_internal.h"

static uint64_t rng_state = 88172645463325252ULL;
static double rnd(void)
{
    rng_state ^= rng_state << 13, rng_state ^= rng_state >> 7, rng_state ^= rng_state << 17;
    return (double)(rng_state >> 11) / 9007199254740992.0;
}

// 2-opt untangling of a random tour: a random simple polygon.
static void random_polygon(int n, ori_v2 *p)
{
    for (int i = 0; i < n; ++i) p[i] = ori_v2_make(rnd(), rnd());
    for (bool changed = true; changed;) {
        changed = false;
        for (int i = 0; i < n; ++i)
            for (int j = i + 2; j < n; ++j) {
                if (i == 0 && j == n - 1) continue;
                if (ori__segments_cross_properly(p[i], p[i + 1], p[j], p[(j + 1) % n])) {
                    for (int a = i + 1, b = j; a < b; ++a, --b) {
                        ori_v2 t = p[a];
                        p[a] = p[b], p[b] = t;
                    }
                    changed = true;
                }
            }
    }
}

static int linkage_case(int n, bool closed)
{
    ori_v2 *p = malloc(sizeof *p * (size_t)n);
    int *e = malloc(sizeof *e * 2 * (size_t)n);
    random_polygon(n, p);
    int m = closed ? n : n - 1;
    for (int i = 0; i < m; ++i) e[2 * i] = i, e[2 * i + 1] = (i + 1) % n;
    ori_linkage_def def = ori_default_linkage_def();
    def.coords = p, def.vertex_count = n, def.edges = e, def.edge_count = m;
    ori_linkage_motion *mo = NULL;
    ori_error err;
    double t0 = bench_now();
    ori_status st = ori_linkage_unfold(&def, &mo, &err);
    double t = bench_now() - t0;
    if (st == ORI_OK) {
        ori_linkage_result r = ori_linkage_motion_result(mo);
        printf("   random %s of %d vertices: %s, %d events (%d flips, %d straightened), %d steps, %.2f s, "
               "length error %.1e, least distance change %.1e\n",
               closed ? "polygon" : "chain", n, r.final_ok ? (closed ? "convex" : "straight") : "NOT reached", r.events,
               r.flips, r.straightened, r.steps, t, r.max_length_error, r.min_distance_change);
        ori_linkage_motion_destroy(mo);
    } else {
        printf("   random %s of %d vertices: FAILED after %.2f s: %s\n", closed ? "polygon" : "chain", n, t, err.message);
    }
    free(p), free(e);
    return 0;
}

static int hull_case(int faces, int instances, int tries)
{
    int points = faces / 2 + 2, ok = 0, total_tries = 0;
    double time = 0.0, worst_refold = 0.0;
    ori_v3 *p = malloc(sizeof *p * (size_t)points);
    for (int k = 0; k < instances; ++k) {
        for (int i = 0; i < points; ++i) {
            double z = 2.0 * rnd() - 1.0, th = 2.0 * 3.141592653589793 * rnd(), r = sqrt(1.0 - z * z);
            p[i] = ori_v3_make(r * cos(th), r * sin(th), z);
        }
        ori_mesh *m = NULL;
        ori_error err;
        if (ori_unfold_mesh_convex_hull(p, points, &m, &err) != ORI_OK) {
            printf("   hull: %s\n", err.message);
            continue;
        }
        ori_unfold_def def = ori_default_unfold_def();
        def.tries = tries;
        def.seed = (unsigned)k + 1;
        ori_unfold_net *net = NULL;
        double t0 = bench_now();
        ori_status st = ori_unfold_solve(m, &def, &net, &err);
        time += bench_now() - t0;
        if (st == ORI_OK) {
            ori_unfold_result r = ori_unfold_net_result(net);
            ok += r.pieces == 1;
            total_tries += r.tries;
            if (r.refolded) worst_refold = fmax(worst_refold, r.max_refold_error);
            ori_unfold_net_destroy(net);
        }
        ori_unfold_mesh_destroy(m);
    }
    printf("   convex hulls of %d faces: %d/%d in one piece, %.1f tries on average, %.3f s each (tries, layout, "
           "overlap test, refold, collision check), worst refold error %.1e\n",
           faces, ok, instances, (double)total_tries / instances, time / instances, worst_refold);
    free(p);
    return 0;
}

static int run(void)
{
    linkage_case(200, true);
    hull_case(100, 20, 50);
    hull_case(1000, 10, 50);
    hull_case(10000, 3, 20);
    // after the hulls, so that their random points stay those of the figures in docs/unfolding.md
    linkage_case(200, false);
    linkage_case(500, true);
    return 0;
}

const bench_scenario bench_unfold = {"unfold", "Streinu motion of random 200-gon, 200-chain, 500-gon; nets of convex hulls", run};
