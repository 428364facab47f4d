// Reports that the command-line tool and the studio's server (orikin view) both produce: one
// builder each, so that `orikin CMD --json` and the studio's API answer with the same fields and
// values by construction. Built as the static library orikin_cli_report, linked by the CLI and
// by the server; it uses only the public <orikin/...> headers and jansson, and never prints.
//
// Functions: cli_collision_check_motion, cli_collision_check_record, cli_collides,
// cli_collide_frames, cli_collision_json, cli_collision_describe, cli_check_run, cli_check_json,
// cli_check_free, cli_motion_block_json, cli_motion_partial, cli_motion_dof_json, cli_lock_text,
// cli_lock_hint, cli_fold_rounding_hint, cli_fold_json, cli_record_json, cli_collide_json,
// cli_layers_count_json, cli_info_json, cli_tree_json, cli_dof_json, cli_axiom_json,
// cli_axiom_solution_error,
// cli_regularize_request_error, cli_regularize_pattern_error, cli_regularize_refusal,
// cli_regularize_json, cli_face_label, cli_apply_counts_json, cli_apply_new_faces_json,
// cli_modes_solve, cli_modes_hint, cli_modes_shown_frames, cli_modes_creases,
// cli_modes_against_assignment, cli_modes_json, cli_modes_free, cli_compliant_request_init,
// cli_compliant_request_error, cli_compliant_def, cli_compliant_solve, cli_compliant_contacts_json,
// cli_compliant_json, cli_motion_alloc, cli_motion_free, cli_motion_of_fold,
// cli_motion_of_multifold, cli_motion_of_compliant, cli_motion_of_record, cli_path_beside,
// cli_pose_faces, cli_poses_from_positions.
#ifndef ORI_CLI_REPORT_H
#define ORI_CLI_REPORT_H

#include <orikin/orikin.h>

#include <jansson.h>
#include <stdbool.h>
#include <stddef.h>

// --- self-collision along a fold or a sequence (orikin fold, orikin sequence; POST /api/fold,
// POST /api/sequence) ------------------------------------------------------------------------

// The first collision of a checked motion.
typedef struct cli_collision {
    bool checked;            // the motion was checked (not --no-collisions)
    ori_collision_event ev;  // ev.collides: frames 0 … ev.frame − 1 are clean
    bool progress;           // ev.drive_rad is the progress (0 … 1) of a fold toward the targets or of
                             // several drives: "progress" replaces "drive_deg"
} cli_collision;

// Check a solved fold (def as solved) with a collider of its flat pattern: *out filled (checked)
// on success, else the library's failure (the collider then holds the contacts of the colliding
// state). progress may be NULL.
ori_status cli_collision_check_motion(ori_collider *c, const ori_mechanism *m, const ori_motion_def *def,
                                      const ori_motion *mo, ori_progress_fn *progress, void *user, cli_collision *out,
                                      ori_error *err);
// Same for a recorded sequence.
ori_status cli_collision_check_record(ori_collider *c, const ori_record *r, ori_progress_fn *progress, void *user,
                                      cli_collision *out, ori_error *err);
// True when the motion collides (the verdict is then "collision").
bool cli_collides(const cli_collision *c);
// Number of frames to show and write: all of them, or those before the first collision.
int cli_collide_frames(const cli_collision *c, int frames);
// {"fold": k (1-based, with_fold only), "step": s, "drive_deg": x (or "progress": p), "faces": [f, g],
// "point": [x, y, z]}
// or null when clean or unchecked.
json_t *cli_collision_json(const cli_collision *c, bool with_fold);
// One line: "faces 3 and 9 penetrate at step 14, drive 131.810315 deg, at (x, y, z)".
void cli_collision_describe(const cli_collision *c, bool with_fold, char *buf, size_t size);

// orikin collide --json of one state: {file, frame (null: not a file's frame), state (when not
// NULL: how the state was made), posed, faces, collides, pairs, touching, min_clearance, witness,
// clearance_faces, clearance, tolerance, contacts, candidate_pairs, cloud (null without cr)}
// (docs/collision.md): a new object the caller owns.
json_t *cli_collide_json(const char *file, int frame, const char *state, bool posed, const ori_collider *c,
                         const ori_collision_result *r, double clearance, const ori_cloud_result *cr, double cloud_spacing,
                         double cloud_distance);

// --- where a fold stops (orikin fold; POST /api/fold) ---------------------------------------

