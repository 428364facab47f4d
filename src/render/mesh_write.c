// Mesh export of a posed state: the format dispatch, and the text formats OBJ, STL and PLY
// (every coordinate in its shortest exact decimal form, so that a file reads back to the posed
// vertex exactly). The surface itself is built by mesh_surface.c.
#include <math.h>
#include <stdio.h>

#include "mesh_write_internal.h"

// --- formats and defaults -------------------------------------------------------------------

ori_mesh_format ori_mesh_format_from_path(const char *path)
{
    const ori_format_info *f = ori_format_find(path, ORI_FORMAT_KIND_MESH);
    return f ? (ori_mesh_format)f->code : ORI_MESH_UNKNOWN;
}

const char *ori_mesh_format_name(ori_mesh_format f) { return ori__format_name(ORI_FORMAT_KIND_MESH, (int)f); }

ori_export_def ori_default_export_def(void)
{
    ori_export_def d;
    memset(&d, 0, sizeof d);
    ori_render_def r = ori_default_render_def();
    d.format = ORI_MESH_GLTF;
    d.thickness = 0.0;
    d.front = r.front;
    d.back = r.back;
    d.edge = (ori_rgb){0.55, 0.55, 0.55};
    d.keyframe_count = 0;
    d.keyframe_times_s = NULL;
    d.keyframe_poses = NULL;
    d.keyframe_positions = NULL;
    d.obj_mtllib = NULL;
    d.face_orders = NULL;
    d.face_order_count = 0;
    d.values = (ori_value_map){NULL, NULL, 0.0, 1.0};
    d.internal_value = ORI__DEF_COOKIE;
    return d;
}

// --- text formats ---------------------------------------------------------------------------

static void put_v3(ori__text *t, ori_v3 v)
{
    ori__text_real(t, v.x);
    ori__text_puts(t, " ");
    ori__text_real(t, v.y);
    ori__text_puts(t, " ");
    ori__text_real(t, v.z);
}

static const char *part_name[ORI__PART_COUNT] = {"front", "back", "rim"};

