// Overlap structure of a folded state: the arrangement of the folded edges. Points are the
// folded vertices (snapped together within ε = ORI_TOL_LAYERS_SNAP_REL × the folded image's
// diagonal) and the crossings of folded edges; segments are the pieces of folded edges between
// consecutive points (each lists every edge lying along it); cells are the bounded faces of the
// resulting planar graph. Every face of the pattern covers a set of cells, found by a flood
// fill from one of its sides that never crosses its own boundary.
//
// Robustness: a decision on computed coordinates is taken only when the distance involved is
// either at most ε (the features meet) or beyond ORI_LAYERS_AMBIGUITY_FACTOR × ε (they do not);
// anything in between is refused with the element named, rather than guessed. A uniform grid
// over the folded image keeps point-on-segment and crossing tests local.
#include "layers_internal.h"

#include <stdlib.h>

#include "../geometry/geometry_internal.h"

typedef struct work {
    ori_layers *L;
    double eps, band;
    double noise;       // the largest distance taken for "the same" (snapped, on an edge)
    double x0, y0;      // lower-left corner of the point grid
    ori__imap cells;    // point grid cell → first point
    int *next;          // chain of points in a cell
    int np, pcap;
    ori_v2 *pts;
    int *origin;        // a vertex at each point (-1 for crossings)
    // base segments: distinct point pairs of the edges
    int nb;
    int (*bp)[2];
    int *vp;            // vertex → point
    int *e_base;        // edge → base segment
    uint8_t *e_rev;     // edge runs q → p of its base segment
    // incidences: points strictly inside base segments
    struct inc {
        int s, r;
        double t;
    } *inc;
    int ninc, inccap;
    // uniform grid over the base segments
    int gx, gy;
    double gw, gh, gx0, gy0;
    int64_t *goff;
    int *gitems;
} work;

static uint64_t cell_key(int64_t ix, int64_t iy)
{
    // Offset so that small negative indices never make the map's reserved key UINT64_MAX.
    return ((uint64_t)(uint32_t)(ix + 0x40000000) << 32) | (uint64_t)(uint32_t)(iy + 0x40000000);
}

// The point within ε of q (snapping q to it), or a new point. Fails when a point lies in the
// ambiguous band (ε, band]; *clash is then that point.
static int add_point(work *w, ori_v2 q, int origin, int *clash)
{
    int64_t ix = (int64_t)floor((q.x - w->x0) / w->band), iy = (int64_t)floor((q.y - w->y0) / w->band);
    int best = -1;
    double best_d = 0.0;
    for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy) {
            for (int r = ori__imap_get(&w->cells, cell_key(ix + dx, iy + dy)); r >= 0; r = w->next[r]) {
                double d = ori_v2_norm(ori_v2_sub(w->pts[r], q));
                if (d <= w->eps) {
                    if (best < 0 || d < best_d) {
                        best = r;
                        best_d = d;
                    }
                } else if (d <= w->band) {
                    *clash = r;
                    return -1;
                }
            }
        }
    if (best >= 0) {
        if (best_d > w->noise) w->noise = best_d;
        return best;
    }
    if (w->np == w->pcap) {
        w->pcap = w->pcap ? 2 * w->pcap : 64;
        w->pts = ori__realloc(w->pts, sizeof(ori_v2) * (size_t)w->pcap);
        w->next = ori__realloc(w->next, sizeof(int) * (size_t)w->pcap);
        w->origin = ori__realloc(w->origin, sizeof(int) * (size_t)w->pcap);
    }
    int r = w->np++;
    w->pts[r] = q;
    w->origin[r] = origin;
    // The map keeps the first point of each grid cell; later ones chain after it.
    uint64_t key = cell_key(ix, iy);
    int head = ori__imap_get(&w->cells, key);
    if (head < 0) {
        w->next[r] = -1;
        ori__imap_put(&w->cells, key, r);
    } else {
        w->next[r] = w->next[head];
        w->next[head] = r;
    }
    return r;
}

