// The substituted mechanical system (thesis ch. 4.5, 5.1): faces → rigid bodies, creases →
// revolute joints, the loops that close around interior vertices and holes, poses by product
// of exponentials along a spanning tree, loop residuals and their Jacobian.
#include <float.h>
#include <math.h>

#include "kinematics_internal.h"
#include "../pattern/pattern_internal.h"

ori_mechanism_def ori_default_mechanism_def(void)
{
    ori_mechanism_def def;
    def.pattern = NULL;
    def.internal_value = ORI__DEF_COOKIE;
    return def;
}

static void *dup_array(const void *src, size_t count, size_t elem)
{
    size_t bytes;
    if (!ori__mul_size(count, elem, &bytes)) bytes = SIZE_MAX;
    void *dst = ori__alloc(bytes ? bytes : 1);
    if (bytes) memcpy(dst, src, bytes);
    return dst;
}

void ori_mechanism_destroy(ori_mechanism *m)
{
    if (!m) return;
    ori__free(m->vertices);
    ori__free(m->edges);
    ori__free(m->edge_faces);
    ori__free(m->face_offsets);
    ori__free(m->face_verts);
    ori__free(m->vert_offsets);
    ori__free(m->vert_edges);
    ori__free(m->vert_faces);
    ori__free(m->joints);
    ori__free(m->edge_joint);
    ori__free(m->adj_offsets);
    ori__free(m->adj_joint);
    ori__free(m->adj_face);
    ori__free(m->loops);
    ori__free(m->entries);
    ori__free(m->entry_face);
    ori__free(m->loop_cols);
    ori__free(m->bones);
    ori__free(m);
}

// Face on the left of edge e walked out of vertex v.
static int left_face_out_of(const ori_mechanism *m, int e, int v)
{
    return m->edges[e].v[0] == v ? m->edge_faces[2 * e] : m->edge_faces[2 * e + 1];
}

static ori_v3 dir_out_of(const ori_mechanism *m, int e, int v)
{
    int w = m->edges[e].v[0] == v ? m->edges[e].v[1] : m->edges[e].v[0];
    return ori_v3_normalize(ori_v3_sub(m->vertices[w], m->vertices[v]));
}

// A side of an edge is a boundary of the sheet when a face lies on it and the paper does not
// continue across: no face on the other side, or the edge is a boundary/cut without a joint.
static bool boundary_side(const ori_mechanism *m, int e, int side)
{
    int f = m->edge_faces[2 * e + side], g = m->edge_faces[2 * e + 1 - side];
    if (f == ORI_NULL_INDEX) return false;
    if (m->edge_joint[e] != ORI_NULL_INDEX) return false;
    if (g == ORI_NULL_INDEX) return true;
    ori_assignment a = m->edges[e].assignment;
    return a == ORI_ASSIGN_BOUNDARY || a == ORI_ASSIGN_CUT;
}

typedef struct loop_builder {
    const ori_v3 *joint_omega;
    kin_loop *loops;
    int loop_count, loop_cap;
    kin_entry *entries;
    int entry_count, entry_cap;
    int *entry_face;
    int entry_face_cap;
} loop_builder;

static void push_entry(loop_builder *b, int joint, ori_v3 axis, ori_v3 point, int face_after)
{
    kin_entry en;
    en.joint = joint;
    en.col = -1;
    en.sign = ori_v3_dot(axis, b->joint_omega[joint]) >= 0.0 ? 1 : -1;
    en.axis = axis;
    en.point = point;
    int n = b->entry_count;
    ORI__PUSH(b->entries, b->entry_count, b->entry_cap, en);
    ORI__RESERVE(b->entry_face, b->entry_face_cap, n + 1);
    b->entry_face[n] = face_after;
}

// One loop per interior vertex: F(i−1) → F(i) across crease i, R(a_i, θ_i), a_i pointing out of
// the vertex with F(i) on its left, creases in counter-clockwise order.
static void build_vertex_loops(ori_mechanism *m, const ori_pattern *p, loop_builder *b)
{
    for (int v = 0; v < m->vertex_count; ++v) {
        if (!ori_pattern_vertex_is_interior(p, v)) continue;
        int o = m->vert_offsets[v], n = m->vert_offsets[v + 1] - o;
        int first = b->entry_count;
        for (int i = 0; i < n; ++i) {
            int e = m->vert_edges[o + i];
            int j = m->edge_joint[e];
            if (j == ORI_NULL_INDEX) continue; // dangling crease inside one face: no crossing
            push_entry(b, j, dir_out_of(m, e, v), m->vertices[v], m->vert_faces[o + i]);
        }
        if (b->entry_count == first) continue;
        kin_loop L;
        L.vertex = v;
        L.first = first;
        L.count = b->entry_count - first;
        L.rows = 3;
        L.row0 = 0;
        L.col_first = L.col_count = 0;
        ORI__PUSH(b->loops, b->loop_count, b->loop_cap, L);
    }
}

