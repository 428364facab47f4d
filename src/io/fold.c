// FOLD 1.2 documents: the JSON tree is kept whole (jansson) so that every field orikin does not
// interpret survives a round trip; patterns are read from and written into frames.
#include <orikin/fold.h>

#include <stdio.h>

#include "../pattern/pattern_internal.h"
#include "io_internal.h"

struct ori_fold {
    json_t *root;
};

// Frame inheritance chains longer than this are treated as cycles.
#define MAX_INHERIT_DEPTH 64

// Fields FOLD derives from vertices/edges/faces; stale once the topology changes.
static const char *const derived_fields[] = {
    "vertices_vertices", "vertices_edges", "vertices_faces", "edges_faces", "edges_edges",
    "faces_edges",       "faces_faces",    "edgeOrders",     "faceOrders",  "edges_length",
};

static ori_status adopt_root(json_t *root, ori_fold **out, ori_error *error)
{
    if (!json_is_object(root)) {
        json_decref(root);
        return ori__fail(error, ORI_ERR_TYPE, "the top level is not a JSON object");
    }
    json_t *frames = json_object_get(root, "file_frames");
    if (frames) {
        if (!json_is_array(frames)) {
            json_decref(root);
            return ori__fail_at(error, ORI_ERR_TYPE, "file_frames", ORI_NULL_INDEX, "not an array");
        }
        for (size_t i = 0; i < json_array_size(frames); ++i)
            if (!json_is_object(json_array_get(frames, i))) {
                json_decref(root);
                return ori__fail_at(error, ORI_ERR_TYPE, "file_frames", (int)i, "frame is not an object");
            }
    }
    ori_fold *doc = ori__calloc(1, sizeof *doc);
    doc->root = root;
    *out = doc;
    return ORI_OK;
}

ori_status ori_fold_load_string(const char *text, size_t size, ori_fold **out, ori_error *error)
{
    ORI_ASSERT(text && out);
    *out = NULL;
    ori_error_clear(error);
    json_t *root = ori__json_parse(text, size, JSON_REJECT_DUPLICATES, error);
    return root ? adopt_root(root, out, error) : ORI_ERR_PARSE;
}

ori_status ori_fold_load_file(const char *path, ori_fold **out, ori_error *error)
{
    ORI_ASSERT(path && out);
    *out = NULL;
    char *data;
    size_t size;
    ori_status st = ori_file_read_all(path, ORI_FOLD_MAX_BYTES, &data, &size, error);
    if (st != ORI_OK) return st;
    st = ori_fold_load_string(data, size, out, error);
    ori__free(data);
    return st;
}

ori_fold *ori_fold_create(void)
{
    ori_fold *doc = ori__calloc(1, sizeof *doc);
    doc->root = json_object();
    json_object_set_new(doc->root, "file_spec", json_real(1.2));
    json_object_set_new(doc->root, "file_creator", json_string("orikin"));
    json_t *classes = json_array();
    json_array_append_new(classes, json_string("singleModel"));
    json_object_set_new(doc->root, "file_classes", classes);
    return doc;
}

void ori_fold_destroy(ori_fold *doc)
{
    if (!doc) return;
    json_decref(doc->root);
    ori__free(doc);
}

int ori_fold_frame_count(const ori_fold *doc)
{
    ORI_ASSERT(doc);
    json_t *frames = json_object_get(doc->root, "file_frames");
    return 1 + (frames ? (int)json_array_size(frames) : 0);
}

static json_t *frame_object(const ori_fold *doc, int frame)
{
    if (frame == 0) return doc->root;
    json_t *frames = json_object_get(doc->root, "file_frames");
    return json_array_get(frames, (size_t)(frame - 1));
}

