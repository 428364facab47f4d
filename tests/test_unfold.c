// unfold: polyhedral surfaces to nets. The Platonic solids' nets are counted up to congruence
// (cube 11, tetrahedron 2, octahedron 11: the known numbers), every net found is folded back by
// the kinematics onto the shape (1e-9 relative), and bad shapes are refused naming the face.
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "support.h"

#define PI_2 1.57079632679489661923

static ori_unfold_result unfold(const char *rel, bool all)
{
    ori_mesh *m = NULL;
    ori_error err;
    cr_assert_eq(ori_unfold_load_mesh(test_repo_path(rel), &m, &err), ORI_OK, "%s", err.message);
    ori_unfold_def def = ori_default_unfold_def();
    def.all = all;
    ori_unfold_net *net = NULL;
    cr_assert_eq(ori_unfold_solve(m, &def, &net, &err), ORI_OK, "%s", err.message);
    ori_unfold_result r = ori_unfold_net_result(net);
    const ori_pattern *p = ori_unfold_net_pattern(net);
    cr_assert_eq(ori_pattern_face_count(p), r.faces);
    // every edge is a crease with the fold angle of the shape, or a cut glued to its partner
    int creases = 0, cuts = 0;
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge x = ori_pattern_edge(p, e);
        if (x.assignment == ORI_ASSIGN_BOUNDARY) {
            int g = ori_unfold_net_glue(net, e);
            if (g >= 0) {
                cr_assert_eq(ori_unfold_net_glue(net, g), e);
                cuts++;
            }
        } else {
            // F: coplanar neighbours not merged (a ring around a hole stays in pieces)
            if (x.assignment == ORI_ASSIGN_FLAT) cr_assert_eq(x.fold_angle_rad, 0.0);
            else cr_assert(x.assignment == ORI_ASSIGN_MOUNTAIN || x.assignment == ORI_ASSIGN_VALLEY);
            cr_assert((x.assignment == ORI_ASSIGN_MOUNTAIN) == (x.fold_angle_rad < 0.0));
            creases++;
        }
    }
    // a forest of faces (faces − pieces creases), and the cuts whose sides lie on each other
    // (through flat vertices) written as the creases they are
    cr_assert_geq(creases, r.faces - r.pieces);
    cr_assert_eq(cuts, 2 * r.cuts, "every cut is a glued pair of boundary edges");
    ori_unfold_net_destroy(net);
    ori_unfold_mesh_destroy(m);
    return r;
}

Test(unfold, platonic_nets, .init = test_leak_setup, .fini = test_leak_check)
{
    struct {
        const char *file;
        int faces, nets;
    } solids[] = {{"tests/data/unfold/tetrahedron.obj", 4, 2},
                  {"tests/data/unfold/cube.obj", 6, 11},
                  {"tests/data/unfold/octahedron.obj", 8, 11}};
    for (int i = 0; i < 3; ++i) {
        ori_unfold_result r = unfold(solids[i].file, true);
        cr_assert_eq(r.faces, solids[i].faces);
        cr_assert_eq(r.pieces, 1);
        cr_assert_eq(r.overlaps, 0);
        cr_assert_eq(r.distinct_nets, solids[i].nets, "%s: %d nets", solids[i].file, r.distinct_nets);
        cr_assert(r.refolded);
        cr_assert_leq(r.max_refold_error, 1e-9);
        cr_assert_eq(r.fold_order, ORI_FOLD_ORDER_TOGETHER);
    }
}

Test(unfold, dodecahedron_icosahedron_refold, .init = test_leak_setup, .fini = test_leak_check)
{
    ori_unfold_result d = unfold("tests/data/unfold/dodecahedron.obj", false);
    cr_assert_eq(d.faces, 12);
    cr_assert_eq(d.pieces, 1);
    cr_assert_leq(d.max_refold_error, 1e-9);
    ori_unfold_result i = unfold("tests/data/unfold/icosahedron.obj", false);
    cr_assert_eq(i.faces, 20);
    cr_assert_eq(i.pieces, 1);
    cr_assert_leq(i.max_refold_error, 1e-9);
}

