// The API's JSON: field for field what the CLI prints with --json (tests/test_server.c runs
// both and compares them), so that a script and the page read the same answers. The answers of
// fold, sequence, collide and check are built by the CLI's own builders (cli/report/).
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "studio_internal.h"

// A growing text buffer for the state answers, written directly: a 100 × 100 Miura-ori state
// has 50,000 numbers, which a JSON tree and its normalisation take ten times longer to write.
typedef struct text_buf {
    char *p;
    size_t n, cap;
} text_buf;

static void tb_reserve(text_buf *b, size_t more)
{
    if (b->n + more + 1 <= b->cap) return;
    size_t cap = b->cap ? b->cap : 4096;
    while (cap < b->n + more + 1) cap *= 2;
    b->p = realloc(b->p, cap);
    b->cap = cap;
}

static void tb_str(text_buf *b, const char *s)
{
    size_t k = strlen(s);
    tb_reserve(b, k);
    memcpy(b->p + b->n, s, k + 1);
    b->n += k;
}

// A number that reads back exactly: integers as integers (0, 90, 180 are common), anything
// else with 17 significant digits (always enough for a double; the CLI prints the shortest
// such form, which parses to the same double).
static void tb_num(text_buf *b, double x)
{
    tb_reserve(b, 32);
    int k;
    if (x == floor(x) && fabs(x) < 1e15) k = snprintf(b->p + b->n, 32, "%.0f", x == 0.0 ? 0.0 : x);
    else k = snprintf(b->p + b->n, 32, "%.17g", x);
    b->n += (size_t)k;
}

static void tb_degrees(text_buf *b, const double *a, int n)
{
    tb_str(b, "[");
    for (int e = 0; e < n; ++e) {
        if (e) tb_str(b, ",");
        tb_num(b, ori_rad_to_deg_output(a[e]));
    }
    tb_str(b, "]");
}

static void tb_coords(text_buf *b, const ori_v3 *pos, int V)
{
    tb_str(b, "[");
    for (int v = 0; v < V; ++v) {
        tb_str(b, v ? ",[" : "[");
        tb_num(b, pos[v].x);
        tb_str(b, ",");
        tb_num(b, pos[v].y);
        tb_str(b, ",");
        tb_num(b, pos[v].z);
        tb_str(b, "]");
    }
    tb_str(b, "]");
}

char *studio_json_at_text(double t, int fold, double drive_rad, const double *angles_rad, int E, double residual,
                          const ori_v3 *pos, int V, size_t *size)
{
    text_buf b = {NULL, 0, 0};
    tb_reserve(&b, (size_t)(E + 3 * V) * 20 + 256);
    tb_str(&b, "{\"t\":");
    tb_num(&b, t);
    tb_str(&b, ",\"fold\":");
    tb_num(&b, fold + 1);
    tb_str(&b, ",\"drive_deg\":");
    if (isnan(drive_rad)) tb_str(&b, "null"); // a fold toward the targets has no drive angle
    else tb_num(&b, ori_rad_to_deg_output(drive_rad));
    tb_str(&b, ",\"fold_angles_deg\":");
    tb_degrees(&b, angles_rad, E);
    tb_str(&b, ",\"residual\":");
    tb_num(&b, residual);
    tb_str(&b, ",\"vertices_coords\":");
    tb_coords(&b, pos, V);
    tb_str(&b, "}");
    *size = b.n;
    return b.p;
}

char *studio_json_frame_text(int frame, double drive_rad, const double *angles_rad, int E, double residual,
                             const ori_v3 *pos, int V, size_t *size)
{
    text_buf b = {NULL, 0, 0};
    tb_reserve(&b, (size_t)(E + 3 * V) * 20 + 256);
    tb_str(&b, "{\"frame\":");
    tb_num(&b, frame);
    tb_str(&b, ",\"drive_deg\":");
    if (isnan(drive_rad)) tb_str(&b, "null"); // a fold mode: no drive angle
    else tb_num(&b, ori_rad_to_deg_output(drive_rad));
    tb_str(&b, ",\"fold_angles_deg\":");
    tb_degrees(&b, angles_rad, E);
    tb_str(&b, ",\"residual\":");
    tb_num(&b, residual);
    tb_str(&b, ",\"vertices_coords\":");
    tb_coords(&b, pos, V);
    tb_str(&b, "}");
    *size = b.n;
    return b.p;
}

// Little-endian float64 whatever the host.
static void put_f64(unsigned char *p, double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    for (int i = 0; i < 8; ++i) p[i] = (unsigned char)(u >> (8 * i));
}

char *studio_state_binary(double t, int fold, double drive_rad, double residual, const ori_v3 *pos, int V,
                          const double *angles_rad, int E, size_t *size)
{
    size_t n = 8 + 3 * (size_t)V + (size_t)E;
    unsigned char *b = malloc(8 * n);
    double head[8] = {t, (double)(fold + 1), ori_rad_to_deg_output(drive_rad), residual, (double)V, (double)E, 0.0, 0.0};
    size_t k = 0;
    for (int i = 0; i < 8; ++i) put_f64(b + 8 * k++, head[i]);
    for (int v = 0; v < V; ++v) {
        put_f64(b + 8 * k++, pos[v].x);
        put_f64(b + 8 * k++, pos[v].y);
        put_f64(b + 8 * k++, pos[v].z);
    }
    for (int e = 0; e < E; ++e) put_f64(b + 8 * k++, ori_rad_to_deg_output(angles_rad[e]));
    *size = 8 * n;
    return (char *)b;
}