// A field of a frame, following frame_inherit / frame_parent.
static json_t *frame_field(const ori_fold *doc, int frame, const char *key)
{
    for (int depth = 0; depth < MAX_INHERIT_DEPTH; ++depth) {
        json_t *obj = frame_object(doc, frame);
        if (!obj) return NULL;
        json_t *v = json_object_get(obj, key);
        if (v) return v;
        if (frame == 0 || !json_is_true(json_object_get(obj, "frame_inherit"))) return NULL;
        json_t *parent = json_object_get(obj, "frame_parent");
        int pf = json_is_integer(parent) ? (int)json_integer_value(parent) : 0;
        if (pf < 0 || pf >= ori_fold_frame_count(doc) || pf == frame) return NULL;
        frame = pf;
    }
    return NULL;
}

bool ori_fold_frame_is_folded_form(const ori_fold *doc, int frame)
{
    ORI_ASSERT(doc && frame >= 0 && frame < ori_fold_frame_count(doc));
    json_t *classes = frame_field(doc, frame, "frame_classes");
    size_t i;
    json_t *c;
    json_array_foreach(classes, i, c)
    {
        if (json_is_string(c) && strcmp(json_string_value(c), "foldedForm") == 0) return true;
    }
    return false;
}

// --- reading a pattern ---------------------------------------------------------------------

static ori_status need_array(json_t *v, const char *field, ori_error *error)
{
    if (!json_is_array(v)) return ori__fail_at(error, ORI_ERR_TYPE, field, ORI_NULL_INDEX, "not an array");
    if (json_array_size(v) > (size_t)INT32_MAX / 4)
        return ori__fail_at(error, ORI_ERR_LIMIT, field, ORI_NULL_INDEX, "too many entries");
    return ORI_OK;
}

static ori_status read_index(json_t *v, const char *field, int element, int *out, ori_error *error)
{
    if (!json_is_integer(v))
        return ori__fail_at(error, ORI_ERR_TYPE, field, element, "expected integer indices");
    json_int_t x = json_integer_value(v);
    if (x < 0 || x > INT32_MAX)
        return ori__fail_at(error, ORI_ERR_RANGE, field, element, "index %lld out of range", (long long)x);
    *out = (int)x;
    return ORI_OK;
}

static ori_status read_vertices(json_t *coords, ori_pattern *p, bool *has_z, ori_error *error)
{
    ori_status st = need_array(coords, "vertices_coords", error);
    if (st != ORI_OK) return st;
    size_t i;
    json_t *c;
    *has_z = false;
    ORI__RESERVE(p->vertices, p->vertex_cap, (int)json_array_size(coords));
    json_array_foreach(coords, i, c)
    {
        size_t n = json_array_size(c);
        if (!json_is_array(c) || n < 2 || n > 3)
            return ori__fail_at(error, ORI_ERR_TYPE, "vertices_coords", (int)i,
                                "expected an array of 2 or 3 numbers");
        double x[3] = {0.0, 0.0, 0.0};
        for (size_t k = 0; k < n; ++k) {
            json_t *num = json_array_get(c, k);
            if (!json_is_number(num))
                return ori__fail_at(error, ORI_ERR_TYPE, "vertices_coords", (int)i, "coordinate %zu is not a number", k);
            x[k] = json_number_value(num);
        }
        if (n == 3) *has_z = true;
        ori_pattern_add_vertex(p, ori_v3_make(x[0], x[1], x[2]));
    }
    return ORI_OK;
}

