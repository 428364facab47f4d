// Regularization: the nearest exact crease pattern to a rounded drawing (include/orikin/regularize.h).
//
// Unknowns: the coordinates of the vertices that may move (interior and free vertices: x and y;
// a vertex on a straight stretch of the boundary: its position along that line; corners:
// none), scaled by the sheet's diagonal L, and, for the rigid conditions, the fold rate ρ' of
// every crease but one (which fixes the scale of the rates), scaled by their largest start value
// R. Equations per interior vertex with creases u_0 … u_{n−1} (unit directions, counter-
// clockwise; F and J edges dropped):
//   Kawasaki      K = Σ_k (−1)^k α_k = 0                     (α_k the sector from u_k to u_{k+1})
//   first order   F = Σ_k ρ̂_k u_k = 0                       (two rows: a reciprocal diagram)
//   second order  Q = Σ_{i<j} ρ̂_i ρ̂_j (u_i × u_j)·z = 0     (its signed area; the start crease
//                                                             does not matter once F = 0)
// except at a degree-4 vertex with a three-to-one assignment, where Q is replaced by the two rows
// of the mode the assignment picks (mode_of): ρ̂_a − ρ̂_b = 0, ρ̂_c + ρ̂_d = 0, the finite condition.
// Each Gauss–Newton step solves min ‖x̂ − x̂₀‖² + w‖ρ̂ − ρ̂_k‖² subject to the linearised
// equations: y = W⁻¹Aᵀλ with (A W⁻¹ Aᵀ + δI) λ = A_x (x̂_k − x̂₀) − c_k, factored by CHOLMOD
// (AAᵀ of the column-scaled A, simplicial LDLᵀ). The tiny w makes the rates cheap, so the
// coordinates move as little as the conditions allow; δ handles dependent (consistent) rows.
#include <orikin/regularize.h>

#include "../core/suitesparse.h"
#include "flat_internal.h"

#include "../pattern/pattern_internal.h"

enum { VK_FIXED = 0, VK_SLIDE = 1, VK_FREE = 2 };

typedef struct reg_vertex {
    int v;        // FOLD vertex
    int first;    // first crease in crease_nb / crease_edge
    int count;    // creases (even count gets a Kawasaki row)
    int row;      // first equation row
    int nrig;     // rigid rows: 3 (first + second order) or 4 (first order + the assigned mode)
    int eq[2];    // mode rows (nrig 4): local creases with equal rates (the pair of like assignment)
    int opp[2];   // and with opposite rates (the odd crease and the one across from it)
} reg_vertex;

// The budget shared by the attempts of one ori_regularize: the progress callback, its fraction
// (monotone over the attempts) and whether it cancelled.
typedef struct reg_budget {
    ori_progress_fn *progress;
    void *user;
    double k0, tol;  // the input's defect and the tolerance: the fraction's log scale
    double fraction; // reported so far
    bool cancelled;
} reg_budget;

typedef struct reg {
    const ori_pattern *p;
    reg_budget *budget;  // progress and cancel of the main solve (NULL: none, as in the rate pre-pass)
    bool stopped;        // the main solve ended at max_iterations still converging, or was cancelled
    int nv;
    double L, R, w_rate;
    ori_v2 *x0, *x;      // original and current coordinates (unscaled)
    int *kind;           // VK_*
    ori_v2 *slide;       // unit direction for VK_SLIDE
    int *col_x;          // first column of a vertex, or −1
    int *col_r;          // column of a crease's rate (edge-indexed), −1 when none or the fixed one
    double *rate;        // current scaled rates (edge-indexed; 0 for non-creases)
    bool *is_crease;     // edge is a rate unknown or the fixed crease
    int fixed_edge;
    reg_vertex *iv;
    int niv;
    int *crease_nb, *crease_edge;
    bool rigid;
    bool kawasaki;       // a Kawasaki row at every even interior vertex (false: rigid only)
    int ntie, tie_row;   // equalities kept (ties, their rows from tie_row on)
    struct reg_tie *ties;
    bool rates_only;     // pre-pass: coordinates held, only rates move
    bool polish;         // last steps: plain minimum-norm Newton from the current state
    int rows, cols;
    // triplets (row, col, value), in a fixed order every assembly
    int nt, ct;
    int *ti, *tj;
    double *tx;
    double *c;           // equation values
    ori_v2 *dx, *x_save; // Gauss–Newton step and the state it starts from
    double *dr, *r_save;
    double *r_start;     // the start rates (their signs are the assignment's)
} reg;

// An equality of the drawing kept exactly (within the drawing's precision it holds already):
// two sectors of an interior vertex equal, two creases of one straight line through it, or two
// edges parallel. Each angle term is the direction φ of an edge seen from one of its ends.
enum { TIE_SECTORS, TIE_STRAIGHT, TIE_PARALLEL, TIE_SIDE };
typedef struct reg_tie {
    int kind;
    int iv;    // TIE_SECTORS, TIE_STRAIGHT: the interior vertex (index into iv); TIE_SIDE: a FOLD vertex
    int i, j;  // sectors (α_i = α_j), creases (from i to j is π), edges (parallel), or the two
               // boundary neighbours of a vertex on a straight side (from i to j is π)
} reg_tie;

static void push(reg *g, int row, int col, double val)
{
    if (col < 0) return;
    if (g->nt == g->ct) {
        int nc = g->ct ? 2 * g->ct : 1024;
        g->ti = ori__realloc(g->ti, sizeof(int) * (size_t)nc);
        g->tj = ori__realloc(g->tj, sizeof(int) * (size_t)nc);
        g->tx = ori__realloc(g->tx, sizeof(double) * (size_t)nc);
        g->ct = nc;
    }
    g->ti[g->nt] = row;
    g->tj[g->nt] = col;
    g->tx[g->nt] = val;
    g->nt++;
}

// Entries of a gradient gx (∂/∂x̂ of vertex v, already scaled by L) in its columns.
static void push_vertex(reg *g, int row, int v, ori_v2 grad)
{
    if (g->rates_only) return;
    int c = g->col_x[v];
    if (c < 0) return;
    if (g->kind[v] == VK_FREE) {
        push(g, row, c, grad.x);
        push(g, row, c + 1, grad.y);
    } else {
        push(g, row, c, grad.x * g->slide[v].x + grad.y * g->slide[v].y);
    }
}

static double cross2(ori_v2 a, ori_v2 b) { return a.x * b.y - a.y * b.x; }

static void assemble_ties(reg *g);

