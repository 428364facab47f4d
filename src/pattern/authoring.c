// Authoring: the sheet, creases clipped to faces, edits of creases, the face tree.
//
// Every public operation works on a clone and adopts it only when it built successfully, so
// a failure leaves the caller's pattern exactly as it was.
#include <orikin/authoring.h>

#include <stdio.h>
#include <stdlib.h>

#include "pattern_internal.h"

// Replace p's contents by q's (q is consumed).
static void adopt(ori_pattern *p, ori_pattern *q)
{
    ori_pattern t = *p;
    *p = *q;
    *q = t;
    ori_pattern_destroy(q);
}

static ori_status build_default(ori_pattern *p, ori_error *error)
{
    ori_build_def def = ori_default_build_def();
    return ori_pattern_build(p, &def, error);
}

// The end of an edit on the working copy q of p: when the edit (status st) succeeded and q
// builds, p adopts q; otherwise q is dropped and p stays as it was. Returns the status.
static ori_status finish(ori_pattern *p, ori_pattern *q, ori_status st, ori_error *error)
{
    if (st == ORI_OK) st = build_default(q, error);
    if (st != ORI_OK) {
        ori_pattern_destroy(q);
        return st;
    }
    adopt(p, q);
    return ORI_OK;
}

// A working copy of p, built (faces traced when missing); fails when p is not a flat pattern
// that builds.
static ori_status working_copy(const ori_pattern *p, ori_pattern **out, ori_error *error)
{
    *out = NULL;
    if (p->folded_form)
        return ori__fail(error, ORI_ERR_UNSUPPORTED, "a folded form cannot be edited; edit its crease pattern");
    ori_pattern *q = ori_pattern_clone(p);
    if (!q->built) {
        ori_status st = build_default(q, error);
        if (st != ORI_OK) {
            ori_pattern_destroy(q);
            return st;
        }
    }
    *out = q;
    return ORI_OK;
}

// --- sheet ---------------------------------------------------------------------------------

// The polygon as a pattern (boundary edges, one face), in the given order or reversed
// (keeping the first corner first), built with the planarity check.
static ori_status sheet_pattern(const ori_v2 *poly, int n, bool reverse, ori_pattern **out, ori_error *error)
{
    // Coincident corners first: named as corners rather than as the zero-length side or the
    // duplicate vertex the build would report.
    ori_v2 lo = poly[0], hi = poly[0];
    for (int i = 1; i < n; ++i) {
        lo.x = fmin(lo.x, poly[i].x), lo.y = fmin(lo.y, poly[i].y);
        hi.x = fmax(hi.x, poly[i].x), hi.y = fmax(hi.y, poly[i].y);
    }
    double diag = ori_v2_norm(ori_v2_sub(hi, lo));
    double tol = ORI_TOL_LENGTH_REL * (diag > 0.0 ? diag : 1.0);
    for (int j = 1; j < n; ++j)
        for (int i = 0; i < j; ++i)
            if (ori_v2_norm(ori_v2_sub(poly[j], poly[i])) <= tol)
                return ori__fail_at(error, ORI_ERR_DEGENERATE, "", j,
                                    "the polygon is not simple: corner %d coincides with corner %d", j, i);
    ori_pattern_def pdef = ori_default_pattern_def();
    pdef.vertex_capacity = n;
    pdef.edge_capacity = n;
    ori_pattern *p = ori_pattern_create(&pdef);
    for (int i = 0; i < n; ++i) {
        ori_v2 c = reverse ? poly[(n - i) % n] : poly[i];
        ori_pattern_add_vertex(p, ori_v3_make(c.x, c.y, 0.0));
    }
    int *cycle = ori__alloc(sizeof(int) * (size_t)n);
    for (int i = 0; i < n; ++i) {
        ori_pattern_add_edge(p, i, (i + 1) % n, ORI_ASSIGN_BOUNDARY, 0.0);
        cycle[i] = i;
    }
    ori_pattern_add_face(p, cycle, n);
    ori__free(cycle);
    ori_pattern_set_face_name(p, 0, ORI_SHEET_NAME);
    ori_pattern_add_tree_node(p, ORI_SHEET_NAME, ORI_NULL_INDEX);
    ori_error berr;
    ori_status st = build_default(p, &berr);
    if (st == ORI_OK) {
        *out = p;
        return ORI_OK;
    }
    ori_pattern_destroy(p);
    *out = NULL;
    int x = -1, y = -1;
    if (st == ORI_ERR_CROSSING && sscanf(berr.message, "edge %d intersects edge %d", &x, &y) == 2)
        return ori__fail_at(error, st, "", x, "the polygon is not simple: side %d (corner %d to %d) crosses or overlaps side %d",
                            x, x, (x + 1) % n, y);
    if (st == ORI_ERR_DEGENERATE || st == ORI_ERR_DUPLICATE)
        return ori__fail_at(error, ORI_ERR_DEGENERATE, "", berr.element, "the polygon is not simple: %s", berr.message);
    if (error) *error = berr;
    return st;
}

