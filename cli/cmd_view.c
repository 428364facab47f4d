// orikin view: the studio — serve the browser viewer and editor on loopback and open it.
#define _DEFAULT_SOURCE // mkdtemp
#define _POSIX_C_SOURCE 200809L
#include <arpa/inet.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli.h"
#include "server/studio.h"

// Open a page in the desktop's browser (xdg-open) without waiting for it and without failing
// when there is none: a detached grandchild with its output discarded, and the signals the
// server blocks for itself (INT, TERM, HUP) unblocked and at their defaults again.
static void open_browser(const char *target)
{
    pid_t child = fork();
    if (child < 0) return;
    if (child == 0) {
        setsid();
        if (fork() == 0) {
            sigset_t none;
            sigemptyset(&none);
            sigprocmask(SIG_SETMASK, &none, NULL);
            signal(SIGINT, SIG_DFL), signal(SIGTERM, SIG_DFL), signal(SIGHUP, SIG_DFL), signal(SIGPIPE, SIG_DFL);
            int null = open("/dev/null", O_RDWR);
            if (null >= 0) {
                dup2(null, STDIN_FILENO);
                dup2(null, STDOUT_FILENO);
                dup2(null, STDERR_FILENO);
            }
            execlp("xdg-open", "xdg-open", target, (char *)NULL);
            _exit(127);
        }
        _exit(0);
    }
    waitpid(child, NULL, 0);
}

// The URL carries the session token; on a command line (xdg-open URL, then the browser's own)
// any local user reads it in /proc/PID/cmdline. So the browser is handed a page instead, in a
// directory of ours (mode 0700, in $XDG_RUNTIME_DIR or /tmp) and readable by us alone (0600),
// that sends it on to the URL: the command lines show only the page's path. The page is
// removed when the studio stops. Returns false (nothing left behind) when it cannot be made.
typedef struct launch_page {
    char dir[512], path[560];
} launch_page;

static bool launch_page_write(launch_page *lp, const char *url)
{
    const char *base = getenv("XDG_RUNTIME_DIR");
    if (!base || base[0] != '/') base = "/tmp";
    snprintf(lp->dir, sizeof lp->dir, "%s/orikin-view-XXXXXX", base);
    if (!mkdtemp(lp->dir)) return false; // mode 0700
    snprintf(lp->path, sizeof lp->path, "%s/open.html", lp->dir);
    int fd = open(lp->path, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0600);
    if (fd < 0) {
        rmdir(lp->dir);
        return false;
    }
    char page[1024];
    int n = snprintf(page, sizeof page,
                     "<!doctype html><meta charset=\"utf-8\"><meta name=\"referrer\" content=\"no-referrer\">"
                     "<meta http-equiv=\"refresh\" content=\"0;url=%s\"><title>orikin studio</title>"
                     "<p><a href=\"%s\">Open the orikin studio</a></p>\n", url, url);
    bool ok = n > 0 && (size_t)n < sizeof page && write(fd, page, (size_t)n) == n;
    if (close(fd) != 0) ok = false;
    if (!ok) {
        unlink(lp->path);
        rmdir(lp->dir);
    }
    return ok;
}

static void launch_page_remove(const launch_page *lp)
{
    unlink(lp->path);
    rmdir(lp->dir);
}

static bool is_loopback(const char *host)
{
    return strcmp(host, "127.0.0.1") == 0 || strcmp(host, "::1") == 0 || strncmp(host, "127.", 4) == 0;
}

