// States of the document as the render, export and collide commands load them: a frame of the
// document (a folded form as it is, a crease pattern posed from its fold angles), an instant of
// the sequence, a state of the computed fold, or the first contact of either. POST /api/collide
// checks one of them for self-collision (what `orikin collide --json` prints) and GET
// /api/contact gives the state at a motion's first contact.
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "studio_internal.h"

static void copy_string(char *dst, size_t size, const char *src)
{
    snprintf(dst, size, "%s", src ? src : "");
}

static void *xcalloc(size_t n, size_t size) { return calloc(n ? n : 1, size); }

static studio_seq *seq_ref(studio *s)
{
    pthread_mutex_lock(&s->lock);
    studio_seq *q = s->seq;
    if (q) atomic_fetch_add(&q->refs, 1);
    pthread_mutex_unlock(&s->lock);
    return q;
}

static studio_fold *fold_ref(studio *s)
{
    pthread_mutex_lock(&s->lock);
    studio_fold *f = s->fold;
    if (f) atomic_fetch_add(&f->refs, 1);
    pthread_mutex_unlock(&s->lock);
    return f;
}

// --- which state --------------------------------------------------------------------------------

static bool set_contact(const char *v, studio_state_ref *ref, studio_response *out)
{
    if (strcmp(v, "fold") == 0) ref->contact_of_sequence = false;
    else if (strcmp(v, "sequence") == 0) ref->contact_of_sequence = true;
    else {
        studio_fail(out, 400, "contact: \"fold\" or \"sequence\"");
        return false;
    }
    ref->kind = STUDIO_STATE_CONTACT;
    return true;
}

bool studio_state_ref_args(const studio_request *req, studio_state_ref *ref, studio_response *out)
{
    memset(ref, 0, sizeof *ref);
    const char *keys[] = {"frame", "t", "k", "contact", "compliant"};
    int given = 0;
    for (int i = 0; i < 5; ++i) given += studio_arg_get(req, keys[i]) != NULL;
    if (given > 1) {
        studio_fail(out, 400, "name one state: frame, t, k, contact or compliant");
        return false;
    }
    const char *v;
    char *end;
    if ((v = studio_arg_get(req, "frame"))) {
        long x = strtol(v, &end, 10);
        if (end == v || *end || x < 0 || x > 1000000000L) {
            studio_fail(out, 400, "frame: must be a frame number >= 0");
            return false;
        }
        ref->kind = STUDIO_STATE_FRAME;
        ref->frame = (int)x;
    } else if ((v = studio_arg_get(req, "t"))) {
        double x = strtod(v, &end);
        if (end == v || *end || !isfinite(x)) {
            studio_fail(out, 400, "t: must be a number");
            return false;
        }
        ref->kind = STUDIO_STATE_TIME;
        ref->t = x;
    } else if ((v = studio_arg_get(req, "k"))) {
        long x = strtol(v, &end, 10);
        if (end == v || *end || x < 0 || x > 1000000000L) {
            studio_fail(out, 400, "k: must be a state number >= 0");
            return false;
        }
        ref->kind = STUDIO_STATE_FOLD;
        ref->k = (int)x;
    } else if ((v = studio_arg_get(req, "contact"))) {
        return set_contact(v, ref, out);
    } else if ((v = studio_arg_get(req, "compliant"))) {
        if (strcmp(v, "1") != 0) {
            studio_fail(out, 400, "compliant: 1 (the end of the last compliant fold)");
            return false;
        }
        ref->kind = STUDIO_STATE_COMPLIANT;
    }
    return true;
}

