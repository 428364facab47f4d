// The request and response helpers every handler uses: responses and errors, reading request
// bodies and arguments, the job slot, the body limit and the session token. The bottom layer of
// the studio: it calls no handler, no router and no document function.
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

void studio_error_line(char *buf, size_t size, const ori_error *err)
{
    ori_error_format(err, buf, size);
    for (char *c = buf; *c; ++c)
        if (*c == '\n' || *c == '\r') *c = ' ';
}

// The document's file name with another extension ("open-corner.svg").
void studio_download_name(const char *file, const char *ext, char *out, size_t size)
{
    const char *base = strrchr(file, '/');
    base = base ? base + 1 : file;
    const char *dot = strrchr(base, '.');
    int len = dot && dot != base ? (int)(dot - base) : (int)strlen(base);
    if (len > 100) len = 100;
    snprintf(out, size, "%.*s%s", len, base, ext);
    for (char *c = out; *c; ++c)
        if (*c == '"' || *c == '\\' || (unsigned char)*c < 32) *c = '_';
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
    studio_error_line(line, sizeof line, err);
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
