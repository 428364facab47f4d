// Global flat-foldability (layer orders): Flat-Folder's published results for every pattern of
// ../shared/patterns/flat-folder (state counts, component structure, variable and constraint
// counts), the unsatisfiable examples with their reasons, Rabbit Ear's kabuto (all nine
// published faceOrders) and crane, the FOLD spec's diagonal fold, a property test against an
// independent brute force on random flat-foldable patterns, exact big counts, bad input, FOLD and
// SVG output, limits, threads and cancellation, and the `layers` command.
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <jansson.h>
#include <orikin/arrangement.h>
#include <orikin/layers.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "layers/layers_internal.h"
#include "support.h"

TestSuite(layers, .init = test_leak_setup, .fini = test_leak_check);

// --- helpers -------------------------------------------------------------------------------

static ori_layers *solve_pattern(const ori_pattern *p, const ori_layers_def *def)
{
    ori_layers *L = NULL;
    ori_error err;
    ori_error_clear(&err);
    ori_status st = ori_layers_create(p, def, &L, &err);
    cr_assert_eq(st, ORI_OK, "create: %s", err.message);
    st = ori_layers_count(L, &err);
    cr_assert_eq(st, ORI_OK, "count: %s", err.message);
    return L;
}

static char *states_of(const ori_layers *L) { return ori_layers_state_count(L); }

// "|1|3|3|" from the component counts.
static void component_string(const ori_layers *L, char *buf, size_t size)
{
    size_t n = (size_t)snprintf(buf, size, "|");
    for (int c = 0; c < ori_layers_component_count(L); ++c) {
        char *s = ori_layers_component_states(L, c);
        n += (size_t)snprintf(buf + n, size - n, "%s|", s);
        ori_buffer_free(s);
    }
}

// One row of a Flat-Folder CSV (fields split at commas; the fields used here have none).
typedef struct ff_row {
    char number[8];
    long variables, taco_taco, taco_tortilla, tortilla_tortilla, transitivity;
    char states[128];
    char components[512];
    bool found;
} ff_row;

static ff_row ff_lookup(const char *csv_path, const char *number)
{
    ff_row r;
    memset(&r, 0, sizeof r);
    FILE *f = fopen(csv_path, "r");
    cr_assert(f, "cannot open %s", csv_path);
    char line[4096];
    cr_assert(fgets(line, sizeof line, f)); // header
    while (fgets(line, sizeof line, f)) {
        char *field[32];
        int n = 0;
        for (char *p = line; n < 32;) {
            field[n++] = p;
            char *c = strchr(p, ',');
            if (!c) break;
            *c = '\0';
            p = c + 1;
        }
        if (n < 19 || strcmp(field[0], number) != 0) continue;
        // number,author,title,vertices,edges,faces,eps,variables,taco-taco,taco-tortilla,
        // tortilla-tortilla,transitivity,reduced_trans,components,limited,states,
        // component_assignments,setup_sec,solve_sec
        int o = n - 19; // a title with commas shifts the later fields
        snprintf(r.number, sizeof r.number, "%s", field[0]);
        r.variables = atol(field[7 + o]);
        r.taco_taco = atol(field[8 + o]);
        r.taco_tortilla = atol(field[9 + o]);
        r.tortilla_tortilla = atol(field[10 + o]);
        r.transitivity = atol(field[11 + o]);
        snprintf(r.states, sizeof r.states, "%s", field[15 + o]);
        snprintf(r.components, sizeof r.components, "%s", field[16 + o]);
        r.found = true;
        break;
    }
    fclose(f);
    return r;
}

// --- Flat-Folder's published results --------------------------------------------------------

Test(layers, flat_folder_examples_match_published_counts_and_components, .timeout = 60)
{
    const char *dir = test_require_shared("flat-folder");
    DIR *d = opendir(dir);
    cr_assert(d);
    char dirbuf[4096];
    snprintf(dirbuf, sizeof dirbuf, "%s", dir);
    struct dirent *ent;
    int checked = 0;
    while ((ent = readdir(d))) {
        const char *name = ent->d_name;
        size_t len = strlen(name);
        if (len < 6 || strcmp(name + len - 5, ".fold") != 0) continue;
        const char *set = strncmp(name, "grids_", 6) == 0 ? "grids" : strncmp(name, "instagram_", 10) == 0 ? "instagram" : NULL;
        if (!set) continue;
        char number[4] = {0};
        memcpy(number, name + strlen(set) + 1, 3);
        char csv[4200], path[4400];
        snprintf(csv, sizeof csv, "%s/%s_data.csv", dirbuf, set);
        snprintf(path, sizeof path, "%s/%s", dirbuf, name);
        ff_row r = ff_lookup(csv, number);
        cr_assert(r.found, "%s: no row %s in %s", name, number, csv);
        ori_pattern *p = test_load_pattern(path, 0);
        ori_layers *L = solve_pattern(p, NULL);
        ori_layers_info in = ori_layers_get_info(L);
        char *states = states_of(L);
        char comps[512];
        component_string(L, comps, sizeof comps);
        // Exact equality: counts are integers.
        cr_expect_str_eq(states, r.states, "%s: states", name);
        cr_expect_str_eq(comps, r.components, "%s: components", name);
        cr_expect_eq(in.variables, r.variables, "%s: variables", name);
        cr_expect_eq(in.taco_taco, r.taco_taco, "%s: taco-taco", name);
        cr_expect_eq(in.taco_tortilla, r.taco_tortilla, "%s: taco-tortilla", name);
        cr_expect_eq(in.tortilla_tortilla, r.tortilla_tortilla, "%s: tortilla-tortilla", name);
        cr_expect_eq(in.transitivity, r.transitivity, "%s: transitivity", name);
        ori_buffer_free(states);
        ori_layers_destroy(L);
        ori_pattern_destroy(p);
        checked++;
    }
    closedir(d);
    cr_assert_geq(checked, 12, "only %d Flat-Folder examples found", checked);
}

Test(layers, named_examples_sailboat_kabuto_crane)
{
    struct {
        const char *file, *states, *comps;
    } cases[] = {
        {"flat-folder/instagram_001_traditional_Sailboat.fold", "4", "|1|4|"},
        {"flat-folder/instagram_002_traditional_Kabuto.fold", "9", "|1|3|3|"},
        {"flat-folder/instagram_004_traditional_Crane.fold", "5", "|1|5|"},
        {"flat-folder/instagram_043_ku_Quad_Overlap.fold", "65536", "|1|2|2|2|2|2|2|2|2|2|2|2|2|2|2|2|2|"},
        // No faces_vertices: the faces are traced from the edges.
        {"flat-folder/original_kabuto.fold", "9", "|1|3|3|"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        ori_pattern *p = test_load_pattern(test_require_shared(cases[i].file), 0);
        ori_layers *L = solve_pattern(p, NULL);
        char *s = states_of(L);
        char comps[512];
        component_string(L, comps, sizeof comps);
        cr_expect_str_eq(s, cases[i].states, "%s", cases[i].file);
        cr_expect_str_eq(comps, cases[i].comps, "%s", cases[i].file);
        ori_buffer_free(s);
        ori_layers_destroy(L);
        ori_pattern_destroy(p);
    }
}

Test(layers, unsatisfiable_examples_give_zero_with_the_reason)
{
    // Bad Twist: every vertex passes Kawasaki, Maekawa and big-little-big, yet three faces are
    // forced into a cycle by propagation alone.
    ori_pattern *p = test_load_pattern(test_require_shared("flat-folder/unsatisfiable_001_ku_Bad_Twist.fold"), 0);
    ori_layers *L = solve_pattern(p, NULL);
    char *s = states_of(L);
    cr_assert_str_eq(s, "0");
    ori_buffer_free(s);
    ori_layers_conflict c;
    cr_assert(ori_layers_get_conflict(L, &c));
    cr_assert_eq(c.constraint, ORI_LAYERS_TRANSITIVITY);
    cr_assert_eq(c.face_count, 3);
    cr_assert_eq(c.vertex, ORI_NULL_INDEX);
    // The three faces overlap pairwise (they are a constraint of this pattern).
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j) cr_assert_geq(ori__layers_var(L, c.faces[i], c.faces[j]), 0);
    int inv[64];
    int n = ori_layers_conflict_faces(L, inv, 64);
    cr_assert_geq(n, 3);
    ori_layers_info in = ori_layers_get_info(L);
    cr_assert(!in.satisfiable);
    ori_error err;
    cr_assert_eq(ori_layers_select_state(L, "0", &err), ORI_ERR_RANGE);
    ori_layers_destroy(L);
    ori_pattern_destroy(p);

    // One vertex (135, 63.4, 45, 116.6 degrees; V M V V): the 45 degree sector has V on both
    // sides, so big-little-big fails at vertex 3.
    p = test_load_pattern(test_require_shared("flat-folder/unsatisfiable_008_tachioripa_not_foldable.fold"), 0);
    L = solve_pattern(p, NULL);
    s = states_of(L);
    cr_assert_str_eq(s, "0");
    ori_buffer_free(s);
    cr_assert(ori_layers_get_conflict(L, &c));
    cr_assert_eq(c.constraint, ORI_LAYERS_LOCAL);
    cr_assert_eq(c.vertex, 3);
    cr_assert(strstr(c.detail, "big_little_big"), "%s", c.detail);
    ori_layers_destroy(L);
    ori_pattern_destroy(p);
}

// --- Rabbit Ear and the FOLD spec --------------------------------------------------------------

// A faceOrders triple as "f above g" with f < g: +1 or −1 (FOLD: s = +1 when f lies on the side
// g's normal points to).
static int above_lo(const ori_layers *L, int f, int g, int s)
{
    int above_fg = s * (ori_layers_face_flipped(L, g) ? -1 : 1);
    return f < g ? above_fg : -above_fg;
}

Test(layers, rabbit_ear_kabuto_all_nine_published_layerings)
{
    const char *path = test_require_shared("rabbit-ear/fold_kabuto.fold");
    // Frame 0 is the flat folded form (faces wound by side); frames 1–8 add the other eight
    // layerings' faceOrders; frame 9 is the crease pattern.
    ori_pattern *p = test_load_pattern(path, 0);
    ori_layers *L = solve_pattern(p, NULL);
    char *s = states_of(L);
    cr_assert_str_eq(s, "9");
    ori_buffer_free(s);
    int nv = ori_layers_get_info(L).variables;
    cr_assert_eq(nv, 117);
    // The published orders, as a ±1 vector over our variables.
    json_error_t jerr;
    json_t *doc = json_load_file(path, 0, &jerr);
    cr_assert(doc);
    int8_t published[9][117];
    for (int fr = 0; fr < 9; ++fr) {
        json_t *obj = fr == 0 ? doc : json_array_get(json_object_get(doc, "file_frames"), (size_t)(fr - 1));
        json_t *fo = json_object_get(obj, "faceOrders");
        cr_assert_eq(json_array_size(fo), 117);
        memset(published[fr], 0, sizeof published[fr]);
        for (size_t i = 0; i < json_array_size(fo); ++i) {
            json_t *t = json_array_get(fo, i);
            int f = (int)json_integer_value(json_array_get(t, 0)), g = (int)json_integer_value(json_array_get(t, 1));
            int sgn = (int)json_integer_value(json_array_get(t, 2));
            int v = ori__layers_var(L, f, g);
            cr_assert_geq(v, 0, "published pair %d %d does not overlap", f, g);
            published[fr][v] = (int8_t)above_lo(L, f, g, sgn);
        }
        for (int v = 0; v < 117; ++v) cr_assert_neq(published[fr][v], 0, "frame %d lacks variable %d", fr, v);
    }
    json_decref(doc);
    bool matched[9] = {false};
    for (int k = 0; k < 9; ++k) {
        char ks[4];
        snprintf(ks, sizeof ks, "%d", k);
        ori_error err;
        cr_assert_eq(ori_layers_select_state(L, ks, &err), ORI_OK, "%s", err.message);
        int fo[3 * 117];
        cr_assert_eq(ori_layers_face_orders(L, fo, 117), 117);
        int8_t mine[117];
        for (int v = 0; v < 117; ++v) mine[v] = (int8_t)above_lo(L, fo[3 * v], fo[3 * v + 1], fo[3 * v + 2]);
        int hit = -1;
        for (int fr = 0; fr < 9 && hit < 0; ++fr)
            if (memcmp(mine, published[fr], sizeof mine) == 0) hit = fr;
        cr_assert_geq(hit, 0, "state %d is none of the published layerings", k);
        cr_assert(!matched[hit], "two states equal published frame %d", hit);
        matched[hit] = true;
    }
    ori_layers_destroy(L);
    ori_pattern_destroy(p);

    // The crease pattern frame folds to the same nine.
    p = test_load_pattern(path, 9);
    L = solve_pattern(p, NULL);
    s = states_of(L);
    cr_assert_str_eq(s, "9");
    ori_buffer_free(s);
    ori_layers_destroy(L);
    ori_pattern_destroy(p);
}

