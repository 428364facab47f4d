#define _POSIX_C_SOURCE 200809L
#include "support.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

const char *test_shared_path(const char *rel)
{
    static char buf[4096];
    snprintf(buf, sizeof buf, "%s/%s", ORI_SHARED_PATTERNS, rel);
    struct stat st;
    return stat(buf, &st) == 0 ? buf : NULL;
}

const char *test_require_shared(const char *rel)
{
    const char *p = test_shared_path(rel);
    if (!p) cr_skip("../shared/patterns/%s is absent", rel);
    return p;
}

const char *test_repo_path(const char *rel)
{
    static char buf[4096];
    snprintf(buf, sizeof buf, "%s/%s", ORI_SOURCE_DIR, rel);
    return buf;
}

void test_leak_setup(void) { cr_assert_eq(ori_alloc_live_count(), 0); }

void test_leak_check(void)
{
    cr_assert_eq(ori_alloc_live_count(), 0, "%lld library allocations leaked",
                 (long long)ori_alloc_live_count());
}

ori_pattern *test_load_pattern(const char *path, int frame)
{
    ori_fold *doc = NULL;
    ori_error err;
    char msg[512];
    ori_status st = ori_fold_load_file(path, &doc, &err);
    cr_assert_eq(st, ORI_OK, "%s: %s", path, ori_error_format(&err, msg, sizeof msg));
    ori_pattern *p = NULL;
    st = ori_fold_get_pattern(doc, frame, NULL, &p, &err);
    cr_assert_eq(st, ORI_OK, "%s frame %d: %s", path, frame, ori_error_format(&err, msg, sizeof msg));
    ori_fold_destroy(doc);
    return p;
}

