// Authoring: sheets, creases applied to faces with the face tree (and its FOLD round trip),
// the crease collection and composites, edit operations, and the thesis' open corner.
#include <orikin/axioms.h>
#include <orikin/collection.h>
#include <stdio.h>
#include <stdlib.h>

#include "pattern/pattern_internal.h"
#include "support.h"

TestSuite(authoring, .init = test_leak_setup, .fini = test_leak_check);

static ori_pattern *square(double s)
{
    ori_v2 c[4] = {{0, 0}, {s, 0}, {s, s}, {0, s}};
    ori_pattern *p = NULL;
    ori_error err;
    cr_assert_eq(ori_pattern_create_sheet(c, 4, &p, &err), ORI_OK);
    return p;
}

static void apply_builtin(ori_pattern *p, const char *name, const char *face, ori_assignment a)
{
    ori_composite *c = NULL;
    ori_error err;
    char msg[300];
    cr_assert_eq(ori_composite_builtin(name, &c, &err), ORI_OK);
    int f = ori_pattern_find_face_by_name(p, face);
    cr_assert_neq(f, ORI_NULL_INDEX, "face %s", face);
    ori_status st = ori_pattern_apply_composite(p, c, f, &a, NULL, &err);
    cr_assert_eq(st, ORI_OK, "%s on %s: %s", name, face, ori_error_format(&err, msg, sizeof msg));
    ori_composite_destroy(c);
}

static int edge_between(const ori_pattern *p, double ax, double ay, double bx, double by)
{
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        ori_v3 u = ori_pattern_vertex(p, ed.v[0]), w = ori_pattern_vertex(p, ed.v[1]);
        if ((u.x == ax && u.y == ay && w.x == bx && w.y == by) || (u.x == bx && u.y == by && w.x == ax && w.y == ay))
            return e;
    }
    return ORI_NULL_INDEX;
}

static int vertex_at(const ori_pattern *p, double x, double y)
{
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        ori_v3 q = ori_pattern_vertex(p, v);
        if (q.x == x && q.y == y) return v;
    }
    return ORI_NULL_INDEX;
}

static double face_area(const ori_pattern *p, int f) { return 0.5 * ori__pattern_face_area2(p, f); }

// --- sheet ---------------------------------------------------------------------------------

Test(authoring, sheet_square_and_polygon)
{
    ori_pattern *p = square(2);
    cr_assert_eq(ori_pattern_vertex_count(p), 4);
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_BOUNDARY), 4);
    cr_assert_eq(ori_pattern_face_count(p), 1);
    cr_assert_str_eq(ori_pattern_face_name(p, 0), "Obj1");
    cr_assert_eq(ori_pattern_tree_node_count(p), 1);
    cr_assert(ori_pattern_is_built(p));
    ori_pattern_destroy(p);
    // A clockwise L-shape is stored counter-clockwise, first corner first.
    ori_v2 l[6] = {{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}};
    ori_error err;
    cr_assert_eq(ori_pattern_create_sheet(l, 6, &p, &err), ORI_OK);
    cr_assert_float_eq(face_area(p, 0), 3.0, 1e-15);
    cr_assert_float_eq(ori_pattern_vertex(p, 0).x, 0.0, 0.0);
    cr_assert_float_eq(ori_pattern_vertex(p, 1).x, 2.0, 0.0);
    ori_pattern_destroy(p);
}

Test(authoring, sheet_rejects_degenerate_polygons)
{
    ori_pattern *p = NULL;
    ori_error err;
    ori_v2 bow[4] = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
    cr_assert_eq(ori_pattern_create_sheet(bow, 4, &p, &err), ORI_ERR_CROSSING);
    cr_assert_null(p);
    cr_assert(strstr(err.message, "not simple: side 0") != NULL, "%s", err.message);
    ori_v2 line[3] = {{0, 0}, {1, 0}, {3, 0}};
    cr_assert_neq(ori_pattern_create_sheet(line, 3, &p, &err), ORI_OK);
    ori_v2 dup[4] = {{0, 0}, {1, 0}, {1, 0}, {0, 1}};
    cr_assert_eq(ori_pattern_create_sheet(dup, 4, &p, &err), ORI_ERR_DEGENERATE);
    cr_assert(strstr(err.message, "corner 2 coincides with corner 1") != NULL, "%s", err.message);
    cr_assert_eq(ori_pattern_create_sheet(dup, 2, &p, &err), ORI_ERR_DEGENERATE);
    ori_v2 inf[3] = {{0, 0}, {INFINITY, 0}, {0, 1}};
    cr_assert_eq(ori_pattern_create_sheet(inf, 3, &p, &err), ORI_ERR_RANGE);
}

