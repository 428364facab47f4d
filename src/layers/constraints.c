// Variables and constraints of the layer problem (Flat-Folder's model).
//
// Variables: the pairs of faces over a common cell. Rather than all pairs of every cell (the sum
// of k² over the cells), a pair is found where one of its faces enters a cell across a segment
// of its own boundary, plus all pairs of one cell per connected region of the folded image.
//
// Constraints, from edges lying along a common segment (sides decided per segment from the
// folded geometry: a folded crease has both faces on one side, a flat one has one on each):
//   taco-taco          two folded creases, all four faces on one side: the folds may nest or
//                      follow each other but not interleave;
//   taco-tortilla      a folded crease and a flat edge (or a face passing across the crease's
//                      segment): the tortilla is not between the taco's faces;
//   tortilla-tortilla  two flat edges (or a face across a flat crease): the faces on one side
//                      are ordered as those on the other side;
//   transitivity       three faces over one cell: no cycle. Kept implicit as "stacks": the
//                      distinct face sets of the cells that are not contained in a
//                      neighbouring cell's set, each a set of faces that must be totally ordered.
#include "layers_internal.h"

#include <stdlib.h>

static bool sorted_has(const int *a, int64_t n, int x)
{
    int64_t lo = 0, hi = n;
    while (lo < hi) {
        int64_t mid = (lo + hi) / 2;
        if (a[mid] < x) lo = mid + 1;
        else hi = mid;
    }
    return lo < n && a[lo] == x;
}

int ori__layers_var(const ori_layers *L, int f, int g)
{
    const int *row = L->face_nbrs.items + L->face_nbrs.off[f];
    int64_t lo = 0, hi = L->face_nbrs.off[f + 1] - L->face_nbrs.off[f];
    int64_t n = hi;
    while (lo < hi) {
        int64_t mid = (lo + hi) / 2;
        if (row[mid] < g) lo = mid + 1;
        else hi = mid;
    }
    if (lo < n && row[lo] == g) return L->face_nbr_var[L->face_nbrs.off[f] + lo];
    return -1;
}

