// The studio's document state and the API dispatch: models, undo/redo, the job slot, request
// helpers, and loading what `orikin view` is given.
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

studio_def studio_default_def(void)
{
    studio_def d;
    d.path = NULL;
    d.blank_side = 1.0;
    d.max_body_bytes = STUDIO_MAX_BODY_BYTES;
    d.max_open_bytes = STUDIO_MAX_OPEN_BYTES;
    d.cache_bytes = STUDIO_CACHE_BYTES;
    d.work_limit = STUDIO_WORK_LIMIT;
    d.render_pixels = STUDIO_RENDER_MAX_PIXELS;
    d.animation_pixels = STUDIO_ANIMATION_MAX_PIXELS;
    d.autosave = true;
    return d;
}

double studio_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

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
    studio_model_unref(f->model);
    studio_contact_free(&f->contact);
    free(f->start_angles);
    free(f->locks);
    free(f);
}

static void step_clear(studio_step *st)
{
    studio_model_unref(st->model);
    ori_fold_destroy(st->doc);
    memset(st, 0, sizeof *st);
}

// --- document changes ------------------------------------------------------------------------

void studio_drop_results(studio *s)
{
    studio_seq_unref(s->seq);
    s->seq = NULL;
    studio_fold_unref(s->fold);
    s->fold = NULL;
}

static void push_step(studio_step *stack, int *count, const studio_step *st)
{
    if (*count == STUDIO_UNDO_DEPTH) {
        step_clear(&stack[0]);
        memmove(stack, stack + 1, sizeof(studio_step) * (STUDIO_UNDO_DEPTH - 1));
        (*count)--;
    }
    stack[(*count)++] = *st;
}

static void clear_stack(studio_step *stack, int *count)
{
    for (int i = 0; i < *count; ++i) step_clear(&stack[i]);
    *count = 0;
}

// Frame 0 of the document from the current model. ori_fold_set_pattern only fails for a pattern
// it cannot represent, which a model never is; a failure leaves the old frame 0.
static void install_model(studio *s)
{
    ori_error err;
    (void)ori_fold_set_pattern(s->doc, 0, s->model->pattern, &err);
}

void studio_commit(studio *s, studio_model *model)
{
    studio_step st;
    memset(&st, 0, sizeof st);
    st.model = s->model;
    push_step(s->undo, &s->undo_count, &st);
    clear_stack(s->redo, &s->redo_count);
    s->model = model;
    install_model(s);
    s->version++;
    studio_drop_results(s);
    studio_autosave(s);
}

void studio_commit_document(studio *s, ori_fold *doc, studio_model *model, const char *file, ori_format format,
                            bool from_command_line)
{
    studio_step st;
    memset(&st, 0, sizeof st);
    st.model = s->model;
    st.doc = s->doc;
    copy_string(st.file, sizeof st.file, s->file);
    st.format = s->format;
    st.from_command_line = s->from_command_line;
    push_step(s->undo, &s->undo_count, &st);
    clear_stack(s->redo, &s->redo_count);
    s->doc = doc;
    s->model = model;
    copy_string(s->file, sizeof s->file, file);
    s->format = format;
    s->from_command_line = from_command_line;
    install_model(s);
    s->version++;
    studio_drop_results(s);
    studio_autosave(s);
}

// Undo (from = undo stack, to = redo stack) or redo (the other way round).
static bool restore(studio *s, studio_step *from, int *from_count, studio_step *to, int *to_count)
{
    if (*from_count == 0) return false;
    studio_step x = from[--(*from_count)];
    studio_step back;
    memset(&back, 0, sizeof back);
    back.model = s->model;
    if (x.doc) {
        back.doc = s->doc;
        copy_string(back.file, sizeof back.file, s->file);
        back.format = s->format;
        back.from_command_line = s->from_command_line;
        s->doc = x.doc;
        copy_string(s->file, sizeof s->file, x.file);
        s->format = x.format;
        s->from_command_line = x.from_command_line;
    }
    push_step(to, to_count, &back);
    s->model = x.model;
    install_model(s);
    s->version++;
    studio_drop_results(s);
    studio_autosave(s);
    return true;
}

