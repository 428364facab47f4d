// Generator scenario: a 1000 × 1000 Miura-ori (1 M faces, 2 M edges) generated, validated and
// written as FOLD; time per phase and peak memory (library heap and process RSS).
#include <orikin/formats.h>
#include <orikin/generate.h>
#include <stdio.h>
#include <string.h>

#include "bench.h"

static int run(void)
{
    ori_generate_def def = ori_default_generate_def(ORI_TESS_MIURA);
    def.rows = def.cols = 1000;
    ori_error err;
    ori_pattern *p = NULL;
    ori_edge_class *cls = NULL;
    ori_alloc_reset_peak();
    int64_t base = ori_alloc_live_bytes();
    double t0 = bench_now();
    if (ori_generate(&def, &p, &cls, &err) != ORI_OK) return 1;
    double t1 = bench_now();
    int64_t gen_peak = ori_alloc_peak_bytes() - base;
    size_t bytes;
    char *text = ori_pattern_to_fold_text(p, NULL, 0, &bytes);
    double t2 = bench_now();
    const char *path = "bench_generate.fold";
    ori_status st = ori_file_write_atomic(path, text, bytes, &err);
    double t3 = bench_now();
    remove(path);
    int64_t heap = ori_alloc_peak_bytes() - base;
    int64_t rss = bench_peak_rss();
    printf("   %d vertices, %d edges, %d faces\n", ori_pattern_vertex_count(p), ori_pattern_edge_count(p),
           ori_pattern_face_count(p));
    printf("   generate+validate %.3f s (library heap peak %.1f MB)\n", t1 - t0, (double)gen_peak / 1e6);
    printf("   FOLD text (direct writer) %.3f s (%.1f MB), write %.3f s\n", t2 - t1, (double)bytes / 1e6, t3 - t2);
    printf("   peak: library heap %.1f MB, process RSS %.1f MB\n", (double)heap / 1e6, (double)rss / 1e6);
    // For comparison: the same document through the JSON tree (ori_fold_set_pattern + to_string).
    double t4 = bench_now();
    ori_fold *doc = ori_fold_create();
    if (ori_fold_set_pattern(doc, 0, p, &err) != ORI_OK) return 1;
    char *tree_text = ori_fold_to_string(doc);
    double t5 = bench_now();
    printf("   (JSON-tree path for comparison: %.3f s, process RSS peak then %.1f MB, same text: %s)\n", t5 - t4,
           (double)bench_peak_rss() / 1e6, strcmp(tree_text, text) == 0 ? "yes" : "NO");
    ori_buffer_free(tree_text);
    ori_fold_destroy(doc);
    ori_buffer_free(text);
    ori_buffer_free(cls);
    ori_pattern_destroy(p);
    return st == ORI_OK ? 0 : 1;
}

const bench_scenario bench_generate = {"generate", "Miura-ori 1000x1000: generate, validate, write FOLD", run};
