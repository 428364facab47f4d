// orikin layers: global flat-foldability — every flat-folded state (layer order) of a crease
// pattern, counted exactly, with the conflicting constraint named when there is none.
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <orikin/layers.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli.h"
#include "progress.h"
#include "report.h"

#define CMD "layers"

// faces_flatFoldTransform of the frame when it is present and well-formed (6 numbers per
// face), else NULL. *bad is set (with a message printed) when present but malformed.
static double *read_transforms(ori_fold *doc, int frame, int nf, const char *path, bool *bad)
{
    *bad = false;
    char *text = ori_fold_get_custom(doc, frame, "faces_flatFoldTransform");
    if (!text) return NULL;
    json_error_t jerr;
    json_t *arr = json_loads(text, 0, &jerr);
    ori_buffer_free(text);
    double *t = NULL;
    if (!json_is_array(arr) || (int)json_array_size(arr) != nf) {
        cli_input_fail(CMD, path, "faces_flatFoldTransform: needs one transform per face (%d)", nf);
        *bad = true;
    } else {
        t = malloc(sizeof(double) * 6 * (size_t)nf);
        for (int f = 0; f < nf && !*bad; ++f) {
            json_t *m = json_array_get(arr, (size_t)f);
            for (int r = 0; r < 2 && !*bad; ++r) {
                json_t *row = json_array_get(m, (size_t)r);
                for (int c = 0; c < 3 && !*bad; ++c) {
                    json_t *x = json_array_get(row, (size_t)c);
                    if (!json_is_number(x)) {
                        cli_input_fail(CMD, path, "faces_flatFoldTransform %d: needs [[a, b, c], [d, e, f]]", f);
                        *bad = true;
                    } else
                        t[6 * f + 3 * r + c] = json_number_value(x);
                }
            }
        }
        if (*bad) {
            free(t);
            t = NULL;
        }
    }
    json_decref(arr);
    return t;
}

static bool parse_u64(const char *s, uint64_t *out)
{
    if (!s || !*s || *s == '-' || *s == '+') return false;
    for (const char *p = s; *p; ++p)
        if (*p < '0' || *p > '9') return false;
    errno = 0;
    char *end;
    unsigned long long v = strtoull(s, &end, 10);
    if (errno || *end) return false;
    *out = (uint64_t)v;
    return true;
}

static bool is_decimal(const char *s)
{
    if (!s || !*s) return false;
    for (const char *p = s; *p; ++p)
        if (*p < '0' || *p > '9') return false;
    return true;
}

// After --tolerance left the coordinates undecided: the value chosen from the drawing, when
// that one decides them.
static void suggest_tolerance(const ori_pattern *p, const ori_layers_def *given)
{
    ori_layers_def def = *given;
    def.snap_rel = ORI_LAYERS_SNAP_AUTO;
    def.progress = NULL;
    ori_layers *L = NULL;
    ori_error err;
    ori_error_clear(&err);
    if (ori_layers_create(p, &def, &L, &err) == ORI_OK) {
        ori_layers_info in = ori_layers_get_info(L);
        fprintf(stderr, "orikin %s: --tolerance %.2g decides these coordinates (the value chosen from the drawing "
                        "without --tolerance)\n", CMD, in.tolerance);
    } else
        fprintf(stderr, "orikin %s: no tolerance up to 0.01 decides these coordinates either (%s)\n", CMD, err.message);
    ori_layers_destroy(L);
}

// The progress bar with --timeout's budget, and without one a hint, once, when counting has run
// for HINT_AFTER_S seconds: an exact count may take exponential time.
#define HINT_AFTER_S 10.0
typedef struct budget {
    cli_deadline deadline;
    double start;
    bool hinted;
} budget;

static double mono_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static bool budget_fn(double fraction, void *user)
{
    budget *b = user;
    bool go = cli_deadline_fn(fraction, &b->deadline);
    if (!b->hinted && b->deadline.seconds <= 0.0 && mono_s() - b->start > HINT_AFTER_S) {
        b->hinted = true;
        fprintf(stderr, "%sorikin %s: still counting after %.0f s: an exact count can take exponential time; "
                        "--timeout S or --limit N give a lower bound (exit 5)\n",
                b->deadline.bar.tty && b->deadline.bar.shown ? "\n" : "", CMD, HINT_AFTER_S);
    }
    return go;
}