long studio_version(studio *s)
{
    pthread_mutex_lock(&s->lock);
    long v = s->version;
    pthread_mutex_unlock(&s->lock);
    return v;
}

// --- loading ---------------------------------------------------------------------------------

static bool has_suffix(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    if (n < k) return false;
    for (size_t i = 0; i < k; ++i) {
        char c = s[n - k + i];
        if (c >= 'A' && c <= 'Z') c = (char)(c - 'A' + 'a');
        if (c != suffix[i]) return false;
    }
    return true;
}

// A new document holding pattern in frame 0.
static ori_fold *document_of(const ori_pattern *p)
{
    ori_fold *doc = ori_fold_create();
    ori_error err;
    (void)ori_fold_set_pattern(doc, 0, p, &err);
    return doc;
}

static void error_line(char *buf, size_t size, const ori_error *err)
{
    ori_error_format(err, buf, size);
    for (char *c = buf; *c; ++c)
        if (*c == '\n' || *c == '\r') *c = ' ';
}

bool studio_load_text(const char *name, const char *text, size_t size, ori_fold **doc, studio_model **model,
                      char *err, size_t err_size)
{
    *doc = NULL;
    *model = NULL;
    ori_format fmt = ori_format_from_path(name);
    ori_error e;
    ori_pattern *p = NULL;
    if (fmt == ORI_FORMAT_FOLD) {
        ori_fold *d = NULL;
        if (ori_fold_load_string(text, size, &d, &e) != ORI_OK) {
            error_line(err, err_size, &e);
            return false;
        }
        if (ori_fold_get_pattern(d, 0, NULL, &p, &e) != ORI_OK) {
            ori_fold_destroy(d);
            error_line(err, err_size, &e);
            return false;
        }
        *doc = d;
        *model = studio_model_new(p);
        return true;
    }
    if (!ori_format_is_drawing(fmt)) {
        snprintf(err, err_size, "unsupported file type: %s (FOLD, SVG, OPX or CP)", name);
        return false;
    }
    if (ori_import_text(text, size, fmt, NULL, &p, NULL, &e) != ORI_OK) {
        error_line(err, err_size, &e);
        return false;
    }
    *doc = document_of(p);
    *model = studio_model_new(p);
    return true;
}

static bool load_file(const char *path, ori_fold **doc, studio_model **model, char *err, size_t err_size)
{
    ori_format fmt = ori_format_from_path(path);
    if (fmt == ORI_FORMAT_UNKNOWN) {
        snprintf(err, err_size, "%s: unsupported file type (FOLD, SVG, OPX, CP or a SEQ.json)", path);
        return false;
    }
    size_t limit = fmt == ORI_FORMAT_FOLD ? ORI_FOLD_MAX_BYTES : ORI_IMPORT_MAX_BYTES;
    char *text = NULL;
    size_t size = 0;
    ori_error e;
    if (ori_file_read_all(path, limit, &text, &size, &e) != ORI_OK) {
        char line[512];
        error_line(line, sizeof line, &e);
        snprintf(err, err_size, "%s: %s", path, line);
        return false;
    }
    char line[512];
    bool ok = studio_load_text(path, text, size, doc, model, line, sizeof line);
    ori_buffer_free(text);
    if (!ok) snprintf(err, err_size, "%s: %s", path, line);
    return ok;
}

static char *resolve_relative(const char *base, const char *rel)
{
    const char *slash = strrchr(base, '/');
    size_t dir = (rel[0] == '/' || !slash) ? 0 : (size_t)(slash - base) + 1;
    char *p = malloc(dir + strlen(rel) + 1);
    memcpy(p, base, dir);
    strcpy(p + dir, rel);
    return p;
}

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
            error_line(line, sizeof line, &e);
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

static bool blank_sheet(double side, ori_fold **doc, studio_model **model, char *err, size_t err_size)
{
    ori_v2 square[4] = {{0, 0}, {side, 0}, {side, side}, {0, side}};
    ori_pattern *p = NULL;
    ori_error e;
    if (ori_pattern_create_sheet(square, 4, &p, &e) != ORI_OK) {
        error_line(err, err_size, &e);
        return false;
    }
    *doc = document_of(p);
    *model = studio_model_new(p);
    return true;
}

