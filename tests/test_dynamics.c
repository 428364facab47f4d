// Folding dynamics (issue 11): a constant moment against θ = ½(M/J)t², energy conservation of
// elastic hinges (a flap over 1,000 periods, the closed-loop open corner), monotone decay with
// damping, the Lorentz work on a free flap, the thesis' fold (time, latching, springback), the
// open corner with two actuated hinges (residual at every step), stops, and bad input.
#define _POSIX_C_SOURCE 200809L
#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <orikin/actuation.h>

#include "support.h"

TestSuite(dynamics, .init = test_leak_setup, .fini = test_leak_check);

#define DEG (ORI_PI / 180.0)

static double rel(double a, double b) { return fabs(a - b) / fmax(fabs(b), 1e-300); }

typedef struct loaded {
    ori_fold *doc;
    ori_pattern *p;
    ori_mechanism *m;
    ori_design *d;
} loaded;

static loaded load_example(const char *rel_path)
{
    loaded x;
    ori_error err;
    cr_assert_eq(ori_fold_load_file(test_repo_path(rel_path), &x.doc, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_fold_get_pattern(x.doc, 0, NULL, &x.p, &err), ORI_OK, "%s", err.message);
    x.m = test_mechanism_of(x.p);
    ori_design_def dd = ori_default_design_def();
    dd.doc = x.doc;
    dd.pattern = x.p;
    cr_assert_eq(ori_design_create(&dd, &x.d, &err), ORI_OK, "%s: %s", err.field, err.message);
    return x;
}

static void loaded_free(loaded *x)
{
    ori_design_destroy(x->d);
    ori_mechanism_destroy(x->m);
    ori_pattern_destroy(x->p);
    ori_fold_destroy(x->doc);
}

static void set_gravity(loaded *x, bool on)
{
    ori_actuation a = ori_design_actuation(x->d);
    a.gravity_m_s2 = ori_v3_make(0, 0, on ? -9.80665 : 0.0);
    ori_error err;
    cr_assert_eq(ori_design_set_actuation(x->d, &a, &err), ORI_OK);
}

// A simulation of x's design and mechanism at 20 mA for 1 ms (the tests change what they test).
static ori_simulation_def flap_def(const loaded *x)
{
    ori_simulation_def d = ori_default_simulation_def();
    d.design = x->d;
    d.mechanism = x->m;
    d.current_a = 0.02;
    d.duration_s = 1e-3;
    return d;
}

static ori_simulation *run_ok(const ori_simulation_def *d)
{
    ori_simulation *s = NULL;
    ori_error err;
    cr_assert_eq(ori_simulation_run(d, &s, &err), ORI_OK, "%s: %s", err.field, err.message);
    return s;
}

// Inertia of the 500 µm × 500 µm × 10 µm flap about its hinge (an edge of the slab's mid-plane).
static double flap_inertia(const loaded *x)
{
    ori_face_mass fm = ori_design_face_mass(x->d, 1);
    double a = 500e-6, t = 10e-6;
    return fm.mass_kg * (a * a / 3.0 + t * t / 12.0);
}

Test(dynamics, constant_moment_gives_half_M_over_J_t_squared)
{
    // A flap on a crease without a hinge, driven by a constant moment M (no gravity): the
    // midpoint rule integrates the constant acceleration M/J exactly (1e-9 relative required).
    loaded x = load_example("examples/patterns/thesis-flap.fold");
    ori_error err;
    cr_assert_eq(ori_design_set_hinge(x.d, 0, NULL, &err), ORI_OK);
    set_gravity(&x, false);
    double J = flap_inertia(&x), M = 1e-10;
    double applied[7] = {M, 0, 0, 0, 0, 0, 0};
    ori_simulation_def d = ori_default_simulation_def();
    d.design = x.d;
    d.mechanism = x.m;
    d.applied_moments_nm = applied;
    d.duration_s = 2e-3;
    d.has_dt = true;
    d.dt_s = 1e-5;
    d.output_frames = 21;
    d.settle = false;
    ori_simulation *s = run_ok(&d);
    for (int k = 1; k < ori_simulation_frame_count(s); ++k) {
        double t = ori_simulation_frame_time(s, k), th = ori_simulation_frame_angles(s, k)[0];
        cr_assert_lt(rel(th, 0.5 * M / J * t * t), 1e-9, "t = %g: %.17g vs %.17g", t, th, 0.5 * M / J * t * t);
    }
    // The energy balance: kinetic energy = work of the moment.
    ori_simulation_summary su = ori_simulation_summary_of(s);
    cr_assert_lt(su.energy_drift, 1e-12);
    cr_assert_lt(rel(su.energy_in_j, M * ori_simulation_frame_angles(s, 20)[0]), 1e-12);
    ori_simulation_destroy(s);
    loaded_free(&x);
}

// An elastic flap (below yield) released with a rate: 1,000 periods at 64 steps per period.
static ori_simulation *elastic_flap(loaded *x, bool gravity, double damping, int periods, int frames)
{
    set_gravity(x, gravity);
    ori_hinge_mechanics hm;
    ori_design_hinge_mechanics(x->d, 0, &hm);
    double w = sqrt(hm.stiffness_nm_rad / flap_inertia(x)), T = 2 * ORI_PI / w;
    static double start[7], rates[7];
    start[0] = 0.4;
    rates[0] = 0.5 * hm.yield_rotation_rad * w; // amplitude half the elastic range
    ori_simulation_def d = ori_default_simulation_def();
    d.design = x->d;
    d.mechanism = x->m;
    d.start_angles_rad = start;
    d.start_rates_rad_s = rates;
    d.duration_s = periods * T;
    d.has_dt = true;
    d.dt_s = T / 64;
    d.has_damping = true;
    d.damping_ratio = damping;
    d.output_frames = frames;
    d.settle = false;
    return run_ok(&d);
}

Test(dynamics, undamped_elastic_flap_keeps_its_energy_over_1000_periods)
{
    loaded x = load_example("examples/patterns/thesis-flap.fold");
    for (int g = 0; g < 2; ++g) {
        ori_simulation *s = elastic_flap(&x, g == 1, 0.0, 1000, 1001);
        double e0;
        ori_simulation_frame_energy(s, 0, NULL, &e0);
        double worst = 0.0, kmax = 0.0;
        for (int k = 0; k < ori_simulation_frame_count(s); ++k) {
            double kin, e;
            ori_simulation_frame_energy(s, k, &kin, &e);
            worst = fmax(worst, fabs(e - e0));
            kmax = fmax(kmax, kin);
            cr_assert_lt(fabs(ori_simulation_frame_plastic(s, k)[0]), 1e-12); // never yields
        }
        // Relative to the oscillation's energy (the kinetic energy it reaches), 1e-6.
        cr_assert_lt(worst / kmax, 1e-6, "gravity %d: %g", g, worst / kmax);
        cr_assert_lt(ori_simulation_summary_of(s).energy_drift, 1e-6);
        if (g == 0) cr_assert_lt(worst / kmax, 1e-11); // a linear system: the midpoint rule keeps it exactly
        ori_simulation_destroy(s);
    }
    loaded_free(&x);
}

Test(dynamics, damped_energy_decreases_monotonically)
{
    loaded x = load_example("examples/patterns/thesis-flap.fold");
    ori_simulation *s = elastic_flap(&x, true, 0.05, 20, 20 * 32 + 1);
    double prev;
    ori_simulation_frame_energy(s, 0, NULL, &prev);
    double first = prev;
    for (int k = 1; k < ori_simulation_frame_count(s); ++k) {
        double e;
        ori_simulation_frame_energy(s, k, NULL, &e);
        cr_assert_leq(e, prev + 1e-12 * fabs(first), "frame %d: %g after %g", k, e, prev);
        prev = e;
    }
    // ζ = 0.05 over 20 periods: the oscillation energy falls by e^{−2ζω t} ≈ e^{−4π} of itself.
    double kin;
    ori_simulation_frame_energy(s, ori_simulation_frame_count(s) - 1, &kin, NULL);
    ori_simulation_summary su = ori_simulation_summary_of(s);
    cr_assert_gt(su.dissipated_j, 0.0);
    cr_assert_lt(su.energy_drift, 1e-6); // dissipation accounted
    ori_simulation_destroy(s);
    loaded_free(&x);
}

Test(dynamics, lorentz_work_on_a_free_flap)
{
    // A hingeless flap in a fixed horizontal field: the pendulum J·φ̈ = I·w·L·B·cos φ, whose
    // kinetic energy is I·w·L·B·sin φ. The stops are off so that it swings through.
    loaded x = load_example("examples/patterns/thesis-flap.fold");
    ori_error err;
    ori_hinge h;
    ori_design_hinge(x.d, 0, &h);
    ori_design_set_hinge(x.d, 0, NULL, &err);
    set_gravity(&x, false);
    ori_simulation_def d = ori_default_simulation_def();
    d.design = x.d;
    d.mechanism = x.m;
    d.duration_s = 1e-3;
    d.output_frames = 11;
    d.settle = false;
    d.stops = false;
    d.current_a = 0.02;
    // Without hinge data there is no wire: give the crease a hinge of negligible strength.
    h.thickness_m = 1e-9;
    h.span_m = 1.0;
    cr_assert_eq(ori_design_set_hinge(x.d, 0, &h, &err), ORI_OK, "%s", err.message);
    ori_field_change f = {ORI_NULL_INDEX, 0.0, {0, 0.1, 0}, 0};
    d.schedule = &f;
    d.schedule_count = 1;
    d.has_dt = true;
    d.dt_s = 2e-6;
    ori_simulation *s = run_ok(&d);
    double J = flap_inertia(&x), M0 = 0.02 * 500e-6 * 500e-6 * 0.1;
    for (int k = 1; k < 11; ++k) {
        double kin, phi = ori_simulation_frame_angles(s, k)[0];
        ori_simulation_frame_energy(s, k, &kin, NULL);
        cr_assert_lt(fabs(kin - M0 * sin(phi)), 2e-6 * M0, "φ = %g°", phi / DEG); // the hinge's work is below 1e-7 of it
    }
    (void)J;
    cr_assert_lt(ori_simulation_summary_of(s).energy_drift, 1e-6);
    ori_simulation_destroy(s);
    loaded_free(&x);
}

Test(dynamics, thesis_flap_folds_in_a_few_milliseconds_and_latches)
{
    // 20 mA in 0.1 T with the schedule the sizing finds (reoriented at 90°): the flap reaches
    // 180° in about 3.25 ms (the thesis: "within a few milliseconds"), is stopped by the
    // substrate, and springs back by M/k when the current stops to the sizing's permanent fold.
    loaded x = load_example("examples/patterns/thesis-flap.fold");
    ori_motion_def md = ori_default_motion_def();
    md.driven_edge = 0;
    md.to_rad = ORI_PI;
    md.step_rad = 10 * DEG;
    ori_motion *mo = NULL;
    ori_error err;
    cr_assert_eq(ori_motion_solve(x.m, &md, &mo, &err), ORI_OK);
    ori_sizing_def sd = ori_default_sizing_def();
    sd.design = x.d;
    sd.mechanism = x.m;
    sd.motion = mo;
    sd.driven_edge = 0;
    ori_sizing *z = NULL;
    cr_assert_eq(ori_sizing_solve(&sd, &z, &err), ORI_OK);
    ori_field_change sched[2] = {ori_sizing_schedule_at(z, 0), ori_sizing_schedule_at(z, 1)};
    ori_simulation_def d = flap_def(&x); // (its duration set below)
    d.schedule = sched;
    d.schedule_count = 2;
    d.duration_s = 6e-3;
    d.output_frames = 61;
    ori_simulation *s = run_ok(&d);
    ori_simulation_summary su = ori_simulation_summary_of(s);
    printf("thesis flap: 180 deg after %.4g ms at 20 mA, peak %.4g rad/s, latched at %.4g deg\n", su.time_to_target_s * 1e3,
           su.peak_angular_velocity, ori_simulation_latched_angles(s)[0] / DEG);
    cr_assert(su.reached_target);
    cr_assert(su.time_to_target_s > 1e-3 && su.time_to_target_s < 10e-3);
    cr_assert_lt(fabs(su.time_to_target_s - 3.25e-3), 0.03e-3, "%g", su.time_to_target_s); // regression, 1 %
    cr_assert_eq(su.max_residual, 0.0);                                                       // no loop
    ori_hinge_sizing h = ori_sizing_hinge(z, 0);
    bool at_stop = false;
    for (int k = 0; k < ori_simulation_frame_count(s); ++k) {
        double th = ori_simulation_frame_angles(s, k)[0];
        cr_assert_leq(th, ORI_PI, "the flap passed through the substrate");
        at_stop |= th == ORI_PI;
        if (th == ORI_PI) {
            // At the stop the hinge has taken the sizing's permanent fold, within the layered
            // section's departure from the continuum one (M_p/ORI_HINGE_LAYERS of moment).
            cr_assert_lt(fabs(ori_simulation_frame_plastic(s, k)[0] - h.plastic_rotation_rad),
                         h.mechanics.plastic_moment_nm / ORI_HINGE_LAYERS / h.mechanics.stiffness_nm_rad);
            cr_assert_eq(ori_simulation_frame_currents(s, k)[0] == 0.0 || k == 0, true);
        }
    }
    cr_assert(at_stop);
    // Latched: below 180° by about the springback (undamped rebound may yield it a little more),
    // and gravity presses the folded flap down by a fraction of a degree.
    double latched = ori_simulation_latched_angles(s)[0];
    cr_assert(latched < ORI_PI - 0.5 * h.springback_rad && latched > ORI_PI - 2.0 * h.springback_rad, "%g", latched / DEG);
    ori_simulation_destroy(s);
    ori_sizing_destroy(z);
    ori_motion_destroy(mo);
    loaded_free(&x);
}

Test(dynamics, open_corner_two_actuated_hinges_keep_the_loop_closed)
{
    // The open corner (one vertex loop) from the flat sheet, a singular state, with both wires
    // on at once in a tilted field; and the thesis' two folds one after the other. The loop
    // closes to ORI_TOL_RESIDUAL (1e-10) after every step.
    loaded x = load_example("examples/patterns/open-corner-gold.fold");
    double targets[13] = {0};
    targets[11] = 90 * DEG;
    targets[12] = 180 * DEG;
    ori_field_change f = {ORI_NULL_INDEX, 0.0, {0.05, -0.05, 0.07}, 0};
    ori_simulation_def d = ori_default_simulation_def();
    d.design = x.d;
    d.mechanism = x.m;
    d.fixed_face = 4;
    d.target_angles_rad = targets;
    d.current_a = 0.02;
    d.schedule = &f;
    d.schedule_count = 1;
    d.duration_s = 3e-3;
    d.output_frames = 31;
    d.settle = false;
    ori_simulation *s = run_ok(&d);
    ori_simulation_summary su = ori_simulation_summary_of(s);
    cr_assert_leq(su.max_residual, ORI_TOL_RESIDUAL);
    double moved = 0.0;
    for (int k = 0; k < ori_simulation_frame_count(s); ++k) {
        cr_assert_leq(ori_simulation_frame_residual(s, k), ORI_TOL_RESIDUAL);
        moved = fmax(moved, fabs(ori_simulation_frame_angles(s, k)[12]));
    }
    cr_assert_gt(moved, 1 * DEG);
    ori_simulation_destroy(s);

    // The sequence: fold 1 drives the diagonal with crease 11 held, fold 2 crease 11 with the
    // diagonal held; the field follows the sizing's schedule (one change per fold).
    ori_sequence *seq = NULL;
    ori_error err;
    cr_assert_eq(ori_sequence_load_file(test_repo_path("examples/open-corner-gold.seq.json"), &seq, &err), ORI_OK);
    ori_record *r = NULL;
    cr_assert_eq(ori_sequence_run(seq, x.m, NULL, ori_rigid_identity(), &r, &err), ORI_OK);
    ori_sizing_def sd = ori_default_sizing_def();
    sd.design = x.d;
    sd.mechanism = x.m;
    sd.record = r;
    sd.sequence = seq;
    ori_sizing *z = NULL;
    cr_assert_eq(ori_sizing_solve(&sd, &z, &err), ORI_OK);
    ori_field_change sched[ORI_SCHEDULE_MAX];
    int ns = ori_sizing_schedule_count(z);
    for (int i = 0; i < ns; ++i) sched[i] = ori_sizing_schedule_at(z, i);
    int stages[2] = {12, 11}, lock_counts[2] = {1, 1}, locks[2] = {11, 12};
    d.schedule = sched;
    d.schedule_count = ns;
    d.stage_count = 2;
    d.stage_edges = stages;
    d.stage_lock_counts = lock_counts;
    d.stage_lock_edges = locks;
    d.duration_s = 12e-3;
    d.output_frames = 25;
    s = run_ok(&d);
    su = ori_simulation_summary_of(s);
    printf("open corner: both folds done after %.4g ms at 20 mA; latched %.4g deg (diagonal), %.4g deg (down)\n",
           su.time_to_target_s * 1e3, ori_simulation_latched_angles(s)[12] / DEG, ori_simulation_latched_angles(s)[11] / DEG);
    cr_assert(su.reached_target);
    cr_assert_leq(su.max_residual, ORI_TOL_RESIDUAL);
    for (int k = 0; k < ori_simulation_frame_count(s); ++k) cr_assert_leq(ori_simulation_frame_residual(s, k), ORI_TOL_RESIDUAL);
    // Latched near the corner cube: the diagonal folded flat, the down crease near 90°.
    const double *lat = ori_simulation_latched_angles(s);
    cr_assert(lat[12] > 160 * DEG && lat[11] > 60 * DEG && lat[11] < 100 * DEG, "%g %g", lat[12] / DEG, lat[11] / DEG);
    ori_simulation_destroy(s);
    ori_sizing_destroy(z);
    ori_record_destroy(r);
    ori_sequence_destroy(seq);
    loaded_free(&x);
}

Test(dynamics, closed_loop_energy_is_conserved)
{
    // The open corner with elastic hinges only (no current, no gravity), started folded and
    // moving: the loop's constraint forces do no work, so the energy stays (bounded error of the
    // symmetric scheme plus projection), here 1e-6 over about 25 periods.
    loaded x = load_example("examples/patterns/open-corner-gold.fold");
    set_gravity(&x, false);
    ori_motion_def md = ori_default_motion_def();
    md.fixed_face = 4;
    md.driven_edge = 12;
    md.to_rad = 60 * DEG;
    md.step_rad = 60 * DEG;
    int lock = 11;
    md.locked_edges = &lock;
    md.locked_count = 1;
    ori_motion *mo = NULL;
    ori_error err;
    cr_assert_eq(ori_motion_solve(x.m, &md, &mo, &err), ORI_OK);
    double rates[13] = {0};
    rates[12] = 3.0;
    rates[11] = -2.0;
    ori_simulation_def d = ori_default_simulation_def();
    d.design = x.d;
    d.mechanism = x.m;
    d.fixed_face = 4;
    d.start_angles_rad = ori_motion_frame_angles(mo, ori_motion_frame_count(mo) - 1);
    d.start_rates_rad_s = rates;
    d.duration_s = 0.2;
    d.output_frames = 201;
    d.settle = false;
    ori_simulation *s = run_ok(&d);
    ori_simulation_summary su = ori_simulation_summary_of(s);
    cr_assert_lt(su.energy_drift, 1e-6);
    cr_assert_leq(su.max_residual, ORI_TOL_RESIDUAL);
    double e0;
    ori_simulation_frame_energy(s, 0, NULL, &e0);
    for (int k = 0; k < ori_simulation_frame_count(s); ++k) {
        double e;
        ori_simulation_frame_energy(s, k, NULL, &e);
        cr_assert_lt(fabs(e - e0), 1e-6 * e0);
    }
    ori_simulation_destroy(s);
    ori_motion_destroy(mo);
    loaded_free(&x);
}

Test(dynamics, bad_input)
{
    loaded x = load_example("examples/patterns/thesis-flap.fold");
    ori_simulation_def d = flap_def(&x);
    ori_simulation *s = NULL;
    ori_error err;
    d.duration_s = 0.0;
    cr_assert_eq(ori_simulation_run(&d, &s, &err), ORI_ERR_RANGE);
    d.duration_s = 1e-3;
    d.has_dt = true;
    d.dt_s = 2e-3; // larger than the duration
    cr_assert_eq(ori_simulation_run(&d, &s, &err), ORI_ERR_RANGE);
    // The work asked for is bounded up front: a step of 1e-300 s (it overflowed the step count
    // and the default step was used silently) and a duration of 1e6 s are refused, naming the
    // least time step that would do.
    d.dt_s = 1e-300;
    cr_assert_eq(ori_simulation_run(&d, &s, &err), ORI_ERR_LIMIT);
    cr_assert(strstr(err.message, "a larger time step (at least 1e-11 s)"), "%s", err.message);
    d.has_dt = false;
    d.duration_s = 1e6;
    cr_assert_eq(ori_simulation_run(&d, &s, &err), ORI_ERR_LIMIT);
    cr_assert(strstr(err.message, "time steps of"), "%s", err.message);
    cr_assert_null(s);
    d.duration_s = 1e-3;
    d.fixed_face = 7;
    cr_assert_eq(ori_simulation_run(&d, &s, &err), ORI_ERR_RANGE);
    d.fixed_face = 0;
    // The moving flap without panel data.
    ori_design_set_panel(x.d, 1, NULL, &err);
    cr_assert_eq(ori_simulation_run(&d, &s, &err), ORI_ERR_ARGUMENT);
    cr_assert_str_eq(err.field, "faces_orikin:panel");
    cr_assert_eq(err.element, 1);
    ori_panel p = {"Si", 10e-6};
    cr_assert_eq(ori_design_set_panel(x.d, 1, &p, &err), ORI_OK);
    // A zero field with current: rejected by the design and by the simulation's schedule.
    ori_actuation a = ori_design_actuation(x.d);
    a.field_t = ori_v3_make(0, 0, 0);
    cr_assert_eq(ori_design_set_actuation(x.d, &a, &err), ORI_ERR_ARGUMENT);
    ori_field_change zero = {ORI_NULL_INDEX, 0.0, {0, 0, 0}, 0};
    d.schedule = &zero;
    d.schedule_count = 1;
    cr_assert_eq(ori_simulation_run(&d, &s, &err), ORI_ERR_ARGUMENT);
    cr_assert_str_eq(err.field, "orikin:actuation");
    cr_assert_null(s);
    loaded_free(&x);
}

Test(dynamics, max_steps_bounds_the_run_and_the_settling)
{
    // A caller's own step budget: a run planned longer is refused up front, naming the budget;
    // settling (which may need many periods of the slowest hinge) stops at the steps left.
    loaded x = load_example("examples/patterns/thesis-flap.fold");
    ori_simulation_def d = flap_def(&x);
    d.has_dt = true;
    d.dt_s = 1e-5; // 100 planned steps
    d.output_frames = 11;
    ori_simulation *s = NULL;
    ori_error err;
    d.max_steps = 99;
    cr_assert_eq(ori_simulation_run(&d, &s, &err), ORI_ERR_LIMIT);
    cr_assert(strstr(err.message, "more than the 99 a simulation takes"), "%s", err.message);
    cr_assert_null(s);
    // Without a budget the settling runs on after the 100 steps; with one of 120 it stops there.
    d.max_steps = 0;
    s = run_ok(&d);
    int free_steps = ori_simulation_summary_of(s).steps;
    ori_simulation_destroy(s);
    cr_assert_gt(free_steps, 120, "%d", free_steps);
    d.max_steps = 120;
    s = run_ok(&d);
    cr_assert_eq(ori_simulation_summary_of(s).steps, 120);
    ori_simulation_destroy(s);
    loaded_free(&x);
}

Test(dynamics, cli_frames_with_frame_time_and_nothing_written_on_error)
{
    char *dir = test_tmpdir();
    char args[1024], *out = NULL;
    snprintf(args, sizeof args,
             "simulate examples/patterns/thesis-flap.fold --fix 0 --current 0.02 --duration 0.004 --frames 9 -o '%s/out.fold' "
             "--json",
             dir);
    cr_assert_eq(test_run_cli_split(args, &out, NULL), 0);
    json_error_t je;
    json_t *j = json_loads(out, 0, &je);
    cr_assert_not_null(j, "%s", out);
    free(out);
    cr_assert(json_is_number(json_object_get(j, "time_to_target")));
    cr_assert_eq(json_array_size(json_object_get(j, "latched_angle_deg")), 7);
    cr_assert(json_is_number(json_object_get(j, "peak_angular_velocity")));
    cr_assert(json_is_number(json_object_get(j, "energy_drift")));
    cr_assert(json_real_value(json_object_get(j, "max_residual")) <= ORI_TOL_RESIDUAL);
    cr_assert_eq(json_array_size(json_object_get(j, "frames")), 9);
    json_decref(j);
    // The frames replay: folded forms with frame_time in seconds, the flap turning.
    char path[1024];
    snprintf(path, sizeof path, "%s/out.fold", dir);
    ori_fold *doc = NULL;
    ori_error err;
    cr_assert_eq(ori_fold_load_file(path, &doc, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_fold_frame_count(doc), 10);
    for (int k = 1; k < 10; ++k) {
        cr_assert(ori_fold_frame_is_folded_form(doc, k));
        char *t = ori_fold_get_custom(doc, k, "frame_time");
        cr_assert_not_null(t);
        cr_assert_lt(fabs(atof(t) - 0.5e-3 * (k - 1)), 1e-15);
        ori_buffer_free(t);
        char *c = ori_fold_get_custom(doc, k, "orikin:edges_current");
        cr_assert_not_null(c);
        ori_buffer_free(c);
    }
    ori_pattern *last = NULL;
    cr_assert_eq(ori_fold_get_pattern(doc, 9, NULL, &last, &err), ORI_OK, "%s", err.message);
    cr_assert(ori_pattern_is_3d(last));
    cr_assert_gt(ori_pattern_edge(last, 0).fold_angle_rad, 90 * DEG);
    ori_pattern_destroy(last);
    ori_fold_destroy(doc);
    // Bad input: a usage error and an input error, and no file.
    snprintf(args, sizeof args,
             "simulate examples/patterns/thesis-flap.fold --fix 0 --current 0.02 --duration 0.001 --dt 0.01 -o '%s/bad.fold'", dir);
    cr_assert_eq(test_run_cli(args, NULL), 2);
    snprintf(args, sizeof args,
             "simulate tests/data/actuation/no-panel.fold --fix 0 --current 0.02 --duration 0.001 -o '%s/bad.fold'", dir);
    cr_assert_eq(test_run_cli(args, NULL), 3);
    snprintf(path, sizeof path, "%s/bad.fold", dir);
    FILE *f = fopen(path, "r");
    cr_assert_null(f, "a failed run wrote %s", path);
    test_tmpdir_remove(dir);
}

Test(dynamics, cli_actuate_json_fields)
{
    char *out = NULL;
    cr_assert_eq(test_run_cli_split("actuate examples/patterns/thesis-flap.fold --fix 0 --drive 0 --to 180 --json", &out, NULL), 0);
    json_t *j = json_loads(out, 0, NULL);
    cr_assert_not_null(j, "%s", out);
    free(out);
    cr_assert(json_is_true(json_object_get(j, "feasible")));
    json_t *h = json_array_get(json_object_get(j, "hinges"), 0);
    const char *keys[] = {"edge", "M_y", "M_p", "current_needed", "power_peak", "feasible", "optimal_thickness"};
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; ++i) cr_assert_not_null(json_object_get(h, keys[i]), "%s", keys[i]);
    cr_assert_lt(fabs(json_number_value(json_object_get(h, "M_p")) - 1.854e-10), 1e-22);
    json_t *sch = json_object_get(j, "field_schedule");
    cr_assert_eq(json_array_size(sch), 2);
    cr_assert_lt(fabs(json_number_value(json_object_get(json_array_get(sch, 1), "from_deg")) - 90.0), 1e-9);
    json_decref(j);
}