static ori_status read_edges(const ori_fold *doc, int frame, ori_pattern *p, ori_error *error)
{
    json_t *ev = frame_field(doc, frame, "edges_vertices");
    if (!ev) return ORI_OK;
    ori_status st = need_array(ev, "edges_vertices", error);
    if (st != ORI_OK) return st;
    size_t m = json_array_size(ev);
    json_t *ea = frame_field(doc, frame, "edges_assignment");
    json_t *ef = frame_field(doc, frame, "edges_foldAngle");
    if (ea && ((st = need_array(ea, "edges_assignment", error)) != ORI_OK)) return st;
    if (ef && ((st = need_array(ef, "edges_foldAngle", error)) != ORI_OK)) return st;
    if (ea && json_array_size(ea) != m)
        return ori__fail_at(error, ORI_ERR_TOPOLOGY, "edges_assignment", ORI_NULL_INDEX,
                            "has %zu entries but edges_vertices has %zu", json_array_size(ea), m);
    if (ef && json_array_size(ef) != m)
        return ori__fail_at(error, ORI_ERR_TOPOLOGY, "edges_foldAngle", ORI_NULL_INDEX,
                            "has %zu entries but edges_vertices has %zu", json_array_size(ef), m);
    ORI__RESERVE(p->edges, p->edge_cap, (int)m);
    for (size_t e = 0; e < m; ++e) {
        json_t *pair = json_array_get(ev, e);
        if (!json_is_array(pair) || json_array_size(pair) != 2)
            return ori__fail_at(error, ORI_ERR_TYPE, "edges_vertices", (int)e, "expected [vertex, vertex]");
        int v[2];
        for (int k = 0; k < 2; ++k)
            if ((st = read_index(json_array_get(pair, (size_t)k), "edges_vertices", (int)e, &v[k], error)) != ORI_OK)
                return st;
        ori_assignment a = ORI_ASSIGN_UNASSIGNED;
        if (ea) {
            json_t *s = json_array_get(ea, e);
            const char *str = json_string_value(s);
            if (!str || strlen(str) != 1 || !ori_assignment_from_char(str[0], &a))
                return ori__fail_at(error, ORI_ERR_TYPE, "edges_assignment", (int)e,
                                    "expected one of \"B\", \"M\", \"V\", \"F\", \"U\", \"C\", \"J\"");
        }
        double angle = 0.0;
        if (ef) {
            json_t *num = json_array_get(ef, e);
            if (!json_is_number(num))
                return ori__fail_at(error, ORI_ERR_TYPE, "edges_foldAngle", (int)e, "not a number");
            double deg = json_number_value(num);
            if (!(deg >= -180.0 && deg <= 180.0))
                return ori__fail_at(error, ORI_ERR_RANGE, "edges_foldAngle", (int)e,
                                    "fold angle %g is outside [-180, 180] degrees", deg);
            angle = ori_deg_to_rad(deg);
        }
        ori_pattern_add_edge(p, v[0], v[1], a, angle);
    }
    p->has_fold_angles = ef != NULL;
    return ORI_OK;
}

static ori_status read_faces(const ori_fold *doc, int frame, ori_pattern *p, ori_error *error)
{
    json_t *fv = frame_field(doc, frame, "faces_vertices");
    if (!fv) return ORI_OK;
    ori_status st = need_array(fv, "faces_vertices", error);
    if (st != ORI_OK) return st;
    int *buf = NULL;
    int cap = 0;
    size_t f;
    json_t *face;
    json_array_foreach(fv, f, face)
    {
        if (!json_is_array(face) || json_array_size(face) < 3 || json_array_size(face) > (size_t)INT32_MAX / 4) {
            ori__free(buf);
            return ori__fail_at(error, ORI_ERR_TYPE, "faces_vertices", (int)f,
                                "expected an array of at least 3 vertex indices");
        }
        int n = (int)json_array_size(face);
        ORI__RESERVE(buf, cap, n);
        for (int k = 0; k < n; ++k)
            if ((st = read_index(json_array_get(face, (size_t)k), "faces_vertices", (int)f, &buf[k], error)) != ORI_OK) {
                ori__free(buf);
                return st;
            }
        ori_pattern_add_face(p, buf, n);
    }
    ori__free(buf);
    return ORI_OK;
}

