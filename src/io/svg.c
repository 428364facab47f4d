// SVG crease patterns in the Origami Simulator convention, read with libxml2's streaming reader
// (no network, no entity substitution, errors captured instead of printed; memory independent
// of the document's size). Geometry: line,
// polyline, polygon, rect and path (M L H V Z, absolute and relative, implicit repeats) under
// nested groups whose transforms compose; style from presentation attributes, simple
// <style> rules (tag, .class, tag.class) and style="" in CSS precedence; stroke colour gives the
// assignment and opacity × stroke-opacity the fold angle.
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <jansson.h>
#include <libxml/xmlreader.h>
#include <stdlib.h>

#include "reader_internal.h"

#define SVG_NS "http://www.w3.org/2000/svg"
#define MAX_DEPTH 256 // nesting beyond this is refused (stack safety)

typedef struct affine {
    double a, b, c, d, e, f; // x' = a x + c y + e, y' = b x + d y + f
} affine;

static affine affine_identity(void) { return (affine){1, 0, 0, 1, 0, 0}; }

static affine affine_mul(affine m, affine n) // m ∘ n: first n, then m
{
    affine r;
    r.a = m.a * n.a + m.c * n.b;
    r.b = m.b * n.a + m.d * n.b;
    r.c = m.a * n.c + m.c * n.d;
    r.d = m.b * n.c + m.d * n.d;
    r.e = m.a * n.e + m.c * n.f + m.e;
    r.f = m.b * n.e + m.d * n.f + m.f;
    return r;
}

// Inherited style state. stroke holds the raw value ("" = none set anywhere).
typedef struct svg_style {
    char stroke[64];
    char color[64];
    double stroke_opacity; // inherited
    double opacity;        // product of the element's and its ancestors' opacity
    double stroke_width;   // inherited, in the element's user units (default 1)
    bool hidden;           // visibility: hidden / collapse (inherited, children may override)
} svg_style;

// The properties orikin reads, as the cascade leaves them. A declaration of a property sets it
// (with the position of its rule in the style sheets, for "later wins"); an opacity that does
// not parse sets nothing.
enum { P_STROKE, P_COLOR, P_STROKE_OPACITY, P_OPACITY, P_DISPLAY, P_VISIBILITY, P_STROKE_WIDTH, P_COUNT };
typedef struct css_props {
    char stroke[64], color[64];
    double stroke_opacity, opacity, stroke_width;
    bool display_none, hidden;
    int order[P_COUNT]; // position of the declaration that set the property, -1 = not set
} css_props;

// The <style> rules merged by selector: one entry per tag (tag rules), per class (.class) and per
// tag.class, so that an element looks up its few entries instead of testing every rule (a style
// sheet of n rules styling n elements costs n, not n²).
typedef struct css_sheet {
    json_t *index; // "t:tag", "c:class", "tc:tag.class" → entry
    css_props *entries;
    int count, cap;
    int next_order;
} css_sheet;

typedef struct svg_ctx {
    ori__seg_list segs;
    ori_import_stats stats;
    double *widths; // stroke width of each crease element, in drawing units
    int width_count, width_cap;
    css_sheet sheet;
    ori__xml_budget budget;
    int curve_segments; // straight pieces per curve, arc, circle or ellipse; 0: they are refused
    ori_error *error;
} svg_ctx;

// --- small string helpers -------------------------------------------------------------------

static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }

static const char *skip_space(const char *s)
{
    while (is_space(*s)) ++s;
    return s;
}

static const char *skip_sep(const char *s) // whitespace and at most one comma
{
    s = skip_space(s);
    if (*s == ',') s = skip_space(s + 1);
    return s;
}

static void trim_copy(char *dst, size_t size, const char *s, size_t n)
{
    while (n > 0 && is_space(*s)) ++s, --n;
    while (n > 0 && is_space(s[n - 1])) --n;
    if (n >= size) n = size - 1;
    memcpy(dst, s, n);
    dst[n] = '\0';
}

static char lower(char c) { return (c >= 'A' && c <= 'Z') ? (char)(c - 'A' + 'a') : c; }

static bool ieq(const char *a, const char *b)
{
    for (; *a && *b; ++a, ++b)
        if (lower(*a) != lower(*b)) return false;
    return *a == *b;
}

static int line_of(const xmlNode *n) { return n ? (int)xmlGetLineNo(n) : 0; }

