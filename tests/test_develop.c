// develop: folded forms of a flat sheet back to their crease pattern without cuts. Exact round
// trips (generate a pattern, fold it with orikin's kinematics, develop the folded form: the crease
// pattern is the original up to a rigid motion of the plane, 1e-12 of the diagonal, the fold
// angles the state's, and folding it back rebuilds the shape, 1e-9), the shared folded forms
// read in place (rounded coordinates: tolerances stated there), and refusals naming the vertex
// or face (cone points, saddles, a sheet that overlaps itself, a cylinder that does not close).
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "support.h"

TestSuite(develop, .init = test_leak_setup, .fini = test_leak_check);

#define DEG (ORI_PI / 180.0)

// A mesh from a pattern's vertices (given positions) and faces.
static ori_mesh *mesh_of(const ori_pattern *p, const ori_v3 *pos)
{
    int nf = ori_pattern_face_count(p), total = 0;
    for (int f = 0; f < nf; ++f) total += ori_pattern_face_size(p, f);
    int *fs = malloc(((size_t)nf + 1) * sizeof *fs), *fv = malloc((size_t)total * sizeof *fv);
    fs[0] = 0;
    for (int f = 0; f < nf; ++f) fs[f + 1] = fs[f] + ori_pattern_face_vertices(p, f, fv + fs[f], total - fs[f]);
    ori_mesh *m = NULL;
    ori_error err;
    cr_assert_eq(ori_unfold_mesh_create(pos, ori_pattern_vertex_count(p), fs, fv, nf, &m, &err), ORI_OK, "%s", err.message);
    free(fs), free(fv);
    return m;
}

// Fold a generated pattern with the kinematics: drive its first valley to to_deg from flat
// (to_deg > 0), or fold every crease toward ±180° by the fraction −to_deg / 100 (to_deg < 0:
// the target fold); the last state's positions and angles.
static ori_pattern *folded(ori_generate_def *g, double to_deg, ori_v3 **pos, double **angles)
{
    ori_pattern *p = NULL;
    ori_error err;
    cr_assert_eq(ori_generate(g, &p, NULL, &err), ORI_OK, "%s", err.message);
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = p;
    ori_mechanism *mech = NULL;
    cr_assert_eq(ori_mechanism_create(&md, &mech, &err), ORI_OK, "%s", err.message);
    int ne = ori_pattern_edge_count(p), nv = ori_pattern_vertex_count(p), drive = -1;
    for (int e = 0; e < ne && drive < 0; ++e)
        if (ori_pattern_edge(p, e).assignment == ORI_ASSIGN_VALLEY) drive = e;
    cr_assert_geq(drive, 0);
    *pos = malloc(((size_t)nv + 1) * sizeof **pos);
    *angles = malloc(((size_t)ne + 1) * sizeof **angles);
    if (to_deg < 0) {
        ori_target_fold_def t = ori_default_target_fold_def();
        t.fraction = -to_deg / 100.0;
        ori_multifold *mf = NULL;
        cr_assert_eq(ori_target_fold_solve(mech, &t, &mf, &err), ORI_OK, "%s", err.message);
        // reached, or stopped where the rigid motion gets no nearer: either way a closed folded state
        ori_multifold_verdict v = ori_multifold_verdict_of(mf);
        cr_assert(v == ORI_MULTIFOLD_REACHED || v == ORI_MULTIFOLD_STATIONARY, "%s", ori_multifold_reason(mf));
        int last = ori_multifold_frame_count(mf) - 1;
        cr_assert_leq(ori_multifold_frame_residual(mf, last), 1e-10);
        ori_multifold_frame_vertices(mf, last, *pos);
        memcpy(*angles, ori_multifold_frame_angles(mf, last), (size_t)ne * sizeof **angles);
        ori_multifold_destroy(mf);
        ori_mechanism_destroy(mech);
        return p;
    }
    ori_motion_def d = ori_default_motion_def();
    d.driven_edge = drive;
    d.to_rad = to_deg * DEG;
    d.step_rad = 5 * DEG;
    ori_motion *mo = NULL;
    cr_assert_eq(ori_motion_solve(mech, &d, &mo, &err), ORI_OK, "%s", err.message);
    int last = ori_motion_frame_count(mo) - 1;
    cr_assert_eq(ori_motion_frame_drive(mo, last), d.to_rad, "the fold reached %g°", ori_motion_frame_drive(mo, last) / DEG);
    ori_motion_frame_vertices(mo, last, *pos);
    memcpy(*angles, ori_motion_frame_angles(mo, last), (size_t)ne * sizeof **angles);
    ori_motion_destroy(mo);
    ori_mechanism_destroy(mech);
    return p;
}

