// The thick solid of a posed sheet (export --thickness): thick panels. Every face corner (face f
// at vertex v) is offset to v ± (t/2)·n_f along its face's normal; faces joined by a crease with
// (nearly) equal normals share these points, so each flat region of the sheet becomes one slab
// and a flat sheet is a plain slab. Each slab is closed by walls along the edges where it ends:
// the boundary, cuts, and folded creases. At a folded crease two slabs meet along the crease
// line in the mid-surface (the hinge), overlap in a wedge on the inside of the fold and leave a
// V-groove on the outside, as rigid thick panels do.
//
// Every slab is a closed prism over its faces, so the triangles enclose exactly area × t, and
// every edge is shared by exactly two triangles. (A mitred, connected solid cannot keep that
// volume: its flat caps at interior vertices add O(t³) unless they were spherical.)
#include <math.h>

#include "render_internal.h"

typedef struct solid_builder {
    ori__solid *s;
    int cap_points, cap_point_vertex, cap_tris, cap_part, cap_face;
} solid_builder;

static int add_point(solid_builder *b, ori_v3 p, int vertex)
{
    ori__solid *s = b->s;
    ORI__RESERVE(s->points, b->cap_points, s->point_count + 1);
    ORI__RESERVE(s->point_vertex, b->cap_point_vertex, s->point_count + 1);
    s->points[s->point_count] = p;
    s->point_vertex[s->point_count] = vertex;
    return s->point_count++;
}

static void add_tri(solid_builder *b, int p0, int p1, int p2, ori__solid_part part, int face)
{
    if (p0 == p1 || p1 == p2 || p2 == p0) return; // a strip or bow tie collapsed by a shared point
    ori__solid *s = b->s;
    ORI__RESERVE(s->tris, b->cap_tris, s->tri_count + 1);
    ORI__RESERVE(s->part, b->cap_part, s->tri_count + 1);
    ORI__RESERVE(s->tri_face, b->cap_face, s->tri_count + 1);
    s->tris[s->tri_count][0] = p0;
    s->tris[s->tri_count][1] = p1;
    s->tris[s->tri_count][2] = p2;
    s->part[s->tri_count] = (unsigned char)part;
    s->tri_face[s->tri_count] = face;
    s->tri_count++;
}

// The corner (slot in face_verts) of face f at vertex v, or -1.
static int slot_of(const ori_mesh *m, int f, int v)
{
    for (int k = m->face_start[f]; k < m->face_start[f + 1]; ++k)
        if (m->face_verts[k] == v) return k;
    return -1;
}

static bool joined(const ori_mesh *m, int e)
{
    return m->edge_face[e][0] >= 0 && m->edge_face[e][1] >= 0 && m->assign[e] != ORI_ASSIGN_BOUNDARY &&
           m->assign[e] != ORI_ASSIGN_CUT;
}

void ori__solid_build(const ori_mesh *m, double thickness, ori__solid *s)
{
    memset(s, 0, sizeof *s);
    solid_builder b = {s, 0, 0, 0, 0, 0};
    int nc = m->face_start[m->face_count];
    int *slot_face = ori__alloc(sizeof(int) * (size_t)(nc + 1));
    for (int f = 0; f < m->face_count; ++f)
        for (int k = m->face_start[f]; k < m->face_start[f + 1]; ++k) slot_face[k] = f;
    // Corners sharing offset points: union across creases whose faces' normals agree.
    int *uf = ori__alloc(sizeof(int) * (size_t)(nc + 1));
    for (int k = 0; k < nc; ++k) uf[k] = k;
    double same_cos = cos(ORI_TOL_MESH_NORMAL_RAD);
    for (int e = 0; e < m->edge_count; ++e) {
        if (!joined(m, e)) continue;
        int A = m->edge_face[e][0], B = m->edge_face[e][1];
        if (ori_v3_dot(m->normal[A], m->normal[B]) < same_cos) continue;
        for (int i = 0; i < 2; ++i) {
            int ka = slot_of(m, A, m->edge_v[e][i]), kb = slot_of(m, B, m->edge_v[e][i]);
            if (ka < 0 || kb < 0) continue;
            int ra = ori__uf_root(uf, ka), rb = ori__uf_root(uf, kb);
            if (ra < rb) uf[rb] = ra;
            else if (rb < ra) uf[ra] = rb;
        }
    }
    // Offset points of every corner: those of its set's first corner.
    int *plus = ori__alloc(sizeof(int) * (size_t)(nc + 1));
    int *minus = ori__alloc(sizeof(int) * (size_t)(nc + 1));
    double h = 0.5 * thickness;
    for (int k = 0; k < nc; ++k) {
        int r = ori__uf_root(uf, k);
        if (r == k) {
            int v = m->face_verts[k];
            ori_v3 n = m->normal[slot_face[k]];
            plus[k] = add_point(&b, ori_v3_add(m->pos[v], ori_v3_scale(n, h)), v);
            minus[k] = add_point(&b, ori_v3_sub(m->pos[v], ori_v3_scale(n, h)), v);
        } else {
            plus[k] = plus[r];
            minus[k] = minus[r];
        }
    }
    // Top and bottom of every face.
    for (int f = 0; f < m->face_count; ++f)
        for (int t = m->face_tri_start[f]; t < m->face_tri_start[f + 1]; ++t) {
            int k0 = slot_of(m, f, m->tris[t].v[0]), k1 = slot_of(m, f, m->tris[t].v[1]), k2 = slot_of(m, f, m->tris[t].v[2]);
            add_tri(&b, plus[k0], plus[k1], plus[k2], ORI__SOLID_TOP, f);
            add_tri(&b, minus[k0], minus[k2], minus[k1], ORI__SOLID_BOTTOM, f);
        }
    // Walls where a slab ends: every side of a face whose edge does not merge it with the face
    // across (boundary, cut, folded crease).
    for (int e = 0; e < m->edge_count; ++e) {
        int v0 = m->edge_v[e][0], v1 = m->edge_v[e][1];
        for (int side = 0; side < 2; ++side) {
            int f = m->edge_face[e][side];
            if (f < 0) continue;
            // The left face runs v0 → v1, the right one v1 → v0.
            int p = side == 0 ? v0 : v1, q = side == 0 ? v1 : v0;
            int kp = slot_of(m, f, p), kq = slot_of(m, f, q);
            if (kp < 0 || kq < 0) continue;
            int g = m->edge_face[e][1 - side];
            if (joined(m, e) && g >= 0) {
                int gp = slot_of(m, g, p), gq = slot_of(m, g, q);
                if (gp >= 0 && gq >= 0 && plus[gp] == plus[kp] && plus[gq] == plus[kq]) continue; // one slab
            }
            add_tri(&b, plus[kq], plus[kp], minus[kp], ORI__SOLID_RIM, f);
            add_tri(&b, plus[kq], minus[kp], minus[kq], ORI__SOLID_RIM, f);
        }
    }
    ori__free(plus);
    ori__free(minus);
    ori__free(uf);
    ori__free(slot_face);
}

void ori__solid_free(ori__solid *s)
{
    ori__free(s->points);
    ori__free(s->point_vertex);
    ori__free(s->tris);
    ori__free(s->part);
    ori__free(s->tri_face);
    memset(s, 0, sizeof *s);
}
