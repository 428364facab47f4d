// Compliant bar-and-hinge model (issue 23): the dihedral gradient and Hessian against finite
// differences; closed forms (a bar in tension, a flap folding under gravity: torque balance);
// convergence to orikin's exact rigid fold angles as the panels stiffen (Miura 4 × 4, the
// thesis' open corner); explicit vs static agreement; the line search never raises the energy;
// bad input; per-face strain energy; contact warnings.
#include <float.h>
#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <orikin/orikin.h>

#include "compliant/compliant_internal.h"
#include "support.h"

TestSuite(compliant, .init = test_leak_setup, .fini = test_leak_check);

#define DEG (ORI_PI / 180.0)

// A triangle flap (0,0)-(1,0)-(0.5,-1) hinged on the x axis to the fixed square above it.
static ori_pattern *flap_pattern(ori_assignment crease)
{
    ori_pattern_def pd = ori_default_pattern_def();
    ori_pattern *p = ori_pattern_create(&pd);
    int v0 = ori_pattern_add_vertex(p, (ori_v3){0, 0, 0});
    int v1 = ori_pattern_add_vertex(p, (ori_v3){1, 0, 0});
    int v2 = ori_pattern_add_vertex(p, (ori_v3){1, 1, 0});
    int v3 = ori_pattern_add_vertex(p, (ori_v3){0, 1, 0});
    int v4 = ori_pattern_add_vertex(p, (ori_v3){0.5, -1, 0});
    ori_pattern_add_edge(p, v0, v1, crease, 0.0);
    ori_pattern_add_edge(p, v1, v2, ORI_ASSIGN_BOUNDARY, 0.0);
    ori_pattern_add_edge(p, v2, v3, ORI_ASSIGN_BOUNDARY, 0.0);
    ori_pattern_add_edge(p, v3, v0, ORI_ASSIGN_BOUNDARY, 0.0);
    ori_pattern_add_edge(p, v1, v4, ORI_ASSIGN_BOUNDARY, 0.0);
    ori_pattern_add_edge(p, v4, v0, ORI_ASSIGN_BOUNDARY, 0.0);
    int sq[4] = {v0, v1, v2, v3}, tr[3] = {v0, v4, v1};
    ori_pattern_add_face(p, sq, 4);
    ori_pattern_add_face(p, tr, 3);
    ori_error err;
    ori_build_def bd = ori_default_build_def();
    cr_assert_eq(ori_pattern_build(p, &bd, &err), ORI_OK, "%s", err.message);
    return p;
}

static ori_compliant *make(const ori_pattern *p, const ori_compliant_def *d)
{
    ori_compliant *c = NULL;
    ori_error err;
    cr_assert_eq(ori_compliant_create(p, d, &c, &err), ORI_OK, "%s", err.message);
    return c;
}

static int face_containing(const ori_pattern *p, double x, double y) { return test_face_at(p, x, y); }

Test(compliant, hinge_gradient_and_hessian_match_finite_differences)
{
    ori_pattern *p = flap_pattern(ORI_ASSIGN_VALLEY);
    ori_compliant_def d = ori_default_compliant_def();
    ori_compliant *c = make(p, &d);
    cr_assert_gt(c->nhinge, 0);
    // a generic folded position of the four vertices of every hinge
    double *x = malloc(sizeof(double) * 3 * (size_t)c->nv);
    srand(7);
    for (int k = 0; k < 3 * c->nv; ++k) x[k] = c->x0[k] + 0.3 * ((double)rand() / RAND_MAX - 0.5);
    for (int h = 0; h < c->nhinge; ++h) {
        cmp_hinge hh = c->hinges[h];
        hh.ref = ori__cmp_hinge_angle(x, &hh, 0.0);
        double g[12], H[144];
        ori__cmp_hinge_gradient(x, &hh, g);
        ori__cmp_hinge_hessian(x, &hh, H);
        const int node[4] = {hh.j, hh.k, hh.i, hh.l};
        for (int a = 0; a < 12; ++a) {
            double *xa = &x[3 * node[a / 3] + a % 3], s = *xa, eps = 1e-6;
            *xa = s + eps;
            double fp = ori__cmp_hinge_angle(x, &hh, hh.ref);
            double gp[12];
            ori__cmp_hinge_gradient(x, &hh, gp);
            *xa = s - eps;
            double fm = ori__cmp_hinge_angle(x, &hh, hh.ref);
            double gm[12];
            ori__cmp_hinge_gradient(x, &hh, gm);
            *xa = s;
            cr_assert_float_eq(g[a], (fp - fm) / (2 * eps), 1e-7, "hinge %d dρ/dx[%d]: %g vs %g", h, a, g[a],
                               (fp - fm) / (2 * eps));
            for (int b = 0; b < 12; ++b)
                cr_assert_float_eq(H[b * 12 + a], (gp[b] - gm[b]) / (2 * eps), 1e-6, "hinge %d H[%d][%d]", h, b, a);
        }
    }
    // the energy's gradient against finite differences of the energy
    double *g = malloc(sizeof(double) * 3 * (size_t)c->nv);
    for (int h = 0; h < c->nhinge; ++h) c->hinges[h].ref = ori__cmp_hinge_angle(x, &c->hinges[h], 0.0);
    ori__cmp_energy(c, x, 0.7, g);
    for (int k = 0; k < 3 * c->nv; ++k) {
        if (c->dof[k / 3] < 0) continue;
        double s = x[k], eps = 1e-6;
        x[k] = s + eps;
        double ep = ori__cmp_energy(c, x, 0.7, NULL);
        x[k] = s - eps;
        double em = ori__cmp_energy(c, x, 0.7, NULL);
        x[k] = s;
        cr_assert_float_eq(g[k], (ep - em) / (2 * eps), 1e-6, "dE/dx[%d]", k);
    }
    free(g);
    free(x);
    ori_compliant_destroy(c);
    ori_pattern_destroy(p);
}

