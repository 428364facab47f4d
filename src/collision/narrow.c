// The exact test of two posed planar faces (convex or not). Three cases, decided in this order:
//  - coplanar layers (each face within the contact tolerance of the other's plane): they touch
//    when they overlap by a width above the tolerance (2·area/perimeter of the overlap, per
//    pair of convex pieces clipped by Sutherland–Hodgman);
//  - crossing planes: along the planes' intersection line L, each face's material that lies on
//    both sides of the other's plane is the intersection I⁺ ∩ I⁻ of two interval sets, taken
//    with the vertices on the plane (within the penetration tolerance) counted once on one side,
//    once on the other; the faces penetrate when these sets of the two faces overlap along a
//    segment longer than the tolerance. A face merely resting on another (an edge or a vertex on
//    it) has one of the two sets empty: it touches. The even–odd pairing of the sorted crossings
//    holds for non-convex faces;
//  - otherwise the exact distance (edge–edge and vertex–face) says touching or apart.
// Faces that share vertices are only looked at away from them (see pair_test).
#include "collision_internal.h"

void col_work_init(col_work *w, int m)
{
    memset(w, 0, sizeof *w);
    w->cap = m;
    size_t n = (size_t)m + 4;
    w->pp = ori__alloc(sizeof(ori_v3) * n);
    w->qq = ori__alloc(sizeof(ori_v3) * n);
    w->dp = ori__alloc(sizeof(double) * n);
    w->dq = ori__alloc(sizeof(double) * n);
    w->xa = ori__alloc(sizeof(col_xing) * n);
    w->xb = ori__alloc(sizeof(col_xing) * n);
    w->ia = ori__alloc(sizeof(col_xing) * 4 * n);
    w->ib = ori__alloc(sizeof(col_xing) * 4 * n);
    w->ic = ori__alloc(sizeof(col_xing) * 8 * n);
    w->p2 = ori__alloc(sizeof(ori_v2) * n);
    w->q2 = ori__alloc(sizeof(ori_v2) * n);
    w->clip0 = ori__alloc(sizeof(ori_v2) * 3 * n);
    w->clip1 = ori__alloc(sizeof(ori_v2) * 3 * n);
    w->eboxes = ori__alloc(sizeof(col_box) * n);
}

void col_work_free(col_work *w)
{
    ori__free(w->pp);
    ori__free(w->qq);
    ori__free(w->dp);
    ori__free(w->dq);
    ori__free(w->xa);
    ori__free(w->xb);
    ori__free(w->ia);
    ori__free(w->ib);
    ori__free(w->ic);
    ori__free(w->p2);
    ori__free(w->q2);
    ori__free(w->clip0);
    ori__free(w->clip1);
    ori__free(w->eboxes);
    memset(w, 0, sizeof *w);
}

static int face_size(const ori_collider *c, int f) { return c->face_off[f + 1] - c->face_off[f]; }

static int load(const ori_collider *c, int f, ori_v3 *out)
{
    int n = face_size(c, f);
    const int *fv = c->face_verts + c->face_off[f];
    for (int i = 0; i < n; ++i) out[i] = c->pos[fv[i]];
    return n;
}

static void to_frame(const col_geom *g, const ori_v3 *p, int n, ori_v2 *out)
{
    for (int i = 0; i < n; ++i) {
        ori_v3 q = ori_v3_sub(p[i], g->o);
        out[i] = ori_v2_make(ori_v3_dot(q, g->e1), ori_v3_dot(q, g->e2));
    }
}

static ori_v3 from_frame(const col_geom *g, ori_v2 x)
{
    return ori_v3_add(g->o, ori_v3_add(ori_v3_scale(g->e1, x.x), ori_v3_scale(g->e2, x.y)));
}

// --- segments and points -------------------------------------------------------------------

static double clamp01(double x) { return x < 0.0 ? 0.0 : x > 1.0 ? 1.0 : x; }