static void push_inc(work *w, int s, int r, double t)
{
    if (w->ninc == w->inccap) {
        w->inccap = w->inccap ? 2 * w->inccap : 256;
        w->inc = ori__realloc(w->inc, sizeof(*w->inc) * (size_t)w->inccap);
    }
    w->inc[w->ninc].s = s;
    w->inc[w->ninc].r = r;
    w->inc[w->ninc].t = t;
    w->ninc++;
}

static int cmp_inc(const void *a, const void *b)
{
    const struct inc *x = a, *y = b;
    if (x->s != y->s) return x->s < y->s ? -1 : 1;
    if (x->t != y->t) return x->t < y->t ? -1 : 1;
    return (x->r > y->r) - (x->r < y->r);
}

static int grid_col(const work *w, double x)
{
    int i = (int)floor((x - w->gx0) / w->gw);
    return i < 0 ? 0 : i >= w->gx ? w->gx - 1 : i;
}

static int grid_row(const work *w, double y)
{
    int j = (int)floor((y - w->gy0) / w->gh);
    return j < 0 ? 0 : j >= w->gy ? w->gy - 1 : j;
}

// Enter every base segment in the grid cells within `band` of it (two passes: count, fill).
static void build_grid(work *w)
{
    int64_t ncell = (int64_t)w->gx * w->gy;
    w->goff = ori__calloc((size_t)ncell + 1, sizeof(int64_t));
    for (int pass = 0; pass < 2; ++pass) {
        int64_t *fill = NULL;
        if (pass == 1) {
            for (int64_t c = 0; c < ncell; ++c) w->goff[c + 1] += w->goff[c];
            w->gitems = ori__alloc(sizeof(int) * (size_t)(w->goff[ncell] ? w->goff[ncell] : 1));
            fill = ori__alloc(sizeof(int64_t) * (size_t)ncell);
            memcpy(fill, w->goff, sizeof(int64_t) * (size_t)ncell);
        }
        for (int s = 0; s < w->nb; ++s) {
            ori_v2 a = w->pts[w->bp[s][0]], b = w->pts[w->bp[s][1]];
            if (a.x > b.x) {
                ori_v2 t = a;
                a = b;
                b = t;
            }
            int i0 = grid_col(w, a.x - w->band), i1 = grid_col(w, b.x + w->band);
            for (int i = i0; i <= i1; ++i) {
                double xl = w->gx0 + i * w->gw - w->band, xr = w->gx0 + (i + 1) * w->gw + w->band;
                double lo, hi;
                ori__segment_y_range(a, b, xl, xr, &lo, &hi);
                int j0 = grid_row(w, lo - w->band), j1 = grid_row(w, hi + w->band);
                for (int j = j0; j <= j1; ++j) {
                    int64_t c = (int64_t)j * w->gx + i;
                    if (pass == 0) w->goff[c + 1]++;
                    else w->gitems[fill[c]++] = s;
                }
            }
        }
        ori__free(fill);
    }
}

// Point r against every base segment near it: on it (within ε, strictly between its ends),
// or ambiguous. Returns false (error set) on an ambiguity.
static bool point_on_segments(work *w, int r, ori_error *error)
{
    ori_v2 q = w->pts[r];
    int64_t c = (int64_t)grid_row(w, q.y) * w->gx + grid_col(w, q.x);
    for (int64_t k = w->goff[c]; k < w->goff[c + 1]; ++k) {
        int s = w->gitems[k];
        int pa = w->bp[s][0], pb = w->bp[s][1];
        if (r == pa || r == pb) continue;
        ori_v2 a = w->pts[pa], b = w->pts[pb];
        ori_v2 d = ori_v2_sub(b, a);
        double len = ori_v2_norm(d);
        ori_v2 rel = ori_v2_sub(q, a);
        double along = ori_v2_dot(rel, d) / len, off = fabs(ori_v2_cross(d, rel)) / len;
        if (off > w->band || along <= 0.0 || along >= len) continue;
        if (off <= w->eps) {
            if (off > w->noise) w->noise = off;
            push_inc(w, s, r, along / len);
            continue;
        }
        int e = -1;
        for (int x = 0; x < w->L->ne && e < 0; ++x)
            if (w->e_base[x] == s) e = x;
        w->L->fail_amb = off / (w->eps / w->L->snap_rel);
        if (w->origin[r] >= 0) {
            ori__fail_at(error, ORI_ERR_DEGENERATE, "vertices_coords", w->origin[r],
                         "folded, the vertex lies %.3g (relative) from edge %d: the coordinates do not say "
                         "whether it is on the edge",
                         off / (w->eps / w->L->snap_rel), e);
        } else {
            ori__fail_at(error, ORI_ERR_DEGENERATE, "edges_vertices", e,
                         "folded, the edge passes %.3g (relative) from a crossing of other edges: the "
                         "coordinates do not say whether it passes through it",
                         off / (w->eps / w->L->snap_rel));
        }
        return false;
    }
    return true;
}

