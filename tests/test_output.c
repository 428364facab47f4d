// Output speed path: the writers' shortest number format (src/io/text.c over double-conversion)
// against its printf definition, on random bit patterns and on the awkward cases.
#define _POSIX_C_SOURCE 200809L
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/io_internal.h"
#include "support.h"

// The definition: the first of %.15g, %.16g, %.17g that reads back as x; 0 for ±0.
static void reference(double x, char *buf, size_t size)
{
    if (x == 0.0) {
        snprintf(buf, size, "0");
        return;
    }
    for (int prec = 15; prec <= 17; ++prec) {
        snprintf(buf, size, "%.*g", prec, x);
        if (strtod(buf, NULL) == x) break;
    }
}

static void same(double x)
{
    char a[40], b[40];
    ori__format_double(x, a, sizeof a);
    reference(x, b, sizeof b);
    cr_assert_str_eq(a, b, "%a: %s vs printf %s", x, a, b);
    cr_assert(strtod(a, NULL) == x || isnan(x));
}

static uint64_t next(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return *s;
}

Test(output, shortest_format_matches_printf_on_random_doubles)
{
    uint64_t s = 0x9E3779B97F4A7C15ULL;
    for (int i = 0; i < 200000; ++i) {
        uint64_t bits = next(&s);
        double x;
        memcpy(&x, &bits, sizeof x);
        if (isnan(x)) continue;
        same(x);
    }
    // Values as the writers see them: angles in degrees and coordinates with few digits.
    for (int i = 0; i < 200000; ++i) {
        double u = (double)(next(&s) >> 11) * 0x1.0p-53;
        same(360.0 * u - 180.0);
        same(u * 1e3);
        same(round(u * 1e6) / 1e3);
    }
}

Test(output, shortest_format_edge_cases)
{
    double xs[] = {1.0, -1.0, 0.1, 0.3, 1e-4, 1e-5, 1.5e-5, 123456789012345.0, 1234567890123456.0,
                   12345678901234567.0, 1e15, 1e16, 1e17, 1e21, 1e22, 1e100, 1e-100, 1e300, -1e-300, DBL_MAX,
                   -DBL_MAX, DBL_MIN, 5e-324, 1e-310, -2.5e-320, 180.0, -180.00000000286695, 0.5, 2.0 / 3.0,
                   9007199254740993.0, 4.35, 0x1p-44, 0x1p-60, 0x1p70, -0x1p-1000, 100.0, 1e14, 99999999999999.99, 0.000123};
    for (size_t i = 0; i < sizeof xs / sizeof xs[0]; ++i) same(xs[i]);
    char a[40];
    ori__format_double(-0.0, a, sizeof a);
    cr_assert_str_eq(a, "0");
    ori__format_double(INFINITY, a, sizeof a);
    cr_assert_str_eq(a, "inf");
}

// A fold that would write more than 1 GB asks for --force before solving anything (usage
// error, exit 2, naming the option): a 100 × 100 Miura-ori in 1 802 frames of 30 603
// coordinates and 20 200 angles.
Test(output, fold_over_a_gigabyte_asks_for_force)
{
    char *dir = test_tmpdir();
    char args[4300];
    snprintf(args, sizeof args, "generate miura --rows 100 --cols 100 -o '%s/m.fold'", dir);
    cr_assert_eq(test_run_cli(args, NULL), 0);
    char *out = NULL, *err = NULL;
    snprintf(args, sizeof args, "fold '%s/m.fold' --fix 0 --drive 100 --to 90 --step 0.05 -o '%s/o.fold'", dir, dir);
    cr_assert_eq(test_run_cli_split(args, &out, &err), 2, "%s", err);
    cr_assert(strstr(err, "about 1.8 GB (more than 1 GB): add --force"), "%s", err);
    snprintf(args, sizeof args, "%s/o.fold", dir);
    cr_assert_null(test_read_text(args));
    free(out);
    free(err);
    test_tmpdir_remove(dir);
}