bool studio_state_ref_json(json_t *o, studio_state_ref *ref, studio_response *out)
{
    memset(ref, 0, sizeof *ref);
    const char *keys[] = {"frame", "t", "k", "contact"};
    int given = 0;
    for (int i = 0; i < 4; ++i) given += json_object_get(o, keys[i]) != NULL;
    if (given > 1) {
        studio_fail(out, 400, "name one state: frame, t, k or contact");
        return false;
    }
    bool has = false;
    const char *c = NULL;
    if (!studio_get_int(o, "frame", false, &ref->frame, &has, out)) return false;
    if (has) {
        if (ref->frame < 0) {
            studio_fail(out, 400, "frame: must be a frame number >= 0");
            return false;
        }
        return true;
    }
    if (!studio_get_number(o, "t", false, &ref->t, &has, out)) return false;
    if (has) {
        ref->kind = STUDIO_STATE_TIME;
        return true;
    }
    if (!studio_get_int(o, "k", false, &ref->k, &has, out)) return false;
    if (has) {
        if (ref->k < 0) {
            studio_fail(out, 400, "k: must be a state number >= 0");
            return false;
        }
        ref->kind = STUDIO_STATE_FOLD;
        return true;
    }
    if (!studio_get_string(o, "contact", false, &c, out)) return false;
    return c ? set_contact(c, ref, out) : true;
}

// --- loading ------------------------------------------------------------------------------------

void studio_state_free(studio_state *st)
{
    ori_mechanism_destroy(st->own_mech);
    ori_pattern_destroy(st->own);
    studio_model_unref(st->model);
    free(st->positions);
    free(st->angles);
    free(st->poses);
    memset(st, 0, sizeof *st);
}

static bool is_flat_pattern(const ori_pattern *p) { return !ori_pattern_is_folded_form(p) && !ori_pattern_is_3d(p); }

static bool same_topology(const ori_pattern *a, const ori_pattern *b)
{
    return ori_pattern_vertex_count(a) == ori_pattern_vertex_count(b) && ori_pattern_edge_count(a) == ori_pattern_edge_count(b) &&
           ori_pattern_face_count(a) == ori_pattern_face_count(b);
}

