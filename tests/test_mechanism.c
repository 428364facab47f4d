// Mechanism: twists and product of exponentials, faces → bodies and creases → joints, loops
// around vertices and holes, spanning tree and poses, bones, Grübler–Kutzbach and the
// Jacobian DOF (dense and sparse), pose from coordinates.
#include <float.h>
#include <math.h>
#include <string.h>

#include "kinematics/kinematics_internal.h"
#include "support.h"

TestSuite(mechanism, .init = test_leak_setup, .fini = test_leak_check);

// --- helpers ---------------------------------------------------------------------------

static ori_pattern *open_corner(void) { return test_load_pattern(test_repo_path("examples/patterns/open-corner.fold"), 0); }

// Edge joining the points (x0, y0) and (x1, y1) of a flat pattern (either order).

// Face containing the point (x, y) strictly inside (convex faces).


// --- twists and POE ---------------------------------------------------------------------

Test(mechanism, twist_exponential_is_rotation_about_the_axis_through_q)
{
    ori_v3 q = ori_v3_make(2, 1, 0), w = ori_v3_make(0, 0, 1);
    ori_twist xi = ori_twist_from_axis(q, w);
    // ξ = (−ω×q, ω)
    cr_assert_float_eq(xi.v.x, 1.0, 1e-15);
    cr_assert_float_eq(xi.v.y, -2.0, 1e-15);
    cr_assert_float_eq(xi.v.z, 0.0, 1e-15);
    ori_rigid g = ori_twist_exp(xi, ORI_PI / 2);
    // q is fixed, q + (1,0,0) goes to q + (0,1,0).
    ori_v3 a = ori_rigid_apply(g, q), b = ori_rigid_apply(g, ori_v3_make(3, 1, 0));
    cr_assert_float_eq(a.x, 2.0, 1e-15);
    cr_assert_float_eq(a.y, 1.0, 1e-15);
    cr_assert_float_eq(b.x, 2.0, 1e-15);
    cr_assert_float_eq(b.y, 2.0, 1e-15);
}

Test(mechanism, product_of_exponentials_reproduces_the_thesis_end_effector)
{
    // Thesis Fig. 5-3/5-4, Frame A: ω1 = (1,1,0)/√2 through q1 = 0, Θ1 = 90° moves the end
    // effector (0,1,0) to (0.5, 0.5, 1/√2); the second joint of the chain passes through it.
    ori_twist x1 = ori_twist_from_axis(ori_v3_make(0, 0, 0), ori_v3_make(1, 1, 0));
    ori_twist x2 = ori_twist_from_axis(ori_v3_make(0, 1, 0), ori_v3_make(1, 0, 0));
    ori_rigid g = ori_rigid_compose(ori_twist_exp(x1, ORI_PI / 2), ori_twist_exp(x2, 0.7));
    ori_v3 p = ori_rigid_apply(g, ori_v3_make(0, 1, 0));
    cr_assert_float_eq(p.x, 0.5, 1e-15);
    cr_assert_float_eq(p.y, 0.5, 1e-15);
    cr_assert_float_eq(p.z, 1.0 / sqrt(2.0), 1e-15);
}

Test(mechanism, rotation_vector_log_map_inverts_rodrigues)
{
    ori_v3 k = ori_v3_normalize(ori_v3_make(1, -2, 3));
    double angles[] = {0.0, 1e-9, 0.3, 2.0, 3.0, ORI_PI - 1e-7};
    for (size_t i = 0; i < sizeof angles / sizeof angles[0]; ++i) {
        ori_v3 r = ori__kin_rotvec(ori_m3_rotation(k, angles[i]));
        cr_assert_float_eq(r.x, k.x * angles[i], 1e-12);
        cr_assert_float_eq(r.y, k.y * angles[i], 1e-12);
        cr_assert_float_eq(r.z, k.z * angles[i], 1e-12);
    }
}

// --- bodies, joints, loops -----------------------------------------------------------------

