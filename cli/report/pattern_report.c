// The answers about one pattern that need no solve, or one rank: orikin info, tree, dof and
// axiom --json and the studio's GET /api/info, /api/tree, /api/dof, POST /api/axiom, written
// once so that both front ends print the same fields and values by construction.
#include <stdio.h>
#include <stdlib.h>

#include <orikin/authoring.h>

#include "report.h"

json_t *cli_info_json(const char *file, int frame, int frames, const ori_pattern *p)
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

json_t *cli_tree_json(const char *file, const ori_pattern *p)
{
    int nodes = ori_pattern_tree_node_count(p), faces = ori_pattern_face_count(p);
    // children by parent in one pass, in node order
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

json_t *cli_dof_json(const char *file, int frame, const ori_dof_result *r, int loops)
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
    json_object_set_new(out, "nearby_against_assignment",
                        r->nearby_against > 0
                            ? json_pack("{s:i,s:i,s:f}", "creases", r->nearby_against, "edge", r->nearby_against_edge,
                                        "angle_deg", ori_rad_to_deg_output(r->nearby_against_rad))
                            : json_null());
    return out;
}

json_t *cli_axiom_json(int axiom, const ori_line_set *set)
{
    json_t *lines = json_array();
    for (int k = 0; k < set->count; ++k) {
        ori_line l = set->lines[k];
        json_array_append_new(lines, json_pack("{s:[ff],s:[ff]}", "point", l.point.x, l.point.y, "dir", l.dir.x, l.dir.y));
    }
    return json_pack("{s:i,s:o}", "axiom", axiom, "lines", lines);
}

bool cli_axiom_solution_error(int axiom, int solution, int count, char *buf, size_t size)
{
    if (solution >= 1 && solution <= count) return false;
    snprintf(buf, size, "solution %d does not exist (axiom %d has %d solution%s here)", solution, axiom, count,
             count == 1 ? "" : "s");
    return true;
}
