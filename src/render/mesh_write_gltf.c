// glTF 2.0 and GLB: the posed sheet (or solid) as one mesh, or the whole motion as one node per
// face with rotation and translation keyframes from the exact face poses, or (faces that bend:
// keyframe_positions) as one mesh with a morph target per keyframe after the first and a
// weights animation that shows each keyframe in turn.
//
// glTF stores vertex positions as 32-bit floats. Each position is therefore written twice: as
// POSITION (the float nearest to the coordinate, what every viewer uses) and as the
// application-specific attribute _POSITION_LO (the float nearest to what POSITION misses), so
// that POSITION + _POSITION_LO gives the double coordinate to about 1e-15 of its size. The FOLD
// indices are kept in extras: fold_vertices (per vertex) and fold_faces (per triangle) of every
// primitive, fold_face of every animated node.
//
// With face values (ori_export_def.values) every vertex gets COLOR_0, the linear RGB of its face's
// colour on the colour map (a sheet vertex belongs to one face); the materials are then white, as
// glTF multiplies COLOR_0 by the base colour.
#include <math.h>
#include <stdint.h>

#include "mesh_write_internal.h"

enum { GL_FLOAT = 5126, GL_UNSIGNED_INT = 5125, GL_ARRAY_BUFFER = 34962, GL_ELEMENT_ARRAY_BUFFER = 34963 };

// Buffer views, in the order they are laid out in the buffer.
enum {
    VIEW_POS, VIEW_POS_LO, VIEW_NORMAL, VIEW_UV, VIEW_COLOR, VIEW_INDEX, VIEW_TIME, VIEW_ROTATION, VIEW_TRANSLATION,
    VIEW_MORPH,   // morph targets: position and normal displacements (vec3 each)
    VIEW_WEIGHTS, // the weights animation's output
    VIEW_COUNT
};

// A morph animation (keyframe_positions): the keyframes' vertex positions and face normals.
typedef struct morph {
    int K;
    const ori_v3 *pos; // K × vertex_count
    ori_v3 *normal;    // K × face_count, as the mesh computes its own (area-weighted, unit)
} morph;

typedef struct bytes {
    unsigned char *d;
    size_t n, cap;
} bytes;

static void put_u32(bytes *b, uint32_t x)
{
    if (b->n + 4 > b->cap) {
        size_t cap = b->cap ? b->cap * 2 : 4096;
        while (cap < b->n + 4) cap *= 2;
        b->d = ori__realloc(b->d, cap);
        b->cap = cap;
    }
    // Little-endian, as glTF requires, whatever the host.
    b->d[b->n++] = (unsigned char)(x & 255);
    b->d[b->n++] = (unsigned char)((x >> 8) & 255);
    b->d[b->n++] = (unsigned char)((x >> 16) & 255);
    b->d[b->n++] = (unsigned char)((x >> 24) & 255);
}

// n floats at byte offset at of a buffer already large enough, little-endian.
static void put_floats_at(bytes *b, size_t at, const float *f, int n)
{
    for (int i = 0; i < n; ++i) {
        uint32_t x;
        memcpy(&x, &f[i], 4);
        unsigned char *p = b->d + at + 4 * (size_t)i;
        p[0] = (unsigned char)(x & 255);
        p[1] = (unsigned char)((x >> 8) & 255);
        p[2] = (unsigned char)((x >> 16) & 255);
        p[3] = (unsigned char)((x >> 24) & 255);
    }
}

static void put_f32(bytes *b, float f)
{
    uint32_t x;
    memcpy(&x, &f, 4);
    put_u32(b, x);
}

typedef struct gl {
    const ori_mesh *m;
    const ori_export_def *def;
    bytes view[VIEW_COUNT];
    ori__text acc;    // accessors, comma-separated
    int acc_count;
    int view_index[VIEW_COUNT]; // index of a view in the file (views without data are left out)
    ori__text meshes; // meshes
    int mesh_count;
    bool used_material[ORI__PART_COUNT];
    const morph *mo; // a morph animation, or NULL
} gl;

static void real(ori__text *t, double x) { ori__text_real(t, x); }

static double srgb_to_linear(double c);

