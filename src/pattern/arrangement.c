// Planar arrangement: inserting straight segments into a flat crease pattern.
//
// One insertion runs in two phases. The plan (no mutation) snaps the end points (to a vertex,
// else onto an edge, else free), collects every vertex within the tolerance of the segment and
// every edge it properly crosses (exact orientation signs on stored coordinates), sorts these
// events along the segment and merges events closer than the tolerance into groups; each
// group becomes one vertex of the segment's polyline. The commit appends the new vertices,
// splits the crossed edges (the edge keeps its index for the part at its first vertex),
// merges pieces that coincide with existing edges, adds the other pieces as edges and splits
// the faces they cut. A piece's face is found exactly: the face corner at the piece's end
// whose angular sector contains the piece's direction (orientation signs again).
#include <orikin/arrangement.h>

#include <float.h>
#include <stdlib.h>

#include "pattern_internal.h"

ori_insert_def ori_default_insert_def(void)
{
    ori_insert_def def;
    def.overlap = ORI_OVERLAP_KEEP_BOUNDARY;
    def.name_faces = true;
    def.length_scale = ORI_INSERT_AUTO_SCALE;
    def.internal_value = ORI__DEF_COOKIE;
    return def;
}

// --- small geometry ---------------------------------------------------------------------

static double dist2(ori_v2 a, ori_v2 b)
{
    double dx = a.x - b.x, dy = a.y - b.y;
    return dx * dx + dy * dy;
}

// Parameter of the projection of x on segment ab (unclamped); 0 for a zero-length segment.
static double project_param(ori_v2 a, ori_v2 b, ori_v2 x)
{
    ori_v2 d = ori_v2_sub(b, a);
    double l2 = ori_v2_dot(d, d);
    return l2 > 0.0 ? ori_v2_dot(ori_v2_sub(x, a), d) / l2 : 0.0;
}

static double clamp01(double t) { return t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t); }

static ori_v2 lerp(ori_v2 a, ori_v2 b, double t) { return ori_v2_make(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)); }

// Squared distance from x to the closed segment ab.
static double seg_dist2(ori_v2 a, ori_v2 b, ori_v2 x) { return dist2(x, lerp(a, b, clamp01(project_param(a, b, x)))); }

// --- uniform grid (bulk insertion) ------------------------------------------------------

typedef struct grid_node {
    int item, next;
} grid_node;

typedef struct grid {
    bool on;
    double x0, y0, cell;
    int nx, ny;
    int *edge_head, *vert_head; // per cell: first node or -1
    grid_node *nodes;
    int node_count, node_cap;
} grid;

typedef struct face_list {
    int *v;
    int n, cap;
} face_list;

typedef struct event {
    double s;    // position along the segment, 0 at a, 1 at b (ordering only)
    ori_v2 pos;  // where the event is
    int vertex;  // existing vertex or -1
    int edge;    // edge to split here or -1
    int endpoint; // 1 for the snapped end points of the segment
} event;

typedef struct group {
    ori_v2 pos;
    int vertex; // existing or (after commit) new vertex
    int first, count; // range in the sorted events
} group;

typedef struct split_rec {
    int edge;
    int group;
    double t; // parameter along the edge's original extent
} split_rec;

typedef struct edge_split {
    int p, q;         // original end points
    int first, count; // vertices in split_verts, ordered from p to q
} edge_split;

typedef struct int_list {
    int *v;
    int n, cap;
} int_list;

typedef struct arr {
    ori_pattern *p;
    const ori_insert_def *def;
    double tol, tol2;
    grid g;
    int *cells;
    int cell_count, cell_cap;
    int *cand_e, *cand_v;
    int cand_e_count, cand_e_cap, cand_v_count, cand_v_cap;
    int *estamp, *vstamp;
    int estamp_cap, vstamp_cap, stamp;
    int *mark; // vertex → event/group index during one insertion, else -1
    int mark_cap;
    event *ev;
    int ev_count, ev_cap;
    group *gr;
    int gr_count, gr_cap;
    split_rec *sr;
    int sr_count, sr_cap;
    edge_split *es;
    int es_count, es_cap;
    int *split_verts;
    int split_vert_count, split_vert_cap;
    int *overlap_cand;
    int overlap_count, overlap_cap;
    int *near_v;
    int near_count, near_cap;
    // faces (only when the pattern has faces)
    bool faces;
    face_list *fl;
    int fl_count, fl_cap;
    char (*names)[ORI_NAME_MAX];
    int names_cap;
    int_list *glist; // per group: faces containing the group's vertex
    int glist_cap;
    int *fmark;      // per vertex stamp for face bookkeeping
    int fmark_cap, fstamp;
    int *tmp;
    int tmp_cap;
    ori_insert_result res;
} arr;

static int grid_col(const grid *g, double x)
{
    double c = floor((x - g->x0) / g->cell);
    if (!(c >= 0.0)) return 0;
    if (c >= (double)g->nx) return g->nx - 1;
    return (int)c;
}

static int grid_row(const grid *g, double y)
{
    double r = floor((y - g->y0) / g->cell);
    if (!(r >= 0.0)) return 0;
    if (r >= (double)g->ny) return g->ny - 1;
    return (int)r;
}

// Cells that the segment ab, widened by pad (and by one row of cells against rounding),
// passes through.
static void grid_cells(arr *A, ori_v2 a, ori_v2 b, double pad)
{
    const grid *g = &A->g;
    A->cell_count = 0;
    if (a.x > b.x) {
        ori_v2 t = a;
        a = b;
        b = t;
    }
    int c0 = grid_col(g, a.x - pad), c1 = grid_col(g, b.x + pad);
    for (int cx = c0; cx <= c1; ++cx) {
        double xl = g->x0 + (double)cx * g->cell - pad, xr = g->x0 + (double)(cx + 1) * g->cell + pad;
        double lo = fmax(a.x, xl), hi = fmin(b.x, xr);
        double y0, y1;
        if (b.x > a.x && lo <= hi) {
            double t0 = clamp01((lo - a.x) / (b.x - a.x)), t1 = clamp01((hi - a.x) / (b.x - a.x));
            y0 = a.y + t0 * (b.y - a.y);
            y1 = a.y + t1 * (b.y - a.y);
        } else {
            y0 = a.y;
            y1 = b.y;
        }
        if (y0 > y1) {
            double t = y0;
            y0 = y1;
            y1 = t;
        }
        int r0 = grid_row(g, y0 - pad) - 1, r1 = grid_row(g, y1 + pad) + 1;
        if (r0 < 0) r0 = 0;
        if (r1 >= g->ny) r1 = g->ny - 1;
        for (int r = r0; r <= r1; ++r) ORI__PUSH(A->cells, A->cell_count, A->cell_cap, cx * g->ny + r);
    }
}

