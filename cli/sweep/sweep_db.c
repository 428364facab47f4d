// The results database (SQLite): table sweep (key, value) holds the spec, its hash and the point
// count; table points one row per design point: idx (the point's index), sample, one column per
// parameter, status ("ok" or "error"), error, one column per output. Rows are written in point
// order in transactions of a fixed number of points, so that a run killed midway keeps every
// committed point and a resumed run computes only the others; the same rows written the same way
// give the same file, whoever computed them.
#define _POSIX_C_SOURCE 200809L
#include "sweep.h"
#include "sweep_internal.h"

#include <sqlite3.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define SWEEP_DB_FORMAT "1"

struct sweep_db {
    sqlite3 *db;
    sqlite3_stmt *insert;
    const sweep_spec *spec;
    bool in_transaction;
};

static int db_fail(char *err, size_t n, const char *path, sqlite3 *db, const char *what)
{
    return sweep_fail(err, n, "%s: %s: %s", path, what, db ? sqlite3_errmsg(db) : "cannot open");
}

static void quote_ident(char *out, size_t size, const char *name)
{
    snprintf(out, size, "\"%s\"", name); // names are identifiers (checked with the spec)
}

static char *create_sql(const sweep_spec *spec)
{
    size_t cap = 4096;
    char *s = malloc(cap);
    int len = snprintf(s, cap, "CREATE TABLE points(idx INTEGER PRIMARY KEY, sample INTEGER NOT NULL");
    for (int j = 0; j < spec->param_count; ++j) {
        char q[SWEEP_NAME_MAX + 4];
        quote_ident(q, sizeof q, spec->params[j].name);
        // Lists may mix numbers and strings: no type (values kept as given); the others REAL.
        len += snprintf(s + len, cap - (size_t)len, ", %s%s", q, spec->params[j].kind == SWEEP_LIST ? "" : " REAL");
    }
    len += snprintf(s + len, cap - (size_t)len, ", status TEXT NOT NULL, error TEXT");
    for (int o = 0; o < SWEEP_OUT_COUNT; ++o)
        if (spec->outputs[o]) len += snprintf(s + len, cap - (size_t)len, ", %s %s", sweep_output_name(o), sweep_output_sql_type(o));
    snprintf(s + len, cap - (size_t)len, ")");
    return s;
}

static int exec(sqlite3 *db, const char *sql, const char *path, char *err, size_t n)
{
    if (sqlite3_exec(db, sql, NULL, NULL, NULL) != SQLITE_OK) return db_fail(err, n, path, db, sql);
    return 0;
}

// The value of a key of table sweep (malloc'd) or NULL.
static char *meta(sqlite3 *db, const char *schema, const char *key)
{
    char sql[128];
    snprintf(sql, sizeof sql, "SELECT value FROM %s.sweep WHERE key = ?", schema);
    sqlite3_stmt *st = NULL;
    char *v = NULL;
    if (sqlite3_prepare_v2(db, sql, -1, &st, NULL) == SQLITE_OK) {
        sqlite3_bind_text(st, 1, key, -1, SQLITE_STATIC);
        if (sqlite3_step(st) == SQLITE_ROW && sqlite3_column_text(st, 0)) v = strdup((const char *)sqlite3_column_text(st, 0));
    }
    sqlite3_finalize(st);
    return v;
}

static bool has_table(sqlite3 *db, const char *schema, const char *name)
{
    char sql[160];
    snprintf(sql, sizeof sql, "SELECT count(*) FROM %s.sqlite_master WHERE type = 'table' AND name = ?", schema);
    sqlite3_stmt *st = NULL;
    bool yes = false;
    if (sqlite3_prepare_v2(db, sql, -1, &st, NULL) == SQLITE_OK) {
        sqlite3_bind_text(st, 1, name, -1, SQLITE_STATIC);
        yes = sqlite3_step(st) == SQLITE_ROW && sqlite3_column_int(st, 0) > 0;
    }
    sqlite3_finalize(st);
    return yes;
}

