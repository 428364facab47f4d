// orikin sweep (cli/sweep/, docs/sweep.md): a sweep's values equal direct CLI runs of the same
// points; a run killed midway resumes computing only the missing points and ends with the rows
// of an uninterrupted run; shards merged equal one run; a database of another spec is refused;
// seeded draws are reproducible; the MPI driver writes the same database for 1, 2 and 3 ranks;
// orikin-layers-mpi prints the serial `orikin layers --count [--json]` for 1, 2 and 3 ranks.
#define _POSIX_C_SOURCE 200809L
#include <inttypes.h>
#include <jansson.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <sqlite3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "support.h"

TestSuite(sweep, .timeout = 600);

static char *fmt(const char *f, ...) __attribute__((format(printf, 1, 2)));
static char *fmt(const char *f, ...)
{
    static char buf[64][4096]; // a ring: a test keeps at most a few dozen alive
    static int k;
    char *b = buf[k++ % 64];
    va_list ap;
    va_start(ap, f);
    vsnprintf(b, sizeof buf[0], f, ap);
    va_end(ap);
    return b;
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    cr_assert_not_null(f, "%s", path);
    fputs(text, f);
    fclose(f);
}

// The rows of a database as JSON Lines (orikin sweep --export); the caller frees.
static char *rows_of(const char *db)
{
    char *out = NULL;
    int rc = test_run_cli_split(fmt("sweep --export '%s' --jsonl -", db), &out, NULL);
    cr_assert_eq(rc, 0, "export %s: exit %d", db, rc);
    return out;
}

// The points of a database as a JSON array of row objects.
static json_t *points_of(const char *db)
{
    char *text = rows_of(db);
    json_t *a = json_array();
    for (char *line = strtok(text, "\n"); line; line = strtok(NULL, "\n")) {
        json_error_t je;
        json_t *o = json_loads(line, 0, &je);
        cr_assert_not_null(o, "%s: %s", line, je.text);
        json_array_append_new(a, o);
    }
    free(text);
    return a;
}

static int64_t row_count(const char *db)
{
    sqlite3 *h = NULL;
    int64_t n = -1;
    if (sqlite3_open_v2(db, &h, SQLITE_OPEN_READONLY, NULL) == SQLITE_OK) {
        sqlite3_busy_timeout(h, 2000);
        sqlite3_stmt *st = NULL;
        if (sqlite3_prepare_v2(h, "SELECT count(*) FROM points", -1, &st, NULL) == SQLITE_OK && sqlite3_step(st) == SQLITE_ROW)
            n = sqlite3_column_int64(st, 0);
        sqlite3_finalize(st);
    }
    sqlite3_close(h);
    return n;
}

static bool same_file(const char *a, const char *b)
{
    FILE *f = fopen(a, "rb"), *g = fopen(b, "rb");
    bool same = f && g;
    while (same) {
        int x = fgetc(f), y = fgetc(g);
        if (x != y) same = false;
        if (x == EOF || y == EOF) break;
    }
    if (f) fclose(f);
    if (g) fclose(g);
    return same;
}

static double num(const json_t *o, const char *key)
{
    json_t *v = json_object_get(o, key);
    cr_assert(json_is_number(v), "%s is not a number", key);
    return json_number_value(v);
}

static json_t *cli_json(const char *args)
{
    char *out = NULL;
    int rc = test_run_cli_split(args, &out, NULL);
    cr_assert(rc == 0 || rc == 1, "%s: exit %d", args, rc);
    json_error_t je;
    json_t *o = json_loads(out, 0, &je);
    cr_assert_not_null(o, "%s: %s", args, je.text);
    free(out);
    return o;
}

