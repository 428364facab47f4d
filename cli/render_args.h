// The drawing options shared by render and animate: view, camera, size, colours, texture,
// edges, grid, labels.
#ifndef ORI_CLI_RENDER_ARGS_H
#define ORI_CLI_RENDER_ARGS_H

#include "cli.h"

typedef struct cli_render_args {
    bool has_view;
    ori_render_view view;
    bool has_camera, has_yaw, has_pitch, has_roll, has_size, has_front, has_back;
    ori_camera_preset_kind preset;
    double yaw_deg, pitch_deg, roll_deg;
    bool perspective;
    int width, height;
    ori_rgb front, back;
    const char *texture;
    bool edges, grid, labels;
    const char *only_3d; // the first option given that only the 3D view uses (NULL when none)
} cli_render_args;

void cli_render_args_init(cli_render_args *r);

// Offer argv[*i] to the drawing options (labels only when allow_labels). Returns 1 when taken,
// 0 when not a drawing option, -1 after printing a usage error (*rc = its exit code).
int cli_render_option(const char *cmd, int argc, char **argv, int *i, cli_render_args *r, bool allow_labels, int *rc);

// Fill a render def (view set by the caller) and read the texture file into *texture (free with
// ori_buffer_free; NULL without --texture). Prints the error and returns CLI_EXIT_INPUT when
// the texture cannot be read.
int cli_render_def(const char *cmd, const cli_render_args *r, ori_render_def *def, void **texture);

#endif