// Loops around the holes and internal slits: walk each boundary component of the sheet with
// the paper on the left; at every vertex, pass from the face left of the incoming boundary
// side to the face left of the outgoing one clockwise around the vertex, crossing its
// creases. The outer component (largest signed area) is the product of all the others and
// is skipped. Returns the number of components, or -1 when the walk is inconsistent.
static int build_hole_loops(ori_mechanism *m, loop_builder *b)
{
    int E = m->edge_count;
    char *used = ori__calloc((size_t)(2 * E) + 1, 1);
    int components = 0;
    int best_loop = -1;
    double best_area = -DBL_MAX;
    int comp_loops_start = b->loop_count;
    // Index of edge e in vertex v's CCW list.
    for (int e0 = 0; e0 < E; ++e0)
        for (int s0 = 0; s0 < 2; ++s0) {
            if (used[2 * e0 + s0] || !boundary_side(m, e0, s0)) continue;
            components++;
            int first = b->entry_count;
            double area2 = 0.0;
            int e = e0, s = s0;
            int guard = 0;
            bool ok = true;
            for (;;) {
                used[2 * e + s] = 1;
                // Side 0 (left of v0→v1) is walked v0→v1; side 1 is walked v1→v0.
                int u = s == 0 ? m->edges[e].v[0] : m->edges[e].v[1];
                int w = s == 0 ? m->edges[e].v[1] : m->edges[e].v[0];
                area2 += m->vertices[u].x * m->vertices[w].y - m->vertices[w].x * m->vertices[u].y;
                int o = m->vert_offsets[w], n = m->vert_offsets[w + 1] - o;
                int i = -1;
                for (int k = 0; k < n; ++k)
                    if (m->vert_edges[o + k] == e) i = k;
                if (i < 0) { ok = false; break; }
                // In face G_{i-1}; step clockwise until an outgoing boundary side.
                int k = (i - 1 + n) % n;
                int next_e = -1, next_s = -1;
                for (int step = 0; step < n; ++step) {
                    int ek = m->vert_edges[o + k];
                    int sk = m->edges[ek].v[0] == w ? 0 : 1; // side on the left of w → other end
                    if (boundary_side(m, ek, sk)) {
                        next_e = ek;
                        next_s = sk;
                        break;
                    }
                    int j = m->edge_joint[ek];
                    int prev = (k - 1 + n) % n;
                    if (j != ORI_NULL_INDEX) // from G_k to G_{k-1} across a_k: R(−a_k, θ)
                        push_entry(b, j, ori_v3_scale(dir_out_of(m, ek, w), -1.0), m->vertices[w],
                                   m->vert_faces[o + prev]);
                    k = prev;
                }
                if (next_e < 0) { ok = false; break; }
                e = next_e;
                s = next_s;
                if (e == e0 && s == s0) break;
                if (++guard > 2 * E + 2) { ok = false; break; }
            }
            if (!ok) {
                ori__free(used);
                return -1;
            }
            kin_loop L;
            L.vertex = ORI_NULL_INDEX;
            L.first = first;
            L.count = b->entry_count - first;
            L.rows = 6;
            L.row0 = 0;
            L.col_first = L.col_count = 0;
            ORI__PUSH(b->loops, b->loop_count, b->loop_cap, L);
            if (area2 > best_area) {
                best_area = area2;
                best_loop = b->loop_count - 1;
            }
        }
    ori__free(used);
    // Drop the outer component's loop (and loops that cross nothing).
    int w = comp_loops_start;
    for (int l = comp_loops_start; l < b->loop_count; ++l) {
        if (l == best_loop || b->loops[l].count == 0) continue;
        b->loops[w++] = b->loops[l];
    }
    b->loop_count = w;
    return components;
}

static void compute_bones(ori_mechanism *m)
{
    int cap = 0;
    m->bone_count = 0;
    for (int f = 0; f < m->face_count; ++f) {
        int o = m->face_offsets[f], n = m->face_offsets[f + 1] - o;
        // Area centroid of the polygon (vertex average when degenerate).
        double a2 = 0.0, cx = 0.0, cy = 0.0, ax = 0.0, ay = 0.0;
        for (int k = 0; k < n; ++k) {
            ori_v3 p = m->vertices[m->face_verts[o + k]], q = m->vertices[m->face_verts[o + (k + 1) % n]];
            double c = p.x * q.y - q.x * p.y;
            a2 += c;
            cx += (p.x + q.x) * c;
            cy += (p.y + q.y) * c;
            ax += p.x;
            ay += p.y;
        }
        ori_v3 cen = fabs(a2) > 0.0 ? ori_v3_make(cx / (3.0 * a2), cy / (3.0 * a2), 0.0)
                                    : ori_v3_make(ax / n, ay / n, 0.0);
        for (int k = m->adj_offsets[f]; k < m->adj_offsets[f + 1]; ++k) {
            const ori_joint *J = &m->joints[m->adj_joint[k]];
            ori_v3 a = m->vertices[m->edges[J->edge].v[0]], c = m->vertices[m->edges[J->edge].v[1]];
            ori_bone bone;
            bone.face = f;
            bone.edge = J->edge;
            bone.from = cen;
            bone.to = ori_v3_scale(ori_v3_add(a, c), 0.5);
            ORI__PUSH(m->bones, m->bone_count, cap, bone);
        }
    }
}

