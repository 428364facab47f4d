// unfold-linkage: Streinu's expansive motions. Every kept frame of every motion is checked:
// bar lengths kept (1e-9 relative), no vertex–vertex distance decreases (beyond 1e-9 of the
// size), no two bars cross (exact predicate), and the last frame is straight or convex.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "support.h"
#include "unfold/unfold_internal.h"

#include <jansson.h>
#include <stdio.h>

#define PI 3.14159265358979323846

typedef struct lcase {
    ori_v2 *p;
    int n, m;
    int *e;
} lcase;

static lcase make(const ori_v2 *p, int n, bool closed)
{
    lcase c = {malloc(sizeof(ori_v2) * (size_t)n), n, closed ? n : n - 1, malloc(sizeof(int) * 2 * (size_t)n)};
    for (int i = 0; i < n; ++i) c.p[i] = p[i];
    for (int i = 0; i < c.m; ++i) c.e[2 * i] = i, c.e[2 * i + 1] = (i + 1) % n;
    return c;
}

typedef struct bbar {
    double lo, hi;
    int k;
} bbar;
static int cmp_bbar(const void *x, const void *y)
{
    double a = ((const bbar *)x)->lo, b = ((const bbar *)y)->lo;
    return a < b ? -1 : a > b;
}

// No two bars of frame p intersect (exact predicate; bars sharing a vertex skipped): a sweep over
// the bars sorted by their smallest x prunes the pairs.
static void check_no_crossing(const lcase *c, const ori_v2 *p, int f, bbar *bb)
{
    for (int k = 0; k < c->m; ++k) {
        double xa = p[c->e[2 * k]].x, xb = p[c->e[2 * k + 1]].x;
        bb[k] = (bbar){fmin(xa, xb), fmax(xa, xb), k};
    }
    qsort(bb, (size_t)c->m, sizeof *bb, cmp_bbar);
    for (int i = 0; i < c->m; ++i)
        for (int j = i + 1; j < c->m && bb[j].lo <= bb[i].hi; ++j) {
            int k = bb[i].k, l = bb[j].k;
            int a = c->e[2 * k], b = c->e[2 * k + 1], x = c->e[2 * l], y = c->e[2 * l + 1];
            if (a == x || a == y || b == x || b == y) continue;
            cr_assert(!ori__segments_intersect(p[a], p[b], p[x], p[y]), "frame %d: bars %d and %d cross", f, k, l);
        }
}

