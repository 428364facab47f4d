// FOLD 1.2 documents: every field survives a round trip (fold_internal.h: the big arrays packed,
// the rest kept as JSON); patterns are read from and written into frames.
#include <orikin/fold.h>

#include <orikin/arrangement.h>
#include <stdio.h>

#include "../pattern/pattern_internal.h"
#include "fold_internal.h"

// Frame inheritance chains longer than this are treated as cycles.
#define MAX_INHERIT_DEPTH 64

// Peak memory of loading a FOLD file and building a frame's pattern, per byte of the file. The
// text is read whole (1×) and packed (0.5–1×, freed text after); the built pattern with its
// adjacency takes 0.8× (folded frames), 2.8× (a 12 MB 300 × 300 Miura-ori) and up to 6.8× (a
// long chain of short edges, faces traced). Loading refuses files that would need more than
// the machine has, rather than being killed half-way.
#define LOAD_BYTES_PER_FILE_BYTE 6

// Fields FOLD derives from vertices/edges/faces; stale once the topology changes.
static const char *const derived_fields[] = {
    "vertices_vertices", "vertices_edges", "vertices_faces", "edges_faces", "edges_edges",
    "faces_edges",       "faces_faces",    "edgeOrders",     "faceOrders",  "edges_length",
};

// --- loading -------------------------------------------------------------------------------------

static const ori__field *own_field(const ori_fold *doc, int frame, const char *key)
{
    return ori__frame_find(&doc->frames[frame], key);
}

// frame_parent and frame_inherit of every frame: an existing other frame (never truncated:
// 2^32 is not frame 0), a boolean, and no inheritance cycle.
static ori_status check_frames(const ori_fold *doc, ori_error *error)
{
    int n = doc->frame_count;
    for (int k = 1; k < n; ++k) {
        const ori__field *p = own_field(doc, k, "frame_parent"), *inh = own_field(doc, k, "frame_inherit");
        if (inh && !(inh->json && json_is_boolean(inh->json)))
            return ori__fail_at(error, ORI_ERR_TYPE, "file_frames", k - 1, "frame_inherit is not true or false");
        if (!p) {
            if (inh && json_is_true(inh->json))
                return ori__fail_at(error, ORI_ERR_TYPE, "file_frames", k - 1, "frame_inherit needs a frame_parent");
            continue;
        }
        if (!p->json || !json_is_integer(p->json))
            return ori__fail_at(error, ORI_ERR_TYPE, "file_frames", k - 1, "frame_parent is not an integer frame number");
        json_int_t parent = json_integer_value(p->json);
        if (parent < 0 || parent >= n || parent == k)
            return ori__fail_at(error, ORI_ERR_RANGE, "file_frames", k - 1,
                                "frame_parent %lld is not another frame (frames 0 to %d)", (long long)parent, n - 1);
    }
    // Inheritance chains end at a frame that does not inherit (frame 0 never does).
    for (int k = 1; k < n; ++k) {
        int f = k;
        for (int depth = 0; f != 0; ++depth) {
            const ori__field *inh = own_field(doc, f, "frame_inherit");
            if (!inh || !json_is_true(inh->json)) break;
            if (depth >= MAX_INHERIT_DEPTH)
                return ori__fail_at(error, ORI_ERR_RANGE, "file_frames", k - 1,
                                    "frame_parent: the inheritance chain loops or is longer than %d frames",
                                    MAX_INHERIT_DEPTH);
            f = (int)json_integer_value(own_field(doc, f, "frame_parent")->json);
        }
    }
    return ORI_OK;
}

ori_status ori_fold_load_string(const char *text, size_t size, ori_fold **out, ori_error *error)
{
    ORI_ASSERT(text && out);
    *out = NULL;
    ori_error_clear(error);
    ori_fold *doc = NULL;
    ori_status st = ori__doc_parse(text, size, &doc, error);
    if (st == ORI_OK) st = check_frames(doc, error);
    if (st != ORI_OK) {
        ori_fold_destroy(doc);
        return st;
    }
    *out = doc;
    return ORI_OK;
}

ori_status ori_fold_load_file(const char *path, ori_fold **out, ori_error *error)
{
    ORI_ASSERT(path && out);
    *out = NULL;
    ori_error_clear(error);
    char *data;
    size_t size;
    ori_status st = ori__file_read_within_memory(path, ORI_FOLD_MAX_BYTES, LOAD_BYTES_PER_FILE_BYTE, &data, &size, error);
    if (st != ORI_OK) return st;
    st = ori_fold_load_string(data, size, out, error);
    ori__free(data);
    return st;
}

ori_fold *ori_fold_create(void)
{
    ori_fold *doc = ori__doc_new();
    ori__frame *top = &doc->frames[0];
    ori__frame_set(top, "file_spec", json_real(1.2), NULL);
    ori__frame_set(top, "file_creator", json_string("orikin"), NULL);
    json_t *classes = json_array();
    json_array_append_new(classes, json_string("singleModel"));
    ori__frame_set(top, "file_classes", classes, NULL);
    return doc;
}

int ori_fold_frame_count(const ori_fold *doc)
{
    ORI_ASSERT(doc);
    return doc->frame_count;
}

// A field of a frame, following frame_inherit / frame_parent (checked on load).
static const ori__field *frame_field(const ori_fold *doc, int frame, const char *key)
{
    for (int depth = 0; depth <= MAX_INHERIT_DEPTH && frame >= 0 && frame < doc->frame_count; ++depth) {
        const ori__field *f = own_field(doc, frame, key);
        if (f) return f;
        const ori__field *inh = own_field(doc, frame, "frame_inherit");
        const ori__field *parent = own_field(doc, frame, "frame_parent");
        if (frame == 0 || !inh || !json_is_true(inh->json) || !parent || !json_is_integer(parent->json)) return NULL;
        json_int_t pf = json_integer_value(parent->json);
        if (pf < 0 || pf >= doc->frame_count || pf == frame) return NULL;
        frame = (int)pf;
    }
    return NULL;
}

// Whether an array field of strings holds s.
static bool has_string(const ori__field *f, const char *s)
{
    if (!f) return false;
    if (f->pk) {
        if (f->pk->kind != ORI__PK_STRS) return false;
        size_t n = strlen(s);
        for (int64_t i = 0; i < f->pk->count; ++i)
            if ((size_t)ori__pk_len(f->pk, i) == n && memcmp(f->pk->chars + ori__pk_start(f->pk, i), s, n) == 0) return true;
        return false;
    }
    size_t i;
    json_t *c;
    json_array_foreach(f->json, i, c)
    {
        if (json_is_string(c) && strcmp(json_string_value(c), s) == 0) return true;
    }
    return false;
}

