// Arrangement: segment insertion into a flat pattern (splits, snapping, overlaps, face splits
// and names), bulk planarisation, and invariants after thousands of random creases.
#include <orikin/arrangement.h>
#include <orikin/authoring.h>
#include <stdlib.h>

#include "pattern/pattern_internal.h"
#include "support.h"

TestSuite(arrangement, .init = test_leak_setup, .fini = test_leak_check);

// A w × h sheet: vertices 0..3 counter-clockwise from (0,0), boundary edges 0..3, face Obj1.
static ori_pattern *sheet(double w, double h)
{
    ori_pattern_def def = ori_default_pattern_def();
    ori_pattern *p = ori_pattern_create(&def);
    ori_pattern_add_vertex(p, ori_v3_make(0, 0, 0));
    ori_pattern_add_vertex(p, ori_v3_make(w, 0, 0));
    ori_pattern_add_vertex(p, ori_v3_make(w, h, 0));
    ori_pattern_add_vertex(p, ori_v3_make(0, h, 0));
    for (int i = 0; i < 4; ++i) ori_pattern_add_edge(p, i, (i + 1) % 4, ORI_ASSIGN_BOUNDARY, 0.0);
    int f[4] = {0, 1, 2, 3};
    ori_pattern_add_face(p, f, 4);
    ori_pattern_set_face_name(p, 0, "Obj1");
    ori_pattern_add_tree_node(p, "Obj1", ORI_NULL_INDEX);
    return p;
}

static void insert_ok(ori_pattern *p, double ax, double ay, double bx, double by, ori_assignment a,
                      ori_insert_result *r)
{
    ori_error err;
    char msg[300];
    ori_status st = ori_pattern_insert_segment(p, ori_v2_make(ax, ay), ori_v2_make(bx, by), a, 0.0, NULL, r, &err);
    cr_assert_eq(st, ORI_OK, "insert: %s", ori_error_format(&err, msg, sizeof msg));
}

static void build_ok(ori_pattern *p)
{
    ori_error err;
    char msg[300];
    ori_build_def def = ori_default_build_def();
    ori_status st = ori_pattern_build(p, &def, &err);
    cr_assert_eq(st, ORI_OK, "build: %s", ori_error_format(&err, msg, sizeof msg));
}

static double face_area(const ori_pattern *p, int f) { return 0.5 * ori__pattern_face_area2(p, f); }

static bool segments_cross(ori_v2 a, ori_v2 b, ori_v2 c, ori_v2 d)
{
    int o1 = ori_orient2d_sign(a, b, c), o2 = ori_orient2d_sign(a, b, d);
    int o3 = ori_orient2d_sign(c, d, a), o4 = ori_orient2d_sign(c, d, b);
    return o1 * o2 < 0 && o3 * o4 < 0;
}

// The invariants of a valid authored sheet: planar build, Euler V − E + F = 1 (connected, F
// inner faces), every face counter-clockwise and simple, areas summing to the sheet's.
static void check_invariants(ori_pattern *p, double sheet_area)
{
    build_ok(p);
    int V = ori_pattern_vertex_count(p), E = ori_pattern_edge_count(p), F = ori_pattern_face_count(p);
    cr_assert_eq(V - E + F, 1, "Euler: V %d E %d F %d", V, E, F);
    double total = 0.0;
    int buf[4096];
    for (int f = 0; f < F; ++f) {
        double a = face_area(p, f);
        cr_assert_gt(a, 0.0, "face %d not counter-clockwise (area %g)", f, a);
        total += a;
        int n = ori_pattern_face_vertices(p, f, buf, 4096);
        cr_assert_leq(n, 4096);
        for (int i = 0; i < n; ++i)
            for (int j = i + 1; j < n; ++j) {
                cr_assert_neq(buf[i], buf[j], "face %d repeats vertex %d", f, buf[i]);
                if (j == i + 1 || (i == 0 && j == n - 1)) continue;
                ori_v2 a0 = ori__pattern_v2(p, buf[i]), a1 = ori__pattern_v2(p, buf[(i + 1) % n]);
                ori_v2 b0 = ori__pattern_v2(p, buf[j]), b1 = ori__pattern_v2(p, buf[(j + 1) % n]);
                cr_assert(!segments_cross(a0, a1, b0, b1), "face %d sides %d and %d cross", f, i, j);
            }
    }
    cr_assert_float_eq(total, sheet_area, 1e-9 * sheet_area);
}

// The faces the arrangement maintained are the faces of the planar graph: tracing them from
// scratch (ori_pattern_build on a copy without faces) finds as many.
static void check_traced_faces(const ori_pattern *p, const char *what)
{
    ori_pattern *q = ori_pattern_clone(p);
    ori_pattern_clear_faces(q);
    build_ok(q);
    cr_assert_eq(ori_pattern_face_count(q), ori_pattern_face_count(p), "%s: traced faces", what);
    ori_pattern_destroy(q);
}

// The counts of vertices, edges and faces (a failed insertion must leave them as they were).
typedef struct counts {
    int v, e, f;
} counts;

static counts counts_of(const ori_pattern *p)
{
    counts c = {ori_pattern_vertex_count(p), ori_pattern_edge_count(p), ori_pattern_face_count(p)};
    return c;
}

static void assert_counts(const ori_pattern *p, counts c)
{
    cr_assert_eq(ori_pattern_vertex_count(p), c.v);
    cr_assert_eq(ori_pattern_edge_count(p), c.e);
    cr_assert_eq(ori_pattern_face_count(p), c.f);
}

