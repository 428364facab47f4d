// orikin simulate: the folding dynamics of a sheet with elastoplastic hinges driven by Lorentz
// forces, closed loops included; time histories, the latched angles, FOLD frames with frame_time.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "actuation_args.h"
#include "progress.h"

static json_t *deg_array(const double *a, int n)
{
    json_t *j = json_array();
    for (int i = 0; i < n; ++i) json_array_append_new(j, json_real(ori_rad_to_deg_output(a[i])));
    return j;
}

// The field schedule: the file's, or the one the sizing finds best along the quasi-static fold
// of the reference crease (FILE) or along the sequence (SEQ.json). *how says which.
static int choose_schedule(act_input *in, const act_opts *o, int fixed, const double *targets, const ori_record *rec,
                           ori_field_change *sched, int *count, const char **how)
{
    ori_actuation a = ori_design_actuation(in->design);
    *count = 0;
    *how = "the file's";
    if (!o->fixed_field && o->reorientations < 0 && a.schedule_count > 0) return CLI_EXIT_OK; // library default
    if (o->fixed_field || !a.has_field) {
        *how = "fixed";
        return CLI_EXIT_OK;
    }
    const ori_mechanism *m = in->k.mech;
    int ref = a.reference_edge;
    for (int e = 0; e < ori_mechanism_edge_count(m) && ref == ORI_NULL_INDEX; ++e) {
        ori_hinge h;
        if (ori_design_hinge(in->design, e, &h) && h.has_wire) ref = e;
    }
    ori_motion *mo = NULL;
    if (!rec && ref != ORI_NULL_INDEX) {
        ori_motion_def d = ori_default_motion_def();
        d.fixed_face = fixed;
        if (cli_kin_fixed_pose("simulate", in->pattern_path, &in->k, fixed, &d.fixed_pose) != CLI_EXIT_OK)
            return CLI_EXIT_INPUT;
        d.start_angles_rad = in->k.angles;
        d.driven_edge = ref;
        d.to_rad = targets ? targets[ref] : 0.0;
        d.step_rad = ori_deg_to_rad(5.0);
        ori_error err;
        if (ori_motion_solve(m, &d, &mo, &err) != ORI_OK || ori_motion_verdict_of(mo) != ORI_MOTION_VALID) {
            ori_motion_destroy(mo);
            mo = NULL;
        }
    }
    if (!rec && !mo) {
        *how = "fixed (no single fold of the reference crease to optimise along: give a schedule or a SEQ.json)";
        return CLI_EXIT_OK;
    }
    ori_sizing_def sd = ori_default_sizing_def();
    sd.design = in->design;
    sd.mechanism = m;
    sd.motion = mo;
    sd.driven_edge = ref;
    sd.record = rec;
    sd.sequence = rec ? in->seq : NULL;
    sd.schedule = ORI_SCHEDULE_OPTIMIZE;
    sd.reorientations = o->reorientations;
    ori_sizing *z = NULL;
    ori_error err;
    ori_status st = ori_sizing_solve(&sd, &z, &err);
    ori_motion_destroy(mo);
    if (st != ORI_OK) return cli_input_error("simulate", in->is_sequence ? in->path : in->pattern_path, &err);
    *count = ori_sizing_schedule_count(z);
    for (int i = 0; i < *count; ++i) sched[i] = ori_sizing_schedule_at(z, i);
    ori_sizing_destroy(z);
    *how = "optimised along the quasi-static motion";
    return CLI_EXIT_OK;
}

