// Collision along a motion: every step from a clean state A to the next state B is checked —
// B itself (collider.c), and the layer order of every pair of faces whose boxes swept from A to
// B meet: the side of one face relative to the other's front, over the part of it that lies
// over the other (narrow.c, col_face_side). A pair above at A and below at B (or the reverse)
// passed through each other in between even when neither state shows a crossing; stacked
// layers (coplanar, no side) keep the order they had when they came together. The boxes are
// swept with each face's bulge (its path modelled as the screw motion between its poses), and
// a pair whose sides do not decide it and that is nearer at both ends than the two faces can
// travel is checked again in half steps. The first colliding step is then bisected on the
// drive: trial states are solved through the public API (ori_motion_solve from the last clean
// state, or ori_trajectory_at), clean midpoints advance A and its remembered orders, colliding ones
// become B, until B − A is below the drive tolerance.
#include "../core/hash.h"
#include "collision_internal.h"

ori_collision_motion_def ori_default_collision_motion_def(void)
{
    ori_collision_motion_def d;
    memset(&d, 0, sizeof d);
    d.drive_tol_rad = ORI_TOL_CONTACT_DRIVE_RAD;
    d.progress = NULL;
    d.progress_user = NULL;
    d.internal_value = ORI__DEF_COOKIE;
    return d;
}

// --- remembered orders of stacked pairs: pair key → COL_SIDE_ABOVE / BELOW ------------------

#define MEMO_EMPTY UINT64_MAX

typedef struct memo {
    uint64_t *key;
    unsigned char *val;
    int cap, n;
} memo;

static void memo_free(memo *m)
{
    ori__free(m->key);
    ori__free(m->val);
    memset(m, 0, sizeof *m);
}

static void memo_clear(memo *m)
{
    for (int i = 0; i < m->cap; ++i) m->key[i] = MEMO_EMPTY;
    m->n = 0;
}

static void memo_insert(memo *m, uint64_t k, unsigned char v)
{
    int mask = m->cap - 1, i = (int)(ori__mix64(k) & (uint64_t)mask);
    while (m->key[i] != MEMO_EMPTY && m->key[i] != k) i = (i + 1) & mask;
    if (m->key[i] == MEMO_EMPTY) m->n++;
    m->key[i] = k;
    m->val[i] = v;
}

static void memo_put(memo *m, uint64_t k, unsigned char v)
{
    if (2 * (m->n + 1) > m->cap) {
        memo old = *m;
        m->cap = ori__hash_capacity(m->n + 1);
        m->key = ori__alloc(sizeof(uint64_t) * (size_t)m->cap);
        m->val = ori__alloc((size_t)m->cap);
        memo_clear(m);
        for (int i = 0; i < old.cap; ++i)
            if (old.key[i] != MEMO_EMPTY) memo_insert(m, old.key[i], old.val[i]);
        memo_free(&old);
    }
    memo_insert(m, k, v);
}

static col_side memo_get(const memo *m, uint64_t k)
{
    if (m->cap == 0) return COL_SIDE_NONE;
    int mask = m->cap - 1, i = (int)(ori__mix64(k) & (uint64_t)mask);
    while (m->key[i] != MEMO_EMPTY) {
        if (m->key[i] == k) return (col_side)m->val[i];
        i = (i + 1) & mask;
    }
    return COL_SIDE_NONE;
}

// --- one step --------------------------------------------------------------------------------

// The geometry of a prepared state, kept for the clean state A of a step.
typedef struct col_geomset {
    col_geom *geom;
    col_box *boxes;
    const ori_v3 *pos;
    double tol_pen, tol_touch;
    bool valid;
} col_geomset;

// A frame fixed on face f, the same material frame in every state (the checker's in-plane frame
// may pick another vertex when two are equally far): origin at the face's first vertex, e1
// towards the first vertex not at the same place (chosen in state A, kept in B), n its normal.
typedef struct body_frame {
    ori_v3 o, e1, e2, n;
} body_frame;

// The pairs of the incremental checker's last step, sorted by (face, fb), each with its layer
// sides as last found and the state they were found in: the next step's state A is that state
// B, and most of its pairs are the same.
typedef struct col_pair_list {
    int n, cap;
    int *off;                  // face f's pairs are off[f] … off[f + 1] (faces + 2 ints)
    int *fb;                   // their second faces, in order
    unsigned char *kind;       // col_adjacency of each pair
    unsigned char *q, *side;   // col_face_side_quick and col_face_side of f relative to fb …
    unsigned char *q_at, *side_at; // … at these states (their ids; 0: not known)
} col_pair_list;

typedef struct col_pairs {
    col_pair_list cur, old;    // this step's, and the last step's (its storage reused)
    int *by_second;            // scratch: where each face's pairs as the second face start (faces + 2 ints)
} col_pairs;

static void pair_list_free(col_pair_list *l)
{
    ori__free(l->off);
    ori__free(l->fb);
    ori__free(l->kind);
    ori__free(l->q);
    ori__free(l->side);
    ori__free(l->q_at);
    ori__free(l->side_at);
    memset(l, 0, sizeof *l);
}

static void pair_list_reserve(col_pair_list *l, int n)
{
    if (n <= l->cap) return;
    int cap = l->cap;
    ORI__RESERVE(l->fb, cap, n);
    size_t m = (size_t)cap;
    l->kind = ori__realloc(l->kind, m);
    l->q = ori__realloc(l->q, m);
    l->side = ori__realloc(l->side, m);
    l->q_at = ori__realloc(l->q_at, m);
    l->side_at = ori__realloc(l->side_at, m);
    l->cap = cap;
}