Test(unfold, non_convex_shapes, .init = test_leak_setup, .fini = test_leak_check)
{
    ori_unfold_result l = unfold("tests/data/unfold/l-prism.obj", false);
    cr_assert_eq(l.faces, 8); // two L-shaped caps and six walls
    cr_assert_eq(l.overlaps, 0);
    cr_assert_eq(l.pieces, 1);
    cr_assert_leq(l.max_refold_error, 1e-9);
    ori_unfold_result h = unfold("tests/data/unfold/box-with-hole.obj", false);
    cr_assert_eq(h.faces, 16);
    // folding every crease together makes the frame's faces pass through each other; one
    // crease at a time from the leaves of the face tree does not
    cr_assert_eq(h.fold_order, ORI_FOLD_ORDER_LEAVES_FIRST);
    cr_assert(!h.motion_collides);
    cr_assert_eq(h.overlaps, 0);
    cr_assert_eq(h.pieces, 1);
    cr_assert_leq(h.max_refold_error, 1e-9);
}

// Triangulated faces are merged back into the polygons they lie in.
Test(unfold, coplanar_faces_merged, .init = test_leak_setup, .fini = test_leak_check)
{
    ori_v3 v[8];
    for (int i = 0; i < 8; ++i) v[i] = ori_v3_make(i >> 2 & 1, i >> 1 & 1, i & 1);
    int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    int fs[13], fv[36];
    for (int q = 0; q < 6; ++q) {
        int t[6] = {quads[q][0], quads[q][1], quads[q][2], quads[q][0], quads[q][2], quads[q][3]};
        for (int j = 0; j < 6; ++j) fv[6 * q + j] = t[j];
    }
    for (int f = 0; f <= 12; ++f) fs[f] = 3 * f;
    ori_mesh *m = NULL;
    ori_error err;
    cr_assert_eq(ori_unfold_mesh_create(v, 8, fs, fv, 12, &m, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_unfold_mesh_face_count(m), 6);
    ori_unfold_def def = ori_default_unfold_def();
    def.all = true;
    ori_unfold_net *net = NULL;
    cr_assert_eq(ori_unfold_solve(m, &def, &net, &err), ORI_OK);
    ori_unfold_result r = ori_unfold_net_result(net);
    cr_assert_eq(r.input_faces, 12);
    cr_assert_eq(r.distinct_nets, 11);
    int src[4];
    for (int f = 0; f < 6; ++f) cr_assert_eq(ori_unfold_net_face_source(net, f, src, 4), 2);
    ori_unfold_net_destroy(net);
    ori_unfold_mesh_destroy(m);
}

Test(unfold, bad_shapes, .init = test_leak_setup, .fini = test_leak_check)
{
    struct {
        const char *file;
        ori_status st;
        const char *msg;
    } bad[] = {{"tests/data/unfold/nonmanifold.obj", ORI_ERR_TOPOLOGY, "non-manifold"},
               {"tests/data/unfold/degenerate.obj", ORI_ERR_DEGENERATE, "zero area"},
               {"tests/data/unfold/nonplanar.obj", ORI_ERR_DEGENERATE, "not planar"}};
    for (int i = 0; i < 3; ++i) {
        ori_mesh *m = NULL;
        ori_error err;
        cr_assert_eq(ori_unfold_load_mesh(test_repo_path(bad[i].file), &m, &err), bad[i].st, "%s", bad[i].file);
        cr_assert(strstr(err.message, bad[i].msg), "%s", err.message);
        cr_assert_eq(err.element, 0);
        cr_assert_str_eq(err.field, "faces_vertices");
        cr_assert_null(m);
    }
}

// The command writes a FOLD net that orikin reads back: 6 faces, 5 creases and 7 cut edges on
// each side (14 boundary edges, glued in pairs), each face with its input face.
Test(unfold, cli_writes_net, .init = test_leak_setup, .fini = test_leak_check)
{
    char *dir = test_tmpdir();
    char args[1024], path[512];
    snprintf(path, sizeof path, "%s/net.fold", dir);
    snprintf(args, sizeof args, "unfold tests/data/unfold/cube.obj -o '%s' --svg '%s/net.svg' --json", path, dir);
    char *out = NULL;
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    cr_assert(strstr(out, "\"pieces\":1"), "%s", out);
    free(out);
    ori_fold *doc = NULL;
    ori_error err;
    cr_assert_eq(ori_fold_load_file(path, &doc, &err), ORI_OK, "%s", err.message);
    ori_pattern *p = NULL;
    cr_assert_eq(ori_fold_get_pattern(doc, 0, NULL, &p, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_pattern_face_count(p), 6);
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_BOUNDARY), 14);
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_MOUNTAIN), 5);
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge x = ori_pattern_edge(p, e);
        if (x.assignment == ORI_ASSIGN_MOUNTAIN) cr_assert_float_eq(x.fold_angle_rad, -PI_2, 1e-12);
    }
    char *src = ori_fold_get_custom(doc, 0, "faces_orikin:source"), *glue = ori_fold_get_custom(doc, 0, "edges_orikin:glue");
    cr_assert_not_null(src);
    cr_assert_not_null(glue);
    cr_assert(strstr(src, "[0]") && strstr(src, "[5]"), "%s", src);
    ori_buffer_free(src), ori_buffer_free(glue);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    char svg[512];
    snprintf(svg, sizeof svg, "%s/net.svg", dir);
    char *text = test_read_text(svg);
    cr_assert(text && strstr(text, "<svg"));
    free(text);
    test_tmpdir_remove(dir);
}

