// Design data: the hinges, panels and actuation of a crease pattern, read from (and written to)
// the FOLD custom fields edges_orikin:hinge, faces_orikin:panel and orikin:actuation; lengths
// converted from the file's frame_unit to metres; the panels' mass properties; the wire loops.
#include <jansson.h>
#include <stdlib.h>

#include "../core/json_internal.h"
#include "mechanics_internal.h"

#define GRAVITY_STANDARD 9.80665 // m/s², the standard acceleration of gravity (CGPM 1901)

// --- units -------------------------------------------------------------------------------------

ori_status ori_unit_meters(const char *unit, double *meters, ori_error *error)
{
    ORI_ASSERT(unit && meters);
    static const struct {
        const char *name;
        double m;
    } units[] = {{"m", 1.0},     {"cm", 1e-2},    {"mm", 1e-3},          {"um", 1e-6},
                 {"\xc2\xb5m", 1e-6}, {"nm", 1e-9}, {"in", 0.0254}, {"pt", 0.0254 / 72.0}};
    for (size_t i = 0; i < sizeof units / sizeof units[0]; ++i)
        if (strcmp(unit, units[i].name) == 0) {
            *meters = units[i].m;
            return ORI_OK;
        }
    if (strcmp(unit, "unit") == 0)
        return ori__fail_at(error, ORI_ERR_ARGUMENT, "frame_unit", ORI_NULL_INDEX,
                            "the coordinates are unitless (\"unit\"): give the length unit");
    return ori__fail_at(error, ORI_ERR_ARGUMENT, "frame_unit", ORI_NULL_INDEX,
                        "unknown length unit \"%s\" (m, cm, mm, um, nm, in, pt)", unit);
}

// --- mass properties -----------------------------------------------------------------------------

static ori_face_mass polygon_mass(const ori_v3 *v, const int *idx, int n, double mpu, double thickness, double density)
{
    ori_face_mass r;
    memset(&r, 0, sizeof r);
    // Green's theorem in coordinates relative to the first vertex (well conditioned far from
    // the origin), metres.
    ori_v3 o = v[idx[0]];
    double a = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    for (int i = 0; i < n; ++i) {
        ori_v3 p = v[idx[i]], q = v[idx[(i + 1) % n]];
        double x0 = (p.x - o.x) * mpu, y0 = (p.y - o.y) * mpu, x1 = (q.x - o.x) * mpu, y1 = (q.y - o.y) * mpu;
        double cr = x0 * y1 - x1 * y0;
        a += cr;
        sx += (x0 + x1) * cr;
        sy += (y0 + y1) * cr;
        sxx += (x0 * x0 + x0 * x1 + x1 * x1) * cr;
        syy += (y0 * y0 + y0 * y1 + y1 * y1) * cr;
        sxy += (x0 * y1 + 2.0 * x0 * y0 + 2.0 * x1 * y1 + x1 * y0) * cr;
    }
    a *= 0.5;
    if (a == 0.0) return r;
    double cx = sx / (6.0 * a), cy = sy / (6.0 * a);
    // Second moments of area about the centroid (the sign of a cancels for clockwise faces).
    double ixx = sxx / 12.0 - a * cx * cx, iyy = syy / 12.0 - a * cy * cy, ixy = sxy / 24.0 - a * cx * cy;
    double area = fabs(a), sg = a < 0 ? -1.0 : 1.0;
    ixx *= sg;
    iyy *= sg;
    ixy *= sg;
    double rho_h = density * thickness;
    r.mass_kg = rho_h * area;
    r.centroid_m = ori_v3_make(o.x * mpu + cx, o.y * mpu + cy, 0.0);
    double slab = r.mass_kg * thickness * thickness / 12.0; // the slab's extent in z
    ori_m3 I = {{{rho_h * iyy + slab, -rho_h * ixy, 0.0}, {-rho_h * ixy, rho_h * ixx + slab, 0.0},
                 {0.0, 0.0, rho_h * (ixx + iyy)}}};
    r.inertia_kg_m2 = I;
    return r;
}

// --- design record -------------------------------------------------------------------------------

ori_design_def ori_default_design_def(void)
{
    ori_design_def d;
    memset(&d, 0, sizeof d);
    d.internal_value = ORI__DEF_COOKIE;
    return d;
}

void ori_design_destroy(ori_design *d)
{
    if (!d) return;
    ori__free(d->vertices);
    ori__free(d->edges);
    ori__free(d->edge_faces);
    ori__free(d->assignment);
    ori__free(d->face_offsets);
    ori__free(d->face_verts);
    ori__free(d->has_hinge);
    ori__free(d->hinges);
    ori__free(d->has_panel);
    ori__free(d->panels);
    ori__free(d->mass);
    ori_materials_destroy(d->materials);
    ori__free(d);
}

double ori_design_meters_per_unit(const ori_design *d) { return d->meters_per_unit; }
int ori_design_edge_count(const ori_design *d) { return d->edge_count; }
int ori_design_face_count(const ori_design *d) { return d->face_count; }

static bool positive(double x) { return isfinite(x) && x > 0.0; }

#define HINGE_FAIL(...) ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_orikin:hinge", e, __VA_ARGS__)

