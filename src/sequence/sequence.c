// Fold sequences (the folding manager): parsing SEQ.json, running the folds one after the other
// from the geometry the previous one left, the motion record, and exact restoration of any
// instant by continuation from the recorded state before it.
#include <orikin/sequence.h>

#include <orikin/arrangement.h> // ori_pattern_find_edge_at, _face_at: faces and creases named by a point
#include <orikin/tolerance.h>

#include <math.h>
#include <stdlib.h>

#include "../core/json_internal.h"
#include "../kinematics/multifold_internal.h" // ori__mf_close: restoring a fold toward the targets
#include "sequence_internal.h"

// A fold's faces and creases named by a string ("fix": "Obj12" or "@x,y", "drive": "@x,y",
// "lock": ["@x,y", …]) until ori_sequence_resolve turns them into indices. NULL: an index.
typedef struct fold_refs {
    char *fix, *drive;
    char *lock[ORI_SEQUENCE_MAX_LOCKS];
} fold_refs;

struct ori_sequence {
    char *pattern;
    int frame;
    int fold_count;
    ori_sequence_fold *folds;
    fold_refs *refs; // fold_count entries
    bool unresolved; // some reference is still a string
};

// Per fold of a run: where its fixed face is, its drive range, its first recorded frame.
typedef struct record_fold {
    ori_rigid fixed_pose;
    double from_rad, to_rad;
    int first_frame;
} record_fold;

struct ori_record {
    const ori_mechanism *mechanism;
    ori_sequence_fold *folds;
    record_fold *run;
    int fold_count, completed, failed;
    int partial_frames; // trailing frames of a blocked fold (up to its stop)
    ori_motion_verdict verdict;
    char *reason;
    int vertex_count, edge_count;
    int frame_count, frame_cap;
    double *times, *drives, *residuals;
    int *frame_folds;
    double *angles;    // frame_count × edge_count
    ori_v3 *positions; // frame_count × vertex_count
};

// --- parsing -----------------------------------------------------------------------------

static const char *const fold_keys[] = {"fix", "drive", "to", "from", "step", "lock", "name", "percent"};
static const char *const top_keys[] = {"pattern", "frame", "folds", "title", "description"};

static bool known_key(const char *key, const char *const *keys, size_t n)
{
    for (size_t i = 0; i < n; ++i)
        if (strcmp(key, keys[i]) == 0) return true;
    return false;
}

static ori_status fold_fail(ori_error *error, int fold, const char *fmt, const char *what)
{
    return ori__fail_at(error, ORI_ERR_TYPE, "folds", fold, fmt, what);
}

// "@x,y": the point; false when the text is not of that form.
static bool parse_point(const char *t, ori_v2 *p)
{
    if (t[0] != '@') return false;
    char *end;
    double x = strtod(t + 1, &end);
    if (end == t + 1 || *end != ',') return false;
    const char *y0 = end + 1;
    double y = strtod(y0, &end);
    if (end == y0 || *end != '\0' || !isfinite(x) || !isfinite(y)) return false;
    *p = ori_v2_make(x, y);
    return true;
}

// A face ("fix": an index, a face name or "@x,y") or a crease ("drive", lock items: an index or
// "@x,y"); a string is kept in *ref (owned) and the index set to ORI_NULL_INDEX.
static ori_status read_ref(json_t *v, const char *key, int fold, bool face, int *out, char **ref, ori_error *error)
{
    bool item = strcmp(key, "lock") == 0;
    if (json_is_string(v)) {
        const char *t = json_string_value(v);
        ori_v2 p;
        if (!parse_point(t, &p) && (!face || t[0] == '\0' || t[0] == '@' || strlen(t) >= ORI_NAME_MAX)) {
            if (item) return fold_fail(error, fold, "%s", "\"lock\" must be an array of FOLD edge indices or \"@x,y\" points");
            return fold_fail(error, fold,
                             face ? "\"%s\" must be a FOLD face index, a face name or \"@x,y\" (a point in the face)"
                                  : "\"%s\" must be a FOLD edge index or \"@x,y\" (a point on the crease)",
                             key);
        }
        *ref = ori__strdup(t);
        *out = ORI_NULL_INDEX;
        return ORI_OK;
    }
    if (item && (!json_is_integer(v) || json_integer_value(v) < 0 || json_integer_value(v) > INT32_MAX))
        return fold_fail(error, fold, "%s", "\"lock\" must be an array of FOLD edge indices or \"@x,y\" points");
    if (!json_is_integer(v) || json_integer_value(v) < 0 || json_integer_value(v) > INT32_MAX)
        return fold_fail(error, fold,
                         face ? "\"%s\" must be a FOLD index (an integer ≥ 0), a face name or \"@x,y\""
                              : "\"%s\" must be a FOLD index (an integer ≥ 0) or \"@x,y\"",
                         key);
    *out = (int)json_integer_value(v);
    return ORI_OK;
}

static ori_status read_index_field(json_t *obj, const char *key, int fold, bool required, int *out, char **ref,
                                   ori_error *error)
{
    json_t *v = json_object_get(obj, key);
    if (!v) return required ? fold_fail(error, fold, "missing \"%s\"", key) : ORI_OK;
    return read_ref(v, key, fold, strcmp(key, "fix") == 0, out, ref, error);
}