Test(layers, rabbit_ear_crane_three_states)
{
    // Rabbit Ear's published solution of its crane (tests/files/json/crane-layer-solver.json):
    // 802 face orders fixed, one branch of 3.
    ori_pattern *p = test_load_pattern(test_require_shared("rabbit-ear/fold_crane-cp.fold"), 0);
    ori_layers *L = solve_pattern(p, NULL);
    char *s = states_of(L);
    cr_assert_str_eq(s, "3");
    ori_buffer_free(s);
    ori_layers_info in = ori_layers_get_info(L);
    cr_assert_eq(in.fixed_variables, 802);
    cr_assert_eq(in.components, 2);
    ori_layers_destroy(L);
    ori_pattern_destroy(p);
}

Test(layers, fold_spec_diagonal_matches_the_folded_file)
{
    ori_pattern *p = test_load_pattern(test_require_shared("fold-spec/diagonal-cp.fold"), 0);
    ori_layers *L = solve_pattern(p, NULL);
    char *s = states_of(L);
    cr_assert_str_eq(s, "1");
    ori_buffer_free(s);
    ori_error err;
    cr_assert_eq(ori_layers_select_state(L, "0", &err), ORI_OK);
    int fo[3];
    cr_assert_eq(ori_layers_face_orders(L, fo, 1), 1);
    // Valley diagonal: face 1 folds onto face 0's front (+z) and lies face-down, so face 0 is on
    // the side face 1's normal points to: [0, 1, +1].
    cr_assert_eq(fo[0], 0);
    cr_assert_eq(fo[1], 1);
    cr_assert_eq(fo[2], 1);
    // The folded file: same folded coordinates, transforms and orientations.
    json_error_t jerr;
    json_t *doc = json_load_file(test_require_shared("fold-spec/diagonal-folded.fold"), 0, &jerr);
    cr_assert(doc);
    json_t *vc = json_object_get(doc, "vertices_coords");
    for (int v = 0; v < 4; ++v) {
        ori_v2 q = ori_layers_folded_vertex(L, v);
        json_t *c = json_array_get(vc, (size_t)v);
        cr_assert_float_eq(q.x, json_number_value(json_array_get(c, 0)), 1e-15);
        cr_assert_float_eq(q.y, json_number_value(json_array_get(c, 1)), 1e-15);
    }
    json_t *xf = json_object_get(doc, "faces_flatFoldTransform");
    json_t *orient = json_object_get(doc, "faces_flatFoldOrientation");
    for (int f = 0; f < 2; ++f) {
        double t[6];
        ori_layers_face_transform(L, f, t);
        for (int r = 0; r < 2; ++r)
            for (int c = 0; c < 3; ++c)
                cr_assert_float_eq(t[3 * r + c], json_number_value(json_array_get(json_array_get(json_array_get(xf, (size_t)f), (size_t)r), (size_t)c)), 1e-15);
        cr_assert_eq(ori_layers_face_flipped(L, f) ? -1 : 1, (int)json_integer_value(json_array_get(orient, (size_t)f)));
    }
    // The file's transforms, given to the crease pattern, place the faces the same way; a
    // transform that is not an isometry is refused, naming the face.
    double given[12];
    for (int f = 0; f < 2; ++f)
        for (int r = 0; r < 2; ++r)
            for (int c = 0; c < 3; ++c)
                given[6 * f + 3 * r + c] = json_number_value(json_array_get(json_array_get(json_array_get(xf, (size_t)f), (size_t)r), (size_t)c));
    json_decref(doc);
    ori_layers_destroy(L);
    ori_layers_def def = ori_default_layers_def();
    def.face_transforms = given;
    def.face_transform_count = 2;
    L = solve_pattern(p, &def);
    cr_assert_eq(ori_layers_select_state(L, "0", &err), ORI_OK);
    cr_assert_eq(ori_layers_face_orders(L, fo, 1), 1);
    cr_assert_eq(fo[2], 1);
    cr_assert(ori_layers_face_flipped(L, 1));
    ori_layers_destroy(L);
    given[6 + 1] *= 1.5; // face 1 stretched: not an isometry
    cr_assert_eq(ori_layers_create(p, &def, &L, &err), ORI_ERR_ARGUMENT);
    cr_assert_str_eq(err.field, "faces_flatFoldTransform");
    cr_assert_eq(err.element, 1);
    ori_pattern_destroy(p);
    // Solving the folded form itself gives the same single order.
    p = test_load_pattern(test_require_shared("fold-spec/diagonal-folded.fold"), 0);
    L = solve_pattern(p, NULL);
    cr_assert_eq(ori_layers_select_state(L, "0", &err), ORI_OK);
    cr_assert_eq(ori_layers_face_orders(L, fo, 1), 1);
    cr_assert_eq(fo[2], 1);
    ori_layers_destroy(L);
    ori_pattern_destroy(p);
}

// --- property test: random flat-foldable patterns against a brute force ----------------------

static uint64_t rng = 0x2545F4914F6CDD1DULL;
static uint64_t rnd(void)
{
    rng ^= rng >> 12;
    rng ^= rng << 25;
    rng ^= rng >> 27;
    return rng * 2685821657736338717ULL;
}
static double rnd_unit(void) { return (double)(rnd() >> 11) / 9007199254740992.0; }

#define MAXP 16  // polygon corners
#define MAXF 10  // faces
#define MAXS 64  // crease segments

typedef struct poly {
    ori_v2 v[MAXP];
    int n;
} poly;

static double area2(const poly *p)
{
    double a = 0;
    for (int i = 0; i < p->n; ++i) a += ori_v2_cross(p->v[i], p->v[(i + 1) % p->n]);
    return a;
}

// Keep the part of convex p where dot(n, x) ≤ c.
static poly clip_half(const poly *p, ori_v2 n, double c)
{
    poly r;
    r.n = 0;
    for (int i = 0; i < p->n; ++i) {
        ori_v2 a = p->v[i], b = p->v[(i + 1) % p->n];
        double da = ori_v2_dot(n, a) - c, db = ori_v2_dot(n, b) - c;
        if (da <= 0) r.v[r.n++] = a;
        if ((da < 0 && db > 0) || (da > 0 && db < 0)) r.v[r.n++] = ori_v2_add(a, ori_v2_scale(ori_v2_sub(b, a), da / (da - db)));
    }
    return r;
}

// Intersection of convex polygons (q counter-clockwise).
static poly clip_poly(const poly *p, const poly *q)
{
    poly r = *p;
    for (int i = 0; i < q->n && r.n > 0; ++i) {
        ori_v2 a = q->v[i], b = q->v[(i + 1) % q->n];
        ori_v2 n = ori_v2_make(b.y - a.y, a.x - b.x); // outward normal of a CCW edge
        r = clip_half(&r, n, ori_v2_dot(n, a));
    }
    return r;
}

static void apply_t(const double t[6], ori_v2 p, ori_v2 *out)
{
    *out = ori_v2_make(t[0] * p.x + t[1] * p.y + t[2], t[3] * p.x + t[4] * p.y + t[5]);
}

typedef struct piece {
    poly cp;      // in crease-pattern coordinates, CCW
    double t[6];  // crease pattern → folded
} piece;

// A flat-foldable pattern made by simple folds of a square (each fold folds every layer on one
// side of a line over the others), with some creases then made U. Returns NULL when the random
// lines gave degenerate pieces (the caller retries). The pieces are the faces to be.
static ori_pattern *simple_folds(int folds, piece *pieces, int *npieces)
{
    piece P[MAXF];
    int n = 1;
    ori_segment seg[MAXS];
    int ns = 0;
    P[0].cp.n = 4;
    P[0].cp.v[0] = ori_v2_make(0, 0);
    P[0].cp.v[1] = ori_v2_make(1, 0);
    P[0].cp.v[2] = ori_v2_make(1, 1);
    P[0].cp.v[3] = ori_v2_make(0, 1);
    double id[6] = {1, 0, 0, 0, 1, 0};
    memcpy(P[0].t, id, sizeof id);
    for (int i = 0; i < 4; ++i) {
        seg[ns].a = P[0].cp.v[i];
        seg[ns].b = P[0].cp.v[(i + 1) % 4];
        seg[ns].assignment = ORI_ASSIGN_BOUNDARY;
        seg[ns++].fold_angle_rad = 0;
    }
    for (int k = 0; k < folds; ++k) {
        // A random line through the folded image: through a random corner's neighbourhood.
        double lo_x = 1e9, hi_x = -1e9, lo_y = 1e9, hi_y = -1e9;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < P[i].cp.n; ++j) {
                ori_v2 q;
                apply_t(P[i].t, P[i].cp.v[j], &q);
                lo_x = fmin(lo_x, q.x), hi_x = fmax(hi_x, q.x), lo_y = fmin(lo_y, q.y), hi_y = fmax(hi_y, q.y);
            }
        ori_v2 c = ori_v2_make(lo_x + (0.25 + 0.5 * rnd_unit()) * (hi_x - lo_x), lo_y + (0.25 + 0.5 * rnd_unit()) * (hi_y - lo_y));
        double ang = ORI_PI * rnd_unit();
        ori_v2 d = ori_v2_make(cos(ang), sin(ang)), nrm = ori_v2_make(-d.y, d.x);
        double off = ori_v2_dot(nrm, c);
        bool up = rnd() & 1;
        piece Q[MAXF];
        int m = 0;
        for (int i = 0; i < n; ++i) {
            // The line in this piece's crease-pattern coordinates: folded x = A p + b.
            const double *t = P[i].t;
            ori_v2 ncp = ori_v2_make(nrm.x * t[0] + nrm.y * t[3], nrm.x * t[1] + nrm.y * t[4]);
            double ccp = off - (nrm.x * t[2] + nrm.y * t[5]);
            poly stay = clip_half(&P[i].cp, ncp, ccp);
            ori_v2 neg = ori_v2_scale(ncp, -1);
            poly move = clip_half(&P[i].cp, neg, -ccp);
            double as = area2(&stay), am = area2(&move);
            if ((stay.n > 0 && as < 2e-3) || (move.n > 0 && am < 2e-3)) return NULL;
            // Every vertex of the piece well away from the line (no near-coincidences).
            for (int j = 0; j < P[i].cp.n; ++j) {
                double dist = fabs(ori_v2_dot(ncp, P[i].cp.v[j]) - ccp);
                if (dist < 0.02) return NULL;
            }
            if (stay.n >= 3 && move.n >= 3) {
                if (m + 2 > MAXF || ns >= MAXS) return NULL;
                // The crease: the points of stay on the line.
                ori_v2 e[2];
                int ne = 0;
                for (int j = 0; j < stay.n && ne < 2; ++j)
                    if (fabs(ori_v2_dot(ncp, stay.v[j]) - ccp) < 1e-12) e[ne++] = stay.v[j];
                if (ne < 2) return NULL;
                bool front_up = t[0] * t[4] - t[1] * t[3] > 0;
                seg[ns].a = e[0];
                seg[ns].b = e[1];
                seg[ns].assignment = (up == front_up) ? ORI_ASSIGN_VALLEY : ORI_ASSIGN_MOUNTAIN;
                seg[ns++].fold_angle_rad = 0;
            }
            if (stay.n >= 3) {
                Q[m].cp = stay;
                memcpy(Q[m++].t, t, sizeof(double) * 6);
            }
            if (move.n >= 3) {
                if (m >= MAXF) return NULL;
                Q[m].cp = move;
                // Reflect across the line: r(x) = x − 2 (n·x − off) n.
                double r[6] = {1 - 2 * nrm.x * nrm.x, -2 * nrm.x * nrm.y, 2 * off * nrm.x,
                               -2 * nrm.x * nrm.y, 1 - 2 * nrm.y * nrm.y, 2 * off * nrm.y};
                double *o = Q[m++].t;
                o[0] = r[0] * t[0] + r[1] * t[3];
                o[1] = r[0] * t[1] + r[1] * t[4];
                o[2] = r[0] * t[2] + r[1] * t[5] + r[2];
                o[3] = r[3] * t[0] + r[4] * t[3];
                o[4] = r[3] * t[1] + r[4] * t[4];
                o[5] = r[3] * t[2] + r[4] * t[5] + r[5];
            }
        }
        memcpy(P, Q, sizeof(piece) * (size_t)m);
        n = m;
    }
    ori_pattern *p = NULL;
    ori_error err;
    ori_insert_def def = ori_default_insert_def();
    def.name_faces = false;
    if (ori_pattern_from_segments(seg, ns, &def, &p, NULL, &err) != ORI_OK) return NULL;
    memcpy(pieces, P, sizeof(piece) * (size_t)n);
    *npieces = n;
    return p;
}