// Run `orikin ARGS` from the repository root with stderr redirected as given (a shell
// redirection); its stdout into *out (malloc'd; freed when out is NULL). Returns the exit code.
static int run_cli(const char *args, const char *stderr_to, char **out)
{
    size_t n = strlen(args) + strlen(ORI_CLI_PATH) + strlen(ORI_SOURCE_DIR) + strlen(stderr_to) + 64;
    char *cmd = malloc(n);
    snprintf(cmd, n, "cd '%s' && '%s' %s %s", ORI_SOURCE_DIR, ORI_CLI_PATH, args, stderr_to);
    FILE *f = popen(cmd, "r");
    free(cmd);
    cr_assert_not_null(f);
    size_t cap = 4096, len = 0, got;
    char *buf = malloc(cap);
    while ((got = fread(buf + len, 1, cap - len - 1, f)) > 0) {
        len += got;
        if (cap - len < 2) buf = realloc(buf, cap *= 2);
    }
    buf[len] = '\0';
    int status = pclose(f);
    if (out) *out = buf;
    else free(buf);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int test_run_cli(const char *args, char **output) { return run_cli(args, "2>&1", output); }

int test_run_cli_split(const char *args, char **out, char **err)
{
    char errpath[] = "/tmp/orikin-stderr-XXXXXX", redirect[64];
    int fd = mkstemp(errpath);
    cr_assert_geq(fd, 0);
    close(fd);
    snprintf(redirect, sizeof redirect, "2>'%s'", errpath);
    int rc = run_cli(args, redirect, out);
    char *e = test_read_text(errpath);
    unlink(errpath);
    if (err) *err = e ? e : strdup("");
    else free(e);
    return rc;
}

char *test_tmpdir(void)
{
    char *d = strdup("/tmp/orikin-test-XXXXXX");
    cr_assert_not_null(mkdtemp(d));
    return d;
}

void test_tmpdir_remove(char *dir)
{
    char cmd[4200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) cr_log_warn("could not remove %s", dir);
    free(dir);
}

char *test_read_file(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *buf = malloc((size_t)(n > 0 ? n : 0) + 1);
    size_t got = n > 0 ? fread(buf, 1, (size_t)n, f) : 0;
    buf[got] = '\0';
    fclose(f);
    if (size) *size = got;
    return buf;
}

char *test_read_text(const char *path) { return test_read_file(path, NULL); }

bool test_vertex_flat_foldable(const ori_pattern *p, int v, char *why, size_t why_size)
{
    enum { CAP = 64 };
    int edges[CAP];
    double sec[CAP];
    int n = ori_pattern_vertex_sectors(p, v, edges, sec, CAP);
    if (n > CAP || n < 2) {
        snprintf(why, why_size, "vertex %d: degree %d not checkable", v, n);
        return false;
    }
    double alt = 0.0;
    int m = 0, val = 0;
    for (int i = 0; i < n; ++i) {
        alt += (i % 2 ? -1.0 : 1.0) * sec[i];
        ori_assignment a = ori_pattern_edge(p, edges[i]).assignment;
        if (a == ORI_ASSIGN_MOUNTAIN) m++;
        else if (a == ORI_ASSIGN_VALLEY) val++;
        else {
            snprintf(why, why_size, "vertex %d: edge %d is %s", v, edges[i], ori_assignment_name(a));
            return false;
        }
    }
    if (n % 2 || fabs(alt) > ORI_TOL_KAWASAKI_RAD) {
        snprintf(why, why_size, "vertex %d: Kawasaki fails (degree %d, alternating sum %.3g)", v, n, alt);
        return false;
    }
    if (abs(m - val) != 2) {
        snprintf(why, why_size, "vertex %d: Maekawa fails (%d M, %d V)", v, m, val);
        return false;
    }
    // Runs of equal sectors that are strict local minima.
    for (int i = 0; i < n; ++i) {
        double a = sec[i];
        if (fabs(sec[(i + n - 1) % n] - a) <= ORI_TOL_ANGLE_EQUAL_RAD) continue; // not a run start
        int k = 1;
        while (k < n && fabs(sec[(i + k) % n] - a) <= ORI_TOL_ANGLE_EQUAL_RAD) k++;
        if (k == n) break; // all equal: Maekawa is all there is
        if (!(sec[(i + n - 1) % n] > a && sec[(i + k) % n] > a)) continue;
        int d = 0;
        for (int j = 0; j <= k; ++j) // creases i … i+k bound sectors i … i+k−1
            d += ori_pattern_edge(p, edges[(i + j) % n]).assignment == ORI_ASSIGN_MOUNTAIN ? 1 : -1;
        if (abs(d) != (k + 1) % 2) {
            snprintf(why, why_size, "vertex %d: big-little-big fails on %d equal sector(s) from edge %d", v, k,
                     edges[i]);
            return false;
        }
    }
    return true;
}

int test_edge_at(const ori_pattern *p, double x0, double y0, double x1, double y1)
{
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge E = ori_pattern_edge(p, e);
        ori_v3 a = ori_pattern_vertex(p, E.v[0]), b = ori_pattern_vertex(p, E.v[1]);
        if ((a.x == x0 && a.y == y0 && b.x == x1 && b.y == y1) || (a.x == x1 && a.y == y1 && b.x == x0 && b.y == y0))
            return e;
    }
    cr_assert_fail("no edge (%g,%g)-(%g,%g)", x0, y0, x1, y1);
    return -1;
}

int test_vertex_at(const ori_pattern *p, double x, double y)
{
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v)
        if (ori_pattern_vertex(p, v).x == x && ori_pattern_vertex(p, v).y == y) return v;
    cr_assert_fail("no vertex (%g,%g)", x, y);
    return -1;
}

int test_face_at(const ori_pattern *p, double x, double y)
{
    for (int f = 0; f < ori_pattern_face_count(p); ++f) {
        int v[64];
        int n = ori_pattern_face_vertices(p, f, v, 64);
        bool inside = true;
        for (int k = 0; k < n; ++k) {
            ori_v3 a = ori_pattern_vertex(p, v[k]), b = ori_pattern_vertex(p, v[(k + 1) % n]);
            if (ori_orient2d(ori_v2_make(a.x, a.y), ori_v2_make(b.x, b.y), ori_v2_make(x, y)) <= 0.0) inside = false;
        }
        if (inside) return f;
    }
    cr_assert_fail("no face at (%g,%g)", x, y);
    return -1;
}

ori_mechanism *test_mechanism_of(const ori_pattern *p)
{
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = p;
    ori_mechanism *m = NULL;
    ori_error err;
    cr_assert_eq(ori_mechanism_create(&md, &m, &err), ORI_OK, "%s", err.message);
    return m;
}

ori_pattern *test_pattern_of_text(const char *fold_text)
{
    ori_fold *doc = NULL;
    ori_error err;
    cr_assert_eq(ori_fold_load_string(fold_text, strlen(fold_text), &doc, &err), ORI_OK, "%s", err.message);
    ori_pattern *p = NULL;
    cr_assert_eq(ori_fold_get_pattern(doc, 0, NULL, &p, &err), ORI_OK, "%s", err.message);
    ori_fold_destroy(doc);
    return p;
}

