// orikin-layers-mpi: the layer-order count of one crease pattern on MPI ranks (docs/sweep.md,
// docs/layers.md). Every rank reads the file and sets up the same layer problem (the set-up is
// deterministic, so the components are the same everywhere); the independent components are
// then counted across the ranks: rank 0 hands them out one at a time, largest first, to the
// worker ranks as they ask, and counts components itself on a thread of its own while its main
// thread serves the requests. The exact counts (decimal) come back to rank 0, which installs
// them (ori_layers_set_counts) and prints what `orikin layers FILE --count [--json]` prints.
//     mpirun -np 4 orikin-layers-mpi FILE.fold [--json] [--limit N] [--tolerance R] [--frame N] [--timing]
#define _POSIX_C_SOURCE 200809L
#include <mpi.h>

#include <cblas.h>
#include <inttypes.h>
#include <jansson.h>
#include <orikin/orikin.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "report.h"

#define PROG "orikin-layers-mpi"

// Exit codes (as cli/cli.h).
enum { EXIT_OK = 0, EXIT_NEGATIVE = 1, EXIT_USAGE = 2, EXIT_INPUT = 3, EXIT_PARTIAL = 5 };

enum { TAG_RESULT = 1, TAG_WORK };

// A waiting rank 0 polls this often rather than spinning in MPI_Probe (a spinning rank takes
// the core a counting one needs when ranks share cores).
#define LAYERS_MPI_POLL_NS 50000

// --- the components and their counts (rank 0) ------------------------------------------------

typedef struct board {
    const ori_layers *L;
    pthread_mutex_t lock;
    int next;        // next component to hand out (counting down to 1); 0 when all are out
    char **states;   // per component once counted
    bool limited;
    int failed;      // a component that could not be counted (never expected), else 0
} board;

static int take(board *b)
{
    pthread_mutex_lock(&b->lock);
    int j = b->next > 0 ? b->next-- : 0;
    pthread_mutex_unlock(&b->lock);
    return j;
}

static void put(board *b, int j, char *states, bool limited)
{
    pthread_mutex_lock(&b->lock);
    free(b->states[j]);
    b->states[j] = states;
    b->limited |= limited;
    pthread_mutex_unlock(&b->lock);
}

// A component's count as a malloc'd string (the library's buffer copied).
static char *count_one(const ori_layers *L, int j, bool *limited, bool *ok)
{
    char *s = NULL;
    ori_error err;
    ori_error_clear(&err);
    *ok = ori_layers_count_component(L, j, &s, limited, &err) == ORI_OK;
    char *copy = strdup(s ? s : "");
    ori_buffer_free(s);
    return copy;
}

static void *rank0_counter(void *arg)
{
    board *b = arg;
    for (int j; (j = take(b)) > 0;) {
        bool limited = false, ok = true;
        char *s = count_one(b->L, j, &limited, &ok);
        if (!ok) b->failed = j;
        put(b, j, s, limited);
    }
    return NULL;
}

static void send_work(board *b, int rank, int *stopped)
{
    int j = take(b);
    MPI_Send(&j, 1, MPI_INT, rank, TAG_WORK, MPI_COMM_WORLD);
    if (j == 0) (*stopped)++;
}