static int write_frames(const act_input *in, const act_opts *o, const ori_simulation *s)
{
    const ori_mechanism *m = in->k.mech;
    int V = ori_mechanism_vertex_count(m), E = ori_mechanism_edge_count(m);
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)(V + 1));
    char buf[64];
    for (int f = 0; f < ori_simulation_frame_count(s); ++f) {
        ori_simulation_frame_vertices(s, f, pos);
        double t = ori_simulation_frame_time(s, f);
        char title[96];
        snprintf(title, sizeof title, "t = %.6g s", t);
        int fr = ori_fold_append_state(in->k.doc, 0, V, pos, E, ori_simulation_frame_angles(s, f), title);
        snprintf(buf, sizeof buf, "%.17g", t);
        ori_fold_set_custom(in->k.doc, fr, "frame_time", buf, NULL);
        json_t *cur = json_array(), *pl = deg_array(ori_simulation_frame_plastic(s, f), E);
        const double *c = ori_simulation_frame_currents(s, f);
        for (int e = 0; e < E; ++e) json_array_append_new(cur, json_real(c[e]));
        ori_v3 b = ori_simulation_frame_field(s, f);
        json_t *fields[3] = {cur, pl, json_pack("[fff]", b.x, b.y, b.z)};
        const char *keys[3] = {"orikin:edges_current", "orikin:edges_plasticRotation", "orikin:field"};
        for (int k = 0; k < 3; ++k) {
            char *text = json_dumps(fields[k], JSON_COMPACT | JSON_REAL_PRECISION(17));
            ori_fold_set_custom(in->k.doc, fr, keys[k], text, NULL);
            free(text);
            json_decref(fields[k]);
        }
    }
    free(pos);
    ori_error err;
    if (ori_fold_save_file(in->k.doc, o->out, &err) != ORI_OK) return cli_input_error("simulate", o->out, &err);
    return CLI_EXIT_OK;
}

static void print_json(const act_input *in, const ori_simulation *s, const ori_field_change *sched, int ns, const char *how)
{
    int E = ori_mechanism_edge_count(in->k.mech);
    ori_simulation_summary su = ori_simulation_summary_of(s);
    json_t *o = json_object();
    json_object_set_new(o, "file", json_string(in->path));
    json_object_set_new(o, "time_to_target", su.reached_target ? json_real(su.time_to_target_s) : json_null());
    json_object_set_new(o, "latched_angle_deg", deg_array(ori_simulation_latched_angles(s), E));
    json_object_set_new(o, "peak_angular_velocity", json_real(su.peak_angular_velocity));
    json_object_set_new(o, "energy_drift", json_real(su.energy_drift));
    json_object_set_new(o, "max_residual", json_real(su.max_residual));
    json_object_set_new(o, "dt", json_real(su.dt_s));
    json_object_set_new(o, "steps", json_integer(su.steps));
    json_object_set_new(o, "explicit_steps", json_integer(su.explicit_steps));
    json_object_set_new(o, "energy_in", json_real(su.energy_in_j));
    json_object_set_new(o, "dissipated", json_real(su.dissipated_j));
    json_object_set_new(o, "schedule", json_string(how));
    if (ns) json_object_set_new(o, "field_schedule", act_schedule_json(sched, ns));
    json_t *fr = json_array();
    for (int f = 0; f < ori_simulation_frame_count(s); ++f) {
        double ke, te;
        ori_simulation_frame_energy(s, f, &ke, &te);
        json_t *cur = json_array();
        const double *c = ori_simulation_frame_currents(s, f);
        for (int e = 0; e < E; ++e) json_array_append_new(cur, json_real(c[e]));
        ori_v3 b = ori_simulation_frame_field(s, f);
        json_array_append_new(
            fr, json_pack("{s:f,s:o,s:o,s:o,s:[fff],s:f,s:f,s:f}", "t", ori_simulation_frame_time(s, f), "angles_deg",
                          deg_array(ori_simulation_frame_angles(s, f), E), "currents", cur, "plastic_rotation_deg",
                          deg_array(ori_simulation_frame_plastic(s, f), E), "field", b.x, b.y, b.z, "kinetic_energy", ke,
                          "energy", te, "residual", ori_simulation_frame_residual(s, f)));
    }
    json_object_set_new(o, "frames", fr);
    cli_print_json(o);
}