static ori_linkage_result check_motion_per(const lcase *c, bool closed, int per)
{
    ori_linkage_def def = ori_default_linkage_def();
    def.coords = c->p, def.vertex_count = c->n, def.edges = c->e, def.edge_count = c->m;
    def.steps_per_event = per;
    ori_linkage_motion *mo = NULL;
    ori_error err;
    cr_assert_eq(ori_linkage_unfold(&def, &mo, &err), ORI_OK, "%d vertices: %s", c->n, err.message);
    ori_linkage_result r = ori_linkage_motion_result(mo);
    cr_assert_eq(r.kind, closed ? ORI_LINKAGE_POLYGON : ORI_LINKAGE_CHAIN);
    cr_assert(r.final_ok);
    double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
    for (int i = 0; i < c->n; ++i)
        lo_x = fmin(lo_x, c->p[i].x), hi_x = fmax(hi_x, c->p[i].x), lo_y = fmin(lo_y, c->p[i].y), hi_y = fmax(hi_y, c->p[i].y);
    double size = hypot(hi_x - lo_x, hi_y - lo_y);
    int F = ori_linkage_motion_frame_count(mo);
    cr_assert(F > 1 || r.steps == 0); // an input already straight or convex has only its first frame
    bbar *bb = malloc(sizeof *bb * (size_t)c->m);
    for (int f = 0; f < F; ++f) {
        const ori_v2 *p = ori_linkage_motion_frame(mo, f);
        for (int k = 0; k < c->m; ++k) {
            int a = c->e[2 * k], b = c->e[2 * k + 1];
            double L0 = ori_v2_norm(ori_v2_sub(c->p[a], c->p[b])), L = ori_v2_norm(ori_v2_sub(p[a], p[b]));
            cr_assert_leq(fabs(L - L0) / L0, 1e-9, "frame %d bar %d: length %.17g vs %.17g", f, k, L, L0);
        }
        check_no_crossing(c, p, f, bb);
        if (f == 0) continue;
        const ori_v2 *q = ori_linkage_motion_frame(mo, f - 1);
        for (int a = 0; a < c->n; ++a)
            for (int b = a + 1; b < c->n; ++b) {
                double px = p[a].x - p[b].x, py = p[a].y - p[b].y, qx = q[a].x - q[b].x, qy = q[a].y - q[b].y;
                double d = sqrt(px * px + py * py) - sqrt(qx * qx + qy * qy);
                if (d < -1e-9 * size) cr_assert_fail("frame %d: distance %d–%d decreases by %g", f, a, b, d);
            }
    }
    free(bb);
    // the last frame: straight chain (every joint at 180°) or convex polygon (one turning sign)
    const ori_v2 *p = ori_linkage_motion_frame(mo, F - 1);
    int sign = 0;
    for (int i = 1; i + (closed ? 0 : 1) < c->n + (closed ? 1 : 0); ++i) {
        ori_v2 a = ori_v2_sub(p[i % c->n], p[i - 1]), b = ori_v2_sub(p[(i + 1) % c->n], p[i % c->n]);
        double s = ori_v2_cross(a, b) / (ori_v2_norm(a) * ori_v2_norm(b));
        if (!closed) cr_assert_leq(fabs(s), 1e-9, "joint %d not straight: sin %g", i, s);
        if (!closed) cr_assert_gt(ori_v2_dot(a, b), 0.0, "joint %d folded back", i);
        if (closed && fabs(s) > 1e-9) {
            int si = s > 0 ? 1 : -1;
            cr_assert(sign == 0 || si == sign, "polygon not convex at vertex %d", i % c->n);
            sign = si;
        }
    }
    cr_assert_leq(r.max_length_error, 1e-9);
    cr_assert_geq(r.min_distance_change, -1e-9 * size);
    cr_assert_leq(r.max_event_residual, 1e-6); // sine of the aligned angle where the bracket closed
    ori_linkage_motion_destroy(mo);
    return r;
}

static void check_motion(const lcase *c, bool closed) { (void)check_motion_per(c, closed, 4); }

static void free_case(lcase *c) { free(c->p), free(c->e); }

