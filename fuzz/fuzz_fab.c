// libFuzzer target for the fabrication writers (include/orikin/fab.h): the lithography layout
// (ori_fab_layout_create), its GDSII stream (ori_gds_write) and layer map, the cutting files
// (ori_dxf_write, ori_cut_svg_write) and the dash rule (ori_crease_dashes), on fuzzed small
// patterns with fuzzed parameters, hostile ones included (0, negative, huge, tiny, NaN, ±inf).
// The input is a 56-byte header of parameters followed by a FOLD document (read planarised, at
// most 64 vertices; with header bit 0 its actuation data make a design, so wires and pads are
// drawn). Work stays bounded: a cutting SVG of more than 20,000 dashes is not written.
//
// Invariants beyond "no crash, no leak, no sanitizer report":
// - a refusal (layout, GDSII, DXF, SVG) carries a message; an accepted layout's points and
//   widths are finite, its polygons of 3 points or more;
// - the GDSII stream is a well-formed record sequence: every record's length even and ≥ 4 and
//   inside the stream, HEADER first, then BGNLIB, LIBNAME (the name asked for), UNITS (two
//   finite reals > 0), one BGNSTR, STRNAME (the name asked for) … ENDSTR, ENDLIB last; one
//   element per shape in shape order (BOUNDARY per polygon, PATH per path, TEXT per text) on
//   the shape's layer, each ended by ENDEL; a BOUNDARY's XY closed (first point = last) with
//   point_count + 1 of 4 … 8191 points; every coordinate and width the shape's in database
//   units (the UNITS record's), rounded to the nearest; a TEXT's STRING is the shape's text;
// - ori_gds_real8 is exact: the 8-byte excess-64 real decoded here equals x for every finite
//   |x| in [16^-65, 16^63), is 0 below, refused above; the mantissa is normalised;
// - the layer map has a line per layer whose shape count is the layout's;
// - the DXF is (group code, value) line pairs: integer codes, finite coordinates, a comment,
//   then SECTION … ENDSEC blocks, EOF last; one LINE per B, C, M, V or U edge on its layer;
// - the cutting SVG parses (libxml2), has a finite viewBox with every line inside it; its "cut"
//   group has a line per B and C edge (the DXF's CUT lines), every other group an "eN" group
//   per crease of its kind (the DXF's lines of that layer) with ori_crease_dashes lines; an SVG
//   is written only when the DXF is, and refused when a crease's dashes are;
// - ori_crease_dashes: the count does not depend on cap, is −1 (refused) or ≥ 0; the dashes
//   increase, do not overlap and lie within [vertex_gap, length − vertex_gap] (to rounding).
#include <float.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <math.h>
#include <orikin/orikin.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define HEADER 56
#define MAX_SVG_DASHES 20000

static void fail(const char *what)
{
    fprintf(stderr, "fuzz_fab: %s\n", what);
    abort();
}

// A length from two bytes: one time in eight a hostile value, else typical × 10^±4.
static double hostile(const uint8_t *q, double typical)
{
    if (q[0] < 32) {
        static const double bad[16] = {0.0, -1.0, NAN, INFINITY, -INFINITY, 1e300, 1e-300, 5e-324,
                                       DBL_MAX, -1e-300, 1e30, 1e-30, -0.0, 1e10, 1e-12, 2.0};
        double b = bad[q[1] % 16];
        return b == -1.0 ? -typical : b == 2.0 ? typical * 2.0 : b;
    }
    return typical * pow(10.0, ((int)q[1] - 128) / 32.0);
}

static uint32_t be16(const unsigned char *p) { return (uint32_t)p[0] << 8 | p[1]; }
static int32_t be32(const unsigned char *p)
{
    return (int32_t)((uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3]);
}

// The excess-64 base-16 real: sign, 7-bit exponent, 56-bit mantissa m: m · 16^(e − 64) / 2^56.
static double real8_decode(const unsigned char *b)
{
    uint64_t m = 0;
    for (int i = 1; i < 8; ++i) m = m << 8 | b[i];
    int e = b[0] & 0x7f;
    double x = ldexp((double)m, 4 * (e - 64) - 56);
    return (b[0] & 0x80) ? -x : x;
}

