// Output guard (see output_guard.h).
#include "output_guard.h"

#include <string.h>

#include "cli.h"

int cli_guard_strip(const char *cmd, int *argc, char **argv, bool *force)
{
    *force = false;
    int w = 1;
    for (int i = 1; i < *argc; ++i) {
        if (strcmp(argv[i], "--force") == 0) {
            if (*force) return cli_usage(cmd, "--force given twice");
            *force = true;
            continue;
        }
        argv[w++] = argv[i];
    }
    *argc = w;
    argv[w] = NULL;
    return CLI_EXIT_OK;
}

int cli_guard_check(const char *cmd, double frames, double bytes, bool force)
{
    if (force || (frames <= CLI_GUARD_MAX_FRAMES && bytes <= CLI_GUARD_MAX_BYTES)) return CLI_EXIT_OK;
    if (frames > CLI_GUARD_MAX_FRAMES)
        return cli_usage(cmd, "this run would write %.0f frames (more than %d): add --force to write them", frames,
                         CLI_GUARD_MAX_FRAMES);
    return cli_usage(cmd, "this run would write about %.2g GB (more than %.0f GB): add --force to write it", bytes / 1e9,
                     CLI_GUARD_MAX_BYTES / 1e9);
}

int cli_guard_solves(const char *cmd, double solves, const char *option, bool force)
{
    if (force || solves <= CLI_GUARD_MAX_SOLVES) return CLI_EXIT_OK;
    return cli_usage(cmd, "this run would solve %.3g states (more than %d): a larger %s, or add --force", solves,
                     CLI_GUARD_MAX_SOLVES, option);
}
