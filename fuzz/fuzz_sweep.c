// libFuzzer target for the sweep spec reader (cli/sweep/sweep_spec.c and the job parser it runs,
// sweep_job.c's sweep_cfg_parse): the input is the JSON text of a spec (seeds: examples/sweeps,
// tests/data/sweep, fuzz/seeds/sweep). It is written as tests/data/sweep/spec.json in a
// temporary directory that mirrors examples/patterns/, so that a base named as the repository's
// specs name it ("../../../examples/patterns/thesis-flap.fold") reads. A spec with a string that
// could name a file outside that directory (an absolute path, /dev, /proc, /sys) is skipped.
// Work stays bounded: a few points are evaluated (the first, the last, four chosen by the input),
// whatever the point count.
//
// Invariants beyond "no crash, no leak, no sanitizer report":
// - a refused spec gives SWEEP_EXIT_INPUT, no spec, and a non-empty one-line message;
// - an accepted spec's point count is grid × samples, the grid the product of its range and
//   list counts, 1 … SWEEP_MAX_POINTS; samples > 1 only with a random parameter;
// - its hash is 32 lowercase hex digits, the same when the spec is read again; its canonical
//   text read as a spec gives the same canonical text and hash;
// - sweep_point_values is deterministic (the same index twice, the same values and sample),
//   the sample is index mod samples, a list's value is its element at the point's digit of the
//   grid (the last parameter varying fastest), a range's value lies between from and to, a
//   uniform draw in [lo, hi], a normal draw finite;
// - sweep_point_job is the template with every "$name" of a parameter replaced by its value
//   (the same keys, array sizes and other values) and dumps as JSON.
#define _XOPEN_SOURCE 700
#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "sweep.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static char base_dir[256], spec_path[320], canon_path[320];
static bool trace;

static void fail(const char *what)
{
    fprintf(stderr, "fuzz_sweep: %s\n", what);
    abort();
}

static void write_file(const char *path, const void *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(data, 1, size, f) != size || fclose(f) != 0) fail(path);
}

static int remove_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
    (void)st, (void)flag, (void)ftw;
    return remove(path);
}

static void remove_base_dir(void) { nftw(base_dir, remove_entry, 16, FTW_DEPTH | FTW_PHYS); }

static void make_dir(const char *sub)
{
    char path[400];
    snprintf(path, sizeof path, "%s/%s", base_dir, sub);
    if (mkdir(path, 0700) != 0 && errno != EEXIST) fail(path);
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    trace = getenv("FUZZ_SWEEP_TRACE") != NULL;
    const char *tmp = getenv("TMPDIR");
    snprintf(base_dir, sizeof base_dir, "%s/fuzz_sweep.XXXXXX", tmp && *tmp ? tmp : "/tmp");
    if (!mkdtemp(base_dir)) fail("mkdtemp");
    atexit(remove_base_dir);
    const char *dirs[] = {"examples", "examples/patterns", "tests", "tests/data", "tests/data/sweep"};
    for (size_t i = 0; i < sizeof dirs / sizeof dirs[0]; ++i) make_dir(dirs[i]);
    static const char *const patterns[] = {"degree4-vertex", "degree6-vertex", "non-flat-foldable-vertex", "open-corner-gold",
                                           "open-corner", "thesis-flap", "two-flaps"};
    for (size_t i = 0; i < sizeof patterns / sizeof patterns[0]; ++i) {
        char src[512], dst[512];
        snprintf(src, sizeof src, "%s/examples/patterns/%s.fold", ORI_SOURCE_DIR, patterns[i]);
        snprintf(dst, sizeof dst, "%s/examples/patterns/%s.fold", base_dir, patterns[i]);
        char *text = NULL;
        size_t n = 0;
        ori_error e;
        if (ori_file_read_all(src, (size_t)1 << 20, &text, &n, &e) != ORI_OK) fail(src);
        write_file(dst, text, n);
        ori_buffer_free(text);
    }
    snprintf(spec_path, sizeof spec_path, "%s/tests/data/sweep/spec.json", base_dir);
    snprintf(canon_path, sizeof canon_path, "%s/tests/data/sweep/canonical.json", base_dir);
    return 0;
}

