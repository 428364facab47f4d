// The thesis' "cloud of proximity" (ch. 5.4): sample points on every face — its vertices, its
// edges divided into pieces at most the spacing long, and a square grid of that spacing inside
// it, all fixed on the face so that they move with it — and report the sample pairs of faces
// sharing no vertex that come closer than a distance. A uniform grid of cells as wide as the
// distance finds them: each sample meets only the samples of its own and the 26 neighbouring
// cells. Kept as the thesis describes it, as an approximation and a cross-check of the exact
// clearance (collider.c): its least distance is never below the exact one, and above it by at
// most the distance from a point of a face to its nearest sample on either face.
#include <stdlib.h>

#include "../core/hash.h"
#include "collision_internal.h"

ori_cloud_def ori_default_cloud_def(void)
{
    ori_cloud_def d;
    memset(&d, 0, sizeof d);
    d.spacing = 0.0;
    d.distance = 0.0;
    d.max_points = ORI_CLOUD_MAX_POINTS;
    d.internal_value = ORI__DEF_COOKIE;
    return d;
}

typedef struct sample {
    int64_t cell[3];
    ori_v3 p;
    int face;
} sample;

static int cmp_cell(const int64_t *a, const int64_t *b)
{
    for (int k = 0; k < 3; ++k)
        if (a[k] != b[k]) return (a[k] > b[k]) - (a[k] < b[k]);
    return 0;
}

static int cmp_sample(const void *x, const void *y)
{
    const sample *a = x, *b = y;
    int r = cmp_cell(a->cell, b->cell);
    if (r) return r;
    return (a->face > b->face) - (a->face < b->face);
}

static int cmp_pair(const void *x, const void *y)
{
    const ori_cloud_pair *a = x, *b = y;
    if (a->face_a != b->face_a) return (a->face_a > b->face_a) - (a->face_a < b->face_a);
    return (a->face_b > b->face_b) - (a->face_b < b->face_b);
}

// Even–odd test (same rule as narrow.c; boundary samples come from the edges instead).
static bool inside(const ori_v2 *poly, int n, ori_v2 x)
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

// Samples of face f: appended to *out when out is not NULL; returns their number.
static int64_t face_samples(ori_collider *c, int f, double h, sample **out, int64_t *count, int64_t *cap)
{
    const col_geom *g = &c->geom[f];
    const int *fv = c->face_verts + c->face_off[f];
    int n = c->face_off[f + 1] - c->face_off[f];
    ori_v2 *p2 = c->work.p2;
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (int i = 0; i < n; ++i) {
        ori_v3 r = ori_v3_sub(c->pos[fv[i]], g->o);
        p2[i] = ori_v2_make(ori_v3_dot(r, g->e1), ori_v3_dot(r, g->e2));
        xmin = fmin(xmin, p2[i].x);
        xmax = fmax(xmax, p2[i].x);
        ymin = fmin(ymin, p2[i].y);
        ymax = fmax(ymax, p2[i].y);
    }
    int64_t total = 0;
#define EMIT(q2)                                                                                            \
    do {                                                                                                    \
        if (out) {                                                                                          \
            if (*count >= *cap) {                                                                           \
                *cap = *cap ? 2 * *cap : 1024;                                                              \
                sample *grown = ori__alloc(sizeof(sample) * (size_t)*cap);                                  \
                if (*out) memcpy(grown, *out, sizeof(sample) * (size_t)*count);                             \
                ori__free(*out);                                                                            \
                *out = grown;                                                                               \
            }                                                                                               \
            (*out)[*count].p = ori_v3_add(g->o, ori_v3_add(ori_v3_scale(g->e1, (q2).x), ori_v3_scale(g->e2, (q2).y))); \
            (*out)[*count].face = f;                                                                        \
            (*count)++;                                                                                     \
        }                                                                                                   \
        total++;                                                                                            \
    } while (0)
    for (int i = 0; i < n; ++i) {
        ori_v2 a = p2[i], b = p2[(i + 1) % n];
        EMIT(a);
        double len = ori_v2_norm(ori_v2_sub(b, a));
        int64_t k = (int64_t)ceil(len / h);
        for (int64_t j = 1; j < k; ++j) {
            ori_v2 q = ori_v2_add(a, ori_v2_scale(ori_v2_sub(b, a), (double)j / (double)k));
            EMIT(q);
        }
    }
    // interior grid anchored at the face's first vertex (fixed on the face)
    double x0 = p2[0].x + h * floor((xmin - p2[0].x) / h), y0 = p2[0].y + h * floor((ymin - p2[0].y) / h);
    int64_t nx = (int64_t)floor((xmax - x0) / h) + 1, ny = (int64_t)floor((ymax - y0) / h) + 1;
    for (int64_t iy = 0; iy < ny; ++iy)
        for (int64_t ix = 0; ix < nx; ++ix) {
            ori_v2 q = ori_v2_make(x0 + (double)ix * h, y0 + (double)iy * h);
            if (inside(p2, n, q)) EMIT(q);
        }
#undef EMIT
    return total;
}

