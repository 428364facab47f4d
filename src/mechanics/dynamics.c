// Folding dynamics of the whole mechanism (SPEC capability 18, the wrench formulation the thesis
// proposes in ch. 5.3), closed loops included.
//
// Coordinates: the fold angles θ of the free (M, V, U) creases. The panels form a tree from the
// fixed face (the public spanning tree); each panel's spatial velocity is the sum of the world
// twists of the creases on its path times their rates, so the mass matrix is assembled by the
// composite-rigid-body method and the velocity-product and external terms by a recursive
// Newton–Euler pass, both in world-frame screw coordinates (twists (v, ω), wrenches (f, τ)).
// Hinge moments, damping and applied moments act on the fold angles directly; gravity and the
// Lorentz forces on the wires are wrenches on the panels. The creases that close loops carry no
// inertia of their own; the loop-closure equations Φ(θ) = 0 tie them to the tree.
//
// Constraint forces: the accelerations minimise ½(θ̈ − M⁻¹Q)ᵀM(θ̈ − M⁻¹Q) subject to
// Φ_θ θ̈ = γ (Gauss's principle), solved by an augmented Lagrangian with mass-orthogonal
// projections (Bayo & García de Jalón): (M + Φ_θᵀWΦ_θ) θ̈ = Q − Φ_θᵀ(λ − Wγ), λ ← λ + W(Φ_θθ̈ − γ),
// with a penalty W per loop scaled by the inertia of its lightest crease. It needs no rank
// decisions, so redundant loop equations (overconstrained patterns such as the Miura-ori) and
// singular states (the flat sheet) are handled the same way as regular ones.
//
// Time integration: the implicit midpoint rule, v₁ = v₀ + h·a(θ₀ + h/2·v_m, v_m), θ₁ = θ₀ + h·v_m,
// solved by fixed-point iteration on the midpoint acceleration. It is symmetric and symplectic
// on the unconstrained (tree) part: quadratic invariants are kept exactly, so an elastic flap's
// energy stays constant to rounding, and a constant moment gives θ = ½(M/J)t² exactly. After each
// step θ₁ is projected onto Φ = 0 (Gauss–Newton with minimum-norm steps, to ORI_DYN_PROJECT_TOL)
// and v₁ onto the tangent space (mass-orthogonal, which is also the perfectly inelastic impact when a
// crease hits its ±180° stop). The loops therefore close at every step to machine precision.
#include <stdlib.h>

#include "mechanics_internal.h"

typedef struct dyn_wire {
    int edge, face, col;
    wire_segments seg;
    double current;   // signed current when on
    bool on;
    int dir;          // direction of the crease toward its target
    double target;
    bool reached;
    double t_reached;
} dyn_wire;

typedef struct dyn {
    const ori_design *d;
    const ori_mechanism *m;
    mech_tree t;
    mech_loops L;
    int n, E, F, rows;
    double mpu;
    ori_rigid g0;
    ori_v3 gravity, field;
    // schedule
    int nsched, sched_next;
    ori_field_change sched[ORI_SCHEDULE_MAX];
    int *sched_dir;
    // stages (a fold sequence): the wire of each in turn
    int nstage, stage;
    int *stage_wire;
    bool auto_polarity;
    // per edge
    bool *has_sec;
    hinge_section *sec;
    hinge_fibres *fib;
    double *damp, *applied, *target, *start; // start: the closed start state
    // per coordinate: creases held at held_at (a ±180° stop with its sign, or a fold's lock)
    int *stop;
    bool *held;
    double *held_at;
    int *lock_first;   // per stage: its locks in lock_edges[lock_first[k] … lock_first[k+1])
    const int *lock_edges;
    dyn_wire *w;
    int nw;
    // assembly
    mech_spd *K;
    double *pen;       // penalty per constraint row (loop rows, then one per coordinate)
    double *mdiag;     // diagonal of the mass matrix per coordinate
    double *mfloor;    // the inertia of the panel a crease turns: the scale of coordinates without inertia of their own
    double *lam;       // multipliers of the last acceleration solve (loop rows, then per coordinate)
    double *jac, *gam, *phi;
    ori_rigid *poses;
    body_inertia *body, *comp;
    sv6 *S, *Vf, *Af, *Wf, *Wext;
    double *eth, *erate, *rhs, *x, *y, *r, *tmp, *tmp2, *zero;
    // per evaluation outputs
    double power_in, power_damp, kinetic;
} dyn;

struct ori_simulation {
    int E, V, frames;
    const ori_mechanism *m;
    int fixed;
    ori_rigid g0;
    double *time, *angles, *currents, *plastic, *kin, *total, *res;
    ori_v3 *field;
    double *latched;
    ori_simulation_summary sum;
};

ori_simulation_def ori_default_simulation_def(void)
{
    ori_simulation_def d;
    memset(&d, 0, sizeof d);
    d.fixed_face = 0;
    d.fixed_pose = ori_rigid_identity();
    d.auto_polarity = true;
    d.current_off_at_target = true;
    d.stops = true;
    d.output_frames = 101;
    d.settle = true;
    d.internal_value = ORI__DEF_COOKIE;
    return d;
}

// --- assembly -------------------------------------------------------------------------------

static void to_edges(const dyn *s, const double *q, const double *v)
{
    for (int e = 0; e < s->E; ++e) {
        int c = s->t.col_of_edge[e];
        s->eth[e] = c >= 0 ? q[c] : 0.0;
        if (v) s->erate[e] = c >= 0 ? v[c] : 0.0;
    }
}

// Φ_θ x: loop rows, then one row per coordinate (stops; zero when inactive).
static void phi_mult(const dyn *s, const double *x, double *out)
{
    for (int k = 0; k < s->L.count; ++k) {
        int nr = s->L.nrows[k];
        double *o = out + s->L.row0[k];
        for (int r = 0; r < nr; ++r) o[r] = 0.0;
        for (int i = s->L.first[k]; i < s->L.first[k] + s->L.size[k]; ++i) {
            int c = s->t.col_of_edge[s->L.edge[i]];
            if (c < 0) continue;
            const double *j = s->jac + 6 * (size_t)i;
            for (int r = 0; r < nr; ++r) o[r] += j[r] * x[c];
        }
    }
    for (int c = 0; c < s->n; ++c) out[s->rows + c] = s->held[c] ? x[c] : 0.0;
}

static void phi_tmult(const dyn *s, const double *y, double *out)
{
    for (int c = 0; c < s->n; ++c) out[c] = s->held[c] ? y[s->rows + c] : 0.0;
    for (int k = 0; k < s->L.count; ++k) {
        int nr = s->L.nrows[k];
        const double *yy = y + s->L.row0[k];
        for (int i = s->L.first[k]; i < s->L.first[k] + s->L.size[k]; ++i) {
            int c = s->t.col_of_edge[s->L.edge[i]];
            if (c < 0) continue;
            const double *j = s->jac + 6 * (size_t)i;
            for (int r = 0; r < nr; ++r) out[c] += j[r] * yy[r];
        }
    }
}

static bool constrained(const dyn *s)
{
    if (s->rows > 0) return true;
    for (int c = 0; c < s->n; ++c)
        if (s->held[c]) return true;
    return false;
}