// A document frame, as orikin render / export load it (cli/state_args.c): a crease-pattern
// frame posed from its own fold angles (fixed face 0), a folded form as it is, drawn on frame
// 0's crease pattern when it is a state of it.
static bool load_frame(studio *s, int frame, bool need_pose, studio_state *st, studio_response *out)
{
    ori_pattern *pf = NULL;
    ori_error err;
    pthread_mutex_lock(&s->lock);
    int frames = ori_fold_frame_count(s->doc);
    if (frame >= frames) {
        pthread_mutex_unlock(&s->lock);
        studio_fail(out, 400, "frame %d does not exist (frames 0 to %d)", frame, frames - 1);
        return false;
    }
    st->model = studio_model_ref(s->model);
    ori_status gs = ORI_OK;
    if (frame != 0) {
        ori_build_def bd = ori_default_build_def();
        bd.check_planarity = false;
        gs = ori_fold_get_pattern(s->doc, frame, &bd, &pf, &err);
    }
    pthread_mutex_unlock(&s->lock);
    if (gs != ORI_OK) {
        char line[400];
        ori_error_format(&err, line, sizeof line);
        studio_fail(out, 400, "frame %d: %s", frame, line);
        return false;
    }
    const ori_pattern *p0 = st->model->pattern;
    const ori_pattern *p = pf ? pf : p0;
    st->frame = frame;
    snprintf(st->label, sizeof st->label, "frame %d", frame);
    int nv = ori_pattern_vertex_count(p), ne = ori_pattern_edge_count(p), nf = ori_pattern_face_count(p);
    if (is_flat_pattern(p)) {
        st->own = pf;
        st->pattern = p;
        st->has_flat = st->cp_frame = st->posed = true;
        st->angles = xcalloc((size_t)ne, sizeof(double));
        for (int e = 0; e < ne; ++e) {
            st->angles[e] = ori_pattern_edge(p, e).fold_angle_rad;
            if (st->angles[e] != 0.0) st->folded = true;
        }
        if (!need_pose) return true;
        st->positions = xcalloc((size_t)nv, sizeof(ori_v3));
        st->poses = xcalloc((size_t)nf, sizeof(ori_rigid));
        if (!st->folded) {
            for (int v = 0; v < nv; ++v) st->positions[v] = ori_pattern_vertex(p, v);
            for (int f = 0; f < nf; ++f) st->poses[f] = ori_rigid_identity();
            return true;
        }
        const ori_mechanism *m = NULL;
        if (pf) {
            ori_mechanism_def md = ori_default_mechanism_def();
            md.pattern = pf;
            if (ori_mechanism_create(&md, &st->own_mech, &err) == ORI_OK) m = st->own_mech;
        } else {
            m = studio_model_mechanism(st->model, &err);
        }
        if (!m) {
            char line[400];
            ori_error_format(&err, line, sizeof line);
            studio_fail(out, 400, "frame %d: %s", frame, line);
            return false;
        }
        double *closed = xcalloc((size_t)ne, sizeof(double));
        ori_status ps = ori_mechanism_pose_state(m, st->angles, 0, ori_rigid_identity(), closed, st->positions, st->poses, &err);
        if (ps == ORI_OK) memcpy(st->angles, closed, sizeof(double) * (size_t)ne);
        free(closed);
        if (ps == ORI_ERR_ARGUMENT) {
            studio_fail(out, 400,
                        "frame %d: its edges_foldAngle are not a folded state (the loops around the vertices do not close)",
                        frame);
            return false;
        }
        if (ps != ORI_OK) {
            studio_fail_error(out, studio_status_of(ps), &err);
            return false;
        }
        return true;
    }
    // a folded form
    st->folded = true;
    st->positions = xcalloc((size_t)nv, sizeof(ori_v3));
    for (int v = 0; v < nv; ++v) st->positions[v] = ori_pattern_vertex(p, v);
    if (ori_pattern_has_fold_angles(p)) {
        st->angles = xcalloc((size_t)ne, sizeof(double));
        for (int e = 0; e < ne; ++e) st->angles[e] = ori_pattern_edge(p, e).fold_angle_rad;
    }
    st->own = pf;
    st->collide_pattern = p;
    if (pf && is_flat_pattern(p0) && same_topology(p0, pf)) {
        st->pattern = p0;
        st->has_flat = true;
        st->poses = cli_poses_from_positions(studio_model_mechanism(st->model, NULL), st->positions);
    } else {
        st->pattern = p;
    }
    if (ori_pattern_face_count(st->collide_pattern) == 0) {
        studio_fail(out, 400, "faces_vertices: frame %d is a folded form without faces", frame);
        return false;
    }
    return true;
}

// Face poses of a sequence state: forward kinematics from its fold's fixed face, placed where
// the state has that face (as orikin render / export pose a sequence).
static void sequence_poses(const ori_mechanism *m, const ori_sequence *seq, int fold, const double *angles,
                           const ori_v3 *pos, ori_rigid *poses)
{
    cli_pose_faces(m, ori_sequence_fold_at(seq, fold).fixed_face, angles, pos, poses);
}

static void alloc_state(studio_state *st, const ori_mechanism *m)
{
    st->positions = xcalloc((size_t)ori_mechanism_vertex_count(m), sizeof(ori_v3));
    st->angles = xcalloc((size_t)ori_mechanism_edge_count(m), sizeof(double));
    st->poses = xcalloc((size_t)ori_mechanism_face_count(m), sizeof(ori_rigid));
}

