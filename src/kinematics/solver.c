// The corrector of the numeric continuation: Newton on the stacked loop residuals with the
// driven and locked creases eliminated (they are constants, not unknowns). Each iteration
// solves J_F δ = −r:
//   sweep   block forward substitution along the loops (build_sweep): each loop determines the
//           creases no earlier loop did, from its own equations; one pass over the loops, no
//           factorization. Used first for large patterns whenever the ordering exists;
//   dense   LAPACK dgelsd (SVD, minimum norm: robust at rank-deficient states), small systems;
//   sparse  CHOLMOD on the normal matrix JᵀJ, accumulated loop by loop (each loop couples only
//           its own creases) into a fixed upper-triangular pattern analysed once (AMD); where
//           the sweep does not exist or fails (a singular block, a step that does not help).
// The sparse factor is reused by later iterations and steps (chord / simplified Newton) while
// the residual contracts faster than ORI_KIN_CHORD_RATE per iteration, and renewed otherwise.
// Tangents solve the same system with the drive column as right-hand side: by the sweep when
// every loop agrees with its solution, else by least squares with a factor renewed at the
// current state, because the predictor's accuracy rests on them.
#include <lapacke.h>
#include <math.h>
#include <stdlib.h>

#include "kinematics_internal.h"

struct kin_solver {
    const ori_mechanism *m;
    int *col;       // per joint: free column, KIN_FIXED or KIN_DRIVE
    int ncols, drive, rows;
    bool sparse, min_norm;
    double *res;    // rows
    double *blocks; // 6 × loop_col_total
    double *jd;     // drive column (rows)
    double *half;   // per-joint half-angle cosine and sine, scratch of the evaluation
    double *th_eval; // the state of the last evaluation
    bool eval_valid;
    double eval_r;
    bool jac_valid; // blocks, jd (and the dense matrix) are of the last evaluated state
    // dense
    double *a, *rhs, *sv;
    double sv_min;      // smallest singular value kept by the last dense solve (0: rank 0)
    int sv_call;        // the corrector call of that solve
    int polish_iterations; // iterations of the last corrector call after its residual reached ORI_TOL_NEWTON
    // sparse: symmetric JᵀJ in a fixed pattern
    kin_sls *sls;
    int *pair_pos;  // per loop: for local free columns a ≤ b, the position in the values
    int *pair_first; // per loop: first index into pair_pos
    int *loop_free; // per loop: local free loop-columns (indices into the loop's columns), sorted by matrix column
    int *loop_free_first;
    double *g;
    bool have_factor;   // a factor exists
    bool factor_damped; // it is of JᵀJ + λI, λ > 0 (JᵀJ was not numerically positive definite)
    bool factor_current; // the factor is of the Jacobian at the last evaluated state
    bool refactor;      // renew before the next solve
    bool fresh;         // the last solve renewed the factor
    bool stale_ok;      // the last call converged with the previous call's factor
    int calls;          // corrector calls so far
    int factor_call;    // corrector call in which the factor was made
    // sweep: loops in propagation order, each determining its still undetermined columns
    bool sweep;          // an ordering exists that determines every free column
    int sweep_count;
    int *sweep_loop;     // sweep_count loops
    int *sweep_first;    // sweep_count + 1 offsets into sweep_new
    int *sweep_new;      // loop-local column indices (into the loop's columns) the loop determines
    int *sweep_kfirst;   // sweep_count + 1 offsets into sweep_known
    int *sweep_known;    // loop-local indices of free columns determined by earlier loops
    // the same resolved for sweep_solve, which streams through them in sweep order instead of
    // chasing loop → loop column → joint → free column (on a 1000 × 1000 sheet each of those
    // indirections is a cache miss): per step its first row and row count, per entry the index
    // of its Jacobian block (L->col_first + c) and its free column
    int *sweep_row0, *sweep_rows;
    int *sweep_new_blk, *sweep_new_x;
    int *sweep_known_blk, *sweep_known_x;
    int sweep_retry_at;  // after a failed sweep, the corrector call that tries it again
    int sweep_iterations; // corrector iterations done by the sweep
    // corrector scratch
    double *step, *neg, *best;
    int *free_joint;     // free column → joint
};

// --- construction -------------------------------------------------------------------------

