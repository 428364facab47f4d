// Carpenter's rule by Streinu's pointed pseudo-triangulations (thesis ch. 6; I. Streinu,
// "Pseudo-triangulations, rigidity and motion planning", DCG 2005). The bars are completed to
// a pointed pseudo-triangulation (PPT: a maximal planar graph in which every vertex has an angle
// larger than π), a convex-hull edge that is not a bar is removed (the drive, chosen by looking
// ahead so that its motion does not meet an event at once) and the remaining framework has a
// one-degree-of-freedom motion that is expansive (no distance decreases). The motion is followed
// by predictor–corrector continuation (its direction: the drive lengthens; the tangent from the
// square rigidity system, KLU sparse LU; the curve parametrised by its fastest coordinate; the
// step from the velocity field, no edge turning more than 0.1 rad; chord-Newton projection onto
// every edge length) until the reflex angle of some vertex reaches π (root-finding on its sine,
// bracket 1e-12 of the size in arc length). Then the two aligned edges are both bars (the joint
// is straight: it stays straight, the two bars become one) or one of them is not a bar: it is
// removed and the graph completed again (the flip), decided where the angle is 1e-7 past π.
// Every combinatorial decision uses the exact orientation predicate with Simulation of
// Simplicity, so collinear inputs need no special case.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <orikin/tolerance.h>
#include <orikin/unfold.h>

#include "../core/core_internal.h"
#include "../core/suitesparse.h"

#include "unfold_internal.h"

struct ori_linkage_motion {
    int n;
    ori_linkage_result result;
    ori_v2 *frames; // frame_count × n
    bool *is_event;
    int frame_count, frame_cap;
};

ori_linkage_def ori_default_linkage_def(void)
{
    ori_linkage_def d;
    memset(&d, 0, sizeof d);
    d.steps_per_event = 8;
    d.internal_value = ORI__DEF_COOKIE;
    return d;
}

// --- state --------------------------------------------------------------------------------

typedef struct lk_edge {
    int a, b;
    bool bar;
    double len;
} lk_edge;

typedef struct lk {
    int n;
    ori_v2 *p;
    bool closed;
    double scale;
    // frozen (straightened) vertices: position a + t (b − a), evaluated latest first
    bool *frozen;
    int *fa, *fb, *forder, nfrozen;
    double *ft;
    // edges of the pseudo-triangulation (bars included), the drive edge apart
    lk_edge *e;
    int ne, ecap;
    int drv_a, drv_b; // removed hull edge (−1 when none)
    int prev_a, prev_b; // the drive before the last event (−1 when none)
    ori_v2 *sd, *se;    // symbolic perturbation directions (see orient)
    // adjacency (rebuilt on demand): CSR sorted counter-clockwise
    int *adj_start, *adj, adj_cap;
} lk;

static int active_count(const lk *L) { return L->n - L->nfrozen; }

// Orientation of three vertices, exact, with ties broken by Simulation of Simplicity: vertex i is
// perturbed by ε sd[i] + ε² se[i]. sd is the cubic expansion (p − c)|p − c|² about the input's
// centroid c, which moves a vertex lying between two others on a line not through c to the side
// of c (a point exactly on a hull edge falls inside; a notch tip on a diagonal goes inward); se
// = (i, i²), points of a parabola (never collinear), decides the rest. So no three vertices are
// collinear for the combinatorics (a zig-zag with its lower points on one line, a vertex exactly
// on a diagonal). Along the motion exact ties do not occur; they do in inputs.
static int orient(const lk *L, int a, int b, int c)
{
    ori_v2 d[3] = {L->sd[a], L->sd[b], L->sd[c]}, e[3] = {L->se[a], L->se[b], L->se[c]};
    return ori__orient2d_perturbed(L->p[a], L->p[b], L->p[c], d, e);
}

// Segments a–b and c–d (four distinct vertices) cross, under the same perturbation.
static bool cross_sos(const lk *L, int a, int b, int c, int d)
{
    return orient(L, a, b, c) * orient(L, a, b, d) < 0 && orient(L, c, d, a) * orient(L, c, d, b) < 0;
}

// Sign of coordinate k (0 x, 1 y) of vertex q minus that of c, under the perturbation of orient:
// the values, then the ε and ε² directions, compared in turn (exact comparisons of doubles).
static int coord_cmp(const lk *L, int c, int q, int k)
{
    double a[3] = {k ? L->p[q].y : L->p[q].x, k ? L->sd[q].y : L->sd[q].x, k ? L->se[q].y : L->se[q].x};
    double b[3] = {k ? L->p[c].y : L->p[c].x, k ? L->sd[c].y : L->sd[c].x, k ? L->se[c].y : L->se[c].x};
    for (int i = 0; i < 3; ++i)
        if (a[i] != b[i]) return a[i] > b[i] ? 1 : -1;
    return 0;
}

// Angular order around centre c: half-plane first (above, or on the line to the right: 0), then
// orientation; both under the perturbation, so that the order is that of the perturbed points.
static int half_of(const lk *L, int c, int q)
{
    int y = coord_cmp(L, c, q, 1);
    return (y > 0 || (y == 0 && coord_cmp(L, c, q, 0) > 0)) ? 0 : 1;
}

static _Thread_local const lk *g_sort_lk; // qsort has no context argument
static _Thread_local int g_sort_centre;
static int cmp_angle(const void *x, const void *y)
{
    int a = *(const int *)x, b = *(const int *)y;
    int ha = half_of(g_sort_lk, g_sort_centre, a), hb = half_of(g_sort_lk, g_sort_centre, b);
    if (ha != hb) return ha - hb;
    int o = orient(g_sort_lk, g_sort_centre, a, b);
    return o > 0 ? -1 : o < 0 ? 1 : (a - b);
}

static void sort_around(const lk *L, int c, int *nb, int k)
{
    g_sort_lk = L;
    g_sort_centre = c;
    qsort(nb, (size_t)k, sizeof *nb, cmp_angle);
}

static void build_adj(lk *L, bool with_drive)
{
    int n = L->n;
    int *deg = ori__calloc((size_t)n + 1, sizeof *deg);
    int m = L->ne + (with_drive && L->drv_a >= 0 ? 1 : 0);
    for (int k = 0; k < L->ne; ++k) deg[L->e[k].a]++, deg[L->e[k].b]++;
    if (m > L->ne) deg[L->drv_a]++, deg[L->drv_b]++;
    ORI__RESERVE(L->adj, L->adj_cap, 2 * m + 1);
    if (!L->adj_start) L->adj_start = ori__alloc(((size_t)n + 1) * sizeof *L->adj_start);
    L->adj_start[0] = 0;
    for (int v = 0; v < n; ++v) L->adj_start[v + 1] = L->adj_start[v] + deg[v];
    for (int v = 0; v < n; ++v) deg[v] = L->adj_start[v];
    for (int k = 0; k < L->ne; ++k) {
        L->adj[deg[L->e[k].a]++] = L->e[k].b;
        L->adj[deg[L->e[k].b]++] = L->e[k].a;
    }
    if (m > L->ne) {
        L->adj[deg[L->drv_a]++] = L->drv_b;
        L->adj[deg[L->drv_b]++] = L->drv_a;
    }
    for (int v = 0; v < n; ++v) sort_around(L, v, L->adj + L->adj_start[v], L->adj_start[v + 1] - L->adj_start[v]);
    ori__free(deg);
}

static int find_edge(const lk *L, int a, int b)
{
    for (int k = 0; k < L->ne; ++k)
        if ((L->e[k].a == a && L->e[k].b == b) || (L->e[k].a == b && L->e[k].b == a)) return k;
    return -1;
}

static void add_edge(lk *L, int a, int b, bool bar, double len)
{
    lk_edge x = {a, b, bar, len};
    ORI__PUSH(L->e, L->ne, L->ecap, x);
}

static void remove_edge(lk *L, int k) { L->e[k] = L->e[--L->ne]; }

// Pointed: some angle between consecutive neighbours exceeds π (strictly), or degree ≤ 1.
static bool pointed_list(const lk *L, int v, const int *nb, int k)
{
    if (k <= 1) return true;
    for (int i = 0; i < k; ++i)
        if (orient(L, v, nb[i], nb[(i + 1) % k]) < 0) return true;
    return false;
}

// Reflex wedge of v in the current adjacency: consecutive (a, b) with orient(v, a, b) < 0.
static bool reflex_wedge(const lk *L, int v, int *wa, int *wb)
{
    const int *nb = L->adj + L->adj_start[v];
    int k = L->adj_start[v + 1] - L->adj_start[v];
    for (int i = 0; i < k; ++i)
        if (orient(L, v, nb[i], nb[(i + 1) % k]) < 0) {
            *wa = nb[i], *wb = nb[(i + 1) % k];
            return true;
        }
    return false;
}

