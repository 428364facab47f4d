// SVG picture of a flat-folded state beside its crease pattern (Cairo's SVG surface, written
// into memory). The folded state is seen from above: every cell of the overlap structure takes
// the colour of the side its top face shows (front or back), darker the more layers lie under
// it, and a folded edge is drawn where the top faces on its two sides differ (the outline one
// sees on the folded model).
#include "layers_internal.h"

#include <cairo-svg.h>
#include <cairo.h>
#include <stdio.h>

typedef struct sink {
    unsigned char *data;
    size_t n, cap;
} sink;

static cairo_status_t write_sink(void *closure, const unsigned char *data, unsigned int length)
{
    sink *s = closure;
    if (s->n + length + 1 > s->cap) {
        size_t cap = s->cap ? s->cap : 4096;
        while (cap < s->n + length + 1) cap *= 2;
        s->data = ori__realloc(s->data, cap);
        s->cap = cap;
    }
    memcpy(s->data + s->n, data, length);
    s->n += length;
    return CAIRO_STATUS_SUCCESS;
}

typedef struct view {
    double x0, y0, scale, ox, oy;
} view;

// Fit the box [lo, hi] into a square panel of side `side` at (ox, oy), y up.
static view fit(ori_v2 lo, ori_v2 hi, double ox, double oy, double side)
{
    view v;
    double w = hi.x - lo.x, h = hi.y - lo.y, m = w > h ? w : h;
    v.scale = m > 0.0 ? side / m : 1.0;
    v.x0 = lo.x - (m - w) / 2.0;
    v.y0 = lo.y - (m - h) / 2.0;
    v.ox = ox;
    v.oy = oy + side;
    return v;
}

static void to_px(const view *v, ori_v2 p, double *x, double *y)
{
    *x = v->ox + (p.x - v->x0) * v->scale;
    *y = v->oy - (p.y - v->y0) * v->scale;
}

static void crease_style(cairo_t *cr, ori_assignment a)
{
    static const double dash[] = {6.0, 3.0}, dashdot[] = {8.0, 3.0, 1.5, 3.0}, dot[] = {1.5, 3.0};
    cairo_set_dash(cr, NULL, 0, 0.0);
    cairo_set_line_width(cr, 1.5);
    switch (a) {
    case ORI_ASSIGN_MOUNTAIN:
        cairo_set_source_rgb(cr, 0.84, 0.15, 0.16);
        cairo_set_dash(cr, dashdot, 4, 0.0);
        break;
    case ORI_ASSIGN_VALLEY:
        cairo_set_source_rgb(cr, 0.12, 0.47, 0.71);
        cairo_set_dash(cr, dash, 2, 0.0);
        break;
    case ORI_ASSIGN_UNASSIGNED: cairo_set_source_rgb(cr, 0.58, 0.40, 0.74); break;
    case ORI_ASSIGN_FLAT:
        cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);
        cairo_set_line_width(cr, 0.75);
        break;
    case ORI_ASSIGN_JOIN:
        cairo_set_source_rgb(cr, 0.7, 0.7, 0.7);
        cairo_set_dash(cr, dot, 2, 0.0);
        cairo_set_line_width(cr, 0.75);
        break;
    default:
        cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
        cairo_set_line_width(cr, 2.0);
        break;
    }
}

