// Authoring endpoints: the document and its face tree, a new sheet, opening a file, collection
// patterns, axiom creases, edits of existing creases, undo history, checks, export and
// save-back. Each edit works on a clone of the current pattern and becomes the new document
// only when the library accepted it.
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "studio_internal.h"

static void copy_string(char *dst, size_t size, const char *src)
{
    snprintf(dst, size, "%s", src ? src : "");
}

// --- reading the document ------------------------------------------------------------------

void studio_api_document(studio *s, const studio_request *req, studio_response *out)
{
    (void)req;
    pthread_mutex_lock(&s->lock);
    char *text = ori_fold_to_string(s->doc);
    pthread_mutex_unlock(&s->lock);
    studio_respond_text(out, 200, "application/json", text, strlen(text));
    ori_buffer_free(text);
}

// The current model (a reference) and file label, read under the lock.
static studio_model *current(studio *s, char *file, size_t size)
{
    pthread_mutex_lock(&s->lock);
    studio_model *m = studio_model_ref(s->model);
    if (file) copy_string(file, size, s->file);
    pthread_mutex_unlock(&s->lock);
    return m;
}

void studio_api_tree(studio *s, const studio_request *req, studio_response *out)
{
    (void)req;
    char file[STUDIO_PATH_MAX];
    studio_model *m = current(s, file, sizeof file);
    studio_respond_json(out, 200, cli_tree_json(file, m->pattern));
    studio_model_unref(m);
}

void studio_api_info(studio *s, const studio_request *req, studio_response *out)
{
    (void)req;
    pthread_mutex_lock(&s->lock);
    json_t *o = cli_info_json(s->file, 0, ori_fold_frame_count(s->doc), s->model->pattern);
    pthread_mutex_unlock(&s->lock);
    studio_respond_json(out, 200, o);
}

static bool parse_frame_arg(const studio_request *req, int *frame, studio_response *out)
{
    const char *v = studio_arg_get(req, "frame");
    *frame = 0;
    if (!v) return true;
    char *end;
    long x = strtol(v, &end, 10);
    if (end == v || *end || x < 0 || x > 1000000000L) {
        studio_fail(out, 400, "frame: must be a frame number >= 0");
        return false;
    }
    *frame = (int)x;
    return true;
}

// GET /api/check?frame=N&tolerance_deg=D: what `orikin check FILE --frame N --tolerance D --json`
// prints (the same builder, cli/report).
void studio_api_check(studio *s, const studio_request *req, studio_response *out)
{
    int frame;
    if (!parse_frame_arg(req, &frame, out)) return;
    const char *tv = studio_arg_get(req, "tolerance_deg");
    double tol = 0.0;
    if (tv) {
        char *end;
        tol = strtod(tv, &end);
        if (end == tv || *end || !(tol >= 0.0 && tol <= 1.0)) {
            studio_fail(out, 400, "tolerance_deg: an angle in degrees in [0, 1]");
            return;
        }
    }
    char file[STUDIO_PATH_MAX];
    studio_model *m = NULL;
    ori_pattern *other = NULL;
    pthread_mutex_lock(&s->lock);
    copy_string(file, sizeof file, s->file);
    int frames = ori_fold_frame_count(s->doc);
    ori_error err;
    ori_status st = ORI_OK;
    if (frame >= frames) {
        pthread_mutex_unlock(&s->lock);
        studio_fail(out, 400, "frame %d does not exist (frames 0 to %d)", frame, frames - 1);
        return;
    }
    if (frame == 0) m = studio_model_ref(s->model);
    else st = ori_fold_get_pattern(s->doc, frame, NULL, &other, &err);
    pthread_mutex_unlock(&s->lock);
    if (st != ORI_OK) {
        studio_fail_error(out, 400, &err);
        return;
    }
    const ori_pattern *p = m ? m->pattern : other;
    cli_check chk;
    cli_check_run(p, file, tv != NULL, tol, &chk);
    studio_respond_json(out, 200, cli_check_json(&chk, file, frame, p));
    cli_check_free(&chk);
    studio_model_unref(m);
    ori_pattern_destroy(other);
}

// Why regularize refuses, as `orikin regularize` says it (NULL: it succeeded).
// POST /api/regularize {rigid, max_move}: `orikin regularize --json` on the document's crease
// pattern; when it succeeds the regularized pattern becomes the document (undoable).
void studio_api_regularize(studio *s, const studio_request *req, studio_response *out)
{
    json_t *o = studio_body_object(req, out);
    if (!o) return;
    static const char *const keys[] = {"rigid", "max_move", NULL};
    ori_regularize_def def = ori_default_regularize_def();
    bool rigid = false, ok = studio_check_keys(o, keys, out) && studio_get_bool(o, "rigid", &rigid, out) &&
                            studio_get_number(o, "max_move", false, &def.max_move_rel, NULL, out);
    json_decref(o);
    if (!ok) return;
    def.rigid = rigid;
    char mistake[200];
    if (cli_regularize_request_error(&def, "max_move", mistake, sizeof mistake)) {
        studio_fail(out, 400, "%s", mistake);
        return;
    }
    if (!studio_job_begin(s, "regularize", out)) return;
    char file[STUDIO_PATH_MAX];
    pthread_mutex_lock(&s->lock);
    studio_model *model = studio_model_ref(s->model);
    long version = s->version;
    copy_string(file, sizeof file, s->file);
    pthread_mutex_unlock(&s->lock);
    const ori_pattern *p = model->pattern;
    ori_regularize_result r;
    ori_pattern *q = NULL;
    ori_error err;
    if (cli_regularize_pattern_error(p, 0, mistake, sizeof mistake)) {
        studio_fail(out, 400, "%s", mistake);
    } else {
        ori_status st = ori_regularize(p, &def, &q, &r, &err);
        if (st != ORI_OK) {
            studio_fail_error(out, studio_status_of(st), &err);
        } else {
            char buf[320];
            const char *why = cli_regularize_refusal(&r, &def, buf, sizeof buf);
            json_t *j = cli_regularize_json(file, &def, &r, why, NULL);
            bool replaced = false;
            pthread_mutex_lock(&s->lock);
            if (!why && q && s->version == version) {
                studio_commit(s, studio_model_new(q));
                q = NULL;
                replaced = true;
            }
            json_object_set_new(j, "replaced", json_boolean(replaced));
            json_object_set_new(j, "version", json_integer(s->version));
            json_object_set_new(j, "undo", json_integer(s->undo_count));
            json_object_set_new(j, "redo", json_integer(s->redo_count));
            pthread_mutex_unlock(&s->lock);
            if (!why && !replaced) {
                json_decref(j);
                studio_fail(out, 409, "the document changed while regularize ran: nothing was replaced");
            } else {
                studio_respond_json(out, 200, j);
            }
        }
    }
    ori_pattern_destroy(q);
    studio_model_unref(model);
    studio_job_end(s);
}

