// The collision checker of one pattern: faces (FOLD faces_vertices), which faces share a
// vertex, convex pieces of non-convex faces (ear clipping, once), and the check of one state:
// face planes and boxes, the broad phase (bvh.c), the exact pair test (narrow.c), the contacts
// and the least clearance between faces that share no vertex.
#include <stdlib.h>

#include "collision_internal.h"

ori_collider_def ori_default_collider_def(void)
{
    ori_collider_def d;
    memset(&d, 0, sizeof d);
    d.pattern = NULL;
    d.clearance = 0.0;
    d.internal_value = ORI__DEF_COOKIE;
    return d;
}

// --- creation -------------------------------------------------------------------------------

static bool convex_crease_pair(const ori_collider *c, int f, int g);

static int cmp_int(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

// Ear clipping of a simple polygon given by 2D points (counter-clockwise or not); triangles as
// positions into the cycle. Returns the triangle count, or -1 when no ear is found (a
// self-touching or degenerate cycle).
static int ear_clip(const ori_v2 *pt, int n, int *tri_out)
{
    double area = 0.0;
    for (int i = 0; i < n; ++i) area += ori_v2_cross(pt[i], pt[(i + 1) % n]);
    int *idx = ori__alloc(sizeof(int) * (size_t)n);
    for (int i = 0; i < n; ++i) idx[i] = area >= 0.0 ? i : n - 1 - i;
    int m = n, count = 0, guard = 0;
    int i = 0;
    while (m > 3 && guard < 2 * m) {
        int a = idx[(i + m - 1) % m], b = idx[i % m], cc = idx[(i + 1) % m];
        bool ear = ori_orient2d_sign(pt[a], pt[b], pt[cc]) > 0;
        for (int k = 0; k < m && ear; ++k) {
            int v = idx[k];
            if (v == a || v == b || v == cc) continue;
            // a vertex inside or on the candidate triangle blocks the ear
            if (ori_orient2d_sign(pt[a], pt[b], pt[v]) >= 0 && ori_orient2d_sign(pt[b], pt[cc], pt[v]) >= 0 &&
                ori_orient2d_sign(pt[cc], pt[a], pt[v]) >= 0)
                ear = false;
        }
        if (ear) {
            tri_out[3 * count] = a;
            tri_out[3 * count + 1] = b;
            tri_out[3 * count + 2] = cc;
            count++;
            memmove(idx + i % m, idx + i % m + 1, sizeof(int) * (size_t)(m - i % m - 1));
            m--;
            guard = 0;
            i = i % m;
        } else {
            i = (i + 1) % m;
            guard++;
        }
    }
    if (m == 3) {
        tri_out[3 * count] = idx[0];
        tri_out[3 * count + 1] = idx[1];
        tri_out[3 * count + 2] = idx[2];
        count++;
    } else {
        count = -1;
    }
    ori__free(idx);
    return count;
}

// The face's cycle in 2D: the flat sheet's xy, or (folded forms) its own plane.
static void face_2d(const ori_pattern *p, const int *fv, int n, ori_v2 *out)
{
    ori_v3 nrm = ori_v3_make(0.0, 0.0, 0.0), p0 = ori_pattern_vertex(p, fv[0]);
    for (int i = 0; i < n; ++i) {
        ori_v3 a = ori_v3_sub(ori_pattern_vertex(p, fv[i]), p0), b = ori_v3_sub(ori_pattern_vertex(p, fv[(i + 1) % n]), p0);
        nrm = ori_v3_add(nrm, ori_v3_cross(a, b));
    }
    nrm = ori_v3_normalize(nrm);
    bool flat = fabs(nrm.x) + fabs(nrm.y) == 0.0 || !ori_pattern_is_3d(p);
    ori_v3 e1 = ori_v3_make(1.0, 0.0, 0.0), e2 = ori_v3_make(0.0, 1.0, 0.0);
    if (!flat) {
        ori_v3 ref = fabs(nrm.x) < 0.6 ? ori_v3_make(1.0, 0.0, 0.0) : ori_v3_make(0.0, 1.0, 0.0);
        e1 = ori_v3_normalize(ori_v3_sub(ref, ori_v3_scale(nrm, ori_v3_dot(ref, nrm))));
        e2 = ori_v3_cross(nrm, e1);
    }
    for (int i = 0; i < n; ++i) {
        ori_v3 q = ori_v3_sub(ori_pattern_vertex(p, fv[i]), p0);
        out[i] = ori_v2_make(ori_v3_dot(q, e1), ori_v3_dot(q, e2));
    }
}

static bool convex_cycle(const ori_v2 *pt, int n)
{
    int pos = 0, neg = 0;
    for (int i = 0; i < n; ++i) {
        int s = ori_orient2d_sign(pt[i], pt[(i + 1) % n], pt[(i + 2) % n]);
        pos += s > 0;
        neg += s < 0;
    }
    return pos == 0 || neg == 0;
}

ori_status ori_collider_create(const ori_collider_def *def, ori_collider **out, ori_error *error)
{
    ORI_ASSERT(def && def->internal_value == ORI__DEF_COOKIE && def->pattern && out);
    *out = NULL;
    ori_error_clear(error);
    const ori_pattern *p = def->pattern;
    if (!(def->clearance >= 0.0) || !isfinite(def->clearance))
        return ori__fail(error, ORI_ERR_RANGE, "the clearance must be a length >= 0, got %g", def->clearance);
    int nf = ori_pattern_face_count(p), nv = ori_pattern_vertex_count(p);
    if (nf == 0) return ori__fail_at(error, ORI_ERR_TOPOLOGY, "faces_vertices", ORI_NULL_INDEX, "the pattern has no faces");
    ori_collider *c = ori__calloc(1, sizeof *c);
    c->vertex_count = nv;
    c->face_count = nf;
    c->edge_count = ori_pattern_edge_count(p);
    c->diagonal = ori_pattern_diagonal(p);
    c->clearance = def->clearance;
    c->face_off = ori__alloc(sizeof(int) * (size_t)(nf + 1));
    c->face_off[0] = 0;
    for (int f = 0; f < nf; ++f) {
        int s = ori_pattern_face_size(p, f);
        c->face_off[f + 1] = c->face_off[f] + s;
        if (s > c->max_face) c->max_face = s;
    }
    int total = c->face_off[nf];
    c->face_verts = ori__alloc(sizeof(int) * (size_t)(total + 1));
    for (int f = 0; f < nf; ++f)
        ori_pattern_face_vertices(p, f, c->face_verts + c->face_off[f], c->face_off[f + 1] - c->face_off[f]);

    // Convex pieces: non-convex faces are split into triangles once (faces are rigid).
    c->tri_off = ori__alloc(sizeof(int) * (size_t)(nf + 1));
    c->tri_off[0] = 0;
    int tri_cap = 0, tri_n = 0;
    c->tris = NULL;
    ori_v2 *pt = ori__alloc(sizeof(ori_v2) * (size_t)(c->max_face + 1));
    int *tri = ori__alloc(sizeof(int) * (size_t)(3 * c->max_face + 3));
    for (int f = 0; f < nf; ++f) {
        int n = c->face_off[f + 1] - c->face_off[f];
        const int *fv = c->face_verts + c->face_off[f];
        int added = 0;
        if (n > 3) {
            face_2d(p, fv, n, pt);
            if (!convex_cycle(pt, n)) {
                added = ear_clip(pt, n, tri);
                if (added < 0) {
                    ori__free(pt);
                    ori__free(tri);
                    ori_collider_destroy(c);
                    return ori__fail_at(error, ORI_ERR_DEGENERATE, "faces_vertices", f,
                                        "the face is not a simple polygon (it cannot be split into triangles)");
                }
                ORI__RESERVE(c->tris, tri_cap, 3 * (tri_n + added));
                for (int k = 0; k < 3 * added; ++k) c->tris[3 * tri_n + k] = tri[k];
                tri_n += added;
            }
        }
        c->tri_off[f + 1] = tri_n;
    }
    ori__free(pt);
    ori__free(tri);

    // Faces sharing a vertex: through the vertex → faces incidence.
    int *vf_off = ori__calloc((size_t)nv + 2, sizeof(int));
    for (int k = 0; k < total; ++k) vf_off[c->face_verts[k] + 1]++;
    for (int v = 0; v < nv; ++v) vf_off[v + 1] += vf_off[v];
    int *vf = ori__alloc(sizeof(int) * (size_t)(total + 1));
    int *fill = ori__alloc(sizeof(int) * (size_t)(nv + 1));
    memcpy(fill, vf_off, sizeof(int) * (size_t)(nv + 1));
    for (int f = 0; f < nf; ++f)
        for (int k = c->face_off[f]; k < c->face_off[f + 1]; ++k) vf[fill[c->face_verts[k]]++] = f;
    c->adj_off = ori__alloc(sizeof(int) * (size_t)(nf + 1));
    c->adj_off[0] = 0;
    int adj_cap = 0, adj_n = 0;
    c->adj = NULL;
    for (int f = 0; f < nf; ++f) {
        int start = adj_n;
        for (int k = c->face_off[f]; k < c->face_off[f + 1]; ++k) {
            int v = c->face_verts[k];
            for (int j = vf_off[v]; j < vf_off[v + 1]; ++j)
                if (vf[j] != f) ORI__PUSH(c->adj, adj_n, adj_cap, vf[j]);
        }
        if (adj_n - start > 1) qsort(c->adj + start, (size_t)(adj_n - start), sizeof(int), cmp_int);
        int w = start;
        for (int k = start; k < adj_n; ++k)
            if (k == start || c->adj[k] != c->adj[k - 1]) c->adj[w++] = c->adj[k];
        adj_n = w;
        c->adj_off[f + 1] = adj_n;
    }
    ori__free(vf_off);
    ori__free(vf);
    ori__free(fill);
    c->adj_kind = ori__alloc((size_t)adj_n + 1);
    for (int f = 0; f < nf; ++f)
        for (int k = c->adj_off[f]; k < c->adj_off[f + 1]; ++k)
            c->adj_kind[k] = convex_crease_pair(c, f, c->adj[k]) ? COL_ADJ_CREASE : COL_ADJ_VERTEX;

    c->geom = ori__alloc(sizeof(col_geom) * (size_t)nf);
    c->boxes = ori__alloc(sizeof(col_box) * (size_t)nf);
    col_work_init(&c->work, c->max_face);
    *out = c;
    return ORI_OK;
}

void ori_collider_destroy(ori_collider *c)
{
    if (!c) return;
    ori__free(c->face_off);
    ori__free(c->face_verts);
    ori__free(c->tri_off);
    ori__free(c->tris);
    ori__free(c->adj_off);
    ori__free(c->adj);
    ori__free(c->adj_kind);
    ori__free(c->geom);
    ori__free(c->boxes);
    col_bvh_free(&c->bvh);
    ori__free(c->contacts);
    ori__free(c->cloud_pairs);
    col_work_free(&c->work);
    ori__free(c);
}

int ori_collider_face_count(const ori_collider *c)
{
    ORI_ASSERT(c);
    return c->face_count;
}

int ori_collider_vertex_count(const ori_collider *c)
{
    ORI_ASSERT(c);
    return c->vertex_count;
}

col_adjacency col_adjacency_of(const ori_collider *c, int f, int g)
{
    int lo = c->adj_off[f], hi = c->adj_off[f + 1];
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (c->adj[mid] < g) lo = mid + 1;
        else hi = mid;
    }
    return lo < c->adj_off[f + 1] && c->adj[lo] == g ? (col_adjacency)c->adj_kind[lo] : COL_ADJ_NONE;
}

