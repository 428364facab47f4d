// Pattern-level verification: the creases of a vertex as the flat-foldability rules see them
// (F and J edges dropped, sectors merged), one vertex report, and the whole-pattern report with
// its violation list.
#include "flat_internal.h"

#include <stdarg.h>
#include <stdio.h>

#include "../pattern/pattern_internal.h"

static const char *const rule_names[ORI_FLAT_RULE_COUNT] = {"kawasaki", "maekawa", "big_little_big",
                                                            "assignment", "cone"};

const char *ori_flat_rule_name(ori_flat_rule rule)
{
    ORI_ASSERT((int)rule >= 0 && rule < ORI_FLAT_RULE_COUNT);
    return rule_names[rule];
}

static bool is_dropped(ori_assignment a) { return a == ORI_ASSIGN_FLAT || a == ORI_ASSIGN_JOIN; }

int ori__flat_merge_creases(const ori_pattern *p, const int *edges, const double *sectors, int n,
                            int *out_edges, double *out_sectors, int cap)
{
    int first = -1;
    for (int k = 0; k < n && first < 0; ++k)
        if (!is_dropped(p->edges[edges[k]].assignment)) first = k;
    if (first < 0) return 0;
    int count = 0;
    for (int j = 0; j < n; ++j) {
        int k = (first + j) % n;
        if (is_dropped(p->edges[edges[k]].assignment)) {
            // The paper across a flat crease is one sector: add its angle to the open one.
            if (out_sectors && count - 1 < cap && count > 0) out_sectors[count - 1] += sectors[k];
            continue;
        }
        if (count < cap) {
            if (out_edges) out_edges[count] = edges[k];
            if (out_sectors) out_sectors[count] = sectors[k];
        }
        count++;
    }
    return count;
}

int ori_flat_vertex_creases(const ori_pattern *p, int v, int *out_edges, double *out_sectors, int cap)
{
    ORI_ASSERT(p && p->built && v >= 0 && v < p->vertex_count && cap >= 0);
    int n = ori_pattern_vertex_degree(p, v);
    _Alignas(16) unsigned char stack[ORI__FLAT_STACK_DEGREE * (sizeof(int) + sizeof(double)) + 32];
    ori__flat_ws ws;
    ori__flat_ws_begin(&ws, stack, sizeof stack, (size_t)n * (sizeof(int) + sizeof(double)) + 32);
    int *edges = ori__flat_ws_take(&ws, sizeof(int) * (size_t)n);
    double *sectors = ori__flat_ws_take(&ws, sizeof(double) * (size_t)n);
    ori_pattern_vertex_sectors(p, v, edges, sectors, n);
    int count = ori__flat_merge_creases(p, edges, sectors, n, out_edges, out_sectors, cap);
    ori__flat_ws_end(&ws);
    return count;
}

// --- snapping a rounded vertex to the exact one it means ----------------------------------