static ori_status read_names(const ori_fold *doc, int frame, ori_pattern *p, ori_error *error)
{
    json_t *names = frame_field(doc, frame, ORI__KEY_FACES_NAME);
    if (names) {
        if (!json_is_array(names) || json_array_size(names) != (size_t)p->face_count)
            return ori__fail_at(error, ORI_ERR_TYPE, ORI__KEY_FACES_NAME, ORI_NULL_INDEX,
                                "expected an array of one name (or null) per face");
        size_t i;
        json_t *n;
        json_array_foreach(names, i, n)
        {
            if (json_is_null(n)) continue;
            if (!json_is_string(n) || ori_pattern_set_face_name(p, (int)i, json_string_value(n)) != ORI_OK)
                return ori__fail_at(error, ORI_ERR_TYPE, ORI__KEY_FACES_NAME, (int)i,
                                    "expected a name of at most %d characters", ORI_NAME_MAX - 1);
        }
    }
    json_t *tree = frame_field(doc, frame, ORI__KEY_FACE_TREE);
    if (tree) {
        if (!json_is_array(tree))
            return ori__fail_at(error, ORI_ERR_TYPE, ORI__KEY_FACE_TREE, ORI_NULL_INDEX, "not an array");
        size_t i;
        json_t *node;
        json_array_foreach(tree, i, node)
        {
            const char *name = json_string_value(json_object_get(node, "name"));
            json_t *parent = json_object_get(node, "parent");
            int pi = json_is_integer(parent) ? (int)json_integer_value(parent) : ORI_NULL_INDEX - 1;
            if (json_is_null(parent) || (json_is_integer(parent) && json_integer_value(parent) == -1))
                pi = ORI_NULL_INDEX;
            if (!name || pi < ORI_NULL_INDEX || pi >= (int)i ||
                ori_pattern_add_tree_node(p, name, pi) == ORI_NULL_INDEX)
                return ori__fail_at(error, ORI_ERR_TYPE, ORI__KEY_FACE_TREE, (int)i,
                                    "expected {\"name\": string, \"parent\": earlier node index or -1}");
        }
    }
    return ORI_OK;
}

ori_status ori_fold_get_pattern(const ori_fold *doc, int frame, const ori_build_def *def,
                                ori_pattern **out, ori_error *error)
{
    ORI_ASSERT(doc && out);
    *out = NULL;
    ori_error_clear(error);
    if (frame < 0 || frame >= ori_fold_frame_count(doc))
        return ori__fail(error, ORI_ERR_RANGE, "frame %d does not exist (the file has %d)", frame,
                         ori_fold_frame_count(doc));
    ori_pattern_def pdef = ori_default_pattern_def();
    ori_pattern *p = ori_pattern_create(&pdef);
    ori_status st = ORI_OK;
    json_t *coords = frame_field(doc, frame, "vertices_coords");
    bool has_z = false;
    if (!coords) st = ori__fail_at(error, ORI_ERR_TYPE, "vertices_coords", ORI_NULL_INDEX, "missing");
    if (st == ORI_OK) st = read_vertices(coords, p, &has_z, error);
    if (st == ORI_OK) st = read_edges(doc, frame, p, error);
    if (st == ORI_OK) st = read_faces(doc, frame, p, error);
    if (st == ORI_OK) st = read_names(doc, frame, p, error);
    if (st == ORI_OK) {
        p->folded_form = ori_fold_frame_is_folded_form(doc, frame) || ori_pattern_is_3d(p);
        st = ori_pattern_build(p, def, error);
    }
    if (st != ORI_OK) {
        ori_pattern_destroy(p);
        return st;
    }
    *out = p;
    return ORI_OK;
}

// --- writing a pattern ---------------------------------------------------------------------

static json_t *coords_json(const ori_v3 *vertices, int count, bool three)
{
    json_t *arr = json_array();
    for (int i = 0; i < count; ++i) {
        json_t *c = json_array();
        json_array_append_new(c, ori__json_number(vertices[i].x));
        json_array_append_new(c, ori__json_number(vertices[i].y));
        if (three) json_array_append_new(c, ori__json_number(vertices[i].z));
        json_array_append_new(arr, c);
    }
    return arr;
}