static uint64_t pair_key(int a, int b)
{
    return ((uint64_t)(uint32_t)(a < b ? a : b) << 32) | (uint32_t)(a < b ? b : a);
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

#define CELL_FACES(L, c) ((L)->cell_faces.items + (L)->cell_faces.off[c])
#define CELL_SIZE(L, c) ((L)->cell_faces.off[(c) + 1] - (L)->cell_faces.off[c])

static ori_status build_variables(ori_layers *L)
{
    ori__imap pairs;
    ori__imap_init(&pairs, 1024);
    uint64_t *keys = NULL;
    int nkeys = 0, kcap = 0;
#define ADD_PAIR(f, g)                                                                                     \
    do {                                                                                                   \
        uint64_t key_ = pair_key((f), (g));                                                                \
        if (ori__imap_put(&pairs, key_, nkeys) == nkeys) ORI__PUSH(keys, nkeys, kcap, key_);               \
    } while (0)

    // One seed cell per connected region of the image (cells joined across segments).
    int *root = ori__alloc(sizeof(int) * (size_t)(L->nc ? L->nc : 1));
    for (int c = 0; c < L->nc; ++c) root[c] = c;
    for (int s = 0; s < L->ns; ++s) {
        int a = L->seg_cells[s][0], b = L->seg_cells[s][1];
        if (a < 0 || b < 0) continue;
        a = ori__uf_root(root, a);
        b = ori__uf_root(root, b);
        if (a != b) root[a] = b;
    }
    for (int c = 0; c < L->nc; ++c)
        if (ori__uf_root(root, c) == c) {
            const int *F = CELL_FACES(L, c);
            int64_t n = CELL_SIZE(L, c);
            for (int64_t i = 0; i < n; ++i)
                for (int64_t j = i + 1; j < n; ++j) ADD_PAIR(F[i], F[j]);
        }
    ori__free(root);
    // Faces entering a cell across a segment of their boundary meet every face already there.
    for (int s = 0; s < L->ns; ++s) {
        for (int side = 0; side < 2; ++side) {
            int from = L->seg_cells[s][side], to = L->seg_cells[s][1 - side];
            if (to < 0) continue;
            const int *Ft = CELL_FACES(L, to);
            int64_t nt = CELL_SIZE(L, to);
            for (int64_t k = L->seg_edges.off[s]; k < L->seg_edges.off[s + 1]; ++k) {
                int e = L->seg_edges.items[k];
                for (int i = 0; i < 2; ++i) {
                    int f = L->ef[e][i];
                    if (f < 0 || !sorted_has(Ft, nt, f)) continue;
                    if (from >= 0 && sorted_has(CELL_FACES(L, from), CELL_SIZE(L, from), f)) continue;
                    for (int64_t j = 0; j < nt; ++j)
                        if (Ft[j] != f) ADD_PAIR(f, Ft[j]);
                }
            }
        }
    }
#undef ADD_PAIR
    ori__imap_free(&pairs);
    if (nkeys > 1) qsort(keys, (size_t)nkeys, sizeof(uint64_t), cmp_u64);
    L->nvar = nkeys;
    L->var_faces = ori__alloc(sizeof(*L->var_faces) * (size_t)(nkeys ? nkeys : 1));
    int64_t *off = ori__calloc((size_t)L->nf + 1, sizeof(int64_t));
    for (int v = 0; v < nkeys; ++v) {
        L->var_faces[v][0] = (int)(keys[v] >> 32);
        L->var_faces[v][1] = (int)(keys[v] & 0xFFFFFFFFu);
        off[L->var_faces[v][0] + 1]++;
        off[L->var_faces[v][1] + 1]++;
    }
    ori__free(keys);
    for (int f = 0; f < L->nf; ++f) off[f + 1] += off[f];
    L->face_nbrs.rows = L->nf;
    L->face_nbrs.off = off;
    L->face_nbrs.items = ori__alloc(sizeof(int) * (size_t)(off[L->nf] ? off[L->nf] : 1));
    L->face_nbr_var = ori__alloc(sizeof(int) * (size_t)(off[L->nf] ? off[L->nf] : 1));
    int64_t *fill = ori__alloc(sizeof(int64_t) * (size_t)(L->nf ? L->nf : 1));
    memcpy(fill, off, sizeof(int64_t) * (size_t)L->nf);
    // Variables are sorted by (a, b): each face's row comes out ascending.
    for (int v = 0; v < nkeys; ++v) {
        int a = L->var_faces[v][0], b = L->var_faces[v][1];
        L->face_nbrs.items[fill[b]] = a;
        L->face_nbr_var[fill[b]++] = v;
    }
    for (int v = 0; v < nkeys; ++v) {
        int a = L->var_faces[v][0], b = L->var_faces[v][1];
        L->face_nbrs.items[fill[a]] = b;
        L->face_nbr_var[fill[a]++] = v;
    }
    ori__free(fill);
    // Rows got the smaller neighbours first, then the larger ones: both parts ascending.
    return ORI_OK;
}

// Side of face f (one of edge e's faces) relative to segment s of e: 0 left of
// seg_pts[s][0] → [1], 1 right.
static int face_side(const ori_layers *L, int e, int f, int s)
{
    ori_v2 de = ori_v2_sub(L->vf[L->ev[e][1]], L->vf[L->ev[e][0]]);
    ori_v2 ds = ori_v2_sub(L->pts[L->seg_pts[s][1]], L->pts[L->seg_pts[s][0]]);
    bool same = ori_v2_dot(de, ds) > 0.0;
    bool left_of_edge = (L->ef[e][0] == f) != (L->flip[f] != 0);
    return (left_of_edge == same) ? 0 : 1;
}

static bool two_faced(const ori_layers *L, int e)
{
    return L->ef[e][0] >= 0 && L->ef[e][1] >= 0 && L->ef[e][0] != L->ef[e][1] && L->asg[e] != ORI_ASSIGN_CUT &&
           L->asg[e] != ORI_ASSIGN_BOUNDARY;
}

typedef struct growing {
    ori__equiv *equiv;
    int ncap;
    ori__taco *taco;
    int tcap;
} growing;

static bool add_equiv(ori_layers *L, growing *g, int kind, int x1, int y1, int x2, int y2, const int faces[4])
{
    int l1 = ori__layers_above(L, x1, y1), l2 = ori__layers_above(L, x2, y2);
    if (l1 < 0 || l2 < 0) return false;
    ori__equiv q;
    q.lit[0] = l1;
    q.lit[1] = l2;
    q.kind = kind;
    memcpy(q.faces, faces, sizeof q.faces);
    ORI__PUSH(g->equiv, L->n_equiv, g->ncap, q);
    L->count_kind[kind]++;
    return true;
}

static bool add_taco(ori_layers *L, growing *g, int a, int b, int c, int d)
{
    ori__taco t;
    t.faces[0] = a;
    t.faces[1] = b;
    t.faces[2] = c;
    t.faces[3] = d;
    const int pr[6][2] = {{a, b}, {a, c}, {a, d}, {b, c}, {b, d}, {c, d}};
    for (int i = 0; i < 6; ++i) {
        t.lit[i] = ori__layers_above(L, pr[i][0], pr[i][1]);
        if (t.lit[i] < 0) return false;
    }
    ORI__PUSH(g->taco, L->n_taco, g->tcap, t);
    L->count_kind[ORI_LAYERS_TACO_TACO]++;
    return true;
}

static ori_status edge_constraints(ori_layers *L, growing *g, ori_error *error)
{
    ori__imap seen_pairs, seen_cross;
    ori__imap_init(&seen_pairs, 1024);
    ori__imap_init(&seen_cross, 1024);
    int *common = NULL;
    int ccap = 0;
    ori_status st = ORI_OK;
    for (int s = 0; s < L->ns && st == ORI_OK; ++s) {
        int64_t b = L->seg_edges.off[s], n = L->seg_edges.off[s + 1] - b;
        const int *E = L->seg_edges.items + b;
        // Edge pairs along the segment.
        for (int64_t i = 0; i < n && st == ORI_OK; ++i) {
            int e1 = E[i];
            if (!two_faced(L, e1)) continue;
            for (int64_t j = i + 1; j < n && st == ORI_OK; ++j) {
                int e2 = E[j];
                if (!two_faced(L, e2)) continue;
                int64_t before = seen_pairs.count;
                ori__imap_put(&seen_pairs, pair_key(e1, e2), 0);
                if (seen_pairs.count == before) continue; // met along another segment already
                int a = L->ef[e1][0], bb = L->ef[e1][1], c = L->ef[e2][0], d = L->ef[e2][1];
                int sa = face_side(L, e1, a, s), sb = face_side(L, e1, bb, s);
                int sc = face_side(L, e2, c, s), sd = face_side(L, e2, d, s);
                bool t1 = sa == sb, t2 = sc == sd;
                bool ok = true;
                int faces[4];
                if (t1 && t2) {
                    if (sa == sc) ok = add_taco(L, g, a, bb, c, d);
                } else if (t1 || t2) {
                    int ta = t1 ? a : c, tb = t1 ? bb : d, side = t1 ? sa : sc;
                    int x = t1 ? c : a, y = t1 ? d : bb, sx = t1 ? sc : sa;
                    int tort = (sx == side) ? x : y;
                    faces[0] = ta;
                    faces[1] = tb;
                    faces[2] = tort;
                    faces[3] = tort;
                    ok = add_equiv(L, g, ORI_LAYERS_TACO_TORTILLA, ta, tort, tb, tort, faces);
                } else {
                    int l1 = sa == 0 ? a : bb, r1 = sa == 0 ? bb : a;
                    int l2 = sc == 0 ? c : d, r2 = sc == 0 ? d : c;
                    faces[0] = l1;
                    faces[1] = r1;
                    faces[2] = l2;
                    faces[3] = r2;
                    ok = add_equiv(L, g, ORI_LAYERS_TORTILLA_TORTILLA, l1, l2, r1, r2, faces);
                }
                if (!ok)
                    st = ori__fail_at(error, ORI_ERR_INTERNAL, "edges_vertices", e1,
                                      "faces along the folded edge and edge %d do not overlap as they must", e2);
            }
        }
        // Faces passing across the segment (over both of its cells).
        int cl = L->seg_cells[s][0], cr = L->seg_cells[s][1];
        if (cl < 0 || cr < 0 || st != ORI_OK) continue;
        const int *A = CELL_FACES(L, cl), *B = CELL_FACES(L, cr);
        int64_t na = CELL_SIZE(L, cl), nb = CELL_SIZE(L, cr);
        int nc = 0;
        for (int64_t i = 0, j = 0; i < na && j < nb;) {
            if (A[i] < B[j]) i++;
            else if (A[i] > B[j]) j++;
            else {
                ORI__PUSH(common, nc, ccap, A[i]);
                i++;
                j++;
            }
        }
        for (int64_t i = 0; i < n && st == ORI_OK; ++i) {
            int e = E[i];
            if (!two_faced(L, e)) continue;
            int a = L->ef[e][0], bb = L->ef[e][1];
            bool taco = face_side(L, e, a, s) == face_side(L, e, bb, s);
            for (int k = 0; k < nc && st == ORI_OK; ++k) {
                int t = common[k];
                if (t == a || t == bb) continue;
                uint64_t key = ((uint64_t)(uint32_t)e << 32) | (uint32_t)t;
                int64_t before = seen_cross.count;
                ori__imap_put(&seen_cross, key, 0);
                if (seen_cross.count == before) continue;
                int faces[4] = {a, bb, t, t};
                bool ok = add_equiv(L, g, taco ? ORI_LAYERS_TACO_TORTILLA : ORI_LAYERS_TORTILLA_TORTILLA, a, t, bb, t,
                                    faces);
                if (!ok)
                    st = ori__fail_at(error, ORI_ERR_INTERNAL, "edges_vertices", e,
                                      "a face across the folded edge does not overlap the edge's faces");
            }
        }
    }
    ori__free(common);
    ori__imap_free(&seen_pairs);
    ori__imap_free(&seen_cross);
    return st;
}

// Face set of cell a is contained in that of cell b.
static bool cell_subset(const ori_layers *L, int a, int b)
{
    const int *A = CELL_FACES(L, a), *B = CELL_FACES(L, b);
    int64_t na = CELL_SIZE(L, a), nb = CELL_SIZE(L, b), j = 0;
    if (na > nb) return false;
    for (int64_t i = 0; i < na; ++i) {
        while (j < nb && B[j] < A[i]) j++;
        if (j == nb || B[j] != A[i]) return false;
        j++;
    }
    return true;
}

// A variable's triples are all (a, b, c) with c in some stack holding a and b. Overlapping
// stacks repeat most of them (a pair of large faces sits in many stacks that differ by a face
// or two), so each variable keeps only the stacks, taken largest first, that bring a third face
// none of the kept ones had: the triples stay the same, the work of propagating them drops
// several times.
static int64_t prune_slots(ori_layers *L)
{
    int64_t thirds = 0;
    int *stamp = ori__alloc(sizeof(int) * (size_t)(L->nf ? L->nf : 1));
    for (int f = 0; f < L->nf; ++f) stamp[f] = -1;
    int64_t w = 0;
    for (int v = 0; v < L->nvar; ++v) {
        int64_t b = L->var_slot_off[v], e = L->var_slot_off[v + 1];
        L->var_slot_off[v] = w;
        stamp[L->var_faces[v][0]] = stamp[L->var_faces[v][1]] = v;
        for (int64_t k = b; k < e; ++k) {
            const ori__stack *S = &L->stacks[L->slots[k].stack];
            const int *F = L->stack_faces + S->faces_at;
            bool fresh = false;
            for (int i = 0; i < S->k; ++i)
                if (stamp[F[i]] != v) {
                    stamp[F[i]] = v;
                    fresh = true;
                    thirds++;
                }
            if (fresh) L->slots[w++] = L->slots[k];
        }
    }
    L->var_slot_off[L->nvar] = w;
    L->slots = ori__realloc(L->slots, sizeof(ori__slot) * (size_t)(w ? w : 1));
    ori__free(stamp);
    return thirds / 3; // each triple is met from its three pairs
}

static const ori_layers *g_sort_layers; // qsort has no context argument (C17)
static uint64_t *g_sort_hash;

static int cmp_cells(const void *x, const void *y)
{
    int a = *(const int *)x, b = *(const int *)y;
    const ori_layers *L = g_sort_layers;
    int64_t na = CELL_SIZE(L, a), nb = CELL_SIZE(L, b);
    if (na != nb) return na < nb ? -1 : 1;
    if (g_sort_hash[a] != g_sort_hash[b]) return g_sort_hash[a] < g_sort_hash[b] ? -1 : 1;
    int c = memcmp(CELL_FACES(L, a), CELL_FACES(L, b), sizeof(int) * (size_t)na);
    if (c) return c;
    return (a > b) - (a < b);
}

#include <pthread.h>
static pthread_mutex_t g_sort_lock = PTHREAD_MUTEX_INITIALIZER;

static ori_status build_stacks(ori_layers *L, ori_error *error)
{
    int nc = L->nc;
    uint8_t *skip = ori__calloc((size_t)(nc ? nc : 1), 1);
    for (int c = 0; c < nc; ++c) skip[c] = CELL_SIZE(L, c) < 3;
    for (int s = 0; s < L->ns; ++s) {
        int a = L->seg_cells[s][0], b = L->seg_cells[s][1];
        if (a < 0 || b < 0) continue;
        if (CELL_SIZE(L, a) < CELL_SIZE(L, b) && cell_subset(L, a, b)) skip[a] = 1;
        else if (CELL_SIZE(L, b) < CELL_SIZE(L, a) && cell_subset(L, b, a)) skip[b] = 1;
    }
    int *cand = ori__alloc(sizeof(int) * (size_t)(nc ? nc : 1));
    uint64_t *hash = ori__alloc(sizeof(uint64_t) * (size_t)(nc ? nc : 1));
    int ncand = 0;
    for (int c = 0; c < nc; ++c) {
        if (skip[c]) continue;
        uint64_t h = 0x9E3779B97F4A7C15ULL;
        for (int64_t k = 0; k < CELL_SIZE(L, c); ++k) h = (h ^ (uint64_t)CELL_FACES(L, c)[k]) * 0x100000001B3ULL;
        hash[c] = h;
        cand[ncand++] = c;
    }
    ori__free(skip);
    pthread_mutex_lock(&g_sort_lock);
    g_sort_layers = L;
    g_sort_hash = hash;
    if (ncand > 1) qsort(cand, (size_t)ncand, sizeof(int), cmp_cells);
    pthread_mutex_unlock(&g_sort_lock);
    int nstack = 0;
    int64_t nfaces = 0, nvars = 0;
    int *keep = ori__alloc(sizeof(int) * (size_t)(ncand ? ncand : 1));
    struct flist {
        int *items;
        int n, cap;
    } *flist = ori__calloc((size_t)(L->nf ? L->nf : 1), sizeof(struct flist));
    for (int i = ncand - 1; i >= 0; --i) { // largest first: see prune_slots
        int c = cand[i];
        if (i < ncand - 1) {
            int p = cand[i + 1];
            if (CELL_SIZE(L, p) == CELL_SIZE(L, c) && hash[p] == hash[c] &&
                memcmp(CELL_FACES(L, p), CELL_FACES(L, c), sizeof(int) * (size_t)CELL_SIZE(L, c)) == 0)
                continue;
        }
        // Contained in a larger stack kept already (found through its rarest face)?
        const int *F = CELL_FACES(L, c);
        int64_t k = CELL_SIZE(L, c);
        int rare = F[0];
        for (int64_t x = 1; x < k; ++x)
            if (flist[F[x]].n < flist[rare].n) rare = F[x];
        bool inside = false;
        for (int x = 0; x < flist[rare].n && !inside; ++x) {
            int t = keep[flist[rare].items[x]];
            inside = CELL_SIZE(L, t) > k && cell_subset(L, c, t);
        }
        if (inside) continue;
        for (int64_t x = 0; x < k; ++x) ORI__PUSH(flist[F[x]].items, flist[F[x]].n, flist[F[x]].cap, nstack);
        keep[nstack++] = c;
        nfaces += k;
        nvars += k * k;
    }
    for (int f = 0; f < L->nf; ++f) ori__free(flist[f].items);
    ori__free(flist);
    ori__free(hash);
    L->n_stack = nstack;
    L->stacks = ori__alloc(sizeof(ori__stack) * (size_t)(nstack ? nstack : 1));
    L->stack_faces = ori__alloc(sizeof(int) * (size_t)(nfaces ? nfaces : 1));
    L->stack_vars = ori__alloc(sizeof(int) * (size_t)(nvars ? nvars : 1));
    int64_t fo = 0, vo = 0;
    int64_t *cnt = ori__calloc((size_t)L->nvar + 1, sizeof(int64_t));
    ori_status st = ORI_OK;
    ori__free(cand);
    cand = keep;
    for (int i = 0; i < nstack; ++i) {
        int c = cand[i], k = (int)CELL_SIZE(L, c);
        const int *F = CELL_FACES(L, c);
        ori__stack *S = &L->stacks[i];
        if (k > 65535 && st == ORI_OK)
            st = ori__fail_at(error, ORI_ERR_LIMIT, "faces_vertices", F[0], "%d faces over one cell (at most 65535)", k);
        S->k = k;
        S->words = (k + 63) / 64;
        S->faces_at = fo;
        S->vars_at = vo;
        S->bits_at = L->n_bitwords;
        L->n_bitwords += 2 * (int64_t)k * S->words;
        memcpy(L->stack_faces + fo, F, sizeof(int) * (size_t)k);
        int *M = L->stack_vars + vo;
        for (int a = 0; a < k; ++a) {
            M[a * k + a] = -1;
            for (int b = a + 1; b < k; ++b) {
                int v = ori__layers_var(L, F[a], F[b]);
                if (v < 0 && st == ORI_OK)
                    st = ori__fail_at(error, ORI_ERR_INTERNAL, "faces_vertices", F[a],
                                      "faces %d and %d share a cell but have no variable", F[a], F[b]);
                M[a * k + b] = M[b * k + a] = v;
                if (v >= 0) cnt[v + 1]++;
            }
        }
        fo += k;
        vo += (int64_t)k * k;
    }
    for (int v = 0; v < L->nvar; ++v) cnt[v + 1] += cnt[v];
    L->var_slot_off = cnt;
    L->slots = ori__alloc(sizeof(ori__slot) * (size_t)(cnt[L->nvar] ? cnt[L->nvar] : 1));
    int64_t *fill = ori__alloc(sizeof(int64_t) * (size_t)(L->nvar ? L->nvar : 1));
    memcpy(fill, cnt, sizeof(int64_t) * (size_t)L->nvar);
    for (int i = 0; i < nstack; ++i) {
        const ori__stack *S = &L->stacks[i];
        const int *M = L->stack_vars + S->vars_at;
        for (int a = 0; a < S->k; ++a)
            for (int b = a + 1; b < S->k; ++b) {
                int v = M[a * S->k + b];
                if (v < 0) continue;
                ori__slot sl = {i, a, b};
                L->slots[fill[v]++] = sl;
            }
    }
    ori__free(fill);
    ori__free(cand);
    // Every stack of each variable, compactly, before pruning (the bit rows need them all).
    L->var_fslot_off = ori__alloc(sizeof(int64_t) * (size_t)(L->nvar + 1));
    memcpy(L->var_fslot_off, cnt, sizeof(int64_t) * (size_t)(L->nvar + 1));
    L->fslots = ori__alloc(sizeof(ori__fslot) * (size_t)(cnt[L->nvar] ? cnt[L->nvar] : 1));
    for (int64_t i = 0; i < cnt[L->nvar]; ++i) {
        L->fslots[i].stack = L->slots[i].stack;
        L->fslots[i].ia = (uint16_t)L->slots[i].ia;
        L->fslots[i].ib = (uint16_t)L->slots[i].ib;
    }
    if (st == ORI_OK) L->count_kind[ORI_LAYERS_TRANSITIVITY] = prune_slots(L);
    return st;
}

ori_status ori__layers_constraints(ori_layers *L, ori_error *error)
{
    ori_status st = build_variables(L);
    if (st != ORI_OK) return st;
    growing g = {0};
    st = edge_constraints(L, &g, error);
    L->equiv = g.equiv;
    L->taco = g.taco;
    if (st != ORI_OK) return st;
    // Taco-taco constraints of each variable.
    int64_t *off = ori__calloc((size_t)L->nvar + 1, sizeof(int64_t));
    for (int t = 0; t < L->n_taco; ++t)
        for (int i = 0; i < 6; ++i) off[ORI__LIT_VAR(L->taco[t].lit[i]) + 1]++;
    for (int v = 0; v < L->nvar; ++v) off[v + 1] += off[v];
    L->var_tacos.rows = L->nvar;
    L->var_tacos.off = off;
    L->var_tacos.items = ori__alloc(sizeof(int) * (size_t)(off[L->nvar] ? off[L->nvar] : 1));
    int64_t *fill = ori__alloc(sizeof(int64_t) * (size_t)(L->nvar ? L->nvar : 1));
    memcpy(fill, off, sizeof(int64_t) * (size_t)L->nvar);
    for (int t = 0; t < L->n_taco; ++t)
        for (int i = 0; i < 6; ++i) L->var_tacos.items[fill[ORI__LIT_VAR(L->taco[t].lit[i])]++] = t;
    ori__free(fill);
    st = build_stacks(L, error);
    if (st != ORI_OK) return st;
    return ORI_OK;
}
