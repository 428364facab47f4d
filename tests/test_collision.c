// Self-collision (SPEC capability 11): exact contact of posed faces (crossing, touching,
// stacked layers, faces sharing vertices), the least clearance and its witness against closed
// forms and a brute-force all-pairs check, the first contact along a fold and a sequence pinned
// to closed forms to 1e-6°, the Miura-ori folded flat, the shared folded forms, the cloud of
// proximity as a cross-check, bad input.
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <orikin/collision.h>
#include <orikin/generate.h>

#include "collision/collision_internal.h"
#include "support.h"

TestSuite(collision, .init = test_leak_setup, .fini = test_leak_check);

#define DEG (ORI_PI / 180.0)

// --- every motion check twice: the incremental checker and the reference one ---------------------

// The motion checks of this suite go through these: the incremental checker (the default) and
// then today's checker (col_collider_set_reference: every step from nothing) on the same
// motion; the statuses, the events and the contacts the collider holds after must be the same,
// to the last bit (the first contact to far better than 1e-9 of the drive).
static void assert_same_contact(const ori_contact *a, const ori_contact *b, const char *what)
{
    cr_assert_eq(a->face_a, b->face_a, "%s: face_a %d, reference %d", what, a->face_a, b->face_a);
    cr_assert_eq(a->face_b, b->face_b, "%s: face_b %d, reference %d", what, a->face_b, b->face_b);
    cr_assert_eq(a->kind, b->kind, "%s: kind", what);
    cr_assert_eq(a->adjacent, b->adjacent, "%s: adjacent", what);
    cr_assert_eq(a->stacked, b->stacked, "%s: stacked", what);
    cr_assert_eq(a->collides, b->collides, "%s: collides", what);
    cr_assert(a->distance == b->distance, "%s: distance %.17g, reference %.17g", what, a->distance, b->distance);
    cr_assert(a->point.x == b->point.x && a->point.y == b->point.y && a->point.z == b->point.z,
              "%s: point (%.17g, %.17g, %.17g), reference (%.17g, %.17g, %.17g)", what, a->point.x, a->point.y,
              a->point.z, b->point.x, b->point.y, b->point.z);
}

typedef struct checked {
    ori_status st;
    ori_collision_event ev;
    int nk;
    ori_contact *k;
} checked;

static checked checked_of(const ori_collider *c, ori_status st, const ori_collision_event *ev)
{
    checked x;
    x.st = st;
    x.ev = *ev;
    x.nk = ori_collider_contact_count(c);
    x.k = malloc(sizeof(ori_contact) * (size_t)(x.nk + 1));
    for (int i = 0; i < x.nk; ++i) x.k[i] = ori_collider_contact(c, i);
    return x;
}

static void assert_same_checked(checked *a, checked *b, const char *what)
{
    cr_assert_eq(a->st, b->st, "%s: status %d, reference %d", what, a->st, b->st);
    if (a->st == ORI_OK) {
        const ori_collision_event *x = &a->ev, *y = &b->ev;
        cr_assert_eq(x->collides, y->collides, "%s: collides %d, reference %d", what, x->collides, y->collides);
        if (x->collides) {
            cr_assert_eq(x->frame, y->frame, "%s: frame %d, reference %d", what, x->frame, y->frame);
            cr_assert_eq(x->fold, y->fold, "%s: fold", what);
            cr_assert_eq(x->step, y->step, "%s: step", what);
            cr_assert(x->drive_rad == y->drive_rad, "%s: drive %.17g, reference %.17g", what, x->drive_rad, y->drive_rad);
            cr_assert(x->time == y->time, "%s: time %.17g, reference %.17g", what, x->time, y->time);
            cr_assert_eq(x->states_solved, y->states_solved, "%s: states solved %d, reference %d", what, x->states_solved,
                         y->states_solved);
            assert_same_contact(&x->contact, &y->contact, what);
        }
        cr_assert_eq(a->nk, b->nk, "%s: %d contacts held, reference %d", what, a->nk, b->nk);
        for (int i = 0; i < a->nk; ++i) assert_same_contact(&a->k[i], &b->k[i], what);
    }
    free(a->k);
    free(b->k);
}

static int motions_compared;

static ori_status check_motion_both(ori_collider *c, const ori_mechanism *m, const ori_motion_def *d, const ori_motion *mo,
                                    const ori_collision_motion_def *cd, ori_collision_event *ev, ori_error *err)
{
    ori_collision_event e0;
    ori_error err0;
    col_collider_set_reference(c, true);
    ori_status s0 = ori_collision_check_motion(c, m, d, mo, cd, &e0, &err0);
    checked ref = checked_of(c, s0, &e0);
    col_collider_set_reference(c, false);
    ori_status st = ori_collision_check_motion(c, m, d, mo, cd, ev, err);
    checked inc = checked_of(c, st, ev);
    assert_same_checked(&inc, &ref, "fold");
    motions_compared++;
    return st;
}

static ori_status check_record_both(ori_collider *c, const ori_record *r, const ori_collision_motion_def *cd,
                                    ori_collision_event *ev, ori_error *err)
{
    ori_collision_event e0;
    ori_error err0;
    col_collider_set_reference(c, true);
    ori_status s0 = ori_collision_check_record(c, r, cd, &e0, &err0);
    checked ref = checked_of(c, s0, &e0);
    col_collider_set_reference(c, false);
    ori_status st = ori_collision_check_record(c, r, cd, ev, err);
    checked inc = checked_of(c, st, ev);
    assert_same_checked(&inc, &ref, "sequence");
    motions_compared++;
    return st;
}

static ori_status check_multifold_both(ori_collider *c, const ori_multifold *mf, const int *locked, int locked_count,
                                       const ori_collision_motion_def *cd, ori_collision_event *ev, ori_error *err)
{
    ori_collision_event e0;
    ori_error err0;
    col_collider_set_reference(c, true);
    ori_status s0 = ori_collision_check_multifold(c, mf, locked, locked_count, cd, &e0, &err0);
    checked ref = checked_of(c, s0, &e0);
    col_collider_set_reference(c, false);
    ori_status st = ori_collision_check_multifold(c, mf, locked, locked_count, cd, ev, err);
    checked inc = checked_of(c, st, ev);
    assert_same_checked(&inc, &ref, "multifold");
    motions_compared++;
    return st;
}

// --- building posed faces by hand --------------------------------------------------------------

// A folded form of separate faces: each face given by its own vertices (no sharing unless the
// caller repeats an index through share_with). Vertices are appended in order.
typedef struct scene {
    ori_pattern *p;
    ori_v3 pos[256];
    int nv;
} scene;

static scene scene_new(void)
{
    scene s;
    memset(&s, 0, sizeof s);
    ori_pattern_def pd = ori_default_pattern_def();
    s.p = ori_pattern_create(&pd);
    return s;
}

static int scene_vertex(scene *s, ori_v3 x)
{
    s->pos[s->nv] = x;
    ori_pattern_add_vertex(s->p, x);
    return s->nv++;
}

// A face from vertex indices (edges added as boundary edges when missing).
static int scene_face_idx(scene *s, const int *v, int n)
{
    for (int i = 0; i < n; ++i) {
        int a = v[i], b = v[(i + 1) % n];
        bool have = false;
        for (int e = 0; e < ori_pattern_edge_count(s->p); ++e) {
            ori_edge ed = ori_pattern_edge(s->p, e);
            if ((ed.v[0] == a && ed.v[1] == b) || (ed.v[0] == b && ed.v[1] == a)) have = true;
        }
        if (!have) ori_pattern_add_edge(s->p, a, b, ORI_ASSIGN_BOUNDARY, 0.0);
    }
    return ori_pattern_add_face(s->p, v, n);
}

static int scene_face(scene *s, const ori_v3 *pts, int n)
{
    int v[32];
    for (int i = 0; i < n; ++i) v[i] = scene_vertex(s, pts[i]);
    return scene_face_idx(s, v, n);
}

// Axis-aligned square [x0, x0+a] × [y0, y0+a] at height z (counter-clockwise from +z).
static int scene_square_z(scene *s, double x0, double y0, double a, double z)
{
    ori_v3 q[4] = {{x0, y0, z}, {x0 + a, y0, z}, {x0 + a, y0 + a, z}, {x0, y0 + a, z}};
    return scene_face(s, q, 4);
}

static ori_collider *scene_collider(scene *s, double clearance)
{
    ori_pattern_set_folded_form(s->p, true);
    ori_build_def bd = ori_default_build_def();
    bd.check_planarity = false;
    bd.compute_faces = false;
    ori_error err;
    cr_assert_eq(ori_pattern_build(s->p, &bd, &err), ORI_OK, "%s", err.message);
    ori_collider_def cd = ori_default_collider_def();
    cd.pattern = s->p;
    cd.clearance = clearance;
    ori_collider *c = NULL;
    cr_assert_eq(ori_collider_create(&cd, &c, &err), ORI_OK, "%s", err.message);
    return c;
}

static ori_collision_result check_ok(ori_collider *c, const ori_v3 *pos)
{
    ori_collision_result r;
    ori_error err;
    cr_assert_eq(ori_collider_check(c, pos, &r, &err), ORI_OK, "%s", err.message);
    return r;
}