// A string that could name a file outside the temporary tree (or a device that never ends).
static bool names_outside(const json_t *t)
{
    if (json_is_string(t)) {
        const char *s = json_string_value(t);
        return s[0] == '/' || strstr(s, "dev/") || strstr(s, "proc/") || strstr(s, "sys/") || strstr(s, "../../../../");
    }
    const char *k;
    json_t *v;
    if (json_is_object(t)) {
        json_object_foreach((json_t *)t, k, v) if (names_outside(v)) return true;
    }
    for (size_t i = 0; json_is_array(t) && i < json_array_size(t); ++i)
        if (names_outside(json_array_get(t, i))) return true;
    return false;
}

// The parameter a template string names ("$name"), or −1.
static int param_of(const sweep_spec *s, const json_t *t)
{
    if (!json_is_string(t) || json_string_value(t)[0] != '$') return -1;
    for (int j = 0; j < s->param_count; ++j)
        if (strcmp(s->params[j].name, json_string_value(t) + 1) == 0) return j;
    return -1;
}

// job is template with each "$name" replaced by its value.
static void check_substituted(const sweep_spec *s, const json_t *t, const json_t *job, const sweep_value *values)
{
    if (!job) fail("job: a value went missing");
    int j = param_of(s, t);
    if (j >= 0) {
        if (values[j].is_string) {
            if (!json_is_string(job) || strcmp(json_string_value(job), values[j].string) != 0) fail("job: a string value not substituted");
        } else if (!json_is_real(job) || json_real_value(job) != values[j].number) {
            fail("job: a number value not substituted");
        }
        return;
    }
    if (json_typeof(t) != json_typeof(job)) fail("job: a value changed type");
    if (json_is_array(t)) {
        if (json_array_size(t) != json_array_size(job)) fail("job: an array changed size");
        for (size_t i = 0; i < json_array_size(t); ++i)
            check_substituted(s, json_array_get(t, i), json_array_get(job, i), values);
    } else if (json_is_object(t)) {
        if (json_object_size(t) != json_object_size(job)) fail("job: an object changed keys");
        const char *k;
        json_t *v;
        json_object_foreach((json_t *)t, k, v) check_substituted(s, v, json_object_get(job, k), values);
    } else if (!json_equal((json_t *)t, (json_t *)job)) {
        fail("job: a value that names no parameter changed");
    }
}

static void check_point(const sweep_spec *s, int64_t index)
{
    sweep_value a[SWEEP_MAX_PARAMS], b[SWEEP_MAX_PARAMS];
    int64_t sa = -1, sb = -1;
    sweep_point_values(s, index, a, &sa);
    sweep_point_values(s, index, b, &sb);
    if (sa != sb || sa != index % s->samples) fail("point: the sample is not index mod samples");
    int64_t g = index / s->samples;
    for (int j = s->param_count - 1; j >= 0; --j) {
        const sweep_param *p = &s->params[j];
        if (a[j].is_string != b[j].is_string || a[j].string != b[j].string ||
            memcmp(&a[j].number, &b[j].number, sizeof(double)) != 0)
            fail("point: the same index gave other values");
        double x = a[j].number;
        if (p->kind == SWEEP_UNIFORM) {
            if (a[j].is_string || !(x >= p->a && x <= p->b)) fail("point: a uniform draw outside [lo, hi]");
            continue;
        }
        if (p->kind == SWEEP_NORMAL) {
            if (a[j].is_string || !isfinite(x)) fail("point: a normal draw not finite");
            continue;
        }
        int i = (int)(g % p->count);
        g /= p->count;
        if (p->kind == SWEEP_RANGE) {
            if (a[j].is_string || !(x >= fmin(p->a, p->b) && x <= fmax(p->a, p->b))) {
                fprintf(stderr, "%s = %.17g, range [%.17g, %.17g], %d of %d\n", p->name, x, p->a, p->b, i, p->count);
                fail("point: a range value outside [from, to]");
            }
            if ((i == 0 && x != p->a) || (i == p->count - 1 && p->count > 1 && x != p->b)) fail("point: a range's ends are not from and to");
        } else {
            json_t *v = json_array_get(p->values, (size_t)i);
            if (json_is_string(v) ? !a[j].is_string || strcmp(a[j].string, json_string_value(v)) != 0
                                  : a[j].is_string || x != json_number_value(v))
                fail("point: a list value is not its element at the point's grid digit");
        }
    }
    json_t *job = sweep_point_job(s, index);
    check_substituted(s, s->template_, job, a);
    char *text = json_dumps(job, JSON_COMPACT);
    if (!text) fail("job: does not dump as JSON");
    json_t *back = json_loads(text, JSON_DECODE_ANY, NULL);
    if (!back) fail("job: its JSON does not read back");
    json_decref(back);
    free(text);
    json_decref(job);
}