static double edge_length(const ori_pattern *p, int e)
{
    ori_edge ed = ori_pattern_edge(p, e);
    return ori_v2_norm(ori_v2_sub(ori__pattern_v2(p, ed.v[1]), ori__pattern_v2(p, ed.v[0])));
}

// Sum of the lengths of the edges lying along segment ab.
static double covered_length(const ori_pattern *p, ori_v2 a, ori_v2 b)
{
    int es[1024];
    int n = ori_pattern_edges_on_segment(p, a, b, es, 1024);
    cr_assert_leq(n, 1024);
    double s = 0.0;
    for (int i = 0; i < n; ++i) s += edge_length(p, es[i]);
    return s;
}

Test(arrangement, diagonal_splits_face_and_names_parts)
{
    ori_pattern *p = sheet(2, 2);
    ori_insert_result r;
    insert_ok(p, 0, 0, 2, 2, ORI_ASSIGN_VALLEY, &r);
    cr_assert_eq(r.vertices_added, 0);
    cr_assert_eq(r.edges_added, 1);
    cr_assert_eq(r.faces_split, 1);
    cr_assert_eq(r.segment_edges, 1);
    cr_assert_eq(ori_pattern_vertex_count(p), 4);
    cr_assert_eq(ori_pattern_edge_count(p), 5);
    cr_assert_eq(ori_pattern_face_count(p), 2);
    ori_edge e = ori_pattern_edge(p, 4);
    cr_assert_eq(e.v[0], 0);
    cr_assert_eq(e.v[1], 2);
    cr_assert_eq(e.assignment, ORI_ASSIGN_VALLEY);
    // Left of (0,0)→(2,2) is the upper-left triangle: Obj11 keeps face index 0.
    cr_assert_str_eq(ori_pattern_face_name(p, 0), "Obj11");
    cr_assert_str_eq(ori_pattern_face_name(p, 1), "Obj12");
    int fv[8];
    cr_assert_eq(ori_pattern_face_vertices(p, 0, fv, 8), 3);
    bool has3 = fv[0] == 3 || fv[1] == 3 || fv[2] == 3;
    cr_assert(has3, "Obj11 must contain the upper-left corner");
    cr_assert_eq(ori_pattern_tree_node_count(p), 3);
    cr_assert_eq(ori_pattern_tree_node(p, 1).parent, 0);
    cr_assert_str_eq(ori_pattern_tree_node(p, 2).name, "Obj12");
    check_invariants(p, 4.0);
    ori_pattern_destroy(p);
}

Test(arrangement, crossing_creases_split_edges_and_keep_indices)
{
    ori_pattern *p = sheet(2, 2);
    ori_insert_result r;
    insert_ok(p, 0, 1, 2, 1, ORI_ASSIGN_MOUNTAIN, &r); // T-junctions on edges 3 and 1
    cr_assert_eq(r.vertices_added, 2);
    cr_assert_eq(r.edges_split, 2);
    cr_assert_eq(r.edges_added, 3);
    // Split edges keep their index for the part at their first vertex.
    cr_assert_eq(ori_pattern_edge(p, 1).v[0], 1);
    cr_assert_float_eq(ori_pattern_vertex(p, ori_pattern_edge(p, 1).v[1]).y, 1.0, 1e-15);
    insert_ok(p, 1, 0, 1, 2, ORI_ASSIGN_VALLEY, &r); // crosses the mountain at (1,1)
    cr_assert_eq(r.vertices_added, 3);
    cr_assert_eq(r.edges_split, 3);
    cr_assert_eq(r.segment_edges, 2);
    cr_assert_eq(r.faces_split, 2);
    cr_assert_eq(ori_pattern_face_count(p), 4);
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_MOUNTAIN), 2);
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_VALLEY), 2);
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_BOUNDARY), 8);
    // The split mountain's lengths add up to the original.
    cr_assert_float_eq(covered_length(p, ori_v2_make(0, 1), ori_v2_make(2, 1)), 2.0, 1e-15);
    cr_assert_float_eq(covered_length(p, ori_v2_make(0, 0), ori_v2_make(2, 0)), 2.0, 1e-15);
    check_invariants(p, 4.0);
    ori_pattern_destroy(p);
}

Test(arrangement, snapping_to_existing_vertex_creates_no_vertex)
{
    ori_pattern *p = sheet(1, 1);
    ori_insert_result r;
    insert_ok(p, 0, 0.5, 1, 0.5, ORI_ASSIGN_VALLEY, &r);
    int v = ori_pattern_vertex_count(p);
    // Through (0.5, 0.5)? no vertex there yet: a crossing vertex is created.
    insert_ok(p, 0.5, 0, 0.5, 1, ORI_ASSIGN_VALLEY, &r);
    cr_assert_eq(ori_pattern_vertex_count(p), v + 3);
    v = ori_pattern_vertex_count(p);
    // A diagonal passing 1e-12 from the centre vertex and ending 1e-12 off the corners.
    insert_ok(p, 1e-12, -1e-12, 1 - 1e-12, 1 + 1e-12, ORI_ASSIGN_MOUNTAIN, &r);
    cr_assert_eq(r.vertices_added, 0);
    cr_assert_eq(ori_pattern_vertex_count(p), v);
    cr_assert_eq(r.segment_edges, 2, "split at the centre vertex");
    cr_assert_eq(r.faces_split, 2);
    check_invariants(p, 1.0);
    ori_pattern_destroy(p);
}

