// Status names and messages from the one X-macro table; error records.
#include "core_internal.h"

#include <stdio.h>

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
    if (fmt) vsnprintf(error->message, sizeof error->message, fmt, ap);
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
