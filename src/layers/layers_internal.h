// Private pieces of the global layer-order solver (src/layers): exact natural numbers on GMP's
// mpn layer, the folded geometry, the overlap structure of the folded faces, the variables and
// constraints, and the counting solver. Never included by cli/ or public headers.
#ifndef ORI_LAYERS_INTERNAL_H
#define ORI_LAYERS_INTERNAL_H

#include <orikin/layers.h>

#include <gmp.h>
#include <stdint.h>

#include "../core/core_internal.h"

// --- exact natural numbers (bignum.c) ------------------------------------------------------
// A natural number as n little-endian limbs (n = 0 is zero, the top limb is non-zero). Limbs up
// to one are stored inline (d == NULL), so that the many small counts of a search never touch
// the heap. Every heap limb comes from the counted allocator: GMP's mpn functions take caller
// buffers and allocate nothing of their own for the sizes used here.
typedef struct ori__nat {
    int n;          // limbs in use
    int cap;        // heap capacity (0 while inline)
    mp_limb_t one;  // the inline limb
    mp_limb_t *d;   // heap limbs, or NULL
} ori__nat;

static inline const mp_limb_t *ori__nat_limbs(const ori__nat *x) { return x->d ? x->d : &x->one; }
void ori__nat_init(ori__nat *x);
void ori__nat_free(ori__nat *x);
void ori__nat_set_u64(ori__nat *x, uint64_t v);
void ori__nat_copy(ori__nat *dst, const ori__nat *src);
bool ori__nat_is_zero(const ori__nat *x);
int ori__nat_cmp(const ori__nat *a, const ori__nat *b);
int ori__nat_cmp_u64(const ori__nat *a, uint64_t v);
void ori__nat_add(ori__nat *acc, const ori__nat *b);       // acc += b
void ori__nat_sub(ori__nat *acc, const ori__nat *b);       // acc -= b (b ≤ acc)
void ori__nat_mul(ori__nat *acc, const ori__nat *b);       // acc *= b
void ori__nat_divmod(ori__nat *q, ori__nat *r, const ori__nat *a, const ori__nat *b); // b > 0
char *ori__nat_to_decimal(const ori__nat *x);              // ori__alloc'd, NUL-terminated
bool ori__nat_from_decimal(ori__nat *x, const char *s);    // digits only

// --- compressed sparse rows ----------------------------------------------------------------
// Row r holds items[off[r] .. off[r + 1]).
typedef struct ori__csr {
    int rows;
    int64_t *off;
    int *items;
} ori__csr;
void ori__csr_free(ori__csr *c);

// --- hash map from 64-bit keys to ints (map.c) ----------------------------------------------
// Open addressing with linear probing; the key UINT64_MAX is reserved (empty slot).
typedef struct ori__imap {
    uint64_t *keys;
    int *vals;
    int64_t cap, count;
} ori__imap;
void ori__imap_init(ori__imap *m, int64_t expected);
void ori__imap_free(ori__imap *m);
// The value of key, or -1.
int ori__imap_get(const ori__imap *m, uint64_t key);
// Insert key → val unless present; returns the value now stored.
int ori__imap_put(ori__imap *m, uint64_t key, int val);

// --- the solver object ----------------------------------------------------------------------

// Literal: 2·var + neg. Variable v joins faces a < b and is +1 when a lies above b (higher in
// the folded frame's +z), −1 when b lies above a; literal 2v is true when v = +1.
#define ORI__LIT(var, neg) (2 * (var) + (neg))
#define ORI__LIT_VAR(l) ((l) >> 1)
#define ORI__LIT_NEG(l) ((l) & 1)

// A binary equivalence lit_a ⇔ lit_b (taco-tortilla, tortilla-tortilla).
typedef struct ori__equiv {
    int lit[2];
    int kind;      // ORI_LAYERS_TACO_TORTILLA or ORI_LAYERS_TORTILLA_TORTILLA
    int faces[4];  // the constraint's faces (taco a, b, tortilla c, c) or (a, b, c, d)
} ori__equiv;