// Kinematics, mass matrix and (with forces) the right-hand side Q − c(θ, θ̇) at (q, v); the
// hinge moments from the committed fibres. Factors K = M + Φᵀ·diag(pen)·Φ.
static bool assemble(dyn *s, const double *q, const double *v, bool forces)
{
    int F = s->F, n = s->n;
    to_edges(s, q, v);
    ori__tree_poses(&s->t, s->eth, s->g0, s->poses);
    const ori_face_mass *fm = s->d->mass;
    for (int f = 0; f < F; ++f) {
        s->body[f] = ori__body_world(&fm[f], s->poses[f], s->mpu);
        s->comp[f] = s->body[f];
    }
    // Twists and velocities down the tree; bias accelerations (θ̈ = 0).
    s->kinetic = 0.0;
    s->power_in = 0.0;
    for (int k = 0; k < F; ++k) {
        int f = s->t.order[k], p = s->t.parent[f], c = s->t.pcol[f];
        if (p == ORI_NULL_INDEX) {
            s->Vf[f] = s->Af[f] = s->S[f] = sv6_zero();
            continue;
        }
        s->S[f] = c >= 0 ? ori__tree_twist(&s->t, f, s->poses, s->mpu) : sv6_zero();
        double rate = c >= 0 ? v[c] : 0.0;
        s->Vf[f] = sv6_add(s->Vf[p], sv6_scale(s->S[f], rate));
        s->Af[f] = sv6_add(s->Af[p], sv6_scale(sv6_ad(s->Vf[p], s->S[f]), rate));
        sv6 h = ori__inertia_apply(&s->body[f], s->Vf[f]);
        s->kinetic += 0.5 * sv6_dot(s->Vf[f], h);
    }
    // External wrenches: gravity and the Lorentz forces on the wires.
    for (int f = 0; f < F; ++f) {
        ori_v3 fg = ori_v3_scale(s->gravity, s->body[f].m);
        s->Wext[f] = sv6_make(fg, ori_v3_cross(ori_v3_scale(s->body[f].h, s->body[f].m > 0 ? 1.0 / s->body[f].m : 0.0), fg));
    }
    for (int i = 0; i < s->nw; ++i) {
        const dyn_wire *w = &s->w[i];
        if (!w->on || w->current == 0.0) continue;
        ori_v3 f, mo;
        ori__wire_wrench(s->d, &w->seg, 0, 3, s->poses[w->face], w->current, s->field, &f, &mo);
        sv6 W = sv6_make(f, mo);
        s->Wext[w->face] = sv6_add(s->Wext[w->face], W);
        s->power_in += sv6_dot(W, s->Vf[w->face]);
        // The loop closes along the crease on the other face: no net force on the pair.
        int o = w->seg.other;
        ori__wire_wrench(s->d, &w->seg, 3, 4, s->poses[o], w->current, s->field, &f, &mo);
        W = sv6_make(f, mo);
        s->Wext[o] = sv6_add(s->Wext[o], W);
        s->power_in += sv6_dot(W, s->Vf[o]);
    }
    // Composite inertias (children into parents) and the velocity-product wrenches.
    for (int k = F - 1; k >= 0; --k) {
        int f = s->t.order[k], p = s->t.parent[f];
        if (p == ORI_NULL_INDEX) continue;
        if (forces) {
            sv6 h = ori__inertia_apply(&s->body[f], s->Vf[f]);
            sv6 ga = ori__inertia_apply(&s->body[f], s->Af[f]);
            ori_v3 wv = s->Vf[f].w, vv = s->Vf[f].v;
            sv6 bias = sv6_make(ori_v3_cross(wv, h.v), ori_v3_add(ori_v3_cross(wv, h.w), ori_v3_cross(vv, h.v)));
            s->Wf[f] = sv6_add(sv6_add(ga, bias), sv6_scale(s->Wext[f], -1.0));
        }
        ori__body_add(&s->comp[p], &s->comp[f]);
    }
    if (forces) {
        for (int c = 0; c < n; ++c) s->rhs[c] = 0.0;
        for (int k = F - 1; k >= 0; --k) {
            int f = s->t.order[k], p = s->t.parent[f], c = s->t.pcol[f];
            if (p == ORI_NULL_INDEX) continue;
            if (c >= 0) s->rhs[c] -= sv6_dot(s->S[f], s->Wf[f]);
            if (s->t.parent[p] != ORI_NULL_INDEX) s->Wf[p] = sv6_add(s->Wf[p], s->Wf[f]);
        }
        // Hinge, damping and applied moments on the fold angles.
        s->power_damp = 0.0;
        for (int c = 0; c < n; ++c) {
            int e = s->t.edge_of_col[c];
            double mom = s->applied[e];
            if (s->has_sec[e]) mom -= ori__hinge_moment(&s->sec[e], &s->fib[e], q[c], NULL, NULL);
            double cd = s->damp[e];
            mom -= cd * v[c];
            s->power_damp += cd * v[c] * v[c];
            s->power_in += s->applied[e] * v[c];
            s->rhs[c] += mom;
        }
    }
    // Mass matrix (composite rigid bodies) plus the constraint penalty.
    ori__spd_zero(s->K);
    double diag = 0.0;
    for (int c = 0; c < n; ++c) s->mdiag[c] = s->mfloor[c];
    for (int k = 0; k < F; ++k) {
        int f = s->t.order[k], i = s->t.pcol[f];
        if (i < 0) continue;
        sv6 Fv = ori__inertia_apply(&s->comp[f], s->S[f]);
        for (int a = f; s->t.parent[a] != ORI_NULL_INDEX; a = s->t.parent[a]) {
            int j = s->t.pcol[a];
            if (j < 0) continue;
            double mij = sv6_dot(s->S[a], Fv);
            ori__spd_add(s->K, i, j, mij);
            if (i == j) {
                diag = fmax(diag, mij);
                s->mdiag[i] = fmax(s->mdiag[i], mij);
            }
        }
    }
    if (!(diag > 0.0)) return false;
    // The penalty of each loop's rows scales with the lightest crease in it (and a held crease's
    // with its own inertia): every coordinate sees a penalty ORI_DYN_ALM_PENALTY times its own
    // inertia or less, so the rounding of the stiff part stays below ORI_DYN_ALM_PENALTY × ε of
    // the light panels' accelerations, however heavy the rest of the sheet.
    ori__loops_jacobian(&s->L, s->eth, v ? s->erate : NULL, s->jac, s->gam);
    for (int k = 0; k < s->L.count; ++k) {
        int nr = s->L.nrows[k];
        double lightest = INFINITY;
        for (int i = s->L.first[k]; i < s->L.first[k] + s->L.size[k]; ++i) {
            int ci = s->t.col_of_edge[s->L.edge[i]];
            if (ci >= 0) lightest = fmin(lightest, s->mdiag[ci]);
        }
        double wl = ORI_DYN_ALM_PENALTY * (isfinite(lightest) ? lightest : diag);
        for (int r = 0; r < nr; ++r) s->pen[s->L.row0[k] + r] = wl;
        for (int i = s->L.first[k]; i < s->L.first[k] + s->L.size[k]; ++i) {
            int ci = s->t.col_of_edge[s->L.edge[i]];
            if (ci < 0) continue;
            for (int j = s->L.first[k]; j < s->L.first[k] + s->L.size[k]; ++j) {
                int cj = s->t.col_of_edge[s->L.edge[j]];
                if (cj < ci) continue;
                double dot = 0.0;
                for (int r = 0; r < nr; ++r) dot += s->jac[6 * (size_t)i + r] * s->jac[6 * (size_t)j + r];
                ori__spd_add(s->K, ci, cj, wl * dot);
            }
        }
    }
    for (int c = 0; c < n; ++c) {
        s->pen[s->rows + c] = ORI_DYN_ALM_PENALTY * s->mdiag[c];
        if (s->held[c]) ori__spd_add(s->K, c, c, s->pen[s->rows + c]);
    }
    return ori__spd_factor(s->K);
}

static double norm_inf(const double *x, int n)
{
    double m = 0.0;
    for (int i = 0; i < n; ++i) m = fmax(m, fabs(x[i]));
    return m;
}

