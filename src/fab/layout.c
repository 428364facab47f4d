// The lithography layout of a crease pattern (include/orikin/fab.h): panels shrunk by the hinge
// gap, hinge strips, wires with leads and pads, alignment marks and a label, in pattern units.
#include <math.h>
#include <string.h>

#include <orikin/arrangement.h>
#include <orikin/fab.h>
#include <orikin/kinematics.h>

#include "../core/core_internal.h"

typedef struct shape_rec {
    int layer, kind, element, first, count;
    double width;
    int text; // offset into texts, −1 when none
} shape_rec;

struct ori_fab_layout {
    shape_rec *shapes;
    int count, cap;
    ori_v2 *points;
    int point_count, point_cap;
    char *texts;
    int text_len, text_cap;
    double mpu;
};

static const char *const layer_names[] = {"?", "PANEL", "HINGE", "WIRE", "PAD", "MARK", "LABEL"};
static const char *const layer_descriptions[] = {
    "?",
    "panels: each face, its creases moved inward by half the hinge gap",
    "hinge metal: a strip per crease, centred on it, across the gap and onto both panels",
    "actuation wires: the Lorentz current loop on the moving panel and its leads (paths)",
    "contact pads at the ends of the wire leads",
    "alignment marks: crosses outside the corners of the sheet",
    "text label",
};

const char *ori_fab_layer_name(int layer)
{
    return layer >= ORI_FAB_LAYER_FIRST && layer <= ORI_FAB_LAYER_LAST ? layer_names[layer] : "?";
}

const char *ori_fab_layer_description(int layer)
{
    return layer >= ORI_FAB_LAYER_FIRST && layer <= ORI_FAB_LAYER_LAST ? layer_descriptions[layer] : "?";
}

ori_fab_def ori_default_fab_def(void)
{
    ori_fab_def d;
    memset(&d, 0, sizeof d);
    d.pattern = NULL;
    d.design = NULL;
    d.meters_per_unit = 0.0;
    d.fixed_face = ORI_NULL_INDEX;
    d.hinge_gap_m = 0.0;
    d.default_hinge_span_m = 20e-6;
    d.hinge_overlap_m = 10e-6;
    d.hinge_width_m = 0.0;
    d.hinges_everywhere = true;
    d.wire_width_m = 0.0;
    d.pad_size_m = 100e-6;
    d.lead_length_m = 150e-6;
    d.mark_size_m = 100e-6;
    d.mark_margin_m = 200e-6;
    d.label_height_m = 100e-6;
    ori__strlcpy(d.label, "orikin", sizeof d.label);
    d.internal_value = 1;
    return d;
}

void ori_fab_layout_destroy(ori_fab_layout *l)
{
    if (!l) return;
    ori__free(l->shapes);
    ori__free(l->points);
    ori__free(l->texts);
    ori__free(l);
}

int ori_fab_shape_count(const ori_fab_layout *l) { ORI_ASSERT(l); return l->count; }

double ori_fab_layout_meters_per_unit(const ori_fab_layout *l) { ORI_ASSERT(l); return l->mpu; }

ori_fab_shape ori_fab_shape_at(const ori_fab_layout *l, int i)
{
    ORI_ASSERT(l && i >= 0 && i < l->count);
    const shape_rec *r = &l->shapes[i];
    ori_fab_shape s;
    s.layer = r->layer;
    s.kind = (ori_fab_shape_kind)r->kind;
    s.element = r->element;
    s.point_count = r->count;
    s.points = l->points + r->first;
    s.width = r->width;
    s.text = r->text >= 0 ? l->texts + r->text : NULL;
    return s;
}

static void add_shape(ori_fab_layout *l, int layer, int kind, int element, const ori_v2 *pts, int n, double width,
                      const char *text)
{
    ori__grow((void **)&l->shapes, &l->cap, l->count + 1, sizeof *l->shapes);
    ori__grow((void **)&l->points, &l->point_cap, l->point_count + n, sizeof *l->points);
    shape_rec *r = &l->shapes[l->count++];
    r->layer = layer;
    r->kind = kind;
    r->element = element;
    r->first = l->point_count;
    r->count = n;
    r->width = width;
    r->text = -1;
    memcpy(l->points + l->point_count, pts, sizeof *pts * (size_t)n);
    l->point_count += n;
    if (text) {
        int len = (int)strlen(text) + 1;
        ori__grow((void **)&l->texts, &l->text_cap, l->text_len + len, 1);
        memcpy(l->texts + l->text_len, text, (size_t)len);
        r->text = l->text_len;
        l->text_len += len;
    }
}