int studio_create(const studio_def *def, studio **out, char *err, size_t err_size)
{
    *out = NULL;
    studio *s = calloc(1, sizeof *s);
    s->def = def ? *def : studio_default_def();
    pthread_mutex_init(&s->lock, NULL);
    pthread_mutex_init(&s->job_lock, NULL);
    ori_sequence *seq = NULL;
    bool ok;
    if (!s->def.path) {
        ok = blank_sheet(s->def.blank_side, &s->doc, &s->model, err, err_size);
        copy_string(s->file, sizeof s->file, "sheet.fold");
        s->format = ORI_FORMAT_FOLD;
    } else if (has_suffix(s->def.path, ".json") && !has_suffix(s->def.path, ".fold")) {
        // a fold sequence: its pattern is the document, and it runs at once
        ori_error e;
        ok = ori_sequence_load_file(s->def.path, &seq, &e) == ORI_OK;
        if (!ok) {
            char line[512];
            error_line(line, sizeof line, &e);
            snprintf(err, err_size, "%s: %s", s->def.path, line);
        } else {
            char *pattern = resolve_relative(s->def.path, ori_sequence_pattern_path(seq));
            ok = load_file(pattern, &s->doc, &s->model, err, err_size);
            copy_string(s->file, sizeof s->file, pattern);
            studio_utf8_clean(s->file);
            copy_string(s->save_path, sizeof s->save_path, pattern);
            copy_string(s->seq_path, sizeof s->seq_path, s->def.path);
            copy_string(s->seq_pattern_ref, sizeof s->seq_pattern_ref, ori_sequence_pattern_path(seq));
            free(pattern);
            s->format = s->save_format = ori_format_from_path(s->file);
            s->from_command_line = true;
        }
    } else {
        ok = load_file(s->def.path, &s->doc, &s->model, err, err_size);
        copy_string(s->file, sizeof s->file, s->def.path);
        studio_utf8_clean(s->file);
        copy_string(s->save_path, sizeof s->save_path, s->def.path);
        s->format = s->save_format = ori_format_from_path(s->def.path);
        s->from_command_line = true;
    }
    if (ok && s->model) install_model(s);
    if (ok && seq) {
        studio_response r;
        memset(&r, 0, sizeof r);
        studio_collide_opts opts = {false, 0.0};
        studio_run_sequence(s, seq, s->seq_path, &opts, &r);
        seq = NULL;
        if (r.status != 200) {
            // the body is {"error": "..."}: the message alone
            json_t *j = json_loadb(r.body, r.size, 0, NULL);
            const char *m = j ? json_string_value(json_object_get(j, "error")) : NULL;
            snprintf(err, err_size, "%s: %s", s->def.path, m ? m : "the sequence could not run");
            json_decref(j);
            ok = false;
        }
        studio_response_free(&r);
    }
    ori_sequence_destroy(seq);
    if (!ok) {
        studio_destroy(s);
        return 3;
    }
    // What is on disk now, and an autosave an earlier session left beside the file.
    if (s->from_command_line && s->save_path[0]) studio_disk_remember(&s->doc_disk, s->save_path);
    if (s->def.autosave && s->from_command_line && s->save_path[0]) {
        studio_journal_path(s->save_path, s->journal, sizeof s->journal);
        s->recovery = s->journal[0] && access(s->journal, F_OK) == 0;
    }
    if (s->seq_path[0]) studio_disk_remember(&s->seq_disk, s->seq_path);
    s->saved_model = studio_model_ref(s->model);
    *out = s;
    return 0;
}

void studio_destroy(studio *s)
{
    if (!s) return;
    studio_drop_results(s);
    clear_stack(s->undo, &s->undo_count);
    clear_stack(s->redo, &s->redo_count);
    studio_model_unref(s->model);
    studio_model_unref(s->saved_model);
    ori_fold_destroy(s->doc);
    pthread_mutex_destroy(&s->lock);
    pthread_mutex_destroy(&s->job_lock);
    free(s);
}

// --- responses ---------------------------------------------------------------------------------

void studio_response_free(studio_response *r)
{
    if (!r) return;
    free(r->body);
    r->body = NULL;
    r->size = 0;
}