// Squared distance of segments p1p2 and q1q2 and the parameters s, t of the closest points
// (Ericson, Real-Time Collision Detection, 5.1.9), with exact-zero guards only: edges have
// positive length, and the clamped re-solve keeps near-parallel segments accurate.
static double seg_seg2(ori_v3 p1, ori_v3 p2, ori_v3 q1, ori_v3 q2, double *sp, double *tp)
{
    ori_v3 d1 = ori_v3_sub(p2, p1), d2 = ori_v3_sub(q2, q1), r = ori_v3_sub(p1, q1);
    double a = ori_v3_dot(d1, d1), e = ori_v3_dot(d2, d2), f = ori_v3_dot(d2, r);
    double s = 0.0, t = 0.0;
    if (a == 0.0 && e == 0.0) {
        s = t = 0.0;
    } else if (a == 0.0) {
        t = clamp01(f / e);
    } else {
        double cc = ori_v3_dot(d1, r);
        if (e == 0.0) {
            s = clamp01(-cc / a);
        } else {
            double b = ori_v3_dot(d1, d2), denom = a * e - b * b;
            s = denom > 0.0 ? clamp01((b * f - cc * e) / denom) : 0.0;
            t = (b * s + f) / e;
            if (t < 0.0) {
                t = 0.0;
                s = clamp01(-cc / a);
            } else if (t > 1.0) {
                t = 1.0;
                s = clamp01((b - cc) / a);
            }
        }
    }
    *sp = s;
    *tp = t;
    ori_v3 x = ori_v3_sub(ori_v3_add(p1, ori_v3_scale(d1, s)), ori_v3_add(q1, ori_v3_scale(d2, t)));
    return ori_v3_dot(x, x);
}

// Closest points of segments p1p2 and q1q2 and their distance.
static double seg_seg(ori_v3 p1, ori_v3 p2, ori_v3 q1, ori_v3 q2, ori_v3 *cp, ori_v3 *cq)
{
    double s, t, d2 = seg_seg2(p1, p2, q1, q2, &s, &t);
    *cp = ori_v3_add(p1, ori_v3_scale(ori_v3_sub(p2, p1), s));
    *cq = ori_v3_add(q1, ori_v3_scale(ori_v3_sub(q2, q1), t));
    return sqrt(d2);
}

// Even–odd point-in-polygon in 2D (boundary cases are decided by the edge distances instead).
static bool inside2(const ori_v2 *poly, int n, ori_v2 x)
{
    bool in = false;
    for (int i = 0, j = n - 1; i < n; j = i++) {
        ori_v2 a = poly[i], b = poly[j];
        if ((a.y > x.y) != (b.y > x.y)) {
            double xc = a.x + (x.y - a.y) * (b.x - a.x) / (b.y - a.y);
            if (x.x < xc) in = !in;
        }
    }
    return in;
}

// Distance from x to face g (loaded as q with 2D frame q2), closest point on the face.
static double point_face(const col_geom *g, const ori_v3 *q, const ori_v2 *q2, int m, ori_v3 x, ori_v3 *cq)
{
    ori_v3 r = ori_v3_sub(x, g->o);
    ori_v2 x2 = ori_v2_make(ori_v3_dot(r, g->e1), ori_v3_dot(r, g->e2));
    double h = ori_v3_dot(r, g->n);
    if (inside2(q2, m, x2)) {
        *cq = ori_v3_sub(x, ori_v3_scale(g->n, h));
        return fabs(h);
    }
    double best = INFINITY;
    for (int j = 0; j < m; ++j) {
        ori_v3 a, b;
        double d = seg_seg(x, x, q[j], q[(j + 1) % m], &a, &b);
        if (d < best) {
            best = d;
            *cq = b;
        }
    }
    return best;
}

// Lower bound of the distance of face p (n vertices) to the plane of face g: the least
// distance of its vertices when they all lie on one side, else 0.
static double plane_gap(const col_geom *g, const ori_v3 *p, int n)
{
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < n; ++i) {
        double h = ori_v3_dot(g->n, p[i]) - g->d;
        lo = h < lo ? h : lo;
        hi = h > hi ? h : hi;
    }
    return lo > 0.0 ? lo : hi < 0.0 ? -hi : 0.0;
}

// plane_gap from the signed distances d of the n vertices.
static double gap_of(const double *d, int n)
{
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < n; ++i) {
        lo = d[i] < lo ? d[i] : lo;
        hi = d[i] > hi ? d[i] : hi;
    }
    return lo > 0.0 ? lo : hi < 0.0 ? -hi : 0.0;
}

// Squared gap between two boxes (0 when they overlap).
static double box_gap2(const col_box *a, const col_box *b) { return col_box_dist2(a, b); }

static col_box seg_box(ori_v3 a, ori_v3 b)
{
    col_box x;
    x.lo = ori_v3_make(a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.z < b.z ? a.z : b.z);
    x.hi = ori_v3_make(a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z);
    return x;
}

