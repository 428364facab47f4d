// The posed mesh: every face triangulated once by ear clipping with exact orientation tests (in
// the flat sheet, or for a folded form in the plane of the face), front normals in the current
// pose, and the rigid pose of a face from positions.
#include <math.h>

#include "render_internal.h"

// --- ear clipping ---------------------------------------------------------------------------

// p[j] lies inside or on the boundary of the counter-clockwise triangle abc.
static bool in_closed_triangle(ori_v2 a, ori_v2 b, ori_v2 c, ori_v2 p)
{
    return ori_orient2d_sign(a, b, p) >= 0 && ori_orient2d_sign(b, c, p) >= 0 && ori_orient2d_sign(c, a, p) >= 0;
}

// Triangulate the simple counter-clockwise polygon p[0..n-1] into at most n − 2 triangles of
// local indices (counter-clockwise), returning their number. An ear is a strictly convex vertex
// whose triangle holds no other vertex, not even on its boundary; only reflex and flat vertices
// can be there (a convex vertex inside an ear implies a reflex one inside), so only they are
// tested. Every decision is an exact orientation sign. If a (degenerate) polygon has no ear, a
// convex vertex is clipped anyway; zero-area triangles are dropped.
static int ear_clip(const ori_v2 *p, int n, int *next, int *prev, bool *reflex, int (*out)[3])
{
    int count = 0;
    if (n < 3) return 0;
    for (int i = 0; i < n; ++i) {
        next[i] = (i + 1) % n;
        prev[i] = (i + n - 1) % n;
    }
    for (int i = 0; i < n; ++i) reflex[i] = ori_orient2d_sign(p[prev[i]], p[i], p[next[i]]) <= 0;
    int left = n, i = 0, misses = 0;
    while (left > 3) {
        int a = prev[i], c = next[i];
        bool ear = !reflex[i];
        if (ear) {
            for (int j = next[c]; j != a; j = next[j]) {
                if (!reflex[j]) continue;
                if (in_closed_triangle(p[a], p[i], p[c], p[j])) {
                    ear = false;
                    break;
                }
            }
        }
        if (!ear && misses > left) {
            // No ear in a whole round: a degenerate polygon. Clip the first convex vertex, or
            // drop a flat one.
            int k = i;
            do {
                if (ori_orient2d_sign(p[prev[k]], p[k], p[next[k]]) > 0) break;
                k = next[k];
            } while (k != i);
            i = k;
            a = prev[i];
            c = next[i];
            ear = true;
        }
        if (ear) {
            if (ori_orient2d_sign(p[a], p[i], p[c]) > 0) {
                out[count][0] = a;
                out[count][1] = i;
                out[count][2] = c;
                count++;
            }
            next[a] = c;
            prev[c] = a;
            left--;
            reflex[a] = ori_orient2d_sign(p[prev[a]], p[a], p[c]) <= 0;
            reflex[c] = ori_orient2d_sign(p[a], p[c], p[next[c]]) <= 0;
            misses = 0;
            i = a;
        } else {
            i = next[i];
            misses++;
        }
    }
    int a = prev[i], c = next[i];
    if (ori_orient2d_sign(p[a], p[i], p[c]) > 0) {
        out[count][0] = a;
        out[count][1] = i;
        out[count][2] = c;
        count++;
    }
    return count;
}

// Newell's normal of a polygon (twice its vector area).
static ori_v3 newell(const ori_v3 *pts, const int *idx, int n)
{
    ori_v3 s = {0, 0, 0};
    for (int k = 0; k < n; ++k) {
        ori_v3 a = pts[idx[k]], b = pts[idx[(k + 1) % n]];
        s.x += (a.y - b.y) * (a.z + b.z);
        s.y += (a.z - b.z) * (a.x + b.x);
        s.z += (a.x - b.x) * (a.y + b.y);
    }
    return s;
}