static int cmp_i64(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

static void build_sparse(kin_solver *s)
{
    const ori_mechanism *m = s->m;
    int nl = m->loop_count;
    s->loop_free_first = ori__alloc(sizeof(int) * ((size_t)nl + 1));
    s->pair_first = ori__alloc(sizeof(int) * ((size_t)nl + 1));
    int nf = 0, np = 0;
    for (int l = 0; l < nl; ++l) {
        const kin_loop *L = &m->loops[l];
        int k = 0;
        for (int c = 0; c < L->col_count; ++c) k += s->col[m->loop_cols[L->col_first + c]] >= 0;
        s->loop_free_first[l] = nf;
        s->pair_first[l] = np;
        nf += k;
        np += k * (k + 1) / 2;
    }
    s->loop_free_first[nl] = nf;
    s->pair_first[nl] = np;
    s->loop_free = ori__alloc(sizeof(int) * ((size_t)nf + 1));
    s->pair_pos = ori__alloc(sizeof(int) * ((size_t)np + 1));
    // Local free columns sorted by matrix column.
    for (int l = 0; l < nl; ++l) {
        const kin_loop *L = &m->loops[l];
        int *lf = s->loop_free + s->loop_free_first[l];
        int k = 0;
        for (int c = 0; c < L->col_count; ++c) {
            int fc = s->col[m->loop_cols[L->col_first + c]];
            if (fc < 0) continue;
            int t = k++;
            while (t > 0 && s->col[m->loop_cols[L->col_first + lf[t - 1]]] > fc) {
                lf[t] = lf[t - 1];
                t--;
            }
            lf[t] = c;
        }
    }
    // Upper-triangle pattern: (row a, column b) with a ≤ b for every pair of a loop's columns,
    // plus the diagonal of every column (λI and isolated columns).
    int64_t *keys = ori__alloc(sizeof(int64_t) * ((size_t)np + (size_t)s->ncols + 1));
    int nk = 0;
    for (int l = 0; l < nl; ++l) {
        const kin_loop *L = &m->loops[l];
        const int *lf = s->loop_free + s->loop_free_first[l];
        int k = s->loop_free_first[l + 1] - s->loop_free_first[l];
        for (int b = 0; b < k; ++b)
            for (int a = 0; a <= b; ++a) {
                int ra = s->col[m->loop_cols[L->col_first + lf[a]]], cb = s->col[m->loop_cols[L->col_first + lf[b]]];
                keys[nk++] = (int64_t)cb * s->ncols + ra;
            }
    }
    for (int c = 0; c < s->ncols; ++c) keys[nk++] = (int64_t)c * s->ncols + c;
    // Sort (column-major order = CSC) and deduplicate.
    int64_t *sorted = keys;
    qsort(sorted, (size_t)nk, sizeof(int64_t), cmp_i64);
    int nu = 0;
    for (int i = 0; i < nk; ++i)
        if (nu == 0 || sorted[nu - 1] != sorted[i]) sorted[nu++] = sorted[i];
    int *colptr = ori__calloc((size_t)s->ncols + 1, sizeof(int));
    int *rowind = ori__alloc(sizeof(int) * ((size_t)nu + 1));
    for (int i = 0; i < nu; ++i) {
        int cb = (int)(sorted[i] / s->ncols), ra = (int)(sorted[i] % s->ncols);
        colptr[cb + 1]++;
        rowind[i] = ra;
    }
    for (int c = 0; c < s->ncols; ++c) colptr[c + 1] += colptr[c];
    // Positions of every loop pair by binary search in its column.
    for (int l = 0; l < nl; ++l) {
        const kin_loop *L = &m->loops[l];
        const int *lf = s->loop_free + s->loop_free_first[l];
        int k = s->loop_free_first[l + 1] - s->loop_free_first[l];
        int q = s->pair_first[l];
        for (int b = 0; b < k; ++b)
            for (int a = 0; a <= b; ++a) {
                int ra = s->col[m->loop_cols[L->col_first + lf[a]]], cb = s->col[m->loop_cols[L->col_first + lf[b]]];
                int lo = colptr[cb], hi = colptr[cb + 1] - 1;
                while (lo < hi) {
                    int mid = (lo + hi) / 2;
                    if (rowind[mid] < ra) lo = mid + 1;
                    else hi = mid;
                }
                s->pair_pos[q++] = lo;
            }
    }
    s->sls = ori__sls_create_sym(s->ncols, colptr, rowind);
    ori__free(keys);
    ori__free(colptr);
    ori__free(rowind);
}

// The sweep (block forward substitution). Starting at the loops of the driven crease and going
// breadth first, a loop whose undetermined free columns are no more than its rows determines
// them all from its own equations, given the columns determined before (least squares on the
// loop's block: a degree-4 vertex with one known crease determines the other three; one with
// two known the remaining two). When every free column is determined this way, the loops in
// that order give a block lower-triangular left inverse M of J_F (M J_F = I when every block
// has full column rank), and θ ← θ − M r(θ) converges quadratically like Gauss–Newton, at the
// cost of one pass over the loops instead of a sparse factorization. The loops that determine
// nothing are still checked: the corrector stops only when every loop closes.
static void build_sweep(kin_solver *s)
{
    const ori_mechanism *m = s->m;
    int nl = m->loop_count, nc = s->ncols;
    int *cl_first = ori__calloc((size_t)nc + 2, sizeof(int));
    for (int l = 0; l < nl; ++l) {
        const kin_loop *L = &m->loops[l];
        for (int c = 0; c < L->col_count; ++c) {
            int fc = s->col[m->loop_cols[L->col_first + c]];
            if (fc >= 0) cl_first[fc + 2]++;
        }
    }
    for (int k = 0; k < nc; ++k) cl_first[k + 2] += cl_first[k + 1];
    int *cl = ori__alloc(sizeof(int) * ((size_t)cl_first[nc + 1] + 1));
    int *unknown = ori__alloc(sizeof(int) * ((size_t)nl + 1));
    for (int l = 0; l < nl; ++l) {
        const kin_loop *L = &m->loops[l];
        unknown[l] = 0;
        for (int c = 0; c < L->col_count; ++c) {
            int fc = s->col[m->loop_cols[L->col_first + c]];
            if (fc >= 0) {
                cl[cl_first[fc + 1]++] = l;
                unknown[l]++;
            }
        }
    }
    // cl_first[k] .. cl_first[k + 1]: the loops of column k.
    bool *known = ori__calloc((size_t)nc + 1, sizeof(bool));
    bool *queued = ori__calloc((size_t)nl + 1, sizeof(bool));
    int *queue = ori__alloc(sizeof(int) * ((size_t)nl + 1));
    s->sweep_loop = ori__alloc(sizeof(int) * ((size_t)nl + 1));
    s->sweep_first = ori__alloc(sizeof(int) * ((size_t)nl + 2));
    s->sweep_kfirst = ori__alloc(sizeof(int) * ((size_t)nl + 2));
    s->sweep_new = ori__alloc(sizeof(int) * ((size_t)nc + 1));
    s->sweep_known = ori__alloc(sizeof(int) * ((size_t)m->loop_col_total + 1));
    int head = 0, tail = 0, determined = 0, nk = 0;
    s->sweep_count = 0;
    s->sweep_first[0] = 0;
    s->sweep_kfirst[0] = 0;
    for (int l = 0; l < nl; ++l) {
        const kin_loop *L = &m->loops[l];
        for (int c = 0; c < L->col_count; ++c)
            if (m->loop_cols[L->col_first + c] == s->drive && unknown[l] <= L->rows && !queued[l]) {
                queued[l] = true;
                queue[tail++] = l;
            }
    }
    for (;;) {
        while (head < tail) {
            int l = queue[head++];
            const kin_loop *L = &m->loops[l];
            if (unknown[l] == 0) continue; // every column already determined: a check loop
            int k = s->sweep_count++;
            s->sweep_loop[k] = l;
            int nn = s->sweep_first[k];
            for (int c = 0; c < L->col_count; ++c) {
                int fc = s->col[m->loop_cols[L->col_first + c]];
                if (fc < 0) continue;
                if (known[fc]) {
                    s->sweep_known[nk++] = c;
                    continue;
                }
                s->sweep_new[nn++] = c;
                known[fc] = true;
                determined++;
                for (int q = cl_first[fc]; q < cl_first[fc + 1]; ++q) {
                    int l2 = cl[q];
                    unknown[l2]--;
                    if (!queued[l2] && unknown[l2] <= m->loops[l2].rows) {
                        queued[l2] = true;
                        queue[tail++] = l2;
                    }
                }
            }
            s->sweep_first[k + 1] = nn;
            s->sweep_kfirst[k + 1] = nk;
        }
        if (determined == nc) break;
        // Columns out of reach of the drive (e.g. behind locked creases): start again at the
        // first loop that can determine its columns on its own.
        int seed = -1;
        for (int l = 0; l < nl && seed < 0; ++l)
            if (!queued[l] && unknown[l] > 0 && unknown[l] <= m->loops[l].rows) seed = l;
        if (seed < 0) break;
        queued[seed] = true;
        queue[tail++] = seed;
    }
    s->sweep = determined == nc && nc > 0;
    if (s->sweep) {
        int K = s->sweep_count;
        s->sweep_row0 = ori__alloc(sizeof(int) * ((size_t)K + 1));
        s->sweep_rows = ori__alloc(sizeof(int) * ((size_t)K + 1));
        s->sweep_new_blk = ori__alloc(sizeof(int) * ((size_t)s->sweep_first[K] + 1));
        s->sweep_new_x = ori__alloc(sizeof(int) * ((size_t)s->sweep_first[K] + 1));
        s->sweep_known_blk = ori__alloc(sizeof(int) * ((size_t)s->sweep_kfirst[K] + 1));
        s->sweep_known_x = ori__alloc(sizeof(int) * ((size_t)s->sweep_kfirst[K] + 1));
        for (int k = 0; k < K; ++k) {
            const kin_loop *L = &m->loops[s->sweep_loop[k]];
            s->sweep_row0[k] = L->row0;
            s->sweep_rows[k] = L->rows;
            for (int t = s->sweep_first[k]; t < s->sweep_first[k + 1]; ++t) {
                s->sweep_new_blk[t] = L->col_first + s->sweep_new[t];
                s->sweep_new_x[t] = s->col[m->loop_cols[L->col_first + s->sweep_new[t]]];
            }
            for (int t = s->sweep_kfirst[k]; t < s->sweep_kfirst[k + 1]; ++t) {
                s->sweep_known_blk[t] = L->col_first + s->sweep_known[t];
                s->sweep_known_x[t] = s->col[m->loop_cols[L->col_first + s->sweep_known[t]]];
            }
        }
    }
    ori__free(cl_first);
    ori__free(cl);
    ori__free(unknown);
    ori__free(known);
    ori__free(queued);
    ori__free(queue);
}

kin_solver *ori__kin_solver_create(const ori_mechanism *m, const int *col_of_joint, int ncols, int drive_joint,
                                   const kin_solver_opts *opts)
{
    kin_solver *s = ori__calloc(1, sizeof *s);
    s->m = m;
    s->ncols = ncols;
    s->drive = drive_joint;
    s->rows = m->rows;
    s->min_norm = opts && opts->min_norm;
    ori_linear lin = opts ? opts->linear : ORI_LINEAR_AUTO;
    bool large = ncols > ORI_MOTION_DENSE_MAX_UNKNOWNS;
    s->sparse = lin == ORI_LINEAR_SPARSE || lin == ORI_LINEAR_SWEEP || (lin == ORI_LINEAR_AUTO && large);
    if (s->rows == 0 || ncols == 0) s->sparse = false;
    bool want_sweep = s->sparse && !s->min_norm && (lin == ORI_LINEAR_SWEEP || (lin == ORI_LINEAR_AUTO && large));
    s->col = ori__alloc(sizeof(int) * (size_t)(m->joint_count + 1));
    for (int j = 0; j < m->joint_count; ++j) s->col[j] = col_of_joint[j];
    s->res = ori__calloc((size_t)s->rows + 1, sizeof(double));
    s->blocks = ori__calloc((size_t)(6 * m->loop_col_total) + 1, sizeof(double));
    s->jd = ori__calloc((size_t)s->rows + 1, sizeof(double));
    s->half = ori__alloc(sizeof(double) * 2 * (size_t)(m->joint_count + 1));
    s->th_eval = ori__calloc((size_t)m->joint_count + 1, sizeof(double));
    s->g = ori__alloc(sizeof(double) * ((size_t)ncols + 1));
    s->step = ori__alloc(sizeof(double) * ((size_t)ncols + 1));
    s->neg = ori__alloc(sizeof(double) * ((size_t)s->rows + 1));
    s->best = ori__alloc(sizeof(double) * ((size_t)m->joint_count + 1));
    s->free_joint = ori__alloc(sizeof(int) * ((size_t)ncols + 1));
    for (int j = 0; j < m->joint_count; ++j)
        if (s->col[j] >= 0) s->free_joint[s->col[j]] = j;
    if (!s->sparse) {
        size_t big = (size_t)(s->rows > ncols ? s->rows : ncols) + 1;
        s->a = ori__alloc(sizeof(double) * ((size_t)s->rows * (size_t)ncols + 1));
        s->rhs = ori__alloc(sizeof(double) * big);
        s->sv = ori__alloc(sizeof(double) * big);
        return s;
    }
    build_sparse(s);
    if (want_sweep) build_sweep(s);
    s->refactor = true;
    return s;
}

void ori__kin_solver_destroy(kin_solver *s)
{
    if (!s) return;
    ori__sls_destroy(s->sls);
    ori__free(s->col);
    ori__free(s->res);
    ori__free(s->blocks);
    ori__free(s->jd);
    ori__free(s->half);
    ori__free(s->th_eval);
    ori__free(s->a);
    ori__free(s->rhs);
    ori__free(s->sv);
    ori__free(s->pair_pos);
    ori__free(s->pair_first);
    ori__free(s->loop_free);
    ori__free(s->loop_free_first);
    ori__free(s->g);
    ori__free(s->step);
    ori__free(s->neg);
    ori__free(s->best);
    ori__free(s->free_joint);
    ori__free(s->sweep_loop);
    ori__free(s->sweep_first);
    ori__free(s->sweep_new);
    ori__free(s->sweep_kfirst);
    ori__free(s->sweep_known);
    ori__free(s->sweep_row0);
    ori__free(s->sweep_rows);
    ori__free(s->sweep_new_blk);
    ori__free(s->sweep_new_x);
    ori__free(s->sweep_known_blk);
    ori__free(s->sweep_known_x);
    ori__free(s);
}

int ori__kin_solver_factorizations(const kin_solver *s) { return s->sls ? ori__sls_factorizations(s->sls) : 0; }
bool ori__kin_solver_sweep(const kin_solver *s) { return s->sweep; }
int ori__kin_solver_sweep_iterations(const kin_solver *s) { return s->sweep_iterations; }
bool ori__kin_solver_sparse(const kin_solver *s) { return s->sparse; }

// --- evaluation ----------------------------------------------------------------------------

// Residual at th (cached for the last evaluated state). The Jacobian is computed on demand
// (jacobian()): a converged corrector needs no Jacobian at its last state.
static double residual_at(kin_solver *s, const double *th)
{
    const ori_mechanism *m = s->m;
    if (s->eval_valid && memcmp(s->th_eval, th, sizeof(double) * (size_t)m->joint_count) == 0) return s->eval_r;
    double r = ori__kin_eval(m, th, s->res, NULL, s->half);
    memcpy(s->th_eval, th, sizeof(double) * (size_t)m->joint_count);
    s->eval_valid = true;
    s->jac_valid = false;
    s->eval_r = r;
    return r;
}

// Residual and Jacobian blocks at th; the dense path scatters J_F into its matrix. Returns the
// max-norm of P − I.
static double evaluate(kin_solver *s, const double *th)
{
    const ori_mechanism *m = s->m;
    bool same = s->eval_valid && memcmp(s->th_eval, th, sizeof(double) * (size_t)m->joint_count) == 0;
    if (same && s->jac_valid) return s->eval_r;
    double r = ori__kin_eval(m, th, s->res, s->blocks, s->half);
    memcpy(s->th_eval, th, sizeof(double) * (size_t)m->joint_count);
    s->eval_valid = true;
    s->eval_r = r;
    s->jac_valid = true;
    s->factor_current = false;
    // jd: only the rows of the loops through the drive are ever set, all of them at every
    // evaluation (the rest stay zero from the allocation): no clearing of all rows.
    if (!s->sparse)
        for (size_t k = 0; k < (size_t)s->rows * (size_t)s->ncols; ++k) s->a[k] = 0.0;
    for (int l = 0; l < m->loop_count; ++l) {
        const kin_loop *L = &m->loops[l];
        for (int c = 0; c < L->col_count; ++c) {
            int j = m->loop_cols[L->col_first + c];
            const double *b = s->blocks + 6 * (L->col_first + c);
            int fc = s->col[j];
            if (j == s->drive) {
                for (int q = 0; q < L->rows; ++q) s->jd[L->row0 + q] = b[q];
            } else if (fc >= 0 && !s->sparse) {
                for (int q = 0; q < L->rows; ++q) s->a[(size_t)(L->row0 + q) + (size_t)s->rows * (size_t)fc] = b[q];
            }
        }
    }
    return r;
}

// Jᵀ y loop by loop (sparse path).
static void jt_mult(const kin_solver *s, const double *y, double *out)
{
    const ori_mechanism *m = s->m;
    for (int k = 0; k < s->ncols; ++k) out[k] = 0.0;
    for (int l = 0; l < m->loop_count; ++l) {
        const kin_loop *L = &m->loops[l];
        const int *lf = s->loop_free + s->loop_free_first[l];
        int k = s->loop_free_first[l + 1] - s->loop_free_first[l];
        for (int a = 0; a < k; ++a) {
            const double *b = s->blocks + 6 * (L->col_first + lf[a]);
            double acc = 0.0;
            for (int q = 0; q < L->rows; ++q) acc += b[q] * y[L->row0 + q];
            out[s->col[m->loop_cols[L->col_first + lf[a]]]] += acc;
        }
    }
}

// Assemble JᵀJ at the last evaluation and factor it (+λI when not positive definite).
// JᵀJ of the last evaluation into the fixed pattern; returns its trace.
static double assemble_normal(kin_solver *s)
{
    const ori_mechanism *m = s->m;
    double *v = ori__sls_values(s->sls);
    ori__sls_clear_values(s->sls);
    double tr = 0.0;
    for (int l = 0; l < m->loop_count; ++l) {
        const kin_loop *L = &m->loops[l];
        const int *lf = s->loop_free + s->loop_free_first[l];
        int k = s->loop_free_first[l + 1] - s->loop_free_first[l];
        int q = s->pair_first[l];
        for (int b = 0; b < k; ++b) {
            const double *bb = s->blocks + 6 * (L->col_first + lf[b]);
            for (int a = 0; a <= b; ++a) {
                const double *ba = s->blocks + 6 * (L->col_first + lf[a]);
                double acc = 0.0;
                for (int r = 0; r < L->rows; ++r) acc += ba[r] * bb[r];
                v[s->pair_pos[q++]] += acc;
                if (a == b) tr += acc;
            }
        }
    }
    return tr;
}

// Factor JᵀJ (assembled) + λI, λ = 0 or, when that is not numerically positive definite, the
// Levenberg–Marquardt damping ORI_TOL_RANK_REL × mean diagonal.
static bool factor_assembled(kin_solver *s, double trace)
{
    bool ok = ori__sls_factor(s->sls, 0.0);
    s->factor_damped = !ok;
    if (!ok) ok = ori__sls_factor(s->sls, ORI_TOL_RANK_REL * (s->ncols > 0 ? trace / s->ncols : 1.0));
    s->have_factor = ok;
    s->factor_current = ok;
    s->refactor = false;
    s->factor_call = s->calls;
    return ok;
}

// Assemble JᵀJ at the last evaluation and factor it (+λI when not positive definite).
static bool refactor_now(kin_solver *s) { return factor_assembled(s, assemble_normal(s)); }

// Dense least squares: minimise |A x − b| (A = the current J_F, copied), minimum norm.
static bool dense_solve(kin_solver *s, const double *b, double *x)
{
    int rows = s->rows, n = s->ncols;
    int ld = rows > n ? rows : n;
    double *a = ori__alloc(sizeof(double) * ((size_t)rows * (size_t)n + 1));
    for (size_t k = 0; k < (size_t)rows * (size_t)n; ++k) a[k] = s->a[k];
    for (int k = 0; k < ld; ++k) s->rhs[k] = k < rows ? b[k] : 0.0;
    int rank = 0;
    lapack_int info = LAPACKE_dgelsd(LAPACK_COL_MAJOR, rows, n, 1, a, rows > 0 ? rows : 1, s->rhs, ld > 0 ? ld : 1,
                                     s->sv, ORI_TOL_RANK_REL, &rank);
    ori__free(a);
    if (info != 0) return false;
    for (int k = 0; k < n; ++k) {
        if (!isfinite(s->rhs[k])) return false;
        x[k] = s->rhs[k];
    }
    s->sv_min = rank > 0 ? s->sv[rank - 1] : 0.0;
    s->sv_call = s->calls;
    return true;
}

// Sparse least-squares step (JᵀJ) x = Jᵀ b: right-hand side from the current Jacobian, factor
// from the last factorization unless a renewal is due (or `current` demands one at this state).
static bool sparse_step(kin_solver *s, const double *b, double *x, bool current)
{
    s->fresh = false;
    if (s->refactor || !s->have_factor || (current && !s->factor_current)) {
        if (!refactor_now(s)) return false;
        s->fresh = true;
    }
    jt_mult(s, b, s->g);
    return ori__sls_solve(s->sls, s->g, x);
}

// --- corrector, tangent, rank ------------------------------------------------------------

// Least squares min |A x − b| for one loop's block (rows ≤ 6, k ≤ rows unknowns; A column-major
// with leading dimension rows, destroyed; b destroyed) by Householder QR. False when the block
// is (nearly) rank deficient: a diagonal entry of R below ORI_KIN_SWEEP_PIVOT_REL × the largest
// column norm.
static bool small_lsq(double *a, int rows, int k, double *b, double *x)
{
    double cmax = 0.0;
    for (int j = 0; j < k; ++j) {
        double nr = 0.0;
        for (int i = 0; i < rows; ++i) nr += a[i + rows * j] * a[i + rows * j];
        cmax = fmax(cmax, sqrt(nr));
    }
    if (!(cmax > 0.0)) return false;
    double diag[6];
    for (int j = 0; j < k; ++j) {
        double *aj = a + rows * j;
        double nr = 0.0;
        for (int i = j; i < rows; ++i) nr += aj[i] * aj[i];
        nr = sqrt(nr);
        if (!(nr > ORI_KIN_SWEEP_PIVOT_REL * cmax)) return false;
        double alpha = aj[j] > 0.0 ? -nr : nr;
        // v = a_j(j:) − α e_j, H = I − 2 v vᵀ / vᵀv, vᵀv = 2 nr (nr + |a_jj|).
        double v[6];
        for (int i = j; i < rows; ++i) v[i] = aj[i];
        v[j] -= alpha;
        double vv = 2.0 * nr * (nr + fabs(aj[j]));
        for (int c = j + 1; c < k; ++c) {
            double *ac = a + rows * c;
            double d = 0.0;
            for (int i = j; i < rows; ++i) d += v[i] * ac[i];
            d = 2.0 * d / vv;
            for (int i = j; i < rows; ++i) ac[i] -= d * v[i];
        }
        double d = 0.0;
        for (int i = j; i < rows; ++i) d += v[i] * b[i];
        d = 2.0 * d / vv;
        for (int i = j; i < rows; ++i) b[i] -= d * v[i];
        diag[j] = alpha;
    }
    for (int j = k - 1; j >= 0; --j) {
        double acc = b[j];
        for (int c = j + 1; c < k; ++c) acc -= a[j + rows * c] * x[c];
        x[j] = acc / diag[j];
    }
    return true;
}

static inline void cross3(const double *a, const double *b, double *c)
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}
static inline double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The same least squares for a vertex loop's block (3 rows, k ≤ 3 columns of the blocks array,
// stride 6) in closed form with cross products: k = 3, x = (b·(a2×a3), b·(a3×a1), b·(a1×a2))/det;
// k = 2, the components of b's projection on the plane n = a1×a2, x = ((b×a2)·n, (a1×b)·n)/|n|²;
// k = 1, x = a·b/a·a. The rank test is Householder's: with R11 = |a1|, R22 = |a1×a2|/|a1| and
// R33 = det/|a1×a2|, each must exceed ORI_KIN_SWEEP_PIVOT_REL × the largest column norm.
static bool vertex_lsq(const double *const a[3], int k, const double *b, double *x)
{
    double n1 = dot3(a[0], a[0]);
    double cmax2 = n1;
    for (int t = 1; t < k; ++t) cmax2 = fmax(cmax2, dot3(a[t], a[t]));
    double tol2 = ORI_KIN_SWEEP_PIVOT_REL * ORI_KIN_SWEEP_PIVOT_REL * cmax2;
    if (!(n1 > tol2)) return false;
    if (k == 1) {
        x[0] = dot3(a[0], b) / n1;
        return true;
    }
    double n[3];
    cross3(a[0], a[1], n);
    double nn = dot3(n, n);
    if (!(nn > tol2 * n1)) return false; // R22² = |a1×a2|²/|a1|²
    if (k == 2) {
        double u[3], v[3];
        cross3(b, a[1], u);
        cross3(a[0], b, v);
        x[0] = dot3(u, n) / nn;
        x[1] = dot3(v, n) / nn;
        return true;
    }
    double det = dot3(n, a[2]);
    if (!(det * det > tol2 * nn)) return false; // R33² = det²/|a1×a2|²
    double c23[3], c31[3];
    cross3(a[1], a[2], c23);
    cross3(a[2], a[0], c31);
    x[0] = dot3(b, c23) / det;
    x[1] = dot3(b, c31) / det;
    x[2] = dot3(b, n) / det;
    return true;
}

