// Fabrication files (include/orikin/fab.h): GDSII reals and record bytes of a tiny library, the
// panels shrunk by the hinge gap, hinge strips and wires of the gold open corner, crease dashes,
// DXF and laser SVG contents, the CLI's errors. The independent readers (gdspy, ezdxf) are in
// tests/fab_readback.py.
#include <orikin/fab.h>
#include <stdio.h>
#include <string.h>

#include "support.h"

TestSuite(fab, .init = test_leak_setup, .fini = test_leak_check);

static char msg[512];

static void real8_is(double x, const char *hex)
{
    unsigned char b[8];
    cr_assert(ori_gds_real8(x, b), "%g", x);
    char got[17];
    for (int i = 0; i < 8; ++i) snprintf(got + 2 * i, 3, "%02x", b[i]);
    cr_assert_str_eq(got, hex, "%.17g", x);
}

// Expected bytes: the exact value of the double as 16^(e−64) · m / 2^56 (computed with exact
// rationals); 1e-9 is the database unit of every nm-grid GDSII file (39 44 B8 2F A0 9B 5A 54).
Test(fab, real8_exact)
{
    real8_is(1.0, "4110000000000000");
    real8_is(1e-9, "3944b82fa09b5a54");
    real8_is(1e-3, "3e4189374bc6a7f0");
    real8_is(1e-6, "3c10c6f7a0b5ed8d");
    real8_is(-2.5, "c128000000000000");
    real8_is(0.5, "4080000000000000");
    real8_is(100.0, "4264000000000000");
    real8_is(1.0 / 16.0, "4010000000000000");
    real8_is(0.0, "0000000000000000");
    // decode and compare: every double in range round-trips exactly
    double xs[] = {3.141592653589793, 1e-70, 7.0e70, -123456.789e-20};
    for (int k = 0; k < 4; ++k) {
        unsigned char b[8];
        cr_assert(ori_gds_real8(xs[k], b));
        unsigned long long m = 0;
        for (int i = 1; i < 8; ++i) m = m << 8 | b[i];
        double v = ldexp((double)m, 4 * ((b[0] & 0x7f) - 64) - 56) * ((b[0] & 0x80) ? -1.0 : 1.0);
        cr_assert_eq(v, xs[k], "%.17g decoded as %.17g", xs[k], v);
        cr_assert(m >> 52 != 0, "normalised: the first hex digit of the mantissa is nonzero");
    }
    unsigned char b[8];
    cr_assert_not(ori_gds_real8(1e80, b), "beyond 16^63");
    cr_assert(ori_gds_real8(1e-90, b));
    cr_assert_eq(b[0], 0, "underflow is 0");
}

static const char square_text[] = "{\"file_spec\":1.2,\"frame_unit\":\"um\",\"vertices_coords\":[[0,0],[2,0],[2,2],[0,2]],"
                                  "\"edges_vertices\":[[0,1],[1,2],[2,3],[3,0]],\"edges_assignment\":[\"B\",\"B\",\"B\",\"B\"],"
                                  "\"faces_vertices\":[[0,1,2,3]]}";

static void be16(unsigned char *p, unsigned v) { p[0] = (unsigned char)(v >> 8), p[1] = (unsigned char)v; }
static void be32(unsigned char *p, int v)
{
    unsigned u = (unsigned)v;
    p[0] = (unsigned char)(u >> 24), p[1] = (unsigned char)(u >> 16), p[2] = (unsigned char)(u >> 8), p[3] = (unsigned char)u;
}

// The layout of the 2 × 2 µm square p (µm units) with no marks and no label.
static ori_fab_layout *tiny_layout(const ori_pattern *p)
{
    ori_fab_def d = ori_default_fab_def();
    d.pattern = p;
    d.meters_per_unit = 1e-6;
    d.mark_size_m = 0.0;
    d.label[0] = '\0';
    ori_fab_layout *l = NULL;
    ori_error err;
    cr_assert_eq(ori_fab_layout_create(&d, &l, &err), ORI_OK, "%s", ori_error_format(&err, msg, sizeof msg));
    return l;
}