ori_status ori_mechanism_create(const ori_mechanism_def *def, ori_mechanism **out, ori_error *error)
{
    ORI_ASSERT(def && def->internal_value == ORI__DEF_COOKIE && out);
    *out = NULL;
    const ori_pattern *p = def->pattern;
    ORI_ASSERT(p);
    if (!p->built) return ori__fail(error, ORI_ERR_ARGUMENT, "the pattern is not built");
    if (p->folded_form || ori_pattern_is_3d(p))
        return ori__fail(error, ORI_ERR_ARGUMENT,
                         "the mechanism needs the flat crease pattern (this frame is a folded form)");
    if (p->face_count == 0) return ori__fail(error, ORI_ERR_TOPOLOGY, "the pattern has no faces");

    ori_mechanism *m = ori__calloc(1, sizeof *m);
    m->vertex_count = p->vertex_count;
    m->edge_count = p->edge_count;
    m->face_count = p->face_count;
    m->diagonal = p->diagonal > 0.0 ? p->diagonal : 1.0;
    m->vertices = dup_array(p->vertices, (size_t)p->vertex_count, sizeof(ori_v3));
    for (int v = 0; v < m->vertex_count; ++v) m->vertices[v].z = 0.0;
    m->edges = dup_array(p->edges, (size_t)p->edge_count, sizeof(ori_edge));
    m->edge_faces = dup_array(p->edge_faces, (size_t)(2 * p->edge_count), sizeof(int));
    m->face_offsets = dup_array(p->face_offsets, (size_t)p->face_count + 1, sizeof(int));
    m->face_verts = dup_array(p->face_vertices, (size_t)p->face_offsets[p->face_count], sizeof(int));
    m->vert_offsets = dup_array(p->vert_edge_offsets, (size_t)p->vertex_count + 1, sizeof(int));
    m->vert_edges = dup_array(p->vert_edges, (size_t)p->vert_edge_offsets[p->vertex_count], sizeof(int));
    int half = m->vert_offsets[m->vertex_count];
    m->vert_faces = ori__alloc(sizeof(int) * (size_t)(half > 0 ? half : 1));
    for (int v = 0; v < m->vertex_count; ++v)
        for (int k = m->vert_offsets[v]; k < m->vert_offsets[v + 1]; ++k)
            m->vert_faces[k] = left_face_out_of(m, m->vert_edges[k], v);

    // Joints: every edge with two different faces that is a crease or a join.
    m->edge_joint = ori__alloc(sizeof(int) * (size_t)(m->edge_count > 0 ? m->edge_count : 1));
    m->joints = ori__alloc(sizeof(ori_joint) * (size_t)(m->edge_count > 0 ? m->edge_count : 1));
    int revolute = 0, rigid = 0;
    for (int e = 0; e < m->edge_count; ++e) {
        m->edge_joint[e] = ORI_NULL_INDEX;
        ori_assignment a = m->edges[e].assignment;
        int fl = m->edge_faces[2 * e], fr = m->edge_faces[2 * e + 1];
        if (a == ORI_ASSIGN_BOUNDARY || a == ORI_ASSIGN_CUT) continue;
        if (fl == ORI_NULL_INDEX || fr == ORI_NULL_INDEX || fl == fr) continue;
        ori_joint J;
        J.edge = e;
        J.face_left = fl;
        J.face_right = fr;
        J.q = m->vertices[m->edges[e].v[0]];
        J.omega = ori_v3_normalize(ori_v3_sub(m->vertices[m->edges[e].v[1]], J.q));
        J.assignment = a;
        J.kind = a == ORI_ASSIGN_FLAT ? ORI_JOINT_FLAT : a == ORI_ASSIGN_JOIN ? ORI_JOINT_RIGID : ORI_JOINT_REVOLUTE;
        if (J.kind == ORI_JOINT_REVOLUTE) revolute++;
        else rigid++;
        m->edge_joint[e] = m->joint_count;
        m->joints[m->joint_count++] = J;
    }

    // Face adjacency through joints (CSR), in joint order: deterministic trees.
    m->adj_offsets = ori__calloc((size_t)m->face_count + 1, sizeof(int));
    for (int j = 0; j < m->joint_count; ++j) {
        m->adj_offsets[m->joints[j].face_left + 1]++;
        m->adj_offsets[m->joints[j].face_right + 1]++;
    }
    for (int f = 0; f < m->face_count; ++f) m->adj_offsets[f + 1] += m->adj_offsets[f];
    int na = m->adj_offsets[m->face_count];
    m->adj_joint = ori__alloc(sizeof(int) * (size_t)(na > 0 ? na : 1));
    m->adj_face = ori__alloc(sizeof(int) * (size_t)(na > 0 ? na : 1));
    int *fill = ori__alloc(sizeof(int) * (size_t)m->face_count);
    for (int f = 0; f < m->face_count; ++f) fill[f] = m->adj_offsets[f];
    for (int j = 0; j < m->joint_count; ++j) {
        int a = m->joints[j].face_left, c = m->joints[j].face_right;
        m->adj_joint[fill[a]] = j;
        m->adj_face[fill[a]++] = c;
        m->adj_joint[fill[c]] = j;
        m->adj_face[fill[c]++] = a;
    }
    ori__free(fill);

    // The faces must form one body graph.
    int *order = ori__alloc(sizeof(int) * (size_t)m->face_count);
    int *pf = ori__alloc(sizeof(int) * (size_t)m->face_count);
    ori__kin_bfs(m, 0, order, pf, NULL);
    int unreached = ORI_NULL_INDEX;
    for (int f = 0; f < m->face_count && unreached == ORI_NULL_INDEX; ++f)
        if (f != 0 && pf[f] == ORI_NULL_INDEX) unreached = f;
    ori__free(order);
    ori__free(pf);
    if (unreached != ORI_NULL_INDEX) {
        ori_mechanism_destroy(m);
        return ori__fail_at(error, ORI_ERR_TOPOLOGY, "faces_vertices", unreached,
                            "face %d is not connected to face 0 through creases (the sheet falls apart)",
                            unreached);
    }

    // Loops: interior vertices, then holes and internal slits.
    loop_builder b = {0};
    ori_v3 *omegas = ori__alloc(sizeof(ori_v3) * (size_t)(m->joint_count + 1));
    for (int j = 0; j < m->joint_count; ++j) omegas[j] = m->joints[j].omega;
    b.joint_omega = omegas;
    build_vertex_loops(m, p, &b);
    m->vertex_loop_count = b.loop_count;
    int components = build_hole_loops(m, &b);
    int cycle_rank = m->joint_count - m->face_count + 1;
    ori__free(omegas);
    if (components < 0 || b.loop_count != cycle_rank) {
        ori__free(b.loops);
        ori__free(b.entries);
        ori__free(b.entry_face);
        ori_mechanism_destroy(m);
        return ori__fail(error, ORI_ERR_TOPOLOGY,
                         "the loops around vertices and holes (%d) do not span the %d cycles of the face graph",
                         components < 0 ? -1 : b.loop_count, cycle_rank);
    }
    m->loops = b.loops;
    m->loop_count = b.loop_count;
    m->entries = b.entries;
    m->entry_count = b.entry_count;
    m->entry_face = b.entry_face;
    if (!m->loops) m->loops = ori__alloc(sizeof(kin_loop));
    if (!m->entries) m->entries = ori__alloc(sizeof(kin_entry));
    if (!m->entry_face) m->entry_face = ori__alloc(sizeof(int));

    // Distinct joints (columns) per loop and row offsets.
    m->loop_cols = ori__alloc(sizeof(int) * (size_t)(m->entry_count > 0 ? m->entry_count : 1));
    int total = 0, rows = 0;
    for (int l = 0; l < m->loop_count; ++l) {
        kin_loop *L = &m->loops[l];
        L->col_first = total;
        L->row0 = rows;
        rows += L->rows;
        for (int i = 0; i < L->count; ++i) {
            kin_entry *en = &m->entries[L->first + i];
            int c = -1;
            for (int k = L->col_first; k < total; ++k)
                if (m->loop_cols[k] == en->joint) c = k - L->col_first;
            if (c < 0) {
                c = total - L->col_first;
                m->loop_cols[total++] = en->joint;
            }
            en->col = c;
        }
        L->col_count = total - L->col_first;
    }
    m->loop_col_total = total;
    m->rows = rows;

    m->grubler = 6 * (m->face_count - 1) - 5 * revolute - 6 * rigid;
    compute_bones(m);
    *out = m;
    return ORI_OK;
}

