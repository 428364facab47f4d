// The job of one design point, run through the library: the base pattern (a FOLD file or a
// generator), the fold (a drive or toward the targets) with its collision check, the actuation
// sizing, the dynamics, the layer count. A worker keeps the last pattern and motion so that
// points differing only in the design reuse them; every figure is computed from the point's
// own inputs, so a result never depends on which worker computed it or in which order.
#define _POSIX_C_SOURCE 200809L
#include "sweep_internal.h"

#include <orikin/arrangement.h>
#include <orikin/collision.h>
#include <orikin/generate.h>
#include <orikin/layers.h>
#include <orikin/tolerance.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

// --- parsing --------------------------------------------------------------------------------

static bool keys_ok(const json_t *o, const char *const *keys, size_t n, const char **bad)
{
    const char *k;
    json_t *v;
    json_object_foreach((json_t *)o, k, v) {
        bool ok = false;
        for (size_t i = 0; i < n; ++i) ok |= strcmp(k, keys[i]) == 0;
        if (!ok) {
            *bad = k;
            return false;
        }
    }
    return true;
}
#define KEYS_OK(o, keys, bad) keys_ok(o, keys, sizeof keys / sizeof keys[0], bad)

// A number field: 1 found, 0 absent, -1 present but not a finite number.
static int num(const json_t *o, const char *key, double *out)
{
    json_t *v = json_object_get(o, key);
    if (!v || json_is_null(v)) return 0;
    if (!json_is_number(v) || !isfinite(json_number_value(v))) return -1;
    *out = json_number_value(v);
    return 1;
}

// An integer field (a real with an integral value counts: parameter values are reals).
static int integer(const json_t *o, const char *key, int lo, int hi, int *out)
{
    double d;
    int r = num(o, key, &d);
    if (r <= 0) return r;
    if (d != floor(d) || d < lo || d > hi) return -1;
    *out = (int)d;
    return 1;
}

static int boolean(const json_t *o, const char *key, bool *out)
{
    json_t *v = json_object_get(o, key);
    if (!v || json_is_null(v)) return 0;
    if (!json_is_boolean(v)) return -1;
    *out = json_is_true(v);
    return 1;
}

static int string(const json_t *o, const char *key, char *out, size_t size)
{
    json_t *v = json_object_get(o, key);
    if (!v || json_is_null(v)) return 0;
    if (!json_is_string(v) || strlen(json_string_value(v)) >= size) return -1;
    strcpy(out, json_string_value(v));
    return 1;
}

// A face or crease: an index, [x, y] (the one there), or (crease) "center".
static int element(const json_t *v, bool crease, int *kind, int *index, double xy[2])
{
    if (json_is_number(v)) {
        double d = json_number_value(v);
        if (d != floor(d) || d < 0 || d > 1e9) return -1;
        *kind = 0;
        *index = (int)d;
        return 0;
    }
    if (json_is_array(v) && json_array_size(v) == 2 && json_is_number(json_array_get(v, 0)) &&
        json_is_number(json_array_get(v, 1))) {
        *kind = 1;
        xy[0] = json_number_value(json_array_get(v, 0));
        xy[1] = json_number_value(json_array_get(v, 1));
        return isfinite(xy[0]) && isfinite(xy[1]) ? 0 : -1;
    }
    if (crease && json_is_string(v) && strcmp(json_string_value(v), "center") == 0) {
        *kind = 2;
        return 0;
    }
    return -1;
}

static char *canonical(const json_t *a, const json_t *b, const json_t *c)
{
    json_t *o = json_object();
    if (a) json_object_set(o, "a", (json_t *)a);
    if (b) json_object_set(o, "b", (json_t *)b);
    if (c) json_object_set(o, "c", (json_t *)c);
    char *s = json_dumps(o, JSON_SORT_KEYS | JSON_COMPACT | JSON_REAL_PRECISION(17));
    json_decref(o);
    return s;
}

static int parse_base(const json_t *b, const char *dir, sweep_cfg *c, char *err, size_t n)
{
    const char *bad;
    if (json_is_string(b) || (json_is_object(b) && json_object_get(b, "file"))) {
        const json_t *f = json_is_string(b) ? b : json_object_get(b, "file");
        static const char *const keys[] = {"file"};
        if (json_is_object(b) && !KEYS_OK(b, keys, &bad)) return sweep_fail(err, n, "base.%s: unknown field (file)", bad);
        if (!json_is_string(f)) return sweep_fail(err, n, "base.file: must be a path");
        const char *p = json_string_value(f);
        if (snprintf(c->file, sizeof c->file, "%s%s", p[0] == '/' ? "" : dir, p) >= (int)sizeof c->file)
            return sweep_fail(err, n, "base.file: path too long");
        c->base_is_file = true;
        return 0;
    }
    if (!json_is_object(b) || !json_is_string(json_object_get(b, "generate")))
        return sweep_fail(err, n, "base: must be a FOLD file, {\"file\": PATH} or {\"generate\": KIND, ...}");
    static const char *const keys[] = {"generate", "rows", "cols", "sides", "angle", "width", "height", "twist_size",
                                       "bistable_height"};
    if (!KEYS_OK(b, keys, &bad))
        return sweep_fail(err, n, "base.%s: unknown field (generate, rows, cols, sides, angle, width, height, twist_size)", bad);
    ori_tessellation kind;
    const char *name = json_string_value(json_object_get(b, "generate"));
    if (!ori_tessellation_from_name(name, &kind))
        return sweep_fail(err, n, "base.generate: '%s' is not a tessellation (miura, yoshimura, waterbomb, square-twist, kresling)",
                          name);
    c->gen = ori_default_generate_def(kind);
    double d;
    int r;
    if ((r = integer(b, "rows", 1, 1 << 20, &c->gen.rows)) < 0) return sweep_fail(err, n, "base.rows: must be an integer >= 1");
    if ((r = integer(b, "cols", 1, 1 << 20, &c->gen.cols)) < 0) return sweep_fail(err, n, "base.cols: must be an integer >= 1");
    if ((r = integer(b, "sides", 3, 1 << 20, &c->gen.sides)) < 0) return sweep_fail(err, n, "base.sides: must be an integer >= 3");
    if ((r = num(b, "angle", &d)) < 0) return sweep_fail(err, n, "base.angle: must be a number (degrees)");
    if (r) c->gen.angle_rad = ori_deg_to_rad(d);
    if ((r = num(b, "width", &c->gen.width)) < 0) return sweep_fail(err, n, "base.width: must be a number");
    if ((r = num(b, "height", &c->gen.height)) < 0) return sweep_fail(err, n, "base.height: must be a number");
    if (r && kind == ORI_TESS_KRESLING) c->gen.bistable_height = false;
    if ((r = num(b, "twist_size", &c->gen.twist_size)) < 0) return sweep_fail(err, n, "base.twist_size: must be a number");
    ori_pattern_counts counts;
    ori_error e;
    if (ori_generate_counts(&c->gen, &counts, &e) != ORI_OK) return sweep_fail(err, n, "base.%s: %s", e.field, e.message);
    return 0;
}