static ori_status read_angle_field(json_t *obj, const char *key, int fold, bool *present, double *out_rad,
                                   ori_error *error)
{
    json_t *v = json_object_get(obj, key);
    *present = v != NULL;
    if (!v) return ORI_OK;
    if (!json_is_number(v)) return fold_fail(error, fold, "\"%s\" must be a number of degrees", key);
    double deg = json_number_value(v);
    if (!(deg >= -180.0 && deg <= 180.0))
        return ori__fail_at(error, ORI_ERR_RANGE, "folds", fold, "\"%s\" = %g is outside [-180, 180] degrees", key, deg);
    *out_rad = ori_deg_to_rad(deg);
    return ORI_OK;
}

static ori_status parse_fold(json_t *obj, int i, ori_sequence_fold *f, fold_refs *refs, ori_error *error)
{
    memset(f, 0, sizeof *f);
    if (!json_is_object(obj)) return fold_fail(error, i, "%s", "a fold must be an object");
    const char *key;
    json_t *val;
    json_object_foreach(obj, key, val)
    {
        if (!known_key(key, fold_keys, sizeof fold_keys / sizeof fold_keys[0]))
            return fold_fail(error, i, "unknown field \"%s\" (fix, drive, to, from, step, lock, name, percent)", key);
    }
    ori_status st;
    // "fix" is optional, as --fix is: the face at the sheet's centroid (ori_sequence_resolve).
    f->fix_default = !json_object_get(obj, "fix");
    f->fixed_face = ORI_NULL_INDEX;
    if ((st = read_index_field(obj, "fix", i, false, &f->fixed_face, &refs->fix, error)) != ORI_OK) return st;
    bool has_to, has_step;
    json_t *percent = json_object_get(obj, "percent"); // a fold toward the targets (targets.c)
    if (percent) {
        if (!json_is_number(percent) || !(json_number_value(percent) >= 0.0 && json_number_value(percent) <= 100.0))
            return ori__fail_at(error, ORI_ERR_RANGE, "folds", i, "\"percent\" must be a number from 0 to 100");
        if (json_object_get(obj, "drive") || json_object_get(obj, "to") || json_object_get(obj, "from"))
            return fold_fail(error, i, "%s", "\"percent\" folds every crease toward its target: no drive, to or from");
        f->targets = true;
        f->fraction = json_number_value(percent) / 100.0;
        f->driven_edge = ORI_NULL_INDEX;
    } else {
        if ((st = read_index_field(obj, "drive", i, true, &f->driven_edge, &refs->drive, error)) != ORI_OK) return st;
        if ((st = read_angle_field(obj, "to", i, &has_to, &f->to_rad, error)) != ORI_OK) return st;
        if (!has_to) return fold_fail(error, i, "missing \"%s\"", "to");
        if ((st = read_angle_field(obj, "from", i, &f->has_from, &f->from_rad, error)) != ORI_OK) return st;
    }
    json_t *step = json_object_get(obj, "step");
    has_step = step != NULL;
    f->step_rad = ori_deg_to_rad(10.0);
    if (has_step) {
        if (!json_is_number(step) || !(json_number_value(step) > 0.0) || json_number_value(step) > 360.0)
            return ori__fail_at(error, ORI_ERR_RANGE, "folds", i, "\"step\" must be a number of degrees in (0, 360]");
        if (json_number_value(step) < 360.0 / ORI_SEQUENCE_MAX_FOLD_STATES)
            return ori__fail_at(error, ORI_ERR_RANGE, "folds", i,
                                "\"step\" %g deg asks for more than %d states in one fold: at least %g deg",
                                json_number_value(step), ORI_SEQUENCE_MAX_FOLD_STATES, 360.0 / ORI_SEQUENCE_MAX_FOLD_STATES);
        f->step_rad = ori_deg_to_rad(json_number_value(step));
    }
    json_t *lock = json_object_get(obj, "lock");
    if (lock) {
        if (!json_is_array(lock))
            return fold_fail(error, i, "%s", "\"lock\" must be an array of FOLD edge indices or \"@x,y\" points");
        if (json_array_size(lock) > ORI_SEQUENCE_MAX_LOCKS)
            return ori__fail_at(error, ORI_ERR_LIMIT, "folds", i, "more than %d locked creases", ORI_SEQUENCE_MAX_LOCKS);
        size_t k;
        json_t *e;
        json_array_foreach(lock, k, e)
        {
            int c = f->locked_count;
            if ((st = read_ref(e, "lock", i, false, &f->locked[c], &refs->lock[c], error)) != ORI_OK) return st;
            f->locked_count++;
        }
    }
    json_t *name = json_object_get(obj, "name");
    if (name) {
        if (!json_is_string(name) || strlen(json_string_value(name)) >= ORI_NAME_MAX)
            return fold_fail(error, i, "\"%s\" must be a string of at most 63 characters", "name");
        ori__strlcpy(f->name, json_string_value(name), sizeof f->name);
    }
    return ORI_OK;
}

