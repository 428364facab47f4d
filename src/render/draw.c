// Drawing with Cairo: the crease view (thesis line styles: mountain dash-dot, valley dashed),
// the 3D view (two-sided colours, directional shading, texture, creases on top, ground grid)
// painted back to front (order.c), and the SVG / PDF / PNG writers into memory or a file.
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <orikin/flat.h>

#include "../io/io_internal.h"
#include "render_internal.h"

// --- colours --------------------------------------------------------------------------------

static const struct {
    const char *name;
    unsigned rgb;
} named_colours[] = {
    {"white", 0xffffff},  {"black", 0x000000},   {"grey", 0x808080},    {"gray", 0x808080},
    {"silver", 0xc0c0c0}, {"red", 0xff0000},     {"green", 0x008000},   {"blue", 0x0000ff},
    {"yellow", 0xffff00}, {"orange", 0xffa500},  {"purple", 0x800080},  {"pink", 0xffc0cb},
    {"brown", 0xa52a2a},  {"cyan", 0x00ffff},    {"magenta", 0xff00ff}, {"navy", 0x000080},
    {"teal", 0x008080},   {"olive", 0x808000},   {"maroon", 0x800000},  {"gold", 0xffd700},
    {"ivory", 0xfffff0},  {"beige", 0xf5f5dc},   {"tan", 0xd2b48c},     {"salmon", 0xfa8072},
    {"coral", 0xff7f50},  {"skyblue", 0x87ceeb}, {"lightblue", 0xadd8e6},
};

static ori_rgb rgb_of(unsigned x)
{
    ori_rgb c = {((x >> 16) & 255) / 255.0, ((x >> 8) & 255) / 255.0, (x & 255) / 255.0};
    return c;
}

static int hexval(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    c = (char)tolower((unsigned char)c);
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

bool ori_rgb_parse(const char *text, ori_rgb *out)
{
    if (!text || !out) return false;
    size_t n = strlen(text);
    if (text[0] == '#' && (n == 4 || n == 7)) {
        unsigned x = 0;
        for (size_t i = 1; i < n; ++i) {
            int h = hexval(text[i]);
            if (h < 0) return false;
            x = x * 16 + (unsigned)h;
            if (n == 4) x = x * 16 + (unsigned)h; // #abc = #aabbcc
        }
        *out = rgb_of(x);
        return true;
    }
    for (size_t i = 0; i < sizeof named_colours / sizeof named_colours[0]; ++i) {
        const char *a = named_colours[i].name, *b = text;
        while (*a && tolower((unsigned char)*b) == *a) {
            a++;
            b++;
        }
        if (!*a && !*b) {
            *out = rgb_of(named_colours[i].rgb);
            return true;
        }
    }
    return false;
}

// --- formats and defaults -------------------------------------------------------------------

ori_image_format ori_image_format_from_path(const char *path)
{
    const ori_format_info *f = ori_format_find(path, ORI_FORMAT_KIND_IMAGE);
    return f ? (ori_image_format)f->code : ORI_IMAGE_UNKNOWN;
}

const char *ori_image_format_name(ori_image_format f) { return ori__format_name(ORI_FORMAT_KIND_IMAGE, (int)f); }

ori_render_def ori_default_render_def(void)
{
    ori_render_def d;
    memset(&d, 0, sizeof d);
    d.view = ORI_RENDER_CREASES;
    d.format = ORI_IMAGE_PNG;
    d.width = 800;
    d.height = 600;
    d.camera = ori_camera_preset(ORI_CAMERA_ISO, 0.0, 0.0, 0.0);
    d.fit_camera = true;
    d.front = rgb_of(0xe8a33d);
    d.back = rgb_of(0xf3efe4);
    d.background = rgb_of(0xffffff);
    d.shading = true;
    d.all_edges = false;
    d.grid = false;
    d.labels = false;
    d.mark_failing = true;
    d.texture_png = NULL;
    d.texture_size = 0;
    d.values = (ori_value_map){NULL, NULL, 0.0, 1.0};
    d.line_width_rel = 1.0 / 400.0;
    d.internal_value = ORI__DEF_COOKIE;
    return d;
}

ori_status ori__render_check_size(const ori_render_def *def, ori_error *error)
{
    if (def->width < 1 || def->height < 1 || def->width > ORI_RENDER_MAX_SIZE || def->height > ORI_RENDER_MAX_SIZE)
        return ori__fail(error, ORI_ERR_ARGUMENT, "image size %dx%d is outside 1 to %d", def->width, def->height,
                         ORI_RENDER_MAX_SIZE);
    if (!(def->line_width_rel >= 0.0) || !isfinite(def->line_width_rel))
        return ori__fail(error, ORI_ERR_ARGUMENT, "line width must be a finite number >= 0");
    // A camera from a NaN or infinite turn (ori_camera_preset with yaw NaN) puts every point at
    // NaN: refused here, not drawn (fuzz_python: render(yaw_rad=nan) reached undefined behaviour
    // in the depth order's grid).
    const ori_camera *c = &def->camera;
    bool finite = isfinite(c->target.x) && isfinite(c->target.y) && isfinite(c->target.z) && isfinite(c->cx) &&
                  isfinite(c->cy) && isfinite(c->scale) && isfinite(c->distance);
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) finite = finite && isfinite(c->rotation.m[i][k]);
    if (!finite) return ori__fail(error, ORI_ERR_ARGUMENT, "camera: its rotation, target, scale and distance must be finite");
    return ORI_OK;
}

// --- textures -------------------------------------------------------------------------------

typedef struct read_ctx {
    const unsigned char *data;
    size_t size, at;
} read_ctx;

static cairo_status_t read_mem(void *closure, unsigned char *out, unsigned int length)
{
    read_ctx *r = closure;
    if (r->size - r->at < length) return CAIRO_STATUS_READ_ERROR;
    memcpy(out, r->data + r->at, length);
    r->at += length;
    return CAIRO_STATUS_SUCCESS;
}

