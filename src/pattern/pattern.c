// Crease pattern storage: creation, mutation, getters, face names and the face tree.
#include "pattern_internal.h"

static const char assignment_chars[ORI_ASSIGN_COUNT] = {'B', 'M', 'V', 'F', 'U', 'C', 'J'};
static const char *const assignment_names[ORI_ASSIGN_COUNT] = {
    "boundary", "mountain", "valley", "flat", "unassigned", "cut", "join"};

char ori_assignment_to_char(ori_assignment a)
{
    ORI_ASSERT((int)a >= 0 && a < ORI_ASSIGN_COUNT);
    return assignment_chars[a];
}

bool ori_assignment_from_char(char c, ori_assignment *out)
{
    if (c >= 'a' && c <= 'z') c = (char)(c - 'a' + 'A');
    for (int i = 0; i < ORI_ASSIGN_COUNT; ++i)
        if (assignment_chars[i] == c) {
            *out = (ori_assignment)i;
            return true;
        }
    return false;
}

const char *ori_assignment_name(ori_assignment a)
{
    ORI_ASSERT((int)a >= 0 && a < ORI_ASSIGN_COUNT);
    return assignment_names[a];
}

bool ori_assignment_is_fold(ori_assignment a)
{
    return a == ORI_ASSIGN_MOUNTAIN || a == ORI_ASSIGN_VALLEY || a == ORI_ASSIGN_UNASSIGNED;
}

ori_pattern_def ori_default_pattern_def(void)
{
    ori_pattern_def def;
    def.vertex_capacity = 0;
    def.edge_capacity = 0;
    def.internal_value = ORI__DEF_COOKIE;
    return def;
}

ori_pattern *ori_pattern_create(const ori_pattern_def *def)
{
    ORI_ASSERT(def && def->internal_value == ORI__DEF_COOKIE);
    ORI_ASSERT(def->vertex_capacity >= 0 && def->edge_capacity >= 0);
    ori_pattern *p = ori__calloc(1, sizeof *p);
    if (def->vertex_capacity) ORI__RESERVE(p->vertices, p->vertex_cap, def->vertex_capacity);
    if (def->edge_capacity) ORI__RESERVE(p->edges, p->edge_cap, def->edge_capacity);
    ORI__RESERVE(p->face_offsets, p->face_cap, 1);
    p->face_offsets[0] = 0;
    p->diagonal = 1.0;
    return p;
}

static void free_derived(ori_pattern *p)
{
    ori__free(p->vert_edge_offsets);
    ori__free(p->vert_edges);
    ori__free(p->face_edges);
    ori__free(p->edge_faces);
    ori__free(p->edge_hash);
    p->vert_edge_offsets = p->vert_edges = p->face_edges = p->edge_faces = p->edge_hash = NULL;
    p->edge_hash_cap = 0;
}

void ori__pattern_invalidate(ori_pattern *p)
{
    if (!p->built) return;
    free_derived(p);
    p->built = false;
}

void ori_pattern_destroy(ori_pattern *p)
{
    if (!p) return;
    free_derived(p);
    ori__free(p->vertices);
    ori__free(p->edges);
    ori__free(p->face_offsets);
    ori__free(p->face_vertices);
    ori__free(p->face_names);
    ori__free(p->tree);
    ori__free(p->tree_hash);
    ori__free(p);
}

static void *dup_array(const void *src, size_t bytes)
{
    if (!src || bytes == 0) return NULL;
    void *d = ori__alloc(bytes);
    memcpy(d, src, bytes);
    return d;
}

ori_pattern *ori_pattern_clone(const ori_pattern *s)
{
    ORI_ASSERT(s);
    ori_pattern *p = ori__calloc(1, sizeof *p);
    *p = *s;
    p->vertices = dup_array(s->vertices, sizeof(ori_v3) * (size_t)s->vertex_cap);
    p->edges = dup_array(s->edges, sizeof(ori_edge) * (size_t)s->edge_cap);
    p->face_offsets = dup_array(s->face_offsets, sizeof(int) * (size_t)s->face_cap);
    p->face_vertices = dup_array(s->face_vertices, sizeof(int) * (size_t)s->face_vertex_cap);
    p->face_names = dup_array(s->face_names, sizeof(*s->face_names) * (size_t)s->face_cap);
    p->tree = dup_array(s->tree, sizeof(ori_tree_node) * (size_t)s->tree_cap);
    p->tree_hash = dup_array(s->tree_hash, sizeof(int) * (size_t)s->tree_hash_cap);
    if (s->built) {
        p->vert_edge_offsets = dup_array(s->vert_edge_offsets, sizeof(int) * (size_t)(s->vertex_count + 1));
        p->vert_edges = dup_array(s->vert_edges, sizeof(int) * 2 * (size_t)s->edge_count);
        p->face_edges = dup_array(s->face_edges, sizeof(int) * (size_t)s->face_vertex_count);
        p->edge_faces = dup_array(s->edge_faces, sizeof(int) * 2 * (size_t)s->edge_count);
        p->edge_hash = dup_array(s->edge_hash, sizeof(int) * (size_t)s->edge_hash_cap);
    }
    return p;
}

