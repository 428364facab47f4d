// Actuation scenarios: (1) the dynamics of a 20×20 Miura-ori with every crease a gold hinge
// carrying a wire, 1 mm cells of 10 µm silicon, in a fixed 0.1 T field, for 10 ms of simulated
// time from a 30° fold (wall time per simulated millisecond, memory); (2) the quasi-static sizing
// of a 100×100 Miura-ori folded by a two-fold sequence (5° → 90° → 170° on the middle zig-zag
// crease), every crease a wired gold hinge.
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench.h"
#include <orikin/actuation.h>
#include <orikin/generate.h>
#include <orikin/sequence.h>

#define DEG (ORI_PI / 180.0)

static ori_pattern *miura(int n)
{
    ori_generate_def g = ori_default_generate_def(ORI_TESS_MIURA);
    g.rows = n;
    g.cols = n;
    g.width = 1.0;
    g.height = sqrt(1.25);
    g.angle_rad = atan2(1.0, 0.5);
    ori_pattern *p = NULL;
    ori_error err;
    return ori_generate(&g, &p, NULL, &err) == ORI_OK ? p : NULL;
}

// Every crease a 10 µm × 0.6 µm gold hinge (wired when `wire` says so), every face 10 µm
// silicon; millimetre cells.
static ori_design *miura_design(const ori_pattern *p, const ori_mechanism *m, bool (*wire)(int edge, void *), void *user)
{
    ori_design_def dd = ori_default_design_def();
    dd.pattern = p;
    dd.has_meters_per_unit = true;
    dd.meters_per_unit = 1e-3;
    ori_design *d = NULL;
    ori_error err;
    if (ori_design_create(&dd, &d, &err) != ORI_OK) return NULL;
    ori_panel panel = {"Si", 10e-6};
    for (int f = 0; f < ori_pattern_face_count(p); ++f) ori_design_set_panel(d, f, &panel, &err);
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        if (ori_mechanism_edge_joint(m, e) == ORI_NULL_INDEX) continue;
        ori_hinge h;
        memset(&h, 0, sizeof h);
        strcpy(h.material, "Au");
        h.width_m = 10e-6;
        h.thickness_m = 0.6e-6;
        h.span_m = 12e-6;
        if (wire && wire(e, user)) {
            h.has_wire = true;
            h.wire.length_m = 0.4e-3;
            h.wire.lever_m = 0.1e-3;
            h.wire.turns = 1;
            h.wire.face = ORI_NULL_INDEX;
            h.wire.width_m = h.width_m;
            h.wire.thickness_m = h.thickness_m;
        }
        if (ori_design_set_hinge(d, e, &h, &err) != ORI_OK) {
            h.has_wire = false; // a wire that does not fit its panel: the crease stays a plain hinge
            ori_design_set_hinge(d, e, &h, &err);
        }
    }
    ori_actuation a = ori_design_actuation(d);
    a.has_field = true;
    a.field_t = ori_v3_make(0.0, 0.06, 0.08);
    a.has_current_limit = true;
    a.current_limit_a = 0.05;
    ori_design_set_actuation(d, &a, &err);
    return d;
}

static bool every(int e, void *user)
{
    (void)e, (void)user;
    return true;
}

static int middle_zigzag(ori_pattern *p, int n)
{
    int i = n / 2, j = n / 2;
    return ori_pattern_find_edge(p, j * (n + 1) + i, (j + 1) * (n + 1) + i);
}

static int dynamics(void)
{
    int n = 20;
    ori_pattern *p = miura(n);
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = p;
    ori_mechanism *m = NULL;
    ori_error err;
    if (!p || ori_mechanism_create(&md, &m, &err) != ORI_OK) return 1;
    int drive = middle_zigzag(p, n);
    double sg = ori_pattern_edge(p, drive).assignment == ORI_ASSIGN_VALLEY ? 1.0 : -1.0;
    ori_motion_def mo = ori_default_motion_def();
    mo.driven_edge = drive;
    mo.to_rad = sg * 30 * DEG;
    mo.step_rad = 5 * DEG;
    ori_motion *start = NULL;
    if (ori_motion_solve(m, &mo, &start, &err) != ORI_OK || ori_motion_verdict_of(start) != ORI_MOTION_VALID) return 1;
    ori_design *d = miura_design(p, m, every, NULL);
    int wired = 0;
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_hinge h;
        wired += ori_design_hinge(d, e, &h) && h.has_wire;
    }
    ori_simulation_def sd = ori_default_simulation_def();
    sd.design = d;
    sd.mechanism = m;
    sd.start_angles_rad = ori_motion_frame_angles(start, ori_motion_frame_count(start) - 1);
    sd.current_a = 0.02;
    sd.duration_s = 10e-3;
    sd.output_frames = 11;
    sd.settle = false;
    ori_alloc_reset_peak();
    int64_t base = ori_alloc_live_bytes();
    double t0 = bench_now(), c0 = bench_cpu_now();
    ori_simulation *s = NULL;
    ori_status st = ori_simulation_run(&sd, &s, &err);
    double t1 = bench_now(), c1 = bench_cpu_now();
    if (st != ORI_OK) {
        printf("   dynamics failed: %s\n", err.message);
        return 1;
    }
    ori_simulation_summary su = ori_simulation_summary_of(s);
    printf("   dynamics %dx%d Miura, %d creases (%d wired), %d panels: 10 ms simulated in %d steps of %.3g s (%d explicit); "
           "%.3f s wall (%.3f s CPU) = %.3f s per simulated ms; max residual %.1e, energy drift %.2e; heap peak %.1f MB, "
           "RSS peak %.1f MB\n",
           n, n, ori_mechanism_joint_count(m), wired, ori_mechanism_face_count(m), su.steps, su.dt_s, su.explicit_steps, t1 - t0,
           c1 - c0, (t1 - t0) / 10.0, su.max_residual, su.energy_drift, (double)(ori_alloc_peak_bytes() - base) / 1e6,
           (double)bench_peak_rss() / 1e6);
    fflush(stdout);
    ori_simulation_destroy(s);
    ori_design_destroy(d);
    ori_motion_destroy(start);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
    return 0;
}

