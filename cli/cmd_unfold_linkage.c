// orikin unfold-linkage: straighten a planar chain or convexify a simple polygon without
// self-intersection (Streinu's pseudo-triangulation motions); the motion as FOLD frames.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "progress.h"

#define CMD "unfold-linkage"

extern const cli_command cli_cmd_unfold_linkage;

static const char help[] =
    "usage: orikin unfold-linkage FILE [--steps-per-event N] [--limit N] [--timeout S]\n"
    "                             [-o OUT.fold] [--json]\n"
    "\n"
    "Unfold a planar linkage (carpenter's rule): FILE is a FOLD file whose frame_classes list\n"
    "\"linkage\", with 2D vertices_coords and edges_vertices forming one simple open chain or one\n"
    "simple closed polygon. The bars are completed to a pointed pseudo-triangulation, a convex-hull\n"
    "edge that is not a bar is removed and the one-degree-of-freedom expansive motion is followed\n"
    "(Streinu): at every event (two edges aligned, located to 1e-12) the pseudo-triangulation is\n"
    "flipped, until the chain is straight or the polygon convex. No bar length changes, no distance\n"
    "decreases, no bars cross. Collinear vertices are fine (exact predicates, ties broken by\n"
    "symbolic perturbation). Trees, crossing bars and repeated vertices are refused (exit 3).\n"
    "\n"
    "options:\n"
    "  --steps-per-event N  frames kept between two events (default 8; 0 = every step)\n"
    "  --limit N            stop after N events (default 100 x vertices + 100: Streinu's motion\n"
    "                       has O(n^2) events at most, more at the default means flips cycling)\n"
    "  --timeout S          stop after S seconds\n"
    "  -o, --output OUT     write the motion as a FOLD animation (frame 0 the input, one frame per\n"
    "                       kept configuration; played backwards it folds the straight chain or\n"
    "                       convex polygon into the input)\n"
    "  --json               print {kind, events, frames, final, stopped, max_length_error,\n"
    "                       min_distance_change} as JSON\n"
    "\n"
    "exit codes: 0 straight or convex, 1 not reached, 3 bad linkage, 4 the motion broke its\n"
    "guarantees, 5 stopped at --limit or --timeout (the motion so far is written, \"final\":\n"
    "\"not reached\", \"stopped\" names the bound; run again from its last frame to go on)\n"
    "\n"
    "example:\n"
    "  orikin unfold-linkage tests/data/unfold/spiral.fold -o spiral-motion.fold --json\n";

// Read the linkage: frame_classes has "linkage", vertices_coords 2D (or z = 0), edges_vertices.
static int load(const char *path, ori_v2 **coords, int *n, int **edges, int *m, json_t **root)
{
    json_error_t je;
    *root = json_load_file(path, 0, &je);
    if (!*root) {
        if (je.line <= 0) return cli_input_fail(CMD, path, "cannot read: %s", je.text);
        return cli_input_fail(CMD, path, "line %d, column %d: %s", je.line, je.column, je.text);
    }
    json_t *cls = json_object_get(*root, "frame_classes");
    bool linkage = false;
    size_t i;
    json_t *x;
    if (json_is_array(cls)) json_array_foreach(cls, i, x) linkage |= json_is_string(x) && strcmp(json_string_value(x), "linkage") == 0;
    if (!linkage) return cli_input_fail(CMD, path, "frame_classes: not a linkage (frame_classes must list \"linkage\")");
    json_t *vc = json_object_get(*root, "vertices_coords"), *ev = json_object_get(*root, "edges_vertices");
    if (!json_is_array(vc)) return cli_input_fail(CMD, path, "vertices_coords: missing or not an array");
    if (!json_is_array(ev)) return cli_input_fail(CMD, path, "edges_vertices: missing or not an array");
    *n = (int)json_array_size(vc);
    *m = (int)json_array_size(ev);
    *coords = calloc((size_t)*n + 1, sizeof **coords);
    *edges = calloc(2 * (size_t)*m + 2, sizeof **edges);
    json_array_foreach(vc, i, x) {
        size_t d = json_array_size(x);
        if (!json_is_array(x) || d < 2 || d > 3 || !json_is_number(json_array_get(x, 0)) || !json_is_number(json_array_get(x, 1)))
            return cli_input_fail(CMD, path, "vertices_coords %zu: not a 2D point", i);
        if (d == 3 && (!json_is_number(json_array_get(x, 2)) || json_number_value(json_array_get(x, 2)) != 0.0))
            return cli_input_fail(CMD, path, "vertices_coords %zu: a linkage is planar (z must be 0)", i);
        (*coords)[i] = ori_v2_make(json_number_value(json_array_get(x, 0)), json_number_value(json_array_get(x, 1)));
    }
    json_array_foreach(ev, i, x) {
        if (!json_is_array(x) || json_array_size(x) != 2 || !json_is_integer(json_array_get(x, 0)) ||
            !json_is_integer(json_array_get(x, 1)))
            return cli_input_fail(CMD, path, "edges_vertices %zu: not a pair of vertex indices", i);
        json_int_t a = json_integer_value(json_array_get(x, 0)), b = json_integer_value(json_array_get(x, 1));
        if (a < 0 || b < 0 || a >= *n || b >= *n)
            return cli_input_fail(CMD, path, "edges_vertices %zu: vertex index out of range", i);
        (*edges)[2 * i] = (int)a, (*edges)[2 * i + 1] = (int)b;
    }
    return CLI_EXIT_OK;
}

