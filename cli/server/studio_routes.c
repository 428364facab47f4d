// The studio's API dispatch: the route table and the handlers of the session itself
// (progress, session). Routes call down into the handlers (studio_author.c, studio_kin.c, …),
// which call the document (studio_doc.c) and the request helpers (studio_request.c); nothing
// calls back up into this file.
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
    {"POST", "/api/compliant", studio_api_compliant},
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
