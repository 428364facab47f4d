// Lorentz actuation of compliant panels (issue 23): the thesis' flap (a 10 µm silicon flap on a
// 0.6 µm gold hinge, a wire 500 µm from it, a field across the crease) in the bar-and-hinge model
// with the design's panels, layered gold hinge and wire. Checked against closed forms: the elastic
// balance k·θ = N·I·w·L·B·cos θ, the rigid model's moment at the same angle, the plastic balance
// with the monotonic moment law and the elastic springback once the current stops; the wire's
// energy gradient against finite differences; polarity; bad input.
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <orikin/orikin.h>

#include "compliant/compliant_internal.h"
#include "support.h"

TestSuite(compliant_lorentz, .init = test_leak_setup, .fini = test_leak_check);

#define DEG (ORI_PI / 180.0)

typedef struct flap {
    ori_fold *doc;
    ori_pattern *p;
    ori_design *d;
    ori_hinge_mechanics hm;
    double nwlb; // N·w·L·B per ampere (N·m/A)
} flap;

static flap load_flap(bool gravity)
{
    flap x;
    ori_error err;
    cr_assert_eq(ori_fold_load_file(test_repo_path("examples/patterns/thesis-flap.fold"), &x.doc, &err), ORI_OK, "%s",
                 err.message);
    cr_assert_eq(ori_fold_get_pattern(x.doc, 0, NULL, &x.p, &err), ORI_OK, "%s", err.message);
    ori_design_def dd = ori_default_design_def();
    dd.doc = x.doc;
    dd.pattern = x.p;
    cr_assert_eq(ori_design_create(&dd, &x.d, &err), ORI_OK, "%s", err.message);
    cr_assert(ori_design_hinge_mechanics(x.d, 0, &x.hm));
    ori_hinge h;
    cr_assert(ori_design_hinge(x.d, 0, &h));
    ori_actuation a = ori_design_actuation(x.d);
    x.nwlb = h.wire.turns * h.wire.length_m * h.wire.lever_m * ori_v3_norm(a.field_t);
    (void)gravity;
    return x;
}

static void flap_free(flap *x)
{
    ori_design_destroy(x->d);
    ori_pattern_destroy(x->p);
    ori_fold_destroy(x->doc);
}

// The compliant model of the flap with its design, the substrate (face 0) held, the crease's
// rest angle flat (the wire folds it), current I at fraction 1.
static ori_compliant *flap_model(const flap *x, double current_a, double *zeros)
{
    ori_compliant_def d = ori_compliant_physical_def();
    d.design = x->d;
    d.fixed_face = 0;
    d.field_t = ori_design_actuation(x->d).field_t;
    d.current_a = current_a;
    d.target_angles_rad = zeros;
    d.keep_frames = true;
    ori_compliant *c = NULL;
    ori_error err;
    cr_assert_eq(ori_compliant_create(x->p, &d, &c, &err), ORI_OK, "%s", err.message);
    return c;
}

// θ with k·θ = M·cos θ (Newton from M/k).
static double elastic_balance(double k, double m)
{
    double t = m / k;
    for (int i = 0; i < 60; ++i) t -= (k * t - m * cos(t)) / (k + m * sin(t));
    return t;
}

Test(compliant_lorentz, elastic_flap_balances_the_hinge_against_the_lorentz_moment)
{
    flap x = load_flap(false);
    double zeros[7] = {0};
    // half the current that would bring the hinge to first yield at flat
    double I = 0.5 * x.hm.yield_moment_nm / x.nwlb;
    ori_compliant *c = flap_model(&x, I, zeros);
    cr_assert_eq(ori_compliant_wire_count(c), 1);
    ori_error err;
    cr_assert_eq(ori_compliant_solve_static(c, &err), ORI_OK, "%s", err.message);
    double th = ori_compliant_fold_angle(c, 0);
    double want = elastic_balance(x.hm.stiffness_nm_rad, I * x.nwlb);
    printf("elastic flap: %.9g deg (closed form %.9g), max strain %.3g\n", th / DEG, want / DEG, ori_compliant_max_strain(c));
    // valley by polarity; the panels (10 µm silicon against 0.6 µm gold) bend by far less than 1e-6
    cr_assert(th > 0.0);
    cr_assert_lt(fabs(th - want), 1e-6 * want, "%.12g vs %.12g", th, want);
    cr_assert_lt(fabs(ori_compliant_wire_current(c, 0)), I * (1 + 1e-15));
    cr_assert_eq(ori_compliant_wire_current(c, 1), 0.0);
    // elastic: no permanent rotation, and the current's ramp is a path of equilibria
    cr_assert_lt(fabs(ori_compliant_plastic_rotation(c, 0)), 1e-12);
    cr_assert_gt(ori_compliant_frame_count(c), 8);
    for (int k = 1; k < ori_compliant_frame_count(c); ++k) {
        double f = ori_compliant_frame_fraction(c, k), a = ori_compliant_frame_angles(c, k)[0];
        double w = elastic_balance(x.hm.stiffness_nm_rad, f * I * x.nwlb);
        cr_assert_lt(fabs(a - w), 1e-6 * want + 1e-12, "frame %d: %g vs %g", k, a, w);
    }
    // the current off: back to flat
    cr_assert_eq(ori_compliant_set_fraction(c, 0.0, &err), ORI_OK);
    cr_assert_eq(ori_compliant_solve_static(c, &err), ORI_OK, "%s", err.message);
    cr_assert_lt(fabs(ori_compliant_fold_angle(c, 0)), 1e-9 * want);
    ori_compliant_destroy(c);
    flap_free(&x);
}

