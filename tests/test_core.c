// Core: status table, error formatting, counted allocator, arena, math (Rodrigues, twist
// exponential), robust orientation.
#include <float.h>

#include "core/core_internal.h"
#include "support.h"

TestSuite(core, .init = test_leak_setup, .fini = test_leak_check);

Test(core, status_table_names_and_messages)
{
    cr_assert_eq(ORI_OK, 0);
    cr_assert_str_eq(ori_status_name(ORI_ERR_PARSE), "ERR_PARSE");
    cr_assert_str_eq(ori_status_message(ORI_ERR_CROSSING), "edges cross without a shared vertex");
    cr_assert_str_eq(ori_status_name((ori_status)999), "UNKNOWN");
    for (int s = 0; s < ORI_STATUS_COUNT; ++s) cr_assert(strlen(ori_status_message((ori_status)s)) > 0);
}

Test(core, error_format_prefers_position_then_element)
{
    ori_error e;
    char buf[256];
    ori__fail_pos(&e, ORI_ERR_PARSE, 3, 7, "unexpected '}'");
    cr_assert_str_eq(ori_error_format(&e, buf, sizeof buf), "line 3, column 7: unexpected '}'");
    ori__fail_at(&e, ORI_ERR_RANGE, "edges_vertices", 12, "vertex index 99 out of range");
    cr_assert_str_eq(ori_error_format(&e, buf, sizeof buf), "edges_vertices 12: vertex index 99 out of range");
    ori__fail(&e, ORI_ERR_IO, "cannot open");
    cr_assert_str_eq(ori_error_format(&e, buf, sizeof buf), "cannot open");
    cr_assert_eq(e.element, ORI_NULL_INDEX);
}

Test(core, counted_allocator_tracks_live_and_peak)
{
    int64_t base = ori_alloc_live_bytes();
    ori_alloc_reset_peak();
    void *a = ori__alloc(1000);
    void *b = ori__alloc(24);
    cr_assert_eq(ori_alloc_live_count(), 2);
    cr_assert_eq(ori_alloc_live_bytes() - base, 1024);
    a = ori__realloc(a, 4000);
    cr_assert_eq(ori_alloc_live_bytes() - base, 4024);
    cr_assert_geq(ori_alloc_peak_bytes() - base, 5024); // old and new block briefly coexist
    ori__free(a);
    ori__free(b);
    cr_assert_eq(ori_alloc_live_bytes(), base);
}

Test(core, growable_array_and_arena)
{
    int *arr = NULL, n = 0, cap = 0;
    for (int i = 0; i < 10000; ++i) ORI__PUSH(arr, n, cap, i * 3);
    cr_assert_eq(n, 10000);
    cr_assert_eq(arr[9999], 29997);
    cr_assert_geq(cap, 10000);
    ori__free(arr);

    ori__arena arena;
    ori__arena_init(&arena, 256);
    double *x = ORI__ARENA_NEW(&arena, double, 10);
    double *y = ORI__ARENA_NEW(&arena, double, 1000); // larger than a block
    cr_assert_eq((uintptr_t)x % 16, 0);
    cr_assert_eq((uintptr_t)y % 16, 0);
    cr_assert_eq(y[999], 0.0);
    ori__arena_reset(&arena);
}

Test(core, rodrigues_rotation_is_orthonormal_and_right_handed)
{
    ori_v3 k = ori_v3_normalize(ori_v3_make(1, 1, 0));
    ori_m3 r = ori_m3_rotation(k, ORI_PI / 2);
    // (0,1,0) about (1,1,0)/√2 by 90° → (0.5, 0.5, 1/√2) (the thesis' end effector)
    ori_v3 p = ori_m3_apply(r, ori_v3_make(0, 1, 0));
    cr_assert_float_eq(p.x, 0.5, 4 * DBL_EPSILON);
    cr_assert_float_eq(p.y, 0.5, 4 * DBL_EPSILON);
    cr_assert_float_eq(p.z, 1 / sqrt(2.0), 4 * DBL_EPSILON);
    ori_m3 rt = ori_m3_mul(r, ori_m3_transpose(r));
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) cr_assert_float_eq(rt.m[i][j], i == j ? 1.0 : 0.0, 4 * DBL_EPSILON);
}

