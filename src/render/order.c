// Back-to-front order of the posed faces for the painter's algorithm (vector output needs it;
// there is no z-buffer in SVG or PDF).
//
// 1. Every pair of triangles of different faces whose images overlap (found with a uniform grid
//    over their image bounding boxes) is compared at a point inside the overlap: the farther
//    face must be drawn first. Planar faces that do not intersect keep one order over their
//    whole overlap, so one point decides it. Faces whose triangles cross in space (the depth
//    difference changes sign over the overlap) are marked for splitting.
// 2. Two faces lying in one plane (folded flat onto each other) are ordered by stacking: walking
//    the face graph from a root, crossing a crease folded flat puts the next face one layer to
//    the front (valley) or back (mountain) of the current one. Exact for stacks made by a chain
//    of folds. When the state has FOLD faceOrders (a folded form's own, or the layer solver's),
//    the faces they link are ranked by them instead (transitively, a topological sort per stack).
// 3. The face graph may have cycles (three faces overlapping like a pinwheel): its strongly
//    connected components, and the faces that cross, become groups, merged until the graph of
//    groups is acyclic, which is then sorted topologically (Kahn). A group of one face is drawn
//    whole; a larger group is split exactly by a BSP tree of its triangles, traversed from the
//    eye.
#include <math.h>
#include <stdlib.h>

#include "render_internal.h"

// --- small polygon helpers -------------------------------------------------------------------

// Most corners of a polygon clipped here: a triangle clipped by three half-planes has at most 9;
// a BSP fragment with more than BSP_FAN_LIMIT corners is cut into a fan of triangles.
#define MAX_CLIP 16
#define BSP_FAN_LIMIT 12

// The overlap of two triangles is sampled at its corners pulled this fraction of the way from
// its centroid (strictly inside both triangles, away from a shared edge).
#define OVERLAP_SAMPLE 0.999

// Clip the convex polygon (x, y) by the half-plane left of a → b (or right, when sign < 0).
static int clip_half(const ori_v2 *in, int n, ori_v2 a, ori_v2 b, double sign, ori_v2 *out)
{
    int m = 0;
    for (int i = 0; i < n; ++i) {
        ori_v2 p = in[i], q = in[(i + 1) % n];
        double sp = sign * ori_v2_cross(ori_v2_sub(b, a), ori_v2_sub(p, a));
        double sq = sign * ori_v2_cross(ori_v2_sub(b, a), ori_v2_sub(q, a));
        if (sp >= 0.0 && m < MAX_CLIP) out[m++] = p;
        if ((sp >= 0.0) != (sq >= 0.0) && m < MAX_CLIP) {
            double t = sp / (sp - sq);
            out[m++] = ori_v2_add(p, ori_v2_scale(ori_v2_sub(q, p), t));
        }
    }
    return m;
}

static double area2(const ori_v2 *p, int n)
{
    double s = 0.0;
    for (int i = 0; i < n; ++i) s += ori_v2_cross(p[i], p[(i + 1) % n]);
    return s;
}

// --- per-triangle image data ----------------------------------------------------------------

typedef struct tri_img {
    ori_v2 p[3];   // image x, y
    double w[3];   // depth of each corner
    double area2;  // signed twice the image area
    double x0, y0, x1, y1;
    int face;
    bool visible;  // in front of the eye and not degenerate
} tri_img;

// Depth of a triangle at image point q (inside it): barycentric in the image, linear in depth
// for an orthographic camera, linear in 1/depth (perspective-correct) otherwise.
static double depth_at(const tri_img *t, ori_v2 q, bool perspective)
{
    double l0 = ori_v2_cross(ori_v2_sub(t->p[1], q), ori_v2_sub(t->p[2], q)) / t->area2;
    double l1 = ori_v2_cross(ori_v2_sub(t->p[2], q), ori_v2_sub(t->p[0], q)) / t->area2;
    double l2 = 1.0 - l0 - l1;
    if (perspective) return 1.0 / (l0 / t->w[0] + l1 / t->w[1] + l2 / t->w[2]);
    return l0 * t->w[0] + l1 * t->w[1] + l2 * t->w[2];
}

// --- growable pair list ---------------------------------------------------------------------

typedef struct edge_list {
    int (*e)[2];
    int count, cap;
} edge_list;

static void edge_push(edge_list *l, int from, int to)
{
    ORI__RESERVE(l->e, l->cap, l->count + 1);
    l->e[l->count][0] = from;
    l->e[l->count][1] = to;
    l->count++;
}

// --- stacking of faces folded flat ------------------------------------------------------------