// {"kind": "crease_limit"|"singular", "drive_deg", "edge" (or null), "edge_angle_deg" (or null),
// "singular_edges": [...]}, or null when the motion did not stop (ori_motion_block_of).
json_t *cli_motion_block_json(const ori_motion *mo);
// The frames end before the target: at the stop of a blocked fold, or before a collision.
bool cli_motion_partial(const ori_motion *mo, const cli_collision *col);
// The free mechanism's DOF at the last frame, or null when there is no frame.
json_t *cli_motion_dof_json(const ori_motion *mo);

// --- a fold's and a sequence's answer (orikin fold/sequence --json; POST /api/fold, /api/sequence)

// What the fold was asked to do: its fields in the answer.
typedef struct cli_fold_fields {
    const char *file;          // as the command names it
    int fix, drive;            // face held fixed, crease driven
    double to_deg, step_deg;
    const int *locks;          // locked creases (lock_count of them; not owned)
    int lock_count;
} cli_fold_fields;

// When a fold is not rigidly foldable and interior vertices of flat miss Kawasaki by under
// 1e-3 rad (a drawing's rounded coordinates), the advice in buf (size bytes): true; else false.
bool cli_fold_rounding_hint(const ori_pattern *flat, const ori_motion *mo, char *buf, size_t size);
// {file, valid, verdict, reason, collision, hint, rigidly_foldable, dof, grubler, solver,
// fixed_face, drive, to_deg, step_deg, locked, [frame_a, frame_b, surrounding, split],
// offending_edges, blocked, partial, frames, stats} (docs/kinematics.md §11): a new object the
// caller owns. lock_hint: an underdetermined fold's lock suggestion (cli_lock_hint) or NULL.
json_t *cli_fold_json(const cli_fold_fields *fields, const ori_pattern *flat, const ori_mechanism *m,
                      const ori_motion *mo, const cli_collision *col, const char *lock_hint);
// {sequence, pattern, valid, verdict, reason, collision, failed_fold, duration, partial_frames,
// folds, frames} of a recorded sequence (docs/sequence.md; edge_count creases): a new object.
json_t *cli_record_json(const char *sequence, const char *pattern, const ori_sequence *s, const ori_record *r,
                        int edge_count, const cli_collision *col);

// --- the fold modes (orikin fold --percent / several --drive / --symmetric / --lock auto; POST /api/fold)

// A fold of several degrees of freedom: the request (resolved creases and face), the pattern it
// runs on (borrowed), and what cli_modes_solve made (owned; cli_modes_free).
typedef struct cli_modes {
    int fix;                            // the face held fixed
    bool has_percent;                   // toward the targets, percent (0–100) of the way
    double percent;
    const int *drives;                  // several drives: creases and targets (ndrives each; borrowed)
    const double *to_deg;
    int ndrives;
    const int *given_locks;             // creases held at their start angle (borrowed)
    int ngiven;
    bool lock_auto, symmetric;
    double step_deg;
    const ori_mechanism *mech;          // the pattern (borrowed)
    const ori_pattern *flat;
    const double *start;                // start fold angles (edge_count, radians)
    ori_rigid pose;                     // the fixed face's world pose at the start
    ori_progress_fn *progress;          // the solve's progress (may be NULL)
    void *progress_user;
    // results
    ori_multifold *mf;
    int *group;                         // symmetry orbits (edge_count) or NULL
    int sym_order, sym_groups;
    int *locks;                         // the lock set used (given, then automatic)
    int nlocks;
    bool lock_set_failed;               // the failure was the automatic lock set's
    char hint[1024];                    // rounded coordinates, or an underdetermined fold's lock suggestion
    cli_collision col;                  // the caller's self-collision check of mf (zero: unchecked)
} cli_modes;

