// Edge unfolding of polyhedral surfaces: faces (coplanar neighbours merged) → a spanning tree
// of the face graph (steepest-edge cut trees, random minimum spanning trees, breadth-first
// trees; several tries) → the net laid out in the plane → overlap test of every pair of faces
// (broad phase on boxes, separating axes on the convex pieces of the faces) → a crease pattern
// whose fold angles rebuild the shape, checked by folding it back with orikin's kinematics.
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <orikin/collision.h>
#include <orikin/fold.h>
#include <orikin/kinematics.h>
#include <orikin/render.h>
#include <orikin/tolerance.h>
#include <orikin/unfold.h>

#include "../core/core_internal.h"
#include "../core/hash.h"
#include "unfold_internal.h"



ori_unfold_def ori_default_unfold_def(void)
{
    ori_unfold_def d;
    memset(&d, 0, sizeof d);
    d.tries = 50;
    d.seed = 1;
    d.max_trees = 10000000;
    d.internal_value = ORI__DEF_COOKIE;
    return d;
}

void ori_unfold_mesh_destroy(ori_mesh *m)
{
    if (!m) return;
    ori__free(m->v), ori__free(m->fstart), ori__free(m->fv), ori__free(m->src_start), ori__free(m->src);
    ori__free(m->hint);
    ori__free(m);
}

int ori_unfold_mesh_face_count(const ori_mesh *m) { return m->nf; }
int ori_unfold_mesh_vertex_count(const ori_mesh *m) { return m->nv; }

static ori_v3 face_normal(const ori_v3 *v, const int *f, int k)
{
    ori_v3 n = {0, 0, 0};
    for (int i = 0; i < k; ++i) n = ori_v3_add(n, ori_v3_cross(v[f[i]], v[f[(i + 1) % k]]));
    return n; // twice the vector area
}

// --- edges of a face list --------------------------------------------------------------------

typedef struct half {
    int a, b, face, idx; // directed a→b in face at corner idx
} half;

static int cmp_half(const void *x, const void *y)
{
    const half *p = x, *q = y;
    int pa = p->a < p->b ? p->a : p->b, pb = p->a < p->b ? p->b : p->a;
    int qa = q->a < q->b ? q->a : q->b, qb = q->a < q->b ? q->b : q->a;
    if (pa != qa) return pa - qa;
    if (pb != qb) return pb - qb;
    return p->face - q->face;
}

// Pair every half-edge with its twin; twin[h] = −1 on the boundary. Fails on non-manifold or
// inconsistently oriented edges.
static ori_status pair_halves(half *h, int nh, int *twin, const char *what, ori_error *error)
{
    qsort(h, (size_t)nh, sizeof *h, cmp_half);
    for (int i = 0; i < nh; ++i) twin[i] = -1;
    for (int i = 0; i < nh;) {
        int j = i + 1;
        while (j < nh && cmp_half(&(half){h[i].a, h[i].b, 0, 0}, &(half){h[j].a, h[j].b, 0, 0}) == 0) ++j;
        if (j - i > 2)
            return ori__fail_at(error, ORI_ERR_TOPOLOGY, what, h[i].face,
                                "non-manifold: edge %d–%d is shared by %d faces", h[i].a, h[i].b, j - i);
        if (j - i == 2) {
            if (h[i].a == h[i + 1].a)
                return ori__fail_at(error, ORI_ERR_TOPOLOGY, what, h[i + 1].face,
                                    "faces %d and %d are not consistently oriented (edge %d–%d)", h[i].face,
                                    h[i + 1].face, h[i].a, h[i].b);
            twin[i] = i + 1, twin[i + 1] = i;
        }
        i = j;
    }
    return ORI_OK;
}

// --- loading ---------------------------------------------------------------------------------

// Validate the input faces and merge coplanar neighbours into polygons.
static ori_status build_mesh(ori_v3 *v, int nv, int *fstart, int *fv, int nf, ori_mesh **out, ori_error *error)
{
    ori_mesh *m = ori__calloc(1, sizeof *m);
    m->nv = nv, m->v = v;
    ori_v3 lo = {INFINITY, INFINITY, INFINITY}, hi = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < nv; ++i) {
        lo = ori_v3_make(fmin(lo.x, v[i].x), fmin(lo.y, v[i].y), fmin(lo.z, v[i].z));
        hi = ori_v3_make(fmax(hi.x, v[i].x), fmax(hi.y, v[i].y), fmax(hi.z, v[i].z));
    }
    m->diag = nv ? ori_v3_norm(ori_v3_sub(hi, lo)) : 1.0;
    ori_status st = ORI_OK;
    if (nf == 0) st = ori__fail(error, ORI_ERR_TOPOLOGY, "no faces");
    ori_v3 *nrm = ori__alloc(((size_t)nf + 1) * sizeof *nrm);
    for (int f = 0; f < nf && st == ORI_OK; ++f) {
        int k = fstart[f + 1] - fstart[f];
        const int *fc = fv + fstart[f];
        for (int i = 0; i < k && st == ORI_OK; ++i) {
            if (fc[i] < 0 || fc[i] >= nv) st = ori__fail_at(error, ORI_ERR_RANGE, "faces_vertices", f, "vertex index out of range");
            for (int j = i + 1; j < k && st == ORI_OK; ++j)
                if (fc[i] == fc[j]) st = ori__fail_at(error, ORI_ERR_DEGENERATE, "faces_vertices", f, "repeats vertex %d", fc[i]);
        }
        if (st != ORI_OK) break;
        if (k < 3) {
            st = ori__fail_at(error, ORI_ERR_DEGENERATE, "faces_vertices", f, "has fewer than 3 vertices");
            break;
        }
        ori_v3 n = face_normal(v, fc, k);
        double area = 0.5 * ori_v3_norm(n);
        if (!(area > 1e-12 * m->diag * m->diag)) {
            st = ori__fail_at(error, ORI_ERR_DEGENERATE, "faces_vertices", f, "degenerate face (zero area)");
            break;
        }
        n = ori_v3_normalize(n);
        nrm[f] = n;
        for (int i = 0; i < k; ++i)
            if (fabs(ori_v3_dot(ori_v3_sub(v[fc[i]], v[fc[0]]), n)) > ORI_TOL_UNFOLD_PLANAR_REL * m->diag) {
                st = ori__fail_at(error, ORI_ERR_DEGENERATE, "faces_vertices", f,
                                  "not planar: vertex %d is %.3g off the face's plane", fc[i],
                                  fabs(ori_v3_dot(ori_v3_sub(v[fc[i]], v[fc[0]]), n)));
                break;
            }
    }
    int nh = fstart[nf];
    half *h = ori__alloc(((size_t)nh + 1) * sizeof *h);
    int *twin = ori__alloc(((size_t)nh + 1) * sizeof *twin);
    if (st == ORI_OK) {
        for (int f = 0, q = 0; f < nf; ++f)
            for (int i = fstart[f]; i < fstart[f + 1]; ++i)
                h[q++] = (half){fv[i], fv[i + 1 < fstart[f + 1] ? i + 1 : fstart[f]], f, i - fstart[f]};
        st = pair_halves(h, nh, twin, "faces_vertices", error);
    }
    if (st != ORI_OK) {
        ori__free(nrm), ori__free(h), ori__free(twin);
        m->v = NULL;
        ori_unfold_mesh_destroy(m);
        return st;
    }
    // merge: union of faces across edges with equal normals
    int *uf = ori__alloc((size_t)nf * sizeof *uf);
    for (int f = 0; f < nf; ++f) uf[f] = f;
    for (int i = 0; i < nh; ++i) {
        int j = twin[i];
        if (j < i) continue;
        int f = h[i].face, g = h[j].face;
        double ang = atan2(ori_v3_norm(ori_v3_cross(nrm[f], nrm[g])), ori_v3_dot(nrm[f], nrm[g]));
        if (ang < ORI_TOL_UNFOLD_MERGE_RAD) {
            int a = ori__uf_root(uf, f), b = ori__uf_root(uf, g);
            if (a != b) uf[a] = b;
        }
    }
    // For each group: boundary half-edges (twin outside the group); one loop → a merged face.
    int *group = ori__alloc((size_t)nf * sizeof *group), ng = 0;
    int *gid = ori__alloc((size_t)nf * sizeof *gid);
    for (int f = 0; f < nf; ++f) gid[f] = -1;
    for (int f = 0; f < nf; ++f) {
        int r = ori__uf_root(uf, f);
        if (gid[r] < 0) gid[r] = ng++;
        group[f] = gid[r];
    }
    // next boundary half-edge: map from start vertex within group
    int cap_fv = nh + 1, cap_f = nf + 1, nmf = 0, nfv = 0;
    m->fstart = ori__alloc(((size_t)cap_f + 1) * sizeof(int));
    m->fv = ori__alloc((size_t)cap_fv * sizeof(int));
    m->src_start = ori__alloc(((size_t)cap_f + 1) * sizeof(int));
    m->src = ori__alloc((size_t)nf * sizeof(int));
    int nsrc = 0;
    // boundary halves per group, sorted by group then start vertex
    int *bh = ori__alloc(((size_t)nh + 1) * sizeof *bh), nb = 0;
    for (int i = 0; i < nh; ++i) {
        int j = twin[i];
        if (j < 0 || group[h[j].face] != group[h[i].face]) bh[nb++] = i;
    }
    int *bcount = ori__calloc((size_t)ng + 1, sizeof *bcount);
    for (int i = 0; i < nb; ++i) bcount[group[h[bh[i]].face] + 1]++;
    for (int g = 0; g < ng; ++g) bcount[g + 1] += bcount[g];
    int *bsorted = ori__alloc(((size_t)nb + 1) * sizeof *bsorted), *fill = ori__alloc(((size_t)ng + 1) * sizeof *fill);
    memcpy(fill, bcount, (size_t)ng * sizeof *fill);
    for (int i = 0; i < nb; ++i) bsorted[fill[group[h[bh[i]].face]]++] = bh[i];
    bool *used = ori__calloc((size_t)nh + 1, 1);
    for (int g = 0; g < ng; ++g) {
        int s = bcount[g], e = bcount[g + 1];
        // one loop with every vertex once?
        bool single = e - s >= 3;
        int start = single ? bsorted[s] : -1, cur = start, len = 0;
        while (single) {
            used[cur] = true;
            len++;
            int nxt = -1, hits = 0;
            for (int t = s; t < e; ++t)
                if (h[bsorted[t]].a == h[cur].b) nxt = bsorted[t], hits++;
            if (hits != 1) single = false;
            else if (nxt == start) break;
            else if (used[nxt]) single = false;
            else cur = nxt;
        }
        if (single && len != e - s) single = false;
        if (single) {
            m->fstart[nmf] = nfv;
            m->src_start[nmf] = nsrc;
            cur = start;
            do {
                m->fv[nfv++] = h[cur].a;
                int nxt = -1;
                for (int t = s; t < e; ++t)
                    if (h[bsorted[t]].a == h[cur].b) nxt = bsorted[t];
                cur = nxt;
            } while (cur != start);
            for (int f = 0; f < nf; ++f)
                if (group[f] == g) m->src[nsrc++] = f;
            nmf++;
        } else {
            // keep the group's faces as they are
            for (int f = 0; f < nf; ++f) {
                if (group[f] != g) continue;
                m->fstart[nmf] = nfv;
                m->src_start[nmf] = nsrc;
                for (int i = fstart[f]; i < fstart[f + 1]; ++i) m->fv[nfv++] = fv[i];
                m->src[nsrc++] = f;
                nmf++;
            }
        }
    }
    m->fstart[nmf] = nfv, m->src_start[nmf] = nsrc, m->nf = nmf;
    ori__free(used), ori__free(bsorted), ori__free(fill), ori__free(bcount), ori__free(bh), ori__free(group), ori__free(gid);
    ori__free(uf), ori__free(nrm), ori__free(h), ori__free(twin);
    *out = m;
    return ORI_OK;
}

