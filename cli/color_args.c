// Colour by value: --color and the values of a state (color_args.h).
#include "color_args.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const names[] = {"none", "strain", "fold-angle", "target-error"};

const char *cli_color_name(cli_color_kind kind) { return names[kind]; }

int cli_color_option(const char *cmd, int argc, char **argv, int *i, cli_color_kind *kind, int *rc)
{
    *rc = CLI_EXIT_OK;
    if (strcmp(argv[*i], "--color") != 0) return 0;
    if (*kind != CLI_COLOR_NONE) {
        *rc = cli_usage(cmd, "--color given twice");
        return -1;
    }
    const char *v = cli_option_value(cmd, argc, argv, i);
    if (!v) {
        *rc = CLI_EXIT_USAGE;
        return -1;
    }
    for (int k = CLI_COLOR_STRAIN; k <= CLI_COLOR_TARGET_ERROR; ++k)
        if (strcmp(v, names[k]) == 0) {
            *kind = (cli_color_kind)k;
            return 1;
        }
    *rc = cli_usage(cmd, "--color is strain, fold-angle or target-error, got '%s'", v);
    return -1;
}

// A frame's field as numbers: NULL when absent; *bad set when present but not n numbers.
static double *read_numbers(const ori_fold *doc, int frame, const char *key, int n, bool *bad)
{
    *bad = false;
    char *text = ori_fold_get_custom(doc, frame, key);
    if (!text) return NULL;
    json_t *arr = json_loads(text, JSON_DECODE_ANY, NULL);
    ori_buffer_free(text);
    if (!json_is_array(arr) || (int)json_array_size(arr) != n) {
        json_decref(arr);
        *bad = true;
        return NULL;
    }
    double *v = malloc(sizeof(double) * (size_t)(n + 1));
    for (int k = 0; k < n; ++k) {
        json_t *x = json_array_get(arr, (size_t)k);
        if (!json_is_number(x) || !isfinite(json_number_value(x))) {
            free(v);
            json_decref(arr);
            *bad = true;
            return NULL;
        }
        v[k] = json_number_value(x);
    }
    json_decref(arr);
    return v;
}

static bool is_crease(const ori_pattern *p, int e)
{
    int f[2];
    ori_pattern_edge_faces(p, e, f);
    return f[0] >= 0 && f[1] >= 0;
}

// The strain of every face of FOLD frame `frame` (faces_orikin:strain, else the largest |strain|
// of its edges' edges_orikin:strain) into *out (malloc'd, face_count).
static int strain_of(const char *cmd, const char *path, const ori_pattern *p, const ori_fold *doc, int frame, double **out)
{
    int F = ori_pattern_face_count(p), E = ori_pattern_edge_count(p);
    bool bad;
    double *fs = read_numbers(doc, frame, "faces_orikin:strain", F, &bad);
    if (bad) return cli_input_fail(cmd, path, "frame %d: faces_orikin:strain is not %d finite numbers (one per face)", frame, F);
    if (fs) {
        for (int f = 0; f < F; ++f) fs[f] = fabs(fs[f]);
        *out = fs;
        return CLI_EXIT_OK;
    }
    double *es = read_numbers(doc, frame, "edges_orikin:strain", E, &bad);
    if (bad) return cli_input_fail(cmd, path, "frame %d: edges_orikin:strain is not %d finite numbers (one per edge)", frame, E);
    if (!es)
        return cli_input_fail(cmd, path,
                              "frame %d has no faces_orikin:strain or edges_orikin:strain (a compliant fold writes them: "
                              "orikin fold FILE --compliant -o OUT.fold)",
                              frame);
    double *v = malloc(sizeof(double) * (size_t)(F + 1));
    int *fe = NULL, cap = 0;
    for (int f = 0; f < F; ++f) {
        int n = ori_pattern_face_size(p, f);
        if (n > cap) fe = realloc(fe, sizeof(int) * (size_t)(cap = n));
        ori_pattern_face_edges(p, f, fe, n);
        double m = 0.0;
        for (int k = 0; k < n; ++k)
            if (fe[k] >= 0) m = fmax(m, fabs(es[fe[k]]));
        v[f] = m;
    }
    free(fe);
    free(es);
    *out = v;
    return CLI_EXIT_OK;
}

// The model's face strains of its recorded state k (malloc'd, face_count).
static double *model_strains(const cli_state *st, int k)
{
    int F = ori_pattern_face_count(st->pattern);
    double *v = malloc(sizeof(double) * (size_t)(F + 1));
    memcpy(v, ori_compliant_frame_face_strains(st->compliant, k), sizeof(double) * (size_t)F);
    return v;
}

