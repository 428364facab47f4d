// Validation and derived topology of a pattern: index checks, welding or rejecting coincident
// vertices, zero-length and duplicate edges, crossing edges (uniform grid + exact predicates),
// vertex → edges in cyclic order, faces (given, or traced from the planar graph), edge → faces.
#include "pattern_internal.h"

#include "../core/hash.h"
#include "../geometry/geometry_internal.h"

#include <float.h>
#include <stdlib.h>

ori_build_def ori_default_build_def(void)
{
    ori_build_def def;
    def.weld = false;
    def.check_planarity = true;
    def.compute_faces = true;
    def.planarize = false;
    def.internal_value = ORI__DEF_COOKIE;
    return def;
}

// --- edge lookup -----------------------------------------------------------------------

int ori_pattern_find_edge(const ori_pattern *p, int a, int b)
{
    ORI_ASSERT(p && p->built);
    if (a < 0 || b < 0 || a >= p->vertex_count || b >= p->vertex_count) return ORI_NULL_INDEX;
    uint64_t key = ori__pair_key(a, b);
    int mask = p->edge_hash_cap - 1;
    for (int i = (int)(ori__mix64(key) & (uint64_t)mask);; i = (i + 1) & mask) {
        int e = p->edge_hash[i];
        if (e < 0) return ORI_NULL_INDEX;
        if (ori__pair_key(p->edges[e].v[0], p->edges[e].v[1]) == key) return e;
    }
}

// --- vertices ----------------------------------------------------------------------------

static double bbox_diagonal(const ori_pattern *p, ori_v3 *lo_out)
{
    ori_v3 lo = {0, 0, 0}, hi = {0, 0, 0};
    if (p->vertex_count > 0) lo = hi = p->vertices[0];
    for (int i = 1; i < p->vertex_count; ++i) {
        ori_v3 v = p->vertices[i];
        lo.x = fmin(lo.x, v.x), lo.y = fmin(lo.y, v.y), lo.z = fmin(lo.z, v.z);
        hi.x = fmax(hi.x, v.x), hi.y = fmax(hi.y, v.y), hi.z = fmax(hi.z, v.z);
    }
    if (lo_out) *lo_out = lo;
    double d = ori_v3_norm(ori_v3_sub(hi, lo));
    return d > 0.0 ? d : 1.0;
}

static inline uint64_t cell_hash(const int64_t c[3])
{
    return ori__mix64((uint64_t)c[0] * 0x9E3779B97F4A7C15ULL ^ ori__mix64((uint64_t)c[1] + 0x632BE59BD9B4E019ULL) ^
                      ori__mix64((uint64_t)c[2] * 0x94D049BB133111EBULL + 7));
}