// Bar in tension: the flap's apex (unit mass) hangs under gravity g from two bars of stiffness
// k = axial / L0 with no crease stiffness: 2 k (L − L0) h / L = m g, h = √(L² − ¼).
Test(compliant, bar_in_tension_closed_form)
{
    ori_pattern *p = flap_pattern(ORI_ASSIGN_FLAT);
    ori_compliant_def d = ori_default_compliant_def();
    d.crease_stiffness = 0.0;
    d.gravity = 1.0;
    d.fixed_face = face_containing(p, 0.5, 0.5);
    ori_compliant *c = make(p, &d);
    ori_error err;
    cr_assert_eq(ori_compliant_solve_static(c, &err), ORI_OK, "%s", err.message);
    double l0 = sqrt(1.25), k = 20.0 / l0;
    double L = l0;
    for (int it = 0; it < 100; ++it) { // Newton on f(L) = 2k(L − L0)h/L − 1
        double h = sqrt(L * L - 0.25);
        double f = 2 * k * (L - l0) * h / L - 1.0;
        double df = 2 * k * (h / L + (L - l0) * (0.25 / (L * L * h)));
        L -= f / df;
    }
    const ori_v3 *x = ori_compliant_positions(c);
    int apex = test_vertex_at(p, 0.5, -1);
    double z = -sqrt(L * L - 0.25);
    cr_assert_float_eq(x[apex].z, z, 1e-9, "apex z %.12g vs %.12g", x[apex].z, z);
    cr_assert_float_eq(x[apex].y, 0.0, 1e-9);
    int e = ori_pattern_find_edge(p, test_vertex_at(p, 1, 0), apex);
    cr_assert_float_eq(ori_compliant_edge_strain(c, e), (L - l0) / l0, 1e-9);
    cr_assert_leq(ori_compliant_gradient_norm(c), fmax(1e-10 * ori_compliant_load_scale(c), ori_compliant_gradient_floor(c)));
    ori_compliant_destroy(c);
    ori_pattern_destroy(p);
}

// A flap folding under gravity: its weight's torque m g d cos ρ balances the crease k_h |ρ|
// (k_h = 0.7 · 1, d = 1 the apex's distance to the crease), with near-rigid bars.
Test(compliant, flap_under_gravity_torque_balance)
{
    ori_pattern *p = flap_pattern(ORI_ASSIGN_FLAT);
    ori_compliant_def d = ori_default_compliant_def();
    d.axial_stiffness = 20.0 * 1e8;
    d.gravity = 0.5;
    d.fixed_face = face_containing(p, 0.5, 0.5);
    ori_compliant *c = make(p, &d);
    ori_error err;
    cr_assert_eq(ori_compliant_solve_static(c, &err), ORI_OK, "%s", err.message);
    double r = 0.5;
    for (int it = 0; it < 50; ++it) r -= (0.7 * r - 0.5 * cos(r)) / (0.7 + 0.5 * sin(r));
    int crease = test_edge_at(p, 0, 0, 1, 0);
    double rho = ori_compliant_fold_angle(c, crease);
    // the flap falls (−z): a mountain fold, negative in FOLD's sign
    cr_assert_lt(rho, 0.0);
    cr_assert_float_eq(-rho, r, 1e-7, "fold angle %.12g vs torque balance %.12g", -rho, r);
    int apex = test_vertex_at(p, 0.5, -1);
    cr_assert_float_eq(ori_compliant_positions(c)[apex].z, -sin(r), 1e-7);
    ori_compliant_destroy(c);
    ori_pattern_destroy(p);
}