// Largest distance (relative to the flat diagonal) between the developed crease pattern and the
// original one after the best rigid motion of the plane (2D Kabsch, rotation only: the developed
// sheet keeps the side its faces' normals point to).
static double cp_distance(const ori_pattern *orig, const ori_unfold_net *net)
{
    const ori_pattern *cp = ori_unfold_net_pattern(net);
    int n = ori_pattern_vertex_count(cp);
    cr_assert_eq(n, ori_pattern_vertex_count(orig), "one crease-pattern vertex per sheet vertex");
    ori_v2 ca = {0, 0}, cb = {0, 0};
    for (int v = 0; v < n; ++v) {
        ori_v3 a = ori_pattern_vertex(cp, v), b = ori_pattern_vertex(orig, ori_unfold_net_vertex_source(net, v));
        ca = ori_v2_add(ca, ori_v2_make(a.x, a.y)), cb = ori_v2_add(cb, ori_v2_make(b.x, b.y));
    }
    ca = ori_v2_scale(ca, 1.0 / n), cb = ori_v2_scale(cb, 1.0 / n);
    double sc = 0, cc = 0;
    for (int v = 0; v < n; ++v) {
        ori_v3 a3 = ori_pattern_vertex(cp, v), b3 = ori_pattern_vertex(orig, ori_unfold_net_vertex_source(net, v));
        ori_v2 a = ori_v2_sub(ori_v2_make(a3.x, a3.y), ca), b = ori_v2_sub(ori_v2_make(b3.x, b3.y), cb);
        cc += ori_v2_dot(a, b), sc += ori_v2_cross(a, b);
    }
    double t = atan2(sc, cc), cs = cos(t), sn = sin(t), worst = 0, lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int v = 0; v < n; ++v) {
        ori_v3 a3 = ori_pattern_vertex(cp, v), b3 = ori_pattern_vertex(orig, ori_unfold_net_vertex_source(net, v));
        ori_v2 a = ori_v2_sub(ori_v2_make(a3.x, a3.y), ca), b = ori_v2_sub(ori_v2_make(b3.x, b3.y), cb);
        ori_v2 ra = ori_v2_make(cs * a.x - sn * a.y, sn * a.x + cs * a.y);
        worst = fmax(worst, ori_v2_norm(ori_v2_sub(ra, b)));
        lo[0] = fmin(lo[0], b3.x), lo[1] = fmin(lo[1], b3.y), hi[0] = fmax(hi[0], b3.x), hi[1] = fmax(hi[1], b3.y);
    }
    return worst / hypot(hi[0] - lo[0], hi[1] - lo[1]);
}

// Every crease of the developed pattern carries the state's fold angle of the same crease of
// the original (found by its end vertices); returns the largest difference (radians).
static double angle_distance(const ori_pattern *orig, const double *angles, const ori_unfold_net *net)
{
    const ori_pattern *cp = ori_unfold_net_pattern(net);
    double worst = 0;
    int creases = 0;
    for (int e = 0; e < ori_pattern_edge_count(cp); ++e) {
        ori_edge x = ori_pattern_edge(cp, e);
        int a = ori_unfold_net_vertex_source(net, x.v[0]), b = ori_unfold_net_vertex_source(net, x.v[1]), found = -1;
        for (int k = 0; k < ori_pattern_edge_count(orig) && found < 0; ++k) {
            ori_edge y = ori_pattern_edge(orig, k);
            if ((y.v[0] == a && y.v[1] == b) || (y.v[0] == b && y.v[1] == a)) found = k;
        }
        cr_assert_geq(found, 0, "edge %d–%d of the crease pattern is an edge of the original", a, b);
        ori_edge y = ori_pattern_edge(orig, found);
        if (y.assignment == ORI_ASSIGN_BOUNDARY) {
            cr_assert_eq(x.assignment, ORI_ASSIGN_BOUNDARY);
            continue;
        }
        creases++;
        cr_assert_eq(x.assignment, angles[found] < 0 ? ORI_ASSIGN_MOUNTAIN : ORI_ASSIGN_VALLEY, "edge %d", e);
        worst = fmax(worst, fabs(x.fold_angle_rad - angles[found]));
    }
    cr_assert_gt(creases, 0);
    return worst;
}

