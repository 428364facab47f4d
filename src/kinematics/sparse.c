// Sparse least squares through CHOLMOD: the matrix is given as Jᵀ (n unknowns × m equations,
// compressed columns = one column per equation, so the pattern is the loop structure), and
// CHOLMOD factors JᵀJ + λI = (Jᵀ)(Jᵀ)ᵀ + λI directly from it (stype 0); or the caller assembles
// the symmetric JᵀJ itself (upper triangle, stype 1), which the corrector does because the
// normal matrix of a loop-closure Jacobian is cheap to accumulate loop by loop. The
// fill-reducing ordering (AMD) is analysed once per pattern; numeric factorizations reuse it.
//
// CHOLMOD starts as everywhere in the library (src/core/suitesparse.h): memory through the
// counted allocator, no printing, its OpenMP loops serial inside our factorizations and solves.
#include <string.h>

#include "../core/suitesparse.h"
#include "kinematics_internal.h"

// Flops per factor entry above which the factorization is supernodal (see start()).
#define ORI_KIN_SUPERNODAL_SWITCH 100.0

struct kin_sls {
    cholmod_common cm;
    cholmod_sparse *at; // n × m, packed, sorted
    cholmod_factor *L;
    cholmod_dense *b, *x, *y, *e;
    int n, m;
    bool factored;
    int factorizations;
};

static kin_sls *start(void)
{
    kin_sls *s = ori__calloc(1, sizeof *s);
    ori__cholmod_start(&s->cm);
    // Simplicial LDLᵀ up to ORI_KIN_SUPERNODAL_SWITCH flops per factor entry (AMD's estimate at
    // analysis), supernodal LLᵀ (BLAS on dense blocks) above. On loop-closure Jacobians of
    // sheet-like patterns the flops per entry grow with the size (nested-dissection fill):
    // 54 on a 100 × 100 Miura-ori, where simplicial is faster (no BLAS call, no BLAS threads
    // waking), 325 on a 1000 × 1000 one, where one factorization of JᵀJ takes 24 s simplicial
    // and 4.4 s supernodal (one OpenBLAS thread; docs/kinematics.md §14).
    s->cm.supernodal = CHOLMOD_AUTO;
    s->cm.supernodal_switch = ORI_KIN_SUPERNODAL_SWITCH;
    return s;
}

static kin_sls *create(int n, int m, const int *colptr, const int *rowind, int stype)
{
    kin_sls *s = start();
    s->n = n;
    s->m = m;
    int nnz = colptr[m];
    s->at = cholmod_allocate_sparse((size_t)n, (size_t)m, (size_t)(nnz > 0 ? nnz : 1), 1, 1, stype, CHOLMOD_REAL, &s->cm);
    int *p = s->at->p, *i = s->at->i;
    for (int k = 0; k <= m; ++k) p[k] = colptr[k];
    for (int k = 0; k < nnz; ++k) i[k] = rowind[k];
    double *x = s->at->x;
    for (int k = 0; k < nnz; ++k) x[k] = 0.0;
    s->L = cholmod_analyze(s->at, &s->cm);
    s->b = cholmod_zeros((size_t)n, 1, CHOLMOD_REAL, &s->cm);
    return s;
}

kin_sls *ori__sls_create(int n, int m, const int *colptr, const int *rowind)
{
    return create(n, m, colptr, rowind, 0);
}

kin_sls *ori__sls_create_sym(int n, const int *colptr, const int *rowind)
{
    return create(n, n, colptr, rowind, 1);
}

void ori__sls_destroy(kin_sls *s)
{
    if (!s) return;
    ori__suitesparse_route_memory();
    cholmod_free_factor(&s->L, &s->cm);
    cholmod_free_sparse(&s->at, &s->cm);
    cholmod_free_dense(&s->b, &s->cm);
    cholmod_free_dense(&s->x, &s->cm);
    cholmod_free_dense(&s->y, &s->cm);
    cholmod_free_dense(&s->e, &s->cm);
    cholmod_finish(&s->cm);
    ori__free(s);
}

