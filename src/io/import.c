// Importing drawings: reading a file's (or a text's) segments, and planarising them into
// a crease pattern (arrangement with the weld tolerance, then clean-up of drawing artefacts:
// collinear pass-through vertices and hole faces).
#include <stdlib.h>

#include "../core/hash.h"
#include "../geometry/geometry_internal.h"
#include "../pattern/pattern_internal.h"
#include "reader_internal.h"

ori_import_def ori_default_import_def(void)
{
    ori_import_def def;
    def.weld_rel = ORI_TOL_IMPORT_WELD_REL;
    def.gap_rel = ORI_IMPORT_GAP_AUTO;
    def.merge_collinear = true;
    def.remove_holes = true;
    def.curve_segments = 0;
    def.heal_splits = true;
    def.internal_value = ORI__DEF_COOKIE;
    return def;
}

static void stats_reset(ori_import_stats *stats)
{
    if (stats) {
        memset(stats, 0, sizeof *stats);
        stats->dangling_example = stats->part_example = ORI_NULL_INDEX;
    }
}

// The segments of a drawing's text with the reader of its format.
static ori_status text_segments(const char *text, size_t size, ori_format format, int curve_segments,
                                ori_segment **segments, int *count, ori_import_stats *stats, ori_error *error)
{
    if (!ori_format_is_drawing(format))
        return ori__fail(error, ORI_ERR_UNSUPPORTED, "cannot read segments from a '%s' file", ori_format_name(format));
    if (size == 0) return ori__fail(error, ORI_ERR_PARSE, "the file is empty");
    if (format == ORI_FORMAT_SVG) return ori_svg_read_curves(text, size, curve_segments, segments, count, stats, error);
    if (format == ORI_FORMAT_OPX) return ori_opx_read_segments(text, size, segments, count, stats, error);
    return ori_cp_read_segments(text, size, segments, count, stats, error);
}

static ori_status read_segments(const char *path, ori_format format, int curve_segments, ori_segment **segments,
                                int *count, ori_import_stats *stats, ori_error *error)
{
    ORI_ASSERT(path && segments && count);
    *segments = NULL;
    *count = 0;
    stats_reset(stats);
    if (format == ORI_FORMAT_UNKNOWN) format = ori_format_from_path(path);
    if (!ori_format_is_drawing(format))
        return ori__fail(error, ORI_ERR_UNSUPPORTED, "cannot read segments from a '%s' file", ori_format_name(format));
    char *text;
    size_t size;
    ori_status st = ori_file_read_all(path, ORI_IMPORT_MAX_BYTES, &text, &size, error);
    if (st != ORI_OK) return st;
    st = text_segments(text, size, format, curve_segments, segments, count, stats, error);
    ori__free(text);
    return st;
}

ori_status ori_read_segments(const char *path, ori_format format, ori_segment **segments, int *count,
                             ori_import_stats *stats, ori_error *error)
{
    return read_segments(path, format, 0, segments, count, stats, error);
}

// --- planarisation and clean-up --------------------------------------------------------------

// Remove every vertex that only joins two collinear edges (within tol) of equal assignment and
// fold angle; the chains become single edges. Chains that would end on the same two vertices
// (another chain or an edge) keep their vertices (within a coarse weld, two sides of a thin triangle can both look
// straight: merging both would lay two edges on one vertex pair). Returns a new unbuilt
// pattern, or NULL when there is nothing to merge.
static ori_pattern *merge_collinear(const ori_pattern *p, double tol)
{
    int nv = p->vertex_count, ne = p->edge_count;
    char *removed = ori__calloc((size_t)(nv ? nv : 1), 1);
    char *kept = ori__calloc((size_t)(nv ? nv : 1), 1); // vertices a repeated chain keeps
    int *parent = ori__alloc(sizeof(int) * (size_t)(ne ? ne : 1));
    int *end0 = ori__alloc(sizeof(int) * (size_t)(ne ? ne : 1));
    int *end1 = ori__alloc(sizeof(int) * (size_t)(ne ? ne : 1));
    int cap = ori__hash_capacity(ne);
    int *slot = ori__alloc(sizeof(int) * (size_t)cap);
    int merged;
    for (bool again = true; again;) {
        again = false;
        memset(removed, 0, (size_t)(nv ? nv : 1));
        for (int e = 0; e < ne; ++e) parent[e] = e;
        merged = 0;
        for (int v = 0; v < nv; ++v) {
            if (kept[v] || ori_pattern_vertex_degree(p, v) != 2) continue;
            int ed[2];
            ori_pattern_vertex_edges(p, v, ed, 2);
            const ori_edge *e0 = &p->edges[ed[0]], *e1 = &p->edges[ed[1]];
            if (e0->assignment != e1->assignment || e0->fold_angle_rad != e1->fold_angle_rad) continue;
            int u = e0->v[0] == v ? e0->v[1] : e0->v[0], w = e1->v[0] == v ? e1->v[1] : e1->v[0];
            if (u == w) continue;
            ori_v2 pu = ori__pattern_v2(p, u), pv = ori__pattern_v2(p, v), pw = ori__pattern_v2(p, w);
            ori_v2 d = ori_v2_sub(pw, pu);
            double len = ori_v2_norm(d);
            if (!(len > 0.0)) continue;
            double dist = fabs(ori_orient2d(pu, pw, pv)) / len;
            if (dist > tol || ori_v2_dot(ori_v2_sub(pu, pv), ori_v2_sub(pw, pv)) >= 0.0) continue;
            removed[v] = 1;
            int a = ori__uf_root(parent, ed[0]), b = ori__uf_root(parent, ed[1]);
            if (a != b) parent[a < b ? b : a] = a < b ? a : b;
            merged++;
        }
        if (merged == 0) break;
        // A group is a chain u – v1 – … – w of merged edges: u and w, the kept vertices, each
        // occur once among the group's edge ends (a single unmerged edge is the chain u – w).
        for (int e = 0; e < ne; ++e) end0[e] = end1[e] = ORI_NULL_INDEX;
        for (int e = 0; e < ne; ++e) {
            int r = ori__uf_root(parent, e);
            for (int k = 0; k < 2; ++k) {
                int v = p->edges[e].v[k];
                if (removed[v]) continue;
                if (end0[r] == ORI_NULL_INDEX) end0[r] = v;
                else end1[r] = v;
            }
        }
        // Two groups on the same ends: both keep their vertices, and the merge is planned again.
        for (int i = 0; i < cap; ++i) slot[i] = -1;
        for (int e = 0; e < ne; ++e) {
            if (ori__uf_root(parent, e) != e) continue;
            ORI_ASSERT(end0[e] != ORI_NULL_INDEX && end1[e] != ORI_NULL_INDEX);
            uint64_t key = ori__pair_key(end0[e], end1[e]);
            for (int i = (int)(ori__mix64(key) & (uint64_t)(cap - 1));; i = (i + 1) & (cap - 1)) {
                int o = slot[i];
                if (o < 0) {
                    slot[i] = e;
                    break;
                }
                if (ori__pair_key(end0[o], end1[o]) != key) continue;
                for (int f = 0; f < ne; ++f) {
                    int r = ori__uf_root(parent, f);
                    if (r != e && r != o) continue;
                    for (int k = 0; k < 2; ++k)
                        if (removed[p->edges[f].v[k]]) kept[p->edges[f].v[k]] = 1, again = true;
                }
                break;
            }
        }
    }
    ori__free(slot);
    ori__free(kept);
    if (merged == 0) {
        ori__free(end0);
        ori__free(end1);
        ori__free(removed);
        ori__free(parent);
        return NULL;
    }
    int *map = ori__alloc(sizeof(int) * (size_t)(nv ? nv : 1));
    ori_pattern_def pdef = ori_default_pattern_def();
    ori_pattern *q = ori_pattern_create(&pdef);
    for (int v = 0; v < nv; ++v) map[v] = removed[v] ? ORI_NULL_INDEX : ori_pattern_add_vertex(q, p->vertices[v]);
    // One edge per group, at the position of its lowest edge index (the root).
    for (int e = 0; e < ne; ++e) {
        if (ori__uf_root(parent, e) != e) continue;
        ori_pattern_add_edge(q, map[end0[e]], map[end1[e]], p->edges[e].assignment, p->edges[e].fold_angle_rad);
    }
    q->has_fold_angles = p->has_fold_angles;
    ori__free(end0);
    ori__free(end1);
    ori__free(map);
    ori__free(removed);
    ori__free(parent);
    return q;
}