static void round_trip(ori_generate_def g, double to_deg, const char *what)
{
    ori_v3 *pos;
    double *angles;
    ori_pattern *p = folded(&g, to_deg, &pos, &angles);
    for (int e = 0; e < ori_pattern_edge_count(p); ++e)
        if (ori_pattern_edge(p, e).assignment != ORI_ASSIGN_BOUNDARY)
            cr_assert_gt(fabs(angles[e]), 1 * DEG, "%s: crease %d folded (%g°)", what, e, angles[e] / DEG);
    ori_mesh *m = mesh_of(p, pos);
    ori_unfold_net *net = NULL;
    ori_error err;
    cr_assert_eq(ori_unfold_develop(m, 0.0, &net, &err), ORI_OK, "%s: %s", what, err.message);
    ori_unfold_result r = ori_unfold_net_result(net);
    cr_assert(r.developed);
    cr_assert_eq(r.cuts, 0);
    cr_assert_eq(r.faces, ori_pattern_face_count(p), "%s: no faces merged", what);
    cr_assert_gt(r.interior_vertices, 0);
    cr_assert_leq(ori_rad_to_deg(r.max_angle_defect_rad), 1e-10, "%s: angle defect %g°", what, ori_rad_to_deg(r.max_angle_defect_rad));
    cr_assert_leq(r.max_length_error, 1e-12, "%s: %g", what, r.max_length_error);
    cr_assert_leq(r.max_closing_error, 1e-12, "%s: %g", what, r.max_closing_error);
    double dcp = cp_distance(p, net), dang = angle_distance(p, angles, net);
    cr_assert_leq(dcp, 1e-12, "%s: crease pattern %g off the original", what, dcp);
    cr_assert_leq(dang, 1e-12, "%s: fold angles %g rad off the state's", what, dang);
    cr_assert(r.refolded);
    cr_assert_leq(r.fold_residual, 1e-9, "%s: loop residual %g", what, r.fold_residual);
    cr_assert_leq(r.max_refold_error, 1e-9, "%s: refolded %g off the shape", what, r.max_refold_error);
    cr_log_info("%s: %d faces, %d interior vertices, CP %.2g, angles %.2g rad, defect %.2g°, refold %.2g", what, r.faces,
                r.interior_vertices, dcp, dang, ori_rad_to_deg(r.max_angle_defect_rad), r.max_refold_error);
    ori_unfold_net_destroy(net);
    ori_unfold_mesh_destroy(m);
    ori_pattern_destroy(p);
    free(pos), free(angles);
}

Test(develop, miura_round_trip)
{
    ori_generate_def g = ori_default_generate_def(ORI_TESS_MIURA);
    g.rows = 3, g.cols = 4;
    round_trip(g, 70.0, "miura 3×4");
}

Test(develop, waterbomb_round_trip)
{
    ori_generate_def g = ori_default_generate_def(ORI_TESS_WATERBOMB);
    g.rows = 1, g.cols = 1;
    round_trip(g, -40.0, "waterbomb base");
}

Test(develop, waterbomb_tessellation_round_trip)
{
    ori_generate_def g = ori_default_generate_def(ORI_TESS_WATERBOMB);
    g.rows = 2, g.cols = 2;
    round_trip(g, -30.0, "waterbomb 2×2");
}


