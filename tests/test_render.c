// Pictures of states (src/render): triangulation, camera, the depth order, PNG pixels measured,
// SVG parsed with libxml2 (crease styles; the open corner's occlusion), PDF through pdftoppm,
// GIF decoded with giflib, textures, stacking of faces folded flat, and bad input.
#define _POSIX_C_SOURCE 200809L
#include <cairo.h>
#include <gif_lib.h>
#include <jansson.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "render/render_internal.h"
#include "support.h"

TestSuite(render, .init = test_leak_setup, .fini = test_leak_check);

// --- helpers ----------------------------------------------------------------------------------

// A flat pattern from a polygon outline (boundary edges) plus creases between outline vertices
// or new points, built with faces traced.
static ori_pattern *polygon_sheet(const double (*xy)[2], int n)
{
    ori_pattern_def pd = ori_default_pattern_def();
    ori_pattern *p = ori_pattern_create(&pd);
    for (int i = 0; i < n; ++i) ori_pattern_add_vertex(p, ori_v3_make(xy[i][0], xy[i][1], 0));
    for (int i = 0; i < n; ++i) ori_pattern_add_edge(p, i, (i + 1) % n, ORI_ASSIGN_BOUNDARY, 0.0);
    return p;
}

static void build(ori_pattern *p)
{
    ori_error err;
    ori_build_def bd = ori_default_build_def();
    cr_assert_eq(ori_pattern_build(p, &bd, &err), ORI_OK, "%s", err.message);
}

// A strip of k unit squares along x (0..k × 0..1) with creases at x = 1 … k−1 of the given
// assignments.
static ori_pattern *strip(int k, const ori_assignment *creases)
{
    ori_pattern_def pd = ori_default_pattern_def();
    ori_pattern *p = ori_pattern_create(&pd);
    for (int i = 0; i <= k; ++i) ori_pattern_add_vertex(p, ori_v3_make(i, 0, 0));
    for (int i = 0; i <= k; ++i) ori_pattern_add_vertex(p, ori_v3_make(i, 1, 0));
    for (int i = 0; i < k; ++i) {
        ori_pattern_add_edge(p, i, i + 1, ORI_ASSIGN_BOUNDARY, 0.0);
        ori_pattern_add_edge(p, k + 1 + i, k + 2 + i, ORI_ASSIGN_BOUNDARY, 0.0);
    }
    ori_pattern_add_edge(p, 0, k + 1, ORI_ASSIGN_BOUNDARY, 0.0);
    ori_pattern_add_edge(p, k, 2 * k + 1, ORI_ASSIGN_BOUNDARY, 0.0);
    for (int i = 1; i < k; ++i) ori_pattern_add_edge(p, i, k + 1 + i, creases[i - 1], 0.0);
    build(p);
    return p;
}

// Pose fold angles (radians per edge) with face `fixed` in place; positions into pos.
static void pose(const ori_pattern *p, const double *angles, int fixed, ori_v3 *pos)
{
    ori_mechanism *m = test_mechanism_of(p);
    ori_error err;
    cr_assert_eq(ori_mechanism_pose_state(m, angles, fixed, ori_rigid_identity(), NULL, pos, NULL, &err), ORI_OK, "%s",
                 err.message);
    ori_mechanism_destroy(m);
}

static cairo_status_t read_png(void *closure, unsigned char *data, unsigned int length)
{
    const unsigned char **p = closure;
    memcpy(data, *p, length);
    *p += length;
    return CAIRO_STATUS_SUCCESS;
}

static cairo_surface_t *decode_png(const void *data)
{
    const unsigned char *p = data;
    cairo_surface_t *s = cairo_image_surface_create_from_png_stream(read_png, &p);
    cr_assert_eq(cairo_surface_status(s), CAIRO_STATUS_SUCCESS, "not a PNG");
    return s;
}

typedef struct rgb8 {
    int r, g, b;
} rgb8;

static rgb8 pixel(cairo_surface_t *s, int x, int y)
{
    cairo_surface_flush(s);
    const unsigned char *d = cairo_image_surface_get_data(s);
    uint32_t v = *(const uint32_t *)(d + (size_t)y * cairo_image_surface_get_stride(s) + 4 * (size_t)x);
    rgb8 c = {(v >> 16) & 255, (v >> 8) & 255, v & 255};
    return c;
}

static rgb8 to8(ori_rgb c, double k)
{
    rgb8 r = {(int)lround(255 * c.r * k), (int)lround(255 * c.g * k), (int)lround(255 * c.b * k)};
    return r;
}

static int dist2(rgb8 a, rgb8 b) { return (a.r - b.r) * (a.r - b.r) + (a.g - b.g) * (a.g - b.g) + (a.b - b.b) * (a.b - b.b); }

// Fraction of pixels nearest to colours[which] among colours[0..n-1].
static double fraction_nearest(cairo_surface_t *s, const rgb8 *colours, int n, int which)
{
    int w = cairo_image_surface_get_width(s), h = cairo_image_surface_get_height(s);
    long count = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            rgb8 p = pixel(s, x, y);
            int best = 0;
            for (int i = 1; i < n; ++i)
                if (dist2(p, colours[i]) < dist2(p, colours[best])) best = i;
            count += best == which;
        }
    return (double)count / ((double)w * h);
}

// The colours a test picture holds: background, front, back, then the lines (valley, mountain,
// boundary), so that line pixels are not counted as either side.
static int palette(const ori_render_def *d, rgb8 *c)
{
    c[0] = to8(d->background, 1);
    c[1] = to8(d->front, 1);
    c[2] = to8(d->back, 1);
    c[3] = (rgb8){0x1f, 0x5f, 0xd6};
    c[4] = (rgb8){0xd7, 0x19, 0x1c};
    c[5] = (rgb8){0x3a, 0x3a, 0x3a};
    return 6;
}

static ori_render_def top_def(int w, int h)
{
    ori_render_def d = ori_default_render_def();
    d.view = ORI_RENDER_3D;
    d.width = w;
    d.height = h;
    d.camera = ori_camera_preset(ORI_CAMERA_TOP, 0, 0, 0);
    d.shading = false;
    d.front = (ori_rgb){0.0, 0.75, 0.0};
    d.back = (ori_rgb){0.5, 0.0, 1.0};
    return d;
}

static cairo_surface_t *render_png(const ori_state_view *sv, const ori_render_def *d)
{
    void *data = NULL;
    size_t size = 0;
    ori_error err;
    cr_assert_eq(ori_render_image(sv, d, &data, &size, &err), ORI_OK, "%s", err.message);
    cairo_surface_t *s = decode_png(data);
    ori_buffer_free(data);
    cr_assert_eq(cairo_image_surface_get_width(s), d->width);
    cr_assert_eq(cairo_image_surface_get_height(s), d->height);
    return s;
}

// The open corner folded into the corner cube (the end of examples/open-corner.seq.json).
typedef struct corner {
    test_open_corner c;
    double angles[16];
    ori_v3 pos[16];
} corner;

