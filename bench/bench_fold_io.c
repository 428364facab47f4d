// FOLD I/O scenario: write and re-read a generated square grid crease pattern.
#include <stdio.h>
#include <string.h>

#include "bench.h"

static int run(void)
{
    const int n = 300; // n × n squares: (n+1)² vertices, 2n(n+1) edges
    ori_pattern_def def = ori_default_pattern_def();
    ori_pattern *p = ori_pattern_create(&def);
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) ori_pattern_add_vertex(p, ori_v3_make(i, j, 0));
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            int v = j * (n + 1) + i;
            bool bj = j == 0 || j == n, bi = i == 0 || i == n;
            if (i < n) ori_pattern_add_edge(p, v, v + 1, bj ? ORI_ASSIGN_BOUNDARY : ORI_ASSIGN_MOUNTAIN, 0);
            if (j < n) ori_pattern_add_edge(p, v, v + n + 1, bi ? ORI_ASSIGN_BOUNDARY : ORI_ASSIGN_VALLEY, 0);
        }
    ori_error err;
    double t0 = bench_now();
    if (ori_pattern_build(p, NULL, &err) != ORI_OK) return 1;
    double t1 = bench_now();
    ori_fold *doc = ori_fold_create();
    ori_fold_set_pattern(doc, 0, p, &err);
    char *text = ori_fold_to_string(doc);
    double t2 = bench_now();
    ori_fold *again = NULL;
    ori_pattern *q = NULL;
    if (ori_fold_load_string(text, strlen(text), &again, &err) != ORI_OK) return 1;
    if (ori_fold_get_pattern(again, 0, NULL, &q, &err) != ORI_OK) return 1;
    double t3 = bench_now();
    printf("   %d vertices, %d edges, %d faces; %.1f MB of FOLD text\n", ori_pattern_vertex_count(q),
           ori_pattern_edge_count(q), ori_pattern_face_count(q), (double)strlen(text) / 1e6);
    printf("   build+validate %.3f s, write %.3f s, read+validate %.3f s\n", t1 - t0, t2 - t1, t3 - t2);
    ori_buffer_free(text);
    ori_pattern_destroy(q);
    ori_pattern_destroy(p);
    ori_fold_destroy(again);
    ori_fold_destroy(doc);
    return 0;
}

const bench_scenario bench_fold_io = {"fold_io", "FOLD write and read of a 300x300 grid pattern", run};