// Random simple polygon: random points in the unit square, a random tour untangled by 2-opt
// (reverse the path between two crossing edges until none cross).
static void random_polygon(unsigned seed, int n, ori_v2 *p)
{
    srand(seed);
    for (int i = 0; i < n; ++i) p[i] = ori_v2_make((double)rand() / RAND_MAX, (double)rand() / RAND_MAX);
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

// Random simple polygons and the open chains on the same vertices (the polygon minus its last
// bar), 20 to 100 vertices: every one must reach its end state.
static void random_batch(int n, unsigned seeds, bool closed)
{
    ori_v2 *p = malloc(sizeof *p * (size_t)n);
    for (unsigned seed = 1; seed <= seeds; ++seed) {
        random_polygon(seed, n, p);
        lcase c = make(p, n, closed);
        check_motion(&c, closed);
        free_case(&c);
    }
    free(p);
}

Test(linkage, random_polygons, .init = test_leak_setup, .fini = test_leak_check, .timeout = 900)
{
    random_batch(8, 4, true);
    random_batch(20, 12, true);
    random_batch(50, 10, true);
    random_batch(100, 4, true);
}

Test(linkage, random_chains, .init = test_leak_setup, .fini = test_leak_check, .timeout = 900)
{
    random_batch(8, 4, false);
    random_batch(20, 12, false);
    random_batch(50, 10, false);
    random_batch(100, 4, false);
}

// 200 vertices: one polygon, one chain (every frame checked as above).
Test(linkage, random_200, .init = test_leak_setup, .fini = test_leak_check, .timeout = 900)
{
    ori_v2 *p = malloc(sizeof *p * 200);
    random_polygon(1, 200, p);
    for (int closed = 0; closed < 2; ++closed) {
        lcase c = make(p, 200, closed);
        check_motion(&c, closed);
        free_case(&c);
    }
    free(p);
}

// 500 vertices, one polygon and one chain; the kept frames are the events (steps_per_event 1),
// so expansion is checked between consecutive events. Release builds only: the debug (ASan)
// build would take many minutes.
#ifdef NDEBUG
Test(linkage, random_500, .init = test_leak_setup, .fini = test_leak_check, .timeout = 1200)
{
    ori_v2 *p = malloc(sizeof *p * 500);
    random_polygon(1, 500, p);
    for (int closed = 0; closed < 2; ++closed) {
        lcase c = make(p, 500, closed);
        ori_linkage_result r = check_motion_per(&c, closed, 1);
        cr_assert_gt(r.events, 500);
        free_case(&c);
    }
    free(p);
}
#endif

// A 40-vertex open spiral (an Archimedean spiral's points every half radian).
static lcase spiral40(void)
{
    ori_v2 p[40];
    for (int i = 0; i < 40; ++i) {
        double t = 0.5 * i, r = 0.3 + 0.15 * t;
        p[i] = ori_v2_make(r * cos(t), r * sin(t));
    }
    return make(p, 40, false);
}

Test(linkage, spiral_chain, .init = test_leak_setup, .fini = test_leak_check)
{
    lcase c = spiral40();
    check_motion(&c, false);
    free_case(&c);
}

// The event bound (docs/conventions.md, "Bounded work"): the spiral needs many events; with
// max_events at half that count the run stops with ORI_ERR_LIMIT, names the bound and hands out
// nothing; with the bound at the count it needs, it finishes. (The bound is checked before each
// motion segment, so the event that ends the motion may be the one past it.)
Test(linkage, event_limit_stops_the_motion, .init = test_leak_setup, .fini = test_leak_check)
{
    lcase c = spiral40();
    ori_linkage_def def = ori_default_linkage_def();
    def.coords = c.p, def.vertex_count = c.n, def.edges = c.e, def.edge_count = c.m;
    ori_linkage_motion *mo = NULL;
    ori_error err;
    cr_assert_eq(ori_linkage_unfold(&def, &mo, &err), ORI_OK, "%s", err.message);
    int events = ori_linkage_motion_result(mo).events;
    ori_linkage_motion_destroy(mo);
    cr_assert_gt(events, 2);
    def.max_events = events / 2;
    mo = NULL;
    cr_assert_eq(ori_linkage_unfold(&def, &mo, &err), ORI_ERR_LIMIT);
    cr_assert_null(mo);
    cr_assert(strstr(err.message, "events") != NULL, "%s", err.message);
    // With keep_partial the motion so far: exactly max_events events, not straight, every bar
    // length kept and no distance decreasing over its frames, its last frame an event.
    def.keep_partial = true;
    cr_assert_eq(ori_linkage_unfold(&def, &mo, &err), ORI_ERR_LIMIT);
    cr_assert_not_null(mo);
    ori_linkage_result r = ori_linkage_motion_result(mo);
    cr_assert(r.stopped && !r.final_ok);
    cr_assert_eq(r.events, events / 2);
    cr_assert_eq(r.frames, ori_linkage_motion_frame_count(mo));
    cr_assert_gt(r.frames, 1);
    cr_assert(ori_linkage_motion_frame_is_event(mo, r.frames - 1));
    cr_assert_leq(r.max_length_error, 1e-12);
    cr_assert_geq(r.min_distance_change, -1e-12);
    ori_linkage_motion_destroy(mo);
    mo = NULL;
    def.keep_partial = false;
    def.max_events = events;
    cr_assert_eq(ori_linkage_unfold(&def, &mo, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_linkage_motion_result(mo).events, events);
    ori_linkage_motion_destroy(mo);
    free_case(&c);
}

// Progress: the chain's end distance over its length, never decreasing, 1 at the straight end;
// returning false cancels with ORI_ERR_LIMIT (not retried with another perturbation), and with
// keep_partial the motion up to the cancel comes back.
typedef struct lk_fractions {
    double last;
    int n, cancel_at;
    bool monotone;
} lk_fractions;
static bool lk_record(double f, void *user)
{
    lk_fractions *F = user;
    if (f < F->last || f < 0.0 || f > 1.0) F->monotone = false;
    F->last = f;
    return ++F->n != F->cancel_at;
}
Test(linkage, progress_and_cancel, .init = test_leak_setup, .fini = test_leak_check)
{
    lcase c = spiral40();
    ori_linkage_def def = ori_default_linkage_def();
    def.coords = c.p, def.vertex_count = c.n, def.edges = c.e, def.edge_count = c.m;
    lk_fractions F = {0.0, 0, -1, true};
    def.progress = lk_record, def.progress_user = &F;
    ori_linkage_motion *mo = NULL;
    ori_error err;
    cr_assert_eq(ori_linkage_unfold(&def, &mo, &err), ORI_OK, "%s", err.message);
    ori_linkage_result r = ori_linkage_motion_result(mo);
    ori_linkage_motion_destroy(mo);
    cr_assert(F.monotone);
    cr_assert_gt(F.n, 2);
    cr_assert_leq(F.n, r.events + 1);
    cr_assert_gt(F.last, 0.5, "the chain is mostly straight before its last events: %g", F.last);
    F = (lk_fractions){0.0, 0, 3, true};
    def.keep_partial = true;
    mo = NULL;
    cr_assert_eq(ori_linkage_unfold(&def, &mo, &err), ORI_ERR_LIMIT);
    cr_assert(strstr(err.message, "cancelled") != NULL, "%s", err.message);
    cr_assert_eq(F.n, 3, "one cancel, no retry");
    cr_assert_not_null(mo);
    cr_assert(ori_linkage_motion_result(mo).stopped);
    cr_assert_lt(ori_linkage_motion_result(mo).events, r.events);
    ori_linkage_motion_destroy(mo);
    free_case(&c);
}

Test(linkage, star_polygon, .init = test_leak_setup, .fini = test_leak_check)
{
    ori_v2 p[16];
    for (int i = 0; i < 16; ++i) {
        double r = i % 2 ? 1.0 : 0.4;
        p[i] = ori_v2_make(r * cos(2 * PI * i / 16), r * sin(2 * PI * i / 16));
    }
    lcase c = make(p, 16, true);
    check_motion(&c, true);
    free_case(&c);
}




// Knitting needles (Connelly–Demaine–Rote's locked 3D example, flattened): two long bars
// folded back over a short zig-zag, slightly rotated off the axes.
Test(linkage, knitting_chain, .init = test_leak_setup, .fini = test_leak_check)
{
    ori_v2 q[] = {{0.0, 3.0}, {0.35, 0.1}, {0.6, 0.55}, {0.9, 0.12}, {1.2, 0.5}, {1.55, 0.05}, {1.9, 3.1}};
    int n = (int)(sizeof q / sizeof *q);
    for (int i = 0; i < n; ++i) q[i] = ori_v2_make(q[i].x * cos(0.1) - q[i].y * sin(0.1), q[i].x * sin(0.1) + q[i].y * cos(0.1));
    lcase c = make(q, n, false);
    check_motion(&c, false);
    free_case(&c);
}

// A doubly wound polygon: a thin strip along a spiral of two turns (out along one spiral, back
// along a parallel one), closed at both ends.
Test(linkage, doubly_wound_polygon, .init = test_leak_setup, .fini = test_leak_check)
{
    ori_v2 p[64];
    int n = 0, k = 30;
    for (int i = 0; i < k; ++i) {
        double t = 4 * PI * i / (k - 1), r = 1.0 + 0.4 * t / (2 * PI);
        p[n++] = ori_v2_make(r * cos(t), r * sin(t));
    }
    for (int i = k - 1; i >= 0; --i) {
        double t = 4 * PI * i / (k - 1) + 0.013, r = 1.15 + 0.4 * t / (2 * PI);
        p[n++] = ori_v2_make(r * cos(t), r * sin(t));
    }
    lcase c = make(p, n, true);
    check_motion(&c, true);
    free_case(&c);
}

Test(linkage, refused, .init = test_leak_setup, .fini = test_leak_check)
{
    ori_v2 p[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 2}};
    int tree[] = {0, 1, 0, 2, 0, 3};
    int cross[] = {0, 2, 1, 3};
    int dup_e[] = {0, 1, 1, 2};
    ori_v2 dup_p[] = {{0, 0}, {1, 0}, {0, 0}};
    ori_linkage_def def = ori_default_linkage_def();
    ori_linkage_motion *mo = NULL;
    ori_error err;
    def.coords = p, def.vertex_count = 4, def.edges = tree, def.edge_count = 3;
    cr_assert_eq(ori_linkage_unfold(&def, &mo, &err), ORI_ERR_TOPOLOGY);
    cr_assert_eq(err.element, 0);
    cr_assert(strstr(err.message, "trees can lock"));
    def.edges = cross, def.edge_count = 2;
    cr_assert_eq(ori_linkage_unfold(&def, &mo, &err), ORI_ERR_TOPOLOGY); // two separate bars
    int chain_cross[] = {0, 2, 2, 1, 1, 3};
    def.edges = chain_cross, def.edge_count = 3;
    cr_assert_eq(ori_linkage_unfold(&def, &mo, &err), ORI_ERR_CROSSING);
    cr_assert_eq(err.element, 2);
    def.coords = dup_p, def.vertex_count = 3, def.edges = dup_e, def.edge_count = 2;
    cr_assert_eq(ori_linkage_unfold(&def, &mo, &err), ORI_ERR_DUPLICATE);
    cr_assert_eq(err.element, 2);
    cr_assert_null(mo);
}

// Degenerate inputs: straight joints (collinear consecutive bars, on the hull or not) are already
// straight; a vertex exactly between two others (a regular zig-zag: its lower points on one line;
// a notch vertex exactly on both diagonals of a square) is handled by the symbolic perturbation.
Test(linkage, collinear_inputs, .init = test_leak_setup, .fini = test_leak_check)
{
    ori_v2 sq[] = {{0, 0}, {1, 0}, {2, 0}, {2, 2}, {1, 1.2}, {0, 2}}; // notched, straight joint at (1, 0)
    lcase c = make(sq, 6, true);
    check_motion(&c, true);
    free_case(&c);
    ori_v2 ch[] = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {0.5, 1}};
    c = make(ch, 5, false);
    check_motion(&c, false);
    free_case(&c);
    ori_v2 zz[] = {{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}, {5, 1}, {6, 0}};
    c = make(zz, 7, false);
    check_motion(&c, false);
    free_case(&c);
    c = make(zz, 7, true); // closed: the bar 6–0 lies on the line through 2 and 4
    ori_linkage_def def = ori_default_linkage_def();
    def.coords = c.p, def.vertex_count = c.n, def.edges = c.e, def.edge_count = c.m;
    ori_linkage_motion *mo = NULL;
    ori_error err;
    cr_assert_eq(ori_linkage_unfold(&def, &mo, &err), ORI_ERR_CROSSING, "%s", err.message); // 6–0 touches vertex 2
    free_case(&c);
    ori_v2 notch[] = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 2}}; // (2, 2) on both diagonals
    c = make(notch, 5, true);
    check_motion(&c, true);
    free_case(&c);
    // a grid-like comb: many vertices on common lines
    ori_v2 comb[] = {{0, 0}, {0, 2}, {1, 2}, {1, 0}, {2, 0}, {2, 2}, {3, 2}, {3, 0}, {4, 0}, {4, 2}};
    c = make(comb, 10, false);
    check_motion(&c, false);
    free_case(&c);
}

