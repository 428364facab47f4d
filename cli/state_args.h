// State selection shared by the commands that show or export a state (render, animate, export;
// meant for collide and the studio too): the input file and the options naming a state of it,
// turned into one posed sheet, or into the frames of a motion.
//
//   IN.fold [--frame N]               a frame: a folded form (3D vertices_coords), or a crease
//                                     pattern posed from its edges_foldAngle (the loops must close)
//   IN.svg | IN.opx | IN.cp           a drawing's crease pattern (read as every command reads it)
//   IN.fold --fix F --drive E --to D  a fold (the kinematics options of `orikin fold`, faces and
//                                     creases by index, name or @x,y as there; --fix optional:
//                                     the face at the sheet's centre); the state is the fold's
//     [--from --step --lock --solver --linear --frame N]     last frame
//   IN --percent P | --drive E1,E2 --to A1,A2 [--ratio R1,R2] | --lock auto | --symmetric
//                                     the modes of `orikin fold` (fold_modes.c, the same code):
//                                     the state is where the fold ends (its goal, or where it stops
//                                     short, said on stderr); a motion's times are its progress
//   SEQ.json [--at T]                 a fold sequence at time T (default: its end)
//
// Usage:
//   cli_state_args sa;  cli_state_args_init(&sa);
//   for (i...) { int took = cli_state_option(cmd, argc, argv, &i, &sa, &rc); if (took < 0) return rc; if (took) continue; ... }
//   if ((rc = cli_state_finish(cmd, &sa)) != CLI_EXIT_OK) return rc;
//   cli_state st;  if ((rc = cli_state_load(cmd, &sa, true, &st)) != CLI_EXIT_OK) return rc;
//   ori_state_view view = cli_state_view(&st);  ...  cli_state_free(&st);
#ifndef ORI_CLI_STATE_ARGS_H
#define ORI_CLI_STATE_ARGS_H

#include "collide_args.h"
#include "kin_args.h"

#define CLI_STATE_MAX_FOLD_ARGS 64

// Help lines for the modes of `orikin fold` in the state options (render, animate, export).
#define CLI_STATE_MODES_HELP                                                                                  \
    "  --percent P | --drive E1,E2,... --to A1,A2,... [--ratio R1,...] | --lock auto | --symmetric\n"         \
    "                       the modes of orikin fold (patterns with several degrees of freedom):\n"          \
    "                       the state is where that fold ends (its goal, or where it stops short,\n"       \
    "                       said on stderr); --fix is optional everywhere (default: the face at\n"       \
    "                       the sheet's centre, named on stderr)\n"                                        \
    "  --compliant [--percent P] [--dynamic] [--fix F] [--preset NAME] [--axial K] [--facet K]\n"         \
    "              [--crease K] [--damping Z] [--gravity G] [--steps N] [--threads N]\n"               \
    "                       the compliant fold of orikin fold --compliant (bending panels): the\n"      \
    "                       state is its equilibrium, the motion its load steps (not a glTF\n"        \
    "                       animation: the faces bend); --color strain from the model\n"

// Where the state comes from.
typedef enum cli_state_source {
    CLI_STATE_FRAME = 0, // a FOLD frame
    CLI_STATE_FOLD,      // a fold (kinematics options)
    CLI_STATE_SEQUENCE,  // a fold sequence (SEQ.json)
} cli_state_source;

// The state options as given.
typedef struct cli_state_args {
    const char *path;                         // IN: a FOLD file or SEQ.json
    bool has_frame, has_at;
    int frame;                                // --frame N (default 0)
    double at;                                // --at T
    int fold_argc;                            // the fold options, collected for cli_fold_parse
    char *fold_argv[CLI_STATE_MAX_FOLD_ARGS]; // [0] = command, [1] = IN, then the options
    cli_fold_args fold;                       // parsed by cli_state_finish
    cli_state_source source;                  // decided by cli_state_finish
    char frame_text[24];                      // --frame's value passed on to the fold options
    int fold_argc_all;                        // fold_argc with --frame added (cli_state_finish)
    bool modes;                               // the fold options use a mode of `orikin fold` (fold_modes.h):
                                              // --percent, several drives, --ratio, --lock auto, --symmetric
    bool compliant;                           // --compliant: the bar-and-hinge model's fold (fold_compliant.h)
    cli_compliant_request compliant_req;      // its request (parsed by cli_state_finish)
    const char *compliant_fix;                // its --fix, resolved when loading (NULL: the model's default)
} cli_state_args;

