// Import and export of other tools' formats: SVG (Origami Simulator convention), ORIPA .opx and
// .cp; the direct FOLD text writer. Every shared SVG/OPX/CP pattern imports into a valid FOLD
// whose per-assignment edge lengths equal the drawing's; flat-foldable ones pass Kawasaki and
// Maekawa; exports round-trip; malformed input fails with the line and writes nothing.
#include <orikin/formats.h>
#include <orikin/generate.h>
#include <stdio.h>
#include <sys/stat.h>

#include "pattern/pattern_internal.h"
#include "support.h"

TestSuite(formats, .init = test_leak_setup, .fini = test_leak_check);

static char msg[512];

static ori_pattern *import_ok(const char *path, ori_import_stats *stats)
{
    ori_pattern *p = NULL;
    ori_error err;
    ori_status st = ori_import_file(path, ORI_FORMAT_UNKNOWN, NULL, &p, stats, &err);
    cr_assert_eq(st, ORI_OK, "%s: %s", path, ori_error_format(&err, msg, sizeof msg));
    return p;
}

static double edge_length(const ori_pattern *p, int e)
{
    ori_edge ed = ori_pattern_edge(p, e);
    ori_v3 u = ori_pattern_vertex(p, ed.v[0]), w = ori_pattern_vertex(p, ed.v[1]);
    return hypot(w.x - u.x, w.y - u.y);
}

// Write as FOLD text, read it back with full validation (planarity, faces), compare.
static void reload_check(const ori_pattern *p, const char *what)
{
    size_t n;
    char *text = ori_pattern_to_fold_text(p, NULL, 0, &n);
    cr_assert_eq(strlen(text), n);
    ori_fold *doc = NULL;
    ori_error err;
    cr_assert_eq(ori_fold_load_string(text, n, &doc, &err), ORI_OK, "%s", what);
    ori_pattern *q = NULL;
    ori_status st = ori_fold_get_pattern(doc, 0, NULL, &q, &err);
    cr_assert_eq(st, ORI_OK, "%s: %s", what, ori_error_format(&err, msg, sizeof msg));
    cr_assert_eq(ori_pattern_vertex_count(q), ori_pattern_vertex_count(p));
    cr_assert_eq(ori_pattern_edge_count(q), ori_pattern_edge_count(p));
    cr_assert_eq(ori_pattern_face_count(q), ori_pattern_face_count(p));
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge a = ori_pattern_edge(p, e), b = ori_pattern_edge(q, e);
        cr_assert_eq(a.assignment, b.assignment);
        cr_assert_float_eq(a.fold_angle_rad, b.fold_angle_rad, 1e-14);
    }
    ori_pattern_destroy(q);
    ori_fold_destroy(doc);
    ori_buffer_free(text);
}

// Kawasaki within tol (radians) and, when asked, Maekawa at every interior vertex; returns the
// number of interior vertices.
static int check_flat(const ori_pattern *p, double tol, bool maekawa, const char *what)
{
    int interior = 0;
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        if (!ori_pattern_vertex_is_interior(p, v)) continue;
        interior++;
        int ed[64];
        double sec[64];
        int n = ori_pattern_vertex_sectors(p, v, ed, sec, 64);
        cr_assert_eq(n % 2, 0, "%s: vertex %d has odd degree %d", what, v, n);
        double alt = 0.0;
        int m = 0, val = 0;
        for (int i = 0; i < n; ++i) {
            alt += (i % 2 ? -1.0 : 1.0) * sec[i];
            ori_assignment a = ori_pattern_edge(p, ed[i]).assignment;
            m += a == ORI_ASSIGN_MOUNTAIN;
            val += a == ORI_ASSIGN_VALLEY;
        }
        cr_assert_leq(fabs(alt), tol, "%s: Kawasaki at vertex %d: %.3g rad", what, v, alt);
        if (maekawa) cr_assert_eq(abs(m - val), 2, "%s: Maekawa at vertex %d: %d M, %d V", what, v, m, val);
    }
    return interior;
}

// --- every shared drawing --------------------------------------------------------------------

typedef struct shared_case {
    const char *rel;
    double kawasaki_tol; // < 0: not flat-foldable as drawn (not checked)
    bool maekawa;        // the assignment as drawn is a flat fold's
} shared_case;

// SVG tessellations are drawn with 3-decimal coordinates: their angles are only that precise,
// 3e-4 rad covers them (observed ≤ 2.6e-4). The bases and ORIPA files are exact. Origami
// Simulator's bird and waterbomb bases draw the degree-8 centre half-folded (4 M, 4 V at 90°):
// Kawasaki holds there, Maekawa (a flat fold's count) does not.
static const shared_case shared_cases[] = {
    {"origamisimulator/Bases_birdBase.svg", ORI_TOL_KAWASAKI_RAD, false},
    {"origamisimulator/Bases_boatBase.svg", 3e-4, true},
    {"origamisimulator/Bases_frogBase.svg", -1, false},
    {"origamisimulator/Bases_pinwheelBase.svg", 3e-4, true},
    {"origamisimulator/Bases_squareBase.svg", ORI_TOL_KAWASAKI_RAD, true},
    {"origamisimulator/Bases_waterbombBase.svg", ORI_TOL_KAWASAKI_RAD, false},
    {"origamisimulator/Curved_huffmanTower.svg", -1, false},
    {"origamisimulator/Origami_flappingBird.svg", -1, false},
    {"origamisimulator/Origami_hypar.svg", -1, false},
    {"origamisimulator/Origami_singlesquaretwist.svg", 3e-4, true},
    {"origamisimulator/Origami_squaretwistManyAngles.svg", 3e-4, true},
    {"origamisimulator/Origami_traditionalCrane.svg", -1, false},
    {"origamisimulator/SimpleFolds_brochurefold.svg", ORI_TOL_KAWASAKI_RAD, true},
    {"origamisimulator/SimpleFolds_mapfold.svg", ORI_TOL_KAWASAKI_RAD, true},
    {"origamisimulator/SimpleFolds_russianTriangle.svg", ORI_TOL_KAWASAKI_RAD, true},
    {"origamisimulator/SimpleFolds_simpleVertex.svg", ORI_TOL_KAWASAKI_RAD, true},
    {"origamisimulator/Tessellations_huffmanExtrudedBoxes.svg", -1, false},
    {"origamisimulator/Tessellations_huffmanWaterbomb.svg", -1, false},
    {"origamisimulator/Tessellations_langOvalTessellation.svg", -1, false},
    {"origamisimulator/Tessellations_miura-ori.svg", 3e-4, true},
    {"origamisimulator/Tessellations_miura_sharpangle.svg", 3e-4, true},
    {"origamisimulator/Tessellations_reschTriTessellation.svg", -1, false},
    {"origamisimulator/Tessellations_waterbomb.svg", 3e-4, true},
    {"oripa/crane_base_mitani.opx", ORI_TOL_KAWASAKI_RAD, true},
    {"oripa/waterbomb_base_collapse.opx", -1, false},
    {"rabbit-ear/opx_bird-base.opx", ORI_TOL_KAWASAKI_RAD, true},
    {"rabbit-ear/opx_one-crease.opx", ORI_TOL_KAWASAKI_RAD, true},
    {"rabbit-ear/cp_bird-base.cp", ORI_TOL_KAWASAKI_RAD, true},
    {"rabbit-ear/cp_square-fish.cp", ORI_TOL_KAWASAKI_RAD, true},
    {"rabbit-ear/cp_windmill.cp", ORI_TOL_KAWASAKI_RAD, true},
};

Test(formats, every_shared_drawing_imports_with_matching_lengths)
{
    test_require_shared("origamisimulator/Bases_birdBase.svg");
    for (size_t i = 0; i < sizeof shared_cases / sizeof shared_cases[0]; ++i) {
        const char *path = test_require_shared(shared_cases[i].rel);
        ori_segment *segs;
        int n;
        ori_error err;
        cr_assert_eq(ori_read_segments(path, ORI_FORMAT_UNKNOWN, &segs, &n, NULL, &err), ORI_OK, "%s: %s",
                     shared_cases[i].rel, ori_error_format(&err, msg, sizeof msg));
        double src[ORI_ASSIGN_COUNT] = {0}, dst[ORI_ASSIGN_COUNT] = {0};
        for (int k = 0; k < n; ++k) src[segs[k].assignment] += ori_v2_norm(ori_v2_sub(segs[k].b, segs[k].a));
        ori_pattern *p = NULL;
        cr_assert_eq(ori_segments_to_pattern(segs, n, NULL, &p, &err), ORI_OK, "%s: %s", shared_cases[i].rel,
                     ori_error_format(&err, msg, sizeof msg));
        for (int e = 0; e < ori_pattern_edge_count(p); ++e) dst[ori_pattern_edge(p, e).assignment] += edge_length(p, e);
        // Splits keep lengths; welding moves each end point by at most the weld distance.
        double diag = ori_pattern_diagonal(p);
        double slack = 2.0 * n * ORI_TOL_IMPORT_WELD_REL * diag;
        for (int a = 0; a < ORI_ASSIGN_COUNT; ++a)
            cr_assert_float_eq(dst[a], src[a], slack, "%s: %s length %.9g, drawn %.9g", shared_cases[i].rel,
                               ori_assignment_name((ori_assignment)a), dst[a], src[a]);
        cr_assert_gt(ori_pattern_face_count(p), 0);
        for (int f = 0; f < ori_pattern_face_count(p); ++f) cr_assert_gt(ori__pattern_face_area2(p, f), 0.0);
        reload_check(p, shared_cases[i].rel);
        if (shared_cases[i].kawasaki_tol >= 0.0)
            check_flat(p, shared_cases[i].kawasaki_tol, shared_cases[i].maekawa, shared_cases[i].rel);
        ori_pattern_destroy(p);
        ori_buffer_free(segs);
    }
}

Test(formats, simple_drawings_have_the_expected_edges)
{
    static const struct {
        const char *rel;
        int b, m, v, faces, interior;
    } want[] = {
        {"origamisimulator/Bases_squareBase.svg", 8, 4, 2, 6, 1},
        {"origamisimulator/Bases_waterbombBase.svg", 8, 4, 4, 8, 1},
        {"origamisimulator/Bases_birdBase.svg", 8, 12, 8, 16, 5},
        {"origamisimulator/SimpleFolds_simpleVertex.svg", 8, 3, 1, 4, 1},
        {"rabbit-ear/cp_bird-base.cp", 4, 12, 4, 12, 5}, // 8 half sides drawn, merged to 4
        {"rabbit-ear/opx_bird-base.opx", 4, 12, 4, 12, 5},
        {"rabbit-ear/opx_one-crease.opx", 4, 1, 0, 2, 0},
    };
    for (size_t i = 0; i < sizeof want / sizeof want[0]; ++i) {
        ori_import_stats stats;
        ori_pattern *p = import_ok(test_require_shared(want[i].rel), &stats);
        cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_BOUNDARY), want[i].b, "%s", want[i].rel);
        cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_MOUNTAIN), want[i].m, "%s", want[i].rel);
        cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_VALLEY), want[i].v, "%s", want[i].rel);
        cr_assert_eq(ori_pattern_face_count(p), want[i].faces, "%s", want[i].rel);
        cr_assert_eq(ori_pattern_interior_vertex_count(p), want[i].interior, "%s", want[i].rel);
        cr_assert_eq(ori_pattern_edge_count(p), want[i].b + want[i].m + want[i].v);
        ori_pattern_destroy(p);
    }
}