static ori_contact find_contact(const ori_collider *c, int f, int g)
{
    for (int i = 0; i < ori_collider_contact_count(c); ++i) {
        ori_contact k = ori_collider_contact(c, i);
        if (k.face_a == (f < g ? f : g) && k.face_b == (f < g ? g : f)) return k;
    }
    cr_assert_fail("no contact between faces %d and %d", f, g);
    ori_contact none;
    memset(&none, 0, sizeof none);
    return none;
}

static void scene_free(scene *s, ori_collider *c)
{
    ori_collider_destroy(c);
    ori_pattern_destroy(s->p);
}

// --- one state: the cases -------------------------------------------------------------------

Test(collision, parallel_squares_have_the_plane_distance_as_clearance)
{
    scene s = scene_new();
    scene_square_z(&s, 0, 0, 1, 0);
    scene_square_z(&s, 0.25, 0.5, 1, 0.3);
    ori_collider *c = scene_collider(&s, 0);
    ori_collision_result r = check_ok(c, s.pos);
    cr_assert(!r.collides);
    cr_assert_eq(r.contact_count, 0);
    cr_assert_float_eq(r.min_clearance, 0.3, 1e-15);
    cr_assert(r.has_witness);
    cr_assert_float_eq(r.witness.z, 0.15, 1e-15);
    cr_assert_eq(r.clearance_faces[0], 0);
    cr_assert_eq(r.clearance_faces[1], 1);
    scene_free(&s, c);
}

Test(collision, a_square_through_another_penetrates_with_a_witness_on_the_crossing)
{
    scene s = scene_new();
    scene_square_z(&s, 0, 0, 2, 0);
    // vertical square x = 1, y ∈ [0.5, 1.5], z ∈ [−0.5, 0.5]: crosses the first along y ∈ [0.5, 1.5]
    ori_v3 q[4] = {{1, 0.5, -0.5}, {1, 1.5, -0.5}, {1, 1.5, 0.5}, {1, 0.5, 0.5}};
    scene_face(&s, q, 4);
    ori_collider *c = scene_collider(&s, 0);
    ori_collision_result r = check_ok(c, s.pos);
    cr_assert(r.collides);
    cr_assert_eq(r.penetrating, 1);
    ori_contact k = find_contact(c, 0, 1);
    cr_assert_eq(k.kind, ORI_CONTACT_PENETRATING);
    cr_assert(!k.adjacent);
    // the crossing is the segment x = 1, z = 0, y ∈ [0.5, 1.5]: its midpoint
    cr_assert_float_eq(k.point.x, 1.0, 1e-15);
    cr_assert_float_eq(k.point.y, 1.0, 1e-15);
    cr_assert_float_eq(k.point.z, 0.0, 1e-15);
    cr_assert_float_eq(r.min_clearance, 0.0, 0.0);
    scene_free(&s, c);
}

Test(collision, a_face_resting_on_another_touches_and_a_tiny_dip_still_touches)
{
    double dips[3] = {0.0, 3e-10, -3e-10}; // within the penetration tolerance (1e-9 × diagonal)
    for (int i = 0; i < 3; ++i) {
        scene s = scene_new();
        scene_square_z(&s, 0, 0, 2, 0);
        // a wall standing on the square, its bottom edge at z = dip
        ori_v3 q[4] = {{1, 0.5, dips[i]}, {1, 1.5, dips[i]}, {1, 1.5, 1}, {1, 0.5, 1}};
        scene_face(&s, q, 4);
        ori_collider *c = scene_collider(&s, 0);
        ori_collision_result r = check_ok(c, s.pos);
        cr_assert(!r.collides, "dip %g", dips[i]);
        cr_assert_eq(r.touching, 1, "dip %g", dips[i]);
        cr_assert_eq(find_contact(c, 0, 1).kind, ORI_CONTACT_TOUCHING);
        cr_assert_float_eq(r.min_clearance, 0.0, 0.0);
        scene_free(&s, c);
    }
    // a real dip (1e-6 of the size, far above the penetration tolerance) penetrates
    scene s = scene_new();
    scene_square_z(&s, 0, 0, 2, 0);
    ori_v3 q[4] = {{1, 0.5, -1e-6}, {1, 1.5, -1e-6}, {1, 1.5, 1}, {1, 0.5, 1}};
    scene_face(&s, q, 4);
    ori_collider *c = scene_collider(&s, 0);
    ori_collision_result r = check_ok(c, s.pos);
    cr_assert(r.collides);
    cr_assert_eq(find_contact(c, 0, 1).kind, ORI_CONTACT_PENETRATING);
    scene_free(&s, c);
}

Test(collision, crossed_edges_and_a_corner_on_a_face_touch)
{
    scene s = scene_new();
    scene_square_z(&s, 0, 0, 1, 0);
    // a square above, tilted so that its lowest corner rests on the first square's middle
    ori_v3 q[3] = {{0.5, 0.5, 0}, {0.9, 0.5, 0.5}, {0.5, 0.9, 0.5}};
    scene_face(&s, q, 3);
    ori_collider *c = scene_collider(&s, 0);
    ori_collision_result r = check_ok(c, s.pos);
    cr_assert(!r.collides);
    ori_contact k = find_contact(c, 0, 1);
    cr_assert_eq(k.kind, ORI_CONTACT_TOUCHING);
    cr_assert_float_eq(k.point.x, 0.5, 1e-12);
    cr_assert_float_eq(k.point.y, 0.5, 1e-12);
    cr_assert_float_eq(k.point.z, 0.0, 1e-12);
    scene_free(&s, c);

    // two triangles whose edges cross like an X, each on its own side of the other's plane
    s = scene_new();
    ori_v3 a[3] = {{-1, 0, 0}, {1, 0, 0}, {0, 0, -1}};      // in y = 0, below z = 0, top edge on the x axis
    ori_v3 b[3] = {{0, -1, 0}, {0, 1, 0}, {0, 0, 1}};       // in x = 0, above z = 0, bottom edge on the y axis
    scene_face(&s, a, 3);
    scene_face(&s, b, 3);
    c = scene_collider(&s, 0);
    r = check_ok(c, s.pos);
    cr_assert(!r.collides);
    cr_assert_eq(r.touching, 1);
    k = find_contact(c, 0, 1);
    cr_assert_float_eq(ori_v3_norm(k.point), 0.0, 1e-15);
    scene_free(&s, c);
}

Test(collision, coplanar_layers_that_overlap_are_stacked_and_touch)
{
    scene s = scene_new();
    scene_square_z(&s, 0, 0, 1, 0);
    scene_square_z(&s, 0.5, 0.5, 1, 0);   // overlaps the first on [0.5, 1]²
    scene_square_z(&s, 1.0, -1.0, 1, 0);  // meets the first at its corner (1, 0) only
    scene_square_z(&s, 3.0, 0.0, 1, 0);   // apart: 2 from the first, 0.5 from the second
    ori_collider *c = scene_collider(&s, 0);
    ori_collision_result r = check_ok(c, s.pos);
    cr_assert(!r.collides);
    ori_contact k = find_contact(c, 0, 1);
    cr_assert_eq(k.kind, ORI_CONTACT_TOUCHING);
    cr_assert(k.stacked);
    cr_assert_float_eq(k.point.x, 0.75, 1e-12); // centroid of the overlap
    cr_assert_float_eq(k.point.y, 0.75, 1e-12);
    k = find_contact(c, 0, 2);
    cr_assert_eq(k.kind, ORI_CONTACT_TOUCHING);
    cr_assert(!k.stacked);
    cr_assert_eq(r.touching, 2);
    cr_assert_float_eq(r.min_clearance, 0.0, 0.0);
    scene_free(&s, c);
}

Test(collision, a_non_convex_face_is_met_only_where_it_has_material)
{
    // an L-shaped face: [0,2]×[0,2] without the quarter [1,2]×[1,2]
    scene s = scene_new();
    ori_v3 l[6] = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
    scene_face(&s, l, 6);
    // a vertical square through the missing quarter: no contact, clearance 0.25 (to the notch edge)
    ori_v3 q[4] = {{1.25, 1.5, -0.5}, {1.75, 1.5, -0.5}, {1.75, 1.5, 0.5}, {1.25, 1.5, 0.5}};
    scene_face(&s, q, 4);
    ori_collider *c = scene_collider(&s, 0);
    ori_collision_result r = check_ok(c, s.pos);
    cr_assert(!r.collides);
    cr_assert_eq(r.contact_count, 0);
    cr_assert_float_eq(r.min_clearance, 0.25, 1e-14);
    scene_free(&s, c);
    // the same square moved over the material of the L crosses it
    s = scene_new();
    scene_face(&s, l, 6);
    ori_v3 q2[4] = {{1.25, 0.5, -0.5}, {1.75, 0.5, -0.5}, {1.75, 0.5, 0.5}, {1.25, 0.5, 0.5}};
    scene_face(&s, q2, 4);
    c = scene_collider(&s, 0);
    r = check_ok(c, s.pos);
    cr_assert(r.collides);
    ori_contact k = find_contact(c, 0, 1);
    cr_assert_float_eq(k.point.x, 1.5, 1e-14);
    cr_assert_float_eq(k.point.y, 0.5, 1e-14);
    scene_free(&s, c);
    // and a square lying in the notch, coplanar, touches along the notch's sides only
    s = scene_new();
    scene_face(&s, l, 6);
    scene_square_z(&s, 1, 1, 1, 0);
    c = scene_collider(&s, 0);
    r = check_ok(c, s.pos);
    cr_assert(!r.collides);
    k = find_contact(c, 0, 1);
    cr_assert_eq(k.kind, ORI_CONTACT_TOUCHING);
    cr_assert(!k.stacked);
    scene_free(&s, c);
}