Test(arrangement, collinear_overlap_keeps_boundary_and_reassigns_creases)
{
    ori_pattern *p = sheet(2, 2);
    ori_insert_result r;
    // Along the bottom boundary, beyond both corners' tolerance? No: exactly along it.
    insert_ok(p, 0, 0, 2, 0, ORI_ASSIGN_VALLEY, &r);
    cr_assert_eq(r.edges_added, 0);
    cr_assert_eq(r.edges_overlapped, 1);
    cr_assert_eq(ori_pattern_edge(p, 0).assignment, ORI_ASSIGN_BOUNDARY);
    // A crease, then a longer collinear one over it: the crease takes the new assignment.
    insert_ok(p, 0, 1, 2, 1, ORI_ASSIGN_VALLEY, &r);
    int e_count = ori_pattern_edge_count(p);
    insert_ok(p, 0.5, 1, 1.5, 1, ORI_ASSIGN_MOUNTAIN, &r); // inside the valley: splits it twice
    cr_assert_eq(r.vertices_added, 2);
    cr_assert_eq(r.edges_overlapped, 1);
    cr_assert_eq(r.edges_added, 2);
    cr_assert_eq(ori_pattern_edge_count(p), e_count + 2);
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_MOUNTAIN), 1);
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_VALLEY), 2);
    cr_assert_float_eq(covered_length(p, ori_v2_make(0, 1), ori_v2_make(2, 1)), 2.0, 1e-15);
    check_invariants(p, 4.0);
    ori_pattern_destroy(p);
}

Test(arrangement, overlap_rules)
{
    ori_pattern *p = sheet(1, 1);
    ori_insert_def def = ori_default_insert_def();
    def.overlap = ORI_OVERLAP_REPLACE;
    ori_error err;
    cr_assert_eq(ori_pattern_insert_segment(p, ori_v2_make(1, 0), ori_v2_make(0, 0), ORI_ASSIGN_CUT, 0.0, &def, NULL, &err), ORI_OK);
    cr_assert_eq(ori_pattern_edge(p, 0).assignment, ORI_ASSIGN_CUT);
    def.overlap = ORI_OVERLAP_KEEP_EXISTING;
    cr_assert_eq(ori_pattern_insert_segment(p, ori_v2_make(0, 0), ori_v2_make(1, 0), ORI_ASSIGN_VALLEY, 0.0, &def, NULL, &err), ORI_OK);
    cr_assert_eq(ori_pattern_edge(p, 0).assignment, ORI_ASSIGN_CUT);
    ori_pattern_destroy(p);
}

Test(arrangement, degenerate_and_bad_input_leave_pattern_unchanged)
{
    ori_pattern *p = sheet(1, 1);
    ori_error err;
    ori_insert_result r;
    ori_status st = ori_pattern_insert_segment(p, ori_v2_make(0, 0), ori_v2_make(1e-12, 0), ORI_ASSIGN_VALLEY, 0.0, NULL, &r, &err);
    cr_assert_eq(st, ORI_ERR_DEGENERATE);
    cr_assert(strstr(err.message, "shorter than the length tolerance") != NULL);
    st = ori_pattern_insert_segment(p, ori_v2_make(NAN, 0), ori_v2_make(1, 0), ORI_ASSIGN_VALLEY, 0.0, NULL, &r, &err);
    cr_assert_eq(st, ORI_ERR_RANGE);
    assert_counts(p, (counts){4, 4, 1});
    ori_pattern_set_folded_form(p, true);
    st = ori_pattern_insert_segment(p, ori_v2_make(0, 0), ori_v2_make(1, 1), ORI_ASSIGN_VALLEY, 0.0, NULL, &r, &err);
    cr_assert_eq(st, ORI_ERR_UNSUPPORTED);
    ori_pattern_destroy(p);
}

Test(arrangement, free_and_dangling_segments)
{
    ori_pattern *p = sheet(2, 2);
    ori_insert_result r;
    insert_ok(p, 0, 1, 1, 1, ORI_ASSIGN_VALLEY, &r); // from the boundary to the middle: a slit
    cr_assert_eq(r.vertices_added, 2);
    cr_assert_eq(r.faces_split, 0);
    cr_assert_eq(ori_pattern_face_size(p, 0), 7); // 5 corners + the slit (u, w, u)
    build_ok(p);
    insert_ok(p, 1, 1, 2, 1, ORI_ASSIGN_VALLEY, &r); // completes the cut across the sheet
    cr_assert_eq(r.faces_split, 1);
    check_invariants(p, 4.0);
    ori_pattern_destroy(p);
}

Test(arrangement, floating_segment_in_a_face_is_refused)
{
    ori_pattern *p = sheet(2, 2);
    ori_error err;
    ori_status st = ori_pattern_insert_segment(p, ori_v2_make(0.5, 0.5), ori_v2_make(1.5, 1.0), ORI_ASSIGN_VALLEY,
                                               0.0, NULL, NULL, &err);
    cr_assert_eq(st, ORI_ERR_UNSUPPORTED);
    cr_assert(strstr(err.message, "would float inside a face") != NULL, "%s", err.message);
    cr_assert_eq(ori_pattern_edge_count(p), 4);
    cr_assert_eq(ori_pattern_vertex_count(p), 4);
    // Hanging from the boundary is a slit; continuing from its free end is fine too.
    insert_ok(p, 1, 0, 1, 0.5, ORI_ASSIGN_VALLEY, NULL);
    insert_ok(p, 1, 0.5, 1.5, 1.0, ORI_ASSIGN_VALLEY, NULL);
    build_ok(p);
    // Without faces anything goes (faces are traced later).
    ori_pattern_clear_faces(p);
    insert_ok(p, 0.2, 1.5, 0.4, 1.5, ORI_ASSIGN_VALLEY, NULL);
    ori_pattern_destroy(p);
}