// A 2 × 2 µm square with no marks and no label: the whole stream, byte for byte.
Test(fab, gds_records_of_a_tiny_library)
{
    ori_pattern *p = test_pattern_of_text(square_text);
    ori_fab_layout *l = tiny_layout(p);
    ori_error err;
    cr_assert_eq(ori_fab_shape_count(l), 1);
    size_t n = 0;
    unsigned char *g = ori_gds_write(l, NULL, &n, &err);
    cr_assert(g);
    unsigned char want[256];
    int k = 0;
    const unsigned char head[] = {0x00, 0x06, 0x00, 0x02, 0x02, 0x58, 0x00, 0x1c, 0x01, 0x02};
    memcpy(want + k, head, sizeof head), k += (int)sizeof head;
    for (int t = 0; t < 2; ++t) {
        unsigned date[6] = {1970, 1, 1, 0, 0, 0};
        for (int i = 0; i < 6; ++i) be16(want + k, date[i]), k += 2;
    }
    const unsigned char lib[] = {0x00, 0x0a, 0x02, 0x06, 'O', 'R', 'I', 'K', 'I', 'N', 0x00, 0x14, 0x03, 0x05,
                                 0x3e, 0x41, 0x89, 0x37, 0x4b, 0xc6, 0xa7, 0xf0,  // 1e-3 user units per dbu
                                 0x39, 0x44, 0xb8, 0x2f, 0xa0, 0x9b, 0x5a, 0x54,  // 1e-9 m per dbu
                                 0x00, 0x1c, 0x05, 0x02};
    memcpy(want + k, lib, sizeof lib), k += (int)sizeof lib;
    for (int t = 0; t < 2; ++t) {
        unsigned date[6] = {1970, 1, 1, 0, 0, 0};
        for (int i = 0; i < 6; ++i) be16(want + k, date[i]), k += 2;
    }
    const unsigned char cell[] = {0x00, 0x0a, 0x06, 0x06, 'D', 'E', 'V', 'I', 'C', 'E', 0x00, 0x04, 0x08, 0x00,
                                  0x00, 0x06, 0x0d, 0x02, 0x00, 0x01, 0x00, 0x06, 0x0e, 0x02, 0x00, 0x00,
                                  0x00, 0x2c, 0x10, 0x03};
    memcpy(want + k, cell, sizeof cell), k += (int)sizeof cell;
    int xy[] = {0, 0, 2000, 0, 2000, 2000, 0, 2000, 0, 0}; // nm, closed
    for (int i = 0; i < 10; ++i) be32(want + k, xy[i]), k += 4;
    const unsigned char tail[] = {0x00, 0x04, 0x11, 0x00, 0x00, 0x04, 0x07, 0x00, 0x00, 0x04, 0x04, 0x00};
    memcpy(want + k, tail, sizeof tail), k += (int)sizeof tail;
    cr_assert_eq(n, (size_t)k, "%zu bytes, want %d", n, k);
    for (int i = 0; i < k; ++i) cr_assert_eq(g[i], want[i], "byte %d: %02x, want %02x", i, g[i], want[i]);
    // a 1-µm database unit: the coordinates are 0 and 2
    ori_gds_def gd = ori_default_gds_def();
    gd.database_unit_m = 1e-6;
    unsigned char *g2 = ori_gds_write(l, &gd, &n, &err);
    cr_assert_eq(n, (size_t)k);
    cr_assert_eq(g2[k - 52 + 11], 2, "x of the second point is 2 database units");
    ori_buffer_free(g2);
    ori_buffer_free(g);
    ori_fab_layout_destroy(l);
    ori_pattern_destroy(p);
}

// What a GDSII stream cannot hold is refused, not written wrong (fuzz_fab's finds): a name past
// a record's 16-bit length, a database unit that the excess-64 real would write as 0.
Test(fab, gds_refuses_what_a_stream_cannot_hold)
{
    ori_pattern *p = test_pattern_of_text(square_text);
    ori_fab_layout *l = tiny_layout(p);
    ori_error err;
    static char name[70001];
    memset(name, 'N', sizeof name - 1);
    ori_gds_def gd = ori_default_gds_def();
    gd.cell_name = name; // 70,000 bytes: the record length would wrap to 4,468
    size_t n = 1;
    cr_assert_null(ori_gds_write(l, &gd, &n, &err));
    cr_assert_eq(err.status, ORI_ERR_LIMIT);
    cr_assert_str_eq(err.field, "cell_name");
    cr_assert_eq(n, 0, "no size on failure");
    name[65530] = '\0'; // the longest that fits: 65,530 bytes + the 4-byte header
    unsigned char *g = ori_gds_write(l, &gd, &n, &err);
    cr_assert(g, "%s", err.message);
    ori_buffer_free(g);
    gd = ori_default_gds_def();
    gd.database_unit_m = 1e-80; // below 16^-65 m: written as 0 before
    cr_assert_null(ori_gds_write(l, &gd, &n, &err));
    cr_assert_eq(err.status, ORI_ERR_RANGE);
    cr_assert_str_eq(err.field, "units");
    ori_fab_layout_destroy(l);
    // metres per unit so small that the default pads are beyond the range of doubles in pattern
    // units (1e-4 m / 5e-324 m): refused with the field, not laid out at infinity
    ori_fab_def d = ori_default_fab_def();
    d.pattern = p;
    d.label[0] = '\0';
    d.meters_per_unit = 5e-324;
    d.hinge_overlap_m = 0.0;
    d.default_hinge_span_m = 0.0;
    d.mark_size_m = 100e-6;
    cr_assert_eq(ori_fab_layout_create(&d, &l, &err), ORI_ERR_RANGE);
    cr_assert_str_eq(err.field, "pad_size", "the first length out of range");
    cr_assert_null(l);
    // each length in range, their sum not: a mark margin near the largest double
    d.meters_per_unit = 1.0;
    d.mark_margin_m = 1.7e308;
    d.mark_size_m = 1e308;
    cr_assert_eq(ori_fab_layout_create(&d, &l, &err), ORI_ERR_RANGE, "%s", err.message);
    cr_assert_null(l);
    ori_pattern_destroy(p);
}

