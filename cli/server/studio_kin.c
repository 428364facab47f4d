// Kinematics endpoints: the mechanism and its bone structure, degrees of freedom, a fold
// (exactly what `orikin fold --json` prints), fold sequences (what `orikin sequence --json`
// prints) and any instant of one (what `orikin sequence --at T --json` prints). Long
// computations take the job slot and run on a reference to the document's model, outside the
// document lock; their result is published only when the document has not changed meanwhile.
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "studio_internal.h"

static void copy_string(char *dst, size_t size, const char *src)
{
    snprintf(dst, size, "%s", src ? src : "");
}

static bool parse_number_arg(const studio_request *req, const char *key, double *out, bool *present, studio_response *res)
{
    const char *v = studio_arg_get(req, key);
    *present = v != NULL;
    if (!v) return true;
    char *end;
    double x = strtod(v, &end);
    if (end == v || *end || !isfinite(x)) {
        studio_fail(res, 400, "%s: must be a number", key);
        return false;
    }
    *out = x;
    return true;
}

static bool binary_requested(const studio_request *req)
{
    const char *b = studio_arg_get(req, "binary");
    return b && strcmp(b, "1") == 0;
}

// Index checks the library would otherwise assert on: face and edges of a fold.
static bool check_fold_indices(const ori_mechanism *m, const char *where, int fix, int drive, bool targets,
                               const int *locks, int lock_count, studio_response *out)
{
    int faces = ori_mechanism_face_count(m), edges = ori_mechanism_edge_count(m);
    if (fix < 0 || fix >= faces) {
        studio_fail(out, 400, "%sfaces_vertices %d: no face %d (the pattern has faces 0 to %d)", where, fix, fix, faces - 1);
        return false;
    }
    if (!(targets && drive == ORI_NULL_INDEX) && (drive < 0 || drive >= edges)) { // a fold toward the targets drives none
        studio_fail(out, 400, "%sedges_vertices %d: no edge %d (the pattern has edges 0 to %d)", where, drive, drive,
                    edges - 1);
        return false;
    }
    for (int i = 0; i < lock_count; ++i)
        if (locks[i] < 0 || locks[i] >= edges) {
            studio_fail(out, 400, "%sedges_vertices %d: no edge %d to lock (the pattern has edges 0 to %d)", where, locks[i],
                        locks[i], edges - 1);
            return false;
        }
    return true;
}

static double elements_of(const ori_mechanism *m)
{
    return (double)ori_mechanism_vertex_count(m) + (double)ori_mechanism_edge_count(m) +
           (double)ori_mechanism_face_count(m);
}

// Output frames of a fold driven over range_deg at step_deg: the start, one per step, the last
// on the target (a last step shorter than ORI_KIN_GRID_MERGE of a step merges into it).
static double frames_of(double range_deg, double step_deg)
{
    return ceil(fabs(range_deg) / step_deg - ORI_KIN_GRID_MERGE) + 1.0;
}

// The world pose of the fixed face at the start: identity for a flat start, the rigid fit of
// its vertices for a folded one.
static bool start_pose(const ori_mechanism *m, int face, bool folded, const ori_v3 *coords, ori_rigid *pose,
                       studio_response *out)
{
    *pose = ori_rigid_identity();
    if (!folded) return true;
    ori_error err;
    if (ori_mechanism_face_pose_from_coords(m, face, coords, pose, &err) != ORI_OK) {
        studio_fail_error(out, 400, &err);
        return false;
    }
    return true;
}

// --- self-collision of a fold or a sequence (as orikin fold / sequence check it) --------------

ori_collider *studio_collider(const ori_pattern *p, double clearance, studio_response *out)
{
    ori_collider_def cd = ori_default_collider_def();
    cd.pattern = p;
    cd.clearance = clearance;
    ori_collider *c = NULL;
    ori_error err;
    if (ori_collider_create(&cd, &c, &err) != ORI_OK) {
        if (err.status == ORI_ERR_RANGE) studio_fail(out, 400, "clearance: must be a length >= 0, got %g", clearance);
        else studio_fail_error(out, 400, &err);
        return NULL;
    }
    return c;
}

// no_collisions (true: the motion is not checked) and clearance (a length >= 0) of a JSON body.
static bool collide_opts_json(json_t *o, studio_collide_opts *c, studio_response *out)
{
    c->skip = false;
    c->clearance = 0.0;
    if (!studio_get_bool(o, "no_collisions", &c->skip, out) ||
        !studio_get_number(o, "clearance", false, &c->clearance, NULL, out))
        return false;
    if (!(c->clearance >= 0.0)) {
        studio_fail(out, 400, "clearance: must be a length >= 0, got %g", c->clearance);
        return false;
    }
    return true;
}

// The same as query arguments: no_collisions=1 (or true), clearance=D.
static bool collide_opts_args(const studio_request *req, studio_collide_opts *c, studio_response *out)
{
    c->skip = false;
    c->clearance = 0.0;
    const char *v = studio_arg_get(req, "no_collisions");
    if (v) {
        if (strcmp(v, "1") == 0 || strcmp(v, "true") == 0) c->skip = true;
        else if (strcmp(v, "0") != 0 && strcmp(v, "false") != 0) {
            studio_fail(out, 400, "no_collisions: 1 or 0");
            return false;
        }
    }
    bool has;
    if (!parse_number_arg(req, "clearance", &c->clearance, &has, out)) return false;
    if (!(c->clearance >= 0.0)) {
        studio_fail(out, 400, "clearance: must be a length >= 0, got %g", c->clearance);
        return false;
    }
    return true;
}

static void contact_alloc(studio_contact *c, int E, int V)
{
    c->angles = calloc((size_t)E + 1, sizeof(double));
    c->positions = calloc((size_t)V + 1, sizeof(ori_v3));
}

// The state at a fold's first contact: solved from the last clean state to the event's drive
// angle in one step, as the collision check's bisection solves it.
static void fold_contact(const ori_mechanism *m, const ori_motion_def *def, const ori_motion *mo, const cli_collision *col,
                         studio_contact *c)
{
    int E = ori_mechanism_edge_count(m), V = ori_mechanism_vertex_count(m);
    const ori_collision_event *ev = &col->ev;
    const double *lo = ori_motion_frame_angles(mo, ev->frame > 0 ? ev->frame - 1 : 0);
    ori_motion_def d = *def;
    d.start_angles_rad = lo;
    d.has_from = false;
    d.to_rad = ev->drive_rad;
    d.step_rad = fabs(ev->drive_rad - lo[d.driven_edge]);
    contact_alloc(c, E, V);
    if (!(d.step_rad > 0.0)) {
        memcpy(c->angles, lo, sizeof(double) * (size_t)E);
        ori_mechanism_vertex_positions(m, lo, d.fixed_face, d.fixed_pose, c->positions);
        c->residual = ori_mechanism_residual(m, lo);
    } else {
        ori_motion *x = NULL;
        ori_error err;
        int n = 0;
        if (ori_motion_solve(m, &d, &x, &err) != ORI_OK || (n = ori_motion_frame_count(x)) == 0 ||
            ori_motion_frame_drive(x, n - 1) != ev->drive_rad) {
            ori_motion_destroy(x);
            studio_contact_free(c);
            return;
        }
        memcpy(c->angles, ori_motion_frame_angles(x, n - 1), sizeof(double) * (size_t)E);
        ori_motion_frame_vertices(x, n - 1, c->positions);
        c->residual = ori_motion_frame_residual(x, n - 1);
        ori_motion_destroy(x);
    }
    c->has = true;
    c->t = ev->time;
    c->fold = 0;
    c->drive_rad = ev->drive_rad;
}

