// orikin-sweep-mpi: `orikin sweep` on MPI ranks (docs/sweep.md). Every rank parses the same
// command line; rank 0 runs the driver (spec, database, missing points, writing, progress) and
// hands the points out dynamically: each worker holds up to SWEEP_MPI_DEPTH points at a time and
// gets the next as soon as it returns a result, so uneven points balance themselves; rank 0
// computes points too between messages. Rows are written by rank 0 in point order, as the serial
// run writes them, so the database is the same whatever the number of ranks.
//     mpirun -np 4 orikin-sweep-mpi SPEC.json -o out.db
#define _POSIX_C_SOURCE 200809L
#include <mpi.h>

#include <cblas.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "sweep.h"

enum { TAG_START = 1, TAG_READY, TAG_WORK, TAG_RESULT, TAG_STOP };

// Points a worker holds at once (one computing, the others queued), so that it never waits
// for rank 0 while rank 0 computes a point of its own.
#define SWEEP_MPI_DEPTH 2

// A waiting rank polls this often instead of spinning in MPI_Probe: on a machine with more
// ranks than free cores a spinning rank takes the core a computing one needs. The queued point
// of SWEEP_MPI_DEPTH hides the latency.
#define SWEEP_MPI_POLL_NS 50000

static void wait_message(int source, int tag, MPI_Status *st)
{
    for (;;) {
        int flag = 0;
        MPI_Iprobe(source, tag, MPI_COMM_WORLD, &flag, st);
        if (flag) return;
        struct timespec ts = {0, SWEEP_MPI_POLL_NS};
        nanosleep(&ts, NULL);
    }
}

typedef struct mpi_ctx {
    int size;
    bool started;
} mpi_ctx;

static int64_t position_of(const int64_t *todo, int64_t n, int64_t index)
{
    int64_t lo = 0, hi = n - 1;
    while (lo <= hi) {
        int64_t mid = lo + (hi - lo) / 2;
        if (todo[mid] == index) return mid;
        if (todo[mid] < index) lo = mid + 1;
        else hi = mid - 1;
    }
    return -1;
}

static void send_work(const int64_t *todo, int64_t pos, int rank)
{
    int64_t msg = todo[pos];
    MPI_Send(&msg, 1, MPI_INT64_T, rank, TAG_WORK, MPI_COMM_WORLD);
}