typedef struct col_step {
    ori_collider *c;
    col_bvh bvh;     // over the swept boxes
    col_geomset a;   // state A (valid after the first clean state)
    col_geomset tmp; // scratch for swapping
    col_box *swept;
    struct tracked {
        int a, b;
        bool crease;  // convex faces joined by a crease: they turn about its line, never through each other
        unsigned char sa; // col_side of a relative to b's front at the clean state (NONE when not needed)
        unsigned char qb; // col_side at B from a's vertices alone (col_face_side_quick)
        bool adjacent; // the faces share a vertex
        signed char open; // not decided by the layer sides (1; -1: and touching at B): the sweep decides
        unsigned char kind; // col_adjacency
    } *pairs;            // the incremental checker's: in the order of s->w.cur
    double *reach, *bulge; // per face over the step: path-length bound and bulge off the chords
    struct open_pair {
        int i;             // a tracked pair left open at B
        double reach;      // how far its face a can travel relative to its face b
    } *opens;
    int open_cap;
    int npairs, pair_cap;
    memo mem, next;  // orders at the clean state A, and at B when B is clean
    // the incremental checker (not the reference one)
    body_frame *fra, *frb;     // per face over the step: its body frame at A and at B (sweep_bounds)
    int state_seq;             // the last state id given (new_state_id)
    unsigned char state_a, state_b; // ids of the state A (0: none) and of the last step's B
    col_pairs w;
    int refits;                // steps since the hierarchy of the swept boxes was built
} col_step;

static void step_init(col_step *s, ori_collider *c)
{
    memset(s, 0, sizeof *s);
    s->c = c;
    s->a.geom = ori__alloc(sizeof(col_geom) * (size_t)c->face_count);
    s->a.boxes = ori__alloc(sizeof(col_box) * (size_t)c->face_count);
    s->tmp.geom = ori__alloc(sizeof(col_geom) * (size_t)c->face_count);
    s->tmp.boxes = ori__alloc(sizeof(col_box) * (size_t)c->face_count);
    s->swept = ori__alloc(sizeof(col_box) * (size_t)c->face_count);
    s->reach = ori__alloc(sizeof(double) * (size_t)c->face_count);
    s->bulge = ori__alloc(sizeof(double) * (size_t)c->face_count);
    s->fra = ori__alloc(sizeof(body_frame) * (size_t)c->face_count);
    s->frb = ori__alloc(sizeof(body_frame) * (size_t)c->face_count);
}

static void step_free(col_step *s)
{
    col_bvh_free(&s->bvh);
    ori__free(s->a.geom);
    ori__free(s->a.boxes);
    ori__free(s->tmp.geom);
    ori__free(s->tmp.boxes);
    ori__free(s->swept);
    ori__free(s->reach);
    ori__free(s->bulge);
    ori__free(s->fra);
    ori__free(s->frb);
    pair_list_free(&s->w.cur);
    pair_list_free(&s->w.old);
    ori__free(s->w.by_second);
    ori__free(s->opens);
    ori__free(s->pairs);
    memo_free(&s->mem);
    memo_free(&s->next);
}

static bool collect_pair(void *user, int a, int b)
{
    col_step *s = user;
    ORI__RESERVE(s->pairs, s->pair_cap, s->npairs + 1);
    s->pairs[s->npairs].a = a;
    s->pairs[s->npairs].b = b;
    col_adjacency adj = col_adjacency_of(s->c, a, b);
    s->pairs[s->npairs].crease = adj == COL_ADJ_CREASE;
    s->pairs[s->npairs].adjacent = adj != COL_ADJ_NONE;
    s->pairs[s->npairs].kind = (unsigned char)adj;
    s->pairs[s->npairs].open = 0;
    s->pairs[s->npairs].sa = COL_SIDE_NONE;
    s->npairs++;
    return true;
}

// Copy the checker's prepared geometry into g.
static void geom_save(const ori_collider *c, col_geomset *g)
{
    memcpy(g->geom, c->geom, sizeof(col_geom) * (size_t)c->face_count);
    memcpy(g->boxes, c->boxes, sizeof(col_box) * (size_t)c->face_count);
    g->pos = c->pos;
    g->tol_pen = c->tol_pen;
    g->tol_touch = c->tol_touch;
    g->valid = true;
}

// Exchange the checker's prepared geometry with g's (pointers only).
static void geom_swap(ori_collider *c, col_geomset *g)
{
    col_geom *gm = c->geom;
    col_box *bx = c->boxes;
    const ori_v3 *p = c->pos;
    double tp = c->tol_pen, tt = c->tol_touch;
    c->geom = g->geom;
    c->boxes = g->boxes;
    c->pos = g->pos;
    c->tol_pen = g->tol_pen;
    c->tol_touch = g->tol_touch;
    g->geom = gm;
    g->boxes = bx;
    g->pos = p;
    g->tol_pen = tp;
    g->tol_touch = tt;
}

static ori_contact first_colliding(const ori_collider *c)
{
    int pick = -1;
    for (int i = 0; i < c->contact_count; ++i)
        if (c->contacts[i].kind == ORI_CONTACT_PENETRATING) {
            pick = i;
            break;
        }
    for (int i = 0; i < c->contact_count && pick < 0; ++i)
        if (c->contacts[i].collides) pick = i;
    ORI_ASSERT(pick >= 0);
    return c->contacts[pick];
}

static double turn_angle(ori_v3 u, ori_v3 v)
{
    return atan2(ori_v3_norm(ori_v3_cross(u, v)), ori_v3_dot(u, v));
}

static int frame_vertex(const ori_collider *c, int f, const ori_v3 *pos)
{
    int first = c->face_off[f];
    ori_v3 p0 = pos[c->face_verts[first]];
    int best = first + 1;
    double far = -1.0;
    for (int i = first + 1; i < c->face_off[f + 1]; ++i) {
        double d = ori_v3_norm(ori_v3_sub(pos[c->face_verts[i]], p0));
        if (d > 1e-3 * c->diagonal) return i;
        if (d > far) {
            far = d;
            best = i;
        }
    }
    return best;
}