// Layer vector of every face: crossing a crease folded flat from face p to face c adds ±n_p
// (valley: c lies on p's front side). Breadth-first from the lowest face of each component.
void ori__render_stacking(const ori_mesh *m, ori_v3 *layer)
{
    int nf = m->face_count;
    bool *seen = ori__calloc((size_t)nf, sizeof(bool));
    int *queue = ori__alloc(sizeof(int) * (size_t)nf);
    // Adjacency through edges: per face, the edges on its sides.
    double flat_cos = cos(ORI_TOL_RENDER_FLAT_FOLD_RAD);
    for (int root = 0; root < nf; ++root) {
        if (seen[root]) continue;
        seen[root] = true;
        layer[root] = ori_v3_make(0, 0, 0);
        int head = 0, tail = 0;
        queue[tail++] = root;
        while (head < tail) {
            int f = queue[head++];
            for (int k = m->face_start[f]; k < m->face_start[f + 1]; ++k) {
                int e = m->face_side_edge[k];
                if (e < 0 || m->assign[e] == ORI_ASSIGN_CUT) continue;
                int g = m->edge_face[e][0] == f ? m->edge_face[e][1] : m->edge_face[e][0];
                if (g < 0 || seen[g]) continue;
                seen[g] = true;
                ori_v3 step = ori_v3_make(0, 0, 0);
                if (ori_v3_dot(m->normal[f], m->normal[g]) < -flat_cos) {
                    double a = m->angle[e];
                    if (a > 0.0) step = m->normal[f];
                    else if (a < 0.0) step = ori_v3_scale(m->normal[f], -1.0);
                }
                layer[g] = ori_v3_add(layer[f], step);
                queue[tail++] = g;
            }
        }
    }
    ori__free(seen);
    ori__free(queue);
}

// --- FOLD faceOrders ---------------------------------------------------------------------------

ori_status ori__face_orders_check(const ori_mesh *m, const int *fo, int count, ori_error *error)
{
    if (count < 0 || (count > 0 && !fo)) return ori__fail(error, ORI_ERR_ARGUMENT, "faceOrders: bad count %d", count);
    for (int i = 0; i < count; ++i) {
        int f = fo[3 * i], g = fo[3 * i + 1], sg = fo[3 * i + 2];
        if (f < 0 || f >= m->face_count || g < 0 || g >= m->face_count)
            return ori__fail_at(error, ORI_ERR_ARGUMENT, "faceOrders", i, "faceOrders[%d] = [%d, %d, %d]: no such face (%d faces)",
                                i, f, g, sg, m->face_count);
        if (f == g)
            return ori__fail_at(error, ORI_ERR_ARGUMENT, "faceOrders", i, "faceOrders[%d] orders face %d against itself", i, f);
        if (sg != 1 && sg != -1)
            return ori__fail_at(error, ORI_ERR_ARGUMENT, "faceOrders", i, "faceOrders[%d]: the order must be +1 or -1, got %d", i,
                                sg);
    }
    return ORI_OK;
}

// --- strongly connected components (iterative Tarjan) ----------------------------------------

// comp[v] = component id of node v (components numbered in reverse topological order).
// Returns the number of components.
static int tarjan(int n, const int *adj_start, const int *adj, int *comp)
{
    int *index = ori__alloc(sizeof(int) * (size_t)(n + 1));
    int *low = ori__alloc(sizeof(int) * (size_t)(n + 1));
    bool *on = ori__calloc((size_t)n + 1, sizeof(bool));
    int *stack = ori__alloc(sizeof(int) * (size_t)(n + 1));
    int *call = ori__alloc(sizeof(int) * (size_t)(n + 1));
    int *iter = ori__alloc(sizeof(int) * (size_t)(n + 1));
    for (int i = 0; i < n; ++i) index[i] = -1;
    int counter = 0, sp = 0, ncomp = 0;
    for (int s = 0; s < n; ++s) {
        if (index[s] >= 0) continue;
        int depth = 0;
        call[depth] = s;
        iter[depth] = adj_start[s];
        index[s] = low[s] = counter++;
        stack[sp++] = s;
        on[s] = true;
        while (depth >= 0) {
            int v = call[depth];
            if (iter[depth] < adj_start[v + 1]) {
                int w = adj[iter[depth]++];
                if (index[w] < 0) {
                    index[w] = low[w] = counter++;
                    stack[sp++] = w;
                    on[w] = true;
                    depth++;
                    call[depth] = w;
                    iter[depth] = adj_start[w];
                } else if (on[w] && index[w] < low[v]) {
                    low[v] = index[w];
                }
            } else {
                if (low[v] == index[v]) {
                    int w;
                    do {
                        w = stack[--sp];
                        on[w] = false;
                        comp[w] = ncomp;
                    } while (w != v);
                    ncomp++;
                }
                depth--;
                if (depth >= 0) {
                    int u = call[depth];
                    if (low[v] < low[u]) low[u] = low[v];
                }
            }
        }
    }
    ori__free(index);
    ori__free(low);
    ori__free(on);
    ori__free(stack);
    ori__free(call);
    ori__free(iter);
    return ncomp;
}

