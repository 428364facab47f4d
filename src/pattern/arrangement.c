// Planar arrangement: inserting straight segments into a flat crease pattern.
//
// One insertion runs in two phases: the plan (no mutation) decides everything, the commit
// carries it out. The plan snaps the end points (to a vertex, else onto an edge, else free) and
// then refines the segment's polyline in rounds until it is consistent with the snapping:
// - events along the segment (end points, vertices, points where edges pass) are sorted and
//   merged into groups closer than the tolerance, each group one vertex of the polyline (an
//   existing vertex wins);
// - a vertex within the tolerance of a piece of the polyline joins it; an edge passing within
//   the tolerance of a group is split there; an edge that a piece crosses (snapping moved the
//   pieces off the straight segment) is split at the crossing; and, in a pattern without faces,
//   a split edge whose part turned near another vertex is split there too.
// Then every edge of the result is planned with its final vertex indices: a piece joining two
// vertices that an edge already joins overlaps that edge, a part of a split edge doing so merges
// into it (one edge remains); there are never two edges on the same two vertices. The planned
// edges are checked exactly against their neighbours (no crossing, touch or collinear overlap
// away from a shared vertex); what the snapping cannot make consistent is refused, leaving the
// pattern as it was. The commit appends the new vertices, splits the edges, adds the pieces and
// splits the faces they cut. A piece's face is found exactly: the face corner at the piece's
// end whose angular sector contains the piece's direction (orientation signs again).
#include <orikin/arrangement.h>

#include <float.h>
#include <stdlib.h>

#include "../core/hash.h"
#include "../geometry/geometry_internal.h"
#include "pattern_internal.h"

static const ori_insert_def default_def = {.overlap = ORI_OVERLAP_KEEP_BOUNDARY,
                                           .name_faces = true,
                                           .length_scale = ORI_INSERT_AUTO_SCALE,
                                           .internal_value = ORI__DEF_COOKIE};

ori_insert_def ori_default_insert_def(void) { return default_def; }

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

// Segments ab and pq cross properly (each has its end points strictly on both sides of the
// other's line), decided exactly.
static bool cross_properly(ori_v2 a, ori_v2 b, ori_v2 p, ori_v2 q)
{
    return ori_orient2d_sign(a, b, p) * ori_orient2d_sign(a, b, q) < 0 &&
           ori_orient2d_sign(p, q, a) * ori_orient2d_sign(p, q, b) < 0;
}

// The crossing point of segments ab and pq, which cross properly: from the orientation values
// (accurate, never 0/0 since the signs differ), clamped to both segments' boxes.
static ori_v2 crossing_point(ori_v2 a, ori_v2 b, ori_v2 p, ori_v2 q)
{
    double op = ori_orient2d(a, b, p), oq = ori_orient2d(a, b, q);
    ori_v2 x = lerp(p, q, op / (op - oq));
    double lo_x = fmax(fmin(p.x, q.x), fmin(a.x, b.x)), hi_x = fmin(fmax(p.x, q.x), fmax(a.x, b.x));
    double lo_y = fmax(fmin(p.y, q.y), fmin(a.y, b.y)), hi_y = fmin(fmax(p.y, q.y), fmax(a.y, b.y));
    if (lo_x <= hi_x) x.x = fmin(fmax(x.x, lo_x), hi_x);
    if (lo_y <= hi_y) x.y = fmin(fmax(x.y, lo_y), hi_y);
    return x;
}

// Next value of a stamp that marks membership in arr[0..cap) without clearing it; the array
// is cleared when the stamp wraps around.
static int next_stamp(int *stamp, int *arr, int cap)
{
    if (++*stamp == INT32_MAX) {
        *stamp = 1;
        if (cap > 0) memset(arr, 0, sizeof(int) * (size_t)cap);
    }
    return *stamp;
}

// --- uniform grid (bulk insertion) ------------------------------------------------------

typedef struct grid_node {
    int item, next;
} grid_node;

typedef struct grid {
    bool on;
    double x0, y0, x1, y1, cell;
    int nx, ny;
    int built_edges; // edges when the grid was (re)built: it is refined as they multiply
    int *edge_head, *vert_head; // per cell: first node or -1
    grid_node *nodes;
    int node_count, node_cap;
} grid;

// A face's vertices while an insertion runs. Loaded faces borrow their vertices from one copy of
// the pattern's (no allocation per face: a single insertion into a pattern of thousands of faces
// would otherwise allocate thousands of lists); a face gets its own array when it grows.
typedef struct face_list {
    int *v;
    int n, cap;
    bool owned;
} face_list;

typedef struct event {
    double s;     // position along the segment, 0 at a, 1 at b (ordering only)
    ori_v2 pos;   // where the event is
    int vertex;   // existing vertex or -1
    int edge;     // edge passing here (split it here) or -1
    int endpoint; // 1 for the snapped end points of the segment
    bool turned;  // pos is on a part of the edge that had turned off its line (see split_rec)
} event;

typedef struct group {
    ori_v2 pos;
    int vertex;       // existing vertex, or -1 for a new one
    int id;           // its vertex index after the commit (new vertices numbered on from the count)
    int first, count; // range in the sorted events
    double t;         // parameter of pos along the segment's line (unclamped)
} group;

typedef struct split_rec {
    int edge;
    int id;     // the vertex it is split at (a group's, or an existing vertex off the segment)
    double t;   // parameter of that point along the edge
    bool pivot; // that point is not where the edge itself passes (its parts there turn)
} split_rec;

// An edge split at an existing vertex that is not where the edge passes: a group's vertex the
// edge passes within tol of, or (no faces) a vertex a turned part passes within tol of.
typedef struct vertex_split {
    int edge, vertex;
} vertex_split;

typedef struct edge_split {
    int p, q;         // original end points
    int first, count; // vertices in split_verts, ordered from p to q
} edge_split;

// One edge of the planned result, in commit order: the parts of the split edges (by edge
// index, each from its first vertex), then the pieces of the segment.
typedef enum op_kind {
    OP_KEEP,    // a part that keeps the split edge's index
    OP_APPEND,  // a further part, appended
    OP_MERGE,   // a part joining two vertices already joined by edge `target`
    OP_DROP,    // (a new pattern only) the split edge lies entirely on other edges: it goes
    OP_PIECE,   // a piece of the segment, appended
    OP_OVERLAP, // a piece of the segment along edge `target`
} op_kind;

typedef struct op {
    op_kind kind;
    int u, w;           // end vertices (final indices)
    int edge;           // KEEP/APPEND/MERGE/DROP: the split edge; PIECE/OVERLAP: the piece's first group
    int target;         // MERGE/OVERLAP: the edge it lies on (index valid when the op runs)
    ori_assignment asg; // KEEP/APPEND/MERGE: the split edge's assignment and fold angle
    double angle;
    bool pivot;         // KEEP/APPEND: the part turned off the edge's line (see split_rec)
} op;

// A vertex near the segment's line, with its parameter along it.
typedef struct near_vertex {
    double t;
    int v;
} near_vertex;

// An edge of the planned result near the segment (for the final check): its parameter range
// along the segment's line within the reach, end vertices, whether the insertion makes it.
typedef struct span {
    double t0, t1;
    int v[2];
    int edge; // existing edge, or the split edge of a part, or -1 for a piece
    bool fresh;
} span;

typedef struct int_list {
    int *v;
    int n, cap;
} int_list;

// Vertices and edges near a segment (see gather).
typedef struct cand_list {
    int_list v, e;
} cand_list;

