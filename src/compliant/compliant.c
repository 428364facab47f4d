// The compliant bar-and-hinge model: building it from a flat pattern (faces triangulated by ear
// clipping, bars on every edge and diagonal, crease and facet hinges), the implicit static
// solver (Newton on the total energy, CHOLMOD Cholesky of the Hessian + λI, load stepping over
// the fold fraction, a backtracking line search on the energy), results and frames.
// docs/compliant.md gives the model equation by equation.
#include <float.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>

#include "compliant_internal.h"

// Default largest rest-angle change per load step (10°).
#define CMP_DEFAULT_STEP_RAD (ORI_PI / 18.0)
// Default static equilibrium tolerance, relative to the load scale.
#define CMP_DEFAULT_TOLERANCE 1e-10
// Default Newton iterations per load step.
#define CMP_DEFAULT_ITERATIONS 200
// Roundoff floor of the gradient: this many ε × the largest element force scale.
#define CMP_GRADIENT_FLOOR_EPS 64.0
// Armijo constant of the line search, and its largest number of halvings.
#define CMP_ARMIJO 1e-4
#define CMP_MAX_BACKTRACKS 60
// The explicit time history (keep_frames): a frame every CMP_FIRST_FRAME_INTERVAL steps at first,
// at most CMP_TIME_FRAMES of them (thinned by halves, the interval doubled).
#define CMP_FIRST_FRAME_INTERVAL 16
#define CMP_TIME_FRAMES 256
// Relative energy change below which two energies are equal to roundoff (the line search then
// accepts a step that lowers |∇E|, since the energy can no longer tell).
#define CMP_ENERGY_ROUNDOFF 1e-13
// Filipov et al. 2017's facet bending coefficient (physical preset).
#define CMP_FILIPOV_C 0.55
// A sheet given in another plane than z = 0 is flat when no vertex is farther than this × the
// pattern's diagonal from the faces' mean plane (single-precision exports: 1e-6).
#define CMP_PLANE_REL 1e-6
// Most threads of the explicit solver, and the fewest elements (bars and hinges) a thread gets:
// below, a step takes less time than the threads take to meet.
#define CMP_MAX_THREADS 64
#define CMP_THREAD_ELEMENTS 4096
// Largest change of the wires' current fraction per load step of the static solver.
#define CMP_WIRE_LOAD_STEP (1.0 / 32.0)
// Contact warnings kept (face pairs).
#define CMP_MAX_CONTACTS 256
// Explicit steps between contact checks.
#define CMP_CONTACT_INTERVAL 1024

ori_compliant_def ori_default_compliant_def(void)
{
    ori_compliant_def d;
    memset(&d, 0, sizeof d);
    d.preset = ORI_COMPLIANT_ORIGAMI_SIMULATOR;
    d.axial_stiffness = 20.0;
    d.facet_stiffness = 0.2;
    d.crease_stiffness = 0.7;
    d.young_modulus_pa = 169e9;
    d.poisson_ratio = 0.22;
    d.thickness_m = 1e-6;
    d.density_kg_m3 = 2330.0;
    d.crease_stiffness_per_m = 1e-9;
    d.damping = 0.45;
    d.gravity = 0.0;
    d.fixed_face = ORI_NULL_INDEX;
    d.target_angles_rad = NULL;
    d.fraction = 1.0;
    d.max_step_rad = CMP_DEFAULT_STEP_RAD;
    d.max_iterations = CMP_DEFAULT_ITERATIONS;
    d.tolerance = CMP_DEFAULT_TOLERANCE;
    d.check_contacts = true;
    d.keep_frames = false;
    d.design = NULL;
    d.current_a = 0.0;
    d.field_t = (ori_v3){0.0, 0.0, 0.0};
    d.auto_polarity = true;
    d.threads = 1;
    d.internal_value = ORI__DEF_COOKIE;
    return d;
}

ori_compliant_def ori_compliant_physical_def(void)
{
    ori_compliant_def d = ori_default_compliant_def();
    d.preset = ORI_COMPLIANT_PHYSICAL;
    return d;
}

void ori__cmp_set_trace(ori_compliant *c, ori__cmp_trace_fn *fn, void *user)
{
    c->trace = fn;
    c->trace_user = user;
}

static void free_frame(cmp_frame *f)
{
    ori__free(f->x);
    ori__free(f->angles);
    ori__free(f->strains);
    ori__free(f->face_energy);
    ori__free(f->face_strain);
}

static void free_frames(ori_compliant *c)
{
    for (int k = 0; k < c->nframes; ++k) free_frame(&c->frames[k]);
    c->nframes = 0;
}

// The explicit time history keeps at most CMP_TIME_FRAMES frames: past that, every other frame
// after the first goes and the interval between kept frames doubles (the frames stay evenly
// spaced in time).
static void thin_frames(ori_compliant *c)
{
    int w = 1;
    for (int k = 1; k < c->nframes; ++k) {
        if (k % 2 == 1) free_frame(&c->frames[k]);
        else c->frames[w++] = c->frames[k];
    }
    c->nframes = w;
    c->frame_interval *= 2;
}

void ori_compliant_destroy(ori_compliant *c)
{
    if (!c) return;
    free_frames(c);
    ori__free(c->frames);
    ori__free(c->bars);
    ori__free(c->hinges);
    ori__free(c->tris);
    ori__free(c->tri_face);
    ori__free(c->contacts);
    ori_collider_destroy(c->collider);
    ori_pattern_destroy(c->tri_pattern);
    ori__free(c->edge_bar);
    ori__free(c->edge_hinge);
    ori__free(c->mass);
    ori__free(c->hsec);
    ori__free(c->hfib);
    ori__free(c->hplastic);
    ori__free(c->wires);
    ori__free(c->wpts);
    ori__free(c->dof);
    ori__free(c->x);
    ori__free(c->x0);
    ori__free(c->v);
    ori__free(c->nb_start);
    ori__free(c->nb);
    ori__free(c->colptr);
    ori__free(c->rowind);
    ori__sls_destroy(c->sls);
    ori__free(c);
}