// An accessor over the last count elements written to a view (starting at byte offset).
static int accessor(gl *g, int view, size_t offset, int count, const char *type, const float *mn, const float *mx,
                    int ncomp, int component_type)
{
    ori__text *t = &g->acc;
    if (g->acc_count) ori__text_puts(t, ",");
    ORI_ASSERT(g->view_index[view] >= 0);
    ori__text_printf(t, "{\"bufferView\":%d,\"byteOffset\":%zu,\"componentType\":%d,\"count\":%d,\"type\":\"%s\"",
                     g->view_index[view], offset, component_type, count, type);
    if (mn) {
        ori__text_puts(t, ",\"min\":[");
        for (int i = 0; i < ncomp; ++i) {
            if (i) ori__text_puts(t, ",");
            real(t, (double)mn[i]);
        }
        ori__text_puts(t, "],\"max\":[");
        for (int i = 0; i < ncomp; ++i) {
            if (i) ori__text_puts(t, ",");
            real(t, (double)mx[i]);
        }
        ori__text_puts(t, "]");
    }
    ori__text_puts(t, "}");
    return g->acc_count++;
}

// One primitive of a part: its vertices and triangles into the views, its accessors, and its
// JSON (appended to prim).
static void primitive(gl *g, const ori__xpart *p, int part, bool has_uv, ori__text *prim, bool *first)
{
    if (p->tcount == 0) return;
    size_t off_pos = g->view[VIEW_POS].n, off_lo = g->view[VIEW_POS_LO].n, off_n = g->view[VIEW_NORMAL].n;
    size_t off_uv = g->view[VIEW_UV].n, off_i = g->view[VIEW_INDEX].n, off_c = g->view[VIEW_COLOR].n;
    float mn[3] = {INFINITY, INFINITY, INFINITY}, mx[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int v = 0; v < p->vcount; ++v) {
        double c[3] = {p->pos[v].x, p->pos[v].y, p->pos[v].z};
        double n[3] = {p->nrm[v].x, p->nrm[v].y, p->nrm[v].z};
        for (int k = 0; k < 3; ++k) {
            float hi = (float)c[k];
            float lo = (float)(c[k] - (double)hi);
            put_f32(&g->view[VIEW_POS], hi);
            put_f32(&g->view[VIEW_POS_LO], lo);
            put_f32(&g->view[VIEW_NORMAL], (float)n[k]);
            if (hi < mn[k]) mn[k] = hi;
            if (hi > mx[k]) mx[k] = hi;
        }
        if (has_uv) {
            put_f32(&g->view[VIEW_UV], (float)p->uv[v].x);
            put_f32(&g->view[VIEW_UV], (float)p->uv[v].y);
        }
    }
    for (int t = 0; t < p->tcount; ++t)
        for (int k = 0; k < 3; ++k) put_u32(&g->view[VIEW_INDEX], (uint32_t)p->tri[t][k]);
    const ori_value_map *vm = &g->def->values;
    if (vm->face_values) {
        // The face of each vertex: that of a triangle using it (-1: none, the bar's bottom).
        int *vface = ori__alloc(sizeof(int) * (size_t)p->vcount);
        for (int v = 0; v < p->vcount; ++v) vface[v] = -1;
        for (int t = 0; t < p->tcount; ++t)
            for (int k = 0; k < 3; ++k) vface[p->tri[t][k]] = p->fold_face[t];
        for (int v = 0; v < p->vcount; ++v) {
            double val = vface[v] >= 0 ? vm->face_values[vface[v]] : NAN;
            ori_rgb c = ori_colormap(ori_value_map_position(vm, val));
            put_f32(&g->view[VIEW_COLOR], (float)srgb_to_linear(c.r));
            put_f32(&g->view[VIEW_COLOR], (float)srgb_to_linear(c.g));
            put_f32(&g->view[VIEW_COLOR], (float)srgb_to_linear(c.b));
        }
        ori__free(vface);
    }
    int a_pos = accessor(g, VIEW_POS, off_pos, p->vcount, "VEC3", mn, mx, 3, GL_FLOAT);
    int a_lo = accessor(g, VIEW_POS_LO, off_lo, p->vcount, "VEC3", NULL, NULL, 3, GL_FLOAT);
    int a_n = accessor(g, VIEW_NORMAL, off_n, p->vcount, "VEC3", NULL, NULL, 3, GL_FLOAT);
    int a_uv = has_uv ? accessor(g, VIEW_UV, off_uv, p->vcount, "VEC2", NULL, NULL, 2, GL_FLOAT) : -1;
    int a_c = vm->face_values ? accessor(g, VIEW_COLOR, off_c, p->vcount, "VEC3", NULL, NULL, 3, GL_FLOAT) : -1;
    int a_i = accessor(g, VIEW_INDEX, off_i, 3 * p->tcount, "SCALAR", NULL, NULL, 1, GL_UNSIGNED_INT);
    g->used_material[part] = true;
    if (!*first) ori__text_puts(prim, ",");
    *first = false;
    ori__text_printf(prim, "{\"attributes\":{\"POSITION\":%d,\"_POSITION_LO\":%d,\"NORMAL\":%d", a_pos, a_lo, a_n);
    if (a_uv >= 0) ori__text_printf(prim, ",\"TEXCOORD_0\":%d", a_uv);
    if (a_c >= 0) ori__text_printf(prim, ",\"COLOR_0\":%d", a_c);
    ori__text_puts(prim, "}");
    const morph *mo = g->mo;
    if (mo && mo->K > 1) {
        // Keyframe k's target: each vertex's displacement from keyframe 0 (its pattern vertex's
        // position) and its normal's (its face's, with the side's sign).
        int *vface = ori__alloc(sizeof(int) * (size_t)p->vcount);
        for (int v = 0; v < p->vcount; ++v) vface[v] = -1;
        for (int t = 0; t < p->tcount; ++t)
            for (int k = 0; k < 3; ++k) vface[p->tri[t][k]] = p->fold_face[t];
        double side = part == ORI__PART_BACK ? -1.0 : 1.0;
        int V = g->m->vertex_count, F = g->m->face_count;
        ori__text_puts(prim, ",\"targets\":[");
        for (int k = 1; k < mo->K; ++k) {
            size_t off_tp = g->view[VIEW_MORPH].n;
            float tmn[3] = {INFINITY, INFINITY, INFINITY}, tmx[3] = {-INFINITY, -INFINITY, -INFINITY};
            for (int v = 0; v < p->vcount; ++v) {
                ori_v3 a = mo->pos[(size_t)k * V + p->fold_vertex[v]], b = mo->pos[p->fold_vertex[v]];
                float d[3] = {(float)(a.x - b.x), (float)(a.y - b.y), (float)(a.z - b.z)};
                for (int q = 0; q < 3; ++q) {
                    put_f32(&g->view[VIEW_MORPH], d[q]);
                    if (d[q] < tmn[q]) tmn[q] = d[q];
                    if (d[q] > tmx[q]) tmx[q] = d[q];
                }
            }
            size_t off_tn = g->view[VIEW_MORPH].n;
            for (int v = 0; v < p->vcount; ++v) {
                int f = vface[v];
                ori_v3 n = f >= 0 ? ori_v3_scale(mo->normal[(size_t)k * F + f], side) : p->nrm[v];
                put_f32(&g->view[VIEW_MORPH], (float)(n.x - p->nrm[v].x));
                put_f32(&g->view[VIEW_MORPH], (float)(n.y - p->nrm[v].y));
                put_f32(&g->view[VIEW_MORPH], (float)(n.z - p->nrm[v].z));
            }
            int a_tp = accessor(g, VIEW_MORPH, off_tp, p->vcount, "VEC3", tmn, tmx, 3, GL_FLOAT);
            int a_tn = accessor(g, VIEW_MORPH, off_tn, p->vcount, "VEC3", NULL, NULL, 3, GL_FLOAT);
            ori__text_printf(prim, "%s{\"POSITION\":%d,\"NORMAL\":%d}", k > 1 ? "," : "", a_tp, a_tn);
        }
        ori__text_puts(prim, "]");
        ori__free(vface);
    }
    ori__text_printf(prim, ",\"indices\":%d,\"material\":%d,\"mode\":4,\"extras\":{\"side\":\"%s\",\"fold_vertices\":[", a_i,
                     part, part == ORI__PART_FRONT ? "front" : part == ORI__PART_BACK ? "back" : "rim");
    for (int v = 0; v < p->vcount; ++v) {
        if (v) ori__text_puts(prim, ",");
        ori__text_int(prim, p->fold_vertex[v]);
    }
    ori__text_puts(prim, "],\"fold_faces\":[");
    for (int t = 0; t < p->tcount; ++t) {
        if (t) ori__text_puts(prim, ",");
        ori__text_int(prim, p->fold_face[t]);
    }
    ori__text_puts(prim, "]}}");
}

