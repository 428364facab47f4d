// orikin edit: re-assign, flip, remove and move creases of a crease pattern.
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>

#include <orikin/authoring.h>

#include "cli.h"

enum op_kind { OP_ASSIGN, OP_FLIP, OP_REMOVE, OP_MOVE };

typedef struct op {
    enum op_kind kind;
    const char *edge; // "12" (index in the input file) or "@x,y" (the edge through a point)
    ori_assignment asg;
    double seg[4];
} op;

static const char *const op_names[] = {"--assign", "--flip", "--remove", "--move"};

// The current index of the edge an operation (option opt) names, or an exit code after an error
// message: an edge the file does not have is an out-of-range command-line value.
static int resolve(const char *path, const ori_pattern *p, const int *map, int n_orig, const char *opt, const char *spec,
                   int *edge)
{
    char where[96];
    snprintf(where, sizeof where, "%s %s", opt, spec);
    if (spec[0] == '@') {
        double xy[2];
        if (!cli_parse_doubles(spec + 1, xy, 2)) return cli_usage("edit", "an edge is an index or @x,y (got %s)", spec);
        int e = ori_pattern_find_edge_at(p, ori_v2_make(xy[0], xy[1]));
        if (e == ORI_NULL_INDEX)
            return cli_value_fail("edit", path, where, "no edge passes through (%g, %g) (see orikin info --edges)", xy[0], xy[1]);
        *edge = e;
        return CLI_EXIT_OK;
    }
    int id;
    if (!cli_parse_int(spec, &id)) return cli_usage("edit", "an edge is an index or @x,y (got %s)", spec);
    if (id < 0 || id >= n_orig)
        return cli_value_fail("edit", path, where, "no such edge (the file has %d edges: 0 to %d)", n_orig, n_orig - 1);
    if (map[id] == ORI_NULL_INDEX)
        return cli_value_fail("edit", path, where, "the edge was removed by an earlier operation");
    *edge = map[id];
    return CLI_EXIT_OK;
}

static void apply_removal(int *map, int n, const ori_remove_result *r)
{
    for (int i = 0; i < n; ++i) map[i] = ori_remove_result_map_edge(r, map[i]);
}

static const char *face_desc(const ori_pattern *p, int f, char *buf, size_t size)
{
    const char *name = f == ORI_NULL_INDEX ? NULL : ori_pattern_face_name(p, f);
    if (name) snprintf(buf, size, "%s", name);
    else snprintf(buf, size, "face %d", f);
    return buf;
}