static int master_run(void *ctxp, const sweep_spec *spec, const int64_t *todo, int64_t n, sweep_sink_fn *sink, void *user)
{
    mpi_ctx *ctx = ctxp;
    int size = ctx->size;
    // The workers read the spec themselves (same command line) and must find the same hash.
    ctx->started = true;
    for (int r = 1; r < size; ++r) MPI_Send((void *)spec->hash, (int)sizeof spec->hash, MPI_CHAR, r, TAG_START, MPI_COMM_WORLD);
    int bad = 0;
    for (int r = 1; r < size; ++r) {
        int ok = 0;
        MPI_Recv(&ok, 1, MPI_INT, r, TAG_READY, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        bad += !ok;
    }
    if (bad) {
        fprintf(stderr, "orikin-sweep-mpi: %d rank%s could not read the same spec (see above)\n", bad, bad == 1 ? "" : "s");
        return SWEEP_EXIT_INPUT;
    }
    sweep_worker *w = sweep_worker_create(spec);
    sweep_result **slot = calloc((size_t)n + 1, sizeof *slot);
    int64_t next = 0, written = 0;
    for (int k = 0; k < SWEEP_MPI_DEPTH; ++k)
        for (int r = 1; r < size && next < n; ++r) send_work(todo, next++, r);
    while (written < n) {
        for (;;) { // every result that has arrived, each worker refilled at once
            int flag = 0;
            MPI_Status st;
            MPI_Iprobe(MPI_ANY_SOURCE, TAG_RESULT, MPI_COMM_WORLD, &flag, &st);
            if (!flag) break;
            sweep_result *r = malloc(sizeof *r);
            MPI_Recv(r, (int)sizeof *r, MPI_BYTE, st.MPI_SOURCE, TAG_RESULT, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            int64_t pos = position_of(todo, n, r->index);
            if (pos < 0 || slot[pos]) {
                free(r);
                continue;
            }
            slot[pos] = r;
            if (next < n) send_work(todo, next++, st.MPI_SOURCE);
        }
        while (written < n && slot[written]) {
            sink(slot[written], user);
            free(slot[written]);
            slot[written++] = NULL;
        }
        if (written >= n) break;
        if (next < n) { // rank 0 computes the next point itself
            int64_t pos = next++;
            slot[pos] = malloc(sizeof **slot);
            sweep_worker_run(w, todo[pos], slot[pos]);
        } else { // everything is handed out: wait for a result
            MPI_Status st;
            wait_message(MPI_ANY_SOURCE, TAG_RESULT, &st);
        }
    }
    free(slot);
    sweep_worker_destroy(w);
    return 0;
}

static void worker_loop(const char *spec_path, const char *fold_dir)
{
    sweep_spec *spec = NULL;
    sweep_worker *w = NULL;
    sweep_result *r = malloc(sizeof *r);
    for (;;) {
        MPI_Status st;
        wait_message(0, MPI_ANY_TAG, &st);
        if (st.MPI_TAG == TAG_STOP) {
            MPI_Recv(NULL, 0, MPI_BYTE, 0, TAG_STOP, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            break;
        }
        if (st.MPI_TAG == TAG_START) {
            char hash[33];
            MPI_Recv(hash, (int)sizeof hash, MPI_CHAR, 0, TAG_START, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            char err[1024];
            int ok = 0;
            if (!spec && spec_path && sweep_spec_load(spec_path, &spec, err, sizeof err) != 0)
                fprintf(stderr, "orikin-sweep-mpi: %s: %s\n", spec_path, err);
            if (spec && fold_dir && !spec->fold_dir) spec->fold_dir = strdup(fold_dir); // (rank 0 made it)
            if (spec && strcmp(spec->hash, hash) == 0) ok = 1;
            else if (spec)
                fprintf(stderr, "orikin-sweep-mpi: %s: this rank reads another spec or base file (hash %s, rank 0 %s)\n", spec_path,
                        spec->hash, hash);
            if (ok && !w) w = sweep_worker_create(spec);
            MPI_Send(&ok, 1, MPI_INT, 0, TAG_READY, MPI_COMM_WORLD);
            continue;
        }
        int64_t index;
        MPI_Recv(&index, 1, MPI_INT64_T, 0, TAG_WORK, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        sweep_worker_run(w, index, r);
        MPI_Send(r, (int)sizeof *r, MPI_BYTE, 0, TAG_RESULT, MPI_COMM_WORLD);
    }
    free(r);
    sweep_worker_destroy(w);
    sweep_spec_free(spec);
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    // Output must not depend on the machine (as orikin's main): one OpenBLAS thread per rank.
    openblas_set_num_threads(1);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    int rc = 0;
    if (rank == 0) {
        bool help = false;
        for (int i = 1; i < argc; ++i) help |= strcmp(argv[i], "-h") == 0 || strcmp(argv[i], "--help") == 0;
        if (help) {
            printf("usage: mpirun -np N orikin-sweep-mpi SPEC.json [options of orikin sweep]\n\n"
                   "orikin sweep on MPI ranks: rank 0 writes the database and hands the points out one by one\n"
                   "to the other ranks (and computes too); the database is the same for any number of ranks.\n"
                   "The options are those of orikin sweep (orikin sweep -h; docs/sweep.md).\n");
        } else {
            mpi_ctx ctx = {size, false};
            sweep_backend b = {master_run, &ctx, "mpi", size};
            rc = sweep_main("orikin-sweep-mpi", argc, argv, &b);
        }
        for (int r = 1; r < size; ++r) MPI_Send(NULL, 0, MPI_BYTE, r, TAG_STOP, MPI_COMM_WORLD);
        fflush(stdout);
    } else {
        // The spec path as rank 0 reads it (the first operand); errors are rank 0's to report.
        const char *spec_path = NULL, *fold_dir = NULL;
        for (int i = 1; i < argc; ++i) {
            const char *o = argv[i];
            if (strcmp(o, "--fold-files") == 0 && i + 1 < argc) fold_dir = argv[++i];
            else if (strcmp(o, "-o") == 0 || strcmp(o, "--shard") == 0 || strcmp(o, "--commit") == 0 || strcmp(o, "--csv") == 0 ||
                     strcmp(o, "--jsonl") == 0 || strcmp(o, "--merge") == 0 || strcmp(o, "--export") == 0)
                ++i;
            else if ((o[0] != '-' || !o[1]) && !spec_path) spec_path = o;
        }
        worker_loop(spec_path, fold_dir);
    }
    MPI_Finalize();
    return rc;
}