// "2.4e-05 (from the drawing: …)" or "1e-06 (--tolerance)".
static void print_tolerance(const ori_layers_info *in)
{
    if (in->tolerance_from_drawing)
        printf("tolerance    %.2g (from the drawing: lengths agree within %.2g of its size, angles within %.2g rad; "
               "--tolerance overrides)\n",
               in->tolerance, in->noise_length, in->noise_angle);
    else
        printf("tolerance    %.2g (--tolerance)\n", in->tolerance);
}

static int run(int argc, char **argv)
{
    const char *path = NULL, *out = NULL, *svg = NULL, *state = NULL;
    bool json = false, count_only = false;
    bool seen_limit = false, seen_threads = false, seen_tol = false, seen_timeout = false;
    double timeout_s = 0.0;
    double tol = ORI_LAYERS_SNAP_AUTO;
    int threads = 1;
    cli_seen seen = {0};
    cli_input in;
    cli_input_init(&in);
    uint64_t limit = ORI_LAYERS_NO_LIMIT;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (strcmp(a, "--json") == 0) json = true;
        else if (strcmp(a, "--count") == 0) count_only = true;
        else if (strcmp(a, "--state") == 0) {
            if (state) return cli_usage(CMD, "--state given twice");
            state = cli_option_value(CMD, argc, argv, &i);
            if (!state) return CLI_EXIT_USAGE;
            if (!is_decimal(state)) return cli_usage(CMD, "--state needs a state number ≥ 0 (got '%s')", state);
        } else if (strcmp(a, "--limit") == 0) {
            if (seen_limit) return cli_usage(CMD, "--limit given twice");
            seen_limit = true;
            const char *v = cli_option_value(CMD, argc, argv, &i);
            if (!v) return CLI_EXIT_USAGE;
            if (!parse_u64(v, &limit) || limit == 0 || limit == ORI_LAYERS_NO_LIMIT)
                return cli_usage(CMD, "--limit needs a count ≥ 1 (got '%s')", v);
        } else if (strcmp(a, "--threads") == 0) {
            if (seen_threads) return cli_usage(CMD, "--threads given twice");
            seen_threads = true;
            const char *v = cli_option_value(CMD, argc, argv, &i);
            if (!v) return CLI_EXIT_USAGE;
            if (!cli_parse_int(v, &threads) || threads < 1 || threads > 256)
                return cli_usage(CMD, "--threads needs a count from 1 to 256 (got '%s')", v);
        } else if (strcmp(a, "--timeout") == 0) {
            if (seen_timeout) return cli_usage(CMD, "--timeout given twice");
            seen_timeout = true;
            const char *v = cli_option_value(CMD, argc, argv, &i);
            if (!v) return CLI_EXIT_USAGE;
            if (!cli_parse_double(v, &timeout_s) || !(timeout_s > 0.0) || timeout_s > 1e9)
                return cli_usage(CMD, "--timeout needs seconds in (0, 1e9] (got '%s')", v);
        } else if (strcmp(a, "--tolerance") == 0) {
            if (seen_tol) return cli_usage(CMD, "--tolerance given twice");
            seen_tol = true;
            const char *v = cli_option_value(CMD, argc, argv, &i);
            if (!v) return CLI_EXIT_USAGE;
            if (!cli_parse_double(v, &tol) || !(tol > 0.0) || !(tol <= 1e-2))
                return cli_usage(CMD, "--tolerance needs a relative length in (0, 0.01] (got '%s')", v);
        } else if (strcmp(a, "-o") == 0 || strcmp(a, "--output") == 0) {
            if (out) return cli_usage(CMD, "-o given twice");
            out = cli_option_value(CMD, argc, argv, &i);
            if (!out) return CLI_EXIT_USAGE;
        } else if (strcmp(a, "--svg") == 0) {
            if (svg) return cli_usage(CMD, "--svg given twice");
            svg = cli_option_value(CMD, argc, argv, &i);
            if (!svg) return CLI_EXIT_USAGE;
        } else {
            // after this command's own --tolerance (a snapping length), the input options
            int r = cli_input_option(CMD, argc, argv, &i, &in, &seen);
            if (r < 0) return -r;
            if (r > 0) continue;
            if (a[0] == '-' && a[1] != '\0') return cli_usage(CMD, "unknown option %s", a);
            if (path) return cli_usage(CMD, "one FILE only");
            path = a;
        }
    }
    if (!path) return cli_usage(CMD, "missing FILE");
    if (limit != ORI_LAYERS_NO_LIMIT && (state || out || svg))
        return cli_usage(CMD, "--limit counts only: states cannot be numbered (drop --state, -o and --svg)");
    if (seen_timeout && (state || out || svg))
        return cli_usage(CMD, "--timeout counts only: states cannot be numbered (drop --state, -o and --svg)");
    if (count_only && (state || out || svg)) return cli_usage(CMD, "--count prints the count only (drop --state, -o, --svg)");

    ori_fold *doc;
    ori_pattern *p;
    int rc = cli_input_load(CMD, path, &in, &doc, &p);
    if (rc != CLI_EXIT_OK) return rc;
    int frame = in.frame;
    // A crease pattern may carry its folded placement; a folded form's coordinates are folded
    // already (its transforms would apply to the unfolded coordinates, which it lacks).
    bool bad = false;
    double *xf = ori_pattern_is_folded_form(p) ? NULL : read_transforms(doc, frame, ori_pattern_face_count(p), path, &bad);
    if (bad) {
        ori_pattern_destroy(p);
        ori_fold_destroy(doc);
        return CLI_EXIT_INPUT;
    }
    ori_layers_def def = ori_default_layers_def();
    def.face_transforms = xf;
    def.face_transform_count = xf ? ori_pattern_face_count(p) : 0;
    def.limit = limit;
    def.threads = threads;
    def.snap_rel = tol;
    budget bud;
    cli_deadline_begin(&bud.deadline, CMD, "counting layer orders", timeout_s);
    bud.start = mono_s();
    bud.hinted = false;
    def.progress = budget_fn;
    def.progress_user = &bud;
    ori_layers *L = NULL;
    ori_error err;
    ori_error_clear(&err);
    ori_status st = ori_layers_create(p, &def, &L, &err);
    free(xf);
    bud.start = mono_s(); // the hint is about counting, not the set-up
    if (st == ORI_OK) st = ori_layers_count(L, &err);
    cli_progress_end(&bud.deadline.bar);
    // Stopped at --timeout: the counts so far are a partial answer (lower bounds).
    if (st == ORI_ERR_LIMIT && bud.deadline.expired) st = ORI_OK;
    if (st != ORI_OK) {
        rc = st == ORI_ERR_INTERNAL ? CLI_EXIT_INTERNAL : cli_input_error(CMD, path, &err);
        if (st == ORI_ERR_INTERNAL) cli_input_error(CMD, path, &err);
        if (st == ORI_ERR_DEGENERATE && seen_tol) suggest_tolerance(p, &def);
        ori_layers_destroy(L);
        ori_pattern_destroy(p);
        ori_fold_destroy(doc);
        return rc;
    }
    ori_layers_info info = ori_layers_get_info(L);
    char *states = ori_layers_state_count(L);
    ori_layers_conflict conf;
    bool unsat = ori_layers_get_conflict(L, &conf);
    int nconf = unsat ? ori_layers_conflict_faces(L, NULL, 0) : 0;
    int *conf_faces = malloc(sizeof(int) * (size_t)(nconf ? nconf : 1));
    if (unsat) ori_layers_conflict_faces(L, conf_faces, nconf);

    // A state for -o, --svg or --state.
    const char *k = state ? state : "0";
    bool want_state = !unsat && (state || out || svg);
    if (want_state && (st = ori_layers_select_state(L, k, &err)) != ORI_OK) {
        rc = st == ORI_ERR_RANGE ? cli_usage(CMD, "--state: %s", err.message) : cli_input_error(CMD, path, &err);
        goto finish;
    }
    if (unsat && (out || svg)) {
        fprintf(stderr, "orikin %s: %s: no flat-folded state to write (%s)\n", CMD, path, conf.detail);
    }
    if (want_state && out) {
        int fr = ori_layers_append_frame(L, p, doc, frame, &err);
        if (fr < 0 || (st = ori_fold_save_file(doc, out, &err)) != ORI_OK) {
            rc = cli_input_error(CMD, out, &err);
            goto finish;
        }
    }
    if (want_state && svg) {
        char *text = NULL;
        size_t size = 0;
        st = ori_layers_svg(L, p, &text, &size, &err);
        if (st == ORI_OK) st = ori_file_write_atomic(svg, text, size, &err);
        ori_buffer_free(text);
        if (st != ORI_OK) {
            rc = cli_input_error(CMD, svg, &err);
            goto finish;
        }
    }

    const char *why = info.stopped ? "at least: stopped at --timeout" : "at least: limited";
    if (count_only && !json) {
        printf("%s%s%s%s\n", states, info.limited ? " (" : "", info.limited ? why : "", info.limited ? ")" : "");
    } else if (json) {
        json_t *o = cli_layers_count_json(L, limit != ORI_LAYERS_NO_LIMIT, seen_timeout);
        if (state && want_state) {
            json_object_set_new(o, "state", json_string(k));
            int nv = ori_layers_face_orders(L, NULL, 0);
            int *fo = malloc(sizeof(int) * 3 * (size_t)(nv ? nv : 1));
            ori_layers_face_orders(L, fo, nv);
            json_t *arr = json_array();
            for (int i = 0; i < nv; ++i) {
                json_t *t = json_array();
                for (int j = 0; j < 3; ++j) json_array_append_new(t, json_integer(fo[3 * i + j]));
                json_array_append_new(arr, t);
            }
            free(fo);
            json_object_set_new(o, "faceOrders", arr);
        }
        cli_print_json(o);
    } else {
        printf("file         %s (frame %d, %s)\n", path, frame,
               ori_pattern_is_folded_form(p) ? "folded form" : "crease pattern");
        print_tolerance(&info);
        if (!(unsat && conf.constraint == ORI_LAYERS_LOCAL)) {
            printf("faces        %d; overlap: %d points, %d segments, %d cells\n", info.faces, info.points,
                   info.segments, info.cells);
            if (unsat) printf("variables    %d face pairs (%d classes)\n", info.variables, info.classes);
            else
                printf("variables    %d face pairs (%d classes; %d fixed by the M/V assignment)\n", info.variables,
                       info.classes, info.fixed_variables);
            printf("constraints  taco-taco %" PRId64 ", taco-tortilla %" PRId64 ", tortilla-tortilla %" PRId64
                   ", transitivity %" PRId64 "\n",
                   info.taco_taco, info.taco_tortilla, info.tortilla_tortilla, info.transitivity);
        }
        if (!unsat || conf.constraint == ORI_LAYERS_EXHAUSTED) {
            printf("components   %d: |", info.components);
            for (int c = 0; c < info.components; ++c) {
                char *n = ori_layers_component_states(L, c);
                printf("%s|", n);
                ori_buffer_free(n);
            }
            printf("\n");
        }
        if (unsat) {
            printf("states       0\n");
            printf("verdict: NO flat-folded state: %s\n", conf.detail);
            if (conf.constraint == ORI_LAYERS_LOCAL && fabs(conf.kawasaki_rad) > 0.0 &&
                fabs(conf.kawasaki_rad) <= 1e-3 && !seen_tol)
                printf("hint: no tolerance chosen from the drawing accepts this vertex; a larger --tolerance (e.g. "
                       "%.1g) takes it for a rounded one, knowingly\n",
                       fmin(1e-2, 2 * fabs(conf.kawasaki_rad)));
            if (conf.face_count > 0) {
                printf("constraint faces:");
                for (int i = 0; i < conf.face_count; ++i) printf(" %d", conf.faces[i]);
                printf("\n");
            }
            printf("faces involved:");
            for (int i = 0; i < nconf; ++i) printf(" %d", conf_faces[i]);
            printf("\n");
        } else {
            if (info.stopped)
                printf("states       %s (at least: stopped at --timeout %g s; each count is the states counted so "
                       "far)\n",
                       states, timeout_s);
            else
                printf("states       %s%s\n", states, info.limited ? " (at least: each component limited)" : "");
            if (state) {
                int nv = ori_layers_face_orders(L, NULL, 0);
                int *fo = malloc(sizeof(int) * 3 * (size_t)(nv ? nv : 1));
                ori_layers_face_orders(L, fo, nv);
                printf("state %s faceOrders:", k);
                for (int i = 0; i < nv; ++i) printf(" [%d,%d,%d]", fo[3 * i], fo[3 * i + 1], fo[3 * i + 2]);
                printf("\n");
                free(fo);
            }
            if (out) printf("wrote %s (state %s as a foldedForm frame with faceOrders)\n", out, k);
            if (svg) printf("wrote %s\n", svg);
            if (info.limited && strcmp(states, "0") == 0)
                printf("verdict: undecided: no state found within the budget\n");
            else
                printf("verdict: flat-foldable, %s%s state%s\n", info.limited ? "at least " : "", states,
                       strcmp(states, "1") == 0 ? "" : "s");
        }
    }
    rc = unsat ? CLI_EXIT_NEGATIVE : info.limited ? CLI_EXIT_PARTIAL : CLI_EXIT_OK;
