// Private pieces of the flat-foldability module shared by vertex.c (single-vertex theory) and
// check.c (pattern check and report).
#ifndef ORI_FLAT_INTERNAL_H
#define ORI_FLAT_INTERNAL_H

#include <orikin/flat.h>

#include "../core/core_internal.h"

// Degree up to which single-vertex routines work in stack memory (larger: one heap block).
#define ORI__FLAT_STACK_DEGREE 32

// Scratch memory for one single-vertex computation: a caller-provided (stack) buffer when it
// is large enough, else one heap block. Bump allocation, 16-byte aligned.
typedef struct ori__flat_ws {
    unsigned char *base;
    size_t used, cap;
    void *heap;
} ori__flat_ws;

void ori__flat_ws_begin(ori__flat_ws *ws, void *stack, size_t stack_bytes, size_t need);
void *ori__flat_ws_take(ori__flat_ws *ws, size_t bytes);
void ori__flat_ws_end(ori__flat_ws *ws);

// Saturating exact arithmetic on counts.
ori_mv_count ori__mv_mul(ori_mv_count a, ori_mv_count b);
ori_mv_count ori__mv_add(ori_mv_count a, ori_mv_count b);
// binom(n, k) exactly (0 outside 0 ≤ k ≤ n), overflow flagged.
ori_mv_count ori__binomial(int n, int k);

// Merge a vertex's full edge list (edges, sectors_rad of length n, from ori_pattern_vertex_sectors)
// into creases: F and J edges dropped, sectors merged across them. Writes at most cap entries of
// out_edges / out_sectors (either may be NULL); returns the crease count.
int ori__flat_merge_creases(const ori_pattern *pattern, const int *edges, const double *sectors_rad,
                            int n, int *out_edges, double *out_sectors, int cap);

// Fill a vertex report (all fields but vertex) from creases in cyclic order.
void ori__flat_vertex_report(const double *sectors_rad, const ori_assignment *creases, int n,
                             double sector_sum_rad, ori_vertex_report *out);

#endif