static ori_mesh *mesh_arrays(const ori_v3 *v, int nv, const int *fs, const int *fv, int nf)
{
    ori_mesh *m = NULL;
    ori_error err;
    cr_assert_eq(ori_unfold_mesh_create(v, nv, fs, fv, nf, &m, &err), ORI_OK, "%s", err.message);
    return m;
}

// A square frame (a sheet with a hole) folded 60° along x = 1.5 through both bars: two U-shaped
// faces joined by two creases; the face graph has a loop round the hole that must close.
Test(develop, frame_with_hole)
{
    const double th = 60 * DEG;
    ori_v2 flat[12] = {{0, 0}, {1.5, 0}, {1.5, 1}, {1, 1}, {1, 2}, {1.5, 2}, {1.5, 3}, {0, 3}, {3, 0}, {3, 3}, {2, 2}, {2, 1}};
    ori_v3 v[12];
    for (int i = 0; i < 12; ++i) {
        double d = flat[i].x - 1.5;
        v[i] = d > 0 ? ori_v3_make(1.5 + d * cos(th), flat[i].y, d * sin(th)) : ori_v3_make(flat[i].x, flat[i].y, 0);
    }
    int fs[3] = {0, 8, 16}, fv[16] = {0, 1, 2, 3, 4, 5, 6, 7, 1, 8, 9, 6, 5, 10, 11, 2};
    ori_mesh *m = mesh_arrays(v, 12, fs, fv, 2);
    ori_unfold_net *net = NULL;
    ori_error err;
    cr_assert_eq(ori_unfold_develop(m, 0.0, &net, &err), ORI_OK, "%s", err.message);
    ori_unfold_result r = ori_unfold_net_result(net);
    cr_assert_eq(r.interior_vertices, 0);
    cr_assert_leq(r.max_closing_error, 1e-15);
    const ori_pattern *cp = ori_unfold_net_pattern(net);
    int creases = 0;
    for (int e = 0; e < ori_pattern_edge_count(cp); ++e) {
        ori_edge x = ori_pattern_edge(cp, e);
        if (x.assignment == ORI_ASSIGN_BOUNDARY) continue;
        creases++;
        cr_assert_eq(x.assignment, ORI_ASSIGN_VALLEY, "folded toward +z: valley");
        cr_assert_float_eq(x.fold_angle_rad, th, 1e-14);
    }
    cr_assert_eq(creases, 2);
    cr_assert_eq(ori_pattern_vertex_count(cp), 12);
    // the crease pattern is the flat frame up to a rigid motion: distances between vertices kept
    for (int a = 0; a < 12; ++a)
        for (int b = 0; b < 12; ++b) {
            ori_v3 pa = ori_pattern_vertex(cp, a), pb = ori_pattern_vertex(cp, b);
            ori_v2 fa = flat[ori_unfold_net_vertex_source(net, a)], fb = flat[ori_unfold_net_vertex_source(net, b)];
            cr_assert_float_eq(hypot(pa.x - pb.x, pa.y - pb.y), ori_v2_norm(ori_v2_sub(fa, fb)), 1e-14);
        }
    cr_assert_leq(r.max_refold_error, 1e-12);
    ori_unfold_net_destroy(net);
    ori_unfold_mesh_destroy(m);
}

// A fan of triangles round one apex (vertex 0) at the given heights of the rim.
static ori_mesh *fan(int n, double turn_deg, const double *rim_z, bool closed)
{
    ori_v3 v[32];
    int fs[33], fv[96], nv = closed ? n + 1 : n + 2;
    v[0] = ori_v3_make(0, 0, 0);
    for (int i = 0; i < nv - 1; ++i) {
        double a = i * turn_deg * DEG;
        v[i + 1] = ori_v3_make(cos(a), sin(a), rim_z[i]);
    }
    for (int f = 0; f < n; ++f) {
        fs[f] = 3 * f;
        fv[3 * f] = 0, fv[3 * f + 1] = 1 + f, fv[3 * f + 2] = 1 + (closed ? (f + 1) % n : f + 1);
    }
    fs[n] = 3 * n;
    return mesh_arrays(v, nv, fs, fv, n);
}