static double cross2(const double *o, const double *a, const double *b)
{
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// Is p strictly inside or on triangle abc (counter-clockwise)?
static bool in_triangle(const double *p, const double *a, const double *b, const double *cc)
{
    return cross2(a, b, p) >= 0.0 && cross2(b, cc, p) >= 0.0 && cross2(cc, a, p) >= 0.0;
}

typedef struct link {
    int a, b, edge;  // edge = pattern edge or -1 (diagonal)
    int tri[2], opp[2];
    int ntri;
} link;

typedef struct builder {
    link *links;
    int nlinks, cap_links;
    int *tris;
    int ntri, cap_tris; // ints (3 per triangle)
    int *tri_face;
    int ntf, cap_tf;    // the face of each triangle
} builder;

static int add_link(builder *bd, int a, int b, int edge)
{
    link l = {a, b, edge, {-1, -1}, {-1, -1}, 0};
    ORI__PUSH(bd->links, bd->nlinks, bd->cap_links, l);
    return bd->nlinks - 1;
}

// Attach triangle t (opposite vertex o) to link k; false when a link has three triangles.
static bool attach(builder *bd, int k, int t, int o)
{
    link *l = &bd->links[k];
    if (l->ntri >= 2) return false;
    l->tri[l->ntri] = t;
    l->opp[l->ntri] = o;
    l->ntri++;
    return true;
}

// Ear clipping of face f (vertex list fv, n vertices) in the flat sheet.
static ori_status triangulate(builder *bd, const ori_pattern *p, int f, int *fv, int n, const double *x,
                              ori_error *error)
{
    int *side = ori__alloc(sizeof(int) * (size_t)n);
    double area = 0.0;
    for (int t = 0; t < n; ++t) {
        const double *a = x + 3 * fv[t], *b = x + 3 * fv[(t + 1) % n];
        area += a[0] * b[1] - a[1] * b[0];
    }
    if (!(fabs(area) > 0.0)) {
        ori__free(side);
        return ori__fail_at(error, ORI_ERR_DEGENERATE, "faces_vertices", f, "face %d has zero area", f);
    }
    if (area < 0.0)
        for (int t = 0; t < n / 2; ++t) {
            int s = fv[t];
            fv[t] = fv[n - 1 - t];
            fv[n - 1 - t] = s;
        }
    for (int t = 0; t < n; ++t) {
        int e = ori_pattern_find_edge(p, fv[t], fv[(t + 1) % n]);
        if (e < 0) {
            ori__free(side);
            return ori__fail_at(error, ORI_ERR_TOPOLOGY, "faces_vertices", f, "face %d: no edge joins vertices %d and %d",
                                f, fv[t], fv[(t + 1) % n]);
        }
        side[t] = e; // pattern edge e is link e
    }
    double scale = fabs(area);
    while (n >= 3) {
        // the ear of the best shape (the largest smallest sine of its angles): sliver triangles
        // give their hinges wing heights near 0, and gradients of the fold angle near 1/0
        int ear = -1;
        double best = -1.0;
        for (int t = 0; t < n; ++t) {
            int pv = fv[(t + n - 1) % n], cv = fv[t], nv = fv[(t + 1) % n];
            const double *a = x + 3 * pv, *b = x + 3 * cv, *cc = x + 3 * nv;
            double twice = cross2(a, b, cc);
            if (!(twice > DBL_EPSILON * scale)) continue;
            bool ok = true;
            for (int s = 0; s < n && ok; ++s) {
                int w = fv[s];
                if (w == pv || w == cv || w == nv) continue;
                if (in_triangle(x + 3 * w, a, b, cc)) ok = false;
            }
            if (!ok) continue;
            double ab = hypot(b[0] - a[0], b[1] - a[1]), bc = hypot(cc[0] - b[0], cc[1] - b[1]);
            double ca = hypot(a[0] - cc[0], a[1] - cc[1]);
            // sin of each angle = 2·area / (product of its two sides)
            double q = fmin(twice / (ab * ca), fmin(twice / (ab * bc), twice / (bc * ca)));
            if (q > best * (1.0 + 1e-12)) {
                best = q;
                ear = t;
            }
        }
        if (ear < 0) {
            ori__free(side);
            return ori__fail_at(error, ORI_ERR_DEGENERATE, "faces_vertices", f,
                                "face %d cannot be triangulated (degenerate or self-intersecting)", f);
        }
        int tp = (ear + n - 1) % n, tn = (ear + 1) % n;
        int pv = fv[tp], cv = fv[ear], nv = fv[tn];
        int t = bd->ntri / 3;
        ORI__PUSH(bd->tris, bd->ntri, bd->cap_tris, pv);
        ORI__PUSH(bd->tris, bd->ntri, bd->cap_tris, cv);
        ORI__PUSH(bd->tris, bd->ntri, bd->cap_tris, nv);
        ORI__PUSH(bd->tri_face, bd->ntf, bd->cap_tf, f);
        int closing = n == 3 ? side[tn] : add_link(bd, pv, nv, -1);
        bool ok = attach(bd, side[tp], t, nv) && attach(bd, side[ear], t, pv) && attach(bd, closing, t, cv);
        if (!ok) {
            ori__free(side);
            return ori__fail_at(error, ORI_ERR_TOPOLOGY, "faces_vertices", f, "an edge of face %d has more than two faces", f);
        }
        if (n == 3) break;
        side[tp] = closing;
        for (int s = ear; s < n - 1; ++s) {
            fv[s] = fv[s + 1];
            side[s] = side[s + 1];
        }
        n--;
    }
    ori__free(side);
    return ORI_OK;
}

// The pattern faces beside a link (face[1] −1 when one, or when both triangles are of one face).
static void link_faces(const ori_compliant *c, const link *l, int face[2])
{
    face[0] = c->tri_face[l->tri[0]];
    face[1] = l->ntri == 2 && c->tri_face[l->tri[1]] != face[0] ? c->tri_face[l->tri[1]] : -1;
}

static bool finite_nonneg(double v) { return isfinite(v) && v >= 0.0; }

static ori_status check_def(const ori_compliant_def *d, ori_error *error)
{
    struct { const char *name; double v; bool positive; } f[] = {
        {"axial_stiffness", d->axial_stiffness, true},   {"facet_stiffness", d->facet_stiffness, false},
        {"crease_stiffness", d->crease_stiffness, false}, {"young_modulus_pa", d->young_modulus_pa, true},
        {"thickness_m", d->thickness_m, true},           {"density_kg_m3", d->density_kg_m3, true},
        {"crease_stiffness_per_m", d->crease_stiffness_per_m, false}, {"damping", d->damping, false},
        {"max_step_rad", d->max_step_rad, true},         {"tolerance", d->tolerance, true},
    };
    for (size_t k = 0; k < sizeof f / sizeof f[0]; ++k)
        if (!finite_nonneg(f[k].v) || (f[k].positive && !(f[k].v > 0.0)))
            return ori__fail(error, ORI_ERR_RANGE, "compliant: %s must be finite and %s (got %g)", f[k].name,
                             f[k].positive ? "> 0" : "≥ 0", f[k].v);
    if (!isfinite(d->gravity)) return ori__fail(error, ORI_ERR_RANGE, "compliant: gravity must be finite");
    if (!(d->poisson_ratio > -1.0 && d->poisson_ratio < 0.5))
        return ori__fail(error, ORI_ERR_RANGE, "compliant: poisson_ratio must be in (-1, 0.5) (got %g)", d->poisson_ratio);
    if (!(d->fraction >= 0.0 && d->fraction <= 1.0))
        return ori__fail(error, ORI_ERR_RANGE, "compliant: fraction must be in [0, 1] (got %g)", d->fraction);
    if (d->max_iterations <= 0) return ori__fail(error, ORI_ERR_RANGE, "compliant: max_iterations must be > 0");
    if (d->threads < 1 || d->threads > CMP_MAX_THREADS)
        return ori__fail(error, ORI_ERR_RANGE, "compliant: threads must be 1 to %d (got %d)", CMP_MAX_THREADS, d->threads);
    if (!finite_nonneg(d->current_a))
        return ori__fail(error, ORI_ERR_RANGE, "compliant: current_a must be finite and ≥ 0 (got %g)", d->current_a);
    if (!isfinite(d->field_t.x) || !isfinite(d->field_t.y) || !isfinite(d->field_t.z))
        return ori__fail(error, ORI_ERR_RANGE, "compliant: field_t must be finite");
    if (d->design && d->preset != ORI_COMPLIANT_PHYSICAL)
        return ori__fail(error, ORI_ERR_ARGUMENT, "compliant: a design's hinges, panels and wires are physical: use the physical preset");
    return ORI_OK;
}

static int cmp_int(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

// The sparse pattern of the Hessian: vertex pairs sharing a bar or a hinge.
static void build_pattern(ori_compliant *c)
{
    int nv = c->nv;
    int *deg = ori__calloc((size_t)nv + 1, sizeof(int));
    // pairs (lower dof, higher dof): from bars and hinge wing pairs (i, l); all other hinge pairs are bars
    int npairs = c->nbar + c->nhinge;
    // a wire couples every vertex of its loop's triangles with every other
    int *wv = NULL, nwv = 0, cap_wv = 0, *wstart = ori__calloc((size_t)c->nwire + 1, sizeof(int));
    for (int w = 0; w < c->nwire; ++w) {
        int from = nwv;
        for (int k = 0; k < c->wires[w].count; ++k)
            for (int q = 0; q < 3; ++q) {
                int v = c->wpts[c->wires[w].first + k].v[q];
                bool seen = false;
                for (int r = from; r < nwv && !seen; ++r) seen = wv[r] == v;
                if (!seen) ORI__PUSH(wv, nwv, cap_wv, v);
            }
        wstart[w + 1] = nwv;
        int n = nwv - from;
        npairs += n * (n - 1) / 2;
    }
    int *pa = ori__alloc(sizeof(int) * (size_t)(npairs > 0 ? npairs : 1));
    int *pb = ori__alloc(sizeof(int) * (size_t)(npairs > 0 ? npairs : 1));
    int np = 0;
    for (int b = 0; b < c->nbar; ++b) {
        pa[np] = c->bars[b].a;
        pb[np++] = c->bars[b].b;
    }
    for (int h = 0; h < c->nhinge; ++h) {
        pa[np] = c->hinges[h].i;
        pb[np++] = c->hinges[h].l;
    }
    for (int w = 0; w < c->nwire; ++w)
        for (int r = wstart[w]; r < wstart[w + 1]; ++r)
            for (int q = r + 1; q < wstart[w + 1]; ++q) {
                pa[np] = wv[r];
                pb[np++] = wv[q];
            }
    ori__free(wv);
    ori__free(wstart);
    for (int k = 0; k < np; ++k) {
        int a = pa[k], b = pb[k];
        if (c->dof[a] < 0 || c->dof[b] < 0 || a == b) continue;
        if (c->dof[a] > c->dof[b]) {
            pa[k] = b;
            pb[k] = a;
        }
        deg[pb[k]]++;
    }
    c->nb_start = ori__calloc((size_t)nv + 1, sizeof(int));
    for (int v = 0; v < nv; ++v) c->nb_start[v + 1] = c->nb_start[v] + deg[v];
    c->nb = ori__alloc(sizeof(int) * (size_t)(c->nb_start[nv] > 0 ? c->nb_start[nv] : 1));
    for (int v = 0; v < nv; ++v) deg[v] = c->nb_start[v];
    for (int k = 0; k < np; ++k) {
        int a = pa[k], b = pb[k];
        if (c->dof[a] < 0 || c->dof[b] < 0 || a == b) continue;
        c->nb[deg[b]++] = a;
    }
    // sort each list by dof (dof order = vertex order among free vertices) and remove duplicates
    int w = 0;
    int *start = ori__alloc(sizeof(int) * ((size_t)nv + 1));
    for (int v = 0; v < nv; ++v) {
        int s = c->nb_start[v], e = c->nb_start[v + 1];
        qsort(c->nb + s, (size_t)(e - s), sizeof(int), cmp_int);
        start[v] = w;
        for (int k = s; k < e; ++k)
            if (k == s || c->nb[k] != c->nb[k - 1]) c->nb[w++] = c->nb[k];
    }
    start[nv] = w;
    memcpy(c->nb_start, start, sizeof(int) * ((size_t)nv + 1));
    ori__free(start);
    ori__free(deg);
    ori__free(pa);
    ori__free(pb);
    // scalar compressed columns (upper triangle)
    int nd = c->ndof;
    c->colptr = ori__alloc(sizeof(int) * ((size_t)nd + 1));
    c->colptr[0] = 0;
    for (int v = 0; v < nv; ++v) {
        if (c->dof[v] < 0) continue;
        int cnt = c->nb_start[v + 1] - c->nb_start[v];
        for (int q = 0; q < 3; ++q) c->colptr[c->dof[v] + q + 1] = c->colptr[c->dof[v] + q] + 3 * cnt + q + 1;
    }
    int nnz = c->colptr[nd];
    c->rowind = ori__alloc(sizeof(int) * (size_t)(nnz > 0 ? nnz : 1));
    for (int v = 0; v < nv; ++v) {
        if (c->dof[v] < 0) continue;
        for (int q = 0; q < 3; ++q) {
            int k = c->colptr[c->dof[v] + q];
            for (int s = c->nb_start[v]; s < c->nb_start[v + 1]; ++s)
                for (int p = 0; p < 3; ++p) c->rowind[k++] = c->dof[c->nb[s]] + p;
            for (int p = 0; p <= q; ++p) c->rowind[k++] = c->dof[v] + p;
        }
    }
    c->sls = ori__sls_create_sym(nd, c->colptr, c->rowind);
}

// The rotation taking the sheet's plane to z = 0 (identity for a pattern in z = 0): a planar
// sheet in another plane (Origami Simulator exports its flat sheet in y = 0) is turned so that
// the faces' Newell normal points to +z. False when the vertices are not in one plane.
static bool sheet_plane(const ori_pattern *p, ori_m3 *rot)
{
    memset(rot, 0, sizeof *rot);
    rot->m[0][0] = rot->m[1][1] = rot->m[2][2] = 1.0;
    if (!ori_pattern_is_3d(p)) return true;
    int nv = ori_pattern_vertex_count(p), nf = ori_pattern_face_count(p);
    double n[3] = {0, 0, 0}, cen[3] = {0, 0, 0};
    for (int v = 0; v < nv; ++v) {
        ori_v3 q = ori_pattern_vertex(p, v);
        cen[0] += q.x / nv;
        cen[1] += q.y / nv;
        cen[2] += q.z / nv;
    }
    int cap = 0, *fv = NULL;
    for (int f = 0; f < nf; ++f) {
        int k = ori_pattern_face_size(p, f);
        if (k > cap) {
            cap = k;
            fv = ori__realloc(fv, sizeof(int) * (size_t)cap);
        }
        ori_pattern_face_vertices(p, f, fv, cap);
        for (int t = 0; t < k; ++t) {
            ori_v3 a = ori_pattern_vertex(p, fv[t]), b = ori_pattern_vertex(p, fv[(t + 1) % k]);
            n[0] += (a.y - b.y) * (a.z + b.z);
            n[1] += (a.z - b.z) * (a.x + b.x);
            n[2] += (a.x - b.x) * (a.y + b.y);
        }
    }
    ori__free(fv);
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0.0)) return false;
    for (int q = 0; q < 3; ++q) n[q] /= len;
    double diag = ori_pattern_diagonal(p), worst = 0.0;
    for (int v = 0; v < nv; ++v) {
        ori_v3 q = ori_pattern_vertex(p, v);
        worst = fmax(worst, fabs((q.x - cen[0]) * n[0] + (q.y - cen[1]) * n[1] + (q.z - cen[2]) * n[2]));
    }
    if (!(worst <= CMP_PLANE_REL * diag)) return false;
    // an orthonormal frame (e1, e2, n): rows of the rotation
    double e1[3];
    if (fabs(n[0]) < 0.9) {
        // x minus its component along n
        e1[0] = 1.0 - n[0] * n[0];
        e1[1] = -n[0] * n[1];
        e1[2] = -n[0] * n[2];
    } else { // y minus its component along n
        e1[0] = -n[1] * n[0];
        e1[1] = 1.0 - n[1] * n[1];
        e1[2] = -n[1] * n[2];
    }
    double l1 = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    for (int q = 0; q < 3; ++q) e1[q] /= l1;
    double e2[3] = {n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2], n[0] * e1[1] - n[1] * e1[0]};
    for (int q = 0; q < 3; ++q) {
        rot->m[0][q] = e1[q];
        rot->m[1][q] = e2[q];
        rot->m[2][q] = n[q];
    }
    return true;
}

