// Numerical rank of the loop-closure Jacobian: dense by SVD (LAPACK), sparse by inverse
// subspace iteration with a CHOLMOD factor of JᵀJ + μI. Below solver.c, cone.c and dof.c, which
// use it; above jacobian.c and sparse.c.
#include <float.h>
#include <lapacke.h>
#include <math.h>

#include "kinematics_internal.h"

int ori__dense_rank(double *a, int rows, int cols, double rel_tol, double *sigma_max, double *sigma_cut)
{
    *sigma_max = 0.0;
    *sigma_cut = 0.0;
    int ns = rows < cols ? rows : cols;
    if (ns <= 0) return 0;
    double *s = ori__alloc(sizeof(double) * (size_t)ns);
    lapack_int info = LAPACKE_dgesdd(LAPACK_COL_MAJOR, 'N', rows, cols, a, rows, s, NULL, 1, NULL, 1);
    if (info != 0) {
        ori__free(s);
        return -1;
    }
    *sigma_max = s[0];
    int rank = 0;
    for (int i = 0; i < ns; ++i)
        if (s[i] > rel_tol * s[0] && s[i] > 0.0) {
            rank++;
            *sigma_cut = s[i];
        }
    ori__free(s);
    return rank;
}

// Deterministic pseudo-random numbers in [−1, 1) (64-bit LCG, top bits).
static double lcg(uint64_t *state)
{
    *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*state >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

static void orthonormalize(double *x, int n, int b)
{
    for (int i = 0; i < b; ++i) {
        double *xi = x + (size_t)i * n;
        for (int pass = 0; pass < 2; ++pass)
            for (int j = 0; j < i; ++j) {
                const double *xj = x + (size_t)j * n;
                double d = 0.0;
                for (int k = 0; k < n; ++k) d += xi[k] * xj[k];
                for (int k = 0; k < n; ++k) xi[k] -= d * xj[k];
            }
        double nr = 0.0;
        for (int k = 0; k < n; ++k) nr += xi[k] * xi[k];
        nr = sqrt(nr);
        if (nr > 0.0)
            for (int k = 0; k < n; ++k) xi[k] /= nr;
    }
}

// Eigenvalues of a small symmetric matrix (column-major b × b, destroyed) by cyclic Jacobi
// rotations (Golub & Van Loan 8.5), to full relative accuracy of the matrix' norm. For the
// Rayleigh–Ritz blocks of the sparse nullity: LAPACK's dsyev goes through OpenBLAS' dsymv,
// which wakes its worker threads even for a 4 × 4 matrix, and they then spin on the CPU for a
// while. False when the sweeps do not converge (never seen; dsyev would be the fallback).
static bool jacobi_eigenvalues(double *a, int b, double *w)
{
#define A(i, j) a[(i) + (size_t)b * (j)]
    bool converged = false;
    for (int sweep = 0; sweep < 64 && !converged; ++sweep) {
        double off = 0.0, diag = 0.0;
        for (int j = 0; j < b; ++j) {
            diag += A(j, j) * A(j, j);
            for (int i = 0; i < j; ++i) off += 2.0 * A(i, j) * A(i, j);
        }
        if (off <= DBL_EPSILON * DBL_EPSILON * (diag + off)) {
            converged = true;
            break;
        }
        for (int p = 0; p < b; ++p)
            for (int q = p + 1; q < b; ++q) {
                double apq = A(p, q);
                if (apq == 0.0) continue;
                // Rotation zeroing A(p, q): t = tan φ, the smaller root of t² + 2τt − 1 = 0.
                double tau = (A(q, q) - A(p, p)) / (2.0 * apq);
                double t = (tau >= 0.0 ? 1.0 : -1.0) / (fabs(tau) + sqrt(1.0 + tau * tau));
                double c = 1.0 / sqrt(1.0 + t * t), s = t * c;
                for (int k = 0; k < b; ++k) { // columns p, q
                    double akp = A(k, p), akq = A(k, q);
                    A(k, p) = c * akp - s * akq;
                    A(k, q) = s * akp + c * akq;
                }
                for (int k = 0; k < b; ++k) { // rows p, q
                    double apk = A(p, k), aqk = A(q, k);
                    A(p, k) = c * apk - s * aqk;
                    A(q, k) = s * apk + c * aqk;
                }
            }
    }
    for (int i = 0; i < b; ++i) w[i] = A(i, i);
#undef A
    return converged;
}

// Sparse nullity: σ_max by power iteration on JᵀJ; then subspace iteration with
// (JᵀJ + μI)⁻¹, μ = τ², τ = ORI_TOL_RANK_REL_SPARSE·σ_max, and Rayleigh–Ritz on the block:
// the Ritz values σ_i = |J x_i| below τ count as null directions. The block grows (×2) while
// all its Ritz values are null. Accurate while the smallest nonzero σ is well above τ.
static int sparse_nullity(kin_sls *sls, int n, int m, double smax_known, double *sigma_max, double *sigma_cut)
{
    uint64_t seed = 0x9E3779B97F4A7C15ULL;
    double *x = ori__alloc(sizeof(double) * (size_t)n);
    double *y = ori__alloc(sizeof(double) * (size_t)(m > 0 ? m : 1));
    for (int k = 0; k < n; ++k) x[k] = lcg(&seed);
    double lam = smax_known * smax_known;
    for (int it = 0; it < 40 && !(smax_known > 0.0); ++it) {
        double nr = 0.0;
        for (int k = 0; k < n; ++k) nr += x[k] * x[k];
        nr = sqrt(nr);
        if (!(nr > 0.0)) break;
        for (int k = 0; k < n; ++k) x[k] /= nr;
        ori__sls_mult(sls, x, y);
        double yy = 0.0;
        for (int k = 0; k < m; ++k) yy += y[k] * y[k];
        lam = yy;
        ori__sls_mult_t(sls, y, x);
    }
    double smax = sqrt(lam);
    *sigma_max = smax;
    *sigma_cut = 0.0;
    if (!(smax > 0.0)) {
        ori__free(x);
        ori__free(y);
        return n;
    }
    double tau = ORI_TOL_RANK_REL_SPARSE * smax;
    if (!ori__sls_factor(sls, tau * tau)) {
        ori__free(x);
        ori__free(y);
        return -1;
    }
    int null_count = 0;
    int b = 4;
    for (;;) {
        if (b > n) b = n;
        double *X = ori__alloc(sizeof(double) * (size_t)n * (size_t)b);
        double *Y = ori__alloc(sizeof(double) * (size_t)m * (size_t)b + 1);
        for (size_t k = 0; k < (size_t)n * (size_t)b; ++k) X[k] = lcg(&seed);
        orthonormalize(X, n, b);
        for (int it = 0; it < 6; ++it) {
            // The block's columns in one solve (one pass over the factor: on a 1000 × 1000
            // Miura-ori the factor is 0.8 GB, each pass memory-bound).
            ori__sls_solve_many(sls, b, X, X);
            orthonormalize(X, n, b);
        }
        // Rayleigh–Ritz: G = (JX)ᵀ(JX), eigenvalues = Ritz σ².
        for (int i = 0; i < b; ++i) ori__sls_mult(sls, X + (size_t)i * n, Y + (size_t)i * m);
        double *G = ori__alloc(sizeof(double) * (size_t)b * (size_t)b);
        for (int i = 0; i < b; ++i)
            for (int j = 0; j < b; ++j) {
                double d = 0.0;
                for (int k = 0; k < m; ++k) d += Y[(size_t)i * m + k] * Y[(size_t)j * m + k];
                G[i + (size_t)b * j] = d;
            }
        double *w = ori__alloc(sizeof(double) * (size_t)b);
        lapack_int info = b <= ORI_KIN_JACOBI_MAX ? (jacobi_eigenvalues(G, b, w) ? 0 : 1)
                                                  : LAPACKE_dsyev(LAPACK_COL_MAJOR, 'N', 'U', b, G, b, w);
        null_count = 0;
        double cut = 0.0;
        for (int i = 0; i < b && info == 0; ++i) {
            double s = sqrt(fmax(w[i], 0.0));
            if (s < tau) null_count++;
            else if (cut == 0.0 || s < cut) cut = s;
        }
        *sigma_cut = cut;
        ori__free(G);
        ori__free(w);
        ori__free(X);
        ori__free(Y);
        if (info != 0) {
            null_count = -1;
            break;
        }
        if (null_count < b || b >= n || b >= 256) break;
        b *= 2;
    }
    ori__free(x);
    ori__free(y);
    return null_count;
}

ori_status ori__kin_nullity(const ori_mechanism *m, const double *th, const int *col_of_joint, int ncols,
                            ori_dof_result *out, ori_error *error)
{
    out->unknowns = ncols;
    out->equations = m->rows;
    out->rank = 0;
    out->dof = ncols;
    out->sigma_max = out->sigma_cut = 0.0;
    out->dense = true;
    if (ncols == 0 || m->rows == 0) return ORI_OK;
    size_t entries = (size_t)m->rows * (size_t)ncols;
    if (entries <= (size_t)ORI_DOF_DENSE_MAX_ENTRIES) {
        double *a = ori__kin_jacobian_dense(m, col_of_joint, ncols, th);
        int rank = ori__dense_rank(a, m->rows, ncols, ORI_TOL_RANK_REL, &out->sigma_max, &out->sigma_cut);
        ori__free(a);
        if (rank < 0) return ori__fail(error, ORI_ERR_INTERNAL, "SVD of the loop-closure Jacobian failed");
        out->rank = rank;
        out->dof = ncols - rank;
        return ORI_OK;
    }
    return ori__kin_nullity_sparse(m, th, col_of_joint, ncols, out, error);
}

// σ_max of J by power iteration on JᵀJ (sls holds Jᵀ: n × m).
static double sigma_max_of(kin_sls *sls, int n, int m)
{
    uint64_t seed = 0x2545F4914F6CDD1DULL;
    double *x = ori__alloc(sizeof(double) * ((size_t)n + 1));
    double *y = ori__alloc(sizeof(double) * ((size_t)m + 1));
    for (int k = 0; k < n; ++k) x[k] = lcg(&seed);
    double lam = 0.0;
    for (int it = 0; it < 40; ++it) {
        double nr = 0.0;
        for (int k = 0; k < n; ++k) nr += x[k] * x[k];
        nr = sqrt(nr);
        if (!(nr > 0.0)) break;
        for (int k = 0; k < n; ++k) x[k] /= nr;
        ori__sls_mult(sls, x, y);
        double yy = 0.0;
        for (int k = 0; k < m; ++k) yy += y[k] * y[k];
        lam = yy;
        ori__sls_mult_t(sls, y, x);
    }
    ori__free(x);
    ori__free(y);
    return sqrt(lam);
}

// Smallest singular value of a matrix S stored in s (p × q, q ≥ p, compressed columns: s was
// created with n = p "unknowns" and m = q "equations"), when S Sᵀ is positive definite: inverse
// iteration with the Cholesky factor of S Sᵀ, Rayleigh quotient |Sᵀx|² of the unit iterate.
// Returns -1 when S Sᵀ is not positive definite (S is rank deficient to working precision).
static double sigma_min_full(kin_sls *s, int p, int q)
{
    if (!ori__sls_factor(s, 0.0)) return -1.0;
    uint64_t seed = 0x9E3779B97F4A7C15ULL;
    double *x = ori__alloc(sizeof(double) * ((size_t)p + 1));
    double *y = ori__alloc(sizeof(double) * ((size_t)p + 1));
    double *z = ori__alloc(sizeof(double) * ((size_t)q + 1));
    for (int k = 0; k < p; ++k) x[k] = lcg(&seed);
    double sigma = -1.0, prev = INFINITY;
    for (int it = 0; it < ORI_KIN_INVERSE_ITERATIONS; ++it) {
        double nr = 0.0;
        for (int k = 0; k < p; ++k) nr += x[k] * x[k];
        nr = sqrt(nr);
        if (!(nr > 0.0)) break;
        for (int k = 0; k < p; ++k) x[k] /= nr;
        ori__sls_mult(s, x, z); // Sᵀx
        double zz = 0.0;
        for (int k = 0; k < q; ++k) zz += z[k] * z[k];
        sigma = sqrt(zz);
        if (fabs(prev - sigma) <= 1e-3 * sigma) break;
        prev = sigma;
        if (!ori__sls_solve(s, x, y)) {
            sigma = -1.0;
            break;
        }
        for (int k = 0; k < p; ++k) x[k] = y[k];
    }
    ori__free(x);
    ori__free(y);
    ori__free(z);
    return sigma;
}

// Full-rank shortcut of the sparse nullity. Rows of J whose norm is below a thousandth of the
// rank tolerance (exactly zero at the flat state: the normal component of every vertex loop)
// are dropped; then J' (the rest) has full row rank when J'J'ᵀ has a Cholesky factor and its
// smallest singular value is at least the tolerance (nullity n − rows). Returns the nullity,
// or -1 when that does not hold (or J′ has more rows than columns).
static int full_rank_nullity(int n, int m, const int *colptr, const int *rowind, const double *vals, double smax,
                             double *sigma_cut)
{
    double tau = ORI_TOL_RANK_REL_SPARSE * smax;
    int *keep = ori__alloc(sizeof(int) * ((size_t)m + 1)); // equation → kept row index or -1
    int mk = 0;
    for (int r = 0; r < m; ++r) {
        double nr = 0.0;
        for (int k = colptr[r]; k < colptr[r + 1]; ++k) nr += vals[k] * vals[k];
        keep[r] = sqrt(nr) > 1e-3 * tau ? mk++ : -1;
    }
    int result = -1;
    if (mk <= n) {
        // J' as an mk × n matrix in compressed columns (one column per unknown).
        int *cp = ori__calloc((size_t)n + 2, sizeof(int));
        for (int r = 0; r < m; ++r)
            if (keep[r] >= 0)
                for (int k = colptr[r]; k < colptr[r + 1]; ++k) cp[rowind[k] + 2]++;
        for (int c = 0; c < n; ++c) cp[c + 2] += cp[c + 1];
        int nnz = cp[n + 1];
        int *ri = ori__alloc(sizeof(int) * ((size_t)nnz + 1));
        double *vv = ori__alloc(sizeof(double) * ((size_t)nnz + 1));
        for (int r = 0; r < m; ++r) // rows ascending: each column's row indices come out sorted
            if (keep[r] >= 0)
                for (int k = colptr[r]; k < colptr[r + 1]; ++k) {
                    int at = cp[rowind[k] + 1]++;
                    ri[at] = keep[r];
                    vv[at] = vals[k];
                }
        kin_sls *rs = ori__sls_create(mk, n, cp, ri);
        double *x = ori__sls_values(rs);
        for (int k = 0; k < nnz; ++k) x[k] = vv[k];
        double smin = mk > 0 ? sigma_min_full(rs, mk, n) : INFINITY;
        if (smin >= tau) {
            result = n - mk;
            *sigma_cut = mk > 0 ? smin : 0.0;
        }
        ori__sls_destroy(rs);
        ori__free(cp);
        ori__free(ri);
        ori__free(vv);
    }
    // More rows than columns: a full-column-rank test would cost the same factorization of JᵀJ
    // as the subspace iteration, which settles nullity 0 in its first block anyway.
    ori__free(keep);
    return result;
}

ori_status ori__kin_nullity_sparse(const ori_mechanism *m, const double *th, const int *col_of_joint, int ncols,
                                   ori_dof_result *out, ori_error *error)
{
    out->unknowns = ncols;
    out->equations = m->rows;
    int *colptr, *rowind;
    double *vals;
    kin_sls *sls = ori__kin_jacobian_sls_parts(m, col_of_joint, ncols, th, &colptr, &rowind, &vals);
    double smax = sigma_max_of(sls, ncols, m->rows);
    int nul = -1;
    if (smax > 0.0) nul = full_rank_nullity(ncols, m->rows, colptr, rowind, vals, smax, &out->sigma_cut);
    ori__free(colptr); // (before the subspace iteration's factorization: less at the peak)
    ori__free(rowind);
    ori__free(vals);
    if (nul >= 0) out->sigma_max = smax;
    else nul = sparse_nullity(sls, ncols, m->rows, smax, &out->sigma_max, &out->sigma_cut);
    ori__sls_destroy(sls);
    if (nul < 0) return ori__fail(error, ORI_ERR_INTERNAL, "sparse rank estimation failed");
    out->dense = false;
    out->dof = nul;
    out->rank = ncols - nul;
    return ORI_OK;
}
