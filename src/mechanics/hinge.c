// Hinge and wire formulas (thesis eq. 1.1 and 1.2) and the layered elastoplastic section used
// by the dynamics.
//
// The thesis treats gold as elastic–perfectly plastic: the bending moment grows until the hinge
// yields and then stays at M_req = ¼·w·t²·σ_y. A rectangular section does this gradually: the
// outer fibres yield first (M_y = σ_y·w·t²/6, at the yield rotation θ_y = M_y/k), and the
// moment tends to M_p = 1.5·M_y as the plastic zones spread inward: M = M_p(1 − ⅓(θ_y/θ)²).
// Unloading is elastic, which is the springback; what remains is the permanent (latched) fold.
// The dynamics follows any history (loading, unloading, reversal) with a stack of
// elastic–perfectly-plastic fibres through the thickness, each carrying strain κ·z with the
// curvature κ = (θ − θ_rest)/span uniform over the hinge's span.
#include "mechanics_internal.h"

double ori_hinge_yield_moment(double yield_strength_pa, double width_m, double thickness_m)
{
    return yield_strength_pa * width_m * thickness_m * thickness_m / 6.0;
}

double ori_hinge_plastic_moment(double yield_strength_pa, double width_m, double thickness_m)
{
    return 0.25 * width_m * thickness_m * thickness_m * yield_strength_pa;
}

double ori_hinge_stiffness(double youngs_modulus_pa, double width_m, double thickness_m, double span_m)
{
    return youngs_modulus_pa * width_m * thickness_m * thickness_m * thickness_m / (12.0 * span_m);
}

double ori_hinge_monotonic_moment(double k, double m_y, double rotation_rad)
{
    ORI_ASSERT(k > 0.0 && m_y > 0.0 && !isnan(rotation_rad));
    double th_y = m_y / k, a = fabs(rotation_rad);
    if (a <= th_y) return k * rotation_rad;
    double r = th_y / a;
    double m = 1.5 * m_y * (1.0 - r * r / 3.0);
    return rotation_rad < 0.0 ? -m : m;
}

double ori_wire_resistance(double resistivity_ohm_m, double length_m, double width_m, double thickness_m)
{
    return resistivity_ohm_m * length_m / (width_m * thickness_m);
}

double ori_lorentz_axis_moment(ori_v3 axis_point, ori_v3 axis_dir, ori_v3 wire_center, ori_v3 wire_dir, double length_m,
                               int turns, double current_a, ori_v3 field_t)
{
    ori_v3 f = ori_v3_scale(ori_v3_cross(wire_dir, field_t), (double)turns * current_a * length_m);
    return ori_v3_dot(axis_dir, ori_v3_cross(ori_v3_sub(wire_center, axis_point), f));
}

// --- layered section -------------------------------------------------------------------------
//
// N fibres of equal thickness at normalised depths ζ_i = (2i + 1)/N − 1 (z = ζ·t/2). With their
// positions scaled by c = 1/(1 − 1/N²) and their areas by 1/c, the fibre sums reproduce the
// elastic stiffness E·w·t³/12 and the plastic moment ¼·σ_y·w·t² exactly (the midpoint sums
// alone miss the stiffness by 1/N²). Strains are in units of the yield strain, rotations in
// units of θ_y (the rotation that brings the outer surface to yield): fibre i has strain
// e_i = u·c·ζ_i at u = (θ − θ_rest)/θ_y, stress s_i = clamp(e_i − p_i, −1, 1) σ_y, and
// M = M_p·(2/N)·Σ s_i ζ_i. Pure bending keeps the section antisymmetric, so only the upper
// half is stored.

static const double layers = (double)ORI_HINGE_LAYERS;

static double zeta(int i) { return (2.0 * (double)(i + ORI__HALF_LAYERS) + 1.0) / layers - 1.0; }
static double scale_c(void) { return 1.0 / (1.0 - 1.0 / (layers * layers)); }

double ori__hinge_moment(const hinge_section *s, const hinge_fibres *from, double theta, hinge_fibres *to,
                         double *dissipated)
{
    double u = (theta - s->rest) / s->th_y, c = scale_c();
    double sum = 0.0, diss = 0.0;
    for (int i = 0; i < ORI__HALF_LAYERS; ++i) {
        double z = zeta(i), e = u * c * z, p = from->p[i];
        double st = e - p;
        if (st > 1.0) {
            diss += (e - 1.0 - p);
            p = e - 1.0;
            st = 1.0;
        } else if (st < -1.0) {
            diss -= (e + 1.0 - p);
            p = e + 1.0;
            st = -1.0;
        }
        if (to) to->p[i] = p;
        sum += st * z;
    }
    // Plastic work: σ_y·ε_y·Δp per unit volume, over both halves; σ_y·ε_y·w·t·span = 2·M_p·θ_y.
    if (dissipated) *dissipated = 2.0 * s->m_p * s->th_y * (2.0 / (layers * c)) * diss;
    return s->m_p * (4.0 / layers) * sum;
}

double ori__hinge_energy(const hinge_section *s, const hinge_fibres *f, double theta)
{
    double u = (theta - s->rest) / s->th_y, c = scale_c();
    double sum = 0.0;
    for (int i = 0; i < ORI__HALF_LAYERS; ++i) {
        double st = u * c * zeta(i) - f->p[i];
        sum += st * st;
    }
    // ½·E·(ε − ε_p)² per unit volume: ½·σ_y·ε_y·s² → M_p·θ_y·(2/(N·c))·Σ_upper s².
    return s->m_p * s->th_y * (2.0 / (layers * c)) * sum;
}

double ori__hinge_plastic_rotation(const hinge_section *s, const hinge_fibres *f, double theta)
{
    double m = ori__hinge_moment(s, f, theta, NULL, NULL);
    return theta - s->rest - m / s->k;
}

double ori__hinge_potential(const hinge_section *s, const hinge_fibres *from, double theta, double *moment, double *tangent)
{
    double u = (theta - s->rest) / s->th_y, c = scale_c();
    double phi = 0.0, sum = 0.0, stiff = 0.0;
    for (int i = 0; i < ORI__HALF_LAYERS; ++i) {
        double z = zeta(i), st = u * c * z - from->p[i];
        if (st > 1.0) {
            phi += st - 0.5;
            sum += z;
        } else if (st < -1.0) {
            phi += -st - 0.5;
            sum -= z;
        } else {
            phi += 0.5 * st * st;
            sum += st * z;
            stiff += c * z * z;
        }
    }
    // Per fibre ½s² while elastic, ½ + (|s| − 1) beyond yield (the plastic work of the step):
    // the same scale as ori__hinge_energy, whose derivative is the moment above.
    if (moment) *moment = s->m_p * (4.0 / layers) * sum;
    if (tangent) *tangent = s->m_p * (4.0 / layers) * stiff / s->th_y;
    return s->m_p * s->th_y * (4.0 / (layers * c)) * phi;
}