double ori_flat_snap_sectors(const double *s, int n, double tol, double *out)
{
    ORI_ASSERT((s || n == 0) && out && n >= 0 && tol >= 0.0);
    if (n == 0) return 0.0;
    if (n % 2 != 0) return INFINITY;
    _Alignas(16) unsigned char stack[ORI__FLAT_STACK_DEGREE * (3 * sizeof(int) + 3 * sizeof(double)) + 64];
    ori__flat_ws ws;
    ori__flat_ws_begin(&ws, stack, sizeof stack, (size_t)n * (3 * sizeof(int) + 3 * sizeof(double)) + 64);
    int *order = ori__flat_ws_take(&ws, sizeof(int) * (size_t)n);
    int *cls = ori__flat_ws_take(&ws, sizeof(int) * (size_t)n);
    int *cn = ori__flat_ws_take(&ws, sizeof(int) * (size_t)n);  // class sizes
    double *ce = ori__flat_ws_take(&ws, sizeof(double) * (size_t)n); // class sign sums e_c
    double *ca = ori__flat_ws_take(&ws, sizeof(double) * (size_t)n); // class sector sums a_c
    double *orig = ori__flat_ws_take(&ws, sizeof(double) * (size_t)n);
    memcpy(orig, s, sizeof(double) * (size_t)n);
    // Insertion sort of the sector indices by value (degrees are small).
    for (int i = 0; i < n; ++i) {
        int j = i;
        while (j > 0 && orig[order[j - 1]] > orig[i]) {
            order[j] = order[j - 1];
            --j;
        }
        order[j] = i;
    }
    // Equality classes: a gap above tol in the sorted values starts a new class.
    int classes = 0;
    for (int k = 0; k < n; ++k) {
        int i = order[k];
        if (k == 0 || orig[i] - orig[order[k - 1]] > tol) {
            cn[classes] = 0;
            ce[classes] = 0.0;
            ca[classes] = 0.0;
            classes++;
        }
        int c = classes - 1;
        cls[i] = c;
        cn[c]++;
        ce[c] += (i % 2 == 0) ? 1.0 : -1.0;
        ca[c] += orig[i];
    }
    // β_c = m_c + p·e_c/n_c + q minimises Σ (β − α)² subject to Σ e_c β_c = 0 (Kawasaki) and
    // Σ n_c β_c = 2π. The 2 × 2 system is singular exactly when e_c/n_c is the same for every
    // class (integers: decided exactly); then Kawasaki either always holds (ratio 0) or never.
    bool proportional = true;
    for (int c = 1; c < classes && proportional; ++c)
        proportional = (long)ce[c] * cn[0] == (long)ce[0] * cn[c];
    double E2 = 0.0, E1 = 0.0, K = 0.0, S = 0.0;
    for (int c = 0; c < classes; ++c) {
        E2 += ce[c] * ce[c] / cn[c];
        E1 += ce[c];
        K += ce[c] * (ca[c] / cn[c]);
        S += ca[c];
    }
    double p = 0.0, q = 0.0, worst = 0.0;
    if (proportional) {
        if (ce[0] != 0.0) {
            worst = INFINITY;
            goto done;
        }
        q = (2.0 * ORI_PI - S) / n;
    } else {
        double D = E2 * n - E1 * E1;
        double r1 = -K, r2 = 2.0 * ORI_PI - S;
        p = (r1 * n - E1 * r2) / D;
        q = (E2 * r2 - E1 * r1) / D;
    }
    for (int i = 0; i < n; ++i) {
        int c = cls[i];
        double b = ca[c] / cn[c] + p * ce[c] / cn[c] + q;
        if (!(b > 0.0)) {
            worst = INFINITY;
            goto done;
        }
        double d = fabs(b - orig[i]);
        if (d > worst) worst = d;
        out[i] = b;
    }
done:
    if (!isfinite(worst)) memcpy(out, orig, sizeof(double) * (size_t)n);
    ori__flat_ws_end(&ws);
    return worst;
}

// Check vertex v; its creases and sectors are left in edges_out / sectors_out (capacity = the
// vertex degree). A vertex that fails exactly is checked again on its snapped sectors when
// tol > 0 (within tolerance when that passes and the snap moved no sector by more than tol).
static void check_vertex(const ori_pattern *p, int v, int *edges_out, double *sectors_out, double tol,
                         ori_vertex_report *r)
{
    int n_all = ori_pattern_vertex_degree(p, v);
    _Alignas(16) unsigned char stack[ORI__FLAT_STACK_DEGREE * (sizeof(int) + 2 * sizeof(double) + sizeof(ori_assignment)) + 96];
    ori__flat_ws ws;
    ori__flat_ws_begin(&ws, stack, sizeof stack,
                       (size_t)n_all * (sizeof(int) + 2 * sizeof(double) + sizeof(ori_assignment)) + 96);
    int *edges = ori__flat_ws_take(&ws, sizeof(int) * (size_t)n_all);
    double *sectors = ori__flat_ws_take(&ws, sizeof(double) * (size_t)n_all);
    ori_assignment *a = ori__flat_ws_take(&ws, sizeof(ori_assignment) * (size_t)n_all);
    ori_pattern_vertex_sectors(p, v, edges, sectors, n_all);
    double sum = 0.0;
    for (int k = 0; k < n_all; ++k) sum += sectors[k];
    int n = ori__flat_merge_creases(p, edges, sectors, n_all, edges_out, sectors_out, n_all);
    for (int i = 0; i < n; ++i) {
        ori_assignment x = p->edges[edges_out[i]].assignment;
        // B and C never occur at interior vertices; elsewhere they are creases of unknown sense.
        a[i] = (x == ORI_ASSIGN_MOUNTAIN || x == ORI_ASSIGN_VALLEY) ? x : ORI_ASSIGN_UNASSIGNED;
    }
    ori__flat_vertex_report(sectors_out, a, n, sum, r);
    r->vertex = v;
    r->within_tolerance = false;
    r->deviation_rad = 0.0;
    if (!r->flat_foldable && tol > 0.0 && n <= n_all) {
        double *snapped = ori__flat_ws_take(&ws, sizeof(double) * (size_t)(n + 1));
        double dev = ori_flat_snap_sectors(sectors_out, n, tol, snapped);
        if (dev <= tol) {
            ori_vertex_report rs;
            ori__flat_vertex_report(snapped, a, n, 2.0 * ORI_PI, &rs);
            if (rs.flat_foldable) {
                // Keep what was measured (sectors, alternating sum, sector sum) and the rule
                // answers of the exact vertex the drawing means.
                rs.vertex = v;
                rs.kawasaki_rad = r->kawasaki_rad;
                rs.sector_sum_rad = r->sector_sum_rad;
                rs.within_tolerance = true;
                rs.deviation_rad = dev;
                *r = rs;
            }
        }
    }
    ori__flat_ws_end(&ws);
}

