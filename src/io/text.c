// The writers' text buffer (FOLD text, JSON, SVG, CP, OPX): appends, printf, JSON strings, and
// numbers in their shortest exact form. Allocated with ori__alloc; the caller owns data.
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "io_internal.h"

void ori__text_reserve(ori__text *t, size_t extra)
{
    if (t->len + extra + 1 <= t->cap) return;
    size_t cap = t->cap ? t->cap : 4096;
    while (cap < t->len + extra + 1) cap *= 2;
    t->data = ori__realloc(t->data, cap);
    t->cap = cap;
    t->data[t->len] = '\0'; // terminated even when nothing is ever appended
}

void ori__text_printf(ori__text *t, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    va_list again;
    va_copy(again, ap);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (n > 0) {
        ori__text_reserve(t, (size_t)n);
        vsnprintf(t->data + t->len, (size_t)n + 1, fmt, again);
        t->len += (size_t)n;
    } else {
        ori__text_reserve(t, 0);
    }
    va_end(again);
}

// Two decimal digits at a time ("00" … "99").
static const char digit_pairs[201] = "0001020304050607080910111213141516171819202122232425262728293031323334353637383940414243444546474849"
                                     "5051525354555657585960616263646566676869707172737475767778798081828384858687888990919293949596979899";

void ori__text_int(ori__text *t, long long x)
{
    unsigned long long u = x < 0 ? 0ull - (unsigned long long)x : (unsigned long long)x;
    int digits = 1;
    for (unsigned long long v = u; v >= 10; v /= 10) ++digits;
    size_t n = (size_t)digits + (x < 0);
    if (t->len + n + 1 > t->cap) ori__text_reserve(t, n);
    // Written in place from the last digit back, two at a time.
    char *p = t->data + t->len + n;
    while (u >= 100) {
        unsigned r = (unsigned)(u % 100);
        u /= 100;
        p -= 2;
        p[0] = digit_pairs[2 * r], p[1] = digit_pairs[2 * r + 1];
    }
    if (u >= 10) {
        p -= 2;
        p[0] = digit_pairs[2 * u], p[1] = digit_pairs[2 * u + 1];
    } else {
        *--p = (char)('0' + u);
    }
    if (x < 0) *--p = '-';
    t->len += n;
    t->data[t->len] = '\0';
}

// The printf reference: the first of %.15g, %.16g, %.17g that reads back as x.
static size_t format_double_printf(double x, char *buf, size_t size)
{
    int n = 0;
    for (int prec = 15; prec <= 17; ++prec) {
        n = snprintf(buf, size, "%.*g", prec, x);
        if (strtod(buf, NULL) == x) break;
    }
    return n > 0 ? ((size_t)n < size ? (size_t)n : size - 1) : 0;
}

// The same text as format_double_printf, from the shortest digits (about 20× faster: no
// multi-precision printf, no strtod). For a normal double the first precision P ≥ 15 whose
// correctly rounded digits read back gives exactly the shortest digits (at most one 15-digit
// decimal lies within half an ulp; from 16 digits on both pick the nearest), so only %g's
// layout is rebuilt: exponent X = point − 1, scientific when X < −4 or X ≥ P = max(15, n),
// no trailing zeros, an exponent of at least two digits. Subnormals (fewer significant bits)
// non-finite values and powers of two needing 16 or 17 digits take the printf path.
size_t ori__format_double(double x, char *buf, size_t size)
{
    if (x == 0.0) {
        snprintf(buf, size, "0");
        return size > 1 ? 1 : 0;
    }
    if (!isfinite(x) || fabs(x) < DBL_MIN || size < 32) return format_double_printf(x, buf, size);
    char d[24];
    int n, point;
    int neg = ori__shortest_digits(x, d, &n, &point);
    int e2;
    if (n >= 16 && fabs(frexp(x, &e2)) == 0.5) {
        // A power of two: the rounding interval is narrower below than above, and the
        // shortest digits may then differ from printf's nearest 16 (2^-44: …0802e-14, printf
        // …08015e-14). Keep printf's text.
        return format_double_printf(x, buf, size);
    }
    int X = point - 1, P = n > 15 ? n : 15;
    char *p = buf;
    if (neg) *p++ = '-';
    if (X < -4 || X >= P) {
        *p++ = d[0];
        if (n > 1) {
            *p++ = '.';
            memcpy(p, d + 1, (size_t)(n - 1));
            p += n - 1;
        }
        *p++ = 'e';
        *p++ = X < 0 ? '-' : '+';
        int e = X < 0 ? -X : X;
        if (e >= 100) *p++ = (char)('0' + e / 100);
        *p++ = (char)('0' + e / 10 % 10);
        *p++ = (char)('0' + e % 10);
    } else if (X >= 0) {
        for (int i = 0; i <= X; ++i) *p++ = i < n ? d[i] : '0';
        if (n > X + 1) {
            *p++ = '.';
            memcpy(p, d + X + 1, (size_t)(n - X - 1));
            p += n - X - 1;
        }
    } else {
        *p++ = '0';
        *p++ = '.';
        for (int i = 0; i < -X - 1; ++i) *p++ = '0';
        memcpy(p, d, (size_t)n);
        p += n;
    }
    *p = '\0';
    return (size_t)(p - buf);
}

void ori__text_real(ori__text *t, double x)
{
    // Formatted in place: at most 24 characters ("-1.2345678901234567e-308").
    if (t->len + 41 > t->cap) ori__text_reserve(t, 40);
    t->len += ori__format_double(x, t->data + t->len, 40);
}

void ori__text_json_string(ori__text *t, const char *s, size_t n)
{
    ori__text_put(t, "\"", 1);
    size_t run = 0; // bytes copied as they are, appended a run at a time
    for (size_t i = 0; i < n; ++i) {
        unsigned char c = (unsigned char)s[i];
        if (c >= 0x20 && c != '"' && c != '\\') continue;
        ori__text_put(t, s + run, i - run);
        run = i + 1;
        switch (c) {
        case '"': ori__text_puts(t, "\\\""); break;
        case '\\': ori__text_puts(t, "\\\\"); break;
        case '\n': ori__text_puts(t, "\\n"); break;
        case '\r': ori__text_puts(t, "\\r"); break;
        case '\t': ori__text_puts(t, "\\t"); break;
        case '\b': ori__text_puts(t, "\\b"); break;
        case '\f': ori__text_puts(t, "\\f"); break;
        default: ori__text_printf(t, "\\u%04x", c);
        }
    }
    ori__text_put(t, s + run, n - run);
    ori__text_put(t, "\"", 1);
}
