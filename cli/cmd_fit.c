// orikin fit: transfer functions of a fold (thesis ch. 5.1): polynomials of the constrained
// crease angles in the driven angle.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "kin_args.h"
#include "output_guard.h"

// -o: the exact samples the fit was made from, as folded-form frames of the pattern (as orikin
// fold writes them), with the transfer functions under "orikin:fit".
static int write_samples(const cli_fold_args *a, const cli_kin *k, const ori_fit_def *fd, const ori_fit *fit)
{
    ori_motion *mo = NULL;
    ori_error err;
    if (ori_motion_solve(k->mech, &fd->motion, &mo, &err) != ORI_OK) return cli_input_error("fit", a->path, &err);
    const ori_mechanism *m = k->mech;
    int V = ori_mechanism_vertex_count(m), E = ori_mechanism_edge_count(m);
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)(V + 1));
    for (int f = 0; f < ori_motion_frame_count(mo); ++f) {
        ori_motion_frame_vertices(mo, f, pos);
        char title[128];
        snprintf(title, sizeof title, "fit sample: crease %d at %g deg", a->drive, ori_rad_to_deg_output(ori_motion_frame_drive(mo, f)));
        ori_fold_append_state(k->doc, 0, V, pos, E, ori_motion_frame_angles(mo, f), title);
    }
    free(pos);
    ori_motion_destroy(mo);
    json_t *o = json_object();
    json_object_set_new(o, "drive", json_integer(a->drive));
    json_object_set_new(o, "degree", json_integer(a->degree));
    json_object_set_new(o, "variable", json_string("driven angle in degrees; coefficients c0 first"));
    json_t *arr = json_array();
    double coef[13];
    for (int i = 0; i < ori_fit_crease_count(fit); ++i) {
        ori_fit_crease c = ori_fit_crease_of(fit, i);
        ori_fit_coefficients(fit, i, coef, 13);
        json_t *cs = json_array();
        for (int q = 0; q <= a->degree; ++q) json_array_append_new(cs, json_real(ori_rad_to_deg(coef[q]) * pow(ORI_PI / 180.0, q)));
        json_array_append_new(arr, json_pack("{s:i,s:o,s:f}", "edge", c.edge, "coefficients", cs, "max_error_deg",
                                             ori_rad_to_deg(c.max_error_rad)));
    }
    json_object_set_new(o, "creases", arr);
    char *text = json_dumps(o, JSON_COMPACT);
    json_decref(o);
    ori_status st = ori_fold_set_custom(k->doc, 0, "orikin:fit", text, &err);
    free(text);
    if (st != ORI_OK || ori_fold_save_file(k->doc, a->out, &err) != ORI_OK) return cli_input_error("fit", a->out, &err);
    return CLI_EXIT_OK;
}