Test(formats, exact_bases_satisfy_big_little_big)
{
    static const char *const rel[] = {"origamisimulator/Bases_squareBase.svg",
                                      "origamisimulator/SimpleFolds_simpleVertex.svg",
                                      "origamisimulator/SimpleFolds_mapfold.svg", "rabbit-ear/cp_bird-base.cp",
                                      "rabbit-ear/opx_bird-base.opx", "oripa/crane_base_mitani.opx",
                                      "rabbit-ear/cp_windmill.cp"};
    char why[256];
    for (size_t i = 0; i < sizeof rel / sizeof rel[0]; ++i) {
        ori_pattern *p = import_ok(test_require_shared(rel[i]), NULL);
        for (int v = 0; v < ori_pattern_vertex_count(p); ++v)
            if (ori_pattern_vertex_is_interior(p, v))
                cr_assert(test_vertex_flat_foldable(p, v, why, sizeof why), "%s: %s", rel[i], why);
        ori_pattern_destroy(p);
    }
}

Test(formats, svg_opacity_is_the_fold_angle)
{
    // birdBase: the two diagonals are blue at opacity 0.5 → valley 90°; red lines fold −180°.
    ori_pattern *p = import_ok(test_require_shared("origamisimulator/Bases_birdBase.svg"), NULL);
    int half = 0;
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        if (ed.assignment == ORI_ASSIGN_MOUNTAIN) cr_assert_float_eq(ed.fold_angle_rad, -ORI_PI, 1e-15);
        if (ed.assignment == ORI_ASSIGN_BOUNDARY) cr_assert_eq(ed.fold_angle_rad, 0.0);
        if (ed.assignment == ORI_ASSIGN_VALLEY && fabs(ed.fold_angle_rad - ORI_PI / 2) < 1e-15) half++;
    }
    cr_assert_eq(half, 4); // two diagonals through the centre, each split once
    cr_assert(ori_pattern_has_fold_angles(p));
    ori_pattern_destroy(p);
}

// --- SVG features --------------------------------------------------------------------------

static ori_segment *read_svg_file(const char *rel, int *n, ori_import_stats *stats)
{
    char *text = test_read_text(test_repo_path(rel));
    cr_assert_not_null(text, "%s", rel);
    ori_segment *segs = NULL;
    ori_error err;
    ori_status st = ori_svg_read_segments(text, strlen(text), &segs, n, stats, &err);
    free(text);
    cr_assert_eq(st, ORI_OK, "%s: %s", rel, ori_error_format(&err, msg, sizeof msg));
    return segs;
}

static void assert_seg(const ori_segment *s, double ax, double ay, double bx, double by, ori_assignment a,
                       double angle)
{
    cr_assert_float_eq(s->a.x, ax, 1e-12);
    cr_assert_float_eq(s->a.y, ay, 1e-12);
    cr_assert_float_eq(s->b.x, bx, 1e-12);
    cr_assert_float_eq(s->b.y, by, 1e-12);
    cr_assert_eq(s->assignment, a);
    cr_assert_float_eq(s->fold_angle_rad, angle, 1e-15);
}

Test(formats, svg_transforms_compose_and_y_flips)
{
    int n;
    ori_segment *s = read_svg_file("tests/data/formats/transforms.svg", &n, NULL);
    cr_assert_eq(n, 4);
    assert_seg(&s[0], 12, -22, 14, -22, ORI_ASSIGN_MOUNTAIN, -ORI_PI);      // matrix ∘ translate
    assert_seg(&s[1], 3, -3, 3, -6, ORI_ASSIGN_VALLEY, ORI_PI);             // scale ∘ rotate about (1, 1)
    assert_seg(&s[2], 1, -1, 2, -1, ORI_ASSIGN_FLAT, 0.0);                   // skewX(45)
    assert_seg(&s[3], 0, -5, 4, -5, ORI_ASSIGN_VALLEY, 0.25 * ORI_PI);       // opacity 0.5 × 0.5, inherited stroke
    ori_buffer_free(s);
}

Test(formats, svg_styles_paths_and_ignored_elements)
{
    int n;
    ori_import_stats stats;
    ori_segment *s = read_svg_file("tests/data/formats/vertex.svg", &n, &stats);
    cr_assert_eq(n, 8); // 4 sides, 2 + 1 mountains, 1 valley
    cr_assert_eq(stats.segments, 8);
    cr_assert_eq(stats.ignored_elements, 1);
    cr_assert_str_eq(stats.ignored_colour, "#123456");
    cr_assert_eq(stats.unsupported_elements, 1); // <text>
    assert_seg(&s[3], 50, -250, 50, -50, ORI_ASSIGN_BOUNDARY, 0.0); // z closes the relative square
    assert_seg(&s[5], 150, -150, 250, -150, ORI_ASSIGN_MOUNTAIN, -ORI_PI); // implicit repeated l
    assert_seg(&s[7], 150, -150, 150, -250, ORI_ASSIGN_VALLEY, 0.5 * ORI_PI); // class rule, stroke-opacity
    ori_pattern *p = NULL;
    ori_error err;
    cr_assert_eq(ori_segments_to_pattern(s, n, NULL, &p, &err), ORI_OK);
    cr_assert_eq(ori_pattern_edge_count(p), 12);
    cr_assert_eq(ori_pattern_face_count(p), 4);
    cr_assert_eq(check_flat(p, ORI_TOL_KAWASAKI_RAD, true, "vertex.svg"), 1);
    ori_pattern_destroy(p);
    ori_buffer_free(s);
}

static ori_status svg_status(const char *svg, ori_error *err)
{
    ori_segment *s = NULL;
    int n = -1;
    ori_status st = ori_svg_read_segments(svg, strlen(svg), &s, &n, NULL, err);
    if (st == ORI_OK) ori_buffer_free(s);
    else {
        cr_assert_null(s);
        cr_assert_eq(n, 0);
    }
    return st;
}

Test(formats, svg_errors_name_the_line)
{
    ori_error err;
    cr_assert_eq(svg_status("<svg xmlns='http://www.w3.org/2000/svg'>\n<line x1='0' y1='0' x2='1' y2='1'>\n</svg>", &err),
                 ORI_ERR_PARSE);
    cr_assert_eq(err.line, 3);
    cr_assert(strstr(err.message, "XML"), "%s", err.message);
    cr_assert_eq(svg_status("<svg>\n<path stroke='red' d='M0 0 L10'/></svg>", &err), ORI_ERR_PARSE);
    cr_assert_eq(err.line, 2);
    cr_assert(strstr(err.message, "path data"), "%s", err.message);
    cr_assert_eq(svg_status("<svg>\n\n<path stroke='#00f' d='M0 0 Q 1 1 2 0'/></svg>", &err), ORI_ERR_UNSUPPORTED);
    cr_assert_eq(err.line, 3);
    cr_assert(strstr(err.message, "'Q'"), "%s", err.message);
    cr_assert_eq(svg_status("<svg><path stroke='#00f' d='M0 0 a 1 1 0 0 1 2 0'/></svg>", &err), ORI_ERR_UNSUPPORTED);
    cr_assert_eq(svg_status("<svg><circle stroke='#f00' r='3'/></svg>", &err), ORI_ERR_UNSUPPORTED);
    cr_assert_eq(svg_status("<svg><rect stroke='#000' width='3' height='3' rx='1'/></svg>", &err), ORI_ERR_UNSUPPORTED);
    cr_assert_eq(svg_status("<svg><line stroke='#000' x1='3%' x2='1'/></svg>", &err), ORI_ERR_PARSE);
    cr_assert_eq(svg_status("<svg><g transform='rotate(1 2)'><line stroke='#000' x2='1'/></g></svg>", &err),
                 ORI_ERR_PARSE);
    cr_assert(strstr(err.message, "rotate"), "%s", err.message);
    cr_assert_eq(svg_status("<svg><polyline stroke='#000' points='0,0 1,x'/></svg>", &err), ORI_ERR_PARSE);
    cr_assert_eq(svg_status("<svg><path stroke='#000' d='M0 0 L1 1 Z 3 4'/></svg>", &err), ORI_ERR_PARSE);
    cr_assert(strstr(err.message, "expected a command"), "%s", err.message);
    cr_assert_eq(svg_status("<svg><path stroke='#000' d='0 0 L1 1'/></svg>", &err), ORI_ERR_PARSE);
    cr_assert_eq(svg_status("<html><line/></html>", &err), ORI_ERR_PARSE);
    cr_assert(strstr(err.message, "<svg>"), "%s", err.message);
    cr_assert_eq(svg_status("", &err), ORI_ERR_PARSE);
    // Curves in a non-crease colour, unknown elements and namespaces are ignored.
    cr_assert_eq(svg_status("<svg><path stroke='#abc' d='M0 0 C 1 1 2 2 3 3'/><foo:bar xmlns:foo='x'/><blink/></svg>", &err),
                 ORI_OK);
}

Test(formats, svg_colours_in_every_notation)
{
    static const struct {
        const char *stroke;
        ori_assignment a;
    } c[] = {{"#FF0000", ORI_ASSIGN_MOUNTAIN},       {"#f00", ORI_ASSIGN_MOUNTAIN},  {"red", ORI_ASSIGN_MOUNTAIN},
             {"rgb(255, 0, 0)", ORI_ASSIGN_MOUNTAIN}, {"rgb(0%,0%,100%)", ORI_ASSIGN_VALLEY},
             {"Blue", ORI_ASSIGN_VALLEY},            {"#00ff00", ORI_ASSIGN_CUT},    {"lime", ORI_ASSIGN_CUT},
             {"green", ORI_ASSIGN_CUT},              {"#ff0", ORI_ASSIGN_FLAT},      {"yellow", ORI_ASSIGN_FLAT},
             {"#ff00ff", ORI_ASSIGN_UNASSIGNED},     {"fuchsia", ORI_ASSIGN_UNASSIGNED},
             {"black", ORI_ASSIGN_BOUNDARY},         {"#000000 !important", ORI_ASSIGN_BOUNDARY}};
    for (size_t i = 0; i < sizeof c / sizeof c[0]; ++i) {
        char svg[256];
        snprintf(svg, sizeof svg, "<svg><line style='stroke: %s' x2='1'/></svg>", c[i].stroke);
        ori_segment *s;
        int n;
        cr_assert_eq(ori_svg_read_segments(svg, strlen(svg), &s, &n, NULL, NULL), ORI_OK);
        cr_assert_eq(n, 1, "%s", c[i].stroke);
        cr_assert_eq(s[0].assignment, c[i].a, "%s", c[i].stroke);
        ori_buffer_free(s);
    }
    // currentColor follows color; #fe0000 is not red.
    const char *svg = "<svg color='#00f'><line stroke='currentColor' x2='1'/><line stroke='#fe0000' x2='2'/></svg>";
    ori_segment *s;
    int n;
    ori_import_stats stats;
    cr_assert_eq(ori_svg_read_segments(svg, strlen(svg), &s, &n, &stats, NULL), ORI_OK);
    cr_assert_eq(n, 1);
    cr_assert_eq(s[0].assignment, ORI_ASSIGN_VALLEY);
    cr_assert_eq(stats.ignored_elements, 1);
    ori_buffer_free(s);
}

Test(formats, svg_entities_are_not_expanded_and_nothing_is_fetched)
{
    const char *svg = "<?xml version='1.0'?>\n<!DOCTYPE svg [<!ENTITY e SYSTEM 'file:///etc/passwd'>]>\n"
                      "<svg><line stroke='#f00' x2='1'/><text>&e;</text></svg>";
    ori_segment *s;
    int n;
    ori_error err;
    cr_assert_eq(ori_svg_read_segments(svg, strlen(svg), &s, &n, NULL, &err), ORI_OK, "%s",
                 ori_error_format(&err, msg, sizeof msg));
    cr_assert_eq(n, 1);
    ori_buffer_free(s);
}

// --- ORIPA ---------------------------------------------------------------------------------