// --- changing the document -----------------------------------------------------------------

// Publish an edited pattern. A change of topology drops the document's other frames (states of
// the old pattern), as `orikin edit` does; the document is then replaced, so undo brings them back.
static void commit_edit(studio *s, ori_pattern *p)
{
    bool topology = ori_pattern_edge_count(p) != ori_pattern_edge_count(s->model->pattern) ||
                    ori_pattern_vertex_count(p) != ori_pattern_vertex_count(s->model->pattern);
    studio_model *m = studio_model_new(p);
    if (topology && ori_fold_frame_count(s->doc) > 1) {
        char *text = ori_fold_to_string(s->doc);
        ori_fold *copy = NULL;
        ori_error err;
        if (ori_fold_load_string(text, strlen(text), &copy, &err) == ORI_OK) {
            ori_fold_set_custom(copy, 0, "file_frames", NULL, NULL);
            studio_commit_document(s, copy, m, s->file, s->format, s->from_command_line);
            ori_buffer_free(text);
            return;
        }
        ori_buffer_free(text);
    }
    studio_commit(s, m);
}

static json_t *version_json(studio *s)
{
    return json_pack("{s:I,s:i,s:i}", "version", (json_int_t)s->version, "undo", s->undo_count, "redo", s->redo_count);
}

void studio_api_new(studio *s, const studio_request *req, studio_response *out)
{
    json_t *o = studio_body_object(req, out);
    if (!o) return;
    static const char *const keys[] = {"square", "rect", "polygon", "title", NULL};
    double square = 0.0, rect[2];
    bool has_square = false, has_rect = false;
    const char *title = NULL;
    json_t *poly = json_object_get(o, "polygon");
    if (!studio_check_keys(o, keys, out) || !studio_get_number(o, "square", false, &square, &has_square, out) ||
        !studio_get_numbers(o, "rect", false, rect, 2, &has_rect, out) || !studio_get_string(o, "title", false, &title, out)) {
        json_decref(o);
        return;
    }
    if ((int)has_square + (int)has_rect + (int)(poly != NULL) != 1) {
        json_decref(o);
        studio_fail(out, 400, "give one of square (a side), rect ([width, height]) or polygon ([[x, y], ...])");
        return;
    }
    ori_v2 *pts = NULL;
    int n = 0;
    if (has_square || has_rect) {
        double w = has_square ? square : rect[0], h = has_square ? square : rect[1];
        if (!(w > 0.0 && h > 0.0 && w <= ORI_COORD_MAX && h <= ORI_COORD_MAX)) {
            json_decref(o);
            studio_fail(out, 400, "%s: sides must be positive", has_square ? "square" : "rect");
            return;
        }
        pts = malloc(4 * sizeof *pts);
        pts[0] = ori_v2_make(0, 0);
        pts[1] = ori_v2_make(w, 0);
        pts[2] = ori_v2_make(w, h);
        pts[3] = ori_v2_make(0, h);
        n = 4;
    } else {
        if (!json_is_array(poly) || json_array_size(poly) < 3 || json_array_size(poly) > 100000) {
            json_decref(o);
            studio_fail(out, 400, "polygon: must be an array of at least 3 points [x, y]");
            return;
        }
        n = (int)json_array_size(poly);
        pts = malloc(sizeof *pts * (size_t)n);
        for (int i = 0; i < n; ++i) {
            json_t *p = json_array_get(poly, (size_t)i);
            json_t *x = json_array_get(p, 0), *y = json_array_get(p, 1);
            if (!json_is_array(p) || json_array_size(p) != 2 || !json_is_number(x) || !json_is_number(y) ||
                !(fabs(json_number_value(x)) <= ORI_COORD_MAX) || !(fabs(json_number_value(y)) <= ORI_COORD_MAX)) {
                free(pts);
                json_decref(o);
                studio_fail(out, 400, "polygon %d: must be a point [x, y] of finite numbers", i);
                return;
            }
            pts[i] = ori_v2_make(json_number_value(x), json_number_value(y));
        }
    }
    ori_pattern *p = NULL;
    ori_error err;
    ori_status st = ori_pattern_create_sheet(pts, n, &p, &err);
    free(pts);
    if (st != ORI_OK) {
        json_decref(o);
        studio_fail_error(out, 400, &err);
        return;
    }
    ori_fold *doc = ori_fold_create();
    if (title) ori_fold_set_string(doc, 0, "file_title", title);
    json_decref(o);
    pthread_mutex_lock(&s->lock);
    studio_commit_document(s, doc, studio_model_new(p), "sheet.fold", ORI_FORMAT_FOLD, false);
    json_t *r = version_json(s);
    pthread_mutex_unlock(&s->lock);
    studio_respond_json(out, 200, r);
}