// The independent check: from the pattern's faces placed by the simulation's transforms, every
// overlapping pair, every triple over a common region, the M/V orders, and — sampled between
// all breakpoints along every folded crease, just off both sides — which faces pass across it
// and which other creases lie along it. A state (±1 per pair) is valid when no three faces over
// one region cycle, each crease's faces keep their M/V order, no face passing across a crease
// lies between its two faces, and two creases along the same line with all four faces on one
// side do not interleave.
typedef struct brute {
    int nf, npair;
    int pair[MAXF][MAXF]; // -1 or pair index (i < j)
    int trip[512][3];
    int ntrip;
    int fixed_pair[64], fixed_val[64], nfixed;
    int tt[256][3]; // taco faces a, b and tortilla g: g not between
    int ntt;
    int tc[256][4]; // tacos a|b, c|d: no interleaving
    int ntc;
} brute;

static int above(const brute *B, uint32_t mask, int f, int g)
{
    int i = f < g ? f : g, j = f < g ? g : f;
    int bit = (mask >> B->pair[i][j]) & 1; // 1: lower index above
    int lo_above = bit ? 1 : -1;
    return f < g ? lo_above : -lo_above;
}

static bool between(const brute *B, uint32_t m, int x, int a, int b)
{
    return (above(B, m, a, x) > 0 && above(B, m, x, b) > 0) || (above(B, m, b, x) > 0 && above(B, m, x, a) > 0);
}

static bool valid_state(const brute *B, uint32_t m)
{
    for (int i = 0; i < B->nfixed; ++i)
        if ((int)((m >> B->fixed_pair[i]) & 1) != B->fixed_val[i]) return false;
    for (int i = 0; i < B->ntrip; ++i) {
        int a = B->trip[i][0], b = B->trip[i][1], c = B->trip[i][2];
        int ab = above(B, m, a, b), bc = above(B, m, b, c), ca = above(B, m, c, a);
        if (ab == bc && bc == ca) return false; // a cycle
    }
    for (int i = 0; i < B->ntt; ++i)
        if (between(B, m, B->tt[i][2], B->tt[i][0], B->tt[i][1])) return false;
    for (int i = 0; i < B->ntc; ++i) {
        int a = B->tc[i][0], b = B->tc[i][1], c = B->tc[i][2], d = B->tc[i][3];
        if (between(B, m, c, a, b) != between(B, m, d, a, b)) return false;
    }
    return true;
}

static bool inside(const poly *p, ori_v2 q)
{
    for (int i = 0; i < p->n; ++i)
        if (ori_v2_cross(ori_v2_sub(p->v[(i + 1) % p->n], p->v[i]), ori_v2_sub(q, p->v[i])) <= 1e-12) return false;
    return true;
}

static void add_unique3(int (*list)[3], int *n, int a, int b, int c)
{
    for (int i = 0; i < *n; ++i)
        if (list[i][0] == a && list[i][1] == b && list[i][2] == c) return;
    cr_assert_lt(*n, 256);
    list[*n][0] = a, list[*n][1] = b, list[*n][2] = c;
    (*n)++;
}

static bool build_brute(const ori_pattern *p, const piece *P, int np, brute *B)
{
    int nf = ori_pattern_face_count(p);
    if (nf > MAXF) return false;
    memset(B, 0, sizeof *B);
    B->nf = nf;
    poly fold[MAXF];
    bool flip[MAXF] = {false};
    for (int f = 0; f < nf; ++f) {
        int fv[MAXP];
        int n = ori_pattern_face_vertices(p, f, fv, MAXP);
        ori_v2 c = ori_v2_make(0, 0);
        poly cp;
        cp.n = n;
        for (int k = 0; k < n; ++k) {
            ori_v3 q = ori_pattern_vertex(p, fv[k]);
            cp.v[k] = ori_v2_make(q.x, q.y);
            c = ori_v2_add(c, ori_v2_scale(cp.v[k], 1.0 / n));
        }
        int owner = -1;
        for (int i = 0; i < np && owner < 0; ++i)
            if (inside(&P[i].cp, c)) owner = i;
        cr_assert_geq(owner, 0, "face %d lies in no piece", f);
        if (area2(&cp) < 0)
            for (int k = 0; k < n / 2; ++k) {
                ori_v2 t = cp.v[k];
                cp.v[k] = cp.v[n - 1 - k];
                cp.v[n - 1 - k] = t;
            }
        const double *t = P[owner].t;
        flip[f] = t[0] * t[4] - t[1] * t[3] < 0;

        fold[f].n = n;
        for (int k = 0; k < n; ++k) apply_t(t, cp.v[flip[f] ? n - 1 - k : k], &fold[f].v[k]);
    }
    // The solver keeps face 0 face-up; when the simulation turned it over, turn the whole model
    // over (mirror the image, swap every face's side) so that "above" means the same in both.
    bool turned = flip[0];
    if (turned)
        for (int f = 0; f < nf; ++f) {
            flip[f] = !flip[f];
            int n = fold[f].n;
            poly m;
            m.n = n;
            for (int k = 0; k < n; ++k) m.v[k] = ori_v2_make(-fold[f].v[n - 1 - k].x, fold[f].v[n - 1 - k].y);
            fold[f] = m;
        }
    for (int i = 0; i < nf; ++i)
        for (int j = 0; j < nf; ++j) B->pair[i][j] = -1;
    for (int i = 0; i < nf; ++i)
        for (int j = i + 1; j < nf; ++j) {
            poly x = clip_poly(&fold[i], &fold[j]);
            if (x.n >= 3 && area2(&x) > 1e-9) B->pair[i][j] = B->npair++;
        }
    if (B->npair > 30) return false;
    for (int i = 0; i < nf; ++i)
        for (int j = i + 1; j < nf; ++j)
            for (int k = j + 1; k < nf; ++k) {
                if (B->pair[i][j] < 0 || B->pair[i][k] < 0 || B->pair[j][k] < 0) continue;
                poly x = clip_poly(&fold[i], &fold[j]);
                x = clip_poly(&x, &fold[k]);
                if (x.n >= 3 && area2(&x) > 1e-9) {
                    cr_assert_lt(B->ntrip, 512);
                    B->trip[B->ntrip][0] = i, B->trip[B->ntrip][1] = j, B->trip[B->ntrip++][2] = k;
                }
            }
    // Creases in the folded frame.
    int ne = ori_pattern_edge_count(p);
    struct crease {
        ori_v2 a, b;
        int f[2];
    } cr[128];
    int nc = 0;
    for (int e = 0; e < ne; ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        int fc[2];
        ori_pattern_edge_faces(p, e, fc);
        if (fc[0] < 0 || fc[1] < 0 || ed.assignment == ORI_ASSIGN_CUT) continue; // a cut joins nothing
        cr_assert_lt(nc, 128);
        int l = fc[0], r = fc[1];
        // Both faces place the crease at the same folded segment; take face l's.
        int fv[MAXP];
        int n = ori_pattern_face_vertices(p, l, fv, MAXP);
        (void)n;
        ori_v3 a = ori_pattern_vertex(p, ed.v[0]), b = ori_pattern_vertex(p, ed.v[1]);
        int owner = -1;
        ori_v2 mid = ori_v2_make(0, 0);
        for (int k = 0; k < n; ++k) {
            ori_v3 q = ori_pattern_vertex(p, fv[k]);
            mid = ori_v2_add(mid, ori_v2_scale(ori_v2_make(q.x, q.y), 1.0 / n));
        }
        for (int i = 0; i < np && owner < 0; ++i)
            if (inside(&P[i].cp, mid)) owner = i;
        apply_t(P[owner].t, ori_v2_make(a.x, a.y), &cr[nc].a);
        apply_t(P[owner].t, ori_v2_make(b.x, b.y), &cr[nc].b);
        if (turned) {
            cr[nc].a.x = -cr[nc].a.x;
            cr[nc].b.x = -cr[nc].b.x;
        }
        cr[nc].f[0] = l;
        cr[nc].f[1] = r;
        if (ed.assignment == ORI_ASSIGN_MOUNTAIN || ed.assignment == ORI_ASSIGN_VALLEY) {
            // r lies above l exactly when valley XOR l face-down.
            bool r_above = (ed.assignment == ORI_ASSIGN_VALLEY) != flip[l];
            int i = l < r ? l : r, j = l < r ? r : l;
            cr_assert_geq(B->pair[i][j], 0);
            B->fixed_pair[B->nfixed] = B->pair[i][j];
            // bit 1: lower index above
            B->fixed_val[B->nfixed++] = (r_above == (r < l)) ? 1 : 0;
        }
        nc++;
    }
    // Samples along each crease, between every breakpoint (ends of collinear creases, crossings).
    for (int c = 0; c < nc; ++c) {
        ori_v2 a = cr[c].a, d = ori_v2_sub(cr[c].b, a);
        double len = ori_v2_norm(d);
        ori_v2 u = ori_v2_scale(d, 1.0 / len), nn = ori_v2_make(-u.y, u.x);
        double tb[600];
        int nb = 0;
        tb[nb++] = 0;
        tb[nb++] = 1;
        for (int f = 0; f < nf; ++f)
            for (int k = 0; k < fold[f].n; ++k) {
                ori_v2 p0 = fold[f].v[k], p1 = fold[f].v[(k + 1) % fold[f].n];
                double s0 = ori_v2_dot(nn, ori_v2_sub(p0, a)), s1 = ori_v2_dot(nn, ori_v2_sub(p1, a));
                if (fabs(s0) < 1e-9) tb[nb++] = ori_v2_dot(u, ori_v2_sub(p0, a)) / len;
                else if ((s0 < 0) != (s1 < 0) && fabs(s1) >= 1e-9) {
                    ori_v2 x = ori_v2_add(p0, ori_v2_scale(ori_v2_sub(p1, p0), s0 / (s0 - s1)));
                    tb[nb++] = ori_v2_dot(u, ori_v2_sub(x, a)) / len;
                }
                cr_assert_lt(nb, 590);
            }
        for (int i = 1; i < nb; ++i)
            for (int j = i; j > 0 && tb[j] < tb[j - 1]; --j) {
                double t = tb[j];
                tb[j] = tb[j - 1];
                tb[j - 1] = t;
            }
        for (int i = 0; i + 1 < nb; ++i) {
            if (tb[i] < 0 || tb[i + 1] > 1 || tb[i + 1] - tb[i] < 1e-7) continue;
            ori_v2 pt = ori_v2_add(a, ori_v2_scale(d, 0.5 * (tb[i] + tb[i + 1])));
            ori_v2 pl = ori_v2_add(pt, ori_v2_scale(nn, 1e-7)), pr = ori_v2_sub(pt, ori_v2_scale(nn, 1e-7));
            // Creases through pt, with the side their faces take.
            int tacos[32][3], nt = 0;
            for (int c2 = 0; c2 < nc; ++c2) {
                ori_v2 d2 = ori_v2_sub(cr[c2].b, cr[c2].a);
                double l2 = ori_v2_norm(d2);
                double off = fabs(ori_v2_cross(d2, ori_v2_sub(pt, cr[c2].a))) / l2;
                double along = ori_v2_dot(d2, ori_v2_sub(pt, cr[c2].a)) / (l2 * l2);
                if (off > 1e-9 || along <= 0 || along >= 1) continue;
                int f0 = cr[c2].f[0], f1 = cr[c2].f[1];
                int s0 = inside(&fold[f0], pl) ? 0 : inside(&fold[f0], pr) ? 1 : -1;
                int s1 = inside(&fold[f1], pl) ? 0 : inside(&fold[f1], pr) ? 1 : -1;
                cr_assert(s0 >= 0 && s1 >= 0 && s0 == s1, "a crease's faces are not on one side");
                tacos[nt][0] = f0 < f1 ? f0 : f1, tacos[nt][1] = f0 < f1 ? f1 : f0, tacos[nt++][2] = s0;
            }
            for (int x = 0; x < nt; ++x) {
                for (int g = 0; g < nf; ++g)
                    if (g != tacos[x][0] && g != tacos[x][1] && inside(&fold[g], pl) && inside(&fold[g], pr))
                        add_unique3(B->tt, &B->ntt, tacos[x][0], tacos[x][1], g);
                for (int y = x + 1; y < nt; ++y) {
                    if (tacos[x][2] != tacos[y][2]) continue;
                    bool dup = false;
                    for (int z = 0; z < B->ntc && !dup; ++z)
                        dup = B->tc[z][0] == tacos[x][0] && B->tc[z][1] == tacos[x][1] && B->tc[z][2] == tacos[y][0] &&
                              B->tc[z][3] == tacos[y][1];
                    if (dup) continue;
                    cr_assert_lt(B->ntc, 256);
                    B->tc[B->ntc][0] = tacos[x][0], B->tc[B->ntc][1] = tacos[x][1];
                    B->tc[B->ntc][2] = tacos[y][0], B->tc[B->ntc++][3] = tacos[y][1];
                }
            }
        }
    }
    return true;
}

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

