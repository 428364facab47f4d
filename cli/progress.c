// Progress on stderr (see progress.h).
#define _POSIX_C_SOURCE 200809L
#include "progress.h"

#include <stdio.h>
#include <time.h>
#include <unistd.h>

// Nothing is shown for operations shorter than this (seconds), and a terminal bar is redrawn
// at most this often.
#define PROGRESS_DELAY_S 1.0
#define PROGRESS_REDRAW_S 0.1
#define PROGRESS_BAR_WIDTH 30

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void cli_progress_begin(cli_progress *p, const char *cmd, const char *label)
{
    p->cmd = cmd;
    p->label = label;
    p->start = now_s();
    p->last_draw = 0.0;
    p->last_decile = -1;
    p->tty = isatty(fileno(stderr)) != 0;
    p->shown = false;
    p->quiet = false;
}

bool cli_progress_update(cli_progress *p, double fraction)
{
    if (p->quiet) return true;
    if (!(fraction >= 0.0)) fraction = 0.0; // also NaN
    if (fraction > 1.0) fraction = 1.0;
    double t = now_s();
    double elapsed = t - p->start;
    if (elapsed < PROGRESS_DELAY_S) return true;
    if (p->tty) {
        if (p->shown && t - p->last_draw < PROGRESS_REDRAW_S && fraction < 1.0) return true;
        int filled = (int)(fraction * PROGRESS_BAR_WIDTH + 0.5);
        char bar[PROGRESS_BAR_WIDTH + 1];
        for (int i = 0; i < PROGRESS_BAR_WIDTH; ++i) bar[i] = i < filled ? '#' : '.';
        bar[PROGRESS_BAR_WIDTH] = '\0';
        double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
        fprintf(stderr, "\rorikin %s: %s [%s] %3d%% %.1fs (~%.0fs left) ", p->cmd, p->label, bar,
                (int)(fraction * 100.0), elapsed, eta);
        fflush(stderr);
        p->last_draw = t;
        p->shown = true;
    } else {
        int decile = (int)(fraction * 10.0);
        if (decile > p->last_decile && decile < 10) {
            fprintf(stderr, "orikin %s: %s %d%% (%.1fs)\n", p->cmd, p->label, decile * 10, elapsed);
            p->last_decile = decile;
            p->shown = true;
        }
    }
    return true;
}

bool cli_progress_fn(double fraction, void *user) { return cli_progress_update(user, fraction); }

void cli_progress_end(cli_progress *p)
{
    if (p->quiet || !p->shown) return;
    double elapsed = now_s() - p->start;
    if (p->tty) {
        cli_progress_update(p, 1.0);
        fputc('\n', stderr);
    } else {
        fprintf(stderr, "orikin %s: %s done (%.1fs)\n", p->cmd, p->label, elapsed);
    }
    p->shown = false;
}

bool cli_deadline_fn(double fraction, void *user)
{
    cli_deadline *d = user;
    cli_progress_update(&d->bar, fraction);
    if (d->seconds > 0.0 && now_s() - d->bar.start > d->seconds) d->expired = true;
    return !d->expired;
}

void cli_deadline_begin(cli_deadline *d, const char *cmd, const char *label, double seconds)
{
    cli_progress_begin(&d->bar, cmd, label);
    d->seconds = seconds;
    d->expired = false;
}