// Project a face onto the coordinate plane its normal is closest to, keeping its orientation
// (counter-clockwise when seen from the side its normal points to).
static void project_face(const ori_v3 *pts, const int *idx, int n, ori_v2 *out)
{
    ori_v3 nrm = newell(pts, idx, n);
    double ax = fabs(nrm.x), ay = fabs(nrm.y), az = fabs(nrm.z);
    for (int k = 0; k < n; ++k) {
        ori_v3 q = pts[idx[k]];
        if (az >= ax && az >= ay) out[k] = nrm.z >= 0 ? ori_v2_make(q.x, q.y) : ori_v2_make(q.y, q.x);
        else if (ax >= ay) out[k] = nrm.x >= 0 ? ori_v2_make(q.y, q.z) : ori_v2_make(q.z, q.y);
        else out[k] = nrm.y >= 0 ? ori_v2_make(q.z, q.x) : ori_v2_make(q.x, q.z);
    }
}

// --- creation and pose ----------------------------------------------------------------------

static ori_status check_positions(const ori_v3 *pos, int n, ori_error *error)
{
    for (int v = 0; v < n; ++v)
        if (!ori__coord_ok(pos[v].x) || !ori__coord_ok(pos[v].y) || !ori__coord_ok(pos[v].z))
            return ori__fail_at(error, ORI_ERR_RANGE, "vertices_coords", v, "position of vertex %d is not finite", v);
    return ORI_OK;
}

void ori__mesh_set_angles(ori_mesh *m, const double *fold_angles_rad)
{
    for (int e = 0; e < m->edge_count; ++e) m->angle[e] = fold_angles_rad ? fold_angles_rad[e] : m->pattern_angle[e];
}

static void update_normals(ori_mesh *m)
{
    for (int f = 0; f < m->face_count; ++f) {
        ori_v3 s = {0, 0, 0};
        for (int t = m->face_tri_start[f]; t < m->face_tri_start[f + 1]; ++t) {
            ori_v3 a = m->pos[m->tris[t].v[0]], b = m->pos[m->tris[t].v[1]], c = m->pos[m->tris[t].v[2]];
            s = ori_v3_add(s, ori_v3_cross(ori_v3_sub(b, a), ori_v3_sub(c, a)));
        }
        m->normal[f] = ori_v3_normalize(s);
    }
}

