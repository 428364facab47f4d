// The compliant fold as the CLI (fold --compliant) and the studio (POST /api/compliant) both run
// it: one request, one definition, one solve and one JSON, so the two answer alike by
// construction.
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "report.h"

void cli_compliant_request_init(cli_compliant_request *r)
{
    memset(r, 0, sizeof *r);
    r->percent = 100.0;
    r->steps = 1000000;
    r->threads = 1;
    r->fix = ORI_NULL_INDEX;
}

bool cli_compliant_request_error(const cli_compliant_request *r, char *buf, size_t size)
{
    struct { const char *name; bool given; double v; bool zero_ok; } k[] = {
        {"--axial", r->has_axial, r->axial, false}, {"--facet", r->has_facet, r->facet, true},
        {"--crease", r->has_crease, r->crease, true}, {"--damping", r->has_damping, r->damping, true},
    };
    if (!(r->percent >= 0.0 && r->percent <= 100.0)) {
        snprintf(buf, size, "--percent needs a number from 0 to 100, got '%g'", r->percent);
        return true;
    }
    for (size_t i = 0; i < sizeof k / sizeof k[0]; ++i)
        if (k[i].given && !(isfinite(k[i].v) && (k[i].v > 0.0 || (k[i].zero_ok && k[i].v == 0.0)))) {
            snprintf(buf, size, "%s needs a number %s, got '%g'", k[i].name, k[i].zero_ok ? ">= 0" : "> 0", k[i].v);
            return true;
        }
    if (!isfinite(r->gravity)) {
        snprintf(buf, size, "--gravity needs a number, got '%g'", r->gravity);
        return true;
    }
    if (r->steps <= 0) {
        snprintf(buf, size, "--steps needs a positive integer, got '%d'", r->steps);
        return true;
    }
    if (r->threads < 1 || r->threads > 64) {
        snprintf(buf, size, "--threads needs an integer from 1 to 64, got '%d'", r->threads);
        return true;
    }
    return false;
}

ori_compliant_def cli_compliant_def(const cli_compliant_request *r)
{
    ori_compliant_def d = r->physical ? ori_compliant_physical_def() : ori_default_compliant_def();
    if (r->has_axial) d.axial_stiffness = r->axial;
    if (r->has_facet) d.facet_stiffness = r->facet;
    if (r->has_crease) {
        d.crease_stiffness = r->crease;
        d.crease_stiffness_per_m = r->crease;
    }
    if (r->has_damping) d.damping = r->damping;
    d.threads = r->threads;
    d.gravity = r->gravity;
    d.fraction = r->percent / 100.0;
    d.keep_frames = r->all_frames;
    d.fixed_face = r->fix;
    return d;
}

ori_status cli_compliant_solve(const ori_pattern *p, const cli_compliant_request *r, ori_compliant **out, bool *reached,
                               int *explicit_steps, ori_error *why, ori_error *error)
{
    *out = NULL;
    *reached = false;
    *explicit_steps = 0;
    memset(why, 0, sizeof *why);
    ori_compliant_def d = cli_compliant_def(r);
    ori_status st = ori_compliant_create(p, &d, out, error);
    if (st != ORI_OK) return st;
    st = r->dynamic ? ori_compliant_run_dynamic(*out, r->steps, 1e-6, explicit_steps, why)
                    : ori_compliant_solve_static(*out, why);
    *reached = st == ORI_OK;
    return ORI_OK;
}

// [fn(c, 0), …, fn(c, n − 1)]: a per-edge or per-face result of the model (degrees: radians shown
// in degrees).
static json_t *result_array(const ori_compliant *c, int n, double (*fn)(const ori_compliant *, int), bool degrees)
{
    json_t *a = json_array();
    for (int i = 0; i < n; ++i) {
        double v = fn(c, i);
        json_array_append_new(a, json_real(degrees ? ori_rad_to_deg_output(v) : v));
    }
    return a;
}

json_t *cli_compliant_contacts_json(const ori_compliant *c, const char *fraction_key)
{
    json_t *cs = json_array();
    for (int k = 0; k < ori_compliant_contact_count(c); ++k) {
        int f0, f1, step;
        double fr;
        ori_compliant_contact(c, k, &f0, &f1, &step, &fr);
        json_array_append_new(cs, json_pack("{s:[ii],s:i,s:f}", "faces", f0, f1, "step", step, fraction_key, fr));
    }
    return cs;
}

json_t *cli_compliant_json(const char *file, const cli_compliant_request *r, const ori_compliant *c, bool reached,
                           int explicit_steps, const char *reason, bool positions)
{
    int V = ori_compliant_vertex_count(c), NF = ori_compliant_face_count(c);
    json_t *o = json_object();
    json_object_set_new(o, "file", json_string(file));
    json_object_set_new(o, "model", json_string("compliant"));
    json_object_set_new(o, "solver", json_string(r->dynamic ? "explicit" : "static"));
    json_object_set_new(o, "preset", json_string(r->physical ? "physical" : "origami-simulator"));
    json_object_set_new(o, "percent", json_real(r->percent));
    json_object_set_new(o, "reached", json_boolean(reached));
    json_object_set_new(o, "reached_fraction", json_real(ori_compliant_fraction(c)));
    json_object_set_new(o, "max_strain", json_real(ori_compliant_max_strain(c)));
    json_object_set_new(o, "energy", json_real(ori_compliant_energy(c)));
    json_object_set_new(o, "crease_error_deg", json_real(ori_compliant_crease_error(c) * 180.0 / ORI_PI));
    json_object_set_new(o, "gradient_norm", json_real(ori_compliant_gradient_norm(c)));
    json_object_set_new(o, "load_scale", json_real(ori_compliant_load_scale(c)));
    json_object_set_new(o, "vertices", json_integer(V));
    json_object_set_new(o, "bars", json_integer(ori_compliant_bar_count(c)));
    json_object_set_new(o, "hinges", json_integer(ori_compliant_hinge_count(c)));
    if (r->dynamic) {
        json_object_set_new(o, "steps", json_integer(explicit_steps));
        json_object_set_new(o, "time_step", json_real(ori_compliant_time_step(c)));
    } else {
        int it, fa, bt, ls;
        ori_compliant_stats(c, &it, &fa, &bt, &ls);
        json_object_set_new(o, "newton_iterations", json_integer(it));
        json_object_set_new(o, "load_steps", json_integer(ls));
    }
    int E = ori_compliant_edge_count(c);
    json_object_set_new(o, "fold_angles_deg", result_array(c, E, ori_compliant_fold_angle, true));
    json_object_set_new(o, "strains", result_array(c, E, ori_compliant_edge_strain, false));
    json_object_set_new(o, "face_energies", result_array(c, NF, ori_compliant_face_energy, false));
    json_object_set_new(o, "face_strains", result_array(c, NF, ori_compliant_face_strain, false));
    json_object_set_new(o, "contacts", cli_compliant_contacts_json(c, "fraction"));
    json_object_set_new(o, "contacts_truncated", json_boolean(ori_compliant_contacts_truncated(c)));
    if (!reached) json_object_set_new(o, "reason", json_string(reason ? reason : ""));
    if (positions) {
        const ori_v3 *x = ori_compliant_positions(c);
        json_t *pos = json_array();
        for (int v = 0; v < V; ++v) json_array_append_new(pos, json_pack("[fff]", x[v].x, x[v].y, x[v].z));
        json_object_set_new(o, "positions", pos);
    }
    return o;
}
