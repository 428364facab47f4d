// Meshes of states (src/render/mesh_write*): OBJ, STL, PLY, glTF and GLB read back to the posed
// vertices, triangle areas sum to the sheet's, thick solids are watertight with volume =
// area × thickness, and animated glTF reproduces every keyframe's vertices from its nodes.
#define _POSIX_C_SOURCE 200809L
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "support.h"

TestSuite(export, .init = test_leak_setup, .fini = test_leak_check);

// --- states -------------------------------------------------------------------------------------

typedef struct state {
    ori_pattern *p;
    ori_v3 *pos;
    double *ang;
} state;

static void state_free(state *s)
{
    ori_pattern_destroy(s->p);
    free(s->pos);
    free(s->ang);
}

// The last frame of a fold of p driving edge `drive` to to_deg (face `fix` fixed, `lock` held).
static state fold_state(ori_pattern *p, int fix, int drive, int lock, double to_deg)
{
    state s = {p, NULL, NULL};
    ori_mechanism *m = test_mechanism_of(p);
    ori_motion_def d = ori_default_motion_def();
    d.fixed_face = fix;
    d.driven_edge = drive;
    d.to_rad = ori_deg_to_rad(to_deg);
    d.step_rad = ori_deg_to_rad(fabs(to_deg) / 4);
    d.locked_edges = lock >= 0 ? &lock : NULL;
    d.locked_count = lock >= 0;
    ori_motion *mo = NULL;
    ori_error err;
    cr_assert_eq(ori_motion_solve(m, &d, &mo, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_motion_verdict_of(mo), ORI_MOTION_VALID, "%s", ori_motion_reason(mo));
    int last = ori_motion_frame_count(mo) - 1;
    int nv = ori_pattern_vertex_count(p), ne = ori_pattern_edge_count(p);
    s.pos = malloc(sizeof(ori_v3) * (size_t)nv);
    s.ang = malloc(sizeof(double) * (size_t)ne);
    ori_motion_frame_vertices(mo, last, s.pos);
    memcpy(s.ang, ori_motion_frame_angles(mo, last), sizeof(double) * (size_t)ne);
    ori_motion_destroy(mo);
    ori_mechanism_destroy(m);
    return s;
}

// The open corner's first fold at 60° (diagonal driven, lower-left triangle fixed).
static state corner_60(void)
{
    test_open_corner c = test_open_corner_load();
    ori_mechanism_destroy(c.m);
    return fold_state(c.p, c.t2, c.diag, c.down, 60.0);
}

// A 4 × 4 Miura-ori folded to 100° by its middle zig-zag crease.
static state miura_100(void)
{
    ori_pattern *p = test_miura(4, 4, 1.0, 1.0, ori_deg_to_rad(60.0), NULL);
    int drive = ori_pattern_find_edge(p, 2 * 5 + 2, 3 * 5 + 2);
    double sg = ori_pattern_edge(p, drive).assignment == ORI_ASSIGN_VALLEY ? 1.0 : -1.0;
    return fold_state(p, 0, drive, -1, sg * 100.0);
}

static state flat_state(ori_pattern *p)
{
    state s = {p, NULL, NULL};
    int nv = ori_pattern_vertex_count(p);
    s.pos = malloc(sizeof(ori_v3) * (size_t)nv);
    for (int v = 0; v < nv; ++v) s.pos[v] = ori_pattern_vertex(p, v);
    return s;
}

// A non-convex (comb-shaped) flat sheet with one face.
static ori_pattern *comb_sheet(void)
{
    static const double comb[][2] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}, {5, 3}, {4, 3}, {4, 1}, {3, 1}, {3, 3},
                                     {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
    int n = (int)(sizeof comb / sizeof comb[0]);
    ori_pattern_def pd = ori_default_pattern_def();
    ori_pattern *p = ori_pattern_create(&pd);
    for (int i = 0; i < n; ++i) ori_pattern_add_vertex(p, ori_v3_make(comb[i][0], comb[i][1], 0));
    for (int i = 0; i < n; ++i) ori_pattern_add_edge(p, i, (i + 1) % n, ORI_ASSIGN_BOUNDARY, 0.0);
    ori_error err;
    ori_build_def bd = ori_default_build_def();
    cr_assert_eq(ori_pattern_build(p, &bd, &err), ORI_OK, "%s", err.message);
    return p;
}

static ori_mesh *mesh_of(const state *s)
{
    ori_state_view sv = {s->p, s->pos, s->ang};
    ori_mesh *m = NULL;
    ori_error err;
    cr_assert_eq(ori_mesh_create(&sv, &m, &err), ORI_OK, "%s", err.message);
    return m;
}

// Export into memory; the text is NUL-terminated for the text formats.
static char *export_text(const ori_mesh *m, ori_mesh_format f, double thickness, size_t *size)
{
    ori_export_def d = ori_default_export_def();
    d.format = f;
    d.thickness = thickness;
    void *data = NULL;
    ori_error err;
    cr_assert_eq(ori_mesh_export(m, &d, &data, size, &err), ORI_OK, "%s", err.message);
    char *t = malloc(*size + 1);
    memcpy(t, data, *size);
    t[*size] = '\0';
    ori_buffer_free(data);
    return t;
}

static double tri_area(ori_v3 a, ori_v3 b, ori_v3 c) { return 0.5 * ori_v3_norm(ori_v3_cross(ori_v3_sub(b, a), ori_v3_sub(c, a))); }

static double diag_of(const state *s)
{
    ori_v3 lo = s->pos[0], hi = s->pos[0];
    for (int v = 1; v < ori_pattern_vertex_count(s->p); ++v) {
        lo = ori_v3_make(fmin(lo.x, s->pos[v].x), fmin(lo.y, s->pos[v].y), fmin(lo.z, s->pos[v].z));
        hi = ori_v3_make(fmax(hi.x, s->pos[v].x), fmax(hi.y, s->pos[v].y), fmax(hi.z, s->pos[v].z));
    }
    return ori_v3_norm(ori_v3_sub(hi, lo));
}

// --- OBJ, STL, PLY ------------------------------------------------------------------------------

// OBJ vertex i is FOLD vertex i − 1, exactly; the front and back groups each hold every
// triangle once, and their areas sum to the sheet's (4).
Test(export, obj_reads_back_to_the_posed_vertices)
{
    state s = corner_60();
    ori_mesh *m = mesh_of(&s);
    size_t size;
    char *t = export_text(m, ORI_MESH_OBJ, 0.0, &size);
    ori_v3 v[64];
    int nv = 0, side = -1, tris[2] = {0, 0};
    double area[2] = {0, 0};
    for (char *line = strtok(t, "\n"); line; line = strtok(NULL, "\n")) {
        if (line[0] == 'v' && line[1] == ' ') {
            cr_assert_eq(sscanf(line + 2, "%lf %lf %lf", &v[nv].x, &v[nv].y, &v[nv].z), 3);
            nv++;
        } else if (strncmp(line, "g front", 7) == 0) side = 0;
        else if (strncmp(line, "g back", 6) == 0) side = 1;
        else if (line[0] == 'f' && line[1] == ' ') {
            int a, b, c, x;
            cr_assert_eq(sscanf(line + 2, "%d/%d/%d %d/%d/%d %d/%d/%d", &a, &x, &x, &b, &x, &x, &c, &x, &x), 9, "%s", line);
            cr_assert_geq(side, 0);
            area[side] += tri_area(v[a - 1], v[b - 1], v[c - 1]);
            tris[side]++;
        }
    }
    cr_assert_eq(nv, ori_pattern_vertex_count(s.p));
    double diag = diag_of(&s);
    for (int i = 0; i < nv; ++i) cr_assert_leq(ori_v3_norm(ori_v3_sub(v[i], s.pos[i])), 1e-9 * diag, "vertex %d", i);
    for (int k = 0; k < 2; ++k) {
        cr_assert_eq(tris[k], ori_mesh_triangle_count(m));
        cr_assert_leq(fabs(area[k] - 4.0), 4.0 * 1e-9, "side %d area %.17g", k, area[k]);
    }
    free(t);
    ori_mesh_destroy(m);
    state_free(&s);
}

// A file OBJ comes with its material library: "mtllib" names the .mtl beside it, and every
// "usemtl" of the OBJ (front, back; rim for a solid) is defined there with the colours asked for.
static char *slurp(const char *path)
{
    char *t = test_read_file(path, NULL);
    cr_assert_not_null(t, "%s", path);
    return t;
}

Test(export, obj_files_name_their_material_library_and_it_defines_every_material)
{
    state s = corner_60();
    ori_mesh *m = mesh_of(&s);
    char *dir = test_tmpdir(), obj[512], mtl[512];
    snprintf(obj, sizeof obj, "%s/corner.obj", dir);
    snprintf(mtl, sizeof mtl, "%s/corner.mtl", dir);
    for (int solid = 0; solid < 2; ++solid) {
        ori_export_def d = ori_default_export_def();
        d.front = (ori_rgb){1.0, 0.0, 0.0};
        d.back = (ori_rgb){0.0, 0.0, 1.0};
        d.thickness = solid ? 0.05 : 0.0;
        ori_error err;
        cr_assert_eq(ori_mesh_export_file(m, &d, obj, &err), ORI_OK, "%s", err.message);
        char *o = slurp(obj), *l = slurp(mtl);
        cr_assert(strstr(o, "\nmtllib corner.mtl\n"), "the OBJ names its library");
        int used = 0;
        for (char *line = strtok(o, "\n"); line; line = strtok(NULL, "\n")) {
            if (strncmp(line, "usemtl ", 7) != 0) continue;
            char want[64];
            snprintf(want, sizeof want, "newmtl %s\n", line + 7);
            cr_assert(strstr(l, want), "%s is defined", line + 7);
            used++;
        }
        // The sheet: front and back; the thick panels: front, back and rim in each panel.
        if (solid) cr_assert(used >= 3 && used % 3 == 0, "%d usemtl lines", used);
        else cr_assert_eq(used, 2);
        cr_assert(strstr(l, "newmtl front\nKa 1 0 0\nKd 1 0 0\n"), "%s", l);
        cr_assert(strstr(l, "newmtl back\nKa 0 0 1\nKd 0 0 1\n"), "%s", l);
        free(o);
        free(l);
    }
    // An OBJ that cannot be written leaves no library behind.
    ori_export_def d = ori_default_export_def();
    ori_error err;
    cr_assert_eq(ori_mesh_export_file(m, &d, "/nonexistent-dir/x.obj", &err), ORI_ERR_IO);
    cr_assert_eq(access("/nonexistent-dir/x.mtl", F_OK), -1);
    // Nor does it touch a library the user has there (it deleted it before: the .mtl was
    // written first, then removed when the OBJ failed).
    char bad[512], mine[512];
    snprintf(bad, sizeof bad, "%s/x.obj", dir);
    snprintf(mine, sizeof mine, "%s/x.mtl", dir);
    FILE *f = fopen(mine, "w");
    cr_assert_not_null(f);
    fputs("mine\n", f);
    fclose(f);
    cr_assert_eq(mkdir(bad, 0700), 0);
    cr_assert_eq(ori_mesh_export_file(m, &d, bad, &err), ORI_ERR_IO);
    char *kept = slurp(mine);
    cr_assert_str_eq(kept, "mine\n");
    free(kept);
    test_tmpdir_remove(dir);
    ori_mesh_destroy(m);
    state_free(&s);
}

typedef struct stl {
    ori_v3 (*tri)[3];
    int n;
} stl;

static stl parse_stl(char *t)
{
    stl s = {NULL, 0};
    int cap = 0, k = 0;
    cr_assert(strncmp(t, "solid", 5) == 0);
    for (char *line = strtok(t, "\n"); line; line = strtok(NULL, "\n")) {
        while (*line == ' ') line++;
        if (strncmp(line, "vertex ", 7) != 0) continue;
        if (k == 0) {
            if (s.n == cap) {
                cap = cap ? 2 * cap : 64;
                s.tri = realloc(s.tri, sizeof *s.tri * (size_t)cap);
            }
        }
        ori_v3 *q = &s.tri[s.n][k];
        cr_assert_eq(sscanf(line + 7, "%lf %lf %lf", &q->x, &q->y, &q->z), 3);
        if (++k == 3) {
            k = 0;
            s.n++;
        }
    }
    return s;
}

// Every STL vertex is a posed vertex exactly; front and back each cover the sheet.
Test(export, stl_reads_back_to_the_posed_vertices)
{
    state s = miura_100();
    ori_mesh *m = mesh_of(&s);
    size_t size;
    char *t = export_text(m, ORI_MESH_STL, 0.0, &size);
    stl st = parse_stl(t);
    cr_assert_eq(st.n, 2 * ori_mesh_triangle_count(m));
    double diag = diag_of(&s), area = 0.0;
    int nv = ori_pattern_vertex_count(s.p);
    for (int i = 0; i < st.n; ++i) {
        area += tri_area(st.tri[i][0], st.tri[i][1], st.tri[i][2]);
        for (int k = 0; k < 3; ++k) {
            double best = INFINITY;
            for (int v = 0; v < nv; ++v) best = fmin(best, ori_v3_norm(ori_v3_sub(st.tri[i][k], s.pos[v])));
            cr_assert_leq(best, 1e-9 * diag, "triangle %d corner %d is %.3g from every posed vertex", i, k, best);
        }
    }
    // Flat area of the Miura: 16 parallelograms 1 × sin 60°.
    double sheet = 16.0 * sin(ori_deg_to_rad(60.0));
    cr_assert_leq(fabs(area / 2 - sheet), sheet * 1e-9, "area %.17g vs %.17g", area / 2, sheet);
    free(st.tri);
    free(t);
    ori_mesh_destroy(m);
    state_free(&s);
}

// PLY keeps the FOLD vertex of every vertex (its coordinates equal the posed vertex) and the
// FOLD face and side of every triangle.
Test(export, ply_keeps_fold_indices)
{
    state s = corner_60();
    ori_mesh *m = mesh_of(&s);
    size_t size;
    char *t = export_text(m, ORI_MESH_PLY, 0.0, &size);
    int nv = 0, nf = 0;
    char *body = strstr(t, "end_header\n");
    cr_assert_not_null(body);
    cr_assert_eq(sscanf(strstr(t, "element vertex"), "element vertex %d", &nv), 1);
    cr_assert_eq(sscanf(strstr(t, "element face"), "element face %d", &nf), 1);
    cr_assert_eq(nf, 2 * ori_mesh_triangle_count(m));
    char *line = strtok(body + strlen("end_header\n"), "\n");
    ori_v3 *v = malloc(sizeof(ori_v3) * (size_t)nv);
    double diag = diag_of(&s);
    for (int i = 0; i < nv; ++i, line = strtok(NULL, "\n")) {
        double n[3];
        int r, g, b, fv;
        cr_assert_eq(sscanf(line, "%lf %lf %lf %lf %lf %lf %d %d %d %d", &v[i].x, &v[i].y, &v[i].z, &n[0], &n[1], &n[2], &r, &g,
                            &b, &fv),
                     10);
        cr_assert_leq(ori_v3_norm(ori_v3_sub(v[i], s.pos[fv])), 1e-9 * diag, "vertex %d (FOLD %d)", i, fv);
        cr_assert_leq(fabs(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1.0), 1e-12);
    }
    double area[2] = {0, 0};
    for (int i = 0; i < nf; ++i, line = strtok(NULL, "\n")) {
        int k, a, b, c, face, side;
        cr_assert_eq(sscanf(line, "%d %d %d %d %d %d", &k, &a, &b, &c, &face, &side), 6);
        cr_assert_eq(k, 3);
        cr_assert(face >= 0 && face < ori_pattern_face_count(s.p));
        cr_assert(side == 0 || side == 1);
        area[side] += tri_area(v[a], v[b], v[c]);
    }
    cr_assert_leq(fabs(area[0] - 4.0), 4e-9);
    cr_assert_leq(fabs(area[1] - 4.0), 4e-9);
    free(v);
    free(t);
    ori_mesh_destroy(m);
    state_free(&s);
}

// Directed edges of an STL keyed by their exact coordinates: every edge of every triangle
// appears once, and once in the opposite direction (a closed, consistently oriented surface).
static int unmatched_edges(const stl *st)
{
    int n = 3 * st->n, bad = 0;
    for (int i = 0; i < n; ++i) {
        ori_v3 a = st->tri[i / 3][i % 3], b = st->tri[i / 3][(i % 3 + 1) % 3];
        int same = 0, reverse = 0;
        for (int j = 0; j < n; ++j) {
            ori_v3 c = st->tri[j / 3][j % 3], d = st->tri[j / 3][(j % 3 + 1) % 3];
            same += a.x == c.x && a.y == c.y && a.z == c.z && b.x == d.x && b.y == d.y && b.z == d.z;
            reverse += a.x == d.x && a.y == d.y && a.z == d.z && b.x == c.x && b.y == c.y && b.z == c.z;
        }
        bad += same != 1 || reverse != 1;
    }
    return bad;
}

static double volume(const stl *st)
{
    double v = 0.0;
    for (int i = 0; i < st->n; ++i) {
        ori_v3 a = st->tri[i][0], b = st->tri[i][1], c = st->tri[i][2];
        v += ori_v3_dot(a, ori_v3_cross(b, c)) / 6.0;
    }
    return v;
}

// The solids of a thick STL: one "solid … endsolid" block each.
static int stl_solids(const char *text, stl **out)
{
    int n = 0;
    *out = NULL;
    for (const char *p = text; (p = strstr(p, "solid ")) != NULL;) {
        if (p != text && p[-1] != '\n') { // "endsolid …"
            p += 6;
            continue;
        }
        const char *end = strstr(p, "endsolid");
        cr_assert(end, "a solid without endsolid");
        size_t len = (size_t)(end - p);
        char *block = malloc(len + 1);
        memcpy(block, p, len);
        block[len] = '\0';
        *out = realloc(*out, sizeof(stl) * (size_t)(n + 1));
        (*out)[n++] = parse_stl(block);
        free(block);
        p = end + 8;
    }
    return n;
}

// Every thick solid is a set of closed panel solids, each watertight (each edge in exactly two
// of its triangles, consistently oriented), whose volumes sum to area × thickness to 1e-9: a
// flat sheet, the open corner folded 60°, a folded Miura-ori, a non-convex sheet.
Test(export, thick_stl_is_watertight_with_the_right_volume)
{
    state states[4] = {flat_state(test_load_pattern(test_repo_path("examples/patterns/open-corner.fold"), 0)), corner_60(),
                       miura_100(), flat_state(comb_sheet())};
    double areas[4] = {4.0, 4.0, 16.0 * sin(ori_deg_to_rad(60.0)), 11.0};
    for (int i = 0; i < 4; ++i) {
        ori_mesh *m = mesh_of(&states[i]);
        double t = 0.05;
        size_t size;
        char *text = export_text(m, ORI_MESH_STL, t, &size);
        stl *sol;
        int n = stl_solids(text, &sol);
        cr_assert_gt(n, 0);
        double vol = 0.0;
        for (int k = 0; k < n; ++k) {
            cr_assert_gt(sol[k].n, 0);
            cr_assert_eq(unmatched_edges(&sol[k]), 0, "state %d solid %d: open or non-manifold edges", i, k);
            double vk = volume(&sol[k]);
            cr_assert_gt(vk, 0.0, "state %d solid %d: inside out", i, k);
            vol += vk;
            free(sol[k].tri);
        }
        free(sol);
        cr_assert_leq(fabs(vol - areas[i] * t), 1e-9 * areas[i] * t, "state %d: volume %.17g, area × thickness %.17g", i, vol,
                      areas[i] * t);
        free(text);
        ori_mesh_destroy(m);
        state_free(&states[i]);
    }
}

// --- thick panels stacked flat --------------------------------------------------------------------

// Separating-axis test of two convex solids given by their triangles: true when some face
// normal or edge cross product separates them (touching within eps counts as separate).
static bool solids_separate(const stl *a, const stl *b, double eps)
{
    const stl *s[2] = {a, b};
    int na = 3 * a->n, nb = 3 * b->n;
    ori_v3 *axes = malloc(sizeof(ori_v3) * (size_t)(a->n + b->n + na * nb));
    int n = 0;
    for (int k = 0; k < 2; ++k)
        for (int i = 0; i < s[k]->n; ++i)
            axes[n++] = ori_v3_cross(ori_v3_sub(s[k]->tri[i][1], s[k]->tri[i][0]), ori_v3_sub(s[k]->tri[i][2], s[k]->tri[i][0]));
    for (int i = 0; i < na; ++i)
        for (int j = 0; j < nb; ++j) {
            ori_v3 ea = ori_v3_sub(a->tri[i / 3][(i % 3 + 1) % 3], a->tri[i / 3][i % 3]);
            ori_v3 eb = ori_v3_sub(b->tri[j / 3][(j % 3 + 1) % 3], b->tri[j / 3][j % 3]);
            axes[n++] = ori_v3_cross(ea, eb);
        }
    bool sep = false;
    for (int k = 0; k < n && !sep; ++k) {
        double len = ori_v3_norm(axes[k]);
        if (!(len > 1e-12)) continue;
        ori_v3 u = ori_v3_scale(axes[k], 1.0 / len);
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        for (int q = 0; q < 2; ++q)
            for (int i = 0; i < s[q]->n; ++i)
                for (int c = 0; c < 3; ++c) {
                    double d = ori_v3_dot(u, s[q]->tri[i][c]);
                    lo[q] = fmin(lo[q], d);
                    hi[q] = fmax(hi[q], d);
                }
        sep = hi[0] <= lo[1] + eps || hi[1] <= lo[0] + eps;
    }
    free(axes);
    return sep;
}

// A Miura-ori of 2 × 2 cells folded flat (180°) by its middle zig-zag crease.
static state miura_flat(void)
{
    ori_pattern *p = test_miura(2, 2, 1.0, 1.0, ori_deg_to_rad(60.0), NULL);
    int drive = ori_pattern_find_edge(p, 1 * 3 + 1, 2 * 3 + 1);
    cr_assert_geq(drive, 0);
    double sg = ori_pattern_edge(p, drive).assignment == ORI_ASSIGN_VALLEY ? 1.0 : -1.0;
    return fold_state(p, 0, drive, -1, sg * 180.0);
}

// Issue 24: the open corner folded to 180° (its two triangles stacked) and a Miura folded flat
// export at t/L = 0.02, 0.05 and 0.1 as closed panel solids (every edge in exactly two triangles
// of its solid), of volume Σ area × t to 1e-6, no two of them overlapping (separating axes:
// every panel here is convex), panels in one plane offset by their layer.
Test(export, thick_panels_stacked_flat_do_not_interpenetrate)
{
    test_open_corner c = test_open_corner_load();
    ori_mechanism_destroy(c.m);
    // orikin fold open-corner.fold --fix 4 --drive 12 --lock 11 --to 180
    state states[2] = {fold_state(c.p, 4, 12, 11, 180.0), miura_flat()};
    double areas[2] = {4.0, 4.0 * sin(ori_deg_to_rad(60.0))};
    int min_stacked[2] = {1, 1};
    const double rel[3] = {0.02, 0.05, 0.1};
    for (int i = 0; i < 2; ++i) {
        ori_mesh *m = mesh_of(&states[i]);
        cr_assert_leq(fabs(ori_mesh_area(m) - areas[i]), 1e-9 * areas[i], "state %d: area %.17g", i, ori_mesh_area(m));
        for (int r = 0; r < 3; ++r) {
            double t = rel[r]; // L = 1: the side of a cell
            ori_export_def d = ori_default_export_def();
            d.thickness = t;
            ori_thick_info info;
            ori_error err;
            cr_assert_eq(ori_mesh_thick_panels(m, &d, &info, &err), ORI_OK, "%s", err.message);
            cr_assert_eq(info.overlapping, 0, "state %d t %g: %d overlapping pairs", i, t, info.overlapping);
            cr_assert_geq(info.stacked, min_stacked[i], "state %d: %d panels stacked", i, info.stacked);
            size_t size;
            char *text = export_text(m, ORI_MESH_STL, t, &size);
            cr_assert(strstr(text, ORI_THICK_PANEL_TAG), "the file names its thick panels");
            stl *sol;
            int n = stl_solids(text, &sol);
            cr_assert_eq(n, info.panels);
            double vol = 0.0;
            for (int k = 0; k < n; ++k) {
                cr_assert_eq(unmatched_edges(&sol[k]), 0, "state %d t %g solid %d: open or non-manifold", i, t, k);
                double vk = volume(&sol[k]);
                cr_assert_gt(vk, 0.0);
                vol += vk;
            }
            cr_assert_leq(fabs(vol - areas[i] * t), 1e-6 * areas[i] * t, "state %d t %g: volume %.17g vs %.17g", i, t, vol,
                          areas[i] * t);
            for (int a = 0; a < n; ++a)
                for (int b = a + 1; b < n; ++b)
                    cr_assert(solids_separate(&sol[a], &sol[b], 1e-9), "state %d t %g: panels %d and %d overlap", i, t, a, b);
            for (int k = 0; k < n; ++k) free(sol[k].tri);
            free(sol);
            free(text);
        }
        ori_mesh_destroy(m);
        state_free(&states[i]);
    }
}

// --- glTF -----------------------------------------------------------------------------------------

typedef struct gltf {
    json_t *root;
    unsigned char *bin;
    size_t bin_len;
} gltf;

static int b64(int c)
{
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    return c == '+' ? 62 : c == '/' ? 63 : -1;
}

static uint32_t le32(const unsigned char *p) { return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24; }

// Parse a .gltf (buffer as a base64 data URI) or a .glb held in memory.
static gltf gltf_parse(const unsigned char *data, size_t size)
{
    gltf g = {NULL, NULL, 0};
    json_error_t je;
    if (size >= 12 && le32(data) == 0x46546C67u) {
        cr_assert_eq(le32(data + 4), 2);
        cr_assert_eq(le32(data + 8), size, "GLB length");
        uint32_t jlen = le32(data + 12);
        cr_assert_eq(le32(data + 16), 0x4E4F534Au);
        g.root = json_loadb((const char *)data + 20, jlen, 0, &je);
        const unsigned char *b = data + 20 + jlen;
        cr_assert_eq(le32(b + 4), 0x004E4942u);
        g.bin_len = le32(b);
        g.bin = malloc(g.bin_len);
        memcpy(g.bin, b + 8, g.bin_len);
    } else {
        g.root = json_loadb((const char *)data, size, 0, &je);
        cr_assert_not_null(g.root, "%s", je.text);
        const char *uri = json_string_value(json_object_get(json_array_get(json_object_get(g.root, "buffers"), 0), "uri"));
        const char *prefix = "data:application/octet-stream;base64,";
        cr_assert(uri && strncmp(uri, prefix, strlen(prefix)) == 0);
        const char *c = uri + strlen(prefix);
        size_t n = strlen(c);
        g.bin = malloc(n);
        uint32_t acc = 0;
        int bits = 0;
        for (size_t i = 0; i < n && c[i] != '='; ++i) {
            int v = b64(c[i]);
            cr_assert_geq(v, 0);
            acc = acc << 6 | (uint32_t)v;
            bits += 6;
            if (bits >= 8) {
                bits -= 8;
                g.bin[g.bin_len++] = (unsigned char)(acc >> bits);
            }
        }
    }
    cr_assert_not_null(g.root);
    cr_assert_str_eq(json_string_value(json_object_get(json_object_get(g.root, "asset"), "version")), "2.0");
    return g;
}

static void gltf_free(gltf *g)
{
    json_decref(g->root);
    free(g->bin);
}

// An accessor's floats (or unsigned ints converted) as doubles, ncomp per element (malloc'd).
static double *accessor(const gltf *g, int index, int *count, int *ncomp)
{
    json_t *a = json_array_get(json_object_get(g->root, "accessors"), (size_t)index);
    cr_assert_not_null(a);
    json_t *bv = json_array_get(json_object_get(g->root, "bufferViews"), (size_t)json_integer_value(json_object_get(a, "bufferView")));
    const char *type = json_string_value(json_object_get(a, "type"));
    int nc = strcmp(type, "SCALAR") == 0 ? 1 : strcmp(type, "VEC2") == 0 ? 2 : strcmp(type, "VEC3") == 0 ? 3 : 4;
    int n = (int)json_integer_value(json_object_get(a, "count"));
    int ct = (int)json_integer_value(json_object_get(a, "componentType"));
    size_t off = (size_t)json_integer_value(json_object_get(bv, "byteOffset")) + (size_t)json_integer_value(json_object_get(a, "byteOffset"));
    json_t *js = json_object_get(bv, "byteStride");
    size_t stride = js ? (size_t)json_integer_value(js) : 4 * (size_t)nc;
    double *out = malloc(sizeof(double) * (size_t)n * (size_t)nc + 1);
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < nc; ++k) {
            const unsigned char *p = g->bin + off + (size_t)i * stride + 4 * (size_t)k;
            cr_assert_leq((size_t)(p - g->bin) + 4, g->bin_len);
            uint32_t u = le32(p);
            if (ct == 5126) {
                float f;
                memcpy(&f, &u, 4);
                out[(size_t)i * nc + k] = f;
            } else {
                out[(size_t)i * nc + k] = u;
            }
        }
    *count = n;
    *ncomp = nc;
    return out;
}

