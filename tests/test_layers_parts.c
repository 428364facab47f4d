// A layer count in parts (src/layers/layers_parts.c, the library side of orikin-layers-mpi):
// every component counted alone and installed on a fresh solver gives the serial counts, total,
// verdict and state selection; a component with no state gives the EXHAUSTED conflict; bad
// counts are refused and leave the solver as it was; the limit and threads agree.
#define _POSIX_C_SOURCE 200809L
#include <orikin/layers.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "support.h"

TestSuite(layers_parts, .init = test_leak_setup, .fini = test_leak_check);

static ori_layers *create(const ori_pattern *p, uint64_t limit)
{
    ori_layers_def def = ori_default_layers_def();
    def.limit = limit;
    ori_layers *L = NULL;
    ori_error err;
    ori_error_clear(&err);
    cr_assert_eq(ori_layers_create(p, &def, &L, &err), ORI_OK, "%s", err.message);
    return L;
}

// Count every component of B alone, install them on B, compare with A counted serially.
static void parts_equal_serial(const char *path, uint64_t limit, int min_components)
{
    ori_pattern *p = test_load_pattern(path, 0);
    ori_layers *A = create(p, limit), *B = create(p, limit);
    ori_error err;
    ori_error_clear(&err);
    cr_assert_eq(ori_layers_count(A, &err), ORI_OK);
    int n = ori_layers_component_count(B);
    cr_assert_eq(n, ori_layers_component_count(A));
    cr_assert_geq(n, min_components, "%s", path);
    char **s = calloc((size_t)n, sizeof *s);
    bool limited = false;
    for (int c = n - 1; c >= 0; --c) { // any order: the largest first, as the MPI driver
        bool lim = false;
        cr_assert_eq(ori_layers_count_component(B, c, &s[c], &lim, &err), ORI_OK);
        char *want = ori_layers_component_states(A, c);
        cr_assert_str_eq(s[c], want, "%s component %d", path, c);
        ori_buffer_free(want);
        limited |= lim;
    }
    cr_assert(!ori_layers_get_info(B).counted, "counting a component alone records nothing");
    cr_assert_eq(ori_layers_set_counts(B, (const char *const *)s, limited, &err), ORI_OK, "%s", err.message);
    ori_layers_info ia = ori_layers_get_info(A), ib = ori_layers_get_info(B);
    cr_assert(ib.counted);
    cr_assert_eq(ib.limited, ia.limited);
    cr_assert_eq(ib.satisfiable, ia.satisfiable);
    char *ta = ori_layers_state_count(A), *tb = ori_layers_state_count(B);
    cr_assert_str_eq(tb, ta, "%s", path);
    if (!ia.limited) { // the same numbering of the states: the last state's face orders agree
        cr_assert_eq(ori_layers_select_state(A, "0", &err), ORI_OK);
        cr_assert_eq(ori_layers_select_state(B, "0", &err), ORI_OK);
        int nv = ori_layers_face_orders(A, NULL, 0);
        int *fa = malloc(sizeof(int) * 3 * (size_t)(nv ? nv : 1)), *fb = malloc(sizeof(int) * 3 * (size_t)(nv ? nv : 1));
        ori_layers_face_orders(A, fa, nv);
        cr_assert_eq(ori_layers_face_orders(B, fb, nv), nv);
        cr_assert_arr_eq(fa, fb, sizeof(int) * 3 * (size_t)nv);
        free(fa);
        free(fb);
    }
    ori_buffer_free(ta);
    ori_buffer_free(tb);
    for (int c = 0; c < n; ++c) ori_buffer_free(s[c]);
    free(s);
    ori_layers_destroy(A);
    ori_layers_destroy(B);
    ori_pattern_destroy(p);
}

Test(layers_parts, components_counted_alone_give_the_serial_count)
{
    parts_equal_serial(test_repo_path("tests/data/layers/corner-flaps.fold"), ORI_LAYERS_NO_LIMIT, 6);
    parts_equal_serial(test_repo_path("examples/patterns/degree6-vertex.fold"), ORI_LAYERS_NO_LIMIT, 2);
}

