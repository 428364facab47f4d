// Element formulas of the bar-and-hinge model: the fold angle of a hinge, its exact gradient
// (the dihedral-angle derivatives of Schenk & Guest / Liu & Paulino's MERLIN, used by Origami
// Simulator too) and its Hessian by complex-step differentiation of that gradient (every
// operation of the gradient is analytic, so Im ∇ρ(x + ih eₐ)/h is the column a of ∇²ρ to
// machine precision, with no subtractive cancellation); the energy, gradient and Hessian of a
// whole state.
//
// Hinge j → k with wings i (left of j → k in the flat sheet) and l (right):
//   r_ij = x_i − x_j, r_kj = x_k − x_j, r_kl = x_k − x_l, m = r_ij × r_kj, n = r_kj × r_kl,
//   ρ = atan2((m × n)·r_kj/|r_kj|, −m·n)   (0 flat, + valley: the wings rise toward +z)
//   ∂ρ/∂x_i = −|r_kj|/|m|² m,  ∂ρ/∂x_l = |r_kj|/|n|² n,
//   ∂ρ/∂x_j = (r_ij·r_kj/|r_kj|² − 1) ∂ρ/∂x_i − (r_kl·r_kj/|r_kj|²) ∂ρ/∂x_l,
//   ∂ρ/∂x_k = (r_kl·r_kj/|r_kj|² − 1) ∂ρ/∂x_l − (r_ij·r_kj/|r_kj|²) ∂ρ/∂x_i.
#include <complex.h>

#include "compliant_internal.h"

// Complex-step size relative to the model's length scale.
#define CMP_COMPLEX_STEP 1e-30

static double wrap_pi(double a)
{
    while (a > ORI_PI) a -= 2.0 * ORI_PI;
    while (a <= -ORI_PI) a += 2.0 * ORI_PI;
    return a;
}

void ori__cmp_set_ref(cmp_hinge *h, double ref)
{
    h->ref = ref;
    h->cache_ref = ref;
    h->cref = cos(ref);
    h->sref = sin(ref);
}

// The angle of (cth, s) unwrapped about ref: ref + the angle turned from ref, in (−π, π]. About the
// hinge's cached reference (the usual case: the last accepted angle) the turn is the atan2 of the
// pair rotated by −ref, and a small turn (|tan| ≤ 1/8, every step of the explicit solver) is its
// Taylor series (to t⁹ up to 1/64, to t¹⁷ beyond; truncation below 1e-18): no atan2 call.
static inline double unwrap(const cmp_hinge *h, double ref, double s, double cth)
{
    if (ref != h->cache_ref) return ref + wrap_pi(atan2(s, cth) - ref);
    double y = s * h->cref - cth * h->sref, xx = cth * h->cref + s * h->sref;
    if (xx > 0.0 && fabs(y) <= 0.015625 * xx) { // |t| ≤ 1/64: to t⁹ (truncation below 1e-21)
        double t = y / xx, t2 = t * t;
        double p = 1.0 / 3.0 - t2 * (1.0 / 5.0 - t2 * (1.0 / 7.0 - t2 * (1.0 / 9.0)));
        return ref + t * (1.0 - t2 * p);
    }
    if (xx > 0.0 && fabs(y) <= 0.125 * xx) {
        double t = y / xx, t2 = t * t;
        double p = 1.0 / 17.0;
        p = 1.0 / 15.0 - t2 * p;
        p = 1.0 / 13.0 - t2 * p;
        p = 1.0 / 11.0 - t2 * p;
        p = 1.0 / 9.0 - t2 * p;
        p = 1.0 / 7.0 - t2 * p;
        p = 1.0 / 5.0 - t2 * p;
        p = 1.0 / 3.0 - t2 * p;
        return ref + t * (1.0 - t2 * p);
    }
    return ref + atan2(y, xx);
}

