// Exact segment predicates shared by the pattern build (planarity check) and the arrangement
// (consistency of an insertion before it is committed).
#ifndef ORI_GEOMETRY_INTERNAL_H
#define ORI_GEOMETRY_INTERNAL_H

#include <orikin/math.h>

// The y range [*lo, *hi] of segment ab (a.x <= b.x) over the x range [xl, xr], for entering
// the segment in the columns of a grid; all of ab's y range when ab is vertical or does not reach
// into [xl, xr] (rounding at a column's edge).
static inline void ori__segment_y_range(ori_v2 a, ori_v2 b, double xl, double xr, double *lo, double *hi)
{
    double y0 = a.y, y1 = b.y, x0 = xl > a.x ? xl : a.x, x1 = xr < b.x ? xr : b.x;
    if (b.x > a.x && x0 <= x1) {
        double t0 = (x0 - a.x) / (b.x - a.x), t1 = (x1 - a.x) / (b.x - a.x);
        y0 = a.y + t0 * (b.y - a.y);
        y1 = a.y + t1 * (b.y - a.y);
    }
    *lo = y0 < y1 ? y0 : y1;
    *hi = y0 < y1 ? y1 : y0;
}

// c, collinear with ab (the caller checked), lies in the closed bounding box of ab. (Out of
// line: it is off the hot path of ori__segments_conflict.)
bool ori__in_segment_box(ori_v2 a, ori_v2 b, ori_v2 c);

// Segments sx and sy share the end point s: whether they overlap (collinear, same side of s).
bool ori__overlap_beyond(ori_v2 s, ori_v2 x, ori_v2 y);

// Whether direction u→x points into the corner at u of a region that lies left of the path
// prev → u → next (the sector counter-clockwise from next to prev), decided exactly. Convex,
// reflex and straight corners are told apart by orientation signs; a zero-angle corner (a slit
// tip, prev = next's direction) holds every direction but the slit's own.
bool ori__corner_contains(ori_v2 u, ori_v2 next, ori_v2 prev, ori_v2 x);

// Whether the segments ab (end vertices ev[0], ev[1]) and cd (fv[0], fv[1]) have a common point
// other than a shared end vertex: a crossing, a touch, a collinear overlap, or the same two
// vertices. Exact (orientation signs on the given coordinates). Inline: the pattern build's
// planarity check calls it for every pair of edges sharing a grid cell.
static inline bool ori__segments_conflict(ori_v2 a, ori_v2 b, const int ev[2], ori_v2 c, ori_v2 d, const int fv[2])
{
    // Disjoint closed bounding boxes: no common point at all (exact comparisons). Most pairs
    // that share a grid cell end here without an orientation test.
    if ((a.x > b.x ? a.x : b.x) < (c.x < d.x ? c.x : d.x) || (c.x > d.x ? c.x : d.x) < (a.x < b.x ? a.x : b.x) ||
        (a.y > b.y ? a.y : b.y) < (c.y < d.y ? c.y : d.y) || (c.y > d.y ? c.y : d.y) < (a.y < b.y ? a.y : b.y))
        return false;
    int shared = (ev[0] == fv[0] || ev[0] == fv[1]) + (ev[1] == fv[0] || ev[1] == fv[1]);
    if (shared == 2) return true; // the same two vertices
    if (shared == 1) {
        // Only a collinear overlap beyond the shared end point conflicts.
        bool a_shared = ev[0] == fv[0] || ev[0] == fv[1], c_shared = fv[0] == ev[0] || fv[0] == ev[1];
        return a_shared ? ori__overlap_beyond(a, b, c_shared ? d : c) : ori__overlap_beyond(b, a, c_shared ? d : c);
    }
    // (Computed only here: with a shared end point two of them are exactly zero, which sends
    // every call through the slow exact path of ori_orient2d.)
    int o1 = ori_orient2d_sign(a, b, c), o2 = ori_orient2d_sign(a, b, d);
    int o3 = ori_orient2d_sign(c, d, a), o4 = ori_orient2d_sign(c, d, b);
    if (o1 != o2 && o3 != o4 && o1 * o2 <= 0 && o3 * o4 <= 0) {
        if (o1 == 0 && o2 == 0)
            return ori__in_segment_box(a, b, c) || ori__in_segment_box(a, b, d) || ori__in_segment_box(c, d, a);
        return true;
    }
    if (o1 == 0 && ori__in_segment_box(a, b, c)) return true;
    if (o2 == 0 && ori__in_segment_box(a, b, d)) return true;
    if (o3 == 0 && ori__in_segment_box(c, d, a)) return true;
    if (o4 == 0 && ori__in_segment_box(c, d, b)) return true;
    return false;
}

#endif
