// Cutting files of a flat crease pattern (include/orikin/fab.h): ASCII DXF R12 with a layer per
// kind of line, and an SVG for laser cutters with each crease as explicit dashes or slits.
#include <math.h>
#include <string.h>

#include <orikin/fab.h>

#include "../core/core_internal.h"
#include "../io/io_internal.h"

ori_cut_def ori_default_cut_def(void)
{
    ori_cut_def d;
    d.mm_per_unit = 1.0;
    d.dash_mm = 3.0;
    d.gap_mm = 1.5;
    d.vertex_gap_mm = 1.0;
    d.perforate = false;
    d.perforation_mm = 0.5;
    d.perforation_pitch_mm = 1.5;
    d.stroke_mm = 0.1;
    d.internal_value = 1;
    return d;
}

int ori_crease_dashes(double length, const ori_cut_def *def, double *starts, double *ends, int cap)
{
    ori_cut_def d = def ? *def : ori_default_cut_def();
    double dash = d.perforate ? d.perforation_mm : d.dash_mm;
    double gap = d.perforate ? d.perforation_pitch_mm - d.perforation_mm : d.gap_mm;
    double s0 = d.vertex_gap_mm, stretch = length - 2.0 * d.vertex_gap_mm;
    if (!(stretch > 0.0) || !(dash > 0.0)) return 0;
    if (gap < 0.0) gap = 0.0;
    if (stretch <= dash) {
        if (cap > 0) starts[0] = s0, ends[0] = s0 + stretch;
        return 1;
    }
    int n = (int)floor((stretch + gap) / (dash + gap));
    double used = n * dash + (n - 1) * gap, lead = 0.5 * (stretch - used);
    for (int i = 0; i < n && i < cap; ++i) {
        starts[i] = s0 + lead + i * (dash + gap);
        ends[i] = starts[i] + dash;
    }
    return n;
}

// Layer of an edge: 0 cut, 1 mountain, 2 valley, 3 unassigned; −1 not written.
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

static const char *const dxf_layers[4] = {"CUT", "MOUNTAIN", "VALLEY", "UNASSIGNED"};
static const int dxf_colours[4] = {7, 1, 5, 3};

static void pair_real(ori__text *t, int code, double x)
{
    ori__text_printf(t, "%d\n", code);
    ori__text_real(t, x == 0.0 ? 0.0 : x);
    ori__text_puts(t, "\n");
}

static bool flat_pattern(const ori_pattern *p)
{
    return p && !ori_pattern_is_folded_form(p) && !ori_pattern_is_3d(p);
}

static void bounds(const ori_pattern *p, double *x0, double *y0, double *x1, double *y1)
{
    *x0 = *y0 = INFINITY;
    *x1 = *y1 = -INFINITY;
    for (int i = 0; i < ori_pattern_vertex_count(p); ++i) {
        ori_v3 q = ori_pattern_vertex(p, i);
        *x0 = fmin(*x0, q.x), *y0 = fmin(*y0, q.y), *x1 = fmax(*x1, q.x), *y1 = fmax(*y1, q.y);
    }
    if (!(*x0 <= *x1)) *x0 = *y0 = *x1 = *y1 = 0.0;
}

char *ori_dxf_write(const ori_pattern *p, const ori_cut_def *def)
{
    if (!flat_pattern(p)) return NULL;
    ori_cut_def d = def ? *def : ori_default_cut_def();
    double s = d.mm_per_unit;
    double x0, y0, x1, y1;
    bounds(p, &x0, &y0, &x1, &y1);
    ori__text t = {NULL, 0, 0};
    ori__text_puts(&t, "999\norikin crease pattern (mm)\n0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1009\n9\n$INSUNITS\n70\n4\n");
    ori__text_puts(&t, "9\n$EXTMIN\n");
    pair_real(&t, 10, x0 * s);
    pair_real(&t, 20, y0 * s);
    pair_real(&t, 30, 0.0);
    ori__text_puts(&t, "9\n$EXTMAX\n");
    pair_real(&t, 10, x1 * s);
    pair_real(&t, 20, y1 * s);
    pair_real(&t, 30, 0.0);
    ori__text_puts(&t, "0\nENDSEC\n0\nSECTION\n2\nTABLES\n");
    ori__text_puts(&t, "0\nTABLE\n2\nLTYPE\n70\n1\n0\nLTYPE\n2\nCONTINUOUS\n70\n0\n3\nSolid line\n72\n65\n73\n0\n40\n0.0\n0\nENDTAB\n");
    ori__text_puts(&t, "0\nTABLE\n2\nLAYER\n70\n4\n");
    for (int k = 0; k < 4; ++k)
        ori__text_printf(&t, "0\nLAYER\n2\n%s\n70\n0\n62\n%d\n6\nCONTINUOUS\n", dxf_layers[k], dxf_colours[k]);
    ori__text_puts(&t, "0\nENDTAB\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n");
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        int k = edge_kind(ed.assignment);
        if (k < 0) continue;
        ori_v3 a = ori_pattern_vertex(p, ed.v[0]), b = ori_pattern_vertex(p, ed.v[1]);
        ori__text_printf(&t, "0\nLINE\n8\n%s\n", dxf_layers[k]);
        pair_real(&t, 10, a.x * s);
        pair_real(&t, 20, a.y * s);
        pair_real(&t, 30, 0.0);
        pair_real(&t, 11, b.x * s);
        pair_real(&t, 21, b.y * s);
        pair_real(&t, 31, 0.0);
    }
    ori__text_puts(&t, "0\nENDSEC\n0\nEOF\n");
    return t.data;
}

