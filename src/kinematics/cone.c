// Branch analysis at a singular start (above all the flat state, where every vertex's axes are
// coplanar and first-order analysis admits motions that do not exist).
//
// Loop closure to second order (Baker–Campbell–Hausdorff): for a loop with spatial twists ξ_i
// at the start state, log Π exp(ξ_i v_i t) = t Σ v_i ξ_i + ½ t² Σ_{i<j} v_i v_j [ξ_i, ξ_j] + O(t³).
// A tangent v of a real motion therefore satisfies the linear equations B v = 0 and, for every
// left null vector n of B (a direction the loop cannot correct at first order, e.g. the normal
// of a flat vertex), the quadratic condition q_n(v) = ½ Σ_{i<j} v_i v_j n·[ξ_i, ξ_j] = 0.
//
// Per loop this is resolved exactly where possible: with d = 2 local first-order freedoms and
// one quadratic (every degree-4 vertex, and a degree-5 vertex with one crease locked) the cone
// is the zero set of a 2×2 quadratic form: two lines (the two branches crossing at the flat
// state; for flat-foldable vertices the fold-angle multiplier relations of Evans et al. 2015),
// one double line, none (the vertex is locally rigid) or the whole plane. Choosing a line per
// vertex turns the cone into linear equations; the MV assignment picks the line whose signs it
// admits. Loops with more freedom keep their quadratic equations, solved with the linear ones
// by Gauss–Newton from a seed whose signs follow the assignment. When the preferred choice has
// no solution, other line combinations are enumerated (bounded) to tell an invalid assignment
// (a motion exists but folds a crease the wrong way) from a rigid pattern (no motion at all).
//
// A fully folded start (moving creases at 0 or ±π: every face in one plane, stacked) is the same
// kind of singular point; the expansion holds at any state. There a crease at ±π can only turn
// toward 0: it counts as assigned −sign θ (θ − π sign θ folds from 0 that way), and a line that
// turns it outward is infeasible.
#include <lapacke.h>
#include <math.h>

#include "kinematics_internal.h"

typedef struct lin_row {
    int first, count; // terms[first .. first+count)
    double drive;     // coefficient of the drive (moved to the right-hand side with the sign)
} lin_row;

typedef struct term {
    int col;
    double coef;
} term;

typedef struct quad {
    int first, count;  // local movable joints: qjoint[first .. first+count)
    int s_first;       // S (count × count, row-major) at qs[s_first ..]
} quad;

typedef struct choice {
    int joint_first, count; // local movable joints (cjoint[])
    int dir_first;          // two directions, count entries each (cdir[])
    int preferred;          // 0 or 1
    int score[2];           // assignment score of each line (best orientation; see line_score)
    bool full[2];           // the line folds every assigned crease of the loop, each as assigned
} choice;

typedef struct cone_sys {
    const ori_mechanism *m;
    const double *th; // the start state
    const int *col;
    int ncols, drive;
    double sign;
    // linear rows (fixed part)
    lin_row *rows;
    int nrows, rows_cap;
    term *terms;
    int nterms, terms_cap;
    // quadratics
    quad *quads;
    int nquads, quads_cap;
    int *qjoint;
    int nqjoint, qjoint_cap;
    double *qs;
    int nqs, qs_cap;
    // per-loop line choices
    choice *choices;
    int nchoices, choices_cap;
    int *cjoint;
    int ncjoint, cjoint_cap;
    double *cdir;
    int ncdir, cdir_cap;
} cone_sys;

static void add_row(cone_sys *c, const int *joints, const double *coefs, int k)
{
    lin_row r;
    r.first = c->nterms;
    r.count = 0;
    r.drive = 0.0;
    for (int i = 0; i < k; ++i) {
        if (coefs[i] == 0.0) continue;
        int j = joints[i];
        if (j == c->drive) {
            r.drive += coefs[i];
        } else if (c->col[j] >= 0) {
            term t = {c->col[j], coefs[i]};
            ORI__PUSH(c->terms, c->nterms, c->terms_cap, t);
            r.count++;
        }
    }
    ORI__PUSH(c->rows, c->nrows, c->rows_cap, r);
}

// 2×2 symmetric eigen-decomposition: values ascending, unit vectors.
static void eig2(const double m[4], double lam[2], double vec[2][2])
{
    double a = m[0], b = 0.5 * (m[1] + m[2]), d = m[3];
    double tr = 0.5 * (a + d), df = 0.5 * (a - d);
    double r = hypot(df, b);
    lam[0] = tr - r;
    lam[1] = tr + r;
    // Eigenvector of the larger eigenvalue: angle φ with tan 2φ = 2b/(a − d).
    double phi = 0.5 * atan2(2.0 * b, a - d);
    vec[1][0] = cos(phi);
    vec[1][1] = sin(phi);
    vec[0][0] = -sin(phi);
    vec[0][1] = cos(phi);
}

