// The thick solid of a posed sheet (export --thickness): offset thick panels. Faces joined by a
// crease with (nearly) equal normals form one panel (a flat region of the sheet; a flat sheet is
// one panel), and every panel is its own closed prism over its faces, walls where it ends (the
// boundary, cuts and folded creases), so every edge of a panel is shared by exactly two of its
// triangles and the panels enclose exactly area × t.
//
// Offset panels (Edmondson/Morgan et al., Mech. Sci. 7 (2016) 69): a panel lies on the back side
// of the zero-thickness sheet, between the mid-surface and the mid-surface − t·n (n its front
// normal), so the hinge of a valley fold lies on the valley (front) surface and two panels of a
// valley fold meet there instead of overlapping in a wedge. Panels lying in one plane (folded
// flat onto each other, fold angles ±180) are stacked: sorted by their layer (the layer order of
// render's stacking along the fold tree, or FOLD faceOrders when given), each takes the slab of
// thickness t just above the highest lower panel of its plane that it overlaps, so stacked panels
// touch and never interpenetrate. A plane's panels go on the front side instead where their back
// would overlap another panel (a greedy search by separating axes). The zero-thickness poses are unchanged; only the offsets differ.
#include <math.h>
#include <stdlib.h>

#include "render_internal.h"

// Panels whose mid-planes are this close (× the reference diagonal) and parallel share a plane.
#define PLANE_TOL_REL 1e-7

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

typedef struct panel_key {
    double height; // layer along the plane's normal
    int panel;
} panel_key;

static int cmp_key(const void *a, const void *b)
{
    const panel_key *x = a, *y = b;
    if (x->height < y->height) return -1;
    if (x->height > y->height) return 1;
    return (x->panel > y->panel) - (x->panel < y->panel);
}

// --- overlap of panels (separating axes of triangle prisms) --------------------------------

// A triangle of a panel thickened: the triangle at offsets lo and lo + t along n0.
typedef struct prism {
    ori_v3 p[6];
    ori_v3 lo, hi; // bounding box
    int group;     // the plane group whose side choice moves it
    int panel;
} prism;

static void prism_axes_project(const prism *a, ori_v3 n, double *mn, double *mx)
{
    *mn = INFINITY;
    *mx = -INFINITY;
    for (int i = 0; i < 6; ++i) {
        double d = ori_v3_dot(n, a->p[i]);
        *mn = fmin(*mn, d);
        *mx = fmax(*mx, d);
    }
}

// True when some axis separates a and b (their interiors are disjoint; touching counts as
// disjoint within eps).
static bool separated_on(const prism *a, const prism *b, ori_v3 n, double eps)
{
    double len = ori_v3_norm(n);
    if (!(len > 1e-300)) return false;
    n = ori_v3_scale(n, 1.0 / len);
    double a0, a1, b0, b1;
    prism_axes_project(a, n, &a0, &a1);
    prism_axes_project(b, n, &b0, &b1);
    return a1 <= b0 + eps || b1 <= a0 + eps;
}

static bool prisms_overlap(const prism *a, const prism *b, double eps)
{
    for (int k = 0; k < 3; ++k)
        if (a->hi.x * (k == 0) + a->hi.y * (k == 1) + a->hi.z * (k == 2) <=
                b->lo.x * (k == 0) + b->lo.y * (k == 1) + b->lo.z * (k == 2) + eps ||
            b->hi.x * (k == 0) + b->hi.y * (k == 1) + b->hi.z * (k == 2) <=
                a->lo.x * (k == 0) + a->lo.y * (k == 1) + a->lo.z * (k == 2) + eps)
            return false;
    const prism *pr[2] = {a, b};
    ori_v3 edges[2][4];
    for (int i = 0; i < 2; ++i) {
        const prism *q = pr[i];
        for (int k = 0; k < 3; ++k) edges[i][k] = ori_v3_sub(q->p[(k + 1) % 3], q->p[k]);
        edges[i][3] = ori_v3_sub(q->p[3], q->p[0]);
        ori_v3 n = ori_v3_cross(edges[i][0], edges[i][1]);
        if (separated_on(a, b, n, eps)) return false;
        for (int k = 0; k < 3; ++k)
            if (separated_on(a, b, ori_v3_cross(edges[i][k], n), eps)) return false;
    }
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (separated_on(a, b, ori_v3_cross(edges[0][i], edges[1][j]), eps)) return false;
    return true;
}