Test(formats, opx_structure_and_defaults)
{
    // one-crease.opx: a mountain diagonal (200,-200)–(-200,200) in ORIPA's y-down frame.
    ori_segment *s;
    int n;
    ori_import_stats stats;
    ori_error err;
    cr_assert_eq(ori_read_segments(test_require_shared("rabbit-ear/opx_one-crease.opx"), ORI_FORMAT_UNKNOWN, &s, &n,
                                   &stats, &err),
                 ORI_OK);
    cr_assert_eq(n, 5);
    assert_seg(&s[0], 200, 200, -200, -200, ORI_ASSIGN_MOUNTAIN, -ORI_PI);
    ori_buffer_free(s);
    // Missing properties are 0; type 7 is refused with the line of its object.
    char *text = test_read_text(test_repo_path("tests/data/formats/bad_type.opx"));
    cr_assert_eq(ori_opx_read_segments(text, strlen(text), &s, &n, NULL, &err), ORI_ERR_PARSE);
    cr_assert_eq(err.line, 7);
    cr_assert(strstr(err.message, "type 7"), "%s", err.message);
    free(text);
    const char *aux = "<java><object class='oripa.OriLineProxy'><void property='x1'><double>5</double></void>"
                      "<void property='type'><int>3</int></void></object>"
                      "<object class='oripa.OriLineProxy'/></java>";
    cr_assert_eq(ori_opx_read_segments(aux, strlen(aux), &s, &n, &stats, &err), ORI_OK);
    cr_assert_eq(n, 1); // the second line is type 0 (aux) by default
    cr_assert_eq(stats.ignored_elements, 1);
    assert_seg(&s[0], 0, 0, 5, 0, ORI_ASSIGN_VALLEY, ORI_PI);
    ori_buffer_free(s);
    const char *bad = "<java>\n<object class='oripa.OriLineProxy'><void property='x0'><double>1e</double></void></object></java>";
    cr_assert_eq(ori_opx_read_segments(bad, strlen(bad), &s, &n, NULL, &err), ORI_ERR_PARSE);
    cr_assert_eq(err.line, 2);
    cr_assert_eq(ori_opx_read_segments("<svg/>", 6, &s, &n, NULL, &err), ORI_ERR_PARSE);
    cr_assert(strstr(err.message, "not an ORIPA file"));
}

Test(formats, cp_lines_and_errors)
{
    ori_segment *s;
    int n;
    ori_error err;
    const char *ok = "1 0 0 10 0\r\n\n  2\t0 0   10 10  \n4 0 0 1 1\n3 1e1 0 0 1.5E1\n";
    cr_assert_eq(ori_cp_read_segments(ok, strlen(ok), &s, &n, NULL, &err), ORI_OK);
    cr_assert_eq(n, 3);
    assert_seg(&s[2], 10, 0, 0, -15, ORI_ASSIGN_VALLEY, ORI_PI);
    ori_buffer_free(s);
    // A UTF-8 byte-order mark (Windows editors) is not part of the first line.
    const char *bom = "\xEF\xBB\xBF" "2 0 0 1 1\n";
    cr_assert_eq(ori_cp_read_segments(bom, strlen(bom), &s, &n, NULL, &err), ORI_OK);
    cr_assert_eq(n, 1);
    ori_buffer_free(s);
    static const struct {
        const char *text;
        int line;
    } bad[] = {{"1 0 0 10 0\n2 0 0 10\n", 2},          {"1 0 0 10 0 7\n", 1}, {"\n\nx 0 0 1 1\n", 3},
               {"7 0 0 1 1\n", 1},                      {"2 0 0 1 1e999\n", 1}, {"2 0 0 nan 1\n", 1},
               {"2 0x10 0 1 1\n", 1},                   {"1.5 0 0 1 1\n", 1}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        cr_assert_eq(ori_cp_read_segments(bad[i].text, strlen(bad[i].text), &s, &n, NULL, &err), ORI_ERR_PARSE, "%zu", i);
        cr_assert_eq(err.line, bad[i].line, "case %zu: line %d", i, err.line);
    }
}

// --- export and round trips ------------------------------------------------------------------

// Every edge of p has an edge of q with the same end points, assignment and fold angle.
static void assert_same_edges(const ori_pattern *p, const ori_pattern *q, double angle_tol)
{
    cr_assert_eq(ori_pattern_edge_count(q), ori_pattern_edge_count(p));
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge a = ori_pattern_edge(p, e);
        ori_v3 a0 = ori_pattern_vertex(p, a.v[0]), a1 = ori_pattern_vertex(p, a.v[1]);
        bool found = false;
        for (int f = 0; f < ori_pattern_edge_count(q) && !found; ++f) {
            ori_edge b = ori_pattern_edge(q, f);
            ori_v3 b0 = ori_pattern_vertex(q, b.v[0]), b1 = ori_pattern_vertex(q, b.v[1]);
            bool same = (a0.x == b0.x && a0.y == b0.y && a1.x == b1.x && a1.y == b1.y) ||
                        (a0.x == b1.x && a0.y == b1.y && a1.x == b0.x && a1.y == b0.y);
            if (!same) continue;
            found = true;
            cr_assert_eq(b.assignment, a.assignment, "edge %d", e);
            cr_assert_float_eq(b.fold_angle_rad, a.fold_angle_rad, angle_tol, "edge %d", e);
        }
        cr_assert(found, "edge %d (%g, %g)–(%g, %g) missing", e, a0.x, a0.y, a1.x, a1.y);
    }
}

static ori_pattern *reimport(const char *text, ori_format f)
{
    ori_segment *s;
    int n;
    ori_error err;
    ori_status st = f == ORI_FORMAT_SVG ? ori_svg_read_segments(text, strlen(text), &s, &n, NULL, &err)
                    : f == ORI_FORMAT_CP ? ori_cp_read_segments(text, strlen(text), &s, &n, NULL, &err)
                                         : ori_opx_read_segments(text, strlen(text), &s, &n, NULL, &err);
    cr_assert_eq(st, ORI_OK, "%s", ori_error_format(&err, msg, sizeof msg));
    ori_pattern *q = NULL;
    st = ori_segments_to_pattern(s, n, NULL, &q, &err);
    cr_assert_eq(st, ORI_OK, "%s", ori_error_format(&err, msg, sizeof msg));
    ori_buffer_free(s);
    return q;
}

Test(formats, svg_export_round_trips_edges_assignments_and_angles)
{
    ori_generate_def def = ori_default_generate_def(ORI_TESS_SQUARE_TWIST);
    def.rows = 2;
    def.cols = 3;
    def.angle_rad = ori_deg_to_rad(30.0);
    ori_pattern *p = NULL;
    cr_assert_eq(ori_generate(&def, &p, NULL, NULL), ORI_OK);
    // give the creases varied fold angles (sign by assignment)
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        double mag = ORI_PI * (0.1 + 0.9 * (e % 7) / 6.0);
        if (ed.assignment == ORI_ASSIGN_MOUNTAIN) ori_pattern_set_fold_angle(p, e, -mag);
        if (ed.assignment == ORI_ASSIGN_VALLEY) ori_pattern_set_fold_angle(p, e, mag);
    }
    char *svg = ori_svg_write(p, NULL);
    cr_assert(strstr(svg, "viewBox=\""));
    cr_assert(strstr(svg, "stroke=\"#ff0000\""));
    ori_pattern *q = reimport(svg, ORI_FORMAT_SVG);
    assert_same_edges(p, q, 1e-15); // (to the last bit: see svg_opacity_gives_the_angle_back_to_the_last_bit)
    cr_assert_eq(ori_pattern_face_count(q), ori_pattern_face_count(p));
    ori_pattern_destroy(q);
    ori_buffer_free(svg);
    // full_fold: every M/V back at ±π
    ori_svg_write_def sdef = ori_default_svg_write_def();
    sdef.full_fold = true;
    svg = ori_svg_write(p, &sdef);
    cr_assert_null(strstr(svg, "stroke-opacity"));
    ori_buffer_free(svg);
    ori_pattern_destroy(p);
}

Test(formats, cp_and_opx_export_round_trip)
{
    ori_pattern *p = import_ok(test_require_shared("rabbit-ear/cp_bird-base.cp"), NULL);
    char *cp = ori_cp_write(p);
    ori_pattern *q = reimport(cp, ORI_FORMAT_CP);
    assert_same_edges(p, q, 0.0);
    ori_pattern_destroy(q);
    char *opx = ori_opx_write(p);
    q = reimport(opx, ORI_FORMAT_OPX);
    assert_same_edges(p, q, 0.0);
    ori_pattern_destroy(q);
    ori_buffer_free(cp);
    ori_buffer_free(opx);
    ori_pattern_destroy(p);
}

// --- planarisation ---------------------------------------------------------------------------

Test(formats, crossing_and_overlapping_segments_are_planarised)
{
    // Square with two crossing diagonals drawn in pieces that overlap, and a hole that a crease
    // joins to the left side.
    ori_segment s[] = {
        {{0, 0}, {4, 0}, ORI_ASSIGN_BOUNDARY, 0},        {{4, 0}, {4, 4}, ORI_ASSIGN_BOUNDARY, 0},
        {{4, 4}, {0, 4}, ORI_ASSIGN_BOUNDARY, 0},        {{0, 4}, {0, 0}, ORI_ASSIGN_BOUNDARY, 0},
        {{0, 0}, {3, 3}, ORI_ASSIGN_VALLEY, ORI_PI},     {{2, 2}, {4, 4}, ORI_ASSIGN_VALLEY, ORI_PI},
        {{0, 4}, {4, 0}, ORI_ASSIGN_MOUNTAIN, -ORI_PI},
        {{0.5, 1.5}, {1, 1.5}, ORI_ASSIGN_BOUNDARY, 0}, {{1, 1.5}, {1, 2}, ORI_ASSIGN_BOUNDARY, 0},
        {{1, 2}, {0.5, 2}, ORI_ASSIGN_BOUNDARY, 0},     {{0.5, 2}, {0.5, 1.5}, ORI_ASSIGN_BOUNDARY, 0},
        {{0, 1.5}, {0.5, 1.5}, ORI_ASSIGN_VALLEY, ORI_PI},
    };
    int n = (int)(sizeof s / sizeof s[0]);
    ori_pattern *p = NULL;
    ori_error err;
    cr_assert_eq(ori_segments_to_pattern(s, n, NULL, &p, &err), ORI_OK, "%s", ori_error_format(&err, msg, sizeof msg));
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_VALLEY), 3); // overlap merged, split at the centre
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_MOUNTAIN), 2);
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_BOUNDARY), 9); // left side split by the crease
    cr_assert_eq(ori_pattern_face_count(p), 4);                            // the hole is not a face
    double area = 0.0;
    for (int f = 0; f < ori_pattern_face_count(p); ++f) area += 0.5 * ori__pattern_face_area2(p, f);
    cr_assert_float_eq(area, 16.0 - 0.25, 1e-12); // and is cut out of the face around it
    cr_assert_eq(ori_pattern_interior_vertex_count(p), 1);
    ori_pattern_destroy(p);
    ori_import_def def = ori_default_import_def();
    def.remove_holes = false;
    cr_assert_eq(ori_segments_to_pattern(s, n, &def, &p, &err), ORI_OK);
    cr_assert_eq(ori_pattern_face_count(p), 5);
    ori_pattern_destroy(p);
    // Without the joining crease the hole floats inside a face: refused, with its place.
    cr_assert_eq(ori_segments_to_pattern(s, n - 1, NULL, &p, &err), ORI_ERR_TOPOLOGY);
    cr_assert_null(p);
    cr_assert(strstr(err.message, "(0.5, 1.5)"), "%s", err.message);
    cr_assert_eq(ori_segments_to_pattern(s, 0, NULL, &p, &err), ORI_ERR_NOT_FOUND);
    // A separate sheet inside the (connected) hole is another piece of paper: allowed.
    ori_segment t[sizeof s / sizeof s[0] + 4];
    memcpy(t, s, sizeof s);
    ori_segment piece[4] = {{{0.6, 1.6}, {0.9, 1.6}, ORI_ASSIGN_BOUNDARY, 0}, {{0.9, 1.6}, {0.9, 1.9}, ORI_ASSIGN_BOUNDARY, 0},
                            {{0.9, 1.9}, {0.6, 1.9}, ORI_ASSIGN_BOUNDARY, 0}, {{0.6, 1.9}, {0.6, 1.6}, ORI_ASSIGN_BOUNDARY, 0}};
    memcpy(t + n, piece, sizeof piece);
    cr_assert_eq(ori_segments_to_pattern(t, n + 4, NULL, &p, &err), ORI_OK, "%s", ori_error_format(&err, msg, sizeof msg));
    cr_assert_eq(ori_pattern_face_count(p), 5);
    ori_pattern_destroy(p);
}