static double poly_area(ori_fab_shape s)
{
    double a = 0.0;
    for (int i = 0; i < s.point_count; ++i) {
        ori_v2 u = s.points[i], v = s.points[(i + 1) % s.point_count];
        a += u.x * v.y - u.y * v.x;
    }
    return 0.5 * a;
}

// Two 100 × 100 µm panels across a valley: each loses gap/2 × 100 µm; the strip is centred on the
// crease, its width along it and gap + 2 × overlap across.
Test(fab, panels_shrink_by_half_the_gap)
{
    static const char text[] = "{\"file_spec\":1.2,\"frame_unit\":\"um\",\"vertices_coords\":[[0,0],[100,0],[200,0],[200,100],"
                               "[100,100],[0,100]],\"edges_vertices\":[[0,1],[1,2],[2,3],[3,4],[4,5],[5,0],[1,4]],"
                               "\"edges_assignment\":[\"B\",\"B\",\"B\",\"B\",\"B\",\"B\",\"V\"],"
                               "\"faces_vertices\":[[0,1,4,5],[1,2,3,4]]}";
    ori_pattern *p = test_pattern_of_text(text);
    ori_fab_def d = ori_default_fab_def();
    d.pattern = p;
    d.meters_per_unit = 1e-6;
    d.hinge_gap_m = 10e-6;
    d.hinge_overlap_m = 5e-6;
    d.hinge_width_m = 40e-6;
    ori_fab_layout *l = NULL;
    ori_error err;
    cr_assert_eq(ori_fab_layout_create(&d, &l, &err), ORI_OK);
    int panels = 0, hinges = 0, marks = 0, labels = 0;
    for (int i = 0; i < ori_fab_shape_count(l); ++i) {
        ori_fab_shape s = ori_fab_shape_at(l, i);
        if (s.layer == ORI_FAB_PANEL) {
            ++panels;
            cr_assert_float_eq(poly_area(s), 95.0 * 100.0, 1e-9, "panel %d: area %g", s.element, poly_area(s));
            for (int k = 0; k < s.point_count; ++k)
                cr_assert(s.element == 0 ? s.points[k].x <= 95.0 + 1e-12 : s.points[k].x >= 105.0 - 1e-12);
        } else if (s.layer == ORI_FAB_HINGE) {
            ++hinges;
            cr_assert_eq(s.element, 6);
            cr_assert_float_eq(poly_area(s), 40.0 * 20.0, 1e-9);
            double y0 = 1e9, y1 = -1e9, x0 = 1e9, x1 = -1e9;
            for (int k = 0; k < 4; ++k)
                y0 = fmin(y0, s.points[k].y), y1 = fmax(y1, s.points[k].y), x0 = fmin(x0, s.points[k].x),
                x1 = fmax(x1, s.points[k].x);
            cr_assert_float_eq(y0, 30.0, 1e-12);
            cr_assert_float_eq(y1, 70.0, 1e-12);
            cr_assert_float_eq(x0, 90.0, 1e-12);
            cr_assert_float_eq(x1, 110.0, 1e-12);
        } else if (s.layer == ORI_FAB_MARK) {
            ++marks;
            cr_assert_float_eq(poly_area(s), 100.0 * 10.0, 1e-9);
        } else if (s.layer == ORI_FAB_LABEL) {
            ++labels;
            cr_assert_str_eq(s.text, "orikin");
        }
    }
    cr_assert_eq(panels, 2);
    cr_assert_eq(hinges, 1);
    cr_assert_eq(marks, 8);
    cr_assert_eq(labels, 1);
    ori_fab_layout_destroy(l);
    // a gap wider than a panel leaves no panel
    d.hinge_gap_m = 250e-6;
    cr_assert_eq(ori_fab_layout_create(&d, &l, &err), ORI_ERR_DEGENERATE);
    cr_assert_null(l);
    cr_assert_str_eq(err.field, "faces_vertices");
    d.hinge_gap_m = 10e-6;
    d.pad_size_m = -1.0;
    cr_assert_eq(ori_fab_layout_create(&d, &l, &err), ORI_ERR_RANGE);
    cr_assert_str_eq(err.field, "pad_size");
    ori_pattern_destroy(p);
}