// A hinge the dynamics turns past 180° (a distorted degree-4 vertex at 100 %, stiff bars, soft
// facets: fuzz_compliant's input, kept as its seed) is reported at ±180°, and the frames written read back:
// a FOLD file holds fold angles in [−180°, 180°] (it was written at 210° and refused on reading).
Test(compliant, a_hinge_past_180_is_reported_at_180_and_reads_back)
{
    // the seed: 16 bytes of parameters (decoded here as the target does), then the FOLD text
    FILE *f = fopen(test_repo_path("fuzz/seeds/compliant/flap-past-180-under-gravity"), "rb");
    cr_assert(f);
    char buf[8192];
    size_t n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    cr_assert_gt(n, 16);
    ori_fold *in = NULL;
    ori_pattern *p = NULL;
    ori_error err;
    cr_assert_eq(ori_fold_load_string(buf + 16, n - 16, &in, &err), ORI_OK, "%s", err.message);
    ori_build_def bd = ori_default_build_def();
    bd.planarize = true; // (its mutated edges cross, as the target reads them)
    cr_assert_eq(ori_fold_get_pattern(in, 0, &bd, &p, &err), ORI_OK, "%s", err.message);
    ori_fold_destroy(in);
    const unsigned char *b = (const unsigned char *)buf; // as fuzz/fuzz_compliant.c decodes them
    ori_compliant_def d = ori_default_compliant_def();
    cr_assert_eq(b[0] & 1, 0, "the preset of Origami Simulator");
    d.axial_stiffness = 20.0 * pow(10.0, 6.0 * b[1] / 255.0 - 3.0);
    d.facet_stiffness = 0.2 * pow(10.0, 6.0 * b[2] / 255.0 - 3.0);
    d.crease_stiffness = 0.7 * pow(10.0, 6.0 * b[3] / 255.0 - 3.0);
    d.fraction = (b[4] | (b[5] << 8)) / 65535.0;
    d.max_step_rad = 0.02 + 0.5 * ((b[6] | (b[7] << 8)) / 65535.0);
    d.max_iterations = 40;
    d.damping = (b[8] / 255.0) * 2.0;
    d.gravity = (b[9] & 1) ? 0.0 : 0.05 * (b[9] / 255.0);
    d.fixed_face = b[10] % (ori_pattern_face_count(p) + 2) - 1;
    d.keep_frames = (b[11] & 1) != 0;
    d.check_contacts = (b[11] & 2) != 0;
    ori_compliant *c = make(p, &d);
    ori_compliant_solve_static(c, &err); // (converged or not: the state reached)
    int steps = 0;
    ori_compliant_run_dynamic(c, 400, 1e-6, &steps, &err);
    int E = ori_pattern_edge_count(p), at = 0;
    double *angles = malloc(sizeof(double) * (size_t)E);
    for (int e = 0; e < E; ++e) {
        angles[e] = ori_compliant_fold_angle(c, e);
        cr_assert_leq(fabs(angles[e]), ORI_PI, "edge %d: %.17g", e, angles[e]);
        at += fabs(angles[e]) == ORI_PI;
    }
    cr_assert_geq(at, 1, "a hinge held at 180 degrees");
    ori_fold *doc = ori_fold_create();
    cr_assert_eq(ori_fold_set_pattern(doc, 0, p, &err), ORI_OK);
    ori_fold_append_state(doc, 0, ori_compliant_vertex_count(c), ori_compliant_positions(c), E, angles, "dynamic");
    char *text = ori_fold_to_string(doc);
    ori_fold *back = NULL;
    ori_pattern *q = NULL;
    cr_assert_eq(ori_fold_load_string(text, strlen(text), &back, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_fold_get_pattern(back, 1, NULL, &q, &err), ORI_OK, "%s", err.message);
    ori_pattern_destroy(q);
    ori_fold_destroy(back);
    ori_buffer_free(text);
    ori_fold_destroy(doc);
    free(angles);
    ori_compliant_destroy(c);
    ori_pattern_destroy(p);
}

// The sign of a driven valley agrees with the rigid kinematics: a valley target of 90° lifts the flap.
Test(compliant, valley_lifts_like_the_rigid_fold)
{
    ori_pattern *p = flap_pattern(ORI_ASSIGN_VALLEY);
    ori_compliant_def d = ori_default_compliant_def();
    d.fraction = 0.5;
    d.fixed_face = face_containing(p, 0.5, 0.5);
    ori_compliant *c = make(p, &d);
    ori_error err;
    cr_assert_eq(ori_compliant_solve_static(c, &err), ORI_OK, "%s", err.message);
    int crease = test_edge_at(p, 0, 0, 1, 0);
    cr_assert_float_eq(ori_compliant_fold_angle(c, crease), 90 * DEG, 1e-9);
    ori_mechanism *m = test_mechanism_of(p);
    ori_motion_def md = ori_default_motion_def();
    md.fixed_face = d.fixed_face;
    md.driven_edge = crease;
    md.to_rad = 90 * DEG;
    ori_motion *mo = test_solve(m, &md);
    ori_v3 *xr = malloc(sizeof(ori_v3) * (size_t)ori_pattern_vertex_count(p));
    ori_motion_frame_vertices(mo, ori_motion_frame_count(mo) - 1, xr);
    const ori_v3 *xc = ori_compliant_positions(c);
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        cr_assert_float_eq(xc[v].x, xr[v].x, 1e-9);
        cr_assert_float_eq(xc[v].y, xr[v].y, 1e-9);
        cr_assert_float_eq(xc[v].z, xr[v].z, 1e-9);
    }
    free(xr);
    ori_motion_destroy(mo);
    ori_mechanism_destroy(m);
    ori_compliant_destroy(c);
    ori_pattern_destroy(p);
}