Test(formats, near_misses_within_the_weld_tolerance_join)
{
    // A crease whose end stops 1e-6 short of the boundary, and one whose end is 1e-6 off a vertex.
    ori_segment s[] = {
        {{0, 0}, {1, 0}, ORI_ASSIGN_BOUNDARY, 0},     {{1, 0}, {1, 1}, ORI_ASSIGN_BOUNDARY, 0},
        {{1, 1}, {0, 1}, ORI_ASSIGN_BOUNDARY, 0},     {{0, 1}, {0, 0}, ORI_ASSIGN_BOUNDARY, 0},
        {{0.5, 1e-6}, {0.5, 1}, ORI_ASSIGN_VALLEY, 0}, {{1e-6, 1 + 1e-6}, {0.5, 0.5}, ORI_ASSIGN_MOUNTAIN, 0},
    };
    ori_pattern *p = NULL;
    ori_error err;
    cr_assert_eq(ori_segments_to_pattern(s, 6, NULL, &p, &err), ORI_OK, "%s", ori_error_format(&err, msg, sizeof msg));
    cr_assert_eq(ori_pattern_vertex_count(p), 7); // 4 corners, 2 side midpoints, the T-junction
    cr_assert_eq(ori_pattern_face_count(p), 3);
    ori_pattern_destroy(p);
}

// Origami Simulator's Huffman tower is drawn with 3-decimal coordinates whose end points miss
// each other by up to 1.4e-3 (5e-7 of the drawing's size). At every weld tolerance above that
// it imports into a valid pattern (the arrangement once repeated an edge when two crossings
// snapped together at 1e-5 and 1e-6); below it the drawing falls apart into pieces floating
// inside faces, which is reported as such.
Test(formats, huffman_tower_imports_at_every_weld_tolerance)
{
    // The tower's lines miss each other by up to 0.94 px of a drawing 1,908 px across (4.9e-4 of
    // it): less than the 1 px they are drawn with. Gap closing (the default) joins them whatever
    // the weld; without it, a weld below 1e-7 leaves pieces inside faces, refused.
    const char *path = test_require_shared("origamisimulator/Curved_huffmanTower.svg");
    const double ok[] = {1e-3, 3e-4, 1e-4, 5e-5, 2e-5, 1e-5, 5e-6, 2e-6, 1e-6, 1e-7, 1e-8, 1e-9};
    for (size_t i = 0; i < sizeof ok / sizeof ok[0]; ++i) {
        ori_import_def def = ori_default_import_def();
        def.weld_rel = ok[i];
        ori_pattern *p = NULL;
        ori_error err;
        ori_import_stats stats;
        ori_status st = ori_import_file(path, ORI_FORMAT_UNKNOWN, &def, &p, &stats, &err);
        cr_assert_eq(st, ORI_OK, "tolerance %g: %s", ok[i], ori_error_format(&err, msg, sizeof msg));
        cr_assert_gt(ori_pattern_face_count(p), 500, "tolerance %g", ok[i]);
        for (int f = 0; f < ori_pattern_face_count(p); ++f) cr_assert_gt(ori__pattern_face_area2(p, f), 0.0);
        cr_assert_eq(stats.parts, 1, "tolerance %g", ok[i]);
        cr_assert_eq(stats.dangling, 0, "tolerance %g: vertex %d", ok[i], stats.dangling_example);
        cr_assert_float_eq(stats.stroke_width, 1.0, 0.0); // (SVG's default stroke width)
        reload_check(p, "huffman tower");
        ori_pattern_destroy(p);
    }
    for (double weld = 1e-7; weld >= 1e-9; weld /= 10) {
        ori_import_def def = ori_default_import_def();
        def.weld_rel = weld;
        def.gap_rel = 0.0;
        ori_pattern *p = NULL;
        ori_error err;
        cr_assert_eq(ori_import_file(path, ORI_FORMAT_UNKNOWN, &def, &p, NULL, &err), ORI_ERR_TOPOLOGY, "tolerance %g", weld);
        cr_assert_null(p);
        cr_assert(strstr(err.message, "touch nothing else and lie inside a face") != NULL, "tolerance %g: %s", weld,
                  err.message);
    }
    // and through the CLI
    char *dir = test_tmpdir(), args[8192];
    snprintf(args, sizeof args, "convert '%s' '%s/tower.fold' --tolerance 1e-7", path, dir);
    char *output = NULL;
    cr_assert_eq(test_run_cli(args, &output), 0, "%s", output);
    free(output);
    snprintf(args, sizeof args, "convert '%s' '%s/tower.fold' --tolerance 1e-7 --gaps 0", path, dir);
    cr_assert_eq(test_run_cli(args, &output), 3, "%s", output);
    cr_assert(strstr(output, "touch nothing else") != NULL, "%s", output);
    free(output);
    test_tmpdir_remove(dir);
}

// --- the FOLD text writer --------------------------------------------------------------------

static void assert_text_equals_jansson_path(const ori_pattern *p)
{
    ori_fold_field extra[] = {{"file_title", "\"t\""}, {"orikin:x", "[\"a\",\"b\"]"}};
    size_t n;
    char *direct = ori_pattern_to_fold_text(p, extra, 2, &n);
    ori_fold *doc = ori_fold_create();
    cr_assert_eq(ori_fold_set_custom(doc, 0, "file_title", "\"t\"", NULL), ORI_OK);
    cr_assert_eq(ori_fold_set_custom(doc, 0, "orikin:x", "[\"a\",\"b\"]", NULL), ORI_OK);
    cr_assert_eq(ori_fold_set_pattern(doc, 0, p, NULL), ORI_OK);
    char *tree = ori_fold_to_string(doc);
    cr_assert_str_eq(direct, tree);
    ori_buffer_free(tree);
    ori_buffer_free(direct);
    ori_fold_destroy(doc);
}

Test(formats, fold_text_writer_matches_the_json_tree_writer)
{
    for (int k = 0; k < ORI_TESS_COUNT; ++k) {
        ori_generate_def def = ori_default_generate_def((ori_tessellation)k);
        def.rows = 3;
        def.cols = 2;
        ori_pattern *p = NULL;
        cr_assert_eq(ori_generate(&def, &p, NULL, NULL), ORI_OK);
        ori_pattern_set_fold_angle(p, 0, ori_deg_to_rad(-37.5));
        assert_text_equals_jansson_path(p);
        ori_pattern_destroy(p);
    }
    // names, tree, 3D coordinates, no fold angles, an empty pattern
    ori_pattern *p = test_load_pattern(test_repo_path("examples/patterns/open-corner.fold"), 0);
    assert_text_equals_jansson_path(p);
    cr_assert_eq(ori_pattern_add_tree_node(p, "Obj\"1\\", ORI_NULL_INDEX), ori_pattern_tree_node_count(p) - 1);
    ori_pattern_set_vertex(p, 0, ori_v3_make(0.1, 0.2, 0.3));
    ori_pattern_set_has_fold_angles(p, false);
    assert_text_equals_jansson_path(p);
    ori_pattern_destroy(p);
    ori_pattern_def pdef = ori_default_pattern_def();
    p = ori_pattern_create(&pdef);
    assert_text_equals_jansson_path(p);
    ori_pattern_destroy(p);
}

// --- command line ----------------------------------------------------------------------------

static bool exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

Test(formats, cli_convert_writes_nothing_on_bad_input)
{
    char *dir = test_tmpdir();
    static const char *const bad[] = {"bad_xml.svg", "bad_path.svg", "curve.svg", "bad_line.cp", "empty.cp",
                                      "bad_type.opx", "no_creases.svg"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        char args[2048], out[600];
        snprintf(out, sizeof out, "%s/out%zu.fold", dir, i);
        snprintf(args, sizeof args, "convert tests/data/formats/%s '%s'", bad[i], out);
        char *output = NULL;
        int rc = test_run_cli(args, &output);
        cr_assert_eq(rc, 3, "%s: exit %d: %s", bad[i], rc, output);
        cr_assert(strstr(output, bad[i]), "%s", output);
        cr_assert_not(exists(out), "%s was written", out);
        free(output);
    }
    char args[4096], out[600];
    snprintf(out, sizeof out, "%s/vertex.fold", dir);
    snprintf(args, sizeof args, "convert tests/data/formats/vertex.svg '%s'", out);
    char *output = NULL;
    cr_assert_eq(test_run_cli(args, &output), 0, "%s", output);
    cr_assert(strstr(output, "warning: 1 element(s) ignored"), "%s", output);
    free(output);
    ori_pattern *p = test_load_pattern(out, 0);
    cr_assert_eq(ori_pattern_edge_count(p), 12);
    ori_pattern_destroy(p);
    // FOLD → SVG → FOLD through the CLI
    char svg[600], back[600];
    snprintf(svg, sizeof svg, "%s/vertex.svg", dir);
    snprintf(back, sizeof back, "%s/back.fold", dir);
    snprintf(args, sizeof args, "convert '%s' '%s' && %s convert '%s' '%s'", out, svg, ORI_CLI_PATH, svg, back);
    cr_assert_eq(test_run_cli(args, NULL), 0);
    p = test_load_pattern(back, 0);
    cr_assert_eq(ori_pattern_edge_count(p), 12);
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_MOUNTAIN), 3);
    ori_pattern_destroy(p);
    test_tmpdir_remove(dir);
}

// Islands (parts of a drawing inside a face of another part) against a brute-force reference:
// random axis-aligned squares, some nested, some side by side, some touching a vertex of another
// straight above their leftmost corner (the ray of the check passes through a vertex). The import
// must fail exactly when some square's corner lies strictly inside another square.
static void square_segments(ori_segment *s, double x, double y, double d)
{
    ori_v2 c[4] = {{x, y}, {x + d, y}, {x + d, y + d}, {x, y + d}};
    for (int k = 0; k < 4; ++k) {
        s[k].a = c[k];
        s[k].b = c[(k + 1) % 4];
        s[k].assignment = ORI_ASSIGN_BOUNDARY;
        s[k].fold_angle_rad = 0.0;
    }
}