// Rank 0: count on a thread while the main thread (the only one calling MPI) serves the
// workers: a worker's message carries its last result (component, limited, decimal count;
// component 0 for its first request) and is answered with the next component, 0 to stop.
static void rank0_count(board *b, int size)
{
    pthread_t tid;
    bool threaded = pthread_create(&tid, NULL, rank0_counter, b) == 0;
    if (!threaded) rank0_counter(b);
    int stopped = 0;
    while (stopped < size - 1) {
        int flag = 0;
        MPI_Status st;
        MPI_Iprobe(MPI_ANY_SOURCE, TAG_RESULT, MPI_COMM_WORLD, &flag, &st);
        if (!flag) {
            struct timespec ts = {0, LAYERS_MPI_POLL_NS};
            nanosleep(&ts, NULL);
            continue;
        }
        int len = 0;
        MPI_Get_count(&st, MPI_CHAR, &len);
        char *msg = malloc((size_t)len + 1);
        MPI_Recv(msg, len, MPI_CHAR, st.MPI_SOURCE, TAG_RESULT, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        msg[len] = '\0';
        int j = 0, lim = 0, ok = 0, at = 0;
        if (sscanf(msg, "%d %d %d %n", &j, &lim, &ok, &at) >= 3 && j > 0 && j < ori_layers_component_count(b->L)) {
            if (!ok) b->failed = j;
            put(b, j, strdup(msg + at), lim != 0);
        }
        free(msg);
        send_work(b, st.MPI_SOURCE, &stopped);
    }
    if (threaded) pthread_join(tid, NULL);
}

static void worker_count(const ori_layers *L)
{
    char first[] = "0 0 1 ";
    MPI_Send(first, (int)strlen(first), MPI_CHAR, 0, TAG_RESULT, MPI_COMM_WORLD);
    for (;;) {
        int j = 0;
        MPI_Recv(&j, 1, MPI_INT, 0, TAG_WORK, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (j <= 0) break;
        bool limited = false, ok = true;
        char *s = count_one(L, j, &limited, &ok);
        size_t n = strlen(s) + 40;
        char *msg = malloc(n);
        snprintf(msg, n, "%d %d %d %s", j, limited ? 1 : 0, ok ? 1 : 0, s);
        MPI_Send(msg, (int)strlen(msg), MPI_CHAR, 0, TAG_RESULT, MPI_COMM_WORLD);
        free(msg);
        free(s);
    }
}

// --- input and output (as orikin layers) -----------------------------------------------------

static bool parse_u64(const char *s, uint64_t *out)
{
    if (!s || !*s) return false;
    uint64_t v = 0;
    for (const char *c = s; *c; ++c) {
        if (*c < '0' || *c > '9') return false;
        uint64_t d = (uint64_t)(*c - '0');
        if (v > (UINT64_MAX - d) / 10) return false;
        v = 10 * v + d;
    }
    *out = v;
    return true;
}

// faces_flatFoldTransform of the frame, as orikin layers reads it (NULL when absent).
static double *read_transforms(ori_fold *doc, int frame, int nf, const char *path, bool *bad, bool talk)
{
    *bad = false;
    char *text = ori_fold_get_custom(doc, frame, "faces_flatFoldTransform");
    if (!text) return NULL;
    json_t *arr = json_loads(text, 0, NULL);
    ori_buffer_free(text);
    double *t = NULL;
    if (json_is_array(arr) && (int)json_array_size(arr) == nf) {
        t = malloc(sizeof(double) * 6 * (size_t)(nf ? nf : 1));
        for (int f = 0; f < nf && !*bad; ++f)
            for (int r = 0; r < 2 && !*bad; ++r)
                for (int c = 0; c < 3 && !*bad; ++c) {
                    json_t *x = json_array_get(json_array_get(json_array_get(arr, (size_t)f), (size_t)r), (size_t)c);
                    if (json_is_number(x)) t[6 * f + 3 * r + c] = json_number_value(x);
                    else *bad = true;
                }
    } else
        *bad = true;
    json_decref(arr);
    if (*bad) {
        if (talk) fprintf(stderr, PROG ": %s: faces_flatFoldTransform: needs [[a, b, c], [d, e, f]] for each of the %d faces\n", path, nf);
        free(t);
        t = NULL;
    }
    return t;
}

// What `orikin layers FILE --count [--json]` prints (cli/cmd_layers.c; the test compares them).
static int print_result(const ori_layers *L, bool json, bool limit_given)
{
    ori_layers_info info = ori_layers_get_info(L);
    char *states = ori_layers_state_count(L);
    ori_layers_conflict conf;
    bool unsat = ori_layers_get_conflict(L, &conf);
    if (!json) {
        printf("%s%s\n", states, info.limited ? " (at least: limited)" : "");
        ori_buffer_free(states);
        return unsat ? EXIT_NEGATIVE : info.limited ? EXIT_PARTIAL : EXIT_OK;
    }
    json_t *o = cli_layers_count_json(L, limit_given, false);
    // numbers in their shortest exact form, as every orikin --json prints them
    char *raw = json_dumps(o, JSON_COMPACT | JSON_PRESERVE_ORDER | JSON_REAL_PRECISION(17));
    char *text = raw ? ori_json_normalize(raw, false, NULL) : NULL;
    fputs(text ? text : "null\n", stdout); // (normalised text ends with its newline)
    free(raw);
    ori_buffer_free(text);
    json_decref(o);
    ori_buffer_free(states);
    return unsat ? EXIT_NEGATIVE : info.limited ? EXIT_PARTIAL : EXIT_OK;
}

static const char *HELP =
    "usage: mpirun -np N " PROG " FILE.fold [--json] [--limit N] [--tolerance R] [--frame N] [--timing]\n"
    "\n"
    "orikin layers FILE --count on MPI ranks: every rank sets up the same layer problem; its\n"
    "independent components are counted across the ranks (rank 0 hands them out one by one,\n"
    "largest first, and counts too) and rank 0 prints the exact count, the same for any number\n"
    "of ranks and the same as orikin layers FILE --count (with --json, as orikin layers --json).\n"
    "A single big component is counted by one rank. Exit 0 when a state exists, 1 when none\n"
    "does, 2 for a bad command line, 3 for an invalid file. See docs/sweep.md.\n"
    "\n"
    "options (as orikin layers):\n"
    "  --json         print orikin layers' JSON summary\n"
    "  --limit N      count at most N states per component (the count is then a lower bound)\n"
    "  --tolerance R  snapping length of the folded image relative to its diagonal, in (0, 0.01]\n"
    "  --frame N      the FOLD frame to read; default 0\n"
    "  --timing       print the set-up and the count's wall seconds on stderr (rank 0's)\n";

static int usage(bool talk, const char *msg, const char *arg)
{
    if (talk) fprintf(stderr, PROG ": %s%s%s%s\n(" PROG " -h for help)\n", msg, arg ? " (got '" : "", arg ? arg : "", arg ? "')" : "");
    return EXIT_USAGE;
}

// Set up the layer problem as orikin layers does; every rank runs it (only rank 0 talks).
static int setup(int argc, char **argv, bool talk, ori_layers **out, bool *json, bool *limit_given, bool *help,
                 bool *timing)
{
    const char *path = NULL;
    uint64_t limit = ORI_LAYERS_NO_LIMIT;
    double tol = ORI_LAYERS_SNAP_AUTO; // from the drawing, as orikin layers
    int frame = 0;
    *json = *limit_given = *help = *timing = false;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) *help = true;
        else if (strcmp(a, "--json") == 0) *json = true;
        else if (strcmp(a, "--timing") == 0) *timing = true;
        else if (strcmp(a, "--count") == 0) continue; // always a count
        else if (strcmp(a, "--limit") == 0 || strcmp(a, "--tolerance") == 0 || strcmp(a, "--frame") == 0) {
            if (i + 1 >= argc) return usage(talk, "missing value after", a);
            const char *v = argv[++i];
            char *end = NULL;
            if (a[2] == 'l') {
                if (*limit_given) return usage(talk, "--limit given twice", NULL);
                *limit_given = true;
                if (!parse_u64(v, &limit) || limit == 0 || limit == ORI_LAYERS_NO_LIMIT)
                    return usage(talk, "--limit needs a count >= 1", v);
            } else if (a[2] == 't') {
                tol = strtod(v, &end);
                if (end == v || *end || !(tol > 0.0) || !(tol <= 1e-2))
                    return usage(talk, "--tolerance needs a relative length in (0, 0.01]", v);
            } else {
                long f = strtol(v, &end, 10);
                if (end == v || *end || f < 0 || f > 1000000) return usage(talk, "--frame needs a frame number >= 0", v);
                frame = (int)f;
            }
        } else if (a[0] == '-' && a[1]) return usage(talk, "unknown option", a);
        else if (path) return usage(talk, "one FILE only", a);
        else path = a;
    }
    if (*help) return EXIT_OK;
    if (!path) return usage(talk, "missing FILE", NULL);
    ori_error err;
    ori_error_clear(&err);
    char buf[600];
    ori_fold *doc = NULL;
    ori_pattern *p = NULL;
    ori_status st = ori_fold_load_file(path, &doc, &err);
    if (st == ORI_OK && (frame >= ori_fold_frame_count(doc))) {
        if (talk) fprintf(stderr, PROG ": %s: --frame: frame %d does not exist (%d frames)\n", path, frame, ori_fold_frame_count(doc));
        ori_fold_destroy(doc);
        return EXIT_INPUT;
    }
    ori_build_def bd = ori_default_build_def();
    if (st == ORI_OK) st = ori_fold_get_pattern(doc, frame, &bd, &p, &err);
    if (st != ORI_OK) {
        if (talk) fprintf(stderr, PROG ": %s: %s\n", path, ori_error_format(&err, buf, sizeof buf));
        ori_fold_destroy(doc);
        return EXIT_INPUT;
    }
    bool bad = false;
    double *xf = ori_pattern_is_folded_form(p) ? NULL : read_transforms(doc, frame, ori_pattern_face_count(p), path, &bad, talk);
    ori_layers_def def = ori_default_layers_def();
    def.face_transforms = xf;
    def.face_transform_count = xf ? ori_pattern_face_count(p) : 0;
    def.limit = limit;
    def.snap_rel = tol;
    if (!bad) st = ori_layers_create(p, &def, out, &err);
    free(xf);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    if (bad) return EXIT_INPUT;
    if (st != ORI_OK) {
        if (talk) fprintf(stderr, PROG ": %s: %s\n", path, ori_error_format(&err, buf, sizeof buf));
        return EXIT_INPUT;
    }
    return EXIT_OK;
}

