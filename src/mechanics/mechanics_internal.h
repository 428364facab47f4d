// Private pieces of src/mechanics shared by the materials table, the design data, the sizing
// and the dynamics: the design record, the layered hinge section, the wire geometry, the
// sheet's kinematic tree in spatial (world-frame) screw coordinates, the loop-closure
// constraints assembled from the public mechanism data, and a symmetric positive definite
// solver (dense LAPACK for small systems, CHOLMOD for large ones).
#ifndef ORI_MECHANICS_INTERNAL_H
#define ORI_MECHANICS_INTERNAL_H

#include <orikin/actuation.h>

#include "../core/core_internal.h"

struct ori_materials {
    ori_material *items;
    int count, cap;
};

struct ori_design {
    int vertex_count, edge_count, face_count;
    double meters_per_unit;
    double diagonal;            // pattern units
    ori_v3 *vertices;           // flat, pattern units
    int (*edges)[2];
    int (*edge_faces)[2];   // left and right face of each edge (ORI_NULL_INDEX: none)
    ori_assignment *assignment;
    int *face_offsets, *face_verts;
    bool *has_hinge;
    ori_hinge *hinges;
    bool *has_panel;
    ori_panel *panels;
    ori_face_mass *mass;
    ori_actuation act;
    ori_materials *materials;   // own copy
};

// --- materials (materials.c) -----------------------------------------------------------------
void ori__materials_copy(ori_materials *dst, const ori_materials *src);
const ori_material *ori__materials_get(const ori_materials *table, const char *name);

// --- layered elastoplastic hinge section (hinge.c) -------------------------------------------
// A rectangular hinge in pure bending as ORI_HINGE_LAYERS elastic–perfectly-plastic fibres
// (symmetric pairs: only the upper half is stored). Rotations relative to the stress-free angle,
// normalised by the first-yield rotation θ_y; the fibre positions and areas are scaled so that
// the elastic stiffness and the fully plastic moment are exact.
#define ORI__HALF_LAYERS (ORI_HINGE_LAYERS / 2)
typedef struct hinge_section {
    double k;      // elastic stiffness (N·m/rad)
    double m_y;    // first-yield moment
    double m_p;    // fully plastic moment
    double th_y;   // yield rotation M_y / k
    double rest;   // stress-free fold angle (rad)
} hinge_section;

typedef struct hinge_fibres {
    double p[ORI__HALF_LAYERS]; // plastic strain / yield strain of the upper fibres
} hinge_fibres;

// Moment (N·m, on the fold angle) at fold angle theta starting from state `from`; the updated
// fibres go to `to` (may be NULL; may equal from). *dissipated (may be NULL) gets the plastic
// work of the update (J).
double ori__hinge_moment(const hinge_section *s, const hinge_fibres *from, double theta, hinge_fibres *to,
                         double *dissipated);
// Elastic energy stored in the hinge at fold angle theta with fibres f (J).
double ori__hinge_energy(const hinge_section *s, const hinge_fibres *f, double theta);
// Permanent rotation: the fold angle at which the hinge would carry no moment, minus the rest.
double ori__hinge_plastic_rotation(const hinge_section *s, const hinge_fibres *f, double theta);
// Incremental potential of a step from fibres `from` to fold angle theta (J): the elastic energy
// while no fibre yields, plus the step's plastic work beyond; convex in theta. Its derivative
// (*moment, = ori__hinge_moment's) and second derivative (*tangent, the elastic fibres'
// stiffness) in theta; either may be NULL. The compliant model's energy of a layered hinge.
double ori__hinge_potential(const hinge_section *s, const hinge_fibres *from, double theta, double *moment, double *tangent);
// The section of an edge's hinge (false when none); rest angle 0.
bool ori__design_section(const ori_design *d, int edge, hinge_section *out);

// --- wire geometry (design.c) -----------------------------------------------------------------
// The current loop of an edge's wire placed on face `face`, in the flat frame (pattern units),
// each segment from a to b in the direction of positive current: on the wire's face the leg out
// from the crease, the wire along it and the leg back (segments 0–2); the loop closes along the
// crease itself (segment 3: the hinge strips and the leads), on the other face. A closed loop in
// a uniform field feels no net force, only a moment.
typedef struct wire_segments {
    ori_v3 a[4], b[4];
    int turns;
    int other; // the face across the crease, carrying segment 3
} wire_segments;
bool ori__wire_segments(const ori_design *d, int edge, int face, wire_segments *out);
// Lorentz wrench (force, moment about the world origin; SI) on segments [first, last) posed by g
// (pattern units → world pattern units), current I, field B.
void ori__wire_wrench(const ori_design *d, const wire_segments *w, int first, int last, ori_rigid g, double current_a,
                      ori_v3 field_t, ori_v3 *force, ori_v3 *moment);

// Generalised Lorentz moment (on the fold angle, positive = valley) of edge e's wire on face f.
double ori__wire_moment(const ori_design *d, int e, int f, const ori_rigid *poses, double current_a, ori_v3 field_t);

