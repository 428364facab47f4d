// SuiteSparse's start-up, once for the library (src/core/suitesparse.h).
#include "suitesparse.h"

#include "core_internal.h"

#ifdef ORI_HAVE_GOMP
// The OpenMP runtime CHOLMOD is built with (declared here: no -fopenmp for the library itself).
int omp_get_max_active_levels(void);
void omp_set_max_active_levels(int levels);
#endif

static void *ss_malloc(size_t n) { return ori__alloc(n ? n : 1); }
static void *ss_calloc(size_t n, size_t s) { return ori__calloc(n ? n : 1, s ? s : 1); }
static void *ss_realloc(void *p, size_t n) { return ori__realloc(p, n ? n : 1); }
static void ss_free(void *p) { ori__free(p); }

void ori__suitesparse_route_memory(void)
{
    SuiteSparse_config.malloc_func = ss_malloc;
    SuiteSparse_config.calloc_func = ss_calloc;
    SuiteSparse_config.realloc_func = ss_realloc;
    SuiteSparse_config.free_func = ss_free;
}

void ori__cholmod_start(cholmod_common *cm)
{
    ori__suitesparse_route_memory();
    cholmod_start(cm);
    cm->print = 0;
    cm->error_handler = NULL;
    cm->quick_return_if_not_posdef = 1;
}

void ori__klu_start(klu_common *kc)
{
    ori__suitesparse_route_memory();
    klu_defaults(kc);
}

int ori__suitesparse_serial_begin(void)
{
#ifdef ORI_HAVE_GOMP
    int levels = omp_get_max_active_levels();
    omp_set_max_active_levels(0);
    return levels;
#else
    return 0;
#endif
}

void ori__suitesparse_serial_end(int levels)
{
#ifdef ORI_HAVE_GOMP
    omp_set_max_active_levels(levels);
#else
    (void)levels;
#endif
}