static bool is_hex32(const char *h)
{
    if (strlen(h) != 32) return false;
    for (int i = 0; i < 32; ++i)
        if (!((h[i] >= '0' && h[i] <= '9') || (h[i] >= 'a' && h[i] <= 'f'))) return false;
    return true;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    json_t *peek = json_loadb((const char *)data, size, JSON_DECODE_ANY, NULL);
    bool outside = peek && names_outside(peek);
    json_decref(peek);
    if (outside) return 0;
    write_file(spec_path, data, size);
    sweep_spec *s = NULL;
    char err[512] = "";
    int rc = sweep_spec_load(spec_path, &s, err, sizeof err);
    if (trace) fprintf(stderr, "fuzz_sweep: %s%s\n", rc ? "refused: " : "accepted", rc ? err : "");
    if (rc) {
        if (rc != SWEEP_EXIT_INPUT || s) fail("a refusal is not SWEEP_EXIT_INPUT with no spec");
        if (!err[0] || strchr(err, '\n')) fail("a refusal's message is empty or more than one line");
        if (ori_alloc_live_count() != 0) fail("leak");
        return 0;
    }
    int64_t grid = 1;
    bool random = false;
    for (int j = 0; j < s->param_count; ++j) {
        const sweep_param *p = &s->params[j];
        if (p->kind == SWEEP_RANGE || p->kind == SWEEP_LIST) grid *= p->count;
        else random = true;
        if (p->count < 1) fail("a parameter of no values");
    }
    if (s->grid_points != grid || s->point_count != grid * s->samples || s->point_count < 1 ||
        s->point_count > SWEEP_MAX_POINTS || s->samples < 1 || (s->samples > 1 && !random))
        fail("the point count is not grid × samples in 1 … SWEEP_MAX_POINTS");
    if (!is_hex32(s->hash)) fail("the hash is not 32 hex digits");
    if (trace) fprintf(stderr, "fuzz_sweep: %lld points, hash %s\n", (long long)s->point_count, s->hash);
    // bounded: the first and last points and four the input picks
    uint64_t h = 1469598103934665603ULL;
    for (size_t i = 0; i < size; ++i) h = (h ^ data[i]) * 1099511628211ULL;
    int64_t picks[6] = {0, s->point_count - 1};
    for (int k = 2; k < 6; ++k) {
        h = h * 6364136223846793005ULL + 1442695040888963407ULL;
        picks[k] = (int64_t)((h >> 11) % (uint64_t)s->point_count);
    }
    for (int k = 0; k < 6; ++k) check_point(s, picks[k]);
    // read again: the same hash; its canonical text as a spec: the same canonical text and hash
    sweep_spec *again = NULL;
    if (sweep_spec_load(spec_path, &again, err, sizeof err) != 0) fail("the same spec refused the second time");
    if (strcmp(again->hash, s->hash) != 0 || strcmp(again->canonical, s->canonical) != 0) fail("the hash is not deterministic");
    sweep_spec_free(again);
    write_file(canon_path, s->canonical, strlen(s->canonical));
    if (sweep_spec_load(canon_path, &again, err, sizeof err) != 0) {
        fprintf(stderr, "canonical %s\nrefused: %s\n", s->canonical, err);
        fail("the canonical text is refused as a spec");
    }
    if (strcmp(again->canonical, s->canonical) != 0 || strcmp(again->hash, s->hash) != 0) {
        fprintf(stderr, "canonical %s\nagain     %s\n", s->canonical, again->canonical);
        fail("the canonical text's canonical text or hash differs");
    }
    sweep_spec_free(again);
    sweep_spec_free(s);
    if (ori_alloc_live_count() != 0) fail("leak");
    return 0;
}