// The sequence at time t, restored exactly (ori_record_at, as orikin render --at does).
static bool load_time(studio *s, double t, studio_state *st, studio_response *out)
{
    studio_seq *q = seq_ref(s);
    if (!q) {
        studio_fail(out, 409, "t: no sequence has run on this document");
        return false;
    }
    double duration = ori_record_duration(q->record);
    bool ok = true;
    if (!(t >= 0.0 && t <= duration) || duration == 0.0) {
        studio_fail(out, 400, "t: time %g is outside [0, %g]", t, duration);
        ok = false;
    } else if (cli_collides(&q->collision) && !(t < q->collision.ev.time)) {
        studio_fail(out, 409, "t: the sequence collides at t = %.9g: later states are not clean (contact=sequence shows the contact)",
                    q->collision.ev.time);
        ok = false;
    }
    if (ok) {
        const ori_mechanism *m = q->model->mech;
        st->model = studio_model_ref(q->model);
        st->pattern = q->model->pattern;
        st->has_flat = st->posed = st->folded = true;
        st->frame = -1;
        snprintf(st->label, sizeof st->label, "t = %g", t);
        alloc_state(st, m);
        int fold = 0;
        ori_error err;
        pthread_mutex_lock(&q->lock);
        ori_status rs = ori_record_at(q->record, t, st->angles, st->positions, NULL, &fold, NULL, &err);
        pthread_mutex_unlock(&q->lock);
        if (rs != ORI_OK) {
            studio_fail_error(out, studio_status_of(rs), &err);
            ok = false;
        } else {
            sequence_poses(m, q->sequence, fold, st->angles, st->positions, st->poses);
        }
    }
    studio_seq_unref(q);
    return ok;
}

static bool load_fold_state(studio *s, int k, studio_state *st, studio_response *out)
{
    studio_fold *f = fold_ref(s);
    if (!f) {
        studio_fail(out, 409, "k: no fold has been computed on this document");
        return false;
    }
    bool ok = k < f->clean_frames;
    if (!ok) {
        studio_fail(out, 400, "k: no state %d (the fold has states 0 to %d%s)", k, f->clean_frames - 1,
                    cli_collides(&f->collision) ? ": it collides after them" : "");
    } else {
        const ori_mechanism *m = f->model->mech;
        st->model = studio_model_ref(f->model);
        st->pattern = f->model->pattern;
        st->has_flat = st->posed = st->folded = true;
        st->frame = -1;
        snprintf(st->label, sizeof st->label, "fold state %d", k);
        alloc_state(st, m);
        if (f->multi) { // a fold mode
            memcpy(st->angles, ori_multifold_frame_angles(f->multi, k), sizeof(double) * (size_t)ori_mechanism_edge_count(m));
            ori_multifold_frame_vertices(f->multi, k, st->positions);
            ori_mechanism_face_poses(m, st->angles, f->def.fixed_face, f->def.fixed_pose, st->poses);
        } else {
            ori_motion_frame_vertices(f->motion, k, st->positions);
            ori_motion_frame_face_poses(f->motion, k, st->poses);
            memcpy(st->angles, ori_motion_frame_angles(f->motion, k), sizeof(double) * (size_t)ori_mechanism_edge_count(m));
        }
    }
    studio_fold_unref(f);
    return ok;
}

static bool load_contact(studio *s, bool of_sequence, studio_state *st, studio_response *out)
{
    studio_seq *q = of_sequence ? seq_ref(s) : NULL;
    studio_fold *f = of_sequence ? NULL : fold_ref(s);
    const studio_contact *c = q ? &q->contact : f ? &f->contact : NULL;
    studio_model *model = q ? q->model : f ? f->model : NULL;
    bool ok = c && c->has;
    if (!q && !f) studio_fail(out, 409, "contact: no %s has run on this document", of_sequence ? "sequence" : "fold");
    else if (!ok) studio_fail(out, 409, "contact: the %s does not collide", of_sequence ? "sequence" : "fold");
    if (ok) {
        const ori_mechanism *m = model->mech;
        st->model = studio_model_ref(model);
        st->pattern = model->pattern;
        st->has_flat = st->posed = st->folded = true;
        st->frame = -1;
        snprintf(st->label, sizeof st->label, "first contact of the %s", of_sequence ? "sequence" : "fold");
        alloc_state(st, m);
        memcpy(st->positions, c->positions, sizeof(ori_v3) * (size_t)ori_mechanism_vertex_count(m));
        memcpy(st->angles, c->angles, sizeof(double) * (size_t)ori_mechanism_edge_count(m));
        if (q) sequence_poses(m, q->sequence, c->fold, st->angles, st->positions, st->poses);
        else ori_mechanism_face_poses(m, st->angles, f->def.fixed_face, f->def.fixed_pose, st->poses);
    }
    studio_seq_unref(q);
    studio_fold_unref(f);
    return ok;
}