Test(sweep, actuation_values_equal_orikin_actuate)
{
    char *dir = test_tmpdir();
    const char *db = fmt("%s/flap.db", dir);
    char *out = NULL;
    cr_assert_eq(test_run_cli(fmt("sweep tests/data/sweep/flap.json -o '%s' --quiet", db), &out), 0, "%s", out);
    free(out);
    json_t *pts = points_of(db);
    cr_assert_eq(json_array_size(pts), 4);
    int feasible = 0;
    for (size_t i = 0; i < 4; ++i) {
        json_t *p = json_array_get(pts, i);
        cr_assert_eq(json_integer_value(json_object_get(p, "idx")), (json_int_t)i);
        cr_assert_str_eq(json_string_value(json_object_get(p, "status")), "ok");
        double B = num(p, "B"), I = num(p, "I_max");
        // The last parameter varies fastest.
        cr_assert_eq(B, i < 2 ? 0.05 : 0.1);
        cr_assert_eq(I, i % 2 ? 0.03 : 0.02);
        json_t *c = cli_json(fmt("actuate examples/patterns/thesis-flap.fold --fix 0 --drive 0 --to 180 --step 10 --field 0,%.17g,0 "
                                 "--current-limit %.17g --json",
                                 B, I));
        // The same library calls on the same inputs: equal to the last bit (1e-15 relative allowed).
        double a = num(p, "current_needed"), b = num(c, "current_needed");
        cr_assert(fabs(a - b) <= 1e-15 * fabs(b), "point %zu: current %.17g, actuate %.17g", i, a, b);
        a = num(p, "mechanism_current"), b = num(c, "mechanism_current_needed");
        cr_assert(fabs(a - b) <= 1e-15 * fabs(b), "point %zu: mechanism current %.17g, actuate %.17g", i, a, b);
        cr_assert_eq(json_integer_value(json_object_get(p, "feasible")), json_is_true(json_object_get(c, "feasible")), "point %zu", i);
        cr_assert_eq(json_integer_value(json_object_get(p, "worst_edge")), json_integer_value(json_object_get(c, "worst_edge")));
        feasible += json_is_true(json_object_get(c, "feasible"));
        json_decref(c);
    }
    // The thesis: 0.1 T folds the flap with about 10 mA; 0.05 T needs twice that.
    json_t *p0 = json_array_get(pts, 0), *p2 = json_array_get(pts, 2);
    cr_assert(fabs(num(p0, "current_needed") / num(p2, "current_needed") - 2.0) < 1e-12);
    cr_assert(feasible >= 1 && feasible <= 3, "%d feasible", feasible);
    json_decref(pts);
    test_tmpdir_remove(dir);
}

Test(sweep, fold_and_layers_values_equal_orikin_fold_and_layers)
{
    char *dir = test_tmpdir();
    const char *spec = fmt("%s/corner.json", dir), *db = fmt("%s/corner.db", dir);
    write_text(spec, fmt("{\"base\": \"%s\", \"parameters\": [{\"name\": \"to\", \"values\": [30, 90, 150]}],"
                         " \"job\": {\"fold\": {\"fix\": 4, \"drive\": 12, \"lock\": [11], \"to\": \"$to\"}, \"collide\": true}}",
                         test_repo_path("examples/patterns/open-corner.fold")));
    char *out = NULL;
    cr_assert_eq(test_run_cli(fmt("sweep '%s' -o '%s' --quiet", spec, db), &out), 0, "%s", out);
    free(out);
    json_t *pts = points_of(db);
    cr_assert_eq(json_array_size(pts), 3);
    for (size_t i = 0; i < 3; ++i) {
        json_t *p = json_array_get(pts, i);
        json_t *c = cli_json(fmt("fold examples/patterns/open-corner.fold --fix 4 --drive 12 --lock 11 --to %g --json", num(p, "to")));
        cr_assert_str_eq(json_string_value(json_object_get(p, "verdict")), json_string_value(json_object_get(c, "verdict")), "to %g",
                         num(p, "to"));
        cr_assert_eq(json_integer_value(json_object_get(p, "collides")), !json_is_null(json_object_get(c, "collision")));
        if (strcmp(json_string_value(json_object_get(p, "verdict")), "valid") == 0) {
            cr_assert_eq(num(p, "reached"), 1.0);
            cr_assert_eq((size_t)num(p, "frames"), json_array_size(json_object_get(c, "frames")));
        }
        json_decref(c);
    }
    json_decref(pts);
    // Layers of generated Miura-ori, as orikin generate + orikin layers count them.
    spec = fmt("%s/layers.json", dir), db = fmt("%s/layers.db", dir);
    write_text(spec, "{\"base\": {\"generate\": \"miura\", \"rows\": \"$r\", \"cols\": 2},"
                     " \"parameters\": [{\"name\": \"r\", \"from\": 1, \"to\": 3, \"count\": 3}], \"job\": {\"layers\": true}}");
    cr_assert_eq(test_run_cli(fmt("sweep '%s' -o '%s' --quiet", spec, db), &out), 0, "%s", out);
    free(out);
    pts = points_of(db);
    cr_assert_eq(json_array_size(pts), 3);
    for (int r = 1; r <= 3; ++r) {
        const char *fold = fmt("%s/m%d.fold", dir, r);
        cr_assert_eq(test_run_cli(fmt("generate miura --rows %d --cols 2 -o '%s'", r, fold), &out), 0, "%s", out);
        free(out);
        json_t *c = cli_json(fmt("layers '%s' --json", fold));
        json_t *p = json_array_get(pts, (size_t)r - 1);
        cr_assert_str_eq(json_string_value(json_object_get(p, "layer_count")), json_string_value(json_object_get(c, "states")));
        json_decref(c);
    }
    json_decref(pts);
    test_tmpdir_remove(dir);
}