// Point in the face polygon (pattern units), boundary included within the tolerance.
static bool in_face(const ori_design *d, int face, ori_v3 p)
{
    int n = d->face_offsets[face + 1] - d->face_offsets[face];
    const int *idx = d->face_verts + d->face_offsets[face];
    double tol = ORI_ACT_WIRE_INSIDE_REL * d->diagonal;
    bool inside = false;
    for (int i = 0; i < n; ++i) {
        ori_v3 a = d->vertices[idx[i]], b = d->vertices[idx[(i + 1) % n]];
        // Distance to the side: on the boundary counts as inside.
        ori_v3 ab = ori_v3_sub(b, a), ap = ori_v3_sub(p, a);
        double L2 = ori_v3_dot(ab, ab), s = L2 > 0 ? ori_v3_dot(ap, ab) / L2 : 0.0;
        s = s < 0 ? 0 : s > 1 ? 1 : s;
        ori_v3 c = ori_v3_add(a, ori_v3_scale(ab, s));
        if (hypot(p.x - c.x, p.y - c.y) <= tol) return true;
        if ((a.y > p.y) != (b.y > p.y)) {
            double x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
            if (p.x < x) inside = !inside;
        }
    }
    return inside;
}

// The wire loop of hinge h on `edge` placed on `face`; false when its centre is outside the face.
static bool segments_of(const ori_design *d, int edge, const ori_hinge *h, int face, wire_segments *out)
{
    ori_v3 v0 = d->vertices[d->edges[edge][0]], v1 = d->vertices[d->edges[edge][1]];
    ori_v3 w = ori_v3_normalize(ori_v3_sub(v1, v0));
    ori_v3 left = ori_v3_make(-w.y, w.x, 0.0);
    ori_v3 dir = face == d->edge_faces[edge][0] ? left : ori_v3_scale(left, -1.0);
    double mpu = d->meters_per_unit;
    ori_v3 mid = ori_v3_scale(ori_v3_add(v0, v1), 0.5);
    ori_v3 half = ori_v3_scale(w, 0.5 * h->wire.length_m / mpu), lev = ori_v3_scale(dir, h->wire.lever_m / mpu);
    ori_v3 h1 = ori_v3_sub(mid, half), h2 = ori_v3_add(mid, half);
    ori_v3 w1 = ori_v3_add(h1, lev), w2 = ori_v3_add(h2, lev);
    out->a[0] = h1, out->b[0] = w1; // out along the panel
    out->a[1] = w1, out->b[1] = w2; // the wire, along the edge direction
    out->a[2] = w2, out->b[2] = h2; // back to the hinge
    out->a[3] = h2, out->b[3] = h1; // closing along the crease, on the other face
    out->turns = h->wire.turns;
    out->other = face == d->edge_faces[edge][0] ? d->edge_faces[edge][1] : d->edge_faces[edge][0];
    return in_face(d, face, ori_v3_add(mid, lev));
}

bool ori__wire_segments(const ori_design *d, int edge, int face, wire_segments *out)
{
    if (!d->has_hinge[edge] || !d->hinges[edge].has_wire) return false;
    return segments_of(d, edge, &d->hinges[edge], face, out);
}

void ori__wire_wrench(const ori_design *d, const wire_segments *w, int first, int last, ori_rigid g, double current_a,
                      ori_v3 field_t, ori_v3 *force, ori_v3 *moment)
{
    double mpu = d->meters_per_unit;
    ori_v3 f = ori_v3_make(0, 0, 0), m = ori_v3_make(0, 0, 0);
    for (int s = first; s < last; ++s) {
        ori_v3 a = ori_v3_scale(ori_rigid_apply(g, w->a[s]), mpu), b = ori_v3_scale(ori_rigid_apply(g, w->b[s]), mpu);
        ori_v3 fs = ori_v3_scale(ori_v3_cross(ori_v3_sub(b, a), field_t), (double)w->turns * current_a);
        ori_v3 p = ori_v3_scale(ori_v3_add(a, b), 0.5);
        f = ori_v3_add(f, fs);
        m = ori_v3_add(m, ori_v3_cross(p, fs));
    }
    *force = f;
    *moment = m;
}

static ori_status validate_hinge(const ori_design *d, int e, const ori_hinge *h, ori_error *error)
{
    char name[ORI_MATERIAL_NAME_MAX + 1];
    ori__strlcpy(name, h->material, sizeof name);
    const ori_material *m = ori__materials_get(d->materials, h->material);
    if (!m) return HINGE_FAIL("unknown material \"%s\"", name);
    if (!m->has_yield)
        return HINGE_FAIL("material %s does not yield: it cannot be a plastic hinge", name);
    if (!positive(h->width_m)) return HINGE_FAIL("width must be a positive length in metres");
    if (!positive(h->thickness_m))
        return HINGE_FAIL("thickness must be a positive length in metres");
    if (!positive(h->span_m)) return HINGE_FAIL("span must be a positive length in metres");
    if (d->edge_faces[e][0] == ORI_NULL_INDEX || d->edge_faces[e][1] == ORI_NULL_INDEX)
        return HINGE_FAIL("edge %d is not a crease between two faces", e);
    if (!h->has_wire) return ORI_OK;
    const ori_wire *w = &h->wire;
    if (!m->has_resistivity)
        return HINGE_FAIL("material %s is not a conductor: it cannot carry the wire's current", name);
    const char *bad = !positive(w->length_m)      ? "wire.length"
                      : !positive(w->lever_m)     ? "wire.lever"
                      : !positive(w->width_m)     ? "wire.width"
                      : !positive(w->thickness_m) ? "wire.thickness"
                                                  : NULL;
    if (bad) return HINGE_FAIL("%s must be a positive length in metres", bad);
    if (w->turns < 1) return HINGE_FAIL("wire.turns must be an integer >= 1");
    if (w->has_current && !(isfinite(w->current_a) && w->current_a >= 0.0))
        return HINGE_FAIL("wire.current must be a current >= 0 in amperes");
    if (w->face != ORI_NULL_INDEX && w->face != d->edge_faces[e][0] && w->face != d->edge_faces[e][1])
        return HINGE_FAIL("wire.face is not one of the crease's two faces");
    // The wire must lie on a panel beside the crease: on the named face, or on one of the two.
    bool ok = false;
    for (int s = 0; s < 2; ++s) {
        int f = d->edge_faces[e][s];
        if (w->face != ORI_NULL_INDEX && f != w->face) continue;
        wire_segments ws;
        ok |= segments_of(d, e, h, f, &ws);
    }
    if (!ok)
        return HINGE_FAIL("wire.lever %g m puts the wire outside its panel", h->wire.lever_m);
    return ORI_OK;
}

