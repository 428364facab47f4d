/// orikin compliant folding (spec item 19): a bar-and-hinge model of the sheet (Origami
/// Simulator's, Ghassaei et al. 7OSME 2018; MERLIN's, Liu & Paulino 2017). Faces are
/// triangulated; every edge and diagonal is a bar; creases are hinges driven toward their target
/// angle × the fold fraction; diagonals are facet hinges resisting panel bending. An implicit
/// static solver (Newton on the total energy, CHOLMOD Cholesky, load stepping over the fraction,
/// energy line search) and an explicit dynamic one (damped Verlet, Origami Simulator's scheme).
/// docs/compliant.md gives the model equation by equation.
///
/// Functions: ori_default_compliant_def, ori_compliant_physical_def, ori_compliant_create,
/// ori_compliant_destroy, ori_compliant_solve_static, ori_compliant_run_dynamic, and the accessors
/// below (positions, fold angles, strains, per-face strain energy, contact warnings, frames).
#ifndef ORIKIN_COMPLIANT_H
#define ORIKIN_COMPLIANT_H

#include "actuation.h"
#include "base.h"
#include "math.h"
#include "pattern.h"

#ifdef __cplusplus
extern "C" {
#endif

/// How the stiffnesses are given.
typedef enum ori_compliant_preset {
    ORI_COMPLIANT_ORIGAMI_SIMULATOR = 0, ///< normalised: bar k = axial/L0, hinge k = stiffness·L, unit mass per vertex
    ORI_COMPLIANT_PHYSICAL,              ///< SI: panel E, thickness, ν, density; crease stiffness per length (N·m/rad/m)
} ori_compliant_preset;

/// Model and solver parameters; get them from ori_default_compliant_def() (Origami Simulator's
/// defaults) or ori_compliant_physical_def() (a 1 µm silicon-like panel with soft hinges).
typedef struct ori_compliant_def {
    ori_compliant_preset preset;
    // --- ORI_COMPLIANT_ORIGAMI_SIMULATOR ---
    double axial_stiffness;  ///< bar stiffness k = axial_stiffness / L0 (Origami Simulator: 20)
    double facet_stiffness;  ///< facet hinge k = facet_stiffness · L (Origami Simulator: 0.2)
    double crease_stiffness; ///< crease hinge k = crease_stiffness · L (Origami Simulator: 0.7)
    // --- ORI_COMPLIANT_PHYSICAL (SI) ---
    double young_modulus_pa;         ///< panel Young's modulus (Pa)
    double poisson_ratio;            ///< panel Poisson ratio
    double thickness_m;              ///< panel thickness (m); pattern lengths are metres
    double density_kg_m3;            ///< panel density (kg/m³): lumped vertex masses
    double crease_stiffness_per_m;   ///< crease hinge stiffness per unit length (N·m/rad per m)
    // --- both ---
    double damping;                  ///< explicit solver: fraction of critical damping per bar (Origami Simulator: 0.45)
    double gravity;                  ///< acceleration along −z (model units or m/s²), 0 = none
    int fixed_face;                  ///< face whose vertices are held (FOLD index), ORI_NULL_INDEX = the face nearest the sheet's centre
    const double *target_angles_rad; ///< crease targets at 100 %, edge_count (NULL: ori_target_angles_default); copied
    double fraction;                 ///< fold fraction 0 … 1: crease rest angle = target · fraction
    double max_step_rad;             ///< static solver: largest rest-angle change per load step (> 0)
    int max_iterations;              ///< static solver: Newton iterations per load step
    double tolerance;                ///< static equilibrium: |∇E|∞ ≤ tolerance · load scale (1e-10)
    // --- a device design (both presets; its stiffnesses are physical, so use it with the physical preset) ---
    const ori_design *design;        ///< NULL, or the design of the pattern (edges and faces alike; read at creation only):
                                     ///< pattern lengths in its frame_unit; creases with a hinge are layered
                                     ///< elastoplastic sections (rest angle target · fraction); faces with a panel take its
                                     ///< material's E and density and its thickness; wires carry current × fraction in field_t
    double current_a;                ///< current of every wire without its own (A, ≥ 0), at fraction 1
    ori_v3 field_t;                  ///< uniform magnetic field (T)
    bool auto_polarity;              ///< each wire's current is signed to turn its crease toward its assignment (valley +) at the flat state (default true)
    int threads;                     ///< threads of the explicit solver (1 … 64; default 1): fewer when a thread would get
                                     ///< under 4,096 bars and hinges; the result is the one thread's to roundoff
    bool keep_frames;                ///< keep one frame per load step (static), or the time history (explicit: the start, a frame
                                     ///< every 16 steps, thinned by halves to at most 256, and the end); else only the last
    bool check_contacts;             ///< warn of faces passing through each other (after each load step; every 1024 explicit steps and at the end); default true
    int internal_value;              ///< set by the default functions; do not change
} ori_compliant_def;

/// Origami Simulator's preset: axial 20, facet 0.2, crease 0.7, damping 0.45, no gravity, fraction 1.
ORI_API ori_compliant_def ori_default_compliant_def(void);
/// The physical preset (SI): E 169 GPa, ν 0.22, t 1 µm, density 2330 kg/m³, crease 1e-9 N·m/rad per m.
ORI_API ori_compliant_def ori_compliant_physical_def(void);

/// A bar-and-hinge model of one flat pattern, with its current state and frames.
typedef struct ori_compliant ori_compliant;

/// Build the model of a built flat pattern (z = 0, or a planar sheet in another plane, turned into
/// z = 0 with the faces' normal on +z). Fails (*out NULL) with ORI_ERR_ARGUMENT when the vertices
/// are not in one plane (a folded form), ORI_ERR_DEGENERATE for a degenerate face (zero area,
/// repeated vertex, zero-length edge; error.element = its FOLD index), ORI_ERR_TOPOLOGY for an
/// edge of three faces, ORI_ERR_RANGE for a bad fixed face or a non-finite or negative stiffness,
/// fraction, target or tolerance (the message names the field). Destroy with ori_compliant_destroy.
ORI_API ori_status ori_compliant_create(const ori_pattern *pattern, const ori_compliant_def *def,
                                        ori_compliant **out, ori_error *error);
/// Destroy a model; NULL is a no-op.
ORI_API void ori_compliant_destroy(ori_compliant *c);

/// Static equilibrium at def->fraction: load steps from the current fraction (0 at creation),
/// Newton with an energy line search at each. ORI_OK when every step reached |∇E|∞ ≤
/// tolerance · load scale (or its roundoff floor, ori_compliant_gradient_floor);
/// ORI_ERR_NOT_CONVERGED otherwise (the state and frames up to the last equilibrium are kept,
/// ori_compliant_fraction says how far).
ORI_API ori_status ori_compliant_solve_static(ori_compliant *c, ori_error *error);
/// Set the fold fraction of the next solve (0 … 1). ORI_ERR_RANGE outside.
ORI_API ori_status ori_compliant_set_fraction(ori_compliant *c, double fraction, ori_error *error);

/// Explicit dynamics at def->fraction (rest angles set at once, as Origami Simulator's slider):
/// at most max_steps damped Verlet steps of ori_compliant_time_step, stopping once the largest
/// force is ≤ force_tolerance · load scale and the largest speed ≤ force_tolerance · load scale ·
/// time step / mass. Returns the steps done in *steps (may be NULL); ORI_ERR_NOT_CONVERGED when
/// not settled or when the state stops being finite (the message says which; the state is kept).
ORI_API ori_status ori_compliant_run_dynamic(ori_compliant *c, int max_steps, double force_tolerance,
                                            int *steps, ori_error *error);
/// Stable explicit time step: 0.9 / (2π ω_max), ω_max a Gershgorin bound of √(K/m) at the flat state.
ORI_API double ori_compliant_time_step(const ori_compliant *c);

/// Counts: vertices, bars (edges + diagonals), hinges (crease and facet), triangles.
ORI_API int ori_compliant_vertex_count(const ori_compliant *c);
ORI_API int ori_compliant_bar_count(const ori_compliant *c);
ORI_API int ori_compliant_hinge_count(const ori_compliant *c);
ORI_API int ori_compliant_triangle_count(const ori_compliant *c);

/// Current vertex positions (vertex_count, owned by c, valid until the next solve).
ORI_API const ori_v3 *ori_compliant_positions(const ori_compliant *c);
/// Current fold angle of a pattern edge (radians, FOLD sign: + valley), in [−π, π]: a hinge
/// turned past ±π (its faces passing through each other, see the contacts) is reported at ±π;
/// 0 for boundary edges.
ORI_API double ori_compliant_fold_angle(const ori_compliant *c, int edge);
/// Axial strain (L − L0)/L0 of a pattern edge's bar.
ORI_API double ori_compliant_edge_strain(const ori_compliant *c, int edge);
/// Largest |strain| over every bar (edges and diagonals).
ORI_API double ori_compliant_max_strain(const ori_compliant *c);
/// Total potential energy (bars + hinges + gravity) of the current state.
ORI_API double ori_compliant_energy(const ori_compliant *c);
/// |∇E|∞ of the current state, the load scale it is measured against (a force) and the roundoff
/// floor of the gradient (64 ε × the largest element force scale: k·L0 of a bar, k_h·π·|∇ρ| of a hinge).
ORI_API double ori_compliant_gradient_norm(const ori_compliant *c);
ORI_API double ori_compliant_load_scale(const ori_compliant *c);
ORI_API double ori_compliant_gradient_floor(const ori_compliant *c);
/// Permanent (plastic) rotation of an edge's layered hinge in the current state (radians: the
/// fold angle at which it would carry no moment, minus its rest angle); 0 for other edges.
ORI_API double ori_compliant_plastic_rotation(const ori_compliant *c, int edge);
/// Signed current (A) of an edge's wire at the current fraction (current × fraction × polarity);
/// 0 without a wire.
ORI_API double ori_compliant_wire_current(const ori_compliant *c, int edge);
/// Number of the design's wires in the model.
ORI_API int ori_compliant_wire_count(const ori_compliant *c);
/// Fraction of the current state (the last equilibrium's).
ORI_API double ori_compliant_fraction(const ori_compliant *c);
/// Largest |fold angle − target · fraction| over the creases (radians).
ORI_API double ori_compliant_crease_error(const ori_compliant *c);
/// Solver counters: Newton iterations, factorizations, line-search backtracks, load steps.
ORI_API void ori_compliant_stats(const ori_compliant *c, int *iterations, int *factorizations, int *backtracks,
                                 int *load_steps);

/// Number of pattern edges (the per-edge results).
ORI_API int ori_compliant_edge_count(const ori_compliant *c);
/// Number of pattern faces (the per-face results below).
ORI_API int ori_compliant_face_count(const ori_compliant *c);
/// Strain energy of a pattern face in the current state: its bars' and facet hinges' energy (a bar
/// or facet hinge between two faces gives each half; crease hinges and gravity are not counted).
ORI_API double ori_compliant_face_energy(const ori_compliant *c, int face);
/// Largest |axial strain| over the bars of a pattern face (its edges and diagonals), current state.
ORI_API double ori_compliant_face_strain(const ori_compliant *c, int face);

/// Contact warnings (check_contacts): pairs of pattern faces whose deformed triangles pass
/// through each other (the collision module's penetration test), each pair once with the first
/// load step (static, 1-based) or explicit step it was seen at and that step's fraction; at most
/// 256 pairs (ori_compliant_contacts_truncated says when more were left out).
ORI_API int ori_compliant_contact_count(const ori_compliant *c);
ORI_API void ori_compliant_contact(const ori_compliant *c, int k, int *face_a, int *face_b, int *step, double *fraction);
ORI_API bool ori_compliant_contacts_truncated(const ori_compliant *c);

/// Frames kept (keep_frames: one per load step, or the explicit time history; else the last).
ORI_API int ori_compliant_frame_count(const ori_compliant *c);
/// Frame k's fraction, positions (vertex_count), fold angles and strains (edge_count each); owned by c.
ORI_API double ori_compliant_frame_fraction(const ori_compliant *c, int k);
/// Frame k's explicit time (steps × ori_compliant_time_step, model time units; 0 for the static solver's frames).
ORI_API double ori_compliant_frame_time(const ori_compliant *c, int k);
ORI_API const ori_v3 *ori_compliant_frame_positions(const ori_compliant *c, int k);
ORI_API const double *ori_compliant_frame_angles(const ori_compliant *c, int k);
ORI_API const double *ori_compliant_frame_strains(const ori_compliant *c, int k);
/// Frame k's per-face strain energies and largest |strain| (face_count each); owned by c.
ORI_API const double *ori_compliant_frame_face_energies(const ori_compliant *c, int k);
ORI_API const double *ori_compliant_frame_face_strains(const ori_compliant *c, int k);

#ifdef __cplusplus
}
#endif

#endif
