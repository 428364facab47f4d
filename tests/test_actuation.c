// Hinge mechanics and Lorentz actuation (issue 11): the materials table (built-in = data file),
// the design formulas, the FOLD design data and its errors, the Lorentz moment from the posed
// sheet against I·w·L·B·cos Θ, the layered elastoplastic section, the quasi-static sizing of
// the thesis' flap (width range, field reorientation, optimal thickness), the open corner with
// gold hinges, and the minimum-norm point behind the field schedule.
#define _POSIX_C_SOURCE 200809L
#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <orikin/actuation.h>

#include "mechanics/mechanics_internal.h"
#include "support.h"

TestSuite(actuation, .init = test_leak_setup, .fini = test_leak_check);

#define DEG (ORI_PI / 180.0)

static double rel(double a, double b) { return fabs(a - b) / fmax(fabs(b), 1e-300); }

// A design example loaded whole: document, flat pattern, mechanism, design.
typedef struct loaded {
    ori_fold *doc;
    ori_pattern *p;
    ori_mechanism *m;
    ori_design *d;
} loaded;

static ori_status load_text(const char *text, const ori_design_def *base, loaded *x, ori_error *err)
{
    memset(x, 0, sizeof *x);
    cr_assert_eq(ori_fold_load_string(text, strlen(text), &x->doc, err), ORI_OK, "%s", err->message);
    cr_assert_eq(ori_fold_get_pattern(x->doc, 0, NULL, &x->p, err), ORI_OK, "%s", err->message);
    x->m = test_mechanism_of(x->p);
    ori_design_def dd = base ? *base : ori_default_design_def();
    dd.doc = x->doc;
    dd.pattern = x->p;
    return ori_design_create(&dd, &x->d, err);
}

static void loaded_free(loaded *x)
{
    ori_design_destroy(x->d);
    ori_mechanism_destroy(x->m);
    ori_pattern_destroy(x->p);
    ori_fold_destroy(x->doc);
}

static char *example_text(const char *rel_path)
{
    char *t = test_read_text(test_repo_path(rel_path));
    cr_assert_not_null(t);
    return t;
}

static loaded load_example(const char *rel_path)
{
    char *t = example_text(rel_path);
    loaded x;
    ori_error err;
    cr_assert_eq(load_text(t, NULL, &x, &err), ORI_OK, "%s: %s", err.field, err.message);
    free(t);
    return x;
}

// The flap's FOLD text with a JSON edit: path "key" or "key/index/key…", value JSON (NULL: delete).
static char *flap_edit(const char *path, const char *value)
{
    char *t = example_text("examples/patterns/thesis-flap.fold");
    json_error_t je;
    json_t *root = json_loads(t, 0, &je);
    free(t);
    cr_assert_not_null(root);
    char buf[256];
    snprintf(buf, sizeof buf, "%s", path);
    json_t *cur = root;
    char *save = NULL, *tok = strtok_r(buf, "/", &save), *next;
    while ((next = strtok_r(NULL, "/", &save))) {
        cur = json_is_array(cur) ? json_array_get(cur, (size_t)atoi(tok)) : json_object_get(cur, tok);
        cr_assert_not_null(cur, "%s", path);
        tok = next;
    }
    json_t *v = value ? json_loads(value, JSON_DECODE_ANY, &je) : NULL;
    if (json_is_array(cur)) {
        cr_assert(v);
        json_array_set_new(cur, (size_t)atoi(tok), v);
    } else if (v) {
        json_object_set_new(cur, tok, v);
    } else {
        json_object_del(cur, tok);
    }
    char *out = json_dumps(root, JSON_COMPACT | JSON_REAL_PRECISION(17));
    json_decref(root);
    return out;
}

static ori_error design_error(const char *path, const char *value)
{
    char *t = flap_edit(path, value);
    loaded x;
    ori_error err;
    ori_error_clear(&err);
    ori_status st = load_text(t, NULL, &x, &err);
    free(t);
    cr_assert_neq(st, ORI_OK, "%s = %s was accepted", path, value ? value : "(deleted)");
    loaded_free(&x);
    return err;
}

// --- materials -----------------------------------------------------------------------------