static int assigned_sign(const ori_mechanism *m, int joint)
{
    ori_assignment a = m->joints[joint].assignment;
    return a == ORI_ASSIGN_VALLEY ? 1 : a == ORI_ASSIGN_MOUNTAIN ? -1 : 0;
}

// Whether the joint is at ±π at the start (fully folded: it can only move toward 0).
static bool at_limit(const cone_sys *c, int joint) { return fabs(c->th[joint]) >= ORI_PI - ORI_TOL_KIN_FOLDED_RAD; }

// The direction a crease's velocity must take from the start: away from 0 as assigned for a
// crease short of ±π (0 = either); toward 0 for a crease at ±π, whatever its assignment. A
// fully folded state is a flat state of the sheet with the frames of the creases at ±π flipped
// (θ' = θ − π sign θ): there the crease folds from θ' = 0 toward −sign θ, as if so assigned.
static int admitted_sign(const cone_sys *c, int joint)
{
    if (at_limit(c, joint)) return c->th[joint] > 0.0 ? -1 : 1;
    return assigned_sign(c->m, joint);
}

// Assignment score of a local direction dir (best of both orientations unless the drive fixes
// it): violations × K − agreements, K larger than any crease count. Fewer violations first, then
// the branch that folds more assigned creases in their direction (a branch leaving assigned
// creases flat — folding along one straight line through a Miura vertex — ranks below the one
// folding them all).
#define SCORE_K 100000
static int line_score(const cone_sys *c, const int *joints, const double *dir, int k, int *orient, bool *full)
{
    double big = 0.0;
    for (int i = 0; i < k; ++i) big = fmax(big, fabs(dir[i]));
    double thr = ORI_TOL_CONE_REL * big;
    int best = INT32_MAX / 2, best_o = 1;
    *full = false;
    for (int o = 1; o >= -1; o -= 2) {
        int bad = 0, good = 0, assigned = 0;
        bool feasible = true;
        for (int i = 0; i < k; ++i) {
            double x = o * dir[i];
            if (joints[i] == c->drive) {
                if (!(x * c->sign > thr)) feasible = false;
                continue;
            }
            int s = admitted_sign(c, joints[i]);
            assigned += s != 0;
            if (s == 0 || !(fabs(x) > thr)) continue;
            if (x * s < 0.0) {
                bad++;
                if (at_limit(c, joints[i])) feasible = false; // beyond ±π: no motion at all
            } else {
                good++;
            }
        }
        int score = feasible ? bad * SCORE_K - good : INT32_MAX / 4;
        if (score < best) {
            best = score;
            best_o = o;
        }
        if (feasible && bad == 0 && good == assigned) *full = true;
    }
    *orient = best_o;
    return best;
}