bool ori_collider_adjacent(const ori_collider *c, int f, int g)
{
    ORI_ASSERT(c && f >= 0 && f < c->face_count && g >= 0 && g < c->face_count);
    return f != g && col_adjacency_of(c, f, g) != COL_ADJ_NONE;
}

int col_shared_vertices(const ori_collider *c, int f, int g, int *out, int cap)
{
    int n = 0;
    for (int i = c->face_off[f]; i < c->face_off[f + 1]; ++i)
        for (int j = c->face_off[g]; j < c->face_off[g + 1]; ++j)
            if (c->face_verts[i] == c->face_verts[j]) {
                if (n < cap) out[n] = c->face_verts[i];
                n++;
            }
    return n;
}

// Two convex faces with a common side (a crease).
static bool convex_crease_pair(const ori_collider *c, int f, int g)
{
    if (c->tri_off[f + 1] > c->tri_off[f] || c->tri_off[g + 1] > c->tri_off[g]) return false;
    int nf = c->face_off[f + 1] - c->face_off[f], ng = c->face_off[g + 1] - c->face_off[g];
    const int *a = c->face_verts + c->face_off[f], *b = c->face_verts + c->face_off[g];
    for (int i = 0; i < nf; ++i) {
        int u = a[i], v = a[(i + 1) % nf];
        for (int j = 0; j < ng; ++j) {
            int x = b[j], y = b[(j + 1) % ng];
            if ((u == x && v == y) || (u == y && v == x)) return true;
        }
    }
    return false;
}