// Assemble the equation values c and the triplets of the Jacobian at the current state. The
// column scaling W^{-1/2} is applied here (rate columns × 1/√w).
static void assemble(reg *g)
{
    g->nt = 0;
    double rs = 1.0 / sqrt(g->w_rate);
    for (int a = 0; a < g->niv; ++a) {
        const reg_vertex *V = &g->iv[a];
        int n = V->count, v = V->v, row = V->row;
        ori_v2 pv = g->x[v];
        ori_v2 d[ORI__FLAT_STACK_DEGREE], u[ORI__FLAT_STACK_DEGREE];
        double len[ORI__FLAT_STACK_DEGREE];
        ORI_ASSERT(n <= ORI__FLAT_STACK_DEGREE);
        for (int k = 0; k < n; ++k) {
            ori_v2 q = g->x[g->crease_nb[V->first + k]];
            d[k] = ori_v2_make(q.x - pv.x, q.y - pv.y);
            len[k] = sqrt(d[k].x * d[k].x + d[k].y * d[k].y);
            u[k] = ori_v2_make(d[k].x / len[k], d[k].y / len[k]);
        }
        ori_v2 gsum = {0.0, 0.0};
        if (g->kawasaki && n % 2 == 0) {
            double K = 0.0;
            for (int k = 0; k < n; ++k) {
                int k1 = (k + 1) % n;
                double al = atan2(cross2(d[k], d[k1]), d[k].x * d[k1].x + d[k].y * d[k1].y);
                if (al <= 0.0) al += 2.0 * ORI_PI;
                K += (k % 2 == 0) ? al : -al;
                double wk = (k % 2 == 0) ? -2.0 : 2.0;
                double s = wk * g->L / (len[k] * len[k]);
                ori_v2 gk = ori_v2_make(-d[k].y * s, d[k].x * s);
                push_vertex(g, row, g->crease_nb[V->first + k], gk);
                gsum.x -= gk.x;
                gsum.y -= gk.y;
            }
            push_vertex(g, row, v, gsum);
            g->c[row] = K;
            row++;
        }
        if (!g->rigid) continue;
        // First order: F = Σ ρ̂_k u_k (rows row, row + 1); second order Q (row + 2).
        ori_v2 F = {0.0, 0.0};
        for (int k = 0; k < n; ++k) {
            double r = g->rate[g->crease_edge[V->first + k]];
            F.x += r * u[k].x;
            F.y += r * u[k].y;
        }
        g->c[row] = F.x;
        g->c[row + 1] = F.y;
        double Q = 0.0;
        ori_v2 before = {0.0, 0.0};
        for (int k = 0; k < n; ++k) {
            double r = g->rate[g->crease_edge[V->first + k]];
            Q += r * cross2(before, u[k]);
            before.x += r * u[k].x;
            before.y += r * u[k].y;
        }
        bool moded = V->nrig == 4;
        if (moded) {
            // The assigned mode (see mode_of): ρ̂_a − ρ̂_b = 0 and ρ̂_c + ρ̂_d = 0.
            int ea = g->crease_edge[V->first + V->eq[0]], eb = g->crease_edge[V->first + V->eq[1]];
            int ec = g->crease_edge[V->first + V->opp[0]], ed = g->crease_edge[V->first + V->opp[1]];
            g->c[row + 2] = g->rate[ea] - g->rate[eb];
            g->c[row + 3] = g->rate[ec] + g->rate[ed];
            push(g, row + 2, g->col_r[ea], rs);
            push(g, row + 2, g->col_r[eb], -rs);
            push(g, row + 3, g->col_r[ec], rs);
            push(g, row + 3, g->col_r[ed], rs);
        } else {
            g->c[row + 2] = Q;
        }
        ori_v2 sx = {0.0, 0.0}, sy = {0.0, 0.0}, sq = {0.0, 0.0};
        ori_v2 after = F; // Σ_{j>k} ρ̂_j u_j after subtracting the prefix and u_k
        before = ori_v2_make(0.0, 0.0);
        for (int k = 0; k < n; ++k) {
            int e = g->crease_edge[V->first + k], nb = g->crease_nb[V->first + k];
            double r = g->rate[e];
            after.x -= r * u[k].x;
            after.y -= r * u[k].y;
            ori_v2 B = ori_v2_make(after.x - before.x, after.y - before.y);
            // rate columns
            if (g->col_r[e] >= 0) {
                push(g, row, g->col_r[e], u[k].x * rs);
                push(g, row + 1, g->col_r[e], u[k].y * rs);
                if (!moded) push(g, row + 2, g->col_r[e], cross2(u[k], B) * rs);
            }
            // coordinates: ∂u/∂d = (I − u uᵀ)/|d|, times L for scaled coordinates
            double s = g->L / len[k];
            double pxx = (1.0 - u[k].x * u[k].x) * s, pxy = -u[k].x * u[k].y * s, pyy = (1.0 - u[k].y * u[k].y) * s;
            // F_x = Σ r u_x: gradient wrt d = r (pxx, pxy); F_y: r (pxy, pyy)
            ori_v2 gfx = ori_v2_make(r * pxx, r * pxy), gfy = ori_v2_make(r * pxy, r * pyy);
            ori_v2 du = ori_v2_make(r * B.y, -r * B.x); // ∂Q/∂u_k
            ori_v2 gq = ori_v2_make(pxx * du.x + pxy * du.y, pxy * du.x + pyy * du.y);
            push_vertex(g, row, nb, gfx);
            push_vertex(g, row + 1, nb, gfy);
            if (!moded) push_vertex(g, row + 2, nb, gq);
            sx = ori_v2_make(sx.x - gfx.x, sx.y - gfx.y);
            sy = ori_v2_make(sy.x - gfy.x, sy.y - gfy.y);
            sq = ori_v2_make(sq.x - gq.x, sq.y - gq.y);
            before.x += r * u[k].x;
            before.y += r * u[k].y;
        }
        push_vertex(g, row, v, sx);
        push_vertex(g, row + 1, v, sy);
        if (!moded) push_vertex(g, row + 2, v, sq);
    }
    assemble_ties(g);
}

// The direction of the edge from vertex a to vertex b, with its gradient (scaled coordinates)
// pushed into row with coefficient c: ∂φ/∂b = (−d_y, d_x)/|d|², ∂φ/∂a the opposite.
static double push_direction(reg *g, int row, int a, int b, double c)
{
    ori_v2 d = ori_v2_make(g->x[b].x - g->x[a].x, g->x[b].y - g->x[a].y);
    double l2 = d.x * d.x + d.y * d.y, s = c * g->L / l2;
    ori_v2 gb = ori_v2_make(-d.y * s, d.x * s);
    push_vertex(g, row, b, gb);
    push_vertex(g, row, a, ori_v2_make(-gb.x, -gb.y));
    return atan2(d.y, d.x);
}