// qhull's hulls of random points on the sphere unfold in one piece and fold back.
Test(unfold, random_convex_hulls, .init = test_leak_setup, .fini = test_leak_check)
{
    unsigned long long s = 12345;
    for (int k = 0; k < 5; ++k) {
        ori_v3 pts[102];
        for (int i = 0; i < 102; ++i) {
            double u[2];
            for (int j = 0; j < 2; ++j) {
                s ^= s << 13, s ^= s >> 7, s ^= s << 17;
                u[j] = (double)(s >> 11) / 9007199254740992.0;
            }
            double z = 2 * u[0] - 1, r = sqrt(1 - z * z), th = 2 * 3.141592653589793 * u[1];
            pts[i] = ori_v3_make(r * cos(th), r * sin(th), z);
        }
        ori_mesh *m = NULL;
        ori_error err;
        cr_assert_eq(ori_unfold_mesh_convex_hull(pts, 102, &m, &err), ORI_OK, "%s", err.message);
        cr_assert_eq(ori_unfold_mesh_face_count(m), 200); // 2n − 4 triangles
        ori_unfold_def def = ori_default_unfold_def();
        ori_unfold_net *net = NULL;
        cr_assert_eq(ori_unfold_solve(m, &def, &net, &err), ORI_OK);
        ori_unfold_result r = ori_unfold_net_result(net);
        cr_assert_eq(r.pieces, 1);
        cr_assert_eq(r.overlaps, 0);
        cr_assert_leq(r.max_refold_error, 1e-9);
        ori_unfold_net_destroy(net);
        ori_unfold_mesh_destroy(m);
    }
}

// A spiky shape (an icosahedron with a tall pyramid on every face): one try gives no net
// without overlap and the split leaves pieces that do not overlap; more tries find one net.
Test(unfold, split_when_no_net, .init = test_leak_setup, .fini = test_leak_check)
{
    ori_mesh *m = NULL;
    ori_error err;
    cr_assert_eq(ori_unfold_load_mesh(test_repo_path("tests/data/unfold/spiky.obj"), &m, &err), ORI_OK);
    ori_unfold_def def = ori_default_unfold_def();
    def.tries = 1;
    ori_unfold_net *net = NULL;
    cr_assert_eq(ori_unfold_solve(m, &def, &net, &err), ORI_OK);
    ori_unfold_result r = ori_unfold_net_result(net);
    cr_assert_gt(r.pieces, 1);
    cr_assert_eq(r.overlaps, 0);
    cr_assert(!r.refolded);
    const ori_pattern *p = ori_unfold_net_pattern(net);
    int creases = 0;
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) creases += ori_pattern_edge(p, e).assignment != ORI_ASSIGN_BOUNDARY;
    cr_assert_eq(creases, r.faces - r.pieces);
    ori_unfold_net_destroy(net);
    def.tries = 50;
    cr_assert_eq(ori_unfold_solve(m, &def, &net, &err), ORI_OK);
    r = ori_unfold_net_result(net);
    cr_assert_eq(r.pieces, 1);
    cr_assert_leq(r.max_refold_error, 1e-9);
    ori_unfold_net_destroy(net);
    ori_unfold_mesh_destroy(m);
}