ori_status ori_pattern_create_sheet(const ori_v2 *poly, int n, ori_pattern **out, ori_error *error)
{
    ORI_ASSERT(out && (poly || n == 0));
    *out = NULL;
    ori_error_clear(error);
    if (n < 3) return ori__fail(error, ORI_ERR_DEGENERATE, "a sheet needs at least 3 corners (got %d)", n);
    for (int i = 0; i < n; ++i)
        if (!ori__coord_ok(poly[i].x) || !ori__coord_ok(poly[i].y))
            return ori__fail_at(error, ORI_ERR_RANGE, "corners", i, "corner is not finite or exceeds %g", ORI_COORD_MAX);
    ori_pattern *p;
    ori_status st = sheet_pattern(poly, n, false, &p, error);
    if (st != ORI_OK) return st;
    double area2 = 0.0;
    for (int i = 0; i < n; ++i) area2 += ori_v2_cross(poly[i], poly[(i + 1) % n]);
    double diag = ori_pattern_diagonal(p);
    if (!(fabs(area2) > ORI_TOL_LENGTH_REL * diag * diag)) {
        ori_pattern_destroy(p);
        return ori__fail(error, ORI_ERR_DEGENERATE, "the polygon has no area (its corners are collinear)");
    }
    if (area2 < 0.0) { // clockwise: reversed, keeping the first corner first
        ori_pattern_destroy(p);
        st = sheet_pattern(poly, n, true, &p, error);
        if (st != ORI_OK) return st;
    }
    *out = p;
    return ORI_OK;
}

// --- clipping -----------------------------------------------------------------------------

typedef struct interval {
    double t0, t1;
} interval;

static int compare_double(const void *pa, const void *pb)
{
    double a = *(const double *)pa, b = *(const double *)pb;
    return (a > b) - (a < b);
}

static int compare_interval(const void *pa, const void *pb)
{
    const interval *a = pa, *b = pb;
    return (a->t0 > b->t0) - (a->t0 < b->t0);
}

// Winding number of face f around x (exact orientation tests on stored coordinates).
static int face_winding(const ori_pattern *p, int f, ori_v2 x)
{
    const int *fv = p->face_vertices + p->face_offsets[f];
    int n = p->face_offsets[f + 1] - p->face_offsets[f];
    int wn = 0;
    for (int i = 0; i < n; ++i) {
        ori_v2 u = ori__pattern_v2(p, fv[i]), w = ori__pattern_v2(p, fv[(i + 1) % n]);
        if (u.y <= x.y) {
            if (w.y > x.y && ori_orient2d_sign(u, w, x) > 0) wn++;
        } else if (w.y <= x.y && ori_orient2d_sign(u, w, x) < 0) {
            wn--;
        }
    }
    return wn;
}