static void grid_push(grid *g, int *head, int cell, int item)
{
    grid_node n = {item, head[cell]};
    ORI__PUSH(g->nodes, g->node_count, g->node_cap, n);
    head[cell] = g->node_count - 1;
}

static void grid_add_edge(arr *A, int e)
{
    if (!A->g.on) return;
    const ori_edge *ed = &A->p->edges[e];
    grid_cells(A, ori__pattern_v2(A->p, ed->v[0]), ori__pattern_v2(A->p, ed->v[1]), 0.0);
    for (int i = 0; i < A->cell_count; ++i) grid_push(&A->g, A->g.edge_head, A->cells[i], e);
}

static void grid_add_vertex(arr *A, int v)
{
    if (!A->g.on) return;
    ori_v2 x = ori__pattern_v2(A->p, v);
    grid_push(&A->g, A->g.vert_head, grid_col(&A->g, x.x) * A->g.ny + grid_row(&A->g, x.y), v);
}

static void grid_init(arr *A, double x0, double y0, double x1, double y1, double cell, int budget)
{
    grid *g = &A->g;
    double w = fmax(x1 - x0, 0.0), h = fmax(y1 - y0, 0.0);
    if (!(cell > 0.0)) cell = fmax(w, h);
    if (!(cell > 0.0)) cell = 1.0;
    for (;;) {
        double nx = floor(w / cell) + 1.0, ny = floor(h / cell) + 1.0;
        if (nx * ny <= (double)budget) {
            g->nx = (int)nx;
            g->ny = (int)ny;
            break;
        }
        cell *= 1.5;
    }
    g->x0 = x0;
    g->y0 = y0;
    g->cell = cell;
    size_t cells = (size_t)g->nx * (size_t)g->ny;
    g->edge_head = ori__alloc(sizeof(int) * cells);
    g->vert_head = ori__alloc(sizeof(int) * cells);
    for (size_t i = 0; i < cells; ++i) g->edge_head[i] = g->vert_head[i] = -1;
    g->on = true;
    for (int v = 0; v < A->p->vertex_count; ++v) grid_add_vertex(A, v);
    for (int e = 0; e < A->p->edge_count; ++e) grid_add_edge(A, e);
}

// --- per-vertex / per-edge scratch ---------------------------------------------------------

static void ensure_vertex_arrays(arr *A)
{
    int n = A->p->vertex_count;
    if (A->mark_cap < n) {
        int old = A->mark_cap;
        ORI__RESERVE(A->mark, A->mark_cap, n);
        for (int i = old; i < A->mark_cap; ++i) A->mark[i] = -1;
    }
    if (A->vstamp_cap < n) {
        int old = A->vstamp_cap;
        ORI__RESERVE(A->vstamp, A->vstamp_cap, n);
        for (int i = old; i < A->vstamp_cap; ++i) A->vstamp[i] = 0;
    }
    if (A->fmark_cap < n) {
        int old = A->fmark_cap;
        ORI__RESERVE(A->fmark, A->fmark_cap, n);
        for (int i = old; i < A->fmark_cap; ++i) A->fmark[i] = 0;
    }
}

static void ensure_edge_arrays(arr *A)
{
    int m = A->p->edge_count;
    if (A->estamp_cap < m) {
        int old = A->estamp_cap;
        ORI__RESERVE(A->estamp, A->estamp_cap, m);
        for (int i = old; i < A->estamp_cap; ++i) A->estamp[i] = 0;
    }
}

// Candidate vertices and edges near the segment ab (within pad): every element in linear
// mode after a bounding-box test, the grid cells along the segment in bulk mode.
static void gather(arr *A, ori_v2 a, ori_v2 b, double pad)
{
    ori_pattern *p = A->p;
    ensure_vertex_arrays(A);
    ensure_edge_arrays(A);
    A->cand_e_count = A->cand_v_count = 0;
    double lx = fmin(a.x, b.x) - pad, hx = fmax(a.x, b.x) + pad;
    double ly = fmin(a.y, b.y) - pad, hy = fmax(a.y, b.y) + pad;
    if (!A->g.on) {
        for (int v = 0; v < p->vertex_count; ++v) {
            ori_v3 x = p->vertices[v];
            if (x.x >= lx && x.x <= hx && x.y >= ly && x.y <= hy) ORI__PUSH(A->cand_v, A->cand_v_count, A->cand_v_cap, v);
        }
        for (int e = 0; e < p->edge_count; ++e) {
            ori_v3 u = p->vertices[p->edges[e].v[0]], w = p->vertices[p->edges[e].v[1]];
            if (fmax(u.x, w.x) < lx || fmin(u.x, w.x) > hx || fmax(u.y, w.y) < ly || fmin(u.y, w.y) > hy) continue;
            ORI__PUSH(A->cand_e, A->cand_e_count, A->cand_e_cap, e);
        }
        return;
    }
    if (++A->stamp == INT32_MAX) {
        A->stamp = 1;
        memset(A->estamp, 0, sizeof(int) * (size_t)A->estamp_cap);
        memset(A->vstamp, 0, sizeof(int) * (size_t)A->vstamp_cap);
    }
    grid_cells(A, a, b, pad);
    for (int i = 0; i < A->cell_count; ++i) {
        int c = A->cells[i];
        for (int n = A->g.vert_head[c]; n >= 0; n = A->g.nodes[n].next) {
            int v = A->g.nodes[n].item;
            if (A->vstamp[v] == A->stamp) continue;
            A->vstamp[v] = A->stamp;
            ori_v3 x = p->vertices[v];
            if (x.x >= lx && x.x <= hx && x.y >= ly && x.y <= hy) ORI__PUSH(A->cand_v, A->cand_v_count, A->cand_v_cap, v);
        }
        for (int n = A->g.edge_head[c]; n >= 0; n = A->g.nodes[n].next) {
            int e = A->g.nodes[n].item;
            if (A->estamp[e] == A->stamp) continue;
            A->estamp[e] = A->stamp;
            ORI__PUSH(A->cand_e, A->cand_e_count, A->cand_e_cap, e);
        }
    }
}

// --- planning -------------------------------------------------------------------------------