static double rnd(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return (double)(*s >> 8) / 16777216.0;
}

// A point on the boundary of the unit square chosen by t in [0, 4).
static ori_v2 on_boundary(double t)
{
    if (t < 1) return ori_v2_make(t, 0);
    if (t < 2) return ori_v2_make(1, t - 1);
    if (t < 3) return ori_v2_make(3 - t, 1);
    return ori_v2_make(0, 4 - t);
}

Test(arrangement, random_chords_keep_invariants)
{
    ori_pattern *p = sheet(1, 1);
    unsigned s = 12345;
    ori_v2 chords[120][2];
    for (int i = 0; i < 120; ++i) {
        ori_v2 a, b;
        int kind = i % 4;
        if (kind == 0) { // through existing vertices: pick two vertices
            int n = ori_pattern_vertex_count(p);
            a = ori__pattern_v2(p, (int)(rnd(&s) * n) % n);
            b = ori__pattern_v2(p, (int)(rnd(&s) * n) % n);
            if (a.x == b.x && a.y == b.y) b = on_boundary(4 * rnd(&s));
            // extend the chord to the boundary? keep it between the two points
        } else if (kind == 1) { // axis-parallel at lattice positions (many collinear overlaps)
            double c = floor(rnd(&s) * 8) / 8;
            if (rnd(&s) < 0.5) a = ori_v2_make(0, c), b = ori_v2_make(1, c);
            else a = ori_v2_make(c, 0), b = ori_v2_make(c, 1);
        } else {
            a = on_boundary(4 * rnd(&s));
            b = on_boundary(4 * rnd(&s));
        }
        chords[i][0] = a;
        chords[i][1] = b;
        ori_error err;
        ori_status st = ori_pattern_insert_segment(p, a, b, rnd(&s) < 0.5 ? ORI_ASSIGN_MOUNTAIN : ORI_ASSIGN_VALLEY,
                                                   0.0, NULL, NULL, &err);
        cr_assert(st == ORI_OK || st == ORI_ERR_DEGENERATE);
        if (i % 20 == 19) check_invariants(p, 1.0);
    }
    check_invariants(p, 1.0);
    // Every chord is covered exactly by edges along it (its pieces sum to its length).
    for (int i = 0; i < 120; ++i) {
        double len = ori_v2_norm(ori_v2_sub(chords[i][1], chords[i][0]));
        if (len == 0.0) continue;
        cr_assert_float_eq(covered_length(p, chords[i][0], chords[i][1]), len, 1e-12, "chord %d", i);
    }
    // The boundary is still B along the whole perimeter.
    double perim = 0.0;
    for (int e = 0; e < ori_pattern_edge_count(p); ++e)
        if (ori_pattern_edge(p, e).assignment == ORI_ASSIGN_BOUNDARY) perim += edge_length(p, e);
    cr_assert_float_eq(perim, 4.0, 1e-12);
    ori_pattern_destroy(p);
}

// Distance along the ray x + t·d (t > 0) to the k-th edge it crosses (sorted), or the last one.
static double ray_hit(const ori_pattern *p, ori_v2 x, ori_v2 d, int k)
{
    double hits[64];
    int n = 0;
    for (int e = 0; e < p->edge_count; ++e) { // (the arrays directly: this runs 4000 times over 10 000 edges)
        ori_v3 u3 = p->vertices[p->edges[e].v[0]], w3 = p->vertices[p->edges[e].v[1]];
        ori_v2 u = {u3.x, u3.y}, w = {w3.x, w3.y};
        ori_v2 r = ori_v2_sub(w, u);
        double den = ori_v2_cross(d, r);
        if (den == 0.0) continue;
        ori_v2 q = ori_v2_sub(u, x);
        double t = ori_v2_cross(q, r) / den, s = ori_v2_cross(q, d) / den;
        if (t <= 1e-9 || s < 0.0 || s > 1.0) continue;
        // keep the 64 nearest
        if (n < 64) hits[n++] = t;
        else {
            int far = 0;
            for (int i = 1; i < 64; ++i) if (hits[i] > hits[far]) far = i;
            if (t < hits[far]) hits[far] = t;
        }
    }
    for (int i = 1; i < n; ++i)
        for (int j = i; j > 0 && hits[j] < hits[j - 1]; --j) {
            double t = hits[j];
            hits[j] = hits[j - 1];
            hits[j - 1] = t;
        }
    if (n == 0) return 0.0;
    return hits[k < n ? k : n - 1];
}

Test(arrangement, thousands_of_random_creases)
{
    ori_pattern *p = sheet(1, 1);
    unsigned s = 777;
    for (int i = 0; i < 2000; ++i) {
        ori_v2 a, d;
        double ang = 2 * ORI_PI * rnd(&s);
        int kind = i % 5;
        if (kind == 4) { // lattice lines: collinear overlaps and exact crossings at vertices
            double c = floor(rnd(&s) * 16) / 16;
            a = rnd(&s) < 0.5 ? ori_v2_make(0, c) : ori_v2_make(c, 0);
            d = a.x == 0 ? ori_v2_make(1, 0) : ori_v2_make(0, 1);
        } else {
            if (kind == 3) { // from an existing vertex, in a random direction
                int n = ori_pattern_vertex_count(p);
                a = ori__pattern_v2(p, (int)(rnd(&s) * n) % n);
            } else {
                a = ori_v2_make(0.02 + 0.96 * rnd(&s), 0.02 + 0.96 * rnd(&s));
            }
            d = ori_v2_make(cos(ang), sin(ang));
        }
        // Extend both ways to the 1st..3rd edge crossed: a crease ending on edges, crossing
        // up to four others (or passing through vertices).
        double t1 = ray_hit(p, a, d, (int)(rnd(&s) * 3));
        double t0 = ray_hit(p, a, ori_v2_scale(d, -1), (int)(rnd(&s) * 3));
        if (kind == 4) t0 = 0.0, t1 = 1.0;
        ori_v2 x0 = ori_v2_sub(a, ori_v2_scale(d, t0)), x1 = ori_v2_add(a, ori_v2_scale(d, t1));
        ori_error err;
        char msg[300];
        ori_status st = ori_pattern_insert_segment(p, x0, x1, (ori_assignment)(1 + i % 4), 0.0, NULL, NULL, &err);
        cr_assert(st == ORI_OK || st == ORI_ERR_DEGENERATE, "segment %d: %s", i, ori_error_format(&err, msg, sizeof msg));
        if (i % 500 == 499) check_invariants(p, 1.0);
    }
    check_invariants(p, 1.0);
    cr_assert_gt(ori_pattern_face_count(p), 2000);
    check_traced_faces(p, "2000 creases");
    ori_pattern_destroy(p);
}