// The state at a sequence's first contact: restored at the event's time.
static void record_contact(const ori_mechanism *m, const ori_record *r, const cli_collision *col, studio_contact *c)
{
    contact_alloc(c, ori_mechanism_edge_count(m), ori_mechanism_vertex_count(m));
    ori_error err;
    if (ori_record_at(r, col->ev.time, c->angles, c->positions, &c->drive_rad, &c->fold, &c->residual, &err) != ORI_OK) {
        studio_contact_free(c);
        return;
    }
    c->has = true;
    c->t = col->ev.time;
}

// --- sequence states: the scrubbing cache, or an exact restore ----------------------------------

static studio_seq *seq_ref(studio *s)
{
    pthread_mutex_lock(&s->lock);
    studio_seq *q = s->seq;
    if (q) atomic_fetch_add(&q->refs, 1);
    pthread_mutex_unlock(&s->lock);
    return q;
}

// The cache state at time t (within STUDIO_TIME_SNAP), or -1.
static int cache_frame(const ori_record *fine, double t)
{
    int lo = 0, hi = ori_record_frame_count(fine) - 1;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (ori_record_frame_time(fine, mid) < t) lo = mid + 1;
        else hi = mid;
    }
    for (int k = lo - 1; k <= lo; ++k)
        if (k >= 0 && fabs(ori_record_frame_time(fine, k) - t) <= STUDIO_TIME_SNAP) return k;
    return -1;
}

static ori_status seq_state_at(studio_seq *q, double t, double *angles, ori_v3 *pos, double *drive, int *fold,
                               double *residual, ori_error *err)
{
    int k = q->fine ? cache_frame(q->fine, t) : -1;
    if (k >= 0) {
        int E = ori_mechanism_edge_count(q->model->mech), V = ori_mechanism_vertex_count(q->model->mech);
        memcpy(angles, ori_record_frame_angles(q->fine, k), sizeof(double) * (size_t)E);
        memcpy(pos, ori_record_frame_vertices(q->fine, k), sizeof(ori_v3) * (size_t)V);
        *drive = ori_record_frame_drive(q->fine, k);
        *fold = ori_record_frame_fold(q->fine, k);
        *residual = ori_record_frame_residual(q->fine, k);
        return ORI_OK;
    }
    pthread_mutex_lock(&q->lock);
    ori_status st = ori_record_at(q->record, t, angles, pos, drive, fold, residual, err);
    pthread_mutex_unlock(&q->lock);
    return st;
}

// --- mechanism, DOF ------------------------------------------------------------------------------

void studio_api_mechanism(studio *s, const studio_request *req, studio_response *out)
{
    double fix_d = 0;
    bool has_fix;
    if (!parse_number_arg(req, "fix", &fix_d, &has_fix, out)) return;
    pthread_mutex_lock(&s->lock);
    studio_model *model = studio_model_ref(s->model);
    pthread_mutex_unlock(&s->lock);
    ori_error err;
    const ori_mechanism *m = studio_model_mechanism(model, &err);
    if (!m) {
        studio_model_unref(model);
        studio_fail_error(out, 400, &err);
        return;
    }
    int F = ori_mechanism_face_count(m);
    if (has_fix && !(fix_d == floor(fix_d) && fix_d >= 0 && fix_d < F)) {
        studio_model_unref(model);
        studio_fail(out, 400, "fix: no face %g (the pattern has faces 0 to %d)", fix_d, F - 1);
        return;
    }
    json_t *o = json_object();
    json_object_set_new(o, "faces", json_integer(F));
    json_object_set_new(o, "grubler", json_integer(ori_mechanism_grubler(m)));
    static const char *const kinds[] = {"revolute", "flat", "rigid"};
    json_t *joints = json_array();
    for (int j = 0; j < ori_mechanism_joint_count(m); ++j) {
        ori_joint jt = ori_mechanism_joint(m, j);
        json_array_append_new(joints, json_pack("{s:i,s:i,s:i,s:s}", "edge", jt.edge, "face_left", jt.face_left,
                                                "face_right", jt.face_right, "kind", kinds[jt.kind]));
    }
    json_object_set_new(o, "joints", joints);
    json_t *bones = json_array();
    for (int b = 0; b < ori_mechanism_bone_count(m); ++b) {
        ori_bone bn = ori_mechanism_bone(m, b);
        json_array_append_new(bones, json_pack("{s:i,s:i,s:[fff],s:[fff]}", "face", bn.face, "edge", bn.edge, "from",
                                               bn.from.x, bn.from.y, bn.from.z, "to", bn.to.x, bn.to.y, bn.to.z));
    }
    json_object_set_new(o, "bones", bones);
    json_t *loops = json_array();
    int cap = 16;
    int *buf = malloc(sizeof(int) * (size_t)cap);
    for (int l = 0; l < ori_mechanism_loop_count(m); ++l) {
        ori_loop lp = ori_mechanism_loop(m, l);
        if (lp.crease_count > cap) {
            cap = lp.crease_count;
            buf = realloc(buf, sizeof(int) * (size_t)cap);
        }
        int n = ori_mechanism_loop_edges(m, l, buf, cap);
        json_t *cr = json_array();
        for (int i = 0; i < n && i < cap; ++i) json_array_append_new(cr, json_integer(buf[i]));
        json_array_append_new(loops, json_pack("{s:o,s:o}", "vertex", lp.vertex >= 0 ? json_integer(lp.vertex) : json_null(),
                                               "creases", cr));
    }
    free(buf);
    json_object_set_new(o, "loops", loops);
    if (has_fix) {
        int *pf = malloc(sizeof(int) * (size_t)(F + 1)), *pe = malloc(sizeof(int) * (size_t)(F + 1));
        ori_mechanism_spanning_tree(m, (int)fix_d, pf, pe);
        json_t *jf = json_array(), *je = json_array();
        for (int f = 0; f < F; ++f) {
            json_array_append_new(jf, json_integer(pf[f]));
            json_array_append_new(je, json_integer(pe[f]));
        }
        json_object_set_new(o, "spanning_tree", json_pack("{s:i,s:o,s:o}", "root", (int)fix_d, "parent_face", jf,
                                                          "parent_edge", je));
        free(pf);
        free(pe);
    }
    studio_model_unref(model);
    studio_respond_json(out, 200, o);
}