// Minimise ½xᵀMx − bᵀx subject to Φ_θ x = g (rows + n entries, stops included) by the augmented
// Lagrangian, multipliers lam (rows + n, warm start, updated).
static bool alm(dyn *s, const double *b, const double *g, double *lam, double *x)
{
    int n = s->n, mr = s->rows + n;
    if (!constrained(s)) return ori__spd_solve(s->K, b, x);
    double gn = norm_inf(g, mr);
    for (int it = 0; it < ORI_DYN_ALM_MAX; ++it) {
        for (int k = 0; k < mr; ++k) s->y[k] = s->pen[k] * g[k] - lam[k];
        phi_tmult(s, s->y, s->tmp);
        for (int c = 0; c < n; ++c) s->tmp[c] += b[c];
        if (!ori__spd_solve(s->K, s->tmp, x)) return false;
        phi_mult(s, x, s->r);
        for (int k = 0; k < mr; ++k) {
            s->r[k] -= g[k];
            lam[k] += s->pen[k] * s->r[k];
        }
        if (norm_inf(s->r, mr) <= ORI_DYN_ALM_TOL * (gn + norm_inf(x, n))) return true;
    }
    return true; // the remaining error is far below the step's own; the projections follow
}

// Accelerations at (q, v) with the current forces; also sets the multipliers of the stops.
static bool accel(dyn *s, const double *q, const double *v, double *a)
{
    if (!assemble(s, q, v, true)) return false;
    int mr = s->rows + s->n;
    for (int k = 0; k < s->rows; ++k) s->phi[k] = s->gam[k];
    for (int c = 0; c < s->n; ++c) s->phi[s->rows + c] = 0.0;
    // Multipliers from zero at every evaluation: near a singular state the constraint rows that
    // lose rank converge slowly, and carrying their multipliers over would let them grow without
    // bound; from zero they stay a smooth function of the state.
    for (int k = 0; k < mr; ++k) s->lam[k] = 0.0;
    return alm(s, s->rhs, s->phi, s->lam, a);
}

// Gauss–Newton projection of q onto Φ = 0 (loops and stops): minimum-norm steps from
// (Φ_θᵀΦ_θ + μI)Δ = −Φ_θᵀΦ, μ = ORI_DYN_PROJECT_SHIFT × the largest diagonal entry, which
// stay exact where Φ_θ loses rank (the flat sheet), unlike the multiplier iteration. Uses K as
// scratch (the caller assembles again afterwards).
static bool project_position(dyn *s, double *q)
{
    int n = s->n, mr = s->rows + n;
    for (int it = 0; it < ORI_DYN_PROJECT_MAX; ++it) {
        to_edges(s, q, NULL);
        ori__loops_residual(&s->L, s->eth, s->phi);
        for (int c = 0; c < n; ++c) s->phi[s->rows + c] = s->held[c] ? q[c] - s->held_at[c] : 0.0;
        if (norm_inf(s->phi, mr) <= ORI_DYN_PROJECT_TOL) return true;
        ori__loops_jacobian(&s->L, s->eth, NULL, s->jac, NULL);
        ori__spd_zero(s->K);
        double diag = 1.0;
        for (int c = 0; c < n; ++c)
            if (s->held[c]) ori__spd_add(s->K, c, c, 1.0);
        for (int k = 0; k < s->L.count; ++k) {
            int nr = s->L.nrows[k];
            for (int i = s->L.first[k]; i < s->L.first[k] + s->L.size[k]; ++i) {
                int ci = s->t.col_of_edge[s->L.edge[i]];
                if (ci < 0) continue;
                for (int j = s->L.first[k]; j < s->L.first[k] + s->L.size[k]; ++j) {
                    int cj = s->t.col_of_edge[s->L.edge[j]];
                    if (cj < ci) continue;
                    double dot = 0.0;
                    for (int r = 0; r < nr; ++r) dot += s->jac[6 * (size_t)i + r] * s->jac[6 * (size_t)j + r];
                    ori__spd_add(s->K, ci, cj, dot);
                    if (ci == cj) diag = fmax(diag, dot);
                }
            }
        }
        for (int c = 0; c < n; ++c) ori__spd_add(s->K, c, c, ORI_DYN_PROJECT_SHIFT * diag);
        phi_tmult(s, s->phi, s->tmp);
        for (int c = 0; c < n; ++c) s->tmp[c] = -s->tmp[c];
        if (!ori__spd_factor(s->K) || !ori__spd_solve(s->K, s->tmp, s->x)) return false;
        for (int c = 0; c < n; ++c) q[c] += s->x[c];
    }
    return false;
}

// ½ vᵀ M v with M = K − Φᵀ·diag(pen)·Φ of the last assembly.
static double kinetic_of(dyn *s, const double *v)
{
    int n = s->n;
    ori__spd_mult(s->K, v, s->tmp2);
    phi_mult(s, v, s->r);
    for (int k = 0; k < s->rows + n; ++k) s->r[k] *= s->pen[k];
    phi_tmult(s, s->r, s->y);
    double e = 0.0;
    for (int c = 0; c < n; ++c) e += v[c] * (s->tmp2[c] - s->y[c]);
    return 0.5 * e;
}

// Mass-orthogonal projection of v onto the tangent space Φ_θ v = 0 (needs the assembly at q).
static bool project_velocity(dyn *s, double *v)
{
    int n = s->n, mr = s->rows + n;
    // M v = K v − Φᵀ·diag(pen)·Φ v.
    ori__spd_mult(s->K, v, s->tmp2);
    phi_mult(s, v, s->r);
    for (int k = 0; k < mr; ++k) s->r[k] *= s->pen[k];
    phi_tmult(s, s->r, s->y);
    double *mv = s->tmp2;
    for (int c = 0; c < n; ++c) mv[c] -= s->y[c];
    double *lam = ori__calloc((size_t)mr + 1, sizeof(double));
    double *mvc = ori__alloc(sizeof(double) * (size_t)(n + 1));
    memcpy(mvc, mv, sizeof(double) * (size_t)n);
    bool ok = alm(s, mvc, s->zero, lam, v);
    ori__free(lam);
    ori__free(mvc);
    return ok;
}

// --- set-up ----------------------------------------------------------------------------------

static void dyn_free(dyn *s)
{
    ori__spd_destroy(s->K);
    ori__loops_free(&s->L);
    ori__tree_free(&s->t);
    void *ptrs[] = {s->pen, s->mdiag, s->mfloor, s->sched_dir, s->stage_wire, s->held, s->held_at, s->lock_first, s->has_sec, s->sec, s->fib, s->damp, s->applied, s->target, s->start, s->stop,
                    s->w, s->lam, s->jac, s->gam, s->phi, s->poses, s->body, s->comp, s->S, s->Vf, s->Af, s->Wf,
                    s->Wext, s->eth, s->erate, s->rhs, s->x, s->y, s->r, s->tmp, s->tmp2, s->zero};
    for (size_t i = 0; i < sizeof ptrs / sizeof ptrs[0]; ++i) ori__free(ptrs[i]);
    memset(s, 0, sizeof *s);
}

// Inertia (kg·m²) of a face's panel about the crease of edge e.
static double panel_inertia_about(const ori_design *d, int face, int e)
{
    const ori_face_mass *fm = &d->mass[face];
    double mpu = d->meters_per_unit;
    ori_v3 a = ori_v3_scale(d->vertices[d->edges[e][0]], mpu), b = ori_v3_scale(d->vertices[d->edges[e][1]], mpu);
    ori_v3 w = ori_v3_normalize(ori_v3_sub(b, a));
    ori_v3 r = ori_v3_cross(ori_v3_sub(fm->centroid_m, a), w);
    return ori_v3_dot(w, ori_m3_apply(fm->inertia_kg_m2, w)) + fm->mass_kg * ori_v3_dot(r, r);
}