// --fold-files DIR: every point's fold as DIR/point-INDEX.fold, the base with the fold's last
// state appended: its fold angles are those of orikin fold at the point's parameters (to 1e-9
// degrees, the file's 17 digits), and it names its point and parameters.
Test(sweep, fold_files_hold_each_points_folded_state)
{
    char *dir = test_tmpdir();
    const char *spec = fmt("%s/corner.json", dir), *db = fmt("%s/corner.db", dir), *files = fmt("%s/points", dir);
    write_text(spec, fmt("{\"base\": \"%s\", \"parameters\": [{\"name\": \"to\", \"values\": [30, 90, 150]}],"
                         " \"job\": {\"fold\": {\"fix\": 4, \"drive\": 12, \"lock\": [11], \"to\": \"$to\"}}}",
                         test_repo_path("examples/patterns/open-corner.fold")));
    char *out = NULL;
    cr_assert_eq(test_run_cli(fmt("sweep '%s' -o '%s' --fold-files '%s' --quiet", spec, db, files), &out), 0, "%s", out);
    free(out);
    const double to[3] = {30, 90, 150};
    for (int i = 0; i < 3; ++i) {
        json_error_t je;
        json_t *doc = json_load_file(fmt("%s/point-%d.fold", files, i), 0, &je);
        cr_assert_not_null(doc, "point %d: %s", i, je.text);
        json_t *frames = json_object_get(doc, "file_frames");
        cr_assert_eq(json_array_size(frames), 1, "point %d: the base and one folded frame", i);
        json_t *fr = json_array_get(frames, 0);
        cr_assert_eq(json_integer_value(json_object_get(fr, "orikin:sweep_point")), i);
        cr_assert_float_eq(json_number_value(json_object_get(json_object_get(fr, "orikin:parameters"), "to")), to[i], 0.0);
        json_t *c = cli_json(fmt("fold examples/patterns/open-corner.fold --fix 4 --drive 12 --lock 11 --to %g --json", to[i]));
        json_t *frs = json_object_get(c, "frames");
        json_t *want = json_object_get(json_array_get(frs, json_array_size(frs) - 1), "fold_angles_deg");
        json_t *got = json_object_get(fr, "edges_foldAngle");
        cr_assert_eq(json_array_size(got), json_array_size(want), "point %d", i);
        for (size_t e = 0; e < json_array_size(want); ++e)
            cr_assert_float_eq(json_number_value(json_array_get(got, e)), json_number_value(json_array_get(want, e)), 1e-9,
                               "point %d crease %zu", i, e);
        json_decref(c);
        json_decref(doc);
    }
    // not a directory: refused before anything is computed
    write_text(fmt("%s/plain", dir), "x");
    cr_assert_eq(test_run_cli(fmt("sweep '%s' -o '%s/b.db' --fold-files '%s/plain' --quiet", spec, dir, dir), &out), 3, "%s", out);
    cr_assert(strstr(out, "not a directory"), "%s", out);
    free(out);
    test_tmpdir_remove(dir);
}

