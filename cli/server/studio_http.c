// The HTTP front of the studio (libmicrohttpd, one thread per connection): every request must
// name this server in its Host header (DNS rebinding; one Host, Origin and token header each,
// the port in decimal), API requests must carry the session token, bodies are size-limited
// before they are read and never read past twice the limit (a page takes none), and the only files
// served are the web assets embedded in the binary, looked up by exact path. Against a local
// user who opens connections to shut others out: up to STUDIO_MAX_CONNECTIONS at once, and a
// connection that has not shown the token is dropped after STUDIO_IDLE_SECONDS of silence.
#define _DEFAULT_SOURCE
#include <arpa/inet.h>
#include <microhttpd.h>
#include <netinet/in.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/resource.h>
#include <sys/socket.h>

#include "studio_internal.h"

// The asset table generated at build time (cli/server/tools/embed_assets.c).
extern const studio_asset studio_embedded_assets[];
extern const int studio_embedded_asset_count;

// Most query arguments kept per request (the API uses two or three).
#define MAX_ARGS 32

struct studio_http {
    struct MHD_Daemon *daemon;
    studio *s;
    char token[2 * STUDIO_TOKEN_BYTES + 1];
    char host[128];   // the listening address as given ("127.0.0.1", "::1", "0.0.0.0")
    bool wildcard;    // listening on every address: any numeric Host is this server
    bool ipv6;
    int port;
};