void studio_api_open(studio *s, const studio_request *req, studio_response *out)
{
    const char *name = studio_arg_get(req, "name");
    if (!name || !*name || strlen(name) >= 512) {
        studio_fail(out, 400, "name: the file's name is needed (its extension gives the format)");
        return;
    }
    // Only the name's extension is used: nothing from a request ever reaches the file system.
    const char *slash = strrchr(name, '/');
    char base[512];
    copy_string(base, sizeof base, slash ? slash + 1 : name);
    studio_utf8_clean(base);
    ori_fold *doc = NULL;
    studio_model *m = NULL;
    char err[600];
    if (!studio_load_text(base, req->body ? req->body : "", req->body ? req->body_size : 0, &doc, &m, err, sizeof err)) {
        studio_fail(out, 400, "%s: %s", base, err);
        return;
    }
    pthread_mutex_lock(&s->lock);
    studio_commit_document(s, doc, m, base, ori_format_from_path(base), false);
    json_t *r = version_json(s);
    pthread_mutex_unlock(&s->lock);
    studio_respond_json(out, 200, r);
}

// A face given by index or name (as the CLI's --face). False after a 400.
static bool find_face(const ori_pattern *p, json_t *spec, int *face, studio_response *out)
{
    if (json_is_integer(spec)) {
        json_int_t i = json_integer_value(spec);
        if (i < 0 || i >= ori_pattern_face_count(p)) {
            studio_fail(out, 400, "face %lld does not exist (faces 0 to %d)", (long long)i, ori_pattern_face_count(p) - 1);
            return false;
        }
        *face = (int)i;
        return true;
    }
    if (!json_is_string(spec)) {
        studio_fail(out, 400, "face: must be a face index or name (Obj12)");
        return false;
    }
    const char *name = json_string_value(spec);
    int idx = ori_pattern_find_face_by_name(p, name);
    if (idx == ORI_NULL_INDEX) {
        if (ori_pattern_find_tree_node(p, name) != ORI_NULL_INDEX)
            studio_fail(out, 400, "%.64s is not a folding element any more (it was split)", name);
        else studio_fail(out, 400, "no face named %.64s", name);
        return false;
    }
    *face = idx;
    return true;
}

static bool parse_assign(json_t *o, bool *has, ori_assignment *a, studio_response *out)
{
    const char *v = NULL;
    *has = false;
    if (!studio_get_string(o, "assign", false, &v, out)) return false;
    if (!v) return true;
    if (strlen(v) != 1 || !ori_assignment_from_char(v[0], a) ||
        !(*a == ORI_ASSIGN_MOUNTAIN || *a == ORI_ASSIGN_VALLEY || *a == ORI_ASSIGN_FLAT || *a == ORI_ASSIGN_UNASSIGNED)) {
        studio_fail(out, 400, "assign: must be \"M\", \"V\", \"F\" or \"U\"");
        return false;
    }
    *has = true;
    return true;
}

static json_t *apply_json(studio *s, const ori_pattern *p, int nodes_before, const char *target, const ori_apply_result *r)
{
    json_t *o = version_json(s);
    json_object_set_new(o, "applied_to", json_string(target));
    cli_apply_counts_json(o, r);
    json_t *faces = cli_apply_new_faces_json(p, nodes_before);
    json_object_set_new(o, "new_faces", faces);
    return o;
}

void studio_api_apply(studio *s, const studio_request *req, studio_response *out)
{
    json_t *o = studio_body_object(req, out);
    if (!o) return;
    static const char *const keys[] = {"pattern", "face", "assign", NULL};
    bool has_asg;
    ori_assignment asg = ORI_ASSIGN_UNASSIGNED;
    json_t *pat = json_object_get(o, "pattern"), *face_spec = json_object_get(o, "face");
    if (!studio_check_keys(o, keys, out) || !parse_assign(o, &has_asg, &asg, out)) {
        json_decref(o);
        return;
    }
    if (!pat || !face_spec) {
        json_decref(o);
        studio_fail(out, 400, "%s: missing", pat ? "face" : "pattern");
        return;
    }
    ori_composite *comp = NULL;
    ori_error err;
    ori_status st;
    if (json_is_string(pat)) {
        st = ori_composite_builtin(json_string_value(pat), &comp, &err);
    } else if (json_is_object(pat)) {
        char *text = json_dumps(pat, JSON_COMPACT | JSON_REAL_PRECISION(17));
        st = ori_composite_load_string(text, strlen(text), &comp, &err);
        free(text);
    } else {
        json_decref(o);
        studio_fail(out, 400, "pattern: must be a built-in name or a composite object");
        return;
    }
    if (st != ORI_OK) {
        json_decref(o);
        studio_fail_error(out, 400, &err);
        return;
    }
    pthread_mutex_lock(&s->lock);
    int face;
    if (find_face(s->model->pattern, face_spec, &face, out)) {
        ori_pattern *p = ori_pattern_clone(s->model->pattern);
        int nodes = ori_pattern_tree_node_count(p);
        char target[ORI_NAME_MAX + 16];
        cli_face_label(p, face, target, sizeof target);
        ori_apply_result r;
        st = ori_pattern_apply_composite(p, comp, face, has_asg ? &asg : NULL, &r, &err);
        if (st != ORI_OK) {
            ori_pattern_destroy(p);
            studio_fail_error(out, studio_status_of(st), &err);
        } else {
            json_t *res = apply_json(s, p, nodes, target, &r);
            commit_edit(s, p);
            json_object_set_new(res, "version", json_integer(s->version));
            json_object_set_new(res, "undo", json_integer(s->undo_count));
            studio_respond_json(out, 200, res);
        }
    }
    pthread_mutex_unlock(&s->lock);
    ori_composite_destroy(comp);
    json_decref(o);
}

