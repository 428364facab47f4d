// orikin sweep: parameter studies over designs (SPEC item 23; docs/sweep.md). The spec (JSON)
// names a base pattern (a FOLD file or a generator call), parameters (ranges, lists, seeded
// random draws), the job each design point runs through the library (fold, collide, actuate,
// simulate, layers) and the scalar outputs kept; results go to SQLite, one row per point.
// Shared by `orikin sweep` (cli/cmd_sweep.c) and the MPI driver (cli/sweep/sweep_mpi.c):
// the spec and its points (sweep_spec.c), the job (sweep_job.c), the database (sweep_db.c)
// and the driver (sweep_driver.c). Only the public <orikin/...> headers are used.
#ifndef ORI_CLI_SWEEP_H
#define ORI_CLI_SWEEP_H

#include <orikin/orikin.h>

#include <jansson.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

// Exit codes (as cli/cli.h).
enum { SWEEP_EXIT_OK = 0, SWEEP_EXIT_USAGE = 2, SWEEP_EXIT_INPUT = 3, SWEEP_EXIT_INTERNAL = 4 };

// Most parameters of a spec, most values of a list, longest parameter name.
#define SWEEP_MAX_PARAMS 32
#define SWEEP_NAME_MAX 48
// Most points of a sweep (rows of the database).
#define SWEEP_MAX_POINTS ((int64_t)100000000)

// --- the spec -------------------------------------------------------------------------------

typedef enum sweep_param_kind {
    SWEEP_RANGE = 0, // from, to, count: evenly spaced, both ends included
    SWEEP_LIST,      // values: numbers or strings
    SWEEP_UNIFORM,   // uniform: [lo, hi), one draw per point
    SWEEP_NORMAL,    // normal: [mean, sd], one draw per point
} sweep_param_kind;

// A parameter value: a number or a string (lists may hold either).
typedef struct sweep_value {
    bool is_string;
    double number;
    const char *string; // owned by the spec
} sweep_value;

typedef struct sweep_param {
    char name[SWEEP_NAME_MAX];
    sweep_param_kind kind;
    double a, b;   // range from/to, uniform lo/hi, normal mean/sd
    int count;     // range count, list length (1 for random parameters)
    json_t *values; // list values (owned by the spec's JSON)
} sweep_param;

// The outputs a sweep can keep (columns of the points table).
typedef enum sweep_output {
    SWEEP_OUT_VERDICT = 0,       // TEXT: the fold's verdict ("valid", "blocked", ...; "collision")
    SWEEP_OUT_REACHED,           // REAL: fraction of the fold reached, 0 … 1
    SWEEP_OUT_FRAMES,            // INTEGER: output frames of the fold
    SWEEP_OUT_COLLIDES,          // INTEGER 0/1
    SWEEP_OUT_MIN_CLEARANCE,     // REAL: least distance of faces sharing no vertex over the frames checked
    SWEEP_OUT_FEASIBLE,          // INTEGER 0/1: actuation feasible within the limits
    SWEEP_OUT_CURRENT_NEEDED,    // REAL (A): the largest current a wire needs
    SWEEP_OUT_MECHANISM_CURRENT, // REAL (A): the common current by virtual work
    SWEEP_OUT_WORST_EDGE,        // INTEGER: the hinge needing current_needed
    SWEEP_OUT_FOLD_TIME,         // REAL (s): simulated time until every wired crease reaches its target
    SWEEP_OUT_SIM_REACHED,       // INTEGER 0/1: the simulation reached the targets
    SWEEP_OUT_LAYER_COUNT,       // TEXT: exact number of flat-folded states (decimal)
    SWEEP_OUT_COUNT
} sweep_output;

// Output name ("min_clearance"), its SQL type, and the job it needs ("fold", "collide", ...).
const char *sweep_output_name(sweep_output o);
const char *sweep_output_sql_type(sweep_output o);
const char *sweep_output_job(sweep_output o);

typedef struct sweep_spec {
    char *path;          // the spec file as given
    char *dir;           // its directory ("" or ending in '/'): base files are relative to it
    json_t *root;        // the spec as read
    json_t *template_;   // root without "parameters", "samples", "seed", "outputs": substituted per point
    sweep_param params[SWEEP_MAX_PARAMS];
    int param_count;
    int64_t grid_points; // product of the range and list counts
    int64_t samples;     // repetitions of every grid point (random draws differ)
    uint64_t seed;
    int64_t point_count; // grid_points × samples
    bool outputs[SWEEP_OUT_COUNT];
    bool has_random;
    uint64_t file_hash[2]; // of the base file's bytes (0 for a generated base)
    char hash[33];       // 128-bit hex of the canonical spec and the base file's bytes
    char *canonical;     // canonical spec text (sorted keys, compact, shortest numbers)
    char *fold_dir;      // where the points' FOLD files go (--fold-files; not part of the spec), or NULL
} sweep_spec;

