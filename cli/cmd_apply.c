// orikin apply: a pattern from the crease collection (built-in or a composite file) on a face.
#include <stdlib.h>
#include <string.h>

#include <orikin/collection.h>

#include "cli.h"
#include "report.h"
#include "kin_args.h"

static void list_builtins(void)
{
    for (int i = 0; i < ori_collection_builtin_count(); ++i)
        printf("%-16s %s\n", ori_collection_builtin_name(i), ori_collection_builtin_summary(i));
}

// The summary: text line(s) or one JSON object.
static void report(bool json, const char *out, const ori_pattern *p, int node_before, const char *face_name,
                   const char *pattern, const ori_apply_result *r)
{
    json_t *o = json_object(), *leaves = cli_apply_new_faces_json(p, node_before);
    // The text line names the first few new faces and counts the rest (--json lists them all):
    // 512 random creases make 90,000 faces, which no line should spell out.
    enum { SHOWN = 8 };
    char names[1024] = "";
    size_t len = 0, count = json_array_size(leaves);
    for (size_t i = 0; i < count && i < SHOWN; ++i) {
        json_t *leaf = json_array_get(leaves, i);
        len += (size_t)snprintf(names + len, sizeof names - len, "%s%.60s (face %d)",
                                len ? ", " : "; new folding elements: ", json_string_value(json_object_get(leaf, "name")),
                                (int)json_integer_value(json_object_get(leaf, "face")));
    }
    if (count > SHOWN)
        snprintf(names + len, sizeof names - len, " and %zu more (--json lists them all)", count - SHOWN);
    json_object_set_new(o, "output", json_string(out));
    json_object_set_new(o, "pattern", json_string(pattern));
    json_object_set_new(o, "face", json_string(face_name));
    cli_apply_counts_json(o, r);
    json_object_set_new(o, "last_edge", json_integer(ori_pattern_edge_count(p) - 1));
    json_object_set_new(o, "new_faces", leaves);
    cli_json_counts(o, p);
    cli_print_summary(json, o, "applied to %s: %d crease piece%s, %d face split%s, %d new edge%s (edges %d to %d)%s",
                      face_name, r->segments, r->segments == 1 ? "" : "s", r->faces_split, r->faces_split == 1 ? "" : "s",
                      r->edges_added, r->edges_added == 1 ? "" : "s", r->first_edge, ori_pattern_edge_count(p) - 1, names);
}