int ori_pattern_add_vertex(ori_pattern *p, ori_v3 position)
{
    ORI_ASSERT(p);
    ori__pattern_invalidate(p);
    ORI__PUSH(p->vertices, p->vertex_count, p->vertex_cap, position);
    return p->vertex_count - 1;
}

int ori_pattern_add_edge(ori_pattern *p, int v0, int v1, ori_assignment a, double fold_angle_rad)
{
    ORI_ASSERT(p && (int)a >= 0 && a < ORI_ASSIGN_COUNT);
    ori__pattern_invalidate(p);
    ori_edge e;
    e.v[0] = v0;
    e.v[1] = v1;
    e.assignment = a;
    e.fold_angle_rad = fold_angle_rad;
    ORI__PUSH(p->edges, p->edge_count, p->edge_cap, e);
    return p->edge_count - 1;
}

void ori__pattern_reserve_faces(ori_pattern *p, int faces, int face_vertices)
{
    int old_cap = p->face_cap;
    ORI__RESERVE(p->face_offsets, p->face_cap, faces + 1);
    if (p->face_names && p->face_cap != old_cap) {
        p->face_names = ori__realloc(p->face_names, sizeof(*p->face_names) * (size_t)p->face_cap);
        memset(p->face_names + old_cap, 0, sizeof(*p->face_names) * (size_t)(p->face_cap - old_cap));
    }
    ORI__RESERVE(p->face_vertices, p->face_vertex_cap, face_vertices);
}

int ori_pattern_add_face(ori_pattern *p, const int *vertices, int count)
{
    ORI_ASSERT(p && vertices && count >= 1);
    ori__pattern_invalidate(p);
    ori__pattern_reserve_faces(p, p->face_count + 1, p->face_vertex_count + count);
    memcpy(p->face_vertices + p->face_vertex_count, vertices, sizeof(int) * (size_t)count);
    p->face_vertex_count += count;
    p->face_count += 1;
    p->face_offsets[p->face_count] = p->face_vertex_count;
    if (p->face_names) p->face_names[p->face_count - 1][0] = '\0';
    return p->face_count - 1;
}

void ori_pattern_set_vertex(ori_pattern *p, int v, ori_v3 position)
{
    ORI_ASSERT(p && v >= 0 && v < p->vertex_count);
    ori__pattern_invalidate(p);
    p->vertices[v] = position;
}

void ori_pattern_set_assignment(ori_pattern *p, int e, ori_assignment a)
{
    ORI_ASSERT(p && e >= 0 && e < p->edge_count && (int)a >= 0 && a < ORI_ASSIGN_COUNT);
    p->edges[e].assignment = a;
}

void ori_pattern_set_fold_angle(ori_pattern *p, int e, double fold_angle_rad)
{
    ORI_ASSERT(p && e >= 0 && e < p->edge_count);
    p->edges[e].fold_angle_rad = fold_angle_rad;
}

void ori_pattern_clear_faces(ori_pattern *p)
{
    ORI_ASSERT(p);
    ori__pattern_invalidate(p);
    p->face_count = 0;
    p->face_vertex_count = 0;
    p->face_offsets[0] = 0;
    if (p->face_names) {
        ori__free(p->face_names);
        p->face_names = NULL;
    }
}

void ori_pattern_set_folded_form(ori_pattern *p, bool folded_form)
{
    ORI_ASSERT(p);
    ori__pattern_invalidate(p);
    p->folded_form = folded_form;
}

void ori_pattern_set_has_fold_angles(ori_pattern *p, bool has) { ORI_ASSERT(p); p->has_fold_angles = has; }

bool ori_pattern_is_built(const ori_pattern *p) { return p && p->built; }
int ori_pattern_vertex_count(const ori_pattern *p) { ORI_ASSERT(p); return p->vertex_count; }
int ori_pattern_edge_count(const ori_pattern *p) { ORI_ASSERT(p); return p->edge_count; }
int ori_pattern_face_count(const ori_pattern *p) { ORI_ASSERT(p); return p->face_count; }