// Snap an end point: to the nearest vertex within tol, else onto the nearest edge within tol
// (a T-junction, split there), else free. Fills the event; returns the snapped position.
static ori_v2 snap_endpoint(arr *A, ori_v2 x, double s, event *out)
{
    ori_pattern *p = A->p;
    gather(A, x, x, 2.0 * A->tol);
    out->s = s;
    out->endpoint = 1;
    out->vertex = -1;
    out->edge = -1;
    out->pos = x;
    double best = A->tol2;
    for (int i = 0; i < A->cand_v_count; ++i) {
        int v = A->cand_v[i];
        double d = dist2(ori__pattern_v2(p, v), x);
        if (d <= best) {
            best = d;
            out->vertex = v;
        }
    }
    if (out->vertex >= 0) {
        out->pos = ori__pattern_v2(p, out->vertex);
        return out->pos;
    }
    best = A->tol2;
    for (int i = 0; i < A->cand_e_count; ++i) {
        int e = A->cand_e[i];
        ori_v2 u = ori__pattern_v2(p, p->edges[e].v[0]), w = ori__pattern_v2(p, p->edges[e].v[1]);
        double t = project_param(u, w, x);
        if (!(t > 0.0 && t < 1.0)) continue;
        ori_v2 y = lerp(u, w, t);
        double d = dist2(x, y);
        if (d > best) continue;
        best = d;
        // A projection within tol of the edge's end is that end (never a duplicate vertex).
        if (dist2(y, u) <= A->tol2) {
            out->vertex = p->edges[e].v[0];
            out->edge = -1;
            out->pos = u;
        } else if (dist2(y, w) <= A->tol2) {
            out->vertex = p->edges[e].v[1];
            out->edge = -1;
            out->pos = w;
        } else {
            out->vertex = -1;
            out->edge = e;
            // On the edge's line exactly when x already is; else its projection.
            out->pos = ori_orient2d_sign(u, w, x) == 0 ? x : y;
        }
    }
    return out->pos;
}

static int compare_events(const void *pa, const void *pb)
{
    const event *a = pa, *b = pb;
    if (a->s != b->s) return a->s < b->s ? -1 : 1;
    if (a->endpoint != b->endpoint) return b->endpoint - a->endpoint;
    if ((a->vertex >= 0) != (b->vertex >= 0)) return a->vertex >= 0 ? -1 : 1;
    if (a->vertex != b->vertex) return a->vertex < b->vertex ? -1 : 1;
    return (a->edge > b->edge) - (a->edge < b->edge);
}

static int compare_splits(const void *pa, const void *pb)
{
    const split_rec *a = pa, *b = pb;
    if (a->edge != b->edge) return a->edge < b->edge ? -1 : 1;
    if (a->t != b->t) return a->t < b->t ? -1 : 1;
    return (a->group > b->group) - (a->group < b->group);
}

static void reset_marks(arr *A)
{
    for (int i = 0; i < A->ev_count; ++i)
        if (A->ev[i].vertex >= 0) A->mark[A->ev[i].vertex] = -1;
    for (int i = 0; i < A->gr_count; ++i)
        if (A->gr[i].vertex >= 0 && A->gr[i].vertex < A->mark_cap) A->mark[A->gr[i].vertex] = -1;
}

typedef enum plan_outcome { PLAN_OK, PLAN_DEGENERATE, PLAN_FLOATING } plan_outcome;

static bool floating_pieces(arr *A);