static int run(int argc, char **argv)
{
    const char *path = NULL, *out = NULL;
    op *ops = calloc((size_t)argc, sizeof *ops);
    int nops = 0, rc = CLI_EXIT_OK;
    bool json = false;
    cli_input input;
    cli_input_init(&input);
    cli_seen seen = {0};
    for (int i = 1; i < argc && rc == CLI_EXIT_OK; ++i) {
        const char *v;
        op o;
        memset(&o, 0, sizeof o);
        int r = cli_input_option("edit", argc, argv, &i, &input, &seen);
        if (r != 0) {
            if (r < 0) rc = -r;
            continue;
        }
        if (strcmp(argv[i], "--json") == 0) {
            json = true;
            continue;
        }
        if (strcmp(argv[i], "--assign") == 0) {
            if (!(v = cli_option_value("edit", argc, argv, &i))) {
                rc = CLI_EXIT_USAGE;
                break;
            }
            const char *eq = strrchr(v, '=');
            if (!eq || eq == v || strlen(eq + 1) != 1 || !ori_assignment_from_char(eq[1], &o.asg)) {
                rc = cli_usage("edit", "--assign takes E=M, E=V, E=F or E=U (got %s)", v);
                break;
            }
            char *spec = malloc((size_t)(eq - v) + 1);
            memcpy(spec, v, (size_t)(eq - v));
            spec[eq - v] = '\0';
            o.kind = OP_ASSIGN;
            o.edge = spec;
        } else if (strcmp(argv[i], "--flip") == 0 || strcmp(argv[i], "--remove") == 0) {
            o.kind = argv[i][2] == 'f' ? OP_FLIP : OP_REMOVE;
            if (!(o.edge = cli_option_value("edit", argc, argv, &i))) rc = CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--move") == 0) {
            if (i + 2 >= argc) {
                rc = cli_usage("edit", "--move needs E x1,y1,x2,y2");
                break;
            }
            o.kind = OP_MOVE;
            o.edge = argv[i + 1];
            if (!cli_parse_doubles(argv[i + 2], o.seg, 4)) rc = cli_usage("edit", "--move needs E x1,y1,x2,y2");
            i += 2;
        } else if (strcmp(argv[i], "-o") == 0 || strcmp(argv[i], "--output") == 0) {
            if (!(out = cli_option_once("edit", argc, argv, &i, &seen))) rc = CLI_EXIT_USAGE;
            continue;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            rc = cli_usage("edit", "unknown option %s", argv[i]);
            continue;
        } else if (!path) {
            path = argv[i];
            continue;
        } else {
            rc = cli_usage("edit", "one FILE only");
            continue;
        }
        ops[nops++] = o;
    }
    if (rc == CLI_EXIT_OK && !path) rc = cli_usage("edit", "missing FILE");
    if (rc == CLI_EXIT_OK && nops == 0) rc = cli_usage("edit", "nothing to do: give --assign, --flip, --remove or --move");
    if (rc == CLI_EXIT_OK) rc = cli_check_json_output("edit", out, json);
    ori_fold *doc = NULL;
    ori_pattern *p = NULL;
    if (rc == CLI_EXIT_OK) rc = cli_input_load("edit", path, &input, &doc, &p);
    int n_orig = p ? ori_pattern_edge_count(p) : 0;
    int *map = malloc(sizeof(int) * (size_t)(n_orig + 1));
    for (int i = 0; i < n_orig; ++i) map[i] = i;
    char *log = NULL;
    size_t log_len = 0;
    FILE *logf = open_memstream(&log, &log_len);
    bool topology = false;
    json_t *log_json = json_array();
    for (int k = 0; k < nops && rc == CLI_EXIT_OK; ++k) {
        const op *o = &ops[k];
        int e = ORI_NULL_INDEX;
        rc = resolve(path, p, map, n_orig, op_names[o->kind], o->edge, &e);
        if (rc != CLI_EXIT_OK) break;
        ori_error err;
        ori_status st = ORI_OK;
        ori_edge before = ori_pattern_edge(p, e);
        // How the log names the edge: as given, with its current index when that differs.
        char label[96];
        int given_id;
        if (o->edge[0] == '@') snprintf(label, sizeof label, "edge %d (%s)", e, o->edge);
        else if (cli_parse_int(o->edge, &given_id) && given_id != e) snprintf(label, sizeof label, "edge %d (now %d)", given_id, e);
        else snprintf(label, sizeof label, "edge %d", e);
        char f0[ORI_NAME_MAX + 16], f1[ORI_NAME_MAX + 16], fm[ORI_NAME_MAX + 16];
        int faces[2];
        ori_pattern_edge_faces(p, e, faces);
        face_desc(p, faces[0], f0, sizeof f0);
        face_desc(p, faces[1], f1, sizeof f1);
        switch (o->kind) {
        case OP_ASSIGN:
            st = ori_pattern_assign_crease(p, e, o->asg, &err);
            if (st == ORI_OK)
                fprintf(logf, "%s: %c -> %c\n", label, ori_assignment_to_char(before.assignment),
                        ori_assignment_to_char(o->asg));
            break;
        case OP_FLIP:
            st = ori_pattern_flip_crease(p, e, &err);
            if (st == ORI_OK)
                fprintf(logf, "%s: %c -> %c (flipped)\n", label, ori_assignment_to_char(before.assignment),
                        ori_assignment_to_char(ori_pattern_edge(p, e).assignment));
            break;
        case OP_REMOVE: {
            ori_remove_result r;
            st = ori_pattern_remove_crease(p, e, &r, &err);
            if (st != ORI_OK) break;
            topology = true;
            apply_removal(map, n_orig, &r);
            int kept = r.kept_face == ORI_NULL_INDEX ? ORI_NULL_INDEX
                                                     : r.kept_face - (r.removed_face != ORI_NULL_INDEX && r.removed_face < r.kept_face);
            fprintf(logf, "removed %s", label);
            if (r.removed_face != ORI_NULL_INDEX)
                fprintf(logf, ": %s + %s -> %s%s", f0, f1, face_desc(p, kept, fm, sizeof fm),
                        r.name_restored ? " (name restored)" : "");
            if (r.removed_edge_count > 1) fprintf(logf, "; %d collinear edge pair(s) rejoined", r.removed_edge_count - 1);
            fprintf(logf, "; later edge indices shift down\n");
            break;
        }
        case OP_MOVE: {
            ori_remove_result r;
            ori_apply_result a;
            st = ori_pattern_move_crease(p, e, ori_v2_make(o->seg[0], o->seg[1]), ori_v2_make(o->seg[2], o->seg[3]), &r, &a,
                                         &err);
            if (st != ORI_OK) break;
            topology = true;
            apply_removal(map, n_orig, &r);
            fprintf(logf, "moved %s to (%g, %g)-(%g, %g): now edges %d to %d\n", label, o->seg[0], o->seg[1], o->seg[2],
                    o->seg[3], a.first_edge, ori_pattern_edge_count(p) - 1);
            break;
        }
        }
        if (st != ORI_OK) {
            // An edge the operation does not apply to (a boundary edge, a J edge) is the command
            // line's mistake (2); geometry the file cannot take is the file's (3).
            char buf[512];
            ori_error_format(&err, buf, sizeof buf);
            fprintf(stderr, "orikin edit: %s: %s %s: %s\n", path, op_names[o->kind], o->edge, buf);
            rc = st == ORI_ERR_ARGUMENT ? CLI_EXIT_USAGE : CLI_EXIT_INPUT;
        } else {
            fflush(logf);
            const char *last = log;
            for (const char *c = log; c && *c; ++c)
                if (c[0] == '\n' && c[1]) last = c + 1;
            json_t *entry = json_object();
            json_object_set_new(entry, "op", json_string(op_names[o->kind] + 2));
            json_object_set_new(entry, "edge", json_string(o->edge));
            json_object_set_new(entry, "edge_index", json_integer(e));
            json_object_set_new(entry, "text", json_stringn(last ? last : "", last ? strcspn(last, "\n") : 0));
            json_array_append_new(log_json, entry);
        }
    }
    fclose(logf);
    int dropped = 0;
    if (rc == CLI_EXIT_OK) {
        if (topology && ori_fold_frame_count(doc) > 1 && !input.frame_given) {
            dropped = ori_fold_frame_count(doc) - 1;
            fprintf(stderr, "orikin edit: note: dropped %d frame(s) (file_frames) that no longer match the pattern\n",
                    dropped);
            ori_fold_set_custom(doc, 0, "file_frames", NULL, NULL);
        }
        rc = cli_write_frame_pattern("edit", &doc, &input, p, out);
        if (rc == CLI_EXIT_OK && !cli_is_stdout(out)) {
            json_t *o = json_object();
            json_object_set_new(o, "output", json_string(out));
            json_object_set_new(o, "operations", json_incref(log_json));
            json_object_set_new(o, "dropped_frames", json_integer(dropped));
            cli_json_counts(o, p);
            if (json) cli_print_json(o);
            else {
                json_decref(o);
                fputs(log, stdout);
            }
        }
    }
    json_decref(log_json);
    free(log);
    for (int k = 0; k < nops; ++k)
        if (ops[k].kind == OP_ASSIGN) free((char *)ops[k].edge);
    free(ops);
    free(map);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    return rc;
}