static void refused(ori_mesh *m, const char *field, int element, const char *words)
{
    ori_unfold_net *net = NULL;
    ori_error err;
    cr_assert_eq(ori_unfold_develop(m, 0.0, &net, &err), ORI_ERR_NOT_FOUND);
    cr_assert_null(net);
    cr_assert_str_eq(err.field, field);
    cr_assert_eq(err.element, element);
    cr_assert(strstr(err.message, words), "%s", err.message);
    ori_unfold_mesh_destroy(m);
}

Test(develop, refusals)
{
    // a cone point: four triangles round an apex raised above the rim (angle sum < 360°)
    double up[8] = {-0.5, -0.5, -0.5, -0.5};
    refused(fan(4, 90, up, true), "vertices_coords", 0, "not developable at vertex 0: its face angles sum to 3");
    // a saddle: six triangles, rim alternately up and down (angle sum > 360°)
    double saddle[8] = {0.8, -0.8, 0.8, -0.8, 0.8, -0.8};
    refused(fan(6, 60, saddle, true), "vertices_coords", 0, "not developable at vertex 0");
    // a helical fan of 9 × ~50°: a developable strip whose development wraps over itself
    double helix[12];
    for (int i = 0; i < 10; ++i) helix[i] = 0.05 * i;
    refused(fan(9, 50, helix, false), "faces_vertices", 0, "overlaps itself");
    // an open octagonal tube: no interior vertex, but it does not close when laid out flat
    ori_v3 v[16];
    int fs[9], fv[32];
    for (int i = 0; i < 8; ++i) {
        v[i] = ori_v3_make(cos(i * ORI_PI / 4), sin(i * ORI_PI / 4), 0), v[8 + i] = ori_v3_make(v[i].x, v[i].y, 1);
        fs[i] = 4 * i;
        int j = (i + 1) % 8;
        fv[4 * i] = i, fv[4 * i + 1] = j, fv[4 * i + 2] = 8 + j, fv[4 * i + 3] = 8 + i;
    }
    fs[8] = 32;
    ori_mesh *m = mesh_arrays(v, 16, fs, fv, 8);
    ori_unfold_net *net = NULL;
    ori_error err;
    cr_assert_eq(ori_unfold_develop(m, 0.0, &net, &err), ORI_ERR_NOT_FOUND);
    cr_assert_str_eq(err.field, "vertices_coords");
    cr_assert(strstr(err.message, "not developable without a cut"), "%s", err.message);
    // a looser tolerance than 0.5 rad is refused
    cr_assert_eq(ori_unfold_develop(m, 0.6, &net, &err), ORI_ERR_RANGE);
    ori_unfold_mesh_destroy(m);
    // the cube: every corner 270°
    cr_assert_eq(ori_unfold_load_mesh(test_repo_path("tests/data/unfold/cube.obj"), &m, &err), ORI_OK);
    refused(m, "vertices_coords", 0, "sum to 270°");
}

