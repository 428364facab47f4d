// Import scenarios on inputs built to be costly (issue 14: every reader linear or n log n on any
// input): an SVG style sheet of n rules styling n elements, random line soups (every pair of
// lines may cross: the output itself grows as n²), a drawing of tens of thousands of separate
// pieces (the islands check), and the memory of loading a big FOLD file relative to its size.
#include <math.h>
#include <stdarg.h>
#include <orikin/formats.h>
#include <orikin/generate.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

typedef struct text {
    char *s;
    size_t n, cap;
} text;

static void put(text *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void put(text *t, const char *fmt, ...)
{
    va_list ap;
    for (;;) {
        va_start(ap, fmt);
        int k = vsnprintf(t->s + t->n, t->cap - t->n, fmt, ap);
        va_end(ap);
        if ((size_t)k < t->cap - t->n) {
            t->n += (size_t)k;
            return;
        }
        t->cap = t->cap ? 2 * t->cap : 1 << 16;
        t->s = realloc(t->s, t->cap);
    }
}

static double rnd(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return (double)(*s >> 8) / 16777216.0;
}

// Read and planarise an SVG text; prints the figures. Returns the status.
static ori_status import_svg(const char *what, const text *t)
{
    ori_segment *segs = NULL;
    int n = 0;
    ori_error err;
    double t0 = bench_now();
    ori_status st = ori_svg_read_segments(t->s, t->n, &segs, &n, NULL, &err);
    double t1 = bench_now();
    ori_pattern *p = NULL;
    if (st == ORI_OK) st = ori_segments_to_pattern(segs, n, NULL, &p, &err);
    double t2 = bench_now();
    if (st == ORI_OK)
        printf("   %-34s %7.2f MB: read %.3f s, planarise %.3f s -> %d vertices, %d edges, %d faces\n", what,
               (double)t->n / 1e6, t1 - t0, t2 - t1, ori_pattern_vertex_count(p), ori_pattern_edge_count(p),
               ori_pattern_face_count(p));
    else
        printf("   %-34s failed: %s\n", what, err.message);
    ori_buffer_free(segs);
    ori_pattern_destroy(p);
    return st;
}

static int run(void)
{
    const char *head = "<svg xmlns=\"http://www.w3.org/2000/svg\">";
    // 1. A style sheet of 20 000 class rules styling 20 000 lines (was rules × elements).
    text t = {NULL, 0, 0};
    put(&t, "%s<style>", head);
    for (int i = 0; i < 20000; ++i) put(&t, ".c%d { stroke: #ff0000 }\n", i);
    put(&t, "</style>");
    for (int i = 0; i < 20000; ++i) put(&t, "<line class=\"c%d\" x1=\"%d\" y1=\"0\" x2=\"%d\" y2=\"10\"/>\n", i, i, i);
    put(&t, "</svg>");
    if (import_svg("css: 20k rules x 20k lines", &t) != ORI_OK) return 1;
    // 2. Random line soups: n lines across the drawing, about n²/4 crossings.
    for (int n = 400; n <= 1600; n *= 2) {
        t.n = 0;
        put(&t, "%s", head);
        unsigned s = (unsigned)n;
        for (int i = 0; i < n; ++i)
            put(&t, "<line x1=\"%.6f\" y1=\"%.6f\" x2=\"%.6f\" y2=\"%.6f\" stroke=\"#ff0000\"/>\n", 100 * rnd(&s),
                100 * rnd(&s), 100 * rnd(&s), 100 * rnd(&s));
        put(&t, "</svg>");
        char what[64];
        snprintf(what, sizeof what, "soup: %d random lines", n);
        if (import_svg(what, &t) != ORI_OK) return 1;
    }
    // 3. 62 500 separate triangles (each its own piece: the islands check).
    t.n = 0;
    put(&t, "%s", head);
    for (int i = 0; i < 250; ++i)
        for (int j = 0; j < 250; ++j)
            put(&t, "<path d=\"M%d %d L%d %d L%d %d Z\" stroke=\"#000000\"/>\n", 3 * i, 3 * j, 3 * i + 1, 3 * j, 3 * i, 3 * j + 1);
    put(&t, "</svg>");
    if (import_svg("pieces: 62 500 separate triangles", &t) != ORI_OK) return 1;
    free(t.s);

    // 4. Memory of a FOLD file: a 300 × 300 Miura-ori loaded (document) and built (pattern).
    ori_generate_def def = ori_default_generate_def(ORI_TESS_MIURA);
    def.rows = def.cols = 300;
    ori_pattern *p = NULL;
    ori_error err;
    if (ori_generate(&def, &p, NULL, &err) != ORI_OK) return 1;
    size_t size;
    char *fold = ori_pattern_to_fold_text(p, NULL, 0, &size);
    ori_pattern_destroy(p);
    ori_alloc_reset_peak();
    int64_t base = ori_alloc_live_bytes();
    double t0 = bench_now();
    ori_fold *doc = NULL;
    if (ori_fold_load_string(fold, size, &doc, &err) != ORI_OK) return 1;
    double t1 = bench_now();
    int64_t doc_bytes = ori_alloc_live_bytes() - base, doc_peak = ori_alloc_peak_bytes() - base;
    if (ori_fold_get_pattern(doc, 0, NULL, &p, &err) != ORI_OK) return 1;
    double t2 = bench_now();
    int64_t all_peak = ori_alloc_peak_bytes() - base;
    printf("   fold: %.1f MB Miura-ori 300 x 300: parse %.3f s (document %.2fx the text, peak %.2fx), "
           "pattern %.3f s (peak with the document %.2fx)\n",
           (double)size / 1e6, t1 - t0, (double)doc_bytes / (double)size, (double)doc_peak / (double)size, t2 - t1,
           (double)all_peak / (double)size);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    ori_buffer_free(fold);
    return 0;
}

const bench_scenario bench_import = {"import",
                                     "costly imports: SVG style sheets, line soups, many pieces; FOLD load memory",
                                     run};
