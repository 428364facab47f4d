// orikin regularize: the nearest exact (and, on request, rigidly foldable) crease pattern to a
// rounded drawing.
#include <math.h>
#include <orikin/flat.h>
#include <orikin/regularize.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "progress.h"
#include "report.h"

static double deg(double rad) { return ori_rad_to_deg_output(rad); }

static int run(int argc, char **argv)
{
    const char *cmd = "regularize", *path = NULL, *out = NULL;
    bool json = false, rigid = false, rigid_only = false;
    double timeout_s = 0.0;
    ori_regularize_def def = ori_default_regularize_def();
    cli_input in;
    cli_input_init(&in);
    cli_seen seen = {0};
    for (int i = 1; i < argc; ++i) {
        const char *o = argv[i];
        int r = cli_input_option(cmd, argc, argv, &i, &in, &seen);
        if (r < 0) return -r;
        if (r > 0) continue;
        if (strcmp(o, "--json") == 0) json = true;
        else if (strcmp(o, "--rigid") == 0) rigid = true;
        else if (strcmp(o, "--rigid-only") == 0) rigid_only = true;
        else if (strcmp(o, "-o") == 0) {
            if (!(out = cli_option_once(cmd, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
        } else if (strcmp(o, "--max-move") == 0) {
            const char *v = cli_option_once(cmd, argc, argv, &i, &seen);
            if (!v) return CLI_EXIT_USAGE;
            if (!cli_parse_double(v, &def.max_move_rel))
                return cli_usage(cmd, "--max-move needs a fraction of the sheet size in (0, 1], got '%s'", v);
        } else if (strcmp(o, "--limit") == 0) {
            const char *v = cli_option_once(cmd, argc, argv, &i, &seen);
            if (!v) return CLI_EXIT_USAGE;
            if (!cli_parse_int(v, &def.max_iterations) || def.max_iterations < 1 || def.max_iterations > 1000000)
                return cli_usage(cmd, "--limit needs a number of iterations from 1 to 1000000, got '%s'", v);
        } else if (strcmp(o, "--timeout") == 0) {
            const char *v = cli_option_once(cmd, argc, argv, &i, &seen);
            if (!v) return CLI_EXIT_USAGE;
            if (!cli_parse_double(v, &timeout_s) || !(timeout_s > 0.0) || timeout_s > 1e9)
                return cli_usage(cmd, "--timeout needs seconds in (0, 1e9], got '%s'", v);
        } else if (o[0] == '-' && o[1] != '\0') {
            return cli_usage(cmd, "unknown option %s", o);
        } else if (!path) {
            path = o;
        } else {
            return cli_usage(cmd, "one FILE only");
        }
    }
    if (!path) return cli_usage(cmd, "missing FILE");
    def.rigid = rigid;
    def.rigid_only = rigid_only;
    char mistake[200];
    if (cli_regularize_request_error(&def, "--max-move", mistake, sizeof mistake)) return cli_usage(cmd, "%s", mistake);
    rigid = rigid || rigid_only;
    ori_fold *doc;
    ori_pattern *p;
    int rc = cli_input_load(cmd, path, &in, &doc, &p);
    if (rc != CLI_EXIT_OK) return rc;
    if (cli_regularize_pattern_error(p, in.frame, mistake, sizeof mistake)) {
        ori_pattern_destroy(p);
        ori_fold_destroy(doc);
        return cli_input_fail(cmd, path, "%s", mistake);
    }
    ori_regularize_result r;
    ori_pattern *q = NULL;
    ori_error err;
    // The budget: --limit iterations per attempt, --timeout seconds; stopped, the best found is
    // reported (exit 5) and written with -o, to be regularized further.
    cli_deadline deadline;
    cli_deadline_begin(&deadline, cmd, "regularizing", timeout_s);
    def.progress = cli_deadline_fn, def.progress_user = &deadline;
    def.keep_partial = true;
    ori_status st = ori_regularize(p, &def, &q, &r, &err);
    cli_progress_end(&deadline.bar);
    if (st == ORI_ERR_LIMIT && r.stopped) st = ORI_OK; // (cancelled at --timeout: a partial answer)
    if (st != ORI_OK) {
        ori_pattern_destroy(p);
        ori_fold_destroy(doc);
        return cli_input_error("regularize", path, &err);
    }
    // The verdict: written only when every condition holds and nothing moved too far.
    char buf[320];
    const char *why = cli_regularize_refusal(&r, &def, buf, sizeof buf);
    bool ok = why == NULL;
    bool partial = r.stopped && q != NULL; // the best found, written for another run to go on from
    int code = ok ? CLI_EXIT_OK : r.stopped ? CLI_EXIT_PARTIAL : CLI_EXIT_NEGATIVE;
    if ((ok || partial) && out) {
        code = cli_write_frame_pattern("regularize", &doc, &in, q, out);
        if (code != CLI_EXIT_OK) ok = partial = false;
        else if (partial) code = CLI_EXIT_PARTIAL;
    }
    if (json) {
        json_t *o = cli_regularize_json(path, &def, &r, why, (ok || partial) && out ? out : NULL);
        cli_print_json(o);
        printf("\n");
    } else {
        printf("regularize %s: %d interior vertices, %d unknowns, %d equations, %d iterations\n", path,
               r.interior_vertices, r.unknowns, r.equations, r.iterations);
        if (rigid_only)
            printf("  Kawasaki: not required (--rigid-only); largest miss %.3g deg\n", deg(r.kawasaki_before_rad));
        else
            printf("  Kawasaki: largest miss %.3g deg before, %.3g deg after\n", deg(r.kawasaki_before_rad),
                   deg(r.kawasaki_after_rad));
        if (r.ties > 0)
            printf("  kept %d equalities of the drawing exactly (equal sectors, straight lines%s) within its precision, "
                   "%.3g deg%s\n",
                   r.ties, r.parallels_kept ? ", parallel edges" : "", deg(r.equal_tolerance_rad),
                   r.sides_moved ? "; its corners and sides moved too (they missed them by that much)" : "");
        if (rigid && rigid_only) // (the mode relations need Kawasaki: every vertex is held to first order)
            printf("  rigid: first- and second-order closure at all %d interior vertices (the assigned modes "
                   "need Kawasaki); defect %.3g before, %.3g after\n",
                   r.interior_vertices, r.rigid_before, r.rigid_after);
        else if (rigid)
            printf("  rigid: %d degree-4 vertices in their assigned mode, %d to second order; defect %.3g before, "
                   "%.3g after\n",
                   r.mode_vertices, r.interior_vertices - r.mode_vertices, r.rigid_before, r.rigid_after);
        if (r.max_move_vertex != ORI_NULL_INDEX)
            printf("  moved %d vertices: largest %.3g of the sheet size (vertex %d), RMS %.3g\n", r.moved_vertices,
                   r.max_move_rel, r.max_move_vertex, r.rms_move_rel);
        else if (ok)
            printf("  no vertex moved: the pattern is exact already\n");
        else
            printf("  no vertex moved\n");
        // Every interior vertex in its assigned mode: the rates are a finite motion (see
        // docs/verification.md); otherwise the certificate is second order.
        const char *kind = rigid && r.interior_vertices == 0
                               ? "no interior vertex constrains the fold rates: rigidly foldable as far as vertices "
                                 "tell (loops of faces around holes and cuts are fold's to check)"
                           : !rigid ? "flat-foldable (Kawasaki exact)"
                           : rigid_only && r.mode_vertices == r.interior_vertices
                               ? "rigidly foldable along the assignment (every vertex of degree 4 in its assigned mode); "
                                 "flat-foldability not required"
                           : rigid_only ? "rigidly foldable to second order; flat-foldability not required"
                           : r.mode_vertices == r.interior_vertices
                               ? "rigidly foldable along the assignment (every vertex of degree 4 in its assigned mode), "
                                 "flat-foldable"
                               : "rigidly foldable to second order, flat-foldable";
        if (!rigid_only && r.flat_foldable)
            printf("  full local check of the result: every interior vertex passes (Kawasaki, Maekawa, "
                   "big-little-big, the assignment)\n");
        if (r.stopped)
        {
            char bound[64];
            if (deadline.expired) snprintf(bound, sizeof bound, "--timeout %g s", timeout_s);
            else snprintf(bound, sizeof bound, "--limit %d iterations", def.max_iterations);
            if (partial && out) printf("verdict: %s (%s); written to %s: regularize it again to go on\n", why, bound, out);
            else if (partial) printf("verdict: %s (%s); give -o OUT to keep it and go on from there\n", why, bound);
            else printf("verdict: %s (%s); nothing to keep: its moves are too large or make edges cross\n", why, bound);
        }
        else if (!ok && why) printf("verdict: refused: %s\n", why);
        else if (out) printf("verdict: %s; written to %s\n", kind, out);
        else printf("verdict: %s (dry run: give -o OUT to write it)\n", kind);
    }
    ori_pattern_destroy(q);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    return code;
}

const cli_command cli_cmd_regularize = {
    "regularize",
    "move vertices the least so that a rounded drawing is exactly flat- (and rigidly) foldable",
    "usage: orikin regularize FILE [-o OUT] [--rigid | --rigid-only] [--max-move REL]\n"
    "                         [--limit N] [--timeout S] [--json] [input options]\n"
    "\n"
    "Drawings from other tools carry rounded coordinates: their vertices miss Kawasaki by a\n"
    "few thousandths of a degree, so exact checks fail and a rigid fold finds no motion. This\n"
    "moves the vertices as little as possible (least squares, sparse Gauss-Newton) so that every\n"
    "interior vertex satisfies Kawasaki exactly (to 1e-12 rad): interior vertices move in the\n"
    "plane, boundary vertices slide along their straight side, corners stay; the topology and\n"
    "assignment are kept. With --rigid the pattern is also made rigidly foldable from the flat\n"
    "state: fold rates whose rotations close at every vertex; a degree-4 vertex is held to the\n"
    "folding mode its assignment picks (opposite creases of like sign fold equally, the odd one\n"
    "opposite to the one across), which makes the whole motion exist; other vertices to second\n"
    "order (zero-area reciprocal diagram). --rigid-only asks for rigid foldability alone, without\n"
    "Kawasaki: designs that fold rigidly but not flat (odd degrees, Resch, hypar, Mooser's train).\n"
    "Equalities the drawing holds within its precision (4 x its largest Kawasaki miss) stay exact:\n"
    "equal sectors at a vertex, creases continuing each other straight, parallel edges (corners and\n"
    "sides move too when they miss them; fewer are kept when they cannot all hold). The result must\n"
    "pass the full local check (Kawasaki, Maekawa, big-little-big, the exact test with the\n"
    "assignment) before it is called flat-foldable.\n"
    "Reports the largest and RMS displacement relative to the sheet's diagonal. Refuses (exit 1,\n"
    "nothing written) when a vertex would move more than --max-move of the sheet size: such a\n"
    "drawing is not a rounded exact pattern. Exit codes: 0 exact, 1 refused, 5 stopped at\n"
    "--limit or --timeout (the best found, a partial answer). See docs/verification.md.\n"
    "\n"
    "options:\n"
    "  -o OUT          write the regularized pattern (FOLD: every other field kept; .svg, .cp,\n"
    "                  .opx by extension); without it, a dry run\n"
    "  --rigid         also make the pattern rigidly foldable (assigned modes at degree 4,\n"
    "                  second order elsewhere)\n"
    "  --rigid-only    rigid foldability without Kawasaki (no flat-foldability asked or checked)\n"
    "  --max-move REL  largest displacement accepted, relative to the sheet's diagonal; default 1e-3\n"
    "  --limit N       Gauss-Newton iterations per attempt (default 100); reached while still\n"
    "                  converging, it stops with the best found (exit 5, written with -o)\n"
    "  --timeout S     stop after S seconds with the best found (exit 5, written with -o)\n"

    "  --json          print {\"file\", \"rigid\", \"converged\", \"refused\", \"reason\",\n"
    "                  \"interior_vertices\", \"unknowns\", \"equations\", \"iterations\", \"stopped\",\n"
    "                  \"moved_vertices\", \"max_move_rel\", \"max_move_vertex\", \"rms_move_rel\",\n"
    "                  \"max_move_allowed_rel\", \"kawasaki_before_deg\", \"kawasaki_after_deg\",\n"
    "                  \"crossing_edge\", \"rigid_before\", \"rigid_after\", \"mode_vertices\",\n"
    "                  \"against_edge\", \"rigid_only\", \"equal_tolerance_deg\", \"ties\",\n"
    "                  \"parallels_kept\", \"sides_moved\", \"flat_foldable\", \"check_vertex\",\n"
    "                  \"output\"}\n"
    "\n",
    run,
    "input options (FILE is a FOLD file or a drawing: .svg, .opx, .cp):\n"
    CLI_INPUT_HELP
    "\n"
    "example: orikin regularize miura.fold --rigid -o miura-exact.fold\n",
};