// The wedge closest to π at a non-pointed vertex (smallest positive sine).
static void flattest_wedge(const lk *L, int v, int *wa, int *wb)
{
    const int *nb = L->adj + L->adj_start[v];
    int k = L->adj_start[v + 1] - L->adj_start[v];
    double best = INFINITY;
    for (int i = 0; i < k; ++i) {
        int a = nb[i], b = nb[(i + 1) % k];
        ori_v2 da = ori_v2_sub(L->p[a], L->p[v]), db = ori_v2_sub(L->p[b], L->p[v]);
        double s = ori_v2_cross(da, db) / (ori_v2_norm(da) * ori_v2_norm(db));
        if (ori_v2_dot(da, db) < 0.0 && fabs(s) < best) best = fabs(s), *wa = a, *wb = b;
    }
    if (!isfinite(best)) *wa = nb[0], *wb = nb[1 % k];
}

// Candidate edge a–b: touches no edge except at a or b, no vertex on it, pointed at both ends.
static bool candidate_ok(const lk *L, int a, int b)
{
    for (int k = 0; k < L->ne; ++k) {
        int c = L->e[k].a, d = L->e[k].b;
        if ((c == a && d == b) || (c == b && d == a)) return false;
        bool sa = c == a || d == a, sb = c == b || d == b;
        if (sa || sb) {
            int other = (c == a || c == b) ? d : c, shared = (c == a || c == b) ? c : d;
            int far = shared == a ? b : a;
            // collinear overlap of two edges from the shared vertex
            if (orient(L, shared, far, other) == 0) {
                ori_v2 u = ori_v2_sub(L->p[far], L->p[shared]), w = ori_v2_sub(L->p[other], L->p[shared]);
                if (ori_v2_dot(u, w) > 0.0) return false;
            }
            continue;
        }
        if (cross_sos(L, a, b, c, d)) return false;
    }
    if (L->drv_a >= 0) {
        int c = L->drv_a, d = L->drv_b;
        if (!(c == a || d == a || c == b || d == b) && cross_sos(L, a, b, c, d)) return false;
    }
    int tmp[512];
    for (int end = 0; end < 2; ++end) {
        int v = end ? b : a, o = end ? a : b;
        int k = L->adj_start[v + 1] - L->adj_start[v];
        int *nb = k + 1 <= 512 ? tmp : ori__alloc(((size_t)k + 1) * sizeof *nb);
        memcpy(nb, L->adj + L->adj_start[v], (size_t)k * sizeof *nb);
        nb[k] = o;
        sort_around(L, v, nb, k + 1);
        bool ok = pointed_list(L, v, nb, k + 1);
        if (nb != tmp) ori__free(nb);
        if (!ok) return false;
    }
    return true;
}

// Faces of the planar graph (adjacency built): half-edge u→w is followed by w→x with x the
// neighbour of w just before u counter-clockwise. Returns the faces as vertex cycles.
typedef struct lk_faces {
    int *start, *v, count;
    double *area;
} lk_faces;

static int adj_index(const lk *L, int v, int w)
{
    for (int i = L->adj_start[v]; i < L->adj_start[v + 1]; ++i)
        if (L->adj[i] == w) return i;
    return -1;
}

static lk_faces trace_faces(const lk *L)
{
    int h = L->adj_start[L->n];
    bool *used = ori__calloc((size_t)h + 1, 1);
    lk_faces F = {ori__alloc(((size_t)h + 2) * sizeof(int)), ori__alloc(((size_t)h + 1) * sizeof(int)), 0,
                  ori__alloc(((size_t)h + 1) * sizeof(double))};
    int nv = 0;
    F.start[0] = 0;
    for (int u0 = 0; u0 < L->n; ++u0)
        for (int i0 = L->adj_start[u0]; i0 < L->adj_start[u0 + 1]; ++i0) {
            if (used[i0]) continue;
            int u = u0, i = i0;
            double area = 0.0;
            while (!used[i]) {
                used[i] = true;
                int w = L->adj[i];
                F.v[nv++] = u;
                area += ori_v2_cross(L->p[u], L->p[w]);
                int j = adj_index(L, w, u);
                int k = L->adj_start[w + 1] - L->adj_start[w];
                int prev = L->adj_start[w] + ((j - L->adj_start[w]) + k - 1) % k;
                u = w;
                i = prev;
            }
            F.area[F.count] = 0.5 * area;
            F.start[++F.count] = nv;
        }
    ori__free(used);
    return F;
}

static void faces_free(lk_faces *F) { ori__free(F->start), ori__free(F->v), ori__free(F->area); }

// Complete the graph to a pointed pseudo-triangulation: add valid edges inside the inner faces
// that have more than three convex corners, shortest gaps first. excl_a–excl_b is never added.
static int hull(const lk *L, int *out);

// Smallest angle (as 1 − cos, monotone) between edge a–b and the edges at a and at b.
static double edge_clearance(const lk *L, int a, int b)
{
    double worst = 2.0;
    for (int end = 0; end < 2; ++end) {
        int v = end ? b : a, o = end ? a : b;
        ori_v2 d = ori_v2_normalize(ori_v2_sub(L->p[o], L->p[v]));
        for (int i = L->adj_start[v]; i < L->adj_start[v + 1]; ++i) {
            ori_v2 e = ori_v2_normalize(ori_v2_sub(L->p[L->adj[i]], L->p[v]));
            worst = fmin(worst, 1.0 - ori_v2_dot(d, e));
        }
    }
    return worst;
}

static ori_status complete(lk *L, int excl_a, int excl_b, ori_error *error)
{
    int *h = ori__alloc(((size_t)L->n + 1) * 2 * sizeof *h);
    int hk = hull(L, h);
    build_adj(L, false);
    for (int i = 0; i < hk; ++i) {
        int a = h[i], b = h[(i + 1) % hk];
        // a hull edge is in every pseudo-triangulation, even the one just removed at an event
        // whose vertex stayed on the hull (a chain end swinging through the line of the edge)
        if (find_edge(L, a, b) < 0 && candidate_ok(L, a, b)) {
            add_edge(L, a, b, false, ori_v2_norm(ori_v2_sub(L->p[a], L->p[b])));
            build_adj(L, false);
        }
    }
    ori__free(h);
    for (;;) {
        build_adj(L, false);
        lk_faces F = trace_faces(L);
        int outer = 0;
        for (int f = 1; f < F.count; ++f)
            if (F.area[f] < F.area[outer]) outer = f;
        bool added = false, bad = false;
        for (int f = 0; f < F.count && !added; ++f) {
            if (f == outer) continue;
            int s = F.start[f], k = F.start[f + 1] - s;
            int convex = 0;
            for (int i = 0; i < k; ++i)
                if (orient(L, F.v[s + (i + k - 1) % k], F.v[s + i], F.v[s + (i + 1) % k]) >= 0) convex++;
            if (convex <= 3) continue;
            bad = true;
            // Among the first valid candidates take the best conditioned: the largest of the
            // smallest angles the new edge makes with the edges at its ends (near an event a valid
            // but almost degenerate diagonal would leave a sliver and a singular framework).
            int best_a = -1, best_b = -1, found = 0;
            double best_score = -1.0;
            for (int gap = 2; gap <= k / 2 + 1 && found < 32; ++gap)
                for (int i = 0; i < k && found < 32; ++i) {
                    int a = F.v[s + i], b = F.v[s + (i + gap) % k];
                    if (a == b) continue;
                    if ((a == excl_a && b == excl_b) || (a == excl_b && b == excl_a)) continue;
                    if ((a == best_a && b == best_b) || (a == best_b && b == best_a)) continue;
                    if (find_edge(L, a, b) >= 0) continue;
                    if (!candidate_ok(L, a, b)) continue;
                    found++;
                    double score = edge_clearance(L, a, b);
                    if (score > best_score) best_score = score, best_a = a, best_b = b;
                }
            if (best_a >= 0) {
                add_edge(L, best_a, best_b, false, ori_v2_norm(ori_v2_sub(L->p[best_a], L->p[best_b])));
                added = true;
            }
        }
        if (!added && !bad) {
            faces_free(&F);
            return ORI_OK;
        }
        if (!added) {
            faces_free(&F);
            return ori__fail(error, ORI_ERR_INTERNAL, "pseudo-triangulation: no edge completes a face");
        }
        faces_free(&F);
    }
}

// Convex hull of the active vertices (exact, collinear points dropped), counter-clockwise.
static _Thread_local const lk *g_hull_lk;
static int cmp_xy(const void *x, const void *y)
{
    // lexicographic on the perturbed coordinates (consistent with orient)
    int a = *(const int *)x, b = *(const int *)y;
    int c = coord_cmp(g_hull_lk, b, a, 0);
    return c ? c : coord_cmp(g_hull_lk, b, a, 1);
}