// --- getters ---------------------------------------------------------------------------

int ori_mechanism_vertex_count(const ori_mechanism *m) { ORI_ASSERT(m); return m->vertex_count; }
int ori_mechanism_edge_count(const ori_mechanism *m) { ORI_ASSERT(m); return m->edge_count; }
int ori_mechanism_face_count(const ori_mechanism *m) { ORI_ASSERT(m); return m->face_count; }
int ori_mechanism_joint_count(const ori_mechanism *m) { ORI_ASSERT(m); return m->joint_count; }
int ori_mechanism_grubler(const ori_mechanism *m) { ORI_ASSERT(m); return m->grubler; }
int ori_mechanism_loop_count(const ori_mechanism *m) { ORI_ASSERT(m); return m->loop_count; }
int ori_mechanism_bone_count(const ori_mechanism *m) { ORI_ASSERT(m); return m->bone_count; }

ori_joint ori_mechanism_joint(const ori_mechanism *m, int j)
{
    ORI_ASSERT(m && j >= 0 && j < m->joint_count);
    return m->joints[j];
}

int ori_mechanism_edge_joint(const ori_mechanism *m, int e)
{
    ORI_ASSERT(m && e >= 0 && e < m->edge_count);
    return m->edge_joint[e];
}

ori_loop ori_mechanism_loop(const ori_mechanism *m, int l)
{
    ORI_ASSERT(m && l >= 0 && l < m->loop_count);
    ori_loop r;
    r.vertex = m->loops[l].vertex;
    r.crease_count = m->loops[l].count;
    r.rows = m->loops[l].rows;
    return r;
}

int ori_mechanism_loop_edges(const ori_mechanism *m, int l, int *out, int cap)
{
    ORI_ASSERT(m && l >= 0 && l < m->loop_count);
    const kin_loop *L = &m->loops[l];
    for (int i = 0; i < L->count && i < cap; ++i) out[i] = m->joints[m->entries[L->first + i].joint].edge;
    return L->count;
}

int ori_mechanism_loop_faces(const ori_mechanism *m, int l, int *out, int cap)
{
    ORI_ASSERT(m && l >= 0 && l < m->loop_count);
    const kin_loop *L = &m->loops[l];
    for (int i = 0; i < L->count && i < cap; ++i)
        out[i] = m->entry_face[L->first + (i + L->count - 1) % L->count];
    return L->count;
}

int ori_mechanism_vertex_faces(const ori_mechanism *m, int v, int *out, int cap)
{
    ORI_ASSERT(m && v >= 0 && v < m->vertex_count);
    int o = m->vert_offsets[v], n = m->vert_offsets[v + 1] - o;
    for (int k = 0; k < n && k < cap; ++k) out[k] = m->vert_faces[o + k];
    return n;
}

ori_bone ori_mechanism_bone(const ori_mechanism *m, int i)
{
    ORI_ASSERT(m && i >= 0 && i < m->bone_count);
    return m->bones[i];
}

// --- joint space -------------------------------------------------------------------------

void ori__kin_edges_to_joints(const ori_mechanism *m, const double *edge_angles, double *th)
{
    for (int j = 0; j < m->joint_count; ++j) {
        const ori_joint *J = &m->joints[j];
        th[j] = (J->kind == ORI_JOINT_REVOLUTE && edge_angles) ? edge_angles[J->edge] : 0.0;
    }
}