// A taco-taco constraint: creases a|b and c|d overlap with all four faces on one side.
typedef struct ori__taco {
    int faces[4];
    int lit[6]; // above(a,b) above(a,c) above(a,d) above(b,c) above(b,d) above(c,d)
} ori__taco;

// A maximal stack: the faces over one cell of the overlap structure (no other stack holds all
// of them). Every three of its faces form a transitivity constraint. var[i·k + j] is the
// variable of faces i and j of the stack (faces sorted, so i < j ⇔ face i < face j).
typedef struct ori__stack {
    int k;
    int words;        // 64-bit words per bit row: ⌈k / 64⌉
    int64_t faces_at; // offset into ori_layers.stack_faces
    int64_t vars_at;  // offset into ori_layers.stack_vars (k·k ints, diagonal unused)
    int64_t bits_at;  // offset into a solver's bit rows: above[i] (the faces known above face
                      // i) at bits_at + i·words, below[i] at bits_at + (k + i)·words
} ori__stack;

// Every stack holding a variable, with the positions of its faces (for the bit rows).
typedef struct ori__fslot {
    int stack;
    uint16_t ia, ib;
} ori__fslot;

// Where a variable sits in a stack: the stack and the positions of its two faces.
typedef struct ori__slot {
    int stack;
    int ia, ib;
} ori__slot;

struct ori_layers {
    // Pattern data (copied) and folded geometry.
    int nv, ne, nf;
    int (*ev)[2];
    int (*ef)[2];              // left / right face of v0→v1 in the crease pattern, -1 if none
    ori_assignment *asg;
    ori__csr face_edges;       // edges of each face, in its cycle order
    ori_v2 *vf;                // folded vertex positions
    double (*xf)[6];           // face transforms: x' = a x + b y + c, y' = d x + e y + f
    uint8_t *flip;             // face lies face-down (front side towards −z) when folded

    // Overlap structure (points, segments, cells of the arrangement of the folded edges).
    int np, ns, nc;
    ori_v2 *pts;
    int (*seg_pts)[2];
    int (*seg_cells)[2];       // cell left / right of seg_pts[0]→[1]; -1 outside
    ori__csr seg_edges;        // edges lying along each segment
    ori__csr edge_segs;        // segments of each edge, from v0 to v1
    ori__csr cell_segs;        // half-edges (2·seg + dir) around each cell, counter-clockwise
    ori__csr cell_faces;       // faces over each cell (ascending)
    ori__csr face_cells;       // cells under each face

    // Variables.
    int nvar;
    int (*var_faces)[2];
    ori__csr face_nbrs;        // per face: overlapping faces (ascending) …
    int *face_nbr_var;         // … and the variable of each (parallel to face_nbrs.items)

    // Constraints.
    int n_equiv, n_taco;
    ori__equiv *equiv;
    ori__taco *taco;
    int64_t count_kind[4];     // taco-taco, taco-tortilla, tortilla-tortilla, transitivity
    ori__csr var_tacos;        // taco-taco constraints of each variable
    int n_stack;
    ori__stack *stacks;
    int *stack_faces;
    int *stack_vars;
    ori__slot *slots;          // per variable (var_slot_off), stacks covering its triples
    int64_t *var_slot_off;
    ori__fslot *fslots;        // per variable (var_fslot_off), every stack holding it
    int64_t *var_fslot_off;
    int64_t n_bitwords;        // size of a solver's bit rows

    // Equivalence classes (union-find with parity) and the fixed part.
    int n_class;
    int *var_class;            // class of each variable
    int8_t *var_par;           // x[var] = var_par · x[class]
    int64_t *class_weight;     // constraints each class takes part in (branching heuristic)
    uint8_t *class_tied;       // a member variable sits in a stack holding two variables of one
                               // class (triples there may be implied by the equivalences)
    ori__csr class_vars;
    int *cc_node;              // Flat-Folder's taco-tortilla graphs: node (t, x) is 2·var(t, x) + (t is
                               // the pair's larger face); cc_node[node] is its component
    int8_t *class_val;         // after setup propagation: ±1 fixed, 0 free
    int8_t *var_val;           // same per variable