static int hull(const lk *L, int *out)
{
    int m = 0;
    int *pts = ori__alloc((size_t)L->n * sizeof *pts);
    for (int v = 0; v < L->n; ++v)
        if (!L->frozen[v]) pts[m++] = v;
    g_hull_lk = L;
    qsort(pts, (size_t)m, sizeof *pts, cmp_xy);
    int h = 0;
    for (int i = 0; i < m; ++i) {
        while (h >= 2 && orient(L, out[h - 2], out[h - 1], pts[i]) <= 0) h--;
        out[h++] = pts[i];
    }
    for (int i = m - 2, lo = h + 1; i >= 0; --i) {
        while (h >= lo && orient(L, out[h - 2], out[h - 1], pts[i]) <= 0) h--;
        out[h++] = pts[i];
    }
    ori__free(pts);
    return h - 1;
}

static void place_frozen(lk *L, ori_v2 *p)
{
    for (int i = L->nfrozen - 1; i >= 0; --i) {
        int v = L->forder[i];
        ori_v2 a = p[L->fa[v]], b = p[L->fb[v]];
        p[v] = ori_v2_add(a, ori_v2_scale(ori_v2_sub(b, a), L->ft[v]));
    }
}

// --- the rigidity system ------------------------------------------------------------------

// Rows: one per edge (2 v·Δp = 0 for lengths), one "parameter" row, three pins (vertex pin0
// fixed, pin1 not rotating about it). The parameter row is either the drive edge (its length
// grows at unit rate: the expansive direction) or a single coordinate kcol held (local
// parametrisation of the curve by its fastest-moving coordinate, regular where the drive length
// is stationary).
typedef struct lk_sys {
    int na;   // active vertices
    int *col; // vertex → active index (−1 frozen)
    int rows; // ne + 1 + 3
    int pin0, pin1;
    int kcol; // −1: drive row; else the held unknown
    int *colptr, *rowind; // Jᵀ in compressed columns (column = equation)
    double *x;            // its values
    klu_common kc;
    klu_symbolic *sym;
    klu_numeric *num;
} lk_sys;

static void sys_create(const lk *L, lk_sys *S, int kcol)
{
    S->col = ori__alloc((size_t)L->n * sizeof *S->col);
    S->na = 0;
    for (int v = 0; v < L->n; ++v) S->col[v] = L->frozen[v] ? -1 : S->na++;
    S->rows = L->ne + 1 + 3;
    S->kcol = kcol;
    // pins: an edge away from the drive when there is one
    int pe = 0;
    for (int k = 0; k < L->ne; ++k)
        if (L->e[k].a != L->drv_a && L->e[k].a != L->drv_b && L->e[k].b != L->drv_a && L->e[k].b != L->drv_b) {
            pe = k;
            break;
        }
    S->pin0 = L->e[pe].a, S->pin1 = L->e[pe].b;
    if (S->pin0 == L->drv_a || S->pin0 == L->drv_b) S->pin0 = L->e[pe].b, S->pin1 = L->e[pe].a;
    S->colptr = ori__alloc(((size_t)S->rows + 1) * sizeof *S->colptr);
    S->rowind = ori__alloc((size_t)(4 * (L->ne + 1) + 4) * sizeof *S->rowind);
    int nz = 0, r = 0;
    for (int k = 0; k <= L->ne; ++k) {
        S->colptr[r++] = nz;
        if (k == L->ne && kcol >= 0) {
            S->rowind[nz++] = kcol;
            continue;
        }
        int a = k < L->ne ? L->e[k].a : L->drv_a, b = k < L->ne ? L->e[k].b : L->drv_b;
        int ca = S->col[a], cb = S->col[b];
        int lo = ca < cb ? ca : cb, hi = ca < cb ? cb : ca;
        S->rowind[nz++] = 2 * lo, S->rowind[nz++] = 2 * lo + 1, S->rowind[nz++] = 2 * hi, S->rowind[nz++] = 2 * hi + 1;
    }
    int c0 = S->col[S->pin0], c1 = S->col[S->pin1];
    S->colptr[r++] = nz, S->rowind[nz++] = 2 * c0;
    S->colptr[r++] = nz, S->rowind[nz++] = 2 * c0 + 1;
    S->colptr[r++] = nz, S->rowind[nz++] = 2 * c1, S->rowind[nz++] = 2 * c1 + 1;
    S->colptr[r] = nz;
    S->x = ori__alloc(((size_t)nz + 1) * sizeof *S->x);
    ori__klu_start(&S->kc);
    S->sym = klu_analyze(S->rows, S->colptr, S->rowind, &S->kc);
    S->num = NULL;
}

static void sys_destroy(lk_sys *S)
{
    if (S->num) klu_free_numeric(&S->num, &S->kc);
    if (S->sym) klu_free_symbolic(&S->sym, &S->kc);
    ori__free(S->col), ori__free(S->colptr), ori__free(S->rowind), ori__free(S->x);
    memset(S, 0, sizeof *S);
}

static bool sys_factor(const lk *L, lk_sys *S, const ori_v2 *p)
{
    double *x = S->x;
    int nz = 0;
    for (int k = 0; k <= L->ne; ++k) {
        if (k == L->ne && S->kcol >= 0) {
            x[nz++] = 1.0;
            continue;
        }
        int a = k < L->ne ? L->e[k].a : L->drv_a, b = k < L->ne ? L->e[k].b : L->drv_b;
        if (S->col[a] > S->col[b]) {
            int t = a;
            a = b, b = t;
        }
        ori_v2 d = ori_v2_sub(p[a], p[b]);
        x[nz++] = d.x, x[nz++] = d.y, x[nz++] = -d.x, x[nz++] = -d.y;
    }
    ori_v2 r = ori_v2_sub(p[S->pin1], p[S->pin0]);
    x[nz++] = 1.0, x[nz++] = 1.0, x[nz++] = -r.y, x[nz++] = r.x;
    if (!S->sym) return false;
    if (S->num) klu_free_numeric(&S->num, &S->kc);
    S->num = klu_factor(S->colptr, S->rowind, S->x, S->sym, &S->kc);
    return S->num != NULL && S->kc.status == KLU_OK;
}

// Solve J x = b (square): KLU factors Jᵀ (sparse LU with partial pivoting), its transposed
// solve gives J x = b. False when the factor is singular or the solution not finite.
static bool sys_solve(lk_sys *S, const double *b, double *out, double *w1, double *w2)
{
    (void)w1, (void)w2;
    int n = S->rows;
    for (int i = 0; i < n; ++i) out[i] = b[i];
    if (!klu_tsolve(S->sym, S->num, n, 1, out, &S->kc)) return false;
    for (int i = 0; i < n; ++i)
        if (!isfinite(out[i])) return false;
    return true;
}

// --- the motion ---------------------------------------------------------------------------

typedef struct lk_run {
    lk *L;
    lk_sys S;
    double *rhs, *sol, *w1, *w2;
    ori_linkage_motion *M;
    int per;          // frames kept per event interval (0 = all)
    ori_v2 *buf;      // steps of the current interval, every stride-th (per > 0)
    int buf_count, buf_cap, stride, skipped;
    ori_progress_fn *progress; // per event, may be NULL
    void *progress_user;
    int end_a, end_b;          // a chain's ends (−1 for a polygon) and
    double total;              // its total bar length: progress is their distance over it
    double fraction;           // reported so far (monotone)
    bool cancelled;            // the progress callback returned false
} lk_run;

// Progress at an event: for a chain the distance of its ends over its length (every distance
// grows along an expansive motion; 1 when straight), for a polygon the share of the event budget.
static bool report_progress(lk_run *R, int max_events)
{
    if (!R->progress) return true;
    double f = (double)R->M->result.events / max_events;
    if (R->end_a >= 0 && R->total > 0.0) f = ori_v2_norm(ori_v2_sub(R->L->p[R->end_b], R->L->p[R->end_a])) / R->total;
    f = fmin(fmax(f, R->fraction), 1.0);
    R->fraction = f;
    if (R->progress(f, R->progress_user)) return true;
    R->cancelled = true;
    return false;
}

static void append_frame(ori_linkage_motion *M, const ori_v2 *f, bool event)
{
    if (M->frame_count == M->frame_cap) {
        M->frame_cap = M->frame_cap ? 2 * M->frame_cap : 64;
        M->frames = ori__realloc(M->frames, (size_t)M->frame_cap * (size_t)M->n * sizeof *M->frames);
        M->is_event = ori__realloc(M->is_event, (size_t)M->frame_cap * sizeof *M->is_event);
    }
    memcpy(M->frames + (size_t)M->frame_count * (size_t)M->n, f, (size_t)M->n * sizeof *f);
    M->is_event[M->frame_count++] = event;
}

