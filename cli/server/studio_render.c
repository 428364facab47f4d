// Pictures, meshes and animations of the studio's states (GET /api/export with a picture, mesh
// or animation format): the render module's writers on the state the request names, with the
// drawing options of `orikin render`, `orikin export` and `orikin animate`, so that the bytes
// equal what those commands write for the same state and options.
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "studio_internal.h"

// Most frames of one animation (as orikin animate).
#define MAX_ANIMATION_FRAMES 10000

static void *xcalloc(size_t n, size_t size) { return calloc(n ? n : 1, size); }

// --- arguments ------------------------------------------------------------------------------------

static bool flag_arg(const studio_request *req, const char *key, bool *out, bool *given, studio_response *res)
{
    const char *v = studio_arg_get(req, key);
    if (given) *given = v != NULL;
    if (!v) return true;
    if (strcmp(v, "1") == 0 || strcmp(v, "true") == 0) *out = true;
    else if (strcmp(v, "0") == 0 || strcmp(v, "false") == 0) *out = false;
    else {
        studio_fail(res, 400, "%s: 1 or 0", key);
        return false;
    }
    return true;
}

static bool number_arg(const studio_request *req, const char *key, double *out, bool *given, studio_response *res)
{
    const char *v = studio_arg_get(req, key);
    if (given) *given = v != NULL;
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

// "x,y,z".
static bool vector_arg(const studio_request *req, const char *key, ori_v3 *out, bool *given, studio_response *res)
{
    const char *v = studio_arg_get(req, key);
    *given = v != NULL;
    if (!v) return true;
    double x, y, z;
    char tail;
    if (sscanf(v, "%lf,%lf,%lf%c", &x, &y, &z, &tail) != 3 || !isfinite(x) || !isfinite(y) || !isfinite(z)) {
        studio_fail(res, 400, "%s: three numbers x,y,z", key);
        return false;
    }
    *out = ori_v3_make(x, y, z);
    return true;
}

static bool color_arg(const studio_request *req, const char *key, ori_rgb *out, bool *given, studio_response *res)
{
    const char *v = studio_arg_get(req, key);
    *given = v != NULL;
    if (v && !ori_rgb_parse(v, out)) {
        studio_fail(res, 400, "%s: a colour (#rrggbb, #rgb or a name such as orange)", key);
        return false;
    }
    return true;
}

// The drawing options of orikin render / animate, as query arguments.
typedef struct draw_args {
    bool has_view;
    ori_render_view view;
    bool only_3d;       // an option only the 3D view uses was given
    ori_camera_preset_kind preset;
    double yaw, pitch, roll; // degrees
    bool perspective, edges, grid, labels;
    bool has_eye;       // the page's view: eye direction and up vector (model coordinates)
    ori_v3 eye, up;
    int width, height;
    ori_rgb front, back;
} draw_args;

static bool parse_draw(const studio_request *req, draw_args *d, studio_response *out)
{
    memset(d, 0, sizeof *d);
    ori_render_def def = ori_default_render_def();
    d->preset = ORI_CAMERA_ISO;
    d->width = def.width;
    d->height = def.height;
    d->front = def.front;
    d->back = def.back;
    const char *v = studio_arg_get(req, "view");
    if (v) {
        d->has_view = true;
        if (strcmp(v, "cp") == 0) d->view = ORI_RENDER_CREASES;
        else if (strcmp(v, "3d") == 0) d->view = ORI_RENDER_3D;
        else {
            studio_fail(out, 400, "view: cp or 3d");
            return false;
        }
    }
    if ((v = studio_arg_get(req, "camera"))) {
        static const char *const names[] = {"iso", "top", "front", "side", "bottom"};
        static const ori_camera_preset_kind kinds[] = {ORI_CAMERA_ISO, ORI_CAMERA_TOP, ORI_CAMERA_FRONT, ORI_CAMERA_SIDE,
                                                       ORI_CAMERA_BOTTOM};
        int k = -1;
        for (int i = 0; i < 5; ++i)
            if (strcmp(v, names[i]) == 0) k = i;
        if (k < 0) {
            studio_fail(out, 400, "camera: iso, top, front, side or bottom");
            return false;
        }
        d->preset = kinds[k];
        d->only_3d = true;
    }
    bool g[12] = {false};
    bool has_up = false;
    if (!number_arg(req, "yaw", &d->yaw, &g[0], out) || !number_arg(req, "pitch", &d->pitch, &g[1], out) ||
        !number_arg(req, "roll", &d->roll, &g[2], out) || !flag_arg(req, "perspective", &d->perspective, &g[3], out) ||
        !flag_arg(req, "edges", &d->edges, &g[4], out) || !flag_arg(req, "grid", &d->grid, &g[5], out) ||
        !flag_arg(req, "labels", &d->labels, &g[6], out) || !color_arg(req, "front", &d->front, &g[7], out) ||
        !color_arg(req, "back", &d->back, &g[8], out) || !vector_arg(req, "eye", &d->eye, &d->has_eye, out) ||
        !vector_arg(req, "up", &d->up, &has_up, out))
        return false;
    for (int i = 0; i < 9; ++i)
        if (g[i] && i != 6) d->only_3d = true;
    if (d->has_eye != has_up) {
        studio_fail(out, 400, "eye and up: give both (the view direction and the image's up)");
        return false;
    }
    if (d->has_eye) {
        d->only_3d = true;
        ori_v3 back = ori_v3_normalize(d->eye), right = ori_v3_normalize(ori_v3_cross(d->up, back));
        if (ori_v3_norm(back) == 0.0 || ori_v3_norm(right) == 0.0) {
            studio_fail(out, 400, "eye and up: two independent directions");
            return false;
        }
    }
    if ((v = studio_arg_get(req, "size"))) {
        int w = 0, h = 0;
        char tail;
        if (sscanf(v, "%dx%d%c", &w, &h, &tail) != 2 || w < 1 || h < 1 || w > ORI_RENDER_MAX_SIZE || h > ORI_RENDER_MAX_SIZE) {
            studio_fail(out, 400, "size: WxH with W and H from 1 to %d", ORI_RENDER_MAX_SIZE);
            return false;
        }
        d->width = w;
        d->height = h;
    }
    return true;
}

// The render def orikin render builds from the same options (cli/render_args.c), with the
// page's camera when it gives one.
static ori_render_def draw_def(const draw_args *d)
{
    ori_render_def def = ori_default_render_def();
    def.width = d->width;
    def.height = d->height;
    def.camera = ori_camera_preset(d->preset, ori_deg_to_rad(d->yaw), ori_deg_to_rad(d->pitch), ori_deg_to_rad(d->roll));
    if (d->has_eye) {
        // rows: the image's right, up and towards-the-viewer axes in world coordinates
        ori_v3 back = ori_v3_normalize(d->eye), right = ori_v3_normalize(ori_v3_cross(d->up, back));
        ori_v3 up = ori_v3_cross(back, right);
        ori_v3 r[3] = {right, up, back};
        for (int i = 0; i < 3; ++i) {
            def.camera.rotation.m[i][0] = r[i].x;
            def.camera.rotation.m[i][1] = r[i].y;
            def.camera.rotation.m[i][2] = r[i].z;
        }
    }
    def.camera.perspective = d->perspective;
    def.fit_camera = true;
    def.front = d->front;
    def.back = d->back;
    def.all_edges = d->edges;
    def.grid = d->grid;
    def.labels = d->labels;
    return def;
}

// --- answers -------------------------------------------------------------------------------------

static void respond_file(studio *s, const studio_export_format *f, const char *suffix, void *data, size_t size,
                         studio_response *out)
{
    studio_respond_text(out, 200, f->mime, data, size);
    char file[STUDIO_PATH_MAX], ext[48];
    pthread_mutex_lock(&s->lock);
    snprintf(file, sizeof file, "%s", s->file);
    pthread_mutex_unlock(&s->lock);
    snprintf(ext, sizeof ext, "%s%s", suffix, f->extension);
    studio_download_name(file, ext, out->filename, sizeof out->filename);
}

static void fail_render(studio_response *out, ori_status st, const ori_error *err)
{
    studio_fail_error(out, st == ORI_ERR_INTERNAL || st == ORI_ERR_NOMEM ? 500 : 400, err);
}

// Strain colours (render / animate --color strain of --compliant): the faces' largest strain in
// the compliant model's recorded states sources[0 … n − 1], into values (n × face_count, malloc'd),
// and the bar's range over all of them.
static double *strain_values(const ori_compliant *c, const int *sources, int n, ori_value_map *map)
{
    int F = ori_compliant_face_count(c);
    double *v = xcalloc((size_t)n * (size_t)F, sizeof(double));
    map->min = INFINITY;
    map->max = -INFINITY;
    for (int i = 0; i < n; ++i) {
        memcpy(v + (size_t)i * F, ori_compliant_frame_face_strains(c, sources[i]), sizeof(double) * (size_t)F);
        for (int f = 0; f < F; ++f) {
            map->min = fmin(map->min, v[(size_t)i * F + f]);
            map->max = fmax(map->max, v[(size_t)i * F + f]);
        }
    }
    if (!(map->min <= map->max)) map->min = map->max = 0.0;
    map->face_values = v;
    map->edge_values = NULL;
    return v;
}

// color=strain: false after a 400 (another quantity, or a state that is not a compliant fold's).
static bool strain_asked(const studio_request *req, bool compliant, bool *asked, studio_response *out)
{
    const char *v = studio_arg_get(req, "color");
    *asked = v != NULL;
    if (v && strcmp(v, "strain") != 0) {
        studio_fail(out, 400, "color: strain (the faces of a compliant fold; fold-angle and target-error are the CLI's)");
        return false;
    }
    if (v && !compliant) {
        studio_fail(out, 400, "color=strain colours a compliant fold: compliant=1 or of=compliant");
        return false;
    }
    return true;
}

// The map of the compliant fold's last recorded state (its end), values malloc'd into *values.
static ori_value_map end_strains(const studio_cfold *cf, double **values)
{
    ori_value_map map;
    int last = ori_compliant_frame_count(cf->c) - 1;
    *values = strain_values(cf->c, &last, 1, &map);
    return map;
}

// A picture of a state (orikin render IN [state] -o OUT.png|.svg|.pdf).
static void export_picture(studio *s, const studio_request *req, const studio_export_format *f, studio_response *out)
{
    draw_args d;
    studio_state_ref ref;
    bool strain = false;
    if (!parse_draw(req, &d, out) || !studio_state_ref_args(req, &ref, out) ||
        !strain_asked(req, ref.kind == STUDIO_STATE_COMPLIANT, &strain, out))
        return;
    if ((double)d.width * d.height > s->def.render_pixels) {
        studio_fail(out, 400, "size: %dx%d is over the studio's %.0f pixels: use a smaller size", d.width, d.height,
                    s->def.render_pixels);
        return;
    }
    if (d.has_view && d.view == ORI_RENDER_CREASES && d.only_3d) {
        studio_fail(out, 400, "view=cp draws the crease pattern: the camera, colour, grid and edge options are for view=3d");
        return;
    }
    if (d.has_view && d.view == ORI_RENDER_3D && d.labels) {
        studio_fail(out, 400, "labels is for the crease view (view=cp)");
        return;
    }
    if (d.has_view && d.view == ORI_RENDER_CREASES && ref.kind != STUDIO_STATE_FRAME) {
        studio_fail(out, 400, "view=cp draws the crease pattern: name a frame, not t, k or contact");
        return;
    }
    // The view: as asked; else the crease pattern of a crease-pattern frame, 3D otherwise.
    bool decided = d.has_view || d.only_3d || d.labels || ref.kind != STUDIO_STATE_FRAME;
    ori_render_view view = d.has_view ? d.view : d.labels ? ORI_RENDER_CREASES : ORI_RENDER_3D;
    if (!studio_job_begin(s, "picture", out)) return;
    studio_state st;
    if (studio_state_load(s, &ref, decided && view == ORI_RENDER_3D, &st, out)) {
        if (!decided) view = st.cp_frame ? ORI_RENDER_CREASES : ORI_RENDER_3D;
        if (view == ORI_RENDER_CREASES && !st.has_flat) {
            studio_fail(out, 400, "frame %d is a folded form without a crease pattern: use view=3d", st.frame);
        } else {
            ori_render_def def = draw_def(&d);
            def.view = view;
            def.format = (ori_image_format)f->render_format;
            double *values = NULL;
            studio_cfold *cf = strain ? studio_cfold_get(s) : NULL;
            if (cf) def.values = end_strains(cf, &values);
            ori_state_view sv = {st.pattern, view == ORI_RENDER_CREASES ? NULL : st.positions, st.angles};
            void *data = NULL;
            size_t size = 0;
            ori_error err;
            ori_status rs = strain && !cf ? ORI_ERR_NOT_FOUND : ori_render_image(&sv, &def, &data, &size, &err);
            if (strain && !cf) studio_fail(out, 409, "the compliant fold was replaced: solve it again");
            else if (rs != ORI_OK) fail_render(out, rs, &err);
            else respond_file(s, f, "", data, size, out);
            ori_buffer_free(data);
            free(values);
            studio_cfold_unref(cf);
        }
        studio_state_free(&st);
    }
    studio_job_end(s);
}

// A mesh of a state (orikin export IN [state] -o OUT.obj|…).
static void export_mesh(studio *s, const studio_request *req, const studio_export_format *f, studio_response *out)
{
    studio_state_ref ref;
    ori_export_def def = ori_default_export_def();
    double thickness = 0.0;
    bool g;
    if (!studio_state_ref_args(req, &ref, out) || !number_arg(req, "thickness", &thickness, NULL, out) ||
        !color_arg(req, "front", &def.front, &g, out) || !color_arg(req, "back", &def.back, &g, out))
        return;
    if (!(thickness >= 0.0)) {
        studio_fail(out, 400, "thickness: a length >= 0 (pattern units)");
        return;
    }
    if (!studio_job_begin(s, "mesh", out)) return;
    studio_state st;
    if (studio_state_load(s, &ref, true, &st, out)) {
        ori_state_view sv = {st.pattern, st.positions, st.angles};
        ori_mesh *mesh = NULL;
        ori_error err;
        void *data = NULL;
        size_t size = 0;
        def.format = (ori_mesh_format)f->render_format;
        def.thickness = thickness;
        // a compliant fold's glTF carries its strain as vertex colours (as orikin export --compliant)
        double *values = NULL;
        studio_cfold *cf = ref.kind == STUDIO_STATE_COMPLIANT &&
                                   (def.format == ORI_MESH_GLTF || def.format == ORI_MESH_GLB)
                               ? studio_cfold_get(s)
                               : NULL;
        if (cf) def.values = end_strains(cf, &values);
        ori_status rs = ori_mesh_create(&sv, &mesh, &err);
        if (rs == ORI_OK) rs = ori_mesh_export(mesh, &def, &data, &size, &err);
        if (rs != ORI_OK) fail_render(out, rs, &err);
        else respond_file(s, f, "", data, size, out);
        ori_buffer_free(data);
        ori_mesh_destroy(mesh);
        free(values);
        studio_cfold_unref(cf);
        studio_state_free(&st);
    }
    studio_job_end(s);
}

// --- motions ---------------------------------------------------------------------------------------

// A motion as keyframes, as orikin export --animate and orikin animate take it (the shared
// cli_motion_of_* of report.h): the state drawn when it is one picture (the motion's end), and
// the keyframes.
typedef struct motion {
    studio_model *model;
    cli_motion k;
    ori_v3 *end_positions;
    double *end_angles;
    studio_cfold *compliant; // of=compliant: the fold (a reference), else NULL
} motion;

static void motion_free(motion *m)
{
    studio_model_unref(m->model);
    studio_cfold_unref(m->compliant);
    cli_motion_free(&m->k);
    free(m->end_positions);
    free(m->end_angles);
    memset(m, 0, sizeof *m);
}

static void set_sizes(motion *m, studio_model *model)
{
    m->model = studio_model_ref(model);
    m->end_positions = xcalloc((size_t)ori_mechanism_vertex_count(model->mech), sizeof(ori_v3));
    m->end_angles = xcalloc((size_t)ori_mechanism_edge_count(model->mech), sizeof(double));
}

// The studio's limit on the frames a motion export solves.
static bool within_work_limit(const studio_model *model, int samples, double work_limit, studio_response *out)
{
    const ori_mechanism *mech = model->mech;
    double elements =
        (double)(ori_mechanism_vertex_count(mech) + ori_mechanism_edge_count(mech) + ori_mechanism_face_count(mech));
    if (samples >= 2 && samples * elements > work_limit) {
        studio_fail(out, 400, "%d frames of %.0f elements are over the studio's limit of %.3g: fewer frames", samples,
                    elements, work_limit);
        return false;
    }
    return true;
}

// The sequence: its recorded states (samples = 0) or samples states evenly spaced in time, each
// restored exactly; one second per fold. The whole record, as orikin export / animate take it.
static bool sequence_motion(studio *s, int samples, double work_limit, motion *m, studio_response *out)
{
    pthread_mutex_lock(&s->lock);
    studio_seq *q = s->seq;
    if (q) atomic_fetch_add(&q->refs, 1);
    pthread_mutex_unlock(&s->lock);
    if (!q) {
        studio_fail(out, 409, "of=sequence: no sequence has run on this document");
        return false;
    }
    bool ok = ori_record_verdict(q->record) == ORI_MOTION_VALID && ori_record_frame_count(q->record) > 0;
    if (!ok) studio_fail(out, 409, "of=sequence: fold %d of the sequence is %s", ori_record_failed_fold(q->record) + 1,
                         ori_motion_verdict_name(ori_record_verdict(q->record)));
    ok = ok && within_work_limit(q->model, samples, work_limit, out);
    if (ok) {
        set_sizes(m, q->model);
        ori_error err;
        pthread_mutex_lock(&q->lock);
        ori_status rs = ori_record_at(q->record, ori_record_duration(q->record), m->end_angles, m->end_positions, NULL,
                                      NULL, NULL, &err);
        if (rs == ORI_OK)
            rs = cli_motion_of_record(q->model->mech, q->sequence, q->record, samples, studio_job_progress, s, &m->k, &err);
        pthread_mutex_unlock(&q->lock);
        if (rs != ORI_OK) {
            studio_fail_error(out, studio_status_of(rs), &err);
            ok = false;
        }
    }
    studio_seq_unref(q);
    return ok;
}

// The computed fold: its output steps (samples = 0), or solved again with samples steps evenly
// spaced in drive, times (drive − from) / (to − from); a fold mode's frames timed by their
// progress, or samples states at evenly spaced progress. Every step, as orikin export / animate
// take the fold.
static bool fold_motion(studio *s, int samples, double work_limit, motion *m, studio_response *out)
{
    pthread_mutex_lock(&s->lock);
    studio_fold *f = s->fold;
    if (f) atomic_fetch_add(&f->refs, 1);
    pthread_mutex_unlock(&s->lock);
    if (!f) {
        studio_fail(out, 409, "of=fold: no fold has been computed on this document");
        return false;
    }
    const ori_mechanism *mech = f->model->mech;
    bool ok;
    if (f->motion) {
        ok = ori_motion_verdict_of(f->motion) == ORI_MOTION_VALID && ori_motion_frame_count(f->motion) > 0;
        if (!ok) studio_fail(out, 409, "of=fold: the fold is %s", ori_motion_verdict_name(ori_motion_verdict_of(f->motion)));
    } else {
        ori_multifold_verdict v = ori_multifold_verdict_of(f->multi);
        ok = (v == ORI_MULTIFOLD_REACHED || ori_multifold_frame_count(f->multi) >= 2) && v != ORI_MULTIFOLD_INVALID_ASSIGNMENT;
        if (!ok) studio_fail(out, 409, "of=fold: the fold is %s: %s", ori_multifold_verdict_name(v), ori_multifold_reason(f->multi));
    }
    ok = ok && within_work_limit(f->model, samples, work_limit, out);
    if (ok) {
        set_sizes(m, f->model);
        ori_error err;
        ori_status rs;
        int E = ori_mechanism_edge_count(mech);
        if (f->motion) {
            int last = ori_motion_frame_count(f->motion) - 1;
            ori_motion_frame_vertices(f->motion, last, m->end_positions);
            memcpy(m->end_angles, ori_motion_frame_angles(f->motion, last), sizeof(double) * (size_t)E);
            rs = cli_motion_of_fold(mech, &f->def, f->motion, f->start_drive_rad, samples, &m->k, &err);
        } else {
            int last = ori_multifold_frame_count(f->multi) - 1;
            ori_multifold_frame_vertices(f->multi, last, m->end_positions);
            memcpy(m->end_angles, ori_multifold_frame_angles(f->multi, last), sizeof(double) * (size_t)E);
            rs = cli_motion_of_multifold(mech, f->multi, f->locks, f->def.locked_count, f->def.fixed_face, samples,
                                         studio_job_progress, s, &m->k, &err);
        }
        if (rs != ORI_OK) {
            studio_fail_error(out, rs == ORI_ERR_NOT_CONVERGED ? 400 : studio_status_of(rs), &err);
            ok = false;
        }
    }
    studio_fold_unref(f);
    return ok;
}

static bool load_motion(studio *s, bool of_sequence, int samples, motion *m, studio_response *out)
{
    memset(m, 0, sizeof *m);
    bool ok = of_sequence ? sequence_motion(s, samples, s->def.work_limit, m, out)
                          : fold_motion(s, samples, s->def.work_limit, m, out);
    if (!ok) motion_free(m);
    return ok;
}

// The compliant fold's load steps (of=compliant), as orikin animate --compliant takes them.
static bool compliant_motion(studio *s, int samples, motion *m, studio_response *out)
{
    memset(m, 0, sizeof *m);
    m->compliant = studio_cfold_get(s);
    if (!m->compliant) {
        studio_fail(out, 409, "of=compliant: no compliant fold has been solved on this document");
        return false;
    }
    m->model = studio_model_ref(m->compliant->model);
    ori_error err;
    if (cli_motion_of_compliant(m->compliant->c, samples, &m->k, &err) != ORI_OK) {
        studio_fail_error(out, 409, &err);
        motion_free(m);
        return false;
    }
    return true;
}

// The whole motion as a glTF animation (orikin export IN --animate -o OUT.gltf|.glb).
static bool compliant_motion(studio *s, int samples, motion *m, studio_response *out);

static void export_mesh_motion(studio *s, const studio_request *req, const studio_export_format *f, bool of_sequence,
                               bool of_compliant, studio_response *out)
{
    ori_export_def def = ori_default_export_def();
    bool g;
    if (!color_arg(req, "front", &def.front, &g, out) || !color_arg(req, "back", &def.back, &g, out)) return;
    if (studio_arg_get(req, "thickness")) {
        studio_fail(out, 400, "thickness: an animation moves each face as a rigid node: it takes no thickness");
        return;
    }
    if (!studio_job_begin(s, "animated mesh", out)) return;
    motion m;
    if (of_compliant ? compliant_motion(s, 0, &m, out) : load_motion(s, of_sequence, 0, &m, out)) {
        // a compliant fold's faces bend: one mesh posed as its first state, morphing through the
        // others (as orikin export --compliant --animate)
        ori_state_view sv = of_compliant ? (ori_state_view){m.model->pattern, m.k.positions, m.k.angles}
                                         : (ori_state_view){m.model->pattern, m.end_positions, m.end_angles};
        ori_mesh *mesh = NULL;
        ori_error err;
        void *data = NULL;
        size_t size = 0;
        def.format = (ori_mesh_format)f->render_format;
        def.keyframe_count = m.k.count;
        def.keyframe_times_s = m.k.times;
        if (of_compliant) def.keyframe_positions = m.k.positions;
        else def.keyframe_poses = m.k.poses;
        ori_status rs = ori_mesh_create(&sv, &mesh, &err);
        if (rs == ORI_OK) rs = ori_mesh_export(mesh, &def, &data, &size, &err);
        if (rs != ORI_OK) fail_render(out, rs, &err);
        else respond_file(s, f, of_compliant ? "-compliant" : of_sequence ? "-sequence" : "-fold", data, size, out);
        ori_buffer_free(data);
        ori_mesh_destroy(mesh);
        motion_free(&m);
    }
    studio_job_end(s);
}

typedef struct gif_frames {
    const motion *m;
    double *values;  // color=strain: frame_count × face_count, else NULL
    int face_count;
} gif_frames;

static ori_status gif_values(int index, const double **face_values, const double **edge_values, void *user,
                             ori_error *error)
{
    (void)error;
    const gif_frames *g = user;
    *face_values = g->values + (size_t)index * (size_t)g->face_count;
    *edge_values = NULL;
    return ORI_OK;
}

static ori_status gif_frame(int index, ori_state_view *view, void *user, ori_error *error)
{
    (void)error;
    const motion *m = ((const gif_frames *)user)->m;
    view->pattern = m->model->pattern;
    view->positions = m->k.positions + (size_t)index * (size_t)m->k.vertex_count;
    view->fold_angles_rad = m->k.angles + (size_t)index * (size_t)m->k.edge_count;
    return ORI_OK;
}

// The whole motion as an animated GIF (orikin animate IN -o OUT.gif).
static void export_gif(studio *s, const studio_request *req, const studio_export_format *f, bool of_sequence,
                       bool of_compliant, studio_response *out)
{
    draw_args d;
    double fps = 15.0, duration = 3.0;
    bool has_fps = false, has_duration = false;
    if (studio_arg_get(req, "view") || studio_arg_get(req, "labels")) {
        studio_fail(out, 400, "an animation shows the 3D view (no view or labels)");
        return;
    }
    if (!parse_draw(req, &d, out) || !number_arg(req, "fps", &fps, &has_fps, out) ||
        !number_arg(req, "duration", &duration, &has_duration, out))
        return;
    if (!(fps >= 1.0 && fps <= 50.0)) {
        studio_fail(out, 400, "fps: a frame rate from 1 to 50 per second");
        return;
    }
    if (!(duration > 0.0 && duration <= 3600.0)) {
        studio_fail(out, 400, "duration: a time in seconds, above 0 and at most 3600");
        return;
    }
    int frames = (int)lround(fps * duration) + 1;
    if (frames > MAX_ANIMATION_FRAMES) {
        studio_fail(out, 400, "fps %g over duration %g gives %d frames, more than %d", fps, duration, frames,
                    MAX_ANIMATION_FRAMES);
        return;
    }
    if ((double)d.width * d.height * frames > s->def.animation_pixels) {
        studio_fail(out, 400, "%d frames of %dx%d are over the studio's %.3g pixels: a smaller size or fewer frames", frames,
                    d.width, d.height, s->def.animation_pixels);
        return;
    }
    bool strain = false;
    if (!strain_asked(req, of_compliant, &strain, out)) return;
    if (!studio_job_begin(s, "animation: solving frames", out)) return;
    motion m;
    if (of_compliant ? compliant_motion(s, frames, &m, out) : load_motion(s, of_sequence, frames, &m, out)) {
        ori_gif_def def = ori_default_gif_def();
        def.render = draw_def(&d);
        def.render.view = ORI_RENDER_3D;
        gif_frames gf = {&m, NULL, 0};
        def.frame_count = m.k.count;
        def.frame = gif_frame;
        def.user = &gf;
        ori_value_map map = {NULL, NULL, 0.0, 0.0};
        if (strain) { // one bar over every frame's strains (as orikin animate --compliant --color strain)
            gf.values = strain_values(m.compliant->c, m.k.sources, m.k.count, &map);
            gf.face_count = ori_compliant_face_count(m.compliant->c);
            def.frame_values = gif_values;
            def.render.values.min = map.min;
            def.render.values.max = map.max;
        }
        // the frames span the motion evenly over the duration
        def.fps = (m.k.count - 1) / duration;
        if (def.fps < 1.0) def.fps = 1.0;
        if (def.fps > 100.0) def.fps = 100.0;
        studio_job_phase(s, "animation: drawing frames");
        def.progress = studio_job_progress;
        def.progress_user = s;
        void *data = NULL;
        size_t size = 0;
        ori_error err;
        ori_status rs = ori_gif_write(&def, &data, &size, &err);
        if (rs != ORI_OK) fail_render(out, rs, &err);
        else respond_file(s, f, of_compliant ? "-compliant" : of_sequence ? "-sequence" : "-fold", data, size, out);
        ori_buffer_free(data);
        free(gf.values);
        motion_free(&m);
    }
    studio_job_end(s);
}

void studio_export_render(studio *s, const studio_request *req, const studio_export_format *f, studio_response *out)
{
    const char *of = studio_arg_get(req, "of");
    bool motion_asked = of && strcmp(of, "state") != 0;
    if (of && strcmp(of, "state") != 0 && strcmp(of, "sequence") != 0 && strcmp(of, "fold") != 0 &&
        strcmp(of, "compliant") != 0) {
        studio_fail(out, 400, "of: state, sequence, fold or compliant");
        return;
    }
    bool of_sequence = motion_asked && strcmp(of, "sequence") == 0;
    bool of_compliant = motion_asked && strcmp(of, "compliant") == 0;

    if (motion_asked && !f->motion) {
        studio_fail(out, 400, "%s holds one state: of=sequence and of=fold are for gltf, glb and gif", f->name);
        return;
    }
    if (f->kind == STUDIO_EXPORT_ANIMATION && !motion_asked) {
        studio_fail(out, 400, "%s is an animation: of=sequence or of=fold", f->name);
        return;
    }
    if (motion_asked) {
        const char *keys[] = {"frame", "t", "k", "contact", "compliant"};
        for (int i = 0; i < 5; ++i)
            if (studio_arg_get(req, keys[i])) {
                studio_fail(out, 400, "%s names one state: the motion of=%s has them all", keys[i], of);
                return;
            }
    }
    if (f->kind == STUDIO_EXPORT_PICTURE) export_picture(s, req, f, out);
    else if (f->kind == STUDIO_EXPORT_ANIMATION) export_gif(s, req, f, of_sequence, of_compliant, out);
    else if (motion_asked) export_mesh_motion(s, req, f, of_sequence, of_compliant, out);
    else export_mesh(s, req, f, out);
}