// Symmetry orbits, the automatic lock set and the fold (ori_target_fold_solve or
// ori_drives_fold_solve); the library's failure with *err (lock_set_failed says which step).
ori_status cli_modes_solve(cli_modes *x, ori_error *err);
// The hint of a fold that did not reach its goal: rounded coordinates (Kawasaki missed by under
// 1e-3 rad) or, underdetermined, a lock set (searched with progress, which may be NULL).
void cli_modes_hint(cli_modes *x, ori_progress_fn *progress, void *user);
// Frames to show and write: all of them, or those before the first collision.
int cli_modes_shown_frames(const cli_modes *x);
// Per crease with a goal: start, target, goal, reached (radians), fraction of the way.
typedef struct cli_modes_crease {
    int edge;
    double start, target, goal, reached, fraction;
    bool still; // set by the text summary: short of its goal and not moved
} cli_modes_crease;
// The rows into rows (edge_count + 1 entries); returns their number.
int cli_modes_creases(const cli_modes *x, cli_modes_crease *rows);
// Creases folding against their assignment on a shown frame: edge, M/V, worst angle (radians).
typedef struct cli_modes_against {
    int edge;
    char assignment;
    double angle;
} cli_modes_against;
int cli_modes_against_assignment(const cli_modes *x, cli_modes_against *rows);
// orikin fold --json of a mode: {file, mode, valid, verdict, reason, collision, hint, stop_edge,
// fixed_face, percent, step_deg, symmetry, locked, lock_auto, drives, creases,
// against_assignment, frames, stats}: a new object.
json_t *cli_modes_json(const cli_modes *x, const char *file);
// Release the results (the request and pattern are the caller's).
void cli_modes_free(cli_modes *x);

// --- local flat-foldability (orikin check; GET /api/check) ----------------------------------

// A pattern's check at a tolerance and, without one, whether rounding explains the failures.
typedef struct cli_check {
    ori_flat_report *report;  // every interior vertex at the tolerance
    bool has_tolerance;       // a tolerance was asked for (then no rounding hint is computed)
    double tolerance_deg;     // 0 … 1
    int rounding_failures;    // without a tolerance: failures within ORI_FLAT_ROUNDING_HINT_RAD
    double rounding_max_rad;  // the largest sector change they need
    char hint[400];           // "" or the advice (naming file as the command to run)
} cli_check;

// Check pattern (built) at tolerance_deg (meaningful when has_tolerance); file names the pattern
// in the hint. Free with cli_check_free.
void cli_check_run(const ori_pattern *p, const char *file, bool has_tolerance, double tolerance_deg, cli_check *out);
// {file, frame, locally_flat_foldable, interior_vertices, failed_vertices, tolerance_deg,
// within_tolerance_vertices, max_deviation_deg, rounding_failures, hint, vertices: [...],
// violations: [...]} (docs/verification.md).
json_t *cli_check_json(const cli_check *c, const char *file, int frame, const ori_pattern *p);
void cli_check_free(cli_check *c);

// --- which creases to lock (an underdetermined fold's "hint"; orikin fold, POST /api/fold) --------

// "lock N more creases, e.g. --lock a,b,c (or --lock auto)" for the lock set locks[0 … n) into buf.
void cli_lock_text(const int *locks, int n, char *buf, size_t size);
// A lock set that leaves the single-drive fold def one degree of freedom (ori_mechanism_lock_set
// at def's start angles), as that text into buf (empty when none is found), and as a new JSON
// array in *locks when locks is not NULL (untouched then). Returns the count, or −1.
int cli_lock_hint(const ori_mechanism *m, const ori_motion_def *def, char *buf, size_t size, json_t **locks);

// --- layer orders (orikin layers --json, orikin-layers-mpi --json) ------------------------

// A counted layer problem as JSON: states, components, faces, variables, constraints,
// tolerance, tolerance_source, drawing_noise, unsatisfiable, and "limited" (budget_given: a
// --limit or --timeout was given) and "timed_out" (timeout_given). New reference.
json_t *cli_layers_count_json(const ori_layers *L, bool budget_given, bool timeout_given);

// --- one pattern's facts (orikin info, tree, dof, axiom --json; GET /api/info, /api/tree,
// /api/dof, POST /api/axiom) --------------------------------------------------------------

// {file, frame, frames, vertices, edges, edges_by_assignment, faces, interior_vertices,
// dimension, folded_form} of pattern p, frame `frame` of a file of `frames` frames: a new object.
json_t *cli_info_json(const char *file, int frame, int frames, const ori_pattern *p);
// {file, nodes: [{name, parent, children, leaf, face}], folding_elements: [{face, name}]}: the
// face tree of p, a new object.
json_t *cli_tree_json(const char *file, const ori_pattern *p);
// {file, frame, grubler, unknowns, equations, rank, dof, generic_dof, singular, rigid,
// undetermined, probe_solves, method, sigma_max, sigma_cut, loops, nearby_against_assignment}
// of a rank r of a mechanism with `loops` vertex loops: a new object.
json_t *cli_dof_json(const char *file, int frame, const ori_dof_result *r, int loops);
// {axiom, lines: [{point, dir}]} of the solutions set of a Huzita–Hatori axiom: a new object.
json_t *cli_axiom_json(int axiom, const ori_line_set *set);
// Why solution (1-based) of an axiom with count solutions does not exist, into buf: true; false
// when it exists (orikin crease --solution, POST /api/crease's solution).
bool cli_axiom_solution_error(int axiom, int solution, int count, char *buf, size_t size);

