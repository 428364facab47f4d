// Exporting a flat crease pattern: SVG in the Origami Simulator convention (one <line> per
// edge, colour by assignment, stroke-opacity = |fold angle| / π), optional labels, and the
// dispatch by format (CP and OPX writers live in oripa.c).
#include <orikin/formats.h>

#include <stdio.h>

#include "../pattern/pattern_internal.h"
#include "io_internal.h"

ori_svg_write_def ori_default_svg_write_def(void)
{
    ori_svg_write_def def;
    def.stroke_width_rel = 1.0 / 300.0;
    def.margin_rel = 0.05;
    def.full_fold = false;
    def.label_faces = false;
    def.label_edges = false;
    def.internal_value = ORI__DEF_COOKIE;
    return def;
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

static void put_xy(ori__text *t, const char *xa, double x, const char *ya, double y)
{
    ori__text_printf(t, " %s=\"", xa);
    ori__text_real(t, x);
    ori__text_printf(t, "\" %s=\"", ya);
    ori__text_real(t, y);
    ori__text_puts(t, "\"");
}

// Labels (faces: index and name at the centroid of the face's corners; edges: index at the
// middle) in a group the reader skips, drawn over the creases. Drawing frame: y down.
static void write_labels(ori__text *t, const ori_pattern *p, const ori_svg_write_def *def, double side)
{
    // (a white outline under each label keeps it legible where it sits on a line)
    ori__text_puts(t, "<g id=\"orikin-labels\" font-family=\"sans-serif\" text-anchor=\"middle\" "
                      "dominant-baseline=\"central\" stroke=\"#ffffff\" paint-order=\"stroke\" stroke-linejoin=\"round\" "
                      "stroke-width=\"");
    ori__text_real(t, side / 500.0);
    ori__text_puts(t, "\">\n");
    if (def->label_faces) {
        ori__text_puts(t, "<g fill=\"#404040\" font-size=\"");
        ori__text_real(t, side / 40.0);
        ori__text_puts(t, "\">\n");
        for (int f = 0; f < p->face_count; ++f) {
            double cx = 0.0, cy = 0.0;
            int n = p->face_offsets[f + 1] - p->face_offsets[f];
            for (int k = p->face_offsets[f]; k < p->face_offsets[f + 1]; ++k) {
                cx += p->vertices[p->face_vertices[k]].x;
                cy += p->vertices[p->face_vertices[k]].y;
            }
            ori__text_puts(t, "<text");
            put_xy(t, "x", cx / n, "y", -cy / n);
            ori__text_printf(t, ">%d", f);
            if (p->face_names && p->face_names[f][0]) {
                ori__text_puts(t, " ");
                for (const char *c = p->face_names[f]; *c; ++c) { // (names are plain, but escape anyway)
                    if (*c == '<') ori__text_puts(t, "&lt;");
                    else if (*c == '&') ori__text_puts(t, "&amp;");
                    else ori__text_put(t, c, 1);
                }
            }
            ori__text_puts(t, "</text>\n");
        }
        ori__text_puts(t, "</g>\n");
    }
    if (def->label_edges) {
        ori__text_puts(t, "<g fill=\"#007000\" font-size=\"");
        ori__text_real(t, side / 60.0);
        ori__text_puts(t, "\">\n");
        for (int e = 0; e < p->edge_count; ++e) {
            ori_v3 u = p->vertices[p->edges[e].v[0]], v = p->vertices[p->edges[e].v[1]];
            ori__text_puts(t, "<text");
            put_xy(t, "x", 0.5 * (u.x + v.x), "y", -0.5 * (u.y + v.y));
            ori__text_printf(t, ">%d</text>\n", e);
        }
        ori__text_puts(t, "</g>\n");
    }
    ori__text_puts(t, "</g>\n");
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
    ori__text t = {NULL, 0, 0};
    ori__text_puts(&t, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"");
    ori__text_real(&t, minx - margin);
    ori__text_puts(&t, " ");
    ori__text_real(&t, miny - margin);
    ori__text_puts(&t, " ");
    ori__text_real(&t, maxx - minx + 2 * margin);
    ori__text_puts(&t, " ");
    ori__text_real(&t, maxy - miny + 2 * margin);
    ori__text_puts(&t, "\">\n<g fill=\"none\" stroke-width=\"");
    ori__text_real(&t, width);
    ori__text_puts(&t, "\" stroke-linecap=\"round\">\n");
    static const char *const attr[4] = {"<line x1=\"", "\" y1=\"", "\" x2=\"", "\" y2=\""};
    for (int e = 0; e < p->edge_count; ++e) {
        const ori_edge *ed = &p->edges[e];
        const char *stroke = stroke_of(ed->assignment);
        if (!stroke) continue;
        ori_v3 u = p->vertices[ed->v[0]], v = p->vertices[ed->v[1]];
        double xy[4] = {u.x, -u.y, v.x, -v.y};
        for (int k = 0; k < 4; ++k) {
            ori__text_puts(&t, attr[k]);
            ori__text_real(&t, xy[k]);
        }
        ori__text_printf(&t, "\" stroke=\"%s\"", stroke);
        if (ed->assignment == ORI_ASSIGN_MOUNTAIN || ed->assignment == ORI_ASSIGN_VALLEY) {
            // The fold angle is the crease's target; a crease at 0 (a flat crease pattern, e.g.
            // a generated one) has none and is drawn folded flat, so that it shows.
            double a = fabs(ed->fold_angle_rad);
            double o = def->full_fold || a == 0.0 || a >= ORI_PI ? 1.0 : a / ORI_PI;
            if (o != 1.0) {
                ori__text_puts(&t, " stroke-opacity=\"");
                ori__text_real(&t, o);
                ori__text_puts(&t, "\"");
            }
        }
        ori__text_puts(&t, "/>\n");
    }
    ori__text_puts(&t, "</g>\n");
    if (def->label_faces || def->label_edges) write_labels(&t, p, def, side);
    ori__text_puts(&t, "</svg>\n");
    return t.data;
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
    if (format != ORI_FORMAT_SVG)
        for (int e = 0; e < p->edge_count; ++e) {
            ori_assignment a = p->edges[e].assignment;
            if (a != ORI_ASSIGN_FLAT && a != ORI_ASSIGN_UNASSIGNED) continue;
            int n = ori_pattern_count_assignment(p, a);
            return ori__fail_at(error, ORI_ERR_UNSUPPORTED, "edges_assignment", e,
                                "ORIPA has no %s crease (%d in the pattern): its auxiliary lines are not creases and "
                                "would not come back; assign them M or V (orikin edit --assign %d=M), or export "
                                ".fold or .svg",
                                a == ORI_ASSIGN_FLAT ? "flat (F)" : "unassigned (U)", n, e);
        }
    char *text = format == ORI_FORMAT_SVG ? ori_svg_write(p, svg_def)
                 : format == ORI_FORMAT_CP ? ori_cp_write(p)
                                           : ori_opx_write(p);
    ori_status st = ori_file_write_atomic(path, text, strlen(text), error);
    ori__free(text);
    return st;
}