ori_v3 ori_pattern_vertex(const ori_pattern *p, int v)
{
    ORI_ASSERT(p && v >= 0 && v < p->vertex_count);
    return p->vertices[v];
}

ori_edge ori_pattern_edge(const ori_pattern *p, int e)
{
    ORI_ASSERT(p && e >= 0 && e < p->edge_count);
    return p->edges[e];
}

int ori_pattern_face_size(const ori_pattern *p, int f)
{
    ORI_ASSERT(p && f >= 0 && f < p->face_count);
    return p->face_offsets[f + 1] - p->face_offsets[f];
}

int ori_pattern_face_vertices(const ori_pattern *p, int f, int *out, int cap)
{
    int n = ori_pattern_face_size(p, f);
    int m = n < cap ? n : cap;
    if (out && m > 0) memcpy(out, p->face_vertices + p->face_offsets[f], sizeof(int) * (size_t)m);
    return n;
}

int ori_pattern_face_edges(const ori_pattern *p, int f, int *out, int cap)
{
    ORI_ASSERT(p && p->built);
    int n = ori_pattern_face_size(p, f);
    int m = n < cap ? n : cap;
    if (out && m > 0) memcpy(out, p->face_edges + p->face_offsets[f], sizeof(int) * (size_t)m);
    return n;
}

bool ori_pattern_is_folded_form(const ori_pattern *p) { ORI_ASSERT(p); return p->folded_form; }
bool ori_pattern_has_fold_angles(const ori_pattern *p) { ORI_ASSERT(p); return p->has_fold_angles; }
int ori_pattern_absent_fold_angle_count(const ori_pattern *p) { ORI_ASSERT(p); return p->absent_fold_angles; }
int ori_pattern_planarized_from(const ori_pattern *p) { ORI_ASSERT(p); return p->planarized_from; }

bool ori_pattern_is_3d(const ori_pattern *p)
{
    ORI_ASSERT(p);
    double tol = ORI_TOL_PLANAR_REL * ori_pattern_diagonal(p);
    for (int i = 0; i < p->vertex_count; ++i)
        if (fabs(p->vertices[i].z) > tol) return true;
    return false;
}

double ori_pattern_diagonal(const ori_pattern *p)
{
    ORI_ASSERT(p);
    if (p->built) return p->diagonal;
    if (p->vertex_count < 2) return 1.0;
    ori_v3 lo = p->vertices[0], hi = p->vertices[0];
    for (int i = 1; i < p->vertex_count; ++i) {
        ori_v3 v = p->vertices[i];
        lo.x = fmin(lo.x, v.x), lo.y = fmin(lo.y, v.y), lo.z = fmin(lo.z, v.z);
        hi.x = fmax(hi.x, v.x), hi.y = fmax(hi.y, v.y), hi.z = fmax(hi.z, v.z);
    }
    double d = ori_v3_norm(ori_v3_sub(hi, lo));
    return d > 0.0 && isfinite(d) ? d : 1.0;
}

int ori_pattern_count_assignment(const ori_pattern *p, ori_assignment a)
{
    ORI_ASSERT(p);
    int n = 0;
    for (int i = 0; i < p->edge_count; ++i) n += p->edges[i].assignment == a;
    return n;
}

double ori__pattern_face_area2(const ori_pattern *p, int f)
{
    const int *fv = p->face_vertices + p->face_offsets[f];
    int n = p->face_offsets[f + 1] - p->face_offsets[f];
    double a = 0.0;
    for (int i = 0; i < n; ++i) {
        ori_v3 u = p->vertices[fv[i]], w = p->vertices[fv[(i + 1) % n]];
        a += u.x * w.y - u.y * w.x;
    }
    return a;
}

int ori__pattern_parts(const ori_pattern *p, int *part)
{
    for (int v = 0; v < p->vertex_count; ++v) part[v] = v;
    for (int e = 0; e < p->edge_count; ++e) {
        int a = ori__uf_root(part, p->edges[e].v[0]), b = ori__uf_root(part, p->edges[e].v[1]);
        if (a != b) part[a < b ? b : a] = a < b ? a : b; // (the smaller index stays the root)
    }
    int parts = 0;
    for (int v = 0; v < p->vertex_count; ++v) {
        part[v] = ori__uf_root(part, v);
        parts += part[v] == v;
    }
    return parts;
}

// --- names and tree ----------------------------------------------------------------------

