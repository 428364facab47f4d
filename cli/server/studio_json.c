// The API's JSON: field for field what the CLI prints with --json (tests/test_server.c runs
// both and compares them), so that a script and the page read the same answers. The answers of
// fold, sequence, collide and check are built by the CLI's own builders (cli/report/).
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "studio_internal.h"

// A growing text buffer for the state answers, written directly: a 100 × 100 Miura-ori state
// has 50,000 numbers, which a JSON tree and its normalisation take ten times longer to write.
typedef struct text_buf {
    char *p;
    size_t n, cap;
} text_buf;

static void tb_reserve(text_buf *b, size_t more)
{
    if (b->n + more + 1 <= b->cap) return;
    size_t cap = b->cap ? b->cap : 4096;
    while (cap < b->n + more + 1) cap *= 2;
    b->p = realloc(b->p, cap);
    b->cap = cap;
}

static void tb_str(text_buf *b, const char *s)
{
    size_t k = strlen(s);
    tb_reserve(b, k);
    memcpy(b->p + b->n, s, k + 1);
    b->n += k;
}

// A number that reads back exactly: integers as integers (0, 90, 180 are common), anything
// else with 17 significant digits (always enough for a double; the CLI prints the shortest
// such form, which parses to the same double).
static void tb_num(text_buf *b, double x)
{
    tb_reserve(b, 32);
    int k;
    if (x == floor(x) && fabs(x) < 1e15) k = snprintf(b->p + b->n, 32, "%.0f", x == 0.0 ? 0.0 : x);
    else k = snprintf(b->p + b->n, 32, "%.17g", x);
    b->n += (size_t)k;
}

static void tb_degrees(text_buf *b, const double *a, int n)
{
    tb_str(b, "[");
    for (int e = 0; e < n; ++e) {
        if (e) tb_str(b, ",");
        tb_num(b, ori_rad_to_deg_output(a[e]));
    }
    tb_str(b, "]");
}

static void tb_coords(text_buf *b, const ori_v3 *pos, int V)
{
    tb_str(b, "[");
    for (int v = 0; v < V; ++v) {
        tb_str(b, v ? ",[" : "[");
        tb_num(b, pos[v].x);
        tb_str(b, ",");
        tb_num(b, pos[v].y);
        tb_str(b, ",");
        tb_num(b, pos[v].z);
        tb_str(b, "]");
    }
    tb_str(b, "]");
}

char *studio_json_at_text(double t, int fold, double drive_rad, const double *angles_rad, int E, double residual,
                          const ori_v3 *pos, int V, size_t *size)
{
    text_buf b = {NULL, 0, 0};
    tb_reserve(&b, (size_t)(E + 3 * V) * 20 + 256);
    tb_str(&b, "{\"t\":");
    tb_num(&b, t);
    tb_str(&b, ",\"fold\":");
    tb_num(&b, fold + 1);
    tb_str(&b, ",\"drive_deg\":");
    if (isnan(drive_rad)) tb_str(&b, "null"); // a fold toward the targets has no drive angle
    else tb_num(&b, ori_rad_to_deg_output(drive_rad));
    tb_str(&b, ",\"fold_angles_deg\":");
    tb_degrees(&b, angles_rad, E);
    tb_str(&b, ",\"residual\":");
    tb_num(&b, residual);
    tb_str(&b, ",\"vertices_coords\":");
    tb_coords(&b, pos, V);
    tb_str(&b, "}");
    *size = b.n;
    return b.p;
}

char *studio_json_frame_text(int frame, double drive_rad, const double *angles_rad, int E, double residual,
                             const ori_v3 *pos, int V, size_t *size)
{
    text_buf b = {NULL, 0, 0};
    tb_reserve(&b, (size_t)(E + 3 * V) * 20 + 256);
    tb_str(&b, "{\"frame\":");
    tb_num(&b, frame);
    tb_str(&b, ",\"drive_deg\":");
    tb_num(&b, ori_rad_to_deg_output(drive_rad));
    tb_str(&b, ",\"fold_angles_deg\":");
    tb_degrees(&b, angles_rad, E);
    tb_str(&b, ",\"residual\":");
    tb_num(&b, residual);
    tb_str(&b, ",\"vertices_coords\":");
    tb_coords(&b, pos, V);
    tb_str(&b, "}");
    *size = b.n;
    return b.p;
}

// Little-endian float64 whatever the host.
static void put_f64(unsigned char *p, double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    for (int i = 0; i < 8; ++i) p[i] = (unsigned char)(u >> (8 * i));
}

char *studio_state_binary(double t, int fold, double drive_rad, double residual, const ori_v3 *pos, int V,
                          const double *angles_rad, int E, size_t *size)
{
    size_t n = 8 + 3 * (size_t)V + (size_t)E;
    unsigned char *b = malloc(8 * n);
    double head[8] = {t, (double)(fold + 1), ori_rad_to_deg_output(drive_rad), residual, (double)V, (double)E, 0.0, 0.0};
    size_t k = 0;
    for (int i = 0; i < 8; ++i) put_f64(b + 8 * k++, head[i]);
    for (int v = 0; v < V; ++v) {
        put_f64(b + 8 * k++, pos[v].x);
        put_f64(b + 8 * k++, pos[v].y);
        put_f64(b + 8 * k++, pos[v].z);
    }
    for (int e = 0; e < E; ++e) put_f64(b + 8 * k++, ori_rad_to_deg_output(angles_rad[e]));
    *size = 8 * n;
    return (char *)b;
}

// --- orikin dof, tree, info, axiom --json ----------------------------------------------------