// Integer-grid linkages (4–12 vertices on an 8 × 8 grid, 2-opt untangled): many exact
// collinearities. Those the validation accepts (no bar touching another) must all unfold; among
// them the chain [5,0] [4,0] [3,3] [7,7] [5,7] [1,4] [3,0], which the first perturbation fails.
Test(linkage, grid_linkages, .init = test_leak_setup, .fini = test_leak_check, .timeout = 600)
{
    ori_v2 g26[] = {{5, 0}, {4, 0}, {3, 3}, {7, 7}, {5, 7}, {1, 4}, {3, 0}};
    lcase c = make(g26, 7, false);
    check_motion(&c, false);
    free_case(&c);
    srand(11);
    int accepted = 0;
    for (int t = 0; t < 300; ++t) {
        int n = 4 + rand() % 9;
        ori_v2 p[12];
        for (int i = 0; i < n; ++i) p[i] = ori_v2_make(rand() % 8, rand() % 8);
        for (int it = 0, changed = 1; changed && it < 1000; ++it) {
            changed = 0;
            for (int i = 0; i < n; ++i)
                for (int j = i + 2; j < n; ++j) {
                    if (i == 0 && j == n - 1) continue;
                    if (ori__segments_cross_properly(p[i], p[i + 1], p[j], p[(j + 1) % n])) {
                        for (int a = i + 1, b = j; a < b; ++a, --b) {
                            ori_v2 x = p[a];
                            p[a] = p[b], p[b] = x;
                        }
                        changed = 1;
                    }
                }
        }
        bool closed = t & 1;
        c = make(p, n, closed);
        ori_linkage_def def = ori_default_linkage_def();
        def.coords = c.p, def.vertex_count = c.n, def.edges = c.e, def.edge_count = c.m;
        ori_linkage_motion *mo = NULL;
        ori_error err;
        ori_status st = ori_linkage_unfold(&def, &mo, &err);
        ori_linkage_motion_destroy(mo);
        if (st == ORI_ERR_CROSSING || st == ORI_ERR_DUPLICATE) {
            free_case(&c);
            continue;
        }
        accepted++;
        check_motion(&c, closed);
        free_case(&c);
    }
    cr_assert_geq(accepted, 100);
}