// Largest |compliant − rigid| crease angle (degrees) of a compliant solve at the given panel
// stiffness ratio, the rigid state being orikin's exact fold at the compliant drives.
static double rigid_error(const ori_pattern *p, double fraction, double ratio, const int *drives, int ndrives)
{
    ori_compliant_def d = ori_default_compliant_def();
    d.axial_stiffness *= ratio;
    d.facet_stiffness *= ratio;
    d.fraction = fraction;
    d.fixed_face = 0;
    ori_compliant *c = make(p, &d);
    ori_error err;
    cr_assert_eq(ori_compliant_solve_static(c, &err), ORI_OK, "ratio %g: %s", ratio, err.message);
    int ne = ori_pattern_edge_count(p);
    ori_mechanism *m = test_mechanism_of(p);
    double to[8];
    for (int k = 0; k < ndrives; ++k) to[k] = ori_compliant_fold_angle(c, drives[k]);
    const double *rigid;
    ori_motion *mo = NULL;
    ori_multifold *mf = NULL;
    if (ndrives == 1) {
        ori_motion_def md = ori_default_motion_def();
        md.fixed_face = 0;
        md.driven_edge = drives[0];
        md.to_rad = to[0];
        mo = test_solve(m, &md);
        rigid = ori_motion_frame_angles(mo, ori_motion_frame_count(mo) - 1);
    } else {
        ori_drives_fold_def dd = ori_default_drives_fold_def();
        dd.fixed_face = 0;
        dd.driven_edges = drives;
        dd.to_rad = to;
        dd.driven_count = ndrives;
        dd.step_rad = 2 * DEG;
        cr_assert_eq(ori_drives_fold_solve(m, &dd, &mf, &err), ORI_OK, "%s", err.message);
        cr_assert_eq(ori_multifold_verdict_of(mf), ORI_MULTIFOLD_REACHED, "%s", ori_multifold_reason(mf));
        rigid = ori_multifold_frame_angles(mf, ori_multifold_frame_count(mf) - 1);
    }
    double worst = 0.0;
    if (getenv("CMP_DEBUG"))
        for (int e = 0; e < ne; ++e)
            if (ori_assignment_is_fold(ori_pattern_edge(p, e).assignment))
                cr_log_info("edge %d (%c): compliant %.6f rigid %.6f", e, ori_assignment_to_char(ori_pattern_edge(p, e).assignment), ori_compliant_fold_angle(c, e) / DEG, rigid[e] / DEG);
    for (int e = 0; e < ne; ++e)
        if (ori_assignment_is_fold(ori_pattern_edge(p, e).assignment))
            worst = fmax(worst, fabs(ori_compliant_fold_angle(c, e) - rigid[e]) / DEG);
    ori_motion_destroy(mo);
    ori_multifold_destroy(mf);
    ori_mechanism_destroy(m);
    ori_compliant_destroy(c);
    return worst;
}

static void converge_to_rigid(const ori_pattern *p, double fraction, const int *drives, int ndrives, const char *name)
{
    double prev = INFINITY;
    for (int dec = 1; dec <= 6; ++dec) {
        double ratio = pow(10.0, dec);
        double e = rigid_error(p, fraction, ratio, drives, ndrives);
        cr_log_info("%s: stiffness ×1e%d: largest crease-angle error vs rigid %.3g°", name, dec, e);
        cr_assert_lt(e, prev, "%s: error at ×1e%d (%g°) not below ×1e%d's (%g°)", name, dec, e, dec - 1, prev);
        prev = e;
    }
    cr_assert_leq(prev, 1e-3, "%s: error %g° at ×1e6", name, prev);
}

Test(compliant, miura_converges_to_the_rigid_fold)
{
    ori_pattern *p = test_generated(ORI_TESS_MIURA, 4, 4);
    // drive: the crease of face 0 with the largest compliant angle is as good as any; take a fold of face 0
    int fe[8];
    int n = ori_pattern_face_edges(p, 0, fe, 8);
    int drive = -1;
    for (int k = 0; k < n && drive < 0; ++k)
        if (ori_assignment_is_fold(ori_pattern_edge(p, fe[k]).assignment)) drive = fe[k];
    cr_assert_geq(drive, 0);
    converge_to_rigid(p, 0.5, &drive, 1, "miura 4x4");
    ori_pattern_destroy(p);
}