static int prepare_insert(sweep_db *d, const char *path, char *err, size_t n)
{
    int cols = 2 + d->spec->param_count + 2;
    for (int o = 0; o < SWEEP_OUT_COUNT; ++o) cols += d->spec->outputs[o];
    char sql[2048] = "INSERT INTO points VALUES (?";
    for (int i = 1; i < cols; ++i) strcat(sql, ", ?");
    strcat(sql, ")");
    if (sqlite3_prepare_v2(d->db, sql, -1, &d->insert, NULL) != SQLITE_OK) return db_fail(err, n, path, d->db, "prepare");
    return 0;
}

int sweep_db_open(const char *path, const sweep_spec *spec, sweep_db **out, char *err, size_t n)
{
    *out = NULL;
    sweep_db *d = calloc(1, sizeof *d);
    d->spec = spec;
    int rc = 0;
    if (sqlite3_open_v2(path, &d->db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, NULL) != SQLITE_OK) {
        rc = db_fail(err, n, path, d->db, "cannot open");
        goto fail;
    }
    sqlite3_busy_timeout(d->db, 10000);
    // Commits survive a killed process in any mode; NORMAL syncs less often than FULL (the file
    // is the same: only when it reaches the disk changes).
    sqlite3_exec(d->db, "PRAGMA synchronous = NORMAL", NULL, NULL, NULL);
    if (!has_table(d->db, "main", "sweep")) {
        if (has_table(d->db, "main", "points") || sqlite3_exec(d->db, "SELECT 1 FROM sqlite_master", NULL, NULL, NULL) != SQLITE_OK) {
            rc = sweep_fail(err, n, "%s: not a sweep database", path);
            goto fail;
        }
        char *create = create_sql(spec);
        char points[32];
        snprintf(points, sizeof points, "%lld", (long long)spec->point_count);
        sqlite3_stmt *st = NULL;
        rc = exec(d->db, "BEGIN", path, err, n);
        if (!rc) rc = exec(d->db, "CREATE TABLE sweep(key TEXT PRIMARY KEY, value TEXT NOT NULL)", path, err, n);
        if (!rc) rc = exec(d->db, create, path, err, n);
        free(create);
        const char *kv[][2] = {{"format", SWEEP_DB_FORMAT}, {"spec_hash", spec->hash},  {"spec", spec->canonical},
                               {"points", points},          {"spec_file", spec->path}, {"orikin", ori_version_string()}};
        if (!rc && sqlite3_prepare_v2(d->db, "INSERT INTO sweep VALUES (?, ?)", -1, &st, NULL) != SQLITE_OK)
            rc = db_fail(err, n, path, d->db, "prepare");
        for (size_t i = 0; !rc && i < sizeof kv / sizeof kv[0]; ++i) {
            sqlite3_bind_text(st, 1, kv[i][0], -1, SQLITE_STATIC);
            sqlite3_bind_text(st, 2, kv[i][1], -1, SQLITE_STATIC);
            if (sqlite3_step(st) != SQLITE_DONE) rc = db_fail(err, n, path, d->db, "write");
            sqlite3_reset(st);
        }
        sqlite3_finalize(st);
        if (!rc) rc = exec(d->db, "COMMIT", path, err, n);
        if (rc) goto fail;
    } else {
        char *hash = meta(d->db, "main", "spec_hash");
        bool same = hash && strcmp(hash, spec->hash) == 0;
        if (!same)
            rc = sweep_fail(err, n, "%s: holds the results of another spec or base file (hash %s, this spec %s): use another -o or remove it",
                            path, hash ? hash : "none", spec->hash);
        free(hash);
        if (rc) goto fail;
    }
    if ((rc = prepare_insert(d, path, err, n))) goto fail;
    *out = d;
    return 0;
fail:
    sqlite3_finalize(d->insert);
    sqlite3_close(d->db);
    free(d);
    return rc ? rc : SWEEP_EXIT_INPUT;
}