static void set_body(studio_response *out, int status, const char *type, char *body, size_t size)
{
    free(out->body);
    out->status = status;
    out->content_type = type;
    out->body = body;
    out->size = size;
}

void studio_respond_text(studio_response *out, int status, const char *content_type, const char *text, size_t size)
{
    char *b = malloc(size + 1);
    memcpy(b, text, size);
    b[size] = '\0';
    set_body(out, status, content_type, b, size);
}

char *studio_json_text(json_t *value, size_t *size)
{
    char *raw = json_dumps(value, JSON_ENCODE_ANY | JSON_COMPACT | JSON_REAL_PRECISION(17));
    json_decref(value);
    char *text = raw ? ori_json_normalize(raw, false, NULL) : NULL;
    free(raw);
    if (!text) {
        if (size) *size = 4;
        return strdup("null");
    }
    size_t n = strlen(text);
    char *copy = malloc(n + 1);
    memcpy(copy, text, n + 1);
    ori_buffer_free(text);
    if (size) *size = n;
    return copy;
}

void studio_respond_json(studio_response *out, int status, json_t *value)
{
    size_t n;
    char *text = studio_json_text(value, &n);
    set_body(out, status, "application/json", text, n);
}

void studio_utf8_clean(char *s)
{
    unsigned char *p = (unsigned char *)s;
    while (*p) {
        int n = *p < 0x80 ? 1 : (*p & 0xE0) == 0xC0 ? 2 : (*p & 0xF0) == 0xE0 ? 3 : (*p & 0xF8) == 0xF0 ? 4 : 0;
        bool ok = n > 0;
        for (int k = 1; ok && k < n; ++k) ok = (p[k] & 0xC0) == 0x80;
        // overlong forms, surrogates and code points beyond U+10FFFF are not UTF-8 either
        if (ok && n == 2) ok = *p >= 0xC2;
        if (ok && n == 3) ok = !(*p == 0xE0 && p[1] < 0xA0) && !(*p == 0xED && p[1] >= 0xA0);
        if (ok && n == 4) ok = !(*p == 0xF0 && p[1] < 0x90) && !(*p == 0xF4 && p[1] >= 0x90) && *p <= 0xF4;
        if (!ok) {
            *p++ = '?';
            continue;
        }
        p += n;
    }
}

void studio_fail(studio_response *out, int status, const char *fmt, ...)
{
    char msg[640];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    for (char *c = msg; *c; ++c)
        if (*c == '\n' || *c == '\r' || *c == '\t') *c = ' ';
    // a message may quote the request (a name, a token of bad JSON): keep it valid UTF-8
    studio_utf8_clean(msg);
    studio_respond_json(out, status, json_pack("{s:s}", "error", msg));
}

int studio_status_of(ori_status st)
{
    return st == ORI_ERR_INTERNAL || st == ORI_ERR_NOT_CONVERGED || st == ORI_ERR_NOMEM ? 500 : 400;
}

void studio_fail_error(studio_response *out, int status, const ori_error *err)
{
    char line[512];
    error_line(line, sizeof line, err);
    studio_fail(out, status, "%s", line);
}

const char *studio_arg_get(const studio_request *req, const char *key)
{
    for (int i = 0; i < req->arg_count; ++i)
        if (req->args[i].key && strcmp(req->args[i].key, key) == 0) return req->args[i].value ? req->args[i].value : "";
    return NULL;
}

// --- request bodies ----------------------------------------------------------------------------

json_t *studio_body_object(const studio_request *req, studio_response *out)
{
    if (!req->body || req->body_size == 0) {
        studio_fail(out, 400, "the request needs a JSON object body");
        return NULL;
    }
    json_error_t je;
    json_t *o = json_loadb(req->body, req->body_size, JSON_REJECT_DUPLICATES, &je);
    if (!o) {
        studio_fail(out, 400, "malformed JSON: line %d, column %d: %s", je.line, je.column, je.text);
        return NULL;
    }
    if (!json_is_object(o)) {
        json_decref(o);
        studio_fail(out, 400, "the request body must be a JSON object");
        return NULL;
    }
    return o;
}

