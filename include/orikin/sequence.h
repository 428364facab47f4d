/// orikin sequence: the folding manager (SPEC capability 8, thesis ch. 9.7). A fold sequence
/// is a list of folds; each starts from the geometry the previous one left (its fold angles,
/// and the fixed face where it is now). Running it records every step (the motion record), so
/// that any instant of the whole sequence can be restored exactly.
///
/// Functions: ori_sequence_parse, ori_sequence_load_file, ori_sequence_destroy,
/// ori_sequence_pattern_path, ori_sequence_frame, ori_sequence_fold_count,
/// ori_sequence_fold_at, ori_sequence_to_json, ori_sequence_run, ori_record_destroy,
/// ori_record_fold_count, ori_record_completed_folds, ori_record_partial_frames, ori_record_verdict, ori_record_reason,
/// ori_record_failed_fold, ori_record_frame_count, ori_record_frame_time,
/// ori_record_frame_fold, ori_record_frame_drive, ori_record_frame_angles,
/// ori_record_frame_residual, ori_record_frame_vertices, ori_record_angles, ori_record_vertices,
/// ori_record_duration, ori_record_at.
///
/// Time: T runs from 0 (the start state) to the number of completed folds; T = k + s with
/// 0 ≤ s ≤ 1 is the fraction s of fold k + 1's drive range (T = 1.5: halfway through fold 2).
#ifndef ORIKIN_SEQUENCE_H
#define ORIKIN_SEQUENCE_H

#include "base.h"
#include "kinematics.h"
#include "math.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Most creases one fold may lock.
#define ORI_SEQUENCE_MAX_LOCKS 64
/// Most output states one fold of a sequence may ask for: its "step" is at least
/// 360° / ORI_SEQUENCE_MAX_FOLD_STATES (a smaller step is ORI_ERR_RANGE, naming the fold).
#define ORI_SEQUENCE_MAX_FOLD_STATES 100000

/// One fold of a sequence (FOLD indices, radians).
typedef struct ori_sequence_fold {
    char name[ORI_NAME_MAX];           ///< optional label ("" when none)
    int fixed_face;                    ///< face held in place
    int driven_edge;                   ///< crease turned
    bool has_from;                     ///< output starts at from_rad (reached silently)
    double from_rad;
    double to_rad;                     ///< target angle of the driven crease
    double step_rad;                   ///< output spacing (> 0)
    int locked_count;
    int locked[ORI_SEQUENCE_MAX_LOCKS]; ///< creases held at their current angle
    bool targets;                      ///< a fold toward the targets ("percent"; ori_target_fold_solve): driven_edge is ORI_NULL_INDEX, from/to unused
    double fraction;                   ///< targets: how far along the motion toward them, 0 … 1 (the progress 1 − D/D₀ where it stops)
    bool fix_default;                  ///< no "fix" given: ori_sequence_resolve holds ori_pattern_center_face (the face at the sheet's centroid)
} ori_sequence_fold;

/// Opaque fold sequence (as read from a SEQ.json file).
typedef struct ori_sequence ori_sequence;

/// Parse a sequence: {"pattern": "FILE.fold", "frame": N (optional), "folds": [{"fix": F (optional:
/// the face at the sheet's centroid, set by ori_sequence_resolve, as orikin fold without --fix),
/// (F a face index, name or "@x,y"; E and the lock items an edge index or "@x,y": names and
/// points are kept until ori_sequence_resolve, fixed_face / driven_edge / locked[k] ORI_NULL_INDEX)
/// "drive": E, "to": DEG, "step": DEG (default 10), "from": DEG (optional), "lock": [E…]
/// (optional), "name": "…" (optional)}, …]}; a fold {"fix": F, "percent": P, "step", "lock",
/// "name"} folds every crease toward its target instead (docs/kinematics.md §16; its record
/// "drive" is the progress 0 … 1). Angles in degrees in [−180, 180]. Errors carry
/// the JSON line/column (syntax) or field "folds" and the fold index. Destroy with
/// ori_sequence_destroy.
ORI_API ori_status ori_sequence_parse(const char *json, size_t size, ori_sequence **out, ori_error *error);
/// Resolve the faces and creases a sequence names by string — "fix": a face name ("Obj12") or
/// "@x,y" (the face containing the point), "drive" and "lock" items: "@x,y" (the crease through
/// the point) — against the flat crease pattern (frame 0) they refer to; indices are kept. Run
/// this before ori_sequence_run when the file may hold such names (ori_sequence_run refuses
/// unresolved ones). ORI_ERR_RANGE with field "folds" and the fold index on a name or point the
/// pattern does not have ("fix: no face named Obj9"); the sequence is then unchanged.
ORI_API ori_status ori_sequence_resolve(ori_sequence *sequence, const ori_pattern *flat, ori_error *error);
/// Read and parse a sequence file.
ORI_API ori_status ori_sequence_load_file(const char *path, ori_sequence **out, ori_error *error);
/// Destroy a sequence; NULL is a no-op.
ORI_API void ori_sequence_destroy(ori_sequence *sequence);
/// The pattern path as written in the file (relative paths are relative to the sequence file).
ORI_API const char *ori_sequence_pattern_path(const ori_sequence *sequence);
/// Frame of the pattern file whose fold angles start the sequence (default 0).
ORI_API int ori_sequence_frame(const ori_sequence *sequence);
/// Number of folds in the sequence (≥ 1).
ORI_API int ori_sequence_fold_count(const ori_sequence *sequence);
/// A fold by value.
ORI_API ori_sequence_fold ori_sequence_fold_at(const ori_sequence *sequence, int fold);
/// The sequence as compact JSON text in the file format (degrees). Free with ori_buffer_free.
ORI_API char *ori_sequence_to_json(const ori_sequence *sequence);