int64_t sweep_db_done(sweep_db *d, unsigned char *done)
{
    sqlite3_stmt *st = NULL;
    int64_t count = 0;
    if (sqlite3_prepare_v2(d->db, "SELECT idx FROM points", -1, &st, NULL) != SQLITE_OK) return 0;
    while (sqlite3_step(st) == SQLITE_ROW) {
        int64_t i = sqlite3_column_int64(st, 0);
        if (i >= 0 && i < d->spec->point_count && !done[i]) {
            done[i] = 1;
            count++;
        }
    }
    sqlite3_finalize(st);
    return count;
}

int sweep_db_put(sweep_db *d, const sweep_result *r, char *err, size_t n)
{
    if (!d->in_transaction) {
        if (exec(d->db, "BEGIN IMMEDIATE", "database", err, n)) return SWEEP_EXIT_INPUT;
        d->in_transaction = true;
    }
    sqlite3_stmt *st = d->insert;
    sweep_value values[SWEEP_MAX_PARAMS];
    int64_t sample;
    sweep_point_values(d->spec, r->index, values, &sample);
    int c = 1;
    sqlite3_bind_int64(st, c++, r->index);
    sqlite3_bind_int64(st, c++, sample);
    for (int j = 0; j < d->spec->param_count; ++j, ++c) {
        if (values[j].is_string) sqlite3_bind_text(st, c, values[j].string, -1, SQLITE_TRANSIENT);
        else sqlite3_bind_double(st, c, values[j].number);
    }
    sqlite3_bind_text(st, c++, r->ok ? "ok" : "error", -1, SQLITE_STATIC);
    if (r->ok) sqlite3_bind_null(st, c++);
    else sqlite3_bind_text(st, c++, r->error, -1, SQLITE_TRANSIENT);
    for (int o = 0; o < SWEEP_OUT_COUNT; ++o) {
        if (!d->spec->outputs[o]) continue;
        if (!r->has[o]) sqlite3_bind_null(st, c);
        else if (o == SWEEP_OUT_VERDICT) sqlite3_bind_text(st, c, r->verdict, -1, SQLITE_TRANSIENT);
        else if (o == SWEEP_OUT_LAYER_COUNT) sqlite3_bind_text(st, c, r->layer_count, -1, SQLITE_TRANSIENT);
        else if (strcmp(sweep_output_sql_type(o), "INTEGER") == 0) sqlite3_bind_int64(st, c, (sqlite3_int64)r->real[o]);
        else sqlite3_bind_double(st, c, r->real[o]);
        c++;
    }
    int rc = sqlite3_step(st);
    sqlite3_reset(st);
    sqlite3_clear_bindings(st);
    if (rc != SQLITE_DONE) return sweep_fail(err, n, "database: cannot store point %lld: %s", (long long)r->index, sqlite3_errmsg(d->db));
    return 0;
}

int sweep_db_commit(sweep_db *d, char *err, size_t n)
{
    if (!d->in_transaction) return 0;
    d->in_transaction = false;
    return exec(d->db, "COMMIT", "database", err, n);
}

void sweep_db_close(sweep_db *d)
{
    if (!d) return;
    if (d->in_transaction) sqlite3_exec(d->db, "ROLLBACK", NULL, NULL, NULL);
    sqlite3_finalize(d->insert);
    sqlite3_close(d->db);
    free(d);
}

// --- merge ----------------------------------------------------------------------------------

static char *table_sql(sqlite3 *db, const char *schema, const char *name)
{
    char sql[160];
    snprintf(sql, sizeof sql, "SELECT sql FROM %s.sqlite_master WHERE type = 'table' AND name = ?", schema);
    sqlite3_stmt *st = NULL;
    char *v = NULL;
    if (sqlite3_prepare_v2(db, sql, -1, &st, NULL) == SQLITE_OK) {
        sqlite3_bind_text(st, 1, name, -1, SQLITE_STATIC);
        if (sqlite3_step(st) == SQLITE_ROW && sqlite3_column_text(st, 0)) v = strdup((const char *)sqlite3_column_text(st, 0));
    }
    sqlite3_finalize(st);
    return v;
}

