// A growing text buffer for the writers (FOLD text, SVG, CP, OPX): appends, printf, and
// numbers in their shortest exact form. Allocated with ori__alloc; the caller owns data.
#include <stdio.h>

#include "import_internal.h"
#include "io_internal.h"

void ori__text_reserve(ori__text *t, size_t extra)
{
    if (t->len + extra + 1 <= t->cap) return;
    size_t cap = t->cap ? t->cap : 4096;
    while (cap < t->len + extra + 1) cap *= 2;
    t->data = ori__realloc(t->data, cap);
    t->cap = cap;
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

void ori__text_real(ori__text *t, double x)
{
    char num[40];
    ori__format_double(x, num, sizeof num);
    ori__text_puts(t, num);
}