// Parameter intervals of the line a→b inside face f (appended to *iv).
static void clip_face(const ori_pattern *p, int f, ori_v2 a, ori_v2 b, double tol_t, interval **iv, int *count,
                      int *cap)
{
    const int *fv = p->face_vertices + p->face_offsets[f];
    int n = p->face_offsets[f + 1] - p->face_offsets[f];
    ori_v2 d = ori_v2_sub(b, a);
    double l2 = ori_v2_dot(d, d);
    int *side = ori__alloc(sizeof(int) * (size_t)n);
    double *ts = ori__alloc(sizeof(double) * (size_t)(2 * n));
    int nt = 0;
    for (int i = 0; i < n; ++i) side[i] = ori_orient2d_sign(a, b, ori__pattern_v2(p, fv[i]));
    for (int i = 0; i < n; ++i) {
        int j = (i + 1) % n;
        ori_v2 xi = ori__pattern_v2(p, fv[i]), xj = ori__pattern_v2(p, fv[j]);
        if (side[i] == 0) ts[nt++] = ori_v2_dot(ori_v2_sub(xi, a), d) / l2;
        if (side[i] * side[j] < 0) {
            double oi = ori_orient2d(a, b, xi), oj = ori_orient2d(a, b, xj);
            ori_v2 X = ori_v2_add(xi, ori_v2_scale(ori_v2_sub(xj, xi), oi / (oi - oj)));
            ts[nt++] = ori_v2_dot(ori_v2_sub(X, a), d) / l2;
        }
    }
    qsort(ts, (size_t)nt, sizeof *ts, compare_double);
    for (int k = 0; k + 1 < nt; ++k) {
        double t0 = ts[k], t1 = ts[k + 1];
        if (!(t1 - t0 > tol_t)) continue;
        // Along a side of the face (collinear): boundary, not a crease through the face.
        bool along = false;
        for (int i = 0; i < n && !along; ++i) {
            int j = (i + 1) % n;
            if (side[i] != 0 || side[j] != 0) continue;
            double ti = ori_v2_dot(ori_v2_sub(ori__pattern_v2(p, fv[i]), a), d) / l2;
            double tj = ori_v2_dot(ori_v2_sub(ori__pattern_v2(p, fv[j]), a), d) / l2;
            along = fmin(ti, tj) <= t0 + tol_t && fmax(ti, tj) >= t1 - tol_t;
        }
        if (along) continue;
        ori_v2 mid = ori_v2_add(a, ori_v2_scale(d, 0.5 * (t0 + t1)));
        if (face_winding(p, f, mid) == 0) continue;
        if (*count > 0 && (*iv)[*count - 1].t1 == t0) {
            (*iv)[*count - 1].t1 = t1;
        } else {
            interval x = {t0, t1};
            ORI__PUSH(*iv, *count, *cap, x);
        }
    }
    ori__free(side);
    ori__free(ts);
}

// Intervals of the crease inside the target, sorted and merged; returns the count.
static int clip_crease(const ori_pattern *p, const ori_crease *c, int face, interval **out)
{
    ori_v2 d = ori_v2_sub(c->b, c->a);
    double len = ori_v2_norm(d);
    double tol = ORI_TOL_LENGTH_REL * ori_pattern_diagonal(p);
    double tol_t = tol / len;
    interval *iv = NULL;
    int n = 0, cap = 0;
    int f0 = face == ORI_NULL_INDEX ? 0 : face, f1 = face == ORI_NULL_INDEX ? p->face_count : face + 1;
    ori_v2 nrm = ori_v2_scale(ori_v2_perp(d), 1.0 / len);
    for (int f = f0; f < f1; ++f) {
        if (face == ORI_NULL_INDEX) {
            // Quick rejection: every corner of the face clearly on one side of the line (the
            // margin, far above rounding, keeps the exact test in charge of close calls).
            const int *fv = p->face_vertices + p->face_offsets[f];
            int m = p->face_offsets[f + 1] - p->face_offsets[f], pos = 0, neg = 0;
            for (int i = 0; i < m; ++i) {
                double h = ori_v2_dot(ori_v2_sub(ori__pattern_v2(p, fv[i]), c->a), nrm);
                pos += h > tol;
                neg += h < -tol;
            }
            if (pos == m || neg == m) continue;
        }
        clip_face(p, f, c->a, c->b, tol_t, &iv, &n, &cap);
    }
    if (n > 1) qsort(iv, (size_t)n, sizeof *iv, compare_interval);
    int m = 0;
    for (int i = 0; i < n; ++i) {
        interval x = iv[i];
        if (!c->infinite) {
            x.t0 = fmax(x.t0, 0.0);
            x.t1 = fmin(x.t1, 1.0);
        }
        if (!(x.t1 - x.t0 > tol_t)) continue;
        if (m > 0 && x.t0 <= iv[m - 1].t1 + tol_t)
            iv[m - 1].t1 = fmax(iv[m - 1].t1, x.t1);
        else
            iv[m++] = x;
    }
    *out = iv;
    return m;
}

