// The freedom of a fold's solved creases without a dense Jacobian: a basis of the null space of
// the loop-closure Jacobian J (rows × variables, sparse, kept factored as J Jᵀ + λI by CHOLMOD in
// an mf_system) from random vectors projected onto it, and the creases to lock chosen on that
// basis by a rank-revealing QR (LAPACK dgeqp3) of its transpose. Used by lockset.c and drives.c
// when the dense Jacobian would exceed ORI_LOCKSET_DENSE_MAX_ENTRIES.
//
// Projection: P v = v − Jᵀ (J Jᵀ + λI)⁻¹ J v removes every component along a right singular
// vector of singular value σ but a fraction λ/(σ² + λ) of it; applied ORI_LOCKSET_PROJECTIONS
// times to k random vectors it leaves the null space plus (λ/(σ² + λ))^ORI_LOCKSET_PROJECTIONS
// of the rest, and the numerical rank of the k projected vectors (dgeqp3: diagonal entries of R
// above ORI_TOL_LOCKSET_NULL_REL × the random vectors' norm) is the nullity d as long as d < k (k doubles until it is).
// Locking: with N (n × d) an orthonormal basis of the null space, locking the variables L
// leaves the motions {N c : (N c)_L = 0}, none iff N_L has rank d; column pivoting on Nᵀ picks d
// variables whose rows of N are best conditioned first. Weights w (the creases' speed in the
// probe motion) scale the rows by 1/w, as the dense path scales J's columns by w (the null space
// of J W is W⁻¹ times that of J): creases the motion uses are kept free.
#include <lapacke.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "multifold_internal.h"

static double uniform(uint64_t *state)
{
    *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*state >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

int ori__mf_freedom(mf_system *s, const double *weight, int *lock)
{
    int n = s->nvar, R = ori__mf_rows(s);
    if (n == 0) return 0;
    uint64_t seed = 0x2545F4914F6CDD1DULL;
    double *jv = ori__alloc(sizeof(double) * (size_t)(R + 1));
    double *p = ori__alloc(sizeof(double) * (size_t)(n + 1));
    int k = n < ORI_LOCKSET_SPARSE_BLOCK ? n : ORI_LOCKSET_SPARSE_BLOCK;
    int d = -1;
    double *y = NULL, *tau = NULL;
    int *jpvt = NULL;
    for (;;) {
        if ((double)n * (double)k > ORI_LOCKSET_SPARSE_MAX_BASIS) {
            d = -2; // the freedom is too large for a dense basis
            break;
        }
        y = ori__alloc(sizeof(double) * ((size_t)n * (size_t)k + 1));
        tau = ori__alloc(sizeof(double) * (size_t)(k + 1));
        jpvt = ori__calloc((size_t)k + 1, sizeof(int));
        bool ok = true;
        double ref = 0.0; // the largest random vector's norm: the scale of the null components
        for (int c = 0; c < k && ok; ++c) {
            double *v = y + (size_t)c * (size_t)n, nn = 0.0;
            for (int i = 0; i < n; ++i) {
                v[i] = uniform(&seed);
                nn += v[i] * v[i];
            }
            ref = fmax(ref, sqrt(nn));
            for (int it = 0; it < ORI_LOCKSET_PROJECTIONS && ok; ++it) {
                ori__mf_jv(s, v, jv);
                ok = ori__mf_minnorm(s, jv, p);
                for (int i = 0; i < n && ok; ++i) v[i] -= p[i];
            }
        }
        int rank = 0;
        if (ok && LAPACKE_dgeqp3(LAPACK_COL_MAJOR, n, k, y, n, jpvt, tau) == 0) {
            int kmin = n < k ? n : k;
            for (int i = 0; i < kmin; ++i)
                if (fabs(y[(size_t)i * (size_t)n + (size_t)i]) > ORI_TOL_LOCKSET_NULL_REL * ref) rank++;
        } else {
            break; // d stays -1
        }
        if (rank < k || k == n) {
            d = rank;
            break;
        }
        ori__free(y);
        ori__free(tau);
        ori__free(jpvt);
        y = tau = NULL;
        jpvt = NULL;
        k = 2 * k < n ? 2 * k : n;
    }
    if (d > 0 && lock) {
        // Q: the first d columns of the QR's orthogonal factor span the projected vectors.
        bool ok = LAPACKE_dorgqr(LAPACK_COL_MAJOR, n, d, d, y, n, tau) == 0;
        double *b = ok ? ori__alloc(sizeof(double) * ((size_t)d * (size_t)n + 1)) : NULL;
        int *piv = ok ? ori__calloc((size_t)n + 1, sizeof(int)) : NULL;
        double *tb = ok ? ori__alloc(sizeof(double) * (size_t)(d + 1)) : NULL;
        if (ok) {
            for (int i = 0; i < d; ++i) // b = (W⁻¹ Q)ᵀ, d × n column-major
                for (int j = 0; j < n; ++j)
                    b[i + (size_t)d * (size_t)j] = y[(size_t)i * (size_t)n + (size_t)j] / (weight ? weight[j] : 1.0);
            ok = LAPACKE_dgeqp3(LAPACK_COL_MAJOR, d, n, b, d, piv, tb) == 0;
        }
        if (ok)
            for (int i = 0; i < d; ++i) lock[i] = piv[i] - 1;
        else d = -1;
        ori__free(b);
        ori__free(piv);
        ori__free(tb);
    }
    ori__free(y);
    ori__free(tau);
    ori__free(jpvt);
    ori__free(jv);
    ori__free(p);
    return d;
}
