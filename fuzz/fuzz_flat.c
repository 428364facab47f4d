// libFuzzer target for the local flat-foldability checks (include/orikin/flat.h). Input: a
// FOLD document when it starts with '{' (frame 0, small patterns only: ≤ 64 vertices, ≤ 200
// edges), checked with ori_flat_check_pattern (exact, and with a tolerance from the document's
// length), every recorded vertex compared with ori_flat_check_vertex and ori_flat_vertex_creases
// and run through the single-vertex checks below; otherwise a single vertex: byte 0 the degree
// (2…12), byte 1 the mode (bit 0: sectors scaled so that both alternating sums are π, i.e.
// flat and Kawasaki; bit 1: one sector byte per sector, else eight bytes as a raw double made
// finite and ≥ 0), the sectors, then the assignments (two bits per crease: M, V, U, F) and a
// snapping tolerance byte. Invariants (abort on violation): no crash, leak or sanitizer report;
// ori_flat_kawasaki_sum equals the alternating sum recomputed here (1e-9), ori_flat_kawasaki
// matches it; ori_flat_maekawa equals |#M − #V| = 2 counted here; ori_flat_count_assignments
// equals the rows of ori_flat_enumerate (not truncated, lexicographic, distinct) and a brute
// force over all 2^n M/V assignments filtered by ori_flat_assignment_valid (the same rows);
// every valid assignment satisfies Kawasaki, Maekawa and big-little-big; the completions of
// the U creases: ori_flat_count_completions = rows of ori_flat_enumerate_completions = brute
// force, each row keeping the M/V creases; ori_flat_snap_sectors, when finite, returns the
// largest change and its sectors satisfy Kawasaki and sum to 2π (1e-9); pattern reports:
// failed ≤ interior, within ≤ interior, recorded = interior, flat_foldable ⇔ failed = 0, max
// deviation finite, ≥ 0 and ≥ each recorded vertex's deviation, violations in range and finite.
#include <orikin/orikin.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define MAXN 12

static const double TWO_PI = 6.283185307179586476925286766559;

static void to_row(const ori_assignment *a, int n, char *row)
{
    for (int i = 0; i < n; i++) row[i] = a[i] == ORI_ASSIGN_MOUNTAIN ? 'M' : 'V';
    row[n] = '\0';
}

static void from_row(const char *row, int n, ori_assignment *a)
{
    for (int i = 0; i < n; i++) {
        if (row[i] != 'M' && row[i] != 'V') abort();
        a[i] = row[i] == 'M' ? ORI_ASSIGN_MOUNTAIN : ORI_ASSIGN_VALLEY;
    }
    if (row[n] != '\0') abort();
}