// The gold open corner: hinge strips of the design's 8 µm width and 12 µm span gaps; wires on
// the two wired creases with the design's lever (the farthest point of the loop from its crease).
Test(fab, open_corner_gold_hinges_and_wires)
{
    ori_fold *doc = NULL;
    ori_error err;
    cr_assert_eq(ori_fold_load_file(test_repo_path("examples/patterns/open-corner-gold.fold"), &doc, &err), ORI_OK);
    ori_pattern *p = NULL;
    cr_assert_eq(ori_fold_get_pattern(doc, 0, NULL, &p, &err), ORI_OK);
    ori_design_def dd = ori_default_design_def();
    dd.doc = doc;
    dd.pattern = p;
    ori_design *design = NULL;
    cr_assert_eq(ori_design_create(&dd, &design, &err), ORI_OK);
    ori_fab_def d = ori_default_fab_def();
    d.pattern = p;
    d.design = design;
    d.fixed_face = 4;
    ori_fab_layout *l = NULL;
    cr_assert_eq(ori_fab_layout_create(&d, &l, &err), ORI_OK, "%s", ori_error_format(&err, msg, sizeof msg));
    int wires = 0, hinges = 0, pads = 0;
    for (int i = 0; i < ori_fab_shape_count(l); ++i) {
        ori_fab_shape s = ori_fab_shape_at(l, i);
        if (s.layer == ORI_FAB_HINGE) {
            ++hinges;
            cr_assert_float_eq(poly_area(s), 8.0 * (12.0 + 2.0 * 10.0), 1e-9);
        } else if (s.layer == ORI_FAB_PAD) {
            ++pads;
            cr_assert_float_eq(poly_area(s), 100.0 * 100.0, 1e-6);
        } else if (s.layer == ORI_FAB_WIRE) {
            ++wires;
            ori_hinge h;
            cr_assert(ori_design_hinge(design, s.element, &h) && h.has_wire);
            cr_assert_float_eq(s.width, 8.0, 1e-12, "the conductor is as wide as the hinge (the design's default)");
            ori_edge ed = ori_pattern_edge(p, s.element);
            ori_v3 a = ori_pattern_vertex(p, ed.v[0]), b = ori_pattern_vertex(p, ed.v[1]);
            double len = hypot(b.x - a.x, b.y - a.y), far = 0.0;
            for (int k = 0; k < s.point_count; ++k) {
                double dist = fabs((b.x - a.x) * (s.points[k].y - a.y) - (b.y - a.y) * (s.points[k].x - a.x)) / len;
                far = fmax(far, dist);
            }
            cr_assert_float_eq(far, 1e6 * h.wire.lever_m, 1e-9, "crease %d: lever %g", s.element, far);
            cr_assert_eq(s.point_count, 4 * h.wire.turns, "a spiral of %d turns", h.wire.turns);
        }
    }
    cr_assert_eq(hinges, 5, "the five creases carry hinge data");
    cr_assert_eq(wires, 2);
    cr_assert_eq(pads, 4);
    char *map = ori_fab_layer_map(l);
    cr_assert(strstr(map, "1/0 PANEL") && strstr(map, "2/0 HINGE") && strstr(map, "3/0 WIRE") && strstr(map, "6/0 LABEL"));
    ori_buffer_free(map);
    ori_fab_layout_destroy(l);
    ori_design_destroy(design);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
}

Test(fab, crease_dashes)
{
    ori_cut_def d = ori_default_cut_def(); // dash 3, gap 1.5, vertex gap 1
    double s[64], e[64];
    // stretch 98: n = floor(99.5 / 4.5) = 22 dashes, 66 mm of dash, centred
    int n = ori_crease_dashes(100.0, &d, s, e, 64);
    cr_assert_eq(n, 22);
    double used = 22 * 3.0 + 21 * 1.5;
    cr_assert_float_eq(s[0], 1.0 + 0.5 * (98.0 - used), 1e-12);
    cr_assert_float_eq(e[n - 1], 99.0 - 0.5 * (98.0 - used), 1e-12);
    for (int i = 0; i < n; ++i) {
        cr_assert_float_eq(e[i] - s[i], 3.0, 1e-12);
        if (i) cr_assert_float_eq(s[i] - e[i - 1], 1.5, 1e-12);
    }
    cr_assert_eq(ori_crease_dashes(2.5, &d, s, e, 64), 1, "shorter than a dash: one dash over the stretch");
    cr_assert_float_eq(s[0], 1.0, 1e-15);
    cr_assert_float_eq(e[0], 1.5, 1e-15);
    cr_assert_eq(ori_crease_dashes(2.0, &d, s, e, 64), 0, "no room between the vertex gaps");
    cr_assert_eq(ori_crease_dashes(100.0, &d, s, e, 4), 22, "the count even when cap is smaller");
    d.perforate = true; // 0.5 slits every 1.5
    n = ori_crease_dashes(100.0, &d, s, e, 64);
    cr_assert_eq(n, (int)floor((98.0 + 1.0) / 1.5));
    cr_assert_float_eq(s[1] - s[0], 1.5, 1e-12);
    cr_assert_float_eq(e[0] - s[0], 0.5, 1e-12);
}