// OBJ. The sheet keeps FOLD's numbering: OBJ vertex i is FOLD vertex i − 1, with its flat-sheet
// texture coordinate; normals are per face (front, then back); "g front" / "g back" groups use
// materials of the same names, and "# face F" starts each face's triangles. The solid lists its
// own points.
static void write_obj(const ori_mesh *m, const ori_export_def *def, ori__text *t)
{
    ori__text_printf(t, "# orikin %s: posed sheet, %d faces\n", ori_version_string(), m->face_count);
    if (def->obj_mtllib) ori__text_printf(t, "mtllib %s\n", def->obj_mtllib);
    if (!(def->thickness > 0.0)) {
        ori__text_puts(t, "# two-sided sheet: vertex i is FOLD vertex i-1; groups front and back\no sheet\n");
        for (int v = 0; v < m->vertex_count; ++v) {
            ori__text_puts(t, "v ");
            put_v3(t, m->pos[v]);
            ori__text_puts(t, "\n");
        }
        ori__uv_map u = ori__uv_of_mesh(m);
        if (m->has_flat)
            for (int v = 0; v < m->vertex_count; ++v) {
                ori_v2 uv = ori__uv_at(&u, m->ref[v]);
                // OBJ's v runs upwards.
                ori__text_puts(t, "vt ");
                ori__text_real(t, uv.x);
                ori__text_puts(t, " ");
                ori__text_real(t, 1.0 - uv.y);
                ori__text_puts(t, "\n");
            }
        for (int side = 0; side < 2; ++side)
            for (int f = 0; f < m->face_count; ++f) {
                ori__text_puts(t, "vn ");
                put_v3(t, side == 0 ? m->normal[f] : ori_v3_scale(m->normal[f], -1.0));
                ori__text_puts(t, "\n");
            }
        for (int side = 0; side < 2; ++side) {
            ori__text_printf(t, "g %s\nusemtl %s\n", part_name[side], part_name[side]);
            for (int f = 0; f < m->face_count; ++f) {
                ori__text_printf(t, "# face %d\n", f);
                int nidx = side * m->face_count + f + 1;
                for (int tr = m->face_tri_start[f]; tr < m->face_tri_start[f + 1]; ++tr) {
                    int a = m->tris[tr].v[0] + 1, b = m->tris[tr].v[side ? 2 : 1] + 1, c = m->tris[tr].v[side ? 1 : 2] + 1;
                    if (m->has_flat) ori__text_printf(t, "f %d/%d/%d %d/%d/%d %d/%d/%d\n", a, a, nidx, b, b, nidx, c, c, nidx);
                    else ori__text_printf(t, "f %d//%d %d//%d %d//%d\n", a, nidx, b, nidx, c, nidx);
                }
            }
        }
        return;
    }
    ori__xmesh x;
    ori__xmesh_build(m, def, false, &x);
    ori__text_printf(t, "# %s ", ORI_THICK_PANEL_TAG);
    ori__text_real(t, def->thickness);
    ori__text_printf(t, ": %d separate closed panel solids (objects panel_K), %d offset by their layer\n", x.panel_count,
                     x.stacked_panels);
    for (int i = 0; i < ORI__PART_COUNT; ++i)
        for (int v = 0; v < x.part[i].vcount; ++v) {
            ori__text_puts(t, "v ");
            put_v3(t, x.part[i].pos[v]);
            ori__text_puts(t, "\nvn ");
            put_v3(t, x.part[i].nrm[v]);
            ori__text_puts(t, "\n");
        }
    for (int q = 0; q < x.panel_count; ++q) {
        ori__text_printf(t, "o panel_%d\n", q);
        int base = 1;
        for (int i = 0; i < ORI__PART_COUNT; ++i) {
            bool named = false;
            for (int tr = 0; tr < x.part[i].tcount; ++tr) {
                if (x.part[i].panel[tr] != q) continue;
                if (!named) ori__text_printf(t, "g %s\nusemtl %s\n", part_name[i], part_name[i]);
                named = true;
                int a = base + x.part[i].tri[tr][0], b = base + x.part[i].tri[tr][1], c = base + x.part[i].tri[tr][2];
                ori__text_printf(t, "f %d//%d %d//%d %d//%d\n", a, a, b, b, c, c);
            }
            base += x.part[i].vcount;
        }
    }
    ori__xmesh_free(&x);
}

// STL, text: a binary STL holds 32-bit floats only, which would round the posed vertices.
static void put_facet(ori__text *t, ori_v3 a, ori_v3 b, ori_v3 c)
{
    ori_v3 n = ori_v3_normalize(ori_v3_cross(ori_v3_sub(b, a), ori_v3_sub(c, a)));
    ori__text_puts(t, "facet normal ");
    put_v3(t, n);
    ori__text_puts(t, "\n outer loop\n  vertex ");
    put_v3(t, a);
    ori__text_puts(t, "\n  vertex ");
    put_v3(t, b);
    ori__text_puts(t, "\n  vertex ");
    put_v3(t, c);
    ori__text_puts(t, "\n endloop\nendfacet\n");
}

// A thick solid is one "solid" block per panel, named orikin_thick_panel_K and carrying the tag
// and the thickness, so that a reader (and orikin's) sees separate closed solids.
static void write_stl(const ori_mesh *m, const ori_export_def *def, ori__text *t)
{
    ori__xmesh x;
    ori__xmesh_build(m, def, false, &x);
    if (!(def->thickness > 0.0)) {
        ori__text_puts(t, "solid orikin\n");
        for (int i = 0; i < ORI__PART_COUNT; ++i)
            for (int tr = 0; tr < x.part[i].tcount; ++tr)
                put_facet(t, x.part[i].pos[x.part[i].tri[tr][0]], x.part[i].pos[x.part[i].tri[tr][1]],
                          x.part[i].pos[x.part[i].tri[tr][2]]);
        ori__text_puts(t, "endsolid orikin\n");
    } else {
        for (int q = 0; q < x.panel_count; ++q) {
            ori__text_printf(t, "solid orikin_thick_panel_%d %s ", q, ORI_THICK_PANEL_TAG);
            ori__text_real(t, def->thickness);
            ori__text_puts(t, "\n");
            for (int i = 0; i < ORI__PART_COUNT; ++i)
                for (int tr = 0; tr < x.part[i].tcount; ++tr)
                    if (x.part[i].panel[tr] == q)
                        put_facet(t, x.part[i].pos[x.part[i].tri[tr][0]], x.part[i].pos[x.part[i].tri[tr][1]],
                                  x.part[i].pos[x.part[i].tri[tr][2]]);
            ori__text_printf(t, "endsolid orikin_thick_panel_%d\n", q);
        }
    }
    ori__xmesh_free(&x);
}