// Compressed adjacency of a graph given by its edge list (self-loops dropped).
static void adjacency(int n, const edge_list *l, int **start, int **adj)
{
    *start = ori__calloc((size_t)n + 2, sizeof(int));
    *adj = ori__alloc(sizeof(int) * (size_t)(l->count + 1));
    for (int i = 0; i < l->count; ++i)
        if (l->e[i][0] != l->e[i][1]) (*start)[l->e[i][0] + 1]++;
    for (int i = 0; i < n; ++i) (*start)[i + 1] += (*start)[i];
    int *fill = ori__alloc(sizeof(int) * (size_t)(n + 1));
    memcpy(fill, *start, sizeof(int) * (size_t)(n + 1));
    for (int i = 0; i < l->count; ++i)
        if (l->e[i][0] != l->e[i][1]) (*adj)[fill[l->e[i][0]]++] = l->e[i][1];
    ori__free(fill);
}

// faceOrders as a layer order: the faces they link (components of the pairs) share the normal n0
// of the component's first face, and a linear extension of "f lies above g along n0" ranks
// them (Kahn; faces of an inconsistent cycle come last, in index order). Two faces of one
// component compare by rank, so unlisted pairs of a stack follow the listed ones transitively.
typedef struct listed_layers {
    int *comp;  // per face: component root, or -1 when faceOrders do not name it
    int *rank;  // per face: position along up
    ori_v3 *up; // per face: its component's n0
} listed_layers;

static void listed_build(const ori_mesh *m, const int *fo, int count, listed_layers *L)
{
    memset(L, 0, sizeof *L);
    if (count <= 0) return;
    int nf = m->face_count;
    L->comp = ori__alloc(sizeof(int) * (size_t)(nf + 1));
    L->rank = ori__calloc((size_t)nf + 1, sizeof(int));
    L->up = ori__calloc((size_t)nf + 1, sizeof(ori_v3));
    int *uf = ori__alloc(sizeof(int) * (size_t)(nf + 1));
    bool *named = ori__calloc((size_t)nf + 1, sizeof(bool));
    for (int f = 0; f < nf; ++f) uf[f] = f;
    for (int i = 0; i < count; ++i) {
        int f = fo[3 * i], g = fo[3 * i + 1];
        named[f] = named[g] = true;
        int rf = ori__uf_root(uf, f), rg = ori__uf_root(uf, g);
        if (rf != rg) uf[rf < rg ? rg : rf] = rf < rg ? rf : rg;
    }
    for (int f = 0; f < nf; ++f) {
        L->comp[f] = named[f] ? ori__uf_root(uf, f) : -1;
        if (named[f]) L->up[f] = ori_v3_scale(m->normal[L->comp[f]], (double)m->fold_sign[L->comp[f]]);
    }
    edge_list el = {NULL, 0, 0};
    for (int i = 0; i < count; ++i) {
        int f = fo[3 * i], g = fo[3 * i + 1];
        double up = (double)fo[3 * i + 2] * m->fold_sign[g] * ori_v3_dot(m->normal[g], L->up[g]);
        if (up > 0.0) edge_push(&el, g, f); // f above g along n0: g first
        else if (up < 0.0) edge_push(&el, f, g);
    }
    int *st, *adj;
    adjacency(nf, &el, &st, &adj);
    int *indeg = ori__calloc((size_t)nf + 1, sizeof(int));
    for (int i = 0; i < nf; ++i)
        for (int k = st[i]; k < st[i + 1]; ++k) indeg[adj[k]]++;
    int *queue = ori__alloc(sizeof(int) * (size_t)(nf + 1));
    int head = 0, tail = 0;
    for (int i = 0; i < nf; ++i)
        if (indeg[i] == 0) queue[tail++] = i;
    while (head < tail) {
        int g = queue[head++];
        for (int k = st[g]; k < st[g + 1]; ++k)
            if (--indeg[adj[k]] == 0) queue[tail++] = adj[k];
    }
    for (int i = 0; i < nf; ++i) L->rank[i] = -1;
    for (int i = 0; i < tail; ++i) L->rank[queue[i]] = i;
    for (int i = 0, next = tail; i < nf; ++i)
        if (L->rank[i] < 0) L->rank[i] = next++;
    ori__free(indeg);
    ori__free(queue);
    ori__free(st);
    ori__free(adj);
    ori__free(el.e);
    ori__free(uf);
    ori__free(named);
}

static void listed_free(listed_layers *L)
{
    ori__free(L->comp);
    ori__free(L->rank);
    ori__free(L->up);
}

// The order faceOrders give faces a and b as seen from the eye: -1 when a is farther (drawn
// first), +1 when a is nearer, 0 when they do not order the two (or the stack is seen edge-on).
static int listed_order(const listed_layers *L, ori_v3 toward_eye, int a, int b)
{
    if (!L || !L->comp || L->comp[a] < 0 || L->comp[a] != L->comp[b]) return 0;
    double d = ori_v3_dot(L->up[a], toward_eye);
    if (d == 0.0) return 0;
    double ha = L->rank[a] * d, hb = L->rank[b] * d;
    return ha < hb ? -1 : ha > hb ? 1 : 0;
}

