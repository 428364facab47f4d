// orikin tolerance: the fabrication tolerance of a fold: seeded perturbations of the pattern's
// vertices, each sample folded as the nominal one, and the distribution of the final pose's error.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fab_args.h"
#include "kin_args.h"
#include "output_guard.h"
#include "progress.h"

static const char *const metric_keys[ORI_TOLERANCE_METRIC_COUNT] = {"position", "end_effector", "face_normal_deg",
                                                                    "fold_angle_deg", "gap", "current"};
static const char *const metric_labels[ORI_TOLERANCE_METRIC_COUNT] = {"vertex position", "end effector", "face normal",
                                                                      "fold angle", "seam gap", "current needed"};

static bool is_angle(int m) { return m == ORI_TOLERANCE_METRIC_NORMAL || m == ORI_TOLERANCE_METRIC_ANGLE; }

static int run(int argc, char **argv)
{
    const char *cmd = "tolerance", *v;
    char **rest = malloc(sizeof(char *) * (size_t)(argc + 1));
    int nrest = 0;
    rest[nrest++] = argv[0];
    cli_seen seen = {0};
    bool has_sigma = false, json = false, has_width = false;
    double width_sigma = 0.0;
    const char *unit_opt = NULL, *materials = NULL;
    double sigma = 0.0, sigma_unit = 0.0;
    int samples = 1000, threads = 1;
    unsigned long long seed = 1;
    bool force = false;
    int rc = cli_guard_strip(cmd, &argc, argv, &force);
    for (int i = 1; i < argc && rc == CLI_EXIT_OK; ++i) {
        if (strcmp(argv[i], "--vertex-sigma") == 0) {
            if (!(v = cli_option_once(cmd, argc, argv, &i, &seen))) rc = CLI_EXIT_USAGE;
            else if (!fab_parse_length(v, &sigma, &sigma_unit))
                rc = cli_usage(cmd, "--vertex-sigma: a length >= 0, bare (pattern units) or with a unit (1um), not \"%s\"", v);
            has_sigma = true;
        } else if (strcmp(argv[i], "--width-sigma") == 0) {
            if (!(v = cli_option_once(cmd, argc, argv, &i, &seen))) rc = CLI_EXIT_USAGE;
            else if (!cli_parse_double(v, &width_sigma) || width_sigma < 0.0)
                rc = cli_usage(cmd, "--width-sigma: a relative standard deviation >= 0 (0.05 = 5 %%), not \"%s\"", v);
            has_width = true;
        } else if (strcmp(argv[i], "--unit") == 0) {
            if (!(unit_opt = cli_option_once(cmd, argc, argv, &i, &seen))) rc = CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--materials") == 0) {
            if (!(materials = cli_option_once(cmd, argc, argv, &i, &seen))) rc = CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--samples") == 0) {
            if (!(v = cli_option_once(cmd, argc, argv, &i, &seen))) rc = CLI_EXIT_USAGE;
            else if (!cli_parse_int(v, &samples) || samples < 1 || samples > ORI_TOLERANCE_MAX_SAMPLES)
                rc = cli_usage(cmd, "--samples: 1 to %d, not \"%s\"", ORI_TOLERANCE_MAX_SAMPLES, v);
        } else if (strcmp(argv[i], "--seed") == 0) {
            if (!(v = cli_option_once(cmd, argc, argv, &i, &seen))) rc = CLI_EXIT_USAGE;
            else {
                char *end;
                seed = strtoull(v, &end, 10);
                if (!*v || *end || v[0] == '-') rc = cli_usage(cmd, "--seed: a non-negative integer, not \"%s\"", v);
            }
        } else if (strcmp(argv[i], "--threads") == 0) {
            if (!(v = cli_option_once(cmd, argc, argv, &i, &seen))) rc = CLI_EXIT_USAGE;
            else if (!cli_parse_int(v, &threads) || threads < 1 || threads > 256)
                rc = cli_usage(cmd, "--threads: 1 to 256, not \"%s\"", v);
        } else if (strcmp(argv[i], "--json") == 0) {
            json = true;
        } else {
            rest[nrest++] = argv[i];
        }
    }
    if (rc == CLI_EXIT_OK && !has_sigma) rc = cli_usage(cmd, "--vertex-sigma LEN is required (e.g. 1um)");
    double unit_m = 0.0;
    if (rc == CLI_EXIT_OK && unit_opt) {
        ori_error e;
        if (ori_unit_meters(unit_opt, &unit_m, &e) != ORI_OK) rc = cli_usage(cmd, "--unit: %s", e.message);
    }
    if (rc == CLI_EXIT_OK && !has_width && (unit_opt || materials))
        rc = cli_usage(cmd, "%s: for the sizing of --width-sigma", unit_opt ? "--unit" : "--materials");
    cli_fold_args fa;
    memset(&fa, 0, sizeof fa);
    if (rc == CLI_EXIT_OK) rc = cli_fold_parse(cmd, nrest, rest, false, &fa);
    free(rest);
    if (rc == CLI_EXIT_OK && fa.out) rc = cli_usage(cmd, "-o: tolerance writes nothing (it prints the distribution)");
    if (rc != CLI_EXIT_OK) return rc;
    json |= fa.json;
    cli_kin k;
    if ((rc = cli_kin_load(cmd, fa.path, fa.frame, &k)) != CLI_EXIT_OK) return rc;
    ori_motion_def def;
    rc = cli_fold_resolve(cmd, &fa, &k);
    if (rc == CLI_EXIT_OK) rc = cli_fold_def(cmd, &fa, &k, &def);
    // Every sample is a whole fold: its output steps (start, one a step, the end) are exact
    // solves, bounded together as `fit` bounds its samples (--force lifts it).
    if (rc == CLI_EXIT_OK) {
        double from = def.has_from ? def.from_rad : (def.start_angles_rad ? def.start_angles_rad[def.driven_edge] : 0.0);
        double steps = ceil(fabs(def.to_rad - from) / def.step_rad) + 1.0;
        rc = cli_guard_solves(cmd, (double)samples * steps, "--step or fewer --samples", force);
    }
    double file_m = 0.0;
    bool has_unit = fab_file_unit(k.doc, &file_m);
    if (unit_opt) has_unit = true, file_m = unit_m;
    if (rc == CLI_EXIT_OK && sigma_unit > 0.0 && !has_unit)
        rc = cli_input_fail(cmd, fa.path, "frame_unit: the coordinates are unitless: give --vertex-sigma in pattern units (no unit)");
    double sigma_units = sigma_unit > 0.0 ? sigma * sigma_unit / file_m : sigma;
    char *unit_text = ori_fold_get_custom(k.doc, 0, "frame_unit");
    char unit[16] = "";
    if (has_unit && unit_text) {
        json_t *j = json_loads(unit_text, JSON_DECODE_ANY, NULL);
        if (j && json_is_string(j)) snprintf(unit, sizeof unit, "%s", json_string_value(j));
        json_decref(j);
    }
    ori_buffer_free(unit_text);
    if (unit_opt) snprintf(unit, sizeof unit, "%s", unit_opt);
    ori_materials *mat = NULL;
    ori_design_def dd = ori_default_design_def();
    if (rc == CLI_EXIT_OK && has_width) {
        mat = ori_materials_create();
        ori_error e;
        if (materials && ori_materials_load_file(mat, materials, &e) != ORI_OK) rc = cli_input_error(cmd, materials, &e);
        dd.doc = k.doc;
        dd.pattern = k.flat;
        dd.materials = mat;
        dd.has_meters_per_unit = unit_opt != NULL;
        dd.meters_per_unit = unit_m;
    }
    ori_tolerance *t = NULL;
    if (rc == CLI_EXIT_OK) {
        ori_tolerance_def td = ori_default_tolerance_def();
        td.pattern = k.flat;
        td.motion = &def;
        td.vertex_sigma = sigma_units;
        td.samples = samples;
        td.seed = seed;
        td.threads = threads;
        td.design = has_width ? &dd : NULL;
        td.width_sigma_rel = width_sigma;
        cli_progress bar;
        cli_progress_begin(&bar, cmd, "folding samples");
        bar.quiet = json;
        td.progress = cli_progress_fn;
        td.progress_user = &bar;
        ori_error err;
        ori_status st = ori_tolerance_run(&td, &t, &err);
        cli_progress_end(&bar);
        if (st != ORI_OK && strcmp(err.field, "frame_unit") == 0)
            rc = cli_input_fail(cmd, fa.path, "frame_unit: %s (--unit U: m, cm, mm, um, nm, in, pt)", err.message);
        else if (st != ORI_OK) rc = cli_input_error(cmd, fa.path, &err);
    }
    if (rc == CLI_EXIT_OK) {
        ori_tolerance_stats s[ORI_TOLERANCE_METRIC_COUNT];
        for (int m = 0; m < ORI_TOLERANCE_METRIC_COUNT; ++m) s[m] = ori_tolerance_stats_of(t, (ori_tolerance_metric)m);
        int failed = ori_tolerance_failed_count(t);
        if (json) {
            json_t *o = json_object(), *ms = json_object();
            json_object_set_new(o, "file", json_string(fa.path));
            json_object_set_new(o, "fixed_face", json_integer(fa.fix));
            json_object_set_new(o, "drive", json_integer(fa.drive));
            json_object_set_new(o, "to_deg", json_real(fa.to_deg));
            json_object_set_new(o, "vertex_sigma", json_real(sigma_units));
            json_object_set_new(o, "unit", has_unit ? json_string(unit) : json_null());
            json_object_set_new(o, "samples", json_integer(samples));
            json_object_set_new(o, "seed", json_integer((json_int_t)seed));
            json_object_set_new(o, "failed", json_integer(failed));
            json_object_set_new(o, "contacts", json_integer(ori_tolerance_contact_count(t)));
            json_object_set_new(o, "width_sigma", has_width ? json_real(width_sigma) : json_null());
            json_object_set_new(o, "nominal_current", has_width ? json_real(ori_tolerance_nominal_current(t)) : json_null());
            for (int m = 0; m < ORI_TOLERANCE_METRIC_COUNT; ++m) {
                double f = is_angle(m) ? 180.0 / ORI_PI : 1.0;
                if (m == ORI_TOLERANCE_METRIC_CURRENT && !has_width) continue;
                json_object_set_new(ms, metric_keys[m],
                                    json_pack("{s:f,s:f,s:f,s:f,s:f,s:f,s:f,s:f}", "mean", s[m].mean * f, "sd", s[m].sd * f,
                                              "min", s[m].min * f, "max", s[m].max * f, "p50", s[m].p50 * f, "p90",
                                              s[m].p90 * f, "p95", s[m].p95 * f, "p99", s[m].p99 * f));
            }
            json_object_set_new(o, "metrics", ms);
            cli_print_json(o);
        } else {
            const char *u = has_unit ? unit : "units";
            printf("%s: fold crease %d to %g deg, face %d fixed%s\n", fa.path, fa.drive, fa.to_deg, fa.fix,
                   fa.fix_default ? CLI_FOLD_DEFAULT_FIX_NOTE : "");
            printf("%d samples, every vertex moved by a normal deviate of sigma = %g %s in x and y (seed %llu)\n", samples,
                   sigma_units, u, seed);
            if (has_width)
                printf("every hinge width x (1 + %g x a normal deviate); the nominal fold needs %.4g mA\n", width_sigma,
                       1e3 * ori_tolerance_nominal_current(t));
            printf("\n%-16s %-6s %12s %12s %12s %12s %12s %12s\n", "final-pose error", "unit", "mean", "sd", "p50", "p95",
                   "p99", "max");
            for (int m = 0; m < ORI_TOLERANCE_METRIC_COUNT; ++m) {
                if (m == ORI_TOLERANCE_METRIC_GAP && ori_tolerance_contact_count(t) == 0) continue;
                if (m == ORI_TOLERANCE_METRIC_CURRENT && !has_width) continue;
                double f = is_angle(m) ? 180.0 / ORI_PI : m == ORI_TOLERANCE_METRIC_CURRENT ? 1e3 : 1.0;
                const char *mu = is_angle(m) ? "deg" : m == ORI_TOLERANCE_METRIC_CURRENT ? "mA" : u;
                printf("%-16s %-6s %12.5g %12.5g %12.5g %12.5g %12.5g %12.5g\n", metric_labels[m], mu,
                       s[m].mean * f, s[m].sd * f, s[m].p50 * f, s[m].p95 * f, s[m].p99 * f, s[m].max * f);
            }
            printf("\n(position: the largest distance of a vertex from its nominal final place, the fixed face held;\n"
                   " face normal, fold angle: the largest deviation over the faces and creases%s)\n",
                   ori_tolerance_contact_count(t) ? "; seam gap: the widest opening between vertices that meet" : "");
            printf("%d of %d samples did not fold validly\n", failed, samples);
        }
    }
    ori_tolerance_destroy(t);
    ori_materials_destroy(mat);
    cli_kin_free(&k);
    return cli_finish(rc);
}