static bool is_cut_or_boundary(ori_assignment a) { return a == ORI_ASSIGN_BOUNDARY || a == ORI_ASSIGN_CUT; }

// Faces bounded only by B/C edges that all have paper on their other side are holes (a black
// outline drawn inside the sheet). Returns how many were removed (faces re-added, unbuilt).
static int remove_holes(ori_pattern *p)
{
    int nf = p->face_count;
    char *hole = ori__calloc((size_t)(nf ? nf : 1), 1);
    int holes = 0;
    for (int f = 0; f < nf; ++f) {
        bool all = true;
        for (int k = p->face_offsets[f]; k < p->face_offsets[f + 1] && all; ++k) {
            int e = p->face_edges[k];
            int other = p->edge_faces[2 * e] == f ? p->edge_faces[2 * e + 1] : p->edge_faces[2 * e];
            all = is_cut_or_boundary(p->edges[e].assignment) && other != ORI_NULL_INDEX && other != f;
        }
        hole[f] = all;
        holes += all;
    }
    if (holes) {
        int *offsets = ori__alloc(sizeof(int) * (size_t)(nf + 1));
        int *verts = ori__alloc(sizeof(int) * (size_t)(p->face_vertex_count ? p->face_vertex_count : 1));
        memcpy(offsets, p->face_offsets, sizeof(int) * (size_t)(nf + 1));
        memcpy(verts, p->face_vertices, sizeof(int) * (size_t)p->face_vertex_count);
        ori_pattern_clear_faces(p);
        for (int f = 0; f < nf; ++f)
            if (!hole[f]) ori_pattern_add_face(p, verts + offsets[f], offsets[f + 1] - offsets[f]);
        ori__free(offsets);
        ori__free(verts);
    }
    ori__free(hole);
    return holes;
}

// Whether non-vertical segment s (left end l, right end r) lies below segment t at x just right
// of x0, both spanning it and not crossing (planar edges): decided exactly by orientation signs.
static bool below(ori_v2 sl, ori_v2 sr, ori_v2 tl, ori_v2 tr)
{
    if (sl.x >= tl.x) { // s starts within t's x range: where is s's start relative to t?
        int o = ori_orient2d_sign(tl, tr, sl);
        if (o == 0) o = ori_orient2d_sign(tl, tr, sr); // they meet there: the slopes decide
        return o < 0;
    }
    int o = ori_orient2d_sign(sl, sr, tl);
    if (o == 0) o = ori_orient2d_sign(sl, sr, tr);
    return o > 0;
}

static int grid_index(double v, double v0, double cell, int n)
{
    double c = floor((v - v0) / cell);
    if (!(c >= 0.0)) return 0;
    return c >= (double)n ? n - 1 : (int)c;
}

// All edges in a uniform grid of square cells, by columns and the rows an edge's y range covers
// within a column (one row more on each side against rounding at the column's edges); CSR:
// cell → edges. For the islands check and the nearest-line queries of gaps and diagnosis.
typedef struct line_grid {
    double x0, y0, cell;
    int nx, ny;
    int *start, *items;
} line_grid;