static int parse_hinge(const json_t *h, sweep_hinge_spec *s, char *err, size_t n)
{
    static const char *const keys[] = {"material", "width", "thickness", "span", "wire"};
    const char *bad;
    if (!json_is_object(h)) return sweep_fail(err, n, "design.hinge: must be an object");
    if (!KEYS_OK(h, keys, &bad)) return sweep_fail(err, n, "design.hinge.%s: unknown field (material, width, thickness, span, wire)", bad);
    int r;
    if ((r = string(h, "material", s->material, sizeof s->material)) < 0)
        return sweep_fail(err, n, "design.hinge.material: must be a material name");
    s->has_material = r;
    if ((r = num(h, "width", &s->width)) < 0) return sweep_fail(err, n, "design.hinge.width: must be a number (m)");
    s->has_width = r;
    if ((r = num(h, "thickness", &s->thickness)) < 0) return sweep_fail(err, n, "design.hinge.thickness: must be a number (m)");
    s->has_thickness = r;
    if ((r = num(h, "span", &s->span)) < 0) return sweep_fail(err, n, "design.hinge.span: must be a number (m)");
    s->has_span = r;
    s->wire = -1;
    json_t *w = json_object_get(h, "wire");
    if (json_is_false(w)) s->wire = 0;
    else if (w) {
        static const char *const wkeys[] = {"length", "lever", "turns"};
        if (!json_is_object(w)) return sweep_fail(err, n, "design.hinge.wire: must be false or {length, lever, turns}");
        if (!KEYS_OK(w, wkeys, &bad)) return sweep_fail(err, n, "design.hinge.wire.%s: unknown field (length, lever, turns)", bad);
        s->wire = 1;
        if ((r = num(w, "length", &s->wire_length)) < 0) return sweep_fail(err, n, "design.hinge.wire.length: must be a number (m)");
        s->has_wire_length = r;
        if ((r = num(w, "lever", &s->wire_lever)) < 0) return sweep_fail(err, n, "design.hinge.wire.lever: must be a number (m)");
        s->has_wire_lever = r;
        if (integer(w, "turns", 1, 1000000, &s->wire_turns) < 0)
            return sweep_fail(err, n, "design.hinge.wire.turns: must be an integer >= 1");
    }
    return 0;
}

static int parse_design(const json_t *d, sweep_cfg *c, char *err, size_t n)
{
    static const char *const keys[] = {"unit", "hinges", "hinge", "wires", "panel", "field", "current_limit", "gravity"};
    const char *bad;
    if (!json_is_object(d)) return sweep_fail(err, n, "design: must be an object");
    if (!KEYS_OK(d, keys, &bad))
        return sweep_fail(err, n, "design.%s: unknown field (unit, hinges, hinge, wires, panel, field, current_limit, gravity)", bad);
    json_t *wires = json_object_get(d, "wires");
    if (json_is_string(wires) && strcmp(json_string_value(wires), "every") == 0) c->wires = 0;
    else if (json_is_string(wires) && strcmp(json_string_value(wires), "driven") == 0) c->wires = 1;
    else if (json_is_array(wires) && json_array_size(wires) <= SWEEP_MAX_LOCKS) {
        c->wires = 2;
        for (size_t i = 0; i < json_array_size(wires); ++i) {
            json_t *x = json_array_get(wires, i);
            double v = json_number_value(x);
            if (!json_is_number(x) || v != floor(v) || v < 0 || v > 1e9)
                return sweep_fail(err, n, "design.wires[%zu]: must be a crease index", i);
            c->wire_edges[c->wire_count++] = (int)v;
        }
    } else if (wires) return sweep_fail(err, n, "design.wires: must be \"every\", \"driven\" or a list of crease indices");
    char s[32];
    int r;
    if ((r = string(d, "unit", s, sizeof s)) < 0) return sweep_fail(err, n, "design.unit: must be a unit name");
    if (r) {
        ori_error e;
        if (ori_unit_meters(s, &c->unit_m, &e) != ORI_OK)
            return sweep_fail(err, n, "design.unit: '%s' is not m, cm, mm, um, nm, in or pt", s);
        c->has_unit = true;
    }
    c->hinges_every = !c->base_is_file;
    if ((r = string(d, "hinges", s, sizeof s)) < 0 || (r && strcmp(s, "every") && strcmp(s, "file")))
        return sweep_fail(err, n, "design.hinges: must be \"every\" (every crease) or \"file\" (the file's hinges)");
    if (r) c->hinges_every = strcmp(s, "every") == 0;
    if (c->hinges_every && !c->base_is_file && !c->has_unit)
        return sweep_fail(err, n, "design.unit: a generated pattern is unitless: give the unit of its lengths (m, mm, um, ...)");
    json_t *h = json_object_get(d, "hinge");
    if (h) {
        int rc = parse_hinge(h, &c->hinge, err, n);
        if (rc) return rc;
        c->has_hinge = true;
    }
    if (c->hinges_every) {
        if (!c->has_hinge || !c->hinge.has_material || !c->hinge.has_width || !c->hinge.has_thickness)
            return sweep_fail(err, n, "design.hinge: \"hinges\": \"every\" needs material, width and thickness");
        if (c->hinge.wire == 1 && (!c->hinge.has_wire_length || !c->hinge.has_wire_lever))
            return sweep_fail(err, n, "design.hinge.wire: a new wire needs length and lever");
    }
    json_t *p = json_object_get(d, "panel");
    if (p) {
        static const char *const pkeys[] = {"material", "thickness"};
        if (!json_is_object(p)) return sweep_fail(err, n, "design.panel: must be {material, thickness}");
        if (!KEYS_OK(p, pkeys, &bad)) return sweep_fail(err, n, "design.panel.%s: unknown field (material, thickness)", bad);
        if ((r = string(p, "material", c->panel_material, sizeof c->panel_material)) < 0)
            return sweep_fail(err, n, "design.panel.material: must be a material name");
        c->has_panel_material = r;
        if ((r = num(p, "thickness", &c->panel_thickness)) < 0) return sweep_fail(err, n, "design.panel.thickness: must be a number (m)");
        c->has_panel_thickness = r;
        c->has_panel = true;
    }
    json_t *f = json_object_get(d, "field");
    if (f) {
        double b[3];
        bool ok = json_is_array(f) && json_array_size(f) == 3;
        for (int i = 0; i < 3 && ok; ++i) {
            json_t *x = json_array_get(f, (size_t)i);
            ok = json_is_number(x) && isfinite(b[i] = json_number_value(x));
        }
        if (!ok) return sweep_fail(err, n, "design.field: must be [BX, BY, BZ] in teslas");
        c->has_field = true;
        c->field = ori_v3_make(b[0], b[1], b[2]);
    }
    if ((r = num(d, "current_limit", &c->current_limit)) < 0) return sweep_fail(err, n, "design.current_limit: must be a number (A)");
    c->has_current_limit = r;
    bool g;
    if ((r = boolean(d, "gravity", &g)) < 0) return sweep_fail(err, n, "design.gravity: must be true or false");
    c->gravity = r ? g : -1;
    return 0;
}