Test(compliant_lorentz, plastic_flap_yields_to_the_monotonic_law_and_springs_back_by_m_over_k)
{
    flap x = load_flap(false);
    double zeros[7] = {0};
    double I = 0.02; // the thesis' 20 mA: far beyond the gold's plastic moment at flat
    ori_compliant *c = flap_model(&x, I, zeros);
    ori_error err;
    cr_assert_eq(ori_compliant_solve_static(c, &err), ORI_OK, "%s", err.message);
    double th = ori_compliant_fold_angle(c, 0);
    double m = I * x.nwlb * cos(th);
    double mono = ori_hinge_monotonic_moment(x.hm.stiffness_nm_rad, x.hm.yield_moment_nm, th);
    printf("plastic flap: %.6g deg at 20 mA, moment %.4g N m (monotonic law %.4g), plastic rotation %.6g deg\n", th / DEG, m,
           mono, ori_compliant_plastic_rotation(c, 0) / DEG);
    // the Lorentz moment falls with cos θ until the yielding hinge carries it (68.3° here)
    cr_assert(th > 45 * DEG && th < 90 * DEG, "%g", th / DEG);
    cr_assert_gt(th - x.hm.yield_rotation_rad, 10 * DEG); // well into the plastic range
    // the layered section against the continuum law: within M_p / ORI_HINGE_LAYERS
    cr_assert_lt(fabs(m - mono), x.hm.plastic_moment_nm / ORI_HINGE_LAYERS, "%g vs %g", m, mono);
    double perm = ori_compliant_plastic_rotation(c, 0);
    // (the 10 µm flap bends under 1 µN at its far edge by ~1e-5 rad, so the rigid cos θ is good to ~1e-6)
    cr_assert_lt(fabs(perm - (th - m / x.hm.stiffness_nm_rad)), 1e-5 * th, "%.12g vs %.12g", perm, th - m / x.hm.stiffness_nm_rad);
    // the current off: the hinge unloads elastically by M/k and keeps the plastic rotation
    cr_assert_eq(ori_compliant_set_fraction(c, 0.0, &err), ORI_OK);
    cr_assert_eq(ori_compliant_solve_static(c, &err), ORI_OK, "%s", err.message);
    double latched = ori_compliant_fold_angle(c, 0);
    printf("plastic flap: latched at %.6g deg (springback %.4g deg)\n", latched / DEG, (th - latched) / DEG);
    cr_assert_lt(fabs(latched - perm), 1e-6 * perm, "%.10g vs %.10g", latched, perm);
    cr_assert_lt(fabs(ori_compliant_plastic_rotation(c, 0) - perm), 1e-9 * perm);
    ori_compliant_destroy(c);
    flap_free(&x);
}

Test(compliant_lorentz, wire_energy_gradient_and_hessian_match_finite_differences)
{
    flap x = load_flap(false);
    double zeros[7] = {0};
    ori_compliant *c = flap_model(&x, 0.003, zeros);
    int nv = ori_compliant_vertex_count(c);
    // a bent, tilted state: every vertex moved
    double *xs = malloc(sizeof(double) * 3 * (size_t)nv), *g = malloc(sizeof(double) * 3 * (size_t)nv);
    double *gp = malloc(sizeof(double) * 3 * (size_t)nv), *gm = malloc(sizeof(double) * 3 * (size_t)nv);
    double L = 500e-6;
    for (int v = 0; v < nv; ++v)
        for (int q = 0; q < 3; ++q) xs[3 * v + q] = c->x[3 * v + q] + L * 0.05 * sin(1.0 + 3.0 * v + q);
    ori__cmp_energy(c, xs, 1.0, g);
    ori__cmp_hessian(c, xs, 1.0, false);
    const double *val = ori__sls_values(c->sls);
    double gscale = 0.0;
    for (int k = 0; k < 3 * nv; ++k) gscale = fmax(gscale, fabs(g[k]));
    for (int v = 0; v < nv; ++v) {
        if (c->dof[v] < 0) continue;
        for (int q = 0; q < 3; ++q) {
            double h = 1e-7 * L, keep = xs[3 * v + q];
            xs[3 * v + q] = keep + h;
            double ep = ori__cmp_energy(c, xs, 1.0, gp);
            xs[3 * v + q] = keep - h;
            double em = ori__cmp_energy(c, xs, 1.0, gm);
            xs[3 * v + q] = keep;
            cr_assert_lt(fabs((ep - em) / (2 * h) - g[3 * v + q]), 1e-6 * gscale, "gradient %d.%d", v, q);
            // column (v, q) of the Hessian against the gradient's central difference
            int col = c->dof[v] + q;
            for (int w = 0; w < nv; ++w) {
                if (c->dof[w] < 0) continue;
                for (int r = 0; r < 3; ++r) {
                    int row = c->dof[w] + r;
                    double fd = (gp[3 * w + r] - gm[3 * w + r]) / (2 * h);
                    int a = row < col ? row : col, b = row < col ? col : row;
                    double hv = 0.0;
                    for (int k = c->colptr[b]; k < c->colptr[b + 1]; ++k)
                        if (c->rowind[k] == a) hv = val[k];
                    cr_assert_lt(fabs(fd - hv), 1e-5 * gscale / L, "hessian (%d.%d, %d.%d): %g vs %g", w, r, v, q, hv, fd);
                }
            }
        }
    }
    free(xs);
    free(g);
    free(gp);
    free(gm);
    ori_compliant_destroy(c);
    flap_free(&x);
}

