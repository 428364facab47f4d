// orikin tree: the face tree (crease history) of a pattern; its leaves are the folding elements.
#include <string.h>

#include <orikin/authoring.h>

#include "cli.h"
#include "report.h"

static void print_node(const ori_pattern *p, int node, int depth)
{
    ori_tree_node n = ori_pattern_tree_node(p, node);
    int face = ori_pattern_find_face_by_name(p, n.name);
    int width = 24 - 2 * depth;
    if (width < 1) width = 1;
    if (face != ORI_NULL_INDEX) printf("%*s%-*s  face %d", 2 * depth, "", width, n.name, face);
    else if (ori_pattern_node_child_count(p, node) == 0) printf("%*s%-*s  (no face)", 2 * depth, "", width, n.name);
    else printf("%*s%s", 2 * depth, "", n.name);
    printf("\n");
    for (int i = 0; i < ori_pattern_tree_node_count(p); ++i)
        if (ori_pattern_tree_node(p, i).parent == node) print_node(p, i, depth + 1);
}

static int run(int argc, char **argv)
{
    const char *path = NULL;
    bool json = false;
    cli_input in;
    cli_input_init(&in);
    cli_seen seen = {0};
    for (int i = 1; i < argc; ++i) {
        int r = cli_input_option("tree", argc, argv, &i, &in, &seen);
        if (r < 0) return -r;
        if (r > 0) continue;
        if (strcmp(argv[i], "--json") == 0) json = true;
        else if (argv[i][0] == '-' && argv[i][1] != '\0') return cli_usage("tree", "unknown option %s", argv[i]);
        else if (!path) path = argv[i];
        else return cli_usage("tree", "one FILE only");
    }
    if (!path) return cli_usage("tree", "missing FILE");
    ori_fold *doc;
    ori_pattern *p;
    int rc = cli_input_load("tree", path, &in, &doc, &p);
    if (rc != CLI_EXIT_OK) return rc;
    int nodes = ori_pattern_tree_node_count(p), faces = ori_pattern_face_count(p);
    if (json) {
        json_t *out = cli_tree_json(path, p);
        cli_print_json(out);
    } else {
        if (nodes == 0) printf("no face tree (the file has no crease history)\n");
        for (int i = 0; i < nodes; ++i)
            if (ori_pattern_tree_node(p, i).parent == ORI_NULL_INDEX) print_node(p, i, 0);
        int outside = 0;
        for (int f = 0; f < faces; ++f)
            if (ori_pattern_face_node(p, f) == ORI_NULL_INDEX) outside++;
        if (outside > 0 && nodes > 0) printf("faces outside the tree:");
        if (outside > 0) {
            int shown = 0;
            for (int f = 0; f < faces && shown < 20; ++f)
                if (ori_pattern_face_node(p, f) == ORI_NULL_INDEX) {
                    const char *name = ori_pattern_face_name(p, f);
                    if (nodes > 0) printf(" %d%s%s%s", f, name ? " (" : "", name ? name : "", name ? ")" : "");
                    shown++;
                }
            if (nodes > 0) printf("%s\n", outside > shown ? " ..." : "");
        }
        printf("%d folding element%s (faces)\n", faces, faces == 1 ? "" : "s");
    }
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    return CLI_EXIT_OK;
}

const cli_command cli_cmd_tree = {
    "tree",
    "the face tree (crease history); its leaves are the folding elements",
    "usage: orikin tree FILE [input options] [--json]\n"
    "\n"
    "Print the face tree of a crease pattern: every crease applied to a face ObjK split it into\n"
    "ObjK1 (left of the crease's direction) and ObjK2 (right). The leaves are the folding\n"
    "elements, shown with their FOLD face index. Faces without a name (patterns imported from\n"
    "elsewhere) are listed after the tree.\n"
    "\n"
    "options:\n"
    "  --json             print {\"file\", \"nodes\": [{\"name\", \"parent\", \"children\", \"leaf\",\n"
    "                     \"face\"}], \"folding_elements\": [{\"face\", \"name\"}]}\n" CLI_INPUT_HELP
    "\n"
    "example: orikin tree examples/patterns/open-corner.fold\n",
    run,
    NULL,
};