bool studio_check_keys(json_t *o, const char *const *keys, studio_response *out)
{
    const char *key;
    json_t *v;
    json_object_foreach(o, key, v) {
        bool known = false;
        for (int i = 0; keys[i] && !known; ++i) known = strcmp(keys[i], key) == 0;
        if (!known) {
            char list[400] = "";
            for (int i = 0; keys[i]; ++i) {
                strncat(list, i ? ", " : "", sizeof list - strlen(list) - 1);
                strncat(list, keys[i], sizeof list - strlen(list) - 1);
            }
            studio_fail(out, 400, "unknown field \"%.60s\" (fields: %s)", key, list);
            return false;
        }
    }
    return true;
}

bool studio_get_int(json_t *o, const char *key, bool required, int *out, bool *present, studio_response *res)
{
    json_t *v = json_object_get(o, key);
    if (present) *present = v != NULL;
    if (!v) {
        if (required) studio_fail(res, 400, "%s: missing (an integer)", key);
        return !required;
    }
    if (!json_is_integer(v) || json_integer_value(v) < -2147483647LL || json_integer_value(v) > 2147483647LL) {
        studio_fail(res, 400, "%s: must be an integer", key);
        return false;
    }
    *out = (int)json_integer_value(v);
    return true;
}

bool studio_get_number(json_t *o, const char *key, bool required, double *out, bool *present, studio_response *res)
{
    json_t *v = json_object_get(o, key);
    if (present) *present = v != NULL;
    if (!v) {
        if (required) studio_fail(res, 400, "%s: missing (a number)", key);
        return !required;
    }
    if (!json_is_number(v) || !isfinite(json_number_value(v))) {
        studio_fail(res, 400, "%s: must be a number", key);
        return false;
    }
    *out = json_number_value(v);
    return true;
}

bool studio_get_bool(json_t *o, const char *key, bool *out, studio_response *res)
{
    json_t *v = json_object_get(o, key);
    if (!v) return true;
    if (!json_is_boolean(v)) {
        studio_fail(res, 400, "%s: must be true or false", key);
        return false;
    }
    *out = json_is_true(v);
    return true;
}

bool studio_get_string(json_t *o, const char *key, bool required, const char **out, studio_response *res)
{
    json_t *v = json_object_get(o, key);
    if (!v) {
        if (required) studio_fail(res, 400, "%s: missing (a string)", key);
        return !required;
    }
    if (!json_is_string(v)) {
        studio_fail(res, 400, "%s: must be a string", key);
        return false;
    }
    *out = json_string_value(v);
    return true;
}

bool studio_get_numbers(json_t *o, const char *key, bool required, double *out, int n, bool *present,
                        studio_response *res)
{
    json_t *v = json_object_get(o, key);
    if (present) *present = v != NULL;
    if (!v) {
        if (required) studio_fail(res, 400, "%s: missing (an array of %d numbers)", key, n);
        return !required;
    }
    if (!json_is_array(v) || (int)json_array_size(v) != n) {
        studio_fail(res, 400, "%s: must be an array of %d numbers", key, n);
        return false;
    }
    for (int i = 0; i < n; ++i) {
        json_t *x = json_array_get(v, (size_t)i);
        if (!json_is_number(x) || !isfinite(json_number_value(x))) {
            studio_fail(res, 400, "%s: must be an array of %d numbers", key, n);
            return false;
        }
        out[i] = json_number_value(x);
    }
    return true;
}

bool studio_get_int_list(json_t *o, const char *key, int *out, int cap, int *count, studio_response *res)
{
    *count = 0;
    json_t *v = json_object_get(o, key);
    if (!v) return true;
    if (!json_is_array(v)) {
        studio_fail(res, 400, "%s: must be an array of integers", key);
        return false;
    }
    if ((int)json_array_size(v) > cap) {
        studio_fail(res, 400, "%s: more than %d entries", key, cap);
        return false;
    }
    for (size_t i = 0; i < json_array_size(v); ++i) {
        json_t *x = json_array_get(v, i);
        if (!json_is_integer(x) || json_integer_value(x) < -2147483647LL || json_integer_value(x) > 2147483647LL) {
            studio_fail(res, 400, "%s: must be an array of integers", key);
            return false;
        }
        out[(*count)++] = (int)json_integer_value(x);
    }
    return true;
}

// --- the job slot --------------------------------------------------------------------------------