int main(int argc, char **argv)
{
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    // Output must not depend on the machine (as orikin's main): one OpenBLAS thread per rank.
    openblas_set_num_threads(1);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    ori_layers *L = NULL;
    bool json, limit_given, help, timing;
    double t0 = MPI_Wtime();
    int rc = setup(argc, argv, rank == 0, &L, &json, &limit_given, &help, &timing);
    double t1 = MPI_Wtime();
    // Every rank must have the same problem: the same verdict of the set-up and the same
    // number of components and variables (a rank that reads another file stops them all).
    ori_layers_info info = L ? ori_layers_get_info(L) : (ori_layers_info){0};
    int mine[3] = {rc, L ? info.components : -1, L ? info.variables : -1}, lo[3], hi[3];
    MPI_Allreduce(mine, lo, 3, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    MPI_Allreduce(mine, hi, 3, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (help) {
        if (rank == 0) fputs(HELP, stdout);
        rc = EXIT_OK;
    } else if (memcmp(lo, hi, sizeof lo) != 0) {
        if (rank == 0 && rc == EXIT_OK)
            fprintf(stderr, PROG ": the ranks set up different problems (another file on some rank?): components %d to %d\n", lo[1], hi[1]);
        rc = hi[0] ? hi[0] : EXIT_INPUT;
    } else if (rc == EXIT_OK) {
        // A problem the set-up decided already (no state) needs no counting.
        bool decided = info.counted;
        int n = info.components;
        if (rank == 0) {
            board b = {.L = L, .next = decided ? 0 : n - 1, .limited = false, .failed = 0};
            pthread_mutex_init(&b.lock, NULL);
            b.states = calloc((size_t)(n ? n : 1), sizeof *b.states);
            if (n > 0) b.states[0] = strdup("1");
            rank0_count(&b, size);
            double t2 = MPI_Wtime();
            if (timing)
                fprintf(stderr, PROG ": set-up %.3f s, count %.3f s on %d rank%s\n", t1 - t0, t2 - t1, size,
                        size == 1 ? "" : "s");
            pthread_mutex_destroy(&b.lock);
            ori_error err;
            ori_error_clear(&err);
            if (!decided && (b.failed || ori_layers_set_counts(L, (const char *const *)b.states, b.limited, &err) != ORI_OK)) {
                fprintf(stderr, PROG ": component %d could not be counted\n", b.failed);
                rc = 4;
            } else
                rc = print_result(L, json, limit_given);
            for (int j = 0; j < n; ++j) free(b.states[j]);
            free(b.states);
            fflush(stdout);
        } else
            worker_count(L);
    }
    ori_layers_destroy(L);
    MPI_Finalize();
    return rc;
}