Test(formats, islands_inside_faces_are_found_exactly)
{
    unsigned seed = 99;
    int outcomes[2] = {0, 0};
    for (int trial = 0; trial < 200; ++trial) {
        int n = 2 + trial % 6;
        double sq[8][3];
        ori_segment segs[32];
        for (int i = 0; i < n; ++i) {
            for (int attempt = 0;; ++attempt) { // squares whose outlines do not meet (so each is its own part)
                cr_assert_lt(attempt, 100000);
                seed = seed * 1664525u + 1013904223u;
                double x = (double)(seed >> 24 & 15), d = 1 + (double)(seed >> 20 & 7);
                double y = (double)(seed >> 12 & 15);
                if (trial % 3 == 0 && i == 1) x = sq[0][0], y = sq[0][1] + sq[0][2] + 1; // straight above: same x
                bool ok = true;
                for (int j = 0; j < i && ok; ++j) {
                    // outlines meet when the boxes overlap without one being strictly inside the other
                    double ax0 = x, ax1 = x + d, ay0 = y, ay1 = y + d, bx0 = sq[j][0], bx1 = sq[j][0] + sq[j][2];
                    double by0 = sq[j][1], by1 = sq[j][1] + sq[j][2];
                    bool apart = ax1 < bx0 || bx1 < ax0 || ay1 < by0 || by1 < ay0;
                    bool a_in_b = ax0 > bx0 && ax1 < bx1 && ay0 > by0 && ay1 < by1;
                    bool b_in_a = bx0 > ax0 && bx1 < ax1 && by0 > ay0 && by1 < ay1;
                    ok = apart || a_in_b || b_in_a;
                }
                if (ok) {
                    sq[i][0] = x, sq[i][1] = y, sq[i][2] = d;
                    break;
                }
            }
            square_segments(segs + 4 * i, sq[i][0], sq[i][1], sq[i][2]);
        }
        bool nested = false;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                nested = nested || (i != j && sq[i][0] > sq[j][0] && sq[i][0] < sq[j][0] + sq[j][2] && sq[i][1] > sq[j][1] &&
                                    sq[i][1] < sq[j][1] + sq[j][2]);
        ori_import_def def = ori_default_import_def();
        def.remove_holes = false; // (a square inside a square would otherwise make it a hole)
        ori_pattern *p = NULL;
        ori_error err;
        char msg[300];
        ori_status st = ori_segments_to_pattern(segs, 4 * n, &def, &p, &err);
        cr_assert_eq(st, nested ? ORI_ERR_TOPOLOGY : ORI_OK, "trial %d (%d squares): %s", trial, n,
                     ori_error_format(&err, msg, sizeof msg));
        outcomes[nested]++;
        ori_pattern_destroy(p);
    }
    cr_assert_gt(outcomes[0], 30, "%d without islands", outcomes[0]);
    cr_assert_gt(outcomes[1], 30, "%d with islands", outcomes[1]);
}

// Entity references are expanded by orikin within a budget: entities that expand to more than
// 8 times the file (plus 1 MB) are refused with a clear error, never expanded at length; ordinary
// entities (Illustrator writes some) and a byte-order mark work.
Test(formats, svg_entities_expand_within_a_budget)
{
    const char *ok = "\xEF\xBB\xBF<?xml version=\"1.0\"?>\n<!DOCTYPE svg [<!ENTITY red \"#ff0000\"><!ENTITY two \"&red;\">\n"
                     "<!ENTITY css \".v { stroke: #0000ff }\">]>\n"
                     "<svg xmlns=\"http://www.w3.org/2000/svg\"><style>&css;</style>\n"
                     "<line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"0\" stroke=\"&two;\"/>\n"
                     "<line class=\"v\" x1=\"0\" y1=\"1\" x2=\"1\" y2=\"1\"/></svg>\n";
    ori_segment *s = NULL;
    int n = 0;
    ori_error err;
    char msg[300];
    cr_assert_eq(ori_svg_read_segments(ok, strlen(ok), &s, &n, NULL, &err), ORI_OK, "%s", ori_error_format(&err, msg, sizeof msg));
    cr_assert_eq(n, 2);
    cr_assert_eq(s[0].assignment, ORI_ASSIGN_MOUNTAIN);
    cr_assert_eq(s[1].assignment, ORI_ASSIGN_VALLEY);
    ori_buffer_free(s);
    // 1000-character entity (below libxml2's own limits) read by 2 attributes of 4000 lines:
    // 8 MB of expansion from a 340 KB file.
    size_t cap = 400000, len = 0;
    char *big = malloc(cap);
    len += (size_t)snprintf(big + len, cap - len, "<!DOCTYPE svg [<!ENTITY a \"xxxxxxxxxx\"><!ENTITY b \"");
    for (int i = 0; i < 10; ++i) len += (size_t)snprintf(big + len, cap - len, "&a;");
    len += (size_t)snprintf(big + len, cap - len, "\"><!ENTITY c \"");
    for (int i = 0; i < 10; ++i) len += (size_t)snprintf(big + len, cap - len, "&b;");
    len += (size_t)snprintf(big + len, cap - len, "\">]>\n<svg xmlns=\"http://www.w3.org/2000/svg\"><style>.q{}</style>\n");
    for (int i = 0; i < 4000; ++i)
        len += (size_t)snprintf(big + len, cap - len,
                                "<line x1=\"0\" y1=\"%d\" x2=\"1\" y2=\"%d\" stroke=\"#f00\" class=\"&c;\" style=\"&c;\"/>\n", i, i);
    len += (size_t)snprintf(big + len, cap - len, "</svg>\n");
    ori_status st = ori_svg_read_segments(big, len, &s, &n, NULL, &err);
    if (st == ORI_ERR_PARSE) { // (libxml2 versions that count attribute expansion refuse it themselves)
        cr_assert(strstr(err.message, "entity"), "%s", err.message);
    } else {
        cr_assert_eq(st, ORI_ERR_LIMIT, "%s", ori_error_format(&err, msg, sizeof msg));
        cr_assert(strstr(err.message, "entity references expand to more than 8 times the file's size"), "%s", err.message);
        cr_assert_gt(err.line, 1);
    }
    ori_buffer_free(s);
    cr_assert_null(s);
    free(big);
}