bool ori_fold_frame_is_folded_form(const ori_fold *doc, int frame)
{
    ORI_ASSERT(doc && frame >= 0 && frame < ori_fold_frame_count(doc));
    return has_string(frame_field(doc, frame, "frame_classes"), "foldedForm");
}

// --- reading a pattern ---------------------------------------------------------------------

// Entries of an array field (packed, or a JSON array), or -1 (after the error) when it is not an
// array or too long.
static int64_t array_size(const ori__field *f, const char *field, ori_error *error)
{
    int64_t n;
    if (f->pk) n = f->pk->count;
    else if (json_is_array(f->json)) n = (int64_t)json_array_size(f->json);
    else {
        ori__fail_at(error, ORI_ERR_TYPE, field, ORI_NULL_INDEX, "not an array");
        return -1;
    }
    if (n > INT32_MAX / 4) {
        ori__fail_at(error, ORI_ERR_LIMIT, field, ORI_NULL_INDEX, "too many entries");
        return -1;
    }
    return n;
}

// An empty packed array reads as an empty array of any kind.
static bool empty_pk(const ori__packed *pk) { return pk && pk->count == 0; }

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

// Value k of row i of a packed index array (ints only: the row's numbers were all written as
// integers, checked with first_real by the caller).
static ori_status pk_index(const ori__packed *pk, int64_t k, const char *field, int element, int *out, ori_error *error)
{
    double x = ori__pk_num(pk, k);
    if (x < 0 || x > INT32_MAX)
        return ori__fail_at(error, ORI_ERR_RANGE, field, element, "index %lld out of range", (long long)x);
    *out = (int)x;
    return ORI_OK;
}

static ori_status read_vertices(const ori__field *coords, ori_pattern *p, bool *has_z, ori_error *error)
{
    *has_z = false;
    int64_t n = array_size(coords, "vertices_coords", error);
    if (n < 0) return error ? error->status : ORI_ERR_TYPE;
    ORI__RESERVE(p->vertices, p->vertex_cap, (int)n);
    const ori__packed *pk = coords->pk;
    if (pk && !empty_pk(pk)) {
        if (pk->kind != ORI__PK_ROWS)
            return ori__fail_at(error, ORI_ERR_TYPE, "vertices_coords", 0, "expected an array of 2 or 3 numbers");
        for (int64_t i = 0; i < n; ++i) {
            int64_t s = ori__pk_start(pk, i), len = ori__pk_len(pk, i);
            if (len < 2 || len > 3)
                return ori__fail_at(error, ORI_ERR_TYPE, "vertices_coords", (int)i, "expected an array of 2 or 3 numbers");
            double x[3] = {ori__pk_num(pk, s), ori__pk_num(pk, s + 1), len == 3 ? ori__pk_num(pk, s + 2) : 0.0};
            if (len == 3) *has_z = true;
            ori_pattern_add_vertex(p, ori_v3_make(x[0], x[1], x[2]));
        }
        return ORI_OK;
    }
    if (pk) return ORI_OK;
    size_t i;
    json_t *c;
    json_array_foreach(coords->json, i, c)
    {
        size_t m = json_array_size(c);
        if (!json_is_array(c) || m < 2 || m > 3)
            return ori__fail_at(error, ORI_ERR_TYPE, "vertices_coords", (int)i, "expected an array of 2 or 3 numbers");
        double x[3] = {0.0, 0.0, 0.0};
        for (size_t k = 0; k < m; ++k) {
            json_t *num = json_array_get(c, k);
            if (!json_is_number(num))
                return ori__fail_at(error, ORI_ERR_TYPE, "vertices_coords", (int)i, "coordinate %zu is not a number", k);
            x[k] = json_number_value(num);
        }
        if (m == 3) *has_z = true;
        ori_pattern_add_vertex(p, ori_v3_make(x[0], x[1], x[2]));
    }
    return ORI_OK;
}

// Edge e's two vertex indices.
static ori_status edge_vertices(const ori__field *ev, int64_t e, int v[2], ori_error *error)
{
    const ori__packed *pk = ev->pk;
    if (pk) {
        if (pk->kind != ORI__PK_ROWS || ori__pk_len(pk, e) != 2)
            return ori__fail_at(error, ORI_ERR_TYPE, "edges_vertices", (int)e, "expected [vertex, vertex]");
        if (pk->first_real == e) return ori__fail_at(error, ORI_ERR_TYPE, "edges_vertices", (int)e, "expected integer indices");
        int64_t s = ori__pk_start(pk, e);
        for (int k = 0; k < 2; ++k) {
            ori_status st = pk_index(pk, s + k, "edges_vertices", (int)e, &v[k], error);
            if (st != ORI_OK) return st;
        }
        return ORI_OK;
    }
    json_t *pair = json_array_get(ev->json, (size_t)e);
    if (!json_is_array(pair) || json_array_size(pair) != 2)
        return ori__fail_at(error, ORI_ERR_TYPE, "edges_vertices", (int)e, "expected [vertex, vertex]");
    for (int k = 0; k < 2; ++k) {
        ori_status st = read_index(json_array_get(pair, (size_t)k), "edges_vertices", (int)e, &v[k], error);
        if (st != ORI_OK) return st;
    }
    return ORI_OK;
}

static ori_status edge_assignment(const ori__field *ea, int64_t e, ori_assignment *a, ori_error *error)
{
    const char *str = NULL;
    size_t len = 0;
    if (ea->pk && ea->pk->kind == ORI__PK_STRS) {
        str = ea->pk->chars + ori__pk_start(ea->pk, e);
        len = (size_t)ori__pk_len(ea->pk, e);
    } else if (!ea->pk) {
        json_t *s = json_array_get(ea->json, (size_t)e);
        str = json_string_value(s);
        len = str ? json_string_length(s) : 0;
    }
    if (!str || len != 1 || !ori_assignment_from_char(str[0], a))
        return ori__fail_at(error, ORI_ERR_TYPE, "edges_assignment", (int)e,
                            "expected one of \"B\", \"M\", \"V\", \"F\", \"U\", \"C\", \"J\"");
    return ORI_OK;
}