// POSITION + _POSITION_LO of a primitive: the exact coordinates (malloc'd); POSITION alone
// into hi when not NULL (malloc'd).
static ori_v3 *positions_of(const gltf *g, json_t *prim, int *count, ori_v3 **hi)
{
    json_t *attr = json_object_get(prim, "attributes");
    int n, nc, n2, nc2;
    double *h = accessor(g, (int)json_integer_value(json_object_get(attr, "POSITION")), &n, &nc);
    double *l = accessor(g, (int)json_integer_value(json_object_get(attr, "_POSITION_LO")), &n2, &nc2);
    cr_assert_eq(n, n2);
    ori_v3 *p = malloc(sizeof(ori_v3) * (size_t)n + 1);
    if (hi) *hi = malloc(sizeof(ori_v3) * (size_t)n + 1);
    for (int i = 0; i < n; ++i) {
        p[i] = ori_v3_make(h[3 * i] + l[3 * i], h[3 * i + 1] + l[3 * i + 1], h[3 * i + 2] + l[3 * i + 2]);
        if (hi) (*hi)[i] = ori_v3_make(h[3 * i], h[3 * i + 1], h[3 * i + 2]);
    }
    free(h);
    free(l);
    *count = n;
    return p;
}

// glTF and GLB: POSITION + _POSITION_LO equals the posed FOLD vertex named in extras to 1e-9 of
// the sheet (POSITION alone to float precision); each side's triangles cover the sheet; the
// FOLD faces of the triangles are listed.
Test(export, gltf_and_glb_read_back_to_the_posed_vertices)
{
    state s = corner_60();
    ori_mesh *m = mesh_of(&s);
    double diag = diag_of(&s);
    for (int binary = 0; binary < 2; ++binary) {
        ori_export_def d = ori_default_export_def();
        d.format = binary ? ORI_MESH_GLB : ORI_MESH_GLTF;
        void *data = NULL;
        size_t size = 0;
        ori_error err;
        cr_assert_eq(ori_mesh_export(m, &d, &data, &size, &err), ORI_OK, "%s", err.message);
        gltf g = gltf_parse(data, size);
        json_t *prims = json_object_get(json_array_get(json_object_get(g.root, "meshes"), 0), "primitives");
        cr_assert_eq(json_array_size(prims), 2, "front and back");
        for (size_t pi = 0; pi < 2; ++pi) {
            json_t *prim = json_array_get(prims, pi);
            int n;
            ori_v3 *hi = NULL;
            ori_v3 *p = positions_of(&g, prim, &n, &hi);
            json_t *fv = json_object_get(json_object_get(prim, "extras"), "fold_vertices");
            cr_assert_eq((int)json_array_size(fv), n);
            for (int i = 0; i < n; ++i) {
                int v = (int)json_integer_value(json_array_get(fv, (size_t)i));
                cr_assert_leq(ori_v3_norm(ori_v3_sub(p[i], s.pos[v])), 1e-9 * diag, "vertex %d (FOLD %d)", i, v);
                cr_assert_leq(ori_v3_norm(ori_v3_sub(hi[i], s.pos[v])), 1e-7 * diag, "float POSITION %d", i);
            }
            int ni, nc;
            double *idx = accessor(&g, (int)json_integer_value(json_object_get(prim, "indices")), &ni, &nc);
            json_t *ff = json_object_get(json_object_get(prim, "extras"), "fold_faces");
            cr_assert_eq((int)json_array_size(ff) * 3, ni);
            double area = 0.0;
            for (int t = 0; t < ni; t += 3) area += tri_area(p[(int)idx[t]], p[(int)idx[t + 1]], p[(int)idx[t + 2]]);
            cr_assert_leq(fabs(area - 4.0), 4e-9, "side %zu area %.17g", pi, area);
            free(idx);
            free(hi);
            free(p);
        }
        gltf_free(&g);
        ori_buffer_free(data);
    }
    ori_mesh_destroy(m);
    state_free(&s);
}

