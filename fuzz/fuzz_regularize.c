// libFuzzer target for regularization (regularize.h, issue 27 item 6). The input is either a raw
// FOLD document (it starts with '{'; frame 0, at most 64 vertices and 160 edges, as fuzz_layers
// reads it) or bytes that make a nearly flat-foldable pattern: a single vertex of degree 4, 6 or
// 8 whose alternate sectors sum to π, with a Maekawa assignment (or a fuzzed one), or a generated
// Miura, Yoshimura or square twist of at most 2 × 2 cells; its vertices then jittered (up to about 1e-3 of
// its size, sometimes not at all) and the pattern rebuilt from FOLD text. Options fuzzed: rigid,
// rigid only, max_move_rel (0, tiny, the default, 1, huge, inf) and 1–8 iterations (bounded work).
// Invariants: no crash, leak or sanitizer report; a refusal carries a message and gives no pattern;
// iterations ≤ the limit; a pattern is given only for a converged, not refused answer with no
// crossing edge, and then it has the same vertex, edge and face counts, the same edge ends,
// assignments and fold angles, Kawasaki after ≤ ORI_TOL_REGULARIZE_KAWASAKI_RAD and (but rigid
// only) passes ori_flat_check_pattern exactly as flat_foldable says, no vertex moved farther than
// the reported max_move_rel ≤ the option's, the reported vertex the one that moved most, the moved
// ones counted, rms ≤ max; refused only beyond the limit; an answer without a pattern is not
// converged, refused or crossing; a vertex of odd degree is never converged but with rigid only;
// the same input twice gives the same answer (a quarter of the inputs); but rigid only, the result
// regularized again is converged and moves no vertex farther than 1e-7 of the diagonal.
#include <float.h>
#include <math.h>
#include <orikin/orikin.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_bytes.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);


static ori_pattern *fr_from_text(const char *text)
{
    ori_fold *doc = NULL;
    ori_error err;
    if (ori_fold_load_string(text, strlen(text), &doc, &err) != ORI_OK) return NULL;
    ori_pattern *p = NULL;
    ori_fold_get_pattern(doc, 0, NULL, &p, &err);
    ori_fold_destroy(doc);
    return p;
}

// A flat-foldable vertex of degree 4, 6 or 8 (alternate sectors summing to π, every sector in
// [12°, 170°]) with creases to the unit circle and boundary chords, written as FOLD text.
static ori_pattern *fr_vertex(fk_bytes *b, double jitter)
{
    int k = 2 + fk_u8(b) % 3, n = 2 * k;
    double w[8], sum[2] = {0.0, 0.0};
    for (int i = 0; i < n; ++i) sum[i & 1] += w[i] = 1.0 + fk_u8(b);
    double t = fk_range(b, 0.0, 2.0 * ORI_PI);
    double cx = jitter * fk_range(b, -1.0, 1.0), cy = jitter * fk_range(b, -1.0, 1.0);
    char text[4096];
    size_t len = 0;
    len += (size_t)snprintf(text + len, sizeof text - len, "{\"vertices_coords\":[[%.17g,%.17g]", cx, cy);
    for (int i = 0; i < n; ++i) {
        double gap = ORI_PI * w[i] / sum[i & 1];
        if (gap < 12.0 * ORI_PI / 180.0 || gap > 170.0 * ORI_PI / 180.0) return NULL;
        double a = t + jitter * fk_range(b, -1.0, 1.0);
        len += (size_t)snprintf(text + len, sizeof text - len, ",[%.17g,%.17g]", cos(a), sin(a));
        t += gap;
    }
    len += (size_t)snprintf(text + len, sizeof text - len, "],\"edges_vertices\":[");
    for (int i = 0; i < n; ++i) len += (size_t)snprintf(text + len, sizeof text - len, "%s[0,%d]", i ? "," : "", i + 1);
    for (int i = 0; i < n; ++i) len += (size_t)snprintf(text + len, sizeof text - len, ",[%d,%d]", i + 1, (i + 1) % n + 1);
    len += (size_t)snprintf(text + len, sizeof text - len, "],\"edges_assignment\":[");
    // Maekawa: k + 1 creases of one kind, rotated; or the fuzzed bits as they come.
    uint8_t mv = fk_u8(b), how = fk_u8(b);
    char letter[8];
    for (int i = 0; i < n; ++i) {
        if (how & 1) letter[i] = (mv >> i) & 1 ? 'M' : 'V';
        else letter[i] = ((i + mv) % n < k + 1) == !(how & 2) ? 'M' : 'V';
    }
    for (int i = 0; i < n; ++i) len += (size_t)snprintf(text + len, sizeof text - len, "%s\"%c\"", i ? "," : "", letter[i]);
    for (int i = 0; i < n; ++i) len += (size_t)snprintf(text + len, sizeof text - len, ",\"B\"");
    snprintf(text + len, sizeof text - len, "]}");
    return fr_from_text(text);
}