// The end of the last compliant fold (its faces bend: no face poses).
static bool load_compliant_state(studio *s, studio_state *st, studio_response *out)
{
    studio_cfold *f = studio_cfold_get(s);
    if (!f) {
        studio_fail(out, 409, "compliant=1: no compliant fold has been solved on this document");
        return false;
    }
    const ori_pattern *p = f->model->pattern;
    int V = ori_pattern_vertex_count(p), E = ori_pattern_edge_count(p);
    st->model = studio_model_ref(f->model);
    st->pattern = p;
    st->has_flat = st->folded = true;
    st->frame = -1;
    st->positions = malloc(sizeof(ori_v3) * (size_t)(V + 1));
    st->angles = malloc(sizeof(double) * (size_t)(E + 1));
    memcpy(st->positions, ori_compliant_positions(f->c), sizeof(ori_v3) * (size_t)V);
    for (int e = 0; e < E; ++e) st->angles[e] = ori_compliant_fold_angle(f->c, e);
    snprintf(st->label, sizeof st->label, "compliant fold, %.6g %%", 100.0 * ori_compliant_fraction(f->c));
    studio_cfold_unref(f);
    return true;
}

bool studio_state_load(studio *s, const studio_state_ref *ref, bool need_pose, studio_state *st, studio_response *out)
{
    memset(st, 0, sizeof *st);
    bool ok;
    switch (ref->kind) {
    case STUDIO_STATE_TIME: ok = load_time(s, ref->t, st, out); break;
    case STUDIO_STATE_FOLD: ok = load_fold_state(s, ref->k, st, out); break;
    case STUDIO_STATE_CONTACT: ok = load_contact(s, ref->contact_of_sequence, st, out); break;
    case STUDIO_STATE_COMPLIANT: ok = load_compliant_state(s, st, out); break;
    case STUDIO_STATE_FRAME:
    default: ok = load_frame(s, ref->frame, need_pose, st, out); break;
    }
    if (!ok) studio_state_free(st);
    else if (!st->collide_pattern) st->collide_pattern = st->pattern;
    return ok;
}

// --- GET /api/contact ------------------------------------------------------------------------------

void studio_api_contact(studio *s, const studio_request *req, studio_response *out)
{
    const char *of = studio_arg_get(req, "of");
    if (!of || (strcmp(of, "fold") != 0 && strcmp(of, "sequence") != 0)) {
        studio_fail(out, 400, "of: \"fold\" or \"sequence\"");
        return;
    }
    bool of_sequence = strcmp(of, "sequence") == 0;
    studio_seq *q = of_sequence ? seq_ref(s) : NULL;
    studio_fold *f = of_sequence ? NULL : fold_ref(s);
    const studio_contact *c = q ? &q->contact : f ? &f->contact : NULL;
    const cli_collision *col = q ? &q->collision : f ? &f->collision : NULL;
    const ori_mechanism *m = q ? q->model->mech : f ? f->model->mech : NULL;
    if (!q && !f) {
        studio_fail(out, 409, "no %s has run on this document", of);
    } else if (!cli_collides(col)) {
        studio_fail(out, 409, "the %s does not collide%s", of, col->checked ? "" : " (it was not checked)");
    } else if (!c->has) {
        studio_fail(out, 500, "the state at the first contact could not be solved again");
    } else {
        int V = ori_mechanism_vertex_count(m), E = ori_mechanism_edge_count(m);
        const char *b = studio_arg_get(req, "binary");
        if (b && strcmp(b, "1") == 0) {
            size_t size;
            char *body = studio_state_binary(c->t, c->fold, c->drive_rad, c->residual, c->positions, V, c->angles, E, &size);
            studio_respond_text(out, 200, "application/octet-stream", body, size);
            free(body);
        } else {
            json_t *o = json_object();
            json_object_set_new(o, "of", json_string(of));
            json_object_set_new(o, "collision", cli_collision_json(col, of_sequence));
            json_object_set_new(o, "t", json_real(c->t));
            json_object_set_new(o, "fold", json_integer(c->fold + 1));
            // NaN: a fold toward the targets (no drive angle)
            json_object_set_new(o, "drive_deg", isnan(c->drive_rad) ? json_null() : json_real(ori_rad_to_deg_output(c->drive_rad)));
            json_t *ang = json_array(), *pos = json_array();
            for (int e = 0; e < E; ++e) json_array_append_new(ang, json_real(ori_rad_to_deg_output(c->angles[e])));
            for (int v = 0; v < V; ++v)
                json_array_append_new(pos, json_pack("[fff]", c->positions[v].x, c->positions[v].y, c->positions[v].z));
            json_object_set_new(o, "fold_angles_deg", ang);
            json_object_set_new(o, "residual", json_real(c->residual));
            json_object_set_new(o, "vertices_coords", pos);
            studio_respond_json(out, 200, o);
        }
    }
    studio_seq_unref(q);
    studio_fold_unref(f);
}