static int64_t scalar(sqlite3 *db, const char *sql)
{
    sqlite3_stmt *st = NULL;
    int64_t v = -1;
    if (sqlite3_prepare_v2(db, sql, -1, &st, NULL) == SQLITE_OK && sqlite3_step(st) == SQLITE_ROW) v = sqlite3_column_int64(st, 0);
    sqlite3_finalize(st);
    return v;
}

int sweep_db_merge(const char *out, char **inputs, int count, char *err, size_t n)
{
    for (int i = 0; i < count; ++i)
        if (strcmp(inputs[i], out) == 0) return sweep_fail(err, n, "%s: the output cannot be one of the inputs", out);
    char tmp[4096];
    snprintf(tmp, sizeof tmp, "%s.tmp.%ld", out, (long)getpid());
    unlink(tmp);
    sqlite3 *db = NULL;
    int rc = 0;
    char *hash = NULL, *schema = NULL;
    if (sqlite3_open_v2(tmp, &db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, NULL) != SQLITE_OK) {
        rc = db_fail(err, n, out, db, "cannot create");
        goto done;
    }
    for (int i = 0; i < count && !rc; ++i) {
        const char *in = inputs[i];
        if (access(in, R_OK) != 0) {
            rc = sweep_fail(err, n, "%s: cannot read it", in);
            break;
        }
        sqlite3_stmt *st = NULL;
        if (sqlite3_prepare_v2(db, "ATTACH ? AS src", -1, &st, NULL) != SQLITE_OK) rc = db_fail(err, n, in, db, "attach");
        if (!rc) {
            sqlite3_bind_text(st, 1, in, -1, SQLITE_STATIC);
            if (sqlite3_step(st) != SQLITE_DONE) rc = db_fail(err, n, in, db, "cannot open");
        }
        sqlite3_finalize(st);
        if (!rc) rc = exec(db, "BEGIN", out, err, n);
        if (rc) break;
        char *h = has_table(db, "src", "sweep") ? meta(db, "src", "spec_hash") : NULL;
        char *s = h ? table_sql(db, "src", "points") : NULL;
        if (!h || !s) rc = sweep_fail(err, n, "%s: not a sweep database", in);
        else if (!hash) {
            // The first input gives the spec and the table.
            hash = h, schema = s, h = s = NULL;
            rc = exec(db, "CREATE TABLE sweep(key TEXT PRIMARY KEY, value TEXT NOT NULL)", out, err, n);
            if (!rc) rc = exec(db, "INSERT INTO sweep SELECT * FROM src.sweep ORDER BY key", out, err, n);
            if (!rc) rc = exec(db, schema, out, err, n);
        } else if (strcmp(h, hash) != 0) {
            rc = sweep_fail(err, n, "%s: comes from another spec (hash %s, %s has %s): shards of one sweep only", in, h, inputs[0], hash);
        } else if (strcmp(s, schema) != 0) {
            rc = sweep_fail(err, n, "%s: its points table differs from %s's", in, inputs[0]);
        }
        free(h);
        free(s);
        if (!rc) {
            int64_t clash = scalar(db, "SELECT count(*) FROM (SELECT * FROM src.points WHERE idx IN (SELECT idx FROM main.points) "
                                       "EXCEPT SELECT * FROM main.points)");
            if (clash != 0)
                rc = sweep_fail(err, n, "%s: %lld points disagree with the same points of an earlier input", in, (long long)clash);
        }
        if (!rc) rc = exec(db, "INSERT OR IGNORE INTO main.points SELECT * FROM src.points ORDER BY idx", out, err, n);
        if (!rc) rc = exec(db, "COMMIT", out, err, n);
        if (!rc) rc = exec(db, "DETACH src", out, err, n);
    }
done:
    sqlite3_close(db);
    free(hash);
    free(schema);
    if (!rc && rename(tmp, out) != 0) rc = sweep_fail(err, n, "%s: cannot write it", out);
    if (rc) unlink(tmp);
    return rc;
}

// --- export ---------------------------------------------------------------------------------

typedef struct buf {
    char *s;
    size_t len, cap;
} buf;