ori_status ori_sequence_parse(const char *text, size_t size, ori_sequence **out, ori_error *error)
{
    ORI_ASSERT(text && out);
    *out = NULL;
    ori_error_clear(error);
    json_t *root = ori__json_parse(text, size, JSON_REJECT_DUPLICATES, error);
    if (!root) return ORI_ERR_PARSE;
    ori_status st = ORI_OK;
    ori_sequence *s = ori__calloc(1, sizeof *s);
    const char *key;
    json_t *val;
    if (!json_is_object(root)) {
        st = ori__fail(error, ORI_ERR_TYPE, "a sequence must be a JSON object {\"pattern\", \"folds\"}");
        goto done;
    }
    json_object_foreach(root, key, val)
    {
        if (!known_key(key, top_keys, sizeof top_keys / sizeof top_keys[0])) {
            st = ori__fail_at(error, ORI_ERR_TYPE, key, ORI_NULL_INDEX,
                              "unknown field (pattern, frame, folds, title, description)");
            goto done;
        }
    }
    json_t *pattern = json_object_get(root, "pattern");
    if (!json_is_string(pattern) || json_string_length(pattern) == 0) {
        st = ori__fail_at(error, ORI_ERR_TYPE, "pattern", ORI_NULL_INDEX, "must name the FOLD file of the crease pattern");
        goto done;
    }
    s->pattern = ori__strdup(json_string_value(pattern));
    json_t *frame = json_object_get(root, "frame");
    if (frame && (!json_is_integer(frame) || json_integer_value(frame) < 0 || json_integer_value(frame) > INT32_MAX)) {
        st = ori__fail_at(error, ORI_ERR_TYPE, "frame", ORI_NULL_INDEX, "must be a frame number ≥ 0");
        goto done;
    }
    s->frame = frame ? (int)json_integer_value(frame) : 0;
    json_t *folds = json_object_get(root, "folds");
    if (!json_is_array(folds) || json_array_size(folds) == 0 || json_array_size(folds) > 100000) {
        st = ori__fail_at(error, ORI_ERR_TYPE, "folds", ORI_NULL_INDEX, "must be a non-empty array of folds");
        goto done;
    }
    s->fold_count = (int)json_array_size(folds);
    s->folds = ori__calloc((size_t)s->fold_count, sizeof *s->folds);
    s->refs = ori__calloc((size_t)s->fold_count, sizeof *s->refs);
    for (int i = 0; i < s->fold_count && st == ORI_OK; ++i) {
        st = parse_fold(json_array_get(folds, (size_t)i), i, &s->folds[i], &s->refs[i], error);
        fold_refs *r = &s->refs[i];
        s->unresolved = s->unresolved || r->fix || r->drive || s->folds[i].fix_default;
        for (int k = 0; k < s->folds[i].locked_count; ++k) s->unresolved = s->unresolved || r->lock[k];
    }
done:
    json_decref(root);
    if (st != ORI_OK) {
        ori_sequence_destroy(s);
        return st;
    }
    *out = s;
    return ORI_OK;
}

ori_status ori_sequence_load_file(const char *path, ori_sequence **out, ori_error *error)
{
    ORI_ASSERT(path && out);
    *out = NULL;
    char *data;
    size_t size;
    ori_status st = ori_file_read_all(path, (size_t)64 << 20, &data, &size, error);
    if (st != ORI_OK) return st;
    st = ori_sequence_parse(data, size, out, error);
    ori__free(data);
    return st;
}

static void free_refs(fold_refs *r)
{
    ori__free(r->fix);
    ori__free(r->drive);
    for (int k = 0; k < ORI_SEQUENCE_MAX_LOCKS; ++k) ori__free(r->lock[k]);
    memset(r, 0, sizeof *r);
}

void ori_sequence_destroy(ori_sequence *s)
{
    if (!s) return;
    for (int i = 0; s->refs && i < s->fold_count; ++i) free_refs(&s->refs[i]);
    ori__free(s->refs);
    ori__free(s->pattern);
    ori__free(s->folds);
    ori__free(s);
}

static ori_status resolve_face(const ori_pattern *p, int fold, const char *ref, int *out, ori_error *error)
{
    ori_v2 q;
    if (!parse_point(ref, &q)) {
        int f = ori_pattern_find_face_by_name(p, ref);
        if (f == ORI_NULL_INDEX) return ori__fail_at(error, ORI_ERR_RANGE, "folds", fold, "fix: no face named %s", ref);
        *out = f;
        return ORI_OK;
    }
    bool on_edge;
    int f = ori_pattern_find_face_at(p, q, &on_edge);
    if (f != ORI_NULL_INDEX && on_edge)
        return ori__fail_at(error, ORI_ERR_RANGE, "folds", fold,
                            "fix: (%g, %g) lies on an edge of face %d: give a point inside a face", q.x, q.y, f);
    if (f != ORI_NULL_INDEX) {
        *out = f;
        return ORI_OK;
    }
    return ori__fail_at(error, ORI_ERR_RANGE, "folds", fold, "fix: no face contains (%g, %g)", q.x, q.y);
}