static int write_motion(const char *out, json_t *root, const ori_linkage_motion *mo)
{
    json_t *doc = json_deep_copy(root);
    json_object_set_new(doc, "file_creator", json_string("orikin unfold-linkage"));
    json_object_set_new(doc, "file_classes", json_pack("[s]", "animation"));
    json_t *frames = json_array();
    int n = ori_linkage_motion_vertex_count(mo);
    for (int f = 0; f < ori_linkage_motion_frame_count(mo); ++f) {
        const ori_v2 *p = ori_linkage_motion_frame(mo, f);
        json_t *vc = json_array();
        for (int v = 0; v < n; ++v) json_array_append_new(vc, json_pack("[ff]", p[v].x, p[v].y));
        json_t *fr = json_object();
        json_object_set_new(fr, "frame_classes", json_pack("[s]", "linkage"));
        json_object_set_new(fr, "frame_parent", json_integer(0));
        json_object_set_new(fr, "frame_inherit", json_true());
        json_object_set_new(fr, "frame_title", json_sprintf("%s %d", ori_linkage_motion_frame_is_event(mo, f) ? "event" : "step", f));
        json_object_set_new(fr, "vertices_coords", vc);
        json_array_append_new(frames, fr);
    }
    json_object_set_new(doc, "file_frames", frames);
    char *text = json_dumps(doc, JSON_COMPACT | JSON_REAL_PRECISION(17));
    json_decref(doc);
    ori_error err;
    ori_error_clear(&err);
    ori_status st = ori_file_write_atomic(out, text, strlen(text), &err);
    free(text);
    if (st != ORI_OK) return cli_input_error(CMD, out, &err);
    return CLI_EXIT_OK;
}

