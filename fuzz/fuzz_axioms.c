// libFuzzer target for the Huzita–Justin axioms (include/orikin/axioms.h): ori_axiom_1 … 7,
// ori_axiom_solve, ori_line_make, ori_line_reflect, ori_axiom_max_solutions. Input: byte 0 picks
// the axiom (1…7, others too), then ten values (p1, p2, l1 point and direction, l2 point and
// direction), each one kind byte: a small integer grid value (coincident points, parallel and
// axis-aligned lines come often), a hostile constant (0, ±inf, NaN, 1e300, 1e-300, 1e154) or
// the next eight bytes as a raw double. Invariants (abort on violation): ori_axiom_solve agrees
// with ori_axiom_<n>; count ≤ ori_axiom_max_solutions; every line finite and canonical (unit
// dir with dir.x > 0 or dir = (0, 1), point nearest the origin); reflecting twice is the
// identity; and, for finite inputs of moderate scale S (largest input magnitude), each axiom's
// defining property checked here to a tolerance scaled by S: 1 passes through p1 and p2; 2
// reflects p1 onto p2; 3 reflects l1 onto l2; 4 passes through p1 perpendicular to l1; 5 passes
// through p2 and reflects p1 onto l1; 6 reflects p1 onto l1 and p2 onto l2; 7 reflects p1 onto
// l1 and is perpendicular to l2. Any crash, leak or sanitizer report is a bug.
#include <orikin/orikin.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static double take(const uint8_t **d, size_t *n)
{
    if (*n == 0) return 0.0;
    uint8_t k = **d;
    (*d)++, (*n)--;
    switch (k >> 5) {
    case 0: case 1: case 2: case 3: return (double)((int)(k & 0x7f) - 64) / 8.0; // grid
    case 4: return (double)((int)(k & 31) - 16);
    case 5: {
        static const double special[8] = {0.0, INFINITY, -INFINITY, NAN, 1e300, 1e-300, 1e154, -1e-7};
        return special[k & 7];
    }
    default: {
        double v = 0.0;
        if (*n >= 8) {
            memcpy(&v, *d, 8);
            *d += 8, *n -= 8;
        }
        return v;
    }
    }
}

static double dot(ori_v2 a, ori_v2 b) { return a.x * b.x + a.y * b.y; }
static double cross(ori_v2 a, ori_v2 b) { return a.x * b.y - a.y * b.x; }
static ori_v2 sub(ori_v2 a, ori_v2 b) { return (ori_v2){a.x - b.x, a.y - b.y}; }

// Distance of x from line (dir any nonzero length).
static double dist(ori_line l, ori_v2 x)
{
    double len = hypot(l.dir.x, l.dir.y);
    return fabs(cross(l.dir, sub(x, l.point))) / len;
}

// scale: the input magnitude (the nearest point is rounded relative to it)
static void check_canonical(ori_line l, double scale)
{
    if (!isfinite(l.point.x) || !isfinite(l.point.y) || !isfinite(l.dir.x) || !isfinite(l.dir.y)) abort();
    if (fabs(hypot(l.dir.x, l.dir.y) - 1.0) > 1e-12) abort();
    if (!(l.dir.x > 0.0 || (l.dir.x == 0.0 && l.dir.y > 0.0))) abort(); // (vertical: up, |dir| = 1 to rounding)
    double r = hypot(l.point.x, l.point.y);
    if (fabs(dot(l.point, l.dir)) > 1e-9 * fmax(fmax(r, scale), 1e-300)) {
        if (getenv("FUZZ_DEBUG")) fprintf(stderr, "line %.17g %.17g dir %.17g %.17g\n", l.point.x, l.point.y, l.dir.x, l.dir.y);
        abort();
    }
}