void ori_flat_check_vertex(const ori_pattern *p, int v, ori_vertex_report *out)
{
    ORI_ASSERT(p && p->built && v >= 0 && v < p->vertex_count && out);
    int n = ori_pattern_vertex_degree(p, v);
    _Alignas(16) unsigned char stack[ORI__FLAT_STACK_DEGREE * (sizeof(int) + sizeof(double)) + 32];
    ori__flat_ws ws;
    ori__flat_ws_begin(&ws, stack, sizeof stack, (size_t)n * (sizeof(int) + sizeof(double)) + 32);
    int *edges = ori__flat_ws_take(&ws, sizeof(int) * (size_t)n);
    double *sectors = ori__flat_ws_take(&ws, sizeof(double) * (size_t)n);
    check_vertex(p, v, edges, sectors, 0.0, out);
    ori__flat_ws_end(&ws);
}

// --- pattern report ----------------------------------------------------------------------

struct ori_flat_report {
    int interior;
    int failed;
    int within;                      // vertices flat-foldable only within the tolerance
    double max_deviation;            // largest deviation among those
    int vertex_count;                // recorded vertex reports
    ori_vertex_report *vertices;
    int *crease_offsets;             // vertex_count + 1 entries (CSR into creases / sectors)
    int *creases;
    double *sectors;
    int violation_count, violation_cap;
    ori_flat_violation *violations;
};

ori_flat_check_def ori_default_flat_check_def(void)
{
    ori_flat_check_def def;
    def.record_vertices = true;
    def.tolerance_rad = 0.0;
    def.internal_value = ORI__DEF_COOKIE;
    return def;
}

static double deg(double rad) { return ori_rad_to_deg_output(rad); }

static void add_violation(ori_flat_report *rep, int vertex, ori_flat_rule rule, int edge, double value,
                          const char *fmt, ...) __attribute__((format(printf, 6, 7)));

static void add_violation(ori_flat_report *rep, int vertex, ori_flat_rule rule, int edge, double value,
                          const char *fmt, ...)
{
    ori_flat_violation x;
    x.vertex = vertex;
    x.rule = rule;
    x.edge = edge;
    x.value = value;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(x.detail, sizeof x.detail, fmt, ap);
    va_end(ap);
    ORI__PUSH(rep->violations, rep->violation_count, rep->violation_cap, x);
}

static const char *count_text(ori_mv_count c, char *buf, size_t size)
{
    if (c.overflow) snprintf(buf, size, "more than %llu", (unsigned long long)UINT64_MAX);
    else snprintf(buf, size, "%llu", (unsigned long long)c.count);
    return buf;
}