static void build(cone_sys *c, const double *th)
{
    const ori_mechanism *m = c->m;
    double *blocks = ori__calloc((size_t)(6 * m->loop_col_total) + 1, sizeof(double));
    ori__kin_eval(m, th, NULL, blocks, NULL);
    // Spatial twists of every entry (for the brackets), recomputed like ori__kin_eval.
    double inv_diag = 1.0 / m->diagonal;
    int maxk = 1;
    for (int l = 0; l < m->loop_count; ++l) maxk = m->loops[l].col_count > maxk ? m->loops[l].col_count : maxk;
    int *loc = ori__alloc(sizeof(int) * (size_t)maxk);         // local index of each loop column, -1 = fixed
    int *lj = ori__alloc(sizeof(int) * (size_t)maxk);          // joints of the local movable columns
    double *B = ori__alloc(sizeof(double) * (size_t)(6 * maxk)); // column-major rows × k
    double *S = ori__alloc(sizeof(double) * (size_t)(maxk * maxk));
    double *vt = ori__alloc(sizeof(double) * (size_t)(maxk * maxk));
    double *coef = ori__alloc(sizeof(double) * (size_t)maxk);
    ori_v3 *ew = ori__alloc(sizeof(ori_v3) * (size_t)(m->entry_count + 1));
    ori_v3 *ev = ori__alloc(sizeof(ori_v3) * (size_t)(m->entry_count + 1));
    for (int l = 0; l < m->loop_count; ++l) {
        const kin_loop *L = &m->loops[l];
        int k = 0;
        for (int q = 0; q < L->col_count; ++q) {
            int j = m->loop_cols[L->col_first + q];
            bool mov = j == c->drive || c->col[j] >= 0;
            loc[q] = mov ? k : -1;
            if (mov) lj[k++] = j;
        }
        if (k == 0) continue;
        int rows = L->rows;
        for (int q = 0; q < L->col_count; ++q) {
            if (loc[q] < 0) continue;
            for (int r = 0; r < rows; ++r) B[r + rows * loc[q]] = blocks[6 * (L->col_first + q) + r];
        }
        // Linear rows: the loop's first-order equations.
        for (int r = 0; r < rows; ++r) {
            for (int i = 0; i < k; ++i) coef[i] = B[r + rows * i];
            add_row(c, lj, coef, k);
        }
        // SVD of B (rows × k): rank, left and right null spaces.
        double sv[6], u[36], superb[6];
        double *bc = ori__alloc(sizeof(double) * (size_t)(rows * k));
        for (int i = 0; i < rows * k; ++i) bc[i] = B[i];
        lapack_int info = LAPACKE_dgesvd(LAPACK_COL_MAJOR, 'A', 'A', rows, k, bc, rows, sv, u, rows, vt, k, superb);
        ori__free(bc);
        if (info != 0) continue;
        int ns = rows < k ? rows : k;
        double smax = ns > 0 ? sv[0] : 0.0;
        int rank = 0;
        for (int i = 0; i < ns; ++i)
            if (sv[i] > ORI_TOL_RANK_REL * (smax > 1.0 ? smax : 1.0)) rank++;
        if (rank == rows) continue; // regular loop: first order decides
        // Spatial twists of the loop's entries at th.
        ori_rigid P = ori_rigid_identity();
        for (int i = 0; i < L->count; ++i) {
            const kin_entry *en = &m->entries[L->first + i];
            ew[i] = ori_m3_apply(P.r, en->axis);
            ev[i] = rows == 6 ? ori_v3_scale(ori_v3_cross(ori_rigid_apply(P, en->point), ew[i]), inv_diag)
                              : ori_v3_make(0, 0, 0);
            if (rows == 3) {
                P.r = ori_m3_mul(P.r, ori_m3_rotation(en->axis, th[en->joint]));
            } else {
                ori_twist xi = ori_twist_from_axis(en->point, en->axis);
                P = ori_rigid_compose(P, ori_twist_exp(xi, th[en->joint]));
            }
        }
        int d = k - rank; // local first-order freedom (right null space: columns rank.. of V)
        for (int nn = rank; nn < rows; ++nn) {
            double n6[6];
            for (int r = 0; r < 6; ++r) n6[r] = r < rows ? u[r + rows * nn] : 0.0;
            for (int i = 0; i < k * k; ++i) S[i] = 0.0;
            double smag = 0.0;
            for (int a = 0; a < L->count; ++a) {
                const kin_entry *ea = &m->entries[L->first + a];
                int ka = loc[ea->col];
                if (ka < 0) continue;
                for (int b = a + 1; b < L->count; ++b) {
                    const kin_entry *eb = &m->entries[L->first + b];
                    int kb = loc[eb->col];
                    if (kb < 0) continue;
                    double val;
                    ori_v3 ww = ori_v3_cross(ew[a], ew[b]);
                    if (rows == 3) {
                        val = n6[0] * ww.x + n6[1] * ww.y + n6[2] * ww.z;
                    } else {
                        ori_v3 vv = ori_v3_sub(ori_v3_cross(ew[a], ev[b]), ori_v3_cross(ew[b], ev[a]));
                        val = n6[0] * vv.x + n6[1] * vv.y + n6[2] * vv.z + n6[3] * ww.x + n6[4] * ww.y + n6[5] * ww.z;
                    }
                    if (ka == kb) {
                        S[ka * k + ka] += 0.5 * val;
                    } else {
                        S[ka * k + kb] += 0.25 * val;
                        S[kb * k + ka] += 0.25 * val;
                    }
                    smag = fmax(smag, fabs(val));
                }
            }
            double thr = ORI_TOL_CONE_REL * (smag > 0.0 ? smag : 1.0);
            bool single = rows - rank == 1;
            if (single && d <= 2) {
                // Restrict to the local null space N (k × d): M = Nᵀ S N.
                double M[4] = {0, 0, 0, 0};
                double N[2][64];
                int dd = d;
                for (int a = 0; a < dd; ++a)
                    for (int i = 0; i < k && i < 64; ++i) N[a][i] = vt[(rank + a) + k * i];
                if (k > 64) goto keep_quadratic;
                for (int a = 0; a < dd; ++a)
                    for (int b = 0; b < dd; ++b) {
                        double x = 0.0;
                        for (int i = 0; i < k; ++i)
                            for (int jx = 0; jx < k; ++jx) x += N[a][i] * S[i * k + jx] * N[b][jx];
                        M[a * 2 + b] = x;
                    }
                if (dd == 0) continue;
                if (dd == 1) {
                    if (fabs(M[0]) > thr) {
                        // The only first-order motion violates second order: locally rigid.
                        for (int i = 0; i < k; ++i) {
                            for (int q = 0; q < k; ++q) coef[q] = q == i ? 1.0 : 0.0;
                            add_row(c, lj, coef, k);
                        }
                    }
                    continue;
                }
                double lam[2], ev2[2][2];
                eig2(M, lam, ev2);
                double dirs[2][64];
                int nlines;
                if (fabs(lam[0]) <= thr && fabs(lam[1]) <= thr) {
                    continue; // the whole plane: second order does not restrict
                } else if (lam[0] > thr || lam[1] < -thr) {
                    for (int i = 0; i < k; ++i) {
                        for (int q = 0; q < k; ++q) coef[q] = q == i ? 1.0 : 0.0;
                        add_row(c, lj, coef, k);
                    }
                    continue;
                } else if (fabs(lam[0]) <= thr || fabs(lam[1]) <= thr) {
                    int z = fabs(lam[0]) <= thr ? 0 : 1;
                    for (int i = 0; i < k; ++i) dirs[0][i] = ev2[z][0] * N[0][i] + ev2[z][1] * N[1][i];
                    nlines = 1;
                } else {
                    double a0 = sqrt(lam[1]), a1 = sqrt(-lam[0]);
                    for (int s = 0; s < 2; ++s) {
                        double y0 = a0 * ev2[0][0] + (s == 0 ? 1 : -1) * a1 * ev2[1][0];
                        double y1 = a0 * ev2[0][1] + (s == 0 ? 1 : -1) * a1 * ev2[1][1];
                        double nrm = hypot(y0, y1);
                        for (int i = 0; i < k; ++i) dirs[s][i] = (y0 * N[0][i] + y1 * N[1][i]) / nrm;
                    }
                    nlines = 2;
                }
                choice ch;
                ch.joint_first = c->ncjoint;
                ch.count = k;
                ch.dir_first = c->ncdir;
                for (int i = 0; i < k; ++i) ORI__PUSH(c->cjoint, c->ncjoint, c->cjoint_cap, lj[i]);
                for (int s = 0; s < 2; ++s)
                    for (int i = 0; i < k; ++i) ORI__PUSH(c->cdir, c->ncdir, c->cdir_cap, dirs[nlines == 2 ? s : 0][i]);
                int o;
                ch.full[1] = false;
                ch.score[0] = line_score(c, lj, dirs[0], k, &o, &ch.full[0]);
                ch.score[1] = nlines == 2 ? line_score(c, lj, dirs[1], k, &o, &ch.full[1]) : INT32_MAX / 2;
                ch.preferred = ch.full[1] != ch.full[0] ? (ch.full[1] ? 1 : 0) : ch.score[1] < ch.score[0] ? 1 : 0;
                ORI__PUSH(c->choices, c->nchoices, c->choices_cap, ch);
                continue;
            }
        keep_quadratic:;
            quad qd;
            qd.first = c->nqjoint;
            qd.count = k;
            qd.s_first = c->nqs;
            for (int i = 0; i < k; ++i) ORI__PUSH(c->qjoint, c->nqjoint, c->qjoint_cap, lj[i]);
            for (int i = 0; i < k * k; ++i) ORI__PUSH(c->qs, c->nqs, c->qs_cap, S[i]);
            ORI__PUSH(c->quads, c->nquads, c->quads_cap, qd);
        }
    }
    ori__free(blocks);
    ori__free(loc);
    ori__free(lj);
    ori__free(B);
    ori__free(S);
    ori__free(vt);
    ori__free(coef);
    ori__free(ew);
    ori__free(ev);
}

