// Layer count across MPI ranks (issue 26): one crease pattern of the Flat-Folder corpus whose
// count is split over independent components of similar cost, counted serially in this
// process (as `orikin layers --count`) and by orikin-layers-mpi under mpirun at 1 and 2 ranks
// (loopback): the count's wall seconds (best of REPEATS; rank 0's --timing figure, beside the
// whole run's with MPI start-up and the set-up every rank repeats), the speed-up of 2 ranks over
// 1 and the parallel efficiency; the counts must agree.
// Needs ../shared/patterns/flat-folder-corpus (or $ORIKIN_SHARED_PATTERNS/flat-folder-corpus).
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#define REPEATS 3

// The pattern: Guyver Unit I (1,182 faces, 59,599 variables, 23 components) counted exactly:
// two components of 42,286 states and two of 12,288 carry most of the count, so the split can
// balance at 2 ranks; its count (about 1 s) outweighs its set-up (about 0.5 s).
#define LAYERS_MPI_FILE "instagram/166_shuki_Guyver_Unit_I.fold"

// Run cmd, its stdout into out; wall seconds, or -1 on failure.
static double timed(const char *cmd, char *out, size_t cap)
{
    double t0 = bench_now();
    FILE *f = popen(cmd, "r");
    if (!f) return -1.0;
    size_t n = fread(out, 1, cap - 1, f);
    out[n] = '\0';
    int st = pclose(f);
    double t = bench_now() - t0;
    return st == 0 ? t : -1.0;
}

static int run(void)
{
#ifndef ORI_LAYERS_MPI
    printf("   (MPI not found at build time: no orikin-layers-mpi figures)\n");
    return 0;
#else
    const char *root = getenv("ORIKIN_SHARED_PATTERNS");
    char path[4096];
    snprintf(path, sizeof path, "%s/flat-folder-corpus/" LAYERS_MPI_FILE, root ? root : "../shared/patterns");
    FILE *probe = fopen(path, "r");
    if (!probe) {
        printf("   %s absent: skipped\n", path);
        return 0;
    }
    fclose(probe);
    // Serial: the same work in this process (read, set up, count), as `orikin layers --count`.
    char cmd[8192], want[4096] = "", got[4096];
    double serial = 1e30, serial_setup = 0, serial_count = 0;
    for (int k = 0; k < REPEATS; ++k) {
        double t0 = bench_now(), t1 = t0;
        ori_fold *doc = NULL;
        ori_pattern *p = NULL;
        ori_layers *L = NULL;
        ori_error err;
        ori_error_clear(&err);
        ori_status st = ori_fold_load_file(path, &doc, &err);
        if (st == ORI_OK) st = ori_fold_get_pattern(doc, 0, NULL, &p, &err);
        if (st == ORI_OK) st = ori_layers_create(p, NULL, &L, &err);
        t1 = bench_now();
        if (st == ORI_OK) st = ori_layers_count(L, &err);
        if (st == ORI_OK) {
            char *n = ori_layers_state_count(L);
            snprintf(want, sizeof want, "%s", n);
            ori_buffer_free(n);
        }
        double t = bench_now() - t0;
        ori_layers_destroy(L);
        ori_pattern_destroy(p);
        ori_fold_destroy(doc);
        if (st != ORI_OK) {
            printf("   %s: %s\n", path, err.message);
            return 1;
        }
        if (t < serial) serial = t, serial_setup = t1 - t0, serial_count = t - (t1 - t0);
    }
    // MPI: the count's wall seconds as rank 0 measures them (--timing), and the whole run's.
    double best[3] = {0, 1e30, 1e30}, wall[3] = {0, 0, 0};
    for (int k = 0; k < REPEATS; ++k)
        for (int np = 1; np <= 2; ++np) {
            snprintf(cmd, sizeof cmd,
                     "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader "
                     "OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_oob_tcp_if_include=lo '%s' --oversubscribe "
                     "-np %d '%s' '%s' --timing 2>&1",
                     ORI_MPIEXEC, np, ORI_LAYERS_MPI, path);
            double t = timed(cmd, got, sizeof got);
            const char *c = strstr(got, ", count ");
            // The count's line (stdout) among --timing's (stderr), in either order.
            size_t lw = strlen(want);
            bool same = false;
            for (const char *q = got; (q = strstr(q, want)) && !same; ++q)
                same = (q == got || q[-1] == '\n') && q[lw] == '\n';
            if (t < 0 || !c || !same) {
                printf("   mpirun -np %d: '%s', serial '%s'\n", np, got, want);
                return 1;
            }
            double count = atof(c + strlen(", count "));
            if (count < best[np]) best[np] = count, wall[np] = t;
        }
    printf("   %s: %s states\n", LAYERS_MPI_FILE, want);
    printf("   serial, in this process (best of %d): set-up %.3f s + count %.3f s\n", REPEATS, serial_setup, serial_count);
    printf("   mpirun -np 1 (best of %d): count %.3f s (%.3f s with start-up and set-up)\n", REPEATS, best[1], wall[1]);
    printf("   mpirun -np 2 (best of %d): count %.3f s (%.3f s with start-up and set-up): speed-up %.2f, parallel "
           "efficiency %.2f (vs the serial count: %.2f)\n",
           REPEATS, best[2], wall[2], best[1] / best[2], best[1] / (2 * best[2]), serial_count / (2 * best[2]));
    return 0;
#endif
}

const bench_scenario bench_layers_mpi = {
    "layers_mpi",
    "one pattern's layer count split over its components: serial, orikin-layers-mpi at 1 and 2 ranks",
    run,
};
