// Collision internals shared by collider.c (faces, adjacency, one state), narrow.c (the exact
// face–face tests), bvh.c (broad phase), motion.c (along a motion) and cloud.c.
#ifndef ORI_COLLISION_INTERNAL_H
#define ORI_COLLISION_INTERNAL_H

#include <orikin/collision.h>
#include <orikin/tolerance.h>

#include "../core/core_internal.h"

// --- bounding-volume hierarchy over boxes (bvh.c) ------------------------------------------

typedef struct col_box {
    ori_v3 lo, hi;
} col_box;

typedef struct col_node {
    col_box box;
    int left, right; // children (inner node), -1 for a leaf
    int first, count; // items[first .. first+count) below the node
} col_node;

typedef struct col_bvh {
    col_node *nodes;
    int node_count, node_cap;
    int *items;
    int item_cap;
    double *keys;     // split keys per item (build scratch)
    int key_cap;
    const col_box *boxes; // the item boxes of the last build (not owned)
    // traversal scratch
    int *stack;
    int stack_cap;
} col_bvh;

void col_bvh_free(col_bvh *bvh);
// Median-split hierarchy of n boxes (leaves of at most a few items).
void col_bvh_build(col_bvh *bvh, const col_box *boxes, int n);
// The same hierarchy over new boxes of the same items (each node's box the union of its items'):
// the pairs it gives are exact, only the traversal's pruning degrades as the items move.
void col_bvh_refit(col_bvh *bvh, const col_box *boxes);
// Every pair a < b whose boxes are at most margin apart in every axis; fn returns false to stop.
typedef bool col_pair_fn(void *user, int a, int b);
void col_bvh_self_pairs(col_bvh *bvh, double margin, col_pair_fn *fn, void *user);
// Branch and bound: fn(user, a, b, best) returns the distance of pair a < b (or a value ≥ best to
// skip it); pairs whose boxes are best or more apart are never visited. Returns the least
// distance found, starting from best.
typedef double col_dist_fn(void *user, int a, int b, double best);
double col_bvh_nearest(col_bvh *bvh, double best, col_dist_fn *fn, void *user);

static inline double col_box_dist2(const col_box *a, const col_box *b)
{
    double d2 = 0.0, g, h;
    g = a->lo.x - b->hi.x;
    h = b->lo.x - a->hi.x;
    g = g > h ? g : h;
    if (g > 0.0) d2 += g * g;
    g = a->lo.y - b->hi.y;
    h = b->lo.y - a->hi.y;
    g = g > h ? g : h;
    if (g > 0.0) d2 += g * g;
    g = a->lo.z - b->hi.z;
    h = b->lo.z - a->hi.z;
    g = g > h ? g : h;
    if (g > 0.0) d2 += g * g;
    return d2;
}

static inline bool col_box_near(const col_box *a, const col_box *b, double margin)
{
    return a->lo.x - b->hi.x <= margin && b->lo.x - a->hi.x <= margin && a->lo.y - b->hi.y <= margin &&
           b->lo.y - a->hi.y <= margin && a->lo.z - b->hi.z <= margin && b->lo.z - a->hi.z <= margin;
}

// --- faces of a state ----------------------------------------------------------------------

// Plane and frame of one posed face.
typedef struct col_geom {
    ori_v3 n;      // unit normal (Newell), the face's front side for counter-clockwise faces
    double d;      // plane: n·x = d
    ori_v3 o;      // origin of the in-plane frame (vertex centroid)
    ori_v3 e1, e2; // in-plane orthonormal basis, e1 × e2 = n
    double dev;    // largest distance of a vertex from the plane
} col_geom;

// How the exact test classified a pair.
typedef enum col_class {
    COL_APART = 0,    // not in contact (distance valid when computed)
    COL_TOUCH,
    COL_CROSS,
} col_class;

typedef struct col_pair_result {
    col_class cls;
    bool stacked;        // coplanar layers overlapping by area
    bool has_distance;   // distance and points computed
    double distance;
    ori_v3 pa, pb;       // closest points (has_distance), on face a and face b
    ori_v3 point;        // witness of a contact
} col_pair_result;

// Side of face a relative to face b's front side over the part of a that lies over b.
typedef enum col_side {
    COL_SIDE_NONE = 0, // a does not lie over b (or too thin a sliver to say)
    COL_SIDE_ABOVE,    // on b's front side
    COL_SIDE_BELOW,    // on b's back side
    COL_SIDE_FLAT,     // within the contact tolerance of b's plane: stacked
    COL_SIDE_MIXED,    // on both sides: a crosses b's plane over b
} col_side;

// A point where a face's boundary crosses the other face's plane: its position t along the
// planes' intersection line, and the point.
typedef struct col_xing {
    double t;
    ori_v3 p;
} col_xing;