static body_frame body_frame_of(const ori_collider *c, int f, int j, const ori_v3 *pos, ori_v3 n)
{
    body_frame b;
    b.o = pos[c->face_verts[c->face_off[f]]];
    ori_v3 s = ori_v3_sub(pos[c->face_verts[j]], b.o);
    b.n = n;
    b.e1 = ori_v3_normalize(ori_v3_sub(s, ori_v3_scale(n, ori_v3_dot(s, n))));
    b.e2 = ori_v3_cross(n, b.e1);
    return b;
}

// A rotation by φ turns some vector of an orthonormal frame by at least θ with
// sin(θ/2) ≥ sin(φ/2)·√(2/3): the frames' largest turn bounds φ. Returns the arc factor
// k = (φ/2)/sin(φ/2) (a path's length over its chord).
static double arc_factor(const body_frame *fa, const body_frame *fb)
{
    double th = turn_angle(fa->n, fb->n), t1 = turn_angle(fa->e1, fb->e1), t2 = turn_angle(fa->e2, fb->e2);
    if (t1 > th) th = t1;
    if (t2 > th) th = t2;
    double sphi = sin(0.5 * th) / sqrt(2.0 / 3.0);
    double half = sphi >= 1.0 ? 0.5 * ORI_PI : asin(sphi);
    return half > 1e-9 ? half / sin(half) : 1.0;
}

// How far each face can travel over the step A → B (the checker prepared at B, s->a at A). The
// face's path is modelled as the screw motion between its two poses: a point whose chord is c
// travels at most c·k along an arc that bulges at most c·√(k² − 1)/2 off its chord, k from the
// face's rotation (arc_factor). The chord of any point of a face is at most its vertices'
// largest (the displacement is affine in the point).
static void sweep_bounds(col_step *s, const ori_v3 *b)
{
    const ori_collider *c = s->c;
    for (int f = 0; f < c->face_count; ++f) {
        int j = frame_vertex(c, f, s->a.pos);
        body_frame fa = body_frame_of(c, f, j, s->a.pos, s->a.geom[f].n), fb = body_frame_of(c, f, j, b, c->geom[f].n);
        s->fra[f] = fa;
        s->frb[f] = fb;
        double k = arc_factor(&fa, &fb);
        double chord = 0.0;
        for (int i = c->face_off[f]; i < c->face_off[f + 1]; ++i) {
            int v = c->face_verts[i];
            double d = ori_v3_norm(ori_v3_sub(b[v], s->a.pos[v]));
            if (d > chord) chord = d;
        }
        s->reach[f] = chord * k;
        s->bulge[f] = 0.5 * chord * sqrt(k * k - 1.0);
    }
}

// x at B back to A by the body's motion: oA + Σ ((x − oB)·eB_i) eA_i.
static ori_v3 body_back(const body_frame *fa, const body_frame *fb, ori_v3 x)
{
    ori_v3 y = ori_v3_sub(x, fb->o);
    double u = ori_v3_dot(y, fb->e1), v = ori_v3_dot(y, fb->e2), w = ori_v3_dot(y, fb->n);
    return ori_v3_add(fa->o, ori_v3_add(ori_v3_scale(fa->e1, u), ori_v3_add(ori_v3_scale(fa->e2, v), ori_v3_scale(fa->n, w))));
}

// How far face a can travel relative to face b over the step: a's motion seen from b (b's own
// motion undone), bounded as in sweep_bounds. Two neighbouring faces of a sheet that moves as a
// whole move little relative to each other even when both travel far.
static double relative_reach_of(const col_step *s, int a, const body_frame *a_at_a, const body_frame *a_at_b,
                                const body_frame *b_at_a, const body_frame *b_at_b, const ori_v3 *pos_b);

static double relative_reach(const col_step *s, int a, int b, const ori_v3 *pos_b)
{
    const ori_collider *c = s->c;
    int ja = frame_vertex(c, a, s->a.pos), jb = frame_vertex(c, b, s->a.pos);
    body_frame aA = body_frame_of(c, a, ja, s->a.pos, s->a.geom[a].n), aB = body_frame_of(c, a, ja, pos_b, c->geom[a].n);
    body_frame bA = body_frame_of(c, b, jb, s->a.pos, s->a.geom[b].n), bB = body_frame_of(c, b, jb, pos_b, c->geom[b].n);
    return relative_reach_of(s, a, &aA, &aB, &bA, &bB, pos_b);
}

// The same from the faces' body frames at A and B (those of sweep_bounds: the same values).
static double relative_reach_of(const col_step *s, int a, const body_frame *a_at_a, const body_frame *a_at_b,
                                const body_frame *b_at_a, const body_frame *b_at_b, const ori_v3 *pos_b)
{
    const ori_collider *c = s->c;
    body_frame aA = *a_at_a, aB = *a_at_b, bA = *b_at_a, bB = *b_at_b;
    // a's frame at B seen from b, against a's frame at A
    body_frame rel;
    rel.o = body_back(&bA, &bB, aB.o);
    rel.n = ori_v3_sub(body_back(&bA, &bB, ori_v3_add(aB.o, aB.n)), rel.o);
    rel.e1 = ori_v3_sub(body_back(&bA, &bB, ori_v3_add(aB.o, aB.e1)), rel.o);
    rel.e2 = ori_v3_sub(body_back(&bA, &bB, ori_v3_add(aB.o, aB.e2)), rel.o);
    double k = arc_factor(&aA, &rel);
    double chord = 0.0;
    for (int i = c->face_off[a]; i < c->face_off[a + 1]; ++i) {
        int v = c->face_verts[i];
        double d = ori_v3_norm(ori_v3_sub(body_back(&bA, &bB, pos_b[v]), s->a.pos[v]));
        if (d > chord) chord = d;
    }
    return chord * k;
}