// What unfold writes, orikin reads (issue: nets of flat or touching layouts had two vertices at
// one point, "vertex coincides"): over seeds on shapes with flat vertices (a folded Miura), a hole
// and a non-convex cap, every cut net saved as FOLD loads and builds again, every vertex stands
// apart from every other, and the net folds back onto the shape.
Test(unfold, every_cut_net_reads_back, .init = test_leak_setup, .fini = test_leak_check)
{
    const char *shapes[] = {"tests/data/unfold/miura-folded.obj", "tests/data/unfold/box-with-hole.obj",
                            "tests/data/unfold/l-prism.obj", "tests/data/unfold/cube.obj"};
    for (int i = 0; i < 4; ++i) {
        ori_mesh *m = NULL;
        ori_error err;
        cr_assert_eq(ori_unfold_load_mesh(test_repo_path(shapes[i]), &m, &err), ORI_OK, "%s", err.message);
        for (uint64_t seed = 1; seed <= 24; ++seed) {
            ori_unfold_def def = ori_default_unfold_def();
            def.seed = seed;
            ori_unfold_net *net = NULL;
            cr_assert_eq(ori_unfold_solve(m, &def, &net, &err), ORI_OK, "%s", err.message);
            ori_unfold_result r = ori_unfold_net_result(net);
            cr_assert_eq(r.overlaps, 0, "%s seed %d", shapes[i], (int)seed);
            ori_fold *doc = ori_fold_create();
            cr_assert_eq(ori_fold_set_pattern(doc, 0, ori_unfold_net_pattern(net), &err), ORI_OK, "%s", err.message);
            char *text = ori_fold_to_string(doc);
            ori_fold *back = NULL;
            cr_assert_eq(ori_fold_load_string(text, strlen(text), &back, &err), ORI_OK, "%s", err.message);
            ori_pattern *p = NULL;
            ori_status st = ori_fold_get_pattern(back, 0, NULL, &p, &err);
            cr_assert_eq(st, ORI_OK, "%s seed %d: %s (element %d)", shapes[i], (int)seed, err.message, err.element);
            cr_assert_eq(ori_pattern_face_count(p), r.faces);
            if (r.pieces == 1) cr_assert(r.refolded && r.max_refold_error <= 1e-9, "%s seed %d", shapes[i], (int)seed);
            ori_pattern_destroy(p);
            ori_fold_destroy(back);
            ori_buffer_free(text);
            ori_fold_destroy(doc);
            ori_unfold_net_destroy(net);
        }
        ori_unfold_mesh_destroy(m);
    }
}

// An empty mesh is refused (it called memcpy from NULL: UBSan, and fuzz_unfold's one-byte input).
Test(unfold, an_empty_mesh_is_refused, .init = test_leak_setup, .fini = test_leak_check)
{
    ori_mesh *m = NULL;
    ori_error err;
    int start = 0;
    ori_status st = ori_unfold_mesh_create(NULL, 0, &start, NULL, 0, &m, &err);
    cr_assert_neq(st, ORI_OK);
    cr_assert_null(m);
}

static bool cancel_at_once(double fraction, void *user)
{
    (void)fraction;
    ++*(int *)user;
    return false;
}

// --all is bounded: Kirchhoff's count of the spanning trees is reported (the Platonic solids'
// known numbers), --limit stops the enumeration with a lower bound, and so does a progress
// callback that cancels.
Test(unfold, all_nets_are_bounded_and_say_how_far_they_got, .init = test_leak_setup, .fini = test_leak_check)
{
    struct {
        const char *file;
        double trees;
    } solids[] = {{"tests/data/unfold/tetrahedron.obj", 16},     {"tests/data/unfold/cube.obj", 384},
                  {"tests/data/unfold/octahedron.obj", 384},     {"tests/data/unfold/dodecahedron.obj", 5184000},
                  {"tests/data/unfold/icosahedron.obj", 5184000}};
    for (int i = 0; i < 5; ++i) {
        ori_mesh *m = NULL;
        ori_error err;
        cr_assert_eq(ori_unfold_load_mesh(test_repo_path(solids[i].file), &m, &err), ORI_OK, "%s", err.message);
        ori_unfold_def def = ori_default_unfold_def();
        def.all = true;
        def.max_trees = 100;
        ori_unfold_net *net = NULL;
        cr_assert_eq(ori_unfold_solve(m, &def, &net, &err), ORI_OK, "%s", err.message);
        ori_unfold_result r = ori_unfold_net_result(net);
        cr_assert_eq(r.spanning_trees_total, solids[i].trees, "%s: %.17g trees", solids[i].file, r.spanning_trees_total);
        cr_assert_eq(r.all_complete, solids[i].trees <= 100);
        cr_assert_eq(r.spanning_trees, solids[i].trees <= 100 ? (long long)solids[i].trees : 100);
        cr_assert_geq(r.distinct_nets, 1);
        ori_unfold_net_destroy(net);
        if (i == 1) { // the cube: a callback that cancels at its first call stops at once
            int calls = 0;
            def.max_trees = 10000000;
            def.progress = cancel_at_once, def.progress_user = &calls;
            cr_assert_eq(ori_unfold_solve(m, &def, &net, &err), ORI_OK, "%s", err.message);
            r = ori_unfold_net_result(net);
            cr_assert(calls == 0 || !r.all_complete); // (384 trees: called only every 4096)
            cr_assert_eq(r.distinct_nets, 11);
            ori_unfold_net_destroy(net);
        }
        ori_unfold_mesh_destroy(m);
    }
}