/// Opaque motion record of a run.
typedef struct ori_record ori_record;

/// Run the sequence on a mechanism from start_angles_rad (edge_count entries, NULL = flat) with
/// the first fold's fixed face at fixed_pose. Folds run in order until one is not valid; the
/// record keeps the completed folds and the verdict of the failing one. Run-time errors (bad
/// index in a fold, …) return a status naming the fold. Destroy with ori_record_destroy.
ORI_API ori_status ori_sequence_run(const ori_sequence *sequence, const ori_mechanism *mechanism,
                                    const double *start_angles_rad, ori_rigid fixed_pose,
                                    ori_record **out, ori_error *error);
/// ori_sequence_run with progress: called with the fraction of the folds done (fold i at fraction
/// s of its drive range: (i + s) / fold_count; monotone, 1 at the end), may be NULL. Returning
/// false cancels: ORI_ERR_LIMIT ("cancelled"), no record.
ORI_API ori_status ori_sequence_run_progress(const ori_sequence *sequence, const ori_mechanism *mechanism,
                                             const double *start_angles_rad, ori_rigid fixed_pose,
                                             ori_progress_fn *progress, void *progress_user, ori_record **out,
                                             ori_error *error);
/// Destroy a record; NULL is a no-op. Destroy it before its mechanism.
ORI_API void ori_record_destroy(ori_record *record);

/// Number of folds in the sequence.
ORI_API int ori_record_fold_count(const ori_record *record);
/// True when fold `fold` (0-based) is a fold toward the targets ("percent"): its frames' drive is
/// then the progress (0 … 1), not an angle.
ORI_API bool ori_record_fold_is_targets(const ori_record *record, int fold);
/// Folds that completed validly (all of them when the sequence is valid).
ORI_API int ori_record_completed_folds(const ori_record *record);
/// ORI_MOTION_VALID when every fold completed, else the verdict of the first failing fold.
ORI_API ori_motion_verdict ori_record_verdict(const ori_record *record);
/// Why the failing fold is not valid, or NULL.
ORI_API const char *ori_record_reason(const ori_record *record);
/// Index (0-based) of the failing fold, or ORI_NULL_INDEX.
ORI_API int ori_record_failed_fold(const ori_record *record);

/// Recorded states: the start state, then every output step of every completed fold (the
/// first state of a fold, equal to the last of the previous one, is not repeated), and when
/// the failing fold is BLOCKED its states up to the stop (ori_record_partial_frames).
ORI_API int ori_record_frame_count(const ori_record *record);
/// The number of trailing recorded states that belong to a blocked fold (its motion up to the
/// stop, times as fractions of the planned fold), 0 when there are none.
ORI_API int ori_record_partial_frames(const ori_record *record);
/// Sequence time T of a recorded state.
ORI_API double ori_record_frame_time(const ori_record *record, int frame);
/// Fold (0-based) a recorded state belongs to (0 for the start state).
ORI_API int ori_record_frame_fold(const ori_record *record, int frame);
/// Driven-crease angle of that fold at the state (radians).
ORI_API double ori_record_frame_drive(const ori_record *record, int frame);
/// Fold angles of a recorded state (edge_count entries, radians). Owned by the record.
ORI_API const double *ori_record_frame_angles(const ori_record *record, int frame);
/// Loop-closure residual of a recorded state.
ORI_API double ori_record_frame_residual(const ori_record *record, int frame);
/// World vertex positions of a recorded state (vertex_count entries). Owned by the record.
ORI_API const ori_v3 *ori_record_frame_vertices(const ori_record *record, int frame);
/// Fold angles of every recorded state in one block owned by the record: state k's edge_count
/// angles start at the result + k × *frame_stride (may be NULL). NULL when there are no states.
ORI_API const double *ori_record_angles(const ori_record *record, int *frame_stride);
/// World vertex positions of every recorded state in one block owned by the record
/// (frame_count × vertex_count, frame-major). NULL when there are no states.
ORI_API const ori_v3 *ori_record_vertices(const ori_record *record);
/// The end of time: the number of completed folds.
ORI_API double ori_record_duration(const ori_record *record);

/// The state at time t (0 ≤ t ≤ duration), solved exactly (continuation from the recorded
/// state before t, not interpolation): fold angles (edge_count entries), vertex positions
/// (vertex_count entries; may be NULL), residual and fold index (either may be NULL), drive
/// angle. Fails with ORI_ERR_RANGE for t outside [0, duration] — or, when a fold was blocked
/// and recorded up to its stop (ori_record_partial_frames), beyond the last of those frames.
ORI_API ori_status ori_record_at(const ori_record *record, double t, double *angles_rad,
                                 ori_v3 *positions, double *drive_rad, int *fold,
                                 double *residual, ori_error *error);

#ifdef __cplusplus
}
#endif

#endif