void ori__kin_joints_to_edges(const ori_mechanism *m, const double *th, double *edge_angles)
{
    for (int e = 0; e < m->edge_count; ++e) edge_angles[e] = 0.0;
    for (int j = 0; j < m->joint_count; ++j) edge_angles[m->joints[j].edge] = th[j];
}

// --- spanning tree and poses -----------------------------------------------------------

void ori__kin_bfs(const ori_mechanism *m, int root, int *order, int *parent_face, int *parent_joint)
{
    int F = m->face_count;
    char *seen = ori__calloc((size_t)F, 1);
    for (int f = 0; f < F; ++f) {
        if (parent_face) parent_face[f] = ORI_NULL_INDEX;
        if (parent_joint) parent_joint[f] = ORI_NULL_INDEX;
        order[f] = ORI_NULL_INDEX;
    }
    int head = 0, tail = 0;
    order[tail++] = root;
    seen[root] = 1;
    while (head < tail) {
        int f = order[head++];
        for (int k = m->adj_offsets[f]; k < m->adj_offsets[f + 1]; ++k) {
            int g = m->adj_face[k];
            if (seen[g]) continue;
            seen[g] = 1;
            if (parent_face) parent_face[g] = f;
            if (parent_joint) parent_joint[g] = m->adj_joint[k];
            order[tail++] = g;
        }
    }
    ori__free(seen);
}

void ori_mechanism_spanning_tree(const ori_mechanism *m, int root, int *parent_face, int *parent_edge)
{
    ORI_ASSERT(m && root >= 0 && root < m->face_count);
    int F = m->face_count;
    int *order = ori__alloc(sizeof(int) * (size_t)F);
    int *pf = ori__alloc(sizeof(int) * (size_t)F);
    int *pj = ori__alloc(sizeof(int) * (size_t)F);
    ori__kin_bfs(m, root, order, pf, pj);
    for (int f = 0; f < F; ++f) {
        if (parent_face) parent_face[f] = pf[f];
        if (parent_edge) parent_edge[f] = pj[f] == ORI_NULL_INDEX ? ORI_NULL_INDEX : m->joints[pj[f]].edge;
    }
    ori__free(order);
    ori__free(pf);
    ori__free(pj);
}

// Motion of face `child` relative to its neighbour across joint j: e^{±ξθ}.
static ori_rigid joint_motion(const ori_mechanism *m, int j, int child, double theta)
{
    const ori_joint *J = &m->joints[j];
    ori_twist xi = ori_twist_from_axis(J->q, J->omega);
    return ori_twist_exp(xi, child == J->face_left ? theta : -theta);
}

void ori__kin_face_poses(const ori_mechanism *m, const double *th, int fixed_face, ori_rigid fixed_pose,
                         ori_rigid *poses)
{
    int F = m->face_count;
    int *order = ori__alloc(sizeof(int) * (size_t)F);
    int *pf = ori__alloc(sizeof(int) * (size_t)F);
    int *pj = ori__alloc(sizeof(int) * (size_t)F);
    ori__kin_bfs(m, fixed_face, order, pf, pj);
    for (int k = 0; k < F; ++k) {
        int f = order[k];
        if (f == ORI_NULL_INDEX) break;
        if (pf[f] == ORI_NULL_INDEX) poses[f] = fixed_pose;
        else poses[f] = ori_rigid_compose(poses[pf[f]], joint_motion(m, pj[f], f, th[pj[f]]));
    }
    ori__free(order);
    ori__free(pf);
    ori__free(pj);
}

void ori_mechanism_face_poses(const ori_mechanism *m, const double *angles, int fixed_face, ori_rigid fixed_pose,
                              ori_rigid *poses)
{
    ORI_ASSERT(m && poses && fixed_face >= 0 && fixed_face < m->face_count);
    double *th = ori__alloc(sizeof(double) * (size_t)(m->joint_count + 1));
    ori__kin_edges_to_joints(m, angles, th);
    ori__kin_face_poses(m, th, fixed_face, fixed_pose, poses);
    ori__free(th);
}

void ori_mechanism_vertex_positions(const ori_mechanism *m, const double *angles, int fixed_face,
                                    ori_rigid fixed_pose, ori_v3 *out)
{
    ORI_ASSERT(m && out && fixed_face >= 0 && fixed_face < m->face_count);
    int F = m->face_count;
    ori_rigid *poses = ori__alloc(sizeof(ori_rigid) * (size_t)F);
    ori_mechanism_face_poses(m, angles, fixed_face, fixed_pose, poses);
    int *order = ori__alloc(sizeof(int) * (size_t)F);
    ori__kin_bfs(m, fixed_face, order, NULL, NULL);
    char *done = ori__calloc((size_t)m->vertex_count + 1, 1);
    for (int v = 0; v < m->vertex_count; ++v) out[v] = ori_rigid_apply(fixed_pose, m->vertices[v]);
    for (int k = 0; k < F; ++k) {
        int f = order[k];
        if (f == ORI_NULL_INDEX) break;
        for (int i = m->face_offsets[f]; i < m->face_offsets[f + 1]; ++i) {
            int v = m->face_verts[i];
            if (done[v]) continue;
            done[v] = 1;
            out[v] = ori_rigid_apply(poses[f], m->vertices[v]);
        }
    }
    ori__free(done);
    ori__free(order);
    ori__free(poses);
}

// --- loop evaluation ---------------------------------------------------------------------


