// Tessellation generators: closed-form counts, Euler characteristic, counter-clockwise faces,
// local flat-foldability (Kawasaki, Maekawa, big-little-big) at every interior vertex for
// several parameter sets, the geometry each generator promises, and parameter errors.
#include <float.h>
#include <stdio.h>

#include <orikin/generate.h>

#include "pattern/pattern_internal.h"
#include "support.h"

TestSuite(generate, .init = test_leak_setup, .fini = test_leak_check);

static ori_pattern *gen_ok(const ori_generate_def *def, ori_edge_class **classes)
{
    ori_pattern *p = NULL;
    ori_error err;
    char msg[512];
    ori_status st = ori_generate(def, &p, classes, &err);
    cr_assert_eq(st, ORI_OK, "%s: %s", ori_tessellation_name(def->kind), ori_error_format(&err, msg, sizeof msg));
    cr_assert(ori_pattern_is_built(p));
    return p;
}

// Counts match the formulas, V − E + F = 1 (one disk), faces counter-clockwise, all fold
// angles explicit and 0, every interior vertex locally flat-foldable. Returns interior count.
static int check_pattern(const ori_generate_def *def, const ori_pattern *p)
{
    ori_pattern_counts n;
    cr_assert_eq(ori_generate_counts(def, &n, NULL), ORI_OK);
    cr_assert_eq(ori_pattern_vertex_count(p), n.vertices);
    cr_assert_eq(ori_pattern_edge_count(p), n.edges);
    cr_assert_eq(ori_pattern_face_count(p), n.faces);
    cr_assert_eq(n.vertices - n.edges + n.faces, 1, "Euler characteristic of a disk");
    cr_assert(ori_pattern_has_fold_angles(p));
    for (int f = 0; f < ori_pattern_face_count(p); ++f)
        cr_assert_gt(ori__pattern_face_area2(p, f), 0.0, "face %d is not counter-clockwise", f);
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        cr_assert_eq(ed.fold_angle_rad, 0.0);
        int faces[2];
        ori_pattern_edge_faces(p, e, faces);
        bool b = ed.assignment == ORI_ASSIGN_BOUNDARY;
        // boundary edges have paper on one side only, creases on both
        cr_assert_eq((faces[0] != ORI_NULL_INDEX) + (faces[1] != ORI_NULL_INDEX), b ? 1 : 2, "edge %d", e);
    }
    int interior = 0;
    char why[256];
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        if (!ori_pattern_vertex_is_interior(p, v)) continue;
        interior++;
        cr_assert(test_vertex_flat_foldable(p, v, why, sizeof why), "%s %dx%d: %s", ori_tessellation_name(def->kind),
                  def->rows, def->cols, why);
    }
    return interior;
}

static double deg(double d) { return ori_deg_to_rad(d); }

Test(generate, names_round_trip)
{
    for (int k = 0; k < ORI_TESS_COUNT; ++k) {
        ori_tessellation t;
        cr_assert(ori_tessellation_from_name(ori_tessellation_name((ori_tessellation)k), &t));
        cr_assert_eq(t, k);
    }
    ori_tessellation t;
    cr_assert_not(ori_tessellation_from_name("origami", &t));
    cr_assert_str_eq(ori_edge_class_name(ORI_EDGE_CLASS_ZIGZAG), "zigzag");
}

// --- Miura-ori -----------------------------------------------------------------------------

// The table's parameter sets say what each tessellation reads: a field outside its set changes
// nothing (the same vertices and edges), and a field in it (set to another valid value) changes
// the pattern.
static bool same_pattern(const ori_pattern *a, const ori_pattern *b)
{
    if (ori_pattern_vertex_count(a) != ori_pattern_vertex_count(b) || ori_pattern_edge_count(a) != ori_pattern_edge_count(b))
        return false;
    for (int v = 0; v < ori_pattern_vertex_count(a); ++v) {
        ori_v3 p = ori_pattern_vertex(a, v), q = ori_pattern_vertex(b, v);
        if (p.x != q.x || p.y != q.y || p.z != q.z) return false;
    }
    for (int e = 0; e < ori_pattern_edge_count(a); ++e) {
        ori_edge x = ori_pattern_edge(a, e), y = ori_pattern_edge(b, e);
        if (x.v[0] != y.v[0] || x.v[1] != y.v[1] || x.assignment != y.assignment) return false;
    }
    return true;
}

