// Flat-foldability: Hull's count (SPEC reference values, Theorem 3 bounds), enumeration, the
// exact crimp test and their agreement on random vertices, completions of U creases, big-little-
// big, pattern checks of reference files, and the `check` / `mv-count` CLI on bad input.
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <jansson.h>
#include <orikin/flat.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "flat/flat_internal.h"
#include "support.h"

TestSuite(flat, .init = test_leak_setup, .fini = test_leak_check);

// --- helpers -------------------------------------------------------------------------------

#define MAXN 64

static void to_rad(const double *deg, int n, double *rad)
{
    for (int i = 0; i < n; ++i) rad[i] = ori_deg_to_rad(deg[i]);
}

static ori_mv_count count_deg(const double *deg, int n)
{
    double rad[MAXN];
    to_rad(deg, n, rad);
    return ori_flat_count_assignments(rad, n);
}

static void equal_sectors(int n, double *rad)
{
    for (int i = 0; i < n; ++i) rad[i] = 2.0 * ORI_PI / n;
}

static void parse_letters(const char *s, ori_assignment *a)
{
    for (int i = 0; s[i]; ++i) cr_assert(ori_assignment_from_char(s[i], &a[i]));
}

static bool valid_deg(const double *deg, const char *letters)
{
    int n = (int)strlen(letters);
    double rad[MAXN];
    ori_assignment a[MAXN];
    to_rad(deg, n, rad);
    parse_letters(letters, a);
    return ori_flat_assignment_valid(rad, a, n);
}

static uint64_t binom(int n, int k)
{
    ori_mv_count c = ori__binomial(n, k);
    cr_assert(!c.overflow);
    return c.count;
}

// xorshift64*: deterministic pseudo-random numbers for the property tests.
static uint64_t rng = 0x9E3779B97F4A7C15ULL;
static uint64_t rnd(void)
{
    rng ^= rng >> 12;
    rng ^= rng << 25;
    rng ^= rng >> 27;
    return rng * 2685821657736338717ULL;
}
static int rnd_int(int lo, int hi) { return lo + (int)(rnd() % (uint64_t)(hi - lo + 1)); }
static double rnd_unit(void) { return (double)(rnd() >> 11) / 9007199254740992.0; }

// A random composition of total into k ≥ 1 positive integer parts.
static void composition(int total, int k, int *parts)
{
    int cuts[MAXN + 1];
    cuts[0] = 0;
    int c = 1;
    while (c < k) { // k − 1 distinct cut points in 1 … total − 1
        int x = rnd_int(1, total - 1);
        bool dup = false;
        for (int j = 1; j < c; ++j) dup |= cuts[j] == x;
        if (!dup) cuts[c++] = x;
    }
    cuts[k] = total;
    for (int i = 1; i < k; ++i) // insertion sort
        for (int j = i; j > 1 && cuts[j - 1] > cuts[j]; --j) {
            int t = cuts[j];
            cuts[j] = cuts[j - 1];
            cuts[j - 1] = t;
        }
    for (int i = 0; i < k; ++i) parts[i] = cuts[i + 1] - cuts[i];
}

// A random Kawasaki vertex of n = 2m creases. Tie-heavy: sectors are multiples of 2π/units with
// few units, so equal sectors and equal runs are common. Generic: real-valued compositions.
// Cones (sector sum ≠ 2π, alternating sum still 0) with probability 1/5.
static void random_vertex(int n, bool ties, double *rad)
{
    int m = n / 2;
    if (ties) {
        static const int units_choice[] = {8, 12, 16, 24, 36};
        int units;
        do units = units_choice[rnd_int(0, 4)];
        while (units / 2 < m);
        int odd[MAXN], even[MAXN];
        composition(units / 2, m, odd);
        composition(units / 2, m, even);
        for (int i = 0; i < m; ++i) {
            rad[2 * i] = odd[i] * (2.0 * ORI_PI / units);
            rad[2 * i + 1] = even[i] * (2.0 * ORI_PI / units);
        }
    } else {
        double so = 0, se = 0;
        for (int i = 0; i < m; ++i) {
            rad[2 * i] = 0.05 + rnd_unit();
            rad[2 * i + 1] = 0.05 + rnd_unit();
            so += rad[2 * i];
            se += rad[2 * i + 1];
        }
        for (int i = 0; i < m; ++i) {
            rad[2 * i] *= ORI_PI / so;
            rad[2 * i + 1] *= ORI_PI / se;
        }
    }
    if (rnd_int(0, 4) == 0) {
        double f = 0.5 + rnd_unit();
        for (int i = 0; i < n; ++i) rad[i] *= f;
    }
}

// Every assignment (2^n, crease 0 first) accepted by the exact test, sorted; returns the count.
static int brute_force_valid(const double *rad, int n, char *rows)
{
    int count = 0;
    ori_assignment a[MAXN];
    for (uint32_t mask = 0; mask < (1u << n); ++mask) {
        for (int i = 0; i < n; ++i) a[i] = (mask >> (n - 1 - i)) & 1 ? ORI_ASSIGN_VALLEY : ORI_ASSIGN_MOUNTAIN;
        if (!ori_flat_assignment_valid(rad, a, n)) continue;
        char *row = rows + (size_t)count * (size_t)(n + 1);
        for (int i = 0; i < n; ++i) row[i] = ori_assignment_to_char(a[i]);
        row[n] = '\0';
        count++;
    }
    return count; // mask order with M = 0 first is lexicographic order (M < V)
}

// --- Hull's count: SPEC / thesis reference values -----------------------------------------

Test(flat, thesis_example_c_100_70_50_40_30_70_is_8)
{
    const double deg[] = {100, 70, 50, 40, 30, 70};
    ori_mv_count c = count_deg(deg, 6);
    cr_assert_eq(c.count, 8);
    cr_assert(!c.overflow);
}

Test(flat, c_90_90_90_90_is_8)
{
    const double deg[] = {90, 90, 90, 90};
    cr_assert_eq(count_deg(deg, 4).count, 8);
}

Test(flat, c_60x6_is_30)
{
    const double deg[] = {60, 60, 60, 60, 60, 60};
    cr_assert_eq(count_deg(deg, 6).count, 30);
}

Test(flat, c_45x8_is_112)
{
    const double deg[] = {45, 45, 45, 45, 45, 45, 45, 45};
    cr_assert_eq(count_deg(deg, 8).count, 112);
}

Test(flat, c_60_120_120_60_is_6)
{
    const double deg[] = {60, 120, 120, 60};
    cr_assert_eq(count_deg(deg, 4).count, 6);
    // Thesis fig. 4-4(b): the creases around the two 60° sectors take two of one letter.
    cr_assert(valid_deg(deg, "VVVM"));
    cr_assert(!valid_deg(deg, "VVMV"));
}

