// Miura-ori scenario: an R×C Miura-ori folded by its middle zigzag crease from 5° to 175° in
// 100 output steps (numeric continuation, sparse CHOLMOD corrector above
// ORI_MOTION_DENSE_MAX_UNKNOWNS creases). The 5° start state is reached first from the flat
// sheet (second-order branch analysis at the singular flat state) and reported separately.
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <cblas.h>

#include "bench.h"
#include <orikin/generate.h>
#include <orikin/kinematics.h>

// The Miura-ori from the library's generator: straight edge 1, vertex rows 1 apart and shifted
// by 0.5 on odd rows (zig-zag edge √1.25, cell angle atan2(1, 0.5) ≈ 63.4°). Vertex (i, j) is
// j(C+1) + i; zig-zag column i is M for odd i.
static ori_pattern *miura(int rows, int cols)
{
    ori_generate_def g = ori_default_generate_def(ORI_TESS_MIURA);
    g.rows = rows;
    g.cols = cols;
    g.width = 1.0;
    g.height = sqrt(1.25);
    g.angle_rad = atan2(1.0, 0.5);
    ori_pattern *p = NULL;
    ori_error err;
    return ori_generate(&g, &p, NULL, &err) == ORI_OK ? p : NULL;
}

// Reset the peak resident set size (Linux: "5" to /proc/self/clear_refs): the RSS peak printed
// is the fold's, not the flat → 5° setup's (its second-order analysis peaks higher).
static void reset_peak_rss(void)
{
    FILE *f = fopen("/proc/self/clear_refs", "w");
    if (!f) return;
    fputs("5", f);
    fclose(f);
}

static int one(int n)
{
    ori_pattern *p = miura(n, n);
    if (!p) return 1;
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = p;
    ori_mechanism *m = NULL;
    ori_error err;
    if (ori_mechanism_create(&md, &m, &err) != ORI_OK) return 1;
    int i = n / 2, j = n / 2;
    int drive = ori_pattern_find_edge(p, j * (n + 1) + i, (j + 1) * (n + 1) + i);
    double sg = ori_pattern_edge(p, drive).assignment == ORI_ASSIGN_VALLEY ? 1.0 : -1.0;
    // Setup: flat → 5°.
    ori_alloc_reset_peak();
    double t0 = bench_now();
    ori_motion_def d = ori_default_motion_def();
    d.driven_edge = drive;
    d.to_rad = sg * ori_deg_to_rad(5.0);
    d.step_rad = ori_deg_to_rad(5.0);
    ori_motion *start = NULL;
    if (ori_motion_solve(m, &d, &start, &err) != ORI_OK || ori_motion_verdict_of(start) != ORI_MOTION_VALID) return 1;
    double t1 = bench_now();
    // The measured fold: 5° → 175° in 100 output steps.
    d.start_angles_rad = ori_motion_frame_angles(start, ori_motion_frame_count(start) - 1);
    d.to_rad = sg * ori_deg_to_rad(175.0);
    d.step_rad = ori_deg_to_rad(170.0 / 100.0);
    d.last_frame_only = true; // the figure is the solve: the frames' path is not needed
    ori_alloc_reset_peak();
    reset_peak_rss();
    int64_t base = ori_alloc_live_bytes();
    double t2 = bench_now(), c2 = bench_cpu_now();
    ori_motion *mo = NULL;
    if (ori_motion_solve(m, &d, &mo, &err) != ORI_OK) return 1;
    double t3 = bench_now(), c3 = bench_cpu_now();

    ori_motion_stats st = ori_motion_stats_of(mo);
    printf("   %3dx%-3d %5d creases: flat->5deg %.3f s; 5->175deg %.3f s wall (%.3f s CPU), %d frames, %d steps "
           "(%d rejected), %d Newton its (%d by the sweep), %d factorizations, max residual %.1e, dof %d, %s; heap peak %.1f MB, "
           "RSS peak %.1f MB\n",
           n, n, ori_mechanism_joint_count(m), t1 - t0, t3 - t2, c3 - c2, st.frames, st.steps,
           st.rejected_steps, st.newton_iterations, st.sweep_iterations, st.factorizations, st.max_residual, ori_motion_dof(mo),
           ori_motion_verdict_name(ori_motion_verdict_of(mo)), (double)(ori_alloc_peak_bytes() - base) / 1e6,
           (double)bench_peak_rss() / 1e6);
    fflush(stdout);
    int bad = ori_motion_verdict_of(mo) != ORI_MOTION_VALID;
    ori_motion_destroy(mo);
    ori_motion_destroy(start);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
    return bad;
}

// Available memory (MemAvailable, bytes), 0 if unknown.
static int64_t mem_available(void)
{
    FILE *f = fopen("/proc/meminfo", "r");
    if (!f) return 0;
    char line[256];
    long long kb = 0;
    while (fgets(line, sizeof line, f))
        if (sscanf(line, "MemAvailable: %lld kB", &kb) == 1) break;
    fclose(f);
    return (int64_t)kb * 1024;
}

// The 1000 × 1000 sheet (2 M creases) needs about 3 GB at its peak and minutes: it runs with
// ORI_BENCH_LARGE=1 in the environment (`ORI_BENCH_LARGE=1 make bench`) when the machine has
// this much memory available, else the line says why it was skipped.
#define BENCH_MIURA_LARGE_BYTES ((int64_t)4 << 30)

static int run(void)
{
    // One core, as the CLI runs (cli/main.c): CHOLMOD's supernodal factorizations of the large
    // sheets call BLAS, whose worker threads would otherwise add a second core's CPU time.
    openblas_set_num_threads(1);
    int sizes[3] = {10, 32, 100};
    int bad = 0;
    for (int k = 0; k < 3; ++k) bad |= one(sizes[k]);
    // ORI_BENCH_MIURA_SIZE=N: one extra N × N sheet (e.g. 300 or 500, for measuring).
    const char *extra = getenv("ORI_BENCH_MIURA_SIZE");
    if (extra && atoi(extra) > 1) bad |= one(atoi(extra));
    int64_t avail = mem_available();
    const char *large = getenv("ORI_BENCH_LARGE");
    if (!large || strcmp(large, "1") != 0) {
        printf("   1000x1000: skipped (minutes and about 3 GB: run with ORI_BENCH_LARGE=1)\n");
    } else if (avail >= BENCH_MIURA_LARGE_BYTES) {
        bad |= one(1000);
    } else {
        printf("   1000x1000: skipped (%.1f GB available, needs %.0f GB)\n", (double)avail / 1e9,
               (double)BENCH_MIURA_LARGE_BYTES / 1e9);
    }
    return bad;
}

const bench_scenario bench_miura = {"miura", "Miura-ori RxC folded 5 to 175 deg in 100 output steps", run};
