// Degrees of freedom: the nullity of the loop-closure Jacobian (the true DOF of
// overconstrained mechanisms, where the Grübler–Kutzbach count fails), dense by SVD or sparse
// by inverse subspace iteration with a CHOLMOD factor; and, at singular states such as the
// flat sheet, the nullity at a nearby regular state on the motion.
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
static int sparse_nullity(kin_sls *sls, int n, int m, double *sigma_max, double *sigma_cut)
{
    uint64_t seed = 0x9E3779B97F4A7C15ULL;
    double *x = ori__alloc(sizeof(double) * (size_t)n);
    double *y = ori__alloc(sizeof(double) * (size_t)(m > 0 ? m : 1));
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
            for (int i = 0; i < b; ++i) {
                ori__sls_solve(sls, X + (size_t)i * n, x);
                for (int k = 0; k < n; ++k) X[(size_t)i * n + k] = x[k];
            }
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
        double *blocks = ori__calloc((size_t)(6 * m->loop_col_total) + 1, sizeof(double));
        ori__kin_eval(m, th, NULL, blocks, NULL);
        double *a = ori__calloc(entries, sizeof(double));
        for (int l = 0; l < m->loop_count; ++l) {
            const kin_loop *L = &m->loops[l];
            for (int c = 0; c < L->col_count; ++c) {
                int col = col_of_joint[m->loop_cols[L->col_first + c]];
                if (col < 0) continue;
                for (int r = 0; r < L->rows; ++r)
                    a[(size_t)(L->row0 + r) + (size_t)m->rows * (size_t)col] = blocks[6 * (L->col_first + c) + r];
            }
        }
        int rank = ori__dense_rank(a, m->rows, ncols, ORI_TOL_RANK_REL, &out->sigma_max, &out->sigma_cut);
        ori__free(a);
        ori__free(blocks);
        if (rank < 0) return ori__fail(error, ORI_ERR_INTERNAL, "SVD of the loop-closure Jacobian failed");
        out->rank = rank;
        out->dof = ncols - rank;
        return ORI_OK;
    }
    return ori__kin_nullity_sparse(m, th, col_of_joint, ncols, out, error);
}

ori_status ori__kin_nullity_sparse(const ori_mechanism *m, const double *th, const int *col_of_joint, int ncols,
                                   ori_dof_result *out, ori_error *error)
{
    out->unknowns = ncols;
    out->equations = m->rows;
    kin_sls *sls = ori__kin_jacobian_sls(m, col_of_joint, ncols, th);
    int nul = sparse_nullity(sls, ncols, m->rows, &out->sigma_max, &out->sigma_cut);
    ori__sls_destroy(sls);
    if (nul < 0) return ori__fail(error, ORI_ERR_INTERNAL, "sparse rank estimation failed");
    out->dense = false;
    out->dof = nul;
    out->rank = ncols - nul;
    return ORI_OK;
}

ori_dof_def ori_default_dof_def(void)
{
    ori_dof_def def;
    def.angles_rad = NULL;
    def.locked_edges = NULL;
    def.locked_count = 0;
    def.probe_generic = true;
    def.internal_value = ORI__DEF_COOKIE;
    return def;
}

ori_status ori_mechanism_dof(const ori_mechanism *m, const ori_dof_def *def, ori_dof_result *out, ori_error *error)
{
    ORI_ASSERT(m && def && def->internal_value == ORI__DEF_COOKIE && out);
    memset(out, 0, sizeof *out);
    out->grubler = m->grubler;
    out->generic_dof = -1;
    int J = m->joint_count;
    if (def->angles_rad)
        for (int e = 0; e < m->edge_count; ++e)
            if (!isfinite(def->angles_rad[e]))
                return ori__fail_at(error, ORI_ERR_RANGE, "edges_foldAngle", e, "fold angle is not finite");
    int *col = ori__alloc(sizeof(int) * (size_t)(J + 1));
    for (int j = 0; j < J; ++j) col[j] = m->joints[j].kind == ORI_JOINT_REVOLUTE ? 0 : KIN_FIXED;
    for (int i = 0; i < def->locked_count; ++i) {
        int e = def->locked_edges[i];
        if (e < 0 || e >= m->edge_count) {
            ori__free(col);
            return ori__fail_at(error, ORI_ERR_RANGE, "edges_vertices", e, "no edge %d", e);
        }
        if (m->edge_joint[e] != ORI_NULL_INDEX) col[m->edge_joint[e]] = KIN_FIXED;
    }
    int n = 0;
    for (int j = 0; j < J; ++j)
        if (col[j] >= 0) col[j] = n++;
    double *th = ori__alloc(sizeof(double) * (size_t)(J + 1));
    ori__kin_edges_to_joints(m, def->angles_rad, th);
    double res = ori__kin_residual(m, th);
    if (!(res <= ORI_TOL_START_RESIDUAL)) {
        ori__free(col);
        ori__free(th);
        return ori__fail(error, ORI_ERR_ARGUMENT,
                         "the fold angles do not close the loops (residual %.3g above %.0e)", res,
                         ORI_TOL_START_RESIDUAL);
    }
    ori_status st = ori__kin_nullity(m, th, col, n, out, error);
    out->grubler = m->grubler;
    out->generic_dof = -1;
    if (st == ORI_OK && def->probe_generic && out->dof > 0 && m->rows > 0) {
        // Step along a motion and measure there; a single step may leave some vertices flat
        // (still singular), so step again from the new state while the nullity drops.
        double *cur = ori__alloc(sizeof(double) * (size_t)(J + 1));
        double *next = ori__alloc(sizeof(double) * (size_t)(J + 1));
        memcpy(cur, th, sizeof(double) * (size_t)J);
        int best = -1;
        for (int round = 0; round < ORI_KIN_PROBE_ROUNDS && st == ORI_OK; ++round) {
            if (!ori__kin_probe_generic(m, cur, col, n, next)) break;
            ori_dof_result near;
            st = ori__kin_nullity(m, next, col, n, &near, error);
            if (st != ORI_OK || (best >= 0 && near.dof >= best)) break;
            best = near.dof;
            memcpy(cur, next, sizeof(double) * (size_t)J);
            if (best == 0) break;
        }
        if (best < 0) {
            out->generic_dof = 0;
            out->rigid = true;
        } else {
            out->generic_dof = best;
        }
        ori__free(cur);
        ori__free(next);
        if (st == ORI_OK) out->singular = out->dof > out->generic_dof;
    } else if (st == ORI_OK && out->dof == 0) {
        out->generic_dof = 0;
    }
    ori__free(col);
    ori__free(th);
    return st;
}