Test(collision, faces_sharing_a_vertex_are_checked_away_from_it)
{
    // Two triangles sharing the vertex at the origin. Apart: nothing (they meet only there).
    scene s = scene_new();
    int o = scene_vertex(&s, ori_v3_make(0, 0, 0));
    int a1 = scene_vertex(&s, ori_v3_make(1, 0, 0)), a2 = scene_vertex(&s, ori_v3_make(1, 1, 0));
    int b1 = scene_vertex(&s, ori_v3_make(-1, 0, 0.2)), b2 = scene_vertex(&s, ori_v3_make(-1, -1, 0.2));
    int fa[3] = {o, a1, a2}, fb[3] = {o, b1, b2};
    scene_face_idx(&s, fa, 3);
    scene_face_idx(&s, fb, 3);
    ori_collider *c = scene_collider(&s, 0);
    cr_assert(ori_collider_adjacent(c, 0, 1));
    ori_collision_result r = check_ok(c, s.pos);
    cr_assert(!r.collides);
    cr_assert_eq(r.contact_count, 0);
    cr_assert(isinf(r.min_clearance)); // no pair shares no vertex
    cr_assert(!r.has_witness);
    scene_free(&s, c);
    // The second triangle turned into the first: they cross along a ray from the shared vertex.
    s = scene_new();
    o = scene_vertex(&s, ori_v3_make(0, 0, 0));
    a1 = scene_vertex(&s, ori_v3_make(2, -1, 0));
    a2 = scene_vertex(&s, ori_v3_make(2, 1, 0));
    b1 = scene_vertex(&s, ori_v3_make(2, 0, -1));
    b2 = scene_vertex(&s, ori_v3_make(2, 0, 1));
    int ga[3] = {o, a1, a2}, gb[3] = {o, b1, b2};
    scene_face_idx(&s, ga, 3);
    scene_face_idx(&s, gb, 3);
    c = scene_collider(&s, 0);
    r = check_ok(c, s.pos);
    cr_assert(r.collides);
    ori_contact k = find_contact(c, 0, 1);
    cr_assert_eq(k.kind, ORI_CONTACT_PENETRATING);
    cr_assert(k.adjacent);
    cr_assert_float_eq(k.point.x, 1.0, 1e-14); // midpoint of the crossing from (0,0,0) to (2,0,0)
    cr_assert_float_eq(k.point.y, 0.0, 1e-14);
    scene_free(&s, c);
}

Test(collision, a_crease_folded_flat_stacks_its_faces_and_one_folded_to_90_does_not_touch)
{
    for (int flat = 0; flat < 2; ++flat) {
        scene s = scene_new();
        int v0 = scene_vertex(&s, ori_v3_make(0, 0, 0)), v1 = scene_vertex(&s, ori_v3_make(0, 1, 0));
        int a = scene_vertex(&s, ori_v3_make(1, 0, 0)), b = scene_vertex(&s, ori_v3_make(1, 1, 0));
        ori_v3 x = flat ? ori_v3_make(1, 0, 1e-13) : ori_v3_make(0, 0, 1);
        ori_v3 y = flat ? ori_v3_make(1, 1, 1e-13) : ori_v3_make(0, 1, 1);
        int cc = scene_vertex(&s, x), d = scene_vertex(&s, y);
        int f0[4] = {v0, a, b, v1}, f1[4] = {v1, d, cc, v0};
        scene_face_idx(&s, f0, 4);
        scene_face_idx(&s, f1, 4);
        ori_collider *c = scene_collider(&s, 0);
        ori_collision_result r = check_ok(c, s.pos);
        cr_assert(!r.collides);
        cr_assert_eq(r.touching, flat ? 1 : 0);
        if (flat) {
            ori_contact k = find_contact(c, 0, 1);
            cr_assert(k.adjacent && k.stacked);
        }
        scene_free(&s, c);
    }
}

Test(collision, the_clearance_makes_near_faces_collide)
{
    scene s = scene_new();
    scene_square_z(&s, 0, 0, 1, 0);
    scene_square_z(&s, 0, 0, 1, 0.05);
    scene_square_z(&s, 0, 0, 1, 0.5);
    ori_collider *c = scene_collider(&s, 0.1);
    ori_collision_result r = check_ok(c, s.pos);
    cr_assert(r.collides);
    cr_assert_eq(r.near, 1);
    ori_contact k = find_contact(c, 0, 1);
    cr_assert_eq(k.kind, ORI_CONTACT_NEAR);
    cr_assert(k.collides);
    cr_assert_float_eq(k.distance, 0.05, 1e-15);
    cr_assert_float_eq(r.min_clearance, 0.05, 1e-15);
    cr_assert_float_eq(r.witness.z, 0.025, 1e-15);
    scene_free(&s, c);
}

Test(collision, bad_input_is_named)
{
    scene s = scene_new();
    scene_square_z(&s, 0, 0, 1, 0);
    ori_v3 q[4] = {{3, 0, 0}, {4, 0, 0}, {4, 1, 0.2}, {3, 1, 0}}; // not planar
    scene_face(&s, q, 4);
    ori_collider *c = scene_collider(&s, 0);
    ori_collision_result r;
    ori_error err;
    cr_assert_eq(ori_collider_check(c, s.pos, &r, &err), ORI_ERR_DEGENERATE);
    cr_assert_str_eq(err.field, "faces_vertices");
    cr_assert_eq(err.element, 1);
    cr_assert(strstr(err.message, "not planar"), "%s", err.message);
    s.pos[0].x = NAN;
    cr_assert_eq(ori_collider_check(c, s.pos, &r, &err), ORI_ERR_RANGE);
    cr_assert_eq(err.element, 0);
    ori_collider_destroy(c);
    ori_collider_def cd = ori_default_collider_def();
    cd.pattern = s.p;
    cd.clearance = -1;
    cr_assert_eq(ori_collider_create(&cd, &c, &err), ORI_ERR_RANGE);
    cr_assert_null(c);
    ori_pattern_destroy(s.p);
}

// --- the strip with two flaps (issue reference case) ---------------------------------------

// A strip of width 1 along x: left flap [−L1, 0], middle panel [0, g], right flap [g, g + L2],
// two valley creases at x = 0 and x = g. Faces and creases found by coordinates.
typedef struct strip {
    ori_pattern *p;
    ori_mechanism *m;
    int left_crease, right_crease;
    int left, middle, right;
} strip;

static strip strip_make(double g, double l1, double l2)
{
    strip s;
    ori_pattern_def pd = ori_default_pattern_def();
    s.p = ori_pattern_create(&pd);
    double xs[4] = {-l1, 0.0, g, g + l2};
    for (int i = 0; i < 4; ++i) {
        ori_pattern_add_vertex(s.p, ori_v3_make(xs[i], 0.0, 0.0));
        ori_pattern_add_vertex(s.p, ori_v3_make(xs[i], 1.0, 0.0));
    }
    for (int i = 0; i < 3; ++i) {
        ori_pattern_add_edge(s.p, 2 * i, 2 * i + 2, ORI_ASSIGN_BOUNDARY, 0.0);
        ori_pattern_add_edge(s.p, 2 * i + 1, 2 * i + 3, ORI_ASSIGN_BOUNDARY, 0.0);
    }
    ori_pattern_add_edge(s.p, 0, 1, ORI_ASSIGN_BOUNDARY, 0.0);
    s.left_crease = ori_pattern_add_edge(s.p, 2, 3, ORI_ASSIGN_VALLEY, 0.0);
    s.right_crease = ori_pattern_add_edge(s.p, 4, 5, ORI_ASSIGN_VALLEY, 0.0);
    ori_pattern_add_edge(s.p, 6, 7, ORI_ASSIGN_BOUNDARY, 0.0);
    ori_error err;
    cr_assert_eq(ori_pattern_build(s.p, NULL, &err), ORI_OK, "%s", err.message);
    s.left = test_face_at(s.p, -0.5 * l1, 0.5);
    s.middle = test_face_at(s.p, 0.5 * g, 0.5);
    s.right = test_face_at(s.p, g + 0.5 * l2, 0.5);
    s.m = test_mechanism_of(s.p);
    return s;
}

static void strip_free(strip *s)
{
    ori_mechanism_destroy(s->m);
    ori_pattern_destroy(s->p);
}

static ori_collider *collider_of(const ori_pattern *p, double clearance)
{
    ori_collider_def cd = ori_default_collider_def();
    cd.pattern = p;
    cd.clearance = clearance;
    ori_collider *c = NULL;
    ori_error err;
    cr_assert_eq(ori_collider_create(&cd, &c, &err), ORI_OK, "%s", err.message);
    return c;
}