static ori_status resolve_edge(const ori_pattern *p, int fold, const char *key, const char *ref, int *out,
                               ori_error *error)
{
    ori_v2 q;
    parse_point(ref, &q); // checked when parsed
    int e = ori_pattern_find_edge_at(p, q);
    if (e == ORI_NULL_INDEX)
        return ori__fail_at(error, ORI_ERR_RANGE, "folds", fold, "%s: no crease passes through (%g, %g)", key, q.x, q.y);
    *out = e;
    return ORI_OK;
}

ori_status ori_sequence_resolve(ori_sequence *s, const ori_pattern *flat, ori_error *error)
{
    ORI_ASSERT(s && flat);
    if (!s->unresolved) return ORI_OK;
    // Resolve into copies: the sequence is unchanged on failure.
    ori_sequence_fold *folds = ori__alloc(sizeof *folds * (size_t)s->fold_count);
    memcpy(folds, s->folds, sizeof *folds * (size_t)s->fold_count);
    ori_status st = ORI_OK;
    for (int i = 0; i < s->fold_count && st == ORI_OK; ++i) {
        const fold_refs *r = &s->refs[i];
        ori_sequence_fold *f = &folds[i];
        if (r->fix) st = resolve_face(flat, i, r->fix, &f->fixed_face, error);
        if (f->fix_default) f->fixed_face = ori_pattern_center_face(flat);
        if (st == ORI_OK && r->drive) st = resolve_edge(flat, i, "drive", r->drive, &f->driven_edge, error);
        for (int k = 0; k < f->locked_count && st == ORI_OK; ++k)
            if (r->lock[k]) st = resolve_edge(flat, i, "lock", r->lock[k], &f->locked[k], error);
    }
    if (st == ORI_OK) {
        memcpy(s->folds, folds, sizeof *folds * (size_t)s->fold_count);
        for (int i = 0; i < s->fold_count; ++i) free_refs(&s->refs[i]);
        s->unresolved = false;
    }
    ori__free(folds);
    return st;
}

const char *ori_sequence_pattern_path(const ori_sequence *s) { ORI_ASSERT(s); return s->pattern; }
int ori_sequence_frame(const ori_sequence *s) { ORI_ASSERT(s); return s->frame; }
int ori_sequence_fold_count(const ori_sequence *s) { ORI_ASSERT(s); return s->fold_count; }

ori_sequence_fold ori_sequence_fold_at(const ori_sequence *s, int fold)
{
    ORI_ASSERT(s && fold >= 0 && fold < s->fold_count);
    return s->folds[fold];
}

static json_t *degrees(double rad) { return json_real(ori_rad_to_deg_output(rad)); }

char *ori_sequence_to_json(const ori_sequence *s)
{
    ORI_ASSERT(s);
    json_t *root = json_object();
    json_object_set_new(root, "pattern", json_string(s->pattern));
    json_object_set_new(root, "frame", json_integer(s->frame));
    json_t *folds = json_array();
    for (int i = 0; i < s->fold_count; ++i) {
        const ori_sequence_fold *f = &s->folds[i];
        json_t *o = json_object();
        if (f->name[0]) json_object_set_new(o, "name", json_string(f->name));
        const fold_refs *r = &s->refs[i];
        if (!(f->fix_default && f->fixed_face == ORI_NULL_INDEX)) // an unresolved default: no "fix", as read
            json_object_set_new(o, "fix", r->fix ? json_string(r->fix) : json_integer(f->fixed_face));
        if (f->targets) {
            json_object_set_new(o, "percent", json_real(100.0 * f->fraction));
        } else {
            json_object_set_new(o, "drive", r->drive ? json_string(r->drive) : json_integer(f->driven_edge));
            if (f->has_from) json_object_set_new(o, "from", degrees(f->from_rad));
            json_object_set_new(o, "to", degrees(f->to_rad));
        }
        json_object_set_new(o, "step", degrees(f->step_rad));
        json_t *lock = json_array();
        for (int k = 0; k < f->locked_count; ++k)
            json_array_append_new(lock, r->lock[k] ? json_string(r->lock[k]) : json_integer(f->locked[k]));
        json_object_set_new(o, "lock", lock);
        json_array_append_new(folds, o);
    }
    json_object_set_new(root, "folds", folds);
    char *raw = json_dumps(root, JSON_COMPACT | JSON_REAL_PRECISION(17));
    json_decref(root);
    char *text = ori__strdup(raw);
    free(raw);
    return text;
}

// --- running -------------------------------------------------------------------------------

static void record_state(ori_record *r, double t, int fold, double drive, const double *angles,
                         const ori_v3 *positions, double residual)
{
    int n = r->frame_count;
    if (n == r->frame_cap) {
        int cap = r->frame_cap ? 2 * r->frame_cap : 16;
        r->times = ori__realloc(r->times, sizeof(double) * (size_t)cap);
        r->drives = ori__realloc(r->drives, sizeof(double) * (size_t)cap);
        r->residuals = ori__realloc(r->residuals, sizeof(double) * (size_t)cap);
        r->frame_folds = ori__realloc(r->frame_folds, sizeof(int) * (size_t)cap);
        r->angles = ori__realloc(r->angles, sizeof(double) * (size_t)cap * (size_t)(r->edge_count ? r->edge_count : 1));
        r->positions = ori__realloc(r->positions, sizeof(ori_v3) * (size_t)cap * (size_t)(r->vertex_count ? r->vertex_count : 1));
        r->frame_cap = cap;
    }
    r->times[n] = t;
    r->frame_folds[n] = fold;
    r->drives[n] = drive;
    r->residuals[n] = residual;
    memcpy(r->angles + (size_t)n * (size_t)r->edge_count, angles, sizeof(double) * (size_t)r->edge_count);
    memcpy(r->positions + (size_t)n * (size_t)r->vertex_count, positions, sizeof(ori_v3) * (size_t)r->vertex_count);
    r->frame_count = n + 1;
}