// --- axioms --------------------------------------------------------------------------------

enum { IN_P1 = 1, IN_P2 = 2, IN_L1 = 4, IN_L2 = 8 };
static const int axiom_needs[8] = {0, IN_P1 | IN_P2, IN_P1 | IN_P2, IN_L1 | IN_L2, IN_P1 | IN_L1, IN_P1 | IN_P2 | IN_L1,
                                   IN_P1 | IN_P2 | IN_L1 | IN_L2, IN_P1 | IN_L1 | IN_L2};
static const char *const axiom_inputs[8] = {"", "p1, p2", "p1, p2", "l1, l2", "p1, l1", "p1, p2, l1", "p1, p2, l1, l2",
                                            "p1, l1, l2"};

// The axiom and its inputs from a request: {"axiom": N, "p1": [x, y], "l1": [x, y, dx, dy], …}.
static bool parse_axiom(json_t *o, ori_axiom_input *in, studio_response *out)
{
    memset(in, 0, sizeof *in);
    if (!studio_get_int(o, "axiom", true, &in->axiom, NULL, out)) return false;
    if (in->axiom < 1 || in->axiom > 7) {
        studio_fail(out, 400, "axiom: a number from 1 to 7");
        return false;
    }
    int given = 0;
    bool present;
    double x[4];
    if (!studio_get_numbers(o, "p1", false, x, 2, &present, out)) return false;
    if (present) in->p1 = ori_v2_make(x[0], x[1]), given |= IN_P1;
    if (!studio_get_numbers(o, "p2", false, x, 2, &present, out)) return false;
    if (present) in->p2 = ori_v2_make(x[0], x[1]), given |= IN_P2;
    const char *lk[2] = {"l1", "l2"};
    for (int k = 0; k < 2; ++k) {
        if (!studio_get_numbers(o, lk[k], false, x, 4, &present, out)) return false;
        if (!present) continue;
        if (x[2] == 0.0 && x[3] == 0.0) {
            studio_fail(out, 400, "%s: the direction dx, dy must not be zero", lk[k]);
            return false;
        }
        ori_line l = {ori_v2_make(x[0], x[1]), ori_v2_make(x[2], x[3])};
        *(k == 0 ? &in->l1 : &in->l2) = l;
        given |= k == 0 ? IN_L1 : IN_L2;
    }
    for (int k = 0; k < 2; ++k) {
        ori_v2 p = k == 0 ? in->p1 : in->p2;
        if (!(fabs(p.x) <= ORI_COORD_MAX && fabs(p.y) <= ORI_COORD_MAX)) {
            studio_fail(out, 400, "p%d: coordinates beyond %g", k + 1, ORI_COORD_MAX);
            return false;
        }
        ori_line l = k == 0 ? in->l1 : in->l2;
        if (!(fabs(l.point.x) <= ORI_COORD_MAX && fabs(l.point.y) <= ORI_COORD_MAX && fabs(l.dir.x) <= ORI_COORD_MAX &&
              fabs(l.dir.y) <= ORI_COORD_MAX)) {
            studio_fail(out, 400, "l%d: coordinates beyond %g", k + 1, ORI_COORD_MAX);
            return false;
        }
    }
    if (given != axiom_needs[in->axiom]) {
        studio_fail(out, 400, "axiom %d takes %s%s", in->axiom, axiom_inputs[in->axiom],
                    (given & ~axiom_needs[in->axiom]) ? "; other inputs were given" : "");
        return false;
    }
    return true;
}

void studio_api_axiom(studio *s, const studio_request *req, studio_response *out)
{
    json_t *o = studio_body_object(req, out);
    if (!o) return;
    static const char *const keys[] = {"axiom", "p1", "p2", "l1", "l2", "face", NULL};
    ori_axiom_input in;
    if (!studio_check_keys(o, keys, out) || !parse_axiom(o, &in, out)) {
        json_decref(o);
        return;
    }
    ori_line_set set = ori_axiom_solve(&in);
    json_t *res = cli_axiom_json(in.axiom, &set);
    // Each solution clipped to the target face (or the whole sheet), for drawing.
    pthread_mutex_lock(&s->lock);
    const ori_pattern *p = s->model->pattern;
    int face = ORI_NULL_INDEX;
    json_t *fs = json_object_get(o, "face");
    if (fs && !find_face(p, fs, &face, out)) {
        pthread_mutex_unlock(&s->lock);
        json_decref(res);
        json_decref(o);
        return;
    }
    int cap = 2 * (ori_pattern_face_count(p) + 1);
    double *t = malloc(sizeof(double) * 2 * (size_t)cap);
    json_t *segs = json_array();
    for (int k = 0; k < set.count; ++k) {
        ori_line l = set.lines[k];
        ori_crease c;
        c.a = l.point;
        c.b = ori_v2_add(l.point, l.dir);
        c.infinite = true;
        c.assignment = ORI_ASSIGN_UNASSIGNED;
        c.fold_angle_rad = 0.0;
        int n = ori_pattern_clip_crease(p, &c, face, t, cap);
        if (n > cap) n = cap;
        json_t *pieces = json_array();
        for (int i = 0; i < n; ++i) {
            ori_v2 a = ori_v2_add(c.a, ori_v2_scale(l.dir, t[2 * i])), b = ori_v2_add(c.a, ori_v2_scale(l.dir, t[2 * i + 1]));
            json_array_append_new(pieces, json_pack("[ffff]", a.x, a.y, b.x, b.y));
        }
        json_array_append_new(segs, pieces);
    }
    pthread_mutex_unlock(&s->lock);
    free(t);
    json_object_set_new(res, "segments", segs);
    json_decref(o);
    studio_respond_json(out, 200, res);
}