static ori_status validate_panel(const ori_design *d, int f, const ori_panel *p, ori_error *error)
{
    const ori_material *m = ori__materials_get(d->materials, p->material);
    if (!m)
        return ori__fail_at(error, ORI_ERR_ARGUMENT, "faces_orikin:panel", f, "unknown material \"%s\"", p->material);
    if (!positive(p->thickness_m))
        return ori__fail_at(error, ORI_ERR_ARGUMENT, "faces_orikin:panel", f,
                            "thickness must be a positive length in metres");
    return ORI_OK;
}

static bool nonzero_field(ori_v3 b) { return isfinite(b.x) && isfinite(b.y) && isfinite(b.z) && ori_v3_norm(b) > 0.0; }

static ori_status validate_actuation(const ori_design *d, const ori_actuation *a, ori_error *error)
{
    const char *F = "orikin:actuation";
    if (a->has_field && !nonzero_field(a->field_t))
        return ori__fail_at(error, ORI_ERR_ARGUMENT, F, ORI_NULL_INDEX, "field: the magnetic field is zero (or not finite)");
    if (a->has_current_limit && !positive(a->current_limit_a))
        return ori__fail_at(error, ORI_ERR_ARGUMENT, F, ORI_NULL_INDEX, "current_limit must be a positive current in amperes");
    ori_v3 g = a->gravity_m_s2;
    if (!(isfinite(g.x) && isfinite(g.y) && isfinite(g.z)))
        return ori__fail_at(error, ORI_ERR_ARGUMENT, F, ORI_NULL_INDEX, "gravity must be finite");
    if (!(isfinite(a->damping_ratio) && a->damping_ratio >= 0.0))
        return ori__fail_at(error, ORI_ERR_ARGUMENT, F, ORI_NULL_INDEX, "damping must be a ratio >= 0");
    if (a->reference_edge != ORI_NULL_INDEX && (a->reference_edge < 0 || a->reference_edge >= d->edge_count))
        return ori__fail_at(error, ORI_ERR_RANGE, F, ORI_NULL_INDEX, "crease %d does not exist", a->reference_edge);
    if (a->schedule_count < 0 || a->schedule_count > ORI_SCHEDULE_MAX)
        return ori__fail_at(error, ORI_ERR_LIMIT, F, ORI_NULL_INDEX, "schedule: at most %d entries", ORI_SCHEDULE_MAX);
    for (int i = 0; i < a->schedule_count; ++i) {
        const ori_field_change *c = &a->schedule[i];
        if (!nonzero_field(c->field_t))
            return ori__fail_at(error, ORI_ERR_ARGUMENT, F, ORI_NULL_INDEX, "schedule %d: the magnetic field is zero", i);
        if (!(isfinite(c->from_rad) && fabs(c->from_rad) <= ORI_PI + ORI_TOL_FOLD_SIGN_RAD))
            return ori__fail_at(error, ORI_ERR_RANGE, F, ORI_NULL_INDEX, "schedule %d: from_deg outside [-180, 180]", i);
        if (c->fold < 0) return ori__fail_at(error, ORI_ERR_RANGE, F, ORI_NULL_INDEX, "schedule %d: fold must be >= 1", i);
        if (c->edge != ORI_NULL_INDEX && (c->edge < 0 || c->edge >= d->edge_count))
            return ori__fail_at(error, ORI_ERR_RANGE, F, ORI_NULL_INDEX, "schedule %d: crease %d does not exist", i, c->edge);
    }
    return ORI_OK;
}

static void update_mass(ori_design *d, int f)
{
    memset(&d->mass[f], 0, sizeof d->mass[f]);
    if (!d->has_panel[f]) return;
    const ori_material *m = ori__materials_get(d->materials, d->panels[f].material);
    d->mass[f] = polygon_mass(d->vertices, d->face_verts + d->face_offsets[f], d->face_offsets[f + 1] - d->face_offsets[f],
                              d->meters_per_unit, d->panels[f].thickness_m, m->density_kg_m3);
}

// --- reading the FOLD fields -----------------------------------------------------------------------

static json_t *custom(const ori_fold *doc, const char *key, ori_error *error, ori_status *st)
{
    *st = ORI_OK;
    char *text = ori_fold_get_custom(doc, 0, key);
    if (!text) return NULL;
    json_t *v = ori__json_parse(text, strlen(text), JSON_DECODE_ANY, error);
    ori_buffer_free(text);
    if (!v) *st = ORI_ERR_PARSE;
    return v;
}

static bool keys_ok(json_t *obj, const char *const *keys, size_t n, const char **bad)
{
    const char *key;
    json_t *v;
    json_object_foreach(obj, key, v)
    {
        bool known = false;
        for (size_t i = 0; i < n; ++i) known |= strcmp(key, keys[i]) == 0;
        if (!known) {
            *bad = key;
            return false;
        }
    }
    return true;
}