static void line_grid_cells(const ori_pattern *p, const line_grid *g, int e, int *count, int *fill)
{
    ori_v2 a = ori__pattern_v2(p, p->edges[e].v[0]), b = ori__pattern_v2(p, p->edges[e].v[1]);
    if (a.x > b.x) {
        ori_v2 t = a;
        a = b;
        b = t;
    }
    int c0 = grid_index(a.x, g->x0, g->cell, g->nx), c1 = grid_index(b.x, g->x0, g->cell, g->nx);
    for (int cx = c0; cx <= c1; ++cx) {
        double lo, hi;
        ori__segment_y_range(a, b, g->x0 + cx * g->cell, g->x0 + (cx + 1) * g->cell, &lo, &hi);
        int r0 = grid_index(lo, g->y0, g->cell, g->ny) - 1, r1 = grid_index(hi, g->y0, g->cell, g->ny) + 1;
        if (r0 < 0) r0 = 0;
        if (r1 >= g->ny) r1 = g->ny - 1;
        for (int r = r0; r <= r1; ++r) {
            int cell = cx * g->ny + r;
            if (fill) g->items[fill[cell]++] = e;
            else count[cell]++;
        }
    }
}

// About one cell per edge, no smaller than radius (a nearest-line query looks at the 3 × 3 cells
// around its point) nor than a quarter of the mean edge length (a long edge then enters a few
// cells per edge length, not hundreds).
static void line_grid_build(const ori_pattern *p, double radius, line_grid *g)
{
    double lx = INFINITY, ly = INFINITY, hx = -INFINITY, hy = -INFINITY, total = 0.0;
    for (int v = 0; v < p->vertex_count; ++v) {
        lx = fmin(lx, p->vertices[v].x), ly = fmin(ly, p->vertices[v].y);
        hx = fmax(hx, p->vertices[v].x), hy = fmax(hy, p->vertices[v].y);
    }
    for (int e = 0; e < p->edge_count; ++e)
        total += ori_v2_norm(ori_v2_sub(ori__pattern_v2(p, p->edges[e].v[1]), ori__pattern_v2(p, p->edges[e].v[0])));
    double w = hx - lx, h = hy - ly;
    g->cell = fmax(fmax(radius, 0.25 * total / (p->edge_count + 1.0)), sqrt(fmax(w * h, 0.0) / (p->edge_count + 1.0)));
    if (!(g->cell > 0.0) || !isfinite(g->cell)) g->cell = fmax(fmax(w, h), 1.0);
    while ((floor(w / g->cell) + 1.0) * (floor(h / g->cell) + 1.0) > (double)(1 << 22)) g->cell *= 1.5;
    g->x0 = lx, g->y0 = ly;
    g->nx = (int)floor(w / g->cell) + 1, g->ny = (int)floor(h / g->cell) + 1;
    size_t cells = (size_t)g->nx * (size_t)g->ny;
    g->start = ori__calloc(cells + 1, sizeof(int));
    for (int e = 0; e < p->edge_count; ++e) line_grid_cells(p, g, e, g->start + 1, NULL);
    for (size_t c = 0; c < cells; ++c) g->start[c + 1] += g->start[c];
    g->items = ori__alloc(sizeof(int) * (size_t)(g->start[cells] ? g->start[cells] : 1));
    int *fill = ori__alloc(sizeof(int) * cells);
    memcpy(fill, g->start, sizeof(int) * cells);
    for (int e = 0; e < p->edge_count; ++e) line_grid_cells(p, g, e, NULL, fill);
    ori__free(fill);
}

static void line_grid_free(line_grid *g)
{
    ori__free(g->start);
    ori__free(g->items);
}

// A connected part of the drawing that lies inside a face of another part (a hole or a crease
// touching nothing) cannot be expressed: FOLD faces are single cycles. Reject it, naming where.
//
// For each part, the vertical ray up from (just right of) its leftmost vertex q finds the lowest
// edge e of any other part: q lies in the face below e, so the part is inside a face exactly when
// e has a face on that side. Parts inside a face whose ray first meets yet another part are
// found through the leftmost part in that face, whose ray meets the face's own boundary. The
// edges are found in a grid walked upwards from q (about √E cells), not by testing every face.
static ori_status check_islands(const ori_pattern *p, ori_error *error)
{
    int nv = p->vertex_count;
    int *comp = ori__alloc(sizeof(int) * (size_t)(nv ? nv : 1));
    int parts = ori__pattern_parts(p, comp);
    if (parts <= 1 || p->face_count == 0) {
        ori__free(comp);
        return ORI_OK;
    }
    // leftmost (then lowest) vertex of each component
    int *left = ori__alloc(sizeof(int) * (size_t)nv);
    for (int v = 0; v < nv; ++v) left[v] = ORI_NULL_INDEX;
    for (int v = 0; v < nv; ++v) {
        int r = comp[v];
        ori_v3 a = p->vertices[v];
        if (left[r] == ORI_NULL_INDEX || a.x < p->vertices[left[r]].x ||
            (a.x == p->vertices[left[r]].x && a.y < p->vertices[left[r]].y))
            left[r] = v;
    }
    line_grid g;
    line_grid_build(p, 0.0, &g);
    ori_status st = ORI_OK;
    for (int r = 0; r < nv && st == ORI_OK; ++r) {
        if (comp[r] != r || left[r] == ORI_NULL_INDEX) continue;
        ori_v2 q = ori__pattern_v2(p, left[r]);
        int col = grid_index(q.x, g.x0, g.cell, g.nx), best = ORI_NULL_INDEX;
        ori_v2 bl = q, br = q;
        double best_y = INFINITY;
        for (int row = grid_index(q.y, g.y0, g.cell, g.ny); row < g.ny; ++row) {
            // (the lowest edge found lies at best_y ≈: once a row ends below it, no later row has a lower one)
            if (best != ORI_NULL_INDEX && g.y0 + row * g.cell > best_y + g.cell) break;
            int cell = col * g.ny + row;
            for (int k = g.start[cell]; k < g.start[cell + 1]; ++k) {
                int e = g.items[k];
                if (comp[p->edges[e].v[0]] == r) continue;
                ori_v2 a = ori__pattern_v2(p, p->edges[e].v[0]), b = ori__pattern_v2(p, p->edges[e].v[1]);
                ori_v2 el = a.x < b.x ? a : b, er = a.x < b.x ? b : a;
                if (!(el.x <= q.x && q.x < er.x)) continue;     // spans x just right of q
                if (ori_orient2d_sign(el, er, q) >= 0) continue; // not above q
                if (best == ORI_NULL_INDEX || below(el, er, bl, br)) {
                    best = e, bl = el, br = er;
                    best_y = el.y + (q.x - el.x) / (er.x - el.x) * (er.y - el.y);
                }
            }
        }
        if (best == ORI_NULL_INDEX) continue;
        // The face below best: right of v0→v1 when it runs left to right, else left of it.
        bool ltr = ori__pattern_v2(p, p->edges[best].v[0]).x < ori__pattern_v2(p, p->edges[best].v[1]).x;
        if (p->edge_faces[2 * best + (ltr ? 1 : 0)] != ORI_NULL_INDEX)
            st = ori__fail_at(error, ORI_ERR_TOPOLOGY, "vertices_coords", left[r],
                              "the lines around (%g, %g) touch nothing else and lie inside a face: FOLD faces "
                              "cannot have holes; connect them to the rest with a crease",
                              q.x, q.y);
    }
    line_grid_free(&g);
    ori__free(comp);
    ori__free(left);
    return st;
}