static int byte_of(double c) { return (int)lround(fmin(1.0, fmax(0.0, c)) * 255.0); }

// PLY, text: doubles, vertex normals and colours (the material of the part), and the FOLD
// vertex of every vertex and FOLD face and side (0 front, 1 back, 2 rim) of every triangle.
static void write_ply(const ori_mesh *m, const ori_export_def *def, ori__text *t)
{
    ori__xmesh x;
    ori__xmesh_build(m, def, false, &x);
    char thick[200] = "";
    if (def->thickness > 0.0) {
        ori__text tt = {NULL, 0, 0};
        ori__text_reserve(&tt, 0);
        ori__text_real(&tt, def->thickness);
        snprintf(thick, sizeof thick, "comment %s %.*s: %d separate closed panel solids (face property panel)\n",
                 ORI_THICK_PANEL_TAG, (int)tt.len, tt.data, x.panel_count);
        ori__free(tt.data);
    }
    int nv = 0, nt = 0;
    for (int i = 0; i < ORI__PART_COUNT; ++i) {
        nv += x.part[i].vcount;
        nt += x.part[i].tcount;
    }
    ori__text_printf(t,
                     "ply\nformat ascii 1.0\ncomment orikin %s: posed sheet, %s\n%s"
                     "element vertex %d\nproperty double x\nproperty double y\nproperty double z\n"
                     "property double nx\nproperty double ny\nproperty double nz\n"
                     "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty int fold_vertex\n"
                     "element face %d\nproperty list uchar int vertex_indices\nproperty int fold_face\n"
                     "property uchar side\n%send_header\n",
                     ori_version_string(), def->thickness > 0.0 ? "closed solid" : "two-sided sheet", thick, nv, nt,
                     def->thickness > 0.0 ? "property int panel\n" : "");
    ori_rgb colour[ORI__PART_COUNT] = {def->front, def->back, def->edge};
    for (int i = 0; i < ORI__PART_COUNT; ++i)
        for (int v = 0; v < x.part[i].vcount; ++v) {
            put_v3(t, x.part[i].pos[v]);
            ori__text_puts(t, " ");
            put_v3(t, x.part[i].nrm[v]);
            ori__text_printf(t, " %d %d %d %d\n", byte_of(colour[i].r), byte_of(colour[i].g), byte_of(colour[i].b),
                             x.part[i].fold_vertex[v]);
        }
    int base = 0;
    for (int i = 0; i < ORI__PART_COUNT; ++i) {
        for (int tr = 0; tr < x.part[i].tcount; ++tr) {
            ori__text_printf(t, "3 %d %d %d %d %d", base + x.part[i].tri[tr][0], base + x.part[i].tri[tr][1],
                             base + x.part[i].tri[tr][2], x.part[i].fold_face[tr], i);
            if (x.part[i].panel) ori__text_printf(t, " %d", x.part[i].panel[tr]);
            ori__text_puts(t, "\n");
        }
        base += x.part[i].vcount;
    }
    ori__xmesh_free(&x);
}

// --- entry points ---------------------------------------------------------------------------

