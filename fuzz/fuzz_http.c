// libFuzzer target for the studio's HTTP front (orikin view's libmicrohttpd layer: request line
// and header parsing, the Host, Origin and token checks, body limits, routing to the API and the
// embedded assets): an input is the raw bytes a client sends on one loopback connection to a
// studio on a blank sheet (started once, token "fuzztoken0123456789abcdef0123456"; every "@P" of
// the input is replaced by the server's port, so that a Host header can name it). The answer
// must be empty (connection closed) or start with an HTTP status line; an /api/ request answered
// 2xx must have carried the token. Any crash, sanitizer report or abort is a bug.
#define _GNU_SOURCE
#include <arpa/inet.h>
#include <netinet/in.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdbool.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include "studio.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define TOKEN "fuzztoken0123456789abcdef0123456"

static int port = -1;

static void start(void)
{
    studio_def def = studio_default_def();
    def.work_limit = 2e5; // refusals and parsing are what is fuzzed: keep each input fast
    def.cache_bytes = (size_t)1 << 20;
    def.max_open_bytes = 1 << 20;
    def.render_pixels = 1 << 16;
    def.animation_pixels = 1 << 18;
    studio *s = NULL;
    char err[256];
    if (studio_create(&def, &s, err, sizeof err) != 0) abort();
    studio_http *h = studio_http_start(s, "127.0.0.1", 0, TOKEN, err, sizeof err);
    if (!h) abort();
    port = studio_http_port(h); // kept for the process's life (libFuzzer never returns)
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (port < 0) start();
    if (size > 1 << 16) return 0;
    char digits[8];
    int nd = snprintf(digits, sizeof digits, "%d", port);
    uint8_t *req = malloc(size * 3 + 1), *w = req; // "@P" (2 bytes) becomes at most 5 digits
    for (size_t i = 0; i < size; ++i) {
        if (i + 1 < size && data[i] == '@' && data[i + 1] == 'P') {
            memcpy(w, digits, (size_t)nd);
            w += nd;
            ++i;
        } else {
            *w++ = data[i];
        }
    }
    size_t req_size = (size_t)(w - req);
    int fd = socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) abort();
    struct sockaddr_in a;
    memset(&a, 0, sizeof a);
    a.sin_family = AF_INET;
    a.sin_port = htons((uint16_t)port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    // The server refuses connections beyond its per-client limit while earlier ones close:
    // wait for a slot (a connection never accepted is the limit working, not a finding).
    int tries = 0;
    while (connect(fd, (struct sockaddr *)&a, sizeof a) != 0) {
        close(fd);
        if (++tries > 200) {
            free(req);
            return 0;
        }
        usleep(10000);
        fd = socket(AF_INET, SOCK_STREAM, 0);
        if (fd < 0) abort();
    }
    struct timeval tv = {3, 0};
    setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
    setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &tv, sizeof tv);
    size_t sent = 0;
    while (sent < req_size) {
        ssize_t n = send(fd, req + sent, req_size - sent, MSG_NOSIGNAL);
        if (n <= 0) break; // the server may close early (a refused request): fine
        sent += (size_t)n;
    }
    shutdown(fd, SHUT_WR);
    char head[16] = "";
    size_t got = 0;
    char buf[4096];
    for (;;) {
        ssize_t n = recv(fd, buf, sizeof buf, 0);
        if (n <= 0) break;
        if (got < sizeof head - 1) {
            size_t k = (size_t)n < sizeof head - 1 - got ? (size_t)n : sizeof head - 1 - got;
            memcpy(head + got, buf, k);
            head[got + k] = '\0';
        }
        got += (size_t)n;
    }
    close(fd);
    free(req);
    if (got > 0 && got < 12) abort(); // a truncated status line
    if (got >= 12) {
        if (strncmp(head, "HTTP/1.", 7) != 0 || head[8] != ' ' || head[9] < '1' || head[9] > '5') abort();
        bool api = (size >= 9 && memcmp(data, "GET /api/", 9) == 0) || (size >= 10 && memcmp(data, "POST /api/", 10) == 0);
        if (api && head[9] == '2' && !memmem(data, size, TOKEN, strlen(TOKEN))) abort(); // answered without the token
    }
    return 0;
}
