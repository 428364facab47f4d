// orikin check: local flat-foldability of every interior vertex of a FOLD pattern.
#include <orikin/flat.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "report.h"

static const char *yes_no(bool b) { return b ? "yes" : "no"; }

static void print_count(ori_mv_count c, int width)
{
    if (c.overflow) printf("%-*s", width, ">2^64");
    else printf("%-*llu", width, (unsigned long long)c.count);
}

static int run(int argc, char **argv)
{
    const char *path = NULL;
    bool json = false, has_tol = false;
    double tol_deg = 0.0;
    cli_seen seen = {0};
    cli_input in;
    cli_input_init(&in);
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--json") == 0) json = true;
        else if (strcmp(argv[i], "--tolerance") == 0) { // degrees here: before the input options' --tolerance
            has_tol = true;
            const char *v = cli_option_once("check", argc, argv, &i, &seen);
            if (!v) return CLI_EXIT_USAGE;
            if (!cli_parse_double(v, &tol_deg) || tol_deg < 0.0 || tol_deg > 1.0)
                return cli_usage("check", "--tolerance needs an angle in degrees in [0, 1], got '%s'", v);
        } else {
            int r = cli_input_option("check", argc, argv, &i, &in, &seen);
            if (r < 0) return -r;
            if (r > 0) continue;
            if (argv[i][0] == '-' && argv[i][1] != '\0') return cli_usage("check", "unknown option %s", argv[i]);
            if (path) return cli_usage("check", "one FILE only");
            path = argv[i];
        }
    }
    if (!path) return cli_usage("check", "missing FILE");
    ori_fold *doc;
    ori_pattern *p;
    int rc = cli_input_load("check", path, &in, &doc, &p);
    if (rc != CLI_EXIT_OK) return rc;
    int frame = in.frame;

    cli_check chk;
    cli_check_run(p, path, has_tol, tol_deg, &chk);
    const ori_flat_report *rep = chk.report;
    const char *hint = chk.hint;
    int nv = ori_flat_report_vertex_count(rep);
    int max_degree = 1;
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        int d = ori_pattern_vertex_degree(p, v);
        if (d > max_degree) max_degree = d;
    }
    int *edges = malloc(sizeof(int) * (size_t)max_degree);
    double *sectors = malloc(sizeof(double) * (size_t)max_degree);
    bool ok = ori_flat_report_flat_foldable(rep);
    int nviol = ori_flat_report_violation_count(rep);

    if (json) {
        cli_print_json(cli_check_json(&chk, path, frame, p));
    } else {
        printf("file     %s (frame %d, %s)\n", path, frame,
               ori_pattern_is_folded_form(p) ? "folded form" : "crease pattern");
        if (nv > 0) {
            printf("%-7s %-6s %-4s %-4s %-4s %-8s %-6s %s\n", "vertex", "degree", "K", "M", "BLB", "C", "valid",
                   "sectors (deg)");
            for (int i = 0; i < nv; ++i) {
                ori_vertex_report r = ori_flat_report_vertex(rep, i);
                int n = ori_flat_report_vertex_creases(rep, i, edges, sectors, r.degree);
                const char *m = r.maekawa == ORI_FLAT_UNDETERMINED ? "n/a" : yes_no(r.maekawa == ORI_FLAT_YES);
                printf("%-7d %-6d %-4s %-4s %-4s ", r.vertex, r.degree, yes_no(r.kawasaki), m, yes_no(r.big_little_big));
                print_count(r.mv_count, 8);
                printf(" %-6s", r.within_tolerance ? "~yes" : r.flat_foldable ? "yes" : "NO");
                for (int k = 0; k < n; ++k) printf(" %.6g", ori_rad_to_deg_output(sectors[k]));
                printf("\n");
            }
        }
        int per_rule[ORI_FLAT_RULE_COUNT] = {0};
        for (int i = 0; i < nviol; ++i) {
            ori_flat_violation x = ori_flat_report_violation(rep, i);
            per_rule[x.rule]++;
            printf("vertex %d: %s: %s\n", x.vertex, ori_flat_rule_name(x.rule), x.detail);
        }
        int interior = ori_flat_report_interior_count(rep), failed = ori_flat_report_failed_count(rep);
        int within = ori_flat_report_within_count(rep);
        for (int i = 0; i < nv; ++i) {
            ori_vertex_report r = ori_flat_report_vertex(rep, i);
            if (r.within_tolerance)
                printf("vertex %d: within tolerance: flat-foldable once its sectors move by %.3g deg\n", r.vertex,
                       ori_rad_to_deg_output(r.deviation_rad));
        }
        if (interior == 0) printf("verdict: no interior vertices; nothing to fold locally\n");
        else if (ok && within > 0)
            printf("verdict: locally flat-foldable within %g deg (%d of %d interior vertices within tolerance, "
                   "largest deviation %.3g deg)\n",
                   tol_deg, within, interior, ori_rad_to_deg_output(ori_flat_report_max_deviation(rep)));
        else if (ok) printf("verdict: locally flat-foldable (%d interior vert%s)\n", interior, interior == 1 ? "ex" : "ices");
        else {
            printf("verdict: NOT locally flat-foldable: %d of %d interior vert%s fail%s (", failed, interior,
                   interior == 1 ? "ex" : "ices", failed == 1 && interior == 1 ? "s" : "");
            const char *sep = "";
            for (int r = 0; r < ORI_FLAT_RULE_COUNT; ++r)
                if (per_rule[r]) {
                    printf("%s%s %d", sep, ori_flat_rule_name((ori_flat_rule)r), per_rule[r]);
                    sep = ", ";
                }
            printf(")\n");
        }
        if (hint[0]) printf("note: %s\n", hint);
    }
    free(edges);
    free(sectors);
    cli_check_free(&chk);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    return ok ? CLI_EXIT_OK : CLI_EXIT_NEGATIVE;
}