// job.sequence: the folds of a sequence file, with parameters, run on the base as orikin
// sequence runs the same file: the same verdict, states and collision; its --fold-files state is
// the sequence's last. A spec that mixes it with a fold or asks what it cannot give is refused.
Test(sweep, a_sequence_job_equals_orikin_sequence)
{
    char *dir = test_tmpdir();
    const char *corner = test_repo_path("examples/patterns/open-corner.fold");
    const char *spec = fmt("%s/seq.json", dir), *db = fmt("%s/seq.db", dir);
    char files[600];
    snprintf(files, sizeof files, "%s/points", dir);
    write_text(spec, fmt("{\"base\": \"%s\", \"parameters\": [{\"name\": \"a\", \"values\": [60, 180]},"
                         " {\"name\": \"b\", \"values\": [90, 180]}],"
                         " \"job\": {\"sequence\": {\"folds\": [{\"fix\": 4, \"drive\": 12, \"lock\": [11], \"to\": \"$a\", \"step\": 30},"
                         " {\"fix\": 4, \"drive\": 11, \"lock\": [12], \"to\": \"$b\", \"step\": 30}]}, \"collide\": true}}",
                         corner));
    char *out = NULL;
    cr_assert_eq(test_run_cli(fmt("sweep '%s' -o '%s' --fold-files '%s' --quiet", spec, db, files), &out), 0, "%s", out);
    free(out);
    json_t *pts = points_of(db);
    cr_assert_eq(json_array_size(pts), 4);
    int collided = 0;
    for (size_t i = 0; i < 4; ++i) {
        json_t *p = json_array_get(pts, i);
        const char *seq = fmt("%s/p%zu.seq.json", dir, i);
        write_text(seq, fmt("{\"pattern\": \"%s\", \"folds\": [{\"fix\": 4, \"drive\": 12, \"lock\": [11], \"to\": %g, \"step\": 30},"
                            " {\"fix\": 4, \"drive\": 11, \"lock\": [12], \"to\": %g, \"step\": 30}]}",
                            corner, num(p, "a"), num(p, "b")));
        json_t *c = cli_json(fmt("sequence '%s' --json", seq));
        bool collides = !json_is_null(json_object_get(c, "collision"));
        collided += collides;
        cr_assert_str_eq(json_string_value(json_object_get(p, "verdict")), collides ? "collision" : json_string_value(json_object_get(c, "verdict")),
                         "point %zu", i);
        cr_assert_eq(json_integer_value(json_object_get(p, "collides")), collides, "point %zu", i);
        if (!collides) {
            cr_assert_eq((size_t)num(p, "frames"), json_array_size(json_object_get(c, "frames")), "point %zu", i);
            // the folds done of the two (all of them when valid)
            bool valid = strcmp(json_string_value(json_object_get(c, "verdict")), "valid") == 0;
            cr_assert_float_eq(num(p, "reached"), valid ? 1.0 : num(c, "duration") / 2.0, 1e-15, "point %zu", i);
            // its FOLD file holds the sequence's last state
            json_error_t je;
            json_t *doc = json_load_file(fmt("%s/point-%zu.fold", files, i), 0, &je);
            cr_assert_not_null(doc, "%s", je.text);
            json_t *got = json_object_get(json_array_get(json_object_get(doc, "file_frames"), 0), "edges_foldAngle");
            json_t *frs = json_object_get(c, "frames");
            json_t *want = json_object_get(json_array_get(frs, json_array_size(frs) - 1), "fold_angles_deg");
            cr_assert_eq(json_array_size(got), json_array_size(want));
            for (size_t e = 0; e < json_array_size(want); ++e)
                cr_assert_float_eq(json_number_value(json_array_get(got, e)), json_number_value(json_array_get(want, e)), 1e-9,
                                   "point %zu crease %zu", i, e);
            json_decref(doc);
        }
        json_decref(c);
    }
    json_decref(pts);
    // refused before anything runs, naming the field
    static const char *const bad[][2] = {
        {"\"job\": {\"fold\": {\"drive\": 12, \"to\": 90}, \"sequence\": {\"folds\": []}}", "job.sequence: one motion per point"},
        {"\"job\": {\"sequence\": {\"folds\": [{\"drive\": 12, \"to\": 90}, {\"drive\": 11, \"to\": 400}]}}", "job.sequence.folds[1]"},
        {"\"job\": {\"sequence\": {\"folds\": [{\"drive\": 12, \"to\": 90}]}, \"actuate\": true}", "job.actuate"},
        {"\"job\": {\"sequence\": [1]}", "job.sequence: must be"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        write_text(spec, fmt("{\"base\": \"%s\", %s}", corner, bad[k][0]));
        cr_assert_eq(test_run_cli(fmt("sweep '%s' -o '%s/bad.db' --quiet", spec, dir), &out), 3, "%s: %s", bad[k][0], out);
        cr_assert(strstr(out, bad[k][1]), "%s: %s", bad[k][0], out);
        free(out);
    }
    test_tmpdir_remove(dir);
}

Test(sweep, fold_time_equals_orikin_simulate)
{
    char *dir = test_tmpdir();
    const char *spec = fmt("%s/sim.json", dir), *db = fmt("%s/sim.db", dir);
    write_text(spec, fmt("{\"base\": \"%s\", \"parameters\": [{\"name\": \"I\", \"values\": [0.015, 0.03]}],"
                         " \"job\": {\"simulate\": {\"current\": \"$I\", \"duration\": 0.01, \"fix\": 0}}}",
                         test_repo_path("examples/patterns/thesis-flap.fold")));
    char *out = NULL;
    cr_assert_eq(test_run_cli(fmt("sweep '%s' -o '%s' --quiet", spec, db), &out), 0, "%s", out);
    free(out);
    json_t *pts = points_of(db);
    cr_assert_eq(json_array_size(pts), 2);
    double t[2];
    for (size_t i = 0; i < 2; ++i) {
        json_t *p = json_array_get(pts, i);
        cr_assert_eq(json_integer_value(json_object_get(p, "sim_reached")), 1);
        json_t *c = cli_json(fmt("simulate examples/patterns/thesis-flap.fold --fix 0 --current %.17g --duration 0.01 --json", num(p, "I")));
        t[i] = num(p, "fold_time");
        cr_assert_eq(t[i], num(c, "time_to_target"), "I %g: %.17g vs %.17g", num(p, "I"), t[i], num(c, "time_to_target"));
        json_decref(c);
    }
    // The thesis flap folds within a few milliseconds, faster with more current.
    cr_assert(t[0] > 1e-3 && t[0] < 1e-2 && t[1] < t[0], "%g %g", t[0], t[1]);
    json_decref(pts);
    test_tmpdir_remove(dir);
}

Test(sweep, driven_wires_put_the_current_on_the_driven_crease)
{
    char *dir = test_tmpdir();
    const char *spec = fmt("%s/w.json", dir), *db = fmt("%s/w.db", dir);
    write_text(spec, "{\"base\": {\"generate\": \"miura\", \"rows\": 4, \"cols\": 4},"
                     " \"design\": {\"unit\": \"mm\", \"wires\": \"$wires\", \"hinge\": {\"material\": \"Au\", \"width\": 10e-6,"
                     " \"thickness\": 0.1e-6, \"wire\": {\"length\": 0.4e-3, \"lever\": 0.1e-3}}, \"panel\": {\"material\": \"Si\","
                     " \"thickness\": 10e-6}, \"field\": [0, 0.06, 0.08]},"
                     " \"parameters\": [{\"name\": \"wires\", \"values\": [\"driven\", \"every\"]}],"
                     " \"job\": {\"fold\": {\"drive\": 10, \"to\": -60}, \"actuate\": true}}");
    char *out = NULL;
    cr_assert_eq(test_run_cli(fmt("sweep '%s' -o '%s' --quiet", spec, db), &out), 0, "%s", out);
    free(out);
    json_t *pts = points_of(db);
    json_t *one = json_array_get(pts, 0), *all = json_array_get(pts, 1);
    cr_assert_str_eq(json_string_value(json_object_get(one, "status")), "ok");
    cr_assert_eq(json_integer_value(json_object_get(one, "worst_edge")), 10);
    // One wire must fold the whole mechanism alone: more current than when every crease pulls.
    cr_assert(num(one, "mechanism_current") > num(all, "mechanism_current"), "%g %g", num(one, "mechanism_current"),
              num(all, "mechanism_current"));
    json_decref(pts);
    test_tmpdir_remove(dir);
}

Test(sweep, a_killed_run_resumes_with_only_the_missing_points)
{
    char *dir = test_tmpdir();
    const char *ref = fmt("%s/ref.db", dir);
    char *out = NULL;
    cr_assert_eq(test_run_cli(fmt("sweep tests/data/sweep/kill.json -o '%s' --quiet", ref), &out), 0, "%s", out);
    free(out);
    const char *db = fmt("%s/killed.db", dir);
    pid_t pid = fork();
    cr_assert_geq(pid, 0);
    if (pid == 0) {
        if (chdir(ORI_SOURCE_DIR) != 0) _exit(100);
        execl(ORI_CLI_PATH, ORI_CLI_PATH, "sweep", "tests/data/sweep/kill.json", "-o", db, "--commit", "1", "--quiet", (char *)NULL);
        _exit(101);
    }
    // Kill it once some points are stored (polling the database as another reader would).
    int64_t n = 0;
    for (int k = 0; k < 60000 && n < 25; ++k) {
        struct timespec ts = {0, 2000000};
        nanosleep(&ts, NULL);
        if (access(db, R_OK) == 0) n = row_count(db);
    }
    kill(pid, SIGKILL);
    int status;
    waitpid(pid, &status, 0);
    cr_assert(WIFSIGNALED(status), "the run ended before it was killed");
    int64_t kept = row_count(db);
    cr_assert(kept >= 25 && kept < 240, "%lld points kept", (long long)kept);
    // The resumed run computes exactly the others.
    char *err = NULL;
    cr_assert_eq(test_run_cli_split(fmt("sweep tests/data/sweep/kill.json -o '%s'", db), &out, &err), 0, "%s", err);
    cr_assert(strstr(err, fmt("240 points, %lld stored in", (long long)kept)), "%s", err);
    cr_assert(strstr(out, fmt("%lld points computed", (long long)(240 - kept))), "%s", out);
    cr_assert(strstr(out, "240 of 240 stored"), "%s", out);
    free(out);
    free(err);
    // A third run has nothing left to do.
    cr_assert_eq(test_run_cli(fmt("sweep tests/data/sweep/kill.json -o '%s' --quiet", db), &out), 0);
    cr_assert(strstr(out, "0 points computed"), "%s", out);
    free(out);
    char *a = rows_of(ref), *b = rows_of(db);
    cr_assert_str_eq(a, b);
    // Every row is a real answer: folds up to 170 deg of the 10 x 10 Miura-ori.
    cr_assert(strstr(a, "\"verdict\":\"valid\""));
    free(a);
    free(b);
    test_tmpdir_remove(dir);
}

Test(sweep, shards_merged_equal_one_run)
{
    char *dir = test_tmpdir();
    const char *one = fmt("%s/one.db", dir);
    char *out = NULL;
    const char *spec = "tests/data/sweep/flap.json";
    cr_assert_eq(test_run_cli(fmt("sweep %s -o '%s' --quiet", spec, one), &out), 0, "%s", out);
    free(out);
    for (int i = 0; i < 3; ++i) {
        cr_assert_eq(test_run_cli(fmt("sweep %s -o '%s/s%d.db' --shard %d/3 --quiet", spec, dir, i, i), &out), 0, "%s", out);
        free(out);
    }
    cr_assert_eq(row_count(fmt("%s/s0.db", dir)), 2); // points 0 and 3
    cr_assert_eq(row_count(fmt("%s/s1.db", dir)), 1);
    const char *merged = fmt("%s/merged.db", dir);
    cr_assert_eq(test_run_cli(fmt("sweep --merge '%s' '%s/s2.db' '%s/s0.db' '%s/s1.db'", merged, dir, dir, dir), &out), 0, "%s", out);
    free(out);
    char *a = rows_of(one), *b = rows_of(merged);
    cr_assert_str_eq(a, b);
    free(a);
    free(b);
    // A shard of another spec is refused, naming it; nothing is written.
    const char *other = fmt("%s/other.json", dir), *odb = fmt("%s/other.db", dir);
    write_text(other, fmt("{\"base\": \"%s\", \"job\": {\"layers\": true}}", test_repo_path("examples/patterns/thesis-flap.fold")));
    cr_assert_eq(test_run_cli(fmt("sweep '%s' -o '%s' --quiet", other, odb), &out), 0, "%s", out);
    free(out);
    const char *bad = fmt("%s/bad.db", dir);
    cr_assert_eq(test_run_cli(fmt("sweep --merge '%s' '%s/s0.db' '%s'", bad, dir, odb), &out), 3);
    cr_assert(strstr(out, "comes from another spec"), "%s", out);
    free(out);
    cr_assert_neq(access(bad, F_OK), 0);
    // Resuming into a database of another spec is refused too.
    cr_assert_eq(test_run_cli(fmt("sweep '%s' -o '%s' --quiet", other, one), &out), 3);
    cr_assert(strstr(out, "holds the results of another spec"), "%s", out);
    free(out);
    test_tmpdir_remove(dir);
}

Test(sweep, seeded_draws_are_reproducible_and_follow_their_distribution)
{
    char *dir = test_tmpdir();
    const char *spec = fmt("%s/mc.json", dir);
    write_text(spec, fmt("{\"base\": \"%s\", \"design\": {\"field\": [0, \"$B\", 0], \"current_limit\": \"$I\"},"
                         " \"parameters\": [{\"name\": \"B\", \"uniform\": [0.05, 0.1]}, {\"name\": \"I\", \"normal\": [0.02, 0.002]}],"
                         " \"samples\": 400, \"seed\": 42, \"job\": {\"fold\": {\"fix\": 0, \"drive\": 0, \"to\": 90, \"step\": 30},"
                         " \"actuate\": true}, \"outputs\": [\"current_needed\"]}",
                         test_repo_path("examples/patterns/thesis-flap.fold")));
    char *out = NULL;
    cr_assert_eq(test_run_cli(fmt("sweep '%s' -o '%s/a.db' --quiet", spec, dir), &out), 0, "%s", out);
    free(out);
    cr_assert_eq(test_run_cli(fmt("sweep '%s' -o '%s/b.db' --quiet --shard 1/2", spec, dir), &out), 0, "%s", out);
    free(out);
    json_t *a = points_of(fmt("%s/a.db", dir)), *b = points_of(fmt("%s/b.db", dir));
    cr_assert_eq(json_array_size(a), 400);
    cr_assert_eq(json_array_size(b), 200);
    double sb = 0, si = 0, si2 = 0;
    for (size_t i = 0; i < 400; ++i) {
        json_t *p = json_array_get(a, i);
        double B = num(p, "B"), I = num(p, "I");
        cr_assert(B >= 0.05 && B < 0.1);
        sb += B, si += I, si2 += I * I;
        cr_assert_eq(json_integer_value(json_object_get(p, "sample")), (json_int_t)i);
        if (i % 2 == 1) { // the shard drew the same values for the same points
            json_t *q = json_array_get(b, i / 2);
            cr_assert_eq(num(q, "B"), B);
            cr_assert_eq(num(q, "I"), I);
            cr_assert_eq(num(q, "current_needed"), num(p, "current_needed"));
        }
        // The current needed scales as 1/B (the Lorentz moment is linear in B): a real figure per draw.
        double c0 = num(json_array_get(a, 0), "current_needed") * num(json_array_get(a, 0), "B");
        cr_assert(fabs(num(p, "current_needed") * B - c0) < 1e-9 * c0, "B %g: %.17g", B, num(p, "current_needed") * B);
    }
    double mi = si / 400, sd = sqrt(si2 / 400 - mi * mi);
    // Means within 4 standard errors, the spread within 15 %.
    cr_assert(fabs(sb / 400 - 0.075) < 4 * 0.05 / sqrt(12.0) / 20, "uniform mean %g", sb / 400);
    cr_assert(fabs(mi - 0.02) < 4 * 0.002 / 20, "normal mean %g", mi);
    cr_assert(fabs(sd - 0.002) < 0.15 * 0.002, "normal sd %g", sd);
    json_decref(a);
    json_decref(b);
    test_tmpdir_remove(dir);
}

Test(sweep, a_failed_point_records_its_error_and_the_sweep_goes_on)
{
    char *dir = test_tmpdir();
    const char *spec = fmt("%s/f.json", dir), *db = fmt("%s/f.db", dir);
    write_text(spec, fmt("{\"base\": \"%s\", \"parameters\": [{\"name\": \"e\", \"values\": [12, 999]}],"
                         " \"job\": {\"fold\": {\"fix\": 4, \"drive\": \"$e\", \"lock\": [11], \"to\": 60}}}",
                         test_repo_path("examples/patterns/open-corner.fold")));
    char *out = NULL;
    cr_assert_eq(test_run_cli(fmt("sweep '%s' -o '%s' --quiet", spec, db), &out), 0, "%s", out);
    cr_assert(strstr(out, "2 points computed"), "%s", out);
    cr_assert(strstr(out, "1 failed"), "%s", out);
    free(out);
    json_t *pts = points_of(db);
    cr_assert_str_eq(json_string_value(json_object_get(json_array_get(pts, 0), "status")), "ok");
    json_t *p2 = json_array_get(pts, 1);
    cr_assert_str_eq(json_string_value(json_object_get(p2, "status")), "error");
    cr_assert(strstr(json_string_value(json_object_get(p2, "error")), "job.fold.drive: no edge 999"), "%s",
              json_string_value(json_object_get(p2, "error")));
    cr_assert(json_is_null(json_object_get(p2, "verdict")));
    json_decref(pts);
    test_tmpdir_remove(dir);
}

#ifdef ORI_SWEEP_MPI
// mpirun as root needs the two OMPI_ALLOW_RUN_AS_ROOT variables; loopback only.
static int mpirun(int np, const char *args)
{
    char cmd[8192];
    snprintf(cmd, sizeof cmd,
             "cd '%s' && ASAN_OPTIONS=detect_leaks=0 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_oob_tcp_if_include=lo "
             "OMPI_MCA_rmaps_base_oversubscribe=1 '%s' --oversubscribe -np %d '%s' %s > /dev/null 2>&1",
             ORI_SOURCE_DIR, ORI_MPIEXEC, np, ORI_SWEEP_MPI, args);
    int st = system(cmd);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

Test(sweep, mpi_databases_are_identical_for_1_2_3_ranks)
{
    char *dir = test_tmpdir();
    const char *serial = fmt("%s/serial.db", dir);
    char *out = NULL;
    cr_assert_eq(test_run_cli(fmt("sweep tests/data/sweep/mpi.json -o '%s' --quiet", serial), &out), 0, "%s", out);
    free(out);
    char *want = rows_of(serial);
    cr_assert(strstr(want, "\"status\":\"ok\""));
    for (int np = 1; np <= 3; ++np) {
        const char *db = fmt("%s/np%d.db", dir, np);
        cr_assert_eq(mpirun(np, fmt("tests/data/sweep/mpi.json -o '%s' --quiet", db)), 0, "np %d", np);
        char *got = rows_of(db);
        cr_assert_str_eq(got, want, "np %d", np);
        free(got);
        // Written in point order in the same transactions: the same file, byte for byte.
        cr_assert(same_file(db, serial), "np %d: %s differs from the serial database", np, db);
    }
    // The points' FOLD files are the same, byte for byte, whichever rank computed them.
    char serial_files[600], mpi_files[600]; // (kept: fmt's ring is reused by the loop below)
    snprintf(serial_files, sizeof serial_files, "%s/serial-files", dir);
    snprintf(mpi_files, sizeof mpi_files, "%s/mpi-files", dir);
    cr_assert_eq(test_run_cli(fmt("sweep tests/data/sweep/mpi.json -o '%s/f1.db' --fold-files '%s' --quiet", dir, serial_files), &out), 0,
                 "%s", out);
    free(out);
    cr_assert_eq(mpirun(2, fmt("tests/data/sweep/mpi.json -o '%s/f2.db' --fold-files '%s' --quiet", dir, mpi_files)), 0);
    for (int i = 0; i < 36; ++i)
        cr_assert(same_file(fmt("%s/point-%d.fold", serial_files, i), fmt("%s/point-%d.fold", mpi_files, i)), "point %d", i);
    // An MPI run resumes a serial one that stopped halfway (a shard's points are there).
    const char *half = fmt("%s/half.db", dir);
    cr_assert_eq(test_run_cli(fmt("sweep tests/data/sweep/mpi.json -o '%s' --quiet --shard 0/2", half), &out), 0, "%s", out);
    free(out);
    cr_assert_eq(mpirun(2, fmt("tests/data/sweep/mpi.json -o '%s' --quiet", half)), 0);
    char *got = rows_of(half);
    cr_assert_str_eq(got, want);
    free(got);
    free(want);
    test_tmpdir_remove(dir);
}
#endif

#ifdef ORI_LAYERS_MPI
// orikin-layers-mpi under mpirun: stdout into *out (malloc'd); the exit code.
static int layers_mpirun(int np, const char *dir, const char *args, char **out)
{
    const char *file = fmt("%s/layers-np%d.out", dir, np);
    char cmd[8192];
    snprintf(cmd, sizeof cmd,
             "cd '%s' && ASAN_OPTIONS=detect_leaks=0 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_oob_tcp_if_include=lo "
             "OMPI_MCA_rmaps_base_oversubscribe=1 '%s' --oversubscribe -np %d '%s' %s > '%s' 2>/dev/null",
             ORI_SOURCE_DIR, ORI_MPIEXEC, np, ORI_LAYERS_MPI, args, file);
    int st = system(cmd);
    *out = test_read_text(file);
    cr_assert_not_null(*out);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

// The count of FILE on 1, 2 and 3 ranks prints exactly what `orikin layers FILE --count` and
// `--count --json` print (the same exit code too); returns the serial JSON.
static json_t *layers_same_on_every_rank_count(const char *file, const char *extra, int want_rc)
{
    char *dir = test_tmpdir();
    char *text = NULL, *json = NULL;
    cr_assert_eq(test_run_cli_split(fmt("layers '%s' --count %s", file, extra), &text, NULL), want_rc, "%s", file);
    cr_assert_eq(test_run_cli_split(fmt("layers '%s' --count --json %s", file, extra), &json, NULL), want_rc, "%s", file);
    for (int np = 1; np <= 3; ++np) {
        char *got = NULL;
        cr_assert_eq(layers_mpirun(np, dir, fmt("'%s' %s", file, extra), &got), want_rc, "%s np %d", file, np);
        cr_assert_str_eq(got, text, "%s np %d", file, np);
        free(got);
        cr_assert_eq(layers_mpirun(np, dir, fmt("'%s' --json %s", file, extra), &got), want_rc, "%s np %d", file, np);
        cr_assert_str_eq(got, json, "%s np %d --json", file, np);
        free(got);
    }
    json_t *o = json_loads(json, 0, NULL);
    cr_assert_not_null(o);
    free(text);
    free(json);
    test_tmpdir_remove(dir);
    return o;
}

// The product of the component counts (small enough for 64 bits here) is the state count.
static void assert_product(const json_t *o, int64_t states, size_t min_components)
{
    const json_t *c = json_object_get(o, "components");
    cr_assert_geq(json_array_size(c), min_components);
    int64_t prod = 1;
    for (size_t i = 0; i < json_array_size(c); ++i) prod *= json_integer_value(json_array_get(c, i));
    cr_assert_eq(prod, states);
    cr_assert_str_eq(json_string_value(json_object_get(o, "states")), fmt("%" PRId64, states));
}

Test(sweep, mpi_layer_counts_equal_the_serial_count_for_1_2_3_ranks)
{
    // Corner flaps that never overlap one another: each U flap is a component of its own
    // (2 states), the M flap is fixed by its assignment: |1|2|2|2|2|2|, 32 states.
    json_t *o = layers_same_on_every_rank_count("tests/data/layers/corner-flaps.fold", "", 0);
    assert_product(o, 32, 6);
    json_decref(o);
    // Decided at set-up (a vertex that is not locally flat-foldable): no counting, exit 1.
    o = layers_same_on_every_rank_count("examples/patterns/non-flat-foldable-vertex.fold", "", 1);
    cr_assert_str_eq(json_string_value(json_object_get(json_object_get(o, "unsatisfiable"), "constraint")), "local");
    json_decref(o);
    // A bad file (exit 3) and a bad option (exit 2) on every rank: nothing on stdout.
    char *dir = test_tmpdir(), *got = NULL;
    cr_assert_eq(layers_mpirun(2, dir, "tests/data/bad-json.fold", &got), 3);
    cr_assert_str_eq(got, "");
    free(got);
    cr_assert_eq(layers_mpirun(2, dir, "tests/data/layers/corner-flaps.fold --limit 0", &got), 2);
    cr_assert_str_eq(got, "");
    free(got);
    test_tmpdir_remove(dir);
}

Test(sweep, mpi_layer_counts_of_corpus_patterns_equal_the_serial_count)
{
    const char *grid = test_require_shared("flat-folder-corpus/grids/002_brown_2x2_D1.fold");
    json_t *o = layers_same_on_every_rank_count(grid, "", 0);
    assert_product(o, 16, 5); // Flat-Folder's row: |1|2|2|2|2|, 16 states
    json_decref(o);
    // Components of different sizes (Flat-Folder's row: |1|3|3|492|, 4428 states) ...
    const char *bird = test_require_shared("flat-folder-corpus/instagram/003_ku_Triangle_Bird.fold");
    o = layers_same_on_every_rank_count(bird, "", 0);
    assert_product(o, 4428, 4);
    json_decref(o);
    // ... and with a limit: the big component stops at 100, the count is a lower bound.
    o = layers_same_on_every_rank_count(bird, "--limit 100", 5);
    cr_assert(json_is_true(json_object_get(o, "limited")));
    assert_product(o, 900, 4);
    json_decref(o);
}
#endif
