// Private pieces of the unfolding module (src/unfold): the exact orientation predicate shared by
// the linkage motion (linkage.c) and the overlap test of nets (net.c); the surfaces, face graphs
// and nets of net.c shared with the development of folded forms (develop.c).
#ifndef ORI_UNFOLD_INTERNAL_H
#define ORI_UNFOLD_INTERNAL_H

#include <stdint.h>

#include <orikin/math.h>
#include <orikin/unfold.h>

// Sign of the orientation of (a, b, c): +1 counter-clockwise, −1 clockwise, 0 collinear,
// exact for the given doubles (a floating-point filter, then GMP rationals when it cannot decide).
int ori__orient2d_exact(ori_v2 a, ori_v2 b, ori_v2 c);
// True when closed segments ab and cd intersect (exactly), touching included.
bool ori__segments_intersect(ori_v2 a, ori_v2 b, ori_v2 c, ori_v2 d);
// True when the segments cross at a single point interior to both (exactly).
bool ori__segments_cross_properly(ori_v2 a, ori_v2 b, ori_v2 c, ori_v2 d);
// Sign of the orientation of the points p_k + ε d[k] + ε² e[k] (p = a, b, c; d and e hold three
// directions each) for an infinitesimal ε > 0: the lowest non-zero coefficient of the polynomial
// in ε, each exact (Simulation of Simplicity with the given perturbation). Zero only when every
// coefficient vanishes.
int ori__orient2d_perturbed(ori_v2 a, ori_v2 b, ori_v2 c, const ori_v2 *d, const ori_v2 *e);

// --- polyhedral surfaces and nets (net.c), shared with the development of folded forms (develop.c)

struct ori_mesh {
    int nv, nf;
    ori_v3 *v;
    int *fstart, *fv;  // merged faces (counter-clockwise seen from outside)
    int *src_start, *src; // input faces of each merged face
    double diag;
    int nhint;            // FOLD input: M/V of its creases, triples (min vertex, max vertex, ±1) sorted,
    int *hint;            // the sign of flat-folded (±180°) creases, which the geometry cannot tell
};

typedef struct fedge {
    int f, g;   // faces (f holds a→b, g holds b→a); g = −1 on the boundary
    int fi, gi; // corner index of a in f, of b in g
    int a, b;   // 3D vertices
    double angle; // FOLD fold angle of the crease (radians): negative for convex edges (mountain)
} fedge;

typedef struct net_ctx {
    const ori_mesh *m;
    int ne;
    fedge *e;
    int *fe_start, *fe; // face → its edge indices
    ori_v2 *local;      // per face corner: coordinates in the face's own plane frame
    ori_v3 *normal;
    // work
    ori_v2 *pos;        // placed corner positions (per face corner)
    uint64_t rng;
} net_ctx;

struct ori_unfold_net {
    ori_unfold_result result;
    ori_pattern *pattern;
    int *src_start, *src; // per net face
    int *glue;            // per net edge
    int *vertex3d;        // per net vertex: the 3D vertex it folds onto
    ori_v3 *shape;        // per net vertex: its 3D position
};

// Face graph of a surface: edges (with the FOLD fold angle of the shape), faces' local frames.
void ori__net_ctx_init(net_ctx *c, const ori_mesh *m);
void ori__net_ctx_free(net_ctx *c);
// Number of corners of face f.
int ori__net_fsize(const ori_mesh *m, int f);
// Lay the faces out along the tree edges (in_tree per edge) breadth-first from root into c->pos;
// order receives the faces in that order, parent_edge the tree edge to each face's parent.
int ori__net_layout(net_ctx *c, const bool *in_tree, int root, int *order, int *parent_edge, bool *placed);
// Triangles of every face (tri_start: face_count + 1 entries; tri: 3 per triangle, corner indices).
void ori__net_build_tris(const net_ctx *c, int *tri_start, int *tri);
// True when placed faces f and g overlap by more than tol (separating axes on their triangles).
bool ori__net_faces_overlap(const net_ctx *c, int f, int g, const int *tri_start, const int *tri, double tol);
// Overlapping pairs of placed faces within the same piece (piece NULL: all), counted up to limit.
// Whether faces f and g of the laid-out net touch: a corner within ORI_TOL_UNFOLD_CONTACT_REL ×
// the diagonal of the other's boundary, other than as the same 3D vertex (which is welded).
bool ori__net_faces_touch(const net_ctx *c, int f, int g);
int ori__net_count_overlaps(const net_ctx *c, const int *tri_start, const int *tri, const int *piece, int limit);
// True when the face graph without the edges decided_out[k] is connected.
bool ori__net_connected_without(const net_ctx *c, const bool *decided_out, int nf);
// The crease pattern of the placed faces: tree edges creases, the others cuts (B, glued pairs).
ori_unfold_net *ori__net_make(const net_ctx *c, const bool *in_tree, const int *piece, int pieces);

#endif