ori_status ori_mesh_create(const ori_state_view *state, ori_mesh **out, ori_error *error)
{
    ORI_ASSERT(state && out);
    *out = NULL;
    const ori_pattern *p = state->pattern;
    ORI_ASSERT(p);
    if (!ori_pattern_is_built(p)) return ori__fail(error, ORI_ERR_ARGUMENT, "the pattern is not built");
    int nv = ori_pattern_vertex_count(p), ne = ori_pattern_edge_count(p), nf = ori_pattern_face_count(p);
    if (nf < 1) return ori__fail_at(error, ORI_ERR_ARGUMENT, "faces_vertices", ORI_NULL_INDEX, "the pattern has no faces");
    if (state->positions) {
        ori_status st = check_positions(state->positions, nv, error);
        if (st != ORI_OK) return st;
    }
    ori_mesh *m = ori__calloc(1, sizeof *m);
    m->vertex_count = nv;
    m->edge_count = ne;
    m->face_count = nf;
    m->has_flat = !ori_pattern_is_folded_form(p) && !ori_pattern_is_3d(p);
    m->ref = ori__calloc((size_t)nv + 1, sizeof *m->ref);
    m->pos = ori__calloc((size_t)nv + 1, sizeof *m->pos);
    for (int v = 0; v < nv; ++v) {
        ori_v3 q = ori_pattern_vertex(p, v);
        if (m->has_flat) q.z = 0.0;
        else if (state->positions) q = state->positions[v];
        m->ref[v] = q;
    }
    m->edge_v = ori__calloc((size_t)ne + 1, sizeof *m->edge_v);
    m->edge_face = ori__calloc((size_t)ne + 1, sizeof *m->edge_face);
    m->assign = ori__calloc((size_t)ne + 1, sizeof *m->assign);
    m->angle = ori__calloc((size_t)ne + 1, sizeof *m->angle);
    m->pattern_angle = ori__calloc((size_t)ne + 1, sizeof *m->pattern_angle);
    for (int e = 0; e < ne; ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        m->edge_v[e][0] = ed.v[0];
        m->edge_v[e][1] = ed.v[1];
        m->assign[e] = ed.assignment;
        // Without fold angles the assignment gives the direction a flat-folded crease took.
        double a = ed.fold_angle_rad;
        if (a == 0.0 && !ori_pattern_has_fold_angles(p))
            a = ed.assignment == ORI_ASSIGN_VALLEY ? ORI_PI : ed.assignment == ORI_ASSIGN_MOUNTAIN ? -ORI_PI : 0.0;
        m->pattern_angle[e] = a;
        ori_pattern_edge_faces(p, e, m->edge_face[e]);
    }
    m->face_start = ori__calloc((size_t)nf + 1, sizeof *m->face_start);
    int total = 0, largest = 3;
    for (int f = 0; f < nf; ++f) {
        int n = ori_pattern_face_size(p, f);
        m->face_start[f] = total;
        total += n;
        if (n > largest) largest = n;
    }
    m->face_start[nf] = total;
    m->face_verts = ori__calloc((size_t)total + 1, sizeof *m->face_verts);
    m->face_side_edge = ori__calloc((size_t)total + 1, sizeof *m->face_side_edge);
    m->face_tri_start = ori__calloc((size_t)nf + 1, sizeof *m->face_tri_start);
    m->tris = ori__calloc((size_t)total + 1, sizeof *m->tris);
    m->normal = ori__calloc((size_t)nf + 1, sizeof *m->normal);
    m->fold_sign = ori__calloc((size_t)nf + 1, sizeof *m->fold_sign);

    ori_v2 *pts = ori__alloc(sizeof(ori_v2) * (size_t)largest);
    int *next = ori__alloc(sizeof(int) * (size_t)largest * 2);
    bool *reflex = ori__alloc(sizeof(bool) * (size_t)largest);
    int(*tri)[3] = ori__alloc(sizeof(int[3]) * (size_t)largest);
    int tc = 0;
    for (int f = 0; f < nf; ++f) {
        int o = m->face_start[f], n = m->face_start[f + 1] - o;
        int *fv = m->face_verts + o;
        ori_pattern_face_vertices(p, f, fv, n);
        ori_pattern_face_edges(p, f, m->face_side_edge + o, n);
        if (m->has_flat) {
            // A flat face listed clockwise is stored counter-clockwise: its front is the side
            // facing +z in the flat sheet.
            double area2 = 0.0;
            for (int k = 0; k < n; ++k) area2 += ori_v2_cross(ori_v2_make(m->ref[fv[k]].x, m->ref[fv[k]].y),
                                                            ori_v2_make(m->ref[fv[(k + 1) % n]].x, m->ref[fv[(k + 1) % n]].y));
            m->fold_sign[f] = area2 < 0.0 ? -1 : 1;
            if (area2 < 0.0) {
                for (int k = 0; k < n / 2; ++k) {
                    int t = fv[k];
                    fv[k] = fv[n - 1 - k];
                    fv[n - 1 - k] = t;
                }
                for (int k = 0; k < n; ++k) m->face_side_edge[o + k] = ori_pattern_find_edge(p, fv[k], fv[(k + 1) % n]);
            }
            for (int k = 0; k < n; ++k) pts[k] = ori_v2_make(m->ref[fv[k]].x, m->ref[fv[k]].y);
        } else {
            m->fold_sign[f] = 1;
            project_face(m->ref, fv, n, pts);
        }
        m->face_tri_start[f] = tc;
        int cnt = ear_clip(pts, n, next, next + largest, reflex, tri);
        for (int t = 0; t < cnt; ++t) {
            m->tris[tc].face = f;
            for (int k = 0; k < 3; ++k) m->tris[tc].v[k] = fv[tri[t][k]];
            tc++;
        }
    }
    m->face_tri_start[nf] = tc;
    m->tri_count = tc;
    ori__free(pts);
    ori__free(next);
    ori__free(reflex);
    ori__free(tri);

    ori_v3 lo = m->ref[0], hi = m->ref[0];
    for (int v = 1; v < nv; ++v) {
        lo = ori_v3_make(fmin(lo.x, m->ref[v].x), fmin(lo.y, m->ref[v].y), fmin(lo.z, m->ref[v].z));
        hi = ori_v3_make(fmax(hi.x, m->ref[v].x), fmax(hi.y, m->ref[v].y), fmax(hi.z, m->ref[v].z));
    }
    m->ref_diag = ori_v3_norm(ori_v3_sub(hi, lo));
    if (!(m->ref_diag > 0.0)) m->ref_diag = 1.0;
    ori_status st = ori_mesh_set_pose(m, state->positions ? state->positions : m->ref, state->fold_angles_rad, error);
    if (st != ORI_OK) {
        ori_mesh_destroy(m);
        return st;
    }
    *out = m;
    return ORI_OK;
}

