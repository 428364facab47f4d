// Symmetries of the flat crease pattern: the isometries of the plane that map vertices onto
// vertices and edges onto edges with the same assignment. Every such isometry fixes the
// centroid c of the vertices, so it is determined by the image of one vertex a (the one with
// the fewest vertices at its distance from c, farthest first) and by whether it reflects: for
// each vertex b at a's distance, the rotation about c taking a to b and the reflection across
// the line through c bisecting a and b are the only candidates, each checked on every vertex
// (binary search in the x-sorted vertices) and every edge.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "multifold_internal.h"

typedef struct sym_xv {
    double x;
    int v;
} sym_xv;

typedef struct sym_ctx {
    const ori_mechanism *m;
    sym_xv *sorted; // vertices by x
    double tol;
    ori_v3 c;
} sym_ctx;

static int cmp_x(const void *a, const void *b)
{
    double x = ((const sym_xv *)a)->x, y = ((const sym_xv *)b)->x;
    return x < y ? -1 : x > y;
}

static int find_vertex(const sym_ctx *s, double x, double y)
{
    const ori_mechanism *m = s->m;
    int lo = 0, hi = m->vertex_count;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (s->sorted[mid].x < x - s->tol) lo = mid + 1;
        else hi = mid;
    }
    for (int k = lo; k < m->vertex_count; ++k) {
        ori_v3 p = m->vertices[s->sorted[k].v];
        if (p.x > x + s->tol) break;
        if (fabs(p.y - y) <= s->tol) return s->sorted[k].v;
    }
    return -1;
}

// Apply the symmetry to every vertex; vmap receives the images. False when some vertex or edge
// has no image.
static bool check(const sym_ctx *s, const ori_symmetry *g, int *vmap, int *emap)
{
    const ori_mechanism *m = s->m;
    for (int v = 0; v < m->vertex_count; ++v) {
        ori_v3 p = m->vertices[v];
        double x = g->r[0][0] * p.x + g->r[0][1] * p.y + g->t[0];
        double y = g->r[1][0] * p.x + g->r[1][1] * p.y + g->t[1];
        if ((vmap[v] = find_vertex(s, x, y)) < 0) return false;
    }
    for (int e = 0; e < m->edge_count; ++e) {
        int a = vmap[m->edges[e].v[0]], b = vmap[m->edges[e].v[1]];
        int f = -1;
        for (int k = m->vert_offsets[a]; k < m->vert_offsets[a + 1]; ++k) {
            int c = m->vert_edges[k];
            if ((m->edges[c].v[0] == a && m->edges[c].v[1] == b) || (m->edges[c].v[0] == b && m->edges[c].v[1] == a)) {
                f = c;
                break;
            }
        }
        if (f < 0 || m->edges[f].assignment != m->edges[e].assignment) return false;
        if (emap) emap[e] = f;
    }
    return true;
}