Test(core, twist_exponential_rotates_about_an_offset_axis)
{
    // Axis through q = (0, 1, 0) along x: the thesis' joint 2. A point on the axis is fixed;
    // (0, 2, 0) goes to (0, 1, 1) at +90° (right-hand rule).
    ori_twist xi = ori_twist_from_axis(ori_v3_make(0, 1, 0), ori_v3_make(1, 0, 0));
    ori_rigid g = ori_twist_exp(xi, ORI_PI / 2);
    ori_v3 a = ori_rigid_apply(g, ori_v3_make(5, 1, 0));
    ori_v3 b = ori_rigid_apply(g, ori_v3_make(0, 2, 0));
    cr_assert_float_eq(a.x, 5.0, 8 * DBL_EPSILON);
    cr_assert_float_eq(a.y, 1.0, 8 * DBL_EPSILON);
    cr_assert_float_eq(a.z, 0.0, 8 * DBL_EPSILON);
    cr_assert_float_eq(b.x, 0.0, 8 * DBL_EPSILON);
    cr_assert_float_eq(b.y, 1.0, 8 * DBL_EPSILON);
    cr_assert_float_eq(b.z, 1.0, 8 * DBL_EPSILON);
    // Composition with the inverse is the identity.
    ori_rigid id = ori_rigid_compose(g, ori_rigid_inverse(g));
    ori_v3 c = ori_rigid_apply(id, ori_v3_make(0.3, -2, 7));
    cr_assert_float_eq(c.y, -2.0, 16 * DBL_EPSILON);
    cr_assert_float_eq(c.z, 7.0, 16 * DBL_EPSILON);
}

Test(core, normalize_of_zero_is_zero_not_nan)
{
    ori_v3 z = ori_v3_normalize(ori_v3_make(0, 0, 0));
    cr_assert_eq(z.x, 0.0);
    cr_assert_eq(z.y, 0.0);
    cr_assert_eq(z.z, 0.0);
    ori_v2 w = ori_v2_normalize(ori_v2_make(0, 0));
    cr_assert_eq(w.x, 0.0);
    cr_assert_eq(ori_angle_ccw_v2(w, ori_v2_make(1, 0)), 0.0);
}

Test(core, orient2d_is_exact_on_nearly_collinear_points)
{
    ori_v2 a = {0.5, 0.5};
    // Points on the line y = x perturbed by one ulp: naive arithmetic loses the sign.
    for (int i = 0; i < 64; ++i) {
        double x = 0.5 + i * DBL_EPSILON;
        ori_v2 b = {12.0, 12.0}, c = {24.0, 24.0};
        ori_v2 p = {x, nextafter(x, 1.0)};
        cr_assert_eq(ori_orient2d_sign(a, b, c), 0);
        // p lies above y = x: counter-clockwise from (b → c)? orientation of (b, c, p) > 0
        cr_assert_eq(ori_orient2d_sign(b, c, p), 1, "i=%d", i);
        ori_v2 q = {x, nextafter(x, 0.0)};
        cr_assert_eq(ori_orient2d_sign(b, c, q), -1, "i=%d", i);
    }
    cr_assert_eq(ori_orient2d_sign((ori_v2){0, 0}, (ori_v2){1, 0}, (ori_v2){0, 1}), 1);
}

Test(core, angles_wrap)
{
    cr_assert_float_eq(ori_wrap_angle(3 * ORI_PI), ORI_PI, 1e-15);
    cr_assert_float_eq(ori_wrap_angle(-ORI_PI / 2 - 2 * ORI_PI), -ORI_PI / 2, 1e-14);
    cr_assert_float_eq(ori_angle_ccw_v2(ori_v2_make(1, 0), ori_v2_make(0, -1)), 1.5 * ORI_PI, 1e-15);
    cr_assert_float_eq(ori_angle_between_v3(ori_v3_make(1, 0, 0), ori_v3_make(0, 0, 2)), ORI_PI / 2, 1e-15);
}