// Record a configuration. With per > 0 the steps of an interval go to a buffer thinned by
// doubling its stride (memory stays bounded however many steps an interval takes); a kept
// frame (the start, an event) flushes per − 1 of them evenly spaced, then itself.
static void push_frame(lk_run *R, const ori_v2 *p, bool keep, bool event)
{
    ori_linkage_motion *M = R->M;
    int n = M->n;
    ori_v2 *f = ori__alloc((size_t)n * sizeof *f);
    memcpy(f, p, (size_t)n * sizeof *f);
    place_frozen(R->L, f);
    if (R->per == 0) {
        append_frame(M, f, event);
    } else if (!keep) {
        if (++R->skipped >= R->stride) {
            R->skipped = 0;
            if (R->buf_count == R->buf_cap) {
                // thin: keep every other buffered frame, double the stride
                for (int i = 0; 2 * i < R->buf_count; ++i)
                    memmove(R->buf + (size_t)i * n, R->buf + (size_t)(2 * i) * n, (size_t)n * sizeof *R->buf);
                R->buf_count = (R->buf_count + 1) / 2;
                R->stride *= 2;
            }
            memcpy(R->buf + (size_t)R->buf_count * n, f, (size_t)n * sizeof *f);
            R->buf_count++;
        }
    } else {
        for (int j = 1; j < R->per && R->buf_count > 0; ++j) {
            int src = (int)((double)R->buf_count * j / R->per);
            if (src >= R->buf_count) src = R->buf_count - 1;
            int prev = (int)((double)R->buf_count * (j - 1) / R->per);
            if (j > 1 && src == prev) continue;
            append_frame(M, R->buf + (size_t)src * n, false);
        }
        append_frame(M, f, event);
        R->buf_count = 0, R->stride = 1, R->skipped = 0;
    }
    ori__free(f);
}

// Unit tangent of the motion at p (zero for frozen vertices): the parameter row's rate is 1,
// then normalised; false when the system is singular.
static bool tangent(lk_run *R, const ori_v2 *p, ori_v2 *v)
{
    lk *L = R->L;
    lk_sys *S = &R->S;
    if (!sys_factor(L, S, p)) return false;
    for (int r = 0; r < S->rows; ++r) R->rhs[r] = 0.0;
    R->rhs[L->ne] = 1.0;
    if (!sys_solve(S, R->rhs, R->sol, R->w1, R->w2)) return false;
    double norm = 0.0;
    for (int i = 0; i < 2 * S->na; ++i) norm += R->sol[i] * R->sol[i];
    norm = sqrt(norm);
    if (!(norm > 0.0) || !isfinite(norm)) return false;
    for (int q = 0; q < L->n; ++q) v[q] = ori_v2_make(0.0, 0.0);
    for (int q = 0; q < L->n; ++q)
        if (S->col[q] >= 0) v[q] = ori_v2_make(R->sol[2 * S->col[q]] / norm, R->sol[2 * S->col[q] + 1] / norm);
    return true;
}

// Newton projection of p onto every edge length, the held coordinate and the pins.
static bool project(lk_run *R, ori_v2 *p)
{
    lk *L = R->L;
    lk_sys *S = &R->S;
    double prev = INFINITY;
    // Chord Newton: the Jacobian is factored at the first iterate only and reused (the predictor
    // is close to the curve; convergence stays fast and each iteration costs a solve, not a factor).
    for (int it = 0; it < 24; ++it) {
        double worst = 0.0;
        for (int k = 0; k < L->ne; ++k) {
            ori_v2 d = ori_v2_sub(p[L->e[k].a], p[L->e[k].b]);
            double len = L->e[k].len;
            double f = 0.5 * (ori_v2_dot(d, d) - len * len);
            R->rhs[k] = -f;
            // relative length error; for bars much shorter than the linkage, relative to 1% of
            // its size (the rounding of coordinates of that size)
            worst = fmax(worst, fabs(f) / (len * fmax(len, 1e-2 * L->scale)));
        }
        R->rhs[L->ne] = R->rhs[L->ne + 1] = R->rhs[L->ne + 2] = R->rhs[L->ne + 3] = 0.0;
        if (worst <= ORI_TOL_LINKAGE_NEWTON || (worst <= ORI_TOL_LINKAGE_NEWTON_FLOOR && worst > 0.5 * prev)) return true;
        prev = worst;
        if (!isfinite(worst) || worst > 1e-2) {
            return false;
        }
        if (it == 0 && !sys_factor(L, S, p)) {
            return false;
        }
        if (!sys_solve(S, R->rhs, R->sol, R->w1, R->w2)) return false;
        for (int q = 0; q < L->n; ++q)
            if (S->col[q] >= 0) p[q].x += R->sol[2 * S->col[q]], p[q].y += R->sol[2 * S->col[q] + 1];
    }
    return false;
}

// Monitored wedges: per active vertex its reflex wedge.
typedef struct lk_watch {
    int v, a, b;
} lk_watch;

static double wedge_sine(const ori_v2 *p, lk_watch w)
{
    ori_v2 da = ori_v2_sub(p[w.a], p[w.v]), db = ori_v2_sub(p[w.b], p[w.v]);
    return ori_v2_cross(da, db) / (ori_v2_norm(da) * ori_v2_norm(db));
}

// The configuration a distance s along tangent t0 from p0, projected.
static bool state_at(lk_run *R, const ori_v2 *p0, const ori_v2 *t0, double s, ori_v2 *out)
{
    int n = R->L->n;
    for (int q = 0; q < n; ++q) out[q] = ori_v2_add(p0[q], ori_v2_scale(t0[q], s));
    return project(R, out);
}

// Rate of change of wedge_sine along the tangent t (per unit arc length).
static double wedge_rate(const ori_v2 *p, const ori_v2 *t, lk_watch w)
{
    ori_v2 u = ori_v2_sub(p[w.a], p[w.v]), x = ori_v2_sub(p[w.b], p[w.v]);
    ori_v2 du = ori_v2_sub(t[w.a], t[w.v]), dx = ori_v2_sub(t[w.b], t[w.v]);
    double nu = ori_v2_norm(u), nx = ori_v2_norm(x), g = ori_v2_cross(u, x) / (nu * nx);
    double dc = ori_v2_cross(du, x) + ori_v2_cross(u, dx);
    return dc / (nu * nx) - g * (ori_v2_dot(u, du) / (nu * nu) + ori_v2_dot(x, dx) / (nx * nx));
}

// Choose the drive among the hull edges of the graph that are not bars (the previous drive
// first when it still is one, then the longest): any of them leaves an expansive mechanism, but
// right after a flip some would meet an event at once (a flat pseudo-triangle straightened by
// lengthening its long side) and flip back, a cycle. Each candidate's motion is looked ahead:
// the first whose nearest event (the reflex sines' linear extrapolation) is not immediate is
// taken, else the one whose event is farthest. False when every hull edge is a bar.
static bool pick_drive(lk_run *R, int prev_a, int prev_b)
{
    lk *L = R->L;
    int n = L->n;
    int *h = ori__alloc(((size_t)n + 1) * 2 * sizeof *h);
    int hk = hull(L, h);
    int cand[8], nc = 0;
    double clen[8];
    for (int i = 0; i < hk; ++i) {
        int e = find_edge(L, h[i], h[(i + 1) % hk]);
        if (e < 0 || L->e[e].bar) continue;
        bool prev = (L->e[e].a == prev_a && L->e[e].b == prev_b) || (L->e[e].a == prev_b && L->e[e].b == prev_a);
        double key = prev ? INFINITY : L->e[e].len;
        int pos = nc < 8 ? nc++ : 8;
        while (pos > 0 && clen[pos - 1] < key) {
            if (pos < 8) cand[pos] = cand[pos - 1], clen[pos] = clen[pos - 1];
            pos--;
        }
        if (pos < 8) cand[pos] = e, clen[pos] = key;
    }
    ori__free(h);
    L->drv_a = L->drv_b = -1;
    if (nc == 0) return false;
    int ca[8], cb[8];
    for (int i = 0; i < nc; ++i) ca[i] = L->e[cand[i]].a, cb[i] = L->e[cand[i]].b;
    ori_v2 *t = ori__alloc((size_t)n * sizeof *t);
    int best = 0;
    double best_score = -1.0, enough = ORI_TOL_LINKAGE_DRIVE_AHEAD_REL * L->scale;
    for (int i = 0; i < nc && nc > 1; ++i) {
        int e = find_edge(L, ca[i], cb[i]);
        remove_edge(L, e);
        L->drv_a = ca[i], L->drv_b = cb[i];
        build_adj(L, false);
        double score = INFINITY;
        lk_sys S0 = R->S;
        memset(&R->S, 0, sizeof R->S);
        sys_create(L, &R->S, -1);
        if (tangent(R, L->p, t)) {
            for (int v = 0; v < n; ++v) {
                lk_watch w = {v, -1, -1};
                if (L->frozen[v] || !reflex_wedge(L, v, &w.a, &w.b)) continue;
                double g = wedge_sine(L->p, w), r = wedge_rate(L->p, t, w);
                if (g >= 0.0) score = 0.0;
                else if (r > 0.0) score = fmin(score, -g / r);
            }
        } else {
            score = 0.0;
        }
        sys_destroy(&R->S);
        R->S = S0;
        add_edge(L, ca[i], cb[i], false, ori_v2_norm(ori_v2_sub(L->p[ca[i]], L->p[cb[i]])));
        L->drv_a = L->drv_b = -1;
        if (score > best_score) best_score = score, best = i;
        if (score >= enough) break;
    }
    ori__free(t);
    int e = find_edge(L, ca[best], cb[best]);
    L->drv_a = ca[best], L->drv_b = cb[best];
    L->e[e].len = ori_v2_norm(ori_v2_sub(L->p[ca[best]], L->p[cb[best]]));
    remove_edge(L, e);
    return true;
}

