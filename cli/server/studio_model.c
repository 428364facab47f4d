// The studio's models and computed results: a pattern with its mechanism built once (shared
// by reference between the document, the undo stack and running jobs), and the reference counts
// of the fold, sequence and contact results; a frame of the document as a state. The lowest
// layer of the document: it calls only the request helpers.
#define _DEFAULT_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "studio_internal.h"

static void copy_string(char *dst, size_t size, const char *src)
{
    snprintf(dst, size, "%s", src ? src : "");
}

// --- models and results --------------------------------------------------------------------

studio_model *studio_model_new(ori_pattern *pattern)
{
    studio_model *m = calloc(1, sizeof *m);
    atomic_init(&m->refs, 1);
    m->pattern = pattern;
    pthread_mutex_init(&m->lock, NULL);
    return m;
}

studio_model *studio_model_ref(studio_model *m)
{
    if (m) atomic_fetch_add(&m->refs, 1);
    return m;
}

void studio_model_unref(studio_model *m)
{
    if (!m || atomic_fetch_sub(&m->refs, 1) != 1) return;
    ori_mechanism_destroy(m->mech);
    ori_pattern_destroy(m->pattern);
    pthread_mutex_destroy(&m->lock);
    free(m);
}

const ori_mechanism *studio_model_mechanism(studio_model *m, ori_error *error)
{
    pthread_mutex_lock(&m->lock);
    if (!m->mech_tried) {
        m->mech_tried = true;
        ori_error_clear(&m->mech_error);
        if (ori_pattern_is_folded_form(m->pattern) || ori_pattern_is_3d(m->pattern)) {
            m->mech_error.status = ORI_ERR_ARGUMENT;
            copy_string(m->mech_error.message, sizeof m->mech_error.message,
                        "frame 0 is a folded form: the kinematics needs the flat crease pattern there");
        } else {
            ori_mechanism_def md = ori_default_mechanism_def();
            md.pattern = m->pattern;
            if (ori_mechanism_create(&md, &m->mech, &m->mech_error) != ORI_OK) m->mech = NULL;
        }
    }
    const ori_mechanism *mech = m->mech;
    if (!mech && error) *error = m->mech_error;
    pthread_mutex_unlock(&m->lock);
    return mech;
}

void studio_contact_free(studio_contact *c)
{
    free(c->angles);
    free(c->positions);
    memset(c, 0, sizeof *c);
}

void studio_seq_unref(studio_seq *q)
{
    if (!q || atomic_fetch_sub(&q->refs, 1) != 1) return;
    // records refer to the mechanism: destroy them before the model
    ori_record_destroy(q->fine);
    ori_record_destroy(q->record);
    ori_sequence_destroy(q->sequence);
    studio_model_unref(q->model);
    pthread_mutex_destroy(&q->lock);
    studio_contact_free(&q->contact);
    free(q->json);
    free(q);
}

void studio_fold_unref(studio_fold *f)
{
    if (!f || atomic_fetch_sub(&f->refs, 1) != 1) return;
    ori_motion_destroy(f->motion);
    ori_multifold_destroy(f->multi);
    studio_model_unref(f->model);
    studio_contact_free(&f->contact);
    free(f->start_angles);
    free(f->locks);
    free(f);
}

// --- a frame of the document as a state -------------------------------------------------------

bool studio_frame_state(studio *s, int frame, double **angles, ori_v3 **coords, bool *folded, studio_response *out)
{
    const ori_pattern *flat = s->model->pattern;
    int E = ori_pattern_edge_count(flat), V = ori_pattern_vertex_count(flat);
    int frames = ori_fold_frame_count(s->doc);
    if (frame < 0 || frame >= frames) {
        studio_fail(out, 400, "frame %d does not exist (frames 0 to %d)", frame, frames - 1);
        return false;
    }
    ori_pattern *other = NULL;
    const ori_pattern *state = flat;
    if (frame != 0) {
        ori_build_def bd = ori_default_build_def();
        bd.check_planarity = false;
        ori_error e;
        if (ori_fold_get_pattern(s->doc, frame, &bd, &other, &e) != ORI_OK) {
            char line[400];
            studio_error_line(line, sizeof line, &e);
            studio_fail(out, 400, "frame %d: %s", frame, line);
            return false;
        }
        if (ori_pattern_edge_count(other) != E || ori_pattern_vertex_count(other) != V) {
            ori_pattern_destroy(other);
            studio_fail(out, 400, "frame %d has different vertices or edges from frame 0: not a state of the same pattern",
                        frame);
            return false;
        }
        state = other;
    }
    // As the CLI: a flat crease-pattern frame is the flat state whatever its edges_foldAngle
    // says (there the angles are targets); a folded frame gives the start angles.
    bool folded_state = ori_pattern_is_folded_form(state) || ori_pattern_is_3d(state);
    *angles = calloc((size_t)E + 1, sizeof(double));
    *coords = calloc((size_t)V + 1, sizeof(ori_v3));
    for (int e = 0; e < E; ++e) (*angles)[e] = folded_state ? ori_pattern_edge(state, e).fold_angle_rad : 0.0;
    for (int v = 0; v < V; ++v) (*coords)[v] = ori_pattern_vertex(state, v);
    *folded = ori_pattern_is_3d(state);
    ori_pattern_destroy(other);
    return true;
}