Test(layers_parts, corpus_patterns_and_limits_give_the_serial_count)
{
    const char *bird = test_require_shared("flat-folder-corpus/instagram/003_ku_Triangle_Bird.fold");
    parts_equal_serial(bird, ORI_LAYERS_NO_LIMIT, 4);
    parts_equal_serial(bird, 100, 4);
}

typedef struct job {
    const ori_layers *L;
    int c;
    char *states;
} job;

static void *count_job(void *arg)
{
    job *j = arg;
    ori_layers_count_component(j->L, j->c, &j->states, NULL, NULL);
    return NULL;
}

Test(layers_parts, components_count_on_threads_at_once)
{
    ori_pattern *p = test_load_pattern(test_repo_path("tests/data/layers/corner-flaps.fold"), 0);
    ori_layers *L = create(p, ORI_LAYERS_NO_LIMIT);
    int n = ori_layers_component_count(L);
    job jobs[16];
    pthread_t t[16];
    cr_assert_leq(n, 16);
    for (int c = 0; c < n; ++c) {
        jobs[c] = (job){L, c, NULL};
        cr_assert_eq(pthread_create(&t[c], NULL, count_job, &jobs[c]), 0);
    }
    const char *s[16];
    for (int c = 0; c < n; ++c) {
        pthread_join(t[c], NULL);
        cr_assert_str_eq(jobs[c].states, c == 0 ? "1" : "2");
        s[c] = jobs[c].states;
    }
    ori_error err;
    cr_assert_eq(ori_layers_set_counts(L, s, false, &err), ORI_OK);
    char *total = ori_layers_state_count(L);
    cr_assert_str_eq(total, "32");
    ori_buffer_free(total);
    for (int c = 0; c < n; ++c) ori_buffer_free(jobs[c].states);
    ori_layers_destroy(L);
    ori_pattern_destroy(p);
}

Test(layers_parts, a_component_without_state_is_exhausted_and_bad_counts_are_refused)
{
    ori_pattern *p = test_load_pattern(test_repo_path("tests/data/layers/corner-flaps.fold"), 0);
    ori_layers *L = create(p, ORI_LAYERS_NO_LIMIT);
    int n = ori_layers_component_count(L);
    cr_assert_eq(n, 6);
    ori_error err;
    char *out = NULL;
    cr_assert_eq(ori_layers_count_component(L, n, &out, NULL, &err), ORI_ERR_RANGE);
    cr_assert_null(out);
    cr_assert_eq(ori_layers_count_component(L, -1, &out, NULL, &err), ORI_ERR_RANGE);
    const char *bad[6] = {"1", "2", "2x", "2", "2", "2"};
    cr_assert_eq(ori_layers_set_counts(L, bad, false, &err), ORI_ERR_ARGUMENT);
    cr_assert(strstr(err.message, "component 2"), "%s", err.message);
    const char *fixed[6] = {"2", "2", "2", "2", "2", "2"};
    cr_assert_eq(ori_layers_set_counts(L, fixed, false, &err), ORI_ERR_ARGUMENT);
    cr_assert(!ori_layers_get_info(L).counted, "a refused install changes nothing");
    // A worker that found no state for component 4: no state at all, the component named.
    const char *none[6] = {"1", "2", "2", "2", "0", "2"};
    cr_assert_eq(ori_layers_set_counts(L, none, false, &err), ORI_OK);
    ori_layers_info in = ori_layers_get_info(L);
    cr_assert(in.counted && !in.satisfiable);
    ori_layers_conflict why;
    cr_assert(ori_layers_get_conflict(L, &why));
    cr_assert_eq(why.constraint, ORI_LAYERS_EXHAUSTED);
    cr_assert_eq(why.component, 4);
    int nf = ori_layers_conflict_faces(L, NULL, 0);
    cr_assert_geq(nf, 2, "the faces of component 4's variables");
    char *total = ori_layers_state_count(L);
    cr_assert_str_eq(total, "0");
    ori_buffer_free(total);
    // Installed once: a second install is a no-op.
    cr_assert_eq(ori_layers_set_counts(L, fixed, false, &err), ORI_OK);
    cr_assert(!ori_layers_get_info(L).satisfiable);
    ori_layers_destroy(L);
    ori_pattern_destroy(p);
}
