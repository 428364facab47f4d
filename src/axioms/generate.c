// Tessellation generators. Every pattern is written straight into the pattern's arrays by index
// arithmetic (vertices by formula, edges appended in a documented order, faces counter-
// clockwise), then validated once by ori_pattern_build. docs/generators.md derives the
// geometry and the mountain/valley assignments and lists the edge index ranges.
#include <float.h>
#include <orikin/generate.h>

#include "../pattern/pattern_internal.h"

// Rows and columns above this are rejected before any count is formed (keeps every count
// formula far from int64 overflow); the edge limit is the real bound.
#define MAX_GRID_SIDE (1 << 26)

// The table of tessellations (one row each, at the end of this file): name, parameters read,
// defaults, counts with their own checks, face size and writer.
typedef struct gen gen; // the arrays being written
typedef struct tess_row {
    const char *name;        // ori_tessellation_name
    unsigned params;         // the ori_generate_def fields it reads (ori_generate_param bits)
    int rows;                // default rows
    double angle_rad;        // default angle (0 where none is read)
    int face_size;           // vertices of each of its faces
    ori_status (*counts)(const ori_generate_def *def, int64_t rows, int64_t cols, ori_pattern_counts *n, ori_error *error);
    void (*write)(gen *g, const ori_generate_def *def);
} tess_row;
static const tess_row *tess_row_of(ori_tessellation kind);

static const char *const class_names[ORI_EDGE_CLASS_COUNT] = {
    "boundary", "straight", "zigzag", "horizontal", "vertical", "diagonal",
    "square",   "pleat",    "polygon", "lateral",   "seam"};

const char *ori_tessellation_name(ori_tessellation kind)
{
    ORI_ASSERT((int)kind >= 0 && kind < ORI_TESS_COUNT);
    return tess_row_of(kind)->name;
}

bool ori_tessellation_from_name(const char *name, ori_tessellation *out)
{
    ORI_ASSERT(name && out);
    for (int i = 0; i < ORI_TESS_COUNT; ++i)
        if (strcmp(name, tess_row_of((ori_tessellation)i)->name) == 0) {
            *out = (ori_tessellation)i;
            return true;
        }
    return false;
}

const char *ori_edge_class_name(ori_edge_class c)
{
    ORI_ASSERT((int)c >= 0 && c < ORI_EDGE_CLASS_COUNT);
    return class_names[c];
}

ori_generate_def ori_default_generate_def(ori_tessellation kind)
{
    ORI_ASSERT((int)kind >= 0 && kind < ORI_TESS_COUNT);
    ori_generate_def def;
    def.kind = kind;
    def.rows = 4;
    def.cols = 4;
    def.sides = 6;
    def.angle_rad = 0.0;
    def.width = 1.0;
    def.height = 1.0;
    def.twist_size = 0.5;
    def.bistable_height = false;
    const tess_row *t = tess_row_of(kind);
    def.rows = t->rows;
    def.angle_rad = t->angle_rad;
    def.bistable_height = (t->params & ORI_GEN_BISTABLE_HEIGHT) != 0; // on where it is read
    def.internal_value = ORI__DEF_COOKIE;
    return def;
}

double ori_kresling_bistable_height(int sides, double width, double angle_rad)
{
    ORI_ASSERT(sides >= 3);
    double u = ORI_PI / sides;
    if (!(angle_rad < 0.5 * ORI_PI - u - ORI_TOL_ANGLE_EQUAL_RAD)) return 0.0;
    double r = width / (2.0 * sin(u));
    double h2 = 4.0 * r * r * cos(u) * cos(u + angle_rad);
    return h2 > 0.0 && isfinite(h2) ? sqrt(h2) : 0.0;
}

// --- parameters and counts -----------------------------------------------------------------

static ori_status check_positive(double x, const char *field, ori_error *error)
{
    if (!(x > 0.0) || !isfinite(x))
        return ori__fail_at(error, ORI_ERR_ARGUMENT, field, ORI_NULL_INDEX, "must be a finite number > 0 (got %.17g)", x);
    return ORI_OK;
}

static ori_status check_grid(int n, const char *field, int lo, ori_error *error)
{
    if (n < lo || n > MAX_GRID_SIDE)
        return ori__fail_at(error, ORI_ERR_ARGUMENT, field, ORI_NULL_INDEX, "must be between %d and %d (got %d)", lo,
                            MAX_GRID_SIDE, n);
    return ORI_OK;
}

// Open or half-open angle range check: an angle within ORI_TOL_ANGLE_EQUAL_RAD of a bound is
// that bound (60° typed for a limit of π/2 − π/6 must not slip through by one ulp). Messages
// in degrees because people read them.
static ori_status check_angle(double a, double lo, double hi, bool hi_closed, ori_error *error)
{
    const double tol = ORI_TOL_ANGLE_EQUAL_RAD;
    bool ok = isfinite(a) && a > lo + tol && (hi_closed ? a <= hi + tol : a < hi - tol);
    if (ok) return ORI_OK;
    // Inside the range as typed but within the tolerance of an open bound: say so, or the
    // message would contradict itself ("89.9999999° is outside (0°, 90°)").
    // (A value that is the bound up to rounding, e.g. 60° typed for π/3, is just outside.)
    double ulps = 16.0 * DBL_EPSILON * fmax(fabs(lo), fabs(hi));
    bool at_lo = isfinite(a) && a > lo + ulps && a <= lo + tol;
    bool at_hi = isfinite(a) && !hi_closed && a < hi - ulps && a >= hi - tol;
    if (at_lo || at_hi)
        return ori__fail_at(error, ORI_ERR_ARGUMENT, "angle", ORI_NULL_INDEX,
                            "%.10g° is within %.2g° of the open bound %.10g° of (%.10g°, %.10g°%c, which counts as the "
                            "bound",
                            ori_rad_to_deg(a), ori_rad_to_deg(tol), ori_rad_to_deg(at_lo ? lo : hi), ori_rad_to_deg(lo),
                            ori_rad_to_deg(hi), hi_closed ? ']' : ')');
    return ori__fail_at(error, ORI_ERR_ARGUMENT, "angle", ORI_NULL_INDEX, "%.10g° is outside (%.10g°, %.10g°%c",
                        ori_rad_to_deg(a), ori_rad_to_deg(lo), ori_rad_to_deg(hi), hi_closed ? ']' : ')');
}