Test(actuation, builtin_materials_equal_the_data_file)
{
    // The table compiled in and data/materials.json (installed by make install) agree exactly.
    ori_materials *builtin = ori_materials_create();
    ori_materials *file = ori_materials_create();
    ori_error err;
    cr_assert_eq(ori_materials_load_file(file, test_repo_path("data/materials.json"), &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_materials_count(file), ori_materials_count(builtin));
    char *text = test_read_text(test_repo_path("data/materials.json"));
    json_t *root = json_loads(text, 0, NULL);
    free(text);
    cr_assert_eq((int)json_object_size(json_object_get(root, "materials")), ori_materials_count(builtin));
    json_decref(root);
    for (int i = 0; i < ori_materials_count(builtin); ++i) {
        ori_material a = ori_materials_at(builtin, i);
        int j = ori_materials_find(file, a.name);
        cr_assert_geq(j, 0, "%s missing from data/materials.json", a.name);
        ori_material b = ori_materials_at(file, j);
        cr_assert(a.youngs_modulus_pa == b.youngs_modulus_pa && a.density_kg_m3 == b.density_kg_m3, "%s", a.name);
        cr_assert(a.has_yield == b.has_yield && (!a.has_yield || a.yield_strength_pa == b.yield_strength_pa), "%s", a.name);
        cr_assert(a.has_resistivity == b.has_resistivity && (!a.has_resistivity || a.resistivity_ohm_m == b.resistivity_ohm_m),
                  "%s", a.name);
        cr_assert(a.has_current_density_max == b.has_current_density_max &&
                      (!a.has_current_density_max || a.current_density_max_a_m2 == b.current_density_max_a_m2),
                  "%s", a.name);
    }
    // Gold as in the thesis (ch. 2.2.2).
    ori_material au = ori_materials_at(builtin, ori_materials_find(builtin, "Au"));
    cr_assert(au.youngs_modulus_pa == 80e9 && au.yield_strength_pa == 206e6 && au.resistivity_ohm_m == 2.35e-8);
    // The JSON writer reads back to the same table.
    char *json = ori_materials_to_json(builtin);
    ori_materials *again = ori_materials_create();
    cr_assert_eq(ori_materials_load(again, json, strlen(json), &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_materials_count(again), ori_materials_count(builtin));
    ori_buffer_free(json);
    ori_materials_destroy(again);
    ori_materials_destroy(file);
    ori_materials_destroy(builtin);
}

Test(actuation, materials_extend_replace_and_reject)
{
    ori_materials *t = ori_materials_create();
    int n0 = ori_materials_count(t);
    ori_error err;
    const char *extend = "{\"materials\": {\"NiTi\": {\"youngs_modulus_Pa\": 75e9, \"density_kg_m3\": 6450, "
                         "\"yield_strength_Pa\": 560e6, \"resistivity_ohm_m\": 8.2e-7}, "
                         "\"Au\": {\"youngs_modulus_Pa\": 79e9, \"density_kg_m3\": 19300, \"yield_strength_Pa\": 100e6, "
                         "\"resistivity_ohm_m\": 2.2e-8}}}";
    cr_assert_eq(ori_materials_load(t, extend, strlen(extend), &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_materials_count(t), n0 + 1);
    ori_material au = ori_materials_at(t, ori_materials_find(t, "Au"));
    cr_assert(au.yield_strength_pa == 100e6 && !au.has_current_density_max); // replaced whole
    const char *bad[] = {
        "{\"materials\": {\"X\": {\"youngs_modulus_Pa\": -1, \"density_kg_m3\": 1}}}",
        "{\"materials\": {\"X\": {\"youngs_modulus_Pa\": 1e9}}}",
        "{\"materials\": {\"X\": {\"youngs_modulus_Pa\": 1e9, \"density_kg_m3\": 1, \"colour\": 3}}}",
        "{\"materials\": {\"X\": {\"youngs_modulus_Pa\": 1e9, \"density_kg_m3\": 0}}}",
        "{\"materials\": [1]}",
        "{\"materials\": {\"X\": {\"youngs_modulus_Pa\": 1e9, \"density_kg_m3\": 1}}, \"extra\": 1}",
        "{\"materials\": {",
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        ori_error_clear(&err);
        cr_assert_neq(ori_materials_load(t, bad[i], strlen(bad[i]), &err), ORI_OK, "%s", bad[i]);
        cr_assert_eq(ori_materials_count(t), n0 + 1, "a failed load changed the table");
    }
    const char *replace = "{\"replace\": true, \"materials\": {\"Only\": {\"youngs_modulus_Pa\": 1e9, \"density_kg_m3\": 1000}}}";
    cr_assert_eq(ori_materials_load(t, replace, strlen(replace), &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_materials_count(t), 1);
    cr_assert_eq(ori_materials_find(t, "Au"), ORI_NULL_INDEX);
    ori_materials_destroy(t);
}

// --- formulas -------------------------------------------------------------------------------

Test(actuation, hinge_and_wire_formulas)
{
    // Thesis eq. 1.1 and the beam formulas, for the thesis' gold hinge (tolerance 1e-12 relative).
    double sy = 206e6, E = 80e9, w = 10e-6, t = 0.6e-6, span = 12e-6;
    cr_assert_lt(rel(ori_hinge_plastic_moment(sy, w, t), 0.25 * w * t * t * sy), 1e-12);
    cr_assert_lt(rel(ori_hinge_plastic_moment(sy, w, t), 1.854e-10), 1e-12);
    cr_assert_lt(rel(ori_hinge_yield_moment(sy, w, t), sy * w * t * t / 6.0), 1e-12);
    cr_assert_lt(rel(ori_hinge_yield_moment(sy, w, t), 1.236e-10), 1e-12);
    cr_assert_lt(rel(ori_hinge_stiffness(E, w, t, span), E * w * t * t * t / (12.0 * span)), 1e-12);
    cr_assert_lt(rel(ori_hinge_stiffness(E, w, t, span), 1.2e-9), 1e-12);
    cr_assert_lt(rel(ori_wire_resistance(2.35e-8, 1.5e-3, w, t), 2.35e-8 * 1.5e-3 / (w * t)), 1e-12);
    cr_assert_lt(rel(ori_wire_resistance(2.35e-8, 1.5e-3, w, t), 5.875), 1e-12);
    // M_p = 1.5 M_y for a rectangle; the monotonic curve: k·θ to θ_y, then M_p(1 − ⅓(θ_y/θ)²).
    double k = 1.2e-9, my = 1.236e-10, thy = my / k;
    cr_assert_lt(rel(ori_hinge_monotonic_moment(k, my, 0.5 * thy), 0.5 * my), 1e-12);
    cr_assert_lt(rel(ori_hinge_monotonic_moment(k, my, thy), my), 1e-12);
    cr_assert_lt(rel(ori_hinge_monotonic_moment(k, my, 2 * thy), 1.5 * my * (1.0 - 1.0 / 12.0)), 1e-12);
    cr_assert_lt(rel(ori_hinge_monotonic_moment(k, my, -3 * thy), -1.5 * my * (1.0 - 1.0 / 27.0)), 1e-12);
    cr_assert_lt(rel(ori_hinge_monotonic_moment(k, my, 1e6 * thy), 1.5 * my), 1e-12);
    // The Lorentz moment of a wire about an axis: I·w·L·B for B along the lever, zero along the wire.
    ori_v3 q = ori_v3_make(0, 0, 0), x = ori_v3_make(1, 0, 0);
    ori_v3 c = ori_v3_make(0.25e-3, 0.5e-3, 0);
    cr_assert_lt(rel(ori_lorentz_axis_moment(q, x, c, x, 5e-4, 1, 0.02, ori_v3_make(0, 0.1, 0)), 0.02 * 5e-4 * 5e-4 * 0.1), 1e-12);
    cr_assert_lt(fabs(ori_lorentz_axis_moment(q, x, c, x, 5e-4, 1, 0.02, ori_v3_make(0.1, 0, 0))), 1e-25);
    cr_assert_lt(rel(ori_lorentz_axis_moment(q, x, c, x, 5e-4, 3, -0.02, ori_v3_make(0, 0.1, 0)), -3 * 0.02 * 5e-4 * 5e-4 * 0.1), 1e-12);
    double m;
    ori_error err;
    cr_assert_eq(ori_unit_meters("um", &m, &err), ORI_OK);
    cr_assert_eq(m, 1e-6);
    cr_assert_eq(ori_unit_meters("mm", &m, &err), ORI_OK);
    cr_assert_eq(m, 1e-3);
    cr_assert_eq(ori_unit_meters("unit", &m, &err), ORI_ERR_ARGUMENT);
    cr_assert_str_eq(err.field, "frame_unit");
    cr_assert_eq(ori_unit_meters("furlong", &m, &err), ORI_ERR_ARGUMENT);
}

Test(actuation, layered_section_elastic_plastic_springback)
{
    hinge_section s = {1.2e-9, 1.236e-10, 1.854e-10, 1.236e-10 / 1.2e-9, 0.0};
    hinge_fibres f = {{0}};
    // Elastic range: exact stiffness and energy ½kθ² (1e-12 relative).
    for (double u = -0.95; u <= 0.95; u += 0.1) {
        double th = u * s.th_y;
        cr_assert_lt(rel(ori__hinge_moment(&s, &f, th, NULL, NULL), s.k * th), 1e-12, "u = %g", u);
        cr_assert_lt(rel(ori__hinge_energy(&s, &f, th), 0.5 * s.k * th * th), 1e-12, "u = %g", u);
    }
    // Monotonic loading follows the rectangular section within the layering (1/ORI_HINGE_LAYERS of
    // M_p), and reaches M_p exactly once every fibre has yielded.
    double dissipated = 0.0, work = 0.0, prev_m = 0.0, prev_th = 0.0;
    for (int i = 1; i <= 4000; ++i) {
        double th = 8.0 * s.th_y * i / 4000.0, d;
        double mom = ori__hinge_moment(&s, &f, th, &f, &d);
        dissipated += d;
        work += 0.5 * (mom + prev_m) * (th - prev_th);
        prev_m = mom, prev_th = th;
        cr_assert_leq(fabs(mom - ori_hinge_monotonic_moment(s.k, s.m_y, th)), s.m_p / ORI_HINGE_LAYERS, "θ = %g θ_y",
                      th / s.th_y);
    }
    cr_assert_lt(rel(ori__hinge_moment(&s, &f, 1e4 * s.th_y, NULL, NULL), s.m_p), 1e-12);
    // Work in = stored elastic energy + plastic dissipation (trapezoid rule, 4000 increments).
    cr_assert_lt(rel(work, ori__hinge_energy(&s, &f, prev_th) + dissipated), 1e-6);
    // Unloading is elastic with the initial stiffness (the springback), over twice the elastic
    // range (Masing), leaving the permanent rotation θ − M/k.
    double th0 = prev_th, m0 = ori__hinge_moment(&s, &f, th0, NULL, NULL);
    for (double back = 0.0; back <= 1.9 * s.th_y; back += 0.1 * s.th_y)
        cr_assert_lt(fabs(ori__hinge_moment(&s, &f, th0 - back, NULL, NULL) - (m0 - s.k * back)), 1e-12 * s.m_p);
    double perm = ori__hinge_plastic_rotation(&s, &f, th0);
    cr_assert_lt(rel(perm, th0 - m0 / s.k), 1e-12);
    cr_assert_lt(fabs(ori__hinge_moment(&s, &f, perm, NULL, NULL)), 1e-12 * s.m_p);
}

// --- design data ----------------------------------------------------------------------------

Test(actuation, thesis_flap_design_data)
{
    loaded x = load_example("examples/patterns/thesis-flap.fold");
    cr_assert_eq(ori_design_meters_per_unit(x.d), 1e-6);
    ori_hinge h;
    cr_assert(ori_design_hinge(x.d, 0, &h));
    cr_assert(!ori_design_hinge(x.d, 1, NULL));
    cr_assert_str_eq(h.material, "Au");
    cr_assert(h.width_m == 10e-6 && h.thickness_m == 0.6e-6 && h.has_wire && h.wire.turns == 1);
    cr_assert(h.wire.width_m == h.width_m && h.wire.thickness_m == h.thickness_m); // defaults
    ori_hinge_mechanics hm;
    cr_assert(ori_design_hinge_mechanics(x.d, 0, &hm));
    cr_assert_lt(rel(hm.plastic_moment_nm, 1.854e-10), 1e-12);
    cr_assert_lt(rel(hm.wire_path_m, 1.5e-3), 1e-12);
    cr_assert_lt(rel(hm.resistance_ohm, 2.35e-8 * 1.5e-3 / (10e-6 * 0.6e-6)), 1e-12);
    cr_assert_lt(rel(hm.current_max_a, 2e9 * 10e-6 * 0.6e-6), 1e-12);
    // The 500 µm × 500 µm × 10 µm silicon flap: mass, centroid, inertia (1e-12 relative).
    ori_face_mass fm = ori_design_face_mass(x.d, 1);
    double a = 500e-6, t = 10e-6, mass = 2329.0 * a * a * t;
    cr_assert_lt(rel(fm.mass_kg, mass), 1e-12);
    cr_assert_lt(rel(fm.centroid_m.x, 250e-6), 1e-12);
    cr_assert_lt(rel(fm.centroid_m.y, 250e-6), 1e-12);
    cr_assert_lt(rel(fm.inertia_kg_m2.m[0][0], mass * (a * a + t * t) / 12.0), 1e-12);
    cr_assert_lt(rel(fm.inertia_kg_m2.m[2][2], mass * a * a / 6.0), 1e-12);
    cr_assert_lt(fabs(fm.inertia_kg_m2.m[0][1]), 1e-12 * fm.inertia_kg_m2.m[0][0]);
    ori_actuation act = ori_design_actuation(x.d);
    cr_assert(act.has_field && act.field_t.y == 0.1 && act.has_current_limit && act.current_limit_a == 0.02);
    cr_assert_eq(act.gravity_m_s2.z, -9.80665);
    cr_assert_eq(ori_design_wire_face(x.d, x.m, 0, 0), 1);
    cr_assert_eq(ori_design_wire_face(x.d, x.m, 0, 1), 0);
    // Written back and read again: the same design.
    ori_error err;
    cr_assert_eq(ori_design_write(x.d, x.doc, &err), ORI_OK);
    char *text = ori_fold_to_string(x.doc);
    loaded y;
    cr_assert_eq(load_text(text, NULL, &y, &err), ORI_OK, "%s", err.message);
    ori_buffer_free(text);
    ori_hinge h2;
    cr_assert(ori_design_hinge(y.d, 0, &h2));
    cr_assert(memcmp(&h, &h2, sizeof h) == 0 || (h.width_m == h2.width_m && h.span_m == h2.span_m &&
                                                  h.wire.lever_m == h2.wire.lever_m && h.wire.length_m == h2.wire.length_m));
    cr_assert_eq(ori_design_actuation(y.d).field_t.y, 0.1);
    loaded_free(&y);
    loaded_free(&x);
}

Test(actuation, bad_design_data_is_named)
{
    struct {
        const char *path, *value, *field;
        int element;
    } cases[] = {
        {"edges_orikin:hinge/0/material", "\"Unobtainium\"", "edges_orikin:hinge", 0},
        {"edges_orikin:hinge/0/width", "-1e-6", "edges_orikin:hinge", 0},
        {"edges_orikin:hinge/0/thickness", "0", "edges_orikin:hinge", 0},
        {"edges_orikin:hinge/0/material", "\"Si\"", "edges_orikin:hinge", 0},       // does not yield
        {"edges_orikin:hinge/0/material", "\"polyimide\"", "edges_orikin:hinge", 0}, // a wire that does not conduct
        {"edges_orikin:hinge/0/wire/lever", "900e-6", "edges_orikin:hinge", 0},      // outside the flap
        {"edges_orikin:hinge/0/wire/turns", "0", "edges_orikin:hinge", 0},
        {"edges_orikin:hinge/1", "{\"material\": \"Au\", \"width\": 1e-5, \"thickness\": 6e-7}", "edges_orikin:hinge", 1},
        {"faces_orikin:panel/1/material", "\"Kryptonite\"", "faces_orikin:panel", 1},
        {"faces_orikin:panel/1/thickness", "-1e-5", "faces_orikin:panel", 1},
        {"orikin:actuation/field", "[0, 0, 0]", "orikin:actuation", ORI_NULL_INDEX},
        {"orikin:actuation/current_limit", "-0.02", "orikin:actuation", ORI_NULL_INDEX},
        {"orikin:actuation/colour", "1", "orikin:actuation", ORI_NULL_INDEX},
        {"frame_unit", "\"unit\"", "frame_unit", ORI_NULL_INDEX},
        {"frame_unit", NULL, "frame_unit", ORI_NULL_INDEX},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        ori_error err = design_error(cases[i].path, cases[i].value);
        cr_assert_str_eq(err.field, cases[i].field, "%s: %s", cases[i].path, err.message);
        cr_assert_eq(err.element, cases[i].element, "%s: %s", cases[i].path, err.message);
    }
    // A unitless file is fine with the unit given.
    char *t = flap_edit("frame_unit", NULL);
    ori_design_def dd = ori_default_design_def();
    dd.has_meters_per_unit = true;
    dd.meters_per_unit = 1e-6;
    loaded x;
    ori_error err;
    cr_assert_eq(load_text(t, &dd, &x, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_design_meters_per_unit(x.d), 1e-6);
    free(t);
    loaded_free(&x);
}

// --- Lorentz moment from the posed sheet ------------------------------------------------------

Test(actuation, lorentz_moment_from_the_pose_is_IwLBcos)
{
    // The flap folds about the x axis (its hinge runs from (0,0) to (500,0) µm); the wire lies
    // 500 µm into the flap, so the direction from hinge to wire is d = (0, cos φ, sin φ) at fold
    // angle φ and the moment is I·w·L·B·cos Θ with cos Θ = d·B/|B|, at every step (1e-12).
    loaded x = load_example("examples/patterns/thesis-flap.fold");
    ori_motion_def md = ori_default_motion_def();
    md.fixed_face = 0;
    md.driven_edge = 0;
    md.to_rad = ORI_PI;
    md.step_rad = 1.0 * DEG;
    ori_motion *mo = NULL;
    ori_error err;
    cr_assert_eq(ori_motion_solve(x.m, &md, &mo, &err), ORI_OK);
    cr_assert_eq(ori_motion_frame_count(mo), 181);
    const ori_v3 fields[] = {{0, 0.1, 0}, {0, 0.0707, 0.0707}, {0.03, -0.05, 0.08}, {0, 0, -0.1}};
    const double currents[] = {0.02, -0.013};
    double w = 500e-6, L = 500e-6;
    ori_rigid poses[2];
    for (int f = 0; f < 181; ++f) {
        ori_motion_frame_face_poses(mo, f, poses);
        double phi = ori_motion_frame_angles(mo, f)[0];
        ori_v3 dir = ori_v3_make(0, cos(phi), sin(phi));
        for (size_t b = 0; b < sizeof fields / sizeof fields[0]; ++b)
            for (size_t c = 0; c < 2; ++c) {
                double I = currents[c], B = ori_v3_norm(fields[b]);
                double cos_theta = ori_v3_dot(dir, fields[b]) / B;
                double expect = I * w * L * B * cos_theta;
                double got = ori_design_wire_moment(x.d, x.m, 0, 0, poses, I, fields[b]);
                cr_assert_leq(fabs(got - expect), 1e-12 * fabs(I) * w * L * B, "φ = %d°, field %zu: %g vs %g", f, b, got, expect);
                // Reversing the current or the field reverses the moment.
                cr_assert_eq(ori_design_wire_moment(x.d, x.m, 0, 0, poses, -I, fields[b]), -got);
                cr_assert_leq(fabs(ori_design_wire_moment(x.d, x.m, 0, 0, poses, I, ori_v3_scale(fields[b], -1.0)) + got),
                              1e-12 * fabs(I) * w * L * B);
            }
        // The thesis' field, horizontal across the hinge: M_app = I·w·L·B·cos φ.
        cr_assert_leq(fabs(ori_design_wire_moment(x.d, x.m, 0, 0, poses, 0.02, ori_v3_make(0, 0.1, 0)) -
                           0.02 * w * L * 0.1 * cos(phi)),
                      1e-12 * 0.02 * w * L * 0.1);
    }
    ori_motion_destroy(mo);
    loaded_free(&x);
}

// --- sizing ----------------------------------------------------------------------------------

typedef struct sized {
    loaded x;
    ori_motion *mo;
    ori_sizing *z;
} sized;

static ori_motion *flap_fold(const loaded *x, double step_deg)
{
    ori_motion_def md = ori_default_motion_def();
    md.fixed_face = 0;
    md.driven_edge = 0;
    md.to_rad = ORI_PI;
    md.step_rad = step_deg * DEG;
    ori_motion *mo = NULL;
    ori_error err;
    cr_assert_eq(ori_motion_solve(x->m, &md, &mo, &err), ORI_OK);
    return mo;
}

static ori_sizing *size_flap(const loaded *x, const ori_motion *mo, ori_schedule_mode mode, int reorientations)
{
    ori_sizing_def sd = ori_default_sizing_def();
    sd.design = x->d;
    sd.mechanism = x->m;
    sd.motion = mo;
    sd.driven_edge = 0;
    sd.schedule = mode;
    sd.reorientations = reorientations;
    ori_sizing *z = NULL;
    ori_error err;
    cr_assert_eq(ori_sizing_solve(&sd, &z, &err), ORI_OK, "%s: %s", err.field, err.message);
    return z;
}

static void set_width(loaded *x, double w)
{
    ori_hinge h;
    ori_design_hinge(x->d, 0, &h);
    h.width_m = w;
    h.wire.width_m = w;
    ori_error err;
    cr_assert_eq(ori_design_set_hinge(x->d, 0, &h, &err), ORI_OK, "%s", err.message);
}

Test(actuation, thesis_flap_needs_one_field_reorientation)
{
    // Folding to 180° with a fixed field is impossible (the moment vanishes at 90° for a
    // horizontal field; no single orientation serves the half turn): the thesis reorients B
    // halfway. The optimal single reorientation comes at 90°, between fields in the plane
    // across the hinge.
    loaded x = load_example("examples/patterns/thesis-flap.fold");
    ori_motion *mo = flap_fold(&x, 10.0);
    ori_sizing *fixed = size_flap(&x, mo, ORI_SCHEDULE_FIXED, 0);
    cr_assert(isinf(ori_sizing_hinge(fixed, 0).current_needed_a));
    cr_assert(!ori_sizing_summary_of(fixed).feasible);
    ori_sizing *none = size_flap(&x, mo, ORI_SCHEDULE_OPTIMIZE, 0);
    cr_assert(isinf(ori_sizing_hinge(none, 0).current_needed_a));
    ori_sizing *one = size_flap(&x, mo, ORI_SCHEDULE_AUTO, -1);
    ori_sizing_summary su = ori_sizing_summary_of(one);
    cr_assert(su.optimized && su.reorientations == 1 && su.feasible);
    cr_assert_eq(ori_sizing_schedule_count(one), 2);
    ori_field_change c0 = ori_sizing_schedule_at(one, 0), c1 = ori_sizing_schedule_at(one, 1);
    cr_assert_eq(c0.from_rad, 0.0);
    cr_assert_lt(fabs(c1.from_rad - 90.0 * DEG), 1e-12);
    for (int i = 0; i < 2; ++i) {
        ori_field_change c = ori_sizing_schedule_at(one, i);
        cr_assert_lt(fabs(ori_v3_norm(c.field_t) - 0.1), 1e-12); // the magnitude is kept
        cr_assert_lt(fabs(c.field_t.x), 1e-12);                   // across the hinge
    }
    // The field leans toward the flap's motion: up and forward before 90°, up and back after.
    cr_assert(c0.field_t.y > 0 && c0.field_t.z > 0 && c1.field_t.y < 0 && c1.field_t.z > 0);
    // Every frame's current is the required moment over the moment per ampere of its field,
    // and the largest is the hinge's current_needed.
    ori_hinge_sizing h = ori_sizing_hinge(one, 0);
    double most = 0.0;
    for (int f = 0; f < ori_sizing_frame_count(one); ++f) {
        ori_sizing_step s = ori_sizing_step_at(one, 0, f);
        cr_assert_lt(rel(s.current_a, s.required_moment_nm / s.lorentz_moment_per_amp), 1e-12);
        cr_assert_lt(rel(s.power_w, s.current_a * s.current_a * h.mechanics.resistance_ohm), 1e-12);
        cr_assert_lt(rel(s.current_density_a_m2, fabs(s.current_a) / h.mechanics.conductor_area_m2), 1e-12);
        cr_assert_lt(rel(s.required_moment_nm, h.mechanics.plastic_moment_nm - s.gravity_moment_nm), 1e-12);
        most = fmax(most, fabs(s.current_a));
    }
    cr_assert_eq(h.current_needed_a, most);
    cr_assert(h.current_needed_a < 0.02);
    // The thesis' claim, for this 10 µm hinge: less than 20 mA in 0.1 T folds it to 180°.
    // Single flap: the mechanism's virtual-work current equals the hinge's (1e-9).
    cr_assert_lt(rel(su.mechanism_current_a, h.current_needed_a), 1e-9);
    // Springback and permanent fold from the rectangular section: 180° − M(π)/k.
    double mend = ori_hinge_monotonic_moment(h.mechanics.stiffness_nm_rad, h.mechanics.yield_moment_nm, ORI_PI);
    cr_assert_lt(rel(h.springback_rad, mend / h.mechanics.stiffness_nm_rad), 1e-12);
    cr_assert_lt(rel(h.plastic_rotation_rad, ORI_PI - h.springback_rad), 1e-12);
    // Gravity at 500 µm: a few per cent of M_p, negligible.
    cr_assert(h.gravity_ratio > 0.0 && h.gravity_ratio < ORI_ACT_GRAVITY_MINOR);
    ori_sizing_destroy(one);
    ori_sizing_destroy(none);
    ori_sizing_destroy(fixed);
    ori_motion_destroy(mo);
    loaded_free(&x);
}

Test(actuation, thesis_flap_width_range_for_20_mA)
{
    // The hinge widths for which 20 mA (0.1 T, one reorientation) folds the 500 µm flap to 180°:
    // at the upper end the current needed is exactly 20 mA; at the lower end gravity and the gold
    // film's current-density limit meet (narrower films cannot carry the current gravity needs).
    loaded x = load_example("examples/patterns/thesis-flap.fold");
    ori_motion *mo = flap_fold(&x, 10.0);
    ori_sizing *z = size_flap(&x, mo, ORI_SCHEDULE_AUTO, -1);
    ori_hinge_sizing h = ori_sizing_hinge(z, 0);
    cr_assert(h.has_width_range);
    double lo = h.width_min_m, hi = h.width_max_m;
    printf("thesis flap: 20 mA folds hinges %.4g to %.4g um wide; current at 10 um %.4g mA; optimal thickness %.4g um\n",
           lo * 1e6, hi * 1e6, h.current_needed_a * 1e3, h.optimal_thickness_m * 1e6);
    cr_assert(lo > 1e-6 && lo < 5e-6 && hi > 15e-6 && hi < 25e-6, "range %g – %g", lo, hi);
    // Re-size at the ends with the schedule held (the design's schedule = the one found at 10 µm).
    ori_actuation a = ori_design_actuation(x.d);
    a.schedule_count = ori_sizing_schedule_count(z);
    for (int i = 0; i < a.schedule_count; ++i) a.schedule[i] = ori_sizing_schedule_at(z, i);
    ori_error err;
    cr_assert_eq(ori_design_set_actuation(x.d, &a, &err), ORI_OK);
    set_width(&x, hi);
    ori_sizing *at_hi = size_flap(&x, mo, ORI_SCHEDULE_DESIGN, 0);
    cr_assert_lt(rel(ori_sizing_hinge(at_hi, 0).current_needed_a, 0.02), 1e-8);
    set_width(&x, hi * 1.001);
    ori_sizing *past_hi = size_flap(&x, mo, ORI_SCHEDULE_DESIGN, 0);
    cr_assert(!ori_sizing_hinge(past_hi, 0).feasible);
    set_width(&x, lo);
    ori_sizing *at_lo = size_flap(&x, mo, ORI_SCHEDULE_DESIGN, 0);
    ori_hinge_sizing hl = ori_sizing_hinge(at_lo, 0);
    cr_assert_lt(rel(hl.current_density_peak_a_m2, 2e9), 1e-8); // gold's current-density limit
    cr_assert(hl.feasible || rel(hl.current_needed_a, hl.mechanics.current_max_a) < 1e-8);
    set_width(&x, lo * 0.999);
    ori_sizing *past_lo = size_flap(&x, mo, ORI_SCHEDULE_DESIGN, 0);
    cr_assert(!ori_sizing_hinge(past_lo, 0).feasible);
    ori_sizing_destroy(past_lo);
    ori_sizing_destroy(at_lo);
    ori_sizing_destroy(past_hi);
    ori_sizing_destroy(at_hi);
    ori_sizing_destroy(z);
    ori_motion_destroy(mo);
    loaded_free(&x);
}

Test(actuation, optimal_thickness_maximises_the_margin)
{
    // Without gravity the margin min_f(I_max(t)·P_f − ¼σ_y·w·t²), I_max = min(I_limit, j_max·w·t),
    // peaks at t* = min(2·j_max·P_min/σ_y, I_limit/(j_max·w)) (P_min: the weakest moment per
    // ampere along the motion): closed form against the golden-section search (1e-8).
    loaded x = load_example("examples/patterns/thesis-flap.fold");
    ori_actuation a = ori_design_actuation(x.d);
    a.gravity_m_s2 = ori_v3_make(0, 0, 0);
    ori_error err;
    cr_assert_eq(ori_design_set_actuation(x.d, &a, &err), ORI_OK);
    ori_motion *mo = flap_fold(&x, 10.0);
    double limits[] = {0.02, 0.003};
    for (int k = 0; k < 2; ++k) {
        a.current_limit_a = limits[k];
        cr_assert_eq(ori_design_set_actuation(x.d, &a, &err), ORI_OK);
        ori_sizing *z = size_flap(&x, mo, ORI_SCHEDULE_AUTO, -1);
        ori_hinge_sizing h = ori_sizing_hinge(z, 0);
        double pmin = INFINITY;
        for (int f = 0; f < ori_sizing_frame_count(z); ++f) pmin = fmin(pmin, ori_sizing_step_at(z, 0, f).lorentz_moment_per_amp);
        double j = 2e9, w = 10e-6, sy = 206e6;
        double expect = fmin(2.0 * j * pmin / sy, limits[k] / (j * w));
        cr_assert(h.has_optimal_thickness);
        cr_assert_lt(rel(h.optimal_thickness_m, expect), 1e-8, "limit %g: %g vs %g", limits[k], h.optimal_thickness_m, expect);
        cr_assert_eq(h.gravity_moment_max_nm, 0.0);
        ori_sizing_destroy(z);
    }
    ori_motion_destroy(mo);
    loaded_free(&x);
}

Test(actuation, gravity_negligible_at_500um_decisive_at_5cm)
{
    // The same flap read with 100× larger coordinates (5 cm): gravity's moment dwarfs M_p.
    char *t = example_text("examples/patterns/thesis-flap.fold");
    ori_design_def dd = ori_default_design_def();
    dd.has_meters_per_unit = true;
    dd.meters_per_unit = 1e-4;
    loaded x;
    ori_error err;
    cr_assert_eq(load_text(t, &dd, &x, &err), ORI_OK);
    free(t);
    ori_hinge h;
    ori_design_hinge(x.d, 0, &h);
    h.wire.length_m = h.wire.lever_m = 5e-2;
    cr_assert_eq(ori_design_set_hinge(x.d, 0, &h, &err), ORI_OK, "%s", err.message);
    ori_motion *mo = flap_fold(&x, 10.0);
    ori_sizing *z = size_flap(&x, mo, ORI_SCHEDULE_AUTO, -1);
    ori_hinge_sizing hz = ori_sizing_hinge(z, 0);
    // m·g·(a/2) for a 5 cm × 5 cm × 10 µm silicon flap.
    double m = 2329.0 * 0.05 * 0.05 * 10e-6;
    cr_assert_lt(rel(hz.gravity_moment_max_nm, m * 9.80665 * 0.025), 1e-9);
    cr_assert_gt(hz.gravity_ratio, 1.0);
    cr_assert(!hz.has_width_range); // no gold hinge that thin holds it
    ori_sizing_destroy(z);
    ori_motion_destroy(mo);
    loaded_free(&x);
}

Test(actuation, sizing_errors_name_the_crease)
{
    loaded x = load_example("examples/patterns/thesis-flap.fold");
    ori_motion *mo = flap_fold(&x, 30.0);
    ori_sizing_def sd = ori_default_sizing_def();
    sd.design = x.d;
    sd.mechanism = x.m;
    sd.motion = mo;
    sd.driven_edge = 0;
    ori_sizing *z = NULL;
    ori_error err;
    // The driven (actuated) crease without hinge data.
    ori_hinge keep;
    ori_design_hinge(x.d, 0, &keep);
    ori_design_set_hinge(x.d, 0, NULL, &err);
    cr_assert_eq(ori_sizing_solve(&sd, &z, &err), ORI_ERR_ARGUMENT);
    cr_assert_str_eq(err.field, "edges_orikin:hinge");
    cr_assert_eq(err.element, 0);
    // A hinge without a wire: nothing actuates.
    ori_hinge bare = keep;
    bare.has_wire = false;
    cr_assert_eq(ori_design_set_hinge(x.d, 0, &bare, &err), ORI_OK);
    cr_assert_eq(ori_sizing_solve(&sd, &z, &err), ORI_ERR_ARGUMENT);
    cr_assert_str_eq(err.field, "edges_orikin:hinge");
    // No field.
    cr_assert_eq(ori_design_set_hinge(x.d, 0, &keep, &err), ORI_OK);
    ori_actuation a = ori_design_actuation(x.d);
    a.has_field = false;
    cr_assert_eq(ori_design_set_actuation(x.d, &a, &err), ORI_OK);
    cr_assert_eq(ori_sizing_solve(&sd, &z, &err), ORI_ERR_ARGUMENT);
    cr_assert_str_eq(err.field, "orikin:actuation");
    cr_assert_null(z);
    ori_motion_destroy(mo);
    loaded_free(&x);
}

Test(actuation, open_corner_sequence_by_virtual_work)
{
    // The open corner with gold hinges, folded as the thesis does (two folds). In fold 1 the
    // diagonal's wire must also bend the three creases that follow it: the mechanism's current
    // by virtual work exceeds what the diagonal alone needs about its own axis. One field
    // reorientation per fold keeps it within 20 mA.
    loaded x = load_example("examples/patterns/open-corner-gold.fold");
    ori_sequence *s = NULL;
    ori_error err;
    cr_assert_eq(ori_sequence_load_file(test_repo_path("examples/open-corner-gold.seq.json"), &s, &err), ORI_OK);
    ori_record *r = NULL;
    cr_assert_eq(ori_sequence_run(s, x.m, NULL, ori_rigid_identity(), &r, &err), ORI_OK);
    cr_assert_eq(ori_record_verdict(r), ORI_MOTION_VALID);
    ori_sizing_def sd = ori_default_sizing_def();
    sd.design = x.d;
    sd.mechanism = x.m;
    sd.record = r;
    sd.sequence = s;
    ori_sizing *z = NULL;
    cr_assert_eq(ori_sizing_solve(&sd, &z, &err), ORI_OK, "%s", err.message);
    ori_sizing_summary su = ori_sizing_summary_of(z);
    cr_assert(su.feasible);
    cr_assert_eq(su.reorientations, 2);
    cr_assert_eq(ori_sizing_hinge_count(z), 5);
    double diag = 0.0;
    for (int i = 0; i < 5; ++i) {
        ori_hinge_sizing h = ori_sizing_hinge(z, i);
        if (h.edge == 12) diag = h.current_needed_a;
        cr_assert_eq(h.actuated, h.edge == 11 || h.edge == 12);
        cr_assert(h.travel_rad > 0.0);
    }
    cr_assert(diag > 0.0 && su.mechanism_current_a > diag && su.mechanism_current_a <= 0.02,
              "diagonal %g, mechanism %g", diag, su.mechanism_current_a);
    // The change for fold 2 is due as fold 2 starts: crease 11 at its start angle.
    ori_field_change last = ori_sizing_schedule_at(z, ori_sizing_schedule_count(z) - 1);
    cr_assert(last.edge == 11 && last.fold == 1 && last.from_rad == 0.0);
    ori_sizing_destroy(z);
    ori_record_destroy(r);
    ori_sequence_destroy(s);
    loaded_free(&x);
}

// --- the minimum-norm point -----------------------------------------------------------------

Test(actuation, min_norm_point_of_a_hull)
{
    const ori_v3 a[] = {{1, 1, 0}, {1, -1, 0}, {2, 0, 1}, {1, 0, -1}};
    ori_v3 x = ori__min_norm_point(a, 4);
    cr_assert(fabs(x.x - 1) < 1e-15 && fabs(x.y) < 1e-15 && fabs(x.z) < 1e-15);
    const ori_v3 e[] = {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
    x = ori__min_norm_point(e, 3);
    cr_assert(fabs(x.x - 1.0 / 3) < 1e-15 && fabs(x.y - 1.0 / 3) < 1e-15 && fabs(x.z - 1.0 / 3) < 1e-15);
    // An arc of unit vectors from 0° to 80°: the chord's midpoint direction, at distance cos 40°.
    ori_v3 arc[9];
    for (int i = 0; i < 9; ++i) arc[i] = ori_v3_make(0, cos(i * 10 * DEG), sin(i * 10 * DEG));
    x = ori__min_norm_point(arc, 9);
    cr_assert_lt(fabs(ori_v3_norm(x) - cos(40 * DEG)), 1e-14);
    cr_assert_lt(fabs(atan2(x.z, x.y) - 40 * DEG), 1e-12);
    // A half circle contains the origin's chord: distance 0 (no single orientation).
    ori_v3 half[19];
    for (int i = 0; i < 19; ++i) half[i] = ori_v3_make(0, cos(i * 10 * DEG), sin(i * 10 * DEG));
    cr_assert_lt(ori_v3_norm(ori__min_norm_point(half, 19)), 1e-13);
    // Random sets: the result satisfies the optimality condition x·p ≥ |x|² for every point.
    unsigned seed = 7;
    for (int trial = 0; trial < 20000; ++trial) {
        int n = 1 + (int)(rand_r(&seed) % 12);
        ori_v3 p[12];
        double big = 0.0;
        for (int i = 0; i < n; ++i) {
            double r[3];
            for (int k = 0; k < 3; ++k) r[k] = (double)rand_r(&seed) / RAND_MAX - 0.3;
            p[i] = trial % 2 ? ori_v3_make(0, 100 * cos(2 * r[0]), 100 * sin(2 * r[1])) : ori_v3_make(r[0], r[1], r[2]);
            big = fmax(big, ori_v3_dot(p[i], p[i]));
        }
        x = ori__min_norm_point(p, n);
        for (int i = 0; i < n; ++i)
            cr_assert_geq(ori_v3_dot(x, p[i]) - ori_v3_dot(x, x), -1e-9 * big, "trial %d", trial);
    }
}