// Edge e's fold angle in radians; ±180° within ORI_TOL_FILE_ANGLE_RAD is ±π. A null entry
// (Origami Simulator's exports write null on boundary edges) is an absent angle: 0, *absent set.
static ori_status edge_angle(const ori__field *ef, int64_t e, double *out, bool *absent, ori_error *error)
{
    double deg;
    *absent = false;
    if (ef->pk && ef->pk->kind == ORI__PK_NUMS) {
        deg = ori__pk_num(ef->pk, e);
    } else {
        json_t *num = ef->pk ? NULL : json_array_get(ef->json, (size_t)e);
        if (json_is_null(num)) {
            *absent = true;
            *out = 0.0;
            return ORI_OK;
        }
        if (!json_is_number(num)) return ori__fail_at(error, ORI_ERR_TYPE, "edges_foldAngle", (int)e, "not a number");
        deg = json_number_value(num);
    }
    double rad = ori_deg_to_rad(deg);
    if (fabs(rad) > ORI_PI && fabs(rad) - ORI_PI <= ORI_TOL_FILE_ANGLE_RAD) rad = rad > 0 ? ORI_PI : -ORI_PI;
    if (!(fabs(rad) <= ORI_PI))
        return ori__fail_at(error, ORI_ERR_RANGE, "edges_foldAngle", (int)e, "fold angle %g is outside [-180, 180] degrees",
                            deg);
    *out = rad;
    return ORI_OK;
}

static ori_status read_edges(const ori_fold *doc, int frame, ori_pattern *p, ori_error *error)
{
    const ori__field *ev = frame_field(doc, frame, "edges_vertices");
    if (!ev) return ORI_OK;
    int64_t m = array_size(ev, "edges_vertices", error);
    if (m < 0) return error ? error->status : ORI_ERR_TYPE;
    const ori__field *ea = frame_field(doc, frame, "edges_assignment");
    const ori__field *ef = frame_field(doc, frame, "edges_foldAngle");
    int64_t na = ea ? array_size(ea, "edges_assignment", error) : m;
    if (na < 0) return error ? error->status : ORI_ERR_TYPE;
    int64_t nf = ef ? array_size(ef, "edges_foldAngle", error) : m;
    if (nf < 0) return error ? error->status : ORI_ERR_TYPE;
    if (na != m)
        return ori__fail_at(error, ORI_ERR_TOPOLOGY, "edges_assignment", ORI_NULL_INDEX,
                            "has %lld entries but edges_vertices has %lld", (long long)na, (long long)m);
    if (nf != m)
        return ori__fail_at(error, ORI_ERR_TOPOLOGY, "edges_foldAngle", ORI_NULL_INDEX,
                            "has %lld entries but edges_vertices has %lld", (long long)nf, (long long)m);
    ORI__RESERVE(p->edges, p->edge_cap, (int)m);
    for (int64_t e = 0; e < m; ++e) {
        int v[2];
        ori_status st = edge_vertices(ev, e, v, error);
        ori_assignment a = ORI_ASSIGN_UNASSIGNED;
        double angle = 0.0;
        if (st == ORI_OK && ea) st = edge_assignment(ea, e, &a, error);
        bool absent = false;
        if (st == ORI_OK && ef) st = edge_angle(ef, e, &angle, &absent, error);
        if (st != ORI_OK) return st;
        p->absent_fold_angles += absent;
        ori_pattern_add_edge(p, v[0], v[1], a, angle);
    }
    p->has_fold_angles = ef != NULL;
    return ORI_OK;
}

static ori_status read_faces(const ori_fold *doc, int frame, ori_pattern *p, ori_error *error)
{
    const ori__field *fv = frame_field(doc, frame, "faces_vertices");
    if (!fv) return ORI_OK;
    int64_t nf = array_size(fv, "faces_vertices", error);
    if (nf < 0) return error ? error->status : ORI_ERR_TYPE;
    int *buf = NULL;
    int cap = 0;
    ori_status st = ORI_OK;
    const ori__packed *pk = fv->pk;
    for (int64_t f = 0; f < nf && st == ORI_OK; ++f) {
        int64_t n;
        json_t *face = NULL;
        if (pk) n = pk->kind == ORI__PK_ROWS ? ori__pk_len(pk, f) : 0;
        else n = json_is_array(face = json_array_get(fv->json, (size_t)f)) ? (int64_t)json_array_size(face) : 0;
        if (n < 3 || n > INT32_MAX / 4) {
            st = ori__fail_at(error, ORI_ERR_TYPE, "faces_vertices", (int)f, "expected an array of at least 3 vertex indices");
            break;
        }
        if (pk && pk->first_real == f) {
            st = ori__fail_at(error, ORI_ERR_TYPE, "faces_vertices", (int)f, "expected integer indices");
            break;
        }
        ORI__RESERVE(buf, cap, (int)n);
        for (int64_t k = 0; k < n && st == ORI_OK; ++k)
            st = pk ? pk_index(pk, ori__pk_start(pk, f) + k, "faces_vertices", (int)f, &buf[k], error)
                    : read_index(json_array_get(face, (size_t)k), "faces_vertices", (int)f, &buf[k], error);
        if (st == ORI_OK) ori_pattern_add_face(p, buf, (int)n);
    }
    ori__free(buf);
    return st;
}