// Cell hash of 3D points with cell size h: for each vertex, the earlier vertex within tol, or -1.
static ori_status find_close_vertices(ori_pattern *p, double tol, int *twin)
{
    int n = p->vertex_count;
    double h = tol > 0.0 ? tol : DBL_MIN;
    int cap = ori__hash_capacity(n);
    int *head = ori__alloc(sizeof(int) * (size_t)cap);
    int *next = ori__alloc(sizeof(int) * (size_t)(n ? n : 1));
    int64_t *cell = ori__alloc(sizeof(int64_t) * 3 * (size_t)(n ? n : 1));
    for (int i = 0; i < cap; ++i) head[i] = -1;
    // When every vertex lies in the same z layer of cells (a flat sheet), probes of the layers
    // above and below can never match: skip them (9 probes per vertex instead of 27).
    bool one_layer = true;
    // Cells count from the lower corner of the bounding box: at most diagonal / h ≈ 1e9 per axis,
    // whatever the coordinates' offset from the origin (an int64 cast of a larger value is UB).
    ori_v3 lo = n > 0 ? p->vertices[0] : ori_v3_make(0, 0, 0);
    for (int i = 1; i < n; ++i)
        lo = ori_v3_make(fmin(lo.x, p->vertices[i].x), fmin(lo.y, p->vertices[i].y), fmin(lo.z, p->vertices[i].z));
    int64_t z_layer = n > 0 ? (int64_t)floor((p->vertices[0].z - lo.z) / h) : 0;
    for (int i = 1; i < n && one_layer; ++i) one_layer = (int64_t)floor((p->vertices[i].z - lo.z) / h) == z_layer;
    int dz_lo = one_layer ? 0 : -1, dz_hi = one_layer ? 0 : 1;
    ori_status st = ORI_OK;
    for (int i = 0; i < n && st == ORI_OK; ++i) {
        ori_v3 v = p->vertices[i];
        int64_t c[3] = {(int64_t)floor((v.x - lo.x) / h), (int64_t)floor((v.y - lo.y) / h), (int64_t)floor((v.z - lo.z) / h)};
        memcpy(cell + 3 * i, c, sizeof c);
        twin[i] = -1;
        for (int dx = -1; dx <= 1 && twin[i] < 0; ++dx)
            for (int dy = -1; dy <= 1 && twin[i] < 0; ++dy)
                for (int dz = dz_lo; dz <= dz_hi && twin[i] < 0; ++dz) {
                    int64_t k[3] = {c[0] + dx, c[1] + dy, c[2] + dz};
                    for (int j = head[cell_hash(k) & (uint64_t)(cap - 1)]; j >= 0; j = next[j]) {
                        if (cell[3 * j] != k[0] || cell[3 * j + 1] != k[1] || cell[3 * j + 2] != k[2]) continue;
                        if (ori_v3_norm(ori_v3_sub(p->vertices[j], v)) <= tol) {
                            twin[i] = twin[j] >= 0 ? twin[j] : j;
                            break;
                        }
                    }
                }
        int slot = (int)(cell_hash(c) & (uint64_t)(cap - 1));
        next[i] = head[slot];
        head[slot] = i;
    }
    ori__free(head);
    ori__free(next);
    ori__free(cell);
    return st;
}

// Merge vertex i into twin[i]: edges are remapped, vertices compacted (indices change).
static void weld_vertices(ori_pattern *p, const int *twin)
{
    int n = p->vertex_count;
    int *map = ori__alloc(sizeof(int) * (size_t)(n ? n : 1));
    int m = 0;
    for (int i = 0; i < n; ++i) {
        if (twin[i] < 0) {
            map[i] = m;
            p->vertices[m++] = p->vertices[i];
        } else {
            map[i] = map[twin[i]];
        }
    }
    p->vertex_count = m;
    for (int e = 0; e < p->edge_count; ++e)
        for (int k = 0; k < 2; ++k) p->edges[e].v[k] = map[p->edges[e].v[k]];
    for (int k = 0; k < p->face_vertex_count; ++k) p->face_vertices[k] = map[p->face_vertices[k]];
    ori__free(map);
}

// --- cyclic order --------------------------------------------------------------------------

typedef struct sort_item {
    ori_v2 d;  // direction from the vertex
    int half;  // 0: angle in [0, π), 1: [π, 2π)
    int edge;
} sort_item;

static int compare_dirs(const void *pa, const void *pb)
{
    const sort_item *a = pa, *b = pb;
    if (a->half != b->half) return a->half - b->half;
    ori_v2 o = {0.0, 0.0};
    int s = ori_orient2d_sign(o, a->d, b->d);
    if (s != 0) return -s; // a before b when b is counter-clockwise of a
    return (a->edge > b->edge) - (a->edge < b->edge);
}

static void sort_vertex_edges_2d(ori_pattern *p)
{
    sort_item *items = NULL;
    int cap = 0;
    for (int v = 0; v < p->vertex_count; ++v) {
        int b = p->vert_edge_offsets[v], n = p->vert_edge_offsets[v + 1] - b;
        if (n < 2) continue;
        ORI__RESERVE(items, cap, n);
        ori_v2 o = ori__pattern_v2(p, v);
        for (int k = 0; k < n; ++k) {
            int e = p->vert_edges[b + k];
            int w = p->edges[e].v[0] == v ? p->edges[e].v[1] : p->edges[e].v[0];
            ori_v2 d = ori_v2_sub(ori__pattern_v2(p, w), o);
            items[k].d = d;
            items[k].half = (d.y < 0.0 || (d.y == 0.0 && d.x < 0.0)) ? 1 : 0;
            items[k].edge = e;
        }
        qsort(items, (size_t)n, sizeof *items, compare_dirs);
        for (int k = 0; k < n; ++k) p->vert_edges[b + k] = items[k].edge;
    }
    ori__free(items);
}

