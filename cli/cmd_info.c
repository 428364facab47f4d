// orikin info: what a FOLD file holds.
#include <string.h>

#include "cli.h"

static int run(int argc, char **argv)
{
    const char *path = NULL;
    int frame = 0;
    bool json = false;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--json") == 0) json = true;
        else if (strcmp(argv[i], "--frame") == 0) {
            if (cli_option_frame("info", argc, argv, &i, &frame) != CLI_EXIT_OK) return CLI_EXIT_USAGE;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') return cli_usage("info", "unknown option %s", argv[i]);
        else if (!path) path = argv[i];
        else return cli_usage("info", "one FILE only");
    }
    if (!path) return cli_usage("info", "missing FILE");
    ori_fold *doc;
    ori_pattern *p;
    int rc = cli_load_pattern("info", path, frame, false, &doc, &p);
    if (rc != CLI_EXIT_OK) return rc;
    int counts[ORI_ASSIGN_COUNT];
    for (int a = 0; a < ORI_ASSIGN_COUNT; ++a) counts[a] = ori_pattern_count_assignment(p, (ori_assignment)a);
    int dim = ori_pattern_is_3d(p) ? 3 : 2;
    if (json) {
        json_t *by = json_object();
        for (int a = 0; a < ORI_ASSIGN_COUNT; ++a) {
            char key[2] = {ori_assignment_to_char((ori_assignment)a), '\0'};
            json_object_set_new(by, key, json_integer(counts[a]));
        }
        json_t *out = json_object();
        json_object_set_new(out, "file", json_string(path));
        json_object_set_new(out, "frame", json_integer(frame));
        json_object_set_new(out, "frames", json_integer(ori_fold_frame_count(doc)));
        json_object_set_new(out, "vertices", json_integer(ori_pattern_vertex_count(p)));
        json_object_set_new(out, "edges", json_integer(ori_pattern_edge_count(p)));
        json_object_set_new(out, "edges_by_assignment", by);
        json_object_set_new(out, "faces", json_integer(ori_pattern_face_count(p)));
        json_object_set_new(out, "interior_vertices", json_integer(ori_pattern_interior_vertex_count(p)));
        json_object_set_new(out, "dimension", json_integer(dim));
        json_object_set_new(out, "folded_form", json_boolean(ori_pattern_is_folded_form(p)));
        cli_print_json(out);
    } else {
        printf("file               %s\n", path);
        printf("frame              %d of %d\n", frame, ori_fold_frame_count(doc));
        printf("kind               %s, %dD\n", ori_pattern_is_folded_form(p) ? "folded form" : "crease pattern", dim);
        printf("vertices           %d (%d interior)\n", ori_pattern_vertex_count(p), ori_pattern_interior_vertex_count(p));
        printf("edges              %d:", ori_pattern_edge_count(p));
        for (int a = 0; a < ORI_ASSIGN_COUNT; ++a)
            if (counts[a]) printf(" %c %d", ori_assignment_to_char((ori_assignment)a), counts[a]);
        printf("\n");
        printf("faces              %d\n", ori_pattern_face_count(p));
    }
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    return CLI_EXIT_OK;
}

const cli_command cli_cmd_info = {
    "info",
    "counts of vertices, edges by assignment, faces and frames of a FOLD file",
    "usage: orikin info FILE [--frame N] [--json]\n"
    "\n"
    "Load a FOLD file (validating it) and print what it holds: vertices (and how many are\n"
    "interior), edges by assignment (B M V F U C J), faces, frames, and whether the frame is\n"
    "a flat crease pattern or a folded form in 2D or 3D.\n"
    "\n"
    "options:\n"
    "  --frame N   frame to read (0 = top level, k = file_frames[k-1]); default 0\n"
    "  --json      print {\"file\", \"frame\", \"frames\", \"vertices\", \"edges\",\n"
    "              \"edges_by_assignment\", \"faces\", \"interior_vertices\", \"dimension\",\n"
    "              \"folded_form\"}\n"
    "\n"
    "example: orikin info examples/patterns/open-corner.fold\n",
    run,
};