static void store_frame(ori_compliant *c, bool replace_last);
static void make_collider(ori_compliant *c, const builder *bd);

// Does a triangle of face f have the vertices a, b and o?
static bool face_has_triangle(const ori_compliant *c, int f, int a, int b, int o)
{
    for (int t = 0; t < c->ntri; ++t) {
        if (c->tri_face[t] != f) continue;
        const int *v = c->tris + 3 * t;
        bool ha = v[0] == a || v[1] == a || v[2] == a, hb = v[0] == b || v[1] == b || v[2] == b;
        bool ho = v[0] == o || v[1] == o || v[2] == o;
        if (ha && hb && ho) return true;
    }
    return false;
}

// A point X (flat sheet, z = 0) as barycentric weights in the triangle of face f that holds it
// (the one it is deepest inside: a point on an edge shared by two of them takes either).
static void locate(const ori_compliant *c, int f, const double X[2], cmp_wpt *out)
{
    double best = -INFINITY;
    for (int t = 0; t < c->ntri; ++t) {
        if (c->tri_face[t] != f) continue;
        const int *v = c->tris + 3 * t;
        const double *a = c->x + 3 * v[0], *b = c->x + 3 * v[1], *cc = c->x + 3 * v[2];
        double area = cross2(a, b, cc), w[3];
        w[0] = ((b[0] - X[0]) * (cc[1] - X[1]) - (b[1] - X[1]) * (cc[0] - X[0])) / area;
        w[1] = ((cc[0] - X[0]) * (a[1] - X[1]) - (cc[1] - X[1]) * (a[0] - X[0])) / area;
        w[2] = 1.0 - w[0] - w[1];
        double m = fmin(w[0], fmin(w[1], w[2]));
        if (m > best) {
            best = m;
            for (int q = 0; q < 3; ++q) {
                out->v[q] = v[q];
                out->w[q] = w[q];
            }
        }
    }
}

// The design's wires: each current loop (ori__wire_segments, on the panel the design names or
// else the one of its crease farther from the fixed face) in CMP_WIRE_SUBSEGMENTS pieces per
// segment, its points fixed in their triangles; with auto_polarity, the current signed so that
// the loop's moment at the flat state turns the crease toward its assignment.
static void place_wires(ori_compliant *c, const ori_pattern *p, const ori_design *dsg, const ori_m3 *rot)
{
    int nf = c->nf;
    int *depth = ori__alloc(sizeof(int) * (size_t)nf);
    for (int f = 0; f < nf; ++f) depth[f] = -1;
    depth[c->def.fixed_face] = 0;
    for (bool changed = true; changed;) { // breadth-first depths by relaxation
        changed = false;
        for (int hh = 0; hh < c->nhinge; ++hh) {
            int a = c->hinges[hh].face[0], b = c->hinges[hh].face[1];
            if (a < 0 || b < 0) continue;
            if (depth[a] >= 0 && (depth[b] < 0 || depth[b] > depth[a] + 1)) depth[b] = depth[a] + 1, changed = true;
            if (depth[b] >= 0 && (depth[a] < 0 || depth[a] > depth[b] + 1)) depth[a] = depth[b] + 1, changed = true;
        }
    }
    int cap_w = 0, cap_p = 0;
    for (int e = 0; e < c->ne; ++e) {
        ori_hinge hg;
        if (!ori_design_hinge(dsg, e, &hg) || !hg.has_wire || c->edge_hinge[e] < 0) continue;
        int fa = dsg->edge_faces[e][0], fb = dsg->edge_faces[e][1];
        if (fa < 0 || fb < 0) continue;
        int face = hg.wire.face != ORI_NULL_INDEX ? hg.wire.face : depth[fb] > depth[fa] ? fb : fa;
        wire_segments ws;
        ori__wire_segments(dsg, e, face, &ws);
        cmp_wire wr = {e, face, ws.turns, c->nwpt, 4 * CMP_WIRE_SUBSEGMENTS,
                       (double)ws.turns * (hg.wire.has_current ? hg.wire.current_a : c->def.current_a)};
        for (int sg = 0; sg < 4; ++sg)
            for (int k = 0; k < CMP_WIRE_SUBSEGMENTS; ++k) {
                double t = (double)k / CMP_WIRE_SUBSEGMENTS;
                ori_v3 P = ori_v3_add(ws.a[sg], ori_v3_scale(ori_v3_sub(ws.b[sg], ws.a[sg]), t));
                double X[2] = {c->unit * (rot->m[0][0] * P.x + rot->m[0][1] * P.y + rot->m[0][2] * P.z),
                               c->unit * (rot->m[1][0] * P.x + rot->m[1][1] * P.y + rot->m[1][2] * P.z)};
                cmp_wpt pt;
                locate(c, face, X, &pt);
                ORI__PUSH(c->wpts, c->nwpt, cap_p, pt);
            }
        if (c->def.auto_polarity) {
            const cmp_hinge *h = &c->hinges[c->edge_hinge[e]];
            int wing = face_has_triangle(c, face, h->j, h->k, h->i) ? 2 : 3, wv = wing == 2 ? h->i : h->l;
            const double *xj = c->x + 3 * h->j, *xk = c->x + 3 * h->k;
            double ax[3] = {xk[0] - xj[0], xk[1] - xj[1], xk[2] - xj[2]};
            double al = sqrt(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]);
            for (int q = 0; q < 3; ++q) ax[q] /= al;
            // turning the panel by δ about the crease: dp = δ ax × (p − x_j); dU/dδ and dθ/dδ
            double B[3] = {c->field.x, c->field.y, c->field.z}, dU = 0.0;
            for (int i = 0; i < wr.count; ++i) {
                double pm[3], pp[3], pi[3], d[3], gu[3], r[3], mv[3];
                ori__cmp_wire_point(c, wr.first + (i + wr.count - 1) % wr.count, c->x, pm);
                ori__cmp_wire_point(c, wr.first + (i + 1) % wr.count, c->x, pp);
                ori__cmp_wire_point(c, wr.first + i, c->x, pi);
                for (int q = 0; q < 3; ++q) {
                    d[q] = pp[q] - pm[q];
                    r[q] = pi[q] - xj[q];
                }
                gu[0] = d[1] * B[2] - d[2] * B[1]; // ∂U/∂p_i = −½ ni (p_{i+1} − p_{i−1}) × B
                gu[1] = d[2] * B[0] - d[0] * B[2];
                gu[2] = d[0] * B[1] - d[1] * B[0];
                mv[0] = ax[1] * r[2] - ax[2] * r[1];
                mv[1] = ax[2] * r[0] - ax[0] * r[2];
                mv[2] = ax[0] * r[1] - ax[1] * r[0];
                dU -= 0.5 * wr.ni * (gu[0] * mv[0] + gu[1] * mv[1] + gu[2] * mv[2]);
            }
            double g[12], r[3], mv[3];
            ori__cmp_hinge_gradient(c->x, h, g);
            const double *xw = c->x + 3 * wv;
            for (int q = 0; q < 3; ++q) r[q] = xw[q] - xj[q];
            mv[0] = ax[1] * r[2] - ax[2] * r[1];
            mv[1] = ax[2] * r[0] - ax[0] * r[2];
            mv[2] = ax[0] * r[1] - ax[1] * r[0];
            double dth = g[3 * wing] * mv[0] + g[3 * wing + 1] * mv[1] + g[3 * wing + 2] * mv[2];
            ori_assignment as = ori_pattern_edge(p, e).assignment;
            double dir = as == ORI_ASSIGN_VALLEY ? 1.0 : as == ORI_ASSIGN_MOUNTAIN ? -1.0 : h->target < 0.0 ? -1.0 : 1.0;
            double drive = dth != 0.0 ? -dU / dth : 0.0; // the moment on the fold angle
            if (drive * dir < 0.0) wr.ni = -wr.ni;
        }
        ORI__PUSH(c->wires, c->nwire, cap_w, wr);
    }
    ori__free(depth);
}