// A mesh of the xmesh's parts; returns its index, or -1 when it has no triangles.
static int mesh_of(gl *g, const ori__xmesh *x, const char *name)
{
    ori__text prim = {NULL, 0, 0};
    ori__text_reserve(&prim, 0);
    bool first = true;
    for (int i = 0; i < ORI__PART_COUNT; ++i) primitive(g, &x->part[i], i, x->has_uv, &prim, &first);
    int idx = -1;
    if (!first) {
        if (g->mesh_count) ori__text_puts(&g->meshes, ",");
        ori__text_puts(&g->meshes, "{\"name\":");
        ori__text_json_string(&g->meshes, name, strlen(name));
        ori__text_puts(&g->meshes, ",\"primitives\":[");
        ori__text_put(&g->meshes, prim.data, prim.len);
        ori__text_puts(&g->meshes, "]");
        if (g->mo && g->mo->K > 1) { // the morph targets' default weights: keyframe 0
            ori__text_puts(&g->meshes, ",\"weights\":[");
            for (int k = 1; k < g->mo->K; ++k) ori__text_puts(&g->meshes, k > 1 ? ",0" : "0");
            ori__text_puts(&g->meshes, "]");
        }
        ori__text_puts(&g->meshes, "}");
        idx = g->mesh_count++;
    }
    ori__free(prim.data);
    return idx;
}