void ori_mesh_destroy(ori_mesh *m)
{
    if (!m) return;
    ori__free(m->ref);
    ori__free(m->pos);
    ori__free(m->face_start);
    ori__free(m->face_verts);
    ori__free(m->face_side_edge);
    ori__free(m->face_tri_start);
    ori__free(m->tris);
    ori__free(m->normal);
    ori__free(m->fold_sign);
    ori__free(m->edge_v);
    ori__free(m->edge_face);
    ori__free(m->assign);
    ori__free(m->angle);
    ori__free(m->pattern_angle);
    ori__free(m);
}

ori_status ori_mesh_set_pose(ori_mesh *m, const ori_v3 *positions, const double *fold_angles_rad, ori_error *error)
{
    ORI_ASSERT(m && positions);
    ori_status st = check_positions(positions, m->vertex_count, error);
    if (st != ORI_OK) return st;
    if (positions != m->pos) memcpy(m->pos, positions, sizeof(ori_v3) * (size_t)m->vertex_count);
    ori__mesh_set_angles(m, fold_angles_rad);
    update_normals(m);
    return ORI_OK;
}

// --- queries --------------------------------------------------------------------------------

int ori_mesh_vertex_count(const ori_mesh *m) { return m->vertex_count; }
int ori_mesh_face_count(const ori_mesh *m) { return m->face_count; }
int ori_mesh_triangle_count(const ori_mesh *m) { return m->tri_count; }

ori_mesh_triangle ori_mesh_triangle_at(const ori_mesh *m, int t)
{
    ORI_ASSERT(t >= 0 && t < m->tri_count);
    return m->tris[t];
}

int ori_mesh_face_triangles(const ori_mesh *m, int face, int *first)
{
    ORI_ASSERT(face >= 0 && face < m->face_count);
    if (first) *first = m->face_tri_start[face];
    return m->face_tri_start[face + 1] - m->face_tri_start[face];
}

ori_v3 ori_mesh_vertex(const ori_mesh *m, int v)
{
    ORI_ASSERT(v >= 0 && v < m->vertex_count);
    return m->pos[v];
}

ori_v3 ori_mesh_reference_vertex(const ori_mesh *m, int v)
{
    ORI_ASSERT(v >= 0 && v < m->vertex_count);
    return m->ref[v];
}

bool ori_mesh_has_flat(const ori_mesh *m) { return m->has_flat; }

ori_v3 ori_mesh_face_normal(const ori_mesh *m, int face)
{
    ORI_ASSERT(face >= 0 && face < m->face_count);
    return m->normal[face];
}

double ori_mesh_area(const ori_mesh *m)
{
    double s = 0.0;
    for (int t = 0; t < m->tri_count; ++t) {
        ori_v3 a = m->pos[m->tris[t].v[0]], b = m->pos[m->tris[t].v[1]], c = m->pos[m->tris[t].v[2]];
        s += 0.5 * ori_v3_norm(ori_v3_cross(ori_v3_sub(b, a), ori_v3_sub(c, a)));
    }
    return s;
}