static void check_real8(double x)
{
    unsigned char b[8];
    bool ok = ori_gds_real8(x, b);
    if (!isfinite(x)) {
        if (ok) fail("real8 took a non-finite value");
        return;
    }
    double a = fabs(x);
    if (a >= ldexp(1.0, 252)) { // 16^63
        if (ok) fail("real8 took a value beyond 16^63");
        return;
    }
    if (!ok) fail("real8 refused a value in range");
    double y = real8_decode(b);
    if (a < ldexp(1.0, -260)) { // 16^-65: underflow to 0
        if (y != 0.0) fail("real8 below 16^-65 is not 0");
        return;
    }
    if (y != x) {
        fprintf(stderr, "real8(%.17g) decodes to %.17g\n", x, y);
        fail("real8 is not exact");
    }
    uint64_t m = 0;
    for (int i = 1; i < 8; ++i) m = m << 8 | b[i];
    if (m >> 52 == 0) fail("real8 mantissa not normalised");
}

enum {
    G_HEADER = 0x0002, G_BGNLIB = 0x0102, G_LIBNAME = 0x0206, G_UNITS = 0x0305, G_ENDLIB = 0x0400,
    G_BGNSTR = 0x0502, G_STRNAME = 0x0606, G_ENDSTR = 0x0700, G_BOUNDARY = 0x0800, G_PATH = 0x0900,
    G_TEXT = 0x0C00, G_LAYER = 0x0D02, G_WIDTH = 0x0F03, G_XY = 0x1003, G_ENDEL = 0x1100, G_STRING = 0x1906,
};

// A record at *pos: its type and data (n bytes); advances *pos.
static unsigned next_record(const unsigned char *g, size_t size, size_t *pos, const unsigned char **body, size_t *n)
{
    if (*pos + 4 > size) fail("gds: stream ends inside a record header");
    size_t len = be16(g + *pos);
    if (len < 4 || (len & 1) || *pos + len > size) fail("gds: a record length is odd, below 4 or past the end");
    unsigned type = be16(g + *pos + 2);
    *body = g + *pos + 4;
    *n = len - 4;
    *pos += len;
    return type;
}

static void expect(unsigned got, unsigned want, const char *what)
{
    if (got != want) {
        fprintf(stderr, "gds: record 0x%04x where %s (0x%04x) belongs\n", got, what, want);
        fail("gds: record out of order");
    }
}

// The name as written: its bytes, padded with one NUL to even length.
static void check_string(const unsigned char *body, size_t n, const char *want, const char *what)
{
    size_t m = strlen(want);
    if (n != m + (m & 1) || memcmp(body, want, m) != 0 || ((m & 1) && body[m] != 0)) fail(what);
}

static void check_coord(int32_t got, double x, double scale)
{
    double want = nearbyint(x * scale);
    if (fabs((double)got - want) > 0.0) {
        fprintf(stderr, "gds: coordinate %d for %.17g × %.17g\n", got, x, scale);
        fail("gds: a coordinate is not the shape's in database units");
    }
}