Test(mechanism, open_corner_bodies_joints_and_loop)
{
    ori_pattern *p = open_corner();
    ori_mechanism *m = test_mechanism_of(p);
    cr_assert_eq(ori_mechanism_face_count(m), 5);
    cr_assert_eq(ori_mechanism_joint_count(m), 5);
    cr_assert_eq(ori_mechanism_loop_count(m), 1);
    ori_loop L = ori_mechanism_loop(m, 0);
    cr_assert_eq(L.crease_count, 5);
    cr_assert_eq(L.rows, 3);
    cr_assert_eq(ori_pattern_vertex(p, L.vertex).x, 1.0);
    cr_assert_eq(ori_pattern_vertex(p, L.vertex).y, 1.0);
    // Boundary edges are not joints; the diagonal's axis runs from v[0] to v[1], face_left on
    // its left.
    cr_assert_eq(ori_mechanism_edge_joint(m, test_edge_at(p, 0, 0, 1, 0)), ORI_NULL_INDEX);
    int diag = test_edge_at(p, 1, 1, 0, 0);
    ori_joint J = ori_mechanism_joint(m, ori_mechanism_edge_joint(m, diag));
    ori_edge E = ori_pattern_edge(p, diag);
    ori_v3 a = ori_pattern_vertex(p, E.v[0]), b = ori_pattern_vertex(p, E.v[1]);
    cr_assert_float_eq(J.q.x, a.x, 0.0);
    cr_assert_float_eq(J.omega.x, (b.x - a.x) / sqrt(2.0), 1e-15);
    int v[8];
    int n = ori_pattern_face_vertices(p, J.face_left, v, 8);
    double cx = 0, cy = 0;
    for (int k = 0; k < n; ++k) {
        cx += ori_pattern_vertex(p, v[k]).x / n;
        cy += ori_pattern_vertex(p, v[k]).y / n;
    }
    cr_assert_gt(ori_v2_cross(ori_v2_make(J.omega.x, J.omega.y), ori_v2_make(cx - J.q.x, cy - J.q.y)), 0.0);
    // Loop creases counter-clockwise: each face F(i) is on the left of crease i walked out.
    int edges[8], faces[8];
    cr_assert_eq(ori_mechanism_loop_edges(m, 0, edges, 8), 5);
    cr_assert_eq(ori_mechanism_loop_faces(m, 0, faces, 8), 5);
    double prev = -1.0;
    int wraps = 0;
    for (int i = 0; i < 5; ++i) {
        ori_edge Ei = ori_pattern_edge(p, edges[i]);
        int far = ori_pattern_vertex(p, Ei.v[0]).x == 1.0 && ori_pattern_vertex(p, Ei.v[0]).y == 1.0 ? Ei.v[1] : Ei.v[0];
        double ang = atan2(ori_pattern_vertex(p, far).y - 1.0, ori_pattern_vertex(p, far).x - 1.0);
        if (ang < prev) wraps++;
        prev = ang;
    }
    cr_assert_leq(wraps, 1);
    // Vertex faces: the five faces around the centre.
    int vf[8];
    cr_assert_eq(ori_mechanism_vertex_faces(m, L.vertex, vf, 8), 5);
    for (int i = 0; i < 5; ++i) cr_assert_neq(vf[i], ORI_NULL_INDEX);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

Test(mechanism, grubler_count_of_the_open_corner_is_minus_one)
{
    ori_pattern *p = open_corner();
    ori_mechanism *m = test_mechanism_of(p);
    cr_assert_eq(ori_mechanism_grubler(m), -1); // 6(5 − 1) − 5·5, thesis eq. (1.3)
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

Test(mechanism, bones_join_face_centroids_to_crease_midpoints)
{
    ori_pattern *p = open_corner();
    ori_mechanism *m = test_mechanism_of(p);
    cr_assert_eq(ori_mechanism_bone_count(m), 10); // 5 creases × 2 faces
    int T2 = test_face_at(p, 0.7, 0.3), diag = test_edge_at(p, 1, 1, 0, 0);
    bool found = false;
    for (int i = 0; i < ori_mechanism_bone_count(m); ++i) {
        ori_bone b = ori_mechanism_bone(m, i);
        if (b.face != T2 || b.edge != diag) continue;
        found = true;
        cr_assert_float_eq(b.from.x, 2.0 / 3.0, 1e-15); // centroid of (0,0), (1,0), (1,1)
        cr_assert_float_eq(b.from.y, 1.0 / 3.0, 1e-15);
        cr_assert_float_eq(b.to.x, 0.5, 1e-15);
        cr_assert_float_eq(b.to.y, 0.5, 1e-15);
    }
    cr_assert(found);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

Test(mechanism, spanning_tree_and_poses_by_product_of_exponentials)
{
    ori_pattern *p = open_corner();
    ori_mechanism *m = test_mechanism_of(p);
    int T2 = test_face_at(p, 0.7, 0.3), T1 = test_face_at(p, 0.3, 0.7), diag = test_edge_at(p, 1, 1, 0, 0);
    int parent_face[5], parent_edge[5];
    ori_mechanism_spanning_tree(m, T2, parent_face, parent_edge);
    cr_assert_eq(parent_face[T2], ORI_NULL_INDEX);
    int roots = 0;
    for (int f = 0; f < 5; ++f) roots += parent_face[f] == ORI_NULL_INDEX;
    cr_assert_eq(roots, 1);
    // Fold only the diagonal by +90° (valley): T1 turns about the diagonal and lifts to +z.
    double ang[13] = {0};
    ang[diag] = ORI_PI / 2;
    ori_rigid poses[5];
    ori_mechanism_face_poses(m, ang, T2, ori_rigid_identity(), poses);
    ori_v3 c = ori_rigid_apply(poses[T1], ori_v3_make(0, 1, 0));
    cr_assert_float_eq(c.x, 0.5, 1e-15);
    cr_assert_float_eq(c.y, 0.5, 1e-15);
    cr_assert_float_eq(c.z, 1.0 / sqrt(2.0), 1e-15);
    // The same fold seen from T1 fixed: T2 lifts to +z too (valley from either side).
    ori_mechanism_face_poses(m, ang, T1, ori_rigid_identity(), poses);
    ori_v3 d = ori_rigid_apply(poses[T2], ori_v3_make(1, 0, 0));
    cr_assert_gt(d.z, 0.5);
    // A world pose of the fixed face carries everything.
    ori_rigid G;
    G.r = ori_m3_rotation(ori_v3_make(0, 0, 1), 0.3);
    G.t = ori_v3_make(5, -1, 2);
    ori_v3 pos[9];
    ori_mechanism_vertex_positions(m, ang, T2, G, pos);
    ori_v3 want = ori_rigid_apply(G, ori_v3_make(0.5, 0.5, 1.0 / sqrt(2.0)));
    int v01 = -1;
    for (int v = 0; v < 9; ++v)
        if (ori_pattern_vertex(p, v).x == 0 && ori_pattern_vertex(p, v).y == 1) v01 = v;
    cr_assert_float_eq(pos[v01].x, want.x, 1e-14);
    cr_assert_float_eq(pos[v01].y, want.y, 1e-14);
    cr_assert_float_eq(pos[v01].z, want.z, 1e-14);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

Test(mechanism, residual_of_a_non_closing_state_and_of_a_closing_one)
{
    ori_pattern *p = open_corner();
    ori_mechanism *m = test_mechanism_of(p);
    double ang[13] = {0};
    cr_assert_eq(ori_mechanism_residual(m, ang), 0.0);
    ang[test_edge_at(p, 1, 1, 0, 0)] = 0.5; // one crease alone does not close the loop
    cr_assert_gt(ori_mechanism_residual(m, ang), 0.1);
    // The straight line left–right folds as one crease: right = left = θ closes.
    double b[13] = {0};
    b[test_edge_at(p, 1, 1, 2, 1)] = 0.8;
    b[test_edge_at(p, 1, 1, 0, 1)] = 0.8;
    cr_assert_leq(ori_mechanism_residual(m, b), 1e-15);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

Test(mechanism, pose_from_coordinates_recovers_a_rigid_motion)
{
    ori_pattern *p = open_corner();
    ori_mechanism *m = test_mechanism_of(p);
    ori_rigid G;
    G.r = ori_m3_rotation(ori_v3_normalize(ori_v3_make(1, 2, 2)), 1.1);
    G.t = ori_v3_make(-3, 4, 0.5);
    ori_v3 coords[9];
    for (int v = 0; v < 9; ++v) coords[v] = ori_rigid_apply(G, ori_pattern_vertex(p, v));
    ori_rigid H;
    ori_error err;
    int f = test_face_at(p, 1.5, 0.5);
    cr_assert_eq(ori_mechanism_face_pose_from_coords(m, f, coords, &H, &err), ORI_OK);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) cr_assert_float_eq(H.r.m[i][j], G.r.m[i][j], 1e-14);
    cr_assert_float_eq(H.t.x, G.t.x, 1e-14);
    // A face that is not rigidly placed is rejected.
    coords[0].z += 0.3;
    cr_assert_eq(ori_mechanism_face_pose_from_coords(m, test_face_at(p, 0.7, 0.3), coords, &H, &err), ORI_ERR_DEGENERATE);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

Test(mechanism, folded_form_input_is_rejected)
{
    ori_pattern *p = open_corner();
    ori_pattern_set_vertex(p, 0, ori_v3_make(0, 0, 0.5));
    ori_error err;
    cr_assert_eq(ori_pattern_build(p, NULL, &err), ORI_OK);
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = p;
    ori_mechanism *m = (ori_mechanism *)1;
    cr_assert_eq(ori_mechanism_create(&md, &m, &err), ORI_ERR_ARGUMENT);
    cr_assert_null(m);
    cr_assert(strstr(err.message, "flat crease pattern"));
    ori_pattern_destroy(p);
}

// --- holes --------------------------------------------------------------------------------

// A 3×3 square with a 1×1 hole in the middle and four pinwheel creases from the hole's
// corners to the outer sides: four faces in a ring, no interior vertex, one hole loop.
static ori_pattern *pinwheel_frame(void)
{
    ori_pattern_def pd = ori_default_pattern_def();
    ori_pattern *p = ori_pattern_create(&pd);
    double pts[][2] = {{0, 0}, {1, 0}, {3, 0}, {3, 1}, {3, 3}, {2, 3}, {0, 3}, {0, 2}, {1, 1}, {2, 1}, {2, 2}, {1, 2}};
    for (int i = 0; i < 12; ++i) ori_pattern_add_vertex(p, ori_v3_make(pts[i][0], pts[i][1], 0));
    int outer[] = {0, 1, 2, 3, 4, 5, 6, 7};
    for (int i = 0; i < 8; ++i) ori_pattern_add_edge(p, outer[i], outer[(i + 1) % 8], ORI_ASSIGN_BOUNDARY, 0);
    int hole[] = {8, 9, 10, 11};
    for (int i = 0; i < 4; ++i) ori_pattern_add_edge(p, hole[i], hole[(i + 1) % 4], ORI_ASSIGN_BOUNDARY, 0);
    ori_pattern_add_edge(p, 8, 1, ORI_ASSIGN_VALLEY, 0);
    ori_pattern_add_edge(p, 9, 3, ORI_ASSIGN_VALLEY, 0);
    ori_pattern_add_edge(p, 10, 5, ORI_ASSIGN_VALLEY, 0);
    ori_pattern_add_edge(p, 11, 7, ORI_ASSIGN_VALLEY, 0);
    int f0[] = {1, 2, 3, 9, 8}, f1[] = {3, 4, 5, 10, 9}, f2[] = {5, 6, 7, 11, 10}, f3[] = {7, 0, 1, 8, 11};
    ori_pattern_add_face(p, f0, 5);
    ori_pattern_add_face(p, f1, 5);
    ori_pattern_add_face(p, f2, 5);
    ori_pattern_add_face(p, f3, 5);
    ori_error err;
    cr_assert_eq(ori_pattern_build(p, NULL, &err), ORI_OK, "%s", err.message);
    return p;
}

Test(mechanism, a_hole_adds_a_six_equation_loop)
{
    ori_pattern *p = pinwheel_frame();
    ori_mechanism *m = test_mechanism_of(p);
    cr_assert_eq(ori_mechanism_joint_count(m), 4);
    cr_assert_eq(ori_mechanism_loop_count(m), 1);
    ori_loop L = ori_mechanism_loop(m, 0);
    cr_assert_eq(L.vertex, ORI_NULL_INDEX);
    cr_assert_eq(L.rows, 6);
    cr_assert_eq(L.crease_count, 4);
    cr_assert_eq(ori_mechanism_grubler(m), 6 * 3 - 5 * 4);
    double ang[16] = {0};
    cr_assert_eq(ori_mechanism_residual(m, ang), 0.0);
    // Folding one crease of the ring alone breaks the translation closure around the hole.
    ang[12] = 0.3;
    cr_assert_gt(ori_mechanism_residual(m, ang), 1e-3);
    // At the flat state the four axes (two pairs of parallel lines) leave a 1-dimensional
    // infinitesimal motion: rank 3 of 6 equations over 4 creases.
    ori_dof_def dd = ori_default_dof_def();
    dd.probe_generic = false;
    ori_dof_result r;
    ori_error err;
    cr_assert_eq(ori_mechanism_dof(m, &dd, &r, &err), ORI_OK);
    cr_assert_eq(r.equations, 6);
    cr_assert_eq(r.unknowns, 4);
    cr_assert_eq(r.rank, 3);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

// --- degrees of freedom -------------------------------------------------------------------

Test(mechanism, jacobian_dof_of_the_open_corner_flat_is_singular_and_two_nearby)
{
    ori_pattern *p = open_corner();
    ori_mechanism *m = test_mechanism_of(p);
    ori_dof_def dd = ori_default_dof_def();
    ori_dof_result r;
    ori_error err;
    cr_assert_eq(ori_mechanism_dof(m, &dd, &r, &err), ORI_OK);
    cr_assert_eq(r.grubler, -1);
    cr_assert_eq(r.equations, 3);
    cr_assert_eq(r.unknowns, 5);
    cr_assert_eq(r.rank, 2); // the flat vertex cannot close z at first order
    cr_assert_eq(r.dof, 3);
    cr_assert_eq(r.generic_dof, 2); // the spherical 5R loop
    cr_assert(r.singular);
    cr_assert(r.dense);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

Test(mechanism, jacobian_dof_of_the_open_corner_away_from_flat_is_two)
{
    ori_pattern *p = open_corner();
    ori_mechanism *m = test_mechanism_of(p);
    // A closed folded state: right = up-left line folded as one (left–right line) plus nothing
    // else is special; use the first fold at Θ1 = 90° (from the closed form).
    double ang[13] = {0};
    ang[test_edge_at(p, 1, 1, 0, 0)] = ORI_PI / 2;
    ang[test_edge_at(p, 1, 1, 2, 1)] = asin(1.0 / sqrt(3.0));
    ang[test_edge_at(p, 1, 1, 1, 2)] = ORI_PI / 3;
    ang[test_edge_at(p, 1, 1, 0, 1)] = -asin(1.0 / sqrt(3.0));
    cr_assert_leq(ori_mechanism_residual(m, ang), 1e-15);
    ori_dof_def dd = ori_default_dof_def();
    dd.angles_rad = ang;
    ori_dof_result r;
    ori_error err;
    cr_assert_eq(ori_mechanism_dof(m, &dd, &r, &err), ORI_OK);
    cr_assert_eq(r.rank, 3);
    cr_assert_eq(r.dof, 2);
    cr_assert_eq(r.generic_dof, 2);
    cr_assert_not(r.singular);
    // Locking the down crease leaves the 4R: one DOF.
    int lock = test_edge_at(p, 1, 1, 1, 0);
    dd.locked_edges = &lock;
    dd.locked_count = 1;
    cr_assert_eq(ori_mechanism_dof(m, &dd, &r, &err), ORI_OK);
    cr_assert_eq(r.dof, 1);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

Test(mechanism, dof_rejects_angles_that_do_not_close)
{
    ori_pattern *p = open_corner();
    ori_mechanism *m = test_mechanism_of(p);
    double ang[13] = {0};
    ang[test_edge_at(p, 1, 1, 0, 0)] = 0.5;
    ori_dof_def dd = ori_default_dof_def();
    dd.angles_rad = ang;
    ori_dof_result r;
    ori_error err;
    cr_assert_eq(ori_mechanism_dof(m, &dd, &r, &err), ORI_ERR_ARGUMENT);
    cr_assert(strstr(err.message, "do not close"));
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

Test(mechanism, sparse_dof_agrees_with_dense_svd)
{
    // A folded 6×6 Miura state from the numeric solver, then the sparse nullity (forced by a
    // direct call) against the dense SVD.
    // Generator parameters (test_miura): straight edge 1, vertex rows 1 apart shifted by 0.4 on
    // odd rows: zig-zag edge √(0.4² + 1), cell angle atan2(1, 0.4).
    ori_pattern *p = test_miura(6, 6, 1.0, sqrt(0.4 * 0.4 + 1.0), atan2(1.0, 0.4), NULL);
    ori_mechanism *m = test_mechanism_of(p);
    int drive = ori_pattern_find_edge(p, 3 * 7 + 3, 4 * 7 + 3);
    double sg = ori_pattern_edge(p, drive).assignment == ORI_ASSIGN_VALLEY ? 1.0 : -1.0;
    ori_motion_def d = ori_default_motion_def();
    d.driven_edge = drive;
    d.to_rad = sg * 1.0;
    d.step_rad = 1.0;
    ori_motion *mo = NULL;
    ori_error err;
    cr_assert_eq(ori_motion_solve(m, &d, &mo, &err), ORI_OK);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_VALID);
    const double *ang = ori_motion_frame_angles(mo, ori_motion_frame_count(mo) - 1);
    int J = ori_mechanism_joint_count(m);
    double *th = malloc(sizeof(double) * (size_t)J);
    int *col = malloc(sizeof(int) * (size_t)J);
    ori__kin_edges_to_joints(m, ang, th);
    int n = 0;
    for (int j = 0; j < J; ++j) col[j] = n++;
    ori_dof_result dense;
    cr_assert_eq(ori__kin_nullity(m, th, col, n, &dense, &err), ORI_OK);
    cr_assert(dense.dense);
    cr_assert_eq(dense.dof, 1);
    ori_dof_result sparse;
    cr_assert_eq(ori__kin_nullity_sparse(m, th, col, n, &sparse, &err), ORI_OK);
    cr_assert_not(sparse.dense);
    cr_assert_eq(sparse.dof, 1);
    cr_assert_float_eq(sparse.sigma_max, dense.sigma_max, 0.02 * dense.sigma_max, "%.17g vs %.17g", sparse.sigma_max, dense.sigma_max); // 40 power iterations: σ_max only scales the rank threshold
    // At the flat state: nullity = creases − 2 × interior vertices for both methods.
    double *flat = calloc((size_t)J, sizeof(double));
    cr_assert_eq(ori__kin_nullity(m, flat, col, n, &dense, &err), ORI_OK);
    cr_assert_eq(ori__kin_nullity_sparse(m, flat, col, n, &sparse, &err), ORI_OK);
    cr_assert_eq(dense.dof, n - 2 * 25);
    cr_assert_eq(sparse.dof, dense.dof);
    free(flat);
    kin_sls *sls = ori__kin_jacobian_sls(m, col, n, th);
    // Products against the dense evaluation: J·1 summed two ways.
    double *ones = malloc(sizeof(double) * (size_t)n), *y = malloc(sizeof(double) * (size_t)m->rows);
    for (int k = 0; k < n; ++k) ones[k] = 1.0;
    ori__sls_mult(sls, ones, y);
    double *blocks = calloc((size_t)(6 * m->loop_col_total) + 1, sizeof(double));
    ori__kin_eval(m, th, NULL, blocks, NULL);
    for (int l = 0; l < m->loop_count; ++l) {
        const kin_loop *L = &m->loops[l];
        for (int r = 0; r < L->rows; ++r) {
            double s = 0.0;
            for (int c = 0; c < L->col_count; ++c) s += blocks[6 * (L->col_first + c) + r];
            cr_assert_float_eq(y[L->row0 + r], s, 1e-14);
        }
    }
    ori__sls_destroy(sls);
    free(ones);
    free(y);
    free(blocks);
    free(th);
    free(col);
    ori_motion_destroy(mo);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

Test(mechanism, disconnected_sheet_is_rejected_naming_a_face)
{
    ori_pattern_def pd = ori_default_pattern_def();
    ori_pattern *p = ori_pattern_create(&pd);
    double pts[][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {3, 0}, {3, 1}, {2, 1}};
    for (int i = 0; i < 8; ++i) ori_pattern_add_vertex(p, ori_v3_make(pts[i][0], pts[i][1], 0));
    for (int s = 0; s < 2; ++s)
        for (int i = 0; i < 4; ++i) ori_pattern_add_edge(p, 4 * s + i, 4 * s + (i + 1) % 4, ORI_ASSIGN_BOUNDARY, 0);
    ori_error err;
    cr_assert_eq(ori_pattern_build(p, NULL, &err), ORI_OK);
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = p;
    ori_mechanism *m;
    cr_assert_eq(ori_mechanism_create(&md, &m, &err), ORI_ERR_TOPOLOGY);
    cr_assert_eq(err.element, 1);
    cr_assert(strstr(err.message, "not connected"));
    ori_pattern_destroy(p);
}

// --- loop evaluation --------------------------------------------------------------------------

// At a closing state the Jacobian columns are the derivatives of the residual (rotation vector
// of P, translation / diagonal): central differences agree to O(h²). The rotation cache of the
// solver gives the same numbers as rotations computed per crossing.
static void check_jacobian(const ori_mechanism *m, const double *th)
{
    int J = m->joint_count;
    double *res = malloc(sizeof(double) * (size_t)m->rows), *res2 = malloc(sizeof(double) * (size_t)m->rows);
    double *rp = malloc(sizeof(double) * (size_t)m->rows), *rm = malloc(sizeof(double) * (size_t)m->rows);
    double *blocks = calloc((size_t)(6 * m->loop_col_total) + 1, sizeof(double));
    double *blocks2 = calloc((size_t)(6 * m->loop_col_total) + 1, sizeof(double));
    double *rot = malloc(sizeof(double) * 2 * (size_t)J);
    double *t = malloc(sizeof(double) * (size_t)J);
    double r1 = ori__kin_eval(m, th, res, blocks, rot);
    double r2 = ori__kin_eval(m, th, res2, blocks2, NULL);
    cr_assert_leq(r1, ORI_TOL_RESIDUAL);
    cr_assert_float_eq(r1, r2, 1e-15);
    for (int k = 0; k < m->rows; ++k) cr_assert_float_eq(res[k], res2[k], 1e-15);
    for (int k = 0; k < 6 * m->loop_col_total; ++k) cr_assert_float_eq(blocks[k], blocks2[k], 1e-15);
    const double h = 1e-6;
    for (int j = 0; j < J; ++j) {
        memcpy(t, th, sizeof(double) * (size_t)J);
        t[j] = th[j] + h;
        ori__kin_eval(m, t, rp, NULL, rot);
        t[j] = th[j] - h;
        ori__kin_eval(m, t, rm, NULL, rot);
        for (int l = 0; l < m->loop_count; ++l) {
            const kin_loop *L = &m->loops[l];
            for (int r = 0; r < L->rows; ++r) {
                double want = 0.0;
                for (int c = 0; c < L->col_count; ++c)
                    if (m->loop_cols[L->col_first + c] == j) want = blocks[6 * (L->col_first + c) + r];
                double fd = (rp[L->row0 + r] - rm[L->row0 + r]) / (2 * h);
                cr_assert_float_eq(fd, want, 1e-8, "joint %d loop %d row %d", j, l, r);
            }
        }
    }
    free(res);
    free(res2);
    free(rp);
    free(rm);
    free(blocks);
    free(blocks2);
    free(rot);
    free(t);
}

Test(mechanism, loop_jacobian_is_the_derivative_of_the_residual)
{
    // A folded Miura-ori (vertex loops), and the flat ring around a hole (a 6-row loop).
    ori_pattern *p = test_miura(3, 4, 1.0, 1.1, 1.2, NULL);
    ori_mechanism *m = test_mechanism_of(p);
    int drive = ori_pattern_find_edge(p, 1 * 5 + 2, 2 * 5 + 2);
    ori_motion_def d = ori_default_motion_def();
    d.driven_edge = drive;
    d.to_rad = (ori_pattern_edge(p, drive).assignment == ORI_ASSIGN_VALLEY ? 1.0 : -1.0) * 1.2;
    d.step_rad = 1.2;
    ori_motion *mo = NULL;
    ori_error err;
    cr_assert_eq(ori_motion_solve(m, &d, &mo, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_VALID);
    double *th = malloc(sizeof(double) * (size_t)m->joint_count);
    ori__kin_edges_to_joints(m, ori_motion_frame_angles(mo, ori_motion_frame_count(mo) - 1), th);
    check_jacobian(m, th);
    free(th);
    ori_motion_destroy(mo);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
    p = pinwheel_frame();
    m = test_mechanism_of(p);
    double flat[4] = {0};
    check_jacobian(m, flat);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}