static ori_status check_crease(const ori_pattern *p, const ori_crease *c, int face, ori_error *error)
{
    if (!ori__coord_ok(c->a.x) || !ori__coord_ok(c->a.y) || !ori__coord_ok(c->b.x) || !ori__coord_ok(c->b.y) ||
        !isfinite(c->fold_angle_rad))
        return ori__fail(error, ORI_ERR_RANGE, "crease points must be finite and at most %g, the fold angle finite", ORI_COORD_MAX);
    if ((int)c->assignment < 0 || c->assignment >= ORI_ASSIGN_COUNT || !(ori_assignment_is_fold(c->assignment) || c->assignment == ORI_ASSIGN_FLAT))
        return ori__fail(error, ORI_ERR_ARGUMENT, "a crease is M, V, F or U");
    if (face != ORI_NULL_INDEX && (face < 0 || face >= p->face_count))
        return ori__fail_at(error, ORI_ERR_RANGE, "faces_vertices", face, "no such face (the pattern has %d)",
                            p->face_count);
    if (p->face_count == 0) return ori__fail(error, ORI_ERR_ARGUMENT, "the pattern has no faces");
    double tol = ORI_TOL_LENGTH_REL * ori_pattern_diagonal(p);
    if (!(ori_v2_norm(ori_v2_sub(c->b, c->a)) > tol))
        return ori__fail(error, ORI_ERR_DEGENERATE, "the crease's two points coincide");
    return ORI_OK;
}

int ori_pattern_clip_crease(const ori_pattern *p, const ori_crease *c, int face, double *t_out, int cap)
{
    ORI_ASSERT(p && c && (t_out || cap == 0));
    if (check_crease(p, c, face, NULL) != ORI_OK) return 0;
    interval *iv;
    int n = clip_crease(p, c, face, &iv);
    for (int i = 0; i < n && i < cap; ++i) {
        t_out[2 * i] = iv[i].t0;
        t_out[2 * i + 1] = iv[i].t1;
    }
    ori__free(iv);
    return n;
}

static void face_label(const ori_pattern *p, int face, char *buf, size_t size)
{
    if (face == ORI_NULL_INDEX) snprintf(buf, size, "the sheet");
    else if (ori_pattern_face_name(p, face)) snprintf(buf, size, "face %s", ori_pattern_face_name(p, face));
    else snprintf(buf, size, "face %d", face);
}

// Apply creases to q in place (q built): all clipped to the target as it is now, then
// inserted. q is left unbuilt.
static ori_status apply_impl(ori_pattern *q, const ori_crease *cs, int count, int face, ori_apply_result *res,
                             ori_error *error)
{
    interval **iv = ori__calloc((size_t)(count ? count : 1), sizeof *iv);
    int *n = ori__calloc((size_t)(count ? count : 1), sizeof *n);
    ori_status st = ORI_OK;
    for (int k = 0; k < count && st == ORI_OK; ++k) {
        st = check_crease(q, &cs[k], face, error);
        if (st != ORI_OK) break;
        n[k] = clip_crease(q, &cs[k], face, &iv[k]);
        if (n[k] == 0) {
            char label[ORI_NAME_MAX + 16];
            face_label(q, face, label, sizeof label);
            if (count == 1) st = ori__fail(error, ORI_ERR_NOT_FOUND, "the crease does not cross %s", label);
            else st = ori__fail_at(error, ORI_ERR_NOT_FOUND, "creases", k, "the crease does not cross %s", label);
        }
    }
    ori_insert_def def = ori_default_insert_def();
    def.length_scale = ori_pattern_diagonal(q);
    for (int k = 0; k < count && st == ORI_OK; ++k) {
        ori_v2 d = ori_v2_sub(cs[k].b, cs[k].a);
        for (int i = 0; i < n[k] && st == ORI_OK; ++i) {
            ori_insert_result r;
            ori_v2 a = ori_v2_add(cs[k].a, ori_v2_scale(d, iv[k][i].t0));
            ori_v2 b = ori_v2_add(cs[k].a, ori_v2_scale(d, iv[k][i].t1));
            st = ori_pattern_insert_segment(q, a, b, cs[k].assignment, cs[k].fold_angle_rad, &def, &r, error);
            res->segments++;
            res->faces_split += r.faces_split;
            res->vertices_added += r.vertices_added;
            res->edges_added += r.edges_added;
        }
    }
    for (int k = 0; k < count; ++k) ori__free(iv[k]);
    ori__free(iv);
    ori__free(n);
    return st;
}

ori_status ori_pattern_apply_creases(ori_pattern *p, const ori_crease *cs, int count, int face, ori_apply_result *out,
                                     ori_error *error)
{
    ORI_ASSERT(p && (cs || count == 0) && count >= 0);
    ori_error_clear(error);
    ori_apply_result res;
    memset(&res, 0, sizeof res);
    res.first_edge = p->edge_count;
    if (out) *out = res;
    ori_pattern *q;
    ori_status st = working_copy(p, &q, error);
    if (st != ORI_OK) return st;
    st = finish(p, q, apply_impl(q, cs, count, face, &res, error), error);
    if (st == ORI_OK && out) *out = res;
    return st;
}