void cli_state_args_init(cli_state_args *a);

// Offer argv[*i] to the state options (and the first positional argument, IN). Returns 1 when
// taken (*i advanced past its value), 0 when it is not a state option, -1 after printing a
// usage error (*rc = its exit code). A repeated single-valued option is a usage error.
int cli_state_option(const char *cmd, int argc, char **argv, int *i, cli_state_args *a, int *rc);

// After the options: IN is required; a SEQ.json (a JSON object with "folds") takes --at but
// neither --frame nor fold options; a FOLD file takes --frame and fold options but not --at.
// Parses the fold options. Prints a usage error and returns its code, or CLI_EXIT_OK.
int cli_state_finish(const char *cmd, cli_state_args *a);

// A loaded source and the chosen state: the posed sheet.
typedef struct cli_state {
    cli_state_source source;
    const char *path;        // IN as given
    char *pattern_path;      // the FOLD file (a sequence's pattern, resolved against SEQ.json's folder)
    ori_pattern *pattern;    // topology to draw: the flat crease pattern when there is one, else the folded form
    ori_pattern *frame_pattern; // a folded-form frame drawn on frame 0's crease pattern: the frame's own
                                // pattern (its size sets the collision tolerances, as the studio's), else NULL
    bool has_flat;           // pattern is a flat crease pattern (texture coordinates, the crease view)
    ori_mechanism *mech;     // the crease pattern's mechanism, or NULL
    ori_v3 *positions;       // world position of every vertex (NULL: not posed, need_pose was false)
    ori_rigid *poses;        // flat → world pose of every face, or NULL (folded forms, unposed, non-rigid faces)
    double *angles;          // fold angle of every edge (radians), or NULL when unknown
    int *face_orders;        // a FOLD frame's faceOrders: face_order_count triples (f, g, s), or NULL
    int face_order_count;    // (for ori_render_def's face_orders: the layer order of stacked faces)
    bool folded;             // the state is not the flat sheet
    bool cp_frame;           // the chosen state is a crease-pattern frame (posed from its fold angles)
    int frame_count;         // frames of the FOLD file (1 for a fold or a sequence)
    char label[160];         // what the state is: "frame 2", "crease 12 folded to 90 deg", "t = 1.5"
    // Internals kept for motions.
    const cli_state_args *args; // the options it was loaded with (kept alive by the caller)
    cli_fold_args fold;         // a fold: args->fold with its faces and creases resolved
    ori_fold *doc;
    cli_kin kin;
    bool has_kin;
    ori_sequence *seq;
    ori_record *record;
    ori_motion *motion;
    double start_drive_rad;  // a fold: the driven crease's angle where the motion starts
    struct cli_fold_modes *modes; // a fold in one of the modes: its solve (owns pattern and mechanism), else NULL
    ori_compliant *compliant;     // a compliant fold: the model with its load steps (or explicit end), else NULL
} cli_state;

// Load the chosen state. need_pose = false skips posing a crease-pattern frame (the crease view
// needs none). Prints the error (one line) and returns its exit code: 3 bad input (file, frame
// that does not exist, angles that do not close), 2 usage (--at out of range), 1 a fold or
// sequence that is not valid.
int cli_state_load(const char *cmd, const cli_state_args *a, bool need_pose, cli_state *s);
// The library's view of the state.
ori_state_view cli_state_view(const cli_state *s);
void cli_state_free(cli_state *s);

// Check the motion of a fold or a sequence for self-collision as `orikin fold` and `orikin
// sequence` do (o: --no-collisions, --clearance D); a FOLD frame is not checked (out->checked
// false). Prints the error and returns its exit code on failure, else CLI_EXIT_OK.
int cli_state_collisions(const char *cmd, const cli_state *s, const cli_collide_opts *o, cli_collision *out);

// A motion as frames: its natural keyframes (samples = 0: the frames of a multi-frame FOLD, a
// fold's output steps, a sequence's recorded states) or samples ≥ 2 frames evenly spaced in
// time (exact states for a fold or a sequence; the stored frame nearest in time for a FOLD file,
// which holds nothing between its frames). Times in seconds: one second per fold (sequence time
// T), a FOLD file's "orikin:time" when every frame has one, else its frames spread over one
// second (cli_motion, report.h).
// Build the motion of a loaded state (cli_state_load first). A FOLD file with a single state has
// no motion: input error. Shows a progress bar on stderr when solving takes over a second.
int cli_state_motion(const char *cmd, cli_state *s, int samples, cli_motion *m);

#endif