// x = M b along the sweep, with the Jacobian blocks of the last evaluation. False when a
// loop's block is rank deficient (then the sparse factorization takes over).
#define ORI_KIN_SWEEP_AHEAD 8
static bool sweep_solve(kin_solver *s, const double *b, double *x)
{
    const double *blocks = s->blocks;
    for (int k = 0; k < s->sweep_count; ++k) {
        int rows = s->sweep_rows[k], row0 = s->sweep_row0[k];
        if (k + ORI_KIN_SWEEP_AHEAD < s->sweep_count) {
            // The loop a few steps ahead: its blocks and right-hand side (sweep order is not
            // memory order, so the hardware prefetcher cannot guess them).
            int ka = k + ORI_KIN_SWEEP_AHEAD;
            const double *ba = blocks + 6 * (size_t)s->sweep_new_blk[s->sweep_first[ka]];
            __builtin_prefetch(ba);
            __builtin_prefetch(ba + 8);
            __builtin_prefetch(ba + 16);
            __builtin_prefetch(b + s->sweep_row0[ka]);
        }
        double rhs[6], y[6];
        for (int q = 0; q < rows; ++q) rhs[q] = b[row0 + q];
        for (int t = s->sweep_kfirst[k]; t < s->sweep_kfirst[k + 1]; ++t) {
            const double *bc = blocks + 6 * (size_t)s->sweep_known_blk[t];
            double xc = x[s->sweep_known_x[t]];
            for (int q = 0; q < rows; ++q) rhs[q] -= bc[q] * xc;
        }
        int n = s->sweep_first[k + 1] - s->sweep_first[k];
        const int *nb = s->sweep_new_blk + s->sweep_first[k];
        const int *nx = s->sweep_new_x + s->sweep_first[k];
        bool ok;
        if (rows == 3) {
            const double *a[3] = {blocks + 6 * (size_t)nb[0], n > 1 ? blocks + 6 * (size_t)nb[1] : NULL,
                                  n > 2 ? blocks + 6 * (size_t)nb[2] : NULL};
            ok = vertex_lsq(a, n, rhs, y);
        } else {
            double a[36];
            for (int t = 0; t < n; ++t)
                for (int q = 0; q < rows; ++q) a[q + rows * t] = blocks[6 * (size_t)nb[t] + q];
            ok = small_lsq(a, rows, n, rhs, y);
        }
        if (!ok) return false;
        for (int t = 0; t < n; ++t) {
            if (!isfinite(y[t])) return false;
            x[nx[t]] = y[t];
        }
    }
    return true;
}