// Phase 1 (no mutation): PLAN_DEGENERATE when the snapped end points coincide, PLAN_FLOATING
// when a piece would float inside a face (see floating_pieces).
static plan_outcome plan(arr *A, ori_v2 a, ori_v2 b)
{
    ori_pattern *p = A->p;
    A->ev_count = A->gr_count = A->sr_count = A->overlap_count = A->near_count = 0;
    event ea, eb;
    ori_v2 sa = snap_endpoint(A, a, 0.0, &ea);
    ori_v2 sb = snap_endpoint(A, b, 1.0, &eb);
    if ((ea.vertex >= 0 && ea.vertex == eb.vertex) || dist2(sa, sb) <= A->tol2) return PLAN_DEGENERATE;
    ORI__PUSH(A->ev, A->ev_count, A->ev_cap, ea);
    ORI__PUSH(A->ev, A->ev_count, A->ev_cap, eb);
    if (ea.vertex >= 0) A->mark[ea.vertex] = 0;
    if (eb.vertex >= 0) A->mark[eb.vertex] = 1;

    gather(A, sa, sb, 2.0 * A->tol);
    // Vertices on the segment (within tol): the segment passes through them.
    for (int i = 0; i < A->cand_v_count; ++i) {
        int v = A->cand_v[i];
        ori_v2 x = ori__pattern_v2(p, v);
        double d = seg_dist2(sa, sb, x);
        if (d <= 4.0 * A->tol2) ORI__PUSH(A->near_v, A->near_count, A->near_cap, v);
        if (A->mark[v] >= 0 || d > A->tol2) continue;
        event e = {clamp01(project_param(sa, sb, x)), x, v, -1, 0};
        A->mark[v] = A->ev_count;
        ORI__PUSH(A->ev, A->ev_count, A->ev_cap, e);
    }
    // Edges: overlaps (both ends on the segment) and proper crossings.
    for (int i = 0; i < A->cand_e_count; ++i) {
        int e = A->cand_e[i];
        int vp = p->edges[e].v[0], vq = p->edges[e].v[1];
        bool on_p = A->mark[vp] >= 0, on_q = A->mark[vq] >= 0;
        if (on_p && on_q) {
            ORI__PUSH(A->overlap_cand, A->overlap_count, A->overlap_cap, e);
            continue;
        }
        if (on_p || on_q || e == ea.edge || e == eb.edge) continue;
        ori_v2 P = ori__pattern_v2(p, vp), Q = ori__pattern_v2(p, vq);
        int sp = ori_orient2d_sign(sa, sb, P), sq = ori_orient2d_sign(sa, sb, Q);
        if (sp * sq >= 0) continue;
        int oa = ori_orient2d_sign(P, Q, sa), ob = ori_orient2d_sign(P, Q, sb);
        if (oa * ob >= 0) continue;
        // Proper crossing: the point from the orientation values (accurate, never 0/0 since
        // the signs differ), clamped to both segments' boxes.
        double op = ori_orient2d(sa, sb, P), oq = ori_orient2d(sa, sb, Q);
        double te = op / (op - oq);
        ori_v2 X = lerp(P, Q, te);
        double lo_x = fmax(fmin(P.x, Q.x), fmin(sa.x, sb.x)), hi_x = fmin(fmax(P.x, Q.x), fmax(sa.x, sb.x));
        double lo_y = fmax(fmin(P.y, Q.y), fmin(sa.y, sb.y)), hi_y = fmin(fmax(P.y, Q.y), fmax(sa.y, sb.y));
        if (lo_x <= hi_x) X.x = fmin(fmax(X.x, lo_x), hi_x);
        if (lo_y <= hi_y) X.y = fmin(fmax(X.y, lo_y), hi_y);
        double va = ori_orient2d(P, Q, sa), vb = ori_orient2d(P, Q, sb);
        event ev = {clamp01(va / (va - vb)), X, -1, e, 0};
        ORI__PUSH(A->ev, A->ev_count, A->ev_cap, ev);
    }
    if (A->ev_count > 1) qsort(A->ev, (size_t)A->ev_count, sizeof *A->ev, compare_events);
    for (int i = 0; i < A->ev_count; ++i)
        if (A->ev[i].vertex >= 0) A->mark[A->ev[i].vertex] = i;

    // Groups: consecutive events closer than tol are one point (an existing vertex wins,
    // then an end point); two distinct existing vertices never merge.
    for (int i = 0; i < A->ev_count; ++i) {
        const event *e = &A->ev[i];
        group *g = A->gr_count > 0 ? &A->gr[A->gr_count - 1] : NULL;
        bool join = false;
        if (g) {
            const event *last = &A->ev[i - 1];
            join = dist2(e->pos, g->pos) <= A->tol2 || dist2(e->pos, last->pos) <= A->tol2;
            if (join && e->vertex >= 0 && g->vertex >= 0 && e->vertex != g->vertex) join = false;
        }
        if (!join) {
            group ng = {e->pos, e->vertex, i, 1};
            ORI__PUSH(A->gr, A->gr_count, A->gr_cap, ng);
            continue;
        }
        g->count++;
        if (g->vertex < 0 && e->vertex >= 0) {
            g->vertex = e->vertex;
            g->pos = e->pos;
        } else if (g->vertex < 0 && e->endpoint && !A->ev[g->first].endpoint) {
            g->pos = e->pos;
        }
    }
    // A new point closer than tol to an existing vertex near the segment becomes it.
    for (int k = 0; k < A->gr_count; ++k) {
        group *g = &A->gr[k];
        if (g->vertex >= 0) continue;
        double best = A->tol2;
        for (int i = 0; i < A->near_count; ++i) {
            double d = dist2(ori__pattern_v2(p, A->near_v[i]), g->pos);
            if (d <= best) {
                best = d;
                g->vertex = A->near_v[i];
            }
        }
        for (int j = g->first; j < g->first + g->count && g->vertex < 0; ++j) {
            int e = A->ev[j].edge;
            if (e < 0) continue;
            for (int k2 = 0; k2 < 2; ++k2)
                if (dist2(ori__pattern_v2(p, p->edges[e].v[k2]), g->pos) <= A->tol2) g->vertex = p->edges[e].v[k2];
        }
        if (g->vertex >= 0) g->pos = ori__pattern_v2(p, g->vertex);
    }
    // Edge splits, one per (edge, group), skipped where the group is the edge's own end.
    for (int k = 0; k < A->gr_count; ++k) {
        const group *g = &A->gr[k];
        for (int j = g->first; j < g->first + g->count; ++j) {
            int e = A->ev[j].edge;
            if (e < 0 || p->edges[e].v[0] == g->vertex || p->edges[e].v[1] == g->vertex) continue;
            bool dup = false;
            for (int i = 0; i < A->sr_count && !dup; ++i) dup = A->sr[i].edge == e && A->sr[i].group == k;
            if (dup) continue;
            ori_v2 P = ori__pattern_v2(p, p->edges[e].v[0]), Q = ori__pattern_v2(p, p->edges[e].v[1]);
            split_rec r = {e, k, project_param(P, Q, g->pos)};
            ORI__PUSH(A->sr, A->sr_count, A->sr_cap, r);
        }
    }
    return A->faces && floating_pieces(A) ? PLAN_FLOATING : PLAN_OK;
}

// --- faces ----------------------------------------------------------------------------------

static void list_push(int_list *l, int x) { ORI__PUSH(l->v, l->n, l->cap, x); }

static void list_remove(int_list *l, int x)
{
    for (int i = 0; i < l->n; ++i)
        if (l->v[i] == x) {
            l->v[i] = l->v[--l->n];
            return;
        }
}

static bool list_has(const int_list *l, int x)
{
    for (int i = 0; i < l->n; ++i)
        if (l->v[i] == x) return true;
    return false;
}

static void faces_load(arr *A)
{
    ori_pattern *p = A->p;
    A->faces = p->face_count > 0;
    if (!A->faces) return;
    ORI__RESERVE(A->fl, A->fl_cap, p->face_count);
    ORI__RESERVE(A->names, A->names_cap, p->face_count);
    A->fl_count = p->face_count;
    for (int f = 0; f < p->face_count; ++f) {
        face_list *F = &A->fl[f];
        F->v = NULL;
        F->n = F->cap = 0;
        int b = p->face_offsets[f], n = p->face_offsets[f + 1] - b;
        ORI__RESERVE(F->v, F->cap, n);
        memcpy(F->v, p->face_vertices + b, sizeof(int) * (size_t)n);
        F->n = n;
        ori__strlcpy(A->names[f], p->face_names ? p->face_names[f] : "", ORI_NAME_MAX);
    }
}

static void faces_store(arr *A)
{
    ori_pattern *p = A->p;
    if (!A->faces) return;
    int total = 0;
    for (int f = 0; f < A->fl_count; ++f) total += A->fl[f].n;
    bool any_name = false;
    for (int f = 0; f < A->fl_count && !any_name; ++f) any_name = A->names[f][0] != '\0';
    ori__pattern_reserve_faces(p, A->fl_count, total);
    int k = 0;
    p->face_offsets[0] = 0;
    for (int f = 0; f < A->fl_count; ++f) {
        memcpy(p->face_vertices + k, A->fl[f].v, sizeof(int) * (size_t)A->fl[f].n);
        k += A->fl[f].n;
        p->face_offsets[f + 1] = k;
    }
    p->face_count = A->fl_count;
    p->face_vertex_count = total;
    if (any_name || p->face_names)
        for (int f = 0; f < A->fl_count; ++f) ori_pattern_set_face_name(p, f, A->names[f][0] ? A->names[f] : NULL);
}

static void faces_free(arr *A)
{
    for (int f = 0; f < A->fl_count; ++f) ori__free(A->fl[f].v);
    ori__free(A->fl);
    ori__free(A->names);
    A->fl = NULL;
    A->names = NULL;
    A->fl_count = A->fl_cap = A->names_cap = 0;
}

