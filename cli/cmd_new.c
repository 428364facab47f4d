// orikin new: a blank sheet (square, rectangle or simple polygon) with one face, Obj1.
#include <stdlib.h>
#include <string.h>

#include <orikin/authoring.h>

#include "cli.h"

// Comma-separated numbers; returns the count or -1.
static int parse_list(const char *s, double *out, int cap)
{
    int n = 0;
    const char *p = s;
    while (*p) {
        const char *comma = strchr(p, ',');
        size_t len = comma ? (size_t)(comma - p) : strlen(p);
        char buf[64];
        if (len == 0 || len >= sizeof buf || n >= cap) return -1;
        memcpy(buf, p, len);
        buf[len] = '\0';
        if (!cli_parse_double(buf, &out[n++])) return -1;
        if (!comma) break;
        p = comma + 1;
        if (!*p) return -1;
    }
    return n;
}

static int run(int argc, char **argv)
{
    const char *out = NULL, *title = NULL, *description = NULL;
    int kinds = 0;
    double w = 0.0, h = 0.0;
    double *poly = NULL;
    int ncoords = 0;
    int rc = CLI_EXIT_OK;
    bool json = false;
    cli_seen seen = {0};
    for (int i = 1; i < argc && rc == CLI_EXIT_OK; ++i) {
        const char *v;
        if (strcmp(argv[i], "--square") == 0) {
            if (!(v = cli_option_once("new", argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (!cli_parse_double(v, &w)) return cli_usage("new", "--square needs a side length");
            h = w;
            kinds++;
        } else if (strcmp(argv[i], "--rect") == 0) {
            if (!cli_once("new", &seen, argv[i])) return CLI_EXIT_USAGE;
            if (i + 2 >= argc) return cli_usage("new", "--rect needs a width and a height");
            if (!cli_parse_double(argv[i + 1], &w) || !cli_parse_double(argv[i + 2], &h))
                return cli_usage("new", "--rect needs two numbers W H");
            i += 2;
            kinds++;
        } else if (strcmp(argv[i], "--polygon") == 0) {
            if (!(v = cli_option_once("new", argc, argv, &i, &seen))) {
                free(poly);
                return CLI_EXIT_USAGE;
            }
            free(poly);
            size_t cap = strlen(v) / 2 + 2;
            poly = malloc(sizeof(double) * cap);
            ncoords = parse_list(v, poly, (int)cap);
            if (ncoords < 0 || ncoords % 2 != 0)
                rc = cli_usage("new", "--polygon needs x1,y1,x2,y2,... (an even count of numbers)");
            kinds++;
        } else if (strcmp(argv[i], "-o") == 0 || strcmp(argv[i], "--output") == 0) {
            if (!(out = cli_option_once("new", argc, argv, &i, &seen))) rc = CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--title") == 0) {
            if (!(title = cli_option_once("new", argc, argv, &i, &seen))) rc = CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--description") == 0) {
            if (!(description = cli_option_once("new", argc, argv, &i, &seen))) rc = CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--json") == 0) {
            json = true;
        } else {
            rc = cli_usage("new", "unknown argument %s", argv[i]);
        }
    }
    if (rc == CLI_EXIT_OK && kinds != 1) rc = cli_usage("new", "give exactly one of --square, --rect, --polygon");
    if (rc == CLI_EXIT_OK) rc = cli_check_json_output("new", out, json);
    if (rc != CLI_EXIT_OK) {
        free(poly);
        return rc;
    }
    ori_v2 *pts;
    int n;
    const char *what = "--polygon";
    if (poly) {
        n = ncoords / 2;
        pts = malloc(sizeof *pts * (size_t)(n ? n : 1));
        for (int k = 0; k < n; ++k) pts[k] = ori_v2_make(poly[2 * k], poly[2 * k + 1]);
        free(poly);
    } else {
        what = w == h ? "--square" : "--rect";
        if (!(w > 0.0) || !(h > 0.0)) return cli_value_fail("new", NULL, what, "the sheet's sides must be positive");
        n = 4;
        pts = malloc(sizeof *pts * 4);
        pts[0] = ori_v2_make(0, 0);
        pts[1] = ori_v2_make(w, 0);
        pts[2] = ori_v2_make(w, h);
        pts[3] = ori_v2_make(0, h);
    }
    ori_pattern *p;
    ori_error err;
    ori_status st = ori_pattern_create_sheet(pts, n, &p, &err);
    free(pts);
    if (st != ORI_OK) { // the values given are the sheet: a usage error naming the option
        char buf[400];
        return cli_value_fail("new", NULL, what, "%s", ori_error_format(&err, buf, sizeof buf));
    }
    ori_fold *doc = ori_fold_create();
    if (title) ori_fold_set_string(doc, 0, "file_title", title);
    if (description) ori_fold_set_string(doc, 0, "file_description", description);
    ori_fold_set_custom(doc, 0, "frame_classes", "[\"creasePattern\"]", NULL);
    rc = cli_write_pattern("new", doc, p, out);
    if (rc == CLI_EXIT_OK && !cli_is_stdout(out)) {
        json_t *o = json_object();
        json_object_set_new(o, "output", json_string(out));
        cli_json_counts(o, p);
        json_object_set_new(o, "face", json_string("Obj1"));
        cli_print_summary(json, o, "%s: a sheet of %d corners, one face Obj1", out, ori_pattern_vertex_count(p));
    }
    ori_fold_destroy(doc);
    ori_pattern_destroy(p);
    return rc;
}

const cli_command cli_cmd_new = {
    "new",
    "a blank sheet: square, rectangle or simple polygon, one face Obj1",
    "usage: orikin new (--square S | --rect W H | --polygon x1,y1,x2,y2,...) [--title T]\n"
    "                  [--description D] [-o OUT.fold [--json]]\n"
    "\n"
    "Create an uncreased sheet: its corners as vertices, its sides as boundary edges (B), and\n"
    "one face named Obj1, the root of the face tree that crease commands grow (Obj1 -> Obj11,\n"
    "Obj12 -> ...). A square is [0,S]x[0,S], a rectangle [0,W]x[0,H]; a polygon must be simple\n"
    "(either orientation; it is stored counter-clockwise, first corner first). Without -o the\n"
    "FOLD text goes to stdout; with -o a one-line summary is printed (--json: an object).\n"
    "\n"
    "options:\n"
    "  --square S                 square sheet of side S > 0\n"
    "  --rect W H                 rectangular sheet W wide, H high\n"
    "  --polygon x1,y1,x2,y2,...  sheet bounded by this simple polygon (at least 3 corners)\n"
    "  --title T                  file_title of the FOLD file\n"
    "  --description D            file_description of the FOLD file\n"
    "  -o, --output OUT.fold      write here (atomically) instead of stdout (.svg, .cp, .opx:\n"
    "                             export in that format)\n"
    "  --json                     with -o: print {output, vertices, edges, faces,\n"
    "                             edges_by_assignment, face}\n"
    "\n"
    "exit codes: 0 written, 2 bad command line (a degenerate or non-simple sheet too)\n"
    "example: orikin new --square 2 -o sheet.fold\n",
    run,
    NULL,
};