// A quaternion (x, y, z, w) applied to p.
static ori_v3 quat_apply(const double *q, ori_v3 p)
{
    ori_v3 u = ori_v3_make(q[0], q[1], q[2]);
    double w = q[3];
    ori_v3 t = ori_v3_scale(ori_v3_cross(u, p), 2.0);
    return ori_v3_add(ori_v3_add(p, ori_v3_scale(t, w)), ori_v3_cross(u, t));
}

static void check_animation(const char *path, int keyframes, const double *times, const ori_v3 *const *frames, double diag)
{
    char *data = NULL;
    size_t size = 0;
    ori_error err;
    cr_assert_eq(ori_file_read_all(path, 1 << 28, &data, &size, &err), ORI_OK, "%s", err.message);
    gltf g = gltf_parse((unsigned char *)data, size);
    json_t *anim = json_array_get(json_object_get(g.root, "animations"), 0);
    cr_assert_not_null(anim);
    json_t *nodes = json_object_get(g.root, "nodes"), *meshes = json_object_get(g.root, "meshes");
    json_t *channels = json_object_get(anim, "channels"), *samplers = json_object_get(anim, "samplers");
    int checked = 0;
    for (size_t c = 0; c < json_array_size(channels); ++c) {
        json_t *ch = json_array_get(channels, c);
        if (strcmp(json_string_value(json_object_get(json_object_get(ch, "target"), "path")), "rotation") != 0) continue;
        int node = (int)json_integer_value(json_object_get(json_object_get(ch, "target"), "node"));
        // The node's translation channel.
        json_t *tch = NULL;
        for (size_t c2 = 0; c2 < json_array_size(channels); ++c2) {
            json_t *x = json_array_get(channels, c2);
            json_t *tg = json_object_get(x, "target");
            if (json_integer_value(json_object_get(tg, "node")) == node && strcmp(json_string_value(json_object_get(tg, "path")), "translation") == 0)
                tch = x;
        }
        cr_assert_not_null(tch);
        json_t *rs = json_array_get(samplers, (size_t)json_integer_value(json_object_get(ch, "sampler")));
        json_t *ts = json_array_get(samplers, (size_t)json_integer_value(json_object_get(tch, "sampler")));
        int n, nc, nr, nt, nt2;
        double *tin = accessor(&g, (int)json_integer_value(json_object_get(rs, "input")), &n, &nc);
        double *rot = accessor(&g, (int)json_integer_value(json_object_get(rs, "output")), &nr, &nc);
        double *tra = accessor(&g, (int)json_integer_value(json_object_get(ts, "output")), &nt, &nt2);
        cr_assert_eq(n, keyframes);
        cr_assert_eq(nr, keyframes);
        cr_assert_eq(nt, keyframes);
        for (int k = 0; k < n; ++k) cr_assert_leq(fabs(tin[k] - times[k]), 1e-6 * fmax(1.0, times[k]));
        json_t *nd = json_array_get(nodes, (size_t)node);
        json_t *mesh = json_array_get(meshes, (size_t)json_integer_value(json_object_get(nd, "mesh")));
        json_t *prims = json_object_get(mesh, "primitives");
        for (size_t pi = 0; pi < json_array_size(prims); ++pi) {
            json_t *prim = json_array_get(prims, pi);
            int nv;
            ori_v3 *ref = positions_of(&g, prim, &nv, NULL);
            json_t *fv = json_object_get(json_object_get(prim, "extras"), "fold_vertices");
            for (int k = 0; k < keyframes; ++k)
                for (int i = 0; i < nv; ++i) {
                    int v = (int)json_integer_value(json_array_get(fv, (size_t)i));
                    ori_v3 w = ori_v3_add(quat_apply(rot + 4 * k, ref[i]), ori_v3_make(tra[3 * k], tra[3 * k + 1], tra[3 * k + 2]));
                    cr_assert_leq(ori_v3_norm(ori_v3_sub(w, frames[k][v])), 1e-6 * diag,
                                  "node %d keyframe %d: FOLD vertex %d is %.3g away", node, k, v, ori_v3_norm(ori_v3_sub(w, frames[k][v])));
                    checked++;
                }
            free(ref);
        }
        free(tin);
        free(rot);
        free(tra);
    }
    cr_assert_gt(checked, 0);
    gltf_free(&g);
    ori_buffer_free(data);
}

