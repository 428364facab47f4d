// A guard against runaway output: a command that would write more than CLI_GUARD_MAX_FRAMES
// frames or CLI_GUARD_MAX_BYTES bytes asks for --force (a usage error, exit 2, naming it).
#ifndef ORI_CLI_OUTPUT_GUARD_H
#define ORI_CLI_OUTPUT_GUARD_H

#include <stdbool.h>

#define CLI_GUARD_MAX_FRAMES 10000
#define CLI_GUARD_MAX_BYTES 1e9
#define CLI_GUARD_MAX_SOLVES 1000000

// Remove --force from argv (compacting it, *argc updated); *force says whether it was there.
// Given twice: usage error, returns CLI_EXIT_USAGE; else CLI_EXIT_OK.
int cli_guard_strip(const char *cmd, int *argc, char **argv, bool *force);
// With frames output frames of about bytes bytes in all (estimates made before the run): the
// usage error "orikin CMD: this run would write N frames (about X GB): add --force to write
// them" unless force; CLI_EXIT_OK otherwise.
int cli_guard_check(const char *cmd, double frames, double bytes, bool force);
// With solves exact solves asked for (an estimate made before the run): the usage error "orikin
// CMD: this run would solve N states (more than CLI_GUARD_MAX_SOLVES): a larger OPTION, or add
// --force" unless force; CLI_EXIT_OK otherwise.
int cli_guard_solves(const char *cmd, double solves, const char *option, bool force);

#endif