ori_status ori_unfold_mesh_create(const ori_v3 *coords, int vertex_count, const int *face_start, const int *face_vertices,
                                  int face_count, ori_mesh **out, ori_error *error)
{
    ORI_ASSERT(out && (vertex_count == 0 || coords) && face_start);
    *out = NULL;
    for (int i = 0; i < vertex_count; ++i)
        if (!ori__coord_ok(coords[i].x) || !ori__coord_ok(coords[i].y) || !ori__coord_ok(coords[i].z))
            return ori__fail_at(error, ORI_ERR_RANGE, "vertices_coords", i, "coordinate not finite");
    ori_v3 *v = ori__alloc(((size_t)vertex_count + 1) * sizeof *v);
    if (vertex_count) memcpy(v, coords, (size_t)vertex_count * sizeof *v); // (no memcpy from NULL)
    int *fs = ori__alloc(((size_t)face_count + 1) * sizeof *fs);
    memcpy(fs, face_start, ((size_t)face_count + 1) * sizeof *fs);
    int *fv = ori__alloc(((size_t)fs[face_count] + 1) * sizeof *fv);
    if (fs[face_count]) memcpy(fv, face_vertices, (size_t)fs[face_count] * sizeof *fv);
    ori_status st = build_mesh(v, vertex_count, fs, fv, face_count, out, error);
    if (st != ORI_OK) ori__free(v);
    ori__free(fs), ori__free(fv);
    return st;
}

// OBJ: "v x y z" and "f a b c ..." (1-based, negative relative, "a/t/n" forms).
static ori_status read_obj(const char *text, ori_v3 **pv, int *pnv, int **pfs, int **pfv, int *pnf, ori_error *error)
{
    int nv = 0, cv = 0, nf = 0, cf = 0, nfv = 0, cfv = 0;
    ori_v3 *v = NULL;
    int *fs = NULL, *fv = NULL;
    int line = 1;
    int nfs = 0;
    ORI__PUSH(fs, nfs, cf, 0);
    for (const char *p = text; *p; ++line) {
        const char *eol = strchr(p, '\n');
        size_t len = eol ? (size_t)(eol - p) : strlen(p);
        char buf[4096];
        if (len >= sizeof buf) {
            ori__free(v), ori__free(fs), ori__free(fv);
            return ori__fail_pos(error, ORI_ERR_LIMIT, line, 1, "line too long");
        }
        memcpy(buf, p, len);
        buf[len] = '\0';
        p = eol ? eol + 1 : p + len;
        char *s = buf;
        while (*s == ' ' || *s == '\t') ++s;
        if (s[0] == 'v' && (s[1] == ' ' || s[1] == '\t')) {
            ori_v3 x;
            if (sscanf(s + 2, "%lf %lf %lf", &x.x, &x.y, &x.z) != 3) {
                ori__free(v), ori__free(fs), ori__free(fv);
                return ori__fail_pos(error, ORI_ERR_PARSE, line, 1, "vertex needs three numbers");
            }
            ORI__PUSH(v, nv, cv, x);
        } else if (s[0] == 'f' && (s[1] == ' ' || s[1] == '\t')) {
            char *q = s + 2;
            int count = 0;
            for (;;) {
                while (*q == ' ' || *q == '\t' || *q == '\r') ++q;
                if (!*q) break;
                char *end;
                long idx = strtol(q, &end, 10);
                if (end == q || idx == 0) {
                    ori__free(v), ori__free(fs), ori__free(fv);
                    return ori__fail_pos(error, ORI_ERR_PARSE, line, (int)(q - buf) + 1, "bad vertex index");
                }
                long vi = idx > 0 ? idx - 1 : nv + idx;
                if (vi < 0 || vi >= nv) {
                    ori__free(v), ori__free(fs), ori__free(fv);
                    return ori__fail_pos(error, ORI_ERR_RANGE, line, (int)(q - buf) + 1, "vertex %ld does not exist", idx);
                }
                ORI__PUSH(fv, nfv, cfv, (int)vi);
                count++;
                q = end;
                while (*q && *q != ' ' && *q != '\t') ++q;
            }
            ORI__PUSH(fs, nfs, cf, nfv);
            nf = nfs - 1;
            (void)count;
        }
    }
    // fs holds nf + 1 entries (pushes above keep fs[nf] = nfv)
    *pv = v, *pnv = nv, *pfs = fs, *pfv = fv, *pnf = nf;
    return ORI_OK;
}

// STL (binary, or ASCII "solid ... facet ... vertex x y z"): vertices welded by exact coordinates.
static int cmp_v3_idx_data(const ori_v3 *v, int a, int b)
{
    if (v[a].x != v[b].x) return v[a].x < v[b].x ? -1 : 1;
    if (v[a].y != v[b].y) return v[a].y < v[b].y ? -1 : 1;
    if (v[a].z != v[b].z) return v[a].z < v[b].z ? -1 : 1;
    return 0;
}
static _Thread_local const ori_v3 *g_weld_v; // qsort has no context argument
static int cmp_weld(const void *x, const void *y) { return cmp_v3_idx_data(g_weld_v, *(const int *)x, *(const int *)y); }

static ori_status read_stl(const char *data, size_t size, ori_v3 **pv, int *pnv, int **pfs, int **pfv, int *pnf, ori_error *error)
{
    ori_v3 *raw = NULL;
    int nr = 0, cr = 0;
    bool binary = size >= 84;
    uint32_t ntri = 0;
    if (binary) {
        memcpy(&ntri, data + 80, 4);
        binary = (size_t)84 + (size_t)ntri * 50 == size;
    }
    if (binary) {
        for (uint32_t t = 0; t < ntri; ++t)
            for (int k = 0; k < 3; ++k) {
                float x[3];
                memcpy(x, data + 84 + (size_t)t * 50 + 12 + (size_t)k * 12, 12);
                ori_v3 p = {x[0], x[1], x[2]};
                ORI__PUSH(raw, nr, cr, p);
            }
    } else {
        if (strncmp(data, "solid", 5) != 0) return ori__fail_pos(error, ORI_ERR_PARSE, 1, 1, "not an STL file");
        int line = 1;
        for (const char *p = data; *p; ++p) {
            if (*p == '\n') line++;
            if (strncmp(p, "vertex", 6) == 0 && (p == data || p[-1] == ' ' || p[-1] == '\t' || p[-1] == '\n')) {
                ori_v3 x;
                if (sscanf(p + 6, "%lf %lf %lf", &x.x, &x.y, &x.z) != 3) {
                    ori__free(raw);
                    return ori__fail_pos(error, ORI_ERR_PARSE, line, 1, "vertex needs three numbers");
                }
                ORI__PUSH(raw, nr, cr, x);
            }
        }
        if (nr % 3) {
            ori__free(raw);
            return ori__fail(error, ORI_ERR_PARSE, "facets must have three vertices");
        }
    }
    int *idx = ori__alloc(((size_t)nr + 1) * sizeof *idx), *map = ori__alloc(((size_t)nr + 1) * sizeof *map);
    for (int i = 0; i < nr; ++i) idx[i] = i;
    g_weld_v = raw;
    qsort(idx, (size_t)nr, sizeof *idx, cmp_weld);
    ori_v3 *v = ori__alloc(((size_t)nr + 1) * sizeof *v);
    int nv = 0;
    for (int i = 0; i < nr; ++i) {
        if (i == 0 || cmp_v3_idx_data(raw, idx[i], idx[i - 1]) != 0) v[nv++] = raw[idx[i]];
        map[idx[i]] = nv - 1;
    }
    int nf = nr / 3;
    int *fs = ori__alloc(((size_t)nf + 1) * sizeof *fs), *fv = ori__alloc(((size_t)nr + 1) * sizeof *fv);
    for (int f = 0; f <= nf; ++f) fs[f] = 3 * f;
    for (int i = 0; i < nr; ++i) fv[i] = map[i];
    ori__free(raw), ori__free(idx), ori__free(map);
    *pv = v, *pnv = nv, *pfs = fs, *pfv = fv, *pnf = nf;
    return ORI_OK;
}

static int cmp_hint(const void *x, const void *y)
{
    const int *a = x, *b = y;
    return a[0] != b[0] ? (a[0] > b[0]) - (a[0] < b[0]) : (a[1] > b[1]) - (a[1] < b[1]);
}

// The input's M (−1) or V (+1) of the edge a–b, 0 when none is known.
static int flat_fold_hint(const ori_mesh *m, int a, int b)
{
    if (!m->nhint) return 0;
    int key[3] = {a < b ? a : b, a < b ? b : a, 0};
    const int *h = bsearch(key, m->hint, (size_t)m->nhint, 3 * sizeof *m->hint, cmp_hint);
    return h ? h[2] : 0;
}

// A two-sided sheet (every face also listed with its cycle reversed, as orikin export writes a
// posed sheet's back) is read as its front: a face that reverses an earlier face is dropped.
static _Thread_local const int *g_key;
static _Thread_local const int *g_key_start;
static int cmp_face_key(const void *x, const void *y)
{
    int a = *(const int *)x, b = *(const int *)y;
    int na = g_key_start[a + 1] - g_key_start[a], nb = g_key_start[b + 1] - g_key_start[b];
    if (na != nb) return na - nb;
    for (int i = 0; i < na; ++i)
        if (g_key[g_key_start[a] + i] != g_key[g_key_start[b] + i]) return g_key[g_key_start[a] + i] - g_key[g_key_start[b] + i];
    return a - b;
}
static int cmp_int(const void *x, const void *y) { return *(const int *)x - *(const int *)y; }

static bool reverses(const int *a, const int *b, int k)
{
    int p = -1;
    for (int j = 0; j < k && p < 0; ++j)
        if (b[j] == a[0]) p = j;
    if (p < 0) return false;
    for (int j = 0; j < k; ++j)
        if (b[((p - j) % k + k) % k] != a[j]) return false;
    return true;
}

static void drop_back_faces(int *fs, int *fv, int *pnf)
{
    int nf = *pnf;
    if (nf < 2) return;
    int *key = ori__alloc(((size_t)fs[nf] + 1) * sizeof *key), *idx = ori__alloc((size_t)nf * sizeof *idx);
    bool *drop = ori__calloc((size_t)nf, sizeof *drop);
    memcpy(key, fv, (size_t)fs[nf] * sizeof *key);
    for (int f = 0; f < nf; ++f) {
        qsort(key + fs[f], (size_t)(fs[f + 1] - fs[f]), sizeof *key, cmp_int);
        idx[f] = f;
    }
    g_key = key, g_key_start = fs;
    qsort(idx, (size_t)nf, sizeof *idx, cmp_face_key);
    for (int i = 1; i < nf; ++i) {
        int a = idx[i - 1], b = idx[i], k = fs[a + 1] - fs[a];
        if (k != fs[b + 1] - fs[b] || memcmp(key + fs[a], key + fs[b], (size_t)k * sizeof *key) != 0) continue;
        if (!drop[a] && reverses(fv + fs[a], fv + fs[b], k)) drop[b] = true; // a < b: the later one goes
    }
    int m = 0, q = 0;
    for (int f = 0; f < nf; ++f) {
        if (drop[f]) continue;
        int s0 = fs[f], s1 = fs[f + 1];
        fs[m] = q;
        for (int i = s0; i < s1; ++i) fv[q++] = fv[i];
        m++;
    }
    fs[m] = q;
    *pnf = m;
    ori__free(key), ori__free(idx), ori__free(drop);
}

