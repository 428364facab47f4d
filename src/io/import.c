// Importing drawings: format by extension, reading a file's segments, and planarising them into
// a crease pattern (arrangement with the weld tolerance, then clean-up of drawing artefacts:
// collinear pass-through vertices and hole faces).
#include <ctype.h>
#include <stdlib.h>

#include "../pattern/pattern_internal.h"
#include "reader_internal.h"

// --- formats ---------------------------------------------------------------------------------

ori_format ori_format_from_path(const char *path)
{
    ORI_ASSERT(path);
    const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
    if (!dot || (slash && dot < slash)) return ORI_FORMAT_UNKNOWN;
    char ext[8];
    size_t n = strlen(dot + 1);
    if (n == 0 || n >= sizeof ext) return ORI_FORMAT_UNKNOWN;
    for (size_t i = 0; i <= n; ++i) ext[i] = (char)tolower((unsigned char)dot[1 + i]);
    if (strcmp(ext, "fold") == 0) return ORI_FORMAT_FOLD;
    if (strcmp(ext, "svg") == 0) return ORI_FORMAT_SVG;
    if (strcmp(ext, "opx") == 0) return ORI_FORMAT_OPX;
    if (strcmp(ext, "cp") == 0) return ORI_FORMAT_CP;
    return ORI_FORMAT_UNKNOWN;
}

const char *ori_format_name(ori_format format)
{
    switch (format) {
    case ORI_FORMAT_FOLD: return "fold";
    case ORI_FORMAT_SVG: return "svg";
    case ORI_FORMAT_OPX: return "opx";
    case ORI_FORMAT_CP: return "cp";
    default: return "unknown";
    }
}

ori_import_def ori_default_import_def(void)
{
    ori_import_def def;
    def.weld_rel = ORI_TOL_IMPORT_WELD_REL;
    def.merge_collinear = true;
    def.remove_holes = true;
    def.internal_value = ORI__DEF_COOKIE;
    return def;
}

ori_status ori_read_segments(const char *path, ori_format format, ori_segment **segments, int *count,
                             ori_import_stats *stats, ori_error *error)
{
    ORI_ASSERT(path && segments && count);
    *segments = NULL;
    *count = 0;
    if (stats) memset(stats, 0, sizeof *stats);
    if (format == ORI_FORMAT_UNKNOWN) format = ori_format_from_path(path);
    if (format != ORI_FORMAT_SVG && format != ORI_FORMAT_OPX && format != ORI_FORMAT_CP)
        return ori__fail(error, ORI_ERR_UNSUPPORTED, "cannot read segments from a '%s' file", ori_format_name(format));
    char *text;
    size_t size;
    ori_status st = ori_file_read_all(path, ORI_IMPORT_MAX_BYTES, &text, &size, error);
    if (st != ORI_OK) return st;
    if (size == 0) st = ori__fail(error, ORI_ERR_PARSE, "the file is empty");
    else if (format == ORI_FORMAT_SVG) st = ori_svg_read_segments(text, size, segments, count, stats, error);
    else if (format == ORI_FORMAT_OPX) st = ori_opx_read_segments(text, size, segments, count, stats, error);
    else st = ori_cp_read_segments(text, size, segments, count, stats, error);
    ori__free(text);
    return st;
}

// --- planarisation and clean-up --------------------------------------------------------------

