// Private parts of the compliant bar-and-hinge model (compliant.c, dynamics.c): the model, the
// element formulas (bars, hinges with the exact dihedral gradient and a complex-step Hessian),
// the energy / gradient / Hessian of a state. Tests include it to check derivatives.
#ifndef ORI_COMPLIANT_INTERNAL_H
#define ORI_COMPLIANT_INTERNAL_H

#include <orikin/collision.h>
#include <orikin/compliant.h>

#include "../core/core_internal.h"
#include "../kinematics/kinematics_internal.h"
#include "../mechanics/mechanics_internal.h"

typedef struct cmp_bar {
    int a, b;
    int edge;    // pattern edge, or -1 for a diagonal
    double l0, k;
    double c;    // damping coefficient of the explicit solver
    int face[2]; // the pattern faces of its triangles (face[1] −1 when one, or when both are face[0])
} cmp_bar;

typedef struct cmp_hinge {
    int j, k;    // the hinge axis j → k
    int i, l;    // wing vertices: i left of j → k in the flat sheet, l right
    int edge;    // pattern edge, or -1 for a diagonal
    bool crease; // crease hinge (driven) or facet hinge (rest 0)
    double k_h;  // stiffness (torque per radian)
    double target; // rest angle at fraction 1 (radians)
    double ref;  // last accepted fold angle: the unwrapping reference
    double cache_ref, cref, sref; // cos and sin of cache_ref (set with ori__cmp_set_ref; NaN: none)
    int face[2]; // the pattern faces of its two triangles (face[1] −1 when both are face[0])
} cmp_hinge;

// A point of a wire's current loop, fixed in its triangle: p = Σ w[q] x[v[q]].
typedef struct cmp_wpt {
    int v[3];
    double w[3];
} cmp_wpt;

// A design's wire: its closed current loop (points first … first + count − 1, in order of the
// current) on its panel. Its energy in a uniform field B is −ni·fraction·B·A(p), A = ½ Σ p_i ×
// p_{i+1} the loop's vector area: the Lorentz forces on the loop's segments, lumped half to
// each end, are exactly minus its gradient.
// Pieces each straight segment of a wire's loop is split into (its points follow the panel's
// triangles as they bend).
#define CMP_WIRE_SUBSEGMENTS 8
// Point k of the wire loops at positions x (3 nv).
void ori__cmp_wire_point(const ori_compliant *c, int k, const double *x, double p[3]);

typedef struct cmp_wire {
    int edge, face, turns;
    int first, count;
    double ni; // turns × signed current at fraction 1 (A)
} cmp_wire;

typedef struct cmp_frame {
    double fraction;
    double time; // the explicit solver's time at the frame (0 for the static solver's)
    ori_v3 *x;
    double *angles, *strains;
    double *face_energy, *face_strain; // per pattern face
} cmp_frame;

// A contact warning: two faces passing through each other at a load step (or explicit step).
typedef struct cmp_contact {
    int face_a, face_b, step;
    double fraction;
} cmp_contact;

// Optional trace of the static solver's accepted energies (tests): called per accepted step
// with the energy before and after it.
typedef void ori__cmp_trace_fn(double before, double after, void *user);

struct ori_compliant {
    ori_compliant_def def;
    int nv, ne, nf;
    int nbar, nhinge, ntri;
    cmp_bar *bars;
    cmp_hinge *hinges;
    int *tris;      // 3 per triangle
    int *tri_face;  // triangle → pattern face
    int *edge_bar;  // pattern edge → bar
    int *edge_hinge; // pattern edge → hinge or -1
    hinge_section *hsec; // per hinge: its layered section (a design's hinge), when hplastic
    hinge_fibres *hfib;  // per hinge: the fibres of the last accepted state
    bool *hplastic;      // per hinge (NULL without a design)
    cmp_wire *wires;
    int nwire;
    cmp_wpt *wpts;
    int nwpt;
    ori_v3 field;   // B (T)
    double unit;    // metres per pattern unit (1 without a design): positions inside are metres
    double *mass;   // per vertex
    double m_min;
    int *dof;       // vertex → first free dof, or -1 when held
    int ndof;
    double *x;      // 3 nv positions
    double *x0;     // the flat sheet
    double *v;      // 3 nv velocities (explicit solver)
    double fraction;
    double gravity_factor; // 0 … 1: how much of the gravity acts (ramped by the first static solve)
    double load_scale, grad_floor, mean_length;
    double dt;
    // sparse Hessian (upper triangle, ndof × ndof): per vertex, its sorted lower neighbours
    int *nb_start, *nb;  // CSR over vertices (free ones): neighbours with a smaller dof
    int *colptr, *rowind;
    kin_sls *sls;
    int iterations, factorizations, backtracks, load_steps;
    ori__cmp_trace_fn *trace;
    void *trace_user;
    cmp_frame *frames;
    int nframes, cap_frames;
    double time;        // explicit time run so far (steps × dt)
    int frame_interval; // explicit steps between kept frames (keep_frames; doubled as they are thinned)
    // contact checks of the deformed sheet: the triangles as a pattern and its collider
    ori_pattern *tri_pattern;
    ori_collider *collider;
    cmp_contact *contacts;
    int ncontacts, cap_contacts;
    bool contacts_truncated;
    int check_step; // the step number the next check is recorded with
};