// Folded forms: order the edges at each vertex by walking the face corners around it.
// A counter-clockwise face … u → v → w … puts edge(v, w) just before edge(v, u) around v.
static void order_vertex_edges_by_faces(ori_pattern *p)
{
    int total = 2 * p->edge_count;
    int *next = ori__alloc(sizeof(int) * (size_t)(total ? total : 1)); // per slot in vert_edges
    int *has_prev = ori__calloc((size_t)(total ? total : 1), sizeof(int));
    int *tmp = NULL;
    int tmp_cap = 0;
    for (int i = 0; i < total; ++i) next[i] = -1;
    for (int f = 0; f < p->face_count; ++f) {
        int b = p->face_offsets[f], n = p->face_offsets[f + 1] - b;
        for (int k = 0; k < n; ++k) {
            int v = p->face_vertices[b + k];
            int e_out = p->face_edges[b + k];
            int e_in = p->face_edges[b + (k + n - 1) % n];
            int vb = p->vert_edge_offsets[v], vn = p->vert_edge_offsets[v + 1] - vb;
            int s_out = -1, s_in = -1;
            for (int j = 0; j < vn; ++j) {
                if (p->vert_edges[vb + j] == e_out) s_out = vb + j;
                if (p->vert_edges[vb + j] == e_in) s_in = vb + j;
            }
            if (s_out >= 0 && s_in >= 0 && next[s_out] < 0) {
                next[s_out] = s_in;
                has_prev[s_in] = 1;
            }
        }
    }
    for (int v = 0; v < p->vertex_count; ++v) {
        int vb = p->vert_edge_offsets[v], vn = p->vert_edge_offsets[v + 1] - vb;
        if (vn < 2) continue;
        ORI__RESERVE(tmp, tmp_cap, vn);
        int start = vb;
        for (int j = 0; j < vn; ++j)
            if (!has_prev[vb + j]) {
                start = vb + j;
                break;
            }
        int m = 0, s = start;
        char *seen = ori__calloc((size_t)vn, 1);
        while (s >= 0 && m < vn && !seen[s - vb]) {
            seen[s - vb] = 1;
            tmp[m++] = p->vert_edges[s];
            s = next[s];
        }
        for (int j = 0; j < vn; ++j)
            if (!seen[j]) tmp[m++] = p->vert_edges[vb + j]; // edges without faces keep their place
        memcpy(p->vert_edges + vb, tmp, sizeof(int) * (size_t)vn);
        ori__free(seen);
    }
    ori__free(tmp);
    ori__free(next);
    ori__free(has_prev);
}

// --- crossing edges ------------------------------------------------------------------------

// Uniform grid over the bounding box of the sheet (about one cell per edge).
typedef struct crossing_grid {
    double minx, miny, cell;
    int64_t nx, ny;
} crossing_grid;