Test(arrangement, bulk_planarises_crossing_and_overlapping_segments)
{
    enum { N = 3000 };
    ori_segment *segs = malloc(sizeof *segs * N);
    unsigned s = 99;
    for (int i = 0; i < N; ++i) {
        if (i % 3 == 0) { // lattice segments: duplicates and collinear overlaps
            double x = floor(rnd(&s) * 20), y = floor(rnd(&s) * 20), l = 1 + floor(rnd(&s) * 4);
            segs[i].a = ori_v2_make(x, y);
            segs[i].b = rnd(&s) < 0.5 ? ori_v2_make(x + l, y) : ori_v2_make(x, y + l);
        } else {
            segs[i].a = ori_v2_make(20 * rnd(&s), 20 * rnd(&s));
            double ang = 2 * ORI_PI * rnd(&s), l = 0.3 + 2 * rnd(&s);
            segs[i].b = ori_v2_make(segs[i].a.x + l * cos(ang), segs[i].a.y + l * sin(ang));
        }
        segs[i].assignment = (ori_assignment)(1 + i % 2);
        segs[i].fold_angle_rad = 0.0;
    }
    ori_pattern *p = NULL;
    ori_insert_result r;
    ori_error err;
    char msg[300];
    ori_status st = ori_pattern_from_segments(segs, N, NULL, &p, &r, &err);
    cr_assert_eq(st, ORI_OK, "%s", ori_error_format(&err, msg, sizeof msg));
    cr_assert_gt(r.edges_split, 1000);
    cr_assert_gt(r.edges_overlapped, 10);
    cr_assert_gt(ori_pattern_face_count(p), 100);
    for (int i = 0; i < N; i += 7) {
        double len = ori_v2_norm(ori_v2_sub(segs[i].b, segs[i].a));
        cr_assert_float_eq(covered_length(p, segs[i].a, segs[i].b), len, 1e-9, "segment %d", i);
    }
    ori_pattern_destroy(p);
    free(segs);
}

Test(arrangement, bulk_rejects_non_finite_with_index)
{
    ori_segment segs[2] = {{{0, 0}, {1, 1}, ORI_ASSIGN_VALLEY, 0.0}, {{0, 1}, {INFINITY, 0}, ORI_ASSIGN_VALLEY, 0.0}};
    ori_pattern *p = NULL;
    ori_error err;
    cr_assert_eq(ori_pattern_from_segments(segs, 2, NULL, &p, NULL, &err), ORI_ERR_RANGE);
    cr_assert_null(p);
    cr_assert_eq(err.element, 1);
    cr_assert_str_eq(err.field, "segments");
}

Test(arrangement, bulk_skips_degenerate_segments)
{
    ori_segment segs[3] = {{{0, 0}, {1, 0}, ORI_ASSIGN_BOUNDARY, 0.0},
                           {{0.5, 0.5}, {0.5, 0.5}, ORI_ASSIGN_VALLEY, 0.0},
                           {{0, 0}, {0, 1}, ORI_ASSIGN_BOUNDARY, 0.0}};
    ori_pattern *p = NULL;
    ori_insert_result r;
    ori_error err;
    cr_assert_eq(ori_pattern_from_segments(segs, 3, NULL, &p, &r, &err), ORI_OK);
    cr_assert_eq(r.segments_skipped, 1);
    cr_assert_eq(ori_pattern_edge_count(p), 2);
    cr_assert_eq(ori_pattern_vertex_count(p), 3);
    ori_pattern_destroy(p);
}