void studio_api_crease(studio *s, const studio_request *req, studio_response *out)
{
    json_t *o = studio_body_object(req, out);
    if (!o) return;
    static const char *const keys[] = {"axiom", "p1", "p2", "l1", "l2", "solution", "line", "face", "all", "assign", NULL};
    bool has_asg, all = false, has_line, has_solution;
    ori_assignment asg = ORI_ASSIGN_UNASSIGNED;
    double line[4];
    int solution = 1;
    if (!studio_check_keys(o, keys, out) || !parse_assign(o, &has_asg, &asg, out) ||
        !studio_get_bool(o, "all", &all, out) || !studio_get_numbers(o, "line", false, line, 4, &has_line, out) ||
        !studio_get_int(o, "solution", false, &solution, &has_solution, out)) {
        json_decref(o);
        return;
    }
    bool has_axiom = json_object_get(o, "axiom") != NULL;
    json_t *face_spec = json_object_get(o, "face");
    if (has_axiom == has_line) {
        json_decref(o);
        studio_fail(out, 400, "give either axiom (with its inputs) or line [x1, y1, x2, y2]");
        return;
    }
    if (all == (face_spec != NULL)) {
        json_decref(o);
        studio_fail(out, 400, "give either face (a name or index) or \"all\": true");
        return;
    }
    ori_crease c;
    c.infinite = true;
    c.assignment = asg;
    c.fold_angle_rad = 0.0;
    char what[64];
    if (has_line) {
        if (json_object_get(o, "p1") || json_object_get(o, "p2") || json_object_get(o, "l1") || json_object_get(o, "l2") ||
            has_solution) {
            json_decref(o);
            studio_fail(out, 400, "line takes no other axiom inputs");
            return;
        }
        for (int i = 0; i < 4; ++i)
            if (!(fabs(line[i]) <= ORI_COORD_MAX)) {
                json_decref(o);
                studio_fail(out, 400, "line: coordinates beyond %g", ORI_COORD_MAX);
                return;
            }
        c.a = ori_v2_make(line[0], line[1]);
        c.b = ori_v2_make(line[2], line[3]);
        snprintf(what, sizeof what, "the line");
    } else {
        ori_axiom_input in;
        if (!parse_axiom(o, &in, out)) {
            json_decref(o);
            return;
        }
        ori_line_set set = ori_axiom_solve(&in);
        if (set.count == 0) {
            json_decref(o);
            studio_fail(out, 400, "axiom %d has no solution for these inputs", in.axiom);
            return;
        }
        if (!has_solution && set.count > 1) {
            json_decref(o);
            studio_fail(out, 400, "axiom %d has %d solutions here: choose one with solution 1 to %d", in.axiom, set.count,
                        set.count);
            return;
        }
        char mistake[160];
        if (cli_axiom_solution_error(in.axiom, solution, set.count, mistake, sizeof mistake)) {
            json_decref(o);
            studio_fail(out, 400, "%s", mistake);
            return;
        }
        ori_line l = set.lines[solution - 1];
        c.a = l.point;
        c.b = ori_v2_add(l.point, l.dir);
        snprintf(what, sizeof what, "axiom %d solution %d", in.axiom, solution);
    }
    pthread_mutex_lock(&s->lock);
    int face = ORI_NULL_INDEX;
    if (!face_spec || find_face(s->model->pattern, face_spec, &face, out)) {
        ori_pattern *p = ori_pattern_clone(s->model->pattern);
        int nodes = ori_pattern_tree_node_count(p);
        char target[ORI_NAME_MAX + 16];
        cli_face_label(p, face, target, sizeof target);
        ori_apply_result r;
        ori_error err;
        ori_status st = ori_pattern_apply_crease(p, &c, face, &r, &err);
        if (st != ORI_OK) {
            ori_pattern_destroy(p);
            studio_fail_error(out, studio_status_of(st), &err);
        } else {
            json_t *res = apply_json(s, p, nodes, target, &r);
            json_object_set_new(res, "crease", json_string(what));
            commit_edit(s, p);
            json_object_set_new(res, "version", json_integer(s->version));
            json_object_set_new(res, "undo", json_integer(s->undo_count));
            studio_respond_json(out, 200, res);
        }
    }
    pthread_mutex_unlock(&s->lock);
    json_decref(o);
}

// --- edits of existing creases ---------------------------------------------------------------

enum op_kind { OP_ASSIGN, OP_FLIP, OP_REMOVE, OP_MOVE };