static void prism_place(const ori_mesh *m, const ori_mesh_triangle *t, ori_v3 n0, double lo, double thickness, prism *out)
{
    for (int k = 0; k < 3; ++k) {
        out->p[k] = ori_v3_add(m->pos[t->v[k]], ori_v3_scale(n0, lo));
        out->p[k + 3] = ori_v3_add(m->pos[t->v[k]], ori_v3_scale(n0, lo + thickness));
    }
    out->lo = out->hi = out->p[0];
    for (int k = 1; k < 6; ++k) {
        out->lo = ori_v3_make(fmin(out->lo.x, out->p[k].x), fmin(out->lo.y, out->p[k].y), fmin(out->lo.z, out->p[k].z));
        out->hi = ori_v3_make(fmax(out->hi.x, out->p[k].x), fmax(out->hi.y, out->p[k].y), fmax(out->hi.z, out->p[k].z));
    }
}

// Pairs of overlapping prisms of different panels that involve group g (g < 0: all pairs).
static int overlaps_of(const prism *P, int n, int g, double eps)
{
    int count = 0;
    for (int i = 0; i < n; ++i) {
        if (g >= 0 && P[i].group != g) continue;
        for (int j = 0; j < n; ++j) {
            if (P[j].panel == P[i].panel) continue;
            if (g >= 0 ? (P[j].group == g && j < i) : j < i) continue;
            if (prisms_overlap(&P[i], &P[j], eps)) count++;
        }
    }
    return count;
}