double ori__cmp_hinge_angle(const double *x, const cmp_hinge *h, double ref)
{
    const double *xj = x + 3 * h->j, *xk = x + 3 * h->k, *xi = x + 3 * h->i, *xl = x + 3 * h->l;
    double rij[3], rkj[3], rkl[3], m[3], n[3], mn[3];
    for (int q = 0; q < 3; ++q) {
        rij[q] = xi[q] - xj[q];
        rkj[q] = xk[q] - xj[q];
        rkl[q] = xk[q] - xl[q];
    }
    m[0] = rij[1] * rkj[2] - rij[2] * rkj[1];
    m[1] = rij[2] * rkj[0] - rij[0] * rkj[2];
    m[2] = rij[0] * rkj[1] - rij[1] * rkj[0];
    n[0] = rkj[1] * rkl[2] - rkj[2] * rkl[1];
    n[1] = rkj[2] * rkl[0] - rkj[0] * rkl[2];
    n[2] = rkj[0] * rkl[1] - rkj[1] * rkl[0];
    mn[0] = m[1] * n[2] - m[2] * n[1];
    mn[1] = m[2] * n[0] - m[0] * n[2];
    mn[2] = m[0] * n[1] - m[1] * n[0];
    double len = sqrt(rkj[0] * rkj[0] + rkj[1] * rkj[1] + rkj[2] * rkj[2]);
    double s = (mn[0] * rkj[0] + mn[1] * rkj[1] + mn[2] * rkj[2]) / (len > 0.0 ? len : 1.0);
    double cth = -(m[0] * n[0] + m[1] * n[1] + m[2] * n[2]);
    return unwrap(h, ref, s, cth);
}

// A hinge's angle about h->ref and its gradient (as gradient_real), sharing r, m, n. Written in
// scalars: vectors on the stack, stored one lane and loaded two, stall the store forwarding.
static double hinge_angle_gradient(const double *x, const cmp_hinge *h, double *g)
{
    const double *xj = x + 3 * h->j, *xk = x + 3 * h->k, *xi = x + 3 * h->i, *xl = x + 3 * h->l;
    double ax = xi[0] - xj[0], ay = xi[1] - xj[1], az = xi[2] - xj[2]; // r_ij
    double kx = xk[0] - xj[0], ky = xk[1] - xj[1], kz = xk[2] - xj[2]; // r_kj
    double lx = xk[0] - xl[0], ly = xk[1] - xl[1], lz = xk[2] - xl[2]; // r_kl
    double mx = ay * kz - az * ky, my = az * kx - ax * kz, mz = ax * ky - ay * kx; // m = r_ij × r_kj
    double nx = ky * lz - kz * ly, ny = kz * lx - kx * lz, nz = kx * ly - ky * lx; // n = r_kj × r_kl
    double cx = my * nz - mz * ny, cy = mz * nx - mx * nz, cz = mx * ny - my * nx; // m × n
    double kk = kx * kx + ky * ky + kz * kz;
    double len = sqrt(kk), ikk = 1.0 / kk;
    // the angle's sine and cosine both times |r_kj| (its atan2 does not see a common scale)
    double s = cx * kx + cy * ky + cz * kz;
    double cth = -(mx * nx + my * ny + mz * nz) * len;
    double mm = mx * mx + my * my + mz * mz, nn = nx * nx + ny * ny + nz * nz;
    double a = (ax * kx + ay * ky + az * kz) * ikk, b = (lx * kx + ly * ky + lz * kz) * ikk;
    double imn = len / (mm * nn), fi = -nn * imn, fl = mm * imn;
    double gix = fi * mx, giy = fi * my, giz = fi * mz, glx = fl * nx, gly = fl * ny, glz = fl * nz;
    g[6] = gix, g[7] = giy, g[8] = giz, g[9] = glx, g[10] = gly, g[11] = glz;
    g[0] = (a - 1.0) * gix - b * glx, g[1] = (a - 1.0) * giy - b * gly, g[2] = (a - 1.0) * giz - b * glz;
    g[3] = (b - 1.0) * glx - a * gix, g[4] = (b - 1.0) * gly - a * giy, g[5] = (b - 1.0) * glz - a * giz;
    return unwrap(h, h->ref, s, cth);
}