// A new state's id, 1 … 255 (0 names none): when they run out, every kept side is forgotten, A's
// too, and the ids start again, so that an id kept with a side names one state.
static unsigned char new_state_id(col_step *s)
{
    if (s->state_seq >= 255) {
        col_pair_list *lists[2] = {&s->w.cur, &s->w.old};
        for (int k = 0; k < 2; ++k)
            if (lists[k]->n > 0) {
                memset(lists[k]->q_at, 0, (size_t)lists[k]->n);
                memset(lists[k]->side_at, 0, (size_t)lists[k]->n);
            }
        s->state_seq = 0;
        s->state_a = s->state_b = 0;
    }
    return (unsigned char)++s->state_seq;
}

static bool pair_collect(void *user, int a, int b)
{
    col_step *s = user;
    ORI__RESERVE(s->pairs, s->pair_cap, s->npairs + 1);
    s->pairs[s->npairs].a = a;
    s->pairs[s->npairs].b = b;
    s->npairs++;
    return true;
}

// After this many steps on a refitted hierarchy, it is built again.
#define REFIT_STEPS 8

// The incremental checker's pairs of the step: those of the swept boxes within margin (the same
// as the reference checker's), from the hierarchy of the step before refitted to the new boxes
// (built again every REFIT_STEPS steps), sorted, each with its adjacency (from the sorted
// adjacency lists) and with the sides the last step's list had for it; into s->pairs.
static void incremental_pairs(col_step *s, double margin)
{
    ori_collider *c = s->c;
    col_pairs *w = &s->w;
    int F = c->face_count;
    if (s->bvh.node_count == 0 || s->refits >= REFIT_STEPS || s->bvh.boxes != s->swept) {
        col_bvh_build(&s->bvh, s->swept, F);
        s->refits = 0;
    } else {
        col_bvh_refit(&s->bvh, s->swept);
        s->refits++;
    }
    s->npairs = 0;
    col_bvh_self_pairs(&s->bvh, margin, pair_collect, s);
    int n = s->npairs;
    struct tracked *tp = s->pairs;
    col_pair_list spare = w->old; // the list before last, whose storage this step's takes
    w->old = w->cur;
    w->cur = spare;
    col_pair_list *l = &w->cur, *o = &w->old;
    pair_list_reserve(l, n + 1);
    int *fb = l->fb;
    unsigned char *kind = l->kind;
    // sorted by (a, b) in place of the hierarchy's order: the first faces counted out by second
    // face into the list (scratch), then placed by first face, second faces in order
    if (!l->off) l->off = ori__alloc(sizeof(int) * (size_t)(F + 2));
    if (!w->by_second) w->by_second = ori__alloc(sizeof(int) * (size_t)(F + 2));
    int *off = l->off, *offb = w->by_second;
    memset(off, 0, sizeof(int) * (size_t)(F + 2));
    memset(offb, 0, sizeof(int) * (size_t)(F + 2));
    for (int i = 0; i < n; ++i) {
        off[tp[i].a + 2]++;
        offb[tp[i].b + 2]++;
    }
    for (int f = 0; f < F; ++f) {
        off[f + 2] += off[f + 1];
        offb[f + 2] += offb[f + 1];
    }
    for (int i = 0; i < n; ++i) fb[offb[tp[i].b + 1]++] = tp[i].a;
    for (int g = 0; g < F; ++g)
        for (int j = offb[g]; j < offb[g + 1]; ++j) {
            int fa = fb[j], at = off[fa + 1]++;
            tp[at].a = fa;
            tp[at].b = g;
        }
    for (int i = 0; i < n; ++i) fb[i] = tp[i].b;
    // now off[f] … off[f + 1] is face f's run, in order
    for (int f = 0; f < F; ++f) {
        int lo = off[f], hi = off[f + 1];
        int k = c->adj_off[f], kend = c->adj_off[f + 1];
        int j0 = o->n > 0 ? o->off[f] : 0, jend = o->n > 0 ? o->off[f + 1] : 0;
        for (int i = lo; i < hi; ++i) {
            int g = fb[i];
            while (k < kend && c->adj[k] < g) k++;
            kind[i] = k < kend && c->adj[k] == g ? c->adj_kind[k] : (unsigned char)COL_ADJ_NONE;
            // the sides the last step's list had for the pair (both runs sorted)
            while (j0 < jend && o->fb[j0] < g) j0++;
            if (j0 < jend && o->fb[j0] == g) {
                l->q[i] = o->q[j0];
                l->q_at[i] = o->q_at[j0];
                l->side[i] = o->side[j0];
                l->side_at[i] = o->side_at[j0];
            } else {
                l->q_at[i] = l->side_at[i] = 0;
            }
        }
    }
    l->n = n;
    for (int f = 0; f < F; ++f)
        for (int i = off[f]; i < off[f + 1]; ++i) {
            struct tracked *t = &s->pairs[i];
            t->a = f;
            t->b = fb[i];
            t->kind = kind[i];
            t->crease = t->kind == COL_ADJ_CREASE;
            t->adjacent = t->kind != COL_ADJ_NONE;
            t->open = 0;
            t->sa = COL_SIDE_NONE;
        }
    s->npairs = n;
}