// Handle the alignment of edges v–a and v–b at the current positions: straighten (both bars)
// or remove the one that is not a bar.
static void handle_event(lk_run *R, int v, int a, int b)
{
    lk *L = R->L;
    int ea = find_edge(L, v, a), eb = find_edge(L, v, b);
    bool bar_a = ea >= 0 && L->e[ea].bar, bar_b = eb >= 0 && L->e[eb].bar;
    if (bar_a && bar_b) {
        double la = L->e[ea].len, lb = L->e[eb].len;
        L->frozen[v] = true;
        L->fa[v] = a, L->fb[v] = b, L->ft[v] = la / (la + lb);
        L->forder[L->nfrozen++] = v;
        for (int k = L->ne - 1; k >= 0; --k)
            if (L->e[k].a == v || L->e[k].b == v) remove_edge(L, k);
        int ab = find_edge(L, a, b);
        if (ab >= 0) remove_edge(L, ab);
        add_edge(L, a, b, true, la + lb);
        L->p[v] = ori_v2_add(L->p[a], ori_v2_scale(ori_v2_sub(L->p[b], L->p[a]), L->ft[v]));
        R->M->result.straightened++;
    } else {
        int k = (ea >= 0 && !bar_a) ? ea : eb;
        if (k >= 0 && !L->e[k].bar) remove_edge(L, k);
        R->M->result.flips++;
    }
    R->M->result.events++;
}

#ifndef NDEBUG
// Debug check after every restructuring (O(edges²), linkages up to 150 vertices): the graph with the drive is a pointed
// pseudo-triangulation — 2n − 3 edges, no two crossing (exactly, in the real configuration and
// under the perturbation), every active vertex pointed. False names nothing: the caller fails.
static bool ppt_ok(lk *L)
{
    int m = L->ne + (L->drv_a >= 0 ? 1 : 0);
    if (active_count(L) > 2 && m != 2 * active_count(L) - 3) return false;
    for (int i = 0; i <= L->ne; ++i) {
        int a = i < L->ne ? L->e[i].a : L->drv_a, b = i < L->ne ? L->e[i].b : L->drv_b;
        if (a < 0) continue;
        for (int j = i + 1; j <= L->ne; ++j) {
            int c = j < L->ne ? L->e[j].a : L->drv_a, d = j < L->ne ? L->e[j].b : L->drv_b;
            if (c < 0 || a == c || a == d || b == c || b == d) continue;
            if (ori__segments_cross_properly(L->p[a], L->p[b], L->p[c], L->p[d]) || cross_sos(L, a, b, c, d)) return false;
        }
    }
    build_adj(L, true);
    bool ok = true;
    for (int v = 0; v < L->n && ok; ++v)
        if (!L->frozen[v]) ok = pointed_list(L, v, L->adj + L->adj_start[v], L->adj_start[v + 1] - L->adj_start[v]);
    build_adj(L, false);
    return ok;
}
#endif

// Rebuild after an event: settle non-pointed vertices, complete, choose a drive.
// Returns 1 when a drive exists (continue), 0 when done, −1 on failure.
static int restructure(lk_run *R, int excl_a, int excl_b, ori_error *error)
{
    lk *L = R->L;
    int prev_a = L->prev_a, prev_b = L->prev_b;
    L->drv_a = L->drv_b = -1;
    for (int guard = 0; guard < 4 * L->n; ++guard) {
        build_adj(L, false);
        int bad = -1;
        for (int v = 0; v < L->n && bad < 0; ++v) {
            if (L->frozen[v]) continue;
            int k = L->adj_start[v + 1] - L->adj_start[v];
            if (!pointed_list(L, v, L->adj + L->adj_start[v], k)) bad = v;
        }
        if (bad < 0) break;
        int a = -1, b = -1;
        flattest_wedge(L, bad, &a, &b);
        handle_event(R, bad, a, b);
    }
    if (complete(L, excl_a, excl_b, error) != ORI_OK) return -1;
    if (active_count(L) <= 2) return 0;
    if (L->ne != 2 * active_count(L) - 3) {
        ori__fail(error, ORI_ERR_INTERNAL, "pseudo-triangulation has %d edges on %d vertices (points not in general position)",
                  L->ne, active_count(L));
        return -1;
    }
    int more = pick_drive(R, prev_a, prev_b) ? 1 : 0;
#ifndef NDEBUG
    if (L->n <= 150 && !ppt_ok(L)) { // quadratic: checked up to 150 vertices
        ori__fail(error, ORI_ERR_INTERNAL, "pseudo-triangulation not planar or not pointed after event %d",
                  R->M->result.events);
        return -1;
    }
#endif
    return more;
}

static int fastest(const lk *L, const lk_sys *S, const ori_v2 *t)
{
    int best = -1;
    double bv = -1.0;
    for (int q = 0; q < L->n; ++q) {
        if (S->col[q] < 0 || q == S->pin0) continue;
        if (fabs(t[q].x) > bv) bv = fabs(t[q].x), best = 2 * S->col[q];
        if (fabs(t[q].y) > bv) bv = fabs(t[q].y), best = 2 * S->col[q] + 1;
    }
    return best;
}

// The straightest angle between consecutive edges at any vertex (|sin| < 1e-6, the edges
// pointing apart): the event to handle when the framework is singular.
static bool flattest_any(const lk *L, lk_watch *out)
{
    double best = 1e-6;
    bool found = false;
    for (int v = 0; v < L->n; ++v) {
        if (L->frozen[v]) continue;
        const int *nb = L->adj + L->adj_start[v];
        int deg = L->adj_start[v + 1] - L->adj_start[v];
        for (int i = 0; i < deg; ++i) {
            lk_watch cand = {v, nb[i], nb[(i + 1) % deg]};
            ori_v2 da = ori_v2_sub(L->p[cand.a], L->p[v]), db = ori_v2_sub(L->p[cand.b], L->p[v]);
            double sn = fabs(wedge_sine(L->p, cand));
            if (ori_v2_dot(da, db) < 0.0 && sn < best) best = sn, *out = cand, found = true;
        }
    }
    return found;
}

// |t| of unknown k (active index k / 2, component k % 2).
static double coord_of(const lk *L, const lk_sys *S, const ori_v2 *t, int k)
{
    for (int q = 0; q < L->n; ++q)
        if (S->col[q] == k / 2) return fabs(k % 2 ? t[q].y : t[q].x);
    return 0.0;
}

// Adaptive step from the velocity field: the arc length along the unit tangent t over which no
// edge (drive included) turns by more than ORI_LINKAGE_STEP_TURN_RAD to first order, and at
// most ORI_LINKAGE_STEP_MAX_REL of the linkage's size. Far from events the reflex angles need no step limit of
// their own: each decreases monotonically (the motion is expansive), so an event is a single
// sign change of its sine at the step's ends, found by root-finding whatever the step.
static double step_cap(const lk *L, const ori_v2 *t)
{
    double rate = 0.0;
    for (int k = 0; k <= L->ne; ++k) {
        int a = k < L->ne ? L->e[k].a : L->drv_a, b = k < L->ne ? L->e[k].b : L->drv_b;
        if (a < 0) continue;
        double len = ori_v2_norm(ori_v2_sub(L->p[a], L->p[b]));
        rate = fmax(rate, ori_v2_norm(ori_v2_sub(t[a], t[b])) / len);
    }
    double cap = ORI_LINKAGE_STEP_MAX_REL * L->scale;
    return rate > 0.0 ? fmin(cap, ORI_LINKAGE_STEP_TURN_RAD / rate) : cap;
}