static ori_status read_names(const ori_fold *doc, int frame, ori_pattern *p, ori_error *error)
{
    const ori__field *names = frame_field(doc, frame, ORI__KEY_FACES_NAME);
    if (names) {
        int64_t n = names->pk ? names->pk->count : json_is_array(names->json) ? (int64_t)json_array_size(names->json) : -1;
        if (n != p->face_count || (names->pk && names->pk->kind != ORI__PK_STRS && n > 0))
            return ori__fail_at(error, ORI_ERR_TYPE, ORI__KEY_FACES_NAME, ORI_NULL_INDEX,
                                "expected an array of one name (or null) per face");
        for (int64_t i = 0; i < n; ++i) {
            char name[ORI_NAME_MAX + 1];
            bool ok;
            if (names->pk) {
                int64_t len = ori__pk_len(names->pk, i);
                ok = len < (int64_t)sizeof name;
                if (ok) {
                    memcpy(name, names->pk->chars + ori__pk_start(names->pk, i), (size_t)len);
                    name[len] = '\0';
                }
            } else {
                json_t *v = json_array_get(names->json, (size_t)i);
                if (json_is_null(v)) continue;
                ok = json_is_string(v) && strlen(json_string_value(v)) < sizeof name;
                if (ok) snprintf(name, sizeof name, "%s", json_string_value(v));
            }
            if (!ok || ori_pattern_set_face_name(p, (int)i, name) != ORI_OK)
                return ori__fail_at(error, ORI_ERR_TYPE, ORI__KEY_FACES_NAME, (int)i,
                                    "expected a name of at most %d characters", ORI_NAME_MAX - 1);
        }
    }
    const ori__field *tree = frame_field(doc, frame, ORI__KEY_FACE_TREE);
    if (tree && !empty_pk(tree->pk)) {
        if (!tree->json || !json_is_array(tree->json))
            return ori__fail_at(error, ORI_ERR_TYPE, ORI__KEY_FACE_TREE, ORI_NULL_INDEX, "not an array");
        size_t i;
        json_t *node;
        json_array_foreach(tree->json, i, node)
        {
            const char *name = json_string_value(json_object_get(node, "name"));
            json_t *parent = json_object_get(node, "parent");
            int pi = json_is_integer(parent) ? (int)json_integer_value(parent) : ORI_NULL_INDEX - 1;
            if (json_is_integer(parent) && (json_integer_value(parent) < -1 || json_integer_value(parent) > INT32_MAX))
                pi = ORI_NULL_INDEX - 1;
            if (json_is_null(parent) || (json_is_integer(parent) && json_integer_value(parent) == -1)) pi = ORI_NULL_INDEX;
            if (!name || pi < ORI_NULL_INDEX || pi >= (int)i || ori_pattern_add_tree_node(p, name, pi) == ORI_NULL_INDEX)
                return ori__fail_at(error, ORI_ERR_TYPE, ORI__KEY_FACE_TREE, (int)i,
                                    "expected {\"name\": string, \"parent\": earlier node index or -1}");
        }
    }
    return ORI_OK;
}

// --- planarising a frame whose edges cross or overlap ---------------------------------------

static bool is_derived(const char *key)
{
    for (size_t i = 0; i < sizeof derived_fields / sizeof derived_fields[0]; ++i)
        if (strcmp(key, derived_fields[i]) == 0) return true;
    return false;
}

// A field of the frame (or a frame it inherits from) tied to the file's vertex, edge or face
// indices that planarising would lose, or NULL. The pattern's own fields are rebuilt; FOLD's
// derived ones (vertices_vertices, faceOrders, ...) go stale and are dropped anyway.
static const char *index_field_lost(const ori_fold *doc, int frame)
{
    static const char *const rebuilt[] = {"vertices_coords", "edges_vertices", "edges_assignment", "edges_foldAngle",
                                          "faces_vertices"};
    for (int depth = 0; depth <= MAX_INHERIT_DEPTH && frame >= 0 && frame < doc->frame_count; ++depth) {
        const ori__frame *fr = &doc->frames[frame];
        for (int i = 0; i < fr->count; ++i) {
            const char *key = fr->fields[i].key;
            if (strncmp(key, "vertices_", 9) != 0 && strncmp(key, "edges_", 6) != 0 && strncmp(key, "faces_", 6) != 0)
                continue;
            bool ok = is_derived(key);
            for (size_t k = 0; k < sizeof rebuilt / sizeof rebuilt[0] && !ok; ++k) ok = strcmp(key, rebuilt[k]) == 0;
            if (!ok) return key;
        }
        const ori__field *inh = own_field(doc, frame, "frame_inherit");
        const ori__field *parent = own_field(doc, frame, "frame_parent");
        if (frame == 0 || !inh || !json_is_true(inh->json) || !parent || !json_is_integer(parent->json)) break;
        frame = (int)json_integer_value(parent->json);
    }
    return NULL;
}

static bool boundary_like(ori_assignment a) { return a == ORI_ASSIGN_BOUNDARY || a == ORI_ASSIGN_CUT; }

// The planar pattern of the file's edges as segments (read: the frame as read, unbuilt). The
// arrangement is made twice, overlapped edges keeping the first and taking the last segment's
// assignment (the geometry is the same): where the two differ, a boundary or cut wins over a
// crease and an assigned crease over U; two different creases (M on V) are refused.
static ori_status planarize(const ori_pattern *read, ori_pattern **out, ori_error *error)
{
    *out = NULL;
    int m = read->edge_count;
    ori_segment *segs = ori__alloc(sizeof(ori_segment) * (size_t)(m ? m : 1));
    for (int e = 0; e < m; ++e) {
        ori_v3 a = read->vertices[read->edges[e].v[0]], b = read->vertices[read->edges[e].v[1]];
        segs[e] = (ori_segment){ori_v2_make(a.x, a.y), ori_v2_make(b.x, b.y), read->edges[e].assignment,
                                read->edges[e].fold_angle_rad};
    }
    ori_insert_def idef = ori_default_insert_def();
    idef.name_faces = false;
    idef.overlap = ORI_OVERLAP_KEEP_EXISTING;
    ori_pattern *first = NULL, *last = NULL;
    ori_status st = ori_pattern_from_segments(segs, m, &idef, &first, NULL, error);
    idef.overlap = ORI_OVERLAP_REPLACE;
    if (st == ORI_OK) st = ori_pattern_from_segments(segs, m, &idef, &last, NULL, error);
    ori__free(segs);
    if (st == ORI_OK && (first->edge_count != last->edge_count || first->vertex_count != last->vertex_count))
        st = ori__fail(error, ORI_ERR_INTERNAL, "planarising the edges gave two different arrangements");
    for (int e = 0; st == ORI_OK && e < first->edge_count; ++e) {
        ori_edge *f = &first->edges[e];
        const ori_edge *l = &last->edges[e];
        if (f->assignment == l->assignment && f->fold_angle_rad == l->fold_angle_rad) continue;
        bool fb = boundary_like(f->assignment), lb = boundary_like(l->assignment);
        if (fb || lb) { // the sheet's outline stays
            if (lb && !fb) f->assignment = l->assignment, f->fold_angle_rad = l->fold_angle_rad;
            continue;
        }
        if (f->assignment == ORI_ASSIGN_UNASSIGNED) {
            f->assignment = l->assignment, f->fold_angle_rad = l->fold_angle_rad;
            continue;
        }
        if (l->assignment == ORI_ASSIGN_UNASSIGNED) continue;
        ori_v3 a = first->vertices[f->v[0]], b = first->vertices[f->v[1]];
        if (f->assignment != l->assignment)
            st = ori__fail_at(error, ORI_ERR_TOPOLOGY, "edges_assignment", ORI_NULL_INDEX,
                              "overlapping creases disagree on (%g, %g)-(%g, %g): %s and %s", a.x, a.y, b.x, b.y,
                              ori_assignment_name(f->assignment), ori_assignment_name(l->assignment));
        else
            st = ori__fail_at(error, ORI_ERR_TOPOLOGY, "edges_foldAngle", ORI_NULL_INDEX,
                              "overlapping creases disagree on (%g, %g)-(%g, %g): %g and %g degrees", a.x, a.y, b.x, b.y,
                              ori_rad_to_deg_output(f->fold_angle_rad), ori_rad_to_deg_output(l->fold_angle_rad));
    }
    ori_pattern_destroy(last);
    if (st != ORI_OK) {
        ori_pattern_destroy(first);
        return st;
    }
    first->has_fold_angles = read->has_fold_angles;
    first->absent_fold_angles = read->absent_fold_angles;
    first->planarized_from = m;
    *out = first;
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
    const ori__field *coords = frame_field(doc, frame, "vertices_coords");
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
    bool repeats = st == ORI_ERR_TOPOLOGY && error && strcmp(error->field, "edges_vertices") == 0 &&
                   strncmp(error->message, "edge repeats", 12) == 0;
    if ((st == ORI_ERR_CROSSING || repeats) && def && def->planarize && !p->folded_form) {
        const char *lost = index_field_lost(doc, frame);
        if (lost) {
            if (error) {
                size_t n = strlen(error->message);
                snprintf(error->message + n, sizeof error->message - n,
                         " (planarising the frame would lose %s, which follows the file's numbering)", lost);
            }
        } else {
            ori_pattern *q = NULL;
            ori_error_clear(error);
            st = planarize(p, &q, error);
            ori_pattern_destroy(p);
            p = q;
        }
    }
    if (st != ORI_OK) {
        ori_pattern_destroy(p);
        return st;
    }
    *out = p;
    return ORI_OK;
}