// Kresling storey: polygon side a, lateral b, diagonal c, developed shift s and strip height H.
typedef struct kresling_geom {
    double a, b, c, s, strip_h, h;
} kresling_geom;

static kresling_geom kresling_geometry(const ori_generate_def *def)
{
    kresling_geom g;
    double u = ORI_PI / def->sides, phi = def->angle_rad;
    double r = def->width / (2.0 * sin(u));
    g.h = def->bistable_height ? ori_kresling_bistable_height(def->sides, def->width, phi) : def->height;
    g.a = def->width;
    // Bottom vertex i at angle 2πi/n, top vertex i at 2πi/n + φ, height h; lateral b joins
    // B_i T_i, the diagonal c joins B_i T_{i+1} (the long one: Kresling's valley diagonal).
    double sb = 2.0 * r * sin(0.5 * phi), sc = 2.0 * r * sin(u + 0.5 * phi);
    g.b = sqrt(g.h * g.h + sb * sb);
    g.c = sqrt(g.h * g.h + sc * sc);
    // Development: B_0 = (0, 0), B_1 = (a, 0), T_0 = (s, H) with |T_0| = b, |T_1| = c:
    // s = (c² − b² − a²) / 2a = R (sin(u + φ) − sin u).
    g.s = r * (sin(u + phi) - sin(u));
    double h2 = g.b * g.b - g.s * g.s;
    g.strip_h = h2 > 0.0 ? sqrt(h2) : 0.0;
    return g;
}

// --- counts, each tessellation checking its own parameters -------------------------------------

static ori_status counts_miura(const ori_generate_def *def, int64_t r, int64_t c, ori_pattern_counts *n, ori_error *error)
{
    ori_status st = check_angle(def->angle_rad, 0.0, 0.5 * ORI_PI, false, error);
    if (st != ORI_OK) return st;
    n->vertices = (r + 1) * (c + 1);
    n->edges = c * (r + 1) + r * (c + 1);
    n->faces = r * c;
    return ORI_OK;
}

static ori_status counts_yoshimura(const ori_generate_def *def, int64_t r, int64_t c, ori_pattern_counts *n,
                                   ori_error *error)
{
    ori_status st = check_angle(def->angle_rad, 0.0, ORI_PI / 3.0, true, error);
    if (st != ORI_OK) return st;
    n->vertices = (c + 1) * (r + 1) + (r + 1) / 2;
    n->edges = c * (r + 1) + (r + 1) / 2 + 2 * r * c + 2 * r;
    n->faces = r * (2 * c + 1);
    return ORI_OK;
}

static ori_status counts_waterbomb(const ori_generate_def *def, int64_t r, int64_t c, ori_pattern_counts *n,
                                   ori_error *error)
{
    // Big-little-big at a base centre needs the diagonals at ≥ 30° from the x axis.
    double phi = atan2(def->height, def->width);
    if (phi < ORI_PI / 6.0 - ORI_TOL_ANGLE_EQUAL_RAD)
        return ori__fail_at(error, ORI_ERR_ARGUMENT, "height", ORI_NULL_INDEX,
                            "height/width = %g is below tan 30° = 0.57735: the diagonals must make at "
                            "least 30° with the x axis for the waterbomb assignment to fold flat",
                            def->height / def->width);
    int64_t centres = ((r + 1) / 2) * c + (r / 2) * (c + 1);
    n->vertices = (2 * c + 1) * (r + 1) + centres;
    n->edges = 2 * c * (r + 1) + r * (2 * c + 1) + centres + 4 * c * r;
    n->faces = 6 * c * r;
    return ORI_OK;
}

static ori_status counts_square_twist(const ori_generate_def *def, int64_t r, int64_t c, ori_pattern_counts *n,
                                      ori_error *error)
{
    ori_status st = check_angle(def->angle_rad, 0.0, 0.5 * ORI_PI, false, error);
    if (st != ORI_OK) return st;
    if (!(def->twist_size > 0.0 && def->twist_size < 1.0))
        return ori__fail_at(error, ORI_ERR_ARGUMENT, "twist_size", ORI_NULL_INDEX, "must be in (0, 1) (got %g)",
                            def->twist_size);
    n->vertices = 4 * r * c + 4 * r + 4 * c + 4;
    n->edges = 8 * r * c + 6 * r + 6 * c + 4;
    n->faces = 4 * r * c + 2 * r + 2 * c + 1;
    return ORI_OK;
}

static ori_status counts_kresling(const ori_generate_def *def, int64_t r, int64_t c, ori_pattern_counts *n,
                                  ori_error *error)
{
    (void)c; // the Kresling has sides, not columns
    int64_t s = def->sides;
    double limit = 0.5 * ORI_PI - ORI_PI / (double)def->sides;
    ori_status st = check_angle(def->angle_rad, 0.0, limit, false, error);
    if (st != ORI_OK) return st;
    kresling_geom g = kresling_geometry(def);
    if (!(g.strip_h > 0.0) || !isfinite(g.strip_h))
        return ori__fail_at(error, ORI_ERR_ARGUMENT, "height", ORI_NULL_INDEX, "the storey is degenerate");
    n->vertices = (s + 1) * (r + 1);
    n->edges = s * (r + 1) + (2 * s + 1) * r;
    n->faces = 2 * s * r;
    return ORI_OK;
}