static void print_text(const act_input *in, const ori_simulation *s, const ori_field_change *sched, int ns, const char *how)
{
    const ori_mechanism *m = in->k.mech;
    int E = ori_mechanism_edge_count(m);
    ori_simulation_summary su = ori_simulation_summary_of(s);
    int cols[8], nc = 0;
    for (int e = 0; e < E && nc < 8; ++e) {
        ori_hinge h;
        if (ori_design_hinge(in->design, e, &h) && h.has_wire && ori_mechanism_edge_joint(m, e) != ORI_NULL_INDEX) cols[nc++] = e;
    }
    printf("%s: %d steps of %.4g s (%d taken explicitly), field schedule %s\n", in->path, su.steps, su.dt_s,
           su.explicit_steps, how);
    for (int i = 0; i < ns; ++i)
        printf("  from crease %d at %8.3f deg: B = (%.6g, %.6g, %.6g) T\n", sched[i].edge, ori_rad_to_deg_output(sched[i].from_rad),
               sched[i].field_t.x, sched[i].field_t.y, sched[i].field_t.z);
    printf("\n%12s", "t (ms)");
    for (int i = 0; i < nc; ++i) printf("  crease %-3d I(mA) plastic", cols[i]);
    printf("  %12s  residual\n", "energy (J)");
    int F = ori_simulation_frame_count(s), every = F > 41 ? (F - 1 + 39) / 40 : 1;
    for (int f = 0; f < F; ++f) {
        if (f % every && f != F - 1) continue;
        const double *a = ori_simulation_frame_angles(s, f), *c = ori_simulation_frame_currents(s, f),
                     *p = ori_simulation_frame_plastic(s, f);
        double te;
        ori_simulation_frame_energy(s, f, NULL, &te);
        printf("%12.5f", 1e3 * ori_simulation_frame_time(s, f));
        for (int i = 0; i < nc; ++i)
            printf("  %10.3f %6.2f %7.2f", ori_rad_to_deg_output(a[cols[i]]), 1e3 * c[cols[i]], ori_rad_to_deg_output(p[cols[i]]));
        printf("  %12.5e  %.1e\n", te, ori_simulation_frame_residual(s, f));
    }
    if (F > 41) printf("(every %d-th of %d frames: see --json or -o)\n", every, F);
    printf("\n");
    if (su.reached_target) printf("the wired creases reach their targets after %.4g ms\n", 1e3 * su.time_to_target_s);
    else printf("the wired creases do not all reach their targets\n");
    printf("latched angles (currents off, at rest):");
    for (int i = 0; i < nc; ++i) printf(" crease %d %.3f deg", cols[i], ori_rad_to_deg_output(ori_simulation_latched_angles(s)[cols[i]]));
    printf("\npeak angular velocity %.4g rad/s, energy drift %.2e, largest loop-closure residual %.1e\n",
           su.peak_angular_velocity, su.energy_drift, su.max_residual);
}