// The gradient, written once for real and complex coordinates.
#define CMP_HINGE_GRADIENT(T, SQRT, NAME)                                                         \
    static void NAME(const T *xj, const T *xk, const T *xi, const T *xl, T *g)                   \
    {                                                                                            \
        T rij[3], rkj[3], rkl[3], m[3], n[3];                                                    \
        for (int q = 0; q < 3; ++q) {                                                            \
            rij[q] = xi[q] - xj[q];                                                              \
            rkj[q] = xk[q] - xj[q];                                                              \
            rkl[q] = xk[q] - xl[q];                                                              \
        }                                                                                        \
        m[0] = rij[1] * rkj[2] - rij[2] * rkj[1];                                                \
        m[1] = rij[2] * rkj[0] - rij[0] * rkj[2];                                                \
        m[2] = rij[0] * rkj[1] - rij[1] * rkj[0];                                                \
        n[0] = rkj[1] * rkl[2] - rkj[2] * rkl[1];                                                \
        n[1] = rkj[2] * rkl[0] - rkj[0] * rkl[2];                                                \
        n[2] = rkj[0] * rkl[1] - rkj[1] * rkl[0];                                                \
        T kk = rkj[0] * rkj[0] + rkj[1] * rkj[1] + rkj[2] * rkj[2];                              \
        T len = SQRT(kk);                                                                        \
        T mm = m[0] * m[0] + m[1] * m[1] + m[2] * m[2];                                          \
        T nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];                                          \
        T a = (rij[0] * rkj[0] + rij[1] * rkj[1] + rij[2] * rkj[2]) / kk;                        \
        T b = (rkl[0] * rkj[0] + rkl[1] * rkj[1] + rkl[2] * rkj[2]) / kk;                        \
        T *gj = g, *gk = g + 3, *gi = g + 6, *gl = g + 9;                                        \
        for (int q = 0; q < 3; ++q) {                                                            \
            gi[q] = -len / mm * m[q];                                                            \
            gl[q] = len / nn * n[q];                                                             \
        }                                                                                        \
        for (int q = 0; q < 3; ++q) {                                                            \
            gj[q] = (a - 1.0) * gi[q] - b * gl[q];                                               \
            gk[q] = (b - 1.0) * gl[q] - a * gi[q];                                               \
        }                                                                                        \
    }

// The square root of a complex step's coordinate a + ib, |b| ≪ a: √a + i b / (2√a), exact to
// first order in b, which is all a complex step keeps (b ~ 1e-30 of the scale, so the next term
// is below 1e-60 of it). csqrt's general branch cuts and scalings cost a fifth of the Hessian.
static inline double complex csqrt_step(double complex z)
{
    double r = sqrt(creal(z));
    return r + cimag(z) / (2.0 * r) * I;
}

CMP_HINGE_GRADIENT(double, sqrt, gradient_real)
CMP_HINGE_GRADIENT(double complex, csqrt_step, gradient_complex)

void ori__cmp_hinge_gradient(const double *x, const cmp_hinge *h, double g[12])
{
    gradient_real(x + 3 * h->j, x + 3 * h->k, x + 3 * h->i, x + 3 * h->l, g);
}

void ori__cmp_hinge_hessian(const double *x, const cmp_hinge *h, double hess[144])
{
    const int node[4] = {h->j, h->k, h->i, h->l};
    double complex z[12], g[12];
    double scale = 0.0;
    for (int a = 0; a < 4; ++a)
        for (int q = 0; q < 3; ++q) {
            z[3 * a + q] = x[3 * node[a] + q];
            scale = fmax(scale, fabs(x[3 * node[a] + q] - x[3 * node[0] + q]));
        }
    double step = CMP_COMPLEX_STEP * (scale > 0.0 ? scale : 1.0);
    for (int col = 0; col < 12; ++col) {
        z[col] += step * I;
        gradient_complex(z, z + 3, z + 6, z + 9, g);
        z[col] = creal(z[col]);
        for (int row = 0; row < 12; ++row) hess[row * 12 + col] = cimag(g[row]) / step;
    }
    // Symmetrize (the exact Hessian is symmetric; this removes the last roundoff).
    for (int r = 0; r < 12; ++r)
        for (int cc = r + 1; cc < 12; ++cc) {
            double s = 0.5 * (hess[r * 12 + cc] + hess[cc * 12 + r]);
            hess[r * 12 + cc] = hess[cc * 12 + r] = s;
        }
}

