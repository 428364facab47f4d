// orikin actuate: size the hinges and the Lorentz actuation of a fold or a fold sequence.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "actuation_args.h"

static json_t *num(double x) { return isfinite(x) ? json_real(x) : json_null(); }

static const char *gravity_word(double ratio)
{
    return ratio >= 1.0 ? "decisive" : ratio >= ORI_ACT_GRAVITY_MINOR ? "significant" : "negligible";
}

static void print_json(const act_input *in, const ori_sizing *z)
{
    ori_actuation a = ori_design_actuation(in->design);
    ori_sizing_summary su = ori_sizing_summary_of(z);
    json_t *o = json_object();
    json_object_set_new(o, "file", json_string(in->path));
    json_object_set_new(o, "feasible", json_boolean(su.feasible));
    json_object_set_new(o, "current_limit", a.has_current_limit ? json_real(a.current_limit_a) : json_null());
    json_object_set_new(o, "current_needed", num(su.current_needed_a));
    json_object_set_new(o, "worst_edge", su.worst_edge >= 0 ? json_integer(su.worst_edge) : json_null());
    json_object_set_new(o, "mechanism_current_needed", num(su.mechanism_current_a));
    json_object_set_new(o, "gravity_ratio_max", json_real(su.gravity_ratio_max));
    json_object_set_new(o, "gravity", json_string(gravity_word(su.gravity_ratio_max)));
    json_object_set_new(o, "schedule", json_string(su.optimized ? "optimized" : "design"));
    json_object_set_new(o, "reorientations", json_integer(su.reorientations));
    int ns = ori_sizing_schedule_count(z);
    ori_field_change sch[ORI_SCHEDULE_MAX];
    for (int i = 0; i < ns; ++i) sch[i] = ori_sizing_schedule_at(z, i);
    json_object_set_new(o, "field_schedule", act_schedule_json(sch, ns));
    json_t *hs = json_array(), *steps = json_array();
    int S = ori_sizing_frame_count(z);
    for (int i = 0; i < ori_sizing_hinge_count(z); ++i) {
        ori_hinge_sizing h = ori_sizing_hinge(z, i);
        ori_hinge hd;
        ori_design_hinge(in->design, h.edge, &hd);
        json_t *j = json_object();
        json_object_set_new(j, "edge", json_integer(h.edge));
        json_object_set_new(j, "material", json_string(hd.material));
        json_object_set_new(j, "width", json_real(hd.width_m));
        json_object_set_new(j, "thickness", json_real(hd.thickness_m));
        json_object_set_new(j, "M_y", json_real(h.mechanics.yield_moment_nm));
        json_object_set_new(j, "M_p", json_real(h.mechanics.plastic_moment_nm));
        json_object_set_new(j, "stiffness", json_real(h.mechanics.stiffness_nm_rad));
        json_object_set_new(j, "yield_rotation_deg", json_real(ori_rad_to_deg_output(h.mechanics.yield_rotation_rad)));
        json_object_set_new(j, "travel_deg", json_real(ori_rad_to_deg_output(h.travel_rad)));
        json_object_set_new(j, "springback_deg", json_real(ori_rad_to_deg_output(h.springback_rad)));
        json_object_set_new(j, "plastic_rotation_deg", json_real(ori_rad_to_deg_output(h.plastic_rotation_rad)));
        json_object_set_new(j, "gravity_moment_max", json_real(h.gravity_moment_max_nm));
        json_object_set_new(j, "gravity_ratio", json_real(h.gravity_ratio));
        json_object_set_new(j, "actuated", json_boolean(h.actuated));
        json_object_set_new(j, "current_needed", h.actuated ? num(h.current_needed_a) : json_null());
        json_object_set_new(j, "power_peak", h.actuated ? num(h.power_peak_w) : json_null());
        json_object_set_new(j, "current_density_peak", h.actuated ? num(h.current_density_peak_a_m2) : json_null());
        json_object_set_new(j, "resistance", h.actuated ? json_real(h.mechanics.resistance_ohm) : json_null());
        json_object_set_new(j, "feasible", json_boolean(h.feasible));
        json_object_set_new(j, "optimal_thickness", h.has_optimal_thickness ? json_real(h.optimal_thickness_m) : json_null());
        json_object_set_new(j, "width_range",
                            h.has_width_range ? json_pack("[ff]", h.width_min_m, h.width_max_m) : json_null());
        json_array_append_new(hs, j);
        if (!h.actuated) continue;
        json_t *fr = json_array();
        for (int f = 0; f < S; ++f) {
            ori_sizing_step s = ori_sizing_step_at(z, i, f);
            int de;
            double dr = ori_sizing_frame_drive(z, f, &de);
            ori_v3 b = ori_sizing_frame_field(z, f);
            json_t *x = json_object();
            json_object_set_new(x, "drive_deg", json_real(ori_rad_to_deg_output(dr)));
            json_object_set_new(x, "angle_deg", json_real(ori_rad_to_deg_output(s.angle_rad)));
            json_object_set_new(x, "field", json_pack("[fff]", b.x, b.y, b.z));
            json_object_set_new(x, "lorentz_moment_per_amp", json_real(s.lorentz_moment_per_amp));
            json_object_set_new(x, "gravity_moment", json_real(s.gravity_moment_nm));
            json_object_set_new(x, "required_moment", json_real(s.required_moment_nm));
            json_object_set_new(x, "current", num(s.current_a));
            json_object_set_new(x, "power", num(s.power_w));
            json_object_set_new(x, "current_density", num(s.current_density_a_m2));
            json_array_append_new(fr, x);
        }
        json_array_append_new(steps, json_pack("{s:i,s:o}", "edge", h.edge, "frames", fr));
    }
    json_object_set_new(o, "hinges", hs);
    json_object_set_new(o, "steps", steps);
    cli_print_json(o);
}