// Check the step from the clean state a (orders s->mem) to b. On a collision *hit is set and
// *contact tells where; the checker is left prepared at b in every case, and when b is clean,
// s->next holds the orders at b. *split is set when b is clean but some pair of faces sharing
// no vertex could have met between a and b: the layer sides do not decide it (the faces do not
// lie over each other at both ends on one side) and they are nearer at both ends than their
// sweeps' reach. The caller then checks the step in halves.
static ori_status step_check(col_step *s, const ori_v3 *a, const ori_v3 *b, bool *hit, bool *split, ori_contact *contact,
                             ori_error *error)
{
    ori_collider *c = s->c;
    *hit = false;
    *split = false;
    ori_status st;
    // A's geometry is kept from the previous step (computed here only for the first one).
    if (!s->a.valid) {
        if ((st = col_state_prepare(c, a, error)) != ORI_OK) return st;
        geom_save(c, &s->a);
        s->state_a = new_state_id(s);
    }
    if ((st = col_state_prepare(c, b, error)) != ORI_OK) return st;
    unsigned char bid = new_state_id(s);
    s->state_b = bid;
    col_pair_list *w = &s->w.cur;
    // One traversal of the boxes swept from A to B gives both the candidates of B's check (the
    // pairs whose boxes at B are near) and the pairs whose layer order is compared.
    int F = c->face_count;
    double near = c->tol_touch > c->clearance ? c->tol_touch : c->clearance;
    double margin = near > s->a.tol_touch ? near : s->a.tol_touch;
    sweep_bounds(s, b);
    for (int f = 0; f < F; ++f) {
        const col_box *x = &s->a.boxes[f], *y = &c->boxes[f];
        col_box *sw = &s->swept[f];
        double h = s->bulge[f];
        sw->lo.x = (x->lo.x < y->lo.x ? x->lo.x : y->lo.x) - h;
        sw->lo.y = (x->lo.y < y->lo.y ? x->lo.y : y->lo.y) - h;
        sw->lo.z = (x->lo.z < y->lo.z ? x->lo.z : y->lo.z) - h;
        sw->hi.x = (x->hi.x > y->hi.x ? x->hi.x : y->hi.x) + h;
        sw->hi.y = (x->hi.y > y->hi.y ? x->hi.y : y->hi.y) + h;
        sw->hi.z = (x->hi.z > y->hi.z ? x->hi.z : y->hi.z) + h;
    }
    s->npairs = 0;
    if (!c->reference) {
        incremental_pairs(s, margin);
    } else {
        col_bvh_build(&s->bvh, s->swept, F);
        col_bvh_self_pairs(&s->bvh, margin, collect_pair, s);
    }
    ori_collision_result r;
    col_check_begin(c, &r);
    for (int i = 0; i < s->npairs; ++i)
        if (col_box_near(&c->boxes[s->pairs[i].a], &c->boxes[s->pairs[i].b], near)) {
            if (c->reference) col_check_pair(c, &r, false, s->pairs[i].a, s->pairs[i].b);
            else col_check_pair_kind(c, &r, false, s->pairs[i].a, s->pairs[i].b, (col_adjacency)s->pairs[i].kind);
        }
    col_check_end(c, false, &r);
    if (r.collides) {
        *hit = true;
        *contact = first_colliding(c);
        return ORI_OK;
    }
    // Sides from the vertices alone first: a face whose vertices all lie strictly on the same
    // side of the other's plane at both ends of the step cannot have changed sides, nor be
    // stacked; only the other pairs need the overlap.
    for (int i = 0; i < s->npairs; ++i)
        s->pairs[i].qb = s->pairs[i].crease ? COL_SIDE_NONE : col_face_side_quick(c, s->pairs[i].a, s->pairs[i].b);
    geom_swap(c, &s->a); // the checker at A
    for (int i = 0; i < s->npairs; ++i) {
        struct tracked *t = &s->pairs[i];
        t->sa = COL_SIDE_NONE;
        t->open = 0;
        if (t->crease) continue;
        // A was the B of the step before: its sides found then are A's
        int k = c->reference ? -1 : i;
        bool kept = k >= 0 && s->state_a != 0;
        col_side qa = kept && w->q_at[k] == s->state_a ? (col_side)w->q[k] : col_face_side_quick(c, t->a, t->b);
        if ((qa == COL_SIDE_ABOVE || qa == COL_SIDE_BELOW) && qa == t->qb) continue;
        t->sa = kept && w->side_at[k] == s->state_a ? (col_side)w->side[k]
                : c->reference                         ? col_face_side(c, t->a, t->b, NULL)
                                                       : col_face_side_parted(c, t->a, t->b, NULL);
        t->open = t->adjacent ? 0 : 1; // until the sides at both ends agree
    }
    geom_swap(c, &s->a); // back to B
    for (int i = 0; i < s->npairs; ++i)
        if (!c->reference && !s->pairs[i].crease) {
            w->q[i] = s->pairs[i].qb;
            w->q_at[i] = bid;
        }
    memo_clear(&s->next);
    int flip = -1;
    ori_v3 flip_point = ori_v3_make(0.0, 0.0, 0.0);
    for (int i = 0; i < s->npairs; ++i) {
        uint64_t key = ori__pair_key(s->pairs[i].a, s->pairs[i].b);
        col_side was = s->pairs[i].sa == COL_SIDE_FLAT ? memo_get(&s->mem, key) : s->pairs[i].sa;
        if (was != COL_SIDE_ABOVE && was != COL_SIDE_BELOW) continue;
        if (s->pairs[i].qb == was) { // still strictly on that side: no flip, not stacked
            s->pairs[i].open = 0;
            continue;
        }
        ori_v3 p;
        col_side now = col_face_side(c, s->pairs[i].a, s->pairs[i].b, &p);
        if (!c->reference) {
            w->side[i] = (unsigned char)now;
            w->side_at[i] = bid;
        }
        if (now == was || now == COL_SIDE_FLAT) s->pairs[i].open = 0;
        if (now == COL_SIDE_FLAT) memo_put(&s->next, key, (unsigned char)was);
        bool flipped = (was == COL_SIDE_ABOVE && now == COL_SIDE_BELOW) || (was == COL_SIDE_BELOW && now == COL_SIDE_ABOVE);
        // report the first flipped pair in (face_a, face_b) order
        bool first = flip < 0 || s->pairs[i].a < s->pairs[flip].a ||
                     (s->pairs[i].a == s->pairs[flip].a && s->pairs[i].b < s->pairs[flip].b);
        if (flipped && first) {
            flip = i;
            flip_point = p;
        }
    }
    if (flip >= 0) {
        *hit = true;
        memset(contact, 0, sizeof *contact);
        contact->face_a = s->pairs[flip].a;
        contact->face_b = s->pairs[flip].b;
        contact->kind = ORI_CONTACT_PENETRATING;
        contact->adjacent = col_adjacency_of(c, s->pairs[flip].a, s->pairs[flip].b) != COL_ADJ_NONE;
        contact->stacked = s->pairs[flip].sa == COL_SIDE_FLAT;
        contact->collides = true;
        contact->point = flip_point;
        return ORI_OK;
    }
    // The pairs left open: could they have met within the step? Not when they are farther apart
    // than a's reach relative to b at either end, nor when they touch at both ends (a contact
    // the states classify).
    int open = 0;
    for (int i = 0; i < s->npairs; ++i) {
        struct tracked *t = &s->pairs[i];
        if (!t->open) continue;
        double reach = c->reference ? relative_reach(s, t->a, t->b, b)
                                    : relative_reach_of(s, t->a, &s->fra[t->a], &s->frb[t->a], &s->fra[t->b], &s->frb[t->b], b);
        ori_v3 pa, pb;
        double d = col_face_distance(c, t->a, t->b, reach, &pa, &pb);
        t->open = d >= reach ? 0 : d <= c->tol_touch ? -1 : 1; // -1: touching at B, decided below with A
        if (t->open != 0) {
            ORI__RESERVE(s->opens, s->open_cap, open + 1);
            s->opens[open].i = i;
            s->opens[open].reach = reach;
            open++;
        }
    }
    if (open == 0) return ORI_OK;
    geom_swap(c, &s->a);
    for (int o = 0; o < open && !*split; ++o) {
        struct tracked *t = &s->pairs[s->opens[o].i];
        double reach = s->opens[o].reach;
        ori_v3 pa, pb;
        double d = col_face_distance(c, t->a, t->b, reach, &pa, &pb);
        bool touching_b = t->open < 0;
        if (d < reach && !(touching_b && d <= c->tol_touch)) *split = true;
    }
    geom_swap(c, &s->a);
    return ORI_OK;
}