// Corrector by the sweep: θ ← θ − M r(θ) until every loop closes to ORI_TOL_NEWTON. False,
// with th at the best state met, when a step does not reduce the residual at least by
// ORI_KIN_SWEEP_RATE (Newton near the solution does far better: a round-off floor above
// ORI_TOL_NEWTON, or a linear crawl, goes to least squares), a block is singular, or the budget
// runs out.
static bool sweep_correct(kin_solver *s, double *th, int max_iter, int *iterations, double *residual)
{
    const ori_mechanism *m = s->m;
    double prev = INFINITY, best = INFINITY;
    int it = 0;
    bool ok = false;
    for (;; ++it) {
        // The first state almost always needs a step: residual and Jacobian in one pass.
        double r = it == 0 ? evaluate(s, th) : residual_at(s, th);
        if (r <= ORI_TOL_NEWTON) {
            ok = true;
            *residual = r;
            break;
        }
        if (!(r <= ORI_KIN_SWEEP_RATE * prev) || it >= max_iter) break;
        if (r < best) {
            best = r;
            memcpy(s->best, th, sizeof(double) * (size_t)m->joint_count);
        }
        prev = r;
        evaluate(s, th);
        for (int k = 0; k < s->rows; ++k) s->neg[k] = -s->res[k];
        if (!sweep_solve(s, s->neg, s->step)) break;
        for (int k = 0; k < s->ncols; ++k) th[s->free_joint[k]] += s->step[k];
    }
    *iterations = it;
    if (!ok && best < INFINITY) memcpy(th, s->best, sizeof(double) * (size_t)m->joint_count);
    return ok;
}