// The left flap stands at 90°; the right flap is driven from 0 to 180° by 10° steps, the middle
// fixed and the left crease locked. Returns the event.
static ori_collision_event strip_fold(strip *s, ori_collider *c, ori_motion **mo_out)
{
    double *start = calloc((size_t)ori_mechanism_edge_count(s->m), sizeof(double));
    start[s->left_crease] = 90 * DEG;
    ori_motion_def d = ori_default_motion_def();
    d.fixed_face = s->middle;
    d.start_angles_rad = start;
    d.driven_edge = s->right_crease;
    d.to_rad = 180 * DEG;
    d.step_rad = 10 * DEG;
    d.locked_edges = &s->left_crease;
    d.locked_count = 1;
    ori_motion *mo = NULL;
    ori_error err;
    cr_assert_eq(ori_motion_solve(s->m, &d, &mo, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_VALID);
    cr_assert_eq(ori_motion_frame_count(mo), 19);
    ori_collision_motion_def cd = ori_default_collision_motion_def();
    ori_collision_event ev;
    cr_assert_eq(check_motion_both(c, s->m, &d, mo, &cd, &ev, &err), ORI_OK, "%s", err.message);
    free(start);
    if (mo_out) *mo_out = mo;
    else ori_motion_destroy(mo);
    return ev;
}

// The same two folds as a sequence: left crease to 90°, then the right one to 180°.
static ori_collision_event strip_sequence(strip *s, ori_collider *c, ori_record **rec_out)
{
    char json[512];
    snprintf(json, sizeof json,
             "{\"pattern\": \"strip.fold\", \"folds\": [{\"fix\": %d, \"drive\": %d, \"to\": 90, \"step\": 30, \"lock\": [%d]},"
             "{\"fix\": %d, \"drive\": %d, \"to\": 180, \"step\": 10, \"lock\": [%d]}]}",
             s->middle, s->left_crease, s->right_crease, s->middle, s->right_crease, s->left_crease);
    ori_sequence *seq = NULL;
    ori_error err;
    cr_assert_eq(ori_sequence_parse(json, strlen(json), &seq, &err), ORI_OK, "%s", err.message);
    ori_record *r = NULL;
    cr_assert_eq(ori_sequence_run(seq, s->m, NULL, ori_rigid_identity(), &r, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_record_verdict(r), ORI_MOTION_VALID);
    ori_collision_motion_def cd = ori_default_collision_motion_def();
    ori_collision_event ev;
    cr_assert_eq(check_record_both(c, r, &cd, &ev, &err), ORI_OK, "%s", err.message);
    ori_sequence_destroy(seq);
    if (rec_out) *rec_out = r;
    else ori_record_destroy(r);
    return ev;
}

// The first contact: 1e-6° bracket, and the penetration tolerance (1e-9 of the size) delays
// detection by far less.
#define CONTACT_TOL_DEG 1e-6

Test(collision, strip_tip_meets_the_standing_flap_at_cos_rho_equal_minus_g_over_l2)
{
    double g = 1.0, l1 = 2.0, l2 = 1.5; // l2² = 2.25 < g² + l1² = 5
    double want = acos(-g / l2) / DEG;   // 131.8103148957786°
    strip s = strip_make(g, l1, l2);
    ori_collider *c = collider_of(s.p, 0);
    ori_collision_event ev = strip_fold(&s, c, NULL);
    cr_assert(ev.collides);
    cr_assert_eq(ev.frame, 14); // 130° clean, 140° collides
    cr_assert_eq(ev.step, 14);
    cr_assert_float_eq(ev.drive_rad / DEG, want, CONTACT_TOL_DEG);
    cr_assert_geq(ev.drive_rad / DEG, want - 1e-9); // never before the contact
    cr_assert_eq(ev.contact.face_a, s.left < s.right ? s.left : s.right);
    cr_assert_eq(ev.contact.face_b, s.left < s.right ? s.right : s.left);
    cr_assert_eq(ev.contact.kind, ORI_CONTACT_PENETRATING);
    // the witness is on the tip edge, which lies on the standing flap x = 0 at z = √(l2² − g²)
    cr_assert_float_eq(ev.contact.point.x, 0.0, 1e-7);
    cr_assert_float_eq(ev.contact.point.z, sqrt(l2 * l2 - g * g), 1e-7);
    cr_assert_float_eq(ev.contact.point.y, 0.5, 1e-7);
    cr_assert_gt(ev.states_solved, 20);
    ori_record *r = NULL;
    ev = strip_sequence(&s, c, &r);
    cr_assert(ev.collides);
    cr_assert_eq(ev.fold, 1);
    cr_assert_eq(ev.step, 14);
    cr_assert_eq(ev.frame, 3 + 14); // the start, 3 steps of fold 1, 14 of fold 2
    cr_assert_float_eq(ev.drive_rad / DEG, want, CONTACT_TOL_DEG);
    cr_assert_float_eq(ev.time, 1.0 + want / 180.0, CONTACT_TOL_DEG / 180.0);
    cr_assert_eq(ev.contact.kind, ORI_CONTACT_PENETRATING);
    ori_record_destroy(r);
    ori_collider_destroy(c);
    strip_free(&s);
}

// Large steps: the tip passes through the standing flap between two clean states (120° is
// short of the contact, 180° only touches: the flap lies on the middle panel across the standing
// flap's hinge line), and neither state has the flaps over each other, so the layer sides say
// nothing. The sweep's reach sends the step to half steps, and the first contact is found where
// the closed form puts it, for steps of 60° and of the whole 180°.
Test(collision, a_tip_passing_through_within_one_large_step_is_found_at_its_first_contact)
{
    double g = 1.0, l1 = 2.0, l2 = 1.5;
    double want = acos(-g / l2) / DEG;
    strip s = strip_make(g, l1, l2);
    ori_collider *c = collider_of(s.p, 0);
    double steps[2] = {60.0, 180.0};
    for (int i = 0; i < 2; ++i) {
        double *start = calloc((size_t)ori_mechanism_edge_count(s.m), sizeof(double));
        start[s.left_crease] = 90 * DEG;
        ori_motion_def d = ori_default_motion_def();
        d.fixed_face = s.middle;
        d.start_angles_rad = start;
        d.driven_edge = s.right_crease;
        d.to_rad = 180 * DEG;
        d.step_rad = steps[i] * DEG;
        d.locked_edges = &s.left_crease;
        d.locked_count = 1;
        ori_motion *mo = NULL;
        ori_error err;
        cr_assert_eq(ori_motion_solve(s.m, &d, &mo, &err), ORI_OK, "%s", err.message);
        int n = ori_motion_frame_count(mo);
        cr_assert_eq(n, (int)(180.0 / steps[i]) + 1);
        // every stored state is clean on its own
        for (int k = 0; k < n; ++k) {
            ori_v3 pos[8];
            ori_motion_frame_vertices(mo, k, pos);
            ori_collision_result r;
            cr_assert_eq(ori_collider_check(c, pos, &r, &err), ORI_OK, "%s", err.message);
            cr_assert(!r.collides, "step %g: state %d is clean", steps[i], k);
        }
        ori_collision_motion_def cd = ori_default_collision_motion_def();
        ori_collision_event ev;
        cr_assert_eq(check_motion_both(c, s.m, &d, mo, &cd, &ev, &err), ORI_OK, "%s", err.message);
        cr_assert(ev.collides, "step %g", steps[i]);
        cr_assert_eq(ev.frame, n - 1);
        cr_assert_float_eq(ev.drive_rad / DEG, want, CONTACT_TOL_DEG, "step %g: %.9f", steps[i], ev.drive_rad / DEG);
        cr_assert_geq(ev.drive_rad / DEG, want - 1e-9);
        cr_assert_eq(ev.contact.kind, ORI_CONTACT_PENETRATING);
        cr_assert_float_eq(ev.contact.point.z, sqrt(l2 * l2 - g * g), 1e-6);
        ori_motion_destroy(mo);
        free(start);
    }
    ori_collider_destroy(c);
    strip_free(&s);
}

Test(collision, strip_flap_meets_the_standing_flaps_top_edge_at_180_minus_atan_l1_over_g)
{
    double g = 1.0, l1 = 1.0, l2 = 3.0; // l2² = 9 > g² + l1² = 2
    double want = 180.0 - atan(l1 / g) / DEG; // 135°
    strip s = strip_make(g, l1, l2);
    ori_collider *c = collider_of(s.p, 0);
    ori_collision_event ev = strip_fold(&s, c, NULL);
    cr_assert(ev.collides);
    cr_assert_eq(ev.frame, 14); // 130° clean; 135° itself is contact, 140° collides
    cr_assert_float_eq(ev.drive_rad / DEG, want, CONTACT_TOL_DEG);
    cr_assert_geq(ev.drive_rad / DEG, want - 1e-9);
    // the witness is on the standing flap's top edge (0, y, l1)
    cr_assert_float_eq(ev.contact.point.x, 0.0, 1e-6);
    cr_assert_float_eq(ev.contact.point.z, l1, 1e-6);
    ev = strip_sequence(&s, c, NULL);
    cr_assert(ev.collides);
    cr_assert_eq(ev.fold, 1);
    cr_assert_float_eq(ev.drive_rad / DEG, want, CONTACT_TOL_DEG);
    ori_collider_destroy(c);
    strip_free(&s);
}

Test(collision, strip_short_flap_lands_on_the_middle_panel_touching)
{
    double g = 1.0, l1 = 1.0, l2 = 0.8; // l2 < g: lands on the middle panel at 180°
    strip s = strip_make(g, l1, l2);
    ori_collider *c = collider_of(s.p, 0);
    ori_motion *mo = NULL;
    ori_collision_event ev = strip_fold(&s, c, &mo);
    cr_assert(!ev.collides);
    // the last state (180°): the flap lies on the middle panel, stacked and touching
    ori_v3 pos[8];
    ori_motion_frame_vertices(mo, ori_motion_frame_count(mo) - 1, pos);
    ori_collision_result r = check_ok(c, pos);
    cr_assert(!r.collides);
    cr_assert_eq(r.touching, 1);
    ori_contact k = find_contact(c, s.middle, s.right);
    cr_assert(k.stacked && k.adjacent);
    cr_assert_float_eq(k.point.x, g - 0.5 * l2, 1e-12);
    // the flap's tip is g − l2 from the standing flap: the least clearance, at (0.2, y, 0)…(0, y, 0)
    cr_assert_float_eq(r.min_clearance, g - l2, 1e-12);
    ori_motion_destroy(mo);
    ev = strip_sequence(&s, c, NULL);
    cr_assert(!ev.collides);
    ori_collider_destroy(c);
    strip_free(&s);
}

// --- the Miura-ori folded from flat to 180° -----------------------------------------------------

// R × C Miura-ori (a = 1, b = 1, γ = 60°) folded by its middle zig-zag crease from flat to
// ±180° (its assignment's sign) in steps of step_deg.
typedef struct miura_fold {
    ori_pattern *p;
    ori_mechanism *m;
    ori_motion_def d;
    ori_motion *mo;
} miura_fold;

static miura_fold miura_fold_make(int rows, int cols, double step_deg)
{
    miura_fold x;
    x.p = test_miura(rows, cols, 1.0, 1.0, 60 * DEG, NULL);
    x.m = test_mechanism_of(x.p);
    int i = cols / 2, j = rows / 2;
    int drive = ori_pattern_find_edge(x.p, j * (cols + 1) + i, (j + 1) * (cols + 1) + i);
    cr_assert_neq(drive, ORI_NULL_INDEX);
    double sg = ori_pattern_edge(x.p, drive).assignment == ORI_ASSIGN_VALLEY ? 1.0 : -1.0;
    x.d = ori_default_motion_def();
    x.d.fixed_face = ori_mechanism_face_count(x.m) / 2;
    x.d.driven_edge = drive;
    x.d.to_rad = sg * ORI_PI;
    x.d.step_rad = step_deg * DEG;
    ori_error err;
    x.mo = NULL;
    cr_assert_eq(ori_motion_solve(x.m, &x.d, &x.mo, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_motion_verdict_of(x.mo), ORI_MOTION_VALID);
    return x;
}

static void miura_fold_free(miura_fold *x)
{
    ori_motion_destroy(x->mo);
    ori_mechanism_destroy(x->m);
    ori_pattern_destroy(x->p);
}

Test(collision, miura_folded_flat_never_penetrates_and_ends_in_touching_layers)
{
    miura_fold x = miura_fold_make(4, 4, 10.0);
    ori_collider *c = collider_of(x.p, 0);
    ori_collision_motion_def cd = ori_default_collision_motion_def();
    ori_collision_event ev;
    ori_error err;
    cr_assert_eq(check_motion_both(c, x.m, &x.d, x.mo, &cd, &ev, &err), ORI_OK, "%s", err.message);
    cr_assert(!ev.collides, "frame %d faces %d %d", ev.frame, ev.contact.face_a, ev.contact.face_b);
    int nf = ori_motion_frame_count(x.mo), nv = ori_mechanism_vertex_count(x.m);
    cr_assert_eq(nf, 19);
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)nv);
    for (int k = 0; k < nf; ++k) {
        ori_motion_frame_vertices(x.mo, k, pos);
        ori_collision_result r = check_ok(c, pos);
        cr_assert_eq(r.penetrating, 0, "frame %d", k);
        cr_assert(!r.collides);
        if (k == 0) {
            // flat: faces side by side, the nearest faces sharing no vertex are one cell apart
            cr_assert_eq(r.contact_count, 0);
            cr_assert_float_eq(r.min_clearance, sqrt(3.0) / 2.0, 1e-12); // rows of cells: b·sin γ
        }
        if (k == nf - 1) {
            // folded flat: every face lies in one of the stack's layers
            cr_assert_gt(r.touching, ori_mechanism_face_count(x.m));
            int stacked = 0;
            for (int i = 0; i < ori_collider_contact_count(c); ++i) {
                ori_contact t = ori_collider_contact(c, i);
                cr_assert_eq(t.kind, ORI_CONTACT_TOUCHING);
                stacked += t.stacked;
            }
            cr_assert_gt(stacked, 0);
            cr_assert_float_eq(r.min_clearance, 0.0, 0.0);
        }
    }
    free(pos);
    ori_collider_destroy(c);
    miura_fold_free(&x);
}

// --- the shared folded forms ------------------------------------------------------------------

static ori_pattern *load_folded(const char *rel)
{
    const char *path = test_require_shared(rel);
    ori_fold *doc = NULL;
    ori_error err;
    cr_assert_eq(ori_fold_load_file(path, &doc, &err), ORI_OK, "%s", err.message);
    ori_build_def bd = ori_default_build_def();
    bd.check_planarity = false;
    ori_pattern *p = NULL;
    cr_assert_eq(ori_fold_get_pattern(doc, 0, &bd, &p, &err), ORI_OK, "%s", err.message);
    ori_fold_destroy(doc);
    cr_assert(ori_pattern_is_3d(p));
    return p;
}

static ori_v3 *positions_of(const ori_pattern *p)
{
    int nv = ori_pattern_vertex_count(p);
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)(nv + 1));
    for (int v = 0; v < nv; ++v) pos[v] = ori_pattern_vertex(p, v);
    return pos;
}