typedef struct arr {
    ori_pattern *p;
    const ori_insert_def *def;
    double tol, tol2;
    grid g;
    int *cells;
    int cell_count, cell_cap;
    // candidates near the segment (gather) and the stamps that deduplicate them
    cand_list cand;  // near the segment
    cand_list local; // near one part of a split edge, or one vertex
    int *estamp, *vstamp;
    int estamp_cap, vstamp_cap, estamp_now, vstamp_now;
    // the segment being inserted
    ori_v2 sa, sb;  // snapped end points
    ori_v2 dir;     // sb − sa
    double len;     // |sb − sa|
    double maxdev;  // largest distance of a group from the segment's line
    double reach;   // the survivors lie within this of the line
    double pad;     // the candidates cover this much around the segment
    int v0, e0;     // vertex and edge counts before the insertion (first new indices)
    int *mark;      // vertex → group index during one insertion, else -1
    int mark_cap;
    int *vev;       // vertex → vev_now when it is an event of this insertion
    int vev_cap, vev_now;
    int *esr, *esr_stamp; // edge → its first split_rec, valid when esr_stamp is esr_now
    int esr_cap, esr_stamp_cap, esr_now;
    int *eadd;      // edge → eadd_now when a refinement round gave it an event
    int eadd_cap, eadd_now;
    event *ev;
    int ev_count, ev_cap;
    group *gr;
    int gr_count, gr_cap;
    bool revisit;   // a vertex is two groups that are not consecutive
    ori_v2 *npos;   // positions of the new vertices
    int npos_cap;
    double *gmax, *gmin; // prefix maximum and suffix minimum of the groups' t
    int gmax_cap, gmin_cap;
    split_rec *sr;
    int sr_count, sr_cap;
    vertex_split *xs; // kept through the rounds of one insertion
    int xs_count, xs_cap;
    near_vertex *sv; // survivors: candidates near the line, vertices sorted by t
    int sv_count, sv_cap;
    span *se;        // survivor edges with their spans (v, edge; fresh false)
    int se_count, se_cap;
    int *chain;      // vertices along one edge as planned (edge_chain)
    int chain_count, chain_cap;
    bool *chain_pivot; // per chain vertex: the edge turns there (see split_rec)
    int chain_pivot_cap;
    op *ops;
    int op_count, op_cap;
    int *own_edge, *own_part; // plan_edges: the split edges, the chain index of the part each keeps
    int own_edge_cap, own_part_cap;
    int_list appended;        // plan_edges: the split edge of each appended part, in order
    uint64_t *hkeys; // vertex pair → edge (open addressing)
    int *hvals;
    int hcap, hmax; // capacity in use (a power of two), allocated
    span *spans;
    int span_count, span_cap;
    int *active;
    int active_count, active_cap;
    int bad_e, bad_f; // edges named when the plan is refused
    edge_split *es;
    int es_count, es_cap;
    int *split_verts;
    int split_vert_count, split_vert_cap;
    // faces (only when the pattern has faces)
    bool faces;
    face_list *fl;
    int fl_count, fl_cap;
    int *fl_block; // the loaded faces' vertices (borrowed by their lists)
    char (*names)[ORI_NAME_MAX];
    int names_cap;
    int_list *glist; // per group: faces containing the group's vertex
    int glist_cap;
    int *fmark;      // per vertex stamp for face bookkeeping
    int fmark_cap, fstamp;
    int *tmp;
    int tmp_cap;
    // ori_pattern_from_segments (a new pattern, whose indices nobody holds yet): an edge that
    // snapping lays entirely onto others is dropped (marked here, removed at the end)
    bool may_drop;
    char *dead;
    int dead_cap, dropped;
    ori_insert_result res;
} arr;

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
        double y0, y1;
        ori__segment_y_range(a, b, g->x0 + (double)cx * g->cell - pad, g->x0 + (double)(cx + 1) * g->cell + pad, &y0, &y1);
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
    g->x1 = x1;
    g->y1 = y1;
    g->cell = cell;
    g->built_edges = A->p->edge_count;
    size_t cells = (size_t)g->nx * (size_t)g->ny;
    g->edge_head = ori__alloc(sizeof(int) * cells);
    g->vert_head = ori__alloc(sizeof(int) * cells);
    for (size_t i = 0; i < cells; ++i) g->edge_head[i] = g->vert_head[i] = -1;
    g->on = true;
    for (int v = 0; v < A->p->vertex_count; ++v) grid_add_vertex(A, v);
    for (int e = 0; e < A->p->edge_count; ++e) grid_add_edge(A, e);
}

// Cells for the edges as they are now: about one cell per average edge length, and at most
// ~4 cells per edge. Planarising long crossing segments splits them into many short edges; a
// grid sized for the segments would then hold thousands of edges per cell, and each insertion
// would look at all of them (quadratic work). Rebuilt whenever the edges have doubled, the grid
// keeps a few edges per cell at amortised linear cost.
static bool is_dead(const arr *A, int e);

static void grid_rebuild(arr *A)
{
    grid *g = &A->g;
    ori_pattern *p = A->p;
    double total = 0.0;
    int live = 0;
    for (int e = 0; e < p->edge_count; ++e) {
        if (is_dead(A, e)) continue;
        total += ori_v2_norm(ori_v2_sub(ori__pattern_v2(p, p->edges[e].v[1]), ori__pattern_v2(p, p->edges[e].v[0])));
        live++;
    }
    double diag = hypot(g->x1 - g->x0, g->y1 - g->y0);
    double cell = fmax(live > 0 ? total / live : diag, diag / 4096.0);
    int64_t budget = 4 * (int64_t)p->edge_count + 16;
    if (budget > 1 << 24) budget = 1 << 24;
    ori__free(g->edge_head);
    ori__free(g->vert_head);
    g->node_count = 0;
    grid_init(A, g->x0, g->y0, g->x1, g->y1, cell, (int)budget);
}

// --- per-vertex / per-edge scratch ---------------------------------------------------------

// Grow an int array indexed by vertex or edge to n entries, new entries set to fill.
static void ensure_filled(int **a, int *cap, int n, int fill)
{
    if (*cap >= n) return;
    int old = *cap;
    ORI__RESERVE(*a, *cap, n);
    if (fill == 0 || fill == -1) memset(*a + old, fill == 0 ? 0 : 0xFF, sizeof(int) * (size_t)(*cap - old));
    else
        for (int i = old; i < *cap; ++i) (*a)[i] = fill;
}

static void ensure_vertex_arrays(arr *A)
{
    int n = A->p->vertex_count;
    ensure_filled(&A->mark, &A->mark_cap, n, -1);
    ensure_filled(&A->vstamp, &A->vstamp_cap, n, 0);
    ensure_filled(&A->fmark, &A->fmark_cap, n, 0);
    ensure_filled(&A->vev, &A->vev_cap, n, 0);
}

static void ensure_edge_arrays(arr *A)
{
    int m = A->p->edge_count;
    ensure_filled(&A->estamp, &A->estamp_cap, m, 0);
    ensure_filled(&A->esr, &A->esr_cap, m, 0);
    ensure_filled(&A->esr_stamp, &A->esr_stamp_cap, m, 0);
    ensure_filled(&A->eadd, &A->eadd_cap, m, 0);
}

static bool is_dead(const arr *A, int e) { return e < A->dead_cap && A->dead[e]; }

static void mark_dead(arr *A, int e)
{
    if (A->dead_cap <= e) {
        int old = A->dead_cap;
        ORI__RESERVE(A->dead, A->dead_cap, e + 1);
        memset(A->dead + old, 0, (size_t)(A->dead_cap - old));
    }
    A->dead[e] = 1;
    A->dropped++;
}

// Remove the dropped edges, keeping the order of the others (see arr.may_drop).
static void remove_dropped(arr *A)
{
    ori_pattern *p = A->p;
    int n = 0;
    for (int e = 0; e < p->edge_count; ++e)
        if (!is_dead(A, e)) p->edges[n++] = p->edges[e];
    p->edge_count = n;
}

// Candidate vertices and edges near the segment ab (within pad) into out: every element in
// linear mode after a bounding-box test, the grid cells along the segment in bulk mode.
static void gather(arr *A, ori_v2 a, ori_v2 b, double pad, cand_list *out)
{
    ori_pattern *p = A->p;
    ensure_vertex_arrays(A);
    ensure_edge_arrays(A);
    out->v.n = out->e.n = 0;
    double lx = fmin(a.x, b.x) - pad, hx = fmax(a.x, b.x) + pad;
    double ly = fmin(a.y, b.y) - pad, hy = fmax(a.y, b.y) + pad;
    if (!A->g.on) {
        for (int v = 0; v < p->vertex_count; ++v) {
            ori_v3 x = p->vertices[v];
            if (x.x >= lx && x.x <= hx && x.y >= ly && x.y <= hy) list_push(&out->v, v);
        }
        for (int e = 0; e < p->edge_count; ++e) {
            ori_v3 u = p->vertices[p->edges[e].v[0]], w = p->vertices[p->edges[e].v[1]];
            if (fmax(u.x, w.x) < lx || fmin(u.x, w.x) > hx || fmax(u.y, w.y) < ly || fmin(u.y, w.y) > hy) continue;
            if (!is_dead(A, e)) list_push(&out->e, e);
        }
        return;
    }
    int vs = next_stamp(&A->vstamp_now, A->vstamp, A->vstamp_cap);
    int es = next_stamp(&A->estamp_now, A->estamp, A->estamp_cap);
    grid_cells(A, a, b, pad);
    for (int i = 0; i < A->cell_count; ++i) {
        int c = A->cells[i];
        for (int n = A->g.vert_head[c]; n >= 0; n = A->g.nodes[n].next) {
            int v = A->g.nodes[n].item;
            if (A->vstamp[v] == vs) continue;
            A->vstamp[v] = vs;
            ori_v3 x = p->vertices[v];
            if (x.x >= lx && x.x <= hx && x.y >= ly && x.y <= hy) list_push(&out->v, v);
        }
        for (int n = A->g.edge_head[c]; n >= 0; n = A->g.nodes[n].next) {
            int e = A->g.nodes[n].item;
            if (A->estamp[e] == es) continue;
            A->estamp[e] = es;
            if (!is_dead(A, e)) list_push(&out->e, e);
        }
    }
}

// --- vertex pair → edge -------------------------------------------------------------------

// An empty table for n pairs (sized to n, so that clearing it costs O(n)).
static void pairs_reset(arr *A, int n)
{
    A->hcap = ori__hash_capacity(n);
    if (A->hcap > A->hmax) {
        ori__free(A->hkeys);
        ori__free(A->hvals);
        A->hkeys = ori__alloc(sizeof(uint64_t) * (size_t)A->hcap);
        A->hvals = ori__alloc(sizeof(int) * (size_t)A->hcap);
        A->hmax = A->hcap;
    }
    for (int i = 0; i < A->hcap; ++i) A->hkeys[i] = UINT64_MAX; // no pair has this key
}