static double face_area2(const arr *A, int f)
{
    const face_list *F = &A->fl[f];
    double s = 0.0;
    for (int i = 0; i < F->n; ++i) {
        ori_v2 u = ori__pattern_v2(A->p, F->v[i]), w = ori__pattern_v2(A->p, F->v[(i + 1) % F->n]);
        s += u.x * w.y - u.y * w.x;
    }
    return s;
}

// Whether direction u→x points into the face at its corner i (vertex u), decided exactly.
static bool corner_contains(const arr *A, int f, int i, bool ccw, ori_v2 x)
{
    const face_list *F = &A->fl[f];
    int n = F->n;
    int in = F->v[(i + 1) % n], ip = F->v[(i + n - 1) % n];
    if (!ccw) {
        int t = in;
        in = ip;
        ip = t;
    }
    ori_v2 u = ori__pattern_v2(A->p, F->v[i]), nx = ori__pattern_v2(A->p, in), pv = ori__pattern_v2(A->p, ip);
    int a = ori_orient2d_sign(u, nx, x);  // > 0: x counter-clockwise of next
    int b = ori_orient2d_sign(u, x, pv);  // > 0: prev counter-clockwise of x
    int o = ori_orient2d_sign(u, nx, pv);
    double dn = ori_v2_dot(ori_v2_sub(nx, u), ori_v2_sub(pv, u));
    if (o > 0) return a > 0 && b > 0;
    if (o < 0) return a > 0 || b > 0;
    if (dn < 0.0) return a > 0; // straight corner (180°)
    // zero-angle corner: a slit tip or a spike; everything but the slit's own direction
    return !(a == 0 && ori_v2_dot(ori_v2_sub(x, u), ori_v2_sub(nx, u)) > 0.0);
}

// Names of the two parts of face f (now f and g): N → N1 (left, f) and N2 (right, g), both
// recorded under N in the face tree. Unnamed faces (or naming off) leave g unnamed.
static void name_children(arr *A, int f, int g)
{
    ori_pattern *p = A->p;
    const char *parent = A->names[f];
    size_t len = strlen(parent);
    A->names[g][0] = '\0';
    if (!A->def->name_faces || len == 0 || len + 2 > ORI_NAME_MAX) return;
    char n1[ORI_NAME_MAX], n2[ORI_NAME_MAX];
    memcpy(n1, parent, len);
    memcpy(n2, parent, len);
    n1[len] = '1';
    n2[len] = '2';
    n1[len + 1] = n2[len + 1] = '\0';
    int node = ori_pattern_find_tree_node(p, parent);
    if (node == ORI_NULL_INDEX) node = ori_pattern_add_tree_node(p, parent, ORI_NULL_INDEX);
    ori_pattern_add_tree_node(p, n1, node);
    ori_pattern_add_tree_node(p, n2, node);
    ori__strlcpy(A->names[f], n1, ORI_NAME_MAX);
    ori__strlcpy(A->names[g], n2, ORI_NAME_MAX);
}

static int new_face(arr *A)
{
    ORI__RESERVE(A->fl, A->fl_cap, A->fl_count + 1);
    ORI__RESERVE(A->names, A->names_cap, A->fl_count + 1);
    face_list *F = &A->fl[A->fl_count];
    F->v = NULL;
    F->n = F->cap = 0;
    A->names[A->fl_count][0] = '\0';
    return A->fl_count++;
}

// Split face f along the chord from its corner i (u) to corner j (w), u→w along the segment.
// The part left of u→w keeps index f, the right part is appended.
static void split_face(arr *A, int f, int i, int j, bool ccw)
{
    int g = new_face(A);
    face_list *F = &A->fl[f], *G = &A->fl[g];
    int n = F->n;
    ORI__RESERVE(A->tmp, A->tmp_cap, n + 1);
    // R = c[i..j] (right of u→w for a counter-clockwise face), L = c[j..i].
    int ln = 0;
    for (int k = i;; k = (k + 1) % n) {
        ORI__PUSH(G->v, G->n, G->cap, F->v[k]);
        if (k == j) break;
    }
    for (int k = j;; k = (k + 1) % n) {
        A->tmp[ln++] = F->v[k];
        if (k == i) break;
    }
    memcpy(F->v, A->tmp, sizeof(int) * (size_t)ln);
    F->n = ln;
    if (!ccw) {
        face_list t = *F;
        *F = *G;
        *G = t;
    }
    name_children(A, f, g);
    A->res.faces_added++;
    A->res.faces_split++;
    // Face lists of the segment's vertices.
    if (++A->fstamp == INT32_MAX) {
        A->fstamp = 1;
        memset(A->fmark, 0, sizeof(int) * (size_t)A->fmark_cap);
    }
    for (int k = 0; k < F->n; ++k) A->fmark[F->v[k]] = A->fstamp;
    for (int k = 0; k < G->n; ++k) {
        int x = G->v[k], gi = A->mark[x];
        if (gi < 0) continue;
        if (!list_has(&A->glist[gi], g)) list_push(&A->glist[gi], g);
        if (A->fmark[x] != A->fstamp) list_remove(&A->glist[gi], f);
    }
}

// A slit: the free vertex u hangs from corner j (vertex w) of face f.
static void insert_spike(arr *A, int f, int j, int u)
{
    face_list *F = &A->fl[f];
    int w = F->v[j];
    ORI__RESERVE(F->v, F->cap, F->n + 2);
    memmove(F->v + j + 3, F->v + j + 1, sizeof(int) * (size_t)(F->n - j - 1));
    F->v[j + 1] = u;
    F->v[j + 2] = w;
    F->n += 2;
    int gi = A->mark[u];
    if (gi >= 0 && !list_has(&A->glist[gi], f)) list_push(&A->glist[gi], f);
}

// Split the face that the new edge u→w (groups gu, gw) runs through.
static void cut_faces(arr *A, int gu, int gw)
{
    int u = A->gr[gu].vertex, w = A->gr[gw].vertex;
    ori_v2 pu = ori__pattern_v2(A->p, u), pw = ori__pattern_v2(A->p, w);
    int_list *lu = &A->glist[gu], *lw = &A->glist[gw];
    for (int k = 0; k < lu->n; ++k) {
        int f = lu->v[k];
        bool ccw = face_area2(A, f) >= 0.0;
        face_list *F = &A->fl[f];
        for (int i = 0; i < F->n; ++i) {
            if (F->v[i] != u || !corner_contains(A, f, i, ccw, pw)) continue;
            if (lw->n == 0) {
                insert_spike(A, f, i, w);
                return;
            }
            for (int j = 0; j < F->n; ++j)
                if (F->v[j] == w && corner_contains(A, f, j, ccw, pu)) {
                    split_face(A, f, i, j, ccw);
                    return;
                }
        }
    }
    if (lu->n == 0)
        for (int k = 0; k < lw->n; ++k) {
            int f = lw->v[k];
            bool ccw = face_area2(A, f) >= 0.0;
            face_list *F = &A->fl[f];
            for (int j = 0; j < F->n; ++j)
                if (F->v[j] == w && corner_contains(A, f, j, ccw, pu)) {
                    insert_spike(A, f, j, u);
                    return;
                }
        }
}

