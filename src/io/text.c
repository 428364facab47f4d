// The writers' text buffer (FOLD text, JSON, SVG, CP, OPX): appends, printf, JSON strings, and
// numbers in their shortest exact form. Allocated with ori__alloc; the caller owns data.
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

void ori__format_double(double x, char *buf, size_t size)
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