Test(flat, theorem3_bounds_hold_and_equal_angles_hit_the_upper_bound)
{
    for (int m = 1; m <= 8; ++m) {
        int n = 2 * m;
        double rad[MAXN];
        equal_sectors(n, rad);
        ori_mv_count c = ori_flat_count_assignments(rad, n);
        uint64_t upper = 2 * binom(n, m - 1), lower = (uint64_t)1 << m;
        cr_assert_eq(c.count, upper, "n=%d: C=%llu, 2*binom=%llu", n, (unsigned long long)c.count,
                     (unsigned long long)upper);
        cr_assert_geq(c.count, lower);
        // Sharpness of the lower bound: generic angles (no equal sectors anywhere in the
        // recursion) give exactly 2^m.
        random_vertex(n, false, rad);
        c = ori_flat_count_assignments(rad, n);
        cr_assert_eq(c.count, lower, "generic n=%d: C=%llu", n, (unsigned long long)c.count);
    }
}

Test(flat, theorem3_bounds_hold_for_random_vertices)
{
    for (int trial = 0; trial < 2000; ++trial) {
        int m = rnd_int(1, 8), n = 2 * m;
        double rad[MAXN];
        random_vertex(n, trial % 3 != 0, rad);
        ori_mv_count c = ori_flat_count_assignments(rad, n);
        cr_assert_geq(c.count, (uint64_t)1 << m);
        cr_assert_leq(c.count, 2 * binom(n, m - 1));
    }
}

Test(flat, count_is_zero_without_kawasaki_and_one_without_creases)
{
    const double bad[] = {80, 100, 80, 100};
    cr_assert_eq(count_deg(bad, 4).count, 0);
    const double odd[] = {90, 90, 45, 45, 90}; // the open corner
    cr_assert_eq(count_deg(odd, 5).count, 0);
    cr_assert_eq(ori_flat_count_assignments(NULL, 0).count, 1);
    const double two[] = {180, 180}; // a straight crease through the vertex
    cr_assert_eq(count_deg(two, 2).count, 2);
    cr_assert(valid_deg(two, "MM"));
    cr_assert(!valid_deg(two, "MV"));
}

Test(flat, count_is_exact_near_uint64_limit_and_overflow_is_flagged)
{
    double rad[128];
    equal_sectors(66, rad);
    ori_mv_count c = ori_flat_count_assignments(rad, 66);
    cr_assert(!c.overflow);
    cr_assert_eq(c.count, 14014184607208045260ULL); // 2·binom(66, 32)
    equal_sectors(80, rad);
    c = ori_flat_count_assignments(rad, 80);
    cr_assert(c.overflow);
    cr_assert_eq(c.count, UINT64_MAX);
    ori_mv_count b = ori__binomial(67, 33);
    cr_assert(!b.overflow);
    cr_assert_eq(b.count, 14226520737620288370ULL);
    cr_assert(ori__binomial(68, 34).overflow);
    cr_assert_eq(ori__binomial(5, 7).count, 0);
}

Test(flat, reduction_with_tied_runs_matches_theorem4)
{
    // k = 1 (two equal smallest sectors): binom(3, 1) = 3, reduced (120, 120): 2.
    const double a[] = {120, 60, 60, 120};
    cr_assert_eq(count_deg(a, 4).count, 6);
    // k = 2 (three 30° sectors between 100 and 50): binom(4, 2) = 6, merged 100 − 30 + 50 = 120,
    // reduced (120, 120): 2.
    const double b[] = {100, 30, 30, 30, 50, 120};
    cr_assert_eq(count_deg(b, 6).count, 12);
    // k = 3 (four 20° sectors between 80 and 100): binom(5, 2) = 10, the run vanishes:
    // (80, 100, 60, 40); then 40 between 60 and 80: 2, merged 60 − 40 + 80 = 100; (100, 100): 2.
    const double c[] = {80, 20, 20, 20, 20, 100, 60, 40};
    cr_assert_eq(count_deg(c, 8).count, 40);
    // Not Kawasaki: 0.
    const double d[] = {80, 30, 30, 30, 100, 90};
    cr_assert_eq(count_deg(d, 6).count, 0);
}

// --- enumeration and the exact test ------------------------------------------------------

Test(flat, enumerate_90x4_gives_the_8_maekawa_assignments)
{
    double rad[4];
    equal_sectors(4, rad);
    char rows[16 * 5];
    bool truncated = true;
    int k = ori_flat_enumerate(rad, 4, rows, 16, &truncated);
    cr_assert_eq(k, 8);
    cr_assert(!truncated);
    const char *want[] = {"MMMV", "MMVM", "MVMM", "MVVV", "VMMM", "VMVV", "VVMV", "VVVM"};
    for (int i = 0; i < 8; ++i) cr_assert_str_eq(rows + 5 * i, want[i]);
}

Test(flat, enumerate_thesis_example_lists_8_valid_assignments)
{
    const double deg[] = {100, 70, 50, 40, 30, 70};
    double rad[6];
    to_rad(deg, 6, rad);
    char rows[64 * 7];
    int k = ori_flat_enumerate(rad, 6, rows, 64, NULL);
    cr_assert_eq(k, 8);
    ori_assignment a[6];
    for (int i = 0; i < k; ++i) {
        parse_letters(rows + 7 * i, a);
        cr_assert(ori_flat_assignment_valid(rad, a, 6), "%s", rows + 7 * i);
        cr_assert(ori_flat_maekawa(a, 6));
        // the 30° sector (creases 4, 5) and the crimped 50° sector (creases 2, 3) are pleats
        cr_assert_neq(a[4], a[5]);
        cr_assert_neq(a[2], a[3]);
    }
}

Test(flat, enumerate_truncates_at_capacity)
{
    double rad[8];
    equal_sectors(8, rad);
    char rows[10 * 9];
    bool truncated = false;
    cr_assert_eq(ori_flat_enumerate(rad, 8, rows, 10, &truncated), 10);
    cr_assert(truncated);
    cr_assert_eq(ori_flat_enumerate(rad, 8, NULL, 0, &truncated), 0);
    cr_assert(truncated);
    // Large degree: the enumeration stops at the cap without materialising C = 2·binom(80, 39).
    double big[80];
    equal_sectors(80, big);
    char *many = malloc(100 * 81);
    cr_assert_eq(ori_flat_enumerate(big, 80, many, 100, &truncated), 100);
    cr_assert(truncated);
    ori_assignment a[80];
    parse_letters(many + 81 * 99, a);
    cr_assert(ori_flat_assignment_valid(big, a, 80));
    free(many);
}

