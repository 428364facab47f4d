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
    CLI_EXIT_PARTIAL = 5,  // stopped at a budget (--limit, --timeout, Ctrl-C of a search): the answer is partial
};

// Run the command line argv[0..argc) (argv[0] the program, argv[1] the command) in-process and
// return its exit code (enum cli_exit): help and --version, the command's outputs staged and
// committed together when it succeeds, stdout flushed (cli_finish). Never calls exit(); the
// caller sets up signals and threads (cli/main.c). Defined in cli/dispatch.c.
int cli_main(int argc, char **argv);

// A subcommand: cli/cmd_<id>.c defines `const cli_command cli_cmd_<id>`.
typedef struct cli_command {
    const char *name;     // as typed: "mv-count"
    const char *summary;  // one line for `orikin -h`
    const char *help;     // full help: synopsis, paragraph, options, example
    int (*run)(int argc, char **argv); // argv[0] is the command name
    const char *help_more; // more help printed after help, or NULL (C99 caps a literal at 4095)
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
// The usage error for a --lock-style list cli_parse_int_list refused: names the limit when
// the list has more than cap entries, else the expected form. Returns CLI_EXIT_USAGE.
int cli_int_list_usage(const char *cmd, const char *opt, const char *value, int cap);
int cli_parse_int_list(const char *s, int *out, int cap);
// The assignment of a new crease: one letter, M, V, F or U.
bool cli_parse_crease_assignment(const char *s, ori_assignment *out);

// The value after option argv[*i] (advancing *i); NULL (after a usage message) when missing.
const char *cli_option_value(const char *cmd, int argc, char **argv, int *i);
// The frame number ≥ 0 after --frame (argv[*i], advancing *i) into *frame: CLI_EXIT_OK, or
// CLI_EXIT_USAGE after a usage message.
int cli_option_frame(const char *cmd, int argc, char **argv, int *i, int *frame);

// Load a FOLD file and the pattern of a frame; on failure print the error and return
// CLI_EXIT_INPUT (with *doc and *pattern NULL), else CLI_EXIT_OK. A frame the file does not have
// is an out-of-range command-line value: "orikin CMD: FILE: --frame N: frame N does not exist
// (frames 0 to M)", CLI_EXIT_USAGE.
int cli_load_pattern(const char *cmd, const char *path, int frame, bool weld, ori_fold **doc,
                     ori_pattern **pattern);

// Write the pattern into frame 0 of doc and save the document to out atomically, or print the
// FOLD text on stdout when out is NULL or "-"; an out ending in .svg, .cp or .opx is an export
// of the pattern in that format. Prints the error and returns its exit code on failure (3).
int cli_write_pattern(const char *cmd, ori_fold *doc, const ori_pattern *pattern, const char *out);
// A face given by name ("Obj12") or FOLD index ("3"); prints an input error naming the file
// and returns CLI_EXIT_INPUT when there is none, else CLI_EXIT_OK with *face set.
int cli_find_face(const char *cmd, const char *file, const ori_pattern *pattern, const char *spec, int *face);

// --- conventions shared by every command (docs/conventions.md) --------------------------------

// A single-valued option given twice is a usage error. Declare `cli_seen seen = {0};` in the
// command and guard each single-valued option with cli_once (or take its value with
// cli_option_once); flags (--json) may repeat.
//     } else if (strcmp(argv[i], "--fix") == 0) {
//         if (!(v = cli_option_once(cmd, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
typedef struct cli_seen {
    const char *names[48];
    int count;
} cli_seen;
// Record option name ("-o" counts as "--output"); false after the usage error "NAME given
// twice" when it was already given.
bool cli_once(const char *cmd, cli_seen *seen, const char *name);
// The value of the single-valued option argv[*i] (advancing *i), or NULL after a usage message
// when the value is missing or the option was already given.
const char *cli_option_once(const char *cmd, int argc, char **argv, int *i, cli_seen *seen);
// cli_option_frame for a --frame given at most once.
int cli_option_frame_once(const char *cmd, int argc, char **argv, int *i, cli_seen *seen, int *frame);

// A command-line value out of range for the file it refers to (a face, edge or frame the file
// does not have) or for what it constructs (file NULL): "orikin CMD: FILE: OPTION: message" on
// stderr, one line; returns CLI_EXIT_USAGE.
int cli_value_fail(const char *cmd, const char *file, const char *option, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
// A face given by name ("Obj12") or FOLD index ("3") for option (e.g. "--face"): CLI_EXIT_OK
// with *face set, else CLI_EXIT_USAGE after cli_value_fail (a face the file does not have).
int cli_find_face_option(const char *cmd, const char *file, const ori_pattern *pattern, const char *option,
                         const char *spec, int *face);

// --- reading a pattern: FOLD, SVG, OPX and CP, one set of options -----------------------------

// The input options of every command that reads a pattern (CLI_INPUT_HELP lists them):
// --frame N and --weld (FOLD), --tolerance REL, --gaps REL, --flatten-curves N, --keep-collinear
// and --keep-holes (drawings). Initialise with cli_input_init.
typedef struct cli_input {
    int frame;
    bool frame_given, weld;
    ori_import_def import;
    const char *import_option; // the first drawing-only option given (NULL: none)
    ori_import_stats stats;    // after cli_input_load of a drawing: what the import found
    bool drawing;              // after cli_input_load: the file was a drawing (SVG, OPX, CP)
} cli_input;
void cli_input_init(cli_input *in);
// When argv[*i] is an input option: parse it (advancing *i) and return 1; 0 when it is not one;
// -CLI_EXIT_USAGE after a usage message (bad value, given twice).
int cli_input_option(const char *cmd, int argc, char **argv, int *i, cli_input *in, cli_seen *seen);
// Load FILE by its extension: a FOLD document and the pattern of --frame, or a drawing (SVG,
// OPX, CP) planarised into a new FOLD document (frame 0, frame_classes creasePattern), with its
// warnings on stderr: elements skipped, gaps closed, crease ends left dangling, separate pieces
// (each with an example and what would fix it). Options that do not apply to the file's kind
// are usage errors. Returns CLI_EXIT_OK, or the exit code after printing the error.
int cli_input_load(const char *cmd, const char *path, cli_input *in, ori_fold **doc, ori_pattern **pattern);
// The help lines of the input options, for a command's -h text.
#define CLI_INPUT_HELP CLI_INPUT_HELP_FOLD CLI_INPUT_HELP_TOLERANCE CLI_INPUT_HELP_DRAWING
// The same in parts, for a command whose own --tolerance means something else (check, layers):
// it reads drawings with the default weld tolerance.
#define CLI_INPUT_HELP_FOLD                                                                                \
    "  --frame N          FOLD input: frame to read (0 = top level, k = file_frames[k-1]); default 0\n"    \
    "  --weld             FOLD input: merge vertices closer than the length tolerance\n"
#define CLI_INPUT_HELP_TOLERANCE                                                                           \
    "  --tolerance REL    drawing input: weld points closer than REL x the drawing's size (default\n"     \
    "                     5e-5)\n"
#define CLI_INPUT_HELP_DRAWING                                                                             \
    "  --gaps REL|auto    drawing input: join crease ends within REL x the drawing's size of another\n"   \
    "                     line (auto, the default: the width the lines are drawn with; 0: off)\n"        \
    "  --flatten-curves N SVG input: draw each curve, arc, circle or ellipse in a crease colour as N\n"   \
    "                     straight creases (an approximation, to view and check curved-crease\n"         \
    "                     drawings; default: refused, a crease is straight)\n"                           \
    "  --keep-collinear   drawing input: keep vertices that only join two collinear edges\n"             \
    "  --keep-holes       drawing input: keep faces bounded only by boundary lines (holes)\n"

// --- writing a pattern and the summary ----------------------------------------------------------

// cli_write_pattern for a pattern read with cli_input_load: with --frame N the output is that
// frame alone (ori_fold_extract_frame: *doc is replaced), as convert --frame writes it.
int cli_write_frame_pattern(const char *cmd, ori_fold **doc, const cli_input *in, const ori_pattern *pattern,
                            const char *out);

// Commands that produce a pattern (new, apply, edit, crease, convert, generate) write it to
// -o FILE and print a one-line summary on stdout, or with --json the summary as one JSON object;
// without -o (or with -o -) the FOLD text goes to stdout and nothing else. --json needs -o: the
// check, CLI_EXIT_USAGE after a message, else CLI_EXIT_OK.
int cli_check_json_output(const char *cmd, const char *out, bool json);
// Whether out means stdout (NULL or "-").
bool cli_is_stdout(const char *out);
// The counts of a pattern into a JSON object: vertices, edges, faces, edges_by_assignment.
void cli_json_counts(json_t *obj, const ori_pattern *pattern);
// Print the summary: with json, obj as compact JSON (released); else the text line (obj released).
void cli_print_summary(bool json, json_t *obj, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

// Print a jansson value as JSON (shortest exact numbers) on stdout and release it.
void cli_print_json(json_t *value);
// Flush stdout; when that fails (full disk, closed pipe) print "orikin CMD: stdout: cannot
// write: why" and return CLI_EXIT_INPUT (3, as for a file that cannot be written), else code.
int cli_finish(int code);
// The command name cli_finish puts in its message (main sets it before running a command).
void cli_set_command(const char *cmd);

#endif