// An error at element n: "line L: <name>: message".
static ori_status fail(svg_ctx *c, const xmlNode *n, ori_status st, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static ori_status fail(svg_ctx *c, const xmlNode *n, ori_status st, const char *fmt, ...)
{
    char msg[200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    const char *name = n ? (const char *)n->name : "";
    int line = line_of(n);
    if (line > 0) return ori__fail_pos(c->error, st, line, 0, "<%s>: %s", name, msg);
    return ori__fail(c->error, st, "<%s>: %s", name, msg);
}

// --- numbers, lengths, colours --------------------------------------------------------------

// A length attribute: a number with an optional absolute unit (px by default), in user units
// (96 px per inch). Percentages and font-relative units are refused.
static bool parse_length(const char *s, double *out)
{
    s = skip_space(s);
    double v;
    size_t n = ori__scan_number(s, &v);
    if (!n) return false;
    s = skip_space(s + n);
    double k = 1.0;
    if (*s == '\0' || strncmp(s, "px", 2) == 0) k = 1.0, s += *s ? 2 : 0;
    else if (strncmp(s, "mm", 2) == 0) k = 96.0 / 25.4, s += 2;
    else if (strncmp(s, "cm", 2) == 0) k = 96.0 / 2.54, s += 2;
    else if (strncmp(s, "in", 2) == 0) k = 96.0, s += 2;
    else if (strncmp(s, "pt", 2) == 0) k = 96.0 / 72.0, s += 2;
    else if (strncmp(s, "pc", 2) == 0) k = 16.0, s += 2;
    else return false;
    if (*skip_space(s) != '\0') return false;
    *out = v * k;
    return true;
}

// opacity values: a number or a percentage, clamped to [0, 1].
static bool parse_opacity(const char *s, double *out)
{
    s = skip_space(s);
    double v;
    size_t n = ori__scan_number(s, &v);
    if (!n) return false;
    s = skip_space(s + n);
    if (*s == '%') v /= 100.0, s = skip_space(s + 1);
    if (*s != '\0') return false;
    *out = v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v;
    return true;
}

static int hexval(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    c = lower(c);
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

// Assignment of a stroke colour (Origami Simulator): black B, red M, blue V, lime/"green" C,
// yellow F, magenta U. Returns false for any other colour; *none for no stroke at all.
static bool colour_assignment(const char *raw, const char *current, ori_assignment *out, bool *none)
{
    char s[64];
    trim_copy(s, sizeof s, raw, strlen(raw));
    for (char *p = s; *p; ++p) *p = lower(*p);
    *none = s[0] == '\0' || strcmp(s, "none") == 0 || strcmp(s, "transparent") == 0;
    if (*none) return false;
    if (strcmp(s, "currentcolor") == 0) {
        if (!current || !current[0]) return false;
        return colour_assignment(current, NULL, out, none);
    }
    static const struct {
        const char *name;
        unsigned rgb;
    } named[] = {{"black", 0x000000}, {"red", 0xff0000},     {"blue", 0x0000ff},    {"lime", 0x00ff00},
                 {"green", 0x00ff00}, {"yellow", 0xffff00},  {"magenta", 0xff00ff}, {"fuchsia", 0xff00ff}};
    long rgb = -1;
    size_t n = strlen(s);
    if (s[0] == '#' && (n == 4 || n == 7)) {
        unsigned v = 0;
        bool ok = true;
        for (size_t i = 1; i < n && ok; ++i) ok = hexval(s[i]) >= 0;
        if (ok && n == 7)
            for (size_t i = 1; i < 7; ++i) v = v * 16 + (unsigned)hexval(s[i]);
        if (ok && n == 4)
            for (size_t i = 1; i < 4; ++i) v = v * 256 + (unsigned)hexval(s[i]) * 17;
        if (ok) rgb = (long)v;
    } else if (strncmp(s, "rgb(", 4) == 0) {
        const char *p = s + 4;
        unsigned v = 0;
        bool ok = true;
        for (int k = 0; k < 3 && ok; ++k) {
            double x;
            p = skip_space(p);
            size_t m = ori__scan_number(p, &x);
            ok = m > 0;
            p = skip_space(p + m);
            if (ok && *p == '%') x = x * 255.0 / 100.0, p = skip_space(p + 1);
            ok = ok && x >= 0.0 && x <= 255.0 && x == floor(x);
            v = v * 256 + (unsigned)(ok ? x : 0);
            if (k < 2) {
                if (*p != ',') ok = false;
                else p++;
            }
        }
        if (ok && *skip_space(p) == ')') rgb = (long)v;
    } else {
        for (size_t i = 0; i < sizeof named / sizeof named[0]; ++i)
            if (strcmp(s, named[i].name) == 0) rgb = (long)named[i].rgb;
    }
    switch (rgb) {
    case 0x000000: *out = ORI_ASSIGN_BOUNDARY; return true;
    case 0xff0000: *out = ORI_ASSIGN_MOUNTAIN; return true;
    case 0x0000ff: *out = ORI_ASSIGN_VALLEY; return true;
    case 0x00ff00: *out = ORI_ASSIGN_CUT; return true;
    case 0xffff00: *out = ORI_ASSIGN_FLAT; return true;
    case 0xff00ff: *out = ORI_ASSIGN_UNASSIGNED; return true;
    default: return false;
    }
}

// --- style ----------------------------------------------------------------------------------

static void props_clear(css_props *p)
{
    memset(p, 0, sizeof *p);
    for (int k = 0; k < P_COUNT; ++k) p->order[k] = -1;
}

// One declaration into a property set (order: its position; "!important" is dropped).
static void declare(css_props *p, const char *name, const char *value, int order)
{
    char v[64];
    trim_copy(v, sizeof v, value, strlen(value));
    char *bang = strstr(v, "!important");
    if (bang) trim_copy(v, sizeof v, v, (size_t)(bang - v));
    double x;
    int k = -1;
    if (ieq(name, "stroke")) ori__strlcpy(p->stroke, v, sizeof p->stroke), k = P_STROKE;
    else if (ieq(name, "color")) ori__strlcpy(p->color, v, sizeof p->color), k = P_COLOR;
    else if (ieq(name, "stroke-opacity") && parse_opacity(v, &x)) p->stroke_opacity = x, k = P_STROKE_OPACITY;
    else if (ieq(name, "opacity") && parse_opacity(v, &x)) p->opacity = x, k = P_OPACITY;
    else if (ieq(name, "display")) p->display_none = ieq(v, "none"), k = P_DISPLAY;
    else if (ieq(name, "visibility")) p->hidden = ieq(v, "hidden") || ieq(v, "collapse"), k = P_VISIBILITY;
    else if (ieq(name, "stroke-width") && parse_length(v, &x) && x >= 0.0) p->stroke_width = x, k = P_STROKE_WIDTH;
    if (k >= 0) p->order[k] = order;
}

// "a: b; c: d" declarations, each with the given order.
static void declare_all(css_props *p, const char *decls, int order)
{
    const char *q = decls;
    while (*q) {
        const char *end = strchr(q, ';');
        size_t n = end ? (size_t)(end - q) : strlen(q);
        const char *colon = memchr(q, ':', n);
        if (colon) {
            char name[48], value[96];
            trim_copy(name, sizeof name, q, (size_t)(colon - q));
            trim_copy(value, sizeof value, colon + 1, n - (size_t)(colon - q) - 1);
            declare(p, name, value, order);
        }
        q += n;
        if (*q == ';') ++q;
    }
}

// Copy into dst every property src sets later than dst (or all of them with force).
static void props_merge(css_props *dst, const css_props *src, bool force)
{
    for (int k = 0; k < P_COUNT; ++k) {
        if (src->order[k] < 0 || (!force && src->order[k] <= dst->order[k])) continue;
        switch (k) {
        case P_STROKE: memcpy(dst->stroke, src->stroke, sizeof dst->stroke); break;
        case P_COLOR: memcpy(dst->color, src->color, sizeof dst->color); break;
        case P_STROKE_OPACITY: dst->stroke_opacity = src->stroke_opacity; break;
        case P_OPACITY: dst->opacity = src->opacity; break;
        case P_DISPLAY: dst->display_none = src->display_none; break;
        case P_STROKE_WIDTH: dst->stroke_width = src->stroke_width; break;
        default: dst->hidden = src->hidden; break;
        }
        dst->order[k] = src->order[k];
    }
}

static const css_props *sheet_find(const css_sheet *sh, const char *kind, const char *a, const char *b)
{
    if (!sh->index) return NULL;
    char key[160];
    snprintf(key, sizeof key, "%s:%s%s%s", kind, a, b ? "." : "", b ? b : "");
    json_t *v = json_object_get(sh->index, key);
    return v ? &sh->entries[json_integer_value(v)] : NULL;
}

static css_props *sheet_entry(css_sheet *sh, const char *tag, const char *cls)
{
    char key[160];
    snprintf(key, sizeof key, "%s:%s%s%s", !cls[0] ? "t" : !tag[0] ? "c" : "tc", tag[0] ? tag : cls, tag[0] && cls[0] ? "." : "",
             tag[0] && cls[0] ? cls : "");
    if (!sh->index) sh->index = json_object();
    json_t *v = json_object_get(sh->index, key);
    if (v) return &sh->entries[json_integer_value(v)];
    ORI__RESERVE(sh->entries, sh->cap, sh->count + 1);
    props_clear(&sh->entries[sh->count]);
    json_object_set_new(sh->index, key, json_integer(sh->count));
    return &sh->entries[sh->count++];
}

// Apply a property set to the inherited state (opacity sets the element's own, *own).
static void apply_props(svg_style *st, double *own, bool *display_none, const css_props *p)
{
    if (p->order[P_STROKE] >= 0) memcpy(st->stroke, p->stroke, sizeof st->stroke);
    if (p->order[P_COLOR] >= 0) memcpy(st->color, p->color, sizeof st->color);
    if (p->order[P_STROKE_OPACITY] >= 0) st->stroke_opacity = p->stroke_opacity;
    if (p->order[P_OPACITY] >= 0) *own = p->opacity;
    if (p->order[P_DISPLAY] >= 0) *display_none = p->display_none;
    if (p->order[P_VISIBILITY] >= 0) st->hidden = p->hidden;
    if (p->order[P_STROKE_WIDTH] >= 0) st->stroke_width = p->stroke_width;
}

// Presentation attributes, then matching <style> rules (tag rules, then class and tag.class
// rules, file order within each), then style="": the CSS cascade for the properties orikin
// reads. st holds the inherited state on entry and the element's computed state on return
// (opacity multiplied in).
static void element_style(svg_ctx *c, const xmlNode *n, svg_style *st, bool *display_none)
{
    static const char *const names[P_COUNT] = {"stroke",  "color",      "stroke-opacity", "opacity",
                                               "display", "visibility", "stroke-width"};
    *display_none = false;
    double own = 1.0;
    css_props p;
    props_clear(&p);
    for (int k = 0; k < P_COUNT; ++k) {
        char *v = ori__xml_attr(n, names[k], &c->budget);
        if (v) declare(&p, names[k], v, 0);
        ori__free(v);
    }
    apply_props(st, &own, display_none, &p);
    const char *tag = (const char *)n->name;
    const css_props *t = sheet_find(&c->sheet, "t", tag, NULL);
    if (t) apply_props(st, &own, display_none, t);
    char *cls = c->sheet.index ? ori__xml_attr(n, "class", &c->budget) : NULL;
    if (cls) {
        props_clear(&p);
        for (const char *q = cls; *q;) { // each class of the list: .class and tag.class rules
            q = skip_space(q);
            const char *e = q;
            while (*e && !is_space(*e)) ++e;
            char one[64];
            if ((size_t)(e - q) < sizeof one) {
                memcpy(one, q, (size_t)(e - q));
                one[e - q] = '\0';
                const css_props *a = one[0] ? sheet_find(&c->sheet, "c", one, NULL) : NULL;
                const css_props *b = one[0] ? sheet_find(&c->sheet, "tc", tag, one) : NULL;
                if (a) props_merge(&p, a, false);
                if (b) props_merge(&p, b, false);
            }
            q = e;
        }
        apply_props(st, &own, display_none, &p);
        ori__free(cls);
    }
    char *style = ori__xml_attr(n, "style", &c->budget);
    if (style) {
        props_clear(&p);
        declare_all(&p, style, 0);
        apply_props(st, &own, display_none, &p);
        ori__free(style);
    }
    st->opacity *= own;
}

// Collect "selectors { declarations }" rules from a <style> text into the sheet; selectors that
// are not a plain tag, .class or tag.class (and @-rules) are skipped.
static void add_style_rules(svg_ctx *c, const char *text)
{
    char *copy = ori__strdup(text);
    // strip comments
    for (char *p = copy; (p = strstr(p, "/*")) != NULL;) {
        char *e = strstr(p + 2, "*/");
        char *stop = e ? e + 2 : p + strlen(p);
        memset(p, ' ', (size_t)(stop - p));
        p = stop;
    }
    char *p = copy;
    while (*p) {
        char *open = strchr(p, '{');
        if (!open) break;
        if (*skip_space(p) == '@') { // skip an @-rule block, nested braces included
            int depth = 0;
            char *q = open;
            for (; *q; ++q) {
                if (*q == '{') depth++;
                else if (*q == '}' && --depth == 0) break;
            }
            p = *q ? q + 1 : q;
            continue;
        }
        char *close = strchr(open, '}');
        if (!close) break;
        *open = '\0';
        *close = '\0';
        char *decls = open + 1;
        int order = ++c->sheet.next_order;
        for (char *sel = p; sel && *sel;) {
            char *comma = strchr(sel, ',');
            if (comma) *comma = '\0';
            char one[96];
            trim_copy(one, sizeof one, sel, strlen(sel));
            char *dot = strchr(one, '.');
            bool simple = one[0] != '\0' && strpbrk(one, " >+~#:[*") == NULL && (!dot || !strchr(dot + 1, '.'));
            if (simple) {
                char tag[32] = "", cls[64] = "";
                if (dot) {
                    *dot = '\0';
                    ori__strlcpy(cls, dot + 1, sizeof cls);
                }
                ori__strlcpy(tag, one, sizeof tag);
                if (tag[0] || cls[0]) declare_all(sheet_entry(&c->sheet, tag, cls), decls, order);
            }
            sel = comma ? comma + 1 : NULL;
        }
        p = close + 1;
    }
    ori__free(copy);
}

// --- geometry -------------------------------------------------------------------------------

static bool is_svg_element(const xmlNode *n)
{
    return n->type == XML_ELEMENT_NODE && (!n->ns || !n->ns->href || strcmp((const char *)n->ns->href, SVG_NS) == 0);
}

static bool name_is(const xmlNode *n, const char *name) { return strcmp((const char *)n->name, name) == 0; }

typedef struct emit {
    svg_ctx *c;
    affine m;
    ori_assignment asg;
    double angle;
} emit;

static void emit_segment(emit *e, double x0, double y0, double x1, double y1)
{
    affine m = e->m;
    ori__seg_push(&e->c->segs, m.a * x0 + m.c * y0 + m.e, m.b * x0 + m.d * y0 + m.f, m.a * x1 + m.c * y1 + m.e,
                  m.b * x1 + m.d * y1 + m.f, e->asg, e->angle);
}

static ori_status length_attr(svg_ctx *c, const xmlNode *n, const char *name, double *out)
{
    *out = 0.0; // SVG: a missing coordinate is 0
    char *v = ori__xml_attr(n, name, &c->budget);
    if (!v) return ORI_OK;
    bool ok = parse_length(v, out);
    ori_status st = ok ? ORI_OK : fail(c, n, ORI_ERR_PARSE, "attribute %s=\"%.40s\" is not a length", name, v);
    ori__free(v);
    return st;
}

// points="x,y x,y …" (polyline, polygon).
static ori_status read_points(emit *e, const xmlNode *n, bool closed)
{
    char *v = ori__xml_attr(n, "points", &e->c->budget);
    if (!v) return ORI_OK;
    const char *p = skip_space(v);
    double first[2] = {0, 0}, prev[2] = {0, 0};
    int k = 0;
    ori_status st = ORI_OK;
    while (*p) {
        double xy[2];
        for (int i = 0; i < 2; ++i) {
            size_t m = ori__scan_number(p, &xy[i]);
            if (!m) {
                st = fail(e->c, n, ORI_ERR_PARSE, "points: expected a number at \"%.20s\"", p);
                break;
            }
            p = skip_sep(p + m);
        }
        if (st != ORI_OK) break;
        if (k == 0) memcpy(first, xy, sizeof xy);
        else emit_segment(e, prev[0], prev[1], xy[0], xy[1]);
        memcpy(prev, xy, sizeof xy);
        k++;
    }
    if (st == ORI_OK && closed && k > 2) emit_segment(e, prev[0], prev[1], first[0], first[1]);
    ori__free(v);
    return st;
}

// A curve in n straight pieces: the cubic Bézier p0 c1 c2 p3 (a quadratic given as its cubic).
static void emit_cubic(emit *e, int n, double x0, double y0, double x1, double y1, double x2, double y2, double x3,
                       double y3)
{
    double px = x0, py = y0;
    for (int i = 1; i <= n; ++i) {
        double t = (double)i / n, u = 1.0 - t;
        double qx = i == n ? x3 : u * u * u * x0 + 3 * u * u * t * x1 + 3 * u * t * t * x2 + t * t * t * x3;
        double qy = i == n ? y3 : u * u * u * y0 + 3 * u * u * t * y1 + 3 * u * t * t * y2 + t * t * t * y3;
        emit_segment(e, px, py, qx, qy);
        px = qx, py = qy;
    }
}

// The elliptical arc from (x0, y0) to (x1, y1) with radii rx, ry, x-axis rotation phi (degrees)
// and the large-arc and sweep flags, in n straight pieces (SVG 1.1 F.6.5: endpoint to centre
// parameterisation, radii scaled up when too small; zero radii draw a line).
static void emit_arc(emit *e, int n, double x0, double y0, double rx, double ry, double phi, bool large, bool sweep,
                     double x1, double y1)
{
    rx = fabs(rx), ry = fabs(ry);
    if (rx == 0.0 || ry == 0.0) {
        emit_segment(e, x0, y0, x1, y1);
        return;
    }
    double cp = cos(ori_deg_to_rad(phi)), sp = sin(ori_deg_to_rad(phi));
    double dx = 0.5 * (x0 - x1), dy = 0.5 * (y0 - y1);
    double xp = cp * dx + sp * dy, yp = -sp * dx + cp * dy;
    double lam = xp * xp / (rx * rx) + yp * yp / (ry * ry);
    if (lam > 1.0) rx *= sqrt(lam), ry *= sqrt(lam);
    double num = rx * rx * ry * ry - rx * rx * yp * yp - ry * ry * xp * xp;
    double den = rx * rx * yp * yp + ry * ry * xp * xp;
    double k = den > 0.0 && num > 0.0 ? sqrt(num / den) : 0.0;
    if (large == sweep) k = -k;
    double cxp = k * rx * yp / ry, cyp = -k * ry * xp / rx;
    double cx = cp * cxp - sp * cyp + 0.5 * (x0 + x1), cy = sp * cxp + cp * cyp + 0.5 * (y0 + y1);
    double t0 = atan2((yp - cyp) / ry, (xp - cxp) / rx);
    double t1 = atan2((-yp - cyp) / ry, (-xp - cxp) / rx);
    double dt = t1 - t0;
    if (sweep && dt < 0.0) dt += 2.0 * ORI_PI;
    if (!sweep && dt > 0.0) dt -= 2.0 * ORI_PI;
    double px = x0, py = y0;
    for (int i = 1; i <= n; ++i) {
        double t = t0 + dt * i / n;
        double qx = i == n ? x1 : cx + rx * cos(t) * cp - ry * sin(t) * sp;
        double qy = i == n ? y1 : cy + rx * cos(t) * sp + ry * sin(t) * cp;
        emit_segment(e, px, py, qx, qy);
        px = qx, py = qy;
    }
}

// The ellipse centred at (cx, cy) with radii rx, ry as a closed polygon of n pieces.
static void emit_ellipse(emit *e, int n, double cx, double cy, double rx, double ry)
{
    for (int i = 0; i < n; ++i) {
        double a = 2.0 * ORI_PI * i / n, b = 2.0 * ORI_PI * (i + 1) / n;
        emit_segment(e, cx + rx * cos(a), cy + ry * sin(a), cx + rx * cos(b), cy + ry * sin(b));
    }
}

// An arc flag of path data: a single '0' or '1' (SVG allows them unseparated, "a1 1 0 01 2 3").
static size_t scan_flag(const char *p, double *out)
{
    if (*p != '0' && *p != '1') return 0;
    *out = *p - '0';
    return 1;
}

// Path data: M L H V Z straight; C S Q T A (curves and arcs) flattened into curve_segments
// pieces each when the reader was asked to, else refused.
static ori_status read_path(emit *e, const xmlNode *n)
{
    char *v = ori__xml_attr(n, "d", &e->c->budget);
    if (!v) return ORI_OK;
    const char *p = skip_space(v);
    double cx = 0, cy = 0, sx = 0, sy = 0;
    double kx = 0, ky = 0; // the last control point of a C/S (or Q/T) command, for S (or T)
    char cmd = 0, last = 0;
    int pieces = e->c->curve_segments;
    ori_status st = ORI_OK;
    while (*p && st == ORI_OK) {
        if ((*p >= 'A' && *p <= 'Z') || (*p >= 'a' && *p <= 'z')) {
            cmd = *p++;
            p = skip_space(p);
            if (cmd == 'Z' || cmd == 'z') {
                emit_segment(e, cx, cy, sx, sy);
                cx = sx, cy = sy;
                cmd = 0; // a number right after Z is an error
                last = 'Z';
                p = skip_sep(p);
                continue;
            }
            if (!strchr("MmLlHhVvCcSsQqTtAa", cmd)) {
                st = fail(e->c, n, ORI_ERR_PARSE, "path data: unknown command '%c'", cmd);
                break;
            }
            if (!strchr("MmLlHhVv", cmd) && pieces == 0) {
                st = fail(e->c, n, ORI_ERR_UNSUPPORTED,
                          "path command '%c' draws a curve or arc; crease lines must be straight (M L H V Z); "
                          "--flatten-curves N approximates each curve by N straight creases",
                          cmd);
                break;
            }
        } else if (!cmd) {
            st = fail(e->c, n, ORI_ERR_PARSE, "path data: expected a command at \"%.20s\"", p);
            break;
        }
        char up = (char)(cmd >= 'a' ? cmd - 'a' + 'A' : cmd);
        int need = up == 'H' || up == 'V' ? 1 : up == 'C' ? 6 : up == 'S' || up == 'Q' ? 4 : up == 'A' ? 7 : 2;
        double a[7] = {0, 0, 0, 0, 0, 0, 0};
        for (int i = 0; i < need; ++i) {
            size_t m = up == 'A' && (i == 3 || i == 4) ? scan_flag(p, &a[i]) : ori__scan_number(p, &a[i]);
            if (!m) {
                st = fail(e->c, n, ORI_ERR_PARSE, "path data: expected a %s after '%c' at \"%.20s\"",
                          up == 'A' && (i == 3 || i == 4) ? "flag (0 or 1)" : "number", cmd, *p ? p : "end of data");
                break;
            }
            p = skip_sep(p + m);
        }
        if (st != ORI_OK) break;
        bool rel = cmd >= 'a' && cmd <= 'z';
        double ox = rel ? cx : 0.0, oy = rel ? cy : 0.0; // origin of relative coordinates
        double nx = cx, ny = cy;
        char prev = last;
        last = up;
        switch (up) {
        case 'M':
            nx = ox + a[0], ny = oy + a[1];
            sx = nx, sy = ny;
            cmd = rel ? 'l' : 'L'; // further pairs are implicit line-tos
            break;
        case 'L':
            nx = ox + a[0], ny = oy + a[1];
            emit_segment(e, cx, cy, nx, ny);
            break;
        case 'H':
            nx = ox + a[0];
            emit_segment(e, cx, cy, nx, ny);
            break;
        case 'V':
            ny = oy + a[0];
            emit_segment(e, cx, cy, nx, ny);
            break;
        case 'C':
        case 'S': {
            double x1, y1, x2, y2;
            if (up == 'C') x1 = ox + a[0], y1 = oy + a[1], x2 = ox + a[2], y2 = oy + a[3], nx = ox + a[4], ny = oy + a[5];
            else {
                bool reflect = prev == 'C' || prev == 'S';
                x1 = reflect ? 2 * cx - kx : cx, y1 = reflect ? 2 * cy - ky : cy;
                x2 = ox + a[0], y2 = oy + a[1], nx = ox + a[2], ny = oy + a[3];
            }
            emit_cubic(e, pieces, cx, cy, x1, y1, x2, y2, nx, ny);
            kx = x2, ky = y2;
            e->c->stats.flattened_curves++;
            break;
        }
        case 'Q':
        case 'T': {
            double qx, qy;
            if (up == 'Q') qx = ox + a[0], qy = oy + a[1], nx = ox + a[2], ny = oy + a[3];
            else {
                bool reflect = prev == 'Q' || prev == 'T';
                qx = reflect ? 2 * cx - kx : cx, qy = reflect ? 2 * cy - ky : cy;
                nx = ox + a[0], ny = oy + a[1];
            }
            emit_cubic(e, pieces, cx, cy, cx + 2.0 / 3.0 * (qx - cx), cy + 2.0 / 3.0 * (qy - cy), nx + 2.0 / 3.0 * (qx - nx),
                       ny + 2.0 / 3.0 * (qy - ny), nx, ny);
            kx = qx, ky = qy;
            e->c->stats.flattened_curves++;
            break;
        }
        default: // A
            nx = ox + a[5], ny = oy + a[6];
            emit_arc(e, pieces, cx, cy, a[0], a[1], a[2], a[3] != 0.0, a[4] != 0.0, nx, ny);
            e->c->stats.flattened_curves++;
            break;
        }
        cx = nx, cy = ny;
    }
    ori__free(v);
    return st;
}

// transform="matrix(…) translate(…) scale(…) rotate(…) skewX(…) skewY(…)", composed left to right.
static ori_status read_transform(svg_ctx *c, const xmlNode *n, affine *m)
{
    char *v = ori__xml_attr(n, "transform", &c->budget);
    if (!v) return ORI_OK;
    const char *p = skip_space(v);
    affine t = affine_identity();
    ori_status st = ORI_OK;
    while (*p && st == ORI_OK) {
        const char *name = p;
        while ((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z')) ++p;
        size_t len = (size_t)(p - name);
        p = skip_space(p);
        double arg[6];
        int k = 0;
        if (*p != '(' || len == 0) {
            st = fail(c, n, ORI_ERR_PARSE, "transform: expected name(…) at \"%.20s\"", name);
            break;
        }
        p = skip_space(p + 1);
        while (*p && *p != ')' && k < 6) {
            size_t used = ori__scan_number(p, &arg[k]);
            if (!used) break;
            k++;
            p = skip_sep(p + used);
        }
        if (*p != ')') {
            st = fail(c, n, ORI_ERR_PARSE, "transform: bad arguments at \"%.20s\"", name);
            break;
        }
        p = skip_sep(p + 1);
        char fn[16];
        trim_copy(fn, sizeof fn, name, len < 15 ? len : 15);
        affine u = affine_identity();
        if (strcmp(fn, "matrix") == 0 && k == 6) u = (affine){arg[0], arg[1], arg[2], arg[3], arg[4], arg[5]};
        else if (strcmp(fn, "translate") == 0 && (k == 1 || k == 2)) u.e = arg[0], u.f = k == 2 ? arg[1] : 0.0;
        else if (strcmp(fn, "scale") == 0 && (k == 1 || k == 2)) u.a = arg[0], u.d = k == 2 ? arg[1] : arg[0];
        else if (strcmp(fn, "rotate") == 0 && (k == 1 || k == 3)) {
            double cs = cos(ori_deg_to_rad(arg[0])), sn = sin(ori_deg_to_rad(arg[0]));
            u = (affine){cs, sn, -sn, cs, 0, 0};
            if (k == 3) { // rotate about (cx, cy): translate(c) rotate translate(−c)
                affine to = {1, 0, 0, 1, arg[1], arg[2]}, back = {1, 0, 0, 1, -arg[1], -arg[2]};
                u = affine_mul(to, affine_mul(u, back));
            }
        } else if (strcmp(fn, "skewX") == 0 && k == 1) u.c = tan(ori_deg_to_rad(arg[0]));
        else if (strcmp(fn, "skewY") == 0 && k == 1) u.b = tan(ori_deg_to_rad(arg[0]));
        else {
            st = fail(c, n, ORI_ERR_PARSE, "transform: unknown or malformed '%s' (%s)", fn,
                      k == 0 ? "no arguments" : "wrong number of arguments");
            break;
        }
        t = affine_mul(t, u);
    }
    ori__free(v);
    if (st == ORI_OK) *m = affine_mul(*m, t);
    return st;
}

// --- elements ------------------------------------------------------------------------------

static ori_status shape(svg_ctx *c, const xmlNode *n, affine m, const svg_style *style)
{
    if (style->hidden) return ORI_OK;
    ori_assignment asg;
    bool none;
    if (!colour_assignment(style->stroke, style->color, &asg, &none)) {
        if (!none) {
            if (c->stats.ignored_elements++ == 0) ori__strlcpy(c->stats.ignored_colour, style->stroke, sizeof c->stats.ignored_colour);
        }
        return ORI_OK;
    }
    if ((name_is(n, "circle") || name_is(n, "ellipse")) && c->curve_segments == 0)
        return fail(c, n, ORI_ERR_UNSUPPORTED,
                    "a %s cannot be a crease: crease lines must be straight (--flatten-curves N approximates it by N "
                    "straight creases)",
                    (const char *)n->name);
    // The drawn width of its lines (stroke-width scaled by the transform): how far apart two lines
    // may be and still touch on the page (the import closes such gaps).
    double drawn = style->stroke_width * sqrt(fabs(m.a * m.d - m.b * m.c));
    if (isfinite(drawn)) ORI__PUSH(c->widths, c->width_count, c->width_cap, drawn);
    double opacity = style->opacity * style->stroke_opacity;
    double angle = 0.0;
    if (asg == ORI_ASSIGN_MOUNTAIN) angle = -opacity * ORI_PI;
    else if (asg == ORI_ASSIGN_VALLEY) angle = opacity * ORI_PI;
    emit e = {c, m, asg, angle};
    ori_status st = ORI_OK;
    if (name_is(n, "line")) {
        double x1, y1, x2, y2;
        if ((st = length_attr(c, n, "x1", &x1)) || (st = length_attr(c, n, "y1", &y1)) ||
            (st = length_attr(c, n, "x2", &x2)) || (st = length_attr(c, n, "y2", &y2)))
            return st;
        emit_segment(&e, x1, y1, x2, y2);
    } else if (name_is(n, "circle") || name_is(n, "ellipse")) {
        double x, y, rx, ry;
        bool circle = name_is(n, "circle");
        if ((st = length_attr(c, n, "cx", &x)) || (st = length_attr(c, n, "cy", &y)) ||
            (st = length_attr(c, n, circle ? "r" : "rx", &rx)) || (st = length_attr(c, n, circle ? "r" : "ry", &ry)))
            return st;
        if (rx < 0.0 || ry < 0.0) return fail(c, n, ORI_ERR_PARSE, "negative radius");
        if (rx > 0.0 && ry > 0.0) {
            emit_ellipse(&e, c->curve_segments, x, y, rx, ry);
            c->stats.flattened_curves++;
        }
    } else if (name_is(n, "rect")) {
        double x, y, w, h, rx, ry;
        if ((st = length_attr(c, n, "x", &x)) || (st = length_attr(c, n, "y", &y)) ||
            (st = length_attr(c, n, "width", &w)) || (st = length_attr(c, n, "height", &h)) ||
            (st = length_attr(c, n, "rx", &rx)) || (st = length_attr(c, n, "ry", &ry)))
            return st;
        if (w < 0.0 || h < 0.0) return fail(c, n, ORI_ERR_PARSE, "negative width or height");
        if ((rx > 0.0 || ry > 0.0) && c->curve_segments == 0)
            return fail(c, n, ORI_ERR_UNSUPPORTED,
                        "rounded corners (rx, ry) are arcs; crease lines must be straight (--flatten-curves N "
                        "approximates each by N straight creases)");
        if ((rx > 0.0 || ry > 0.0) && w > 0.0 && h > 0.0) { // SVG: a missing radius is the other; at most half the side
            if (!(rx > 0.0)) rx = ry;
            if (!(ry > 0.0)) ry = rx;
            rx = fmin(rx, 0.5 * w), ry = fmin(ry, 0.5 * h);
            int k = c->curve_segments;
            emit_segment(&e, x + rx, y, x + w - rx, y);
            emit_arc(&e, k, x + w - rx, y, rx, ry, 0, false, true, x + w, y + ry);
            emit_segment(&e, x + w, y + ry, x + w, y + h - ry);
            emit_arc(&e, k, x + w, y + h - ry, rx, ry, 0, false, true, x + w - rx, y + h);
            emit_segment(&e, x + w - rx, y + h, x + rx, y + h);
            emit_arc(&e, k, x + rx, y + h, rx, ry, 0, false, true, x, y + h - ry);
            emit_segment(&e, x, y + h - ry, x, y + ry);
            emit_arc(&e, k, x, y + ry, rx, ry, 0, false, true, x + rx, y);
            c->stats.flattened_curves += 4;
        } else if (w > 0.0 && h > 0.0) {
            emit_segment(&e, x, y, x + w, y);
            emit_segment(&e, x + w, y, x + w, y + h);
            emit_segment(&e, x + w, y + h, x, y + h);
            emit_segment(&e, x, y + h, x, y);
        }
    } else if (name_is(n, "polyline") || name_is(n, "polygon")) {
        st = read_points(&e, n, name_is(n, "polygon"));
    } else {
        st = read_path(&e, n);
    }
    return st;
}

// The state an element passes to its children.
typedef struct frame {
    affine m;
    svg_style style;
} frame;

// One element, given its parent's state. *enter says whether its children are to be read (a
// group), in which case *child holds the state they inherit.
static ori_status element(svg_ctx *c, const xmlNode *n, const frame *parent, frame *child, bool *enter)
{
    static const char *const skipped[] = {"defs", "symbol", "clipPath", "mask", "marker", "pattern",
                                          "metadata", "title", "desc", "style", "script", "linearGradient",
                                          "radialGradient", "filter"};
    static const char *const unsupported[] = {"use", "image", "text", "foreignObject", "switch"};
    static const char *const shapes[] = {"line", "rect", "polyline", "polygon", "path", "circle", "ellipse"};
    *enter = false;
    if (!is_svg_element(n)) return ORI_OK; // other namespaces (sodipodi:namedview, …)
    for (size_t i = 0; i < sizeof skipped / sizeof skipped[0]; ++i)
        if (name_is(n, skipped[i])) return ORI_OK;
    for (size_t i = 0; i < sizeof unsupported / sizeof unsupported[0]; ++i)
        if (name_is(n, unsupported[i])) {
            c->stats.unsupported_elements++;
            return ORI_OK;
        }
    bool group = name_is(n, "g") || name_is(n, "a") || name_is(n, "svg");
    if (name_is(n, "g")) { // the labels orikin's writer adds are not part of the drawing
        char *id = ori__xml_attr(n, "id", &c->budget);
        bool labels = id && strcmp(id, "orikin-labels") == 0;
        ori__free(id);
        if (labels) return ORI_OK;
    }
    bool is_shape = false;
    for (size_t i = 0; i < sizeof shapes / sizeof shapes[0]; ++i) is_shape |= name_is(n, shapes[i]);
    if (!group && !is_shape) return ORI_OK; // unknown elements are ignored with their content
    frame f = *parent;
    bool display_none;
    element_style(c, n, &f.style, &display_none);
    if (display_none) return ORI_OK;
    ori_status st = read_transform(c, n, &f.m);
    if (st != ORI_OK) return st;
    if (is_shape) return shape(c, n, f.m, &f.style);
    if (name_is(n, "svg")) { // nested viewport: its x, y offset (viewBox scaling is not applied)
        double x, y;
        if ((st = length_attr(c, n, "x", &x)) || (st = length_attr(c, n, "y", &y))) return st;
        affine off = {1, 0, 0, 1, x, y};
        f.m = affine_mul(f.m, off);
    }
    *child = f;
    *enter = true;
    return ORI_OK;
}

// --- entry ----------------------------------------------------------------------------------

// One pass of the streaming reader over the document (the tree of a large drawing would take
// gigabytes): with styles_only, collect the <style> rules; otherwise read the geometry, each
// element seeing the state of its parent in frames[depth − 1].
static ori_status stream(svg_ctx *c, const char *text, size_t size, bool styles_only)
{
    xmlTextReaderPtr r = xmlReaderForMemory(text, (int)size, NULL, NULL, ORI__XML_OPTIONS);
    if (!r) return ori__fail(c->error, ORI_ERR_NOMEM, "cannot create the XML reader");
    ori__xml_first_error first;
    memset(&first, 0, sizeof first);
    xmlTextReaderSetStructuredErrorHandler(r, ori__xml_reader_error, &first);
    frame *frames = ori__alloc(sizeof(frame) * (MAX_DEPTH + 1));
    int skip = -1; // depth of the element whose content is not read
    ori_status st = ORI_OK;
    int ret;
    while (st == ORI_OK && (ret = xmlTextReaderRead(r)) == 1) {
        int type = xmlTextReaderNodeType(r), depth = xmlTextReaderDepth(r);
        if (type == XML_READER_TYPE_END_ELEMENT && depth == skip) skip = -1;
        if (type != XML_READER_TYPE_ELEMENT || (skip >= 0 && depth > skip)) continue;
        const xmlNode *n = xmlTextReaderCurrentNode(r);
        bool empty = xmlTextReaderIsEmptyElement(r) == 1, enter = false;
        if (!n) continue;
        if (depth > MAX_DEPTH) {
            st = fail(c, n, ORI_ERR_LIMIT, "elements nested deeper than %d levels", MAX_DEPTH);
        } else if (depth == 0) {
            if (!is_svg_element(n) || !name_is(n, "svg")) {
                st = ori__fail_pos(c->error, ORI_ERR_PARSE, line_of(n) > 0 ? line_of(n) : 1, 0,
                                   "the root element is <%s>, not <svg>", (const char *)n->name);
            } else if (!styles_only) {
                memset(&frames[0], 0, sizeof frames[0]);
                frames[0].m = affine_identity();
                frames[0].style.stroke_opacity = 1.0;
                frames[0].style.stroke_width = 1.0;
                frames[0].style.opacity = 1.0;
                bool display_none;
                element_style(c, n, &frames[0].style, &display_none);
                st = read_transform(c, n, &frames[0].m);
                enter = !display_none;
            } else {
                enter = true;
            }
        } else if (styles_only) {
            enter = true;
            if (is_svg_element(n) && name_is(n, "style") && !empty) {
                xmlNode *full = xmlTextReaderExpand(r);
                char *css = full ? ori__xml_text(full, &c->budget) : NULL;
                if (css) add_style_rules(c, css);
                ori__free(css);
            }
        } else {
            st = element(c, n, &frames[depth - 1], &frames[depth], &enter);
        }
        if (st == ORI_OK && c->budget.exceeded)
            st = fail(c, n, ORI_ERR_LIMIT, "entity references expand to more than %d times the file's size",
                      ORI__XML_EXPANSION_PER_BYTE);
        if (!enter && !empty) skip = depth;
    }
    if (st == ORI_OK && ret < 0) st = ori__xml_error(&first, c->error);
    xmlFreeTextReader(r);
    ori__free(frames);
    return st;
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

ori_status ori_svg_read_segments(const char *text, size_t size, ori_segment **segments, int *count,
                                 ori_import_stats *stats, ori_error *error)
{
    return ori_svg_read_curves(text, size, 0, segments, count, stats, error);
}

ori_status ori_svg_read_curves(const char *text, size_t size, int curve_segments, ori_segment **segments, int *count,
                               ori_import_stats *stats, ori_error *error)
{
    ORI_ASSERT(text && segments && count);
    ori__reader_begin(segments, count, stats, error);
    if (curve_segments < 0 || curve_segments > ORI_IMPORT_CURVE_SEGMENTS_MAX)
        return ori__fail(error, ORI_ERR_ARGUMENT, "%d pieces per curve is outside [0, %d]", curve_segments,
                         ORI_IMPORT_CURVE_SEGMENTS_MAX);
    if (size > (size_t)INT32_MAX) return ori__fail(error, ORI_ERR_LIMIT, "the SVG file is too large");
    svg_ctx c;
    memset(&c, 0, sizeof c);
    c.error = error;
    c.curve_segments = curve_segments;
    ori__xml_budget_init(&c.budget, size);
    // <style> rules may come after the elements they style: a first pass collects them, only
    // when the text has a <style> at all.
    const char *needle = "<style";
    bool has_style = false;
    for (size_t i = 0; i + 6 <= size && !has_style; ++i) has_style = memcmp(text + i, needle, 6) == 0;
    ori_status st = has_style ? stream(&c, text, size, true) : ORI_OK;
    if (st == ORI_OK) st = stream(&c, text, size, false);
    json_decref(c.sheet.index);
    ori__free(c.sheet.entries);
    if (c.width_count > 0) { // the median: a few thick outlines do not set it
        qsort(c.widths, (size_t)c.width_count, sizeof(double), compare_doubles);
        c.stats.stroke_width = c.widths[c.width_count / 2];
    }
    ori__free(c.widths);
    return ori__reader_end(st, &c.segs, &c.stats, segments, count, stats);
}