ori_status ori_compliant_create(const ori_pattern *p, const ori_compliant_def *def, ori_compliant **out,
                                ori_error *error)
{
    ORI_ASSERT(p && def && out);
    ORI_ASSERT(def->internal_value == ORI__DEF_COOKIE);
    *out = NULL;
    ori_status st = check_def(def, error);
    if (st) return st;
    if (!ori_pattern_is_built(p)) return ori__fail(error, ORI_ERR_ARGUMENT, "compliant: the pattern is not built");
    int nv = ori_pattern_vertex_count(p), ne = ori_pattern_edge_count(p), nf = ori_pattern_face_count(p);
    ori_m3 rot;
    if (!sheet_plane(p, &rot))
        return ori__fail(error, ORI_ERR_ARGUMENT,
                         "compliant: the model starts from a flat sheet: the vertices do not lie in one plane (a folded form?)");
    if (nf <= 0) return ori__fail(error, ORI_ERR_ARGUMENT, "compliant: the pattern has no faces");
    if (def->fixed_face != ORI_NULL_INDEX && (def->fixed_face < 0 || def->fixed_face >= nf))
        return ori__fail_at(error, ORI_ERR_RANGE, "faces_vertices", def->fixed_face, "compliant: no face %d to fix",
                            def->fixed_face);
    const ori_design *dsg = def->design;
    if (dsg && (ori_design_edge_count(dsg) != ne || ori_design_face_count(dsg) != nf))
        return ori__fail(error, ORI_ERR_ARGUMENT, "compliant: the design has %d edges and %d faces, the pattern %d and %d",
                         ori_design_edge_count(dsg), ori_design_face_count(dsg), ne, nf);
    double *target = ori__alloc(sizeof(double) * (size_t)(ne > 0 ? ne : 1));
    if (def->target_angles_rad) memcpy(target, def->target_angles_rad, sizeof(double) * (size_t)ne);
    else ori_target_angles_default(p, target);
    for (int e = 0; e < ne; ++e)
        if (!isfinite(target[e]) || fabs(target[e]) > ORI_PI) {
            ori__free(target);
            return ori__fail_at(error, ORI_ERR_RANGE, "edges_foldAngle", e, "compliant: target angle of edge %d out of ±180°", e);
        }

    ori_compliant *c = ori__calloc(1, sizeof *c);
    c->def = *def;
    c->def.target_angles_rad = NULL;
    c->def.design = NULL;
    c->unit = dsg ? ori_design_meters_per_unit(dsg) : 1.0;
    c->field = def->field_t;
    c->nv = nv;
    c->ne = ne;
    c->x = ori__alloc(sizeof(double) * 3 * (size_t)(nv > 0 ? nv : 1));
    c->x0 = ori__alloc(sizeof(double) * 3 * (size_t)(nv > 0 ? nv : 1));
    c->v = ori__calloc(3 * (size_t)(nv > 0 ? nv : 1), sizeof(double));
    for (int v = 0; v < nv; ++v) {
        ori_v3 q = ori_pattern_vertex(p, v);
        c->x[3 * v] = rot.m[0][0] * q.x + rot.m[0][1] * q.y + rot.m[0][2] * q.z;
        c->x[3 * v + 1] = rot.m[1][0] * q.x + rot.m[1][1] * q.y + rot.m[1][2] * q.z;
        c->x[3 * v + 2] = 0.0;
        c->x[3 * v] *= c->unit;
        c->x[3 * v + 1] *= c->unit;
    }
    memcpy(c->x0, c->x, sizeof(double) * 3 * (size_t)nv);

    builder bd = {0};
    for (int e = 0; e < ne; ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        add_link(&bd, ed.v[0], ed.v[1], e);
    }
    int fcap = 16;
    int *fv = ori__alloc(sizeof(int) * (size_t)fcap);
    for (int f = 0; f < nf && !st; ++f) {
        int n = ori_pattern_face_size(p, f);
        if (n > fcap) {
            fcap = n;
            fv = ori__realloc(fv, sizeof(int) * (size_t)fcap);
        }
        ori_pattern_face_vertices(p, f, fv, fcap);
        if (n < 3) st = ori__fail_at(error, ORI_ERR_DEGENERATE, "faces_vertices", f, "face %d has fewer than 3 vertices", f);
        for (int a = 0; a < n && !st; ++a)
            for (int b = a + 1; b < n && !st; ++b)
                if (fv[a] == fv[b])
                    st = ori__fail_at(error, ORI_ERR_DEGENERATE, "faces_vertices", f, "face %d repeats vertex %d", f, fv[a]);
        if (!st) st = triangulate(&bd, p, f, fv, n, c->x, error);
    }
    ori__free(fv);
    if (st) {
        ori__free(bd.links);
        ori__free(bd.tris);
        ori__free(bd.tri_face);
        ori__free(target);
        ori_compliant_destroy(c);
        return st;
    }
    c->tris = bd.tris;
    c->ntri = bd.ntri / 3;
    c->tri_face = bd.tri_face;
    c->nf = nf;
    if (def->check_contacts) make_collider(c, &bd);

    // mean edge length, triangle areas
    double lsum = 0.0;
    int lcount = 0;
    for (int k = 0; k < bd.nlinks; ++k) {
        const double *a = c->x + 3 * bd.links[k].a, *b = c->x + 3 * bd.links[k].b;
        lsum += hypot(b[0] - a[0], b[1] - a[1]);
        lcount++;
    }
    c->mean_length = lcount ? lsum / lcount : 1.0;
    double *tri_area = ori__alloc(sizeof(double) * (size_t)(c->ntri > 0 ? c->ntri : 1));
    for (int t = 0; t < c->ntri; ++t) {
        const int *v = c->tris + 3 * t;
        tri_area[t] = 0.5 * cross2(c->x + 3 * v[0], c->x + 3 * v[1], c->x + 3 * v[2]);
    }
    const ori_compliant_def *d = &c->def;
    bool phys = d->preset == ORI_COMPLIANT_PHYSICAL;
    // per face: Young's modulus, thickness, density (a design's panel, else the preset's)
    double *fE = ori__alloc(sizeof(double) * (size_t)nf), *ft = ori__alloc(sizeof(double) * (size_t)nf);
    double *frho = ori__alloc(sizeof(double) * (size_t)nf);
    for (int f = 0; f < nf; ++f) {
        fE[f] = d->young_modulus_pa;
        ft[f] = d->thickness_m;
        frho[f] = d->density_kg_m3;
        ori_panel pn;
        if (dsg && ori_design_panel(dsg, f, &pn)) {
            const ori_material *m = ori__materials_get(dsg->materials, pn.material);
            if (m && m->youngs_modulus_pa > 0.0) fE[f] = m->youngs_modulus_pa;
            if (m && m->density_kg_m3 > 0.0) frho[f] = m->density_kg_m3;
            ft[f] = pn.thickness_m;
        }
    }
    // masses: unit per vertex (Origami Simulator), or ρ t A / 3 per triangle corner
    c->mass = ori__calloc((size_t)(nv > 0 ? nv : 1), sizeof(double));
    for (int t = 0; t < c->ntri; ++t) {
        int f = c->tri_face[t];
        for (int q = 0; q < 3; ++q) c->mass[c->tris[3 * t + q]] += phys ? frho[f] * ft[f] * tri_area[t] / 3.0 : 0.0;
    }
    bool *used = ori__calloc((size_t)(nv > 0 ? nv : 1), sizeof(bool));
    for (int t = 0; t < 3 * c->ntri; ++t) used[c->tris[t]] = true;
    if (!phys)
        for (int v = 0; v < nv; ++v) c->mass[v] = 1.0;

    // bars
    c->bars = ori__alloc(sizeof(cmp_bar) * (size_t)(bd.nlinks > 0 ? bd.nlinks : 1));
    c->edge_bar = ori__alloc(sizeof(int) * (size_t)(ne > 0 ? ne : 1));
    c->edge_hinge = ori__alloc(sizeof(int) * (size_t)(ne > 0 ? ne : 1));
    for (int e = 0; e < ne; ++e) c->edge_bar[e] = c->edge_hinge[e] = -1;
    for (int k = 0; k < bd.nlinks; ++k) {
        const link *l = &bd.links[k];
        if (l->ntri == 0) continue; // an edge of no face: nothing holds it
        const double *a = c->x + 3 * l->a, *b = c->x + 3 * l->b;
        double l0 = hypot(b[0] - a[0], b[1] - a[1]);
        if (!(l0 > 0.0)) {
            st = ori__fail_at(error, ORI_ERR_DEGENERATE, "edges_vertices", l->edge, "edge %d has zero length", l->edge);
            break;
        }
        cmp_bar bar = {l->a, l->b, l->edge, l0, 0.0, 0.0, {-1, -1}};
        link_faces(c, l, bar.face);
        if (phys) {
            double eta = 0.0; // Σ E t A over the bar's triangles
            for (int s = 0; s < l->ntri; ++s) {
                int f = c->tri_face[l->tri[s]];
                eta += fE[f] * ft[f] * tri_area[l->tri[s]];
            }
            bar.k = (2.0 / 3.0) * eta / (1.0 - d->poisson_ratio) / (l0 * l0);
        } else {
            bar.k = d->axial_stiffness / l0;
        }
        double mm = fmin(c->mass[l->a], c->mass[l->b]);
        bar.c = d->damping * 2.0 * sqrt(bar.k * mm);
        if (l->edge >= 0) c->edge_bar[l->edge] = c->nbar;
        c->bars[c->nbar++] = bar;
    }
    // hinges
    c->hinges = ori__alloc(sizeof(cmp_hinge) * (size_t)(bd.nlinks > 0 ? bd.nlinks : 1));
    if (dsg) {
        c->hsec = ori__calloc((size_t)(bd.nlinks > 0 ? bd.nlinks : 1), sizeof(hinge_section));
        c->hfib = ori__calloc((size_t)(bd.nlinks > 0 ? bd.nlinks : 1), sizeof(hinge_fibres));
        c->hplastic = ori__calloc((size_t)(bd.nlinks > 0 ? bd.nlinks : 1), sizeof(bool));
    }
    for (int k = 0; k < bd.nlinks && !st; ++k) {
        const link *l = &bd.links[k];
        if (l->ntri != 2) continue;
        ori_assignment as = l->edge >= 0 ? ori_pattern_edge(p, l->edge).assignment : ORI_ASSIGN_JOIN;
        if (as == ORI_ASSIGN_CUT) continue;
        bool crease = as == ORI_ASSIGN_MOUNTAIN || as == ORI_ASSIGN_VALLEY || as == ORI_ASSIGN_FLAT ||
                      as == ORI_ASSIGN_UNASSIGNED;
        cmp_hinge h;
        h.j = l->a;
        h.k = l->b;
        h.edge = l->edge;
        h.crease = crease;
        ori__cmp_set_ref(&h, 0.0);
        link_faces(c, l, h.face);
        h.target = crease && l->edge >= 0 ? target[l->edge] : 0.0;
        // the wing on the left of j → k is i
        double s0 = cross2(c->x + 3 * h.j, c->x + 3 * h.k, c->x + 3 * l->opp[0]);
        if (s0 > 0.0) {
            h.i = l->opp[0];
            h.l = l->opp[1];
        } else {
            h.i = l->opp[1];
            h.l = l->opp[0];
        }
        const double *a = c->x + 3 * h.j, *b = c->x + 3 * h.k;
        double len = hypot(b[0] - a[0], b[1] - a[1]);
        hinge_section sec;
        if (crease && dsg && l->edge >= 0 && ori__design_section(dsg, l->edge, &sec)) {
            c->hsec[c->nhinge] = sec;
            c->hplastic[c->nhinge] = true;
            h.k_h = sec.k;
        } else if (crease) {
            h.k_h = phys ? d->crease_stiffness_per_m * len : d->crease_stiffness * len;
        } else if (phys) {
            int f = h.face[0];
            double D = fE[f] * pow(ft[f], 3) / (12.0 * (1.0 - d->poisson_ratio * d->poisson_ratio));
            h.k_h = CMP_FILIPOV_C * D * cbrt(len / ft[f]);
        } else {
            h.k_h = d->facet_stiffness * len;
        }
        if (l->edge >= 0) c->edge_hinge[l->edge] = c->nhinge;
        c->hinges[c->nhinge++] = h;
    }
    ori__free(bd.links);
    ori__free(target);
    ori__free(fE);
    ori__free(ft);
    ori__free(frho);
    if (st) {
        ori__free(tri_area);
        ori__free(used);
        ori_compliant_destroy(c);
        return st;
    }
    // the fixed face: the given one, or the face whose centroid is nearest the sheet's centre
    int ff = d->fixed_face;
    if (ff == ORI_NULL_INDEX) {
        double cx = 0.0, cy = 0.0;
        for (int v = 0; v < nv; ++v) {
            cx += c->x[3 * v];
            cy += c->x[3 * v + 1];
        }
        cx /= nv > 0 ? nv : 1;
        cy /= nv > 0 ? nv : 1;
        double best = INFINITY;
        int vb[64];
        for (int f = 0; f < nf; ++f) {
            int n = ori_pattern_face_vertices(p, f, vb, 64);
            if (n > 64) n = 64;
            double fx = 0.0, fy = 0.0;
            for (int q = 0; q < n; ++q) {
                fx += c->x[3 * vb[q]];
                fy += c->x[3 * vb[q] + 1];
            }
            double dd = hypot(fx / n - cx, fy / n - cy);
            if (dd < best) {
                best = dd;
                ff = f;
            }
        }
    }
    c->def.fixed_face = ff;
    c->dof = ori__alloc(sizeof(int) * (size_t)(nv > 0 ? nv : 1));
    for (int v = 0; v < nv; ++v) c->dof[v] = used[v] ? 0 : -1;
    {
        int n = ori_pattern_face_size(p, ff);
        int *vb = ori__alloc(sizeof(int) * (size_t)n);
        ori_pattern_face_vertices(p, ff, vb, n);
        for (int q = 0; q < n; ++q) c->dof[vb[q]] = -1;
        ori__free(vb);
    }
    c->ndof = 0;
    for (int v = 0; v < nv; ++v)
        if (c->dof[v] == 0) {
            c->dof[v] = c->ndof;
            c->ndof += 3;
        }
    ori__free(tri_area);
    ori__free(used);
    if (dsg) place_wires(c, p, dsg, &rot);

    // scales
    double load = 0.0, floor_scale = 0.0, kmax_h = 0.0;
    for (int h = 0; h < c->nhinge; ++h) {
        if (c->hinges[h].crease) load = fmax(load, c->hinges[h].k_h * fabs(c->hinges[h].target) / c->mean_length);
        kmax_h = fmax(kmax_h, c->hinges[h].k_h);
        floor_scale = fmax(floor_scale, c->hinges[h].k_h * ORI_PI / c->mean_length);
    }
    if (d->gravity != 0.0)
        for (int v = 0; v < nv; ++v) load = fmax(load, c->mass[v] * fabs(d->gravity));
    // a wire's Lorentz force N·I·|B|·(its loop's longest segment)
    for (int w = 0; w < c->nwire; ++w) {
        const cmp_wire *wr = &c->wires[w];
        double seg = 0.0;
        for (int i = 0; i < wr->count; ++i) {
            double a[3], b[3];
            ori__cmp_wire_point(c, wr->first + i, c->x, a);
            ori__cmp_wire_point(c, wr->first + (i + 1) % wr->count, c->x, b);
            seg = fmax(seg, sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) + (b[2] - a[2]) * (b[2] - a[2])));
        }
        load = fmax(load, fabs(wr->ni) * ori_v3_norm(c->field) * seg * CMP_WIRE_SUBSEGMENTS);
    }
    if (!(load > 0.0)) load = kmax_h > 0.0 ? kmax_h / c->mean_length : 1.0;
    for (int b = 0; b < c->nbar; ++b) floor_scale = fmax(floor_scale, c->bars[b].k * c->bars[b].l0);
    // a hinge's force k_h (ρ − ρ_rest) ∇ρ is known to about ε k_h π |∇ρ|, |∇ρ| ≤ |r_kj| / height
    for (int h = 0; h < c->nhinge; ++h) {
        double g[12], gmax = 0.0;
        ori__cmp_hinge_gradient(c->x, &c->hinges[h], g);
        for (int q = 0; q < 12; ++q) gmax = fmax(gmax, fabs(g[q]));
        floor_scale = fmax(floor_scale, c->hinges[h].k_h * ORI_PI * gmax);
    }
    c->load_scale = load;
    c->grad_floor = CMP_GRADIENT_FLOOR_EPS * DBL_EPSILON * fmax(floor_scale, load);
    c->m_min = INFINITY;
    for (int v = 0; v < nv; ++v)
        if (c->dof[v] >= 0) c->m_min = fmin(c->m_min, c->mass[v]);
    if (!isfinite(c->m_min)) c->m_min = 1.0;

    build_pattern(c);
    // explicit time step: Gershgorin bound of the largest eigenvalue of M⁻¹K at the flat state
    {
        ori__cmp_hessian(c, c->x, 0.0, false);
        const double *val = ori__sls_values(c->sls);
        double *rows = ori__calloc((size_t)(c->ndof > 0 ? c->ndof : 1), sizeof(double));
        for (int col = 0; col < c->ndof; ++col)
            for (int k = c->colptr[col]; k < c->colptr[col + 1]; ++k) {
                int r = c->rowind[k];
                rows[r] += fabs(val[k]);
                if (r != col) rows[col] += fabs(val[k]);
            }
        double w2 = 0.0;
        for (int v = 0; v < nv; ++v)
            if (c->dof[v] >= 0)
                for (int q = 0; q < 3; ++q) w2 = fmax(w2, rows[c->dof[v] + q] / c->mass[v]);
        ori__free(rows);
        c->dt = w2 > 0.0 ? 0.9 / (2.0 * ORI_PI * sqrt(w2)) : 1.0;
    }
    c->fraction = 0.0;
    store_frame(c, false);
    *out = c;
    return ORI_OK;
}