// A dash tiny against its crease: ⌊(stretch + gap) / (dash + gap)⌋ was converted to int beyond
// its range (undefined behaviour; fuzz_fab's find, orikin fab -o x.svg --dash 1e-300 --dash-gap 0).
Test(fab, crease_dashes_refuse_out_of_range)
{
    ori_cut_def d = ori_default_cut_def();
    d.dash_mm = 1e-300;
    d.gap_mm = 0.0;
    cr_assert_eq(ori_crease_dashes(10.0, &d, NULL, NULL, 0), -1, "8e300 dashes: refused");
    d.dash_mm = 1.0 / 1024.0; // the 8 mm stretch: 8,192 dashes, exactly (binary fractions)
    cr_assert_eq(ori_crease_dashes(10.0, &d, NULL, NULL, 0), 8192);
    d.dash_mm = 0x1.0p-20; // 8,388,608: more than ORI_CUT_MAX_DASHES
    cr_assert_eq(ori_crease_dashes(10.0, &d, NULL, NULL, 0), -1);
    d = ori_default_cut_def();
    d.gap_mm = NAN;
    cr_assert_eq(ori_crease_dashes(10.0, &d, NULL, NULL, 0), -1, "a NaN gap");
    d = ori_default_cut_def();
    d.perforate = true;
    d.perforation_pitch_mm = d.perforation_mm; // no gap between slits
    cr_assert_eq(ori_crease_dashes(10.0, &d, NULL, NULL, 0), -1, "pitch not longer than the slit");
    d.gap_mm = NAN; // the dash style's fields do not matter when perforating
    d.perforation_pitch_mm = 1.5;
    cr_assert_eq(ori_crease_dashes(100.0, &d, NULL, NULL, 0), (int)floor(99.0 / 1.5));
    // the writers say why
    ori_pattern *p = test_load_pattern(test_repo_path("examples/patterns/open-corner.fold"), 0);
    ori_error err;
    d = ori_default_cut_def();
    d.mm_per_unit = 50.0; // a 100 mm sheet, creases of 50 and 70.7 mm
    d.dash_mm = 1e-300;
    d.gap_mm = 0.0;
    cr_assert_null(ori_cut_svg_write(p, &d, &err));
    cr_assert_eq(err.status, ORI_ERR_LIMIT);
    cr_assert(err.element >= 0 && ori_assignment_is_fold(ori_pattern_edge(p, err.element).assignment), "the crease: %d",
              err.element);
    char *dxf = ori_dxf_write(p, &d, &err); // whole lines: the dashes do not matter
    cr_assert(dxf, "%s", err.message);
    ori_buffer_free(dxf);
    d = ori_default_cut_def();
    d.stroke_mm = INFINITY;
    cr_assert_null(ori_cut_svg_write(p, &d, &err));
    cr_assert_str_eq(err.field, "stroke_mm");
    d = ori_default_cut_def();
    d.mm_per_unit = INFINITY;
    cr_assert_null(ori_dxf_write(p, &d, &err));
    cr_assert_str_eq(err.field, "mm_per_unit");
    d.mm_per_unit = 1e308; // finite, but the 2-unit sheet is beyond the range of coordinates in mm
    cr_assert_null(ori_cut_svg_write(p, &d, &err));
    cr_assert_eq(err.status, ORI_ERR_RANGE);
    ori_pattern_destroy(p);
    char *out = NULL;
    remove("/tmp/orikin-fab-tiny-dash.svg");
    cr_assert_eq(test_run_cli("fab examples/patterns/open-corner.fold -o /tmp/orikin-fab-tiny-dash.svg --scale 50 --dash 1e-300 "
                              "--dash-gap 0", &out), 3);
    cr_assert(strstr(out, "dashes"), "%s", out);
    free(out);
    FILE *f = fopen("/tmp/orikin-fab-tiny-dash.svg", "rb");
    cr_assert_null(f, "nothing written");
}

static int count_of(const char *text, const char *needle)
{
    int n = 0;
    for (const char *q = text; (q = strstr(q, needle)); q += strlen(needle)) ++n;
    return n;
}

