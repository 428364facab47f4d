// orikin info: what a pattern file holds, and (--faces, --edges) every face and edge with its
// name, assignment, length, centroid or end points: how to find the index a command needs.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "report.h"

// A point as JSON [x, y] (or [x, y, z] for a 3D pattern).
static json_t *point_json(ori_v3 x, bool three)
{
    json_t *a = json_array();
    json_array_append_new(a, json_real(x.x));
    json_array_append_new(a, json_real(x.y));
    if (three) json_array_append_new(a, json_real(x.z));
    return a;
}

static void print_point(ori_v3 x, bool three)
{
    if (three) printf("(%.6g, %.6g, %.6g)", x.x, x.y, x.z);
    else printf("(%.6g, %.6g)", x.x, x.y);
}

// Centroid of a face's corners and its area (the polygon's, from its projection on the plane it
// spans: the length of the vector area).
static void face_shape(const ori_pattern *p, int f, int *buf, ori_v3 *centroid, double *area)
{
    int n = ori_pattern_face_vertices(p, f, buf, ori_pattern_face_size(p, f));
    ori_v3 c = {0, 0, 0}, s = {0, 0, 0};
    for (int k = 0; k < n; ++k) c = ori_v3_add(c, ori_pattern_vertex(p, buf[k]));
    c = ori_v3_scale(c, 1.0 / n);
    for (int k = 0; k < n; ++k)
        s = ori_v3_add(s, ori_v3_cross(ori_v3_sub(ori_pattern_vertex(p, buf[k]), c),
                                       ori_v3_sub(ori_pattern_vertex(p, buf[(k + 1) % n]), c)));
    *centroid = c;
    *area = 0.5 * ori_v3_norm(s);
}

static json_t *faces_json(const ori_pattern *p, bool three)
{
    json_t *arr = json_array();
    int max = 0;
    for (int f = 0; f < ori_pattern_face_count(p); ++f) max = ori_pattern_face_size(p, f) > max ? ori_pattern_face_size(p, f) : max;
    int *buf = malloc(sizeof(int) * (size_t)(max + 1));
    for (int f = 0; f < ori_pattern_face_count(p); ++f) {
        ori_v3 c;
        double area;
        face_shape(p, f, buf, &c, &area);
        json_t *o = json_object(), *vs = json_array();
        for (int k = 0; k < ori_pattern_face_size(p, f); ++k) json_array_append_new(vs, json_integer(buf[k]));
        const char *name = ori_pattern_face_name(p, f);
        json_object_set_new(o, "face", json_integer(f));
        json_object_set_new(o, "name", name ? json_string(name) : json_null());
        json_object_set_new(o, "vertices", vs);
        json_object_set_new(o, "area", json_real(area));
        json_object_set_new(o, "centroid", point_json(c, three));
        json_array_append_new(arr, o);
    }
    free(buf);
    return arr;
}

static json_t *edges_json(const ori_pattern *p, bool three)
{
    json_t *arr = json_array();
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        ori_v3 a = ori_pattern_vertex(p, ed.v[0]), b = ori_pattern_vertex(p, ed.v[1]);
        int faces[2];
        ori_pattern_edge_faces(p, e, faces);
        char asg[2] = {ori_assignment_to_char(ed.assignment), '\0'};
        json_t *o = json_object(), *fs = json_array();
        for (int k = 0; k < 2; ++k) json_array_append_new(fs, faces[k] >= 0 ? json_integer(faces[k]) : json_null());
        json_object_set_new(o, "edge", json_integer(e));
        json_object_set_new(o, "assignment", json_string(asg));
        json_object_set_new(o, "fold_angle_deg", json_real(ori_rad_to_deg_output(ed.fold_angle_rad)));
        json_object_set_new(o, "length", json_real(ori_v3_norm(ori_v3_sub(b, a))));
        json_object_set_new(o, "vertices", json_pack("[ii]", ed.v[0], ed.v[1]));
        json_object_set_new(o, "from", point_json(a, three));
        json_object_set_new(o, "to", point_json(b, three));
        json_object_set_new(o, "faces", fs);
        json_array_append_new(arr, o);
    }
    return arr;
}

static void print_faces(const ori_pattern *p, bool three)
{
    int max = 0;
    for (int f = 0; f < ori_pattern_face_count(p); ++f) max = ori_pattern_face_size(p, f) > max ? ori_pattern_face_size(p, f) : max;
    int *buf = malloc(sizeof(int) * (size_t)(max + 1));
    printf("face  name                vertices  area          centroid\n");
    for (int f = 0; f < ori_pattern_face_count(p); ++f) {
        ori_v3 c;
        double area;
        face_shape(p, f, buf, &c, &area);
        const char *name = ori_pattern_face_name(p, f);
        printf("%-5d %-19s %-9d %-13.6g ", f, name ? name : "-", ori_pattern_face_size(p, f), area);
        print_point(c, three);
        printf("\n");
    }
    free(buf);
}