const cli_command cli_cmd_edit = {
    "edit",
    "re-assign, flip, remove or move creases",
    "usage: orikin edit FILE (--assign E=M|V|F|U | --flip E | --remove E | --move E x1,y1,x2,y2)...\n"
    "                   [input options] [-o OUT [--json]]\n"
    "\n"
    "Edit the creases of a crease pattern, operations in the order given. An edge E is its\n"
    "index in FILE (operations track the renumbering of earlier removals) or @x,y, the edge\n"
    "through the point (x, y) at that moment. --flip turns a mountain into a valley and back\n"
    "(reversing the joint axis by the right-hand rule) and negates an explicit fold angle.\n"
    "--remove merges the two faces beside the crease; when they are the two halves ObjK1 and\n"
    "ObjK2 of one split, the merged face is ObjK again. A crossing the crease had split is\n"
    "rejoined. Removing renumbers the later edges (and vertices, faces). --move removes the\n"
    "crease and applies the segment x1,y1-x2,y2 (clipped to the sheet) with its assignment.\n"
    "Boundary edges cannot be edited. On any error nothing is written. Without -o the FOLD\n"
    "text goes to stdout; with -o a line per operation is printed (--json: an object).\n"
    "\n"
    "options:\n"
    "  --assign E=X          assign crease E: M mountain, V valley, F flat, U unassigned\n"
    "  --flip E              mountain <-> valley\n"
    "  --remove E            remove crease E\n"
    "  --move E x1,y1,x2,y2  move crease E onto this segment\n"
    "  -o, --output OUT      write the FOLD file here (atomically; .svg, .cp, .opx: export)\n"
    "  --json                with -o: print {output, operations: [{op, edge, edge_index, text}],\n"
    "                        dropped_frames, vertices, edges, faces, edges_by_assignment}\n" CLI_INPUT_HELP
    "\n"
    "exit codes: 0 written, 2 bad command line (an unknown edge, a boundary edge), 3 bad file\n"
    "example: orikin edit corner.fold --assign @0.5,1=M --flip 8 -o corner2.fold\n",
    run,
    NULL,
};