static void corner_cube(corner *k, double t)
{
    k->c = test_open_corner_load();
    ori_sequence *s = NULL;
    ori_error err;
    cr_assert_eq(ori_sequence_load_file(test_repo_path("examples/open-corner.seq.json"), &s, &err), ORI_OK, "%s", err.message);
    ori_record *r = NULL;
    cr_assert_eq(ori_sequence_run(s, k->c.m, NULL, ori_rigid_identity(), &r, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_record_at(r, t, k->angles, k->pos, NULL, NULL, NULL, &err), ORI_OK, "%s", err.message);
    ori_record_destroy(r);
    ori_sequence_destroy(s);
}

// --- triangulation ------------------------------------------------------------------------------

// Twice the signed area of a triangle in the flat sheet.
static double tri_area2(const ori_mesh *m, ori_mesh_triangle t)
{
    ori_v3 a = ori_mesh_reference_vertex(m, t.v[0]), b = ori_mesh_reference_vertex(m, t.v[1]), c = ori_mesh_reference_vertex(m, t.v[2]);
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// A comb (non-convex, with collinear vertices on its base): n − 2 triangles, all
// counter-clockwise, areas summing to the polygon's, none containing another vertex.
Test(render, ear_clipping_triangulates_non_convex_faces)
{
    static const double comb[][2] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}, {5, 3}, {4, 3}, {4, 1}, {3, 1}, {3, 3},
                                     {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
    int n = (int)(sizeof comb / sizeof comb[0]);
    ori_pattern *p = polygon_sheet(comb, n);
    build(p);
    cr_assert_eq(ori_pattern_face_count(p), 1);
    ori_state_view sv = {p, NULL, NULL};
    ori_mesh *m = NULL;
    ori_error err;
    cr_assert_eq(ori_mesh_create(&sv, &m, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_mesh_triangle_count(m), n - 2);
    double area = 0.0;
    for (int t = 0; t < ori_mesh_triangle_count(m); ++t) {
        ori_mesh_triangle tr = ori_mesh_triangle_at(m, t);
        double a2 = tri_area2(m, tr);
        cr_assert_gt(a2, 0.0, "triangle %d is not counter-clockwise", t);
        area += 0.5 * a2;
        for (int v = 0; v < n; ++v) {
            if (v == tr.v[0] || v == tr.v[1] || v == tr.v[2]) continue;
            ori_v2 q = ori_v2_make(comb[v][0], comb[v][1]);
            ori_v2 a = ori_v2_make(comb[tr.v[0]][0], comb[tr.v[0]][1]), b = ori_v2_make(comb[tr.v[1]][0], comb[tr.v[1]][1]),
                   c = ori_v2_make(comb[tr.v[2]][0], comb[tr.v[2]][1]);
            bool inside = ori_orient2d_sign(a, b, q) > 0 && ori_orient2d_sign(b, c, q) > 0 && ori_orient2d_sign(c, a, q) > 0;
            cr_assert(!inside, "triangle %d holds vertex %d", t, v);
        }
    }
    // Area of the comb: 5 × 3 minus two 1 × 2 notches = 11 (exact in binary).
    cr_assert_eq(area, 11.0);
    cr_assert_eq(ori_mesh_area(m), 11.0);
    ori_v3 nrm = ori_mesh_face_normal(m, 0);
    cr_assert_eq(nrm.z, 1.0);
    ori_mesh_destroy(m);
    ori_pattern_destroy(p);
}

// A face listed clockwise in the flat sheet keeps +z as its front: its triangles turn
// counter-clockwise seen from +z.
Test(render, clockwise_faces_face_up)
{
    static const double sq[][2] = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    ori_pattern *p = polygon_sheet(sq, 4);
    int f[4] = {0, 1, 2, 3};
    ori_pattern_add_face(p, f, 4);
    build(p);
    ori_state_view sv = {p, NULL, NULL};
    ori_mesh *m = NULL;
    ori_error err;
    cr_assert_eq(ori_mesh_create(&sv, &m, &err), ORI_OK, "%s", err.message);
    for (int t = 0; t < ori_mesh_triangle_count(m); ++t) cr_assert_gt(tri_area2(m, ori_mesh_triangle_at(m, t)), 0.0);
    cr_assert_eq(ori_mesh_face_normal(m, 0).z, 1.0);
    ori_mesh_destroy(m);
    ori_pattern_destroy(p);
}

// The rigid pose of a face from positions reproduces them; a stretched face is refused.
Test(render, face_pose_from_positions)
{
    corner k;
    corner_cube(&k, 0.5);
    ori_state_view sv = {k.c.p, k.pos, k.angles};
    ori_mesh *m = NULL;
    ori_error err;
    cr_assert_eq(ori_mesh_create(&sv, &m, &err), ORI_OK, "%s", err.message);
    for (int f = 0; f < ori_mesh_face_count(m); ++f) {
        ori_rigid g;
        cr_assert_eq(ori_mesh_face_pose(m, f, k.pos, &g, &err), ORI_OK, "%s", err.message);
        int first, n = ori_mesh_face_triangles(m, f, &first);
        for (int t = first; t < first + n; ++t)
            for (int i = 0; i < 3; ++i) {
                int v = ori_mesh_triangle_at(m, t).v[i];
                ori_v3 d = ori_v3_sub(ori_rigid_apply(g, ori_mesh_reference_vertex(m, v)), k.pos[v]);
                cr_assert_leq(ori_v3_norm(d), 1e-12, "face %d vertex %d", f, v);
            }
    }
    // Move a corner of the lower-left triangle (vertex (0, 0)) off its rigid place.
    ori_v3 bad[16];
    memcpy(bad, k.pos, sizeof bad);
    bad[test_vertex_at(k.c.p, 0, 0)].x += 0.1;
    ori_rigid g;
    cr_assert_eq(ori_mesh_face_pose(m, k.c.t2, bad, &g, &err), ORI_ERR_DEGENERATE);
    cr_assert_eq(err.element, k.c.t2);
    ori_mesh_destroy(m);
    test_open_corner_free(&k.c);
}

// --- camera ---------------------------------------------------------------------------------------

Test(render, camera_presets_and_fit)
{
    // Top: x right, y up (image y down); yaw 90° turns +x to where +y was.
    ori_camera c = ori_camera_preset(ORI_CAMERA_TOP, 0, 0, 0);
    ori_v3 o = ori_camera_project(&c, ori_v3_make(0, 0, 0)), x = ori_camera_project(&c, ori_v3_make(1, 0, 0)),
           y = ori_camera_project(&c, ori_v3_make(0, 1, 0)), z = ori_camera_project(&c, ori_v3_make(0, 0, 1));
    cr_assert_eq(x.x - o.x, 1.0);
    cr_assert_eq(y.y - o.y, -1.0);
    cr_assert_lt(z.z, o.z, "+z is nearer to a viewer above");
    ori_camera cy = ori_camera_preset(ORI_CAMERA_TOP, ORI_PI / 2, 0, 0);
    ori_v3 xt = ori_camera_project(&cy, ori_v3_make(1, 0, 0));
    cr_assert_leq(fabs(xt.x - 0.0), 1e-15);
    cr_assert_leq(fabs(xt.y + 1.0), 1e-15);
    // Front: z up; side: y right; bottom: y down.
    ori_camera f = ori_camera_preset(ORI_CAMERA_FRONT, 0, 0, 0);
    cr_assert_eq(ori_camera_project(&f, ori_v3_make(0, 0, 1)).y, -1.0);
    ori_camera s = ori_camera_preset(ORI_CAMERA_SIDE, 0, 0, 0);
    cr_assert_eq(ori_camera_project(&s, ori_v3_make(0, 1, 0)).x, 1.0);
    ori_camera b = ori_camera_preset(ORI_CAMERA_BOTTOM, 0, 0, 0);
    cr_assert_eq(ori_camera_project(&b, ori_v3_make(0, 1, 0)).y, 1.0);
    // Iso: the eye direction (1, −1, 1) projects onto the centre.
    ori_camera iso = ori_camera_preset(ORI_CAMERA_ISO, 0, 0, 0);
    ori_v3 e = ori_camera_project(&iso, ori_v3_make(1, -1, 1));
    cr_assert_leq(fabs(e.x) + fabs(e.y), 1e-15);
    // Fit: every point inside the image, the margin kept on the tight side.
    ori_v3 pts[4] = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
    ori_camera_fit(&c, pts, 4, 400, 300, 0.05);
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (int i = 0; i < 4; ++i) {
        ori_v3 q = ori_camera_project(&c, pts[i]);
        x0 = fmin(x0, q.x);
        x1 = fmax(x1, q.x);
        y0 = fmin(y0, q.y);
        y1 = fmax(y1, q.y);
    }
    cr_assert_leq(fabs(x0 - 15.0), 1e-9);
    cr_assert_leq(fabs(x1 - 385.0), 1e-9);
    cr_assert_leq(fabs((y0 + y1) / 2 - 150.0), 1e-9);
    // Perspective: the nearer of two equal segments is longer in the image.
    ori_camera p = ori_camera_preset(ORI_CAMERA_TOP, 0, 0, 0);
    p.perspective = true;
    ori_v3 box[2] = {{-1, -1, 0}, {1, 1, 1}};
    ori_camera_fit(&p, box, 2, 400, 400, 0.05);
    cr_assert_leq(fabs(p.distance - ORI_CAMERA_PERSPECTIVE_DISTANCE * 1.5), 1e-12); // radius |(2, 2, 1)| / 2
    double near = ori_camera_project(&p, ori_v3_make(1, 0, 1)).x - ori_camera_project(&p, ori_v3_make(0, 0, 1)).x;
    double far = ori_camera_project(&p, ori_v3_make(1, 0, 0)).x - ori_camera_project(&p, ori_v3_make(0, 0, 0)).x;
    cr_assert_gt(near, far);
}

// --- PNG, measured ------------------------------------------------------------------------------

// A flat 2 × 2 sheet seen from the top fills the fitted square: (300 − 2·15)² of 400 × 300
// pixels = 60.75 %, within 1 %.
Test(render, flat_sheet_from_the_top_fills_its_square)
{
    ori_pattern *p = test_load_pattern(test_repo_path("examples/patterns/open-corner.fold"), 0);
    ori_state_view sv = {p, NULL, NULL};
    ori_render_def d = top_def(400, 300);
    cairo_surface_t *s = render_png(&sv, &d);
    rgb8 colours[6];
    int nc = palette(&d, colours);
    double front = fraction_nearest(s, colours, nc, 1);
    cr_assert_leq(fabs(front - 270.0 * 270.0 / (400.0 * 300.0)), 0.01, "front fraction %.4f", front);
    cr_assert_leq(fraction_nearest(s, colours, nc, 2), 0.001, "no back side shows");
    // Inside, away from creases, the colour is exact.
    rgb8 c = pixel(s, 200 - 60, 150 - 60);
    cr_assert_eq(dist2(c, colours[1]), 0, "(%d,%d,%d)", c.r, c.g, c.b);
    cairo_surface_destroy(s);
    // With light: colour × (ambient + diffuse · l·z), l the light's unit vector.
    d.shading = true;
    s = render_png(&sv, &d);
    double lz = ORI_RENDER_LIGHT_Z / sqrt(ORI_RENDER_LIGHT_X * ORI_RENDER_LIGHT_X + ORI_RENDER_LIGHT_Y * ORI_RENDER_LIGHT_Y +
                                         ORI_RENDER_LIGHT_Z * ORI_RENDER_LIGHT_Z);
    rgb8 lit = to8(d.front, ORI_RENDER_AMBIENT + ORI_RENDER_DIFFUSE * lz);
    c = pixel(s, 200 - 60, 150 - 60);
    cr_assert_leq(dist2(c, lit), 3, "(%d,%d,%d) vs (%d,%d,%d)", c.r, c.g, c.b, lit.r, lit.g, lit.b);
    cairo_surface_destroy(s);
    ori_pattern_destroy(p);
}

// A 2 × 1 sheet folded 180° along its middle, seen from the top: a valley puts the folded half
// on top, showing its back; a mountain puts it underneath, and the front of the fixed half shows.
Test(render, half_folded_flat_shows_the_right_side)
{
    ori_assignment kinds[2] = {ORI_ASSIGN_VALLEY, ORI_ASSIGN_MOUNTAIN};
    for (int k = 0; k < 2; ++k) {
        ori_pattern *p = strip(2, &kinds[k]);
        int left = test_face_at(p, 0.5, 0.5), crease = test_edge_at(p, 1, 0, 1, 1);
        double angles[8] = {0};
        angles[crease] = k == 0 ? ORI_PI : -ORI_PI;
        ori_v3 pos[8];
        pose(p, angles, left, pos);
        ori_state_view sv = {p, pos, angles};
        ori_render_def d = top_def(400, 300);
        cairo_surface_t *s = render_png(&sv, &d);
        rgb8 colours[6];
        int nc = palette(&d, colours);
        double expect = 270.0 * 270.0 / (400.0 * 300.0);
        double shown = fraction_nearest(s, colours, nc, k == 0 ? 2 : 1), hidden = fraction_nearest(s, colours, nc, k == 0 ? 1 : 2);
        cr_assert_leq(fabs(shown - expect), 0.01, "%s: %.4f of the image shows the %s side", k ? "mountain" : "valley", shown,
                      k ? "front" : "back");
        cr_assert_leq(hidden, 0.002, "the other side shows on %.4f", hidden);
        rgb8 c = pixel(s, 200, 150);
        cr_assert_eq(dist2(c, colours[k == 0 ? 2 : 1]), 0);
        cairo_surface_destroy(s);
        ori_pattern_destroy(p);
    }
}

// A z-fold (valley then mountain, both 180°) stacks three panels: from the top the last panel's
// front shows, from below the first panel's back.
Test(render, z_fold_stacks_in_fold_order)
{
    ori_assignment kinds[2] = {ORI_ASSIGN_VALLEY, ORI_ASSIGN_MOUNTAIN};
    ori_pattern *p = strip(3, kinds);
    int first = test_face_at(p, 0.5, 0.5), last = test_face_at(p, 2.5, 0.5);
    double angles[12] = {0};
    angles[test_edge_at(p, 1, 0, 1, 1)] = ORI_PI;
    angles[test_edge_at(p, 2, 0, 2, 1)] = -ORI_PI;
    ori_v3 pos[8];
    pose(p, angles, first, pos);
    // All three panels lie on the unit square.
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) cr_assert(pos[v].x > -1e-12 && pos[v].x < 1 + 1e-12);
    (void)last;
    ori_state_view sv = {p, pos, angles};
    ori_render_def d = top_def(300, 300);
    rgb8 front = to8(d.front, 1), back = to8(d.back, 1);
    cairo_surface_t *s = render_png(&sv, &d);
    cr_assert_eq(dist2(pixel(s, 150, 150), front), 0, "from the top the third panel's front shows");
    cairo_surface_destroy(s);
    d.camera = ori_camera_preset(ORI_CAMERA_BOTTOM, 0, 0, 0);
    s = render_png(&sv, &d);
    cr_assert_eq(dist2(pixel(s, 150, 150), back), 0, "from below the first panel's back shows");
    cairo_surface_destroy(s);
    ori_pattern_destroy(p);
}

// A texture with four coloured quadrants lands on the matching quadrants of the flat sheet
// (its top-left at the sheet's top-left, y up in the sheet).
Test(render, texture_maps_by_flat_sheet_coordinates)
{
    cairo_surface_t *tex = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 2, 2);
    cairo_t *cr = cairo_create(tex);
    double q[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}}; // TL red, TR green, BL blue, BR yellow
    for (int i = 0; i < 4; ++i) {
        cairo_set_source_rgb(cr, q[i][0], q[i][1], q[i][2]);
        cairo_rectangle(cr, i % 2, i / 2, 1, 1);
        cairo_fill(cr);
    }
    cairo_destroy(cr);
    char *dir = test_tmpdir();
    char path[512];
    snprintf(path, sizeof path, "%s/tex.png", dir);
    cr_assert_eq(cairo_surface_write_to_png(tex, path), CAIRO_STATUS_SUCCESS);
    cairo_surface_destroy(tex);
    char *png = NULL;
    size_t png_size = 0;
    ori_error err;
    cr_assert_eq(ori_file_read_all(path, 1 << 20, &png, &png_size, &err), ORI_OK);
    static const double square[][2] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    ori_pattern *p = polygon_sheet(square, 4);
    build(p);
    ori_state_view sv = {p, NULL, NULL};
    ori_render_def d = top_def(300, 300);
    d.texture_png = png;
    d.texture_size = png_size;
    cairo_surface_t *s = render_png(&sv, &d);
    // Quadrant centres of the fitted 270-pixel square at (15, 15).
    int at[4][2] = {{82, 82}, {217, 82}, {82, 217}, {217, 217}};
    for (int i = 0; i < 4; ++i) {
        rgb8 c = pixel(s, at[i][0], at[i][1]);
        rgb8 want = {(int)(255 * q[i][0]), (int)(255 * q[i][1]), (int)(255 * q[i][2])};
        cr_assert_leq(dist2(c, want), 48, "quadrant %d: (%d,%d,%d)", i, c.r, c.g, c.b);
    }
    cairo_surface_destroy(s);
    // Not a PNG: refused.
    d.texture_png = "GIF89a not a png";
    d.texture_size = 16;
    void *data = NULL;
    size_t size = 0;
    cr_assert_eq(ori_render_image(&sv, &d, &data, &size, &err), ORI_ERR_PARSE);
    cr_assert_null(data);
    ori_buffer_free(png);
    ori_pattern_destroy(p);
    test_tmpdir_remove(dir);
}

// --- the depth order -------------------------------------------------------------------------------

// Depth of a piece's plane at image point q: affine in the image for an orthographic camera,
// 1/depth affine with perspective.
static double piece_depth(const ori__order *o, const ori__piece *pc, ori_v2 q, bool perspective)
{
    // The piece's largest-area corner triangle defines its plane in (x, y, depth).
    const ori_v3 *pt = o->points + pc->first;
    double best = 0.0;
    int bi = 1;
    for (int i = 1; i + 1 < pc->count; ++i) {
        double a = fabs((pt[i].x - pt[0].x) * (pt[i + 1].y - pt[0].y) - (pt[i].y - pt[0].y) * (pt[i + 1].x - pt[0].x));
        if (a > best) {
            best = a;
            bi = i;
        }
    }
    ori_v3 a = pt[0], b = pt[bi], c = pt[bi + 1];
    double det = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    double u = ((q.x - a.x) * (c.y - a.y) - (q.y - a.y) * (c.x - a.x)) / det;
    double v = ((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x)) / det;
    if (perspective) return 1.0 / (1.0 / a.z + u * (1.0 / b.z - 1.0 / a.z) + v * (1.0 / c.z - 1.0 / a.z));
    return a.z + u * (b.z - a.z) + v * (c.z - a.z);
}

