// libFuzzer target for the command line's option parsing: the input is an argv, tokens split on
// newline or NUL bytes; the first token names a command of a short list of cheap ones (below),
// the rest are its options and values. "@F0".."@F9" stand for fixed input files (copies of
// examples/patterns/*.fold, two drawings and a fold sequence, in a temporary directory), "@O"
// and "@O.EXT" for an output file in the run's own temporary directory. The command runs in-process through
// cli_main (cli/dispatch.c), the dispatch of the orikin binary, with stdin from /dev/null and
// the CLI's stdout and stderr discarded (fd 2 stays for the sanitizers' reports).
//
// Work stays bounded: commands that serve, spawn jobs or simulate (view, sweep, simulate,
// animate) are not on the list, and an input with a number of magnitude over
// 180 in any token (or comma-separated part of one; 12 for generate) is skipped, so --limit 1e9,
// --size 100000x100000 or a 500 x 500 grid never run; defaults that are much work are bounded
// (bounded_defaults: tolerance gets --samples 8 unless it is given) and counts of work capped
// (option_caps: --samples 16, --threads 2); at most 24 tokens of 200 bytes. fold --compliant
// is skipped: its static solver's bounded search (load steps quartered until 1e-6 of the first,
// each up to max_iterations Newton steps) took 0.4 s in RelWithDebInfo and over 10 s under the
// sanitizers on degree4-vertex.fold (3,076 Newton iterations before "no equilibrium beyond
// 41.8 %"), found by this target's second run; it needs its own target with a smaller budget.
//
// Invariants: no crash, leak or sanitizer report; the exit code is one of the documented ones
// (0 ok, 1 negative, 2 usage, 3 bad input, 5 partial; 4, an internal failure, is a finding);
// nothing is written outside the run's temporary directory: a token with a '/' (an absolute
// path, "..") is skipped, the run's working directory is its temporary directory, the fixed
// inputs are compared with their originals after every run (and an input that names one as an
// output is skipped), and the temporary directory holds nothing beside in/ and run/.
// FUZZ_CLI_ARGS_TRACE=1 prints each run's command and exit code (to see what a corpus reaches).
#define _XOPEN_SOURCE 700
#include <ctype.h>
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cblas.h>

#include "cli.h"

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define MAX_TOKENS 24
#define MAX_TOKEN_BYTES 200
#define MAX_NUMBER 180.0      // degrees go to 180
#define MAX_GENERATE_NUMBER 12.0 // generate's counts and sizes: a 12 x 12 grid at most

static const char *const cheap_commands[] = {
    "apply", "axiom",  "check", "collide", "convert",    "crease", "dof",    "edit",
    "export", "fab",   "fit",   "fold",    "generate",   "info",   "layers", "mv-count",
    "new",   "regularize", "render", "tolerance", "tree", "unfold", "unfold-linkage", "sequence",
    "actuate",
};

// @F0..@F9 (copied with the pattern the sequence names, which @F4 is).
static const char *const input_sources[] = {
    "examples/patterns/degree4-vertex.fold",  "examples/patterns/degree6-vertex.fold",
    "examples/patterns/non-flat-foldable-vertex.fold", "examples/patterns/open-corner-gold.fold",
    "examples/patterns/open-corner.fold",     "examples/patterns/thesis-flap.fold",
    "examples/patterns/two-flaps.fold",       "tests/data/formats/bird.cp",
    "tests/data/formats/gap.svg",             "examples/open-corner.seq.json",
};
#define INPUT_COUNT ((int)(sizeof input_sources / sizeof input_sources[0]))

// Options added when the input does not give them: defaults that are real work (tolerance's
// 1000 Monte Carlo samples take 11 s under the sanitizers; found by this target's first run).
static const struct {
    const char *command, *option, *value;
} bounded_defaults[] = {
    {"tolerance", "--samples", "8"},
};

// Options whose value is a count of work, with a smaller cap than MAX_NUMBER.
static const struct {
    const char *option;
    double max;
} option_caps[] = {
    {"--samples", 16},
    {"--threads", 2},
};