// Enter edge e in the cells its segment passes through (column by column, padded by one cell
// for rounding). Pass 1 (items == NULL) counts entries per cell into slot[cell + 1]; pass 2
// writes e at items[slot[cell]++]. Edges are entered in increasing order, so every cell lists
// its edges in increasing order (an edge may repeat, adjacently).
static void grid_enter(const ori_pattern *p, int e, const crossing_grid *g, int *slot, int *items)
{
    double minx = g->minx, miny = g->miny, cell = g->cell;
    int64_t nx = g->nx, ny = g->ny;
    ori_v2 a = ori__pattern_v2(p, p->edges[e].v[0]), b = ori__pattern_v2(p, p->edges[e].v[1]);
    if (a.x > b.x) {
        ori_v2 t = a;
        a = b;
        b = t;
    }
    int64_t c0 = (int64_t)floor((a.x - minx) / cell), c1 = (int64_t)floor((b.x - minx) / cell);
    if (c0 < 0) c0 = 0;
    if (c1 >= nx) c1 = nx - 1;
    for (int64_t cx = c0; cx <= c1; ++cx) {
        // y-range of the segment within this column (padded by one cell for rounding)
        double x0 = fmax(a.x, minx + (double)cx * cell), y0, y1;
        ori__segment_y_range(a, b, minx + (double)cx * cell, minx + (double)(cx + 1) * cell, &y0, &y1);
        int64_t r0 = (int64_t)floor((y0 - miny) / cell) - 1, r1 = (int64_t)floor((y1 - miny) / cell) + 1;
        if (r0 < 0) r0 = 0;
        if (r1 >= ny) r1 = ny - 1;
        int64_t cx_lo = cx > 0 ? cx - 1 : cx;
        // also enter the previous column's overlap band for points exactly on a column edge
        for (int64_t ccx = cx_lo; ccx <= cx; ++ccx)
            for (int64_t r = r0; r <= r1; ++r) {
                if (ccx != cx && (x0 > minx + (double)cx * cell)) continue;
                int64_t id = ccx * ny + r;
                if (items) items[slot[id]++] = e;
                else slot[id + 1]++;
            }
    }
}

// Each edge is entered in the cells its segment passes through, the entries are bucketed by
// cell (counting sort, two passes), then pairs within a cell are tested.
static ori_status check_crossings(ori_pattern *p, ori_error *error)
{
    int m = p->edge_count;
    if (m < 2) return ORI_OK;
    ori_v3 lo3;
    double diag = bbox_diagonal(p, &lo3);
    double minx = lo3.x, miny = lo3.y, maxx = minx, maxy = miny;
    for (int i = 0; i < p->vertex_count; ++i) {
        maxx = fmax(maxx, p->vertices[i].x);
        maxy = fmax(maxy, p->vertices[i].y);
    }
    double w = fmax(maxx - minx, diag * ORI_GRID_MIN_EXTENT_REL), h = fmax(maxy - miny, diag * ORI_GRID_MIN_EXTENT_REL);
    double cell = sqrt(w * h / (double)m);
    if (!(cell > 0.0)) cell = diag;
    int64_t nx = (int64_t)(w / cell) + 1, ny = (int64_t)(h / cell) + 1;
    while (nx * ny > 4 * (int64_t)m + 16) {
        cell *= 1.5;
        nx = (int64_t)(w / cell) + 1;
        ny = (int64_t)(h / cell) + 1;
    }
    crossing_grid g = {minx, miny, cell, nx, ny};
    size_t cells = (size_t)(nx * ny);
    int *start = ori__calloc(cells + 1, sizeof(int)); // start[c] … start[c+1]: cell c's entries
    for (int e = 0; e < m; ++e) grid_enter(p, e, &g, start, NULL);
    int64_t total = 0;
    for (size_t c = 0; c < cells; ++c) {
        total += start[c + 1];
        if (total > INT32_MAX) ori__assert_fail("crossing grid: too many entries", __FILE__, __LINE__);
        start[c + 1] = (int)total;
    }
    int *items = ori__alloc(sizeof(int) * (size_t)(total ? total : 1));
    int *fill = ori__alloc(sizeof(int) * cells);
    memcpy(fill, start, sizeof(int) * cells);
    for (int e = 0; e < m; ++e) grid_enter(p, e, &g, fill, items);
    ori__free(fill);
    ori_status st = ORI_OK;
    int bad_e = -1, bad_f = -1;
    for (size_t c = 0; c < cells && st == ORI_OK; ++c) {
        int i = start[c], j = start[c + 1];
        for (int x = i; x < j && st == ORI_OK; ++x) {
            // Edges conflict when they intersect anywhere but at a shared end point.
            const int *ev = p->edges[items[x]].v;
            ori_v2 a = ori__pattern_v2(p, ev[0]), b = ori__pattern_v2(p, ev[1]);
            for (int y = x + 1; y < j; ++y) {
                if (items[x] == items[y]) continue;
                const int *fv = p->edges[items[y]].v;
                if (ori__segments_conflict(a, b, ev, ori__pattern_v2(p, fv[0]), ori__pattern_v2(p, fv[1]), fv)) {
                    bad_e = items[x] < items[y] ? items[x] : items[y];
                    bad_f = items[x] < items[y] ? items[y] : items[x];
                    st = ORI_ERR_CROSSING;
                    break;
                }
            }
        }
    }
    ori__free(items);
    ori__free(start);
    if (st != ORI_OK)
        return ori__fail_at(error, st, "edges_vertices", bad_e,
                            "edge %d intersects edge %d away from a shared vertex", bad_e, bad_f);
    return ORI_OK;
}

