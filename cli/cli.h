// Shared pieces of the orikin command-line tool: the command record, exit codes, argument
// parsing and error reporting. Uses only the public <orikin/...> headers.
#ifndef ORI_CLI_H
#define ORI_CLI_H

#include <orikin/orikin.h>

#include <jansson.h>
#include <stdbool.h>
#include <stdio.h>

// Exit codes of every command.
enum cli_exit {
    CLI_EXIT_OK = 0,       // done; checked and positive
    CLI_EXIT_NEGATIVE = 1, // checked and negative (not foldable, invalid, collision)
    CLI_EXIT_USAGE = 2,    // bad command line
    CLI_EXIT_INPUT = 3,    // bad input file or value
    CLI_EXIT_INTERNAL = 4, // internal failure
};

// A subcommand: cli/cmd_<id>.c defines `const cli_command cli_cmd_<id>`.
typedef struct cli_command {
    const char *name;     // as typed: "mv-count"
    const char *summary;  // one line for `orikin -h`
    const char *help;     // full help: synopsis, paragraph, options, example
    int (*run)(int argc, char **argv); // argv[0] is the command name
} cli_command;

// True for -h / --help.
bool cli_is_help(const char *arg);
// Print a command's help to stdout; returns CLI_EXIT_OK.
int cli_print_help(const cli_command *cmd);
// Usage error to stderr ("orikin CMD: msg" + hint); returns CLI_EXIT_USAGE.
int cli_usage(const char *cmd, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
// Input error to stderr ("orikin CMD: FILE: where: msg"); returns CLI_EXIT_INPUT.
int cli_input_error(const char *cmd, const char *file, const ori_error *error);
// Input error with a free message ("orikin CMD: FILE: msg"); returns CLI_EXIT_INPUT.
int cli_input_fail(const char *cmd, const char *file, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

// Number parsing: the whole string must be consumed and the value finite.
bool cli_parse_double(const char *s, double *out);
bool cli_parse_int(const char *s, int *out);
// Exactly n comma-separated numbers ("x,y" or "x,y,dx,dy").
bool cli_parse_doubles(const char *s, double *out, int n);
// A comma-separated list of integers; returns the count (≤ cap) or -1 on a bad list.
int cli_parse_int_list(const char *s, int *out, int cap);
// The assignment of a new crease: one letter, M, V, F or U.
bool cli_parse_crease_assignment(const char *s, ori_assignment *out);

// The value after option argv[*i] (advancing *i); NULL (after a usage message) when missing.
const char *cli_option_value(const char *cmd, int argc, char **argv, int *i);
// The frame number ≥ 0 after --frame (argv[*i], advancing *i) into *frame: CLI_EXIT_OK, or
// CLI_EXIT_USAGE after a usage message.
int cli_option_frame(const char *cmd, int argc, char **argv, int *i, int *frame);

// Load a FOLD file and the pattern of a frame; on failure print the error and return
// CLI_EXIT_INPUT (with *doc and *pattern NULL), else CLI_EXIT_OK.
int cli_load_pattern(const char *cmd, const char *path, int frame, bool weld, ori_fold **doc,
                     ori_pattern **pattern);

// Write the pattern into frame 0 of doc and save the document to out atomically, or print the
// FOLD text on stdout when out is NULL. Prints the error and returns its exit code on failure.
int cli_write_pattern(const char *cmd, ori_fold *doc, const ori_pattern *pattern, const char *out);
// A face given by name ("Obj12") or FOLD index ("3"); prints an input error naming the file
// and returns CLI_EXIT_INPUT when there is none, else CLI_EXIT_OK with *face set.
int cli_find_face(const char *cmd, const char *file, const ori_pattern *pattern, const char *spec, int *face);

// Print a jansson value as JSON (shortest exact numbers) on stdout and release it.
void cli_print_json(json_t *value);
// Flush stdout; when that fails (full disk, closed pipe) print "orikin CMD: stdout: cannot
// write: why" and return CLI_EXIT_INPUT (3, as for a file that cannot be written), else code.
int cli_finish(int code);
// The command name cli_finish puts in its message (main sets it before running a command).
void cli_set_command(const char *cmd);

#endif