// A number field: required (missing = error), or optional (missing leaves *out).
static bool get_number(json_t *obj, const char *key, bool required, double *out, bool *present)
{
    json_t *v = json_object_get(obj, key);
    if (present) *present = v && !json_is_null(v);
    if (!v || json_is_null(v)) return !required;
    if (!json_is_number(v)) return false;
    *out = json_number_value(v);
    return true;
}

static bool get_v3(json_t *v, ori_v3 *out)
{
    if (!json_is_array(v) || json_array_size(v) != 3) return false;
    double c[3];
    for (int i = 0; i < 3; ++i) {
        json_t *x = json_array_get(v, (size_t)i);
        if (!json_is_number(x)) return false;
        c[i] = json_number_value(x);
    }
    *out = ori_v3_make(c[0], c[1], c[2]);
    return true;
}

static const char *const hinge_keys[] = {"material", "width", "thickness", "span", "wire"};
static const char *const wire_keys[] = {"length", "lever", "turns", "face", "width", "thickness", "current"};

static ori_status parse_hinge(ori_design *d, int e, json_t *o, ori_hinge *h, ori_error *error)
{
    const char *F = "edges_orikin:hinge";
    memset(h, 0, sizeof *h);
    const char *bad = NULL;
    if (!json_is_object(o)) return ori__fail_at(error, ORI_ERR_TYPE, F, e, "must be null or an object");
    if (!keys_ok(o, hinge_keys, sizeof hinge_keys / sizeof hinge_keys[0], &bad))
        return ori__fail_at(error, ORI_ERR_ARGUMENT, F, e, "unknown key \"%s\"", bad);
    json_t *mat = json_object_get(o, "material");
    if (!json_is_string(mat)) return ori__fail_at(error, ORI_ERR_TYPE, F, e, "missing \"material\" (a name)");
    if (strlen(json_string_value(mat)) >= sizeof h->material)
        return ori__fail_at(error, ORI_ERR_ARGUMENT, F, e, "unknown material \"%.40s…\"", json_string_value(mat));
    ori__strlcpy(h->material, json_string_value(mat), sizeof h->material);
    if (!get_number(o, "width", true, &h->width_m, NULL))
        return ori__fail_at(error, ORI_ERR_TYPE, F, e, "\"width\" must be a length in metres");
    if (!get_number(o, "thickness", true, &h->thickness_m, NULL))
        return ori__fail_at(error, ORI_ERR_TYPE, F, e, "\"thickness\" must be a length in metres");
    bool has_span;
    h->span_m = ORI_HINGE_SPAN_PER_THICKNESS * h->thickness_m;
    if (!get_number(o, "span", false, &h->span_m, &has_span))
        return ori__fail_at(error, ORI_ERR_TYPE, F, e, "\"span\" must be a length in metres");
    json_t *w = json_object_get(o, "wire");
    if (!w || json_is_null(w)) return validate_hinge(d, e, h, error);
    if (!json_is_object(w)) return ori__fail_at(error, ORI_ERR_TYPE, F, e, "\"wire\" must be null or an object");
    if (!keys_ok(w, wire_keys, sizeof wire_keys / sizeof wire_keys[0], &bad))
        return ori__fail_at(error, ORI_ERR_ARGUMENT, F, e, "wire: unknown key \"%s\"", bad);
    h->has_wire = true;
    ori_wire *wi = &h->wire;
    wi->turns = 1;
    wi->face = ORI_NULL_INDEX;
    wi->width_m = h->width_m;
    wi->thickness_m = h->thickness_m;
    if (!get_number(w, "length", true, &wi->length_m, NULL))
        return ori__fail_at(error, ORI_ERR_TYPE, F, e, "wire.length must be a length in metres");
    if (!get_number(w, "lever", true, &wi->lever_m, NULL))
        return ori__fail_at(error, ORI_ERR_TYPE, F, e, "wire.lever must be a length in metres");
    if (!get_number(w, "width", false, &wi->width_m, NULL) || !get_number(w, "thickness", false, &wi->thickness_m, NULL))
        return ori__fail_at(error, ORI_ERR_TYPE, F, e, "wire.width and wire.thickness are lengths in metres");
    if (!get_number(w, "current", false, &wi->current_a, &wi->has_current))
        return ori__fail_at(error, ORI_ERR_TYPE, F, e, "wire.current must be a current in amperes");
    json_t *t = json_object_get(w, "turns");
    if (t && !json_is_null(t)) {
        if (!json_is_integer(t) || json_integer_value(t) < 1 || json_integer_value(t) > 1000000)
            return ori__fail_at(error, ORI_ERR_TYPE, F, e, "wire.turns must be an integer >= 1");
        wi->turns = (int)json_integer_value(t);
    }
    json_t *fc = json_object_get(w, "face");
    if (fc && !json_is_null(fc)) {
        if (!json_is_integer(fc) || json_integer_value(fc) < 0 || json_integer_value(fc) >= d->face_count)
            return ori__fail_at(error, ORI_ERR_TYPE, F, e, "wire.face must be a face index");
        wi->face = (int)json_integer_value(fc);
    }
    return validate_hinge(d, e, h, error);
}