// The exact predicate decides what doubles cannot: nearly collinear points.
Test(linkage, exact_orientation)
{
    ori_v2 a = {0.5, 0.5}, b = {12.0, 12.0}, c = {24.0, 24.0};
    cr_assert_eq(ori__orient2d_exact(a, b, c), 0);
    ori_v2 d = {24.0, nextafter(24.0, 25.0)};
    cr_assert_eq(ori__orient2d_exact(a, b, d), 1);
    ori_v2 e = {24.0, nextafter(24.0, 23.0)};
    cr_assert_eq(ori__orient2d_exact(a, b, e), -1);
}

// The command writes the motion as FOLD frames that keep every bar length; the last is convex.
Test(linkage, cli_writes_motion, .init = test_leak_setup, .fini = test_leak_check)
{
    char *dir = test_tmpdir();
    char args[1024], path[512];
    snprintf(path, sizeof path, "%s/motion.fold", dir);
    snprintf(args, sizeof args, "unfold-linkage tests/data/unfold/star.fold --steps-per-event 3 -o '%s' --json", path);
    char *out = NULL;
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    cr_assert(strstr(out, "\"final\":\"convex\""), "%s", out);
    free(out);
    json_error_t je;
    json_t *doc = json_load_file(path, 0, &je);
    cr_assert_not_null(doc, "%s", je.text);
    json_t *frames = json_object_get(doc, "file_frames"), *v0 = json_object_get(doc, "vertices_coords");
    cr_assert_gt(json_array_size(frames), 3);
    size_t n = json_array_size(v0);
    for (size_t f = 0; f < json_array_size(frames); ++f) {
        json_t *vc = json_object_get(json_array_get(frames, f), "vertices_coords");
        cr_assert_eq(json_array_size(vc), n);
        for (size_t i = 0; i < n; ++i) {
            size_t j = (i + 1) % n;
            double L0 = hypot(json_number_value(json_array_get(json_array_get(v0, i), 0)) - json_number_value(json_array_get(json_array_get(v0, j), 0)),
                              json_number_value(json_array_get(json_array_get(v0, i), 1)) - json_number_value(json_array_get(json_array_get(v0, j), 1)));
            double L = hypot(json_number_value(json_array_get(json_array_get(vc, i), 0)) - json_number_value(json_array_get(json_array_get(vc, j), 0)),
                             json_number_value(json_array_get(json_array_get(vc, i), 1)) - json_number_value(json_array_get(json_array_get(vc, j), 1)));
            cr_assert_leq(fabs(L - L0) / L0, 1e-9);
        }
    }
    json_decref(doc);
    test_tmpdir_remove(dir);
}