// Whether the state closed to ORI_TOL_NEWTON is also that close in the angles (dense path): a
// solve of this corrector call measured σ_min of J_F, and |r|₂ / σ_min ≤ ORI_TOL_NEWTON_STATE_RAD.
static bool settled(const kin_solver *s)
{
    if (s->sv_call != s->calls || !(s->sv_min > 0.0)) return false;
    double rr = 0.0;
    for (int k = 0; k < s->rows; ++k) rr += s->res[k] * s->res[k];
    return sqrt(rr) <= ORI_TOL_NEWTON_STATE_RAD * s->sv_min;
}

int ori__kin_solver_polish_iterations(const kin_solver *s) { return s->polish_iterations; }

bool ori__kin_correct(kin_solver *s, double *th, int max_iter, int *iterations, double *residual)
{
    double r0 = 0.0, prev = INFINITY;
    bool converged = false;
    int it = 0, it_sweep = 0;
    double *step = s->step, *neg = s->neg;
    const int *free_joint = s->free_joint;
    double r = INFINITY;
    bool step_fresh = true;
    bool polishing = false; // the last step started from a state within ORI_TOL_NEWTON
    s->calls++;
    s->polish_iterations = 0;
    if (s->sweep && s->calls >= s->sweep_retry_at) {
        bool ok = sweep_correct(s, th, max_iter, &it_sweep, &r);
        s->sweep_iterations += it_sweep;
        if (ok) {
            *iterations = it_sweep;
            *residual = r;
            return true;
        }
        // Unstable or singular here: the least-squares corrector goes on from the best state
        // the sweep reached, and the sweep rests for a few calls.
        s->sweep_retry_at = s->calls + ORI_KIN_SWEEP_RETRY;
    }
    // Retry an old factor now and then: conditioning improves away from the flat state.
    if (s->sparse && !s->stale_ok && s->calls % ORI_KIN_STALE_RETRY != 0) s->refactor = true;
    for (;; ++it) {
        // The first state of a call almost always needs a Newton step: evaluate everything at
        // once. Later states are checked first and differentiated only if not converged.
        r = it == 0 ? evaluate(s, th) : residual_at(s, th);
        if (it == 0) r0 = r;
        // Dense: the residual bounds the state's error only through σ_min of J_F (the error is
        // about |r|₂ / σ_min: 7.4e-14 / 2e-3, 1.1e-9°, on a degree-8 vertex with nearly coplanar
        // free creases). Within ORI_TOL_NEWTON it polishes on while that exceeds
        // ORI_TOL_NEWTON_STATE_RAD and a step still at least halves the residual (the round-off
        // floor ends it); a polish step that made it worse is undone.
        if (polishing && !(r <= 0.5 * prev)) {
            if (r > prev) {
                for (int k = 0; k < s->ncols; ++k) th[free_joint[k]] -= step[k];
                r = residual_at(s, th);
            }
            converged = true;
            break;
        }
        if (r <= ORI_TOL_NEWTON) {
            if (s->sparse || s->ncols == 0 || settled(s) || it >= max_iter) {
                converged = true;
                break;
            }
            polishing = true;
            s->polish_iterations++;
            prev = r;
            evaluate(s, th);
            for (int k = 0; k < s->rows; ++k) neg[k] = -s->res[k];
            if (!dense_solve(s, neg, step)) {
                converged = true;
                break;
            }
            for (int k = 0; k < s->ncols; ++k) th[free_joint[k]] += step[k];
            continue;
        }
        if (it > 0 && r <= ORI_TOL_RESIDUAL && r > 0.5 * prev) {
            converged = true; // round-off floor reached
            break;
        }
        if (!isfinite(r)) break;
        if (it > 0 && !step_fresh) {
            // A chord step (old factor) that contracted too slowly: renew the factor. A chord
            // iteration costs a fraction of a factorization, so above ORI_KIN_CHORD_RATE the
            // remaining chord steps would cost more than one Newton step. One that made things
            // worse is undone.
            if (it == 1) s->stale_ok = r <= ORI_KIN_CHORD_RATE * prev;
            if (r > ORI_KIN_CHORD_RATE * prev) s->refactor = true;
            if (r > prev) {
                for (int k = 0; k < s->ncols; ++k) th[free_joint[k]] -= step[k];
                r = residual_at(s, th);
            }
        } else if (it > 0 && (r > ORI_KIN_GROWTH_STEP * prev || r > ORI_KIN_GROWTH_TOTAL * r0)) {
            break; // a Newton step must not grow the residual
        }
        if (it >= max_iter || s->ncols == 0) break;
        prev = r;
        evaluate(s, th);
        for (int k = 0; k < s->rows; ++k) neg[k] = -s->res[k];
        bool ok = s->sparse ? sparse_step(s, neg, step, false) : dense_solve(s, neg, step);
        step_fresh = !s->sparse || s->fresh;
        if (!ok) break;
        for (int k = 0; k < s->ncols; ++k) th[free_joint[k]] += step[k];
    }
    if (s->sparse && !converged) s->refactor = true;
    *iterations = it + it_sweep;
    *residual = r;
    return converged || r <= ORI_TOL_RESIDUAL;
}

