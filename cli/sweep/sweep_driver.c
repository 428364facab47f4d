// The sweep driver: command line, the points still missing from the database (this shard's),
// the backend that computes them, rows written in point order, progress and ETA on stderr,
// merging and exporting.
#define _POSIX_C_SOURCE 200809L
#include "sweep.h"
#include "sweep_internal.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int usage(const char *prog, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int usage(const char *prog, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "%s: ", prog);
    vfprintf(stderr, fmt, ap);
    fprintf(stderr, "\ntry '%s -h'\n", prog);
    va_end(ap);
    return SWEEP_EXIT_USAGE;
}

void sweep_args_free(sweep_args *a)
{
    free(a->db_default);
    free(a->inputs);
    memset(a, 0, sizeof *a);
}

int sweep_parse_args(const char *prog, int argc, char **argv, sweep_args *a)
{
    memset(a, 0, sizeof *a);
    a->shards = 1;
    a->commit_every = 16;
    a->inputs = calloc((size_t)argc + 1, sizeof(char *));
    const char *seen[16];
    int nseen = 0;
    for (int i = 1; i < argc; ++i) {
        const char *o = argv[i];
        bool valued = strcmp(o, "-o") == 0 || strcmp(o, "--shard") == 0 || strcmp(o, "--commit") == 0 || strcmp(o, "--csv") == 0 ||
                      strcmp(o, "--jsonl") == 0 || strcmp(o, "--merge") == 0 || strcmp(o, "--export") == 0 ||
                      strcmp(o, "--fold-files") == 0;
        if (valued) {
            for (int s = 0; s < nseen; ++s)
                if (strcmp(seen[s], o) == 0) return usage(prog, "%s given twice", o);
            seen[nseen++] = o;
            if (i + 1 >= argc) return usage(prog, "%s needs a value", o);
            const char *v = argv[++i];
            if (strcmp(o, "-o") == 0) a->db_path = v;
            else if (strcmp(o, "--csv") == 0) a->csv = v;
            else if (strcmp(o, "--jsonl") == 0) a->jsonl = v;
            else if (strcmp(o, "--merge") == 0) a->merge_out = v;
            else if (strcmp(o, "--export") == 0) a->export_db = v;
            else if (strcmp(o, "--fold-files") == 0) a->fold_dir = v;
            else if (strcmp(o, "--commit") == 0) {
                char *end;
                long c = strtol(v, &end, 10);
                if (*end || end == v || c < 1 || c > 1000000) return usage(prog, "--commit needs a number of points from 1 to 1000000, got '%s'", v);
                a->commit_every = (int)c;
            } else {
                int I, N, len = 0;
                if (sscanf(v, "%d/%d%n", &I, &N, &len) != 2 || v[len] || N < 1 || I < 0 || I >= N)
                    return usage(prog, "--shard needs I/N with 0 <= I < N (the I-th of N slices), got '%s'", v);
                a->shard = I;
                a->shards = N;
            }
        } else if (strcmp(o, "--quiet") == 0) a->quiet = true;
        else if (strcmp(o, "--dry-run") == 0) a->dry_run = true;
        else if (o[0] == '-' && o[1]) return usage(prog, "unknown option %s", o);
        else a->inputs[a->input_count++] = argv[i];
    }
    if (a->merge_out) {
        if (a->input_count < 1) return usage(prog, "--merge OUT.db needs the shard databases to combine");
        if (a->db_path || a->shards > 1 || a->dry_run || a->export_db)
            return usage(prog, "--merge takes only the databases (and --csv/--jsonl for the result)");
        return 0;
    }
    if (a->export_db) {
        if (a->input_count) return usage(prog, "--export DB takes no SPEC");
        if (!a->csv && !a->jsonl) return usage(prog, "--export DB needs --csv FILE or --jsonl FILE");
        if (a->db_path || a->shards > 1 || a->dry_run) return usage(prog, "--export takes only --csv and --jsonl");
        return 0;
    }
    if (a->input_count != 1) return usage(prog, a->input_count ? "one SPEC.json only" : "missing SPEC.json");
    a->spec_path = a->inputs[0];
    if (!a->db_path) {
        size_t n = strlen(a->spec_path);
        a->db_default = malloc(n + 4);
        strcpy(a->db_default, a->spec_path);
        if (n > 5 && strcmp(a->db_default + n - 5, ".json") == 0) a->db_default[n - 5] = '\0';
        strcat(a->db_default, ".db");
        a->db_path = a->db_default;
    }
    if (a->csv && a->jsonl && strcmp(a->csv, a->jsonl) == 0) return usage(prog, "--csv and --jsonl name the same file");
    if (a->fold_dir && (a->merge_out || a->export_db)) return usage(prog, "--fold-files is for a run that computes points");
    return 0;
}