Test(flat, exact_test_on_reference_vertices)
{
    const double rabbit[] = {45, 112.5, 135, 67.5}; // rabbit-ear invalid-single-vertex frame 0
    cr_assert(valid_deg(rabbit, "MVVV"));
    cr_assert(!valid_deg(rabbit, "VVMV")); // 45° sector between V and V
    cr_assert(!valid_deg(rabbit, "MVMV")); // Maekawa
    const double tachi[] = {135, 63.434948822922, 45, 116.565051177078};
    // Flat-Folder unsatisfiable_008: creases around the 45° sector both V.
    cr_assert(!valid_deg(tachi, "MVVV"));
    cr_assert(valid_deg(tachi, "MMVM") || valid_deg(tachi, "MVMM") || valid_deg(tachi, "VMVV"));
    const double kaw_fail[] = {80, 100, 80, 100};
    cr_assert(!valid_deg(kaw_fail, "MMMV"));
}

Test(flat, exact_test_is_invariant_under_rotation_reflection_and_mv_swap)
{
    for (int trial = 0; trial < 500; ++trial) {
        int n = 2 * rnd_int(1, 5);
        double rad[MAXN], rot[MAXN], ref[MAXN];
        random_vertex(n, true, rad);
        ori_assignment a[MAXN], ar[MAXN], af[MAXN], as[MAXN];
        for (int i = 0; i < n; ++i) a[i] = rnd_int(0, 1) ? ORI_ASSIGN_MOUNTAIN : ORI_ASSIGN_VALLEY;
        int s = rnd_int(0, n - 1);
        for (int i = 0; i < n; ++i) {
            rot[i] = rad[(i + s) % n];
            ar[i] = a[(i + s) % n];
            // reflection: crease i ↦ crease −i, sector i (creases i, i+1) ↦ sector −i−1
            af[i] = a[(n - i) % n];
            ref[i] = rad[(2 * n - i - 1) % n];
            as[i] = a[i] == ORI_ASSIGN_MOUNTAIN ? ORI_ASSIGN_VALLEY : ORI_ASSIGN_MOUNTAIN;
        }
        bool v = ori_flat_assignment_valid(rad, a, n);
        cr_assert_eq(ori_flat_assignment_valid(rot, ar, n), v);
        cr_assert_eq(ori_flat_assignment_valid(ref, af, n), v);
        cr_assert_eq(ori_flat_assignment_valid(rad, as, n), v);
    }
}

// The central property: for random flat-foldable vertices (ties and cones included) the set the
// exact crimp test accepts equals Hull's enumeration, its size equals Hull's C, and every
// accepted assignment satisfies Maekawa and big-little-big.
Test(flat, property_exact_test_equals_enumeration_equals_count)
{
    const int max_n = 10;
    char *brute = malloc((size_t)(1 << max_n) * (max_n + 1));
    char *rows = malloc((size_t)(1 << max_n) * (max_n + 1));
    int tested_ties = 0;
    for (int trial = 0; trial < 6000; ++trial) {
        int n = 2 * rnd_int(1, max_n / 2);
        double rad[MAXN];
        bool ties = trial % 4 != 0;
        random_vertex(n, ties, rad);
        ori_mv_count c = ori_flat_count_assignments(rad, n);
        bool truncated = true;
        int k = ori_flat_enumerate(rad, n, rows, 1 << n, &truncated);
        int b = brute_force_valid(rad, n, brute);
        cr_assert(!truncated);
        cr_assert_eq((uint64_t)k, c.count, "trial %d n=%d: enumeration %d, C %llu", trial, n, k,
                     (unsigned long long)c.count);
        cr_assert_eq(b, k, "trial %d n=%d: exact test accepts %d, enumeration %d", trial, n, b, k);
        for (int i = 0; i < k; ++i) {
            cr_assert_str_eq(rows + i * (n + 1), brute + i * (n + 1), "trial %d row %d", trial, i);
            ori_assignment a[MAXN];
            parse_letters(rows + i * (n + 1), a);
            cr_assert(ori_flat_maekawa(a, n));
            cr_assert_eq(ori_flat_big_little_big(rad, a, n, NULL), ORI_NULL_INDEX);
        }
        // Equal sectors occur in most tie-heavy vertices; count them to be sure ties are tested.
        for (int i = 0; i < n; ++i)
            if (fabs(rad[i] - rad[(i + 1) % n]) <= ORI_TOL_ANGLE_EQUAL_RAD) {
                tested_ties++;
                break;
            }
    }
    cr_assert_gt(tested_ties, 3000);
    free(brute);
    free(rows);
}

Test(flat, property_completions_of_unassigned_creases)
{
    const int max_n = 10;
    char *brute = malloc((size_t)(1 << max_n) * (max_n + 1));
    char *rows = malloc((size_t)(1 << max_n) * (max_n + 1));
    for (int trial = 0; trial < 1500; ++trial) {
        int n = 2 * rnd_int(1, max_n / 2);
        double rad[MAXN];
        random_vertex(n, trial % 3 != 0, rad);
        int b = brute_force_valid(rad, n, brute);
        // A partial assignment: from a valid one half of the time, random otherwise.
        ori_assignment a[MAXN];
        const char *base = (b > 0 && rnd_int(0, 1)) ? brute + (size_t)rnd_int(0, b - 1) * (n + 1) : NULL;
        for (int i = 0; i < n; ++i) {
            if (rnd_int(0, 2) == 0) a[i] = ORI_ASSIGN_UNASSIGNED;
            else if (base) a[i] = base[i] == 'M' ? ORI_ASSIGN_MOUNTAIN : ORI_ASSIGN_VALLEY;
            else a[i] = rnd_int(0, 1) ? ORI_ASSIGN_MOUNTAIN : ORI_ASSIGN_VALLEY;
        }
        int expected = 0;
        char *match = malloc((size_t)(b ? b : 1) * (n + 1));
        for (int r = 0; r < b; ++r) {
            const char *row = brute + r * (n + 1);
            bool ok = true;
            for (int i = 0; i < n && ok; ++i)
                if (a[i] != ORI_ASSIGN_UNASSIGNED) ok = row[i] == ori_assignment_to_char(a[i]);
            if (ok) memcpy(match + (size_t)expected++ * (n + 1), row, (size_t)n + 1);
        }
        ori_mv_count c = ori_flat_count_completions(rad, a, n);
        cr_assert_eq(c.count, (uint64_t)expected, "trial %d", trial);
        bool truncated = true;
        int k = ori_flat_enumerate_completions(rad, a, n, rows, 1 << n, &truncated);
        cr_assert_eq(k, expected);
        cr_assert(!truncated);
        for (int i = 0; i < k; ++i) cr_assert_str_eq(rows + i * (n + 1), match + i * (n + 1));
        free(match);
    }
    free(brute);
    free(rows);
}