// `orikin export SEQ.json --animate`: one node per face whose rotation and translation at
// keyframe k carry the face's flat-sheet vertices onto the sequence's recorded state k, to
// 1e-6 of the sheet; keyframe times are the sequence times (one second per fold).
Test(export, animated_gltf_reproduces_every_keyframe)
{
    test_open_corner c = test_open_corner_load();
    ori_sequence *s = NULL;
    ori_error err;
    cr_assert_eq(ori_sequence_load_file(test_repo_path("examples/open-corner.seq.json"), &s, &err), ORI_OK);
    ori_record *r = NULL;
    cr_assert_eq(ori_sequence_run(s, c.m, NULL, ori_rigid_identity(), &r, &err), ORI_OK);
    int K = ori_record_frame_count(r);
    double times[64];
    const ori_v3 *frames[64];
    cr_assert_leq(K, 64);
    for (int k = 0; k < K; ++k) {
        times[k] = ori_record_frame_time(r, k);
        frames[k] = ori_record_frame_vertices(r, k);
    }
    char *dir = test_tmpdir();
    for (int binary = 0; binary < 2; ++binary) {
        char args[1024], path[512];
        snprintf(path, sizeof path, "%s/anim.%s", dir, binary ? "glb" : "gltf");
        snprintf(args, sizeof args, "export examples/open-corner.seq.json --animate -o '%s'", path);
        char *out = NULL;
        cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
        free(out);
        check_animation(path, K, times, frames, 2.0 * sqrt(2.0));
    }
    ori_record_destroy(r);
    ori_sequence_destroy(s);
    test_open_corner_free(&c);
    test_tmpdir_remove(dir);
}