ori_status ori__texture_load(const ori_render_def *def, cairo_surface_t **out, ori_error *error)
{
    *out = NULL;
    if (!def->texture_png) return ORI_OK;
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (def->texture_size < 8 || memcmp(def->texture_png, sig, 8) != 0)
        return ori__fail(error, ORI_ERR_PARSE, "the texture is not a PNG image");
    read_ctx r = {def->texture_png, def->texture_size, 0};
    cairo_surface_t *s = cairo_image_surface_create_from_png_stream(read_mem, &r);
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS || cairo_image_surface_get_width(s) < 1 ||
        cairo_image_surface_get_height(s) < 1) {
        cairo_surface_destroy(s);
        return ori__fail(error, ORI_ERR_PARSE, "the texture is not a readable PNG image");
    }
    *out = s;
    return ORI_OK;
}

// --- the crease view ------------------------------------------------------------------------

typedef struct line_style {
    ori_rgb colour;
    double width;      // in line widths
    double dash[4];    // in line widths; count 0 = solid
    int dash_count;
    bool round;        // round caps (dots)
} line_style;

static line_style crease_style(ori_assignment a)
{
    line_style s;
    memset(&s, 0, sizeof s);
    s.width = 1.0;
    switch (a) {
    case ORI_ASSIGN_MOUNTAIN: // dash-dot (thesis ch. 7)
        s.colour = rgb_of(0xd7191c);
        s.dash[0] = 6.0;
        s.dash[1] = 2.0;
        s.dash[2] = 1.0;
        s.dash[3] = 2.0;
        s.dash_count = 4;
        break;
    case ORI_ASSIGN_VALLEY: // dashed
        s.colour = rgb_of(0x1f5fd6);
        s.dash[0] = 5.0;
        s.dash[1] = 3.0;
        s.dash_count = 2;
        break;
    case ORI_ASSIGN_BOUNDARY:
        s.colour = rgb_of(0x000000);
        s.width = 1.5;
        break;
    case ORI_ASSIGN_FLAT:
        s.colour = rgb_of(0x9a9a9a);
        s.width = 0.7;
        break;
    case ORI_ASSIGN_UNASSIGNED: // dotted purple
        s.colour = rgb_of(0x8e44ad);
        s.dash[0] = 0.0;
        s.dash[1] = 2.5;
        s.dash_count = 2;
        s.round = true;
        s.width = 1.3;
        break;
    case ORI_ASSIGN_CUT:
        s.colour = rgb_of(0x1a9641);
        s.width = 1.5;
        break;
    case ORI_ASSIGN_JOIN: // long dashes, light grey
    default:
        s.colour = rgb_of(0xb8b8b8);
        s.width = 0.7;
        s.dash[0] = 8.0;
        s.dash[1] = 3.0;
        s.dash_count = 2;
        break;
    }
    return s;
}

static void set_source(cairo_t *cr, ori_rgb c) { cairo_set_source_rgb(cr, c.r, c.g, c.b); }

static void apply_style(cairo_t *cr, const line_style *s, double lw)
{
    set_source(cr, s->colour);
    cairo_set_line_width(cr, s->width * lw);
    cairo_set_line_cap(cr, s->round ? CAIRO_LINE_CAP_ROUND : CAIRO_LINE_CAP_BUTT);
    double d[4];
    for (int i = 0; i < s->dash_count; ++i) d[i] = s->dash[i] * lw;
    cairo_set_dash(cr, d, s->dash_count, 0.0);
}

// Line width: a fraction of the image, but at most LINE_PER_EDGE of the mean edge length in the
// image, so that a dense pattern is not buried under its lines.
#define LINE_PER_EDGE (1.0 / 12.0)
#define LINE_MIN 0.25
static double line_width_of(const ori_render_def *def, double mean_edge)
{
    double lw = fmax(0.75, def->line_width_rel * fmin(def->width, def->height));
    if (mean_edge > 0.0) lw = fmin(lw, fmax(LINE_MIN, LINE_PER_EDGE * mean_edge));
    return lw;
}

// Labels are drawn with a small built-in stroke font (digits, v, f, -): vector paths that look
// the same on every machine, with no dependency on the system's fonts. Each glyph is polylines
// in a box 0.5 wide and 1 high (y up), a point (-1, -1) ending a polyline; the entries after the
// last one are padding (zeros), never drawn.
typedef struct glyph {
    char c;
    float pts[24][2];
} glyph;

static const glyph glyphs[] = {
    {'0', {{0, 0}, {0.5f, 0}, {0.5f, 1}, {0, 1}, {0, 0}, {-1, -1}}},
    {'1', {{0.1f, 0.8f}, {0.25f, 1}, {0.25f, 0}, {-1, -1}, {0.05f, 0}, {0.45f, 0}, {-1, -1}}},
    {'2', {{0, 1}, {0.5f, 1}, {0.5f, 0.5f}, {0, 0.5f}, {0, 0}, {0.5f, 0}, {-1, -1}}},
    {'3', {{0, 1}, {0.5f, 1}, {0.5f, 0}, {0, 0}, {-1, -1}, {0.1f, 0.5f}, {0.5f, 0.5f}, {-1, -1}}},
    {'4', {{0, 1}, {0, 0.5f}, {0.5f, 0.5f}, {-1, -1}, {0.5f, 1}, {0.5f, 0}, {-1, -1}}},
    {'5', {{0.5f, 1}, {0, 1}, {0, 0.5f}, {0.5f, 0.5f}, {0.5f, 0}, {0, 0}, {-1, -1}}},
    {'6', {{0.5f, 1}, {0, 1}, {0, 0}, {0.5f, 0}, {0.5f, 0.5f}, {0, 0.5f}, {-1, -1}}},
    {'7', {{0, 1}, {0.5f, 1}, {0.2f, 0}, {-1, -1}}},
    {'8', {{0, 0}, {0.5f, 0}, {0.5f, 1}, {0, 1}, {0, 0}, {-1, -1}, {0, 0.5f}, {0.5f, 0.5f}, {-1, -1}}},
    {'9', {{0.5f, 0.5f}, {0, 0.5f}, {0, 1}, {0.5f, 1}, {0.5f, 0}, {0, 0}, {-1, -1}}},
    {'v', {{0, 0.6f}, {0.25f, 0}, {0.5f, 0.6f}, {-1, -1}}},
    {'f', {{0.45f, 1}, {0.2f, 1}, {0.2f, 0}, {-1, -1}, {0, 0.6f}, {0.4f, 0.6f}, {-1, -1}}},
    {'-', {{0.05f, 0.5f}, {0.45f, 0.5f}, {-1, -1}}},
    {'+', {{0.05f, 0.5f}, {0.45f, 0.5f}, {-1, -1}, {0.25f, 0.3f}, {0.25f, 0.7f}, {-1, -1}}},
    {'.', {{0.2f, 0}, {0.3f, 0}, {0.3f, 0.1f}, {0.2f, 0.1f}, {0.2f, 0}, {-1, -1}}},
    {'e', {{0, 0.3f}, {0.5f, 0.3f}, {0.5f, 0.6f}, {0, 0.6f}, {0, 0}, {0.5f, 0}, {-1, -1}}},
};