void studio_api_dof(studio *s, const studio_request *req, studio_response *out)
{
    json_t *o = studio_body_object(req, out);
    if (!o) return;
    static const char *const keys[] = {"lock", "frame", "t", NULL};
    int locks[STUDIO_MAX_LOCKS], nlock = 0, frame = 0;
    double t = 0;
    bool has_t = false;
    if (!studio_check_keys(o, keys, out) || !studio_get_int_list(o, "lock", locks, STUDIO_MAX_LOCKS, &nlock, out) ||
        !studio_get_int(o, "frame", false, &frame, NULL, out) || !studio_get_number(o, "t", false, &t, &has_t, out)) {
        json_decref(o);
        return;
    }
    json_decref(o);
    if (!studio_job_begin(s, "degrees of freedom", out)) return;
    char file[STUDIO_PATH_MAX];
    double *angles = NULL;
    ori_v3 *coords = NULL;
    bool folded = false;
    studio_seq *q = NULL;
    pthread_mutex_lock(&s->lock);
    studio_model *model = studio_model_ref(s->model);
    copy_string(file, sizeof file, s->file);
    bool ok = true;
    if (has_t) {
        q = s->seq;
        if (q) atomic_fetch_add(&q->refs, 1);
        else studio_fail(out, 409, "t: no sequence has run");
        ok = q != NULL;
    } else {
        ok = studio_frame_state(s, frame, &angles, &coords, &folded, out);
    }
    pthread_mutex_unlock(&s->lock);
    ori_error err;
    const ori_mechanism *m = ok ? studio_model_mechanism(model, &err) : NULL;
    if (ok && !m) {
        studio_fail_error(out, 400, &err);
        ok = false;
    }
    if (ok) {
        int E = ori_mechanism_edge_count(m);
        for (int i = 0; i < nlock && ok; ++i)
            if (locks[i] < 0 || locks[i] >= E) {
                studio_fail(out, 400, "edges_vertices %d: no edge %d to lock (the pattern has edges 0 to %d)", locks[i],
                            locks[i], E - 1);
                ok = false;
            }
    }
    if (ok && q) {
        if (!(t >= 0 && t <= ori_record_duration(q->record))) {
            studio_fail(out, 400, "t: time %g is outside [0, %g]", t, ori_record_duration(q->record));
            ok = false;
        } else {
            angles = calloc((size_t)ori_mechanism_edge_count(m) + 1, sizeof(double));
            coords = calloc((size_t)ori_mechanism_vertex_count(m) + 1, sizeof(ori_v3));
            double drive, res;
            int fold;
            ori_status st = seq_state_at(q, t, angles, coords, &drive, &fold, &res, &err);
            if (st != ORI_OK) {
                studio_fail_error(out, studio_status_of(st), &err);
                ok = false;
            }
        }
    }
    if (ok) {
        ori_dof_def def = ori_default_dof_def();
        def.angles_rad = angles;
        def.locked_edges = locks;
        def.locked_count = nlock;
        ori_dof_result r;
        ori_status st = ori_mechanism_dof(m, &def, &r, &err);
        if (st != ORI_OK) studio_fail_error(out, studio_status_of(st), &err);
        else studio_respond_json(out, 200, studio_json_dof(file, frame, &r, ori_mechanism_loop_count(m)));
    }
    free(angles);
    free(coords);
    studio_seq_unref(q);
    studio_model_unref(model);
    studio_job_end(s);
}

// --- a fold --------------------------------------------------------------------------------------

static bool parse_solver(json_t *o, ori_solver *solver, ori_linear *linear, studio_response *out)
{
    const char *sv = NULL, *lv = NULL;
    if (!studio_get_string(o, "solver", false, &sv, out) || !studio_get_string(o, "linear", false, &lv, out)) return false;
    *solver = ORI_SOLVER_AUTO;
    *linear = ORI_LINEAR_AUTO;
    if (sv) {
        if (strcmp(sv, "auto") == 0) *solver = ORI_SOLVER_AUTO;
        else if (strcmp(sv, "analytic") == 0) *solver = ORI_SOLVER_ANALYTIC;
        else if (strcmp(sv, "numeric") == 0) *solver = ORI_SOLVER_NUMERIC;
        else {
            studio_fail(out, 400, "solver: auto, analytic or numeric");
            return false;
        }
    }
    if (lv) {
        if (strcmp(lv, "auto") == 0) *linear = ORI_LINEAR_AUTO;
        else if (strcmp(lv, "dense") == 0) *linear = ORI_LINEAR_DENSE;
        else if (strcmp(lv, "sparse") == 0) *linear = ORI_LINEAR_SPARSE;
        else if (strcmp(lv, "sweep") == 0) *linear = ORI_LINEAR_SWEEP;
        else {
            studio_fail(out, 400, "linear: auto, dense, sparse or sweep");
            return false;
        }
    }
    return true;
}

// The fold request: fix, drive, to, step, from, lock, frame, after_sequence, solver, linear.
// A face may be named ("Obj1212") and a crease given as "@x,y" (the crease through that point):
// the references are kept until the document's model is known.
typedef struct fold_request {
    studio_fold_spec spec;
    int frame;
    bool after_sequence;
    studio_collide_opts collide;
    ori_solver solver;
    ori_linear linear;
    bool lock_auto;                         // "lock": "auto" (orikin fold --lock auto with one drive)
    json_t *fix_ref, *drive_ref, *lock_ref; // borrowed from the request body
} fold_request;

// A crease: an index, or "@x,y". False after a 400.
static bool crease_ref(const ori_pattern *p, json_t *v, const char *what, int *out, studio_response *res)
{
    if (json_is_integer(v) && json_integer_value(v) >= -2147483647LL && json_integer_value(v) <= 2147483647LL) {
        *out = (int)json_integer_value(v);
        return true;
    }
    double x, y;
    char tail;
    const char *t = json_is_string(v) ? json_string_value(v) : NULL;
    if (!t || t[0] != '@' || sscanf(t + 1, "%lf,%lf%c", &x, &y, &tail) != 2 || !isfinite(x) || !isfinite(y)) {
        studio_fail(res, 400, "%s: an edge index or \"@x,y\"", what);
        return false;
    }
    *out = ori_pattern_find_edge_at(p, ori_v2_make(x, y));
    if (*out == ORI_NULL_INDEX) {
        studio_fail(res, 400, "%s: no edge passes through (%g, %g)", what, x, y);
        return false;
    }
    return true;
}

// Resolve the fold's face and crease references against the document's pattern.
static bool resolve_fold(const ori_pattern *p, fold_request *f, studio_response *out)
{
    json_t *fix = f->fix_ref;
    if (json_is_string(fix)) {
        f->spec.fix = ori_pattern_find_face_by_name(p, json_string_value(fix));
        if (f->spec.fix == ORI_NULL_INDEX) {
            studio_fail(out, 400, "fix: no face named %.64s", json_string_value(fix));
            return false;
        }
    } else if (json_is_integer(fix) && json_integer_value(fix) >= -2147483647LL && json_integer_value(fix) <= 2147483647LL) {
        f->spec.fix = (int)json_integer_value(fix);
    } else {
        studio_fail(out, 400, "fix: a face index or name");
        return false;
    }
    if (!crease_ref(p, f->drive_ref, "drive", &f->spec.drive, out)) return false;
    f->spec.lock_count = 0;
    f->lock_auto = json_is_string(f->lock_ref) && strcmp(json_string_value(f->lock_ref), "auto") == 0;
    if (f->lock_ref && !f->lock_auto) {
        if (!json_is_array(f->lock_ref) || json_array_size(f->lock_ref) > STUDIO_MAX_LOCKS) {
            studio_fail(out, 400, "lock: \"auto\" or an array of at most %d edges (indices or \"@x,y\")", STUDIO_MAX_LOCKS);
            return false;
        }
        for (size_t i = 0; i < json_array_size(f->lock_ref); ++i)
            if (!crease_ref(p, json_array_get(f->lock_ref, i), "lock", &f->spec.locks[f->spec.lock_count++], out)) return false;
    }
    return true;
}