// The shared folded forms, read in place. Their coordinates are rounded (6 digits for Hull's
// square twist), so the angle defects and the refold error are of that order, not 1e-15.
static ori_unfold_result develop_shared(const char *rel, double tol_rad, int creases)
{
    const char *path = test_require_shared(rel);
    ori_mesh *m = NULL;
    ori_error err;
    cr_assert_eq(ori_unfold_load_mesh(path, &m, &err), ORI_OK, "%s", err.message);
    ori_unfold_net *net = NULL;
    cr_assert_eq(ori_unfold_develop(m, tol_rad, &net, &err), ORI_OK, "%s: %s", rel, err.message);
    ori_unfold_result r = ori_unfold_net_result(net);
    const ori_pattern *cp = ori_unfold_net_pattern(net);
    int n = 0;
    for (int e = 0; e < ori_pattern_edge_count(cp); ++e) {
        ori_edge x = ori_pattern_edge(cp, e);
        if (x.assignment == ORI_ASSIGN_BOUNDARY) continue;
        n++;
        cr_assert((x.assignment == ORI_ASSIGN_MOUNTAIN) == (x.fold_angle_rad < 0));
        for (int k = 0; k < 2; ++k) cr_assert_float_eq(ori_pattern_vertex(cp, x.v[k]).z, 0.0, 0.0, "flat");
    }
    cr_assert_eq(n, creases, "%s: %d creases", rel, n);
    // the file's own M/V (where it has them) agree with the signs from the geometry (flat-folded
    // ±180° creases take theirs from the file)
    ori_fold *doc = NULL;
    ori_pattern *file = NULL;
    cr_assert_eq(ori_fold_load_file(path, &doc, &err), ORI_OK);
    cr_assert_eq(ori_fold_get_pattern(doc, 0, NULL, &file, &err), ORI_OK);
    int compared = 0;
    for (int e = 0; e < ori_pattern_edge_count(cp); ++e) {
        ori_edge x = ori_pattern_edge(cp, e);
        int a = ori_unfold_net_vertex_source(net, x.v[0]), b = ori_unfold_net_vertex_source(net, x.v[1]);
        for (int k = 0; k < ori_pattern_edge_count(file); ++k) {
            ori_edge y = ori_pattern_edge(file, k);
            if (!((y.v[0] == a && y.v[1] == b) || (y.v[0] == b && y.v[1] == a))) continue;
            if (y.assignment != ORI_ASSIGN_MOUNTAIN && y.assignment != ORI_ASSIGN_VALLEY) continue;
            cr_assert_eq(x.assignment, y.assignment, "%s: edge %d–%d", rel, a, b);
            compared++;
        }
    }
    cr_log_info("%s: %d creases' M/V equal the file's", rel, compared);
    ori_pattern_destroy(file);
    ori_fold_destroy(doc);
    cr_log_info("%s: %d faces, %d creases, %d interior vertices, defect %.3g°, length %.3g, closing %.3g, residual %.3g, "
                "refold %.3g",
                rel, r.faces, n, r.interior_vertices, ori_rad_to_deg(r.max_angle_defect_rad), r.max_length_error, r.max_closing_error,
                r.fold_residual, r.max_refold_error);
    ori_unfold_net_destroy(net);
    ori_unfold_mesh_destroy(m);
    return r;
}

Test(develop, shared_folded_forms)
{
    // Hull's rigidly folded square twist (6 digits): 4 interior vertices
    ori_unfold_result r = develop_shared("fold-spec/squaretwist.fold", 0.0, 12);
    cr_assert_eq(r.interior_vertices, 4);
    cr_assert_leq(ori_rad_to_deg(r.max_angle_defect_rad), 1e-3);
    cr_assert_leq(r.max_length_error, 1e-5);
    cr_assert_leq(r.max_refold_error, 1e-5);
    // Ku's three-fold example and the folded diagonal: integer coordinates, exact
    r = develop_shared("fold-spec/simple.fold", 0.0, 3);
    cr_assert_leq(r.max_refold_error, 1e-12);
    r = develop_shared("fold-spec/diagonal-folded.fold", 0.0, 1);
    cr_assert_leq(r.max_refold_error, 1e-12);
    // Rabbit Ear's kabuto, frame 0 (a folded form; full double coordinates)
    r = develop_shared("rabbit-ear/fold_kabuto.fold", 0.0, 20);
    cr_assert_leq(ori_rad_to_deg(r.max_angle_defect_rad), 1e-10);
    cr_assert_leq(r.max_refold_error, 1e-12);
    // Rabbit Ear's 3D bird base is a relaxed simulation, not an isometric fold: refused at the
    // default tolerance (vertex 10 sums to 360.165°), developed within 0.2°
    const char *path = test_require_shared("rabbit-ear/fold_bird-base-3d.fold");
    ori_mesh *m = NULL;
    ori_error err;
    cr_assert_eq(ori_unfold_load_mesh(path, &m, &err), ORI_OK);
    refused(m, "vertices_coords", 10, "360.165°");
    r = develop_shared("rabbit-ear/fold_bird-base-3d.fold", 0.2 * DEG, 20);
    cr_assert_leq(ori_rad_to_deg(r.max_angle_defect_rad), 0.2);
    cr_assert_leq(r.max_refold_error, 1e-3);
}