static const glyph *glyph_of(char c)
{
    for (size_t i = 0; i < sizeof glyphs / sizeof glyphs[0]; ++i)
        if (glyphs[i].c == c) return &glyphs[i];
    return NULL;
}

// The label's strokes as one path, centred on (x, y), glyphs `size` high.
static void label_path(cairo_t *cr, double x, double y, const char *text, double size)
{
    size_t n = strlen(text);
    double advance = 0.8 * size, width = n ? (double)(n - 1) * advance + 0.5 * size : 0.0;
    double x0 = x - 0.5 * width, y0 = y + 0.5 * size;
    for (size_t i = 0; i < n; ++i) {
        const glyph *g = glyph_of(text[i]);
        if (!g) continue;
        int end = 23; // the last polyline's end: the zeros after it are padding (drawn, they were a
        while (end > 0 && g->pts[end][0] >= 0) end--; // stray dot at the glyph's corner)
        bool pen = false;
        for (int k = 0; k <= end; ++k) {
            if (g->pts[k][0] < 0) {
                pen = false;
                continue;
            }
            double px = x0 + i * advance + g->pts[k][0] * size, py = y0 - g->pts[k][1] * size;
            if (pen) cairo_line_to(cr, px, py);
            else cairo_move_to(cr, px, py);
            pen = true;
        }
    }
}

static void draw_label(cairo_t *cr, double x, double y, const char *text, ori_rgb colour, double size)
{
    cairo_set_dash(cr, NULL, 0, 0);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    // A white halo keeps the number readable over lines.
    label_path(cr, x, y, text, size);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_set_line_width(cr, 0.42 * size);
    cairo_stroke_preserve(cr);
    set_source(cr, colour);
    cairo_set_line_width(cr, 0.14 * size);
    cairo_stroke(cr);
}

// --- colour by value: the colour bar -------------------------------------------------------

// The bar's label size: glyphs this high (image units).
static double bar_font(const ori_render_def *def) { return fmax(6.0, 0.024 * fmin(def->width, def->height)); }

// Width of the strip on the right that the colour bar takes (0 without values): the bar, its
// ticks and labels of up to 9 characters ("-1.23e-05"). At most a third of the image.
static double bar_strip(const ori_render_def *def)
{
    if (!ori__value_map_active(&def->values)) return 0.0;
    double fs = bar_font(def);
    return fmin(def->width / 3.0, 11.0 * fs);
}

// Width of an edge painted by its value, in line widths (wider than a crease, to show its colour).
#define VALUE_LINE_WIDTH 2.5

static ori_rgb value_colour(const ori_value_map *map, double v) { return ori_colormap(ori_value_map_position(map, v)); }

// The colour bar in the strip: min at the bottom, max at the top, a gradient through the colour
// Face f of a flat pattern as a closed path, at (ox + s x, oy − s y); *fv (capacity *cap) is scratch.
static void face_path(cairo_t *cr, const ori_pattern *p, int f, double ox, double oy, double s, int **fv, int *cap)
{
    int n = ori_pattern_face_size(p, f);
    ORI__RESERVE(*fv, *cap, n);
    ori_pattern_face_vertices(p, f, *fv, n);
    for (int k = 0; k < n; ++k) {
        ori_v3 q = ori_pattern_vertex(p, (*fv)[k]);
        if (k == 0) cairo_move_to(cr, ox + s * q.x, oy - s * q.y);
        else cairo_line_to(cr, ox + s * q.x, oy - s * q.y);
    }
    cairo_close_path(cr);
}

// map (true vector in SVG and PDF), a thin frame, ticks and their labels on the right.
static void draw_bar(cairo_t *cr, const ori_render_def *def)
{
    double fs = bar_font(def), W = def->width, H = def->height;
    double x0 = W - bar_strip(def) + 0.6 * fs, bw = 1.2 * fs;
    double y_top = 0.12 * H, y_bot = 0.88 * H;
    cairo_pattern_t *g = cairo_pattern_create_linear(0.0, y_bot, 0.0, y_top);
    enum { STOPS = 33 };
    for (int k = 0; k < STOPS; ++k) {
        double t = (double)k / (STOPS - 1);
        ori_rgb c = ori_colormap(t);
        cairo_pattern_add_color_stop_rgb(g, t, c.r, c.g, c.b);
    }
    cairo_rectangle(cr, x0, y_top, bw, y_bot - y_top);
    cairo_set_source(cr, g);
    cairo_fill(cr);
    cairo_pattern_destroy(g);
    cairo_set_dash(cr, NULL, 0, 0);
    cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
    cairo_set_line_width(cr, fmax(0.5, 0.06 * fs));
    cairo_rectangle(cr, x0, y_top, bw, y_bot - y_top);
    cairo_stroke(cr);
    double values[ORI_RENDER_BAR_TICKS];
    char labels[ORI_RENDER_BAR_TICKS][ORI_RENDER_BAR_LABEL_MAX];
    int n = ori_value_map_ticks(&def->values, values, labels);
    for (int k = 0; k < n; ++k) {
        double y = n == 1 ? y_bot : y_bot - (y_bot - y_top) * k / (n - 1);
        cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
        cairo_set_line_width(cr, fmax(0.5, 0.06 * fs));
        cairo_move_to(cr, x0 + bw, y);
        cairo_line_to(cr, x0 + bw + 0.35 * fs, y);
        cairo_stroke(cr);
        size_t len = strlen(labels[k]);
        double width = (double)(len - 1) * 0.8 * fs + 0.5 * fs;
        draw_label(cr, x0 + bw + 0.9 * fs + 0.5 * width, y, labels[k], rgb_of(0x202020), fs);
    }
}