// The style cascade: tag rules, then .class and tag.class rules in file order (later wins, for
// each property separately), then style=""; an opacity that does not parse overrides nothing.
Test(formats, svg_style_cascade_order)
{
    const char *text = "<svg xmlns=\"http://www.w3.org/2000/svg\"><style>\n"
                       "line { stroke: #000000 }\n"
                       ".a { stroke: #ff0000; stroke-opacity: 0.5 }\n"
                       "line.b { stroke: #0000ff }\n"
                       ".c { stroke-opacity: bogus }\n"
                       ".a { stroke-opacity: 0.25 }\n"
                       "</style>\n"
                       "<line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"0\"/>\n"                                 // B (tag rule)
                       "<line class=\"a\" x1=\"0\" y1=\"1\" x2=\"1\" y2=\"1\"/>\n"                     // M at 0.25
                       "<line class=\"a b\" x1=\"0\" y1=\"2\" x2=\"1\" y2=\"2\"/>\n"                   // V (later), 0.25
                       "<line class=\"b a c\" x1=\"0\" y1=\"3\" x2=\"1\" y2=\"3\"/>\n"                 // same: order is the sheet's
                       "<line class=\"a\" style=\"stroke:#0000ff\" x1=\"0\" y1=\"4\" x2=\"1\" y2=\"4\"/>\n" // V (style="")
                       "<path class=\"b\" d=\"M0 5 L1 5\"/>\n"                                          // no stroke: ignored
                       "</svg>\n";
    ori_segment *s = NULL;
    int n = 0;
    ori_error err;
    cr_assert_eq(ori_svg_read_segments(text, strlen(text), &s, &n, NULL, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(n, 5);
    ori_assignment want[5] = {ORI_ASSIGN_BOUNDARY, ORI_ASSIGN_MOUNTAIN, ORI_ASSIGN_VALLEY, ORI_ASSIGN_VALLEY, ORI_ASSIGN_VALLEY};
    double angle[5] = {0, -0.25 * ORI_PI, 0.25 * ORI_PI, 0.25 * ORI_PI, 0.25 * ORI_PI};
    for (int i = 0; i < 5; ++i) {
        cr_assert_eq(s[i].assignment, want[i], "line %d", i);
        cr_assert_float_eq(s[i].fold_angle_rad, angle[i], 1e-15, "line %d", i);
    }
    ori_buffer_free(s);
}

// Fold angles come back through the SVG opacity (read as opacity × π) to the last bit: exactly
// in most cases, else as a neighbouring double (where the opacities are coarser than the angles,
// no opacity gives the angle itself).
Test(formats, svg_opacity_gives_the_angle_back_to_the_last_bit)
{
    int exact = 0, total = 0;
    for (int k = 1; k < 20000; ++k) {
        double a = ORI_PI * k / 20000.0 + (k % 3) * 1e-13;
        ori_segment seg = {{0, 0}, {1, 0}, ORI_ASSIGN_VALLEY, a};
        ori_pattern *p = NULL;
        cr_assert_eq(ori_segments_to_pattern(&seg, 1, NULL, &p, NULL), ORI_OK);
        char *svg = ori_svg_write(p, NULL);
        ori_segment *s = NULL;
        int n = 0;
        cr_assert_eq(ori_svg_read_segments(svg, strlen(svg), &s, &n, NULL, NULL), ORI_OK);
        cr_assert_eq(n, 1);
        double b = s[0].fold_angle_rad;
        cr_assert(b == a || b == nextafter(a, 0.0) || b == nextafter(a, 4.0), "angle %d: %.17g back as %.17g", k, a, b);
        exact += b == a;
        total++;
        ori_buffer_free(s);
        ori_buffer_free(svg);
        ori_pattern_destroy(p);
    }
    cr_assert_gt(exact, total * 8 / 10, "exact %d of %d", exact, total);
}

// A generated pattern (fold angles 0: no targets) shows its creases: drawn folded flat.
Test(formats, svg_of_a_generated_pattern_shows_its_creases)
{
    ori_generate_def def = ori_default_generate_def(ORI_TESS_MIURA);
    ori_pattern *p = NULL;
    cr_assert_eq(ori_generate(&def, &p, NULL, NULL), ORI_OK);
    char *svg = ori_svg_write(p, NULL);
    cr_assert_null(strstr(svg, "stroke-opacity"), "creases at 0 are written at opacity 1");
    ori_pattern *q = reimport(svg, ORI_FORMAT_SVG);
    for (int e = 0; e < ori_pattern_edge_count(q); ++e) {
        ori_edge ed = ori_pattern_edge(q, e);
        if (ed.assignment == ORI_ASSIGN_MOUNTAIN) cr_assert_eq(ed.fold_angle_rad, -ORI_PI);
        if (ed.assignment == ORI_ASSIGN_VALLEY) cr_assert_eq(ed.fold_angle_rad, ORI_PI);
    }
    cr_assert_eq(ori_pattern_count_assignment(q, ORI_ASSIGN_MOUNTAIN), ori_pattern_count_assignment(p, ORI_ASSIGN_MOUNTAIN));
    ori_pattern_destroy(q);
    ori_buffer_free(svg);
    ori_pattern_destroy(p);
}

// A chain of nearly collinear edges (within the weld) merged into its chord can cross an edge
// that passes closer than the weld: the merged pattern does not build, and the chain keeps its
// vertices. Before, the first read succeeded (its segments in another order), but the CP orikin
// wrote was refused on reading ("edge 0 intersects edge 1 away from a shared vertex"; fuzz_cp,
// fuzz/seeds/cp/merged-chord-crosses-an-edge). Whatever orikin writes, it reads.
Test(formats, a_merged_chord_that_would_cross_keeps_its_vertices)
{
    const char *cp = "1 -014 -200 200 -100\n1 200 -4 00300 280\n1 200 100 -00 0032\n"
                     "1 -201 -21 0 520200\n1 2 -216 200 977\n1 200 100 -00 003200200\n";
    ori_pattern *p = reimport(cp, ORI_FORMAT_CP);
    for (int round = 0; round < 3; ++round) { // written and read again, three times over
        char *text = ori_cp_write(p);
        cr_assert_not_null(text);
        ori_pattern *q = reimport(text, ORI_FORMAT_CP);
        cr_assert_gt(ori_pattern_edge_count(q), 0);
        ori_buffer_free(text);
        ori_pattern_destroy(p);
        p = q;
    }
    ori_pattern_destroy(p);
}

// Labels: one <text> per face (index and name) and per edge, in a group the reader skips
// silently; the drawing reads back as the same pattern.
Test(formats, svg_labels_faces_and_edges_and_reads_back)
{
    ori_pattern *p = test_load_pattern(test_repo_path("examples/patterns/open-corner.fold"), 0);
    ori_svg_write_def def = ori_default_svg_write_def();
    def.label_faces = def.label_edges = true;
    char *svg = ori_svg_write(p, &def);
    int texts = 0;
    for (const char *c = svg; (c = strstr(c, "<text")) != NULL; ++c) texts++;
    cr_assert_eq(texts, ori_pattern_face_count(p) + ori_pattern_edge_count(p));
    char face0[64];
    snprintf(face0, sizeof face0, ">0%s%s</text>", ori_pattern_face_name(p, 0) ? " " : "",
             ori_pattern_face_name(p, 0) ? ori_pattern_face_name(p, 0) : "");
    cr_assert(strstr(svg, face0), "%s lacks %s", svg, face0);
    ori_segment *s = NULL;
    int n = 0;
    ori_import_stats stats;
    cr_assert_eq(ori_svg_read_segments(svg, strlen(svg), &s, &n, &stats, NULL), ORI_OK);
    cr_assert_eq(stats.unsupported_elements, 0);
    cr_assert_eq(n, ori_pattern_edge_count(p));
    ori_buffer_free(s);
    ori_pattern *q = reimport(svg, ORI_FORMAT_SVG);
    cr_assert_eq(ori_pattern_face_count(q), ori_pattern_face_count(p));
    ori_pattern_destroy(q);
    ori_buffer_free(svg);
    ori_pattern_destroy(p);
}

// ORIPA has no flat or unassigned crease: exporting one is refused with the reason and the
// edge, instead of writing an auxiliary line that would not come back.
Test(formats, cp_and_opx_export_refuse_flat_and_unassigned_creases)
{
    char *dir = test_tmpdir();
    char path[600];
    ori_pattern *p = test_load_pattern(test_repo_path("examples/patterns/open-corner.fold"), 0);
    int e = 0;
    while (ori_pattern_edge(p, e).assignment == ORI_ASSIGN_BOUNDARY) ++e;
    ori_error err;
    cr_assert_eq(ori_pattern_assign_crease(p, e, ORI_ASSIGN_UNASSIGNED, &err), ORI_OK);
    const char *ext[2] = {"cp", "opx"};
    for (int k = 0; k < 2; ++k) {
        snprintf(path, sizeof path, "%s/out.%s", dir, ext[k]);
        cr_assert_eq(ori_export_file(p, ORI_FORMAT_UNKNOWN, NULL, path, &err), ORI_ERR_UNSUPPORTED);
        cr_assert_eq(err.element, e);
        cr_assert(strstr(err.message, "ORIPA has no unassigned (U) crease"), "%s", err.message);
        cr_assert_null(test_read_text(path));
    }
    // SVG keeps U (magenta) and reads it back.
    snprintf(path, sizeof path, "%s/out.svg", dir);
    cr_assert_eq(ori_export_file(p, ORI_FORMAT_UNKNOWN, NULL, path, &err), ORI_OK);
    ori_pattern *q = import_ok(path, NULL);
    cr_assert_eq(ori_pattern_count_assignment(q, ORI_ASSIGN_UNASSIGNED), 1);
    ori_pattern_destroy(q);
    // With M instead, CP and OPX export and read back the same creases.
    cr_assert_eq(ori_pattern_assign_crease(p, e, ORI_ASSIGN_MOUNTAIN, &err), ORI_OK);
    for (int k = 0; k < 2; ++k) {
        snprintf(path, sizeof path, "%s/out.%s", dir, ext[k]);
        cr_assert_eq(ori_export_file(p, ORI_FORMAT_UNKNOWN, NULL, path, &err), ORI_OK, "%s", err.message);
        q = import_ok(path, NULL);
        cr_assert_eq(ori_pattern_edge_count(q), ori_pattern_edge_count(p));
        cr_assert_eq(ori_pattern_count_assignment(q, ORI_ASSIGN_MOUNTAIN), ori_pattern_count_assignment(p, ORI_ASSIGN_MOUNTAIN));
        ori_pattern_destroy(q);
    }
    ori_pattern_destroy(p);
    test_tmpdir_remove(dir);
}

// A drawing whose lines all collapse under the weld (its size comes from one far-away stray
// line) is refused, not turned into an empty pattern that writes as nothing (found by fuzzing).
Test(formats, a_drawing_whose_lines_all_weld_away_is_refused)
{
    ori_segment s[3] = {{{0, 0}, {1, 0}, ORI_ASSIGN_MOUNTAIN, -ORI_PI},
                        {{0, 0}, {0, 1}, ORI_ASSIGN_VALLEY, ORI_PI},
                        {{0, 5.5e9}, {3, 5.5e9}, ORI_ASSIGN_VALLEY, ORI_PI}};
    ori_pattern *p = NULL;
    ori_error err;
    cr_assert_eq(ori_segments_to_pattern(s, 3, NULL, &p, &err), ORI_ERR_DEGENERATE);
    cr_assert_null(p);
    cr_assert(strstr(err.message, "every line is shorter than the weld tolerance"), "%s", err.message);
    // A weld below the lines' lengths keeps them (when they are not below the length tolerance
    // of the whole drawing, 1e-9 of it, which no weld can change).
    s[2].a.y = s[2].b.y = 5.5e6;
    cr_assert_eq(ori_segments_to_pattern(s, 3, NULL, &p, &err), ORI_ERR_DEGENERATE);
    ori_import_def def = ori_default_import_def();
    def.weld_rel = 1e-8;
    cr_assert_eq(ori_segments_to_pattern(s, 3, &def, &p, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_pattern_edge_count(p), 3);
    ori_pattern_destroy(p);
}

// libxml2's messages can span lines ("Input is not proper UTF-8, indicate encoding !\nBytes:
// 0xFF …"): the error is one line (the CLI prints one line per error).
Test(formats, xml_errors_are_one_line)
{
    const char text[] = "<svg xmlns=\"http://www.w3.org/2000/svg\"><line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"1\" "
                        "stroke=\"#000\" id=\"\xff\xfe\"/></svg>";
    ori_segment *seg = NULL;
    int n = 0;
    ori_error err;
    cr_assert_eq(ori_svg_read_segments(text, sizeof text - 1, &seg, &n, NULL, &err), ORI_ERR_PARSE);
    cr_assert_null(strchr(err.message, '\n'), "%s", err.message);
    cr_assert(strstr(err.message, "UTF-8") && strstr(err.message, "; Bytes: 0xFF 0xFE"), "%s", err.message);
    cr_assert_gt(err.line, 0);
}

// Creases drawn past the border (Lang's drawings in Origami Simulator) make faces outside the
// sheet, joined to it only across the border: the import clips them at the border. A square
// [0, 10]² with two creases from the top side that cross 0.5 below the bottom side (a triangle
// outside, tails past it) and a vertical crease overshooting both sides by 1 (tails without
// faces): only the sheet is left, every edge inside it, its faces the square's area, and its
// mechanism (which refuses a sheet that falls apart) builds.
Test(formats, creases_drawn_past_the_border_are_clipped)
{
    char *dir = test_tmpdir();
    char path[600];
    snprintf(path, sizeof path, "%s/overshoot.svg", dir);
    FILE *f = fopen(path, "w");
    cr_assert(f);
    // (SVG y down: the bottom side is y = 10; the creases cross at (5, 10.5).)
    fprintf(f, "<svg xmlns='http://www.w3.org/2000/svg'><g stroke-width='0.05'>\n"
               "<rect x='0' y='0' width='10' height='10' stroke='#000'/>\n"
               "<line x1='2' y1='0' x2='5.9' y2='13.65' stroke='#f00'/>\n"
               "<line x1='8' y1='0' x2='4.1' y2='13.65' stroke='#f00'/>\n"
               "<line x1='3' y1='-1' x2='3' y2='11' stroke='#00f'/>\n"
               "</g></svg>\n");
    fclose(f);
    ori_import_stats stats;
    ori_pattern *p = import_ok(path, &stats);
    cr_assert_eq(stats.clipped_faces, 1, "%d", stats.clipped_faces);
    cr_assert_eq(stats.clipped, 6, "%d", stats.clipped); // 2 triangle sides, 2 tails below it, 2 vertical tails
    cr_assert_eq(stats.dangling, 0);
    cr_assert_eq(stats.parts, 1);
    double area = 0.0;
    for (int fc = 0; fc < ori_pattern_face_count(p); ++fc) area += 0.5 * fabs(ori__pattern_face_area2(p, fc));
    cr_assert_float_eq(area, 100.0, 1e-9);
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        ori_v3 x = ori_pattern_vertex(p, v);
        cr_assert(x.x >= -1e-12 && x.x <= 10 + 1e-12 && x.y <= 1e-12 && x.y >= -10 - 1e-12, "vertex %d (%g, %g)", v, x.x, x.y);
    }
    // every boundary edge has the sheet on one side only
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        int fs[2];
        ori_pattern_edge_faces(p, e, fs);
        bool border = ori_pattern_edge(p, e).assignment == ORI_ASSIGN_BOUNDARY;
        cr_assert_eq((fs[0] == ORI_NULL_INDEX) + (fs[1] == ORI_NULL_INDEX), border ? 1 : 0, "edge %d", e);
    }
    ori_mechanism *m = test_mechanism_of(p);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
    // The CLI says so in one note, and dof folds it.
    char args[1024], *out = NULL;
    snprintf(args, sizeof args, "dof '%s'", path);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    cr_assert(strstr(out, "clipped the creases drawn past the border: 6 crease piece(s)"), "%s", out);
    cr_assert_not(strstr(out, "falls apart"), "%s", out);
    free(out);
    // A drawing without a closed border is left alone (nothing is outside of nothing).
    snprintf(path, sizeof path, "%s/open.svg", dir);
    f = fopen(path, "w");
    fprintf(f, "<svg xmlns='http://www.w3.org/2000/svg'><g stroke-width='0.05'>\n"
               "<polyline points='0,10 0,0 10,0 10,10' stroke='#000'/>\n"
               "<line x1='0' y1='5' x2='10' y2='5' stroke='#f00'/><line x1='0' y1='10' x2='10' y2='10' stroke='#f00'/>\n"
               "</g></svg>\n");
    fclose(f);
    p = import_ok(path, &stats);
    cr_assert_eq(stats.clipped, 0);
    cr_assert_eq(ori_pattern_face_count(p), 2);
    ori_pattern_destroy(p);
    test_tmpdir_remove(dir);
}

// Origami Simulator's drawings of Lang (creases overshooting the border), Huffman's waterbomb and
// the whirlpool fold as one sheet.
Test(formats, shared_drawings_with_creases_past_the_border_fold_as_one_sheet)
{
    static const char *const names[] = {"Origami_langCardinal.svg", "Origami_langKnlDragon.svg",
                                        "Tessellations_langHoneycomb.svg", "Tessellations_huffmanWaterbomb.svg",
                                        "Tessellations_whirlpool.svg"};
    int found = 0;
    for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i) {
        char rel[256];
        snprintf(rel, sizeof rel, "origamisimulator/%s", names[i]);
        const char *path = test_shared_path(rel);
        if (!path) continue;
        found++;
        char args[1024], *out = NULL;
        snprintf(args, sizeof args, "dof '%s'", path);
        int rc = test_run_cli(args, &out);
        cr_assert_eq(rc, 0, "%s: exit %d: %s", names[i], rc, out);
        // (the whirlpool's lines miss each other: healed within their width, not clipped; the
        // cardinal's tails cross a hair outside the border: merged into it, nothing left to clip)
        cr_assert(strstr(out, i == 4 ? "lines drawn to meet missed each other" : "clipped the creases drawn past the border") ||
                      (i == 0 && strstr(out, "lines meeting a hair beside a vertex meet at it")),
                  "%s: %s", names[i], out);
        cr_assert_not(strstr(out, "falls apart"), "%s: %s", names[i], out);
        free(out);
    }
    if (!found) cr_skip("../shared/patterns/origamisimulator is absent");
}