static void free_sys(cone_sys *c)
{
    ori__free(c->rows);
    ori__free(c->terms);
    ori__free(c->quads);
    ori__free(c->qjoint);
    ori__free(c->qs);
    ori__free(c->choices);
    ori__free(c->cjoint);
    ori__free(c->cdir);
}

// --- Gauss–Newton on [linear rows; line rows; quadratics] ----------------------------------

// The equations of one line choice in compressed form: equation e touches the free columns
// col[ptr[e] .. ptr[e+1]) (sorted, distinct); eval fills residuals g and derivatives val.
typedef struct eqset {
    int m, n;
    int *ptr, *col;
    double *val, *g;
} eqset;

static double value_of(const cone_sys *c, const double *x, int joint)
{
    if (joint == c->drive) return c->sign;
    int col = c->col[joint];
    return col >= 0 ? x[col] : 0.0;
}

static int free_col(const cone_sys *c, int joint) { return joint == c->drive ? -1 : c->col[joint]; }

// Append the sorted distinct free columns of a joint list as one equation's pattern.
static void push_pattern(eqset *E, int *cap, const cone_sys *c, const int *joints, const int *cols, int k)
{
    int start = E->ptr[E->m], cur = start;
    for (int i = 0; i < k; ++i) {
        int col = cols ? cols[i] : free_col(c, joints[i]);
        if (col < 0) continue;
        bool exists = false;
        for (int q = start; q < cur; ++q) exists |= E->col[q] == col;
        if (exists) continue;
        ORI__RESERVE(E->col, *cap, cur + 1);
        int t = cur;
        while (t > start && E->col[t - 1] > col) {
            E->col[t] = E->col[t - 1];
            t--;
        }
        E->col[t] = col;
        cur++;
    }
    E->ptr[E->m + 1] = cur;
    E->m++;
}