// --- serial backend -------------------------------------------------------------------------

static int serial_run(void *ctx, const sweep_spec *spec, const int64_t *todo, int64_t n, sweep_sink_fn *sink, void *user)
{
    (void)ctx;
    sweep_worker *w = sweep_worker_create(spec);
    sweep_result *r = malloc(sizeof *r);
    for (int64_t i = 0; i < n; ++i) {
        sweep_worker_run(w, todo[i], r);
        sink(r, user);
    }
    free(r);
    sweep_worker_destroy(w);
    return 0;
}

sweep_backend sweep_serial_backend(void)
{
    sweep_backend b = {serial_run, NULL, "serial", 1};
    return b;
}

// --- writing in order, progress ---------------------------------------------------------------

typedef struct sink_state {
    const char *prog;
    sweep_db *db;
    int commit_every, pending;
    int64_t written, total, failed;
    double start, last_draw;
    int last_decile;
    bool tty, quiet, shown;
    int rc;
    char err[512];
} sink_state;

static void format_eta(double s, char *buf, size_t n)
{
    if (s >= 3600) snprintf(buf, n, "%dh%02dm", (int)(s / 3600), (int)(s / 60) % 60);
    else if (s >= 60) snprintf(buf, n, "%dm%02ds", (int)(s / 60), (int)s % 60);
    else snprintf(buf, n, "%.0fs", s);
}

static void progress(sink_state *s, bool final)
{
    if (s->quiet) return;
    double t = now_s(), el = t - s->start;
    if (!final && el < 1.0) return;
    double frac = s->total ? (double)s->written / (double)s->total : 1.0, rate = el > 0 ? s->written / el : 0.0;
    char eta[32];
    format_eta(rate > 0 ? (double)(s->total - s->written) / rate : 0.0, eta, sizeof eta);
    if (s->tty) {
        if (!final && t - s->last_draw < 0.2) return;
        fprintf(stderr, "\r%s: %lld/%lld points (%d%%), %.3g points/s, ETA %s%s", s->prog, (long long)s->written, (long long)s->total,
                (int)(100 * frac), rate, eta, final ? "\n" : "   ");
        s->last_draw = t;
        s->shown = true;
    } else {
        int decile = (int)(10 * frac);
        if (final ? s->shown : decile > s->last_decile && decile < 10) {
            fprintf(stderr, "%s: %lld/%lld points (%d%%), %.3g points/s, ETA %s\n", s->prog, (long long)s->written,
                    (long long)s->total, (int)(100 * frac), rate, eta);
            s->last_decile = decile;
            s->shown = true;
        }
    }
    fflush(stderr);
}

static void sink(const sweep_result *r, void *user)
{
    sink_state *s = user;
    if (s->rc) return;
    s->rc = sweep_db_put(s->db, r, s->err, sizeof s->err);
    s->written++;
    s->failed += !r->ok;
    if (!s->rc && ++s->pending >= s->commit_every) {
        s->rc = sweep_db_commit(s->db, s->err, sizeof s->err);
        s->pending = 0;
    }
    progress(s, false);
}

static int exports(const char *prog, const char *db, const sweep_args *a)
{
    char err[600];
    if (a->csv && sweep_db_export(db, a->csv, false, err, sizeof err)) {
        fprintf(stderr, "%s: %s\n", prog, err);
        return SWEEP_EXIT_INPUT;
    }
    if (a->jsonl && sweep_db_export(db, a->jsonl, true, err, sizeof err)) {
        fprintf(stderr, "%s: %s\n", prog, err);
        return SWEEP_EXIT_INPUT;
    }
    return 0;
}