// Every single-vertex invariant for sectors s (finite, ≥ 0) and assignments a (M, V, U, F).
static void check_vertex(const double *s, const ori_assignment *a, int n, double snap_tol)
{
    static char rows[(1 << MAXN) * (MAXN + 1)], brute[(1 << MAXN) * (MAXN + 1)];
    double alt = 0.0, sum = 0.0;
    for (int i = 0; i < n; i++) alt += (i & 1) ? -s[i] : s[i], sum += s[i];
    double ks = ori_flat_kawasaki_sum(s, n);
    if (fabs(ks - alt) > 1e-9 * (1.0 + sum)) abort();
    bool kaw = ori_flat_kawasaki(s, n);
    if (kaw != (n % 2 == 0 && fabs(ks) <= ORI_TOL_KAWASAKI_RAD)) abort();

    // M/V assignment: U and F taken as M and V
    ori_assignment mv[MAXN], comp[MAXN];
    int m = 0, v = 0, u = 0;
    for (int i = 0; i < n; i++) {
        mv[i] = (a[i] == ORI_ASSIGN_MOUNTAIN || a[i] == ORI_ASSIGN_UNASSIGNED) ? ORI_ASSIGN_MOUNTAIN : ORI_ASSIGN_VALLEY;
        m += mv[i] == ORI_ASSIGN_MOUNTAIN, v += mv[i] == ORI_ASSIGN_VALLEY;
        comp[i] = (a[i] == ORI_ASSIGN_MOUNTAIN || a[i] == ORI_ASSIGN_VALLEY) ? a[i] : ORI_ASSIGN_UNASSIGNED;
        u += comp[i] == ORI_ASSIGN_UNASSIGNED;
    }
    if (ori_flat_maekawa(mv, n) != (abs(m - v) == 2)) abort();
    int rc = -7;
    int blb = ori_flat_big_little_big(s, mv, n, &rc);
    if (blb != ORI_NULL_INDEX && (blb < 0 || blb >= n || rc < 2 || rc > n)) abort();

    // count = enumerate = brute force
    ori_mv_count c = ori_flat_count_assignments(s, n);
    if (c.overflow || c.count > (1u << n)) abort();
    if (!kaw && c.count != 0) abort();
    bool trunc = true;
    int rows_n = ori_flat_enumerate(s, n, rows, 1 << n, &trunc);
    if (trunc || rows_n < 0 || (uint64_t)rows_n != c.count) abort();
    int brute_n = 0;
    for (int mask = 0; mask < (1 << n); mask++) {
        ori_assignment t[MAXN];
        for (int i = 0; i < n; i++) t[i] = (mask >> (n - 1 - i)) & 1 ? ORI_ASSIGN_VALLEY : ORI_ASSIGN_MOUNTAIN;
        if (!ori_flat_assignment_valid(s, t, n)) continue;
        if (!kaw || !ori_flat_maekawa(t, n) || ori_flat_big_little_big(s, t, n, NULL) != ORI_NULL_INDEX) abort();
        to_row(t, n, brute + (size_t)brute_n * (MAXN + 1));
        brute_n++;
    }
    if (brute_n != rows_n) abort();
    for (int r = 0; r < rows_n; r++) {
        ori_assignment t[MAXN];
        from_row(rows + (size_t)r * (size_t)(n + 1), n, t);
        if (strcmp(rows + (size_t)r * (size_t)(n + 1), brute + (size_t)r * (MAXN + 1)) != 0) abort();
    }

    // completions of the U creases
    ori_mv_count cc = ori_flat_count_completions(s, comp, n);
    if (cc.overflow || cc.count > (1u << u)) abort();
    int cr = ori_flat_enumerate_completions(s, comp, n, rows, 1 << u, &trunc);
    if (trunc || cr < 0 || (uint64_t)cr != cc.count) abort();
    int cb = 0;
    for (int mask = 0; mask < (1 << u); mask++) {
        ori_assignment t[MAXN];
        for (int i = 0, k = 0; i < n; i++)
            t[i] = comp[i] != ORI_ASSIGN_UNASSIGNED ? comp[i] : ((mask >> k++) & 1 ? ORI_ASSIGN_VALLEY : ORI_ASSIGN_MOUNTAIN);
        cb += ori_flat_assignment_valid(s, t, n);
    }
    if (cb != cr) abort();
    for (int r = 0; r < cr; r++) {
        ori_assignment t[MAXN];
        from_row(rows + (size_t)r * (size_t)(n + 1), n, t);
        if (!ori_flat_assignment_valid(s, t, n)) abort();
        for (int i = 0; i < n; i++)
            if (comp[i] != ORI_ASSIGN_UNASSIGNED && comp[i] != t[i]) abort();
    }

    // snapping
    double out[MAXN];
    double dev = ori_flat_snap_sectors(s, n, snap_tol, out);
    if (isnan(dev) || dev < 0.0) abort();
    if (isfinite(dev)) {
        double oalt = 0.0, osum = 0.0, big = 0.0;
        for (int i = 0; i < n; i++) {
            if (!isfinite(out[i])) abort();
            oalt += (i & 1) ? -out[i] : out[i], osum += out[i];
            big = fmax(big, fabs(out[i] - s[i]));
        }
        if (fabs(oalt) > 1e-9 || fabs(osum - TWO_PI) > 1e-9) abort();
        if (fabs(big - dev) > 1e-9) abort();
    }
}

