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

// The def's lengths that the SVG uses (all: the DXF only mm_per_unit): finite, the dashes and
// slits, the stroke and the scale > 0, gaps ≥ 0, a slit shorter than its pitch.
static ori_status check_def(const ori_cut_def *d, bool svg, ori_error *error)
{
    if (!(isfinite(d->mm_per_unit) && d->mm_per_unit > 0.0))
        return ori__fail_at(error, ORI_ERR_RANGE, "mm_per_unit", ORI_NULL_INDEX, "mm_per_unit must be a finite number > 0");
    if (!svg) return ORI_OK;
    const char *names[] = {"dash_mm", "gap_mm", "vertex_gap_mm", "perforation_mm", "perforation_pitch_mm", "stroke_mm"};
    double vals[] = {d->dash_mm, d->gap_mm, d->vertex_gap_mm, d->perforation_mm, d->perforation_pitch_mm, d->stroke_mm};
    bool zero_ok[] = {false, true, true, false, false, false};
    for (int i = 0; i < 6; ++i) {
        if (d->perforate ? i <= 1 : i == 3 || i == 4) continue; // the other style's fields are not used
        if (!(isfinite(vals[i]) && (vals[i] > 0.0 || (zero_ok[i] && vals[i] == 0.0))))
            return ori__fail_at(error, ORI_ERR_RANGE, names[i], ORI_NULL_INDEX, "%s must be a finite length %s (mm)", names[i],
                                zero_ok[i] ? ">= 0" : "> 0");
    }
    if (d->perforate && !(d->perforation_pitch_mm > d->perforation_mm))
        return ori__fail_at(error, ORI_ERR_RANGE, "perforation_pitch_mm", ORI_NULL_INDEX,
                            "perforation_pitch_mm must be longer than perforation_mm (a slit starts every pitch)");
    return ORI_OK;
}

int ori_crease_dashes(double length, const ori_cut_def *def, double *starts, double *ends, int cap)
{
    ori_cut_def d = def ? *def : ori_default_cut_def();
    if (check_def(&d, true, NULL) != ORI_OK) return -1;
    double dash = d.perforate ? d.perforation_mm : d.dash_mm;
    double gap = d.perforate ? d.perforation_pitch_mm - d.perforation_mm : d.gap_mm;
    double s0 = d.vertex_gap_mm, stretch = length - 2.0 * d.vertex_gap_mm;
    if (!(stretch > 0.0)) return 0;
    if (stretch <= dash) {
        if (cap > 0) starts[0] = s0, ends[0] = s0 + stretch;
        return 1;
    }
    // (as a double first: a dash tiny against the crease would overflow an int)
    double count = floor((stretch + gap) / (dash + gap));
    if (!(count <= ORI_CUT_MAX_DASHES)) return -1;
    int n = (int)count;
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

// The pattern flat and the def in range, its extent in mm finite (*x0 … *y1 its bounds).
static ori_status check_input(const ori_pattern *p, const ori_cut_def *d, bool svg, double *x0, double *y0, double *x1,
                              double *y1, ori_error *error)
{
    ORI_ASSERT(p);
    if (ori_pattern_is_folded_form(p) || ori_pattern_is_3d(p))
        return ori__fail(error, ORI_ERR_ARGUMENT, "cut: the pattern is folded (a cutting file needs the flat crease pattern)");
    ori_status st = check_def(d, svg, error);
    if (st != ORI_OK) return st;
    bounds(p, x0, y0, x1, y1);
    double s = d->mm_per_unit, m = svg ? 4.0 * d->stroke_mm : 0.0;
    if (!(isfinite(fmax(fabs(*x0), fabs(*x1)) * s + m) && isfinite(fmax(fabs(*y0), fabs(*y1)) * s + m) &&
          isfinite((*x1 - *x0) * s + m) && isfinite((*y1 - *y0) * s + m)))
        return ori__fail_at(error, ORI_ERR_RANGE, "mm_per_unit", ORI_NULL_INDEX,
                            "the pattern at %g mm per unit is beyond the range of coordinates", s);
    return ORI_OK;
}

char *ori_dxf_write(const ori_pattern *p, const ori_cut_def *def, ori_error *error)
{
    ori_cut_def d = def ? *def : ori_default_cut_def();
    double s = d.mm_per_unit;
    double x0, y0, x1, y1;
    if (check_input(p, &d, false, &x0, &y0, &x1, &y1, error) != ORI_OK) return NULL;
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

char *ori_cut_svg_write(const ori_pattern *p, const ori_cut_def *def, ori_error *error)
{
    ori_cut_def d = def ? *def : ori_default_cut_def();
    double s = d.mm_per_unit;
    double x0, y0, x1, y1;
    if (check_input(p, &d, true, &x0, &y0, &x1, &y1, error) != ORI_OK) return NULL;
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
            if (n < 0) {
                ori__free(st);
                ori__free(en);
                ori__free(t.data);
                ori__fail_at(error, ORI_ERR_LIMIT, "edges_vertices", e,
                             "more than %d dashes (longer dashes or gaps, or fewer mm per unit)", ORI_CUT_MAX_DASHES);
                return NULL;
            }
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