double ori__cmp_hinge_energy(const ori_compliant *c, int hh, double theta, double fraction, double *d1, double *d2)
{
    const cmp_hinge *h = &c->hinges[hh];
    double rest = h->crease ? h->target * fraction : 0.0;
    if (c->hplastic && c->hplastic[hh]) {
        hinge_section s = c->hsec[hh];
        s.rest = rest;
        return ori__hinge_potential(&s, &c->hfib[hh], theta, d1, d2);
    }
    double d = theta - rest;
    if (d1) *d1 = h->k_h * d;
    if (d2) *d2 = h->k_h;
    return 0.5 * h->k_h * d * d;
}

void ori__cmp_commit_fibres(ori_compliant *c, const double *x, double fraction)
{
    if (!c->hplastic) return;
    for (int hh = 0; hh < c->nhinge; ++hh) {
        if (!c->hplastic[hh]) continue;
        const cmp_hinge *h = &c->hinges[hh];
        hinge_section s = c->hsec[hh];
        s.rest = h->crease ? h->target * fraction : 0.0;
        ori__hinge_moment(&s, &c->hfib[hh], ori__cmp_hinge_angle(x, h, h->ref), &c->hfib[hh], NULL);
    }
}

// A wire loop's point k at positions x.
void ori__cmp_wire_point(const ori_compliant *c, int k, const double *x, double p[3])
{
    const cmp_wpt *w = &c->wpts[k];
    for (int q = 0; q < 3; ++q) p[q] = w->w[0] * x[3 * w->v[0] + q] + w->w[1] * x[3 * w->v[1] + q] + w->w[2] * x[3 * w->v[2] + q];
}

static void cross3(const double *a, const double *b, double *out)
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

// The wires' energy −Σ ni·fraction·B·A(loop) and its gradient (added to grad).
static double wires_energy(const ori_compliant *c, const double *x, double fraction, double *grad)
{
    double e = 0.0, B[3] = {c->field.x, c->field.y, c->field.z};
    for (int w = 0; w < c->nwire; ++w) {
        const cmp_wire *wr = &c->wires[w];
        double s = wr->ni * fraction;
        if (s == 0.0) continue;
        int n = wr->count;
        double area[3] = {0, 0, 0};
        for (int i = 0; i < n; ++i) {
            double p[3], q[3], cr[3];
            ori__cmp_wire_point(c, wr->first + i, x, p);
            ori__cmp_wire_point(c, wr->first + (i + 1) % n, x, q);
            cross3(p, q, cr);
            for (int r = 0; r < 3; ++r) area[r] += 0.5 * cr[r];
            if (!grad) continue;
            // ∂(B·A)/∂p_i = ½ (p_{i+1} − p_{i−1}) × B: this pair gives p_i ½ p_{i+1} × B and p_{i+1} −½ p_i × B
            double fq[3], fp[3];
            cross3(q, B, fq);
            cross3(p, B, fp);
            const cmp_wpt *a = &c->wpts[wr->first + i], *b = &c->wpts[wr->first + (i + 1) % n];
            for (int t = 0; t < 3; ++t)
                for (int r = 0; r < 3; ++r) {
                    grad[3 * a->v[t] + r] -= s * 0.5 * a->w[t] * fq[r];
                    grad[3 * b->v[t] + r] += s * 0.5 * b->w[t] * fp[r];
                }
        }
        e -= s * (B[0] * area[0] + B[1] * area[1] + B[2] * area[2]);
    }
    return e;
}

