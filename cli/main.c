// orikin: the command-line tool. The process set-up (signal handlers, one OpenBLAS thread) around
// cli_main (cli/dispatch.c: the command table, help, staged outputs).
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <string.h>

#include <cblas.h>

#include "cli.h"

// SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGXFSZ (file size limit): remove the temporary
// files of outputs being written (the library tracks them; ori_file_remove_temporaries is
// async-signal-safe), then die of the signal as if unhandled, so the shell sees the usual status.
static void on_signal(int sig)
{
    ori_file_remove_temporaries();
    signal(sig, SIG_DFL);
    raise(sig);
}

static void install_signal_handlers(void)
{
    static const int sigs[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGXFSZ};
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; ++i) {
        struct sigaction old;
        // A signal ignored by the parent (nohup, a background job's SIGINT) stays ignored.
        if (sigaction(sigs[i], NULL, &old) == 0 && old.sa_handler == SIG_IGN) continue;
        sigaction(sigs[i], &sa, NULL);
    }
}

int main(int argc, char **argv)
{
    install_signal_handlers();
    // Output must not depend on the machine: OpenBLAS splits dense products (the SVDs of dof,
    // the dense corrector) over its threads in an order that changes the last digits.
    openblas_set_num_threads(1);
    return cli_main(argc, argv);
}