// --- one state ------------------------------------------------------------------------------

ori_status col_state_prepare(ori_collider *c, const ori_v3 *positions, ori_error *error)
{
    ORI_ASSERT(positions);
    for (int v = 0; v < c->vertex_count; ++v)
        if (!ori__coord_ok(positions[v].x) || !ori__coord_ok(positions[v].y) || !ori__coord_ok(positions[v].z))
            return ori__fail_at(error, ORI_ERR_RANGE, "vertices_coords", v, "the coordinate is not a finite number");
    c->pos = positions;
    double maxdev = 0.0;
    double planar = ORI_TOL_FACE_PLANAR_REL * c->diagonal;
    double tiny = ORI_TOL_PENETRATION_REL * c->diagonal;
    for (int f = 0; f < c->face_count; ++f) {
        const int *fv = c->face_verts + c->face_off[f];
        int n = c->face_off[f + 1] - c->face_off[f];
        ori_v3 p0 = positions[fv[0]];
        ori_v3 area = ori_v3_make(0.0, 0.0, 0.0), sum = ori_v3_make(0.0, 0.0, 0.0);
        col_box box = {p0, p0};
        for (int i = 0; i < n; ++i) {
            ori_v3 p = positions[fv[i]];
            ori_v3 a = ori_v3_sub(p, p0), b = ori_v3_sub(positions[fv[(i + 1) % n]], p0);
            area = ori_v3_add(area, ori_v3_cross(a, b));
            sum = ori_v3_add(sum, a);
            box.lo = ori_v3_make(fmin(box.lo.x, p.x), fmin(box.lo.y, p.y), fmin(box.lo.z, p.z));
            box.hi = ori_v3_make(fmax(box.hi.x, p.x), fmax(box.hi.y, p.y), fmax(box.hi.z, p.z));
        }
        double a2 = 0.5 * ori_v3_norm(area);
        if (!(a2 > tiny * tiny))
            return ori__fail_at(error, ORI_ERR_DEGENERATE, "faces_vertices", f, "the face has no area (its vertices are collinear)");
        col_geom *g = &c->geom[f];
        g->n = ori_v3_normalize(area);
        g->o = ori_v3_add(p0, ori_v3_scale(sum, 1.0 / (double)n));
        g->d = ori_v3_dot(g->n, g->o);
        g->dev = 0.0;
        int worst = fv[0];
        for (int i = 0; i < n; ++i) {
            double dv = fabs(ori_v3_dot(g->n, ori_v3_sub(positions[fv[i]], g->o)));
            if (dv > g->dev) {
                g->dev = dv;
                worst = fv[i];
            }
        }
        if (g->dev > planar)
            return ori__fail_at(error, ORI_ERR_DEGENERATE, "faces_vertices", f,
                                "the face is not planar: vertex %d is %.3g off its plane (at most %.3g, %g of the "
                                "pattern's size)",
                                worst, g->dev, planar, ORI_TOL_FACE_PLANAR_REL);
        // in-plane frame: e1 towards the vertex farthest from the first one, projected (a
        // folded form may repeat a position along a face's cycle)
        ori_v3 s = ori_v3_sub(positions[fv[1]], p0);
        for (int i = 2; i < n; ++i) {
            ori_v3 t = ori_v3_sub(positions[fv[i]], p0);
            if (ori_v3_dot(t, t) > ori_v3_dot(s, s)) s = t;
        }
        g->e1 = ori_v3_normalize(ori_v3_sub(s, ori_v3_scale(g->n, ori_v3_dot(s, g->n))));
        g->e2 = ori_v3_cross(g->n, g->e1);
        if (g->dev > maxdev) maxdev = g->dev;
        c->boxes[f] = box;
    }
    c->tol_pen = fmax(ORI_TOL_PENETRATION_REL * c->diagonal, ORI_COLLISION_PLANAR_SLACK * maxdev);
    c->tol_touch = fmax(ORI_TOL_CONTACT_REL * c->diagonal, c->tol_pen);
    return ORI_OK;
}