static ori_v3 face_centroid(const ori_pattern *p, int f)
{
    int v[64], n = ori_pattern_face_vertices(p, f, v, 64);
    ori_v3 s = ori_v3_make(0, 0, 0);
    for (int i = 0; i < n; ++i) s = ori_v3_add(s, ori_pattern_vertex(p, v[i]));
    return ori_v3_scale(s, 1.0 / n);
}

static ori_v3 face_normal_of(const ori_pattern *p, int f)
{
    int v[64], n = ori_pattern_face_vertices(p, f, v, 64);
    ori_v3 a = ori_v3_make(0, 0, 0), p0 = ori_pattern_vertex(p, v[0]);
    for (int i = 0; i < n; ++i)
        a = ori_v3_add(a, ori_v3_cross(ori_v3_sub(ori_pattern_vertex(p, v[i]), p0),
                                       ori_v3_sub(ori_pattern_vertex(p, v[(i + 1) % n]), p0)));
    return ori_v3_normalize(a);
}

// The folded form with face f cut free (new vertices) and translated so that its centroid lands
// on face g's centroid: f now passes through g.
static ori_pattern *moved_through(const ori_pattern *p, int f, int g)
{
    ori_pattern_def pd = ori_default_pattern_def();
    ori_pattern *q = ori_pattern_create(&pd);
    int nv = ori_pattern_vertex_count(p);
    for (int v = 0; v < nv; ++v) ori_pattern_add_vertex(q, ori_pattern_vertex(p, v));
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        ori_pattern_add_edge(q, ed.v[0], ed.v[1], ed.assignment, ed.fold_angle_rad);
    }
    ori_v3 t = ori_v3_sub(face_centroid(p, g), face_centroid(p, f));
    for (int h = 0; h < ori_pattern_face_count(p); ++h) {
        int v[64], n = ori_pattern_face_vertices(p, h, v, 64);
        if (h == f) {
            int w[64];
            for (int i = 0; i < n; ++i) w[i] = ori_pattern_add_vertex(q, ori_v3_add(ori_pattern_vertex(p, v[i]), t));
            for (int i = 0; i < n; ++i) ori_pattern_add_edge(q, w[i], w[(i + 1) % n], ORI_ASSIGN_CUT, 0.0);
            ori_pattern_add_face(q, w, n);
        } else {
            ori_pattern_add_face(q, v, n);
        }
    }
    ori_pattern_set_folded_form(q, true);
    ori_build_def bd = ori_default_build_def();
    bd.check_planarity = false;
    bd.compute_faces = false;
    ori_error err;
    cr_assert_eq(ori_pattern_build(q, &bd, &err), ORI_OK, "%s", err.message);
    return q;
}

static void shared_form_case(const char *rel)
{
    ori_pattern *p = load_folded(rel);
    ori_collider *c = collider_of(p, 0);
    ori_v3 *pos = positions_of(p);
    ori_collision_result r = check_ok(c, pos);
    cr_assert(!r.collides, "%s: %d penetrating", rel, r.penetrating);
    cr_assert_eq(r.penetrating, 0);
    cr_log_info("%s: %d faces, %d touching, min clearance %g", rel, ori_collider_face_count(c), r.touching, r.min_clearance);
    // Move one face through another: the pair of faces whose planes are furthest from parallel
    // among faces sharing no vertex (a clean crossing).
    int nf = ori_pattern_face_count(p), bf = -1, bg = -1;
    double best = 0.0;
    for (int f = 0; f < nf; ++f)
        for (int g = 0; g < nf; ++g) {
            if (f == g || ori_collider_adjacent(c, f, g)) continue;
            double s = ori_v3_norm(ori_v3_cross(face_normal_of(p, f), face_normal_of(p, g)));
            if (s > best + 1e-9) {
                best = s;
                bf = f;
                bg = g;
            }
        }
    cr_assert_geq(bf, 0);
    ori_pattern *q = moved_through(p, bf, bg);
    ori_collider *cq = collider_of(q, 0);
    ori_v3 *qpos = positions_of(q);
    r = check_ok(cq, qpos);
    cr_assert(r.collides, "%s: face %d moved through face %d", rel, bf, bg);
    ori_contact k = find_contact(cq, bf, bg);
    cr_assert_eq(k.kind, ORI_CONTACT_PENETRATING, "%s: faces %d and %d", rel, bf, bg);
    // the crossing passes through the target's centroid, where the moved face's centroid is
    cr_assert_float_eq(ori_v3_dot(ori_v3_sub(k.point, face_centroid(p, bg)), face_normal_of(p, bg)), 0.0, 1e-9);
    for (int i = 0; i < ori_collider_contact_count(cq); ++i) {
        ori_contact t = ori_collider_contact(cq, i);
        if (t.kind == ORI_CONTACT_PENETRATING) cr_assert(t.face_a == bf || t.face_b == bf, "%s: %d-%d", rel, t.face_a, t.face_b);
    }
    free(qpos);
    ori_collider_destroy(cq);
    ori_pattern_destroy(q);
    free(pos);
    ori_collider_destroy(c);
    ori_pattern_destroy(p);
}