// The clean state b (the checker is prepared at it, its positions at pos) becomes A.
static void step_advance(col_step *s, const ori_v3 *pos)
{
    memo t = s->mem;
    s->mem = s->next;
    s->next = t;
    geom_save(s->c, &s->a);
    s->a.pos = pos;
    s->state_a = s->state_b;
}

// --- bisection -------------------------------------------------------------------------------

// Where trial states come from: solve(x) fills pos (and *drive) with the state at parameter x,
// reached from the current clean state; commit() makes the last solved state the clean one.
typedef struct col_source {
    ori_status (*solve)(void *user, double x, ori_v3 *pos, double *drive, ori_error *error);
    void (*commit)(void *user);
    void *user;
} col_source;

// The walk over one step, from the clean state A (parameter lo, positions *pa) to the frame at
// x1 (positions pk, drive d1): targets are checked from A; a clean target whose sweep leaves a
// pair undecided is halved first (down to a bracket of split_tol in the drive); a clean,
// decided one becomes A; a colliding one becomes the bracket's end hi, and the bracket is
// bisected until the drive bracket is at most tol. So the contact found is the first one along
// the motion, not merely one within the step.
typedef struct walk_out {
    bool collides;
    double x, drive;
    ori_contact contact;
    int solved;
} walk_out;

#define WALK_STACK 64

typedef ori_status col_prepare_fn(void *user, int k, double *per, ori_error *error);

static ori_status walk_step(col_step *s, const col_source *src, col_prepare_fn *prepare, int k_frame, ori_v3 **pa,
                            ori_v3 **pt, ori_v3 **ph, const ori_v3 *pk, double lo, double x1, double d1, double tol,
                            double split_tol, walk_out *out, ori_error *error)
{
    // The drive's rate per unit of the parameter, and the source's start state, are prepared
    // only when the step needs a state between its frames.
    bool prepared = false;
    double drive_per_x = 0.0;
#define WALK_PREPARE()                                                                                                 \
    do {                                                                                                               \
        if (!prepared) {                                                                                               \
            ori_status pst = prepare(src->user, k_frame, &drive_per_x, error);                                         \
            if (pst != ORI_OK) return pst;                                                                             \
            prepared = true;                                                                                           \
        }                                                                                                              \
    } while (0)
    size_t bytes = sizeof(ori_v3) * (size_t)s->c->vertex_count;
    double stack[WALK_STACK];
    int top = 0;
    stack[top++] = x1;
    bool have_hit = false;
    double hi = x1, drive_hi = d1;
    ori_contact hit_contact;
    memset(&hit_contact, 0, sizeof hit_contact);
    memset(out, 0, sizeof *out);
    for (;;) {
        if (top == 0) {
            if (!have_hit) return ORI_OK; // clean up to x1
            WALK_PREPARE();
            double mid = 0.5 * (lo + hi);
            if (fabs(hi - lo) * drive_per_x <= tol || mid == lo || mid == hi) break;
            stack[top++] = mid;
        }
        double x = stack[top - 1], drive = d1;
        bool solved = false;
        if (x == x1 && !have_hit) {
            memcpy(*pt, pk, bytes);
        } else {
            WALK_PREPARE();
            ori_status st = src->solve(src->user, x, *pt, &drive, error);
            if (st != ORI_OK) return st;
            out->solved++;
            solved = true;
        }
        bool h, split;
        ori_contact k;
        ori_status st = step_check(s, *pa, *pt, &h, &split, &k, error);
        if (st != ORI_OK) return st;
        if (h) {
            have_hit = true;
            hi = x;
            drive_hi = drive;
            hit_contact = k;
            ori_v3 *t = *ph;
            *ph = *pt;
            *pt = t;
            top = 0; // the targets beyond x no longer matter
            continue;
        }
        if (split) WALK_PREPARE();
        double mid = 0.5 * (lo + x);
        if (split && fabs(x - lo) * drive_per_x > split_tol && mid != lo && mid != x && top < WALK_STACK) {
            stack[top++] = mid;
            continue;
        }
        ori_v3 *t = *pa;
        *pa = *pt;
        *pt = t;
        step_advance(s, *pa);
        if (solved) src->commit(src->user);
        lo = x;
        top--;
    }
#undef WALK_PREPARE
    // Leave the checker with the contacts of the colliding state.
    ori_status st = col_state_prepare(s->c, *ph, error);
    if (st != ORI_OK) return st;
    ori_collision_result r;
    col_check_prepared(s->c, false, &r);
    out->collides = true;
    out->x = hi;
    out->drive = drive_hi;
    out->contact = hit_contact;
    return ORI_OK;
}

