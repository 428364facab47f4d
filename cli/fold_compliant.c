// orikin fold --compliant: fold with the bar-and-hinge model (include/orikin/compliant.h,
// docs/compliant.md): every pattern folds, bending its panels where it must, and the report says
// how far it went, how much the sheet strains and how far each crease is from its target.
// cmd_fold.c hands the command line over when --compliant is given.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "fold_compliant.h"
#include "kin_args.h"
#include "output_guard.h"
#include "progress.h"
#include "report.h"

typedef struct compliant_args {
    const char *path, *out, *fix;
    bool json;
    cli_compliant_request r; // the fold asked (shared with the studio: cli/report)
    cli_input input;
} compliant_args;

static int parse_positive(const char *cmd, const char *opt, const char *v, bool zero_ok, double *out)
{
    if (!cli_parse_double(v, out) || !isfinite(*out) || *out < 0.0 || (!zero_ok && *out == 0.0))
        return cli_usage(cmd, "%s needs a number %s, got '%s'", opt, zero_ok ? ">= 0" : "> 0", v);
    return CLI_EXIT_OK;
}

int cli_compliant_option(const char *cmd, int argc, char **argv, int *i, cli_compliant_request *r, const char **fix,
                         cli_seen *seen)
{
    const char *o = argv[*i], *v = NULL;
    if (strcmp(o, "--compliant") == 0) return 1;
    if (strcmp(o, "--dynamic") == 0) {
        r->dynamic = true;
        return 1;
    }
    static const char *const valued[] = {"--percent", "--fix",    "--preset", "--axial", "--facet",
                                         "--crease",  "--damping", "--gravity", "--steps", "--threads"};
    int k = 0;
    while (k < 10 && strcmp(o, valued[k]) != 0) k++;
    if (k == 10) return 0;
    if (!(v = cli_option_once(cmd, argc, argv, i, seen))) return -CLI_EXIT_USAGE;
    int rc = CLI_EXIT_OK;
    if (strcmp(o, "--percent") == 0) {
        if (!cli_parse_double(v, &r->percent) || !(r->percent >= 0.0 && r->percent <= 100.0))
            rc = cli_usage(cmd, "--percent needs a number from 0 to 100, got '%s'", v);
    } else if (strcmp(o, "--fix") == 0) {
        *fix = v;
    } else if (strcmp(o, "--preset") == 0) {
        if (strcmp(v, "origami-simulator") == 0) r->physical = false;
        else if (strcmp(v, "physical") == 0) r->physical = true;
        else rc = cli_usage(cmd, "--preset is origami-simulator or physical, got '%s'", v);
    } else if (k >= 3 && k <= 6) { // the preset's stiffnesses and damping, each replaced
        struct {
            double *value;
            bool *given, zero_ok;
        } const stiff[4] = {{&r->axial, &r->has_axial, false},
                            {&r->facet, &r->has_facet, true},
                            {&r->crease, &r->has_crease, true},
                            {&r->damping, &r->has_damping, true}};
        rc = parse_positive(cmd, o, v, stiff[k - 3].zero_ok, stiff[k - 3].value);
        *stiff[k - 3].given = true;
    } else if (strcmp(o, "--gravity") == 0) {
        if (!cli_parse_double(v, &r->gravity) || !isfinite(r->gravity))
            rc = cli_usage(cmd, "--gravity needs a number, got '%s'", v);
    } else if (strcmp(o, "--steps") == 0) {
        if (!cli_parse_int(v, &r->steps) || r->steps <= 0) rc = cli_usage(cmd, "--steps needs a positive integer, got '%s'", v);
    } else if (!cli_parse_int(v, &r->threads) || r->threads < 1 || r->threads > 64) {
        rc = cli_usage(cmd, "--threads needs an integer from 1 to 64, got '%s'", v);
    }
    return rc == CLI_EXIT_OK ? 1 : -rc;
}