static int parse_fold(const json_t *f, sweep_cfg *c, char *err, size_t n)
{
    static const char *const keys[] = {"drive", "to", "from", "step", "fix", "lock", "percent"};
    const char *bad;
    if (!json_is_object(f)) return sweep_fail(err, n, "job.fold: must be an object");
    if (!KEYS_OK(f, keys, &bad)) return sweep_fail(err, n, "job.fold.%s: unknown field (drive, to, from, step, fix, lock, percent)", bad);
    c->fold = true;
    int r;
    json_t *drive = json_object_get(f, "drive");
    if ((r = num(f, "percent", &c->percent)) < 0) return sweep_fail(err, n, "job.fold.percent: must be a number from 0 to 100");
    c->targets = r;
    if (c->targets) {
        if (drive || json_object_get(f, "to") || json_object_get(f, "from"))
            return sweep_fail(err, n, "job.fold.percent: folds toward the targets (no drive, to or from)");
        if (!(c->percent >= 0.0 && c->percent <= 100.0)) return sweep_fail(err, n, "job.fold.percent: must be from 0 to 100");
    } else {
        if (!drive) return sweep_fail(err, n, "job.fold.drive: missing (a crease index, [x, y] or \"center\"; or give percent)");
        if (element(drive, true, &c->drive_kind, &c->drive, c->drive_xy) < 0)
            return sweep_fail(err, n, "job.fold.drive: must be a crease index, [x, y] (the crease there) or \"center\"");
        if ((r = num(f, "to", &c->to_deg)) <= 0 || fabs(c->to_deg) > 180.0)
            return sweep_fail(err, n, "job.fold.to: must be an angle from -180 to 180 (degrees)");
        if ((r = num(f, "from", &c->from_deg)) < 0 || (r && fabs(c->from_deg) > 180.0))
            return sweep_fail(err, n, "job.fold.from: must be an angle from -180 to 180 (degrees)");
        c->has_from = r;
    }
    c->step_deg = 10.0;
    if ((r = num(f, "step", &c->step_deg)) < 0 || !(c->step_deg > 0.0))
        return sweep_fail(err, n, "job.fold.step: must be a positive angle (degrees)");
    c->fix_kind = -1;
    json_t *fix = json_object_get(f, "fix");
    if (fix && element(fix, false, &c->fix_kind, &c->fix, c->fix_xy) < 0)
        return sweep_fail(err, n, "job.fold.fix: must be a face index or [x, y] (the face there)");
    json_t *lock = json_object_get(f, "lock");
    if (lock) {
        if (!json_is_array(lock) || json_array_size(lock) > SWEEP_MAX_LOCKS)
            return sweep_fail(err, n, "job.fold.lock: must be an array of crease indices (at most %d)", SWEEP_MAX_LOCKS);
        for (size_t i = 0; i < json_array_size(lock); ++i) {
            json_t *x = json_array_get(lock, i);
            double d = json_number_value(x);
            if (!json_is_number(x) || d != floor(d) || d < 0 || d > 1e9)
                return sweep_fail(err, n, "job.fold.lock[%zu]: must be a crease index", i);
            c->locks[c->lock_count++] = (int)d;
        }
    }
    return 0;
}

int sweep_cfg_parse(const json_t *t, const char *dir, sweep_cfg *c, char *err, size_t n)
{
    memset(c, 0, sizeof *c);
    c->gravity = -1;
    c->reorientations = -1;
    c->layers_limit = ORI_LAYERS_NO_LIMIT;
    c->sim_fix = -1;
    const json_t *base = json_object_get(t, "base"), *design = json_object_get(t, "design"), *job = json_object_get(t, "job");
    int rc = parse_base(base, dir, c, err, n);
    if (!rc && design) rc = parse_design(design, c, err, n);
    if (!rc && !design) c->hinges_every = false;
    if (rc) return rc;
    static const char *const keys[] = {"fold", "sequence", "collide", "actuate", "simulate", "layers"};
    const char *bad;
    if (!KEYS_OK(job, keys, &bad))
        return sweep_fail(err, n, "job.%s: unknown stage (fold, sequence, collide, actuate, simulate, layers)", bad);
    json_t *f = json_object_get(job, "fold");
    if (json_is_false(f) || json_is_null(f)) f = NULL;
    if (f && (rc = parse_fold(f, c, err, n))) return rc;
    json_t *seq = json_object_get(job, "sequence");
    if (json_is_false(seq) || json_is_null(seq)) seq = NULL;
    if (seq) { // the folds of a sequence file, run on the base (docs/sequence.md)
        if (f) return sweep_fail(err, n, "job.sequence: one motion per point: job.fold or job.sequence");
        static const char *const qkeys[] = {"folds"};
        if (!json_is_object(seq) || !json_is_array(json_object_get(seq, "folds")))
            return sweep_fail(err, n, "job.sequence: must be {\"folds\": [...]} (the folds as in a SEQ.json, from the flat base)");
        if (!KEYS_OK(seq, qkeys, &bad)) return sweep_fail(err, n, "job.sequence.%s: unknown field (folds)", bad);
        json_t *whole = json_deep_copy(seq);
        json_object_set_new(whole, "pattern", json_string("(the sweep's base)"));
        c->sequence = json_dumps(whole, JSON_COMPACT | JSON_REAL_PRECISION(17));
        json_decref(whole);
        ori_sequence *probe = NULL;
        ori_error e;
        if (ori_sequence_parse(c->sequence, strlen(c->sequence), &probe, &e) != ORI_OK)
        {
            if (e.element >= 0 && strcmp(e.field, "folds") == 0)
                return sweep_fail(err, n, "job.sequence.folds[%d]: %s", e.element, e.message);
            return sweep_fail(err, n, "job.sequence%s%s: %s", e.field[0] ? "." : "", e.field, e.message);
        }
        ori_sequence_destroy(probe);
        c->fold = true;
        f = seq;
    }
    json_t *col = json_object_get(job, "collide");
    int r;
    if (col && !json_is_false(col)) {
        if (!c->fold) return sweep_fail(err, n, "job.collide: checks the fold's motion: needs job.fold");
        c->collide = true;
        if (json_is_object(col)) {
            static const char *const ckeys[] = {"clearance"};
            if (!KEYS_OK(col, ckeys, &bad)) return sweep_fail(err, n, "job.collide.%s: unknown field (clearance)", bad);
            if ((r = num(col, "clearance", &c->clearance)) < 0 || !(c->clearance >= 0.0))
                return sweep_fail(err, n, "job.collide.clearance: must be a length >= 0");
        } else if (!json_is_true(col)) return sweep_fail(err, n, "job.collide: must be true or {\"clearance\": D}");
    }
    json_t *act = json_object_get(job, "actuate");
    if (act && !json_is_false(act)) {
        if (!c->fold || c->targets || c->sequence)
            return sweep_fail(err, n, "job.actuate: sizes the fold of a driven crease: needs job.fold with drive and to");
        c->actuate = true;
        if (json_is_object(act)) {
            static const char *const akeys[] = {"reorientations", "fixed_field"};
            if (!KEYS_OK(act, akeys, &bad)) return sweep_fail(err, n, "job.actuate.%s: unknown field (reorientations, fixed_field)", bad);
            if (integer(act, "reorientations", 0, ORI_SCHEDULE_MAX - 1, &c->reorientations) < 0)
                return sweep_fail(err, n, "job.actuate.reorientations: must be an integer from 0 to %d", ORI_SCHEDULE_MAX - 1);
            if (boolean(act, "fixed_field", &c->fixed_field) < 0) return sweep_fail(err, n, "job.actuate.fixed_field: must be true or false");
            if (c->fixed_field && c->reorientations >= 0)
                return sweep_fail(err, n, "job.actuate.fixed_field: excludes reorientations");
        } else if (!json_is_true(act)) return sweep_fail(err, n, "job.actuate: must be true or an object");
    }
    json_t *sim = json_object_get(job, "simulate");
    if (sim && !json_is_false(sim)) {
        static const char *const skeys[] = {"current", "duration", "dt", "fix"};
        if (!json_is_object(sim)) return sweep_fail(err, n, "job.simulate: must be {current, duration, dt, fix}");
        if (!KEYS_OK(sim, skeys, &bad)) return sweep_fail(err, n, "job.simulate.%s: unknown field (current, duration, dt, fix)", bad);
        if (integer(sim, "fix", 0, 1 << 30, &c->sim_fix) < 0) return sweep_fail(err, n, "job.simulate.fix: must be a face index");
        c->simulate = true;
        if (num(sim, "current", &c->sim_current) <= 0 || !(c->sim_current >= 0))
            return sweep_fail(err, n, "job.simulate.current: must be a current >= 0 (A)");
        if (num(sim, "duration", &c->sim_duration) <= 0 || !(c->sim_duration > 0))
            return sweep_fail(err, n, "job.simulate.duration: must be a time > 0 (s)");
        if ((r = num(sim, "dt", &c->sim_dt)) < 0 || (r && !(c->sim_dt > 0)))
            return sweep_fail(err, n, "job.simulate.dt: must be a time > 0 (s)");
        c->has_sim_dt = r;
    }
    json_t *lay = json_object_get(job, "layers");
    if (lay && !json_is_false(lay)) {
        c->layers = true;
        if (json_is_object(lay)) {
            static const char *const lkeys[] = {"limit"};
            if (!KEYS_OK(lay, lkeys, &bad)) return sweep_fail(err, n, "job.layers.%s: unknown field (limit)", bad);
            double d;
            if ((r = num(lay, "limit", &d)) < 0 || (r && (d < 1 || d != floor(d) || d > 1e18)))
                return sweep_fail(err, n, "job.layers.limit: must be an integer >= 1");
            if (r) c->layers_limit = (uint64_t)d;
        } else if (!json_is_true(lay)) return sweep_fail(err, n, "job.layers: must be true or {\"limit\": N}");
    }
    if ((c->actuate || c->simulate) && !design)
        if (!c->base_is_file) return sweep_fail(err, n, "design: a generated pattern has no hinges: give design.unit and design.hinge");
    if (c->simulate && c->sequence) return sweep_fail(err, n, "job.simulate: simulates one driven fold: use job.fold, not job.sequence");
    if (c->wires == 1 && (!c->fold || c->targets || c->sequence))
        return sweep_fail(err, n, "design.wires: \"driven\" wires the fold's driven crease: needs job.fold with a drive");
    c->base_key = canonical(base, NULL, NULL);
    c->fold_key = canonical(base, f, col);
    return 0;
}