double col_face_distance(ori_collider *c, int f, int g, double bound, ori_v3 *pa, ori_v3 *pb)
{
    col_work *w = &c->work;
    const col_geom *gf = &c->geom[f], *gg = &c->geom[g];
    int n = load(c, f, w->pp), m = load(c, g, w->qq);
    // Separating planes give a lower bound: most far pairs end here.
    double lb = plane_gap(gg, w->pp, n), lq = plane_gap(gf, w->qq, m);
    if (lq > lb) lb = lq;
    if (lb >= bound) return lb;
    double best2 = bound * bound;
    int kind = -1, bi = 0, bj = 0; // 0 edge–edge, 1 vertex of f on g, 2 vertex of g on f
    double bs = 0.0, bt = 0.0;
    // Vertex–face first: cheap, and often the answer, which then prunes the edge pairs.
    bool q2_ready = false, p2_ready = false;
    for (int i = 0; i < n; ++i) {
        ori_v3 r = ori_v3_sub(w->pp[i], gg->o);
        double h = ori_v3_dot(r, gg->n);
        if (!(h * h < best2)) continue;
        if (!q2_ready) {
            to_frame(gg, w->qq, m, w->q2);
            q2_ready = true;
        }
        if (inside2(w->q2, m, ori_v2_make(ori_v3_dot(r, gg->e1), ori_v3_dot(r, gg->e2)))) {
            best2 = h * h;
            kind = 1;
            bi = i;
            bs = h;
        }
    }
    for (int j = 0; j < m; ++j) {
        ori_v3 r = ori_v3_sub(w->qq[j], gf->o);
        double h = ori_v3_dot(r, gf->n);
        if (!(h * h < best2)) continue;
        if (!p2_ready) {
            to_frame(gf, w->pp, n, w->p2);
            p2_ready = true;
        }
        if (inside2(w->p2, n, ori_v2_make(ori_v3_dot(r, gf->e1), ori_v3_dot(r, gf->e2)))) {
            best2 = h * h;
            kind = 2;
            bj = j;
            bs = h;
        }
    }
    col_box *eb = w->eboxes;
    for (int j = 0; j < m; ++j) eb[j] = seg_box(w->qq[j], w->qq[(j + 1) % m]);
    for (int i = 0; i < n; ++i) {
        ori_v3 a = w->pp[i], b = w->pp[(i + 1) % n];
        col_box ea = seg_box(a, b);
        for (int j = 0; j < m; ++j) {
            if (box_gap2(&ea, &eb[j]) >= best2) continue;
            double sp, tp, d2 = seg_seg2(a, b, w->qq[j], w->qq[(j + 1) % m], &sp, &tp);
            if (d2 < best2) {
                best2 = d2;
                kind = 0;
                bi = i;
                bj = j;
                bs = sp;
                bt = tp;
            }
        }
    }
    if (kind < 0) return bound;
    if (kind == 0) {
        ori_v3 a = w->pp[bi], b = w->pp[(bi + 1) % n], q1 = w->qq[bj], q2 = w->qq[(bj + 1) % m];
        *pa = ori_v3_add(a, ori_v3_scale(ori_v3_sub(b, a), bs));
        *pb = ori_v3_add(q1, ori_v3_scale(ori_v3_sub(q2, q1), bt));
    } else if (kind == 1) {
        *pa = w->pp[bi];
        *pb = ori_v3_sub(w->pp[bi], ori_v3_scale(gg->n, bs));
    } else {
        *pb = w->qq[bj];
        *pa = ori_v3_sub(w->qq[bj], ori_v3_scale(gf->n, bs));
    }
    return sqrt(best2);
}

// --- overlap of two faces in one plane frame -----------------------------------------------

// Convex piece k of face f as 2D points (from the face's 2D cycle src), counter-clockwise.
// Returns the point count (0 for a piece without area).
static int piece(const ori_collider *c, int f, int k, const ori_v2 *src, ori_v2 *out)
{
    int tn = c->tri_off[f + 1] - c->tri_off[f], n;
    if (tn == 0) {
        n = face_size(c, f);
        memcpy(out, src, sizeof(ori_v2) * (size_t)n);
    } else {
        const int *t = c->tris + 3 * (c->tri_off[f] + k);
        out[0] = src[t[0]];
        out[1] = src[t[1]];
        out[2] = src[t[2]];
        n = 3;
    }
    double area = 0.0;
    for (int i = 0; i < n; ++i) area += ori_v2_cross(out[i], out[(i + 1) % n]);
    if (area == 0.0) return 0;
    if (area < 0.0)
        for (int i = 0; i < n / 2; ++i) {
            ori_v2 tmp = out[i];
            out[i] = out[n - 1 - i];
            out[n - 1 - i] = tmp;
        }
    return n;
}