static void eq_build(const cone_sys *c, const int *pick, eqset *E)
{
    int m = c->nrows + c->nquads;
    for (int h = 0; h < c->nchoices; ++h) m += c->choices[h].count;
    E->n = c->ncols;
    E->m = 0;
    E->ptr = ori__calloc((size_t)m + 2, sizeof(int));
    E->col = NULL;
    int cap = 0;
    int *cols = NULL, ccap = 0;
    for (int r = 0; r < c->nrows; ++r) {
        ORI__RESERVE(cols, ccap, c->rows[r].count + 1);
        for (int t = 0; t < c->rows[r].count; ++t) cols[t] = c->terms[c->rows[r].first + t].col;
        push_pattern(E, &cap, c, NULL, cols, c->rows[r].count);
    }
    for (int h = 0; h < c->nchoices; ++h)
        for (int i = 0; i < c->choices[h].count; ++i) {
                push_pattern(E, &cap, c, c->cjoint + c->choices[h].joint_first, NULL, c->choices[h].count);
        }
    for (int q = 0; q < c->nquads; ++q) {
        push_pattern(E, &cap, c, c->qjoint + c->quads[q].first, NULL, c->quads[q].count);
    }
    ori__free(cols);
    if (!E->col) E->col = ori__alloc(sizeof(int));
    E->val = ori__calloc((size_t)E->ptr[E->m] + 1, sizeof(double));
    E->g = ori__calloc((size_t)E->m + 1, sizeof(double));
    (void)pick;
}

static void eq_free(eqset *E)
{
    ori__free(E->ptr);
    ori__free(E->col);
    ori__free(E->val);
    ori__free(E->g);
}

static void add_deriv(eqset *E, int e, int col, double d)
{
    if (col < 0) return;
    for (int q = E->ptr[e]; q < E->ptr[e + 1]; ++q)
        if (E->col[q] == col) {
            E->val[q] += d;
            return;
        }
}

// Residuals (and derivatives when deriv) at x; returns the residual max-norm.
static double eq_eval(const cone_sys *c, const int *pick, const double *x, eqset *E, bool deriv)
{
    if (deriv)
        for (int q = 0; q < E->ptr[E->m]; ++q) E->val[q] = 0.0;
    int e = 0;
    double worst = 0.0;
    for (int r = 0; r < c->nrows; ++r, ++e) {
        const lin_row *R = &c->rows[r];
        double s = R->drive * c->sign;
        for (int t = 0; t < R->count; ++t) {
            const term *T = &c->terms[R->first + t];
            s += T->coef * x[T->col];
            if (deriv) add_deriv(E, e, T->col, T->coef);
        }
        E->g[e] = s;
    }
    for (int h = 0; h < c->nchoices; ++h) {
        const choice *ch = &c->choices[h];
        const double *d = c->cdir + ch->dir_first + (size_t)pick[h] * ch->count;
        const int *js = c->cjoint + ch->joint_first;
        double dot = 0.0;
        for (int i = 0; i < ch->count; ++i) dot += d[i] * value_of(c, x, js[i]);
        for (int i = 0; i < ch->count; ++i, ++e) {
            E->g[e] = value_of(c, x, js[i]) - d[i] * dot;
            if (deriv)
                for (int k = 0; k < ch->count; ++k) add_deriv(E, e, free_col(c, js[k]), (i == k ? 1.0 : 0.0) - d[i] * d[k]);
        }
    }
    for (int q = 0; q < c->nquads; ++q, ++e) {
        const quad *Q = &c->quads[q];
        const double *S = c->qs + Q->s_first;
        const int *js = c->qjoint + Q->first;
        double s = 0.0;
        for (int i = 0; i < Q->count; ++i) {
            double sy = 0.0;
            for (int k = 0; k < Q->count; ++k) sy += S[i * Q->count + k] * value_of(c, x, js[k]);
            s += value_of(c, x, js[i]) * sy;
            if (deriv) add_deriv(E, e, free_col(c, js[i]), 2.0 * sy);
        }
        E->g[e] = s;
    }
    for (int k = 0; k < E->m; ++k) worst = fmax(worst, fabs(E->g[k]));
    return isfinite(worst) ? worst : INFINITY;
}

typedef struct lsq {
    bool dense;
    double *jac, *rhs, *sv;
    kin_sls *sls;
    int factor_state; // sparse: 0 none, 1 a factor of JᵀJ (λ = 0), 2 of JᵀJ + λI, for the values in sls
} lsq;

// Copy the equations' derivatives into the sparse object; false when they equal the values
// already there (the factor, if any, still applies: the line and linear rows of the cone never
// change, so on a pattern of degree-4 vertices one factorization serves every iteration).
static bool lsq_load(lsq *L, const eqset *E)
{
    double *v = ori__sls_values(L->sls);
    int nnz = E->ptr[E->m];
    bool same = L->factor_state != 0;
    for (int q = 0; q < nnz && same; ++q) same = v[q] == E->val[q];
    if (same) return false;
    for (int q = 0; q < nnz; ++q) v[q] = E->val[q];
    L->factor_state = 0;
    return true;
}