static bool parse_fold(json_t *o, fold_request *f, studio_response *out)
{
    static const char *const keys[] = {"fix", "drive", "to", "step", "from", "lock", "frame", "after_sequence", "solver",
                                       "linear", "no_collisions", "clearance", NULL};
    memset(f, 0, sizeof *f);
    f->spec.step_deg = 10.0;
    f->fix_ref = json_object_get(o, "fix");
    f->drive_ref = json_object_get(o, "drive");
    f->lock_ref = json_object_get(o, "lock");
    if (!studio_check_keys(o, keys, out)) return false;
    if (!f->fix_ref || !f->drive_ref) {
        studio_fail(out, 400, "%s: missing", f->fix_ref ? "drive" : "fix");
        return false;
    }
    if (!studio_get_number(o, "to", true, &f->spec.to_deg, NULL, out) ||
        !studio_get_number(o, "step", false, &f->spec.step_deg, NULL, out) ||
        !studio_get_number(o, "from", false, &f->spec.from_deg, &f->spec.has_from, out) ||
        !studio_get_int(o, "frame", false, &f->frame, NULL, out) ||
        !studio_get_bool(o, "after_sequence", &f->after_sequence, out) || !parse_solver(o, &f->solver, &f->linear, out) ||
        !collide_opts_json(o, &f->collide, out))
        return false;
    if (!(fabs(f->spec.to_deg) <= 180.0)) {
        studio_fail(out, 400, "to: %g is outside [-180, 180] degrees", f->spec.to_deg);
        return false;
    }
    if (f->spec.has_from && !(fabs(f->spec.from_deg) <= 180.0)) {
        studio_fail(out, 400, "from: %g is outside [-180, 180] degrees", f->spec.from_deg);
        return false;
    }
    if (!(f->spec.step_deg > 0.0)) {
        studio_fail(out, 400, "step must be a positive angle in degrees, got %g", f->spec.step_deg);
        return false;
    }
    if (f->frame < 0) {
        studio_fail(out, 400, "frame: must be a frame number >= 0");
        return false;
    }
    if (f->after_sequence && f->frame != 0) {
        studio_fail(out, 400, "give frame or after_sequence, not both");
        return false;
    }
    return true;
}

// "lock": "auto" with one drive: the lock set that leaves the drive one degree of freedom
// (ori_mechanism_lock_set), then the ordinary fold with those locks, as orikin fold does.
static bool auto_locks(const ori_mechanism *m, const double *angles, fold_request *f, studio_response *out)
{
    int E = ori_mechanism_edge_count(m);
    int *locks = malloc(sizeof(int) * (size_t)(E + 1));
    ori_error err;
    int n = ori_mechanism_lock_set(m, angles, &f->spec.drive, 1, NULL, 0, NULL, locks, E + 1, &err);
    bool ok = true;
    if (n < 0) {
        studio_fail_error(out, 400, &err);
        ok = false;
    } else if (n == 0) {
        studio_fail(out, 400, "lock auto: nothing to lock, the drive leaves no freedom");
        ok = false;
    } else if (n > STUDIO_MAX_LOCKS) {
        studio_fail(out, 400, "lock auto: %d creases to lock, more than the studio's %d", n, STUDIO_MAX_LOCKS);
        ok = false;
    } else {
        memcpy(f->spec.locks, locks, sizeof(int) * (size_t)n);
        f->spec.lock_count = n;
    }
    free(locks);
    return ok;
}

// A computed fold on model, for GET /api/fold/frame: def as solved, with its own copies of the
// start angles (E) and of the def.locked_count locks.
static studio_fold *new_fold(studio_model *model, const ori_motion_def *def, const double *angles, int E, const int *locks)
{
    studio_fold *res = calloc(1, sizeof *res);
    atomic_init(&res->refs, 1);
    res->model = studio_model_ref(model);
    res->def = *def;
    res->start_angles = malloc(sizeof(double) * (size_t)(E + 1));
    memcpy(res->start_angles, angles, sizeof(double) * (size_t)E);
    res->def.start_angles_rad = res->start_angles;
    res->locks = malloc(sizeof(int) * (size_t)(def->locked_count + 1));
    memcpy(res->locks, locks, sizeof(int) * (size_t)def->locked_count);
    res->def.locked_edges = res->locks;
    return res;
}

// Make res the document's fold unless the document changed while it was computed.
static void publish_fold(studio *s, long version, studio_fold *res)
{
    pthread_mutex_lock(&s->lock);
    if (s->version == version) {
        studio_fold_unref(s->fold);
        s->fold = res;
        res = NULL;
    }
    pthread_mutex_unlock(&s->lock);
    studio_fold_unref(res);
}

// --- the fold modes (orikin fold --percent, several drives, --symmetric, --lock auto) ------

// A body asking for a mode: "percent", "symmetric": true, or "drive" as an array.
static bool wants_mode(json_t *o)
{
    return json_object_get(o, "percent") || json_is_true(json_object_get(o, "symmetric")) ||
           json_is_array(json_object_get(o, "drive"));
}

#define MODES_MAX 256 // drives and locks of a mode (as orikin fold takes)

// The mode's fields as orikin fold's options: {fix (default: the face at the centre), percent |
// drive: [E…] and to: [A…], step, lock: [E…] | "auto", symmetric, frame, no_collisions,
// clearance}. The creases and face are resolved against p.
typedef struct modes_request {
    int fix;
    bool has_percent, lock_auto, symmetric;
    double percent, step_deg;
    int drives[MODES_MAX], ndrives;
    double to[MODES_MAX];
    int locks[MODES_MAX], nlocks;
    int frame;
    studio_collide_opts collide;
} modes_request;

