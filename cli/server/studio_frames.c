// GET /api/frames: a multi-frame FOLD document's states as a motion the folding manager replays
// (the output of orikin simulate -o, whose frames carry frame_time in seconds; orikin sequence's
// with orikin:time; any other with one unit per frame), chosen and timed as render, animate and
// export take them (cli/state_args.c): after a flat crease-pattern frame 0 its other frames,
// otherwise every frame.
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "studio_internal.h"

// How the replayed frames are timed (the JSON "unit" and the binary header's third number).
typedef enum frames_unit {
    FRAMES_UNIT_FRAME = 0, // no usable times: frame i at time i
    FRAMES_UNIT_SECONDS,   // frame_time (orikin simulate), seconds
    FRAMES_UNIT_FOLD,      // orikin:time (orikin sequence), sequence time in folds
} frames_unit;

static const char *const unit_names[] = {"frame", "s", "fold"};

// A number written as a FOLD custom field's JSON text, or false.
static bool parse_time(const char *text, double *out)
{
    if (!text) return false;
    char *end;
    double x = strtod(text, &end);
    if (end == text || !isfinite(x)) return false;
    while (*end == ' ' || *end == '\n' || *end == '\t' || *end == '\r') end++;
    if (*end) return false;
    *out = x;
    return true;
}

// Times of frames first .. first+n-1 from key, strictly increasing; false when any is missing.
static bool frame_times(const ori_fold *doc, int first, int n, const char *key, double *times)
{
    for (int i = 0; i < n; ++i) {
        char *t = ori_fold_get_custom(doc, first + i, key);
        bool ok = parse_time(t, &times[i]);
        ori_buffer_free(t);
        if (!ok || (i > 0 && !(times[i] > times[i - 1]))) return false;
    }
    return true;
}

static void put_f64(unsigned char *p, double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    for (int i = 0; i < 8; ++i) p[i] = (unsigned char)(u >> (8 * i));
}

void studio_api_frames(studio *s, const studio_request *req, studio_response *out)
{
    const char *b = studio_arg_get(req, "binary");
    bool binary = b && strcmp(b, "1") == 0;
    pthread_mutex_lock(&s->lock);
    const ori_pattern *flat = s->model->pattern;
    int V = ori_pattern_vertex_count(flat), E = ori_pattern_edge_count(flat);
    int frames = ori_fold_frame_count(s->doc);
    ori_pattern *p0 = NULL;
    ori_error err;
    ori_build_def bd = ori_default_build_def();
    bd.check_planarity = false;
    if (ori_fold_get_pattern(s->doc, 0, &bd, &p0, &err) != ORI_OK) {
        pthread_mutex_unlock(&s->lock);
        studio_fail_error(out, 400, &err);
        return;
    }
    int first = frames > 1 && !ori_pattern_is_folded_form(p0) && !ori_pattern_is_3d(p0) ? 1 : 0;
    ori_pattern_destroy(p0);
    int n = frames - first; // 1: one state, nothing to replay (the page then keeps its timeline)
    double *times = malloc(sizeof(double) * (size_t)n);
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)n * (size_t)V + 1);
    for (int i = 0; i < n; ++i) {
        int k = first + i;
        ori_pattern *p = NULL;
        if (ori_fold_get_pattern(s->doc, k, &bd, &p, &err) != ORI_OK) {
            pthread_mutex_unlock(&s->lock);
            char line[400];
            ori_error_format(&err, line, sizeof line);
            studio_fail(out, 400, "frame %d: %s", k, line);
            free(times);
            free(pos);
            return;
        }
        if (ori_pattern_vertex_count(p) != V || ori_pattern_edge_count(p) != E) {
            ori_pattern_destroy(p);
            pthread_mutex_unlock(&s->lock);
            studio_fail(out, 400, "frame %d is not a state of the same pattern (other vertices or edges than frame 0)", k);
            free(times);
            free(pos);
            return;
        }
        for (int v = 0; v < V; ++v) pos[(size_t)i * V + v] = ori_pattern_vertex(p, v);
        ori_pattern_destroy(p);
    }
    // frame_time (seconds, orikin simulate) first; then orikin:time (orikin sequence); else index.
    frames_unit unit = FRAMES_UNIT_SECONDS;
    if (!frame_times(s->doc, first, n, "frame_time", times)) {
        unit = FRAMES_UNIT_FOLD;
        if (!frame_times(s->doc, first, n, "orikin:time", times)) {
            unit = FRAMES_UNIT_FRAME;
            for (int i = 0; i < n; ++i) times[i] = (double)i;
        }
    }
    char file[STUDIO_PATH_MAX];
    snprintf(file, sizeof file, "%s", s->file);
    pthread_mutex_unlock(&s->lock);

    if (binary) {
        // Little-endian float64: count, V, unit (0 frame, 1 s, 2 fold), first frame, 0 × 4;
        // then count times; then count × 3V vertex coordinates.
        size_t words = 8 + (size_t)n + 3 * (size_t)n * (size_t)V;
        unsigned char *body = malloc(8 * words);
        double head[8] = {(double)n, (double)V, (double)unit, (double)first, 0, 0, 0, 0};
        size_t w = 0;
        for (int i = 0; i < 8; ++i) put_f64(body + 8 * w++, head[i]);
        for (int i = 0; i < n; ++i) put_f64(body + 8 * w++, times[i]);
        for (size_t j = 0; j < (size_t)n * (size_t)V; ++j) {
            put_f64(body + 8 * w++, pos[j].x);
            put_f64(body + 8 * w++, pos[j].y);
            put_f64(body + 8 * w++, pos[j].z);
        }
        free(out->body);
        out->status = 200;
        out->content_type = "application/octet-stream";
        out->body = (char *)body;
        out->size = 8 * words;
    } else {
        json_t *o = json_object();
        json_object_set_new(o, "file", json_string(file));
        json_object_set_new(o, "unit", json_string(unit_names[unit]));
        json_object_set_new(o, "first_frame", json_integer(first));
        json_object_set_new(o, "vertex_count", json_integer(V));
        json_t *ts = json_array(), *fr = json_array(), *coords = json_array();
        for (int i = 0; i < n; ++i) {
            json_array_append_new(fr, json_integer(first + i));
            json_array_append_new(ts, json_real(times[i]));
            json_t *vs = json_array();
            for (int v = 0; v < V; ++v) {
                ori_v3 x = pos[(size_t)i * V + v];
                json_array_append_new(vs, json_pack("[fff]", x.x, x.y, x.z));
            }
            json_array_append_new(coords, vs);
        }
        json_object_set_new(o, "frames", fr);
        json_object_set_new(o, "times", ts);
        json_object_set_new(o, "vertices_coords", coords);
        studio_respond_json(out, 200, o);
    }
    free(times);
    free(pos);
}