static ori_motion_def fold_def(const ori_sequence_fold *f, const double *start, ori_rigid pose)
{
    ori_motion_def d = ori_default_motion_def();
    d.fixed_face = f->fixed_face;
    d.fixed_pose = pose;
    d.start_angles_rad = start;
    d.driven_edge = f->driven_edge;
    d.has_from = f->has_from;
    d.from_rad = f->from_rad;
    d.to_rad = f->to_rad;
    d.step_rad = f->step_rad;
    d.locked_edges = f->locked;
    d.locked_count = f->locked_count;
    return d;
}

// Sequence time of drive angle x in a fold ranging from → to.
static double fold_time(int fold, double from, double to, double x)
{
    double span = to - from;
    double s = span != 0.0 ? (x - from) / span : 1.0;
    if (s < 0.0) s = 0.0;
    if (s > 1.0) s = 1.0;
    return (double)fold + s;
}

// A fold toward the targets: its frames recorded with the progress (0 … 1) as the "drive";
// angles and poses updated to its end. Not reaching the goal fails the sequence (blocked).
static ori_status ori__sequence_target_fold(ori_record *r, int i, const ori_sequence_fold *f, double *angles,
                                            ori_rigid pose, ori_rigid *poses, ori_v3 *pos, ori_progress_fn *progress,
                                            void *progress_user, ori_error *error)
{
    ori_target_fold_def td = ori_default_target_fold_def();
    td.fixed_face = f->fixed_face;
    td.fixed_pose = pose;
    td.start_angles_rad = angles;
    td.fraction = f->fraction;
    td.step_rad = f->step_rad;
    td.locked_edges = f->locked;
    td.locked_count = f->locked_count;
    td.progress = progress;
    td.progress_user = progress_user;
    ori_multifold *mf = NULL;
    ori_error e;
    ori_status st = ori_target_fold_solve(r->mechanism, &td, &mf, &e);
    if (st == ORI_ERR_LIMIT && progress && strcmp(e.message, "cancelled") == 0)
        return ori__fail(error, ORI_ERR_LIMIT, "cancelled");
    if (st != ORI_OK) {
        char msg[256];
        ori_error_format(&e, msg, sizeof msg);
        return ori__fail_at(error, st, "folds", i, "%s", msg);
    }
    // The same engine, the same verdict as orikin fold --percent: a motion against the assignment
    // is invalid (nothing of it recorded, as for a drive); one that stops short of its fraction is
    // blocked, recorded up to its stop (its frames, t the fraction of the planned fold reached).
    int nf = ori_multifold_frame_count(mf);
    bool partial = false;
    if (ori_multifold_verdict_of(mf) != ORI_MULTIFOLD_REACHED) {
        bool invalid = ori_multifold_verdict_of(mf) == ORI_MULTIFOLD_INVALID_ASSIGNMENT;
        r->verdict = invalid ? ORI_MOTION_INVALID_ASSIGNMENT : ORI_MOTION_BLOCKED;
        r->failed = i;
        r->reason = ori__strdup(ori_multifold_reason(mf));
        partial = !invalid && nf > 1;
        if (!partial) {
            ori_multifold_destroy(mf);
            return ORI_OK;
        }
    }
    record_fold *rf = &r->run[i];
    rf->fixed_pose = pose;
    // t = i + s, s the progress over the fraction asked for (the fold's own 0 … 1).
    rf->from_rad = 0.0;
    rf->to_rad = f->fraction;
    rf->first_frame = r->frame_count;
    for (int k = i > 0 ? 1 : 0; k < nf; ++k) {
        double pr = ori_multifold_frame_progress(mf, k);
        ori_multifold_frame_vertices(mf, k, pos);
        record_state(r, fold_time(i, 0.0, f->fraction, pr), i, pr, ori_multifold_frame_angles(mf, k), pos,
                     ori_multifold_frame_residual(mf, k));
    }
    if (partial) r->partial_frames = r->frame_count - rf->first_frame;
    if (i > 0) rf->first_frame -= 1;
    memcpy(angles, ori_multifold_frame_angles(mf, nf - 1), sizeof(double) * (size_t)r->edge_count);
    ori_mechanism_face_poses(r->mechanism, angles, f->fixed_face, pose, poses);
    ori_multifold_destroy(mf);
    return ORI_OK;
}

ori_status ori_sequence_run(const ori_sequence *s, const ori_mechanism *m, const double *start,
                            ori_rigid fixed_pose, ori_record **out, ori_error *error)
{
    return ori_sequence_run_progress(s, m, start, fixed_pose, NULL, NULL, out, error);
}