ori_v3 ori__kin_rotvec(ori_m3 r)
{
    ori_v3 s = ori_v3_make(0.5 * (r.m[2][1] - r.m[1][2]), 0.5 * (r.m[0][2] - r.m[2][0]),
                           0.5 * (r.m[1][0] - r.m[0][1]));
    double c = 0.5 * (r.m[0][0] + r.m[1][1] + r.m[2][2] - 1.0);
    double sn = ori_v3_norm(s);
    // Near the identity (every converged loop): φ/sin φ = 1 + sin²φ/6 + O(sin⁴φ), exact in double
    // precision below ORI_KIN_ROTVEC_SERIES_MAX, without the atan2.
    if (c > 0.0 && sn < ORI_KIN_ROTVEC_SERIES_MAX) return ori_v3_scale(s, 1.0 + sn * sn / 6.0);
    double phi = atan2(sn, c);
    if (sn > 0.0 && isfinite(sn)) {
        // phi/sin(phi) is bounded away from phi = π; there use the diagonal for the axis.
        if (phi < 0.5 * ORI_PI) return ori_v3_scale(s, phi / sn);
    }
    if (c >= 0.0) return s; // phi ≈ 0
    // Far from 0 (near π): k kᵀ = ((R + Rᵀ)/2 − cos φ I)/(1 − cos φ); the column of its
    // largest diagonal entry is a well-scaled multiple of k.
    double d[3] = {r.m[0][0] - c, r.m[1][1] - c, r.m[2][2] - c};
    int i = d[0] >= d[1] && d[0] >= d[2] ? 0 : d[1] >= d[2] ? 1 : 2;
    double col[3];
    for (int k = 0; k < 3; ++k) col[k] = 0.5 * (r.m[k][i] + r.m[i][k]) - (k == i ? c : 0.0);
    ori_v3 k = ori_v3_normalize(ori_v3_make(col[0], col[1], col[2]));
    if (ori_v3_dot(k, s) < 0.0) k = ori_v3_scale(k, -1.0);
    return ori_v3_scale(k, phi);
}

static double m3_dev_identity(ori_m3 r)
{
    double d = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double x = fabs(r.m[i][j] - (i == j ? 1.0 : 0.0));
            if (x > d || isnan(x)) d = x;
        }
    return d;
}

// Vertex loop (3 rows): P = R_1 R_2 ··· R_n with R_i = R(a_i, θ_i), accumulated as a unit
// quaternion (w, v): crossing i multiplies it by (cos(θ_i/2), sin(θ_i/2) a_i), half the work of
// 3 × 3 products. The half-angle sines and cosines come from half (per joint, computed once
// per evaluation) or are computed here when half is NULL. The Jacobian column of crossing i is
// the spatial axis P_{i−1} a_i (the quaternion rotation v' = a + w t + v × t, t = 2 v × a),
// accumulated into cols. The residual is log P = φ k from the quaternion (φ = 2 atan2(|v|, w),
// w ≥ 0), and the returned max-norm of P − I is taken from P − I = 2w[v]× + 2[v]×², which has no
// cancellation against the identity.
// rot (3 values) receives the residual and axes (L->count, optional) each crossing's spatial axis.
static double eval_vertex_loop(const ori_mechanism *m, const kin_loop *L, const double *th, double *rot, double *cols,
                               const double *half, ori_v3 *axes)
{
    double w = 1.0, x = 0.0, y = 0.0, z = 0.0;
    for (int i = 0; i < L->count; ++i) {
        const kin_entry *en = &m->entries[L->first + i];
        const double ax = en->axis.x, ay = en->axis.y, az = en->axis.z;
        if (cols || axes) {
            double sx = ax, sy = ay, sz = az;
            if (i > 0) {
                double tx = 2.0 * (y * az - z * ay), ty = 2.0 * (z * ax - x * az), tz = 2.0 * (x * ay - y * ax);
                sx = ax + w * tx + (y * tz - z * ty);
                sy = ay + w * ty + (z * tx - x * tz);
                sz = az + w * tz + (x * ty - y * tx);
            }
            if (cols) {
                double *c = cols + 6 * (L->col_first + en->col);
                c[0] += sx;
                c[1] += sy;
                c[2] += sz;
            }
            if (axes) axes[i] = ori_v3_make(sx, sy, sz);
        }
        double hc, hs;
        if (half) {
            hc = half[2 * en->joint];
            hs = half[2 * en->joint + 1];
        } else {
            double t = 0.5 * th[en->joint];
            hc = cos(t);
            hs = sin(t);
        }
        // (w, v)(hc, hs a) = (w hc − hs v·a, hc v + hs (w a + v × a))
        double va = x * ax + y * ay + z * az;
        double nx = hc * x + hs * (w * ax + (y * az - z * ay));
        double ny = hc * y + hs * (w * ay + (z * ax - x * az));
        double nz = hc * z + hs * (w * az + (x * ay - y * ax));
        w = hc * w - hs * va;
        x = nx;
        y = ny;
        z = nz;
    }
    if (w < 0.0) { // the same rotation, angle in [0, π]
        w = -w;
        x = -x;
        y = -y;
        z = -z;
    }
    double d[9] = {-2.0 * (y * y + z * z), 2.0 * (x * y - w * z),  2.0 * (x * z + w * y),
                   2.0 * (x * y + w * z),  -2.0 * (x * x + z * z), 2.0 * (y * z - w * x),
                   2.0 * (x * z - w * y),  2.0 * (y * z + w * x),  -2.0 * (x * x + y * y)};
    double dev = 0.0, sum = 0.0;
    for (int k = 0; k < 9; ++k) {
        double a = fabs(d[k]);
        dev = a > dev ? a : dev;
        sum += a;
    }
    if (isnan(sum) || isnan(w)) dev = NAN;
    if (rot) {
        // |v| = sin(φ/2): φ/|v| = 2 (1 + |v|²/6 + 3|v|⁴/40 + …), the series exact in double
        // precision below ORI_KIN_ROTVEC_SERIES_MAX.
        double n = sqrt(x * x + y * y + z * z);
        double f = n < ORI_KIN_ROTVEC_SERIES_MAX ? 2.0 * (1.0 + n * n / 6.0) : 2.0 * atan2(n, w) / n;
        rot[0] = f * x;
        rot[1] = f * y;
        rot[2] = f * z;
    }
    return dev;
}