// --- writing a pattern ---------------------------------------------------------------------

static ori__packed *coords_packed(const ori_v3 *vertices, int count, bool three)
{
    ori__packed *pk = ori__pk_new(ORI__PK_ROWS, false, (int64_t)count * (three ? 3 : 2));
    for (int i = 0; i < count; ++i) {
        ori__pk_push_real(pk, vertices[i].x);
        ori__pk_push_real(pk, vertices[i].y);
        if (three) ori__pk_push_real(pk, vertices[i].z);
        ori__pk_end_row(pk);
    }
    ori__pk_shrink(pk);
    return pk;
}

// Number e of an old edges_foldAngle field, if it is one.
static bool old_angle(const ori__field *old, int64_t e, double *deg)
{
    if (!old) return false;
    if (old->pk) {
        if (old->pk->kind != ORI__PK_NUMS || e >= old->pk->count) return false;
        *deg = ori__pk_num(old->pk, e);
        return true;
    }
    json_t *o = json_array_get(old->json, (size_t)e);
    if (!json_is_number(o)) return false;
    *deg = json_number_value(o);
    return true;
}

// Fold angles in degrees; an unchanged angle keeps the file's own number.
static ori__packed *fold_angles_packed(const double *angles_rad, int count, const ori__field *old)
{
    int64_t old_n = !old ? -1 : old->pk ? old->pk->count : (int64_t)json_array_size(old->json);
    bool same_size = old_n == count;
    ori__packed *pk = ori__pk_new(ORI__PK_NUMS, false, count);
    for (int e = 0; e < count; ++e) {
        double rad = angles_rad[e], deg;
        if (same_size && old_angle(old, e, &deg) && ori_deg_to_rad(deg) == rad) ori__pk_push_real(pk, deg);
        else ori__pk_push_real(pk, ori_rad_to_deg_output(rad));
    }
    ori__pk_shrink(pk);
    return pk;
}

static ori__packed *pattern_angles_packed(const ori_pattern *p, const ori__field *old)
{
    double *a = ori__alloc(sizeof(double) * (size_t)(p->edge_count ? p->edge_count : 1));
    for (int e = 0; e < p->edge_count; ++e) a[e] = p->edges[e].fold_angle_rad;
    ori__packed *pk = fold_angles_packed(a, p->edge_count, old);
    ori__free(a);
    return pk;
}

// The pattern's angles as a JSON array that keeps the file's null entries (absent angles, read
// as 0) where the angle is still 0; NULL when the old field has no null to keep.
static json_t *angles_keeping_nulls(const ori_pattern *p, const ori__field *old)
{
    if (!old || old->pk || !json_is_array(old->json) || json_array_size(old->json) != (size_t)p->edge_count) return NULL;
    bool any = false;
    for (int e = 0; e < p->edge_count && !any; ++e)
        any = json_is_null(json_array_get(old->json, (size_t)e)) && p->edges[e].fold_angle_rad == 0.0;
    if (!any) return NULL;
    json_t *a = json_array();
    for (int e = 0; e < p->edge_count; ++e) {
        json_t *o = json_array_get(old->json, (size_t)e);
        double rad = p->edges[e].fold_angle_rad, deg;
        if (json_is_null(o) && rad == 0.0) json_array_append_new(a, json_null());
        else if (old_angle(old, e, &deg) && ori_deg_to_rad(deg) == rad) json_array_append(a, o);
        else json_array_append_new(a, json_real(ori_rad_to_deg_output(rad)));
    }
    return a;
}

static ori__packed *edges_packed(const ori_pattern *p)
{
    ori__packed *pk = ori__pk_new(ORI__PK_ROWS, true, 2 * (int64_t)p->edge_count);
    for (int e = 0; e < p->edge_count; ++e) {
        ori__pk_push_int(pk, p->edges[e].v[0]);
        ori__pk_push_int(pk, p->edges[e].v[1]);
        ori__pk_end_row(pk);
    }
    ori__pk_shrink(pk);
    return pk;
}

static ori__packed *assignments_packed(const ori_pattern *p)
{
    ori__packed *pk = ori__pk_new(ORI__PK_STRS, false, p->edge_count);
    for (int e = 0; e < p->edge_count; ++e) {
        char c = ori_assignment_to_char(p->edges[e].assignment);
        ori__pk_push_string(pk, &c, 1);
    }
    ori__pk_shrink(pk);
    return pk;
}