// An angle difference wrapped into (−π, π] (period 2π) or (−π/2, π/2] (period π: directions
// of undirected edges).
static double wrap(double a, double period)
{
    a = fmod(a, period);
    if (a > 0.5 * period) a -= period;
    if (a <= -0.5 * period) a += period;
    return a;
}

// The tie rows (after every vertex's rows): their values into c and their gradients.
static void assemble_ties(reg *g)
{
    for (int t = 0; t < g->ntie; ++t) {
        const reg_tie *T = &g->ties[t];
        int row = g->tie_row + t;
        if (T->kind == TIE_PARALLEL) {
            const ori_edge *a = &g->p->edges[T->i], *b = &g->p->edges[T->j];
            double pa = push_direction(g, row, a->v[0], a->v[1], 1.0);
            double pb = push_direction(g, row, b->v[0], b->v[1], -1.0);
            g->c[row] = wrap(pa - pb, ORI_PI);
            continue;
        }
        if (T->kind == TIE_SIDE) {
            double pi = push_direction(g, row, T->iv, T->i, -1.0), pj = push_direction(g, row, T->iv, T->j, 1.0);
            g->c[row] = wrap(pj - pi - ORI_PI, 2.0 * ORI_PI);
            continue;
        }
        const reg_vertex *V = &g->iv[T->iv];
        int n = V->count, v = V->v;
        const int *nb = g->crease_nb + V->first;
        if (T->kind == TIE_STRAIGHT) { // from crease i counter-clockwise to crease j is π
            double pi = push_direction(g, row, v, nb[T->i], -1.0), pj = push_direction(g, row, v, nb[T->j], 1.0);
            g->c[row] = wrap(pj - pi - ORI_PI, 2.0 * ORI_PI);
            continue;
        }
        // α_i − α_j with α_k = φ_{k+1} − φ_k (each sector below 2π: the wrap is exact)
        int i1 = (T->i + 1) % n, j1 = (T->j + 1) % n;
        double a1 = push_direction(g, row, v, nb[i1], 1.0), a0 = push_direction(g, row, v, nb[T->i], -1.0);
        double b1 = push_direction(g, row, v, nb[j1], -1.0), b0 = push_direction(g, row, v, nb[T->j], 1.0);
        g->c[row] = wrap(wrap(a1 - a0, 2.0 * ORI_PI) - wrap(b1 - b0, 2.0 * ORI_PI), 2.0 * ORI_PI);
    }
}

// A degree-4 vertex whose start rates (targets or assignment) have three signs alike and one
// odd (Maekawa) has two folding modes through the flat state, and the signs pick one: the two
// creases of like sign that lie across from each other fold equally (ρ_a = ρ_b) and the odd
// crease folds opposite to the one across from it (ρ_c = −ρ_d). At a flat-foldable vertex these
// two relations and the first-order closure leave that mode's line alone, and along it
// tan(ρ_c/2) / tan(ρ_a/2) stays the flat state's rate ratio (Tachi 2009; Evans, Lang, Magleby,
// Howell 2015): rates that agree at every such vertex are a finite motion, not only a
// second-order one. Sets V->eq, V->opp; false when the vertex is not of this kind.
static bool mode_of(const reg *g, reg_vertex *V)
{
    if (V->count != 4) return false;
    int sgn[4], pos = 0;
    for (int k = 0; k < 4; ++k) {
        double r = g->rate[g->crease_edge[V->first + k]];
        if (r == 0.0) return false;
        sgn[k] = r > 0.0 ? 1 : -1;
        pos += sgn[k] > 0;
    }
    if (pos != 1 && pos != 3) return false;
    int odd_sign = pos == 1 ? 1 : -1, c = 0;
    while (sgn[c] != odd_sign) ++c;
    V->opp[0] = c;
    V->opp[1] = (c + 2) % 4;
    V->eq[0] = (c + 1) % 4;
    V->eq[1] = (c + 3) % 4;
    return true;
}

// Max-norm of the equations: Kawasaki rows in radians, rigid rows scaled (rates / R).
static void defects(const reg *g, double *kaw, double *rig)
{
    *kaw = 0.0;
    *rig = 0.0;
    for (int a = 0; a < g->niv; ++a) {
        const reg_vertex *V = &g->iv[a];
        int row = V->row;
        if (g->kawasaki && V->count % 2 == 0) {
            if (fabs(g->c[row]) > *kaw) *kaw = fabs(g->c[row]);
            row++;
        }
        if (g->rigid)
            for (int k = 0; k < V->nrig; ++k)
                if (fabs(g->c[row + k]) > *rig) *rig = fabs(g->c[row + k]);
    }
    for (int t = 0; t < g->ntie; ++t) // (angles, as Kawasaki's)
        if (fabs(g->c[g->tie_row + t]) > *kaw) *kaw = fabs(g->c[g->tie_row + t]);
}

