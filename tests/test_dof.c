// Degrees of freedom (src/kinematics/dof.c, rank.c, probe.c): rank and nullity values on
// reference patterns (flat states counted exactly, generic states from the probe), the sparse
// full-rank certificate against the dense SVD, the probe's budget, progress and cancelling, and
// the CLI's output independent of OpenBLAS' thread count.
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "kinematics/kinematics_internal.h"
#include "support.h"
#include <orikin/generate.h>


static int interior_vertices(const ori_mechanism *m)
{
    int n = 0;
    for (int l = 0; l < ori_mechanism_loop_count(m); ++l) n += ori_mechanism_loop(m, l).vertex != ORI_NULL_INDEX;
    return n;
}

static ori_dof_result dof_of(const ori_mechanism *m, const ori_dof_def *d)
{
    ori_dof_result r;
    ori_error err;
    cr_assert_eq(ori_mechanism_dof(m, d, &r, &err), ORI_OK, "%s", err.message);
    return r;
}

// Flat Miura-ori R × R: at the flat state only the in-plane rows of each vertex loop count
// (the normal rows vanish identically), 2 per interior vertex, all independent: dof = creases
// − 2·(R−1)². Nearby, the Miura-ori has one degree of freedom. 4 × 4 and 10 × 10 by the dense
// SVD; 40 × 40 (3 120 creases, 1.4e7 entries) by the sparse method.
Test(dof, miura_flat_and_nearby_dense_and_sparse, .timeout = 120)
{
    int sizes[3] = {4, 10, 40};
    for (int k = 0; k < 3; ++k) {
        int n = sizes[k];
        ori_pattern *p = test_generated(ORI_TESS_MIURA, n, n);
        ori_mechanism *m = test_mechanism_of(p);
        ori_dof_def d = ori_default_dof_def();
        ori_dof_result r = dof_of(m, &d);
        int creases = ori_mechanism_joint_count(m);
        cr_assert_eq(interior_vertices(m), (n - 1) * (n - 1));
        cr_assert_eq(r.unknowns, creases);
        cr_assert_eq(r.equations, 3 * (n - 1) * (n - 1));
        cr_assert_eq(r.rank, 2 * (n - 1) * (n - 1), "%dx%d: rank %d", n, n, r.rank);
        cr_assert_eq(r.dof, creases - 2 * (n - 1) * (n - 1));
        cr_assert_eq(r.generic_dof, 1, "%dx%d: generic %d", n, n, r.generic_dof);
        cr_assert(r.singular);
        cr_assert_not(r.rigid);
        cr_assert_not(r.undetermined);
        cr_assert_eq(r.dense, n < 40);
        cr_assert_gt(r.sigma_cut, ORI_TOL_RANK_REL_SPARSE * r.sigma_max);
        ori_mechanism_destroy(m);
        ori_pattern_destroy(p);
    }
}