// Every symmetry (up to cap into out, each with its edge map into emaps when not NULL: cap ×
// edge_count); returns the group order.
static int symmetries(const ori_mechanism *m, ori_symmetry *out, int cap, int *emaps)
{
    int V = m->vertex_count;
    if (V == 0) return 0;
    sym_ctx s;
    s.m = m;
    s.tol = ORI_TOL_SYMMETRY_REL * m->diagonal;
    s.sorted = ori__alloc(sizeof(sym_xv) * (size_t)V);
    for (int v = 0; v < V; ++v) s.sorted[v] = (sym_xv){m->vertices[v].x, v};
    qsort(s.sorted, (size_t)V, sizeof(sym_xv), cmp_x);
    s.c = ori_v3_make(0, 0, 0);
    for (int v = 0; v < V; ++v) s.c = ori_v3_add(s.c, m->vertices[v]);
    s.c = ori_v3_scale(s.c, 1.0 / V);
    double *rad = ori__alloc(sizeof(double) * (size_t)V);
    for (int v = 0; v < V; ++v) rad[v] = hypot(m->vertices[v].x - s.c.x, m->vertices[v].y - s.c.y);
    // Reference vertex: off the centre, fewest vertices at its distance.
    int a = -1, best = V + 1;
    for (int v = 0; v < V; ++v) {
        if (rad[v] <= s.tol) continue;
        int n = 0;
        for (int w = 0; w < V; ++w) n += fabs(rad[w] - rad[v]) <= s.tol;
        if (n < best || (n == best && rad[v] > rad[a])) {
            best = n;
            a = v;
        }
    }
    int order = 0;
    int *vmap = ori__alloc(sizeof(int) * (size_t)V);
    int *emap = ori__alloc(sizeof(int) * (size_t)(m->edge_count + 1));
    if (a < 0) { // a single vertex: only the identity is reported
        ori__free(rad);
        ori__free(vmap);
        ori__free(emap);
        ori__free(s.sorted);
        return 0;
    }
    double ax = m->vertices[a].x - s.c.x, ay = m->vertices[a].y - s.c.y;
    double aa = atan2(ay, ax);
    for (int b = 0; b < V; ++b) {
        if (fabs(rad[b] - rad[a]) > s.tol) continue;
        double bb = atan2(m->vertices[b].y - s.c.y, m->vertices[b].x - s.c.x);
        for (int refl = 0; refl < 2; ++refl) {
            ori_symmetry g;
            memset(&g, 0, sizeof g);
            if (!refl) { // rotation by bb − aa
                double t = bb - aa, co = cos(t), si = sin(t);
                g.r[0][0] = co;
                g.r[0][1] = -si;
                g.r[1][0] = si;
                g.r[1][1] = co;
            } else { // reflection across the line at angle (aa + bb) / 2
                double t = aa + bb, co = cos(t), si = sin(t);
                g.r[0][0] = co;
                g.r[0][1] = si;
                g.r[1][0] = si;
                g.r[1][1] = -co;
                g.reflection = true;
            }
            // Exact identity for a → a without reflection.
            if (b == a && !refl) {
                g.r[0][0] = g.r[1][1] = 1.0;
                g.r[0][1] = g.r[1][0] = 0.0;
            }
            g.t[0] = s.c.x - (g.r[0][0] * s.c.x + g.r[0][1] * s.c.y);
            g.t[1] = s.c.y - (g.r[1][0] * s.c.x + g.r[1][1] * s.c.y);
            if (!check(&s, &g, vmap, emap)) continue;
            if (order < cap) {
                if (out) out[order] = g;
                if (emaps) memcpy(emaps + (size_t)order * (size_t)m->edge_count, emap, sizeof(int) * (size_t)m->edge_count);
            }
            order++;
        }
    }
    ori__free(rad);
    ori__free(vmap);
    ori__free(emap);
    ori__free(s.sorted);
    return order;
}

int ori_mechanism_symmetries(const ori_mechanism *m, ori_symmetry *out, int cap)
{
    ORI_ASSERT(m && (out || cap == 0));
    return symmetries(m, out, cap, NULL);
}

static int find_root(int *parent, int x)
{
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
}

int ori_mechanism_symmetry_orbits(const ori_mechanism *m, int *orbit)
{
    ORI_ASSERT(m && orbit);
    int E = m->edge_count;
    int order = symmetries(m, NULL, 0, NULL);
    int *emaps = ori__alloc(sizeof(int) * (size_t)(order > 0 ? order : 1) * (size_t)(E + 1));
    symmetries(m, NULL, order, emaps);
    for (int e = 0; e < E; ++e) orbit[e] = e;
    for (int g = 0; g < order; ++g)
        for (int e = 0; e < E; ++e) {
            int x = find_root(orbit, e), y = find_root(orbit, emaps[(size_t)g * (size_t)E + (size_t)e]);
            if (x != y) orbit[x > y ? x : y] = x < y ? x : y; // the smaller index is the root
        }
    int n = 0;
    for (int e = 0; e < E; ++e) {
        orbit[e] = find_root(orbit, e);
        int j = m->edge_joint[e];
        if (orbit[e] == e && j != ORI_NULL_INDEX && m->joints[j].kind == ORI_JOINT_REVOLUTE) n++;
    }
    ori__free(emaps);
    return n;
}