static ori_v2 v2(double x, double y) { return (ori_v2){x, y}; }
static ori_v2 add(ori_v2 a, ori_v2 b) { return v2(a.x + b.x, a.y + b.y); }
static ori_v2 sub(ori_v2 a, ori_v2 b) { return v2(a.x - b.x, a.y - b.y); }
static ori_v2 mul(ori_v2 a, double s) { return v2(a.x * s, a.y * s); }
static double cross(ori_v2 a, ori_v2 b) { return a.x * b.y - a.y * b.x; }
static double dot(ori_v2 a, ori_v2 b) { return a.x * b.x + a.y * b.y; }
static ori_v2 vxy(const ori_pattern *p, int v)
{
    ori_v3 q = ori_pattern_vertex(p, v);
    return v2(q.x, q.y);
}

static double signed_area(const ori_v2 *pts, int n)
{
    double a = 0.0;
    for (int i = 0; i < n; ++i) a += cross(pts[i], pts[(i + 1) % n]);
    return 0.5 * a;
}

// A rectangle centred at c with half extents hu along the unit u and hv along the unit v = u
// turned left: counter-clockwise.
static void add_rect(ori_fab_layout *l, int layer, int element, ori_v2 c, ori_v2 u, double hu, double hv)
{
    ori_v2 v = v2(-u.y, u.x);
    ori_v2 r[4] = {add(add(c, mul(u, -hu)), mul(v, -hv)), add(add(c, mul(u, hu)), mul(v, -hv)),
                   add(add(c, mul(u, hu)), mul(v, hv)), add(add(c, mul(u, -hu)), mul(v, hv))};
    add_shape(l, layer, ORI_FAB_POLYGON, element, r, 4, 0.0, NULL);
}

static bool is_crease(ori_assignment a) { return ori_assignment_is_fold(a); }

// Gap (pattern units) of an edge: 0 for edges that are not creases.
static double edge_gap(const ori_fab_def *d, double mpu, int e)
{
    ori_edge ed = ori_pattern_edge(d->pattern, e);
    if (!is_crease(ed.assignment)) return 0.0;
    if (d->hinge_gap_m > 0.0) return d->hinge_gap_m / mpu;
    ori_hinge h;
    if (d->design && ori_design_hinge(d->design, e, &h)) return h.span_m / mpu;
    return d->default_hinge_span_m / mpu;
}