Test(compliant, open_corner_converges_to_the_rigid_fold)
{
    test_open_corner oc = test_open_corner_load();
    // Two degrees of freedom: two drives. With two creases given, the other three close in two
    // ways (mirror branches); driving up and down, the rigid fold from flat stays on the branch
    // the compliant sheet takes (driving diag and right it lands on the other one, 35.8° away).
    int drives[2] = {oc.up, oc.down};
    converge_to_rigid(oc.p, 0.4, drives, 2, "open corner");
    test_open_corner_free(&oc);
}

// The explicit solver's settled state is the static equilibrium.
Test(compliant, explicit_settles_on_the_static_equilibrium)
{
    ori_pattern *p = flap_pattern(ORI_ASSIGN_VALLEY);
    ori_compliant_def d = ori_default_compliant_def();
    d.fraction = 0.4;
    d.gravity = 0.3;
    d.fixed_face = face_containing(p, 0.5, 0.5);
    ori_compliant *cs = make(p, &d), *cd = make(p, &d);
    ori_error err;
    cr_assert_eq(ori_compliant_solve_static(cs, &err), ORI_OK, "%s", err.message);
    int steps = 0;
    cr_assert_eq(ori_compliant_run_dynamic(cd, 2000000, 1e-9, &steps, &err), ORI_OK, "%s", err.message);
    cr_log_info("explicit: %d steps of %g", steps, ori_compliant_time_step(cd));
    const ori_v3 *a = ori_compliant_positions(cs), *b = ori_compliant_positions(cd);
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        cr_assert_float_eq(a[v].x, b[v].x, 1e-7);
        cr_assert_float_eq(a[v].y, b[v].y, 1e-7);
        cr_assert_float_eq(a[v].z, b[v].z, 1e-7);
    }
    ori_compliant_destroy(cs);
    ori_compliant_destroy(cd);
    ori_pattern_destroy(p);
}

// keep_frames with the explicit solver: its time history. The flat start at t = 0, frames evenly
// spaced at a whole number of time steps, at most 257 (a run of 5,000 steps, 312 frames of 16
// steps, is thinned once: a frame every 32 steps), the last at steps × dt and equal to the final
// state; the same run
// without keep_frames ends in the same state with one frame.
Test(compliant, the_explicit_solver_keeps_its_time_history)
{
    ori_pattern *p = flap_pattern(ORI_ASSIGN_VALLEY);
    ori_compliant_def d = ori_default_compliant_def();
    d.fraction = 0.4;
    d.gravity = 0.3;
    d.fixed_face = face_containing(p, 0.5, 0.5);
    d.keep_frames = true;
    ori_compliant *c = make(p, &d);
    d.keep_frames = false;
    ori_compliant *one = make(p, &d);
    ori_error err;
    int steps = 0, steps1 = 0;
    cr_assert_eq(ori_compliant_run_dynamic(c, 5000, 1e-300, &steps, &err), ORI_ERR_NOT_CONVERGED); // (never settles)
    cr_assert_eq(ori_compliant_run_dynamic(one, 5000, 1e-300, &steps1, &err), ORI_ERR_NOT_CONVERGED);
    cr_assert_eq(steps, 5000);
    double dt = ori_compliant_time_step(c);
    int n = ori_compliant_frame_count(c), V = ori_pattern_vertex_count(p);
    cr_assert(n >= 3 && n <= 257, "%d frames", n);
    cr_assert_eq(ori_compliant_frame_time(c, 0), 0.0);
    for (int v = 0; v < V; ++v) cr_assert_eq(ori_compliant_frame_positions(c, 0)[v].z, 0.0, "the flat start");
    double gap = ori_compliant_frame_time(c, 1);
    cr_assert_float_eq(gap / dt, 32.0, 1e-9, "thinned once: a frame every 32 steps (%g)", gap / dt);
    for (int k = 1; k < n - 1; ++k)
        cr_assert_float_eq(ori_compliant_frame_time(c, k), k * gap, 1e-9 * gap * n, "frame %d", k);
    cr_assert_float_eq(ori_compliant_frame_time(c, n - 1), 5000 * dt, 1e-12 * 5000 * dt);
    cr_assert_eq(ori_compliant_frame_count(one), 1);
    const ori_v3 *end = ori_compliant_frame_positions(c, n - 1), *x = ori_compliant_positions(c), *y = ori_compliant_positions(one);
    for (int v = 0; v < V; ++v) {
        cr_assert(end[v].x == x[v].x && end[v].y == x[v].y && end[v].z == x[v].z, "the last frame is the final state");
        cr_assert(y[v].x == x[v].x && y[v].y == x[v].y && y[v].z == x[v].z, "keeping frames changes nothing");
    }
    ori_compliant_destroy(c);
    ori_compliant_destroy(one);
    ori_pattern_destroy(p);
}