Test(generate, the_table_says_which_parameters_each_tessellation_reads)
{
    for (int k = 0; k < ORI_TESS_COUNT; ++k) {
        ori_tessellation kind = (ori_tessellation)k;
        unsigned reads = ori_tessellation_params(kind);
        cr_assert(reads & ORI_GEN_ROWS && reads & ORI_GEN_WIDTH, "%s", ori_tessellation_name(kind));
        cr_assert_neq((reads & ORI_GEN_COLS) != 0, (reads & ORI_GEN_SIDES) != 0, "%s: columns or sides", ori_tessellation_name(kind));
        ori_generate_def base = ori_default_generate_def(kind);
        cr_assert_eq(base.bistable_height, (reads & ORI_GEN_BISTABLE_HEIGHT) != 0);
        if (reads & ORI_GEN_BISTABLE_HEIGHT) base.bistable_height = false; // so that height is read
        ori_pattern *p0 = gen_ok(&base, NULL);
        for (unsigned bit = ORI_GEN_COLS; bit <= ORI_GEN_TWIST_SIZE; bit <<= 1) {
            ori_generate_def d = base;
            if (bit == ORI_GEN_COLS) d.cols = 3;
            if (bit == ORI_GEN_SIDES) d.sides = 5;
            if (bit == ORI_GEN_ANGLE) d.angle_rad *= 0.9;
            if (bit == ORI_GEN_WIDTH) d.width = 1.3;
            if (bit == ORI_GEN_HEIGHT) d.height = 1.2;
            if (bit == ORI_GEN_TWIST_SIZE) d.twist_size = 0.4;
            ori_pattern *p1 = gen_ok(&d, NULL);
            bool same = same_pattern(p0, p1);
            cr_assert_eq(!same, (reads & bit) != 0, "%s: parameter bit %u %s", ori_tessellation_name(kind), bit,
                         same ? "changes nothing though the table says it is read" : "changes the pattern though the table says it is not read");
            ori_pattern_destroy(p1);
        }
        ori_pattern_destroy(p0);
    }
}

Test(generate, miura_counts_sectors_and_classes)
{
    const int sizes[][2] = {{1, 1}, {2, 3}, {5, 4}, {7, 7}};
    const double angles[] = {10.0, 45.0, 60.0, 84.0};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s)
        for (size_t a = 0; a < sizeof angles / sizeof angles[0]; ++a) {
            ori_generate_def def = ori_default_generate_def(ORI_TESS_MIURA);
            def.rows = sizes[s][0];
            def.cols = sizes[s][1];
            def.angle_rad = deg(angles[a]);
            def.width = 1.5;
            def.height = 0.75;
            ori_edge_class *cls;
            ori_pattern *p = gen_ok(&def, &cls);
            int R = def.rows, C = def.cols;
            cr_assert_eq(ori_pattern_vertex_count(p), (R + 1) * (C + 1));
            cr_assert_eq(ori_pattern_edge_count(p), C * (R + 1) + R * (C + 1));
            cr_assert_eq(ori_pattern_face_count(p), R * C);
            cr_assert_eq(check_pattern(&def, p), (R - 1) * (C - 1));
            // Documented index ranges: [0, C(R+1)) straight rows, then zig-zag columns.
            for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
                ori_edge ed = ori_pattern_edge(p, e);
                ori_v3 u = ori_pattern_vertex(p, ed.v[0]), w = ori_pattern_vertex(p, ed.v[1]);
                bool straight_range = e < C * (R + 1);
                if (ed.assignment == ORI_ASSIGN_BOUNDARY) cr_assert_eq(cls[e], ORI_EDGE_CLASS_BOUNDARY);
                else cr_assert_eq(cls[e], straight_range ? ORI_EDGE_CLASS_STRAIGHT : ORI_EDGE_CLASS_ZIGZAG);
                if (straight_range) {
                    cr_assert_eq(u.y, w.y);
                    cr_assert_float_eq(w.x - u.x, 1.5, 1e-12);
                } else {
                    // zig-zag segments have length b and make γ with the x axis
                    double len = hypot(w.x - u.x, w.y - u.y);
                    cr_assert_float_eq(len, 0.75, 1e-12);
                    cr_assert_float_eq(fabs(atan2(w.y - u.y, fabs(w.x - u.x))), def.angle_rad, 1e-12);
                }
            }
            // Interior sectors: γ, π−γ, π−γ, γ in some rotation; the straight creases are the
            // collinear pair, of opposite assignment; the zig-zag pair agrees.
            for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
                if (!ori_pattern_vertex_is_interior(p, v)) continue;
                int ed[4];
                double sec[4];
                cr_assert_eq(ori_pattern_vertex_sectors(p, v, ed, sec, 4), 4);
                int small = 0;
                for (int k = 0; k < 4; ++k) {
                    bool is_small = fabs(sec[k] - def.angle_rad) < 1e-12;
                    bool is_big = fabs(sec[k] - (ORI_PI - def.angle_rad)) < 1e-12;
                    cr_assert(is_small || is_big);
                    small += is_small;
                }
                cr_assert_eq(small, 2);
                ori_assignment s0 = ORI_ASSIGN_COUNT, s1 = ORI_ASSIGN_COUNT, z0 = ORI_ASSIGN_COUNT, z1 = ORI_ASSIGN_COUNT;
                for (int k = 0; k < 4; ++k) {
                    ori_assignment asg = ori_pattern_edge(p, ed[k]).assignment;
                    ori_assignment *slot;
                    if (cls[ed[k]] == ORI_EDGE_CLASS_STRAIGHT) slot = s0 == ORI_ASSIGN_COUNT ? &s0 : &s1;
                    else slot = z0 == ORI_ASSIGN_COUNT ? &z0 : &z1;
                    *slot = asg;
                }
                cr_assert_neq(s0, s1);
                cr_assert_eq(z0, z1);
            }
            ori_buffer_free(cls);
            ori_pattern_destroy(p);
        }
}