static void print_edges(const ori_pattern *p, bool three)
{
    printf("edge  asg  angle     length        vertices      from -> to\n");
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        ori_v3 a = ori_pattern_vertex(p, ed.v[0]), b = ori_pattern_vertex(p, ed.v[1]);
        char verts[32];
        snprintf(verts, sizeof verts, "%d-%d", ed.v[0], ed.v[1]);
        printf("%-5d %-4c %-9.6g %-13.6g %-13s ", e, ori_assignment_to_char(ed.assignment),
               ori_rad_to_deg_output(ed.fold_angle_rad), ori_v3_norm(ori_v3_sub(b, a)), verts);
        print_point(a, three);
        printf(" -> ");
        print_point(b, three);
        printf("\n");
    }
}

static int run(int argc, char **argv)
{
    const char *cmd = "info", *path = NULL;
    bool json = false, faces = false, edges = false;
    cli_input in;
    cli_input_init(&in);
    cli_seen seen = {0};
    for (int i = 1; i < argc; ++i) {
        int r = cli_input_option(cmd, argc, argv, &i, &in, &seen);
        if (r < 0) return -r;
        if (r > 0) continue;
        if (strcmp(argv[i], "--json") == 0) json = true;
        else if (strcmp(argv[i], "--faces") == 0) faces = true;
        else if (strcmp(argv[i], "--edges") == 0) edges = true;
        else if (argv[i][0] == '-' && argv[i][1] != '\0') return cli_usage(cmd, "unknown option %s", argv[i]);
        else if (!path) path = argv[i];
        else return cli_usage(cmd, "one FILE only");
    }
    if (!path) return cli_usage(cmd, "missing FILE");
    ori_fold *doc;
    ori_pattern *p;
    int rc = cli_input_load(cmd, path, &in, &doc, &p);
    if (rc != CLI_EXIT_OK) return rc;
    int counts[ORI_ASSIGN_COUNT];
    for (int a = 0; a < ORI_ASSIGN_COUNT; ++a) counts[a] = ori_pattern_count_assignment(p, (ori_assignment)a);
    bool three = ori_pattern_is_3d(p);
    int dim = three ? 3 : 2;
    if (json) {
        json_t *out = cli_info_json(path, in.frame, ori_fold_frame_count(doc), p);
        if (faces) json_object_set_new(out, "face_list", faces_json(p, three));
        if (edges) json_object_set_new(out, "edge_list", edges_json(p, three));
        cli_print_json(out);
    } else {
        printf("file               %s\n", path);
        printf("frame              %d of %d\n", in.frame, ori_fold_frame_count(doc));
        printf("kind               %s, %dD\n", ori_pattern_is_folded_form(p) ? "folded form" : "crease pattern", dim);
        printf("vertices           %d (%d interior)\n", ori_pattern_vertex_count(p), ori_pattern_interior_vertex_count(p));
        printf("edges              %d:", ori_pattern_edge_count(p));
        for (int a = 0; a < ORI_ASSIGN_COUNT; ++a)
            if (counts[a]) printf(" %c %d", ori_assignment_to_char((ori_assignment)a), counts[a]);
        printf("\n");
        printf("faces              %d\n", ori_pattern_face_count(p));
        if (faces) {
            printf("\n");
            print_faces(p, three);
        }
        if (edges) {
            printf("\n");
            print_edges(p, three);
        }
    }
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    return CLI_EXIT_OK;
}

const cli_command cli_cmd_info = {
    "info",
    "what a pattern file holds; every face and edge with its index, name and place",
    "usage: orikin info FILE [--faces] [--edges] [input options] [--json]\n"
    "\n"
    "Load a pattern (FOLD, or an SVG, OPX or CP drawing, validating it) and print what it\n"
    "holds: vertices (and how many are interior), edges by assignment (B M V F U C J), faces,\n"
    "frames, and whether the frame is a flat crease pattern or a folded form in 2D or 3D. With\n"
    "--faces and --edges, every face (index, name, vertex count, area, centroid) and every edge\n"
    "(index, assignment, fold angle in degrees, length, end vertices and points): the indices\n"
    "and names the other commands take (--fix, --drive, --face, edit's E).\n"
    "\n"
    "options:\n"
    "  --faces            list the faces\n"
    "  --edges            list the edges\n" CLI_INPUT_HELP
    "  --json             print {file, frame, frames, vertices, edges, edges_by_assignment,\n"
    "                     faces, interior_vertices, dimension, folded_form}, with --faces\n"
    "                     face_list: [{face, name, vertices, area, centroid}], with --edges\n"
    "                     edge_list: [{edge, assignment, fold_angle_deg, length, vertices, from,\n"
    "                     to, faces}] (faces: left and right of from -> to, null for none)\n"
    "\n"
    "example: orikin info examples/patterns/open-corner.fold --faces\n",
    run,
    NULL,
};