// orikin export's two-sided OBJ of a folded Miura-ori (tests/data/unfold/miura-folded.obj: crease
// 4 of tests/data/miura-4x4.fold driven to 60°, exact coordinates) develops back onto that file's
// crease pattern with its assignments; `orikin unfold -o` keeps the folded form as frame 1 and the
// result folds with `orikin fold`.
Test(develop, exported_obj_back_to_its_file)
{
    ori_mesh *m = NULL;
    ori_error err;
    cr_assert_eq(ori_unfold_load_mesh(test_repo_path("tests/data/unfold/miura-folded.obj"), &m, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_unfold_mesh_face_count(m), 16, "the back side is dropped, the front's triangles merged into quads");
    ori_unfold_net *net = NULL;
    cr_assert_eq(ori_unfold_develop(m, 0.0, &net, &err), ORI_OK, "%s", err.message);
    ori_fold *doc = NULL;
    ori_pattern *orig = NULL;
    cr_assert_eq(ori_fold_load_file(test_repo_path("tests/data/miura-4x4.fold"), &doc, &err), ORI_OK);
    cr_assert_eq(ori_fold_get_pattern(doc, 0, NULL, &orig, &err), ORI_OK);
    double d = cp_distance(orig, net);
    cr_assert_leq(d, 1e-12, "crease pattern %g off the file's", d);
    const ori_pattern *cp = ori_unfold_net_pattern(net);
    for (int e = 0; e < ori_pattern_edge_count(cp); ++e) {
        ori_edge x = ori_pattern_edge(cp, e);
        int a = ori_unfold_net_vertex_source(net, x.v[0]), b = ori_unfold_net_vertex_source(net, x.v[1]), hits = 0;
        for (int k = 0; k < ori_pattern_edge_count(orig); ++k) {
            ori_edge y = ori_pattern_edge(orig, k);
            if ((y.v[0] == a && y.v[1] == b) || (y.v[0] == b && y.v[1] == a)) {
                cr_assert_eq(x.assignment, y.assignment, "edge %d–%d", a, b);
                hits++;
            }
        }
        cr_assert_eq(hits, 1);
    }
    ori_pattern_destroy(orig);
    ori_fold_destroy(doc);
    ori_unfold_net_destroy(net);
    ori_unfold_mesh_destroy(m);

    char *dir = test_tmpdir(), args[1024], *out = NULL;
    snprintf(args, sizeof args, "unfold tests/data/unfold/miura-folded.obj -o %s/cp.fold", dir);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    free(out);
    snprintf(args, sizeof args, "%s/cp.fold", dir);
    cr_assert_eq(ori_fold_load_file(args, &doc, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_fold_frame_count(doc), 2);
    cr_assert_not(ori_fold_frame_is_folded_form(doc, 0));
    cr_assert(ori_fold_frame_is_folded_form(doc, 1));
    ori_pattern *f0 = NULL, *f1 = NULL;
    cr_assert_eq(ori_fold_get_pattern(doc, 0, NULL, &f0, &err), ORI_OK, "%s", err.message);
    int drive = -1;
    for (int e = 0; e < ori_pattern_edge_count(f0) && drive < 0; ++e)
        if (ori_pattern_edge(f0, e).assignment == ORI_ASSIGN_VALLEY) drive = e;
    cr_assert_geq(drive, 0);
    ori_pattern_destroy(f0);
    cr_assert_eq(ori_fold_get_pattern(doc, 1, NULL, &f1, &err), ORI_OK, "%s", err.message);
    cr_assert(ori_pattern_is_3d(f1));
    ori_pattern_destroy(f1);
    ori_fold_destroy(doc);
    snprintf(args, sizeof args, "fold %s/cp.fold --fix 0 --drive %d --to 30 --json", dir, drive);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    free(out);
    test_tmpdir_remove(dir);
}
