// Folded forms back to their crease pattern: a surface that is a folded flat sheet (every
// interior vertex's face angles sum to 2π) is developed isometrically into the plane without
// cuts. The faces are laid out along a breadth-first tree of the face graph (net.c's layout);
// every edge off the tree must then find its two copies at the same place (the check that also
// catches holes the sheet does not close around and cone points missed by the angle test), the
// sheet must not overlap itself (net.c's overlap test), and the crease pattern (every interior
// edge a crease with the fold angle of the shape) is folded back by the kinematics.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <orikin/fold.h>
#include <orikin/kinematics.h>
#include <orikin/tolerance.h>
#include <orikin/unfold.h>

#include "../core/core_internal.h"
#include "unfold_internal.h"


// Interior angle of a counter-clockwise polygon's corner i (radians, in (0, 2π)).
static double corner_angle(const ori_v2 *p, int k, int i)
{
    ori_v2 a = ori_v2_sub(p[(i + 1) % k], p[i]), b = ori_v2_sub(p[(i + k - 1) % k], p[i]);
    double t = atan2(ori_v2_cross(a, b), ori_v2_dot(a, b));
    return t < 0.0 ? t + 2.0 * ORI_PI : t;
}

// Fold the crease pattern back with the kinematics: face 0 placed where the shape has it, the
// fold angles closed onto the loop-closure manifold when they close within
// ORI_TOL_START_RESIDUAL (else posed along the spanning tree as they are). Fills the refold
// error (/ diag) and the loop residual of the angles; false when the mechanism cannot be made.
static bool refold(ori_unfold_net *net, double diag, ori_unfold_result *r)
{
    ori_error err;
    ori_build_def bd = ori_default_build_def();
    bd.check_planarity = false;
    if (ori_pattern_build(net->pattern, &bd, &err) != ORI_OK) return false;
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = net->pattern;
    ori_mechanism *mech = NULL;
    if (ori_mechanism_create(&md, &mech, &err) != ORI_OK) return false;
    int nv = ori_pattern_vertex_count(net->pattern), ne = ori_pattern_edge_count(net->pattern);
    double *angles = ori__alloc(((size_t)ne + 1) * sizeof *angles);
    ori_v3 *pos = ori__alloc(((size_t)nv + 1) * sizeof *pos);
    for (int e = 0; e < ne; ++e) angles[e] = ori_pattern_edge(net->pattern, e).fold_angle_rad;
    r->fold_residual = ori_mechanism_residual(mech, angles);
    ori_rigid pose;
    bool ok = ori_mechanism_face_pose_from_coords(mech, 0, net->shape, &pose, &err) == ORI_OK;
    if (ok && ori_mechanism_pose_state(mech, angles, 0, pose, NULL, pos, NULL, &err) != ORI_OK)
        ori_mechanism_vertex_positions(mech, angles, 0, pose, pos);
    if (ok) {
        double worst = 0.0;
        for (int v = 0; v < nv; ++v) worst = fmax(worst, ori_v3_norm(ori_v3_sub(pos[v], net->shape[v])) / diag);
        r->max_refold_error = worst;
        r->refolded = true;
    }
    ori__free(angles), ori__free(pos);
    ori_mechanism_destroy(mech);
    return ok;
}