static int piece_count(const ori_collider *c, int f)
{
    int tn = c->tri_off[f + 1] - c->tri_off[f];
    return tn == 0 ? 1 : tn;
}

// Sutherland–Hodgman: clip convex counter-clockwise subject s (ns points) by convex
// counter-clockwise window cw (nc points). The result is in *res (one of the two buffers).
static int clip_convex(ori_v2 *s, int ns, const ori_v2 *cw, int nc, ori_v2 *buf, ori_v2 **res)
{
    ori_v2 *in = s, *out = buf;
    int n = ns;
    for (int e = 0; e < nc && n > 0; ++e) {
        ori_v2 a = cw[e], b = cw[(e + 1) % nc], ab = ori_v2_sub(b, a);
        int m = 0;
        for (int i = 0; i < n; ++i) {
            ori_v2 p = in[i], q = in[(i + 1) % n];
            double sp = ori_v2_cross(ab, ori_v2_sub(p, a)), sq = ori_v2_cross(ab, ori_v2_sub(q, a));
            if (sp >= 0.0) out[m++] = p;
            if ((sp >= 0.0) != (sq >= 0.0)) {
                double t = sp / (sp - sq);
                out[m++] = ori_v2_add(p, ori_v2_scale(ori_v2_sub(q, p), t));
            }
        }
        ori_v2 *tmp = in;
        in = out;
        out = tmp;
        n = m;
    }
    *res = in;
    return n;
}

typedef struct overlap_out {
    double width;     // widest overlap piece: 2·area/perimeter
    ori_v2 centroid;  // of that piece
    double hmin, hmax; // heights of face a over b's plane on overlap pieces wider than the tolerance
    bool any;         // some piece wider than the tolerance
} overlap_out;

// Overlap of face a (2D points a2, in b's frame) and face b (b2). With heights, the height of
// a's plane along b's normal is taken at every corner of every overlap piece wider than tol.
static void overlap(ori_collider *c, int a, const ori_v2 *a2, int b, const ori_v2 *b2, double tol, bool heights,
                    overlap_out *o)
{
    col_work *w = &c->work;
    const col_geom *ga = &c->geom[a], *gb = &c->geom[b];
    double cosab = ori_v3_dot(ga->n, gb->n);
    o->width = 0.0;
    o->any = false;
    o->hmin = INFINITY;
    o->hmax = -INFINITY;
    o->centroid = ori_v2_make(0.0, 0.0);
    int ka = piece_count(c, a), kb = piece_count(c, b);
    // piece buffers: the subject in clip0 (first part), the window in the tail of clip1
    for (int i = 0; i < ka; ++i)
        for (int j = 0; j < kb; ++j) {
            ori_v2 *win = w->clip1 + 2 * (size_t)(w->cap + 4);
            int nb = piece(c, b, j, b2, win);
            int na = piece(c, a, i, a2, w->clip0);
            if (na == 0 || nb == 0) continue;
            ori_v2 *res;
            int m = clip_convex(w->clip0, na, win, nb, w->clip1, &res);
            if (m < 3) continue;
            double area2 = 0.0, per = 0.0, cx = 0.0, cy = 0.0;
            for (int k = 0; k < m; ++k) {
                ori_v2 p = res[k], q = res[(k + 1) % m];
                double cr = ori_v2_cross(p, q);
                area2 += cr;
                cx += (p.x + q.x) * cr;
                cy += (p.y + q.y) * cr;
                ori_v2 e = ori_v2_sub(q, p);
                per += sqrt(ori_v2_dot(e, e));
            }
            if (!(area2 > 0.0) || !(per > 0.0)) continue;
            double width = area2 / per; // 2·(area2/2)/per
            if (width > tol && heights && cosab != 0.0) {
                for (int k = 0; k < m; ++k) {
                    ori_v3 x3 = from_frame(gb, res[k]);
                    double h = (ga->d - ori_v3_dot(ga->n, x3)) / cosab;
                    o->hmin = fmin(o->hmin, h);
                    o->hmax = fmax(o->hmax, h);
                }
            }
            if (width > tol) o->any = true;
            if (width > o->width) {
                o->width = width;
                o->centroid = ori_v2_make(cx / (3.0 * area2), cy / (3.0 * area2));
            }
        }
}