ori_status ori_generate_counts(const ori_generate_def *def, ori_pattern_counts *out, ori_error *error)
{
    ORI_ASSERT(def && out && def->internal_value == ORI__DEF_COOKIE);
    ORI_ASSERT((int)def->kind >= 0 && def->kind < ORI_TESS_COUNT);
    ori_error_clear(error);
    const tess_row *t = tess_row_of(def->kind);
    ori_status st;
    if ((st = check_grid(def->rows, "rows", 1, error)) != ORI_OK) return st;
    if ((t->params & ORI_GEN_SIDES) && (st = check_grid(def->sides, "sides", 3, error)) != ORI_OK) return st;
    if ((t->params & ORI_GEN_COLS) && (st = check_grid(def->cols, "cols", 1, error)) != ORI_OK) return st;
    if ((st = check_positive(def->width, "width", error)) != ORI_OK) return st;
    bool uses_height = (t->params & ORI_GEN_HEIGHT) && !((t->params & ORI_GEN_BISTABLE_HEIGHT) && def->bistable_height);
    if (uses_height && (st = check_positive(def->height, "height", error)) != ORI_OK) return st;
    ori_pattern_counts n = {0, 0, 0};
    if ((st = t->counts(def, def->rows, def->cols, &n, error)) != ORI_OK) return st;
    if (n.edges > ORI_GENERATE_MAX_EDGES)
        return ori__fail(error, ORI_ERR_LIMIT, "the pattern would have %lld edges; the limit is %lld",
                         (long long)n.edges, (long long)ORI_GENERATE_MAX_EDGES);
    *out = n;
    return ORI_OK;
}

// --- writing the arrays ----------------------------------------------------------------------

struct gen {
    ori_pattern *p;
    ori_edge_class *cls; // may be NULL
};

static inline void put_vertex(ori_pattern *p, int v, double x, double y)
{
    p->vertices[v] = ori_v3_make(x, y, 0.0);
}

static inline void put_edge(gen *g, int a, int b, ori_assignment asg, ori_edge_class c)
{
    ori_pattern *p = g->p;
    ori_edge *e = &p->edges[p->edge_count];
    e->v[0] = a;
    e->v[1] = b;
    e->assignment = asg;
    e->fold_angle_rad = 0.0;
    if (g->cls) g->cls[p->edge_count] = c;
    p->edge_count++;
}

static inline void put_face(ori_pattern *p, const int *v, int n)
{
    memcpy(p->face_vertices + p->face_vertex_count, v, sizeof(int) * (size_t)n);
    p->face_vertex_count += n;
    p->face_count++;
    p->face_offsets[p->face_count] = p->face_vertex_count;
}

static inline void face3(ori_pattern *p, int a, int b, int c)
{
    int v[3] = {a, b, c};
    put_face(p, v, 3);
}

static inline void face4(ori_pattern *p, int a, int b, int c, int d)
{
    int v[4] = {a, b, c, d};
    put_face(p, v, 4);
}

// --- Miura-ori -------------------------------------------------------------------------------
// Vertex (i, j), i ∈ [0, C], j ∈ [0, R]: index j(C+1) + i at (i·a + [j odd]·b·cos γ, j·b·sin γ).
// Edges: straight (x direction) first, row by row, then zig-zag, column segment by segment.
// Zig-zag column i is M for odd i, V for even i; a straight segment i→i+1 of row j takes the
// assignment of zig-zag column i+1 when j is even and of column i when j is odd (at every
// interior vertex the straight segment on the side of the two γ sectors is the odd one out).

static ori_assignment miura_zigzag(int i) { return (i % 2) ? ORI_ASSIGN_MOUNTAIN : ORI_ASSIGN_VALLEY; }

static void gen_miura(gen *g, const ori_generate_def *def)
{
    ori_pattern *p = g->p;
    int R = def->rows, C = def->cols;
    double a = def->width, b = def->height;
    double dx = b * cos(def->angle_rad), dy = b * sin(def->angle_rad);
    for (int j = 0; j <= R; ++j)
        for (int i = 0; i <= C; ++i) put_vertex(p, j * (C + 1) + i, i * a + ((j % 2) ? dx : 0.0), j * dy);
    for (int j = 0; j <= R; ++j)
        for (int i = 0; i < C; ++i) {
            bool boundary = j == 0 || j == R;
            ori_assignment asg = boundary ? ORI_ASSIGN_BOUNDARY : miura_zigzag((j % 2) ? i : i + 1);
            put_edge(g, j * (C + 1) + i, j * (C + 1) + i + 1, asg,
                     boundary ? ORI_EDGE_CLASS_BOUNDARY : ORI_EDGE_CLASS_STRAIGHT);
        }
    for (int j = 0; j < R; ++j)
        for (int i = 0; i <= C; ++i) {
            bool boundary = i == 0 || i == C;
            put_edge(g, j * (C + 1) + i, (j + 1) * (C + 1) + i, boundary ? ORI_ASSIGN_BOUNDARY : miura_zigzag(i),
                     boundary ? ORI_EDGE_CLASS_BOUNDARY : ORI_EDGE_CLASS_ZIGZAG);
        }
    for (int j = 0; j < R; ++j)
        for (int i = 0; i < C; ++i) {
            int v = j * (C + 1) + i;
            face4(p, v, v + 1, v + C + 2, v + C + 1);
        }
}

