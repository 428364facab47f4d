// The counting solver.
//
// Set-up (ori__layers_presolve): the binary constraints (taco-tortilla, tortilla-tortilla) are
// equivalences between two literals; union-find with parity merges the variables into classes
// (one decision then sets a whole class). The M/V assignment fixes the variable of every
// assigned crease; generalised arc consistency on every constraint (a table per constraint
// kind: which partial assignments conflict, which force a literal, which are "dead", satisfied
// whatever the free literals do) propagates to a fixpoint. The free classes then fall into
// independent components: two classes are connected by a constraint that is not dead. This
// fixpoint and these components are exactly Flat-Folder's (propagation to the GAC fixpoint is
// unique), so the component structure matches its published one.
//
// Counting (ori__layers_solve): instead of enumerating every state of a component (Flat-Folder),
// a DPLL search counts them: branch on the most constrained class, propagate, split the free
// classes that remain into connected components again (dynamic decomposition), count each
// separately and multiply. Counts of components already met under the same boundary (the values
// of the fixed variables their live constraints touch) come from a cache. Exponentially many
// states are thus counted without being visited; counts are exact naturals (bignum.c).
// Independent components run on several threads when asked.
//
// Unranking (ori__layers_unrank): the same search, walking into the branch and the digits of
// the mixed radix of the sub-counts that contain state k.
#include "layers_internal.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>

#include "../core/hash.h"

// --- tables ---------------------------------------------------------------------------------