Test(fab, dxf_and_svg_layers)
{
    ori_pattern *p = test_load_pattern(test_repo_path("examples/patterns/open-corner.fold"), 0);
    ori_cut_def d = ori_default_cut_def();
    d.mm_per_unit = 50.0; // a 100 mm sheet
    ori_error err;
    char *dxf = ori_dxf_write(p, &d, &err);
    cr_assert(dxf, "%s", err.message);
    cr_assert(strstr(dxf, "$ACADVER\n1\nAC1009\n"));
    cr_assert_eq(count_of(dxf, "0\nLINE\n8\nCUT\n"), ori_pattern_count_assignment(p, ORI_ASSIGN_BOUNDARY));
    cr_assert_eq(count_of(dxf, "0\nLINE\n8\nMOUNTAIN\n"), ori_pattern_count_assignment(p, ORI_ASSIGN_MOUNTAIN));
    cr_assert_eq(count_of(dxf, "0\nLINE\n8\nVALLEY\n"), ori_pattern_count_assignment(p, ORI_ASSIGN_VALLEY));
    cr_assert(strstr(dxf, "0\nEOF\n"));
    char *svg = ori_cut_svg_write(p, &d, &err);
    cr_assert(svg, "%s", err.message);
    cr_assert(strstr(svg, "width=\"100.4mm\""), "100 mm and two stroke widths of margin");
    cr_assert(strstr(svg, "<g id=\"mountain\"") && strstr(svg, "<g id=\"valley\"") && strstr(svg, "<g id=\"cut\""));
    // every crease of the open corner (50 or 70.7 mm) as its dashes
    int want = ori_pattern_count_assignment(p, ORI_ASSIGN_BOUNDARY);
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        if (!ori_assignment_is_fold(ed.assignment)) continue;
        ori_v3 a = ori_pattern_vertex(p, ed.v[0]), b = ori_pattern_vertex(p, ed.v[1]);
        want += ori_crease_dashes(50.0 * hypot(b.x - a.x, b.y - a.y), &d, NULL, NULL, 0);
    }
    cr_assert_eq(count_of(svg, "<line "), want);
    ori_buffer_free(svg);
    ori_buffer_free(dxf);
    ori_pattern_destroy(p);
}

Test(fab, cli_errors)
{
    char *out = NULL;
    cr_assert_eq(test_run_cli("fab examples/patterns/open-corner.fold -o /tmp/x.png", &out), 2);
    cr_assert(strstr(out, ".gds, .dxf or .svg"), "%s", out);
    free(out);
    cr_assert_eq(test_run_cli("fab examples/patterns/open-corner.fold -o /tmp/orikin-fab-unitless.gds", &out), 3);
    cr_assert(strstr(out, "frame_unit") && strstr(out, "--unit"), "%s", out);
    free(out);
    cr_assert_eq(test_run_cli("fab examples/patterns/open-corner.fold -o /tmp/x.gds --dash 2", &out), 2);
    cr_assert(strstr(out, "--dash"), "%s", out);
    free(out);
    cr_assert_eq(test_run_cli("fab examples/patterns/open-corner.fold -o /tmp/x.svg --dash -2", &out), 2);
    free(out);
    FILE *f = fopen("/tmp/orikin-fab-unitless.gds", "rb");
    cr_assert_null(f, "nothing written on an input error");
}

// --- fabrication tolerance ---------------------------------------------------------------

// The thesis' first fold of the open corner (2 × 2 sheet): diagonal to 90°, the down crease
// locked, the lower triangle fixed.
typedef struct corner_fold {
    test_open_corner oc;
    int locks[1];
    ori_motion_def def;
} corner_fold;

static void corner_fold_init(corner_fold *c, double to_deg)
{
    c->oc = test_open_corner_load();
    c->locks[0] = c->oc.down;
    c->def = ori_default_motion_def();
    c->def.fixed_face = c->oc.t2;
    c->def.driven_edge = c->oc.diag;
    c->def.to_rad = to_deg * ORI_PI / 180.0;
    c->def.step_rad = 10.0 * ORI_PI / 180.0;
    c->def.locked_edges = c->locks;
    c->def.locked_count = 1;
}

static ori_tolerance *run_tolerance(corner_fold *c, double sigma, int samples, uint64_t seed, int threads)
{
    ori_tolerance_def td = ori_default_tolerance_def();
    td.pattern = c->oc.p;
    td.motion = &c->def;
    td.vertex_sigma = sigma;
    td.samples = samples;
    td.seed = seed;
    td.threads = threads;
    ori_tolerance *t = NULL;
    ori_error err;
    cr_assert_eq(ori_tolerance_run(&td, &t, &err), ORI_OK, "%s", ori_error_format(&err, msg, sizeof msg));
    return t;
}