static void record_violations(ori_flat_report *rep, const ori_pattern *p, const ori_vertex_report *r,
                              const int *edges, const double *sectors)
{
    int v = r->vertex, n = r->degree;
    char buf[32];
    if (!r->kawasaki) {
        if (n % 2 != 0)
            add_violation(rep, v, ORI_FLAT_RULE_KAWASAKI, ORI_NULL_INDEX, r->kawasaki_rad,
                          "odd number of creases (%d): a flat fold needs an even number", n);
        else
            add_violation(rep, v, ORI_FLAT_RULE_KAWASAKI, ORI_NULL_INDEX, r->kawasaki_rad,
                          "alternating sector sum is %.6g deg (%.3g rad), not 0", deg(r->kawasaki_rad),
                          r->kawasaki_rad);
    }
    if (r->maekawa == ORI_FLAT_NO)
        add_violation(rep, v, ORI_FLAT_RULE_MAEKAWA, ORI_NULL_INDEX, (double)(r->mountains - r->valleys),
                      "M - V = %d (%d M, %d V), not +2 or -2", r->mountains - r->valleys, r->mountains,
                      r->valleys);
    if (!r->big_little_big) {
        int i = r->blb_crease, c = r->blb_run_creases;
        char letters[24];
        int nl = 0;
        for (int j = 0; j < c && nl < (int)sizeof letters - 4; ++j)
            letters[nl++] = ori_assignment_to_char(p->edges[edges[(i + j) % n]].assignment);
        letters[nl] = '\0';
        if (c - 1 == 1)
            add_violation(rep, v, ORI_FLAT_RULE_BIG_LITTLE_BIG, edges[i], sectors[i],
                          "sector %.6g deg between edges %d and %d is smaller than both neighbours, "
                          "but both creases are %c",
                          deg(sectors[i]), edges[i], edges[(i + 1) % n], letters[0]);
        else
            add_violation(rep, v, ORI_FLAT_RULE_BIG_LITTLE_BIG, edges[i], sectors[i],
                          "%d equal sectors of %.6g deg from edge %d are smaller than both neighbours; "
                          "their %d creases %s need %s",
                          c - 1, deg(sectors[i]), edges[i], c, letters,
                          (c % 2 == 0) ? "as many M as V" : "M - V = +1 or -1");
    }
    if (!r->assignment_valid && r->kawasaki) {
        if (r->unassigned > 0)
            add_violation(rep, v, ORI_FLAT_RULE_ASSIGNMENT, ORI_NULL_INDEX, 0.0,
                          "no choice of M/V for its %d unassigned creases folds flat (C = %s for the "
                          "sectors)",
                          r->unassigned, count_text(r->mv_count, buf, sizeof buf));
        else
            add_violation(rep, v, ORI_FLAT_RULE_ASSIGNMENT, ORI_NULL_INDEX, 0.0,
                          "this assignment does not fold flat (crimp reduction gets stuck); C = %s "
                          "other assignments do",
                          count_text(r->mv_count, buf, sizeof buf));
    }
    if (r->cone)
        add_violation(rep, v, ORI_FLAT_RULE_CONE, ORI_NULL_INDEX, r->sector_sum_rad - 2.0 * ORI_PI,
                      "sectors sum to %.10g deg (%+.3g rad off 360): the paper is a cone here",
                      deg(r->sector_sum_rad), r->sector_sum_rad - 2.0 * ORI_PI);
}