Test(flat, completions_all_unassigned_equal_count)
{
    for (int trial = 0; trial < 300; ++trial) {
        int n = 2 * rnd_int(1, 12);
        double rad[MAXN];
        random_vertex(n, true, rad);
        ori_assignment u[MAXN];
        for (int i = 0; i < n; ++i) u[i] = ORI_ASSIGN_UNASSIGNED;
        ori_mv_count a = ori_flat_count_completions(rad, u, n), c = ori_flat_count_assignments(rad, n);
        cr_assert_eq(a.count, c.count);
    }
}

// --- big-little-big ------------------------------------------------------------------------

Test(flat, big_little_big_strict_minimum_needs_opposite_creases)
{
    const double deg[] = {45, 112.5, 135, 67.5};
    double rad[4];
    to_rad(deg, 4, rad);
    ori_assignment a[4];
    int run = 0;
    parse_letters("MVVV", a);
    cr_assert_eq(ori_flat_big_little_big(rad, a, 4, &run), ORI_NULL_INDEX);
    cr_assert_eq(run, 0);
    parse_letters("VVMV", a); // 45° sector 0 lies between creases 0 and 1
    cr_assert_eq(ori_flat_big_little_big(rad, a, 4, &run), 0);
    cr_assert_eq(run, 2);
    parse_letters("VVMM", a); // BLB holds at the 45°; the assignment fails Maekawa only
    cr_assert_eq(ori_flat_big_little_big(rad, a, 4, NULL), 0);
    parse_letters("MVMM", a);
    cr_assert_eq(ori_flat_big_little_big(rad, a, 4, NULL), ORI_NULL_INDEX);
}

Test(flat, big_little_big_generalised_to_runs_of_equal_sectors)
{
    // Two equal 60° sectors (k = 1, creases 3, 0, 1): |#M − #V| = 1.
    const double deg[] = {60, 120, 120, 60};
    double rad[4];
    to_rad(deg, 4, rad);
    ori_assignment a[4];
    int run = 0;
    parse_letters("VVMV", a);
    cr_assert_eq(ori_flat_big_little_big(rad, a, 4, &run), 3); // run starts at sector 3 / crease 3
    cr_assert_eq(run, 3);
    parse_letters("VVVM", a);
    cr_assert_eq(ori_flat_big_little_big(rad, a, 4, NULL), ORI_NULL_INDEX);
    // Three equal 30° sectors (k = 2, creases 1..4): #M = #V.
    const double d6[] = {100, 30, 30, 30, 50, 120};
    double r6[6];
    to_rad(d6, 6, r6);
    ori_assignment b[6];
    parse_letters("MMMVVV", b); // creases 1..4 = M M V V: balanced
    cr_assert_eq(ori_flat_big_little_big(r6, b, 6, NULL), ORI_NULL_INDEX);
    parse_letters("MMVMVV", b); // creases 1..4 = M V M V: balanced
    cr_assert_eq(ori_flat_big_little_big(r6, b, 6, NULL), ORI_NULL_INDEX);
    parse_letters("MMMMVV", b); // creases 1..4 = M M M V: not balanced
    cr_assert_eq(ori_flat_big_little_big(r6, b, 6, &run), 1);
    cr_assert_eq(run, 4);
    // U creases: passes while some completion balances the run.
    parse_letters("MMMUUV", b);
    cr_assert_eq(ori_flat_big_little_big(r6, b, 6, NULL), ORI_NULL_INDEX);
    parse_letters("MMMMUV", b);
    cr_assert_eq(ori_flat_big_little_big(r6, b, 6, NULL), 1);
    // All equal: no run is smaller than its neighbours.
    double eq[8];
    equal_sectors(8, eq);
    ori_assignment c[8];
    parse_letters("MMMMMMMM", c);
    cr_assert_eq(ori_flat_big_little_big(eq, c, 8, NULL), ORI_NULL_INDEX);
}

Test(flat, kawasaki_and_maekawa)
{
    const double ok[] = {45, 112.5, 135, 67.5}, bad[] = {45, 112.5, 133.8369, 68.6631};
    double r[4];
    to_rad(ok, 4, r);
    cr_assert(ori_flat_kawasaki(r, 4));
    cr_assert_float_eq(ori_flat_kawasaki_sum(r, 4), 0.0, 1e-14);
    to_rad(bad, 4, r);
    cr_assert(!ori_flat_kawasaki(r, 4));
    cr_assert(ori_flat_kawasaki(NULL, 0));
    ori_assignment a[4];
    parse_letters("MMMV", a);
    cr_assert(ori_flat_maekawa(a, 4));
    parse_letters("MMVV", a);
    cr_assert(!ori_flat_maekawa(a, 4));
    cr_assert(ori_flat_maekawa(NULL, 0));
}

// --- patterns ------------------------------------------------------------------------------

static ori_vertex_report check_only_vertex(const ori_pattern *p, int *interior)
{
    ori_flat_report *rep = ori_flat_check_pattern(p, NULL);
    *interior = ori_flat_report_interior_count(rep);
    cr_assert_eq(ori_flat_report_vertex_count(rep), *interior);
    cr_assert_geq(*interior, 1);
    ori_vertex_report r = ori_flat_report_vertex(rep, 0);
    ori_flat_report_destroy(rep);
    return r;
}

static bool has_violation(const ori_flat_report *rep, int vertex, ori_flat_rule rule)
{
    for (int i = 0; i < ori_flat_report_violation_count(rep); ++i) {
        ori_flat_violation v = ori_flat_report_violation(rep, i);
        if (v.vertex == vertex && v.rule == rule) return true;
    }
    return false;
}

Test(flat, rabbit_ear_single_vertex_frames_get_their_verdicts)
{
    const char *path = test_require_shared("rabbit-ear/fold_invalid-single-vertex-2d.fold");
    // frame: kawasaki, maekawa, big-little-big, valid
    const bool want[5][4] = {
        {true, true, true, true},    // 0: valid
        {true, false, true, false},  // 1: breaks Maekawa
        {false, true, true, false},  // 2: breaks Kawasaki
        {false, false, true, false}, // 3: breaks both
        {true, true, false, false},  // 4: only big-little-big
    };
    for (int f = 0; f < 5; ++f) {
        ori_pattern *p = test_load_pattern(path, f);
        int interior;
        ori_vertex_report r = check_only_vertex(p, &interior);
        cr_assert_eq(interior, 1);
        cr_assert_eq(r.vertex, 5);
        cr_assert_eq(r.degree, 4, "the F crease (edge 5) is dropped");
        cr_assert(!r.cone);
        cr_assert_eq(r.kawasaki, want[f][0], "frame %d", f);
        cr_assert_eq(r.maekawa == ORI_FLAT_YES, want[f][1], "frame %d", f);
        cr_assert_eq(r.big_little_big, want[f][2], "frame %d", f);
        cr_assert_eq(r.assignment_valid, want[f][3], "frame %d", f);
        cr_assert_eq(r.flat_foldable, want[f][3], "frame %d", f);
        if (f == 2 || f == 3) cr_assert_float_eq(fabs(r.kawasaki_rad), 0.040601, 5e-7);
        else cr_assert_eq(r.mv_count.count, 4);
        int edges[8];
        double sec[8];
        int n = ori_flat_vertex_creases(p, 5, edges, sec, 8);
        cr_assert_eq(n, 4);
        const int want_edges[] = {6, 4, 8, 7};
        for (int i = 0; i < 4; ++i) cr_assert_eq(edges[i], want_edges[i]);
        if (f != 2 && f != 3) {
            const double want_deg[] = {45, 112.5, 135, 67.5};
            for (int i = 0; i < 4; ++i) cr_assert_float_eq(sec[i], ori_deg_to_rad(want_deg[i]), 1e-12);
        }
        ori_pattern_destroy(p);
    }
}

