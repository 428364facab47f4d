// The studio's document: its models and computed results, the undo and redo stacks, loading
// what `orikin view` is given, and creating and destroying a studio. Handlers and the router
// call down into it; it calls only the request helpers (studio_request.c) and the disk.
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

static void copy_string(char *dst, size_t size, const char *src)
{
    snprintf(dst, size, "%s", src ? src : "");
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
    studio_cfold_unref(s->compliant);
    s->compliant = NULL;
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

// The loaders' name for studio_error_line (kept so that their bodies read as before).
static void error_line(char *buf, size_t size, const ori_error *err) { studio_error_line(buf, size, err); }

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
        ori_build_def bd = ori_default_build_def();
        bd.planarize = true; // as the CLI loads it (cli_load_pattern)
        if (ori_fold_get_pattern(d, 0, &bd, &p, &e) != ORI_OK) {
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
            char *pattern = cli_path_beside(s->def.path, ori_sequence_pattern_path(seq));
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

// --- undo, redo -----------------------------------------------------------------------------

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

// --- recovery ---------------------------------------------------------------------------------

// POST /api/recover {"action": "recover" | "discard"}: the journal an earlier session left
// becomes the document (an undoable step; save-back still writes the command-line file), or is
// removed.
void studio_api_recover(studio *s, const studio_request *req, studio_response *out)
{
    json_t *o = studio_body_object(req, out);
    if (!o) return;
    static const char *const keys[] = {"action", NULL};
    const char *action = NULL;
    if (!studio_check_keys(o, keys, out) || !studio_get_string(o, "action", true, &action, out)) {
        json_decref(o);
        return;
    }
    bool recover = strcmp(action, "recover") == 0, discard = strcmp(action, "discard") == 0;
    json_decref(o);
    if (!recover && !discard) {
        studio_fail(out, 400, "action: \"recover\" or \"discard\"");
        return;
    }
    pthread_mutex_lock(&s->lock);
    if (!s->recovery) {
        pthread_mutex_unlock(&s->lock);
        studio_fail(out, 409, "there is no autosave to recover");
        return;
    }
    if (recover) {
        size_t size = 0;
        char *text = NULL;
        ori_error err;
        if (ori_file_read_all(s->journal, s->def.max_open_bytes, &text, &size, &err) != ORI_OK) {
            pthread_mutex_unlock(&s->lock);
            studio_fail_error(out, 500, &err);
            return;
        }
        ori_fold *doc = NULL;
        studio_model *m = NULL;
        char msg[600];
        bool ok = studio_load_text("autosave.fold", text, size, &doc, &m, msg, sizeof msg);
        ori_buffer_free(text);
        if (!ok) {
            pthread_mutex_unlock(&s->lock);
            studio_fail(out, 409, "the autosave %s cannot be read (%s): discard it", s->journal, msg);
            return;
        }
        s->recovery = false;
        studio_commit_document(s, doc, m, s->file, s->format, true); // writes the journal anew
    } else {
        s->recovery = false;
        unlink(s->journal);
    }
    json_t *r = json_pack("{s:I,s:i,s:i,s:b}", "version", (json_int_t)s->version, "undo", s->undo_count, "redo",
                          s->redo_count, "recovered", recover);
    pthread_mutex_unlock(&s->lock);
    studio_respond_json(out, 200, r);
}