// Dense (minimum-norm SVD steps, exact nullity) for small systems; a probe, which needs neither
// the minimum norm nor the nullity, goes sparse above ORI_MOTION_DENSE_MAX_UNKNOWNS (an SVD per
// Gauss–Newton iteration made the probe of a few hundred creases take seconds per try).
static void lsq_init(lsq *L, const eqset *E, bool probe)
{
    int m = E->m, n = E->n;
    L->dense = (!probe && (size_t)m * (size_t)n <= (size_t)ORI_DOF_DENSE_MAX_ENTRIES / 4) ||
               n <= ORI_MOTION_DENSE_MAX_UNKNOWNS;
    L->jac = L->rhs = L->sv = NULL;
    L->sls = NULL;
    L->factor_state = 0;
    if (L->dense) {
        L->jac = ori__alloc(sizeof(double) * ((size_t)m * (size_t)n + 1));
        L->rhs = ori__alloc(sizeof(double) * ((size_t)(m > n ? m : n) + 1));
        L->sv = ori__alloc(sizeof(double) * ((size_t)(m < n ? m : n) + 1));
    } else {
        L->sls = ori__sls_create(n, m, E->ptr, E->col);
    }
}

static void lsq_free(lsq *L)
{
    ori__free(L->jac);
    ori__free(L->rhs);
    ori__free(L->sv);
    ori__sls_destroy(L->sls);
}

// Least-squares step: minimise |J dx + g|; minimum norm (dense) or lightly damped (sparse).
static bool lsq_step(lsq *L, const eqset *E, double *dx)
{
    int m = E->m, n = E->n;
    if (L->dense) {
        for (size_t k = 0; k < (size_t)m * (size_t)n; ++k) L->jac[k] = 0.0;
        for (int e = 0; e < m; ++e)
            for (int q = E->ptr[e]; q < E->ptr[e + 1]; ++q) L->jac[e + (size_t)m * E->col[q]] += E->val[q];
        int ld = m > n ? m : n;
        for (int k = 0; k < ld; ++k) L->rhs[k] = k < m ? -E->g[k] : 0.0;
        int rank;
        lapack_int info = LAPACKE_dgelsd(LAPACK_COL_MAJOR, m, n, 1, L->jac, m > 0 ? m : 1, L->rhs, ld > 0 ? ld : 1,
                                         L->sv, ORI_TOL_RANK_REL, &rank);
        if (info != 0) return false;
        for (int k = 0; k < n; ++k) dx[k] = L->rhs[k];
        return true;
    }
    if (lsq_load(L, E)) {
        double tr = 0.0;
        for (int q = 0; q < E->ptr[m]; ++q) tr += E->val[q] * E->val[q];
        if (ori__sls_factor(L->sls, 0.0)) L->factor_state = 1;
        else if (ori__sls_factor(L->sls, ORI_TOL_RANK_REL * (n > 0 ? tr / n : 1.0))) L->factor_state = 2;
        else return false;
    }
    double *neg = ori__alloc(sizeof(double) * ((size_t)m + 1));
    double *rhs = ori__alloc(sizeof(double) * ((size_t)n + 1));
    for (int e = 0; e < m; ++e) neg[e] = -E->g[e];
    ori__sls_mult_t(L->sls, neg, rhs);
    bool ok = ori__sls_solve(L->sls, rhs, dx);
    ori__free(neg);
    ori__free(rhs);
    return ok;
}

// Nullity of the equations' Jacobian at the current values (dense SVD or sparse rcond test).
static int lsq_nullity(lsq *L, const eqset *E)
{
    int m = E->m, n = E->n;
    if (n == 0) return 0;
    if (L->dense) {
        for (size_t k = 0; k < (size_t)m * (size_t)n; ++k) L->jac[k] = 0.0;
        for (int e = 0; e < m; ++e)
            for (int q = E->ptr[e]; q < E->ptr[e + 1]; ++q) L->jac[e + (size_t)m * E->col[q]] += E->val[q];
        double smax, scut;
        int rank = ori__dense_rank(L->jac, m, n, ORI_TOL_RANK_REL, &smax, &scut);
        return rank < 0 ? 0 : n - rank;
    }
    if (lsq_load(L, E) || L->factor_state != 1) {
        L->factor_state = 0;
        if (!ori__sls_factor(L->sls, 0.0)) return 1;
        L->factor_state = 1;
    }
    return ori__sls_rcond(L->sls) < ORI_TOL_RANK_REL_SPARSE ? 1 : 0;
}