static void push_contact(ori_collider *c, const ori_contact *k)
{
    ORI__PUSH(c->contacts, c->contact_count, c->contact_cap, *k);
}

static void note_clearance(ori_collision_result *r, int f, int g, double d, ori_v3 pa, ori_v3 pb)
{
    if (d < r->min_clearance || (d == r->min_clearance && r->clearance_faces[0] == ORI_NULL_INDEX)) {
        r->min_clearance = d;
        r->clearance_faces[0] = f;
        r->clearance_faces[1] = g;
        r->clearance_points[0] = pa;
        r->clearance_points[1] = pb;
    }
}

void col_check_pair(ori_collider *c, ori_collision_result *r, bool want_clearance, int f, int g)
{
    col_check_pair_kind(c, r, want_clearance, f, g, col_adjacency_of(c, f, g));
}

void col_collider_set_reference(ori_collider *c, bool reference)
{
    c->reference = reference;
}

void col_check_pair_kind(ori_collider *c, ori_collision_result *r, bool want_clearance, int f, int g, col_adjacency kind)
{
    r->candidate_pairs++;
    bool adj = kind != COL_ADJ_NONE;
    col_pair_result pr;
    // Nearby pairs are the likely nearest: measuring them below the least distance so far
    // gives the nearest-pair search a tight bound from the start.
    c->distance_bound = want_clearance ? r->min_clearance : 0.0;
    col_pair_test(c, f, g, kind, &pr);
    if (pr.has_distance) r->distance_pairs++;
    ori_contact k;
    memset(&k, 0, sizeof k);
    k.face_a = f;
    k.face_b = g;
    k.adjacent = adj;
    k.stacked = pr.stacked;
    k.point = pr.point;
    if (pr.cls == COL_CROSS) {
        k.kind = ORI_CONTACT_PENETRATING;
        k.collides = true;
        push_contact(c, &k);
        if (!adj) note_clearance(r, f, g, 0.0, pr.point, pr.point);
    } else if (pr.cls == COL_TOUCH) {
        k.kind = ORI_CONTACT_TOUCHING;
        k.collides = !adj && c->clearance > 0.0;
        push_contact(c, &k);
        if (!adj) note_clearance(r, f, g, 0.0, pr.point, pr.point);
    } else if (!adj && pr.has_distance) {
        note_clearance(r, f, g, pr.distance, pr.pa, pr.pb);
        if (pr.distance < c->clearance) {
            k.kind = ORI_CONTACT_NEAR;
            k.collides = true;
            k.distance = pr.distance;
            k.point = ori_v3_scale(ori_v3_add(pr.pa, pr.pb), 0.5);
            push_contact(c, &k);
        }
    }
}

