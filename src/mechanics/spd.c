// Symmetric positive definite solves for the dynamics and the sizing: dense Cholesky (LAPACK)
// for small systems, CHOLMOD's simplicial LDLᵀ for large sparse ones with the fill-reducing
// ordering analysed once per pattern. CHOLMOD's memory goes through the library's counted
// allocator and it never prints.
#include <lapacke.h>
#include <stdlib.h>

#include "../core/suitesparse.h"
#include "mechanics_internal.h"

struct mech_spd {
    int n;
    bool dense;
    double *a, *lu;      // dense: n × n (column-major), and its factor
    bool factored;
    cholmod_common cm;
    cholmod_sparse *A;   // upper triangle, sorted columns
    cholmod_factor *L;
    cholmod_dense *b, *x, *y, *e;
};

static int cmp_int(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

mech_spd *ori__spd_create(int n, int pairs, const int *ii, const int *jj)
{
    mech_spd *s = ori__calloc(1, sizeof *s);
    s->n = n;
    s->dense = n <= ORI_MECH_DENSE_MAX;
    if (s->dense) {
        s->a = ori__calloc((size_t)n * (size_t)n + 1, sizeof(double));
        s->lu = ori__calloc((size_t)n * (size_t)n + 1, sizeof(double));
        return s;
    }
    // Column counts of the upper triangle (row ≤ column), the diagonal always present.
    int *cnt = ori__calloc((size_t)n + 1, sizeof(int));
    for (int c = 0; c < n; ++c) cnt[c] = 1;
    for (int k = 0; k < pairs; ++k) {
        int r = ii[k] < jj[k] ? ii[k] : jj[k], c = ii[k] < jj[k] ? jj[k] : ii[k];
        if (r != c) cnt[c]++;
    }
    int *ptr = ori__alloc(sizeof(int) * (size_t)(n + 1));
    ptr[0] = 0;
    for (int c = 0; c < n; ++c) ptr[c + 1] = ptr[c] + cnt[c];
    int *rows = ori__alloc(sizeof(int) * (size_t)(ptr[n] + 1));
    for (int c = 0; c < n; ++c) {
        rows[ptr[c]] = c;
        cnt[c] = 1;
    }
    for (int k = 0; k < pairs; ++k) {
        int r = ii[k] < jj[k] ? ii[k] : jj[k], c = ii[k] < jj[k] ? jj[k] : ii[k];
        if (r != c) rows[ptr[c] + cnt[c]++] = r;
    }
    // Sort and deduplicate each column.
    int nnz = 0;
    int *p2 = ori__alloc(sizeof(int) * (size_t)(n + 1));
    for (int c = 0; c < n; ++c) {
        int *col = rows + ptr[c];
        qsort(col, (size_t)cnt[c], sizeof(int), cmp_int);
        p2[c] = nnz;
        for (int k = 0; k < cnt[c]; ++k)
            if (k == 0 || col[k] != col[k - 1]) rows[nnz++] = col[k];
    }
    p2[n] = nnz;
    ori__cholmod_start(&s->cm);
    s->cm.supernodal = CHOLMOD_SIMPLICIAL;
    s->A = cholmod_allocate_sparse((size_t)n, (size_t)n, (size_t)(nnz > 0 ? nnz : 1), 1, 1, 1, CHOLMOD_REAL, &s->cm);
    int *cp = s->A->p, *ri = s->A->i;
    for (int c = 0; c <= n; ++c) cp[c] = p2[c];
    for (int k = 0; k < nnz; ++k) ri[k] = rows[k];
    ori__free(cnt);
    ori__free(ptr);
    ori__free(p2);
    ori__free(rows);
    ori__spd_zero(s);
    s->L = cholmod_analyze(s->A, &s->cm);
    s->b = cholmod_zeros((size_t)n, 1, CHOLMOD_REAL, &s->cm);
    return s;
}

void ori__spd_destroy(mech_spd *s)
{
    if (!s) return;
    if (!s->dense) {
        ori__suitesparse_route_memory();
        cholmod_free_factor(&s->L, &s->cm);
        cholmod_free_sparse(&s->A, &s->cm);
        cholmod_free_dense(&s->b, &s->cm);
        cholmod_free_dense(&s->x, &s->cm);
        cholmod_free_dense(&s->y, &s->cm);
        cholmod_free_dense(&s->e, &s->cm);
        cholmod_finish(&s->cm);
    }
    ori__free(s->a);
    ori__free(s->lu);
    ori__free(s);
}

void ori__spd_zero(mech_spd *s)
{
    s->factored = false;
    if (s->dense) {
        memset(s->a, 0, sizeof(double) * (size_t)s->n * (size_t)s->n);
        return;
    }
    double *x = s->A->x;
    int nnz = ((int *)s->A->p)[s->n];
    for (int k = 0; k < nnz; ++k) x[k] = 0.0;
}

void ori__spd_add(mech_spd *s, int i, int j, double v)
{
    int r = i < j ? i : j, c = i < j ? j : i;
    if (s->dense) {
        s->a[(size_t)c * (size_t)s->n + (size_t)r] += v; // upper triangle, column-major
        return;
    }
    const int *cp = s->A->p, *ri = s->A->i;
    int lo = cp[c], hi = cp[c + 1] - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        if (ri[mid] == r) {
            ((double *)s->A->x)[mid] += v;
            return;
        }
        if (ri[mid] < r) lo = mid + 1;
        else hi = mid - 1;
    }
    ORI_ASSERT(!"entry outside the analysed pattern");
}

