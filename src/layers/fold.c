// Folded geometry of a flat-foldable crease pattern: every face's isometry into the folded
// frame. Face 0 stays in place; crossing a folded crease (M, V, U) composes a reflection
// across the crease's line in the crease pattern, crossing a flat one (F, J) composes nothing.
// Each vertex takes its image through the first face that reaches it (breadth first, so the
// chain of reflections is as short as possible) and every other face must agree with it.
#include "layers_internal.h"

// Transform t (6 numbers: x' = t0 x + t1 y + t2, y' = t3 x + t4 y + t5) applied to p.
static ori_v2 apply(const double t[6], ori_v2 p)
{
    return ori_v2_make(t[0] * p.x + t[1] * p.y + t[2], t[3] * p.x + t[4] * p.y + t[5]);
}

// out = a ∘ b (first b, then a).
static void compose(const double a[6], const double b[6], double out[6])
{
    double r[6];
    r[0] = a[0] * b[0] + a[1] * b[3];
    r[1] = a[0] * b[1] + a[1] * b[4];
    r[2] = a[0] * b[2] + a[1] * b[5] + a[2];
    r[3] = a[3] * b[0] + a[4] * b[3];
    r[4] = a[3] * b[1] + a[4] * b[4];
    r[5] = a[3] * b[2] + a[4] * b[5] + a[5];
    memcpy(out, r, sizeof r);
}

// Reflection across the line through u and v.
static void reflection(ori_v2 u, ori_v2 v, double out[6])
{
    ori_v2 d = ori_v2_normalize(ori_v2_sub(v, u));
    double a = 2.0 * d.x * d.x - 1.0, b = 2.0 * d.x * d.y, c = 2.0 * d.y * d.y - 1.0;
    out[0] = a;
    out[1] = b;
    out[3] = b;
    out[4] = c;
    out[2] = u.x - (a * u.x + b * u.y);
    out[5] = u.y - (b * u.x + c * u.y);
}

static bool is_folded(ori_assignment a)
{
    return a == ORI_ASSIGN_MOUNTAIN || a == ORI_ASSIGN_VALLEY || a == ORI_ASSIGN_UNASSIGNED;
}

// Folded images of the vertices from the face transforms (first face in order wins), then the
// check that every face agrees. order lists the faces in the order they were placed.
static ori_status place_vertices(ori_layers *L, const ori_pattern *p, const int *order, ori_error *error)
{
    double lo_x = 1e300, lo_y = 1e300, hi_x = -1e300, hi_y = -1e300;
    for (int v = 0; v < L->nv; ++v) {
        ori_v3 q = ori_pattern_vertex(p, v);
        lo_x = q.x < lo_x ? q.x : lo_x;
        hi_x = q.x > hi_x ? q.x : hi_x;
        lo_y = q.y < lo_y ? q.y : lo_y;
        hi_y = q.y > hi_y ? q.y : hi_y;
    }
    double diag = L->nv ? hypot(hi_x - lo_x, hi_y - lo_y) : 1.0;
    if (!(diag > 0.0)) diag = 1.0;
    double tol = L->snap_rel * diag;
    uint8_t *seen = ori__calloc((size_t)(L->nv ? L->nv : 1), 1);
    int fv[1024];
    for (int i = 0; i < L->nf; ++i) {
        int f = order[i];
        int n = ori_pattern_face_vertices(p, f, fv, 1024);
        if (n > 1024) {
            ori__free(seen);
            return ori__fail_at(error, ORI_ERR_LIMIT, "faces_vertices", f, "face has more than 1024 vertices");
        }
        for (int k = 0; k < n; ++k) {
            int v = fv[k];
            ori_v3 q = ori_pattern_vertex(p, v);
            ori_v2 img = apply(L->xf[f], ori_v2_make(q.x, q.y));
            double gap = seen[v] ? ori_v2_norm(ori_v2_sub(img, L->vf[v])) : 0.0;
            if (!seen[v]) {
                seen[v] = 1;
                L->vf[v] = img;
            } else if (gap <= tol) {
                if (gap / diag > L->noise_len) L->noise_len = gap / diag;
            } else {
                ori__free(seen);
                L->fail_need = gap / diag;
                return ori__fail_at(error, ORI_ERR_TOPOLOGY, "vertices_coords", v,
                                    "the sheet does not fold consistently here: face %d puts the vertex %.3g "
                                    "(relative %.3g) away from where the other faces put it",
                                    f, ori_v2_norm(ori_v2_sub(img, L->vf[v])),
                                    ori_v2_norm(ori_v2_sub(img, L->vf[v])) / diag);
            }
        }
    }
    ori__free(seen);
    return ORI_OK;
}