static bool parse_modes(json_t *o, const ori_pattern *p, modes_request *q, studio_response *out)
{
    static const char *const keys[] = {"fix", "drive", "to", "percent", "step", "lock", "symmetric", "frame",
                                       "no_collisions", "clearance", "from", "solver", "linear", "after_sequence", NULL};
    memset(q, 0, sizeof *q);
    q->step_deg = 10.0;
    if (!studio_check_keys(o, keys, out)) return false;
    for (const char *const *k = (const char *const[]){"from", "solver", "linear", "after_sequence", NULL}; *k; ++k)
        if (json_object_get(o, *k)) {
            studio_fail(out, 400, "%s applies to a single drive, not with percent, several drives or symmetric", *k);
            return false;
        }
    bool has_to;
    if (!studio_get_number(o, "percent", false, &q->percent, &q->has_percent, out) ||
        !studio_get_number(o, "step", false, &q->step_deg, NULL, out) || !studio_get_bool(o, "symmetric", &q->symmetric, out) ||
        !studio_get_int(o, "frame", false, &q->frame, NULL, out) || !collide_opts_json(o, &q->collide, out))
        return false;
    if (q->has_percent && !(q->percent >= 0.0 && q->percent <= 100.0)) {
        studio_fail(out, 400, "percent needs a number from 0 to 100, got %g", q->percent);
        return false;
    }
    if (!(q->step_deg > 0.0)) {
        studio_fail(out, 400, "step must be a positive angle in degrees, got %g", q->step_deg);
        return false;
    }
    if (q->frame < 0) {
        studio_fail(out, 400, "frame: must be a frame number >= 0");
        return false;
    }
    json_t *fix = json_object_get(o, "fix");
    if (!fix) {
        q->fix = ori_pattern_center_face(p); // as orikin fold without --fix
    } else if (json_is_string(fix)) {
        q->fix = ori_pattern_find_face_by_name(p, json_string_value(fix));
        if (q->fix == ORI_NULL_INDEX) {
            studio_fail(out, 400, "fix: no face named %.64s", json_string_value(fix));
            return false;
        }
    } else if (json_is_integer(fix) && json_integer_value(fix) >= 0 && json_integer_value(fix) < ori_pattern_face_count(p)) {
        q->fix = (int)json_integer_value(fix);
    } else {
        studio_fail(out, 400, "fix: a face index (0 to %d) or name", ori_pattern_face_count(p) - 1);
        return false;
    }
    json_t *lock = json_object_get(o, "lock");
    q->lock_auto = json_is_string(lock) && strcmp(json_string_value(lock), "auto") == 0;
    if (lock && !q->lock_auto) {
        if (!json_is_array(lock) || json_array_size(lock) > MODES_MAX) {
            studio_fail(out, 400, "lock: \"auto\" or an array of at most %d edges (indices or \"@x,y\")", MODES_MAX);
            return false;
        }
        for (size_t i = 0; i < json_array_size(lock); ++i)
            if (!crease_ref(p, json_array_get(lock, i), "lock", &q->locks[q->nlocks++], out)) return false;
    }
    json_t *drive = json_object_get(o, "drive"), *to = json_object_get(o, "to");
    has_to = to != NULL;
    if (q->has_percent) {
        if (drive || has_to) {
            studio_fail(out, 400, "percent folds every crease toward its target: no drive or to with it");
            return false;
        }
        if (q->lock_auto) {
            studio_fail(out, 400, "lock auto applies to drives: percent needs no lock set");
            return false;
        }
        return true;
    }
    if (!drive) {
        studio_fail(out, 400, "drive: missing (or percent)");
        return false;
    }
    json_t *one = json_is_array(drive) ? NULL : drive;
    q->ndrives = one ? 1 : (int)json_array_size(drive);
    if (q->ndrives < 1 || q->ndrives > MODES_MAX) {
        studio_fail(out, 400, "drive: an edge or an array of 1 to %d edges (indices or \"@x,y\")", MODES_MAX);
        return false;
    }
    for (int i = 0; i < q->ndrives; ++i)
        if (!crease_ref(p, one ? one : json_array_get(drive, (size_t)i), "drive", &q->drives[i], out)) return false;
    int nto = json_is_array(to) ? (int)json_array_size(to) : has_to ? 1 : 0;
    if (nto != q->ndrives) {
        studio_fail(out, 400, "to has %d angles for %d driven creases", nto, q->ndrives);
        return false;
    }
    for (int i = 0; i < nto; ++i) {
        json_t *v = json_is_array(to) ? json_array_get(to, (size_t)i) : to;
        if (!json_is_number(v) || !(fabs(json_number_value(v)) <= 180.0)) {
            studio_fail(out, 400, "to: angles in [-180, 180] degrees");
            return false;
        }
        q->to[i] = json_number_value(v);
    }
    return true;
}

// POST /api/fold in a mode: the same solve, collision check and answer as orikin fold in that
// mode (cli/report/modes_report.c), kept for GET /api/fold/frame.
static void fold_modes_api(studio *s, json_t *o, studio_response *out)
{
    char file[STUDIO_PATH_MAX];
    double *angles = NULL;
    ori_v3 *coords = NULL;
    bool folded = false;
    pthread_mutex_lock(&s->lock);
    studio_model *model = studio_model_ref(s->model);
    long version = s->version;
    copy_string(file, sizeof file, s->file);
    pthread_mutex_unlock(&s->lock);
    modes_request q;
    bool ok = parse_modes(o, model->pattern, &q, out);
    if (ok) {
        pthread_mutex_lock(&s->lock);
        ok = studio_frame_state(s, q.frame, &angles, &coords, &folded, out);
        pthread_mutex_unlock(&s->lock);
    }
    ori_error err;
    const ori_mechanism *m = ok ? studio_model_mechanism(model, &err) : NULL;
    if (ok && !m) {
        studio_fail_error(out, 400, &err);
        ok = false;
    }
    ok = ok && check_fold_indices(m, "", q.fix, q.ndrives ? q.drives[0] : ORI_NULL_INDEX, q.has_percent, q.locks, q.nlocks, out);
    for (int i = 1; ok && i < q.ndrives; ++i) ok = check_fold_indices(m, "", q.fix, q.drives[i], false, NULL, 0, out);
    if (ok) { // the studio's limit on recorded states, from the largest crease change over the step
        int E = ori_mechanism_edge_count(m);
        double change = 0.0;
        if (q.has_percent) {
            double *tgt = malloc(sizeof(double) * (size_t)(E + 1));
            ori_target_angles_default(model->pattern, tgt);
            for (int e = 0; e < E; ++e) change = fmax(change, fabs(q.percent / 100.0 * (tgt[e] - angles[e])));
            free(tgt);
        } else {
            for (int i = 0; i < q.ndrives; ++i) change = fmax(change, fabs(ori_deg_to_rad(q.to[i]) - angles[q.drives[i]]));
        }
        double frames = frames_of(ori_rad_to_deg(change), q.step_deg);
        if (frames > STUDIO_MAX_FRAMES_PER_FOLD || frames * elements_of(m) > s->def.work_limit) {
            studio_fail(out, 400, "the fold would record %.0f states of %.0f elements; the studio's limit is %d states and "
                        "%.3g in all: use a larger step", frames, elements_of(m), STUDIO_MAX_FRAMES_PER_FOLD, s->def.work_limit);
            ok = false;
        }
    }
    ori_rigid pose = ori_rigid_identity();
    ok = ok && start_pose(m, q.fix, folded, coords, &pose, out);
    cli_modes x;
    memset(&x, 0, sizeof x);
    if (ok) {
        x.fix = q.fix;
        x.has_percent = q.has_percent;
        x.percent = q.percent;
        x.drives = q.drives;
        x.to_deg = q.to;
        x.ndrives = q.ndrives;
        x.given_locks = q.locks;
        x.ngiven = q.nlocks;
        x.lock_auto = q.lock_auto;
        x.symmetric = q.symmetric;
        x.step_deg = q.step_deg;
        x.mech = m;
        x.flat = model->pattern;
        x.start = angles;
        x.pose = pose;
        x.progress = studio_job_progress;
        x.progress_user = s;
        studio_job_phase(s, "fold: solving");
        ori_status st = cli_modes_solve(&x, &err);
        if (st != ORI_OK) {
            studio_fail_error(out, studio_status_of(st), &err);
            ok = false;
        }
    }
    if (ok) cli_modes_hint(&x, studio_job_progress, s);
    if (ok && !q.collide.skip) {
        // every step checked for self-collision (as orikin fold)
        ori_collider *c = studio_collider(model->pattern, q.collide.clearance, out);
        ok = c != NULL;
        if (ok) {
            studio_job_phase(s, "fold: checking collisions");
            ori_collision_motion_def cd = ori_default_collision_motion_def();
            cd.progress = studio_job_progress;
            cd.progress_user = s;
            ori_status st = ori_collision_check_multifold(c, x.mf, x.locks, x.nlocks, &cd, &x.col.ev, &err);
            ori_collider_destroy(c);
            x.col.checked = st == ORI_OK;
            x.col.progress = true;
            if (st != ORI_OK) {
                studio_fail_error(out, studio_status_of(st), &err);
                ok = false;
            }
        }
    }
    if (ok) {
        studio_respond_json(out, 200, cli_modes_json(&x, file));
        int E = ori_mechanism_edge_count(m), V = ori_mechanism_vertex_count(m);
        ori_motion_def def = ori_default_motion_def();
        def.fixed_face = q.fix;
        def.fixed_pose = pose;
        def.locked_count = x.nlocks;
        studio_fold *res = new_fold(model, &def, angles, E, x.locks);
        res->start_drive_rad = NAN;
        res->collision = x.col;
        res->clean_frames = cli_modes_shown_frames(&x);
        if (cli_collides(&x.col)) { // the state at first contact, at the event's progress
            studio_contact *c = &res->contact;
            contact_alloc(c, E, V);
            c->has = ori_multifold_at(x.mf, x.locks, x.nlocks, x.col.ev.drive_rad, c->angles, c->positions, &err) == ORI_OK;
            if (!c->has) studio_contact_free(c);
            c->t = x.col.ev.time;
            c->drive_rad = NAN;
            c->residual = c->has ? ori_mechanism_residual(m, c->angles) : 0.0;
        }
        res->multi = x.mf;
        x.mf = NULL;
        publish_fold(s, version, res);
    }
    cli_modes_free(&x);
    free(angles);
    free(coords);
    studio_model_unref(model);
}

