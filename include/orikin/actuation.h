/// orikin actuation: hinge mechanics, Lorentz-force actuation and folding dynamics (thesis
/// ch. 2.2.2, 2.3 and 5.3; SPEC capabilities 12 and 18). Faces are rigid panels with mass,
/// creases are elastoplastic metal hinges, and a current in a wire on a panel, placed in a
/// magnetic field B, folds it (Lorentz force F = N·I·ℓ × B). SI units throughout: metres,
/// kilograms, seconds, amperes, teslas, newton-metres; angles in radians.
///
/// Functions: ori_materials_create, ori_materials_destroy, ori_materials_load,
/// ori_materials_load_file, ori_materials_count, ori_materials_at, ori_materials_find,
/// ori_materials_set, ori_materials_to_json, ori_hinge_yield_moment, ori_hinge_plastic_moment,
/// ori_hinge_stiffness, ori_hinge_monotonic_moment, ori_wire_resistance, ori_lorentz_axis_moment,
/// ori_unit_meters, ori_default_design_def, ori_design_create, ori_design_destroy,
/// ori_design_meters_per_unit, ori_design_edge_count, ori_design_face_count, ori_design_hinge,
/// ori_design_set_hinge, ori_design_panel, ori_design_set_panel, ori_design_actuation,
/// ori_design_set_actuation, ori_design_hinge_mechanics, ori_design_face_mass,
/// ori_design_wire_face, ori_design_wire_moment, ori_design_write, ori_default_sizing_def,
/// ori_sizing_solve, ori_sizing_destroy, ori_sizing_hinge_count, ori_sizing_hinge,
/// ori_sizing_frame_count, ori_sizing_step_at, ori_sizing_frame_field, ori_sizing_frame_drive,
/// ori_sizing_schedule_count, ori_sizing_schedule_at, ori_sizing_summary_of,
/// ori_default_simulation_def, ori_simulation_run, ori_simulation_destroy,
/// ori_simulation_frame_count, ori_simulation_frame_time, ori_simulation_frame_angles,
/// ori_simulation_frame_currents, ori_simulation_frame_plastic, ori_simulation_frame_field,
/// ori_simulation_frame_energy, ori_simulation_frame_residual, ori_simulation_frame_vertices,
/// ori_simulation_latched_angles, ori_simulation_summary_of.
///
/// Conventions. A hinge's rotation is its crease's fold angle (FOLD sign: positive = valley).
/// A wire runs parallel to its hinge on the panel that moves (the face on the far side of the
/// hinge from the fixed face, unless the design names the face), centred on the hinge's
/// midpoint at distance `lever` inside that face; positive current flows along the edge
/// direction v0 → v1. Panels are slabs of their thickness centred on the face plane.
#ifndef ORIKIN_ACTUATION_H
#define ORIKIN_ACTUATION_H

#include "base.h"
#include "fold.h"
#include "kinematics.h"
#include "math.h"
#include "pattern.h"
#include "sequence.h"

