// The exported surface of a posed state, shared by every mesh writer (mesh_write.c: OBJ, STL,
// PLY; mesh_write_gltf.c: glTF and GLB): the two-sided sheet or the thick solid as parts of
// triangles with their own vertices, texture coordinates and FOLD indices.
#include <math.h>

#include "mesh_write_internal.h"

typedef struct part_builder {
    ori__xpart *p;
    int cap_pos, cap_nrm, cap_uv, cap_fv, cap_tri, cap_face, cap_panel;
} part_builder;

static int part_vertex(part_builder *b, ori_v3 pos, ori_v3 nrm, ori_v2 uv, int fold_vertex)
{
    ori__xpart *p = b->p;
    ORI__RESERVE(p->pos, b->cap_pos, p->vcount + 1);
    ORI__RESERVE(p->nrm, b->cap_nrm, p->vcount + 1);
    ORI__RESERVE(p->uv, b->cap_uv, p->vcount + 1);
    ORI__RESERVE(p->fold_vertex, b->cap_fv, p->vcount + 1);
    p->pos[p->vcount] = pos;
    p->nrm[p->vcount] = nrm;
    p->uv[p->vcount] = uv;
    p->fold_vertex[p->vcount] = fold_vertex;
    return p->vcount++;
}

static void part_tri(part_builder *b, int a, int c, int d, int face)
{
    ori__xpart *p = b->p;
    ORI__RESERVE(p->tri, b->cap_tri, p->tcount + 1);
    ORI__RESERVE(p->fold_face, b->cap_face, p->tcount + 1);
    p->tri[p->tcount][0] = a;
    p->tri[p->tcount][1] = c;
    p->tri[p->tcount][2] = d;
    p->fold_face[p->tcount] = face;
    p->tcount++;
}

ori__uv_map ori__uv_of_mesh(const ori_mesh *m)
{
    ori__uv_map u = {INFINITY, INFINITY, 0, 0};
    double x1 = -INFINITY, y1 = -INFINITY;
    for (int v = 0; v < m->vertex_count; ++v) {
        u.x0 = fmin(u.x0, m->ref[v].x);
        u.y0 = fmin(u.y0, m->ref[v].y);
        x1 = fmax(x1, m->ref[v].x);
        y1 = fmax(y1, m->ref[v].y);
    }
    u.dx = x1 - u.x0;
    u.dy = y1 - u.y0;
    if (!(u.dx > 0.0)) u.dx = 1.0;
    if (!(u.dy > 0.0)) u.dy = 1.0;
    return u;
}

// Both sides of face f: vertices at positions pts (world or reference), the front with the
// face's normal nf.
static void sheet_face(const ori_mesh *m, int f, const ori_v3 *pts, ori_v3 nf, const ori__uv_map *u, part_builder *front,
                       part_builder *back)
{
    int o = m->face_start[f], n = m->face_start[f + 1] - o;
    int base_f = front->p->vcount, base_b = back->p->vcount;
    for (int k = 0; k < n; ++k) {
        int v = m->face_verts[o + k];
        ori_v2 uv = ori__uv_at(u, m->ref[v]);
        part_vertex(front, pts[v], nf, uv, v);
        part_vertex(back, pts[v], ori_v3_scale(nf, -1.0), uv, v);
    }
    for (int t = m->face_tri_start[f]; t < m->face_tri_start[f + 1]; ++t) {
        int l[3];
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < n; ++k)
                if (m->face_verts[o + k] == m->tris[t].v[i]) l[i] = k;
        part_tri(front, base_f + l[0], base_f + l[1], base_f + l[2], f);
        part_tri(back, base_b + l[0], base_b + l[2], base_b + l[1], f);
    }
}

// Unit normal of the reference face (for the reference sheet).
static ori_v3 ref_normal(const ori_mesh *m, int f)
{
    ori_v3 s = {0, 0, 0};
    for (int t = m->face_tri_start[f]; t < m->face_tri_start[f + 1]; ++t) {
        ori_v3 a = m->ref[m->tris[t].v[0]], b = m->ref[m->tris[t].v[1]], c = m->ref[m->tris[t].v[2]];
        s = ori_v3_add(s, ori_v3_cross(ori_v3_sub(b, a), ori_v3_sub(c, a)));
    }
    return ori_v3_normalize(s);
}