bool studio_job_begin(studio *s, const char *name, studio_response *out)
{
    pthread_mutex_lock(&s->job_lock);
    if (s->busy) {
        double elapsed = studio_now() - s->job_start;
        char running[48];
        copy_string(running, sizeof running, s->job);
        pthread_mutex_unlock(&s->job_lock);
        studio_fail(out, 409, "busy: %s has been running for %.1f s; try again when it is done", running, elapsed);
        return false;
    }
    s->busy = true;
    copy_string(s->job, sizeof s->job, name);
    s->job_start = studio_now();
    s->job_fraction = -1.0;
    pthread_mutex_unlock(&s->job_lock);
    return true;
}

void studio_job_phase(studio *s, const char *name)
{
    pthread_mutex_lock(&s->job_lock);
    copy_string(s->job, sizeof s->job, name);
    s->job_fraction = -1.0;
    pthread_mutex_unlock(&s->job_lock);
}

bool studio_job_progress(double fraction, void *user)
{
    studio *s = user;
    pthread_mutex_lock(&s->job_lock);
    s->job_fraction = fraction < 0.0 ? 0.0 : fraction > 1.0 ? 1.0 : fraction;
    pthread_mutex_unlock(&s->job_lock);
    return true;
}

void studio_job_end(studio *s)
{
    pthread_mutex_lock(&s->job_lock);
    s->busy = false;
    s->job[0] = '\0';
    pthread_mutex_unlock(&s->job_lock);
}

void studio_api_progress(studio *s, const studio_request *req, studio_response *out)
{
    (void)req;
    pthread_mutex_lock(&s->job_lock);
    json_t *o = json_object();
    json_object_set_new(o, "busy", json_boolean(s->busy));
    json_object_set_new(o, "job", s->busy ? json_string(s->job) : json_null());
    json_object_set_new(o, "elapsed_s", s->busy ? json_real(studio_now() - s->job_start) : json_null());
    // Phases that report progress (sequence runs, the collision checks, exports) give the
    // fraction done; the others do not report one: the page shows the elapsed time.
    json_object_set_new(o, "fraction", s->busy && s->job_fraction >= 0.0 ? json_real(s->job_fraction) : json_null());
    pthread_mutex_unlock(&s->job_lock);
    studio_respond_json(out, 200, o);
}

// --- session, undo, redo ----------------------------------------------------------------------