Test(fab, tolerance_zero_sigma_is_the_nominal_fold)
{
    corner_fold c;
    corner_fold_init(&c, 90.0);
    ori_tolerance *t = run_tolerance(&c, 0.0, 5, 7, 1);
    cr_assert_eq(ori_tolerance_failed_count(t), 0);
    for (int i = 0; i < 5; ++i) {
        ori_tolerance_sample s = ori_tolerance_sample_at(t, i);
        cr_assert(s.folded);
        cr_assert_eq(s.position_error, 0.0);
        cr_assert_eq(s.end_effector_error, 0.0);
        cr_assert_eq(s.normal_error_rad, 0.0);
        cr_assert_eq(s.angle_error_rad, 0.0);
    }
    ori_tolerance_destroy(t);
    test_open_corner_free(&c.oc);
}

// The same seed gives the same samples bit for bit, whatever the threads; another seed others.
Test(fab, tolerance_reproducible)
{
    corner_fold c;
    corner_fold_init(&c, 90.0);
    ori_tolerance *a = run_tolerance(&c, 1e-3, 40, 42, 1), *b = run_tolerance(&c, 1e-3, 40, 42, 2),
                  *d = run_tolerance(&c, 1e-3, 40, 43, 1);
    int differ = 0;
    for (int i = 0; i < 40; ++i) {
        ori_tolerance_sample x = ori_tolerance_sample_at(a, i), y = ori_tolerance_sample_at(b, i),
                             z = ori_tolerance_sample_at(d, i);
        cr_assert(x.folded);
        cr_assert(memcmp(&x, &y, sizeof x) == 0, "sample %d differs between 1 and 2 threads", i);
        differ += x.position_error != z.position_error;
        cr_assert_gt(x.position_error, 0.0);
    }
    cr_assert_gt(differ, 35, "another seed, other samples");
    // the statistics are those of the samples
    ori_tolerance_stats s = ori_tolerance_stats_of(a, ORI_TOLERANCE_METRIC_POSITION);
    double sum = 0.0, mx = 0.0;
    for (int i = 0; i < 40; ++i) sum += ori_tolerance_sample_at(a, i).position_error,
                                 mx = fmax(mx, ori_tolerance_sample_at(a, i).position_error);
    cr_assert_eq(s.count, 40);
    cr_assert_float_eq(s.mean, sum / 40, 1e-15);
    cr_assert_eq(s.max, mx);
    cr_assert(s.min <= s.p50 && s.p50 <= s.p90 && s.p90 <= s.p95 && s.p95 <= s.p99 && s.p99 <= s.max);
    ori_tolerance_destroy(a);
    ori_tolerance_destroy(b);
    ori_tolerance_destroy(d);
    test_open_corner_free(&c.oc);
}

// Small perturbations: the same draws scaled by 2 (same seed) double every sample's error to
// first order: the error is linear in σ (relative deviation O(σ)).
Test(fab, tolerance_linear_in_small_sigma)
{
    corner_fold c;
    corner_fold_init(&c, 90.0);
    ori_tolerance *a = run_tolerance(&c, 1e-6, 20, 5, 1), *b = run_tolerance(&c, 2e-6, 20, 5, 1);
    for (int i = 0; i < 20; ++i) {
        ori_tolerance_sample x = ori_tolerance_sample_at(a, i), y = ori_tolerance_sample_at(b, i);
        cr_assert(x.folded && y.folded);
        cr_assert_float_eq(y.position_error / x.position_error, 2.0, 1e-3, "sample %d: %.9g", i,
                           y.position_error / x.position_error);
        cr_assert_float_eq(y.normal_error_rad / x.normal_error_rad, 2.0, 1e-3);
        cr_assert_float_eq(y.end_effector_error / x.end_effector_error, 2.0, 1e-3);
        // a vertex perturbed by δ moves by at least about δ: the error is of the order of σ
        cr_assert(x.position_error > 1e-8 && x.position_error < 1e-4, "%g", x.position_error);
    }
    ori_tolerance_destroy(a);
    ori_tolerance_destroy(b);
    test_open_corner_free(&c.oc);
}