// --- regularization (orikin regularize --json; POST /api/regularize) --------------------------

// The mistake in a regularization request (max_move outside (0, 1], named max_move_name as the
// front end spells it; rigid with rigid_only) as one line into buf: true; false when it is valid.
bool cli_regularize_request_error(const ori_regularize_def *def, const char *max_move_name, char *buf, size_t size);
// Why pattern p (frame `frame` of its file) cannot be regularized (a folded form) into buf: true.
bool cli_regularize_pattern_error(const ori_pattern *p, int frame, char *buf, size_t size);
// Why the result r of ori_regularize under def is refused, as one line into buf (size bytes,
// returned), or NULL when it is accepted (every condition holds, nothing moved too far).
const char *cli_regularize_refusal(const ori_regularize_result *r, const ori_regularize_def *def, char *buf, size_t size);
// {file, rigid, converged, refused, reason (why or null), interior_vertices, …, check_vertex,
// output (the path written, or null)} (docs/verification.md): a new object the caller owns.
json_t *cli_regularize_json(const char *file, const ori_regularize_def *def, const ori_regularize_result *r,
                            const char *why, const char *output);

// --- a composite or a crease applied to a face (orikin apply, crease --json; POST /api/apply,
// /api/crease) --------------------------------------------------------------------------------

// A face as the reports name it: its name, else "face N", or "the sheet" for ORI_NULL_INDEX
// (into buf, size bytes; returned).
const char *cli_face_label(const ori_pattern *p, int f, char *buf, size_t size);
// segments, faces_split, edges_added and first_edge of r, set on object o.
void cli_apply_counts_json(json_t *o, const ori_apply_result *r);
// [{name, face}] of the folding elements that tree nodes nodes_before … of p name: a new array.
json_t *cli_apply_new_faces_json(const ori_pattern *p, int nodes_before);

// --- the compliant fold (orikin fold --compliant; POST /api/compliant) --------------------

// A compliant fold as asked: the options of fold --compliant and the fields of the request.
typedef struct cli_compliant_request {
    double percent;          // 0 … 100
    bool dynamic;            // the explicit solver
    bool physical;           // the physical preset (else Origami Simulator's)
    bool has_axial, has_facet, has_crease, has_damping;
    double axial, facet, crease, damping;
    double gravity;
    int steps;               // explicit steps (> 0)
    int threads;             // explicit solver threads (1 … 64)
    int fix;                 // face held (ORI_NULL_INDEX: the model's default)
    bool all_frames;         // keep one frame per load step (static)
} cli_compliant_request;

// Defaults: 100 %, static, Origami Simulator's preset, no gravity, 1,000,000 steps, 1 thread.
void cli_compliant_request_init(cli_compliant_request *r);
// The mistake of a request (a range, a combination), written as the CLI's usage message with the
// option names (--percent, --axial, ...); false when there is none.
bool cli_compliant_request_error(const cli_compliant_request *r, char *buf, size_t size);
// The model's definition for a request (the fraction, the preset with its replaced stiffnesses).
ori_compliant_def cli_compliant_def(const cli_compliant_request *r);
// Build the model of p and fold it. ORI_OK with *out (destroy with ori_compliant_destroy) and
// *reached, *explicit_steps and, when not reached, *why (the solver's message); otherwise the
// model's refusal (bad input) in *error.
ori_status cli_compliant_solve(const ori_pattern *p, const cli_compliant_request *r, ori_compliant **out, bool *reached,
                               int *explicit_steps, ori_error *why, ori_error *error);