static void check_gds(const unsigned char *g, size_t size, const ori_fab_layout *l, const char *lib, const char *cell)
{
    size_t pos = 0, n;
    const unsigned char *b;
    expect(next_record(g, size, &pos, &b, &n), G_HEADER, "HEADER");
    expect(next_record(g, size, &pos, &b, &n), G_BGNLIB, "BGNLIB");
    expect(next_record(g, size, &pos, &b, &n), G_LIBNAME, "LIBNAME");
    check_string(b, n, lib, "gds: LIBNAME is not the name asked for");
    expect(next_record(g, size, &pos, &b, &n), G_UNITS, "UNITS");
    if (n != 16) fail("gds: UNITS is not two reals");
    double per_user = real8_decode(b), dbu = real8_decode(b + 8);
    if (!(per_user > 0.0) || !(dbu > 0.0) || !isfinite(per_user) || !isfinite(dbu))
        fail("gds: UNITS not two finite reals > 0");
    double scale = ori_fab_layout_meters_per_unit(l) / dbu;
    expect(next_record(g, size, &pos, &b, &n), G_BGNSTR, "BGNSTR");
    expect(next_record(g, size, &pos, &b, &n), G_STRNAME, "STRNAME");
    check_string(b, n, cell, "gds: STRNAME is not the name asked for");
    for (int i = 0; i < ori_fab_shape_count(l); ++i) {
        ori_fab_shape s = ori_fab_shape_at(l, i);
        unsigned want = s.kind == ORI_FAB_POLYGON ? G_BOUNDARY : s.kind == ORI_FAB_PATH ? G_PATH : G_TEXT;
        expect(next_record(g, size, &pos, &b, &n), want, "the shape's element");
        if (n != 0) fail("gds: element record with data");
        unsigned t;
        bool layer = false, xy = false, str = false, width = false;
        while ((t = next_record(g, size, &pos, &b, &n)) != G_ENDEL) {
            if (t == G_ENDSTR || t == G_ENDLIB || t == G_BOUNDARY || t == G_PATH || t == G_TEXT)
                fail("gds: element not ended by ENDEL");
            if (t == G_LAYER) {
                if (n != 2 || (int)be16(b) != s.layer) fail("gds: LAYER is not the shape's");
                layer = true;
            } else if (t == G_WIDTH) {
                if (n != 4 || s.kind != ORI_FAB_PATH) fail("gds: WIDTH out of place");
                check_coord(be32(b), s.width, scale);
                width = true;
            } else if (t == G_STRING) {
                check_string(b, n, s.text ? s.text : "", "gds: STRING is not the shape's text");
                str = true;
            } else if (t == G_XY) {
                if (n % 8) fail("gds: XY not of points");
                int m = (int)(n / 8);
                int want_m = s.kind == ORI_FAB_POLYGON ? s.point_count + 1 : s.kind == ORI_FAB_PATH ? s.point_count : 1;
                if (m != want_m) fail("gds: XY point count is not the shape's");
                if (s.kind == ORI_FAB_POLYGON) {
                    if (m < 4 || m > 8191) fail("gds: BOUNDARY of fewer than 4 or more than 8191 points");
                    if (memcmp(b, b + 8 * (m - 1), 8) != 0) fail("gds: BOUNDARY not closed");
                }
                for (int k = 0; k < m; ++k) {
                    ori_v2 p = s.points[k % s.point_count];
                    check_coord(be32(b + 8 * k), p.x, scale);
                    check_coord(be32(b + 8 * k + 4), p.y, scale);
                }
                xy = true;
            }
        }
        if (!layer || !xy || (s.kind == ORI_FAB_PATH && !width) || (s.kind == ORI_FAB_TEXT && !str))
            fail("gds: element lacks LAYER, XY, WIDTH or STRING");
    }
    expect(next_record(g, size, &pos, &b, &n), G_ENDSTR, "ENDSTR");
    expect(next_record(g, size, &pos, &b, &n), G_ENDLIB, "ENDLIB");
    if (pos != size) fail("gds: bytes after ENDLIB");
}

static void check_layer_map(const char *map, const ori_fab_layout *l)
{
    if (!map) fail("layer map is NULL");
    for (int k = ORI_FAB_LAYER_FIRST; k <= ORI_FAB_LAYER_LAST; ++k) {
        int count = 0;
        for (int i = 0; i < ori_fab_shape_count(l); ++i) count += ori_fab_shape_at(l, i).layer == k;
        char want[64];
        snprintf(want, sizeof want, "\n%d/0 %s ", k, ori_fab_layer_name(k));
        const char *at = strstr(map, want);
        if (!at) fail("layer map lacks a layer");
        const char *eol = strchr(at + 1, '\n'), *paren = NULL; // the last "(N shapes)" of the line
        for (const char *c = at + 1; eol && c < eol; ++c)
            if (*c == '(') paren = c;
        if (!paren || atoi(paren + 1) != count) fail("layer map count is not the layout's");
    }
}