Test(generate, miura_300x300_builds)
{
    ori_generate_def def = ori_default_generate_def(ORI_TESS_MIURA);
    def.rows = def.cols = 300;
    ori_pattern *p = gen_ok(&def, NULL);
    cr_assert_eq(ori_pattern_vertex_count(p), 301 * 301);
    cr_assert_eq(ori_pattern_edge_count(p), 2 * 300 * 301);
    cr_assert_eq(ori_pattern_face_count(p), 300 * 300);
    cr_assert_eq(ori_pattern_interior_vertex_count(p), 299 * 299);
    ori_pattern_destroy(p);
}

// --- Yoshimura -----------------------------------------------------------------------------

Test(generate, yoshimura_degree6_and_flat_foldable)
{
    const int sizes[][2] = {{1, 1}, {2, 2}, {3, 5}, {6, 4}};
    const double angles[] = {15.0, 30.0, 45.0, 60.0};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s)
        for (size_t a = 0; a < sizeof angles / sizeof angles[0]; ++a) {
            ori_generate_def def = ori_default_generate_def(ORI_TESS_YOSHIMURA);
            def.rows = sizes[s][0];
            def.cols = sizes[s][1];
            def.angle_rad = deg(angles[a]);
            def.width = 2.0;
            ori_pattern *p = gen_ok(&def, NULL);
            int R = def.rows, C = def.cols;
            cr_assert_eq(ori_pattern_vertex_count(p), (C + 1) * (R + 1) + (R + 1) / 2);
            cr_assert_eq(ori_pattern_face_count(p), R * (2 * C + 1));
            int interior = check_pattern(&def, p);
            // interior vertices: rows 1..R−1, C−1 on even rows and C on odd rows
            int want = 0;
            for (int j = 1; j < R; ++j) want += (j % 2) ? C : C - 1;
            cr_assert_eq(interior, want);
            for (int v = 0; v < ori_pattern_vertex_count(p); ++v)
                if (ori_pattern_vertex_is_interior(p, v)) cr_assert_eq(ori_pattern_vertex_degree(p, v), 6);
            cr_assert_float_eq(ori_pattern_diagonal(p), hypot(2.0 * C, R * tan(def.angle_rad)), 1e-12);
            ori_pattern_destroy(p);
        }
}

// --- waterbomb -----------------------------------------------------------------------------

