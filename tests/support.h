// Helpers for the Criterion tests: shared reference patterns (skipped when ../shared is
// absent), leak checks on the counted allocator, running the CLI, temp files.
#ifndef ORI_TEST_SUPPORT_H
#define ORI_TEST_SUPPORT_H

#include <jansson.h>
#include <criterion/criterion.h>
#include <orikin/orikin.h>

// Path of ../shared/patterns/<rel> when it exists, else NULL.
const char *test_shared_path(const char *rel);
// Same, but skips the current test (cr_skip) when the file is absent (a user's clone).
const char *test_require_shared(const char *rel);
// Path of <repo>/<rel> (examples/, tests/data/ ...). Static buffer, valid until the next call.
const char *test_repo_path(const char *rel);

// Per-test leak check: use as .init = test_leak_setup, .fini = test_leak_check.
void test_leak_setup(void);
void test_leak_check(void);

// Load a frame of a FOLD file (default build def); fails the test on error.
ori_pattern *test_load_pattern(const char *path, int frame);

// Run `orikin ARGS` (a shell-quoted argument string, run from the repository root); stdout and
// stderr go to *output (malloc'd, may be NULL). Returns the exit code.
int test_run_cli(const char *args, char **output);

// Same, with stdout and stderr captured separately into *out and *err (malloc'd, may be NULL).
int test_run_cli_split(const char *args, char **out, char **err);

// A fresh temporary directory (malloc'd path); removed by test_tmpdir_remove.
char *test_tmpdir(void);
void test_tmpdir_remove(char *dir);
// orikin fold examples/patterns/open-corner.fold --compliant --percent 40 -o DIR/o.fold, loaded:
// the document (frame 1: the bent state, with its strain fields). Destroy with ori_fold_destroy.
ori_fold *test_compliant_open_corner(const char *dir);
// The same with extra options (e.g. "--all-frames") written to DIR/NAME, loaded.
ori_fold *test_compliant_open_corner_with(const char *dir, const char *extra, const char *name);
// Run the CLI (as test_run_cli), assert exit 0 and that stdout+stderr is one JSON object: the
// parsed object (json_decref it).
json_t *test_run_cli_json(const char *args);

// Read a whole file (malloc'd, NUL-terminated) or NULL.
char *test_read_text(const char *path);
// The file's bytes (malloc'd, NUL-terminated after them), their count in *size (may be NULL);
// NULL when it cannot be read.
char *test_read_file(const char *path, size_t *size);

// Locate elements of a flat pattern by exact coordinates (fails the test when absent): the
// edge joining (x0,y0)-(x1,y1), the vertex at (x,y), the face containing (x,y) strictly.
int test_edge_at(const ori_pattern *p, double x0, double y0, double x1, double y1);
int test_vertex_at(const ori_pattern *p, double x, double y);
int test_face_at(const ori_pattern *p, double x, double y);
// The mechanism of a built flat pattern (fails the test on error).
ori_mechanism *test_mechanism_of(const ori_pattern *p);
// The crease pattern of frame 0 of FOLD text (asserts it loads); the caller destroys it.
ori_pattern *test_pattern_of_text(const char *fold_text);
// ori_motion_solve, asserting ORI_OK; the caller destroys the motion.
ori_motion *test_solve(const ori_mechanism *m, const ori_motion_def *d);

// The thesis' open corner (examples/patterns/open-corner.fold, 2 × 2 with the centre (1, 1)) with
// its mechanism; creases and faces found by coordinates, as the file's order may change: the
// diagonal (1,1)–(0,0) and the creases from the centre down, right, up and left; the triangles
// t1 (above the diagonal) and t2 (below), and the squares lr, ur, ul (lower right, upper right,
// upper left). The one set-up for the tests that fold it (test_kinematics.c, test_sequence.c). Free with test_open_corner_free.
typedef struct test_open_corner {
    ori_pattern *p;
    ori_mechanism *m;
    int diag, down, right, up, left;
    int t1, t2, lr, ur, ul;
} test_open_corner;
test_open_corner test_open_corner_load(void);
void test_open_corner_free(test_open_corner *c);
// The corner's first fold: t2 fixed, the diagonal driven to to_deg (degrees) in 10° steps, the crease
// down locked, with the given solver. The lock lives in static storage: one such definition at a time.
ori_motion_def test_open_corner_first_fold(const test_open_corner *c, ori_solver solver, double to_deg);


// Local flat-foldability of an interior vertex of a built flat pattern, checked independently
// of src/flat: Kawasaki (|alternating sector sum| ≤ ORI_TOL_KAWASAKI_RAD), Maekawa over the M/V
// creases (|M − V| = 2, every crease M or V) and the generalised big-little-big rule (a run of
// k equal sectors smaller than both neighbours has |M − V| = (k + 1) mod 2 over its k + 1
// creases). Returns true when all hold; otherwise writes the first failure into why.
bool test_vertex_flat_foldable(const ori_pattern *p, int vertex, char *why, size_t why_size);

// R × C Miura-ori from the library's generator (ori_generate, ORI_TESS_MIURA; docs/generators.md):
// straight edge a (along x), zig-zag edge b, acute cell angle gamma_rad between them. Vertex (i, j)
// has index j(C+1) + i at (i·a + [j odd]·b cos γ, j·b sin γ); zig-zag column i is M for odd i.
// classes (may be NULL) receives one ori_edge_class per edge (free with ori_buffer_free).
// Fails the test on error.
ori_pattern *test_miura(int rows, int cols, double a, double b, double gamma_rad, ori_edge_class **classes);
// A generated tessellation of rows × cols (cols: sides for the Kresling), its other parameters
// the defaults (ori_default_generate_def). Fails the test on error.
ori_pattern *test_generated(ori_tessellation kind, int rows, int cols);
// The zig-zag crease of the middle cell of test_miura(n, n, …) and the sign of its assignment.
int test_miura_drive(const ori_pattern *p, int n, double *sign);

#endif