// The model's contact warnings: [{faces: [a, b], step, <fraction_key>: the fraction}].
json_t *cli_compliant_contacts_json(const ori_compliant *c, const char *fraction_key);
// fold --compliant --json: {file, model, solver, preset, percent, reached, reached_fraction,
// max_strain, energy, crease_error_deg, gradient_norm, load_scale, vertices, bars, hinges, steps |
// newton_iterations, load_steps, fold_angles_deg, strains, face_energies, face_strains, contacts,
// contacts_truncated, reason (when not reached)}; with positions also "positions" ([x, y, z] per
// vertex, the studio's drawing).
json_t *cli_compliant_json(const char *file, const cli_compliant_request *r, const ori_compliant *c, bool reached,
                           int explicit_steps, const char *reason, bool positions);

// --- small pieces both front ends need (common.c) -------------------------------------------

// path read relative to the folder of file (as a sequence names its pattern): malloc'd; an
// absolute path, or a file without a folder, gives path itself.
char *cli_path_beside(const char *file, const char *path);
// Every face's pose in a state (angles, positions) by forward kinematics from fixed_face, placed
// where positions have it (its rigid fit; the identity when it has none); poses: face_count.
void cli_pose_faces(const ori_mechanism *mech, int fixed_face, const double *angles, const ori_v3 *positions,
                    ori_rigid *poses);
// Every face's pose fitted to world positions: malloc'd (face_count), or NULL without a
// mechanism or when some face is not a rigid copy of its reference.
ori_rigid *cli_poses_from_positions(const ori_mechanism *mech, const ori_v3 *positions);

// --- a motion as keyframes (orikin export --animate, orikin animate; GET /api/export of=fold|sequence)

// A motion as frames: times (s), world vertices, fold angles and flat → world face poses of each.
typedef struct cli_motion {
    int count, vertex_count, face_count, edge_count;
    double *times;      // count
    ori_v3 *positions;  // count × vertex_count
    ori_rigid *poses;   // count × face_count, or NULL when some face is not rigid
    double *angles;     // count × edge_count, or NULL
    int *sources;       // count: the FOLD frame each one shows (a FOLD file's frames), or NULL
    double duration;    // seconds
} cli_motion;

// Allocate count zeroed frames (poses and angles only when asked); sources NULL, duration 0.
void cli_motion_alloc(cli_motion *m, int count, int vertex_count, int face_count, int edge_count, bool poses,
                      bool angles);
// Release the frames (m zeroed).
void cli_motion_free(cli_motion *m);
// A single-drive fold solved on mech with def, its drive starting at from_rad: its output steps
// (samples < 2) or, samples ≥ 2, solved again with samples steps evenly spaced in drive; times
// (drive − from) / (to − from) (the frame index when to = from). ORI_ERR_NOT_CONVERGED (said in
// *err) when the motion solved again is not valid; the solver's failure otherwise.
ori_status cli_motion_of_fold(const ori_mechanism *mech, const ori_motion_def *def, const ori_motion *motion,
                              double from_rad, int samples, cli_motion *m, ori_error *err);
// A fold toward the targets or by several drives (locks: the fold's lock set): its frames timed by
// their progress (0 … 1) when samples < 2, else samples states at evenly spaced progress, each
// closed exactly (ori_multifold_at); the faces posed from fixed_face's pose in each state.
// progress (may be NULL) sees the fraction of samples done.
ori_status cli_motion_of_multifold(const ori_mechanism *mech, const ori_multifold *mf, const int *locks, int nlocks,
                                   int fixed_face, int samples, ori_progress_fn *progress, void *user, cli_motion *m,
                                   ori_error *err);
// A compliant fold solved with its frames kept (cli_compliant_request all_frames): its recorded
// states (the load steps from the flat sheet, timed by their fraction of the way 0 … 1; or the
// explicit solver's time history, timed by its time), or
// samples states at evenly spaced fractions, each the recorded state nearest to it (the model
// holds nothing between its steps); sources: the state's index in the model; no face poses (the
// faces bend). ORI_ERR_RANGE (said in *err) when the model recorded fewer than two states.
ori_status cli_motion_of_compliant(const ori_compliant *c, int samples, cli_motion *m, ori_error *err);
// A sequence run: its recorded states (samples < 2) or samples states evenly spaced over its
// duration, each restored exactly (ori_record_at); one second per fold; the faces posed from each
// fold's fixed face.
ori_status cli_motion_of_record(const ori_mechanism *mech, const ori_sequence *seq, const ori_record *r, int samples,
                                ori_progress_fn *progress, void *user, cli_motion *m, ori_error *err);

#endif
