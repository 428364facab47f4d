// orikin apply: a pattern from the crease collection (built-in or a composite file) on a face.
#include <string.h>

#include <orikin/collection.h>

#include "cli.h"

static void list_builtins(void)
{
    for (int i = 0; i < ori_collection_builtin_count(); ++i)
        printf("%-16s %s\n", ori_collection_builtin_name(i), ori_collection_builtin_summary(i));
}

static void report(const ori_pattern *p, int node_before, const char *face_name, const ori_apply_result *r)
{
    printf("applied to %s: %d crease piece%s, %d face split%s, %d new edge%s (edges %d to %d)\n", face_name,
           r->segments, r->segments == 1 ? "" : "s", r->faces_split, r->faces_split == 1 ? "" : "s", r->edges_added,
           r->edges_added == 1 ? "" : "s", r->first_edge, ori_pattern_edge_count(p) - 1);
    int leaves = 0;
    for (int i = node_before; i < ori_pattern_tree_node_count(p); ++i) {
        ori_tree_node n = ori_pattern_tree_node(p, i);
        int f = ori_pattern_find_face_by_name(p, n.name);
        if (f == ORI_NULL_INDEX) continue;
        printf("%s %s (face %d)", leaves++ ? "," : "new folding elements:", n.name, f);
    }
    if (leaves) printf("\n");
}

static int run(int argc, char **argv)
{
    const char *path = NULL, *pattern = NULL, *face_spec = NULL, *out = NULL;
    bool has_asg = false;
    ori_assignment asg = ORI_ASSIGN_UNASSIGNED;
    for (int i = 1; i < argc; ++i) {
        const char *v;
        if (strcmp(argv[i], "--list") == 0) {
            list_builtins();
            return CLI_EXIT_OK;
        } else if (strcmp(argv[i], "--pattern") == 0) {
            if (!(pattern = cli_option_value("apply", argc, argv, &i))) return CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--face") == 0) {
            if (!(face_spec = cli_option_value("apply", argc, argv, &i))) return CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--assign") == 0) {
            if (!(v = cli_option_value("apply", argc, argv, &i))) return CLI_EXIT_USAGE;
            if (!cli_parse_crease_assignment(v, &asg)) return cli_usage("apply", "--assign takes M, V, F or U");
            has_asg = true;
        } else if (strcmp(argv[i], "-o") == 0 || strcmp(argv[i], "--output") == 0) {
            if (!(out = cli_option_value("apply", argc, argv, &i))) return CLI_EXIT_USAGE;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            return cli_usage("apply", "unknown option %s", argv[i]);
        } else if (!path) {
            path = argv[i];
        } else {
            return cli_usage("apply", "one FILE only");
        }
    }
    if (!path) return cli_usage("apply", "missing FILE");
    if (!pattern) return cli_usage("apply", "missing --pattern NAME|PATH.json (see orikin apply --list)");
    if (!face_spec) return cli_usage("apply", "missing --face NAME");
    ori_composite *comp = NULL;
    ori_error err;
    bool is_file = strchr(pattern, '/') || strchr(pattern, '.');
    ori_status st = is_file ? ori_composite_load_file(pattern, &comp, &err) : ori_composite_builtin(pattern, &comp, &err);
    if (st != ORI_OK) return cli_input_error("apply", pattern, &err);
    ori_fold *doc;
    ori_pattern *p;
    int rc = cli_load_pattern("apply", path, 0, false, &doc, &p);
    if (rc != CLI_EXIT_OK) {
        ori_composite_destroy(comp);
        return rc;
    }
    int face = 0;
    rc = cli_find_face("apply", path, p, face_spec, &face);
    if (rc == CLI_EXIT_OK) {
        char face_name[ORI_NAME_MAX + 16];
        const char *fname = ori_pattern_face_name(p, face);
        if (fname) snprintf(face_name, sizeof face_name, "%s", fname);
        else snprintf(face_name, sizeof face_name, "face %d", face);
        int nodes = ori_pattern_tree_node_count(p);
        ori_apply_result r;
        st = ori_pattern_apply_composite(p, comp, face, has_asg ? &asg : NULL, &r, &err);
        if (st != ORI_OK) rc = cli_input_error("apply", path, &err);
        else rc = cli_write_pattern("apply", doc, p, out);
        if (rc == CLI_EXIT_OK && out) report(p, nodes, face_name, &r);
    }
    ori_composite_destroy(comp);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    return rc;
}

const cli_command cli_cmd_apply = {
    "apply",
    "apply a pattern of the crease collection (built-in or composite file) to a face",
    "usage: orikin apply FILE --pattern NAME|PATH.json --face NAME [--assign M|V|F|U] [-o OUT]\n"
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
    "text goes to stdout; with -o a summary is printed.\n"
    "\n"
    "options:\n"
    "  --pattern NAME|PATH   a built-in name or a composite .json file\n"
    "  --face NAME           the target face: its name (Obj12) or FOLD face index\n"
    "  --assign M|V|F|U      assignment of every new crease (overrides the composite's)\n"
    "  -o, --output OUT      write the FOLD file here (atomically)\n"
    "  --list                list the built-in patterns\n"
    "\n"
    "exit codes: 0 applied, 2 bad command line, 3 bad file, unknown face or pattern, crease\n"
    "misses the face (nothing written)\n"
    "example: orikin apply sheet.fold --pattern middle-h --face Obj1 --assign V -o step1.fold\n",
    run,
};