// --- Yoshimura -------------------------------------------------------------------------------
// Rows j ∈ [0, R] at y = j·h, h = (w/2)·tan θ. Even rows: C+1 vertices at x = k·w; odd rows:
// C+2 vertices at x = 0, w/2, 3w/2, …, (C−½)w, C·w. Horizontal creases V, diagonals M (4 M
// and 2 V at every interior vertex), the short vertical ends of each strip are boundary.

static int yosh_row_start(int j, int C) { return j * (C + 1) + j / 2; }

static void gen_yoshimura(gen *g, const ori_generate_def *def)
{
    ori_pattern *p = g->p;
    int R = def->rows, C = def->cols;
    double w = def->width, h = 0.5 * w * tan(def->angle_rad);
    for (int j = 0; j <= R; ++j) {
        int s = yosh_row_start(j, C);
        if (j % 2 == 0) {
            for (int k = 0; k <= C; ++k) put_vertex(p, s + k, k * w, j * h);
        } else {
            put_vertex(p, s, 0.0, j * h);
            for (int m = 1; m <= C; ++m) put_vertex(p, s + m, (m - 0.5) * w, j * h);
            put_vertex(p, s + C + 1, C * w, j * h);
        }
    }
    // Horizontal edges, row by row.
    for (int j = 0; j <= R; ++j) {
        int s = yosh_row_start(j, C), n = (j % 2) ? C + 2 : C + 1;
        bool boundary = j == 0 || j == R;
        for (int k = 0; k + 1 < n; ++k)
            put_edge(g, s + k, s + k + 1, boundary ? ORI_ASSIGN_BOUNDARY : ORI_ASSIGN_VALLEY,
                     boundary ? ORI_EDGE_CLASS_BOUNDARY : ORI_EDGE_CLASS_HORIZONTAL);
    }
    // Each strip: the two boundary ends, the 2C diagonals, then 2C+1 triangles.
    for (int j = 0; j < R; ++j) {
        bool even_below = j % 2 == 0;
        int e = yosh_row_start(even_below ? j : j + 1, C); // the row with C+1 vertices
        int o = yosh_row_start(even_below ? j + 1 : j, C); // the row with C+2 vertices
        // ends: E_0–O_0 and E_C–O_{C+1}, directed upwards
        if (even_below) {
            put_edge(g, e, o, ORI_ASSIGN_BOUNDARY, ORI_EDGE_CLASS_BOUNDARY);
            put_edge(g, e + C, o + C + 1, ORI_ASSIGN_BOUNDARY, ORI_EDGE_CLASS_BOUNDARY);
        } else {
            put_edge(g, o, e, ORI_ASSIGN_BOUNDARY, ORI_EDGE_CLASS_BOUNDARY);
            put_edge(g, o + C + 1, e + C, ORI_ASSIGN_BOUNDARY, ORI_EDGE_CLASS_BOUNDARY);
        }
        // diagonals: E_k to O_k (k ≥ 1) and O_{k+1} (k ≤ C−1)
        for (int k = 0; k <= C; ++k) {
            if (k >= 1) put_edge(g, e + k, o + k, ORI_ASSIGN_MOUNTAIN, ORI_EDGE_CLASS_DIAGONAL);
            if (k <= C - 1) put_edge(g, e + k, o + k + 1, ORI_ASSIGN_MOUNTAIN, ORI_EDGE_CLASS_DIAGONAL);
        }
        // triangles on the C+1-vertex row (apex O_{k+1}) and on the C+2-vertex row (apex E_m)
        for (int k = 0; k < C; ++k) {
            if (even_below) face3(p, e + k, e + k + 1, o + k + 1);
            else face3(p, e + k + 1, e + k, o + k + 1);
        }
        for (int m = 0; m <= C; ++m) {
            if (even_below) face3(p, o + m + 1, o + m, e + m);
            else face3(p, o + m, o + m + 1, e + m);
        }
    }
}

// --- waterbomb -------------------------------------------------------------------------------
// Grid x_i = i·w/2 (i ∈ [0, 2C]), y_j = j·h/2 (j ∈ [0, 2R]). Base row r spans y_{2r}…y_{2r+2}
// with its centres at y_{2r+1}, x_i for odd i (r even) or even i (r odd: shifted by half a
// base; the end centres lie on the side boundaries). Creases: the horizontal lines y_{2r} and
// the vertical lines x_i are M, the diagonals from each centre to its four corners are V.
// Vertices: every (i, 2r) first (row-major), then the centres row by row.

typedef struct wb_index {
    int C, R;
    int *centre_start; // R+1 entries: first centre index of base row r (absolute vertex index)
} wb_index;

static inline int wb_grid(const wb_index *x, int i, int r2) { return r2 / 2 * (2 * x->C + 1) + i; }
static inline int wb_parity(int r) { return (r % 2) ? 0 : 1; } // parity of the centre columns
static inline int wb_centre(const wb_index *x, int r, int i) { return x->centre_start[r] + (i - wb_parity(r)) / 2; }