Test(flat, flat_folder_traditional_models_are_locally_flat_foldable)
{
    const char *files[] = {"flat-folder/instagram_001_traditional_Sailboat.fold",
                           "flat-folder/instagram_002_traditional_Kabuto.fold",
                           "flat-folder/instagram_004_traditional_Crane.fold"};
    const int interior[] = {9, 3, 48};
    for (int i = 0; i < 3; ++i) {
        ori_pattern *p = test_load_pattern(test_require_shared(files[i]), 0);
        ori_flat_report *rep = ori_flat_check_pattern(p, NULL);
        cr_assert(ori_flat_report_flat_foldable(rep), "%s", files[i]);
        cr_assert_eq(ori_flat_report_interior_count(rep), interior[i]);
        cr_assert_eq(ori_flat_report_violation_count(rep), 0);
        for (int k = 0; k < ori_flat_report_vertex_count(rep); ++k) {
            ori_vertex_report r = ori_flat_report_vertex(rep, k);
            cr_assert(r.kawasaki && r.maekawa == ORI_FLAT_YES && r.big_little_big && r.assignment_valid);
            cr_assert_geq(r.mv_count.count, (uint64_t)1 << (r.degree / 2));
        }
        ori_flat_report_destroy(rep);
        ori_pattern_destroy(p);
    }
}

Test(flat, other_flat_folder_patterns_are_locally_flat_foldable)
{
    const char *files[] = {"flat-folder/instagram_074_miuraoripa_Miura-ori.fold",
                           "flat-folder/instagram_082_traditionaloripa_4_Birdbase.fold",
                           "flat-folder/instagram_102_traditionaloripa_Pinwheel.fold",
                           "flat-folder/instagram_006_ku_Thirds_Pinwheel.fold",
                           "flat-folder/grids_001_brown_2x2_C1.fold", "flat-folder/grids_002_brown_2x2_D1.fold"};
    for (int i = 0; i < 6; ++i) {
        ori_pattern *p = test_load_pattern(test_require_shared(files[i]), 0);
        ori_flat_report *rep = ori_flat_check_pattern(p, NULL);
        cr_assert(ori_flat_report_flat_foldable(rep), "%s", files[i]);
        cr_assert_gt(ori_flat_report_interior_count(rep), 0);
        ori_flat_report_destroy(rep);
        ori_pattern_destroy(p);
    }
}

// The benchmark's Miura-ori (straight horizontal creases, vertical zigzags) with its assignment
// is valid at every vertex; flipping one crease breaks exactly its two end vertices.
Test(flat, generated_miura_ori_is_locally_flat_foldable)
{
    const int n = 12;
    ori_pattern_def def = ori_default_pattern_def();
    ori_pattern *p = ori_pattern_create(&def);
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) ori_pattern_add_vertex(p, ori_v3_make(i + (j % 2) * 0.3, j, 0));
    int flip = -1;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            int v = j * (n + 1) + i;
            if (i < n) {
                int zig = (j % 2 == 0) ? i + 1 : i;
                ori_assignment a = (j == 0 || j == n) ? ORI_ASSIGN_BOUNDARY
                                   : zig % 2 == 0     ? ORI_ASSIGN_MOUNTAIN
                                                      : ORI_ASSIGN_VALLEY;
                int e = ori_pattern_add_edge(p, v, v + 1, a, 0);
                if (i == 5 && j == 6) flip = e;
            }
            if (j < n)
                ori_pattern_add_edge(p, v, v + n + 1,
                                     (i == 0 || i == n) ? ORI_ASSIGN_BOUNDARY
                                     : i % 2 == 0       ? ORI_ASSIGN_MOUNTAIN
                                                        : ORI_ASSIGN_VALLEY,
                                     0);
        }
    cr_assert_eq(ori_pattern_build(p, NULL, NULL), ORI_OK);
    ori_flat_report *rep = ori_flat_check_pattern(p, NULL);
    cr_assert(ori_flat_report_flat_foldable(rep));
    cr_assert_eq(ori_flat_report_interior_count(rep), (n - 1) * (n - 1));
    ori_vertex_report r = ori_flat_report_vertex(rep, 0);
    cr_assert_eq(r.mv_count.count, 6); // θ, 180−θ, 180−θ, θ: binom(3, 1) · 2
    ori_flat_report_destroy(rep);
    ori_edge e = ori_pattern_edge(p, flip);
    ori_pattern_set_assignment(p, flip, e.assignment == ORI_ASSIGN_MOUNTAIN ? ORI_ASSIGN_VALLEY : ORI_ASSIGN_MOUNTAIN);
    rep = ori_flat_check_pattern(p, NULL);
    cr_assert_eq(ori_flat_report_failed_count(rep), 2);
    cr_assert(has_violation(rep, e.v[0], ORI_FLAT_RULE_MAEKAWA));
    cr_assert(has_violation(rep, e.v[1], ORI_FLAT_RULE_MAEKAWA));
    ori_flat_report_destroy(rep);
    ori_pattern_destroy(p);
}

Test(flat, tachi_not_foldable_fails_big_little_big)
{
    ori_pattern *p = test_load_pattern(test_require_shared("flat-folder/unsatisfiable_008_tachioripa_not_foldable.fold"), 0);
    ori_flat_report *rep = ori_flat_check_pattern(p, NULL);
    cr_assert(!ori_flat_report_flat_foldable(rep));
    ori_vertex_report r = ori_flat_report_vertex(rep, 0);
    cr_assert_eq(r.vertex, 3);
    cr_assert(r.kawasaki);
    cr_assert_eq(r.maekawa, ORI_FLAT_YES);
    cr_assert(!r.big_little_big);
    cr_assert(!r.assignment_valid);
    cr_assert(has_violation(rep, 3, ORI_FLAT_RULE_BIG_LITTLE_BIG));
    // The 45° sector lies between edges 11 and 9, both V; the violation points at edge 11.
    ori_flat_violation v = ori_flat_report_violation(rep, 0);
    cr_assert_eq(v.rule, ORI_FLAT_RULE_BIG_LITTLE_BIG);
    cr_assert_eq(v.edge, 11);
    cr_assert_float_eq(v.value, ori_deg_to_rad(45), 1e-9);
    ori_flat_report_destroy(rep);
    ori_pattern_destroy(p);
}