Test(layers, random_simple_folds_match_brute_force_over_all_orders, .timeout = 120)
{
    int tested = 0, multi = 0, tries = 0;
    int maxf = 0, maxcount = 0, tacos = 0, none = 0;
    while (tested < 200 && tries < 20000) {
        tries++;
        piece P[MAXF];
        int np = 0;
        int folds = 2 + (int)(rnd() % 3);
        ori_pattern *p = simple_folds(folds, P, &np);
        if (!p) continue;
        // Make creases unassigned at random (more states).
        for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
            ori_edge ed = ori_pattern_edge(p, e);
            if (ed.assignment != ORI_ASSIGN_BOUNDARY && (rnd() % 3 == 0)) ori_pattern_set_assignment(p, e, ORI_ASSIGN_UNASSIGNED);
        }
        // And in one pattern of three, swap one M/V crease (often no state is left then).
        bool swapped = false;
        if (rnd() % 3 == 0) {
            int ne = ori_pattern_edge_count(p), e = (int)(rnd() % (uint64_t)ne);
            ori_edge ed = ori_pattern_edge(p, e);
            if (ed.assignment == ORI_ASSIGN_MOUNTAIN || ed.assignment == ORI_ASSIGN_VALLEY) {
                ori_pattern_set_assignment(p, e, ed.assignment == ORI_ASSIGN_MOUNTAIN ? ORI_ASSIGN_VALLEY : ORI_ASSIGN_MOUNTAIN);
                swapped = true;
            }
        }
        brute B;
        if (!build_brute(p, P, np, &B)) {
            ori_pattern_destroy(p);
            continue;
        }
        int free_bits = B.npair - B.nfixed;
        if (free_bits > 18 || B.npair > 30) {
            ori_pattern_destroy(p);
            continue;
        }
        // Brute force over every order of the overlapping pairs.
        uint32_t *valid = malloc(sizeof(uint32_t) * ((size_t)1 << 18));
        int nvalid = 0;
        int freepos[32], nfree = 0;
        uint32_t base = 0;
        for (int i = 0; i < B.npair; ++i) {
            int fx = -1;
            for (int k = 0; k < B.nfixed; ++k)
                if (B.fixed_pair[k] == i) fx = B.fixed_val[k];
            if (fx < 0) freepos[nfree++] = i;
            else if (fx) base |= 1u << i;
        }
        for (uint32_t m = 0; m < (1u << nfree); ++m) {
            uint32_t mask = base;
            for (int k = 0; k < nfree; ++k)
                if ((m >> k) & 1) mask |= 1u << freepos[k];
            if (valid_state(&B, mask)) valid[nvalid++] = mask;
        }
        // The solver.
        ori_layers *L = solve_pattern(p, NULL);
        ori_layers_info in = ori_layers_get_info(L);
        ori_layers_conflict why;
        bool local = ori_layers_get_conflict(L, &why) && why.constraint == ORI_LAYERS_LOCAL;
        if (!local) cr_assert_eq(in.variables, B.npair, "variables: solver %d, brute %d", in.variables, B.npair);
        char *s = states_of(L);
        char expect[32];
        snprintf(expect, sizeof expect, "%d", nvalid);
        cr_assert_str_eq(s, expect, "pattern %d (%d faces, %d pairs)", tested, B.nf, B.npair);
        ori_buffer_free(s);
        cr_assert(swapped || nvalid >= 1, "a simple-fold pattern always folds");
        if (nvalid == 0) {
            none++;
            ori_layers_conflict conf;
            cr_assert(ori_layers_get_conflict(L, &conf));
        }
        // Every numbered state is one of the brute force's, and all of them are reached.
        uint32_t *mine = malloc(sizeof(uint32_t) * (size_t)(nvalid ? nvalid : 1));
        for (int k = 0; k < nvalid; ++k) {
            char ks[16];
            snprintf(ks, sizeof ks, "%d", k);
            ori_error err;
            cr_assert_eq(ori_layers_select_state(L, ks, &err), ORI_OK);
            uint32_t mask = 0;
            for (int i = 0; i < B.nf; ++i)
                for (int j = i + 1; j < B.nf; ++j)
                    if (B.pair[i][j] >= 0 && ori_layers_face_above(L, i, j) > 0) mask |= 1u << B.pair[i][j];
            mine[k] = mask;
        }
        qsort(mine, (size_t)nvalid, sizeof(uint32_t), cmp_u32);
        qsort(valid, (size_t)nvalid, sizeof(uint32_t), cmp_u32);
        cr_assert_eq(memcmp(mine, valid, sizeof(uint32_t) * (size_t)nvalid), 0, "the numbered states differ from the brute force's");
        if (nvalid > 1) multi++;
        if (B.nf > maxf) maxf = B.nf;
        if (nvalid > maxcount) maxcount = nvalid;
        if (in.taco_taco > 0) tacos++;
        free(mine);
        free(valid);
        ori_layers_destroy(L);
        ori_pattern_destroy(p);
        tested++;
    }
    cr_log_info("%d patterns in %d tries: %d with several states (up to %d), %d with none, %d with taco-taco, up "
                "to %d faces",
                tested, tries, multi, maxcount, none, tacos, maxf);
    cr_assert_geq(none, 5, "only %d patterns without a state", none);
    cr_assert_geq(tested, 200, "only %d random patterns in %d tries", tested, tries);
    cr_assert_geq(multi, 40, "only %d patterns with more than one state", multi);
    cr_assert_geq(tacos, 20, "only %d patterns with taco-taco constraints", tacos);
    cr_assert_geq(maxf, 8, "no pattern reached 8 faces");
}

// --- exact counts --------------------------------------------------------------------------

Test(layers, natural_numbers_are_exact)
{
    ori__nat a, b, q, r;
    ori__nat_init(&a);
    ori__nat_init(&b);
    ori__nat_init(&q);
    ori__nat_init(&r);
    ori__nat_set_u64(&a, 1);
    ori__nat_set_u64(&b, 2);
    for (int i = 0; i < 128; ++i) ori__nat_mul(&a, &b);
    char *s = ori__nat_to_decimal(&a);
    cr_assert_str_eq(s, "340282366920938463463374607431768211456"); // 2^128
    ori__free(s);
    ori__nat_set_u64(&b, 1);
    ori__nat_sub(&a, &b);
    s = ori__nat_to_decimal(&a);
    cr_assert_str_eq(s, "340282366920938463463374607431768211455");
    ori__free(s);
    // (2^128 − 1) = 3 · 5 · 17 · 257 · 641 · 65537 · 274177 · 6700417 · 67280421310721
    ori__nat_set_u64(&b, 67280421310721ULL);
    ori__nat_divmod(&q, &r, &a, &b);
    cr_assert(ori__nat_is_zero(&r));
    s = ori__nat_to_decimal(&q);
    cr_assert_str_eq(s, "5057672949897463733145855");
    ori__free(s);
    ori__nat_mul(&q, &b);
    cr_assert_eq(ori__nat_cmp(&q, &a), 0);
    cr_assert(ori__nat_from_decimal(&b, "000123456789012345678901234567890"));
    s = ori__nat_to_decimal(&b);
    cr_assert_str_eq(s, "123456789012345678901234567890");
    ori__free(s);
    cr_assert(!ori__nat_from_decimal(&b, "12a"));
    ori__nat_set_u64(&b, UINT64_MAX);
    ori__nat_add(&b, &b);
    s = ori__nat_to_decimal(&b);
    cr_assert_str_eq(s, "36893488147419103230");
    ori__free(s);
    ori__nat_free(&a);
    ori__nat_free(&b);
    ori__nat_free(&q);
    ori__nat_free(&r);
}