// --- planarisation, gaps, diagnosis -------------------------------------------------------------

// Planarise with the weld, then merge collinear pass-through vertices and remove holes as def
// says (no island check).
static ori_status pipeline(const ori_segment *segs, int count, const ori_import_def *def, double weld, ori_pattern **out,
                           ori_error *error)
{
    *out = NULL;
    // The arrangement snaps within ORI_TOL_LENGTH_REL × length_scale: scale it to the weld.
    ori_insert_def idef = ori_default_insert_def();
    idef.name_faces = false;
    idef.length_scale = weld / ORI_TOL_LENGTH_REL;
    ori_pattern *p = NULL;
    ori_status st = ori_pattern_from_segments(segs, count, &idef, &p, NULL, error);
    if (st != ORI_OK) return st;
    ori_pattern_set_has_fold_angles(p, true);
    ori_build_def bdef = ori_default_build_def();
    if (def->merge_collinear) {
        // A chain of nearly collinear edges becomes its chord, which lies up to the weld away from
        // the chain: where another edge passes closer than that, the chord crosses it and the
        // merged pattern does not build. Such chains keep their vertices (the pattern as
        // planarised), so that a file orikin writes from it reads back (fuzz_cp found one).
        ori_pattern *q = merge_collinear(p, weld);
        if (q && ori_pattern_build(q, &bdef, NULL) == ORI_OK) {
            ori_pattern_destroy(p);
            p = q;
        } else {
            ori_pattern_destroy(q);
        }
    }
    if (st == ORI_OK && def->remove_holes && remove_holes(p) > 0) st = ori_pattern_build(p, &bdef, error);
    if (st != ORI_OK) {
        ori_pattern_destroy(p);
        return st;
    }
    *out = p;
    return ORI_OK;
}

// The closest point to x on an edge other than those at vertex v (within radius, which must not
// exceed the grid's cell): its distance, or INFINITY. *at receives the point.
static double nearest_line(const ori_pattern *p, const line_grid *g, int v, ori_v2 x, double radius, ori_v2 *at, int *edge)
{
    int cx = grid_index(x.x, g->x0, g->cell, g->nx), cy = grid_index(x.y, g->y0, g->cell, g->ny);
    double best = INFINITY;
    for (int i = cx - 1; i <= cx + 1; ++i)
        for (int j = cy - 1; j <= cy + 1; ++j) {
            if (i < 0 || j < 0 || i >= g->nx || j >= g->ny) continue;
            int cell = i * g->ny + j;
            for (int k = g->start[cell]; k < g->start[cell + 1]; ++k) {
                int e = g->items[k];
                if (p->edges[e].v[0] == v || p->edges[e].v[1] == v) continue;
                ori_v2 a = ori__pattern_v2(p, p->edges[e].v[0]), b = ori__pattern_v2(p, p->edges[e].v[1]);
                ori_v2 d = ori_v2_sub(b, a);
                double l2 = ori_v2_dot(d, d), t = l2 > 0.0 ? ori_v2_dot(ori_v2_sub(x, a), d) / l2 : 0.0;
                t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
                ori_v2 q = ori_v2_add(a, ori_v2_scale(d, t));
                double dist = ori_v2_norm(ori_v2_sub(x, q));
                if (dist < best) best = dist, *at = q, *edge = e;
            }
        }
    return best <= radius ? best : INFINITY;
}

// Where the ray from u through the dangling end v, continued by at most reach past v, first meets
// another edge (not at u or v): the distance past v, or INFINITY.
static double ray_hit(const ori_pattern *p, const line_grid *g, int u, int v, double reach, ori_v2 *at, int *edge)
{
    ori_v2 a = ori__pattern_v2(p, u), x = ori__pattern_v2(p, v), dir = ori_v2_sub(x, a);
    double len = ori_v2_norm(dir);
    if (!(len > 0.0)) return INFINITY;
    dir = ori_v2_scale(dir, 1.0 / len);
    int cx = grid_index(x.x, g->x0, g->cell, g->nx), cy = grid_index(x.y, g->y0, g->cell, g->ny);
    double best = INFINITY;
    for (int i = cx - 1; i <= cx + 1; ++i)
        for (int j = cy - 1; j <= cy + 1; ++j) {
            if (i < 0 || j < 0 || i >= g->nx || j >= g->ny) continue;
            int cell = i * g->ny + j;
            for (int k = g->start[cell]; k < g->start[cell + 1]; ++k) {
                int e = g->items[k], e0 = p->edges[e].v[0], e1 = p->edges[e].v[1];
                if (e0 == v || e1 == v || e0 == u || e1 == u) continue;
                ori_v2 b0 = ori__pattern_v2(p, e0), b1 = ori__pattern_v2(p, e1), r = ori_v2_sub(b1, b0);
                double den = ori_v2_cross(dir, r);
                if (den == 0.0) continue;
                ori_v2 q = ori_v2_sub(b0, x);
                double t = ori_v2_cross(q, r) / den, s = ori_v2_cross(q, dir) / den;
                if (t >= 0.0 && t <= reach && s >= 0.0 && s <= 1.0 && t < best)
                    best = t, *at = ori_v2_add(x, ori_v2_scale(dir, t)), *edge = e;
            }
        }
    return best;
}

