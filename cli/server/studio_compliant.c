// POST /api/compliant: the compliant fold of the document's pattern (the bar-and-hinge model),
// as `orikin fold FILE --compliant --json` with the same request, solve and JSON (cli/report),
// plus the vertex positions the studio draws and the faces' strain colours. Body: {percent, dynamic, preset, axial, facet,
// crease, damping, gravity, steps, threads, fix (a face index or name)}, each optional.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "studio_internal.h"

static bool parse_request(json_t *o, const ori_pattern *p, cli_compliant_request *r, studio_response *out)
{
    static const char *const keys[] = {"percent", "dynamic", "preset", "axial", "facet", "crease", "damping",
                                       "gravity", "steps", "threads", "fix", NULL};
    if (!studio_check_keys(o, keys, out)) return false;
    const char *preset = NULL;
    bool ok = studio_get_number(o, "percent", false, &r->percent, NULL, out) &&
              studio_get_bool(o, "dynamic", &r->dynamic, out) && studio_get_string(o, "preset", false, &preset, out) &&
              studio_get_number(o, "axial", false, &r->axial, &r->has_axial, out) &&
              studio_get_number(o, "facet", false, &r->facet, &r->has_facet, out) &&
              studio_get_number(o, "crease", false, &r->crease, &r->has_crease, out) &&
              studio_get_number(o, "damping", false, &r->damping, &r->has_damping, out) &&
              studio_get_number(o, "gravity", false, &r->gravity, NULL, out) &&
              studio_get_int(o, "steps", false, &r->steps, NULL, out) && studio_get_int(o, "threads", false, &r->threads, NULL, out);
    if (!ok) return false;
    if (preset) {
        if (strcmp(preset, "physical") == 0) r->physical = true;
        else if (strcmp(preset, "origami-simulator") != 0) {
            studio_fail(out, 400, "preset: origami-simulator or physical, got '%.64s'", preset);
            return false;
        }
    }
    json_t *fix = json_object_get(o, "fix");
    if (fix && json_is_string(fix)) {
        r->fix = ori_pattern_find_face_by_name(p, json_string_value(fix));
        if (r->fix == ORI_NULL_INDEX) {
            studio_fail(out, 400, "fix: no face named %.64s", json_string_value(fix));
            return false;
        }
    } else if (fix && json_is_integer(fix) && json_integer_value(fix) >= 0 &&
               json_integer_value(fix) < ori_pattern_face_count(p)) {
        r->fix = (int)json_integer_value(fix);
    } else if (fix) {
        studio_fail(out, 400, "fix: a face index (0 to %d) or name", ori_pattern_face_count(p) - 1);
        return false;
    }
    char mistake[200];
    if (cli_compliant_request_error(r, mistake, sizeof mistake)) {
        studio_fail(out, 400, "%s", mistake);
        return false;
    }
    return true;
}

// The faces coloured by their largest strain as `orikin render --color strain` paints them: the
// render module's colour map over [smallest, largest] (sRGB), and the bar's ticks.
static json_t *strain_colors(const ori_compliant *c)
{
    int F = ori_compliant_face_count(c);
    ori_value_map map = {NULL, NULL, INFINITY, -INFINITY};
    for (int f = 0; f < F; ++f) {
        map.min = fmin(map.min, ori_compliant_face_strain(c, f));
        map.max = fmax(map.max, ori_compliant_face_strain(c, f));
    }
    if (F == 0) map.min = map.max = 0.0;
    json_t *faces = json_array();
    for (int f = 0; f < F; ++f) {
        ori_rgb k = ori_colormap(ori_value_map_position(&map, ori_compliant_face_strain(c, f)));
        json_array_append_new(faces, json_pack("[fff]", k.r, k.g, k.b));
    }
    double ticks[ORI_RENDER_BAR_TICKS];
    char labels[ORI_RENDER_BAR_TICKS][ORI_RENDER_BAR_LABEL_MAX];
    int n = ori_value_map_ticks(&map, ticks, labels);
    json_t *lab = json_array();
    for (int k = 0; k < n; ++k) json_array_append_new(lab, json_string(labels[k]));
    return json_pack("{s:o,s:f,s:f,s:o}", "faces", faces, "min", map.min, "max", map.max, "ticks", lab);
}

void studio_cfold_unref(studio_cfold *f)
{
    if (!f || atomic_fetch_sub(&f->refs, 1) != 1) return;
    ori_compliant_destroy(f->c);
    studio_model_unref(f->model);
    free(f);
}

studio_cfold *studio_cfold_get(studio *s)
{
    pthread_mutex_lock(&s->lock);
    studio_cfold *f = s->compliant;
    if (f) atomic_fetch_add(&f->refs, 1);
    pthread_mutex_unlock(&s->lock);
    return f;
}

void studio_api_compliant(studio *s, const studio_request *req, studio_response *out)
{
    json_t *o = studio_body_object(req, out);
    if (!o) return;
    char file[STUDIO_PATH_MAX];
    pthread_mutex_lock(&s->lock);
    studio_model *model = studio_model_ref(s->model);
    long version = s->version;
    snprintf(file, sizeof file, "%s", s->file);
    pthread_mutex_unlock(&s->lock);
    cli_compliant_request r;
    cli_compliant_request_init(&r);
    bool ok = parse_request(o, model->pattern, &r, out);
    json_decref(o);
    if (!ok || !studio_job_begin(s, "compliant", out)) {
        studio_model_unref(model);
        return;
    }
    ori_compliant *c = NULL;
    ori_error err, why;
    bool reached = false;
    int steps = 0;
    r.all_frames = true; // its load steps: the motion of=compliant exports (as render / animate --compliant)
    ori_status st = cli_compliant_solve(model->pattern, &r, &c, &reached, &steps, &why, &err);
    if (st != ORI_OK) {
        studio_fail_error(out, studio_status_of(st), &err);
    } else {
        json_t *j = cli_compliant_json(file, &r, c, reached, steps, why.message, true);
        json_object_set_new(j, "version", json_integer(version));
        json_object_set_new(j, "strain_colors", strain_colors(c));
        studio_respond_json(out, 200, j);
        studio_cfold *f = calloc(1, sizeof *f);
        atomic_init(&f->refs, 1);
        f->model = studio_model_ref(model);
        f->c = c;
        c = NULL;
        pthread_mutex_lock(&s->lock);
        if (s->version == version) { // (unless the document changed meanwhile)
            studio_cfold_unref(s->compliant);
            s->compliant = f;
            f = NULL;
        }
        pthread_mutex_unlock(&s->lock);
        studio_cfold_unref(f);
    }
    ori_compliant_destroy(c);
    studio_model_unref(model);
    studio_job_end(s);
}