// A strip of n equal stamps with every crease unassigned, folded into one stack: the solver's
// count equals the brute force's for every n up to 6.
static ori_pattern *stamp_strip(int n, piece *P)
{
    ori_segment seg[64];
    int ns = 0;
    for (int i = 0; i <= n; ++i) {
        seg[ns].a = ori_v2_make(i, 0);
        seg[ns].b = ori_v2_make(i, 1);
        seg[ns].assignment = (i == 0 || i == n) ? ORI_ASSIGN_BOUNDARY : ORI_ASSIGN_UNASSIGNED;
        seg[ns++].fold_angle_rad = 0;
    }
    for (int i = 0; i < n; ++i)
        for (int y = 0; y < 2; ++y) {
            seg[ns].a = ori_v2_make(i, y);
            seg[ns].b = ori_v2_make(i + 1, y);
            seg[ns].assignment = ORI_ASSIGN_BOUNDARY;
            seg[ns++].fold_angle_rad = 0;
        }
    for (int i = 0; i < n; ++i) {
        P[i].cp.n = 4;
        P[i].cp.v[0] = ori_v2_make(i, 0);
        P[i].cp.v[1] = ori_v2_make(i + 1, 0);
        P[i].cp.v[2] = ori_v2_make(i + 1, 1);
        P[i].cp.v[3] = ori_v2_make(i, 1);
        // Stamp i lands on [0, 1]: x' = x − i, or mirrored x' = i + 1 − x for odd i.
        double t[6] = {i % 2 ? -1 : 1, 0, i % 2 ? i + 1 : -i, 0, 1, 0};
        memcpy(P[i].t, t, sizeof t);
    }
    ori_pattern *p = NULL;
    ori_error err;
    ori_insert_def def = ori_default_insert_def();
    def.name_faces = false;
    cr_assert_eq(ori_pattern_from_segments(seg, ns, &def, &p, NULL, &err), ORI_OK, "%s", err.message);
    return p;
}

Test(layers, stamp_strips_match_brute_force)
{
    for (int n = 2; n <= 6; ++n) {
        piece P[MAXF];
        ori_pattern *p = stamp_strip(n, P);
        brute B;
        cr_assert(build_brute(p, P, n, &B));
        cr_assert_eq(B.npair, n * (n - 1) / 2);
        int nvalid = 0;
        for (uint32_t m = 0; m < (1u << B.npair); ++m) nvalid += valid_state(&B, m);
        ori_layers *L = solve_pattern(p, NULL);
        char *s = states_of(L), expect[16];
        snprintf(expect, sizeof expect, "%d", nvalid);
        cr_assert_str_eq(s, expect, "%d stamps", n);
        cr_log_info("%d stamps: %s states", n, s);
        ori_buffer_free(s);
        ori_layers_destroy(L);
        ori_pattern_destroy(p);
    }
}

// --- nets and strips: faces stacked edge to edge ------------------------------------------
// Faces whose edges lie on another crease's line (box pleating, nets, strips of unequal
// stamps) are where a solver may take a face touching a crease line for one crossing it. The
// brute force above decides "crossing" by sampling just off both sides of each folded crease,
// so it is independent of the solver's constraint generation.

// Brute force over every order of the overlapping pairs of p: the number of valid states, or
// -1 when the problem is too big for it (more than 18 free pairs). With L non-NULL, also
// asserts that L's count and its numbered states are exactly the brute force's.
static int brute_check(const ori_pattern *p, const piece *P, int np, const ori_layers *Lc, const char *what)
{
    ori_layers *L = (ori_layers *)Lc;
    brute B;
    if (!build_brute(p, P, np, &B)) return -1;
    int freepos[32], nfree = 0;
    uint32_t base = 0;
    for (int i = 0; i < B.npair; ++i) {
        int fx = -1;
        for (int k = 0; k < B.nfixed; ++k)
            if (B.fixed_pair[k] == i) fx = B.fixed_val[k];
        if (fx < 0) freepos[nfree++] = i;
        else if (fx) base |= 1u << i;
    }
    if (nfree > 18) return -1;
    uint32_t *valid = malloc(sizeof(uint32_t) * ((size_t)1 << nfree));
    int nvalid = 0;
    for (uint32_t m = 0; m < (1u << nfree); ++m) {
        uint32_t mask = base;
        for (int k = 0; k < nfree; ++k)
            if ((m >> k) & 1) mask |= 1u << freepos[k];
        if (valid_state(&B, mask)) valid[nvalid++] = mask;
    }
    if (L) {
        ori_layers_info in = ori_layers_get_info(L);
        cr_assert_eq(in.variables, B.npair, "%s: variables: solver %d, brute %d", what, in.variables, B.npair);
        char *s = states_of(L), expect[32];
        snprintf(expect, sizeof expect, "%d", nvalid);
        cr_assert_str_eq(s, expect, "%s (%d faces, %d pairs): solver %s, brute force %d", what, B.nf, B.npair, s, nvalid);
        ori_buffer_free(s);
        uint32_t *mine = malloc(sizeof(uint32_t) * (size_t)(nvalid ? nvalid : 1));
        for (int k = 0; k < nvalid; ++k) {
            char ks[16];
            snprintf(ks, sizeof ks, "%d", k);
            ori_error err;
            cr_assert_eq(ori_layers_select_state(L, ks, &err), ORI_OK);
            uint32_t mask = 0;
            for (int i = 0; i < B.nf; ++i)
                for (int j = i + 1; j < B.nf; ++j)
                    if (B.pair[i][j] >= 0 && ori_layers_face_above(L, i, j) > 0) mask |= 1u << B.pair[i][j];
            mine[k] = mask;
        }
        qsort(mine, (size_t)nvalid, sizeof(uint32_t), cmp_u32);
        qsort(valid, (size_t)nvalid, sizeof(uint32_t), cmp_u32);
        cr_assert_eq(memcmp(mine, valid, sizeof(uint32_t) * (size_t)nvalid), 0, "%s: the numbered states differ", what);
        free(mine);
    }
    free(valid);
    return nvalid;
}

static ori_assignment random_crease(int u_in)
{
    if (u_in > 0 && rnd() % (uint64_t)u_in == 0) return ORI_ASSIGN_UNASSIGNED;
    return (rnd() & 1) ? ORI_ASSIGN_MOUNTAIN : ORI_ASSIGN_VALLEY;
}

// Reflection of transform t across the vertical (vertical = true) or horizontal grid line at
// coordinate c of the crease pattern: out = t ∘ r.
static void reflect_grid(const double t[6], bool vertical, double c, double out[6])
{
    double r[6] = {1, 0, 0, 0, 1, 0};
    if (vertical) r[0] = -1, r[2] = 2 * c;
    else r[4] = -1, r[5] = 2 * c;
    double o[6];
    o[0] = t[0] * r[0] + t[1] * r[3];
    o[1] = t[0] * r[1] + t[1] * r[4];
    o[2] = t[0] * r[2] + t[1] * r[5] + t[2];
    o[3] = t[3] * r[0] + t[4] * r[3];
    o[4] = t[3] * r[1] + t[4] * r[4];
    o[5] = t[3] * r[2] + t[4] * r[5] + t[5];
    memcpy(out, o, sizeof o);
}

// A net of k unit squares (a tree: each square added touches exactly one square already
// there, so no vertex is interior), every shared side a crease (M/V, U one time in u_in), all
// folded flat: the squares land on grid squares, their sides on each other's crease lines.
// sq gives the squares (x, y) when non-NULL (k of them, a tree), else they are random.
static ori_pattern *square_net(int k, const int (*sq)[2], const ori_assignment *asg, int u_in, piece *P)
{
    int X[MAXF], Y[MAXF], parent[MAXF];
    parent[0] = -1;
    if (sq) {
        for (int i = 0; i < k; ++i) X[i] = sq[i][0], Y[i] = sq[i][1];
    } else {
        X[0] = Y[0] = 0;
        for (int n = 1; n < k;) {
            int from = (int)(rnd() % (uint64_t)n), dir = (int)(rnd() % 4);
            int x = X[from] + (dir == 0) - (dir == 1), y = Y[from] + (dir == 2) - (dir == 3);
            int touch = 0;
            bool taken = false;
            for (int j = 0; j < n; ++j) {
                taken |= X[j] == x && Y[j] == y;
                touch += abs(X[j] - x) + abs(Y[j] - y) == 1;
            }
            if (taken || touch != 1) continue;
            X[n] = x, Y[n] = y;
            n++;
        }
    }
    // Tree edges (the shared sides) and transforms, breadth first from square 0.
    double id[6] = {1, 0, 0, 0, 1, 0};
    bool placed[MAXF] = {false};
    memcpy(P[0].t, id, sizeof id);
    placed[0] = true;
    int order[MAXF], head = 0, tail = 0;
    order[tail++] = 0;
    while (head < tail) {
        int i = order[head++];
        for (int j = 0; j < k; ++j) {
            if (placed[j] || abs(X[j] - X[i]) + abs(Y[j] - Y[i]) != 1) continue;
            bool vertical = X[j] != X[i];
            double c = vertical ? (X[i] > X[j] ? X[i] : X[j]) : (Y[i] > Y[j] ? Y[i] : Y[j]);
            reflect_grid(P[i].t, vertical, c, P[j].t);
            placed[j] = true;
            parent[j] = i;
            order[tail++] = j;
        }
    }
    cr_assert_eq(tail, k, "the squares of a net must be connected");
    ori_segment seg[MAXS];
    int ns = 0, ncrease = 0;
    for (int i = 0; i < k; ++i) {
        P[i].cp.n = 4;
        P[i].cp.v[0] = ori_v2_make(X[i], Y[i]);
        P[i].cp.v[1] = ori_v2_make(X[i] + 1, Y[i]);
        P[i].cp.v[2] = ori_v2_make(X[i] + 1, Y[i] + 1);
        P[i].cp.v[3] = ori_v2_make(X[i], Y[i] + 1);
        for (int s = 0; s < 4; ++s) {
            ori_v2 a = P[i].cp.v[s], b = P[i].cp.v[(s + 1) % 4];
            // The square across this side, if any.
            int nx = X[i] + (s == 1) - (s == 3), ny = Y[i] + (s == 2) - (s == 0), other = -1;
            for (int j = 0; j < k; ++j)
                if (X[j] == nx && Y[j] == ny) other = j;
            if (other >= 0 && other < i) continue; // entered with the other square
            cr_assert_lt(ns, MAXS);
            seg[ns].a = a;
            seg[ns].b = b;
            seg[ns].fold_angle_rad = 0;
            if (other < 0) seg[ns].assignment = ORI_ASSIGN_BOUNDARY;
            else {
                cr_assert(parent[other] == i || parent[i] == other);
                seg[ns].assignment = asg ? asg[ncrease] : random_crease(u_in);
                ncrease++;
            }
            ns++;
        }
    }
    ori_pattern *p = NULL;
    ori_error err;
    ori_insert_def def = ori_default_insert_def();
    def.name_faces = false;
    cr_assert_eq(ori_pattern_from_segments(seg, ns, &def, &p, NULL, &err), ORI_OK, "%s", err.message);
    return p;
}