static void print_text(const act_input *in, const ori_sizing *z)
{
    ori_actuation a = ori_design_actuation(in->design);
    ori_sizing_summary su = ori_sizing_summary_of(z);
    char lim[32] = "none";
    if (a.has_current_limit) snprintf(lim, sizeof lim, "%.4g mA", 1e3 * a.current_limit_a);
    printf("field |B| = %g T, current limit %s, gravity %s\n", ori_v3_norm(ori_sizing_frame_field(z, 0)), lim,
           ori_v3_norm(a.gravity_m_s2) > 0 ? "on" : "off");
    printf("field schedule (%s, %d reorientation%s):\n", su.optimized ? "optimised" : "from the design", su.reorientations,
           su.reorientations == 1 ? "" : "s");
    for (int i = 0; i < ori_sizing_schedule_count(z); ++i) {
        ori_field_change c = ori_sizing_schedule_at(z, i);
        printf("  from crease %d at %8.3f deg: B = (%.6g, %.6g, %.6g) T\n", c.edge, ori_rad_to_deg_output(c.from_rad),
               c.field_t.x, c.field_t.y, c.field_t.z);
    }
    printf("\n%5s %-9s %8s %7s %11s %11s %11s %10s %10s %10s %10s %10s %5s %9s %16s\n", "edge", "material", "w(um)", "t(um)",
           "M_y(N*m)", "M_p(N*m)", "k(N*m/rad)", "springback", "I(mA)", "P(mW)", "J(A/m2)", "gravity", "ok", "t_opt(um)",
           "width range(um)");
    for (int i = 0; i < ori_sizing_hinge_count(z); ++i) {
        ori_hinge_sizing h = ori_sizing_hinge(z, i);
        ori_hinge hd;
        ori_design_hinge(in->design, h.edge, &hd);
        char cur[32] = "-", pow_[32] = "-", den[32] = "-", topt[32] = "-", range[48] = "-";
        if (h.actuated) {
            snprintf(cur, sizeof cur, "%.4g", 1e3 * h.current_needed_a);
            snprintf(pow_, sizeof pow_, "%.4g", 1e3 * h.power_peak_w);
            snprintf(den, sizeof den, "%.3g", h.current_density_peak_a_m2);
        }
        if (h.has_optimal_thickness) snprintf(topt, sizeof topt, "%.4g", 1e6 * h.optimal_thickness_m);
        if (h.has_width_range) snprintf(range, sizeof range, "%.4g - %.4g", 1e6 * h.width_min_m, 1e6 * h.width_max_m);
        printf("%5d %-9s %8.4g %7.4g %11.4e %11.4e %11.4e %6.2f deg %10s %10s %10s %9.1f%% %5s %9s %16s\n", h.edge,
               hd.material, 1e6 * hd.width_m, 1e6 * hd.thickness_m, h.mechanics.yield_moment_nm, h.mechanics.plastic_moment_nm,
               h.mechanics.stiffness_nm_rad, ori_rad_to_deg_output(h.springback_rad), cur, pow_, den, 100.0 * h.gravity_ratio,
               h.feasible ? "yes" : "NO", topt, range);
    }
    printf("(springback: elastic recovery when the current stops at the end; gravity: largest gravity moment / M_p)\n");
    printf("gravity is %s here (at most %.3g %% of a hinge's plastic moment)\n", gravity_word(su.gravity_ratio_max),
           100.0 * su.gravity_ratio_max);
    if (isfinite(su.mechanism_current_a))
        printf("the mechanism (virtual work, every turning hinge yielding) needs %.4g mA in every wire\n",
               1e3 * su.mechanism_current_a);
    else
        printf("the mechanism (virtual work, every turning hinge yielding) cannot be driven by its wires in this field\n");
    int S = ori_sizing_frame_count(z);
    for (int i = 0; i < ori_sizing_hinge_count(z); ++i) {
        ori_hinge_sizing h = ori_sizing_hinge(z, i);
        if (!h.actuated) continue;
        printf("\nhinge %d along the motion (drive: the driven crease and its angle):\n%6s %10s %10s %14s %13s %13s %10s "
               "%10s %11s\n",
               h.edge, "crease", "drive", "angle", "M/I (N*m/A)", "gravity(N*m)", "needed(N*m)", "I(mA)", "P(mW)", "J(A/m2)");
        for (int f = 0; f < S; ++f) {
            ori_sizing_step s = ori_sizing_step_at(z, i, f);
            int de;
            double dr = ori_sizing_frame_drive(z, f, &de);
            printf("%6d %10.3f %10.3f %14.5e %13.5e %13.5e %10.4g %10.4g %11.4g\n", de, ori_rad_to_deg_output(dr),
                   ori_rad_to_deg_output(s.angle_rad),
                   s.lorentz_moment_per_amp, s.gravity_moment_nm, s.required_moment_nm, 1e3 * s.current_a, 1e3 * s.power_w,
                   s.current_density_a_m2);
        }
    }
    printf("\n");
    if (su.feasible) {
        printf("verdict: feasible: the largest current a wire needs is %.4g mA (crease %d)", 1e3 * su.current_needed_a,
               su.worst_edge);
        if (a.has_current_limit) printf(", within the %.4g mA limit", 1e3 * a.current_limit_a);
        printf("\n");
        return;
    }
    for (int i = 0; i < ori_sizing_hinge_count(z); ++i) {
        ori_hinge_sizing h = ori_sizing_hinge(z, i);
        if (h.feasible) continue;
        if (!isfinite(h.current_needed_a))
            printf("verdict: not feasible: the field cannot fold hinge %d (no moment in the needed direction at %.3f deg)\n",
                   h.edge, ori_rad_to_deg_output(ori_sizing_step_at(z, i, h.worst_frame).angle_rad));
        else if (a.has_current_limit && h.current_needed_a > a.current_limit_a)
            printf("verdict: not feasible: hinge %d needs %.4g mA, above the %.4g mA limit\n", h.edge, 1e3 * h.current_needed_a,
                   1e3 * a.current_limit_a);
        else
            printf("verdict: not feasible: hinge %d needs %.4g mA, above what its film carries (%.4g mA at the material's "
                   "current-density limit)\n",
                   h.edge, 1e3 * h.current_needed_a, 1e3 * h.mechanics.current_max_a);
        return;
    }
    printf("verdict: not feasible: the mechanism needs %.4g mA in every wire to overcome all its yielding hinges%s\n",
           1e3 * su.mechanism_current_a, a.has_current_limit ? ", above the limit" : "");
}

