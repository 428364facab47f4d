// orikin_bench [NAME...] [ARG...]: run every benchmark scenario (or the named ones) and print
// figures. Arguments that name no scenario are left to the scenarios (bench_argc, bench_argv).
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench.h"

#define ORI_BENCH_SCENARIO(id) extern const bench_scenario bench_##id;
#include "scenarios.inc"
#undef ORI_BENCH_SCENARIO

static const bench_scenario *const scenarios[] = {
#define ORI_BENCH_SCENARIO(id) &bench_##id,
#include "scenarios.inc"
#undef ORI_BENCH_SCENARIO
    NULL,
};

int bench_argc;
char **bench_argv;

double bench_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double bench_cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double bench_median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

int64_t bench_peak_rss(void)
{
    FILE *f = fopen("/proc/self/status", "r");
    if (!f) return 0;
    char line[256];
    long long kb = 0;
    while (fgets(line, sizeof line, f))
        if (sscanf(line, "VmHWM: %lld kB", &kb) == 1) break;
    fclose(f);
    return (int64_t)kb * 1024;
}

// Reset the process's peak resident set size (Linux: "5" to /proc/self/clear_refs), so that
// each scenario reports its own peak.
static void reset_peak_rss(void)
{
    FILE *f = fopen("/proc/self/clear_refs", "w");
    if (!f) return;
    fputs("5", f);
    fclose(f);
}

int main(int argc, char **argv)
{
    int failed = 0, ran = 0;
    bench_argc = argc;
    bench_argv = argv;
    int named = 0;
    for (int a = 1; a < argc; ++a)
        for (int i = 0; scenarios[i]; ++i) named += strcmp(argv[a], scenarios[i]->name) == 0;
    for (int i = 0; scenarios[i]; ++i) {
        bool wanted = named == 0;
        for (int a = 1; a < argc; ++a) wanted |= strcmp(argv[a], scenarios[i]->name) == 0;
        if (!wanted) continue;
        printf("== %s: %s\n", scenarios[i]->name, scenarios[i]->description);
        fflush(stdout);
        reset_peak_rss();
        ori_alloc_reset_peak();
        if (scenarios[i]->run() != 0) {
            printf("   FAILED\n");
            failed++;
        }
        ran++;
    }
    if (ran == 0) printf("no scenario matched\n");
    return failed ? 1 : 0;
}