// The current index of the edge an operation names: an index in the document before the request
// (tracked through earlier removals) or "@x,y", the edge through that point now.
static bool resolve_edge(const ori_pattern *p, const int *map, int n_orig, json_t *spec, int *edge, char *label,
                         size_t label_size, studio_response *out)
{
    if (json_is_string(spec)) {
        const char *t = json_string_value(spec);
        double x, y;
        char tail;
        if (t[0] != '@' || sscanf(t + 1, "%lf,%lf%c", &x, &y, &tail) != 2 || !isfinite(x) || !isfinite(y)) {
            studio_fail(out, 400, "edge: an index or \"@x,y\" (got %.40s)", t);
            return false;
        }
        int e = ori_pattern_find_edge_at(p, ori_v2_make(x, y));
        if (e == ORI_NULL_INDEX) {
            studio_fail(out, 400, "no edge passes through (%g, %g)", x, y);
            return false;
        }
        *edge = e;
        snprintf(label, label_size, "edge %d (%.40s)", e, t);
        return true;
    }
    if (!json_is_integer(spec)) {
        studio_fail(out, 400, "edge: an index or \"@x,y\"");
        return false;
    }
    json_int_t id = json_integer_value(spec);
    if (id < 0 || id >= n_orig) {
        studio_fail(out, 400, "edges_vertices %lld: no such edge (the pattern has %d edges)", (long long)id, n_orig);
        return false;
    }
    if (map[id] == ORI_NULL_INDEX) {
        studio_fail(out, 400, "edges_vertices %lld: the edge was removed by an earlier operation", (long long)id);
        return false;
    }
    *edge = map[id];
    if (*edge != id) snprintf(label, label_size, "edge %lld (now %d)", (long long)id, *edge);
    else snprintf(label, label_size, "edge %d", *edge);
    return true;
}

static void map_removal(int *map, int n, const ori_remove_result *r)
{
    for (int i = 0; i < n; ++i) map[i] = ori_remove_result_map_edge(r, map[i]);
}

// One operation on p; false after a 400. Appends a line to log.
static bool edit_one(ori_pattern *p, json_t *op, int index, int *map, int n_orig, json_t *log, studio_response *out)
{
    static const char *const keys[] = {"op", "edge", "to", "segment", NULL};
    if (!json_is_object(op)) {
        studio_fail(out, 400, "ops %d: must be an object {\"op\", \"edge\", ...}", index);
        return false;
    }
    if (!studio_check_keys(op, keys, out)) return false;
    const char *name = NULL;
    if (!studio_get_string(op, "op", true, &name, out)) return false;
    enum op_kind kind;
    if (strcmp(name, "assign") == 0) kind = OP_ASSIGN;
    else if (strcmp(name, "flip") == 0) kind = OP_FLIP;
    else if (strcmp(name, "remove") == 0) kind = OP_REMOVE;
    else if (strcmp(name, "move") == 0) kind = OP_MOVE;
    else {
        studio_fail(out, 400, "ops %d: op is assign, flip, remove or move", index);
        return false;
    }
    ori_assignment asg = ORI_ASSIGN_UNASSIGNED;
    double seg[4];
    if (kind == OP_ASSIGN) {
        const char *to = NULL;
        if (!studio_get_string(op, "to", true, &to, out)) return false;
        if (strlen(to) != 1 || !ori_assignment_from_char(to[0], &asg)) {
            studio_fail(out, 400, "ops %d: to must be \"M\", \"V\", \"F\" or \"U\"", index);
            return false;
        }
    }
    if (kind == OP_MOVE) {
        if (!studio_get_numbers(op, "segment", true, seg, 4, NULL, out)) return false;
        for (int i = 0; i < 4; ++i)
            if (!(fabs(seg[i]) <= ORI_COORD_MAX)) {
                studio_fail(out, 400, "ops %d: segment coordinates beyond %g", index, ORI_COORD_MAX);
                return false;
            }
    }
    json_t *spec = json_object_get(op, "edge");
    if (!spec) {
        studio_fail(out, 400, "ops %d: edge: missing", index);
        return false;
    }
    int e;
    char label[96];
    if (!resolve_edge(p, map, n_orig, spec, &e, label, sizeof label, out)) return false;
    ori_edge before = ori_pattern_edge(p, e);
    int faces[2];
    ori_pattern_edge_faces(p, e, faces);
    char f0[ORI_NAME_MAX + 16], f1[ORI_NAME_MAX + 16], fm[ORI_NAME_MAX + 16], line[320];
    cli_face_label(p, faces[0], f0, sizeof f0);
    cli_face_label(p, faces[1], f1, sizeof f1);
    ori_error err;
    ori_status st = ORI_OK;
    line[0] = '\0';
    switch (kind) {
    case OP_ASSIGN:
        st = ori_pattern_assign_crease(p, e, asg, &err);
        if (st == ORI_OK)
            snprintf(line, sizeof line, "%s: %c -> %c", label, ori_assignment_to_char(before.assignment),
                     ori_assignment_to_char(asg));
        break;
    case OP_FLIP:
        st = ori_pattern_flip_crease(p, e, &err);
        if (st == ORI_OK)
            snprintf(line, sizeof line, "%s: %c -> %c (flipped)", label, ori_assignment_to_char(before.assignment),
                     ori_assignment_to_char(ori_pattern_edge(p, e).assignment));
        break;
    case OP_REMOVE: {
        ori_remove_result r;
        st = ori_pattern_remove_crease(p, e, &r, &err);
        if (st != ORI_OK) break;
        map_removal(map, n_orig, &r);
        int kept = r.kept_face == ORI_NULL_INDEX ? ORI_NULL_INDEX
                                                 : r.kept_face - (r.removed_face != ORI_NULL_INDEX && r.removed_face < r.kept_face);
        int n = snprintf(line, sizeof line, "removed %s", label);
        if (r.removed_face != ORI_NULL_INDEX && n < (int)sizeof line)
            n += snprintf(line + n, sizeof line - (size_t)n, ": %s + %s -> %s%s", f0, f1, cli_face_label(p, kept, fm, sizeof fm),
                          r.name_restored ? " (name restored)" : "");
        if (r.removed_edge_count > 1 && n < (int)sizeof line)
            snprintf(line + n, sizeof line - (size_t)n, "; %d collinear edge pair(s) rejoined", r.removed_edge_count - 1);
        break;
    }
    case OP_MOVE: {
        ori_remove_result r;
        ori_apply_result a;
        st = ori_pattern_move_crease(p, e, ori_v2_make(seg[0], seg[1]), ori_v2_make(seg[2], seg[3]), &r, &a, &err);
        if (st != ORI_OK) break;
        map_removal(map, n_orig, &r);
        snprintf(line, sizeof line, "moved %s to (%g, %g)-(%g, %g): now edges %d to %d", label, seg[0], seg[1], seg[2],
                 seg[3], a.first_edge, ori_pattern_edge_count(p) - 1);
        break;
    }
    }
    if (st != ORI_OK) {
        char msg[512];
        ori_error_format(&err, msg, sizeof msg);
        studio_fail(out, studio_status_of(st), "ops %d (%s %s): %s", index, name, label, msg);
        return false;
    }
    studio_utf8_clean(line); // a truncated line may end inside a character
    json_array_append_new(log, json_string(line));
    return true;
}