// Two edges from one vertex, crossed by a third segment closer together than the tolerance:
// the crossings snap to one vertex, and the two far parts of the edges then join the same two
// vertices. They must become one edge (a merge), never two edges with the same end points.
Test(arrangement, split_parts_that_snap_together_are_one_edge)
{
    ori_segment s[3] = {{{1655.555, -2874.012}, {1688.235, -2938.14}, ORI_ASSIGN_FLAT, 0.0},
                        {{1665.989, -2869.686}, {1688.234, -2938.141}, ORI_ASSIGN_FLAT, 0.0},
                        {{1617.164, -2938.13}, {1689.158, -2938.115}, ORI_ASSIGN_FLAT, 0.0}};
    ori_insert_def def = ori_default_insert_def();
    def.length_scale = 19083609.913247552; // tolerance 0.019
    ori_pattern *p = NULL;
    ori_insert_result r;
    ori_error err;
    char msg[300];
    ori_status st = ori_pattern_from_segments(s, 3, &def, &p, &r, &err); // builds: no repeated edge
    cr_assert_eq(st, ORI_OK, "%s", ori_error_format(&err, msg, sizeof msg));
    cr_assert_eq(r.edges_merged, 1);
    cr_assert_eq(r.segments_skipped, 0);
    cr_assert_eq(ori_pattern_vertex_count(p), 6); // 2 + 1 end points (one welded), crossing, 2 ends
    cr_assert_eq(ori_pattern_edge_count(p), 5);
    int v = test_vertex_at(p, 1688.235, -2938.14), x = ori_pattern_vertex_count(p) - 2;
    int e = ori_pattern_find_edge(p, v, x);
    cr_assert_neq(e, ORI_NULL_INDEX, "the merged part joins the crossing to the shared end");
    for (int k = 0; k < ori_pattern_edge_count(p); ++k) cr_assert_eq(ori_pattern_edge(p, k).assignment, ORI_ASSIGN_FLAT);
    ori_pattern_destroy(p);
    // The same one segment at a time into a pattern without faces (nothing is dropped there).
    ori_pattern_def pdef = ori_default_pattern_def();
    p = ori_pattern_create(&pdef);
    for (int i = 0; i < 3; ++i) cr_assert_eq(ori_pattern_insert_segments(p, s + i, 1, &def, &r, &err), ORI_OK);
    cr_assert_eq(r.edges_merged, 1);
    cr_assert_eq(ori_pattern_edge_count(p), 5);
    build_ok(p);
    ori_pattern_destroy(p);
}

// In a pattern with faces the same snap would collapse the thin face between the two edges:
// refused, leaving the pattern unchanged; the sheet still takes the crease at a finer scale.
Test(arrangement, a_merge_that_would_collapse_a_face_is_refused)
{
    ori_pattern *p = sheet(100, 100);
    insert_ok(p, 0, 0, 100, 40, ORI_ASSIGN_VALLEY, NULL);
    insert_ok(p, 0, 0, 100, 41, ORI_ASSIGN_MOUNTAIN, NULL);
    counts before = counts_of(p);
    ori_insert_def def = ori_default_insert_def();
    def.length_scale = 0.02 / ORI_TOL_LENGTH_REL; // the creases are 0.01 apart at x = 1
    ori_error err;
    ori_status st = ori_pattern_insert_segment(p, ori_v2_make(1, 0), ori_v2_make(1, 100), ORI_ASSIGN_VALLEY, 0.0, &def,
                                               NULL, &err);
    cr_assert_eq(st, ORI_ERR_DEGENERATE);
    cr_assert(strstr(err.message, "would merge edge") != NULL, "%s", err.message);
    assert_counts(p, before);
    insert_ok(p, 1, 0, 1, 100, ORI_ASSIGN_VALLEY, NULL);
    check_invariants(p, 1e4);
    ori_pattern_destroy(p);
}

// Points on circles around each end point, closer to it than the tolerance.
static ori_v2 jitter(ori_v2 x, double radius, unsigned *s)
{
    double r = radius * rnd(s), a = 2 * ORI_PI * rnd(s);
    return ori_v2_make(x.x + r * cos(a), x.y + r * sin(a));
}

// V − E + F = number of connected parts (faces traced from the planar graph, holes included).
static void check_euler(const ori_pattern *p)
{
    int V = ori_pattern_vertex_count(p), E = ori_pattern_edge_count(p), F = ori_pattern_face_count(p);
    int *part = malloc(sizeof(int) * (size_t)(V + 1));
    int parts = ori__pattern_parts(p, part);
    free(part);
    cr_assert_eq(V - E + F, parts, "Euler: V %d E %d F %d, %d parts", V, E, F, parts);
}

// Whether some edge passes within r of x (bounding boxes first: this runs for every sample point
// of every segment of every soup).
static bool near_an_edge(const ori_pattern *p, ori_v2 x, double r)
{
    for (int e = 0; e < p->edge_count; ++e) {
        ori_v3 a3 = p->vertices[p->edges[e].v[0]], b3 = p->vertices[p->edges[e].v[1]];
        if (fmin(a3.x, b3.x) > x.x + r || fmax(a3.x, b3.x) < x.x - r || fmin(a3.y, b3.y) > x.y + r || fmax(a3.y, b3.y) < x.y - r)
            continue;
        ori_v2 a = {a3.x, a3.y}, d = {b3.x - a3.x, b3.y - a3.y};
        double t = ori_v2_dot(ori_v2_sub(x, a), d) / ori_v2_dot(d, d);
        t = t < 0 ? 0 : (t > 1 ? 1 : t);
        if (ori_v2_norm(ori_v2_sub(x, ori_v2_add(a, ori_v2_scale(d, t)))) <= r) return true;
    }
    return false;
}