double ori__cmp_energy(const ori_compliant *c, const double *x, double fraction, double *grad)
{
    double e = 0.0;
    if (grad)
        for (int k = 0; k < 3 * c->nv; ++k) grad[k] = 0.0;
    for (int b = 0; b < c->nbar; ++b) {
        const cmp_bar *bar = &c->bars[b];
        const double *xa = x + 3 * bar->a, *xb = x + 3 * bar->b;
        double d[3] = {xb[0] - xa[0], xb[1] - xa[1], xb[2] - xa[2]};
        double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        double s = len - bar->l0;
        e += 0.5 * bar->k * s * s;
        if (grad && len > 0.0) {
            double f = bar->k * s / len;
            for (int q = 0; q < 3; ++q) {
                grad[3 * bar->b + q] += f * d[q];
                grad[3 * bar->a + q] -= f * d[q];
            }
        }
    }
    for (int hh = 0; hh < c->nhinge; ++hh) {
        const cmp_hinge *h = &c->hinges[hh];
        double m;
        e += ori__cmp_hinge_energy(c, hh, ori__cmp_hinge_angle(x, h, h->ref), fraction, &m, NULL);
        if (grad) {
            double g[12];
            ori__cmp_hinge_gradient(x, h, g);
            const int node[4] = {h->j, h->k, h->i, h->l};
            for (int a = 0; a < 4; ++a)
                for (int q = 0; q < 3; ++q) grad[3 * node[a] + q] += m * g[3 * a + q];
        }
    }
    if (c->nwire) e += wires_energy(c, x, fraction, grad);
    double g = c->def.gravity * c->gravity_factor;
    if (g != 0.0)
        for (int v = 0; v < c->nv; ++v) {
            e += c->mass[v] * g * (x[3 * v + 2] - c->x0[3 * v + 2]);
            if (grad) grad[3 * v + 2] += c->mass[v] * g;
        }
    if (grad)
        for (int v = 0; v < c->nv; ++v)
            if (c->dof[v] < 0) grad[3 * v] = grad[3 * v + 1] = grad[3 * v + 2] = 0.0;
    return e;
}

void ori__cmp_forces_range(const ori_compliant *c, const double *x, double fraction, double *grad, int bar0, int bar1,
                           int hinge0, int hinge1)
{
    for (int b = bar0; b < bar1; ++b) {
        const cmp_bar *bar = &c->bars[b];
        const double *xa = x + 3 * bar->a, *xb = x + 3 * bar->b;
        double dx = xb[0] - xa[0], dy = xb[1] - xa[1], dz = xb[2] - xa[2]; // scalars, as in hinge_angle_gradient
        double len = sqrt(dx * dx + dy * dy + dz * dz);
        if (!(len > 0.0)) continue;
        double f = bar->k * (len - bar->l0) / len;
        double *ga = grad + 3 * bar->a, *gb = grad + 3 * bar->b;
        gb[0] += f * dx, gb[1] += f * dy, gb[2] += f * dz;
        ga[0] -= f * dx, ga[1] -= f * dy, ga[2] -= f * dz;
    }
    for (int hh = hinge0; hh < hinge1; ++hh) {
        const cmp_hinge *h = &c->hinges[hh];
        double g[12], m;
        double th = hinge_angle_gradient(x, h, g);
        if (c->hplastic && c->hplastic[hh]) ori__cmp_hinge_energy(c, hh, th, fraction, &m, NULL);
        else m = h->k_h * (th - (h->crease ? h->target * fraction : 0.0));
        double *gj = grad + 3 * h->j, *gk = grad + 3 * h->k, *gi = grad + 3 * h->i, *gl = grad + 3 * h->l;
        for (int q = 0; q < 3; ++q) {
            gj[q] += m * g[q];
            gk[q] += m * g[3 + q];
            gi[q] += m * g[6 + q];
            gl[q] += m * g[9 + q];
        }
    }
}

void ori__cmp_wire_forces(const ori_compliant *c, const double *x, double fraction, double *grad)
{
    if (c->nwire) wires_energy(c, x, fraction, grad);
}