static ori_status draw_creases(cairo_t *cr, const ori_pattern *p, const ori_render_def *def, ori_error *error)
{
    if (ori_pattern_is_folded_form(p) || ori_pattern_is_3d(p))
        return ori__fail(error, ORI_ERR_UNSUPPORTED, "the crease view needs a flat crease pattern, not a folded form");
    int nv = ori_pattern_vertex_count(p), ne = ori_pattern_edge_count(p), nf = ori_pattern_face_count(p);
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (int v = 0; v < nv; ++v) {
        ori_v3 q = ori_pattern_vertex(p, v);
        x0 = fmin(x0, q.x);
        x1 = fmax(x1, q.x);
        y0 = fmin(y0, q.y);
        y1 = fmax(y1, q.y);
    }
    if (nv == 0) x0 = x1 = y0 = y1 = 0.0;
    // With a colour bar the pattern is fitted to the image left of its strip.
    double W = def->width - bar_strip(def), H = def->height, margin = 0.06 * fmin(W, H);
    double dx = x1 - x0, dy = y1 - y0;
    double s = (dx > 0.0 && dy > 0.0) ? fmin((W - 2 * margin) / dx, (H - 2 * margin) / dy)
               : dx > 0.0             ? (W - 2 * margin) / dx
               : dy > 0.0             ? (H - 2 * margin) / dy
                                      : 1.0;
    double ox = 0.5 * W - s * 0.5 * (x0 + x1), oy = 0.5 * H + s * 0.5 * (y0 + y1);
#define IX(q) (ox + s * (q).x)
#define IY(q) (oy - s * (q).y)
    double mean = 0.0;
    for (int e = 0; e < ne; ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        mean += s * ori_v3_norm(ori_v3_sub(ori_pattern_vertex(p, ed.v[1]), ori_pattern_vertex(p, ed.v[0])));
    }
    double lw = line_width_of(def, ne ? mean / ne : 0.0);
    set_source(cr, def->background);
    cairo_paint(cr);
    // The paper.
    int *fv = NULL, cap = 0;
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    for (int f = 0; f < nf; ++f) {
        face_path(cr, p, f, ox, oy, s, &fv, &cap);
    }
    cairo_set_source_rgb(cr, 0.985, 0.978, 0.955);
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
    cairo_fill(cr);
    const ori_value_map *vm = &def->values;
    if (vm->face_values) {
        // Faces with a value in its colour (with a seam hairline, as in 3D).
        for (int f = 0; f < nf; ++f) {
            if (isnan(vm->face_values[f])) continue;
            face_path(cr, p, f, ox, oy, s, &fv, &cap);
            set_source(cr, value_colour(vm, vm->face_values[f]));
            cairo_fill_preserve(cr);
            cairo_set_line_width(cr, ORI_RENDER_SEAM_WIDTH);
            cairo_stroke(cr);
        }
    }
    // Lines: faint kinds first, the boundary last; edges with a value after them, solid in its colour.
    static const ori_assignment order[] = {ORI_ASSIGN_JOIN,     ORI_ASSIGN_FLAT,   ORI_ASSIGN_UNASSIGNED, ORI_ASSIGN_CUT,
                                           ORI_ASSIGN_VALLEY,   ORI_ASSIGN_MOUNTAIN, ORI_ASSIGN_BOUNDARY};
    for (size_t k = 0; k < sizeof order / sizeof order[0]; ++k) {
        line_style st = crease_style(order[k]);
        apply_style(cr, &st, lw);
        for (int e = 0; e < ne; ++e) {
            ori_edge ed = ori_pattern_edge(p, e);
            if (ed.assignment != order[k]) continue;
            if (vm->edge_values && !isnan(vm->edge_values[e])) continue;
            ori_v3 a = ori_pattern_vertex(p, ed.v[0]), b = ori_pattern_vertex(p, ed.v[1]);
            // Dashes start afresh on every crease, as a drawn crease pattern does.
            cairo_move_to(cr, IX(a), IY(a));
            cairo_line_to(cr, IX(b), IY(b));
            if (st.dash_count) cairo_stroke(cr);
        }
        if (!st.dash_count) cairo_stroke(cr);
    }
    cairo_set_dash(cr, NULL, 0, 0);
    if (vm->edge_values) {
        cairo_set_line_width(cr, VALUE_LINE_WIDTH * lw);
        cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
        for (int e = 0; e < ne; ++e) {
            if (isnan(vm->edge_values[e])) continue;
            ori_edge ed = ori_pattern_edge(p, e);
            ori_v3 a = ori_pattern_vertex(p, ed.v[0]), b = ori_pattern_vertex(p, ed.v[1]);
            set_source(cr, value_colour(vm, vm->edge_values[e]));
            cairo_move_to(cr, IX(a), IY(a));
            cairo_line_to(cr, IX(b), IY(b));
            cairo_stroke(cr);
        }
    }
    if (def->mark_failing) {
        ori_flat_report *r = ori_flat_check_pattern(p, NULL);
        cairo_set_source_rgb(cr, 1.0, 0.45, 0.0);
        cairo_set_line_width(cr, 1.5 * lw);
        for (int i = 0; i < ori_flat_report_vertex_count(r); ++i) {
            ori_vertex_report vr = ori_flat_report_vertex(r, i);
            if (vr.flat_foldable) continue;
            ori_v3 q = ori_pattern_vertex(p, vr.vertex);
            cairo_new_sub_path(cr);
            cairo_arc(cr, IX(q), IY(q), 5.0 * lw, 0.0, 2.0 * ORI_PI);
        }
        cairo_stroke(cr);
        ori_flat_report_destroy(r);
    }
    if (def->labels) {
        double fs = fmax(6.0, 0.018 * fmin(W, H));
        char buf[32];
        for (int f = 0; f < nf; ++f) {
            int n = ori_pattern_face_size(p, f);
            ORI__RESERVE(fv, cap, n);
            ori_pattern_face_vertices(p, f, fv, n);
            // Label at the centroid of the face's area.
            double ax = 0, ay = 0, a2 = 0;
            for (int k = 0; k < n; ++k) {
                ori_v3 u = ori_pattern_vertex(p, fv[k]), w = ori_pattern_vertex(p, fv[(k + 1) % n]);
                double c = u.x * w.y - w.x * u.y;
                a2 += c;
                ax += (u.x + w.x) * c;
                ay += (u.y + w.y) * c;
            }
            if (a2 == 0.0) continue;
            ori_v3 ctr = ori_v3_make(ax / (3 * a2), ay / (3 * a2), 0);
            snprintf(buf, sizeof buf, "f%d", f);
            draw_label(cr, IX(ctr), IY(ctr), buf, rgb_of(0x6b6b6b), fs * 1.1);
        }
        for (int e = 0; e < ne; ++e) {
            ori_edge ed = ori_pattern_edge(p, e);
            ori_v3 a = ori_pattern_vertex(p, ed.v[0]), b = ori_pattern_vertex(p, ed.v[1]);
            ori_v3 mid = ori_v3_scale(ori_v3_add(a, b), 0.5);
            snprintf(buf, sizeof buf, "%d", e);
            line_style st = crease_style(ed.assignment);
            draw_label(cr, IX(mid), IY(mid), buf, st.colour, fs);
        }
        for (int v = 0; v < nv; ++v) {
            ori_v3 q = ori_pattern_vertex(p, v);
            snprintf(buf, sizeof buf, "v%d", v);
            draw_label(cr, IX(q) + 0.9 * fs, IY(q) - 0.8 * fs, buf, rgb_of(0x202020), fs);
        }
    }
#undef IX
#undef IY
    ori__free(fv);
    if (ori__value_map_active(vm)) draw_bar(cr, def);
    return ORI_OK;
}

