// libFuzzer target for the actuation dynamics (ori_simulation_run): the input is 16 bytes of
// simulation parameters (current, duration, time step, damping, stops, pulse, output frames,
// settle, fixed face) followed by a FOLD document with actuation data (seeds: the thesis flap
// and the gold open corner, fuzz/seeds/simulate). Work stays bounded: at most 2,000 planned time
// steps, the settling's included (max_steps; an automatic time step can be tiny, and settling
// once ran unbounded, found by CI as a 13 s input). Invariants: no crash, leak or sanitizer report; a refusal says why; every output
// frame has finite angles in [−180°, 180°] and finite energies, times increase, and the
// summary is finite.
#include <math.h>
#include <orikin/orikin.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static double unit(const uint8_t *q) { return (q[0] | (q[1] << 8)) / 65535.0; }

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 16) return 0;
    const uint8_t *q = data;
    ori_fold *doc = NULL;
    ori_pattern *p = NULL;
    ori_error err;
    if (ori_fold_load_string((const char *)data + 16, size - 16, &doc, &err) != ORI_OK ||
        ori_fold_get_pattern(doc, 0, NULL, &p, &err) != ORI_OK || ori_pattern_is_folded_form(p) ||
        ori_pattern_vertex_count(p) > 64) {
        ori_pattern_destroy(p);
        ori_fold_destroy(doc);
        if (ori_alloc_live_count() != 0) abort();
        return 0;
    }
    ori_design_def dd = ori_default_design_def();
    dd.doc = doc;
    dd.pattern = p;
    dd.has_meters_per_unit = (q[15] & 1) != 0;
    dd.meters_per_unit = 1e-6;
    ori_design *d = NULL;
    ori_mechanism *m = NULL;
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = p;
    if (ori_design_create(&dd, &d, &err) == ORI_OK && ori_mechanism_create(&md, &m, &err) == ORI_OK) {
        ori_simulation_def sd = ori_default_simulation_def();
        sd.design = d;
        sd.mechanism = m;
        sd.fixed_face = q[0] % (ori_pattern_face_count(p) + 1); // one past the last: refused
        sd.current_a = 0.1 * unit(q + 1);
        sd.duration_s = 1e-5 + 1e-2 * unit(q + 3);
        if (q[5] & 1) {
            sd.has_dt = true;
            sd.dt_s = sd.duration_s / (1.0 + 1900.0 * unit(q + 6));
        }
        if (q[5] & 2) {
            sd.has_damping = true;
            sd.damping_ratio = 2.0 * unit(q + 8);
        }
        sd.stops = (q[5] & 4) != 0;
        sd.current_off_at_target = (q[5] & 8) != 0;
        sd.auto_polarity = (q[5] & 16) != 0;
        sd.settle = (q[5] & 32) != 0;
        if (q[5] & 64) {
            sd.has_pulse = true;
            sd.pulse_s = sd.duration_s * unit(q + 10);
        }
        sd.output_frames = 2 + q[12] % 19;
        sd.max_steps = 2000;
        ori_simulation *s = NULL;
        if (ori_simulation_run(&sd, &s, &err) == ORI_OK) {
            int n = ori_simulation_frame_count(s), E = ori_pattern_edge_count(p);
            if (n < 2) abort();
            double last = -INFINITY;
            for (int k = 0; k < n; ++k) {
                double t = ori_simulation_frame_time(s, k);
                if (!(t > last) || !isfinite(t)) abort();
                last = t;
                const double *a = ori_simulation_frame_angles(s, k);
                for (int e = 0; e < E; ++e)
                    if (!(fabs(a[e]) <= ORI_PI + 1e-9)) abort();
                double kin, pot;
                ori_simulation_frame_energy(s, k, &kin, &pot);
                if (!isfinite(kin) || !isfinite(pot) || kin < -1e-12) abort();
            }
            ori_simulation_summary sum = ori_simulation_summary_of(s);
            if (!isfinite(sum.energy_drift) || !isfinite(sum.max_residual) || !(sum.dt_s > 0.0) || sum.steps < 1) abort();
            ori_simulation_destroy(s);
        } else if (!err.message[0]) {
            abort(); // a refusal says why
        }
    }
    ori_mechanism_destroy(m);
    ori_design_destroy(d);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