// One Gauss–Newton step (see the file comment): the change of the coordinates and rates into
// g->dx, g->dr (not applied). Returns false when the factorization fails.
static bool step(reg *g, cholmod_common *cm, cholmod_factor **L)
{
    assemble(g);
    if (g->rows == 0 || g->cols == 0) return true;
    cholmod_triplet *T = cholmod_allocate_triplet((size_t)g->rows, (size_t)g->cols, (size_t)(g->nt ? g->nt : 1), 0,
                                                  CHOLMOD_REAL, cm);
    int *Ti = T->i, *Tj = T->j;
    double *Tx = T->x;
    for (int t = 0; t < g->nt; ++t) {
        Ti[t] = g->ti[t];
        Tj[t] = g->tj[t];
        Tx[t] = g->tx[t];
    }
    T->nnz = (size_t)g->nt;
    cholmod_sparse *A = cholmod_triplet_to_sparse(T, (size_t)g->nt, cm);
    cholmod_free_triplet(&T, cm);
    if (!A) return false;
    // b = A_x (x̂_k − x̂₀) − c (coordinate columns only; the rates are anchored at the current
    // state). A's coordinate columns are unscaled (weight 1), so A (y) uses them directly.
    cholmod_dense *b = cholmod_zeros((size_t)g->rows, 1, CHOLMOD_REAL, cm);
    double *bx = b->x;
    for (int r = 0; r < g->rows; ++r) bx[r] = -g->c[r];
    if (!g->rates_only && !g->polish) {
        cholmod_dense *dx = cholmod_zeros((size_t)g->cols, 1, CHOLMOD_REAL, cm);
        double *dxx = dx->x;
        for (int v = 0; v < g->nv; ++v) {
            int c = g->col_x[v];
            if (c < 0) continue;
            double ex = (g->x[v].x - g->x0[v].x) / g->L, ey = (g->x[v].y - g->x0[v].y) / g->L;
            if (g->kind[v] == VK_FREE) {
                dxx[c] = ex;
                dxx[c + 1] = ey;
            } else {
                dxx[c] = ex * g->slide[v].x + ey * g->slide[v].y;
            }
        }
        double one[2] = {1.0, 0.0}, onep[2] = {1.0, 0.0};
        cholmod_sdmult(A, 0, one, onep, dx, b, cm); // b = A dx + b
        cholmod_free_dense(&dx, cm);
    }
    if (!*L) *L = cholmod_analyze(A, cm);
    // δ: a tiny multiple of the largest diagonal of AAᵀ, so that dependent rows do not stop the
    // factorization; the iteration converges all the same on consistent equations.
    double dmax = 0.0;
    {
        double *rowsq = ori__calloc((size_t)g->rows, sizeof(double));
        int *Ap = A->p, *Ai = A->i;
        double *Ax = A->x;
        for (int j = 0; j < g->cols; ++j)
            for (int k = Ap[j]; k < Ap[j + 1]; ++k) rowsq[Ai[k]] += Ax[k] * Ax[k];
        for (int r = 0; r < g->rows; ++r)
            if (rowsq[r] > dmax) dmax = rowsq[r];
        ori__free(rowsq);
    }
    double beta[2] = {ORI_REGULARIZE_DAMPING_REL * (dmax > 0.0 ? dmax : 1.0), 0.0};
    bool ok = cholmod_factorize_p(A, beta, NULL, 0, *L, cm) && cm->status == CHOLMOD_OK;
    if (ok) {
        cholmod_dense *lam = cholmod_solve(CHOLMOD_A, *L, b, cm);
        ok = lam != NULL;
        if (ok) {
            cholmod_dense *y = cholmod_zeros((size_t)g->cols, 1, CHOLMOD_REAL, cm);
            double one[2] = {1.0, 0.0}, zero[2] = {0.0, 0.0};
            cholmod_sdmult(A, 1, one, zero, lam, y, cm); // y = Aᵀ λ (scaled unknowns)
            double *yx = y->x;
            for (int v = 0; v < g->nv; ++v) g->dx[v] = ori_v2_make(0.0, 0.0);
            if (!g->rates_only)
                for (int v = 0; v < g->nv; ++v) {
                    int c = g->col_x[v];
                    if (c < 0) continue;
                    ori_v2 target;
                    if (g->kind[v] == VK_FREE) {
                        target = ori_v2_make(g->x0[v].x + g->L * yx[c], g->x0[v].y + g->L * yx[c + 1]);
                    } else {
                        target = ori_v2_make(g->x0[v].x + g->L * yx[c] * g->slide[v].x,
                                             g->x0[v].y + g->L * yx[c] * g->slide[v].y);
                    }
                    // Anchored steps aim at x₀ + L·y; polishing steps move by L·y from here.
                    ori_v2 from = g->polish ? ori_v2_make(0.0, 0.0) : ori_v2_make(g->x0[v].x - g->x[v].x, g->x0[v].y - g->x[v].y);
                    g->dx[v] = ori_v2_make(target.x - g->x0[v].x + from.x, target.y - g->x0[v].y + from.y);
                }
            for (int e = 0; e < g->p->edge_count; ++e) g->dr[e] = 0.0;
            if (g->rigid) {
                double rs = 1.0 / sqrt(g->w_rate);
                for (int e = 0; e < g->p->edge_count; ++e)
                    if (g->col_r[e] >= 0) g->dr[e] = rs * yx[g->col_r[e]];
            }
            cholmod_free_dense(&y, cm);
            cholmod_free_dense(&lam, cm);
        }
    }
    cholmod_free_dense(&b, cm);
    cholmod_free_sparse(&A, cm);
    return ok;
}

ori_regularize_def ori_default_regularize_def(void)
{
    ori_regularize_def def;
    def.rigid = false;
    def.rigid_only = false;
    def.max_move_rel = ORI_REGULARIZE_MAX_MOVE_REL;
    def.max_iterations = 100;
    def.progress = NULL;
    def.progress_user = NULL;
    def.keep_partial = false;
    def.internal_value = ORI__DEF_COOKIE;
    return def;
}

static bool is_boundary_edge(ori_assignment a) { return a == ORI_ASSIGN_BOUNDARY || a == ORI_ASSIGN_CUT; }

// Largest |alternating sector sum| over the interior vertices of a built pattern.
static double max_kawasaki(const ori_pattern *p)
{
    double worst = 0.0;
    double sec[ORI__FLAT_STACK_DEGREE];
    for (int v = 0; v < p->vertex_count; ++v) {
        if (!ori_pattern_vertex_is_interior(p, v)) continue;
        int n = ori_flat_vertex_creases(p, v, NULL, sec, ORI__FLAT_STACK_DEGREE);
        if (n > ORI__FLAT_STACK_DEGREE || n % 2 != 0) continue;
        double k = fabs(ori_flat_kawasaki_sum(sec, n));
        if (k > worst) worst = k;
    }
    return worst;
}

// Report the share of the defect removed, on a log scale from the input's defect k0 to the
// tolerance (monotone: never less than before); false when the callback cancels.
static bool report_progress(reg_budget *b, double worst)
{
    if (!b->progress) return true;
    double f = 1.0;
    if (b->k0 > b->tol && worst > b->tol) f = worst >= b->k0 ? 0.0 : log(b->k0 / worst) / log(b->k0 / b->tol);
    if (f > b->fraction) b->fraction = f;
    if (b->progress(b->fraction, b->user)) return true;
    b->cancelled = true;
    return false;
}