bool ori__spd_factor(mech_spd *s)
{
    if (s->dense) {
        memcpy(s->lu, s->a, sizeof(double) * (size_t)s->n * (size_t)s->n);
        s->factored = s->n == 0 || LAPACKE_dpotrf(LAPACK_COL_MAJOR, 'U', s->n, s->lu, s->n) == 0;
        return s->factored;
    }
    ori__suitesparse_route_memory();
    int ok = cholmod_factorize(s->A, s->L, &s->cm);
    s->factored = ok && s->cm.status == CHOLMOD_OK && s->L->minor == s->L->n;
    return s->factored;
}

bool ori__spd_solve(mech_spd *s, const double *b, double *x)
{
    if (!s->factored) return false;
    int n = s->n;
    if (s->dense) {
        for (int k = 0; k < n; ++k) x[k] = b[k];
        if (n == 0) return true;
        if (LAPACKE_dpotrs(LAPACK_COL_MAJOR, 'U', n, 1, s->lu, n, x, n) != 0) return false;
    } else {
        ori__suitesparse_route_memory();
        double *bb = s->b->x;
        for (int k = 0; k < n; ++k) bb[k] = b[k];
        if (!cholmod_solve2(CHOLMOD_A, s->L, s->b, NULL, &s->x, NULL, &s->y, &s->e, &s->cm)) return false;
        const double *xx = s->x->x;
        for (int k = 0; k < n; ++k) x[k] = xx[k];
    }
    for (int k = 0; k < n; ++k)
        if (!isfinite(x[k])) return false;
    return true;
}

void ori__spd_mult(const mech_spd *s, const double *x, double *y)
{
    int n = s->n;
    for (int k = 0; k < n; ++k) y[k] = 0.0;
    if (s->dense) {
        for (int c = 0; c < n; ++c)
            for (int r = 0; r <= c; ++r) {
                double a = s->a[(size_t)c * (size_t)n + (size_t)r];
                y[r] += a * x[c];
                if (r != c) y[c] += a * x[r];
            }
        return;
    }
    const int *cp = s->A->p, *ri = s->A->i;
    const double *ax = s->A->x;
    for (int c = 0; c < n; ++c)
        for (int k = cp[c]; k < cp[c + 1]; ++k) {
            int r = ri[k];
            y[r] += ax[k] * x[c];
            if (r != c) y[c] += ax[k] * x[r];
        }
}