void sweep_cfg_free(sweep_cfg *c)
{
    free(c->base_key);
    free(c->fold_key);
    free(c->sequence);
    c->base_key = c->fold_key = c->sequence = NULL;
}

// --- the worker -----------------------------------------------------------------------------

struct sweep_worker {
    const sweep_spec *spec;
    // The base (key: cfg.base_key).
    char *base_key;
    char base_error[SWEEP_ERROR_MAX];
    ori_fold *doc;
    ori_pattern *pattern;
    ori_mechanism *mech;
    bool has_layers;
    uint64_t layers_limit; // the limit has_layers was counted with
    char layers_error[SWEEP_ERROR_MAX];
    char layer_count[96];
    // The fold (key: cfg.fold_key).
    char *fold_key;
    char fold_error[SWEEP_ERROR_MAX];
    int fix, drive;
    int locks[SWEEP_MAX_LOCKS];
    int lock_count;
    ori_motion *motion;
    ori_multifold *multi;
    ori_sequence *sequence; // job.sequence: the folds and their run
    ori_record *record;
    char verdict[32];
    double reached;
    int frames;
    bool collides;
    double min_clearance;
};

sweep_worker *sweep_worker_create(const sweep_spec *spec)
{
    sweep_worker *w = calloc(1, sizeof *w);
    w->spec = spec;
    return w;
}

static void drop_fold(sweep_worker *w)
{
    ori_motion_destroy(w->motion);
    ori_multifold_destroy(w->multi);
    ori_record_destroy(w->record);
    ori_sequence_destroy(w->sequence);
    w->motion = NULL;
    w->multi = NULL;
    w->record = NULL;
    w->sequence = NULL;
    free(w->fold_key);
    w->fold_key = NULL;
}

static void drop_base(sweep_worker *w)
{
    drop_fold(w);
    ori_mechanism_destroy(w->mech);
    ori_pattern_destroy(w->pattern);
    ori_fold_destroy(w->doc);
    w->mech = NULL;
    w->pattern = NULL;
    w->doc = NULL;
    w->has_layers = false;
    free(w->base_key);
    w->base_key = NULL;
}

void sweep_worker_destroy(sweep_worker *w)
{
    if (!w) return;
    drop_base(w);
    free(w);
}

static void fmt_error(char *out, size_t size, const char *stage, const ori_error *e)
{
    char buf[300];
    ori_error_format(e, buf, sizeof buf);
    snprintf(out, size, "%s: %s", stage, buf);
}

static void load_base(sweep_worker *w, const sweep_cfg *c)
{
    w->base_key = strdup(c->base_key);
    w->base_error[0] = '\0';
    ori_error e;
    if (c->base_is_file) {
        if (ori_fold_load_file(c->file, &w->doc, &e) != ORI_OK ||
            ori_fold_get_pattern(w->doc, 0, NULL, &w->pattern, &e) != ORI_OK) {
            fmt_error(w->base_error, sizeof w->base_error, "base", &e);
            return;
        }
        if (ori_pattern_is_folded_form(w->pattern) || ori_pattern_is_3d(w->pattern)) {
            snprintf(w->base_error, sizeof w->base_error, "base: frame 0 is a folded form (the kinematics needs the crease pattern)");
            return;
        }
        if (ori_fold_set_pattern(w->doc, 0, w->pattern, &e) != ORI_OK) {
            fmt_error(w->base_error, sizeof w->base_error, "base", &e);
            return;
        }
    } else if (ori_generate(&c->gen, &w->pattern, NULL, &e) != ORI_OK) {
        fmt_error(w->base_error, sizeof w->base_error, "base", &e);
        return;
    }
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = w->pattern;
    if (ori_mechanism_create(&md, &w->mech, &e) != ORI_OK) fmt_error(w->base_error, sizeof w->base_error, "base", &e);
}