static int sizing(void)
{
    int n = 100;
    ori_pattern *p = miura(n);
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = p;
    ori_mechanism *m = NULL;
    ori_error err;
    if (!p || ori_mechanism_create(&md, &m, &err) != ORI_OK) return 1;
    int drive = middle_zigzag(p, n);
    double sg = ori_pattern_edge(p, drive).assignment == ORI_ASSIGN_VALLEY ? 1.0 : -1.0;
    ori_motion_def mo = ori_default_motion_def();
    mo.driven_edge = drive;
    mo.to_rad = sg * 5 * DEG;
    mo.step_rad = 5 * DEG;
    ori_motion *start = NULL;
    if (ori_motion_solve(m, &mo, &start, &err) != ORI_OK || ori_motion_verdict_of(start) != ORI_MOTION_VALID) return 1;
    char json[512];
    snprintf(json, sizeof json,
             "{\"pattern\": \"miura.fold\", \"folds\": [{\"fix\": 0, \"drive\": %d, \"to\": %g, \"step\": 10}, "
             "{\"fix\": 0, \"drive\": %d, \"to\": %g, \"step\": 10}]}",
             drive, sg * 90, drive, sg * 170);
    ori_sequence *seq = NULL;
    if (ori_sequence_parse(json, strlen(json), &seq, &err) != ORI_OK) return 1;
    double t0 = bench_now();
    ori_record *r = NULL;
    if (ori_sequence_run(seq, m, ori_motion_frame_angles(start, ori_motion_frame_count(start) - 1), ori_rigid_identity(), &r,
                         &err) != ORI_OK ||
        ori_record_verdict(r) != ORI_MOTION_VALID)
        return 1;
    double t1 = bench_now();
    ori_design *d = miura_design(p, m, every, NULL);
    ori_sizing_def sd = ori_default_sizing_def();
    sd.design = d;
    sd.mechanism = m;
    sd.record = r;
    sd.sequence = seq;
    ori_alloc_reset_peak();
    int64_t base = ori_alloc_live_bytes();
    double t2 = bench_now(), c2 = bench_cpu_now();
    ori_sizing *z = NULL;
    ori_status st = ori_sizing_solve(&sd, &z, &err);
    double t3 = bench_now(), c3 = bench_cpu_now();
    if (st != ORI_OK) {
        printf("   sizing failed: %s\n", err.message);
        return 1;
    }
    ori_sizing_summary su = ori_sizing_summary_of(z);
    int wired = 0, finite = 0;
    double most = 0.0;
    for (int i = 0; i < ori_sizing_hinge_count(z); ++i) {
        ori_hinge_sizing h = ori_sizing_hinge(z, i);
        if (!h.actuated) continue;
        wired++;
        if (isfinite(h.current_needed_a)) {
            finite++;
            most = fmax(most, h.current_needed_a);
        }
    }
    printf("   (each wire alone: %d of %d can drive their creases in the common field, the most needing %.4g mA)\n", finite,
           wired, most * 1e3);
    printf("   sizing %dx%d Miura sequence (2 folds, %d states; running it took %.2f s): %d hinges (%d wired) sized in %.3f s "
           "wall (%.3f s CPU); mechanism current %.4g mA, %d reorientations; heap peak %.1f MB, RSS peak %.1f MB\n",
           n, n, ori_sizing_frame_count(z), t1 - t0, ori_sizing_hinge_count(z), wired, t3 - t2, c3 - c2,
           su.mechanism_current_a * 1e3, su.reorientations, (double)(ori_alloc_peak_bytes() - base) / 1e6,
           (double)bench_peak_rss() / 1e6);
    fflush(stdout);
    ori_sizing_destroy(z);
    ori_design_destroy(d);
    ori_record_destroy(r);
    ori_sequence_destroy(seq);
    ori_motion_destroy(start);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
    return 0;
}

static int run(void) { return dynamics() | sizing(); }

const bench_scenario bench_actuation = {
    "actuation", "20x20 Miura dynamics for 10 ms (every crease a wired gold hinge); sizing of a 100x100 Miura sequence", run};