typedef struct fixed_input {
    char path[512];
    char *data;
    size_t size;
} fixed_input;

static char base_dir[256];   // the fuzz target's temporary directory: in/ and run/
static char parent_dir[256];
static char run_dir[300];
static fixed_input inputs[INPUT_COUNT];
static int start_dir = -1; // the working directory libFuzzer started in (its corpus paths)
static char start_path[1024];
static char artifact_arg[1100];
static char *new_argv[256];
static bool trace; // FUZZ_CLI_ARGS_TRACE set: each run's command and exit code on fd 2

static void die(const char *what)
{
    fprintf(stderr, "fuzz_cli_args: %s: %s\n", what, strerror(errno));
    abort();
}

static char *read_file(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap);
    size_t got;
    while (buf && (got = fread(buf + n, 1, cap - n, f)) > 0) {
        n += got;
        if (n == cap) buf = realloc(buf, cap *= 2);
    }
    fclose(f);
    *size = n;
    return buf;
}

static void write_file(const char *path, const char *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(data, 1, size, f) != size || fclose(f) != 0) die(path);
}

static long count_entries(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d) die(dir);
    long n = 0;
    for (struct dirent *e; (e = readdir(d));) ++n;
    closedir(d);
    return n;
}

static int remove_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
    (void)st, (void)flag, (void)ftw;
    return remove(path);
}

// Empty the run directory (the command's outputs, directories too): removed and made again.
static void clear_run_dir(void)
{
    if (nftw(run_dir, remove_entry, 16, FTW_DEPTH | FTW_PHYS) != 0 || mkdir(run_dir, 0700) != 0) die(run_dir);
}

// Each run's working directory is run/, and libFuzzer writes a crash's input while still in it:
// a relative -artifact_prefix (run.sh's) becomes absolute, and without one it is the starting
// directory, libFuzzer's default ("./"). Flags are parsed after LLVMFuzzerInitialize.
static void absolute_artifact_prefix(int *argc, char ***argv)
{
    const char *flag = "-artifact_prefix=";
    size_t flag_len = strlen(flag);
    int n = *argc < 254 ? *argc : 254, given = -1;
    for (int i = 0; i < n; ++i) {
        new_argv[i] = (*argv)[i];
        if (strncmp(new_argv[i], flag, flag_len) == 0) given = i;
    }
    const char *prefix = given >= 0 ? (*argv)[given] + flag_len : "";
    if (prefix[0] == '/') return;
    snprintf(artifact_arg, sizeof artifact_arg, "%s%s/%s", flag, start_path, prefix);
    if (given >= 0) {
        new_argv[given] = artifact_arg;
    } else {
        new_argv[n++] = artifact_arg;
    }
    new_argv[n] = NULL;
    *argc = n;
    *argv = new_argv;
}

static void remove_base_dir(void)
{
    if (start_dir >= 0 && fchdir(start_dir) != 0) return;
    nftw(base_dir, remove_entry, 16, FTW_DEPTH | FTW_PHYS);
}