// Load and check a spec. On failure returns SWEEP_EXIT_INPUT with one line in err ("FIELD:
// message", the field as a JSON path like job.fold.to or parameters[1].count); *out NULL.
int sweep_spec_load(const char *path, sweep_spec **out, char *err, size_t err_size);
void sweep_spec_free(sweep_spec *spec);

// The parameter values of a point (param_count entries) and its sample number.
void sweep_point_values(const sweep_spec *spec, int64_t index, sweep_value *values, int64_t *sample);
// The job of a point: the template with every "$name" string replaced by its value (new reference).
json_t *sweep_point_job(const sweep_spec *spec, int64_t index);

// --- the job --------------------------------------------------------------------------------

#define SWEEP_ERROR_MAX 320

// The result of one point: each output present or NULL (SQL NULL).
typedef struct sweep_result {
    int64_t index;
    int32_t ok;                         // 0: the point failed (error holds why)
    int32_t has[SWEEP_OUT_COUNT];       // the output has a value
    double real[SWEEP_OUT_COUNT];       // REAL and INTEGER outputs
    char verdict[32];
    char layer_count[96];
    char error[SWEEP_ERROR_MAX];
} sweep_result;

// A worker computes points; it keeps the last base pattern, mechanism and fold so that points
// differing only in later stages (design, actuation) reuse them (results do not depend on it).
typedef struct sweep_worker sweep_worker;
sweep_worker *sweep_worker_create(const sweep_spec *spec);
void sweep_worker_destroy(sweep_worker *w);
// Compute point index into *out; a failure is recorded in *out (ok = 0), never fatal.
void sweep_worker_run(sweep_worker *w, int64_t index, sweep_result *out);

// --- the database ---------------------------------------------------------------------------

typedef struct sweep_db sweep_db;
// Open (creating when absent) the results database of spec at path. An existing database of
// another spec (hash) is refused: SWEEP_EXIT_INPUT with a line in err.
int sweep_db_open(const char *path, const sweep_spec *spec, sweep_db **out, char *err, size_t err_size);
// Mark in done (point_count bytes) the points already stored; returns how many.
int64_t sweep_db_done(sweep_db *db, unsigned char *done);
// Store a point's row (inside the current transaction; sweep_db_commit ends it). 0 or exit code.
int sweep_db_put(sweep_db *db, const sweep_result *r, char *err, size_t err_size);
int sweep_db_commit(sweep_db *db, char *err, size_t err_size);
void sweep_db_close(sweep_db *db);
// Merge shard databases into out (a new file, written whole then renamed): every input must
// come from the same spec (hash), and points present in several must agree.
int sweep_db_merge(const char *out, char **inputs, int input_count, char *err, size_t err_size);
// Export the points of a database as CSV (header line) or JSON Lines to path ("-": stdout).
int sweep_db_export(const char *db_path, const char *out, bool jsonl, char *err, size_t err_size);

// --- the driver -----------------------------------------------------------------------------

// A point ready to be written (in point order) by the driver.
typedef void sweep_sink_fn(const sweep_result *r, void *user);

// How the missing points get computed: serially here, or by MPI ranks (sweep_mpi.c).
// run computes todo[0 … n−1] (point indices, ascending) and calls sink for each in that order.
typedef struct sweep_backend {
    int (*run)(void *ctx, const sweep_spec *spec, const int64_t *todo, int64_t n, sweep_sink_fn *sink, void *sink_user);
    void *ctx;
    const char *name; // "serial", "mpi"
    int ranks;
} sweep_backend;

// The serial backend.
sweep_backend sweep_serial_backend(void);

// `orikin sweep` with argv[0] the command name: parse, run with backend (NULL: serial), print.
// Returns the exit code. prog is the name messages carry ("orikin sweep", "orikin-sweep-mpi").
int sweep_main(const char *prog, int argc, char **argv, const sweep_backend *backend);

// The parsed command line (shared with the MPI driver, which parses on every rank).
typedef struct sweep_args {
    const char *spec_path;
    const char *db_path;   // -o (default: SPEC without .json, + .db)
    char *db_default;
    int shard, shards;     // --shard I/N (0 ≤ I < N); 0/1 without
    int commit_every;      // --commit N
    const char *csv, *jsonl;
    bool quiet, dry_run;
    const char *merge_out; // --merge OUT.db: the inputs are the rest
    char **inputs;
    int input_count;
    const char *export_db; // --export DB
    const char *fold_dir;  // --fold-files DIR: each point's folded state as DIR/point-INDEX.fold
} sweep_args;
// Parse argv (argv[0] the command); prints a usage error and returns SWEEP_EXIT_USAGE, or 0.
int sweep_parse_args(const char *prog, int argc, char **argv, sweep_args *a);
void sweep_args_free(sweep_args *a);

#endif