static double distance_to_axis(const ori_design *d, int face, int e)
{
    double mpu = d->meters_per_unit;
    ori_v3 a = ori_v3_scale(d->vertices[d->edges[e][0]], mpu), b = ori_v3_scale(d->vertices[d->edges[e][1]], mpu);
    ori_v3 w = ori_v3_normalize(ori_v3_sub(b, a));
    return ori_v3_norm(ori_v3_cross(ori_v3_sub(d->mass[face].centroid_m, a), w));
}

static int sgn(double x) { return (x > 0) - (x < 0); }

static ori_status dyn_init(dyn *s, const ori_simulation_def *def, double *q, double *longest_period, double *shortest_period,
                           ori_error *error)
{
    const ori_design *d = def->design;
    const ori_mechanism *m = def->mechanism;
    memset(s, 0, sizeof *s);
    s->d = d;
    s->m = m;
    s->E = ori_mechanism_edge_count(m);
    s->F = ori_mechanism_face_count(m);
    s->mpu = d->meters_per_unit;
    s->g0 = def->fixed_pose;
    s->gravity = d->act.gravity_m_s2;
    ori__tree_init(&s->t, m, def->fixed_face);
    ori__loops_init(&s->L, m, d->diagonal);
    int n = s->n = s->t.n, E = s->E, F = s->F;
    s->rows = s->L.rows;
    int mr = s->rows + n;
    s->has_sec = ori__calloc((size_t)E + 1, sizeof(bool));
    s->sec = ori__calloc((size_t)E + 1, sizeof(hinge_section));
    s->fib = ori__calloc((size_t)E + 1, sizeof(hinge_fibres));
    s->damp = ori__calloc((size_t)E + 1, sizeof(double));
    s->applied = ori__calloc((size_t)E + 1, sizeof(double));
    s->target = ori__calloc((size_t)E + 1, sizeof(double));
    s->start = ori__calloc((size_t)E + 1, sizeof(double));
    s->stop = ori__calloc((size_t)n + 1, sizeof(int));
    s->held = ori__calloc((size_t)n + 1, sizeof(bool));
    s->held_at = ori__calloc((size_t)n + 1, sizeof(double));
    s->w = ori__calloc((size_t)E + 1, sizeof(dyn_wire));
    s->sched_dir = ori__calloc(ORI_SCHEDULE_MAX, sizeof(int));
    s->lam = ori__calloc((size_t)mr + 1, sizeof(double));
    s->pen = ori__calloc((size_t)mr + 1, sizeof(double));
    s->mdiag = ori__calloc((size_t)n + 1, sizeof(double));
    s->mfloor = ori__calloc((size_t)n + 1, sizeof(double));
    s->phi = ori__calloc((size_t)mr + 1, sizeof(double));
    s->gam = ori__calloc((size_t)s->rows + 1, sizeof(double));
    s->zero = ori__calloc((size_t)mr + 1, sizeof(double));
    s->y = ori__calloc((size_t)mr + 1, sizeof(double));
    s->r = ori__calloc((size_t)mr + 1, sizeof(double));
    s->tmp2 = ori__calloc((size_t)mr + 1, sizeof(double));
    int entries = s->L.count ? s->L.first[s->L.count - 1] + s->L.size[s->L.count - 1] : 0;
    s->jac = ori__calloc(6 * (size_t)entries + 1, sizeof(double));
    s->poses = ori__calloc((size_t)F + 1, sizeof(ori_rigid));
    s->body = ori__calloc((size_t)F + 1, sizeof(body_inertia));
    s->comp = ori__calloc((size_t)F + 1, sizeof(body_inertia));
    s->S = ori__calloc((size_t)F + 1, sizeof(sv6));
    s->Vf = ori__calloc((size_t)F + 1, sizeof(sv6));
    s->Af = ori__calloc((size_t)F + 1, sizeof(sv6));
    s->Wf = ori__calloc((size_t)F + 1, sizeof(sv6));
    s->Wext = ori__calloc((size_t)F + 1, sizeof(sv6));
    s->eth = ori__calloc((size_t)E + 1, sizeof(double));
    s->erate = ori__calloc((size_t)E + 1, sizeof(double));
    s->rhs = ori__calloc((size_t)n + 1, sizeof(double));
    s->x = ori__calloc((size_t)n + 1, sizeof(double));
    s->tmp = ori__calloc((size_t)n + 1, sizeof(double));

    // Moving panels need mass.
    for (int f = 0; f < F; ++f)
        if (f != def->fixed_face && !(d->mass[f].mass_kg > 0.0))
            return ori__fail_at(error, ORI_ERR_ARGUMENT, "faces_orikin:panel", f,
                                "face %d moves but has no panel data (material and thickness)", f);
    // The start state, closed exactly.
    double *zeros = ori__calloc((size_t)E + 1, sizeof(double));
    ori_status st = ori_mechanism_pose_state(m, def->start_angles_rad ? def->start_angles_rad : zeros, def->fixed_face,
                                             def->fixed_pose, s->start, NULL, NULL, error);
    ori__free(zeros);
    if (st != ORI_OK) return st;
    for (int c = 0; c < n; ++c) {
        q[c] = s->start[s->t.edge_of_col[c]];
        if (def->stops && fabs(q[c]) >= ORI_PI) {
            s->stop[c] = sgn(q[c]);
            s->held[c] = true;
            s->held_at[c] = s->stop[c] * ORI_PI;
        }
    }
    for (int e = 0; e < E; ++e) {
        if (def->target_angles_rad) s->target[e] = def->target_angles_rad[e];
        else s->target[e] = d->assignment[e] == ORI_ASSIGN_VALLEY ? ORI_PI : d->assignment[e] == ORI_ASSIGN_MOUNTAIN ? -ORI_PI : 0.0;
        if (def->applied_moments_nm) s->applied[e] = def->applied_moments_nm[e];
    }
    // Hinges: stress-free at the start; damping as a fraction of critical for the panel beyond.
    double zeta = def->has_damping ? def->damping_ratio : d->act.damping_ratio;
    double wmax2 = 0.0, wmin2 = INFINITY;
    for (int c = 0; c < n; ++c) {
        int e = s->t.edge_of_col[c];
        int a = d->edge_faces[e][0], b = d->edge_faces[e][1];
        int mover = s->t.depth[a] >= s->t.depth[b] ? a : b;
        double J = panel_inertia_about(d, mover, e);
        s->mfloor[c] = J;
        double w2 = 0.0;
        if (ori__design_section(d, e, &s->sec[e])) {
            s->has_sec[e] = true;
            s->sec[e].rest = s->start[e];
            s->damp[e] = 2.0 * zeta * sqrt(s->sec[e].k * J);
            w2 += s->sec[e].k / J;
            wmin2 = fmin(wmin2, s->sec[e].k / J);
        }
        double g = ori_v3_norm(s->gravity);
        w2 += g * d->mass[mover].mass_kg * distance_to_axis(d, mover, e) / J;
        wmax2 = fmax(wmax2, w2);
    }
    // Wires.
    for (int e = 0; e < E; ++e) {
        int c = s->t.col_of_edge[e];
        if (c < 0 || !d->has_hinge[e] || !d->hinges[e].has_wire) continue;
        dyn_wire *w = &s->w[s->nw];
        w->edge = e;
        w->col = c;
        w->face = ori_design_wire_face(d, m, e, def->fixed_face);
        if (!ori__wire_segments(d, e, w->face, &w->seg))
            return ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_orikin:hinge", e,
                                "the wire lies outside face %d, the panel that moves", w->face);
        const ori_wire *wi = &d->hinges[e].wire;
        w->current = wi->has_current ? wi->current_a : def->current_a;
        w->on = w->current > 0.0;
        w->target = s->target[e];
        w->dir = fabs(w->target - s->start[e]) > ORI_DYN_TARGET_RAD ? sgn(w->target - s->start[e]) : 0;
        if (w->dir == 0) w->on = false;
        s->nw++;
        double J = panel_inertia_about(d, w->face, e);
        double ml = (double)wi->turns * w->current * wi->length_m * wi->lever_m;
        wmax2 = fmax(wmax2, ml * (d->act.has_field ? ori_v3_norm(d->act.field_t) : 0.0) / J);
    }
    // Field schedule.
    if (def->schedule_count > 0) {
        s->nsched = def->schedule_count;
        memcpy(s->sched, def->schedule, sizeof(ori_field_change) * (size_t)s->nsched);
    } else if (d->act.schedule_count > 0) {
        s->nsched = d->act.schedule_count;
        memcpy(s->sched, d->act.schedule, sizeof(ori_field_change) * (size_t)s->nsched);
    } else if (d->act.has_field) {
        s->nsched = 1;
        s->sched[0].edge = ORI_NULL_INDEX;
        s->sched[0].field_t = d->act.field_t;
    }
    s->field = s->nsched ? s->sched[0].field_t : ori_v3_make(0, 0, 0);
    s->sched_next = 1;
    int ref = d->act.reference_edge != ORI_NULL_INDEX ? d->act.reference_edge : s->nw ? s->w[0].edge : ORI_NULL_INDEX;
    for (int i = 0; i < s->nsched; ++i) {
        int e = s->sched[i].edge != ORI_NULL_INDEX ? s->sched[i].edge : ref;
        s->sched[i].edge = e;
        if (e == ORI_NULL_INDEX || s->t.col_of_edge[e] < 0) {
            if (i > 0)
                return ori__fail_at(error, ORI_ERR_ARGUMENT, "orikin:actuation", ORI_NULL_INDEX,
                                    "schedule %d: no crease to follow (name one with \"crease\")", i);
            continue;
        }
        int dir = sgn(s->target[e] - s->start[e]);
        s->sched_dir[i] = dir ? dir : sgn(s->sched[i].from_rad - s->start[e]);
    }
    // Stages: one wire at a time, in the order of the sequence's folds.
    s->auto_polarity = def->auto_polarity;
    if (def->stage_count > 0) {
        s->nstage = def->stage_count;
        s->stage_wire = ori__alloc(sizeof(int) * (size_t)s->nstage);
        for (int k = 0; k < s->nstage; ++k) {
            int e = def->stage_edges[k], found = -1;
            for (int i = 0; i < s->nw; ++i)
                if (s->w[i].edge == e) found = i;
            if (found < 0)
                return ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_orikin:hinge", e,
                                    "fold %d drives crease %d, which has no wire", k + 1, e);
            s->stage_wire[k] = found;
        }
        s->lock_first = ori__calloc((size_t)s->nstage + 1, sizeof(int));
        for (int k = 0; k < s->nstage; ++k) {
            int cnt = def->stage_lock_counts ? def->stage_lock_counts[k] : 0;
            s->lock_first[k + 1] = s->lock_first[k] + cnt;
        }
        s->lock_edges = def->stage_lock_edges;
        for (int k = 0; k < s->lock_first[s->nstage]; ++k) {
            int e = s->lock_edges[k];
            if (e < 0 || e >= E || s->t.col_of_edge[e] < 0)
                return ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_vertices", e, "a fold locks %d, which is not a crease that moves", e);
        }
        for (int i = 0; i < s->nw; ++i) s->w[i].on = false;
        s->stage = -1; // the first events switch stage 0 on
    }
    bool any_current = false;
    for (int i = 0; i < s->nw; ++i) any_current |= s->w[i].on || (s->nstage && s->w[i].current > 0.0);
    if (any_current && !(ori_v3_norm(s->field) > 0.0))
        return ori__fail_at(error, ORI_ERR_ARGUMENT, "orikin:actuation", ORI_NULL_INDEX,
                            "field: no magnetic field, so the currents exert no force");
    // Linear algebra pattern: mass matrix (a crease with its ancestors) and the loops.
    int pairs = 0, cap = 0;
    int *pi = NULL, *pj = NULL;
    for (int f = 0; f < F; ++f) {
        int i = s->t.pcol[f];
        if (i < 0) continue;
        for (int a = f; s->t.parent[a] != ORI_NULL_INDEX; a = s->t.parent[a])
            if (s->t.pcol[a] >= 0) {
                if (pairs == cap) {
                    cap = cap ? 2 * cap : 256;
                    pi = ori__realloc(pi, sizeof(int) * (size_t)cap);
                    pj = ori__realloc(pj, sizeof(int) * (size_t)cap);
                }
                pi[pairs] = i;
                pj[pairs++] = s->t.pcol[a];
            }
    }
    for (int k = 0; k < s->L.count; ++k)
        for (int i = s->L.first[k]; i < s->L.first[k] + s->L.size[k]; ++i)
            for (int j = s->L.first[k]; j < s->L.first[k] + s->L.size[k]; ++j) {
                int ci = s->t.col_of_edge[s->L.edge[i]], cj = s->t.col_of_edge[s->L.edge[j]];
                if (ci < 0 || cj < 0 || cj < ci) continue;
                if (pairs == cap) {
                    cap = cap ? 2 * cap : 256;
                    pi = ori__realloc(pi, sizeof(int) * (size_t)cap);
                    pj = ori__realloc(pj, sizeof(int) * (size_t)cap);
                }
                pi[pairs] = ci;
                pj[pairs++] = cj;
            }
    s->K = ori__spd_create(n, pairs, pi, pj);
    ori__free(pi);
    ori__free(pj);
    *shortest_period = wmax2 > 0 ? 2.0 * ORI_PI / sqrt(wmax2) : INFINITY;
    *longest_period = isfinite(wmin2) ? 2.0 * ORI_PI / sqrt(wmin2) : INFINITY;
    return ORI_OK;
}