// --- faces -------------------------------------------------------------------------------

// A traced cycle is the outer boundary of its part of the graph exactly when the region left of
// it holds the points just left of the cycle's lowest-leftmost vertex (the region of a face lies
// within its boundary's hull, right of that vertex). Decided by orientation signs, so that a
// tree, whose single cycle has zero area, is never taken for a face.
static bool is_outer_boundary(const ori_pattern *p, const int *cycle, int n)
{
    int m = 0;
    for (int i = 1; i < n; ++i) {
        ori_v3 a = p->vertices[cycle[i]], b = p->vertices[cycle[m]];
        if (a.x < b.x || (a.x == b.x && a.y < b.y)) m = i;
    }
    ori_v2 u = ori__pattern_v2(p, cycle[m]);
    ori_v2 left = ori_v2_make(u.x - fmax(1.0, fabs(u.x)), u.y); // (exact: a point left of u)
    for (int i = 0; i < n; ++i)
        if (cycle[i] == cycle[m] &&
            ori__corner_contains(u, ori__pattern_v2(p, cycle[(i + 1) % n]), ori__pattern_v2(p, cycle[(i + n - 1) % n]), left))
            return true;
    return false;
}

// Trace faces of the planar graph: the face left of half-edge u→v continues with the edge just
// clockwise of (v→u) around v. Every cycle is a face but the outer boundaries.
static void trace_faces(ori_pattern *p)
{
    int m = p->edge_count;
    int nh = 2 * m;
    int *pos = ori__alloc(sizeof(int) * (size_t)(nh ? nh : 1)); // half-edge → slot at its origin
    char *used = ori__calloc((size_t)(nh ? nh : 1), 1);
    for (int v = 0; v < p->vertex_count; ++v)
        for (int s = p->vert_edge_offsets[v]; s < p->vert_edge_offsets[v + 1]; ++s) {
            int e = p->vert_edges[s];
            int dir = p->edges[e].v[0] == v ? 0 : 1;
            pos[2 * e + dir] = s;
        }
    int *cycle = NULL;
    int ccount = 0, ccap = 0;
    for (int h0 = 0; h0 < nh; ++h0) {
        if (used[h0]) continue;
        ccount = 0;
        int h = h0;
        while (!used[h]) {
            used[h] = 1;
            int e = h / 2, dir = h % 2;
            int u = p->edges[e].v[dir], v = p->edges[e].v[1 - dir];
            ORI__PUSH(cycle, ccount, ccap, u);
            int twin = 2 * e + (1 - dir);
            int s = pos[twin];
            int vb = p->vert_edge_offsets[v], vn = p->vert_edge_offsets[v + 1] - vb;
            int sp = vb + (s - vb + vn - 1) % vn;
            int e2 = p->vert_edges[sp];
            h = 2 * e2 + (p->edges[e2].v[0] == v ? 0 : 1);
        }
        if (ccount >= 3 && !is_outer_boundary(p, cycle, ccount)) {
            ori__pattern_reserve_faces(p, p->face_count + 1, p->face_vertex_count + ccount);
            memcpy(p->face_vertices + p->face_vertex_count, cycle, sizeof(int) * (size_t)ccount);
            p->face_vertex_count += ccount;
            p->face_count += 1;
            p->face_offsets[p->face_count] = p->face_vertex_count;
        }
    }
    ori__free(cycle);
    ori__free(pos);
    ori__free(used);
}