// A drawing split by lines that were drawn to meet and miss (Origami Simulator's whirlpool): a
// square whose middle crease is drawn twice, 0.003 apart, the bottom side in two halves ending on
// them: the strip between the two is outside the paper, and only the top side joins the halves.
// Within the drawn line width (0.05) the lines touch on the page: by default the import welds
// with the smallest doubling of the tolerance that joins the pieces (4e-4: 0.003 of a diagonal
// of 14.14 is 2.1e-4) and says so; with heal_splits off (an explicit --tolerance) it says the
// paper is 2 pieces that no crease joins, names a vertex and that tolerance.
Test(formats, a_sheet_split_by_lines_that_miss_is_reported_with_the_tolerance_that_joins_it)
{
    char *dir = test_tmpdir();
    char path[600];
    snprintf(path, sizeof path, "%s/split.svg", dir);
    FILE *f = fopen(path, "w");
    cr_assert(f);
    fprintf(f, "<svg xmlns='http://www.w3.org/2000/svg'><g stroke-width='0.05'>\n"
               "<line x1='0' y1='0' x2='10' y2='0' stroke='#000'/><line x1='0' y1='10' x2='5' y2='10' stroke='#000'/>\n"
               "<line x1='5.003' y1='10' x2='10' y2='10' stroke='#000'/>\n"
               "<line x1='0' y1='0' x2='0' y2='10' stroke='#000'/><line x1='10' y1='0' x2='10' y2='10' stroke='#000'/>\n"
               "<line x1='5' y1='0' x2='5' y2='10' stroke='#f00'/><line x1='5.003' y1='0' x2='5.003' y2='10' stroke='#f00'/>\n"
               "</g></svg>\n");
    fclose(f);
    ori_import_stats stats;
    ori_pattern *p = import_ok(path, &stats);
    cr_assert_float_eq(stats.healed_weld_rel, 4e-4, 1e-15, "%g", stats.healed_weld_rel);
    cr_assert_eq(stats.healed_sheets, 2);
    cr_assert_eq(stats.sheets, 1);
    cr_assert_eq(stats.split_vertex, ORI_NULL_INDEX);
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_MOUNTAIN), 1); // the crease drawn twice is one
    ori_mechanism_destroy(test_mechanism_of(p));
    ori_pattern_destroy(p);
    ori_import_def def = ori_default_import_def();
    def.heal_splits = false;
    ori_error err;
    cr_assert_eq(ori_import_file(path, ORI_FORMAT_UNKNOWN, &def, &p, &stats, &err), ORI_OK);
    cr_assert_eq(stats.parts, 1);
    cr_assert_eq(stats.sheets, 2);
    cr_assert_eq(stats.healed_weld_rel, 0.0);
    cr_assert_neq(stats.split_vertex, ORI_NULL_INDEX);
    cr_assert_eq(ori_pattern_face_count(p), 2);
    cr_assert_float_eq(stats.split_tolerance_rel, 4e-4, 1e-15, "%g", stats.split_tolerance_rel);
    ori_pattern_destroy(p);
    char args[1024], *out = NULL;
    snprintf(args, sizeof args, "convert '%s' '%s/split.fold'", path, dir);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    cr_assert(strstr(out, "note: lines drawn to meet missed each other and left the paper in 2 pieces"), "%s", out);
    cr_assert(strstr(out, "--tolerance 5e-05 keeps them apart"), "%s", out);
    free(out);
    snprintf(args, sizeof args, "convert '%s' '%s/split.fold' --tolerance 5e-5", path, dir);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    cr_assert(strstr(out, "the paper is 2 pieces that no crease joins"), "%s", out);
    cr_assert(strstr(out, "--tolerance 0.0004 joins them"), "%s", out);
    free(out);
    // Segments without a line width (ori_segments_to_pattern, as a .cp has none) are not healed.
    ori_segment *segs;
    int n;
    cr_assert_eq(ori_read_segments(path, ORI_FORMAT_UNKNOWN, &segs, &n, NULL, &err), ORI_OK);
    cr_assert_eq(ori_segments_to_pattern(segs, n, NULL, &p, &err), ORI_OK);
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_MOUNTAIN), 2);
    ori_pattern_destroy(p);
    ori_buffer_free(segs);
    test_tmpdir_remove(dir);
}