// --- BSP of a group's triangles -----------------------------------------------------------

typedef struct bsp_poly {
    int face;
    int n;
    ori_v3 p[MAX_CLIP]; // view coordinates
    int tag[MAX_CLIP];  // FOLD edge of side i → i+1, or -1
} bsp_poly;

typedef struct bsp_ctx {
    const ori_mesh *m;
    const ori_camera *cam;
    const ori_v3 *layer;
    const listed_layers *listed; // faceOrders' layer order
    ori_v3 toward_eye_world; // orthographic: the view's back axis in world coordinates
    double tol;
    bsp_poly *out;
    int out_count, out_cap;
    int splits;
} bsp_ctx;

static ori_v3 view_normal(const bsp_ctx *c, int face) { return ori_m3_apply(c->cam->rotation, c->m->normal[face]); }

// Split a convex polygon by the plane n·x = d: parts with s ≥ 0 into *front, s ≤ 0 into *back.
static void split_poly(const bsp_poly *in, ori_v3 n, double d, bsp_poly *front, bsp_poly *back)
{
    front->face = back->face = in->face;
    front->n = back->n = 0;
    double s[MAX_CLIP];
    for (int i = 0; i < in->n; ++i) s[i] = ori_v3_dot(n, in->p[i]) - d;
    for (int i = 0; i < in->n; ++i) {
        int j = (i + 1) % in->n;
        ori_v3 p = in->p[i], q = in->p[j];
        if (s[i] >= 0.0 && front->n < MAX_CLIP) {
            front->p[front->n] = p;
            front->tag[front->n++] = in->tag[i];
        }
        if (s[i] <= 0.0 && back->n < MAX_CLIP) {
            back->p[back->n] = p;
            back->tag[back->n++] = in->tag[i];
        }
        if ((s[i] > 0.0 && s[j] < 0.0) || (s[i] < 0.0 && s[j] > 0.0)) {
            double t = s[i] / (s[i] - s[j]);
            ori_v3 x = ori_v3_add(p, ori_v3_scale(ori_v3_sub(q, p), t));
            // The cut point continues side i on both parts; the cut itself has no edge.
            if (front->n < MAX_CLIP) {
                front->p[front->n] = x;
                front->tag[front->n++] = s[i] > 0.0 ? -1 : in->tag[i];
            }
            if (back->n < MAX_CLIP) {
                back->p[back->n] = x;
                back->tag[back->n++] = s[i] < 0.0 ? -1 : in->tag[i];
            }
        }
    }
}

// Append a polygon to a list, as a fan of triangles when it has grown too many corners.
static void add_poly(bsp_poly *list, int *n, const bsp_poly *p)
{
    if (p->n <= BSP_FAN_LIMIT) {
        list[(*n)++] = *p;
        return;
    }
    for (int k = 1; k + 1 < p->n; ++k) {
        bsp_poly *t = &list[(*n)++];
        t->face = p->face;
        t->n = 3;
        t->p[0] = p->p[0];
        t->p[1] = p->p[k];
        t->p[2] = p->p[k + 1];
        t->tag[0] = k == 1 ? p->tag[0] : -1;
        t->tag[1] = p->tag[k];
        t->tag[2] = k + 2 == p->n ? p->tag[k + 1] : -1;
    }
}

static void emit(bsp_ctx *c, const bsp_poly *p)
{
    ORI__RESERVE(c->out, c->out_cap, c->out_count + 1);
    c->out[c->out_count++] = *p;
}

static double stack_height(const bsp_ctx *c, int face) { return ori_v3_dot(c->layer[face], c->toward_eye_world); }

static int cmp_height_ctx_sort(const bsp_ctx *c, const bsp_poly *a, const bsp_poly *b)
{
    if (a->face != b->face) {
        int listed = listed_order(c->listed, c->toward_eye_world, a->face, b->face);
        if (listed) return listed;
    }
    double ha = stack_height(c, a->face), hb = stack_height(c, b->face);
    if (ha != hb) return ha < hb ? -1 : 1;
    return a->face - b->face;
}