const cli_command cli_cmd_check = {
    "check",
    "local flat-foldability of each interior vertex (Kawasaki, Maekawa, BLB, C)",
    "usage: orikin check FILE [--tolerance DEG] [--json] [input options]\n"
    "\n"
    "Check every interior vertex of a crease pattern (FOLD, or a drawing: SVG, OPX, CP; or a\n"
    "folded form) for local flat-foldability with its mountain-valley assignment: Kawasaki\n"
    "(alternating sector sum 0, even degree), Maekawa (M - V = +-2), the generalised big-little-\n"
    "big rule, an exact test of the assignment (crimp reduction), and Hull's count C of valid\n"
    "assignments. F and J edges are ignored (their sectors merge); U creases count as free: a\n"
    "vertex passes when some choice of M/V for them folds flat. A vertex whose sectors do not\n"
    "sum to 360 degrees is a cone. Prints a table and every broken rule, then a verdict. Exit\n"
    "0 when every interior vertex is locally flat-foldable, 1 when not, 3 for an invalid file.\n"
    "\n"
    "Drawings from other tools carry rounded coordinates. With --tolerance DEG a vertex that\n"
    "misses Kawasaki, the 360 degree sum or an equality of sectors by at most DEG is checked as\n"
    "the exact vertex it means (its sectors snapped, least squares) and reported \"within\n"
    "tolerance\" with its deviation. Without it, check says when every failure is below 0.01\n"
    "degree and suggests --tolerance or 'orikin regularize'.\n"
    "\n"
    "options:\n"
    "  --tolerance DEG  accept vertices within DEG degrees of an exact flat-foldable one\n"
    "              (0 to 1; default 0: exact up to rounding)\n"
    "  --json      print {\"file\", \"frame\", \"locally_flat_foldable\", \"interior_vertices\",\n"
    "              \"failed_vertices\", \"vertices\": [{\"vertex\", \"degree\", \"creases\",\n"
    "              \"assignment\", \"sectors_deg\", \"sector_sum_deg\", \"kawasaki\", \"maekawa\",\n"
    "              \"big_little_big\", \"mv_count\", \"assignment_valid\", \"cone\",\n"
    "              \"flat_foldable\", \"within_tolerance\", \"deviation_deg\"}], \"violations\":\n"
    "              [{\"vertex\", \"rule\", \"edge\", \"detail\"}], \"tolerance_deg\",\n"
    "              \"within_tolerance_vertices\", \"max_deviation_deg\", \"rounding_failures\", \"hint\"}\n"
    "              (see docs/verification.md)\n"
    "\n"
    "input options (a drawing is read with the default weld tolerance: use 'orikin convert\n"
    "--tolerance REL' first to choose another):\n"
    CLI_INPUT_HELP_FOLD CLI_INPUT_HELP_DRAWING
    "\n"
    "example: orikin check examples/patterns/degree4-vertex.fold\n",
    run,
    NULL,
};