ori_motion *test_solve(const ori_mechanism *m, const ori_motion_def *d)
{
    ori_motion *mo = NULL;
    ori_error err;
    ori_status st = ori_motion_solve(m, d, &mo, &err);
    cr_assert_eq(st, ORI_OK, "%s", err.message);
    return mo;
}

int test_miura_drive(const ori_pattern *p, int n, double *sign)
{
    int e = ori_pattern_find_edge(p, (n / 2) * (n + 1) + n / 2, (n / 2 + 1) * (n + 1) + n / 2);
    *sign = ori_pattern_edge(p, e).assignment == ORI_ASSIGN_VALLEY ? 1.0 : -1.0;
    return e;
}

ori_pattern *test_miura(int rows, int cols, double a, double b, double gamma_rad, ori_edge_class **classes)
{
    ori_generate_def g = ori_default_generate_def(ORI_TESS_MIURA);
    g.rows = rows;
    g.cols = cols;
    g.width = a;
    g.height = b;
    g.angle_rad = gamma_rad;
    ori_pattern *p = NULL;
    ori_error err;
    cr_assert_eq(ori_generate(&g, &p, classes, &err), ORI_OK, "%s", err.message);
    return p;
}

ori_pattern *test_generated(ori_tessellation kind, int rows, int cols)
{
    ori_generate_def g = ori_default_generate_def(kind);
    g.rows = rows;
    if (ori_tessellation_params(kind) & ORI_GEN_SIDES) g.sides = cols;
    else g.cols = cols;
    ori_pattern *p = NULL;
    ori_error err;
    cr_assert_eq(ori_generate(&g, &p, NULL, &err), ORI_OK, "%s", err.message);
    return p;
}

test_open_corner test_open_corner_load(void)
{
    test_open_corner c;
    c.p = test_load_pattern(test_repo_path("examples/patterns/open-corner.fold"), 0);
    c.m = test_mechanism_of(c.p);
    c.diag = test_edge_at(c.p, 1, 1, 0, 0);
    c.down = test_edge_at(c.p, 1, 1, 1, 0);
    c.right = test_edge_at(c.p, 1, 1, 2, 1);
    c.up = test_edge_at(c.p, 1, 1, 1, 2);
    c.left = test_edge_at(c.p, 1, 1, 0, 1);
    c.t1 = test_face_at(c.p, 0.3, 0.7);
    c.t2 = test_face_at(c.p, 0.7, 0.3);
    c.lr = test_face_at(c.p, 1.5, 0.5);
    c.ur = test_face_at(c.p, 1.5, 1.5);
    c.ul = test_face_at(c.p, 0.5, 1.5);
    return c;
}

ori_motion_def test_open_corner_first_fold(const test_open_corner *c, ori_solver solver, double to_deg)
{
    static int lock;
    lock = c->down;
    ori_motion_def d = ori_default_motion_def();
    d.fixed_face = c->t2;
    d.driven_edge = c->diag;
    d.to_rad = to_deg * (ORI_PI / 180.0);
    d.step_rad = 10 * (ORI_PI / 180.0);
    d.locked_edges = &lock;
    d.locked_count = 1;
    d.solver = solver;
    return d;
}

void test_open_corner_free(test_open_corner *c)
{
    ori_mechanism_destroy(c->m);
    ori_pattern_destroy(c->p);
}

ori_fold *test_compliant_open_corner(const char *dir) { return test_compliant_open_corner_with(dir, "", "o.fold"); }

json_t *test_run_cli_json(const char *args)
{
    char *out = NULL;
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    json_t *o = json_loads(out, 0, NULL);
    cr_assert_not_null(o, "%s", out);
    free(out);
    return o;
}

ori_fold *test_compliant_open_corner_with(const char *dir, const char *extra, const char *name)
{
    char args[2048], path[1024], *out = NULL;
    snprintf(args, sizeof args, "fold examples/patterns/open-corner.fold --compliant --percent 40 %s -o '%s/%s'", extra, dir, name);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    free(out);
    snprintf(path, sizeof path, "%s/%s", dir, name);
    ori_fold *doc = NULL;
    ori_error err;
    cr_assert_eq(ori_fold_load_file(path, &doc, &err), ORI_OK, "%s", err.message);
    return doc;
}