static int run(int argc, char **argv)
{
    act_opts o;
    char **rest = malloc(sizeof(char *) * (size_t)(argc + 1));
    int nrest = 0;
    int rc = act_parse("simulate", argc, argv, true, &o, &nrest, rest);
    const char *path = NULL;
    for (int i = 1; i < nrest && rc == CLI_EXIT_OK; ++i) {
        if (rest[i][0] == '-' && rest[i][1] != '\0') rc = cli_usage("simulate", "unknown option %s", rest[i]);
        else if (path) rc = cli_usage("simulate", "one FILE or SEQ.json only");
        else path = rest[i];
    }
    free(rest);
    if (rc != CLI_EXIT_OK) return rc;
    if (!path) return cli_usage("simulate", "missing FILE or SEQ.json");
    if (o.compliant) return act_simulate_compliant(path, &o);
    if (!o.has_duration) return cli_usage("simulate", "missing --duration S");
    if (o.has_dt && !(ceil(o.duration / (o.frames - 1) / o.dt) * (o.frames - 1) <= ORI_DYN_MAX_STEPS)) // the library's own bound, before any work
        return cli_usage("simulate", "--dt %g over --duration %g is more than the %.3g time steps a simulation takes: --dt at least %.3g", o.dt, o.duration, (double)ORI_DYN_MAX_STEPS, o.duration / ORI_DYN_MAX_STEPS);
    act_input in;
    if ((rc = act_load("simulate", path, &o, &in)) != CLI_EXIT_OK) return rc;
    const ori_mechanism *m = in.k.mech;
    int E = ori_mechanism_edge_count(m), F = ori_mechanism_face_count(m);
    ori_record *rec = NULL;
    ori_simulation *s = NULL;
    double *targets = NULL;
    int fixed = 0;
    if (o.has_fix) rc = cli_spec_face("simulate", in.pattern_path, in.k.flat, "--fix", o.fix_spec, &fixed);
    if (rc == CLI_EXIT_OK && in.is_sequence) {
        rc = act_run_sequence("simulate", &in, &rec);
        if (!o.has_fix) fixed = ori_sequence_fold_at(in.seq, 0).fixed_face;
    } else if (rc == CLI_EXIT_OK && !o.has_fix) {
        rc = cli_usage("simulate", "missing --fix FACE");
    }
    if (rc == CLI_EXIT_OK && (fixed < 0 || fixed >= F))
        rc = cli_input_fail("simulate", in.pattern_path, "faces_vertices %d: no face %d (the pattern has faces 0 to %d)", fixed,
                            fixed, F - 1);
    bool own_currents = true;
    for (int e = 0; e < E; ++e) {
        ori_hinge h;
        if (ori_design_hinge(in.design, e, &h) && h.has_wire && !h.wire.has_current) own_currents = false;
    }
    if (rc == CLI_EXIT_OK && !o.has_current && !own_currents) rc = cli_usage("simulate", "missing --current A");
    // Targets: the sequence's end state, the file's edges_foldAngle, or ±180 by assignment.
    int *stages = NULL, nstage = 0, *lock_counts = NULL, *locks = NULL;
    if (rc == CLI_EXIT_OK && (rec || ori_pattern_has_fold_angles(in.k.flat))) {
        targets = malloc(sizeof(double) * (size_t)(E + 1));
        for (int e = 0; e < E; ++e)
            targets[e] = rec ? ori_record_frame_angles(rec, ori_record_frame_count(rec) - 1)[e]
                             : ori_pattern_edge(in.k.flat, e).fold_angle_rad;
    }
    if (rc == CLI_EXIT_OK && rec) {
        // The folds one after the other: each fold's wire drives its crease to where the fold
        // leaves it, then the next fold's wire takes over.
        nstage = ori_sequence_fold_count(in.seq);
        stages = malloc(sizeof(int) * (size_t)nstage);
        lock_counts = malloc(sizeof(int) * (size_t)nstage);
        locks = malloc(sizeof(int) * (size_t)(nstage * ORI_SEQUENCE_MAX_LOCKS + 1));
        int nl = 0;
        for (int k = 0; k < nstage; ++k) {
            ori_sequence_fold sf = ori_sequence_fold_at(in.seq, k);
            stages[k] = sf.driven_edge;
            lock_counts[k] = sf.locked_count;
            for (int i = 0; i < sf.locked_count; ++i) locks[nl++] = sf.locked[i];
        }
        for (int f = 0; f < ori_record_frame_count(rec); ++f) {
            int e = stages[ori_record_frame_fold(rec, f)];
            targets[e] = ori_record_frame_angles(rec, f)[e];
        }
    }
    ori_field_change sched[ORI_SCHEDULE_MAX];
    int ns = 0;
    const char *how = "";
    double *by_assignment = NULL;
    if (rc == CLI_EXIT_OK && !targets) {
        by_assignment = malloc(sizeof(double) * (size_t)(E + 1));
        for (int e = 0; e < E; ++e) {
            ori_assignment a = ori_pattern_edge(in.k.flat, e).assignment;
            by_assignment[e] = a == ORI_ASSIGN_VALLEY ? ORI_PI : a == ORI_ASSIGN_MOUNTAIN ? -ORI_PI : 0.0;
        }
    }
    if (rc == CLI_EXIT_OK) rc = choose_schedule(&in, &o, fixed, targets ? targets : by_assignment, rec, sched, &ns, &how);
    if (rc == CLI_EXIT_OK) {
        ori_simulation_def d = ori_default_simulation_def();
        d.design = in.design;
        d.mechanism = m;
        d.fixed_face = fixed;
        rc = cli_kin_fixed_pose("simulate", in.pattern_path, &in.k, fixed, &d.fixed_pose);
        d.start_angles_rad = in.k.angles;
        d.target_angles_rad = targets;
        d.current_a = o.has_current ? o.current : 0.0;
        d.schedule = sched;
        d.schedule_count = ns;
        d.stage_edges = stages;
        d.stage_count = nstage;
        d.stage_lock_counts = lock_counts;
        d.stage_lock_edges = locks;
        if (ns == 0 && strncmp(how, "fixed", 5) == 0) {
            ori_actuation a = ori_design_actuation(in.design);
            if (a.has_field) {
                sched[0].edge = ORI_NULL_INDEX;
                sched[0].from_rad = 0.0;
                sched[0].field_t = a.field_t;
                d.schedule_count = 1;
            }
        }
        d.duration_s = o.duration;
        d.has_dt = o.has_dt;
        d.dt_s = o.dt;
        d.has_pulse = o.has_pulse;
        d.pulse_s = o.pulse;
        d.stops = !o.no_stops;
        d.output_frames = o.frames;
        cli_progress bar;
        cli_progress_begin(&bar, "simulate", "integrating");
        d.progress = cli_progress_fn;
        d.progress_user = &bar;
        ori_error err;
        if (rc == CLI_EXIT_OK && ori_simulation_run(&d, &s, &err) != ORI_OK) {
            rc = cli_input_error("simulate", in.is_sequence ? in.path : in.pattern_path, &err);
            if (err.status == ORI_ERR_NOT_CONVERGED) rc = CLI_EXIT_INTERNAL;
        }
        cli_progress_end(&bar);
        if (!ns) {
            ns = d.schedule_count;
            if (!ns) {
                ori_actuation a = ori_design_actuation(in.design);
                ns = a.schedule_count;
                memcpy(sched, a.schedule, sizeof(ori_field_change) * (size_t)ns);
            }
        }
    }
    if (rc == CLI_EXIT_OK && o.out) rc = write_frames(&in, &o, s);
    if (rc == CLI_EXIT_OK) {
        if (o.json) print_json(&in, s, sched, ns, how);
        else print_text(&in, s, sched, ns, how);
    }
    free(targets);
    free(stages);
    free(lock_counts);
    free(locks);
    free(by_assignment);
    ori_simulation_destroy(s);
    ori_record_destroy(rec);
    act_free(&in);
    return cli_finish(rc);
}