void ori__cmp_forces_finish(const ori_compliant *c, const double *x, double fraction, double *grad)
{
    if (c->nwire) wires_energy(c, x, fraction, grad);
    double gr = c->def.gravity * c->gravity_factor;
    if (gr != 0.0)
        for (int v = 0; v < c->nv; ++v) grad[3 * v + 2] += c->mass[v] * gr;
    for (int v = 0; v < c->nv; ++v)
        if (c->dof[v] < 0) grad[3 * v] = grad[3 * v + 1] = grad[3 * v + 2] = 0.0;
}

void ori__cmp_forces(const ori_compliant *c, const double *x, double fraction, double *grad)
{
    memset(grad, 0, sizeof(double) * 3 * (size_t)c->nv);
    ori__cmp_forces_range(c, x, fraction, grad, 0, c->nbar, 0, c->nhinge);
    ori__cmp_forces_finish(c, x, fraction, grad);
}

void ori__cmp_face_strain(const ori_compliant *c, const double *x, double *energy, double *strain)
{
    for (int f = 0; f < c->nf; ++f) energy[f] = strain[f] = 0.0;
    for (int b = 0; b < c->nbar; ++b) {
        const cmp_bar *bar = &c->bars[b];
        const double *xa = x + 3 * bar->a, *xb = x + 3 * bar->b;
        double d[3] = {xb[0] - xa[0], xb[1] - xa[1], xb[2] - xa[2]};
        double s = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - bar->l0;
        double e = 0.5 * bar->k * s * s, eps = fabs(s) / bar->l0;
        int n = bar->face[1] >= 0 ? 2 : 1;
        for (int q = 0; q < n; ++q) {
            energy[bar->face[q]] += e / n;
            strain[bar->face[q]] = fmax(strain[bar->face[q]], eps);
        }
    }
    for (int hh = 0; hh < c->nhinge; ++hh) {
        const cmp_hinge *h = &c->hinges[hh];
        if (h->crease) continue;
        double d = ori__cmp_hinge_angle(x, h, h->ref);
        double e = 0.5 * h->k_h * d * d;
        int n = h->face[1] >= 0 ? 2 : 1;
        for (int q = 0; q < n; ++q) energy[h->face[q]] += e / n;
    }
}

double ori__cmp_grad_norm(const ori_compliant *c, const double *grad)
{
    double n = 0.0;
    for (int v = 0; v < c->nv; ++v)
        if (c->dof[v] >= 0)
            for (int q = 0; q < 3; ++q) n = fmax(n, fabs(grad[3 * v + q]));
    return n;
}

// Position of vertex a in vertex b's list of lower neighbours (a's dof < b's), by bisection; -1
// never happens for pairs of the model (the pattern holds them all).
static int neighbour(const ori_compliant *c, int a, int b)
{
    int lo = c->nb_start[b], hi = c->nb_start[b + 1] - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        if (c->nb[mid] == a) return mid - c->nb_start[b];
        if (c->dof[c->nb[mid]] < c->dof[a]) lo = mid + 1;
        else hi = mid - 1;
    }
    return -1;
}

// Add the node block K (3 × 3, K[p][q] = ∂²E/∂x_a,p ∂x_b,q) of nodes a, b (a ≠ b or a = b). Column
// dof(b) + q holds b's lower neighbours' rows (3 each, in order), then b's own rows 0 … q: one
// bisection finds the block, not one an entry.
static void add_block(ori_compliant *c, double *val, int a, int b, double K[3][3])
{
    if (c->dof[a] < 0 || c->dof[b] < 0) return;
    if (a == b) {
        const int *cp = c->colptr + c->dof[a];
        int own = 3 * (c->nb_start[a + 1] - c->nb_start[a]);
        for (int q = 0; q < 3; ++q)
            for (int p = 0; p <= q; ++p) val[cp[q] + own + p] += K[p][q];
        return;
    }
    bool fwd = c->dof[a] < c->dof[b];
    int lo = fwd ? a : b, hi = fwd ? b : a;
    int pos = neighbour(c, lo, hi);
    if (pos < 0) return;
    const int *cp = c->colptr + c->dof[hi];
    for (int q = 0; q < 3; ++q) {
        double *col = val + cp[q] + 3 * pos;
        for (int p = 0; p < 3; ++p) col[p] += fwd ? K[p][q] : K[q][p];
    }
}

