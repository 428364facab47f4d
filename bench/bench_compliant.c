// Compliant bar-and-hinge model (docs/compliant.md): explicit steps per second on Origami
// Simulator's box-pleat tessellation (../shared/patterns/origamisimulator or
// $ORIKIN_SHARED_PATTERNS, 5,776 vertices) at 100 %, and the static solver (Newton, CHOLMOD)
// on Miura-ori sheets at 50 %. CPU seconds of the process and wall seconds.
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"
#include <orikin/compliant.h>
#include <orikin/fold.h>
#include <orikin/generate.h>

static int explicit_box_pleat(void)
{
    const char *root = getenv("ORIKIN_SHARED_PATTERNS");
    char path[4096];
    snprintf(path, sizeof path, "%s/origamisimulator/Pleating_BoxPleatTessellation.fold", root ? root : "../shared/patterns");
    ori_fold *doc = NULL;
    ori_pattern *p = NULL;
    ori_error err;
    if (ori_fold_load_file(path, &doc, &err) != ORI_OK) {
        printf("   %s absent: explicit scenario skipped\n", path);
        return 0;
    }
    if (ori_fold_get_pattern(doc, 0, NULL, &p, &err) != ORI_OK) {
        printf("   %s: %s\n", path, err.message);
        ori_fold_destroy(doc);
        return 1;
    }
    ori_compliant_def d = ori_default_compliant_def();
    d.fraction = 1.0;
    ori_compliant *c = NULL;
    double t0 = bench_now();
    if (ori_compliant_create(p, &d, &c, &err) != ORI_OK) {
        printf("   %s\n", err.message);
        return 1;
    }
    double t1 = bench_now();
    int V = ori_compliant_vertex_count(c);
    const int steps = 2000;
    int done = 0;
    printf("   box pleat: %d vertices, %d bars, %d hinges; model built in %.3f s; time step %.4g\n", V,
           ori_compliant_bar_count(c), ori_compliant_hinge_count(c), t1 - t0, ori_compliant_time_step(c));
    for (int threads = 1; threads <= 2; ++threads) {
        if (threads > 1) { // the same run again from the flat sheet, on more threads
            ori_compliant_destroy(c);
            d.threads = threads;
            if (ori_compliant_create(p, &d, &c, &err) != ORI_OK) return 1;
        }
        double w0 = bench_now(), c0 = bench_cpu_now();
        ori_compliant_run_dynamic(c, steps, 1e-300, &done, NULL); // never settles: runs every step
        double w1 = bench_now(), c1 = bench_cpu_now();
        printf("   explicit, %d thread%s: %d steps in %.3f s wall (%.3f s CPU): %.0f steps/s, %.2f million node-steps/s\n",
               threads, threads > 1 ? "s" : "", done, w1 - w0, c1 - c0, done / (w1 - w0), done * (double)V / (w1 - w0) * 1e-6);
    }
    printf("   after %d steps (t = %.3g): max strain %.3g %%, crease error %.3g deg\n", done,
           done * ori_compliant_time_step(c), 100.0 * ori_compliant_max_strain(c),
           ori_compliant_crease_error(c) * 180.0 / ORI_PI);
    ori_compliant_destroy(c);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    return 0;
}

static int static_miura(int n)
{
    ori_generate_def g = ori_default_generate_def(ORI_TESS_MIURA);
    g.rows = n;
    g.cols = n;
    ori_pattern *p = NULL;
    ori_error err;
    if (ori_generate(&g, &p, NULL, &err) != ORI_OK) return 1;
    ori_compliant_def d = ori_default_compliant_def();
    d.fraction = 0.5;
    ori_compliant *c = NULL;
    double w0 = bench_now(), c0 = bench_cpu_now();
    if (ori_compliant_create(p, &d, &c, &err) != ORI_OK) return 1;
    double w1 = bench_now();
    ori_status st = ori_compliant_solve_static(c, &err);
    double w2 = bench_now(), c2 = bench_cpu_now();
    int it, fa, bt, ls;
    ori_compliant_stats(c, &it, &fa, &bt, &ls);
    printf("   Miura %dx%d at 50 %%: %d vertices; %s in %.3f s wall (%.3f s CPU; model %.3f s): %d load steps, %d Newton "
           "iterations, |grad E| %.2g of load %.3g\n",
           n, n, ori_compliant_vertex_count(c), st == ORI_OK ? "equilibrium" : "NOT CONVERGED", w2 - w0, c2 - c0, w1 - w0,
           ls, it, ori_compliant_gradient_norm(c), ori_compliant_load_scale(c));
    ori_compliant_destroy(c);
    ori_pattern_destroy(p);
    return st == ORI_OK ? 0 : 1;
}

static int run(void)
{
    if (explicit_box_pleat()) return 1;
    if (static_miura(20)) return 1;
    return static_miura(100);
}

const bench_scenario bench_compliant = {"compliant",
                                         "compliant model: explicit steps/s on the box pleat, static Miura 100x100 at 50 %",
                                         run};