static ori_status add_panel(ori_fab_layout *l, const ori_fab_def *d, double mpu, int f, ori_error *error)
{
    const ori_pattern *p = d->pattern;
    int n = ori_pattern_face_size(p, f);
    int *vs = ori__alloc(sizeof(int) * (size_t)n * 2);
    int *es = vs + n;
    ori_pattern_face_vertices(p, f, vs, n);
    ori_pattern_face_edges(p, f, es, n);
    ori_v2 *pts = ori__alloc(sizeof(ori_v2) * (size_t)n * 2);
    double *off = ori__alloc(sizeof(double) * (size_t)n);
    for (int i = 0; i < n; ++i) pts[i] = vxy(p, vs[i]);
    bool ccw = signed_area(pts, n) > 0.0;
    ori_v2 *q = pts + n; // the vertex cycle counter-clockwise
    for (int i = 0; i < n; ++i) {
        int k = ccw ? i : n - 1 - i;
        q[i] = pts[k];
        // edge i of q joins q[i] and q[i+1]: edge k of the face when ccw, else edge k − 1
        off[i] = edge_gap(d, mpu, es[ccw ? k : (k - 1 + n) % n]) * 0.5;
    }
    ori_v2 *out = ori__alloc(sizeof(ori_v2) * (size_t)n * 2);
    int *from = ori__alloc(sizeof(int) * (size_t)n * 2); // the face edge (of q) that starts at out[k]; −1 for a step
    int m = 0;
    for (int i = 0; i < n; ++i) {
        int h = (i - 1 + n) % n;
        ori_v2 a0 = q[h], a1 = q[i], b1 = q[(i + 1) % n];
        ori_v2 da = sub(a1, a0), db = sub(b1, a1);
        double la = sqrt(dot(da, da)), lb = sqrt(dot(db, db));
        da = mul(da, 1.0 / la);
        db = mul(db, 1.0 / lb);
        ori_v2 na = v2(-da.y, da.x), nb = v2(-db.y, db.x);
        ori_v2 pa = add(a1, mul(na, off[h])), pb = add(a1, mul(nb, off[i]));
        double c = cross(da, db);
        if (fabs(c) < ORI_TOL_ANGLE_EQUAL_RAD) { // collinear (sin of the turn): one point, or a step between the offsets
            if (fabs(off[h] - off[i]) > 0.0) from[m] = -1, out[m++] = pa;
            from[m] = i, out[m++] = pb;
            continue;
        }
        // pa + s·da = pb + t·db
        double s = cross(sub(pb, pa), db) / c;
        from[m] = i, out[m++] = add(pa, mul(da, s));
    }
    // A gap too wide for the panel turns an offset edge around (or the polygon inside out).
    bool valid = signed_area(out, m) > 0.0;
    for (int k = 0; k < m && valid; ++k)
        if (from[k] >= 0) valid = dot(sub(out[(k + 1) % m], out[k]), sub(q[(from[k] + 1) % n], q[from[k]])) > 0.0;
    ori__free(from);
    ori_status st = ORI_OK;
    if (!valid) st = ori__fail_at(error, ORI_ERR_DEGENERATE, "faces_vertices", f,
                                 "the hinge gap leaves face %d no panel (--gap: narrower than the panel)", f);
    else add_shape(l, ORI_FAB_PANEL, ORI_FAB_POLYGON, f, out, m, 0.0, NULL);
    ori__free(out);
    ori__free(off);
    ori__free(pts);
    ori__free(vs);
    return st;
}

static ori_v2 face_centroid(const ori_pattern *p, int f)
{
    int n = ori_pattern_face_size(p, f);
    int *vs = ori__alloc(sizeof(int) * (size_t)n);
    ori_pattern_face_vertices(p, f, vs, n);
    ori_v2 c = v2(0, 0);
    for (int i = 0; i < n; ++i) c = add(c, vxy(p, vs[i]));
    ori__free(vs);
    return mul(c, 1.0 / n);
}