// --- the 3D view ----------------------------------------------------------------------------

// The ground grid: a square of nice spacing around the box lo–hi, in the plane z = lo.z.
typedef struct grid_box {
    double x0, x1, y0, y1, z, step;
} grid_box;

static grid_box grid_of(ori_v3 lo, ori_v3 hi)
{
    grid_box g;
    double ext = fmax(hi.x - lo.x, hi.y - lo.y);
    if (!(ext > 0.0)) ext = fmax(hi.z - lo.z, 1.0);
    double raw = ext / 8.0, p = pow(10.0, floor(log10(raw))), k = raw / p;
    g.step = p * (k < 1.5 ? 1.0 : k < 3.5 ? 2.0 : k < 7.5 ? 5.0 : 10.0);
    double pad = 0.15 * ext;
    g.x0 = floor((lo.x - pad) / g.step) * g.step;
    g.x1 = ceil((hi.x + pad) / g.step) * g.step;
    g.y0 = floor((lo.y - pad) / g.step) * g.step;
    g.y1 = ceil((hi.y + pad) / g.step) * g.step;
    g.z = lo.z;
    return g;
}

int ori__render_scene_points(const ori_mesh *m, const ori_render_def *def, const ori_v3 *scene_lo,
                             const ori_v3 *scene_hi, ori_v3 *out)
{
    memcpy(out, m->pos, sizeof(ori_v3) * (size_t)m->vertex_count);
    int n = m->vertex_count;
    if (def->grid) {
        ori_v3 lo, hi;
        ori_mesh_bounds(m, &lo, &hi);
        grid_box g = grid_of(scene_lo ? *scene_lo : lo, scene_hi ? *scene_hi : hi);
        out[n++] = ori_v3_make(g.x0, g.y0, g.z);
        out[n++] = ori_v3_make(g.x1, g.y0, g.z);
        out[n++] = ori_v3_make(g.x0, g.y1, g.z);
        out[n++] = ori_v3_make(g.x1, g.y1, g.z);
    }
    return n;
}

ori_camera ori__render_fit(const ori_render_def *def, const ori_v3 *points, int count)
{
    ori_camera c = def->camera;
    // With a colour bar the sheet is fitted to the image left of its strip.
    int w = def->width - (int)ceil(bar_strip(def));
    if (def->fit_camera) ori_camera_fit(&c, points, count, w < 1 ? 1 : w, def->height, 0.05);
    return c;
}

static void draw_grid(cairo_t *cr, const ori_camera *cam, grid_box g, double lw)
{
    cairo_set_source_rgb(cr, 0.80, 0.81, 0.83);
    cairo_set_line_width(cr, 0.6 * lw);
    cairo_set_dash(cr, NULL, 0, 0);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    int nx = (int)lround((g.x1 - g.x0) / g.step), ny = (int)lround((g.y1 - g.y0) / g.step);
    for (int i = 0; i <= nx; ++i) {
        double x = g.x0 + i * g.step;
        ori_v3 a = ori_camera_project(cam, ori_v3_make(x, g.y0, g.z)), b = ori_camera_project(cam, ori_v3_make(x, g.y1, g.z));
        if (cam->perspective && !(a.z > 0.0 && b.z > 0.0)) continue;
        cairo_move_to(cr, a.x, a.y);
        cairo_line_to(cr, b.x, b.y);
    }
    for (int j = 0; j <= ny; ++j) {
        double y = g.y0 + j * g.step;
        ori_v3 a = ori_camera_project(cam, ori_v3_make(g.x0, y, g.z)), b = ori_camera_project(cam, ori_v3_make(g.x1, y, g.z));
        if (cam->perspective && !(a.z > 0.0 && b.z > 0.0)) continue;
        cairo_move_to(cr, a.x, a.y);
        cairo_line_to(cr, b.x, b.y);
    }
    cairo_stroke(cr);
}