ori_status ori_unfold_load_mesh(const char *path, ori_mesh **out, ori_error *error)
{
    ORI_ASSERT(path && out);
    *out = NULL;
    size_t len = strlen(path);
    const char *ext = len >= 4 ? path + len - 4 : "";
    ori_v3 *v = NULL;
    int *fs = NULL, *fv = NULL, nv = 0, nf = 0, *hint = NULL, nhint = 0;
    ori_status st;
    if (len >= 5 && strcmp(path + len - 5, ".fold") == 0) {
        ori_fold *doc = NULL;
        st = ori_fold_load_file(path, &doc, error);
        if (st != ORI_OK) return st;
        ori_pattern *p = NULL;
        st = ori_fold_get_pattern(doc, 0, NULL, &p, error);
        ori_fold_destroy(doc);
        if (st != ORI_OK) return st;
        nv = ori_pattern_vertex_count(p), nf = ori_pattern_face_count(p);
        v = ori__alloc(((size_t)nv + 1) * sizeof *v);
        for (int i = 0; i < nv; ++i) v[i] = ori_pattern_vertex(p, i);
        fs = ori__alloc(((size_t)nf + 1) * sizeof *fs);
        int total = 0;
        for (int f = 0; f < nf; ++f) total += ori_pattern_face_size(p, f);
        fv = ori__alloc(((size_t)total + 1) * sizeof *fv);
        fs[0] = 0;
        for (int f = 0; f < nf; ++f) fs[f + 1] = fs[f] + ori_pattern_face_vertices(p, f, fv + fs[f], total - fs[f]);
        // the creases' M/V (or the sign of their fold angle) for flat-folded edges
        int ne = ori_pattern_edge_count(p);
        hint = ori__alloc(((size_t)ne + 1) * 3 * sizeof *hint);
        for (int e = 0; e < ne; ++e) {
            ori_edge x = ori_pattern_edge(p, e);
            int sign = x.assignment == ORI_ASSIGN_MOUNTAIN ? -1 : x.assignment == ORI_ASSIGN_VALLEY ? 1
                       : x.fold_angle_rad < 0.0 ? -1 : x.fold_angle_rad > 0.0 ? 1 : 0;
            if (!sign) continue;
            int *t = hint + 3 * nhint++;
            t[0] = x.v[0] < x.v[1] ? x.v[0] : x.v[1], t[1] = x.v[0] < x.v[1] ? x.v[1] : x.v[0], t[2] = sign;
        }
        qsort(hint, (size_t)nhint, 3 * sizeof *hint, cmp_hint);
        ori_pattern_destroy(p);
    } else {
        char *data = NULL;
        size_t size = 0;
        st = ori_file_read_all(path, (size_t)1 << 31, &data, &size, error);
        if (st != ORI_OK) return st;
        // orikin's thick exports are separate closed panel solids, offset off the sheet: there
        // is no one surface to unfold (the tag is on the first lines: an OBJ comment, an STL
        // solid name).
        const char *tag = size > 0 ? strstr(data, ORI_THICK_PANEL_TAG) : NULL;
        if (tag && tag - data < 512) {
            double t = 0.0;
            sscanf(tag + strlen(ORI_THICK_PANEL_TAG), "%lf", &t);
            ori_buffer_free(data);
            return ori__fail(error, ORI_ERR_UNSUPPORTED,
                             "an orikin thick export (separate closed panel solids, thickness %g), not one surface: "
                             "export the state without --thickness to unfold it",
                             t);
        }
        if (strcmp(ext, ".obj") == 0 || strcmp(ext, ".OBJ") == 0) st = read_obj(data, &v, &nv, &fs, &fv, &nf, error);
        else if (strcmp(ext, ".stl") == 0 || strcmp(ext, ".STL") == 0) st = read_stl(data, size, &v, &nv, &fs, &fv, &nf, error);
        else st = ori__fail(error, ORI_ERR_UNSUPPORTED, "unknown shape format (expected .obj, .stl or .fold)");
        ori_buffer_free(data);
        if (st != ORI_OK) return st;
        drop_back_faces(fs, fv, &nf);
    }
    st = ori_unfold_mesh_create(v, nv, fs, fv, nf, out, error);
    if (st == ORI_OK) (*out)->hint = hint, (*out)->nhint = nhint, hint = NULL;
    ori__free(v), ori__free(fs), ori__free(fv), ori__free(hint);
    return st;
}

// --- the face graph and nets ---------------------------------------------------------------



static uint64_t rnd(net_ctx *c)
{
    c->rng ^= c->rng << 13, c->rng ^= c->rng >> 7, c->rng ^= c->rng << 17;
    return c->rng;
}
static double rnd01(net_ctx *c) { return (double)(rnd(c) >> 11) / 9007199254740992.0; }

int ori__net_fsize(const ori_mesh *m, int f) { return m->fstart[f + 1] - m->fstart[f]; }

void ori__net_ctx_init(net_ctx *c, const ori_mesh *m)
{
    memset(c, 0, sizeof *c);
    c->m = m;
    int nh = m->fstart[m->nf];
    half *h = ori__alloc(((size_t)nh + 1) * sizeof *h);
    int *twin = ori__alloc(((size_t)nh + 1) * sizeof *twin);
    for (int f = 0, q = 0; f < m->nf; ++f)
        for (int i = m->fstart[f]; i < m->fstart[f + 1]; ++i)
            h[q++] = (half){m->fv[i], m->fv[i + 1 < m->fstart[f + 1] ? i + 1 : m->fstart[f]], f, i - m->fstart[f]};
    pair_halves(h, nh, twin, "faces", NULL);
    c->normal = ori__alloc(((size_t)m->nf + 1) * sizeof *c->normal);
    for (int f = 0; f < m->nf; ++f) c->normal[f] = ori_v3_normalize(face_normal(m->v, m->fv + m->fstart[f], ori__net_fsize(m, f)));
    c->e = ori__alloc(((size_t)nh + 1) * sizeof *c->e);
    for (int i = 0; i < nh; ++i) {
        int j = twin[i];
        if (j >= 0 && j < i) continue;
        fedge x = {h[i].face, j >= 0 ? h[j].face : -1, h[i].idx, j >= 0 ? h[j].idx : -1, h[i].a, h[i].b, 0.0};
        if (j >= 0) {
            ori_v3 nf = c->normal[x.f], ng = c->normal[x.g];
            double mag = atan2(ori_v3_norm(ori_v3_cross(nf, ng)), ori_v3_dot(nf, ng));
            // convex when g's centroid lies below f's plane
            ori_v3 cg = {0, 0, 0};
            int k = ori__net_fsize(m, x.g);
            for (int t = 0; t < k; ++t) cg = ori_v3_add(cg, m->v[m->fv[m->fstart[x.g] + t]]);
            cg = ori_v3_scale(cg, 1.0 / k);
            bool convex = ori_v3_dot(ori_v3_sub(cg, m->v[x.a]), nf) < 0.0;
            int sign = ORI_PI - mag < ORI_TOL_UNFOLD_FLAT_FOLD_RAD ? flat_fold_hint(m, x.a, x.b) : 0;
            if (sign) convex = sign < 0; // flat-folded: the input's assignment decides
            x.angle = convex ? -mag : mag;
        }
        c->e[c->ne++] = x;
    }
    c->fe_start = ori__calloc((size_t)m->nf + 2, sizeof(int));
    for (int k = 0; k < c->ne; ++k) {
        c->fe_start[c->e[k].f + 1]++;
        if (c->e[k].g >= 0) c->fe_start[c->e[k].g + 1]++;
    }
    for (int f = 0; f < m->nf; ++f) c->fe_start[f + 1] += c->fe_start[f];
    c->fe = ori__alloc(((size_t)2 * c->ne + 1) * sizeof(int));
    int *fill = ori__alloc(((size_t)m->nf + 1) * sizeof *fill);
    memcpy(fill, c->fe_start, (size_t)m->nf * sizeof *fill);
    for (int k = 0; k < c->ne; ++k) {
        c->fe[fill[c->e[k].f]++] = k;
        if (c->e[k].g >= 0) c->fe[fill[c->e[k].g]++] = k;
    }
    ori__free(fill);
    c->local = ori__alloc(((size_t)nh + 1) * sizeof *c->local);
    c->pos = ori__alloc(((size_t)nh + 1) * sizeof *c->pos);
    for (int f = 0; f < m->nf; ++f) {
        const int *fc = m->fv + m->fstart[f];
        ori_v3 o = m->v[fc[0]], u = ori_v3_normalize(ori_v3_sub(m->v[fc[1]], o));
        ori_v3 w = ori_v3_cross(c->normal[f], u);
        for (int i = 0; i < ori__net_fsize(m, f); ++i) {
            ori_v3 d = ori_v3_sub(m->v[fc[i]], o);
            c->local[m->fstart[f] + i] = ori_v2_make(ori_v3_dot(d, u), ori_v3_dot(d, w));
        }
    }
    c->rng = 0x9E3779B97F4A7C15ULL;
    ori__free(h), ori__free(twin);
}

void ori__net_ctx_free(net_ctx *c)
{
    ori__free(c->e), ori__free(c->fe_start), ori__free(c->fe), ori__free(c->local), ori__free(c->pos), ori__free(c->normal);
}

// Lay out the faces along the tree (in_tree[k] for each face edge) from root: each face's
// corners in c->pos. order receives the faces in breadth-first order, parent_edge per face.
int ori__net_layout(net_ctx *c, const bool *in_tree, int root, int *order, int *parent_edge, bool *placed)
{
    const ori_mesh *m = c->m;
    for (int f = 0; f < m->nf; ++f) placed[f] = false, parent_edge[f] = -1;
    for (int i = 0; i < ori__net_fsize(m, root); ++i) c->pos[m->fstart[root] + i] = c->local[m->fstart[root] + i];
    int head = 0, tail = 0;
    order[tail++] = root;
    placed[root] = true;
    while (head < tail) {
        int f = order[head++];
        for (int t = c->fe_start[f]; t < c->fe_start[f + 1]; ++t) {
            int k = c->fe[t];
            if (!in_tree[k]) continue;
            fedge *x = &c->e[k];
            int g = x->f == f ? x->g : x->f;
            if (g < 0 || placed[g]) continue;
            // shared vertices a, b: their placed positions in f, local positions in g
            int fi = x->f == f ? x->fi : x->gi, gi = x->f == f ? x->gi : x->fi;
            int kf = ori__net_fsize(m, f), kg = ori__net_fsize(m, g);
            ori_v2 P0 = c->pos[m->fstart[f] + fi], P1 = c->pos[m->fstart[f] + (fi + 1) % kf];
            // in g the edge runs the other way: corner gi is P1's vertex, gi + 1 is P0's
            ori_v2 L1 = c->local[m->fstart[g] + gi], L0 = c->local[m->fstart[g] + (gi + 1) % kg];
            ori_v2 dp = ori_v2_sub(P1, P0), dl = ori_v2_sub(L1, L0);
            double ang = atan2(dp.y, dp.x) - atan2(dl.y, dl.x);
            double cs = cos(ang), sn = sin(ang);
            for (int i = 0; i < kg; ++i) {
                ori_v2 q = ori_v2_sub(c->local[m->fstart[g] + i], L0);
                c->pos[m->fstart[g] + i] = ori_v2_add(P0, ori_v2_make(cs * q.x - sn * q.y, sn * q.x + cs * q.y));
            }
            c->pos[m->fstart[g] + gi] = P1, c->pos[m->fstart[g] + (gi + 1) % kg] = P0;
            placed[g] = true;
            parent_edge[g] = k;
            order[tail++] = g;
        }
    }
    return tail;
}