Test(flat, bad_twist_passes_every_local_rule)
{
    // Flat-Folder unsatisfiable_001: locally fine everywhere, globally unfoldable (no layer order).
    ori_pattern *p = test_load_pattern(test_require_shared("flat-folder/unsatisfiable_001_ku_Bad_Twist.fold"), 0);
    ori_flat_report *rep = ori_flat_check_pattern(p, NULL);
    cr_assert(ori_flat_report_flat_foldable(rep));
    ori_flat_report_destroy(rep);
    ori_pattern_destroy(p);
}

Test(flat, wavy_miura_fails_kawasaki)
{
    ori_pattern *p = test_load_pattern(test_require_shared("rabbit-ear/fold_wavy-miura-no-faces.fold"), 0);
    ori_flat_report *rep = ori_flat_check_pattern(p, NULL);
    cr_assert(!ori_flat_report_flat_foldable(rep));
    cr_assert_eq(ori_flat_report_interior_count(rep), 49);
    double worst = 0.0;
    int kawasaki_failures = 0;
    for (int k = 0; k < ori_flat_report_vertex_count(rep); ++k) {
        ori_vertex_report r = ori_flat_report_vertex(rep, k);
        cr_assert_eq(r.degree, 4);
        kawasaki_failures += !r.kawasaki;
        worst = fmax(worst, fabs(r.kawasaki_rad));
        if (!r.kawasaki) cr_assert(has_violation(rep, r.vertex, ORI_FLAT_RULE_KAWASAKI));
    }
    cr_assert_gt(kawasaki_failures, 0);
    // PROVENANCE: "max deviation 0.52 rad", measured as |sum of alternate sectors − π|, which
    // is half the alternating sum.
    cr_assert_float_eq(worst / 2, 0.524, 0.001);
    ori_flat_report_destroy(rep);
    ori_pattern_destroy(p);
}

Test(flat, rabbit_ear_crane_passes_kawasaki_and_maekawa_everywhere)
{
    ori_pattern *p = test_load_pattern(test_require_shared("rabbit-ear/fold_crane-cp.fold"), 0);
    ori_flat_report *rep = ori_flat_check_pattern(p, NULL);
    cr_assert_eq(ori_flat_report_interior_count(rep), 44);
    for (int k = 0; k < ori_flat_report_vertex_count(rep); ++k) {
        ori_vertex_report r = ori_flat_report_vertex(rep, k);
        cr_assert(r.kawasaki);
        cr_assert_eq(r.maekawa, ORI_FLAT_YES);
    }
    ori_flat_report_destroy(rep);
    ori_pattern_destroy(p);
}

// Every .fold under the shared patterns, every frame: loads and checks without error; the JSON
// of `orikin check` parses, has the contract's fields and agrees with the exit code.
Test(flat, check_runs_on_every_shared_fold_file_and_frame)
{
    test_require_shared("PROVENANCE.md");
    const char *dirs[] = {"flat-folder", "fold-spec", "rabbit-ear", "origamisimulator", "oripa"};
    int files = 0, frames_checked = 0;
    for (int d = 0; d < 5; ++d) {
        char dir[4096];
        snprintf(dir, sizeof dir, "%s/%s", ORI_SHARED_PATTERNS, dirs[d]);
        DIR *h = opendir(dir);
        if (!h) continue;
        struct dirent *ent;
        while ((ent = readdir(h))) {
            size_t len = strlen(ent->d_name);
            if (len < 6 || strcmp(ent->d_name + len - 5, ".fold") != 0) continue;
            char path[8192];
            snprintf(path, sizeof path, "%s/%s", dir, ent->d_name);
            files++;
            ori_fold *doc = NULL;
            ori_error err;
            cr_assert_eq(ori_fold_load_file(path, &doc, &err), ORI_OK, "%s", path);
            int frames = ori_fold_frame_count(doc);
            ori_fold_destroy(doc);
            for (int f = 0; f < frames; ++f) {
                ori_pattern *p = test_load_pattern(path, f);
                ori_flat_report *rep = ori_flat_check_pattern(p, NULL);
                bool ok = ori_flat_report_flat_foldable(rep);
                int interior = ori_flat_report_interior_count(rep);
                ori_flat_report_destroy(rep);
                ori_pattern_destroy(p);
                char args[9000], *out = NULL, *errtext = NULL;
                snprintf(args, sizeof args, "check '%s' --frame %d --json", path, f);
                int code = test_run_cli_split(args, &out, &errtext);
                cr_assert(code == 0 || code == 1, "%s frame %d: exit %d: %s", path, f, code, errtext);
                cr_assert_eq(code, ok ? 0 : 1);
                json_error_t je;
                json_t *root = json_loads(out, 0, &je);
                cr_assert_not_null(root, "%s frame %d: %s", path, f, je.text);
                cr_assert(json_is_string(json_object_get(root, "file")));
                cr_assert_eq(json_is_true(json_object_get(root, "locally_flat_foldable")), ok);
                cr_assert_eq(json_integer_value(json_object_get(root, "interior_vertices")), interior);
                json_t *vs = json_object_get(root, "vertices");
                cr_assert_eq((int)json_array_size(vs), interior);
                size_t i;
                json_t *v;
                json_array_foreach(vs, i, v)
                {
                    const char *keys[] = {"vertex", "degree", "sectors_deg", "kawasaki", "maekawa",
                                          "big_little_big", "mv_count", "assignment_valid"};
                    for (int k = 0; k < 8; ++k) cr_assert_not_null(json_object_get(v, keys[k]), "%s", keys[k]);
                    cr_assert_eq(json_array_size(json_object_get(v, "sectors_deg")),
                                 (size_t)json_integer_value(json_object_get(v, "degree")));
                }
                cr_assert(json_is_array(json_object_get(root, "violations")));
                cr_assert_eq(json_array_size(json_object_get(root, "violations")) == 0, ok);
                json_decref(root);
                free(out);
                free(errtext);
                frames_checked++;
            }
        }
        closedir(h);
    }
    cr_assert_geq(files, 30);
    cr_assert_geq(frames_checked, 45);
}