static void count_layers(sweep_worker *w, const sweep_cfg *c)
{
    w->has_layers = true;
    w->layers_limit = c->layers_limit;
    w->layers_error[0] = '\0';
    ori_layers_def ld = ori_default_layers_def();
    ld.limit = c->layers_limit;
    ori_layers *L = NULL;
    ori_error e;
    if (ori_layers_create(w->pattern, &ld, &L, &e) != ORI_OK || ori_layers_count(L, &e) != ORI_OK) {
        fmt_error(w->layers_error, sizeof w->layers_error, "layers", &e);
        ori_layers_destroy(L);
        return;
    }
    char *count = ori_layers_state_count(L);
    snprintf(w->layer_count, sizeof w->layer_count, "%s%s", count, ori_layers_get_info(L).limited ? "+" : "");
    ori_buffer_free(count);
    ori_layers_destroy(L);
}

// The interior crease whose midpoint is nearest to the centre of the sheet's bounding box.
static int center_crease(const ori_pattern *p)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        ori_v3 x = ori_pattern_vertex(p, v);
        lo[0] = fmin(lo[0], x.x), lo[1] = fmin(lo[1], x.y), hi[0] = fmax(hi[0], x.x), hi[1] = fmax(hi[1], x.y);
    }
    double cx = 0.5 * (lo[0] + hi[0]), cy = 0.5 * (lo[1] + hi[1]), best = INFINITY;
    int at = ORI_NULL_INDEX;
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        if (ed.assignment != ORI_ASSIGN_MOUNTAIN && ed.assignment != ORI_ASSIGN_VALLEY && ed.assignment != ORI_ASSIGN_UNASSIGNED)
            continue;
        ori_v3 a = ori_pattern_vertex(p, ed.v[0]), b = ori_pattern_vertex(p, ed.v[1]);
        double dx = 0.5 * (a.x + b.x) - cx, dy = 0.5 * (a.y + b.y) - cy, d = dx * dx + dy * dy;
        if (d < best) best = d, at = e;
    }
    return at;
}

// Resolve the fold's faces and creases against the pattern; false with w->fold_error set.
static bool resolve(sweep_worker *w, const sweep_cfg *c)
{
    int E = ori_pattern_edge_count(w->pattern), F = ori_pattern_face_count(w->pattern);
    if (c->fix_kind < 0) w->fix = ori_pattern_center_face(w->pattern);
    else if (c->fix_kind == 0) w->fix = c->fix;
    else {
        bool on_edge;
        w->fix = ori_pattern_find_face_at(w->pattern, ori_v2_make(c->fix_xy[0], c->fix_xy[1]), &on_edge);
        if (w->fix == ORI_NULL_INDEX) {
            snprintf(w->fold_error, sizeof w->fold_error, "job.fold.fix: no face at (%g, %g)", c->fix_xy[0], c->fix_xy[1]);
            return false;
        }
    }
    if (w->fix < 0 || w->fix >= F) {
        snprintf(w->fold_error, sizeof w->fold_error, "job.fold.fix: no face %d (the pattern has faces 0 to %d)", w->fix, F - 1);
        return false;
    }
    if (!c->targets) {
        w->drive = c->drive_kind == 0   ? c->drive
                   : c->drive_kind == 1 ? ori_pattern_find_edge_at(w->pattern, ori_v2_make(c->drive_xy[0], c->drive_xy[1]))
                                        : center_crease(w->pattern);
        if (w->drive == ORI_NULL_INDEX) {
            snprintf(w->fold_error, sizeof w->fold_error, "job.fold.drive: no crease %s", c->drive_kind == 1 ? "through that point" : "in the pattern");
            return false;
        }
        if (w->drive < 0 || w->drive >= E) {
            snprintf(w->fold_error, sizeof w->fold_error, "job.fold.drive: no edge %d (the pattern has edges 0 to %d)", w->drive, E - 1);
            return false;
        }
    }
    w->lock_count = c->lock_count;
    for (int i = 0; i < c->lock_count; ++i) {
        if (c->locks[i] >= E) {
            snprintf(w->fold_error, sizeof w->fold_error, "job.fold.lock[%d]: no edge %d (the pattern has edges 0 to %d)", i, c->locks[i], E - 1);
            return false;
        }
        w->locks[i] = c->locks[i];
    }
    return true;
}

static ori_motion_def motion_def(const sweep_worker *w, const sweep_cfg *c)
{
    ori_motion_def d = ori_default_motion_def();
    d.fixed_face = w->fix;
    d.driven_edge = w->drive;
    d.has_from = c->has_from;
    d.from_rad = ori_deg_to_rad(c->from_deg);
    d.to_rad = ori_deg_to_rad(c->to_deg);
    d.step_rad = ori_deg_to_rad(c->step_deg);
    d.locked_edges = w->locks;
    d.locked_count = w->lock_count;
    return d;
}

// Least clearance over frames 0 … last (positions from get).
static bool clearance_over(ori_collider *col, int last, void (*get)(const void *, int, int, ori_v3 *), const void *src, int V,
                           double *out, ori_error *e)
{
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)(V + 1));
    double m = INFINITY;
    bool ok = true;
    for (int f = 0; f <= last && ok; ++f) {
        get(src, f, V, pos);
        ori_collision_result r;
        ok = ori_collider_check(col, pos, &r, e) == ORI_OK;
        if (ok) m = fmin(m, r.min_clearance);
    }
    free(pos);
    *out = m;
    return ok;
}

static void motion_vertices(const void *mo, int f, int V, ori_v3 *pos)
{
    (void)V;
    ori_motion_frame_vertices(mo, f, pos);
}
static void multi_vertices(const void *mf, int f, int V, ori_v3 *pos)
{
    (void)V;
    ori_multifold_frame_vertices(mf, f, pos);
}
static void record_vertices(const void *r, int f, int V, ori_v3 *pos)
{
    memcpy(pos, ori_record_frame_vertices(r, f), sizeof(ori_v3) * (size_t)V);
}

