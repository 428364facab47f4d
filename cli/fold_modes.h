// The folding modes of `orikin fold` for patterns with several degrees of freedom: toward the
// targets (--percent), several drives (--drive E1,E2 --to A1,A2 / --ratio), an automatic lock
// set (--lock auto, with several drives or symmetry) and symmetry (--symmetric). cmd_fold.c hands
// a command line over when cli_fold_modes_wanted says so; its ordinary single-drive fold (--lock
// auto included) asks for a lock suggestion when the fold is underdetermined.
#ifndef ORI_CLI_FOLD_MODES_H
#define ORI_CLI_FOLD_MODES_H

#include "kin_args.h"

// True when the fold command line uses one of the modes (--percent, --symmetric, --ratio, or
// several comma-separated --drive creases; --lock auto with one drive is the ordinary fold's,
// resolved by cli_fold_resolve).
bool cli_fold_modes_wanted(int argc, char **argv);
// Run `orikin fold` in one of the modes; returns the exit code.
int cli_fold_modes_run(int argc, char **argv);

// The modes as a state for the commands that show one (render, animate, export, collide through
// cli/state_args.c): the same parsing and solve as `orikin fold`, without its output.
typedef struct cli_fold_modes cli_fold_modes;
// Parse the fold options of argv (argv[0] the command, then FILE and the options: the modes' and
// --fix, --lock, --step, --frame) for command cmd. Prints a usage error and returns its code, or
// CLI_EXIT_OK with *out allocated (cli_fold_modes_free).
int cli_fold_modes_open(const char *cmd, int argc, char **argv, cli_fold_modes **out);
// Load FILE, resolve faces and creases (no --fix: cli_fold_default_fix) and solve. Prints the
// error and returns its exit code on failure; a fold that stops short is not a failure (see the
// result's verdict).
int cli_fold_modes_solve(cli_fold_modes *r);
// The result (owned by r), the loaded pattern and mechanism (owned by r), the fixed face (and
// whether it is the default), the creases held fixed (given and automatic; owned by r).
const ori_multifold *cli_fold_modes_result(const cli_fold_modes *r);
cli_kin *cli_fold_modes_kin(cli_fold_modes *r);
int cli_fold_modes_fixed_face(const cli_fold_modes *r);
bool cli_fold_modes_fix_default(const cli_fold_modes *r);
const int *cli_fold_modes_locks(const cli_fold_modes *r, int *count);
// What the fold is, for a picture's label: "toward the targets, 100 %", "creases 3,7 to 90,-90 deg",
// followed by the verdict when it stopped short.
void cli_fold_modes_label(const cli_fold_modes *r, char *buf, size_t size);
void cli_fold_modes_free(cli_fold_modes *r);

// A lock set that leaves the single-drive fold `def` one degree of freedom, as the text
// "lock N more creases, e.g. --lock a,b,c" into buf (empty when none is found), and as a JSON
// array when locks is not NULL (NULL stays NULL then). Returns the count, or -1.
int cli_fold_modes_suggest(const cli_kin *k, const ori_motion_def *def, char *buf, size_t size, json_t **locks);

// The help lines of the modes, appended to fold's help.
#define CLI_FOLD_MODES_HELP                                                                                   \
    "\n"                                                                                                      \
    "Patterns with several degrees of freedom (docs/kinematics.md, 'Several degrees of freedom'):\n"         \
    "  --percent P     fold every crease toward its target (edges_foldAngle or SVG opacity; +-180 by\n"       \
    "                  assignment where absent) by projecting onto the rigid motions, and stop P\n"        \
    "                  percent (0-100) of the way along that motion (Origami Simulator's slider;\n"         \
    "                  progress = 1 - distance to the targets / distance at the start); reports how\n"     \
    "                  far each crease got\n"                                                              \
    "  --drive E1,E2,... --to A1,A2,...   drive several creases together (the rest solved); creases\n"     \
    "                  by index or @x,y as for --lock (--drive @0.5,0.25,12: two creases)\n"                \
    "  --ratio R1,R2,...  with one --to A: crease Ei goes to Ri x A degrees\n"                               \
    "  --lock auto     lock the creases a rank-revealing QR of the Jacobian leaves over (one degree\n"       \
    "                  of freedom per drive); an underdetermined fold suggests such a set\n"                \
    "  --symmetric     keep creases that the pattern's symmetries map onto each other at equal angles\n"    \
    "  the modes check every step for self-collision as the ordinary fold does (--no-collisions,\n"         \
    "                  --clearance D; verdict collision, stopping at the last clean step)\n"              \
    "  with a mode, --json prints {mode, verdict, reason, collision, stop_edge, symmetry, locked, drives,\n"           \
    "                  creases: [{edge, start_deg, target_deg, goal_deg, reached_deg, fraction}],\n"         \
    "                  against_assignment: [{edge, assignment, angle_deg}],\n"                            \
    "                  frames: [{progress, fold_angles_deg, residual}], stats: {steps, rejected_steps,\n"   \
    "                  newton_iterations, held_at_180, max_residual}}; -o writes the\n"                    \
    "                  motion up to where it stops (titled partial when the goal is not reached)\n"

#endif
