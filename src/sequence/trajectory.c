// One view over the three motion results (ori_motion, ori_multifold, ori_record): frames, their
// parameter and drive, and the state at any parameter, restored as each kind does it. Nothing is
// copied: the view points at the result.
#include <orikin/trajectory.h>

#include <math.h>
#include <string.h>

#include "../core/core_internal.h"
#include "../kinematics/multifold_internal.h" // the multifold's mechanism and edge count
#include "sequence_internal.h"

ori_trajectory ori_trajectory_of_motion(const ori_mechanism *mechanism, const ori_motion_def *def, const ori_motion *motion)
{
    ORI_ASSERT(mechanism && def && motion);
    ori_trajectory t;
    memset(&t, 0, sizeof t);
    t.kind = ORI_TRAJECTORY_MOTION;
    t.mechanism = mechanism;
    t.def = def;
    t.motion = motion;
    return t;
}

ori_trajectory ori_trajectory_of_multifold(const ori_multifold *fold, const int *locked_edges, int locked_count)
{
    ORI_ASSERT(fold && locked_count >= 0 && (locked_count == 0 || locked_edges));
    ori_trajectory t;
    memset(&t, 0, sizeof t);
    t.kind = ORI_TRAJECTORY_MULTIFOLD;
    t.mechanism = fold->m;
    t.multifold = fold;
    t.locked_edges = locked_edges;
    t.locked_count = locked_count;
    return t;
}

ori_trajectory ori_trajectory_of_record(const ori_record *record)
{
    ORI_ASSERT(record);
    ori_trajectory t;
    memset(&t, 0, sizeof t);
    t.kind = ORI_TRAJECTORY_RECORD;
    t.mechanism = ori__record_mechanism(record);
    t.record = record;
    return t;
}

int ori_trajectory_frame_count(const ori_trajectory *t)
{
    ORI_ASSERT(t);
    switch (t->kind) {
    case ORI_TRAJECTORY_MOTION: return ori_motion_frame_count(t->motion);
    case ORI_TRAJECTORY_MULTIFOLD: return ori_multifold_frame_count(t->multifold);
    case ORI_TRAJECTORY_RECORD:
    default: return ori_record_frame_count(t->record);
    }
}

int ori_trajectory_vertex_count(const ori_trajectory *t)
{
    ORI_ASSERT(t);
    return ori_mechanism_vertex_count(t->mechanism);
}

int ori_trajectory_edge_count(const ori_trajectory *t)
{
    ORI_ASSERT(t);
    return ori_mechanism_edge_count(t->mechanism);
}

const double *ori_trajectory_frame_angles(const ori_trajectory *t, int k)
{
    ORI_ASSERT(t && k >= 0 && k < ori_trajectory_frame_count(t));
    switch (t->kind) {
    case ORI_TRAJECTORY_MOTION: return ori_motion_frame_angles(t->motion, k);
    case ORI_TRAJECTORY_MULTIFOLD: return ori_multifold_frame_angles(t->multifold, k);
    case ORI_TRAJECTORY_RECORD:
    default: return ori_record_frame_angles(t->record, k);
    }
}

void ori_trajectory_frame_vertices(const ori_trajectory *t, int k, ori_v3 *positions)
{
    ORI_ASSERT(t && positions && k >= 0 && k < ori_trajectory_frame_count(t));
    switch (t->kind) {
    case ORI_TRAJECTORY_MOTION: ori_motion_frame_vertices(t->motion, k, positions); break;
    case ORI_TRAJECTORY_MULTIFOLD: ori_multifold_frame_vertices(t->multifold, k, positions); break;
    case ORI_TRAJECTORY_RECORD:
    default:
        memcpy(positions, ori_record_frame_vertices(t->record, k),
               sizeof(ori_v3) * (size_t)ori_mechanism_vertex_count(t->mechanism));
        break;
    }
}

double ori_trajectory_frame_param(const ori_trajectory *t, int k)
{
    ORI_ASSERT(t && k >= 0 && k < ori_trajectory_frame_count(t));
    switch (t->kind) {
    case ORI_TRAJECTORY_MOTION: return ori_motion_frame_drive(t->motion, k);
    case ORI_TRAJECTORY_MULTIFOLD: return ori_multifold_frame_progress(t->multifold, k);
    case ORI_TRAJECTORY_RECORD:
    default: return ori_record_frame_time(t->record, k);
    }
}

double ori_trajectory_frame_drive(const ori_trajectory *t, int k)
{
    ORI_ASSERT(t && k >= 0 && k < ori_trajectory_frame_count(t));
    switch (t->kind) {
    case ORI_TRAJECTORY_MOTION: return ori_motion_frame_drive(t->motion, k);
    case ORI_TRAJECTORY_MULTIFOLD: return ori_multifold_frame_progress(t->multifold, k);
    case ORI_TRAJECTORY_RECORD:
    default: return ori_record_frame_drive(t->record, k);
    }
}

