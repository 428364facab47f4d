// Transfer functions (thesis ch. 5.1 "Curve Fitting", 9.5): the constrained crease angles as
// polynomials of the driven angle. Least squares by QR (LAPACKE_dgels) in the scaled variable
// t = (x − c)/w ∈ [−1, 1] (c the centre, w the half-width of the sampled range), where the
// Vandermonde matrix is well conditioned; the coefficients are then expanded to monomials of x
// (radians). The error is measured with those monomial coefficients against exact solutions on a
// grid `refine` times finer. Exact solving stays the default everywhere else.
#include <lapacke.h>
#include <math.h>

#include "kinematics_internal.h"

struct ori_fit {
    int degree;
    int count;
    int samples;
    ori_fit_crease *creases;
    double *coef; // count × (degree + 1), monomials of x
};

ori_fit_def ori_default_fit_def(void)
{
    ori_fit_def d;
    d.motion = ori_default_motion_def();
    d.degree = 4;
    d.refine = 10;
    d.internal_value = ORI__DEF_COOKIE;
    return d;
}

void ori_fit_destroy(ori_fit *f)
{
    if (!f) return;
    ori__free(f->creases);
    ori__free(f->coef);
    ori__free(f);
}

static double binom(int n, int k)
{
    double r = 1.0;
    for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
    return r;
}

static double horner(const double *c, int degree, double x)
{
    double y = 0.0;
    for (int k = degree; k >= 0; --k) y = y * x + c[k];
    return y;
}

static ori_status verdict_error(const ori_motion *mo, ori_error *error)
{
    const char *why = ori_motion_reason(mo);
    return ori__fail(error, ORI_ERR_ARGUMENT, "the fold is %s: %s", ori_motion_verdict_name(ori_motion_verdict_of(mo)),
                     why ? why : "");
}