// Proper crossings of base segments (each end of either segment more than `band` from the
// other's line, on opposite sides), each handled in the grid cell that contains it.
static bool crossings(work *w, ori_error *error)
{
    int64_t ncell = (int64_t)w->gx * w->gy;
    for (int64_t c = 0; c < ncell; ++c) {
        int cx = (int)(c % w->gx), cy = (int)(c / w->gx);
        for (int64_t k1 = w->goff[c]; k1 < w->goff[c + 1]; ++k1) {
            int s1 = w->gitems[k1];
            ori_v2 a = w->pts[w->bp[s1][0]], b = w->pts[w->bp[s1][1]];
            ori_v2 ab = ori_v2_sub(b, a);
            double lab = ori_v2_norm(ab);
            for (int64_t k2 = k1 + 1; k2 < w->goff[c + 1]; ++k2) {
                int s2 = w->gitems[k2];
                if (w->bp[s1][0] == w->bp[s2][0] || w->bp[s1][0] == w->bp[s2][1] || w->bp[s1][1] == w->bp[s2][0] ||
                    w->bp[s1][1] == w->bp[s2][1])
                    continue;
                ori_v2 p = w->pts[w->bp[s2][0]], q = w->pts[w->bp[s2][1]];
                if (fmax(p.x, q.x) < fmin(a.x, b.x) || fmax(a.x, b.x) < fmin(p.x, q.x) ||
                    fmax(p.y, q.y) < fmin(a.y, b.y) || fmax(a.y, b.y) < fmin(p.y, q.y))
                    continue;
                double dp = ori_v2_cross(ab, ori_v2_sub(p, a)) / lab, dq = ori_v2_cross(ab, ori_v2_sub(q, a)) / lab;
                if (!((dp > w->band && dq < -w->band) || (dp < -w->band && dq > w->band))) continue;
                ori_v2 pq = ori_v2_sub(q, p);
                double lpq = ori_v2_norm(pq);
                double da = ori_v2_cross(pq, ori_v2_sub(a, p)) / lpq, db = ori_v2_cross(pq, ori_v2_sub(b, p)) / lpq;
                if (!((da > w->band && db < -w->band) || (da < -w->band && db > w->band))) continue;
                double u = dp / (dp - dq);
                ori_v2 x = ori_v2_add(p, ori_v2_scale(pq, u));
                if (grid_col(w, x.x) != cx || grid_row(w, x.y) != cy) continue;
                int clash = -1;
                int r = add_point(w, x, -1, &clash);
                if (r < 0) {
                    w->L->fail_amb = ori_v2_norm(ori_v2_sub(w->pts[clash], x)) / (w->eps / w->L->snap_rel);
                    int e = -1;
                    for (int i = 0; i < w->L->ne && e < 0; ++i)
                        if (w->e_base[i] == s1) e = i;
                    ori__fail_at(error, ORI_ERR_DEGENERATE, "edges_vertices", e,
                                 "folded, the edge crosses another one %.3g (relative) from a third feature: the "
                                 "coordinates do not say whether they meet",
                                 ori_v2_norm(ori_v2_sub(w->pts[clash], x)) / (w->eps / w->L->snap_rel));
                    return false;
                }
                double t1 = ori_v2_dot(ori_v2_sub(x, a), ab) / (lab * lab);
                push_inc(w, s1, r, t1);
                push_inc(w, s2, r, u);
            }
        }
    }
    return true;
}