// Iterate until the equations hold (or max_iterations); returns the iterations done.
static int solve(reg *g, int max_iterations, double kaw_tol, double rig_tol, bool *converged)
{
    cholmod_common cm;
    ori__cholmod_start(&cm);
    cm.quick_return_if_not_posdef = 0; // as before: a failed factorization is told by its status
    cm.supernodal = CHOLMOD_SIMPLICIAL;
    cholmod_factor *L = NULL;
    int it = 0;
    *converged = false;
    double best = INFINITY;
    int stalled = 0;
    int ne = g->p->edge_count;
    for (; it < max_iterations; ++it) {
        assemble(g);
        double kaw, rig;
        defects(g, &kaw, &rig);
        if (kaw <= kaw_tol && rig <= rig_tol) {
            *converged = true;
            break;
        }
        double worst = fmax(kaw, rig);
        if (g->budget && !report_progress(g->budget, worst)) {
            g->stopped = true;
            break;
        }
        // Close to the solution, weight coordinates and rates alike and anchor the step at the
        // current state: the remaining moves are ~1e-9 and no longer shape the answer, while
        // the disparate weights would cost six digits of the coordinate part.
        if (!g->polish && worst <= ORI_REGULARIZE_POLISH) {
            g->polish = true;
            g->w_rate = 1.0;
            best = INFINITY;
            stalled = 0;
        }
        // Stop when the defect has not shrunk for a few steps (inconsistent equations).
        if (worst < ORI_REGULARIZE_PROGRESS * best) {
            best = worst;
            stalled = 0;
        } else if (++stalled >= ORI_REGULARIZE_STALL_STEPS) {
            break;
        }
        if (!step(g, &cm, &L)) break;
        // Backtracking: far from the solution a full step of the quadratic conditions can
        // overshoot; halve it until the defect drops (the full step is taken near the solution).
        memcpy(g->x_save, g->x, sizeof(ori_v2) * (size_t)g->nv);
        memcpy(g->r_save, g->rate, sizeof(double) * (size_t)ne);
        double t = 1.0;
        for (int h = 0; h < ORI_REGULARIZE_BACKTRACK_MAX; ++h, t *= 0.5) {
            for (int v = 0; v < g->nv; ++v)
                g->x[v] = ori_v2_make(g->x_save[v].x + t * g->dx[v].x, g->x_save[v].y + t * g->dx[v].y);
            for (int e = 0; e < ne; ++e) g->rate[e] = g->r_save[e] + t * g->dr[e];
            assemble(g);
            double k2, r2;
            defects(g, &k2, &r2);
            if (fmax(k2, r2) < worst) break;
        }
    }
    if (!*converged && it == max_iterations) {
        assemble(g);
        double kaw, rig;
        defects(g, &kaw, &rig);
        *converged = kaw <= kaw_tol && rig <= rig_tol;
        if (!*converged && g->budget) g->stopped = true; // the budget, not a stall, ended it
    }
    cholmod_free_factor(&L, &cm);
    cholmod_finish(&cm);
    return it;
}

static int compare_keyed(const void *a, const void *b)
{
    const double *x = a, *y = b;
    return x[0] < y[0] ? -1 : x[0] > y[0];
}

// Whether the direction of edge e cannot change: both ends fixed, or sliding along the edge's
// own line (a boundary edge on a straight side).
static bool direction_fixed(const reg *g, int e)
{
    const ori_edge *ed = &g->p->edges[e];
    for (int k = 0; k < 2; ++k) {
        int kind = g->kind[ed->v[k]];
        if (!(kind == VK_FIXED || (kind == VK_SLIDE && is_boundary_edge(ed->assignment)))) return false;
    }
    return true;
}

static void add_tie(reg *g, int *cap, int kind, int iv, int i, int j);
static void find_ties(reg *g, int *cap, double tau, bool parallel);
static bool is_boundary_edge(ori_assignment a);

static void add_tie(reg *g, int *cap, int kind, int iv, int i, int j)
{
    if (g->ntie == *cap) {
        *cap = *cap ? 2 * *cap : 64;
        g->ties = ori__realloc(g->ties, sizeof(reg_tie) * (size_t)*cap);
    }
    reg_tie t = {kind, iv, i, j};
    g->ties[g->ntie++] = t;
}

// The equalities of the drawing within tau (radians), as ties: at every interior vertex the
// sectors within tau of each other (chained in sorted order) and the creases that continue each
// other straight; with parallel, edges whose directions lie within tau (chained, modulo π),
// each tied to a member whose direction cannot change when there is one.
static void find_ties(reg *g, int *cap, double tau, bool parallel)
{
    double key[2 * ORI__FLAT_STACK_DEGREE];
    for (int a = 0; a < g->niv; ++a) {
        const reg_vertex *V = &g->iv[a];
        int n = V->count;
        if (n < 2) continue;
        double phi[ORI__FLAT_STACK_DEGREE];
        for (int k = 0; k < n; ++k) {
            ori_v2 q = g->x0[g->crease_nb[V->first + k]], c = g->x0[V->v];
            phi[k] = atan2(q.y - c.y, q.x - c.x);
        }
        for (int k = 0; k < n; ++k) {
            double al = wrap(phi[(k + 1) % n] - phi[k], 2.0 * ORI_PI);
            if (al <= 0.0) al += 2.0 * ORI_PI;
            key[2 * k] = al, key[2 * k + 1] = k;
        }
        qsort(key, (size_t)n, 2 * sizeof(double), compare_keyed);
        for (int k = 0; k + 1 < n; ++k)
            if (key[2 * k + 2] - key[2 * k] <= tau) add_tie(g, cap, TIE_SECTORS, a, (int)key[2 * k + 1], (int)key[2 * k + 3]);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                if (i != j && fabs(wrap(phi[j] - phi[i] - ORI_PI, 2.0 * ORI_PI)) <= tau && i < j)
                    add_tie(g, cap, TIE_STRAIGHT, a, i, j);
    }
    if (!parallel) return;
    int ne = g->p->edge_count, m = 0;
    double *dir = ori__alloc(sizeof(double) * 2 * (size_t)(ne + 1));
    for (int e = 0; e < ne; ++e) {
        const ori_edge *ed = &g->p->edges[e];
        if (ed->assignment == ORI_ASSIGN_JOIN) continue;
        ori_v2 a = g->x0[ed->v[0]], b = g->x0[ed->v[1]];
        double t = atan2(b.y - a.y, b.x - a.x);
        if (t < 0.0) t += ORI_PI;
        if (t >= ORI_PI) t -= ORI_PI;
        dir[2 * m] = t, dir[2 * m + 1] = e;
        m++;
    }
    qsort(dir, (size_t)m, 2 * sizeof(double), compare_keyed);
    // classes: runs of directions within tau of the previous one, the last run joined to the
    // first when they meet across 0 = π
    int start = 0;
    if (m > 1 && dir[0] + ORI_PI - dir[2 * (m - 1)] <= tau) {
        start = m - 1;
        while (start > 0 && dir[2 * start] - dir[2 * (start - 1)] <= tau) --start;
        if (start == 0) start = m; // (everything one class: treat as not wrapping)
        else start = start % m;
    }
    if (start == m) start = 0;
    int *cls = ori__alloc(sizeof(int) * (size_t)(m + 1));
    for (int k = 0; k < m;) {
        int n = 0, first = (start + k) % m;
        cls[n++] = (int)dir[2 * first + 1];
        int at = first;
        ++k;
        while (k < m) {
            int nx = (start + k) % m;
            double gap = dir[2 * nx] - dir[2 * at];
            if (gap < 0.0) gap += ORI_PI;
            if (gap > tau) break;
            cls[n++] = (int)dir[2 * nx + 1];
            at = nx;
            ++k;
        }
        if (n < 2) continue;
        int anchor = -1;
        for (int i = 0; i < n && anchor < 0; ++i)
            if (direction_fixed(g, cls[i])) anchor = i;
        for (int i = 0; i < n; ++i) {
            if (anchor >= 0) {
                if (i != anchor && !direction_fixed(g, cls[i])) add_tie(g, cap, TIE_PARALLEL, -1, cls[i], cls[anchor]);
            } else if (i > 0) {
                add_tie(g, cap, TIE_PARALLEL, -1, cls[i], cls[i - 1]);
            }
        }
    }
    ori__free(cls);
    ori__free(dir);
}