// The progress of fold i of n: its own fraction mapped onto [i/n, (i+1)/n].
typedef struct seq_progress {
    ori_progress_fn *fn;
    void *user;
    int fold, folds;
} seq_progress;

static bool seq_progress_fn(double f, void *user)
{
    const seq_progress *p = user;
    return p->fn(((double)p->fold + f) / (double)p->folds, p->user);
}

ori_status ori_sequence_run_progress(const ori_sequence *s, const ori_mechanism *m, const double *start,
                                     ori_rigid fixed_pose, ori_progress_fn *progress, void *progress_user,
                                     ori_record **out, ori_error *error)
{
    ORI_ASSERT(s && m && out);
    seq_progress sp = {progress, progress_user, 0, s->fold_count > 0 ? s->fold_count : 1};
    *out = NULL;
    ori_error_clear(error);
    for (int i = 0; i < s->fold_count && s->unresolved; ++i) {
        const fold_refs *r = &s->refs[i];
        const char *ref = r->fix ? r->fix : r->drive;
        for (int k = 0; !ref && k < s->folds[i].locked_count; ++k) ref = r->lock[k];
        if (!ref && s->folds[i].fix_default && s->folds[i].fixed_face == ORI_NULL_INDEX)
            return ori__fail_at(error, ORI_ERR_ARGUMENT, "folds", i,
                                "no \"fix\": the face at the sheet's centre is found against the pattern "
                                "(ori_sequence_resolve first)");
        if (ref)
            return ori__fail_at(error, ORI_ERR_ARGUMENT, "folds", i,
                                "\"%s\" names a face or crease by name or point: resolve it against the pattern "
                                "first (ori_sequence_resolve)",
                                ref);
    }
    ori_record *r = ori__calloc(1, sizeof *r);
    r->mechanism = m;
    r->fold_count = s->fold_count;
    r->folds = ori__alloc(sizeof(ori_sequence_fold) * (size_t)s->fold_count);
    memcpy(r->folds, s->folds, sizeof(ori_sequence_fold) * (size_t)s->fold_count);
    r->run = ori__calloc((size_t)s->fold_count, sizeof(record_fold));
    r->failed = ORI_NULL_INDEX;
    r->verdict = ORI_MOTION_VALID;
    r->vertex_count = ori_mechanism_vertex_count(m);
    r->edge_count = ori_mechanism_edge_count(m);
    int F = ori_mechanism_face_count(m);

    double *angles = ori__calloc((size_t)(r->edge_count ? r->edge_count : 1), sizeof(double));
    if (start) memcpy(angles, start, sizeof(double) * (size_t)r->edge_count);
    ori_rigid *poses = ori__alloc(sizeof(ori_rigid) * (size_t)(F ? F : 1));
    ori_v3 *pos = ori__alloc(sizeof(ori_v3) * (size_t)(r->vertex_count ? r->vertex_count : 1));
    ori_rigid pose = fixed_pose;
    ori_status st = ORI_OK;

    for (int i = 0; i < s->fold_count; ++i) {
        const ori_sequence_fold *f = &s->folds[i];
        if (i > 0) {
            // the new fixed face stays where the previous fold left it
            if (f->fixed_face < 0 || f->fixed_face >= F) {
                st = ori__fail_at(error, ORI_ERR_RANGE, "folds", i, "fix: face %d does not exist (%d faces)", f->fixed_face, F);
                break;
            }
            pose = poses[f->fixed_face];
        }
        sp.fold = i;
        if (progress && !seq_progress_fn(0.0, &sp)) {
            st = ori__fail(error, ORI_ERR_LIMIT, "cancelled");
            break;
        }
        if (f->targets) { // a fold toward the targets (src/kinematics/targets.c)
            if ((st = ori__sequence_target_fold(r, i, f, angles, pose, poses, pos, progress ? seq_progress_fn : NULL,
                                                &sp, error)) != ORI_OK)
                break;
            if (r->failed != ORI_NULL_INDEX) break;
            r->completed = i + 1;
            continue;
        }
        ori_motion_def d = fold_def(f, angles, pose);
        if (progress) {
            d.progress = seq_progress_fn;
            d.progress_user = &sp;
        }
        ori_motion *mo = NULL;
        ori_error e;
        st = ori_motion_solve(m, &d, &mo, &e);
        if (st == ORI_ERR_LIMIT && progress && strcmp(e.message, "cancelled") == 0) {
            ori__fail(error, ORI_ERR_LIMIT, "cancelled");
            break;
        }
        if (st != ORI_OK) {
            char msg[256];
            ori_error_format(&e, msg, sizeof msg);
            ori__fail_at(error, st, "folds", i, "%s", msg);
            break;
        }
        ori_motion_verdict v = ori_motion_verdict_of(mo);
        int nf = ori_motion_frame_count(mo);
        // A blocked fold is recorded up to its stop (the frames of a partial fold, times as
        // fractions of the planned one); any other failure records nothing of its fold.
        bool partial = v == ORI_MOTION_BLOCKED && nf > 0;
        if (v != ORI_MOTION_VALID) {
            r->verdict = v;
            r->failed = i;
            const char *why = ori_motion_reason(mo);
            r->reason = ori__strdup(why ? why : ori_motion_verdict_name(v));
            if (!partial) {
                ori_motion_destroy(mo);
                break;
            }
        }
        record_fold *rf = &r->run[i];
        rf->fixed_pose = pose;
        rf->from_rad = ori_motion_frame_drive(mo, 0);
        rf->to_rad = partial ? d.to_rad : ori_motion_frame_drive(mo, nf - 1);
        if (partial && rf->to_rad == rf->from_rad) rf->to_rad = ori_motion_frame_drive(mo, nf - 1);
        rf->first_frame = r->frame_count;
        for (int k = 0; k < nf; ++k) {
            // the first state of a fold repeats the last of the previous one (unless "from" jumps)
            if (k == 0 && i > 0 && !f->has_from) continue;
            double drive = ori_motion_frame_drive(mo, k);
            ori_motion_frame_vertices(mo, k, pos);
            record_state(r, fold_time(i, rf->from_rad, rf->to_rad, drive), i, drive,
                         ori_motion_frame_angles(mo, k), pos, ori_motion_frame_residual(mo, k));
        }
        if (i > 0 && !f->has_from) rf->first_frame -= 1; // fold i starts at the previous end state
        memcpy(angles, ori_motion_frame_angles(mo, nf - 1), sizeof(double) * (size_t)r->edge_count);
        ori_motion_frame_face_poses(mo, nf - 1, poses);
        ori_motion_destroy(mo);
        if (partial) {
            r->partial_frames = r->frame_count - rf->first_frame - (i > 0 && !f->has_from ? 1 : 0);
            break;
        }
        r->completed = i + 1;
    }
    ori__free(angles);
    ori__free(poses);
    ori__free(pos);
    if (st == ORI_OK && progress && !progress(1.0, progress_user)) st = ori__fail(error, ORI_ERR_LIMIT, "cancelled");
    if (st != ORI_OK) {
        ori_record_destroy(r);
        return st;
    }
    *out = r;
    return ORI_OK;
}