ori_status ori_fit_solve(const ori_mechanism *m, const ori_fit_def *def, ori_fit **out, ori_error *error)
{
    ORI_ASSERT(m && def && def->internal_value == ORI__DEF_COOKIE && out);
    *out = NULL;
    if (def->degree < 0 || def->degree > 12)
        return ori__fail(error, ORI_ERR_RANGE, "the polynomial degree must be 0 to 12 (got %d)", def->degree);
    if (def->refine < 1) return ori__fail(error, ORI_ERR_RANGE, "refine must be at least 1 (got %d)", def->refine);
    ori_motion *coarse = NULL, *fine = NULL;
    ori_status st = ori_motion_solve(m, &def->motion, &coarse, error);
    if (st != ORI_OK) return st;
    if (ori_motion_verdict_of(coarse) != ORI_MOTION_VALID) {
        st = verdict_error(coarse, error);
        ori_motion_destroy(coarse);
        return st;
    }
    int n = ori_motion_frame_count(coarse), d = def->degree, E = m->edge_count;
    if (n < d + 1) {
        ori_motion_destroy(coarse);
        return ori__fail(error, ORI_ERR_ARGUMENT, "degree %d needs at least %d samples; the fold gives %d (use a smaller step)",
                         d, d + 1, n);
    }
    ori_motion_def fd = def->motion;
    fd.step_rad = def->motion.step_rad / def->refine;
    st = ori_motion_solve(m, &fd, &fine, error);
    if (st != ORI_OK || ori_motion_verdict_of(fine) != ORI_MOTION_VALID) {
        if (st == ORI_OK) st = verdict_error(fine, error);
        ori_motion_destroy(coarse);
        ori_motion_destroy(fine);
        return st;
    }
    // Constrained creases: revolute, not driven, angle changing over the samples.
    const double *a0 = ori_motion_frame_angles(coarse, 0);
    int *edges = ori__alloc(sizeof(int) * (size_t)(E + 1));
    int count = 0;
    for (int e = 0; e < E; ++e) {
        int j = m->edge_joint[e];
        if (j == ORI_NULL_INDEX || e == def->motion.driven_edge || m->joints[j].kind != ORI_JOINT_REVOLUTE) continue;
        double dev = 0.0;
        for (int k = 0; k < n; ++k) dev = fmax(dev, fabs(ori_motion_frame_angles(coarse, k)[e] - a0[e]));
        if (dev > ORI_TOL_FOLD_SIGN_RAD) edges[count++] = e;
    }
    double x0 = ori_motion_frame_drive(coarse, 0), x1 = ori_motion_frame_drive(coarse, n - 1);
    double c = 0.5 * (x0 + x1), w = 0.5 * fabs(x1 - x0);
    if (!(w > 0.0)) {
        ori__free(edges);
        ori_motion_destroy(coarse);
        ori_motion_destroy(fine);
        return ori__fail(error, ORI_ERR_ARGUMENT, "the fold's range is empty");
    }
    int nr = count > 0 ? count : 1;
    double *V = ori__alloc(sizeof(double) * (size_t)n * (size_t)(d + 1));
    double *Y = ori__calloc((size_t)n * (size_t)nr, sizeof(double));
    for (int k = 0; k < n; ++k) {
        double t = (ori_motion_frame_drive(coarse, k) - c) / w, p = 1.0;
        for (int q = 0; q <= d; ++q, p *= t) V[k + (size_t)n * q] = p;
        for (int i = 0; i < count; ++i) Y[k + (size_t)n * i] = ori_motion_frame_angles(coarse, k)[edges[i]];
    }
    lapack_int info = LAPACKE_dgels(LAPACK_COL_MAJOR, 'N', n, d + 1, nr, V, n, Y, n);
    ori_fit *f = ori__calloc(1, sizeof *f);
    f->degree = d;
    f->count = count;
    f->samples = n;
    f->creases = ori__alloc(sizeof(ori_fit_crease) * (size_t)nr);
    f->coef = ori__calloc((size_t)nr * (size_t)(d + 1), sizeof(double));
    for (int i = 0; i < count && info == 0; ++i) {
        // θ = Σ a_q ((x − c)/w)^q = Σ_q a_q w^−q Σ_r C(q, r) x^r (−c)^(q−r).
        double *mono = f->coef + (size_t)i * (d + 1);
        for (int q = 0; q <= d; ++q) {
            double aq = Y[q + (size_t)n * i] / pow(w, q);
            for (int r = 0; r <= q; ++r) mono[r] += aq * binom(q, r) * pow(-c, q - r);
        }
        double err = 0.0;
        for (int k = 0; k < ori_motion_frame_count(fine); ++k) {
            double x = ori_motion_frame_drive(fine, k);
            err = fmax(err, fabs(horner(mono, d, x) - ori_motion_frame_angles(fine, k)[edges[i]]));
        }
        f->creases[i].edge = edges[i];
        f->creases[i].max_error_rad = err;
    }
    ori__free(V);
    ori__free(Y);
    ori__free(edges);
    ori_motion_destroy(coarse);
    ori_motion_destroy(fine);
    if (info != 0) {
        ori_fit_destroy(f);
        return ori__fail(error, ORI_ERR_INTERNAL, "least-squares fit failed (LAPACK info %d)", (int)info);
    }
    *out = f;
    return ORI_OK;
}

int ori_fit_crease_count(const ori_fit *f) { ORI_ASSERT(f); return f->count; }
int ori_fit_sample_count(const ori_fit *f) { ORI_ASSERT(f); return f->samples; }

ori_fit_crease ori_fit_crease_of(const ori_fit *f, int i)
{
    ORI_ASSERT(f && i >= 0 && i < f->count);
    return f->creases[i];
}

int ori_fit_coefficients(const ori_fit *f, int i, double *out, int cap)
{
    ORI_ASSERT(f && i >= 0 && i < f->count);
    for (int k = 0; k <= f->degree && k < cap; ++k) out[k] = f->coef[(size_t)i * (f->degree + 1) + k];
    return f->degree + 1;
}

double ori_fit_eval(const ori_fit *f, int i, double x)
{
    ORI_ASSERT(f && i >= 0 && i < f->count);
    return horner(f->coef + (size_t)i * (f->degree + 1), f->degree, x);
}