// The wire of crease e on face wf: one turn is a U from the crease (leads across it to two
// pads on the other panel); more turns are a rectangular spiral inward, its inner end on a pad
// inside the coil. Local frame: u along the crease from its midpoint, v into the wire's panel.
static void add_wire(ori_fab_layout *l, const ori_fab_def *d, double mpu, int e, int wf, const ori_hinge *h)
{
    const ori_pattern *p = d->pattern;
    ori_edge ed = ori_pattern_edge(p, e);
    ori_v2 a = vxy(p, ed.v[0]), b = vxy(p, ed.v[1]);
    ori_v2 u = sub(b, a);
    u = mul(u, 1.0 / sqrt(dot(u, u)));
    ori_v2 v = v2(-u.y, u.x);
    ori_v2 mid = mul(add(a, b), 0.5);
    if (dot(sub(face_centroid(p, wf), mid), v) < 0.0) v = mul(v, -1.0);
    double half = 0.5 * h->wire.length_m / mpu, lever = h->wire.lever_m / mpu;
    double w = d->wire_width_m > 0.0 ? d->wire_width_m : h->wire.width_m > 0.0 ? h->wire.width_m : h->width_m;
    w /= mpu;
    double lead = d->lead_length_m / mpu, pad = d->pad_size_m / mpu;
    double pitch = 2.0 * w, base = 0.5 * edge_gap(d, mpu, e) + w;
    int turns = h->wire.turns < 1 ? 1 : h->wire.turns;
    ori_v2 loc[4 * 64 + 4];
    int n = 0;
    loc[n++] = v2(-half, -lead);
    for (int k = 0; k < turns && k < 64; ++k) {
        double x0 = -half + k * pitch, x1 = half - k * pitch, top = lever - k * pitch;
        if (k > 0) loc[n++] = v2(x0, base + k * pitch);
        loc[n++] = v2(x0, top);
        loc[n++] = v2(x1, top);
        if (turns == 1) loc[n++] = v2(x1, -lead);
        else if (k + 1 < turns) loc[n++] = v2(x1, base + (k + 1) * pitch);
        else loc[n++] = v2(x1, base + (k + 1) * pitch > top ? top : base + (k + 1) * pitch);
    }
    ori_v2 pts[4 * 64 + 4];
    for (int i = 0; i < n; ++i) pts[i] = add(add(mid, mul(u, loc[i].x)), mul(v, loc[i].y));
    add_shape(l, ORI_FAB_WIRE, ORI_FAB_PATH, e, pts, n, w, NULL);
    ori_v2 pa = add(pts[0], mul(v, -0.5 * pad));
    add_rect(l, ORI_FAB_PAD, e, pa, u, 0.5 * pad, 0.5 * pad);
    if (turns == 1) add_rect(l, ORI_FAB_PAD, e, add(pts[n - 1], mul(v, -0.5 * pad)), u, 0.5 * pad, 0.5 * pad);
    else add_rect(l, ORI_FAB_PAD, e, pts[n - 1], u, 0.5 * pad, 0.5 * pad);
}

static ori_status check_length(ori_error *error, const char *name, double x)
{
    if (isfinite(x) && x >= 0.0) return ORI_OK;
    return ori__fail_at(error, ORI_ERR_RANGE, name, ORI_NULL_INDEX, "%s must be a finite length ≥ 0 (metres)", name);
}