double ori_trajectory_frame_drive_rad(const ori_trajectory *t, int k)
{
    ORI_ASSERT(t && k >= 0 && k < ori_trajectory_frame_count(t));
    switch (t->kind) {
    case ORI_TRAJECTORY_MOTION: return ori_motion_frame_drive(t->motion, k);
    case ORI_TRAJECTORY_MULTIFOLD: return NAN;
    case ORI_TRAJECTORY_RECORD:
    default:
        return ori_record_fold_is_targets(t->record, ori_record_frame_fold(t->record, k))
                   ? NAN
                   : ori_record_frame_drive(t->record, k);
    }
}

int ori_trajectory_frame_fold(const ori_trajectory *t, int k)
{
    ORI_ASSERT(t && k >= 0 && k < ori_trajectory_frame_count(t));
    return t->kind == ORI_TRAJECTORY_RECORD ? ori_record_frame_fold(t->record, k) : 0;
}

bool ori_trajectory_param_range(const ori_trajectory *t, double *first, double *last)
{
    ORI_ASSERT(t);
    int n = ori_trajectory_frame_count(t);
    if (n == 0) return false;
    if (first) *first = ori_trajectory_frame_param(t, 0);
    if (last) *last = ori_trajectory_frame_param(t, n - 1);
    return true;
}

// A fold: frame k's state at its drive; between frames k and k + 1 (the last frame at or before
// x along the drive's direction) solved again from frame k to x in one step, as the collision
// check's first trial state of a step is.
static ori_status motion_at(const ori_trajectory *t, double x, double *angles, ori_v3 *positions, double *drive,
                            ori_error *error)
{
    const ori_motion *mo = t->motion;
    int n = ori_motion_frame_count(mo), E = ori_mechanism_edge_count(t->mechanism);
    double p0 = ori_motion_frame_drive(mo, 0), p1 = ori_motion_frame_drive(mo, n - 1);
    double s = p1 >= p0 ? 1.0 : -1.0;
    int k = 0;
    while (k + 1 < n && s * (ori_motion_frame_drive(mo, k + 1) - x) <= 0.0) k++;
    if (drive) *drive = x;
    const double *a0 = ori_motion_frame_angles(mo, k);
    if (k + 1 == n || ori_motion_frame_drive(mo, k) == x) {
        memcpy(angles, a0, sizeof(double) * (size_t)E);
        if (positions) ori_motion_frame_vertices(mo, k, positions);
        return ORI_OK;
    }
    ori_motion_def d = *t->def;
    d.progress = NULL; // the fold's own progress: not for a state between its frames
    d.progress_user = NULL;
    d.start_angles_rad = a0;
    d.has_from = false;
    d.to_rad = x;
    d.step_rad = fabs(x - a0[d.driven_edge]);
    if (!(d.step_rad > 0.0)) {
        memcpy(angles, a0, sizeof(double) * (size_t)E);
        if (positions) ori_mechanism_vertex_positions(t->mechanism, a0, d.fixed_face, d.fixed_pose, positions);
        return ORI_OK;
    }
    ori_motion *trial = NULL;
    ori_status st = ori_motion_solve(t->mechanism, &d, &trial, error);
    if (st != ORI_OK) return st;
    int nf = ori_motion_frame_count(trial);
    if (nf == 0 || ori_motion_frame_drive(trial, nf - 1) != x) {
        ori_motion_destroy(trial);
        return ori__fail_at(error, ORI_ERR_NOT_CONVERGED, "edges_vertices", d.driven_edge,
                            "the state at drive %.9g rad between two steps could not be solved", x);
    }
    memcpy(angles, ori_motion_frame_angles(trial, nf - 1), sizeof(double) * (size_t)E);
    if (positions) ori_motion_frame_vertices(trial, nf - 1, positions);
    ori_motion_destroy(trial);
    return ORI_OK;
}

ori_status ori_trajectory_at(const ori_trajectory *t, double x, double *angles_rad, ori_v3 *positions, double *drive,
                             ori_error *error)
{
    ORI_ASSERT(t && angles_rad);
    ori_error_clear(error);
    double first, last;
    if (!ori_trajectory_param_range(t, &first, &last))
        return ori__fail(error, ORI_ERR_RANGE, "the motion has no frames: no state at %g", x);
    double lo = fmin(first, last), hi = fmax(first, last);
    if (!(x >= lo && x <= hi)) return ori__fail(error, ORI_ERR_RANGE, "%g is outside the frames' [%g, %g]", x, lo, hi);
    switch (t->kind) {
    case ORI_TRAJECTORY_MOTION: return motion_at(t, x, angles_rad, positions, drive, error);
    case ORI_TRAJECTORY_MULTIFOLD: {
        ori_status st = ori_multifold_at(t->multifold, t->locked_edges, t->locked_count, x, angles_rad, positions, error);
        if (st == ORI_OK && drive) *drive = x;
        return st;
    }
    case ORI_TRAJECTORY_RECORD:
    default: return ori_record_at(t->record, x, angles_rad, positions, drive, NULL, NULL, error);
    }
}