static ori_status run_motion(lk_run *R, int max_events, ori_error *error)
{
    lk *L = R->L;
    int n = L->n;
    ori_v2 *t0 = ori__alloc((size_t)n * sizeof *t0), *t1 = ori__alloc((size_t)n * sizeof *t1);
    ori_v2 *p1 = ori__alloc((size_t)n * sizeof *p1);
    ori_v2 *p0 = ori__alloc((size_t)n * sizeof *p0), *pm = ori__alloc((size_t)n * sizeof *pm);
    lk_watch *watch = ori__alloc(((size_t)n + 1) * sizeof *watch);
    ori_status st = ORI_OK;
    push_frame(R, L->p, true, false);
    // Straight joints of the input (two bars exactly opposite) are straight already: freeze them
    // (the perturbed predicate would see them slightly bent).
    for (bool again = true; again && active_count(L) > 2;) {
        again = false;
        for (int v = 0; v < n && !again; ++v) {
            int nb[2], k = 0;
            for (int e = 0; e < L->ne && k <= 2; ++e)
                if (L->e[e].a == v || L->e[e].b == v) {
                    if (k < 2) nb[k] = L->e[e].a == v ? L->e[e].b : L->e[e].a;
                    k++;
                }
            if (L->frozen[v] || k != 2 || ori__orient2d_exact(L->p[nb[0]], L->p[v], L->p[nb[1]]) != 0 ||
                ori_v2_dot(ori_v2_sub(L->p[nb[0]], L->p[v]), ori_v2_sub(L->p[nb[1]], L->p[v])) >= 0.0)
                continue;
            handle_event(R, v, nb[0], nb[1]);
            again = true;
        }
    }
    int rs = restructure(R, -1, -1, error);
    while (rs == 1) {
        if (R->M->result.events >= max_events) { // (more motion to go: the budget is spent)
            st = ori__fail(error, ORI_ERR_LIMIT, "stopped at the limit of %d events", max_events);
            break;
        }
        if (!report_progress(R, max_events)) {
            st = ori__fail(error, ORI_ERR_LIMIT, "cancelled after %d events", R->M->result.events);
            break;
        }
        build_adj(L, false);
        int nw = 0;
        for (int v = 0; v < n; ++v) {
            if (L->frozen[v]) continue;
            int a, b;
            if (reflex_wedge(L, v, &a, &b)) watch[nw++] = (lk_watch){v, a, b};
        }
        // the expansive direction: the drive edge lengthens
        int ev = -1;
        sys_create(L, &R->S, -1);
        if (!tangent(R, L->p, t0)) {
            lk_watch flat;
            if (!flattest_any(L, &flat)) {
                st = ori__fail(error, ORI_ERR_NOT_CONVERGED, "motion: singular rigidity matrix");
                goto done;
            }
            sys_destroy(&R->S);
            watch[nw] = flat;
            ev = nw;
        }
        int k = ev < 0 ? fastest(L, &R->S, t0) : -1;
        if (ev < 0) {
            sys_destroy(&R->S);
            sys_create(L, &R->S, k);
        }
        double h = ev < 0 ? step_cap(L, t0) : 0.0;
        for (int step = 0; ev < 0; ++step) {
            if (step > 1000000) {
                st = ori__fail(error, ORI_ERR_NOT_CONVERGED, "motion: too many steps between events");
                goto done;
            }
            if (step > 0) {
                if (!tangent(R, L->p, t1)) {
                    lk_watch flat;
                    if (!flattest_any(L, &flat)) {
                        st = ori__fail(error, ORI_ERR_NOT_CONVERGED, "motion: singular rigidity matrix");
                        goto done;
                    }
                    watch[nw] = flat;
                    ev = nw;
                    break;
                }
                double dot = 0.0;
                for (int q = 0; q < n; ++q) dot += ori_v2_dot(t0[q], t1[q]);
                if (dot < 0.0)
                    for (int q = 0; q < n; ++q) t1[q] = ori_v2_scale(t1[q], -1.0);
                memcpy(t0, t1, (size_t)n * sizeof *t0);
                int k2 = fastest(L, &R->S, t0);
                if (k2 != R->S.kcol && coord_of(L, &R->S, t0, k2) > 2.0 * coord_of(L, &R->S, t0, R->S.kcol)) {
                    sys_destroy(&R->S);
                    sys_create(L, &R->S, k2);
                }
            }
            if (h < 1e-13 * L->scale) {
                // No step converges: the framework is at a degenerate configuration (two edges at
                // a vertex aligned within rounding, e.g. a hull edge put back at an event). Treat
                // the flattest angle as the event.
                lk_watch flat;
                if (!flattest_any(L, &flat)) {
                    st = ori__fail(error, ORI_ERR_NOT_CONVERGED, "motion: step underflow");
                    goto done;
                }
                watch[nw] = flat;
                ev = nw;
                break;
            }
            h = fmin(h, step_cap(L, t0));
            if (!state_at(R, L->p, t0, h, p1)) {
                h *= 0.5;
                continue;
            }
            int first = -1;
            double first_frac = 2.0;
            for (int w = 0; w < nw; ++w) {
                double g0 = wedge_sine(L->p, watch[w]), g1 = wedge_sine(p1, watch[w]);
                if (g1 >= 0.0) {
                    double frac = g0 < 0.0 ? g0 / (g0 - g1) : 0.0;
                    if (frac < first_frac) first_frac = frac, first = w;
                }
            }
            if (first < 0) {
                memcpy(L->p, p1, (size_t)n * sizeof *p1);
                R->M->result.steps++;
                push_frame(R, L->p, false, false);
                h *= 2.0; // capped by the velocity field at the next step
                continue;
            }
            // Root-finding (Illinois, with bisection every fourth step) on the sine of the
            // first wedge over the step.
            double lo = 0.0, hi = h, glo = wedge_sine(L->p, watch[first]), ghi = wedge_sine(p1, watch[first]);
            double g_start = glo, g_end = ghi;
            memcpy(p0, L->p, (size_t)n * sizeof *p0);
            memcpy(pm, p1, (size_t)n * sizeof *pm);
            int side = 0;
            for (int it = 0; it < 300 && (hi - lo > ORI_TOL_LINKAGE_EVENT_REL * L->scale || (fabs(ghi) > ORI_TOL_LINKAGE_EVENT_SINE && hi - lo > 1e-15 * L->scale)); ++it) {
                double mid = glo < 0.0 && ghi > glo ? lo + (hi - lo) * (glo / (glo - ghi)) : 0.5 * (lo + hi);
                if (!(mid > lo && mid < hi) || it % 4 == 3) mid = 0.5 * (lo + hi);
                if (!state_at(R, p0, t0, mid, p1)) {
                    mid = 0.5 * (lo + hi);
                    if (!state_at(R, p0, t0, mid, p1)) break;
                }
                double g = wedge_sine(p1, watch[first]);
                bool other = false;
                for (int w = 0; w < nw && !other; ++w) other = w != first && wedge_sine(p1, watch[w]) >= 0.0;
                if (g >= 0.0 || other) {
                    hi = mid, ghi = g;
                    memcpy(pm, p1, (size_t)n * sizeof *p1);
                    if (side == 1) glo *= 0.5;
                    side = 1;
                } else {
                    lo = mid, glo = g;
                    if (side == -1) ghi *= 0.5;
                    side = -1;
                }
            }
            int w_ev = first;
            double gmax = -INFINITY;
            for (int w = 0; w < nw; ++w) {
                double g = wedge_sine(pm, watch[w]);
                if (g > gmax) gmax = g, w_ev = w;
            }
            // the located event: |sin| of the aligned angle at the end of the root-finding
            R->M->result.max_event_residual = fmax(R->M->result.max_event_residual, fabs(gmax));
            memcpy(L->p, pm, (size_t)n * sizeof *pm);
            // Past the event: the flip is decided at the configuration where the aligned angle has
            // turned ORI_TOL_LINKAGE_FLIP_SINE past π along the old motion (a concrete instance of
            // the perturbation by the motion's direction: every decision is then exact at a real
            // configuration, and no new edge can make a sliver thinner than that with an edge at
            // its end; the aligned neighbours' distance shrinks by O(sine²) ≈ 1e-14 of it).
            {
                lk_watch wf = watch[w_ev];
                int fa = find_edge(L, wf.v, wf.a), fb = find_edge(L, wf.v, wf.b);
                bool joint = fa >= 0 && L->e[fa].bar && fb >= 0 && L->e[fb].bar; // straightened: no flip to decide
                double target = joint ? 0.0 : ORI_TOL_LINKAGE_FLIP_SINE;
                double slope = (g_end - g_start) / h;
                double extra = slope > 0.0 ? ORI_TOL_LINKAGE_FLIP_SINE / slope : ORI_TOL_LINKAGE_EVENT_REL * L->scale;
                extra = fmax(extra, fmax(hi - lo, ORI_TOL_LINKAGE_EVENT_REL * L->scale));
                if (joint) extra = fmax(hi - lo, ORI_TOL_LINKAGE_EVENT_REL * L->scale);
                for (int it = 0; it < 40 && !(orient(L, wf.v, wf.a, wf.b) > 0 && wedge_sine(L->p, wf) >= 0.5 * target);
                     ++it, extra *= 1.5) {
                    if (!state_at(R, p0, t0, hi + extra, p1)) break;
                    memcpy(L->p, p1, (size_t)n * sizeof *p1);
                }
            }
            ev = w_ev;
        }
        if (R->S.col) sys_destroy(&R->S);
        push_frame(R, L->p, true, true);
        // The drive edge is not put back: the motion has moved its ends apart and other vertices
        // may now lie across it; the completion after the event adds whatever edges are valid.
        L->prev_a = L->drv_a, L->prev_b = L->drv_b;
        L->drv_a = L->drv_b = -1;
        lk_watch w = watch[ev];
        int ea = find_edge(L, w.v, w.a), eb = find_edge(L, w.v, w.b);
        int removed_a = -1, removed_b = -1;
        if (!(ea >= 0 && L->e[ea].bar && eb >= 0 && L->e[eb].bar)) {
            int kk = (ea >= 0 && !L->e[ea].bar) ? ea : eb;
            if (kk >= 0) removed_a = L->e[kk].a, removed_b = L->e[kk].b;
        }
        handle_event(R, w.v, w.a, w.b);
        rs = restructure(R, removed_a, removed_b, error);
    }
    if (rs < 0) st = error ? error->status : ORI_ERR_INTERNAL;
done:
    if (R->S.col) sys_destroy(&R->S);
    ori__free(t0), ori__free(t1), ori__free(p1), ori__free(p0), ori__free(pm), ori__free(watch);
    return st;
}