static ori__packed *faces_packed(const ori_pattern *p)
{
    ori__packed *pk = ori__pk_new(ORI__PK_ROWS, true, p->face_vertex_count);
    for (int f = 0; f < p->face_count; ++f) {
        for (int k = p->face_offsets[f]; k < p->face_offsets[f + 1]; ++k) ori__pk_push_int(pk, p->face_vertices[k]);
        ori__pk_end_row(pk);
    }
    ori__pk_shrink(pk);
    return pk;
}

static bool any_face_name(const ori_pattern *p)
{
    if (!p->face_names) return false;
    for (int f = 0; f < p->face_count; ++f)
        if (p->face_names[f][0]) return true;
    return false;
}

// The pattern's fields into a frame; angles (or angles_json) are its edges_foldAngle when the
// pattern has fold angles (both NULL: written from the pattern).
static void write_pattern_fields(ori__frame *fr, const ori_pattern *p, ori__packed *angles, json_t *angles_json,
                                 bool three)
{
    ori__frame_set(fr, "vertices_coords", NULL, coords_packed(p->vertices, p->vertex_count, three));
    ori__frame_set(fr, "edges_vertices", NULL, edges_packed(p));
    ori__frame_set(fr, "edges_assignment", NULL, assignments_packed(p));
    if (p->has_fold_angles && angles_json) ori__frame_set(fr, "edges_foldAngle", angles_json, NULL);
    else if (p->has_fold_angles) ori__frame_set(fr, "edges_foldAngle", NULL, angles ? angles : pattern_angles_packed(p, NULL));
    else ori__frame_del(fr, "edges_foldAngle");
    if (p->face_count > 0) ori__frame_set(fr, "faces_vertices", NULL, faces_packed(p));
    else ori__frame_del(fr, "faces_vertices"); // (the frame's old faces, if any, are another pattern's)
    if (any_face_name(p)) {
        json_t *names = json_array();
        for (int f = 0; f < p->face_count; ++f)
            json_array_append_new(names, p->face_names[f][0] ? json_string(p->face_names[f]) : json_null());
        ori__frame_set(fr, ORI__KEY_FACES_NAME, names, NULL);
    } else {
        ori__frame_del(fr, ORI__KEY_FACES_NAME);
    }
    if (p->tree_count > 0) {
        json_t *tree = json_array();
        for (int i = 0; i < p->tree_count; ++i)
            json_array_append_new(tree, json_pack("{sssi}", "name", p->tree[i].name, "parent", p->tree[i].parent));
        ori__frame_set(fr, ORI__KEY_FACE_TREE, tree, NULL);
    } else {
        ori__frame_del(fr, ORI__KEY_FACE_TREE);
    }
}

static int64_t field_count(const ori__field *f)
{
    if (!f) return -1;
    if (f->pk) return f->pk->count;
    return json_is_array(f->json) ? (int64_t)json_array_size(f->json) : -1;
}

// Whether any row of the frame's vertices_coords had 3 numbers (a file may mix [x, y] and
// [x, y, z] rows: the first row alone does not say).
static bool had_three_coords(const ori__field *coords)
{
    if (!coords) return false;
    if (coords->pk) {
        if (coords->pk->kind != ORI__PK_ROWS) return false;
        for (int64_t i = 0; i < coords->pk->count; ++i)
            if (ori__pk_len(coords->pk, i) == 3) return true;
        return false;
    }
    size_t i;
    json_t *row;
    json_array_foreach(coords->json, i, row)
    {
        if (json_is_array(row) && json_array_size(row) == 3) return true;
    }
    return false;
}

// Whether the pattern's coordinates need a z to be written without loss: any z that is not
// exactly 0 (ori_pattern_is_3d ignores a z within the planarity tolerance, which a 2D row would
// drop: fuzz_fold found a vertex at y = 6e15 with z = 0.28 written as [x, y]).
static bool needs_z(const ori_pattern *p)
{
    for (int i = 0; i < p->vertex_count; ++i)
        if (p->vertices[i].z != 0.0) return true;
    return false;
}

// Whether entry i of an index-array field equals ints[0..n).
static bool same_row(const ori__field *f, int64_t i, const int *ints, int n)
{
    if (f->pk) {
        const ori__packed *pk = f->pk;
        if (pk->kind != ORI__PK_ROWS || ori__pk_len(pk, i) != n || pk->first_real == i) return false;
        int64_t s = ori__pk_start(pk, i);
        for (int k = 0; k < n; ++k)
            if (ori__pk_num(pk, s + k) != ints[k]) return false;
        return true;
    }
    json_t *arr = json_array_get(f->json, (size_t)i);
    if (!json_is_array(arr) || json_array_size(arr) != (size_t)n) return false;
    for (int k = 0; k < n; ++k) {
        json_t *x = json_array_get(arr, (size_t)k);
        if (!json_is_integer(x) || json_integer_value(x) != ints[k]) return false;
    }
    return true;
}

// The file's edges_vertices are the pattern's edges (compared in place, no copy built).
static bool same_edges(const ori__field *old, const ori_pattern *p)
{
    if (field_count(old) != p->edge_count) return false;
    for (int e = 0; e < p->edge_count; ++e)
        if (!same_row(old, e, p->edges[e].v, 2)) return false;
    return true;
}

// The file's faces_vertices are the pattern's faces (both absent counts as the same).
static bool same_faces(const ori__field *old, const ori_pattern *p)
{
    if (!old) return p->face_count == 0;
    if (field_count(old) != p->face_count) return false;
    for (int f = 0; f < p->face_count; ++f)
        if (!same_row(old, f, p->face_vertices + p->face_offsets[f], p->face_offsets[f + 1] - p->face_offsets[f]))
            return false;
    return true;
}

// Make a frame that inherits hold its inherited fields itself and stop inheriting, so that a field
// the new pattern does not have (fold angles, faces, names) or a derived field that is stale can
// be removed without the parent's showing through.
static bool any_face_name(const ori_pattern *p);

