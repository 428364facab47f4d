// Exporting a flat crease pattern: SVG in the Origami Simulator convention (one <line> per
// edge, colour by assignment, stroke-opacity = |fold angle| / π), and the dispatch by format
// (CP and OPX writers live in oripa.c).
#include <stdio.h>

#include "../pattern/pattern_internal.h"
#include "import_internal.h"
#include "io_internal.h"

ori_svg_write_def ori_default_svg_write_def(void)
{
    ori_svg_write_def def;
    def.stroke_width_rel = 1.0 / 300.0;
    def.margin_rel = 0.05;
    def.full_fold = false;
    def.internal_value = ORI__DEF_COOKIE;
    return def;
}

typedef struct sbuf {
    char *data;
    size_t len, cap;
} sbuf;

static void put(sbuf *b, const char *s)
{
    size_t n = strlen(s);
    if (b->len + n + 1 > b->cap) {
        size_t cap = b->cap ? b->cap : 4096;
        while (cap < b->len + n + 1) cap *= 2;
        b->data = ori__realloc(b->data, cap);
        b->cap = cap;
    }
    memcpy(b->data + b->len, s, n + 1);
    b->len += n;
}

// Shortest decimal that reads back as exactly x (the FOLD writer's formatting).
static const char *fmt(char *buf, size_t size, double x)
{
    ori__format_double(x, buf, size);
    return buf;
}

static const char *stroke_of(ori_assignment a)
{
    switch (a) {
    case ORI_ASSIGN_BOUNDARY: return "#000000";
    case ORI_ASSIGN_MOUNTAIN: return "#ff0000";
    case ORI_ASSIGN_VALLEY: return "#0000ff";
    case ORI_ASSIGN_FLAT: return "#ffff00";
    case ORI_ASSIGN_UNASSIGNED: return "#ff00ff";
    case ORI_ASSIGN_CUT: return "#00ff00";
    default: return NULL; // J: not a line of the drawing
    }
}

char *ori_svg_write(const ori_pattern *p, const ori_svg_write_def *def)
{
    ORI_ASSERT(p);
    ori_svg_write_def defaults = ori_default_svg_write_def();
    if (!def) def = &defaults;
    ORI_ASSERT(def->internal_value == ORI__DEF_COOKIE);
    // Drawing frame: x right, y down (y = −y_fold).
    double minx = 0, maxx = 0, miny = 0, maxy = 0;
    for (int v = 0; v < p->vertex_count; ++v) {
        double x = p->vertices[v].x, y = -p->vertices[v].y;
        if (v == 0 || x < minx) minx = x;
        if (v == 0 || x > maxx) maxx = x;
        if (v == 0 || y < miny) miny = y;
        if (v == 0 || y > maxy) maxy = y;
    }
    double side = fmax(maxx - minx, maxy - miny);
    if (!(side > 0.0)) side = 1.0;
    double margin = def->margin_rel * side, width = def->stroke_width_rel * side;
    char a[40], b[40], c[40], d[40], w[40];
    char head[512];
    snprintf(head, sizeof head,
             "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
             "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"%s %s %s %s\">\n",
             fmt(a, sizeof a, minx - margin), fmt(b, sizeof b, miny - margin),
             fmt(c, sizeof c, maxx - minx + 2 * margin), fmt(d, sizeof d, maxy - miny + 2 * margin));
    sbuf s = {NULL, 0, 0};
    put(&s, head);
    snprintf(head, sizeof head, "<g fill=\"none\" stroke-width=\"%s\" stroke-linecap=\"round\">\n",
             fmt(w, sizeof w, width));
    put(&s, head);
    for (int e = 0; e < p->edge_count; ++e) {
        const ori_edge *ed = &p->edges[e];
        const char *stroke = stroke_of(ed->assignment);
        if (!stroke) continue;
        ori_v3 u = p->vertices[ed->v[0]], v = p->vertices[ed->v[1]];
        char line[320], op[64] = "";
        if (ed->assignment == ORI_ASSIGN_MOUNTAIN || ed->assignment == ORI_ASSIGN_VALLEY) {
            double o = def->full_fold ? 1.0 : fmin(1.0, fabs(ed->fold_angle_rad) / ORI_PI);
            if (o != 1.0) {
                char ob[40];
                snprintf(op, sizeof op, " stroke-opacity=\"%s\"", fmt(ob, sizeof ob, o));
            }
        }
        snprintf(line, sizeof line, "<line x1=\"%s\" y1=\"%s\" x2=\"%s\" y2=\"%s\" stroke=\"%s\"%s/>\n",
                 fmt(a, sizeof a, u.x), fmt(b, sizeof b, -u.y), fmt(c, sizeof c, v.x), fmt(d, sizeof d, -v.y), stroke, op);
        put(&s, line);
    }
    put(&s, "</g>\n</svg>\n");
    return s.data;
}

ori_status ori_export_file(const ori_pattern *p, ori_format format, const ori_svg_write_def *svg_def, const char *path,
                           ori_error *error)
{
    ORI_ASSERT(p && path);
    if (format == ORI_FORMAT_UNKNOWN) format = ori_format_from_path(path);
    if (format != ORI_FORMAT_SVG && format != ORI_FORMAT_CP && format != ORI_FORMAT_OPX)
        return ori__fail(error, ORI_ERR_UNSUPPORTED, "cannot export to a '%s' file", ori_format_name(format));
    if (ori_pattern_is_folded_form(p) || ori_pattern_is_3d(p))
        return ori__fail(error, ORI_ERR_UNSUPPORTED, "%s export needs a flat crease pattern, not a folded form",
                         ori_format_name(format));
    char *text = format == ORI_FORMAT_SVG ? ori_svg_write(p, svg_def)
                 : format == ORI_FORMAT_CP ? ori_cp_write(p)
                                           : ori_opx_write(p);
    ori_status st = ori_file_write_atomic(path, text, strlen(text), error);
    ori__free(text);
    return st;
}