void studio_api_session(studio *s, const studio_request *req, studio_response *out)
{
    (void)req;
    json_t *o = json_object();
    json_t *formats = json_array();
    for (int i = 0; i < studio_export_format_count(); ++i) {
        const studio_export_format *f = studio_export_format_at(i);
        static const char *const kinds[] = {"document", "picture", "mesh", "animation"};
        json_array_append_new(formats, json_pack("{s:s,s:s,s:s,s:s,s:s,s:b}", "format", f->name, "label", f->label,
                                                 "extension", f->extension, "mime", f->mime, "kind", kinds[f->kind],
                                                 "motion", f->motion));
    }
    json_t *coll = json_array();
    for (int i = 0; i < ori_collection_builtin_count(); ++i)
        json_array_append_new(coll, json_pack("{s:s,s:s}", "name", ori_collection_builtin_name(i), "summary",
                                              ori_collection_builtin_summary(i)));
    pthread_mutex_lock(&s->lock);
    json_object_set_new(o, "version", json_integer(s->version));
    json_object_set_new(o, "orikin", json_string(ori_version_string()));
    json_object_set_new(o, "file", json_string(s->file));
    json_object_set_new(o, "format", json_string(ori_format_name(s->format)));
    json_object_set_new(o, "frames", json_integer(ori_fold_frame_count(s->doc)));
    bool can_save = s->from_command_line && s->save_path[0];
    char shown[STUDIO_PATH_MAX];
    copy_string(shown, sizeof shown, s->save_path);
    studio_utf8_clean(shown);
    json_object_set_new(o, "save_path", can_save ? json_string(shown) : json_null());
    copy_string(shown, sizeof shown, s->seq_path);
    studio_utf8_clean(shown);
    json_object_set_new(o, "sequence_path", s->seq_path[0] ? json_string(shown) : json_null());
    json_object_set_new(o, "undo", json_integer(s->undo_count));
    json_object_set_new(o, "redo", json_integer(s->redo_count));
    json_object_set_new(o, "unsaved", json_boolean(s->model != s->saved_model));
    json_t *rec = json_null();
    if (s->recovery) {
        struct stat jst;
        copy_string(shown, sizeof shown, s->journal);
        studio_utf8_clean(shown);
        rec = json_pack("{s:s,s:I}", "path", shown, "modified",
                        (json_int_t)(stat(s->journal, &jst) == 0 ? (long long)jst.st_mtim.tv_sec : 0));
    }
    json_object_set_new(o, "recovery", rec);
    json_t *seq = json_null();
    if (s->seq) {
        seq = json_object();
        json_object_set_new(seq, "duration", json_real(ori_record_duration(s->seq->record)));
        json_object_set_new(seq, "valid", json_boolean(ori_record_verdict(s->seq->record) == ORI_MOTION_VALID));
        json_object_set_new(seq, "grid", json_integer(s->seq->grid));
        json_object_set_new(seq, "frames", json_integer(ori_record_frame_count(s->seq->record)));
        // the sequence collides at this time: later states are not clean (as orikin sequence --at)
        json_object_set_new(seq, "collision_t",
                            cli_collides(&s->seq->collision) ? json_real(s->seq->collision.ev.time) : json_null());
    }
    json_object_set_new(o, "sequence", seq);
    json_object_set_new(o, "fold_frames", s->fold ? json_integer(s->fold->clean_frames) : json_null());
    const ori_pattern *p = s->model->pattern;
    json_object_set_new(o, "vertices", json_integer(ori_pattern_vertex_count(p)));
    json_object_set_new(o, "edges", json_integer(ori_pattern_edge_count(p)));
    json_object_set_new(o, "faces", json_integer(ori_pattern_face_count(p)));
    json_object_set_new(o, "interior_vertices", json_integer(ori_pattern_interior_vertex_count(p)));
    pthread_mutex_unlock(&s->lock);
    json_object_set_new(o, "export_formats", formats);
    json_object_set_new(o, "collection", coll);
    json_object_set_new(o, "limits", json_pack("{s:I,s:I,s:f,s:i,s:i}", "max_body_bytes", (json_int_t)s->def.max_body_bytes,
                                               "max_open_bytes", (json_int_t)s->def.max_open_bytes, "work_limit",
                                               s->def.work_limit, "max_frames_per_fold", STUDIO_MAX_FRAMES_PER_FOLD,
                                               "undo_depth", STUDIO_UNDO_DEPTH));
    // Results that later capabilities add, each one more endpoint and one more overlay.
    json_object_set_new(o, "features", json_pack("{s:b,s:b,s:b,s:b}", "collisions", 1, "regularize", 1, "render", 1,
                                                 "actuation", 0));
    studio_respond_json(out, 200, o);
}

void studio_api_undo(studio *s, const studio_request *req, studio_response *out)
{
    (void)req;
    pthread_mutex_lock(&s->lock);
    bool ok = restore(s, s->undo, &s->undo_count, s->redo, &s->redo_count);
    long v = s->version;
    int u = s->undo_count, r = s->redo_count;
    pthread_mutex_unlock(&s->lock);
    if (!ok) {
        studio_fail(out, 409, "nothing to undo");
        return;
    }
    studio_respond_json(out, 200, json_pack("{s:I,s:i,s:i}", "version", (json_int_t)v, "undo", u, "redo", r));
}

void studio_api_redo(studio *s, const studio_request *req, studio_response *out)
{
    (void)req;
    pthread_mutex_lock(&s->lock);
    bool ok = restore(s, s->redo, &s->redo_count, s->undo, &s->undo_count);
    long v = s->version;
    int u = s->undo_count, r = s->redo_count;
    pthread_mutex_unlock(&s->lock);
    if (!ok) {
        studio_fail(out, 409, "nothing to redo");
        return;
    }
    studio_respond_json(out, 200, json_pack("{s:I,s:i,s:i}", "version", (json_int_t)v, "undo", u, "redo", r));
}

// --- dispatch ------------------------------------------------------------------------------------

typedef void studio_handler(studio *s, const studio_request *req, studio_response *out);