// Scratch of the exact tests, sized by the largest face (allocated once per checker).
typedef struct col_work {
    int cap;
    ori_v3 *pp, *qq;   // face vertices
    double *dp, *dq;   // signed distances to the other face's plane
    col_xing *xa, *xb, *ia, *ib, *ic; // crossings and interval lists (endpoint pairs)
    ori_v2 *p2, *q2;   // face vertices in a plane frame
    ori_v2 *clip0, *clip1; // polygon clipping buffers
    col_box *eboxes;   // edge boxes
} col_work;

void col_work_init(col_work *w, int max_face);
void col_work_free(col_work *w);

struct ori_collider {
    int vertex_count, edge_count, face_count;
    int *face_off, *face_verts;   // faces_vertices, CSR
    int *tri_off, *tris;          // convex pieces of non-convex faces: triangles (3 ints), CSR; 0 for convex faces
    int *adj_off, *adj;           // faces sharing a vertex, sorted, CSR
    unsigned char *adj_kind;      // col_adjacency of each adj entry
    int max_face;                 // largest face size
    double diagonal, clearance;

    // state of the last geometry (col_state_prepare)
    const ori_v3 *pos;
    col_geom *geom;
    col_box *boxes;
    double tol_pen, tol_touch;
    double distance_bound;        // col_pair_test measures non-adjacent pairs exactly below this too
    col_bvh bvh;
    // The checker as it was before the incremental one (the reference the tests and the bench
    // compare it with): every step from nothing (the hierarchy built again, no pair list, no
    // sides kept from the step before) and no shortcut in the exact tests. Off by default.
    bool reference;

    // results of the last check
    ori_contact *contacts;
    int contact_count, contact_cap;

    // cloud results
    ori_cloud_pair *cloud_pairs;
    int cloud_pair_count, cloud_pair_cap;

    col_work work;
};

// Shared vertices of faces f and g (FOLD vertex indices into out, at most cap); returns count.
int col_shared_vertices(const ori_collider *c, int f, int g, int *out, int cap);
// How faces f ≠ g meet by construction.
typedef enum col_adjacency {
    COL_ADJ_NONE = 0,   // no shared vertex
    COL_ADJ_VERTEX,     // a shared vertex (or a shared side of a non-convex face)
    COL_ADJ_CREASE,     // two convex faces with a common side: they meet only on its line (or stacked)
} col_adjacency;
col_adjacency col_adjacency_of(const ori_collider *c, int f, int g);

// Plane, box and tolerances of every face at positions; fails on bad positions or faces.
ori_status col_state_prepare(ori_collider *c, const ori_v3 *positions, ori_error *error);

// The exact test of faces f < g at the prepared state (narrow.c).
void col_pair_test(ori_collider *c, int f, int g, col_adjacency adjacency, col_pair_result *out);
// Exact distance of faces f and g (no crossing assumed) when it is below bound, with the
// closest points on each; otherwise a value >= bound (points unset).
double col_face_distance(ori_collider *c, int f, int g, double bound, ori_v3 *pa, ori_v3 *pb);
// Side of face a relative to face b's front side; *point = a point of the overlap (on b).
col_side col_face_side(ori_collider *c, int a, int b, ori_v3 *point);
// The same, first trying (convex faces) whether a line along a side parts them: faster where
// they mostly do not overlap, slower where they do; the same answer.
col_side col_face_side_parted(ori_collider *c, int a, int b, ori_v3 *point);
// The same from a's vertices alone, whether or not a lies over b: ABOVE or BELOW when all are
// beyond the penetration tolerance on that side, FLAT when all are within it, else MIXED.
col_side col_face_side_quick(const ori_collider *c, int a, int b);

// Check the prepared state: contacts into the collider; want_clearance also finds the least
// clearance (otherwise only pairs within the clearance margin are measured).
void col_check_prepared(ori_collider *c, bool want_clearance, ori_collision_result *out);
// The same in pieces, for callers with their own candidate pairs: begin, every pair f < g whose
// boxes lie within max(contact tolerance, clearance), end (sorts the contacts, finds the least
// clearance with the checker's own hierarchy when wanted, counts and picks the witness).
void col_check_begin(ori_collider *c, ori_collision_result *out);
void col_check_pair(ori_collider *c, ori_collision_result *out, bool want_clearance, int f, int g);
// The same with the pair's col_adjacency_of already known.
void col_check_pair_kind(ori_collider *c, ori_collision_result *out, bool want_clearance, int f, int g,
                         col_adjacency kind);
void col_check_end(ori_collider *c, bool want_clearance, ori_collision_result *out);

// Checks with the reference checker (true) or the incremental one (false, the default): for the
// tests and the bench comparing them.
void col_collider_set_reference(ori_collider *c, bool reference);

#endif