// A strip of k rectangles of random widths 1–3 (height 1), every crease folded (M/V, U one
// time in u_in): the rectangles' ends land on each other's creases.
static ori_pattern *uneven_strip(int k, int u_in, piece *P)
{
    ori_segment seg[MAXS];
    int ns = 0;
    double x = 0;
    double t[6] = {1, 0, 0, 0, 1, 0};
    for (int i = 0; i < k; ++i) {
        double w = 1 + (double)(rnd() % 3);
        P[i].cp.n = 4;
        P[i].cp.v[0] = ori_v2_make(x, 0);
        P[i].cp.v[1] = ori_v2_make(x + w, 0);
        P[i].cp.v[2] = ori_v2_make(x + w, 1);
        P[i].cp.v[3] = ori_v2_make(x, 1);
        if (i > 0) reflect_grid(t, true, x, t);
        memcpy(P[i].t, t, sizeof t);
        seg[ns].a = ori_v2_make(x, 0);
        seg[ns].b = ori_v2_make(x, 1);
        seg[ns].assignment = i == 0 ? ORI_ASSIGN_BOUNDARY : random_crease(u_in);
        seg[ns++].fold_angle_rad = 0;
        for (int y = 0; y < 2; ++y) {
            seg[ns].a = ori_v2_make(x, y);
            seg[ns].b = ori_v2_make(x + w, y);
            seg[ns].assignment = ORI_ASSIGN_BOUNDARY;
            seg[ns++].fold_angle_rad = 0;
        }
        x += w;
    }
    seg[ns].a = ori_v2_make(x, 0);
    seg[ns].b = ori_v2_make(x, 1);
    seg[ns].assignment = ORI_ASSIGN_BOUNDARY;
    seg[ns++].fold_angle_rad = 0;
    ori_pattern *p = NULL;
    ori_error err;
    ori_insert_def def = ori_default_insert_def();
    def.name_faces = false;
    cr_assert_eq(ori_pattern_from_segments(seg, ns, &def, &p, NULL, &err), ORI_OK, "%s", err.message);
    return p;
}

// The cube's cross: squares 0 1 2 3 in a row, 4 above and 5 below square 1.
static const int cube_cross[6][2] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {1, 1}, {1, -1}};

Test(layers, cube_net_all_mountains_has_52_states)
{
    ori_assignment m[5] = {ORI_ASSIGN_MOUNTAIN, ORI_ASSIGN_MOUNTAIN, ORI_ASSIGN_MOUNTAIN, ORI_ASSIGN_MOUNTAIN,
                           ORI_ASSIGN_MOUNTAIN};
    piece P[MAXF];
    ori_pattern *p = square_net(6, cube_cross, m, 0, P);
    ori_layers *L = solve_pattern(p, NULL);
    char *s = states_of(L);
    cr_assert_str_eq(s, "52");
    ori_buffer_free(s);
    ori_layers_info in = ori_layers_get_info(L);
    // No face passes across a crease line: every side lies on one, none crosses it.
    cr_assert_eq(in.taco_tortilla, 0);
    cr_assert_eq(in.cells, 1);
    cr_assert_eq(brute_check(p, P, 6, L, "cube net"), 52);
    ori_layers_destroy(L);
    ori_pattern_destroy(p);
}

Test(layers, random_nets_and_strips_match_brute_force, .timeout = 120)
{
    int tested_nets = 0, tested_strips = 0, tries = 0, multi = 0, maxf = 0, maxcount = 0, tacos = 0;
    while ((tested_nets < 150 || tested_strips < 100) && tries < 5000) {
        tries++;
        piece P[MAXF];
        bool net = tested_nets < 150;
        int k = 2 + (int)(rnd() % 7); // 2 … 8 faces
        ori_pattern *p = net ? square_net(k, NULL, NULL, 4, P) : uneven_strip(k, 3, P);
        ori_layers *L = solve_pattern(p, NULL);
        char what[64];
        snprintf(what, sizeof what, "%s %d (%d faces)", net ? "net" : "strip", net ? tested_nets : tested_strips, k);
        int n = brute_check(p, P, k, L, what);
        if (n >= 0) {
            if (net) tested_nets++;
            else tested_strips++;
            multi += n > 1;
            maxcount = n > maxcount ? n : maxcount;
            maxf = k > maxf ? k : maxf;
            tacos += ori_layers_get_info(L).taco_taco > 0;
        }
        ori_layers_destroy(L);
        ori_pattern_destroy(p);
    }
    cr_log_info("%d nets and %d strips in %d tries: %d with several states (up to %d), %d with taco-taco, up to %d faces",
                tested_nets, tested_strips, tries, multi, maxcount, tacos, maxf);
    cr_assert_geq(tested_nets, 150);
    cr_assert_geq(tested_strips, 100);
    cr_assert_geq(multi, 100);
    cr_assert_geq(tacos, 50);
    cr_assert_eq(maxf, 8);
}

// --- kirigami: cuts are free edges -------------------------------------------------------

// An a × b block of unit squares joined along a random spanning tree of its sides (creases,
// all folded: M/V, U one time in u_in); the other shared sides are cuts (C). Vertices where
// squares meet around a cut are no flat vertices: only the brute force's stacking rules apply.
static ori_pattern *cut_block(int a, int b, int u_in, piece *P)
{
    int k = a * b, parent[MAXF];
    bool in_tree[MAXF] = {false};
    // Random spanning tree: grow from square 0 by random sides to squares not yet reached.
    in_tree[0] = true;
    parent[0] = -1;
    double id[6] = {1, 0, 0, 0, 1, 0};
    memcpy(P[0].t, id, sizeof id);
    for (int n = 1; n < k;) {
        int from = (int)(rnd() % (uint64_t)k), dir = (int)(rnd() % 4);
        if (!in_tree[from]) continue;
        int x = from % a + (dir == 0) - (dir == 1), y = from / a + (dir == 2) - (dir == 3);
        if (x < 0 || x >= a || y < 0 || y >= b || in_tree[y * a + x]) continue;
        int to = y * a + x;
        bool vertical = x != from % a;
        double c = vertical ? (x > from % a ? x : from % a) : (y > from / a ? y : from / a);
        reflect_grid(P[from].t, vertical, c, P[to].t);
        in_tree[to] = true;
        parent[to] = from;
        n++;
    }
    ori_segment seg[MAXS];
    int ns = 0;
    for (int i = 0; i < k; ++i) {
        int X = i % a, Y = i / a;
        P[i].cp.n = 4;
        P[i].cp.v[0] = ori_v2_make(X, Y);
        P[i].cp.v[1] = ori_v2_make(X + 1, Y);
        P[i].cp.v[2] = ori_v2_make(X + 1, Y + 1);
        P[i].cp.v[3] = ori_v2_make(X, Y + 1);
        for (int s = 0; s < 4; ++s) {
            int nx = X + (s == 1) - (s == 3), ny = Y + (s == 2) - (s == 0);
            int other = nx >= 0 && nx < a && ny >= 0 && ny < b ? ny * a + nx : -1;
            if (other >= 0 && other < i) continue;
            cr_assert_lt(ns, MAXS);
            seg[ns].a = P[i].cp.v[s];
            seg[ns].b = P[i].cp.v[(s + 1) % 4];
            seg[ns].fold_angle_rad = 0;
            seg[ns].assignment = other < 0                                        ? ORI_ASSIGN_BOUNDARY
                                 : (parent[other] == i || parent[i] == other) ? random_crease(u_in)
                                                                                : ORI_ASSIGN_CUT;
            ns++;
        }
    }
    ori_pattern *p = NULL;
    ori_error err;
    ori_insert_def def = ori_default_insert_def();
    def.name_faces = false;
    cr_assert_eq(ori_pattern_from_segments(seg, ns, &def, &p, NULL, &err), ORI_OK, "%s", err.message);
    return p;
}

static bool cancel_at_once(double fraction, void *user)
{
    (void)fraction;
    (*(int *)user)++;
    return false;
}

Test(layers, random_kirigami_blocks_match_brute_force, .timeout = 120)
{
    int tested = 0, tries = 0, multi = 0, cuts = 0;
    while (tested < 100 && tries < 2000) {
        tries++;
        piece P[MAXF];
        int a = 2 + (int)(rnd() % 3), b = 2;
        if (a * b > 8) continue;
        ori_pattern *p = cut_block(a, b, 4, P);
        for (int e = 0; e < ori_pattern_edge_count(p); ++e) cuts += ori_pattern_edge(p, e).assignment == ORI_ASSIGN_CUT;
        ori_layers *L = solve_pattern(p, NULL);
        char what[64];
        snprintf(what, sizeof what, "kirigami %d (%d x %d)", tested, a, b);
        int n = brute_check(p, P, a * b, L, what);
        if (n >= 0) {
            tested++;
            multi += n > 1;
        }
        ori_layers_destroy(L);
        ori_pattern_destroy(p);
    }
    cr_log_info("%d kirigami blocks in %d tries, %d with several states, %d cuts", tested, tries, multi, cuts);
    cr_assert_geq(tested, 100);
    cr_assert_geq(multi, 30);
    cr_assert_geq(cuts, 100);
}

Test(layers, kirigami_honeycomb_stops_at_its_budget_with_a_lower_bound, .timeout = 120)
{
    // Origami Simulator's honeycomb kirigami (187 cuts) folded flat: all 276 faces over one cell,
    // one component of 16280 free pairs whose count is astronomically large. The count stops at
    // its budget with a partial answer (exit 5), never hangs.
    const char *kiri = test_require_shared("origamisimulator/Kirigami_honeycombKiri.svg");
    char cmd[4200], *out = NULL;
    snprintf(cmd, sizeof cmd, "layers '%s' --limit 100000 --json", kiri);
    cr_assert_eq(test_run_cli(cmd, &out), 5, "%s", out);
    json_error_t jerr;
    json_t *o = json_loads(out, 0, &jerr);
    cr_assert(o, "%s", out);
    cr_assert_str_eq(json_string_value(json_object_get(o, "states")), "100000");
    cr_assert(json_is_true(json_object_get(o, "limited")));
    cr_assert_eq(json_integer_value(json_object_get(o, "faces")), 276);
    cr_assert_eq(json_integer_value(json_object_get(o, "variables")), 276 * 275 / 2);
    // The cuts join nothing: no taco-tortilla or tortilla-tortilla constraint comes from them.
    json_t *c = json_object_get(o, "constraints");
    cr_assert_eq(json_integer_value(json_object_get(c, "taco_tortilla")), 0);
    cr_assert_eq(json_integer_value(json_object_get(c, "tortilla_tortilla")), 0);
    json_decref(o);
    free(out);
    snprintf(cmd, sizeof cmd, "layers '%s' --timeout 1 --json", kiri);
    cr_assert_eq(test_run_cli(cmd, &out), 5, "%s", out);
    o = json_loads(strchr(out, '{'), 0, &jerr);
    cr_assert(o, "%s", out);
    cr_assert(json_is_true(json_object_get(o, "timed_out")));
    cr_assert(json_is_true(json_object_get(o, "limited")));
    cr_assert(json_is_null(json_object_get(o, "unsatisfiable")));
    // A lower bound: at least the one state every search reaches first.
    const char *n = json_string_value(json_object_get(o, "states"));
    cr_assert(n && strlen(n) >= 1 && strcmp(n, "0") != 0, "%s", out);
    json_decref(o);
    free(out);
}

Test(layers, cancelled_count_keeps_lower_bounds)
{
    // A strip of 10 stamps (1,557,892 states) cancelled at the first report: every count is a lower bound, the
    // total is at most the exact one, and nothing is declared unsatisfiable.
    piece P[MAXF];
    ori_pattern *p = stamp_strip(10, P);
    ori_layers *L = solve_pattern(p, NULL);
    char *exact = states_of(L);
    ori_layers_destroy(L);
    int calls = 0;
    ori_layers_def def = ori_default_layers_def();
    def.progress = cancel_at_once;
    def.progress_user = &calls;
    ori_error err;
    cr_assert_eq(ori_layers_create(p, &def, &L, &err), ORI_OK);
    cr_assert_eq(ori_layers_count(L, &err), ORI_ERR_LIMIT);
    ori_layers_info in = ori_layers_get_info(L);
    cr_assert(in.stopped && in.limited && in.counted && in.satisfiable);
    char *part = states_of(L);
    cr_assert_lt(strtoull(part, NULL, 10), strtoull(exact, NULL, 10), "%s of %s", part, exact);
    cr_assert_gt(calls, 0);
    ori_buffer_free(part);
    ori_buffer_free(exact);
    ori_layers_destroy(L);
    ori_pattern_destroy(p);
}