// --- results ------------------------------------------------------------------------------

// The reported fold angle: the hinge's angle, followed continuously (the energy needs that), held
// at ±180° when it has gone past (the faces then pass through each other, as the contact warnings
// say): a FOLD file holds angles in [−180°, 180°], and orikin reads back what it writes (the
// compliant fuzz target found a flap under gravity at 210°).
static double edge_angle(const ori_compliant *c, const double *x, int e)
{
    int h = c->edge_hinge[e];
    double a = h < 0 ? 0.0 : ori__cmp_hinge_angle(x, &c->hinges[h], c->hinges[h].ref);
    return a > ORI_PI ? ORI_PI : a < -ORI_PI ? -ORI_PI : a;
}

static double bar_strain(const cmp_bar *b, const double *x)
{
    const double *xa = x + 3 * b->a, *xb = x + 3 * b->b;
    double len = sqrt((xb[0] - xa[0]) * (xb[0] - xa[0]) + (xb[1] - xa[1]) * (xb[1] - xa[1]) + (xb[2] - xa[2]) * (xb[2] - xa[2]));
    return (len - b->l0) / b->l0;
}

static void store_frame(ori_compliant *c, bool replace_last)
{
    if (replace_last && c->nframes > 0) {
        c->nframes--;
        ori__free(c->frames[c->nframes].x);
        ori__free(c->frames[c->nframes].angles);
        ori__free(c->frames[c->nframes].strains);
        ori__free(c->frames[c->nframes].face_energy);
        ori__free(c->frames[c->nframes].face_strain);
    }
    ORI__RESERVE(c->frames, c->cap_frames, c->nframes + 1);
    cmp_frame *f = &c->frames[c->nframes++];
    f->fraction = c->fraction;
    f->time = c->time;
    f->x = ori__alloc(sizeof(ori_v3) * (size_t)(c->nv > 0 ? c->nv : 1));
    for (int v = 0; v < c->nv; ++v)
        f->x[v] = (ori_v3){c->x[3 * v] / c->unit, c->x[3 * v + 1] / c->unit, c->x[3 * v + 2] / c->unit};
    f->angles = ori__alloc(sizeof(double) * (size_t)(c->ne > 0 ? c->ne : 1));
    f->strains = ori__alloc(sizeof(double) * (size_t)(c->ne > 0 ? c->ne : 1));
    for (int e = 0; e < c->ne; ++e) {
        f->angles[e] = edge_angle(c, c->x, e);
        f->strains[e] = c->edge_bar[e] >= 0 ? bar_strain(&c->bars[c->edge_bar[e]], c->x) : 0.0;
    }
    f->face_energy = ori__alloc(sizeof(double) * (size_t)(c->nf > 0 ? c->nf : 1));
    f->face_strain = ori__alloc(sizeof(double) * (size_t)(c->nf > 0 ? c->nf : 1));
    ori__cmp_face_strain(c, c->x, f->face_energy, f->face_strain);
}

// --- contact warnings -----------------------------------------------------------------------