double ori__kin_vertex_loop_eval(const ori_mechanism *m, const kin_loop *L, const double *th, double rot[3], ori_v3 *axes)
{
    return eval_vertex_loop(m, L, th, rot, NULL, NULL, axes);
}

// Hole loop (6 rows): rigid motions, translation rows divided by the diagonal.
static double eval_hole_loop(const ori_mechanism *m, const kin_loop *L, const double *th, double *res, double *cols)
{
    double inv_diag = 1.0 / m->diagonal;
    ori_rigid P = ori_rigid_identity();
    for (int i = 0; i < L->count; ++i) {
        const kin_entry *en = &m->entries[L->first + i];
        if (cols) {
            // Spatial twist of this crossing at the current state: Ad(P) ξ.
            ori_v3 w = ori_m3_apply(P.r, en->axis);
            double *c = cols + 6 * (L->col_first + en->col);
            ori_v3 q = ori_rigid_apply(P, en->point);
            ori_v3 v = ori_v3_scale(ori_v3_cross(q, w), inv_diag); // −ω×q = q×ω
            c[0] += v.x;
            c[1] += v.y;
            c[2] += v.z;
            c[3] += w.x;
            c[4] += w.y;
            c[5] += w.z;
        }
        ori_twist xi = ori_twist_from_axis(en->point, en->axis);
        P = ori_rigid_compose(P, ori_twist_exp(xi, th[en->joint]));
    }
    double dev = m3_dev_identity(P.r);
    ori_v3 t = ori_v3_scale(P.t, inv_diag);
    double dt = fmax(fabs(t.x), fmax(fabs(t.y), fabs(t.z)));
    if (dt > dev || isnan(dt)) dev = dt;
    if (res) {
        ori_v3 rv = ori__kin_rotvec(P.r);
        res[L->row0 + 0] = t.x;
        res[L->row0 + 1] = t.y;
        res[L->row0 + 2] = t.z;
        res[L->row0 + 3] = rv.x;
        res[L->row0 + 4] = rv.y;
        res[L->row0 + 5] = rv.z;
    }
    return dev;
}

double ori__kin_eval(const ori_mechanism *m, const double *th, double *res, double *cols, double *half)
{
    double worst = 0.0;
    if (half)
        for (int j = 0; j < m->joint_count; ++j) {
            double t = 0.5 * th[j];
            half[2 * j] = cos(t);
            half[2 * j + 1] = sin(t);
        }
    for (int l = 0; l < m->loop_count; ++l) {
        const kin_loop *L = &m->loops[l];
        // The loop's blocks (disjoint ranges covering the array), zeroed just before they are
        // accumulated: one pass over them instead of a memset of all first (192 MB on a 1000 ×
        // 1000 sheet) and a second pass.
        if (cols) memset(cols + 6 * (size_t)L->col_first, 0, sizeof(double) * 6 * (size_t)L->col_count);
        double dev = L->rows == 3 ? eval_vertex_loop(m, L, th, res ? res + L->row0 : NULL, cols, half, NULL) : eval_hole_loop(m, L, th, res, cols);
        if (dev > worst || isnan(dev)) worst = dev;
    }
    return isnan(worst) ? INFINITY : worst;
}

double ori__kin_residual(const ori_mechanism *m, const double *th) { return ori__kin_eval(m, th, NULL, NULL, NULL); }

double ori_mechanism_residual(const ori_mechanism *m, const double *angles)
{
    ORI_ASSERT(m);
    double *th = ori__alloc(sizeof(double) * (size_t)(m->joint_count + 1));
    ori__kin_edges_to_joints(m, angles, th);
    double r = ori__kin_residual(m, th);
    ori__free(th);
    return r;
}