// Random near-degenerate segment soups: a few points (at drawing-like coordinates), segments
// between them, along their lines and to free points, every end point jittered by less than the
// snap tolerance, which is 1e-2, 1e-3 or 1e-4 of the drawing (a coarse import tolerance). Snapping
// merges crossings, routes segments through nearby vertices and lays edges onto each other; the
// result must build with the planarity check, satisfy Euler's formula, and cover every segment.
static void soup(int trials, int n, bool check_cover)
{
    ori_segment *segs = malloc(sizeof *segs * (size_t)n);
    for (int trial = 0; trial < trials; ++trial) {
        unsigned s = 77u + 7919u * (unsigned)trial;
        double tol = trial % 3 == 0 ? 1.0 : (trial % 3 == 1 ? 0.1 : 0.01); // of an extent of 100
        ori_v2 pts[16];
        int np = 6 + (int)(rnd(&s) * 10);
        for (int i = 0; i < np; ++i)
            for (bool apart = false; !apart;) { // at least 10 tolerances apart
                pts[i] = ori_v2_make(1000 + 100 * rnd(&s), -3000 + 100 * rnd(&s));
                apart = true;
                for (int j = 0; j < i; ++j) apart = apart && ori_v2_norm(ori_v2_sub(pts[i], pts[j])) >= 10 * tol;
            }
        int designed_short = 0;
        for (int i = 0; i < n; ++i) {
            int a = (int)(rnd(&s) * np), b = (int)(rnd(&s) * np);
            ori_v2 A = pts[a], B = pts[b];
            if (i % 3 == 1 && a != b) B = ori_v2_add(A, ori_v2_scale(ori_v2_sub(B, A), 0.2 + 0.6 * rnd(&s)));
            if (i % 3 == 2)
                do B = ori_v2_make(1000 + 100 * rnd(&s), -3000 + 100 * rnd(&s));
                while (ori_v2_norm(ori_v2_sub(A, B)) < 10 * tol);
            designed_short += A.x == B.x && A.y == B.y;
            segs[i].a = jitter(A, 0.9 * tol, &s);
            segs[i].b = jitter(B, 0.9 * tol, &s);
            segs[i].assignment = (ori_assignment)(1 + i % 4);
            segs[i].fold_angle_rad = 0.0;
        }
        ori_insert_def def = ori_default_insert_def();
        def.length_scale = tol / ORI_TOL_LENGTH_REL;
        def.name_faces = false;
        ori_pattern *p = NULL;
        ori_insert_result r;
        ori_error err;
        char msg[300];
        ori_status st = ori_pattern_from_segments(segs, n, &def, &p, &r, &err);
        cr_assert_eq(st, ORI_OK, "trial %d: %s", trial, ori_error_format(&err, msg, sizeof msg));
        check_euler(p);
        // Only segments whose ends are jittered copies of one point may collapse (a few
        // others may be refused in the densest soups, counted as skipped).
        cr_assert_leq(r.segments_skipped, designed_short + (check_cover ? 0 : n / 50), "trial %d", trial);
        for (int i = 0; check_cover && i < n; ++i) {
            if (ori_v2_norm(ori_v2_sub(segs[i].b, segs[i].a)) < 3 * tol) continue;
            for (int k = 0; k <= 10; ++k) {
                ori_v2 x = ori_v2_add(segs[i].a, ori_v2_scale(ori_v2_sub(segs[i].b, segs[i].a), 0.1 * k));
                cr_assert(near_an_edge(p, x, 3 * tol), "trial %d, segment %d at %d/10: no edge within %g", trial, i, k, 3 * tol);
            }
        }
        ori_pattern_destroy(p);
    }
    free(segs);
}

Test(arrangement, near_degenerate_soups_build_and_cover_their_segments)
{
    soup(300, 40, true);
}

Test(arrangement, dense_near_degenerate_soups_build)
{
    soup(20, 200, false);
}

// The same coarse snapping in a sheet with faces: chords between points jittered along the
// boundary (so that they stay on it). Every insertion succeeds or is refused leaving the pattern
// unchanged, and the faces stay a tiling of the sheet.
Test(arrangement, coarse_snapping_in_a_sheet_keeps_the_faces)
{
    for (int trial = 0; trial < 30; ++trial) {
        unsigned s = 500u + 7919u * (unsigned)trial;
        double tol = trial % 3 == 0 ? 1.0 : (trial % 3 == 1 ? 0.1 : 0.01);
        ori_pattern *p = sheet(100, 100);
        ori_insert_def def = ori_default_insert_def();
        def.length_scale = tol / ORI_TOL_LENGTH_REL;
        double t[12];
        for (int i = 0; i < 12; ++i) t[i] = 4 * rnd(&s);
        int applied = 0;
        for (int i = 0; i < 40; ++i) {
            ori_v2 a = ori_v2_scale(on_boundary(t[(int)(rnd(&s) * 12)]), 100);
            ori_v2 b = ori_v2_scale(on_boundary(t[(int)(rnd(&s) * 12)]), 100);
            // (along the side, by less than the tolerance; corners stay put)
            double da = 0.9 * tol * (2 * rnd(&s) - 1), db = 0.9 * tol * (2 * rnd(&s) - 1);
            a = a.x == 0 || a.x == 100 ? ori_v2_make(a.x, fmin(fmax(a.y + da, 0), 100)) : ori_v2_make(fmin(fmax(a.x + da, 0), 100), a.y);
            b = b.x == 0 || b.x == 100 ? ori_v2_make(b.x, fmin(fmax(b.y + db, 0), 100)) : ori_v2_make(fmin(fmax(b.x + db, 0), 100), b.y);
            counts before = counts_of(p);
            ori_error err;
            char msg[300];
            ori_status st = ori_pattern_insert_segment(p, a, b, ORI_ASSIGN_VALLEY, 0.0, &def, NULL, &err);
            cr_assert(st == ORI_OK || st == ORI_ERR_DEGENERATE, "trial %d, chord %d: %s", trial, i,
                      ori_error_format(&err, msg, sizeof msg));
            if (st != ORI_OK) assert_counts(p, before);
            applied += st == ORI_OK;
        }
        cr_assert_gt(applied, 20, "trial %d", trial);
        check_invariants(p, 1e4);
        check_traced_faces(p, "coarse snapping");
        ori_pattern_destroy(p);
    }
}