static ori_status read_hinges(ori_design *d, const ori_fold *doc, ori_error *error)
{
    ori_status st;
    json_t *a = custom(doc, "edges_orikin:hinge", error, &st);
    if (!a) return st;
    if (!json_is_array(a) || json_array_size(a) != (size_t)d->edge_count) {
        json_decref(a);
        return ori__fail_at(error, ORI_ERR_TYPE, "edges_orikin:hinge", ORI_NULL_INDEX,
                            "must be an array with one entry (null or a hinge) per edge (%d)", d->edge_count);
    }
    for (int e = 0; e < d->edge_count && st == ORI_OK; ++e) {
        json_t *o = json_array_get(a, (size_t)e);
        if (json_is_null(o)) continue;
        st = parse_hinge(d, e, o, &d->hinges[e], error);
        d->has_hinge[e] = st == ORI_OK;
    }
    json_decref(a);
    return st;
}

static ori_status read_panels(ori_design *d, const ori_fold *doc, ori_error *error)
{
    const char *F = "faces_orikin:panel";
    ori_status st;
    json_t *a = custom(doc, F, error, &st);
    if (!a) return st;
    if (!json_is_array(a) || json_array_size(a) != (size_t)d->face_count) {
        json_decref(a);
        return ori__fail_at(error, ORI_ERR_TYPE, F, ORI_NULL_INDEX,
                            "must be an array with one entry (null or a panel) per face (%d)", d->face_count);
    }
    static const char *const keys[] = {"material", "thickness"};
    for (int f = 0; f < d->face_count && st == ORI_OK; ++f) {
        json_t *o = json_array_get(a, (size_t)f);
        if (json_is_null(o)) continue;
        const char *bad = NULL;
        ori_panel p;
        memset(&p, 0, sizeof p);
        json_t *mat = json_is_object(o) ? json_object_get(o, "material") : NULL;
        if (!json_is_object(o)) st = ori__fail_at(error, ORI_ERR_TYPE, F, f, "must be null or an object");
        else if (!keys_ok(o, keys, 2, &bad)) st = ori__fail_at(error, ORI_ERR_ARGUMENT, F, f, "unknown key \"%s\"", bad);
        else if (!json_is_string(mat) || strlen(json_string_value(mat)) >= sizeof p.material)
            st = ori__fail_at(error, ORI_ERR_TYPE, F, f, "\"material\" must be a material name");
        else if (!get_number(o, "thickness", true, &p.thickness_m, NULL))
            st = ori__fail_at(error, ORI_ERR_TYPE, F, f, "\"thickness\" must be a length in metres");
        if (st != ORI_OK) break;
        ori__strlcpy(p.material, json_string_value(mat), sizeof p.material);
        st = validate_panel(d, f, &p, error);
        if (st == ORI_OK) {
            d->panels[f] = p;
            d->has_panel[f] = true;
        }
    }
    json_decref(a);
    return st;
}

static ori_status read_actuation(ori_design *d, const ori_fold *doc, ori_error *error)
{
    const char *F = "orikin:actuation";
    ori_status st;
    json_t *o = custom(doc, F, error, &st);
    if (!o) return st;
    static const char *const keys[] = {"field", "current_limit", "gravity", "schedule", "crease", "damping"};
    const char *bad = NULL;
    ori_actuation *a = &d->act;
    json_t *v;
    if (!json_is_object(o)) {
        st = ori__fail_at(error, ORI_ERR_TYPE, F, ORI_NULL_INDEX, "must be an object");
        goto done;
    }
    if (!keys_ok(o, keys, sizeof keys / sizeof keys[0], &bad)) {
        st = ori__fail_at(error, ORI_ERR_ARGUMENT, F, ORI_NULL_INDEX, "unknown key \"%s\"", bad);
        goto done;
    }
    if ((v = json_object_get(o, "field")) && !json_is_null(v)) {
        if (!get_v3(v, &a->field_t)) {
            st = ori__fail_at(error, ORI_ERR_TYPE, F, ORI_NULL_INDEX, "field must be [Bx, By, Bz] in teslas");
            goto done;
        }
        a->has_field = true;
    }
    if (!get_number(o, "current_limit", false, &a->current_limit_a, &a->has_current_limit) ||
        !get_number(o, "damping", false, &a->damping_ratio, NULL)) {
        st = ori__fail_at(error, ORI_ERR_TYPE, F, ORI_NULL_INDEX, "current_limit (A) and damping (ratio) are numbers");
        goto done;
    }
    if ((v = json_object_get(o, "gravity")) && !json_is_null(v)) {
        if (json_is_boolean(v)) a->gravity_m_s2 = ori_v3_make(0, 0, json_is_true(v) ? -GRAVITY_STANDARD : 0.0);
        else if (!get_v3(v, &a->gravity_m_s2)) {
            st = ori__fail_at(error, ORI_ERR_TYPE, F, ORI_NULL_INDEX, "gravity must be true, false or [gx, gy, gz] in m/s²");
            goto done;
        }
    }
    if ((v = json_object_get(o, "crease")) && !json_is_null(v)) {
        if (!json_is_integer(v) || json_integer_value(v) < 0 || json_integer_value(v) >= d->edge_count) {
            st = ori__fail_at(error, ORI_ERR_TYPE, F, ORI_NULL_INDEX, "crease must be an edge index");
            goto done;
        }
        a->reference_edge = (int)json_integer_value(v);
    }
    if ((v = json_object_get(o, "schedule")) && !json_is_null(v)) {
        if (!json_is_array(v) || json_array_size(v) > ORI_SCHEDULE_MAX) {
            st = ori__fail_at(error, ORI_ERR_TYPE, F, ORI_NULL_INDEX, "schedule must be an array of at most %d entries",
                              ORI_SCHEDULE_MAX);
            goto done;
        }
        static const char *const skeys[] = {"from_deg", "field", "crease", "fold"};
        for (size_t i = 0; i < json_array_size(v); ++i) {
            json_t *s = json_array_get(v, i);
            ori_field_change *c = &a->schedule[a->schedule_count];
            double deg = 0.0;
            c->edge = ORI_NULL_INDEX;
            json_t *ce = json_is_object(s) ? json_object_get(s, "crease") : NULL;
            json_t *fo = json_is_object(s) ? json_object_get(s, "fold") : NULL;
            if (!json_is_object(s) || !keys_ok(s, skeys, 4, &bad) ||
                (fo && !json_is_null(fo) && (!json_is_integer(fo) || json_integer_value(fo) < 1 || json_integer_value(fo) > 1000000)) || !get_number(s, "from_deg", true, &deg, NULL) ||
                !get_v3(json_object_get(s, "field"), &c->field_t) ||
                (ce && !json_is_null(ce) &&
                 (!json_is_integer(ce) || json_integer_value(ce) < 0 || json_integer_value(ce) >= d->edge_count))) {
                st = ori__fail_at(error, ORI_ERR_TYPE, F, ORI_NULL_INDEX,
                                  "schedule %zu must be {\"from_deg\": x, \"field\": [Bx, By, Bz], \"crease\": e, \"fold\": k "
                                  "(both optional)}",
                                  i);
                goto done;
            }
            if (ce && !json_is_null(ce)) c->edge = (int)json_integer_value(ce);
            c->fold = fo && !json_is_null(fo) ? (int)json_integer_value(fo) - 1 : 0;
            c->from_rad = ori_deg_to_rad(deg);
            a->schedule_count++;
        }
    }
    st = validate_actuation(d, a, error);
done:
    json_decref(o);
    return st;
}