static int strain_values(const char *cmd, const cli_state_args *a, const cli_state *st, cli_colors *out)
{
    if (st->compliant) {
        out->face_values = model_strains(st, ori_compliant_frame_count(st->compliant) - 1);
        return CLI_EXIT_OK;
    }
    if (st->source != CLI_STATE_FRAME || !st->doc)
        return cli_input_fail(cmd, a->path, "--color strain needs a FOLD frame with strains (orikin fold FILE --compliant -o OUT.fold)");
    return strain_of(cmd, a->path, st->pattern, st->doc, a->frame, &out->face_values);
}

// A FOLD frame's orikin:fraction (1 without one, or without a document).
static int fraction_of(const char *cmd, const char *path, const ori_fold *doc, int frame, double *fraction)
{
    *fraction = 1.0;
    if (!doc) return CLI_EXIT_OK;
    char *t = ori_fold_get_custom(doc, frame, "orikin:fraction");
    json_t *j = t ? json_loads(t, JSON_DECODE_ANY, NULL) : NULL;
    ori_buffer_free(t);
    if (t && (!json_is_number(j) || !(json_number_value(j) >= 0.0 && json_number_value(j) <= 1.0))) {
        json_decref(j);
        return cli_input_fail(cmd, path, "frame %d: orikin:fraction is not a number from 0 to 1", frame);
    }
    if (j) *fraction = json_number_value(j);
    json_decref(j);
    return CLI_EXIT_OK;
}

// Per crease (NaN elsewhere), degrees: the fold angle, or with target its distance from
// fraction × target.
static void angle_of(const ori_pattern *p, const double *angles, const double *target, double fraction, double *out)
{
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        double v = NAN;
        if (is_crease(p, e)) {
            v = angles[e];
            if (target) v = fabs(v - fraction * target[e]);
            v = v * 180.0 / ORI_PI;
        }
        out[e] = v;
    }
}

static int angle_values(const char *cmd, const cli_state_args *a, const cli_state *st, bool error, cli_colors *out)
{
    const ori_pattern *p = st->pattern;
    int E = ori_pattern_edge_count(p);
    if (!st->angles)
        return cli_input_fail(cmd, a->path, "--color %s: the state has no fold angles (a folded form without edges_foldAngle)",
                              error ? "target-error" : "fold-angle");
    double *target = NULL, fraction = 1.0;
    if (error) {
        if (!st->has_flat) return cli_input_fail(cmd, a->path, "--color target-error needs the crease pattern's targets (frame 0)");
        int rc = fraction_of(cmd, a->path, st->source == CLI_STATE_FRAME ? st->doc : NULL, a->frame, &fraction);
        if (rc != CLI_EXIT_OK) return rc;
        if (st->compliant) fraction = ori_compliant_fraction(st->compliant);
        target = malloc(sizeof(double) * (size_t)(E + 1));
        ori_target_angles_default(p, target);
    }
    out->edge_values = malloc(sizeof(double) * (size_t)(E + 1));
    angle_of(p, st->angles, target, fraction, out->edge_values);
    free(target);
    return CLI_EXIT_OK;
}

// The range and count of the values shown (NaN: not shown).
static void value_range(const double *v, size_t n, double *min, double *max, int *shown)
{
    *min = INFINITY;
    *max = -INFINITY;
    *shown = 0;
    for (size_t k = 0; k < n; ++k) {
        if (isnan(v[k])) continue;
        *min = fmin(*min, v[k]);
        *max = fmax(*max, v[k]);
        (*shown)++;
    }
    if (*shown == 0) *min = *max = 0.0;
}

int cli_colors_load(const char *cmd, const cli_state_args *a, const cli_state *st, cli_color_kind kind, cli_colors *out)
{
    memset(out, 0, sizeof *out);
    out->kind = kind;
    int rc = kind == CLI_COLOR_STRAIN ? strain_values(cmd, a, st, out)
                                      : angle_values(cmd, a, st, kind == CLI_COLOR_TARGET_ERROR, out);
    if (rc != CLI_EXIT_OK) {
        cli_colors_free(out);
        return rc;
    }
    const double *v = out->face_values ? out->face_values : out->edge_values;
    int n = out->face_values ? ori_pattern_face_count(st->pattern) : ori_pattern_edge_count(st->pattern);
    value_range(v, (size_t)n, &out->min, &out->max, &out->shown);
    return CLI_EXIT_OK;
}