static ori_status check_def(const ori_mesh *m, const ori_export_def *def, ori_error *error)
{
    if (def->format < ORI_MESH_OBJ || def->format > ORI_MESH_GLB)
        return ori__fail(error, ORI_ERR_ARGUMENT, "unknown mesh format (obj, stl, ply, gltf or glb)");
    if (!(def->thickness >= 0.0) || !isfinite(def->thickness))
        return ori__fail(error, ORI_ERR_ARGUMENT, "thickness must be a finite number >= 0");
    if (def->keyframe_count < 0) return ori__fail(error, ORI_ERR_ARGUMENT, "negative keyframe count");
    if (def->face_order_count < 0 || (def->face_order_count > 0 && !def->face_orders))
        return ori__fail(error, ORI_ERR_ARGUMENT, "faceOrders: %d triples without data", def->face_order_count);
    if (def->face_order_count > 0) {
        ori_status st = ori__face_orders_check(m, def->face_orders, def->face_order_count, error);
        if (st != ORI_OK) return st;
    }
    if (def->keyframe_count > 0) {
        if (def->format != ORI_MESH_GLTF && def->format != ORI_MESH_GLB)
            return ori__fail(error, ORI_ERR_ARGUMENT, "only glTF and GLB hold animations");
        if (def->thickness > 0.0)
            return ori__fail(error, ORI_ERR_ARGUMENT, "a thick solid is not rigid per face: it cannot be animated by face nodes");
        if (!def->keyframe_times_s || !def->keyframe_poses == !def->keyframe_positions)
            return ori__fail(error, ORI_ERR_ARGUMENT, "keyframes need times and either face poses or vertex positions");
        for (int k = 0; k < def->keyframe_count; ++k) {
            double tk = def->keyframe_times_s[k];
            if (!isfinite(tk) || (k > 0 && !(tk > def->keyframe_times_s[k - 1])))
                return ori__fail(error, ORI_ERR_ARGUMENT, "keyframe times must be finite and increasing (keyframe %d)", k);
        }
        for (size_t i = 0; def->keyframe_positions && i < (size_t)def->keyframe_count * (size_t)m->vertex_count; ++i) {
            ori_v3 x = def->keyframe_positions[i];
            if (!ori__coord_ok(x.x) || !ori__coord_ok(x.y) || !ori__coord_ok(x.z))
                return ori__fail(error, ORI_ERR_ARGUMENT, "keyframe position %zu is not finite", i);
        }
        for (size_t i = 0; def->keyframe_poses && i < (size_t)def->keyframe_count * (size_t)m->face_count; ++i) {
            ori_rigid g = def->keyframe_poses[i];
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c)
                    if (!isfinite(g.r.m[r][c]))
                        return ori__fail(error, ORI_ERR_ARGUMENT, "keyframe pose %zu is not finite", i);
            if (!ori__coord_ok(g.t.x) || !ori__coord_ok(g.t.y) || !ori__coord_ok(g.t.z))
                return ori__fail(error, ORI_ERR_ARGUMENT, "keyframe pose %zu is not finite", i);
        }
    }
    return ORI_OK;
}

ori_status ori_mesh_export(const ori_mesh *m, const ori_export_def *def, void **data, size_t *size, ori_error *error)
{
    ORI_ASSERT(m && def && data && size);
    ORI_ASSERT(def->internal_value == ORI__DEF_COOKIE);
    *data = NULL;
    *size = 0;
    ori_status st = check_def(m, def, error);
    if (st == ORI_OK) st = ori__value_map_check(&def->values, error);
    if (st != ORI_OK) return st;
    ori__text t = {NULL, 0, 0};
    ori__text_reserve(&t, 0);
    switch (def->format) {
    case ORI_MESH_OBJ: write_obj(m, def, &t); break;
    case ORI_MESH_STL: write_stl(m, def, &t); break;
    case ORI_MESH_PLY: write_ply(m, def, &t); break;
    case ORI_MESH_GLTF: ori__gltf_write(m, def, false, &t); break;
    case ORI_MESH_GLB: ori__gltf_write(m, def, true, &t); break;
    default: break;
    }
    *data = t.data;
    *size = t.len;
    return ORI_OK;
}

ori_status ori_mesh_thick_panels(const ori_mesh *m, const ori_export_def *def, ori_thick_info *out, ori_error *error)
{
    ORI_ASSERT(m && def && out);
    ORI_ASSERT(def->internal_value == ORI__DEF_COOKIE);
    memset(out, 0, sizeof *out);
    ori_status st = check_def(m, def, error);
    if (st != ORI_OK) return st;
    if (!(def->thickness > 0.0)) return ori__fail(error, ORI_ERR_ARGUMENT, "thick panels need a thickness > 0");
    ori__solid s;
    ori__solid_build(m, def->thickness, def->face_orders, def->face_order_count, &s);
    out->panels = s.panel_count;
    out->stacked = s.stacked_panels;
    out->front = s.front_panels;
    out->overlapping = s.overlapping_pairs;
    ori__solid_free(&s);
    return ORI_OK;
}