void studio_api_fold(studio *s, const studio_request *req, studio_response *out)
{
    json_t *o = studio_body_object(req, out);
    if (!o) return;
    if (wants_mode(o)) {
        if (studio_job_begin(s, "fold", out)) {
            fold_modes_api(s, o, out);
            studio_job_end(s);
        }
        json_decref(o);
        return;
    }
    fold_request f;
    if (!parse_fold(o, &f, out) || !studio_job_begin(s, "fold", out)) {
        json_decref(o);
        return;
    }
    char file[STUDIO_PATH_MAX];
    double *angles = NULL;
    ori_v3 *coords = NULL;
    bool folded = false, ok = true;
    pthread_mutex_lock(&s->lock);
    studio_model *model = studio_model_ref(s->model);
    long version = s->version;
    copy_string(file, sizeof file, s->file);
    if (f.after_sequence) {
        // continue from where the sequence ends (the folding manager's "add a fold"): its last
        // clean state when it collides
        int frames = s->seq ? cli_collide_frames(&s->seq->collision, ori_record_frame_count(s->seq->record)) : 0;
        if (frames == 0) {
            studio_fail(out, 409, "after_sequence: no sequence has run");
            ok = false;
        } else {
            const ori_record *r = s->seq->record;
            int last = frames - 1;
            int E = ori_pattern_edge_count(model->pattern), V = ori_pattern_vertex_count(model->pattern);
            angles = malloc(sizeof(double) * (size_t)(E + 1));
            coords = malloc(sizeof(ori_v3) * (size_t)(V + 1));
            memcpy(angles, ori_record_frame_angles(r, last), sizeof(double) * (size_t)E);
            memcpy(coords, ori_record_frame_vertices(r, last), sizeof(ori_v3) * (size_t)V);
            folded = true;
        }
    } else {
        ok = studio_frame_state(s, f.frame, &angles, &coords, &folded, out);
    }
    pthread_mutex_unlock(&s->lock);
    ok = ok && resolve_fold(model->pattern, &f, out);
    json_decref(o);
    ori_error err;
    const ori_mechanism *m = ok ? studio_model_mechanism(model, &err) : NULL;
    if (ok && !m) {
        studio_fail_error(out, 400, &err);
        ok = false;
    }
    ok = ok && check_fold_indices(m, "", f.spec.fix, f.spec.drive, false, f.spec.locks, f.spec.lock_count, out);
    if (ok && f.lock_auto) ok = auto_locks(m, angles, &f, out);
    if (ok) {
        double start_deg = f.spec.has_from ? f.spec.from_deg : ori_rad_to_deg_output(angles[f.spec.drive]);
        double frames = frames_of(f.spec.to_deg - start_deg, f.spec.step_deg);
        double work = frames * elements_of(m);
        if (frames > STUDIO_MAX_FRAMES_PER_FOLD || work > s->def.work_limit) {
            studio_fail(out, 400, "the fold would record %.0f states of %.0f elements; the studio's limit is %d states and "
                        "%.3g in all: use a larger step", frames, elements_of(m), STUDIO_MAX_FRAMES_PER_FOLD, s->def.work_limit);
            ok = false;
        }
    }
    ori_motion_def def = ori_default_motion_def();
    ok = ok && start_pose(m, f.spec.fix, folded, coords, &def.fixed_pose, out);
    ori_motion *mo = NULL;
    if (ok) {
        def.fixed_face = f.spec.fix;
        def.start_angles_rad = angles;
        def.driven_edge = f.spec.drive;
        def.has_from = f.spec.has_from;
        def.from_rad = ori_deg_to_rad(f.spec.from_deg);
        def.to_rad = ori_deg_to_rad(f.spec.to_deg);
        def.step_rad = ori_deg_to_rad(f.spec.step_deg);
        def.locked_edges = f.spec.locks;
        def.locked_count = f.spec.lock_count;
        def.solver = f.solver;
        def.linear = f.linear;
        ori_status st = ori_motion_solve(m, &def, &mo, &err);
        if (st != ORI_OK) {
            studio_fail_error(out, studio_status_of(st), &err);
            ok = false;
        }
    }
    cli_collision col;
    memset(&col, 0, sizeof col);
    studio_contact contact;
    memset(&contact, 0, sizeof contact);
    if (ok && !f.collide.skip) {
        // every step checked for self-collision, the first contact located (as orikin fold)
        ori_collider *c = studio_collider(model->pattern, f.collide.clearance, out);
        ok = c != NULL;
        if (ok) {
            studio_job_phase(s, "fold: checking collisions");
            ori_status st = cli_collision_check_motion(c, m, &def, mo, studio_job_progress, s, &col, &err);
            ori_collider_destroy(c);
            if (st != ORI_OK) {
                studio_fail_error(out, studio_status_of(st), &err);
                ok = false;
            }
        }
        if (ok && cli_collides(&col)) fold_contact(m, &def, mo, &col, &contact);
    }
    if (ok) {
        char lock_hint[1024] = ""; // an underdetermined fold names a lock set (as orikin fold)
        if (ori_motion_verdict_of(mo) == ORI_MOTION_UNDERDETERMINED) cli_lock_hint(m, &def, lock_hint, sizeof lock_hint, NULL);
        cli_fold_fields fields = {file, f.spec.fix, f.spec.drive, f.spec.to_deg, f.spec.step_deg, f.spec.locks,
                                  f.spec.lock_count};
        studio_respond_json(out, 200, cli_fold_json(&fields, model->pattern, m, mo, &col, lock_hint));
        studio_fold *res = new_fold(model, &def, angles, ori_mechanism_edge_count(m), f.spec.locks);
        res->motion = mo;
        mo = NULL;
        res->start_drive_rad = f.spec.has_from ? def.from_rad : angles[f.spec.drive];
        res->collision = col;
        res->clean_frames = cli_collide_frames(&col, ori_motion_frame_count(res->motion));
        res->contact = contact;
        memset(&contact, 0, sizeof contact);
        publish_fold(s, version, res);
    }
    studio_contact_free(&contact);
    ori_motion_destroy(mo);
    free(angles);
    free(coords);
    studio_model_unref(model);
    studio_job_end(s);
}