ori_status ori_pattern_apply_crease(ori_pattern *p, const ori_crease *c, int face, ori_apply_result *out,
                                    ori_error *error)
{
    ORI_ASSERT(p && c);
    return ori_pattern_apply_creases(p, c, 1, face, out, error);
}

// --- assignment -----------------------------------------------------------------------------

static ori_status check_edge(const ori_pattern *p, int e, const char *verb, ori_error *error)
{
    if (e < 0 || e >= p->edge_count)
        return ori__fail_at(error, ORI_ERR_RANGE, "edges_vertices", e, "no such edge (the pattern has %d)",
                            p->edge_count);
    ori_assignment a = p->edges[e].assignment;
    if (a == ORI_ASSIGN_BOUNDARY || a == ORI_ASSIGN_CUT)
        return ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_vertices", e, "%s edge (%c) cannot be %s; only creases can",
                            a == ORI_ASSIGN_BOUNDARY ? "a boundary" : "a cut", ori_assignment_to_char(a), verb);
    return ORI_OK;
}

ori_status ori_pattern_assign_crease(ori_pattern *p, int e, ori_assignment a, ori_error *error)
{
    ORI_ASSERT(p);
    ori_error_clear(error);
    ori_status st = check_edge(p, e, "re-assigned", error);
    if (st != ORI_OK) return st;
    if (p->edges[e].assignment == ORI_ASSIGN_JOIN)
        return ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_vertices", e, "a join edge (J) cannot be re-assigned");
    if (!(ori_assignment_is_fold(a) || a == ORI_ASSIGN_FLAT))
        return ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_vertices", e, "a crease is assigned M, V, F or U, not %c",
                            ori_assignment_to_char(a));
    double angle = p->edges[e].fold_angle_rad;
    if ((a == ORI_ASSIGN_MOUNTAIN && angle > 0.0) || (a == ORI_ASSIGN_VALLEY && angle < 0.0)) angle = -angle;
    if (a == ORI_ASSIGN_FLAT) angle = 0.0;
    p->edges[e].assignment = a;
    p->edges[e].fold_angle_rad = angle;
    return ORI_OK;
}

ori_status ori_pattern_flip_crease(ori_pattern *p, int e, ori_error *error)
{
    ORI_ASSERT(p);
    ori_error_clear(error);
    ori_status st = check_edge(p, e, "flipped", error);
    if (st != ORI_OK) return st;
    ori_assignment a = p->edges[e].assignment;
    if (a != ORI_ASSIGN_MOUNTAIN && a != ORI_ASSIGN_VALLEY)
        return ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_vertices", e,
                            "only mountains and valleys flip (this crease is %c; assign it M or V)",
                            ori_assignment_to_char(a));
    p->edges[e].assignment = a == ORI_ASSIGN_MOUNTAIN ? ORI_ASSIGN_VALLEY : ORI_ASSIGN_MOUNTAIN;
    p->edges[e].fold_angle_rad = -p->edges[e].fold_angle_rad;
    return ORI_OK;
}

// --- removal ------------------------------------------------------------------------------

typedef struct cycle {
    int *v;
    int n;
} cycle;

static int find_pair(const cycle *c, int x, int y)
{
    for (int i = 0; i < c->n; ++i)
        if (c->v[i] == x && c->v[(i + 1) % c->n] == y) return i;
    return -1;
}

static void reverse_cycle(cycle *c)
{
    for (int i = 0, j = c->n - 1; i < j; ++i, --j) {
        int t = c->v[i];
        c->v[i] = c->v[j];
        c->v[j] = t;
    }
}

// Copy count elements of c starting at position from (cyclically) to out.
static int copy_range(const cycle *c, int from, int count, int *out)
{
    for (int k = 0; k < count; ++k) out[k] = c->v[(from + k) % c->n];
    return count;
}

static int child_count(const ori_pattern *p, int node)
{
    int n = 0;
    for (int i = 0; i < p->tree_count; ++i) n += p->tree[i].parent == node;
    return n;
}

static void delete_tree_node(ori_pattern *p, int node)
{
    for (int i = node; i + 1 < p->tree_count; ++i) p->tree[i] = p->tree[i + 1];
    p->tree_count--;
    for (int i = 0; i < p->tree_count; ++i)
        if (p->tree[i].parent > node) p->tree[i].parent--;
        else if (p->tree[i].parent == node) p->tree[i].parent = ORI_NULL_INDEX;
    ori__pattern_reindex_tree(p);
}