// The triangles of the model as a pattern of their own and its collider (the faces deform, so
// the pattern's own faces are no longer planar). Without one (a build refusing it) there are
// no contact checks.
static void make_collider(ori_compliant *c, const builder *bd)
{
    ori_pattern_def pd = ori_default_pattern_def();
    ori_pattern *tp = ori_pattern_create(&pd);
    for (int v = 0; v < c->nv; ++v) ori_pattern_add_vertex(tp, (ori_v3){c->x[3 * v], c->x[3 * v + 1], 0.0});
    for (int k = 0; k < bd->nlinks; ++k)
        if (bd->links[k].ntri > 0)
            ori_pattern_add_edge(tp, bd->links[k].a, bd->links[k].b, bd->links[k].ntri == 2 ? ORI_ASSIGN_FLAT : ORI_ASSIGN_BOUNDARY, 0.0);
    for (int t = 0; t < c->ntri; ++t) ori_pattern_add_face(tp, c->tris + 3 * t, 3);
    ori_build_def bdef = ori_default_build_def();
    bdef.check_planarity = false;
    bdef.compute_faces = false;
    ori_collider_def cd = ori_default_collider_def();
    cd.pattern = tp;
    if (ori_pattern_build(tp, &bdef, NULL) != ORI_OK || ori_pattern_face_count(tp) != c->ntri ||
        ori_collider_create(&cd, &c->collider, NULL) != ORI_OK) {
        ori_pattern_destroy(tp);
        c->collider = NULL;
        return;
    }
    c->tri_pattern = tp;
}

// Check the current state for faces passing through each other: each pair of pattern faces is
// recorded once, with the first step it was seen at (at most CMP_MAX_CONTACTS pairs).
static void check_contacts(ori_compliant *c, int step, double fraction)
{
    if (!c->collider || !c->def.check_contacts) return;
    ori_v3 *x = ori__alloc(sizeof(ori_v3) * (size_t)(c->nv > 0 ? c->nv : 1));
    for (int v = 0; v < c->nv; ++v) x[v] = (ori_v3){c->x[3 * v], c->x[3 * v + 1], c->x[3 * v + 2]};
    ori_collision_result r;
    if (ori_collider_check(c->collider, x, &r, NULL) == ORI_OK && r.penetrating > 0) {
        for (int k = 0; k < r.contact_count; ++k) {
            ori_contact ct = ori_collider_contact(c->collider, k);
            if (ct.kind != ORI_CONTACT_PENETRATING) continue;
            int fa = c->tri_face[ct.face_a], fb = c->tri_face[ct.face_b];
            if (fa == fb) continue;
            if (fa > fb) {
                int t = fa;
                fa = fb;
                fb = t;
            }
            bool seen = false;
            for (int q = 0; q < c->ncontacts && !seen; ++q) seen = c->contacts[q].face_a == fa && c->contacts[q].face_b == fb;
            if (seen) continue;
            if (c->ncontacts >= CMP_MAX_CONTACTS) {
                c->contacts_truncated = true;
                break;
            }
            cmp_contact cc = {fa, fb, step, fraction};
            ORI__PUSH(c->contacts, c->ncontacts, c->cap_contacts, cc);
        }
    }
    ori__free(x);
}

static void accept_angles(ori_compliant *c)
{
    for (int h = 0; h < c->nhinge; ++h)
        ori__cmp_set_ref(&c->hinges[h], ori__cmp_hinge_angle(c->x, &c->hinges[h], c->hinges[h].ref));
}

// --- explicit solver ----------------------------------------------------------------------

// The explicit solver on def.threads threads. A step has two phases, each thread taking its share:
// (A) the forces of a share of the bars (with their damping) and hinges into the thread's own
// buffer (the wires, on thread 0); (B) for a share of the vertices, the buffers summed, gravity
// added and the vertex moved (held ones stay). The shares meet at a barrier after each phase. A
// convergence check is the same without damping, with the hinges' references accepted first,
// and (B) only measuring |∇E|∞.

// A barrier that spins a little before it sleeps: a step takes a millisecond or less, and a
// condition variable's wake-up alone costs tens of microseconds. Sequentially consistent
// atomics: the last to arrive advances gen and then looks for sleepers; a sleeper counts itself
// (under the mutex) before it looks at gen, so one of the two always sees the other.
#define CMP_BARRIER_SPINS 4000

typedef struct cmp_barrier {
    pthread_mutex_t m;
    pthread_cond_t cv;
    int count;
    atomic_int waiting, sleepers;
    atomic_uint gen;
} cmp_barrier;

static void barrier_wait(cmp_barrier *b)
{
    unsigned g = atomic_load(&b->gen);
    if (atomic_fetch_add(&b->waiting, 1) + 1 == b->count) {
        atomic_store(&b->waiting, 0);
        atomic_fetch_add(&b->gen, 1);
        if (atomic_load(&b->sleepers) > 0) {
            pthread_mutex_lock(&b->m);
            pthread_cond_broadcast(&b->cv);
            pthread_mutex_unlock(&b->m);
        }
        return;
    }
    for (int i = 0; i < CMP_BARRIER_SPINS; ++i)
        if (atomic_load(&b->gen) != g) return;
    pthread_mutex_lock(&b->m);
    atomic_fetch_add(&b->sleepers, 1);
    while (atomic_load(&b->gen) == g) pthread_cond_wait(&b->cv, &b->m);
    atomic_fetch_sub(&b->sleepers, 1);
    pthread_mutex_unlock(&b->m);
}

static void barrier_init(cmp_barrier *b)
{
    pthread_mutex_init(&b->m, NULL);
    pthread_cond_init(&b->cv, NULL);
    b->count = 1;
    atomic_init(&b->waiting, 0);
    atomic_init(&b->sleepers, 0);
    atomic_init(&b->gen, 0u);
}

static void barrier_free(cmp_barrier *b)
{
    pthread_mutex_destroy(&b->m);
    pthread_cond_destroy(&b->cv);
}

typedef struct cmp_pool cmp_pool;
typedef struct cmp_worker {
    cmp_pool *pool;
    int id;
    double *buf;    // its forces (phase A)
    double vmax;    // phase B: largest |speed| (a step) or |∇E| (a check) of its vertices
    bool finite;
    pthread_t tid;
} cmp_worker;

enum { CMP_POOL_STEP, CMP_POOL_CHECK, CMP_POOL_QUIT };

struct cmp_pool {
    ori_compliant *c;
    int n; // shares, the caller's included
    cmp_barrier go, mid, done;
    double frac;
    int mode;
    cmp_worker w[CMP_MAX_THREADS];
};

static void share(int total, int n, int id, int *from, int *to)
{
    *from = (int)((long)total * id / n);
    *to = (int)((long)total * (id + 1) / n);
}

static void phase_a(cmp_pool *pl, cmp_worker *w)
{
    ori_compliant *c = pl->c;
    int b0, b1, h0, h1;
    share(c->nbar, pl->n, w->id, &b0, &b1);
    share(c->nhinge, pl->n, w->id, &h0, &h1);
    double *buf = w->buf;
    memset(buf, 0, sizeof(double) * 3 * (size_t)c->nv);
    if (pl->mode == CMP_POOL_CHECK)
        for (int h = h0; h < h1; ++h) ori__cmp_set_ref(&c->hinges[h], ori__cmp_hinge_angle(c->x, &c->hinges[h], c->hinges[h].ref));
    ori__cmp_forces_range(c, c->x, pl->frac, buf, b0, b1, h0, h1);
    if (w->id == 0) ori__cmp_wire_forces(c, c->x, pl->frac, buf);
    if (pl->mode == CMP_POOL_CHECK) return;
    for (int b = b0; b < b1; ++b) {
        const cmp_bar *bar = &c->bars[b];
        for (int q = 0; q < 3; ++q) {
            double dv = c->v[3 * bar->b + q] - c->v[3 * bar->a + q];
            buf[3 * bar->a + q] -= bar->c * dv;
            buf[3 * bar->b + q] += bar->c * dv;
        }
    }
}

static void phase_b(cmp_pool *pl, cmp_worker *w)
{
    ori_compliant *c = pl->c;
    int v0, v1;
    share(c->nv, pl->n, w->id, &v0, &v1);
    double dt = c->dt, g = c->def.gravity * c->gravity_factor, vmax = 0.0;
    bool finite = true, step = pl->mode == CMP_POOL_STEP;
    for (int v = v0; v < v1; ++v) {
        if (c->dof[v] < 0) continue;
        double inv = dt / c->mass[v];
        for (int q = 0; q < 3; ++q) {
            double f = 0.0;
            for (int i = 0; i < pl->n; ++i) f += pl->w[i].buf[3 * v + q];
            if (q == 2) f += c->mass[v] * g;
            if (!step) {
                vmax = fmax(vmax, fabs(f));
                continue;
            }
            double vv = c->v[3 * v + q] - f * inv;
            c->v[3 * v + q] = vv;
            c->x[3 * v + q] += dt * vv;
            vmax = fmax(vmax, fabs(vv));
            finite &= isfinite(c->x[3 * v + q]) != 0;
        }
    }
    w->vmax = vmax;
    w->finite = finite;
}

static void *pool_worker(void *arg)
{
    cmp_worker *w = arg;
    cmp_pool *pl = w->pool;
    for (;;) {
        barrier_wait(&pl->go);
        if (pl->mode == CMP_POOL_QUIT) break;
        phase_a(pl, w);
        barrier_wait(&pl->mid);
        phase_b(pl, w);
        barrier_wait(&pl->done);
    }
    return NULL;
}

// Start def.threads − 1 workers (fewer when the system gives fewer, none for a small model).
// F (3 nv) is the caller's buffer.
static void pool_start(cmp_pool *pl, ori_compliant *c, double frac, double *F)
{
    memset(pl, 0, sizeof *pl);
    pl->c = c;
    pl->frac = frac;
    barrier_init(&pl->go);
    barrier_init(&pl->mid);
    barrier_init(&pl->done);
    int want = c->def.threads;
    while (want > 1 && c->nbar + c->nhinge < CMP_THREAD_ELEMENTS * want) want--; // too little work to share
    pl->w[0].pool = pl;
    pl->w[0].buf = F;
    pl->n = 1;
    for (int i = 1; i < want; ++i) {
        cmp_worker *w = &pl->w[i];
        w->pool = pl;
        w->id = i;
        w->buf = ori__alloc(sizeof(double) * 3 * (size_t)(c->nv > 0 ? c->nv : 1));
        if (pthread_create(&w->tid, NULL, pool_worker, w) != 0) {
            ori__free(w->buf);
            w->buf = NULL;
            break;
        }
        pl->n = i + 1;
    }
    // no worker has passed the first barrier yet: the counts can still be set
    cmp_barrier *bs[3] = {&pl->go, &pl->mid, &pl->done};
    for (int k = 0; k < 3; ++k) {
        pthread_mutex_lock(&bs[k]->m);
        bs[k]->count = pl->n;
        pthread_mutex_unlock(&bs[k]->m);
    }
}