// --- drawings with rounded coordinates: the tolerance from the drawing -------------------

// Move every vertex of p by up to `noise` (absolute) in x and y, as a drawing program's
// rounding does, and rebuild it. The faces keep their indices.
static void jitter(ori_pattern *p, double noise)
{
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        ori_v3 q = ori_pattern_vertex(p, v);
        q.x += noise * (2 * rnd_unit() - 1);
        q.y += noise * (2 * rnd_unit() - 1);
        ori_pattern_set_vertex(p, v, q);
    }
    ori_error err;
    ori_build_def bd = ori_default_build_def();
    cr_assert_eq(ori_pattern_build(p, &bd, &err), ORI_OK, "%s", err.message);
}

Test(layers, drawn_cube_net_counts_52_with_the_tolerance_from_the_drawing)
{
    // The cross of six squares as Origami Simulator's file draws it: squares of 578.571 units,
    // corners off by up to 0.002 (about 1e-6 of the sheet). Its sides lie on each other's
    // crease lines only within that precision.
    ori_assignment m[5] = {ORI_ASSIGN_MOUNTAIN, ORI_ASSIGN_MOUNTAIN, ORI_ASSIGN_MOUNTAIN, ORI_ASSIGN_MOUNTAIN,
                           ORI_ASSIGN_MOUNTAIN};
    piece P[MAXF];
    ori_pattern *p = square_net(6, cube_cross, m, 0, P);
    for (int v = 0; v < ori_pattern_vertex_count(p); ++v) {
        ori_v3 q = ori_pattern_vertex(p, v);
        ori_pattern_set_vertex(p, v, ori_v3_make(578.571 * q.x, 578.571 * q.y, 0));
    }
    jitter(p, 0.002);
    ori_layers *L = solve_pattern(p, NULL);
    char *s = states_of(L);
    cr_assert_str_eq(s, "52");
    ori_buffer_free(s);
    ori_layers_info in = ori_layers_get_info(L);
    cr_assert(in.tolerance_from_drawing);
    cr_assert_eq(in.taco_tortilla, 0);
    cr_assert_eq(in.cells, 1);
    // Relative to the folded image (one square, 818 units across): 0.002 at each of two corners.
    cr_assert_gt(in.noise_length, 1e-7);
    cr_assert_lt(in.noise_length, 1e-4);
    cr_assert_geq(in.tolerance, 4 * in.noise_length);
    ori_layers_destroy(L);
    // At the strict length the 0.002-wide slivers are real regions: faces overlap the crease
    // lines there, and the count is not the drawing's.
    ori_layers_def def = ori_default_layers_def();
    def.snap_rel = ORI_TOL_LAYERS_SNAP_REL;
    L = NULL;
    ori_error err;
    if (ori_layers_create(p, &def, &L, &err) == ORI_OK) {
        cr_assert_eq(ori_layers_count(L, &err), ORI_OK);
        s = states_of(L);
        cr_assert_str_neq(s, "52");
        ori_buffer_free(s);
        cr_assert_gt(ori_layers_get_info(L).cells, 1);
    }
    ori_layers_destroy(L);
    ori_pattern_destroy(p);
}

Test(layers, random_drawn_nets_and_strips_count_as_the_exact_ones, .timeout = 120)
{
    // The class: nets and strips whose coordinates are rounded (1e-7 to 1e-5 of the sheet)
    // count, with the tolerance chosen from the drawing, exactly what the brute force counts on
    // the exact pattern.
    int tested = 0, tries = 0, multi = 0;
    while (tested < 150 && tries < 3000) {
        tries++;
        piece P[MAXF];
        bool net = tries % 2;
        int k = 2 + (int)(rnd() % 7);
        ori_pattern *p = net ? square_net(k, NULL, NULL, 4, P) : uneven_strip(k, 3, P);
        int expect = brute_check(p, P, k, NULL, "exact");
        if (expect < 0) {
            ori_pattern_destroy(p);
            continue;
        }
        double size = 0;
        for (int i = 0; i < k; ++i) size = fmax(size, fmax(P[i].cp.v[2].x, P[i].cp.v[2].y));
        double noise = size * pow(10.0, -7.0 + 2.0 * rnd_unit());
        jitter(p, noise);
        ori_layers *L = solve_pattern(p, NULL);
        char *s = states_of(L), want[32];
        snprintf(want, sizeof want, "%d", expect);
        cr_assert_str_eq(s, want, "%s of %d faces drawn within %.2g: %s states, the exact one has %s", net ? "net" : "strip",
                         k, noise / size, s, want);
        ori_buffer_free(s);
        ori_layers_info in = ori_layers_get_info(L);
        cr_assert(in.tolerance_from_drawing);
        // Relative to the folded image (at least one unit across): corners moved by noise and
        // reflected across creases turned by up to 2 noise / 1, over lever arms up to the size.
        cr_assert_leq(in.noise_length, 4 * size * noise, "the noise seen (%g) is the drawing's (%g)", in.noise_length,
                      noise);
        multi += expect > 1;
        ori_layers_destroy(L);
        ori_pattern_destroy(p);
        tested++;
    }
    cr_assert_geq(tested, 150);
    cr_assert_geq(multi, 60);
}

Test(layers, published_drawings_with_rounded_coordinates_count_by_default)
{
    // Flat-Folder's Instagram CPs drawn with rounded coordinates (Kawasaki off by up to 4e-4
    // rad, equal sectors off by 1e-6): the published counts and components by default.
    const char *files[][2] = {{"018_komatsu_Butterfly_Base.fold", "018"},
                              {"287_ku_Four_Leaf_Clover.fold", "287"},
                              {"360_fung_I_Heart_Cat_v2_(shaped).fold", "360"}};
    const char *csv = test_require_shared("flat-folder-corpus/instagram_data.csv");
    char csvbuf[4096];
    snprintf(csvbuf, sizeof csvbuf, "%s", csv);
    for (int i = 0; i < 3; ++i) {
        char rel[256];
        snprintf(rel, sizeof rel, "flat-folder-corpus/instagram/%s", files[i][0]);
        ori_pattern *p = test_load_pattern(test_require_shared(rel), 0);
        ff_row r = ff_lookup(csvbuf, files[i][1]);
        cr_assert(r.found);
        ori_layers *L = solve_pattern(p, NULL);
        char *s = states_of(L), comps[512];
        component_string(L, comps, sizeof comps);
        cr_expect_str_eq(s, r.states, "%s", files[i][0]);
        cr_expect_str_eq(comps, r.components, "%s", files[i][0]);
        ori_layers_info in = ori_layers_get_info(L);
        cr_expect(in.tolerance_from_drawing && in.tolerance > ORI_TOL_LAYERS_SNAP_REL, "%s: tolerance %g", files[i][0],
                  in.tolerance);
        ori_buffer_free(s);
        ori_layers_destroy(L);
        // The strict length refuses them (Kawasaki beyond 1e-8 rad).
        ori_layers_def def = ori_default_layers_def();
        def.snap_rel = ORI_TOL_LAYERS_SNAP_REL;
        L = solve_pattern(p, &def);
        ori_layers_conflict c;
        cr_expect(ori_layers_get_conflict(L, &c) && c.constraint == ORI_LAYERS_LOCAL, "%s", files[i][0]);
        ori_layers_destroy(L);
        ori_pattern_destroy(p);
    }
    // Origami Simulator's cube net (corners drawn 0.002 apart): 52 states, not 8.
    const char *cube = test_require_shared("origamisimulator/PolygonUnfolding_cubeunwrapping.svg");
    char cmd[4200], *out = NULL;
    snprintf(cmd, sizeof cmd, "layers '%s' --json", cube);
    cr_assert_eq(test_run_cli(cmd, &out), 0, "%s", out);
    json_error_t jerr;
    json_t *o = json_loads(out, 0, &jerr);
    cr_assert(o, "%s", out);
    cr_assert_str_eq(json_string_value(json_object_get(o, "states")), "52");
    cr_assert_eq(json_integer_value(json_object_get(json_object_get(o, "constraints"), "taco_tortilla")), 0);
    cr_assert_str_eq(json_string_value(json_object_get(o, "tolerance_source")), "drawing");
    json_decref(o);
    free(out);
}

Test(layers, published_drawing_with_overlapping_creases_counts_once_planarised)
{
    // Flat-Folder's General Grievous draws a U crease over part of the sheet's boundary (edges
    // 281 and 436 overlap): read planarised (the boundary stays), its published count and
    // components. (Flat-Folder's 99 tortilla-tortilla constraints come from that U line, which
    // it keeps as a crease; with the boundary there are none, and the states are the same.)
    const char *path = test_require_shared("flat-folder-corpus/instagram/208_kei_General_Grievous.fold");
    char cmd[4200], *out = NULL, *err = NULL;
    snprintf(cmd, sizeof cmd, "layers '%s' --json", path);
    cr_assert_eq(test_run_cli_split(cmd, &out, &err), 0, "%s%s", out, err);
    cr_assert(strstr(err, "note: its edges cross or overlap: planarised 1706 edges into 1705"), "%s", err);
    json_error_t jerr;
    json_t *o = json_loads(out, 0, &jerr);
    cr_assert(o, "%s", out);
    cr_assert_str_eq(json_string_value(json_object_get(o, "states")), "122880");
    cr_assert_eq(json_integer_value(json_object_get(o, "faces")), 933);
    cr_assert_eq(json_integer_value(json_object_get(o, "variables")), 71596);
    json_t *c = json_object_get(o, "constraints");
    cr_assert_eq(json_integer_value(json_object_get(c, "taco_taco")), 17480);
    cr_assert_eq(json_integer_value(json_object_get(c, "taco_tortilla")), 86831);
    cr_assert_eq(json_integer_value(json_object_get(c, "transitivity")), 2938681);
    const int comps[] = {1, 2, 2, 2, 3, 20, 16, 16};
    json_t *cs = json_object_get(o, "components");
    cr_assert_eq(json_array_size(cs), 8);
    for (size_t i = 0; i < 8; ++i) cr_assert_eq(json_integer_value(json_array_get(cs, i)), comps[i], "component %zu", i);
    json_decref(o);
    free(out);
    free(err);
}

Test(layers, cli_says_which_tolerance_decides_undecided_coordinates)
{
    // 2.1e-8 apart at --tolerance 1e-8: undecided; the message names the value that decides.
    char *out = NULL, *err = NULL;
    cr_assert_eq(test_run_cli_split("layers tests/data/layers/ambiguous-strip.fold --tolerance 1e-8", &out, &err), 3);
    cr_assert(strstr(err, "do not say whether they meet"), "%s", err);
    const char *hint = strstr(err, "--tolerance ");
    cr_assert(hint, "%s", err);
    double t = atof(hint + strlen("--tolerance "));
    cr_assert_gt(t, 2.1e-8, "%s", err);
    cr_assert_leq(t, 1e-2, "%s", err);
    free(out);
    free(err);
    // That value works.
    char cmd[256];
    snprintf(cmd, sizeof cmd, "layers tests/data/layers/ambiguous-strip.fold --tolerance %.2g --count", t);
    cr_assert_eq(test_run_cli(cmd, &out), 0, "%s", out);
    cr_assert_str_eq(out, "1\n");
    free(out);
    // Without --tolerance the drawing's own is used and printed.
    cr_assert_eq(test_run_cli("layers tests/data/layers/ambiguous-strip.fold", &out), 0, "%s", out);
    cr_assert(strstr(out, "tolerance    ") && strstr(out, "(from the drawing"), "%s", out);
    free(out);
}

// --- bad input, limits, threads, cancellation ----------------------------------------------