ori_status ori_fab_layout_create(const ori_fab_def *d, ori_fab_layout **out, ori_error *error)
{
    ORI_ASSERT(d && out && d->internal_value == 1);
    *out = NULL;
    const ori_pattern *p = d->pattern;
    if (!p || !ori_pattern_is_built(p)) return ori__fail(error, ORI_ERR_ARGUMENT, "fab: the pattern is missing or not built");
    if (ori_pattern_is_folded_form(p) || ori_pattern_is_3d(p))
        return ori__fail(error, ORI_ERR_ARGUMENT, "fab: the pattern is folded (a mask needs the flat crease pattern)");
    double mpu = d->design ? ori_design_meters_per_unit(d->design) : d->meters_per_unit;
    if (!(mpu > 0.0) || !isfinite(mpu))
        return ori__fail_at(error, ORI_ERR_ARGUMENT, "frame_unit", ORI_NULL_INDEX, "fab: the length unit is unknown");
    ori_status st;
    const char *names[] = {"hinge_gap", "default_hinge_span", "hinge_overlap", "hinge_width", "wire_width",
                           "pad_size", "lead_length", "mark_size", "mark_margin", "label_height"};
    double vals[] = {d->hinge_gap_m, d->default_hinge_span_m, d->hinge_overlap_m, d->hinge_width_m, d->wire_width_m,
                     d->pad_size_m, d->lead_length_m, d->mark_size_m, d->mark_margin_m, d->label_height_m};
    for (int i = 0; i < 10; ++i) {
        double x = vals[i];
        if (i == 0 || i == 3 || i == 4) x = x < 0.0 ? 0.0 : x; // ≤ 0 means "default" there
        if ((st = check_length(error, names[i], x)) != ORI_OK) return st;
        if (!isfinite(x / mpu))
            return ori__fail_at(error, ORI_ERR_RANGE, names[i], ORI_NULL_INDEX,
                                "%s is beyond the range of lengths in the pattern's unit (%g m)", names[i], mpu);
    }
    int nf = ori_pattern_face_count(p), ne = ori_pattern_edge_count(p);
    ori_fab_layout *l = ori__calloc(1, sizeof *l);
    l->mpu = mpu;
    for (int f = 0; f < nf; ++f)
        if ((st = add_panel(l, d, mpu, f, error)) != ORI_OK) {
            ori_fab_layout_destroy(l);
            return st;
        }
    for (int e = 0; e < ne; ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        if (!is_crease(ed.assignment)) continue;
        ori_hinge h;
        bool has = d->design && ori_design_hinge(d->design, e, &h);
        if (!has && !d->hinges_everywhere) continue;
        ori_v2 a = vxy(p, ed.v[0]), b = vxy(p, ed.v[1]);
        ori_v2 u = sub(b, a);
        double len = sqrt(dot(u, u));
        u = mul(u, 1.0 / len);
        double gap = edge_gap(d, mpu, e);
        double w = d->hinge_width_m > 0.0 ? d->hinge_width_m / mpu : has ? h.width_m / mpu : len - gap;
        if (w > len) w = len;
        if (w <= 0.0) continue;
        add_rect(l, ORI_FAB_HINGE, e, mul(add(a, b), 0.5), u, 0.5 * w, 0.5 * gap + d->hinge_overlap_m / mpu);
    }
    // Wires: the face of each from the design (the side away from the fixed face by default).
    ori_mechanism *mech = NULL;
    int fixed = d->fixed_face >= 0 && d->fixed_face < nf ? d->fixed_face : ori_pattern_center_face(p);
    for (int e = 0; e < ne && d->design; ++e) {
        ori_hinge h;
        if (!ori_design_hinge(d->design, e, &h) || !h.has_wire) continue;
        int wf = h.wire.face;
        if (wf < 0) {
            if (!mech) {
                ori_mechanism_def md = ori_default_mechanism_def();
                md.pattern = p;
                if ((st = ori_mechanism_create(&md, &mech, error)) != ORI_OK) {
                    ori_fab_layout_destroy(l);
                    return st;
                }
            }
            wf = ori_design_wire_face(d->design, mech, e, fixed);
        }
        if (wf < 0) continue;
        add_wire(l, d, mpu, e, wf, &h);
    }
    ori_mechanism_destroy(mech);
    // Marks and label around the bounding box.
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (int i = 0; i < ori_pattern_vertex_count(p); ++i) {
        ori_v2 q = vxy(p, i);
        x0 = fmin(x0, q.x), y0 = fmin(y0, q.y), x1 = fmax(x1, q.x), y1 = fmax(y1, q.y);
    }
    double mm = d->mark_margin_m / mpu, ms = d->mark_size_m / mpu;
    if (ms > 0.0) {
        ori_v2 cs[4] = {v2(x0 - mm, y0 - mm), v2(x1 + mm, y0 - mm), v2(x1 + mm, y1 + mm), v2(x0 - mm, y1 + mm)};
        for (int i = 0; i < 4; ++i) {
            add_rect(l, ORI_FAB_MARK, ORI_NULL_INDEX, cs[i], v2(1, 0), 0.5 * ms, 0.05 * ms);
            add_rect(l, ORI_FAB_MARK, ORI_NULL_INDEX, cs[i], v2(0, 1), 0.5 * ms, 0.05 * ms);
        }
    }
    if (d->label[0] && d->label_height_m > 0.0) {
        ori_v2 at = v2(x0 + mm, y0 - mm - 0.5 * d->label_height_m / mpu);
        add_shape(l, ORI_FAB_LABEL, ORI_FAB_TEXT, ORI_NULL_INDEX, &at, 1, d->label_height_m / mpu, d->label);
    }
    // Lengths each in range can still sum past it (a mark margin near the largest double).
    bool finite = true;
    for (int i = 0; i < l->point_count; ++i) finite = finite && isfinite(l->points[i].x) && isfinite(l->points[i].y);
    for (int i = 0; i < l->count; ++i) finite = finite && isfinite(l->shapes[i].width);
    if (!finite) {
        ori_fab_layout_destroy(l);
        return ori__fail(error, ORI_ERR_RANGE, "fab: a shape reaches beyond the range of coordinates (lengths too large "
                                               "for the pattern's unit)");
    }
    *out = l;
    return ORI_OK;
}