// --- kinematic tree (tree.c) -----------------------------------------------------------------
// Spatial twists and wrenches are 6-vectors (v, ω) and (f, τ) in world coordinates (metres,
// moments about the world origin).
typedef struct sv6 {
    ori_v3 v, w;
} sv6;
static inline sv6 sv6_make(ori_v3 v, ori_v3 w) { sv6 r = {v, w}; return r; }
static inline sv6 sv6_zero(void) { return sv6_make(ori_v3_make(0, 0, 0), ori_v3_make(0, 0, 0)); }
static inline sv6 sv6_add(sv6 a, sv6 b) { return sv6_make(ori_v3_add(a.v, b.v), ori_v3_add(a.w, b.w)); }
static inline sv6 sv6_scale(sv6 a, double s) { return sv6_make(ori_v3_scale(a.v, s), ori_v3_scale(a.w, s)); }
static inline double sv6_dot(sv6 a, sv6 b) { return ori_v3_dot(a.v, b.v) + ori_v3_dot(a.w, b.w); }
// Lie bracket ad_a b = (ωa × vb − ωb × va, ωa × ωb).
static inline sv6 sv6_ad(sv6 a, sv6 b)
{
    return sv6_make(ori_v3_sub(ori_v3_cross(a.w, b.v), ori_v3_cross(b.w, a.v)), ori_v3_cross(a.w, b.w));
}

// A rigid body's spatial inertia in world coordinates, in the additive form (bodies combine by
// adding all three): mass, first moment h = m·c and inertia tensor about the world origin.
typedef struct body_inertia {
    double m;
    ori_v3 h;    // kg·m
    ori_m3 io;   // kg·m², about the origin
} body_inertia;
// The world inertia of a face's panel posed by g (pattern units).
body_inertia ori__body_world(const ori_face_mass *fm, ori_rigid g, double meters_per_unit);
void ori__body_add(body_inertia *acc, const body_inertia *b);
// Momentum (linear, angular about the origin) of a body moving with twist V.
sv6 ori__inertia_apply(const body_inertia *b, sv6 V);

// The mechanism as a tree of faces from the fixed face (breadth first), with free joint
// coordinates: every revolute (M, V, U) crease is a coordinate; F creases and J edges are 0.
typedef struct mech_tree {
    const ori_mechanism *m;
    int faces, edges, joints, n;   // n = free coordinates
    int fixed;
    int *order;        // faces in breadth-first order from the fixed face (faces entries)
    int *parent;       // parent face (ORI_NULL_INDEX at the root)
    int *pedge;        // crease to the parent
    int *psign;        // +1 when the face is the crease's face_left, −1 when face_right
    int *pcol;         // coordinate of the crease to the parent, or −1 (locked or root)
    int *col_of_edge;  // coordinate per edge, −1 when not free
    int *edge_of_col;  // edge per coordinate
    int *depth;
} mech_tree;
void ori__tree_init(mech_tree *t, const ori_mechanism *m, int fixed_face);
void ori__tree_free(mech_tree *t);
// Poses of every face for edge angles (flat → world, pattern units), the fixed face at g0.
void ori__tree_poses(const mech_tree *t, const double *edge_angles, ori_rigid g0, ori_rigid *poses);
// World twist (SI) of the crease to face f's parent, seen as the motion of f: psign·Ad_g ξ.
sv6 ori__tree_twist(const mech_tree *t, int f, const ori_rigid *poses, double meters_per_unit);

// --- loop-closure constraints (constraints.c) --------------------------------------------------
typedef struct mech_loops {
    int count, rows;          // loops and equations (3 per vertex loop, 6 per hole loop)
    int *first, *size, *nrows;
    int *edge;                // creases of each loop in order
    int *sign;                // ±1: the face after the crease is its face_left (+1)
    ori_v3 *q, *w;            // flat axis point (pattern units) and unit direction per entry
    int *row0;                // first equation row of each loop
    double inv_diag;          // translations of hole loops are divided by the pattern diagonal
} mech_loops;
void ori__loops_init(mech_loops *l, const ori_mechanism *m, double diagonal);
void ori__loops_free(mech_loops *l);
// Residual Φ (rows entries: rotation vector, and translation/diagonal for holes).
void ori__loops_residual(const mech_loops *l, const double *edge_angles, double *phi);
// Jacobian: for each loop entry, its column block (3 or 6 values; caller maps edges to
// coordinates) in jac[entry·6 …]; with edge_rates (may be NULL) also γ = −Φ̇_θ θ̇ per row.
void ori__loops_jacobian(const mech_loops *l, const double *edge_angles, const double *edge_rates, double *jac,
                         double *gamma);

// --- symmetric positive definite solver (spd.c) --------------------------------------------------
typedef struct mech_spd mech_spd;
// A solver for n × n SPD matrices with the given upper-triangle pattern (i ≤ j pairs, may repeat);
// dense below ORI_MECH_DENSE_MAX unknowns, CHOLMOD (analysed once) above.
mech_spd *ori__spd_create(int n, int pairs, const int *ii, const int *jj);
void ori__spd_destroy(mech_spd *s);
void ori__spd_zero(mech_spd *s);
// Add v to entry (i, j) (either triangle; must be in the pattern).
void ori__spd_add(mech_spd *s, int i, int j, double v);
bool ori__spd_factor(mech_spd *s);
bool ori__spd_solve(mech_spd *s, const double *b, double *x);
// y = A x for the assembled (not factored) matrix.
void ori__spd_mult(const mech_spd *s, const double *x, double *y);

// --- min-norm point of a convex hull (sizing.c, exposed for tests) -------------------------------
// Wolfe's algorithm: the point of conv{p_0 … p_{n−1}} nearest the origin.
ori_v3 ori__min_norm_point(const ori_v3 *p, int n);

#endif