// Convex pieces of a placed face: ear-clipping triangles (indices into the face's corners).
static int triangulate(const ori_v2 *p, int k, int *tri)
{
    int idx[256], n = k, t = 0;
    if (k > 256) return 0;
    for (int i = 0; i < k; ++i) idx[i] = i;
    int guard = 0;
    while (n > 3 && guard++ < 10000) {
        bool cut = false;
        for (int i = 0; i < n && !cut; ++i) {
            int a = idx[(i + n - 1) % n], b = idx[i], cc = idx[(i + 1) % n];
            if (ori_v2_cross(ori_v2_sub(p[b], p[a]), ori_v2_sub(p[cc], p[b])) <= 0.0) continue;
            bool inside = false;
            for (int j = 0; j < n && !inside; ++j) {
                int q = idx[j];
                if (q == a || q == b || q == cc) continue;
                inside = ori__orient2d_exact(p[a], p[b], p[q]) >= 0 && ori__orient2d_exact(p[b], p[cc], p[q]) >= 0 &&
                         ori__orient2d_exact(p[cc], p[a], p[q]) >= 0;
            }
            if (inside) continue;
            tri[3 * t] = a, tri[3 * t + 1] = b, tri[3 * t + 2] = cc, t++;
            memmove(idx + i, idx + i + 1, (size_t)(n - i - 1) * sizeof *idx);
            n--;
            cut = true;
        }
        if (!cut) break;
    }
    if (n == 3) tri[3 * t] = idx[0], tri[3 * t + 1] = idx[1], tri[3 * t + 2] = idx[2], t++;
    return t;
}

// Separating axes with tolerance: two triangles overlap when no edge normal separates them by
// more than −tol (touching along an edge or at a point is not an overlap).
static bool tri_overlap(const ori_v2 *a, const ori_v2 *b, double tol)
{
    const ori_v2 *s[2] = {a, b};
    for (int w = 0; w < 2; ++w)
        for (int i = 0; i < 3; ++i) {
            ori_v2 p = s[w][i], q = s[w][(i + 1) % 3];
            ori_v2 n = ori_v2_normalize(ori_v2_make(q.y - p.y, p.x - q.x)); // outward for ccw
            double amin = INFINITY, amax = -INFINITY, bmin = INFINITY, bmax = -INFINITY;
            for (int j = 0; j < 3; ++j) {
                double x = ori_v2_dot(n, a[j]), y = ori_v2_dot(n, b[j]);
                amin = fmin(amin, x), amax = fmax(amax, x), bmin = fmin(bmin, y), bmax = fmax(bmax, y);
            }
            if (amax <= bmin + tol || bmax <= amin + tol) return false;
        }
    return true;
}

typedef struct face_box {
    double x0, x1, y0, y1;
    int f;
} face_box;

static int cmp_box(const void *x, const void *y)
{
    double a = ((const face_box *)x)->x0, b = ((const face_box *)y)->x0;
    return a < b ? -1 : a > b;
}

bool ori__net_faces_overlap(const net_ctx *c, int f, int g, const int *tri_start, const int *tri, double tol)
{
    const ori_mesh *m = c->m;
    for (int s = tri_start[f]; s < tri_start[f + 1]; ++s)
        for (int t = tri_start[g]; t < tri_start[g + 1]; ++t) {
            ori_v2 A[3], B[3];
            for (int j = 0; j < 3; ++j) A[j] = c->pos[m->fstart[f] + tri[3 * s + j]], B[j] = c->pos[m->fstart[g] + tri[3 * t + j]];
            if (tri_overlap(A, B, tol)) return true;
        }
    return false;
}

static double point_segment_distance(ori_v2 p, ori_v2 a, ori_v2 b)
{
    ori_v2 d = ori_v2_sub(b, a);
    double len2 = ori_v2_dot(d, d), t = len2 > 0.0 ? ori_v2_dot(ori_v2_sub(p, a), d) / len2 : 0.0;
    t = fmin(1.0, fmax(0.0, t));
    return ori_v2_norm(ori_v2_sub(p, ori_v2_add(a, ori_v2_scale(d, t))));
}

// Whether a corner of f lies within tol of g's boundary other than as the same 3D vertex at the
// same place (which the net welds): the net would touch itself there, and a FOLD file cannot
// hold two vertices at one point, nor a vertex on another's edge.
static bool corners_touch(const net_ctx *c, int f, int g, double tol)
{
    const ori_mesh *m = c->m;
    int kf = ori__net_fsize(m, f), kg = ori__net_fsize(m, g);
    for (int i = 0; i < kf; ++i) {
        ori_v2 p = c->pos[m->fstart[f] + i];
        int v = m->fv[m->fstart[f] + i];
        for (int j = 0; j < kg; ++j) {
            int j0 = m->fstart[g] + j, j1 = m->fstart[g] + (j + 1) % kg;
            ori_v2 a = c->pos[j0], b = c->pos[j1];
            if (point_segment_distance(p, a, b) > tol) continue;
            if ((m->fv[j0] == v && ori_v2_norm(ori_v2_sub(p, a)) <= tol) ||
                (m->fv[j1] == v && ori_v2_norm(ori_v2_sub(p, b)) <= tol))
                continue;
            return true;
        }
    }
    return false;
}

bool ori__net_faces_touch(const net_ctx *c, int f, int g)
{
    double tol = ORI_TOL_UNFOLD_CONTACT_REL * c->m->diag;
    return corners_touch(c, f, g, tol) || corners_touch(c, g, f, tol);
}

// Pairs of faces that touch (ori__net_faces_touch) without overlapping, counted.
static int count_touching(const net_ctx *c)
{
    const ori_mesh *m = c->m;
    face_box *b = ori__alloc(((size_t)m->nf + 1) * sizeof *b);
    for (int f = 0; f < m->nf; ++f) {
        face_box x = {INFINITY, -INFINITY, INFINITY, -INFINITY, f};
        for (int i = 0; i < ori__net_fsize(m, f); ++i) {
            ori_v2 p = c->pos[m->fstart[f] + i];
            x.x0 = fmin(x.x0, p.x), x.x1 = fmax(x.x1, p.x), x.y0 = fmin(x.y0, p.y), x.y1 = fmax(x.y1, p.y);
        }
        b[f] = x;
    }
    qsort(b, (size_t)m->nf, sizeof *b, cmp_box);
    double tol = ORI_TOL_UNFOLD_CONTACT_REL * m->diag;
    int count = 0;
    for (int i = 0; i < m->nf; ++i)
        for (int j = i + 1; j < m->nf && b[j].x0 <= b[i].x1 + tol; ++j) {
            if (b[j].y0 > b[i].y1 + tol || b[i].y0 > b[j].y1 + tol) continue;
            if (ori__net_faces_touch(c, b[i].f, b[j].f)) count++;
        }
    ori__free(b);
    return count;
}

void ori__net_build_tris(const net_ctx *c, int *tri_start, int *tri)
{
    const ori_mesh *m = c->m;
    tri_start[0] = 0;
    for (int f = 0; f < m->nf; ++f) {
        int n = triangulate(c->local + m->fstart[f], ori__net_fsize(m, f), tri + 3 * tri_start[f]);
        tri_start[f + 1] = tri_start[f] + n;
    }
}

// Overlapping face pairs among faces with mask[f] (NULL = all), counted (stop after limit).
int ori__net_count_overlaps(const net_ctx *c, const int *tri_start, const int *tri, const int *piece, int limit)
{
    const ori_mesh *m = c->m;
    face_box *b = ori__alloc(((size_t)m->nf + 1) * sizeof *b);
    for (int f = 0; f < m->nf; ++f) {
        face_box x = {INFINITY, -INFINITY, INFINITY, -INFINITY, f};
        for (int i = 0; i < ori__net_fsize(m, f); ++i) {
            ori_v2 p = c->pos[m->fstart[f] + i];
            x.x0 = fmin(x.x0, p.x), x.x1 = fmax(x.x1, p.x), x.y0 = fmin(x.y0, p.y), x.y1 = fmax(x.y1, p.y);
        }
        b[f] = x;
    }
    qsort(b, (size_t)m->nf, sizeof *b, cmp_box);
    double tol = ORI_TOL_UNFOLD_OVERLAP_REL * m->diag;
    int count = 0;
    for (int i = 0; i < m->nf && count < limit; ++i)
        for (int j = i + 1; j < m->nf && b[j].x0 < b[i].x1 - tol && count < limit; ++j) {
            if (b[j].y0 >= b[i].y1 - tol || b[i].y0 >= b[j].y1 - tol) continue;
            if (piece && piece[b[i].f] != piece[b[j].f]) continue;
            if (ori__net_faces_overlap(c, b[i].f, b[j].f, tri_start, tri, tol)) count++;
        }
    ori__free(b);
    return count;
}

// --- spanning trees ----------------------------------------------------------------------------

static int cmp_weight_idx(const void *x, const void *y)
{
    const double *a = x, *b = y;
    return a[0] < b[0] ? -1 : a[0] > b[0];
}

// Kruskal on weights (lower first): in_tree per edge.
static void mst(const net_ctx *c, const double *w, bool *in_tree)
{
    int nf = c->m->nf;
    double *wi = ori__alloc(((size_t)c->ne + 1) * 2 * sizeof *wi);
    for (int k = 0; k < c->ne; ++k) wi[2 * k] = w[k], wi[2 * k + 1] = k;
    qsort(wi, (size_t)c->ne, 2 * sizeof *wi, cmp_weight_idx);
    int *uf = ori__alloc(((size_t)nf + 1) * sizeof *uf);
    for (int f = 0; f < nf; ++f) uf[f] = f;
    for (int k = 0; k < c->ne; ++k) in_tree[k] = false;
    for (int t = 0; t < c->ne; ++t) {
        int k = (int)wi[2 * t + 1];
        if (c->e[k].g < 0) continue;
        int a = ori__uf_root(uf, c->e[k].f), b = ori__uf_root(uf, c->e[k].g);
        if (a == b) continue;
        uf[a] = b;
        in_tree[k] = true;
    }
    ori__free(wi), ori__free(uf);
}

// Steepest-edge unfolding (Schlickkieser): cut, at every vertex but the highest in direction d,
// the edge that rises most steeply; the crease tree is the rest. Weights: cut edges get +1.
static void steepest_weights(const net_ctx *c, ori_v3 d, double *w)
{
    const ori_mesh *m = c->m;
    double *best = ori__alloc(((size_t)m->nv + 1) * sizeof *best);
    int *arg = ori__alloc(((size_t)m->nv + 1) * sizeof *arg);
    for (int v = 0; v < m->nv; ++v) best[v] = -INFINITY, arg[v] = -1;
    for (int k = 0; k < c->ne; ++k) {
        ori_v3 ab = ori_v3_sub(m->v[c->e[k].b], m->v[c->e[k].a]);
        double s = ori_v3_dot(ab, d) / ori_v3_norm(ab);
        if (s > best[c->e[k].a]) best[c->e[k].a] = s, arg[c->e[k].a] = k;
        if (-s > best[c->e[k].b]) best[c->e[k].b] = -s, arg[c->e[k].b] = k;
    }
    for (int k = 0; k < c->ne; ++k) w[k] = 0.0;
    for (int v = 0; v < m->nv; ++v)
        if (arg[v] >= 0 && best[v] > 0.0) w[arg[v]] += 1.0;
    // ties broken by steepness so that the tree is deterministic
    for (int k = 0; k < c->ne; ++k) {
        ori_v3 ab = ori_v3_normalize(ori_v3_sub(m->v[c->e[k].b], m->v[c->e[k].a]));
        w[k] += 1e-3 * fabs(ori_v3_dot(ab, d));
    }
    ori__free(best), ori__free(arg);
}

// --- the net as a crease pattern --------------------------------------------------------------