// --- creases and names ------------------------------------------------------------------------

Test(authoring, crease_splits_face_left_child_first)
{
    ori_pattern *p = square(2);
    ori_crease c = {{0, 1}, {2, 1}, true, ORI_ASSIGN_VALLEY, 0.0};
    ori_apply_result r;
    ori_error err;
    cr_assert_eq(ori_pattern_apply_crease(p, &c, 0, &r, &err), ORI_OK);
    cr_assert_eq(r.segments, 1);
    cr_assert_eq(r.faces_split, 1);
    cr_assert_eq(r.first_edge, 4);
    cr_assert(ori_pattern_is_built(p));
    int up = ori_pattern_find_face_by_name(p, "Obj11"), down = ori_pattern_find_face_by_name(p, "Obj12");
    cr_assert_eq(up, 0);
    cr_assert_eq(down, 1);
    // Obj11 is left of (0,1)→(2,1): above.
    int fv[8], n = ori_pattern_face_vertices(p, up, fv, 8);
    for (int i = 0; i < n; ++i) cr_assert_geq(ori_pattern_vertex(p, fv[i]).y, 1.0);
    // A reversed crease direction names the other way round.
    ori_crease c2 = {{1, 2}, {1, 0}, true, ORI_ASSIGN_VALLEY, 0.0}; // downwards: left is +x
    cr_assert_eq(ori_pattern_apply_crease(p, &c2, up, NULL, &err), ORI_OK);
    int right = ori_pattern_find_face_by_name(p, "Obj111");
    n = ori_pattern_face_vertices(p, right, fv, 8);
    for (int i = 0; i < n; ++i) cr_assert_geq(ori_pattern_vertex(p, fv[i]).x, 1.0);
    // Only Obj11 was split: Obj12 is whole, its top side now has the T-junction vertex (1,1).
    cr_assert_eq(ori_pattern_face_count(p), 3);
    cr_assert_eq(ori_pattern_face_size(p, ori_pattern_find_face_by_name(p, "Obj12")), 5);
    ori_pattern_destroy(p);
}

Test(authoring, crease_on_all_faces_and_errors)
{
    ori_pattern *p = square(2);
    apply_builtin(p, "cross", "Obj1", ORI_ASSIGN_MOUNTAIN);
    cr_assert_eq(ori_pattern_face_count(p), 4);
    const char *names[4] = {"Obj111", "Obj112", "Obj121", "Obj122"};
    for (int i = 0; i < 4; ++i) cr_assert_neq(ori_pattern_find_face_by_name(p, names[i]), ORI_NULL_INDEX);
    // A diagonal across the whole sheet splits the two faces it crosses.
    ori_crease d = {{0, 0}, {1, 1}, true, ORI_ASSIGN_VALLEY, 0.0};
    ori_apply_result r;
    ori_error err;
    cr_assert_eq(ori_pattern_apply_crease(p, &d, ORI_NULL_INDEX, &r, &err), ORI_OK);
    cr_assert_eq(r.segments, 1);
    cr_assert_eq(r.faces_split, 2);
    cr_assert_eq(ori_pattern_face_count(p), 6);
    // Misses, bad face, bad assignment, degenerate: the pattern is unchanged.
    int e = ori_pattern_edge_count(p);
    ori_crease miss = {{0, 3}, {1, 3}, true, ORI_ASSIGN_VALLEY, 0.0};
    cr_assert_eq(ori_pattern_apply_crease(p, &miss, ORI_NULL_INDEX, NULL, &err), ORI_ERR_NOT_FOUND);
    cr_assert_str_eq(err.message, "the crease does not cross the sheet");
    ori_crease along = {{0, 0}, {2, 0}, true, ORI_ASSIGN_VALLEY, 0.0}; // the boundary
    cr_assert_eq(ori_pattern_apply_crease(p, &along, 0, NULL, &err), ORI_ERR_NOT_FOUND);
    cr_assert(strstr(err.message, "does not cross face Obj") != NULL);
    cr_assert_eq(ori_pattern_apply_crease(p, &d, 99, NULL, &err), ORI_ERR_RANGE);
    ori_crease bnd = {{0, 0.5}, {1, 0.5}, true, ORI_ASSIGN_BOUNDARY, 0.0};
    cr_assert_eq(ori_pattern_apply_crease(p, &bnd, 0, NULL, &err), ORI_ERR_ARGUMENT);
    ori_crease pt = {{0.5, 0.5}, {0.5, 0.5}, true, ORI_ASSIGN_VALLEY, 0.0};
    cr_assert_eq(ori_pattern_apply_crease(p, &pt, 0, NULL, &err), ORI_ERR_DEGENERATE);
    cr_assert_eq(ori_pattern_edge_count(p), e);
    ori_pattern_destroy(p);
}