void studio_api_fold_frame(studio *s, const studio_request *req, studio_response *out)
{
    double k_d = 0;
    bool has_k;
    if (!parse_number_arg(req, "k", &k_d, &has_k, out)) return;
    if (!has_k) {
        studio_fail(out, 400, "k: the frame number is needed");
        return;
    }
    pthread_mutex_lock(&s->lock);
    studio_fold *f = s->fold;
    if (f) atomic_fetch_add(&f->refs, 1);
    pthread_mutex_unlock(&s->lock);
    if (!f) {
        studio_fail(out, 409, "no fold has been computed on this document");
        return;
    }
    int n = f->clean_frames;
    if (!(k_d == floor(k_d) && k_d >= 0 && k_d < n)) {
        studio_fold_unref(f);
        studio_fail(out, 400, "k: no frame %g (the fold has frames 0 to %d%s)", k_d, n - 1,
                    cli_collides(&f->collision) ? ": it collides after them" : "");
        return;
    }
    int k = (int)k_d;
    const ori_mechanism *m = f->model->mech;
    int V = ori_mechanism_vertex_count(m), E = ori_mechanism_edge_count(m);
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)(V + 1));
    const double *ang;
    double drive, res;
    if (f->multi) { // a fold mode: no drive angle
        ori_multifold_frame_vertices(f->multi, k, pos);
        ang = ori_multifold_frame_angles(f->multi, k);
        drive = NAN;
        res = ori_multifold_frame_residual(f->multi, k);
    } else {
        ori_motion_frame_vertices(f->motion, k, pos);
        ang = ori_motion_frame_angles(f->motion, k);
        drive = ori_motion_frame_drive(f->motion, k);
        res = ori_motion_frame_residual(f->motion, k);
    }
    size_t size;
    bool binary = binary_requested(req);
    char *b = binary ? studio_state_binary((double)k, 0, drive, res, pos, V, ang, E, &size)
                     : studio_json_frame_text(k, drive, ang, E, res, pos, V, &size);
    free(out->body);
    out->status = 200;
    out->content_type = binary ? "application/octet-stream" : "application/json";
    out->body = b;
    out->size = size;
    free(pos);
    studio_fold_unref(f);
}

// --- sequences -----------------------------------------------------------------------------------

// The sequence's folds as SEQ.json text with every step replaced by range / n, for the first
// `folds` folds (those that completed), or NULL when a range is empty.
static char *fine_sequence_text(const ori_sequence *seq, const ori_record *r, int folds, int n)
{
    char *text = ori_sequence_to_json(seq);
    json_t *j = json_loads(text, 0, NULL);
    ori_buffer_free(text);
    json_t *arr = json_object_get(j, "folds");
    while ((int)json_array_size(arr) > folds) json_array_remove(arr, json_array_size(arr) - 1);
    int frame = 0; // the start state of fold k: the last recorded state before it
    bool empty = false;
    for (int k = 0; k < folds; ++k) {
        ori_sequence_fold f = ori_sequence_fold_at(seq, k);
        while (frame + 1 < ori_record_frame_count(r) && ori_record_frame_fold(r, frame + 1) < k) frame++;
        double from = f.has_from ? f.from_rad : ori_record_frame_angles(r, frame)[f.driven_edge];
        double range = fabs(f.to_rad - from);
        if (!(range > 0.0)) empty = true;
        json_object_set_new(json_array_get(arr, (size_t)k), "step", json_real(ori_rad_to_deg_output(range / n)));
    }
    char *out = empty ? NULL : json_dumps(j, JSON_COMPACT | JSON_REAL_PRECISION(17));
    json_decref(j);
    return out;
}

// The scrubbing cache: the completed folds again on a uniform grid of n states per fold (n a
// multiple of 8 within the memory budget and the work limit), every state solved exactly.
static ori_record *fine_record(const studio *s, const ori_sequence *seq, const ori_record *r, const ori_mechanism *m,
                               const double *start, ori_rigid pose, int *grid)
{
    *grid = 0;
    int folds = ori_record_completed_folds(r);
    if (folds == 0 || s->def.cache_bytes == 0) return NULL;
    // A fold toward the targets has no drive range to grid: its instants are restored exactly
    // (ori_record_at) without a cache.
    for (int k = 0; k < folds; ++k)
        if (ori_sequence_fold_at(seq, k).targets) return NULL;
    double per_state = 8.0 * ori_mechanism_edge_count(m) + 24.0 * ori_mechanism_vertex_count(m) + 64.0;
    double states = fmin((double)s->def.cache_bytes / per_state, s->def.work_limit / elements_of(m));
    int n = (int)fmin((double)STUDIO_GRID_MAX, floor((states - 1.0) / folds / 8.0) * 8.0);
    if (n < 8) return NULL;
    char *text = fine_sequence_text(seq, r, folds, n);
    if (!text) return NULL;
    ori_sequence *fs = NULL;
    ori_record *fine = NULL;
    ori_error err;
    if (ori_sequence_parse(text, strlen(text), &fs, &err) == ORI_OK &&
        ori_sequence_run(fs, m, start, pose, &fine, &err) == ORI_OK &&
        !(ori_record_verdict(fine) == ORI_MOTION_VALID && ori_record_completed_folds(fine) == folds)) {
        ori_record_destroy(fine);
        fine = NULL;
    }
    free(text);
    ori_sequence_destroy(fs);
    if (fine) *grid = n;
    return fine;
}