// One regularization with the ties of level (2: sectors, straight lines and parallels within
// tau; 1: sectors and straight lines; 0: none). With free_sides the corners and sides move too
// (every vertex free, a vertex on a straight side kept on a straight line through its
// neighbours): the drawing's own corners may miss its equalities by its precision.
static ori_status regularize_level(const ori_pattern *p, const ori_regularize_def *def, int level, bool free_sides,
                                   double tau, reg_budget *budget, ori_pattern **out, ori_regularize_result *res,
                                   ori_error *error)
{
    *out = NULL;
    memset(res, 0, sizeof *res);
    res->odd_vertex = ORI_NULL_INDEX;
    res->max_move_vertex = ORI_NULL_INDEX;
    res->crossing_edge = ORI_NULL_INDEX;
    res->against_edge = ORI_NULL_INDEX;
    if (!p->built) return ori__fail(error, ORI_ERR_ARGUMENT, "the pattern is not built");
    if (ori_pattern_is_folded_form(p) || ori_pattern_is_3d(p))
        return ori__fail(error, ORI_ERR_ARGUMENT, "regularize needs a flat crease pattern, not a folded form");

    reg g;
    memset(&g, 0, sizeof g);
    g.p = p;
    g.nv = p->vertex_count;
    g.L = ori_pattern_diagonal(p);
    g.rigid = def->rigid || def->rigid_only;
    g.kawasaki = !def->rigid_only;
    g.w_rate = ORI_REGULARIZE_RATE_WEIGHT;
    g.polish = false;
    g.fixed_edge = ORI_NULL_INDEX;
    int ne = p->edge_count;
    g.x0 = ori__alloc(sizeof(ori_v2) * (size_t)(g.nv + 1));
    g.x = ori__alloc(sizeof(ori_v2) * (size_t)(g.nv + 1));
    g.kind = ori__calloc((size_t)g.nv + 1, sizeof(int));
    g.slide = ori__calloc((size_t)g.nv + 1, sizeof(ori_v2));
    g.col_x = ori__alloc(sizeof(int) * (size_t)(g.nv + 1));
    g.col_r = ori__alloc(sizeof(int) * (size_t)(ne + 1));
    g.rate = ori__calloc((size_t)ne + 1, sizeof(double));
    g.is_crease = ori__calloc((size_t)ne + 1, sizeof(bool));
    for (int v = 0; v < g.nv; ++v) {
        ori_v3 q = ori_pattern_vertex(p, v);
        g.x0[v] = g.x[v] = ori_v2_make(q.x, q.y);
    }

    int tie_cap = 0;
    // Vertex kinds: interior vertices and vertices off the boundary move freely; a boundary
    // vertex between two collinear boundary edges slides along them; other boundary vertices
    // (corners, ends of slits) stay.
    for (int v = 0; v < g.nv; ++v) {
        int deg = ori_pattern_vertex_degree(p, v);
        int bnb[2], nb = 0;
        int es[ORI__FLAT_STACK_DEGREE];
        int *edges = deg <= ORI__FLAT_STACK_DEGREE ? es : ori__alloc(sizeof(int) * (size_t)deg);
        ori_pattern_vertex_edges(p, v, edges, deg);
        for (int k = 0; k < deg; ++k) {
            ori_edge e = ori_pattern_edge(p, edges[k]);
            if (!is_boundary_edge(e.assignment)) continue;
            if (nb < 2) bnb[nb] = e.v[0] == v ? e.v[1] : e.v[0];
            nb++;
        }
        if (edges != es) ori__free(edges);
        if (nb == 0) {
            g.kind[v] = VK_FREE;
        } else if (nb == 2) {
            ori_v2 a = ori_v2_make(g.x0[bnb[0]].x - g.x0[v].x, g.x0[bnb[0]].y - g.x0[v].y);
            ori_v2 b = ori_v2_make(g.x0[bnb[1]].x - g.x0[v].x, g.x0[bnb[1]].y - g.x0[v].y);
            double la = sqrt(a.x * a.x + a.y * a.y), lb = sqrt(b.x * b.x + b.y * b.y);
            // Straight through: the two boundary edges point in opposite directions.
            double sin_turn = cross2(a, b) / (la * lb), cos_turn = (a.x * b.x + a.y * b.y) / (la * lb);
            if (cos_turn < 0.0 && fabs(sin_turn) <= ORI_REGULARIZE_BOUNDARY_STRAIGHT_RAD && free_sides) {
                add_tie(&g, &tie_cap, TIE_SIDE, v, bnb[0], bnb[1]);
            } else if (cos_turn < 0.0 && fabs(sin_turn) <= ORI_REGULARIZE_BOUNDARY_STRAIGHT_RAD) {
                g.kind[v] = VK_SLIDE;
                ori_v2 t = ori_v2_make(b.x / lb - a.x / la, b.y / lb - a.y / la);
                double lt = sqrt(t.x * t.x + t.y * t.y);
                g.slide[v] = ori_v2_make(t.x / lt, t.y / lt);
            }
        }
    }

    if (free_sides)
        for (int v = 0; v < g.nv; ++v) g.kind[v] = VK_FREE;
    res->sides_moved = free_sides;
    // Interior vertices and their creases.
    int total_creases = 0;
    for (int v = 0; v < g.nv; ++v)
        if (ori_pattern_vertex_is_interior(p, v)) {
            g.niv++;
            total_creases += ori_pattern_vertex_degree(p, v);
        }
    g.iv = ori__alloc(sizeof(reg_vertex) * (size_t)(g.niv + 1));
    g.crease_nb = ori__alloc(sizeof(int) * (size_t)(total_creases + 1));
    g.crease_edge = ori__alloc(sizeof(int) * (size_t)(total_creases + 1));
    ori_status st = ORI_OK;
    int a = 0, used = 0;
    for (int v = 0; v < g.nv; ++v) {
        if (!ori_pattern_vertex_is_interior(p, v)) continue;
        int n = ori_flat_vertex_creases(p, v, g.crease_edge + used, NULL, total_creases - used);
        if (n > ORI__FLAT_STACK_DEGREE) {
            st = ori__fail_at(error, ORI_ERR_LIMIT, "vertices_coords", v, "vertex of degree %d (at most %d)", n,
                              ORI__FLAT_STACK_DEGREE);
            goto fail;
        }
        for (int k = 0; k < n; ++k) {
            ori_edge e = ori_pattern_edge(p, g.crease_edge[used + k]);
            g.crease_nb[used + k] = e.v[0] == v ? e.v[1] : e.v[0];
            g.is_crease[g.crease_edge[used + k]] = true;
        }
        if (g.kawasaki && n % 2 != 0 && res->odd_vertex == ORI_NULL_INDEX) res->odd_vertex = v;
        g.iv[a].v = v;
        g.iv[a].first = used;
        g.iv[a].count = n;
        a++;
        used += n;
    }
    g.niv = a;
    res->interior_vertices = g.niv;

    // Fold rates from the targets, and the crease that fixes their scale.
    if (g.rigid) {
        bool has = ori_pattern_has_fold_angles(p);
        g.R = 0.0;
        for (int e = 0; e < ne; ++e) {
            if (!g.is_crease[e]) continue;
            ori_edge ed = ori_pattern_edge(p, e);
            double t = has ? ed.fold_angle_rad : 0.0;
            if (!(fabs(t) > ORI_TOL_FOLD_SIGN_RAD))
                t = ed.assignment == ORI_ASSIGN_VALLEY ? ORI_PI : ed.assignment == ORI_ASSIGN_MOUNTAIN ? -ORI_PI : 0.0;
            g.rate[e] = t;
            if (fabs(t) > g.R) {
                g.R = fabs(t);
                g.fixed_edge = e;
            }
        }
        if (g.R > 0.0)
            for (int e = 0; e < ne; ++e) g.rate[e] /= g.R;
    }
    g.r_start = ori__alloc(sizeof(double) * (size_t)(ne + 1));
    memcpy(g.r_start, g.rate, sizeof(double) * (size_t)ne);
    for (int i = 0; i < g.niv; ++i) {
        g.iv[i].nrig = 3;
        // (The mode relations hold at flat-foldable degree-4 vertices: not without Kawasaki.)
        if (g.rigid && g.kawasaki && mode_of(&g, &g.iv[i])) {
            g.iv[i].nrig = 4;
            res->mode_vertices++;
        }
    }

    // Columns and rows.
    for (int v = 0; v < g.nv; ++v) {
        g.col_x[v] = g.kind[v] == VK_FIXED ? -1 : g.cols;
        g.cols += g.kind[v];
    }
    for (int e = 0; e < ne; ++e) g.col_r[e] = -1;
    if (g.rigid)
        for (int e = 0; e < ne; ++e)
            if (g.is_crease[e] && e != g.fixed_edge) g.col_r[e] = g.cols++;
    for (int i = 0; i < g.niv; ++i) {
        g.iv[i].row = g.rows;
        g.rows += (g.kawasaki && g.iv[i].count % 2 == 0 ? 1 : 0) + (g.rigid ? g.iv[i].nrig : 0);
    }
    if (level > 0) find_ties(&g, &tie_cap, tau, level > 1);
    g.tie_row = g.rows;
    g.rows += g.ntie;
    res->ties = g.ntie;
    res->parallels_kept = level > 1;
    res->equal_tolerance_rad = tau;
    g.c = ori__calloc((size_t)g.rows + 1, sizeof(double));
    g.dx = ori__calloc((size_t)g.nv + 1, sizeof(ori_v2));
    g.x_save = ori__calloc((size_t)g.nv + 1, sizeof(ori_v2));
    g.dr = ori__calloc((size_t)ne + 1, sizeof(double));
    g.r_save = ori__calloc((size_t)ne + 1, sizeof(double));
    res->unknowns = g.cols;
    res->equations = g.rows;
    res->kawasaki_before_rad = max_kawasaki(p);

    bool converged = false;
    if (g.rigid && g.fixed_edge != ORI_NULL_INDEX) {
        // How far the input is from rigid: the best rates with the coordinates held.
        g.rates_only = true;
        solve(&g, ORI_REGULARIZE_RATE_PASSES, INFINITY, ORI_TOL_REGULARIZE_RIGID, &converged);
        double kaw, rig;
        assemble(&g);
        defects(&g, &kaw, &rig);
        res->rigid_before = rig;
        g.rates_only = false;
        g.polish = false;
        g.w_rate = ORI_REGULARIZE_RATE_WEIGHT;
    }
    g.budget = budget;
    if (budget->k0 < 0.0) { // (the first attempt: the input's defect starts the progress scale)
        budget->k0 = g.kawasaki ? res->kawasaki_before_rad : 0.0;
        if (g.rigid) budget->k0 = fmax(budget->k0, res->rigid_before);
        budget->tol = g.kawasaki ? ORI_TOL_REGULARIZE_KAWASAKI_RAD : ORI_TOL_REGULARIZE_RIGID;
    }
    res->iterations = solve(&g, def->max_iterations, ORI_TOL_REGULARIZE_KAWASAKI_RAD,
                            g.rigid ? ORI_TOL_REGULARIZE_RIGID : INFINITY, &converged);
    g.budget = NULL;
    res->stopped = g.stopped;
    if (g.rigid) {
        double kaw, rig;
        assemble(&g);
        defects(&g, &kaw, &rig);
        res->rigid_after = rig;
        // (No interior vertex: nothing constrains the rates, every crease folds on its own.)
        if (g.fixed_edge == ORI_NULL_INDEX && g.niv > 0) converged = false;
        // In its assigned mode every crease of a degree-4 vertex folds with the sign it started
        // with, unless the geometry forbids that assignment (the odd crease on the wrong side):
        // then the motion exists only against the assignment.
        for (int i = 0; i < g.niv && res->against_edge == ORI_NULL_INDEX; ++i) {
            if (g.iv[i].nrig != 4) continue;
            for (int k = 0; k < 4; ++k) {
                int e = g.crease_edge[g.iv[i].first + k];
                if (g.rate[e] * g.r_start[e] < 0.0 && fabs(g.rate[e]) > ORI_TOL_REGULARIZE_AGAINST_RATE) {
                    res->against_edge = e;
                    converged = false;
                    break;
                }
            }
        }
    }
    {
        double kaw, rig;
        assemble(&g);
        defects(&g, &kaw, &rig);
        res->kawasaki_after_rad = kaw;
    }

    // The new pattern: same topology, moved vertices, built (planarity checked).
    ori_pattern *q = ori_pattern_clone(p);
    double sum2 = 0.0;
    for (int v = 0; v < g.nv; ++v) {
        double dx = g.x[v].x - g.x0[v].x, dy = g.x[v].y - g.x0[v].y;
        double d = sqrt(dx * dx + dy * dy) / g.L;
        sum2 += d * d;
        if (d > 0.0) res->moved_vertices++;
        if (d > res->max_move_rel) {
            res->max_move_rel = d;
            res->max_move_vertex = v;
        }
        ori_pattern_set_vertex(q, v, ori_v3_make(g.x[v].x, g.x[v].y, 0.0));
    }
    res->rms_move_rel = g.nv > 0 ? sqrt(sum2 / g.nv) : 0.0;
    res->refused = res->max_move_rel > def->max_move_rel;
    if (res->refused || res->odd_vertex != ORI_NULL_INDEX) res->stopped = false; // (a verdict, whatever the budget)
    // Stopped at the budget: the best found is handed back on request (not exact).
    bool partial = def->keep_partial && res->stopped && !converged && !res->refused && res->odd_vertex == ORI_NULL_INDEX;
    if (!partial && (res->refused || !converged || res->odd_vertex != ORI_NULL_INDEX)) {
        // No pattern to hand back: the result says why.
        ori_pattern_destroy(q);
        goto fail;
    }
    ori_build_def bd = ori_default_build_def();
    bd.compute_faces = false;
    ori_error berr;
    if (ori_pattern_build(q, &bd, &berr) != ORI_OK) {
        // Moving made edges cross (or vertices meet): no exact pattern this close keeps the
        // drawing's topology. A domain answer, not an input error.
        res->crossing_edge = berr.element;
        ori__strlcpy(res->crossing, berr.message, sizeof res->crossing);
        ori_pattern_destroy(q);
        goto fail;
    }
    res->kawasaki_after_rad = max_kawasaki(q);
    res->converged = !partial && (!g.kawasaki || res->kawasaki_after_rad <= ORI_TOL_REGULARIZE_KAWASAKI_RAD);
    *out = q;
fail:
    ori__free(g.x0);
    ori__free(g.x);
    ori__free(g.kind);
    ori__free(g.slide);
    ori__free(g.col_x);
    ori__free(g.col_r);
    ori__free(g.rate);
    ori__free(g.is_crease);
    ori__free(g.iv);
    ori__free(g.crease_nb);
    ori__free(g.crease_edge);
    ori__free(g.ti);
    ori__free(g.tj);
    ori__free(g.tx);
    ori__free(g.c);
    ori__free(g.dx);
    ori__free(g.x_save);
    ori__free(g.dr);
    ori__free(g.r_save);
    ori__free(g.r_start);
    ori__free(g.ties);
    return st;
}