// A face is one cycle, so it cannot hold a hole: every piece must touch the faces' boundary
// (a vertex of a face cycle, or a point on a side), except that a free end of the segment may
// hang from such a point as a slit. True when some piece would float (both ends detached, or
// one end on an existing vertex that belongs to no face).
static bool floating_pieces(arr *A)
{
    ensure_vertex_arrays(A);
    if (++A->fstamp == INT32_MAX) {
        A->fstamp = 1;
        memset(A->fmark, 0, sizeof(int) * (size_t)A->fmark_cap);
    }
    for (int f = 0; f < A->fl_count; ++f)
        for (int i = 0; i < A->fl[f].n; ++i) A->fmark[A->fl[f].v[i]] = A->fstamp;
    const ori_pattern *p = A->p;
    // per group: 1 attached, 0 a free new end point, −1 detached existing vertex
    int prev = 0;
    for (int k = 0; k < A->gr_count; ++k) {
        const group *g = &A->gr[k];
        int state = g->vertex >= 0 ? (A->fmark[g->vertex] == A->fstamp ? 1 : -1) : 0;
        for (int j = g->first; j < g->first + g->count && state != 1; ++j) {
            int e = A->ev[j].edge;
            if (e >= 0 && A->fmark[p->edges[e].v[0]] == A->fstamp && A->fmark[p->edges[e].v[1]] == A->fstamp) state = 1;
        }
        if (k > 0 && (state != 1 && prev != 1)) return true;
        if (state == -1) return true;
        prev = state;
    }
    return false;
}

// --- commit ---------------------------------------------------------------------------------

static uint64_t pair_key(int a, int b)
{
    uint32_t lo = (uint32_t)(a < b ? a : b), hi = (uint32_t)(a < b ? b : a);
    return ((uint64_t)hi << 32) | lo;
}

static int find_split(const arr *A, int a, int b)
{
    uint64_t k = pair_key(a, b);
    for (int i = 0; i < A->es_count; ++i)
        if (pair_key(A->es[i].p, A->es[i].q) == k) return i;
    return -1;
}

// Insert the split vertices into every face side p–q.
static void faces_apply_splits(arr *A)
{
    if (!A->faces || A->es_count == 0) return;
    for (int f = 0; f < A->fl_count; ++f) {
        face_list *F = &A->fl[f];
        int extra = 0;
        for (int i = 0; i < F->n; ++i) {
            int s = find_split(A, F->v[i], F->v[(i + 1) % F->n]);
            if (s >= 0) extra += A->es[s].count;
        }
        if (extra == 0) continue;
        ORI__RESERVE(A->tmp, A->tmp_cap, F->n + extra);
        int m = 0;
        for (int i = 0; i < F->n; ++i) {
            int a = F->v[i], b = F->v[(i + 1) % F->n];
            A->tmp[m++] = a;
            int s = find_split(A, a, b);
            if (s < 0) continue;
            const edge_split *r = &A->es[s];
            if (r->p == a)
                for (int k = 0; k < r->count; ++k) A->tmp[m++] = A->split_verts[r->first + k];
            else
                for (int k = r->count - 1; k >= 0; --k) A->tmp[m++] = A->split_verts[r->first + k];
        }
        ORI__RESERVE(F->v, F->cap, m);
        memcpy(F->v, A->tmp, sizeof(int) * (size_t)m);
        F->n = m;
    }
}

static void apply_overlap(arr *A, int e, ori_assignment asg, double angle)
{
    ori_edge *ed = &A->p->edges[e];
    bool take;
    switch (A->def->overlap) {
    case ORI_OVERLAP_KEEP_EXISTING: take = false; break;
    case ORI_OVERLAP_REPLACE: take = true; break;
    default: take = ed->assignment != ORI_ASSIGN_BOUNDARY && ed->assignment != ORI_ASSIGN_CUT; break;
    }
    if (take) {
        ed->assignment = asg;
        ed->fold_angle_rad = angle;
    }
    A->res.edges_overlapped++;
    A->res.segment_edges++;
}