// Upper bound of face f's samples (to refuse a cloud before allocating it).
static double face_sample_bound(ori_collider *c, int f, double h)
{
    const col_box *b = &c->boxes[f];
    double ext = ori_v3_norm(ori_v3_sub(b->hi, b->lo));
    int n = c->face_off[f + 1] - c->face_off[f];
    return (ext / h + 2.0) * (ext / h + 2.0) + (double)n * (ext / h + 2.0);
}

typedef struct pair_map {
    uint64_t *key;
    int *idx;
    int cap, n;
} pair_map;

static int pair_slot(ori_collider *c, pair_map *m, int a, int b)
{
    uint64_t k = ori__pair_key(a, b);
    if (2 * (m->n + 1) > m->cap) {
        pair_map old = *m;
        m->cap = ori__hash_capacity(m->n + 1);
        m->key = ori__alloc(sizeof(uint64_t) * (size_t)m->cap);
        m->idx = ori__alloc(sizeof(int) * (size_t)m->cap);
        for (int i = 0; i < m->cap; ++i) m->key[i] = UINT64_MAX;
        for (int i = 0; i < old.cap; ++i) {
            if (old.key[i] == UINT64_MAX) continue;
            int mask = m->cap - 1, s = (int)(ori__mix64(old.key[i]) & (uint64_t)mask);
            while (m->key[s] != UINT64_MAX) s = (s + 1) & mask;
            m->key[s] = old.key[i];
            m->idx[s] = old.idx[i];
        }
        ori__free(old.key);
        ori__free(old.idx);
    }
    int mask = m->cap - 1, s = (int)(ori__mix64(k) & (uint64_t)mask);
    while (m->key[s] != UINT64_MAX && m->key[s] != k) s = (s + 1) & mask;
    if (m->key[s] == k) return m->idx[s];
    m->key[s] = k;
    m->idx[s] = c->cloud_pair_count;
    m->n++;
    ori_cloud_pair p;
    memset(&p, 0, sizeof p);
    p.face_a = a;
    p.face_b = b;
    p.distance = INFINITY;
    ORI__PUSH(c->cloud_pairs, c->cloud_pair_count, c->cloud_pair_cap, p);
    return c->cloud_pair_count - 1;
}

