// What applying a composite or a crease to a face did (orikin apply and crease --json, POST
// /api/apply and /api/crease): the target's label, the counts and the new folding elements,
// built once for both front ends.
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <orikin/authoring.h>

#include "report.h"

const char *cli_face_label(const ori_pattern *p, int f, char *buf, size_t size)
{
    const char *name = f == ORI_NULL_INDEX ? NULL : ori_pattern_face_name(p, f);
    if (name) snprintf(buf, size, "%s", name);
    else if (f == ORI_NULL_INDEX) snprintf(buf, size, "the sheet");
    else snprintf(buf, size, "face %d", f);
    return buf;
}

void cli_apply_counts_json(json_t *o, const ori_apply_result *r)
{
    json_object_set_new(o, "segments", json_integer(r->segments));
    json_object_set_new(o, "faces_split", json_integer(r->faces_split));
    json_object_set_new(o, "edges_added", json_integer(r->edges_added));
    json_object_set_new(o, "first_edge", json_integer(r->first_edge));
}

static const ori_pattern *sort_pattern; // qsort has no context argument
static int cmp_face_name(const void *a, const void *b)
{
    return strcmp(ori_pattern_face_name(sort_pattern, *(const int *)a), ori_pattern_face_name(sort_pattern, *(const int *)b));
}

json_t *cli_apply_new_faces_json(const ori_pattern *p, int nodes_before)
{
    json_t *leaves = json_array();
    // The faces by name, sorted once: a lookup per new tree node would be quadratic in the
    // output (512 random creases make 90,000 faces).
    int nf = ori_pattern_face_count(p), *by_name = malloc(((size_t)nf + 1) * sizeof *by_name), nn = 0;
    for (int f = 0; f < nf; ++f)
        if (ori_pattern_face_name(p, f)) by_name[nn++] = f;
    sort_pattern = p;
    qsort(by_name, (size_t)nn, sizeof *by_name, cmp_face_name);
    for (int i = nodes_before; i < ori_pattern_tree_node_count(p); ++i) {
        ori_tree_node n = ori_pattern_tree_node(p, i);
        int f = ORI_NULL_INDEX;
        for (int lo = 0, hi = nn - 1; lo <= hi && f == ORI_NULL_INDEX;) {
            int mid = (lo + hi) / 2, c = strcmp(n.name, ori_pattern_face_name(p, by_name[mid]));
            if (c == 0) f = by_name[mid];
            else if (c < 0) hi = mid - 1;
            else lo = mid + 1;
        }
        if (f != ORI_NULL_INDEX) json_array_append_new(leaves, json_pack("{s:s,s:i}", "name", n.name, "face", f));
    }
    free(by_name);
    return leaves;
}