// Build and traverse at once: polygons behind the splitter (as seen from the eye) are emitted
// first, then the splitter's plane, then those in front.
static void bsp(bsp_ctx *c, bsp_poly *polys, int n)
{
    if (n == 0) return;
    const bsp_poly *sp = &polys[0];
    ori_v3 nrm = view_normal(c, sp->face);
    double d = ori_v3_dot(nrm, sp->p[0]);
    // A split part becomes at most MAX_CLIP − 2 fan triangles.
    size_t room = (size_t)n * (MAX_CLIP - 2);
    bsp_poly *front = ori__alloc(sizeof(bsp_poly) * 2 * room);
    bsp_poly *back = front + room;
    bsp_poly *on = ori__alloc(sizeof(bsp_poly) * (size_t)n);
    int nfront = 0, nback = 0, non = 0;
    on[non++] = *sp;
    for (int i = 1; i < n; ++i) {
        const bsp_poly *q = &polys[i];
        bool pos = false, neg = false;
        for (int k = 0; k < q->n; ++k) {
            double s = ori_v3_dot(nrm, q->p[k]) - d;
            if (s > c->tol) pos = true;
            else if (s < -c->tol) neg = true;
        }
        if (!pos && !neg) on[non++] = *q;
        else if (!neg) front[nfront++] = *q;
        else if (!pos) back[nback++] = *q;
        else {
            bsp_poly f, b;
            split_poly(q, nrm, d, &f, &b);
            c->splits++;
            if (f.n >= 3) add_poly(front, &nfront, &f);
            if (b.n >= 3) add_poly(back, &nback, &b);
        }
    }
    // Coplanar polygons: farther layers first (insertion sort; such sets are small).
    for (int i = 1; i < non; ++i) {
        bsp_poly x = on[i];
        int j = i - 1;
        while (j >= 0 && cmp_height_ctx_sort(c, &on[j], &x) > 0) {
            on[j + 1] = on[j];
            j--;
        }
        on[j + 1] = x;
    }
    double eye_side = c->cam->perspective ? nrm.z * c->cam->distance - d : nrm.z;
    if (eye_side >= 0.0) {
        bsp(c, back, nback);
        for (int i = 0; i < non; ++i) emit(c, &on[i]);
        bsp(c, front, nfront);
    } else {
        bsp(c, front, nfront);
        for (int i = 0; i < non; ++i) emit(c, &on[i]);
        bsp(c, back, nback);
    }
    ori__free(front);
    ori__free(on);
}

// --- the order ------------------------------------------------------------------------------

// Append a point (room reserved by the caller).
static void push_point(ori__order *o, ori_v3 img, int tag)
{
    o->points[o->point_count] = img;
    o->side_edge[o->point_count] = tag;
    o->point_count++;
}

static ori_v3 view_to_image(const ori_camera *c, ori_v3 v)
{
    if (c->perspective) {
        double w = c->distance - v.z;
        double f = w > 0.0 ? c->distance / w : 0.0;
        return ori_v3_make(c->cx + c->scale * f * v.x, c->cy - c->scale * f * v.y, w);
    }
    return ori_v3_make(c->cx + c->scale * v.x, c->cy - c->scale * v.y, -v.z);
}

