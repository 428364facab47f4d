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

void ori__text_put(ori__text *t, const char *s, size_t n)
{
    ori__text_reserve(t, n);
    memcpy(t->data + t->len, s, n);
    t->len += n;
    t->data[t->len] = '\0';
}

void ori__text_puts(ori__text *t, const char *s) { ori__text_put(t, s, strlen(s)); }

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

void ori__text_int(ori__text *t, long long x)
{
    char buf[24], *p = buf + sizeof buf;
    unsigned long long u = x < 0 ? 0ull - (unsigned long long)x : (unsigned long long)x;
    do *--p = (char)('0' + u % 10);
    while (u /= 10);
    if (x < 0) *--p = '-';
    ori__text_put(t, p, (size_t)(buf + sizeof buf - p));
}

// The printf reference: the first of %.15g, %.16g, %.17g that reads back as x.
static void format_double_printf(double x, char *buf, size_t size)
{
    for (int prec = 15; prec <= 17; ++prec) {
        snprintf(buf, size, "%.*g", prec, x);
        if (strtod(buf, NULL) == x) break;
    }
}

// The same text as format_double_printf, from the shortest digits (about 20× faster: no
// multi-precision printf, no strtod). For a normal double the first precision P ≥ 15 whose
// correctly rounded digits read back gives exactly the shortest digits (at most one 15-digit
// decimal lies within half an ulp; from 16 digits on both pick the nearest), so only %g's
// layout is rebuilt: exponent X = point − 1, scientific when X < −4 or X ≥ P = max(15, n),
// no trailing zeros, an exponent of at least two digits. Subnormals (fewer significant bits)
// non-finite values and powers of two needing 16 or 17 digits take the printf path.
void ori__format_double(double x, char *buf, size_t size)
{
    if (x == 0.0) {
        snprintf(buf, size, "0");
        return;
    }
    if (!isfinite(x) || fabs(x) < DBL_MIN || size < 32) {
        format_double_printf(x, buf, size);
        return;
    }
    char d[24];
    int n, point;
    int neg = ori__shortest_digits(x, d, &n, &point);
    int e2;
    if (n >= 16 && fabs(frexp(x, &e2)) == 0.5) {
        // A power of two: the rounding interval is narrower below than above, and the
        // shortest digits may then differ from printf's nearest 16 (2^-44: …0802e-14, printf
        // …08015e-14). Keep printf's text.
        format_double_printf(x, buf, size);
        return;
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
}

void ori__text_real(ori__text *t, double x)
{
    char num[40];
    ori__format_double(x, num, sizeof num);
    ori__text_puts(t, num);
}

void ori__text_json_string(ori__text *t, const char *s, size_t n)
{
    ori__text_puts(t, "\"");
    for (size_t i = 0; i < n; ++i) {
        unsigned char c = (unsigned char)s[i];
        switch (c) {
        case '"': ori__text_puts(t, "\\\""); break;
        case '\\': ori__text_puts(t, "\\\\"); break;
        case '\n': ori__text_puts(t, "\\n"); break;
        case '\r': ori__text_puts(t, "\\r"); break;
        case '\t': ori__text_puts(t, "\\t"); break;
        case '\b': ori__text_puts(t, "\\b"); break;
        case '\f': ori__text_puts(t, "\\f"); break;
        default:
            if (c < 0x20) ori__text_printf(t, "\\u%04x", c);
            else ori__text_put(t, (const char *)&s[i], 1);
        }
    }
    ori__text_puts(t, "\"");
}
