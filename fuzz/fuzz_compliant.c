// libFuzzer target for the compliant (bar-and-hinge) model: the input is 16 bytes of parameters
// (preset, stiffnesses over six decades, fold fraction, load step, damping, gravity, fixed face;
// whether to take the document's device design, the wires' current and the field's direction)
// followed by a FOLD document (seeds: the repository's small flat patterns, fuzz/seeds/compliant).
// With a design (physical preset, its panels, layered hinges and wires; the hinges made flat, as
// simulate --model compliant does) the current ramps with the fraction.
// Work stays bounded: patterns of at most 64 vertices, 8 load steps of Newton, 400 explicit
// steps. Invariants: no crash, leak or sanitizer report; a refusal says why; the static
// solver's states, energies, strains and fold angles are finite (angles in [−180°, 180°],
// energies ≥ 0 without gravity), its frames' fractions increase; the explicit solver at its own stable time
// step never diverges.
#include <math.h>
#include <orikin/orikin.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static double unit(const uint8_t *q) { return (q[0] | (q[1] << 8)) / 65535.0; }

// A stiffness from 1e-3 to 1e3 times base.
static double decades(const uint8_t *q, double base) { return base * pow(10.0, 6.0 * q[0] / 255.0 - 3.0); }

// (with gravity the energy includes m g z, which may be negative)
static void check_state(const ori_compliant *c, int edges, bool gravity)
{
    int V = ori_compliant_vertex_count(c);
    const ori_v3 *x = ori_compliant_positions(c);
    for (int v = 0; v < V; ++v)
        if (!isfinite(x[v].x) || !isfinite(x[v].y) || !isfinite(x[v].z)) abort();
    for (int e = 0; e < edges; ++e) {
        if (!(fabs(ori_compliant_fold_angle(c, e)) <= ORI_PI + 1e-9)) {
            fprintf(stderr, "edge %d angle %.17g\n", e, ori_compliant_fold_angle(c, e));
            abort();
        }
        if (!isfinite(ori_compliant_edge_strain(c, e))) abort();
    }
    double E = ori_compliant_energy(c);
    if (!isfinite(E) || (!gravity && E < -1e-9 * (1.0 + ori_compliant_load_scale(c)))) abort();
    for (int f = 0; f < ori_compliant_face_count(c); ++f)
        if (!isfinite(ori_compliant_face_energy(c, f)) || !isfinite(ori_compliant_face_strain(c, f))) abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 16) return 0;
    const uint8_t *q = data;
    ori_fold *doc = NULL;
    ori_pattern *p = NULL;
    ori_error err;
    ori_build_def bd = ori_default_build_def();
    bd.planarize = true;
    if (ori_fold_load_string((const char *)data + 16, size - 16, &doc, &err) != ORI_OK ||
        ori_fold_get_pattern(doc, 0, &bd, &p, &err) != ORI_OK || ori_pattern_vertex_count(p) > 64) {
        ori_pattern_destroy(p);
        ori_fold_destroy(doc);
        if (ori_alloc_live_count() != 0) abort();
        return 0;
    }
    ori_compliant_def d = (q[0] & 1) ? ori_compliant_physical_def() : ori_default_compliant_def();
    if (!(q[0] & 1)) {
        d.axial_stiffness = decades(q + 1, 20.0);
        d.facet_stiffness = decades(q + 2, 0.2);
        d.crease_stiffness = decades(q + 3, 0.7);
    }
    d.fraction = unit(q + 4);
    d.max_step_rad = 0.02 + 0.5 * unit(q + 6);
    d.max_iterations = 40;
    d.damping = (q[8] / 255.0) * 2.0;
    d.gravity = (q[9] & 1) ? 0.0 : 0.05 * (q[9] / 255.0);
    d.fixed_face = q[10] % (ori_pattern_face_count(p) + 2) - 1; // -1: the default; one past the last: refused
    d.keep_frames = (q[11] & 1) != 0;
    d.check_contacts = (q[11] & 2) != 0;
    int E = ori_pattern_edge_count(p);
    ori_design *design = NULL;
    double *flat = NULL;
    if (q[12] & 1) {
        ori_design_def dd = ori_default_design_def();
        dd.doc = doc;
        dd.pattern = p;
        if (!(q[12] & 2)) { // unitless drawings: as if in micrometres
            dd.has_meters_per_unit = true;
            dd.meters_per_unit = 1e-6;
        }
        if (ori_design_create(&dd, &design, &err) == ORI_OK) {
            ori_compliant_def pd = ori_compliant_physical_def();
            pd.fraction = d.fraction;
            pd.max_iterations = d.max_iterations;
            pd.fixed_face = d.fixed_face;
            pd.keep_frames = d.keep_frames;
            pd.check_contacts = d.check_contacts;
            pd.auto_polarity = (q[12] & 4) != 0;
            pd.design = design;
            pd.current_a = 0.05 * q[13] / 255.0; // 0 … 50 mA
            double th = ORI_PI * q[14] / 255.0, ph = 2.0 * ORI_PI * q[15] / 255.0;
            pd.field_t = ori_v3_make(0.1 * sin(th) * cos(ph), 0.1 * sin(th) * sin(ph), 0.1 * cos(th));
            flat = calloc((size_t)E + 1, sizeof(double));
            pd.target_angles_rad = flat;
            d = pd;
        } else if (!err.message[0]) {
            abort();
        }
    }
    bool gravity_or_wires = d.gravity != 0.0 || design; // the energy may be negative
    ori_compliant *c = NULL;
    if (ori_compliant_create(p, &d, &c, &err) == ORI_OK) {
        // load steps stay few: the fraction's rest-angle change over the step is bounded
        double span = 0.0;
        double *tgt = malloc(sizeof(double) * (size_t)(E + 1));
        ori_target_angles_default(p, tgt);
        for (int e = 0; e < E && !design; ++e) span = fmax(span, fabs(tgt[e]) * d.fraction);
        free(tgt);
        if (span / d.max_step_rad <= 8.0) {
            ori_status st = ori_compliant_solve_static(c, &err);
            if (st != ORI_OK && !err.message[0]) abort(); // a refusal says why
            check_state(c, E, gravity_or_wires);
            for (int e = 0; e < E; ++e)
                if (!isfinite(ori_compliant_plastic_rotation(c, e)) || !isfinite(ori_compliant_wire_current(c, e))) abort();
            double last = -INFINITY;
            for (int k = 0; k < ori_compliant_frame_count(c); ++k) {
                double fr = ori_compliant_frame_fraction(c, k);
                if (!(fr >= last) || !isfinite(fr)) abort();
                last = fr;
            }
        }
        // the explicit solver from the state reached, at its stable step: never diverges
        if (!(ori_compliant_time_step(c) > 0.0)) abort();
        int steps = 0;
        ori_status st = ori_compliant_run_dynamic(c, 400, 1e-6, &steps, &err);
        if (st != ORI_OK && strstr(err.message, "diverged")) abort();
        if (steps < 0 || steps > 400) abort();
        check_state(c, E, gravity_or_wires);
        ori_compliant_destroy(c);
    } else if (!err.message[0]) {
        abort();
    }
    free(flat);
    ori_design_destroy(design);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