Test(compliant, explicit_on_two_threads_takes_the_same_steps_as_one)
{
    // A Miura 40 × 40 at 30 %, 2,000 explicit steps: the force sums shared by two threads (phase
    // A: bars and hinges by share, phase B: vertices by share) give the state of one thread to
    // roundoff (only the order of the sums differs); a wrong share or a race would show here. (That
    // the explicit solver settles on the static equilibrium is the test above.)
    ori_pattern *p = test_generated(ORI_TESS_MIURA, 40, 40);
    ori_error err;
    ori_compliant_def d = ori_default_compliant_def();
    d.fraction = 0.3;
    ori_compliant *c1 = make(p, &d);
    d.threads = 2;
    ori_compliant *c2 = make(p, &d);
    cr_assert_gt(ori_compliant_bar_count(c2) + ori_compliant_hinge_count(c2), 2 * 4096,
                 "a model is shared only past 4,096 elements a thread: %d",
                 ori_compliant_bar_count(c2) + ori_compliant_hinge_count(c2));
    int s1 = 0, s2 = 0;
    cr_assert_eq(ori_compliant_run_dynamic(c1, 2000, 1e-300, &s1, &err), ORI_ERR_NOT_CONVERGED);
    cr_assert_eq(ori_compliant_run_dynamic(c2, 2000, 1e-300, &s2, &err), ORI_ERR_NOT_CONVERGED);
    cr_assert_eq(s1, 2000);
    cr_assert_eq(s2, 2000);
    const ori_v3 *b1 = ori_compliant_positions(c1), *b2 = ori_compliant_positions(c2);
    double moved = 0.0;
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        cr_assert_lt(ori_v3_norm(ori_v3_sub(b1[v], b2[v])), 1e-10, "vertex %d", v);
        moved = fmax(moved, fabs(b1[v].z));
    }
    cr_assert_gt(moved, 1e-3, "the sheet has moved: %g", moved);
    for (int e = 0; e < ori_pattern_edge_count(p); ++e)
        cr_assert_lt(fabs(ori_compliant_fold_angle(c1, e) - ori_compliant_fold_angle(c2, e)), 1e-10, "edge %d", e);
    d.threads = 0;
    ori_compliant *bad = NULL;
    cr_assert_eq(ori_compliant_create(p, &d, &bad, &err), ORI_ERR_RANGE);
    cr_assert(strstr(err.message, "threads"), "%s", err.message);
    ori_compliant_destroy(c1);
    ori_compliant_destroy(c2);
    ori_pattern_destroy(p);
}

typedef struct trace { int accepted, increased; double worst; } trace;

static void on_step(double before, double after, void *user)
{
    trace *t = user;
    t->accepted++;
    if (after > before) {
        t->increased++;
        t->worst = fmax(t->worst, (after - before) / fmax(fabs(before), DBL_MIN));
    }
}

Test(compliant, line_search_never_raises_the_energy)
{
    ori_pattern *p = test_generated(ORI_TESS_MIURA, 4, 4);
    ori_error err;
    ori_compliant_def d = ori_default_compliant_def();
    d.fraction = 0.9;
    d.max_step_rad = 60 * DEG; // long load steps: the line search works
    ori_compliant *c = make(p, &d);
    trace t = {0, 0, 0.0};
    ori__cmp_set_trace(c, on_step, &t);
    cr_assert_eq(ori_compliant_solve_static(c, &err), ORI_OK, "%s", err.message);
    int it, fa, bt, ls;
    ori_compliant_stats(c, &it, &fa, &bt, &ls);
    cr_log_info("miura 90%%: %d iterations, %d factorizations, %d backtracks, %d load steps", it, fa, bt, ls);
    cr_assert_gt(t.accepted, 0);
    // only at roundoff (≤ 1e-13 relative) may an accepted step leave the energy higher
    cr_assert_leq(t.worst, 1e-13);
    cr_assert_leq(ori_compliant_gradient_norm(c), fmax(1e-10 * ori_compliant_load_scale(c), ori_compliant_gradient_floor(c)));
    ori_compliant_destroy(c);
    ori_pattern_destroy(p);
}