// Intersection of two convex polygons (Sutherland–Hodgman); returns the count.
static int convex_clip(const ori_v2 *a, int na, const ori_v2 *b, int nb, ori_v2 *out)
{
    ori_v2 cur[64], nxt[64];
    int n = na;
    memcpy(cur, a, sizeof(ori_v2) * (size_t)na);
    double sb = 0;
    for (int i = 0; i < nb; ++i) sb += ori_v2_cross(b[i], b[(i + 1) % nb]);
    for (int e = 0; e < nb && n > 0; ++e) {
        ori_v2 p0 = b[e], p1 = b[(e + 1) % nb];
        int m = 0;
        for (int i = 0; i < n; ++i) {
            ori_v2 s = cur[i], t = cur[(i + 1) % n];
            double ds = (sb > 0 ? 1 : -1) * ori_v2_cross(ori_v2_sub(p1, p0), ori_v2_sub(s, p0));
            double dt = (sb > 0 ? 1 : -1) * ori_v2_cross(ori_v2_sub(p1, p0), ori_v2_sub(t, p0));
            if (ds >= 0) nxt[m++] = s;
            if ((ds >= 0) != (dt >= 0)) nxt[m++] = ori_v2_add(s, ori_v2_scale(ori_v2_sub(t, s), ds / (ds - dt)));
        }
        n = m;
        memcpy(cur, nxt, sizeof(ori_v2) * (size_t)n);
    }
    memcpy(out, cur, sizeof(ori_v2) * (size_t)n);
    return n;
}

// Every pair of pieces overlapping in the image (more than 1e-6 of a square pixel) is drawn
// back to front: the later piece is not farther at a point inside the overlap. Pieces must be
// convex (Miura faces and triangles are). Returns the number of overlapping pairs checked.
static int check_order(const ori__order *o, double tol, bool perspective)
{
    int pairs = 0;
    for (int i = 0; i < o->piece_count; ++i) {
        const ori__piece *a = &o->pieces[i];
        ori_v2 pa[32];
        for (int k = 0; k < a->count; ++k) pa[k] = ori_v2_make(o->points[a->first + k].x, o->points[a->first + k].y);
        for (int j = i + 1; j < o->piece_count; ++j) {
            const ori__piece *b = &o->pieces[j];
            if (a->face == b->face) continue;
            ori_v2 pb[32], ov[64];
            for (int k = 0; k < b->count; ++k) pb[k] = ori_v2_make(o->points[b->first + k].x, o->points[b->first + k].y);
            int n = convex_clip(pa, a->count, pb, b->count, ov);
            if (n < 3) continue;
            double ar = 0;
            for (int k = 0; k < n; ++k) ar += ori_v2_cross(ov[k], ov[(k + 1) % n]);
            if (fabs(ar) < 2e-6) continue;
            ori_v2 q = {0, 0};
            for (int k = 0; k < n; ++k) q = ori_v2_add(q, ov[k]);
            q = ori_v2_scale(q, 1.0 / n);
            pairs++;
            double da = piece_depth(o, a, q, perspective), db = piece_depth(o, b, q, perspective);
            cr_assert_leq(db, da + tol, "piece %d (face %d) drawn after piece %d (face %d) but behind it: %.17g > %.17g", j,
                          b->face, i, a->face, db, da);
        }
    }
    return pairs;
}

// A 4 × 4 Miura-ori folded to 150° (every crease moving) seen from 40 directions, orthographic
// and in perspective: every overlapping pair of faces is painted back to front.
Test(render, miura_faces_are_painted_back_to_front)
{
    ori_pattern *p = test_miura(4, 4, 1.0, 1.0, ori_deg_to_rad(60.0), NULL);
    ori_mechanism *m = test_mechanism_of(p);
    int drive = ori_pattern_find_edge(p, 2 * 5 + 2, 3 * 5 + 2);
    double sg = ori_pattern_edge(p, drive).assignment == ORI_ASSIGN_VALLEY ? 1.0 : -1.0;
    ori_motion_def d = ori_default_motion_def();
    d.driven_edge = drive;
    d.to_rad = sg * ori_deg_to_rad(150.0);
    d.step_rad = ori_deg_to_rad(150.0);
    ori_motion *mo = NULL;
    ori_error err;
    cr_assert_eq(ori_motion_solve(m, &d, &mo, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_VALID, "%s", ori_motion_reason(mo));
    int last = ori_motion_frame_count(mo) - 1;
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)ori_pattern_vertex_count(p));
    ori_motion_frame_vertices(mo, last, pos);
    ori_state_view sv = {p, pos, ori_motion_frame_angles(mo, last)};
    ori_mesh *mesh = NULL;
    cr_assert_eq(ori_mesh_create(&sv, &mesh, &err), ORI_OK);
    int checked = 0;
    for (int view = 0; view < 2 * 5 * 8; ++view) {
        bool persp = view >= 40;
        int preset = (view / 8) % 5, yaw = 45 * (view % 8);
        ori_camera c = ori_camera_preset((ori_camera_preset_kind)preset, ori_deg_to_rad(yaw), ori_deg_to_rad(20), 0);
        c.perspective = persp;
        ori_v3 pts[64];
        int n = ori_mesh_vertex_count(mesh);
        for (int v = 0; v < n; ++v) pts[v] = ori_mesh_vertex(mesh, v);
        ori_camera_fit(&c, pts, n, 800, 600, 0.05);
        ori__order o;
        ori__order_build(mesh, &c, NULL, 0, &o);
        cr_assert_eq(o.piece_count, ori_mesh_face_count(mesh), "no splitting needed");
        checked += check_order(&o, 1e-9, persp);
        ori__order_free(&o);
    }
    cr_assert_gt(checked, 100, "the views overlap faces (%d pairs checked)", checked);
    ori_mesh_destroy(mesh);
    free(pos);
    ori_motion_destroy(mo);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

// Three long panels overlapping like a pinwheel (each above the next, the last above the
// first) have no back-to-front order: the cycle is split, and the pieces are then in order.
Test(render, cyclic_overlaps_are_split)
{
    ori_pattern_def pd = ori_default_pattern_def();
    ori_pattern *p = ori_pattern_create(&pd);
    // Panel k is a long thin rectangle rotated by 120° k about the z axis, tilted so that its
    // far end is high and its near end low.
    for (int k = 0; k < 3; ++k) {
        double a = 2.0 * ORI_PI * k / 3.0, c = cos(a), s = sin(a);
        double corners[4][3] = {{-3, -0.5, -0.5}, {3, -0.5, 0.5}, {3, 0.5, 0.5}, {-3, 0.5, -0.5}};
        int vs[4];
        for (int i = 0; i < 4; ++i) {
            double x = corners[i][0], y = corners[i][1] + 1.2;
            vs[i] = ori_pattern_add_vertex(p, ori_v3_make(c * x - s * y, s * x + c * y, corners[i][2]));
        }
        for (int i = 0; i < 4; ++i) ori_pattern_add_edge(p, vs[i], vs[(i + 1) % 4], ORI_ASSIGN_BOUNDARY, 0.0);
        ori_pattern_add_face(p, vs, 4);
    }
    ori_pattern_set_folded_form(p, true);
    build(p);
    ori_state_view sv = {p, NULL, NULL};
    ori_mesh *mesh = NULL;
    ori_error err;
    cr_assert_eq(ori_mesh_create(&sv, &mesh, &err), ORI_OK, "%s", err.message);
    ori_camera c = ori_camera_preset(ORI_CAMERA_TOP, 0, 0, 0);
    ori_v3 pts[12];
    for (int v = 0; v < 12; ++v) pts[v] = ori_mesh_vertex(mesh, v);
    ori_camera_fit(&c, pts, 12, 600, 600, 0.05);
    ori__order o;
    ori__order_build(mesh, &c, NULL, 0, &o);
    cr_assert_eq(o.groups_split, 1, "the three panels form one cycle");
    cr_assert_gt(o.piece_count, 3, "and are split into %d pieces", o.piece_count);
    cr_assert_gt(check_order(&o, 1e-9, false), 3);
    ori__order_free(&o);
    ori_mesh_destroy(mesh);
    ori_pattern_destroy(p);
}

// --- SVG and PDF --------------------------------------------------------------------------------

typedef struct svg_path {
    char style[512];
    ori_v2 pt[64];
    int n;
} svg_path;

static void collect_paths(xmlNodePtr node, svg_path *out, int cap, int *n)
{
    for (; node; node = node->next) {
        if (node->type != XML_ELEMENT_NODE) continue;
        if (strcmp((const char *)node->name, "defs") == 0) continue;
        if (strcmp((const char *)node->name, "path") == 0) {
            if (*n >= cap) continue;
            xmlChar *st = xmlGetProp(node, (const xmlChar *)"style"), *d = xmlGetProp(node, (const xmlChar *)"d");
            svg_path *sp = &out[(*n)++];
            snprintf(sp->style, sizeof sp->style, "%s", st ? (const char *)st : "");
            sp->n = 0;
            const char *c = d ? (const char *)d : "";
            while (*c) {
                double x, y;
                int used;
                if ((*c == 'M' || *c == 'L') && sscanf(c + 1, "%lf %lf%n", &x, &y, &used) == 2) {
                    if (sp->n < 64) sp->pt[sp->n++] = ori_v2_make(x, y);
                    c += 1 + used;
                } else {
                    c++;
                }
            }
            xmlFree(st);
            xmlFree(d);
        } else {
            collect_paths(node->children, out, cap, n);
        }
    }
}

// Every <path> of an SVG document, in drawing order: its style and the points of its d; the
// viewBox size into w, h.
static int svg_paths(const void *data, size_t size, svg_path *out, int cap, double *w, double *h)
{
    xmlDocPtr doc = xmlReadMemory(data, (int)size, "x.svg", NULL, XML_PARSE_NONET);
    cr_assert_not_null(doc, "the SVG parses");
    xmlNodePtr root = xmlDocGetRootElement(doc);
    cr_assert_str_eq((const char *)root->name, "svg");
    xmlChar *vb = xmlGetProp(root, (const xmlChar *)"viewBox");
    cr_assert_not_null(vb);
    double x0, y0;
    cr_assert_eq(sscanf((const char *)vb, "%lf %lf %lf %lf", &x0, &y0, w, h), 4);
    xmlFree(vb);
    int n = 0;
    collect_paths(root->children, out, cap, &n);
    xmlFreeDoc(doc);
    return n;
}

// The crease view follows the thesis' line styles: the open corner's one mountain is a red
// dash-dot line (four dash values), its four valleys blue dashed lines (two), its boundary one
// solid black path, and its degree-5 centre is ringed as not flat-foldable.
Test(render, crease_view_svg_has_thesis_line_styles)
{
    ori_pattern *p = test_load_pattern(test_repo_path("examples/patterns/open-corner.fold"), 0);
    ori_state_view sv = {p, NULL, NULL};
    ori_render_def d = ori_default_render_def();
    d.format = ORI_IMAGE_SVG;
    void *data = NULL;
    size_t size = 0;
    ori_error err;
    cr_assert_eq(ori_render_image(&sv, &d, &data, &size, &err), ORI_OK, "%s", err.message);
    static svg_path paths[256];
    double w, h;
    int n = svg_paths(data, size, paths, 256, &w, &h);
    cr_assert_eq(w, 800.0);
    cr_assert_eq(h, 600.0);
    int mountain = 0, valley = 0, boundary = 0, rings = 0;
    for (int i = 0; i < n; ++i) {
        const char *s = paths[i].style;
        const char *dash = strstr(s, "stroke-dasharray:");
        int values = 0;
        if (dash)
            for (const char *c = dash; *c && *c != ';'; ++c) values += *c == ',';
        if (strstr(s, "stroke:rgb(84.313725%,9.803922%,10.980392%)")) { // #d7191c
            cr_assert(dash && values == 3, "mountain: dash-dot (%s)", s);
            mountain++;
        } else if (strstr(s, "stroke:rgb(12.156863%,37.254902%,83.921569%)")) { // #1f5fd6
            cr_assert(dash && values == 1, "valley: dashed (%s)", s);
            valley++;
        } else if (strstr(s, "stroke:rgb(0%,0%,0%)")) {
            cr_assert(!dash, "boundary: solid");
            cr_assert_eq(paths[i].n, 16, "8 boundary segments in one path");
            boundary++;
        } else if (strstr(s, "stroke:rgb(100%,45%,0%)")) {
            rings++;
        }
    }
    cr_assert_eq(mountain, 1);
    cr_assert_eq(valley, 4);
    cr_assert_eq(boundary, 1);
    cr_assert_eq(rings, 1, "vertex 6 is not flat-foldable (degree 5)");
    ori_buffer_free(data);
    ori_pattern_destroy(p);
}

