// orikin simulate --model compliant: the device on compliant panels. The bar-and-hinge model
// with the design's panels (material, thickness), layered elastoplastic hinges and wires (current
// loops in the field, include/orikin/compliant.h) follows its equilibria as the wires' current
// ramps from 0 to --current, then off again: the folded angles under current, how far the
// panels strain, and the angles the hinges keep once the current stops.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "actuation_args.h"
#include "fold_compliant.h"
#include "report.h"

static json_t *deg_list(const double *a, int n)
{
    json_t *j = json_array();
    for (int i = 0; i < n; ++i) json_array_append_new(j, json_real(ori_rad_to_deg_output(a[i])));
    return j;
}

static double frame_max_strain(const ori_compliant *c, int k)
{
    const double *s = ori_compliant_frame_face_strains(c, k);
    double m = 0.0;
    for (int f = 0; f < ori_compliant_face_count(c); ++f) m = fmax(m, s[f]);
    return m;
}

int act_simulate_compliant(const char *path, const act_opts *o)
{
    const char *cmd = "simulate";
    if (act_is_sequence(path)) return cli_usage(cmd, "--model compliant takes a FILE, not a fold sequence");
    if (o->has_duration || o->has_dt || o->has_pulse || o->no_stops || o->has_damping || o->reorientations >= 0 ||
        o->fixed_field || o->frame)
        return cli_usage(cmd, "--model compliant follows the equilibria as the current ramps up and off: --duration, --dt, "
                              "--pulse, --no-stops, --damping, --reorientations, --fixed-field and --frame are the rigid "
                              "model's");
    if (!o->has_fix) return cli_usage(cmd, "missing --fix FACE");
    act_input in;
    int rc = act_load(cmd, path, o, &in);
    if (rc != CLI_EXIT_OK) return rc;
    const ori_pattern *p = in.k.flat;
    int E = ori_pattern_edge_count(p);
    int fixed = 0;
    rc = cli_spec_face(cmd, in.pattern_path, p, "--fix", o->fix_spec, &fixed);
    bool own_currents = true;
    int wired[8], nw = 0, wires = 0;
    for (int e = 0; e < E; ++e) {
        ori_hinge h;
        if (!ori_design_hinge(in.design, e, &h) || !h.has_wire) continue;
        wires++;
        if (!h.wire.has_current) own_currents = false;
        if (nw < 8) wired[nw++] = e;
    }
    ori_actuation act = ori_design_actuation(in.design);
    ori_v3 field = act.schedule_count > 0 ? act.schedule[0].field_t : act.field_t;
    if (rc == CLI_EXIT_OK && wires == 0)
        rc = cli_input_fail(cmd, in.pattern_path, "edges_orikin:hinge: no hinge has a wire: nothing drives the sheet");
    if (rc == CLI_EXIT_OK && !o->has_current && !own_currents) rc = cli_usage(cmd, "missing --current A");
    if (rc == CLI_EXIT_OK && !act.has_field && act.schedule_count == 0)
        rc = cli_input_fail(cmd, in.pattern_path, "orikin:actuation: no magnetic field (give --field BX,BY,BZ)");
    if (rc == CLI_EXIT_OK && (act.gravity_m_s2.x != 0.0 || act.gravity_m_s2.y != 0.0))
        rc = cli_input_fail(cmd, in.pattern_path, "orikin:actuation: the compliant model takes gravity along -z only");
    if (rc != CLI_EXIT_OK) {
        act_free(&in);
        return rc;
    }
    if (!(hypot(field.x, field.y) > 1e-9 * ori_v3_norm(field)) && !o->json)
        fprintf(stderr,
                "orikin simulate: %s: warning: the field is along the sheet's normal: the flat wires feel no moment "
                "(the rigid model reorients it by a schedule; give --field across the creases)\n",
                in.pattern_path);
    double *zeros = calloc((size_t)E + 1, sizeof(double));
    ori_compliant_def d = ori_compliant_physical_def();
    d.design = in.design;
    d.fixed_face = fixed;
    d.field_t = field;
    d.current_a = o->has_current ? o->current : 0.0;
    d.gravity = -act.gravity_m_s2.z;
    d.target_angles_rad = zeros; // the hinges are made flat: the wires fold them
    d.keep_frames = true;
    ori_compliant *c = NULL;
    ori_error err;
    if (ori_compliant_create(p, &d, &c, &err) != ORI_OK) rc = cli_input_error(cmd, in.pattern_path, &err);
    double *loaded = malloc(sizeof(double) * ((size_t)E + 1)), *loaded_pl = malloc(sizeof(double) * ((size_t)E + 1));
    double *latched = malloc(sizeof(double) * ((size_t)E + 1)), *latched_pl = malloc(sizeof(double) * ((size_t)E + 1));
    double *currents = malloc(sizeof(double) * ((size_t)E + 1));
    double loaded_strain = 0.0, loaded_energy = 0.0;
    int load_frames = 0;
    const char *stage = "the current's ramp";
    if (rc == CLI_EXIT_OK && ori_compliant_solve_static(c, &err) == ORI_OK) {
        for (int e = 0; e < E; ++e) {
            loaded[e] = ori_compliant_fold_angle(c, e);
            loaded_pl[e] = ori_compliant_plastic_rotation(c, e);
            currents[e] = ori_compliant_wire_current(c, e);
        }
        loaded_strain = ori_compliant_max_strain(c);
        loaded_energy = ori_compliant_energy(c);
        load_frames = ori_compliant_frame_count(c);
        stage = "switching the current off";
        if (ori_compliant_set_fraction(c, 0.0, &err) != ORI_OK || ori_compliant_solve_static(c, &err) != ORI_OK) rc = -1;
        for (int e = 0; e < E && rc == CLI_EXIT_OK; ++e) {
            latched[e] = ori_compliant_fold_angle(c, e);
            latched_pl[e] = ori_compliant_plastic_rotation(c, e);
        }
    } else if (rc == CLI_EXIT_OK) {
        rc = -1;
    }
    if (rc == -1) {
        // no equilibrium: the sheet snaps (a limit point), or the model cannot hold it
        fprintf(stderr, "orikin simulate: %s: %s: %s\n", in.pattern_path, stage, err.message);
        rc = CLI_EXIT_INTERNAL;
    }
    for (int k = 0; rc == CLI_EXIT_OK && k < ori_compliant_contact_count(c) && !o->json; ++k) {
        int f0, f1, step;
        double fr;
        ori_compliant_contact(c, k, &f0, &f1, &step, &fr);
        fprintf(stderr, "orikin simulate: %s: warning: faces %d and %d pass through each other at load step %d (%.6g %% current)\n",
                in.pattern_path, f0, f1, step, 100.0 * fr);
    }
    if (rc == CLI_EXIT_OK && o->out)
        rc = cli_compliant_write_frames(cmd, o->out, in.k.doc, c, E, true, "compliant simulate: %.6g %% of the current");
    if (rc == CLI_EXIT_OK && o->json) {
        json_t *j = json_object();
        json_object_set_new(j, "file", json_string(in.path));
        json_object_set_new(j, "model", json_string("compliant"));
        json_object_set_new(j, "fixed_face", json_integer(fixed));
        json_object_set_new(j, "field", json_pack("[fff]", field.x, field.y, field.z));
        json_object_set_new(j, "current", json_real(d.current_a));
        json_object_set_new(j, "vertices", json_integer(ori_compliant_vertex_count(c)));
        json_object_set_new(j, "bars", json_integer(ori_compliant_bar_count(c)));
        json_object_set_new(j, "hinges", json_integer(ori_compliant_hinge_count(c)));
        json_object_set_new(j, "wires", json_integer(ori_compliant_wire_count(c)));
        json_t *cur = json_array();
        for (int e = 0; e < E; ++e) json_array_append_new(cur, json_real(currents[e]));
        json_object_set_new(j, "loaded", json_pack("{s:o,s:o,s:o,s:f,s:f}", "angles_deg", deg_list(loaded, E),
                                                   "plastic_rotation_deg", deg_list(loaded_pl, E), "currents", cur,
                                                   "max_strain", loaded_strain, "energy", loaded_energy));
        json_object_set_new(j, "latched_angle_deg", deg_list(latched, E));
        json_object_set_new(j, "plastic_rotation_deg", deg_list(latched_pl, E));
        json_t *fr = json_array();
        for (int k = 0; k < ori_compliant_frame_count(c); ++k)
            json_array_append_new(fr, json_pack("{s:f,s:b,s:o,s:f}", "current_fraction", ori_compliant_frame_fraction(c, k),
                                                "current_on", k < load_frames, "angles_deg",
                                                deg_list(ori_compliant_frame_angles(c, k), E), "max_strain",
                                                frame_max_strain(c, k)));
        json_object_set_new(j, "frames", fr);
        json_object_set_new(j, "contacts", cli_compliant_contacts_json(c, "current_fraction"));
        cli_print_json(j);
    } else if (rc == CLI_EXIT_OK) {
        printf("%s: compliant model (%d vertices, %d bars, %d hinges, %d wire%s), face %d held, B = (%.6g, %.6g, %.6g) T\n",
               in.path, ori_compliant_vertex_count(c), ori_compliant_bar_count(c), ori_compliant_hinge_count(c),
               ori_compliant_wire_count(c), ori_compliant_wire_count(c) == 1 ? "" : "s", fixed, field.x, field.y, field.z);
        printf("quasi-static: the current ramps up in load steps, then off\n\n%12s", "current (%)");
        for (int i = 0; i < nw; ++i) printf("  crease %-3d", wired[i]);
        printf("  max strain\n");
        int F = ori_compliant_frame_count(c), every = F > 41 ? (F - 1 + 39) / 40 : 1;
        for (int k = 0; k < F; ++k) {
            if (k % every && k != F - 1 && k != load_frames - 1) continue;
            const double *a = ori_compliant_frame_angles(c, k);
            printf("%10.3f %s", 100.0 * ori_compliant_frame_fraction(c, k), k < load_frames ? "^" : "v");
            for (int i = 0; i < nw; ++i) printf("  %10.3f", ori_rad_to_deg_output(a[wired[i]]));
            printf("  %.3e\n", frame_max_strain(c, k));
        }
        if (F > 41) printf("(every %d-th of %d frames: see --json or -o)\n", every, F);
        printf("\nunder current:");
        for (int i = 0; i < nw; ++i)
            printf(" crease %d %.3f deg at %.6g mA (plastic %.3f deg)", wired[i], ori_rad_to_deg_output(loaded[wired[i]]),
                   1e3 * currents[wired[i]], ori_rad_to_deg_output(loaded_pl[wired[i]]));
        printf("\nlargest strain under current %.3e\nlatched (current off):", loaded_strain);
        for (int i = 0; i < nw; ++i) printf(" crease %d %.3f deg", wired[i], ori_rad_to_deg_output(latched[wired[i]]));
        printf("\n");
    }
    free(zeros);
    free(loaded);
    free(loaded_pl);
    free(latched);
    free(latched_pl);
    free(currents);
    ori_compliant_destroy(c);
    act_free(&in);
    return cli_finish(rc);
}