static void pool_stop(cmp_pool *pl)
{
    if (pl->n > 1) {
        pl->mode = CMP_POOL_QUIT;
        barrier_wait(&pl->go);
        for (int i = 1; i < pl->n; ++i) pthread_join(pl->w[i].tid, NULL);
    }
    for (int i = 1; i < pl->n; ++i) ori__free(pl->w[i].buf);
    barrier_free(&pl->go);
    barrier_free(&pl->mid);
    barrier_free(&pl->done);
}

// One explicit step (mode CMP_POOL_STEP: returns the largest speed, *finite) or a check
// (CMP_POOL_CHECK: references accepted, returns |∇E|∞).
static double pool_run(cmp_pool *pl, int mode, bool *finite)
{
    pl->mode = mode;
    bool par = pl->n > 1;
    if (par) barrier_wait(&pl->go);
    phase_a(pl, &pl->w[0]);
    if (par) barrier_wait(&pl->mid);
    phase_b(pl, &pl->w[0]);
    if (par) barrier_wait(&pl->done);
    double m = 0.0;
    bool fin = true;
    for (int i = 0; i < pl->n; ++i) {
        m = fmax(m, pl->w[i].vmax);
        fin &= pl->w[i].finite;
    }
    if (finite) *finite = fin;
    return m;
}

// Damped explicit steps at fraction frac until |∇E|∞ ≤ ftol and every speed ≤ ftol Δt / m_min
// (checked every 16 steps), at most max_steps. Returns the steps done; *settled, *diverged.
static int relax(ori_compliant *c, double frac, int max_steps, double ftol, double *F, bool *settled, bool *diverged)
{
    double dt = c->dt, vtol = ftol * dt / c->m_min;
    *settled = *diverged = false;
    int k;
    cmp_pool pool;
    pool_start(&pool, c, frac, F);
    double t0 = c->time;
    for (k = 0; k < max_steps; ++k) {
        bool finite;
        double vmax = pool_run(&pool, CMP_POOL_STEP, &finite);
        if (!finite) {
            *diverged = true;
            pool_stop(&pool);
            return k + 1;
        }
        c->time = t0 + (k + 1) * dt;
        ori__cmp_commit_fibres(c, c->x, frac);
        if (c->def.keep_frames && (k + 1) % c->frame_interval == 0) { // the time history
            store_frame(c, false);
            if (c->nframes > CMP_TIME_FRAMES) thin_frames(c);
        }
        if (k % CMP_CONTACT_INTERVAL == CMP_CONTACT_INTERVAL - 1) check_contacts(c, k + 1, frac);
        if ((k & 15) == 15 && pool_run(&pool, CMP_POOL_CHECK, NULL) <= ftol && vmax <= vtol) {
            *settled = true;
            pool_stop(&pool);
            return k + 1;
        }
    }
    pool_stop(&pool);
    accept_angles(c);
    return k;
}

// --- static solver -----------------------------------------------------------------------

// Newton on E at the given fraction from c->x. Returns true at equilibrium.
static bool newton(ori_compliant *c, double fraction, double tol, double *g, double *gt, double *dx, double *xt,
                   double *rhs, double *sol)
{
    int nv = c->nv, nd = c->ndof;
    double e = ori__cmp_energy(c, c->x, fraction, g);
    for (int it = 0; it < c->def.max_iterations; ++it) {
        double gn = ori__cmp_grad_norm(c, g);
        if (gn <= tol) return true;
        if (nd == 0) return true;
        c->iterations++;
        for (int v = 0; v < nv; ++v)
            if (c->dof[v] >= 0)
                for (int q = 0; q < 3; ++q) rhs[c->dof[v] + q] = -g[3 * v + q];
        // the exact Hessian; when it is not positive definite (or gives no descent), its positive
        // semi-definite part, shifted by λ (Levenberg) while that fails
        bool solved = false;
        for (int pass = 0; pass < 2 && !solved; ++pass) {
            ori__cmp_hessian(c, c->x, fraction, pass == 1);
            double diag = 0.0;
            const double *val = ori__sls_values(c->sls);
            for (int col = 0; col < nd; ++col) diag = fmax(diag, fabs(val[c->colptr[col + 1] - 1]));
            double shift = 0.0, shift_min = 1e-12 * (diag > 0.0 ? diag : 1.0);
            int tries = pass == 0 ? 1 : 40;
            for (int t = 0; t < tries && !solved; ++t) {
                c->factorizations++;
                if (ori__sls_factor(c->sls, shift) && ori__sls_solve(c->sls, rhs, sol)) {
                    double gd = 0.0;
                    for (int k = 0; k < nd; ++k) gd -= rhs[k] * sol[k];
                    if (gd < 0.0) solved = true;
                }
                shift = shift > 0.0 ? shift * 10.0 : shift_min;
            }
        }
        if (!solved) return false;
        for (int k = 0; k < 3 * nv; ++k) dx[k] = 0.0;
        double gd = 0.0;
        for (int v = 0; v < nv; ++v)
            if (c->dof[v] >= 0)
                for (int q = 0; q < 3; ++q) {
                    dx[3 * v + q] = sol[c->dof[v] + q];
                    gd += g[3 * v + q] * dx[3 * v + q];
                }
        // backtracking line search: the energy never increases
        double alpha = 1.0;
        bool accepted = false;
        double et = 0.0;
        for (int bt = 0; bt < CMP_MAX_BACKTRACKS; ++bt) {
            for (int k = 0; k < 3 * nv; ++k) xt[k] = c->x[k] + alpha * dx[k];
            et = ori__cmp_energy(c, xt, fraction, gt);
            if (isfinite(et)) {
                if (et <= e + CMP_ARMIJO * alpha * gd) {
                    accepted = true;
                    break;
                }
                // at roundoff the energy cannot tell: accept a step that does not raise it and lowers |∇E|
                if (et <= e + CMP_ENERGY_ROUNDOFF * fabs(e) && ori__cmp_grad_norm(c, gt) < gn) {
                    accepted = true;
                    break;
                }
            }
            alpha *= 0.5;
            c->backtracks++;
        }
        if (!accepted) return ori__cmp_grad_norm(c, g) <= tol;
        if (c->trace) c->trace(e, et, c->trace_user);
        memcpy(c->x, xt, sizeof(double) * 3 * (size_t)nv);
        memcpy(g, gt, sizeof(double) * 3 * (size_t)nv);
        e = et;
        accept_angles(c);
    }
    return ori__cmp_grad_norm(c, g) <= tol;
}

ori_status ori_compliant_set_fraction(ori_compliant *c, double fraction, ori_error *error)
{
    ORI_ASSERT(c);
    if (!(fraction >= 0.0 && fraction <= 1.0))
        return ori__fail(error, ORI_ERR_RANGE, "compliant: fraction must be in [0, 1] (got %g)", fraction);
    c->def.fraction = fraction;
    return ORI_OK;
}

static void restore(ori_compliant *c, const double *x, const double *ref)
{
    memcpy(c->x, x, sizeof(double) * 3 * (size_t)c->nv);
    for (int h = 0; h < c->nhinge; ++h) ori__cmp_set_ref(&c->hinges[h], ref[h]);
}

// The tangent of the equilibrium path at c->x (fraction f): H dx/dt = −∂∇E/∂t, the load
// parameter t moving the fraction by df and the gravity factor by dg per unit. ∇E is linear in
// both (the rest angles, the wires' current and gravity), so ∂∇E/∂t is the difference of two
// gradients; H is the last factorization (Newton's, one iterate before this equilibrium). False
// when it cannot be solved (the secant predicts instead).
static bool tangent_of(ori_compliant *c, double f, double df, double dg, double *ga, double *gb, double *rhs, double *sol,
                       double *tangent)
{
    if (c->ndof == 0) return false;
    double keep = c->gravity_factor;
    ori__cmp_energy(c, c->x, f, ga);
    c->gravity_factor = keep + dg;
    ori__cmp_energy(c, c->x, f + df, gb);
    c->gravity_factor = keep;
    for (int v = 0; v < c->nv; ++v)
        if (c->dof[v] >= 0)
            for (int q = 0; q < 3; ++q) rhs[c->dof[v] + q] = -(gb[3 * v + q] - ga[3 * v + q]);
    if (!ori__sls_solve(c->sls, rhs, sol)) return false;
    for (int v = 0; v < c->nv; ++v)
        for (int q = 0; q < 3; ++q) tangent[3 * v + q] = c->dof[v] >= 0 ? sol[c->dof[v] + q] : 0.0;
    return true;
}