// --- stepping --------------------------------------------------------------------------------

typedef struct dyn_state {
    double *q, *v, *a_pred, *q0, *v0, *am, *an;
    double t;
    double w_in, dissipated, residual_max, peak_rate;
    int steps, rescued;
} dyn_state;

// Each wire's polarity: its current drives its crease toward the target in the present pose
// and field (a wire on face_right turns the crease the other way).
static void set_polarity(dyn *s, dyn_wire *w)
{
    if (!s->auto_polarity || w->dir == 0) return;
    double mom = ori__wire_moment(s->d, w->edge, w->face, s->poses, 1.0, s->field);
    if (mom * w->dir < 0.0) w->current = -fabs(w->current);
    else w->current = fabs(w->current);
}

// Stage switching, field changes and currents off, at the start of a step (poses of the last
// assembly are those of the present state).
static bool events_before(dyn *s, dyn_state *x, const ori_simulation_def *def)
{
    int switched_on = -1;
    bool grabbed = false;
    if (s->nstage) {
        while (s->stage < s->nstage) {
            if (s->stage >= 0) {
                const dyn_wire *w = &s->w[s->stage_wire[s->stage]];
                if (!w->reached && w->dir != 0) break;
            }
            if (s->stage >= 0) s->w[s->stage_wire[s->stage]].on = false;
            // The stage's locks come off (stops stay); the next stage's creases are held where they are.
            if (s->stage >= 0)
                for (int k = s->lock_first[s->stage]; k < s->lock_first[s->stage + 1]; ++k) {
                    int c = s->t.col_of_edge[s->lock_edges[k]];
                    if (!s->stop[c]) s->held[c] = false;
                }
            s->stage++;
            if (s->stage < s->nstage)
                for (int k = s->lock_first[s->stage]; k < s->lock_first[s->stage + 1]; ++k) {
                    int c = s->t.col_of_edge[s->lock_edges[k]];
                    grabbed |= !s->held[c];
                    s->stop[c] = 0; // a crease at its stop stays there while locked
                    s->held[c] = true;
                    s->held_at[c] = s->held[c] && fabs(x->q[c]) >= ORI_PI ? sgn(x->q[c]) * ORI_PI : x->q[c];
                }
            if (s->stage < s->nstage) {
                dyn_wire *w = &s->w[s->stage_wire[s->stage]];
                w->on = w->current != 0.0 && w->dir != 0 && !w->reached;
                switched_on = s->stage_wire[s->stage];
            }
        }
    }
    while (s->sched_next < s->nsched) {
        const ori_field_change *c = &s->sched[s->sched_next];
        if (s->nstage && s->stage < c->fold) break;
        int col = s->t.col_of_edge[c->edge];
        bool later = s->nstage && s->stage > c->fold;
        if (!later && (x->q[col] - c->from_rad) * s->sched_dir[s->sched_next] < -ORI_DYN_TARGET_RAD) break;
        s->field = c->field_t;
        s->sched_next++;
    }
    if (switched_on >= 0) set_polarity(s, &s->w[switched_on]);
    for (int i = 0; i < s->nw; ++i) {
        dyn_wire *w = &s->w[i];
        if (!w->on) continue;
        if ((def->current_off_at_target && w->reached) || (def->has_pulse && x->t >= def->pulse_s)) w->on = false;
    }
    return grabbed;
}