static const char *const svg_groups[4] = {"cut", "mountain", "valley", "unassigned"};
static const char *const svg_colours[4] = {"#000000", "#ff0000", "#0000ff", "#00a000"};

static void svg_line(ori__text *t, double ax, double ay, double bx, double by)
{
    ori__text_puts(t, "<line x1=\"");
    ori__text_real(t, ax);
    ori__text_puts(t, "\" y1=\"");
    ori__text_real(t, ay);
    ori__text_puts(t, "\" x2=\"");
    ori__text_real(t, bx);
    ori__text_puts(t, "\" y2=\"");
    ori__text_real(t, by);
    ori__text_puts(t, "\"/>\n");
}

char *ori_cut_svg_write(const ori_pattern *p, const ori_cut_def *def)
{
    if (!flat_pattern(p)) return NULL;
    ori_cut_def d = def ? *def : ori_default_cut_def();
    double s = d.mm_per_unit;
    double x0, y0, x1, y1;
    bounds(p, &x0, &y0, &x1, &y1);
    double margin = 2.0 * d.stroke_mm;
    // mm, y down: X = (x − x0)·s + margin, Y = (y1 − y)·s + margin
    double w = (x1 - x0) * s + 2.0 * margin, h = (y1 - y0) * s + 2.0 * margin;
    ori__text t = {NULL, 0, 0};
    ori__text_puts(&t, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
                       "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" width=\"");
    ori__text_real(&t, w);
    ori__text_puts(&t, "mm\" height=\"");
    ori__text_real(&t, h);
    ori__text_puts(&t, "mm\" viewBox=\"0 0 ");
    ori__text_real(&t, w);
    ori__text_puts(&t, " ");
    ori__text_real(&t, h);
    ori__text_puts(&t, "\">\n");
    int cap = 0;
    double *st = NULL, *en = NULL;
    for (int k = 0; k < 4; ++k) {
        ori__text_printf(&t, "<g id=\"%s\" inkscape:groupmode=\"layer\" inkscape:label=\"%s\" fill=\"none\" stroke=\"%s\" "
                             "stroke-width=\"",
                         svg_groups[k], svg_groups[k], svg_colours[k]);
        ori__text_real(&t, d.stroke_mm);
        ori__text_puts(&t, "\">\n");
        for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
            ori_edge ed = ori_pattern_edge(p, e);
            if (edge_kind(ed.assignment) != k) continue;
            ori_v3 a = ori_pattern_vertex(p, ed.v[0]), b = ori_pattern_vertex(p, ed.v[1]);
            double ax = (a.x - x0) * s + margin, ay = (y1 - a.y) * s + margin;
            double bx = (b.x - x0) * s + margin, by = (y1 - b.y) * s + margin;
            if (k == 0) {
                svg_line(&t, ax, ay, bx, by);
                continue;
            }
            double len = hypot(bx - ax, by - ay);
            int n = ori_crease_dashes(len, &d, st, en, cap);
            if (n > cap) {
                cap = n;
                st = ori__realloc(st, sizeof(double) * (size_t)cap);
                en = ori__realloc(en, sizeof(double) * (size_t)cap);
                n = ori_crease_dashes(len, &d, st, en, cap);
            }
            double ux = (bx - ax) / len, uy = (by - ay) / len;
            ori__text_printf(&t, "<g id=\"e%d\">\n", e);
            for (int i = 0; i < n; ++i)
                svg_line(&t, ax + ux * st[i], ay + uy * st[i], ax + ux * en[i], ay + uy * en[i]);
            ori__text_puts(&t, "</g>\n");
        }
        ori__text_puts(&t, "</g>\n");
    }
    ori__free(st);
    ori__free(en);
    ori__text_puts(&t, "</svg>\n");
    return t.data;
}