// --- POST /api/collide -------------------------------------------------------------------------------

void studio_api_collide(studio *s, const studio_request *req, studio_response *out)
{
    json_t *o = studio_body_object(req, out);
    if (!o) return;
    static const char *const keys[] = {"frame", "t", "k", "contact", "compliant", "clearance", "cloud", NULL};
    studio_state_ref ref;
    double clearance = 0.0, spacing = 0.0;
    bool has_cloud = false;
    if (json_object_get(o, "compliant")) { // (as orikin collide FILE --compliant)
        json_decref(o);
        studio_fail(out, 400, "a compliant fold bends its faces, which collide checks as planar panels: the compliant "
                              "fold itself warns of the faces that pass through each other (its contacts)");
        return;
    }
    bool ok = studio_check_keys(o, keys, out) && studio_state_ref_json(o, &ref, out) &&
              studio_get_number(o, "clearance", false, &clearance, NULL, out) &&
              studio_get_number(o, "cloud", false, &spacing, &has_cloud, out);
    json_decref(o);
    if (!ok) return;
    if (!(clearance >= 0.0)) {
        studio_fail(out, 400, "clearance: must be a length >= 0, got %g", clearance);
        return;
    }
    if (has_cloud && !(spacing > 0.0)) {
        studio_fail(out, 400, "cloud: needs a sample spacing > 0, got %g", spacing);
        return;
    }
    if (!studio_job_begin(s, "collide", out)) return;
    char file[STUDIO_PATH_MAX];
    pthread_mutex_lock(&s->lock);
    copy_string(file, sizeof file, s->file);
    pthread_mutex_unlock(&s->lock);
    studio_state st;
    if (studio_state_load(s, &ref, true, &st, out)) {
        ori_collider *c = studio_collider(st.collide_pattern, clearance, out);
        ori_collision_result r;
        ori_cloud_result cr;
        ori_error err;
        double distance = clearance > 0.0 ? clearance : spacing;
        bool done = c != NULL;
        if (done && ori_collider_check(c, st.positions, &r, &err) != ORI_OK) {
            studio_fail_error(out, 400, &err);
            done = false;
        }
        if (done && has_cloud) {
            ori_cloud_def cl = ori_default_cloud_def();
            cl.spacing = spacing;
            cl.distance = distance;
            ori_status cs = ori_collider_cloud(c, st.positions, &cl, &cr, &err);
            if (cs != ORI_OK) {
                if (cs == ORI_ERR_RANGE) studio_fail(out, 400, "cloud: %s", err.message);
                else studio_fail_error(out, studio_status_of(cs), &err);
                done = false;
            }
        }
        if (done) {
            json_t *j = cli_collide_json(file, st.frame, NULL, st.posed, c, &r, clearance, has_cloud ? &cr : NULL, spacing,
                                            distance);
            json_object_set_new(j, "state", json_string(st.label));
            studio_respond_json(out, 200, j);
        }
        ori_collider_destroy(c);
        studio_state_free(&st);
    }
    studio_job_end(s);
}