// A generated Miura or square twist (flat-foldable), its vertices jittered, rebuilt from FOLD text.
static ori_pattern *fr_generated(fk_bytes *b, double jitter)
{
    static const ori_tessellation kinds[] = {ORI_TESS_MIURA, ORI_TESS_SQUARE_TWIST, ORI_TESS_MIURA, ORI_TESS_YOSHIMURA};
    ori_generate_def g = ori_default_generate_def(kinds[fk_u8(b) % 4]);
    g.rows = 1 + fk_u8(b) % 2;
    g.cols = 1 + fk_u8(b) % 2;
    if (fk_u8(b) & 1) g.angle_rad = fk_range(b, 5.0, 85.0) * ORI_PI / 180.0;
    ori_pattern *p = NULL;
    ori_error err;
    if (ori_generate(&g, &p, NULL, &err) != ORI_OK) return NULL;
    int V = ori_pattern_vertex_count(p), E = ori_pattern_edge_count(p);
    double L = ori_pattern_diagonal(p);
    size_t cap = 256 + (size_t)V * 96 + (size_t)E * 32, len = 0;
    char *text = malloc(cap);
    len += (size_t)snprintf(text + len, cap - len, "{\"vertices_coords\":[");
    for (int v = 0; v < V; ++v) {
        ori_v3 x = ori_pattern_vertex(p, v);
        double dx = 0.0, dy = 0.0;
        if (fk_u8(b) & 1) {
            dx = jitter * L * fk_range(b, -1.0, 1.0);
            dy = jitter * L * fk_range(b, -1.0, 1.0);
        }
        len += (size_t)snprintf(text + len, cap - len, "%s[%.17g,%.17g]", v ? "," : "", x.x + dx, x.y + dy);
    }
    len += (size_t)snprintf(text + len, cap - len, "],\"edges_vertices\":[");
    for (int e = 0; e < E; ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        len += (size_t)snprintf(text + len, cap - len, "%s[%d,%d]", e ? "," : "", ed.v[0], ed.v[1]);
    }
    len += (size_t)snprintf(text + len, cap - len, "],\"edges_assignment\":[");
    for (int e = 0; e < E; ++e)
        len += (size_t)snprintf(text + len, cap - len, "%s\"%c\"", e ? "," : "", ori_assignment_to_char(ori_pattern_edge(p, e).assignment));
    snprintf(text + len, cap - len, "]}");
    ori_pattern_destroy(p);
    ori_pattern *q = fr_from_text(text);
    free(text);
    return q;
}

static double fr_max_move(fk_bytes *b)
{
    switch (fk_u8(b) % 8) {
    case 0: return 0.0;
    case 1: return 1e-300;
    case 2: return 1.0;
    case 3: return 1e300;
    case 4: return INFINITY;
    case 5: return DBL_MAX;
    case 6: return fk_range(b, 0.0, 1e-2);
    default: return ORI_REGULARIZE_MAX_MOVE_REL;
    }
}

static int fr_run(const ori_pattern *p, const ori_regularize_def *def, ori_pattern **out, ori_regularize_result *r)
{
    ori_error err;
    memset(r, 0, sizeof *r);
    ori_status st = ori_regularize(p, def, out, r, &err);
    if (st != ORI_OK) {
        if (err.status != st || err.message[0] == '\0') abort(); // a refusal says why
        if (*out) abort();
    }
    return st;
}