void ori__order_build(const ori_mesh *m, const ori_camera *cam, const int *face_orders, int face_order_count,
                      ori__order *o)
{
    memset(o, 0, sizeof *o);
    int nt = m->tri_count, nf = m->face_count;
    ori_v3 *img = ori__alloc(sizeof(ori_v3) * (size_t)(m->vertex_count + 1));
    for (int v = 0; v < m->vertex_count; ++v) img[v] = ori_camera_project(cam, m->pos[v]);
    ori_v3 lo, hi;
    ori_mesh_bounds(m, &lo, &hi);
    double diag = ori_v3_norm(ori_v3_sub(hi, lo));
    if (!(diag > 0.0)) diag = 1.0;
    double tol_depth = ORI_TOL_RENDER_DEPTH_REL * diag;

    // Image triangles.
    tri_img *ti = ori__alloc(sizeof(tri_img) * (size_t)(nt + 1));
    double sx = 0.0, sy = 0.0;
    int nvis = 0;
    double gx0 = INFINITY, gy0 = INFINITY, gx1 = -INFINITY, gy1 = -INFINITY;
    for (int t = 0; t < nt; ++t) {
        tri_img *q = &ti[t];
        q->face = m->tris[t].face;
        q->visible = true;
        for (int k = 0; k < 3; ++k) {
            ori_v3 p = img[m->tris[t].v[k]];
            q->p[k] = ori_v2_make(p.x, p.y);
            q->w[k] = p.z;
            if (cam->perspective && !(p.z > 0.0)) q->visible = false;
        }
        q->area2 = ori_v2_cross(ori_v2_sub(q->p[1], q->p[0]), ori_v2_sub(q->p[2], q->p[0]));
        if (!(q->area2 != 0.0 && isfinite(q->area2))) q->visible = false; // degenerate, or off at infinity
        q->x0 = fmin(q->p[0].x, fmin(q->p[1].x, q->p[2].x));
        q->x1 = fmax(q->p[0].x, fmax(q->p[1].x, q->p[2].x));
        q->y0 = fmin(q->p[0].y, fmin(q->p[1].y, q->p[2].y));
        q->y1 = fmax(q->p[0].y, fmax(q->p[1].y, q->p[2].y));
        if (!q->visible) continue;
        nvis++;
        sx += q->x1 - q->x0;
        sy += q->y1 - q->y0;
        gx0 = fmin(gx0, q->x0);
        gy0 = fmin(gy0, q->y0);
        gx1 = fmax(gx1, q->x1);
        gy1 = fmax(gy1, q->y1);
    }

    ori_v3 *layer = ori__alloc(sizeof(ori_v3) * (size_t)(nf + 1));
    ori__render_stacking(m, layer);
    // The direction towards the eye (world), for comparing layers.
    ori_v3 toward_eye = ori_v3_make(cam->rotation.m[2][0], cam->rotation.m[2][1], cam->rotation.m[2][2]);
    listed_layers listed;
    listed_build(m, face_orders, face_order_count, &listed);

    // Union-find of faces that must be split together.
    int *group = ori__alloc(sizeof(int) * (size_t)(nf + 1));
    for (int f = 0; f < nf; ++f) group[f] = f;
    edge_list edges = {NULL, 0, 0};

    if (nvis > 1) {
        // Uniform grid: cells about the mean triangle size, at most ~4 cells per triangle.
        double cell = fmax(sx, sy) / nvis;
        double ext = fmax(gx1 - gx0, gy1 - gy0);
        if (!(cell > 0.0)) cell = ext > 0.0 ? ext : 1.0;
        double limit = sqrt(4.0 * nvis + 16.0);
        if ((gx1 - gx0) / cell > limit) cell = (gx1 - gx0) / limit;
        if ((gy1 - gy0) / cell > limit) cell = (gy1 - gy0) / limit;
        // (Extents beyond the double range give one cell: slower, never an int overflow.)
        double fw = (gx1 - gx0) / cell, fh = (gy1 - gy0) / cell;
        int gw = fw >= 0.0 && fw <= limit + 1.0 ? (int)fw + 1 : 1, gh = fh >= 0.0 && fh <= limit + 1.0 ? (int)fh + 1 : 1;
        int ncell = gw * gh;
        int *cstart = ori__calloc((size_t)ncell + 2, sizeof(int));
#define CELL_X(x) ((int)fmin(gw - 1, fmax(0.0, floor(((x) - gx0) / cell))))
#define CELL_Y(y) ((int)fmin(gh - 1, fmax(0.0, floor(((y) - gy0) / cell))))
        for (int t = 0; t < nt; ++t) {
            if (!ti[t].visible) continue;
            for (int cy = CELL_Y(ti[t].y0); cy <= CELL_Y(ti[t].y1); ++cy)
                for (int cx = CELL_X(ti[t].x0); cx <= CELL_X(ti[t].x1); ++cx) cstart[cy * gw + cx + 1]++;
        }
        for (int i = 0; i < ncell; ++i) cstart[i + 1] += cstart[i];
        int *cfill = ori__alloc(sizeof(int) * (size_t)(ncell + 1));
        memcpy(cfill, cstart, sizeof(int) * (size_t)(ncell + 1));
        int *ctri = ori__alloc(sizeof(int) * (size_t)(cstart[ncell] + 1));
        for (int t = 0; t < nt; ++t) {
            if (!ti[t].visible) continue;
            for (int cy = CELL_Y(ti[t].y0); cy <= CELL_Y(ti[t].y1); ++cy)
                for (int cx = CELL_X(ti[t].x0); cx <= CELL_X(ti[t].x1); ++cx) ctri[cfill[cy * gw + cx]++] = t;
        }
        ori_v2 a_poly[MAX_CLIP], b_poly[MAX_CLIP];
        for (int cidx = 0; cidx < ncell; ++cidx) {
            int cx = cidx % gw, cy = cidx / gw;
            for (int i = cstart[cidx]; i < cstart[cidx + 1]; ++i) {
                const tri_img *A = &ti[ctri[i]];
                for (int j = i + 1; j < cstart[cidx + 1]; ++j) {
                    const tri_img *B = &ti[ctri[j]];
                    if (A->face == B->face) continue;
                    double ox0 = fmax(A->x0, B->x0), oy0 = fmax(A->y0, B->y0);
                    if (ox0 > fmin(A->x1, B->x1) || oy0 > fmin(A->y1, B->y1)) continue;
                    // Test each pair once: in the cell of the corner of their boxes' overlap.
                    if (CELL_X(ox0) != cx || CELL_Y(oy0) != cy) continue;
                    // Image overlap: A clipped by B's three sides.
                    int n = 3;
                    for (int k = 0; k < 3; ++k) a_poly[k] = A->p[k];
                    double sgn = B->area2 > 0.0 ? 1.0 : -1.0;
                    for (int k = 0; k < 3 && n > 0; ++k) {
                        n = clip_half(a_poly, n, B->p[k], B->p[(k + 1) % 3], sgn, b_poly);
                        memcpy(a_poly, b_poly, sizeof(ori_v2) * (size_t)n);
                    }
                    if (n < 3) continue;
                    double ov = fabs(area2(a_poly, n));
                    if (!(ov > ORI_TOL_RENDER_OVERLAP_REL * fmin(fabs(A->area2), fabs(B->area2)))) continue;
                    ori_v2 q = {0, 0};
                    for (int k = 0; k < n; ++k) q = ori_v2_add(q, a_poly[k]);
                    q = ori_v2_scale(q, 1.0 / n);
                    double dmin = INFINITY, dmax = -INFINITY;
                    for (int k = 0; k < n; ++k) {
                        // Corners pulled slightly towards the centre: inside both triangles.
                        ori_v2 r = ori_v2_add(q, ori_v2_scale(ori_v2_sub(a_poly[k], q), OVERLAP_SAMPLE));
                        double dd = depth_at(A, r, cam->perspective) - depth_at(B, r, cam->perspective);
                        dmin = fmin(dmin, dd);
                        dmax = fmax(dmax, dd);
                    }
                    double dq = depth_at(A, q, cam->perspective) - depth_at(B, q, cam->perspective);
                    int fa = A->face, fb = B->face;
                    if (dmin < -tol_depth && dmax > tol_depth) {
                        // The faces cross in space: split them together.
                        int ra = ori__uf_root(group, fa), rb = ori__uf_root(group, fb);
                        if (ra != rb) group[ra < rb ? rb : ra] = ra < rb ? ra : rb;
                        continue;
                    }
                    if (dq > tol_depth) edge_push(&edges, fa, fb);       // A farther: A first
                    else if (dq < -tol_depth) edge_push(&edges, fb, fa); // B farther
                    else {
                        // One plane: faceOrders when they order the pair, else the lower layer (as
                        // seen from the eye) first.
                        int by_orders = listed_order(&listed, toward_eye, fa, fb);
                        if (by_orders < 0) {
                            edge_push(&edges, fa, fb);
                            continue;
                        }
                        if (by_orders > 0) {
                            edge_push(&edges, fb, fa);
                            continue;
                        }
                        double ha = ori_v3_dot(layer[fa], toward_eye), hb = ori_v3_dot(layer[fb], toward_eye);
                        if (ha < hb || (ha == hb && fa < fb)) edge_push(&edges, fa, fb);
                        else edge_push(&edges, fb, fa);
                    }
                }
            }
        }
#undef CELL_X
#undef CELL_Y
        ori__free(cstart);
        ori__free(cfill);
        ori__free(ctri);
    }

    // Merge cycles into groups until the graph of groups is acyclic.
    int *gid = ori__alloc(sizeof(int) * (size_t)(nf + 1));
    int ngroups = 0;
    int *comp = ori__alloc(sizeof(int) * (size_t)(nf + 1));
    for (;;) {
        // Number the groups 0..ngroups-1 (in order of their lowest face).
        ngroups = 0;
        for (int f = 0; f < nf; ++f) gid[f] = -1;
        int *root_id = comp; // scratch
        for (int f = 0; f < nf; ++f) root_id[f] = -1;
        for (int f = 0; f < nf; ++f) {
            int r = ori__uf_root(group, f);
            if (root_id[r] < 0) root_id[r] = ngroups++;
            gid[f] = root_id[r];
        }
        edge_list ge = {NULL, 0, 0};
        for (int i = 0; i < edges.count; ++i) {
            int a = gid[edges.e[i][0]], b = gid[edges.e[i][1]];
            if (a != b) edge_push(&ge, a, b);
        }
        int *st, *adj;
        adjacency(ngroups, &ge, &st, &adj);
        int *gcomp = ori__alloc(sizeof(int) * (size_t)(ngroups + 1));
        int nc = tarjan(ngroups, st, adj, gcomp);
        bool merged = false;
        if (nc < ngroups) {
            // Merge each component's groups: map a component to its first face's root.
            int *first = ori__alloc(sizeof(int) * (size_t)(nc + 1));
            for (int c = 0; c < nc; ++c) first[c] = -1;
            for (int f = 0; f < nf; ++f) {
                int c = gcomp[gid[f]];
                int r = ori__uf_root(group, f);
                if (first[c] < 0) {
                    first[c] = r;
                    continue;
                }
                int a = ori__uf_root(group, first[c]);
                if (a == r) continue;
                if (a < r) group[r] = a;
                else group[a] = r;
                merged = true;
            }
            ori__free(first);
        }
        if (!merged) {
            // Kahn's topological sort of the groups (ties in group order).
            int *indeg = ori__calloc((size_t)ngroups + 1, sizeof(int));
            for (int i = 0; i < ngroups; ++i)
                for (int k = st[i]; k < st[i + 1]; ++k) indeg[adj[k]]++;
            int *queue = ori__alloc(sizeof(int) * (size_t)(ngroups + 1));
            int head = 0, tail = 0;
            for (int i = 0; i < ngroups; ++i)
                if (indeg[i] == 0) queue[tail++] = i;
            while (head < tail) {
                int g = queue[head++];
                for (int k = st[g]; k < st[g + 1]; ++k)
                    if (--indeg[adj[k]] == 0) queue[tail++] = adj[k];
            }
            ORI_ASSERT(tail == ngroups);
            // comp[g] = rank of group g in drawing order.
            for (int i = 0; i < ngroups; ++i) comp[queue[i]] = i;
            ori__free(indeg);
            ori__free(queue);
        }
        ori__free(st);
        ori__free(adj);
        ori__free(gcomp);
        ori__free(ge.e);
        if (!merged) break;
    }

    // Faces of each group, groups in drawing order.
    int *gsize = ori__calloc((size_t)ngroups + 2, sizeof(int));
    for (int f = 0; f < nf; ++f) gsize[comp[gid[f]] + 1]++;
    for (int i = 0; i < ngroups; ++i) gsize[i + 1] += gsize[i];
    int *gface = ori__alloc(sizeof(int) * (size_t)(nf + 1));
    int *gfill = ori__alloc(sizeof(int) * (size_t)(ngroups + 1));
    memcpy(gfill, gsize, sizeof(int) * (size_t)(ngroups + 1));
    for (int f = 0; f < nf; ++f) gface[gfill[comp[gid[f]]]++] = f;

    int piece_cap = 0, point_cap = 0, tag_cap = 0;
    bsp_ctx bc;
    memset(&bc, 0, sizeof bc);
    bc.m = m;
    bc.cam = cam;
    bc.layer = layer;
    bc.toward_eye_world = toward_eye;
    bc.listed = &listed;
    bc.tol = ORI_TOL_RENDER_PLANE_REL * diag;
    for (int g = 0; g < ngroups; ++g) {
        int n = gsize[g + 1] - gsize[g];
        const int *faces = gface + gsize[g];
        if (n == 1) {
            int f = faces[0];
            int s = m->face_start[f], cnt = m->face_start[f + 1] - s;
            // With perspective, a face reaching behind the eye is left out.
            bool behind = false;
            for (int k = 0; k < cnt; ++k) behind |= !(img[m->face_verts[s + k]].z > 0.0);
            if (behind && cam->perspective) continue;
            ORI__RESERVE(o->pieces, piece_cap, o->piece_count + 1);
            o->pieces[o->piece_count].face = f;
            o->pieces[o->piece_count].first = o->point_count;
            o->pieces[o->piece_count].count = cnt;
            o->piece_count++;
            ORI__RESERVE(o->points, point_cap, o->point_count + cnt);
            ORI__RESERVE(o->side_edge, tag_cap, o->point_count + cnt);
            for (int k = 0; k < cnt; ++k) push_point(o, img[m->face_verts[s + k]], m->face_side_edge[s + k]);
            continue;
        }
        // Split the group: its triangles in view coordinates, each side tagged with its edge.
        o->groups_split++;
        int ntri = 0;
        for (int i = 0; i < n; ++i) ntri += m->face_tri_start[faces[i] + 1] - m->face_tri_start[faces[i]];
        bsp_poly *polys = ori__alloc(sizeof(bsp_poly) * (size_t)(ntri + 1));
        int np = 0;
        for (int i = 0; i < n; ++i) {
            int f = faces[i];
            for (int t = m->face_tri_start[f]; t < m->face_tri_start[f + 1]; ++t) {
                bsp_poly *bp = &polys[np++];
                bp->face = f;
                bp->n = 3;
                for (int k = 0; k < 3; ++k) {
                    int v = m->tris[t].v[k], w = m->tris[t].v[(k + 1) % 3];
                    bp->p[k] = ori_m3_apply(cam->rotation, ori_v3_sub(m->pos[v], cam->target));
                    // A triangle side is a face side (tag its edge) or a diagonal (-1).
                    int tag = -1;
                    for (int j = m->face_start[f]; j < m->face_start[f + 1]; ++j) {
                        int nj = j + 1 == m->face_start[f + 1] ? m->face_start[f] : j + 1;
                        if (m->face_verts[j] == v && m->face_verts[nj] == w) tag = m->face_side_edge[j];
                    }
                    bp->tag[k] = tag;
                }
            }
        }
        bc.out_count = 0;
        bsp(&bc, polys, np);
        ori__free(polys);
        for (int i = 0; i < bc.out_count; ++i) {
            const bsp_poly *bp = &bc.out[i];
            ORI__RESERVE(o->pieces, piece_cap, o->piece_count + 1);
            o->pieces[o->piece_count].face = bp->face;
            o->pieces[o->piece_count].first = o->point_count;
            o->pieces[o->piece_count].count = bp->n;
            o->piece_count++;
            o->fragments++;
            ORI__RESERVE(o->points, point_cap, o->point_count + bp->n);
            ORI__RESERVE(o->side_edge, tag_cap, o->point_count + bp->n);
            for (int k = 0; k < bp->n; ++k) push_point(o, view_to_image(cam, bp->p[k]), bp->tag[k]);
        }
    }
    ori__free(bc.out);
    ori__free(gsize);
    ori__free(gface);
    ori__free(gfill);
    ori__free(gid);
    ori__free(comp);
    ori__free(group);
    ori__free(edges.e);
    ori__free(layer);
    listed_free(&listed);
    ori__free(ti);
    ori__free(img);
}

void ori__order_free(ori__order *o)
{
    ori__free(o->pieces);
    ori__free(o->points);
    ori__free(o->side_edge);
    memset(o, 0, sizeof *o);
}