// Remove every vertex that only joins two collinear edges (within tol) of equal assignment and
// fold angle; the chains become single edges. Returns a new unbuilt pattern, or NULL when there
// is nothing to merge.
static ori_pattern *merge_collinear(const ori_pattern *p, double tol)
{
    int nv = p->vertex_count, ne = p->edge_count;
    char *removed = ori__calloc((size_t)(nv ? nv : 1), 1);
    int *parent = ori__alloc(sizeof(int) * (size_t)(ne ? ne : 1));
    for (int e = 0; e < ne; ++e) parent[e] = e;
    int merged = 0;
    for (int v = 0; v < nv; ++v) {
        if (ori_pattern_vertex_degree(p, v) != 2) continue;
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
    if (merged == 0) {
        ori__free(removed);
        ori__free(parent);
        return NULL;
    }
    int *map = ori__alloc(sizeof(int) * (size_t)(nv ? nv : 1));
    ori_pattern_def pdef = ori_default_pattern_def();
    ori_pattern *q = ori_pattern_create(&pdef);
    for (int v = 0; v < nv; ++v) map[v] = removed[v] ? ORI_NULL_INDEX : ori_pattern_add_vertex(q, p->vertices[v]);
    // A group is a chain u – v1 – … – w of merged edges: u and w, the kept vertices, each occur
    // once among the group's edge ends (a single unmerged edge is the chain u – w).
    int *end0 = ori__alloc(sizeof(int) * (size_t)(ne ? ne : 1));
    int *end1 = ori__alloc(sizeof(int) * (size_t)(ne ? ne : 1));
    for (int e = 0; e < ne; ++e) end0[e] = end1[e] = ORI_NULL_INDEX;
    for (int e = 0; e < ne; ++e) {
        int r = ori__uf_root(parent, e);
        for (int k = 0; k < 2; ++k) {
            int v = p->edges[e].v[k];
            if (removed[v]) continue;
            if (end0[r] == ORI_NULL_INDEX) end0[r] = map[v];
            else end1[r] = map[v];
        }
    }
    // One edge per group, at the position of its lowest edge index (the root).
    for (int e = 0; e < ne; ++e) {
        if (ori__uf_root(parent, e) != e) continue;
        ORI_ASSERT(end0[e] != ORI_NULL_INDEX && end1[e] != ORI_NULL_INDEX);
        ori_pattern_add_edge(q, end0[e], end1[e], p->edges[e].assignment, p->edges[e].fold_angle_rad);
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

// Exact winding number of face f around point q (nonzero: q strictly inside or on its edges).
static int winding(const ori_pattern *p, int f, ori_v2 q)
{
    int wn = 0, b = p->face_offsets[f], n = p->face_offsets[f + 1] - b;
    for (int k = 0; k < n; ++k) {
        ori_v2 a = ori__pattern_v2(p, p->face_vertices[b + k]), c = ori__pattern_v2(p, p->face_vertices[b + (k + 1) % n]);
        if (a.y <= q.y) {
            if (c.y > q.y && ori_orient2d_sign(a, c, q) > 0) wn++;
        } else if (c.y <= q.y && ori_orient2d_sign(a, c, q) < 0) {
            wn--;
        }
    }
    return wn;
}

// A connected part of the drawing that lies inside a face of another part (a hole or a crease
// touching nothing) cannot be expressed: FOLD faces are single cycles. Reject it, naming where.
static ori_status check_islands(const ori_pattern *p, ori_error *error)
{
    int nv = p->vertex_count;
    int *comp = ori__alloc(sizeof(int) * (size_t)(nv ? nv : 1));
    int parts = ori__pattern_parts(p, comp);
    // leftmost (then lowest) vertex of each component
    int *left = ori__alloc(sizeof(int) * (size_t)(nv ? nv : 1));
    for (int v = 0; v < nv; ++v) left[v] = ORI_NULL_INDEX;
    for (int v = 0; v < nv; ++v) {
        int r = comp[v];
        ori_v3 a = p->vertices[v];
        if (left[r] == ORI_NULL_INDEX || a.x < p->vertices[left[r]].x ||
            (a.x == p->vertices[left[r]].x && a.y < p->vertices[left[r]].y))
            left[r] = v;
    }
    ori_status st = ORI_OK;
    for (int r = 0; r < nv && parts > 1 && st == ORI_OK; ++r) {
        if (comp[r] != r || left[r] == ORI_NULL_INDEX) continue;
        ori_v2 q = ori__pattern_v2(p, left[r]);
        for (int f = 0; f < p->face_count; ++f) {
            if (comp[p->face_vertices[p->face_offsets[f]]] == r || winding(p, f, q) == 0) continue;
            st = ori__fail_at(error, ORI_ERR_TOPOLOGY, "vertices_coords", left[r],
                              "the lines around (%g, %g) touch nothing else and lie inside a face: FOLD faces "
                              "cannot have holes; connect them to the rest with a crease",
                              q.x, q.y);
            break;
        }
    }
    ori__free(comp);
    ori__free(left);
    return st;
}

ori_status ori_segments_to_pattern(const ori_segment *segs, int count, const ori_import_def *def, ori_pattern **out,
                                   ori_error *error)
{
    ORI_ASSERT(out && count >= 0 && (segs || count == 0));
    *out = NULL;
    ori_import_def defaults = ori_default_import_def();
    if (!def) def = &defaults;
    ORI_ASSERT(def->internal_value == ORI__DEF_COOKIE);
    ori_error_clear(error);
    if (!(def->weld_rel > 0.0 && def->weld_rel < 1.0))
        return ori__fail(error, ORI_ERR_ARGUMENT, "weld tolerance %g is outside (0, 1)", def->weld_rel);
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
        ori_pattern *q = merge_collinear(p, weld);
        if (q) {
            ori_pattern_destroy(p);
            p = q;
            st = ori_pattern_build(p, &bdef, error);
        }
    }
    if (st == ORI_OK && def->remove_holes && remove_holes(p) > 0) st = ori_pattern_build(p, &bdef, error);
    // After the holes are gone: a separate piece inside a (connected) hole is fine.
    if (st == ORI_OK) st = check_islands(p, error);
    if (st != ORI_OK) {
        ori_pattern_destroy(p);
        return st;
    }
    *out = p;
    return ORI_OK;
}

ori_status ori_import_file(const char *path, ori_format format, const ori_import_def *def, ori_pattern **out,
                           ori_import_stats *stats, ori_error *error)
{
    ORI_ASSERT(path && out);
    *out = NULL;
    ori_segment *segs;
    int n;
    ori_status st = ori_read_segments(path, format, &segs, &n, stats, error);
    if (st != ORI_OK) return st;
    st = ori_segments_to_pattern(segs, n, def, out, error);
    ori__free(segs);
    return st;
}
