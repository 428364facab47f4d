// Colour by value: the colour map (a polynomial fit of viridis), where a value lies on the bar,
// and the bar's tick labels. The drawing of the bar is draw.c's; glTF colours mesh_write_gltf.c's.
#include <math.h>
#include <stdio.h>

#include "render_internal.h"

// Degree-8 least-squares fit of each channel of matplotlib's viridis over 256 samples, constant
// term first (scripts/fit_viridis.py prints them and the largest error: 2.33, 0.49 and 1.00 of
// 1/255 for red, green and blue).
#define COLORMAP_TERMS 9
static const double colormap_coef[3][COLORMAP_TERMS] = {
    {0.262736168, 0.689505848, -6.3466757, 13.8058487, 18.4900994, -164.475208, 335.76583, -285.086196, 87.8964402},
    {0.00295810215, 1.58064897, -2.63216181, 12.6597209, -46.9521768, 99.085098, -112.583279, 64.0722564, -14.3273382},
    {0.333353116, 1.15681578, 6.59488959, -81.7213994, 336.507, -727.361819, 878.045154, -563.311351, 149.904559},
};

static double horner(const double *c, double t)
{
    double y = c[COLORMAP_TERMS - 1];
    for (int k = COLORMAP_TERMS - 2; k >= 0; --k) y = y * t + c[k];
    return fmin(1.0, fmax(0.0, y));
}

ori_rgb ori_colormap(double t)
{
    if (!(t >= 0.0)) t = 0.0; // NaN too
    if (t > 1.0) t = 1.0;
    ori_rgb c = {horner(colormap_coef[0], t), horner(colormap_coef[1], t), horner(colormap_coef[2], t)};
    return c;
}

double ori_value_map_position(const ori_value_map *map, double value)
{
    ORI_ASSERT(map);
    double span = map->max - map->min;
    if (!(span > 0.0) || isnan(value)) return 0.0;
    double t = (value - map->min) / span;
    return fmin(1.0, fmax(0.0, t));
}

int ori_value_map_ticks(const ori_value_map *map, double *values, char (*labels)[ORI_RENDER_BAR_LABEL_MAX])
{
    ORI_ASSERT(map);
    double span = map->max - map->min;
    int n = span > 0.0 ? ORI_RENDER_BAR_TICKS : 1;
    for (int k = 0; k < n; ++k) {
        // The ends exactly; interior ticks evenly between.
        double v = k == 0 ? map->min : k == n - 1 ? map->max : map->min + span * k / (n - 1);
        if (k > 0 && k < n - 1 && fabs(v) < ORI_TOL_BAR_ZERO_REL * span) v = 0.0;
        if (values) values[k] = v;
        if (labels) snprintf(labels[k], ORI_RENDER_BAR_LABEL_MAX, "%.3g", v == 0.0 ? 0.0 : v);
    }
    return n;
}

bool ori__value_map_active(const ori_value_map *map) { return map->face_values || map->edge_values; }

ori_status ori__value_map_check(const ori_value_map *map, ori_error *error)
{
    if (!ori__value_map_active(map)) return ORI_OK;
    if (!isfinite(map->min) || !isfinite(map->max) || map->min > map->max)
        return ori__fail(error, ORI_ERR_ARGUMENT, "values: the colour bar's range needs finite min <= max (got %g, %g)",
                         map->min, map->max);
    return ORI_OK;
}
