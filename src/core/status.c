// Status names and messages from the one X-macro table; error records.
#include "core_internal.h"

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

static const char *const status_names[] = {
#define ORI__NAME(name, msg) #name,
    ORI_STATUS_TABLE(ORI__NAME)
#undef ORI__NAME
};

static const char *const status_messages[] = {
#define ORI__MSG(name, msg) msg,
    ORI_STATUS_TABLE(ORI__MSG)
#undef ORI__MSG
};

const char *ori_status_name(ori_status status)
{
    if ((int)status < 0 || status >= ORI_STATUS_COUNT) return "UNKNOWN";
    return status_names[status];
}

const char *ori_status_message(ori_status status)
{
    if ((int)status < 0 || status >= ORI_STATUS_COUNT) return "unknown status";
    return status_messages[status];
}

void ori_error_clear(ori_error *error)
{
    if (!error) return;
    memset(error, 0, sizeof(*error));
    error->status = ORI_OK;
    error->element = ORI_NULL_INDEX;
}

char *ori_error_format(const ori_error *error, char *buf, size_t size)
{
    if (!buf || size == 0) return buf;
    if (!error) {
        buf[0] = '\0';
        return buf;
    }
    const char *msg = error->message[0] ? error->message : ori_status_message(error->status);
    if (error->line > 0 && error->column > 0)
        snprintf(buf, size, "line %d, column %d: %s", error->line, error->column, msg);
    else if (error->line > 0)
        snprintf(buf, size, "line %d: %s", error->line, msg);
    else if (error->element != ORI_NULL_INDEX && error->field[0])
        snprintf(buf, size, "%s %d: %s", error->field, error->element, msg);
    else if (error->field[0])
        snprintf(buf, size, "%s: %s", error->field, msg);
    else
        snprintf(buf, size, "%s", msg);
    return buf;
}

// --- messages ----------------------------------------------------------------------------------

// A %g conversion without a precision: as printf writes it when that text reads back as the
// value, else with the fewest significant digits (up to 17) that read back within a few ulps
// (so that a bound computed in radians still shows as 60°, while 89.9999999 is never shown as
// 90 and -180.00000000286695 never as -180: a message does not show a value rounded onto the
// bound it violates).
static void format_exact_g(char *out, size_t size, const char *spec, size_t spec_len, int width, bool star_width,
                           double x)
{
    char f[48];
    memcpy(f, spec, spec_len); // "%<flags><width>g" or "%<flags>*g": first as written
    f[spec_len] = '\0';
    for (int prec = 6; prec <= 17; ++prec) {
        if (prec > 6) snprintf(f + spec_len - 1, sizeof f - (spec_len - 1), ".%d%c", prec, spec[spec_len - 1]);
        if (star_width) snprintf(out, size, f, width, x);
        else snprintf(out, size, f, x);
        if (!isfinite(x) || fabs(strtod(out, NULL) - x) <= ORI_TOL_MESSAGE_REL * fabs(x)) return;
    }
}