ori_status ori_design_create(const ori_design_def *def, ori_design **out, ori_error *error)
{
    ORI_ASSERT(def && out && def->internal_value == ORI__DEF_COOKIE && def->pattern);
    *out = NULL;
    const ori_pattern *p = def->pattern;
    ORI_ASSERT(ori_pattern_is_built(p));
    ori_design *d = ori__calloc(1, sizeof *d);
    d->materials = ori_materials_create();
    if (def->materials) ori__materials_copy(d->materials, def->materials);
    d->vertex_count = ori_pattern_vertex_count(p);
    d->edge_count = ori_pattern_edge_count(p);
    d->face_count = ori_pattern_face_count(p);
    d->diagonal = ori_pattern_diagonal(p);
    d->act.reference_edge = ORI_NULL_INDEX;
    int V = d->vertex_count, E = d->edge_count, F = d->face_count;
    d->vertices = ori__alloc(sizeof(ori_v3) * (size_t)(V + 1));
    for (int v = 0; v < V; ++v) d->vertices[v] = ori_pattern_vertex(p, v);
    d->edges = ori__alloc(sizeof(int[2]) * (size_t)(E + 1));
    d->edge_faces = ori__alloc(sizeof(int[2]) * (size_t)(E + 1));
    d->assignment = ori__alloc(sizeof(ori_assignment) * (size_t)(E + 1));
    for (int e = 0; e < E; ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        d->edges[e][0] = ed.v[0];
        d->edges[e][1] = ed.v[1];
        d->assignment[e] = ed.assignment;
        ori_pattern_edge_faces(p, e, d->edge_faces[e]);
    }
    d->face_offsets = ori__alloc(sizeof(int) * (size_t)(F + 1));
    int total = 0;
    for (int f = 0; f < F; ++f) total += ori_pattern_face_size(p, f);
    d->face_verts = ori__alloc(sizeof(int) * (size_t)(total + 1));
    d->face_offsets[0] = 0;
    for (int f = 0; f < F; ++f) {
        int n = ori_pattern_face_size(p, f);
        ori_pattern_face_vertices(p, f, d->face_verts + d->face_offsets[f], n);
        d->face_offsets[f + 1] = d->face_offsets[f] + n;
    }
    d->has_hinge = ori__calloc((size_t)E + 1, sizeof(bool));
    d->hinges = ori__calloc((size_t)E + 1, sizeof(ori_hinge));
    d->has_panel = ori__calloc((size_t)F + 1, sizeof(bool));
    d->panels = ori__calloc((size_t)F + 1, sizeof(ori_panel));
    d->mass = ori__calloc((size_t)F + 1, sizeof(ori_face_mass));

    ori_status st = ORI_OK;
    if (def->has_meters_per_unit) {
        if (!positive(def->meters_per_unit))
            st = ori__fail_at(error, ORI_ERR_ARGUMENT, "frame_unit", ORI_NULL_INDEX, "the length unit must be positive");
        d->meters_per_unit = def->meters_per_unit;
    } else {
        char *unit = def->doc ? ori_fold_get_custom(def->doc, 0, "frame_unit") : NULL;
        json_t *u = unit ? json_loads(unit, JSON_DECODE_ANY, NULL) : NULL;
        if (unit && !json_is_string(u))
            st = ori__fail_at(error, ORI_ERR_TYPE, "frame_unit", ORI_NULL_INDEX, "must be a string");
        else
            st = ori_unit_meters(u ? json_string_value(u) : "unit", &d->meters_per_unit, error);
        json_decref(u);
        ori_buffer_free(unit);
    }
    if (st == ORI_OK && def->doc) st = read_panels(d, def->doc, error);
    if (st == ORI_OK && def->doc) st = read_hinges(d, def->doc, error);
    if (st == ORI_OK && def->doc) st = read_actuation(d, def->doc, error);
    if (st != ORI_OK) {
        ori_design_destroy(d);
        return st;
    }
    for (int f = 0; f < F; ++f) update_mass(d, f);
    *out = d;
    return ORI_OK;
}