finish:
    free(conf_faces);
    ori_buffer_free(states);
    ori_layers_destroy(L);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    return cli_finish(rc);
}

const cli_command cli_cmd_layers = {
    "layers",
    "global flat-foldability: count every flat-folded state (layer order), name the conflict",
    "usage: orikin layers FILE [--count] [--state K] [--limit N] [--timeout S] [-o OUT.fold]\n"
    "                   [--svg OUT.svg] [--tolerance R] [--threads N] [--json] [input options]\n"
    "\n"
    "Fold the crease pattern flat (or take a flat folded form, or faces_flatFoldTransform),\n"
    "build the overlap structure, one variable per pair of overlapping faces and Flat-Folder's\n"
    "taco-taco, taco-tortilla, tortilla-tortilla and transitivity constraints, propagate the\n"
    "M/V assignment (U creases are free), split into independent components and count each\n"
    "exactly, never listing the states. Prints the sizes, the component counts in Flat-Folder's\n"
    "order (|fixed part|smallest|...|) and the number of states, or the constraint that leaves\n"
    "none (a vertex that is not locally flat-foldable is named).\n"
    "Exit 0 when a state exists, 1 when none does, 3 for an invalid file or coordinates that do\n"
    "not determine the overlap structure, 5 when --limit or --timeout stopped the count (the\n"
    "count printed is then a lower bound). See docs/layers.md.\n"
    "\n"
    "options:\n"
    "  --count        print only the number of states\n"
    "  --state K      state to print (faceOrders), write and draw: 0 <= K < the count; default 0\n"
    "  --limit N      count at most N states per component (Flat-Folder's limit; the count is then\n"
    "                 a lower bound and --json adds \"limited\")\n"
    "  --timeout S    stop counting S seconds after the start: the count is then a lower bound (the\n"
    "                 states counted so far); --json adds \"limited\", \"timed_out\". Default: none\n"
    "  -o OUT.fold    write the file with state K appended as a foldedForm frame: folded\n"
    "                 vertices_coords, edges_foldAngle, resolved edges_assignment, faceOrders,\n"
    "                 faces_flatFoldTransform, faces_flatFoldOrientation\n"
    "  --svg OUT.svg  draw the crease pattern and state K seen from above\n"
    "  --tolerance R  snapping length relative to the folded image's diagonal, in (0, 0.01];\n"
    "                 above 1e-8 sectors within R rad are equal and Kawasaki holds within R rad\n"
    "                 or a move of R. Default: from the drawing's precision (a length with every\n"
    "                 distance met at most a quarter of it or beyond 10 times it; docs/layers.md)\n"
    "  --threads N    count independent components on N threads; default 1\n"
    "  --json         print {\"states\": \"N\", \"components\", \"faces\", \"variables\",\n"
    "                 \"constraints\": {\"taco_taco\", \"taco_tortilla\", \"tortilla_tortilla\",\n"
    "                 \"transitivity\"}, \"tolerance\", \"tolerance_source\", \"drawing_noise\",\n"
    "                 \"unsatisfiable\": null | {\"constraint\", \"faces\", \"involved_faces\",\n"
    "                 \"detail\", \"vertex\"}}; with --state also \"state\", \"faceOrders\"\n"
    "\n"
    "input options (FILE a FOLD file or a drawing: SVG, OPX, CP, read with the default weld\n"
    "tolerance; 'orikin convert --tolerance REL' first to choose another):\n"
    CLI_INPUT_HELP_FOLD CLI_INPUT_HELP_DRAWING
    "\n"
    "example: orikin layers examples/patterns/degree6-vertex.fold --state 1 --svg vertex.svg\n",
    run,
    NULL,
};