static int run(int argc, char **argv)
{
    const char *path = NULL, *host = NULL;
    int port = 0;
    bool has_port = false, no_browser = false, no_autosave = false;
    for (int i = 1; i < argc; ++i) {
        const char *v;
        if (strcmp(argv[i], "--no-autosave") == 0) {
            no_autosave = true;
        } else if (strcmp(argv[i], "--no-browser") == 0) {
            no_browser = true;
        } else if (strcmp(argv[i], "--port") == 0) {
            if (has_port) return cli_usage("view", "--port given twice");
            if (!(v = cli_option_value("view", argc, argv, &i))) return CLI_EXIT_USAGE;
            if (!cli_parse_int(v, &port) || port < 0 || port > 65535)
                return cli_usage("view", "--port needs a port number from 0 to 65535 (0: any free port), got '%s'", v);
            has_port = true;
        } else if (strcmp(argv[i], "--host") == 0) {
            if (host) return cli_usage("view", "--host given twice");
            if (!(host = cli_option_value("view", argc, argv, &i))) return CLI_EXIT_USAGE;
            unsigned char addr[16];
            if (inet_pton(AF_INET, host, addr) != 1 && inet_pton(AF_INET6, host, addr) != 1)
                return cli_usage("view", "--host needs a numeric address (127.0.0.1, 0.0.0.0, ::1), got '%s'", host);
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            return cli_usage("view", "unknown option %s", argv[i]);
        } else if (!path) {
            path = argv[i];
        } else {
            return cli_usage("view", "one FILE only");
        }
    }
    if (!studio_assets_built()) {
        fprintf(stderr, "orikin view: the studio's web assets were not built into this orikin (node_modules was missing "
                        "when it was built): run make deps, then rebuild\n");
        return CLI_EXIT_INTERNAL;
    }
    studio_def def = studio_default_def();
    def.path = path;
    def.autosave = !no_autosave;
    studio *s = NULL;
    char err[1024];
    if (studio_create(&def, &s, err, sizeof err) != 0) {
        fprintf(stderr, "orikin view: %s\n", err);
        return CLI_EXIT_INPUT;
    }
    char journal[1024];
    if (studio_recovery_pending(s, journal, sizeof journal))
        fprintf(stderr, "orikin view: note: %s holds unsaved edits of an earlier session: the page offers to recover "
                        "or discard them\n", journal);
    char token[2 * STUDIO_TOKEN_BYTES + 1];
    if (!studio_token_make(token, sizeof token)) {
        studio_destroy(s);
        fprintf(stderr, "orikin view: no source of random numbers for the session token\n");
        return CLI_EXIT_INTERNAL;
    }
    // Ctrl-C and TERM are taken by sigwait below: block them before the server's threads exist.
    sigset_t stop;
    sigemptyset(&stop);
    sigaddset(&stop, SIGINT);
    sigaddset(&stop, SIGTERM);
    sigaddset(&stop, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &stop, NULL);
    studio_http *h = studio_http_start(s, host, port, token, err, sizeof err);
    if (!h) {
        studio_destroy(s);
        fprintf(stderr, "orikin view: %s\n", err);
        return CLI_EXIT_INPUT;
    }
    if (host && !is_loopback(host))
        fprintf(stderr, "orikin view: warning: listening on %s, not only on this machine: anyone who can reach it and "
                        "has the URL with its token can read and change the document\n", host);
    char url[256];
    bool v6 = host && strchr(host, ':');
    const char *shown = !host || strcmp(host, "0.0.0.0") == 0 || strcmp(host, "::") == 0 ? "127.0.0.1" : host;
    if (v6 && strcmp(host, "::") != 0) snprintf(url, sizeof url, "http://[%s]:%d/?token=%s", shown, studio_http_port(h), token);
    else snprintf(url, sizeof url, "http://%s:%d/?token=%s", shown, studio_http_port(h), token);
    printf("orikin view: %s\n", url);
    fflush(stdout);
    launch_page lp;
    bool page = false;
    if (!no_browser) {
        page = launch_page_write(&lp, url);
        if (page) open_browser(lp.path);
        else fprintf(stderr, "orikin view: cannot write the page that opens the browser: open the URL above\n");
    }
    int sig = 0;
    sigwait(&stop, &sig);
    if (page) launch_page_remove(&lp);
    studio_http_stop(h);
    if (studio_unsaved(s, journal, sizeof journal))
        fprintf(stderr, "orikin view: note: the document has unsaved edits; they are kept in %s and offered at the next "
                        "orikin view of this file\n", journal);
    studio_destroy(s);
    return CLI_EXIT_OK;
}

const cli_command cli_cmd_view = {
    "view",
    "the studio: author, verify, fold and watch in the browser (a local web app)",
    "usage: orikin view [FILE.fold|.svg|.opx|.cp|SEQ.json] [--port N] [--host ADDR] [--no-browser]\n"
    "                   [--no-autosave]\n"
    "\n"
    "Serve the studio, orikin's browser viewer and editor, on this machine and open it: the\n"
    "crease pattern in 2D with its face tree (collection patterns, axioms, flip, move, remove,\n"
    "undo), the checks drawn on it, the fold specification by clicks (fix a face, drive and\n"
    "lock creases) with the verdict, the 3D view, and the folding manager's slider over a\n"
    "whole fold sequence. Every computation is the library's own. Prints one line with the\n"
    "URL (it carries the session token every request needs) and serves until Ctrl-C. FILE is\n"
    "written only on an explicit Save, which asks first when FILE changed on disk meanwhile;\n"
    "unsaved edits survive a crash in an autosave beside it. Without FILE the studio starts\n"
    "from a blank square.\n"
    "\n"
    "options:\n"
    "  --port N       port to listen on; 0 (the default) picks a free one\n"
    "  --host ADDR    listen on this numeric address instead of 127.0.0.1 (prints a warning:\n"
    "                 other machines can then connect; they still need the token)\n"
    "  --no-browser   do not open a browser (print the URL only)\n"
    "  --no-autosave  keep no journal of unsaved edits (by default they are written to\n"
    "                 .FILE.orikin-autosave beside FILE after every edit and offered at the\n"
    "                 next orikin view of FILE; Save removes it)\n"
    "\n"
    "exit codes: 0 stopped by Ctrl-C, 2 bad command line, 3 bad file or address, 4 the web\n"
    "assets were not built\n"
    "example: orikin view examples/open-corner.seq.json\n",
    run,
    NULL,
};