    // Components (Flat-Folder's convention: component 0 is the fixed part).
    int n_comp;
    ori__csr comp_classes;     // components 1 … n_comp − 1: their classes
    int *comp_vars;            // number of variables per component
    ori__nat *comp_count;      // per component once counted
    ori__nat total;
    bool counted, limited;
    bool stopped;              // the progress callback cancelled: every count is a lower bound
    uint64_t limit;

    // Verdict.
    bool unsat;
    ori_layers_conflict conflict;
    int *conflict_faces;
    int n_conflict_faces;

    // The selected state (±1 per variable) once ori_layers_select_state ran.
    int8_t *state;
    bool has_state;
    char *state_k;             // the selected state's number (decimal)
    bool transforms_known;     // xf holds real face transforms (not for a folded-form input)

    // Tables: for a partial assignment of a constraint's literals (base-3 code: 0 free,
    // 1 true, 2 false), the literals it forces (bit i: literal i true, bit 8 + i: false),
    // 0xFFFF for a conflict, and bit 15 when every completion is valid (the constraint is dead).
    uint16_t table3[27];
    uint16_t table6[729];

    ori_progress_fn *progress;
    void *progress_user;
    int threads;
    double snap_rel;
    bool snap_auto;            // snap_rel was chosen from the drawing (ORI_LAYERS_SNAP_AUTO); with it
                               // the local check is loosened even at ORI_TOL_LAYERS_SNAP_REL
    // The drawing's precision as the set-up saw it: the largest distance it took for "the same"
    // (relative to the diagonal: folded vertices one face puts apart from another's, points
    // snapped together, a point taken to lie on an edge) and the largest angle (radians) it took
    // for zero or equal (a vertex's Kawasaki sum, the gap between sectors snapped equal).
    double noise_len, noise_ang;
    double noise_ang_len;      // each vertex's Kawasaki sum × its shortest crease / the diagonal
    double noise_gap;          // the largest gap between sectors snapped equal (radians)
    // Why a set-up failed at its snapping length, for the search of a length from the drawing:
    // a distance (relative) that lay in the ambiguous band (only a length below a tenth of it
    // decides it), and one that the length must reach (a vertex folded apart, a Kawasaki sum
    // as a move); 0 when not that.
    double fail_amb, fail_need;
};

#define ORI__TABLE_CONFLICT 0xFFFFu
#define ORI__TABLE_DEAD 0x8000u

// Stages of ori_layers_create (one file each).
ori_status ori__layers_fold(ori_layers *L, const ori_pattern *p, const ori_layers_def *def, ori_error *error);
ori_status ori__layers_overlap(ori_layers *L, ori_error *error);
ori_status ori__layers_constraints(ori_layers *L, ori_error *error);
void ori__layers_tables(ori_layers *L);
ori_status ori__layers_presolve(ori_layers *L, ori_error *error);
ori_status ori__layers_solve(ori_layers *L, ori_error *error);
ori_status ori__layers_unrank(ori_layers *L, int comp, const ori__nat *k, int8_t *val, ori_error *error);
// Count component j (≥ 1) alone with a fresh solver, up to L->limit (layers_parts.c); *exact is
// false when the limit stopped it. Reads L only: calls on different components may run at once.
void ori__layers_count_one(const ori_layers *L, int j, ori__nat *res, bool *exact);

// The variable of faces f and g (any order), or -1 when they do not overlap.
int ori__layers_var(const ori_layers *L, int f, int g);
// The literal "f lies above g" (f ≠ g overlapping).
static inline int ori__layers_above(const ori_layers *L, int f, int g)
{
    int v = ori__layers_var(L, f, g);
    return v < 0 ? -1 : ORI__LIT(v, f > g);
}

// Component j has no state although propagation found no conflict: the verdict (EXHAUSTED) and
// its faces recorded in L (layers_parts.c; the solver and ori_layers_set_counts use it).
void ori__layers_set_exhausted(ori_layers *L, int j);

#endif