static void piece_offsets(const net_ctx *c, const int *piece, int pieces, ori_v2 *offset)
{
    const ori_mesh *m = c->m;
    double *x0 = ori__alloc(((size_t)pieces + 1) * 4 * sizeof(double));
    for (int q = 0; q < pieces; ++q) x0[4 * q] = x0[4 * q + 2] = INFINITY, x0[4 * q + 1] = x0[4 * q + 3] = -INFINITY;
    for (int f = 0; f < m->nf; ++f)
        for (int i = 0; i < ori__net_fsize(m, f); ++i) {
            ori_v2 p = c->pos[m->fstart[f] + i];
            double *b = x0 + 4 * piece[f];
            b[0] = fmin(b[0], p.x), b[1] = fmax(b[1], p.x), b[2] = fmin(b[2], p.y), b[3] = fmax(b[3], p.y);
        }
    double x = 0.0, gap = 0.05 * c->m->diag;
    for (int q = 0; q < pieces; ++q) {
        offset[q] = ori_v2_make(x - x0[4 * q], -x0[4 * q + 2]);
        x += x0[4 * q + 1] - x0[4 * q] + gap;
    }
    ori__free(x0);
}

static _Thread_local const int *g_corner_v3; // qsort has no context argument
static int cmp_corner_v3(const void *x, const void *y)
{
    int a = *(const int *)x, b = *(const int *)y;
    return g_corner_v3[a] != g_corner_v3[b] ? (g_corner_v3[a] > g_corner_v3[b]) - (g_corner_v3[a] < g_corner_v3[b]) : a - b;
}

// Unite (in uf) the copies of a 3D vertex that the layout puts on the same point: around a
// flat vertex (angle sum 2π) the wedges that cuts separate close up again. Left apart they
// would be two vertices at one place, which no FOLD reader takes (orikin's refuses them).
// "The same point" is the pattern reader's own test (ORI_TOL_LENGTH_REL of the net's extent),
// so whatever that test would see as coincident is welded here.
static void weld_coincident_copies(const net_ctx *c, const int *piece, const ori_v2 *off, int *uf)
{
    const ori_mesh *m = c->m;
    int nh = m->fstart[m->nf];
    if (nh < 2) return;
    int *corner = ori__alloc((size_t)nh * sizeof *corner), *face = ori__alloc((size_t)nh * sizeof *face);
    ori_v2 *p = ori__alloc((size_t)nh * sizeof *p);
    for (int f = 0; f < m->nf; ++f)
        for (int i = m->fstart[f]; i < m->fstart[f + 1]; ++i) face[i] = f;
    ori_v2 lo = {INFINITY, INFINITY}, hi = {-INFINITY, -INFINITY};
    for (int i = 0; i < nh; ++i) {
        corner[i] = i;
        p[i] = ori_v2_add(c->pos[i], off[piece[face[i]]]);
        lo.x = fmin(lo.x, p[i].x), lo.y = fmin(lo.y, p[i].y), hi.x = fmax(hi.x, p[i].x), hi.y = fmax(hi.y, p[i].y);
    }
    double tol = ORI_TOL_LENGTH_REL * ori_v2_norm(ori_v2_sub(hi, lo));
    g_corner_v3 = m->fv;
    qsort(corner, (size_t)nh, sizeof *corner, cmp_corner_v3);
    for (int s = 0, t; s < nh; s = t) {
        for (t = s + 1; t < nh && m->fv[corner[t]] == m->fv[corner[s]];) ++t;
        for (int a = s; a < t; ++a)
            for (int b = a + 1; b < t; ++b) {
                int ra = ori__uf_root(uf, corner[a]), rb = ori__uf_root(uf, corner[b]);
                if (ra != rb && ori_v2_norm(ori_v2_sub(p[corner[a]], p[corner[b]])) <= tol) uf[ra] = rb;
            }
    }
    ori__free(corner), ori__free(face), ori__free(p);
}

ori_unfold_net *ori__net_make(const net_ctx *c, const bool *in_tree, const int *piece, int pieces)
{
    const ori_mesh *m = c->m;
    int nh = m->fstart[m->nf];
    // net vertices: corners united across tree edges
    int *uf = ori__alloc(((size_t)nh + 1) * sizeof *uf);
    for (int i = 0; i < nh; ++i) uf[i] = i;
    for (int k = 0; k < c->ne; ++k) {
        if (!in_tree[k]) continue;
        const fedge *x = &c->e[k];
        int kf = ori__net_fsize(m, x->f), kg = ori__net_fsize(m, x->g);
        int fa = m->fstart[x->f] + x->fi, fb = m->fstart[x->f] + (x->fi + 1) % kf;
        int gb = m->fstart[x->g] + x->gi, ga = m->fstart[x->g] + (x->gi + 1) % kg;
        int r1 = ori__uf_root(uf, fa), r2 = ori__uf_root(uf, ga);
        if (r1 != r2) uf[r1] = r2;
        r1 = ori__uf_root(uf, fb), r2 = ori__uf_root(uf, gb);
        if (r1 != r2) uf[r1] = r2;
    }
    ori_v2 *off = ori__alloc(((size_t)pieces + 1) * sizeof *off);
    piece_offsets(c, piece, pieces, off);
    weld_coincident_copies(c, piece, off, uf);
    int *vid = ori__alloc(((size_t)nh + 1) * sizeof *vid);
    for (int i = 0; i < nh; ++i) vid[i] = -1;
    ori_unfold_net *net = ori__calloc(1, sizeof *net);
    ori_pattern_def pd = ori_default_pattern_def();
    net->pattern = ori_pattern_create(&pd);
    net->vertex3d = ori__alloc(((size_t)nh + 1) * sizeof(int));
    net->shape = ori__alloc(((size_t)nh + 1) * sizeof(ori_v3));
    int nv = 0;
    for (int f = 0; f < m->nf; ++f)
        for (int i = 0; i < ori__net_fsize(m, f); ++i) {
            int r = ori__uf_root(uf, m->fstart[f] + i);
            if (vid[r] < 0) {
                ori_v2 p = ori_v2_add(c->pos[m->fstart[f] + i], off[piece[f]]);
                vid[r] = ori_pattern_add_vertex(net->pattern, ori_v3_make(p.x, p.y, 0.0));
                net->vertex3d[nv] = m->fv[m->fstart[f] + i];
                net->shape[nv] = m->v[m->fv[m->fstart[f] + i]];
                nv++;
            }
        }
    int *edge_of = ori__alloc(((size_t)c->ne + 1) * 2 * sizeof *edge_of);
    net->glue = ori__alloc(((size_t)c->ne + 1) * 2 * sizeof(int));
    for (int k = 0; k < c->ne; ++k) {
        const fedge *x = &c->e[k];
        int kf = ori__net_fsize(m, x->f);
        int fa = vid[ori__uf_root(uf, m->fstart[x->f] + x->fi)], fb = vid[ori__uf_root(uf, m->fstart[x->f] + (x->fi + 1) % kf)];
        // A cut whose two sides lie on each other (both ends welded: a zero-width slit through
        // flat vertices) is no cut: it is written as the crease it is in the shape.
        bool closed = false;
        if (!in_tree[k] && x->g >= 0) {
            int kg = ori__net_fsize(m, x->g);
            int gb = vid[ori__uf_root(uf, m->fstart[x->g] + x->gi)], ga = vid[ori__uf_root(uf, m->fstart[x->g] + (x->gi + 1) % kg)];
            closed = (fa == ga && fb == gb) || (fa == gb && fb == ga);
        }
        if (in_tree[k] || closed) {
            ori_assignment as = x->angle < 0.0 ? ORI_ASSIGN_MOUNTAIN : x->angle > 0.0 ? ORI_ASSIGN_VALLEY : ORI_ASSIGN_FLAT;
            int e = ori_pattern_add_edge(net->pattern, fa, fb, as, x->angle);
            edge_of[2 * k] = edge_of[2 * k + 1] = e;
            net->glue[e] = -1;
        } else {
            int e1 = ori_pattern_add_edge(net->pattern, fa, fb, ORI_ASSIGN_BOUNDARY, 0.0);
            edge_of[2 * k] = e1;
            net->glue[e1] = -1;
            if (x->g >= 0) {
                int kg = ori__net_fsize(m, x->g);
                int gb = vid[ori__uf_root(uf, m->fstart[x->g] + x->gi)], ga = vid[ori__uf_root(uf, m->fstart[x->g] + (x->gi + 1) % kg)];
                int e2 = ori_pattern_add_edge(net->pattern, gb, ga, ORI_ASSIGN_BOUNDARY, 0.0);
                edge_of[2 * k + 1] = e2;
                net->glue[e1] = e2, net->glue[e2] = e1;
            }
        }
    }
    net->src_start = ori__alloc(((size_t)m->nf + 1) * sizeof(int));
    net->src = ori__alloc(((size_t)m->src_start[m->nf] + 1) * sizeof(int));
    memcpy(net->src_start, m->src_start, ((size_t)m->nf + 1) * sizeof(int));
    memcpy(net->src, m->src, (size_t)m->src_start[m->nf] * sizeof(int));
    int buf[1024];
    for (int f = 0; f < m->nf; ++f) {
        int k = ori__net_fsize(m, f);
        int *b = k <= 1024 ? buf : ori__alloc((size_t)k * sizeof *b);
        for (int i = 0; i < k; ++i) b[i] = vid[ori__uf_root(uf, m->fstart[f] + i)];
        ori_pattern_add_face(net->pattern, b, k);
        if (b != buf) ori__free(b);
    }
    ori_pattern_set_has_fold_angles(net->pattern, true);
    ori__free(uf), ori__free(vid), ori__free(off), ori__free(edge_of);
    return net;
}

// Check a fold motion for penetration: all creases together (order NULL: angles scaled by
// s/20), or one crease after the other in the given order (8 steps each, the others held at 0
// or at their target). The final state (faces glued) is not checked.
static bool motion_collides(ori_mechanism *mech, ori_collider *col, const double *angles, int ne, const int *order,
                            int count, ori_rigid pose, ori_v3 *pos, double *a)
{
    ori_error err;
    ori_collision_result cr;
    if (!order) {
        for (int s = 1; s < 20; ++s) {
            for (int e = 0; e < ne; ++e) a[e] = angles[e] * s / 20.0;
            ori_mechanism_vertex_positions(mech, a, 0, pose, pos);
            if (ori_collider_check(col, pos, &cr, &err) == ORI_OK && cr.penetrating > 0) return true;
        }
        return false;
    }
    for (int e = 0; e < ne; ++e) a[e] = 0.0;
    for (int i = 0; i < count; ++i) {
        int e = order[i];
        for (int s = 1; s <= 8; ++s) {
            a[e] = angles[e] * s / 8.0;
            if (i == count - 1 && s == 8) break;
            ori_mechanism_vertex_positions(mech, a, 0, pose, pos);
            if (ori_collider_check(col, pos, &cr, &err) == ORI_OK && cr.penetrating > 0) return true;
        }
    }
    return false;
}

static _Thread_local int g_depth_cmp_sign;
static _Thread_local const int *g_depth;
static int cmp_depth(const void *x, const void *y)
{
    int a = g_depth[*(const int *)x], b = g_depth[*(const int *)y];
    return g_depth_cmp_sign * (a - b);
}