// The sparse full-rank certificate at the flat state against the dense SVD: the same nullity,
// and σ_min of the in-plane rows (the smallest singular value counted in the rank) to 1 %.
// With creases locked, some vertices keep a single free crease: their rows are dependent,
// the certificate does not apply and the subspace iteration must agree with the SVD too.
Test(dof, sparse_certificate_agrees_with_svd)
{
    ori_pattern *p = test_generated(ORI_TESS_MIURA, 6, 6);
    ori_mechanism *m = test_mechanism_of(p);
    int J = ori_mechanism_joint_count(m);
    int *col = malloc(sizeof(int) * (size_t)J);
    double *flat = calloc((size_t)J, sizeof(double));
    int n = 0;
    for (int j = 0; j < J; ++j) col[j] = n++;
    ori_dof_result dense, sparse;
    ori_error err;
    cr_assert_eq(ori__kin_nullity(m, flat, col, n, &dense, &err), ORI_OK);
    cr_assert_eq(ori__kin_nullity_sparse(m, flat, col, n, &sparse, &err), ORI_OK);
    cr_assert(dense.dense);
    cr_assert_not(sparse.dense);
    cr_assert_eq(sparse.dof, dense.dof);
    cr_assert_eq(dense.dof, n - 2 * 25);
    cr_assert_float_eq(sparse.sigma_cut, dense.sigma_cut, 0.01 * dense.sigma_cut, "%.17g vs %.17g", sparse.sigma_cut,
                       dense.sigma_cut);
    // Lock every other crease (joint order): rank-deficient rows.
    n = 0;
    for (int j = 0; j < J; ++j) col[j] = j % 2 ? KIN_FIXED : n++;
    cr_assert_eq(ori__kin_nullity(m, flat, col, n, &dense, &err), ORI_OK);
    cr_assert_eq(ori__kin_nullity_sparse(m, flat, col, n, &sparse, &err), ORI_OK);
    cr_assert_eq(sparse.dof, dense.dof, "sparse %d, dense %d", sparse.dof, dense.dof);
    cr_assert_eq(sparse.rank, dense.rank);
    free(col);
    free(flat);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

// Triangulated patterns with degree-6 vertices: at a regular state every loop's 3 equations are
// independent, so the nearby DOF is creases − 3 × interior vertices (Yoshimura 4 × 4: 46 − 33).
Test(dof, yoshimura_nearby_dof_is_creases_minus_equations)
{
    ori_pattern *p = test_generated(ORI_TESS_YOSHIMURA, 4, 4);
    ori_mechanism *m = test_mechanism_of(p);
    ori_dof_def d = ori_default_dof_def();
    ori_dof_result r = dof_of(m, &d);
    cr_assert_eq(r.unknowns, 46);
    cr_assert_eq(r.equations, 33);
    cr_assert_eq(r.rank, 22); // flat: 2 in-plane rows per vertex
    cr_assert_eq(r.generic_dof, r.unknowns - r.equations);
    cr_assert(r.singular);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

// The 2 × 2 square-twist tessellation: the probe's branch enumeration is exponential (it used to
// run 125 s); it stops at the budget and says "undetermined", never "rigid".
Test(dof, square_twist_probe_stops_at_its_budget)
{
    ori_pattern *p = test_load_pattern(test_repo_path("tests/data/square-twist-2x2.fold"), 0);
    ori_mechanism *m = test_mechanism_of(p);
    ori_dof_def d = ori_default_dof_def();
    ori_dof_result r = dof_of(m, &d);
    cr_assert_eq(r.unknowns, 40);
    cr_assert_eq(r.equations, 48);
    cr_assert_eq(r.rank, 32);
    cr_assert_eq(r.dof, 8);
    cr_assert(r.undetermined);
    cr_assert_eq(r.generic_dof, -1);
    cr_assert_not(r.rigid);
    cr_assert_not(r.singular);
    cr_assert_eq(r.probe_solves, ORI_KIN_PROBE_BUDGET);
    d.probe_budget = 8;
    r = dof_of(m, &d);
    cr_assert(r.undetermined);
    cr_assert_eq(r.probe_solves, 8);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

// A probe that finds a motion reports how many combinations it tried (the open corner: the
// first one), and the budget does not change the answer there.
Test(dof, open_corner_probe_within_budget)
{
    test_open_corner c = test_open_corner_load();
    ori_dof_def d = ori_default_dof_def();
    d.probe_budget = 1;
    ori_dof_result r = dof_of(c.m, &d);
    cr_assert_eq(r.dof, 3);
    cr_assert_eq(r.generic_dof, 2);
    cr_assert_eq(r.probe_solves, 1);
    cr_assert_not(r.undetermined);
    test_open_corner_free(&c);
}

typedef struct seen_progress {
    int calls;
    double last;
    bool monotone;
    int cancel_after; // return false at this call (0: never)
} seen_progress;

static bool record_progress(double f, void *user)
{
    seen_progress *s = user;
    s->calls++;
    if (f < s->last) s->monotone = false;
    s->last = f;
    return s->cancel_after == 0 || s->calls < s->cancel_after;
}

Test(dof, progress_reaches_one_and_cancels)
{
    ori_pattern *p = test_generated(ORI_TESS_MIURA, 6, 6);
    ori_mechanism *m = test_mechanism_of(p);
    ori_dof_def d = ori_default_dof_def();
    seen_progress s = {0, 0.0, true, 0};
    d.progress = record_progress;
    d.progress_user = &s;
    ori_dof_result r = dof_of(m, &d);
    cr_assert_eq(r.generic_dof, 1);
    cr_assert_geq(s.calls, 3);
    cr_assert(s.monotone);
    cr_assert_float_eq(s.last, 1.0, 0.0);
    s = (seen_progress){0, 0.0, true, 2};
    ori_error err;
    cr_assert_eq(ori_mechanism_dof(m, &d, &r, &err), ORI_ERR_LIMIT);
    cr_assert(strstr(err.message, "cancelled"));
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

// A drawing is read through the common input layer: Origami Simulator's hypar is rigid.
Test(dof, cli_reads_a_drawing)
{
    const char *svg = test_require_shared("origamisimulator/Origami_hypar.svg");
    char args[4200], *out = NULL;
    snprintf(args, sizeof args, "dof '%s' --json", svg);
    cr_assert_eq(test_run_cli_split(args, &out, NULL), 0);
    cr_assert(strstr(out, "\"generic_dof\":0"), "%s", out);
    cr_assert(strstr(out, "\"rigid\":true"), "%s", out);
    free(out);
}

// Output independent of the machine's thread count (issue 14 item 11): the CLI runs OpenBLAS
// on one thread, so dof (dense SVD) and fold (dense corrector) write the same bytes with
// OPENBLAS_NUM_THREADS=1 and 2.
static char *run_with_threads(const char *threads, const char *args)
{
    setenv("OPENBLAS_NUM_THREADS", threads, 1);
    char *out = NULL;
    cr_assert_eq(test_run_cli_split(args, &out, NULL), 0, "%s", args);
    unsetenv("OPENBLAS_NUM_THREADS");
    return out;
}

Test(dof, cli_output_independent_of_blas_threads, .timeout = 120)
{
    char *dir = test_tmpdir();
    char args[4300];
    snprintf(args, sizeof args, "generate miura --rows 12 --cols 12 -o '%s/m.fold'", dir);
    cr_assert_eq(test_run_cli(args, NULL), 0);
    snprintf(args, sizeof args, "dof '%s/m.fold' --json", dir);
    char *a = run_with_threads("1", args), *b = run_with_threads("2", args);
    cr_assert_str_eq(a, b);
    free(a);
    free(b);
    const char *threads[2] = {"1", "2"};
    char *files[2];
    for (int k = 0; k < 2; ++k) {
        snprintf(args, sizeof args, "fold '%s/m.fold' --fix 0 --drive 12 --to 60 --step 5 --linear dense -o '%s/t%s.fold'",
                 dir, dir, threads[k]);
        free(run_with_threads(threads[k], args));
        snprintf(args, sizeof args, "%s/t%s.fold", dir, threads[k]);
        files[k] = test_read_text(args);
        cr_assert_not_null(files[k]);
    }
    cr_assert(strcmp(files[0], files[1]) == 0, "fold -o differs between 1 and 2 OpenBLAS threads");
    free(files[0]);
    free(files[1]);
    test_tmpdir_remove(dir);
}

// --frame chooses the state: a folded frame of the open corner (written by fold -o) is
// regular, DOF 2 (1 with crease 11 locked), where the flat frame 0 has 3.
Test(dof, cli_frame_is_the_state, .timeout = 60)
{
    char *dir = test_tmpdir();
    char args[4300], *out = NULL;
    snprintf(args, sizeof args,
             "fold examples/patterns/open-corner.fold --fix 4 --drive 12 --lock 11 --to 90 -o '%s/oc.fold'", dir);
    cr_assert_eq(test_run_cli(args, NULL), 0);
    snprintf(args, sizeof args, "dof '%s/oc.fold' --frame 5 --json", dir);
    cr_assert_eq(test_run_cli_split(args, &out, NULL), 0);
    cr_assert(strstr(out, "\"frame\":5,"), "%s", out);
    cr_assert(strstr(out, "\"rank\":3,\"dof\":2,\"generic_dof\":2,\"singular\":false"), "%s", out);
    free(out);
    snprintf(args, sizeof args, "dof '%s/oc.fold' --frame 5 --lock 11 --json", dir);
    cr_assert_eq(test_run_cli_split(args, &out, NULL), 0);
    cr_assert(strstr(out, "\"dof\":1,\"generic_dof\":1"), "%s", out);
    free(out);
    snprintf(args, sizeof args, "dof '%s/oc.fold' --json", dir);
    cr_assert_eq(test_run_cli_split(args, &out, NULL), 0);
    cr_assert(strstr(out, "\"dof\":3,\"generic_dof\":2,\"singular\":true"), "%s", out);
    free(out);
    test_tmpdir_remove(dir);
}