// The degree of every vertex (into deg, vertex_count entries).
static void vertex_degrees(const ori_pattern *p, int *deg)
{
    memset(deg, 0, sizeof(int) * (size_t)p->vertex_count);
    for (int e = 0; e < p->edge_count; ++e) deg[p->edges[e].v[0]]++, deg[p->edges[e].v[1]]++;
}

// Close the gaps of at most gap: a dangling crease shorter than gap (an overshoot past a crossing,
// a stroke fragment) is dropped; a longer one whose free end stops within gap of another line is
// extended along its own direction onto it, or else moved to the nearest point of that line.
// Returns the segments of the result (NULL when nothing changed) with their count in *n.
static ori_segment *close_gaps(const ori_pattern *p, double gap, int *n, int *closed, double *largest)
{
    *n = *closed = 0;
    *largest = 0.0;
    int nv = p->vertex_count, ne = p->edge_count;
    int *deg = ori__alloc(sizeof(int) * (size_t)(nv ? nv : 1));
    vertex_degrees(p, deg);
    int dangling = 0;
    for (int v = 0; v < nv; ++v) dangling += deg[v] == 1;
    if (dangling == 0) {
        ori__free(deg);
        return NULL;
    }
    line_grid g;
    line_grid_build(p, gap, &g);
    ori_segment *segs = ori__alloc(sizeof(ori_segment) * (size_t)ne);
    for (int e = 0; e < ne; ++e) {
        const ori_edge *ed = &p->edges[e];
        ori_v2 end[2] = {ori__pattern_v2(p, ed->v[0]), ori__pattern_v2(p, ed->v[1])};
        bool drop = false;
        for (int k = 0; k < 2 && !drop; ++k) {
            int v = ed->v[k], u = ed->v[1 - k];
            if (deg[v] != 1) continue;
            ori_v2 at;
            int hit = ORI_NULL_INDEX;
            double len = ori_v2_norm(ori_v2_sub(end[k], end[1 - k]));
            if (deg[u] > 1 && len <= gap && nearest_line(p, &g, v, end[k], gap, &at, &hit) <= gap) {
                drop = true; // an overshoot: its free end is as close to a line as its length
                *largest = fmax(*largest, len);
            } else {
                double d = ray_hit(p, &g, u, v, gap, &at, &hit);
                if (!(d <= gap)) d = nearest_line(p, &g, v, end[k], gap, &at, &hit);
                if (!(d <= gap)) continue;
                // Within the gap of an end of the line it meets, it meets at that end (as drawn:
                // the lines touch there), not a sliver away from it.
                for (int j = 0; j < 2; ++j) {
                    ori_v2 c = ori__pattern_v2(p, p->edges[hit].v[j]);
                    if (ori_v2_norm(ori_v2_sub(c, at)) <= gap && ori_v2_norm(ori_v2_sub(c, end[k])) <= 2.0 * gap) {
                        at = c;
                        break;
                    }
                }
                end[k] = at;
                *largest = fmax(*largest, d);
            }
            (*closed)++;
        }
        if (drop) continue;
        ori_segment s = {end[0], end[1], ed->assignment, ed->fold_angle_rad};
        segs[(*n)++] = s;
    }
    line_grid_free(&g);
    ori__free(deg);
    if (*closed == 0) {
        ori__free(segs);
        return NULL;
    }
    return segs;
}

