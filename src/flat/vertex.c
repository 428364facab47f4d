// Single-vertex flat-foldability: Kawasaki, Maekawa, the generalised big-little-big rule, Hull's
// count of valid mountain-valley assignments with its reduction tree (enumeration, completions of
// U creases) and the exact crimp test of one assignment.
//
// Notation: n creases 0…n−1 in cyclic order; sector t runs from crease t to crease t+1, so crease t
// lies between sectors t−1 and t. All equal-angle decisions use ORI_TOL_ANGLE_EQUAL_RAD.
//
// Hull's reduction (thesis Theorem 4; T. Hull, "Counting mountain-valley assignments for flat
// folds", Ars Combinatoria 67, 2003). Take the smallest sector value μ and a maximal run of k+1
// consecutive sectors equal to μ; both neighbours are strictly larger unless all sectors are
// equal. In every valid assignment the k+2 creases bounding and inside the run satisfy
//   k even: #M = #V among them, and the run folds up as a crimp: the sectors α_{i−1}, run,
//           α_{i+k+1} become the single sector α_{i−1} − α_i + α_{i+k+1};
//   k odd:  |#M − #V| = 1, and the run vanishes: α_{i−1} and α_{i+k+1} become adjacent, with one
//           crease between them whose letter is the majority letter of the k+2 creases.
// Every valid assignment of the reduced vertex extends in binom(k+2, (k+2)/2) (k even) or
// binom(k+2, (k+1)/2) (k odd) ways, independently of the rest. Repeating until all sectors are
// equal, where every assignment with #M − #V = ±2 is valid (Theorem 3: C = 2·binom(2m, m−1)),
// gives C. The steps form a tree — leaves are the input creases, an odd step is an inner node
// (the merged crease), an even step a free-standing group, and the final equal-angle vertex the
// root — which also counts completions of partial assignments (a product of small polynomial
// convolutions) and enumerates valid assignments without dead ends.
#include "flat_internal.h"

#include <stdio.h>
#include <stdlib.h>

// --- scratch memory ----------------------------------------------------------------------

void ori__flat_ws_begin(ori__flat_ws *ws, void *stack, size_t stack_bytes, size_t need)
{
    if (need <= stack_bytes) {
        ws->base = stack;
        ws->cap = stack_bytes;
        ws->heap = NULL;
    } else {
        ws->heap = ori__alloc(need);
        ws->base = ws->heap;
        ws->cap = need;
    }
    ws->used = 0;
}

void *ori__flat_ws_take(ori__flat_ws *ws, size_t bytes)
{
    size_t a = (bytes + 15u) & ~(size_t)15u;
    ORI_ASSERT(a >= bytes && ws->used + a <= ws->cap);
    void *p = ws->base + ws->used;
    ws->used += a;
    return p;
}

void ori__flat_ws_end(ori__flat_ws *ws)
{
    ori__free(ws->heap);
    ws->heap = NULL;
}

// Bytes needed for `count` items of `size`, rounded as ori__flat_ws_take rounds.
static size_t ws_bytes(size_t count, size_t size)
{
    size_t b;
    if (!ori__mul_size(count, size, &b)) ori__assert_fail("flat scratch size overflow", __FILE__, __LINE__);
    return (b + 15u) & ~(size_t)15u;
}

// --- exact counts ------------------------------------------------------------------------

static ori_mv_count mv_make(uint64_t c)
{
    ori_mv_count r = {c, false};
    return r;
}

ori_mv_count ori__mv_mul(ori_mv_count a, ori_mv_count b)
{
    // An overflowed count is UINT64_MAX, never 0: a zero factor gives an exact zero.
    if (a.count == 0 || b.count == 0) return mv_make(0);
    ori_mv_count r;
    r.overflow = a.overflow || b.overflow;
    if (a.count > UINT64_MAX / b.count) {
        r.count = UINT64_MAX;
        r.overflow = true;
    } else {
        r.count = a.count * b.count;
    }
    return r;
}

