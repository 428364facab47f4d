// Convex hulls by qhull (libqhull_r, triangulated output) as surfaces to unfold: the test and
// benchmark shapes of docs/unfolding.md.
#define _POSIX_C_SOURCE 200809L
#include <libqhull_r/qhull_ra.h>
#include <stdio.h>
#include <stdlib.h>

#include <orikin/unfold.h>

#include "../core/core_internal.h"

ori_status ori_unfold_mesh_convex_hull(const ori_v3 *points, int count, ori_mesh **out, ori_error *error)
{
    ORI_ASSERT(out && (count == 0 || points));
    *out = NULL;
    if (count < 4) return ori__fail(error, ORI_ERR_ARGUMENT, "a convex hull needs at least 4 points");
    coordT *xyz = ori__alloc((size_t)count * 3 * sizeof *xyz);
    ori_v3 centre = {0, 0, 0};
    for (int i = 0; i < count; ++i) {
        if (!ori__coord_ok(points[i].x) || !ori__coord_ok(points[i].y) || !ori__coord_ok(points[i].z)) {
            ori__free(xyz);
            return ori__fail_at(error, ORI_ERR_RANGE, "points", i, "coordinate not finite");
        }
        xyz[3 * i] = points[i].x, xyz[3 * i + 1] = points[i].y, xyz[3 * i + 2] = points[i].z;
        centre = ori_v3_add(centre, points[i]);
    }
    centre = ori_v3_scale(centre, 1.0 / count);
    // qhull reports to a FILE: keep its messages in memory (the library prints nothing)
    char *msg = NULL;
    size_t msg_size = 0;
    FILE *err = open_memstream(&msg, &msg_size);
    qhT qh_qh;
    qhT *qh = &qh_qh;
    qh_zero(qh, err);
    char flags[] = "qhull Qt";
    int code = qh_new_qhull(qh, 3, count, xyz, False, flags, NULL, err);
    ori_status st = ORI_OK;
    if (code != 0) {
        st = ori__fail(error, ORI_ERR_DEGENERATE, "qhull failed (code %d): the points are degenerate (coplanar?)", code);
    } else {
        int nf = qh->num_facets, nfv = 0;
        int *fs = ori__alloc(((size_t)nf + 1) * sizeof *fs), *fv = ori__alloc(((size_t)nf * 3 + 1) * sizeof *fv);
        int *map = ori__alloc((size_t)count * sizeof *map), nv = 0;
        ori_v3 *v = ori__alloc((size_t)count * sizeof *v);
        for (int i = 0; i < count; ++i) map[i] = -1;
        facetT *facet;
        vertexT *vertex, **vertexp;
        int f = 0;
        FORALLfacets {
            int tri[3], k = 0;
            FOREACHvertex_(facet->vertices) {
                int id = qh_pointid(qh, vertex->point);
                if (map[id] < 0) map[id] = nv, v[nv++] = points[id];
                if (k < 3) tri[k++] = map[id];
            }
            if (k != 3) continue;
            ori_v3 n = ori_v3_cross(ori_v3_sub(v[tri[1]], v[tri[0]]), ori_v3_sub(v[tri[2]], v[tri[0]]));
            if (ori_v3_dot(n, ori_v3_sub(v[tri[0]], centre)) < 0.0) {
                int t = tri[1];
                tri[1] = tri[2], tri[2] = t;
            }
            fs[f] = nfv;
            for (int j = 0; j < 3; ++j) fv[nfv++] = tri[j];
            f++;
        }
        fs[f] = nfv;
        st = ori_unfold_mesh_create(v, nv, fs, fv, f, out, error);
        ori__free(fs), ori__free(fv), ori__free(map), ori__free(v);
    }
    qh_freeqhull(qh, !qh_ALL);
    int curlong, totlong;
    qh_memfreeshort(qh, &curlong, &totlong);
    fclose(err);
    free(msg);
    ori__free(xyz);
    return st;
}