static int run(int argc, char **argv)
{
    bool force;
    int rc = cli_guard_strip("fit", &argc, argv, &force);
    if (rc != CLI_EXIT_OK) return rc;
    cli_fold_args a;
    rc = cli_fold_parse("fit", argc, argv, true, &a);
    if (rc != CLI_EXIT_OK) return rc;
    if (a.degree < 0 || a.degree > 12) return cli_usage("fit", "--degree must be 0 to 12");
    if (a.refine < 1) return cli_usage("fit", "--refine must be at least 1");
    cli_kin k;
    rc = cli_kin_load_input("fit", a.path, a.frame, &a.input, &k);
    if (rc == CLI_EXIT_OK && (rc = cli_fold_resolve("fit", &a, &k)) != CLI_EXIT_OK) cli_kin_free(&k);
    if (rc != CLI_EXIT_OK) return rc;
    ori_fit_def fd = ori_default_fit_def();
    rc = cli_fold_def("fit", &a, &k, &fd.motion);
    if (rc != CLI_EXIT_OK) {
        cli_kin_free(&k);
        return rc;
    }
    fd.degree = a.degree;
    fd.refine = a.refine;
    // The samples and the error grid R times finer: bounded before the run.
    double from0 = fd.motion.has_from ? fd.motion.from_rad : fd.motion.start_angles_rad ? fd.motion.start_angles_rad[a.drive] : 0.0;
    double samples = floor(fabs(fd.motion.to_rad - from0) / fd.motion.step_rad) + 2.0;
    rc = cli_guard_solves("fit", samples * (1.0 + a.refine), "--step or a smaller --refine", force);
    if (rc != CLI_EXIT_OK) {
        cli_kin_free(&k);
        return rc;
    }
    ori_fit *fit = NULL;
    ori_error err;
    ori_status st = ori_fit_solve(k.mech, &fd, &fit, &err);
    if (st != ORI_OK) {
        // An invalid fold is a negative answer; anything else is bad input.
        if (st == ORI_ERR_ARGUMENT && strncmp(err.message, "the fold is ", 12) == 0) {
            fprintf(stderr, "orikin fit: %s: %s\n", a.path, err.message);
            rc = CLI_EXIT_NEGATIVE;
        } else {
            rc = cli_fold_solve_error("fit", &a, st, &err);
        }
        cli_kin_free(&k);
        return rc;
    }
    int n = ori_fit_crease_count(fit), d = a.degree;
    double from = a.has_from ? a.from_deg : ori_rad_to_deg_output(k.angles[a.drive]);
    double coef[13];
    // Coefficients in powers of the drive in degrees: θ_deg = Σ c_k x_deg^k with
    // c_k = (180/π) c_k^rad (π/180)^k.
    if (a.json) {
        json_t *out = json_object();
        json_object_set_new(out, "file", json_string(a.path));
        json_object_set_new(out, "degree", json_integer(d));
        json_object_set_new(out, "drive", json_integer(a.drive));
        json_object_set_new(out, "from_deg", json_real(from));
        json_object_set_new(out, "to_deg", json_real(a.to_deg));
        json_object_set_new(out, "step_deg", json_real(a.step_deg));
        json_object_set_new(out, "samples", json_integer(ori_fit_sample_count(fit)));
        json_object_set_new(out, "error_grid_refine", json_integer(a.refine));
        json_object_set_new(out, "variable", json_string("driven angle in degrees; coefficients c0 first"));
        json_object_set_new(out, "conditioning",
                            json_string("least squares by QR (LAPACKE_dgels) in the scaled variable t = (x - c)/w "
                                        "on [-1, 1], then expanded to monomials"));
        json_t *arr = json_array();
        for (int i = 0; i < n; ++i) {
            ori_fit_crease c = ori_fit_crease_of(fit, i);
            ori_fit_coefficients(fit, i, coef, 13);
            json_t *cs = json_array();
            for (int q = 0; q <= d; ++q)
                json_array_append_new(cs, json_real(ori_rad_to_deg(coef[q]) * pow(ORI_PI / 180.0, q)));
            json_array_append_new(arr, json_pack("{s:i,s:o,s:f}", "edge", c.edge, "coefficients", cs, "max_error_deg",
                                                 ori_rad_to_deg(c.max_error_rad)));
        }
        json_object_set_new(out, "creases", arr);
        cli_print_json(out);
    } else {
        printf("%s: transfer functions of crease %d, %g to %g deg, degree %d, %d samples (step %g deg), face %d "
               "fixed%s\n",
               a.path, a.drive, from, a.to_deg, d, ori_fit_sample_count(fit), a.step_deg, a.fix,
               a.fix_default ? CLI_FOLD_DEFAULT_FIX_NOTE : "");
        printf("theta(x) = c0 + c1 x + ... (x = crease %d in degrees, theta in degrees)\n", a.drive);
        for (int i = 0; i < n; ++i) {
            ori_fit_crease c = ori_fit_crease_of(fit, i);
            ori_fit_coefficients(fit, i, coef, 13);
            printf("crease %-5d", c.edge);
            for (int q = 0; q <= d; ++q) printf(" %+.10e", ori_rad_to_deg(coef[q]) * pow(ORI_PI / 180.0, q));
            printf("   max error %.3g deg\n", ori_rad_to_deg(c.max_error_rad));
        }
        printf("max error measured against exact solutions on a grid %d times finer\n", a.refine);
    }
    if (a.out) rc = write_samples(&a, &k, &fd, fit);
    ori_fit_destroy(fit);
    cli_kin_free(&k);
    return rc;
}

const cli_command cli_cmd_fit = {
    "fit",
    "transfer functions: polynomials of the constrained crease angles in the driven angle",
    "usage: orikin fit FILE [--fix FACE] --drive EDGE --to DEG [--from DEG] [--step DEG]\n"
    "                  [--lock E1,E2,...] [--degree D] [--refine R] [--frame N] [--force] [--json]\n"
    "                  [-o OUT.fold]\n"
    "\n"
    "Solve the fold exactly at every --step (as orikin fold), fit each constrained crease angle\n"
    "by a polynomial of degree D in the driven angle (the thesis' transfer functions, degree 4),\n"
    "and measure the fit's maximum error against exact solutions on a grid R times finer. The\n"
    "fit is least squares by QR in a scaled variable on [-1, 1] (well conditioned), expanded\n"
    "to coefficients of powers of the driven angle in degrees, c0 first. Exact solving stays\n"
    "the default everywhere else. Exit 1 when the fold is not valid.\n"
    "\n"
    "options:\n"
    "  --fix, --drive, --to, --from, --step, --lock, --frame, --weld, --tolerance, --gaps,\n"
    "  --keep-collinear, --keep-holes   as in orikin fold (faces by index, name or @x,y,\n"
    "                creases by index or @x,y)\n"
    "  --degree D    polynomial degree, 0 to 12; default 4\n"
    "  --refine R    error grid: step / R; default 10\n"
    "  --force       solve even when the samples and the error grid exceed 1000000 states\n"
    "  --json        print {degree, drive, from_deg, to_deg, step_deg, samples, creases:\n"
    "                [{edge, coefficients, max_error_deg}]}\n"
    "  -o OUT.fold   write FILE with the exact samples as folded-form frames (as orikin fold)\n"
    "                and the transfer functions under \"orikin:fit\" {drive, degree,\n"
    "                variable, creases}\n"
    "\n"
    "example: orikin fit examples/patterns/open-corner.fold --fix 4 --drive 12 --lock 11 --to 90 --step 10\n",
    run,
    NULL,
};