static int hexval(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// Per-request state: the body read so far.
typedef struct conn {
    char *body;
    size_t size, cap;
    size_t limit;
    size_t dropped; // bytes past the limit, read and dropped
    bool too_large;
} conn;

bool studio_assets_built(void)
{
    return studio_embedded_asset_count > 0;
}

const studio_asset *studio_asset_find(const char *path)
{
    if (!path) return NULL;
    if (strcmp(path, "/") == 0) path = "/index.html";
    for (int i = 0; i < studio_embedded_asset_count; ++i)
        if (strcmp(studio_embedded_assets[i].path, path) == 0) return &studio_embedded_assets[i];
    return NULL;
}

// Percent-decoding of the path and arguments, as MHD's own except that %00 stays as written: a
// NUL would cut the path short ("/index.html%00.js" must not name /index.html).
static size_t unescape(void *cls, struct MHD_Connection *c, char *s)
{
    (void)cls;
    (void)c;
    char *w = s;
    for (const char *r = s; *r;) {
        int hi, lo;
        if (r[0] == '%' && (hi = hexval(r[1])) >= 0 && (lo = hexval(r[2])) >= 0 && (hi | lo) != 0) {
            *w++ = (char)(hi * 16 + lo);
            r += 3;
        } else {
            *w++ = *r++;
        }
    }
    *w = '\0';
    return (size_t)(w - s);
}

static void quiet_log(void *cls, const char *fmt, va_list ap)
{
    (void)cls;
    (void)fmt;
    (void)ap;
}

// Headers every answer carries: nothing is cached, sniffed, framed or sent to other origins.
static void common_headers(struct MHD_Response *r)
{
    MHD_add_response_header(r, "Cache-Control", "no-store");
    MHD_add_response_header(r, "X-Content-Type-Options", "nosniff");
    MHD_add_response_header(r, "Referrer-Policy", "no-referrer");
    MHD_add_response_header(r, "Cross-Origin-Resource-Policy", "same-origin");
    MHD_add_response_header(r, "Cross-Origin-Opener-Policy", "same-origin");
    MHD_add_response_header(r, "X-Frame-Options", "DENY");
    MHD_add_response_header(r, "Content-Security-Policy",
                            "default-src 'self'; img-src 'self' data: blob:; style-src 'self'; script-src 'self'; "
                            "connect-src 'self'; object-src 'none'; base-uri 'none'; frame-ancestors 'none'; "
                            "form-action 'none'");
}

static enum MHD_Result send_buffer(struct MHD_Connection *c, int status, const char *type, char *body, size_t size,
                                   bool owned, const char *filename)
{
    struct MHD_Response *r = MHD_create_response_from_buffer(size, body ? body : (char *)"",
                                                             owned && body ? MHD_RESPMEM_MUST_FREE : MHD_RESPMEM_PERSISTENT);
    if (!r) {
        if (owned) free(body);
        return MHD_NO;
    }
    if (type) MHD_add_response_header(r, "Content-Type", type);
    if (filename && filename[0]) {
        char disp[256];
        snprintf(disp, sizeof disp, "attachment; filename=\"%s\"", filename);
        MHD_add_response_header(r, "Content-Disposition", disp);
    }
    common_headers(r);
    enum MHD_Result ret = MHD_queue_response(c, (unsigned int)status, r);
    MHD_destroy_response(r);
    return ret;
}

static enum MHD_Result send_error(struct MHD_Connection *c, int status, const char *message)
{
    studio_response out;
    memset(&out, 0, sizeof out);
    studio_fail(&out, status, "%s", message);
    return send_buffer(c, status, out.content_type, out.body, out.size, true, NULL);
}

// Is host (without the port) a numeric address?
static bool numeric_host(const char *h, size_t n)
{
    char buf[64];
    unsigned char addr[16];
    if (n == 0 || n >= sizeof buf) return false;
    if (h[0] == '[') {
        if (n < 2 || h[n - 1] != ']') return false;
        memcpy(buf, h + 1, n - 2);
        buf[n - 2] = '\0';
        return inet_pton(AF_INET6, buf, addr) == 1;
    }
    memcpy(buf, h, n);
    buf[n] = '\0';
    return inet_pton(AF_INET, buf, addr) == 1;
}

// The Host header must name this server: the loopback address or localhost (or the address
// given with --host; any numeric address when that is a wildcard), and the port. A page served
// from another name (DNS rebinding) is refused.
static bool host_ok(const studio_http *h, struct MHD_Connection *c)
{
    const char *host = MHD_lookup_connection_value(c, MHD_HEADER_KIND, MHD_HTTP_HEADER_HOST);
    if (!host) return false;
    const char *colon = strrchr(host, ':');
    if (!colon || (host[0] == '[' && colon < strchr(host, ']'))) return false;
    // The port in decimal digits only, equal to ours ("+PORT", " PORT" or "0x…" name no port).
    long port = 0;
    const char *d = colon + 1;
    if (!*d || strlen(d) > 5) return false;
    for (; *d; ++d) {
        if (*d < '0' || *d > '9') return false;
        port = 10 * port + (*d - '0');
    }
    if (port != h->port) return false;
    size_t n = (size_t)(colon - host);
    static const char *const loopback[] = {"127.0.0.1", "localhost", "[::1]"};
    for (size_t i = 0; i < sizeof loopback / sizeof loopback[0]; ++i)
        if (strlen(loopback[i]) == n && strncmp(host, loopback[i], n) == 0) return true;
    char given[140];
    snprintf(given, sizeof given, h->ipv6 ? "[%s]" : "%s", h->host);
    if (strlen(given) == n && strncmp(host, given, n) == 0) return true;
    return h->wildcard && numeric_host(host, n);
}

static bool token_ok(const studio_http *h, struct MHD_Connection *c)
{
    const char *t = MHD_lookup_connection_value(c, MHD_HEADER_KIND, "X-Orikin-Token");
    if (!t) return false;
    size_t n = strlen(h->token);
    if (strlen(t) != n) return false;
    unsigned char diff = 0;
    for (size_t i = 0; i < n; ++i) diff |= (unsigned char)(t[i] ^ h->token[i]);
    return diff == 0;
}

// A browser's Origin, when sent, must be this server's own.
static bool origin_ok(struct MHD_Connection *c)
{
    const char *origin = MHD_lookup_connection_value(c, MHD_HEADER_KIND, "Origin");
    if (!origin) return true;
    const char *host = MHD_lookup_connection_value(c, MHD_HEADER_KIND, MHD_HTTP_HEADER_HOST);
    if (!host) return false;
    char expect[300];
    snprintf(expect, sizeof expect, "http://%s", host);
    return strcmp(origin, expect) == 0;
}

// Headers that must come once: a request with two Host, Origin or token headers is refused
// (which one a check reads would be a guess, and an attacker's choice).
typedef struct header_count {
    int host, origin, token;
} header_count;

static enum MHD_Result count_header(void *cls, enum MHD_ValueKind kind, const char *key, const char *value)
{
    (void)kind;
    (void)value;
    header_count *n = cls;
    if (strcasecmp(key, MHD_HTTP_HEADER_HOST) == 0) n->host++;
    else if (strcasecmp(key, "Origin") == 0) n->origin++;
    else if (strcasecmp(key, "X-Orikin-Token") == 0) n->token++;
    return MHD_YES;
}

static bool headers_once(struct MHD_Connection *c)
{
    header_count n = {0, 0, 0};
    MHD_get_connection_values(c, MHD_HEADER_KIND, count_header, &n);
    return n.host <= 1 && n.origin <= 1 && n.token <= 1;
}

// Whether the request announces a body (a length above 0, or chunks).
static bool has_body(struct MHD_Connection *c)
{
    const char *len = MHD_lookup_connection_value(c, MHD_HEADER_KIND, MHD_HTTP_HEADER_CONTENT_LENGTH);
    if (len && strcmp(len, "0") != 0) return true;
    return MHD_lookup_connection_value(c, MHD_HEADER_KIND, MHD_HTTP_HEADER_TRANSFER_ENCODING) != NULL;
}

typedef struct arg_list {
    studio_arg args[MAX_ARGS];
    int count;
} arg_list;

static enum MHD_Result collect_arg(void *cls, enum MHD_ValueKind kind, const char *key, const char *value)
{
    (void)kind;
    arg_list *a = cls;
    if (a->count < MAX_ARGS) {
        a->args[a->count].key = key;
        a->args[a->count].value = value ? value : "";
        a->count++;
    }
    return MHD_YES;
}

static enum MHD_Result serve_asset(struct MHD_Connection *c, const char *url, bool head)
{
    const studio_asset *a = studio_asset_find(url);
    if (!a) {
        if (!studio_assets_built() && (strcmp(url, "/") == 0 || strcmp(url, "/index.html") == 0)) {
            static const char msg[] = "The studio's web assets were not built into this orikin (node_modules was missing at "
                                      "build time: run make deps, then rebuild).\n";
            return send_buffer(c, 503, "text/plain; charset=utf-8", (char *)msg, sizeof msg - 1, false, NULL);
        }
        static const char nf[] = "not found\n";
        return send_buffer(c, 404, "text/plain; charset=utf-8", (char *)nf, sizeof nf - 1, false, NULL);
    }
    return send_buffer(c, 200, a->content_type, (char *)a->data, head ? 0 : a->size, false, NULL);
}

static enum MHD_Result on_request(void *cls, struct MHD_Connection *c, const char *url, const char *method,
                                  const char *version, const char *upload_data, size_t *upload_data_size, void **state)
{
    (void)version;
    studio_http *h = cls;
    conn *st = *state;
    bool api = strncmp(url, "/api/", 5) == 0;
    if (!st) {
        // Headers are in: refuse before reading any body.
        st = calloc(1, sizeof *st);
        *state = st;
        if (!headers_once(c)) return send_error(c, 400, "refused: a Host, Origin or X-Orikin-Token header given twice");
        if (!host_ok(h, c)) return send_error(c, 403, "refused: the Host header does not name this server");
        bool get = strcmp(method, "GET") == 0, head = strcmp(method, "HEAD") == 0, post = strcmp(method, "POST") == 0;
        if (!api) {
            if (!get && !head) return send_error(c, 405, "only GET is allowed here");
            // Assets take no body: refused before a byte of it is read (an endless one was read
            // forever, 512 MB and on).
            if (has_body(c)) return send_error(c, 413, "a request for a page takes no body");
            st->limit = 0;
            return MHD_YES;
        }
        if (!token_ok(h, c)) return send_error(c, 401, "refused: missing or wrong session token (X-Orikin-Token)");
        // The token holder's connection may stay open while the page works; every other one is
        // dropped after STUDIO_IDLE_SECONDS of silence, so idle connections cannot hold the
        // server's slots.
        MHD_set_connection_option(c, MHD_CONNECTION_OPTION_TIMEOUT, (unsigned int)STUDIO_SESSION_IDLE_SECONDS);
        if (!origin_ok(c)) return send_error(c, 403, "refused: cross-origin request");
        if (!get && !post) return send_error(c, 405, "only GET and POST are allowed");
        st->limit = studio_body_limit(h->s, url);
        const char *len = MHD_lookup_connection_value(c, MHD_HEADER_KIND, MHD_HTTP_HEADER_CONTENT_LENGTH);
        if (len) {
            char *end;
            unsigned long long n = strtoull(len, &end, 10);
            if (end == len || *end || n > st->limit) {
                char msg[160];
                snprintf(msg, sizeof msg, "request body over the limit of %zu bytes", st->limit);
                return send_error(c, 413, msg);
            }
        }
        return MHD_YES;
    }
    if (*upload_data_size > 0) {
        size_t n = *upload_data_size;
        *upload_data_size = 0;
        if (st->too_large || st->size + n > st->limit) {
            // Dropped, then answered 413 at its end (libmicrohttpd answers only once a body is
            // in); but never more than the limit again: an endless body is cut off there.
            st->too_large = true;
            st->dropped += n;
            return st->dropped > st->limit ? MHD_NO : MHD_YES;
        }
        if (st->size + n > st->cap) {
            size_t cap = st->cap ? st->cap : 4096;
            while (cap < st->size + n) cap *= 2;
            st->body = realloc(st->body, cap);
            st->cap = cap;
        }
        memcpy(st->body + st->size, upload_data, n);
        st->size += n;
        return MHD_YES;
    }
    if (!api) return serve_asset(c, url, strcmp(method, "HEAD") == 0);
    if (st->too_large) {
        char msg[160];
        snprintf(msg, sizeof msg, "request body over the limit of %zu bytes", st->limit);
        return send_error(c, 413, msg);
    }
    arg_list args;
    args.count = 0;
    MHD_get_connection_values(c, MHD_GET_ARGUMENT_KIND, collect_arg, &args);
    studio_request req;
    req.method = method;
    req.path = url;
    req.args = args.args;
    req.arg_count = args.count;
    req.body = st->body;
    req.body_size = st->size;
    studio_response out;
    studio_handle(h->s, &req, &out);
    return send_buffer(c, out.status, out.content_type, out.body, out.size, true, out.filename);
}

static void on_completed(void *cls, struct MHD_Connection *c, void **state, enum MHD_RequestTerminationCode code)
{
    (void)cls;
    (void)c;
    (void)code;
    conn *st = *state;
    if (!st) return;
    free(st->body);
    free(st);
    *state = NULL;
}

studio_http *studio_http_start(studio *s, const char *host, int port, const char *token, char *err, size_t err_size)
{
    if (port < 0 || port > 65535) {
        snprintf(err, err_size, "port %d is outside 0 to 65535", port);
        return NULL;
    }
    studio_http *h = calloc(1, sizeof *h);
    h->s = s;
    snprintf(h->token, sizeof h->token, "%s", token);
    snprintf(h->host, sizeof h->host, "%s", host ? host : "127.0.0.1");
    struct sockaddr_in a4;
    struct sockaddr_in6 a6;
    memset(&a4, 0, sizeof a4);
    memset(&a6, 0, sizeof a6);
    const struct sockaddr *addr;
    if (inet_pton(AF_INET, h->host, &a4.sin_addr) == 1) {
        a4.sin_family = AF_INET;
        a4.sin_port = htons((uint16_t)port);
        addr = (const struct sockaddr *)&a4;
        h->wildcard = a4.sin_addr.s_addr == htonl(INADDR_ANY);
    } else if (inet_pton(AF_INET6, h->host, &a6.sin6_addr) == 1) {
        a6.sin6_family = AF_INET6;
        a6.sin6_port = htons((uint16_t)port);
        addr = (const struct sockaddr *)&a6;
        h->ipv6 = true;
        h->wildcard = memcmp(&a6.sin6_addr, &in6addr_any, sizeof a6.sin6_addr) == 0;
    } else {
        snprintf(err, err_size, "--host %s: give a numeric address (127.0.0.1, 0.0.0.0, ::1)", h->host);
        free(h);
        return NULL;
    }
    // Room for STUDIO_MAX_CONNECTIONS descriptors (a soft limit of 1024 would stop accepting
    // first): raised up to the hard limit.
    struct rlimit nofile;
    if (getrlimit(RLIMIT_NOFILE, &nofile) == 0 && nofile.rlim_cur < (rlim_t)STUDIO_MAX_CONNECTIONS + 64) {
        nofile.rlim_cur = nofile.rlim_max < (rlim_t)STUDIO_MAX_CONNECTIONS + 64 ? nofile.rlim_max : (rlim_t)STUDIO_MAX_CONNECTIONS + 64;
        setrlimit(RLIMIT_NOFILE, &nofile);
    }
    unsigned int flags = MHD_USE_INTERNAL_POLLING_THREAD | MHD_USE_THREAD_PER_CONNECTION | MHD_USE_POLL;
    if (h->ipv6) flags |= MHD_USE_IPv6;
    h->daemon = MHD_start_daemon(flags, (uint16_t)port, NULL, NULL, on_request, h, MHD_OPTION_SOCK_ADDR, addr,
                                 MHD_OPTION_NOTIFY_COMPLETED, on_completed, NULL, MHD_OPTION_CONNECTION_LIMIT,
                                 (unsigned int)STUDIO_MAX_CONNECTIONS, MHD_OPTION_CONNECTION_TIMEOUT,
                                 (unsigned int)STUDIO_IDLE_SECONDS,
                                 MHD_OPTION_EXTERNAL_LOGGER, quiet_log, NULL, MHD_OPTION_UNESCAPE_CALLBACK, unescape, NULL,
                                 MHD_OPTION_END);
    if (!h->daemon) {
        snprintf(err, err_size, "cannot listen on %s port %d (in use, or not an address of this machine)", h->host, port);
        free(h);
        return NULL;
    }
    const union MHD_DaemonInfo *info = MHD_get_daemon_info(h->daemon, MHD_DAEMON_INFO_BIND_PORT);
    h->port = info ? info->port : port;
    return h;
}

int studio_http_port(const studio_http *h)
{
    return h->port;
}

void studio_http_stop(studio_http *h)
{
    if (!h) return;
    MHD_stop_daemon(h->daemon);
    free(h);
}