static int run(int argc, char **argv)
{
    act_opts o;
    char **rest = malloc(sizeof(char *) * (size_t)(argc + 1));
    int nrest = 0;
    int rc = act_parse("actuate", argc, argv, false, &o, &nrest, rest);
    if (rc != CLI_EXIT_OK) {
        free(rest);
        return rc;
    }
    // The input decides: a fold sequence takes no fold options.
    const char *path = NULL;
    for (int i = 1; i < nrest && !path; ++i)
        if (rest[i][0] != '-') path = rest[i];
    cli_fold_args fa;
    memset(&fa, 0, sizeof fa);
    bool seq = path && act_is_sequence(path);
    if (seq) {
        for (int i = 1; i < nrest; ++i) {
            if (strcmp(rest[i], "--json") == 0) o.json = true;
            else if (rest[i] == path) continue;
            else if (rest[i][0] == '-') rc = cli_usage("actuate", "%s: a sequence brings its own folds (no fold options)", rest[i]);
            else rc = cli_usage("actuate", "one FILE or SEQ.json only");
            if (rc != CLI_EXIT_OK) break;
        }
    } else {
        rc = cli_fold_parse("actuate", nrest, rest, false, &fa);
        if (rc == CLI_EXIT_OK && fa.out) rc = cli_usage("actuate", "-o: actuate writes nothing (see orikin simulate -o)");
        o.json |= fa.json;
        o.frame = fa.frame;
        path = fa.path;
    }
    free(rest);
    if (rc != CLI_EXIT_OK) return rc;
    act_input in;
    if ((rc = act_load("actuate", path, &o, &in)) != CLI_EXIT_OK) return rc;
    ori_motion *mo = NULL;
    ori_record *rec = NULL;
    ori_sizing *z = NULL;
    if (seq) {
        rc = act_run_sequence("actuate", &in, &rec);
    } else {
        ori_motion_def def;
        rc = cli_fold_resolve("actuate", &fa, &in.k);
        if (rc == CLI_EXIT_OK) rc = cli_fold_def("actuate", &fa, &in.k, &def);
        ori_error err;
        if (rc == CLI_EXIT_OK && ori_motion_solve(in.k.mech, &def, &mo, &err) != ORI_OK) rc = cli_input_error("actuate", path, &err);
        if (rc == CLI_EXIT_OK && ori_motion_verdict_of(mo) != ORI_MOTION_VALID) {
            fprintf(stderr, "orikin actuate: %s: the fold is %s: %s\n", path, ori_motion_verdict_name(ori_motion_verdict_of(mo)),
                    ori_motion_reason(mo) ? ori_motion_reason(mo) : "");
            rc = CLI_EXIT_NEGATIVE;
        }
        if (rc == CLI_EXIT_OK && !o.json)
            printf("%s: fold crease %d to %g deg (step %g deg), face %d fixed%s\n", path, fa.drive, fa.to_deg, fa.step_deg, fa.fix,
                   fa.fix_default ? CLI_FOLD_DEFAULT_FIX_NOTE : "");
    }
    if (rc == CLI_EXIT_OK && seq && !o.json)
        printf("%s: %d folds of %s\n", path, ori_sequence_fold_count(in.seq), in.pattern_path);
    if (rc == CLI_EXIT_OK) rc = act_size("actuate", &in, &o, mo, fa.drive, rec, &z);
    if (rc == CLI_EXIT_OK) {
        if (o.json) print_json(&in, z);
        else print_text(&in, z);
        rc = ori_sizing_summary_of(z).feasible ? CLI_EXIT_OK : CLI_EXIT_NEGATIVE;
    }
    ori_sizing_destroy(z);
    ori_record_destroy(rec);
    ori_motion_destroy(mo);
    act_free(&in);
    return cli_finish(rc);
}

