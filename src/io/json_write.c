// JSON output with numbers in their shortest exact decimal form and a FOLD-friendly layout.

#include "fold_internal.h"

json_t *ori__json_number(double x)
{
    if (x == 0.0) x = 0.0; // drop the sign of −0
    return json_real(x);
}

void ori__json_write_compact_to(ori__text *b, const json_t *v)
{
    switch (json_typeof(v)) {
    case JSON_OBJECT: {
        ori__text_puts(b, "{");
        const char *key;
        json_t *val;
        bool first = true;
        json_object_foreach((json_t *)v, key, val)
        {
            if (!first) ori__text_puts(b, ",");
            first = false;
            ori__text_json_string(b, key, strlen(key));
            ori__text_puts(b, ":");
            ori__json_write_compact_to(b, val);
        }
        ori__text_puts(b, "}");
        break;
    }
    case JSON_ARRAY: {
        ori__text_puts(b, "[");
        for (size_t i = 0; i < json_array_size(v); ++i) {
            if (i) ori__text_puts(b, ",");
            ori__json_write_compact_to(b, json_array_get(v, i));
        }
        ori__text_puts(b, "]");
        break;
    }
    case JSON_STRING: ori__text_json_string(b, json_string_value(v), json_string_length(v)); break;
    case JSON_INTEGER: ori__text_int(b, json_integer_value(v)); break;
    case JSON_REAL: ori__text_real(b, json_real_value(v)); break;
    case JSON_TRUE: ori__text_puts(b, "true"); break;
    case JSON_FALSE: ori__text_puts(b, "false"); break;
    case JSON_NULL: ori__text_puts(b, "null"); break;
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

static void indent(ori__text *b, int n)
{
    for (int i = 0; i < n; ++i) ori__text_puts(b, "  ");
}

static void write_object(ori__text *b, const json_t *obj, int depth);

void ori__json_write_value_pretty(ori__text *b, const char *key, const json_t *val, int depth)
{
    if (key && strcmp(key, "file_frames") == 0 && json_is_array(val) && json_array_size(val) > 0) {
        ori__text_puts(b, "[\n");
        for (size_t i = 0; i < json_array_size(val); ++i) {
            indent(b, depth + 1);
            json_t *fr = json_array_get(val, i);
            if (json_is_object(fr)) write_object(b, fr, depth + 1);
            else ori__json_write_compact_to(b, fr);
            ori__text_puts(b, i + 1 < json_array_size(val) ? ",\n" : "\n");
        }
        indent(b, depth);
        ori__text_puts(b, "]");
    } else if (is_array_of_containers(val)) {
        ori__text_puts(b, "[\n");
        for (size_t i = 0; i < json_array_size(val); ++i) {
            indent(b, depth + 1);
            ori__json_write_compact_to(b, json_array_get(val, i));
            ori__text_puts(b, i + 1 < json_array_size(val) ? ",\n" : "\n");
        }
        indent(b, depth);
        ori__text_puts(b, "]");
    } else {
        ori__json_write_compact_to(b, val);
    }
}

static void write_object(ori__text *b, const json_t *obj, int depth)
{
    if (json_object_size(obj) == 0) {
        ori__text_puts(b, "{}");
        return;
    }
    ori__text_puts(b, "{\n");
    const char *key;
    json_t *val;
    size_t i = 0, n = json_object_size(obj);
    json_object_foreach((json_t *)obj, key, val)
    {
        indent(b, depth + 1);
        ori__text_json_string(b, key, strlen(key));
        ori__text_puts(b, ": ");
        ori__json_write_value_pretty(b, key, val, depth + 1);
        ori__text_puts(b, ++i < n ? ",\n" : "\n");
    }
    indent(b, depth);
    ori__text_puts(b, "}");
}

char *ori__json_write_pretty(const json_t *root)
{
    ori__text b = {NULL, 0, 0};
    if (json_is_object(root)) write_object(&b, root, 0);
    else ori__json_write_compact_to(&b, root);
    ori__text_puts(&b, "\n");
    return b.data;
}

char *ori__json_write_compact(const json_t *root)
{
    ori__text b = {NULL, 0, 0};
    ori__json_write_compact_to(&b, root);
    ori__text_puts(&b, "\n");
    return b.data;
}