Test(fab, tolerance_errors_and_cli)
{
    corner_fold c;
    corner_fold_init(&c, 90.0);
    ori_tolerance_def td = ori_default_tolerance_def();
    td.pattern = c.oc.p;
    td.motion = &c.def;
    td.vertex_sigma = -1.0;
    ori_tolerance *t = NULL;
    ori_error err;
    cr_assert_eq(ori_tolerance_run(&td, &t, &err), ORI_ERR_RANGE);
    cr_assert_str_eq(err.field, "vertex_sigma");
    td.vertex_sigma = 0.0;
    td.samples = 0;
    cr_assert_eq(ori_tolerance_run(&td, &t, &err), ORI_ERR_RANGE);
    cr_assert_null(t);
    test_open_corner_free(&c.oc);
    char *out = NULL;
    cr_assert_eq(test_run_cli("tolerance examples/patterns/open-corner.fold --drive 12 --to 90", &out), 2);
    cr_assert(strstr(out, "--vertex-sigma"), "%s", out);
    free(out);
    cr_assert_eq(test_run_cli("tolerance examples/patterns/open-corner.fold --vertex-sigma 1um --drive 12 --to 90", &out), 3);
    cr_assert(strstr(out, "unitless"), "%s", out);
    free(out);
    char *a = NULL, *b = NULL;
    const char *args = "tolerance examples/patterns/open-corner-gold.fold --vertex-sigma 1um --fix 4 --drive 12 --lock 11 "
                       "--to 90 --samples 50 --seed 9 --json";
    cr_assert_eq(test_run_cli(args, &a), 0, "%s", a);
    cr_assert_eq(test_run_cli(args, &b), 0);
    cr_assert_str_eq(a, b, "the seed reproduces the output");
    cr_assert(strstr(a, "\"samples\":50") && strstr(a, "\"failed\":0") && strstr(a, "\"vertex_sigma\":1,"), "%s", a);
    free(a);
    free(b);
}

// Hinge widths: the thesis flap (one gold hinge, 500 µm silicon panel) sized per sample. M_p ∝ w
// and the current follows M_p, so with the same seed the current's change doubles with σ_w (to first order: 2e-5 here);
// σ_w = 0 gives the nominal current; 5 % widths spread the current by 5 %.
Test(fab, tolerance_hinge_widths_and_current)
{
    ori_fold *doc = NULL;
    ori_pattern *p = NULL;
    ori_error err;
    cr_assert_eq(ori_fold_load_file(test_repo_path("examples/patterns/thesis-flap.fold"), &doc, &err), ORI_OK);
    cr_assert_eq(ori_fold_get_pattern(doc, 0, NULL, &p, &err), ORI_OK);
    ori_motion_def md = ori_default_motion_def();
    md.fixed_face = 0;
    md.driven_edge = 0;
    md.to_rad = ORI_PI;
    md.step_rad = 15.0 * ORI_PI / 180.0;
    ori_design_def dd = ori_default_design_def();
    dd.doc = doc;
    ori_tolerance_def td = ori_default_tolerance_def();
    td.pattern = p;
    td.motion = &md;
    td.design = &dd;
    td.samples = 30;
    td.seed = 3;
    ori_tolerance *t0 = NULL, *t1 = NULL, *t2 = NULL, *t2b = NULL;
    cr_assert_eq(ori_tolerance_run(&td, &t0, &err), ORI_OK, "%s", ori_error_format(&err, msg, sizeof msg));
    double nominal = ori_tolerance_nominal_current(t0);
    cr_assert(nominal > 1e-3 && nominal < 0.02, "%g A", nominal);
    for (int i = 0; i < 30; ++i) cr_assert_eq(ori_tolerance_sample_at(t0, i).current_a, nominal);
    td.width_sigma_rel = 0.01;
    cr_assert_eq(ori_tolerance_run(&td, &t1, &err), ORI_OK);
    td.width_sigma_rel = 0.02;
    cr_assert_eq(ori_tolerance_run(&td, &t2, &err), ORI_OK);
    td.threads = 2;
    cr_assert_eq(ori_tolerance_run(&td, &t2b, &err), ORI_OK);
    for (int i = 0; i < 30; ++i) {
        double c1 = ori_tolerance_sample_at(t1, i).current_a, c2 = ori_tolerance_sample_at(t2, i).current_a;
        cr_assert_float_eq((c2 - nominal) / (c1 - nominal), 2.0, 1e-3, "sample %d: %.12g %.12g %.12g", i, nominal, c1, c2);
        cr_assert_eq(c2, ori_tolerance_sample_at(t2b, i).current_a, "threads give the same sizing");
    }
    ori_tolerance_destroy(t0);
    ori_tolerance_destroy(t1);
    ori_tolerance_destroy(t2);
    ori_tolerance_destroy(t2b);
    td.threads = 1;
    td.samples = 400;
    td.width_sigma_rel = 0.05;
    cr_assert_eq(ori_tolerance_run(&td, &t0, &err), ORI_OK);
    ori_tolerance_stats s = ori_tolerance_stats_of(t0, ORI_TOLERANCE_METRIC_CURRENT);
    cr_assert_eq(s.count, 400);
    cr_assert(s.sd / s.mean > 0.044 && s.sd / s.mean < 0.056, "relative spread %g for 5 %% widths", s.sd / s.mean);
    cr_assert_float_eq(s.mean / nominal, 1.0, 0.01);
    ori_tolerance_destroy(t0);
    td.width_sigma_rel = -1.0;
    cr_assert_eq(ori_tolerance_run(&td, &t0, &err), ORI_ERR_RANGE);
    cr_assert_str_eq(err.field, "width_sigma_rel");
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
}
