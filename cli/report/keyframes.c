// A motion as keyframes, one way for the CLI (orikin export --animate, orikin animate) and the
// studio (GET /api/export of=fold|sequence): the same frames, times and face poses.
#include "report.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void *zalloc(size_t n, size_t size)
{
    void *p = calloc(n ? n : 1, size);
    if (!p) abort(); // (the front ends' policy for small bookkeeping: out of memory ends the run)
    return p;
}

void cli_motion_alloc(cli_motion *m, int count, int vertex_count, int face_count, int edge_count, bool poses,
                      bool angles)
{
    memset(m, 0, sizeof *m);
    m->count = count;
    m->vertex_count = vertex_count;
    m->face_count = face_count;
    m->edge_count = edge_count;
    m->times = zalloc((size_t)count, sizeof(double));
    m->positions = zalloc((size_t)count * (size_t)vertex_count, sizeof(ori_v3));
    m->poses = poses ? zalloc((size_t)count * (size_t)face_count, sizeof(ori_rigid)) : NULL;
    m->angles = angles ? zalloc((size_t)count * (size_t)edge_count, sizeof(double)) : NULL;
}

void cli_motion_free(cli_motion *m)
{
    free(m->times);
    free(m->positions);
    free(m->poses);
    free(m->angles);
    free(m->sources);
    memset(m, 0, sizeof *m);
}

static void alloc_for(cli_motion *m, const ori_mechanism *mech, int count)
{
    cli_motion_alloc(m, count, ori_mechanism_vertex_count(mech), ori_mechanism_face_count(mech),
                     ori_mechanism_edge_count(mech), true, true);
}

static double *frame_angles(cli_motion *m, int i) { return m->angles + (size_t)i * (size_t)m->edge_count; }
static ori_v3 *frame_positions(cli_motion *m, int i) { return m->positions + (size_t)i * (size_t)m->vertex_count; }
static ori_rigid *frame_poses(cli_motion *m, int i) { return m->poses + (size_t)i * (size_t)m->face_count; }

ori_status cli_motion_of_fold(const ori_mechanism *mech, const ori_motion_def *def, const ori_motion *motion,
                              double from_rad, int samples, cli_motion *m, ori_error *err)
{
    memset(m, 0, sizeof *m);
    const ori_motion *mo = motion;
    ori_motion *resolved = NULL;
    double to = def->to_rad, from = from_rad;
    if (samples >= 2 && to != from) {
        // solved again with the output steps at the samples: every frame exact
        ori_motion_def d = *def;
        d.step_rad = fabs(to - from) / (samples - 1);
        ori_status st = ori_motion_solve(mech, &d, &resolved, err);
        if (st != ORI_OK) return st;
        if (ori_motion_verdict_of(resolved) != ORI_MOTION_VALID) {
            ori_motion_destroy(resolved);
            ori_error_clear(err);
            err->status = ORI_ERR_NOT_CONVERGED;
            snprintf(err->message, sizeof err->message, "the fold's motion at %d frames is not valid", samples);
            return err->status;
        }
        mo = resolved;
    }
    int n = ori_motion_frame_count(mo);
    alloc_for(m, mech, n);
    for (int i = 0; i < n; ++i) {
        double d = ori_motion_frame_drive(mo, i);
        m->times[i] = to != from ? (d - from) / (to - from) : (double)i;
        ori_motion_frame_vertices(mo, i, frame_positions(m, i));
        ori_motion_frame_face_poses(mo, i, frame_poses(m, i));
        memcpy(frame_angles(m, i), ori_motion_frame_angles(mo, i), sizeof(double) * (size_t)m->edge_count);
    }
    m->duration = n ? m->times[n - 1] - m->times[0] : 0.0;
    ori_motion_destroy(resolved);
    return ORI_OK;
}