// The same through fold options: the keyframes are the fold's output steps.
Test(export, animated_fold_reproduces_its_steps)
{
    test_open_corner c = test_open_corner_load();
    ori_motion_def d = ori_default_motion_def();
    d.fixed_face = 4;
    d.driven_edge = 12;
    d.to_rad = ori_deg_to_rad(90.0);
    d.step_rad = ori_deg_to_rad(15.0);
    int lock = 11;
    d.locked_edges = &lock;
    d.locked_count = 1;
    ori_motion *mo = NULL;
    ori_error err;
    cr_assert_eq(ori_motion_solve(c.m, &d, &mo, &err), ORI_OK);
    int K = ori_motion_frame_count(mo);
    cr_assert_eq(K, 7);
    ori_v3 pos[7][16];
    const ori_v3 *frames[7];
    double times[7];
    for (int k = 0; k < K; ++k) {
        ori_motion_frame_vertices(mo, k, pos[k]);
        frames[k] = pos[k];
        times[k] = k / 6.0;
    }
    char *dir = test_tmpdir(), args[1024], path[512], *out = NULL;
    snprintf(path, sizeof path, "%s/fold.glb", dir);
    snprintf(args, sizeof args,
             "export examples/patterns/open-corner.fold --fix 4 --drive 12 --lock 11 --to 90 --step 15 --animate -o '%s'", path);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    free(out);
    check_animation(path, K, times, frames, 2.0 * sqrt(2.0));
    ori_motion_destroy(mo);
    test_open_corner_free(&c);
    test_tmpdir_remove(dir);
}