// Map face sides to edges and edges to their left/right faces.
static ori_status link_faces(ori_pattern *p, ori_error *error)
{
    p->face_edges = ori__alloc(sizeof(int) * (size_t)(p->face_vertex_count ? p->face_vertex_count : 1));
    p->edge_faces = ori__alloc(sizeof(int) * 2 * (size_t)(p->edge_count ? p->edge_count : 1));
    for (int i = 0; i < 2 * p->edge_count; ++i) p->edge_faces[i] = ORI_NULL_INDEX;
    for (int f = 0; f < p->face_count; ++f) {
        int b = p->face_offsets[f], n = p->face_offsets[f + 1] - b;
        if (n < 3)
            return ori__fail_at(error, ORI_ERR_TOPOLOGY, "faces_vertices", f,
                                "face has %d vertices (at least 3 needed)", n);
        // A flat sheet's clockwise face keeps its order; its sides are mirrored.
        bool flip = !p->folded_form && ori__pattern_face_area2(p, f) < 0.0;
        for (int k = 0; k < n; ++k) {
            int u = p->face_vertices[b + k], v = p->face_vertices[b + (k + 1) % n];
            int e = ori_pattern_find_edge(p, u, v);
            if (e == ORI_NULL_INDEX)
                return ori__fail_at(error, ORI_ERR_TOPOLOGY, "faces_vertices", f,
                                    "side %d-%d of the face is not an edge", u, v);
            p->face_edges[b + k] = e;
            int side = (p->edges[e].v[0] == u) ? 0 : 1;
            if (flip) side = 1 - side;
            int *slot = &p->edge_faces[2 * e + side];
            if (*slot != ORI_NULL_INDEX && *slot != f)
                return ori__fail_at(error, ORI_ERR_TOPOLOGY, "faces_vertices", f,
                                    "edge %d already has face %d on this side", e, *slot);
            *slot = f;
        }
    }
    return ORI_OK;
}

// --- build -------------------------------------------------------------------------------

static ori_status check_indices(const ori_pattern *p, ori_error *error)
{
    for (int i = 0; i < p->vertex_count; ++i) {
        ori_v3 v = p->vertices[i];
        if (!ori__coord_ok(v.x) || !ori__coord_ok(v.y) || !ori__coord_ok(v.z))
            return ori__fail_at(error, ORI_ERR_RANGE, "vertices_coords", i, "coordinate is not finite or exceeds %g", ORI_COORD_MAX);
    }
    for (int e = 0; e < p->edge_count; ++e) {
        for (int k = 0; k < 2; ++k) {
            int v = p->edges[e].v[k];
            if (v < 0 || v >= p->vertex_count)
                return ori__fail_at(error, ORI_ERR_RANGE, "edges_vertices", e,
                                    "vertex index %d out of range (%d vertices)", v, p->vertex_count);
        }
        if (p->edges[e].v[0] == p->edges[e].v[1])
            return ori__fail_at(error, ORI_ERR_DEGENERATE, "edges_vertices", e,
                                "edge joins vertex %d to itself", p->edges[e].v[0]);
        if (!isfinite(p->edges[e].fold_angle_rad))
            return ori__fail_at(error, ORI_ERR_RANGE, "edges_foldAngle", e, "fold angle is not finite");
    }
    for (int f = 0; f < p->face_count; ++f)
        for (int k = p->face_offsets[f]; k < p->face_offsets[f + 1]; ++k) {
            int v = p->face_vertices[k];
            if (v < 0 || v >= p->vertex_count)
                return ori__fail_at(error, ORI_ERR_RANGE, "faces_vertices", f,
                                    "vertex index %d out of range (%d vertices)", v, p->vertex_count);
        }
    return ORI_OK;
}

static ori_status check_zero_length(const ori_pattern *p, double tol, ori_error *error)
{
    for (int e = 0; e < p->edge_count; ++e) {
        ori_v3 a = p->vertices[p->edges[e].v[0]], b = p->vertices[p->edges[e].v[1]];
        if (p->edges[e].v[0] == p->edges[e].v[1] || ori_v3_norm(ori_v3_sub(a, b)) <= tol)
            return ori__fail_at(error, ORI_ERR_DEGENERATE, "edges_vertices", e,
                                "zero-length edge (vertices %d and %d)", p->edges[e].v[0], p->edges[e].v[1]);
    }
    return ORI_OK;
}