// Solve the cone equations of one line choice from a seed whose signs follow the assignment.
// Returns true with x when the equations are consistent; *extra = excess freedom.
static bool solve_choice(const cone_sys *c, const int *pick, double *x, int *extra, bool probe)
{
    eqset E;
    eq_build(c, pick, &E);
    int n = E.n;
    *extra = 0;
    for (int j = 0; j < c->m->joint_count; ++j) {
        int col = c->col[j];
        if (col >= 0 && j != c->drive) x[col] = 0.5 * admitted_sign(c, j);
    }
    lsq L;
    lsq_init(&L, &E, probe);
    double *dx = ori__alloc(sizeof(double) * ((size_t)n + 1));
    double *trial = ori__alloc(sizeof(double) * ((size_t)n + 1));
    bool ok = false;
    double gn = eq_eval(c, pick, x, &E, true);
    for (int it = 0; it < 60; ++it) {
        double xs = 1.0;
        for (int k = 0; k < n; ++k) xs = fmax(xs, fabs(x[k]));
        if (gn <= ORI_TOL_CONE_REL * xs * xs) {
            ok = true;
            break;
        }
        if (n == 0 || !lsq_step(&L, &E, dx)) break;
        double t = 1.0, tn = INFINITY;
        for (int ls = 0; ls < 40; ++ls) {
            for (int k = 0; k < n; ++k) trial[k] = x[k] + t * dx[k];
            tn = eq_eval(c, pick, trial, &E, false);
            if (tn < gn) break;
            t *= 0.5;
        }
        if (!(tn < gn)) break; // no progress: inconsistent (or a local minimum)
        for (int k = 0; k < n; ++k) x[k] = trial[k];
        gn = eq_eval(c, pick, x, &E, true);
    }
    if (ok) *extra = lsq_nullity(&L, &E);
    ori__free(dx);
    ori__free(trial);
    lsq_free(&L);
    eq_free(&E);
    return ok;
}

// Global score of a tangent: violations × SCORE_K − agreements (see line_score).
static int score_of(const cone_sys *c, const double *x, int *violations)
{
    double big = fabs(c->sign);
    for (int k = 0; k < c->ncols; ++k) big = fmax(big, fabs(x[k]));
    double thr = ORI_TOL_CONE_REL * big;
    int bad = 0, good = 0;
    for (int j = 0; j < c->m->joint_count; ++j) {
        int s = admitted_sign(c, j);
        if (s == 0 || j == c->drive || c->col[j] < 0) continue;
        double v = value_of(c, x, j);
        if (!(fabs(v) > thr)) continue;
        if (v * s < 0.0) bad++;
        else good++;
    }
    *violations = bad;
    return bad * SCORE_K - good;
}

// A 3 × k matrix (column-major) whose rank is 3 for the SVD test with ORI_TOL_RANK_REL, proved
// without the SVD: for any three columns B, σ_3(A) ≥ σ_3(B) (adding columns adds to AAᵀ) and
// σ_3(B) = |det B| / (σ_1(B) σ_2(B)) ≥ 2|det B| / ‖B‖_F², while σ_1(A) ≤ ‖A‖_F. A margin of 2
// covers the rounding of these few products. False means "not proved" (the SVD decides).
static bool surely_full_rank3(const double *a, int k)
{
    if (k < 3 || k > 8) return false;
    double fa = 0.0;
    for (int i = 0; i < 3 * k; ++i) fa += a[i] * a[i];
    fa = sqrt(fa);
    for (int p = 0; p < k; ++p)
        for (int q = p + 1; q < k; ++q)
            for (int r = q + 1; r < k; ++r) {
                const double *x = a + 3 * p, *y = a + 3 * q, *z = a + 3 * r;
                double det = x[0] * (y[1] * z[2] - y[2] * z[1]) - x[1] * (y[0] * z[2] - y[2] * z[0]) +
                             x[2] * (y[0] * z[1] - y[1] * z[0]);
                double fb = 0.0;
                for (int i = 0; i < 3; ++i) fb += x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
                // 2|det B|/‖B‖_F² > 2 · ORI_TOL_RANK_REL · ‖A‖_F
                if (fabs(det) > ORI_TOL_RANK_REL * fa * fb) return true;
            }
    return false;
}

bool ori__kin_loops_deficient(const ori_mechanism *m, const double *th, const int *col_of_joint, int drive_joint)
{
    double *blocks = ori__calloc((size_t)(6 * m->loop_col_total) + 1, sizeof(double));
    ori__kin_eval(m, th, NULL, blocks, NULL);
    bool deficient = false;
    for (int l = 0; l < m->loop_count && !deficient; ++l) {
        const kin_loop *L = &m->loops[l];
        int k = 0;
        for (int q = 0; q < L->col_count; ++q) {
            int j = m->loop_cols[L->col_first + q];
            k += j == drive_joint || col_of_joint[j] >= 0;
        }
        if (k == 0) continue; // a rigid loop: nothing moves
        if (k < L->rows) {
            deficient = true;
            break;
        }
        double *a = ori__alloc(sizeof(double) * (size_t)(L->rows * k));
        int c = 0;
        for (int q = 0; q < L->col_count; ++q) {
            int j = m->loop_cols[L->col_first + q];
            if (j != drive_joint && col_of_joint[j] < 0) continue;
            for (int r = 0; r < L->rows; ++r) a[r + L->rows * c] = blocks[6 * (L->col_first + q) + r];
            c++;
        }
        if (L->rows == 3 && surely_full_rank3(a, k)) {
            ori__free(a);
            continue;
        }
        double smax, scut;
        int rank = ori__dense_rank(a, L->rows, k, ORI_TOL_RANK_REL, &smax, &scut);
        ori__free(a);
        if (rank >= 0 && rank < L->rows) deficient = true;
    }
    ori__free(blocks);
    return deficient;
}