Test(authoring, crease_segment_clipped_and_nonconvex_face)
{
    // U-shaped sheet: a horizontal line crosses it twice; applied to the face it gives two
    // pieces, splitting it once per crossing (one tree level each).
    ori_v2 u[8] = {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
    ori_pattern *p = NULL;
    ori_error err;
    cr_assert_eq(ori_pattern_create_sheet(u, 8, &p, &err), ORI_OK);
    double t[8];
    ori_crease c = {{-1, 2}, {4, 2}, true, ORI_ASSIGN_VALLEY, 0.0};
    cr_assert_eq(ori_pattern_clip_crease(p, &c, 0, t, 4), 2);
    cr_assert_float_eq(t[0], 0.2, 1e-15);
    cr_assert_float_eq(t[1], 0.4, 1e-15);
    ori_apply_result r;
    cr_assert_eq(ori_pattern_apply_crease(p, &c, 0, &r, &err), ORI_OK);
    cr_assert_eq(r.segments, 2);
    cr_assert_eq(r.faces_split, 2);
    cr_assert_eq(ori_pattern_face_count(p), 3);
    double total = 0;
    for (int f = 0; f < 3; ++f) total += face_area(p, f);
    cr_assert_float_eq(total, 7.0, 1e-14);
    // A finite segment: only its part inside the sheet.
    ori_crease s = {{0.5, -1}, {0.5, 0.5}, false, ORI_ASSIGN_MOUNTAIN, 0.0};
    cr_assert_eq(ori_pattern_clip_crease(p, &s, ORI_NULL_INDEX, t, 4), 1);
    cr_assert_float_eq(t[0], 2.0 / 3.0, 1e-15);
    cr_assert_float_eq(t[1], 1.0, 0.0);
    ori_pattern_destroy(p);
}

Test(authoring, face_tree_survives_fold_round_trip)
{
    ori_pattern *p = square(2);
    apply_builtin(p, "middle-h", "Obj1", ORI_ASSIGN_VALLEY);
    apply_builtin(p, "diagonal-right", "Obj12", ORI_ASSIGN_MOUNTAIN);
    ori_fold *doc = ori_fold_create();
    ori_error err;
    cr_assert_eq(ori_fold_set_pattern(doc, 0, p, &err), ORI_OK);
    char *text = ori_fold_to_string(doc);
    ori_fold_destroy(doc);
    cr_assert_eq(ori_fold_load_string(text, strlen(text), &doc, &err), ORI_OK);
    ori_buffer_free(text);
    ori_pattern *q = NULL;
    cr_assert_eq(ori_fold_get_pattern(doc, 0, NULL, &q, &err), ORI_OK);
    ori_fold_destroy(doc);
    cr_assert_eq(ori_pattern_face_count(q), ori_pattern_face_count(p));
    for (int f = 0; f < ori_pattern_face_count(p); ++f)
        cr_assert_str_eq(ori_pattern_face_name(q, f), ori_pattern_face_name(p, f));
    cr_assert_eq(ori_pattern_tree_node_count(q), ori_pattern_tree_node_count(p));
    for (int i = 0; i < ori_pattern_tree_node_count(p); ++i) {
        cr_assert_str_eq(ori_pattern_tree_node(q, i).name, ori_pattern_tree_node(p, i).name);
        cr_assert_eq(ori_pattern_tree_node(q, i).parent, ori_pattern_tree_node(p, i).parent);
    }
    // diagonal-right on the lower half (0,0)-(2,1): from (2,0) to (0,1); left of it is the
    // lower-left triangle.
    int f = ori_pattern_find_face_by_name(q, "Obj121");
    cr_assert_eq(ori_pattern_face_size(q, f), 3);
    cr_assert_float_eq(face_area(q, f), 1.0, 1e-15);
    cr_assert_neq(vertex_at(q, 0, 0), ORI_NULL_INDEX);
    int leaf = ori_pattern_face_node(q, f);
    cr_assert_eq(ori_pattern_node_child_count(q, leaf), 0);
    cr_assert_eq(ori_pattern_node_child_count(q, 0), 2);
    ori_pattern_destroy(q);
    ori_pattern_destroy(p);
}

// --- collection ------------------------------------------------------------------------------

Test(authoring, builtins_listed_and_unknown_rejected)
{
    cr_assert_geq(ori_collection_builtin_count(), 4);
    const char *want[4] = {"diagonal-left", "diagonal-right", "middle-h", "middle-v"};
    for (int i = 0; i < 4; ++i) cr_assert_str_eq(ori_collection_builtin_name(i), want[i]);
    ori_composite *c = NULL;
    ori_error err;
    cr_assert_eq(ori_composite_builtin("diagonal-up", &c, &err), ORI_ERR_NOT_FOUND);
    cr_assert(strstr(err.message, "middle-h") != NULL, "lists the built-ins");
    cr_assert_eq(ori_composite_builtin("diagonal-left", &c, &err), ORI_OK);
    ori_composite_crease k = ori_composite_crease_at(c, 0);
    cr_assert(k.infinite);
    cr_assert_float_eq(k.a.x, 0.0, 0.0);
    cr_assert_float_eq(k.b.y, 1.0, 0.0);
    ori_composite_destroy(c);
}

Test(authoring, composite_json_applies_in_face_coordinates)
{
    const char *json = "{\n"
                       "  \"orikin_composite\": 1,\n"
                       "  \"name\": \"star\",\n"
                       "  \"creases\": [\n"
                       "    {\"pattern\": \"middle-v\", \"assignment\": \"M\"},\n"
                       "    {\"segment\": [0, 0, 0.5, 0.5], \"assignment\": \"V\"},\n"
                       "    {\"line\": [0, 1, 1, 0]}\n"
                       "  ]\n"
                       "}\n";
    ori_composite *c = NULL;
    ori_error err;
    char msg[300];
    cr_assert_eq(ori_composite_load_string(json, strlen(json), &c, &err), ORI_OK, "%s",
                 ori_error_format(&err, msg, sizeof msg));
    cr_assert_str_eq(ori_composite_name(c), "star");
    cr_assert_eq(ori_composite_crease_count(c), 3);
    // On the upper half of a 4 × 2 sheet (box [0,4] × [1,2]).
    ori_v2 r[4] = {{0, 0}, {4, 0}, {4, 2}, {0, 2}};
    ori_pattern *p = NULL;
    cr_assert_eq(ori_pattern_create_sheet(r, 4, &p, &err), ORI_OK);
    apply_builtin(p, "middle-h", "Obj1", ORI_ASSIGN_VALLEY);
    int f = ori_pattern_find_face_by_name(p, "Obj11");
    ori_apply_result res;
    cr_assert_eq(ori_pattern_apply_composite(p, c, f, NULL, &res, &err), ORI_OK, "%s",
                 ori_error_format(&err, msg, sizeof msg));
    // middle-v of the upper half, x = 2 from y = 1 to 2, split at (2, 1.5) where the segment
    // (0,1)-(2,1.5) ends and the anti-diagonal line (0,2)-(4,1) crosses it.
    int mv = ori_pattern_find_edge_at(p, ori_v2_make(2, 1.2));
    cr_assert_neq(mv, ORI_NULL_INDEX);
    cr_assert_eq(ori_pattern_edge(p, mv).assignment, ORI_ASSIGN_MOUNTAIN);
    cr_assert_neq(edge_between(p, 2, 1, 2, 1.5), ORI_NULL_INDEX);
    cr_assert_neq(edge_between(p, 2, 1.5, 2, 2), ORI_NULL_INDEX);
    int seg = ori_pattern_find_edge_at(p, ori_v2_make(0.4, 1.1));
    cr_assert_neq(seg, ORI_NULL_INDEX);
    cr_assert_eq(ori_pattern_edge(p, seg).assignment, ORI_ASSIGN_VALLEY);
    int anti = ori_pattern_find_edge_at(p, ori_v2_make(3, 1.25));
    cr_assert_eq(ori_pattern_edge(p, anti).assignment, ORI_ASSIGN_UNASSIGNED);
    // The lower half was not touched.
    cr_assert_eq(ori_pattern_face_size(p, ori_pattern_find_face_by_name(p, "Obj12")), 5); // T-junction at (2,1)
    double total = 0;
    for (int k = 0; k < ori_pattern_face_count(p); ++k) total += face_area(p, k);
    cr_assert_float_eq(total, 8.0, 1e-14);
    ori_composite_destroy(c);
    ori_pattern_destroy(p);
}

static void expect_parse_error(const char *json, int line, int column, const char *text)
{
    ori_composite *c = NULL;
    ori_error err;
    char msg[300];
    cr_assert_neq(ori_composite_load_string(json, strlen(json), &c, &err), ORI_OK, "accepted: %s", json);
    cr_assert_null(c);
    cr_assert_eq(err.line, line, "%s (line %d)", ori_error_format(&err, msg, sizeof msg), err.line);
    cr_assert_eq(err.column, column, "%s (column %d)", ori_error_format(&err, msg, sizeof msg), err.column);
    cr_assert(strstr(err.message, text) != NULL, "message: %s", err.message);
}

Test(authoring, composite_json_errors_have_line_and_column)
{
    expect_parse_error("{\"creases\": [}", 1, 14, "");
    expect_parse_error("[1, 2]", 1, 1, "a composite is a JSON object");
    expect_parse_error("{\n  \"creases\": []\n}", 2, 14, "creases: expected a non-empty array");
    expect_parse_error("{\n  \"name\": \"x\"\n}", 1, 1, "expected a non-empty array");
    expect_parse_error("{\"creases\": [{\"line\": [0, 0, 1]}]}", 1, 23, "creases[0].line: expected [x1, y1, x2, y2]");
    expect_parse_error("{\"creases\": [\n  {\"line\": [0, 0, 1, 0]},\n  {\"segment\": [0, \"a\", 1, 0]}\n]}", 3, 19,
                       "creases[1].segment[1]: expected a number");
    expect_parse_error("{\"creases\": [{\"line\": [0, 0, 1, 1], \"assignment\": \"B\"}]}", 1, 51,
                       "creases[0].assignment: expected \"M\", \"V\", \"F\" or \"U\"");
    expect_parse_error("{\"creases\": [{\"line\": [0, 0, 1, 1], \"segment\": [0, 0, 1, 1]}]}", 1, 48, "has one of");
    expect_parse_error("{\"creases\": [{\"lines\": [0, 0, 1, 1]}]}", 1, 24, "unknown key");
    expect_parse_error("{\"creases\": [{\"pattern\": \"zigzag\"}]}", 1, 26, "expected the name of a built-in");
    expect_parse_error("{\"creases\": [{\"line\": [0.5, 0.5, 0.5, 0.5]}]}", 1, 23, "the two points coincide");
    expect_parse_error("{\"orikin_composite\": 2, \"creases\": [{\"line\": [0, 0, 1, 1]}]}", 1, 22, "unsupported version");
    expect_parse_error("{\"creases\": [{\"line\": [0, 0, 1, 1]}], \"colour\": 3}", 1, 49, "unknown key");
    expect_parse_error("{\"creases\": [3]}", 1, 14, "creases[0]: expected an object");
}

Test(authoring, composite_crease_missing_face_names_its_index)
{
    const char *json = "{\"creases\": [{\"line\": [0, 0.5, 1, 0.5]}, {\"segment\": [2, 2, 3, 3]}]}";
    ori_composite *c = NULL;
    ori_error err;
    cr_assert_eq(ori_composite_load_string(json, strlen(json), &c, &err), ORI_OK);
    ori_pattern *p = square(1);
    cr_assert_eq(ori_pattern_apply_composite(p, c, 0, NULL, NULL, &err), ORI_ERR_NOT_FOUND);
    cr_assert_str_eq(err.field, "creases");
    cr_assert_eq(err.element, 1);
    cr_assert_eq(ori_pattern_face_count(p), 1, "unchanged");
    ori_composite_destroy(c);
    ori_pattern_destroy(p);
}

// --- edits ---------------------------------------------------------------------------------

Test(authoring, flip_twice_is_identity_and_assign_fixes_angle_sign)
{
    ori_pattern *p = square(2);
    ori_crease c = {{0, 1}, {2, 1}, true, ORI_ASSIGN_MOUNTAIN, -0.75};
    ori_error err;
    cr_assert_eq(ori_pattern_apply_crease(p, &c, 0, NULL, &err), ORI_OK);
    int e = ori_pattern_find_edge_at(p, ori_v2_make(1, 1));
    ori_edge before = ori_pattern_edge(p, e);
    cr_assert_eq(ori_pattern_flip_crease(p, e, &err), ORI_OK);
    cr_assert_eq(ori_pattern_edge(p, e).assignment, ORI_ASSIGN_VALLEY);
    cr_assert_float_eq(ori_pattern_edge(p, e).fold_angle_rad, 0.75, 0.0);
    cr_assert_eq(ori_pattern_flip_crease(p, e, &err), ORI_OK);
    ori_edge after = ori_pattern_edge(p, e);
    cr_assert_eq(after.assignment, before.assignment);
    cr_assert_eq(after.fold_angle_rad, before.fold_angle_rad);
    cr_assert_eq(memcmp(after.v, before.v, sizeof after.v), 0);
    cr_assert_eq(ori_pattern_assign_crease(p, e, ORI_ASSIGN_VALLEY, &err), ORI_OK);
    cr_assert_float_eq(ori_pattern_edge(p, e).fold_angle_rad, 0.75, 0.0);
    cr_assert_eq(ori_pattern_assign_crease(p, e, ORI_ASSIGN_FLAT, &err), ORI_OK);
    cr_assert_float_eq(ori_pattern_edge(p, e).fold_angle_rad, 0.0, 0.0);
    cr_assert_eq(ori_pattern_flip_crease(p, e, &err), ORI_ERR_ARGUMENT, "F does not flip");
    cr_assert_eq(ori_pattern_flip_crease(p, 0, &err), ORI_ERR_ARGUMENT);
    cr_assert(strstr(err.message, "a boundary edge (B) cannot be flipped") != NULL, "%s", err.message);
    cr_assert_eq(ori_pattern_assign_crease(p, 0, ORI_ASSIGN_MOUNTAIN, &err), ORI_ERR_ARGUMENT);
    cr_assert_eq(ori_pattern_assign_crease(p, 99, ORI_ASSIGN_MOUNTAIN, &err), ORI_ERR_RANGE);
    cr_assert_eq(err.element, 99);
    cr_assert_eq(ori_pattern_assign_crease(p, e, ORI_ASSIGN_CUT, &err), ORI_ERR_ARGUMENT);
    ori_pattern_destroy(p);
}

Test(authoring, remove_restores_parent_name_and_rejoins_split_edges)
{
    ori_pattern *p = square(2);
    apply_builtin(p, "middle-h", "Obj1", ORI_ASSIGN_VALLEY);
    int v0 = ori_pattern_vertex_count(p), e0 = ori_pattern_edge_count(p), n0 = ori_pattern_tree_node_count(p);
    apply_builtin(p, "diagonal-left", "Obj12", ORI_ASSIGN_MOUNTAIN); // (0,0)-(2,1)
    int diag = ori_pattern_find_edge_at(p, ori_v2_make(1, 0.5));
    cr_assert_neq(diag, ORI_NULL_INDEX);
    ori_remove_result r;
    ori_error err;
    char msg[300];
    cr_assert_eq(ori_pattern_remove_crease(p, diag, &r, &err), ORI_OK, "%s", ori_error_format(&err, msg, sizeof msg));
    cr_assert(r.name_restored);
    cr_assert_neq(ori_pattern_find_face_by_name(p, "Obj12"), ORI_NULL_INDEX);
    cr_assert_eq(ori_pattern_find_tree_node(p, "Obj121"), ORI_NULL_INDEX);
    cr_assert_eq(ori_pattern_tree_node_count(p), n0);
    cr_assert_eq(ori_pattern_vertex_count(p), v0);
    cr_assert_eq(ori_pattern_edge_count(p), e0);
    cr_assert_eq(ori_pattern_face_count(p), 2);
    cr_assert(ori_pattern_is_built(p));
    ori_pattern_destroy(p);
}

Test(authoring, remove_crossing_crease_rejoins_and_maps_indices)
{
    ori_pattern *p = square(2);
    ori_crease h = {{0, 1}, {2, 1}, true, ORI_ASSIGN_VALLEY, 0.0};
    ori_crease v = {{1, 0}, {1, 2}, true, ORI_ASSIGN_MOUNTAIN, 0.0};
    ori_error err;
    cr_assert_eq(ori_pattern_apply_crease(p, &h, ORI_NULL_INDEX, NULL, &err), ORI_OK);
    int V0 = ori_pattern_vertex_count(p), E0 = ori_pattern_edge_count(p);
    cr_assert_eq(ori_pattern_apply_crease(p, &v, ORI_NULL_INDEX, NULL, &err), ORI_OK);
    cr_assert_eq(ori_pattern_face_count(p), 4);
    int up = ori_pattern_find_edge_at(p, ori_v2_make(1, 1.5));
    ori_remove_result r;
    cr_assert_eq(ori_pattern_remove_crease(p, up, &r, &err), ORI_OK);
    // The upper half of the vertical crease goes; its end (1,2) dissolves into the top side.
    cr_assert_eq(ori_pattern_face_count(p), 3);
    cr_assert_eq(r.removed_vertex_count, 1);
    int down = ori_pattern_find_edge_at(p, ori_v2_make(1, 0.5));
    cr_assert_eq(ori_pattern_remove_crease(p, down, &r, &err), ORI_OK);
    // Now (1,1) has two collinear valley halves: rejoined, and (1,0) rejoined into the bottom.
    cr_assert_eq(r.removed_vertex_count, 2);
    cr_assert_eq(ori_pattern_vertex_count(p), V0);
    cr_assert_eq(ori_pattern_edge_count(p), E0);
    cr_assert_eq(ori_pattern_face_count(p), 2);
    cr_assert_neq(edge_between(p, 0, 1, 2, 1), ORI_NULL_INDEX, "the horizontal crease is one edge again");
    cr_assert_neq(ori_pattern_find_face_by_name(p, "Obj11"), ORI_NULL_INDEX);
    // Index mapping: a removed crease maps to none, later indices shift.
    ori_remove_result m;
    memset(&m, 0, sizeof m);
    m.removed_edge_count = 2;
    m.removed_edges[0] = 3;
    m.merged_into[0] = ORI_NULL_INDEX;
    m.removed_edges[1] = 7;
    m.merged_into[1] = 5;
    cr_assert_eq(ori_remove_result_map_edge(&m, 2), 2);
    cr_assert_eq(ori_remove_result_map_edge(&m, 3), ORI_NULL_INDEX);
    cr_assert_eq(ori_remove_result_map_edge(&m, 7), 4);
    cr_assert_eq(ori_remove_result_map_edge(&m, 9), 7);
    // Boundary edges cannot be removed.
    cr_assert_eq(ori_pattern_remove_crease(p, 0, &r, &err), ORI_ERR_ARGUMENT);
    ori_pattern_destroy(p);
}

Test(authoring, move_crease)
{
    ori_pattern *p = square(2);
    apply_builtin(p, "middle-h", "Obj1", ORI_ASSIGN_VALLEY);
    int e = ori_pattern_find_edge_at(p, ori_v2_make(1, 1));
    ori_remove_result rr;
    ori_apply_result ar;
    ori_error err;
    char msg[300];
    cr_assert_eq(ori_pattern_move_crease(p, e, ori_v2_make(-1, -1), ori_v2_make(3, 3), &rr, &ar, &err), ORI_OK, "%s",
                 ori_error_format(&err, msg, sizeof msg));
    cr_assert(rr.name_restored);
    cr_assert_eq(ar.faces_split, 1);
    cr_assert_eq(ori_pattern_vertex_count(p), 4);
    cr_assert_eq(ori_pattern_edge_count(p), 5);
    int d = edge_between(p, 0, 0, 2, 2);
    cr_assert_neq(d, ORI_NULL_INDEX);
    cr_assert_eq(ori_pattern_edge(p, d).assignment, ORI_ASSIGN_VALLEY);
    cr_assert_neq(ori_pattern_find_face_by_name(p, "Obj11"), ORI_NULL_INDEX, "re-split, renamed");
    // Outside the sheet: refused, unchanged.
    cr_assert_eq(ori_pattern_move_crease(p, d, ori_v2_make(5, 5), ori_v2_make(6, 7), NULL, NULL, &err), ORI_ERR_NOT_FOUND);
    cr_assert_eq(ori_pattern_edge_count(p), 5);
    ori_pattern_destroy(p);
}

// --- the open corner -------------------------------------------------------------------------

static void check_open_corner(const ori_pattern *p)
{
    int c = vertex_at(p, 1, 1);
    cr_assert_neq(c, ORI_NULL_INDEX);
    cr_assert(ori_pattern_vertex_is_interior(p, c));
    int edges[8];
    double sectors[8];
    int n = ori_pattern_vertex_sectors(p, c, edges, sectors, 8);
    cr_assert_eq(n, 5);
    // Counter-clockwise from the crease to (2,1): right, up, left, diagonal, down.
    int start = 0;
    for (int i = 0; i < n; ++i) {
        ori_edge ed = ori_pattern_edge(p, edges[i]);
        int o = ed.v[0] == c ? ed.v[1] : ed.v[0];
        if (ori_pattern_vertex(p, o).x == 2) start = i;
    }
    const double want[5] = {ORI_PI / 2, ORI_PI / 2, ORI_PI / 4, ORI_PI / 4, ORI_PI / 2};
    const double other[5][2] = {{2, 1}, {1, 2}, {0, 1}, {0, 0}, {1, 0}};
    const ori_assignment asg[5] = {ORI_ASSIGN_VALLEY, ORI_ASSIGN_VALLEY, ORI_ASSIGN_MOUNTAIN, ORI_ASSIGN_VALLEY,
                                   ORI_ASSIGN_VALLEY};
    for (int k = 0; k < 5; ++k) {
        int i = (start + k) % n;
        cr_assert_float_eq(sectors[i], want[k], 1e-12, "sector %d: %.17g", k, sectors[i]);
        ori_edge ed = ori_pattern_edge(p, edges[i]);
        int o = ed.v[0] == c ? ed.v[1] : ed.v[0];
        cr_assert_float_eq(ori_pattern_vertex(p, o).x, other[k][0], 0.0);
        cr_assert_float_eq(ori_pattern_vertex(p, o).y, other[k][1], 0.0);
        cr_assert_eq(ed.assignment, asg[k], "crease to (%g, %g)", other[k][0], other[k][1]);
    }
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_MOUNTAIN), 1);
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_VALLEY), 4);
    cr_assert_eq(ori_pattern_count_assignment(p, ORI_ASSIGN_BOUNDARY), 8);
    cr_assert_eq(ori_pattern_face_count(p), 5);
}