ori_status ori_compliant_solve_static(ori_compliant *c, ori_error *error)
{
    ORI_ASSERT(c);
    int n3 = 3 * (c->nv > 0 ? c->nv : 1);
    int nd = c->ndof > 0 ? c->ndof : 1;
    int nh = c->nhinge > 0 ? c->nhinge : 1;
    double *g = ori__alloc(sizeof(double) * (size_t)n3), *gt = ori__alloc(sizeof(double) * (size_t)n3);
    double *dx = ori__alloc(sizeof(double) * (size_t)n3), *xt = ori__alloc(sizeof(double) * (size_t)n3);
    double *rhs = ori__alloc(sizeof(double) * (size_t)nd), *sol = ori__alloc(sizeof(double) * (size_t)nd);
    double *xs = ori__alloc(sizeof(double) * (size_t)n3), *xprev = ori__alloc(sizeof(double) * (size_t)n3);
    double *refs = ori__alloc(sizeof(double) * (size_t)nh);
    double f0 = c->fraction, f1 = c->def.fraction, g0 = c->gravity_factor;
    double span = 0.0;
    for (int h = 0; h < c->nhinge; ++h)
        if (c->hinges[h].crease) span = fmax(span, fabs(c->hinges[h].target * (f1 - f0)));
    // the load parameter t runs 0 → 1: fraction f0 → f1, gravity factor g0 → 1
    double dt0 = fmin(1.0, c->def.max_step_rad / fmax(span, DBL_MIN));
    if (c->def.gravity != 0.0 && g0 < 1.0) dt0 = fmin(dt0, 0.1);
    if (c->nwire > 0 && f1 != f0) dt0 = fmin(dt0, CMP_WIRE_LOAD_STEP / fabs(f1 - f0)); // the current ramps with the fraction
    double tol = fmax(c->def.tolerance * c->load_scale, c->grad_floor);
    ori_status st = ORI_OK;
    double t = 0.0, dt = dt0, dt_prev = 0.0;
    bool have_prev = false, have_tangent = false;
    double *tangent = ori__calloc((size_t)n3, sizeof(double));
    while (t < 1.0) {
        double tn = fmin(1.0, t + dt);
        double f = f0 + (f1 - f0) * tn, gf = g0 + (1.0 - g0) * tn;
        memcpy(xs, c->x, sizeof(double) * (size_t)n3);
        for (int h = 0; h < c->nhinge; ++h) refs[h] = c->hinges[h].ref;
        // predictor: the tangent of the path at the last equilibrium, else the secant of the last two
        if (have_tangent) {
            for (int k = 0; k < 3 * c->nv; ++k) c->x[k] += (tn - t) * tangent[k];
            accept_angles(c);
        } else if (have_prev && dt_prev > 0.0) {
            double r = (tn - t) / dt_prev;
            for (int k = 0; k < 3 * c->nv; ++k) c->x[k] += r * (xs[k] - xprev[k]);
            accept_angles(c);
        }
        c->gravity_factor = gf;
        c->load_steps++;
        if (newton(c, f, tol, g, gt, dx, xt, rhs, sol)) {
            memcpy(xprev, xs, sizeof(double) * (size_t)n3);
            have_prev = true;
            dt_prev = tn - t;
            t = tn;
            c->fraction = f;
            ori__cmp_commit_fibres(c, c->x, f);
            have_tangent = tangent_of(c, f, f1 - f0, 1.0 - g0, g, gt, rhs, sol, tangent);
            store_frame(c, !c->def.keep_frames);
            check_contacts(c, c->load_steps, f);
            dt = fmin(dt0, dt * 1.5);
            continue;
        }
        // no equilibrium from there: back to the last one, a shorter step
        restore(c, xs, refs);
        c->gravity_factor = g0 + (1.0 - g0) * t;
        dt *= 0.25;
        if (dt < 1e-6 * dt0) {
            ori__cmp_energy(c, c->x, c->fraction, g);
            st = ori__fail(error, ORI_ERR_NOT_CONVERGED,
                           "compliant: no equilibrium beyond fraction %.6g (toward %.6g); the state of fraction %.6g is kept",
                           c->fraction, f1, c->fraction);
            break;
        }
    }
    ori__free(g);
    ori__free(gt);
    ori__free(dx);
    ori__free(xt);
    ori__free(rhs);
    ori__free(sol);
    ori__free(xs);
    ori__free(xprev);
    ori__free(refs);
    ori__free(tangent);
    return st;
}

// --- accessors ----------------------------------------------------------------------------

int ori_compliant_vertex_count(const ori_compliant *c) { return c->nv; }
int ori_compliant_bar_count(const ori_compliant *c) { return c->nbar; }
int ori_compliant_hinge_count(const ori_compliant *c) { return c->nhinge; }
int ori_compliant_triangle_count(const ori_compliant *c) { return c->ntri; }
double ori_compliant_time_step(const ori_compliant *c) { return c->dt; }
double ori_compliant_load_scale(const ori_compliant *c) { return c->load_scale; }
double ori_compliant_gradient_floor(const ori_compliant *c) { return c->grad_floor; }
double ori_compliant_fraction(const ori_compliant *c) { return c->fraction; }

const ori_v3 *ori_compliant_positions(const ori_compliant *c)
{
    // the last frame is the current state after every solve (the dynamic solver stores it too)
    return c->frames[c->nframes - 1].x;
}

double ori_compliant_fold_angle(const ori_compliant *c, int edge)
{
    ORI_ASSERT(edge >= 0 && edge < c->ne);
    return edge_angle(c, c->x, edge);
}

double ori_compliant_edge_strain(const ori_compliant *c, int edge)
{
    ORI_ASSERT(edge >= 0 && edge < c->ne);
    return c->edge_bar[edge] >= 0 ? bar_strain(&c->bars[c->edge_bar[edge]], c->x) : 0.0;
}

double ori_compliant_max_strain(const ori_compliant *c)
{
    double m = 0.0;
    for (int b = 0; b < c->nbar; ++b) m = fmax(m, fabs(bar_strain(&c->bars[b], c->x)));
    return m;
}

double ori_compliant_energy(const ori_compliant *c) { return ori__cmp_energy(c, c->x, c->fraction, NULL); }

double ori_compliant_gradient_norm(const ori_compliant *c)
{
    double *g = ori__alloc(sizeof(double) * 3 * (size_t)(c->nv > 0 ? c->nv : 1));
    ori__cmp_energy(c, c->x, c->fraction, g);
    double n = ori__cmp_grad_norm(c, g);
    ori__free(g);
    return n;
}

double ori_compliant_crease_error(const ori_compliant *c)
{
    double m = 0.0;
    for (int h = 0; h < c->nhinge; ++h) {
        const cmp_hinge *hh = &c->hinges[h];
        if (!hh->crease) continue;
        m = fmax(m, fabs(ori__cmp_hinge_angle(c->x, hh, hh->ref) - hh->target * c->fraction));
    }
    return m;
}

void ori_compliant_stats(const ori_compliant *c, int *iterations, int *factorizations, int *backtracks, int *load_steps)
{
    if (iterations) *iterations = c->iterations;
    if (factorizations) *factorizations = c->factorizations;
    if (backtracks) *backtracks = c->backtracks;
    if (load_steps) *load_steps = c->load_steps;
}

int ori_compliant_face_count(const ori_compliant *c) { return c->nf; }
int ori_compliant_edge_count(const ori_compliant *c) { return c->ne; }

double ori_compliant_plastic_rotation(const ori_compliant *c, int edge)
{
    ORI_ASSERT(edge >= 0 && edge < c->ne);
    int hh = c->edge_hinge[edge];
    if (hh < 0 || !c->hplastic || !c->hplastic[hh]) return 0.0;
    const cmp_hinge *h = &c->hinges[hh];
    hinge_section s = c->hsec[hh];
    s.rest = h->crease ? h->target * c->fraction : 0.0;
    return ori__hinge_plastic_rotation(&s, &c->hfib[hh], ori__cmp_hinge_angle(c->x, h, h->ref));
}

double ori_compliant_wire_current(const ori_compliant *c, int edge)
{
    ORI_ASSERT(edge >= 0 && edge < c->ne);
    for (int w = 0; w < c->nwire; ++w)
        if (c->wires[w].edge == edge) {
            return c->wires[w].ni * c->fraction / (double)c->wires[w].turns;
        }
    return 0.0;
}

int ori_compliant_wire_count(const ori_compliant *c) { return c->nwire; }

double ori_compliant_face_energy(const ori_compliant *c, int face)
{
    ORI_ASSERT(face >= 0 && face < c->nf);
    return c->frames[c->nframes - 1].face_energy[face];
}

double ori_compliant_face_strain(const ori_compliant *c, int face)
{
    ORI_ASSERT(face >= 0 && face < c->nf);
    return c->frames[c->nframes - 1].face_strain[face];
}

int ori_compliant_contact_count(const ori_compliant *c) { return c->ncontacts; }

bool ori_compliant_contacts_truncated(const ori_compliant *c) { return c->contacts_truncated; }

void ori_compliant_contact(const ori_compliant *c, int k, int *face_a, int *face_b, int *step, double *fraction)
{
    ORI_ASSERT(k >= 0 && k < c->ncontacts);
    const cmp_contact *ct = &c->contacts[k];
    if (face_a) *face_a = ct->face_a;
    if (face_b) *face_b = ct->face_b;
    if (step) *step = ct->step;
    if (fraction) *fraction = ct->fraction;
}

int ori_compliant_frame_count(const ori_compliant *c) { return c->nframes; }

const double *ori_compliant_frame_face_energies(const ori_compliant *c, int k)
{
    ORI_ASSERT(k >= 0 && k < c->nframes);
    return c->frames[k].face_energy;
}

const double *ori_compliant_frame_face_strains(const ori_compliant *c, int k)
{
    ORI_ASSERT(k >= 0 && k < c->nframes);
    return c->frames[k].face_strain;
}

double ori_compliant_frame_fraction(const ori_compliant *c, int k)
{
    ORI_ASSERT(k >= 0 && k < c->nframes);
    return c->frames[k].fraction;
}

double ori_compliant_frame_time(const ori_compliant *c, int k)
{
    ORI_ASSERT(k >= 0 && k < c->nframes);
    return c->frames[k].time;
}

const ori_v3 *ori_compliant_frame_positions(const ori_compliant *c, int k)
{
    ORI_ASSERT(k >= 0 && k < c->nframes);
    return c->frames[k].x;
}

const double *ori_compliant_frame_angles(const ori_compliant *c, int k)
{
    ORI_ASSERT(k >= 0 && k < c->nframes);
    return c->frames[k].angles;
}

const double *ori_compliant_frame_strains(const ori_compliant *c, int k)
{
    ORI_ASSERT(k >= 0 && k < c->nframes);
    return c->frames[k].strains;
}


ori_status ori_compliant_run_dynamic(ori_compliant *c, int max_steps, double force_tolerance, int *steps,
                                     ori_error *error)
{
    ORI_ASSERT(c);
    if (steps) *steps = 0;
    if (max_steps < 0 || !(force_tolerance > 0.0) || !isfinite(force_tolerance))
        return ori__fail(error, ORI_ERR_RANGE, "compliant: max_steps must be ≥ 0 and force_tolerance finite and > 0");
    c->gravity_factor = 1.0;
    double *F = ori__alloc(sizeof(double) * 3 * (size_t)(c->nv > 0 ? c->nv : 1));
    bool settled, diverged;
    if (c->frame_interval < 1) c->frame_interval = CMP_FIRST_FRAME_INTERVAL;
    c->fraction = c->def.fraction; // (the rest angles are set at once: every frame of the history is at it)
    int k = relax(c, c->def.fraction, max_steps, force_tolerance * c->load_scale, F, &settled, &diverged);
    ori__free(F);
    if (steps) *steps = k;
    // the end (with the history, unless its last frame is the end already)
    bool have_end = c->def.keep_frames && c->nframes > 0 && c->frames[c->nframes - 1].time == c->time;
    if (!have_end) store_frame(c, !c->def.keep_frames);
    if (!diverged) check_contacts(c, k, c->fraction);
    if (diverged) return ori__fail(error, ORI_ERR_NOT_CONVERGED, "compliant: the explicit solver diverged at step %d", k);
    if (!settled) return ori__fail(error, ORI_ERR_NOT_CONVERGED, "compliant: the explicit solver did not settle in %d steps", max_steps);
    return ORI_OK;
}