// --- accessors and setters -------------------------------------------------------------------------

bool ori_design_hinge(const ori_design *d, int e, ori_hinge *out)
{
    ORI_ASSERT(d && e >= 0 && e < d->edge_count);
    if (!d->has_hinge[e]) return false;
    if (out) *out = d->hinges[e];
    return true;
}

ori_status ori_design_set_hinge(ori_design *d, int e, const ori_hinge *h, ori_error *error)
{
    ORI_ASSERT(d && e >= 0 && e < d->edge_count);
    if (!h) {
        d->has_hinge[e] = false;
        return ORI_OK;
    }
    ori_status st = validate_hinge(d, e, h, error);
    if (st != ORI_OK) return st;
    d->hinges[e] = *h;
    d->has_hinge[e] = true;
    return ORI_OK;
}

bool ori_design_panel(const ori_design *d, int f, ori_panel *out)
{
    ORI_ASSERT(d && f >= 0 && f < d->face_count);
    if (!d->has_panel[f]) return false;
    if (out) *out = d->panels[f];
    return true;
}

ori_status ori_design_set_panel(ori_design *d, int f, const ori_panel *p, ori_error *error)
{
    ORI_ASSERT(d && f >= 0 && f < d->face_count);
    if (p) {
        ori_status st = validate_panel(d, f, p, error);
        if (st != ORI_OK) return st;
        d->panels[f] = *p;
    }
    d->has_panel[f] = p != NULL;
    update_mass(d, f);
    return ORI_OK;
}

ori_actuation ori_design_actuation(const ori_design *d)
{
    ORI_ASSERT(d);
    return d->act;
}

ori_status ori_design_set_actuation(ori_design *d, const ori_actuation *a, ori_error *error)
{
    ORI_ASSERT(d && a);
    ori_status st = validate_actuation(d, a, error);
    if (st == ORI_OK) d->act = *a;
    return st;
}

bool ori__design_section(const ori_design *d, int e, hinge_section *out)
{
    if (!d->has_hinge[e]) return false;
    const ori_hinge *h = &d->hinges[e];
    const ori_material *m = ori__materials_get(d->materials, h->material);
    out->k = ori_hinge_stiffness(m->youngs_modulus_pa, h->width_m, h->thickness_m, h->span_m);
    out->m_y = ori_hinge_yield_moment(m->yield_strength_pa, h->width_m, h->thickness_m);
    out->m_p = ori_hinge_plastic_moment(m->yield_strength_pa, h->width_m, h->thickness_m);
    out->th_y = out->m_y / out->k;
    out->rest = 0.0;
    return true;
}

bool ori_design_hinge_mechanics(const ori_design *d, int e, ori_hinge_mechanics *out)
{
    ORI_ASSERT(d && out && e >= 0 && e < d->edge_count);
    memset(out, 0, sizeof *out);
    hinge_section s;
    if (!ori__design_section(d, e, &s)) return false;
    const ori_hinge *h = &d->hinges[e];
    const ori_material *m = ori__materials_get(d->materials, h->material);
    out->stiffness_nm_rad = s.k;
    out->yield_moment_nm = s.m_y;
    out->plastic_moment_nm = s.m_p;
    out->yield_rotation_rad = s.th_y;
    if (!h->has_wire) return true;
    const ori_wire *w = &h->wire;
    out->has_wire = true;
    out->wire_path_m = (double)w->turns * (w->length_m + 2.0 * w->lever_m);
    out->resistance_ohm = ori_wire_resistance(m->resistivity_ohm_m, out->wire_path_m, w->width_m, w->thickness_m);
    out->conductor_area_m2 = fmin(h->width_m * h->thickness_m, w->width_m * w->thickness_m);
    out->has_current_density_max = m->has_current_density_max;
    if (m->has_current_density_max) out->current_max_a = m->current_density_max_a_m2 * out->conductor_area_m2;
    return true;
}

ori_face_mass ori_design_face_mass(const ori_design *d, int f)
{
    ORI_ASSERT(d && f >= 0 && f < d->face_count);
    return d->mass[f];
}

int ori_design_wire_face(const ori_design *d, const ori_mechanism *m, int e, int fixed_face)
{
    ORI_ASSERT(d && m && e >= 0 && e < d->edge_count && fixed_face >= 0 && fixed_face < d->face_count);
    if (!d->has_hinge[e] || !d->hinges[e].has_wire) return ORI_NULL_INDEX;
    if (d->hinges[e].wire.face != ORI_NULL_INDEX) return d->hinges[e].wire.face;
    int F = d->face_count;
    int *parent = ori__alloc(sizeof(int) * (size_t)F), *pedge = ori__alloc(sizeof(int) * (size_t)F);
    ori_mechanism_spanning_tree(m, fixed_face, parent, pedge);
    int a = d->edge_faces[e][0], b = d->edge_faces[e][1];
    int pick;
    if (pedge[a] == e) pick = a;
    else if (pedge[b] == e) pick = b;
    else {
        // A crease that closes a loop: the face farther from the fixed face.
        int da = 0, db = 0;
        for (int f = a; parent[f] != ORI_NULL_INDEX; f = parent[f]) da++;
        for (int f = b; parent[f] != ORI_NULL_INDEX; f = parent[f]) db++;
        pick = db > da ? b : a;
    }
    ori__free(parent);
    ori__free(pedge);
    return pick;
}