// ORIPA auxiliary lines whose coordinates are no number (XMLEncoder's NaN, Infinity; "nan" in
// .cp) are skipped and counted, not a reason to refuse the file; a crease with one still fails
// with its line.
Test(formats, oripa_auxiliary_lines_with_nan_coordinates_are_skipped)
{
    const char *opx = "<java>\n"
                      "<object class='oripa.OriLineProxy'><void property='type'><int>0</int></void>\n"
                      "<void property='x0'><double>NaN</double></void><void property='y1'><double>-Infinity</double></void></object>\n"
                      "<object class='oripa.OriLineProxy'><void property='type'><int>2</int></void>\n"
                      "<void property='x1'><double>4</double></void><void property='y1'><double>3</double></void></object>\n"
                      "</java>";
    ori_segment *s;
    int n;
    ori_import_stats stats;
    ori_error err;
    cr_assert_eq(ori_opx_read_segments(opx, strlen(opx), &s, &n, &stats, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(n, 1);
    cr_assert_eq(stats.ignored_elements, 1);
    cr_assert_eq(stats.degenerate_aux, 1);
    assert_seg(&s[0], 0, 0, 4, -3, ORI_ASSIGN_MOUNTAIN, -ORI_PI);
    ori_buffer_free(s);
    const char *bad = "<java>\n<object class='oripa.OriLineProxy'><void property='type'><int>3</int></void>\n"
                      "<void property='x0'>\n<double>NaN</double></void></object></java>";
    cr_assert_eq(ori_opx_read_segments(bad, strlen(bad), &s, &n, NULL, &err), ORI_ERR_PARSE);
    cr_assert_eq(err.line, 4);
    cr_assert(strstr(err.message, "x0 is not a finite number"), "%s", err.message);
    const char *cp = "1 0 0 10 0\n0 nan 0 NaN 1\n4 -inf 1 2 Infinity\n2 0 0 10 0\n";
    cr_assert_eq(ori_cp_read_segments(cp, strlen(cp), &s, &n, &stats, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(n, 2);
    cr_assert_eq(stats.ignored_elements, 2);
    cr_assert_eq(stats.degenerate_aux, 2);
    ori_buffer_free(s);
    const char *badcp = "1 0 0 10 0\n2 0 nan 10 0\n";
    cr_assert_eq(ori_cp_read_segments(badcp, strlen(badcp), &s, &n, NULL, &err), ORI_ERR_PARSE);
    cr_assert_eq(err.line, 2);
    const char *word = "0 nanny 0 1 1\n";
    cr_assert_eq(ori_cp_read_segments(word, strlen(word), &s, &n, NULL, &err), ORI_ERR_PARSE);
    // The CLI notes it once and reads the file.
    char *dir = test_tmpdir(), path[600], args[1024], *out = NULL;
    snprintf(path, sizeof path, "%s/aux.cp", dir);
    FILE *f = fopen(path, "w");
    fputs("1 0 0 10 0\n1 10 0 10 10\n1 10 10 0 10\n1 0 10 0 0\n2 0 0 10 10\n0 NaN 0 1 1\n", f);
    fclose(f);
    snprintf(args, sizeof args, "info '%s'", path);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    cr_assert(strstr(out, "note: 1 of them had a coordinate that is not a number"), "%s", out);
    free(out);
    test_tmpdir_remove(dir);
}

// Curves are refused unless asked to flatten them: then each cubic, quadratic, arc, circle and
// rounded corner becomes N straight segments whose ends lie on the curve, joined end to end.
Test(formats, svg_curves_flatten_into_n_segments_on_the_curve)
{
    // A cubic from (0, 0) to (10, 0) (control points (0, 10), (10, 10)) and a relative smooth
    // cubic after it, a half circle of radius 5 as an arc from (0, 0) to (10, 0) through
    // (5, -5), a quadratic with its smooth twin, a circle of radius 2 at (20, 20) (SVG frame).
    const char *svg = "<svg xmlns='http://www.w3.org/2000/svg'>\n"
                      "<path stroke='#f00' d='M0 0 C 0 10 10 10 10 0 s 10 -10 10 0'/>\n"
                      "<path stroke='#00f' d='M0 0 A5 5 0 0 1 10 0'/>\n"
                      "<path stroke='#00f' d='M0 30 Q 5 40 10 30 T 20 30'/>\n"
                      "<circle stroke='#000' cx='20' cy='20' r='2'/>\n"
                      "</svg>";
    ori_segment *s;
    int n;
    ori_import_stats stats;
    ori_error err;
    cr_assert_eq(ori_svg_read_segments(svg, strlen(svg), &s, &n, NULL, &err), ORI_ERR_UNSUPPORTED);
    cr_assert(strstr(err.message, "--flatten-curves"), "%s", err.message);
    cr_assert_eq(err.line, 2);
    const int k = 8;
    cr_assert_eq(ori_svg_read_curves(svg, strlen(svg), k, &s, &n, &stats, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(n, 6 * k);
    cr_assert_eq(stats.flattened_curves, 6);
    for (int i = 0; i < n; ++i) // joined end to end within each curve
        if (i % k) cr_assert(s[i].a.x == s[i - 1].b.x && s[i].a.y == s[i - 1].b.y, "segment %d", i);
    // the first cubic (y flipped): the Bernstein form at t = (i + 1) / k
    for (int i = 0; i < k; ++i) {
        double t = (double)(i + 1) / k, u = 1 - t;
        double x = 3 * u * t * t * 10 + t * t * t * 10, y = -(3 * u * u * t * 10 + 3 * u * t * t * 10);
        cr_assert_float_eq(s[i].b.x, x, 1e-12, "%d", i);
        cr_assert_float_eq(s[i].b.y, y, 1e-12, "%d", i);
        cr_assert_eq(s[i].assignment, ORI_ASSIGN_MOUNTAIN);
    }
    cr_assert(s[k - 1].b.x == 10 && s[k - 1].b.y == 0); // the end point exactly
    // the smooth cubic reflects (10, 10) about (10, 0): its first control point is (10, -10)
    {
        double t = 0.5, u = 0.5;
        double y = 3 * u * u * t * -10 + 3 * u * t * t * -10; // SVG y of the mid point
        cr_assert_float_eq(s[k + k / 2 - 1].b.y, -y, 1e-12);
        cr_assert_float_eq(s[2 * k - 1].b.x, 20, 1e-12);
    }
    // the arc: every point 5 from (5, 0), sweep 1 in SVG's y-down frame goes through y = -5, i.e. +5 in FOLD
    for (int i = 2 * k; i < 3 * k; ++i) {
        cr_assert_float_eq(hypot(s[i].b.x - 5, s[i].b.y), 5, 1e-12, "%d", i);
        cr_assert(s[i].b.y >= -1e-12, "%d: %g", i, s[i].b.y);
        cr_assert_eq(s[i].assignment, ORI_ASSIGN_VALLEY);
    }
    cr_assert_float_eq(s[2 * k + k / 2 - 1].b.y, 5, 1e-12);
    // the quadratic: mid point (5, 35) in SVG; the smooth twin mirrors it to (15, 25)
    cr_assert_float_eq(s[3 * k + k / 2 - 1].b.x, 5, 1e-12);
    cr_assert_float_eq(s[3 * k + k / 2 - 1].b.y, -35, 1e-12);
    cr_assert_float_eq(s[4 * k + k / 2 - 1].b.x, 15, 1e-12);
    cr_assert_float_eq(s[4 * k + k / 2 - 1].b.y, -25, 1e-12);
    // the circle: a closed polygon on radius 2
    for (int i = 5 * k; i < 6 * k; ++i) cr_assert_float_eq(hypot(s[i].a.x - 20, s[i].a.y + 20), 2, 1e-12);
    cr_assert(s[6 * k - 1].b.x == s[5 * k].a.x && s[6 * k - 1].b.y == s[5 * k].a.y);
    ori_buffer_free(s);
    // A rounded rectangle: four sides and four corners on their quarter circles.
    const char *rect = "<svg><rect stroke='#000' x='0' y='0' width='10' height='6' rx='2'/></svg>";
    cr_assert_eq(ori_svg_read_curves(rect, strlen(rect), 0, &s, &n, NULL, &err), ORI_ERR_UNSUPPORTED);
    cr_assert_eq(ori_svg_read_curves(rect, strlen(rect), 4, &s, &n, &stats, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(n, 4 + 4 * 4);
    cr_assert_float_eq(hypot(s[1 + 1].b.x - 8, s[1 + 1].b.y + 2), 2, 1e-12); // the first corner about (8, 2)
    ori_buffer_free(s);
    // Through the CLI: a closed curved sheet imports with the option, is refused without it, and
    // the option's value is checked.
    char *dir = test_tmpdir(), path[600], args[1200], *out = NULL;
    snprintf(path, sizeof path, "%s/curved.svg", dir);
    FILE *f = fopen(path, "w");
    fputs("<svg xmlns='http://www.w3.org/2000/svg'><rect stroke='#000' width='20' height='10'/>\n"
          "<path stroke='#f00' d='M10 0 C 4 3 4 7 10 10'/></svg>\n", f);
    fclose(f);
    snprintf(args, sizeof args, "info '%s'", path);
    cr_assert_eq(test_run_cli(args, &out), 3, "%s", out);
    cr_assert(strstr(out, "line 2") && strstr(out, "--flatten-curves N"), "%s", out);
    free(out);
    snprintf(args, sizeof args, "convert '%s' '%s/c.fold' --flatten-curves 12", path, dir);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    cr_assert(strstr(out, "1 curve(s), arc(s) or circle(s) flattened into 12 straight crease(s) each"), "%s", out);
    free(out);
    snprintf(args, sizeof args, "%s/c.fold", dir);
    ori_pattern *p = test_load_pattern(args, 0);
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_MOUNTAIN), 12);
    cr_assert_eq(ori_pattern_face_count(p), 2);
    ori_pattern_destroy(p);
    snprintf(args, sizeof args, "info '%s' --flatten-curves 0", path);
    cr_assert_eq(test_run_cli(args, &out), 2, "%s", out);
    cr_assert(strstr(out, "--flatten-curves"), "%s", out);
    free(out);
    snprintf(args, sizeof args, "info '%s/c.fold' --flatten-curves 4", dir);
    cr_assert_eq(test_run_cli(args, &out), 2, "%s", out);
    free(out);
    test_tmpdir_remove(dir);
}

// The table of file formats: every *_from_path is its lookup; a drawing read from its text is
// the pattern (and the stats) of the same drawing read from its file.
Test(formats, format_table_and_import_from_text)
{
    cr_assert_eq(ori_format_from_path("a/B.SVG"), ORI_FORMAT_SVG);
    cr_assert_eq(ori_format_from_path("x.fold"), ORI_FORMAT_FOLD);
    cr_assert_eq(ori_format_from_path("dir.cp/x"), ORI_FORMAT_UNKNOWN);
    cr_assert_eq(ori_format_from_path("x.png"), ORI_FORMAT_UNKNOWN);
    cr_assert_eq(ori_format_find("x.svg", ORI_FORMAT_KIND_IMAGE)->code, ORI_IMAGE_SVG);
    cr_assert_eq(ori_format_find("x.GLB", ORI_FORMAT_KIND_MESH)->code, ORI_MESH_GLB);
    cr_assert_null(ori_format_find("x.glb", ORI_FORMAT_KIND_IMAGE));
    cr_assert_str_eq(ori_format_name(ORI_FORMAT_OPX), "opx");
    cr_assert(ori_format_is_drawing(ORI_FORMAT_CP) && !ori_format_is_drawing(ORI_FORMAT_FOLD) &&
              !ori_format_is_drawing(ORI_FORMAT_UNKNOWN));
    int n = 0;
    const ori_format_info *t = ori_format_table(&n);
    cr_assert_geq(n, 12);
    for (int i = 0; i < n; ++i) cr_assert(t[i].can_write, "%s", t[i].extension);

    const char *paths[] = {"tests/data/formats/gap.svg", "tests/data/formats/bird.cp"};
    for (int k = 0; k < 2; ++k) {
        ori_import_stats sf, st;
        const char *path = test_repo_path(paths[k]);
        ori_pattern *pf = import_ok(path, &sf), *pt = NULL;
        char *text;
        size_t size;
        ori_error err;
        cr_assert_eq(ori_file_read_all(path, ORI_IMPORT_MAX_BYTES, &text, &size, &err), ORI_OK);
        cr_assert_eq(ori_import_text(text, size, ori_format_from_path(paths[k]), NULL, &pt, &st, &err), ORI_OK, "%s",
                     ori_error_format(&err, msg, sizeof msg));
        ori_buffer_free(text);
        cr_assert_eq(ori_pattern_vertex_count(pt), ori_pattern_vertex_count(pf));
        cr_assert_eq(ori_pattern_edge_count(pt), ori_pattern_edge_count(pf));
        for (int v = 0; v < ori_pattern_vertex_count(pf); ++v) {
            ori_v3 a = ori_pattern_vertex(pf, v), b = ori_pattern_vertex(pt, v);
            cr_assert(a.x == b.x && a.y == b.y, "%s vertex %d", paths[k], v); // exact: the same computation
        }
        cr_assert_eq(st.gaps_closed, sf.gaps_closed);
        cr_assert_eq(st.segments, sf.segments);
        cr_assert(st.stroke_width == sf.stroke_width);
        ori_pattern_destroy(pf);
        ori_pattern_destroy(pt);
    }
    ori_pattern *p = NULL;
    ori_error err;
    cr_assert_eq(ori_import_text("{}", 2, ORI_FORMAT_FOLD, NULL, &p, NULL, &err), ORI_ERR_UNSUPPORTED);
    cr_assert_null(p);
    cr_assert_eq(ori_import_text("", 0, ORI_FORMAT_CP, NULL, &p, NULL, &err), ORI_ERR_PARSE);
    cr_assert_null(p);
}

// The end of the segment from x along the direction angle a (radians) on the border of [0, 10]².
static void ray_to_border(double x, double y, double a, double *bx, double *by)
{
    double dx = cos(a), dy = sin(a), t = INFINITY;
    if (dx > 0) t = fmin(t, (10.0 - x) / dx);
    if (dx < 0) t = fmin(t, -x / dx);
    if (dy > 0) t = fmin(t, (10.0 - y) / dy);
    if (dy < 0) t = fmin(t, -y / dy);
    *bx = x + t * dx;
    *by = y + t * dy;
}

// Lines meeting a hair beside a vertex (Origami Simulator's crane): a crease changing from M to
// V at P on the diagonal of [0, 10]², and two mountains drawn to X, a hair along the diagonal
// from P (closer than the drawn line width, 0.05, farther than the weld): planarised, X splits
// the diagonal and leaves a sliver crease P–X between a degree-2 vertex (M on one side, V on the
// other, which no sheet folds) and X (M, M, V, V: Maekawa fails). Their ends touch on the page:
// the import makes them one vertex, with the degree 4 and the flat-foldability the drawing
// means (Kawasaki exact: X lies on the diagonal, the mountains leave it at α and 450° − α; M, M, M,
// V with the two smaller equal sectors beside the valley). A
// property over random α, distances and sides; a mountain a hair beside a vertex wider than the
// line is kept.
Test(formats, creases_meeting_a_hair_beside_a_vertex_meet_at_it)
{
    char *dir = test_tmpdir();
    char path[600];
    snprintf(path, sizeof path, "%s/hair.svg", dir);
    unsigned seed = 20261204u;
    for (int trial = 0; trial < 40; ++trial) {
        seed = seed * 1103515245u + 12345u;
        // below 135°: the two equal smaller sectors flank the valley (big-little-big holds)
        double alpha = ori_deg_to_rad(60.0 + 70.0 * ((seed >> 8) & 0xffff) / 65535.0);
        seed = seed * 1103515245u + 12345u;
        double d = 0.002 + 0.02 * ((seed >> 8) & 0xffff) / 65535.0; // weld 7e-4 < d < 0.05
        bool on_valley = (seed >> 4) & 1, wide = trial == 39;
        if (wide) d = 0.2; // farther than the line is wide: a real short crease, kept
        double px = 5.0, py = 5.0, s = on_valley ? 1.0 : -1.0;
        double xx = px + s * d / sqrt(2.0), xy = py + s * d / sqrt(2.0);
        double ax, ay, bx, by;
        ray_to_border(xx, xy, alpha, &ax, &ay);
        ray_to_border(xx, xy, ori_deg_to_rad(450.0) - alpha, &bx, &by);
        FILE *f = fopen(path, "w");
        cr_assert(f);
        // (SVG y down: written with y flipped; the diagonal from (0, 0) is M to P, V beyond)
        fprintf(f, "<svg xmlns='http://www.w3.org/2000/svg'><g stroke-width='0.05'>\n"
                   "<rect x='0' y='0' width='10' height='10' stroke='#000'/>\n"
                   "<line x1='0' y1='10' x2='5' y2='5' stroke='#f00'/><line x1='5' y1='5' x2='10' y2='0' stroke='#00f'/>\n"
                   "<line x1='%.17g' y1='%.17g' x2='%.17g' y2='%.17g' stroke='#f00'/>\n"
                   "<line x1='%.17g' y1='%.17g' x2='%.17g' y2='%.17g' stroke='#f00'/>\n"
                   "</g></svg>\n",
                ax, 10.0 - ay, xx, 10.0 - xy, bx, 10.0 - by, xx, 10.0 - xy);
        fclose(f);
        ori_import_stats stats;
        ori_pattern *p = import_ok(path, &stats);
        int interior = 0, at = -1;
        for (int v = 0; v < ori_pattern_vertex_count(p); ++v)
            if (ori_pattern_vertex_is_interior(p, v)) interior++, at = v;
        if (wide) {
            cr_assert_eq(stats.short_creases_merged, 0, "a crease of 0.2 is drawn, not a hair");
            cr_assert_eq(interior, 2, "P and X stay apart");
            ori_pattern_destroy(p);
            continue;
        }
        cr_assert_eq(stats.short_creases_merged, 1, "trial %d (d %g, alpha %g): %d merged", trial, d, alpha, stats.short_creases_merged);
        cr_assert_eq(interior, 1, "trial %d: one vertex where the lines meet, not %d", trial, interior);
        ori_v3 x = ori_pattern_vertex(p, at);
        cr_assert_float_eq(x.x, xx, 1e-9, "trial %d: at X, where most lines end", trial);
        cr_assert_float_eq(x.y, xy - 10.0, 1e-9); // (FOLD y = -SVG y)
        char why[256] = "";
        cr_assert(test_vertex_flat_foldable(p, at, why, sizeof why), "trial %d: %s", trial, why);
        for (int e = 0; e < ori_pattern_edge_count(p); ++e)
            cr_assert_gt(edge_length(p, e), 0.05, "trial %d: no crease shorter than the line width", trial);
        ori_pattern_destroy(p);
    }
    test_tmpdir_remove(dir);
}