const cli_command cli_cmd_tolerance = {
    "tolerance",
    "fabrication tolerance: a fold's final-pose error over seeded perturbations of the pattern",
    "usage: orikin tolerance FILE --vertex-sigma LEN [--fix FACE] --drive EDGE --to DEG [fold options]\n"
    "                        [--samples N] [--seed S] [--threads N] [--force] [--json]\n"
    "\n"
    "How lithography and alignment errors change the folded device (thesis ch. 2.1.1): fold FILE\n"
    "as orikin fold does (rigid), then N copies of its crease pattern with every vertex moved by\n"
    "an independent normal deviate of standard deviation LEN in x and in y, each folded the same\n"
    "way, and print the distribution (mean, sd, percentiles, max) of the final pose's error\n"
    "against the nominal fold: the largest vertex displacement (the fixed face held where the\n"
    "flat sheet has it), the end effector of a single-vertex fold, the largest face-normal and\n"
    "fold-angle deviations, and the seam gap (the widest opening between vertices that meet in\n"
    "the nominal pose). Samples that do not build or fold validly are counted. The same seed\n"
    "gives the same numbers, whatever --threads. Lengths: bare in the pattern's units, or with a\n"
    "unit converted through frame_unit (1um).\n"
    "\n"
    "options:\n"
    "  --vertex-sigma LEN    standard deviation of each vertex coordinate (required; 0: the\n"
    "                        nominal design, zero error)\n"
    "  --samples N           number of samples (default 1000); samples x fold steps over 1000000\n"
    "                        exact solves need --force\n"
    "  --seed S              random seed, a non-negative integer (default 1)\n"
    "  --threads N           worker threads (default 1)\n"
    "  --width-sigma REL     also perturb every hinge's width by this relative standard deviation\n"
    "                        and size each sample's fold as orikin actuate does: the current it\n"
    "                        needs is reported (FILE's edges_orikin:hinge and orikin:actuation)\n"
    "  --unit U, --materials FILE  for that sizing, as for orikin actuate\n"
    "  --fix, --drive, --to, --from, --step, --lock, --frame, --solver, --linear\n"
    "                        the fold, as for orikin fold\n"
    "  --json                print {file, fixed_face, drive, to_deg, vertex_sigma, unit, samples,\n"
    "                        seed, failed, contacts, width_sigma, nominal_current, metrics:\n"
    "                        {position, end_effector, face_normal_deg, fold_angle_deg, gap,\n"
    "                        current (A, with --width-sigma): {mean, sd, min, max, p50, p90, p95,\n"
    "                        p99}}} (lengths in the pattern's units)\n"
    "\n"
    "example: orikin tolerance examples/patterns/open-corner-gold.fold --vertex-sigma 1um --fix 4\n"
    "           --drive 12 --lock 11 --to 90 --samples 1000\n",
    run,
    NULL,
};
