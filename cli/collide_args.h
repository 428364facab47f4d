// Collision checks in the CLI: the glue that lets `orikin fold` and `orikin sequence` check
// their motion (--no-collisions, --clearance D; verdict "collision"). `orikin collide` names its
// one state with state_args.h, as render and export do.
#ifndef ORI_CLI_COLLIDE_ARGS_H
#define ORI_CLI_COLLIDE_ARGS_H

#include <orikin/collision.h>

#include "cli.h"
#include "report.h"

// The collision options of fold and sequence.
typedef struct cli_collide_opts {
    bool skip;           // --no-collisions
    bool has_clearance;  // --clearance D given
    double clearance;    // D (length); 0 by default
    const char *raw;     // the text after --clearance (for the error message)
} cli_collide_opts;

// If argv[*i] is --no-collisions or --clearance D, consume it (advancing *i past its value) and
// return 1; return 0 when it is not one of them; on a usage error print it and return -1.
int cli_collide_option(const char *cmd, int argc, char **argv, int *i, cli_collide_opts *o);
// Take --no-collisions and --clearance D out of argv (compacting it, *argc updated) into *o.
// Returns CLI_EXIT_OK, or CLI_EXIT_USAGE after printing the message.
int cli_collide_strip(const char *cmd, int *argc, char **argv, cli_collide_opts *o);

// Check a solved fold (def as solved) on the mechanism of `flat`. Prints the error and returns
// its exit code on failure (bad clearance: CLI_EXIT_INPUT), else CLI_EXIT_OK with *out filled.
int cli_collide_motion(const char *cmd, const char *path, const cli_collide_opts *o, const ori_pattern *flat,
                       const ori_mechanism *m, const ori_motion_def *def, const ori_motion *mo, cli_collision *out);
// Same for a recorded sequence.
int cli_collide_record(const char *cmd, const char *path, const cli_collide_opts *o, const ori_pattern *flat,
                       const ori_record *r, cli_collision *out);

// Same for a fold with several degrees of freedom (fold_modes.c), with the creases it locked:
// the event's drive_rad is the progress (0 … 1) at first contact.
int cli_collide_multifold(const char *cmd, const char *path, const cli_collide_opts *o, const ori_pattern *flat,
                          const ori_multifold *mf, const int *locked, int locked_count, cli_collision *out);

// cli_collision, cli_collides, cli_collide_frames, cli_collision_json and cli_collision_describe
// are in report.h (shared with the studio's server).

#endif
