// The camera: preset view directions turned by yaw, pitch and roll, fitting to a set of points,
// and the orthographic or perspective projection into image coordinates.
#include <math.h>

#include "render_internal.h"

static ori_m3 rows(ori_v3 right, ori_v3 up, ori_v3 back)
{
    ori_m3 r = {{{right.x, right.y, right.z}, {up.x, up.y, up.z}, {back.x, back.y, back.z}}};
    return r;
}

ori_camera ori_camera_preset(ori_camera_preset_kind preset, double yaw_rad, double pitch_rad, double roll_rad)
{
    ori_m3 base;
    switch (preset) {
    case ORI_CAMERA_TOP:
        base = rows(ori_v3_make(1, 0, 0), ori_v3_make(0, 1, 0), ori_v3_make(0, 0, 1));
        break;
    case ORI_CAMERA_BOTTOM:
        base = rows(ori_v3_make(1, 0, 0), ori_v3_make(0, -1, 0), ori_v3_make(0, 0, -1));
        break;
    case ORI_CAMERA_FRONT:
        base = rows(ori_v3_make(1, 0, 0), ori_v3_make(0, 0, 1), ori_v3_make(0, -1, 0));
        break;
    case ORI_CAMERA_SIDE:
        base = rows(ori_v3_make(0, 1, 0), ori_v3_make(0, 0, 1), ori_v3_make(1, 0, 0));
        break;
    case ORI_CAMERA_ISO:
    default: {
        ori_v3 back = ori_v3_normalize(ori_v3_make(1, -1, 1));
        ori_v3 right = ori_v3_normalize(ori_v3_make(1, 1, 0));
        base = rows(right, ori_v3_cross(back, right), back);
        break;
    }
    }
    // Yaw turns the model about world z before the preset; pitch and roll turn the view about
    // its own right and viewing axes.
    ori_m3 yaw = ori_m3_rotation(ori_v3_make(0, 0, 1), yaw_rad);
    ori_m3 pitch = ori_m3_rotation(ori_v3_make(1, 0, 0), pitch_rad);
    ori_m3 roll = ori_m3_rotation(ori_v3_make(0, 0, 1), roll_rad);
    ori_camera c;
    c.rotation = ori_m3_mul(roll, ori_m3_mul(pitch, ori_m3_mul(base, yaw)));
    c.target = ori_v3_make(0, 0, 0);
    c.cx = 0.0;
    c.cy = 0.0;
    c.scale = 1.0;
    c.perspective = false;
    c.distance = 1.0;
    return c;
}

ori_v3 ori_camera_project(const ori_camera *c, ori_v3 p)
{
    ori_v3 v = ori_m3_apply(c->rotation, ori_v3_sub(p, c->target));
    if (c->perspective) {
        double w = c->distance - v.z;
        // A point at or behind the eye (w ≤ 0) has no image; the drawing leaves it out.
        double f = w > 0.0 ? c->distance / w : 0.0;
        return ori_v3_make(c->cx + c->scale * f * v.x, c->cy - c->scale * f * v.y, w);
    }
    return ori_v3_make(c->cx + c->scale * v.x, c->cy - c->scale * v.y, -v.z);
}

void ori__camera_fit_box(ori_camera *c, ori_v3 lo, ori_v3 hi)
{
    double radius = 0.5 * ori_v3_norm(ori_v3_sub(hi, lo));
    if (!(radius > 0.0)) radius = 1.0;
    c->target = ori_v3_scale(ori_v3_add(lo, hi), 0.5);
    if (c->perspective) c->distance = ORI_CAMERA_PERSPECTIVE_DISTANCE * radius;
    c->scale = 1.0;
    c->cx = 0.0;
    c->cy = 0.0;
}

void ori__camera_fit_extents(ori_camera *c, const double ext[4], int width, int height, double margin_rel,
                             double radius)
{
    // The image at scale 1 about (0, 0) spans ext = {x0, x1, y0, y1}; projection is linear in
    // the scale and the offset, so scale it into the image and centre it.
    double margin = margin_rel * fmin(width, height);
    double aw = fmax(width - 2.0 * margin, 1.0), ah = fmax(height - 2.0 * margin, 1.0);
    double dx = ext[1] - ext[0], dy = ext[3] - ext[2];
    double s;
    if (dx > 0.0 && dy > 0.0) s = fmin(aw / dx, ah / dy);
    else if (dx > 0.0) s = aw / dx;
    else if (dy > 0.0) s = ah / dy;
    else s = fmin(aw, ah) / (2.0 * (radius > 0.0 ? radius : 1.0));
    c->scale = s;
    c->cx = 0.5 * width - s * 0.5 * (ext[0] + ext[1]);
    c->cy = 0.5 * height - s * 0.5 * (ext[2] + ext[3]);
}

void ori__camera_extents_add(const ori_camera *c, const ori_v3 *points, int count, double ext[4])
{
    for (int i = 0; i < count; ++i) {
        ori_v3 q = ori_camera_project(c, points[i]);
        ext[0] = fmin(ext[0], q.x);
        ext[1] = fmax(ext[1], q.x);
        ext[2] = fmin(ext[2], q.y);
        ext[3] = fmax(ext[3], q.y);
    }
}

void ori_camera_fit(ori_camera *c, const ori_v3 *points, int count, int width, int height, double margin_rel)
{
    ORI_ASSERT(c && points && count >= 1 && width > 0 && height > 0);
    ori_v3 lo = points[0], hi = points[0];
    for (int i = 1; i < count; ++i) {
        lo = ori_v3_make(fmin(lo.x, points[i].x), fmin(lo.y, points[i].y), fmin(lo.z, points[i].z));
        hi = ori_v3_make(fmax(hi.x, points[i].x), fmax(hi.y, points[i].y), fmax(hi.z, points[i].z));
    }
    ori__camera_fit_box(c, lo, hi);
    double ext[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY};
    ori__camera_extents_add(c, points, count, ext);
    ori__camera_fit_extents(c, ext, width, height, margin_rel, 0.5 * ori_v3_norm(ori_v3_sub(hi, lo)));
}