static void commit(arr *A, ori_assignment asg, double angle)
{
    ori_pattern *p = A->p;
    ori__pattern_invalidate(p);
    // New vertices.
    for (int k = 0; k < A->gr_count; ++k) {
        group *g = &A->gr[k];
        if (g->vertex >= 0) continue;
        ORI__PUSH(p->vertices, p->vertex_count, p->vertex_cap, ori_v3_make(g->pos.x, g->pos.y, 0.0));
        g->vertex = p->vertex_count - 1;
        A->res.vertices_added++;
        grid_add_vertex(A, g->vertex);
    }
    ensure_vertex_arrays(A);
    for (int k = 0; k < A->gr_count; ++k) A->mark[A->gr[k].vertex] = k;

    // Edge splits, each edge's split points ordered from its first vertex.
    if (A->sr_count > 1) qsort(A->sr, (size_t)A->sr_count, sizeof *A->sr, compare_splits);
    A->es_count = A->split_vert_count = 0;
    for (int i = 0; i < A->sr_count;) {
        int e = A->sr[i].edge, j = i;
        edge_split r = {p->edges[e].v[0], p->edges[e].v[1], A->split_vert_count, 0};
        int prev = p->edges[e].v[0];
        for (; j < A->sr_count && A->sr[j].edge == e; ++j) {
            int v = A->gr[A->sr[j].group].vertex;
            if (v == prev || v == r.q) continue;
            ORI__PUSH(A->split_verts, A->split_vert_count, A->split_vert_cap, v);
            r.count++;
            prev = v;
        }
        i = j;
        if (r.count == 0) continue;
        ORI__PUSH(A->es, A->es_count, A->es_cap, r);
        ori_edge orig = p->edges[e];
        int last = A->split_verts[r.first];
        p->edges[e].v[1] = last;
        for (int k = 1; k <= r.count; ++k) {
            int nv = k < r.count ? A->split_verts[r.first + k] : r.q;
            ori_edge ne = {{last, nv}, orig.assignment, orig.fold_angle_rad};
            ORI__PUSH(p->edges, p->edge_count, p->edge_cap, ne);
            A->res.edges_added++;
            grid_add_edge(A, p->edge_count - 1);
            if (A->mark[last] >= 0 && A->mark[nv] >= 0)
                ORI__PUSH(A->overlap_cand, A->overlap_count, A->overlap_cap, p->edge_count - 1);
            last = nv;
        }
        if (A->mark[p->edges[e].v[0]] >= 0 && A->mark[p->edges[e].v[1]] >= 0)
            ORI__PUSH(A->overlap_cand, A->overlap_count, A->overlap_cap, e);
        A->res.edges_split++;
    }
    faces_apply_splits(A);

    // Face lists of the segment's vertices.
    if (A->faces) {
        if (A->glist_cap < A->gr_count) {
            int old = A->glist_cap;
            ORI__RESERVE(A->glist, A->glist_cap, A->gr_count);
            memset(A->glist + old, 0, sizeof(int_list) * (size_t)(A->glist_cap - old));
        }
        for (int k = 0; k < A->gr_count; ++k) A->glist[k].n = 0;
        for (int f = 0; f < A->fl_count; ++f) {
            const face_list *F = &A->fl[f];
            for (int i = 0; i < F->n; ++i) {
                int gi = A->mark[F->v[i]];
                if (gi >= 0 && !list_has(&A->glist[gi], f)) list_push(&A->glist[gi], f);
            }
        }
    }

    // Pieces.
    for (int k = 0; k + 1 < A->gr_count; ++k) {
        int u = A->gr[k].vertex, w = A->gr[k + 1].vertex;
        if (u == w) continue;
        int over = -1;
        uint64_t key = pair_key(u, w);
        for (int i = 0; i < A->overlap_count && over < 0; ++i) {
            const ori_edge *ed = &p->edges[A->overlap_cand[i]];
            if (pair_key(ed->v[0], ed->v[1]) == key) over = A->overlap_cand[i];
        }
        if (over >= 0) {
            apply_overlap(A, over, asg, angle);
            continue;
        }
        ori_edge ne = {{u, w}, asg, angle};
        ORI__PUSH(p->edges, p->edge_count, p->edge_cap, ne);
        A->res.edges_added++;
        A->res.segment_edges++;
        grid_add_edge(A, p->edge_count - 1);
        ORI__PUSH(A->overlap_cand, A->overlap_count, A->overlap_cap, p->edge_count - 1);
        if (A->faces) cut_faces(A, k, k + 1);
    }
}

static void arr_free(arr *A)
{
    ori__free(A->g.edge_head);
    ori__free(A->g.vert_head);
    ori__free(A->g.nodes);
    ori__free(A->cells);
    ori__free(A->cand_e);
    ori__free(A->cand_v);
    ori__free(A->estamp);
    ori__free(A->vstamp);
    ori__free(A->mark);
    ori__free(A->ev);
    ori__free(A->gr);
    ori__free(A->sr);
    ori__free(A->es);
    ori__free(A->split_verts);
    ori__free(A->overlap_cand);
    ori__free(A->near_v);
    for (int i = 0; i < A->glist_cap; ++i) ori__free(A->glist[i].v);
    ori__free(A->glist);
    ori__free(A->fmark);
    ori__free(A->tmp);
    faces_free(A);
}

// Insert one segment (already validated finite).
static plan_outcome insert_one(arr *A, ori_v2 a, ori_v2 b, ori_assignment asg, double angle)
{
    ensure_vertex_arrays(A);
    plan_outcome r = plan(A, a, b);
    if (r == PLAN_OK) commit(A, asg, angle);
    reset_marks(A);
    return r;
}

static void bbox_with(const ori_pattern *p, double *lo_x, double *lo_y, double *hi_x, double *hi_y)
{
    for (int v = 0; v < p->vertex_count; ++v) {
        *lo_x = fmin(*lo_x, p->vertices[v].x);
        *lo_y = fmin(*lo_y, p->vertices[v].y);
        *hi_x = fmax(*hi_x, p->vertices[v].x);
        *hi_y = fmax(*hi_y, p->vertices[v].y);
    }
}

static bool finite_v2(ori_v2 a) { return isfinite(a.x) && isfinite(a.y); }

static ori_status check_common(const ori_pattern *p, const ori_insert_def *def, ori_error *error)
{
    ORI_ASSERT(def->internal_value == ORI__DEF_COOKIE);
    ORI_ASSERT(def->length_scale == ORI_INSERT_AUTO_SCALE || def->length_scale > 0.0);
    ORI_ASSERT((int)def->overlap >= 0 && def->overlap <= ORI_OVERLAP_REPLACE);
    if (p->folded_form)
        return ori__fail(error, ORI_ERR_UNSUPPORTED, "segments can only be inserted into a flat crease pattern");
    for (int v = 0; v < p->vertex_count; ++v)
        if (!isfinite(p->vertices[v].x) || !isfinite(p->vertices[v].y))
            return ori__fail_at(error, ORI_ERR_RANGE, "vertices_coords", v, "coordinate is not finite");
    for (int e = 0; e < p->edge_count; ++e)
        for (int k = 0; k < 2; ++k)
            if (p->edges[e].v[k] < 0 || p->edges[e].v[k] >= p->vertex_count)
                return ori__fail_at(error, ORI_ERR_RANGE, "edges_vertices", e, "vertex index out of range");
    for (int f = 0; f < p->face_count; ++f)
        for (int k = p->face_offsets[f]; k < p->face_offsets[f + 1]; ++k)
            if (p->face_vertices[k] < 0 || p->face_vertices[k] >= p->vertex_count)
                return ori__fail_at(error, ORI_ERR_RANGE, "faces_vertices", f, "vertex index out of range");
    return ORI_OK;
}