static void detach_frame(ori_fold *doc, int frame)
{
    const ori__field *inh = own_field(doc, frame, "frame_inherit");
    if (frame == 0 || !inh || !json_is_true(inh->json)) return;
    int k = frame;
    for (int depth = 0; depth <= MAX_INHERIT_DEPTH; ++depth) {
        const ori__field *i = own_field(doc, k, "frame_inherit"), *parent = own_field(doc, k, "frame_parent");
        if (k == 0 || !i || !json_is_true(i->json) || !parent) break;
        k = (int)json_integer_value(parent->json);
        const ori__frame *from = &doc->frames[k];
        for (int j = 0; j < from->count; ++j) {
            const ori__field *f = &from->fields[j];
            if ((!f->json && !f->pk) || strncmp(f->key, "file_", 5) == 0 || strcmp(f->key, "frame_parent") == 0 ||
                strcmp(f->key, "frame_inherit") == 0 || own_field(doc, frame, f->key))
                continue;
            json_t *json = f->json ? json_deep_copy(f->json) : NULL;
            ori__packed *pk = f->pk ? ori__pk_copy(f->pk) : NULL;
            ori__frame_set(&doc->frames[frame], f->key, json, pk); // (may move doc->frames[frame]'s fields: from is another frame)
        }
    }
    ori__frame_set(&doc->frames[frame], "frame_inherit", json_false(), NULL);
}

// Whether a frame inherits and one of the frames it inherits from has the field (it would show
// through were the frame's own removed).
static bool inherited(const ori_fold *doc, int frame, const char *key)
{
    const ori__field *inh = own_field(doc, frame, "frame_inherit"), *parent = own_field(doc, frame, "frame_parent");
    if (frame == 0 || !inh || !json_is_true(inh->json) || !parent) return false;
    return frame_field(doc, (int)json_integer_value(parent->json), key) != NULL;
}

ori_status ori_fold_set_pattern(ori_fold *doc, int frame, const ori_pattern *p, ori_error *error)
{
    ORI_ASSERT(doc && p);
    if (frame < 0 || frame >= ori_fold_frame_count(doc))
        return ori__fail(error, ORI_ERR_RANGE, "frame %d does not exist", frame);
    const ori__field *old_coords = frame_field(doc, frame, "vertices_coords");
    bool three = needs_z(p) || had_three_coords(old_coords);
    // Same topology? Then FOLD's derived index fields stay valid.
    bool same = field_count(old_coords) == p->vertex_count && same_edges(frame_field(doc, frame, "edges_vertices"), p) &&
                same_faces(frame_field(doc, frame, "faces_vertices"), p);
    // (The old angles may be this frame's own field, replaced below: the new ones first.)
    const ori__field *old_angles = frame_field(doc, frame, "edges_foldAngle");
    json_t *angles_json = p->has_fold_angles ? angles_keeping_nulls(p, old_angles) : NULL;
    ori__packed *angles = p->has_fold_angles && !angles_json ? pattern_angles_packed(p, old_angles) : NULL;
    // A field the pattern does not have, or a stale derived one, can only be removed from a frame
    // that does not inherit it: such a frame first takes its inherited fields in.
    bool detach = !same || (!p->has_fold_angles && inherited(doc, frame, "edges_foldAngle")) ||
                  (p->face_count == 0 && inherited(doc, frame, "faces_vertices")) ||
                  (!any_face_name(p) && inherited(doc, frame, ORI__KEY_FACES_NAME)) ||
                  (p->tree_count == 0 && inherited(doc, frame, ORI__KEY_FACE_TREE));
    if (detach) detach_frame(doc, frame);
    ori__frame *fr = &doc->frames[frame];
    write_pattern_fields(fr, p, angles, angles_json, three);
    if (!same)
        for (size_t i = 0; i < sizeof derived_fields / sizeof derived_fields[0]; ++i) ori__frame_del(fr, derived_fields[i]);
    return ORI_OK;
}

// A document with a motion (frames appended by orikin) is an animation (FOLD file_classes):
// "singleModel" becomes "animation", other classes stay.
static void mark_animation(ori_fold *doc)
{
    const ori__field *c = ori__frame_find(&doc->frames[0], "file_classes");
    json_t *classes = !c ? json_array() : c->pk ? ori__pk_to_json(c->pk) : json_is_array(c->json) ? json_copy(c->json) : json_array();
    size_t i, single = (size_t)-1;
    json_t *v;
    json_array_foreach(classes, i, v)
    {
        if (!json_is_string(v)) continue;
        if (strcmp(json_string_value(v), "animation") == 0) {
            json_decref(classes);
            return;
        }
        if (strcmp(json_string_value(v), "singleModel") == 0 && single == (size_t)-1) single = i;
    }
    if (single != (size_t)-1) json_array_set_new(classes, single, json_string("animation"));
    else json_array_append_new(classes, json_string("animation"));
    ori__frame_set(&doc->frames[0], "file_classes", classes, NULL);
}

static ori__frame *new_frame(ori_fold *doc, const char *frame_class, const char *title)
{
    mark_animation(doc);
    if (!ori__frame_find(&doc->frames[0], "file_frames")) ori__frame_set(&doc->frames[0], "file_frames", NULL, NULL);
    int k = ori__doc_add_frame(doc);
    ori__frame *fr = &doc->frames[k];
    if (title) ori__frame_set(fr, "frame_title", json_string(title), NULL);
    if (frame_class) {
        json_t *classes = json_array();
        json_array_append_new(classes, json_string(frame_class));
        ori__frame_set(fr, "frame_classes", classes, NULL);
    }
    return fr;
}

static void set_state_fields(ori__frame *fr, int parent, int vertex_count, const ori_v3 *positions, int edge_count,
                             const double *angles_rad)
{
    ori__frame_set(fr, "frame_parent", json_integer(parent), NULL);
    ori__frame_set(fr, "frame_inherit", json_true(), NULL);
    ori__frame_set(fr, "vertices_coords", NULL, coords_packed(positions, vertex_count, true));
    ori__frame_set(fr, "edges_foldAngle", NULL, fold_angles_packed(angles_rad, edge_count, NULL));
}

int ori_fold_append_frame(ori_fold *doc, const ori_pattern *p, const char *frame_class, const char *title, int parent)
{
    ORI_ASSERT(doc && p);
    ORI_ASSERT(parent == ORI_NULL_INDEX || (parent >= 0 && parent < ori_fold_frame_count(doc)));
    ori__frame *fr = new_frame(doc, frame_class, title);
    if (parent == ORI_NULL_INDEX) {
        write_pattern_fields(fr, p, NULL, NULL, needs_z(p));
    } else {
        double *a = ori__alloc(sizeof(double) * (size_t)(p->edge_count ? p->edge_count : 1));
        for (int e = 0; e < p->edge_count; ++e) a[e] = p->edges[e].fold_angle_rad;
        set_state_fields(fr, parent, p->vertex_count, p->vertices, p->edge_count, a);
        ori__free(a);
    }
    return ori_fold_frame_count(doc) - 1;
}