// Fold the net back (one piece): pose by forward kinematics from face 0 placed where the shape
// has it; returns the largest vertex distance to the shape / the diagonal (−1 when not posed).
// *order receives the first collision-free fold order (ORI_FOLD_ORDER_NONE when none is).
static double refold_error(ori_unfold_net *net, double diag, bool *collides, ori_fold_order *order)
{
    *collides = false;
    *order = ORI_FOLD_ORDER_NONE;
    ori_error err;
    ori_build_def bd = ori_default_build_def();
    bd.check_planarity = false;
    if (ori_pattern_build(net->pattern, &bd, &err) != ORI_OK) return -1.0;
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = net->pattern;
    ori_mechanism *mech = NULL;
    if (ori_mechanism_create(&md, &mech, &err) != ORI_OK) return -1.0;
    int nv = ori_pattern_vertex_count(net->pattern), ne = ori_pattern_edge_count(net->pattern);
    int nf = ori_pattern_face_count(net->pattern);
    double *angles = ori__alloc(((size_t)ne + 1) * sizeof *angles);
    for (int e = 0; e < ne; ++e) angles[e] = ori_pattern_edge(net->pattern, e).fold_angle_rad;
    ori_rigid pose;
    double worst = -1.0;
    ori_v3 *pos = ori__alloc(((size_t)nv + 1) * sizeof *pos);
    if (ori_mechanism_face_pose_from_coords(mech, 0, net->shape, &pose, &err) == ORI_OK &&
        ori_mechanism_pose_state(mech, angles, 0, pose, NULL, pos, NULL, &err) == ORI_OK) {
        worst = 0.0;
        for (int v = 0; v < nv; ++v) worst = fmax(worst, ori_v3_norm(ori_v3_sub(pos[v], net->shape[v])) / diag);
        ori_collider_def cd = ori_default_collider_def();
        cd.pattern = net->pattern;
        ori_collider *col = NULL;
        if (ori_collider_create(&cd, &col, &err) == ORI_OK) {
            double *a = ori__alloc(((size_t)ne + 1) * sizeof *a);
            if (!motion_collides(mech, col, angles, ne, NULL, 0, pose, pos, a)) {
                *order = ORI_FOLD_ORDER_TOGETHER;
            } else if (ne <= 600) {
                // one crease at a time by depth in the face tree: leaves first, then root first
                int *pf = ori__alloc(((size_t)nf + 1) * sizeof *pf), *pe = ori__alloc(((size_t)nf + 1) * sizeof *pe);
                int *depth_e = ori__calloc((size_t)ne + 1, sizeof *depth_e), *fd = ori__alloc(((size_t)nf + 1) * sizeof *fd);
                int *creases = ori__alloc(((size_t)nf + 1) * sizeof *creases), nc = 0;
                ori_mechanism_spanning_tree(mech, 0, pf, pe);
                for (int f = 0; f < nf; ++f) {
                    int d = 0;
                    for (int g = f; pf[g] >= 0 && d <= nf; g = pf[g]) d++;
                    fd[f] = d;
                    if (pe[f] >= 0) depth_e[pe[f]] = d, creases[nc++] = pe[f];
                }
                g_depth = depth_e;
                for (int pass = 0; pass < 2 && *order == ORI_FOLD_ORDER_NONE; ++pass) {
                    g_depth_cmp_sign = pass == 0 ? -1 : 1;
                    qsort(creases, (size_t)nc, sizeof *creases, cmp_depth);
                    if (!motion_collides(mech, col, angles, ne, creases, nc, pose, pos, a))
                        *order = pass == 0 ? ORI_FOLD_ORDER_LEAVES_FIRST : ORI_FOLD_ORDER_ROOT_FIRST;
                }
                ori__free(pf), ori__free(pe), ori__free(depth_e), ori__free(fd), ori__free(creases);
            }
            *collides = *order == ORI_FOLD_ORDER_NONE;
            ori__free(a);
            ori_collider_destroy(col);
        }
    }
    ori__free(pos), ori__free(angles);
    ori_mechanism_destroy(mech);
    return worst;
}

// --- congruence classes of nets (for --all) -------------------------------------------------

// A laid-out tree net is one simple outline, every net vertex on it (around any vertex at least
// one edge is cut, else its faces would close a cycle of the tree), and its creases are chords
// between outline corners. Its canonical form: the outline walked with the sheet on the left,
// one token group per outline corner (the length of the edge leaving it, the turn at its end,
// the creases leaving the corner as offsets to their other corner along the outline, in the
// order the walk crosses them), quantised, at the least of its n rotations and n mirrored
// readings. Two nets are congruent (rotation, translation, reflection) exactly when their forms
// are equal, so the classes are a hash set of forms, and no layout is compared twice.

typedef struct outline_ws {
    int *he_edge, *he_twin, *he_next; // per half-edge (corner) of the mesh
    int *corner_of;                   // per outline position: the cut half-edge leaving it
    int *cross_pos, *cross_edge, ncross; // creases crossed, in walk order, with their position
    int *first_pos;                   // per edge: position where first crossed (−1)
    long long *len, *turn;            // per outline position
    int *chord;                       // per crossing: offset to the crease's other corner
    long long *form;                  // the canonical form (tokens)
    int n, form_len;
} outline_ws;

static void outline_ws_init(outline_ws *w, const net_ctx *c)
{
    const ori_mesh *m = c->m;
    int nh = m->fstart[m->nf];
    size_t H = (size_t)nh + 1, E = (size_t)c->ne + 1;
    w->he_edge = ori__alloc(H * sizeof(int)), w->he_twin = ori__alloc(H * sizeof(int)), w->he_next = ori__alloc(H * sizeof(int));
    w->corner_of = ori__alloc(H * sizeof(int)), w->cross_pos = ori__alloc(2 * E * sizeof(int));
    w->cross_edge = ori__alloc(2 * E * sizeof(int)), w->first_pos = ori__alloc(E * sizeof(int));
    w->len = ori__alloc(H * sizeof(long long)), w->turn = ori__alloc(H * sizeof(long long));
    w->chord = ori__alloc(2 * E * sizeof(int));
    w->form = ori__alloc((3 * H + 2 * E) * sizeof(long long));
    for (int k = 0; k < c->ne; ++k) {
        const fedge *x = &c->e[k];
        int a = m->fstart[x->f] + x->fi, b = x->g >= 0 ? m->fstart[x->g] + x->gi : -1;
        w->he_edge[a] = k, w->he_twin[a] = b;
        if (b >= 0) w->he_edge[b] = k, w->he_twin[b] = a;
    }
    for (int f = 0; f < m->nf; ++f)
        for (int i = m->fstart[f]; i < m->fstart[f + 1]; ++i) w->he_next[i] = i + 1 < m->fstart[f + 1] ? i + 1 : m->fstart[f];
}

static void outline_ws_free(outline_ws *w)
{
    ori__free(w->he_edge), ori__free(w->he_twin), ori__free(w->he_next), ori__free(w->corner_of), ori__free(w->cross_pos);
    ori__free(w->cross_edge), ori__free(w->first_pos), ori__free(w->len), ori__free(w->turn), ori__free(w->chord);
    ori__free(w->form);
}

// The tokens of corner i of the outline read from position `start` in direction dir (+1
// along the walk, −1 mirrored: the mirror image walked the other way) into out; returns their
// count: the length of the edge leaving the corner, the turn at that edge's end, the number of
// creases at the corner, their offsets to their other corners.
static int corner_tokens(const outline_ws *w, const int *cstart, int start, int dir, int i, long long *out)
{
    int n = w->n, p = dir > 0 ? start + i : start - i;
    p = p >= n ? p - n : p < 0 ? p + n : p;
    // mirrored, corner p's leaving edge is the walk's edge p − 1, and its turn the walk's at p − 2
    int e = dir > 0 ? p : (p == 0 ? n - 1 : p - 1), tt = dir > 0 ? p : (p >= 2 ? p - 2 : p + n - 2);
    int t = 0, a = cstart[p], b = cstart[p + 1];
    out[t++] = w->len[e];
    out[t++] = w->turn[tt];
    out[t++] = b - a;
    if (dir > 0)
        for (int j = a; j < b; ++j) out[t++] = w->chord[j];
    else
        for (int j = b - 1; j >= a; --j) out[t++] = w->chord[j] ? n - w->chord[j] : 0;
    return t;
}

// Compare the reading (start, dir) with form[0 … len): −1, 0 or 1, generated corner by corner
// and stopped at the first difference (most readings differ in their first tokens).
static int compare_reading(const outline_ws *w, const int *cstart, int start, int dir, const long long *form, int len)
{
    long long g[3 + 64];
    int t = 0;
    for (int i = 0; i < w->n; ++i) {
        int k = corner_tokens(w, cstart, start, dir, i, g);
        for (int j = 0; j < k; ++j, ++t) {
            if (t >= len) return 1;
            if (g[j] != form[t]) return g[j] < form[t] ? -1 : 1;
        }
    }
    return t < len ? -1 : 0;
}

static int write_reading(const outline_ws *w, const int *cstart, int start, int dir, long long *out)
{
    int t = 0;
    for (int i = 0; i < w->n; ++i) t += corner_tokens(w, cstart, start, dir, i, out + t);
    return t;
}

// The canonical form of the laid-out tree net into w->form (w->form_len tokens); false when the
// outline is not one cycle through every cut half-edge (such a layout is not a one-piece net).
static bool net_form(const net_ctx *c, const bool *in_tree, outline_ws *w, int *cstart, double q, double qa)
{
    const ori_mesh *m = c->m;
    int nh = m->fstart[m->nf], cut = 0, start = -1;
    for (int h = 0; h < nh; ++h)
        if (!in_tree[w->he_edge[h]]) {
            cut++;
            if (start < 0) start = h;
        }
    if (start < 0) return false;
    for (int k = 0; k < c->ne; ++k) w->first_pos[k] = -1;
    w->n = 0, w->ncross = 0;
    int h = start;
    do {
        if (w->n >= cut) return false;
        int p = w->n++;
        w->corner_of[p] = h;
        int g = w->he_next[h];
        // around the end corner: cross the creases up to the next cut half-edge, which starts
        // the next outline edge (position p + 1, mod n once n is known)
        while (in_tree[w->he_edge[g]]) {
            w->cross_pos[w->ncross] = p + 1, w->cross_edge[w->ncross++] = w->he_edge[g];
            g = w->he_next[w->he_twin[g]];
        }
        ori_v2 A = c->pos[h], B = c->pos[w->he_next[h]], C = c->pos[w->he_next[g]];
        ori_v2 u = ori_v2_sub(B, A), v = ori_v2_sub(C, B);
        w->len[p] = llround(ori_v2_norm(u) * q);
        w->turn[p] = llround(atan2(u.x * v.y - u.y * v.x, ori_v2_dot(u, v)) * qa);
        h = g;
    } while (h != start);
    if (w->n != cut) return false;
    int n = w->n;
    // crossings in corner order (the walk visits corners in order, so they already are, but for
    // the last edge's end, which is corner 0): rotate that group to the front
    int tail = 0;
    while (tail < w->ncross && w->cross_pos[w->ncross - 1 - tail] == n) tail++;
    for (int i = 0; i < w->ncross; ++i) w->cross_pos[i] %= n;
    if (tail) { // move the last `tail` crossings (corner 0) to the front, keeping their order
        for (int r = 0; r < tail; ++r) {
            int pe = w->cross_pos[w->ncross - 1], ee = w->cross_edge[w->ncross - 1];
            memmove(w->cross_pos + 1, w->cross_pos, (size_t)(w->ncross - 1) * sizeof(int));
            memmove(w->cross_edge + 1, w->cross_edge, (size_t)(w->ncross - 1) * sizeof(int));
            w->cross_pos[0] = pe, w->cross_edge[0] = ee;
        }
    }
    for (int i = 0; i <= n; ++i) cstart[i] = 0;
    for (int i = 0; i < w->ncross; ++i) cstart[w->cross_pos[i] + 1]++;
    for (int i = 0; i < n; ++i) cstart[i + 1] += cstart[i];
    // each crease is crossed twice, once at each of its corners: offsets to the other corner
    for (int i = 0; i < w->ncross; ++i) {
        int k = w->cross_edge[i];
        if (w->first_pos[k] < 0) w->first_pos[k] = i;
    }
    for (int i = 0; i < w->ncross; ++i) {
        int k = w->cross_edge[i], j = w->first_pos[k];
        if (j == i) // the first crossing: the second is the later one of the same edge
            for (int l = i + 1; l < w->ncross; ++l)
                if (w->cross_edge[l] == k) {
                    j = l;
                    break;
                }
        w->chord[i] = ((w->cross_pos[j] - w->cross_pos[i]) % n + n) % n;
    }
    for (int i = 0; i < n; ++i)
        if (cstart[i + 1] - cstart[i] > 64) return false; // (a corner with more creases than a face can have corners)
    w->form_len = write_reading(w, cstart, 0, 1, w->form);
    for (int dir = 1; dir >= -1; dir -= 2)
        for (int s = dir > 0 ? 1 : 0; s < n; ++s)
            if (compare_reading(w, cstart, s, dir, w->form, w->form_len) < 0) w->form_len = write_reading(w, cstart, s, dir, w->form);
    return true;
}