static int edge_kind(ori_assignment a)
{
    switch (a) {
    case ORI_ASSIGN_BOUNDARY:
    case ORI_ASSIGN_CUT: return 0;
    case ORI_ASSIGN_MOUNTAIN: return 1;
    case ORI_ASSIGN_VALLEY: return 2;
    case ORI_ASSIGN_UNASSIGNED: return 3;
    default: return -1;
    }
}

// DXF: (code, value) line pairs; returns the LINE entities by layer into lines[4].
static void check_dxf(const char *dxf, int lines[4])
{
    static const char *const layers[4] = {"CUT", "MOUNTAIN", "VALLEY", "UNASSIGNED"};
    const char *p = dxf;
    int pairs = 0, depth = 0, kind = -2;
    bool eof = false, in_line = false;
    char code_line[64], value[256];
    while (*p) {
        if (eof) fail("dxf: pairs after EOF");
        const char *e1 = strchr(p, '\n');
        if (!e1 || e1 - p >= (long)sizeof code_line) fail("dxf: a code line is unterminated or long");
        memcpy(code_line, p, (size_t)(e1 - p));
        code_line[e1 - p] = '\0';
        const char *e2 = strchr(e1 + 1, '\n');
        if (!e2 || e2 - e1 - 1 >= (long)sizeof value) fail("dxf: a value line is missing or long");
        memcpy(value, e1 + 1, (size_t)(e2 - e1 - 1));
        value[e2 - e1 - 1] = '\0';
        p = e2 + 1;
        char *end;
        long code = strtol(code_line, &end, 10);
        if (end == code_line || *end) fail("dxf: a group code is not an integer");
        if (pairs == 0 && code != 999) fail("dxf: no comment first");
        if (pairs == 1 && !(code == 0 && strcmp(value, "SECTION") == 0)) fail("dxf: no SECTION after the comment");
        ++pairs;
        if (code == 0) {
            if (in_line && kind >= 0) lines[kind]++;
            in_line = strcmp(value, "LINE") == 0;
            kind = -2;
            if (strcmp(value, "SECTION") == 0) {
                if (depth++ != 0) fail("dxf: SECTION inside a SECTION");
            } else if (strcmp(value, "ENDSEC") == 0) {
                if (--depth != 0) fail("dxf: ENDSEC without SECTION");
            } else if (strcmp(value, "EOF") == 0) {
                if (depth != 0) fail("dxf: EOF inside a SECTION");
                eof = true;
            }
        } else if (in_line && code == 8) {
            kind = -1;
            for (int k = 0; k < 4; ++k)
                if (strcmp(value, layers[k]) == 0) kind = k;
            if (kind < 0) fail("dxf: a LINE on an unknown layer");
        } else if (code == 10 || code == 20 || code == 30 || code == 11 || code == 21 || code == 31 || code == 40) {
            double x = strtod(value, &end);
            if (end == value || *end || !isfinite(x)) fail("dxf: a coordinate is not a finite number");
        }
    }
    if (!eof) fail("dxf: no EOF last");
}

// A crease's length in the SVG, as the writer has it: X = (x − x0)·s + margin, Y = (y1 − y)·s + margin.
static double svg_length(const ori_pattern *p, const ori_cut_def *cd, ori_edge ed)
{
    double x0 = INFINITY, y1 = -INFINITY;
    for (int i = 0; i < ori_pattern_vertex_count(p); ++i) {
        x0 = fmin(x0, ori_pattern_vertex(p, i).x);
        y1 = fmax(y1, ori_pattern_vertex(p, i).y);
    }
    double s = cd->mm_per_unit, margin = 2.0 * cd->stroke_mm;
    ori_v3 a = ori_pattern_vertex(p, ed.v[0]), b = ori_pattern_vertex(p, ed.v[1]);
    double ax = (a.x - x0) * s + margin, ay = (y1 - a.y) * s + margin;
    double bx = (b.x - x0) * s + margin, by = (y1 - b.y) * s + margin;
    return hypot(bx - ax, by - ay);
}