ori_status ori_pattern_insert_segment(ori_pattern *p, ori_v2 a, ori_v2 b, ori_assignment asg, double angle,
                                      const ori_insert_def *def, ori_insert_result *out, ori_error *error)
{
    ORI_ASSERT(p && (int)asg >= 0 && asg < ORI_ASSIGN_COUNT);
    ori_insert_def defaults = ori_default_insert_def();
    if (!def) def = &defaults;
    ori_error_clear(error);
    if (out) memset(out, 0, sizeof *out);
    ori_status st = check_common(p, def, error);
    if (st != ORI_OK) return st;
    if (!finite_v2(a) || !finite_v2(b) || !isfinite(angle))
        return ori__fail(error, ORI_ERR_RANGE, "segment coordinates and fold angle must be finite");
    double scale = def->length_scale;
    if (scale == ORI_INSERT_AUTO_SCALE) {
        double lx = fmin(a.x, b.x), ly = fmin(a.y, b.y), hx = fmax(a.x, b.x), hy = fmax(a.y, b.y);
        bbox_with(p, &lx, &ly, &hx, &hy);
        scale = hypot(hx - lx, hy - ly);
        if (!(scale > 0.0) || !isfinite(scale)) scale = 1.0;
    }
    arr A;
    memset(&A, 0, sizeof A);
    A.p = p;
    A.def = def;
    A.tol = ORI_TOL_LENGTH_REL * scale;
    A.tol2 = A.tol * A.tol;
    faces_load(&A);
    plan_outcome r = insert_one(&A, a, b, asg, angle);
    if (r == PLAN_OK) faces_store(&A);
    if (out) *out = A.res;
    arr_free(&A);
    if (r == PLAN_DEGENERATE)
        return ori__fail(error, ORI_ERR_DEGENERATE,
                         "segment (%g, %g)-(%g, %g) is shorter than the length tolerance after snapping",
                         a.x, a.y, b.x, b.y);
    if (r == PLAN_FLOATING)
        return ori__fail(error, ORI_ERR_UNSUPPORTED,
                         "segment (%g, %g)-(%g, %g) would float inside a face without touching its boundary "
                         "(a face cannot have a hole)", a.x, a.y, b.x, b.y);
    return ORI_OK;
}

ori_status ori_pattern_insert_segments(ori_pattern *p, const ori_segment *segs, int count, const ori_insert_def *def,
                                       ori_insert_result *out, ori_error *error)
{
    ORI_ASSERT(p && (segs || count == 0) && count >= 0);
    ori_insert_def defaults = ori_default_insert_def();
    if (!def) def = &defaults;
    ori_error_clear(error);
    if (out) memset(out, 0, sizeof *out);
    ori_status st = check_common(p, def, error);
    if (st != ORI_OK) return st;
    double lx = DBL_MAX, ly = DBL_MAX, hx = -DBL_MAX, hy = -DBL_MAX, total_len = 0.0;
    for (int i = 0; i < count; ++i) {
        const ori_segment *s = &segs[i];
        ORI_ASSERT((int)s->assignment >= 0 && s->assignment < ORI_ASSIGN_COUNT);
        if (!finite_v2(s->a) || !finite_v2(s->b) || !isfinite(s->fold_angle_rad))
            return ori__fail_at(error, ORI_ERR_RANGE, "segments", i, "coordinate or fold angle is not finite");
        lx = fmin(lx, fmin(s->a.x, s->b.x));
        ly = fmin(ly, fmin(s->a.y, s->b.y));
        hx = fmax(hx, fmax(s->a.x, s->b.x));
        hy = fmax(hy, fmax(s->a.y, s->b.y));
        total_len += ori_v2_norm(ori_v2_sub(s->b, s->a));
    }
    if (count == 0) return ORI_OK;
    bbox_with(p, &lx, &ly, &hx, &hy);
    double diag = hypot(hx - lx, hy - ly);
    if (!(diag > 0.0) || !isfinite(diag)) diag = 1.0;
    double scale = def->length_scale == ORI_INSERT_AUTO_SCALE ? diag : def->length_scale;
    arr A;
    memset(&A, 0, sizeof A);
    A.p = p;
    A.def = def;
    A.tol = ORI_TOL_LENGTH_REL * scale;
    A.tol2 = A.tol * A.tol;
    // About one cell per average segment length, at most ~4 cells per element.
    double cell = fmax(total_len / (double)count, diag / 4096.0);
    int64_t budget = 4 * ((int64_t)count + p->edge_count) + 16;
    if (budget > 1 << 24) budget = 1 << 24;
    double pad = 4.0 * A.tol;
    grid_init(&A, lx - pad, ly - pad, hx + pad, hy + pad, cell, (int)budget);
    faces_load(&A);
    int skipped = 0;
    for (int i = 0; i < count; ++i)
        if (insert_one(&A, segs[i].a, segs[i].b, segs[i].assignment, segs[i].fold_angle_rad) != PLAN_OK) skipped++;
    faces_store(&A);
    A.res.segments_skipped = skipped;
    if (out) *out = A.res;
    arr_free(&A);
    return ORI_OK;
}

ori_status ori_pattern_from_segments(const ori_segment *segs, int count, const ori_insert_def *def, ori_pattern **out,
                                     ori_insert_result *result, ori_error *error)
{
    ORI_ASSERT(out);
    *out = NULL;
    ori_pattern_def pdef = ori_default_pattern_def();
    pdef.vertex_capacity = count;
    pdef.edge_capacity = count;
    ori_pattern *p = ori_pattern_create(&pdef);
    ori_status st = ori_pattern_insert_segments(p, segs, count, def, result, error);
    if (st == ORI_OK) {
        ori_build_def bdef = ori_default_build_def();
        st = ori_pattern_build(p, &bdef, error);
    }
    if (st != ORI_OK) {
        ori_pattern_destroy(p);
        return st;
    }
    *out = p;
    return ORI_OK;
}

int ori_pattern_find_edge_at(const ori_pattern *p, ori_v2 x)
{
    ORI_ASSERT(p);
    double tol = ORI_TOL_ON_LINE_REL * ori_pattern_diagonal(p);
    double best = tol * tol;
    int found = ORI_NULL_INDEX;
    for (int e = 0; e < p->edge_count; ++e) {
        double d = seg_dist2(ori__pattern_v2(p, p->edges[e].v[0]), ori__pattern_v2(p, p->edges[e].v[1]), x);
        if (d <= best) {
            best = d;
            found = e;
        }
    }
    return found;
}

int ori_pattern_edges_on_segment(const ori_pattern *p, ori_v2 a, ori_v2 b, int *out, int cap)
{
    ORI_ASSERT(p && (out || cap == 0));
    double tol = ORI_TOL_ON_LINE_REL * ori_pattern_diagonal(p);
    int n = 0;
    for (int e = 0; e < p->edge_count; ++e) {
        ori_v2 u = ori__pattern_v2(p, p->edges[e].v[0]), w = ori__pattern_v2(p, p->edges[e].v[1]);
        if (seg_dist2(a, b, u) <= tol * tol && seg_dist2(a, b, w) <= tol * tol) {
            if (n < cap) out[n] = e;
            n++;
        }
    }
    return n;
}