Test(generate, waterbomb_degree6_and_flat_foldable)
{
    const int sizes[][2] = {{1, 1}, {2, 1}, {2, 3}, {5, 4}};
    const double heights[] = {0.6, 1.0, 2.5};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s)
        for (size_t h = 0; h < sizeof heights / sizeof heights[0]; ++h) {
            ori_generate_def def = ori_default_generate_def(ORI_TESS_WATERBOMB);
            def.rows = sizes[s][0];
            def.cols = sizes[s][1];
            def.height = heights[h];
            ori_pattern *p = gen_ok(&def, NULL);
            int R = def.rows, C = def.cols;
            cr_assert_eq(ori_pattern_face_count(p), 6 * R * C);
            check_pattern(&def, p);
            int interior = 0;
            for (int v = 0; v < ori_pattern_vertex_count(p); ++v)
                if (ori_pattern_vertex_is_interior(p, v)) {
                    cr_assert_eq(ori_pattern_vertex_degree(p, v), 6);
                    interior++;
                }
            // grid lines 1..R−1 × 2C−1 columns, plus the centres off the side boundaries
            int centres = 0;
            for (int r = 0; r < R; ++r) centres += (r % 2) ? C - 1 : C;
            cr_assert_eq(interior, (R - 1) * (2 * C - 1) + centres);
            ori_pattern_destroy(p);
        }
}

// --- square twist --------------------------------------------------------------------------

Test(generate, square_twist_single_matches_reference_counts_and_sectors)
{
    // One twist: 16 V, 24 E, 9 F like rabbit-ear's square-twist.fold; sectors 90−α, 90, 90+α, 90.
    ori_generate_def def = ori_default_generate_def(ORI_TESS_SQUARE_TWIST);
    def.rows = def.cols = 1;
    def.angle_rad = deg(30.0);
    ori_pattern *p = gen_ok(&def, NULL);
    cr_assert_eq(ori_pattern_vertex_count(p), 16);
    cr_assert_eq(ori_pattern_edge_count(p), 24);
    cr_assert_eq(ori_pattern_face_count(p), 9);
    cr_assert_eq(check_pattern(&def, p), 4);
    for (int v = 0; v < 4; ++v) {
        double sec[4];
        cr_assert_eq(ori_pattern_vertex_sectors(p, v, NULL, sec, 4), 4);
        double want[4] = {deg(60.0), deg(90.0), deg(120.0), deg(90.0)};
        int start = -1;
        for (int k = 0; k < 4; ++k)
            if (fabs(sec[k] - want[0]) < 1e-12) start = k;
        cr_assert_geq(start, 0);
        for (int k = 0; k < 4; ++k) cr_assert_float_eq(sec[(start + k) % 4], want[k], 1e-12);
    }
    // square M; each pleat one M line and one V line
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_MOUNTAIN), 8);
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_VALLEY), 4);
    ori_pattern_destroy(p);
}

Test(generate, square_twist_tessellation_flat_foldable)
{
    const int sizes[][2] = {{1, 2}, {2, 2}, {3, 4}, {5, 5}};
    const double angles[] = {10.0, 30.0, 45.0, 70.0};
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; ++s)
        for (size_t a = 0; a < sizeof angles / sizeof angles[0]; ++a) {
            ori_generate_def def = ori_default_generate_def(ORI_TESS_SQUARE_TWIST);
            def.rows = sizes[s][0];
            def.cols = sizes[s][1];
            def.angle_rad = deg(angles[a]);
            def.width = 1.0;
            def.height = 1.6;
            def.twist_size = a % 2 ? 0.3 : 0.9;
            ori_edge_class *cls;
            ori_pattern *p = gen_ok(&def, &cls);
            int R = def.rows, C = def.cols;
            cr_assert_eq(check_pattern(&def, p), 4 * R * C);
            // pleats are axis-aligned; squares have side s
            double side = def.twist_size * 1.0 / (cos(def.angle_rad) + sin(def.angle_rad));
            for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
                ori_edge ed = ori_pattern_edge(p, e);
                ori_v3 u = ori_pattern_vertex(p, ed.v[0]), w = ori_pattern_vertex(p, ed.v[1]);
                if (cls[e] == ORI_EDGE_CLASS_PLEAT) cr_assert(u.x == w.x || u.y == w.y, "pleat %d not axis-aligned", e);
                if (cls[e] == ORI_EDGE_CLASS_SQUARE) cr_assert_float_eq(hypot(w.x - u.x, w.y - u.y), side, 1e-12);
            }
            ori_buffer_free(cls);
            ori_pattern_destroy(p);
        }
}

// --- Kresling ------------------------------------------------------------------------------