void studio_api_edit(studio *s, const studio_request *req, studio_response *out)
{
    json_t *o = studio_body_object(req, out);
    if (!o) return;
    static const char *const keys[] = {"ops", NULL};
    json_t *ops = json_object_get(o, "ops");
    if (!studio_check_keys(o, keys, out)) {
        json_decref(o);
        return;
    }
    if (!json_is_array(ops) || json_array_size(ops) == 0 || json_array_size(ops) > 10000) {
        json_decref(o);
        studio_fail(out, 400, "ops: must be a non-empty array of operations");
        return;
    }
    pthread_mutex_lock(&s->lock);
    ori_pattern *p = ori_pattern_clone(s->model->pattern);
    int n_orig = ori_pattern_edge_count(p);
    int *map = malloc(sizeof(int) * (size_t)(n_orig + 1));
    for (int i = 0; i < n_orig; ++i) map[i] = i;
    json_t *log = json_array();
    bool ok = true;
    for (size_t k = 0; k < json_array_size(ops) && ok; ++k)
        ok = edit_one(p, json_array_get(ops, k), (int)k, map, n_orig, log, out);
    if (ok) {
        commit_edit(s, p);
        json_t *res = version_json(s);
        json_object_set_new(res, "log", log);
        studio_respond_json(out, 200, res);
    } else {
        ori_pattern_destroy(p);
        json_decref(log);
    }
    pthread_mutex_unlock(&s->lock);
    free(map);
    json_decref(o);
}

// --- export and save-back --------------------------------------------------------------------

static const studio_export_format formats[] = {
    {"fold", "FOLD", ".fold", "application/json", STUDIO_EXPORT_DOCUMENT, false, 0},
    {"svg", "SVG crease pattern", ".svg", "image/svg+xml", STUDIO_EXPORT_DOCUMENT, false, 0},
    {"cp", "ORIPA .cp", ".cp", "text/plain", STUDIO_EXPORT_DOCUMENT, false, 0},
    {"opx", "ORIPA .opx", ".opx", "application/xml", STUDIO_EXPORT_DOCUMENT, false, 0},
    // orikin render: a picture of a state
    {"png", "PNG picture", ".png", "image/png", STUDIO_EXPORT_PICTURE, false, ORI_IMAGE_PNG},
    {"svg-picture", "SVG picture", ".svg", "image/svg+xml", STUDIO_EXPORT_PICTURE, false, ORI_IMAGE_SVG},
    {"pdf", "PDF picture", ".pdf", "application/pdf", STUDIO_EXPORT_PICTURE, false, ORI_IMAGE_PDF},
    // orikin export: a mesh of a state, or (glTF) the whole motion
    {"obj", "OBJ mesh", ".obj", "model/obj", STUDIO_EXPORT_MESH, false, ORI_MESH_OBJ},
    {"stl", "STL mesh", ".stl", "model/stl", STUDIO_EXPORT_MESH, false, ORI_MESH_STL},
    {"ply", "PLY mesh", ".ply", "text/plain", STUDIO_EXPORT_MESH, false, ORI_MESH_PLY},
    {"gltf", "glTF mesh", ".gltf", "model/gltf+json", STUDIO_EXPORT_MESH, true, ORI_MESH_GLTF},
    {"glb", "GLB mesh", ".glb", "model/gltf-binary", STUDIO_EXPORT_MESH, true, ORI_MESH_GLB},
    // orikin animate: the whole motion as a GIF
    {"gif", "GIF animation", ".gif", "image/gif", STUDIO_EXPORT_ANIMATION, true, 0},
};

int studio_export_format_count(void) { return (int)(sizeof formats / sizeof formats[0]); }
const studio_export_format *studio_export_format_at(int i) { return &formats[i]; }