ori_status ori_pattern_build(ori_pattern *p, const ori_build_def *def, ori_error *error)
{
    ORI_ASSERT(p);
    ori_build_def defaults = ori_default_build_def();
    if (!def) def = &defaults;
    ORI_ASSERT(def->internal_value == ORI__DEF_COOKIE);
    ori__pattern_invalidate(p);
    ori_error_clear(error);

    ori_status st = check_indices(p, error);
    if (st != ORI_OK) return st;

    double diag = bbox_diagonal(p, NULL);
    double tol = ORI_TOL_LENGTH_REL * diag;
    bool flat = !p->folded_form;

    // Zero-length edges are reported as such (before the coincident-vertex check, which would
    // name their endpoints); with welding they show up after the merge as self-loops.
    if (!def->weld && (st = check_zero_length(p, tol, error)) != ORI_OK) return st;

    if (flat && (def->check_planarity || def->weld) && p->vertex_count > 1) {
        int *twin = ori__alloc(sizeof(int) * (size_t)p->vertex_count);
        find_close_vertices(p, tol, twin);
        int first = -1;
        for (int i = 0; i < p->vertex_count && first < 0; ++i)
            if (twin[i] >= 0) first = i;
        if (first >= 0 && def->weld) {
            weld_vertices(p, twin);
        } else if (first >= 0) {
            int other = twin[first];
            ori__free(twin);
            return ori__fail_at(error, ORI_ERR_DUPLICATE, "vertices_coords", first,
                                "vertex coincides with vertex %d (closer than %.3g; --weld merges them)",
                                other, tol);
        }
        ori__free(twin);
    }


    if (def->weld && (st = check_zero_length(p, tol, error)) != ORI_OK) return st;

    // Edge hash, rejecting duplicates.
    p->edge_hash_cap = ori__hash_capacity(p->edge_count);
    p->edge_hash = ori__alloc(sizeof(int) * (size_t)p->edge_hash_cap);
    for (int i = 0; i < p->edge_hash_cap; ++i) p->edge_hash[i] = -1;
    int mask = p->edge_hash_cap - 1;
    for (int e = 0; e < p->edge_count; ++e) {
        uint64_t key = ori__pair_key(p->edges[e].v[0], p->edges[e].v[1]);
        int i = (int)(ori__mix64(key) & (uint64_t)mask);
        for (;; i = (i + 1) & mask) {
            int o = p->edge_hash[i];
            if (o < 0) {
                p->edge_hash[i] = e;
                break;
            }
            if (ori__pair_key(p->edges[o].v[0], p->edges[o].v[1]) == key) {
                ori__free(p->edge_hash);
                p->edge_hash = NULL;
                p->edge_hash_cap = 0;
                return ori__fail_at(error, ORI_ERR_TOPOLOGY, "edges_vertices", e,
                                    "edge repeats edge %d (same two vertices)", o);
            }
        }
    }

    // Vertex → edges (CSR).
    p->vert_edge_offsets = ori__calloc((size_t)p->vertex_count + 1, sizeof(int));
    p->vert_edges = ori__alloc(sizeof(int) * 2 * (size_t)(p->edge_count ? p->edge_count : 1));
    for (int e = 0; e < p->edge_count; ++e) {
        p->vert_edge_offsets[p->edges[e].v[0] + 1]++;
        p->vert_edge_offsets[p->edges[e].v[1] + 1]++;
    }
    for (int v = 0; v < p->vertex_count; ++v) p->vert_edge_offsets[v + 1] += p->vert_edge_offsets[v];
    int *fill = ori__alloc(sizeof(int) * (size_t)(p->vertex_count ? p->vertex_count : 1));
    memcpy(fill, p->vert_edge_offsets, sizeof(int) * (size_t)p->vertex_count);
    for (int e = 0; e < p->edge_count; ++e) {
        p->vert_edges[fill[p->edges[e].v[0]]++] = e;
        p->vert_edges[fill[p->edges[e].v[1]]++] = e;
    }
    ori__free(fill);
    p->diagonal = diag;
    p->built = true; // find_edge is usable from here on; failures below invalidate again

    if (flat) {
        sort_vertex_edges_2d(p);
        if (def->check_planarity) {
            st = check_crossings(p, error);
            if (st != ORI_OK) {
                ori__pattern_invalidate(p);
                return st;
            }
        }
        if (p->face_count == 0 && def->compute_faces) trace_faces(p);
    } else if (p->face_count == 0 && p->edge_count > 0) {
        ori__pattern_invalidate(p);
        return ori__fail_at(error, ORI_ERR_TOPOLOGY, "faces_vertices", ORI_NULL_INDEX,
                            "a folded form needs faces_vertices (faces cannot be traced in 3D)");
    }
    st = link_faces(p, error);
    if (st != ORI_OK) {
        ori__pattern_invalidate(p);
        return st;
    }
    if (!flat) order_vertex_edges_by_faces(p);
    return ORI_OK;
}