static double attr(xmlNode *n, const char *name)
{
    xmlChar *v = xmlGetProp(n, (const xmlChar *)name);
    char *end;
    double x = v ? strtod((const char *)v, &end) : NAN;
    if (v && *end) x = NAN;
    xmlFree(v);
    return x;
}

// Lines of a group, each inside the view box [0, w] × [0, h] (to rounding).
static int count_lines_in(xmlNode *n, double w, double h)
{
    int c = 0;
    double tol = 1e-9 * (w + h);
    for (xmlNode *k = n->children; k; k = k->next)
        if (k->type == XML_ELEMENT_NODE && xmlStrcmp(k->name, (const xmlChar *)"line") == 0) {
            double x[2] = {attr(k, "x1"), attr(k, "x2")}, y[2] = {attr(k, "y1"), attr(k, "y2")};
            for (int i = 0; i < 2; ++i)
                if (!(x[i] >= -tol && x[i] <= w + tol && y[i] >= -tol && y[i] <= h + tol))
                    fail("svg: a line outside the view box or not a number");
            ++c;
        }
    return c;
}

static void check_svg(const char *svg, const ori_pattern *p, const ori_cut_def *cd, const int lines[4])
{
    xmlDoc *doc = xmlReadMemory(svg, (int)strlen(svg), "cut.svg", NULL, XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING);
    if (!doc) fail("svg: not well-formed XML");
    xmlNode *root = xmlDocGetRootElement(doc);
    if (!root || xmlStrcmp(root->name, (const xmlChar *)"svg") != 0) fail("svg: root is not <svg>");
    xmlChar *vb = xmlGetProp(root, (const xmlChar *)"viewBox");
    double w = NAN, h = NAN;
    if (!vb || sscanf((const char *)vb, "0 0 %lf %lf", &w, &h) != 2 || !(w >= 0.0) || !(h >= 0.0) || !isfinite(w) || !isfinite(h))
        fail("svg: no finite viewBox");
    xmlFree(vb);
    static const char *const groups[4] = {"cut", "mountain", "valley", "unassigned"};
    int k = 0;
    for (xmlNode *g = root->children; g; g = g->next) {
        if (g->type != XML_ELEMENT_NODE) continue;
        if (k >= 4 || xmlStrcmp(g->name, (const xmlChar *)"g") != 0) fail("svg: not four groups");
        xmlChar *id = xmlGetProp(g, (const xmlChar *)"id");
        bool same = id && strcmp((const char *)id, groups[k]) == 0;
        xmlFree(id);
        if (!same) fail("svg: groups out of order");
        if (k == 0) {
            if (count_lines_in(g, w, h) != lines[0]) fail("svg: cut lines are not the DXF's CUT lines");
        } else {
            int creases = 0;
            for (xmlNode *e = g->children; e; e = e->next) {
                if (e->type != XML_ELEMENT_NODE) continue;
                xmlChar *eid = xmlGetProp(e, (const xmlChar *)"id");
                int edge = eid && eid[0] == 'e' ? atoi((const char *)eid + 1) : -1;
                xmlFree(eid);
                if (edge < 0 || edge >= ori_pattern_edge_count(p)) fail("svg: a crease group without its edge");
                ori_edge ed = ori_pattern_edge(p, edge);
                if (edge_kind(ed.assignment) != k) fail("svg: a crease in the wrong group");
                int want = ori_crease_dashes(svg_length(p, cd, ed), cd, NULL, NULL, 0);
                if (count_lines_in(e, w, h) != want) fail("svg: a crease's lines are not its dashes");
                ++creases;
            }
            if (creases != lines[k]) fail("svg: creases are not the DXF's lines of the layer");
        }
        ++k;
    }
    if (k != 4) fail("svg: not four groups");
    xmlFreeDoc(doc);
}