// mkdir -p of the directories of path.
static void make_parents(char *path)
{
    for (char *slash = strchr(path + 1, '/'); slash; slash = strchr(slash + 1, '/')) {
        *slash = '\0';
        if (mkdir(path, 0700) != 0 && errno != EEXIST) die(path);
        *slash = '/';
    }
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    start_dir = open(".", O_RDONLY | O_DIRECTORY);
    if (start_dir < 0 || !getcwd(start_path, sizeof start_path)) die("working directory");
    absolute_artifact_prefix(argc, argv);
    trace = getenv("FUZZ_CLI_ARGS_TRACE") != NULL;
    openblas_set_num_threads(1);
    const char *tmp = getenv("TMPDIR");
    snprintf(parent_dir, sizeof parent_dir, "%s", tmp && *tmp ? tmp : "/tmp");
    snprintf(base_dir, sizeof base_dir, "%s/fuzz_cli_args.XXXXXX", parent_dir);
    if (!mkdtemp(base_dir)) die("mkdtemp");
    char in_dir[300];
    snprintf(in_dir, sizeof in_dir, "%s/in", base_dir);
    snprintf(run_dir, sizeof run_dir, "%s/run", base_dir);
    if (mkdir(in_dir, 0700) != 0 || mkdir(run_dir, 0700) != 0) die("mkdir");
    for (int i = 0; i < INPUT_COUNT; ++i) {
        char src[512];
        snprintf(src, sizeof src, "%s/%s", ORI_SOURCE_DIR, input_sources[i]);
        inputs[i].data = read_file(src, &inputs[i].size);
        if (!inputs[i].data) die(src);
        // in/ mirrors the source tree: a sequence names its pattern relative to itself.
        snprintf(inputs[i].path, sizeof inputs[i].path, "%s/%s", in_dir, input_sources[i]);
        make_parents(inputs[i].path);
        write_file(inputs[i].path, inputs[i].data, inputs[i].size);
    }
    atexit(remove_base_dir);
    // stdin from /dev/null, stdout discarded; the CLI's stderr discarded through the stream
    // (libFuzzer keeps the stream it started with; the sanitizers write to fd 2).
    int null_in = open("/dev/null", O_RDONLY), null_out = open("/dev/null", O_WRONLY);
    if (null_in < 0 || null_out < 0 || dup2(null_in, 0) < 0 || dup2(null_out, 1) < 0) die("/dev/null");
    close(null_in), close(null_out);
    FILE *quiet = fopen("/dev/null", "w");
    if (!quiet) die("/dev/null");
    stderr = quiet;
    return 0;
}

// A number in a token, or in any comma-separated part of one, of magnitude over MAX_NUMBER.
static bool has_big_number(const char *tok, double max)
{
    for (const char *p = tok; *p;) {
        const char *end = strchr(p, ',');
        size_t n = end ? (size_t)(end - p) : strlen(p);
        char part[MAX_TOKEN_BYTES + 1];
        memcpy(part, p, n);
        part[n] = '\0';
        // Scan each number in the part ("1e9", "x=300", "--grid=500").
        for (const char *q = part; *q; ++q) {
            if ((*q >= '0' && *q <= '9') || *q == '.' || ((*q == 'i' || *q == 'I' || *q == 'n' || *q == 'N') &&
                                                         (q == part || q[-1] == '-' || q[-1] == '+' || q[-1] == '='))) {
                char *stop;
                double v = strtod(q, &stop);
                bool word = !(*q >= '0' && *q <= '9') && *q != '.'; // "inf", "nan": not "info"
                if (stop > q && !(word && isalpha((unsigned char)*stop))) {
                    if (!(fabs(v) <= max)) return true;
                    q = stop - 1;
                } else if (word) {
                    while (isalpha((unsigned char)q[1])) ++q;
                }
            }
        }
        if (!end) break;
        p = end + 1;
    }
    return false;
}