typedef struct check_ctx {
    ori_collider *c;
    ori_collision_result *r;
    bool want_clearance;
} check_ctx;

static bool check_pair(void *user, int f, int g)
{
    check_ctx *x = user;
    col_check_pair(x->c, x->r, x->want_clearance, f, g);
    return true;
}

static int cmp_contact(const void *a, const void *b)
{
    const ori_contact *x = a, *y = b;
    if (x->face_a != y->face_a) return (x->face_a > y->face_a) - (x->face_a < y->face_a);
    return (x->face_b > y->face_b) - (x->face_b < y->face_b);
}

typedef struct nearest_user {
    ori_collider *c;
    ori_collision_result *r;
} nearest_user;

static double nearest_pair(void *user, int f, int g, double best)
{
    nearest_user *x = user;
    if (col_adjacency_of(x->c, f, g) != COL_ADJ_NONE) return INFINITY;
    ori_v3 pa, pb;
    double d = col_face_distance(x->c, f, g, best, &pa, &pb);
    x->r->distance_pairs++;
    if (d < best) note_clearance(x->r, f, g, d, pa, pb);
    return d;
}

// A first bound on the least clearance: for every face, its distance to one face sharing no
// vertex with it among its neighbours' neighbours (in a sheet, the nearest faces are there).
static void seed_clearance(ori_collider *c, ori_collision_result *r)
{
    for (int f = 0; f < c->face_count; ++f) {
        int pick = -1;
        for (int k = c->adj_off[f]; k < c->adj_off[f + 1] && pick < 0; ++k) {
            int a = c->adj[k];
            for (int j = c->adj_off[a]; j < c->adj_off[a + 1]; ++j) {
                int b = c->adj[j];
                if (b != f && col_adjacency_of(c, f, b) == COL_ADJ_NONE) {
                    pick = b;
                    break;
                }
            }
        }
        if (pick < 0) continue;
        ori_v3 pa, pb;
        int lo = f < pick ? f : pick, hi = f < pick ? pick : f;
        double d = col_face_distance(c, lo, hi, r->min_clearance, &pa, &pb);
        r->distance_pairs++;
        if (d < r->min_clearance) note_clearance(r, lo, hi, d, pa, pb);
    }
}

