// JSON output with numbers in their shortest exact decimal form and a FOLD-friendly layout.
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "io_internal.h"

json_t *ori__json_number(double x)
{
    if (x == 0.0) x = 0.0; // drop the sign of −0
    return json_real(x);
}

double ori__clean_degrees(double deg)
{
    double r = round(deg);
    if (fabs(deg - r) <= ORI_TOL_PRINT_DEG) deg = r;
    return deg == 0.0 ? 0.0 : deg;
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

typedef struct sbuf {
    char *data;
    int len, cap;
} sbuf;

static void put(sbuf *b, const char *s, size_t n)
{
    ORI__RESERVE(b->data, b->cap, b->len + (int)n + 1);
    memcpy(b->data + b->len, s, n);
    b->len += (int)n;
    b->data[b->len] = '\0';
}

static void puts_(sbuf *b, const char *s) { put(b, s, strlen(s)); }

static void put_string(sbuf *b, const char *s, size_t n)
{
    puts_(b, "\"");
    for (size_t i = 0; i < n; ++i) {
        unsigned char c = (unsigned char)s[i];
        char esc[8];
        switch (c) {
        case '"': puts_(b, "\\\""); break;
        case '\\': puts_(b, "\\\\"); break;
        case '\n': puts_(b, "\\n"); break;
        case '\r': puts_(b, "\\r"); break;
        case '\t': puts_(b, "\\t"); break;
        case '\b': puts_(b, "\\b"); break;
        case '\f': puts_(b, "\\f"); break;
        default:
            if (c < 0x20) {
                snprintf(esc, sizeof esc, "\\u%04x", c);
                puts_(b, esc);
            } else {
                put(b, (const char *)&c, 1);
            }
        }
    }
    puts_(b, "\"");
}

static void write_compact(sbuf *b, const json_t *v)
{
    char num[40];
    switch (json_typeof(v)) {
    case JSON_OBJECT: {
        puts_(b, "{");
        const char *key;
        json_t *val;
        bool first = true;
        json_object_foreach((json_t *)v, key, val)
        {
            if (!first) puts_(b, ",");
            first = false;
            put_string(b, key, strlen(key));
            puts_(b, ":");
            write_compact(b, val);
        }
        puts_(b, "}");
        break;
    }
    case JSON_ARRAY: {
        puts_(b, "[");
        for (size_t i = 0; i < json_array_size(v); ++i) {
            if (i) puts_(b, ",");
            write_compact(b, json_array_get(v, i));
        }
        puts_(b, "]");
        break;
    }
    case JSON_STRING: put_string(b, json_string_value(v), json_string_length(v)); break;
    case JSON_INTEGER:
        snprintf(num, sizeof num, "%" JSON_INTEGER_FORMAT, json_integer_value(v));
        puts_(b, num);
        break;
    case JSON_REAL:
        ori__format_double(json_real_value(v), num, sizeof num);
        puts_(b, num);
        break;
    case JSON_TRUE: puts_(b, "true"); break;
    case JSON_FALSE: puts_(b, "false"); break;
    case JSON_NULL: puts_(b, "null"); break;
    }
}

static bool is_array_of_containers(const json_t *v)
{
    if (!json_is_array(v) || json_array_size(v) == 0) return false;
    for (size_t i = 0; i < json_array_size(v); ++i) {
        json_t *x = json_array_get(v, i);
        if (!json_is_array(x) && !json_is_object(x)) return false;
    }
    return true;
}

static void indent(sbuf *b, int n)
{
    for (int i = 0; i < n; ++i) puts_(b, "  ");
}

static void write_object(sbuf *b, const json_t *obj, int depth);

static void write_value(sbuf *b, const char *key, const json_t *val, int depth)
{
    if (key && strcmp(key, "file_frames") == 0 && json_is_array(val) && json_array_size(val) > 0) {
        puts_(b, "[\n");
        for (size_t i = 0; i < json_array_size(val); ++i) {
            indent(b, depth + 1);
            json_t *fr = json_array_get(val, i);
            if (json_is_object(fr)) write_object(b, fr, depth + 1);
            else write_compact(b, fr);
            puts_(b, i + 1 < json_array_size(val) ? ",\n" : "\n");
        }
        indent(b, depth);
        puts_(b, "]");
    } else if (is_array_of_containers(val)) {
        puts_(b, "[\n");
        for (size_t i = 0; i < json_array_size(val); ++i) {
            indent(b, depth + 1);
            write_compact(b, json_array_get(val, i));
            puts_(b, i + 1 < json_array_size(val) ? ",\n" : "\n");
        }
        indent(b, depth);
        puts_(b, "]");
    } else {
        write_compact(b, val);
    }
}

static void write_object(sbuf *b, const json_t *obj, int depth)
{
    if (json_object_size(obj) == 0) {
        puts_(b, "{}");
        return;
    }
    puts_(b, "{\n");
    const char *key;
    json_t *val;
    size_t i = 0, n = json_object_size(obj);
    json_object_foreach((json_t *)obj, key, val)
    {
        indent(b, depth + 1);
        put_string(b, key, strlen(key));
        puts_(b, ": ");
        write_value(b, key, val, depth + 1);
        puts_(b, ++i < n ? ",\n" : "\n");
    }
    indent(b, depth);
    puts_(b, "}");
}

char *ori__json_write_pretty(const json_t *root)
{
    sbuf b = {NULL, 0, 0};
    if (json_is_object(root)) write_object(&b, root, 0);
    else write_compact(&b, root);
    puts_(&b, "\n");
    return b.data;
}

char *ori__json_write_compact(const json_t *root)
{
    sbuf b = {NULL, 0, 0};
    write_compact(&b, root);
    puts_(&b, "\n");
    return b.data;
}