static void put(buf *b, const char *s, size_t n)
{
    if (b->len + n + 1 > b->cap) {
        b->cap = (b->len + n + 1) * 2;
        b->s = realloc(b->s, b->cap);
    }
    memcpy(b->s + b->len, s, n);
    b->len += n;
    b->s[b->len] = '\0';
}
static void puts_(buf *b, const char *s) { put(b, s, strlen(s)); }

static void csv_text(buf *b, const char *s)
{
    if (!strpbrk(s, ",\"\n\r")) {
        puts_(b, s);
        return;
    }
    put(b, "\"", 1);
    for (const char *p = s; *p; ++p) put(b, p, 1), *p == '"' ? put(b, "\"", 1) : (void)0;
    put(b, "\"", 1);
}

int sweep_db_export(const char *path, const char *out, bool jsonl, char *err, size_t n)
{
    sqlite3 *db = NULL;
    if (access(path, R_OK) != 0) return sweep_fail(err, n, "%s: cannot read it", path);
    if (sqlite3_open_v2(path, &db, SQLITE_OPEN_READONLY, NULL) != SQLITE_OK) {
        int rc = db_fail(err, n, path, db, "cannot open");
        sqlite3_close(db);
        return rc;
    }
    if (!has_table(db, "main", "sweep") || !has_table(db, "main", "points")) {
        sqlite3_close(db);
        return sweep_fail(err, n, "%s: not a sweep database", path);
    }
    sqlite3_stmt *st = NULL;
    if (sqlite3_prepare_v2(db, "SELECT * FROM points ORDER BY idx", -1, &st, NULL) != SQLITE_OK) {
        int rc = db_fail(err, n, path, db, "read");
        sqlite3_close(db);
        return rc;
    }
    int cols = sqlite3_column_count(st);
    buf b = {0};
    puts_(&b, "");
    if (!jsonl) {
        for (int c = 0; c < cols; ++c) {
            if (c) put(&b, ",", 1);
            csv_text(&b, sqlite3_column_name(st, c));
        }
        put(&b, "\n", 1);
    }
    char num[40];
    while (sqlite3_step(st) == SQLITE_ROW) {
        if (jsonl) put(&b, "{", 1);
        for (int c = 0; c < cols; ++c) {
            int t = sqlite3_column_type(st, c);
            if (jsonl) {
                json_t *k = json_string(sqlite3_column_name(st, c));
                char *ks = json_dumps(k, JSON_ENCODE_ANY);
                if (c) put(&b, ",", 1);
                puts_(&b, ks);
                put(&b, ":", 1);
                free(ks);
                json_decref(k);
            } else if (c) put(&b, ",", 1);
            if (t == SQLITE_NULL) {
                if (jsonl) puts_(&b, "null");
            } else if (t == SQLITE_INTEGER) {
                snprintf(num, sizeof num, "%lld", (long long)sqlite3_column_int64(st, c));
                puts_(&b, num);
            } else if (t == SQLITE_FLOAT) {
                double x = sqlite3_column_double(st, c);
                ori_format_real(x, num, sizeof num);
                puts_(&b, num);
            } else {
                const char *s = (const char *)sqlite3_column_text(st, c);
                if (jsonl) {
                    json_t *v = json_string(s ? s : "");
                    char *vs = json_dumps(v, JSON_ENCODE_ANY);
                    puts_(&b, vs ? vs : "\"\"");
                    free(vs);
                    json_decref(v);
                } else csv_text(&b, s ? s : "");
            }
        }
        puts_(&b, jsonl ? "}\n" : "\n");
    }
    sqlite3_finalize(st);
    sqlite3_close(db);
    int rc = 0;
    if (strcmp(out, "-") == 0) {
        if (fwrite(b.s, 1, b.len, stdout) != b.len) rc = sweep_fail(err, n, "stdout: cannot write");
    } else {
        ori_error e;
        if (ori_file_write_atomic(out, b.s, b.len, &e) != ORI_OK) rc = sweep_fail(err, n, "%s: %s", out, e.message);
    }
    free(b.s);
    return rc;
}