double ori__wire_moment(const ori_design *d, int e, int f, const ori_rigid *poses, double current_a, ori_v3 field_t)
{
    wire_segments w;
    ori__wire_segments(d, e, f, &w);
    ori_v3 force, moment;
    ori__wire_wrench(d, &w, 0, 3, poses[f], current_a, field_t, &force, &moment);
    double mpu = d->meters_per_unit;
    ori_v3 v0 = d->vertices[d->edges[e][0]], v1 = d->vertices[d->edges[e][1]];
    ori_v3 q = ori_v3_scale(ori_rigid_apply(poses[f], v0), mpu);
    ori_v3 axis = ori_v3_normalize(ori_rigid_apply_dir(poses[f], ori_v3_sub(v1, v0)));
    // Moment about the axis through q: (M_O − q × F)·ω. On face_left a positive moment about ω
    // opens the valley (θ grows); on face_right it closes it.
    double mw = ori_v3_dot(axis, ori_v3_sub(moment, ori_v3_cross(q, force)));
    return f == d->edge_faces[e][0] ? mw : -mw;
}

double ori_design_wire_moment(const ori_design *d, const ori_mechanism *m, int e, int fixed_face, const ori_rigid *poses,
                              double current_a, ori_v3 field_t)
{
    ORI_ASSERT(d && m && poses);
    int f = ori_design_wire_face(d, m, e, fixed_face);
    if (f == ORI_NULL_INDEX) return 0.0;
    return ori__wire_moment(d, e, f, poses, current_a, field_t);
}

// --- writing ---------------------------------------------------------------------------------------

static json_t *v3_json(ori_v3 v) { return json_pack("[fff]", v.x, v.y, v.z); }

ori_status ori_design_write(const ori_design *d, ori_fold *doc, ori_error *error)
{
    ORI_ASSERT(d && doc);
    json_t *hinges = json_array(), *panels = json_array();
    bool any_hinge = false, any_panel = false;
    for (int e = 0; e < d->edge_count; ++e) {
        if (!d->has_hinge[e]) {
            json_array_append_new(hinges, json_null());
            continue;
        }
        any_hinge = true;
        const ori_hinge *h = &d->hinges[e];
        json_t *o = json_pack("{s:s,s:f,s:f,s:f}", "material", h->material, "width", h->width_m, "thickness",
                              h->thickness_m, "span", h->span_m);
        if (h->has_wire) {
            const ori_wire *w = &h->wire;
            json_t *wo = json_pack("{s:f,s:f,s:i}", "length", w->length_m, "lever", w->lever_m, "turns", w->turns);
            if (w->face != ORI_NULL_INDEX) json_object_set_new(wo, "face", json_integer(w->face));
            if (w->width_m != h->width_m) json_object_set_new(wo, "width", json_real(w->width_m));
            if (w->thickness_m != h->thickness_m) json_object_set_new(wo, "thickness", json_real(w->thickness_m));
            if (w->has_current) json_object_set_new(wo, "current", json_real(w->current_a));
            json_object_set_new(o, "wire", wo);
        } else {
            json_object_set_new(o, "wire", json_null());
        }
        json_array_append_new(hinges, o);
    }
    for (int f = 0; f < d->face_count; ++f) {
        if (!d->has_panel[f]) {
            json_array_append_new(panels, json_null());
            continue;
        }
        any_panel = true;
        json_array_append_new(panels, json_pack("{s:s,s:f}", "material", d->panels[f].material, "thickness",
                                                d->panels[f].thickness_m));
    }
    const ori_actuation *a = &d->act;
    json_t *act = json_object();
    if (a->has_field) json_object_set_new(act, "field", v3_json(a->field_t));
    if (a->has_current_limit) json_object_set_new(act, "current_limit", json_real(a->current_limit_a));
    ori_v3 g = a->gravity_m_s2;
    if (g.x == 0 && g.y == 0 && (g.z == 0 || g.z == -GRAVITY_STANDARD)) json_object_set_new(act, "gravity", json_boolean(g.z != 0));
    else json_object_set_new(act, "gravity", v3_json(g));
    if (a->schedule_count) {
        json_t *s = json_array();
        for (int i = 0; i < a->schedule_count; ++i) {
            json_t *o = json_pack("{s:f,s:o}", "from_deg", ori_rad_to_deg_output(a->schedule[i].from_rad), "field",
                                  v3_json(a->schedule[i].field_t));
            if (a->schedule[i].edge != ORI_NULL_INDEX) json_object_set_new(o, "crease", json_integer(a->schedule[i].edge));
            if (a->schedule[i].fold != 0) json_object_set_new(o, "fold", json_integer(a->schedule[i].fold + 1));
            json_array_append_new(s, o);
        }
        json_object_set_new(act, "schedule", s);
    }
    if (a->reference_edge != ORI_NULL_INDEX) json_object_set_new(act, "crease", json_integer(a->reference_edge));
    if (a->damping_ratio != 0.0) json_object_set_new(act, "damping", json_real(a->damping_ratio));
    ori_status st = ORI_OK;
    const char *keys[3] = {"edges_orikin:hinge", "faces_orikin:panel", "orikin:actuation"};
    json_t *vals[3] = {any_hinge ? hinges : NULL, any_panel ? panels : NULL, act};
    for (int i = 0; i < 3 && st == ORI_OK; ++i) {
        char *text = vals[i] ? json_dumps(vals[i], JSON_COMPACT | JSON_REAL_PRECISION(17)) : NULL;
        st = ori_fold_set_custom(doc, 0, keys[i], text, error);
        free(text);
    }
    json_decref(hinges);
    json_decref(panels);
    json_decref(act);
    return st;
}