Test(compliant, bad_input_is_an_error_never_nan)
{
    ori_pattern *p = flap_pattern(ORI_ASSIGN_VALLEY);
    ori_compliant *c = NULL;
    ori_error err;
    ori_compliant_def d = ori_default_compliant_def();
    d.axial_stiffness = NAN;
    cr_assert_eq(ori_compliant_create(p, &d, &c, &err), ORI_ERR_RANGE);
    cr_assert_null(c);
    cr_assert(strstr(err.message, "axial_stiffness"), "%s", err.message);
    d = ori_default_compliant_def();
    d.fraction = 1.5;
    cr_assert_eq(ori_compliant_create(p, &d, &c, &err), ORI_ERR_RANGE);
    d = ori_default_compliant_def();
    d.fixed_face = 9;
    cr_assert_eq(ori_compliant_create(p, &d, &c, &err), ORI_ERR_RANGE);
    ori_pattern_destroy(p);
    // a face with zero area
    ori_pattern_def pd = ori_default_pattern_def();
    ori_pattern *q = ori_pattern_create(&pd);
    int a = ori_pattern_add_vertex(q, (ori_v3){0, 0, 0}), b = ori_pattern_add_vertex(q, (ori_v3){1, 0, 0});
    int e = ori_pattern_add_vertex(q, (ori_v3){2, 0, 0});
    ori_pattern_add_edge(q, a, b, ORI_ASSIGN_BOUNDARY, 0.0);
    ori_pattern_add_edge(q, b, e, ORI_ASSIGN_BOUNDARY, 0.0);
    ori_pattern_add_edge(q, e, a, ORI_ASSIGN_BOUNDARY, 0.0);
    int f[3] = {a, b, e};
    ori_pattern_add_face(q, f, 3);
    ori_build_def bd = ori_default_build_def();
    if (ori_pattern_build(q, &bd, &err) == ORI_OK) { // the builder may refuse it first: either is an error
        d = ori_default_compliant_def();
        cr_assert_neq(ori_compliant_create(q, &d, &c, &err), ORI_OK);
        cr_assert_null(c);
        cr_assert_eq(err.element, 0, "%s", err.message);
    }
    ori_pattern_destroy(q);
}

// The CLI's -o: FILE with the load steps appended, each with orikin:fraction and
// edges_orikin:strain (one per edge), the last at the fraction asked for.
Test(compliant, cli_writes_frames_with_fraction_and_strain)
{
    char *dir = test_tmpdir();
    char args[4096];
    snprintf(args, sizeof args, "fold examples/patterns/open-corner.fold --compliant --percent 40 --all-frames -o '%s/o.fold'", dir);
    char *out = NULL;
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    free(out);
    char path[4096];
    snprintf(path, sizeof path, "%s/o.fold", dir);
    char *text = test_read_text(path);
    cr_assert_not_null(text);
    json_error_t je;
    json_t *doc = json_loads(text, 0, &je);
    free(text);
    cr_assert_not_null(doc, "%s", je.text);
    json_t *frames = json_object_get(doc, "file_frames");
    cr_assert_gt(json_array_size(frames), 2);
    size_t ne = json_array_size(json_object_get(doc, "edges_vertices"));
    double last = -1.0;
    for (size_t k = 0; k < json_array_size(frames); ++k) {
        json_t *f = json_array_get(frames, k);
        double fr = json_number_value(json_object_get(f, "orikin:fraction"));
        cr_assert_gt(fr, last);
        last = fr;
        json_t *s = json_object_get(f, "edges_orikin:strain");
        cr_assert_eq(json_array_size(s), ne);
        for (size_t e = 0; e < ne; ++e) cr_assert(isfinite(json_number_value(json_array_get(s, e))));
    }
    cr_assert_float_eq(last, 0.4, 1e-15);
    json_decref(doc);
    test_tmpdir_remove(dir);
}

// A strip of three panels, 0.7 | 0.6 | 0.7 wide, the outer two valley flaps with target 170°:
// past 115.4° (cos ρ = −0.3/0.7, where the tips meet over the centre) they cross each other.
static ori_pattern *strip_pattern(void)
{
    ori_pattern_def pd = ori_default_pattern_def();
    ori_pattern *p = ori_pattern_create(&pd);
    const double xs[4] = {0.0, 0.7, 1.3, 2.0};
    for (int k = 0; k < 4; ++k) ori_pattern_add_vertex(p, (ori_v3){xs[k], 0, 0});
    for (int k = 0; k < 4; ++k) ori_pattern_add_vertex(p, (ori_v3){xs[k], 1, 0});
    for (int k = 0; k < 3; ++k) {
        ori_pattern_add_edge(p, k, k + 1, ORI_ASSIGN_BOUNDARY, 0.0);
        ori_pattern_add_edge(p, 4 + k, 5 + k, ORI_ASSIGN_BOUNDARY, 0.0);
    }
    ori_pattern_add_edge(p, 0, 4, ORI_ASSIGN_BOUNDARY, 0.0);
    ori_pattern_add_edge(p, 1, 5, ORI_ASSIGN_VALLEY, 170 * DEG);
    ori_pattern_add_edge(p, 2, 6, ORI_ASSIGN_VALLEY, 170 * DEG);
    ori_pattern_add_edge(p, 3, 7, ORI_ASSIGN_BOUNDARY, 0.0);
    for (int k = 0; k < 3; ++k) {
        int f[4] = {k, k + 1, 5 + k, 4 + k};
        ori_pattern_add_face(p, f, 4);
    }
    ori_pattern_set_has_fold_angles(p, true);
    ori_error err;
    ori_build_def bd = ori_default_build_def();
    cr_assert_eq(ori_pattern_build(p, &bd, &err), ORI_OK, "%s", err.message);
    return p;
}