// --- validation and the checks ------------------------------------------------------------

static ori_status validate(const ori_linkage_def *def, int *order, bool *closed, ori_error *error)
{
    int n = def->vertex_count, m = def->edge_count;
    if (n < 2 || m < 1) return ori__fail(error, ORI_ERR_TOPOLOGY, "a linkage needs at least one bar");
    for (int v = 0; v < n; ++v)
        if (!ori__coord_ok(def->coords[v].x) || !ori__coord_ok(def->coords[v].y))
            return ori__fail_at(error, ORI_ERR_RANGE, "vertices_coords", v, "coordinate not finite");
    int *deg = ori__calloc((size_t)n, sizeof *deg), *nb = ori__alloc((size_t)n * 2 * sizeof *nb);
    ori_status st = ORI_OK;
    for (int k = 0; k < m && st == ORI_OK; ++k) {
        int a = def->edges[2 * k], b = def->edges[2 * k + 1];
        if (a < 0 || a >= n || b < 0 || b >= n)
            st = ori__fail_at(error, ORI_ERR_RANGE, "edges_vertices", k, "vertex index out of range");
        else if (a == b)
            st = ori__fail_at(error, ORI_ERR_DEGENERATE, "edges_vertices", k, "bar joins a vertex to itself");
        else {
            for (int j = 0; j < k && st == ORI_OK; ++j) {
                int c = def->edges[2 * j], d = def->edges[2 * j + 1];
                if ((c == a && d == b) || (c == b && d == a))
                    st = ori__fail_at(error, ORI_ERR_DUPLICATE, "edges_vertices", k, "repeats bar %d", j);
            }
            if (st != ORI_OK) break;
            if (deg[a] == 2 || deg[b] == 2) {
                int v = deg[a] == 2 ? a : b;
                st = ori__fail_at(error, ORI_ERR_TOPOLOGY, "vertices_coords", v,
                                  "has three bars: a tree or graph, not a chain or polygon (trees can lock)");
            } else {
                nb[2 * a + deg[a]++] = b;
                nb[2 * b + deg[b]++] = a;
            }
        }
    }
    for (int v = 0; v < n && st == ORI_OK; ++v)
        if (deg[v] == 0) st = ori__fail_at(error, ORI_ERR_TOPOLOGY, "vertices_coords", v, "has no bar");
    if (st == ORI_OK) {
        int start = 0;
        for (int v = 0; v < n; ++v)
            if (deg[v] == 1) {
                start = v;
                break;
            }
        *closed = deg[start] == 2;
        int prev = -1, cur = start, count = 0;
        while (count < n) {
            order[count++] = cur;
            int next = -1;
            for (int d = 0; d < deg[cur]; ++d)
                if (nb[2 * cur + d] != prev) {
                    next = nb[2 * cur + d];
                    break;
                }
            if (next < 0 || next == start) break;
            prev = cur, cur = next;
        }
        if (count != n || (*closed && m != n) || (!*closed && m != n - 1))
            st = ori__fail_at(error, ORI_ERR_TOPOLOGY, "vertices_coords", cur,
                              "the bars form more than one chain or polygon");
        if (*closed && n < 3) st = ori__fail(error, ORI_ERR_TOPOLOGY, "a polygon needs three bars");
    }
    // coincident vertices (sorted) and crossing bars (all pairs; small inputs)
    for (int a = 0; a < n && st == ORI_OK; ++a)
        for (int b = a + 1; b < n && st == ORI_OK; ++b)
            if (def->coords[a].x == def->coords[b].x && def->coords[a].y == def->coords[b].y)
                st = ori__fail_at(error, ORI_ERR_DUPLICATE, "vertices_coords", b, "repeats vertex %d", a);
    for (int k = 0; k < m && st == ORI_OK; ++k)
        for (int j = k + 1; j < m && st == ORI_OK; ++j) {
            int a = def->edges[2 * k], b = def->edges[2 * k + 1], c = def->edges[2 * j], d = def->edges[2 * j + 1];
            ori_v2 pa = def->coords[a], pb = def->coords[b], pc = def->coords[c], pd = def->coords[d];
            bool share = a == c || a == d || b == c || b == d;
            if (!share) {
                if (ori__segments_intersect(pa, pb, pc, pd))
                    st = ori__fail_at(error, ORI_ERR_CROSSING, "edges_vertices", j, "crosses bar %d", k);
            } else {
                int s = (a == c || a == d) ? a : b, x = s == a ? b : a, y = (c == s) ? d : c;
                ori_v2 ps = def->coords[s];
                if (ori__orient2d_exact(ps, def->coords[x], def->coords[y]) == 0 &&
                    ori_v2_dot(ori_v2_sub(def->coords[x], ps), ori_v2_sub(def->coords[y], ps)) > 0.0)
                    st = ori__fail_at(error, ORI_ERR_CROSSING, "edges_vertices", j, "overlaps bar %d", k);
            }
        }
    ori__free(deg), ori__free(nb);
    return st;
}

static bool final_shape_ok(const ori_linkage_def *def, const int *order, bool closed, const ori_v2 *p, double scale)
{
    int n = def->vertex_count;
    if (!closed) {
        for (int i = 1; i + 1 < n; ++i) {
            ori_v2 a = ori_v2_sub(p[order[i]], p[order[i - 1]]), b = ori_v2_sub(p[order[i + 1]], p[order[i]]);
            if (fabs(ori_v2_cross(a, b)) > 1e-9 * ori_v2_norm(a) * ori_v2_norm(b) || ori_v2_dot(a, b) <= 0.0) return false;
        }
        return true;
    }
    int sign = 0;
    for (int i = 0; i < n; ++i) {
        ori_v2 a = ori_v2_sub(p[order[(i + 1) % n]], p[order[i]]), b = ori_v2_sub(p[order[(i + 2) % n]], p[order[(i + 1) % n]]);
        double c = ori_v2_cross(a, b) / (ori_v2_norm(a) * ori_v2_norm(b));
        if (fabs(c) <= 1e-9) continue;
        int s = c > 0 ? 1 : -1;
        if (sign && s != sign) return false;
        sign = s;
    }
    // total turning one full turn: convex and simple
    double turn = 0.0;
    for (int i = 0; i < n; ++i) {
        ori_v2 a = ori_v2_sub(p[order[(i + 1) % n]], p[order[i]]), b = ori_v2_sub(p[order[(i + 2) % n]], p[order[(i + 1) % n]]);
        turn += atan2(ori_v2_cross(a, b), ori_v2_dot(a, b));
    }
    (void)scale;
    return fabs(fabs(turn) - 6.283185307179586) < 1e-6;
}

static void measure(const ori_linkage_def *def, ori_linkage_motion *M)
{
    int n = M->n;
    double maxerr = 0.0, mind = INFINITY;
    for (int f = 0; f < M->frame_count; ++f) {
        const ori_v2 *p = M->frames + (size_t)f * n;
        for (int k = 0; k < def->edge_count; ++k) {
            int a = def->edges[2 * k], b = def->edges[2 * k + 1];
            double L0 = ori_v2_norm(ori_v2_sub(def->coords[a], def->coords[b]));
            maxerr = fmax(maxerr, fabs(ori_v2_norm(ori_v2_sub(p[a], p[b])) - L0) / L0);
        }
        if (f == 0) continue;
        const ori_v2 *q = p - n;
        for (int a = 0; a < n; ++a)
            for (int b = a + 1; b < n; ++b) {
                double px = p[a].x - p[b].x, py = p[a].y - p[b].y, qx = q[a].x - q[b].x, qy = q[a].y - q[b].y;
                double d = sqrt(px * px + py * py) - sqrt(qx * qx + qy * qy);
                if (d < mind) mind = d;
            }
    }
    M->result.max_length_error = maxerr;
    M->result.min_distance_change = isfinite(mind) ? mind : 0.0;
}