// twice: run it twice and compare (a quarter of the inputs, to keep the work per input small).
static void fr_check(const ori_pattern *p, const ori_regularize_def *def, bool twice)
{
    ori_pattern *q = NULL, *q2 = NULL;
    ori_regularize_result r, r2;
    ori_status st = fr_run(p, def, &q, &r);
    int V = ori_pattern_vertex_count(p), E = ori_pattern_edge_count(p);
    if (twice) {
        ori_status st2 = fr_run(p, def, &q2, &r2);
        if (st != st2) abort();
        // The same answer twice.
        if (st == ORI_OK &&
            (r.converged != r2.converged || r.refused != r2.refused || r.iterations != r2.iterations ||
             r.max_move_rel != r2.max_move_rel || r.max_move_vertex != r2.max_move_vertex || !q != !q2 ||
             r.flat_foldable != r2.flat_foldable || r.check_vertex != r2.check_vertex || r.odd_vertex != r2.odd_vertex))
            abort();
        if (q && q2)
            for (int v = 0; v < V; ++v) {
                ori_v3 a = ori_pattern_vertex(q, v), c = ori_pattern_vertex(q2, v);
                if (a.x != c.x || a.y != c.y || a.z != c.z) abort();
            }
        ori_pattern_destroy(q2);
    }
    if (st != ORI_OK) return;

    if (!(r.iterations >= 0 && r.iterations <= def->max_iterations)) abort();
    if (!(r.odd_vertex == ORI_NULL_INDEX || (r.odd_vertex >= 0 && r.odd_vertex < V))) abort();
    if (!(r.max_move_vertex == ORI_NULL_INDEX || (r.max_move_vertex >= 0 && r.max_move_vertex < V))) abort();
    if (!(r.crossing_edge == ORI_NULL_INDEX || (r.crossing_edge >= 0 && r.crossing_edge < E))) abort();
    if (!(r.check_vertex == ORI_NULL_INDEX || (r.check_vertex >= 0 && r.check_vertex < V))) abort();
    if (!(r.max_move_rel >= 0.0) || !(r.rms_move_rel >= 0.0)) abort();
    if (r.converged && r.odd_vertex != ORI_NULL_INDEX && !def->rigid_only) abort(); // no move helps an odd degree
    if (r.refused && !(r.max_move_rel > def->max_move_rel)) abort(); // refused only beyond the limit
    if (!q) {
        if (r.converged && !r.refused && r.crossing_edge == ORI_NULL_INDEX) abort(); // where is the pattern?
        return;
    }
    // A pattern: converged, within the limit, the same structure.
    if (!r.converged || r.refused || r.crossing_edge != ORI_NULL_INDEX) abort();
    if (!ori_pattern_is_built(q)) abort();
    if (ori_pattern_vertex_count(q) != V || ori_pattern_edge_count(q) != E ||
        ori_pattern_face_count(q) != ori_pattern_face_count(p))
        abort();
    for (int e = 0; e < E; ++e) {
        ori_edge a = ori_pattern_edge(p, e), c = ori_pattern_edge(q, e);
        if (a.v[0] != c.v[0] || a.v[1] != c.v[1] || a.assignment != c.assignment ||
            !(a.fold_angle_rad == c.fold_angle_rad || (isnan(a.fold_angle_rad) && isnan(c.fold_angle_rad))))
            abort();
    }
    if (!def->rigid_only && !(r.kawasaki_after_rad <= ORI_TOL_REGULARIZE_KAWASAKI_RAD)) abort();
    if ((def->rigid || def->rigid_only) && !(r.rigid_after <= ORI_TOL_REGULARIZE_RIGID)) abort();
    if (!(r.max_move_rel <= def->max_move_rel)) abort();
    if (!(r.rms_move_rel <= r.max_move_rel * (1.0 + 1e-12) + 1e-300)) abort();
    ori_flat_report *rep = ori_flat_check_pattern(q, NULL);
    bool flat = ori_flat_report_flat_foldable(rep);
    ori_flat_report_destroy(rep);
    if (!def->rigid_only && (!r.flat_foldable || !flat)) {
        fprintf(stderr, "a pattern given, flat_foldable %d, the check says %d\n", r.flat_foldable, flat);
        abort();
    }
    if (r.flat_foldable != flat) abort();
    // Displacements: none beyond the reported largest, the reported vertex the one that moved most.
    double L = ori_pattern_diagonal(p), most = 0.0;
    int moved = 0;
    for (int v = 0; v < V; ++v) {
        ori_v3 a = ori_pattern_vertex(p, v), c = ori_pattern_vertex(q, v);
        double d = hypot(hypot(a.x - c.x, a.y - c.y), a.z - c.z) / L;
        moved += d > 0.0;
        if (d > most) most = d;
        if (!(d <= r.max_move_rel * (1.0 + 1e-9) + 1e-15)) {
            fprintf(stderr, "vertex %d moved %.17g (of the diagonal), reported at most %.17g\n", v, d, r.max_move_rel);
            abort();
        }
    }
    if (r.max_move_vertex != ORI_NULL_INDEX) {
        ori_v3 a = ori_pattern_vertex(p, r.max_move_vertex), c = ori_pattern_vertex(q, r.max_move_vertex);
        double d = hypot(hypot(a.x - c.x, a.y - c.y), a.z - c.z) / L;
        if (!(fabs(d - most) <= 1e-9 * most + 1e-15)) abort();
    } else if (most > 1e-15) {
        abort(); // moved, but no vertex named
    }
    if (moved != r.moved_vertices) abort();
    // Idempotent: the result regularized again is converged and (nearly) stays where it is. Its
    // precision is then ORI_TOL_ANGLE_EQUAL_RAD (1e-8): ties within it may move vertices by about
    // as much. Not rigid only: without Kawasaki the drawing's precision stays as coarse as it
    // was, and the first result's new near-equalities become ties (moves of 1e-5 are answers).
    if (def->rigid_only) {
        ori_pattern_destroy(q);
        return;
    }
    ori_pattern *q3 = NULL;
    ori_regularize_result r3;
    if (fr_run(q, def, &q3, &r3) != ORI_OK) abort();
    if (!q3 || !r3.converged || !(r3.max_move_rel <= 1e-7)) {
        fprintf(stderr, "regularized again: converged %d, pattern %d, moved %.3g (first %.3g)\n", r3.converged, q3 != NULL,
                r3.max_move_rel, r.max_move_rel);
        fprintf(stderr,
                "first: ties %d parallels %d sides %d tau %.3g kawasaki %.3g -> %.3g iterations %d; again: ties %d "
                "parallels %d sides %d tau %.3g kawasaki %.3g -> %.3g iterations %d vertex %d rigid %d only %d\n",
                r.ties, r.parallels_kept, r.sides_moved, r.equal_tolerance_rad, r.kawasaki_before_rad, r.kawasaki_after_rad,
                r.iterations, r3.ties, r3.parallels_kept, r3.sides_moved, r3.equal_tolerance_rad, r3.kawasaki_before_rad,
                r3.kawasaki_after_rad, r3.iterations, r3.max_move_vertex, def->rigid, def->rigid_only);
        abort();
    }
    ori_pattern_destroy(q3);
    ori_pattern_destroy(q);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    ori_pattern *p = NULL;
    fk_bytes b = {data, size, 0};
    if (size > 0 && data[0] == '{') {
        // A raw FOLD document; the options from its last bytes.
        ori_fold *doc = NULL;
        ori_error err;
        if (ori_fold_load_string((const char *)data, size, &doc, &err) == ORI_OK) {
            ori_fold_get_pattern(doc, 0, NULL, &p, &err);
            ori_fold_destroy(doc);
        }
        b.at = size > 8 ? size - 8 : 0;
        if (p && (ori_pattern_vertex_count(p) > 64 || ori_pattern_edge_count(p) > 160)) {
            ori_pattern_destroy(p);
            p = NULL;
        }
    } else {
        uint8_t how = fk_u8(&b);
        double jitter = how & 2 ? 0.0 : how & 4 ? 1e-3 * fk_range(&b, 0.0, 1.0) : 1e-7 * fk_range(&b, 0.0, 1.0);
        p = how & 1 ? fr_generated(&b, jitter) : fr_vertex(&b, jitter);
    }
    if (p) {
        ori_regularize_def def = ori_default_regularize_def();
        uint8_t o = fk_u8(&b);
        def.rigid = o & 1;
        def.rigid_only = (o & 6) == 6;
        def.max_move_rel = fr_max_move(&b);
        def.max_iterations = 1 + fk_u8(&b) % 8;
        fr_check(p, &def, (o & 24) == 24);
        ori_pattern_destroy(p);
    }
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