Test(generate, kresling_strip_is_the_development_of_the_cylinder)
{
    const int sides[] = {3, 4, 6, 9};
    for (size_t s = 0; s < sizeof sides / sizeof sides[0]; ++s)
        for (int bistable = 0; bistable <= 1; ++bistable) {
            ori_generate_def def = ori_default_generate_def(ORI_TESS_KRESLING);
            int n = sides[s];
            def.sides = n;
            def.rows = 4;
            def.width = 1.3;
            double u = ORI_PI / n;
            def.angle_rad = 0.4 * (0.5 * ORI_PI - u);
            def.bistable_height = bistable;
            def.height = 0.8;
            ori_edge_class *cls;
            ori_pattern *p = gen_ok(&def, &cls);
            cr_assert_eq(ori_pattern_vertex_count(p), (n + 1) * 5);
            cr_assert_eq(ori_pattern_face_count(p), 2 * n * 4);
            cr_assert_eq(check_pattern(&def, p), (n - 1) * 3);
            // Edge lengths equal the 3D distances of the deployed cylinder.
            double r = def.width / (2 * sin(u));
            double h = bistable ? ori_kresling_bistable_height(n, def.width, def.angle_rad) : def.height;
            ori_v3 b0 = {r, 0, 0}, b1 = {r * cos(2 * u), r * sin(2 * u), 0};
            ori_v3 t0 = {r * cos(def.angle_rad), r * sin(def.angle_rad), h};
            ori_v3 t1 = {r * cos(2 * u + def.angle_rad), r * sin(2 * u + def.angle_rad), h};
            double la = ori_v3_norm(ori_v3_sub(b1, b0)), lb = ori_v3_norm(ori_v3_sub(t0, b0)),
                   lc = ori_v3_norm(ori_v3_sub(t1, b0));
            int seams = 0;
            for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
                ori_edge ed = ori_pattern_edge(p, e);
                ori_v3 x = ori_pattern_vertex(p, ed.v[0]), y = ori_pattern_vertex(p, ed.v[1]);
                double len = ori_v3_norm(ori_v3_sub(x, y));
                switch (cls[e]) {
                case ORI_EDGE_CLASS_BOUNDARY:
                case ORI_EDGE_CLASS_POLYGON: cr_assert_float_eq(len, la, 1e-12); break;
                case ORI_EDGE_CLASS_SEAM: seams++; // fallthrough
                case ORI_EDGE_CLASS_LATERAL: cr_assert_float_eq(len, lb, 1e-12); break;
                case ORI_EDGE_CLASS_DIAGONAL:
                    cr_assert_float_eq(len, lc, 1e-12);
                    cr_assert_eq(ed.assignment, ORI_ASSIGN_VALLEY);
                    break;
                default: cr_assert_fail("unexpected class %d", cls[e]);
                }
            }
            cr_assert_eq(seams, 2 * 4);
            if (bistable) {
                // The flat state (height 0, twist π − 2π/n − φ) has the same triangle sides.
                double phi0 = ORI_PI - 2 * u - def.angle_rad;
                cr_assert_float_eq(2 * r * fabs(sin(0.5 * phi0)), lb, 1e-12);
                cr_assert_float_eq(2 * r * fabs(sin(u + 0.5 * phi0)), lc, 1e-12);
            }
            ori_buffer_free(cls);
            ori_pattern_destroy(p);
        }
}

// --- parameters ----------------------------------------------------------------------------

static void expect_arg_error(ori_generate_def def, const char *field, const char *text)
{
    ori_pattern *p = (ori_pattern *)1;
    ori_edge_class *cls = (ori_edge_class *)1;
    ori_error err;
    cr_assert_eq(ori_generate(&def, &p, &cls, &err), ORI_ERR_ARGUMENT, "%s", field);
    cr_assert_null(p);
    cr_assert_null(cls);
    cr_assert_str_eq(err.field, field);
    cr_assert(strstr(err.message, text), "message '%s' lacks '%s'", err.message, text);
}