kin_cone_result ori__kin_cone(const ori_mechanism *m, const double *th, const int *col_of_joint, int ncols,
                              int drive_joint, double sign, bool probe, double *v, int *extra_dof)
{
    return ori__kin_cone_budget(m, th, col_of_joint, ncols, drive_joint, sign, probe, v, extra_dof, NULL);
}

kin_cone_result ori__kin_cone_budget(const ori_mechanism *m, const double *th, const int *col_of_joint, int ncols,
                                     int drive_joint, double sign, bool probe, double *v, int *extra_dof,
                                     long *budget)
{
    cone_sys c;
    memset(&c, 0, sizeof c);
    c.m = m;
    c.th = th;
    c.col = col_of_joint;
    c.ncols = ncols;
    c.drive = drive_joint;
    c.sign = sign >= 0.0 ? 1.0 : -1.0;
    build(&c, th);
    *extra_dof = 0;

    int k = c.nchoices;
    int *pick = ori__calloc((size_t)k + 1, sizeof(int));
    double *x = ori__calloc((size_t)ncols + 1, sizeof(double));
    double *xbest = ori__calloc((size_t)ncols + 1, sizeof(double));
    kin_cone_result result = KIN_CONE_NONE;
    int best_score = INT32_MAX;
    // Loops that can fold as assigned on their own: a line folding every assigned crease of
    // the loop in its direction.
    bool all_local = true;
    for (int h = 0; h < k; ++h)
        if (!c.choices[h].full[0] && !c.choices[h].full[1]) all_local = false;
    // Phase A: combinations of locally admitted lines (the preferred one first). Phase B (only
    // when some loop cannot fold as assigned): every combination, for the least violating
    // motion. Large (sparse) systems try the preferred combination only.
    int flip = k < ORI_KIN_CONE_ENUMERATE_MAX ? k : ORI_KIN_CONE_ENUMERATE_MAX;
    if (ncols > ORI_MOTION_DENSE_MAX_UNKNOWNS) flip = 0;
    long combos = 1L << flip;
    bool found_consistent = false;
    bool exhausted = false;
    for (int phase = 0; phase < 2 && result != KIN_CONE_FOUND && result != KIN_CONE_UNDERDETERMINED && !exhausted;
         ++phase) {
        if (phase == 1 && all_local && !probe) break;
        if (phase == 1 && probe) break; // a probe skips nothing in phase A: phase B would repeat it
        for (long mask = 0; mask < combos; ++mask) {
            bool skip = false;
            for (int h = 0; h < k; ++h) {
                const choice *ch = &c.choices[h];
                bool flipped = h < flip && ((mask >> h) & 1);
                int line = ch->preferred ^ (flipped ? 1 : 0);
                bool exists = ch->score[line] < INT32_MAX / 2;
                if (!exists) skip = true;
                // Phase A keeps, per loop, the lines that fold it as assigned (or, lacking one,
                // the lines without violations).
                bool anyfull = ch->full[0] || ch->full[1];
                bool anyok = ch->score[0] <= 0 || ch->score[1] <= 0;
                if (phase == 0 && !probe && ((anyfull && !ch->full[line]) || (!anyfull && anyok && ch->score[line] > 0)))
                    skip = true;
                pick[h] = line;
            }
            if (skip) continue;
            if (budget && *budget <= 0) {
                exhausted = true;
                break;
            }
            if (budget) --*budget;
            int extra = 0;
            if (!solve_choice(&c, pick, x, &extra, probe)) continue;
            found_consistent = true;
            if (extra > 0 && !probe) {
                *extra_dof = extra;
                result = KIN_CONE_UNDERDETERMINED;
                for (int q = 0; q < ncols; ++q) xbest[q] = x[q];
                break;
            }
            int bad = 0;
            int score = probe ? 0 : score_of(&c, x, &bad);
            if (score < best_score) {
                best_score = score;
                for (int q = 0; q < ncols; ++q) xbest[q] = x[q];
                result = bad == 0 ? KIN_CONE_FOUND : KIN_CONE_VIOLATING;
            }
            if (probe || bad == 0) break;
        }
    }
    // Every loop could fold as assigned on its own, but no combination holds together (or
    // only with some loop reversed): the assignment is not rigidly foldable.
    if (!probe && all_local && result != KIN_CONE_FOUND && result != KIN_CONE_UNDERDETERMINED && k > 0)
        result = KIN_CONE_INCOMPATIBLE;
    // The budget ran out before a motion was found: nothing is proved.
    if (exhausted && result == KIN_CONE_NONE) result = KIN_CONE_EXHAUSTED;
    (void)found_consistent;
    for (int j = 0; j < m->joint_count; ++j) {
        int col = col_of_joint[j];
        v[j] = j == drive_joint ? c.sign : col >= 0 ? xbest[col] : 0.0;
    }
    ori__free(x);
    ori__free(xbest);
    ori__free(pick);
    free_sys(&c);
    return result;
}