Test(authoring, open_corner_as_in_the_thesis)
{
    ori_pattern *p = square(2);
    apply_builtin(p, "middle-h", "Obj1", ORI_ASSIGN_VALLEY);
    apply_builtin(p, "middle-v", "Obj11", ORI_ASSIGN_VALLEY);
    apply_builtin(p, "middle-v", "Obj12", ORI_ASSIGN_VALLEY);
    apply_builtin(p, "diagonal-left", "Obj121", ORI_ASSIGN_VALLEY);
    ori_error err;
    int left = ori_pattern_find_edge_at(p, ori_v2_make(0.5, 1));
    cr_assert_eq(ori_pattern_assign_crease(p, left, ORI_ASSIGN_MOUNTAIN, &err), ORI_OK);
    check_open_corner(p);
    const char *leaves[5] = {"Obj111", "Obj112", "Obj1211", "Obj1212", "Obj122"};
    for (int i = 0; i < 5; ++i) cr_assert_neq(ori_pattern_find_face_by_name(p, leaves[i]), ORI_NULL_INDEX);
    ori_pattern_destroy(p);
}

Test(authoring, open_corner_example_file)
{
    ori_pattern *p = test_load_pattern(test_repo_path("examples/patterns/open-corner.fold"), 0);
    check_open_corner(p);
    ori_pattern_destroy(p);
}