Test(flat, example_patterns)
{
    int interior;
    ori_pattern *p = test_load_pattern(test_repo_path("examples/patterns/degree4-vertex.fold"), 0);
    ori_vertex_report r = check_only_vertex(p, &interior);
    cr_assert(r.flat_foldable && r.kawasaki && r.maekawa == ORI_FLAT_YES && r.big_little_big);
    cr_assert_eq(r.mv_count.count, 6);
    ori_pattern_destroy(p);

    p = test_load_pattern(test_repo_path("examples/patterns/degree6-vertex.fold"), 0);
    r = check_only_vertex(p, &interior);
    cr_assert(r.flat_foldable);
    cr_assert_eq(r.degree, 6);
    cr_assert_eq(r.mv_count.count, 30);
    ori_pattern_destroy(p);

    p = test_load_pattern(test_repo_path("examples/patterns/non-flat-foldable-vertex.fold"), 0);
    r = check_only_vertex(p, &interior);
    cr_assert(!r.kawasaki);
    cr_assert(!r.flat_foldable);
    cr_assert_float_eq(r.kawasaki_rad, ori_deg_to_rad(-40), 1e-12);
    cr_assert_eq(r.mv_count.count, 0);
    ori_pattern_destroy(p);

    // The open corner: five creases (odd) around (1, 1) — a 3D corner, never flat.
    p = test_load_pattern(test_repo_path("examples/patterns/open-corner.fold"), 0);
    r = check_only_vertex(p, &interior);
    cr_assert_eq(interior, 1);
    cr_assert_eq(r.vertex, test_vertex_at(p, 1, 1));
    cr_assert_eq(r.degree, 5);
    cr_assert(!r.kawasaki);
    cr_assert(!r.cone);
    cr_assert_float_eq(r.sector_sum_rad, 2 * ORI_PI, 1e-12);
    cr_assert(!r.flat_foldable);
    cr_assert_eq(r.mv_count.count, 0);
    ori_pattern_destroy(p);
}