// Light for the 3D view, in view coordinates (x right, y up, z towards the viewer): from the
// upper left, in front. A side lit head-on gets AMBIENT + DIFFUSE · n·l.
static ori_v3 light_dir(void) { return ori_v3_normalize(ori_v3_make(ORI_RENDER_LIGHT_X, ORI_RENDER_LIGHT_Y, ORI_RENDER_LIGHT_Z)); }

// Which side of a face the eye sees, and the light on it.
static bool front_visible(const ori_mesh *m, const ori_camera *cam, int face, ori_v3 *n_view)
{
    ori_v3 n = ori_m3_apply(cam->rotation, m->normal[face]);
    *n_view = n;
    if (!cam->perspective) return n.z >= 0.0;
    ori_v3 p = ori_m3_apply(cam->rotation, ori_v3_sub(m->pos[m->face_verts[m->face_start[face]]], cam->target));
    return ori_v3_dot(n, ori_v3_sub(ori_v3_make(0, 0, cam->distance), p)) >= 0.0;
}

// Image → flat-sheet affine map of a face from its largest triangle in the image (exact for an
// orthographic camera; with perspective the texture is mapped affinely per triangle).
static bool image_to_flat(const ori_mesh *m, const ori_camera *cam, int t, cairo_matrix_t *out)
{
    ori_v3 a = ori_camera_project(cam, m->pos[m->tris[t].v[0]]);
    ori_v3 b = ori_camera_project(cam, m->pos[m->tris[t].v[1]]);
    ori_v3 c = ori_camera_project(cam, m->pos[m->tris[t].v[2]]);
    ori_v3 fa = m->ref[m->tris[t].v[0]], fb = m->ref[m->tris[t].v[1]], fc = m->ref[m->tris[t].v[2]];
    // flat → image: [b−a, c−a] maps [fb−fa, fc−fa]; build both affine maps and invert one.
    cairo_matrix_t img = {b.x - a.x, b.y - a.y, c.x - a.x, c.y - a.y, a.x, a.y};
    cairo_matrix_t flat = {fb.x - fa.x, fb.y - fa.y, fc.x - fa.x, fc.y - fa.y, fa.x, fa.y};
    if (cairo_matrix_invert(&img) != CAIRO_STATUS_SUCCESS) return false;
    // image → barycentric (img⁻¹), barycentric → flat (flat).
    cairo_matrix_multiply(out, &img, &flat);
    return true;
}

typedef struct tex_map {
    cairo_surface_t *surface;
    double fx0, fy0, fx1, fy1; // the flat sheet's box, stretched over the image
    int w, h;
} tex_map;

static void paint_texture(cairo_t *cr, const tex_map *tx, const cairo_matrix_t *image_to_flat_m)
{
    // flat → texture pixels (y down in the image).
    double dx = tx->fx1 - tx->fx0, dy = tx->fy1 - tx->fy0;
    cairo_matrix_t to_tex = {tx->w / dx, 0, 0, -tx->h / dy, -tx->fx0 * tx->w / dx, tx->fy1 * tx->h / dy};
    cairo_matrix_t m;
    cairo_matrix_multiply(&m, image_to_flat_m, &to_tex);
    cairo_pattern_t *pat = cairo_pattern_create_for_surface(tx->surface);
    cairo_pattern_set_matrix(pat, &m);
    cairo_pattern_set_extend(pat, CAIRO_EXTEND_PAD);
    cairo_pattern_set_filter(pat, CAIRO_FILTER_GOOD);
    cairo_set_source(cr, pat);
    cairo_paint(cr);
    cairo_pattern_destroy(pat);
}

static line_style edge_style_3d(ori_assignment a)
{
    line_style s = crease_style(a);
    s.dash_count = 0;
    s.round = false;
    if (a == ORI_ASSIGN_BOUNDARY) {
        s.colour = rgb_of(0x3a3a3a);
        s.width = 1.0;
    } else if (a == ORI_ASSIGN_FLAT || a == ORI_ASSIGN_JOIN) {
        s.colour = rgb_of(0x8c8c8c);
        s.width = 0.6;
    }
    return s;
}

static bool edge_drawn(const ori_render_def *def, ori_assignment a)
{
    return def->all_edges || (a != ORI_ASSIGN_FLAT && a != ORI_ASSIGN_JOIN);
}

static void path_piece(cairo_t *cr, const ori__order *o, const ori__piece *pc)
{
    for (int k = 0; k < pc->count; ++k) {
        ori_v3 q = o->points[pc->first + k];
        if (k == 0) cairo_move_to(cr, q.x, q.y);
        else cairo_line_to(cr, q.x, q.y);
    }
    cairo_close_path(cr);
}