typedef struct hedge_sort {
    double angle;
    int h;
} hedge_sort;

static int cmp_hedge(const void *a, const void *b)
{
    const hedge_sort *x = a, *y = b;
    if (x->angle != y->angle) return x->angle < y->angle ? -1 : 1;
    return (x->h > y->h) - (x->h < y->h);
}

static int cmp_int(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

static void free_work(work *w)
{
    ori__imap_free(&w->cells);
    ori__free(w->next);
    ori__free(w->pts);
    ori__free(w->origin);
    ori__free(w->bp);
    ori__free(w->vp);
    ori__free(w->e_base);
    ori__free(w->e_rev);
    ori__free(w->inc);
    ori__free(w->goff);
    ori__free(w->gitems);
}

ori_status ori__layers_overlap(ori_layers *L, ori_error *error)
{
    work w;
    memset(&w, 0, sizeof w);
    w.L = L;
    ori_status st = ORI_OK;
    int nv = L->nv, ne = L->ne;

    double lo_x = 1e300, lo_y = 1e300, hi_x = -1e300, hi_y = -1e300;
    for (int v = 0; v < nv; ++v) {
        lo_x = fmin(lo_x, L->vf[v].x);
        hi_x = fmax(hi_x, L->vf[v].x);
        lo_y = fmin(lo_y, L->vf[v].y);
        hi_y = fmax(hi_y, L->vf[v].y);
    }
    double diag = nv ? hypot(hi_x - lo_x, hi_y - lo_y) : 1.0;
    if (!(diag > 0.0)) diag = 1.0;
    w.eps = L->snap_rel * diag;
    w.band = w.eps * ORI_LAYERS_AMBIGUITY_FACTOR;
    w.x0 = lo_x;
    w.y0 = lo_y;
    ori__imap_init(&w.cells, nv);

    // 1. Points: the folded vertices, snapped.
    w.vp = ori__alloc(sizeof(int) * (size_t)(nv ? nv : 1));
    for (int v = 0; v < nv; ++v) {
        int clash = -1;
        w.vp[v] = add_point(&w, L->vf[v], v, &clash);
        if (w.vp[v] < 0) {
            L->fail_amb = ori_v2_norm(ori_v2_sub(w.pts[clash], L->vf[v])) / diag;
            st = ori__fail_at(error, ORI_ERR_DEGENERATE, "vertices_coords", v,
                              "folded, the vertex lands %.3g (relative) from vertex %d: the coordinates do not "
                              "say whether they meet",
                              ori_v2_norm(ori_v2_sub(w.pts[clash], L->vf[v])) / diag, w.origin[clash]);
            goto done;
        }
    }

    // 2. Base segments: distinct point pairs of the edges.
    {
        ori__imap pairs;
        ori__imap_init(&pairs, ne);
        w.e_base = ori__alloc(sizeof(int) * (size_t)(ne ? ne : 1));
        w.e_rev = ori__calloc((size_t)(ne ? ne : 1), 1);
        w.bp = ori__alloc(sizeof(*w.bp) * (size_t)(ne ? ne : 1));
        for (int e = 0; e < ne; ++e) {
            int p = w.vp[L->ev[e][0]], q = w.vp[L->ev[e][1]];
            if (p == q) {
                // Shorter than the snapping length: only a shorter one keeps the edge.
                L->fail_amb = ORI_LAYERS_AMBIGUITY_FACTOR *
                              ori_v2_norm(ori_v2_sub(L->vf[L->ev[e][1]], L->vf[L->ev[e][0]])) / diag;
                ori__imap_free(&pairs);
                st = ori__fail_at(error, ORI_ERR_DEGENERATE, "edges_vertices", e,
                                  "folded, the edge shrinks to a point (shorter than the snapping length)");
                goto done;
            }
            uint64_t key = ((uint64_t)(uint32_t)(p < q ? p : q) << 32) | (uint32_t)(p < q ? q : p);
            int s = ori__imap_put(&pairs, key, w.nb);
            if (s == w.nb) {
                w.bp[s][0] = p;
                w.bp[s][1] = q;
                w.nb++;
            }
            w.e_base[e] = s;
            w.e_rev[e] = w.bp[s][0] != p;
        }
        ori__imap_free(&pairs);
    }

    // 3. Grid over the base segments, points on segments, crossings.
    {
        double W = fmax(hi_x - lo_x, 1e-3 * diag), H = fmax(hi_y - lo_y, 1e-3 * diag);
        double per = sqrt((double)w.nb / 2.0);
        int g = (int)ceil(per);
        g = g < 1 ? 1 : g > 1024 ? 1024 : g;
        w.gx = g;
        w.gy = g;
        w.gx0 = lo_x - 2 * w.band;
        w.gy0 = lo_y - 2 * w.band;
        w.gw = (W + 4 * w.band) / g;
        w.gh = (H + 4 * w.band) / g;
        build_grid(&w);
        int vertex_points = w.np;
        for (int r = 0; r < vertex_points; ++r)
            if (!point_on_segments(&w, r, error)) {
                st = ORI_ERR_DEGENERATE;
                goto done;
            }
        if (!crossings(&w, error)) {
            st = ORI_ERR_DEGENERATE;
            goto done;
        }
        for (int r = vertex_points; r < w.np; ++r)
            if (!point_on_segments(&w, r, error)) {
                st = ORI_ERR_DEGENERATE;
                goto done;
            }
    }

    // 4. Segments: the pieces of the base segments between consecutive points.
    if (w.ninc > 1) qsort(w.inc, (size_t)w.ninc, sizeof *w.inc, cmp_inc);
    int nseg = 0, segcap = w.nb + w.ninc + 1;
    int (*sp)[2] = ori__alloc(sizeof(*sp) * (size_t)segcap);
    int64_t *base_off = ori__alloc(sizeof(int64_t) * (size_t)(w.nb + 1));
    int *base_segs = ori__alloc(sizeof(int) * (size_t)segcap);
    int nbase_segs = 0;
    {
        ori__imap segmap;
        ori__imap_init(&segmap, segcap);
        int *chain = ori__alloc(sizeof(int) * (size_t)(w.ninc + 2));
        int k = 0;
        for (int s = 0; s < w.nb; ++s) {
            int n = 0;
            chain[n++] = w.bp[s][0];
            while (k < w.ninc && w.inc[k].s == s) {
                if (w.inc[k].r != chain[n - 1]) chain[n++] = w.inc[k].r;
                k++;
            }
            chain[n++] = w.bp[s][1];
            base_off[s] = nbase_segs;
            for (int i = 0; i + 1 < n; ++i) {
                int p = chain[i], q = chain[i + 1];
                for (int j = 0; j < i; ++j)
                    if (chain[j] == q) {
                        int e = -1;
                        for (int x = 0; x < ne && e < 0; ++x)
                            if (w.e_base[x] == s) e = x;
                        ori__imap_free(&segmap);
                        ori__free(chain);
                        ori__free(sp);
                        ori__free(base_off);
                        ori__free(base_segs);
                        st = ori__fail_at(error, ORI_ERR_DEGENERATE, "edges_vertices", e,
                                          "folded, the points along the edge do not come in one order at the "
                                          "snapping length");
                        goto done;
                    }
                uint64_t key = ((uint64_t)(uint32_t)(p < q ? p : q) << 32) | (uint32_t)(p < q ? q : p);
                int id = ori__imap_put(&segmap, key, nseg);
                if (id == nseg) {
                    sp[nseg][0] = p;
                    sp[nseg][1] = q;
                    nseg++;
                }
                base_segs[nbase_segs++] = id;
            }
        }
        base_off[w.nb] = nbase_segs;
        ori__free(chain);
        ori__imap_free(&segmap);
    }
    L->np = w.np;
    L->pts = ori__alloc(sizeof(ori_v2) * (size_t)(w.np ? w.np : 1));
    memcpy(L->pts, w.pts, sizeof(ori_v2) * (size_t)w.np);
    L->ns = nseg;
    L->seg_pts = ori__realloc(sp, sizeof(*sp) * (size_t)(nseg ? nseg : 1));

    // Edge → segments (from its first vertex), segment → edges.
    {
        L->edge_segs.rows = ne;
        L->edge_segs.off = ori__alloc(sizeof(int64_t) * (size_t)(ne + 1));
        int64_t total = 0;
        for (int e = 0; e < ne; ++e) {
            L->edge_segs.off[e] = total;
            total += base_off[w.e_base[e] + 1] - base_off[w.e_base[e]];
        }
        L->edge_segs.off[ne] = total;
        L->edge_segs.items = ori__alloc(sizeof(int) * (size_t)(total ? total : 1));
        int64_t *cnt = ori__calloc((size_t)nseg + 1, sizeof(int64_t));
        for (int e = 0; e < ne; ++e) {
            int64_t b = base_off[w.e_base[e]], n = base_off[w.e_base[e] + 1] - b;
            for (int64_t i = 0; i < n; ++i) {
                int s = base_segs[b + (w.e_rev[e] ? n - 1 - i : i)];
                L->edge_segs.items[L->edge_segs.off[e] + i] = s;
                cnt[s + 1]++;
            }
        }
        for (int s = 0; s < nseg; ++s) cnt[s + 1] += cnt[s];
        L->seg_edges.rows = nseg;
        L->seg_edges.off = cnt;
        L->seg_edges.items = ori__alloc(sizeof(int) * (size_t)(cnt[nseg] ? cnt[nseg] : 1));
        int64_t *fill = ori__alloc(sizeof(int64_t) * (size_t)(nseg ? nseg : 1));
        memcpy(fill, cnt, sizeof(int64_t) * (size_t)nseg);
        for (int e = 0; e < ne; ++e)
            for (int64_t k = L->edge_segs.off[e]; k < L->edge_segs.off[e + 1]; ++k)
                L->seg_edges.items[fill[L->edge_segs.items[k]]++] = e;
        ori__free(fill);
    }
    ori__free(base_off);
    ori__free(base_segs);

    // 5. Cells: half-edge 2s runs seg_pts[s][0] → [1], 2s + 1 back. Around each point the
    // outgoing half-edges are sorted counter-clockwise; a face walk turns to the next one
    // clockwise from the reverse of the half-edge it arrives on.
    {
        int nh = 2 * nseg;
        int64_t *poff = ori__calloc((size_t)w.np + 1, sizeof(int64_t));
        for (int s = 0; s < nseg; ++s) {
            poff[L->seg_pts[s][0] + 1]++;
            poff[L->seg_pts[s][1] + 1]++;
        }
        for (int r = 0; r < w.np; ++r) poff[r + 1] += poff[r];
        hedge_sort *out = ori__alloc(sizeof(hedge_sort) * (size_t)(nh ? nh : 1));
        int64_t *fill = ori__alloc(sizeof(int64_t) * (size_t)(w.np ? w.np : 1));
        memcpy(fill, poff, sizeof(int64_t) * (size_t)w.np);
        for (int h = 0; h < nh; ++h) {
            int s = h >> 1, from = L->seg_pts[s][h & 1], to = L->seg_pts[s][1 - (h & 1)];
            ori_v2 d = ori_v2_sub(w.pts[to], w.pts[from]);
            out[fill[from]].angle = atan2(d.y, d.x);
            out[fill[from]++].h = h;
        }
        ori__free(fill);
        int *hpos = ori__alloc(sizeof(int) * (size_t)(nh ? nh : 1));
        for (int r = 0; r < w.np; ++r) {
            int64_t b = poff[r], n = poff[r + 1] - b;
            qsort(out + b, (size_t)n, sizeof(hedge_sort), cmp_hedge);
            for (int64_t i = 0; i < n; ++i) {
                hpos[out[b + i].h] = (int)i;
                if (i > 0 && out[b + i].angle == out[b + i - 1].angle) {
                    int s = out[b + i].h >> 1;
                    int e = L->seg_edges.items[L->seg_edges.off[s]];
                    ori__free(poff);
                    ori__free(out);
                    ori__free(hpos);
                    st = ori__fail_at(error, ORI_ERR_DEGENERATE, "edges_vertices", e,
                                      "folded, the edge overlaps another one without meeting it at a point");
                    goto done;
                }
            }
        }
        int *hcell = ori__alloc(sizeof(int) * (size_t)(nh ? nh : 1));
        for (int h = 0; h < nh; ++h) hcell[h] = -2;
        int ncell = 0, nouter = 0;
        int *cyc = NULL;
        int ccap = 0;
        int64_t *coff = ori__alloc(sizeof(int64_t) * (size_t)(nh + 1));
        int *citems = ori__alloc(sizeof(int) * (size_t)(nh ? nh : 1));
        int64_t nitems = 0;
        coff[0] = 0;
        for (int h0 = 0; h0 < nh; ++h0) {
            if (hcell[h0] != -2) continue;
            int n = 0;
            double area2 = 0.0;
            int h = h0;
            do {
                hcell[h] = -3;
                ORI__PUSH(cyc, n, ccap, h);
                int s = h >> 1, from = L->seg_pts[s][h & 1], to = L->seg_pts[s][1 - (h & 1)];
                area2 += ori_v2_cross(w.pts[from], w.pts[to]);
                int tw = h ^ 1;
                int64_t b = poff[to], deg = poff[to + 1] - b;
                h = out[b + (hpos[tw] + deg - 1) % deg].h;
            } while (h != h0);
            int id;
            if (area2 > 0.0) {
                id = ncell++;
                for (int i = 0; i < n; ++i) citems[nitems++] = cyc[i];
                coff[ncell] = nitems;
            } else {
                id = -1;
                nouter++;
            }
            for (int i = 0; i < n; ++i) hcell[cyc[i]] = id;
        }
        ori__free(cyc);
        ori__free(poff);
        ori__free(out);
        ori__free(hpos);
        L->nc = ncell;
        L->cell_segs.rows = ncell;
        L->cell_segs.off = ori__realloc(coff, sizeof(int64_t) * (size_t)(ncell + 1));
        L->cell_segs.items = ori__realloc(citems, sizeof(int) * (size_t)(nitems ? nitems : 1));
        L->seg_cells = ori__alloc(sizeof(*L->seg_cells) * (size_t)(nseg ? nseg : 1));
        for (int s = 0; s < nseg; ++s) {
            L->seg_cells[s][0] = hcell[2 * s];
            L->seg_cells[s][1] = hcell[2 * s + 1];
        }
        ori__free(hcell);
        if (nouter != 1) {
            st = ori__fail(error, ORI_ERR_DEGENERATE,
                           "the folded image's outline is %d closed curves instead of one: the overlap structure "
                           "is inconsistent at the snapping length",
                           nouter);
            goto done;
        }
    }

    // 6. Cells under each face: flood fill from the inner side of one of its edges, never
    // crossing its own boundary.
    {
        int nf = L->nf, nc = L->nc;
        int *stamp = ori__alloc(sizeof(int) * (size_t)(nseg ? nseg : 1));
        for (int s = 0; s < nseg; ++s) stamp[s] = -1;
        int *seen = ori__alloc(sizeof(int) * (size_t)(nc ? nc : 1));
        for (int c = 0; c < nc; ++c) seen[c] = -1;
        int *queue = ori__alloc(sizeof(int) * (size_t)(nc ? nc : 1));
        int64_t *foff = ori__alloc(sizeof(int64_t) * (size_t)(nf + 1));
        int *fitems = NULL;
        int64_t nfi = 0, ficap = 0;
        foff[0] = 0;
        for (int f = 0; f < nf; ++f) {
            int start_edge = -1;
            for (int64_t k = L->face_edges.off[f]; k < L->face_edges.off[f + 1]; ++k) {
                int e = L->face_edges.items[k];
                for (int64_t j = L->edge_segs.off[e]; j < L->edge_segs.off[e + 1]; ++j) stamp[L->edge_segs.items[j]] = f;
                if (start_edge < 0 && (L->ef[e][0] == f) != (L->ef[e][1] == f)) start_edge = e;
            }
            if (start_edge < 0) {
                st = ori__fail_at(error, ORI_ERR_TOPOLOGY, "faces_vertices", f, "face has no side with another face or the outside across it");
                ori__free(fitems);
                ori__free(foff);
                ori__free(stamp);
                ori__free(seen);
                ori__free(queue);
                goto done;
            }
            int e = start_edge;
            int s0 = L->edge_segs.items[L->edge_segs.off[e]];
            int h = 2 * s0 + (L->seg_pts[s0][0] == w.vp[L->ev[e][0]] ? 0 : 1);
            bool left = (L->ef[e][0] == f) != (L->flip[f] != 0);
            int c0 = L->seg_cells[s0][(h & 1) ^ (left ? 0 : 1)];
            int head = 0, tail = 0;
            bool bad = c0 < 0;
            if (!bad) {
                queue[tail++] = c0;
                seen[c0] = f;
            }
            while (!bad && head < tail) {
                int c = queue[head++];
                if (nfi == ficap) {
                    ficap = ficap ? 2 * ficap : 1024;
                    fitems = ori__realloc(fitems, sizeof(int) * (size_t)ficap);
                }
                fitems[nfi++] = c;
                for (int64_t k = L->cell_segs.off[c]; k < L->cell_segs.off[c + 1]; ++k) {
                    int hh = L->cell_segs.items[k], s = hh >> 1;
                    if (stamp[s] == f) continue;
                    int c2 = L->seg_cells[s][1 - (hh & 1)];
                    if (c2 < 0) {
                        bad = true;
                        break;
                    }
                    if (seen[c2] != f) {
                        seen[c2] = f;
                        queue[tail++] = c2;
                    }
                }
            }
            if (bad) {
                st = ori__fail_at(error, ORI_ERR_DEGENERATE, "faces_vertices", f,
                                  "folded, the face's outline does not close in the overlap structure at the "
                                  "snapping length");
                ori__free(fitems);
                ori__free(foff);
                ori__free(stamp);
                ori__free(seen);
                ori__free(queue);
                goto done;
            }
            if (nfi - foff[f] > 1) qsort(fitems + foff[f], (size_t)(nfi - foff[f]), sizeof(int), cmp_int);
            foff[f + 1] = nfi;
        }
        ori__free(stamp);
        ori__free(seen);
        ori__free(queue);
        L->face_cells.rows = nf;
        L->face_cells.off = foff;
        L->face_cells.items = fitems ? fitems : ori__alloc(sizeof(int));
        // Transpose: faces over each cell, ascending.
        int64_t *coff = ori__calloc((size_t)nc + 1, sizeof(int64_t));
        for (int64_t i = 0; i < nfi; ++i) coff[fitems[i] + 1]++;
        for (int c = 0; c < nc; ++c) coff[c + 1] += coff[c];
        int *citems = ori__alloc(sizeof(int) * (size_t)(nfi ? nfi : 1));
        int64_t *fill = ori__alloc(sizeof(int64_t) * (size_t)(nc ? nc : 1));
        memcpy(fill, coff, sizeof(int64_t) * (size_t)nc);
        for (int f = 0; f < nf; ++f)
            for (int64_t k = foff[f]; k < foff[f + 1]; ++k) citems[fill[L->face_cells.items[k]]++] = f;
        ori__free(fill);
        L->cell_faces.rows = nc;
        L->cell_faces.off = coff;
        L->cell_faces.items = citems;
    }

done:
    if (w.noise / diag > L->noise_len) L->noise_len = w.noise / diag;
    free_work(&w);
    return st;
}