col_side col_face_side_quick(const ori_collider *c, int a, int b)
{
    const col_geom *gb = &c->geom[b];
    const int *fv = c->face_verts + c->face_off[a];
    int n = face_size(c, a);
    bool pos = false, neg = false, on = false;
    for (int i = 0; i < n; ++i) {
        double h = ori_v3_dot(gb->n, c->pos[fv[i]]) - gb->d;
        if (h > c->tol_pen) pos = true;
        else if (h < -c->tol_pen) neg = true;
        else on = true;
    }
    if (pos && !neg && !on) return COL_SIDE_ABOVE;
    if (neg && !pos && !on) return COL_SIDE_BELOW;
    if (on && !pos && !neg) return COL_SIDE_FLAT;
    return COL_SIDE_MIXED;
}

// Whether the convex polygons p (n points) and q (m) lie on two sides of a line along one of
// their edges' directions, overlapping across it by at most eps: then every convex piece of
// their intersection lies in a strip of width eps, and is at most eps wide (2·area/perimeter).
static bool split_by_a_side(const ori_v2 *p, int n, const ori_v2 *q, int m, double eps)
{
    for (int pass = 0; pass < 2; ++pass) {
        const ori_v2 *e = pass ? q : p;
        int ne = pass ? m : n;
        for (int i = 0; i < ne; ++i) {
            ori_v2 d = ori_v2_sub(e[(i + 1) % ne], e[i]);
            double len = sqrt(ori_v2_dot(d, d));
            if (!(len > 0.0)) continue;
            ori_v2 u = ori_v2_make(-d.y / len, d.x / len);
            double plo = INFINITY, phi = -INFINITY, qlo = INFINITY, qhi = -INFINITY;
            for (int k = 0; k < n; ++k) {
                double t = ori_v2_dot(p[k], u);
                plo = t < plo ? t : plo;
                phi = t > phi ? t : phi;
            }
            for (int k = 0; k < m; ++k) {
                double t = ori_v2_dot(q[k], u);
                qlo = t < qlo ? t : qlo;
                qhi = t > qhi ? t : qhi;
            }
            if (phi <= qlo + eps || qhi <= plo + eps) return true;
        }
    }
    return false;
}

static col_side face_side(ori_collider *c, int a, int b, ori_v3 *point, bool try_split)
{
    col_work *w = &c->work;
    const col_geom *ga = &c->geom[a], *gb = &c->geom[b];
    if (ori_v3_dot(ga->n, gb->n) == 0.0) return COL_SIDE_NONE;
    int n = load(c, a, w->pp), m = load(c, b, w->qq);
    to_frame(gb, w->pp, n, w->p2);
    to_frame(gb, w->qq, m, w->q2);
    // Convex faces that one line parts, up to an eighth of the contact tolerance, have no overlap
    // piece wider than the tolerance: no side, what the clipping below finds (its round-off is
    // far below the rest of the tolerance), without clipping.
    if (try_split && c->tri_off[a + 1] == c->tri_off[a] && c->tri_off[b + 1] == c->tri_off[b] &&
        split_by_a_side(w->p2, n, w->q2, m, 0.125 * c->tol_touch))
        return COL_SIDE_NONE;
    overlap_out o;
    overlap(c, a, w->p2, b, w->q2, c->tol_touch, true, &o);
    if (!o.any) return COL_SIDE_NONE;
    if (point) *point = from_frame(gb, o.centroid);
    // The side is decided at the penetration tolerance, not the contact one: a layer leaving
    // its stack through another is caught as soon as it has moved by more than round-off.
    double t = c->tol_pen;
    if (o.hmax > t && o.hmin < -t) return COL_SIDE_MIXED;
    if (o.hmax > t) return COL_SIDE_ABOVE;
    if (o.hmin < -t) return COL_SIDE_BELOW;
    return COL_SIDE_FLAT;
}

col_side col_face_side(ori_collider *c, int a, int b, ori_v3 *point) { return face_side(c, a, b, point, false); }

col_side col_face_side_parted(ori_collider *c, int a, int b, ori_v3 *point) { return face_side(c, a, b, point, true); }

// --- crossing planes -------------------------------------------------------------------------

static void sort_xings(col_xing *x, int n)
{
    for (int i = 1; i < n; ++i) {
        col_xing v = x[i];
        int j = i - 1;
        while (j >= 0 && x[j].t > v.t) {
            x[j + 1] = x[j];
            j--;
        }
        x[j + 1] = v;
    }
}