// Unit quaternion (x, y, z, w) of a rotation matrix (Shepperd: the largest diagonal term).
static void quat_of(ori_m3 r, double q[4])
{
    double m00 = r.m[0][0], m11 = r.m[1][1], m22 = r.m[2][2], tr = m00 + m11 + m22;
    double x, y, z, w;
    if (tr > 0.0) {
        double s = 2.0 * sqrt(tr + 1.0);
        w = 0.25 * s;
        x = (r.m[2][1] - r.m[1][2]) / s;
        y = (r.m[0][2] - r.m[2][0]) / s;
        z = (r.m[1][0] - r.m[0][1]) / s;
    } else if (m00 > m11 && m00 > m22) {
        double s = 2.0 * sqrt(1.0 + m00 - m11 - m22);
        w = (r.m[2][1] - r.m[1][2]) / s;
        x = 0.25 * s;
        y = (r.m[0][1] + r.m[1][0]) / s;
        z = (r.m[0][2] + r.m[2][0]) / s;
    } else if (m11 > m22) {
        double s = 2.0 * sqrt(1.0 + m11 - m00 - m22);
        w = (r.m[0][2] - r.m[2][0]) / s;
        x = (r.m[0][1] + r.m[1][0]) / s;
        y = 0.25 * s;
        z = (r.m[1][2] + r.m[2][1]) / s;
    } else {
        double s = 2.0 * sqrt(1.0 + m22 - m00 - m11);
        w = (r.m[1][0] - r.m[0][1]) / s;
        x = (r.m[0][2] + r.m[2][0]) / s;
        y = (r.m[1][2] + r.m[2][1]) / s;
        z = 0.25 * s;
    }
    double n = sqrt(x * x + y * y + z * z + w * w);
    q[0] = x / n;
    q[1] = y / n;
    q[2] = z / n;
    q[3] = w / n;
}