const cli_command cli_cmd_actuate = {
    "actuate",
    "size hinges and Lorentz actuation along a fold or sequence: moments, currents, field schedule",
    "usage: orikin actuate FILE [--fix FACE] --drive EDGE --to DEG [fold options] [options]\n"
    "       orikin actuate SEQ.json [options]\n"
    "\n"
    "Size the elastoplastic hinges and the Lorentz-force actuation of a fold or of a fold\n"
    "sequence (thesis ch. 2.2.2). At every step of the motion the wire of each actuated hinge is\n"
    "posed with its panel, so the applied moment M = N*I*w*L*B*cos(Theta) follows the pose; each\n"
    "hinge that turns must supply its fully plastic moment M_p = w*t^2*sigma_y/4 (the thesis'\n"
    "M_req) plus what gravity takes. Per hinge: first-yield and plastic moments, stiffness,\n"
    "springback, the current the motion needs at most, its power I^2*R and current density, the\n"
    "optimal hinge thickness argmax(M_app - M_req) and the hinge widths the current limit folds;\n"
    "for the mechanism, the common current that folds it by virtual work. The field keeps its\n"
    "magnitude; its orientation follows the file's schedule, or the schedule with at most one\n"
    "reorientation per fold (the thesis reorients it halfway) that keeps the largest current\n"
    "lowest. Design data: edges_orikin:hinge, faces_orikin:panel and orikin:actuation in FILE\n"
    "(docs/actuation.md); lengths in FILE's frame_unit. Exit 0 feasible, 1 when a hinge cannot\n"
    "fold within the limit (named), 3 bad input.\n"
    "\n"
    "options:\n"
    "  --fix, --drive, --to, --from, --step, --lock, --frame, --solver, --linear\n"
    "                        the fold, as for orikin fold (FILE only): faces by index, name\n"
    "                        (Obj12) or @x,y, creases by index or @x,y\n"
    "  --current-limit A     largest current a wire may carry (overrides the file)\n"
    "  --field BX,BY,BZ      magnetic field in teslas (overrides the file's field and schedule)\n"
    "  --reorientations N    optimise the field orientation with at most N changes (default one\n"
    "                        per fold, or the file's schedule when it has one)\n"
    "  --fixed-field         never reorient the field\n"
    "  --gravity, --no-gravity  gravity (9.80665 m/s^2 along -z) on or off (overrides the file)\n"
    "  --materials FILE      materials JSON that extends (or with \"replace\": true replaces) the\n"
    "                        built-in table\n"
    "  --unit U              length unit of the coordinates: m, cm, mm, um, nm, in, pt\n"
    "  --json                print {file, feasible, current_limit, current_needed, worst_edge,\n"
    "                        mechanism_current_needed, gravity, gravity_ratio_max, schedule,\n"
    "                        reorientations, field_schedule: [{from_deg, crease, field}], hinges:\n"
    "                        [{edge, material, width, thickness, M_y, M_p, stiffness,\n"
    "                        yield_rotation_deg, travel_deg, springback_deg, plastic_rotation_deg,\n"
    "                        gravity_moment_max, gravity_ratio, actuated, current_needed,\n"
    "                        power_peak, current_density_peak, resistance, feasible,\n"
    "                        optimal_thickness, width_range}], steps: [{edge, frames: [{drive_deg,\n"
    "                        angle_deg, field, lorentz_moment_per_amp, gravity_moment,\n"
    "                        required_moment, current, power, current_density}]}]} (SI units)\n"
    "\n"
    "example: orikin actuate examples/patterns/thesis-flap.fold --fix 0 --drive 0 --to 180\n",
    run,
    NULL,
};