static void events_after(dyn *s, dyn_state *x, double h)
{
    for (int i = 0; i < s->nw; ++i) {
        dyn_wire *w = &s->w[i];
        if (w->reached || w->dir == 0) continue;
        double a = x->q0[w->col], b = x->q[w->col];
        if ((b - w->target) * w->dir < -ORI_DYN_TARGET_RAD) continue;
        double frac = b != a ? (w->target - a) / (b - a) : 1.0;
        frac = frac < 0 ? 0 : frac > 1 ? 1 : frac;
        w->reached = true;
        w->t_reached = x->t - h + frac * h;
    }
}

// One implicit-midpoint step of length h from (x->q, x->v); false when the iteration fails,
// unless `rescue`: then the iterate that changed least is taken (a step of the explicit
// midpoint kind), as at a singular start where the midpoint equation may have no solution.
static bool midpoint_step(dyn *s, dyn_state *x, double h, bool rescue, ori_status *fatal, ori_error *error)
{
    int n = s->n;
    memcpy(x->q0, x->q, sizeof(double) * (size_t)n);
    memcpy(x->v0, x->v, sizeof(double) * (size_t)n);
    memcpy(x->am, x->a_pred, sizeof(double) * (size_t)n);
    double prev = INFINITY;
    bool ok = false;
    int its = rescue ? 2 : ORI_DYN_ITER_MAX;
    for (int it = 0; it < its; ++it) {
        for (int c = 0; c < n; ++c) {
            x->v[c] = x->v0[c] + 0.5 * h * x->am[c];
            x->q[c] = x->q0[c] + 0.5 * h * x->v[c];
        }
        if (!accel(s, x->q, x->v, x->an)) {
            *fatal = ori__fail(error, ORI_ERR_NOT_CONVERGED, "the mass matrix is singular at t = %g s", x->t);
            return false;
        }
        double diff = 0.0, scale = 0.0;
        for (int c = 0; c < n; ++c) {
            diff = fmax(diff, fabs(x->an[c] - x->am[c]));
            scale = fmax(scale, fabs(x->v0[c]) + h * fabs(x->an[c]));
            x->am[c] = x->an[c];
        }
        diff *= 0.5 * h;
        // Converged, or settled at the rounding level of the constrained solve.
        if (diff <= ORI_DYN_ITER_TOL * scale ||
            (it >= 2 && diff >= ORI_DYN_ITER_STALL_RATIO * prev && diff <= ORI_DYN_ITER_STALL * scale)) {
            ok = true;
            break;
        }
        if (it >= 3 && diff > prev) break; // diverging
        prev = diff;
    }
    if (rescue && !ok) {
        ok = true;
        x->rescued++;
    }
    if (!ok) {
        memcpy(x->q, x->q0, sizeof(double) * (size_t)n);
        memcpy(x->v, x->v0, sizeof(double) * (size_t)n);
        return false;
    }
    // Work and damping at the midpoint (the last evaluation).
    x->w_in += h * s->power_in;
    x->dissipated += h * s->power_damp;
    for (int c = 0; c < n; ++c) {
        double vmid = x->v0[c] + 0.5 * h * x->am[c];
        x->v[c] = x->v0[c] + h * x->am[c];
        x->q[c] = x->q0[c] + h * vmid;
    }
    return true;
}

static bool finish_step(dyn *s, dyn_state *x, const ori_simulation_def *def, double h, ori_status *fatal, ori_error *error)
{
    int n = s->n;
    // Creases that hit their ±180° stop.
    bool impact = false;
    if (def->stops)
        for (int c = 0; c < n; ++c)
            if (!s->held[c] && fabs(x->q[c]) > ORI_PI) {
                s->stop[c] = sgn(x->q[c]);
                s->held[c] = true;
                s->held_at[c] = s->stop[c] * ORI_PI;
                impact = true;
            }
    if (constrained(s)) {
        double before = 0.0;
        bool ok = project_position(s, x->q) && assemble(s, x->q, x->v, false);
        if (ok && impact) before = kinetic_of(s, x->v);
        ok = ok && project_velocity(s, x->v);
        if (!ok) {
            *fatal = ori__fail(error, ORI_ERR_NOT_CONVERGED, "the loops could not be closed at t = %g s", x->t + h);
            return false;
        }
        // A perfectly inelastic impact on a stop dissipates the kinetic energy it removes.
        if (impact) x->dissipated += before - kinetic_of(s, x->v);
    }
    // Commit the hinges' plastic flow at the new (projected) angles.
    for (int c = 0; c < n; ++c) {
        int e = s->t.edge_of_col[c];
        if (!s->has_sec[e]) continue;
        double diss = 0.0;
        ori__hinge_moment(&s->sec[e], &s->fib[e], x->q[c], &s->fib[e], &diss);
        x->dissipated += diss;
    }
    x->t += h;
    x->steps++;
    events_after(s, x, h);
    if (!accel(s, x->q, x->v, x->an)) {
        *fatal = ori__fail(error, ORI_ERR_NOT_CONVERGED, "the mass matrix is singular at t = %g s", x->t);
        return false;
    }
    for (int c = 0; c < n; ++c) {
        x->a_pred[c] = 2.0 * x->an[c] - x->am[c];
        x->peak_rate = fmax(x->peak_rate, fabs(x->v[c]));
        if (s->stop[c] && s->stop[c] * s->lam[s->rows + c] < 0.0) {
            s->stop[c] = 0; // the stop pulls: the crease leaves it
            s->held[c] = false;
            s->lam[s->rows + c] = 0.0;
        }
    }
    to_edges(s, x->q, NULL);
    x->residual_max = fmax(x->residual_max, ori_mechanism_residual(s->m, s->eth));
    return true;
}