static int parse(int argc, char **argv, compliant_args *a)
{
    const char *cmd = "fold";
    memset(a, 0, sizeof *a);
    cli_compliant_request_init(&a->r);
    cli_input_init(&a->input);
    cli_seen seen = {0};
    for (int i = 1; i < argc; ++i) {
        const char *o = argv[i];
        int r = cli_input_option(cmd, argc, argv, &i, &a->input, &seen);
        if (r == 0) r = cli_compliant_option(cmd, argc, argv, &i, &a->r, &a->fix, &seen);
        if (r < 0) return -r;
        if (r > 0) continue;
        if (strcmp(o, "--json") == 0) a->json = true;
        else if (strcmp(o, "--all-frames") == 0) a->r.all_frames = true;
        else if (strcmp(o, "-o") == 0 || strcmp(o, "--output") == 0) {
            if (!(a->out = cli_option_once(cmd, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
        } else if (o[0] == '-' && o[1]) {
            return cli_usage(cmd, "unknown option '%s' with --compliant (see orikin fold -h)", o);
        } else if (!a->path) {
            a->path = o;
        } else {
            return cli_usage(cmd, "one FILE only, got '%s' too", o);
        }
    }
    if (!a->path) return cli_usage(cmd, "missing FILE");
    {
        char mistake[200];
        if (cli_compliant_request_error(&a->r, mistake, sizeof mistake)) return cli_usage(cmd, "%s", mistake);
    }
    return CLI_EXIT_OK;
}

static json_t *edge_array(const double *v, int n)
{
    json_t *arr = json_array();
    for (int e = 0; e < n; ++e) json_array_append_new(arr, json_real(v[e]));
    return arr;
}

int cli_compliant_write_frames(const char *cmd, const char *out, ori_fold *doc, const ori_compliant *c, int E, bool all,
                               const char *title_format)
{
    int V = ori_compliant_vertex_count(c), n = ori_compliant_frame_count(c);
    bool timed = n > 0 && ori_compliant_frame_time(c, n - 1) > 0.0; // the explicit solver's time history
    ori_error err;
    for (int k = 0; k < n; ++k) {
        if (k == 0 && ori_compliant_frame_count(c) > 1 && ori_compliant_frame_fraction(c, 0) == 0.0 && !all) continue;
        double f = ori_compliant_frame_fraction(c, k);
        char title[128];
        snprintf(title, sizeof title, title_format, 100.0 * f);
        int fr = ori_fold_append_state(doc, 0, V, ori_compliant_frame_positions(c, k), E, ori_compliant_frame_angles(c, k), title);
        char num[64];
        snprintf(num, sizeof num, "%.17g", f);
        ori_status st = ori_fold_set_custom(doc, fr, "orikin:fraction", num, &err);
        if (st == ORI_OK && timed) { // (animate times the frames by it, as simulate's)
            snprintf(num, sizeof num, "%.17g", ori_compliant_frame_time(c, k));
            st = ori_fold_set_custom(doc, fr, "frame_time", num, &err);
        }
        json_t *s = edge_array(ori_compliant_frame_strains(c, k), E);
        char *text = json_dumps(s, JSON_COMPACT);
        json_decref(s);
        if (st == ORI_OK) st = ori_fold_set_custom(doc, fr, "edges_orikin:strain", text, &err);
        free(text);
        int F = ori_compliant_face_count(c);
        const char *keys[2] = {"faces_orikin:strain_energy", "faces_orikin:strain"};
        const double *vals[2] = {ori_compliant_frame_face_energies(c, k), ori_compliant_frame_face_strains(c, k)};
        for (int q = 0; q < 2 && st == ORI_OK; ++q) {
            s = edge_array(vals[q], F);
            text = json_dumps(s, JSON_COMPACT);
            json_decref(s);
            st = ori_fold_set_custom(doc, fr, keys[q], text, &err);
            free(text);
        }
        if (st != ORI_OK) return cli_input_error(cmd, out, &err);
    }
    ori_status st = ori_fold_save_file(doc, out, &err);
    if (st != ORI_OK) return cli_input_error(cmd, out, &err);
    return CLI_EXIT_OK;
}

bool cli_fold_compliant_wanted(int argc, char **argv)
{
    for (int i = 1; i < argc; ++i)
        if (strcmp(argv[i], "--compliant") == 0) return true;
    return false;
}

int cli_fold_compliant_run(int argc, char **argv)
{
    bool force;
    int rc = cli_guard_strip("fold", &argc, argv, &force);
    if (rc != CLI_EXIT_OK) return rc;
    compliant_args a;
    if ((rc = parse(argc, argv, &a)) != CLI_EXIT_OK) return rc;
    ori_fold *doc = NULL;
    ori_pattern *p = NULL;
    if ((rc = cli_input_load("fold", a.path, &a.input, &doc, &p)) != CLI_EXIT_OK) return rc;
    if (a.fix && (rc = cli_spec_face("fold", a.path, p, "--fix", a.fix, &a.r.fix)) != CLI_EXIT_OK) {
        ori_pattern_destroy(p);
        ori_fold_destroy(doc);
        return rc;
    }
    int V = ori_pattern_vertex_count(p), E = ori_pattern_edge_count(p);
    double frames = a.r.all_frames ? ceil(180.0 * a.r.percent / 100.0 / 10.0) * 4.0 + 1.0 : 1.0;
    double bytes = a.out ? frames * (3.0 * V + 2.0 * E) * 20.0 : 0.0;
    if ((rc = cli_guard_check("fold", frames, bytes, force)) != CLI_EXIT_OK) {
        ori_pattern_destroy(p);
        ori_fold_destroy(doc);
        return rc;
    }
    ori_compliant *c = NULL;
    ori_error err, why;
    bool reached = false;
    int dyn_steps = 0;
    cli_progress bar;
    cli_progress_begin(&bar, "fold", a.r.dynamic ? "explicit dynamics" : "static equilibrium");
    ori_status st = cli_compliant_solve(p, &a.r, &c, &reached, &dyn_steps, &why, &err);
    cli_progress_end(&bar);
    if (st != ORI_OK) {
        rc = cli_input_error("fold", a.path, &err);
        ori_pattern_destroy(p);
        ori_fold_destroy(doc);
        return rc;
    }
    if (!reached && !a.json) fprintf(stderr, "orikin fold: %s: %s\n", a.path, why.message);
    double energy = ori_compliant_energy(c), strain = ori_compliant_max_strain(c);
    double cerr = ori_compliant_crease_error(c), frac = ori_compliant_fraction(c);
    int it, fa, bt, ls;
    ori_compliant_stats(c, &it, &fa, &bt, &ls);
    int NF = ori_compliant_face_count(c), worst_face = 0;
    for (int f = 1; f < NF; ++f)
        if (ori_compliant_face_energy(c, f) > ori_compliant_face_energy(c, worst_face)) worst_face = f;
    // contact warnings: faces passing through each other during the fold
    for (int k = 0; k < ori_compliant_contact_count(c) && !a.json; ++k) {
        int f0, f1, step;
        double fr;
        ori_compliant_contact(c, k, &f0, &f1, &step, &fr);
        fprintf(stderr, "orikin fold: %s: warning: faces %d and %d pass through each other at %s step %d (%.6g %%)\n", a.path,
                f0, f1, a.r.dynamic ? "explicit" : "load", step, 100.0 * fr);
    }
    if (ori_compliant_contacts_truncated(c) && !a.json)
        fprintf(stderr, "orikin fold: %s: warning: more face pairs pass through each other (the first %d are listed)\n", a.path,
                ori_compliant_contact_count(c));
    if (a.json) {
        cli_print_json(cli_compliant_json(a.path, &a.r, c, reached, dyn_steps, why.message, false));
    } else {
        printf("%s: compliant fold (%s, %s solver) to %g %%: %s %.6g %%\n", a.path,
               a.r.physical ? "physical preset" : "Origami Simulator's preset", a.r.dynamic ? "explicit" : "static",
               a.r.percent, reached ? "reached" : "stopped at", 100.0 * frac);
        printf("model: %d vertices, %d bars, %d hinges (%d triangles)\n", V, ori_compliant_bar_count(c),
               ori_compliant_hinge_count(c), ori_compliant_triangle_count(c));
        if (a.r.dynamic) printf("explicit: %d steps of %.4g\n", dyn_steps, ori_compliant_time_step(c));
        else printf("static: %d Newton iterations (%d factorizations), %d load steps, |grad E| %.2g (load scale %.3g)\n", it, fa, ls,
                    ori_compliant_gradient_norm(c), ori_compliant_load_scale(c));
        printf("max strain %.4g %%, energy %.6g, largest crease error vs target %.4g deg\n", 100.0 * strain, energy,
               cerr * 180.0 / ORI_PI);
        printf("largest face strain energy %.6g (face %d, max strain %.4g %%), %d contact warning%s\n",
               NF > 0 ? ori_compliant_face_energy(c, worst_face) : 0.0, worst_face,
               NF > 0 ? 100.0 * ori_compliant_face_strain(c, worst_face) : 0.0, ori_compliant_contact_count(c),
               ori_compliant_contact_count(c) == 1 ? "" : "s");
    }
    if (rc == CLI_EXIT_OK && a.out)
        rc = cli_compliant_write_frames("fold", a.out, doc, c, E, a.r.all_frames,
                                        "compliant fold: %.6g %% of the way to the targets");
    if (rc == CLI_EXIT_OK && !reached) rc = a.r.dynamic ? CLI_EXIT_PARTIAL : CLI_EXIT_NEGATIVE;
    ori_compliant_destroy(c);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    return rc;
}