double *ori__sls_values(kin_sls *s) { return s->at->x; }

void ori__sls_clear_values(kin_sls *s)
{
    const int *p = s->at->p;
    double *x = s->at->x;
    for (int k = 0; k < p[s->m]; ++k) x[k] = 0.0;
}

bool ori__sls_factor(kin_sls *s, double lambda)
{
    ori__suitesparse_route_memory();
    if (!s->L) return false;
    double beta[2] = {lambda, 0.0};
    s->factorizations++;
    int levels = ori__suitesparse_serial_begin();
    int ok = cholmod_factorize_p(s->at, beta, NULL, 0, s->L, &s->cm);
    ori__suitesparse_serial_end(levels);
    s->factored = ok && s->cm.status == CHOLMOD_OK && s->L->minor == s->L->n;
    return s->factored;
}

bool ori__sls_solve(kin_sls *s, const double *rhs, double *out)
{
    if (!s->factored) return false;
    ori__suitesparse_route_memory();
    double *b = s->b->x;
    for (int k = 0; k < s->n; ++k) b[k] = rhs[k];
    int levels = ori__suitesparse_serial_begin();
    int ok = cholmod_solve2(CHOLMOD_A, s->L, s->b, NULL, &s->x, NULL, &s->y, &s->e, &s->cm);
    ori__suitesparse_serial_end(levels);
    if (!ok) return false;
    const double *x = s->x->x;
    for (int k = 0; k < s->n; ++k) {
        if (!isfinite(x[k])) return false;
        out[k] = x[k];
    }
    return true;
}

bool ori__sls_solve_many(kin_sls *s, int k, const double *rhs, double *out)
{
    if (!s->factored) return false;
    ori__suitesparse_route_memory();
    cholmod_dense *b = cholmod_allocate_dense((size_t)s->n, (size_t)k, (size_t)s->n, CHOLMOD_REAL, &s->cm);
    if (!b) return false;
    size_t total = (size_t)s->n * (size_t)k;
    double *bx = b->x;
    for (size_t i = 0; i < total; ++i) bx[i] = rhs[i];
    cholmod_dense *x = cholmod_solve(CHOLMOD_A, s->L, b, &s->cm);
    cholmod_free_dense(&b, &s->cm);
    bool ok = x != NULL;
    for (size_t i = 0; ok && i < total; ++i) ok = isfinite(((const double *)x->x)[i]);
    if (ok) memcpy(out, x->x, sizeof(double) * total);
    cholmod_free_dense(&x, &s->cm);
    return ok;
}

void ori__sls_mult_t(const kin_sls *s, const double *y, double *out)
{
    const int *p = s->at->p, *i = s->at->i;
    const double *x = s->at->x;
    for (int k = 0; k < s->n; ++k) out[k] = 0.0;
    for (int c = 0; c < s->m; ++c) {
        double yc = y[c];
        if (yc == 0.0) continue;
        for (int k = p[c]; k < p[c + 1]; ++k) out[i[k]] += x[k] * yc;
    }
}

void ori__sls_mult(const kin_sls *s, const double *v, double *out)
{
    const int *p = s->at->p, *i = s->at->i;
    const double *x = s->at->x;
    for (int c = 0; c < s->m; ++c) {
        double acc = 0.0;
        for (int k = p[c]; k < p[c + 1]; ++k) acc += x[k] * v[i[k]];
        out[c] = acc;
    }
}

double ori__sls_rcond(kin_sls *s)
{
    if (!s->factored) return 0.0;
    ori__suitesparse_route_memory();
    return cholmod_rcond(s->L, &s->cm);
}

int ori__sls_factorizations(const kin_sls *s) { return s->factorizations; }

size_t ori__sls_factor_nnz(const kin_sls *s)
{
    if (!s->L) return 0;
    if (s->L->is_super) return s->L->xsize;
    return s->L->nzmax;
}