Test(compliant_lorentz, polarity_and_the_rigid_moment)
{
    // A mountain crease with auto polarity turns the other way; without auto polarity the
    // current's own sign decides, and the flap's moment at the elastic balance is the rigid
    // model's ori_lorentz_axis_moment for the same pose.
    flap x = load_flap(false);
    double zeros[7] = {0};
    double I = 0.5 * x.hm.yield_moment_nm / x.nwlb;
    ori_compliant_def d = ori_compliant_physical_def();
    d.design = x.d;
    d.fixed_face = 0;
    d.field_t = ori_design_actuation(x.d).field_t;
    d.current_a = I;
    d.target_angles_rad = zeros;
    ori_pattern_set_assignment(x.p, 0, ORI_ASSIGN_MOUNTAIN);
    ori_compliant *c = NULL;
    ori_error err;
    cr_assert_eq(ori_compliant_create(x.p, &d, &c, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_compliant_solve_static(c, &err), ORI_OK, "%s", err.message);
    double want = elastic_balance(x.hm.stiffness_nm_rad, I * x.nwlb);
    cr_assert_lt(fabs(ori_compliant_fold_angle(c, 0) + want), 1e-6 * want, "%g", ori_compliant_fold_angle(c, 0) / DEG);
    cr_assert_lt(ori_compliant_wire_current(c, 0), 0.0);
    ori_compliant_destroy(c);
    // valley, no auto polarity: the current as given turns the flap as a mountain here
    ori_pattern_set_assignment(x.p, 0, ORI_ASSIGN_VALLEY);
    d.auto_polarity = false;
    cr_assert_eq(ori_compliant_create(x.p, &d, &c, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_compliant_solve_static(c, &err), ORI_OK, "%s", err.message);
    double th = ori_compliant_fold_angle(c, 0);
    cr_assert_lt(fabs(fabs(th) - want), 1e-6 * want);
    // the rigid moment of the same wire about the crease at the compliant pose
    ori_hinge h;
    cr_assert(ori_design_hinge(x.d, 0, &h));
    double lever = h.wire.lever_m, s = sin(th), co = cos(th);
    // the flap (y > 0) turned about the x axis by the fold angle (valley: +z)
    ori_v3 centre = ori_v3_make(250e-6, lever * co, lever * s), axis = ori_v3_make(1, 0, 0);
    double mr = ori_lorentz_axis_moment(ori_v3_make(0, 0, 0), axis, centre, ori_v3_make(1, 0, 0), h.wire.length_m,
                                        h.wire.turns, ori_compliant_wire_current(c, 0), d.field_t);
    cr_assert_lt(fabs(fabs(mr) - x.hm.stiffness_nm_rad * fabs(th)), 1e-6 * x.hm.stiffness_nm_rad * want, "%g vs %g", mr,
                 x.hm.stiffness_nm_rad * th);
    ori_compliant_destroy(c);
    flap_free(&x);
}

Test(compliant_lorentz, a_design_needs_the_physical_preset_and_matching_sizes)
{
    flap x = load_flap(false);
    ori_compliant_def d = ori_default_compliant_def();
    d.design = x.d;
    ori_compliant *c = NULL;
    ori_error err;
    cr_assert_eq(ori_compliant_create(x.p, &d, &c, &err), ORI_ERR_ARGUMENT);
    cr_assert_null(c);
    cr_assert(strstr(err.message, "physical preset"), "%s", err.message);
    d = ori_compliant_physical_def();
    d.design = x.d;
    d.current_a = -1.0;
    cr_assert_eq(ori_compliant_create(x.p, &d, &c, &err), ORI_ERR_RANGE);
    cr_assert(strstr(err.message, "current_a"), "%s", err.message);
    d.current_a = 0.0;
    ori_pattern *other = test_load_pattern(test_repo_path("examples/patterns/degree4-vertex.fold"), 0);
    cr_assert_eq(ori_compliant_create(other, &d, &c, &err), ORI_ERR_ARGUMENT);
    cr_assert(strstr(err.message, "the design has"), "%s", err.message);
    ori_pattern_destroy(other);
    flap_free(&x);
}