void ori__xmesh_face(const ori_mesh *m, int face, const ori__uv_map *u, ori__xmesh *x)
{
    memset(x, 0, sizeof *x);
    x->has_uv = m->has_flat;
    part_builder bf = {&x->part[ORI__PART_FRONT], 0, 0, 0, 0, 0, 0, 0};
    part_builder bb = {&x->part[ORI__PART_BACK], 0, 0, 0, 0, 0, 0, 0};
    sheet_face(m, face, m->ref, ref_normal(m, face), u, &bf, &bb);
}

// Record the panel of the last triangle of a part.
static void part_panel(part_builder *b, int panel)
{
    ori__xpart *p = b->p;
    ORI__RESERVE(p->panel, b->cap_panel, p->tcount);
    p->panel[p->tcount - 1] = panel;
}

void ori__xmesh_build(const ori_mesh *m, const ori_export_def *def, bool reference, ori__xmesh *x)
{
    double thickness = def->thickness;
    memset(x, 0, sizeof *x);
    x->has_uv = m->has_flat;
    ori__uv_map u = ori__uv_of_mesh(m);
    part_builder b[ORI__PART_COUNT];
    for (int i = 0; i < ORI__PART_COUNT; ++i) {
        memset(&b[i], 0, sizeof b[i]);
        b[i].p = &x->part[i];
    }
    if (!(thickness > 0.0)) {
        for (int f = 0; f < m->face_count; ++f)
            sheet_face(m, f, reference ? m->ref : m->pos, reference ? ref_normal(m, f) : m->normal[f], &u,
                       &b[ORI__PART_FRONT], &b[ORI__PART_BACK]);
        return;
    }
    ori__solid s;
    ori__solid_build(m, thickness, def->face_orders, def->face_order_count, &s);
    x->panel_count = s.panel_count;
    x->stacked_panels = s.stacked_panels;
    // Top and bottom share their points within a face (smooth per face); rim triangles get
    // their own vertices (flat shading).
    int *map = ori__alloc(sizeof(int) * (size_t)(s.point_count + 1));
    int *map_face = ori__alloc(sizeof(int) * (size_t)(s.point_count + 1));
    for (int i = 0; i < s.point_count; ++i) map_face[i] = -1;
    for (int part = 0; part < 2; ++part) {
        for (int i = 0; i < s.point_count; ++i) map_face[i] = -1;
        for (int t = 0; t < s.tri_count; ++t) {
            if (s.part[t] != part) continue;
            int f = s.tri_face[t];
            ori_v3 n = part == ORI__SOLID_TOP ? m->normal[f] : ori_v3_scale(m->normal[f], -1.0);
            int idx[3];
            for (int k = 0; k < 3; ++k) {
                int q = s.tris[t][k];
                if (map_face[q] != f) {
                    map_face[q] = f;
                    map[q] = part_vertex(&b[part], s.points[q], n, ori__uv_at(&u, m->ref[s.point_vertex[q]]), s.point_vertex[q]);
                }
                idx[k] = map[q];
            }
            part_tri(&b[part], idx[0], idx[1], idx[2], f);
            part_panel(&b[part], s.tri_panel[t]);
        }
    }
    for (int t = 0; t < s.tri_count; ++t) {
        if (s.part[t] != ORI__SOLID_RIM) continue;
        ori_v3 a = s.points[s.tris[t][0]], c = s.points[s.tris[t][1]], d = s.points[s.tris[t][2]];
        ori_v3 n = ori_v3_normalize(ori_v3_cross(ori_v3_sub(c, a), ori_v3_sub(d, a)));
        int idx[3];
        for (int k = 0; k < 3; ++k) {
            int q = s.tris[t][k];
            idx[k] = part_vertex(&b[ORI__PART_RIM], s.points[q], n, ori__uv_at(&u, m->ref[s.point_vertex[q]]), s.point_vertex[q]);
        }
        part_tri(&b[ORI__PART_RIM], idx[0], idx[1], idx[2], s.tri_face[t]);
        part_panel(&b[ORI__PART_RIM], s.tri_panel[t]);
    }
    ori__free(map);
    ori__free(map_face);
    ori__solid_free(&s);
}

void ori__xmesh_free(ori__xmesh *x)
{
    for (int i = 0; i < ORI__PART_COUNT; ++i) {
        ori__xpart *p = &x->part[i];
        ori__free(p->pos);
        ori__free(p->nrm);
        ori__free(p->uv);
        ori__free(p->fold_vertex);
        ori__free(p->tri);
        ori__free(p->fold_face);
        ori__free(p->panel);
    }
    memset(x, 0, sizeof *x);
}