static void draw_3d(cairo_t *cr, const ori_mesh *m, const ori_render_def *def, const ori_camera *cam,
                    cairo_surface_t *texture, const ori_v3 *scene_lo, const ori_v3 *scene_hi)
{
    double mean = 0.0;
    for (int e = 0; e < m->edge_count; ++e) {
        ori_v3 a = ori_camera_project(cam, m->pos[m->edge_v[e][0]]), b = ori_camera_project(cam, m->pos[m->edge_v[e][1]]);
        mean += hypot(b.x - a.x, b.y - a.y);
    }
    double lw = line_width_of(def, m->edge_count ? mean / m->edge_count : 0.0);
    set_source(cr, def->background);
    cairo_paint(cr);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    if (def->grid) {
        ori_v3 lo, hi;
        ori_mesh_bounds(m, &lo, &hi);
        draw_grid(cr, cam, grid_of(scene_lo ? *scene_lo : lo, scene_hi ? *scene_hi : hi), lw);
    }
    tex_map tx = {texture, 0, 0, 0, 0, 0, 0};
    if (texture) {
        tx.w = cairo_image_surface_get_width(texture);
        tx.h = cairo_image_surface_get_height(texture);
        tx.fx0 = tx.fy0 = INFINITY;
        tx.fx1 = tx.fy1 = -INFINITY;
        for (int v = 0; v < m->vertex_count; ++v) {
            tx.fx0 = fmin(tx.fx0, m->ref[v].x);
            tx.fx1 = fmax(tx.fx1, m->ref[v].x);
            tx.fy0 = fmin(tx.fy0, m->ref[v].y);
            tx.fy1 = fmax(tx.fy1, m->ref[v].y);
        }
        if (!(tx.fx1 > tx.fx0) || !(tx.fy1 > tx.fy0)) tx.surface = NULL;
    }
    ori__order o;
    ori__order_build(m, cam, def->face_orders, def->face_order_count, &o);
    ori_v3 light = light_dir();
    for (int i = 0; i < o.piece_count; ++i) {
        const ori__piece *pc = &o.pieces[i];
        int f = pc->face;
        ori_v3 nv;
        bool front = front_visible(m, cam, f, &nv);
        ori_v3 nvis = front ? nv : ori_v3_scale(nv, -1.0);
        double k = 1.0;
        if (def->shading && ori_v3_norm(nv) > 0.0) k = ORI_RENDER_AMBIENT + ORI_RENDER_DIFFUSE * fmax(0.0, ori_v3_dot(nvis, light));
        ori_rgb c = front ? def->front : def->back;
        // A face with a value shows its colour as it is (no light, no texture): it reads off the bar.
        bool valued = def->values.face_values && !isnan(def->values.face_values[f]);
        if (valued) {
            c = value_colour(&def->values, def->values.face_values[f]);
            k = 1.0;
        }
        c.r *= k;
        c.g *= k;
        c.b *= k;
        path_piece(cr, &o, pc);
        set_source(cr, c);
        if (front && tx.surface && !valued) {
            cairo_fill_preserve(cr);
            cairo_save(cr);
            cairo_clip(cr);
            int t0 = m->face_tri_start[f], t1 = m->face_tri_start[f + 1];
            if (!cam->perspective || pc->count <= 3) {
                // One affine map for the whole face: its largest triangle's.
                int best = -1;
                double area = 0.0;
                for (int t = t0; t < t1; ++t) {
                    ori_v3 a = ori_camera_project(cam, m->pos[m->tris[t].v[0]]);
                    ori_v3 b = ori_camera_project(cam, m->pos[m->tris[t].v[1]]);
                    ori_v3 cc = ori_camera_project(cam, m->pos[m->tris[t].v[2]]);
                    double ar = fabs((b.x - a.x) * (cc.y - a.y) - (b.y - a.y) * (cc.x - a.x));
                    if (ar > area) {
                        area = ar;
                        best = t;
                    }
                }
                cairo_matrix_t mm;
                if (best >= 0 && image_to_flat(m, cam, best, &mm)) paint_texture(cr, &tx, &mm);
            } else {
                for (int t = t0; t < t1; ++t) {
                    cairo_matrix_t mm;
                    if (!image_to_flat(m, cam, t, &mm)) continue;
                    cairo_save(cr);
                    for (int q = 0; q < 3; ++q) {
                        ori_v3 a = ori_camera_project(cam, m->pos[m->tris[t].v[q]]);
                        if (q == 0) cairo_move_to(cr, a.x, a.y);
                        else cairo_line_to(cr, a.x, a.y);
                    }
                    cairo_close_path(cr);
                    cairo_clip(cr);
                    paint_texture(cr, &tx, &mm);
                    cairo_restore(cr);
                }
            }
            if (def->shading && k < 1.0) {
                cairo_set_source_rgba(cr, 0, 0, 0, 1.0 - k);
                cairo_paint(cr);
            }
            cairo_restore(cr);
            cairo_new_path(cr);
        } else {
            // A hairline of the fill colour covers the antialiasing seams between pieces.
            cairo_fill_preserve(cr);
            cairo_set_line_width(cr, ORI_RENDER_SEAM_WIDTH);
            cairo_set_dash(cr, NULL, 0, 0);
            cairo_stroke(cr);
        }
        // The piece's edges, on top of it.
        for (int kk = 0; kk < pc->count; ++kk) {
            int e = o.side_edge[pc->first + kk];
            if (e < 0 || !edge_drawn(def, m->assign[e])) continue;
            line_style st = edge_style_3d(m->assign[e]);
            if (def->values.edge_values && !isnan(def->values.edge_values[e])) {
                st.colour = value_colour(&def->values, def->values.edge_values[e]);
                st.width = VALUE_LINE_WIDTH;
            }
            apply_style(cr, &st, lw);
            cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
            ori_v3 a = o.points[pc->first + kk], b = o.points[pc->first + (kk + 1) % pc->count];
            cairo_move_to(cr, a.x, a.y);
            cairo_line_to(cr, b.x, b.y);
            cairo_stroke(cr);
        }
    }
    ori__order_free(&o);
    if (ori__value_map_active(&def->values)) draw_bar(cr, def);
}

ori_status ori__draw(cairo_t *cr, const ori_mesh *mesh, const ori_pattern *pattern, const ori_render_def *def,
                     const ori_camera *camera, cairo_surface_t *texture, const ori_v3 *scene_lo,
                     const ori_v3 *scene_hi, ori_error *error)
{
    if (def->view == ORI_RENDER_CREASES) return draw_creases(cr, pattern, def, error);
    ori_status st = ori__face_orders_check(mesh, def->face_orders, def->face_order_count, error);
    if (st != ORI_OK) return st;
    draw_3d(cr, mesh, def, camera, texture, scene_lo, scene_hi);
    return ORI_OK;
}

// --- writers --------------------------------------------------------------------------------

typedef struct byte_buf {
    unsigned char *data;
    size_t len, cap;
} byte_buf;