// Where the boundary of face p (n vertices, signed distances d to the other plane) crosses that
// plane, vertices within tol of it counted on side on_sign; sorted along u. Pairs of the result
// are the intervals of the face on the line.
static int crossings(const ori_v3 *p, const double *d, int n, double tol, int on_sign, ori_v3 u, col_xing *out)
{
    int k = 0;
    for (int i = 0; i < n; ++i) {
        int j = (i + 1) % n;
        bool oni = fabs(d[i]) <= tol, onj = fabs(d[j]) <= tol;
        int si = oni ? on_sign : (d[i] > 0.0 ? 1 : -1), sj = onj ? on_sign : (d[j] > 0.0 ? 1 : -1);
        if (si == sj) continue;
        ori_v3 x;
        if (oni) x = p[i];
        else if (onj) x = p[j];
        else x = ori_v3_add(p[i], ori_v3_scale(ori_v3_sub(p[j], p[i]), d[i] / (d[i] - d[j])));
        out[k].t = ori_v3_dot(x, u);
        out[k].p = x;
        k++;
    }
    sort_xings(out, k);
    return k & ~1;
}

// Intersection of two sorted interval lists (endpoint pairs).
static int intersect(const col_xing *a, int na, const col_xing *b, int nb, col_xing *out)
{
    int i = 0, j = 0, k = 0;
    while (i + 1 < na && j + 1 < nb) {
        col_xing lo = a[i].t > b[j].t ? a[i] : b[j];
        col_xing hi = a[i + 1].t < b[j + 1].t ? a[i + 1] : b[j + 1];
        if (lo.t <= hi.t) {
            out[k++] = lo;
            out[k++] = hi;
        }
        if (a[i + 1].t < b[j + 1].t) i += 2;
        else j += 2;
    }
    return k;
}

static bool both_sides(const double *d, int n, double tol)
{
    bool pos = false, neg = false;
    for (int i = 0; i < n; ++i) {
        pos |= d[i] > tol;
        neg |= d[i] < -tol;
    }
    return pos && neg;
}

// The part of the face on both sides of the other plane, as intervals along u into out.
static int two_sided(ori_collider *c, const ori_v3 *p, const double *d, int n, ori_v3 u, col_xing *out)
{
    col_work *w = &c->work;
    int np = crossings(p, d, n, c->tol_pen, +1, u, w->xa);
    int nm = crossings(p, d, n, c->tol_pen, -1, u, w->xb);
    return intersect(w->xa, np, w->xb, nm, out);
}

// --- the pair test ---------------------------------------------------------------------------

static bool is_shared(const int *sv, int ns, int v)
{
    for (int i = 0; i < ns; ++i)
        if (sv[i] == v) return true;
    return false;
}

// Faces sharing vertices: whether their parts away from the shared vertices come within the
// contact tolerance (non-shared vertices to the other face, edges without a shared end to each
// other); *point is the contact.
static bool away_touch(ori_collider *c, int f, int g, const int *sv, int ns, ori_v3 *point)
{
    col_work *w = &c->work;
    const col_geom *gf = &c->geom[f], *gg = &c->geom[g];
    int n = face_size(c, f), m = face_size(c, g);
    const int *fv = c->face_verts + c->face_off[f], *gv = c->face_verts + c->face_off[g];
    double tol = c->tol_touch, tol2 = tol * tol;
    bool p2_ready = false, q2_ready = false;
    ori_v3 cp;
    for (int i = 0; i < n; ++i) {
        if (is_shared(sv, ns, fv[i]) || fabs(w->dp[i]) > tol) continue;
        if (!q2_ready) {
            to_frame(gg, w->qq, m, w->q2);
            q2_ready = true;
        }
        if (point_face(gg, w->qq, w->q2, m, w->pp[i], &cp) <= tol) {
            *point = ori_v3_scale(ori_v3_add(w->pp[i], cp), 0.5);
            return true;
        }
    }
    for (int j = 0; j < m; ++j) {
        if (is_shared(sv, ns, gv[j]) || fabs(w->dq[j]) > tol) continue;
        if (!p2_ready) {
            to_frame(gf, w->pp, n, w->p2);
            p2_ready = true;
        }
        if (point_face(gf, w->pp, w->p2, n, w->qq[j], &cp) <= tol) {
            *point = ori_v3_scale(ori_v3_add(w->qq[j], cp), 0.5);
            return true;
        }
    }
    for (int i = 0; i < n; ++i) {
        if (is_shared(sv, ns, fv[i]) || is_shared(sv, ns, fv[(i + 1) % n])) continue;
        for (int j = 0; j < m; ++j) {
            if (is_shared(sv, ns, gv[j]) || is_shared(sv, ns, gv[(j + 1) % m])) continue;
            ori_v3 a = w->pp[i], b = w->pp[(i + 1) % n], q1 = w->qq[j], q2 = w->qq[(j + 1) % m];
            col_box ea = seg_box(a, b), eq = seg_box(q1, q2);
            if (box_gap2(&ea, &eq) > tol2) continue;
            double s, t;
            if (seg_seg2(a, b, q1, q2, &s, &t) <= tol2) {
                *point = ori_v3_scale(ori_v3_add(ori_v3_add(a, ori_v3_scale(ori_v3_sub(b, a), s)),
                                                 ori_v3_add(q1, ori_v3_scale(ori_v3_sub(q2, q1), t))),
                                      0.5);
                return true;
            }
        }
    }
    return false;
}