static void solve_fold(sweep_worker *w, const sweep_cfg *c)
{
    w->fold_key = strdup(c->fold_key);
    w->fold_error[0] = '\0';
    w->collides = false;
    w->min_clearance = INFINITY;
    ori_error e;
    double start = 0.0, goal = 1.0;
    if (c->sequence) { // job.sequence: its folds run on the base from the flat sheet
        if (ori_sequence_parse(c->sequence, strlen(c->sequence), &w->sequence, &e) != ORI_OK ||
            ori_sequence_resolve(w->sequence, w->pattern, &e) != ORI_OK ||
            ori_sequence_run(w->sequence, w->mech, NULL, ori_rigid_identity(), &w->record, &e) != ORI_OK) {
            fmt_error(w->fold_error, sizeof w->fold_error, "sequence", &e);
            return;
        }
        ori_motion_verdict v = ori_record_verdict(w->record);
        snprintf(w->verdict, sizeof w->verdict, "%s", ori_motion_verdict_name(v));
        w->frames = ori_record_frame_count(w->record);
        // the folds done (the failing one up to where it stopped), of all of them
        w->reached = v == ORI_MOTION_VALID ? 1.0
                     : w->frames > 0       ? ori_record_duration(w->record) / ori_sequence_fold_count(w->sequence)
                                           : 0.0;
    } else if (!resolve(w, c)) {
        return;
    } else if (!c->targets) {
        ori_motion_def d = motion_def(w, c);
        if (ori_motion_solve(w->mech, &d, &w->motion, &e) != ORI_OK) {
            fmt_error(w->fold_error, sizeof w->fold_error, "fold", &e);
            return;
        }
        ori_motion_verdict v = ori_motion_verdict_of(w->motion);
        snprintf(w->verdict, sizeof w->verdict, "%s", ori_motion_verdict_name(v));
        w->frames = ori_motion_frame_count(w->motion);
        start = c->has_from ? ori_deg_to_rad(c->from_deg) : 0.0;
        goal = ori_deg_to_rad(c->to_deg);
        double at = w->frames > 0 ? ori_motion_frame_drive(w->motion, w->frames - 1) : start;
        w->reached = v == ORI_MOTION_VALID ? 1.0 : goal != start ? (at - start) / (goal - start) : 0.0;
    } else {
        ori_target_fold_def d = ori_default_target_fold_def();
        d.fixed_face = w->fix;
        d.fraction = c->percent / 100.0;
        d.step_rad = ori_deg_to_rad(c->step_deg);
        d.locked_edges = w->locks;
        d.locked_count = w->lock_count;
        if (ori_target_fold_solve(w->mech, &d, &w->multi, &e) != ORI_OK) {
            fmt_error(w->fold_error, sizeof w->fold_error, "fold", &e);
            return;
        }
        snprintf(w->verdict, sizeof w->verdict, "%s", ori_multifold_verdict_name(ori_multifold_verdict_of(w->multi)));
        w->frames = ori_multifold_frame_count(w->multi);
        w->reached = w->frames > 0 ? ori_multifold_frame_progress(w->multi, w->frames - 1) : 0.0;
    }
    if (!c->collide || w->frames == 0) return;
    ori_collider_def cd = ori_default_collider_def();
    cd.pattern = w->pattern;
    cd.clearance = c->clearance;
    ori_collider *col = NULL;
    if (ori_collider_create(&cd, &col, &e) != ORI_OK) {
        fmt_error(w->fold_error, sizeof w->fold_error, "collide", &e);
        return;
    }
    ori_collision_motion_def md = ori_default_collision_motion_def();
    ori_collision_event ev;
    ori_status st;
    if (w->record) {
        st = ori_collision_check_record(col, w->record, &md, &ev, &e);
    } else if (w->motion) {
        ori_motion_def d = motion_def(w, c);
        st = ori_collision_check_motion(col, w->mech, &d, w->motion, &md, &ev, &e);
    } else {
        st = ori_collision_check_multifold(col, w->multi, w->locks, w->lock_count, &md, &ev, &e);
    }
    if (st == ORI_OK && ev.collides) {
        w->collides = true;
        snprintf(w->verdict, sizeof w->verdict, "collision");
        w->reached = w->record   ? ev.time / ori_sequence_fold_count(w->sequence)
                     : w->motion ? (goal != start ? (ev.drive_rad - start) / (goal - start) : 0.0)
                                 : ev.drive_rad;
        w->min_clearance = 0.0;
    } else if (st == ORI_OK && w->spec->outputs[SWEEP_OUT_MIN_CLEARANCE]) {
        int V = ori_pattern_vertex_count(w->pattern);
        void (*get)(const void *, int, int, ori_v3 *) = w->record ? record_vertices : w->motion ? motion_vertices : multi_vertices;
        const void *src = w->record ? (const void *)w->record : w->motion ? (const void *)w->motion : (const void *)w->multi;
        if (!clearance_over(col, w->frames - 1, get, src, V, &w->min_clearance, &e)) st = e.status;
    }
    if (st != ORI_OK) fmt_error(w->fold_error, sizeof w->fold_error, "collide", &e);
    ori_collider_destroy(col);
}

// The design of the point: the file's (or none), with the spec's overrides.
static bool make_design(sweep_worker *w, const sweep_cfg *c, ori_design **out, char *err, size_t n)
{
    ori_design_def dd = ori_default_design_def();
    dd.doc = w->doc;
    dd.pattern = w->pattern;
    dd.has_meters_per_unit = c->has_unit;
    dd.meters_per_unit = c->unit_m;
    ori_error e;
    ori_design *d = NULL;
    if (ori_design_create(&dd, &d, &e) != ORI_OK) {
        fmt_error(err, n, "design", &e);
        return false;
    }
    *out = d;
    if (c->has_panel)
        for (int f = 0; f < ori_pattern_face_count(w->pattern); ++f) {
            ori_panel p;
            if (!ori_design_panel(d, f, &p)) {
                if (!c->has_panel_material || !c->has_panel_thickness) continue; // only faces with panel data change
                memset(&p, 0, sizeof p);
            }
            if (c->has_panel_material) snprintf(p.material, sizeof p.material, "%s", c->panel_material);
            if (c->has_panel_thickness) p.thickness_m = c->panel_thickness;
            if (ori_design_set_panel(d, f, &p, &e) != ORI_OK) {
                fmt_error(err, n, "design.panel", &e);
                return false;
            }
        }
    const sweep_hinge_spec *s = &c->hinge;
    if (c->has_hinge)
        for (int ed = 0; ed < ori_pattern_edge_count(w->pattern); ++ed) {
            ori_hinge h;
            bool had = ori_design_hinge(d, ed, &h);
            if (c->hinges_every) {
                if (ori_mechanism_edge_joint(w->mech, ed) == ORI_NULL_INDEX) continue;
                if (!had) memset(&h, 0, sizeof h);
            } else if (!had) continue;
            double t0 = h.thickness_m, w0 = h.width_m;
            bool span_default = had && h.span_m == ORI_HINGE_SPAN_PER_THICKNESS * t0;
            if (s->has_material) snprintf(h.material, sizeof h.material, "%s", s->material);
            if (s->has_width) h.width_m = s->width;
            if (s->has_thickness) h.thickness_m = s->thickness;
            if (s->has_span) h.span_m = s->span;
            else if (!had || span_default) h.span_m = ORI_HINGE_SPAN_PER_THICKNESS * h.thickness_m;
            if (s->wire == 0) h.has_wire = false;
            if (h.has_wire) { // a wire of the hinge's film follows the film
                if (h.wire.thickness_m == t0) h.wire.thickness_m = h.thickness_m;
                if (h.wire.width_m == w0) h.wire.width_m = h.width_m;
            }
            if (s->wire == 1) {
                if (!h.has_wire) {
                    memset(&h.wire, 0, sizeof h.wire);
                    h.wire.turns = 1;
                    h.wire.face = ORI_NULL_INDEX;
                    h.wire.width_m = h.width_m;
                    h.wire.thickness_m = h.thickness_m;
                }
                h.has_wire = true;
                if (s->has_wire_length) h.wire.length_m = s->wire_length;
                if (s->has_wire_lever) h.wire.lever_m = s->wire_lever;
                if (s->wire_turns > 0) h.wire.turns = s->wire_turns;
            }
            if (c->wires == 1 && ed != w->drive) h.has_wire = false;
            if (c->wires == 2) {
                bool listed = false;
                for (int i = 0; i < c->wire_count; ++i) listed |= c->wire_edges[i] == ed;
                if (!listed) h.has_wire = false;
            }
            if (ori_design_set_hinge(d, ed, &h, &e) != ORI_OK) {
                if (c->hinges_every && h.has_wire && !had) { // a wire that does not fit its panel: a plain hinge there
                    h.has_wire = false;
                    if (ori_design_set_hinge(d, ed, &h, &e) == ORI_OK) continue;
                }
                fmt_error(err, n, "design.hinge", &e);
                return false;
            }
        }
    ori_actuation a = ori_design_actuation(d);
    if (c->has_field) {
        a.has_field = true;
        a.field_t = c->field;
        a.schedule_count = 0;
    }
    if (c->has_current_limit) {
        a.has_current_limit = true;
        a.current_limit_a = c->current_limit;
    }
    if (c->gravity == 1) a.gravity_m_s2 = ori_v3_make(0, 0, -9.80665);
    if (c->gravity == 0) a.gravity_m_s2 = ori_v3_make(0, 0, 0);
    if (ori_design_set_actuation(d, &a, &e) != ORI_OK) {
        fmt_error(err, n, "design", &e);
        return false;
    }
    return true;
}