static int uf_find(int *parent, int v)
{
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

// Creases shorter than gap, the drawn line width, between a vertex of three or more lines and a
// pass-through vertex of two creases (lines that meet a hair beside a vertex, welded onto a
// crease there, cut a sliver off it whose far end joins, say, a mountain to a valley on one
// line): their ends touch on the page, so they are one vertex, where the lines meet. Shortest
// first. Returns the segments of the result (NULL when none is contracted) with their count in
// *n and the creases contracted in *contracted.
static ori_segment *contract_short(const ori_pattern *p, double gap, int *n, int *contracted)
{
    *n = *contracted = 0;
    int nv = p->vertex_count, ne = p->edge_count;
    int *order = NULL, count = 0;
    for (int e = 0; e < ne; ++e) {
        const ori_edge *ed = &p->edges[e];
        if (is_cut_or_boundary(ed->assignment)) continue;
        if (ori_v2_norm(ori_v2_sub(ori__pattern_v2(p, ed->v[0]), ori__pattern_v2(p, ed->v[1]))) > gap) continue;
        if (!order) order = ori__alloc(sizeof(int) * (size_t)ne);
        order[count++] = e;
    }
    if (count == 0) return NULL;
    int *deg = ori__alloc(sizeof(int) * (size_t)nv), *parent = ori__alloc(sizeof(int) * (size_t)nv);
    char *on_border = ori__calloc((size_t)nv, 1);
    ori_v2 *at = ori__alloc(sizeof(ori_v2) * (size_t)nv);
    vertex_degrees(p, deg);
    for (int v = 0; v < nv; ++v) parent[v] = v, at[v] = ori__pattern_v2(p, v);
    for (int e = 0; e < ne; ++e)
        if (is_cut_or_boundary(p->edges[e].assignment)) on_border[p->edges[e].v[0]] = on_border[p->edges[e].v[1]] = 1;
    // shortest first (insertion sort: such creases are few)
    for (int i = 1; i < count; ++i) {
        int e = order[i], j = i;
        double l = ori_v2_norm(ori_v2_sub(at[p->edges[e].v[0]], at[p->edges[e].v[1]]));
        while (j > 0 && ori_v2_norm(ori_v2_sub(at[p->edges[order[j - 1]].v[0]], at[p->edges[order[j - 1]].v[1]])) > l) {
            order[j] = order[j - 1];
            j--;
        }
        order[j] = e;
    }
    for (int i = 0; i < count; ++i) {
        int a = uf_find(parent, p->edges[order[i]].v[0]), b = uf_find(parent, p->edges[order[i]].v[1]);
        if (a == b || ori_v2_norm(ori_v2_sub(at[a], at[b])) > gap) continue;
        // only the sliver's pass-through end goes: a vertex of two creases (which no fold turns
        // there), merged into a vertex of three or more lines
        int from = deg[a] == 2 && !on_border[a] && deg[b] >= 3 ? a : deg[b] == 2 && !on_border[b] && deg[a] >= 3 ? b : -1;
        if (from < 0) continue;
        int into = from == a ? b : a;
        parent[from] = into;
        deg[into] += deg[from] - 2;
        (*contracted)++;
    }
    ori_segment *segs = NULL;
    if (*contracted > 0) {
        segs = ori__alloc(sizeof(ori_segment) * (size_t)ne);
        for (int e = 0; e < ne; ++e) {
            const ori_edge *ed = &p->edges[e];
            int a = uf_find(parent, ed->v[0]), b = uf_find(parent, ed->v[1]);
            if (a == b) continue;
            ori_segment sg = {at[a], at[b], ed->assignment, ed->fold_angle_rad};
            segs[(*n)++] = sg;
        }
    }
    ori__free(order);
    ori__free(deg);
    ori__free(parent);
    ori__free(on_border);
    ori__free(at);
    return segs;
}

// Creases drawn past the border (a drawing's lines overshooting its outline) make faces outside
// the sheet, joined to it only across the border: the sheet "falls apart" when folded. Faces
// reached from outside the drawing across creases (not B or C edges) lie outside the sheet;
// when there are some and they cover less than the rest, the edges with no face of the sheet on
// either side are dropped. Returns the segments of the rest (NULL when nothing is clipped) with
// their count in *n, the creases dropped in *clipped and the faces outside in *faces.
static ori_segment *clip_outside(const ori_pattern *p, int *n, int *clipped, int *faces)
{
    *n = *clipped = *faces = 0;
    int nf = p->face_count, ne = p->edge_count;
    if (nf == 0) return NULL;
    char *out = ori__calloc((size_t)nf, 1);
    int *queue = ori__alloc(sizeof(int) * (size_t)nf);
    int head = 0, tail = 0;
    for (int e = 0; e < ne; ++e) {
        int l = p->edge_faces[2 * e], r = p->edge_faces[2 * e + 1];
        if (is_cut_or_boundary(p->edges[e].assignment) || (l == ORI_NULL_INDEX) == (r == ORI_NULL_INDEX)) continue;
        int f = l == ORI_NULL_INDEX ? r : l;
        if (!out[f]) out[f] = 1, queue[tail++] = f;
    }
    while (head < tail) {
        int f = queue[head++];
        for (int k = p->face_offsets[f]; k < p->face_offsets[f + 1]; ++k) {
            int e = p->face_edges[k];
            if (is_cut_or_boundary(p->edges[e].assignment)) continue;
            for (int s = 0; s < 2; ++s) {
                int g = p->edge_faces[2 * e + s];
                if (g != ORI_NULL_INDEX && !out[g]) out[g] = 1, queue[tail++] = g;
            }
        }
    }
    double area_out = 0.0, area_in = 0.0;
    for (int f = 0; f < nf; ++f) {
        double a = fabs(ori__pattern_face_area2(p, f));
        if (out[f]) area_out += a;
        else area_in += a;
    }
    ori__free(queue);
    // (No border drawn, or one that is open: everything is reached, nothing is clipped.)
    if (tail == 0 || !(area_out < area_in)) {
        ori__free(out);
        return NULL;
    }
    ori_segment *segs = ori__alloc(sizeof(ori_segment) * (size_t)ne);
    for (int e = 0; e < ne; ++e) {
        const ori_edge *ed = &p->edges[e];
        int l = p->edge_faces[2 * e], r = p->edge_faces[2 * e + 1];
        bool sheet = (l != ORI_NULL_INDEX && !out[l]) || (r != ORI_NULL_INDEX && !out[r]);
        if (!sheet) {
            *clipped += !is_cut_or_boundary(ed->assignment);
            continue;
        }
        ori_segment s = {ori__pattern_v2(p, ed->v[0]), ori__pattern_v2(p, ed->v[1]), ed->assignment, ed->fold_angle_rad};
        segs[(*n)++] = s;
    }
    *faces = tail;
    ori__free(out);
    return segs;
}

// Dangling ends and separate pieces of the result, with examples and how far the dangling ends
// are from another line (up to ORI_IMPORT_GAP_MAX_REL of the diagonal).
static void diagnose(const ori_pattern *p, double diag, ori_import_stats *stats)
{
    int nv = p->vertex_count;
    int *deg = ori__alloc(sizeof(int) * (size_t)(nv ? nv : 1));
    vertex_degrees(p, deg);
    stats->dangling = 0;
    stats->dangling_example = ORI_NULL_INDEX;
    stats->dangling_gap_rel = 0.0;
    line_grid g = {0, 0, 0, 0, 0, NULL, NULL};
    double reach = ORI_IMPORT_GAP_MAX_REL * diag;
    bool grid = false;
    for (int v = 0; v < nv; ++v) {
        if (deg[v] != 1) continue;
        if (stats->dangling++ == 0) stats->dangling_example = v;
        if (!grid) line_grid_build(p, reach, &g), grid = true;
        ori_v2 at;
        int hit;
        double d = nearest_line(p, &g, v, ori__pattern_v2(p, v), reach, &at, &hit);
        if (d <= reach) stats->dangling_gap_rel = fmax(stats->dangling_gap_rel, d / diag);
    }
    if (grid) line_grid_free(&g);
    // Sheets: faces joined across creases. Two sheets in one connected part of the drawing (joined
    // by boundary or cut lines, at corners or by lines with no paper on either side) are a
    // drawing split there: lines drawn to meet that miss each other, a border drawn through the
    // sheet. Folding says it falls apart.
    int nf = p->face_count;
    stats->sheets = 0;
    stats->split_vertex = ORI_NULL_INDEX;
    if (nf > 0) {
        int *sheet = ori__alloc(sizeof(int) * (size_t)nf);
        for (int f = 0; f < nf; ++f) sheet[f] = f;
        for (int e = 0; e < p->edge_count; ++e) {
            int l = p->edge_faces[2 * e], r = p->edge_faces[2 * e + 1];
            if (l == ORI_NULL_INDEX || r == ORI_NULL_INDEX || is_cut_or_boundary(p->edges[e].assignment)) continue;
            int a = ori__uf_root(sheet, l), b = ori__uf_root(sheet, r);
            if (a != b) sheet[a < b ? b : a] = a < b ? a : b;
        }
        for (int f = 0; f < nf; ++f) stats->sheets += ori__uf_root(sheet, f) == f;
        // (split: two sheets in one connected part of the drawing)
        int *comp = ori__alloc(sizeof(int) * (size_t)(nv ? nv : 1)), *held = ori__alloc(sizeof(int) * (size_t)(nv ? nv : 1));
        ori__pattern_parts(p, comp);
        for (int v = 0; v < nv; ++v) held[v] = ORI_NULL_INDEX;
        for (int f = 0; f < nf && stats->split_vertex == ORI_NULL_INDEX; ++f) {
            int r = ori__uf_root(sheet, f), v = p->face_vertices[p->face_offsets[f]], c = comp[v];
            if (held[c] == ORI_NULL_INDEX) held[c] = r;
            else if (held[c] != r) stats->split_vertex = v;
        }
        ori__free(comp);
        ori__free(held);
        ori__free(sheet);
    }
    int *comp = deg; // (reused)
    stats->parts = ori__pattern_parts(p, comp);
    stats->part_example = ORI_NULL_INDEX;
    for (int v = 0; v < nv && stats->parts > 1; ++v)
        if (comp[v] != comp[0]) {
            stats->part_example = v;
            break;
        }
    ori__free(deg);
}

// The fields of stats that planarisation sets (not the reader's), from src.
static void copy_planarised(ori_import_stats *dst, const ori_import_stats *src)
{
    dst->gap_rel = src->gap_rel;
    dst->gaps_closed = src->gaps_closed;
    dst->largest_gap_rel = src->largest_gap_rel;
    dst->dangling = src->dangling;
    dst->dangling_example = src->dangling_example;
    dst->dangling_gap_rel = src->dangling_gap_rel;
    dst->parts = src->parts;
    dst->part_example = src->part_example;
    dst->clipped = src->clipped;
    dst->clipped_faces = src->clipped_faces;
    dst->short_creases_merged = src->short_creases_merged;
    dst->sheets = src->sheets;
    dst->split_vertex = src->split_vertex;
}

// Planarise, close the gaps, check for islands; stats (may be NULL) receives the diagnosis.
// stroke_width: the drawing's line width in its units (0: unknown).
static ori_status to_pattern(const ori_segment *segs, int count, const ori_import_def *def, double stroke_width,
                             bool suggest, ori_pattern **out, ori_import_stats *stats, ori_error *error)
{
    ORI_ASSERT(out && count >= 0 && (segs || count == 0));
    *out = NULL;
    ori_import_def defaults = ori_default_import_def();
    if (!def) def = &defaults;
    ORI_ASSERT(def->internal_value == ORI__DEF_COOKIE);
    ori_error_clear(error);
    if (!(def->weld_rel > 0.0 && def->weld_rel < 1.0))
        return ori__fail(error, ORI_ERR_ARGUMENT, "weld tolerance %g is outside (0, 1)", def->weld_rel);
    if (!(def->gap_rel == ORI_IMPORT_GAP_AUTO || (def->gap_rel >= 0.0 && def->gap_rel <= ORI_IMPORT_GAP_MAX_REL)))
        return ori__fail(error, ORI_ERR_ARGUMENT, "gap %g is outside [0, %g]", def->gap_rel, ORI_IMPORT_GAP_MAX_REL);
    if (count == 0) return ori__fail(error, ORI_ERR_NOT_FOUND, "no crease lines in the drawing");
    ori_v2 lo = segs[0].a, hi = segs[0].a;
    for (int i = 0; i < count; ++i) {
        ori_v2 pts[2] = {segs[i].a, segs[i].b};
        for (int k = 0; k < 2; ++k) {
            if (!ori__coord_ok(pts[k].x) || !ori__coord_ok(pts[k].y))
                return ori__fail_at(error, ORI_ERR_RANGE, "segments", i, "coordinate is not finite or exceeds %g", ORI_COORD_MAX);
            lo.x = fmin(lo.x, pts[k].x), lo.y = fmin(lo.y, pts[k].y);
            hi.x = fmax(hi.x, pts[k].x), hi.y = fmax(hi.y, pts[k].y);
        }
    }
    double diag = ori_v2_norm(ori_v2_sub(hi, lo));
    if (!(diag > 0.0) || !isfinite(diag)) return ori__fail(error, ORI_ERR_DEGENERATE, "the drawing has no extent");
    double weld = def->weld_rel * diag;
    double gap_rel = def->gap_rel != ORI_IMPORT_GAP_AUTO ? def->gap_rel : stroke_width > 0.0 ? stroke_width / diag : 0.0;
    if (!(gap_rel <= ORI_IMPORT_GAP_MAX_REL)) gap_rel = ORI_IMPORT_GAP_MAX_REL; // (a wider line is no gap)
    ori_pattern *p = NULL;
    ori_status st = pipeline(segs, count, def, weld, &p, error);
    int closed = 0;
    double largest = 0.0;
    // (A joined end may still leave a sliver where it meets its line: later rounds drop it.)
    for (int round = 0; round < 3 && st == ORI_OK && gap_rel * diag > weld; ++round) {
        int n, k;
        double big;
        ori_segment *fixed = close_gaps(p, gap_rel * diag, &n, &k, &big);
        if (!fixed) break;
        closed += round == 0 ? k : 0;
        largest = fmax(largest, big);
        ori_pattern_destroy(p);
        p = NULL;
        st = n > 0 ? pipeline(fixed, n, def, weld, &p, error) : ori__fail(error, ORI_ERR_NOT_FOUND, "no crease lines in the drawing");
        ori__free(fixed);
    }
    // Creases shorter than the drawn line width: their ends are one vertex on the page.
    int contracted = 0;
    if (st == ORI_OK && gap_rel * diag > weld) {
        int n;
        ori_segment *merged = contract_short(p, gap_rel * diag, &n, &contracted);
        if (merged) {
            ori_pattern *q = NULL;
            ori_status sq = n > 0 ? pipeline(merged, n, def, weld, &q, NULL) : ORI_ERR_NOT_FOUND;
            ori__free(merged);
            if (sq == ORI_OK) { // (else the pattern as it was: contracting would break it)
                ori_pattern_destroy(p);
                p = q;
            } else {
                contracted = 0;
            }
        }
    }
    // Creases drawn past the border: clipped at it (the faces outside the sheet are dropped).
    int clipped = 0, clipped_faces = 0;
    if (st == ORI_OK) {
        int n;
        ori_segment *kept = clip_outside(p, &n, &clipped, &clipped_faces);
        if (kept) {
            ori_pattern_destroy(p);
            p = NULL;
            st = pipeline(kept, n, def, weld, &p, error);
            ori__free(kept);
        }
    }
    // Every line shorter than the weld (a drawing whose extent comes from a far-away stray line):
    // nothing is left, which is no crease pattern.
    if (st == ORI_OK && p->edge_count == 0)
        st = ori__fail(error, ORI_ERR_DEGENERATE,
                       "every line is shorter than the weld tolerance (%g of the drawing's size, %g): nothing is left; "
                       "a smaller --tolerance keeps them",
                       def->weld_rel, weld);
    // After the holes are gone: a separate piece inside a (connected) hole is fine.
    if (st == ORI_OK) st = check_islands(p, error);
    if (st != ORI_OK) {
        ori_pattern_destroy(p);
        return st;
    }
    if (stats) {
        stats->gap_rel = gap_rel;
        stats->gaps_closed = closed;
        stats->largest_gap_rel = largest / diag;
        stats->clipped = clipped;
        stats->clipped_faces = clipped_faces;
        stats->short_creases_merged = contracted;
        diagnose(p, diag, stats);
        stats->split_tolerance_rel = 0.0;
        stats->healed_weld_rel = 0.0;
        stats->healed_sheets = 0;
        // Split by boundary lines: lines drawn to meet may miss by more than the weld; find the
        // smallest doubling of the weld, up to the drawn line width (or 32 times the weld when
        // the drawing has none), that makes the split sheets one.
        double reach = fmin(fmax(gap_rel, 32.0 * def->weld_rel), ORI_IMPORT_GAP_MAX_REL);
        for (double w = 2.0 * def->weld_rel; suggest && stats->split_vertex != ORI_NULL_INDEX && w <= reach; w *= 2.0) {
            ori_import_def wider = *def;
            wider.weld_rel = w;
            ori_import_stats s2;
            ori_pattern *q = NULL;
            ori_status st2 = to_pattern(segs, count, &wider, stroke_width, false, &q, &s2, NULL);
            if (st2 == ORI_OK && s2.split_vertex == ORI_NULL_INDEX) {
                stats->split_tolerance_rel = w;
                // Within the drawn line width the lines touch on the page: joined, as gaps are.
                if (def->heal_splits && w <= gap_rel) {
                    int sheets = stats->sheets;
                    copy_planarised(stats, &s2);
                    stats->healed_weld_rel = w;
                    stats->healed_sheets = sheets;
                    ori_pattern_destroy(p);
                    p = q;
                    q = NULL;
                }
                ori_pattern_destroy(q);
                break;
            }
            ori_pattern_destroy(q);
        }
    }
    *out = p;
    return ORI_OK;
}

ori_status ori_segments_to_pattern(const ori_segment *segs, int count, const ori_import_def *def, ori_pattern **out,
                                   ori_error *error)
{
    return to_pattern(segs, count, def, 0.0, false, out, NULL, error);
}

// Planarise the segments a reader found (found: its stats) as ori_import_file does.
static ori_status import_segments(ori_status st, ori_segment *segs, int n, ori_import_stats *found,
                                  const ori_import_def *def, ori_pattern **out, ori_import_stats *stats,
                                  ori_error *error)
{
    if (stats) *stats = *found;
    if (st != ORI_OK) return st;
    st = to_pattern(segs, n, def, found->stroke_width, true, out, found, error);
    ori__free(segs);
    if (stats) *stats = *found;
    return st;
}

ori_status ori_import_file(const char *path, ori_format format, const ori_import_def *def, ori_pattern **out,
                           ori_import_stats *stats, ori_error *error)
{
    ORI_ASSERT(path && out);
    *out = NULL;
    ori_segment *segs;
    int n;
    ori_import_stats found;
    ori_status st = read_segments(path, format, def ? def->curve_segments : 0, &segs, &n, &found, error);
    return import_segments(st, segs, n, &found, def, out, stats, error);
}

ori_status ori_import_text(const char *text, size_t size, ori_format format, const ori_import_def *def,
                           ori_pattern **out, ori_import_stats *stats, ori_error *error)
{
    ORI_ASSERT((text || size == 0) && out);
    *out = NULL;
    ori_segment *segs = NULL;
    int n = 0;
    ori_import_stats found;
    stats_reset(&found);
    ori_status st = text_segments(text, size, format, def ? def->curve_segments : 0, &segs, &n, &found, error);
    return import_segments(st, segs, n, &found, def, out, stats, error);
}