// Whether the vertices of face f other than the shared ones all lie on one side of the other
// face's plane (signed distances d), beyond the contact tolerance.
static bool one_side_beyond(const ori_collider *c, int f, const double *d, int n, const int *sv, int ns)
{
    const int *fv = c->face_verts + c->face_off[f];
    bool pos = false, neg = false;
    for (int i = 0; i < n; ++i) {
        if (is_shared(sv, ns, fv[i])) continue;
        if (d[i] > c->tol_touch) pos = true;
        else if (d[i] < -c->tol_touch) neg = true;
        else return false;
    }
    return !(pos && neg);
}

// Of face f's vertices other than the shared ones (signed distances d to the other face's
// plane): whether all are beyond the contact tolerance from it (*far), and whether all lie on one
// side of it beyond 1.5 tolerances (*one_side).
static void away_vertices(const ori_collider *c, int f, const double *d, int n, const int *sv, int ns, bool *far,
                          bool *one_side)
{
    const int *fv = c->face_verts + c->face_off[f];
    double tol = c->tol_touch, wide = 1.5 * c->tol_touch;
    bool pos = false, neg = false, near = false;
    *far = true;
    for (int i = 0; i < n; ++i) {
        if (is_shared(sv, ns, fv[i])) continue;
        if (!(fabs(d[i]) > tol)) *far = false;
        if (d[i] > wide) pos = true;
        else if (d[i] < -wide) neg = true;
        else near = true;
    }
    *one_side = !near && !(pos && neg);
}

static bool stacked(ori_collider *c, int f, int g, int n, int m, col_pair_result *out)
{
    col_work *w = &c->work;
    const col_geom *gg = &c->geom[g];
    to_frame(gg, w->pp, n, w->p2);
    to_frame(gg, w->qq, m, w->q2);
    overlap_out o;
    overlap(c, f, w->p2, g, w->q2, c->tol_touch, false, &o);
    if (!o.any) return false;
    out->cls = COL_TOUCH;
    out->stacked = true;
    out->point = from_frame(gg, o.centroid);
    return true;
}