const cli_command cli_cmd_simulate = {
    "simulate",
    "folding dynamics: Lorentz-driven elastoplastic hinges, closed loops, latched angles",
    "usage: orikin simulate FILE --fix FACE --current A --duration S [options]\n"
    "       orikin simulate SEQ.json --current A --duration S [options]\n"
    "       orikin simulate FILE --model compliant --fix FACE --current A [options]\n"
    "\n"
    "Integrate the motion of the whole sheet in time (closed loops included): panels with mass\n"
    "and inertia from their geometry and density, elastoplastic hinges (elastic up to first\n"
    "yield, plastic flow beyond, springback and latching when the current stops), viscous\n"
    "damping, gravity, and the Lorentz force of the current A in every wire (or each wire's\n"
    "own current from the file) in the magnetic field. The field follows the file's schedule\n"
    "or, without one, the schedule the sizing finds best along the quasi-static motion. Each\n"
    "wire's current stops when its crease reaches its target (edges_foldAngle, the sequence's\n"
    "end state, or +-180 by assignment); creases stop (perfectly inelastically) at +-180. A\n"
    "SEQ.json runs its folds one after the other: each fold's wire drives its crease while the\n"
    "creases the fold locks are held. The implicit midpoint rule keeps the loops closed at every\n"
    "step (residual below 1e-10) and the energy of an undamped elastic sheet constant. Reports\n"
    "the time to the target, the latched angles after the sheet comes to rest, the peak angular\n"
    "velocity, the energy drift and the largest loop-closure residual. Exit 0 done, 2 usage, 3\n"
    "bad input, 4 the integration failed.\n"

    "\n"
    "options:\n"
    "  --fix FACE          face held in place: FOLD index, name (Obj12) or @x,y (FILE; a sequence\n"
    "                      holds its first fold's)\n"
    "  --current A         current in every wire without its own, in amperes\n"
    "  --duration S        simulated time in seconds\n"
    "  --dt S              time step (default: 1/64 of the shortest natural period)\n"
    "  --damping RATIO     viscous damping of every hinge, fraction of critical (overrides the file)\n"
    "  --field BX,BY,BZ    magnetic field in teslas (overrides the file's field and schedule)\n"
    "  --reorientations N  optimise the field schedule with at most N changes (default: one per fold)\n"
    "  --fixed-field       never reorient the field\n"
    "  --pulse S           switch every current off at time S\n"
    "  --no-stops          let creases pass +-180 degrees\n"
    "  --gravity, --no-gravity  gravity on or off (overrides the file)\n"
    "  --frames N          output frames, evenly spaced in time (default 101)\n"
    "  --frame N           start from the fold angles of frame N (FILE)\n"
    "  --materials FILE    materials JSON extending the built-in table\n"
    "  --unit U            length unit of the coordinates: m, cm, mm, um, nm, in, pt\n"
    "  --model M           rigid (default: rigid panels, dynamics in time) or compliant\n"
    "  --json              print {file, time_to_target (s or null), latched_angle_deg: [per edge],\n"
    "                      peak_angular_velocity, energy_drift, max_residual, dt, steps,\n"
    "                      explicit_steps, energy_in, dissipated, schedule, field_schedule,\n"
    "                      frames: [{t, angles_deg, currents, plastic_rotation_deg, field,\n"
    "                      kinetic_energy, energy, residual}]}\n"
    "  -o OUT.fold         write FILE with every output frame as a folded-form frame with\n"
    "                      frame_time (s), orikin:edges_current (A), orikin:edges_plasticRotation\n"
    "                      (deg) and orikin:field (T)\n"
    "\n"
    "example: orikin simulate examples/patterns/thesis-flap.fold --fix 0 --current 0.02 --duration 0.01\n"
    "         orikin simulate examples/patterns/thesis-flap.fold --model compliant --fix 0 --current 0.02\n",
    run,
    "\ncompliant panels (--model compliant):\n"
    "The panels bend and stretch: the bar-and-hinge model of fold --compliant with the file's\n"
    "panels, layered hinges and wires (docs/compliant.md). Each wire is a current loop on its\n"
    "panel in the field, its Lorentz forces lumped on the panel's vertices. The equilibria are\n"
    "followed as the current ramps from 0 to A in load steps and then off again. Reports the\n"
    "angles under current, the permanent (plastic) rotations, the largest strain and the\n"
    "latched angles. The field is the file's (or its schedule's first), gravity along -z; the\n"
    "rigid model's time options do not apply. Exit 4 when there is no equilibrium along the\n"
    "ramp (the sheet snaps).\n"
    "  --json              prints {file, model, fixed_face, field, current, vertices,\n"
    "                      bars, hinges, wires, loaded: {angles_deg, plastic_rotation_deg,\n"
    "                      currents, max_strain, energy}, latched_angle_deg, plastic_rotation_deg,\n"
    "                      frames: [{current_fraction, current_on, angles_deg, max_strain}],\n"
    "                      contacts}; -o writes every load step as a folded-form frame with\n"
    "                      orikin:fraction (of the current) and the strains of fold --compliant\n",
};