int ori_fold_append_state(ori_fold *doc, int parent, int vertex_count, const ori_v3 *positions, int edge_count,
                          const double *angles_rad, const char *title)
{
    ORI_ASSERT(doc && positions && angles_rad && vertex_count >= 0 && edge_count >= 0);
    ORI_ASSERT(parent >= 0 && parent < ori_fold_frame_count(doc));
    ori__frame *fr = new_frame(doc, "foldedForm", title);
    set_state_fields(fr, parent, vertex_count, positions, edge_count, angles_rad);
    return ori_fold_frame_count(doc) - 1;
}

ori_status ori_fold_extract_frame(const ori_fold *doc, int frame, ori_fold **out, ori_error *error)
{
    ORI_ASSERT(doc && out);
    *out = NULL;
    ori_error_clear(error);
    if (frame < 0 || frame >= doc->frame_count)
        return ori__fail(error, ORI_ERR_RANGE, "frame %d does not exist (frames 0 to %d)", frame, doc->frame_count - 1);
    ori_fold *x = ori__doc_new();
    ori__frame *top = &x->frames[0];
    const ori__frame *f0 = &doc->frames[0];
    // The file's own metadata (file_title, file_author, …), then the frame's fields, nearest first.
    for (int i = 0; i < f0->count; ++i) {
        const ori__field *f = &f0->fields[i];
        if (strncmp(f->key, "file_", 5) != 0 || strcmp(f->key, "file_frames") == 0) continue;
        if (strcmp(f->key, "file_classes") == 0) {
            json_t *classes = json_array();
            json_array_append_new(classes, json_string("singleModel"));
            ori__frame_set(top, f->key, classes, NULL);
            continue;
        }
        ori__frame_set(top, f->key, f->json ? json_deep_copy(f->json) : NULL, f->pk ? ori__pk_copy(f->pk) : NULL);
    }
    int k = frame;
    for (int depth = 0; depth <= MAX_INHERIT_DEPTH; ++depth) {
        const ori__frame *fr = &doc->frames[k];
        for (int i = 0; i < fr->count; ++i) {
            const ori__field *f = &fr->fields[i];
            if (!f->json && !f->pk) continue; // (the file_frames marker)
            if (strncmp(f->key, "file_", 5) == 0 || strcmp(f->key, "frame_parent") == 0 ||
                strcmp(f->key, "frame_inherit") == 0 || ori__frame_find(top, f->key))
                continue;
            ori__frame_set(top, f->key, f->json ? json_deep_copy(f->json) : NULL, f->pk ? ori__pk_copy(f->pk) : NULL);
        }
        const ori__field *inh = own_field(doc, k, "frame_inherit"), *parent = own_field(doc, k, "frame_parent");
        if (k == 0 || !inh || !json_is_true(inh->json) || !parent) break;
        k = (int)json_integer_value(parent->json); // (checked on load)
    }
    if (!ori__frame_find(top, "file_spec")) ori__frame_set(top, "file_spec", json_real(1.2), NULL);
    if (!ori__frame_find(top, "file_classes")) {
        json_t *classes = json_array();
        json_array_append_new(classes, json_string("singleModel"));
        ori__frame_set(top, "file_classes", classes, NULL);
    }
    *out = x;
    return ORI_OK;
}

// --- custom fields -------------------------------------------------------------------------

char *ori_fold_get_custom(const ori_fold *doc, int frame, const char *key)
{
    ORI_ASSERT(doc && key && frame >= 0 && frame < ori_fold_frame_count(doc));
    const ori__field *f = frame_field(doc, frame, key);
    if (!f) return NULL;
    ori__text t = {NULL, 0, 0};
    ori__field_write_compact(doc, f, &t);
    return t.data;
}

ori_status ori_fold_set_custom(ori_fold *doc, int frame, const char *key, const char *json, ori_error *error)
{
    ORI_ASSERT(doc && key && frame >= 0 && frame < ori_fold_frame_count(doc));
    ori_error_clear(error);
    bool frames_key = frame == 0 && strcmp(key, "file_frames") == 0;
    if (!json) {
        if (frames_key) ori__doc_drop_frames(doc);
        else ori__frame_del(&doc->frames[frame], key);
        return ORI_OK;
    }
    if (frames_key) {
        // New frames: read as the file_frames of a document of their own, then moved here.
        size_t n = strlen(json);
        char *text = ori__alloc(n + 32);
        snprintf(text, n + 32, "{\"file_frames\":%s}", json);
        ori_fold *tmp = NULL;
        ori_status st = ori_fold_load_string(text, strlen(text), &tmp, error);
        ori__free(text);
        if (st != ORI_OK) return st;
        ori__doc_drop_frames(doc);
        ori__frame_set(&doc->frames[0], "file_frames", NULL, NULL);
        for (int k = 1; k < tmp->frame_count; ++k) {
            int f = ori__doc_add_frame(doc);
            doc->frames[f] = tmp->frames[k];
            memset(&tmp->frames[k], 0, sizeof tmp->frames[k]);
        }
        ori_fold_destroy(tmp);
        return ORI_OK;
    }
    json_t *v = NULL;
    ori__packed *pk = NULL;
    ori_status st = ori__doc_parse_value(json, strlen(json), &v, &pk, error);
    if (st != ORI_OK) return st;
    ori__frame_set(&doc->frames[frame], key, v, pk);
    return ORI_OK;
}

void ori_fold_set_string(ori_fold *doc, int frame, const char *key, const char *value)
{
    ORI_ASSERT(doc && key && value && frame >= 0 && frame < ori_fold_frame_count(doc));
    ori__frame_set(&doc->frames[frame], key, json_string(value), NULL);
}

// --- output ------------------------------------------------------------------------------

char *ori_fold_to_string(const ori_fold *doc)
{
    ORI_ASSERT(doc);
    ori__text t = {NULL, 0, 0};
    ori__doc_write(doc, &t);
    return t.data;
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

void ori_format_real(double x, char *buf, size_t size)
{
    ORI_ASSERT(buf && size >= 32);
    ori__format_double(x, buf, size);
}

ori_status ori_fold_save_file(const ori_fold *doc, const char *path, ori_error *error)
{
    char *text = ori_fold_to_string(doc);
    ori_status st = ori_file_write_atomic(path, text, strlen(text), error);
    ori_buffer_free(text);
    return st;
}