Test(collision, the_fold_spec_box_is_collision_free_and_a_face_moved_through_another_is_named)
{
    shared_form_case("fold-spec/box.fold");
}

Test(collision, the_fold_spec_square_twist_is_collision_free_and_a_face_moved_through_another_is_named)
{
    shared_form_case("fold-spec/squaretwist.fold");
}

Test(collision, the_rabbit_ear_bird_base_is_collision_free_and_a_face_moved_through_another_is_named)
{
    shared_form_case("rabbit-ear/fold_bird-base-3d.fold");
}

// --- along a motion: the clearance, and stacked layers leaving through each other -------------

Test(collision, with_a_clearance_the_strip_collides_when_the_tip_comes_within_it)
{
    double g = 1.0, l1 = 2.0, l2 = 1.5, D = 0.1;
    double want = acos((D - g) / l2) / DEG; // the tip edge at x = D: 126.8698976°
    strip s = strip_make(g, l1, l2);
    ori_collider *c = collider_of(s.p, D);
    ori_collision_event ev = strip_fold(&s, c, NULL);
    cr_assert(ev.collides);
    cr_assert_eq(ev.frame, 13);
    cr_assert_float_eq(ev.drive_rad / DEG, want, CONTACT_TOL_DEG);
    cr_assert_eq(ev.contact.kind, ORI_CONTACT_NEAR);
    cr_assert_float_eq(ev.contact.distance, D, 1e-7);
    // the witness is midway between the tip edge (x = D) and the standing flap (x = 0)
    cr_assert_float_eq(ev.contact.point.x, 0.5 * D, 1e-7);
    ev = strip_sequence(&s, c, NULL);
    cr_assert_float_eq(ev.drive_rad / DEG, want, CONTACT_TOL_DEG);
    ori_collider_destroy(c);
    strip_free(&s);
}

// A strip of three unit panels P0 [0,1], P1 [1,2], P2 [2,3] with valley creases at x = 1 and 2.
typedef struct strip3 {
    ori_pattern *p;
    ori_mechanism *m;
    int c1, c2, p0, p1, p2;
} strip3;

static strip3 strip3_make(void)
{
    strip3 s;
    ori_pattern_def pd = ori_default_pattern_def();
    s.p = ori_pattern_create(&pd);
    for (int i = 0; i < 4; ++i) {
        ori_pattern_add_vertex(s.p, ori_v3_make(i, 0.0, 0.0));
        ori_pattern_add_vertex(s.p, ori_v3_make(i, 1.0, 0.0));
    }
    for (int i = 0; i < 3; ++i) {
        ori_pattern_add_edge(s.p, 2 * i, 2 * i + 2, ORI_ASSIGN_BOUNDARY, 0.0);
        ori_pattern_add_edge(s.p, 2 * i + 1, 2 * i + 3, ORI_ASSIGN_BOUNDARY, 0.0);
    }
    ori_pattern_add_edge(s.p, 0, 1, ORI_ASSIGN_BOUNDARY, 0.0);
    s.c1 = ori_pattern_add_edge(s.p, 2, 3, ORI_ASSIGN_VALLEY, 0.0);
    s.c2 = ori_pattern_add_edge(s.p, 4, 5, ORI_ASSIGN_VALLEY, 0.0);
    ori_pattern_add_edge(s.p, 6, 7, ORI_ASSIGN_BOUNDARY, 0.0);
    ori_error err;
    cr_assert_eq(ori_pattern_build(s.p, NULL, &err), ORI_OK, "%s", err.message);
    s.p0 = test_face_at(s.p, 0.5, 0.5);
    s.p1 = test_face_at(s.p, 1.5, 0.5);
    s.p2 = test_face_at(s.p, 2.5, 0.5);
    s.m = test_mechanism_of(s.p);
    return s;
}

// Fold first then second crease flat onto P1 (the later flap lands on top), then unfold the
// crease `undo` again.
static ori_collision_event strip3_run(strip3 *s, int first, int second, int undo)
{
    char json[768];
    snprintf(json, sizeof json,
             "{\"pattern\": \"s.fold\", \"folds\": ["
             "{\"fix\": %d, \"drive\": %d, \"to\": 180, \"step\": 10, \"lock\": [%d]},"
             "{\"fix\": %d, \"drive\": %d, \"to\": 180, \"step\": 10, \"lock\": [%d]},"
             "{\"fix\": %d, \"drive\": %d, \"to\": 0, \"step\": 10, \"lock\": [%d]}]}",
             s->p1, first, second, s->p1, second, first, s->p1, undo, undo == first ? second : first);
    ori_sequence *seq = NULL;
    ori_error err;
    cr_assert_eq(ori_sequence_parse(json, strlen(json), &seq, &err), ORI_OK, "%s", err.message);
    ori_record *r = NULL;
    cr_assert_eq(ori_sequence_run(seq, s->m, NULL, ori_rigid_identity(), &r, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_record_verdict(r), ORI_MOTION_VALID, "%s", ori_record_reason(r));
    ori_collider *c = collider_of(s->p, 0);
    // every recorded state alone is clean: the layers only ever touch
    int nv = ori_mechanism_vertex_count(s->m);
    for (int k = 0; k < ori_record_frame_count(r); ++k) {
        ori_collision_result res;
        cr_assert_eq(ori_collider_check(c, ori_record_frame_vertices(r, k), &res, &err), ORI_OK, "%s", err.message);
        cr_assert(!res.collides, "frame %d", k);
    }
    (void)nv;
    ori_collision_motion_def cd = ori_default_collision_motion_def();
    ori_collision_event ev;
    cr_assert_eq(check_record_both(c, r, &cd, &ev, &err), ORI_OK, "%s", err.message);
    ori_collider_destroy(c);
    ori_record_destroy(r);
    ori_sequence_destroy(seq);
    return ev;
}

Test(collision, a_layer_leaving_its_stack_through_the_layer_above_it_penetrates)
{
    strip3 s = strip3_make();
    // P2 folded onto P1 first, P0 on top of it: unfolding P2 takes it up through P0.
    ori_collision_event ev = strip3_run(&s, s.c2, s.c1, s.c2);
    cr_assert(ev.collides);
    cr_assert_eq(ev.fold, 2);
    cr_assert_eq(ev.step, 1);
    cr_assert_eq(ev.contact.kind, ORI_CONTACT_PENETRATING);
    cr_assert(ev.contact.stacked);
    cr_assert_eq(ev.contact.face_a, s.p0 < s.p2 ? s.p0 : s.p2);
    cr_assert_eq(ev.contact.face_b, s.p0 < s.p2 ? s.p2 : s.p0);
    // first contact right at the start of the unfolding (180°), to the drive tolerance
    cr_assert_float_eq(ev.drive_rad / DEG, 180.0, CONTACT_TOL_DEG);
    cr_assert_lt(ev.drive_rad / DEG, 180.0);
    cr_assert_float_eq(ev.contact.point.x, 1.5, 1e-6); // in the overlap of the two layers
    // P0 folded first, P2 on top: unfolding P2 lifts it off the top of the stack.
    ev = strip3_run(&s, s.c1, s.c2, s.c2);
    cr_assert(!ev.collides);
    ori_mechanism_destroy(s.m);
    ori_pattern_destroy(s.p);
}

// --- the broad phase finds what all pairs find; the cloud agrees with the exact clearance ------

// Brute force over all pairs with the same exact test: the contacts of ori_collider_check must
// be exactly these, and its least clearance the least exact distance.
static void compare_with_all_pairs(ori_collider *c, const ori_v3 *pos)
{
    ori_collision_result r = check_ok(c, pos);
    ori_error err;
    cr_assert_eq(col_state_prepare(c, pos, &err), ORI_OK);
    int nf = ori_collider_face_count(c), found = 0;
    double least = INFINITY;
    for (int f = 0; f < nf; ++f)
        for (int g = f + 1; g < nf; ++g) {
            bool adj = ori_collider_adjacent(c, f, g);
            col_pair_result pr;
            col_pair_test(c, f, g, col_adjacency_of(c, f, g), &pr);
            if (pr.cls != COL_APART) {
                found++;
                ori_contact k = find_contact(c, f, g);
                cr_assert_eq(k.kind == ORI_CONTACT_PENETRATING, pr.cls == COL_CROSS, "%d-%d", f, g);
            }
            if (!adj) {
                ori_v3 a, b;
                double d = pr.cls != COL_APART ? 0.0 : col_face_distance(c, f, g, INFINITY, &a, &b);
                least = fmin(least, d);
            }
        }
    cr_assert_eq(found, r.contact_count);
    cr_assert_float_eq(r.min_clearance, least, 0.0);
    cr_assert_lt(r.candidate_pairs, (int64_t)nf * (nf - 1) / 2 + 1);
}

Test(collision, the_broad_phase_misses_nothing_on_a_folding_miura)
{
    miura_fold x = miura_fold_make(6, 6, 15.0);
    ori_collider *c = collider_of(x.p, 0);
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)ori_mechanism_vertex_count(x.m));
    for (int k = 0; k < ori_motion_frame_count(x.mo); k += 3) {
        ori_motion_frame_vertices(x.mo, k, pos);
        compare_with_all_pairs(c, pos);
    }
    free(pos);
    ori_collider_destroy(c);
    miura_fold_free(&x);
}