static bool advance(dyn *s, dyn_state *x, const ori_simulation_def *def, double h, int depth, ori_status *fatal,
                    ori_error *error)
{
    if (events_before(s, x, def)) {
        // Creases just held: their rates stop (a perfectly inelastic grab).
        double before = 0.0;
        if (!assemble(s, x->q, x->v, false) || (before = kinetic_of(s, x->v), !project_velocity(s, x->v))) {
            *fatal = ori__fail(error, ORI_ERR_NOT_CONVERGED, "the loops could not be closed at t = %g s", x->t);
            return false;
        }
        x->dissipated += before - kinetic_of(s, x->v);
    }
    if (midpoint_step(s, x, h, depth >= ORI_DYN_MAX_HALVINGS, fatal, error)) return finish_step(s, x, def, h, fatal, error);
    if (*fatal != ORI_OK) return false;
    return advance(s, x, def, 0.5 * h, depth + 1, fatal, error) && advance(s, x, def, 0.5 * h, depth + 1, fatal, error);
}

// Mechanical energy at the last assembly (kinetic) and the committed hinges; gravity potential.
static double energy(const dyn *s, const dyn_state *x, double *vg)
{
    double e = s->kinetic;
    for (int c = 0; c < s->n; ++c) {
        int ed = s->t.edge_of_col[c];
        if (s->has_sec[ed]) e += ori__hinge_energy(&s->sec[ed], &s->fib[ed], x->q[c]);
    }
    double g = 0.0;
    for (int f = 0; f < s->F; ++f) g -= ori_v3_dot(s->gravity, s->body[f].h);
    *vg = g;
    return e + g;
}

// --- results ---------------------------------------------------------------------------------

void ori_simulation_destroy(ori_simulation *r)
{
    if (!r) return;
    void *ptrs[] = {r->time, r->angles, r->currents, r->plastic, r->kin, r->total, r->res, r->field, r->latched};
    for (size_t i = 0; i < sizeof ptrs / sizeof ptrs[0]; ++i) ori__free(ptrs[i]);
    ori__free(r);
}

static void record(ori_simulation *r, const dyn *s, const dyn_state *x, double total)
{
    int k = r->frames++, E = r->E;
    r->time[k] = x->t;
    double *ang = r->angles + (size_t)k * (size_t)E, *cur = r->currents + (size_t)k * (size_t)E,
           *pl = r->plastic + (size_t)k * (size_t)E;
    for (int e = 0; e < E; ++e) {
        int c = s->t.col_of_edge[e];
        ang[e] = c >= 0 ? x->q[c] : 0.0;
        cur[e] = 0.0;
        pl[e] = c >= 0 && s->has_sec[e] ? ori__hinge_plastic_rotation(&s->sec[e], &s->fib[e], x->q[c]) : 0.0;
    }
    for (int i = 0; i < s->nw; ++i) cur[s->w[i].edge] = s->w[i].on ? s->w[i].current : 0.0;
    r->kin[k] = s->kinetic;
    r->total[k] = total;
    r->field[k] = s->field;
    r->res[k] = ori_mechanism_residual(s->m, ang);
}

