// orikin sweep: parameter studies over designs, results in SQLite (cli/sweep/, docs/sweep.md).
#include "cli.h"
#include "sweep/sweep.h"

static int run(int argc, char **argv) { return sweep_main("orikin sweep", argc, argv, NULL); }

const cli_command cli_cmd_sweep = {
    "sweep",
    "parameter sweeps: fold or sequence, collide, actuate, simulate, layers per design point; SQLite, resumable",
    "usage: orikin sweep SPEC.json [-o OUT.db] [--shard I/N] [--commit N] [--csv FILE]\n"
    "                    [--jsonl FILE] [--fold-files DIR] [--dry-run] [--quiet]\n"
    "       orikin sweep --merge OUT.db A.db B.db ... [--csv FILE] [--jsonl FILE]\n"
    "       orikin sweep --export DB.db [--csv FILE] [--jsonl FILE]\n"
    "\n"
    "Run a design study: SPEC.json names a base pattern (a FOLD file or a generator call such\n"
    "as {\"generate\": \"miura\", \"rows\": 10, \"cols\": 10}), the design (hinges, panels, field), the\n"
    "parameters (from/to/count ranges, lists of values, seeded uniform or normal draws, written\n"
    "\"$name\" where their value goes), the job each point runs (fold by a drive or toward the\n"
    "targets, or a sequence of folds; collide, actuate, simulate, layers) and the outputs kept\n"
    "(verdict, reached, frames, collides, min_clearance, feasible, current_needed,\n"
    "mechanism_current, worst_edge, fold_time, sim_reached, layer_count). Every point is\n"
    "computed by the library in this process and stored as one row of table points in the\n"
    "SQLite database (idx, sample, the parameters,\n"
    "status ok | error, error, the outputs) with the spec's hash in table sweep. A point that\n"
    "fails records its error and the sweep goes on. The database is written in point order,\n"
    "N points per transaction: a run that is killed keeps what it committed, and running the\n"
    "same command again computes only the missing points (a database of another spec or base\n"
    "file is refused). Progress (points done, rate, ETA) on stderr. The format: docs/sweep.md.\n"
    "Exit 0 when every point is stored (failed points included), 2 usage, 3 bad spec (one line\n"
    "naming the spec's field, e.g. job.fold.to) or database.\n"
    "\n"
    "options:\n"
    "  -o FILE          the results database (default: SPEC without .json, + .db)\n"
    "  --shard I/N      compute only the points with index = I mod N (0 <= I < N), for job\n"
    "                   arrays and GNU parallel; combine the shards' databases with --merge\n"
    "  --commit N       points per transaction (default 16)\n"
    "  --csv FILE       afterwards, write the points as CSV (header line; - for stdout)\n"
    "  --jsonl FILE     afterwards, write the points as JSON Lines (one object per point)\n"
    "  --fold-files DIR each point whose job folds also as DIR/point-INDEX.fold: the base with\n"
    "                   the fold's last state appended as a folded frame (orikin:sweep_point,\n"
    "                   orikin:parameters); DIR is made when missing\n"
    "  --dry-run        check the spec and print its point count, parameters and outputs\n"
    "  --quiet          no progress on stderr\n"
    "  --merge OUT.db   combine shard databases of one spec into OUT.db (refuses databases of\n"
    "                   different specs and points that disagree)\n"
    "  --export DB      write DB's points with --csv / --jsonl, computing nothing\n"
    "\n"
    "MPI: orikin-sweep-mpi takes the same options under mpirun (docs/sweep.md).\n"
    "example: orikin sweep examples/sweeps/miura-actuation.json --csv -\n",
    run,
    NULL,
};
