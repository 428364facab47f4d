// The drawing options shared by render and animate.
#include "render_args.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

// Largest texture file read (bytes).
#define TEXTURE_MAX_BYTES ((size_t)1 << 28)

void cli_render_args_init(cli_render_args *r)
{
    memset(r, 0, sizeof *r);
    ori_render_def d = ori_default_render_def();
    r->preset = ORI_CAMERA_ISO;
    r->width = d.width;
    r->height = d.height;
    r->front = d.front;
    r->back = d.back;
}

static int once(const char *cmd, bool *seen, const char *opt, int *rc)
{
    if (*seen) {
        *rc = cli_usage(cmd, "%s given twice", opt);
        return -1;
    }
    *seen = true;
    return 0;
}

static int angle(const char *cmd, const char *opt, const char *v, double *out, int *rc)
{
    if (!cli_parse_double(v, out)) {
        *rc = cli_usage(cmd, "%s needs an angle in degrees, got '%s'", opt, v);
        return -1;
    }
    return 0;
}

// "WxH" with 1 ≤ W, H ≤ ORI_RENDER_MAX_SIZE.
static bool parse_size(const char *s, int *w, int *h)
{
    const char *x = strchr(s, 'x');
    if (!x || x == s || !x[1]) return false;
    char buf[32];
    size_t n = (size_t)(x - s);
    if (n >= sizeof buf) return false;
    memcpy(buf, s, n);
    buf[n] = '\0';
    return cli_parse_int(buf, w) && cli_parse_int(x + 1, h);
}

int cli_render_option(const char *cmd, int argc, char **argv, int *i, cli_render_args *r, bool allow_labels, int *rc)
{
    const char *o = argv[*i];
    *rc = CLI_EXIT_OK;
    static const char *const flags[] = {"--perspective", "--edges", "--grid", "--labels"};
    for (size_t k = 0; k < sizeof flags / sizeof flags[0]; ++k) {
        if (strcmp(o, flags[k]) != 0) continue;
        if (k == 3 && !allow_labels) return 0;
        bool *b = k == 0 ? &r->perspective : k == 1 ? &r->edges : k == 2 ? &r->grid : &r->labels;
        if (*b) {
            *rc = cli_usage(cmd, "%s given twice", o);
            return -1;
        }
        *b = true;
        if (k < 3 && !r->only_3d) r->only_3d = o;
        return 1;
    }
    static const char *const valued[] = {"--view", "--camera", "--yaw", "--pitch", "--roll", "--size", "--front", "--back", "--texture"};
    int which = -1;
    for (size_t k = 0; k < sizeof valued / sizeof valued[0]; ++k)
        if (strcmp(o, valued[k]) == 0) which = (int)k;
    if (which < 0) return 0;
    const char *v = cli_option_value(cmd, argc, argv, i);
    if (!v) {
        *rc = CLI_EXIT_USAGE;
        return -1;
    }
    bool texture_seen = r->texture != NULL;
    bool *seen[] = {&r->has_view, &r->has_camera, &r->has_yaw, &r->has_pitch, &r->has_roll,
                    &r->has_size, &r->has_front, &r->has_back, &texture_seen};
    if (once(cmd, seen[which], o, rc) < 0) return -1;
    if (which >= 1 && which != 5 && !r->only_3d) r->only_3d = o;
    switch (which) {
    case 0:
        if (strcmp(v, "cp") == 0) r->view = ORI_RENDER_CREASES;
        else if (strcmp(v, "3d") == 0) r->view = ORI_RENDER_3D;
        else {
            *rc = cli_usage(cmd, "--view is cp or 3d, got '%s'", v);
            return -1;
        }
        return 1;
    case 1: {
        static const char *const names[] = {"iso", "top", "front", "side", "bottom"};
        static const ori_camera_preset_kind kinds[] = {ORI_CAMERA_ISO, ORI_CAMERA_TOP, ORI_CAMERA_FRONT, ORI_CAMERA_SIDE,
                                                       ORI_CAMERA_BOTTOM};
        for (int k = 0; k < 5; ++k)
            if (strcmp(v, names[k]) == 0) {
                r->preset = kinds[k];
                return 1;
            }
        *rc = cli_usage(cmd, "--camera is iso, top, front, side or bottom, got '%s'", v);
        return -1;
    }
    case 2: return angle(cmd, o, v, &r->yaw_deg, rc) < 0 ? -1 : 1;
    case 3: return angle(cmd, o, v, &r->pitch_deg, rc) < 0 ? -1 : 1;
    case 4: return angle(cmd, o, v, &r->roll_deg, rc) < 0 ? -1 : 1;
    case 5:
        if (!parse_size(v, &r->width, &r->height) || r->width < 1 || r->height < 1 || r->width > ORI_RENDER_MAX_SIZE ||
            r->height > ORI_RENDER_MAX_SIZE) {
            *rc = cli_usage(cmd, "--size needs WxH with W and H from 1 to %d, got '%s'", ORI_RENDER_MAX_SIZE, v);
            return -1;
        }
        return 1;
    case 6:
    case 7:
        if (!ori_rgb_parse(v, which == 6 ? &r->front : &r->back)) {
            *rc = cli_usage(cmd, "%s needs a colour (#rrggbb, #rgb or a name such as orange), got '%s'", o, v);
            return -1;
        }
        return 1;
    default:
        r->texture = v;
        return 1;
    }
}

int cli_render_def(const char *cmd, const cli_render_args *r, ori_render_def *def, void **texture)
{
    *texture = NULL;
    def->width = r->width;
    def->height = r->height;
    def->camera = ori_camera_preset(r->preset, ori_deg_to_rad(r->yaw_deg), ori_deg_to_rad(r->pitch_deg),
                                    ori_deg_to_rad(r->roll_deg));
    def->camera.perspective = r->perspective;
    def->fit_camera = true;
    def->front = r->front;
    def->back = r->back;
    def->all_edges = r->edges;
    def->grid = r->grid;
    def->labels = r->labels;
    if (r->texture) {
        char *data = NULL;
        size_t size = 0;
        ori_error err;
        if (ori_file_read_all(r->texture, TEXTURE_MAX_BYTES, &data, &size, &err) != ORI_OK)
            return cli_input_error(cmd, r->texture, &err);
        *texture = data;
        def->texture_png = data;
        def->texture_size = size;
    }
    return CLI_EXIT_OK;
}