// Deterministic pseudo-random numbers in [0, 1).
static double lcg(uint64_t *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / 9007199254740992.0;
}

Test(collision, the_broad_phase_misses_nothing_in_a_heap_of_triangles)
{
    uint64_t seed = 12345;
    for (int round = 0; round < 4; ++round) {
        scene s = scene_new();
        for (int t = 0; t < 60; ++t) {
            ori_v3 o = ori_v3_make(4 * lcg(&seed), 4 * lcg(&seed), 4 * lcg(&seed)), q[3];
            for (int i = 0; i < 3; ++i) q[i] = ori_v3_add(o, ori_v3_make(lcg(&seed) - 0.5, lcg(&seed) - 0.5, lcg(&seed) - 0.5));
            scene_face(&s, q, 3);
        }
        ori_collider *c = scene_collider(&s, 0);
        compare_with_all_pairs(c, s.pos);
        scene_free(&s, c);
    }
}

static void cloud_agrees(ori_collider *c, const ori_v3 *pos, double spacing)
{
    ori_collision_result r = check_ok(c, pos);
    cr_assert(isfinite(r.min_clearance));
    ori_cloud_def cd = ori_default_cloud_def();
    cd.spacing = spacing;
    cd.distance = r.min_clearance + 1.5 * spacing;
    ori_cloud_result cr;
    ori_error err;
    cr_assert_eq(ori_collider_cloud(c, pos, &cd, &cr, &err), ORI_OK, "%s", err.message);
    cr_assert_gt(cr.points, 0);
    cr_assert_gt(cr.point_pairs, 0);
    // never below the exact clearance (round-off aside), and above it by at most the spacing
    cr_assert_geq(cr.min_distance, r.min_clearance - 1e-12);
    cr_assert_leq(cr.min_distance, r.min_clearance + spacing, "cloud %g exact %g spacing %g", cr.min_distance,
                  r.min_clearance, spacing);
    // the face pair at the least sample distance is one the exact check measures as close
    bool found = false;
    for (int i = 0; i < ori_collider_cloud_pair_count(c); ++i) {
        ori_cloud_pair p = ori_collider_cloud_pair(c, i);
        cr_assert(!ori_collider_adjacent(c, p.face_a, p.face_b));
        cr_assert_float_eq(ori_v3_norm(ori_v3_sub(p.points[0], p.points[1])), p.distance, 1e-12);
        if (p.face_a == r.clearance_faces[0] && p.face_b == r.clearance_faces[1]) found = true;
    }
    cr_assert(found, "the exact clearance pair %d-%d is not in the cloud", r.clearance_faces[0], r.clearance_faces[1]);
}

Test(collision, the_cloud_of_proximity_agrees_with_the_exact_clearance_within_the_spacing)
{
    miura_fold x = miura_fold_make(4, 4, 30.0);
    ori_collider *c = collider_of(x.p, 0);
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)ori_mechanism_vertex_count(x.m));
    for (int k = 1; k < ori_motion_frame_count(x.mo) - 1; k += 2) { // 30°, 90°, 150°
        ori_motion_frame_vertices(x.mo, k, pos);
        cloud_agrees(c, pos, 0.1);
        cloud_agrees(c, pos, 0.05);
    }
    free(pos);
    ori_collider_destroy(c);
    miura_fold_free(&x);
    // the strip in its three regimes, halfway to contact
    double l2s[3] = {1.5, 3.0, 0.8}, l1s[3] = {2.0, 1.0, 1.0};
    for (int i = 0; i < 3; ++i) {
        strip s = strip_make(1.0, l1s[i], l2s[i]);
        ori_collider *cs = collider_of(s.p, 0);
        ori_motion *mo = NULL;
        ori_collision_event ev = strip_fold(&s, cs, &mo);
        (void)ev;
        ori_v3 sp[8];
        ori_motion_frame_vertices(mo, 10, sp);
        cloud_agrees(cs, sp, 0.05);
        ori_motion_destroy(mo);
        ori_collider_destroy(cs);
        strip_free(&s);
    }
}

Test(collision, the_cloud_refuses_bad_spacings)
{
    strip s = strip_make(1.0, 1.0, 1.0);
    ori_collider *c = collider_of(s.p, 0);
    ori_v3 pos[8];
    for (int v = 0; v < 8; ++v) pos[v] = ori_pattern_vertex(s.p, v);
    ori_cloud_def cd = ori_default_cloud_def();
    ori_cloud_result cr;
    ori_error err;
    cd.spacing = -0.1;
    cd.distance = 0.1;
    cr_assert_eq(ori_collider_cloud(c, pos, &cd, &cr, &err), ORI_ERR_RANGE);
    cr_assert(strstr(err.message, "spacing"), "%s", err.message);
    cd.spacing = 0.1;
    cd.distance = 0.0;
    cr_assert_eq(ori_collider_cloud(c, pos, &cd, &cr, &err), ORI_ERR_RANGE);
    cd.distance = 0.1;
    cd.spacing = 1e-5;
    cr_assert_eq(ori_collider_cloud(c, pos, &cd, &cr, &err), ORI_ERR_LIMIT);
    ori_collider_destroy(c);
    strip_free(&s);
}

// A hierarchy refitted to moved boxes gives every pair within the margin, each once: the same
// pairs as a fresh one and as all pairs (the incremental checker refits between rebuilds).
static bool count_pair(void *user, int a, int b)
{
    int *seen = user; // 64 × 64 counts
    cr_assert_lt(a, b);
    seen[a * 64 + b]++;
    return true;
}

Test(collision, a_refitted_hierarchy_gives_the_pairs_of_all_pairs)
{
    uint64_t seed = 99;
    col_box boxes[64];
    for (int i = 0; i < 64; ++i) {
        ori_v3 o = ori_v3_make(6 * lcg(&seed), 6 * lcg(&seed), 2 * lcg(&seed));
        boxes[i].lo = o;
        boxes[i].hi = ori_v3_add(o, ori_v3_make(lcg(&seed), lcg(&seed), lcg(&seed)));
    }
    col_bvh bvh;
    memset(&bvh, 0, sizeof bvh);
    col_bvh_build(&bvh, boxes, 64);
    static int seen[64 * 64];
    for (int round = 0; round < 12; ++round) {
        // every box moves and grows or shrinks: far, in some rounds, from where it was built
        double travel = round < 6 ? 0.3 : 3.0;
        for (int i = 0; i < 64; ++i) {
            ori_v3 d = ori_v3_make(travel * (lcg(&seed) - 0.5), travel * (lcg(&seed) - 0.5), travel * (lcg(&seed) - 0.5));
            boxes[i].lo = ori_v3_add(boxes[i].lo, d);
            boxes[i].hi = ori_v3_add(boxes[i].hi, ori_v3_add(d, ori_v3_make(0.2 * (lcg(&seed) - 0.3), 0.0, 0.0)));
            if (boxes[i].hi.x < boxes[i].lo.x) boxes[i].hi.x = boxes[i].lo.x;
        }
        col_bvh_refit(&bvh, boxes);
        double margin = 0.05 * round;
        memset(seen, 0, sizeof seen);
        col_bvh_self_pairs(&bvh, margin, count_pair, seen);
        int near = 0;
        for (int a = 0; a < 64; ++a)
            for (int b = a + 1; b < 64; ++b) {
                bool want = col_box_near(&boxes[a], &boxes[b], margin);
                near += want;
                cr_assert_eq(seen[a * 64 + b], want ? 1 : 0, "round %d: pair %d %d seen %d times", round, a, b,
                             seen[a * 64 + b]);
            }
        cr_assert_gt(near, 10, "round %d: %d pairs", round, near);
    }
    col_bvh_free(&bvh);
}

// --- the incremental motion checker against the reference on random motions ------------------