Test(generate, bad_parameters_are_argument_errors)
{
    ori_generate_def d = ori_default_generate_def(ORI_TESS_MIURA);
    d.angle_rad = deg(90.0);
    expect_arg_error(d, "angle", "outside (0°, 90°)");
    d = ori_default_generate_def(ORI_TESS_MIURA);
    d.rows = 0;
    expect_arg_error(d, "rows", "between 1 and");
    d = ori_default_generate_def(ORI_TESS_MIURA);
    d.width = -1;
    expect_arg_error(d, "width", "> 0");
    d = ori_default_generate_def(ORI_TESS_MIURA);
    d.height = NAN;
    expect_arg_error(d, "height", "> 0");
    d = ori_default_generate_def(ORI_TESS_YOSHIMURA);
    d.angle_rad = deg(61.0);
    expect_arg_error(d, "angle", "outside (0°, 60°]");
    d = ori_default_generate_def(ORI_TESS_WATERBOMB);
    d.height = 0.5;
    expect_arg_error(d, "height", "tan 30°");
    d = ori_default_generate_def(ORI_TESS_SQUARE_TWIST);
    d.twist_size = 1.0;
    expect_arg_error(d, "twist_size", "(0, 1)");
    d = ori_default_generate_def(ORI_TESS_KRESLING);
    d.sides = 2;
    expect_arg_error(d, "sides", "between 3 and");
    d = ori_default_generate_def(ORI_TESS_KRESLING);
    d.angle_rad = deg(60.0); // limit for n = 6 is 90 − 30 = 60
    expect_arg_error(d, "angle", "outside (0°, 60°)");
    // Yoshimura ignores height; Kresling with a bistable height ignores it too.
    d = ori_default_generate_def(ORI_TESS_YOSHIMURA);
    d.height = -3;
    ori_pattern *p = gen_ok(&d, NULL);
    ori_pattern_destroy(p);
}

Test(generate, size_limit_fails_before_allocating)
{
    ori_generate_def d = ori_default_generate_def(ORI_TESS_WATERBOMB);
    d.rows = d.cols = 10000;
    ori_pattern *p = NULL;
    ori_error err;
    int64_t before = ori_alloc_live_bytes();
    cr_assert_eq(ori_generate(&d, &p, NULL, &err), ORI_ERR_LIMIT);
    cr_assert_eq(ori_alloc_live_bytes(), before);
    cr_assert(strstr(err.message, "limit"));
    ori_pattern_counts n;
    d.rows = d.cols = 1000;
    cr_assert_eq(ori_generate_counts(&d, &n, NULL), ORI_OK);
    cr_assert_eq(n.faces, 6000000);
}

Test(generate, bistable_height_formula)
{
    // Hexagon, side 1 (R = 1), φ = 30°: h² = 4·cos 30°·cos 60° = √3.
    cr_assert_float_eq(ori_kresling_bistable_height(6, 1.0, deg(30.0)), sqrt(sqrt(3.0)), 1e-15);
    cr_assert_eq(ori_kresling_bistable_height(6, 1.0, deg(60.0)), 0.0);
}

// --- command line --------------------------------------------------------------------------

Test(generate, cli_writes_a_valid_fold_with_edge_classes)
{
    char *dir = test_tmpdir();
    char path[600], args[1024];
    snprintf(path, sizeof path, "%s/twist.fold", dir);
    snprintf(args, sizeof args, "generate square-twist --rows 2 --cols 3 --angle 30 -o '%s'", path);
    char *out = NULL;
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    cr_assert(strstr(out, "48 vertices, 82 edges, 35 faces"), "%s", out); // 4RC+4R+4C+4, 8RC+6R+6C+4, 4RC+2R+2C+1
    free(out);
    ori_fold *doc = NULL;
    cr_assert_eq(ori_fold_load_file(path, &doc, NULL), ORI_OK);
    ori_pattern *p = NULL;
    cr_assert_eq(ori_fold_get_pattern(doc, 0, NULL, &p, NULL), ORI_OK); // full validation
    char *cls = ori_fold_get_custom(doc, 0, "orikin:edges_class");
    cr_assert_not_null(cls);
    int n = 0;
    for (const char *c = cls; (c = strstr(c, "\"pleat\"")) != NULL; ++c) n++;
    cr_assert_eq(n, 2 * 2 * 4 + 2 * 3 * 3); // two lines per pleat slot
    char *gen = ori_fold_get_custom(doc, 0, "orikin:generator");
    cr_assert_str_eq(gen, "{\"kind\":\"square-twist\",\"rows\":2,\"cols\":3,\"angle_deg\":30,\"width\":1,"
                          "\"height\":1,\"twist_size\":0.5}");
    ori_buffer_free(gen);
    ori_buffer_free(cls);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    test_tmpdir_remove(dir);
}