void ori__vformat(char *buf, size_t size, const char *fmt, va_list ap)
{
    if (size == 0) return;
    size_t len = 0;
    buf[0] = '\0';
    va_list args;
    va_copy(args, ap);
    for (const char *p = fmt; *p;) {
        if (*p != '%') {
            const char *q = strchr(p, '%');
            size_t n = q ? (size_t)(q - p) : strlen(p);
            if (len + 1 < size) {
                size_t room = size - 1 - len;
                memcpy(buf + len, p, n < room ? n : room);
                len += n < room ? n : room;
                buf[len] = '\0';
            }
            p += n;
            continue;
        }
        // One conversion: %[flags][width][.precision][length]conversion.
        const char *spec = p++;
        while (*p && strchr("-+ #0'", *p)) ++p;
        bool star_width = false, star_prec = false, has_prec = false;
        int width = 0, prec = 0;
        if (*p == '*') star_width = true, ++p;
        else while (*p >= '0' && *p <= '9') ++p;
        if (*p == '.') {
            has_prec = true;
            ++p;
            if (*p == '*') star_prec = true, ++p;
            else while (*p >= '0' && *p <= '9') ++p;
        }
        char length[3] = "";
        if ((p[0] == 'h' && p[1] == 'h') || (p[0] == 'l' && p[1] == 'l')) length[0] = p[0], length[1] = p[1], p += 2;
        else if (*p && strchr("hljztL", *p)) length[0] = *p++;
        char conv = *p ? *p++ : '\0';
        size_t spec_len = (size_t)(p - spec);
        char f[48];
        if (spec_len >= sizeof f || conv == '\0') break; // not a format this library writes
        memcpy(f, spec, spec_len);
        f[spec_len] = '\0';
        if (star_width) width = va_arg(args, int);
        if (star_prec) prec = va_arg(args, int);
        char piece[400];
        piece[0] = '\0';
#define ORI__ONE(type)                                                                                     \
    do {                                                                                                   \
        type v_ = va_arg(args, type);                                                                      \
        if (star_width && star_prec) snprintf(piece, sizeof piece, f, width, prec, v_);                    \
        else if (star_width) snprintf(piece, sizeof piece, f, width, v_);                                  \
        else if (star_prec) snprintf(piece, sizeof piece, f, prec, v_);                                    \
        else snprintf(piece, sizeof piece, f, v_);                                                         \
    } while (0)
        switch (conv) {
        case '%': snprintf(piece, sizeof piece, "%%"); break;
        case 'd': case 'i': case 'o': case 'u': case 'x': case 'X':
            if (!strcmp(length, "hh") || !strcmp(length, "h") || !length[0]) ORI__ONE(int);
            else if (!strcmp(length, "l")) ORI__ONE(long);
            else if (!strcmp(length, "ll")) ORI__ONE(long long);
            else if (!strcmp(length, "j")) ORI__ONE(intmax_t);
            else if (!strcmp(length, "z")) ORI__ONE(size_t);
            else ORI__ONE(ptrdiff_t);
            break;
        case 'c': ORI__ONE(int); break;
        case 's': ORI__ONE(const char *); break;
        case 'p': ORI__ONE(void *); break;
        case 'g': case 'G': case 'f': case 'F': case 'e': case 'E': case 'a': case 'A':
            if (length[0] == 'L') {
                ORI__ONE(long double);
            } else if ((conv == 'g' || conv == 'G') && !has_prec) {
                format_exact_g(piece, sizeof piece, spec, spec_len, width, star_width, va_arg(args, double));
            } else {
                ORI__ONE(double);
            }
            break;
        default: break; // %n and unknown conversions write nothing
        }
#undef ORI__ONE
        size_t n = strlen(piece);
        if (len + 1 < size) {
            size_t room = size - 1 - len;
            memcpy(buf + len, piece, n < room ? n : room);
            len += n < room ? n : room;
            buf[len] = '\0';
        }
    }
    va_end(args);
}

static ori_status vfail(ori_error *error, ori_status status, const char *field, int element,
                        int line, int column, const char *fmt, va_list ap)
{
    if (!error) return status;
    ori_error_clear(error);
    error->status = status;
    error->element = element;
    error->line = line;
    error->column = column;
    if (field) ori__strlcpy(error->field, field, sizeof error->field);
    if (fmt) ori__vformat(error->message, sizeof error->message, fmt, ap);
    return status;
}

ori_status ori__fail(ori_error *error, ori_status status, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    ori_status s = vfail(error, status, NULL, ORI_NULL_INDEX, 0, 0, fmt, ap);
    va_end(ap);
    return s;
}

ori_status ori__fail_at(ori_error *error, ori_status status, const char *field, int element,
                        const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    ori_status s = vfail(error, status, field, element, 0, 0, fmt, ap);
    va_end(ap);
    return s;
}

ori_status ori__fail_pos(ori_error *error, ori_status status, int line, int column,
                         const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    ori_status s = vfail(error, status, NULL, ORI_NULL_INDEX, line, column, fmt, ap);
    va_end(ap);
    return s;
}

void ori__strlcpy(char *dst, const char *src, size_t size)
{
    if (size == 0) return;
    size_t n = src ? strlen(src) : 0;
    if (n >= size) n = size - 1;
    if (n) memcpy(dst, src, n);
    dst[n] = '\0';
}

const char *ori_version_string(void) { return ORI_VERSION; }
