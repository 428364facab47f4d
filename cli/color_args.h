// Colour by value (render --color, export --color): the quantity to show and its values per face
// or edge, read from the chosen state (a compliant fold's frame carries its strains).
//
//   strain        per face: faces_orikin:strain of the frame (largest |axial strain| of the face's
//                 bars, written by `orikin fold --compliant -o`), else the largest |strain| of its
//                 edges in edges_orikin:strain
//   fold-angle    per crease: its fold angle in degrees (the state's; a crease-pattern frame's
//                 edges_foldAngle)
//   target-error  per crease: |fold angle - target x fraction| in degrees; targets as the
//                 compliant fold takes them (frame 0's edges_foldAngle, else +-180 by M/V),
//                 fraction the frame's orikin:fraction (1 without one)
// The bar's range is the smallest and largest value shown.
#ifndef ORI_CLI_COLOR_ARGS_H
#define ORI_CLI_COLOR_ARGS_H

#include "state_args.h"

typedef enum cli_color_kind {
    CLI_COLOR_NONE = 0,
    CLI_COLOR_STRAIN,
    CLI_COLOR_FOLD_ANGLE,
    CLI_COLOR_TARGET_ERROR,
} cli_color_kind;

// Help line of --color, for the commands' option lists.
#define CLI_COLOR_HELP                                                                                      \
    "  --color Q            paint a quantity with a colour bar (viridis, min to max): strain (per\n"        \
    "                       face, from a compliant fold's frame: orikin fold --compliant -o),\n"           \
    "                       fold-angle or target-error (per crease, degrees; see docs/compliant.md)\n"

// Offer argv[*i] to --color. Returns 1 when taken, 0 when not --color, -1 after printing a usage
// error (*rc = CLI_EXIT_USAGE): a repeated --color, or a value that is none of the three.
int cli_color_option(const char *cmd, int argc, char **argv, int *i, cli_color_kind *kind, int *rc);
// The quantity's name as the option spells it ("target-error").
const char *cli_color_name(cli_color_kind kind);

// Values of a loaded state (kind not NONE).
typedef struct cli_colors {
    cli_color_kind kind;
    double *face_values, *edge_values; // face_count / edge_count, NaN where not shown; one of them NULL
    double min, max;                   // over the values shown (0, 0 when none)
    int shown;                         // faces or creases with a value
    int frames;                        // cli_colors_motion: frames of values (each face_count or edge_count); 0: one state
} cli_colors;

// Read or compute the values for st (loaded from a = the state options). Prints the error (one
// line naming the file and field) and returns CLI_EXIT_INPUT when the state does not have them
// (strain of a state that is not a FOLD frame with strains, a field of the wrong length).
int cli_colors_load(const char *cmd, const cli_state_args *a, const cli_state *st, cli_color_kind kind, cli_colors *out);
// The values of every frame of a motion (animate --color), one bar for all of them: the range is
// over every frame. strain needs the motion of a FOLD file's frames (m->sources); fold-angle and
// target-error its angles (target-error: each shown frame's orikin:fraction, else 1). Prints the
// error and returns CLI_EXIT_INPUT as cli_colors_load.
int cli_colors_motion(const char *cmd, const cli_state_args *a, const cli_state *st, const cli_motion *m,
                      cli_color_kind kind, cli_colors *out);
// The library's value map of the colours.
ori_value_map cli_colors_map(const cli_colors *c);
// {"quantity", "min", "max", "labels": [...]} for --json reports.
json_t *cli_colors_json(const cli_colors *c);
void cli_colors_free(cli_colors *c);

#endif