// The corner cube seen into the corner (yaw 90°): the SVG shows three faces of the cube — the
// floor and the two walls are the topmost paths at their centres — and no face is drawn in
// front of a face that hides it.
Test(render, corner_cube_svg_occlusion)
{
    corner k;
    corner_cube(&k, 2.0);
    ori_state_view sv = {k.c.p, k.pos, k.angles};
    ori_render_def d = ori_default_render_def();
    d.view = ORI_RENDER_3D;
    d.format = ORI_IMAGE_SVG;
    d.camera = ori_camera_preset(ORI_CAMERA_ISO, ORI_PI / 2, 0, 0);
    ori_camera cam;
    ori_error err;
    cr_assert_eq(ori_render_camera(&sv, &d, &cam, &err), ORI_OK);
    void *data = NULL;
    size_t size = 0;
    cr_assert_eq(ori_render_image(&sv, &d, &data, &size, &err), ORI_OK, "%s", err.message);
    static svg_path paths[256];
    double w, h;
    int n = svg_paths(data, size, paths, 256, &w, &h);
    // Face fills: match each filled path's points with a face's projected corners.
    int nf = ori_pattern_face_count(k.c.p);
    int face_of[256], fills = 0;
    for (int i = 0; i < n; ++i) {
        face_of[i] = -1;
        if (strstr(paths[i].style, "fill:none") || !strstr(paths[i].style, "fill:rgb")) continue;
        fills++;
        for (int f = 0; f < nf && face_of[i] < 0; ++f) {
            int fv[8], cnt = ori_pattern_face_vertices(k.c.p, f, fv, 8);
            bool all = true;
            for (int q = 0; q < cnt && all; ++q) {
                ori_v3 pr = ori_camera_project(&cam, k.pos[fv[q]]);
                bool found = false;
                for (int j = 0; j < paths[i].n; ++j)
                    found |= fabs(paths[i].pt[j].x - pr.x) < 0.01 && fabs(paths[i].pt[j].y - pr.y) < 0.01;
                all = found;
            }
            if (all && paths[i].n - 1 == cnt) face_of[i] = f;
        }
        cr_assert_geq(face_of[i], 0, "path %d is a whole face", i);
    }
    cr_assert_eq(fills, nf, "every face drawn once");
    // The topmost face at the centres of the floor and of the two walls.
    ori_v3 centres[3] = {{0.5, 0.5, 0.0}, {1.0, 0.5, 0.5}, {0.5, 1.0, 0.5}};
    int expect[3] = {k.c.ul, k.c.lr, k.c.ur}; // the floor's top layer is the upper-left square
    for (int c = 0; c < 3; ++c) {
        ori_v3 q = ori_camera_project(&cam, centres[c]);
        int top = -1;
        for (int i = 0; i < n; ++i) {
            if (face_of[i] < 0) continue;
            // Point in polygon (even-odd) for the path's closed outline.
            int m = paths[i].n - 1;
            bool in = false;
            for (int a = 0, b = m - 1; a < m; b = a++) {
                ori_v2 pa = paths[i].pt[a], pb = paths[i].pt[b];
                if ((pa.y > q.y) != (pb.y > q.y) && q.x < (pb.x - pa.x) * (q.y - pa.y) / (pb.y - pa.y) + pa.x) in = !in;
            }
            if (in) top = face_of[i];
        }
        cr_assert_eq(top, expect[c], "centre %d shows face %d, expected %d", c, top, expect[c]);
    }
    // No face in front of one that hides it: for every two overlapping face paths, the later
    // one is nearer at their overlap (the faces are convex).
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            if (face_of[i] < 0 || face_of[j] < 0) continue;
            ori_v2 ov[64];
            int m = convex_clip(paths[i].pt, paths[i].n - 1, paths[j].pt, paths[j].n - 1, ov);
            if (m < 3) continue;
            double ar = 0;
            for (int q = 0; q < m; ++q) ar += ori_v2_cross(ov[q], ov[(q + 1) % m]);
            if (fabs(ar) < 1e-3) continue;
            ori_v2 q = {0, 0};
            for (int t = 0; t < m; ++t) q = ori_v2_add(q, ov[t]);
            q = ori_v2_scale(q, 1.0 / m);
            // Depth of each face's plane along the view ray through q.
            double depth[2];
            int faces[2] = {face_of[i], face_of[j]};
            for (int s = 0; s < 2; ++s) {
                int fv[8];
                ori_pattern_face_vertices(k.c.p, faces[s], fv, 8);
                ori_v3 a = ori_camera_project(&cam, k.pos[fv[0]]), b = ori_camera_project(&cam, k.pos[fv[1]]),
                       c = ori_camera_project(&cam, k.pos[fv[2]]);
                double det = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
                double u = ((q.x - a.x) * (c.y - a.y) - (q.y - a.y) * (c.x - a.x)) / det;
                double v = ((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x)) / det;
                depth[s] = a.z + u * (b.z - a.z) + v * (c.z - a.z);
            }
            cr_assert_leq(depth[1], depth[0] + 1e-9, "face %d is drawn over face %d but lies behind it", faces[1], faces[0]);
        }
    ori_buffer_free(data);
    test_open_corner_free(&k.c);
}