ori_status ori_layers_svg(const ori_layers *L, const ori_pattern *p, char **out, size_t *size, ori_error *error)
{
    ORI_ASSERT(L && p && out && size);
    *out = NULL;
    *size = 0;
    if (!L->has_state) return ori__fail(error, ORI_ERR_ARGUMENT, "no state selected");
    const double side = 420.0, margin = 30.0, title = 24.0;
    double width = 2 * side + 3 * margin, height = side + 2 * margin + title;
    sink s = {0};
    cairo_surface_t *surf = cairo_svg_surface_create_for_stream(write_sink, &s, width, height);
    cairo_t *cr = cairo_create(surf);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);

    // Left: the crease pattern, boundary last.
    ori_v2 lo = {1e300, 1e300}, hi = {-1e300, -1e300};
    for (int v = 0; v < L->nv; ++v) {
        ori_v3 q = ori_pattern_vertex(p, v);
        lo.x = fmin(lo.x, q.x);
        lo.y = fmin(lo.y, q.y);
        hi.x = fmax(hi.x, q.x);
        hi.y = fmax(hi.y, q.y);
    }
    view cp = fit(lo, hi, margin, margin + title, side);
    for (int pass = 0; pass < 2; ++pass)
        for (int e = 0; e < L->ne; ++e) {
            bool boundary = L->asg[e] == ORI_ASSIGN_BOUNDARY || L->asg[e] == ORI_ASSIGN_CUT;
            if (boundary != (pass == 1)) continue;
            ori_v3 a = ori_pattern_vertex(p, L->ev[e][0]), b = ori_pattern_vertex(p, L->ev[e][1]);
            double x, y;
            crease_style(cr, L->asg[e]);
            to_px(&cp, ori_v2_make(a.x, a.y), &x, &y);
            cairo_move_to(cr, x, y);
            to_px(&cp, ori_v2_make(b.x, b.y), &x, &y);
            cairo_line_to(cr, x, y);
            cairo_stroke(cr);
        }
    cairo_set_dash(cr, NULL, 0, 0.0);

    // Right: the folded state, cell by cell.
    lo = ori_v2_make(1e300, 1e300);
    hi = ori_v2_make(-1e300, -1e300);
    for (int r = 0; r < L->np; ++r) {
        lo.x = fmin(lo.x, L->pts[r].x);
        lo.y = fmin(lo.y, L->pts[r].y);
        hi.x = fmax(hi.x, L->pts[r].x);
        hi.y = fmax(hi.y, L->pts[r].y);
    }
    view fv = fit(lo, hi, 2 * margin + side, margin + title, side);
    int *top = ori__alloc(sizeof(int) * (size_t)(L->nc ? L->nc : 1));
    int kmax = 1;
    for (int c = 0; c < L->nc; ++c) {
        int k = (int)(L->cell_faces.off[c + 1] - L->cell_faces.off[c]);
        kmax = k > kmax ? k : kmax;
    }
    int *stack = ori__alloc(sizeof(int) * (size_t)(kmax ? kmax : 1));
    for (int c = 0; c < L->nc; ++c) {
        int k = ori_layers_cell_stack(L, c, stack, kmax);
        top[c] = k > 0 ? stack[0] : -1;
        if (k == 0) continue;
        bool front = !L->flip[top[c]];
        double shade = 1.0 - 0.45 * (double)(k - 1) / (double)(kmax > 1 ? kmax - 1 : 1);
        if (front) cairo_set_source_rgb(cr, 0.96 * shade, 0.93 * shade, 0.85 * shade);
        else cairo_set_source_rgb(cr, 0.45 * shade, 0.62 * shade, 0.85 * shade);
        bool first = true;
        for (int64_t i = L->cell_segs.off[c]; i < L->cell_segs.off[c + 1]; ++i) {
            int h = L->cell_segs.items[i];
            double x, y;
            to_px(&fv, L->pts[L->seg_pts[h >> 1][h & 1]], &x, &y);
            if (first) cairo_move_to(cr, x, y);
            else cairo_line_to(cr, x, y);
            first = false;
        }
        cairo_close_path(cr);
        cairo_fill_preserve(cr);
        cairo_set_line_width(cr, 0.4);
        cairo_stroke(cr); // hairline in the fill colour closes anti-aliasing seams
    }
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_set_line_width(cr, 1.2);
    for (int sgm = 0; sgm < L->ns; ++sgm) {
        int a = L->seg_cells[sgm][0], b = L->seg_cells[sgm][1];
        int ta = a >= 0 ? top[a] : -1, tb = b >= 0 ? top[b] : -1;
        if (ta == tb) continue;
        double x, y;
        to_px(&fv, L->pts[L->seg_pts[sgm][0]], &x, &y);
        cairo_move_to(cr, x, y);
        to_px(&fv, L->pts[L->seg_pts[sgm][1]], &x, &y);
        cairo_line_to(cr, x, y);
        cairo_stroke(cr);
    }
    ori__free(stack);
    ori__free(top);
    cairo_destroy(cr);
    cairo_surface_finish(surf);
    cairo_status_t cs = cairo_surface_status(surf);
    cairo_surface_destroy(surf);
    if (cs != CAIRO_STATUS_SUCCESS) {
        ori__free(s.data);
        return ori__fail(error, ORI_ERR_INTERNAL, "drawing failed: %s", cairo_status_to_string(cs));
    }
    // The two captions as SVG text elements, inserted before the closing </svg> (on top of
    // the drawing): Cairo's own text goes through fontconfig, whose caches outlive the call.
    char captions[400];
    int cn = snprintf(captions, sizeof captions,
                      "\n<text x=\"%g\" y=\"%g\" font-family=\"sans-serif\" font-size=\"14\">crease pattern</text>"
                      "\n<text x=\"%g\" y=\"%g\" font-family=\"sans-serif\" font-size=\"14\">flat-folded state %.60s "
                      "(seen from +z)</text>\n",
                      margin, margin + 4, 2 * margin + side, margin + 4, L->state_k ? L->state_k : "0");
    unsigned char nul = 0;
    write_sink(&s, &nul, 0);
    s.data[s.n] = '\0';
    char *close = NULL;
    for (char *q = strstr((char *)s.data, "</svg>"); q; q = strstr(q + 1, "</svg>")) close = q;
    if (!close) {
        ori__free(s.data);
        return ori__fail(error, ORI_ERR_INTERNAL, "drawing failed: no </svg>");
    }
    size_t at = (size_t)(close - (char *)s.data);
    char *text = ori__alloc(s.n + (size_t)cn + 1);
    memcpy(text, s.data, at);
    memcpy(text + at, captions, (size_t)cn);
    memcpy(text + at + cn, s.data + at, s.n - at + 1);
    ori__free(s.data);
    *out = text;
    *size = s.n + (size_t)cn;
    return ORI_OK;
}