static bool remove_from_cycle(cycle *c, int v)
{
    int m = 0;
    for (int i = 0; i < c->n; ++i)
        if (c->v[i] != v) c->v[m++] = c->v[i];
    bool changed = m != c->n;
    c->n = m;
    return changed;
}

// Remove crease e from q (built) in place; q is left unbuilt.
static ori_status remove_impl(ori_pattern *q, int e, ori_remove_result *res, ori_error *error)
{
    memset(res, 0, sizeof *res);
    res->kept_face = res->removed_face = ORI_NULL_INDEX;
    ori_status st = check_edge(q, e, "removed", error);
    if (st != ORI_OK) return st;
    int u = q->edges[e].v[0], w = q->edges[e].v[1];
    int f0 = q->edge_faces[2 * e], f1 = q->edge_faces[2 * e + 1];
    if ((f0 == ORI_NULL_INDEX) != (f1 == ORI_NULL_INDEX))
        return ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_vertices", e,
                            "the edge has a face on one side only; removing it would cut into the sheet");
    int F = q->face_count;
    cycle *cy = ori__calloc((size_t)(F ? F : 1), sizeof *cy);
    for (int f = 0; f < F; ++f) {
        int b = q->face_offsets[f], n = q->face_offsets[f + 1] - b;
        cy[f].v = ori__alloc(sizeof(int) * (size_t)(n + 1));
        memcpy(cy[f].v, q->face_vertices + b, sizeof(int) * (size_t)n);
        cy[f].n = n;
    }
    char merged_name[ORI_NAME_MAX] = "";
    int dead_face = ORI_NULL_INDEX, kept = ORI_NULL_INDEX;
    if (f0 != ORI_NULL_INDEX && f0 != f1) {
        cycle *c0 = &cy[f0], *c1 = &cy[f1];
        int i = find_pair(c0, u, w);
        int x = u, y = w;
        if (i < 0) {
            i = find_pair(c0, w, u);
            x = w;
            y = u;
        }
        int j = find_pair(c1, y, x);
        if (j < 0) {
            reverse_cycle(c1);
            j = find_pair(c1, y, x);
        }
        ORI_ASSERT(i >= 0 && j >= 0);
        int *m = ori__alloc(sizeof(int) * (size_t)(c0->n + c1->n));
        int k = copy_range(c0, i + 1, c0->n, m);       // y … x
        k += copy_range(c1, j + 2, c1->n - 2, m + k);  // after x … before y
        kept = f0 < f1 ? f0 : f1;
        dead_face = f0 < f1 ? f1 : f0;
        ori__free(cy[kept].v);
        cy[kept].v = m;
        cy[kept].n = k;
        cy[dead_face].n = 0;
        // Names: two sibling leaves N1, N2 under N merge back into N.
        const char *n0 = ori_pattern_face_name(q, f0), *n1 = ori_pattern_face_name(q, f1);
        int t0 = n0 ? ori_pattern_find_tree_node(q, n0) : ORI_NULL_INDEX;
        int t1 = n1 ? ori_pattern_find_tree_node(q, n1) : ORI_NULL_INDEX;
        if (t0 != ORI_NULL_INDEX && t1 != ORI_NULL_INDEX && t0 != t1 && q->tree[t0].parent != ORI_NULL_INDEX &&
            q->tree[t0].parent == q->tree[t1].parent && child_count(q, q->tree[t0].parent) == 2 &&
            child_count(q, t0) == 0 && child_count(q, t1) == 0) {
            ori__strlcpy(merged_name, q->tree[q->tree[t0].parent].name, ORI_NAME_MAX);
            delete_tree_node(q, t0 > t1 ? t0 : t1);
            delete_tree_node(q, t0 > t1 ? t1 : t0);
            res->name_restored = true;
        } else {
            const char *keep = ori_pattern_face_name(q, kept), *other = ori_pattern_face_name(q, dead_face);
            ori__strlcpy(merged_name, keep ? keep : (other ? other : ""), ORI_NAME_MAX);
        }
    } else if (f0 != ORI_NULL_INDEX) {
        // Both sides in one face: a slit (or a bridge, which would leave a hole).
        cycle *c = &cy[f0];
        int i = find_pair(c, u, w), j = find_pair(c, w, u);
        ORI_ASSERT(i >= 0 && j >= 0);
        int len1 = (j - i - 1 + c->n) % c->n, len2 = (i - j - 1 + c->n) % c->n;
        if (len1 > 0 && len2 > 0) {
            for (int f = 0; f < F; ++f) ori__free(cy[f].v);
            ori__free(cy);
            return ori__fail_at(error, ORI_ERR_ARGUMENT, "edges_vertices", e,
                                "removing the edge would leave a disconnected part inside a face");
        }
        int *m = ori__alloc(sizeof(int) * (size_t)c->n);
        int k = len1 > 0 ? copy_range(c, i + 1, len1, m) : copy_range(c, j + 1, len2, m);
        ori__free(c->v);
        c->v = m;
        c->n = k;
        kept = f0;
        const char *nm = ori_pattern_face_name(q, f0);
        ori__strlcpy(merged_name, nm ? nm : "", ORI_NAME_MAX);
    }
    res->kept_face = kept;
    res->removed_face = dead_face;

    // Dead elements, then dissolution of the crease's end vertices.
    int V = q->vertex_count, E = q->edge_count;
    char *edge_dead = ori__calloc((size_t)E, 1), *vert_dead = ori__calloc((size_t)(V ? V : 1), 1);
    edge_dead[e] = 1;
    res->removed_edges[0] = e;
    res->merged_into[0] = ORI_NULL_INDEX;
    res->removed_edge_count = 1;
    int ends[2] = {u, w};
    for (int k = 0; k < 2; ++k) {
        int v = ends[k], inc[3], deg = 0;
        for (int x = 0; x < E && deg < 3; ++x)
            if (!edge_dead[x] && (q->edges[x].v[0] == v || q->edges[x].v[1] == v)) inc[deg++] = x;
        if (deg == 0) {
            vert_dead[v] = 1;
            for (int f = 0; f < F; ++f) remove_from_cycle(&cy[f], v);
            continue;
        }
        if (deg != 2) continue;
        ori_edge *ea = &q->edges[inc[0]], *eb = &q->edges[inc[1]];
        int pa = ea->v[0] == v ? ea->v[1] : ea->v[0], pb = eb->v[0] == v ? eb->v[1] : eb->v[0];
        ori_v2 X = ori__pattern_v2(q, v), A = ori__pattern_v2(q, pa), B = ori__pattern_v2(q, pb);
        if (ori_orient2d_sign(A, X, B) != 0 || ori_v2_dot(ori_v2_sub(A, X), ori_v2_sub(B, X)) >= 0.0) continue;
        if (ea->assignment != eb->assignment || ea->fold_angle_rad != eb->fold_angle_rad) continue;
        // inc[0] < inc[1]: the lower index covers both.
        if (ea->v[0] == v) ea->v[0] = pb;
        else ea->v[1] = pb;
        edge_dead[inc[1]] = 1;
        res->removed_edges[res->removed_edge_count] = inc[1];
        res->merged_into[res->removed_edge_count] = inc[0];
        res->removed_edge_count++;
        vert_dead[v] = 1;
        for (int f = 0; f < F; ++f) remove_from_cycle(&cy[f], v);
    }
    // Sort the removed edges (with their partners), record removed vertices.
    for (int a = 1; a < res->removed_edge_count; ++a)
        for (int b = a; b > 0 && res->removed_edges[b] < res->removed_edges[b - 1]; --b) {
            int t = res->removed_edges[b];
            res->removed_edges[b] = res->removed_edges[b - 1];
            res->removed_edges[b - 1] = t;
            t = res->merged_into[b];
            res->merged_into[b] = res->merged_into[b - 1];
            res->merged_into[b - 1] = t;
        }
    for (int v = 0; v < V; ++v)
        if (vert_dead[v]) res->removed_vertices[res->removed_vertex_count++] = v;

    // Compact: vertices, edges, faces (names kept in step), in FOLD order.
    ori__pattern_invalidate(q);
    int *vmap = ori__alloc(sizeof(int) * (size_t)(V ? V : 1));
    int nv = 0;
    for (int v = 0; v < V; ++v) {
        vmap[v] = vert_dead[v] ? -1 : nv;
        if (!vert_dead[v]) q->vertices[nv++] = q->vertices[v];
    }
    q->vertex_count = nv;
    int ne = 0;
    for (int x = 0; x < E; ++x) {
        if (edge_dead[x]) continue;
        ori_edge ed = q->edges[x];
        ed.v[0] = vmap[ed.v[0]];
        ed.v[1] = vmap[ed.v[1]];
        q->edges[ne++] = ed;
    }
    q->edge_count = ne;
    char (*names)[ORI_NAME_MAX] = ori__calloc((size_t)(F ? F : 1), sizeof *names);
    for (int f = 0; f < F; ++f) {
        const char *nm = ori_pattern_face_name(q, f);
        ori__strlcpy(names[f], nm ? nm : "", ORI_NAME_MAX);
    }
    if (kept != ORI_NULL_INDEX) ori__strlcpy(names[kept], merged_name, ORI_NAME_MAX);
    int total = 0, nf = 0;
    for (int f = 0; f < F; ++f) total += f == dead_face ? 0 : cy[f].n;
    ori__pattern_reserve_faces(q, F, total);
    int k = 0;
    q->face_offsets[0] = 0;
    for (int f = 0; f < F; ++f) {
        if (f == dead_face) continue;
        for (int i = 0; i < cy[f].n; ++i) q->face_vertices[k++] = vmap[cy[f].v[i]];
        q->face_offsets[++nf] = k;
        if (q->face_names) ori__strlcpy(q->face_names[nf - 1], names[f], ORI_NAME_MAX);
    }
    q->face_count = nf;
    q->face_vertex_count = k;
    for (int f = 0; f < F; ++f) ori__free(cy[f].v);
    ori__free(cy);
    ori__free(names);
    ori__free(vmap);
    ori__free(edge_dead);
    ori__free(vert_dead);
    return ORI_OK;
}