// The two flaps of the strip pass through each other: one warning, that pair, at the first load
// step past 115.4°; none at 50 %, none with check_contacts off.
Test(compliant, contact_warnings_name_the_faces_and_the_step)
{
    ori_pattern *p = strip_pattern();
    int left = face_containing(p, 0.3, 0.5), mid = face_containing(p, 1.0, 0.5), right = face_containing(p, 1.7, 0.5);
    ori_compliant_def d = ori_default_compliant_def();
    d.fixed_face = mid;
    d.fraction = 0.5;
    ori_compliant *c = make(p, &d);
    ori_error err;
    cr_assert_eq(ori_compliant_solve_static(c, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_compliant_contact_count(c), 0);
    cr_assert_eq(ori_compliant_set_fraction(c, 1.0, &err), ORI_OK);
    cr_assert_eq(ori_compliant_solve_static(c, &err), ORI_OK, "%s", err.message);
    cr_assert_float_eq(ori_compliant_fold_angle(c, 7), 170 * DEG, 1e-6); // the flaps rotate freely
    cr_assert_float_eq(ori_compliant_fold_angle(c, 8), 170 * DEG, 1e-6);
    cr_assert_eq(ori_compliant_contact_count(c), 1);
    int fa, fb, step;
    double fr;
    ori_compliant_contact(c, 0, &fa, &fb, &step, &fr);
    cr_assert_eq(fa, left < right ? left : right);
    cr_assert_eq(fb, left < right ? right : left);
    double cross = (180.0 - acos(0.3 / 0.7) / DEG) / 170.0; // 0.679
    cr_log_info("strip: contact at load step %d, fraction %.4f (crossing from %.4f)", step, fr, cross);
    cr_assert_geq(fr, cross);
    cr_assert_leq(fr, cross + 10.0 / 170.0 + 1e-12); // within one load step of 10° at most
    cr_assert_gt(step, 0);
    cr_assert(!ori_compliant_contacts_truncated(c));
    ori_compliant_destroy(c);
    d.check_contacts = false;
    d.fraction = 1.0;
    c = make(p, &d);
    cr_assert_eq(ori_compliant_solve_static(c, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_compliant_contact_count(c), 0);
    ori_compliant_destroy(c);
    ori_pattern_destroy(p);
}

// Per-face strain energy: the faces' energies and the crease hinges' ½ k_h (ρ − ρ_rest)² add up
// to the total energy (no gravity); the stiffest-strained face is where the largest strain is.
Test(compliant, face_energies_add_up_to_the_total)
{
    test_open_corner oc = test_open_corner_load();
    ori_compliant_def d = ori_default_compliant_def();
    d.fraction = 0.4;
    ori_compliant *c = make(oc.p, &d);
    ori_error err;
    cr_assert_eq(ori_compliant_solve_static(c, &err), ORI_OK, "%s", err.message);
    int nf = ori_compliant_face_count(c);
    cr_assert_eq(nf, ori_pattern_face_count(oc.p));
    double sum = 0.0, smax = 0.0;
    for (int f = 0; f < nf; ++f) {
        cr_assert_geq(ori_compliant_face_energy(c, f), 0.0);
        sum += ori_compliant_face_energy(c, f);
        smax = fmax(smax, ori_compliant_face_strain(c, f));
    }
    double creases = 0.0;
    for (int h = 0; h < c->nhinge; ++h) {
        const cmp_hinge *hh = &c->hinges[h];
        if (!hh->crease) continue;
        double r = ori_compliant_fold_angle(c, hh->edge) - 0.4 * hh->target;
        cr_assert_float_eq(hh->k_h, d.crease_stiffness * c->bars[c->edge_bar[hh->edge]].l0, 1e-15);
        creases += 0.5 * hh->k_h * r * r;
    }
    cr_log_info("open corner 40 %%: faces %.9g + creases %.9g = %.9g (total %.9g)", sum, creases, sum + creases,
                ori_compliant_energy(c));
    cr_assert_gt(sum, 1e-6);
    cr_assert_float_eq(sum + creases, ori_compliant_energy(c), 1e-12 * ori_compliant_energy(c));
    cr_assert_float_eq(smax, ori_compliant_max_strain(c), 1e-15);
    const double *fe = ori_compliant_frame_face_energies(c, ori_compliant_frame_count(c) - 1);
    for (int f = 0; f < nf; ++f) cr_assert_eq(fe[f], ori_compliant_face_energy(c, f));
    ori_compliant_destroy(c);
    test_open_corner_free(&oc);
}