// Fold angles in degrees; an unchanged angle keeps the file's own number.
static json_t *fold_angles_json(const double *angles_rad, int count, json_t *old)
{
    json_t *arr = json_array();
    bool same_size = json_is_array(old) && json_array_size(old) == (size_t)count;
    for (int e = 0; e < count; ++e) {
        double rad = angles_rad[e];
        json_t *o = same_size ? json_array_get(old, (size_t)e) : NULL;
        if (o && json_is_number(o) && ori_deg_to_rad(json_number_value(o)) == rad)
            json_array_append(arr, o);
        else
            json_array_append_new(arr, ori__json_number(ori_rad_to_deg_output(rad)));
    }
    return arr;
}

static json_t *pattern_angles_json(const ori_pattern *p, json_t *old)
{
    double *a = ori__alloc(sizeof(double) * (size_t)(p->edge_count ? p->edge_count : 1));
    for (int e = 0; e < p->edge_count; ++e) a[e] = p->edges[e].fold_angle_rad;
    json_t *arr = fold_angles_json(a, p->edge_count, old);
    ori__free(a);
    return arr;
}

static json_t *edges_json(const ori_pattern *p)
{
    json_t *arr = json_array();
    for (int e = 0; e < p->edge_count; ++e)
        json_array_append_new(arr, json_pack("[ii]", p->edges[e].v[0], p->edges[e].v[1]));
    return arr;
}

static json_t *assignments_json(const ori_pattern *p)
{
    json_t *arr = json_array();
    for (int e = 0; e < p->edge_count; ++e) {
        char s[2] = {ori_assignment_to_char(p->edges[e].assignment), '\0'};
        json_array_append_new(arr, json_string(s));
    }
    return arr;
}

static json_t *faces_json(const ori_pattern *p)
{
    json_t *arr = json_array();
    for (int f = 0; f < p->face_count; ++f) {
        json_t *face = json_array();
        for (int k = p->face_offsets[f]; k < p->face_offsets[f + 1]; ++k)
            json_array_append_new(face, json_integer(p->face_vertices[k]));
        json_array_append_new(arr, face);
    }
    return arr;
}

static bool any_face_name(const ori_pattern *p)
{
    if (!p->face_names) return false;
    for (int f = 0; f < p->face_count; ++f)
        if (p->face_names[f][0]) return true;
    return false;
}

static void write_pattern_fields(json_t *obj, const ori_pattern *p, json_t *old_angles, bool three)
{
    json_object_set_new(obj, "vertices_coords", coords_json(p->vertices, p->vertex_count, three));
    json_object_set_new(obj, "edges_vertices", edges_json(p));
    json_object_set_new(obj, "edges_assignment", assignments_json(p));
    if (p->has_fold_angles)
        json_object_set_new(obj, "edges_foldAngle", pattern_angles_json(p, old_angles));
    else
        json_object_del(obj, "edges_foldAngle");
    if (p->face_count > 0) json_object_set_new(obj, "faces_vertices", faces_json(p));
    if (any_face_name(p)) {
        json_t *names = json_array();
        for (int f = 0; f < p->face_count; ++f)
            json_array_append_new(names, p->face_names[f][0] ? json_string(p->face_names[f]) : json_null());
        json_object_set_new(obj, ORI__KEY_FACES_NAME, names);
    } else {
        json_object_del(obj, ORI__KEY_FACES_NAME);
    }
    if (p->tree_count > 0) {
        json_t *tree = json_array();
        for (int i = 0; i < p->tree_count; ++i)
            json_array_append_new(tree, json_pack("{sssi}", "name", p->tree[i].name, "parent", p->tree[i].parent));
        json_object_set_new(obj, ORI__KEY_FACE_TREE, tree);
    } else {
        json_object_del(obj, ORI__KEY_FACE_TREE);
    }
}