Test(layers, bad_input_names_the_element)
{
    // Folded, two vertices land 2.1e-8 of the diagonal apart: neither one point nor clearly two.
    ori_pattern *p = test_load_pattern(test_repo_path("tests/data/layers/ambiguous-strip.fold"), 0);
    ori_layers *L = NULL;
    ori_error err;
    ori_layers_def def = ori_default_layers_def();
    def.snap_rel = ORI_TOL_LAYERS_SNAP_REL;
    cr_assert_eq(ori_layers_create(p, &def, &L, &err), ORI_ERR_DEGENERATE);
    cr_assert_null(L);
    cr_assert_str_eq(err.field, "vertices_coords");
    cr_assert_eq(err.element, 3);
    // A looser snapping length (an imprecise drawing) makes them one point: one state.
    def.snap_rel = 1e-6;
    L = solve_pattern(p, &def);
    char *s = states_of(L);
    cr_assert_str_eq(s, "1");
    ori_buffer_free(s);
    ori_layers_info in = ori_layers_get_info(L);
    cr_assert(!in.tolerance_from_drawing);
    cr_assert_float_eq(in.tolerance, 1e-6, 1e-18);
    ori_layers_destroy(L);
    // By default the tolerance comes from the drawing: the two points 2.1e-8 apart are the
    // drawing's noise (nothing else lies within 10 % of the strip), so they are one point.
    L = solve_pattern(p, NULL);
    s = states_of(L);
    cr_assert_str_eq(s, "1");
    ori_buffer_free(s);
    in = ori_layers_get_info(L);
    cr_assert(in.tolerance_from_drawing);
    cr_assert_float_eq(in.noise_length, 2.1e-8, 2e-9);
    cr_assert_geq(in.tolerance, 4 * in.noise_length);
    cr_assert_leq(in.tolerance, 1e-2);
    ori_layers_destroy(L);
    ori_pattern_destroy(p);

    // Not locally flat-foldable: Kawasaki fails at vertex 0 by 40 degrees.
    p = test_load_pattern(test_repo_path("examples/patterns/non-flat-foldable-vertex.fold"), 0);
    L = solve_pattern(p, NULL);
    ori_layers_conflict c;
    cr_assert(ori_layers_get_conflict(L, &c));
    cr_assert_eq(c.constraint, ORI_LAYERS_LOCAL);
    cr_assert_eq(c.vertex, 0);
    cr_assert_float_eq(fabs(c.kawasaki_rad), ori_deg_to_rad(40.0), 1e-9);
    int faces[8];
    cr_assert_eq(ori_layers_conflict_faces(L, faces, 8), 4);
    ori_layers_destroy(L);
    ori_pattern_destroy(p);
}

static bool cancel_now(double fraction, void *user)
{
    (void)fraction;
    (*(int *)user)++;
    return false;
}

Test(layers, limit_threads_and_cancellation)
{
    ori_pattern *p = test_load_pattern(test_repo_path("tests/data/layers/pleat-unassigned.fold"), 0);
    // Flat-Folder's limit: at most 5 states per component.
    ori_layers_def def = ori_default_layers_def();
    def.limit = 5;
    ori_layers *L = solve_pattern(p, &def);
    char *s = states_of(L);
    cr_assert_str_eq(s, "5");
    ori_buffer_free(s);
    cr_assert(ori_layers_get_info(L).limited);
    ori_error err;
    cr_assert_eq(ori_layers_select_state(L, "0", &err), ORI_ERR_UNSUPPORTED);
    ori_layers_destroy(L);
    // Two threads: the same count.
    def = ori_default_layers_def();
    def.threads = 2;
    L = solve_pattern(p, &def);
    s = states_of(L);
    cr_assert_str_eq(s, "16");
    ori_buffer_free(s);
    cr_assert(!ori_layers_get_info(L).limited);
    // States out of range or not numbers.
    cr_assert_eq(ori_layers_select_state(L, "16", &err), ORI_ERR_RANGE);
    cr_assert_eq(ori_layers_select_state(L, "x", &err), ORI_ERR_RANGE);
    cr_assert_eq(ori_layers_select_state(L, "15", &err), ORI_OK);
    ori_layers_destroy(L);
    // A progress callback that cancels.
    int calls = 0;
    def = ori_default_layers_def();
    def.progress = cancel_now;
    def.progress_user = &calls;
    cr_assert_eq(ori_layers_create(p, &def, &L, &err), ORI_OK);
    cr_assert_eq(ori_layers_count(L, &err), ORI_ERR_LIMIT);
    cr_assert_geq(calls, 1);
    ori_layers_destroy(L);
    ori_pattern_destroy(p);
}

Test(layers, every_state_is_distinct_and_the_cell_stacks_agree)
{
    ori_pattern *p = test_load_pattern(test_repo_path("tests/data/layers/pleat-unassigned.fold"), 0);
    ori_layers *L = solve_pattern(p, NULL);
    cr_assert_eq(ori_layers_cell_count(L), 1);
    int seen_orders[16][4];
    for (int k = 0; k < 16; ++k) {
        char ks[16];
        snprintf(ks, sizeof ks, "%d", k);
        ori_error err;
        cr_assert_eq(ori_layers_select_state(L, ks, &err), ORI_OK);
        int stack[4];
        cr_assert_eq(ori_layers_cell_stack(L, 0, stack, 4), 4);
        // The stack is the order the pair relations give: each face above all later ones.
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) cr_assert_eq(ori_layers_face_above(L, stack[i], stack[j]), 1);
        for (int m = 0; m < k; ++m) cr_assert_neq(memcmp(seen_orders[m], stack, sizeof stack), 0, "states %d and %d", m, k);
        memcpy(seen_orders[k], stack, sizeof stack);
        // Stamp 0 keeps its place and its front up.
        cr_assert(!ori_layers_face_flipped(L, 0));
    }
    ori_layers_destroy(L);
    ori_pattern_destroy(p);
}

// --- output and the command ----------------------------------------------------------------

Test(layers, cli_writes_the_state_as_a_folded_frame_and_an_svg)
{
    char *dir = test_tmpdir();
    char args[1024], *out = NULL;
    snprintf(args, sizeof args, "layers tests/data/layers/pleat-unassigned.fold --state 5 -o %s/state.fold --svg %s/state.svg",
             dir, dir);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    free(out);
    char path[1024];
    snprintf(path, sizeof path, "%s/state.fold", dir);
    // Frame 1 is the state: folded coordinates, faceOrders, resolved assignments.
    json_error_t jerr;
    json_t *doc = json_load_file(path, 0, &jerr);
    cr_assert(doc, "%s", jerr.text);
    json_t *fr = json_array_get(json_object_get(doc, "file_frames"), 0);
    cr_assert(fr);
    cr_assert_str_eq(json_string_value(json_array_get(json_object_get(fr, "frame_classes"), 0)), "foldedForm");
    json_t *fo = json_object_get(fr, "faceOrders");
    cr_assert_eq(json_array_size(fo), 6);
    json_t *asg = json_object_get(fr, "edges_assignment");
    for (size_t i = 0; i < json_array_size(asg); ++i) cr_assert_str_neq(json_string_value(json_array_get(asg, i)), "U");
    // The written orders are the library's state 5.
    ori_pattern *p = test_load_pattern(test_repo_path("tests/data/layers/pleat-unassigned.fold"), 0);
    ori_layers *L = solve_pattern(p, NULL);
    ori_error err;
    cr_assert_eq(ori_layers_select_state(L, "5", &err), ORI_OK);
    int orders[18];
    cr_assert_eq(ori_layers_face_orders(L, orders, 6), 6);
    for (int i = 0; i < 6; ++i) {
        json_t *t = json_array_get(fo, (size_t)i);
        for (int j = 0; j < 3; ++j) cr_assert_eq(json_integer_value(json_array_get(t, (size_t)j)), orders[3 * i + j]);
    }
    // Every folded vertex lies in the unit square the stamps fold onto (exact: reflections of
    // integer coordinates).
    json_t *vc = json_object_get(fr, "vertices_coords");
    for (size_t v = 0; v < json_array_size(vc); ++v) {
        double x = json_number_value(json_array_get(json_array_get(vc, v), 0));
        cr_assert(x == 0.0 || x == 1.0, "folded x = %g", x);
    }
    json_decref(doc);
    ori_layers_destroy(L);
    ori_pattern_destroy(p);
    // The written folded form (U creases now resolved as state 5 folds them; its faces' winding
    // gives their side) has state 5 among its states.
    p = test_load_pattern(path, 1);
    L = solve_pattern(p, NULL);
    char *s = states_of(L);
    int n = atoi(s);
    ori_buffer_free(s);
    bool found = false;
    for (int k = 0; k < n && !found; ++k) {
        char ks[16];
        snprintf(ks, sizeof ks, "%d", k);
        cr_assert_eq(ori_layers_select_state(L, ks, &err), ORI_OK);
        int again[18];
        cr_assert_eq(ori_layers_face_orders(L, again, 6), 6);
        found = memcmp(again, orders, sizeof again) == 0;
    }
    cr_assert(found, "state 5 is not a state of the written folded form (%d states)", n);
    ori_layers_destroy(L);
    ori_pattern_destroy(p);
    // The picture.
    snprintf(path, sizeof path, "%s/state.svg", dir);
    char *svg = test_read_text(path);
    cr_assert(svg);
    cr_assert(strstr(svg, "<svg"));
    cr_assert(strstr(svg, "<path"));
    cr_assert_gt(strlen(svg), 2000);
    free(svg);
    test_tmpdir_remove(dir);
}

Test(layers, cli_json_has_exactly_the_documented_fields)
{
    char *out = NULL;
    cr_assert_eq(test_run_cli("layers tests/data/layers/pleat-unassigned.fold --json", &out), 0);
    json_error_t jerr;
    json_t *o = json_loads(out, 0, &jerr);
    cr_assert(o, "%s", out);
    const char *keys[] = {"states",    "components",       "faces",         "variables",    "constraints",
                          "tolerance", "tolerance_source", "drawing_noise", "unsatisfiable"};
    cr_assert_eq(json_object_size(o), 9);
    for (int i = 0; i < 9; ++i) cr_assert(json_object_get(o, keys[i]), "%s", keys[i]);
    cr_assert_str_eq(json_string_value(json_object_get(o, "states")), "16");
    // Exact coordinates: the tolerance from the drawing is the strict default.
    cr_assert_str_eq(json_string_value(json_object_get(o, "tolerance_source")), "drawing");
    cr_assert_float_eq(json_number_value(json_object_get(o, "tolerance")), ORI_TOL_LAYERS_SNAP_REL, 1e-20);
    cr_assert_eq(json_object_size(json_object_get(o, "drawing_noise")), 2);
    cr_assert(json_is_null(json_object_get(o, "unsatisfiable")));
    json_t *c = json_object_get(o, "constraints");
    cr_assert_eq(json_integer_value(json_object_get(c, "taco_taco")), 1);
    cr_assert_eq(json_integer_value(json_object_get(c, "transitivity")), 4);
    json_decref(o);
    free(out);
    // No state: exit 1 with the reason.
    cr_assert_eq(test_run_cli("layers examples/patterns/non-flat-foldable-vertex.fold --json", &out), 1);
    o = json_loads(out, 0, &jerr);
    cr_assert(o, "%s", out);
    cr_assert_str_eq(json_string_value(json_object_get(o, "states")), "0");
    json_t *u = json_object_get(o, "unsatisfiable");
    cr_assert_str_eq(json_string_value(json_object_get(u, "constraint")), "local");
    cr_assert_eq(json_integer_value(json_object_get(u, "vertex")), 0);
    json_decref(o);
    free(out);
}