// The drawing's precision, for the equalities kept: four times the largest Kawasaki miss of the
// even interior vertices that miss by at most ORI_REGULARIZE_EQUAL_MAX_RAD (farther ones are not
// rounded flat-foldable vertices), within [ORI_TOL_ANGLE_EQUAL_RAD, ORI_REGULARIZE_EQUAL_MAX_RAD].
static double equal_tolerance(const ori_pattern *p)
{
    double worst = 0.0, sec[ORI__FLAT_STACK_DEGREE];
    for (int v = 0; v < p->vertex_count; ++v) {
        if (!ori_pattern_vertex_is_interior(p, v)) continue;
        int n = ori_flat_vertex_creases(p, v, NULL, sec, ORI__FLAT_STACK_DEGREE);
        if (n > ORI__FLAT_STACK_DEGREE || n % 2 != 0) continue;
        double k = fabs(ori_flat_kawasaki_sum(sec, n));
        if (k <= ORI_REGULARIZE_EQUAL_MAX_RAD && k > worst) worst = k;
    }
    return fmin(fmax(4.0 * worst, ORI_TOL_ANGLE_EQUAL_RAD), ORI_REGULARIZE_EQUAL_MAX_RAD);
}

// The full local check of a result (Kawasaki, Maekawa, big-little-big, the exact test with the
// assignment): the first failing vertex and rule into res.
static bool local_check(const ori_pattern *q, ori_regularize_result *res)
{
    ori_flat_check_def cd = ori_default_flat_check_def();
    cd.record_vertices = false;
    ori_flat_report *rep = ori_flat_check_pattern(q, &cd);
    bool ok = ori_flat_report_flat_foldable(rep);
    res->check_failed = ori_flat_report_failed_count(rep);
    if (!ok && ori_flat_report_violation_count(rep) > 0) {
        ori_flat_violation v = ori_flat_report_violation(rep, 0);
        res->check_vertex = v.vertex;
        res->check_rule = v.rule;
        ori__strlcpy(res->check_detail, v.detail, sizeof res->check_detail);
    }
    ori_flat_report_destroy(rep);
    return ok;
}

