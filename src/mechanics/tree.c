// The sheet as a kinematic tree from the fixed face (breadth first over the public spanning
// tree) with its free fold-angle coordinates, poses by product of exponentials along it, and
// the spatial screw quantities the dynamics and the sizing share.
#include "mechanics_internal.h"

void ori__tree_init(mech_tree *t, const ori_mechanism *m, int fixed_face)
{
    memset(t, 0, sizeof *t);
    t->m = m;
    t->fixed = fixed_face;
    int F = t->faces = ori_mechanism_face_count(m);
    int E = t->edges = ori_mechanism_edge_count(m);
    t->joints = ori_mechanism_joint_count(m);
    t->order = ori__alloc(sizeof(int) * (size_t)(F + 1));
    t->parent = ori__alloc(sizeof(int) * (size_t)(F + 1));
    t->pedge = ori__alloc(sizeof(int) * (size_t)(F + 1));
    t->psign = ori__alloc(sizeof(int) * (size_t)(F + 1));
    t->pcol = ori__alloc(sizeof(int) * (size_t)(F + 1));
    t->depth = ori__alloc(sizeof(int) * (size_t)(F + 1));
    t->col_of_edge = ori__alloc(sizeof(int) * (size_t)(E + 1));
    t->edge_of_col = ori__alloc(sizeof(int) * (size_t)(E + 1));
    ori_mechanism_spanning_tree(m, fixed_face, t->parent, t->pedge);
    for (int e = 0; e < E; ++e) {
        t->col_of_edge[e] = -1;
        int j = ori_mechanism_edge_joint(m, e);
        if (j == ORI_NULL_INDEX || ori_mechanism_joint(m, j).kind != ORI_JOINT_REVOLUTE) continue;
        t->edge_of_col[t->n] = e;
        t->col_of_edge[e] = t->n++;
    }
    // Breadth-first order from the parent pointers: children after their parents.
    int *head = ori__alloc(sizeof(int) * (size_t)(F + 1)), *next = ori__alloc(sizeof(int) * (size_t)(F + 1));
    for (int f = 0; f < F; ++f) head[f] = next[f] = -1;
    for (int f = F - 1; f >= 0; --f)
        if (t->parent[f] != ORI_NULL_INDEX) {
            next[f] = head[t->parent[f]];
            head[t->parent[f]] = f;
        }
    int n = 0;
    t->order[n++] = fixed_face;
    t->depth[fixed_face] = 0;
    for (int k = 0; k < n; ++k)
        for (int c = head[t->order[k]]; c != -1; c = next[c]) {
            t->depth[c] = t->depth[t->order[k]] + 1;
            t->order[n++] = c;
        }
    ori__free(head);
    ori__free(next);
    for (int f = 0; f < F; ++f) {
        t->psign[f] = 0;
        t->pcol[f] = -1;
        if (t->parent[f] == ORI_NULL_INDEX) continue;
        ori_joint J = ori_mechanism_joint(m, ori_mechanism_edge_joint(m, t->pedge[f]));
        t->psign[f] = J.face_left == f ? 1 : -1;
        t->pcol[f] = t->col_of_edge[t->pedge[f]];
    }
}

void ori__tree_free(mech_tree *t)
{
    ori__free(t->order);
    ori__free(t->parent);
    ori__free(t->pedge);
    ori__free(t->psign);
    ori__free(t->pcol);
    ori__free(t->depth);
    ori__free(t->col_of_edge);
    ori__free(t->edge_of_col);
    memset(t, 0, sizeof *t);
}

void ori__tree_poses(const mech_tree *t, const double *edge_angles, ori_rigid g0, ori_rigid *poses)
{
    for (int k = 0; k < t->faces; ++k) {
        int f = t->order[k];
        if (t->parent[f] == ORI_NULL_INDEX) {
            poses[f] = g0;
            continue;
        }
        ori_joint J = ori_mechanism_joint(t->m, ori_mechanism_edge_joint(t->m, t->pedge[f]));
        double th = edge_angles[t->pedge[f]];
        ori_rigid rel = th == 0.0 ? ori_rigid_identity() : ori_twist_exp(ori_twist_from_axis(J.q, J.omega), t->psign[f] * th);
        poses[f] = ori_rigid_compose(poses[t->parent[f]], rel);
    }
}

sv6 ori__tree_twist(const mech_tree *t, int f, const ori_rigid *poses, double mpu)
{
    ORI_ASSERT(t->parent[f] != ORI_NULL_INDEX);
    ori_joint J = ori_mechanism_joint(t->m, ori_mechanism_edge_joint(t->m, t->pedge[f]));
    // The crease's axis is fixed in both faces: take it from the parent's pose.
    const ori_rigid *g = &poses[t->parent[f]];
    ori_v3 w = ori_rigid_apply_dir(*g, J.omega);
    ori_v3 q = ori_v3_scale(ori_rigid_apply(*g, J.q), mpu);
    sv6 s = sv6_make(ori_v3_cross(q, w), w); // v = −ω × q = q × ω
    return sv6_scale(s, (double)t->psign[f]);
}

sv6 ori__inertia_apply(const body_inertia *b, sv6 V)
{
    // Linear momentum m(v + ω × c) = m·v + ω × h; angular momentum about the origin
    // I_c ω + c × p = h × v + I_O ω.
    ori_v3 p = ori_v3_add(ori_v3_scale(V.v, b->m), ori_v3_cross(V.w, b->h));
    ori_v3 L = ori_v3_add(ori_v3_cross(b->h, V.v), ori_m3_apply(b->io, V.w));
    return sv6_make(p, L);
}

body_inertia ori__body_world(const ori_face_mass *fm, ori_rigid g, double mpu)
{
    body_inertia b;
    b.m = fm->mass_kg;
    ori_v3 c = ori_v3_add(ori_m3_apply(g.r, fm->centroid_m), ori_v3_scale(g.t, mpu));
    b.h = ori_v3_scale(c, b.m);
    ori_m3 ic = ori_m3_mul(ori_m3_mul(g.r, fm->inertia_kg_m2), ori_m3_transpose(g.r));
    double cc = ori_v3_dot(c, c);
    double cv[3] = {c.x, c.y, c.z};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) b.io.m[i][j] = ic.m[i][j] + b.m * ((i == j ? cc : 0.0) - cv[i] * cv[j]);
    return b;
}

void ori__body_add(body_inertia *acc, const body_inertia *b)
{
    acc->m += b->m;
    acc->h = ori_v3_add(acc->h, b->h);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) acc->io.m[i][j] += b->io.m[i][j];
}