// A square sheet [-1, 1]² with creases from the centre: 4 letters → to the edge midpoints,
// 8 letters → to the midpoints and corners; letters counter-clockwise from +x.
static ori_pattern *star_pattern(const char *letters)
{
    int n = (int)strlen(letters);
    ori_pattern_def def = ori_default_pattern_def();
    ori_pattern *p = ori_pattern_create(&def);
    int c = ori_pattern_add_vertex(p, ori_v3_make(0, 0, 0));
    int ring[8];
    for (int i = 0; i < 8; ++i) {
        static const double xy[8][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
        ring[i] = ori_pattern_add_vertex(p, ori_v3_make(xy[i][0], xy[i][1], 0));
    }
    for (int i = 0; i < 8; ++i) ori_pattern_add_edge(p, ring[i], ring[(i + 1) % 8], ORI_ASSIGN_BOUNDARY, 0);
    for (int i = 0; i < n; ++i) {
        ori_assignment a;
        cr_assert(ori_assignment_from_char(letters[i], &a));
        int target = n == 4 ? ring[2 * i] : ring[i];
        ori_pattern_add_edge(p, c, target, a, 0);
    }
    cr_assert_eq(ori_pattern_build(p, NULL, NULL), ORI_OK);
    return p;
}

Test(flat, unassigned_creases_report_completions)
{
    ori_pattern *p = star_pattern("MUUU");
    ori_vertex_report r;
    ori_flat_check_vertex(p, 0, &r);
    cr_assert_eq(r.degree, 4);
    cr_assert_eq(r.unassigned, 3);
    cr_assert_eq(r.maekawa, ORI_FLAT_UNDETERMINED);
    cr_assert_eq(r.completions.count, 4); // MMMV MMVM MVMM MVVV
    cr_assert(r.assignment_valid && r.flat_foldable);
    ori_pattern_destroy(p);

    p = star_pattern("MMMU"); // only V completes it
    ori_flat_check_vertex(p, 0, &r);
    cr_assert_eq(r.completions.count, 1);
    ori_pattern_destroy(p);

    p = star_pattern("MVMU"); // equal sectors: only Maekawa counts, so MVMM and not MVMV
    ori_flat_check_vertex(p, 0, &r);
    cr_assert_eq(r.completions.count, 1);
    ori_pattern_destroy(p);

    p = star_pattern("MMUFMMFV"); // 8 spokes, F dropped: 6 creases at 0,45,90,180,225,315 deg
    ori_flat_check_vertex(p, 0, &r);
    cr_assert_eq(r.degree, 6);
    cr_assert_eq(r.unassigned, 1);
    ori_flat_report *rep = ori_flat_check_pattern(p, NULL);
    cr_assert_eq(ori_flat_report_interior_count(rep), 1);
    int edges[8];
    double sec[8];
    cr_assert_eq(ori_flat_report_vertex_creases(rep, 0, edges, sec, 8), 6);
    const double want[] = {45, 45, 90, 45, 90, 45};
    for (int i = 0; i < 6; ++i) cr_assert_float_eq(sec[i], ori_deg_to_rad(want[i]), 1e-12);
    double sum = 0;
    for (int i = 0; i < 6; ++i) sum += sec[i];
    cr_assert_float_eq(sum, 2 * ORI_PI, 1e-12);
    ori_flat_report_destroy(rep);
    ori_pattern_destroy(p);
}

Test(flat, join_and_flat_edges_are_merged_and_no_creases_is_flat)
{
    ori_pattern *p = star_pattern("FJFJ");
    ori_vertex_report r;
    ori_flat_check_vertex(p, 0, &r);
    cr_assert_eq(r.degree, 0);
    cr_assert(r.kawasaki && r.maekawa == ORI_FLAT_YES && r.flat_foldable);
    cr_assert_eq(r.mv_count.count, 1);
    cr_assert_float_eq(r.sector_sum_rad, 2 * ORI_PI, 1e-12);
    ori_pattern_destroy(p);

    p = star_pattern("VJVF"); // a straight valley line through the vertex
    ori_flat_check_vertex(p, 0, &r);
    cr_assert_eq(r.degree, 2);
    cr_assert(r.flat_foldable);
    cr_assert_eq(r.mv_count.count, 2);
    ori_pattern_destroy(p);
}

Test(flat, folded_pyramid_apex_is_a_cone)
{
    ori_pattern_def def = ori_default_pattern_def();
    ori_pattern *p = ori_pattern_create(&def);
    int apex = ori_pattern_add_vertex(p, ori_v3_make(0, 0, 1));
    int b[4];
    for (int i = 0; i < 4; ++i) b[i] = ori_pattern_add_vertex(p, ori_v3_make(i == 0 || i == 3 ? 1 : -1, i < 2 ? 1 : -1, 0));
    for (int i = 0; i < 4; ++i) ori_pattern_add_edge(p, b[i], b[(i + 1) % 4], ORI_ASSIGN_BOUNDARY, 0);
    for (int i = 0; i < 4; ++i) ori_pattern_add_edge(p, apex, b[i], i % 2 ? ORI_ASSIGN_MOUNTAIN : ORI_ASSIGN_VALLEY, 0);
    for (int i = 0; i < 4; ++i) {
        int f[3] = {apex, b[i], b[(i + 1) % 4]};
        ori_pattern_add_face(p, f, 3);
    }
    ori_pattern_set_folded_form(p, true);
    cr_assert_eq(ori_pattern_build(p, NULL, NULL), ORI_OK);
    ori_flat_report *rep = ori_flat_check_pattern(p, NULL);
    cr_assert_eq(ori_flat_report_interior_count(rep), 1);
    ori_vertex_report r = ori_flat_report_vertex(rep, 0);
    cr_assert(r.cone);
    // four face corners of acos(1/3)… each: angle between (1,1,−1) and (−1,1,−1) = acos(1/3)
    cr_assert_float_eq(r.sector_sum_rad, 4 * acos(1.0 / 3.0), 1e-12);
    cr_assert(r.kawasaki); // equal corners: alternating sum 0 (a flat-foldable cone)
    cr_assert(!r.flat_foldable);
    cr_assert(has_violation(rep, apex, ORI_FLAT_RULE_CONE));
    ori_flat_report_destroy(rep);
    ori_pattern_destroy(p);
}

Test(flat, report_without_vertex_records_keeps_counts_and_violations)
{
    ori_pattern *p = test_load_pattern(test_repo_path("examples/patterns/non-flat-foldable-vertex.fold"), 0);
    ori_flat_check_def def = ori_default_flat_check_def();
    def.record_vertices = false;
    ori_flat_report *rep = ori_flat_check_pattern(p, &def);
    cr_assert_eq(ori_flat_report_vertex_count(rep), 0);
    cr_assert_eq(ori_flat_report_interior_count(rep), 1);
    cr_assert_eq(ori_flat_report_failed_count(rep), 1);
    cr_assert(has_violation(rep, 0, ORI_FLAT_RULE_KAWASAKI));
    cr_assert_str_eq(ori_flat_rule_name(ORI_FLAT_RULE_BIG_LITTLE_BIG), "big_little_big");
    ori_flat_report_destroy(rep);
    ori_pattern_destroy(p);
}

// --- CLI: bad input ------------------------------------------------------------------------

Test(flat, cli_check_bad_input_names_file_and_index_and_writes_nothing)
{
    struct {
        const char *file, *where;
    } cases[] = {
        {"tests/data/bad-json.fold", "line 4, column 37: "},
        {"tests/data/bad-type.fold", "edges_vertices 2: expected [vertex, vertex]"},
        {"tests/data/bad-assignment-type.fold", "edges_assignment 4: expected one of"},
        {"tests/data/bad-index.fold", "edges_vertices 3: vertex index 9 out of range (4 vertices)"},
        {"tests/data/bad-zero-length.fold", "edges_vertices 5: zero-length edge (vertices 1 and 4)"},
        {"tests/data/bad-coincident.fold", "vertices_coords 4: vertex coincides with vertex 2"},
        {"tests/data/bad-crossing-extra-field.fold", "edges_vertices 4: edge 4 intersects edge 5 away from a shared vertex (planarising"},
        {"tests/data/bad-overlap-mv.fold", "edges_assignment: overlapping creases disagree on (0, 0)-(0.5, 0.5): valley and mountain"},
        {"tests/data/bad-face-side.fold", "faces_vertices 1: side 3-1 of the face is not an edge"},
        {"tests/data/bad-fold-angle.fold", "edges_foldAngle 4: fold angle 200 is outside [-180, 180] degrees"},
        {"tests/data/no-such-file.fold", "tests/data/no-such-file.fold: "},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        char args[512], *out = NULL, *err = NULL;
        for (int json = 0; json < 2; ++json) {
            snprintf(args, sizeof args, "check %s%s", cases[i].file, json ? " --json" : "");
            int code = test_run_cli_split(args, &out, &err);
            cr_assert_eq(code, 3, "%s: exit %d", cases[i].file, code);
            cr_assert_str_eq(out, "", "%s: stdout not empty", cases[i].file);
            char prefix[256];
            snprintf(prefix, sizeof prefix, "orikin check: %s: ", cases[i].file);
            cr_assert_eq(strncmp(err, prefix, strlen(prefix)), 0, "%s: %s", cases[i].file, err);
            cr_assert_not_null(strstr(err, cases[i].where), "%s: %s", cases[i].file, err);
            size_t len = strlen(err);
            cr_assert(len > 0 && err[len - 1] == '\n' && strchr(err, '\n') == err + len - 1, "one line: %s", err);
            free(out);
            free(err);
        }
    }
}

Test(flat, cli_check_weld_merges_coincident_vertices)
{
    char *out = NULL;
    int code = test_run_cli("check tests/data/bad-coincident.fold --weld", &out);
    cr_assert(code == 0 || code == 1, "exit %d: %s", code, out);
    free(out);
}

Test(flat, cli_mv_count_bad_input)
{
    struct {
        const char *args;
        int code;
        const char *msg;
    } cases[] = {
        {"mv-count 90 90 90", 3, "orikin mv-count: 3 sector angles: a flat vertex has an even number of creases"},
        {"mv-count 90 90 90 100", 3, "orikin mv-count: sector angles sum to 370 degrees, not 360"},
        {"mv-count 0 180 90 90", 3, "orikin mv-count: sector 1: 0 degrees; every sector angle must be > 0"},
        {"mv-count -- -10 190 90 90", 2, "unknown option --"},
        {"mv-count 200 -20 90 90", 3, "orikin mv-count: sector 2: -20 degrees"},
        {"mv-count 90 ninety 90 90", 2, "'ninety' is not a number"},
        {"mv-count", 2, "missing sector angles"},
        {"mv-count 90 90 90 90 --assign MMX", 2, "--assign needs one letter per crease"},
        {"mv-count 90 90 90 90 --assign MMXV", 2, "--assign letters must be M, V or U"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        char *out = NULL, *err = NULL;
        int code = test_run_cli_split(cases[i].args, &out, &err);
        cr_assert_eq(code, cases[i].code, "%s: exit %d", cases[i].args, code);
        cr_assert_str_eq(out, "", "%s: stdout %s", cases[i].args, out);
        cr_assert_not_null(strstr(err, cases[i].msg), "%s: %s", cases[i].args, err);
        free(out);
        free(err);
    }
}

Test(flat, cli_mv_count_json_lists_every_valid_assignment)
{
    char *out = NULL;
    cr_assert_eq(test_run_cli("mv-count 100 70 50 40 30 70 --json", &out), 0);
    json_t *root = json_loads(out, 0, NULL);
    cr_assert_not_null(root, "%s", out);
    cr_assert_eq(json_integer_value(json_object_get(root, "count")), 8);
    json_t *list = json_object_get(root, "assignments");
    cr_assert_eq(json_array_size(list), 8);
    const double deg[] = {100, 70, 50, 40, 30, 70};
    for (size_t i = 0; i < 8; ++i) cr_assert(valid_deg(deg, json_string_value(json_array_get(list, i))));
    json_decref(root);
    free(out);
}
