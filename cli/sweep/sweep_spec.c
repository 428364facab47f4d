// The sweep spec: reading and checking it, its points (grid × samples, seeded draws), the
// substitution of parameter values into the job, and the spec's hash.
#define _POSIX_C_SOURCE 200809L
#include "sweep.h"
#include "sweep_internal.h"

#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

static const struct {
    const char *name, *sql, *job;
} outputs[SWEEP_OUT_COUNT] = {
    {"verdict", "TEXT", "fold"},
    {"reached", "REAL", "fold"},
    {"frames", "INTEGER", "fold"},
    {"collides", "INTEGER", "collide"},
    {"min_clearance", "REAL", "collide"},
    {"feasible", "INTEGER", "actuate"},
    {"current_needed", "REAL", "actuate"},
    {"mechanism_current", "REAL", "actuate"},
    {"worst_edge", "INTEGER", "actuate"},
    {"fold_time", "REAL", "simulate"},
    {"sim_reached", "INTEGER", "simulate"},
    {"layer_count", "TEXT", "layers"},
};

const char *sweep_output_name(sweep_output o) { return outputs[o].name; }
const char *sweep_output_sql_type(sweep_output o) { return outputs[o].sql; }
const char *sweep_output_job(sweep_output o) { return outputs[o].job; }

int sweep_fail(char *err, size_t size, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, size, fmt, ap);
    va_end(ap);
    // One line: a name quoted from the spec may hold a newline or another control character
    // (a key "l\nx"): each becomes a '?' (fuzz_sweep found a two-line refusal).
    for (char *c = err; *c; ++c)
        if ((unsigned char)*c < 0x20 || *c == 0x7f) *c = '?';
    return SWEEP_EXIT_INPUT;
}

// --- hashing and random draws ---------------------------------------------------------------

static uint64_t fnv1a(uint64_t h, const void *data, size_t n)
{
    const unsigned char *p = data;
    for (size_t i = 0; i < n; ++i) {
        h ^= p[i];
        h *= 0x100000001b3ULL;
    }
    return h;
}