ori_status ori_unfold_develop(const ori_mesh *m, double tolerance_rad, ori_unfold_net **out, ori_error *error)
{
    ORI_ASSERT(m && out);
    *out = NULL;
    if (!(tolerance_rad >= 0.0) || tolerance_rad > 0.5) // also NaN
        return ori__fail(error, ORI_ERR_RANGE, "angle tolerance must be from 0 to 0.5 rad");
    double tol_angle = tolerance_rad > 0.0 ? tolerance_rad : ORI_TOL_DEVELOP_ANGLE_RAD;
    double tol_close = fmax(ORI_TOL_DEVELOP_CLOSE_REL, tol_angle);
    net_ctx c;
    ori__net_ctx_init(&c, m);
    int nf = m->nf, nh = m->fstart[nf], nv = m->nv;
    ori_status st = ORI_OK;
    bool *all = ori__calloc((size_t)c.ne + 1, sizeof *all);
    if (!ori__net_connected_without(&c, all, nf)) st = ori__fail(error, ORI_ERR_TOPOLOGY, "the surface is not connected");
    ori_unfold_result res;
    memset(&res, 0, sizeof res);
    res.pieces = 1, res.faces = nf, res.input_faces = m->src_start[nf];
    res.best_try = -1, res.distinct_nets = -1, res.fold_order = ORI_FOLD_ORDER_NONE;
    res.max_refold_error = res.fold_residual = -1.0;
    res.developed = true;

    // 1. angle sums at the interior vertices (3D face angles, from each face's own plane frame)
    double *sum = ori__calloc((size_t)nv + 1, sizeof *sum);
    bool *boundary = ori__calloc((size_t)nv + 1, sizeof *boundary), *used = ori__calloc((size_t)nv + 1, sizeof *used);
    for (int f = 0; f < nf; ++f) {
        int k = ori__net_fsize(m, f);
        for (int i = 0; i < k; ++i) {
            int v = m->fv[m->fstart[f] + i];
            sum[v] += corner_angle(c.local + m->fstart[f], k, i);
            used[v] = true;
        }
    }
    for (int k = 0; k < c.ne; ++k)
        if (c.e[k].g < 0) boundary[c.e[k].a] = boundary[c.e[k].b] = true;
    int worst_v = -1;
    double worst_defect = 0.0;
    for (int v = 0; v < nv; ++v) {
        if (!used[v] || boundary[v]) continue;
        res.interior_vertices++;
        double d = fabs(sum[v] - 2.0 * ORI_PI);
        if (worst_v < 0 || d > worst_defect) worst_defect = d, worst_v = v;
    }
    res.max_angle_defect_rad = worst_v >= 0 ? worst_defect : 0.0;
    if (st == ORI_OK && worst_v >= 0 && worst_defect > tol_angle)
        st = ori__fail_at(error, ORI_ERR_NOT_FOUND, "vertices_coords", worst_v,
                          "not developable at vertex %d: its face angles sum to %.6g° (a flat sheet has 360°)", worst_v,
                          ori_rad_to_deg(sum[worst_v]));

    // 2. lay out along a breadth-first tree; the edges off the tree must close
    int *order = ori__alloc(((size_t)nf + 1) * sizeof *order), *parent_edge = ori__alloc(((size_t)nf + 1) * sizeof *parent_edge);
    bool *placed = ori__alloc(((size_t)nf + 1) * sizeof *placed), *tree = ori__calloc((size_t)c.ne + 1, sizeof *tree);
    for (int k = 0; k < c.ne; ++k) all[k] = c.e[k].g >= 0;
    if (st == ORI_OK) {
        ori__net_layout(&c, all, 0, order, parent_edge, placed);
        for (int f = 0; f < nf; ++f)
            if (parent_edge[f] >= 0) tree[parent_edge[f]] = true;
        int bad = -1;
        double worst_gap = 0.0;
        for (int k = 0; k < c.ne; ++k) {
            const fedge *x = &c.e[k];
            if (x->g < 0 || tree[k]) continue;
            int kf = ori__net_fsize(m, x->f), kg = ori__net_fsize(m, x->g);
            ori_v2 fa = c.pos[m->fstart[x->f] + x->fi], fb = c.pos[m->fstart[x->f] + (x->fi + 1) % kf];
            ori_v2 gb = c.pos[m->fstart[x->g] + x->gi], ga = c.pos[m->fstart[x->g] + (x->gi + 1) % kg];
            double gap = fmax(ori_v2_norm(ori_v2_sub(fa, ga)), ori_v2_norm(ori_v2_sub(fb, gb))) / m->diag;
            if (bad < 0 || gap > worst_gap) worst_gap = gap, bad = k;
        }
        res.max_closing_error = bad >= 0 ? worst_gap : 0.0;
        if (bad >= 0 && worst_gap > tol_close)
            st = ori__fail_at(error, ORI_ERR_NOT_FOUND, "vertices_coords", c.e[bad].a,
                              "not developable without a cut: laid out flat, the two sides of edge %d–%d end %.3g "
                              "(relative) apart (the sheet does not close around a hole or a cone point)",
                              c.e[bad].a, c.e[bad].b, worst_gap);
    }

    // 3. one flat position per sheet vertex: the mean of its corners (corners united across edges)
    int *uf = ori__alloc(((size_t)nh + 1) * sizeof *uf), *cnt = ori__calloc((size_t)nh + 1, sizeof *cnt);
    ori_v2 *mean = ori__calloc((size_t)nh + 1, sizeof *mean);
    if (st == ORI_OK) {
        for (int i = 0; i < nh; ++i) uf[i] = i;
        for (int k = 0; k < c.ne; ++k) {
            const fedge *x = &c.e[k];
            if (x->g < 0) continue;
            int kf = ori__net_fsize(m, x->f), kg = ori__net_fsize(m, x->g);
            int pairs[2][2] = {{m->fstart[x->f] + x->fi, m->fstart[x->g] + (x->gi + 1) % kg},
                               {m->fstart[x->f] + (x->fi + 1) % kf, m->fstart[x->g] + x->gi}};
            for (int t = 0; t < 2; ++t) {
                int r1 = ori__uf_root(uf, pairs[t][0]), r2 = ori__uf_root(uf, pairs[t][1]);
                if (r1 != r2) uf[r1] = r2;
            }
        }
        for (int i = 0; i < nh; ++i) {
            int r = ori__uf_root(uf, i);
            mean[r] = ori_v2_add(mean[r], c.pos[i]), cnt[r]++;
        }
        for (int i = 0; i < nh; ++i) {
            int r = ori__uf_root(uf, i);
            c.pos[i] = ori_v2_scale(mean[r], 1.0 / cnt[r]);
        }
        res.max_length_error = 0.0;
        for (int k = 0; k < c.ne; ++k) {
            const fedge *x = &c.e[k];
            int kf = ori__net_fsize(m, x->f);
            double flat = ori_v2_norm(ori_v2_sub(c.pos[m->fstart[x->f] + (x->fi + 1) % kf], c.pos[m->fstart[x->f] + x->fi]));
            double l3 = ori_v3_norm(ori_v3_sub(m->v[x->b], m->v[x->a]));
            res.max_length_error = fmax(res.max_length_error, fabs(flat - l3) / l3);
        }
    }

    // 4. the developed sheet must not overlap itself
    int *tri_start = ori__alloc(((size_t)nf + 2) * sizeof *tri_start);
    int *tri = ori__alloc(((size_t)nh + 1) * 3 * sizeof *tri);
    if (st == ORI_OK) {
        ori__net_build_tris(&c, tri_start, tri);
        if (ori__net_count_overlaps(&c, tri_start, tri, NULL, 1) > 0) {
            double tol = ORI_TOL_UNFOLD_OVERLAP_REL * m->diag;
            int bf = -1, bg = -1;
            for (int f = 0; f < nf && bf < 0; ++f)
                for (int g = f + 1; g < nf && bf < 0; ++g)
                    if (ori__net_faces_overlap(&c, f, g, tri_start, tri, tol)) bf = f, bg = g;
            int sf = bf >= 0 ? m->src[m->src_start[bf]] : 0, sg = bg >= 0 ? m->src[m->src_start[bg]] : 0;
            res.overlaps = 1;
            st = ori__fail_at(error, ORI_ERR_NOT_FOUND, "faces_vertices", sf,
                              "not developable without a cut: the developed sheet overlaps itself (faces %d and %d)", sf,
                              sg);
        }
    }

    if (st == ORI_OK) {
        int *piece = ori__calloc((size_t)nf + 1, sizeof *piece); // one piece: the sheet
        ori_unfold_net *net = ori__net_make(&c, all, piece, 1);
        ori__free(piece);
        refold(net, m->diag, &res);
        net->result = res;
        *out = net;
    }
    ori__free(tri_start), ori__free(tri), ori__free(uf), ori__free(cnt), ori__free(mean);
    ori__free(order), ori__free(parent_edge), ori__free(placed), ori__free(tree);
    ori__free(sum), ori__free(boundary), ori__free(used), ori__free(all);
    ori__net_ctx_free(&c);
    return st;
}