// --- bad input ---------------------------------------------------------------------------------

Test(export, bad_parameters_are_refused_and_nothing_written)
{
    state s = corner_60();
    ori_mesh *m = mesh_of(&s);
    ori_export_def d = ori_default_export_def();
    void *data = NULL;
    size_t size = 0;
    ori_error err;
    d.format = ORI_MESH_UNKNOWN;
    cr_assert_eq(ori_mesh_export(m, &d, &data, &size, &err), ORI_ERR_ARGUMENT);
    d.format = ORI_MESH_STL;
    d.thickness = -1.0;
    cr_assert_eq(ori_mesh_export(m, &d, &data, &size, &err), ORI_ERR_ARGUMENT);
    d.thickness = NAN;
    cr_assert_eq(ori_mesh_export(m, &d, &data, &size, &err), ORI_ERR_ARGUMENT);
    d.thickness = 0.0;
    ori_rigid poses[2 * 5];
    for (int i = 0; i < 10; ++i) poses[i] = ori_rigid_identity();
    double times[2] = {0.0, 1.0};
    d.keyframe_count = 2;
    d.keyframe_times_s = times;
    d.keyframe_poses = poses;
    cr_assert_eq(ori_mesh_export(m, &d, &data, &size, &err), ORI_ERR_ARGUMENT, "keyframes need glTF");
    d.format = ORI_MESH_GLB;
    d.thickness = 0.1;
    cr_assert_eq(ori_mesh_export(m, &d, &data, &size, &err), ORI_ERR_ARGUMENT, "a solid is not animated");
    d.thickness = 0.0;
    times[1] = 0.0;
    cr_assert_eq(ori_mesh_export(m, &d, &data, &size, &err), ORI_ERR_ARGUMENT, "times must increase");
    cr_assert_null(data);
    times[1] = 1.0;
    cr_assert_eq(ori_mesh_export_file(m, &d, "/nonexistent-dir/x.glb", &err), ORI_ERR_IO);
    cr_assert_eq(access("/nonexistent-dir/x.glb", F_OK), -1);
    ori_mesh_destroy(m);
    state_free(&s);
}

// --- reading thick exports back ---------------------------------------------------------------

// orikin's mesh reader sees that a thick export is separate panel solids, and says so in one
// line naming the fix; the thin export of the same state reads back to the same area.
Test(export, thick_exports_are_named_and_refused_by_the_mesh_reader)
{
    state s = corner_60();
    ori_mesh *m = mesh_of(&s);
    char *dir = test_tmpdir(), path[512];
    const char *names[3] = {"thick.stl", "thick.obj", "thin.obj"};
    for (int i = 0; i < 3; ++i) {
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        ori_export_def d = ori_default_export_def();
        d.thickness = i < 2 ? 0.05 : 0.0;
        ori_error err;
        cr_assert_eq(ori_mesh_export_file(m, &d, path, &err), ORI_OK, "%s", err.message);
        char *text = slurp(path);
        if (i < 2) {
            cr_assert(strstr(text, ORI_THICK_PANEL_TAG " 0.05"), "%s names its thick panels", names[i]);
            cr_assert(strstr(text, i == 0 ? "solid orikin_thick_panel_0 " : "\no panel_0\n"), "%s", names[i]);
        }
        free(text);
        ori_mesh *u = NULL;
        ori_status st = ori_unfold_load_mesh(path, &u, &err);
        if (i < 2) {
            cr_assert_eq(st, ORI_ERR_UNSUPPORTED, "%s", names[i]);
            cr_assert(strstr(err.message, "thick export") && strstr(err.message, "without --thickness") &&
                          !strchr(err.message, '\n'),
                      "%s", err.message);
        } else {
            cr_assert_eq(st, ORI_OK, "%s", err.message);
            // The two-sided sheet reads as its front: the sheet's faces (coplanar ones merged).
            cr_assert_geq(ori_unfold_mesh_face_count(u), 1);
            cr_assert_leq(ori_unfold_mesh_face_count(u), ori_pattern_face_count(s.p));
            ori_unfold_mesh_destroy(u);
        }
    }
    test_tmpdir_remove(dir);
    ori_mesh_destroy(m);
    state_free(&s);
}

