// Kirigami: a flat pattern with its cuts opened, so that a folded state has one position per
// vertex. A cut (C, or B between two faces) is a boundary inside the sheet: the faces on its two
// sides move apart, so a vertex where cuts separate the paper into several fans (a vertex inside
// a multi-segment cut, a cut's corner) needs one vertex per fan. Without this the vertex shared by
// both sides is placed by one of them, and a face of the other side is drawn, rendered and checked
// for collision with a corner that is not its own (Origami Simulator's kirigami: "the face is not
// planar: vertex 0 is 0.0559 off its plane").
#include <stdlib.h>
#include <string.h>

#include "kinematics_internal.h"

static bool joins_paper(ori_edge e, const int faces[2])
{
    if (faces[0] == ORI_NULL_INDEX || faces[1] == ORI_NULL_INDEX) return false;
    return e.assignment != ORI_ASSIGN_BOUNDARY && e.assignment != ORI_ASSIGN_CUT;
}

// The vertex face f uses at v (its first corner there).
static int copy_at(const int *off, const int *cf, const int *copy, int v, int f)
{
    for (int k = off[v]; k < off[v + 1]; ++k)
        if (cf[k] == f) return copy[k];
    return v;
}

ori_status ori_pattern_open_cuts(const ori_pattern *p, ori_pattern **out, int *opened, ori_error *error)
{
    ORI_ASSERT(p && out);
    *out = NULL;
    if (opened) *opened = 0;
    ori_error_clear(error);
    if (!ori_pattern_is_built(p)) return ori__fail(error, ORI_ERR_ARGUMENT, "the pattern is not built");
    int V = ori_pattern_vertex_count(p), E = ori_pattern_edge_count(p), F = ori_pattern_face_count(p);
    // Per vertex: its edges in counter-clockwise order; corner k lies after edge k (the face on
    // the left of edge k leaving the vertex). copy[corner] = the vertex that corner uses.
    int *off = ori__alloc(sizeof(int) * (size_t)(V + 1));
    off[0] = 0;
    for (int v = 0; v < V; ++v) off[v + 1] = off[v] + ori_pattern_vertex_degree(p, v);
    int H = off[V];
    int *es = ori__alloc(sizeof(int) * (size_t)(H + 1));
    int *cf = ori__alloc(sizeof(int) * (size_t)(H + 1)); // corner face
    int *copy = ori__alloc(sizeof(int) * (size_t)(H + 1));
    int nv = V;
    for (int v = 0; v < V; ++v) {
        int d = off[v + 1] - off[v], *ev = es + off[v];
        ori_pattern_vertex_edges(p, v, ev, d);
        bool sep_any = false;
        for (int k = 0; k < d; ++k) {
            ori_edge ed = ori_pattern_edge(p, ev[k]);
            int fs[2];
            ori_pattern_edge_faces(p, ev[k], fs);
            cf[off[v] + k] = ed.v[0] == v ? fs[0] : fs[1];
            if (ed.v[0] == ed.v[1]) cf[off[v] + k] = ORI_NULL_INDEX;
            if (!joins_paper(ed, fs)) sep_any = true;
        }
        for (int k = 0; k < d; ++k) copy[off[v] + k] = v;
        if (!sep_any || d == 0) continue;
        // Fans: runs of corners between separating edges; the first keeps the vertex.
        int start = 0;
        for (int k = 0; k < d; ++k) {
            ori_edge ed = ori_pattern_edge(p, ev[k]);
            int fs[2];
            ori_pattern_edge_faces(p, ev[k], fs);
            if (!joins_paper(ed, fs)) {
                start = k;
                break;
            }
        }
        int id = -1;
        bool kept = false; // the first fan keeps the vertex, the others get copies
        for (int i = 0; i < d; ++i) {
            int k = (start + i) % d;
            ori_edge ed = ori_pattern_edge(p, ev[k]);
            int fs[2];
            ori_pattern_edge_faces(p, ev[k], fs);
            if (!joins_paper(ed, fs)) id = -1; // a new fan begins after edge k
            if (cf[off[v] + k] == ORI_NULL_INDEX) continue;
            if (id < 0) {
                id = kept ? nv++ : v;
                kept = true;
            }
            copy[off[v] + k] = id;
        }
    }
    ori_status st = ORI_OK;
    if (nv == V) goto done; // nothing to open
    {
        ori_pattern_def pd = ori_default_pattern_def();
        pd.vertex_capacity = nv;
        pd.edge_capacity = E + (nv - V) + 1;
        ori_pattern *q = ori_pattern_create(&pd);
        for (int v = 0; v < V; ++v) ori_pattern_add_vertex(q, ori_pattern_vertex(p, v));
        int *origin = ori__alloc(sizeof(int) * (size_t)(nv - V + 1)); // the vertex each copy copies
        for (int v = 0; v < V; ++v)
            for (int k = off[v]; k < off[v + 1]; ++k)
                if (copy[k] >= V) origin[copy[k] - V] = v;
        for (int c = 0; c < nv - V; ++c) ori_pattern_add_vertex(q, ori_pattern_vertex(p, origin[c]));
        ori__free(origin);
        // Edges: each keeps its index with the vertices of its left face (else its right face);
        // a cut between two faces whose sides now have different vertices gets a second edge.
        int extra_cap = 16, nextra = 0;
        int (*extra)[2] = ori__alloc(sizeof(int[2]) * (size_t)extra_cap);
        int *extra_of = ori__alloc(sizeof(int) * (size_t)(E + 1));
        for (int e = 0; e < E; ++e) {
            ori_edge ed = ori_pattern_edge(p, e);
            int fs[2];
            ori_pattern_edge_faces(p, e, fs);
            int f0 = fs[0] != ORI_NULL_INDEX ? fs[0] : fs[1];
            int a = ed.v[0], b = ed.v[1];
            if (f0 != ORI_NULL_INDEX) {
                a = copy_at(off, cf, copy, ed.v[0], f0);
                b = copy_at(off, cf, copy, ed.v[1], f0);
            }
            extra_of[e] = -1;
            if (fs[0] != ORI_NULL_INDEX && fs[1] != ORI_NULL_INDEX && fs[0] != fs[1] && !joins_paper(ed, fs)) {
                int a1 = copy_at(off, cf, copy, ed.v[0], fs[1]), b1 = copy_at(off, cf, copy, ed.v[1], fs[1]);
                if (a1 != a || b1 != b) {
                    // The two sides share an end point where the cut ends inside the paper; there
                    // they leave it in the same direction and the cyclic order puts the lower
                    // index first: the side whose face lies clockwise of the other must come
                    // first, the right side at v0, the left side at v1.
                    int ka = a, kb = b, xa = a1, xb = b1; // kept (this index), extra (new edge)
                    if (a1 == a) {
                        ka = a1, kb = b1, xa = a, xb = b;
                    }
                    a = ka, b = kb;
                    if (nextra == extra_cap) {
                        extra_cap *= 2;
                        extra = ori__realloc(extra, sizeof(int[2]) * (size_t)extra_cap);
                    }
                    extra[nextra][0] = xa;
                    extra[nextra][1] = xb;
                    extra_of[e] = nextra++;
                }
            }
            ori_pattern_add_edge(q, a, b, ed.assignment, ed.fold_angle_rad);
        }
        for (int e = 0; e < E; ++e)
            if (extra_of[e] >= 0) {
                ori_edge ed = ori_pattern_edge(p, e);
                ori_pattern_add_edge(q, extra[extra_of[e]][0], extra[extra_of[e]][1], ed.assignment, 0.0);
            }
        ori__free(extra);
        ori__free(extra_of);
        int cap = 16;
        int *fv = ori__alloc(sizeof(int) * (size_t)cap);
        for (int f = 0; f < F; ++f) {
            int n = ori_pattern_face_size(p, f);
            if (n > cap) {
                cap = n;
                fv = ori__realloc(fv, sizeof(int) * (size_t)cap);
            }
            ori_pattern_face_vertices(p, f, fv, n);
            for (int i = 0; i < n; ++i) fv[i] = copy_at(off, cf, copy, fv[i], f);
            ori_pattern_add_face(q, fv, n);
        }
        ori__free(fv);
        ori_pattern_set_has_fold_angles(q, ori_pattern_has_fold_angles(p));
        ori_build_def bd = ori_default_build_def();
        bd.check_planarity = false; // the two sides of a cut coincide in the flat sheet
        bd.compute_faces = false;
        st = ori_pattern_build(q, &bd, error);
        for (int f = 0; st == ORI_OK && f < F; ++f) {
            const char *name = ori_pattern_face_name(p, f);
            if (name) st = ori_pattern_set_face_name(q, f, name);
        }
        if (st != ORI_OK) ori_pattern_destroy(q);
        else *out = q;
    }
done:
    if (st == ORI_OK && !*out) *out = ori_pattern_clone(p);
    if (opened) *opened = nv - V;
    ori__free(off);
    ori__free(es);
    ori__free(cf);
    ori__free(copy);
    return st;
}