static bool had_three_coords(json_t *coords)
{
    json_t *first = json_array_get(coords, 0);
    return json_is_array(first) && json_array_size(first) == 3;
}

// Whether a JSON array of integers equals ints[0..n).
static bool same_ints(json_t *arr, const int *ints, int n)
{
    if (!json_is_array(arr) || json_array_size(arr) != (size_t)n) return false;
    for (int i = 0; i < n; ++i) {
        json_t *x = json_array_get(arr, (size_t)i);
        if (!json_is_integer(x) || json_integer_value(x) != ints[i]) return false;
    }
    return true;
}

// The file's edges_vertices are the pattern's edges (compared in place, no copy built).
static bool same_edges(json_t *old, const ori_pattern *p)
{
    if (!json_is_array(old) || json_array_size(old) != (size_t)p->edge_count) return false;
    for (int e = 0; e < p->edge_count; ++e)
        if (!same_ints(json_array_get(old, (size_t)e), p->edges[e].v, 2)) return false;
    return true;
}

// The file's faces_vertices are the pattern's faces (both absent counts as the same).
static bool same_faces(json_t *old, const ori_pattern *p)
{
    if (!old) return p->face_count == 0;
    if (!json_is_array(old) || json_array_size(old) != (size_t)p->face_count) return false;
    for (int f = 0; f < p->face_count; ++f)
        if (!same_ints(json_array_get(old, (size_t)f), p->face_vertices + p->face_offsets[f],
                       p->face_offsets[f + 1] - p->face_offsets[f]))
            return false;
    return true;
}

ori_status ori_fold_set_pattern(ori_fold *doc, int frame, const ori_pattern *p, ori_error *error)
{
    ORI_ASSERT(doc && p);
    if (frame < 0 || frame >= ori_fold_frame_count(doc))
        return ori__fail(error, ORI_ERR_RANGE, "frame %d does not exist", frame);
    json_t *obj = frame_object(doc, frame);
    json_t *old_coords = frame_field(doc, frame, "vertices_coords");
    bool three = ori_pattern_is_3d(p) || had_three_coords(old_coords);
    // Same topology? Then FOLD's derived index fields stay valid.
    bool same = json_array_size(old_coords) == (size_t)p->vertex_count &&
                same_edges(frame_field(doc, frame, "edges_vertices"), p) &&
                same_faces(frame_field(doc, frame, "faces_vertices"), p);
    json_t *old_angles = json_incref(frame_field(doc, frame, "edges_foldAngle"));
    write_pattern_fields(obj, p, old_angles, three);
    json_decref(old_angles);
    if (!same)
        for (size_t i = 0; i < sizeof derived_fields / sizeof derived_fields[0]; ++i)
            json_object_del(obj, derived_fields[i]);
    return ORI_OK;
}

static json_t *new_frame(ori_fold *doc, const char *frame_class, const char *title)
{
    json_t *frames = json_object_get(doc->root, "file_frames");
    if (!frames) {
        frames = json_array();
        json_object_set_new(doc->root, "file_frames", frames);
    }
    json_t *obj = json_object();
    if (title) json_object_set_new(obj, "frame_title", json_string(title));
    if (frame_class) {
        json_t *classes = json_array();
        json_array_append_new(classes, json_string(frame_class));
        json_object_set_new(obj, "frame_classes", classes);
    }
    json_array_append_new(frames, obj);
    return obj;
}

static void set_state_fields(json_t *obj, int parent, int vertex_count, const ori_v3 *positions,
                             int edge_count, const double *angles_rad)
{
    json_object_set_new(obj, "frame_parent", json_integer(parent));
    json_object_set_new(obj, "frame_inherit", json_true());
    json_object_set_new(obj, "vertices_coords", coords_json(positions, vertex_count, true));
    json_object_set_new(obj, "edges_foldAngle", fold_angles_json(angles_rad, edge_count, NULL));
}