// A FOLD folded form that is a flat sheet (Origami Simulator saves sheets as a foldedForm in the
// x-z plane) is a crease pattern: unfold keeps its creases, assignments and fold angles, turned
// into the x-y plane with edge lengths kept, instead of merging its faces ("0 creases"). Tried
// on a 3 × 3 grid of squares with its 12 interior edges creased, placed in random planes.
static void write_sheet(const char *path, const double rot[3][3], bool fold_over)
{
    FILE *f = fopen(path, "w");
    cr_assert(f);
    fprintf(f, "{\"file_spec\":1.1,\"frame_classes\":[\"foldedForm\"],\"vertices_coords\":[");
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            double x = i, y = j, z = 0.0;
            if (fold_over && i == 3) x = 1.0; // the last column folded back flat over the one before
            double p[3] = {x, y, z};
            fprintf(f, "%s[%.17g,%.17g,%.17g]", i + j ? "," : "", rot[0][0] * p[0] + rot[0][1] * p[1] + rot[0][2] * p[2],
                    rot[1][0] * p[0] + rot[1][1] * p[1] + rot[1][2] * p[2], rot[2][0] * p[0] + rot[2][1] * p[1] + rot[2][2] * p[2]);
        }
    fprintf(f, "],\"edges_vertices\":[");
    int ne = 0;
    char asg[64];
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 3; ++i) {
            fprintf(f, "%s[%d,%d]", ne ? "," : "", j * 4 + i, j * 4 + i + 1);
            asg[ne++] = j == 0 || j == 3 ? 'B' : (i % 2 ? 'M' : 'V');
        }
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j) {
            fprintf(f, ",[%d,%d]", j * 4 + i, (j + 1) * 4 + i);
            asg[ne++] = i == 0 || i == 3 ? 'B' : (j == 1 ? 'F' : 'M');
        }
    fprintf(f, "],\"edges_assignment\":[");
    for (int e = 0; e < ne; ++e) fprintf(f, "%s\"%c\"", e ? "," : "", asg[e]);
    fprintf(f, "],\"edges_foldAngle\":[");
    for (int e = 0; e < ne; ++e) fprintf(f, "%s%s", e ? "," : "", asg[e] == 'M' ? "-180" : asg[e] == 'V' ? "180" : "null");
    fprintf(f, "],\"faces_vertices\":[");
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
            int a = j * 4 + i;
            bool over = fold_over && i == 2; // turned over: its corners run the other way round
            if (over) fprintf(f, "%s[%d,%d,%d,%d]", i + j ? "," : "", a, a + 4, a + 5, a + 1);
            else fprintf(f, "%s[%d,%d,%d,%d]", i + j ? "," : "", a, a + 1, a + 5, a + 4);
        }
    fprintf(f, "]}\n");
    fclose(f);
}