// --- the frames of a trajectory ----------------------------------------------------------------

typedef struct run_out {
    bool collides;
    int frame;
    double x, drive;
    ori_contact contact;
    int solved;
} run_out;

// The source of the trial states between the frames of a trajectory. A fold's (ori_motion) are
// solved from the last clean state of the step (lo_angles, advanced by commit), one step of
// ori_motion_solve each; a multifold's and a sequence's come from ori_trajectory_at (interpolated
// and closed, or continued from the recorded state before them), which needs no clean state.
typedef struct traj_src {
    const ori_trajectory *t;
    int edges;
    double *lo_angles, *trial_angles; // a fold: the last clean state, and the last trial's angles
    double *angles;                   // scratch for the others
} traj_src;

// Ready the source for states between frames k − 1 and k, and give the drive's rate of change per
// unit of the parameter (a fold's parameter is its drive, a multifold's its progress, both 1).
static ori_status traj_prepare(void *user, int k, double *per, ori_error *error)
{
    traj_src *ts = user;
    const ori_trajectory *t = ts->t;
    switch (t->kind) {
    case ORI_TRAJECTORY_MOTION:
        *per = 1.0;
        memcpy(ts->lo_angles, ori_trajectory_frame_angles(t, k - 1), sizeof(double) * (size_t)ts->edges);
        return ORI_OK;
    case ORI_TRAJECTORY_MULTIFOLD:
        *per = 1.0;
        return ORI_OK;
    case ORI_TRAJECTORY_RECORD:
    default: {
        // Within a fold the drive is linear in the time; frame k − 1 may end the previous fold
        // (whose drive is another crease), so the rate comes from the state halfway through the step.
        double t0 = ori_trajectory_frame_param(t, k - 1), t1 = ori_trajectory_frame_param(t, k);
        *per = 0.0;
        if (!(t1 > t0)) return ORI_OK;
        double tm = 0.5 * (t0 + t1), dm;
        ori_status st = ori_trajectory_at(t, tm, ts->angles, NULL, &dm, error);
        if (st != ORI_OK) return st;
        *per = fabs(ori_trajectory_frame_drive(t, k) - dm) / (t1 - tm);
        return ORI_OK;
    }
    }
}

static ori_status traj_solve(void *user, double x, ori_v3 *pos, double *drive, ori_error *error)
{
    traj_src *ts = user;
    const ori_trajectory *t = ts->t;
    if (t->kind != ORI_TRAJECTORY_MOTION) return ori_trajectory_at(t, x, ts->angles, pos, drive, error);
    ori_motion_def d = *t->def;
    d.progress = NULL; // the fold's own progress: not for the trial states
    d.progress_user = NULL;
    double from = ts->lo_angles[d.driven_edge];
    d.start_angles_rad = ts->lo_angles;
    d.has_from = false;
    d.to_rad = x;
    d.step_rad = fabs(x - from);
    *drive = x;
    if (!(d.step_rad > 0.0)) {
        memcpy(ts->trial_angles, ts->lo_angles, sizeof(double) * (size_t)ts->edges);
        ori_mechanism_vertex_positions(t->mechanism, ts->lo_angles, d.fixed_face, d.fixed_pose, pos);
        return ORI_OK;
    }
    ori_motion *mo = NULL;
    ori_status st = ori_motion_solve(t->mechanism, &d, &mo, error);
    if (st != ORI_OK) return st;
    int nf = ori_motion_frame_count(mo);
    if (nf == 0 || ori_motion_frame_drive(mo, nf - 1) != x) {
        ori_motion_destroy(mo);
        return ori__fail_at(error, ORI_ERR_NOT_CONVERGED, "edges_vertices", d.driven_edge,
                            "the state at drive %.9g rad between two steps could not be solved", x);
    }
    memcpy(ts->trial_angles, ori_motion_frame_angles(mo, nf - 1), sizeof(double) * (size_t)ts->edges);
    ori_motion_frame_vertices(mo, nf - 1, pos);
    ori_motion_destroy(mo);
    return ORI_OK;
}

static void traj_commit(void *user)
{
    traj_src *ts = user;
    if (ts->t->kind == ORI_TRAJECTORY_MOTION)
        memcpy(ts->lo_angles, ts->trial_angles, sizeof(double) * (size_t)ts->edges);
}