static bool is_output_option(const char *tok)
{
    return strcmp(tok, "-o") == 0 || strncmp(tok, "--out", 5) == 0 || strncmp(tok, "--save", 6) == 0 ||
           strncmp(tok, "--write", 7) == 0 || strncmp(tok, "--db", 4) == 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static char tokens[MAX_TOKENS][MAX_TOKEN_BYTES + 1];
    static char storage[MAX_TOKENS][600];
    char *argv[MAX_TOKENS + 4];
    int count = 0;
    size_t start = 0;
    for (size_t i = 0; i <= size; ++i) {
        if (i < size && data[i] != '\n' && data[i] != '\0') continue;
        size_t n = i - start;
        if (count == MAX_TOKENS || n > MAX_TOKEN_BYTES) return 0;
        memcpy(tokens[count], data + start, n);
        tokens[count][n] = '\0';
        ++count;
        start = i + 1;
    }
    if (count == 0) return 0;
    bool known = false;
    for (size_t c = 0; c < sizeof cheap_commands / sizeof cheap_commands[0]; ++c)
        if (strcmp(tokens[0], cheap_commands[c]) == 0) known = true;
    if (!known) return 0;
    argv[0] = "orikin";
    double max = strcmp(tokens[0], "generate") == 0 ? MAX_GENERATE_NUMBER : MAX_NUMBER;
    for (int t = 0; t < count; ++t) {
        const char *tok = tokens[t];
        double cap = max;
        for (size_t c = 0; c < sizeof option_caps / sizeof option_caps[0]; ++c) {
            size_t n = strlen(option_caps[c].option);
            if ((t > 0 && strcmp(tokens[t - 1], option_caps[c].option) == 0) ||
                (strncmp(tok, option_caps[c].option, n) == 0 && tok[n] == '='))
                cap = option_caps[c].max;
        }
        if (strchr(tok, '/') || has_big_number(tok, cap)) return 0;
        if (strncmp(tok, "--compliant", 11) == 0) return 0; // see the header comment
        if (tok[0] == '@' && tok[1] == 'F' && tok[2] >= '0' && tok[2] <= '9' && tok[3] == '\0') {
            // An input named as the value of an output option would be overwritten: skipped.
            if (t > 0 && is_output_option(tokens[t - 1])) return 0;
            argv[t + 1] = inputs[tok[2] - '0'].path;
        } else if (tok[0] == '@' && tok[1] == 'O' && (tok[2] == '\0' || tok[2] == '.')) {
            snprintf(storage[t], sizeof storage[t], "%s/out%s", run_dir, tok + 2);
            argv[t + 1] = storage[t];
        } else {
            argv[t + 1] = tokens[t];
        }
        if (strchr(argv[t + 1], '=') && strchr(argv[t + 1], '@')) return 0; // --out=@F0 and the like
    }
    int argc = count + 1;
    for (size_t d = 0; d < sizeof bounded_defaults / sizeof bounded_defaults[0]; ++d) {
        if (strcmp(tokens[0], bounded_defaults[d].command) != 0) continue;
        bool given = false;
        for (int t = 1; t < count; ++t)
            if (strncmp(tokens[t], bounded_defaults[d].option, strlen(bounded_defaults[d].option)) == 0) given = true;
        if (!given && argc + 2 <= MAX_TOKENS + 1) {
            argv[argc++] = (char *)bounded_defaults[d].option;
            argv[argc++] = (char *)bounded_defaults[d].value;
        }
    }
    argv[argc] = NULL;

    if (chdir(run_dir) != 0) die(run_dir);
    int rc = cli_main(argc, argv);
    if (fchdir(start_dir) != 0) die("working directory");
    if (trace) {
        char line[160];
        int len = snprintf(line, sizeof line, "fuzz_cli_args: %s: exit %d\n", tokens[0], rc);
        (void)!write(2, line, (size_t)len);
    }
    fflush(stdout);
    fflush(stderr);
    if (rc != CLI_EXIT_OK && rc != CLI_EXIT_NEGATIVE && rc != CLI_EXIT_USAGE && rc != CLI_EXIT_INPUT &&
        rc != CLI_EXIT_PARTIAL) {
        char msg[96];
        int len = snprintf(msg, sizeof msg, "fuzz_cli_args: exit code %d is not a documented one\n", rc);
        (void)!write(2, msg, (size_t)len);
        abort();
    }
    for (int i = 0; i < INPUT_COUNT; ++i) {
        size_t n = 0;
        char *now = read_file(inputs[i].path, &n);
        if (!now || n != inputs[i].size || memcmp(now, inputs[i].data, n) != 0) {
            (void)!write(2, "fuzz_cli_args: a fixed input file was changed\n", 46);
            abort();
        }
        free(now);
    }
    if (count_entries(base_dir) != 4) { // ".", "..", in, run
        (void)!write(2, "fuzz_cli_args: a file was written beside in/ and run/\n", 55);
        abort();
    }
    clear_run_dir();
    return 0;
}