static void set(sweep_result *r, sweep_output o, double x)
{
    if (!isfinite(x)) return; // INFINITY (cannot) and NaN are SQL NULL
    r->has[o] = 1;
    r->real[o] = x;
}

static void failed(sweep_result *r, const char *why)
{
    r->ok = 0;
    snprintf(r->error, sizeof r->error, "%.*s", (int)sizeof r->error - 1, why);
}

// The dynamics as orikin simulate runs it: targets from the pattern's fold angles (else ±180° by
// assignment), the field schedule the file's, or the one the sizing finds best along the
// quasi-static fold of the reference crease toward its target (5° steps), else the fixed field.
static void simulate(sweep_worker *w, const sweep_cfg *c, const ori_design *d, sweep_result *r)
{
    const bool *want = w->spec->outputs;
    int E = ori_pattern_edge_count(w->pattern);
    int fixed = c->sim_fix >= 0 ? c->sim_fix : c->fold ? w->fix : ori_pattern_center_face(w->pattern);
    char why[SWEEP_ERROR_MAX];
    if (fixed < 0 || fixed >= ori_pattern_face_count(w->pattern)) {
        snprintf(why, sizeof why, "job.simulate.fix: no face %d (the pattern has faces 0 to %d)", fixed,
                 ori_pattern_face_count(w->pattern) - 1);
        failed(r, why);
        return;
    }
    double *targets = malloc(sizeof(double) * (size_t)(E + 1));
    bool angles = ori_pattern_has_fold_angles(w->pattern);
    for (int e = 0; e < E; ++e) {
        ori_edge ed = ori_pattern_edge(w->pattern, e);
        targets[e] = angles ? ed.fold_angle_rad
                     : ed.assignment == ORI_ASSIGN_VALLEY ? ORI_PI : ed.assignment == ORI_ASSIGN_MOUNTAIN ? -ORI_PI : 0.0;
    }
    ori_actuation a = ori_design_actuation(d);
    ori_field_change sched[ORI_SCHEDULE_MAX];
    int ns = 0;
    bool fixed_field = c->fixed_field || !a.has_field;
    ori_error e;
    if (!(!c->fixed_field && c->reorientations < 0 && a.schedule_count > 0) && !fixed_field) {
        int ref = a.reference_edge;
        for (int ed = 0; ed < E && ref == ORI_NULL_INDEX; ++ed) {
            ori_hinge h;
            if (ori_design_hinge(d, ed, &h) && h.has_wire) ref = ed;
        }
        ori_motion *mo = NULL;
        if (ref != ORI_NULL_INDEX) {
            ori_motion_def md = ori_default_motion_def();
            md.fixed_face = fixed;
            md.driven_edge = ref;
            md.to_rad = targets[ref];
            md.step_rad = ori_deg_to_rad(5.0);
            if (ori_motion_solve(w->mech, &md, &mo, &e) != ORI_OK || ori_motion_verdict_of(mo) != ORI_MOTION_VALID) {
                ori_motion_destroy(mo);
                mo = NULL;
            }
        }
        if (mo) {
            ori_sizing_def sd = ori_default_sizing_def();
            sd.design = d;
            sd.mechanism = w->mech;
            sd.motion = mo;
            sd.driven_edge = ref;
            sd.schedule = ORI_SCHEDULE_OPTIMIZE;
            sd.reorientations = c->reorientations;
            ori_sizing *z = NULL;
            ori_status st = ori_sizing_solve(&sd, &z, &e);
            ori_motion_destroy(mo);
            if (st != ORI_OK) {
                fmt_error(why, sizeof why, "simulate", &e);
                failed(r, why);
                free(targets);
                return;
            }
            ns = ori_sizing_schedule_count(z);
            for (int i = 0; i < ns; ++i) sched[i] = ori_sizing_schedule_at(z, i);
            ori_sizing_destroy(z);
        } else {
            fixed_field = true;
        }
    }
    if (fixed_field && a.has_field) {
        sched[0].edge = ORI_NULL_INDEX;
        sched[0].from_rad = 0.0;
        sched[0].field_t = a.field_t;
        sched[0].fold = 0;
        ns = 1;
    }
    ori_simulation_def sd = ori_default_simulation_def();
    sd.design = d;
    sd.mechanism = w->mech;
    sd.fixed_face = fixed;
    sd.target_angles_rad = targets;
    sd.current_a = c->sim_current;
    sd.schedule = sched;
    sd.schedule_count = ns;
    sd.duration_s = c->sim_duration;
    sd.has_dt = c->has_sim_dt;
    sd.dt_s = c->sim_dt;
    ori_simulation *s = NULL;
    if (ori_simulation_run(&sd, &s, &e) != ORI_OK) {
        fmt_error(why, sizeof why, "simulate", &e);
        failed(r, why);
    } else {
        ori_simulation_summary su = ori_simulation_summary_of(s);
        if (want[SWEEP_OUT_SIM_REACHED]) set(r, SWEEP_OUT_SIM_REACHED, su.reached_target);
        if (want[SWEEP_OUT_FOLD_TIME] && su.reached_target) set(r, SWEEP_OUT_FOLD_TIME, su.time_to_target_s);
    }
    ori_simulation_destroy(s);
    free(targets);
}