int cli_colors_motion(const char *cmd, const cli_state_args *a, const cli_state *st, const cli_motion *m,
                      cli_color_kind kind, cli_colors *out)
{
    memset(out, 0, sizeof *out);
    out->kind = kind;
    const ori_pattern *p = st->pattern;
    int F = ori_pattern_face_count(p), E = ori_pattern_edge_count(p), rc = CLI_EXIT_OK;
    bool from_frames = st->source == CLI_STATE_FRAME && st->doc && m->sources;
    size_t per = kind == CLI_COLOR_STRAIN ? (size_t)F : (size_t)E;
    double *all = malloc(sizeof(double) * (per * (size_t)m->count + 1));
    if (kind == CLI_COLOR_STRAIN && st->compliant) {
        for (int i = 0; i < m->count; ++i) {
            double *v = model_strains(st, m->sources[i]);
            memcpy(all + per * (size_t)i, v, sizeof(double) * per);
            free(v);
        }
        out->face_values = all;
    } else if (kind == CLI_COLOR_STRAIN) {
        if (!from_frames) {
            free(all);
            return cli_input_fail(cmd, a->path,
                                  "--color strain needs FOLD frames with strains (orikin fold FILE --compliant --all-frames -o OUT.fold)");
        }
        // Each stored frame is read once, however many animation frames show it.
        for (int i = 0; i < m->count && rc == CLI_EXIT_OK; ++i) {
            if (i > 0 && m->sources[i] == m->sources[i - 1]) {
                memcpy(all + per * (size_t)i, all + per * (size_t)(i - 1), sizeof(double) * per);
                continue;
            }
            double *v = NULL;
            rc = strain_of(cmd, a->path, p, st->doc, m->sources[i], &v);
            if (v) memcpy(all + per * (size_t)i, v, sizeof(double) * per);
            free(v);
        }
        if (rc == CLI_EXIT_OK) out->face_values = all;
    } else {
        bool error = kind == CLI_COLOR_TARGET_ERROR;
        double *target = NULL;
        if (!m->angles)
            rc = cli_input_fail(cmd, a->path, "--color %s: the motion has no fold angles (folded forms without edges_foldAngle)",
                                cli_color_name(kind));
        else if (error && !st->has_flat)
            rc = cli_input_fail(cmd, a->path, "--color target-error needs the crease pattern's targets (frame 0)");
        if (rc == CLI_EXIT_OK && error) {
            target = malloc(sizeof(double) * (size_t)(E + 1));
            ori_target_angles_default(p, target);
        }
        for (int i = 0; i < m->count && rc == CLI_EXIT_OK; ++i) {
            double fraction = 1.0;
            if (error && from_frames) rc = fraction_of(cmd, a->path, st->doc, m->sources[i], &fraction);
            if (error && st->compliant) fraction = ori_compliant_frame_fraction(st->compliant, m->sources[i]);
            if (rc == CLI_EXIT_OK) angle_of(p, m->angles + (size_t)i * (size_t)E, target, fraction, all + per * (size_t)i);
        }
        free(target);
        if (rc == CLI_EXIT_OK) out->edge_values = all;
    }
    if (rc != CLI_EXIT_OK) {
        free(all);
        memset(out, 0, sizeof *out);
        return rc;
    }
    value_range(all, per * (size_t)m->count, &out->min, &out->max, &out->shown);
    out->shown = m->count > 0 ? out->shown / m->count : 0; // per frame (the same faces or creases in every frame)
    out->frames = m->count;
    return CLI_EXIT_OK;
}

ori_value_map cli_colors_map(const cli_colors *c)
{
    ori_value_map m = {c->face_values, c->edge_values, c->min, c->max};
    return m;
}

json_t *cli_colors_json(const cli_colors *c)
{
    json_t *o = json_object();
    json_object_set_new(o, "quantity", json_string(cli_color_name(c->kind)));
    json_object_set_new(o, "per", json_string(c->face_values ? "face" : "crease"));
    json_object_set_new(o, "shown", json_integer(c->shown));
    json_object_set_new(o, "min", json_real(c->min));
    json_object_set_new(o, "max", json_real(c->max));
    ori_value_map m = cli_colors_map(c);
    char labels[ORI_RENDER_BAR_TICKS][ORI_RENDER_BAR_LABEL_MAX];
    int n = ori_value_map_ticks(&m, NULL, labels);
    json_t *l = json_array();
    for (int k = 0; k < n; ++k) json_array_append_new(l, json_string(labels[k]));
    json_object_set_new(o, "labels", l);
    return o;
}

void cli_colors_free(cli_colors *c)
{
    free(c->face_values);
    free(c->edge_values);
    c->face_values = c->edge_values = NULL;
}