ori_status ori__layers_fold(ori_layers *L, const ori_pattern *p, const ori_layers_def *def, ori_error *error)
{
    int nf = L->nf;
    L->vf = ori__calloc((size_t)(L->nv ? L->nv : 1), sizeof(ori_v2));
    L->xf = ori__calloc((size_t)(nf ? nf : 1), sizeof(*L->xf));
    L->flip = ori__calloc((size_t)(nf ? nf : 1), 1);
    int *order = ori__alloc(sizeof(int) * (size_t)(nf ? nf : 1));
    ori_status st = ORI_OK;

    if (def->face_transforms) {
        for (int f = 0; f < nf; ++f) {
            memcpy(L->xf[f], def->face_transforms + 6 * f, sizeof(double) * 6);
            const double *t = L->xf[f];
            double det = t[0] * t[4] - t[1] * t[3];
            double err = fmax(fabs(t[0] * t[0] + t[3] * t[3] - 1.0),
                              fmax(fabs(t[1] * t[1] + t[4] * t[4] - 1.0), fabs(t[0] * t[1] + t[3] * t[4])));
            if (!(err <= ORI_TOL_LAYERS_TRANSFORM)) {
                st = ori__fail_at(error, ORI_ERR_ARGUMENT, "faces_flatFoldTransform", f,
                                  "not an isometry (its columns miss orthonormal by %g)", err);
                goto done;
            }
            L->flip[f] = det < 0.0;
            order[f] = f;
        }
        st = place_vertices(L, p, order, error);
        goto done;
    }

    if (ori_pattern_is_folded_form(p)) {
        // A flat folded form: the coordinates are the folded positions, and a face whose cycle
        // (counter-clockwise in the crease pattern) runs clockwise lies face-down.
        double lo = 1e300, hi = -1e300;
        for (int v = 0; v < L->nv; ++v) {
            ori_v3 q = ori_pattern_vertex(p, v);
            lo = fmin(lo, fmin(q.x, fmin(q.y, q.z)));
            hi = fmax(hi, fmax(q.x, fmax(q.y, q.z)));
        }
        double scale = hi > lo ? hi - lo : 1.0;
        for (int v = 0; v < L->nv; ++v) {
            ori_v3 q = ori_pattern_vertex(p, v);
            if (fabs(q.z) > ORI_TOL_PLANAR_REL * scale) {
                st = ori__fail_at(error, ORI_ERR_UNSUPPORTED, "vertices_coords", v,
                                  "the folded form is not flat (z = %g); layer orders need a flat-folded state", q.z);
                goto done;
            }
            L->vf[v] = ori_v2_make(q.x, q.y);
        }
        int fv[1024];
        for (int f = 0; f < nf; ++f) {
            int n = ori_pattern_face_vertices(p, f, fv, 1024);
            double area2 = 0.0;
            for (int k = 0; k < n && n <= 1024; ++k) {
                ori_v2 a = L->vf[fv[k]], b = L->vf[fv[(k + 1) % n]];
                area2 += a.x * b.y - a.y * b.x;
            }
            L->flip[f] = area2 < 0.0;
            double id[6] = {1, 0, 0, 0, 1, 0};
            memcpy(L->xf[f], id, sizeof id);
        }
        goto done;
    }

    // Crease pattern: breadth-first over the faces, across every crease that joins two faces.
    {
        uint8_t *placed = ori__calloc((size_t)(nf ? nf : 1), 1);
        int head = 0, tail = 0;
        if (nf > 0) {
            double id[6] = {1, 0, 0, 0, 1, 0};
            memcpy(L->xf[0], id, sizeof id);
            placed[0] = 1;
            order[tail++] = 0;
        }
        while (head < tail) {
            int f = order[head++];
            for (int64_t k = L->face_edges.off[f]; k < L->face_edges.off[f + 1]; ++k) {
                int e = L->face_edges.items[k];
                ori_assignment a = L->asg[e];
                if (a == ORI_ASSIGN_BOUNDARY || a == ORI_ASSIGN_CUT) continue;
                int g = L->ef[e][0] == f ? L->ef[e][1] : L->ef[e][0];
                if (g < 0 || placed[g]) continue;
                if (is_folded(a)) {
                    ori_v3 u = ori_pattern_vertex(p, L->ev[e][0]), v = ori_pattern_vertex(p, L->ev[e][1]);
                    double r[6];
                    reflection(ori_v2_make(u.x, u.y), ori_v2_make(v.x, v.y), r);
                    compose(L->xf[f], r, L->xf[g]);
                } else
                    memcpy(L->xf[g], L->xf[f], sizeof(double) * 6);
                placed[g] = 1;
                order[tail++] = g;
            }
        }
        ori__free(placed);
        if (tail < nf) {
            int missing = 0;
            for (int f = 0; f < nf; ++f) {
                bool found = false;
                for (int i = 0; i < tail && !found; ++i) found = order[i] == f;
                if (!found) {
                    missing = f;
                    break;
                }
            }
            st = ori__fail_at(error, ORI_ERR_UNSUPPORTED, "faces_vertices", missing,
                              "face is not joined to face 0 by creases (a separate piece of paper)");
            goto done;
        }
        for (int f = 0; f < nf; ++f) L->flip[f] = L->xf[f][0] * L->xf[f][4] - L->xf[f][1] * L->xf[f][3] < 0.0;
        st = place_vertices(L, p, order, error);
    }
done:
    ori__free(order);
    return st;
}