ori_status ori_pattern_remove_crease(ori_pattern *p, int e, ori_remove_result *out, ori_error *error)
{
    ORI_ASSERT(p);
    ori_error_clear(error);
    ori_remove_result res;
    ori_pattern *q;
    ori_status st = working_copy(p, &q, error);
    if (st != ORI_OK) return st;
    st = finish(p, q, remove_impl(q, e, &res, error), error);
    if (st == ORI_OK && out) *out = res;
    return st;
}

int ori_remove_result_map_edge(const ori_remove_result *r, int e)
{
    ORI_ASSERT(r);
    if (e < 0) return ORI_NULL_INDEX;
    for (int i = 0; i < r->removed_edge_count; ++i)
        if (r->removed_edges[i] == e) {
            if (r->merged_into[i] == ORI_NULL_INDEX) return ORI_NULL_INDEX;
            e = r->merged_into[i];
            break;
        }
    int shift = 0;
    for (int i = 0; i < r->removed_edge_count; ++i) shift += r->removed_edges[i] < e;
    return e - shift;
}

ori_status ori_pattern_move_crease(ori_pattern *p, int e, ori_v2 a, ori_v2 b, ori_remove_result *removed,
                                   ori_apply_result *out, ori_error *error)
{
    ORI_ASSERT(p);
    ori_error_clear(error);
    ori_apply_result res;
    ori_remove_result rr;
    memset(&res, 0, sizeof res);
    memset(&rr, 0, sizeof rr);
    if (out) *out = res;
    ori_pattern *q;
    ori_status st = working_copy(p, &q, error);
    if (st != ORI_OK) return st;
    st = check_edge(q, e, "moved", error);
    ori_crease c;
    if (st == ORI_OK) {
        c.a = a;
        c.b = b;
        c.infinite = false;
        c.assignment = q->edges[e].assignment;
        c.fold_angle_rad = q->edges[e].fold_angle_rad;
        if (c.assignment == ORI_ASSIGN_JOIN) c.assignment = ORI_ASSIGN_UNASSIGNED;
        st = remove_impl(q, e, &rr, error);
    }
    if (st == ORI_OK) st = build_default(q, error);
    if (st == ORI_OK) {
        res.first_edge = q->edge_count;
        st = apply_impl(q, &c, 1, ORI_NULL_INDEX, &res, error);
    }
    st = finish(p, q, st, error);
    if (st == ORI_OK && out) *out = res;
    if (st == ORI_OK && removed) *removed = rr;
    return st;
}

// --- face tree ------------------------------------------------------------------------------

int ori_pattern_face_node(const ori_pattern *p, int face)
{
    const char *name = ori_pattern_face_name(p, face);
    return name ? ori_pattern_find_tree_node(p, name) : ORI_NULL_INDEX;
}

int ori_pattern_node_child_count(const ori_pattern *p, int node)
{
    ORI_ASSERT(p && node >= 0 && node < p->tree_count);
    return child_count(p, node);
}