ori_flat_report *ori_flat_check_pattern(const ori_pattern *p, const ori_flat_check_def *def)
{
    ORI_ASSERT(p && p->built);
    ori_flat_check_def defaults = ori_default_flat_check_def();
    if (!def) def = &defaults;
    ORI_ASSERT(def->internal_value == ORI__DEF_COOKIE);
    ORI_ASSERT(def->tolerance_rad >= 0.0);
    ori_flat_report *rep = ori__calloc(1, sizeof *rep);
    int max_degree = 0;
    for (int v = 0; v < p->vertex_count; ++v) {
        int d = p->vert_edge_offsets[v + 1] - p->vert_edge_offsets[v];
        if (d > max_degree) max_degree = d;
    }
    int *edges = ori__alloc(sizeof(int) * (size_t)(max_degree + 1));
    double *sectors = ori__alloc(sizeof(double) * (size_t)(max_degree + 1));
    if (def->record_vertices) {
        // Size the per-vertex storage up front (no growth copies): one report per interior
        // vertex, at most its degree creases each.
        int count = 0;
        size_t creases = 0;
        for (int v = 0; v < p->vertex_count; ++v)
            if (ori_pattern_vertex_is_interior(p, v)) {
                count++;
                creases += (size_t)(p->vert_edge_offsets[v + 1] - p->vert_edge_offsets[v]);
            }
        rep->vertices = ori__alloc(sizeof(ori_vertex_report) * (size_t)(count ? count : 1));
        rep->crease_offsets = ori__alloc(sizeof(int) * ((size_t)count + 1));
        rep->creases = ori__alloc(sizeof(int) * (creases ? creases : 1));
        rep->sectors = ori__alloc(sizeof(double) * (creases ? creases : 1));
        rep->crease_offsets[0] = 0;
    }
    for (int v = 0; v < p->vertex_count; ++v) {
        if (!ori_pattern_vertex_is_interior(p, v)) continue;
        ori_vertex_report r;
        check_vertex(p, v, edges, sectors, def->tolerance_rad, &r);
        rep->interior++;
        if (r.within_tolerance) {
            rep->within++;
            if (r.deviation_rad > rep->max_deviation) rep->max_deviation = r.deviation_rad;
        }
        if (!r.flat_foldable) {
            rep->failed++;
            record_violations(rep, p, &r, edges, sectors);
        }
        if (def->record_vertices) {
            int i = rep->vertex_count++;
            int base = rep->crease_offsets[i];
            rep->vertices[i] = r;
            if (r.degree > 0) {
                memcpy(rep->creases + base, edges, sizeof(int) * (size_t)r.degree);
                memcpy(rep->sectors + base, sectors, sizeof(double) * (size_t)r.degree);
            }
            rep->crease_offsets[i + 1] = base + r.degree;
        }
    }
    ori__free(edges);
    ori__free(sectors);
    return rep;
}

void ori_flat_report_destroy(ori_flat_report *rep)
{
    if (!rep) return;
    ori__free(rep->vertices);
    ori__free(rep->crease_offsets);
    ori__free(rep->creases);
    ori__free(rep->sectors);
    ori__free(rep->violations);
    ori__free(rep);
}

bool ori_flat_report_flat_foldable(const ori_flat_report *rep)
{
    ORI_ASSERT(rep);
    return rep->failed == 0;
}

int ori_flat_report_interior_count(const ori_flat_report *rep)
{
    ORI_ASSERT(rep);
    return rep->interior;
}

int ori_flat_report_failed_count(const ori_flat_report *rep)
{
    ORI_ASSERT(rep);
    return rep->failed;
}

int ori_flat_report_within_count(const ori_flat_report *rep)
{
    ORI_ASSERT(rep);
    return rep->within;
}

double ori_flat_report_max_deviation(const ori_flat_report *rep)
{
    ORI_ASSERT(rep);
    return rep->max_deviation;
}

int ori_flat_report_vertex_count(const ori_flat_report *rep)
{
    ORI_ASSERT(rep);
    return rep->vertex_count;
}

ori_vertex_report ori_flat_report_vertex(const ori_flat_report *rep, int i)
{
    ORI_ASSERT(rep && i >= 0 && i < rep->vertex_count);
    return rep->vertices[i];
}

int ori_flat_report_vertex_creases(const ori_flat_report *rep, int i, int *edges, double *sectors_rad, int cap)
{
    ORI_ASSERT(rep && i >= 0 && i < rep->vertex_count && cap >= 0);
    int b = rep->crease_offsets[i], n = rep->crease_offsets[i + 1] - b;
    int m = n < cap ? n : cap;
    if (edges && m > 0) memcpy(edges, rep->creases + b, sizeof(int) * (size_t)m);
    if (sectors_rad && m > 0) memcpy(sectors_rad, rep->sectors + b, sizeof(double) * (size_t)m);
    return n;
}

int ori_flat_report_violation_count(const ori_flat_report *rep)
{
    ORI_ASSERT(rep);
    return rep->violation_count;
}

ori_flat_violation ori_flat_report_violation(const ori_flat_report *rep, int i)
{
    ORI_ASSERT(rep && i >= 0 && i < rep->violation_count);
    return rep->violations[i];
}