// A set of canonical forms (open addressing on a 64-bit hash; the forms kept for equality).
typedef struct form_set {
    uint64_t *hash;
    long long **form;
    int *len;
    int cap, count;
} form_set;

static uint64_t form_hash(const long long *f, int n)
{
    uint64_t h = 0x9E3779B97F4A7C15u ^ (uint64_t)n;
    for (int i = 0; i < n; ++i) h = ori__mix64(h ^ (uint64_t)f[i]);
    return h;
}

static void form_set_grow(form_set *s)
{
    int cap = s->cap ? 2 * s->cap : 1024;
    form_set t = {ori__calloc((size_t)cap, sizeof(uint64_t)), ori__calloc((size_t)cap, sizeof(long long *)),
                  ori__calloc((size_t)cap, sizeof(int)), cap, s->count};
    for (int i = 0; i < s->cap; ++i) {
        if (!s->form[i]) continue;
        int j = (int)(s->hash[i] & (uint64_t)(cap - 1));
        while (t.form[j]) j = (j + 1) & (cap - 1);
        t.hash[j] = s->hash[i], t.form[j] = s->form[i], t.len[j] = s->len[i];
    }
    ori__free(s->hash), ori__free(s->form), ori__free(s->len);
    *s = t;
}

// Add the form; true when it was new.
static bool form_set_add(form_set *s, const long long *f, int n)
{
    if (2 * (s->count + 1) > s->cap) form_set_grow(s);
    uint64_t h = form_hash(f, n);
    int j = (int)(h & (uint64_t)(s->cap - 1));
    for (; s->form[j]; j = (j + 1) & (s->cap - 1))
        if (s->hash[j] == h && s->len[j] == n && memcmp(s->form[j], f, (size_t)n * sizeof *f) == 0) return false;
    s->hash[j] = h, s->len[j] = n;
    s->form[j] = ori__alloc((size_t)n * sizeof *f + 1);
    memcpy(s->form[j], f, (size_t)n * sizeof *f);
    s->count++;
    return true;
}

static void form_set_free(form_set *s)
{
    for (int i = 0; i < s->cap; ++i) ori__free(s->form[i]);
    ori__free(s->hash), ori__free(s->form), ori__free(s->len);
}

// The number of spanning trees of the face graph (Kirchhoff: a cofactor of its Laplacian, by
// Gaussian elimination with partial pivoting), as a double: exact below 2^53, else rounded;
// INFINITY beyond the double range. For the progress of --all and its "X of Y trees".
static double spanning_tree_count(const net_ctx *c)
{
    int n = c->m->nf - 1;
    if (n <= 0) return 1.0;
    double *L = ori__calloc((size_t)n * (size_t)n, sizeof *L);
    for (int k = 0; k < c->ne; ++k) {
        int a = c->e[k].f, b = c->e[k].g;
        if (b < 0 || a == b) continue;
        if (a < n) L[(size_t)a * n + a] += 1.0;
        if (b < n) L[(size_t)b * n + b] += 1.0;
        if (a < n && b < n) L[(size_t)a * n + b] -= 1.0, L[(size_t)b * n + a] -= 1.0;
    }
    double log_det = 0.0;
    bool singular = false;
    for (int col = 0; col < n && !singular; ++col) {
        int piv = col;
        for (int r = col + 1; r < n; ++r)
            if (fabs(L[(size_t)r * n + col]) > fabs(L[(size_t)piv * n + col])) piv = r;
        double d = L[(size_t)piv * n + col];
        if (d == 0.0) {
            singular = true;
            break;
        }
        if (piv != col)
            for (int j = 0; j < n; ++j) {
                double t = L[(size_t)col * n + j];
                L[(size_t)col * n + j] = L[(size_t)piv * n + j], L[(size_t)piv * n + j] = t;
            }
        log_det += log(fabs(d));
        for (int r = col + 1; r < n; ++r) {
            double f = L[(size_t)r * n + col] / d;
            if (f == 0.0) continue;
            for (int j = col; j < n; ++j) L[(size_t)r * n + j] -= f * L[(size_t)col * n + j];
        }
    }
    ori__free(L);
    if (singular) return 0.0;
    double t = exp(log_det);
    return t < 9007199254740992.0 ? round(t) : t;
}

typedef struct enum_ctx {
    net_ctx *c;
    bool *in_tree;
    int *order, *parent_edge;
    bool *placed;
    int *tri_start, *tri;
    int *uf, *size, *undo, nundo; // the tree's components (union-find with undo)
    int *uf2, *cstart;      // scratch: union-find over faces; outline corners' crossing starts
    outline_ws w;
    form_set forms;
    double q, qa;           // quantisation of lengths (per diagonal) and of turns (per radian)
    double total;           // spanning trees in all (Kirchhoff)
    long long trees, good, limit;
    ori_progress_fn *progress;
    void *progress_user;
    bool stopped;           // the budget or the progress callback ended the enumeration
} enum_ctx;

static void enum_visit(enum_ctx *E)
{
    E->trees++;
    double all = fmin(E->total, (double)E->limit);
    if (E->progress && (E->trees & 4095) == 0 && !E->progress(all > 0.0 ? fmin(1.0, (double)E->trees / all) : 0.0, E->progress_user))
        E->stopped = true;
    ori__net_layout(E->c, E->in_tree, 0, E->order, E->parent_edge, E->placed);
    if (ori__net_count_overlaps(E->c, E->tri_start, E->tri, NULL, 1) > 0) return;
    E->good++;
    if (net_form(E->c, E->in_tree, &E->w, E->cstart, E->q, E->qa)) form_set_add(&E->forms, E->w.form, E->w.form_len);
}

// Whether the faces stay connected through the edges not decided out.
bool ori__net_connected_without(const net_ctx *c, const bool *decided_out, int nf)
{
    int *uf = ori__alloc(((size_t)nf + 1) * sizeof *uf);
    for (int f = 0; f < nf; ++f) uf[f] = f;
    int comps = nf;
    for (int k = 0; k < c->ne; ++k) {
        if (decided_out[k] || c->e[k].g < 0) continue;
        int a = ori__uf_root(uf, c->e[k].f), b = ori__uf_root(uf, c->e[k].g);
        if (a != b) uf[a] = b, comps--;
    }
    ori__free(uf);
    return comps == 1;
}

// The tree's components: a union-find by size without path compression, so that each union
// can be undone in the order made (the enumeration takes and drops edges depth first).
static int tree_root(const enum_ctx *E, int f)
{
    while (E->uf[f] != f) f = E->uf[f];
    return f;
}

// Take edge k into the tree (false: it would close a cycle; nothing changed).
static bool tree_take(enum_ctx *E, int k)
{
    int a = tree_root(E, E->c->e[k].f), b = tree_root(E, E->c->e[k].g);
    if (a == b) return false;
    if (E->size[a] > E->size[b]) {
        int t = a;
        a = b, b = t;
    }
    E->uf[a] = b, E->size[b] += E->size[a];
    E->undo[E->nundo++] = a;
    return true;
}

static void tree_drop(enum_ctx *E)
{
    int a = E->undo[--E->nundo], b = E->uf[a];
    E->uf[a] = a, E->size[b] -= E->size[a];
}

// Whether the tree's components are still joined by the edges after k (all undecided): else
// skipping k leaves the faces apart. From a copy of the tree's union-find.
static bool stays_connected(const enum_ctx *E, int k)
{
    const net_ctx *c = E->c;
    int nf = c->m->nf, *uf = E->uf2, comps = 0;
    for (int f = 0; f < nf; ++f) {
        uf[f] = tree_root(E, f);
        comps += uf[f] == f;
    }
    for (int j = k + 1; j < c->ne && comps > 1; ++j) {
        if (c->e[j].g < 0) continue;
        int a = ori__uf_root(uf, c->e[j].f), b = ori__uf_root(uf, c->e[j].g);
        if (a != b) uf[a] = b, comps--;
    }
    return comps == 1;
}

// Enumerate spanning trees: decide edges in order (take / skip), pruning cycles and skips that
// disconnect the rest; stops at E->limit trees or when the progress callback says so.
static void enum_rec(enum_ctx *E, int k, int taken, bool *out)
{
    if (E->stopped) return;
    if (E->trees >= E->limit) {
        E->stopped = true;
        return;
    }
    int nf = E->c->m->nf;
    if (taken == nf - 1) {
        enum_visit(E);
        return;
    }
    if (k == E->c->ne) return;
    if (E->c->e[k].g < 0) {
        out[k] = true;
        enum_rec(E, k + 1, taken, out);
        out[k] = false;
        return;
    }
    if (tree_take(E, k)) {
        E->in_tree[k] = true;
        enum_rec(E, k + 1, taken + 1, out);
        E->in_tree[k] = false;
        tree_drop(E);
    }
    out[k] = true;
    if (stays_connected(E, k)) enum_rec(E, k + 1, taken, out);
    out[k] = false;
}

// The parent face of f across its parent edge in a layout.
static int parent_face(const net_ctx *c, const int *parent_edge, int f)
{
    int k = parent_edge[f];
    return k < 0 ? -1 : c->e[k].f == f ? c->e[k].g : c->e[k].f;
}

// A tree without overlap whose net touches itself: swap a tree edge for a cut on the cycle the
// cut closes (kept when the net touches itself no more often and overlaps nowhere), up to
// `swaps` times, so that the net comes out in one piece that a FOLD file can hold. Random
// trees find such nets only after hundreds of tries on a box with a hole. Returns the touching
// count of in_tree on return (its layout in c->pos).
static int untouch(net_ctx *c, bool *in_tree, int touching, int swaps, const int *tri_start, const int *tri, int *order,
                   int *parent_edge, bool *placed)
{
    const ori_mesh *m = c->m;
    int nf = m->nf;
    int *depth = ori__alloc(((size_t)nf + 1) * sizeof *depth), *path = ori__alloc(((size_t)nf + 1) * sizeof *path);
    for (int it = 0; it < swaps && touching > 0; ++it) {
        ori__net_layout(c, in_tree, 0, order, parent_edge, placed);
        for (int i = 0; i < nf; ++i) {
            int f = order[i], p = parent_face(c, parent_edge, f);
            depth[f] = p < 0 ? 0 : depth[p] + 1;
        }
        int k = (int)(rnd(c) % (uint64_t)c->ne);
        if (in_tree[k] || c->e[k].g < 0) continue;
        int np = 0;
        for (int a = c->e[k].f, b = c->e[k].g; a != b;) { // the tree path between the cut's faces
            if (depth[a] >= depth[b]) path[np++] = parent_edge[a], a = parent_face(c, parent_edge, a);
            else path[np++] = parent_edge[b], b = parent_face(c, parent_edge, b);
        }
        if (np == 0) continue;
        int r = path[rnd(c) % (uint64_t)np];
        in_tree[k] = true, in_tree[r] = false;
        ori__net_layout(c, in_tree, 0, order, parent_edge, placed);
        int t = ori__net_count_overlaps(c, tri_start, tri, NULL, 1) > 0 ? INT_MAX : count_touching(c);
        if (t <= touching) touching = t;
        else in_tree[k] = false, in_tree[r] = true;
    }
    ori__net_layout(c, in_tree, 0, order, parent_edge, placed);
    ori__free(depth), ori__free(path);
    return touching;
}