// --fold-files: the base (frame 0 with the file's design data, or the generated pattern) with
// the fold's last state appended as a folded frame, saved atomically as DIR/point-INDEX.fold, with
// the point's index and parameter values. False with the reason in why.
static bool write_fold_file(const sweep_worker *w, int64_t index, char *why, size_t n)
{
    const sweep_spec *spec = w->spec;
    ori_error e;
    ori_fold *doc = NULL;
    if (w->doc) {
        if (ori_fold_extract_frame(w->doc, 0, &doc, &e) != ORI_OK) {
            fmt_error(why, n, "fold file", &e);
            return false;
        }
    } else {
        doc = ori_fold_create();
        if (ori_fold_set_pattern(doc, 0, w->pattern, &e) != ORI_OK) {
            fmt_error(why, n, "fold file", &e);
            ori_fold_destroy(doc);
            return false;
        }
    }
    int V = ori_mechanism_vertex_count(w->mech), E = ori_mechanism_edge_count(w->mech);
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)(V + 1));
    const double *angles;
    if (w->record) {
        memcpy(pos, ori_record_frame_vertices(w->record, w->frames - 1), sizeof(ori_v3) * (size_t)V);
        angles = ori_record_frame_angles(w->record, w->frames - 1);
    } else if (w->motion) {
        ori_motion_frame_vertices(w->motion, w->frames - 1, pos);
        angles = ori_motion_frame_angles(w->motion, w->frames - 1);
    } else {
        ori_multifold_frame_vertices(w->multi, w->frames - 1, pos);
        angles = ori_multifold_frame_angles(w->multi, w->frames - 1);
    }
    char title[96], num[32];
    snprintf(title, sizeof title, "sweep point %lld: %s, %.6g of the way", (long long)index, w->verdict, w->reached);
    int fr = ori_fold_append_state(doc, 0, V, pos, E, angles, title);
    free(pos);
    snprintf(num, sizeof num, "%lld", (long long)index);
    ori_status st = fr < 0 ? ORI_ERR_INTERNAL : ori_fold_set_custom(doc, fr, "orikin:sweep_point", num, &e);
    if (st == ORI_OK) {
        sweep_value values[SWEEP_MAX_PARAMS];
        int64_t sample = 0;
        sweep_point_values(spec, index, values, &sample);
        json_t *o = json_object();
        for (int j = 0; j < spec->param_count; ++j)
            json_object_set_new(o, spec->params[j].name,
                                values[j].is_string ? json_string(values[j].string) : json_real(values[j].number));
        char *text = json_dumps(o, JSON_COMPACT | JSON_SORT_KEYS | JSON_REAL_PRECISION(17));
        json_decref(o);
        st = ori_fold_set_custom(doc, fr, "orikin:parameters", text, &e);
        free(text);
    }
    char path[4096];
    snprintf(path, sizeof path, "%s/point-%lld.fold", spec->fold_dir, (long long)index);
    if (st == ORI_OK) st = ori_fold_save_file(doc, path, &e);
    ori_fold_destroy(doc);
    if (st != ORI_OK) {
        if (fr < 0) snprintf(why, n, "fold file: the state could not be appended");
        else fmt_error(why, n, "fold file", &e);
        return false;
    }
    return true;
}

void sweep_worker_run(sweep_worker *w, int64_t index, sweep_result *r)
{
    memset(r, 0, sizeof *r);
    r->index = index;
    r->ok = 1;
    json_t *job = sweep_point_job(w->spec, index);
    sweep_cfg *c = malloc(sizeof *c);
    char why[SWEEP_ERROR_MAX];
    int rc = sweep_cfg_parse(job, w->spec->dir, c, why, sizeof why);
    json_decref(job);
    if (rc) {
        char msg[SWEEP_ERROR_MAX + 8];
        snprintf(msg, sizeof msg, "spec: %s", why);
        failed(r, msg);
        sweep_cfg_free(c);
        free(c);
        return;
    }
    const bool *want = w->spec->outputs;
    if (!w->base_key || strcmp(w->base_key, c->base_key) != 0) {
        drop_base(w);
        load_base(w, c);
    }
    if (w->base_error[0]) {
        failed(r, w->base_error);
        goto done;
    }
    if (c->layers && want[SWEEP_OUT_LAYER_COUNT]) {
        if (!w->has_layers || w->layers_limit != c->layers_limit) count_layers(w, c);
        if (w->layers_error[0]) {
            failed(r, w->layers_error);
            goto done;
        }
        r->has[SWEEP_OUT_LAYER_COUNT] = 1;
        snprintf(r->layer_count, sizeof r->layer_count, "%s", w->layer_count);
    }
    if (c->fold) {
        if (!w->fold_key || strcmp(w->fold_key, c->fold_key) != 0) {
            drop_fold(w);
            solve_fold(w, c);
        }
        if (w->fold_error[0]) {
            failed(r, w->fold_error);
            goto done;
        }
        if (want[SWEEP_OUT_VERDICT]) {
            r->has[SWEEP_OUT_VERDICT] = 1;
            snprintf(r->verdict, sizeof r->verdict, "%s", w->verdict);
        }
        if (want[SWEEP_OUT_REACHED]) set(r, SWEEP_OUT_REACHED, w->reached);
        if (want[SWEEP_OUT_FRAMES]) set(r, SWEEP_OUT_FRAMES, w->frames);
        if (c->collide && want[SWEEP_OUT_COLLIDES]) set(r, SWEEP_OUT_COLLIDES, w->collides);
        if (c->collide && want[SWEEP_OUT_MIN_CLEARANCE]) set(r, SWEEP_OUT_MIN_CLEARANCE, w->min_clearance);
        if (w->spec->fold_dir && w->frames > 0 && !write_fold_file(w, index, why, sizeof why)) {
            failed(r, why);
            goto done;
        }
    }
    if (!c->actuate && !c->simulate) goto done;
    ori_design *d = NULL;
    if (!make_design(w, c, &d, why, sizeof why)) {
        failed(r, why);
        ori_design_destroy(d);
        goto done;
    }
    ori_error e;
    if (c->actuate && w->motion && ori_motion_verdict_of(w->motion) == ORI_MOTION_VALID) {
        ori_sizing_def sd = ori_default_sizing_def();
        sd.design = d;
        sd.mechanism = w->mech;
        sd.motion = w->motion;
        sd.driven_edge = w->drive;
        if (c->fixed_field) sd.schedule = ORI_SCHEDULE_FIXED;
        else if (c->reorientations >= 0) {
            sd.schedule = ORI_SCHEDULE_OPTIMIZE;
            sd.reorientations = c->reorientations;
        }
        ori_sizing *z = NULL;
        if (ori_sizing_solve(&sd, &z, &e) != ORI_OK) {
            fmt_error(why, sizeof why, "actuate", &e);
            failed(r, why);
        } else {
            ori_sizing_summary su = ori_sizing_summary_of(z);
            if (want[SWEEP_OUT_FEASIBLE]) set(r, SWEEP_OUT_FEASIBLE, su.feasible);
            if (want[SWEEP_OUT_CURRENT_NEEDED] && su.worst_edge >= 0) set(r, SWEEP_OUT_CURRENT_NEEDED, su.current_needed_a);
            if (want[SWEEP_OUT_MECHANISM_CURRENT]) set(r, SWEEP_OUT_MECHANISM_CURRENT, su.mechanism_current_a);
            if (want[SWEEP_OUT_WORST_EDGE] && su.worst_edge >= 0) set(r, SWEEP_OUT_WORST_EDGE, su.worst_edge);
        }
        ori_sizing_destroy(z);
    }
    if (r->ok && c->simulate) simulate(w, c, d, r);
    ori_design_destroy(d);
done:
    if (!r->ok) { // a failed point keeps no partial figures
        memset(r->has, 0, sizeof r->has);
        r->verdict[0] = r->layer_count[0] = '\0';
    }
    sweep_cfg_free(c);
    free(c);
}