static double mag(ori_v2 v) { return fmax(fabs(v.x), fabs(v.y)); }
// Unit vector of a finite nonzero v, scaled by its largest component first so that neither a
// huge (1e307) nor a subnormal direction overflows or loses its digits; (0, 0) otherwise.
static ori_v2 unit(ori_v2 v)
{
    double m = mag(v);
    if (!(m > 0.0) || !isfinite(m)) return (ori_v2){0.0, 0.0};
    ori_v2 w = {v.x / m, v.y / m};
    double len = hypot(w.x, w.y);
    return (ori_v2){w.x / len, w.y / len};
}
// Largest finite coordinate magnitude (non-finite ones ignored).
static double fin(ori_v2 v) { return fmax(isfinite(v.x) ? fabs(v.x) : 0.0, isfinite(v.y) ? fabs(v.y) : 0.0); }

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0) return 0;
    int axiom = (int)(data[0] % 9); // 0 and 8 are out of range
    data++, size--;
    ori_axiom_input in;
    memset(&in, 0, sizeof in);
    in.axiom = axiom;
    in.p1.x = take(&data, &size), in.p1.y = take(&data, &size);
    in.p2.x = take(&data, &size), in.p2.y = take(&data, &size);
    in.l1.point.x = take(&data, &size), in.l1.point.y = take(&data, &size);
    in.l1.dir.x = take(&data, &size), in.l1.dir.y = take(&data, &size);
    in.l2.point.x = take(&data, &size), in.l2.point.y = take(&data, &size);
    in.l2.dir.x = take(&data, &size), in.l2.dir.y = take(&data, &size);

    ori_line_set s = ori_axiom_solve(&in), d;
    switch (axiom) {
    case 1: d = ori_axiom_1(in.p1, in.p2); break;
    case 2: d = ori_axiom_2(in.p1, in.p2); break;
    case 3: d = ori_axiom_3(in.l1, in.l2); break;
    case 4: d = ori_axiom_4(in.p1, in.l1); break;
    case 5: d = ori_axiom_5(in.p1, in.p2, in.l1); break;
    case 6: d = ori_axiom_6(in.p1, in.l1, in.p2, in.l2); break;
    case 7: d = ori_axiom_7(in.p1, in.l1, in.l2); break;
    default: d.count = 0; break;
    }
    if (s.count != d.count) abort();
    if (s.count < 0 || s.count > ori_axiom_max_solutions(axiom)) abort();
    if (ori_axiom_max_solutions(axiom) > 3) abort();
    for (int i = 0; i < s.count; i++)
        if (memcmp(&s.lines[i], &d.lines[i], sizeof(ori_line)) != 0) abort();

    // ori_line_make on the fuzzed l1: canonical, or the zero line for a zero/non-finite dir.
    ori_line m = ori_line_make(in.l1.point, in.l1.dir);
    bool finite_in = isfinite(in.l1.point.x) && isfinite(in.l1.point.y) && isfinite(in.l1.dir.x) &&
                     isfinite(in.l1.dir.y);
    bool zero = m.point.x == 0 && m.point.y == 0 && m.dir.x == 0 && m.dir.y == 0;
    if (finite_in && mag(in.l1.point) < 1e150 && !zero) check_canonical(m, mag(in.l1.point));

    double S = fmax(fmax(mag(in.p1), mag(in.p2)), fmax(mag(in.l1.point), mag(in.l2.point)));
    bool all_finite = isfinite(S) && isfinite(mag(in.l1.dir)) && isfinite(mag(in.l2.dir));
    // property checks: finite inputs of moderate scale with well-defined input directions
    double len1 = hypot(in.l1.dir.x, in.l1.dir.y), len2 = hypot(in.l2.dir.x, in.l2.dir.y);
    bool checkable = all_finite && S < 1e100 && S > 1e-100 && len1 > 1e-100 && len1 < 1e100 &&
                     len2 > 1e-100 && len2 < 1e100;
    double tol = 1e-6 * (S > 0 ? S : 1.0);
    for (int i = 0; i < s.count; i++) {
        ori_line l = s.lines[i];
        double sc = fmax(fmax(fin(in.p1), fin(in.p2)), fmax(fin(in.l1.point), fin(in.l2.point)));
        // axiom 3's bisectors pass through the crossing, |q| / |sin angle| away: rounded there
        if (axiom == 3) {
            double sn = fabs(cross(unit(in.l1.dir), unit(in.l2.dir)));
            if (sn > 0.0 && isfinite(sn)) sc = fmax(sc, 4.0 * sc / sn);
        }
        // A crossing beyond 1e15 (nearly parallel lines far apart): the line is only checked
        // finite and unit (its nearest point is then rounded at a scale past any sheet).
        if (axiom == 3 && !(sc <= 1e15)) {
            if (!isfinite(l.point.x) || !isfinite(l.point.y) || fabs(hypot(l.dir.x, l.dir.y) - 1.0) > 1e-12) abort();
            continue;
        }
        check_canonical(l, sc);
        if (!checkable) continue;
        // (reflected across a line whose nearest point is |q| away, p1 is rounded at that scale)
        double tol_back = fmax(tol, 1e-12 * mag(l.point));
        ori_v2 back = ori_line_reflect(l, ori_line_reflect(l, in.p1));
        if (mag(sub(back, in.p1)) > tol_back) abort();
        ori_v2 u1 = {in.l1.dir.x / len1, in.l1.dir.y / len1}, u2 = {in.l2.dir.x / len2, in.l2.dir.y / len2};
        switch (axiom) {
        case 1:
            if (dist(l, in.p1) > tol || dist(l, in.p2) > tol) abort();
            break;
        case 2:
            if (mag(sub(ori_line_reflect(l, in.p1), in.p2)) > tol) abort();
            break;
        case 3: {
            // (the fold line is fixed by the crossing, sc away: its direction's rounding turns it
            // about there, moving it by up to ~1e-16 sc here; the canonical check's allowance)
            double tol3 = fmax(tol, 1e-9 * sc);
            ori_v2 a = in.l1.point, b = {in.l1.point.x + S * u1.x, in.l1.point.y + S * u1.y};
            if (dist(in.l2, ori_line_reflect(l, a)) > tol3 || dist(in.l2, ori_line_reflect(l, b)) > tol3) {
                if (getenv("FUZZ_DEBUG"))
                    fprintf(stderr, "l1 %.17g %.17g %.17g %.17g l2 %.17g %.17g %.17g %.17g -> %.17g %.17g %.17g %.17g\n", in.l1.point.x, in.l1.point.y,
                            in.l1.dir.x, in.l1.dir.y, in.l2.point.x, in.l2.point.y, in.l2.dir.x, in.l2.dir.y,
                            l.point.x, l.point.y, l.dir.x, l.dir.y);
                abort();
            }
            break;
        }
        case 4:
            if (dist(l, in.p1) > tol || fabs(dot(l.dir, u1)) > 1e-6) abort();
            break;
        case 5:
            if (dist(l, in.p2) > tol || dist(in.l1, ori_line_reflect(l, in.p1)) > tol_back) abort();
            break;
        case 6: {
            // (Beloch's cubic; a root far out, the fold |q| ≫ S away where l1 and l2 are nearly
            // parallel, is checked relative to that distance: such a line misses any sheet)
            double tol6 = 1e-4 * fmax(S, mag(l.point));
            if (dist(in.l1, ori_line_reflect(l, in.p1)) > tol6 || dist(in.l2, ori_line_reflect(l, in.p2)) > tol6) {
                if (getenv("FUZZ_DEBUG"))
                    fprintf(stderr, "axiom 6 line %.17g %.17g dir %.17g %.17g: errors %g %g (S %g)\n", l.point.x, l.point.y,
                            l.dir.x, l.dir.y, dist(in.l1, ori_line_reflect(l, in.p1)), dist(in.l2, ori_line_reflect(l, in.p2)), S);
                abort();
            }
            break;
        }
        case 7:
            // (the fold is perpendicular to l2 through a point |q| away: p1's image is rounded at
            // that scale, far beyond S when l1 and l2 are nearly parallel)
            if (dist(in.l1, ori_line_reflect(l, in.p1)) > tol_back || fabs(dot(l.dir, u2)) > 1e-6) abort();
            break;
        default: abort(); // no solutions outside 1…7
        }
    }
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