static uint64_t splitmix64(uint64_t x)
{
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

// A uniform number in [0, 1) for (seed, point, parameter, stream): a counter-based generator,
// so a point's draws depend on nothing but its index (shards and ranks agree by construction).
static double draw(uint64_t seed, int64_t point, int param, int stream)
{
    uint64_t x = splitmix64(splitmix64(splitmix64(seed) ^ (uint64_t)point) ^ (uint64_t)(param * 2 + stream));
    return (double)(x >> 11) * 0x1.0p-53;
}

// --- points ---------------------------------------------------------------------------------

void sweep_point_values(const sweep_spec *spec, int64_t index, sweep_value *values, int64_t *sample)
{
    int64_t g = index / spec->samples;
    if (sample) *sample = index % spec->samples;
    // The last grid parameter varies fastest.
    for (int j = spec->param_count - 1; j >= 0; --j) {
        const sweep_param *p = &spec->params[j];
        sweep_value *v = &values[j];
        memset(v, 0, sizeof *v);
        if (p->kind == SWEEP_UNIFORM) {
            v->number = p->a + (p->b - p->a) * draw(spec->seed, index, j, 0);
            continue;
        }
        if (p->kind == SWEEP_NORMAL) {
            double u1 = draw(spec->seed, index, j, 0), u2 = draw(spec->seed, index, j, 1);
            v->number = p->a + p->b * sqrt(-2.0 * log(1.0 - u1)) * cos(2.0 * ORI_PI * u2);
            continue;
        }
        int i = (int)(g % p->count);
        g /= p->count;
        if (p->kind == SWEEP_RANGE) {
            v->number = p->count == 1 ? p->a : i == p->count - 1 ? p->b : p->a + (p->b - p->a) * i / (p->count - 1);
        } else {
            json_t *x = json_array_get(p->values, (size_t)i);
            if (json_is_string(x)) {
                v->is_string = true;
                v->string = json_string_value(x);
            } else {
                v->number = json_number_value(x);
            }
        }
    }
}

static const sweep_param *find_param(const sweep_spec *spec, const char *name, int *at)
{
    for (int j = 0; j < spec->param_count; ++j)
        if (strcmp(spec->params[j].name, name) == 0) {
            if (at) *at = j;
            return &spec->params[j];
        }
    return NULL;
}

static json_t *substitute(const sweep_spec *spec, const json_t *t, const sweep_value *values)
{
    if (json_is_string(t)) {
        const char *s = json_string_value(t);
        int j;
        if (s[0] == '$' && find_param(spec, s + 1, &j))
            return values[j].is_string ? json_string(values[j].string) : json_real(values[j].number);
        return json_incref((json_t *)t);
    }
    if (json_is_array(t)) {
        json_t *a = json_array();
        for (size_t i = 0; i < json_array_size(t); ++i) json_array_append_new(a, substitute(spec, json_array_get(t, i), values));
        return a;
    }
    if (json_is_object(t)) {
        json_t *o = json_object();
        const char *k;
        json_t *v;
        json_object_foreach((json_t *)t, k, v) json_object_set_new(o, k, substitute(spec, v, values));
        return o;
    }
    return json_incref((json_t *)t);
}

json_t *sweep_point_job(const sweep_spec *spec, int64_t index)
{
    sweep_value values[SWEEP_MAX_PARAMS];
    sweep_point_values(spec, index, values, NULL);
    return substitute(spec, spec->template_, values);
}

// --- checking -------------------------------------------------------------------------------

// Most values of one parameter whose job is parsed before the sweep runs.
#define SWEEP_CHECK_VALUES 1000

static bool is_identifier(const char *s)
{
    if (!(isalpha((unsigned char)s[0]) || s[0] == '_')) return false;
    for (const char *p = s; *p; ++p)
        if (!(isalnum((unsigned char)*p) || *p == '_')) return false;
    return true;
}

static bool reserved(const char *s)
{
    static const char *const words[] = {"idx", "sample", "status", "error", "rowid", "oid", "_rowid_"};
    for (size_t i = 0; i < sizeof words / sizeof words[0]; ++i)
        if (strcasecmp(s, words[i]) == 0) return true;
    for (int o = 0; o < SWEEP_OUT_COUNT; ++o)
        if (strcasecmp(s, outputs[o].name) == 0) return true;
    return false;
}

// Every "$name" in t names a parameter; marks the parameters used. path is t's JSON path.
static int check_refs(const sweep_spec *spec, const json_t *t, char *path, size_t cap, bool *used, char *err, size_t n)
{
    size_t len = strlen(path);
    if (json_is_string(t)) {
        const char *s = json_string_value(t);
        if (s[0] != '$') return 0;
        int j;
        if (!find_param(spec, s + 1, &j)) return sweep_fail(err, n, "%s: %s is not a parameter (see \"parameters\")", path, s);
        used[j] = true;
        return 0;
    }
    int rc = 0;
    if (json_is_array(t)) {
        for (size_t i = 0; i < json_array_size(t) && !rc; ++i) {
            snprintf(path + len, cap - len, "[%zu]", i);
            rc = check_refs(spec, json_array_get(t, i), path, cap, used, err, n);
        }
    } else if (json_is_object(t)) {
        const char *k;
        json_t *v;
        json_object_foreach((json_t *)t, k, v) {
            snprintf(path + len, cap - len, "%s%s", len ? "." : "", k);
            if ((rc = check_refs(spec, v, path, cap, used, err, n))) break;
        }
    }
    path[len] = '\0';
    return rc;
}

static bool get_number(const json_t *v, double *out)
{
    if (!json_is_number(v)) return false;
    *out = json_number_value(v);
    return isfinite(*out);
}

// The job runs the stage (present and not false).
// Whether the job runs the stage; a sequence is the fold stage's motion (verdict, reached,
// frames, collide).
static bool stage(const json_t *job, const char *name)
{
    const json_t *v = json_object_get(job, name);
    if (strcmp(name, "fold") == 0 && !(v && !json_is_false(v) && !json_is_null(v))) v = json_object_get(job, "sequence");
    return v && !json_is_false(v) && !json_is_null(v);
}

static int parse_param(sweep_spec *spec, json_t *o, int j, char *err, size_t n)
{
    sweep_param *p = &spec->params[j];
    memset(p, 0, sizeof *p);
    if (!json_is_object(o)) return sweep_fail(err, n, "parameters[%d]: must be an object {\"name\": ..., ...}", j);
    json_t *name = json_object_get(o, "name");
    if (!json_is_string(name)) return sweep_fail(err, n, "parameters[%d].name: must be a string", j);
    const char *s = json_string_value(name);
    if (!is_identifier(s) || strlen(s) >= SWEEP_NAME_MAX)
        return sweep_fail(err, n, "parameters[%d].name: '%s' must be a letter or _ then letters, digits or _ (at most %d)", j, s,
                          SWEEP_NAME_MAX - 1);
    if (reserved(s)) return sweep_fail(err, n, "parameters[%d].name: '%s' is reserved (a column of the results)", j, s);
    if (find_param(spec, s, NULL)) return sweep_fail(err, n, "parameters[%d].name: '%s' given twice", j, s);
    strcpy(p->name, s);
    const char *kinds[] = {"from", "values", "uniform", "normal"};
    int found = -1;
    for (int k = 0; k < 4; ++k)
        if (json_object_get(o, kinds[k])) {
            if (found >= 0)
                return sweep_fail(err, n, "parameters[%d]: %s and %s exclude each other (one of from/to/count, values, uniform, normal)",
                                  j, kinds[found], kinds[k]);
            found = k;
        }
    const char *k;
    json_t *v;
    json_object_foreach(o, k, v) {
        bool ok = strcmp(k, "name") == 0 || (found == 0 && (strcmp(k, "from") == 0 || strcmp(k, "to") == 0 || strcmp(k, "count") == 0)) ||
                  (found >= 1 && strcmp(k, kinds[found]) == 0) || strcmp(k, "description") == 0;
        if (!ok) return sweep_fail(err, n, "parameters[%d].%s: unknown field here", j, k);
    }
    if (found < 0) return sweep_fail(err, n, "parameters[%d]: needs from/to/count, values, uniform or normal", j);
    if (found == 0) {
        p->kind = SWEEP_RANGE;
        json_t *c = json_object_get(o, "count");
        if (!get_number(json_object_get(o, "from"), &p->a)) return sweep_fail(err, n, "parameters[%d].from: must be a number", j);
        if (!get_number(json_object_get(o, "to"), &p->b)) return sweep_fail(err, n, "parameters[%d].to: must be a number", j);
        if (!json_is_integer(c) || json_integer_value(c) < 1 || json_integer_value(c) > 100000000)
            return sweep_fail(err, n, "parameters[%d].count: must be an integer from 1 to 100000000", j);
        p->count = (int)json_integer_value(c);
        // from + (to − from)·i / (count − 1) must stay finite: an infinite value would be
        // substituted as nothing (jansson has no real for it), the job silently without it.
        if (p->count > 1 && !isfinite((p->b - p->a) * (p->count - 1)))
            return sweep_fail(err, n, "parameters[%d]: from and to are too far apart for %d values (a value would overflow)", j,
                              p->count);
    } else if (found == 1) {
        p->kind = SWEEP_LIST;
        p->values = json_object_get(o, "values");
        size_t m = json_array_size(p->values);
        if (!json_is_array(p->values) || m == 0) return sweep_fail(err, n, "parameters[%d].values: must be a non-empty array", j);
        for (size_t i = 0; i < m; ++i) {
            json_t *x = json_array_get(p->values, i);
            double d;
            if (!json_is_string(x) && !get_number(x, &d))
                return sweep_fail(err, n, "parameters[%d].values[%zu]: must be a finite number or a string", j, i);
        }
        p->count = (int)m;
    } else {
        p->kind = found == 2 ? SWEEP_UNIFORM : SWEEP_NORMAL;
        json_t *a = json_object_get(o, kinds[found]);
        if (!json_is_array(a) || json_array_size(a) != 2 || !get_number(json_array_get(a, 0), &p->a) ||
            !get_number(json_array_get(a, 1), &p->b))
            return sweep_fail(err, n, "parameters[%d].%s: must be [%s]", j, kinds[found], found == 2 ? "lo, hi" : "mean, sd");
        if (found == 2 && !(p->b >= p->a)) return sweep_fail(err, n, "parameters[%d].uniform: hi must be >= lo", j);
        if (found == 3 && !(p->b >= 0.0)) return sweep_fail(err, n, "parameters[%d].normal: sd must be >= 0", j);
        // every draw finite: hi − lo, and mean ± 9 sd (the largest Box–Muller deviate of 53-bit
        // uniforms is √(2·53·ln 2) ≈ 8.6)
        if (found == 2 && !isfinite(p->b - p->a))
            return sweep_fail(err, n, "parameters[%d].uniform: lo and hi are too far apart (a draw would overflow)", j);
        if (found == 3 && !isfinite(fabs(p->a) + 9.0 * p->b))
            return sweep_fail(err, n, "parameters[%d].normal: mean and sd too large (a draw would overflow)", j);
        p->count = 1;
        spec->has_random = true;
    }
    return 0;
}

void sweep_spec_free(sweep_spec *spec)
{
    if (!spec) return;
    json_decref(spec->root);
    json_decref(spec->template_);
    free(spec->path);
    free(spec->dir);
    ori_buffer_free(spec->canonical);
    free(spec->fold_dir);
    free(spec);
}

static int load(sweep_spec *spec, char *err, size_t n)
{
    json_error_t je;
    spec->root = json_load_file(spec->path, JSON_REJECT_DUPLICATES, &je);
    if (!spec->root) {
        if (je.line <= 0) return sweep_fail(err, n, "%s", je.text);
        return sweep_fail(err, n, "line %d, column %d: %s", je.line, je.column, je.text);
    }
    json_t *root = spec->root;
    if (!json_is_object(root)) return sweep_fail(err, n, "the spec must be a JSON object");
    static const char *const top[] = {"base", "design", "parameters", "samples", "seed", "job", "outputs", "title",
                                      "description"};
    const char *k;
    json_t *v;
    json_object_foreach(root, k, v) {
        bool known = false;
        for (size_t i = 0; i < sizeof top / sizeof top[0]; ++i) known |= strcmp(k, top[i]) == 0;
        if (!known)
            return sweep_fail(err, n, "%s: unknown field (base, design, parameters, samples, seed, job, outputs, title, description)", k);
    }
    if (!json_object_get(root, "base")) return sweep_fail(err, n, "base: missing (a FOLD file or {\"generate\": KIND, ...})");
    if (!json_is_object(json_object_get(root, "job"))) return sweep_fail(err, n, "job: missing or not an object");
    // Parameters.
    json_t *ps = json_object_get(root, "parameters");
    if (ps && !json_is_array(ps)) return sweep_fail(err, n, "parameters: must be an array of {\"name\", ...}");
    if (json_array_size(ps) > SWEEP_MAX_PARAMS) return sweep_fail(err, n, "parameters: at most %d", SWEEP_MAX_PARAMS);
    for (size_t j = 0; j < json_array_size(ps); ++j) {
        int rc = parse_param(spec, json_array_get(ps, j), (int)j, err, n);
        if (rc) return rc;
        spec->param_count++;
    }
    json_t *s = json_object_get(root, "samples");
    spec->samples = 1;
    if (s) {
        if (!json_is_integer(s) || json_integer_value(s) < 1 || json_integer_value(s) > SWEEP_MAX_POINTS)
            return sweep_fail(err, n, "samples: must be an integer from 1 to %lld", (long long)SWEEP_MAX_POINTS);
        spec->samples = json_integer_value(s);
    }
    json_t *seed = json_object_get(root, "seed");
    if (seed) {
        if (!json_is_integer(seed) || json_integer_value(seed) < 0) return sweep_fail(err, n, "seed: must be an integer >= 0");
        spec->seed = (uint64_t)json_integer_value(seed);
    }
    if (spec->samples > 1 && !spec->has_random)
        return sweep_fail(err, n, "samples: %lld repetitions of every point need a random parameter (uniform or normal)",
                          (long long)spec->samples);
    spec->grid_points = 1;
    for (int j = 0; j < spec->param_count; ++j) {
        spec->grid_points *= spec->params[j].count;
        if (spec->grid_points > SWEEP_MAX_POINTS) return sweep_fail(err, n, "parameters: more than %lld points", (long long)SWEEP_MAX_POINTS);
    }
    if ((double)spec->grid_points * (double)spec->samples > (double)SWEEP_MAX_POINTS)
        return sweep_fail(err, n, "samples: more than %lld points in all", (long long)SWEEP_MAX_POINTS);
    spec->point_count = spec->grid_points * spec->samples;
    // The template: base, design and job.
    spec->template_ = json_object();
    static const char *const parts[] = {"base", "design", "job"};
    for (int i = 0; i < 3; ++i)
        if (json_object_get(root, parts[i])) json_object_set(spec->template_, parts[i], json_object_get(root, parts[i]));
    bool used[SWEEP_MAX_PARAMS] = {false};
    char path[512] = "";
    int rc = check_refs(spec, spec->template_, path, sizeof path, used, err, n);
    if (rc) return rc;
    for (int j = 0; j < spec->param_count; ++j)
        if (!used[j])
            return sweep_fail(err, n, "parameters[%d]: '%s' is used nowhere (write \"$%s\" where its value goes)", j, spec->params[j].name,
                              spec->params[j].name);
    // Outputs: default every output of the stages the job runs.
    json_t *job = json_object_get(root, "job");
    json_t *outs = json_object_get(root, "outputs");
    if (outs && (!json_is_array(outs) || json_array_size(outs) == 0))
        return sweep_fail(err, n, "outputs: must be a non-empty array of output names");
    for (int o = 0; o < SWEEP_OUT_COUNT; ++o) {
        bool staged = stage(job, outputs[o].job);
        if (o == SWEEP_OUT_COLLIDES || o == SWEEP_OUT_MIN_CLEARANCE) staged = staged && stage(job, "fold");
        spec->outputs[o] = !outs && staged;
    }
    for (size_t i = 0; i < json_array_size(outs); ++i) {
        json_t *x = json_array_get(outs, i);
        int found = -1;
        for (int o = 0; o < SWEEP_OUT_COUNT && json_is_string(x); ++o)
            if (strcmp(json_string_value(x), outputs[o].name) == 0) found = o;
        if (found < 0) {
            char names[512] = "";
            for (int o = 0; o < SWEEP_OUT_COUNT; ++o) {
                strcat(names, o ? ", " : "");
                strcat(names, outputs[o].name);
            }
            return sweep_fail(err, n, "outputs[%zu]: %s is not an output (%s)", i, json_is_string(x) ? json_string_value(x) : "(not a string)",
                              names);
        }
        if (spec->outputs[found]) return sweep_fail(err, n, "outputs[%zu]: %s given twice", i, outputs[found].name);
        if (!stage(job, outputs[found].job))
            return sweep_fail(err, n, "outputs[%zu]: %s needs job.%s", i, outputs[found].name, outputs[found].job);
        if ((found == SWEEP_OUT_COLLIDES || found == SWEEP_OUT_MIN_CLEARANCE) && !stage(job, "fold"))
            return sweep_fail(err, n, "outputs[%zu]: %s needs job.fold (the motion it checks)", i, outputs[found].name);
        spec->outputs[found] = true;
    }
    bool any = false;
    for (int o = 0; o < SWEEP_OUT_COUNT; ++o) any |= spec->outputs[o];
    if (!any) return sweep_fail(err, n, "job: runs nothing (fold, sequence, collide, actuate, simulate or layers)");
    // The job of every value of every parameter (the others at point 0) must parse: types and
    // shapes are checked before anything runs (values out of a stage's range fail that point).
    sweep_value values[SWEEP_MAX_PARAMS], base[SWEEP_MAX_PARAMS];
    sweep_point_values(spec, 0, base, NULL);
    for (int j = -1; j < spec->param_count; ++j) {
        int count = j < 0 ? 1 : spec->params[j].kind == SWEEP_LIST || spec->params[j].kind == SWEEP_RANGE ? spec->params[j].count : 0;
        // At most SWEEP_CHECK_VALUES values of a long range or list, evenly spread, both ends
        // included (the others fail their point at run time if they must).
        int m = count < SWEEP_CHECK_VALUES ? count : SWEEP_CHECK_VALUES;
        for (int q = 0; q < m; ++q) {
            int i = count <= SWEEP_CHECK_VALUES ? q : (int)((int64_t)q * (count - 1) / (SWEEP_CHECK_VALUES - 1));
            memcpy(values, base, sizeof values);
            if (j >= 0) {
                const sweep_param *p = &spec->params[j];
                memset(&values[j], 0, sizeof values[j]);
                if (p->kind == SWEEP_RANGE) {
                    values[j].number = p->count == 1 ? p->a : i == p->count - 1 ? p->b : p->a + (p->b - p->a) * i / (p->count - 1);
                } else {
                    json_t *x = json_array_get(p->values, (size_t)i);
                    values[j].is_string = json_is_string(x);
                    values[j].string = json_string_value(x);
                    values[j].number = json_number_value(x);
                }
            }
            json_t *t = substitute(spec, spec->template_, values);
            sweep_cfg cfg;
            char why[SWEEP_ERROR_MAX];
            rc = sweep_cfg_parse(t, spec->dir, &cfg, why, sizeof why);
            json_decref(t);
            sweep_cfg_free(&cfg); // (a failed parse may hold some of its fields)
            if (rc) {
                if (j < 0) return sweep_fail(err, n, "%s", why);
                const sweep_param *p = &spec->params[j];
                json_t *x = p->kind == SWEEP_LIST ? json_array_get(p->values, (size_t)i) : NULL;
                if (json_is_string(x)) return sweep_fail(err, n, "%s (with %s = \"%s\")", why, p->name, json_string_value(x));
                char num[32];
                ori_format_real(values[j].number, num, sizeof num);
                return sweep_fail(err, n, "%s (with %s = %s)", why, p->name, num);
            }
            if (j < 0 && cfg.base_is_file) {
                // The base file's bytes are part of the hash: a changed file is another sweep.
                char *data = NULL;
                size_t size = 0;
                ori_error e;
                if (ori_file_read_all(cfg.file, (size_t)1 << 31, &data, &size, &e) != ORI_OK)
                    return sweep_fail(err, n, "base: %s: %s", cfg.file, e.message);
                uint64_t h1 = fnv1a(0xcbf29ce484222325ULL, data, size), h2 = fnv1a(0x84222325cbf29ce4ULL, data, size);
                ori_buffer_free(data);
                spec->file_hash[0] = h1;
                spec->file_hash[1] = h2;
            }
        }
    }
    // A base file named by a parameter would change the hash point by point: not allowed.
    json_t *b = json_object_get(root, "base");
    json_t *bf = json_is_object(b) ? json_object_get(b, "file") : b;
    if (json_is_string(bf) && json_string_value(bf)[0] == '$')
        return sweep_fail(err, n, "base.file: cannot be a parameter (one sweep, one base file)");
    // Canonical text and hash.
    char *text = json_dumps(root, JSON_SORT_KEYS | JSON_COMPACT | JSON_REAL_PRECISION(17));
    ori_error e;
    spec->canonical = ori_json_normalize(text, false, &e);
    free(text);
    if (!spec->canonical) return sweep_fail(err, n, "%s", e.message);
    size_t len = strlen(spec->canonical);
    uint64_t h1 = fnv1a(0xcbf29ce484222325ULL ^ spec->file_hash[0], spec->canonical, len);
    uint64_t h2 = fnv1a(0x84222325cbf29ce4ULL ^ spec->file_hash[1], spec->canonical, len);
    snprintf(spec->hash, sizeof spec->hash, "%016llx%016llx", (unsigned long long)splitmix64(h1), (unsigned long long)splitmix64(h2));
    return 0;
}

int sweep_spec_load(const char *path, sweep_spec **out, char *err, size_t err_size)
{
    *out = NULL;
    sweep_spec *spec = calloc(1, sizeof *spec);
    spec->path = strdup(path);
    const char *slash = strrchr(path, '/');
    size_t dl = slash ? (size_t)(slash - path) + 1 : 0;
    spec->dir = malloc(dl + 1);
    memcpy(spec->dir, path, dl);
    spec->dir[dl] = '\0';
    int rc = load(spec, err, err_size);
    if (rc) {
        sweep_spec_free(spec);
        return rc;
    }
    *out = spec;
    return 0;
}