static int run(int argc, char **argv)
{
    const char *cmd = "apply", *path = NULL, *pattern = NULL, *face_spec = NULL, *out = NULL;
    bool has_asg = false, json = false;
    ori_assignment asg = ORI_ASSIGN_UNASSIGNED;
    cli_input in;
    cli_input_init(&in);
    cli_seen seen = {0};
    for (int i = 1; i < argc; ++i) {
        const char *v;
        int r = cli_input_option(cmd, argc, argv, &i, &in, &seen);
        if (r < 0) return -r;
        if (r > 0) continue;
        if (strcmp(argv[i], "--list") == 0) {
            list_builtins();
            return CLI_EXIT_OK;
        } else if (strcmp(argv[i], "--pattern") == 0) {
            if (!(pattern = cli_option_once(cmd, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--face") == 0) {
            if (!(face_spec = cli_option_once(cmd, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--assign") == 0) {
            if (!(v = cli_option_once(cmd, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (!cli_parse_crease_assignment(v, &asg)) return cli_usage(cmd, "--assign takes M, V, F or U");
            has_asg = true;
        } else if (strcmp(argv[i], "-o") == 0 || strcmp(argv[i], "--output") == 0) {
            if (!(out = cli_option_once(cmd, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--json") == 0) {
            json = true;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            return cli_usage(cmd, "unknown option %s", argv[i]);
        } else if (!path) {
            path = argv[i];
        } else {
            return cli_usage(cmd, "one FILE only");
        }
    }
    if (!path) return cli_usage(cmd, "missing FILE");
    if (!pattern) return cli_usage(cmd, "missing --pattern NAME|PATH.json (see orikin apply --list)");
    if (!face_spec) return cli_usage(cmd, "missing --face NAME");
    int rc = cli_check_json_output(cmd, out, json);
    if (rc != CLI_EXIT_OK) return rc;
    ori_composite *comp = NULL;
    ori_error err;
    bool is_file = strchr(pattern, '/') || strchr(pattern, '.');
    ori_status st = is_file ? ori_composite_load_file(pattern, &comp, &err) : ori_composite_builtin(pattern, &comp, &err);
    if (st != ORI_OK && !is_file) { // a name that is no built-in: the option's value
        char buf[400];
        return cli_value_fail(cmd, NULL, "--pattern", "%s", ori_error_format(&err, buf, sizeof buf));
    }
    if (st != ORI_OK) return cli_input_error(cmd, pattern, &err);
    ori_fold *doc;
    ori_pattern *p;
    rc = cli_input_load(cmd, path, &in, &doc, &p);
    if (rc != CLI_EXIT_OK) {
        ori_composite_destroy(comp);
        return rc;
    }
    int face = 0;
    rc = cli_spec_face(cmd, path, p, "--face", face_spec, &face);
    if (rc == CLI_EXIT_OK) {
        char face_name[ORI_NAME_MAX + 16];
        cli_face_label(p, face, face_name, sizeof face_name);
        int nodes = ori_pattern_tree_node_count(p);
        ori_apply_result r;
        st = ori_pattern_apply_composite(p, comp, face, has_asg ? &asg : NULL, &r, &err);
        if (st == ORI_ERR_NOT_FOUND) rc = cli_value_fail(cmd, path, "--face", "%s", err.message); // misses the face
        else if (st != ORI_OK) rc = cli_input_error(cmd, path, &err);
        else rc = cli_write_frame_pattern(cmd, &doc, &in, p, out);
        if (rc == CLI_EXIT_OK && !cli_is_stdout(out)) report(json, out, p, nodes, face_name, pattern, &r);
    }
    ori_composite_destroy(comp);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    return rc;
}

const cli_command cli_cmd_apply = {
    "apply",
    "apply a pattern of the crease collection (built-in or composite file) to a face",
    "usage: orikin apply FILE --pattern NAME|PATH.json --face NAME [--assign M|V|F|U]\n"
    "                    [input options] [-o OUT [--json]]\n"
    "       orikin apply --list\n"
    "\n"
    "Apply a reusable crease pattern to one face, scaled to the face's bounding box (0,0 its\n"
    "lower-left, 1,1 its upper-right corner). Built-ins (the thesis' toolbar): diagonal-left\n"
    "(DiagonalL, lower-left to upper-right corner), diagonal-right (DiagonalR, lower-right to\n"
    "upper-left), middle-h (MiddleH, horizontal, left to right), middle-v (MiddleV, vertical,\n"
    "bottom to top), cross, diagonals. A composite file is JSON listing creases in normalised\n"
    "coordinates (docs/authoring.md). Each crease splits the faces it crosses within the target\n"
    "face's region: ObjK becomes ObjK1 (left of the crease's direction) and ObjK2. New creases\n"
    "are unassigned (U) unless the composite or --assign says otherwise. Without -o the FOLD\n"
    "text goes to stdout; with -o a one-line summary is printed (--json: an object).\n"
    "\n"
    "options:\n"
    "  --pattern NAME|PATH   a built-in name or a composite .json file\n"
    "  --face NAME           the target face: its name (Obj12), FOLD face index or @x,y (the face\n"
    "                        containing the point)\n"
    "  --assign M|V|F|U      assignment of every new crease (overrides the composite's)\n"
    "  -o, --output OUT      write the FOLD file here (atomically; .svg, .cp, .opx: export)\n"
    "  --json                with -o: print {output, pattern, face, segments, faces_split,\n"
    "                        edges_added, first_edge, last_edge, new_faces: [{name, face}],\n"
    "                        vertices, edges, faces, edges_by_assignment}\n"
    "  --list                list the built-in patterns\n" CLI_INPUT_HELP
    "\n"
    "exit codes: 0 applied, 2 bad command line (an unknown built-in or face, a pattern that\n"
    "misses the face), 3 bad file or composite (nothing written)\n"
    "example: orikin apply sheet.fold --pattern middle-h --face Obj1 --assign V -o step1.fold\n",
    run,
    NULL,
};