// --- the solver ----------------------------------------------------------------------------

static bool tree_spans(const net_ctx *c, const bool *in_tree)
{
    int n = 0;
    for (int k = 0; k < c->ne; ++k) n += in_tree[k];
    return n == c->m->nf - 1;
}

ori_status ori_unfold_solve(const ori_mesh *m, const ori_unfold_def *def, ori_unfold_net **out, ori_error *error)
{
    ORI_ASSERT(m && def && out && def->internal_value == ORI__DEF_COOKIE);
    *out = NULL;
    if (def->tries < 1) return ori__fail(error, ORI_ERR_RANGE, "tries must be at least 1");
    net_ctx c;
    ori__net_ctx_init(&c, m);
    c.rng ^= (uint64_t)def->seed * 0x2545F4914F6CDD1DULL;
    if (!c.rng) c.rng = 1;
    int nf = m->nf;
    // connected?
    bool *none = ori__calloc((size_t)c.ne + 1, 1);
    if (!ori__net_connected_without(&c, none, nf)) {
        ori__free(none);
        ori__net_ctx_free(&c);
        return ori__fail(error, ORI_ERR_TOPOLOGY, "the surface is not connected");
    }
    ori__free(none);
    int *tri_start = ori__alloc(((size_t)nf + 2) * sizeof *tri_start);
    int *tri = ori__alloc(((size_t)m->fstart[nf] + 1) * 3 * sizeof *tri);
    ori__net_build_tris(&c, tri_start, tri);
    bool *in_tree = ori__alloc(((size_t)c.ne + 1) * sizeof *in_tree), *best_tree = ori__alloc(((size_t)c.ne + 1) * sizeof *best_tree);
    double *w = ori__alloc(((size_t)c.ne + 1) * sizeof *w);
    int *order = ori__alloc(((size_t)nf + 1) * sizeof *order), *parent_edge = ori__alloc(((size_t)nf + 1) * sizeof *parent_edge);
    bool *placed = ori__alloc(((size_t)nf + 1) * sizeof *placed);
    // A tree's score: its overlaps first, then the places where the net touches itself
    // (readable only as separate pieces); 0 ends the search.
    int best_overlaps = -1, best_touching = 0, tries = 0, best_try = -1;
    for (int t = 0; t < def->tries; ++t) {
        tries++;
        int kind = t % 3;
        if (kind == 0) {
            double th = 2.0 * 3.141592653589793 * rnd01(&c), z = 2.0 * rnd01(&c) - 1.0, r = sqrt(1.0 - z * z);
            steepest_weights(&c, ori_v3_make(r * cos(th), r * sin(th), z), w);
        } else if (kind == 1) {
            for (int k = 0; k < c.ne; ++k) w[k] = rnd01(&c);
        } else {
            // flat-angle preference: keep creases of small fold angle, random ties
            for (int k = 0; k < c.ne; ++k) w[k] = fabs(c.e[k].angle) + 0.1 * rnd01(&c);
        }
        mst(&c, w, in_tree);
        if (!tree_spans(&c, in_tree)) continue;
        ori__net_layout(&c, in_tree, 0, order, parent_edge, placed);
        int ov = ori__net_count_overlaps(&c, tri_start, tri, NULL, best_overlaps < 0 ? nf * nf : best_overlaps + 1);
        int touching = best_overlaps < 0 || ov <= best_overlaps ? count_touching(&c) : 0;
        if (best_overlaps < 0 || ov < best_overlaps || (ov == best_overlaps && touching < best_touching)) {
            best_overlaps = ov, best_touching = touching, best_try = t;
            memcpy(best_tree, in_tree, (size_t)c.ne * sizeof *in_tree);
        }
        if (ov == 0 && touching == 0) break;
    }
    if (best_overlaps == 0 && best_touching > 0) {
        memcpy(in_tree, best_tree, (size_t)c.ne * sizeof *in_tree);
        best_touching = untouch(&c, in_tree, best_touching, ORI_UNFOLD_UNTOUCH_SWAPS_PER_TRY * def->tries, tri_start, tri,
                                order, parent_edge, placed);
        memcpy(best_tree, in_tree, (size_t)c.ne * sizeof *in_tree);
    }
    ori_unfold_result res;
    memset(&res, 0, sizeof res);
    res.faces = nf;
    res.input_faces = m->src_start[nf];
    res.tries = tries;
    res.distinct_nets = -1;
    res.max_refold_error = -1.0;
    res.fold_order = ORI_FOLD_ORDER_NONE;
    res.interior_vertices = -1;
    res.max_angle_defect_rad = res.max_length_error = res.max_closing_error = res.fold_residual = -1.0;
    // split the best tree into pieces: faces in breadth-first order join their parent's piece
    // unless they overlap a face already there
    int *piece = ori__alloc(((size_t)nf + 1) * sizeof *piece);
    ori__net_layout(&c, best_tree, 0, order, parent_edge, placed);
    int pieces = 1;
    if (best_overlaps == 0 && best_touching == 0) {
        for (int f = 0; f < nf; ++f) piece[f] = 0;
    } else {
        for (int f = 0; f < nf; ++f) piece[f] = -1;
        piece[order[0]] = 0;
        // face boxes to skip pairs far apart
        double *box = ori__alloc(((size_t)nf + 1) * 4 * sizeof *box);
        for (int f = 0; f < nf; ++f) {
            double *b = box + 4 * f;
            b[0] = b[2] = INFINITY, b[1] = b[3] = -INFINITY;
            for (int q = 0; q < ori__net_fsize(m, f); ++q) {
                ori_v2 pq = c.pos[m->fstart[f] + q];
                b[0] = fmin(b[0], pq.x), b[1] = fmax(b[1], pq.x), b[2] = fmin(b[2], pq.y), b[3] = fmax(b[3], pq.y);
            }
        }
        for (int i = 1; i < nf; ++i) {
            int f = order[i], k = parent_edge[f];
            int pf = c.e[k].f == f ? c.e[k].g : c.e[k].f;
            int pp = piece[pf];
            bool clash = false;
            double tol = ORI_TOL_UNFOLD_OVERLAP_REL * m->diag, ctol = ORI_TOL_UNFOLD_CONTACT_REL * m->diag;
            for (int j = 0; j < i && !clash; ++j) {
                int g = order[j];
                if (piece[g] != pp) continue;
                const double *bf = box + 4 * f, *bg = box + 4 * g;
                if (bf[0] > bg[1] + ctol || bg[0] > bf[1] + ctol || bf[2] > bg[3] + ctol || bg[2] > bf[3] + ctol) continue;
                bool apart = bf[0] >= bg[1] - tol || bg[0] >= bf[1] - tol || bf[2] >= bg[3] - tol || bg[2] >= bf[3] - tol;
                clash = (!apart && ori__net_faces_overlap(&c, f, g, tri_start, tri, tol)) || ori__net_faces_touch(&c, f, g);
            }
            if (clash) {
                best_tree[k] = false;
                piece[f] = pieces++;
            } else {
                piece[f] = pp;
            }
        }
        ori__free(box);
        // renumber pieces densely
        int *ren = ori__alloc(((size_t)nf + 1) * sizeof *ren);
        for (int q = 0; q < nf; ++q) ren[q] = -1;
        pieces = 0;
        for (int f = 0; f < nf; ++f) {
            if (ren[piece[f]] < 0) ren[piece[f]] = pieces++;
            piece[f] = ren[piece[f]];
        }
        ori__free(ren);
    }
    res.pieces = pieces;
    res.overlaps = ori__net_count_overlaps(&c, tri_start, tri, piece, nf * nf);
    res.best_try = best_try;
    ori_unfold_net *net = ori__net_make(&c, best_tree, piece, pieces);
    for (int e = 0; e < ori_pattern_edge_count(net->pattern); ++e) res.cuts += net->glue[e] > e; // (closed cuts are creases)
    if (pieces == 1) {
        bool coll = false;
        res.max_refold_error = refold_error(net, m->diag, &coll, &res.fold_order);
        res.motion_collides = coll;
        res.refolded = res.max_refold_error >= 0.0;
    } else {
        ori_build_def bd = ori_default_build_def();
        bd.check_planarity = false;
        ori_error e2;
        ori_pattern_build(net->pattern, &bd, &e2);
    }
    if (def->all) {
        enum_ctx E;
        memset(&E, 0, sizeof E);
        E.c = &c, E.in_tree = in_tree, E.order = order, E.parent_edge = parent_edge, E.placed = placed;
        E.tri_start = tri_start, E.tri = tri, E.limit = def->max_trees;
        E.progress = def->progress, E.progress_user = def->progress_user;
        E.uf = ori__alloc(((size_t)nf + 1) * sizeof *E.uf), E.uf2 = ori__alloc(((size_t)nf + 1) * sizeof *E.uf2);
        E.size = ori__alloc(((size_t)nf + 1) * sizeof *E.size), E.undo = ori__alloc(((size_t)nf + 1) * sizeof *E.undo);
        for (int f = 0; f < nf; ++f) E.uf[f] = f, E.size[f] = 1;
        E.cstart = ori__alloc(((size_t)m->fstart[nf] + 2) * sizeof *E.cstart);
        E.q = ORI_UNFOLD_NET_QUANTA / m->diag, E.qa = ORI_UNFOLD_NET_QUANTA / ORI_PI;
        E.total = spanning_tree_count(&c);
        outline_ws_init(&E.w, &c);
        for (int k = 0; k < c.ne; ++k) in_tree[k] = false;
        bool *outk = ori__calloc((size_t)c.ne + 1, 1);
        enum_rec(&E, 0, 0, outk);
        ori__free(outk);
        res.distinct_nets = E.forms.count;
        res.spanning_trees = E.trees;
        res.overlap_free_trees = E.good;
        res.spanning_trees_total = E.total;
        res.all_complete = !E.stopped;
        form_set_free(&E.forms);
        outline_ws_free(&E.w);
        ori__free(E.uf), ori__free(E.uf2), ori__free(E.size), ori__free(E.undo), ori__free(E.cstart);
    }
    net->result = res;
    ori__free(piece), ori__free(tri_start), ori__free(tri), ori__free(in_tree), ori__free(best_tree), ori__free(w);
    ori__free(order), ori__free(parent_edge), ori__free(placed);
    ori__net_ctx_free(&c);
    *out = net;
    return ORI_OK;
}

void ori_unfold_net_destroy(ori_unfold_net *net)
{
    if (!net) return;
    ori_pattern_destroy(net->pattern);
    ori__free(net->src_start), ori__free(net->src), ori__free(net->glue), ori__free(net->vertex3d), ori__free(net->shape);
    ori__free(net);
}

ori_unfold_result ori_unfold_net_result(const ori_unfold_net *net) { return net->result; }
const ori_pattern *ori_unfold_net_pattern(const ori_unfold_net *net) { return net->pattern; }

int ori_unfold_net_face_source(const ori_unfold_net *net, int face, int *out, int cap)
{
    int n = net->src_start[face + 1] - net->src_start[face];
    for (int i = 0; i < n && i < cap; ++i) out[i] = net->src[net->src_start[face] + i];
    return n;
}

int ori_unfold_net_glue(const ori_unfold_net *net, int edge) { return net->glue[edge]; }
int ori_unfold_net_vertex_source(const ori_unfold_net *net, int vertex) { return net->vertex3d[vertex]; }
ori_v3 ori_unfold_net_vertex_position(const ori_unfold_net *net, int vertex) { return net->shape[vertex]; }
