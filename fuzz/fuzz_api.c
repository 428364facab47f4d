// libFuzzer target for the studio's API handler (orikin view): an input is a list of requests,
// each "METHOD /api/PATH?QUERY" on its first line and its body after, separated by lines "%%",
// run in order on a fresh studio (a blank sheet; POST /api/open loads anything). Every answer
// must be a known status with a body; a JSON answer must parse; a refused request (4xx) must
// leave the document exactly as it was. Any crash, leak, sanitizer report or abort is a bug.
#include <jansson.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "studio.h"
#include <orikin/orikin.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define MAX_REQUESTS 12
#define MAX_ARGS 8

static char *document(studio *s)
{
    studio_request req = {"GET", "/api/document", NULL, 0, NULL, 0};
    studio_response r;
    studio_handle(s, &req, &r);
    if (r.status != 200) abort();
    return r.body;
}

// Split "a=b&c=d" in place (no percent-decoding: the HTTP front does that before the handler).
static int split_query(char *q, studio_arg *args)
{
    int n = 0;
    for (char *tok = q; tok && *tok && n < MAX_ARGS;) {
        char *amp = strchr(tok, '&');
        if (amp) *amp = '\0';
        char *eq = strchr(tok, '=');
        if (eq) *eq = '\0';
        args[n].key = tok;
        args[n].value = eq ? eq + 1 : "";
        n++;
        tok = amp ? amp + 1 : NULL;
    }
    return n;
}

static void one_request(studio *s, char *text, size_t len)
{
    char *nl = memchr(text, '\n', len);
    size_t head_len = nl ? (size_t)(nl - text) : len;
    char head[512];
    if (head_len >= sizeof head) return;
    memcpy(head, text, head_len);
    head[head_len] = '\0';
    const char *body = nl ? nl + 1 : NULL;
    size_t body_size = nl ? len - head_len - 1 : 0;
    char *sp = strchr(head, ' ');
    if (!sp) return;
    *sp = '\0';
    char *target = sp + 1, *q = strchr(target, '?');
    studio_arg args[MAX_ARGS];
    int nargs = 0;
    if (q) {
        *q = '\0';
        nargs = split_query(q + 1, args);
    }
    char *before = document(s);
    long version = studio_version(s);
    studio_request req = {head, target, args, nargs, body, body_size};
    studio_response r;
    studio_handle(s, &req, &r);
    static const int known[] = {200, 400, 404, 405, 409, 413, 500, 501};
    bool ok = false;
    for (size_t i = 0; i < sizeof known / sizeof known[0]; ++i) ok |= r.status == known[i];
    if (!ok || !r.body || !r.content_type) abort();
    if (strcmp(r.content_type, "application/json") == 0) {
        json_t *j = json_loadb(r.body, r.size, JSON_DECODE_ANY, NULL);
        if (!j) abort();
        if (r.status != 200 && !json_is_string(json_object_get(j, "error"))) abort();
        json_decref(j);
    }
    if (r.status >= 400 && r.status < 500) {
        char *after = document(s);
        if (strcmp(before, after) != 0 || studio_version(s) != version) abort(); // refused means unchanged
        free(after);
    }
    free(before);
    studio_response_free(&r);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    memcpy(text, data, size);
    text[size] = '\0';
    studio_def def = studio_default_def();
    def.work_limit = 2e5;          // keep each input fast: refusals are what is fuzzed
    def.cache_bytes = (size_t)1 << 20;
    def.max_open_bytes = 1 << 20;
    def.render_pixels = 1 << 16;   // pictures and animations small enough for many runs a second
    def.animation_pixels = 1 << 18;
    studio *s = NULL;
    char err[256];
    if (studio_create(&def, &s, err, sizeof err) != 0) abort();
    char *p = text, *end = text + size;
    for (int n = 0; n < MAX_REQUESTS && p < end; ++n) {
        char *sep = strstr(p, "\n%%\n");
        size_t len = sep ? (size_t)(sep - p) : (size_t)(end - p);
        one_request(s, p, len);
        p = sep ? sep + 4 : end;
    }
    studio_destroy(s);
    free(text);
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