// Joint-space tangent from the free columns' solution x (drive 1, fixed joints 0).
static void tangent_from(const kin_solver *s, const double *x, double *t)
{
    for (int j = 0; j < s->m->joint_count; ++j) {
        int c = s->col[j];
        t[j] = j == s->drive ? 1.0 : c >= 0 ? x[c] : 0.0;
    }
}

bool ori__kin_tangent(kin_solver *s, const double *th, double *t)
{
    evaluate(s, th);
    double *neg = ori__alloc(sizeof(double) * ((size_t)s->rows + 1));
    double *x = ori__alloc(sizeof(double) * ((size_t)s->ncols + 1));
    for (int k = 0; k < s->rows; ++k) neg[k] = -s->jd[k];
    // The sweep solves J_F t_F = −J_drive exactly when that system is consistent (a regular
    // state); it is kept when every loop, checked ones included, agrees to ORI_TOL_CONE_REL
    // (the defect the start test applies). Otherwise least squares, and near a flat state the
    // normal matrix is badly conditioned and a factor of even a very close state gives a
    // visibly different tangent: always factor at th itself.
    bool ok = s->ncols == 0;
    if (!ok && s->sweep && sweep_solve(s, neg, x)) {
        tangent_from(s, x, t);
        ok = ori__kin_tangent_defect(s, th, t) <= ORI_TOL_CONE_REL;
    }
    if (!ok) ok = s->sparse ? sparse_step(s, neg, x, true) : dense_solve(s, neg, x);
    if (ok) tangent_from(s, x, t);
    ori__free(neg);
    ori__free(x);
    return ok;
}