ori_status ori_regularize(const ori_pattern *p, const ori_regularize_def *def, ori_pattern **out,
                          ori_regularize_result *res, ori_error *error)
{
    ORI_ASSERT(p && def && out && res && def->internal_value == ORI__DEF_COOKIE);
    ORI_ASSERT(def->max_iterations >= 1 && def->max_move_rel >= 0.0);
    *out = NULL;
    if (!p->built) {
        memset(res, 0, sizeof *res);
        return ori__fail(error, ORI_ERR_ARGUMENT, "the pattern is not built");
    }
    double tau = equal_tolerance(p);
    // The drawing's equalities kept, as many as the conditions allow, the corners and sides where
    // they are if possible: all of them, then without the parallels; then the same with the
    // corners and sides free; then none. Each result is checked in full and the first that
    // passes is taken (rigid only: the first found, there is no flat check to pass).
    ori_pattern *q = NULL;
    static const int levels[5] = {2, 1, 2, 1, 0};
    static const bool free_sides[5] = {false, false, true, true, false};
    reg_budget budget = {def->progress, def->progress_user, -1.0, 0.0, 0.0, false};
    for (int t = 0; t < 5; ++t) {
        int level = levels[t];
        ori_status st = regularize_level(p, def, level, free_sides[t], tau, &budget, &q, res, error);
        if (st != ORI_OK) return st;
        res->check_vertex = ORI_NULL_INDEX;
        res->check_rule = ORI_FLAT_RULE_COUNT;
        res->check_failed = 0;
        res->check_detail[0] = '\0';
        res->flat_foldable = false;
        if (res->stopped) break; // the budget is spent: the best found (with keep_partial, in q)
        if (q) {
            res->flat_foldable = local_check(q, res);
            if (res->flat_foldable || def->rigid_only) break;
            res->converged = false; // Kawasaki holds, the full check does not (check_*: why)
            ori_pattern_destroy(q);
            q = NULL;
            if (res->check_rule == ORI_FLAT_RULE_MAEKAWA) break; // (the assignment's, no geometry helps)
        }
        if (res->odd_vertex != ORI_NULL_INDEX) break; // (no tie helps a vertex of odd degree)
    }
    *out = q;
    if (budget.cancelled) return ori__fail(error, ORI_ERR_LIMIT, "cancelled");
    return ORI_OK;
}