// The face tree's names are indexed (a lookup was linear, and authoring quadratic in its output):
// finding a node gives the first of its name, across growth of the index and after a clear.
Test(authoring, tree_nodes_are_found_by_name_through_growth_and_clear)
{
    ori_pattern_def pd = ori_default_pattern_def();
    ori_pattern *p = ori_pattern_create(&pd);
    char name[32];
    for (int i = 0; i < 1000; ++i) {
        snprintf(name, sizeof name, "Obj%d", i);
        cr_assert_eq(ori_pattern_add_tree_node(p, name, i ? i - 1 : ORI_NULL_INDEX), i);
    }
    cr_assert_eq(ori_pattern_add_tree_node(p, "Obj7", ORI_NULL_INDEX), 1000); // a second "Obj7"
    for (int i = 0; i < 1000; ++i) {
        snprintf(name, sizeof name, "Obj%d", i);
        cr_assert_eq(ori_pattern_find_tree_node(p, name), i, "%s", name);
    }
    cr_assert_eq(ori_pattern_find_tree_node(p, "Obj1000"), ORI_NULL_INDEX);
    ori_pattern *q = ori_pattern_clone(p);
    cr_assert_eq(ori_pattern_find_tree_node(q, "Obj999"), 999);
    ori_pattern_clear_tree(p);
    cr_assert_eq(ori_pattern_find_tree_node(p, "Obj7"), ORI_NULL_INDEX);
    cr_assert_eq(ori_pattern_add_tree_node(p, "Obj7", ORI_NULL_INDEX), 0);
    cr_assert_eq(ori_pattern_find_tree_node(p, "Obj7"), 0);
    cr_assert_eq(ori_pattern_find_tree_node(q, "Obj7"), 7);
    ori_pattern_destroy(q);
    ori_pattern_destroy(p);
}
