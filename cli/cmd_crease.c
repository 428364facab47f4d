// orikin crease: a crease from an axiom (or a line) applied to a face or to the whole sheet.
#include <string.h>

#include <orikin/authoring.h>

#include "axiom_args.h"
#include "kin_args.h"
#include "report.h"

static int run(int argc, char **argv)
{
    const char *path = NULL, *face_spec = NULL, *out = NULL;
    ori_axiom_input in;
    memset(&in, 0, sizeof in);
    int given = 0, solution = 0;
    bool all = false, have_axiom = false, have_line = false, have_solution = false, json = false;
    double line[4] = {0, 0, 0, 0};
    ori_assignment asg = ORI_ASSIGN_UNASSIGNED;
    cli_input input;
    cli_input_init(&input);
    cli_seen seen = {0};
    for (int i = 1; i < argc; ++i) {
        int r = axiom_parse_option("crease", argc, argv, &i, &in, &given);
        if (r < 0) return -r;
        if (r == 1) continue;
        r = cli_input_option("crease", argc, argv, &i, &input, &seen);
        if (r < 0) return -r;
        if (r > 0) continue;
        const char *v;
        if (strcmp(argv[i], "--axiom") == 0) {
            if (!(v = cli_option_once("crease", argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (!cli_parse_int(v, &in.axiom) || in.axiom < 1 || in.axiom > 7)
                return cli_usage("crease", "--axiom takes a number from 1 to 7");
            have_axiom = true;
        } else if (strcmp(argv[i], "--line") == 0) {
            if (!(v = cli_option_once("crease", argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (!cli_parse_doubles(v, line, 4)) return cli_usage("crease", "--line needs x1,y1,x2,y2");
            have_line = true;
        } else if (strcmp(argv[i], "--solution") == 0) {
            if (!(v = cli_option_once("crease", argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (!cli_parse_int(v, &solution)) return cli_usage("crease", "--solution takes a number (1, 2, 3)");
            have_solution = true;
        } else if (strcmp(argv[i], "--face") == 0) {
            if (!(face_spec = cli_option_once("crease", argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--all") == 0) {
            all = true;
        } else if (strcmp(argv[i], "--assign") == 0) {
            if (!(v = cli_option_once("crease", argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (!cli_parse_crease_assignment(v, &asg)) return cli_usage("crease", "--assign takes M, V, F or U");
        } else if (strcmp(argv[i], "-o") == 0 || strcmp(argv[i], "--output") == 0) {
            if (!(out = cli_option_once("crease", argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--json") == 0) {
            json = true;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            return cli_usage("crease", "unknown option %s", argv[i]);
        } else if (!path) {
            path = argv[i];
        } else {
            return cli_usage("crease", "one FILE only");
        }
    }
    if (!path) return cli_usage("crease", "missing FILE");
    if (have_axiom == have_line) return cli_usage("crease", "give either --axiom N (with its inputs) or --line x1,y1,x2,y2");
    if (have_line && (given || have_solution)) return cli_usage("crease", "--line takes no other axiom inputs");
    if (have_axiom) {
        int rc = axiom_check_inputs("crease", &in, given);
        if (rc != CLI_EXIT_OK) return rc;
    }
    if (all == (face_spec != NULL)) return cli_usage("crease", "give either --face NAME or --all");
    int rc0 = cli_check_json_output("crease", out, json);
    if (rc0 != CLI_EXIT_OK) return rc0;

    ori_crease c;
    c.infinite = true;
    c.assignment = asg;
    c.fold_angle_rad = 0.0;
    char what[64];
    if (have_line) {
        c.a = ori_v2_make(line[0], line[1]);
        c.b = ori_v2_make(line[2], line[3]);
        snprintf(what, sizeof what, "the line");
    } else {
        // The axiom's inputs are the command line's: no solution, several, or a --solution beyond
        // them are usage errors naming the option.
        ori_line_set s = ori_axiom_solve(&in);
        if (s.count == 0)
            return cli_value_fail("crease", NULL, "--axiom", "axiom %d (%s) has no solution for these inputs", in.axiom,
                                  axiom_summary(in.axiom));
        if (!have_solution && s.count > 1) {
            fprintf(stderr, "orikin crease: --axiom %d has %d solutions here; choose one with --solution 1..%d:\n", in.axiom,
                    s.count, s.count);
            for (int k = 0; k < s.count; ++k)
                fprintf(stderr, "  %d  point (%.17g, %.17g)  dir (%.17g, %.17g)\n", k + 1, s.lines[k].point.x,
                        s.lines[k].point.y, s.lines[k].dir.x, s.lines[k].dir.y);
            return CLI_EXIT_USAGE;
        }
        if (!have_solution) solution = 1;
        char mistake[160];
        if (cli_axiom_solution_error(in.axiom, solution, s.count, mistake, sizeof mistake))
            return cli_value_fail("crease", NULL, "--solution", "%s", mistake);
        ori_line l = s.lines[solution - 1];
        c.a = l.point;
        c.b = ori_v2_add(l.point, l.dir);
        snprintf(what, sizeof what, "axiom %d solution %d", in.axiom, solution);
    }
    ori_fold *doc;
    ori_pattern *p;
    int rc = cli_input_load("crease", path, &input, &doc, &p);
    if (rc != CLI_EXIT_OK) return rc;
    int face = ORI_NULL_INDEX;
    if (face_spec) rc = cli_spec_face("crease", path, p, "--face", face_spec, &face);
    if (rc == CLI_EXIT_OK) {
        char target[ORI_NAME_MAX + 16];
        cli_face_label(p, face, target, sizeof target);
        ori_apply_result r;
        ori_error err;
        ori_status st = ori_pattern_apply_crease(p, &c, face, &r, &err);
        // The line misses the face or sheet, or --line's two points coincide (at the pattern's
        // tolerance): the command line's value, a usage error naming the option.
        if (st == ORI_ERR_NOT_FOUND || (st == ORI_ERR_DEGENERATE && have_line && err.field[0] == '\0'))
            rc = cli_value_fail("crease", path, have_line ? "--line" : "--axiom", "%s", err.message);
        else if (st != ORI_OK) rc = cli_input_error("crease", path, &err);
        else rc = cli_write_frame_pattern("crease", &doc, &input, p, out);
        if (rc == CLI_EXIT_OK && !cli_is_stdout(out)) {
            json_t *o = json_object();
            json_object_set_new(o, "output", json_string(out));
            json_object_set_new(o, "construction", json_string(what));
            json_object_set_new(o, "target", json_string(target));
            json_object_set_new(o, "segments", json_integer(r.segments));
            json_object_set_new(o, "faces_split", json_integer(r.faces_split));
            json_object_set_new(o, "first_edge", json_integer(r.first_edge));
            json_object_set_new(o, "last_edge", json_integer(ori_pattern_edge_count(p) - 1));
            cli_json_counts(o, p);
            cli_print_summary(json, o, "%s applied to %s: %d piece%s, %d face%s split, new edges %d to %d", what, target,
                              r.segments, r.segments == 1 ? "" : "s", r.faces_split, r.faces_split == 1 ? "" : "s",
                              r.first_edge, ori_pattern_edge_count(p) - 1);
        }
    }
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    return rc;
}

const cli_command cli_cmd_crease = {
    "crease",
    "apply a crease from an axiom (or a line) to a face or the whole sheet",
    "usage: orikin crease FILE (--axiom N [--p1 x,y] [--p2 x,y] [--l1 x,y,dx,dy] [--l2 …]\n"
    "                            [--solution K] | --line x1,y1,x2,y2)\n"
    "                      (--face NAME | --all) [--assign M|V|F|U] [input options]\n"
    "                      [-o OUT [--json]]\n"
    "\n"
    "Construct a fold line with Huzita-Hatori axiom N (see orikin axiom -h for the inputs) or\n"
    "through two points (--line, axiom 1 keeping your direction), clip it to the target face\n"
    "or to every face it crosses (--all), and insert it: each face it crosses splits in two\n"
    "like a perforation, ObjK into ObjK1 (left of the line's direction) and ObjK2. When the\n"
    "axiom has several solutions choose one with --solution K (1-based, in the order orikin\n"
    "axiom prints). New creases are unassigned (U) unless --assign says otherwise. Without -o\n"
    "the FOLD text goes to stdout; with -o a one-line summary is printed (--json: an object).\n"
    "\n"
    "options:\n"
    "  --axiom N             axiom 1-7 with its inputs --p1, --p2, --l1, --l2\n"
    "  --solution K          which solution (needed when there are several)\n"
    "  --line x1,y1,x2,y2    the line through two points instead of an axiom\n"
    "  --face NAME           the target face: its name (Obj12), FOLD face index or @x,y (the face\n"
    "                        containing the point)\n"
    "  --all                 every face the line crosses\n"
    "  --assign M|V|F|U      the new crease's assignment (default U)\n"
    "  -o, --output OUT      write the FOLD file here (atomically; .svg, .cp, .opx: export)\n"
    "  --json                with -o: print {output, construction, target, segments,\n"
    "                        faces_split, first_edge, last_edge, vertices, edges, faces,\n"
    "                        edges_by_assignment}\n" CLI_INPUT_HELP
    "\n"
    "exit codes: 0 written, 2 bad command line (no solution, K out of range, an unknown face,\n"
    "a line that misses the face), 3 bad file (nothing written)\n"
    "example: orikin crease sheet.fold --axiom 2 --p1 0,0 --p2 2,2 --face Obj1 --assign V -o d.fold\n",
    run,
    NULL,
};