json_t *studio_json_dof(const char *file, int frame, const ori_dof_result *r, int loops)
{
    json_t *out = json_object();
    json_object_set_new(out, "file", json_string(file));
    json_object_set_new(out, "frame", json_integer(frame));
    json_object_set_new(out, "grubler", json_integer(r->grubler));
    json_object_set_new(out, "unknowns", json_integer(r->unknowns));
    json_object_set_new(out, "equations", json_integer(r->equations));
    json_object_set_new(out, "rank", json_integer(r->rank));
    json_object_set_new(out, "dof", json_integer(r->dof));
    json_object_set_new(out, "generic_dof", r->generic_dof >= 0 ? json_integer(r->generic_dof) : json_null());
    json_object_set_new(out, "singular", json_boolean(r->singular));
    json_object_set_new(out, "rigid", json_boolean(r->rigid));
    json_object_set_new(out, "undetermined", json_boolean(r->undetermined));
    json_object_set_new(out, "probe_solves", json_integer(r->probe_solves));
    json_object_set_new(out, "method", json_string(r->dense ? "dense-svd" : "sparse-cholmod"));
    json_object_set_new(out, "sigma_max", json_real(r->sigma_max));
    json_object_set_new(out, "sigma_cut", json_real(r->sigma_cut));
    json_object_set_new(out, "loops", json_integer(loops));
    json_object_set_new(out, "nearby_against_assignment", // as orikin dof --json (cmd_dof.c)
                        r->nearby_against > 0
                            ? json_pack("{s:i,s:i,s:f}", "creases", r->nearby_against, "edge", r->nearby_against_edge,
                                        "angle_deg", ori_rad_to_deg_output(r->nearby_against_rad))
                            : json_null());
    return out;
}

json_t *studio_json_tree(const char *file, const ori_pattern *p)
{
    int nodes = ori_pattern_tree_node_count(p), faces = ori_pattern_face_count(p);
    // children by parent in one pass (the CLI's double loop is quadratic)
    int *first = malloc(sizeof(int) * (size_t)(nodes + 1)), *next = malloc(sizeof(int) * (size_t)(nodes + 1));
    for (int i = 0; i < nodes; ++i) first[i] = next[i] = -1;
    for (int k = nodes - 1; k >= 0; --k) {
        int parent = ori_pattern_tree_node(p, k).parent;
        if (parent >= 0 && parent < nodes) {
            next[k] = first[parent];
            first[parent] = k;
        }
    }
    json_t *arr = json_array();
    for (int i = 0; i < nodes; ++i) {
        ori_tree_node n = ori_pattern_tree_node(p, i);
        json_t *children = json_array();
        for (int k = first[i]; k >= 0; k = next[k]) json_array_append_new(children, json_string(ori_pattern_tree_node(p, k).name));
        int face = ori_pattern_find_face_by_name(p, n.name);
        json_t *o = json_object();
        json_object_set_new(o, "name", json_string(n.name));
        json_object_set_new(o, "parent", json_integer(n.parent));
        json_object_set_new(o, "children", children);
        json_object_set_new(o, "leaf", json_boolean(first[i] < 0));
        json_object_set_new(o, "face", face == ORI_NULL_INDEX ? json_null() : json_integer(face));
        json_array_append_new(arr, o);
    }
    free(first);
    free(next);
    json_t *elems = json_array();
    for (int f = 0; f < faces; ++f) {
        const char *name = ori_pattern_face_name(p, f);
        json_t *o = json_object();
        json_object_set_new(o, "face", json_integer(f));
        json_object_set_new(o, "name", name ? json_string(name) : json_null());
        json_array_append_new(elems, o);
    }
    json_t *out = json_object();
    json_object_set_new(out, "file", json_string(file));
    json_object_set_new(out, "nodes", arr);
    json_object_set_new(out, "folding_elements", elems);
    return out;
}

json_t *studio_json_info(const char *file, int frame, int frames, const ori_pattern *p)
{
    json_t *by = json_object();
    for (int a = 0; a < ORI_ASSIGN_COUNT; ++a) {
        char key[2] = {ori_assignment_to_char((ori_assignment)a), '\0'};
        json_object_set_new(by, key, json_integer(ori_pattern_count_assignment(p, (ori_assignment)a)));
    }
    json_t *out = json_object();
    json_object_set_new(out, "file", json_string(file));
    json_object_set_new(out, "frame", json_integer(frame));
    json_object_set_new(out, "frames", json_integer(frames));
    json_object_set_new(out, "vertices", json_integer(ori_pattern_vertex_count(p)));
    json_object_set_new(out, "edges", json_integer(ori_pattern_edge_count(p)));
    json_object_set_new(out, "edges_by_assignment", by);
    json_object_set_new(out, "faces", json_integer(ori_pattern_face_count(p)));
    json_object_set_new(out, "interior_vertices", json_integer(ori_pattern_interior_vertex_count(p)));
    json_object_set_new(out, "dimension", json_integer(ori_pattern_is_3d(p) ? 3 : 2));
    json_object_set_new(out, "folded_form", json_boolean(ori_pattern_is_folded_form(p)));
    return out;
}

json_t *studio_json_axiom(int axiom, const ori_line_set *set)
{
    json_t *lines = json_array();
    for (int k = 0; k < set->count; ++k) {
        ori_line l = set->lines[k];
        json_array_append_new(lines, json_pack("{s:[ff],s:[ff]}", "point", l.point.x, l.point.y, "dir", l.dir.x, l.dir.y));
    }
    return json_pack("{s:i,s:o}", "axiom", axiom, "lines", lines);
}