static void check_pattern(const ori_pattern *p, double tol)
{
    ori_flat_check_def def = ori_default_flat_check_def();
    def.tolerance_rad = tol;
    ori_flat_report *r = ori_flat_check_pattern(p, &def);
    int interior = ori_flat_report_interior_count(r), failed = ori_flat_report_failed_count(r);
    int within = ori_flat_report_within_count(r), nv = ori_flat_report_vertex_count(r);
    double maxdev = ori_flat_report_max_deviation(r);
    if (interior < 0 || interior > ori_pattern_vertex_count(p) || failed < 0 || failed > interior ||
        within < 0 || within > interior || nv != interior)
        abort();
    if (ori_flat_report_flat_foldable(r) != (failed == 0)) abort();
    if (!isfinite(maxdev) || maxdev < 0.0 || (within == 0 && maxdev != 0.0)) abort();
    for (int i = 0; i < nv; i++) {
        ori_vertex_report vr = ori_flat_report_vertex(r, i);
        if (vr.vertex < 0 || vr.vertex >= ori_pattern_vertex_count(p)) abort();
        if (vr.mountains + vr.valleys + vr.unassigned != vr.degree) abort();
        if (!isfinite(vr.deviation_rad) || vr.deviation_rad < 0.0) abort();
        if (vr.within_tolerance && vr.deviation_rad > maxdev) abort();
        int edges[64];
        double sec[64], sec2[64];
        int d = ori_flat_report_vertex_creases(r, i, edges, sec, 64);
        int d2 = ori_flat_vertex_creases(p, vr.vertex, NULL, sec2, 64);
        if (d != vr.degree || d2 != d) abort();
        if (tol == 0.0) {
            ori_vertex_report one;
            ori_flat_check_vertex(p, vr.vertex, &one);
            if (one.degree != vr.degree || one.flat_foldable != vr.flat_foldable ||
                one.mountains != vr.mountains || one.valleys != vr.valleys)
                abort();
            if (d >= 2 && d <= MAXN) {
                bool ok = true;
                for (int k = 0; k < d; k++) ok = ok && isfinite(sec[k]) && sec[k] >= 0.0;
                if (ok) {
                    ori_assignment a[MAXN];
                    for (int k = 0; k < d; k++) a[k] = ori_pattern_edge(p, edges[k]).assignment;
                    check_vertex(sec, a, d, 0.01);
                }
            }
        }
    }
    int nviol = ori_flat_report_violation_count(r);
    if (nviol < 0) abort();
    for (int i = 0; i < nviol; i++) {
        ori_flat_violation fv = ori_flat_report_violation(r, i);
        if (fv.vertex < 0 || fv.vertex >= ori_pattern_vertex_count(p) || fv.rule < 0 ||
            fv.rule >= ORI_FLAT_RULE_COUNT || !isfinite(fv.value) || fv.edge < -1 ||
            fv.edge >= ori_pattern_edge_count(p) || memchr(fv.detail, '\0', sizeof fv.detail) == NULL)
            abort();
    }
    ori_flat_report_destroy(r);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size >= 1 && data[0] == '{') {
        ori_fold *doc = NULL;
        ori_error err;
        if (ori_fold_load_string((const char *)data, size, &doc, &err) != ORI_OK) return 0;
        ori_pattern *p = NULL;
        if (ori_fold_get_pattern(doc, 0, NULL, &p, &err) == ORI_OK && ori_pattern_vertex_count(p) <= 64 &&
            ori_pattern_edge_count(p) <= 200) {
            check_pattern(p, 0.0);
            check_pattern(p, (double)(size % 100) * 1e-4);
        }
        ori_pattern_destroy(p);
        ori_fold_destroy(doc);
        if (ori_alloc_live_count() != 0) abort();
        return 0;
    }
    if (size < 2) return 0;
    int n = 2 + data[0] % (MAXN - 1);
    int mode = data[1];
    data += 2, size -= 2;
    double s[MAXN];
    for (int i = 0; i < n; i++) {
        if (mode & 2) {
            s[i] = size ? (double)*data / 255.0 * 3.14159265358979 : 0.0;
            if (size) data++, size--;
        } else {
            double x = 0.0;
            if (size >= 8) {
                memcpy(&x, data, 8);
                data += 8, size -= 8;
            }
            s[i] = isfinite(x) ? fabs(x) : 0.0;
            if (s[i] > 1e6) s[i] = fmod(s[i], 1e6);
        }
    }
    if ((mode & 1) && n % 2 == 0) { // both alternating sums π: flat and Kawasaki
        double e = 0.0, o = 0.0;
        for (int i = 0; i < n; i++) {
            if (i & 1) o += s[i];
            else e += s[i];
        }
        for (int i = 0; i < n; i++) {
            double t = i & 1 ? o : e;
            s[i] = t > 0.0 ? s[i] * (TWO_PI / 2.0) / t : TWO_PI / (double)n;
        }
    }
    ori_assignment a[MAXN];
    static const ori_assignment letters[4] = {ORI_ASSIGN_MOUNTAIN, ORI_ASSIGN_VALLEY, ORI_ASSIGN_UNASSIGNED, ORI_ASSIGN_FLAT};
    uint32_t bits = 0;
    for (int k = 0; k < 3 && size; k++) bits |= (uint32_t)*data << (8 * k), data++, size--;
    for (int i = 0; i < n; i++) a[i] = letters[(bits >> (2 * i)) & 3];
    double snap_tol = size ? (double)*data * 1e-4 : 0.0;
    check_vertex(s, a, n, snap_tol);
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