const char *ori_pattern_face_name(const ori_pattern *p, int f)
{
    ORI_ASSERT(p && f >= 0 && f < p->face_count);
    if (!p->face_names || !p->face_names[f][0]) return NULL;
    return p->face_names[f];
}

ori_status ori_pattern_set_face_name(ori_pattern *p, int f, const char *name)
{
    ORI_ASSERT(p && f >= 0 && f < p->face_count);
    if (name && strlen(name) >= ORI_NAME_MAX) return ORI_ERR_LIMIT;
    if (!p->face_names) {
        if (!name) return ORI_OK;
        p->face_names = ori__calloc((size_t)p->face_cap, sizeof(*p->face_names));
    }
    ori__strlcpy(p->face_names[f], name ? name : "", ORI_NAME_MAX);
    return ORI_OK;
}

int ori_pattern_find_face_by_name(const ori_pattern *p, const char *name)
{
    ORI_ASSERT(p && name);
    if (!p->face_names) return ORI_NULL_INDEX;
    for (int f = 0; f < p->face_count; ++f)
        if (p->face_names[f][0] && strcmp(p->face_names[f], name) == 0) return f;
    return ORI_NULL_INDEX;
}

int ori_pattern_tree_node_count(const ori_pattern *p) { ORI_ASSERT(p); return p->tree_count; }

ori_tree_node ori_pattern_tree_node(const ori_pattern *p, int node)
{
    ORI_ASSERT(p && node >= 0 && node < p->tree_count);
    return p->tree[node];
}

static uint64_t name_hash(const char *s)
{
    uint64_t h = 1469598103934665603u; // FNV-1a
    for (; *s; ++s) h = (h ^ (unsigned char)*s) * 1099511628211u;
    return h;
}

// Enter node i into the name index (kept for the first node of a name).
static void tree_hash_insert(ori_pattern *p, int i)
{
    int mask = p->tree_hash_cap - 1, j = (int)(name_hash(p->tree[i].name) & (uint64_t)mask);
    for (; p->tree_hash[j] >= 0; j = (j + 1) & mask)
        if (strcmp(p->tree[p->tree_hash[j]].name, p->tree[i].name) == 0) return;
    p->tree_hash[j] = i;
}

void ori__pattern_reindex_tree(ori_pattern *p)
{
    int cap = 16;
    while (cap <= 2 * p->tree_count) cap *= 2;
    if (cap != p->tree_hash_cap) {
        ori__free(p->tree_hash);
        p->tree_hash = ori__alloc(sizeof(int) * (size_t)cap);
        p->tree_hash_cap = cap;
    }
    for (int j = 0; j < cap; ++j) p->tree_hash[j] = -1;
    for (int i = 0; i < p->tree_count; ++i) tree_hash_insert(p, i);
}

int ori_pattern_add_tree_node(ori_pattern *p, const char *name, int parent)
{
    ORI_ASSERT(p && name);
    if (strlen(name) == 0 || strlen(name) >= ORI_NAME_MAX) return ORI_NULL_INDEX;
    if (parent != ORI_NULL_INDEX && (parent < 0 || parent >= p->tree_count)) return ORI_NULL_INDEX;
    ori_tree_node n;
    ori__strlcpy(n.name, name, sizeof n.name);
    n.parent = parent;
    ORI__PUSH(p->tree, p->tree_count, p->tree_cap, n);
    // The names are indexed as they come, so finding a node is O(1): a split names two
    // children under their parent, and a pattern of 10^5 faces was quadratic in its output.
    if (2 * p->tree_count >= p->tree_hash_cap) ori__pattern_reindex_tree(p);
    else tree_hash_insert(p, p->tree_count - 1);
    return p->tree_count - 1;
}

void ori_pattern_clear_tree(ori_pattern *p)
{
    ORI_ASSERT(p);
    p->tree_count = 0;
    for (int j = 0; j < p->tree_hash_cap; ++j) p->tree_hash[j] = -1;
}

int ori_pattern_find_tree_node(const ori_pattern *p, const char *name)
{
    ORI_ASSERT(p && name);
    if (!p->tree_hash_cap) return ORI_NULL_INDEX;
    int mask = p->tree_hash_cap - 1;
    for (int j = (int)(name_hash(name) & (uint64_t)mask); p->tree_hash[j] >= 0; j = (j + 1) & mask)
        if (strcmp(p->tree[p->tree_hash[j]].name, name) == 0) return p->tree_hash[j];
    return ORI_NULL_INDEX;
}