// Slot of the pair {a, b}: where it is, or the empty slot where it goes.
static int pairs_slot(const arr *A, int a, int b)
{
    uint64_t key = ori__pair_key(a, b);
    int mask = A->hcap - 1;
    int i = (int)(ori__mix64(key) & (uint64_t)mask);
    while (A->hkeys[i] != UINT64_MAX && A->hkeys[i] != key) i = (i + 1) & mask;
    return i;
}

static int pairs_find(const arr *A, int a, int b)
{
    int i = pairs_slot(A, a, b);
    return A->hkeys[i] == UINT64_MAX ? -1 : A->hvals[i];
}

static void pairs_put(arr *A, int a, int b, int edge)
{
    int i = pairs_slot(A, a, b);
    A->hkeys[i] = ori__pair_key(a, b);
    A->hvals[i] = edge;
}

// --- planning -------------------------------------------------------------------------------

// Snap an end point: to the nearest vertex within tol, else onto the nearest edge within tol
// (a T-junction, split there), else free. Fills the event; returns the snapped position.
static ori_v2 snap_endpoint(arr *A, ori_v2 x, double s, event *out)
{
    ori_pattern *p = A->p;
    gather(A, x, x, 2.0 * A->tol, &A->cand);
    out->s = s;
    out->endpoint = 1;
    out->turned = false;
    out->vertex = -1;
    out->edge = -1;
    out->pos = x;
    double best = A->tol2;
    for (int i = 0; i < A->cand.v.n; ++i) {
        int v = A->cand.v.v[i];
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
    for (int i = 0; i < A->cand.e.n; ++i) {
        int e = A->cand.e.v[i];
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

static int compare_near(const void *pa, const void *pb)
{
    const near_vertex *a = pa, *b = pb;
    return (a->t > b->t) - (a->t < b->t);
}

static int compare_splits(const void *pa, const void *pb)
{
    const split_rec *a = pa, *b = pb;
    if (a->edge != b->edge) return a->edge < b->edge ? -1 : 1;
    if (a->t != b->t) return a->t < b->t ? -1 : 1;
    return (a->id > b->id) - (a->id < b->id);
}

static void reset_marks(arr *A)
{
    for (int i = 0; i < A->gr_count; ++i)
        if (A->gr[i].id >= 0 && A->gr[i].id < A->mark_cap) A->mark[A->gr[i].id] = -1;
}

typedef enum plan_outcome {
    PLAN_OK,
    PLAN_DEGENERATE, // the snapped segment has no length
    PLAN_FLOATING,   // a piece would float inside a face (see floating_pieces)
    PLAN_COLLAPSE,   // snapping would merge existing edges where the pattern has faces, or remove one
    PLAN_CONFLICT,   // snapping would make edges cross (bad_e names one when it exists)
} plan_outcome;

static bool floating_pieces(arr *A);

// Position of a vertex of the plan: existing, or new (numbered on from the vertex count).
static ori_v2 vpos(const arr *A, int id)
{
    return id < A->v0 ? ori__pattern_v2(A->p, id) : A->npos[id - A->v0];
}

// Parameter of x along the segment's line (0 at sa, 1 at sb) and signed distance from it.
static double line_t(const arr *A, ori_v2 x) { return ori_v2_dot(ori_v2_sub(x, A->sa), A->dir) / (A->len * A->len); }
// (Rounded: only used to filter and measure, never to decide a side.)
static double line_dist(const arr *A, ori_v2 x) { return ori_v2_cross(A->dir, ori_v2_sub(x, A->sa)) / A->len; }

// Parameter range along the line of the part of segment xy within the reach of the line
// (widened by the tolerance); false when xy does not come that close.
static bool strip_span(const arr *A, ori_v2 x, ori_v2 y, double *t0, double *t1)
{
    double dx = line_dist(A, x), dy = line_dist(A, y), r = A->reach;
    if ((dx > r && dy > r) || (dx < -r && dy < -r)) return false;
    double l0 = 0.0, l1 = 1.0;
    if (dx != dy) {
        double la = (r - dx) / (dy - dx), lb = (-r - dx) / (dy - dx);
        l0 = fmax(l0, fmin(la, lb));
        l1 = fmin(l1, fmax(la, lb));
        if (l0 > l1) l0 = l1 = clamp01(0.5 * (l0 + l1)); // rounding at a grazing end
    }
    double ta = line_t(A, lerp(x, y, l0)), tb = line_t(A, lerp(x, y, l1)), pad = A->tol / A->len;
    *t0 = fmin(ta, tb) - pad;
    *t1 = fmax(ta, tb) + pad;
    double end = r / A->len;
    return *t1 >= -end && *t0 <= 1.0 + end;
}

// Pieces k (groups k, k+1) whose parameter range may meet [t0, t1]: k0..k1, false if none.
// The groups' t are nearly sorted; the prefix maximum and suffix minimum make it exact.
static bool piece_range(const arr *A, double t0, double t1, int *k0, int *k1)
{
    int n = A->gr_count - 1; // pieces
    if (n < 1) return false;
    int lo = 0, hi = n; // first k with gmax[k + 1] >= t0
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (A->gmax[mid + 1] >= t0) hi = mid;
        else lo = mid + 1;
    }
    *k0 = lo;
    lo = -1, hi = n - 1; // last k with gmin[k] <= t1
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (A->gmin[mid] <= t1) lo = mid;
        else hi = mid - 1;
    }
    *k1 = lo;
    return *k0 <= *k1;
}

// The first survivor vertex with t >= t0.
static int survivor_from(const arr *A, double t0)
{
    int lo = 0, hi = A->sv_count;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (A->sv[mid].t < t0) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

static void push_event(arr *A, ori_v2 pos, int vertex, int edge, bool turned)
{
    event e = {clamp01(line_t(A, pos)), pos, vertex, edge, 0, turned};
    ORI__PUSH(A->ev, A->ev_count, A->ev_cap, e);
    if (vertex >= 0) A->vev[vertex] = A->vev_now;
    if (edge >= 0) A->eadd[edge] = A->eadd_now;
}

// A new point made only by edge e between the two ends of e (the rounds found e crossing an
// earlier polyline; now the polyline runs along e): drop its events, so that e is not split
// there and the piece between its ends overlaps it. Returns whether it dropped any.
static bool drop_needless_points(arr *A)
{
    const ori_pattern *p = A->p;
    int dropped = 0;
    for (int k = 1; k + 1 < A->gr_count; ++k) {
        const group *g = &A->gr[k];
        int e = A->ev[g->first].edge;
        if (g->vertex >= 0 || e < 0) continue;
        bool only_e = true;
        for (int j = g->first; j < g->first + g->count && only_e; ++j) only_e = A->ev[j].edge == e && !A->ev[j].endpoint;
        int u = A->gr[k - 1].id, w = A->gr[k + 1].id, a = p->edges[e].v[0], b = p->edges[e].v[1];
        if (!only_e || !((u == a && w == b) || (u == b && w == a))) continue;
        for (int j = g->first; j < g->first + g->count; ++j) A->ev[j].edge = -2; // dropped below
        dropped++;
    }
    if (dropped == 0) return false;
    int n = 0;
    for (int i = 0; i < A->ev_count; ++i)
        if (A->ev[i].edge != -2) A->ev[n++] = A->ev[i];
    A->ev_count = n;
    return true;
}

// Groups from the events: sorted along the segment, consecutive events closer than tol are one
// point (an existing vertex wins, then an end point; two distinct existing vertices never
// merge); a new point within tol of an existing vertex becomes it. Numbers the new points,
// marks the vertices, and measures how far the polyline strays from the line.
static void form_groups(arr *A)
{
    ori_pattern *p = A->p;
    reset_marks(A);
    A->gr_count = 0;
    if (A->ev_count > 1) qsort(A->ev, (size_t)A->ev_count, sizeof *A->ev, compare_events);
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
            group ng = {e->pos, e->vertex, -1, i, 1, 0.0};
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
    double tl = A->tol / A->len;
    for (int k = 0; k < A->gr_count; ++k) {
        group *g = &A->gr[k];
        if (g->vertex >= 0) continue;
        // the nearest survivor within tol (they are sorted by t)
        double t = line_t(A, g->pos), best = A->tol2;
        for (int i = survivor_from(A, t - tl); i < A->sv_count && A->sv[i].t <= t + tl; ++i) {
            double d = dist2(ori__pattern_v2(p, A->sv[i].v), g->pos);
            if (d <= best) {
                best = d;
                g->vertex = A->sv[i].v;
            }
        }
        if (g->vertex >= 0) g->pos = ori__pattern_v2(p, g->vertex);
    }
    // Groups on one vertex are one: consecutive ones, and a loop back to a vertex through new
    // points only (snapping folded the polyline onto itself there). Numbering, marks, deviation.
    int n = 0, fresh = 0;
    A->revisit = false;
    A->maxdev = 0.0;
    ORI__RESERVE(A->npos, A->npos_cap, A->gr_count);
    for (int k = 0; k < A->gr_count; ++k) {
        group g = A->gr[k];
        int m = g.vertex >= 0 ? A->mark[g.vertex] : -1;
        bool loop = m >= 0;
        for (int j = m + 1; loop && j < n; ++j) loop = A->gr[j].vertex < 0;
        if (loop) {
            fresh -= n - 1 - m;
            A->gr[m].count = g.first + g.count - A->gr[m].first;
            n = m + 1;
            continue;
        }
        if (g.vertex >= 0) {
            g.id = g.vertex;
            if (m >= 0) A->revisit = true; // (a loop through other vertices: refused)
            else A->mark[g.vertex] = n;
        } else {
            g.id = A->v0 + fresh;
            A->npos[fresh++] = g.pos;
        }
        g.t = line_t(A, g.pos);
        A->maxdev = fmax(A->maxdev, fabs(line_dist(A, g.pos)));
        A->gr[n++] = g;
    }
    A->gr_count = n;
    ORI__RESERVE(A->gmax, A->gmax_cap, n);
    ORI__RESERVE(A->gmin, A->gmin_cap, n);
    for (int k = 0; k < n; ++k) A->gmax[k] = k > 0 ? fmax(A->gmax[k - 1], A->gr[k].t) : A->gr[k].t;
    for (int k = n - 1; k >= 0; --k) A->gmin[k] = k + 1 < n ? fmin(A->gmin[k + 1], A->gr[k].t) : A->gr[k].t;
}

static void push_split(arr *A, int e, int id, ori_v2 x, bool pivot)
{
    const ori_edge *ed = &A->p->edges[e];
    if (id == ed->v[0] || id == ed->v[1]) return; // the edge's own end
    split_rec r = {e, id, project_param(ori__pattern_v2(A->p, ed->v[0]), ori__pattern_v2(A->p, ed->v[1]), x), pivot};
    ORI__PUSH(A->sr, A->sr_count, A->sr_cap, r);
}

// Edge splits: one per (edge, group) where an edge passes a group, and the vertex splits;
// sorted by edge, then along it.
static void form_splits(arr *A)
{
    A->sr_count = 0;
    for (int k = 0; k < A->gr_count; ++k) {
        const group *g = &A->gr[k];
        for (int j = g->first; j < g->first + g->count; ++j) {
            const event *e = &A->ev[j];
            if (e->edge >= 0)
                push_split(A, e->edge, g->id, g->pos, e->turned || e->pos.x != g->pos.x || e->pos.y != g->pos.y);
        }
    }
    for (int i = 0; i < A->xs_count; ++i)
        push_split(A, A->xs[i].edge, A->xs[i].vertex, ori__pattern_v2(A->p, A->xs[i].vertex), true);
    if (A->sr_count > 1) qsort(A->sr, (size_t)A->sr_count, sizeof *A->sr, compare_splits);
    int n = 0;
    for (int i = 0; i < A->sr_count; ++i) {
        if (n > 0 && A->sr[n - 1].edge == A->sr[i].edge && A->sr[n - 1].id == A->sr[i].id)
            A->sr[n - 1].pivot = A->sr[n - 1].pivot || A->sr[i].pivot;
        else
            A->sr[n++] = A->sr[i];
    }
    A->sr_count = n;
    int stamp = next_stamp(&A->esr_now, A->esr_stamp, A->esr_stamp_cap);
    for (int i = 0; i < n; ++i)
        if (i == 0 || A->sr[i - 1].edge != A->sr[i].edge) {
            A->esr[A->sr[i].edge] = i;
            A->esr_stamp[A->sr[i].edge] = stamp;
        }
}

static bool is_split(const arr *A, int e) { return A->esr_stamp[e] == A->esr_now; }

// The vertices along edge e as planned: its end points and the groups it is split at, from its
// first vertex (into A->chain; returns the count).
static int edge_chain(arr *A, int e)
{
    const ori_edge *ed = &A->p->edges[e];
    int first = is_split(A, e) ? A->esr[e] : A->sr_count, end = first;
    while (end < A->sr_count && A->sr[end].edge == e) ++end;
    ORI__RESERVE(A->chain, A->chain_cap, end - first + 2);
    ORI__RESERVE(A->chain_pivot, A->chain_pivot_cap, end - first + 2);
    int n = 0;
    A->chain[n] = ed->v[0];
    A->chain_pivot[n++] = false;
    for (int i = first; i < end; ++i) {
        if (A->sr[i].id == A->chain[n - 1]) continue;
        A->chain[n] = A->sr[i].id;
        A->chain_pivot[n++] = A->sr[i].pivot;
    }
    A->chain[n] = ed->v[1];
    A->chain_pivot[n++] = false;
    A->chain_count = n;
    return n;
}

static bool in_chain(const arr *A, int id)
{
    for (int i = 0; i < A->chain_count; ++i)
        if (A->chain[i] == id) return true;
    return false;
}

// The candidates near the polyline: vertices (sorted along the line) and edges within the
// reach of the segment's line (at least the groups' largest deviation + 2 tol; the lists are
// kept while that holds, the pattern does not change during a plan).
static void collect_survivors(arr *A)
{
    ori_pattern *p = A->p;
    if (A->maxdev + 2.0 * A->tol <= A->reach) return;
    A->reach = A->maxdev + 3.0 * A->tol;
    if (A->reach > A->pad) {
        A->pad = 2.0 * A->reach;
        gather(A, A->sa, A->sb, A->pad, &A->cand);
    }
    A->sv_count = A->se_count = 0;
    double end = A->reach / A->len;
    for (int i = 0; i < A->cand.v.n; ++i) {
        int v = A->cand.v.v[i];
        ori_v2 x = ori__pattern_v2(p, v);
        double t = line_t(A, x);
        if (fabs(line_dist(A, x)) > A->reach || t < -end || t > 1.0 + end) continue;
        near_vertex nv = {t, v};
        ORI__PUSH(A->sv, A->sv_count, A->sv_cap, nv);
    }
    if (A->sv_count > 1) qsort(A->sv, (size_t)A->sv_count, sizeof *A->sv, compare_near);
    for (int i = 0; i < A->cand.e.n; ++i) {
        int e = A->cand.e.v[i];
        span sp = {0.0, 0.0, {p->edges[e].v[0], p->edges[e].v[1]}, e, false};
        if (strip_span(A, ori__pattern_v2(p, sp.v[0]), ori__pattern_v2(p, sp.v[1]), &sp.t0, &sp.t1))
            ORI__PUSH(A->se, A->se_count, A->se_cap, sp);
    }
}

// One refinement round of the polyline (the groups): a vertex within tol of a piece joins the
// segment, an edge passing within tol of a group is split there, a split edge whose pivoted
// part passes within tol of a vertex is split there too, and an edge that a piece crosses
// (snapping moved the piece off the straight segment) is split at the crossing.
// Returns whether it added events. Each edge gets at most one new event per round.
static bool refine(arr *A)
{
    ori_pattern *p = A->p;
    int added = 0;
    double tl = A->tol / A->len;
    next_stamp(&A->eadd_now, A->eadd, A->eadd_cap);
    for (int i = 0; i < A->sv_count; ++i) {
        int v = A->sv[i].v, k0, k1;
        if (A->mark[v] >= 0 || A->vev[v] == A->vev_now) continue;
        if (!piece_range(A, A->sv[i].t - tl, A->sv[i].t + tl, &k0, &k1)) continue;
        ori_v2 x = ori__pattern_v2(p, v);
        for (int k = k0; k <= k1; ++k)
            if (seg_dist2(A->gr[k].pos, A->gr[k + 1].pos, x) <= A->tol2) {
                push_event(A, x, v, -1, false);
                added++;
                break;
            }
    }
    for (int i = 0; i < A->se_count; ++i) {
        int e = A->se[i].edge;
        int n = edge_chain(A, e);
        for (int c = 0; c + 1 < n && A->eadd[e] != A->eadd_now; ++c) {
            int x = A->chain[c], y = A->chain[c + 1], k0 = 0, k1 = -1;
            ori_v2 X = vpos(A, x), Y = vpos(A, y);
            double t0 = A->se[i].t0, t1 = A->se[i].t1; // (the edge's span while it is whole)
            bool near = (n == 2 || strip_span(A, X, Y, &t0, &t1)) && piece_range(A, t0, t1, &k0, &k1);
            bool turned = A->chain_pivot[c] || A->chain_pivot[c + 1];
            for (int k = k0; near && k <= k1 + 1; ++k) {
                const group *g = &A->gr[k];
                // (a group near an end point: that vertex joins the segment instead, above)
                if (in_chain(A, g->id) || dist2(g->pos, X) <= A->tol2 || dist2(g->pos, Y) <= A->tol2 ||
                    seg_dist2(X, Y, g->pos) > A->tol2)
                    continue;
                if (g->vertex >= 0) { // split at that vertex directly
                    vertex_split xs = {e, g->vertex};
                    ORI__PUSH(A->xs, A->xs_count, A->xs_cap, xs);
                    A->eadd[e] = A->eadd_now;
                } else { // at the group itself (so that it joins that group), the edge turning there
                    push_event(A, g->pos, -1, e, true);
                }
                added++;
                break;
            }
            // (no faces) a part that turned off the edge's line near another vertex: split the
            // edge there too (the vertex may lie anywhere along the part)
            if (!A->faces && turned && A->eadd[e] != A->eadd_now) {
                gather(A, X, Y, A->tol, &A->local);
                for (int j = 0; j < A->local.v.n; ++j) {
                    int v = A->local.v.v[j];
                    ori_v2 z = ori__pattern_v2(p, v);
                    if (A->mark[v] >= 0 || in_chain(A, v) || dist2(z, X) <= A->tol2 || dist2(z, Y) <= A->tol2 ||
                        seg_dist2(X, Y, z) > A->tol2)
                        continue;
                    vertex_split xs = {e, v};
                    ORI__PUSH(A->xs, A->xs_count, A->xs_cap, xs);
                    A->eadd[e] = A->eadd_now;
                    added++;
                    break;
                }
            }
            for (int k = k0; near && k <= k1 && A->eadd[e] != A->eadd_now; ++k) {
                int u = A->gr[k].id, w = A->gr[k + 1].id;
                if (u == x || u == y || w == x || w == y) continue;
                ori_v2 U = A->gr[k].pos, W = A->gr[k + 1].pos;
                if (!cross_properly(U, W, X, Y)) continue;
                ori_v2 at = crossing_point(U, W, X, Y);
                // (a crossing within tol of the part's end is that vertex, which joins above)
                if (dist2(at, X) <= A->tol2 || dist2(at, Y) <= A->tol2) continue;
                push_event(A, at, -1, e, turned);
                added++;
            }
        }
    }
    return added > 0;
}

// The edges of the result, in commit order (A->ops). The pair map holds the vertex pairs of
// the untouched edges near the plan and of every planned edge: a part or a piece whose two
// vertices are already joined lies on that edge (a piece overlaps it; a part merges into it:
// snapping closed the sliver between them). Each split edge keeps its index for a part of its
// own: one that only it makes (without merges, the part at its first vertex), else one that no
// other edge has taken. PLAN_COLLAPSE when a part would merge into another edge in a pattern with
// faces (a face would collapse), or when every part of a split edge lies on other edges (the
// edge would vanish).
static plan_outcome plan_edges(arr *A)
{
    ori_pattern *p = A->p;
    A->op_count = 0;
    pairs_reset(A, A->se_count + 2 * A->sr_count + A->gr_count);
    for (int i = 0; i < A->se_count; ++i) {
        int e = A->se[i].edge;
        if (!is_split(A, e)) pairs_put(A, p->edges[e].v[0], p->edges[e].v[1], e);
    }
    for (int i = 0; i < A->xs_count; ++i) { // the edges at vertices off the segment
        int v = A->xs[i].vertex;
        gather(A, ori__pattern_v2(p, v), ori__pattern_v2(p, v), A->tol, &A->local);
        for (int j = 0; j < A->local.e.n; ++j) {
            const ori_edge *ed = &p->edges[A->local.e.v[j]];
            if ((ed->v[0] == v || ed->v[1] == v) && !is_split(A, A->local.e.v[j]))
                pairs_put(A, ed->v[0], ed->v[1], A->local.e.v[j]);
        }
    }
    // The split edges in order; how many of them make each new part (a map value v <= -2
    // counts -1 - v of them; >= 0 is an edge).
    int splits = 0;
    for (int i = 0; i < A->sr_count; ++i) {
        if (i > 0 && A->sr[i - 1].edge == A->sr[i].edge) continue;
        ORI__PUSH(A->own_edge, splits, A->own_edge_cap, A->sr[i].edge);
        int n = edge_chain(A, A->sr[i].edge);
        for (int c = 0; c + 1 < n; ++c) {
            int t = pairs_find(A, A->chain[c], A->chain[c + 1]);
            if (t < 0) pairs_put(A, A->chain[c], A->chain[c + 1], t == -1 ? -2 : t - 1);
        }
    }
    ORI__RESERVE(A->own_part, A->own_part_cap, splits);
    for (int i = 0; i < splits; ++i) A->own_part[i] = -1;
    for (int pass = 0; pass < 2; ++pass)
        for (int i = 0; i < splits; ++i) {
            if (A->own_part[i] >= 0) continue;
            int e = A->own_edge[i], n = edge_chain(A, e);
            for (int c = 0; c + 1 < n; ++c) {
                int t = pairs_find(A, A->chain[c], A->chain[c + 1]);
                if (pass == 0 ? t == -2 : t <= -2) {
                    A->own_part[i] = c;
                    pairs_put(A, A->chain[c], A->chain[c + 1], e);
                    break;
                }
            }
        }
    int next = A->e0;
    A->appended.n = 0;
    for (int i = 0; i < splits; ++i) {
        int e = A->own_edge[i], n = edge_chain(A, e);
        for (int c = 0; c + 1 < n; ++c) {
            op o = {OP_KEEP, A->chain[c],      A->chain[c + 1], e, -1, p->edges[e].assignment, p->edges[e].fold_angle_rad,
                    A->chain_pivot[c] || A->chain_pivot[c + 1]};
            int t = pairs_find(A, o.u, o.w);
            if (c == A->own_part[i]) {
                // (kept)
            } else if (t >= 0 || A->own_part[i] < 0) {
                A->bad_e = e;
                A->bad_f = t < A->e0 ? t : A->appended.v[t - A->e0]; // (the edge a new part is of)
                if (A->faces || (A->own_part[i] < 0 && !A->may_drop)) return PLAN_COLLAPSE;
                o.kind = OP_MERGE;
                o.target = t;
            } else {
                o.kind = OP_APPEND;
                pairs_put(A, o.u, o.w, next++);
                list_push(&A->appended, e);
            }
            ORI__PUSH(A->ops, A->op_count, A->op_cap, o);
        }
        if (A->own_part[i] < 0) {
            op o = {OP_DROP, -1, -1, e, -1, p->edges[e].assignment, p->edges[e].fold_angle_rad, false};
            ORI__PUSH(A->ops, A->op_count, A->op_cap, o);
        }
    }
    for (int k = 0; k + 1 < A->gr_count; ++k) {
        op o = {OP_PIECE, A->gr[k].id, A->gr[k + 1].id, k, -1, ORI_ASSIGN_UNASSIGNED, 0.0, false};
        int t = pairs_find(A, o.u, o.w);
        if (t >= 0) {
            o.kind = OP_OVERLAP;
            o.target = t;
        } else {
            pairs_put(A, o.u, o.w, next++);
        }
        ORI__PUSH(A->ops, A->op_count, A->op_cap, o);
    }
    return PLAN_OK;
}

static void push_span(arr *A, int u, int w, int edge, bool fresh)
{
    span s = {0.0, 0.0, {u, w}, edge, fresh};
    if (strip_span(A, vpos(A, u), vpos(A, w), &s.t0, &s.t1)) ORI__PUSH(A->spans, A->span_count, A->span_cap, s);
}

static int compare_spans(const void *pa, const void *pb)
{
    const span *a = pa, *b = pb;
    return (a->t0 > b->t0) - (a->t0 < b->t0);
}

// The final check, exact: near the segment, no planned new edge (a part of a split edge or a
// piece) may meet another edge except at a shared end vertex. (Sweep over the parameter ranges
// along the segment's line.) Names an existing edge concerned in bad_e when there is one.
static bool conflicts(arr *A)
{
    ori_pattern *p = A->p;
    A->span_count = 0;
    for (int i = 0; i < A->op_count; ++i) {
        const op *o = &A->ops[i];
        if (o->kind == OP_KEEP || o->kind == OP_APPEND || o->kind == OP_PIECE)
            push_span(A, o->u, o->w, o->kind == OP_PIECE ? -1 : o->edge, true);
    }
    for (int i = 0; i < A->se_count; ++i)
        if (!is_split(A, A->se[i].edge)) ORI__PUSH(A->spans, A->span_count, A->span_cap, A->se[i]);
    if (A->span_count > 1) qsort(A->spans, (size_t)A->span_count, sizeof *A->spans, compare_spans);
    A->active_count = 0;
    for (int i = 0; i < A->span_count; ++i) {
        const span *s = &A->spans[i];
        ori_v2 a = vpos(A, s->v[0]), b = vpos(A, s->v[1]);
        int n = 0;
        for (int j = 0; j < A->active_count; ++j) {
            const span *r = &A->spans[A->active[j]];
            if (r->t1 < s->t0) continue; // ended before this one starts
            A->active[n++] = A->active[j];
            if (!s->fresh && !r->fresh) continue;
            if (ori__segments_conflict(a, b, s->v, vpos(A, r->v[0]), vpos(A, r->v[1]), r->v)) {
                A->bad_e = s->fresh ? r->edge : s->edge;
                return true;
            }
        }
        A->active_count = n;
        ORI__PUSH(A->active, A->active_count, A->active_cap, i);
    }
    // A part that turned off its edge's line may meet edges anywhere along it.
    for (int i = 0; i < A->op_count; ++i) {
        const op *o = &A->ops[i];
        if ((o->kind != OP_KEEP && o->kind != OP_APPEND) || !o->pivot) continue;
        ori_v2 a = vpos(A, o->u), b = vpos(A, o->w);
        int ov[2] = {o->u, o->w};
        gather(A, a, b, A->tol, &A->local);
        for (int j = 0; j < A->local.e.n; ++j) {
            int f = A->local.e.v[j];
            const int *fv = p->edges[f].v;
            if (!is_split(A, f) && ori__segments_conflict(a, b, ov, ori__pattern_v2(p, fv[0]), ori__pattern_v2(p, fv[1]), fv)) {
                A->bad_e = f;
                return true;
            }
        }
        for (int j = 0; j < A->op_count; ++j) {
            const op *q = &A->ops[j];
            if (j == i || q->kind == OP_MERGE || q->kind == OP_OVERLAP) continue;
            int qv[2] = {q->u, q->w};
            if (ori__segments_conflict(a, b, ov, vpos(A, q->u), vpos(A, q->w), qv)) {
                A->bad_e = q->kind == OP_PIECE ? -1 : q->edge;
                return true;
            }
        }
    }
    return false;
}

// Phase 1 (no mutation): the polyline, refined until consistent (or for at most
// ORI_INSERT_MAX_ROUNDS rounds), then the edges of the result and their exact check.
static plan_outcome plan(arr *A, ori_v2 a, ori_v2 b)
{
    ori_pattern *p = A->p;
    A->ev_count = A->gr_count = A->sr_count = A->op_count = A->xs_count = 0;
    A->bad_e = A->bad_f = -1;
    A->v0 = p->vertex_count;
    A->e0 = p->edge_count;
    ensure_vertex_arrays(A);
    ensure_edge_arrays(A);
    next_stamp(&A->vev_now, A->vev, A->vev_cap);
    event ea, eb;
    ori_v2 sa = snap_endpoint(A, a, 0.0, &ea);
    ori_v2 sb = snap_endpoint(A, b, 1.0, &eb);
    if ((ea.vertex >= 0 && ea.vertex == eb.vertex) || dist2(sa, sb) <= A->tol2) return PLAN_DEGENERATE;
    A->sa = sa;
    A->sb = sb;
    A->dir = ori_v2_sub(sb, sa);
    A->len = ori_v2_norm(A->dir);
    ORI__PUSH(A->ev, A->ev_count, A->ev_cap, ea);
    ORI__PUSH(A->ev, A->ev_count, A->ev_cap, eb);
    if (ea.vertex >= 0) A->vev[ea.vertex] = A->vev_now;
    if (eb.vertex >= 0) A->vev[eb.vertex] = A->vev_now;

    A->maxdev = A->reach = 0.0;
    A->pad = 4.0 * A->tol;
    gather(A, sa, sb, A->pad, &A->cand);
    collect_survivors(A);
    for (int round = 1;; ++round) {
        form_groups(A);
        if (A->gr_count < 2) return PLAN_DEGENERATE;
        form_splits(A);
        collect_survivors(A);
        if (round >= ORI_INSERT_MAX_ROUNDS || !refine(A)) break;
    }
    if (drop_needless_points(A)) {
        form_groups(A);
        form_splits(A);
        collect_survivors(A);
    }
    if (A->faces && floating_pieces(A)) return PLAN_FLOATING;
    for (int i = 0; A->faces && i < A->xs_count; ++i)
        if (A->mark[A->xs[i].vertex] < 0) {
            // (splitting an edge at a vertex off the segment would collapse the sliver between)
            A->bad_e = A->xs[i].edge;
            return PLAN_CONFLICT;
        }
    plan_outcome r = plan_edges(A);
    if (r != PLAN_OK) return r;
    if (A->revisit || conflicts(A)) return PLAN_CONFLICT;
    return PLAN_OK;
}

// --- faces ----------------------------------------------------------------------------------

static void faces_load(arr *A)
{
    ori_pattern *p = A->p;
    A->faces = p->face_count > 0;
    if (!A->faces) return;
    ORI__RESERVE(A->fl, A->fl_cap, p->face_count);
    ORI__RESERVE(A->names, A->names_cap, p->face_count);
    A->fl_count = p->face_count;
    A->fl_block = ori__alloc(sizeof(int) * (size_t)(p->face_vertex_count ? p->face_vertex_count : 1));
    memcpy(A->fl_block, p->face_vertices, sizeof(int) * (size_t)p->face_vertex_count);
    for (int f = 0; f < p->face_count; ++f) {
        face_list *F = &A->fl[f];
        int b = p->face_offsets[f], n = p->face_offsets[f + 1] - b;
        F->v = A->fl_block + b;
        F->n = F->cap = n;
        F->owned = false;
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

// Room for need vertices in face F (a borrowed list gets its own array first).
static void face_reserve(face_list *F, int need)
{
    if (!F->owned) {
        if (need <= F->cap) return;
        int *v = ori__alloc(sizeof(int) * (size_t)(need > 2 * F->n ? need : 2 * F->n));
        memcpy(v, F->v, sizeof(int) * (size_t)F->n);
        F->cap = need > 2 * F->n ? need : 2 * F->n;
        F->v = v;
        F->owned = true;
        return;
    }
    ORI__RESERVE(F->v, F->cap, need);
}

static void faces_free(arr *A)
{
    for (int f = 0; f < A->fl_count; ++f)
        if (A->fl[f].owned) ori__free(A->fl[f].v);
    ori__free(A->fl_block);
    A->fl_block = NULL;
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
    int n = F->n, in = F->v[(i + 1) % n], ip = F->v[(i + n - 1) % n];
    ori_v2 u = ori__pattern_v2(A->p, F->v[i]), nx = ori__pattern_v2(A->p, in), pv = ori__pattern_v2(A->p, ip);
    return ccw ? ori__corner_contains(u, nx, pv, x) : ori__corner_contains(u, pv, nx, x);
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
    F->owned = true;
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
    next_stamp(&A->fstamp, A->fmark, A->fmark_cap);
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
    face_reserve(F, F->n + 2);
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
    next_stamp(&A->fstamp, A->fmark, A->fmark_cap);
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

static int find_split(const arr *A, int a, int b)
{
    uint64_t k = ori__pair_key(a, b);
    for (int i = 0; i < A->es_count; ++i)
        if (ori__pair_key(A->es[i].p, A->es[i].q) == k) return i;
    return -1;
}

// Insert the split vertices into every face side p–q.
static void faces_apply_splits(arr *A)
{
    if (!A->faces || A->es_count == 0) return;
    // Only sides joining two end points of split edges can be split (marked: a stamp per vertex).
    ensure_vertex_arrays(A);
    int stamp = next_stamp(&A->fstamp, A->fmark, A->fmark_cap);
    for (int i = 0; i < A->es_count; ++i) A->fmark[A->es[i].p] = A->fmark[A->es[i].q] = stamp;
    for (int f = 0; f < A->fl_count; ++f) {
        face_list *F = &A->fl[f];
        int extra = 0;
        for (int i = 0; i < F->n; ++i) {
            int a = F->v[i], b = F->v[(i + 1) % F->n];
            if (A->fmark[a] != stamp || A->fmark[b] != stamp) continue;
            int s = find_split(A, a, b);
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
        face_reserve(F, m);
        memcpy(F->v, A->tmp, sizeof(int) * (size_t)m);
        F->n = m;
    }
}

static bool is_cut_or_boundary(ori_assignment a) { return a == ORI_ASSIGN_BOUNDARY || a == ORI_ASSIGN_CUT; }

static void apply_overlap(arr *A, int e, ori_assignment asg, double angle)
{
    ori_edge *ed = &A->p->edges[e];
    bool take;
    switch (A->def->overlap) {
    case ORI_OVERLAP_KEEP_EXISTING: take = false; break;
    case ORI_OVERLAP_REPLACE: take = true; break;
    default: take = !is_cut_or_boundary(ed->assignment); break;
    }
    if (take) {
        ed->assignment = asg;
        ed->fold_angle_rad = angle;
    }
    A->res.edges_overlapped++;
    A->res.segment_edges++;
}

// A part of a split edge (assignment asg) that snapping laid onto edge e: one edge remains, and
// a boundary or cut wins over a crease (the sheet's outline stays).
static void merge_into(arr *A, int e, ori_assignment asg, double angle)
{
    ori_edge *ed = &A->p->edges[e];
    if (is_cut_or_boundary(asg) && !is_cut_or_boundary(ed->assignment)) {
        ed->assignment = asg;
        ed->fold_angle_rad = angle;
    }
    A->res.edges_merged++;
}

// Phase 2: carry out the plan.
static void commit(arr *A, ori_assignment asg, double angle)
{
    ori_pattern *p = A->p;
    ori__pattern_invalidate(p);
    // New vertices (their indices were planned).
    for (int k = 0; k < A->gr_count; ++k) {
        group *g = &A->gr[k];
        if (g->vertex >= 0) continue;
        ORI__PUSH(p->vertices, p->vertex_count, p->vertex_cap, ori_v3_make(g->pos.x, g->pos.y, 0.0));
        ORI_ASSERT(g->id == p->vertex_count - 1);
        g->vertex = g->id;
        A->res.vertices_added++;
        grid_add_vertex(A, g->vertex);
    }
    ensure_vertex_arrays(A);
    for (int k = 0; k < A->gr_count; ++k) A->mark[A->gr[k].vertex] = k;

    // Split edges: the parts, in order from each edge's first vertex.
    A->es_count = A->split_vert_count = 0;
    int i = 0;
    while (i < A->op_count && A->ops[i].kind <= OP_DROP) {
        int e = A->ops[i].edge;
        edge_split r = {p->edges[e].v[0], p->edges[e].v[1], A->split_vert_count, 0};
        for (int part = 0; i < A->op_count && A->ops[i].kind <= OP_DROP && A->ops[i].edge == e; ++i, ++part) {
            const op *o = &A->ops[i];
            if (o->kind == OP_DROP) {
                mark_dead(A, e);
                continue;
            }
            if (part > 0) {
                ORI__PUSH(A->split_verts, A->split_vert_count, A->split_vert_cap, o->u);
                r.count++;
            }
            if (o->kind == OP_KEEP) {
                p->edges[e].v[0] = o->u;
                p->edges[e].v[1] = o->w;
                if (o->pivot) grid_add_edge(A, e); // (else the cells of the whole edge hold it)
            } else if (o->kind == OP_APPEND) {
                ori_edge ne = {{o->u, o->w}, o->asg, o->angle};
                ORI__PUSH(p->edges, p->edge_count, p->edge_cap, ne);
                A->res.edges_added++;
                grid_add_edge(A, p->edge_count - 1);
            }
        }
        ORI__PUSH(A->es, A->es_count, A->es_cap, r);
        A->res.edges_split++;
    }
    for (int j = 0; j < i; ++j) // (after the loop: a merge target may be a part appended later)
        if (A->ops[j].kind == OP_MERGE) merge_into(A, A->ops[j].target, A->ops[j].asg, A->ops[j].angle);
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
            for (int j = 0; j < F->n; ++j) {
                int gi = A->mark[F->v[j]];
                if (gi >= 0 && !list_has(&A->glist[gi], f)) list_push(&A->glist[gi], f);
            }
        }
    }

    // Pieces.
    for (; i < A->op_count; ++i) {
        const op *o = &A->ops[i];
        if (o->kind == OP_OVERLAP) {
            apply_overlap(A, o->target, asg, angle);
            continue;
        }
        ori_edge ne = {{o->u, o->w}, asg, angle};
        ORI__PUSH(p->edges, p->edge_count, p->edge_cap, ne);
        A->res.edges_added++;
        A->res.segment_edges++;
        grid_add_edge(A, p->edge_count - 1);
        if (A->faces) cut_faces(A, o->edge, o->edge + 1);
    }
}

static void arr_free(arr *A)
{
    ori__free(A->g.edge_head);
    ori__free(A->g.vert_head);
    ori__free(A->g.nodes);
    ori__free(A->cells);
    ori__free(A->cand.v.v);
    ori__free(A->cand.e.v);
    ori__free(A->local.v.v);
    ori__free(A->local.e.v);
    ori__free(A->estamp);
    ori__free(A->vstamp);
    ori__free(A->mark);
    ori__free(A->vev);
    ori__free(A->esr);
    ori__free(A->esr_stamp);
    ori__free(A->eadd);
    ori__free(A->ev);
    ori__free(A->gr);
    ori__free(A->npos);
    ori__free(A->gmax);
    ori__free(A->gmin);
    ori__free(A->sr);
    ori__free(A->xs);
    ori__free(A->sv);
    ori__free(A->se);
    ori__free(A->chain);
    ori__free(A->chain_pivot);
    ori__free(A->ops);
    ori__free(A->own_edge);
    ori__free(A->own_part);
    ori__free(A->appended.v);
    ori__free(A->dead);
    ori__free(A->hkeys);
    ori__free(A->hvals);
    ori__free(A->spans);
    ori__free(A->active);
    ori__free(A->es);
    ori__free(A->split_verts);
    for (int i = 0; i < A->glist_cap; ++i) ori__free(A->glist[i].v);
    ori__free(A->glist);
    ori__free(A->fmark);
    ori__free(A->tmp);
    faces_free(A);
}

// Insert one segment (already validated finite).
static plan_outcome insert_one(arr *A, ori_v2 a, ori_v2 b, ori_assignment asg, double angle)
{
    plan_outcome r = plan(A, a, b);
    if (r == PLAN_OK) commit(A, asg, angle);
    reset_marks(A);
    return r;
}

// Grow the box [lx, hx] × [ly, hy] by the pattern's vertices; returns its diagonal (1 when it
// has none: the scale of a single point).
static double grow_box(const ori_pattern *p, double *lx, double *ly, double *hx, double *hy)
{
    for (int v = 0; v < p->vertex_count; ++v) {
        *lx = fmin(*lx, p->vertices[v].x);
        *ly = fmin(*ly, p->vertices[v].y);
        *hx = fmax(*hx, p->vertices[v].x);
        *hy = fmax(*hy, p->vertices[v].y);
    }
    double d = hypot(*hx - *lx, *hy - *ly);
    return d > 0.0 && isfinite(d) ? d : 1.0;
}

static bool finite_v2(ori_v2 a) { return ori__coord_ok(a.x) && ori__coord_ok(a.y); }

// What every insertion does first: outputs cleared, the defaults for a NULL def, the checks.
static ori_status start(const ori_pattern *p, const ori_insert_def **def, ori_insert_result *out, ori_error *error)
{
    if (!*def) *def = &default_def;
    ori_error_clear(error);
    if (out) memset(out, 0, sizeof *out);
    ORI_ASSERT((*def)->internal_value == ORI__DEF_COOKIE);
    ORI_ASSERT((*def)->length_scale == ORI_INSERT_AUTO_SCALE || (*def)->length_scale > 0.0);
    ORI_ASSERT((int)(*def)->overlap >= 0 && (*def)->overlap <= ORI_OVERLAP_REPLACE);
    if (p->folded_form)
        return ori__fail(error, ORI_ERR_UNSUPPORTED, "segments can only be inserted into a flat crease pattern");
    for (int v = 0; v < p->vertex_count; ++v)
        if (!finite_v2(ori_v2_make(p->vertices[v].x, p->vertices[v].y)))
            return ori__fail_at(error, ORI_ERR_RANGE, "vertices_coords", v, "coordinate is not finite or exceeds %g", ORI_COORD_MAX);
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

static void arr_init(arr *A, ori_pattern *p, const ori_insert_def *def, double scale)
{
    memset(A, 0, sizeof *A);
    A->p = p;
    A->def = def;
    A->tol = ORI_TOL_LENGTH_REL * scale;
    A->tol2 = A->tol * A->tol;
}

ori_status ori_pattern_insert_segment(ori_pattern *p, ori_v2 a, ori_v2 b, ori_assignment asg, double angle,
                                      const ori_insert_def *def, ori_insert_result *out, ori_error *error)
{
    ORI_ASSERT(p && (int)asg >= 0 && asg < ORI_ASSIGN_COUNT);
    ori_status st = start(p, &def, out, error);
    if (st != ORI_OK) return st;
    if (!finite_v2(a) || !finite_v2(b) || !isfinite(angle))
        return ori__fail(error, ORI_ERR_RANGE, "segment coordinates must be finite and at most %g, the fold angle finite", ORI_COORD_MAX);
    double lx = fmin(a.x, b.x), ly = fmin(a.y, b.y), hx = fmax(a.x, b.x), hy = fmax(a.y, b.y);
    double scale = def->length_scale != ORI_INSERT_AUTO_SCALE ? def->length_scale : grow_box(p, &lx, &ly, &hx, &hy);
    arr A;
    arr_init(&A, p, def, scale);
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
    if (r == PLAN_COLLAPSE && A.faces)
        return ori__fail_at(error, ORI_ERR_DEGENERATE, "edges_vertices", A.bad_e,
                            "segment (%g, %g)-(%g, %g) would merge edge %d with edge %d: they are closer than the "
                            "length tolerance where it meets them, and the face between them would collapse",
                            a.x, a.y, b.x, b.y, A.bad_e, A.bad_f);
    if (r == PLAN_COLLAPSE)
        return ori__fail_at(error, ORI_ERR_DEGENERATE, "edges_vertices", A.bad_e,
                            "segment (%g, %g)-(%g, %g) would merge edge %d entirely into the edges beside it "
                            "(closer than the length tolerance)", a.x, a.y, b.x, b.y, A.bad_e);
    if (r == PLAN_CONFLICT)
        return ori__fail_at(error, ORI_ERR_DEGENERATE, "edges_vertices", A.bad_e < A.e0 ? A.bad_e : ORI_NULL_INDEX,
                            "segment (%g, %g)-(%g, %g) cannot be inserted consistently: snapped to the length "
                            "tolerance, its edges would meet %s away from a vertex", a.x, a.y, b.x, b.y,
                            A.bad_e >= 0 && A.bad_e < A.e0 ? "an existing edge" : "each other");
    return ORI_OK;
}

static ori_status insert_many(ori_pattern *p, const ori_segment *segs, int count, const ori_insert_def *def,
                              bool may_drop, ori_insert_result *out, ori_error *error)
{
    ORI_ASSERT(p && (segs || count == 0) && count >= 0);
    ori_status st = start(p, &def, out, error);
    if (st != ORI_OK) return st;
    double lx = DBL_MAX, ly = DBL_MAX, hx = -DBL_MAX, hy = -DBL_MAX, total_len = 0.0;
    for (int i = 0; i < count; ++i) {
        const ori_segment *s = &segs[i];
        ORI_ASSERT((int)s->assignment >= 0 && s->assignment < ORI_ASSIGN_COUNT);
        if (!finite_v2(s->a) || !finite_v2(s->b) || !isfinite(s->fold_angle_rad))
            return ori__fail_at(error, ORI_ERR_RANGE, "segments", i, "coordinate (finite, at most %g) or fold angle (finite) out of range", ORI_COORD_MAX);
        lx = fmin(lx, fmin(s->a.x, s->b.x));
        ly = fmin(ly, fmin(s->a.y, s->b.y));
        hx = fmax(hx, fmax(s->a.x, s->b.x));
        hy = fmax(hy, fmax(s->a.y, s->b.y));
        total_len += ori_v2_norm(ori_v2_sub(s->b, s->a));
    }
    if (count == 0) return ORI_OK;
    double diag = grow_box(p, &lx, &ly, &hx, &hy);
    arr A;
    arr_init(&A, p, def, def->length_scale == ORI_INSERT_AUTO_SCALE ? diag : def->length_scale);
    A.may_drop = may_drop;
    // About one cell per average segment length, at most ~4 cells per element.
    double cell = fmax(total_len / (double)count, diag / 4096.0);
    int64_t budget = 4 * ((int64_t)count + p->edge_count) + 16;
    if (budget > 1 << 24) budget = 1 << 24;
    double pad = 4.0 * A.tol;
    grid_init(&A, lx - pad, ly - pad, hx + pad, hy + pad, cell, (int)budget);
    faces_load(&A);
    int skipped = 0;
    for (int i = 0; i < count; ++i) {
        if (insert_one(&A, segs[i].a, segs[i].b, segs[i].assignment, segs[i].fold_angle_rad) != PLAN_OK) skipped++;
        if (p->edge_count > 2 * A.g.built_edges + 1024) grid_rebuild(&A);
    }
    faces_store(&A);
    if (A.dropped > 0) remove_dropped(&A);
    A.res.segments_skipped = skipped;
    if (out) *out = A.res;
    arr_free(&A);
    return ORI_OK;
}

ori_status ori_pattern_insert_segments(ori_pattern *p, const ori_segment *segs, int count, const ori_insert_def *def,
                                       ori_insert_result *out, ori_error *error)
{
    return insert_many(p, segs, count, def, false, out, error);
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
    ori_status st = insert_many(p, segs, count, def, true, result, error);
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

// Signed area and area centroid of face f (shoelace over its vertices).
static double face_area_centroid(const ori_pattern *p, const int *vs, int n, ori_v2 *c)
{
    double a = 0.0, cx = 0.0, cy = 0.0;
    ori_v3 o = ori_pattern_vertex(p, vs[0]); // relative to the first vertex: no cancellation far out
    for (int i = 0; i < n; ++i) {
        ori_v3 q0 = ori_pattern_vertex(p, vs[i]), q1 = ori_pattern_vertex(p, vs[(i + 1) % n]);
        double x0 = q0.x - o.x, y0 = q0.y - o.y, x1 = q1.x - o.x, y1 = q1.y - o.y;
        double w = x0 * y1 - x1 * y0;
        a += w;
        cx += (x0 + x1) * w;
        cy += (y0 + y1) * w;
    }
    a *= 0.5;
    if (a != 0.0) *c = ori_v2_make(o.x + cx / (6.0 * a), o.y + cy / (6.0 * a));
    else *c = ori_v2_make(o.x, o.y);
    return a;
}

int ori_pattern_center_face(const ori_pattern *p)
{
    ORI_ASSERT(p);
    int nv = ori_pattern_vertex_count(p), nf = ori_pattern_face_count(p);
    if (nv == 0 || nf == 0) return 0;
    int cap = 0, *vs = NULL;
    // The sheet's area centroid: the faces' centroids weighted by their areas (a cross-shaped
    // net's bounding-box centre lies on an edge; its area centroid inside the middle square).
    double area = 0.0, sx = 0.0, sy = 0.0;
    ori_v2 *fc = ori__alloc(sizeof(ori_v2) * (size_t)nf);
    for (int f = 0; f < nf; ++f) {
        int n = ori_pattern_face_size(p, f);
        fc[f] = ori_v2_make(NAN, NAN);
        if (n <= 0) continue;
        if (n > cap) {
            ori__free(vs);
            cap = n;
            vs = ori__alloc(sizeof(int) * (size_t)cap);
        }
        ori_pattern_face_vertices(p, f, vs, n);
        double a = fabs(face_area_centroid(p, vs, n, &fc[f]));
        area += a;
        sx += a * fc[f].x;
        sy += a * fc[f].y;
    }
    ori_v2 c;
    if (area > 0.0) {
        c = ori_v2_make(sx / area, sy / area);
    } else { // no area (degenerate faces): the bounding-box centre
        ori_v3 lo = ori_pattern_vertex(p, 0), hi = lo;
        for (int v = 1; v < nv; ++v) {
            ori_v3 q = ori_pattern_vertex(p, v);
            lo.x = fmin(lo.x, q.x), lo.y = fmin(lo.y, q.y), hi.x = fmax(hi.x, q.x), hi.y = fmax(hi.y, q.y);
        }
        c = ori_v2_make(0.5 * (lo.x + hi.x), 0.5 * (lo.y + hi.y));
    }
    bool on_edge;
    int inside = ori_pattern_find_face_at(p, c, &on_edge);
    if (inside != ORI_NULL_INDEX && !on_edge) {
        ori__free(vs);
        ori__free(fc);
        return inside;
    }
    // On an edge, at a vertex, in a hole or outside the sheet (a ring, an L): the face nearest to
    // the centroid (distance to its outline, 0 when the centroid is on it), then the one whose
    // own centroid is nearest, then the lowest index (ties within ORI_TOL_ON_LINE_REL × diagonal).
    double tol = ORI_TOL_ON_LINE_REL * ori_pattern_diagonal(p);
    int best = 0;
    double best_d = INFINITY, best_dc = INFINITY;
    for (int f = 0; f < nf; ++f) {
        int n = ori_pattern_face_size(p, f);
        if (n <= 0) continue;
        ori_pattern_face_vertices(p, f, vs, n);
        double d2 = INFINITY;
        for (int i = 0; i < n; ++i) {
            ori_v3 a = ori_pattern_vertex(p, vs[i]), b = ori_pattern_vertex(p, vs[(i + 1) % n]);
            d2 = fmin(d2, seg_dist2(ori_v2_make(a.x, a.y), ori_v2_make(b.x, b.y), c));
        }
        double d = sqrt(d2), dc = hypot(fc[f].x - c.x, fc[f].y - c.y);
        if (d < best_d - tol || (d <= best_d + tol && dc < best_dc - tol)) {
            best_d = fmin(d, best_d);
            best_dc = dc;
            best = f;
        }
    }
    ori__free(vs);
    ori__free(fc);
    return best;
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

int ori_pattern_find_face_at(const ori_pattern *p, ori_v2 x, bool *on_edge)
{
    ORI_ASSERT(p);
    double tol = ORI_TOL_ON_LINE_REL * ori_pattern_diagonal(p);
    if (on_edge) *on_edge = false;
    int cap = 0, *vs = NULL;
    int found = ORI_NULL_INDEX;
    for (int f = 0; f < ori_pattern_face_count(p) && found == ORI_NULL_INDEX; ++f) {
        int n = ori_pattern_face_size(p, f);
        if (n < 3) continue;
        if (n > cap) {
            ori__free(vs);
            cap = n;
            vs = ori__alloc(sizeof(int) * (size_t)cap);
        }
        ori_pattern_face_vertices(p, f, vs, n);
        bool inside = false, edge = false;
        for (int i = 0, j = n - 1; i < n && !edge; j = i++) { // crossing number, boundary within tol
            ori_v2 a = ori__pattern_v2(p, vs[j]), b = ori__pattern_v2(p, vs[i]);
            if (seg_dist2(a, b, x) <= tol * tol) edge = true;
            else if ((a.y > x.y) != (b.y > x.y) && x.x < a.x + (x.y - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
        }
        if (edge) {
            if (on_edge) *on_edge = true;
            found = f;
        } else if (inside) {
            found = f;
        }
    }
    ori__free(vs);
    return found;
}

int ori_pattern_edges_on_segment(const ori_pattern *p, ori_v2 a, ori_v2 b, int *out, int cap)
{
    ORI_ASSERT(p && (out || cap == 0));
    double tol = ORI_TOL_ON_LINE_REL * ori_pattern_diagonal(p);
    double lx = fmin(a.x, b.x) - tol, hx = fmax(a.x, b.x) + tol, ly = fmin(a.y, b.y) - tol, hy = fmax(a.y, b.y) + tol;
    int n = 0;
    for (int e = 0; e < p->edge_count; ++e) {
        ori_v2 u = ori__pattern_v2(p, p->edges[e].v[0]), w = ori__pattern_v2(p, p->edges[e].v[1]);
        // (both ends must be near the segment, so within its box: most edges end here)
        if (u.x < lx || u.x > hx || u.y < ly || u.y > hy || w.x < lx || w.x > hx || w.y < ly || w.y > hy) continue;
        if (seg_dist2(a, b, u) <= tol * tol && seg_dist2(a, b, w) <= tol * tol) {
            if (n < cap) out[n] = e;
            n++;
        }
    }
    return n;
}
