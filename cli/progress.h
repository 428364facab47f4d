// Progress on stderr for anything that may run over a second: nothing for short runs, a bar
// redrawn in place when stderr is a terminal, and a line every 10 % otherwise (logs stay short).
#ifndef ORI_CLI_PROGRESS_H
#define ORI_CLI_PROGRESS_H

#include <stdbool.h>

typedef struct cli_progress {
    const char *cmd;   // "fold": prefix of every line
    const char *label; // what runs: "solving", "writing frames"
    double start;      // monotonic seconds at begin
    double last_draw;  // when the bar was last drawn
    int last_decile;   // last 10 % mark printed (non-terminal output)
    bool tty;          // stderr is a terminal
    bool shown;        // something was printed (end finishes the line)
    bool quiet;        // never print (--quiet, or JSON-only consumers that ask for silence)
} cli_progress;

// Start timing an operation; nothing is printed before it has run for a second.
void cli_progress_begin(cli_progress *p, const char *cmd, const char *label);
// Report the fraction done (0 … 1). Always returns true: usable directly as an
// ori_progress_fn through cli_progress_fn.
bool cli_progress_update(cli_progress *p, double fraction);
// An ori_progress_fn whose user pointer is a cli_progress.
bool cli_progress_fn(double fraction, void *user);
// Finish: completes the bar (or prints the elapsed time) when anything was shown.
void cli_progress_end(cli_progress *p);

// A progress bar with a time budget (--timeout): the ori_progress_fn cli_deadline_fn draws the
// bar and cancels the operation (returns false) once `seconds` have passed since the bar began
// (seconds ≤ 0: no budget). The library then ends with a partial answer.
typedef struct cli_deadline {
    cli_progress bar;
    double seconds;
    bool expired; // the budget ran out
} cli_deadline;
bool cli_deadline_fn(double fraction, void *user);
// Start a deadline: the bar (cli_progress_begin) and a budget of `seconds` (≤ 0: none), not expired.
void cli_deadline_begin(cli_deadline *d, const char *cmd, const char *label, double seconds);

#endif