// Taco-taco literals: above(a,b) above(a,c) above(a,d) above(b,c) above(b,d) above(c,d), where
// creases join a|b and c|d. Valid: a strict total order of the four faces (no cycle) in which
// the two pairs do not interleave.
static bool taco_valid(int bits)
{
    int idx[4][4];
    const int pr[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    for (int i = 0; i < 6; ++i) {
        bool t = (bits >> i) & 1;
        idx[pr[i][0]][pr[i][1]] = t;
        idx[pr[i][1]][pr[i][0]] = !t;
    }
    // Position = number of faces below: a total order gives 0, 1, 2, 3.
    int pos[4], used = 0;
    for (int i = 0; i < 4; ++i) {
        pos[i] = 0;
        for (int j = 0; j < 4; ++j)
            if (j != i && idx[i][j]) pos[i]++;
        used |= 1 << pos[i];
    }
    if (used != 15) return false; // a cycle
    int lo1 = pos[0] < pos[1] ? pos[0] : pos[1], hi1 = pos[0] ^ pos[1] ^ lo1;
    int c_in = pos[2] > lo1 && pos[2] < hi1, d_in = pos[3] > lo1 && pos[3] < hi1;
    return c_in == d_in;
}

// Transitivity literals: above(a,b) above(b,c) above(a,c). Valid unless they form a cycle.
static bool trans_valid(int bits)
{
    bool ab = bits & 1, bc = (bits >> 1) & 1, ac = (bits >> 2) & 1;
    return !(ab && bc && !ac) && !(!ab && !bc && ac);
}

static void fill_table(uint16_t *table, int n, bool (*valid)(int))
{
    int states = 1;
    for (int i = 0; i < n; ++i) states *= 3;
    for (int code = 0; code < states; ++code) {
        int digit[6], x = code;
        for (int i = 0; i < n; ++i) {
            digit[i] = x % 3;
            x /= 3;
        }
        int can_true = 0, can_false = 0, completions = 0, good = 0;
        for (int bits = 0; bits < (1 << n); ++bits) {
            bool match = true;
            for (int i = 0; i < n && match; ++i)
                if (digit[i] && (((bits >> i) & 1) != (digit[i] == 1))) match = false;
            if (!match) continue;
            completions++;
            if (!valid(bits)) continue;
            good++;
            can_true |= bits;
            can_false |= ~bits & ((1 << n) - 1);
        }
        if (good == 0) {
            table[code] = ORI__TABLE_CONFLICT;
            continue;
        }
        uint16_t r = 0;
        for (int i = 0; i < n; ++i) {
            if (digit[i]) continue;
            bool t = (can_true >> i) & 1, f = (can_false >> i) & 1;
            if (t && !f) r |= (uint16_t)(1u << i);
            if (f && !t) r |= (uint16_t)(1u << (8 + i));
        }
        if (good == completions) r |= ORI__TABLE_DEAD;
        table[code] = r;
    }
}

// The tables are the same for every problem: built once (thread-safe), copied per solver.
static uint16_t g_table6[729], g_table3[27];
static pthread_once_t g_tables_once = PTHREAD_ONCE_INIT;

static void build_tables(void)
{
    fill_table(g_table6, 6, taco_valid);
    fill_table(g_table3, 3, trans_valid);
}

void ori__layers_tables(ori_layers *L)
{
    pthread_once(&g_tables_once, build_tables);
    memcpy(L->table6, g_table6, sizeof g_table6);
    memcpy(L->table3, g_table3, sizeof g_table3);
}

// --- solver state -------------------------------------------------------------------------

typedef struct cache_entry {
    uint64_t h1, h2;
    ori__nat count;
} cache_entry;

// Why a variable got its value (set-up only, for the conflict report).
enum { R_NONE = 0, R_CREASE, R_CLASS, R_TACO, R_TRANS };

typedef struct solver {
    const ori_layers *L;
    int8_t *val;  // per variable
    int8_t *cval; // per class
    uint64_t *bits; // per stack: the faces known above / below each face (ori__stack.bits_at)
    int *trail;   // classes in assignment order
    int ntrail;
    int *queue;   // variables to propagate
    int qtail, qhead;
    // conflict
    int conf_kind;
    int conf_faces[4];
    int conf_nfaces;
    // reasons (set-up)
    bool track;
    int8_t *rkind;
    int (*rdata)[4];
    // scratch for splitting
    int *in_set;
    int set_id;
    int *seen;
    int seen_id;
    int *vseen; // per variable: boundary variable already in the current component's key
    int vseen_id;
    int *score; // per class: live constraint incidences at its last split (branching)
    // scratch of the union-find split
    int *uf;          // per class
    int *face_stamp;  // per stack face (ori__stack.faces_at + i)
    int *face_rep;    // the class first met at that face in this split
    int face_id;
    int *reg;         // stack face indices registered in this split (faces_at + i)
    int nreg, regcap;
    int *pend;        // taco boundaries: class, variable
    int npend, pendcap;
    // cache
    cache_entry *cache;
    uint64_t cmask;
    uint64_t limit;
    bool limited;
    bool ff_rule; // split by Flat-Folder's rule (reported components) instead of the class rule
    // progress
    bool main_thread;
    bool cancel;
    int64_t nodes;
    int64_t node_cap;     // > 0: stop (as cancelled) past this many nodes
    atomic_bool *stop;    // the pool's cancel flag (a worker stops with the main thread), or NULL
    double done_fraction; // of the components finished before the current one
    double comp_share;    // the current component's share of the whole
    double pos_lo, pos_w; // the current node's interval of the component's search (0 … 1)
} solver;

static void solver_init(solver *s, const ori_layers *L, bool with_cache)
{
    memset(s, 0, sizeof *s);
    s->L = L;
    size_t nv = (size_t)(L->nvar ? L->nvar : 1), nc = (size_t)(L->n_class ? L->n_class : 1);
    s->val = ori__calloc(nv, 1);
    s->cval = ori__calloc(nc, 1);
    s->bits = ori__calloc((size_t)(L->n_bitwords ? L->n_bitwords : 1), sizeof(uint64_t));
    s->trail = ori__alloc(sizeof(int) * nc);
    s->queue = ori__alloc(sizeof(int) * nv);
    s->in_set = ori__calloc(nc, sizeof(int));
    s->seen = ori__calloc(nc, sizeof(int));
    s->vseen = ori__calloc(nv, sizeof(int));
    s->score = ori__calloc(nc, sizeof(int));
    s->uf = ori__alloc(sizeof(int) * nc);
    int64_t nsf = L->n_stack ? L->stacks[L->n_stack - 1].faces_at + L->stacks[L->n_stack - 1].k : 0;
    s->face_stamp = ori__calloc((size_t)(nsf ? nsf : 1), sizeof(int));
    s->face_rep = ori__alloc(sizeof(int) * (size_t)(nsf ? nsf : 1));
    s->limit = L->limit;
    if (with_cache) {
        uint64_t cap = 64;
        while (cap < 4 * (uint64_t)L->n_class && cap < (1u << 20)) cap *= 2;
        s->cache = ori__calloc((size_t)cap, sizeof(cache_entry));
        s->cmask = cap - 1;
    }
}

static void solver_free(solver *s)
{
    ori__free(s->val);
    ori__free(s->cval);
    ori__free(s->bits);
    ori__free(s->trail);
    ori__free(s->queue);
    ori__free(s->in_set);
    ori__free(s->seen);
    ori__free(s->vseen);
    ori__free(s->score);
    ori__free(s->uf);
    ori__free(s->face_stamp);
    ori__free(s->face_rep);
    ori__free(s->reg);
    ori__free(s->pend);
    ori__free(s->rkind);
    ori__free(s->rdata);
    if (s->cache) {
        for (uint64_t i = 0; i <= s->cmask; ++i) ori__nat_free(&s->cache[i].count);
        ori__free(s->cache);
    }
}

static void set_conflict(solver *s, int kind, int a, int b, int c, int d, int n)
{
    s->conf_kind = kind;
    s->conf_faces[0] = a;
    s->conf_faces[1] = b;
    s->conf_faces[2] = c;
    s->conf_faces[3] = d;
    s->conf_nfaces = n;
}

// Record variable v's value (x = ±1, 0 to forget it) in the bit rows of every stack holding
// it: +1 puts its lower face above the other.
static void set_bits(solver *s, int v, int x)
{
    const ori_layers *L = s->L;
    for (int64_t k = L->var_fslot_off[v]; k < L->var_fslot_off[v + 1]; ++k) {
        const ori__fslot *fs = &L->fslots[k];
        const ori__stack *S = &L->stacks[fs->stack];
        uint64_t *up = s->bits + S->bits_at, *down = up + (int64_t)S->k * S->words;
        int a = fs->ia, b = fs->ib, w = S->words;
        uint64_t ba = (uint64_t)1 << (a & 63), bb = (uint64_t)1 << (b & 63);
        if (x == 0) {
            up[b * w + (a >> 6)] &= ~ba;
            down[a * w + (b >> 6)] &= ~bb;
            up[a * w + (b >> 6)] &= ~bb;
            down[b * w + (a >> 6)] &= ~ba;
        } else if (x > 0) { // a above b
            up[b * w + (a >> 6)] |= ba;
            down[a * w + (b >> 6)] |= bb;
        } else {
            up[a * w + (b >> 6)] |= bb;
            down[b * w + (a >> 6)] |= ba;
        }
    }
}

// Give class c value x (±1): every member variable follows with its parity.
static void assign_class(solver *s, int c, int x)
{
    const ori_layers *L = s->L;
    s->cval[c] = (int8_t)x;
    s->trail[s->ntrail++] = c;
    for (int64_t k = L->class_vars.off[c]; k < L->class_vars.off[c + 1]; ++k) {
        int v = L->class_vars.items[k];
        s->val[v] = (int8_t)(x * L->var_par[v]);
        set_bits(s, v, s->val[v]);
        s->queue[s->qtail++] = v;
    }
}

static void undo(solver *s, int mark)
{
    const ori_layers *L = s->L;
    while (s->ntrail > mark) {
        int c = s->trail[--s->ntrail];
        s->cval[c] = 0;
        for (int64_t k = L->class_vars.off[c]; k < L->class_vars.off[c + 1]; ++k) {
            int v = L->class_vars.items[k];
            s->val[v] = 0;
            set_bits(s, v, 0);
        }
    }
    s->qhead = s->qtail = 0;
}

// Make literal l true. Returns false when its variable already has the other value.
static bool set_lit(solver *s, int l, int rk, const int *rfaces)
{
    const ori_layers *L = s->L;
    int v = ORI__LIT_VAR(l);
    int want = ORI__LIT_NEG(l) ? -1 : 1;
    if (s->val[v]) return s->val[v] == want;
    int c = L->var_class[v];
    if (s->track) {
        s->rkind[v] = (int8_t)rk;
        memcpy(s->rdata[v], rfaces, sizeof(int) * 4);
        for (int64_t k = L->class_vars.off[c]; k < L->class_vars.off[c + 1]; ++k) {
            int u = L->class_vars.items[k];
            if (u != v) {
                s->rkind[u] = R_CLASS;
                s->rdata[u][0] = v;
            }
        }
    }
    assign_class(s, c, want * L->var_par[v]);
    return true;
}

static inline int digit(const int8_t *val, int l)
{
    int x = val[ORI__LIT_VAR(l)];
    if (!x) return 0;
    return ((x > 0) != ORI__LIT_NEG(l)) ? 1 : 2;
}

static inline int taco_code(const int8_t *val, const ori__taco *t)
{
    return digit(val, t->lit[0]) + 3 * digit(val, t->lit[1]) + 9 * digit(val, t->lit[2]) +
           27 * digit(val, t->lit[3]) + 81 * digit(val, t->lit[4]) + 243 * digit(val, t->lit[5]);
}

// Propagate every queued variable to the fixpoint. Returns false on a conflict.
static bool propagate(solver *s)
{
    const ori_layers *L = s->L;
    int8_t *val = s->val;
    while (s->qhead < s->qtail) {
        int v = s->queue[s->qhead++];
        for (int64_t k = L->var_tacos.off[v]; k < L->var_tacos.off[v + 1]; ++k) {
            const ori__taco *t = &L->taco[L->var_tacos.items[k]];
            uint16_t r = L->table6[taco_code(val, t)];
            if (r == ORI__TABLE_CONFLICT) {
                set_conflict(s, ORI_LAYERS_TACO_TACO, t->faces[0], t->faces[1], t->faces[2], t->faces[3], 4);
                return false;
            }
            if (!(r & 0x3F3F)) continue;
            for (int i = 0; i < 6; ++i) {
                int l = -1;
                if (r & (1u << i)) l = t->lit[i];
                else if (r & (1u << (8 + i))) l = t->lit[i] ^ 1;
                if (l >= 0 && !set_lit(s, l, R_TACO, t->faces)) {
                    set_conflict(s, ORI_LAYERS_TACO_TACO, t->faces[0], t->faces[1], t->faces[2], t->faces[3], 4);
                    return false;
                }
            }
        }
        // Transitivity with bit rows: with t above u just decided, every face above t is above
        // u and every face below u is below t; a face above t and below u closes a cycle.
        for (int64_t k = L->var_slot_off[v]; k < L->var_slot_off[v + 1]; ++k) {
            const ori__slot *sl = &L->slots[k];
            const ori__stack *S = &L->stacks[sl->stack];
            const int *F = L->stack_faces + S->faces_at;
            const int *M = L->stack_vars + S->vars_at;
            int w = S->words, kk = S->k;
            int t = val[v] > 0 ? sl->ia : sl->ib, u = val[v] > 0 ? sl->ib : sl->ia;
            const uint64_t *up = s->bits + S->bits_at, *down = up + (int64_t)kk * w;
            const uint64_t *up_t = up + (int64_t)t * w, *up_u = up + (int64_t)u * w;
            const uint64_t *dn_t = down + (int64_t)t * w, *dn_u = down + (int64_t)u * w;
            for (int q = 0; q < w; ++q)
                if (up_t[q] & dn_u[q]) {
                    int x = q * 64 + __builtin_ctzll(up_t[q] & dn_u[q]);
                    set_conflict(s, ORI_LAYERS_TRANSITIVITY, F[t], F[u], F[x], -1, 3);
                    return false;
                }
            for (int q = 0; q < w; ++q) {
                // Faces above t not yet above u (u itself is below t, not above it).
                uint64_t m = up_t[q] & ~up_u[q];
                while (m) {
                    int x = q * 64 + __builtin_ctzll(m);
                    m &= m - 1;
                    int vx = M[x * kk + u];
                    int rf[4] = {F[t], F[u], F[x], -1};
                    if (!set_lit(s, ORI__LIT(vx, x > u), R_TRANS, rf)) {
                        set_conflict(s, ORI_LAYERS_TRANSITIVITY, F[t], F[u], F[x], -1, 3);
                        return false;
                    }
                }
                m = dn_u[q] & ~dn_t[q];
                while (m) {
                    int y = q * 64 + __builtin_ctzll(m);
                    m &= m - 1;
                    int vy = M[t * kk + y];
                    int rf[4] = {F[t], F[u], F[y], -1};
                    if (!set_lit(s, ORI__LIT(vy, t > y), R_TRANS, rf)) {
                        set_conflict(s, ORI_LAYERS_TRANSITIVITY, F[t], F[u], F[y], -1, 3);
                        return false;
                    }
                }
            }
        }
    }
    s->qhead = s->qtail = 0;
    return true;
}

// --- splitting into components ----------------------------------------------------------------

// Two independent order-free hashes of a multiset of 64-bit items (sums of mixed items).
static inline void hash_add(uint64_t h[2], uint64_t x)
{
    uint64_t y = ori__mix64(x ^ 0x243F6A8885A308D3ULL);
    h[0] += y;
    h[1] += (y ^ (y >> 31)) * 0xBF58476D1CE4E5B9ULL + x;
}

// Sign of literal l relative to its class: the literal is true when x[class] equals it.
static inline int lit_sign(const ori_layers *L, int l)
{
    return L->var_par[ORI__LIT_VAR(l)] * (ORI__LIT_NEG(l) ? -1 : 1);
}

// Literals l1 and l2 are tied by the equivalences: same class, equal (want = 1) or opposite
// (want = -1).
static inline bool tied(const ori_layers *L, int l1, int l2, int want)
{
    return L->var_class[ORI__LIT_VAR(l1)] == L->var_class[ORI__LIT_VAR(l2)] && lit_sign(L, l1) * lit_sign(L, l2) == want;
}

// The transitivity constraint of faces a < b and a third face (variables vab, vbc, vac; the
// literals above(b,c), above(a,c) are negated as given) is implied by the equivalences: one of
// its faces can never lie between the other two (taco-tortilla chains), so no cycle can form.
// Flat-Folder drops these triples too (its "reduced" transitivity).
static bool triple_tied(const ori_layers *L, int vab, int vbc, int nbc, int vac, int nac)
{
    int lab = ORI__LIT(vab, 0), lbc = ORI__LIT(vbc, nbc), lac = ORI__LIT(vac, nac);
    return tied(L, lab, lbc, -1) || tied(L, lab, lac, 1) || tied(L, lac, lbc, 1);
}

// Flat-Folder's reduction: in the graph of tortilla t whose edges are the taco-tortilla
// constraints (taco x|y, tortilla t), faces x and y are connected, so t never lies between them
// and the triple (t, x, y) cannot form a cycle. vtx, vty are the variables of (t, x), (t, y).
static inline bool cc_joined(const ori_layers *L, int t, int vtx, int vty)
{
    int nx = 2 * vtx + (L->var_faces[vtx][0] != t), ny = 2 * vty + (L->var_faces[vty][0] != t);
    return L->cc_node[nx] == L->cc_node[ny];
}

// The triple of faces a < b, c with variables vab, vac, vbc is dropped by that rule.
static bool ff_tied(const ori_layers *L, int a, int b, int c, int vab, int vac, int vbc)
{
    (void)c;
    return cc_joined(L, a, vab, vac) || cc_joined(L, b, vab, vbc) || cc_joined(L, c, vac, vbc);
}

// Split the free classes set[0 … n) into connected components, written one after another into
// out with component j at out[starts[j] … starts[j + 1]); hashes (may be NULL) receives a key of
// each component: its classes and the values of the fixed variables its live constraints
// touch. Returns the number of components.
static int split(solver *s, const int *set, int n, int *out, int *starts, uint64_t (*hashes)[2])
{
    const ori_layers *L = s->L;
    const int8_t *val = s->val;
    if (s->set_id > INT32_MAX - 2 || s->seen_id > INT32_MAX - 2 || s->vseen_id > INT32_MAX - 2 * (n + 1)) {
        // Stamps wrap after 2^31 splits: start them over.
        memset(s->in_set, 0, sizeof(int) * (size_t)(L->n_class ? L->n_class : 1));
        memset(s->seen, 0, sizeof(int) * (size_t)(L->n_class ? L->n_class : 1));
        memset(s->vseen, 0, sizeof(int) * (size_t)(L->nvar ? L->nvar : 1));
        s->set_id = s->seen_id = s->vseen_id = 0;
    }
    int sid = ++s->set_id, vid = ++s->seen_id;
    for (int i = 0; i < n; ++i) s->in_set[set[i]] = sid;
    int ncomp = 0, tail = 0;
    for (int i = 0; i < n; ++i) {
        int c0 = set[i];
        if (s->seen[c0] == vid) continue;
        starts[ncomp] = tail;
        uint64_t h[2] = {0, 0};
        int bid = ++s->vseen_id;
        int head = tail;
        out[tail++] = c0;
        s->seen[c0] = vid;
        while (head < tail) {
            int c = out[head++];
            int live = 0;
            if (hashes) hash_add(h, (uint64_t)c);
            for (int64_t m = L->class_vars.off[c]; m < L->class_vars.off[c + 1]; ++m) {
                int v = L->class_vars.items[m];
                for (int64_t k = L->var_tacos.off[v]; k < L->var_tacos.off[v + 1]; ++k) {
                    const ori__taco *t = &L->taco[L->var_tacos.items[k]];
                    if (L->table6[taco_code(val, t)] & ORI__TABLE_DEAD) continue;
                    live += 3;
                    for (int j = 0; j < 6; ++j) {
                        int u = ORI__LIT_VAR(t->lit[j]);
                        if (val[u]) {
                            if (hashes && s->vseen[u] != bid) {
                                s->vseen[u] = bid;
                                hash_add(h, ((uint64_t)1 << 62) | ((uint64_t)u << 1) | (val[u] > 0));
                            }
                            continue;
                        }
                        int cu = L->var_class[u];
                        if (s->in_set[cu] == sid && s->seen[cu] != vid) {
                            s->seen[cu] = vid;
                            out[tail++] = cu;
                        }
                    }
                }
                // Triples with v and another free variable: the faces free against a or b
                // (neither above nor below it), from the bit rows.
                for (int64_t k = L->var_slot_off[v]; k < L->var_slot_off[v + 1]; ++k) {
                    const ori__slot *sl = &L->slots[k];
                    const ori__stack *S = &L->stacks[sl->stack];
                    const int *F = L->stack_faces + S->faces_at;
                    int kk = S->k, w = S->words;
                    const int *Ma = L->stack_vars + S->vars_at + (int64_t)sl->ia * kk;
                    const int *Mb = L->stack_vars + S->vars_at + (int64_t)sl->ib * kk;
                    const uint64_t *up = s->bits + S->bits_at, *down = up + (int64_t)kk * w;
                    const uint64_t *ua = up + (int64_t)sl->ia * w, *da = down + (int64_t)sl->ia * w;
                    const uint64_t *ub = up + (int64_t)sl->ib * w, *db = down + (int64_t)sl->ib * w;
                    for (int qw = 0; qw < w; ++qw) {
                        uint64_t valid = qw == w - 1 && (kk & 63) ? (((uint64_t)1 << (kk & 63)) - 1) : ~(uint64_t)0;
                        uint64_t fr = (~(ua[qw] | da[qw]) | ~(ub[qw] | db[qw])) & valid;
                        while (fr) {
                            int x = qw * 64 + __builtin_ctzll(fr);
                            fr &= fr - 1;
                            if (x == sl->ia || x == sl->ib) continue;
                            int p = Ma[x], q = Mb[x];
                            if (s->ff_rule ? ff_tied(L, F[sl->ia], F[sl->ib], F[x], v, p, q)
                                           : triple_tied(L, v, q, sl->ib > x, p, sl->ia > x))
                                continue;
                            live++;
                            for (int ww = 0; ww < 2; ++ww) {
                                int u = ww ? q : p;
                                if (val[u]) {
                                    if (hashes && s->vseen[u] != bid) {
                                        s->vseen[u] = bid;
                                        hash_add(h, ((uint64_t)1 << 62) | ((uint64_t)u << 1) | (val[u] > 0));
                                    }
                                    continue;
                                }
                                int cu = L->var_class[u];
                                if (s->in_set[cu] == sid && s->seen[cu] != vid) {
                                    s->seen[cu] = vid;
                                    out[tail++] = cu;
                                }
                            }
                        }
                    }
                }
            }
            s->score[c] = live;
        }
        if (hashes) {
            hashes[ncomp][0] = h[0] ^ ((uint64_t)(tail - starts[ncomp]) << 40);
            hashes[ncomp][1] = h[1];
        }
        ncomp++;
    }
    starts[ncomp] = tail;
    return ncomp;
}


static int uf_root(int *uf, int x)
{
    while (uf[x] != x) x = uf[x] = uf[uf[x]];
    return x;
}

static int cmp_pair(const void *a, const void *b)
{
    const int *x = a, *y = b;
    if (x[0] != y[0]) return (x[0] > y[0]) - (x[0] < y[0]);
    return (x[1] > y[1]) - (x[1] < y[1]);
}

static void push_pair(int **arr, int *n, int *cap, int a, int b)
{
    if (*n + 2 > *cap) {
        *cap = *cap ? 2 * *cap : 256;
        *arr = ori__realloc(*arr, sizeof(int) * (size_t)*cap);
    }
    (*arr)[(*n)++] = a;
    (*arr)[(*n)++] = b;
}

// The same split when no class of the set touches a stack with tied variables: then, inside a
// stack, two free variables sharing a face are joined by their (live) triple, so union-find on
// the faces of every stack holding each free variable finds the components in time linear in
// the stack slots, instead of scanning every third face. The key's boundary is a superset, "the
// fixed variables between faces of the component within one stack" (plus live tacos' fixed
// literals): it holds every fixed variable a live triple of the component touches, and it is a
// function of the set and the values alone, so equal keys still mean equal counts.
static int split_fast(solver *s, const int *set, int n, int *out, int *starts, uint64_t (*hashes)[2])
{
    const ori_layers *L = s->L;
    const int8_t *val = s->val;
    if (s->set_id > INT32_MAX - 2 || s->face_id > INT32_MAX - 2) {
        memset(s->in_set, 0, sizeof(int) * (size_t)(L->n_class ? L->n_class : 1));
        int64_t nsf = L->n_stack ? L->stacks[L->n_stack - 1].faces_at + L->stacks[L->n_stack - 1].k : 0;
        memset(s->face_stamp, 0, sizeof(int) * (size_t)(nsf ? nsf : 1));
        s->set_id = s->face_id = 0;
    }
    int sid = ++s->set_id, fid = ++s->face_id;
    for (int i = 0; i < n; ++i) {
        s->in_set[set[i]] = sid;
        s->uf[set[i]] = set[i];
        s->score[set[i]] = 0;
    }
    s->nreg = 0;
    s->npend = 0;
    for (int i = 0; i < n; ++i) {
        int c = set[i];
        for (int64_t m = L->class_vars.off[c]; m < L->class_vars.off[c + 1]; ++m) {
            int v = L->class_vars.items[m];
            for (int64_t k = L->var_tacos.off[v]; k < L->var_tacos.off[v + 1]; ++k) {
                const ori__taco *t = &L->taco[L->var_tacos.items[k]];
                if (L->table6[taco_code(val, t)] & ORI__TABLE_DEAD) continue;
                s->score[c] += 3;
                for (int j = 0; j < 6; ++j) {
                    int u = ORI__LIT_VAR(t->lit[j]);
                    if (val[u]) {
                        if (hashes) push_pair(&s->pend, &s->npend, &s->pendcap, c, u);
                        continue;
                    }
                    int cu = L->var_class[u];
                    if (s->in_set[cu] != sid) continue;
                    int ra = uf_root(s->uf, c), rb = uf_root(s->uf, cu);
                    if (ra != rb) s->uf[ra] = rb;
                }
            }
            for (int64_t k = L->var_fslot_off[v]; k < L->var_fslot_off[v + 1]; ++k) {
                const ori__fslot *fs = &L->fslots[k];
                const ori__stack *S = &L->stacks[fs->stack];
                for (int e = 0; e < 2; ++e) {
                    int f = e ? fs->ib : fs->ia;
                    int64_t idx = S->faces_at + f;
                    if (s->face_stamp[idx] == fid) {
                        s->score[c]++;
                        int ra = uf_root(s->uf, c), rb = uf_root(s->uf, s->face_rep[idx]);
                        if (ra != rb) s->uf[ra] = rb;
                    } else {
                        s->face_stamp[idx] = fid;
                        s->face_rep[idx] = c;
                        push_pair(&s->reg, &s->nreg, &s->regcap, fs->stack, f);
                    }
                }
            }
        }
    }
    // Components in the order of their first class. While numbering, in_set of a root holds
    // −(component + 1); it is a plain set stamp again on return.
    int ncomp = 0;
    int *count = ori__calloc((size_t)n + 1, sizeof(int));
    for (int i = 0; i < n; ++i) {
        int r = uf_root(s->uf, set[i]);
        if (s->in_set[r] == sid) s->in_set[r] = -(++ncomp);
        count[-s->in_set[r]]++;
    }
    starts[0] = 0;
    for (int j = 0; j < ncomp; ++j) starts[j + 1] = starts[j] + count[j + 1];
    memset(count, 0, sizeof(int) * (size_t)(ncomp + 1));
    uint64_t(*h)[2] = hashes;
    if (h)
        for (int j = 0; j < ncomp; ++j) h[j][0] = h[j][1] = 0;
    for (int i = 0; i < n; ++i) {
        int j = -s->in_set[uf_root(s->uf, set[i])] - 1;
        out[starts[j] + count[j]++] = set[i];
        if (h) hash_add(h[j], (uint64_t)set[i]);
    }
    if (h) {
        for (int i = 0; i < s->npend; i += 2) {
            int j = -s->in_set[uf_root(s->uf, s->pend[i])] - 1;
            int u = s->pend[i + 1];
            hash_add(h[j], ((uint64_t)1 << 62) | ((uint64_t)u << 1) | (val[u] > 0));
        }
        // Registered faces grouped by stack, then the fixed variables between faces of one
        // component.
        int nr = s->nreg / 2;
        if (nr > 1) qsort(s->reg, (size_t)nr, 2 * sizeof(int), cmp_pair);
        // The component of each registration, once (reusing the first half of pend's room).
        int *comp = ori__alloc(sizeof(int) * (size_t)(nr ? nr : 1));
        for (int a = 0; a < nr; ++a)
            comp[a] = -s->in_set[uf_root(s->uf, s->face_rep[L->stacks[s->reg[2 * a]].faces_at + s->reg[2 * a + 1]])] - 1;
        for (int a = 0; a < nr;) {
            int st = s->reg[2 * a], e = a;
            while (e < nr && s->reg[2 * e] == st) e++;
            const ori__stack *S = &L->stacks[st];
            for (int x = a; x < e; ++x) {
                const int *Mrow = L->stack_vars + S->vars_at + (int64_t)s->reg[2 * x + 1] * S->k;
                for (int y = x + 1; y < e; ++y) {
                    if (comp[y] != comp[x]) continue;
                    int u = Mrow[s->reg[2 * y + 1]];
                    if (val[u]) hash_add(h[comp[x]], ((uint64_t)1 << 62) | ((uint64_t)u << 1) | (val[u] > 0));
                }
            }
            a = e;
        }
        ori__free(comp);
        for (int j = 0; j < ncomp; ++j) h[j][0] ^= (uint64_t)(starts[j + 1] - starts[j]) << 40;
    }
    for (int i = 0; i < n; ++i) s->in_set[set[i]] = sid;
    ori__free(count);
    return ncomp;
}

// --- counting -------------------------------------------------------------------------------

// Branch on the class in the most live constraints (counted when the set was split off: those
// still able to constrain something), the static weight breaking ties.
static int choose(const solver *s, const int *set, int n)
{
    int best = set[0];
    int bs = -1;
    int64_t bw = -1;
    for (int i = 0; i < n; ++i) {
        int c = set[i], sc = s->score[c];
        int64_t w = s->L->class_weight[c];
        if (sc > bs || (sc == bs && w > bw)) {
            bs = sc;
            bw = w;
            best = c;
        }
    }
    return best;
}

static void report(solver *s)
{
    const ori_layers *L = s->L;
    if (!s->main_thread || !L->progress) return;
    // Within a component, the share of its search tree already left behind: each decision halves
    // its node's interval, each sub-component takes an equal part of its branch's.
    double f = s->done_fraction + s->comp_share * s->pos_lo;
    if (!L->progress(f < 1.0 ? f : 1.0, L->progress_user)) s->cancel = true;
}

static void count_set(solver *s, const int *set, int n, ori__nat *res, bool *exact, int level, int skip);


// Count component (set, n) with key h, through the cache.
static void count_cached(solver *s, const int *set, int n, const uint64_t h[2], ori__nat *res, bool *exact, int level,
                         int skip)
{
    cache_entry *e = NULL;
    if (s->cache && n > 1) {
        e = &s->cache[h[0] & s->cmask];
        if (e->h1 == h[0] && e->h2 == h[1] && (e->h1 | e->h2)) {
            ori__nat_copy(res, &e->count);
            *exact = true;
            return;
        }
    }
    count_set(s, set, n, res, exact, level, skip);
    if (e && *exact && !s->cancel) {
        e->h1 = h[0];
        e->h2 = h[1];
        ori__nat_copy(&e->count, res);
    }
}

// The free classes of set (after a decision), split; returns the component count and hands
// out the arrays (free them with free_parts).
typedef struct parts {
    int *rest, *out, *starts;
    uint64_t (*h)[2];
    int n, ncomp;
} parts;

static void make_parts(solver *s, const int *set, int n, parts *P)
{
    P->rest = ori__alloc(sizeof(int) * (size_t)n);
    P->n = 0;
    for (int i = 0; i < n; ++i)
        if (!s->cval[set[i]]) P->rest[P->n++] = set[i];
    P->out = ori__alloc(sizeof(int) * (size_t)(P->n ? P->n : 1));
    P->starts = ori__alloc(sizeof(int) * (size_t)(P->n + 1));
    P->h = ori__alloc(sizeof(*P->h) * (size_t)(P->n ? P->n : 1));
    bool tied = false;
    for (int i = 0; i < P->n && !tied; ++i) tied = s->L->class_tied[P->rest[i]];
    P->ncomp = !P->n ? 0
               : tied ? split(s, P->rest, P->n, P->out, P->starts, P->h)
                      : split_fast(s, P->rest, P->n, P->out, P->starts, P->h);
}

static void free_parts(parts *P)
{
    ori__free(P->rest);
    ori__free(P->out);
    ori__free(P->starts);
    ori__free(P->h);
}

// Backoff of the splitting: after a split that finds one component (a dense problem where the
// decisions rarely disconnect anything), the next 2^level − 1 decisions count the remaining set
// as one, without splitting or caching; a split that does disconnect resets the backoff.
#define ORI__SPLIT_BACKOFF_MAX 3

static void count_set(solver *s, const int *set, int n, ori__nat *res, bool *exact, int level, int skip)
{
    ori__nat_set_u64(res, 0);
    *exact = true;
    if (++s->nodes % 4096 == 0) report(s);
    if (s->node_cap > 0 && s->nodes > s->node_cap) s->cancel = true;
    if (s->stop && (s->nodes & 63) == 0 && atomic_load(s->stop)) s->cancel = true;
    if (s->cancel) {
        *exact = false;
        return;
    }
    int x = choose(s, set, n);
    ori__nat prod, sub;
    ori__nat_init(&prod);
    ori__nat_init(&sub);
    double lo = s->pos_lo, half = 0.5 * s->pos_w;
    for (int b = 0; b < 2 && !s->cancel; ++b) {
        int mark = s->ntrail;
        assign_class(s, x, b == 0 ? 1 : -1);
        if (!propagate(s)) {
            undo(s, mark);
            continue;
        }
        bool pex = true;
        s->pos_lo = lo + b * half;
        s->pos_w = half;
        if (skip > 0) {
            int *rest = ori__alloc(sizeof(int) * (size_t)n);
            int m = 0;
            for (int i = 0; i < n; ++i)
                if (!s->cval[set[i]]) rest[m++] = set[i];
            if (m == 0) ori__nat_set_u64(&prod, 1);
            else count_set(s, rest, m, &prod, &pex, level, skip - 1);
            ori__free(rest);
        } else {
            parts P;
            make_parts(s, set, n, &P);
            int lv = P.ncomp == 1 && P.n > 1 ? (level < ORI__SPLIT_BACKOFF_MAX ? level + 1 : level) : 0;
            ori__nat_set_u64(&prod, 1);
            for (int j = 0; j < P.ncomp && !s->cancel; ++j) {
                bool sex;
                s->pos_lo = lo + b * half + j * half / P.ncomp;
                s->pos_w = half / P.ncomp;
                count_cached(s, P.out + P.starts[j], P.starts[j + 1] - P.starts[j], P.h[j], &sub, &sex, lv, (1 << lv) - 1);
                if (ori__nat_is_zero(&sub)) {
                    ori__nat_set_u64(&prod, 0);
                    pex = sex;
                    break;
                }
                ori__nat_mul(&prod, &sub);
                pex = pex && sex;
            }
            free_parts(&P);
        }
        undo(s, mark);
        ori__nat_add(res, &prod);
        *exact = *exact && pex;
        if (s->limit != ORI_LAYERS_NO_LIMIT && ori__nat_cmp_u64(res, s->limit) >= 0) {
            ori__nat_set_u64(res, s->limit);
            *exact = false;
            break;
        }
    }
    if (s->cancel) *exact = false;
    s->pos_lo = lo;
    s->pos_w = 2.0 * half;
    ori__nat_free(&prod);
    ori__nat_free(&sub);
}

// --- set-up ---------------------------------------------------------------------------------

static int uf_find(int *parent, int8_t *par, int x, int8_t *p_out)
{
    int8_t p = 1;
    int r = x;
    while (parent[r] != r) {
        p = (int8_t)(p * par[r]);
        r = parent[r];
    }
    // Path compression with parities.
    int8_t acc = p;
    while (parent[x] != x) {
        int next = parent[x];
        int8_t px = par[x];
        parent[x] = r;
        par[x] = acc;
        acc = (int8_t)(acc * px);
        x = next;
    }
    *p_out = p;
    return r;
}

static void copy_conflict(ori_layers *L, const solver *s)
{
    L->unsat = true;
    L->conflict.constraint = (ori_layers_constraint)s->conf_kind;
    L->conflict.face_count = s->conf_nfaces;
    for (int i = 0; i < 4; ++i) L->conflict.faces[i] = i < s->conf_nfaces ? s->conf_faces[i] : -1;
    L->conflict.vertex = ORI_NULL_INDEX;
    L->conflict.component = -1;
}

// Faces of the conflict and of every order that forced it (reasons followed back to the
// creases), for the report.
static void conflict_closure(ori_layers *L, const solver *s)
{
    uint8_t *fmark = ori__calloc((size_t)(L->nf ? L->nf : 1), 1);
    uint8_t *vmark = ori__calloc((size_t)(L->nvar ? L->nvar : 1), 1);
    int *stack = NULL;
    int n = 0, cap = 0;
    int nf = s->conf_nfaces;
    for (int i = 0; i < nf; ++i)
        for (int j = i + 1; j < nf; ++j) {
            int v = ori__layers_var(L, s->conf_faces[i], s->conf_faces[j]);
            if (v >= 0 && !vmark[v]) {
                vmark[v] = 1;
                ORI__PUSH(stack, n, cap, v);
            }
        }
    for (int i = 0; i < nf; ++i) fmark[s->conf_faces[i]] = 1;
    while (n > 0) {
        int v = stack[--n];
        fmark[L->var_faces[v][0]] = fmark[L->var_faces[v][1]] = 1;
        if (!s->rkind || !s->val[v]) continue;
        int k = s->rkind[v];
        int nxt[6];
        int m = 0;
        if (k == R_CLASS) nxt[m++] = s->rdata[v][0];
        else if (k == R_TACO || k == R_TRANS) {
            int cnt = k == R_TACO ? 4 : 3;
            for (int i = 0; i < cnt; ++i)
                for (int j = i + 1; j < cnt; ++j) {
                    int u = ori__layers_var(L, s->rdata[v][i], s->rdata[v][j]);
                    if (u >= 0) nxt[m++] = u;
                }
        }
        for (int i = 0; i < m; ++i)
            if (!vmark[nxt[i]]) {
                vmark[nxt[i]] = 1;
                ORI__PUSH(stack, n, cap, nxt[i]);
            }
    }
    ori__free(stack);
    int count = 0;
    for (int f = 0; f < L->nf; ++f) count += fmark[f];
    L->conflict_faces = ori__alloc(sizeof(int) * (size_t)(count ? count : 1));
    L->n_conflict_faces = 0;
    for (int f = 0; f < L->nf; ++f)
        if (fmark[f]) L->conflict_faces[L->n_conflict_faces++] = f;
    ori__free(fmark);
    ori__free(vmark);
}

typedef struct comp_sort {
    int vars, first, root;
} comp_sort;

static int cmp_comp(const void *a, const void *b)
{
    const comp_sort *x = a, *y = b;
    if (x->vars != y->vars) return x->vars < y->vars ? -1 : 1;
    return (x->first > y->first) - (x->first < y->first);
}

ori_status ori__layers_presolve(ori_layers *L, ori_error *error)
{
    (void)error;
    int nvar = L->nvar;
    // 1. Classes: union-find with parity over the equivalences.
    int *parent = ori__alloc(sizeof(int) * (size_t)(nvar ? nvar : 1));
    int8_t *par = ori__alloc((size_t)(nvar ? nvar : 1));
    for (int v = 0; v < nvar; ++v) {
        parent[v] = v;
        par[v] = 1;
    }
    for (int i = 0; i < L->n_equiv && !L->unsat; ++i) {
        const ori__equiv *q = &L->equiv[i];
        int v1 = ORI__LIT_VAR(q->lit[0]), v2 = ORI__LIT_VAR(q->lit[1]);
        int8_t s1 = ORI__LIT_NEG(q->lit[0]) ? -1 : 1, s2 = ORI__LIT_NEG(q->lit[1]) ? -1 : 1;
        int8_t p1, p2;
        int r1 = uf_find(parent, par, v1, &p1), r2 = uf_find(parent, par, v2, &p2);
        // x[v1]·s1 = x[v2]·s2 with x[vi] = pi·x[ri].
        int8_t rel = (int8_t)(s1 * p1 * s2 * p2);
        if (r1 == r2) {
            if (rel != 1) {
                L->unsat = true;
                L->conflict.constraint = (ori_layers_constraint)q->kind;
                int nfc = q->faces[2] == q->faces[3] ? 3 : 4;
                L->conflict.face_count = nfc;
                for (int k = 0; k < 4; ++k) L->conflict.faces[k] = k < nfc ? q->faces[k] : -1;
                L->conflict.vertex = ORI_NULL_INDEX;
                L->conflict.component = -1;
            }
            continue;
        }
        parent[r2] = r1;
        par[r2] = rel;
    }
    L->var_class = ori__alloc(sizeof(int) * (size_t)(nvar ? nvar : 1));
    L->var_par = ori__alloc((size_t)(nvar ? nvar : 1));
    int *cid = ori__alloc(sizeof(int) * (size_t)(nvar ? nvar : 1));
    for (int v = 0; v < nvar; ++v) cid[v] = -1;
    L->n_class = 0;
    for (int v = 0; v < nvar; ++v) {
        int8_t p;
        int r = uf_find(parent, par, v, &p);
        if (cid[r] < 0) cid[r] = L->n_class++;
        L->var_class[v] = cid[r];
        L->var_par[v] = p;
    }
    ori__free(cid);
    ori__free(parent);
    ori__free(par);
    int nc = L->n_class;
    int64_t *off = ori__calloc((size_t)nc + 1, sizeof(int64_t));
    for (int v = 0; v < nvar; ++v) off[L->var_class[v] + 1]++;
    for (int c = 0; c < nc; ++c) off[c + 1] += off[c];
    L->class_vars.rows = nc;
    L->class_vars.off = off;
    L->class_vars.items = ori__alloc(sizeof(int) * (size_t)(nvar ? nvar : 1));
    int64_t *fill = ori__alloc(sizeof(int64_t) * (size_t)(nc ? nc : 1));
    memcpy(fill, off, sizeof(int64_t) * (size_t)nc);
    for (int v = 0; v < nvar; ++v) L->class_vars.items[fill[L->var_class[v]]++] = v;
    ori__free(fill);
    L->class_weight = ori__calloc((size_t)(nc ? nc : 1), sizeof(int64_t));
    for (int v = 0; v < nvar; ++v) {
        int64_t w = 3 * (L->var_tacos.off[v + 1] - L->var_tacos.off[v]);
        for (int64_t k = L->var_slot_off[v]; k < L->var_slot_off[v + 1]; ++k) w += L->stacks[L->slots[k].stack].k - 2;
        L->class_weight[L->var_class[v]] += w;
    }
    // Stacks holding two variables of one class: their triples may be tied (split_fast avoids
    // the classes that touch them).
    L->class_tied = ori__calloc((size_t)(nc ? nc : 1), 1);
    {
        int *stamp = ori__alloc(sizeof(int) * (size_t)(nc ? nc : 1));
        for (int c = 0; c < nc; ++c) stamp[c] = -1;
        for (int st = 0; st < L->n_stack; ++st) {
            const ori__stack *S = &L->stacks[st];
            const int *M = L->stack_vars + S->vars_at;
            bool tied = false;
            for (int a = 0; a < S->k && !tied; ++a)
                for (int b = a + 1; b < S->k && !tied; ++b) {
                    int c = L->var_class[M[a * S->k + b]];
                    if (stamp[c] == st) tied = true;
                    stamp[c] = st;
                }
            if (!tied) continue;
            for (int a = 0; a < S->k; ++a)
                for (int b = a + 1; b < S->k; ++b) L->class_tied[L->var_class[M[a * S->k + b]]] = 1;
        }
        ori__free(stamp);
    }
    L->class_val = ori__calloc((size_t)(nc ? nc : 1), 1);
    L->var_val = ori__calloc((size_t)(nvar ? nvar : 1), 1);
    if (L->unsat) return ORI_OK;

    // 2. The creases' assignments, then propagation.
    solver s;
    solver_init(&s, L, false);
    s.track = true;
    s.rkind = ori__calloc((size_t)(nvar ? nvar : 1), 1);
    s.rdata = ori__calloc((size_t)(nvar ? nvar : 1), sizeof(*s.rdata));
    for (int e = 0; e < L->ne && !L->unsat; ++e) {
        ori_assignment a = L->asg[e];
        if (a != ORI_ASSIGN_MOUNTAIN && a != ORI_ASSIGN_VALLEY) continue;
        int l = L->ef[e][0], r = L->ef[e][1];
        if (l < 0 || r < 0 || l == r) continue;
        // Across a valley the moving face comes to the front side of the other one.
        bool r_above = (a == ORI_ASSIGN_VALLEY) != (L->flip[l] != 0);
        int lit = r_above ? ori__layers_above(L, r, l) : ori__layers_above(L, l, r);
        if (lit < 0) continue; // cannot happen for a folded crease
        int rf[4] = {e, l, r, -1};
        if (!set_lit(&s, lit, R_CREASE, rf)) {
            set_conflict(&s, ORI_LAYERS_ASSIGNMENT, l, r, -1, -1, 2);
            copy_conflict(L, &s);
            snprintf(L->conflict.detail, sizeof L->conflict.detail,
                     "the M/V assignment of crease %d contradicts the orders other creases force on faces %d and %d",
                     e, l, r);
            conflict_closure(L, &s);
        }
    }
    if (!L->unsat && !propagate(&s)) {
        copy_conflict(L, &s);
        conflict_closure(L, &s);
    }
    if (L->unsat) {
        solver_free(&s);
        return ORI_OK;
    }
    memcpy(L->var_val, s.val, (size_t)nvar);
    memcpy(L->class_val, s.cval, (size_t)nc);

    // 3. Components of the free classes (Flat-Folder's rule and order: by number of variables).
    {
        int nn = 2 * nvar;
        int *root = ori__alloc(sizeof(int) * (size_t)(nn ? nn : 1));
        for (int i = 0; i < nn; ++i) root[i] = i;
        for (int i = 0; i < L->n_equiv; ++i) {
            const ori__equiv *q = &L->equiv[i];
            if (q->kind != ORI_LAYERS_TACO_TORTILLA) continue;
            int t = q->faces[2], va = ori__layers_var(L, t, q->faces[0]), vb = ori__layers_var(L, t, q->faces[1]);
            int na = 2 * va + (L->var_faces[va][0] != t), nb = 2 * vb + (L->var_faces[vb][0] != t);
            int r0 = ori__uf_root(root, na), r1 = ori__uf_root(root, nb);
            if (r0 != r1) root[r0] = r1;
        }
        for (int i = 0; i < nn; ++i) root[i] = ori__uf_root(root, i);
        L->cc_node = root;
    }
    s.ff_rule = true;
    int *freec = ori__alloc(sizeof(int) * (size_t)(nc ? nc : 1));
    int nfree = 0;
    for (int c = 0; c < nc; ++c)
        if (!s.cval[c]) freec[nfree++] = c;
    int *out = ori__alloc(sizeof(int) * (size_t)(nfree ? nfree : 1));
    int *starts = ori__alloc(sizeof(int) * (size_t)(nfree + 1));
    int ncomp = nfree ? split(&s, freec, nfree, out, starts, NULL) : 0;
    comp_sort *cs = ori__alloc(sizeof(comp_sort) * (size_t)(ncomp ? ncomp : 1));
    for (int j = 0; j < ncomp; ++j) {
        cs[j].root = j;
        cs[j].vars = 0;
        cs[j].first = INT32_MAX;
        for (int i = starts[j]; i < starts[j + 1]; ++i) {
            int c = out[i];
            cs[j].vars += (int)(L->class_vars.off[c + 1] - L->class_vars.off[c]);
            int v0 = L->class_vars.items[L->class_vars.off[c]];
            if (v0 < cs[j].first) cs[j].first = v0;
        }
    }
    if (ncomp > 1) qsort(cs, (size_t)ncomp, sizeof(comp_sort), cmp_comp);
    L->n_comp = ncomp + 1;
    L->comp_vars = ori__alloc(sizeof(int) * (size_t)(ncomp + 1));
    L->comp_classes.rows = ncomp + 1;
    L->comp_classes.off = ori__alloc(sizeof(int64_t) * (size_t)(ncomp + 2));
    L->comp_classes.items = ori__alloc(sizeof(int) * (size_t)(nfree ? nfree : 1));
    int fixed = 0;
    for (int v = 0; v < nvar; ++v) fixed += s.val[v] != 0;
    L->comp_vars[0] = fixed;
    L->comp_classes.off[0] = 0;
    L->comp_classes.off[1] = 0;
    int64_t at = 0;
    for (int j = 0; j < ncomp; ++j) {
        int r = cs[j].root;
        for (int i = starts[r]; i < starts[r + 1]; ++i) L->comp_classes.items[at++] = out[i];
        L->comp_classes.off[j + 2] = at;
        L->comp_vars[j + 1] = cs[j].vars;
    }
    ori__free(cs);
    ori__free(freec);
    ori__free(out);
    ori__free(starts);
    solver_free(&s);
    return ORI_OK;
}

// --- solve ----------------------------------------------------------------------------------

// Nodes of the short search that gives the components not counted before a cancel their lower
// bound (a first state each), all of them together.
#define ORI__PARTIAL_NODES 20000

typedef struct pool {
    ori_layers *L;
    atomic_int next;
    atomic_bool cancel;
    atomic_bool limited;
    atomic_llong done_vars;
    int64_t total_vars;
    uint8_t *done; // per component: 0 not counted, 1 exact, 2 a lower bound
} pool;

static void start_solver(solver *s, const ori_layers *L)
{
    solver_init(s, L, true);
    memcpy(s->val, L->var_val, (size_t)L->nvar);
    memcpy(s->cval, L->class_val, (size_t)L->n_class);
    for (int v = 0; v < L->nvar; ++v)
        if (s->val[v]) set_bits(s, v, s->val[v]);
}

// Count component j into L->comp_count[j]; done[j] becomes 1 when exact, 2 when a lower bound
// (the limit, or a cancel).
static void count_component(solver *s, ori_layers *L, int j, uint8_t *done)
{
    const int *set = L->comp_classes.items + L->comp_classes.off[j];
    int n = (int)(L->comp_classes.off[j + 1] - L->comp_classes.off[j]);
    bool exact;
    s->pos_lo = 0.0;
    s->pos_w = 1.0;
    count_set(s, set, n, &L->comp_count[j], &exact, 0, 0);
    if (!exact) s->limited = true;
    done[j] = exact ? 1 : 2;
}

static void *worker(void *arg)
{
    pool *P = arg;
    ori_layers *L = P->L;
    solver s;
    start_solver(&s, L);
    s.stop = &P->cancel;
    for (;;) {
        if (atomic_load(&P->cancel)) break;
        // Largest components first (they are sorted by ascending size): better balance.
        int j = L->n_comp - atomic_fetch_add(&P->next, 1);
        if (j < 1) break;
        count_component(&s, L, j, P->done);
        if (s.cancel) atomic_store(&P->cancel, true);
        atomic_fetch_add(&P->done_vars, L->comp_vars[j]);
    }
    if (s.limited) atomic_store(&P->limited, true);
    solver_free(&s);
    return NULL;
}

ori_status ori__layers_solve(ori_layers *L, ori_error *error)
{
    L->comp_count = ori__alloc(sizeof(ori__nat) * (size_t)(L->n_comp ? L->n_comp : 1));
    for (int j = 0; j < L->n_comp; ++j) ori__nat_init(&L->comp_count[j]);
    if (L->n_comp > 0) ori__nat_set_u64(&L->comp_count[0], 1);
    pool P;
    P.L = L;
    atomic_init(&P.next, 1);
    atomic_init(&P.cancel, false);
    atomic_init(&P.limited, false);
    atomic_init(&P.done_vars, 0);
    P.total_vars = 0;
    for (int j = 1; j < L->n_comp; ++j) P.total_vars += L->comp_vars[j];
    P.done = ori__calloc((size_t)(L->n_comp ? L->n_comp : 1), 1);
    if (L->n_comp > 0) P.done[0] = 1;
    int extra = L->threads - 1;
    if (extra > L->n_comp - 2) extra = L->n_comp - 2;
    if (extra < 0) extra = 0;
    pthread_t *tids = ori__alloc(sizeof(pthread_t) * (size_t)(extra ? extra : 1));
    int started = 0;
    for (int i = 0; i < extra; ++i)
        if (pthread_create(&tids[i], NULL, worker, &P) == 0) started++;
        else break;
    // The calling thread works too, and it alone reports progress.
    solver s;
    start_solver(&s, L);
    s.main_thread = true;
    for (;;) {
        if (atomic_load(&P.cancel)) break;
        int j = L->n_comp - atomic_fetch_add(&P.next, 1);
        if (j < 1) break;
        s.done_fraction = P.total_vars ? (double)atomic_load(&P.done_vars) / (double)P.total_vars : 0.0;
        s.comp_share = P.total_vars ? (double)L->comp_vars[j] / (double)P.total_vars : 0.0;
        count_component(&s, L, j, P.done);
        if (s.cancel) atomic_store(&P.cancel, true);
        atomic_fetch_add(&P.done_vars, L->comp_vars[j]);
        s.done_fraction = P.total_vars ? (double)atomic_load(&P.done_vars) / (double)P.total_vars : 1.0;
        report(&s);
        if (s.cancel) atomic_store(&P.cancel, true);
    }
    for (int i = 0; i < started; ++i) pthread_join(tids[i], NULL);
    ori__free(tids);
    bool cancelled = atomic_load(&P.cancel);
    if (cancelled) {
        // A partial answer: the components not counted get a lower bound too, the first state
        // a short search finds (1), else 0; nothing is then known to have no state.
        // One budget of nodes for all of them, smallest first (the most lower bounds above 0).
        s.main_thread = false;
        s.limit = 1;
        int64_t cap = s.nodes + ORI__PARTIAL_NODES;
        for (int j = 1; j < L->n_comp && s.nodes < cap; ++j) {
            if (P.done[j]) continue;
            s.cancel = false;
            s.node_cap = cap;
            count_component(&s, L, j, P.done);
            P.done[j] = 2;
        }
        s.limited = true;
    }
    if (s.limited) atomic_store(&P.limited, true);
    solver_free(&s);
    L->limited = atomic_load(&P.limited);
    L->stopped = cancelled;
    ori__nat_set_u64(&L->total, 1);
    for (int j = 0; j < L->n_comp; ++j) ori__nat_mul(&L->total, &L->comp_count[j]);
    for (int j = 1; j < L->n_comp; ++j)
        if (ori__nat_is_zero(&L->comp_count[j]) && P.done[j] == 1) {
            ori__layers_set_exhausted(L, j);
            break;
        }
    ori__free(P.done);
    L->counted = true;
    // "cancelled", as every cancelled operation says (bindings map it); the counts so far stay.
    if (cancelled) return ori__fail(error, ORI_ERR_LIMIT, "cancelled");
    return ORI_OK;
}

// --- unranking ------------------------------------------------------------------------------

static bool unrank_set(solver *s, const int *set, int n, ori__nat *k)
{
    int x = choose(s, set, n);
    ori__nat prod, sub, q, r;
    ori__nat_init(&prod);
    ori__nat_init(&sub);
    ori__nat_init(&q);
    ori__nat_init(&r);
    bool found = false;
    for (int b = 0; b < 2 && !found; ++b) {
        int mark = s->ntrail;
        assign_class(s, x, b == 0 ? 1 : -1);
        if (!propagate(s)) {
            undo(s, mark);
            continue;
        }
        parts P;
        make_parts(s, set, n, &P);
        ori__nat *counts = ori__alloc(sizeof(ori__nat) * (size_t)(P.ncomp ? P.ncomp : 1));
        ori__nat_set_u64(&prod, 1);
        int lv = P.ncomp == 1 && P.n > 1 ? 1 : 0; // the counting search's backoff, from level 0
        for (int j = 0; j < P.ncomp; ++j) {
            bool ex;
            ori__nat_init(&counts[j]);
            count_cached(s, P.out + P.starts[j], P.starts[j + 1] - P.starts[j], P.h[j], &counts[j], &ex, lv, (1 << lv) - 1);
            ori__nat_mul(&prod, &counts[j]);
        }
        if (!ori__nat_is_zero(&prod) && ori__nat_cmp(k, &prod) < 0) {
            // State k lies in this branch: its digits (component 0 least significant).
            found = true;
            for (int j = 0; j < P.ncomp && found; ++j) {
                ori__nat_divmod(&q, &r, k, &counts[j]);
                ori__nat_copy(k, &q);
                found = unrank_set(s, P.out + P.starts[j], P.starts[j + 1] - P.starts[j], &r);
            }
        } else {
            ori__nat_sub(k, &prod);
            undo(s, mark);
        }
        for (int j = 0; j < P.ncomp; ++j) ori__nat_free(&counts[j]);
        ori__free(counts);
        free_parts(&P);
    }
    ori__nat_free(&prod);
    ori__nat_free(&sub);
    ori__nat_free(&q);
    ori__nat_free(&r);
    return found;
}

ori_status ori__layers_unrank(ori_layers *L, int comp, const ori__nat *k, int8_t *val, ori_error *error)
{
    solver s;
    start_solver(&s, L);
    ori__nat kk;
    ori__nat_init(&kk);
    ori__nat_copy(&kk, k);
    const int *set = L->comp_classes.items + L->comp_classes.off[comp];
    int n = (int)(L->comp_classes.off[comp + 1] - L->comp_classes.off[comp]);
    bool ok = n == 0 ? ori__nat_is_zero(&kk) : unrank_set(&s, set, n, &kk);
    ori_status st = ORI_OK;
    if (!ok) st = ori__fail(error, ORI_ERR_INTERNAL, "state not found in component %d", comp);
    else
        for (int i = 0; i < n; ++i) {
            int c = set[i];
            for (int64_t m = L->class_vars.off[c]; m < L->class_vars.off[c + 1]; ++m) {
                int v = L->class_vars.items[m];
                val[v] = s.val[v];
            }
        }
    ori__nat_free(&kk);
    solver_free(&s);
    return st;
}

// --- one component on its own (layers_parts.c) ------------------------------------------------

void ori__layers_count_one(const ori_layers *L, int j, ori__nat *res, bool *exact)
{
    solver s;
    start_solver(&s, L);
    const int *set = L->comp_classes.items + L->comp_classes.off[j];
    int n = (int)(L->comp_classes.off[j + 1] - L->comp_classes.off[j]);
    count_set(&s, set, n, res, exact, 0, 0);
    solver_free(&s);
}