// A PDF parses (pdftoppm renders it at 72 dpi to the right size) and shows the same picture as
// the PNG: the sheet covers the fitted square within 1 % of the page.
Test(render, pdf_renders_through_pdftoppm)
{
    if (system("command -v pdftoppm >/dev/null 2>&1") != 0) cr_skip("pdftoppm (poppler-utils) is not installed");
    ori_pattern *p = test_load_pattern(test_repo_path("examples/patterns/open-corner.fold"), 0);
    ori_state_view sv = {p, NULL, NULL};
    ori_render_def d = top_def(400, 300);
    char *dir = test_tmpdir();
    char pdf[512], cmd[2048], png[560];
    snprintf(pdf, sizeof pdf, "%s/sheet.pdf", dir);
    ori_error err;
    cr_assert_eq(ori_render_file(&sv, &d, pdf, &err), ORI_OK, "%s", err.message);
    snprintf(cmd, sizeof cmd, "pdftoppm -png -r 72 -singlefile '%s' '%s/page' 2>&1", pdf, dir);
    cr_assert_eq(system(cmd), 0, "pdftoppm reads the PDF");
    snprintf(png, sizeof png, "%s/page.png", dir);
    cairo_surface_t *s = cairo_image_surface_create_from_png(png);
    cr_assert_eq(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
    cr_assert_eq(cairo_image_surface_get_width(s), 400);
    cr_assert_eq(cairo_image_surface_get_height(s), 300);
    // Paper (anything but the background) covers the fitted square; poppler draws thin lines
    // at least a pixel wide, so the sides are counted together with the creases on them.
    rgb8 colours[6];
    int nc = palette(&d, colours);
    double paper = 1.0 - fraction_nearest(s, colours, nc, 0);
    cr_assert_leq(fabs(paper - 270.0 * 270.0 / (400.0 * 300.0)), 0.01, "paper fraction %.4f", paper);
    cr_assert_leq(fraction_nearest(s, colours, nc, 2), 0.001, "no back side shows");
    cairo_surface_destroy(s);
    ori_pattern_destroy(p);
    test_tmpdir_remove(dir);
}

// --- GIF -----------------------------------------------------------------------------------------

typedef struct gif_frames {
    const ori_pattern *p;
    ori_v3 pos[5][16];
    double ang[5][16];
} gif_frames;

static ori_status gif_frame(int i, ori_state_view *out, void *user, ori_error *error)
{
    (void)error;
    gif_frames *g = user;
    out->pattern = g->p;
    out->positions = g->pos[i];
    out->fold_angles_rad = g->ang[i];
    return ORI_OK;
}

// Five frames of the corner-cube sequence: a looping GIF of the right size whose delays add up
// to the frames' time plus the final hold, and whose last frame shows the cube (its centre is
// not background).
Test(render, gif_animation_decodes)
{
    corner k;
    corner_cube(&k, 0.0);
    gif_frames g;
    g.p = k.c.p;
    ori_sequence *s = NULL;
    ori_error err;
    cr_assert_eq(ori_sequence_load_file(test_repo_path("examples/open-corner.seq.json"), &s, &err), ORI_OK);
    ori_record *r = NULL;
    cr_assert_eq(ori_sequence_run(s, k.c.m, NULL, ori_rigid_identity(), &r, &err), ORI_OK);
    for (int i = 0; i < 5; ++i) cr_assert_eq(ori_record_at(r, 0.5 * i, g.ang[i], g.pos[i], NULL, NULL, NULL, &err), ORI_OK);
    ori_gif_def d = ori_default_gif_def();
    d.render.width = 160;
    d.render.height = 120;
    d.frame_count = 5;
    d.frame = gif_frame;
    d.user = &g;
    d.fps = 10.0;
    void *data = NULL;
    size_t size = 0;
    cr_assert_eq(ori_gif_write(&d, &data, &size, &err), ORI_OK, "%s", err.message);
    char *dir = test_tmpdir();
    char path[512];
    snprintf(path, sizeof path, "%s/a.gif", dir);
    cr_assert_eq(ori_file_write_atomic(path, data, size, &err), ORI_OK);
    int e = 0;
    GifFileType *gif = DGifOpenFileName(path, &e);
    cr_assert_not_null(gif);
    cr_assert_eq(DGifSlurp(gif), GIF_OK);
    cr_assert_eq(gif->SWidth, 160);
    cr_assert_eq(gif->SHeight, 120);
    cr_assert_eq(gif->ImageCount, 5);
    cr_assert_not_null(gif->SColorMap);
    int delay = 0;
    bool loops = false;
    for (int i = 0; i < gif->ImageCount; ++i) {
        GraphicsControlBlock gcb;
        cr_assert_eq(DGifSavedExtensionToGCB(gif, i, &gcb), GIF_OK);
        delay += gcb.DelayTime;
        for (int x = 0; x < gif->SavedImages[i].ExtensionBlockCount; ++x) {
            ExtensionBlock *b = &gif->SavedImages[i].ExtensionBlocks[x];
            if (b->Function == APPLICATION_EXT_FUNC_CODE && b->ByteCount == 11 && memcmp(b->Bytes, "NETSCAPE2.0", 11) == 0)
                loops = true;
        }
    }
    cr_assert_eq(delay, 50 + 100, "5 frames at 10 fps and a 1 s hold: %d cs", delay);
    cr_assert(loops, "the animation loops");
    // Composite the frames: the last one shows the corner cube.
    unsigned char canvas[160 * 120];
    memset(canvas, 0, sizeof canvas);
    for (int i = 0; i < gif->ImageCount; ++i) {
        GifImageDesc *id = &gif->SavedImages[i].ImageDesc;
        for (int y = 0; y < id->Height; ++y)
            for (int x = 0; x < id->Width; ++x)
                canvas[(y + id->Top) * 160 + x + id->Left] = gif->SavedImages[i].RasterBits[y * id->Width + x];
    }
    int paper = 0;
    for (int i = 0; i < 160 * 120; ++i) {
        GifColorType c = gif->SColorMap->Colors[canvas[i]];
        paper += !(c.Red > 250 && c.Green > 250 && c.Blue > 250);
    }
    cr_assert_gt(paper, 160 * 120 / 10, "the last frame shows the cube (%d paper pixels)", paper);
    DGifCloseFile(gif, &e);
    ori_buffer_free(data);
    // An animation takes its values frame by frame: one state's arrays are refused.
    double vals[5] = {0, 1, 2, 3, 4};
    d.render.values = (ori_value_map){vals, NULL, 0.0, 4.0};
    data = NULL;
    cr_assert_eq(ori_gif_write(&d, &data, &size, &err), ORI_ERR_ARGUMENT);
    cr_assert(strstr(err.message, "values"), "%s", err.message);
    cr_assert_null(data);
    ori_record_destroy(r);
    ori_sequence_destroy(s);
    test_open_corner_free(&k.c);
    test_tmpdir_remove(dir);
}

// Colour by value in an animation (animate --color): frame_values gives each frame's values under
// one bar (render.values' range). Two frames of the flat open corner, every face at the bar's
// bottom in the first and at its top in the second: decoded, each frame paints the faces its
// colour (within the 256-colour palette's rounding). Arrays in render.values, a frame giving
// both kinds or none, and a range that is not finite are refused.
typedef struct gif_valued {
    const ori_pattern *p;
    double lo[8], hi[8];
    int give; // 0 faces, 1 both, 2 none
} gif_valued;
static ori_status valued_frame(int index, ori_state_view *out, void *user, ori_error *error)
{
    (void)index, (void)error;
    out->pattern = ((gif_valued *)user)->p;
    out->positions = NULL;
    out->fold_angles_rad = NULL;
    return ORI_OK;
}
static ori_status valued_values(int index, const double **fv, const double **ev, void *user, ori_error *error)
{
    (void)error;
    gif_valued *g = user;
    if (g->give != 2) *fv = index == 0 ? g->lo : g->hi;
    if (g->give == 1) *ev = g->lo;
    return ORI_OK;
}
static long colour_count(const GifFileType *gif, const unsigned char *canvas, int n, rgb8 want)
{
    long hits = 0;
    for (int i = 0; i < n; ++i) {
        GifColorType c = gif->SColorMap->Colors[canvas[i]];
        rgb8 got = {c.Red, c.Green, c.Blue};
        hits += dist2(got, want) <= 12;
    }
    return hits;
}
Test(render, gif_frames_coloured_by_value_under_one_bar)
{
    gif_valued g;
    memset(&g, 0, sizeof g);
    g.p = test_load_pattern(test_repo_path("examples/patterns/open-corner.fold"), 0);
    cr_assert_leq(ori_pattern_face_count(g.p), 8);
    for (int f = 0; f < 8; ++f) g.lo[f] = 1.0, g.hi[f] = 3.0;
    ori_gif_def d = ori_default_gif_def();
    d.render.width = 200;
    d.render.height = 150;
    d.render.camera = ori_camera_preset(ORI_CAMERA_TOP, 0.0, 0.0, 0.0);
    d.frame_count = 2;
    d.frame = valued_frame;
    d.frame_values = valued_values;
    d.user = &g;
    d.render.values.min = 1.0;
    d.render.values.max = 3.0;
    void *data = NULL;
    size_t size = 0;
    ori_error err;
    cr_assert_eq(ori_gif_write(&d, &data, &size, &err), ORI_OK, "%s", err.message);
    char *dir = test_tmpdir();
    char path[512];
    snprintf(path, sizeof path, "%s/v.gif", dir);
    cr_assert_eq(ori_file_write_atomic(path, data, size, &err), ORI_OK);
    ori_buffer_free(data);
    int e = 0;
    GifFileType *gif = DGifOpenFileName(path, &e);
    cr_assert_not_null(gif);
    cr_assert_eq(DGifSlurp(gif), GIF_OK);
    cr_assert_eq(gif->ImageCount, 2);
    unsigned char canvas[200 * 150];
    memset(canvas, 0, sizeof canvas);
    long low[2], high[2];
    for (int i = 0; i < 2; ++i) {
        GifImageDesc *id = &gif->SavedImages[i].ImageDesc;
        for (int y = 0; y < id->Height; ++y)
            for (int x = 0; x < id->Width; ++x)
                canvas[(y + id->Top) * 200 + x + id->Left] = gif->SavedImages[i].RasterBits[y * id->Width + x];
        low[i] = colour_count(gif, canvas, 200 * 150, to8(ori_colormap(0.0), 1));
        high[i] = colour_count(gif, canvas, 200 * 150, to8(ori_colormap(1.0), 1));
    }
    DGifCloseFile(gif, &e);
    // The sheet covers a good part of the picture; the bar shows both colours in both frames.
    cr_assert_gt(low[0], high[0] + 200 * 150 / 10, "frame 0: %ld bottom-colour pixels, %ld top", low[0], high[0]);
    cr_assert_gt(high[1], low[1] + 200 * 150 / 10, "frame 1: %ld top-colour pixels, %ld bottom", high[1], low[1]);
    g.give = 1;
    cr_assert_eq(ori_gif_write(&d, &data, &size, &err), ORI_ERR_ARGUMENT);
    cr_assert(strstr(err.message, "both"), "%s", err.message);
    g.give = 2;
    cr_assert_eq(ori_gif_write(&d, &data, &size, &err), ORI_ERR_ARGUMENT);
    cr_assert(strstr(err.message, "no values"), "%s", err.message);
    g.give = 0;
    d.render.values.max = NAN;
    cr_assert_eq(ori_gif_write(&d, &data, &size, &err), ORI_ERR_ARGUMENT);
    cr_assert(strstr(err.message, "range"), "%s", err.message);
    cr_assert_null(data);
    ori_pattern_destroy((ori_pattern *)g.p);
    test_tmpdir_remove(dir);
}

// --- bad input --------------------------------------------------------------------------------

// A camera that is not finite (ori_camera_preset turned by a NaN yaw; an infinite scale) is
// refused with ORI_ERR_ARGUMENT naming the camera, for an image and an animation alike. Before,
// render(yaw_rad=nan) from Python drew NaN points and reached undefined behaviour in the depth
// order's grid (fuzz_python, fuzz/seeds/python/render-nan-yaw).
Test(render, a_camera_that_is_not_finite_is_refused)
{
    ori_pattern *p = test_load_pattern(test_repo_path("examples/patterns/open-corner.fold"), 0);
    ori_state_view sv = {p, NULL, NULL};
    ori_render_def d = ori_default_render_def();
    d.view = ORI_RENDER_3D;
    d.width = 64;
    d.height = 48;
    void *data = NULL;
    size_t size = 0;
    ori_error err;
    cr_assert_eq(ori_render_image(&sv, &d, &data, &size, &err), ORI_OK, "%s", err.message);
    ori_buffer_free(data);
    data = NULL;
    d.camera = ori_camera_preset(ORI_CAMERA_ISO, NAN, 0.0, 0.0);
    cr_assert_eq(ori_render_image(&sv, &d, &data, &size, &err), ORI_ERR_ARGUMENT);
    cr_assert(strstr(err.message, "camera"), "%s", err.message);
    cr_assert_null(data);
    d.camera = ori_camera_preset(ORI_CAMERA_ISO, 0.0, 0.0, 0.0);
    d.camera.scale = INFINITY;
    cr_assert_eq(ori_render_image(&sv, &d, &data, &size, &err), ORI_ERR_ARGUMENT);
    ori_gif_def g = ori_default_gif_def();
    g.render.camera = ori_camera_preset(ORI_CAMERA_TOP, 0.0, NAN, 0.0);
    g.frame_count = 1;
    g.frame = valued_frame;
    gif_valued gv;
    memset(&gv, 0, sizeof gv);
    gv.p = p;
    g.user = &gv;
    cr_assert_eq(ori_gif_write(&g, &data, &size, &err), ORI_ERR_ARGUMENT);
    cr_assert(strstr(err.message, "camera"), "%s", err.message);
    cr_assert_null(data);
    ori_pattern_destroy(p);
}

Test(render, bad_input_is_refused_and_nothing_written)
{
    corner k;
    corner_cube(&k, 2.0);
    ori_state_view sv = {k.c.p, k.pos, k.angles};
    ori_render_def d = ori_default_render_def();
    d.view = ORI_RENDER_3D;
    void *data = NULL;
    size_t size = 0;
    ori_error err;
    d.width = 0;
    cr_assert_eq(ori_render_image(&sv, &d, &data, &size, &err), ORI_ERR_ARGUMENT);
    d.width = ORI_RENDER_MAX_SIZE + 1;
    cr_assert_eq(ori_render_image(&sv, &d, &data, &size, &err), ORI_ERR_ARGUMENT);
    d.width = 100;
    d.format = ORI_IMAGE_UNKNOWN;
    cr_assert_eq(ori_render_image(&sv, &d, &data, &size, &err), ORI_ERR_ARGUMENT);
    cr_assert_null(data);
    // An unwritable path: an error, and no file.
    cr_assert_eq(ori_render_file(&sv, &d, "/nonexistent-dir/x.png", &err), ORI_ERR_IO);
    cr_assert_eq(access("/nonexistent-dir/x.png", F_OK), -1);
    // A position that is not finite.
    d.format = ORI_IMAGE_PNG;
    k.pos[3].y = NAN;
    cr_assert_eq(ori_render_image(&sv, &d, &data, &size, &err), ORI_ERR_RANGE);
    cr_assert_eq(err.element, 3);
    test_open_corner_free(&k.c);
}

// A folded form from another tool (FOLD's own example box): drawn in 3D, refused by the crease
// view, which needs a flat sheet.
Test(render, folded_form_draws_in_3d_only)
{
    ori_pattern *folded = test_load_pattern(test_require_shared("fold-spec/box.fold"), 0);
    ori_state_view fv = {folded, NULL, NULL};
    ori_render_def d = ori_default_render_def();
    void *data = NULL;
    size_t size = 0;
    ori_error err;
    cr_assert_eq(ori_render_image(&fv, &d, &data, &size, &err), ORI_ERR_UNSUPPORTED);
    d.view = ORI_RENDER_3D;
    cr_assert_eq(ori_render_image(&fv, &d, &data, &size, &err), ORI_OK, "%s", err.message);
    cairo_surface_t *s = decode_png(data);
    rgb8 colours[3] = {to8(d.background, 1), to8(d.front, 1), to8(d.back, 1)};
    cr_assert_gt(1.0 - fraction_nearest(s, colours, 3, 0), 0.05, "the box shows");
    cairo_surface_destroy(s);
    ori_buffer_free(data);
    ori_pattern_destroy(folded);
}

Test(render, colours_parse)
{
    ori_rgb c;
    cr_assert(ori_rgb_parse("#ff8000", &c));
    cr_assert_eq(c.r, 1.0);
    cr_assert_eq(c.g, 128.0 / 255.0);
    cr_assert_eq(c.b, 0.0);
    cr_assert(ori_rgb_parse("#0F0", &c));
    cr_assert_eq(c.g, 1.0);
    cr_assert(ori_rgb_parse("Orange", &c));
    cr_assert_eq(c.g, 165.0 / 255.0);
    cr_assert(!ori_rgb_parse("#12345", &c));
    cr_assert(!ori_rgb_parse("#gg0000", &c));
    cr_assert(!ori_rgb_parse("oranges", &c));
}

// --- the command line ---------------------------------------------------------------------------

static size_t file_size(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fclose(f);
    return n > 0 ? (size_t)n : 0;
}

// render, animate and export write their files; a failing run writes nothing: an existing
// output stays as it was and no temporary file is left behind.
Test(render, cli_writes_files_and_nothing_on_failure)
{
    char *dir = test_tmpdir();
    char args[2048], path[1024], *out = NULL;
    const char *images[3] = {"c.png", "c.svg", "c.pdf"};
    const char *magic[3] = {"\x89PNG", "<?xml", "%PDF"};
    for (int i = 0; i < 3; ++i) {
        snprintf(args, sizeof args, "render examples/open-corner.seq.json --yaw 90 --grid -o '%s/%s'", dir, images[i]);
        cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
        cr_assert(strstr(out, "wrote"), "%s", out);
        free(out);
        snprintf(path, sizeof path, "%s/%s", dir, images[i]);
        char *t = test_read_text(path);
        cr_assert_not_null(t);
        cr_assert(strncmp(t, magic[i], strlen(magic[i])) == 0, "%s starts with its format's signature", images[i]);
        free(t);
    }
    snprintf(path, sizeof path, "%s/c.png", dir);
    cairo_surface_t *s = cairo_image_surface_create_from_png(path);
    cr_assert_eq(cairo_image_surface_get_width(s), 800);
    cr_assert_eq(cairo_image_surface_get_height(s), 600);
    cairo_surface_destroy(s);
    snprintf(args, sizeof args, "animate examples/open-corner.seq.json --fps 5 --duration 1 --size 200x150 --json -o '%s/a.gif'", dir);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    cr_assert(strstr(out, "\"frames\":6"), "%s", out);
    free(out);
    snprintf(path, sizeof path, "%s/a.gif", dir);
    int e = 0;
    GifFileType *gif = DGifOpenFileName(path, &e);
    cr_assert_not_null(gif);
    cr_assert_eq(DGifSlurp(gif), GIF_OK);
    cr_assert_eq(gif->ImageCount, 6);
    DGifCloseFile(gif, &e);
    snprintf(args, sizeof args, "export examples/open-corner.seq.json --thickness 0.1 --json -o '%s/c.stl'", dir);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    cr_assert(strstr(out, "\"area\":4") && strstr(out, "\"volume\":0.4"), "%s", out);
    free(out);
    // Failures leave an existing file untouched.
    snprintf(path, sizeof path, "%s/keep.png", dir);
    FILE *f = fopen(path, "w");
    fputs("old", f);
    fclose(f);
    const char *bad[] = {"render examples/patterns/open-corner.fold --view 3d --texture README.md -o '%s/keep.png'",
                         "render examples/open-corner.seq.json --at 9 -o '%s/keep.png'",
                         "render examples/patterns/open-corner.fold --frame 99 -o '%s/keep.png'",
                         "render tests/data/render/open-corner-targets.fold --view 3d -o '%s/keep.png'"};
    int codes[] = {3, 2, 3, 3};
    for (int i = 0; i < 4; ++i) {
        snprintf(args, sizeof args, bad[i], dir);
        cr_assert_eq(test_run_cli(args, &out), codes[i], "%s", out);
        // One line "orikin render: ...", and for usage errors the hint after it.
        char *nl = strchr(out, '\n');
        cr_assert(strncmp(out, "orikin render: ", 15) == 0 && nl && (nl[1] == '\0' || strncmp(nl + 1, "Try 'orikin", 11) == 0),
                  "one line: %s", out);
        free(out);
        cr_assert_eq(file_size(path), 3, "keep.png untouched");
    }
    // Only the files written above are in the folder (no temporary file left).
    snprintf(args, sizeof args, "ls -A '%s' | wc -l", dir);
    FILE *ls = popen(args, "r");
    int files = 0;
    cr_assert_eq(fscanf(ls, "%d", &files), 1);
    pclose(ls);
    cr_assert_eq(files, 6, "c.png c.svg c.pdf a.gif c.stl keep.png");
    test_tmpdir_remove(dir);
}

// --- FOLD faceOrders -----------------------------------------------------------------------------

// The integers of a frame's faceOrders ("[[f,g,s],...]") into *out (malloc'd); returns the triples.
static int read_face_orders(const ori_fold *doc, int frame, int **out)
{
    char *text = ori_fold_get_custom(doc, frame, "faceOrders");
    cr_assert(text, "frame %d has faceOrders", frame);
    int n = 0, cap = 64;
    *out = malloc(sizeof(int) * (size_t)cap);
    for (char *c = text; *c;) {
        if (*c == '-' || (*c >= '0' && *c <= '9')) {
            if (n == cap) *out = realloc(*out, sizeof(int) * (size_t)(cap *= 2));
            (*out)[n++] = (int)strtol(c, &c, 10);
        } else {
            ++c;
        }
    }
    ori_buffer_free(text);
    cr_assert_eq(n % 3, 0);
    return n / 3;
}

static ori_pattern *folded_frame(const ori_fold *doc, int frame)
{
    ori_build_def bd = ori_default_build_def();
    bd.check_planarity = false;
    ori_pattern *p = NULL;
    ori_error err;
    cr_assert_eq(ori_fold_get_pattern(doc, frame, frame ? &bd : NULL, &p, &err), ORI_OK, "%s", err.message);
    return p;
}

// Index in an SVG of the last fill of colour c (cairo writes fill:rgb(R%,G%,B%)), or -1.
static long last_fill(const char *svg, const char *colour)
{
    long at = -1;
    for (const char *s = strstr(svg, colour); s; s = strstr(s + 1, colour)) at = s - svg;
    return at;
}

// Two stacked faces whose faceOrders say the opposite of stacking along the valley: the top view
// shows face 0's front (with faceOrders) instead of face 1's back (without), in the PNG's pixel
// at the stack and in the SVG's painting order.
Test(render, face_orders_decide_stacked_faces)
{
    ori_fold *doc = NULL;
    ori_error err;
    cr_assert_eq(ori_fold_load_file(test_repo_path("tests/data/render/stacked-faces.fold"), &doc, &err), ORI_OK, "%s",
                 err.message);
    ori_pattern *p = folded_frame(doc, 0);
    int *fo = NULL;
    int nfo = read_face_orders(doc, 0, &fo);
    cr_assert_eq(nfo, 1);
    ori_state_view sv = {p, NULL, NULL};
    ori_render_def d = top_def(200, 200);
    d.front = (ori_rgb){1, 0, 0};
    d.back = (ori_rgb){0, 0, 1};
    rgb8 front = to8(d.front, 1), back = to8(d.back, 1);
    cairo_surface_t *s = render_png(&sv, &d);
    cr_assert_eq(dist2(pixel(s, 100, 100), back), 0, "without faceOrders the valley stacks face 1 (back up) on top");
    cairo_surface_destroy(s);
    d.face_orders = fo;
    d.face_order_count = nfo;
    s = render_png(&sv, &d);
    cr_assert_eq(dist2(pixel(s, 100, 100), front), 0, "faceOrders put face 0 (front up) on top");
    cairo_surface_destroy(s);
    // The SVG paints face 0 (red) after face 1 (blue).
    d.format = ORI_IMAGE_SVG;
    void *data = NULL;
    size_t size = 0;
    cr_assert_eq(ori_render_image(&sv, &d, &data, &size, &err), ORI_OK, "%s", err.message);
    char *svg = malloc(size + 1);
    memcpy(svg, data, size);
    svg[size] = '\0';
    ori_buffer_free(data);
    long red = last_fill(svg, "fill:rgb(100%, 0%, 0%)"), blue = last_fill(svg, "fill:rgb(0%, 0%, 100%)");
    if (red < 0) red = last_fill(svg, "fill:rgb(100%,0%,0%)"), blue = last_fill(svg, "fill:rgb(0%,0%,100%)");
    cr_assert(red >= 0 && blue >= 0, "both faces are painted");
    cr_assert_gt(red, blue, "face 0 is painted after face 1");
    free(svg);
    // From below the order turns round: face 1's front... its normal points down, so its front.
    d.format = ORI_IMAGE_PNG;
    d.camera = ori_camera_preset(ORI_CAMERA_BOTTOM, 0, 0, 0);
    s = render_png(&sv, &d);
    cr_assert_eq(dist2(pixel(s, 100, 100), front), 0, "from below face 1 (its front down) is nearest");
    cairo_surface_destroy(s);
    // faceOrders naming a face that does not exist are refused.
    int bad[3] = {0, 7, 1};
    d.face_orders = bad;
    d.face_order_count = 1;
    cr_assert_eq(ori_render_image(&sv, &d, &data, &size, &err), ORI_ERR_ARGUMENT);
    free(fo);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
}

// Every flat-folded state of a 4-stamp strip, written by the layer solver as a folded frame
// (what `orikin layers -o` writes), seen from the top shows its top face in that face's colour.
Test(render, layer_solver_states_show_their_top_face)
{
    ori_fold *doc = NULL;
    ori_error err;
    cr_assert_eq(ori_fold_load_file(test_repo_path("tests/data/layers/pleat-unassigned.fold"), &doc, &err), ORI_OK, "%s",
                 err.message);
    ori_pattern *cp = folded_frame(doc, 0);
    ori_layers_def ld = ori_default_layers_def();
    ori_layers *L = NULL;
    cr_assert_eq(ori_layers_create(cp, &ld, &L, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_layers_count(L, &err), ORI_OK, "%s", err.message);
    int top_faces_seen[4] = {0};
    for (int k = 0; k < 16; ++k) {
        char key[8];
        snprintf(key, sizeof key, "%d", k);
        cr_assert_eq(ori_layers_select_state(L, key, &err), ORI_OK, "%s", err.message);
        int frame = ori_layers_append_frame(L, cp, doc, 0, &err);
        cr_assert_geq(frame, 1, "%s", err.message);
        int stack[4];
        cr_assert_eq(ori_layers_cell_count(L), 1);
        cr_assert_eq(ori_layers_cell_stack(L, 0, stack, 4), 4);
        int top = stack[0];
        top_faces_seen[top]++;
        ori_pattern *pf = folded_frame(doc, frame);
        int *fo = NULL;
        int nfo = read_face_orders(doc, frame, &fo);
        ori_state_view sv = {pf, NULL, NULL};
        ori_render_def d = top_def(200, 200);
        d.front = (ori_rgb){1, 0, 0};
        d.back = (ori_rgb){0, 0, 1};
        d.face_orders = fo;
        d.face_order_count = nfo;
        cairo_surface_t *s = render_png(&sv, &d);
        rgb8 want = to8(ori_layers_face_flipped(L, top) ? d.back : d.front, 1);
        cr_assert_eq(dist2(pixel(s, 100, 100), want), 0, "state %d: top face %d shows its %s", k, top,
                     ori_layers_face_flipped(L, top) ? "back" : "front");
        cairo_surface_destroy(s);
        free(fo);
        ori_pattern_destroy(pf);
    }
    // Both outer stamps and inner ones come on top across the states.
    cr_assert(top_faces_seen[0] > 0 && top_faces_seen[3] > 0);
    ori_layers_destroy(L);
    ori_pattern_destroy(cp);
    ori_fold_destroy(doc);
}

// The FOLD specification's box: its corner flaps lie flat against the walls inside (faceOrders);
// seen from outside, every wall shows its front (the box's outside) and no flap's back.
Test(render, fold_spec_box_follows_its_face_orders)
{
    const char *path = test_require_shared("fold-spec/box.fold");
    ori_fold *doc = NULL;
    ori_error err;
    cr_assert_eq(ori_fold_load_file(path, &doc, &err), ORI_OK, "%s", err.message);
    ori_pattern *p = folded_frame(doc, 0);
    int *fo = NULL;
    int nfo = read_face_orders(doc, 0, &fo);
    cr_assert_eq(nfo, 34);
    ori_state_view sv = {p, NULL, NULL};
    ori_render_def d = top_def(300, 300);
    d.front = (ori_rgb){1, 0, 0};
    d.back = (ori_rgb){0, 0, 1};
    d.face_orders = fo;
    d.face_order_count = nfo;
    rgb8 c[6];
    int nc = palette(&d, c);
    // Each side of the box, looked at square-on: sampled on a 9 × 9 grid over the wall facing the
    // eye (within 0.9 of its half-width), no pixel shows a back (a flap showing through).
    static const ori_camera_preset_kind presets[] = {ORI_CAMERA_TOP, ORI_CAMERA_BOTTOM, ORI_CAMERA_FRONT, ORI_CAMERA_SIDE};
    for (size_t i = 0; i < sizeof presets / sizeof presets[0]; ++i) {
        for (int yaw = 0; yaw < 360; yaw += 180) {
            d.camera = ori_camera_preset(presets[i], ori_deg_to_rad(yaw), 0, 0);
            ori_camera cam;
            cr_assert_eq(ori_render_camera(&sv, &d, &cam, &err), ORI_OK, "%s", err.message);
            cairo_surface_t *s = render_png(&sv, &d);
            double t[3] = {cam.rotation.m[2][0], cam.rotation.m[2][1], cam.rotation.m[2][2]};
            int axis = fabs(t[0]) > 0.9 ? 0 : fabs(t[1]) > 0.9 ? 1 : 2;
            cr_assert(fabs(t[axis]) > 0.999, "a square-on view");
            int fronts = 0;
            for (int a = -4; a <= 4; ++a)
                for (int b = -4; b <= 4; ++b) {
                    double q[3];
                    q[axis] = t[axis] > 0 ? 1 : -1;
                    q[(axis + 1) % 3] = 0.9 * a / 4.0;
                    q[(axis + 2) % 3] = 0.9 * b / 4.0;
                    ori_v3 img = ori_camera_project(&cam, ori_v3_make(q[0], q[1], q[2]));
                    rgb8 px = pixel(s, (int)img.x, (int)img.y);
                    int best = 0;
                    for (int k = 1; k < nc; ++k)
                        if (dist2(px, c[k]) < dist2(px, c[best])) best = k;
                    cr_assert_neq(best, 2, "view %zu yaw %d: a back shows at (%g, %g, %g)", i, yaw, q[0], q[1], q[2]);
                    fronts += best == 1;
                }
            cr_assert_geq(fronts, 70, "view %zu yaw %d: the wall shows its front (%d of 81)", i, yaw, fronts);
            cairo_surface_destroy(s);
        }
    }
    free(fo);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
}

// --- colour by value ---------------------------------------------------------------------------

// matplotlib's viridis at 0, 0.5 and 1 (matplotlib 3.6), the colours the fit must reproduce.
static const ori_rgb viridis_ref[3] = {{0.267004, 0.004874, 0.329415}, {0.127568, 0.566949, 0.550556}, {0.993248, 0.906157, 0.143936}};

static double luminance(ori_rgb c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

// The colour map is viridis within the fit's 2.4/255 at both ends and the middle, clamps outside
// [0, 1] (NaN to the bottom), and its luminance rises from end to end (a perceptual ramp).
Test(render, colormap_is_viridis)
{
    const double t[3] = {0.0, 0.5, 1.0};
    for (int i = 0; i < 3; ++i) {
        ori_rgb c = ori_colormap(t[i]);
        cr_assert_leq(fabs(c.r - viridis_ref[i].r), 2.4 / 255, "t %g red %g", t[i], c.r);
        cr_assert_leq(fabs(c.g - viridis_ref[i].g), 2.4 / 255, "t %g green %g", t[i], c.g);
        cr_assert_leq(fabs(c.b - viridis_ref[i].b), 2.4 / 255, "t %g blue %g", t[i], c.b);
    }
    ori_rgb lo = ori_colormap(0.0), hi = ori_colormap(1.0), below = ori_colormap(-3.0), above = ori_colormap(7.0),
            nan = ori_colormap(NAN);
    cr_assert(below.r == lo.r && below.g == lo.g && below.b == lo.b);
    cr_assert(nan.r == lo.r && nan.g == lo.g && nan.b == lo.b);
    cr_assert(above.r == hi.r && above.g == hi.g && above.b == hi.b);
    for (int k = 1; k <= 100; ++k)
        cr_assert_gt(luminance(ori_colormap(k / 100.0)), luminance(ori_colormap((k - 1) / 100.0)), "luminance rises at %d %%", k);
}

// Ticks: min and max exactly at the ends, evenly between, "%.3g" labels, zero read as "0"; one
// tick for an empty range. Positions clamp to [0, 1].
Test(render, colour_bar_ticks_and_positions)
{
    ori_value_map m = {NULL, NULL, -0.5, 1.5};
    double v[ORI_RENDER_BAR_TICKS];
    char l[ORI_RENDER_BAR_TICKS][ORI_RENDER_BAR_LABEL_MAX];
    cr_assert_eq(ori_value_map_ticks(&m, v, l), 5);
    const double want[5] = {-0.5, 0.0, 0.5, 1.0, 1.5};
    const char *labels[5] = {"-0.5", "0", "0.5", "1", "1.5"};
    for (int k = 0; k < 5; ++k) {
        cr_assert_float_eq(v[k], want[k], 1e-15, "tick %d", k);
        cr_assert_str_eq(l[k], labels[k]);
    }
    // Roundoff at zero: -0.3 … 0.1 puts a tick near 0 (−0.3 + 0.3 misses by an ulp).
    ori_value_map z = {NULL, NULL, -0.3, 0.1};
    ori_value_map_ticks(&z, v, l);
    cr_assert_str_eq(l[3], "0", "%s", l[3]);
    ori_value_map small = {NULL, NULL, 0.0, 0.0237822885};
    ori_value_map_ticks(&small, NULL, l);
    cr_assert_str_eq(l[4], "0.0238");
    cr_assert_str_eq(l[2], "0.0119");
    ori_value_map one = {NULL, NULL, 2.0, 2.0};
    cr_assert_eq(ori_value_map_ticks(&one, v, l), 1);
    cr_assert_str_eq(l[0], "2");
    cr_assert_eq(ori_value_map_position(&one, 2.0), 0.0);
    cr_assert_eq(ori_value_map_position(&m, 1.5), 1.0);
    cr_assert_eq(ori_value_map_position(&m, 9.0), 1.0);
    cr_assert_eq(ori_value_map_position(&m, -9.0), 0.0);
    cr_assert_float_eq(ori_value_map_position(&m, 0.0), 0.25, 1e-15);
}

// Where draw.c puts the colour bar: its label size, the strip's left edge, the bar's x range and
// its top and bottom (image units).
typedef struct bar_box {
    double x0, x1, y_top, y_bot, strip;
} bar_box;
static bar_box bar_of(int w, int h)
{
    double fs = fmax(6.0, 0.024 * fmin(w, h));
    bar_box b;
    b.strip = fmin(w / 3.0, 11.0 * fs);
    b.x0 = w - b.strip + 0.6 * fs;
    b.x1 = b.x0 + 1.2 * fs;
    b.y_top = 0.12 * h;
    b.y_bot = 0.88 * h;
    return b;
}

// Three faces with values 0.1, 0.7, 0.4 on a bar from 0.1 to 0.7, from the top: the face of the
// largest value shows the bar's top colour, the smallest its bottom, the middle one the middle
// (each channel to 1/255, Cairo's rounding: a face is painted unshaded in its colour); the bar's own top and bottom pixels
// are those colours (to 2/255: the gradient's stops). The sheet is fitted left of the bar.
Test(render, face_values_paint_the_bar_colours)
{
    const ori_assignment cr[2] = {ORI_ASSIGN_FLAT, ORI_ASSIGN_FLAT};
    ori_pattern *p = strip(3, cr);
    ori_state_view sv = {p, NULL, NULL};
    ori_render_def d = top_def(600, 300);
    d.shading = true; // painted faces ignore the light
    const double vals[3] = {0.1, 0.7, 0.4};
    d.values = (ori_value_map){vals, NULL, 0.1, 0.7};
    ori_camera cam;
    ori_error err;
    cr_assert_eq(ori_render_camera(&sv, &d, &cam, &err), ORI_OK, "%s", err.message);
    cairo_surface_t *s = render_png(&sv, &d);
    const double t[3] = {0.0, 1.0, 0.5};
    for (int f = 0; f < 3; ++f) {
        ori_v3 c = ori_camera_project(&cam, ori_v3_make(f + 0.5, 0.5, 0));
        rgb8 want = to8(ori_colormap(t[f]), 1), got = pixel(s, (int)c.x, (int)c.y);
        cr_assert_leq(dist2(got, want), 3, "face %d at (%g, %g): %d %d %d, want %d %d %d", f, c.x, c.y, got.r, got.g, got.b, want.r,
                      want.g, want.b);
    }
    bar_box b = bar_of(600, 300);
    ori_v3 right = ori_camera_project(&cam, ori_v3_make(3, 0.5, 0));
    cr_assert_lt(right.x, 600 - b.strip, "the sheet ends left of the bar's strip (x %g)", right.x);
    int bx = (int)(0.5 * (b.x0 + b.x1));
    int ys[2] = {(int)ceil(b.y_top) + 1, (int)floor(b.y_bot) - 2};
    for (int k = 0; k < 2; ++k) {
        // The gradient at the pixel's centre.
        double tp = (b.y_bot - (ys[k] + 0.5)) / (b.y_bot - b.y_top);
        rgb8 got = pixel(s, bx, ys[k]), want = to8(ori_colormap(tp), 1);
        cr_assert_gt(k == 0 ? tp : 1.0 - tp, 0.98, "near the %s", k == 0 ? "top" : "bottom");
        cr_assert_leq(dist2(got, want), 3 * 4, "bar at y %d (t %.3f): %d %d %d, want %d %d %d", ys[k], tp, got.r, got.g, got.b,
                      want.r, want.g, want.b);
    }
    cairo_surface_destroy(s);
    // A range that is not finite or reversed is refused.
    d.values.min = 1.0;
    d.values.max = 0.0;
    void *data = NULL;
    size_t size = 0;
    cr_assert_eq(ori_render_image(&sv, &d, &data, &size, &err), ORI_ERR_ARGUMENT);
    cr_assert(strstr(err.message, "values"), "%s", err.message);
    cr_assert_null(data);
    d.values.max = INFINITY;
    cr_assert_eq(ori_render_image(&sv, &d, &data, &size, &err), ORI_ERR_ARGUMENT);
    ori_pattern_destroy(p);
}

// Whether n bytes at data hold text (the drawing buffers are not NUL-terminated).
static bool has_bytes(const void *data, size_t n, const char *text)
{
    size_t k = strlen(text);
    for (size_t i = 0; i + k <= n; ++i)
        if (memcmp((const char *)data + i, text, k) == 0) return true;
    return false;
}

// Edge values in the crease view: a crease with a value is stroked in its colour; without face
// values the paper keeps its colour; an inactive map (no arrays) leaves the picture byte for byte
// as without one, whatever its range says.
Test(render, edge_values_stroke_the_creases)
{
    const ori_assignment cr[1] = {ORI_ASSIGN_VALLEY};
    ori_pattern *p = strip(2, cr);
    int crease = -1;
    for (int e = 0; e < ori_pattern_edge_count(p); ++e)
        if (ori_pattern_edge(p, e).assignment == ORI_ASSIGN_VALLEY) crease = e;
    cr_assert_geq(crease, 0);
    double *ev = malloc(sizeof(double) * (size_t)ori_pattern_edge_count(p));
    for (int e = 0; e < ori_pattern_edge_count(p); ++e) ev[e] = NAN;
    ev[crease] = 90.0;
    ori_state_view sv = {p, NULL, NULL};
    ori_render_def d = ori_default_render_def();
    d.width = 1000;
    d.height = 600;
    d.values = (ori_value_map){NULL, ev, 0.0, 90.0};
    cairo_surface_t *s = render_png(&sv, &d);
    // The crease view's fit (draw.c): the 2 × 1 strip fills the image left of the bar's strip.
    bar_box b = bar_of(1000, 600);
    double W = 1000 - b.strip, H = 600, margin = 0.06 * fmin(W, H);
    double sc = fmin((W - 2 * margin) / 2.0, (H - 2 * margin) / 1.0);
    double ox = 0.5 * W - sc * 1.0, oy = 0.5 * H + sc * 0.5;
    // The crease (3.75 pixels wide) at x = 1: the pixel of the row nearest its colour.
    rgb8 want = to8(ori_colormap(1.0), 1), on = {0, 0, 0};
    int cx = (int)lround(ox + sc * 1.0), cy = (int)(oy - sc * 0.5);
    for (int x = cx - 3; x <= cx + 3; ++x)
        if (dist2(pixel(s, x, cy), want) < dist2(on, want)) on = pixel(s, x, cy);
    rgb8 paper = pixel(s, (int)(ox + sc * 0.5), cy);
    cr_assert_leq(dist2(on, want), 3 * 4, "crease pixel %d %d %d, want %d %d %d", on.r, on.g, on.b, want.r, want.g, want.b);
    cr_assert_leq(dist2(paper, (rgb8){251, 249, 244}), 3, "paper %d %d %d", paper.r, paper.g, paper.b);
    cairo_surface_destroy(s);
    // Inactive maps change nothing (PNG bytes compared; Cairo numbers SVG ids per process).
    ori_render_def active = d;
    ori_render_def d0 = d;
    d0.values = ori_default_render_def().values;
    d.values = (ori_value_map){NULL, NULL, 5.0, -3.0};
    void *a = NULL, *c = NULL;
    size_t na = 0, nc = 0;
    ori_error err;
    cr_assert_eq(ori_render_image(&sv, &d0, &a, &na, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_render_image(&sv, &d, &c, &nc, &err), ORI_OK, "%s", err.message);
    cr_assert(na == nc && memcmp(a, c, na) == 0, "an inactive value map draws the same PNG");
    ori_buffer_free(a);
    ori_buffer_free(c);
    // The SVG's colour bar is a vector gradient, there only with values.
    d0.format = active.format = ORI_IMAGE_SVG;
    cr_assert_eq(ori_render_image(&sv, &d0, &a, &na, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_render_image(&sv, &active, &c, &nc, &err), ORI_OK, "%s", err.message);
    cr_assert_not(has_bytes(a, na, "linearGradient"), "no colour bar without values");
    cr_assert(has_bytes(c, nc, "linearGradient"), "the colour bar's gradient");
    ori_buffer_free(a);
    ori_buffer_free(c);
    free(ev);
    ori_pattern_destroy(p);
}

// A frame's field as n numbers (malloc'd).
static double *frame_numbers(const ori_fold *doc, int frame, const char *key, int n)
{
    char *text = ori_fold_get_custom(doc, frame, key);
    cr_assert_not_null(text, "frame %d has %s", frame, key);
    json_t *a = json_loads(text, JSON_DECODE_ANY, NULL);
    ori_buffer_free(text);
    cr_assert(json_is_array(a) && (int)json_array_size(a) == n, "%s has %d entries", key, n);
    double *v = calloc((size_t)n + 1, sizeof(double));
    for (int k = 0; k < n; ++k) v[k] = json_number_value(json_array_get(a, (size_t)k));
    json_decref(a);
    return v;
}

// animate --color: one bar over the whole motion. The compliant open corner folded to 40 % with
// every load step a frame (fold --compliant --all-frames): the bar's range is the smallest and
// largest face strain over all folded frames; fold-angle over a rigid fold spans the driven
// crease's start and end; strain of a motion that is not FOLD frames is an input error that
// writes nothing.
Test(render, cli_animate_color_has_one_bar_over_the_motion)
{
    char *dir = test_tmpdir();
    char args[2048], path[1024], *out = NULL;
    ori_fold *doc = test_compliant_open_corner_with(dir, "--all-frames", "all.fold");
    snprintf(path, sizeof path, "%s/all.fold", dir);
    ori_error err;
    ori_pattern *p = NULL;
    cr_assert_eq(ori_fold_get_pattern(doc, 0, NULL, &p, &err), ORI_OK, "%s", err.message);
    int F = ori_pattern_face_count(p), frames = ori_fold_frame_count(doc);
    cr_assert_geq(frames, 3, "frame 0 and at least two load steps");
    double lo = INFINITY, hi = -INFINITY;
    for (int k = 1; k < frames; ++k) {
        double *fs = frame_numbers(doc, k, "faces_orikin:strain", F);
        for (int f = 0; f < F; ++f) lo = fmin(lo, fabs(fs[f])), hi = fmax(hi, fabs(fs[f]));
        free(fs);
    }
    // Enough animation frames to show every stored frame (the nearest in time to each).
    snprintf(args, sizeof args, "animate '%s' --color strain --fps 50 --duration 2 --size 160x120 --json -o '%s/s.gif'", path, dir);
    json_t *rep = test_run_cli_json(args);
    json_t *col = json_object_get(rep, "color");
    cr_assert_str_eq(json_string_value(json_object_get(col, "quantity")), "strain");
    cr_assert_eq(json_integer_value(json_object_get(col, "shown")), F);
    cr_assert_eq(json_number_value(json_object_get(col, "min")), lo, "bar min %g, want %g", json_number_value(json_object_get(col, "min")), lo);
    cr_assert_eq(json_number_value(json_object_get(col, "max")), hi, "bar max %g, want %g", json_number_value(json_object_get(col, "max")), hi);
    json_decref(rep);
    snprintf(args, sizeof args, "animate examples/patterns/open-corner.fold --fix 4 --drive 12 --lock 11 --to 90 --color fold-angle "
             "--size 160x120 --json -o '%s/a.gif'", dir);
    rep = test_run_cli_json(args);
    col = json_object_get(rep, "color");
    cr_assert_str_eq(json_string_value(json_object_get(col, "per")), "crease");
    cr_assert_float_eq(json_number_value(json_object_get(col, "max")), 90.0, 1e-9);
    json_decref(rep);
    snprintf(args, sizeof args, "animate examples/open-corner.seq.json --color strain -o '%s/none.gif'", dir);
    cr_assert_eq(test_run_cli(args, &out), 3, "%s", out);
    cr_assert(strstr(out, "--color strain needs FOLD frames with strains"), "%s", out);
    free(out);
    snprintf(path, sizeof path, "%s/none.gif", dir);
    cr_assert_neq(access(path, F_OK), 0, "nothing written");
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    test_tmpdir_remove(dir);
}

// The compliant open corner at 40 % (orikin fold --compliant -o): render --color strain paints
// its most strained face (faces_orikin:strain of the frame) the bar's top colour and its least
// strained face the bottom's, in the crease view; --json reports the bar's range as the frame's
// smallest and largest face strain, labelled as printed; the 3D view shows the top colour
// somewhere; edges_orikin:strain alone gives each face its edges' largest |strain|; a frame
// without strains, or with a field of the wrong length, is an input error that writes nothing.
Test(render, cli_color_strain_paints_the_most_strained_face)
{
    char *dir = test_tmpdir();
    char args[2048], path[1024], *out = NULL;
    ori_fold *doc = test_compliant_open_corner(dir);
    ori_error err;
    ori_pattern *p = NULL;
    cr_assert_eq(ori_fold_get_pattern(doc, 0, NULL, &p, &err), ORI_OK, "%s", err.message);
    int F = ori_pattern_face_count(p);
    double *fs = frame_numbers(doc, 1, "faces_orikin:strain", F);
    int top = 0, bottom = 0;
    for (int f = 1; f < F; ++f) {
        if (fs[f] > fs[top]) top = f;
        if (fs[f] < fs[bottom]) bottom = f;
    }
    cr_assert_gt(fs[top], 0.01, "the open corner at 40 %% strains (%g)", fs[top]);
    for (int f = 0; f < F; ++f) cr_assert(f == top || fs[f] < fs[top] * 0.99, "one face strains most");

    snprintf(args, sizeof args, "render '%s/o.fold' --frame 1 --view cp --color strain --json -o '%s/s.png'", dir, dir);
    json_t *rep = test_run_cli_json(args);
    json_t *col = json_object_get(rep, "color");
    cr_assert_str_eq(json_string_value(json_object_get(col, "quantity")), "strain");
    cr_assert_str_eq(json_string_value(json_object_get(col, "per")), "face");
    cr_assert_eq(json_integer_value(json_object_get(col, "shown")), F);
    cr_assert_eq(json_real_value(json_object_get(col, "max")), fs[top], "bar max = the largest face strain");
    cr_assert_eq(json_real_value(json_object_get(col, "min")), fs[bottom], "bar min = the smallest face strain");
    json_t *labels = json_object_get(col, "labels");
    cr_assert_eq(json_array_size(labels), ORI_RENDER_BAR_TICKS);
    char want[32];
    snprintf(want, sizeof want, "%.3g", fs[bottom]);
    cr_assert_str_eq(json_string_value(json_array_get(labels, 0)), want);
    snprintf(want, sizeof want, "%.3g", fs[top]);
    cr_assert_str_eq(json_string_value(json_array_get(labels, ORI_RENDER_BAR_TICKS - 1)), want);
    json_decref(rep);

    // The crease view's fit (draw.c) of the sheet's box left of the bar's strip; each face's
    // area centroid (inside: the open corner's faces are convex).
    snprintf(path, sizeof path, "%s/s.png", dir);
    cairo_surface_t *s = cairo_image_surface_create_from_png(path);
    cr_assert_eq(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        ori_v3 q = ori_pattern_vertex(p, v);
        x0 = fmin(x0, q.x), x1 = fmax(x1, q.x), y0 = fmin(y0, q.y), y1 = fmax(y1, q.y);
    }
    bar_box b = bar_of(800, 600);
    double W = 800 - b.strip, H = 600, margin = 0.06 * fmin(W, H);
    double sc = fmin((W - 2 * margin) / (x1 - x0), (H - 2 * margin) / (y1 - y0));
    double ox = 0.5 * W - sc * 0.5 * (x0 + x1), oy = 0.5 * H + sc * 0.5 * (y0 + y1);
    const int faces[2] = {top, bottom};
    for (int i = 0; i < 2; ++i) {
        int fv[16], n = ori_pattern_face_vertices(p, faces[i], fv, 16);
        double cx = 0, cy = 0;
        for (int k = 0; k < n; ++k) {
            cx += ori_pattern_vertex(p, fv[k]).x / n;
            cy += ori_pattern_vertex(p, fv[k]).y / n;
        }
        rgb8 got = pixel(s, (int)(ox + sc * cx), (int)(oy - sc * cy)), w8 = to8(ori_colormap(i == 0 ? 1.0 : 0.0), 1);
        cr_assert_leq(dist2(got, w8), 3, "face %d (%s strain %g): %d %d %d, want %d %d %d", faces[i], i == 0 ? "largest" : "smallest",
                      fs[faces[i]], got.r, got.g, got.b, w8.r, w8.g, w8.b);
    }
    cairo_surface_destroy(s);

    // The 3D view of the same frame: the top colour covers a good part of the picture (face 3
    // is a quarter of the sheet), left of the bar.
    snprintf(args, sizeof args, "render '%s/o.fold' --frame 1 --color strain -o '%s/s3.png'", dir, dir);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    snprintf(want, sizeof want, "strain of %d faces from", F);
    cr_assert(strstr(out, want), "%s", out);
    free(out);
    snprintf(path, sizeof path, "%s/s3.png", dir);
    s = cairo_image_surface_create_from_png(path);
    rgb8 hi8 = to8(ori_colormap(1.0), 1);
    long hits = 0;
    for (int y = 0; y < 600; ++y)
        for (int x = 0; x < 800 - (int)b.strip; ++x) hits += dist2(pixel(s, x, y), hi8) <= 3;
    cr_assert_gt(hits, 800 * 600 / 20, "%ld pixels of the top colour", hits);
    cairo_surface_destroy(s);

    // Without faces_orikin:strain a face's strain is the largest |strain| of its edges
    // (edges_orikin:strain): the bar's top is the largest |edge strain|. A field of the wrong
    // length is an input error naming it.
    int E = ori_pattern_edge_count(p);
    double *es = frame_numbers(doc, 1, "edges_orikin:strain", E), emax = 0.0;
    for (int e = 0; e < E; ++e) emax = fmax(emax, fabs(es[e]));
    free(es);
    cr_assert_eq(ori_fold_set_custom(doc, 1, "faces_orikin:strain", NULL, &err), ORI_OK, "%s", err.message);
    snprintf(path, sizeof path, "%s/edges.fold", dir);
    cr_assert_eq(ori_fold_save_file(doc, path, &err), ORI_OK, "%s", err.message);
    snprintf(args, sizeof args, "render '%s' --frame 1 --color strain --json -o '%s/e.png'", path, dir);
    rep = test_run_cli_json(args);
    cr_assert_eq(json_real_value(json_object_get(json_object_get(rep, "color"), "max")), emax, "the largest |edge strain| %g", emax);
    json_decref(rep);
    cr_assert_eq(ori_fold_set_custom(doc, 1, "faces_orikin:strain", "[0.1,0.2]", &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_fold_save_file(doc, path, &err), ORI_OK, "%s", err.message);
    snprintf(args, sizeof args, "render '%s' --frame 1 --color strain -o '%s/bad.png'", path, dir);
    cr_assert_eq(test_run_cli(args, &out), 3, "%s", out);
    cr_assert(strstr(out, "frame 1: faces_orikin:strain is not 5 finite numbers"), "%s", out);
    free(out);

    // Frame 0 is the crease pattern: no strains. Nothing is written.
    snprintf(args, sizeof args, "render '%s/o.fold' --color strain -o '%s/none.png'", dir, dir);
    cr_assert_eq(test_run_cli(args, &out), 3, "%s", out);
    cr_assert(strstr(out, "faces_orikin:strain") && strchr(out, '\n') == out + strlen(out) - 1, "one line: %s", out);
    free(out);
    snprintf(path, sizeof path, "%s/none.png", dir);
    cr_assert_neq(access(path, F_OK), 0, "nothing written");
    free(fs);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    test_tmpdir_remove(dir);
}

// --color target-error and fold-angle of a compliant frame agree with the fold's own report:
// the bar's top is the fold's crease_error_deg (its largest |ρ − target × fraction|, computed by
// the model) and the largest crease fold angle of fold_angles_deg, to 1e-9 degrees (the frame
// stores the angles in degrees).
Test(render, cli_color_target_error_matches_the_fold_report)
{
    char *dir = test_tmpdir();
    char args[2048], *out = NULL;
    snprintf(args, sizeof args, "fold examples/patterns/open-corner.fold --compliant --percent 40 --json -o '%s/o.fold'", dir);
    cr_assert_eq(test_run_cli_split(args, &out, NULL), 0, "%s", out);
    json_t *fold = json_loads(out, 0, NULL);
    cr_assert_not_null(fold, "%s", out);
    free(out);
    double cerr = json_real_value(json_object_get(fold, "crease_error_deg"));
    cr_assert_gt(cerr, 1.0, "the open corner at 40 %% misses its targets (%g deg)", cerr);
    test_open_corner oc = test_open_corner_load();
    json_t *ang = json_object_get(fold, "fold_angles_deg");
    double amax = -INFINITY, amin = INFINITY;
    for (int e = 0; e < ori_pattern_edge_count(oc.p); ++e) {
        int f[2];
        ori_pattern_edge_faces(oc.p, e, f);
        if (f[0] < 0 || f[1] < 0) continue;
        double a = json_real_value(json_array_get(ang, (size_t)e));
        amax = fmax(amax, a);
        amin = fmin(amin, a);
    }
    test_open_corner_free(&oc);
    json_decref(fold);
    const char *kinds[2] = {"target-error", "fold-angle"};
    for (int k = 0; k < 2; ++k) {
        snprintf(args, sizeof args, "render '%s/o.fold' --frame 1 --color %s --json -o '%s/t.svg'", dir, kinds[k], dir);
        json_t *rep = test_run_cli_json(args);
        json_t *col = json_object_get(rep, "color");
        cr_assert_str_eq(json_string_value(json_object_get(col, "per")), "crease");
        cr_assert_eq(json_integer_value(json_object_get(col, "shown")), 5, "the open corner's five creases");
        double mx = json_real_value(json_object_get(col, "max")), mn = json_real_value(json_object_get(col, "min"));
        if (k == 0) {
            cr_assert_float_eq(mx, cerr, 1e-9, "target-error max %.12g, fold's crease error %.12g", mx, cerr);
            cr_assert_geq(mn, 0.0);
        } else {
            cr_assert_float_eq(mx, amax, 1e-9, "fold-angle max %.12g vs %.12g", mx, amax);
            cr_assert_float_eq(mn, amin, 1e-9, "fold-angle min %.12g vs %.12g", mn, amin);
        }
        json_decref(rep);
    }
    test_tmpdir_remove(dir);
}

// The colour bar's labels are drawn stroke by stroke: a glyph draws its polylines and nothing
// else (its table's zero padding once drew a dot at each glyph's corner, so "0.0238" read
// "0..0238"). No path of the picture has a zero-length segment.
Test(render, label_glyphs_draw_no_stray_dots)
{
    char *dir = test_tmpdir(), args[1024], *out = NULL;
    snprintf(args, sizeof args, "render examples/patterns/open-corner.fold --compliant --percent 40 --color strain -o '%s/bar.svg'", dir);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    free(out);
    char path[600];
    snprintf(path, sizeof path, "%s/bar.svg", dir);
    char *svg = test_read_file(path, NULL);
    cr_assert_not_null(svg);
    int paths = 0, zero = 0;
    for (char *d = strstr(svg, " d=\""); d; d = strstr(d, " d=\"")) {
        d += 4;
        paths++;
        double cx = NAN, cy = NAN;
        for (char *q = d; *q && *q != '"';) {
            char op = *q;
            if (op == 'M' || op == 'L') {
                char *end;
                double x = strtod(q + 1, &end), y = strtod(end, &end);
                if (op == 'L' && x == cx && y == cy) zero++;
                cx = x, cy = y;
                q = end;
            } else {
                q++;
            }
        }
    }
    cr_assert_gt(paths, 10, "the picture has its faces, edges, bar and labels");
    cr_assert_eq(zero, 0, "%d zero-length segments (stray dots)", zero);
    free(svg);
    test_tmpdir_remove(dir);
}