// The CLI: the folded open corner at 180° exported thick says what it did (4 panels, 1 lifted by
// its layer, none overlapping), and orikin unfold refuses the file in one line, exit 3.
Test(export, cli_thick_export_summary_and_unfold_refusal)
{
    char *dir = test_tmpdir(), args[1024], *out = NULL;
    snprintf(args, sizeof args,
             "fold examples/patterns/open-corner.fold --fix 4 --drive 12 --lock 11 --to 180 -o '%s/oc.fold'", dir);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    free(out);
    snprintf(args, sizeof args, "export '%s/oc.fold' --frame 19 --thickness 0.05 --json -o '%s/oc.stl'", dir, dir);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    cr_assert(strstr(out, "\"panels\":4") && strstr(out, "\"stacked_panels\":1") && strstr(out, "\"overlapping\":0"), "%s",
              out);
    free(out);
    snprintf(args, sizeof args, "unfold '%s/oc.stl' -o '%s/net.svg'", dir, dir);
    cr_assert_eq(test_run_cli(args, &out), 3, "%s", out);
    char *nl = strchr(out, '\n');
    cr_assert(strstr(out, "thick export") && strstr(out, "without --thickness") && nl && nl[1] == '\0', "%s", out);
    free(out);
    test_tmpdir_remove(dir);
}

// --- vertex colours by value -------------------------------------------------------------------

static double lin(double c) { return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4); }

// COLOR_0 of every primitive against face values: each vertex's colour is the linear RGB of
// its face's place on the colour map (float precision, 1e-6); returns the faces whose vertices
// carry the colour of the bar's top (t = 1) as a bit set.
static unsigned check_colours(const gltf *g, const double *values, const ori_value_map *map)
{
    unsigned at_top = 0;
    json_t *prims = json_object_get(json_array_get(json_object_get(g->root, "meshes"), 0), "primitives");
    cr_assert_geq(json_array_size(prims), 1);
    for (size_t pi = 0; pi < json_array_size(prims); ++pi) {
        json_t *prim = json_array_get(prims, pi);
        json_t *ac = json_object_get(json_object_get(prim, "attributes"), "COLOR_0");
        cr_assert_not_null(ac, "primitive %zu has COLOR_0", pi);
        int n, nc, ni, nci;
        double *c = accessor(g, (int)json_integer_value(ac), &n, &nc);
        cr_assert_eq(nc, 3);
        json_t *fv = json_object_get(json_object_get(prim, "extras"), "fold_vertices");
        cr_assert_eq((int)json_array_size(fv), n, "one colour per vertex");
        double *idx = accessor(g, (int)json_integer_value(json_object_get(prim, "indices")), &ni, &nci);
        json_t *ff = json_object_get(json_object_get(prim, "extras"), "fold_faces");
        for (int t = 0; t < ni / 3; ++t) {
            int f = (int)json_integer_value(json_array_get(ff, (size_t)t));
            double tf = ori_value_map_position(map, values[f]);
            ori_rgb want = ori_colormap(tf);
            for (int k = 0; k < 3; ++k) {
                const double *got = c + 3 * (int)idx[3 * t + k];
                cr_assert_float_eq(got[0], lin(want.r), 1e-6, "face %d red", f);
                cr_assert_float_eq(got[1], lin(want.g), 1e-6, "face %d green", f);
                cr_assert_float_eq(got[2], lin(want.b), 1e-6, "face %d blue", f);
            }
            if (tf == 1.0) at_top |= 1u << f;
        }
        free(c);
        free(idx);
    }
    return at_top;
}

// Face values become COLOR_0 in glTF and GLB (white materials, as COLOR_0 is multiplied by the
// base colour); the face of the largest value has the top colour, viridis' yellow (to the fit's
// 2.4/255 before the sRGB → linear step); without values there is no COLOR_0 and the materials
// keep their colours.
Test(export, gltf_face_values_as_vertex_colours)
{
    state s = corner_60();
    ori_mesh *m = mesh_of(&s);
    int F = ori_mesh_face_count(m);
    double *vals = malloc(sizeof(double) * (size_t)F);
    for (int f = 0; f < F; ++f) vals[f] = 0.01 * (f + 1);
    for (int binary = 0; binary < 2; ++binary) {
        ori_export_def d = ori_default_export_def();
        d.format = binary ? ORI_MESH_GLB : ORI_MESH_GLTF;
        d.values = (ori_value_map){vals, NULL, 0.01, 0.01 * F};
        void *data = NULL;
        size_t size = 0;
        ori_error err;
        cr_assert_eq(ori_mesh_export(m, &d, &data, &size, &err), ORI_OK, "%s", err.message);
        gltf g = gltf_parse(data, size);
        cr_assert_eq(check_colours(&g, vals, &d.values), 1u << (F - 1), "only the last face is at the top");
        json_t *mats = json_object_get(g.root, "materials");
        for (size_t i = 0; i < json_array_size(mats); ++i) {
            json_t *bc = json_object_get(json_object_get(json_array_get(mats, i), "pbrMetallicRoughness"), "baseColorFactor");
            for (size_t k = 0; k < 4; ++k) cr_assert_eq(json_real_value(json_array_get(bc, k)) + json_integer_value(json_array_get(bc, k)), 1.0);
        }
        gltf_free(&g);
        ori_buffer_free(data);
    }
    ori_rgb top = ori_colormap(1.0);
    cr_assert_float_eq(top.r, 0.993248, 2.4 / 255);
    cr_assert_float_eq(top.g, 0.906157, 2.4 / 255);
    cr_assert_float_eq(top.b, 0.143936, 2.4 / 255);
    ori_export_def d = ori_default_export_def();
    void *data = NULL;
    size_t size = 0;
    ori_error err;
    cr_assert_eq(ori_mesh_export(m, &d, &data, &size, &err), ORI_OK, "%s", err.message);
    gltf g = gltf_parse(data, size);
    json_t *prim = json_array_get(json_object_get(json_array_get(json_object_get(g.root, "meshes"), 0), "primitives"), 0);
    cr_assert_null(json_object_get(json_object_get(prim, "attributes"), "COLOR_0"));
    json_t *bc = json_object_get(json_object_get(json_array_get(json_object_get(g.root, "materials"), 0), "pbrMetallicRoughness"),
                                 "baseColorFactor");
    cr_assert_lt(json_real_value(json_array_get(bc, 2)), 0.5, "the front keeps its amber");
    gltf_free(&g);
    ori_buffer_free(data);
    // A reversed range is refused.
    d.values = (ori_value_map){vals, NULL, 1.0, 0.0};
    cr_assert_eq(ori_mesh_export(m, &d, &data, &size, &err), ORI_ERR_ARGUMENT);
    free(vals);
    ori_mesh_destroy(m);
    state_free(&s);
}