int sweep_main(const char *prog, int argc, char **argv, const sweep_backend *backend)
{
    sweep_args a;
    int rc = sweep_parse_args(prog, argc, argv, &a);
    if (rc) {
        sweep_args_free(&a);
        return rc;
    }
    char err[1024];
    if (a.merge_out) {
        rc = sweep_db_merge(a.merge_out, a.inputs, a.input_count, err, sizeof err);
        if (rc) fprintf(stderr, "%s: %s\n", prog, err);
        else {
            printf("%s: merged %d database%s\n", a.merge_out, a.input_count, a.input_count == 1 ? "" : "s");
            rc = exports(prog, a.merge_out, &a);
        }
        sweep_args_free(&a);
        return rc;
    }
    if (a.export_db) {
        rc = exports(prog, a.export_db, &a);
        sweep_args_free(&a);
        return rc;
    }
    sweep_spec *spec = NULL;
    if ((rc = sweep_spec_load(a.spec_path, &spec, err, sizeof err))) {
        fprintf(stderr, "%s: %s: %s\n", prog, a.spec_path, err);
        sweep_args_free(&a);
        return rc;
    }
    if (a.fold_dir) {
        struct stat st;
        if (stat(a.fold_dir, &st) != 0 && mkdir(a.fold_dir, 0777) != 0) {
            fprintf(stderr, "%s: --fold-files %s: cannot create the directory: %s\n", prog, a.fold_dir, strerror(errno));
            sweep_spec_free(spec);
            sweep_args_free(&a);
            return SWEEP_EXIT_INPUT;
        }
        if (stat(a.fold_dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
            fprintf(stderr, "%s: --fold-files %s: not a directory\n", prog, a.fold_dir);
            sweep_spec_free(spec);
            sweep_args_free(&a);
            return SWEEP_EXIT_INPUT;
        }
        spec->fold_dir = strdup(a.fold_dir);
    }
    int64_t mine = 0;
    for (int64_t i = a.shard; i < spec->point_count; i += a.shards) mine++;
    if (a.dry_run) {
        printf("%s: %lld points (%lld grid points x %lld samples), hash %s\n", a.spec_path, (long long)spec->point_count,
               (long long)spec->grid_points, (long long)spec->samples, spec->hash);
        if (a.shards > 1) printf("shard %d/%d: %lld points\n", a.shard, a.shards, (long long)mine);
        printf("parameters:");
        for (int j = 0; j < spec->param_count; ++j) printf(" %s", spec->params[j].name);
        printf("%s\noutputs:", spec->param_count ? "" : " none");
        for (int o = 0; o < SWEEP_OUT_COUNT; ++o)
            if (spec->outputs[o]) printf(" %s", sweep_output_name(o));
        printf("\n");
        sweep_spec_free(spec);
        sweep_args_free(&a);
        return 0;
    }
    sweep_db *db = NULL;
    if ((rc = sweep_db_open(a.db_path, spec, &db, err, sizeof err))) {
        fprintf(stderr, "%s: %s\n", prog, err);
        sweep_spec_free(spec);
        sweep_args_free(&a);
        return rc;
    }
    unsigned char *done = calloc((size_t)spec->point_count + 1, 1);
    int64_t stored = sweep_db_done(db, done), n = 0;
    int64_t *todo = malloc(sizeof(int64_t) * (size_t)(mine + 1));
    for (int64_t i = a.shard; i < spec->point_count; i += a.shards)
        if (!done[i]) todo[n++] = i;
    free(done);
    sweep_backend serial = sweep_serial_backend();
    if (!backend) backend = &serial;
    if (!a.quiet) {
        char shard[48] = "";
        if (a.shards > 1) snprintf(shard, sizeof shard, " of shard %d/%d", a.shard, a.shards);
        char ranks[32] = "";
        if (backend->ranks > 1 || strcmp(backend->name, "serial") != 0) snprintf(ranks, sizeof ranks, " on %d ranks", backend->ranks);
        fprintf(stderr, "%s: %s: %lld points, %lld stored in %s; computing %lld%s%s\n", prog, a.spec_path,
                (long long)spec->point_count, (long long)stored, a.db_path, (long long)n, shard, ranks);
    }
    sink_state s = {0};
    s.prog = prog;
    s.db = db;
    s.commit_every = a.commit_every;
    s.total = n;
    s.start = now_s();
    s.last_decile = -1;
    s.tty = isatty(fileno(stderr)) != 0;
    s.quiet = a.quiet;
    rc = backend->run(backend->ctx, spec, todo, n, sink, &s);
    if (!s.rc) s.rc = sweep_db_commit(db, s.err, sizeof s.err);
    double el = now_s() - s.start;
    progress(&s, true);
    sweep_db_close(db);
    free(todo);
    if (s.rc) {
        fprintf(stderr, "%s: %s\n", prog, s.err);
        rc = s.rc;
    } else if (!rc) {
        printf("%s: %lld points computed in %.3g s (%.3g points/s), %lld failed; %lld of %lld stored\n", a.db_path, (long long)n, el,
               el > 0 ? n / el : 0.0, (long long)s.failed, (long long)(stored + n), (long long)spec->point_count);
        rc = exports(prog, a.db_path, &a);
    }
    sweep_spec_free(spec);
    sweep_args_free(&a);
    return rc;
}