static void gen_waterbomb(gen *g, const ori_generate_def *def)
{
    ori_pattern *p = g->p;
    int R = def->rows, C = def->cols;
    double hw = 0.5 * def->width, hh = 0.5 * def->height;
    wb_index x = {C, R, ori__alloc(sizeof(int) * (size_t)(R + 1))};
    int nv = (2 * C + 1) * (R + 1);
    for (int r = 0; r <= R; ++r)
        for (int i = 0; i <= 2 * C; ++i) put_vertex(p, wb_grid(&x, i, 2 * r), i * hw, 2 * r * hh);
    for (int r = 0; r < R; ++r) {
        x.centre_start[r] = nv;
        for (int i = wb_parity(r); i <= 2 * C; i += 2) put_vertex(p, nv++, i * hw, (2 * r + 1) * hh);
    }
    x.centre_start[R] = nv;
    // Horizontal edges, line by line.
    for (int r = 0; r <= R; ++r) {
        bool boundary = r == 0 || r == R;
        for (int i = 0; i < 2 * C; ++i)
            put_edge(g, wb_grid(&x, i, 2 * r), wb_grid(&x, i + 1, 2 * r),
                     boundary ? ORI_ASSIGN_BOUNDARY : ORI_ASSIGN_MOUNTAIN,
                     boundary ? ORI_EDGE_CLASS_BOUNDARY : ORI_EDGE_CLASS_HORIZONTAL);
    }
    // Per base row: vertical edges (split at a centre), diagonals, faces.
    for (int r = 0; r < R; ++r) {
        for (int i = 0; i <= 2 * C; ++i) {
            bool boundary = i == 0 || i == 2 * C;
            ori_assignment asg = boundary ? ORI_ASSIGN_BOUNDARY : ORI_ASSIGN_MOUNTAIN;
            ori_edge_class cls = boundary ? ORI_EDGE_CLASS_BOUNDARY : ORI_EDGE_CLASS_VERTICAL;
            int lo = wb_grid(&x, i, 2 * r), hi = wb_grid(&x, i, 2 * r + 2);
            if (i % 2 == wb_parity(r)) {
                int c = wb_centre(&x, r, i);
                put_edge(g, lo, c, asg, cls);
                put_edge(g, c, hi, asg, cls);
            } else {
                put_edge(g, lo, hi, asg, cls);
            }
        }
        for (int i = wb_parity(r); i <= 2 * C; i += 2) {
            int c = wb_centre(&x, r, i);
            for (int side = -1; side <= 1; side += 2) {
                int k = i + side;
                if (k < 0 || k > 2 * C) continue;
                put_edge(g, c, wb_grid(&x, k, 2 * r), ORI_ASSIGN_VALLEY, ORI_EDGE_CLASS_DIAGONAL);
                put_edge(g, c, wb_grid(&x, k, 2 * r + 2), ORI_ASSIGN_VALLEY, ORI_EDGE_CLASS_DIAGONAL);
            }
        }
        // Strip between x_i and x_{i+1}: one line carries the centre, the other the corners.
        for (int i = 0; i < 2 * C; ++i) {
            bool centre_left = i % 2 == wb_parity(r);
            int ci = centre_left ? i : i + 1, k = centre_left ? i + 1 : i;
            int cc = wb_centre(&x, r, ci);
            int bc = wb_grid(&x, ci, 2 * r), tc = wb_grid(&x, ci, 2 * r + 2);
            int bk = wb_grid(&x, k, 2 * r), tk = wb_grid(&x, k, 2 * r + 2);
            if (centre_left) {
                face3(p, bc, bk, cc);
                face3(p, cc, bk, tk);
                face3(p, cc, tk, tc);
            } else {
                face3(p, bk, bc, cc);
                face3(p, bk, cc, tk);
                face3(p, tk, cc, tc);
            }
        }
    }
    ori__free(x.centre_start);
}

// --- square twist ------------------------------------------------------------------------------
// Twist (i, j) sits in tile [i·Px, (i+1)·Px] × [j·Py, (j+1)·Py]; handedness χ = +1 when i + j is
// even. Its central square (side s) is rotated by −χα so that every pleat is axis-aligned;
// with p = (s/2)(cos α + sin α), q = (s/2)(cos α − sin α) its corners P0…P3 (counter-clockwise,
// P0 lower left) are, relative to the tile centre,
//   χ = +1: (−p, −q), (q, −p), (p, q), (−q, p);   χ = −1: (−q, −p), (p, −q), (q, p), (−p, q).
// Side k runs P_k → P_{k+1}; its pleat leaves along direction k (down, right, up, left) on the
// lines through P_k and P_{k+1}. Central squares are M; for χ = +1 the pleat line through P_k
// is V and through P_{k+1} M, for χ = −1 the reverse (both twists of a pleat agree).
// Vertices: 4 per twist (4(jC + i) + k), then the boundary points bottom (2 per column), right
// (2 per row), top (2 per column), left (2 per row), then the corners (0,0), (W,0), (W,H), (0,H).

typedef struct st_geom {
    int R, C;
    double px, py, p, q;
    int bottom, right, top, left, corner; // first vertex index of each boundary group
} st_geom;

static inline int st_chi(int i, int j) { return ((i + j) % 2 == 0) ? 1 : -1; }
static inline int st_v(const st_geom *s, int i, int j, int k) { return 4 * (j * s->C + i) + k; }