void ori__solid_build(const ori_mesh *m, double thickness, const int *face_orders, int face_order_count,
                      ori__solid *s)
{
    memset(s, 0, sizeof *s);
    solid_builder b = {s, 0, 0, 0, 0, 0};
    int nf = m->face_count;
    int nc = m->face_start[nf];
    int *slot_face = ori__alloc(sizeof(int) * (size_t)(nc + 1));
    for (int f = 0; f < nf; ++f)
        for (int k = m->face_start[f]; k < m->face_start[f + 1]; ++k) slot_face[k] = f;
    // Corners sharing offset points, and faces forming one panel: union across creases whose
    // faces' normals agree.
    int *uf = ori__alloc(sizeof(int) * (size_t)(nc + 1));
    int *fu = ori__alloc(sizeof(int) * (size_t)(nf + 1));
    for (int k = 0; k < nc; ++k) uf[k] = k;
    for (int f = 0; f < nf; ++f) fu[f] = f;
    double same_cos = cos(ORI_TOL_MESH_NORMAL_RAD);
    for (int e = 0; e < m->edge_count; ++e) {
        if (!joined(m, e)) continue;
        int A = m->edge_face[e][0], B = m->edge_face[e][1];
        if (ori_v3_dot(m->normal[A], m->normal[B]) < same_cos) continue;
        int fa = ori__uf_root(fu, A), fb = ori__uf_root(fu, B);
        if (fa < fb) fu[fb] = fa;
        else if (fb < fa) fu[fa] = fb;
        for (int i = 0; i < 2; ++i) {
            int ka = slot_of(m, A, m->edge_v[e][i]), kb = slot_of(m, B, m->edge_v[e][i]);
            if (ka < 0 || kb < 0) continue;
            int ra = ori__uf_root(uf, ka), rb = ori__uf_root(uf, kb);
            if (ra < rb) uf[rb] = ra;
            else if (rb < ra) uf[ra] = rb;
        }
    }
    // Panels: numbered by their lowest face.
    int *panel_of = ori__alloc(sizeof(int) * (size_t)(nf + 1));
    int *panel_root = ori__alloc(sizeof(int) * (size_t)(nf + 1));
    int np = 0;
    for (int f = 0; f < nf; ++f) panel_of[f] = -1;
    for (int f = 0; f < nf; ++f) {
        int r = ori__uf_root(fu, f);
        if (panel_of[r] < 0) {
            panel_of[r] = np;
            panel_root[np++] = r;
        }
        panel_of[f] = panel_of[r];
    }
    // Layers: faceOrders' ranks where given (f above g along n_g when s = +1), else the stacking.
    ori_v3 *layer = ori__alloc(sizeof(ori_v3) * (size_t)(nf + 1));
    ori__render_stacking(m, layer);
    if (face_orders && face_order_count > 0) {
        // Relax "f lies s·t above g along n_g" a few rounds (a linear extension where the orders
        // are consistent); the stacking is kept for faces the orders do not name.
        for (int round = 0; round < nf + 1; ++round) {
            bool changed = false;
            for (int i = 0; i < face_order_count; ++i) {
                int f = face_orders[3 * i], g = face_orders[3 * i + 1], sg = face_orders[3 * i + 2];
                ori_v3 up = ori_v3_scale(m->normal[g], (double)sg * m->fold_sign[g]);
                double hf = ori_v3_dot(layer[f], up), hg = ori_v3_dot(layer[g], up);
                if (hf < hg + 1.0 - 1e-9) {
                    layer[f] = ori_v3_add(layer[f], ori_v3_scale(up, hg + 1.0 - hf));
                    changed = true;
                }
            }
            if (!changed) break;
        }
    }
    // Planes: panels whose mid-planes coincide (parallel normals, same offset).
    double tol = PLANE_TOL_REL * m->ref_diag;
    int *plane_of = ori__alloc(sizeof(int) * (size_t)(np + 1));
    ori_v3 *pn = ori__alloc(sizeof(ori_v3) * (size_t)(np + 1));
    double *pd = ori__alloc(sizeof(double) * (size_t)(np + 1));
    for (int q = 0; q < np; ++q) {
        int f = panel_root[q];
        pn[q] = m->normal[f];
        pd[q] = ori_v3_dot(pn[q], m->pos[m->face_verts[m->face_start[f]]]);
        plane_of[q] = q;
        for (int r = 0; r < q; ++r) {
            if (plane_of[r] != r) continue;
            double c = ori_v3_dot(pn[q], pn[r]);
            if (fabs(c) < same_cos) continue;
            double sgn = c > 0 ? 1.0 : -1.0;
            if (fabs(pd[q] - sgn * pd[r]) > tol) continue;
            plane_of[q] = r;
            break;
        }
    }
    // Offsets along the plane's normal: the interval [lo, lo + t] of every panel. The panels of
    // a plane, sorted by layer, take consecutive slabs from a base: the lowest panel's back side
    // (or its front, front_side[r] = 1, where its back would overlap another panel).
    double *lo = ori__alloc(sizeof(double) * (size_t)(np + 1));
    int *rank = ori__alloc(sizeof(int) * (size_t)(np + 1));
    double *base_back = ori__alloc(sizeof(double) * (size_t)(np + 1));
    double *flip = ori__alloc(sizeof(double) * (size_t)(np + 1));
    signed char *front_side = ori__calloc((size_t)np + 1, 1);
    panel_key *keys = ori__alloc(sizeof(panel_key) * (size_t)(np + 1));
    s->panel_count = np;
    s->stacked_panels = 0;
    // Triangles by panel, placed in their plane (offset 0), for testing which panels of a plane
    // overlap there.
    int nt = m->tri_count;
    int *tp_start = ori__calloc((size_t)np + 2, sizeof(int));
    int *tp = ori__alloc(sizeof(int) * (size_t)(nt + 1));
    for (int t = 0; t < nt; ++t) tp_start[panel_of[m->tris[t].face] + 1]++;
    for (int q = 0; q < np; ++q) tp_start[q + 1] += tp_start[q];
    int *tp_fill = ori__alloc(sizeof(int) * (size_t)(np + 1));
    memcpy(tp_fill, tp_start, sizeof(int) * (size_t)(np + 1));
    for (int t = 0; t < nt; ++t) tp[tp_fill[panel_of[m->tris[t].face]]++] = t;
    ori__free(tp_fill);
    double eps = 1e-9 * m->ref_diag;
    for (int r = 0; r < np; ++r) {
        if (plane_of[r] != r) continue;
        int k = 0;
        for (int q = r; q < np; ++q)
            if (plane_of[q] == r) keys[k++] = (panel_key){ori_v3_dot(layer[panel_root[q]], pn[r]), q};
        qsort(keys, (size_t)k, sizeof *keys, cmp_key);
        bool up = ori_v3_dot(pn[keys[0].panel], pn[r]) > 0;
        base_back[r] = up ? -thickness : 0.0;
        flip[r] = up ? thickness : -thickness;
        // Bottom to top, each panel takes the slab just above the highest earlier panel of the
        // plane it overlaps (panels side by side in a plane keep the same slab).
        for (int i = 0; i < k; ++i) {
            int q = keys[i].panel;
            rank[q] = 0;
            for (int j = 0; j < i; ++j) {
                int o = keys[j].panel;
                if (rank[o] + 1 <= rank[q]) continue;
                bool hit = false;
                for (int a = tp_start[q]; a < tp_start[q + 1] && !hit; ++a)
                    for (int c = tp_start[o]; c < tp_start[o + 1] && !hit; ++c) {
                        prism pa, pc;
                        prism_place(m, &m->tris[tp[a]], pn[r], 0.0, thickness, &pa);
                        prism_place(m, &m->tris[tp[c]], pn[r], 0.0, thickness, &pc);
                        hit = prisms_overlap(&pa, &pc, eps);
                    }
                if (hit) rank[q] = rank[o] + 1;
            }
        }
        int lifted = 0;
        for (int i = 0; i < k; ++i) lifted += rank[keys[i].panel] > 0;
        s->stacked_panels += lifted;
    }
    ori__free(tp_start);
    ori__free(tp);
    for (int q = 0; q < np; ++q) lo[q] = base_back[plane_of[q]] + rank[q] * thickness;
    // Side search: flip a plane's panels to the front while that removes overlaps.
    prism *P = ori__alloc(sizeof(prism) * (size_t)(nt + 1));
    for (int t = 0; t < nt; ++t) {
        int q = panel_of[m->tris[t].face];
        prism_place(m, &m->tris[t], pn[plane_of[q]], lo[q], thickness, &P[t]);
        P[t].group = plane_of[q];
        P[t].panel = q;
    }
    if (overlaps_of(P, nt, -1, eps) > 0) {
        for (int round = 0; round < 4; ++round) {
            bool changed = false;
            for (int r = 0; r < np; ++r) {
                if (plane_of[r] != r) continue;
                int before = overlaps_of(P, nt, r, eps);
                if (before == 0) continue;
                double shift = front_side[r] ? -flip[r] : flip[r];
                for (int t = 0; t < nt; ++t)
                    if (P[t].group == r) prism_place(m, &m->tris[t], pn[r], lo[P[t].panel] + shift, thickness, &P[t]);
                int after = overlaps_of(P, nt, r, eps);
                if (after < before) {
                    front_side[r] = (signed char)!front_side[r];
                    for (int q = 0; q < np; ++q)
                        if (plane_of[q] == r) lo[q] += shift;
                    changed = true;
                } else {
                    for (int t = 0; t < nt; ++t)
                        if (P[t].group == r) prism_place(m, &m->tris[t], pn[r], lo[P[t].panel], thickness, &P[t]);
                }
            }
            if (!changed) break;
        }
    }
    s->front_panels = 0;
    for (int q = 0; q < np; ++q) s->front_panels += front_side[plane_of[q]];
    s->overlapping_pairs = overlaps_of(P, nt, -1, eps);
    ori__free(P);
    ori__free(rank);
    ori__free(base_back);
    ori__free(flip);
    ori__free(front_side);
    // Offset points of every corner: those of its set's first corner. "plus" is the panel's
    // front surface, "minus" its back.
    int *plus = ori__alloc(sizeof(int) * (size_t)(nc + 1));
    int *minus = ori__alloc(sizeof(int) * (size_t)(nc + 1));
    for (int k = 0; k < nc; ++k) {
        int r = ori__uf_root(uf, k);
        if (r == k) {
            int v = m->face_verts[k];
            int q = panel_of[slot_face[k]];
            ori_v3 n0 = pn[plane_of[q]];
            bool up = ori_v3_dot(m->normal[slot_face[k]], n0) > 0;
            ori_v3 a = ori_v3_add(m->pos[v], ori_v3_scale(n0, lo[q])), c = ori_v3_add(m->pos[v], ori_v3_scale(n0, lo[q] + thickness));
            plus[k] = add_point(&b, up ? c : a, v);
            minus[k] = add_point(&b, up ? a : c, v);
        } else {
            plus[k] = plus[r];
            minus[k] = minus[r];
        }
    }
    s->tri_panel = NULL;
    int cap_tp = 0;
#define PANEL_TRI(p0, p1, p2, part, face)                                                              \
    do {                                                                                               \
        int before = s->tri_count;                                                                     \
        add_tri(&b, p0, p1, p2, part, face);                                                           \
        if (s->tri_count > before) {                                                                   \
            ORI__RESERVE(s->tri_panel, cap_tp, s->tri_count);                                          \
            s->tri_panel[before] = panel_of[face];                                                     \
        }                                                                                              \
    } while (0)
    // Top and bottom of every face.
    for (int f = 0; f < nf; ++f)
        for (int t = m->face_tri_start[f]; t < m->face_tri_start[f + 1]; ++t) {
            int k0 = slot_of(m, f, m->tris[t].v[0]), k1 = slot_of(m, f, m->tris[t].v[1]), k2 = slot_of(m, f, m->tris[t].v[2]);
            PANEL_TRI(plus[k0], plus[k1], plus[k2], ORI__SOLID_TOP, f);
            PANEL_TRI(minus[k0], minus[k2], minus[k1], ORI__SOLID_BOTTOM, f);
        }
    // Walls where a panel ends: every side of a face whose edge does not merge it with the face
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
                if (gp >= 0 && gq >= 0 && plus[gp] == plus[kp] && plus[gq] == plus[kq]) continue; // one panel
            }
            PANEL_TRI(plus[kq], plus[kp], minus[kp], ORI__SOLID_RIM, f);
            PANEL_TRI(plus[kq], minus[kp], minus[kq], ORI__SOLID_RIM, f);
        }
    }
#undef PANEL_TRI
    ori__free(plus);
    ori__free(minus);
    ori__free(lo);
    ori__free(keys);
    ori__free(plane_of);
    ori__free(pn);
    ori__free(pd);
    ori__free(layer);
    ori__free(panel_of);
    ori__free(panel_root);
    ori__free(fu);
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
    ori__free(s->tri_panel);
    memset(s, 0, sizeof *s);
}