// Set a hinge's unwrapping reference (and the cos and sin the angle uses when asked about it).
void ori__cmp_set_ref(cmp_hinge *h, double ref);
// The explicit solver's forces: ∇E at x and fraction into grad (3 nv, zeroed here; held vertices
// 0), with each hinge's angle and gradient in one pass and no energy.
void ori__cmp_forces(const ori_compliant *c, const double *x, double fraction, double *grad);
// Its parts: the bars [bar0, bar1) and hinges [hinge0, hinge1) added to grad; then the wires,
// gravity and the held vertices (ori__cmp_forces_finish), once the parts are summed.
void ori__cmp_forces_range(const ori_compliant *c, const double *x, double fraction, double *grad, int bar0, int bar1,
                           int hinge0, int hinge1);
void ori__cmp_forces_finish(const ori_compliant *c, const double *x, double fraction, double *grad);
// The wires' part of ∇E added to grad.
void ori__cmp_wire_forces(const ori_compliant *c, const double *x, double fraction, double *grad);
// Fold angle ρ of a hinge (radians, + valley) from positions x (3 per vertex), unwrapped about ref.
double ori__cmp_hinge_angle(const double *x, const cmp_hinge *h, double ref);
// Exact gradient of ρ with respect to the 12 coordinates (x_j, x_k, x_i, x_l), as MERLIN's.
void ori__cmp_hinge_gradient(const double *x, const cmp_hinge *h, double g[12]);
// Hessian of ρ (12 × 12, row-major), complex-step differentiation of the exact gradient.
void ori__cmp_hinge_hessian(const double *x, const cmp_hinge *h, double hess[144]);

// Energy of hinge hh at fold angle theta and fraction, its first and second derivatives in theta
// (*d1, *d2): ½k(θ − rest)², or a layered section's incremental potential from its last accepted
// fibres.
double ori__cmp_hinge_energy(const ori_compliant *c, int hh, double theta, double fraction, double *d1, double *d2);
// Accept the layered hinges' fibres at positions x (fraction): the plastic strain moves on.
void ori__cmp_commit_fibres(ori_compliant *c, const double *x, double fraction);
// Total energy at positions x (3 nv) and fraction; gradient (3 nv, NULL = skip, held vertices 0).
double ori__cmp_energy(const ori_compliant *c, const double *x, double fraction, double *grad);
// Assemble the Hessian of the energy at x into the sparse matrix's values (upper triangle); with
// psd its positive semi-definite part (Gauss–Newton hinges k ∇ρ∇ρᵀ, bars without compressive
// geometric stiffness), the fallback when the exact one is not positive definite.
void ori__cmp_hessian(ori_compliant *c, const double *x, double fraction, bool psd);
// |g|∞ over the free dofs.
double ori__cmp_grad_norm(const ori_compliant *c, const double *grad);
// Strain energy (bars and facet hinges) and largest |bar strain| per pattern face at x (nf each):
// a bar or facet hinge between two faces gives each half its energy. Crease hinges and gravity
// are not a panel's strain.
void ori__cmp_face_strain(const ori_compliant *c, const double *x, double *energy, double *strain);
void ori__cmp_set_trace(ori_compliant *c, ori__cmp_trace_fn *fn, void *user);

#endif