ori_status cli_motion_of_multifold(const ori_mechanism *mech, const ori_multifold *mf, const int *locks, int nlocks,
                                   int fixed_face, int samples, ori_progress_fn *progress, void *user, cli_motion *m,
                                   ori_error *err)
{
    memset(m, 0, sizeof *m);
    int n = ori_multifold_frame_count(mf);
    if (n == 0) {
        ori_error_clear(err);
        err->status = ORI_ERR_RANGE;
        snprintf(err->message, sizeof err->message, "the fold has no frames");
        return err->status;
    }
    int count = samples >= 2 ? samples : n;
    alloc_for(m, mech, count);
    double p0 = ori_multifold_frame_progress(mf, 0), p1 = ori_multifold_frame_progress(mf, n - 1);
    for (int i = 0; i < count; ++i) {
        if (samples < 2) {
            m->times[i] = ori_multifold_frame_progress(mf, i);
            ori_multifold_frame_vertices(mf, i, frame_positions(m, i));
            memcpy(frame_angles(m, i), ori_multifold_frame_angles(mf, i), sizeof(double) * (size_t)m->edge_count);
        } else {
            double t = i == count - 1 ? p1 : p0 + (p1 - p0) * i / (count - 1);
            m->times[i] = t;
            ori_status st = ori_multifold_at(mf, locks, nlocks, t, frame_angles(m, i), frame_positions(m, i), err);
            if (st != ORI_OK) {
                cli_motion_free(m);
                return st;
            }
            if (progress) progress((double)(i + 1) / count, user);
        }
        cli_pose_faces(mech, fixed_face, frame_angles(m, i), frame_positions(m, i), frame_poses(m, i));
    }
    m->duration = m->times[count - 1] - m->times[0];
    return ORI_OK;
}

ori_status cli_motion_of_compliant(const ori_compliant *c, int samples, cli_motion *m, ori_error *err)
{
    memset(m, 0, sizeof *m);
    int n = ori_compliant_frame_count(c);
    if (n < 2) {
        ori_error_clear(err);
        err->status = ORI_ERR_RANGE;
        snprintf(err->message, sizeof err->message,
                 "the compliant fold recorded one state: nothing to animate (a static fold records its load steps; "
                 "--dynamic its end)");
        return err->status;
    }
    int V = ori_compliant_vertex_count(c), E = ori_compliant_edge_count(c), F = ori_compliant_face_count(c);
    int count = samples >= 2 ? samples : n;
    cli_motion_alloc(m, count, V, F, E, false, true);
    m->sources = zalloc((size_t)count, sizeof(int));
    // timed by the fraction (load steps), or by the explicit time (a dynamic fold's history)
    bool timed = ori_compliant_frame_time(c, n - 1) > 0.0;
    double (*at)(const ori_compliant *, int) = timed ? ori_compliant_frame_time : ori_compliant_frame_fraction;
    double f0 = at(c, 0), f1 = at(c, n - 1);
    int j = 0;
    for (int i = 0; i < count; ++i) {
        double t = samples >= 2 ? f0 + (f1 - f0) * i / (count - 1) : at(c, i);
        if (samples >= 2)
            while (j + 1 < n && fabs(at(c, j + 1) - t) <= fabs(at(c, j) - t)) j++;
        int k = samples >= 2 ? j : i;
        m->times[i] = t;
        m->sources[i] = k;
        memcpy(frame_positions(m, i), ori_compliant_frame_positions(c, k), sizeof(ori_v3) * (size_t)V);
        memcpy(frame_angles(m, i), ori_compliant_frame_angles(c, k), sizeof(double) * (size_t)E);
    }
    m->duration = m->times[count - 1] - m->times[0];
    return ORI_OK;
}

ori_status cli_motion_of_record(const ori_mechanism *mech, const ori_sequence *seq, const ori_record *r, int samples,
                                ori_progress_fn *progress, void *user, cli_motion *m, ori_error *err)
{
    memset(m, 0, sizeof *m);
    double duration = ori_record_duration(r);
    int count = samples >= 2 ? samples : ori_record_frame_count(r);
    alloc_for(m, mech, count);
    m->duration = duration;
    for (int i = 0; i < count; ++i) {
        int fold = 0;
        if (samples < 2) {
            m->times[i] = ori_record_frame_time(r, i);
            fold = ori_record_frame_fold(r, i);
            memcpy(frame_positions(m, i), ori_record_frame_vertices(r, i), sizeof(ori_v3) * (size_t)m->vertex_count);
            memcpy(frame_angles(m, i), ori_record_frame_angles(r, i), sizeof(double) * (size_t)m->edge_count);
        } else {
            double t = i == count - 1 ? duration : duration * i / (count - 1);
            m->times[i] = t;
            ori_status st = ori_record_at(r, t, frame_angles(m, i), frame_positions(m, i), NULL, &fold, NULL, err);
            if (st != ORI_OK) {
                cli_motion_free(m);
                return st;
            }
            if (progress) progress((double)(i + 1) / count, user);
        }
        cli_pose_faces(mech, ori_sequence_fold_at(seq, fold).fixed_face, frame_angles(m, i), frame_positions(m, i),
                   frame_poses(m, i));
    }
    return ORI_OK;
}