ori_status ori_simulation_run(const ori_simulation_def *def, ori_simulation **out, ori_error *error)
{
    ORI_ASSERT(def && out && def->internal_value == ORI__DEF_COOKIE && def->design && def->mechanism);
    *out = NULL;
    const ori_mechanism *m = def->mechanism;
    int E = ori_mechanism_edge_count(m), F = ori_mechanism_face_count(m);
    if (E != def->design->edge_count || F != def->design->face_count)
        return ori__fail(error, ORI_ERR_ARGUMENT, "the design and the mechanism are not of the same pattern");
    if (def->fixed_face < 0 || def->fixed_face >= F)
        return ori__fail_at(error, ORI_ERR_RANGE, "faces_vertices", def->fixed_face, "no face %d (the sheet has %d)",
                            def->fixed_face, F);
    if (!(isfinite(def->duration_s) && def->duration_s > 0.0))
        return ori__fail(error, ORI_ERR_RANGE, "the duration must be a positive time in seconds");
    if (def->has_dt && !(isfinite(def->dt_s) && def->dt_s > 0.0 && def->dt_s <= def->duration_s))
        return ori__fail(error, ORI_ERR_RANGE, "the time step must be positive and at most the duration (%g s)",
                         def->duration_s);
    if (!(isfinite(def->current_a) && def->current_a >= 0.0))
        return ori__fail(error, ORI_ERR_RANGE, "the current must be >= 0 amperes");
    if (def->has_damping && !(isfinite(def->damping_ratio) && def->damping_ratio >= 0.0))
        return ori__fail(error, ORI_ERR_RANGE, "the damping ratio must be >= 0");
    if (def->output_frames < 2) return ori__fail(error, ORI_ERR_RANGE, "at least 2 output frames");
    if ((double)def->output_frames * (double)(E + 1) > ORI_DYN_MAX_FRAME_VALUES)
        return ori__fail(error, ORI_ERR_LIMIT, "%d frames of %d creases are more than the %g values kept", def->output_frames, E,
                         (double)ORI_DYN_MAX_FRAME_VALUES);
    if (def->schedule_count < 0 || def->schedule_count > ORI_SCHEDULE_MAX || (def->schedule_count && !def->schedule))
        return ori__fail(error, ORI_ERR_RANGE, "at most %d schedule entries", ORI_SCHEDULE_MAX);
    for (int i = 0; i < def->schedule_count; ++i)
        if (!(ori_v3_norm(def->schedule[i].field_t) > 0.0))
            return ori__fail_at(error, ORI_ERR_ARGUMENT, "orikin:actuation", ORI_NULL_INDEX,
                                "schedule %d: the magnetic field is zero", i);

    dyn s;
    int n_coords = 0;
    {
        mech_tree t;
        ori__tree_init(&t, m, def->fixed_face);
        n_coords = t.n;
        ori__tree_free(&t);
    }
    dyn_state x;
    memset(&x, 0, sizeof x);
    size_t nb = sizeof(double) * (size_t)(n_coords + 1);
    x.q = ori__calloc(1, nb), x.v = ori__calloc(1, nb), x.a_pred = ori__calloc(1, nb), x.q0 = ori__calloc(1, nb);
    x.v0 = ori__calloc(1, nb), x.am = ori__calloc(1, nb), x.an = ori__calloc(1, nb);
    ori_simulation *r = NULL;
    double t_long = INFINITY, t_short = INFINITY;
    ori_status st = dyn_init(&s, def, x.q, &t_long, &t_short, error);
    if (st != ORI_OK) goto fail;
    if (s.n == 0) {
        st = ori__fail(error, ORI_ERR_ARGUMENT, "the sheet has no crease that can move");
        goto fail;
    }
    if (def->start_rates_rad_s)
        for (int c = 0; c < s.n; ++c) x.v[c] = def->start_rates_rad_s[s.t.edge_of_col[c]];
    // Polarity: each wire pushes its crease toward its target at the start.
    if (!assemble(&s, x.q, x.v, false) || (constrained(&s) && !project_velocity(&s, x.v))) {
        st = ori__fail(error, ORI_ERR_ARGUMENT, "the moving panels have no inertia about their creases");
        goto fail;
    }
    if (!s.nstage)
        for (int i = 0; i < s.nw; ++i) set_polarity(&s, &s.w[i]);
    int frames = def->output_frames;
    double frame_dt = def->duration_s / (double)(frames - 1);
    double dt = def->has_dt ? def->dt_s : fmin(t_short / ORI_DYN_STEPS_PER_PERIOD, def->duration_s / 100.0);
    // The work a simulation asks for is bounded before it starts (a step of 1e-300 s once
    // overflowed the step count and silently fell back on the default step).
    double steps = ceil(frame_dt / dt) * (double)(frames - 1);
    double max_steps = def->max_steps > 0 ? fmin((double)def->max_steps, ORI_DYN_MAX_STEPS) : ORI_DYN_MAX_STEPS;
    if (!(steps <= max_steps)) {
        st = ori__fail(error, ORI_ERR_LIMIT,
                       "%.3g time steps of %.3g s over %.3g s are more than the %.3g a simulation takes: a larger time step "
                       "(at least %.3g s) or a shorter duration",
                       steps, dt, def->duration_s, max_steps, def->duration_s / max_steps);
        goto fail;
    }
    int per = (int)ceil(frame_dt / dt);
    if (per < 1) per = 1;
    double h = frame_dt / per;
    r = ori__calloc(1, sizeof *r);
    r->E = E;
    r->V = ori_mechanism_vertex_count(m);
    r->m = m;
    r->fixed = def->fixed_face;
    r->g0 = def->fixed_pose;
    r->time = ori__calloc((size_t)frames, sizeof(double));
    r->kin = ori__calloc((size_t)frames, sizeof(double));
    r->total = ori__calloc((size_t)frames, sizeof(double));
    r->res = ori__calloc((size_t)frames, sizeof(double));
    r->field = ori__calloc((size_t)frames, sizeof(ori_v3));
    r->angles = ori__calloc((size_t)frames * (size_t)E + 1, sizeof(double));
    r->currents = ori__calloc((size_t)frames * (size_t)E + 1, sizeof(double));
    r->plastic = ori__calloc((size_t)frames * (size_t)E + 1, sizeof(double));
    r->latched = ori__calloc((size_t)E + 1, sizeof(double));
    if (events_before(&s, &x, def) && !(assemble(&s, x.q, x.v, false) && project_velocity(&s, x.v))) {
        st = ori__fail(error, ORI_ERR_NOT_CONVERGED, "the loops could not be closed at the start");
        goto fail;
    }
    if (!accel(&s, x.q, x.v, x.a_pred)) {
        st = ori__fail(error, ORI_ERR_NOT_CONVERGED, "the mass matrix is singular at the start");
        goto fail;
    }
    double vg0, e0 = energy(&s, &x, &vg0), vg;
    double scale = fabs(e0 - vg0), drift = 0.0;
    to_edges(&s, x.q, NULL);
    x.residual_max = ori_mechanism_residual(m, s.eth);
    record(r, &s, &x, e0);
    for (int k = 1; k < frames; ++k) {
        for (int i = 0; i < per; ++i) {
            if (!advance(&s, &x, def, h, 0, &st, error)) goto fail;
            double e = energy(&s, &x, &vg);
            scale = fmax(scale, fabs(e - vg) + fabs(vg - vg0));
            drift = fmax(drift, fabs(e - e0 - x.w_in + x.dissipated));
        }
        x.t = def->duration_s * (double)k / (double)(frames - 1); // no drift of the clock
        record(r, &s, &x, energy(&s, &x, &vg));
        if (def->progress && !def->progress((double)k / (double)(frames - 1), def->progress_user)) {
            st = ori__fail(error, ORI_ERR_LIMIT, "cancelled");
            goto fail;
        }
    }
    r->sum.reached_target = s.nw > 0;
    r->sum.time_to_target_s = 0.0;
    for (int i = 0; i < s.nw; ++i) {
        if (s.w[i].dir == 0) continue;
        r->sum.reached_target &= s.w[i].reached;
        r->sum.time_to_target_s = fmax(r->sum.time_to_target_s, s.w[i].t_reached);
    }
    bool any_dir = false;
    for (int i = 0; i < s.nw; ++i) any_dir |= s.w[i].dir != 0;
    r->sum.reached_target &= any_dir;
    scale = fmax(scale, fmax(fabs(x.w_in), x.dissipated));
    r->sum.energy_drift = scale > 0 ? drift / scale : 0.0;
    r->sum.energy_in_j = x.w_in;
    r->sum.dissipated_j = x.dissipated;
    r->sum.dt_s = h;
    // Latched state: currents off, critically damped hinges, until it comes to rest.
    if (def->settle && isfinite(t_long)) {
        for (int i = 0; i < s.nw; ++i) s.w[i].on = false;
        double z = fmax(1.0, def->has_damping ? def->damping_ratio : s.d->act.damping_ratio);
        for (int c = 0; c < s.n; ++c) {
            int e = s.t.edge_of_col[c];
            if (!s.has_sec[e]) continue;
            int a = s.d->edge_faces[e][0], b = s.d->edge_faces[e][1];
            int mover = s.t.depth[a] >= s.t.depth[b] ? a : b;
            s.damp[e] = 2.0 * z * sqrt(s.sec[e].k * panel_inertia_about(s.d, mover, e));
        }
        // Bounded by the steps left of the budget (a count computed in double: a long period over
        // a short step would overflow an int).
        double left = max_steps - (double)x.steps;
        int nsteps = (int)fmax(0.0, fmin(ceil(ORI_DYN_SETTLE_PERIODS * t_long / h), left));
        double peak = 0.0;
        for (int i = 0; i < nsteps; ++i) {
            if (!advance(&s, &x, def, h, 0, &st, error)) goto fail;
            peak = fmax(peak, s.kinetic);
            if (i > 0 && s.kinetic <= ORI_DYN_SETTLE_KINETIC * peak) break;
        }
    }
    for (int e = 0; e < E; ++e) {
        int c = s.t.col_of_edge[e];
        r->latched[e] = c >= 0 ? x.q[c] : 0.0;
    }
    r->sum.peak_angular_velocity = x.peak_rate;
    r->sum.max_residual = x.residual_max;
    r->sum.steps = x.steps;
    r->sum.explicit_steps = x.rescued;
    *out = r;
    st = ORI_OK;
    r = NULL;
fail:
    ori_simulation_destroy(r);
    dyn_free(&s);
    ori__free(x.q), ori__free(x.v), ori__free(x.a_pred), ori__free(x.q0), ori__free(x.v0), ori__free(x.am), ori__free(x.an);
    return st;
}

int ori_simulation_frame_count(const ori_simulation *r) { return r->frames; }

double ori_simulation_frame_time(const ori_simulation *r, int k)
{
    ORI_ASSERT(r && k >= 0 && k < r->frames);
    return r->time[k];
}

const double *ori_simulation_frame_angles(const ori_simulation *r, int k)
{
    ORI_ASSERT(r && k >= 0 && k < r->frames);
    return r->angles + (size_t)k * (size_t)r->E;
}

const double *ori_simulation_frame_currents(const ori_simulation *r, int k)
{
    ORI_ASSERT(r && k >= 0 && k < r->frames);
    return r->currents + (size_t)k * (size_t)r->E;
}

const double *ori_simulation_frame_plastic(const ori_simulation *r, int k)
{
    ORI_ASSERT(r && k >= 0 && k < r->frames);
    return r->plastic + (size_t)k * (size_t)r->E;
}

ori_v3 ori_simulation_frame_field(const ori_simulation *r, int k)
{
    ORI_ASSERT(r && k >= 0 && k < r->frames);
    return r->field[k];
}

void ori_simulation_frame_energy(const ori_simulation *r, int k, double *kinetic, double *total)
{
    ORI_ASSERT(r && k >= 0 && k < r->frames);
    if (kinetic) *kinetic = r->kin[k];
    if (total) *total = r->total[k];
}

double ori_simulation_frame_residual(const ori_simulation *r, int k)
{
    ORI_ASSERT(r && k >= 0 && k < r->frames);
    return r->res[k];
}

void ori_simulation_frame_vertices(const ori_simulation *r, int k, ori_v3 *positions)
{
    ORI_ASSERT(r && positions && k >= 0 && k < r->frames);
    ori_mechanism_vertex_positions(r->m, r->angles + (size_t)k * (size_t)r->E, r->fixed, r->g0, positions);
}

const double *ori_simulation_latched_angles(const ori_simulation *r)
{
    ORI_ASSERT(r);
    return r->latched;
}

ori_simulation_summary ori_simulation_summary_of(const ori_simulation *r)
{
    ORI_ASSERT(r);
    return r->sum;
}