void ori_mesh_bounds(const ori_mesh *m, ori_v3 *lo, ori_v3 *hi)
{
    ori_v3 a = m->pos[0], b = m->pos[0];
    for (int v = 1; v < m->vertex_count; ++v) {
        ori_v3 q = m->pos[v];
        a = ori_v3_make(fmin(a.x, q.x), fmin(a.y, q.y), fmin(a.z, q.z));
        b = ori_v3_make(fmax(b.x, q.x), fmax(b.y, q.y), fmax(b.z, q.z));
    }
    if (lo) *lo = a;
    if (hi) *hi = b;
}

// The side of a face its frames are built on: its longest side in the reference position.
static int frame_side(const ori_mesh *m, int face)
{
    int o = m->face_start[face], n = m->face_start[face + 1] - o;
    const int *fv = m->face_verts + o;
    int best = 0;
    double len = -1.0;
    for (int k = 0; k < n; ++k) {
        double l = ori_v3_norm(ori_v3_sub(m->ref[fv[(k + 1) % n]], m->ref[fv[k]]));
        if (l > len) {
            len = l;
            best = k;
        }
    }
    return best;
}

// An orthonormal frame of a face: origin at the start of side k, e1 along that side, e3 its
// unit normal (Newell), e2 = e3 × e1. Returns false for a degenerate face.
static bool face_frame(const ori_mesh *m, int face, int k, const ori_v3 *pts, ori_v3 *origin, ori_m3 *axes)
{
    int o = m->face_start[face], n = m->face_start[face + 1] - o;
    const int *fv = m->face_verts + o;
    ori_v3 e3 = ori_v3_normalize(newell(pts, fv, n));
    ori_v3 e1 = ori_v3_normalize(ori_v3_sub(pts[fv[(k + 1) % n]], pts[fv[k]]));
    // Remove e1's component along e3 (a slightly bent face) and renormalise.
    e1 = ori_v3_normalize(ori_v3_sub(e1, ori_v3_scale(e3, ori_v3_dot(e1, e3))));
    if (ori_v3_norm(e1) == 0.0 || ori_v3_norm(e3) == 0.0) return false;
    ori_v3 e2 = ori_v3_cross(e3, e1);
    *origin = pts[fv[k]];
    ori_v3 cols[3] = {e1, e2, e3};
    for (int i = 0; i < 3; ++i) {
        axes->m[0][i] = cols[i].x;
        axes->m[1][i] = cols[i].y;
        axes->m[2][i] = cols[i].z;
    }
    return true;
}

ori_status ori_mesh_face_pose(const ori_mesh *m, int face, const ori_v3 *positions, ori_rigid *out, ori_error *error)
{
    ORI_ASSERT(m && positions && out);
    if (face < 0 || face >= m->face_count)
        return ori__fail_at(error, ORI_ERR_RANGE, "faces_vertices", face, "no face %d", face);
    ori_v3 o_ref, o_w;
    ori_m3 a_ref, a_w;
    int k = frame_side(m, face);
    if (!face_frame(m, face, k, m->ref, &o_ref, &a_ref) || !face_frame(m, face, k, positions, &o_w, &a_w))
        return ori__fail_at(error, ORI_ERR_DEGENERATE, "faces_vertices", face, "face %d is degenerate", face);
    ori_rigid g;
    g.r = ori_m3_mul(a_w, ori_m3_transpose(a_ref));
    g.t = ori_v3_sub(o_w, ori_m3_apply(g.r, o_ref));
    int o = m->face_start[face], n = m->face_start[face + 1] - o;
    double err = 0.0;
    for (int i = 0; i < n; ++i) {
        int v = m->face_verts[o + i];
        err = fmax(err, ori_v3_norm(ori_v3_sub(ori_rigid_apply(g, m->ref[v]), positions[v])));
    }
    if (!(err <= ORI_TOL_POSE_FIT_REL * m->ref_diag))
        return ori__fail_at(error, ORI_ERR_DEGENERATE, "faces_vertices", face,
                            "face %d is not a rigid copy of its reference (misfit %.3g)", face, err);
    *out = g;
    return ORI_OK;
}