#ifdef __cplusplus
extern "C" {
#endif

// --- materials --------------------------------------------------------------------------

/// Longest material name (bytes, including the terminating NUL).
#define ORI_MATERIAL_NAME_MAX 32

/// A material (SI). Panels need the density; hinges the Young's modulus and yield strength;
/// wires the resistivity. Absent properties have their has_ flag false.
typedef struct ori_material {
    char name[ORI_MATERIAL_NAME_MAX];
    double youngs_modulus_pa;           ///< E (Pa)
    double density_kg_m3;               ///< mass density (kg/m³)
    bool has_yield;                     ///< false for brittle materials (Si): not a hinge
    double yield_strength_pa;           ///< σ_y (Pa)
    bool has_resistivity;               ///< false for insulators: not a wire
    double resistivity_ohm_m;           ///< ρ (Ω·m)
    bool has_current_density_max;       ///< false when no limit is known
    double current_density_max_a_m2;    ///< largest current density the film carries (A/m²)
} ori_material;

/// Opaque table of materials by name.
typedef struct ori_materials ori_materials;

/// The built-in table (data/materials.json compiled in: Au from the thesis, Ag, Al, Cr, Cu, Ni,
/// Ti, Si, SiO2, Si3N4, SU-8, polyimide). Destroy with ori_materials_destroy.
ORI_API ori_materials *ori_materials_create(void);
/// Destroy a table; NULL is a no-op.
ORI_API void ori_materials_destroy(ori_materials *table);
/// Merge a materials JSON document {"replace": false, "materials": {"Au": {"youngs_modulus_Pa":
/// …, "density_kg_m3": …, "yield_strength_Pa": …, "resistivity_ohm_m": …,
/// "current_density_max_A_m2": …, "source": "…"}, …}} into the table: an entry replaces the one
/// of the same name; with "replace": true the table is emptied first. Errors name the
/// material (field "materials") and the JSON position; the table is unchanged on failure.
ORI_API ori_status ori_materials_load(ori_materials *table, const char *json, size_t size, ori_error *error);
/// Read and merge a materials file (see ori_materials_load).
ORI_API ori_status ori_materials_load_file(ori_materials *table, const char *path, ori_error *error);
/// Number of materials.
ORI_API int ori_materials_count(const ori_materials *table);
/// A material by index (0 … count − 1), by value.
ORI_API ori_material ori_materials_at(const ori_materials *table, int index);
/// Index of the material with this exact name, or ORI_NULL_INDEX.
ORI_API int ori_materials_find(const ori_materials *table, const char *name);
/// Add or replace a material. Fails with ORI_ERR_RANGE on a non-positive or non-finite value
/// and ORI_ERR_ARGUMENT on an empty or too long name.
ORI_API ori_status ori_materials_set(ori_materials *table, const ori_material *material, ori_error *error);
/// The table as a materials JSON document (the format of ori_materials_load, without sources).
/// Free with ori_buffer_free.
ORI_API char *ori_materials_to_json(const ori_materials *table);

// --- hinge and wire formulas -------------------------------------------------------------

/// First-yield moment of a rectangular hinge: M_y = σ_y·w·t²/6 (N·m).
ORI_API double ori_hinge_yield_moment(double yield_strength_pa, double width_m, double thickness_m);
/// Fully plastic moment: M_p = ¼·σ_y·w·t² (N·m), the thesis' M_req (eq. 1.1).
ORI_API double ori_hinge_plastic_moment(double yield_strength_pa, double width_m, double thickness_m);
/// Elastic bending stiffness of a hinge bending uniformly over its span: k = E·w·t³/(12·span)
/// (N·m/rad).
ORI_API double ori_hinge_stiffness(double youngs_modulus_pa, double width_m, double thickness_m, double span_m);
/// Moment (N·m) of an elastic–perfectly-plastic rectangular hinge loaded monotonically from
/// rest to rotation rotation_rad: k·θ up to θ_y = M_y/k, then M_p·(1 − ⅓(θ_y/θ)²); odd in θ.
ORI_API double ori_hinge_monotonic_moment(double stiffness_nm_rad, double yield_moment_nm, double rotation_rad);
/// Electrical resistance of a conductor of length l and cross-section w × t: R = ρ·l/(w·t) (Ω).
ORI_API double ori_wire_resistance(double resistivity_ohm_m, double length_m, double width_m, double thickness_m);
/// Moment (N·m) about the axis through axis_point along the unit axis_dir of the Lorentz force
/// F = turns·I·length·(wire_dir × B) on a straight wire centred at wire_center along the unit
/// wire_dir (world coordinates, metres; field in teslas).
ORI_API double ori_lorentz_axis_moment(ori_v3 axis_point, ori_v3 axis_dir, ori_v3 wire_center, ori_v3 wire_dir,
                                       double length_m, int turns, double current_a, ori_v3 field_t);

/// Metres per coordinate unit of a FOLD frame_unit ("m", "cm", "mm", "um", "nm", "in", "pt";
/// "µm" too). Fails with ORI_ERR_ARGUMENT for "unit" (unitless) and unknown names.
ORI_API ori_status ori_unit_meters(const char *unit, double *meters, ori_error *error);

// --- design data ---------------------------------------------------------------------------

/// A wire on a hinge's panel (FOLD: edges_orikin:hinge[e].wire).
typedef struct ori_wire {
    double length_m;   ///< length along the hinge (the thesis' w)
    double lever_m;    ///< distance from the hinge line inside the panel (the thesis' L)
    int turns;         ///< number of turns (≥ 1)
    int face;          ///< panel carrying the wire; ORI_NULL_INDEX = the side away from the fixed face
    double width_m;    ///< conductor width (default: the hinge's)
    double thickness_m; ///< conductor thickness (default: the hinge's)
    bool has_current;  ///< a per-wire current is given
    double current_a;  ///< its magnitude (A)
} ori_wire;

/// An elastoplastic hinge on a crease (FOLD: edges_orikin:hinge[e]).
typedef struct ori_hinge {
    char material[ORI_MATERIAL_NAME_MAX];
    double width_m;     ///< along the crease (the thesis' w_h)
    double thickness_m; ///< film thickness (the thesis' t_h)
    double span_m;      ///< bending length across the crease (default 20 × thickness)
    bool has_wire;
    ori_wire wire;
} ori_hinge;

/// A panel (FOLD: faces_orikin:panel[f]).
typedef struct ori_panel {
    char material[ORI_MATERIAL_NAME_MAX];
    double thickness_m;
} ori_panel;

/// Most entries of a field schedule.
#define ORI_SCHEDULE_MAX 32

/// One field orientation of a schedule: once fold `fold` of a sequence is under way (0 for a
/// single fold) and its crease `edge` passes from_rad (moving from its start toward its
/// target), the field is field_t. Entries take over in order; the first is the start field.
typedef struct ori_field_change {
    int edge;         ///< the crease whose angle triggers it (ORI_NULL_INDEX = the reference crease)
    double from_rad;  ///< trigger angle
    ori_v3 field_t;   ///< B (T)
    int fold;         ///< fold of the sequence (0-based; files write it 1-based as "fold")
} ori_field_change;

/// Actuation settings (FOLD: orikin:actuation).
typedef struct ori_actuation {
    bool has_field;
    ori_v3 field_t;              ///< B (T); its magnitude is kept when the schedule is optimised
    bool has_current_limit;
    double current_limit_a;      ///< largest current a wire may carry (A)
    ori_v3 gravity_m_s2;         ///< gravitational acceleration (zero = off; true in files = 9.80665 along −z)
    int schedule_count;
    ori_field_change schedule[ORI_SCHEDULE_MAX];
    int reference_edge;          ///< crease the schedule follows by default (ORI_NULL_INDEX = first wired hinge)
    double damping_ratio;        ///< viscous damping of every hinge, as a fraction of critical (≥ 0)
} ori_actuation;

/// Creation parameters of a design; get them from ori_default_design_def().
typedef struct ori_design_def {
    const ori_fold *doc;             ///< FOLD document with the design fields (may be NULL: empty design)
    const ori_pattern *pattern;      ///< its flat crease pattern (frame 0), built
    const ori_materials *materials;  ///< NULL = the built-in table; copied, not kept
    bool has_meters_per_unit;        ///< override the file's frame_unit (needed when it is unitless)
    double meters_per_unit;
    int internal_value;              ///< set by ori_default_design_def; do not change
} ori_design_def;

/// Defaults: no document, built-in materials, the file's frame_unit.
ORI_API ori_design_def ori_default_design_def(void);

/// Opaque design: hinges, panels, actuation and the panels' mass properties in SI units.
typedef struct ori_design ori_design;

/// Read the design fields of frame 0 (edges_orikin:hinge, faces_orikin:panel,
/// orikin:actuation) and the length unit (frame_unit, or the def's override). Errors name the
/// field and index: unknown material, a dimension that is not positive, a material lacking the
/// property its role needs, a wire outside its panel, a zero field, a unitless file without
/// an override (ORI_ERR_ARGUMENT, field "frame_unit"). Destroy with ori_design_destroy.
ORI_API ori_status ori_design_create(const ori_design_def *def, ori_design **out, ori_error *error);
/// Destroy a design; NULL is a no-op.
ORI_API void ori_design_destroy(ori_design *design);
/// Metres per pattern coordinate unit.
ORI_API double ori_design_meters_per_unit(const ori_design *design);
/// Number of edges and faces of the design's pattern.
ORI_API int ori_design_edge_count(const ori_design *design);
ORI_API int ori_design_face_count(const ori_design *design);
/// The hinge of an edge; false when it has none.
ORI_API bool ori_design_hinge(const ori_design *design, int edge, ori_hinge *out);
/// Set (NULL: remove) the hinge of an edge; validated as in ori_design_create.
ORI_API ori_status ori_design_set_hinge(ori_design *design, int edge, const ori_hinge *hinge, ori_error *error);
/// The panel of a face; false when it has none.
ORI_API bool ori_design_panel(const ori_design *design, int face, ori_panel *out);
/// Set (NULL: remove) the panel of a face; validated as in ori_design_create.
ORI_API ori_status ori_design_set_panel(ori_design *design, int face, const ori_panel *panel, ori_error *error);
/// The actuation settings by value.
ORI_API ori_actuation ori_design_actuation(const ori_design *design);
/// Replace the actuation settings (command-line overrides); validated as in ori_design_create.
ORI_API ori_status ori_design_set_actuation(ori_design *design, const ori_actuation *actuation, ori_error *error);

/// Mechanical and electrical properties of a hinge.
typedef struct ori_hinge_mechanics {
    double stiffness_nm_rad;      ///< k = E·w·t³/(12·span)
    double yield_moment_nm;       ///< M_y = σ_y·w·t²/6
    double plastic_moment_nm;     ///< M_p = ¼·σ_y·w·t² (the thesis' M_req)
    double yield_rotation_rad;    ///< elastic range θ_y = M_y/k
    bool has_wire;
    double wire_path_m;           ///< conductor length of the wire loop: turns·(length + 2·lever)
    double resistance_ohm;        ///< R = ρ·l/(w·t) of the wire loop
    double conductor_area_m2;     ///< smallest cross-section the current crosses (hinge or wire)
    bool has_current_density_max;
    double current_max_a;         ///< current at the material's current-density limit through that area
} ori_hinge_mechanics;

/// Properties of the hinge of an edge; false when it has none.
ORI_API bool ori_design_hinge_mechanics(const ori_design *design, int edge, ori_hinge_mechanics *out);

/// Mass properties of a panel (zero mass for a face without panel data).
typedef struct ori_face_mass {
    double mass_kg;
    ori_v3 centroid_m;       ///< in the flat sheet's frame, metres
    ori_m3 inertia_kg_m2;    ///< about the centroid, flat frame
} ori_face_mass;

/// Mass, centroid and inertia tensor of a face's panel (polygon × thickness × density).
ORI_API ori_face_mass ori_design_face_mass(const ori_design *design, int face);
/// The face carrying the wire of an edge's hinge when fixed_face is held: the wire's own face
/// if the design names one, else the face of the crease farther from fixed_face in the spanning
/// tree of ori_mechanism_spanning_tree. ORI_NULL_INDEX when the edge has no wire.
ORI_API int ori_design_wire_face(const ori_design *design, const ori_mechanism *mechanism, int edge, int fixed_face);
/// Lorentz moment (N·m) of an edge's wire about its own hinge axis in the posed sheet (face
/// poses from ori_mechanism_face_poses; lengths in pattern units), for current current_a and
/// field field_t. The wire's direction and lever arm follow its panel, so the cos Θ factor of
/// M = N·I·w·L·B·cos Θ comes from the pose. 0 when the edge has no wire.
ORI_API double ori_design_wire_moment(const ori_design *design, const ori_mechanism *mechanism, int edge,
                                      int fixed_face, const ori_rigid *poses, double current_a, ori_v3 field_t);
/// Write the design fields (edges_orikin:hinge, faces_orikin:panel, orikin:actuation) into
/// frame 0 of doc, replacing what was there.
ORI_API ori_status ori_design_write(const ori_design *design, ori_fold *doc, ori_error *error);

// --- quasi-static sizing ---------------------------------------------------------------

/// How the sizing chooses the field orientation along the motion.
typedef enum ori_schedule_mode {
    ORI_SCHEDULE_AUTO = 0, ///< the design's schedule when it has one, else OPTIMIZE
    ORI_SCHEDULE_OPTIMIZE, ///< the orientations (with at most `reorientations` changes) that minimise the largest current
    ORI_SCHEDULE_FIXED,    ///< the design's field, never reoriented
    ORI_SCHEDULE_DESIGN,   ///< the design's schedule (its field alone when it has none)
} ori_schedule_mode;

/// Parameters of a sizing; get them from ori_default_sizing_def(). The motion is either a fold
/// (motion) or a sequence run (record with its sequence).
typedef struct ori_sizing_def {
    const ori_design *design;
    const ori_mechanism *mechanism;
    const ori_motion *motion;        ///< a solved valid fold, or NULL
    int driven_edge;                 ///< the fold's driven crease (with motion)
    const ori_record *record;        ///< a sequence run, or NULL
    const ori_sequence *sequence;    ///< the record's sequence (with record)
    ori_schedule_mode schedule;
    int reorientations;              ///< most field changes OPTIMIZE may use (≥ 0; negative: one per fold)
    ori_progress_fn *progress;       ///< may be NULL
    void *progress_user;
    int internal_value;              ///< set by ori_default_sizing_def; do not change
} ori_sizing_def;

/// Defaults: AUTO schedule with at most one reorientation per fold (the thesis reorients the
/// field once, halfway through its fold).
ORI_API ori_sizing_def ori_default_sizing_def(void);

/// The sizing of one hinge over the whole motion.
typedef struct ori_hinge_sizing {
    int edge;
    ori_hinge_mechanics mechanics;
    double travel_rad;             ///< largest |θ − θ_start| along the motion
    double springback_rad;         ///< elastic recovery when unloaded at the end (M/k, rectangular section)
    double plastic_rotation_rad;   ///< permanent rotation left after springback
    double gravity_moment_max_nm;  ///< largest |gravity moment| of the panels beyond the hinge about its axis
    double gravity_ratio;          ///< gravity_moment_max / M_p: < ORI_ACT_GRAVITY_MINOR negligible, ≥ 1 decisive
    bool actuated;                 ///< the hinge has a wire
    double current_needed_a;       ///< the most the motion needs (INFINITY when the field cannot drive it)
    double power_peak_w;           ///< I²R at that current
    double current_density_peak_a_m2; ///< I / conductor area at that current
    int worst_frame;               ///< frame of current_needed
    bool feasible;                 ///< current_needed within the limit and the film's current-density limit
    bool has_optimal_thickness;
    double optimal_thickness_m;    ///< argmax over t of min over the motion of (M_app − M_req)
    bool has_width_range;
    double width_min_m;            ///< narrowest hinge that still latches its panels against gravity
    double width_max_m;            ///< widest hinge the current limit still folds
} ori_hinge_sizing;

/// One hinge at one frame.
typedef struct ori_sizing_step {
    double angle_rad;              ///< fold angle
    double rate;                   ///< dθ/ds along the motion (s: the driven crease's angle toward its target)
    double lorentz_moment_per_amp; ///< Lorentz moment about the hinge axis per ampere (N·m/A), this frame's field
    double gravity_moment_nm;      ///< gravity moment of the panels beyond the hinge, positive = valley
    double required_moment_nm;     ///< moment the wire must supply where the hinge turns: M_p·sign(rate) − gravity (0 where it does not)
    double current_a;              ///< signed current needed (INFINITY when the wire has no leverage)
    double power_w;                ///< I²R
    double current_density_a_m2;   ///< |I| / conductor area
} ori_sizing_step;

/// Whole-motion figures.
typedef struct ori_sizing_summary {
    bool feasible;                 ///< every actuated hinge is feasible and the mechanism folds
    int worst_edge;                ///< actuated hinge needing the most current (ORI_NULL_INDEX: none)
    double current_needed_a;       ///< its current
    double mechanism_current_a;    ///< common current all wires need by virtual work (INFINITY: cannot)
    int mechanism_worst_frame;
    double gravity_ratio_max;      ///< largest gravity_ratio of any hinge
    int reorientations;            ///< field changes of the schedule used
    bool optimized;                ///< the schedule was optimised (not the design's)
} ori_sizing_summary;

/// Opaque result of a sizing.
typedef struct ori_sizing ori_sizing;

/// Size the hinges along a fold or sequence: per hinge and frame the Lorentz moment from the
/// posed wire, gravity moments, the required moment and the current, power and current density;
/// the field schedule; per hinge the optimal thickness and the width range. Errors: no motion,
/// a motion that is not valid, no field, an actuated crease without hinge data (element = edge).
ORI_API ori_status ori_sizing_solve(const ori_sizing_def *def, ori_sizing **out, ori_error *error);
/// Destroy a sizing; NULL is a no-op.
ORI_API void ori_sizing_destroy(ori_sizing *sizing);
/// Number of hinges sized (edges with hinge data that are joints), in edge order.
ORI_API int ori_sizing_hinge_count(const ori_sizing *sizing);
/// A hinge's sizing by value.
ORI_API ori_hinge_sizing ori_sizing_hinge(const ori_sizing *sizing, int index);
/// Frames of the motion.
ORI_API int ori_sizing_frame_count(const ori_sizing *sizing);
/// Hinge index at frame by value.
ORI_API ori_sizing_step ori_sizing_step_at(const ori_sizing *sizing, int index, int frame);
/// Field in force at a frame (T).
ORI_API ori_v3 ori_sizing_frame_field(const ori_sizing *sizing, int frame);
/// Driven crease and its angle at a frame.
ORI_API double ori_sizing_frame_drive(const ori_sizing *sizing, int frame, int *edge);
/// The field schedule used: start field first, then each change.
ORI_API int ori_sizing_schedule_count(const ori_sizing *sizing);
ORI_API ori_field_change ori_sizing_schedule_at(const ori_sizing *sizing, int index);
/// Whole-motion figures.
ORI_API ori_sizing_summary ori_sizing_summary_of(const ori_sizing *sizing);

// --- dynamics --------------------------------------------------------------------------

/// Parameters of a simulation; get them from ori_default_simulation_def().
typedef struct ori_simulation_def {
    const ori_design *design;
    const ori_mechanism *mechanism;
    int fixed_face;                  ///< panel held in place
    ori_rigid fixed_pose;            ///< its world pose
    const double *start_angles_rad;  ///< start state (edge_count; NULL = flat); copied; closed exactly first
    const double *start_rates_rad_s; ///< start fold-angle rates (edge_count; NULL = at rest); made consistent with the loops
    const double *target_angles_rad; ///< per edge (NULL: ±π by assignment, 0 for F and U)
    double current_a;                ///< current in every wire without its own (A, ≥ 0)
    bool auto_polarity;              ///< each wire's polarity drives its crease toward its target at the start
    const double *applied_moments_nm; ///< constant external moment per edge (NULL: none)
    int schedule_count;              ///< field schedule (0: the design's)
    const ori_field_change *schedule;
    int stage_count;                 ///< > 0: the wires act one after the other (a fold sequence):
    const int *stage_edges;          ///< stage k drives the wire of stage_edges[k] until its crease reaches its target, then the next
    const int *stage_lock_counts;    ///< per stage, creases held at their angle during it (may be NULL)
    const int *stage_lock_edges;     ///< those creases, stage after stage
    double duration_s;               ///< simulated time (> 0)
    bool has_dt;
    double dt_s;                     ///< time step (auto: ORI_DYN_STEPS_PER_PERIOD per shortest hinge period)
    bool has_damping;
    double damping_ratio;            ///< overrides the design's
    bool current_off_at_target;      ///< a wire's current stops when its crease reaches its target
    bool has_pulse;
    double pulse_s;                  ///< currents stop at this time
    bool stops;                      ///< creases stop (perfectly inelastic) at ±180°
    int output_frames;               ///< states kept, evenly spaced in time (≥ 2)
    bool settle;                     ///< afterwards, let the sheet come to rest (currents off, critically damped) for the latched angles
    int max_steps;                   ///< most integration steps, the run's and settling's together (≤ 0: ORI_DYN_MAX_STEPS); a run
                                     ///< planned longer is refused before it starts, settling stops at what is left
    ori_progress_fn *progress;
    void *progress_user;
    int internal_value;              ///< set by ori_default_simulation_def; do not change
} ori_simulation_def;

/// Defaults: face 0 fixed at identity, flat start, targets by assignment, no current, auto
/// polarity, the design's schedule and damping, auto time step, currents off at the target,
/// stops on, 101 output frames, settle on.
ORI_API ori_simulation_def ori_default_simulation_def(void);

/// Whole-run figures.
typedef struct ori_simulation_summary {
    bool reached_target;           ///< every wired crease reached its target
    double time_to_target_s;       ///< when (valid when reached_target)
    double peak_angular_velocity;  ///< largest |dθ/dt| of any crease (rad/s)
    double energy_drift;           ///< max |E − E0 − W_in + D| / max(E, W_in, D): 0 for an exact integrator
    double max_residual;           ///< largest loop-closure residual after any step
    int steps;                     ///< time steps taken (including halved ones)
    int explicit_steps;            ///< steps whose midpoint iteration did not converge at the smallest step and were taken explicitly
    double dt_s;                   ///< time step used
    double energy_in_j;            ///< work done by currents, applied moments and gravity
    double dissipated_j;           ///< plastic and viscous dissipation
} ori_simulation_summary;

/// Opaque result of a simulation.
typedef struct ori_simulation ori_simulation;

/// Integrate the mechanism's motion under the hinge, Lorentz, gravity and applied moments,
/// with the loops closed at every step (implicit midpoint rule in fold-angle coordinates,
/// constraint forces by an augmented Lagrangian, projection onto the loop-closure manifold;
/// docs/actuation.md). Errors: a moving face without panel data, a wired crease without
/// hinge data, duration ≤ 0, dt > duration, a zero field with current, a start state that
/// does not close. Destroy with ori_simulation_destroy.
ORI_API ori_status ori_simulation_run(const ori_simulation_def *def, ori_simulation **out, ori_error *error);
/// Destroy a simulation; NULL is a no-op.
ORI_API void ori_simulation_destroy(ori_simulation *simulation);
/// Output frames (output_frames of them, the first at t = 0, the last at the duration).
ORI_API int ori_simulation_frame_count(const ori_simulation *simulation);
/// Time of a frame (s).
ORI_API double ori_simulation_frame_time(const ori_simulation *simulation, int frame);
/// Fold angles (edge_count, radians). Owned by the simulation.
ORI_API const double *ori_simulation_frame_angles(const ori_simulation *simulation, int frame);
/// Signed current in each edge's wire (edge_count, A; 0 without a wire). Owned by the simulation.
ORI_API const double *ori_simulation_frame_currents(const ori_simulation *simulation, int frame);
/// Plastic (permanent) rotation of each hinge (edge_count, radians). Owned by the simulation.
ORI_API const double *ori_simulation_frame_plastic(const ori_simulation *simulation, int frame);
/// Field in force (T).
ORI_API ori_v3 ori_simulation_frame_field(const ori_simulation *simulation, int frame);
/// Kinetic and total mechanical energy (J) of a frame (total = kinetic + elastic + gravity).
ORI_API void ori_simulation_frame_energy(const ori_simulation *simulation, int frame, double *kinetic_j,
                                         double *total_j);
/// Loop-closure residual of a frame (ori_mechanism_residual).
ORI_API double ori_simulation_frame_residual(const ori_simulation *simulation, int frame);
/// World vertex positions of a frame (vertex_count entries, pattern units).
ORI_API void ori_simulation_frame_vertices(const ori_simulation *simulation, int frame, ori_v3 *positions);
/// Fold angles after the currents stop and the sheet comes to rest (edge_count, radians); the
/// last frame's angles when settle was off. Owned by the simulation.
ORI_API const double *ori_simulation_latched_angles(const ori_simulation *simulation);
/// Whole-run figures.
ORI_API ori_simulation_summary ori_simulation_summary_of(const ori_simulation *simulation);

#ifdef __cplusplus
}
#endif

#endif