// One run of the motion under perturbation variant 0–3 (see ori_linkage_unfold).
static ori_status attempt(const ori_linkage_def *def, const int *order, bool closed, int variant,
                          ori_linkage_motion **out, bool *cancelled, ori_error *error)
{
    int n = def->vertex_count;
    lk L;
    memset(&L, 0, sizeof L);
    L.n = n;
    L.closed = closed;
    L.p = ori__alloc((size_t)n * sizeof *L.p);
    memcpy(L.p, def->coords, (size_t)n * sizeof *L.p);
    L.frozen = ori__calloc((size_t)n, sizeof *L.frozen);
    L.fa = ori__alloc((size_t)n * sizeof(int)), L.fb = ori__alloc((size_t)n * sizeof(int));
    L.forder = ori__alloc((size_t)n * sizeof(int)), L.ft = ori__alloc((size_t)n * sizeof(double));
    L.drv_a = L.drv_b = L.prev_a = L.prev_b = -1;
    L.sd = ori__alloc((size_t)n * sizeof *L.sd), L.se = ori__alloc((size_t)n * sizeof *L.se);
    {
        ori_v2 c = ori_v2_make(0.0, 0.0);
        for (int v = 0; v < n; ++v) c = ori_v2_add(c, ori_v2_scale(L.p[v], 1.0 / n));
        for (int v = 0; v < n; ++v) {
            ori_v2 r = ori_v2_sub(L.p[v], c);
            ori_v2 cubic = ori_v2_scale(r, ori_v2_dot(r, r));
            double w = variant == 3 ? (double)(n - v) : (double)v;
            ori_v2 parabola = ori_v2_make(w, w * w);
            L.sd[v] = variant == 0 ? cubic : variant == 1 ? ori_v2_scale(cubic, -1.0) : parabola;
            L.se[v] = variant <= 1 ? parabola : cubic;
        }
    }
    double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
    for (int v = 0; v < n; ++v)
        lo_x = fmin(lo_x, L.p[v].x), hi_x = fmax(hi_x, L.p[v].x), lo_y = fmin(lo_y, L.p[v].y), hi_y = fmax(hi_y, L.p[v].y);
    L.scale = hypot(hi_x - lo_x, hi_y - lo_y);
    for (int k = 0; k < def->edge_count; ++k) {
        int a = def->edges[2 * k], b = def->edges[2 * k + 1];
        add_edge(&L, a, b, true, ori_v2_norm(ori_v2_sub(L.p[a], L.p[b])));
    }
    // a triangle or a straight chain is already done; a 2-vertex chain too
    ori_linkage_motion *M = ori__calloc(1, sizeof *M);
    M->n = n;
    M->result.kind = closed ? ORI_LINKAGE_POLYGON : ORI_LINKAGE_CHAIN;
    lk_run R;
    memset(&R, 0, sizeof R);
    R.L = &L;
    R.M = M;
    size_t cap = (size_t)(4 * n + 16);
    R.rhs = ori__alloc(cap * sizeof(double)), R.sol = ori__alloc(cap * sizeof(double));
    R.w1 = ori__alloc(cap * sizeof(double)), R.w2 = ori__alloc(2 * cap * sizeof(double));
    R.per = def->steps_per_event;
    R.buf_cap = R.per > 0 ? 4 * R.per + 16 : 0;
    R.buf = R.per > 0 ? ori__alloc((size_t)R.buf_cap * (size_t)n * sizeof *R.buf) : NULL;
    R.stride = 1;
    R.progress = def->progress, R.progress_user = def->progress_user;
    R.end_a = closed ? -1 : order[0], R.end_b = closed ? -1 : order[n - 1];
    for (int k = 0; k < def->edge_count; ++k)
        R.total += ori_v2_norm(ori_v2_sub(def->coords[def->edges[2 * k]], def->coords[def->edges[2 * k + 1]]));
    int max_events = def->max_events > 0 ? def->max_events : 100 * n + 100;
    ori_status st = run_motion(&R, max_events, error);
    // Stopped at the budget (max_events, or cancelled): on request the motion so far, whose last
    // frame is the state at the stop (an event), checked like a whole one.
    bool partial = st == ORI_ERR_LIMIT && def->keep_partial && M->frame_count > 0;
    M->result.stopped = st == ORI_ERR_LIMIT;
    *cancelled = R.cancelled;
    if (st == ORI_OK || partial) {
        const ori_v2 *last = M->frames + (size_t)(M->frame_count - 1) * n;
        M->result.final_ok = st == ORI_OK && final_shape_ok(def, order, closed, last, L.scale);
        M->result.frames = M->frame_count;
        measure(def, M);
        // the motion's own guarantees, checked over the kept frames: a motion that breaks them
        // (a degenerate input the perturbation could not steer, see docs/unfolding.md) is a failure
        if (M->result.max_length_error > ORI_TOL_LINKAGE_CHECK_REL)
            st = ori__fail(error, ORI_ERR_NOT_CONVERGED, "motion: a bar length drifted by %.3g relative",
                           M->result.max_length_error);
        else if (M->result.min_distance_change < -ORI_TOL_LINKAGE_CHECK_REL * L.scale)
            st = ori__fail(error, ORI_ERR_NOT_CONVERGED, "motion: a distance decreased by %.3g (not expansive)",
                           -M->result.min_distance_change);
        if (st != ORI_ERR_LIMIT) partial = false;
    }
    ori__free(R.rhs), ori__free(R.sol), ori__free(R.w1), ori__free(R.w2), ori__free(R.buf);
    ori__free(L.p), ori__free(L.frozen), ori__free(L.fa), ori__free(L.fb), ori__free(L.forder), ori__free(L.ft);
    ori__free(L.e), ori__free(L.adj), ori__free(L.adj_start), ori__free(L.sd), ori__free(L.se);
    if (st != ORI_OK && !partial) {
        ori_linkage_motion_destroy(M);
        return st;
    }
    *out = M;
    return st;
}

ori_status ori_linkage_unfold(const ori_linkage_def *def, ori_linkage_motion **out, ori_error *error)
{
    ORI_ASSERT(def && out && def->internal_value == ORI__DEF_COOKIE);
    *out = NULL;
    if (!def->coords || !def->edges || def->vertex_count < 0 || def->edge_count < 0 || def->steps_per_event < 0)
        return ori__fail(error, ORI_ERR_ARGUMENT, "linkage: missing coordinates or bars");
    int n = def->vertex_count;
    int *order = ori__alloc(((size_t)n + 1) * sizeof *order);
    bool closed = false;
    ori_status st = validate(def, order, &closed, error);
    if (st != ORI_OK) {
        ori__free(order);
        return st;
    }
    // The perturbation is fixed by the input. Where exact collinearities force a flat
    // pseudo-triangle, the motion may not follow the side it chose and fails (detected: an
    // internal error or a broken guarantee); then other perturbations are tried: the cubic
    // expansion reversed, then the parabola first.
    ori_linkage_motion *M = NULL;
    for (int variant = 0; variant < 4; ++variant) {
        ori_linkage_motion_destroy(M); // (a partial motion of the variant before)
        M = NULL;
        bool cancelled = false;
        st = attempt(def, order, closed, variant, &M, &cancelled, error);
        // the automatic limit: flips cycling, another perturbation may not (a cancel is the user's)
        bool cycle = st == ORI_ERR_LIMIT && def->max_events == 0 && !cancelled;
        if (st != ORI_ERR_NOT_CONVERGED && st != ORI_ERR_INTERNAL && !cycle) break;
    }
    ori__free(order);
    if (st != ORI_OK && !(st == ORI_ERR_LIMIT && M)) {
        ori_linkage_motion_destroy(M);
        return st;
    }
    *out = M;
    return st;
}

void ori_linkage_motion_destroy(ori_linkage_motion *motion)
{
    if (!motion) return;
    ori__free(motion->frames);
    ori__free(motion->is_event);
    ori__free(motion);
}

ori_linkage_result ori_linkage_motion_result(const ori_linkage_motion *motion)
{
    ORI_ASSERT(motion);
    return motion->result;
}

int ori_linkage_motion_vertex_count(const ori_linkage_motion *motion) { return motion->n; }
int ori_linkage_motion_frame_count(const ori_linkage_motion *motion) { return motion->frame_count; }

const ori_v2 *ori_linkage_motion_frame(const ori_linkage_motion *motion, int frame)
{
    ORI_ASSERT(motion && frame >= 0 && frame < motion->frame_count);
    return motion->frames + (size_t)frame * motion->n;
}

bool ori_linkage_motion_frame_is_event(const ori_linkage_motion *motion, int frame)
{
    ORI_ASSERT(motion && frame >= 0 && frame < motion->frame_count);
    return motion->is_event[frame];
}