ori_mv_count ori__mv_add(ori_mv_count a, ori_mv_count b)
{
    ori_mv_count r;
    r.overflow = a.overflow || b.overflow;
    if (a.count > UINT64_MAX - b.count) {
        r.count = UINT64_MAX;
        r.overflow = true;
    } else {
        r.count = a.count + b.count;
    }
    return r;
}

static uint64_t gcd_u64(uint64_t a, uint64_t b)
{
    while (b) {
        uint64_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}

ori_mv_count ori__binomial(int n, int k)
{
    if (n < 0 || k < 0 || k > n) return mv_make(0);
    if (k > n - k) k = n - k;
    uint64_t r = 1;
    for (int i = 1; i <= k; ++i) {
        // r·(n−k+i)/i is binom(n−k+i, i), an integer: divide out gcds first so that nothing but
        // the true result can overflow.
        uint64_t num = (uint64_t)(n - k + i), den = (uint64_t)i;
        uint64_t g = gcd_u64(r, den);
        r /= g;
        den /= g;
        num /= den; // den now divides num (gcd(r, den) = 1 and den | r·num)
        if (num != 0 && r > UINT64_MAX / num) {
            ori_mv_count o = {UINT64_MAX, true};
            return o;
        }
        r *= num;
    }
    return mv_make(r);
}

// --- simple rules ------------------------------------------------------------------------

static void assert_sectors(const double *s, int n)
{
    ORI_ASSERT(n >= 0 && (n == 0 || s));
    for (int i = 0; i < n; ++i) ORI_ASSERT(isfinite(s[i]) && s[i] >= 0.0);
    (void)s;
}

double ori_flat_kawasaki_sum(const double *s, int n)
{
    assert_sectors(s, n);
    double sum = 0.0;
    for (int i = 0; i < n; ++i) sum += (i & 1) ? -s[i] : s[i];
    return sum;
}

bool ori_flat_kawasaki(const double *s, int n)
{
    if (n & 1) return false;
    return fabs(ori_flat_kawasaki_sum(s, n)) <= ORI_TOL_KAWASAKI_RAD;
}

bool ori_flat_maekawa(const ori_assignment *a, int n)
{
    ORI_ASSERT(n >= 0 && (n == 0 || a));
    if (n == 0) return true;
    int d = 0;
    for (int i = 0; i < n; ++i) {
        ORI_ASSERT(a[i] == ORI_ASSIGN_MOUNTAIN || a[i] == ORI_ASSIGN_VALLEY);
        d += a[i] == ORI_ASSIGN_MOUNTAIN ? 1 : -1;
    }
    return d == 2 || d == -2;
}

static bool sector_equal(double a, double b) { return fabs(a - b) <= ORI_TOL_ANGLE_EQUAL_RAD; }

// Can k+2 creases with m mountains, v valleys and u unassigned meet the run condition?
static bool run_condition(int k, int m, int v)
{
    int c = k + 2;
    if (k % 2 == 0) return m <= c / 2 && v <= c / 2;
    int hi = (c + 1) / 2, lo = (c - 1) / 2;
    return (m <= hi && v <= lo) || (m <= lo && v <= hi);
}

int ori_flat_big_little_big(const double *s, const ori_assignment *a, int n, int *run_creases)
{
    assert_sectors(s, n);
    ORI_ASSERT(n == 0 || a);
    if (run_creases) *run_creases = 0;
    // A run starts where the link to the previous sector breaks; all linked = all equal (no run
    // is strictly smaller than its neighbours).
    int start = -1;
    for (int t = 0; t < n && start < 0; ++t)
        if (!sector_equal(s[(t + n - 1) % n], s[t])) start = t;
    if (start < 0) return ORI_NULL_INDEX;
    int best = ORI_NULL_INDEX, best_len = 0;
    int t = start, walked = 0;
    while (walked < n) {
        int i = t, len = 1;
        while (len < n && sector_equal(s[(i + len - 1) % n], s[(i + len) % n])) ++len;
        walked += len;
        t = (i + len) % n;
        if (len + 2 > n) continue; // the run's two neighbours must be distinct sectors
        double prev = s[(i + n - 1) % n], next = s[(i + len) % n];
        double first = s[i], last = s[(i + len - 1) % n];
        if (!(prev > first + ORI_TOL_ANGLE_EQUAL_RAD && next > last + ORI_TOL_ANGLE_EQUAL_RAD)) continue;
        int m = 0, v = 0;
        for (int c = 0; c <= len; ++c) {
            ori_assignment x = a[(i + c) % n];
            m += x == ORI_ASSIGN_MOUNTAIN;
            v += x == ORI_ASSIGN_VALLEY;
        }
        if (!run_condition(len - 1, m, v) && (best == ORI_NULL_INDEX || i < best)) {
            best = i;
            best_len = len + 1;
        }
    }
    if (run_creases) *run_creases = best_len;
    return best;
}

// --- Hull's reduction --------------------------------------------------------------------

enum { GROUP_EVEN = 0, GROUP_ODD = 1, GROUP_ROOT = 2 };

// One group of the reduction tree: the creases (leaf ids < n, inner ids ≥ n) of a run (even
// or odd step) or of the final equal-angle vertex (root). An odd group's node is its inner id.
typedef struct group {
    int kind;
    int k;      // run of k+1 sectors, k+2 members (root: unused)
    int first;  // offset into members
    int count;  // number of members
    int node;   // inner id (odd groups), else −1
} group;

typedef struct tree {
    int n;            // leaves
    int nodes;        // leaves + inner nodes
    int group_count;  // the last group is the root
    group *groups;
    int *members;
} tree;

// Bytes of scratch reduce() needs for n creases (tree included).
static size_t reduce_bytes(int n)
{
    size_t m = (size_t)(n > 0 ? n : 1);
    return 2 * ws_bytes(m, sizeof(double)) + 2 * ws_bytes(m, sizeof(int)) + ws_bytes(m / 2 + 2, sizeof(group)) +
           ws_bytes(2 * m + 2, sizeof(int));
}

// Reduce the sectors s (n even ≥ 2) by Hull's steps down to an equal-angle vertex, recording the
// tree and multiplying the binomial factors into *count (the count C when the sectors satisfy
// Kawasaki). Scratch from ws.
static void reduce(const double *s, int n, ori__flat_ws *ws, tree *tr, ori_mv_count *count)
{
    double *sec = ori__flat_ws_take(ws, sizeof(double) * (size_t)n);
    double *tmp_sec = ori__flat_ws_take(ws, sizeof(double) * (size_t)n);
    int *cid = ori__flat_ws_take(ws, sizeof(int) * (size_t)n);
    int *tmp_cid = ori__flat_ws_take(ws, sizeof(int) * (size_t)n);
    tr->n = n;
    tr->nodes = n;
    tr->group_count = 0;
    tr->groups = ori__flat_ws_take(ws, sizeof(group) * (size_t)(n / 2 + 2));
    tr->members = ori__flat_ws_take(ws, sizeof(int) * (size_t)(2 * n + 2));
    int member_count = 0;
    memcpy(sec, s, sizeof(double) * (size_t)n);
    for (int i = 0; i < n; ++i) cid[i] = i;
    int m = n;
    ori_mv_count c = mv_make(1);
    for (;;) {
        double mn = sec[0], mx = sec[0];
        for (int t = 1; t < m; ++t) {
            mn = fmin(mn, sec[t]);
            mx = fmax(mx, sec[t]);
        }
        int i = -1, len = 0;
        if (mx - mn > ORI_TOL_ANGLE_EQUAL_RAD) {
            int j = 0;
            while (sec[j] <= mn + ORI_TOL_ANGLE_EQUAL_RAD) ++j; // a big sector exists
            i = (j + 1) % m;
            while (sec[i] > mn + ORI_TOL_ANGLE_EQUAL_RAD) i = (i + 1) % m;
            while (len < m && sec[(i + len) % m] <= mn + ORI_TOL_ANGLE_EQUAL_RAD) ++len;
            // A run of all but one sector cannot satisfy Kawasaki beyond the tolerances; treat
            // such a vertex as equal-angled (its lone sector is within rounding of the others).
            if (len > m - 2) i = -1;
        }
        if (i < 0) { // Theorem 3: all equal, every assignment with #M − #V = ±2
            group *g = &tr->groups[tr->group_count++];
            g->kind = GROUP_ROOT;
            g->k = m - 2;
            g->first = member_count;
            g->count = m;
            g->node = -1;
            for (int t = 0; t < m; ++t) tr->members[member_count++] = cid[t];
            c = ori__mv_mul(c, ori__mv_mul(mv_make(2), ori__binomial(m, m / 2 - 1)));
            break;
        }
        int k = len - 1;
        int prev = (i + m - 1) % m, next = (i + len) % m;
        group *g = &tr->groups[tr->group_count++];
        g->kind = (k % 2 == 0) ? GROUP_EVEN : GROUP_ODD;
        g->k = k;
        g->first = member_count;
        g->count = k + 2;
        g->node = -1;
        for (int t = 0; t <= len; ++t) tr->members[member_count++] = cid[(i + t) % m];
        // Alternating sum of the run relative to prev's sign; added to the sector that absorbs
        // the run so that the alternating sum of the whole vertex is preserved exactly.
        double r = 0.0;
        for (int t = 0; t < len; ++t) r += (t & 1) ? sec[(i + t) % m] : -sec[(i + t) % m];
        int nm = 0;
        if (k % 2 == 0) {
            c = ori__mv_mul(c, ori__binomial(k + 2, (k + 2) / 2));
            tmp_sec[nm] = sec[prev] + r + sec[next];
            tmp_cid[nm++] = cid[prev];
            for (int q = (next + 1) % m; q != prev; q = (q + 1) % m) {
                tmp_sec[nm] = sec[q];
                tmp_cid[nm++] = cid[q];
            }
        } else {
            c = ori__mv_mul(c, ori__binomial(k + 2, (k + 1) / 2));
            g->node = tr->nodes++;
            tmp_sec[nm] = sec[prev] + r;
            tmp_cid[nm++] = cid[prev];
            tmp_sec[nm] = sec[next];
            tmp_cid[nm++] = g->node;
            for (int q = (next + 1) % m; q != prev; q = (q + 1) % m) {
                tmp_sec[nm] = sec[q];
                tmp_cid[nm++] = cid[q];
            }
        }
        m = nm;
        memcpy(sec, tmp_sec, sizeof(double) * (size_t)m);
        memcpy(cid, tmp_cid, sizeof(int) * (size_t)m);
    }
    *count = c;
}

ori_mv_count ori_flat_count_assignments(const double *s, int n)
{
    assert_sectors(s, n);
    if (n == 0) return mv_make(1);
    if (!ori_flat_kawasaki(s, n)) return mv_make(0);
    _Alignas(16) unsigned char stack[2048];
    ori__flat_ws ws;
    ori__flat_ws_begin(&ws, stack, sizeof stack, reduce_bytes(n));
    tree tr;
    ori_mv_count c;
    reduce(s, n, &ws, &tr, &c);
    ori__flat_ws_end(&ws);
    return c;
}

// --- completions: dynamic programme over the tree ----------------------------------------

typedef struct weights {
    ori_mv_count m, v; // completions of a node's subtree when the node is M / V
} weights;

// Coefficients poly[j] = number of ways the members of g take j mountains.
static void group_poly(const tree *tr, const group *g, const weights *w, ori_mv_count *poly)
{
    for (int j = 0; j <= g->count; ++j) poly[j] = mv_make(0);
    poly[0] = mv_make(1);
    for (int c = 0; c < g->count; ++c) {
        const weights *x = &w[tr->members[g->first + c]];
        for (int j = c + 1; j >= 0; --j) {
            ori_mv_count keep = ori__mv_mul(poly[j], x->v);
            ori_mv_count add = j > 0 ? ori__mv_mul(poly[j - 1], x->m) : mv_make(0);
            poly[j] = ori__mv_add(keep, add);
        }
    }
}

// Mountain counts a group's members may take: targets[0..return) (root: two, others one).
static int group_targets(const group *g, ori_assignment node_value, int targets[2])
{
    switch (g->kind) {
    case GROUP_ROOT:
        if (g->count == 0) {
            targets[0] = 0;
            return 1;
        }
        targets[0] = g->count / 2 + 1;
        targets[1] = g->count / 2 - 1;
        return 2;
    case GROUP_EVEN:
        targets[0] = (g->k + 2) / 2;
        return 1;
    default:
        targets[0] = node_value == ORI_ASSIGN_MOUNTAIN ? (g->k + 3) / 2 : (g->k + 1) / 2;
        return 1;
    }
}

// Weights of every node and the total number of completions of the partial assignment a.
static ori_mv_count tree_weights(const tree *tr, const ori_assignment *a, weights *w, ori_mv_count *poly)
{
    for (int i = 0; i < tr->n; ++i) {
        w[i].m = mv_make(a[i] == ORI_ASSIGN_MOUNTAIN || a[i] == ORI_ASSIGN_UNASSIGNED);
        w[i].v = mv_make(a[i] == ORI_ASSIGN_VALLEY || a[i] == ORI_ASSIGN_UNASSIGNED);
    }
    ori_mv_count total = mv_make(1);
    for (int gi = 0; gi < tr->group_count; ++gi) {
        const group *g = &tr->groups[gi];
        group_poly(tr, g, w, poly);
        int t[2];
        if (g->kind == GROUP_ODD) {
            group_targets(g, ORI_ASSIGN_MOUNTAIN, t);
            w[g->node].m = poly[t[0]];
            group_targets(g, ORI_ASSIGN_VALLEY, t);
            w[g->node].v = poly[t[0]];
        } else {
            int nt = group_targets(g, ORI_ASSIGN_MOUNTAIN, t);
            ori_mv_count f = mv_make(0);
            for (int q = 0; q < nt; ++q)
                if (t[q] >= 0 && t[q] <= g->count) f = ori__mv_add(f, poly[t[q]]);
            total = ori__mv_mul(total, f);
        }
    }
    return total;
}

static size_t tree_dp_bytes(int n)
{
    size_t m = (size_t)(n > 0 ? n : 1);
    return ws_bytes(2 * m + 2, sizeof(weights)) + ws_bytes(m + 2, sizeof(ori_mv_count));
}

static void assert_partial(const ori_assignment *a, int n)
{
    ORI_ASSERT(n == 0 || a);
    for (int i = 0; i < n; ++i)
        ORI_ASSERT(a[i] == ORI_ASSIGN_MOUNTAIN || a[i] == ORI_ASSIGN_VALLEY || a[i] == ORI_ASSIGN_UNASSIGNED);
    (void)a;
}

// --- enumeration -------------------------------------------------------------------------

typedef struct enum_ctx {
    const tree *tr;
    const weights *w;
    ori_assignment *val; // per node (leaves and inner)
    int *forced;         // per level scratch: member slots, one array of 2n+2
    int *comb;           // combination indices, one array of 2n+2
    char *out;
    int max, written;
} enum_ctx;

static void emit(enum_ctx *cx)
{
    int n = cx->tr->n;
    char *row = cx->out + (size_t)cx->written * (size_t)(n + 1);
    for (int i = 0; i < n; ++i) row[i] = ori_assignment_to_char(cx->val[i]);
    row[n] = '\0';
    cx->written++;
}

// Level 0 is the root, level L the group created L-th from last. Every choice made here leaves
// each remaining node with a positive weight, so every branch reaches at least one assignment.
static void enum_level(enum_ctx *cx, int level)
{
    if (cx->written >= cx->max) return;
    const tree *tr = cx->tr;
    if (level == tr->group_count) {
        emit(cx);
        return;
    }
    const group *g = &tr->groups[tr->group_count - 1 - level];
    const int *mem = tr->members + g->first;
    int t[2];
    int nt = group_targets(g, g->kind == GROUP_ODD ? cx->val[g->node] : ORI_ASSIGN_MOUNTAIN, t);
    // Members with one possible letter are forced; the others are free.
    int free_count = 0, forced_m = 0;
    int *free_slots = cx->forced + g->first; // g->count slots reserved for this group
    for (int c = 0; c < g->count; ++c) {
        const weights *x = &cx->w[mem[c]];
        bool can_m = x->m.count > 0 || x->m.overflow, can_v = x->v.count > 0 || x->v.overflow;
        if (can_m && can_v) free_slots[free_count++] = mem[c];
        else if (can_m) {
            cx->val[mem[c]] = ORI_ASSIGN_MOUNTAIN;
            forced_m++;
        } else {
            cx->val[mem[c]] = ORI_ASSIGN_VALLEY;
        }
    }
    for (int q = 0; q < nt; ++q) {
        int r = t[q] - forced_m; // mountains to place among the free members
        if (r < 0 || r > free_count) continue;
        int *comb = cx->comb + g->first;
        for (int j = 0; j < r; ++j) comb[j] = j;
        for (;;) {
            for (int j = 0; j < free_count; ++j) cx->val[free_slots[j]] = ORI_ASSIGN_VALLEY;
            for (int j = 0; j < r; ++j) cx->val[free_slots[comb[j]]] = ORI_ASSIGN_MOUNTAIN;
            enum_level(cx, level + 1);
            if (cx->written >= cx->max) return;
            int j = r - 1;
            while (j >= 0 && comb[j] == free_count - r + j) --j;
            if (j < 0) break;
            comb[j]++;
            for (int l = j + 1; l < r; ++l) comb[l] = comb[l - 1] + 1;
        }
    }
}

static int compare_rows(const void *a, const void *b) { return strcmp(a, b); }

int ori_flat_enumerate_completions(const double *s, const ori_assignment *a, int n, char *out,
                                   int max_assignments, bool *truncated)
{
    assert_sectors(s, n);
    assert_partial(a, n);
    ORI_ASSERT(max_assignments >= 0 && (max_assignments == 0 || out));
    if (truncated) *truncated = false;
    if (n == 0) { // the empty assignment
        if (max_assignments == 0) {
            if (truncated) *truncated = true;
            return 0;
        }
        out[0] = '\0';
        return 1;
    }
    if (!ori_flat_kawasaki(s, n)) return 0;
    _Alignas(16) unsigned char stack[4096];
    ori__flat_ws ws;
    size_t m = (size_t)n;
    ori__flat_ws_begin(&ws, stack, sizeof stack,
                       reduce_bytes(n) + tree_dp_bytes(n) + ws_bytes(2 * m + 2, sizeof(ori_assignment)) +
                           2 * ws_bytes(2 * m + 2, sizeof(int)));
    tree tr;
    ori_mv_count c;
    reduce(s, n, &ws, &tr, &c);
    weights *w = ori__flat_ws_take(&ws, sizeof(weights) * (size_t)tr.nodes);
    ori_mv_count *poly = ori__flat_ws_take(&ws, sizeof(ori_mv_count) * (m + 2));
    ori_mv_count total = tree_weights(&tr, a, w, poly);
    int written = 0;
    if (total.count > 0 || total.overflow) {
        enum_ctx cx;
        cx.tr = &tr;
        cx.w = w;
        cx.val = ori__flat_ws_take(&ws, sizeof(ori_assignment) * (size_t)tr.nodes);
        cx.forced = ori__flat_ws_take(&ws, sizeof(int) * (2 * m + 2));
        cx.comb = ori__flat_ws_take(&ws, sizeof(int) * (2 * m + 2));
        cx.out = out;
        cx.max = max_assignments;
        cx.written = 0;
        if (max_assignments > 0) enum_level(&cx, 0);
        written = cx.written;
        bool more = total.overflow || total.count > (uint64_t)written;
        if (truncated) *truncated = more;
        if (!more && written > 1) qsort(out, (size_t)written, m + 1, compare_rows);
    }
    ori__flat_ws_end(&ws);
    return written;
}

int ori_flat_enumerate(const double *s, int n, char *out, int max_assignments, bool *truncated)
{
    ORI_ASSERT(n >= 0);
    ori_assignment stack[ORI__FLAT_STACK_DEGREE] = {ORI_ASSIGN_UNASSIGNED};
    ori_assignment *u = n <= ORI__FLAT_STACK_DEGREE ? stack : ori__alloc(sizeof(ori_assignment) * (size_t)n);
    for (int i = 0; i < n; ++i) u[i] = ORI_ASSIGN_UNASSIGNED;
    int r = ori_flat_enumerate_completions(s, u, n, out, max_assignments, truncated);
    if (u != stack) ori__free(u);
    return r;
}

// --- exact test: crimp reduction ---------------------------------------------------------

// Crimps (Arkin, Bender, Demaine et al., "When can you fold a map?", 2004; Demaine & O'Rourke,
// Geometric Folding Algorithms, §12.2): a sector no larger than either neighbour whose two
// creases have opposite letters can be folded as a pleat, merging α_{i−1}, α_i, α_{i+1} into
// α_{i−1} − α_i + α_{i+1} and removing both creases; the result folds flat iff the original
// does. A flat-foldable vertex with more than two creases always offers a crimp (its smallest
// run of sectors has opposite neighbouring creases by the generalised big-little-big rule, or,
// with all sectors equal, by Maekawa), so greedy crimping decides the assignment exactly. What
// is left is two creases with two sectors equal by Kawasaki (a sheet folded in half): valid iff
// the two creases have the same letter (#M − #V = ±2).
static bool crimp_reduce(double *sec, ori_assignment *a, double *tsec, ori_assignment *ta, int m)
{
    while (m > 2) {
        int hit = -1;
        for (int t = 0; t < m && hit < 0; ++t) {
            int nx = (t + 1) % m, pv = (t + m - 1) % m;
            if (a[t] != a[nx] && sec[t] <= sec[pv] + ORI_TOL_ANGLE_EQUAL_RAD &&
                sec[t] <= sec[nx] + ORI_TOL_ANGLE_EQUAL_RAD)
                hit = t;
        }
        if (hit < 0) return false;
        int pv = (hit + m - 1) % m, nx = (hit + 1) % m;
        int nm = 0;
        tsec[nm] = sec[pv] - sec[hit] + sec[nx];
        ta[nm++] = a[pv];
        for (int q = (nx + 1) % m; q != pv; q = (q + 1) % m) {
            tsec[nm] = sec[q];
            ta[nm++] = a[q];
        }
        m = nm;
        memcpy(sec, tsec, sizeof(double) * (size_t)m);
        memcpy(a, ta, sizeof(ori_assignment) * (size_t)m);
    }
    return m == 0 || a[0] == a[1];
}

bool ori_flat_assignment_valid(const double *s, const ori_assignment *a, int n)
{
    assert_sectors(s, n);
    ORI_ASSERT(n == 0 || a);
    for (int i = 0; i < n; ++i) ORI_ASSERT(a[i] == ORI_ASSIGN_MOUNTAIN || a[i] == ORI_ASSIGN_VALLEY);
    if (n == 0) return true;
    if (!ori_flat_kawasaki(s, n)) return false;
    _Alignas(16) unsigned char stack[1024];
    ori__flat_ws ws;
    size_t m = (size_t)n;
    ori__flat_ws_begin(&ws, stack, sizeof stack, 2 * ws_bytes(m, sizeof(double)) + 2 * ws_bytes(m, sizeof(ori_assignment)));
    double *sec = ori__flat_ws_take(&ws, sizeof(double) * m);
    double *tsec = ori__flat_ws_take(&ws, sizeof(double) * m);
    ori_assignment *x = ori__flat_ws_take(&ws, sizeof(ori_assignment) * m);
    ori_assignment *tx = ori__flat_ws_take(&ws, sizeof(ori_assignment) * m);
    memcpy(sec, s, sizeof(double) * m);
    memcpy(x, a, sizeof(ori_assignment) * m);
    bool ok = crimp_reduce(sec, x, tsec, tx, n);
    ori__flat_ws_end(&ws);
    return ok;
}

ori_mv_count ori_flat_count_completions(const double *s, const ori_assignment *a, int n)
{
    assert_sectors(s, n);
    assert_partial(a, n);
    if (n == 0) return mv_make(1);
    bool any_u = false;
    for (int i = 0; i < n; ++i) any_u |= a[i] == ORI_ASSIGN_UNASSIGNED;
    if (!any_u) return mv_make(ori_flat_assignment_valid(s, a, n) ? 1 : 0);
    if (!ori_flat_kawasaki(s, n)) return mv_make(0);
    _Alignas(16) unsigned char stack[4096];
    ori__flat_ws ws;
    ori__flat_ws_begin(&ws, stack, sizeof stack, reduce_bytes(n) + tree_dp_bytes(n));
    tree tr;
    ori_mv_count c;
    reduce(s, n, &ws, &tr, &c);
    weights *w = ori__flat_ws_take(&ws, sizeof(weights) * (size_t)tr.nodes);
    ori_mv_count *poly = ori__flat_ws_take(&ws, sizeof(ori_mv_count) * ((size_t)n + 2));
    ori_mv_count total = tree_weights(&tr, a, w, poly);
    ori__flat_ws_end(&ws);
    return total;
}

// --- vertex report -----------------------------------------------------------------------

void ori__flat_vertex_report(const double *s, const ori_assignment *a, int n, double sum,
                             ori_vertex_report *r)
{
    r->degree = n;
    r->mountains = r->valleys = r->unassigned = 0;
    for (int i = 0; i < n; ++i) {
        r->mountains += a[i] == ORI_ASSIGN_MOUNTAIN;
        r->valleys += a[i] == ORI_ASSIGN_VALLEY;
        r->unassigned += a[i] == ORI_ASSIGN_UNASSIGNED;
    }
    ORI_ASSERT(r->mountains + r->valleys + r->unassigned == n);
    r->sector_sum_rad = sum;
    r->cone = !(fabs(sum - 2.0 * ORI_PI) <= ORI_TOL_ANGLE_SUM_RAD);
    r->kawasaki_rad = ori_flat_kawasaki_sum(s, n);
    r->kawasaki = ori_flat_kawasaki(s, n);
    if (r->unassigned > 0) r->maekawa = ORI_FLAT_UNDETERMINED;
    else r->maekawa = (n == 0 || abs(r->mountains - r->valleys) == 2) ? ORI_FLAT_YES : ORI_FLAT_NO;
    r->blb_crease = ori_flat_big_little_big(s, a, n, &r->blb_run_creases);
    r->big_little_big = r->blb_crease == ORI_NULL_INDEX;
    r->mv_count = ori_flat_count_assignments(s, n);
    if (r->unassigned == 0) {
        r->assignment_valid = ori_flat_assignment_valid(s, a, n);
        r->completions = mv_make(r->assignment_valid ? 1 : 0);
    } else {
        r->completions = ori_flat_count_completions(s, a, n);
        r->assignment_valid = r->completions.count > 0 || r->completions.overflow;
    }
    r->flat_foldable = !r->cone && r->assignment_valid;
    r->within_tolerance = false;
    r->deviation_rad = 0.0;
}