// Walk the frames step by step (walk_step), trial states between them from traj_solve.
static ori_status run_frames(ori_collider *c, const ori_trajectory *t, const ori_collision_motion_def *check,
                             run_out *out, ori_error *error)
{
    memset(out, 0, sizeof *out);
    int count = ori_trajectory_frame_count(t);
    traj_src ts = {t, ori_trajectory_edge_count(t), NULL, NULL, NULL};
    ts.lo_angles = ori__alloc(sizeof(double) * (size_t)(ts.edges + 1));
    ts.trial_angles = ori__alloc(sizeof(double) * (size_t)(ts.edges + 1));
    ts.angles = ori__alloc(sizeof(double) * (size_t)(ts.edges + 1));
    col_source src = {traj_solve, traj_commit, &ts};
    int V = c->vertex_count;
    size_t bytes = sizeof(ori_v3) * (size_t)(V + 1);
    ori_v3 *pa = ori__alloc(bytes), *pb = ori__alloc(bytes), *pt = ori__alloc(bytes);
    col_step s;
    step_init(&s, c);
    ori_status st = ORI_OK;
    if (count > 0) {
        ori_trajectory_frame_vertices(t, 0, pa);
        st = col_state_prepare(c, pa, error);
        ori_collision_result r;
        if (st == ORI_OK) {
            col_check_prepared(c, false, &r);
            geom_save(c, &s.a);
            s.state_a = new_state_id(&s);
            if (r.collides) {
                out->collides = true;
                out->frame = 0;
                out->x = ori_trajectory_frame_param(t, 0);
                out->drive = ori_trajectory_frame_drive(t, 0);
                out->contact = first_colliding(c);
            }
        }
    }
    ori_v3 *ph = ori__alloc(bytes);
    for (int k = 1; st == ORI_OK && !out->collides && k < count; ++k) {
        if (check->progress && !check->progress((double)(k - 1) / (double)(count - 1), check->progress_user)) {
            st = ori__fail(error, ORI_ERR_LIMIT, "cancelled");
            break;
        }
        ori_trajectory_frame_vertices(t, k, pb);
        double x0 = ori_trajectory_frame_param(t, k - 1), x1 = ori_trajectory_frame_param(t, k);
        double d1 = ori_trajectory_frame_drive(t, k);
        walk_out wo;
        st = walk_step(&s, &src, traj_prepare, k, &pa, &pt, &ph, pb, x0, x1, d1, check->drive_tol_rad,
                       ORI_TOL_SWEEP_SPLIT_RAD, &wo, error);
        if (st != ORI_OK) break;
        out->solved += wo.solved;
        if (wo.collides) {
            out->collides = true;
            out->frame = k;
            out->x = wo.x;
            out->drive = wo.drive;
            out->contact = wo.contact;
        }
    }
    ori__free(ph);
    if (st == ORI_OK && check->progress) check->progress(1.0, check->progress_user);
    step_free(&s);
    ori__free(pa);
    ori__free(pb);
    ori__free(pt);
    ori__free(ts.lo_angles);
    ori__free(ts.trial_angles);
    ori__free(ts.angles);
    return st;
}

ori_status ori_collision_check_trajectory(ori_collider *c, const ori_trajectory *t, const ori_collision_motion_def *check,
                                          ori_collision_event *out, ori_error *error)
{
    ORI_ASSERT(c && t && check && out && check->internal_value == ORI__DEF_COOKIE);
    ORI_ASSERT(ori_trajectory_vertex_count(t) == c->vertex_count);
    ORI_ASSERT(t->kind == ORI_TRAJECTORY_RECORD || ori_mechanism_face_count(t->mechanism) == c->face_count);
    ori_error_clear(error);
    memset(out, 0, sizeof *out);
    if (!(check->drive_tol_rad > 0.0))
        return ori__fail(error, ORI_ERR_RANGE, "the drive tolerance must be positive, got %g", check->drive_tol_rad);
    run_out ro;
    ori_status st = run_frames(c, t, check, &ro, error);
    if (st != ORI_OK || !ro.collides) return st;
    out->collides = true;
    out->frame = out->step = ro.frame;
    out->fold = 0;
    out->drive_rad = ro.drive;
    out->contact = ro.contact;
    out->states_solved = ro.solved;
    switch (t->kind) {
    case ORI_TRAJECTORY_MOTION: {
        double d0 = ro.frame > 0 ? ori_trajectory_frame_drive(t, ro.frame - 1) : ro.drive;
        double d1 = ori_trajectory_frame_drive(t, ro.frame);
        out->time = ro.frame == 0 ? 0.0 : (double)(ro.frame - 1) + (d1 != d0 ? (ro.drive - d0) / (d1 - d0) : 1.0);
        break;
    }
    case ORI_TRAJECTORY_MULTIFOLD: out->time = ro.drive; break;
    case ORI_TRAJECTORY_RECORD:
    default: {
        out->fold = ori_trajectory_frame_fold(t, ro.frame);
        // step within the fold: frames of this fold counted from its first output step
        int first = ro.frame;
        while (first > 1 && ori_trajectory_frame_fold(t, first - 1) == out->fold) first--;
        out->step = ro.frame == 0 ? 0 : ro.frame - first + 1;
        out->time = ro.x;
        break;
    }
    }
    return ORI_OK;
}

ori_status ori_collision_check_motion(ori_collider *c, const ori_mechanism *m, const ori_motion_def *def,
                                      const ori_motion *motion, const ori_collision_motion_def *check,
                                      ori_collision_event *out, ori_error *error)
{
    ORI_ASSERT(c && m && def && motion);
    ori_trajectory t = ori_trajectory_of_motion(m, def, motion);
    return ori_collision_check_trajectory(c, &t, check, out, error);
}

ori_status ori_collision_check_record(ori_collider *c, const ori_record *record, const ori_collision_motion_def *check,
                                      ori_collision_event *out, ori_error *error)
{
    ORI_ASSERT(c && record);
    ori_trajectory t = ori_trajectory_of_record(record);
    return ori_collision_check_trajectory(c, &t, check, out, error);
}

ori_status ori_collision_check_multifold(ori_collider *c, const ori_multifold *fold, const int *locked_edges,
                                         int locked_count, const ori_collision_motion_def *check,
                                         ori_collision_event *out, ori_error *error)
{
    ORI_ASSERT(c && fold && (locked_count == 0 || locked_edges));
    ori_trajectory t = ori_trajectory_of_multifold(fold, locked_edges, locked_count);
    return ori_collision_check_trajectory(c, &t, check, out, error);
}