// Random two-flap strips (flap lengths, the standing flap's angle, the drive's end, the step and
// the clearance drawn): folds (one drive), the same folds as sequences, and both creases driven
// together (a multifold). Many collide (penetrating, or nearer than the clearance), found by
// bisection after half steps; the rest are clean. Every check is compared with the reference.
Test(collision, the_incremental_checker_agrees_with_the_reference_on_random_strips)
{
    uint64_t seed = 28;
    int collided = 0, clean = 0;
    motions_compared = 0;
    for (int trial = 0; trial < 24; ++trial) {
        double g = 0.5 + lcg(&seed), l1 = 0.5 + 2.0 * lcg(&seed), l2 = 0.5 + 2.5 * lcg(&seed);
        double stand = 30.0 + 120.0 * lcg(&seed), to = 100.0 + 80.0 * lcg(&seed), step = 3.0 + 57.0 * lcg(&seed);
        double clearance = trial % 3 == 0 ? 0.05 * lcg(&seed) : 0.0;
        strip s = strip_make(g, l1, l2);
        ori_collider *c = collider_of(s.p, clearance);
        ori_error err;
        // a fold: the left flap standing, the right one driven
        double *start = calloc((size_t)ori_mechanism_edge_count(s.m), sizeof(double));
        start[s.left_crease] = stand * DEG;
        ori_motion_def d = ori_default_motion_def();
        d.fixed_face = s.middle;
        d.start_angles_rad = start;
        d.driven_edge = s.right_crease;
        d.to_rad = to * DEG;
        d.step_rad = step * DEG;
        d.locked_edges = &s.left_crease;
        d.locked_count = 1;
        ori_motion *mo = NULL;
        cr_assert_eq(ori_motion_solve(s.m, &d, &mo, &err), ORI_OK, "%s", err.message);
        ori_collision_motion_def cd = ori_default_collision_motion_def();
        ori_collision_event ev;
        cr_assert_eq(check_motion_both(c, s.m, &d, mo, &cd, &ev, &err), ORI_OK, "%s", err.message);
        collided += ev.collides;
        clean += !ev.collides;
        ori_motion_destroy(mo);
        // the same as a sequence
        char json[512];
        snprintf(json, sizeof json,
                 "{\"pattern\": \"strip.fold\", \"folds\": [{\"fix\": %d, \"drive\": %d, \"to\": %.6f, \"step\": %.6f, "
                 "\"lock\": [%d]}, {\"fix\": %d, \"drive\": %d, \"to\": %.6f, \"step\": %.6f, \"lock\": [%d]}]}",
                 s.middle, s.left_crease, stand, step, s.right_crease, s.middle, s.right_crease, to, step, s.left_crease);
        ori_sequence *seq = NULL;
        cr_assert_eq(ori_sequence_parse(json, strlen(json), &seq, &err), ORI_OK, "%s", err.message);
        ori_record *r = NULL;
        cr_assert_eq(ori_sequence_run(seq, s.m, NULL, ori_rigid_identity(), &r, &err), ORI_OK, "%s", err.message);
        cr_assert_eq(check_record_both(c, r, &cd, &ev, &err), ORI_OK, "%s", err.message);
        collided += ev.collides;
        clean += !ev.collides;
        ori_record_destroy(r);
        ori_sequence_destroy(seq);
        // both flaps driven together
        int drives[2] = {s.left_crease, s.right_crease};
        double tos[2] = {stand * DEG, to * DEG};
        ori_drives_fold_def dd = ori_default_drives_fold_def();
        dd.fixed_face = s.middle;
        dd.driven_edges = drives;
        dd.to_rad = tos;
        dd.driven_count = 2;
        dd.step_rad = step * DEG;
        ori_multifold *mf = NULL;
        cr_assert_eq(ori_drives_fold_solve(s.m, &dd, &mf, &err), ORI_OK, "%s", err.message);
        if (ori_multifold_frame_count(mf) > 1) {
            cr_assert_eq(check_multifold_both(c, mf, NULL, 0, &cd, &ev, &err), ORI_OK, "%s", err.message);
            collided += ev.collides;
            clean += !ev.collides;
        }
        ori_multifold_destroy(mf);
        free(start);
        ori_collider_destroy(c);
        strip_free(&s);
    }
    cr_assert_geq(motions_compared, 60);
    cr_assert_gt(collided, 10, "%d of the random strip motions collide", collided);
    cr_assert_gt(clean, 10, "%d of the random strip motions are clean", clean);
}

// Random small Miura-ori (rows, columns, sides and angle drawn) folded by a drawn crease toward
// ±180° with drawn steps and fixed faces: stacked layers at the end (the orders kept from step to
// step), and with a clearance, collisions of faces coming nearer than it.
Test(collision, the_incremental_checker_agrees_with_the_reference_on_random_miura_folds)
{
    uint64_t seed = 1728;
    int collided = 0, clean = 0;
    motions_compared = 0;
    for (int trial = 0; trial < 16; ++trial) {
        int rows = 2 + (int)(3.0 * lcg(&seed)), cols = 2 + (int)(3.0 * lcg(&seed));
        double a = 0.7 + 0.6 * lcg(&seed), b = 0.7 + 0.6 * lcg(&seed), gamma = (45.0 + 35.0 * lcg(&seed)) * DEG;
        ori_pattern *p = test_miura(rows, cols, a, b, gamma, NULL);
        ori_mechanism *m = test_mechanism_of(p);
        int i = cols / 2, j = rows / 2;
        int drive = ori_pattern_find_edge(p, j * (cols + 1) + i, (j + 1) * (cols + 1) + i);
        cr_assert_neq(drive, ORI_NULL_INDEX);
        double sg = ori_pattern_edge(p, drive).assignment == ORI_ASSIGN_VALLEY ? 1.0 : -1.0;
        ori_motion_def d = ori_default_motion_def();
        d.fixed_face = (int)(lcg(&seed) * ori_mechanism_face_count(m));
        d.driven_edge = drive;
        d.to_rad = sg * (160.0 + 20.0 * lcg(&seed)) * DEG;
        d.step_rad = (4.0 + 26.0 * lcg(&seed)) * DEG;
        ori_motion *mo = NULL;
        ori_error err;
        cr_assert_eq(ori_motion_solve(m, &d, &mo, &err), ORI_OK, "%s", err.message);
        double clearance = trial % 3 ? 0.15 + 0.3 * lcg(&seed) : 0.0;
        ori_collider *c = collider_of(p, clearance);
        ori_collision_motion_def cd = ori_default_collision_motion_def();
        ori_collision_event ev;
        cr_assert_eq(check_motion_both(c, m, &d, mo, &cd, &ev, &err), ORI_OK, "%s", err.message);
        collided += ev.collides;
        clean += !ev.collides;
        ori_collider_destroy(c);
        ori_motion_destroy(mo);
        ori_mechanism_destroy(m);
        ori_pattern_destroy(p);
    }
    cr_assert_eq(motions_compared, 16);
    cr_assert_gt(collided, 3, "%d of the random Miura folds collide", collided);
    cr_assert_gt(clean, 1, "%d of the random Miura folds are clean", clean);
}

// Hundreds of steps: the incremental checker numbers the states it keeps sides for with 255
// ids and forgets the kept sides when they run out; across that, the events stay the
// reference's (a strip that collides at step 264, one that lands touching after 360, and a
// Miura-ori folded flat in 300 steps).
Test(collision, the_incremental_checker_agrees_with_the_reference_over_hundreds_of_steps)
{
    motions_compared = 0;
    double cases[2][3] = {{1.0, 2.0, 1.5}, {1.0, 1.0, 0.8}}; // g, l1, l2: collides at 131.8°; lands touching
    for (int k = 0; k < 2; ++k) {
        strip s = strip_make(cases[k][0], cases[k][1], cases[k][2]);
        ori_collider *c = collider_of(s.p, 0);
        double *start = calloc((size_t)ori_mechanism_edge_count(s.m), sizeof(double));
        start[s.left_crease] = 90 * DEG;
        ori_motion_def d = ori_default_motion_def();
        d.fixed_face = s.middle;
        d.start_angles_rad = start;
        d.driven_edge = s.right_crease;
        d.to_rad = 180 * DEG;
        d.step_rad = 0.5 * DEG;
        d.locked_edges = &s.left_crease;
        d.locked_count = 1;
        ori_motion *mo = NULL;
        ori_error err;
        cr_assert_eq(ori_motion_solve(s.m, &d, &mo, &err), ORI_OK, "%s", err.message);
        cr_assert_eq(ori_motion_frame_count(mo), 361);
        ori_collision_motion_def cd = ori_default_collision_motion_def();
        ori_collision_event ev;
        cr_assert_eq(check_motion_both(c, s.m, &d, mo, &cd, &ev, &err), ORI_OK, "%s", err.message);
        cr_assert_eq(ev.collides, k == 0);
        if (k == 0) {
            cr_assert_eq(ev.frame, 264); // 131.5° clean, 132° collides
            cr_assert_float_eq(ev.drive_rad / DEG, acos(-1.0 / 1.5) / DEG, CONTACT_TOL_DEG);
        }
        ori_motion_destroy(mo);
        free(start);
        ori_collider_destroy(c);
        strip_free(&s);
    }
    miura_fold x = miura_fold_make(3, 3, 0.6);
    ori_collider *c = collider_of(x.p, 0);
    cr_assert_gt(ori_motion_frame_count(x.mo), 255);
    ori_collision_motion_def cd = ori_default_collision_motion_def();
    ori_collision_event ev;
    ori_error err;
    cr_assert_eq(check_motion_both(c, x.m, &x.d, x.mo, &cd, &ev, &err), ORI_OK, "%s", err.message);
    cr_assert(!ev.collides);
    ori_collider_destroy(c);
    miura_fold_free(&x);
    cr_assert_eq(motions_compared, 3);
}