int ori_fold_append_frame(ori_fold *doc, const ori_pattern *p, const char *frame_class,
                          const char *title, int parent)
{
    ORI_ASSERT(doc && p);
    ORI_ASSERT(parent == ORI_NULL_INDEX || (parent >= 0 && parent < ori_fold_frame_count(doc)));
    json_t *obj = new_frame(doc, frame_class, title);
    if (parent == ORI_NULL_INDEX) {
        write_pattern_fields(obj, p, NULL, ori_pattern_is_3d(p));
    } else {
        double *a = ori__alloc(sizeof(double) * (size_t)(p->edge_count ? p->edge_count : 1));
        for (int e = 0; e < p->edge_count; ++e) a[e] = p->edges[e].fold_angle_rad;
        set_state_fields(obj, parent, p->vertex_count, p->vertices, p->edge_count, a);
        ori__free(a);
    }
    return ori_fold_frame_count(doc) - 1;
}

int ori_fold_append_state(ori_fold *doc, int parent, int vertex_count, const ori_v3 *positions,
                          int edge_count, const double *angles_rad, const char *title)
{
    ORI_ASSERT(doc && positions && angles_rad && vertex_count >= 0 && edge_count >= 0);
    ORI_ASSERT(parent >= 0 && parent < ori_fold_frame_count(doc));
    json_t *obj = new_frame(doc, "foldedForm", title);
    set_state_fields(obj, parent, vertex_count, positions, edge_count, angles_rad);
    return ori_fold_frame_count(doc) - 1;
}

// --- custom fields -------------------------------------------------------------------------

char *ori_fold_get_custom(const ori_fold *doc, int frame, const char *key)
{
    ORI_ASSERT(doc && key && frame >= 0 && frame < ori_fold_frame_count(doc));
    json_t *v = frame_field(doc, frame, key);
    if (!v) return NULL;
    char *text = json_dumps(v, JSON_ENCODE_ANY | JSON_COMPACT | JSON_REAL_PRECISION(17));
    if (!text) return NULL;
    char *copy = ori__strdup(text);
    free(text);
    return copy;
}

ori_status ori_fold_set_custom(ori_fold *doc, int frame, const char *key, const char *json, ori_error *error)
{
    ORI_ASSERT(doc && key && frame >= 0 && frame < ori_fold_frame_count(doc));
    json_t *obj = frame_object(doc, frame);
    if (!json) {
        json_object_del(obj, key);
        return ORI_OK;
    }
    json_t *v = ori__json_parse(json, strlen(json), JSON_DECODE_ANY, error);
    if (!v) return ORI_ERR_PARSE;
    json_object_set_new(obj, key, v);
    return ORI_OK;
}

void ori_fold_set_string(ori_fold *doc, int frame, const char *key, const char *value)
{
    ORI_ASSERT(doc && key && value && frame >= 0 && frame < ori_fold_frame_count(doc));
    json_object_set_new(frame_object(doc, frame), key, json_string(value));
}

// --- output ------------------------------------------------------------------------------

char *ori_fold_to_string(const ori_fold *doc)
{
    ORI_ASSERT(doc);
    return ori__json_write_pretty(doc->root);
}

char *ori_json_normalize(const char *json_text, bool pretty, ori_error *error)
{
    ORI_ASSERT(json_text);
    json_t *v = ori__json_parse(json_text, strlen(json_text), JSON_DECODE_ANY, error);
    if (!v) return NULL;
    char *out = pretty ? ori__json_write_pretty(v) : ori__json_write_compact(v);
    json_decref(v);
    return out;
}

ori_status ori_fold_save_file(const ori_fold *doc, const char *path, ori_error *error)
{
    char *text = ori_fold_to_string(doc);
    ori_status st = ori_file_write_atomic(path, text, strlen(text), error);
    ori_buffer_free(text);
    return st;
}