static cairo_status_t write_mem(void *closure, const unsigned char *data, unsigned int length)
{
    byte_buf *b = closure;
    if (b->len + length > b->cap) {
        size_t cap = b->cap ? b->cap : 65536;
        while (cap < b->len + length) cap *= 2;
        b->data = ori__realloc(b->data, cap);
        b->cap = cap;
    }
    memcpy(b->data + b->len, data, length);
    b->len += length;
    return CAIRO_STATUS_SUCCESS;
}

static ori_status cairo_fail(ori_error *error, cairo_status_t s)
{
    return ori__fail(error, s == CAIRO_STATUS_NO_MEMORY ? ORI_ERR_NOMEM : ORI_ERR_INTERNAL, "drawing failed: %s",
                     cairo_status_to_string(s));
}

ori_status ori_render_camera(const ori_state_view *state, const ori_render_def *def, ori_camera *out, ori_error *error)
{
    ORI_ASSERT(state && def && out);
    ORI_ASSERT(def->internal_value == ORI__DEF_COOKIE);
    ori_status st = ori__render_check_size(def, error);
    if (st != ORI_OK) return st;
    ori_mesh *m = NULL;
    st = ori_mesh_create(state, &m, error);
    if (st != ORI_OK) return st;
    ori_v3 *pts = ori__alloc(sizeof(ori_v3) * (size_t)(m->vertex_count + 4));
    int n = ori__render_scene_points(m, def, NULL, NULL, pts);
    *out = ori__render_fit(def, pts, n);
    ori__free(pts);
    ori_mesh_destroy(m);
    return ORI_OK;
}

ori_status ori_render_image(const ori_state_view *state, const ori_render_def *def, void **data, size_t *size,
                            ori_error *error)
{
    ORI_ASSERT(state && state->pattern && def && data && size);
    ORI_ASSERT(def->internal_value == ORI__DEF_COOKIE);
    *data = NULL;
    *size = 0;
    ori_status st = ori__render_check_size(def, error);
    if (st != ORI_OK) return st;
    if (def->format != ORI_IMAGE_SVG && def->format != ORI_IMAGE_PDF && def->format != ORI_IMAGE_PNG)
        return ori__fail(error, ORI_ERR_ARGUMENT, "unknown image format (svg, pdf or png)");
    if (def->view != ORI_RENDER_CREASES && def->view != ORI_RENDER_3D)
        return ori__fail(error, ORI_ERR_ARGUMENT, "unknown view");
    st = ori__value_map_check(&def->values, error);
    if (st != ORI_OK) return st;
    if (def->view == ORI_RENDER_CREASES && (ori_pattern_is_folded_form(state->pattern) || ori_pattern_is_3d(state->pattern)))
        return ori__fail(error, ORI_ERR_UNSUPPORTED, "the crease view needs a flat crease pattern, not a folded form");
    ori_mesh *m = NULL;
    cairo_surface_t *texture = NULL;
    ori_camera cam = def->camera;
    if (def->view == ORI_RENDER_3D) {
        st = ori_mesh_create(state, &m, error);
        if (st != ORI_OK) return st;
        st = ori__face_orders_check(m, def->face_orders, def->face_order_count, error);
        if (st == ORI_OK) st = ori__texture_load(def, &texture, error);
        if (st != ORI_OK) {
            ori_mesh_destroy(m);
            return st;
        }
        ori_v3 *pts = ori__alloc(sizeof(ori_v3) * (size_t)(m->vertex_count + 4));
        int n = ori__render_scene_points(m, def, NULL, NULL, pts);
        cam = ori__render_fit(def, pts, n);
        ori__free(pts);
    }
    byte_buf out = {NULL, 0, 0};
    cairo_surface_t *surface = NULL;
    unsigned char *pixels = NULL;
    if (def->format == ORI_IMAGE_SVG) {
        surface = cairo_svg_surface_create_for_stream(write_mem, &out, def->width, def->height);
    } else if (def->format == ORI_IMAGE_PDF) {
        surface = cairo_pdf_surface_create_for_stream(write_mem, &out, def->width, def->height);
        cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "orikin");
    } else {
        int stride = cairo_format_stride_for_width(CAIRO_FORMAT_ARGB32, def->width);
        pixels = ori__alloc((size_t)stride * (size_t)def->height);
        surface = cairo_image_surface_create_for_data(pixels, CAIRO_FORMAT_ARGB32, def->width, def->height, stride);
    }
    cairo_t *cr = cairo_create(surface);
    st = ori__draw(cr, m, state->pattern, def, &cam, texture, NULL, NULL, error);
    cairo_status_t cs = cairo_status(cr);
    cairo_destroy(cr);
    if (st == ORI_OK && cs != CAIRO_STATUS_SUCCESS) st = cairo_fail(error, cs);
    if (st == ORI_OK && def->format == ORI_IMAGE_PNG) {
        cs = cairo_surface_write_to_png_stream(surface, write_mem, &out);
        if (cs != CAIRO_STATUS_SUCCESS) st = cairo_fail(error, cs);
    }
    cairo_surface_finish(surface);
    cs = cairo_surface_status(surface);
    if (st == ORI_OK && cs != CAIRO_STATUS_SUCCESS) st = cairo_fail(error, cs);
    cairo_surface_destroy(surface);
    ori__free(pixels);
    if (texture) cairo_surface_destroy(texture);
    ori_mesh_destroy(m);
    if (st != ORI_OK) {
        ori__free(out.data);
        return st;
    }
    *data = out.data;
    *size = out.len;
    return ORI_OK;
}

ori_status ori_render_file(const ori_state_view *state, const ori_render_def *def, const char *path,
                           ori_error *error)
{
    ORI_ASSERT(def && path);
    ori_render_def d = *def;
    ori_image_format by_path = ori_image_format_from_path(path);
    if (by_path != ORI_IMAGE_UNKNOWN) d.format = by_path;
    void *data = NULL;
    size_t size = 0;
    ori_status st = ori_render_image(state, &d, &data, &size, error);
    if (st != ORI_OK) return st;
    st = ori_file_write_atomic(path, data, size, error);
    ori__free(data);
    return st;
}