// orikin export of a compliant fold's frame (orikin fold --compliant -o) writes COLOR_0 by the
// frame's faces_orikin:strain by default, the most strained face at the top colour; --json
// reports the range; --color none leaves the colours out.
Test(export, cli_compliant_frame_exports_strain_colours)
{
    char *dir = test_tmpdir();
    char args[2048], path[1024], *out = NULL;
    ori_fold *doc = test_compliant_open_corner(dir);
    ori_error err;
    char *text = ori_fold_get_custom(doc, 1, "faces_orikin:strain");
    cr_assert_not_null(text);
    json_t *arr = json_loads(text, 0, NULL);
    ori_buffer_free(text);
    int F = (int)json_array_size(arr), top = 0;
    cr_assert_eq(F, 5);
    double fs[5], lo = INFINITY, hi = -INFINITY;
    for (int f = 0; f < F; ++f) {
        fs[f] = json_number_value(json_array_get(arr, (size_t)f));
        lo = fmin(lo, fs[f]);
        hi = fmax(hi, fs[f]);
        if (fs[f] > fs[top]) top = f;
    }
    json_decref(arr);
    ori_fold_destroy(doc);
    snprintf(args, sizeof args, "export '%s/o.fold' --frame 1 --json -o '%s/s.gltf'", dir, dir);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    json_t *rep = json_loads(out, 0, NULL);
    cr_assert_not_null(rep, "%s", out);
    free(out);
    json_t *col = json_object_get(rep, "color");
    cr_assert_eq(json_real_value(json_object_get(col, "max")), hi);
    cr_assert_eq(json_real_value(json_object_get(col, "min")), lo);
    json_decref(rep);
    snprintf(path, sizeof path, "%s/s.gltf", dir);
    char *data = NULL;
    size_t size = 0;
    cr_assert_eq(ori_file_read_all(path, 1 << 28, &data, &size, &err), ORI_OK, "%s", err.message);
    gltf g = gltf_parse((unsigned char *)data, size);
    ori_value_map map = {fs, NULL, lo, hi};
    cr_assert_eq(check_colours(&g, fs, &map), 1u << top, "face %d (strain %g) alone at the top colour", top, hi);
    gltf_free(&g);
    ori_buffer_free(data);
    snprintf(args, sizeof args, "export '%s/o.fold' --frame 1 --color none -o '%s/n.gltf'", dir, dir);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    free(out);
    snprintf(path, sizeof path, "%s/n.gltf", dir);
    char *t = test_read_text(path);
    cr_assert_null(strstr(t, "COLOR_0"), "--color none: no vertex colours");
    free(t);
    test_tmpdir_remove(dir);
}

// A compliant fold's motion (its faces bend) exports as one mesh morphing through the load
// steps: every vertex of keyframe k is the base POSITION plus target k − 1's displacement, equal
// to the load step's vertex to float precision (1e-6 of the sheet); the weights animation has
// keyframe k's target at 1 and the others at 0, at the load steps' times (their fractions).
Test(export, a_compliant_motion_morphs_through_its_load_steps)
{
    char *dir = test_tmpdir(), args[1024], *out = NULL;
    snprintf(args, sizeof args, "export examples/patterns/open-corner.fold --compliant --percent 40 --animate -o '%s/m.glb'", dir);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    cr_assert(strstr(out, "morphing through 9 keyframes"), "%s", out);
    free(out);
    snprintf(args, sizeof args, "fold examples/patterns/open-corner.fold --compliant --percent 40 --all-frames -o '%s/s.fold'", dir);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    free(out);
    char path[600];
    snprintf(path, sizeof path, "%s/s.fold", dir);
    ori_fold *doc = NULL;
    ori_error err;
    cr_assert_eq(ori_fold_load_file(path, &doc, &err), ORI_OK, "%s", err.message);
    int K = ori_fold_frame_count(doc) - 1; // the load steps after the crease pattern
    cr_assert_eq(K, 9);
    ori_v3 *frames[9];
    for (int k = 0; k < K; ++k) frames[k] = NULL;
    int V = 0;
    for (int k = 0; k < K; ++k) {
        ori_build_def bd = ori_default_build_def();
        bd.check_planarity = false;
        ori_pattern *p = NULL;
        cr_assert_eq(ori_fold_get_pattern(doc, k + 1, &bd, &p, &err), ORI_OK, "%s", err.message);
        V = ori_pattern_vertex_count(p);
        frames[k] = malloc(sizeof(ori_v3) * (size_t)V);
        for (int v = 0; v < V; ++v) frames[k][v] = ori_pattern_vertex(p, v);
        ori_pattern_destroy(p);
    }
    char *data = NULL;
    size_t size = 0;
    snprintf(path, sizeof path, "%s/m.glb", dir);
    cr_assert_eq(ori_file_read_all(path, 1 << 28, &data, &size, &err), ORI_OK, "%s", err.message);
    gltf g = gltf_parse((unsigned char *)data, size);
    json_t *mesh = json_array_get(json_object_get(g.root, "meshes"), 0);
    cr_assert_eq(json_array_size(json_object_get(mesh, "weights")), (size_t)(K - 1));
    json_t *prims = json_object_get(mesh, "primitives");
    int checked = 0;
    for (size_t pi = 0; pi < json_array_size(prims); ++pi) {
        json_t *prim = json_array_get(prims, pi), *targets = json_object_get(prim, "targets");
        cr_assert_eq(json_array_size(targets), (size_t)(K - 1));
        int nv;
        ori_v3 *base = positions_of(&g, prim, &nv, NULL);
        json_t *fv = json_object_get(json_object_get(prim, "extras"), "fold_vertices");
        for (int k = 0; k < K; ++k) {
            double *d = NULL;
            int nd = 0, nc = 0;
            if (k > 0) {
                d = accessor(&g, (int)json_integer_value(json_object_get(json_array_get(targets, (size_t)k - 1), "POSITION")), &nd, &nc);
                cr_assert_eq(nd, nv);
            }
            for (int i = 0; i < nv; ++i) {
                int v = (int)json_integer_value(json_array_get(fv, (size_t)i));
                ori_v3 w = base[i];
                if (d) w = ori_v3_add(w, ori_v3_make(d[3 * i], d[3 * i + 1], d[3 * i + 2]));
                cr_assert_leq(ori_v3_norm(ori_v3_sub(w, frames[k][v])), 1e-6 * 2.83, "keyframe %d vertex %d", k, v);
                checked++;
            }
            free(d);
        }
        free(base);
    }
    cr_assert_gt(checked, 0);
    json_t *anim = json_array_get(json_object_get(g.root, "animations"), 0);
    json_t *ch = json_array_get(json_object_get(anim, "channels"), 0);
    cr_assert_str_eq(json_string_value(json_object_get(json_object_get(ch, "target"), "path")), "weights");
    json_t *sm = json_array_get(json_object_get(anim, "samplers"), 0);
    int nt, nc, nw;
    double *t = accessor(&g, (int)json_integer_value(json_object_get(sm, "input")), &nt, &nc);
    double *w = accessor(&g, (int)json_integer_value(json_object_get(sm, "output")), &nw, &nc);
    cr_assert_eq(nt, K);
    cr_assert_eq(nw, K * (K - 1));
    for (int k = 0; k < K; ++k) {
        char *fr = ori_fold_get_custom(doc, k + 1, "orikin:fraction");
        cr_assert_float_eq(t[k], strtod(fr, NULL), 1e-6, "keyframe %d at its fraction", k);
        ori_buffer_free(fr);
        for (int j = 1; j < K; ++j) cr_assert_eq(w[k * (K - 1) + j - 1], j == k ? 1.0 : 0.0);
    }
    free(t);
    free(w);
    gltf_free(&g);
    ori_buffer_free(data);
    for (int k = 0; k < K; ++k) free(frames[k]);
    ori_fold_destroy(doc);
    test_tmpdir_remove(dir);
}