static void check_dashes(double length, const ori_cut_def *cd)
{
    enum { CAP = 64 };
    double s[CAP], e[CAP];
    int n = ori_crease_dashes(length, cd, s, e, CAP);
    int n0 = ori_crease_dashes(length, cd, NULL, NULL, 0);
    if (n != n0) fail("dashes: the count depends on cap");
    if (n < -1) fail("dashes: a count below -1");
    if (n == -1) return; // refused: the def out of range, or more than ORI_CUT_MAX_DASHES
    double tol = 1e-9 * (fabs(length) + fabs(cd->vertex_gap_mm));
    for (int i = 0; i < n && i < CAP; ++i) {
        if (!isfinite(s[i]) || !isfinite(e[i]) || !(s[i] <= e[i])) fail("dashes: a dash ends before it starts");
        if (i > 0 && !(e[i - 1] <= s[i] + tol)) fail("dashes: dashes overlap or go back");
        if (!(s[i] >= cd->vertex_gap_mm - tol) || !(e[i] <= length - cd->vertex_gap_mm + tol))
            fail("dashes: a dash outside the stretch between the vertex gaps");
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static bool init;
    if (!init) {
        xmlInitParser();
        init = true;
    }
    if (size < HEADER) return 0;
    const uint8_t *q = data;
    uint8_t flags = q[0];
    // ori_gds_real8 on the 8 raw bytes as a double
    double raw;
    memcpy(&raw, q + 42, 8);
    check_real8(raw);
    check_real8(ldexp(raw, (int)q[50] - 128));

    ori_fold *doc = NULL;
    ori_pattern *p = NULL;
    ori_error err;
    ori_build_def bd = ori_default_build_def();
    bd.planarize = true;
    if (ori_fold_load_string((const char *)data + HEADER, size - HEADER, &doc, &err) != ORI_OK ||
        ori_fold_get_pattern(doc, 0, &bd, &p, &err) != ORI_OK || ori_pattern_vertex_count(p) > 64) {
        ori_pattern_destroy(p);
        ori_fold_destroy(doc);
        if (ori_alloc_live_count() != 0) fail("leak");
        return 0;
    }
    double mpu = hostile(q + 2, 1e-4);
    ori_design *design = NULL;
    if (flags & 1) {
        ori_design_def dd = ori_default_design_def();
        dd.doc = doc;
        dd.pattern = p;
        dd.has_meters_per_unit = isfinite(mpu) && mpu > 0.0;
        dd.meters_per_unit = mpu;
        if (ori_design_create(&dd, &design, &err) != ORI_OK) design = NULL;
    }
    ori_fab_def fd = ori_default_fab_def();
    fd.pattern = p;
    fd.design = design;
    fd.meters_per_unit = mpu;
    fd.hinges_everywhere = (flags & 2) != 0;
    if (flags & 8) fd.fixed_face = q[1] % (ori_pattern_face_count(p) + 2) - 1;
    double *lens[10] = {&fd.hinge_gap_m, &fd.default_hinge_span_m, &fd.hinge_overlap_m, &fd.hinge_width_m,
                        &fd.wire_width_m, &fd.pad_size_m, &fd.lead_length_m, &fd.mark_size_m, &fd.mark_margin_m,
                        &fd.label_height_m};
    for (int i = 0; i < 10; ++i) *lens[i] = hostile(q + 4 + 2 * i, *lens[i] != 0.0 ? *lens[i] : 20e-6);
    static const char label_chars[] = "orikin FAB label 0123456789-_/<&>\"'";
    int label_len = q[51] % 24;
    for (int i = 0; i < label_len; ++i) fd.label[i] = label_chars[(q[51] + i * 7) % (sizeof label_chars - 1)];
    fd.label[label_len] = '\0';

    ori_fab_layout *l = NULL;
    static int trace = -1;
    if (trace < 0) trace = getenv("FUZZ_FAB_TRACE") != NULL;
    ori_status lst = ori_fab_layout_create(&fd, &l, &err);
    if (trace) fprintf(stderr, "fuzz_fab: %d vertices, design %s, layout %s%s\n", ori_pattern_vertex_count(p),
                       design ? "yes" : "no", lst == ORI_OK ? "ok" : "refused: ", lst == ORI_OK ? "" : err.message);
    if (lst != ORI_OK) {
        if (!err.message[0]) fail("layout refused without a message");
    } else {
        for (int i = 0; i < ori_fab_shape_count(l); ++i) {
            ori_fab_shape s = ori_fab_shape_at(l, i);
            if (!isfinite(s.width) || s.point_count < 1) fail("layout: a shape of no points or a non-finite width");
            if (s.kind == ORI_FAB_POLYGON && s.point_count < 3) fail("layout: a polygon of fewer than 3 points");
            for (int k = 0; k < s.point_count; ++k)
                if (!isfinite(s.points[k].x) || !isfinite(s.points[k].y)) fail("layout: a non-finite point");
        }
        char *map = ori_fab_layer_map(l);
        check_layer_map(map, l);
        ori_buffer_free(map);
        static char long_name[70001];
        if (!long_name[0]) memset(long_name, 'N', sizeof long_name - 1);
        static const char *const names[] = {"ORIKIN", "", "A", "odd", "DEVICE_WITH_A_LONG_NAME_0123456789", long_name};
        ori_gds_def gd = ori_default_gds_def();
        if (flags & 16) {
            gd.library_name = names[q[52] % 6];
            gd.cell_name = names[q[53] % 6];
        }
        if (flags & 32) gd.user_unit_m = hostile(q + 24, 1e-6);
        if (flags & 64) gd.database_unit_m = hostile(q + 26, 1e-9);
        size_t n = 0;
        unsigned char *g = ori_gds_write(l, &gd, &n, &err);
        if (trace) fprintf(stderr, "fuzz_fab: %d shapes, gds %s%s\n", ori_fab_shape_count(l), g ? "ok" : "refused: ",
                           g ? "" : err.message);
        if (!g) {
            if (!err.message[0]) fail("gds refused without a message");
        } else {
            check_gds(g, n, l, gd.library_name, gd.cell_name);
        }
        ori_buffer_free(g);
        ori_fab_layout_destroy(l);
    }
    ori_design_destroy(design);

    ori_cut_def cd = ori_default_cut_def();
    cd.perforate = (flags & 4) != 0;
    double *cuts[7] = {&cd.mm_per_unit, &cd.dash_mm, &cd.gap_mm, &cd.vertex_gap_mm, &cd.perforation_mm,
                       &cd.perforation_pitch_mm, &cd.stroke_mm};
    for (int i = 0; i < 7; ++i) *cuts[i] = hostile(q + 28 + 2 * i, *cuts[i]);
    check_dashes(hostile(q + 2, 10.0), &cd);
    char *dxf = ori_dxf_write(p, &cd, &err);
    int lines[4] = {0};
    if (!dxf) {
        if (!err.message[0]) fail("dxf refused without a message");
    } else {
        check_dxf(dxf, lines);
        int want[4] = {0};
        for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
            int k = edge_kind(ori_pattern_edge(p, e).assignment);
            if (k >= 0) want[k]++;
        }
        if (memcmp(want, lines, sizeof want) != 0) fail("dxf: LINE count is not the edges'");
    }
    // bounded work: the SVG's dashes (−1: a def out of range or too many for a crease)
    double total = 0.0;
    bool refused = false;
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        if (edge_kind(ed.assignment) <= 0) continue;
        double len = svg_length(p, &cd, ed);
        check_dashes(len, &cd);
        int n = ori_crease_dashes(len, &cd, NULL, NULL, 0);
        if (n < 0) refused = true;
        else total += n;
    }
    if (total <= MAX_SVG_DASHES) {
        char *svg = ori_cut_svg_write(p, &cd, &err);
        if (trace) fprintf(stderr, "fuzz_fab: dxf %s, svg of %.0f dashes %s%s\n", dxf ? "ok" : "refused", total,
                           svg ? "ok" : "refused: ", svg ? "" : err.message);
        if (!svg) {
            if (!err.message[0]) fail("svg refused without a message");
        } else {
            if (refused) fail("svg took a crease whose dashes are refused");
            if (!dxf) fail("svg took what the DXF refused");
            check_svg(svg, p, &cd, lines);
        }
        ori_buffer_free(svg);
    }
    ori_buffer_free(dxf);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    if (ori_alloc_live_count() != 0) fail("leak");
    return 0;
}