ori_status ori_collider_cloud(ori_collider *c, const ori_v3 *positions, const ori_cloud_def *def, ori_cloud_result *out,
                              ori_error *error)
{
    ORI_ASSERT(c && positions && def && out && def->internal_value == ORI__DEF_COOKIE);
    ori_error_clear(error);
    memset(out, 0, sizeof *out);
    out->min_distance = INFINITY;
    c->cloud_pair_count = 0;
    double least = ORI_TOL_CONTACT_REL * c->diagonal;
    if (!(def->spacing >= least) || !isfinite(def->spacing))
        return ori__fail(error, ORI_ERR_RANGE, "the sample spacing must be a length >= %g (%g of the pattern's size), got %g",
                         least, ORI_TOL_CONTACT_REL, def->spacing);
    if (!(def->distance >= least) || !isfinite(def->distance))
        return ori__fail(error, ORI_ERR_RANGE, "the proximity distance must be a length >= %g (%g of the pattern's size), got %g",
                         least, ORI_TOL_CONTACT_REL, def->distance);
    ori_status st = col_state_prepare(c, positions, error);
    if (st != ORI_OK) return st;
    double h = def->spacing, dist = def->distance;
    double bound = 0.0;
    for (int f = 0; f < c->face_count; ++f) bound += face_sample_bound(c, f, h);
    if (bound > (double)def->max_points)
        return ori__fail(error, ORI_ERR_LIMIT, "a spacing of %g gives up to %.3g samples (at most %lld): use a larger spacing",
                         h, bound, (long long)def->max_points);
    sample *s = NULL;
    int64_t n = 0, cap = 0;
    for (int f = 0; f < c->face_count; ++f) face_samples(c, f, h, &s, &n, &cap);
    for (int64_t i = 0; i < n; ++i) {
        s[i].cell[0] = (int64_t)floor(s[i].p.x / dist);
        s[i].cell[1] = (int64_t)floor(s[i].p.y / dist);
        s[i].cell[2] = (int64_t)floor(s[i].p.z / dist);
    }
    if (n > 1) qsort(s, (size_t)n, sizeof(sample), cmp_sample);
    out->points = n;
    pair_map map = {NULL, NULL, 0, 0};
    // cell runs: for every sample, the samples of the 27 cells around it that sort after it
    for (int64_t i = 0; i < n; ++i) {
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    int64_t want[3] = {s[i].cell[0] + dx, s[i].cell[1] + dy, s[i].cell[2] + dz};
                    // first sample of that cell (binary search)
                    int64_t lo = 0, hi = n;
                    while (lo < hi) {
                        int64_t mid = lo + (hi - lo) / 2;
                        if (cmp_cell(s[mid].cell, want) < 0) lo = mid + 1;
                        else hi = mid;
                    }
                    for (int64_t j = lo; j < n && cmp_cell(s[j].cell, want) == 0; ++j) {
                        if (j <= i) continue;
                        int a = s[i].face, b = s[j].face;
                        if (a == b || col_adjacency_of(c, a, b) != COL_ADJ_NONE) continue;
                        double d = ori_v3_norm(ori_v3_sub(s[i].p, s[j].p));
                        if (!(d < dist)) continue;
                        out->point_pairs++;
                        int fa = a < b ? a : b, fb = a < b ? b : a;
                        int k = pair_slot(c, &map, fa, fb);
                        ori_cloud_pair *p = &c->cloud_pairs[k];
                        p->point_pairs++;
                        if (d < p->distance) {
                            p->distance = d;
                            p->points[0] = a < b ? s[i].p : s[j].p;
                            p->points[1] = a < b ? s[j].p : s[i].p;
                        }
                        if (d < out->min_distance) out->min_distance = d;
                    }
                }
    }
    ori__free(map.key);
    ori__free(map.idx);
    ori__free(s);
    if (c->cloud_pair_count > 1) qsort(c->cloud_pairs, (size_t)c->cloud_pair_count, sizeof(ori_cloud_pair), cmp_pair);
    out->face_pairs = c->cloud_pair_count;
    return ORI_OK;
}

int ori_collider_cloud_pair_count(const ori_collider *c)
{
    ORI_ASSERT(c);
    return c->cloud_pair_count;
}

ori_cloud_pair ori_collider_cloud_pair(const ori_collider *c, int index)
{
    ORI_ASSERT(c && index >= 0 && index < c->cloud_pair_count);
    return c->cloud_pairs[index];
}
