// Shared pieces of the fabrication commands (see fab_args.h).
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fab_args.h"

bool fab_parse_length(const char *s, double *value, double *unit_m)
{
    if (!s || !*s) return false;
    char *end;
    double x = strtod(s, &end);
    if (end == s || !isfinite(x) || x < 0.0) return false;
    *value = x;
    *unit_m = 0.0;
    if (!*end) return true;
    ori_error err;
    return ori_unit_meters(end, unit_m, &err) == ORI_OK;
}

double fab_length_m(double value, double unit_m, double fallback_m)
{
    return value * (unit_m > 0.0 ? unit_m : fallback_m);
}

bool fab_file_unit(const ori_fold *doc, double *meters)
{
    char *u = ori_fold_get_custom(doc, 0, "frame_unit");
    bool ok = false;
    if (u) {
        json_t *j = json_loads(u, JSON_DECODE_ANY, NULL);
        ori_error err;
        ok = j && json_is_string(j) && ori_unit_meters(json_string_value(j), meters, &err) == ORI_OK;
        json_decref(j);
        ori_buffer_free(u);
    }
    return ok;
}