void ori__cmp_hessian(ori_compliant *c, const double *x, double fraction, bool psd)
{
    ori__sls_clear_values(c->sls);
    double *val = ori__sls_values(c->sls);
    for (int b = 0; b < c->nbar; ++b) {
        const cmp_bar *bar = &c->bars[b];
        const double *xa = x + 3 * bar->a, *xb = x + 3 * bar->b;
        double u[3] = {xb[0] - xa[0], xb[1] - xa[1], xb[2] - xa[2]};
        double len = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        if (!(len > 0.0)) continue;
        for (int q = 0; q < 3; ++q) u[q] /= len;
        double geo = 1.0 - bar->l0 / len; // the geometric (stress) stiffness factor
        if (psd && geo < 0.0) geo = 0.0;
        double K[3][3], N[3][3];
        for (int p = 0; p < 3; ++p)
            for (int q = 0; q < 3; ++q) {
                K[p][q] = bar->k * (u[p] * u[q] + geo * ((p == q) - u[p] * u[q]));
                N[p][q] = -K[p][q];
            }
        add_block(c, val, bar->a, bar->a, K);
        add_block(c, val, bar->b, bar->b, K);
        add_block(c, val, bar->a, bar->b, N);
    }
    for (int hh = 0; hh < c->nhinge; ++hh) {
        const cmp_hinge *h = &c->hinges[hh];
        double d1, d2;
        ori__cmp_hinge_energy(c, hh, ori__cmp_hinge_angle(x, h, h->ref), fraction, &d1, &d2);
        double g[12], H[144];
        ori__cmp_hinge_gradient(x, h, g);
        if (psd) memset(H, 0, sizeof H);
        else ori__cmp_hinge_hessian(x, h, H);
        const int node[4] = {h->j, h->k, h->i, h->l};
        for (int a = 0; a < 4; ++a)
            for (int b = a; b < 4; ++b) {
                double K[3][3];
                for (int p = 0; p < 3; ++p)
                    for (int q = 0; q < 3; ++q) {
                        int r = 3 * a + p, s = 3 * b + q;
                        K[p][q] = d2 * g[r] * g[s] + d1 * H[r * 12 + s];
                    }
                add_block(c, val, node[a], node[b], K);
            }
    }
    // The wires' energy is bilinear in the loop points: ∂²/∂p_i∂p_{i+1} of −(s/2) B·(p_i × p_{i+1})
    // is (s/2)[B]×. Skew, so a vertex's own block gets nothing; indefinite, so the positive
    // semi-definite fallback leaves it out.
    if (psd) return;
    for (int w = 0; w < c->nwire; ++w) {
        const cmp_wire *wr = &c->wires[w];
        double s = 0.5 * wr->ni * fraction;
        if (s == 0.0) continue;
        double Bx[3][3] = {{0.0, -c->field.z, c->field.y}, {c->field.z, 0.0, -c->field.x}, {-c->field.y, c->field.x, 0.0}};
        for (int i = 0; i < wr->count; ++i) {
            const cmp_wpt *a = &c->wpts[wr->first + i], *b = &c->wpts[wr->first + (i + 1) % wr->count];
            for (int ta = 0; ta < 3; ++ta)
                for (int tb = 0; tb < 3; ++tb) {
                    if (a->v[ta] == b->v[tb] || a->w[ta] == 0.0 || b->w[tb] == 0.0) continue;
                    double K[3][3], f = s * a->w[ta] * b->w[tb];
                    for (int p = 0; p < 3; ++p)
                        for (int q = 0; q < 3; ++q) K[p][q] = f * Bx[p][q];
                    add_block(c, val, a->v[ta], b->v[tb], K);
                }
        }
    }
}