void col_pair_test(ori_collider *c, int f, int g, col_adjacency adjacency, col_pair_result *out)
{
    bool adjacent = adjacency != COL_ADJ_NONE;
    memset(out, 0, sizeof *out);
    out->cls = COL_APART;
    col_work *w = &c->work;
    const col_geom *gf = &c->geom[f], *gg = &c->geom[g];
    // Faces joined by a crease meet only as coplanar layers (below): a vertex of either beyond
    // the contact tolerance from the other's plane ends the test (not in the reference checker).
    if (adjacency == COL_ADJ_CREASE && !c->reference) {
        const int *fv = c->face_verts + c->face_off[f], *gv = c->face_verts + c->face_off[g];
        for (int i = 0; i < face_size(c, f); ++i)
            if (fabs(ori_v3_dot(gg->n, c->pos[fv[i]]) - gg->d) > c->tol_touch) return;
        for (int j = 0; j < face_size(c, g); ++j)
            if (fabs(ori_v3_dot(gf->n, c->pos[gv[j]]) - gf->d) > c->tol_touch) return;
    }
    int n = load(c, f, w->pp), m = load(c, g, w->qq);
    double maxp = 0.0, maxq = 0.0;
    for (int i = 0; i < n; ++i) {
        w->dp[i] = ori_v3_dot(gg->n, w->pp[i]) - gg->d;
        maxp = fmax(maxp, fabs(w->dp[i]));
    }
    for (int j = 0; j < m; ++j) {
        w->dq[j] = ori_v3_dot(gf->n, w->qq[j]) - gf->d;
        maxq = fmax(maxq, fabs(w->dq[j]));
    }
    // Faces sharing no vertex with one of them beyond the distance bound from the other's plane
    // are apart: what the distance test below returns at once from the same separating-plane
    // bound, found here without loading the faces again (not in the reference checker).
    if (!adjacent && !c->reference) {
        double bound = 2.0 * (c->tol_touch > c->clearance ? c->tol_touch : c->clearance);
        if (c->distance_bound > bound) bound = c->distance_bound;
        if (gap_of(w->dp, n) >= bound || gap_of(w->dq, m) >= bound) return;
    }
    bool coplanar = maxp <= c->tol_touch && maxq <= c->tol_touch;
    // Two convex faces joined by a crease lie in half-planes of their common line: away from
    // the crease they can only meet as stacked layers (folded to ±180°).
    if (adjacency == COL_ADJ_CREASE) {
        if (coplanar) stacked(c, f, g, n, m, out);
        return;
    }
    if (coplanar) {
        if (stacked(c, f, g, n, m, out)) return;
    } else if (both_sides(w->dp, n, c->tol_pen) && both_sides(w->dq, m, c->tol_pen)) {
        ori_v3 u = ori_v3_cross(gf->n, gg->n);
        double su = ori_v3_norm(u);
        if (su > ORI_COLLISION_PARALLEL_SIN) {
            u = ori_v3_scale(u, 1.0 / su);
            int na = two_sided(c, w->pp, w->dp, n, u, w->ia);
            int nb = two_sided(c, w->qq, w->dq, m, u, w->ib);
            int nc = intersect(w->ia, na, w->ib, nb, w->ic);
            double longest = -1.0;
            for (int k = 0; k + 1 < nc; k += 2) {
                double len = w->ic[k + 1].t - w->ic[k].t;
                if (len > longest) {
                    longest = len;
                    out->point = ori_v3_scale(ori_v3_add(w->ic[k].p, w->ic[k + 1].p), 0.5);
                }
            }
            if (longest > c->tol_pen) {
                out->cls = COL_CROSS;
                return;
            }
            if (longest >= 0.0 && !adjacent) {
                out->cls = COL_TOUCH;
                return;
            }
        }
    }
    if (!adjacent) {
        // exact below the bound: enough for contact and the clearance, and (when the least
        // clearance is wanted) for every pair nearer than the least distance found so far
        double bound = 2.0 * (c->tol_touch > c->clearance ? c->tol_touch : c->clearance);
        if (c->distance_bound > bound) bound = c->distance_bound;
        double d = col_face_distance(c, f, g, bound, &out->pa, &out->pb);
        if (!(d < bound)) return;
        out->has_distance = true;
        out->distance = d;
        if (out->distance <= c->tol_touch) {
            out->cls = COL_TOUCH;
            out->point = ori_v3_scale(ori_v3_add(out->pa, out->pb), 0.5);
        }
        return;
    }
    // Away from the shared vertices only the other vertices (and the edges between them)
    // count: when each face has them all on one side of the other's plane, beyond the
    // tolerance, nothing else touches.
    int sv[64];
    int ns = col_shared_vertices(c, f, g, sv, 64);
    if (ns <= 64 && one_side_beyond(c, f, w->dp, n, sv, ns) && one_side_beyond(c, g, w->dq, m, sv, ns)) return;
    // Nothing touches away from the shared vertices either when no other vertex is within the
    // tolerance of the other face's plane (the vertex tests below skip them all) and one face's
    // other vertices all lie on one side of the other's plane beyond 1.5 tolerances: its edges
    // without a shared end are then more than 1.25 tolerances from every edge of the other face
    // (which lies within a quarter tolerance of its plane), so no edge test below touches either
    // (not in the reference checker).
    if (!c->reference && ns <= 64) {
        bool fv_far, gv_far, f_side, g_side;
        away_vertices(c, f, w->dp, n, sv, ns, &fv_far, &f_side);
        away_vertices(c, g, w->dq, m, sv, ns, &gv_far, &g_side);
        if (fv_far && gv_far && (f_side || g_side)) return;
    }
    ori_v3 p;
    if (away_touch(c, f, g, sv, ns < 64 ? ns : 64, &p)) {
        out->cls = COL_TOUCH;
        out->point = p;
    }
}