// --- queries -----------------------------------------------------------------------------

int ori_pattern_vertex_degree(const ori_pattern *p, int v)
{
    ORI_ASSERT(p && p->built && v >= 0 && v < p->vertex_count);
    return p->vert_edge_offsets[v + 1] - p->vert_edge_offsets[v];
}

int ori_pattern_vertex_edges(const ori_pattern *p, int v, int *out, int cap)
{
    int n = ori_pattern_vertex_degree(p, v);
    int m = n < cap ? n : cap;
    if (out && m > 0) memcpy(out, p->vert_edges + p->vert_edge_offsets[v], sizeof(int) * (size_t)m);
    return n;
}

void ori_pattern_edge_faces(const ori_pattern *p, int e, int faces[2])
{
    ORI_ASSERT(p && p->built && e >= 0 && e < p->edge_count);
    faces[0] = p->edge_faces[2 * e];
    faces[1] = p->edge_faces[2 * e + 1];
}

bool ori_pattern_vertex_is_interior(const ori_pattern *p, int v)
{
    ORI_ASSERT(p && p->built && v >= 0 && v < p->vertex_count);
    int b = p->vert_edge_offsets[v], n = p->vert_edge_offsets[v + 1] - b;
    if (n < 1) return false;
    for (int k = 0; k < n; ++k) {
        int e = p->vert_edges[b + k];
        ori_assignment a = p->edges[e].assignment;
        if (a == ORI_ASSIGN_BOUNDARY || a == ORI_ASSIGN_CUT) return false;
        if (p->edge_faces[2 * e] == ORI_NULL_INDEX || p->edge_faces[2 * e + 1] == ORI_NULL_INDEX) return false;
    }
    return true;
}

int ori_pattern_interior_vertex_count(const ori_pattern *p)
{
    ORI_ASSERT(p && p->built);
    int n = 0;
    for (int v = 0; v < p->vertex_count; ++v) n += ori_pattern_vertex_is_interior(p, v);
    return n;
}

static ori_v3 edge_dir_from(const ori_pattern *p, int e, int v)
{
    int w = p->edges[e].v[0] == v ? p->edges[e].v[1] : p->edges[e].v[0];
    return ori_v3_sub(p->vertices[w], p->vertices[v]);
}

int ori_pattern_vertex_sectors(const ori_pattern *p, int v, int *edges, double *sectors, int cap)
{
    ORI_ASSERT(p && p->built && v >= 0 && v < p->vertex_count);
    int b = p->vert_edge_offsets[v], n = p->vert_edge_offsets[v + 1] - b;
    int m = n < cap ? n : cap;
    for (int k = 0; k < m; ++k) {
        int e = p->vert_edges[b + k];
        if (edges) edges[k] = e;
        if (!sectors) continue;
        int e2 = p->vert_edges[b + (k + 1) % n];
        ori_v3 d1 = edge_dir_from(p, e, v), d2 = edge_dir_from(p, e2, v);
        if (n == 1) {
            sectors[k] = 2.0 * ORI_PI;
        } else if (!p->folded_form) {
            double a = ori_angle_ccw_v2(ori_v2_make(d1.x, d1.y), ori_v2_make(d2.x, d2.y));
            if (n == 2 && a == 0.0) a = 2.0 * ORI_PI;
            sectors[k] = a;
        } else {
            sectors[k] = ori_angle_between_v3(d1, d2);
        }
    }
    return n;
}