double ori__kin_tangent_defect(kin_solver *s, const double *th, const double *t)
{
    const ori_mechanism *m = s->m;
    evaluate(s, th);
    double worst = 0.0, scale = 0.0;
    for (int l = 0; l < m->loop_count; ++l) {
        const kin_loop *L = &m->loops[l];
        for (int q = 0; q < L->rows; ++q) {
            double acc = 0.0;
            for (int c = 0; c < L->col_count; ++c) {
                int j = m->loop_cols[L->col_first + c];
                acc += s->blocks[6 * (L->col_first + c) + q] * t[j];
            }
            worst = fmax(worst, fabs(acc));
            scale = fmax(scale, fabs(s->jd[L->row0 + q]));
        }
    }
    return scale > 0.0 ? worst / scale : worst;
}

int ori__kin_solver_nullity(kin_solver *s, const double *th)
{
    evaluate(s, th);
    if (s->ncols == 0) return 0;
    if (!s->sparse) {
        double *a = ori__alloc(sizeof(double) * ((size_t)s->rows * (size_t)s->ncols + 1));
        for (size_t k = 0; k < (size_t)s->rows * (size_t)s->ncols; ++k) a[k] = s->a[k];
        double smax, scut;
        int rank = ori__dense_rank(a, s->rows, s->ncols, ORI_TOL_RANK_REL, &smax, &scut);
        ori__free(a);
        return rank < 0 ? 0 : s->ncols - rank;
    }
    // Sparse: JᵀJ at th not positive definite, or its Cholesky diagonal ratio (≈ σ_min/σ_max
    // of J) below ORI_TOL_RANK_REL_SPARSE, counts as rank deficient.
    if (!factor_assembled(s, assemble_normal(s))) return 1;
    if (s->factor_damped) return 1;
    return ori__sls_rcond(s->sls) < ORI_TOL_RANK_REL_SPARSE ? 1 : 0;
}