void studio_run_sequence(studio *s, ori_sequence *seq, const char *label, const studio_collide_opts *opts,
                         studio_response *out)
{
    if (!studio_job_begin(s, "sequence", out)) {
        ori_sequence_destroy(seq);
        return;
    }
    char file[STUDIO_PATH_MAX], name[STUDIO_PATH_MAX];
    copy_string(name, sizeof name, label && label[0] ? label : "studio");
    studio_utf8_clean(name);
    double *angles = NULL;
    ori_v3 *coords = NULL;
    bool folded = false;
    pthread_mutex_lock(&s->lock);
    studio_model *model = studio_model_ref(s->model);
    long version = s->version;
    copy_string(file, sizeof file, s->file);
    bool ok = studio_frame_state(s, ori_sequence_frame(seq), &angles, &coords, &folded, out);
    pthread_mutex_unlock(&s->lock);
    ori_error err;
    const ori_mechanism *m = ok ? studio_model_mechanism(model, &err) : NULL;
    if (ok && !m) {
        studio_fail_error(out, 400, &err);
        ok = false;
    }
    // faces by name or "@x,y" and creases by "@x,y" (as orikin sequence resolves them)
    if (ok && ori_sequence_resolve(seq, model->pattern, &err) != ORI_OK) {
        studio_fail_error(out, 400, &err);
        ok = false;
    }
    double work = 0.0;
    for (int k = 0; ok && k < ori_sequence_fold_count(seq); ++k) {
        ori_sequence_fold f = ori_sequence_fold_at(seq, k);
        char where[32];
        snprintf(where, sizeof where, "folds %d: ", k);
        ok = check_fold_indices(m, where, f.fixed_face, f.driven_edge, f.targets, f.locked, f.locked_count, out);
        if (!ok) break;
        // the start angle of a later fold is known only once the earlier ones ran: bound its range
        // (a fold toward the targets turns no crease by more than 360 deg, at most step per state)
        double start = f.targets ? 0.0
                       : f.has_from ? f.from_rad
                       : k == 0     ? angles[f.driven_edge]
                                    : (f.to_rad > 0 ? -ORI_PI : ORI_PI);
        double range_deg = f.targets ? 360.0 : ori_rad_to_deg_output(f.to_rad - start);
        double frames = frames_of(range_deg, ori_rad_to_deg_output(f.step_rad));
        if (frames > STUDIO_MAX_FRAMES_PER_FOLD) {
            studio_fail(out, 400, "folds %d: %.0f states at step %g deg; the studio's limit is %d per fold: use a larger step",
                        k, frames, ori_rad_to_deg_output(f.step_rad), STUDIO_MAX_FRAMES_PER_FOLD);
            ok = false;
        }
        work += frames * elements_of(m);
    }
    if (ok && work > s->def.work_limit) {
        studio_fail(out, 400, "the sequence would record up to %.3g state elements; the studio's limit is %.3g: use larger steps",
                    work, s->def.work_limit);
        ok = false;
    }
    ori_rigid pose = ori_rigid_identity();
    ok = ok && start_pose(m, ori_sequence_fold_at(seq, 0).fixed_face, folded, coords, &pose, out);
    ori_record *r = NULL;
    if (ok) {
        // Its folds report their fraction (/api/progress), folds toward the targets included.
        ori_status st = ori_sequence_run_progress(seq, m, angles, pose, studio_job_progress, s, &r, &err);
        if (st != ORI_OK) {
            studio_fail_error(out, studio_status_of(st), &err);
            ok = false;
        }
    }
    cli_collision col;
    memset(&col, 0, sizeof col);
    if (ok && !opts->skip) {
        // every step checked for self-collision, the first contact located (as orikin sequence)
        ori_collider *c = studio_collider(model->pattern, opts->clearance, out);
        ok = c != NULL;
        if (ok) {
            studio_job_phase(s, "sequence: checking collisions");
            ori_status st = cli_collision_check_record(c, r, studio_job_progress, s, &col, &err);
            ori_collider_destroy(c);
            if (st != ORI_OK) {
                studio_fail_error(out, studio_status_of(st), &err);
                ok = false;
            }
        }
    }
    if (ok) {
        studio_seq *q = calloc(1, sizeof *q);
        atomic_init(&q->refs, 1);
        pthread_mutex_init(&q->lock, NULL);
        q->model = studio_model_ref(model);
        q->sequence = seq;
        q->record = r;
        r = NULL;
        q->collision = col;
        if (cli_collides(&col)) {
            record_contact(m, q->record, &col, &q->contact);
            if (q->contact.has && col.progress) q->contact.drive_rad = NAN; // a fold toward the targets
        }
        q->json = studio_json_text(cli_record_json(name, file, seq, q->record, ori_mechanism_edge_count(m), &col),
                                   &q->json_size);
        studio_job_phase(s, "sequence: states for the slider");
        q->fine = fine_record(s, seq, q->record, m, angles, pose, &q->grid);
        seq = NULL;
        studio_respond_text(out, 200, "application/json", q->json, q->json_size);
        pthread_mutex_lock(&s->lock);
        if (s->version == version) {
            studio_seq_unref(s->seq);
            s->seq = q;
            q = NULL;
        }
        pthread_mutex_unlock(&s->lock);
        studio_seq_unref(q);
    }
    ori_record_destroy(r);
    ori_sequence_destroy(seq);
    free(angles);
    free(coords);
    studio_model_unref(model);
    studio_job_end(s);
}

void studio_api_sequence(studio *s, const studio_request *req, studio_response *out)
{
    if (!req->body || req->body_size == 0) {
        studio_fail(out, 400, "the request needs a SEQ.json body");
        return;
    }
    studio_collide_opts opts;
    if (!collide_opts_args(req, &opts, out)) return;
    ori_sequence *seq = NULL;
    ori_error err;
    if (ori_sequence_parse(req->body, req->body_size, &seq, &err) != ORI_OK) {
        studio_fail_error(out, 400, &err);
        return;
    }
    studio_run_sequence(s, seq, "studio", &opts, out);
}

void studio_api_sequence_get(studio *s, const studio_request *req, studio_response *out)
{
    (void)req;
    studio_seq *q = seq_ref(s);
    if (!q) {
        studio_fail(out, 409, "no sequence has run on this document");
        return;
    }
    studio_respond_text(out, 200, "application/json", q->json, q->json_size);
    studio_seq_unref(q);
}

void studio_api_sequence_at(studio *s, const studio_request *req, studio_response *out)
{
    double t = 0;
    bool has_t;
    if (!parse_number_arg(req, "t", &t, &has_t, out)) return;
    if (!has_t) {
        studio_fail(out, 400, "t: the sequence time is needed");
        return;
    }
    studio_seq *q = seq_ref(s);
    if (!q) {
        studio_fail(out, 409, "no sequence has run on this document");
        return;
    }
    double duration = ori_record_duration(q->record);
    if (!(t >= 0.0 && t <= duration) || duration == 0.0) {
        studio_seq_unref(q);
        studio_fail(out, 400, "t: time %g is outside [0, %g]", t, duration);
        return;
    }
    if (cli_collides(&q->collision) && !(t < q->collision.ev.time)) {
        // as orikin sequence --at T: an instant before the first contact is a clean state
        char hit[256];
        cli_collision_describe(&q->collision, true, hit, sizeof hit);
        double tc = q->collision.ev.time;
        studio_seq_unref(q);
        studio_fail(out, 409, "t: the sequence collides at t = %.9g: %s (GET /api/contact shows it)", tc, hit);
        return;
    }
    const ori_mechanism *m = q->model->mech;
    int V = ori_mechanism_vertex_count(m), E = ori_mechanism_edge_count(m);
    double *ang = malloc(sizeof(double) * (size_t)(E + 1));
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)(V + 1));
    double drive = 0, residual = 0;
    int fold = 0;
    ori_error err;
    ori_status st = seq_state_at(q, t, ang, pos, &drive, &fold, &residual, &err);
    // a fold toward the targets: its "drive" is the progress, no angle (null, NaN in binary)
    if (st == ORI_OK && ori_sequence_fold_at(q->sequence, fold).targets) drive = NAN;
    if (st != ORI_OK) {
        studio_fail_error(out, studio_status_of(st), &err);
    } else {
        size_t size;
        bool binary = binary_requested(req);
        char *b = binary ? studio_state_binary(t, fold, drive, residual, pos, V, ang, E, &size)
                         : studio_json_at_text(t, fold, drive, ang, E, residual, pos, V, &size);
        free(out->body);
        out->status = 200;
        out->content_type = binary ? "application/octet-stream" : "application/json";
        out->body = b;
        out->size = size;
    }
    free(ang);
    free(pos);
    studio_seq_unref(q);
}