static double srgb_to_linear(double c)
{
    c = fmin(1.0, fmax(0.0, c));
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

// Base64 written piece by piece: up to two bytes wait for the next piece.
typedef struct b64_state {
    unsigned char held[2];
    int nheld;
} b64_state;

static const char b64_tab[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

static void b64_group(char *o, const unsigned char *d, int n)
{
    uint32_t v = (uint32_t)d[0] << 16 | (n > 1 ? (uint32_t)d[1] << 8 : 0) | (n > 2 ? d[2] : 0);
    o[0] = b64_tab[v >> 18];
    o[1] = b64_tab[(v >> 12) & 63];
    o[2] = n > 1 ? b64_tab[(v >> 6) & 63] : '=';
    o[3] = n > 2 ? b64_tab[v & 63] : '=';
}

static void b64_put(ori__text *t, b64_state *st, const unsigned char *d, size_t n)
{
    ori__text_reserve(t, (n + 2) / 3 * 4 + 4);
    char *o = t->data + t->len;
    size_t i = 0;
    while (st->nheld > 0 && st->nheld < 3 && i < n) {
        if (st->nheld == 2) {
            unsigned char g[3] = {st->held[0], st->held[1], d[i++]};
            b64_group(o, g, 3);
            o += 4;
            st->nheld = 0;
        } else {
            st->held[st->nheld++] = d[i++];
        }
    }
    for (; i + 2 < n; i += 3, o += 4) b64_group(o, d + i, 3);
    for (; i < n; ++i) st->held[st->nheld++] = d[i];
    t->len = (size_t)(o - t->data);
    t->data[t->len] = '\0';
}

static void b64_finish(ori__text *t, b64_state *st)
{
    if (st->nheld == 0) return;
    char o[4];
    b64_group(o, st->held, st->nheld);
    ori__text_put(t, o, 4);
    st->nheld = 0;
}

void ori__gltf_write(const ori_mesh *m, const ori_export_def *def, bool binary, ori__text *out)
{
    gl g;
    memset(&g, 0, sizeof g);
    g.m = m;
    g.def = def;
    ori__text_reserve(&g.acc, 0);
    ori__text_reserve(&g.meshes, 0);
    ori__text nodes = {NULL, 0, 0}, anim = {NULL, 0, 0};
    ori__text_reserve(&nodes, 0);
    ori__text_reserve(&anim, 0);
    int K = def->keyframe_count, F = m->face_count;
    bool morphing = K > 0 && def->keyframe_positions;
    morph mo = {K, def->keyframe_positions, NULL};
    if (morphing) {
        mo.normal = ori__alloc(sizeof(ori_v3) * (size_t)K * (size_t)(F > 0 ? F : 1));
        for (int k = 0; k < K; ++k)
            for (int f = 0; f < F; ++f) {
                const ori_v3 *x = mo.pos + (size_t)k * (size_t)m->vertex_count;
                ori_v3 sum = {0, 0, 0};
                for (int t = m->face_tri_start[f]; t < m->face_tri_start[f + 1]; ++t) {
                    ori_v3 a = x[m->tris[t].v[0]], b = x[m->tris[t].v[1]], c = x[m->tris[t].v[2]];
                    sum = ori_v3_add(sum, ori_v3_cross(ori_v3_sub(b, a), ori_v3_sub(c, a)));
                }
                mo.normal[(size_t)k * F + f] = ori_v3_normalize(sum);
            }
        g.mo = &mo;
    }
    // The views that will hold data, numbered in layout order.
    bool poses = K > 0 && !morphing;
    bool present[VIEW_COUNT] = {m->tri_count > 0, m->tri_count > 0, m->tri_count > 0, m->tri_count > 0 && m->has_flat,
                                m->tri_count > 0 && def->values.face_values, m->tri_count > 0, K > 0, poses, poses,
                                morphing && K > 1 && m->tri_count > 0, morphing};
    int nviews = 0;
    for (int v = 0; v < VIEW_COUNT; ++v) g.view_index[v] = present[v] ? nviews++ : -1;
    if (morphing) {
        // Node 0 is the sheet, one mesh posed as keyframe 0; its weights animate: at keyframe k
        // target k has weight 1 and the others 0 (between keyframes the two neighbours blend).
        ori__xmesh x;
        ori__xmesh_build(m, def, false, &x);
        int mi = mesh_of(&g, &x, "sheet");
        ori__xmesh_free(&x);
        ori__text_puts(&nodes, "{\"name\":\"sheet\"");
        if (mi >= 0) ori__text_printf(&nodes, ",\"mesh\":%d", mi);
        ori__text_puts(&nodes, "}");
        size_t off_t = g.view[VIEW_TIME].n, off_w = g.view[VIEW_WEIGHTS].n;
        for (int k = 0; k < K; ++k) put_f32(&g.view[VIEW_TIME], (float)def->keyframe_times_s[k]);
        for (int k = 0; k < K; ++k)
            for (int j = 1; j < K; ++j) put_f32(&g.view[VIEW_WEIGHTS], j == k ? 1.0f : 0.0f);
        if (K == 1) put_f32(&g.view[VIEW_WEIGHTS], 0.0f); // (a view is never empty)
        float t0 = (float)def->keyframe_times_s[0], t1 = (float)def->keyframe_times_s[K - 1];
        int a_time = accessor(&g, VIEW_TIME, off_t, K, "SCALAR", &t0, &t1, 1, GL_FLOAT);
        if (mi >= 0 && K > 1) {
            int a_w = accessor(&g, VIEW_WEIGHTS, off_w, K * (K - 1), "SCALAR", NULL, NULL, 1, GL_FLOAT);
            ori__text_printf(&anim, "{\"name\":\"fold\",\"channels\":[{\"sampler\":0,\"target\":{\"node\":0,\"path\":\"weights\"}}],"
                                    "\"samplers\":[{\"input\":%d,\"output\":%d,\"interpolation\":\"LINEAR\"}]}",
                             a_time, a_w);
        }
    } else if (K == 0) {
        ori__xmesh x;
        ori__xmesh_build(m, def, false, &x);
        int mi = mesh_of(&g, &x, def->thickness > 0.0 ? "solid" : "sheet");
        ori__xmesh_free(&x);
        ori__text_puts(&nodes, "{\"name\":\"sheet\"");
        if (mi >= 0) ori__text_printf(&nodes, ",\"mesh\":%d", mi);
        ori__text_puts(&nodes, "}");
    } else {
        // Node 0 holds the faces; node f + 1 is face f, its mesh in reference coordinates.
        ori__text_puts(&nodes, "{\"name\":\"sheet\",\"children\":[");
        for (int f = 0; f < F; ++f) ori__text_printf(&nodes, "%s%d", f ? "," : "", f + 1);
        ori__text_puts(&nodes, "]}");
        size_t off_t = g.view[VIEW_TIME].n;
        for (int k = 0; k < K; ++k) put_f32(&g.view[VIEW_TIME], (float)def->keyframe_times_s[k]);
        float t0 = (float)def->keyframe_times_s[0], t1 = (float)def->keyframe_times_s[K - 1];
        int a_time = accessor(&g, VIEW_TIME, off_t, K, "SCALAR", &t0, &t1, 1, GL_FLOAT);
        ori__uv_map uv = ori__uv_of_mesh(m);
        ori__text chan = {NULL, 0, 0}, samp = {NULL, 0, 0};
        ori__text_reserve(&chan, 0);
        ori__text_reserve(&samp, 0);
        for (int f = 0; f < F; ++f) {
            ori__xmesh x;
            ori__xmesh_face(m, f, &uv, &x);
            char name[32];
            snprintf(name, sizeof name, "face %d", f);
            int mi = mesh_of(&g, &x, name);
            ori__xmesh_free(&x);
            // Keyframes: face f's rotations and translations are blocks of K values, filled
            // below keyframe by keyframe (the poses are stored keyframe-major).
            size_t off_r = (size_t)f * (size_t)K * 16, off_tr = (size_t)f * (size_t)K * 12;
            double q0[4];
            quat_of(def->keyframe_poses[f].r, q0);
            int a_r = accessor(&g, VIEW_ROTATION, off_r, K, "VEC4", NULL, NULL, 4, GL_FLOAT);
            int a_tr = accessor(&g, VIEW_TRANSLATION, off_tr, K, "VEC3", NULL, NULL, 3, GL_FLOAT);
            ori_rigid p0 = def->keyframe_poses[f];
            ori__text_printf(&nodes, ",{\"name\":\"%s\"", name);
            if (mi >= 0) ori__text_printf(&nodes, ",\"mesh\":%d", mi);
            ori__text_puts(&nodes, ",\"rotation\":[");
            for (int i = 0; i < 4; ++i) {
                if (i) ori__text_puts(&nodes, ",");
                real(&nodes, q0[i]);
            }
            ori__text_puts(&nodes, "],\"translation\":[");
            real(&nodes, p0.t.x);
            ori__text_puts(&nodes, ",");
            real(&nodes, p0.t.y);
            ori__text_puts(&nodes, ",");
            real(&nodes, p0.t.z);
            ori__text_printf(&nodes, "],\"extras\":{\"fold_face\":%d}}", f);
            ori__text_printf(&samp, "%s{\"input\":%d,\"output\":%d,\"interpolation\":\"LINEAR\"},"
                                    "{\"input\":%d,\"output\":%d,\"interpolation\":\"LINEAR\"}",
                             f ? "," : "", a_time, a_r, a_time, a_tr);
            ori__text_printf(&chan, "%s{\"sampler\":%d,\"target\":{\"node\":%d,\"path\":\"rotation\"}},"
                                    "{\"sampler\":%d,\"target\":{\"node\":%d,\"path\":\"translation\"}}",
                             f ? "," : "", 2 * f, f + 1, 2 * f + 1, f + 1);
        }
        // Quaternions kept on one side from keyframe to keyframe (q and −q are one rotation, and
        // a player interpolates between neighbours).
        bytes *vr = &g.view[VIEW_ROTATION], *vt = &g.view[VIEW_TRANSLATION];
        vr->cap = vr->n = (size_t)F * (size_t)K * 16;
        vt->cap = vt->n = (size_t)F * (size_t)K * 12;
        vr->d = ori__alloc(vr->n);
        vt->d = ori__alloc(vt->n);
        double *prev = ori__alloc(sizeof(double) * 4 * (size_t)F);
        for (int k = 0; k < K; ++k)
            for (int f = 0; f < F; ++f) {
                ori_rigid pose = def->keyframe_poses[(size_t)k * (size_t)F + (size_t)f];
                double q[4];
                quat_of(pose.r, q);
                double *pq = prev + 4 * (size_t)f;
                if (k > 0 && q[0] * pq[0] + q[1] * pq[1] + q[2] * pq[2] + q[3] * pq[3] < 0.0)
                    for (int i = 0; i < 4; ++i) q[i] = -q[i];
                memcpy(pq, q, sizeof q);
                float fr[4] = {(float)q[0], (float)q[1], (float)q[2], (float)q[3]};
                float ft[3] = {(float)pose.t.x, (float)pose.t.y, (float)pose.t.z};
                put_floats_at(vr, ((size_t)f * (size_t)K + (size_t)k) * 16, fr, 4);
                put_floats_at(vt, ((size_t)f * (size_t)K + (size_t)k) * 12, ft, 3);
            }
        ori__free(prev);
        ori__text_puts(&anim, "{\"name\":\"fold\",\"channels\":[");
        ori__text_put(&anim, chan.data, chan.len);
        ori__text_puts(&anim, "],\"samplers\":[");
        ori__text_put(&anim, samp.data, samp.len);
        ori__text_puts(&anim, "]}");
        ori__free(chan.data);
        ori__free(samp.data);
    }

    // The buffer: the views one after the other (every element is 4-byte aligned), written
    // straight from the views into the output.
    size_t offset[VIEW_COUNT], total = 0;
    for (int v = 0; v < VIEW_COUNT; ++v) {
        offset[v] = total;
        total += g.view[v].n;
    }

    ori__text j = {NULL, 0, 0};
    ori__text_printf(&j, "{\"asset\":{\"version\":\"2.0\",\"generator\":\"orikin %s\"},", ori_version_string());
    ori__text_puts(&j, "\"extras\":{\"orikin\":");
    ori__text_printf(&j, "{\"faces\":%d,\"vertices\":%d,\"thickness\":", F, m->vertex_count);
    real(&j, def->thickness);
    ori__text_printf(&j, ",\"keyframes\":%d%s}},", K, morphing ? ",\"morph\":true" : "");
    ori__text_puts(&j, "\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[");
    ori__text_put(&j, nodes.data, nodes.len);
    ori__text_puts(&j, "],\"meshes\":[");
    ori__text_put(&j, g.meshes.data, g.meshes.len);
    ori__text_puts(&j, "],\"materials\":[");
    ori_rgb colour[ORI__PART_COUNT] = {def->front, def->back, def->edge};
    if (def->values.face_values)
        for (int i = 0; i < ORI__PART_COUNT; ++i) colour[i] = (ori_rgb){1.0, 1.0, 1.0}; // COLOR_0 carries the colour
    static const char *names[ORI__PART_COUNT] = {"front", "back", "rim"};
    // Front and back always; the rim's material when the solid has one.
    int nmat = g.used_material[ORI__PART_RIM] ? 3 : 2;
    for (int i = 0; i < nmat; ++i) {
        if (i) ori__text_puts(&j, ",");
        ori__text_printf(&j, "{\"name\":\"%s\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[", names[i]);
        real(&j, srgb_to_linear(colour[i].r));
        ori__text_puts(&j, ",");
        real(&j, srgb_to_linear(colour[i].g));
        ori__text_puts(&j, ",");
        real(&j, srgb_to_linear(colour[i].b));
        ori__text_puts(&j, ",1],\"metallicFactor\":0,\"roughnessFactor\":0.85},\"doubleSided\":false}");
    }
    ori__text_puts(&j, "]");
    if (g.acc_count) {
        ori__text_puts(&j, ",\"accessors\":[");
        ori__text_put(&j, g.acc.data, g.acc.len);
        ori__text_puts(&j, "],\"bufferViews\":[");
        static const int stride[VIEW_COUNT] = {12, 12, 12, 8, 12, 0, 0, 0, 0, 12, 0};
        static const int target[VIEW_COUNT] = {GL_ARRAY_BUFFER, GL_ARRAY_BUFFER, GL_ARRAY_BUFFER, GL_ARRAY_BUFFER, GL_ARRAY_BUFFER,
                                               GL_ELEMENT_ARRAY_BUFFER, 0, 0, 0, GL_ARRAY_BUFFER, 0};
        bool first = true;
        for (int v = 0; v < VIEW_COUNT; ++v) {
            if (g.view_index[v] < 0) continue;
            ORI_ASSERT(g.view[v].n > 0);
            if (!first) ori__text_puts(&j, ",");
            first = false;
            ori__text_printf(&j, "{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu", offset[v], g.view[v].n);
            if (stride[v]) ori__text_printf(&j, ",\"byteStride\":%d", stride[v]);
            if (target[v]) ori__text_printf(&j, ",\"target\":%d", target[v]);
            ori__text_puts(&j, "}");
        }
        ori__text_puts(&j, "]");
    }
    if (anim.len > 0) {
        ori__text_puts(&j, ",\"animations\":[");
        ori__text_put(&j, anim.data, anim.len);
        ori__text_puts(&j, "]");
    }
    size_t buf_len = total < 4 ? 4 : total;
    static const unsigned char zero[4] = {0, 0, 0, 0};
    ori__text_printf(&j, ",\"buffers\":[{\"byteLength\":%zu", buf_len);
    if (!binary) {
        ori__text_puts(&j, ",\"uri\":\"data:application/octet-stream;base64,");
        ori__text_reserve(out, j.len + (buf_len + 2) / 3 * 4 + 8);
        ori__text_put(out, j.data, j.len);
        b64_state st = {{0, 0}, 0};
        for (int v = 0; v < VIEW_COUNT; ++v) {
            if (g.view[v].n) b64_put(out, &st, g.view[v].d, g.view[v].n);
            ori__free(g.view[v].d);
            g.view[v].d = NULL;
        }
        if (total < 4) b64_put(out, &st, zero, 4);
        b64_finish(out, &st);
        ori__text_puts(out, "\"}]}");
    } else {
        ori__text_puts(&j, "}]}");
        // GLB: 12-byte header, a JSON chunk padded with spaces, a BIN chunk padded with zeros.
        size_t jlen = (j.len + 3) & ~(size_t)3, blen = (buf_len + 3) & ~(size_t)3;
        size_t whole = 12 + 8 + jlen + 8 + blen;
        ori__text_reserve(out, whole);
        bytes b = {NULL, 0, 0};
        put_u32(&b, 0x46546C67u); // "glTF"
        put_u32(&b, 2);
        put_u32(&b, (uint32_t)whole);
        put_u32(&b, (uint32_t)jlen);
        put_u32(&b, 0x4E4F534Au); // "JSON"
        ori__text_put(out, (const char *)b.d, b.n);
        ori__text_put(out, j.data, j.len);
        for (size_t i = j.len; i < jlen; ++i) ori__text_put(out, " ", 1);
        b.n = 0;
        put_u32(&b, (uint32_t)blen);
        put_u32(&b, 0x004E4942u); // "BIN"
        ori__text_put(out, (const char *)b.d, b.n);
        for (int v = 0; v < VIEW_COUNT; ++v) {
            if (g.view[v].n) ori__text_put(out, (const char *)g.view[v].d, g.view[v].n);
            ori__free(g.view[v].d);
            g.view[v].d = NULL;
        }
        ori__text_put(out, (const char *)zero, blen - total);
        ori__free(b.d);
    }
    ori__free(j.data);
    for (int v = 0; v < VIEW_COUNT; ++v) ori__free(g.view[v].d);
    ori__free(g.acc.data);
    ori__free(g.meshes.data);
    ori__free(nodes.data);
    ori__free(anim.data);
    ori__free(mo.normal);
}