static int run(int argc, char **argv)
{
    const char *path = NULL, *out = NULL, *v;
    int per = 8, limit = 0;
    double timeout_s = 0.0;
    bool json = false;
    cli_seen seen = {0};
    for (int i = 1; i < argc; ++i) {
        if (cli_is_help(argv[i])) return cli_print_help(&cli_cmd_unfold_linkage);
        if (strcmp(argv[i], "--json") == 0) {
            json = true;
        } else if (strcmp(argv[i], "-o") == 0 || strcmp(argv[i], "--output") == 0) {
            if (!(out = cli_option_once(CMD, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--steps-per-event") == 0) {
            if (!(v = cli_option_once(CMD, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (!cli_parse_int(v, &per) || per < 0 || per > 100000)
                return cli_usage(CMD, "--steps-per-event needs an integer from 0 to 100000, got '%s'", v);
        } else if (strcmp(argv[i], "--limit") == 0) {
            if (!(v = cli_option_once(CMD, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (!cli_parse_int(v, &limit) || limit < 1 || limit > 100000000)
                return cli_usage(CMD, "--limit needs a number of events from 1 to 100000000, got '%s'", v);
        } else if (strcmp(argv[i], "--timeout") == 0) {
            if (!(v = cli_option_once(CMD, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (!cli_parse_double(v, &timeout_s) || !(timeout_s > 0.0) || timeout_s > 1e9)
                return cli_usage(CMD, "--timeout needs seconds in (0, 1e9], got '%s'", v);
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            return cli_usage(CMD, "unknown option %s", argv[i]);
        } else if (!path) {
            path = argv[i];
        } else {
            return cli_usage(CMD, "one FILE only");
        }
    }
    if (!path) return cli_usage(CMD, "missing FILE");
    ori_v2 *coords = NULL;
    int *edges = NULL, n = 0, m = 0;
    json_t *root = NULL;
    int rc = load(path, &coords, &n, &edges, &m, &root);
    if (rc != CLI_EXIT_OK) {
        free(coords), free(edges), json_decref(root);
        return rc;
    }
    ori_linkage_def def = ori_default_linkage_def();
    def.coords = coords, def.vertex_count = n, def.edges = edges, def.edge_count = m, def.steps_per_event = per;
    def.max_events = limit;
    cli_deadline deadline;
    cli_deadline_begin(&deadline, CMD, "unfolding", timeout_s);
    def.progress = cli_deadline_fn, def.progress_user = &deadline;
    def.keep_partial = true;
    ori_linkage_motion *mo = NULL;
    ori_error err;
    ori_error_clear(&err);
    ori_status st = ori_linkage_unfold(&def, &mo, &err);
    cli_progress_end(&deadline.bar);
    // Stopped at a budget: the motion so far is the answer (exit 5).
    const char *stopped = NULL;
    if (st == ORI_ERR_LIMIT && mo) {
        stopped = deadline.expired ? "timeout" : "limit";
        st = ORI_OK;
    }
    if (st != ORI_OK) {
        rc = (st == ORI_ERR_NOT_CONVERGED || st == ORI_ERR_INTERNAL || st == ORI_ERR_LIMIT)
                 ? (fprintf(stderr, "orikin %s: %s: %s\n", CMD, path, err.message), CLI_EXIT_INTERNAL)
                 : cli_input_error(CMD, path, &err);
        free(coords), free(edges), json_decref(root);
        return rc;
    }
    ori_linkage_result r = ori_linkage_motion_result(mo);
    if (out) rc = write_motion(out, root, mo);
    if (rc == CLI_EXIT_OK) {
        const char *kind = r.kind == ORI_LINKAGE_CHAIN ? "chain" : "polygon";
        const char *final = r.final_ok ? (r.kind == ORI_LINKAGE_CHAIN ? "straight" : "convex") : "not reached";
        if (json) {
            json_t *o = json_object();
            json_object_set_new(o, "kind", json_string(kind));
            json_object_set_new(o, "events", json_integer(r.events));
            json_object_set_new(o, "flips", json_integer(r.flips));
            json_object_set_new(o, "straightened", json_integer(r.straightened));
            json_object_set_new(o, "steps", json_integer(r.steps));
            json_object_set_new(o, "frames", json_integer(r.frames));
            json_object_set_new(o, "final", json_string(final));
            json_object_set_new(o, "stopped", stopped ? json_string(stopped) : json_null());
            json_object_set_new(o, "max_length_error", json_real(r.max_length_error));
            json_object_set_new(o, "min_distance_change", json_real(r.min_distance_change));
            json_object_set_new(o, "max_event_residual", json_real(r.max_event_residual));
            cli_print_json(o); // takes o
        } else {
            printf("%s of %d vertices: %s after %d events (%d flips, %d joints straightened), %d frames\n", kind, n,
                   final, r.events, r.flips, r.straightened, r.frames);
            printf("bar lengths kept to %.3g (relative); least distance change %.3g\n", r.max_length_error,
                   r.min_distance_change);
            if (stopped && deadline.expired)
                printf("stopped at --timeout %g s: the motion so far%s\n", timeout_s, out ? " is written" : "");
            else if (stopped)
                printf("stopped at --limit %d events%s: the motion so far%s\n", def.max_events > 0 ? def.max_events : 100 * n + 100,
                       limit > 0 ? "" : " (the default: flips cycling?)", out ? " is written" : "");
        }
        if (stopped) rc = CLI_EXIT_PARTIAL;
        else if (!r.final_ok) rc = CLI_EXIT_NEGATIVE;
    }
    ori_linkage_motion_destroy(mo);
    free(coords), free(edges), json_decref(root);
    return rc;
}

const cli_command cli_cmd_unfold_linkage = {"unfold-linkage", "straighten a chain or convexify a polygon (Streinu)", help,
                                            run, NULL};