// ½ Σ_{i<j} v_i v_j [ξ_i, ξ_j]: the second-order term of log(Π exp(ξ_i v_i)) (Baker–Campbell–
// Hausdorff) for the spatial twists ξ_i of each loop at state th. [ξ_i, ξ_j] for twists (v, ω):
// (ω_i×v_j − ω_j×v_i, ω_i×ω_j). Accumulated as ½ Σ_j v_j [S_j, ξ_j] with S_j = Σ_{i<j} v_i ξ_i.
void ori__kin_second_order(const ori_mechanism *m, const double *th, const double *vj, double *out)
{
    double inv_diag = 1.0 / m->diagonal;
    for (int l = 0; l < m->loop_count; ++l) {
        const kin_loop *L = &m->loops[l];
        ori_rigid P = ori_rigid_identity();
        ori_v3 sw = ori_v3_make(0, 0, 0), sv = ori_v3_make(0, 0, 0);
        ori_v3 acc_w = ori_v3_make(0, 0, 0), acc_v = ori_v3_make(0, 0, 0);
        for (int i = 0; i < L->count; ++i) {
            const kin_entry *en = &m->entries[L->first + i];
            ori_v3 w = ori_m3_apply(P.r, en->axis);
            ori_v3 v = ori_v3_make(0, 0, 0);
            if (L->rows == 6) v = ori_v3_scale(ori_v3_cross(ori_rigid_apply(P, en->point), w), inv_diag);
            double a = vj[en->joint];
            if (a != 0.0) {
                acc_w = ori_v3_add(acc_w, ori_v3_scale(ori_v3_cross(sw, w), 0.5 * a));
                acc_v = ori_v3_add(acc_v, ori_v3_scale(ori_v3_sub(ori_v3_cross(sw, v), ori_v3_cross(w, sv)), 0.5 * a));
                sw = ori_v3_add(sw, ori_v3_scale(w, a));
                sv = ori_v3_add(sv, ori_v3_scale(v, a));
            }
            double t = th[en->joint];
            if (L->rows == 3) {
                P.r = ori_m3_mul(P.r, ori_m3_rotation(en->axis, t));
            } else {
                ori_twist xi = ori_twist_from_axis(en->point, en->axis);
                P = ori_rigid_compose(P, ori_twist_exp(xi, t));
            }
        }
        if (L->rows == 3) {
            out[L->row0 + 0] = acc_w.x;
            out[L->row0 + 1] = acc_w.y;
            out[L->row0 + 2] = acc_w.z;
        } else {
            out[L->row0 + 0] = acc_v.x;
            out[L->row0 + 1] = acc_v.y;
            out[L->row0 + 2] = acc_v.z;
            out[L->row0 + 3] = acc_w.x;
            out[L->row0 + 4] = acc_w.y;
            out[L->row0 + 5] = acc_w.z;
        }
    }
}

// --- pose from coordinates ---------------------------------------------------------------

// Kabsch: the rotation maximising Σ (R a_k)·b_k via the polar decomposition of the 3×3
// covariance, computed with LAPACK SVD; reflection corrected.
#include <lapacke.h>

ori_status ori_mechanism_face_pose_from_coords(const ori_mechanism *m, int face, const ori_v3 *coords,
                                               ori_rigid *out, ori_error *error)
{
    ORI_ASSERT(m && coords && out);
    if (face < 0 || face >= m->face_count)
        return ori__fail_at(error, ORI_ERR_RANGE, "faces_vertices", face, "no face %d", face);
    int o = m->face_offsets[face], n = m->face_offsets[face + 1] - o;
    ori_v3 ca = ori_v3_make(0, 0, 0), cb = ori_v3_make(0, 0, 0);
    for (int k = 0; k < n; ++k) {
        int v = m->face_verts[o + k];
        if (!isfinite(coords[v].x) || !isfinite(coords[v].y) || !isfinite(coords[v].z))
            return ori__fail_at(error, ORI_ERR_RANGE, "vertices_coords", v, "coordinate is not finite");
        ca = ori_v3_add(ca, m->vertices[v]);
        cb = ori_v3_add(cb, coords[v]);
    }
    ca = ori_v3_scale(ca, 1.0 / n);
    cb = ori_v3_scale(cb, 1.0 / n);
    double h[9] = {0}; // column-major covariance H = Σ a bᵀ
    for (int k = 0; k < n; ++k) {
        int v = m->face_verts[o + k];
        ori_v3 a = ori_v3_sub(m->vertices[v], ca), b = ori_v3_sub(coords[v], cb);
        double av[3] = {a.x, a.y, a.z}, bv[3] = {b.x, b.y, b.z};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) h[i + 3 * j] += av[i] * bv[j];
    }
    double s[3], u[9], vt[9], superb[2];
    if (LAPACKE_dgesvd(LAPACK_COL_MAJOR, 'A', 'A', 3, 3, h, 3, s, u, 3, vt, 3, superb) != 0)
        return ori__fail_at(error, ORI_ERR_DEGENERATE, "faces_vertices", face, "pose fit failed");
    // R = V diag(1, 1, det) Uᵀ.
    double vmat[9], ut[9];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            vmat[i + 3 * j] = vt[j + 3 * i];
            ut[i + 3 * j] = u[j + 3 * i];
        }
    double det_v = vmat[0] * (vmat[4] * vmat[8] - vmat[7] * vmat[5]) - vmat[3] * (vmat[1] * vmat[8] - vmat[7] * vmat[2]) +
                   vmat[6] * (vmat[1] * vmat[5] - vmat[4] * vmat[2]);
    double det_u = u[0] * (u[4] * u[8] - u[7] * u[5]) - u[3] * (u[1] * u[8] - u[7] * u[2]) + u[6] * (u[1] * u[5] - u[4] * u[2]);
    double d = det_v * det_u < 0.0 ? -1.0 : 1.0;
    ori_rigid g;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double x = 0.0;
            for (int k = 0; k < 3; ++k) x += vmat[i + 3 * k] * (k == 2 ? d : 1.0) * ut[k + 3 * j];
            g.r.m[i][j] = x;
        }
    g.t = ori_v3_sub(cb, ori_m3_apply(g.r, ca));
    double err = 0.0;
    for (int k = 0; k < n; ++k) {
        int v = m->face_verts[o + k];
        double e = ori_v3_norm(ori_v3_sub(ori_rigid_apply(g, m->vertices[v]), coords[v]));
        if (e > err) err = e;
    }
    if (!(err <= ORI_TOL_POSE_FIT_REL * m->diagonal))
        return ori__fail_at(error, ORI_ERR_DEGENERATE, "faces_vertices", face,
                            "face %d is not a rigid copy of the flat face (misfit %.3g)", face, err);
    *out = g;
    return ORI_OK;
}