void ori_record_destroy(ori_record *r)
{
    if (!r) return;
    ori__free(r->folds);
    ori__free(r->run);
    ori__free(r->reason);
    ori__free(r->times);
    ori__free(r->drives);
    ori__free(r->residuals);
    ori__free(r->frame_folds);
    ori__free(r->angles);
    ori__free(r->positions);
    ori__free(r);
}

int ori_record_fold_count(const ori_record *r) { ORI_ASSERT(r); return r->fold_count; }
bool ori_record_fold_is_targets(const ori_record *r, int fold)
{
    ORI_ASSERT(r && fold >= 0 && fold < r->fold_count);
    return r->folds[fold].targets;
}
int ori_record_completed_folds(const ori_record *r) { ORI_ASSERT(r); return r->completed; }
ori_motion_verdict ori_record_verdict(const ori_record *r) { ORI_ASSERT(r); return r->verdict; }
const char *ori_record_reason(const ori_record *r) { ORI_ASSERT(r); return r->reason; }
int ori_record_failed_fold(const ori_record *r) { ORI_ASSERT(r); return r->failed; }
int ori_record_frame_count(const ori_record *r) { ORI_ASSERT(r); return r->frame_count; }
int ori_record_partial_frames(const ori_record *r) { ORI_ASSERT(r); return r->partial_frames; }
double ori_record_duration(const ori_record *r) { ORI_ASSERT(r); return (double)r->completed; }

const ori_mechanism *ori__record_mechanism(const ori_record *r)
{
    ORI_ASSERT(r);
    return r->mechanism;
}

double ori_record_frame_time(const ori_record *r, int i)
{
    ORI_ASSERT(r && i >= 0 && i < r->frame_count);
    return r->times[i];
}

int ori_record_frame_fold(const ori_record *r, int i)
{
    ORI_ASSERT(r && i >= 0 && i < r->frame_count);
    return r->frame_folds[i];
}

double ori_record_frame_drive(const ori_record *r, int i)
{
    ORI_ASSERT(r && i >= 0 && i < r->frame_count);
    return r->drives[i];
}

const double *ori_record_frame_angles(const ori_record *r, int i)
{
    ORI_ASSERT(r && i >= 0 && i < r->frame_count);
    return r->angles + (size_t)i * (size_t)r->edge_count;
}

double ori_record_frame_residual(const ori_record *r, int i)
{
    ORI_ASSERT(r && i >= 0 && i < r->frame_count);
    return r->residuals[i];
}

const ori_v3 *ori_record_frame_vertices(const ori_record *r, int i)
{
    ORI_ASSERT(r && i >= 0 && i < r->frame_count);
    return r->positions + (size_t)i * (size_t)r->vertex_count;
}

const double *ori_record_angles(const ori_record *r, int *frame_stride)
{
    ORI_ASSERT(r);
    if (frame_stride) *frame_stride = r->edge_count;
    return r->frame_count > 0 ? r->angles : NULL;
}

const ori_v3 *ori_record_vertices(const ori_record *r)
{
    ORI_ASSERT(r);
    return r->frame_count > 0 ? r->positions : NULL;
}

