/// orikin trajectory: one read-only view over the three motion results — a fold (ori_motion), a
/// fold with several degrees of freedom (ori_multifold: toward targets or several drives) and a
/// sequence run (ori_record) — so that a consumer (collision along a motion, drawing, animation,
/// export) walks frames without knowing which kind it has. The view copies nothing: it points at
/// the result (and, for a fold, its mechanism and def; for a multifold, its locks), which must
/// outlive it. It is a small value (ori_trajectory), built by one of the ori_trajectory_of_*
/// functions, never destroyed.
///
/// Every frame has a parameter (ori_trajectory_frame_param), the coordinate along the motion at
/// which ori_trajectory_at restores a state: a fold's drive angle (radians), a multifold's
/// progress (0 … 1), a sequence's time T (sequence.h). The parameters are monotone over the frames
/// (a fold's drive decreases when it folds toward a smaller angle).
///
/// Functions: ori_trajectory_of_motion, ori_trajectory_of_multifold, ori_trajectory_of_record,
/// ori_trajectory_frame_count, ori_trajectory_vertex_count, ori_trajectory_edge_count,
/// ori_trajectory_frame_angles, ori_trajectory_frame_vertices, ori_trajectory_frame_param,
/// ori_trajectory_frame_drive, ori_trajectory_frame_drive_rad, ori_trajectory_frame_fold,
/// ori_trajectory_param_range, ori_trajectory_at.
#ifndef ORIKIN_TRAJECTORY_H
#define ORIKIN_TRAJECTORY_H

#include "base.h"
#include "kinematics.h"
#include "math.h"
#include "sequence.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Which result a trajectory views.
typedef enum ori_trajectory_kind {
    ORI_TRAJECTORY_MOTION,    ///< a fold with one drive (ori_motion); parameter: the drive angle (rad)
    ORI_TRAJECTORY_MULTIFOLD, ///< toward targets or several drives (ori_multifold); parameter: the progress (0 … 1)
    ORI_TRAJECTORY_RECORD,    ///< a sequence run (ori_record); parameter: the sequence time T
} ori_trajectory_kind;

/// The view: read its kind; the other fields are for the ori_trajectory_* functions (do not change).
typedef struct ori_trajectory {
    ori_trajectory_kind kind;
    const ori_mechanism *mechanism;  ///< the mechanism the result was solved on (borrowed)
    const ori_motion *motion;        ///< MOTION: the fold (borrowed)
    const ori_motion_def *def;       ///< MOTION: the def it was solved with (borrowed)
    const ori_multifold *multifold;  ///< MULTIFOLD: the result (borrowed)
    const int *locked_edges;         ///< MULTIFOLD: creases held when closing a state between frames (borrowed), may be NULL
    int locked_count;
    const ori_record *record;        ///< RECORD: the run (borrowed)
} ori_trajectory;

/// View of a fold solved by ori_motion_solve(mechanism, def, …): mechanism, def and motion are
/// borrowed (def's arrays too) and must outlive the view.
ORI_API ori_trajectory ori_trajectory_of_motion(const ori_mechanism *mechanism, const ori_motion_def *def,
                                                const ori_motion *motion);
/// View of a target or drives fold; locked_edges (locked_count entries, may be NULL when 0) are
/// the fold's locks, held when a state between frames is closed (ori_multifold_at). Borrowed.
ORI_API ori_trajectory ori_trajectory_of_multifold(const ori_multifold *fold, const int *locked_edges, int locked_count);
/// View of a sequence run (borrowed).
ORI_API ori_trajectory ori_trajectory_of_record(const ori_record *record);

/// Number of frames (0 when the result has none: an underdetermined fold, a sequence whose first fold failed).
ORI_API int ori_trajectory_frame_count(const ori_trajectory *t);
/// Vertices of every frame (the mechanism's vertex count).
ORI_API int ori_trajectory_vertex_count(const ori_trajectory *t);
/// Fold angles per frame (the mechanism's edge count).
ORI_API int ori_trajectory_edge_count(const ori_trajectory *t);
/// Fold angles of frame k (edge_count entries, radians), owned by the result: no copy.
ORI_API const double *ori_trajectory_frame_angles(const ori_trajectory *t, int k);
/// World vertex positions of frame k written to positions (vertex_count entries, caller's; the
/// same values as the result's own frame_vertices).
ORI_API void ori_trajectory_frame_vertices(const ori_trajectory *t, int k, ori_v3 *positions);
/// The parameter of frame k: a fold's drive angle (rad), a multifold's progress, a sequence's time T.
ORI_API double ori_trajectory_frame_param(const ori_trajectory *t, int k);
/// The drive value of frame k as the result records it: the driven crease's angle (rad) of a fold
/// or of a sequence's fold by one crease; the progress (0 … 1) of a multifold or of a sequence's
/// fold toward targets.
ORI_API double ori_trajectory_frame_drive(const ori_trajectory *t, int k);
/// The driven crease's angle at frame k (rad), or NaN where the drive is a progress (a multifold,
/// a sequence's fold toward targets).
ORI_API double ori_trajectory_frame_drive_rad(const ori_trajectory *t, int k);
/// The sequence fold (0-based) frame k belongs to; 0 for a fold and a multifold.
ORI_API int ori_trajectory_frame_fold(const ori_trajectory *t, int k);
/// The first and the last frame's parameter (either pointer may be NULL); false without frames.
ORI_API bool ori_trajectory_param_range(const ori_trajectory *t, double *first, double *last);

/// The state at parameter x (between the first and the last frame's, either direction), as each
/// kind restores one: a frame's own state at its parameter; between frames k − 1 and k a fold is
/// solved again from frame k − 1 to the drive x (ori_motion_solve, one step), a multifold
/// interpolated and closed (ori_multifold_at), a sequence continued (ori_record_at). Writes
/// angles_rad (edge_count), and when not NULL positions (vertex_count) and *drive (as
/// ori_trajectory_frame_drive). Fails with ORI_ERR_RANGE outside the frames or without frames,
/// ORI_ERR_NOT_CONVERGED when the state cannot be solved.
ORI_API ori_status ori_trajectory_at(const ori_trajectory *t, double x, double *angles_rad, ori_v3 *positions,
                                     double *drive, ori_error *error);

#ifdef __cplusplus
}
#endif

#endif