static ori_v2 st_corner(const st_geom *s, int i, int j, int k)
{
    double p = s->p, q = s->q;
    static const int sign_a[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    // χ = +1 uses (p, q, p, q) for x and (q, p, q, p) for y; χ = −1 the other way round.
    bool plus = st_chi(i, j) > 0;
    double ax = ((k % 2 == 0) == plus) ? p : q;
    double ay = ((k % 2 == 0) == plus) ? q : p;
    double cx = (i + 0.5) * s->px, cy = (j + 0.5) * s->py;
    return ori_v2_make(cx + sign_a[k][0] * ax, cy + sign_a[k][1] * ay);
}

// Assignment of one line of a pleat leaving side k of twist (i, j): through_start when the line
// passes through the side's start corner P_k, else through its end corner P_{k+1}.
static ori_assignment st_pleat(int i, int j, bool through_start)
{
    bool v = (st_chi(i, j) > 0) == through_start;
    return v ? ORI_ASSIGN_VALLEY : ORI_ASSIGN_MOUNTAIN;
}

static void gen_square_twist(gen *g, const ori_generate_def *def)
{
    ori_pattern *p = g->p;
    st_geom s;
    s.R = def->rows;
    s.C = def->cols;
    s.px = def->width;
    s.py = def->height;
    double a = def->angle_rad;
    double side = def->twist_size * fmin(s.px, s.py) / (cos(a) + sin(a));
    s.p = 0.5 * side * (cos(a) + sin(a));
    s.q = 0.5 * side * (cos(a) - sin(a));
    int R = s.R, C = s.C;
    double W = C * s.px, H = R * s.py;
    s.bottom = 4 * R * C;
    s.right = s.bottom + 2 * C;
    s.top = s.right + 2 * R;
    s.left = s.top + 2 * C;
    s.corner = s.left + 2 * R;
    for (int j = 0; j < R; ++j)
        for (int i = 0; i < C; ++i)
            for (int k = 0; k < 4; ++k) {
                ori_v2 c = st_corner(&s, i, j, k);
                put_vertex(p, st_v(&s, i, j, k), c.x, c.y);
            }
    // Boundary points, each pair in increasing coordinate: bottom (P0.x, P1.x of row 0),
    // right (P1.y, P2.y of column C−1), top (P3.x, P2.x of row R−1), left (P0.y, P3.y of column 0).
    for (int i = 0; i < C; ++i) {
        put_vertex(p, s.bottom + 2 * i, st_corner(&s, i, 0, 0).x, 0.0);
        put_vertex(p, s.bottom + 2 * i + 1, st_corner(&s, i, 0, 1).x, 0.0);
        put_vertex(p, s.top + 2 * i, st_corner(&s, i, R - 1, 3).x, H);
        put_vertex(p, s.top + 2 * i + 1, st_corner(&s, i, R - 1, 2).x, H);
    }
    for (int j = 0; j < R; ++j) {
        put_vertex(p, s.right + 2 * j, W, st_corner(&s, C - 1, j, 1).y);
        put_vertex(p, s.right + 2 * j + 1, W, st_corner(&s, C - 1, j, 2).y);
        put_vertex(p, s.left + 2 * j, 0.0, st_corner(&s, 0, j, 0).y);
        put_vertex(p, s.left + 2 * j + 1, 0.0, st_corner(&s, 0, j, 3).y);
    }
    put_vertex(p, s.corner + 0, 0.0, 0.0);
    put_vertex(p, s.corner + 1, W, 0.0);
    put_vertex(p, s.corner + 2, W, H);
    put_vertex(p, s.corner + 3, 0.0, H);

    // Central squares.
    for (int j = 0; j < R; ++j)
        for (int i = 0; i < C; ++i)
            for (int k = 0; k < 4; ++k)
                put_edge(g, st_v(&s, i, j, k), st_v(&s, i, j, (k + 1) % 4), ORI_ASSIGN_MOUNTAIN,
                         ORI_EDGE_CLASS_SQUARE);
    // Horizontal pleats: slot i ∈ [0, C] of row j joins twist (i−1, j) side 1 (P1 lower, P2
    // upper) to twist (i, j) side 3 (P0 lower, P3 upper).
    for (int j = 0; j < R; ++j)
        for (int i = 0; i <= C; ++i) {
            if (i == 0) {
                put_edge(g, s.left + 2 * j, st_v(&s, 0, j, 0), st_pleat(0, j, false), ORI_EDGE_CLASS_PLEAT);
                put_edge(g, s.left + 2 * j + 1, st_v(&s, 0, j, 3), st_pleat(0, j, true), ORI_EDGE_CLASS_PLEAT);
            } else if (i == C) {
                put_edge(g, st_v(&s, C - 1, j, 1), s.right + 2 * j, st_pleat(C - 1, j, true), ORI_EDGE_CLASS_PLEAT);
                put_edge(g, st_v(&s, C - 1, j, 2), s.right + 2 * j + 1, st_pleat(C - 1, j, false),
                         ORI_EDGE_CLASS_PLEAT);
            } else {
                put_edge(g, st_v(&s, i - 1, j, 1), st_v(&s, i, j, 0), st_pleat(i - 1, j, true), ORI_EDGE_CLASS_PLEAT);
                put_edge(g, st_v(&s, i - 1, j, 2), st_v(&s, i, j, 3), st_pleat(i - 1, j, false), ORI_EDGE_CLASS_PLEAT);
            }
        }
    // Vertical pleats: slot j ∈ [0, R] of column i joins twist (i, j−1) side 2 (P3 left, P2
    // right) to twist (i, j) side 0 (P0 left, P1 right).
    for (int i = 0; i < C; ++i)
        for (int j = 0; j <= R; ++j) {
            if (j == 0) {
                put_edge(g, s.bottom + 2 * i, st_v(&s, i, 0, 0), st_pleat(i, 0, true), ORI_EDGE_CLASS_PLEAT);
                put_edge(g, s.bottom + 2 * i + 1, st_v(&s, i, 0, 1), st_pleat(i, 0, false), ORI_EDGE_CLASS_PLEAT);
            } else if (j == R) {
                put_edge(g, st_v(&s, i, R - 1, 3), s.top + 2 * i, st_pleat(i, R - 1, false), ORI_EDGE_CLASS_PLEAT);
                put_edge(g, st_v(&s, i, R - 1, 2), s.top + 2 * i + 1, st_pleat(i, R - 1, true), ORI_EDGE_CLASS_PLEAT);
            } else {
                put_edge(g, st_v(&s, i, j - 1, 3), st_v(&s, i, j, 0), st_pleat(i, j - 1, false), ORI_EDGE_CLASS_PLEAT);
                put_edge(g, st_v(&s, i, j - 1, 2), st_v(&s, i, j, 1), st_pleat(i, j - 1, true), ORI_EDGE_CLASS_PLEAT);
            }
        }
    // Boundary cycle, counter-clockwise from (0, 0).
    int prev = s.corner + 0;
    for (int k = 0; k < 2 * C; ++k) {
        put_edge(g, prev, s.bottom + k, ORI_ASSIGN_BOUNDARY, ORI_EDGE_CLASS_BOUNDARY);
        prev = s.bottom + k;
    }
    put_edge(g, prev, s.corner + 1, ORI_ASSIGN_BOUNDARY, ORI_EDGE_CLASS_BOUNDARY);
    prev = s.corner + 1;
    for (int k = 0; k < 2 * R; ++k) {
        put_edge(g, prev, s.right + k, ORI_ASSIGN_BOUNDARY, ORI_EDGE_CLASS_BOUNDARY);
        prev = s.right + k;
    }
    put_edge(g, prev, s.corner + 2, ORI_ASSIGN_BOUNDARY, ORI_EDGE_CLASS_BOUNDARY);
    prev = s.corner + 2;
    for (int k = 2 * C - 1; k >= 0; --k) {
        put_edge(g, prev, s.top + k, ORI_ASSIGN_BOUNDARY, ORI_EDGE_CLASS_BOUNDARY);
        prev = s.top + k;
    }
    put_edge(g, prev, s.corner + 3, ORI_ASSIGN_BOUNDARY, ORI_EDGE_CLASS_BOUNDARY);
    prev = s.corner + 3;
    for (int k = 2 * R - 1; k >= 0; --k) {
        put_edge(g, prev, s.left + k, ORI_ASSIGN_BOUNDARY, ORI_EDGE_CLASS_BOUNDARY);
        prev = s.left + k;
    }
    put_edge(g, prev, s.corner + 0, ORI_ASSIGN_BOUNDARY, ORI_EDGE_CLASS_BOUNDARY);

    // Faces: squares, horizontal pleats, vertical pleats, corner regions.
    for (int j = 0; j < R; ++j)
        for (int i = 0; i < C; ++i) face4(p, st_v(&s, i, j, 0), st_v(&s, i, j, 1), st_v(&s, i, j, 2), st_v(&s, i, j, 3));
    for (int j = 0; j < R; ++j)
        for (int i = 0; i <= C; ++i) {
            int ll = i == 0 ? s.left + 2 * j : st_v(&s, i - 1, j, 1);
            int ul = i == 0 ? s.left + 2 * j + 1 : st_v(&s, i - 1, j, 2);
            int lr = i == C ? s.right + 2 * j : st_v(&s, i, j, 0);
            int ur = i == C ? s.right + 2 * j + 1 : st_v(&s, i, j, 3);
            face4(p, ll, lr, ur, ul);
        }
    for (int i = 0; i < C; ++i)
        for (int j = 0; j <= R; ++j) {
            int ll = j == 0 ? s.bottom + 2 * i : st_v(&s, i, j - 1, 3);
            int lr = j == 0 ? s.bottom + 2 * i + 1 : st_v(&s, i, j - 1, 2);
            int ul = j == R ? s.top + 2 * i : st_v(&s, i, j, 0);
            int ur = j == R ? s.top + 2 * i + 1 : st_v(&s, i, j, 1);
            face4(p, ll, lr, ur, ul);
        }
    // Corner region (i, j) around grid point (i·Px, j·Py): the corners of the (up to) four
    // twists around it, missing twists replaced by the boundary points of the pleats.
    for (int j = 0; j <= R; ++j)
        for (int i = 0; i <= C; ++i) {
            bool l = i > 0, r = i < C, d = j > 0, u = j < R;
            if (l && r && d && u) {
                face4(p, st_v(&s, i - 1, j - 1, 2), st_v(&s, i, j - 1, 3), st_v(&s, i, j, 0), st_v(&s, i - 1, j, 1));
            } else if (l && r && u) { // bottom side
                face4(p, s.bottom + 2 * (i - 1) + 1, s.bottom + 2 * i, st_v(&s, i, 0, 0), st_v(&s, i - 1, 0, 1));
            } else if (l && r && d) { // top side
                face4(p, st_v(&s, i - 1, R - 1, 2), st_v(&s, i, R - 1, 3), s.top + 2 * i, s.top + 2 * (i - 1) + 1);
            } else if (d && u && r) { // left side
                face4(p, st_v(&s, 0, j - 1, 3), st_v(&s, 0, j, 0), s.left + 2 * j, s.left + 2 * (j - 1) + 1);
            } else if (d && u && l) { // right side
                face4(p, st_v(&s, C - 1, j - 1, 2), s.right + 2 * (j - 1) + 1, s.right + 2 * j, st_v(&s, C - 1, j, 1));
            } else if (r && u) { // (0, 0)
                face4(p, s.corner + 0, s.bottom + 0, st_v(&s, 0, 0, 0), s.left + 0);
            } else if (l && u) { // (W, 0)
                face4(p, s.bottom + 2 * C - 1, s.corner + 1, s.right + 0, st_v(&s, C - 1, 0, 1));
            } else if (l && d) { // (W, H)
                face4(p, st_v(&s, C - 1, R - 1, 2), s.right + 2 * R - 1, s.corner + 2, s.top + 2 * C - 1);
            } else { // (0, H)
                face4(p, st_v(&s, 0, R - 1, 3), s.top + 0, s.corner + 3, s.left + 2 * R - 1);
            }
        }
}

// --- Kresling --------------------------------------------------------------------------------
// Vertex (i, k), i ∈ [0, n], k ∈ [0, R]: index k(n+1) + i at (i·a + k·s, k·H). Edges: polygon
// edges row by row (B on the first and last row, else M), then per storey the laterals
// (i, k)–(i, k+1) (the seam i = 0 and i = n is B, the others M) and the diagonals
// (i, k)–(i+1, k+1) (V). Faces per storey and column: (B_i, B_{i+1}, T_{i+1}), (B_i, T_{i+1}, T_i).

static void gen_kresling(gen *g, const ori_generate_def *def)
{
    ori_pattern *p = g->p;
    int n = def->sides, R = def->rows;
    kresling_geom k = kresling_geometry(def);
    for (int r = 0; r <= R; ++r)
        for (int i = 0; i <= n; ++i) put_vertex(p, r * (n + 1) + i, i * k.a + r * k.s, r * k.strip_h);
    for (int r = 0; r <= R; ++r) {
        bool boundary = r == 0 || r == R;
        for (int i = 0; i < n; ++i)
            put_edge(g, r * (n + 1) + i, r * (n + 1) + i + 1, boundary ? ORI_ASSIGN_BOUNDARY : ORI_ASSIGN_MOUNTAIN,
                     boundary ? ORI_EDGE_CLASS_BOUNDARY : ORI_EDGE_CLASS_POLYGON);
    }
    for (int r = 0; r < R; ++r) {
        int b = r * (n + 1), t = (r + 1) * (n + 1);
        for (int i = 0; i <= n; ++i) {
            bool seam = i == 0 || i == n;
            put_edge(g, b + i, t + i, seam ? ORI_ASSIGN_BOUNDARY : ORI_ASSIGN_MOUNTAIN,
                     seam ? ORI_EDGE_CLASS_SEAM : ORI_EDGE_CLASS_LATERAL);
        }
        for (int i = 0; i < n; ++i) put_edge(g, b + i, t + i + 1, ORI_ASSIGN_VALLEY, ORI_EDGE_CLASS_DIAGONAL);
        for (int i = 0; i < n; ++i) {
            face3(p, b + i, b + i + 1, t + i + 1);
            face3(p, b + i, t + i + 1, t + i);
        }
    }
}

// --- entry point -----------------------------------------------------------------------------

// --- the table ---------------------------------------------------------------------------------

#define GRID (ORI_GEN_ROWS | ORI_GEN_COLS | ORI_GEN_WIDTH)
static const tess_row tess_table[ORI_TESS_COUNT] = {
    [ORI_TESS_MIURA] = {"miura", GRID | ORI_GEN_ANGLE | ORI_GEN_HEIGHT, 4, ORI_PI / 3.0, 4, counts_miura, gen_miura},
    [ORI_TESS_YOSHIMURA] = {"yoshimura", GRID | ORI_GEN_ANGLE, 4, ORI_PI / 6.0, 3, counts_yoshimura, gen_yoshimura},
    [ORI_TESS_WATERBOMB] = {"waterbomb", GRID | ORI_GEN_HEIGHT, 4, 0.0, 3, counts_waterbomb, gen_waterbomb},
    [ORI_TESS_SQUARE_TWIST] = {"square-twist", GRID | ORI_GEN_ANGLE | ORI_GEN_HEIGHT | ORI_GEN_TWIST_SIZE, 4, ORI_PI / 4.0,
                               4, counts_square_twist, gen_square_twist},
    [ORI_TESS_KRESLING] = {"kresling",
                           ORI_GEN_ROWS | ORI_GEN_SIDES | ORI_GEN_WIDTH | ORI_GEN_ANGLE | ORI_GEN_HEIGHT | ORI_GEN_BISTABLE_HEIGHT,
                           3, ORI_PI / 6.0, 3, counts_kresling, gen_kresling},
};

static const tess_row *tess_row_of(ori_tessellation kind) { return &tess_table[kind]; }

unsigned ori_tessellation_params(ori_tessellation kind)
{
    ORI_ASSERT((int)kind >= 0 && kind < ORI_TESS_COUNT);
    return tess_table[kind].params;
}

ori_status ori_generate(const ori_generate_def *def, ori_pattern **out, ori_edge_class **classes, ori_error *error)
{
    ORI_ASSERT(def && out);
    *out = NULL;
    if (classes) *classes = NULL;
    ori_pattern_counts n;
    ori_status st = ori_generate_counts(def, &n, error);
    if (st != ORI_OK) return st;

    ori_pattern_def pdef = ori_default_pattern_def();
    pdef.vertex_capacity = (int)n.vertices;
    pdef.edge_capacity = (int)n.edges;
    ori_pattern *p = ori_pattern_create(&pdef);
    const tess_row *t = tess_row_of(def->kind);
    ori__pattern_reserve_faces(p, (int)n.faces, (int)(t->face_size * n.faces));
    p->vertex_count = (int)n.vertices;
    p->has_fold_angles = true;
    gen g = {p, classes ? ori__alloc(sizeof(ori_edge_class) * (size_t)n.edges) : NULL};
    t->write(&g, def);
    ORI_ASSERT(p->edge_count == n.edges && p->face_count == n.faces);
    ORI_ASSERT(p->face_vertex_count == t->face_size * n.faces);

    // The patterns are planar by construction (tests/test_generate.c runs the full planarity
    // check on every generator), so the build checks indices, lengths, duplicate edges and that
    // every face side is an edge with one face per side, but skips the all-pairs crossing test
    // that would dominate time and memory at a million cells.
    ori_build_def bdef = ori_default_build_def();
    bdef.check_planarity = false;
    st = ori_pattern_build(p, &bdef, error);
    if (st != ORI_OK) {
        // Only degenerate geometry from extreme parameters gets here (e.g. cells thinner than
        // the length tolerance).
        ori_pattern_destroy(p);
        ori__free(g.cls);
        return st;
    }
    *out = p;
    if (classes) *classes = g.cls;
    return ORI_OK;
}