static void put_rgb(ori__text *t, const char *key, ori_rgb c)
{
    ori__text_printf(t, "%s ", key);
    ori__text_real(t, c.r);
    ori__text_puts(t, " ");
    ori__text_real(t, c.g);
    ori__text_puts(t, " ");
    ori__text_real(t, c.b);
    ori__text_puts(t, "\n");
}

ori_status ori_mesh_export_mtl(const ori_export_def *def, void **data, size_t *size, ori_error *error)
{
    ORI_ASSERT(def && data && size);
    ORI_ASSERT(def->internal_value == ORI__DEF_COOKIE);
    (void)error;
    ori__text t = {NULL, 0, 0};
    ori__text_reserve(&t, 0);
    ori__text_printf(&t, "# orikin %s: materials of the OBJ sheet (front = the side facing +z in the flat sheet)\n",
                     ori_version_string());
    ori_rgb colour[ORI__PART_COUNT] = {def->front, def->back, def->edge};
    for (int i = 0; i < ORI__PART_COUNT; ++i) {
        ori__text_printf(&t, "\nnewmtl %s\n", part_name[i]);
        put_rgb(&t, "Ka", colour[i]);
        put_rgb(&t, "Kd", colour[i]);
        ori__text_puts(&t, "Ks 0 0 0\nd 1\nillum 1\n");
    }
    *data = t.data;
    *size = t.len;
    return ORI_OK;
}

// path with its extension (".obj") replaced by ".mtl"; its base name in *base.
static char *mtl_path_of(const char *path, const char **base)
{
    size_t n = strlen(path);
    char *p = ori__alloc(n + 5);
    memcpy(p, path, n + 1);
    char *dot = strrchr(p, '.');
    char *slash = strrchr(p, '/');
    if (!dot || (slash && dot < slash)) dot = p + n;
    strcpy(dot, ".mtl");
    *base = slash ? p + (slash - p) + 1 : p;
    return p;
}

ori_status ori_mesh_export_file(const ori_mesh *m, const ori_export_def *def, const char *path, ori_error *error)
{
    ORI_ASSERT(def && path);
    ori_export_def d = *def;
    ori_mesh_format by_path = ori_mesh_format_from_path(path);
    if (by_path != ORI_MESH_UNKNOWN) d.format = by_path;
    char *mtl = NULL;
    const char *mtl_base = NULL;
    if (d.format == ORI_MESH_OBJ) {
        mtl = mtl_path_of(path, &mtl_base);
        if (strcmp(mtl, path) == 0) {
            ori__free(mtl); // an OBJ named .mtl: no library beside it
            mtl = NULL;
        } else {
            d.obj_mtllib = mtl_base;
        }
    }
    void *data = NULL, *mdata = NULL;
    size_t size = 0, msize = 0;
    ori_status st = ori_mesh_export(m, &d, &data, &size, error);
    if (st == ORI_OK && mtl) st = ori_mesh_export_mtl(&d, &mdata, &msize, error);
    // The OBJ and its material library are written both or neither: a batch of the caller's,
    // else one of our own (a failure leaves the user's files as they were).
    ori_file_batch *own = NULL, *outer = ori_file_batch_set_current(NULL);
    ori_file_batch_set_current(outer ? outer : (own = ori_file_batch_create()));
    if (st == ORI_OK && mtl) st = ori_file_write_atomic(mtl, mdata, msize, error);
    if (st == ORI_OK) st = ori_file_write_atomic(path, data, size, error);
    ori_file_batch_set_current(outer);
    if (own && st == ORI_OK) st = ori_file_batch_commit(own, error);
    ori_file_batch_destroy(own);
    ori__free(data);
    ori__free(mdata);
    ori__free(mtl);
    return st;
}