static bool nearer_pair(void *user, int f, int g)
{
    nearest_user *x = user;
    double best = x->r->min_clearance;
    if (col_box_dist2(&x->c->boxes[f], &x->c->boxes[g]) < best * best) nearest_pair(user, f, g, best);
    return true;
}

void col_check_begin(ori_collider *c, ori_collision_result *out)
{
    memset(out, 0, sizeof *out);
    out->min_clearance = INFINITY;
    out->clearance_faces[0] = out->clearance_faces[1] = ORI_NULL_INDEX;
    out->tolerance = c->tol_touch;
    c->contact_count = 0;
}

void col_check_prepared(ori_collider *c, bool want_clearance, ori_collision_result *out)
{
    col_check_begin(c, out);
    col_bvh_build(&c->bvh, c->boxes, c->face_count);
    check_ctx x = {c, out, want_clearance};
    col_bvh_self_pairs(&c->bvh, fmax(c->tol_touch, c->clearance), check_pair, &x);
    col_check_end(c, want_clearance, out);
}

void col_check_end(ori_collider *c, bool want_clearance, ori_collision_result *out)
{
    if (c->contact_count > 1) qsort(c->contacts, (size_t)c->contact_count, sizeof(ori_contact), cmp_contact);
    c->distance_bound = 0.0;
    if (want_clearance && out->min_clearance > 0.0) {
        nearest_user nu = {c, out};
        seed_clearance(c, out);
        if (isfinite(out->min_clearance))
            // a nearby pair gave a bound: every nearer pair has boxes within it
            col_bvh_self_pairs(&c->bvh, out->min_clearance, nearer_pair, &nu);
        else
            col_bvh_nearest(&c->bvh, out->min_clearance, nearest_pair, &nu);
    }
    int first = -1;
    for (int i = 0; i < c->contact_count; ++i) {
        const ori_contact *k = &c->contacts[i];
        out->penetrating += k->kind == ORI_CONTACT_PENETRATING;
        out->touching += k->kind == ORI_CONTACT_TOUCHING;
        out->near += k->kind == ORI_CONTACT_NEAR;
        if (k->collides && first < 0) first = i;
    }
    out->contact_count = c->contact_count;
    // Penetration is reported first: the witness is the first penetrating pair, else the first
    // pair nearer than the clearance, else where the clearance is least.
    for (int i = 0; i < c->contact_count; ++i)
        if (c->contacts[i].kind == ORI_CONTACT_PENETRATING) {
            first = i;
            break;
        }
    out->collides = first >= 0;
    if (first >= 0) {
        out->has_witness = true;
        out->witness = c->contacts[first].point;
    } else if (out->clearance_faces[0] != ORI_NULL_INDEX) {
        out->has_witness = true;
        out->witness = ori_v3_scale(ori_v3_add(out->clearance_points[0], out->clearance_points[1]), 0.5);
    }
}

ori_status ori_collider_check(ori_collider *c, const ori_v3 *positions, ori_collision_result *out, ori_error *error)
{
    ORI_ASSERT(c && positions && out);
    ori_error_clear(error);
    memset(out, 0, sizeof *out);
    c->contact_count = 0;
    ori_status st = col_state_prepare(c, positions, error);
    if (st != ORI_OK) return st;
    col_check_prepared(c, true, out);
    return ORI_OK;
}

int ori_collider_contact_count(const ori_collider *c)
{
    ORI_ASSERT(c);
    return c->contact_count;
}

ori_contact ori_collider_contact(const ori_collider *c, int index)
{
    ORI_ASSERT(c && index >= 0 && index < c->contact_count);
    return c->contacts[index];
}