Test(arrangement, find_edge_at_point)
{
    ori_pattern *p = sheet(2, 2);
    insert_ok(p, 0, 1, 2, 1, ORI_ASSIGN_MOUNTAIN, NULL);
    insert_ok(p, 1, 0, 1, 2, ORI_ASSIGN_VALLEY, NULL);
    int e = ori_pattern_find_edge_at(p, ori_v2_make(0.5, 1));
    cr_assert_neq(e, ORI_NULL_INDEX);
    ori_edge ed = ori_pattern_edge(p, e);
    cr_assert_eq(ed.assignment, ORI_ASSIGN_MOUNTAIN);
    cr_assert_float_eq(fmin(ori_pattern_vertex(p, ed.v[0]).x, ori_pattern_vertex(p, ed.v[1]).x), 0.0, 0.0);
    cr_assert_eq(ori_pattern_find_edge_at(p, ori_v2_make(0.5, 0.7)), ORI_NULL_INDEX);
    ori_pattern_destroy(p);
}

// The face at a point: each quadrant of a 2 × 2 sheet creased along both middles, a point on a
// crease (its face named, on_edge set) and a point off the sheet.
Test(arrangement, find_face_at_point)
{
    ori_pattern *p = sheet(2, 2);
    insert_ok(p, 0, 1, 2, 1, ORI_ASSIGN_MOUNTAIN, NULL);
    insert_ok(p, 1, 0, 1, 2, ORI_ASSIGN_VALLEY, NULL);
    cr_assert_eq(ori_pattern_face_count(p), 4);
    const double q[4][2] = {{0.5, 0.5}, {1.5, 0.5}, {0.5, 1.5}, {1.5, 1.5}};
    int seen[4] = {-1, -1, -1, -1};
    for (int k = 0; k < 4; ++k) {
        bool on_edge = true;
        int f = ori_pattern_find_face_at(p, ori_v2_make(q[k][0], q[k][1]), &on_edge);
        cr_assert(f >= 0 && f < 4 && !on_edge, "point %d: face %d", k, f);
        for (int j = 0; j < k; ++j) cr_assert_neq(seen[j], f, "two quadrants in face %d", f);
        seen[k] = f;
        // the face found holds the point: its vertices' box does
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        int vs[8], n = ori_pattern_face_vertices(p, f, vs, 8);
        for (int i = 0; i < n; ++i) {
            ori_v3 v = ori_pattern_vertex(p, vs[i]);
            lo[0] = fmin(lo[0], v.x), lo[1] = fmin(lo[1], v.y), hi[0] = fmax(hi[0], v.x), hi[1] = fmax(hi[1], v.y);
        }
        cr_assert(lo[0] <= q[k][0] && q[k][0] <= hi[0] && lo[1] <= q[k][1] && q[k][1] <= hi[1]);
    }
    bool on_edge = false;
    cr_assert_neq(ori_pattern_find_face_at(p, ori_v2_make(0.5, 1.0), &on_edge), ORI_NULL_INDEX);
    cr_assert(on_edge);
    cr_assert_eq(ori_pattern_find_face_at(p, ori_v2_make(2.5, 0.5), NULL), ORI_NULL_INDEX);
    ori_pattern_destroy(p);
}

// Creases across real crease patterns (other projects' files, read in place): the result
// builds with the planarity check and its faces still tile the sheet.
static double total_area(const ori_pattern *p)
{
    double a = 0.0;
    for (int f = 0; f < ori_pattern_face_count(p); ++f) a += fabs(face_area(p, f));
    return a;
}

static void crease_real_pattern(const char *rel)
{
    ori_pattern *p = test_load_pattern(test_require_shared(rel), 0);
    double area = total_area(p);
    double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        ori_v3 x = ori_pattern_vertex(p, v);
        lo_x = fmin(lo_x, x.x), lo_y = fmin(lo_y, x.y), hi_x = fmax(hi_x, x.x), hi_y = fmax(hi_y, x.y);
    }
    unsigned s = 4242;
    int applied = 0;
    for (int i = 0; i < 40; ++i) {
        // Lines through two random points, a third of them through existing vertices.
        ori_v2 a = ori_v2_make(lo_x + (hi_x - lo_x) * rnd(&s), lo_y + (hi_y - lo_y) * rnd(&s));
        ori_v2 b = ori_v2_make(lo_x + (hi_x - lo_x) * rnd(&s), lo_y + (hi_y - lo_y) * rnd(&s));
        if (i % 3 == 0) {
            int n = ori_pattern_vertex_count(p);
            a = ori__pattern_v2(p, (int)(rnd(&s) * n) % n);
        }
        ori_crease c = {a, b, true, ORI_ASSIGN_UNASSIGNED, 0.0};
        ori_error err;
        char msg[300];
        ori_status st = ori_pattern_apply_crease(p, &c, ORI_NULL_INDEX, NULL, &err);
        cr_assert(st == ORI_OK || st == ORI_ERR_NOT_FOUND || st == ORI_ERR_DEGENERATE, "%s line %d: %s", rel, i,
                  ori_error_format(&err, msg, sizeof msg));
        applied += st == ORI_OK;
    }
    cr_assert_gt(applied, 30);
    build_ok(p);
    cr_assert_float_eq(total_area(p), area, 1e-9 * area);
    check_traced_faces(p, rel);
    ori_pattern_destroy(p);
}

Test(arrangement, creases_across_real_patterns)
{
    crease_real_pattern("flat-folder/instagram_004_traditional_Crane.fold");
    crease_real_pattern("flat-folder/instagram_074_miuraoripa_Miura-ori.fold");
    crease_real_pattern("flat-folder/instagram_082_traditionaloripa_4_Birdbase.fold");
}