Test(unfold, a_planar_folded_form_is_its_own_crease_pattern, .init = test_leak_setup, .fini = test_leak_check)
{
    char *dir = test_tmpdir();
    char in[600], out[600], args[1400];
    snprintf(in, sizeof in, "%s/sheet.fold", dir);
    snprintf(out, sizeof out, "%s/cp.fold", dir);
    srand(21);
    for (int trial = 0; trial < 6; ++trial) {
        // trial 0: the x-z plane (Origami Simulator), then random rotations
        double rot[3][3] = {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}};
        if (trial > 0) {
            double a = 6.283 * rand() / RAND_MAX, b = 3.1415 * rand() / RAND_MAX, c = 6.283 * rand() / RAND_MAX;
            double rz[3][3] = {{cos(a), -sin(a), 0}, {sin(a), cos(a), 0}, {0, 0, 1}};
            double rx[3][3] = {{1, 0, 0}, {0, cos(b), -sin(b)}, {0, sin(b), cos(b)}};
            double rz2[3][3] = {{cos(c), -sin(c), 0}, {sin(c), cos(c), 0}, {0, 0, 1}};
            double t[3][3];
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) {
                    t[i][j] = 0;
                    for (int k = 0; k < 3; ++k) t[i][j] += rx[i][k] * rz2[k][j];
                }
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) {
                    rot[i][j] = 0;
                    for (int k = 0; k < 3; ++k) rot[i][j] += rz[i][k] * t[k][j];
                }
        }
        write_sheet(in, rot, false);
        char *output = NULL;
        snprintf(args, sizeof args, "unfold '%s' -o '%s'", in, out);
        int rc = test_run_cli(args, &output);
        cr_assert_eq(rc, 0, "trial %d: %s", trial, output);
        cr_assert(strstr(output, "planar") && strstr(output, "12 creases (6 mountain, 4 valley, 2 flat"), "trial %d: %s",
                  trial, output);
        free(output);
        ori_pattern *p = test_load_pattern(out, 0);
        cr_assert_not(ori_pattern_is_3d(p));
        cr_assert_eq(ori_pattern_edge_count(p), 24);
        cr_assert_eq(ori_pattern_face_count(p), 9);
        cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_MOUNTAIN), 6);
        cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_VALLEY), 4);
        cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_FLAT), 2);
        for (int e = 0; e < 24; ++e) { // lengths 1 (a rigid motion), angles kept
            ori_edge x = ori_pattern_edge(p, e);
            ori_v3 u = ori_pattern_vertex(p, x.v[0]), w = ori_pattern_vertex(p, x.v[1]);
            cr_assert_float_eq(hypot(w.x - u.x, w.y - u.y), 1.0, 1e-12, "trial %d edge %d", trial, e);
            double want = x.assignment == ORI_ASSIGN_MOUNTAIN ? -ORI_PI : x.assignment == ORI_ASSIGN_VALLEY ? ORI_PI : 0.0;
            cr_assert_float_eq(x.fold_angle_rad, want, 1e-12);
        }
        if (trial == 0) { // the x-z plane turned without rounding: x kept, z the other axis
            for (int v = 0; v < 16; ++v) {
                ori_v3 a = ori_pattern_vertex(p, v);
                cr_assert(a.x == v % 4 && fabs(a.y) == v / 4, "vertex %d at (%g, %g)", v, a.x, a.y);
            }
        }
        ori_pattern_destroy(p);
        if (trial == 0) { // a net asked for: the creases it cannot keep are said
            snprintf(args, sizeof args, "unfold '%s' --cut", in);
            cr_assert_eq(test_run_cli(args, &output), 0, "%s", output);
            cr_assert(strstr(output, "note: the folded form is planar, a crease pattern of 12 creases: --cut merges"),
                      "%s", output);
            free(output);
        }
    }
    // A form folded flat (a column turned over onto the next) is no crease pattern: not claimed.
    double id[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    write_sheet(in, id, true);
    char *output = NULL;
    snprintf(args, sizeof args, "unfold '%s'", in);
    test_run_cli(args, &output);
    cr_assert_not(strstr(output, "planar (a flat sheet"), "%s", output);
    free(output);
    // Origami Simulator's box-pleated pyramid, saved as a flat foldedForm in the x-z plane.
    const char *os = test_shared_path("origamisimulator/Pleating_BoxPleatPyramid.fold");
    if (os) {
        snprintf(args, sizeof args, "unfold '%s' -o '%s'", os, out);
        cr_assert_eq(test_run_cli(args, &output), 0, "%s", output);
        cr_assert(strstr(output, "5100 creases (1632 mountain, 1632 valley, 1836 flat"), "%s", output);
        free(output);
        ori_pattern *p = test_load_pattern(out, 0);
        cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_MOUNTAIN), 1632);
        cr_assert_eq(ori_pattern_face_count(p), 2601);
        ori_pattern_destroy(p);
    }
    test_tmpdir_remove(dir);
}