// A fold toward the targets at time t: the recorded states around t interpolated linearly in
// time, then closed exactly onto the loop-closure manifold (minimum-norm Newton, targets.c).
static ori_status record_at_targets(const ori_record *r, int j, int base, double t, double *angles, ori_v3 *positions,
                                    double *drive_out, int *fold_out, double *residual_out, ori_error *error)
{
    int next = base + 1 < r->frame_count && r->frame_folds[base + 1] == j ? base + 1 : base;
    double t0 = r->times[base], t1 = r->times[next];
    double w = t1 > t0 ? (t - t0) / (t1 - t0) : 0.0;
    const double *a0 = ori_record_frame_angles(r, base), *a1 = ori_record_frame_angles(r, next);
    double *mix = ori__alloc(sizeof(double) * (size_t)(r->edge_count + 1));
    for (int e = 0; e < r->edge_count; ++e) mix[e] = a0[e] + w * (a1[e] - a0[e]);
    ori_status st = ori__mf_close(r->mechanism, r->folds[j].locked, r->folds[j].locked_count, mix, error);
    if (st == ORI_OK) {
        memcpy(angles, mix, sizeof(double) * (size_t)r->edge_count);
        if (positions)
            ori_mechanism_vertex_positions(r->mechanism, angles, r->folds[j].fixed_face, r->run[j].fixed_pose, positions);
    }
    ori__free(mix);
    if (st != ORI_OK) return st;
    if (drive_out) *drive_out = r->drives[base] + w * (r->drives[next] - r->drives[base]);
    if (fold_out) *fold_out = j;
    if (residual_out) *residual_out = ori_mechanism_residual(r->mechanism, angles);
    return ORI_OK;
}

ori_status ori_record_at(const ori_record *r, double t, double *angles, ori_v3 *positions, double *drive_out,
                         int *fold_out, double *residual_out, ori_error *error)
{
    ORI_ASSERT(r && angles);
    ori_error_clear(error);
    // A blocked fold's partial frames (up to its stop) can be restored too: the collision check
    // of a sequence bisects between them.
    bool partial = r->partial_frames > 0 && r->failed != ORI_NULL_INDEX && r->frame_count > 0;
    double end = partial ? fmax((double)r->completed, r->times[r->frame_count - 1]) : (double)r->completed;
    if ((r->completed == 0 && !partial) || !(t >= 0.0 && t <= end))
        return ori__fail(error, ORI_ERR_RANGE, "time %g is outside [0, %.17g]", t, end);
    // fold j holds t ∈ [j, j + 1]; an integer t ≥ 1 is the end of fold t − 1
    int j = (int)floor(t);
    if (j > 0 && (double)j == t) j -= 1;
    int last_fold = partial ? r->failed : r->completed - 1;
    if (j > last_fold) j = last_fold;
    if (j < 0) j = 0;
    const record_fold *rf = &r->run[j];
    double s = t - (double)j;
    double target = rf->from_rad + s * (rf->to_rad - rf->from_rad);
    // the recorded state of fold j at or before t
    int base = rf->first_frame;
    int last = j + 1 < r->completed ? r->run[j + 1].first_frame : r->frame_count - 1;
    for (int k = base; k <= last && k < r->frame_count; ++k)
        if (r->times[k] <= t && (r->frame_folds[k] == j || k == rf->first_frame)) base = k;
    const double *start = ori_record_frame_angles(r, base);
    if (r->folds[j].targets) return record_at_targets(r, j, base, t, angles, positions, drive_out, fold_out, residual_out, error);
    double start_drive = start[r->folds[j].driven_edge];
    if (drive_out) *drive_out = target;
    if (fold_out) *fold_out = j;
    if (start_drive == target || r->times[base] == t) {
        memcpy(angles, start, sizeof(double) * (size_t)r->edge_count);
        if (positions) memcpy(positions, ori_record_frame_vertices(r, base), sizeof(ori_v3) * (size_t)r->vertex_count);
        if (residual_out) *residual_out = r->residuals[base];
        return ORI_OK;
    }
    ori_sequence_fold f = r->folds[j];
    f.has_from = false;
    f.to_rad = target;
    f.step_rad = fabs(target - start_drive);
    ori_motion_def d = fold_def(&f, start, rf->fixed_pose);
    ori_motion *mo = NULL;
    ori_status st = ori_motion_solve(r->mechanism, &d, &mo, error);
    if (st != ORI_OK) return st;
    int nf = ori_motion_frame_count(mo);
    if (ori_motion_verdict_of(mo) != ORI_MOTION_VALID || nf == 0) {
        ori_motion_destroy(mo);
        return ori__fail(error, ORI_ERR_NOT_CONVERGED, "the motion of fold %d could not be restored at time %g", j + 1, t);
    }
    memcpy(angles, ori_motion_frame_angles(mo, nf - 1), sizeof(double) * (size_t)r->edge_count);
    if (positions) ori_motion_frame_vertices(mo, nf - 1, positions);
    if (residual_out) *residual_out = ori_motion_frame_residual(mo, nf - 1);
    ori_motion_destroy(mo);
    return ORI_OK;
}