// The text of the document in a format (NULL with a 400 when it cannot be written).
static char *export_text(studio *s, const char *format, studio_response *out)
{
    const ori_pattern *p = s->model->pattern;
    if (strcmp(format, "fold") == 0) return ori_fold_to_string(s->doc);
    if (ori_pattern_is_folded_form(p) || ori_pattern_is_3d(p)) {
        studio_fail(out, 400, "%s export needs a flat crease pattern; frame 0 is a folded form", format);
        return NULL;
    }
    if (strcmp(format, "svg") == 0) return ori_svg_write(p, NULL);
    if (strcmp(format, "cp") == 0) return ori_cp_write(p);
    if (strcmp(format, "opx") == 0) return ori_opx_write(p);
    studio_fail(out, 400, "format: unknown");
    return NULL;
}

void studio_api_export(studio *s, const studio_request *req, studio_response *out)
{
    const char *format = studio_arg_get(req, "format");
    const studio_export_format *f = NULL;
    for (int i = 0; format && i < studio_export_format_count(); ++i)
        if (strcmp(formats[i].name, format) == 0) f = &formats[i];
    if (!f) {
        char list[200] = "";
        for (int i = 0; i < studio_export_format_count(); ++i) {
            strncat(list, i ? ", " : "", sizeof list - strlen(list) - 1);
            strncat(list, formats[i].name, sizeof list - strlen(list) - 1);
        }
        studio_fail(out, 400, "format: one of %s", list);
        return;
    }
    if (f->kind != STUDIO_EXPORT_DOCUMENT) {
        studio_export_render(s, req, f, out);
        return;
    }
    pthread_mutex_lock(&s->lock);
    char *text = export_text(s, f->name, out);
    char name[160];
    studio_download_name(s->file, f->extension, name, sizeof name);
    pthread_mutex_unlock(&s->lock);
    if (!text) return;
    studio_respond_text(out, 200, f->mime, text, strlen(text));
    copy_string(out->filename, sizeof out->filename, name);
    ori_buffer_free(text);
}

// 409 {"error", "conflict": true}: the file changed on disk since the studio read or wrote it;
// the page asks, then posts again with "overwrite": true.
static void save_conflict(studio_response *out, const char *path)
{
    char shown[STUDIO_PATH_MAX];
    copy_string(shown, sizeof shown, path);
    studio_utf8_clean(shown);
    char msg[STUDIO_PATH_MAX + 160];
    snprintf(msg, sizeof msg, "%s changed on disk since the studio read it: saving would overwrite that change", shown);
    studio_respond_json(out, 409, json_pack("{s:s,s:b}", "error", msg, "conflict", 1));
}

void studio_api_save(studio *s, const studio_request *req, studio_response *out)
{
    json_t *o = studio_body_object(req, out);
    if (!o) return;
    static const char *const keys[] = {"what", "overwrite", NULL};
    const char *what = "document";
    bool overwrite = false;
    if (!studio_check_keys(o, keys, out) || !studio_get_string(o, "what", false, &what, out) ||
        !studio_get_bool(o, "overwrite", &overwrite, out)) {
        json_decref(o);
        return;
    }
    bool doc = strcmp(what, "document") == 0, seq = strcmp(what, "sequence") == 0;
    if (!doc && !seq) {
        json_decref(o);
        studio_fail(out, 400, "what: \"document\" or \"sequence\"");
        return;
    }
    json_decref(o);
    pthread_mutex_lock(&s->lock);
    ori_error err;
    ori_status st = ORI_OK;
    char path[STUDIO_PATH_MAX];
    if (doc) {
        if (!s->from_command_line || !s->save_path[0]) {
            pthread_mutex_unlock(&s->lock);
            studio_fail(out, 409, "this document was not given on the command line: download it instead");
            return;
        }
        copy_string(path, sizeof path, s->save_path);
        if (!overwrite && studio_disk_changed(&s->doc_disk, path)) {
            pthread_mutex_unlock(&s->lock);
            save_conflict(out, path);
            return;
        }
        if (s->save_format == ORI_FORMAT_FOLD) st = ori_fold_save_file(s->doc, path, &err);
        else st = ori_export_file(s->model->pattern, s->save_format, NULL, path, &err);
    } else {
        if (!s->seq_path[0] || !s->seq || !s->from_command_line) {
            pthread_mutex_unlock(&s->lock);
            studio_fail(out, 409, "no sequence file was given on the command line, or no sequence has run: download it instead");
            return;
        }
        copy_string(path, sizeof path, s->seq_path);
        if (!overwrite && studio_disk_changed(&s->seq_disk, path)) {
            pthread_mutex_unlock(&s->lock);
            save_conflict(out, path);
            return;
        }
        char *text = ori_sequence_to_json(s->seq->sequence);
        json_t *j = json_loads(text, 0, NULL);
        ori_buffer_free(text);
        json_object_set_new(j, "pattern", json_string(s->seq_pattern_ref));
        char *pretty = json_dumps(j, JSON_INDENT(2) | JSON_REAL_PRECISION(17));
        json_decref(j);
        char *norm = ori_json_normalize(pretty, true, &err);
        free(pretty);
        if (norm) {
            size_t n = strlen(norm);
            char *withnl = malloc(n + 2);
            memcpy(withnl, norm, n);
            withnl[n] = '\n';
            st = ori_file_write_atomic(path, withnl, n + 1, &err);
            free(withnl);
            ori_buffer_free(norm);
        } else {
            st = ORI_ERR_INTERNAL;
        }
    }
    if (st == ORI_OK && doc) studio_mark_saved(s);
    else if (st == ORI_OK) studio_disk_remember(&s->seq_disk, path);
    pthread_mutex_unlock(&s->lock);
    if (st != ORI_OK) {
        studio_fail_error(out, 500, &err);
        return;
    }
    studio_utf8_clean(path);
    studio_respond_json(out, 200, json_pack("{s:s}", "saved", path));
}