// The hook for actuation results: one more handler here and one more overlay in the page
// (features in GET /api/session says which exist); until then `orikin actuate` computes them.
static void api_actuate(studio *s, const studio_request *req, studio_response *out)
{
    (void)s;
    (void)req;
    studio_fail(out, 501, "actuation is not in the studio yet: use orikin actuate");
}

typedef struct route {
    const char *method;
    const char *path;
    studio_handler *fn;
} route;

static const route routes[] = {
    {"GET", "/api/session", studio_api_session},
    {"GET", "/api/progress", studio_api_progress},
    {"GET", "/api/document", studio_api_document},
    {"GET", "/api/tree", studio_api_tree},
    {"GET", "/api/info", studio_api_info},
    {"GET", "/api/check", studio_api_check},
    {"POST", "/api/dof", studio_api_dof},
    {"GET", "/api/mechanism", studio_api_mechanism},
    {"POST", "/api/new", studio_api_new},
    {"POST", "/api/open", studio_api_open},
    {"POST", "/api/apply", studio_api_apply},
    {"POST", "/api/crease", studio_api_crease},
    {"POST", "/api/axiom", studio_api_axiom},
    {"POST", "/api/edit", studio_api_edit},
    {"POST", "/api/undo", studio_api_undo},
    {"POST", "/api/redo", studio_api_redo},
    {"POST", "/api/save", studio_api_save},
    {"POST", "/api/recover", studio_api_recover},
    {"GET", "/api/export", studio_api_export},
    {"POST", "/api/fold", studio_api_fold},
    {"GET", "/api/fold/frame", studio_api_fold_frame},
    {"POST", "/api/sequence", studio_api_sequence},
    {"GET", "/api/sequence", studio_api_sequence_get},
    {"GET", "/api/sequence/at", studio_api_sequence_at},
    {"GET", "/api/contact", studio_api_contact},
    {"GET", "/api/frames", studio_api_frames},
    {"POST", "/api/collide", studio_api_collide},
    {"POST", "/api/regularize", studio_api_regularize},
    {"POST", "/api/actuate", api_actuate},
};

void studio_handle(studio *s, const studio_request *req, studio_response *out)
{
    memset(out, 0, sizeof *out);
    const char *path = req->path ? req->path : "";
    const char *method = req->method ? req->method : "";
    bool path_known = false;
    for (size_t i = 0; i < sizeof routes / sizeof routes[0]; ++i) {
        if (strcmp(routes[i].path, path) != 0) continue;
        path_known = true;
        if (strcmp(routes[i].method, method) != 0) continue;
        if (req->body_size > studio_body_limit(s, path)) {
            studio_fail(out, 413, "request body of %zu bytes is over the limit of %zu bytes", req->body_size,
                        studio_body_limit(s, path));
            return;
        }
        routes[i].fn(s, req, out);
        if (out->status == 0) studio_fail(out, 500, "internal error: no response");
        return;
    }
    if (path_known) studio_fail(out, 405, "%s is not allowed on %.100s", method, path);
    else studio_fail(out, 404, "no such API endpoint: %.100s", path);
}

size_t studio_body_limit(const studio *s, const char *path)
{
    return path && strcmp(path, "/api/open") == 0 ? s->def.max_open_bytes : s->def.max_body_bytes;
}

bool studio_token_make(char *out, size_t size)
{
    unsigned char bytes[STUDIO_TOKEN_BYTES];
    if (size < 2 * STUDIO_TOKEN_BYTES + 1) return false;
    size_t got = 0;
    while (got < sizeof bytes) {
        ssize_t n = getrandom(bytes + got, sizeof bytes - got, 0);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        got += (size_t)n;
    }
    if (got < sizeof bytes) {
        int fd = open("/dev/urandom", O_RDONLY);
        if (fd < 0) return false;
        while (got < sizeof bytes) {
            ssize_t n = read(fd, bytes + got, sizeof bytes - got);
            if (n <= 0) break;
            got += (size_t)n;
        }
        close(fd);
        if (got < sizeof bytes) return false;
    }
    for (size_t i = 0; i < sizeof bytes; ++i) snprintf(out + 2 * i, 3, "%02x", bytes[i]);
    return true;
}
