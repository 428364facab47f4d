// The studio's server (orikin view): the API handler called directly (status codes, bodies equal
// to the CLI's --json field for field, the document unchanged by every failed request, undo,
// save-back), and the HTTP front over loopback (Host check, token, traversal, body limits, a
// bounded load test with its figures printed).
#define _GNU_SOURCE
#include <arpa/inet.h>
#include <jansson.h>
#include <math.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <glob.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "studio_internal.h"
#include "support.h"

TestSuite(server, .init = test_leak_setup, .fini = test_leak_check);

#define OPEN_CORNER "examples/patterns/open-corner.fold"
#define OPEN_CORNER_SEQ "examples/open-corner.seq.json"
#define WATERBOMB_BASE "tests/data/waterbomb-base.fold"

// --- helpers -------------------------------------------------------------------------------

// A studio on a file (relative to the repository root, as the CLI is run) or a blank sheet.
static studio *open_studio_def(const char *path, size_t cache_bytes)
{
    cr_assert_eq(chdir(ORI_SOURCE_DIR), 0);
    studio_def d = studio_default_def();
    d.path = path;
    d.cache_bytes = cache_bytes;
    d.autosave = strncmp(path ? path : "", "/tmp/", 5) == 0; // never a journal beside the repository's files
    studio *s = NULL;
    char err[1024] = "";
    cr_assert_eq(studio_create(&d, &s, err, sizeof err), 0, "%s", err);
    return s;
}

static studio *open_studio(const char *path) { return open_studio_def(path, STUDIO_CACHE_BYTES); }

// Call the handler; query is "k=v&k=v" (no escapes in the tests).
static studio_response call(studio *s, const char *method, const char *path, const char *query, const char *body)
{
    studio_arg args[16];
    char q[768];
    int n = 0;
    if (query) {
        snprintf(q, sizeof q, "%s", query);
        for (char *tok = strtok(q, "&"); tok && n < 16; tok = strtok(NULL, "&")) {
            char *eq = strchr(tok, '=');
            if (eq) *eq = '\0';
            args[n].key = tok;
            args[n].value = eq ? eq + 1 : "";
            n++;
        }
    }
    studio_request req = {method, path, args, n, body, body ? strlen(body) : 0};
    studio_response r;
    studio_handle(s, &req, &r);
    return r;
}

static json_t *parse(const char *text, size_t size)
{
    json_error_t je;
    json_t *j = json_loadb(text, size, 0, &je);
    cr_assert_not_null(j, "not JSON (%s): %.300s", je.text, text);
    return j;
}

// Call and parse a JSON answer with the expected status.
static json_t *call_json(studio *s, const char *method, const char *path, const char *query, const char *body, int status)
{
    studio_response r = call(s, method, path, query, body);
    cr_assert_eq(r.status, status, "%s %s: status %d, expected %d: %.400s", method, path, r.status, status, r.body);
    cr_assert_str_eq(r.content_type, "application/json");
    json_t *j = parse(r.body, r.size);
    studio_response_free(&r);
    return j;
}

static char *document(studio *s)
{
    studio_response r = call(s, "GET", "/api/document", NULL, NULL);
    cr_assert_eq(r.status, 200);
    return r.body;
}

// The CLI's JSON output (run from the repository root).
static json_t *cli_json(const char *args, int want_rc)
{
    char *out = NULL;
    int rc = test_run_cli(args, &out);
    cr_assert_eq(rc, want_rc, "orikin %s: exit %d, expected %d: %.300s", args, rc, want_rc, out);
    json_t *j = parse(out, strlen(out));
    free(out);
    return j;
}

// A request the server refuses with 400 and an error body containing text.
static void expect_refused(studio *s, const char *method, const char *path, const char *body, const char *text)
{
    studio_response r = call(s, method, path, NULL, body);
    cr_assert_eq(r.status, 400, "%s %s", path, body);
    cr_assert(strstr(r.body, text), "%s %s: %s", path, body, r.body);
    studio_response_free(&r);
}

// Equal JSON (numbers exactly), naming the first field that differs.
static void assert_same(json_t *a, json_t *b, const char *where)
{
    if (json_equal(a, b)) return;
    if (json_is_object(a) && json_is_object(b)) {
        const char *key;
        json_t *v;
        json_object_foreach(a, key, v) {
            cr_assert_not_null(json_object_get(b, key), "%s: field %s missing", where, key);
            char sub[256];
            snprintf(sub, sizeof sub, "%s.%s", where, key);
            assert_same(v, json_object_get(b, key), sub);
        }
        cr_assert_eq(json_object_size(a), json_object_size(b), "%s: %zu fields vs %zu", where, json_object_size(a),
                     json_object_size(b));
    }
    if (json_is_array(a) && json_is_array(b)) {
        cr_assert_eq(json_array_size(a), json_array_size(b), "%s: %zu entries vs %zu", where, json_array_size(a),
                     json_array_size(b));
        for (size_t i = 0; i < json_array_size(a); ++i) {
            char sub[256];
            snprintf(sub, sizeof sub, "%s[%zu]", where, i);
            assert_same(json_array_get(a, i), json_array_get(b, i), sub);
        }
    }
    char *ta = json_dumps(a, JSON_ENCODE_ANY | JSON_REAL_PRECISION(17)), *tb = json_dumps(b, JSON_ENCODE_ANY | JSON_REAL_PRECISION(17));
    cr_assert_fail("%s: %.200s != %.200s", where, ta, tb);
}

// Same structure, numbers within tol (absolute), everything else equal.
static void assert_close(json_t *a, json_t *b, double tol, const char *where)
{
    if (json_is_number(a) && json_is_number(b)) {
        cr_assert_leq(fabs(json_number_value(a) - json_number_value(b)), tol, "%s: %.17g vs %.17g (tolerance %g)", where,
                      json_number_value(a), json_number_value(b), tol);
        return;
    }
    cr_assert_eq(json_typeof(a), json_typeof(b), "%s: different types", where);
    if (json_is_object(a)) {
        cr_assert_eq(json_object_size(a), json_object_size(b), "%s: field counts differ", where);
        const char *key;
        json_t *v;
        json_object_foreach(a, key, v) {
            char sub[256];
            snprintf(sub, sizeof sub, "%s.%s", where, key);
            cr_assert_not_null(json_object_get(b, key), "%s missing", sub);
            assert_close(v, json_object_get(b, key), tol, sub);
        }
    } else if (json_is_array(a)) {
        cr_assert_eq(json_array_size(a), json_array_size(b), "%s: lengths differ", where);
        for (size_t i = 0; i < json_array_size(a); ++i) {
            char sub[256];
            snprintf(sub, sizeof sub, "%s[%zu]", where, i);
            assert_close(json_array_get(a, i), json_array_get(b, i), tol, sub);
        }
    } else {
        assert_same(a, b, where);
    }
}

static void assert_error_body(const studio_response *r, const char *what)
{
    json_t *j = parse(r->body, r->size);
    json_t *e = json_object_get(j, "error");
    cr_assert(json_is_string(e), "%s: no error field: %.200s", what, r->body);
    cr_assert_gt(strlen(json_string_value(e)), 0);
    cr_assert_null(strchr(json_string_value(e), '\n'), "%s: the error is not one line", what);
    cr_assert_eq(json_object_size(j), 1, "%s: {\"error\"} only", what);
    json_decref(j);
}

// --- answers equal to the CLI's --json --------------------------------------------------------

Test(server, fold_equals_cli_json)
{
    studio *s = open_studio(OPEN_CORNER);
    json_t *api = call_json(s, "POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": 12, \"lock\": [11], \"to\": 90, \"step\": 10}", 200);
    json_t *cli = cli_json("fold " OPEN_CORNER " --fix 4 --drive 12 --lock 11 --to 90 --step 10 --json", 0);
    assert_same(api, cli, "fold");
    // the thesis' values (SPEC): at 90° the constrained angles are 60° and asin(1/√3)
    json_t *last = json_array_get(json_object_get(api, "frames"), 9);
    json_t *ang = json_object_get(last, "fold_angles_deg");
    cr_assert_float_eq(json_number_value(json_array_get(ang, 9)), 60.0, 1e-9);
    cr_assert_float_eq(fabs(json_number_value(json_array_get(ang, 6))), asin(1.0 / sqrt(3.0)) * 180.0 / ORI_PI, 1e-9);
    json_decref(api);
    json_decref(cli);
    // the same fold with the face named and the creases given by a point on them
    api = call_json(s, "POST", "/api/fold", NULL,
                    "{\"fix\": \"Obj1212\", \"drive\": \"@0.5,0.5\", \"lock\": [\"@1,0.5\"], \"to\": 90, \"step\": 10}", 200);
    cli = cli_json("fold " OPEN_CORNER " --fix 4 --drive 12 --lock 11 --to 90 --step 10 --json", 0);
    assert_same(api, cli, "fold by name and point");
    json_decref(api);
    json_decref(cli);
    // a fold from a --from angle, another solver choice
    api = call_json(s, "POST", "/api/fold", NULL,
                    "{\"fix\": 4, \"drive\": 12, \"lock\": [11], \"to\": 150, \"from\": 30, \"step\": 40, \"solver\": \"numeric\"}", 200);
    cli = cli_json("fold " OPEN_CORNER " --fix 4 --drive 12 --lock 11 --to 150 --from 30 --step 40 --solver numeric --json", 0);
    assert_same(api, cli, "fold --from --solver numeric");
    json_decref(api);
    json_decref(cli);
    studio_destroy(s);
}

// A fold from a folded frame of the document (the CLI's --frame): its angles and pose.
Test(server, fold_from_a_frame_equals_cli_json)
{
    char *dir = test_tmpdir();
    char args[1024], path[512];
    snprintf(path, sizeof path, "%s/folded.fold", dir);
    snprintf(args, sizeof args, "fold " OPEN_CORNER " --fix 4 --drive 12 --lock 11 --to 90 --step 30 -o '%s'", path);
    cr_assert_eq(test_run_cli(args, NULL), 0);
    studio *s = open_studio(path);
    json_t *api = call_json(s, "POST", "/api/fold", NULL,
                            "{\"fix\": 3, \"drive\": 11, \"lock\": [12], \"to\": 60, \"step\": 20, \"frame\": 4}", 200);
    snprintf(args, sizeof args, "fold '%s' --fix 3 --drive 11 --lock 12 --to 60 --step 20 --frame 4 --json", path);
    json_t *cli = cli_json(args, 0);
    assert_same(api, cli, "fold from frame 4");
    json_decref(api);
    json_decref(cli);
    json_t *sess = call_json(s, "GET", "/api/session", NULL, NULL, 200);
    cr_assert_eq(json_integer_value(json_object_get(sess, "frames")), 5);
    json_decref(sess);
    studio_destroy(s);
    test_tmpdir_remove(dir);
}

Test(server, invalid_fold_equals_cli_json)
{
    char *dir = test_tmpdir();
    char args[1024], path[512];
    snprintf(path, sizeof path, "%s/wrong.fold", dir);
    snprintf(args, sizeof args, "edit " OPEN_CORNER " --flip @0.5,0.5 -o '%s'", path);
    cr_assert_eq(test_run_cli(args, NULL), 0);
    studio *s = open_studio(path);
    json_t *api = call_json(s, "POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": 12, \"lock\": [11], \"to\": -90, \"step\": 30}", 200);
    snprintf(args, sizeof args, "fold '%s' --fix 4 --drive 12 --lock 11 --to -90 --step 30 --json", path);
    json_t *cli = cli_json(args, 1);
    assert_same(api, cli, "invalid fold");
    cr_assert(json_is_false(json_object_get(api, "valid")));
    cr_assert_str_eq(json_string_value(json_object_get(api, "verdict")), "invalid assignment");
    cr_assert_eq(json_integer_value(json_object_get(json_array_get(json_object_get(api, "offending_edges"), 0), "edge")), 6);
    json_decref(api);
    json_decref(cli);
    studio_destroy(s);
    test_tmpdir_remove(dir);
}

// --- the documentation's examples, through both front ends ---------------------------------

// One example of the docs: "orikin fold FILE OPTIONS" or "orikin sequence FILE …", as tokens.
typedef struct doc_example {
    char where[96];
    char *tok[32];
    int n;
    char text[512];
} doc_example;

// Every "orikin CMD" example of README.md and docs/*.md (in code spans and code lines; docs/cli.md
// is generated) whose FILE is in the repository, CMD one of commands (NULL-terminated).
static int doc_examples(doc_example *ex, int cap, const char *const *commands)
{
    cr_assert_eq(chdir(ORI_SOURCE_DIR), 0);
    glob_t g;
    cr_assert_eq(glob("docs/*.md", 0, NULL, &g), 0);
    int count = 0;
    for (size_t fi = 0; fi <= g.gl_pathc; ++fi) {
        const char *file = fi == g.gl_pathc ? "README.md" : g.gl_pathv[fi];
        if (strcmp(file, "docs/cli.md") == 0) continue;
        char *text = test_read_text(file);
        for (const char *at = text; (at = strstr(at, "orikin ")) != NULL; at += 7) {
            bool wanted = false;
            for (const char *const *c = commands; *c && !wanted; ++c)
                wanted = strncmp(at + 7, *c, strlen(*c)) == 0 && at[7 + strlen(*c)] == ' ';
            if (!wanted) continue;
            size_t len = strcspn(at, "`\n#|&;>");
            if (len >= sizeof ex[0].text || count == cap) continue;
            doc_example *e = &ex[count];
            memcpy(e->text, at, len);
            e->text[len] = '\0';
            while (len > 0 && e->text[len - 1] == ' ') e->text[--len] = '\0';
            snprintf(e->where, sizeof e->where, "%s", file);
            e->n = 0;
            for (char *t = strtok(e->text, " "); t && e->n < 32; t = strtok(NULL, " ")) e->tok[e->n++] = t;
            struct stat st;
            if (e->n < 3 || strchr(e->tok[2], '<') || stat(e->tok[2], &st) != 0 || !S_ISREG(st.st_mode)) continue;
            bool duplicate = false;
            for (int k = 0; k < count && !duplicate; ++k) {
                duplicate = ex[k].n == e->n;
                for (int i = 0; i < e->n && duplicate; ++i) duplicate = strcmp(ex[k].tok[i], e->tok[i]) == 0;
            }
            if (!duplicate) count++;
        }
        free(text);
    }
    globfree(&g);
    return count;
}

// A CLI number list ("3,5" or "90") as JSON: one number, or an array when there are several.
static json_t *single_or_array(json_t *a)
{
    if (json_array_size(a) != 1) return a;
    json_t *one = json_incref(json_array_get(a, 0));
    json_decref(a);
    return one;
}

static json_t *numbers_json(const char *v)
{
    json_t *a = json_array();
    char buf[128];
    snprintf(buf, sizeof buf, "%s", v);
    for (char *t = strtok(buf, ","); t; t = strtok(NULL, ",")) json_array_append_new(a, json_real(strtod(t, NULL)));
    return single_or_array(a);
}

// A CLI face or crease list ("3,5", "Obj12", "11,@1,0.5") as the API takes it: an index as a
// number, a name or a point "@x,y" as a string; one value, or an array when there are several.
static json_t *specs_json(const char *v)
{
    json_t *a = json_array();
    char buf[256], *save = NULL;
    snprintf(buf, sizeof buf, "%s", v);
    for (char *t = strtok_r(buf, ",", &save); t; t = strtok_r(NULL, ",", &save)) {
        char *end;
        long x = strtol(t, &end, 10);
        if (t[0] == '@') {
            const char *y = strtok_r(NULL, ",", &save);
            char point[128];
            snprintf(point, sizeof point, "%s,%s", t, y ? y : "");
            json_array_append_new(a, json_string(point));
        } else if (end != t && *end == '\0') {
            json_array_append_new(a, json_integer(x));
        } else {
            json_array_append_new(a, json_string(t));
        }
    }
    return single_or_array(a);
}

// A fold option of the CLI (t, with the next token v) into the body of POST /api/fold, whose
// fields are named like the options: the tokens it takes (1: a flag, 2: with its value), 0 when t
// is not a fold option.
static int fold_option_json(json_t *body, const char *t, const char *v)
{
    if (strcmp(t, "--symmetric") == 0 || strcmp(t, "--no-collisions") == 0) {
        json_object_set_new(body, t[2] == 's' ? "symmetric" : "no_collisions", json_true());
        return 1;
    }
    static const char *const keys[] = {"fix", "drive", "lock", "to", "from", "step", "percent", "solver", "frame"};
    if (strncmp(t, "--", 2) != 0 || !v || !*v) return 0;
    const char *key = t + 2;
    int k = 0;
    while (k < 9 && strcmp(keys[k], key) != 0) k++;
    if (k == 9) return 0;
    json_t *val;
    if (k == 0 || k == 1) val = specs_json(v);
    else if (k == 2 && strcmp(v, "auto") == 0) val = json_string("auto");
    else if (k == 2) {
        val = specs_json(v);
        if (!json_is_array(val)) {
            json_t *one = json_array();
            json_array_append_new(one, val);
            val = one;
        }
    } else if (k == 7) val = json_string(v);
    else if (k == 8) val = json_integer(strtol(v, NULL, 10));
    else val = numbers_json(v);
    json_object_set_new(body, key, val);
    return 2;
}

// A compliant fold's option (orikin fold --compliant …) into the body of POST /api/compliant:
// the tokens it takes, 0 when t is not one.
static int compliant_option_json(json_t *body, const char *t, const char *v)
{
    if (strcmp(t, "--dynamic") == 0) {
        json_object_set_new(body, "dynamic", json_true());
        return 1;
    }
    static const char *const numbers[] = {"percent", "axial", "facet", "crease", "damping", "gravity"};
    if (strncmp(t, "--", 2) != 0 || !v || !*v) return 0;
    const char *key = t + 2;
    for (int k = 0; k < 6; ++k)
        if (strcmp(key, numbers[k]) == 0) {
            json_object_set_new(body, key, json_real(strtod(v, NULL)));
            return 2;
        }
    if (strcmp(key, "steps") == 0 || strcmp(key, "threads") == 0) json_object_set_new(body, key, json_integer(strtol(v, NULL, 10)));
    else if (strcmp(key, "preset") == 0) json_object_set_new(body, key, json_string(v));
    else if (strcmp(key, "fix") == 0) json_object_set_new(body, key, specs_json(v));
    else return 0;
    return 2;
}

// Every fold and sequence example of the documentation answers the same through the studio's API
// as through the CLI's --json: the same verdict, stop and angles (numbers exactly), field for
// field (issue 22). A fold's options become the API's fields (a compliant fold's those of POST
// /api/compliant); -o is the CLI's only (the API answers in JSON).
Test(server, the_docs_fold_and_sequence_examples_answer_the_same_in_the_studio)
{
    static doc_example ex[64];
    static const char *const commands[] = {"fold", "sequence", NULL};
    int n = doc_examples(ex, 64, commands), folds = 0, sequences = 0, compliant = 0;
    for (int i = 0; i < n; ++i) {
        doc_example *e = &ex[i];
        char args[1024] = "";
        size_t w = 0;
        bool seq = strcmp(e->tok[1], "sequence") == 0, is_compliant = false;
        json_t *body = json_object();
        for (int k = 1; k < e->n; ++k) {
            const char *t = e->tok[k], *v = k + 1 < e->n ? e->tok[k + 1] : "";
            if (strcmp(t, "-o") == 0 || strcmp(t, "--output") == 0) {
                k++;
                continue;
            }
            if (strcmp(t, "--json") == 0) continue;
            w += (size_t)snprintf(args + w, sizeof args - w, "%s ", t);
            if (k < 3 || seq) continue;
            if (strcmp(t, "--compliant") == 0) {
                is_compliant = true;
                continue;
            }
            if (strcmp(t, "--all-frames") == 0) continue; // what -o writes, not the answer
            int used = is_compliant ? compliant_option_json(body, t, v) : fold_option_json(body, t, v);
            if (used == 0 && t[0] == '-') cr_assert_fail("%s: %s: option %s has no API field in this test", e->where, e->text, t);
            if (used == 2) {
                w += (size_t)snprintf(args + w, sizeof args - w, "%s ", v);
                k++;
            }
        }
        snprintf(args + w, sizeof args - w, "--json");
        char *out = NULL;
        int rc = test_run_cli(args, &out);
        cr_assert(rc == 0 || rc == 1 || (is_compliant && rc == 5), "orikin %s (%s): exit %d: %.300s", args, e->where, rc, out);
        json_t *cli = parse(out, strlen(out));
        free(out);
        studio *s = open_studio(e->tok[2]);
        json_t *api;
        if (seq) {
            api = call_json(s, "GET", "/api/sequence", NULL, NULL, 200);
            sequences++;
        } else {
            char *b = json_dumps(body, JSON_COMPACT);
            api = call_json(s, "POST", is_compliant ? "/api/compliant" : "/api/fold", NULL, b, 200);
            free(b);
            if (is_compliant) { // (what the page draws, beside the CLI's answer)
                cr_assert(json_is_array(json_object_get(api, "positions")), "%s: the bent sheet's vertices", e->text);
                json_object_del(api, "positions");
                json_object_del(api, "strain_colors");
                json_object_del(api, "version");
                compliant++;
            } else {
                folds++;
            }
        }
        char what[1200];
        snprintf(what, sizeof what, "%.90s: orikin %.1000s", e->where, args);
        assert_same(api, cli, what);
        cr_log_info("same answer: %s", what);
        json_decref(api);
        json_decref(cli);
        json_decref(body);
        studio_destroy(s);
    }
    // (the docs hold at least these: the open corner's folds, the issue-14 vertex, two sequences)
    cr_assert_geq(folds, 3, "%d fold examples found", folds);
    cr_assert_geq(sequences, 2, "%d sequence examples found", sequences);
    cr_assert_geq(compliant, 1, "%d compliant fold examples found", compliant);
    cr_log_info("%d folds, %d compliant folds and %d sequences the same", folds, compliant, sequences);
}

Test(server, sequence_equals_cli_json)
{
    studio *s = open_studio(OPEN_CORNER_SEQ);
    json_t *api = call_json(s, "GET", "/api/sequence", NULL, NULL, 200);
    json_t *cli = cli_json("sequence " OPEN_CORNER_SEQ " --json", 0);
    assert_same(api, cli, "sequence");
    json_decref(api);
    json_decref(cli);
    // POSTing the same sequence gives the same record (named "studio": it came from the page)
    char *text = test_read_text(OPEN_CORNER_SEQ);
    api = call_json(s, "POST", "/api/sequence", NULL, text, 200);
    free(text);
    cli = cli_json("sequence " OPEN_CORNER_SEQ " --json", 0);
    json_object_set_new(cli, "sequence", json_string("studio"));
    assert_same(api, cli, "posted sequence");
    json_decref(api);
    json_decref(cli);
    studio_destroy(s);
}

// A sequence naming its faces (Obj1212, "@x,y") and creases ("@x,y"): the studio resolves them
// as orikin sequence does, on the command line and POSTed, and the record equals the CLI's.
Test(server, sequence_with_names_equals_cli_json)
{
    const char *named = "tests/data/open-corner-named.seq.json";
    studio *s = open_studio(named);
    json_t *api = call_json(s, "GET", "/api/sequence", NULL, NULL, 200);
    char args[256];
    snprintf(args, sizeof args, "sequence %s --json", named);
    json_t *cli = cli_json(args, 0);
    assert_same(api, cli, "named sequence");
    json_t *f0 = json_array_get(json_object_get(api, "folds"), 0);
    cr_assert_eq(json_integer_value(json_object_get(f0, "fix")), 4); // Obj1212 is face 4
    cr_assert_eq(json_integer_value(json_object_get(f0, "drive")), 12); // @0.5,0.5 is crease 12
    json_decref(api);
    char *text = test_read_text(named);
    api = call_json(s, "POST", "/api/sequence", NULL, text, 200);
    free(text);
    json_object_set_new(cli, "sequence", json_string("studio"));
    assert_same(api, cli, "posted named sequence");
    json_decref(api);
    json_decref(cli);
    json_decref(call_json(s, "POST", "/api/sequence", NULL,
                          "{\"pattern\": \"p.fold\", \"folds\": [{\"fix\": \"Obj9\", \"drive\": 12, \"to\": 90}]}", 400));
    studio_destroy(s);
}

// Any instant of the sequence: without the scrubbing cache the answer is the CLI's, exactly;
// with it (the states of a fine grid, each solved exactly) it agrees to 1e-9.
Test(server, sequence_at_equals_cli_json)
{
    static const char *const times[] = {"0", "0.37", "1", "1.5", "1.25", "2"};
    studio *exact = open_studio_def(OPEN_CORNER_SEQ, 0);
    studio *cached = open_studio(OPEN_CORNER_SEQ);
    json_t *session = call_json(cached, "GET", "/api/session", NULL, NULL, 200);
    cr_assert_eq(json_integer_value(json_object_get(json_object_get(session, "sequence"), "grid")), STUDIO_GRID_MAX);
    json_decref(session);
    for (size_t i = 0; i < sizeof times / sizeof times[0]; ++i) {
        char q[64], args[256];
        snprintf(q, sizeof q, "t=%s", times[i]);
        snprintf(args, sizeof args, "sequence " OPEN_CORNER_SEQ " --at %s --json", times[i]);
        json_t *cli = cli_json(args, 0);
        json_t *a = call_json(exact, "GET", "/api/sequence/at", q, NULL, 200);
        assert_same(a, cli, q);
        json_t *b = call_json(cached, "GET", "/api/sequence/at", q, NULL, 200);
        json_object_del(b, "residual");
        json_object_del(cli, "residual");
        assert_close(b, cli, 1e-9, q);
        json_decref(a);
        json_decref(b);
        json_decref(cli);
    }
    studio_destroy(exact);
    studio_destroy(cached);
}

// The binary form of a state holds the same numbers as the JSON form.
Test(server, sequence_at_binary_equals_json)
{
    studio *s = open_studio(OPEN_CORNER_SEQ);
    json_t *j = call_json(s, "GET", "/api/sequence/at", "t=1.5", NULL, 200);
    studio_response r = call(s, "GET", "/api/sequence/at", "t=1.5&binary=1", NULL);
    cr_assert_eq(r.status, 200);
    cr_assert_str_eq(r.content_type, "application/octet-stream");
    json_t *coords = json_object_get(j, "vertices_coords"), *ang = json_object_get(j, "fold_angles_deg");
    int V = (int)json_array_size(coords), E = (int)json_array_size(ang);
    cr_assert_eq(r.size, 8 * (size_t)(8 + 3 * V + E));
    double *d = malloc(r.size);
    for (size_t k = 0; k < r.size / 8; ++k) {
        uint64_t u = 0;
        for (int b = 0; b < 8; ++b) u |= (uint64_t)(unsigned char)r.body[8 * k + (size_t)b] << (8 * b);
        memcpy(&d[k], &u, 8);
    }
    cr_assert_eq(d[0], 1.5);
    cr_assert_eq(d[1], 2.0); // fold 2
    cr_assert_eq(d[2], json_number_value(json_object_get(j, "drive_deg")));
    cr_assert_eq(d[4], (double)V);
    cr_assert_eq(d[5], (double)E);
    for (int v = 0; v < V; ++v)
        for (int c = 0; c < 3; ++c) cr_assert_eq(d[8 + 3 * v + c], json_number_value(json_array_get(json_array_get(coords, (size_t)v), (size_t)c)));
    for (int e = 0; e < E; ++e) cr_assert_eq(d[8 + 3 * V + e], json_number_value(json_array_get(ang, (size_t)e)));
    free(d);
    studio_response_free(&r);
    json_decref(j);
    studio_destroy(s);
}

Test(server, check_dof_tree_info_axiom_equal_cli_json)
{
    studio *s = open_studio(OPEN_CORNER);
    struct {
        const char *method, *path, *body, *cli;
        int rc;
    } cases[] = {
        {"GET", "/api/check", NULL, "check " OPEN_CORNER " --json", 1},
        {"POST", "/api/dof", "{}", "dof " OPEN_CORNER " --json", 0},
        {"POST", "/api/dof", "{\"lock\": [11]}", "dof " OPEN_CORNER " --lock 11 --json", 0},
        {"GET", "/api/tree", NULL, "tree " OPEN_CORNER " --json", 0},
        {"GET", "/api/info", NULL, "info " OPEN_CORNER " --json", 0},
        {"POST", "/api/axiom", "{\"axiom\": 6, \"p1\": [0, -1], \"l1\": [0, 1, 1, 0], \"p2\": [2, 0], \"l2\": [-2, 0, 0, 1]}",
         "axiom 6 --p1 0,-1 --l1 0,1,1,0 --p2 2,0 --l2 -2,0,0,1 --json", 0},
        {"POST", "/api/axiom", "{\"axiom\": 3, \"l1\": [0, 0, 1, 0], \"l2\": [0, 0, 0, 1]}", "axiom 3 --l1 0,0,1,0 --l2 0,0,0,1 --json", 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        json_t *api = call_json(s, cases[i].method, cases[i].path, NULL, cases[i].body, 200);
        json_t *cli = cli_json(cases[i].cli, cases[i].rc);
        json_object_del(api, "segments"); // the axiom's solutions clipped for drawing: the API's addition
        assert_same(api, cli, cases[i].cli);
        json_decref(api);
        json_decref(cli);
    }
    studio_destroy(s);
}

// info, tree, dof and regularize on a second example pattern (a degree-4 vertex): the CLI's
// --json and the studio's API answer with the same object (both built by cli/report/).
Test(server, info_tree_dof_regularize_equal_cli_json_on_degree4)
{
    const char *file = "examples/patterns/degree4-vertex.fold";
    studio *s = open_studio(file);
    struct {
        const char *method, *path, *body, *cli;
        int rc;
    } cases[] = {
        {"GET", "/api/info", NULL, "info examples/patterns/degree4-vertex.fold --json", 0},
        {"GET", "/api/tree", NULL, "tree examples/patterns/degree4-vertex.fold --json", 0},
        {"POST", "/api/dof", "{}", "dof examples/patterns/degree4-vertex.fold --json", 0},
        {"POST", "/api/regularize", "{}", "regularize examples/patterns/degree4-vertex.fold --json", 0},
        {"POST", "/api/regularize", "{\"rigid\": true, \"max_move\": 0.01}",
         "regularize examples/patterns/degree4-vertex.fold --rigid --max-move 0.01 --json", 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        json_t *api = call_json(s, cases[i].method, cases[i].path, NULL, cases[i].body, 200);
        json_t *cli = cli_json(cases[i].cli, cases[i].rc);
        if (strcmp(cases[i].path, "/api/regularize") == 0) {
            // the document's bookkeeping after a replace: the API's additions
            for (const char *const *k = (const char *const[]){"replaced", "version", "undo", "redo", NULL}; *k; ++k)
                json_object_del(api, *k);
        }
        cr_assert_geq(json_object_size(cli), 3, "%s: a real answer", cases[i].cli);
        assert_same(api, cli, cases[i].cli);
        json_decref(api);
        json_decref(cli);
    }
    // the values themselves: one interior vertex of degree 4, four faces; flat, the vertex is
    // singular (rank 2 of 3 equations: 2 DOF), one degree of freedom generically
    json_t *info = cli_json("info examples/patterns/degree4-vertex.fold --json", 0);
    cr_assert_eq(json_integer_value(json_object_get(info, "interior_vertices")), 1);
    cr_assert_eq(json_integer_value(json_object_get(info, "faces")), 4);
    json_decref(info);
    json_t *dof = cli_json("dof examples/patterns/degree4-vertex.fold --json", 0);
    cr_assert_eq(json_integer_value(json_object_get(dof, "dof")), 2);
    cr_assert_eq(json_integer_value(json_object_get(dof, "generic_dof")), 1);
    cr_assert(json_is_true(json_object_get(dof, "singular")));
    json_decref(dof);
    // the same mistake, the same text (each front end names the option as it spells it)
    studio_response r = call(s, "POST", "/api/regularize", NULL, "{\"max_move\": 2}");
    cr_assert_eq(r.status, 400);
    assert_error_body(&r, "max_move 2");
    cr_assert(strstr(r.body, "max_move needs a fraction of the sheet size in (0, 1], got 2"), "%s", r.body);
    studio_response_free(&r);
    char *cli_out = NULL;
    cr_assert_eq(test_run_cli("regularize examples/patterns/degree4-vertex.fold --max-move 2", &cli_out), 2);
    cr_assert(strstr(cli_out, "--max-move needs a fraction of the sheet size in (0, 1], got 2"), "%s", cli_out);
    free(cli_out);
    studio_destroy(s);
}

// The compliant fold (issue 23, the studio half): POST /api/compliant answers what `fold
// --compliant --json` prints, field by field (one request, solve and JSON: cli/report), plus the
// positions the studio draws; a bad value is refused with the CLI's words.
Test(server, compliant_fold_equals_cli_json)
{
    const char *file = "examples/patterns/open-corner.fold";
    studio *s = open_studio(file);
    struct {
        const char *body, *cli;
        int rc;
    } cases[] = {
        {"{\"percent\": 40}", "fold examples/patterns/open-corner.fold --compliant --percent 40 --json", 0},
        {"{\"percent\": 25, \"fix\": 2, \"crease\": 1.5}",
         "fold examples/patterns/open-corner.fold --compliant --percent 25 --fix 2 --crease 1.5 --json", 0},
        {"{\"percent\": 30, \"dynamic\": true, \"steps\": 500}",
         "fold examples/patterns/open-corner.fold --compliant --percent 30 --dynamic --steps 500 --json", 5},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        json_t *api = call_json(s, "POST", "/api/compliant", NULL, cases[i].body, 200);
        json_t *cli = cli_json(cases[i].cli, cases[i].rc);
        json_t *pos = json_object_get(api, "positions");
        cr_assert_eq(json_array_size(pos), (size_t)json_integer_value(json_object_get(cli, "vertices")), "%s", cases[i].cli);
        double zmax = 0.0;
        for (size_t v = 0; v < json_array_size(pos); ++v)
            zmax = fmax(zmax, fabs(json_real_value(json_array_get(json_array_get(pos, v), 2))));
        cr_assert_gt(zmax, 1e-3, "%s: the sheet is folded", cases[i].cli);
        // the strain colours: render --color strain's map over the CLI's face strains (JSON numbers:
        // a whole number reads as an integer)
        json_t *sc = json_object_get(api, "strain_colors"), *fs = json_object_get(cli, "face_strains");
        ori_value_map map = {NULL, NULL, INFINITY, -INFINITY};
        for (size_t f = 0; f < json_array_size(fs); ++f) {
            map.min = fmin(map.min, json_number_value(json_array_get(fs, f)));
            map.max = fmax(map.max, json_number_value(json_array_get(fs, f)));
        }
        cr_assert_float_eq(json_number_value(json_object_get(sc, "max")), map.max, 1e-15 * (1.0 + map.max));
        cr_assert_eq(json_array_size(json_object_get(sc, "faces")), json_array_size(fs));
        for (size_t f = 0; f < json_array_size(fs); ++f) {
            ori_rgb k = ori_colormap(ori_value_map_position(&map, json_number_value(json_array_get(fs, f))));
            json_t *got = json_array_get(json_object_get(sc, "faces"), f);
            cr_assert_float_eq(json_number_value(json_array_get(got, 0)), k.r, 1e-12, "face %zu", f);
            cr_assert_float_eq(json_number_value(json_array_get(got, 1)), k.g, 1e-12, "face %zu", f);
            cr_assert_float_eq(json_number_value(json_array_get(got, 2)), k.b, 1e-12, "face %zu", f);
        }
        json_object_del(api, "strain_colors");
        json_object_del(api, "positions");
        json_object_del(api, "version");
        cr_assert_geq(json_object_size(cli), 10, "%s: a real answer", cases[i].cli);
        assert_same(api, cli, cases[i].cli);
        json_decref(api);
        json_decref(cli);
    }
    // the last compliant fold is a state and a motion of the export until the document changes
    studio_response shot = call(s, "GET", "/api/export", "format=png&compliant=1&size=64x48", NULL);
    cr_assert_eq(shot.status, 200, "%.300s", shot.body);
    studio_response_free(&shot);
    studio_response anim = call(s, "GET", "/api/export", "format=gif&of=compliant&fps=2&duration=1&size=64x48", NULL);
    cr_assert_eq(anim.status, 200, "%.300s", anim.body);
    cr_assert_str_eq(anim.filename, "open-corner-compliant.gif");
    studio_response_free(&anim);
    json_decref(call_json(s, "POST", "/api/new", NULL, "{\"square\": 1}", 200));
    studio_response gone = call(s, "GET", "/api/export", "format=png&compliant=1", NULL);
    cr_assert_eq(gone.status, 409, "a new document has no compliant fold: %d", gone.status);
    studio_response_free(&gone);
    json_decref(call_json(s, "POST", "/api/undo", NULL, NULL, 200));
    expect_refused(s, "POST", "/api/compliant", "{\"percent\": 120}", "--percent needs a number from 0 to 100, got '120'");
    expect_refused(s, "POST", "/api/compliant", "{\"fix\": 99}", "fix: a face index");
    expect_refused(s, "POST", "/api/compliant", "{\"percent\": 10, \"stiff\": 1}", "stiff");
    char *cli_out = NULL;
    cr_assert_eq(test_run_cli("fold examples/patterns/open-corner.fold --compliant --percent 120", &cli_out), 2);
    cr_assert(strstr(cli_out, "--percent needs a number from 0 to 100, got '120'"), "%s", cli_out);
    free(cli_out);
    studio_destroy(s);
}

// --- robustness: failed requests change nothing -------------------------------------------------

Test(server, bad_requests_leave_the_document_unchanged)
{
    studio *s = open_studio(OPEN_CORNER_SEQ);
    static const struct {
        const char *method, *path, *query, *body;
        int status;
    } bad[] = {
        {"POST", "/api/fold", NULL, NULL, 400},
        {"POST", "/api/fold", NULL, "{", 400},
        {"POST", "/api/fold", NULL, "[1, 2]", 400},
        {"POST", "/api/fold", NULL, "{\"fix\": \"4\", \"drive\": 12, \"to\": 90}", 400},
        {"POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": 12, \"to\": 90, \"fix\": 3}", 400},
        {"POST", "/api/fold", NULL, "{\"fix\": 99, \"drive\": 12, \"to\": 90}", 400},
        {"POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": -1, \"to\": 90}", 400},
        {"POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": 12, \"to\": 900}", 400},
        {"POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": 12, \"to\": 90, \"step\": 0}", 400},
        {"POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": 12, \"to\": 90, \"step\": 1e-6}", 400},
        {"POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": 12, \"to\": 90, \"lock\": [99]}", 400},
        {"POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": 12, \"to\": 90, \"lock\": 11}", 400},
        {"POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": 12, \"to\": 90, \"frame\": 7}", 400},
        {"POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": 12, \"to\": 90, \"bogus\": 1}", 400},
        {"POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": 12, \"to\": 90, \"fix2\": 99999999999999999999}", 400},
        {"POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": 12, \"to\": 90, \"solver\": \"magic\"}", 400},
        {"POST", "/api/fold", NULL, "{\"fix\": \"Obj9\", \"drive\": 12, \"to\": 90}", 400},
        {"POST", "/api/fold", NULL, "{\"fix\": 4.5, \"drive\": 12, \"to\": 90}", 400},
        {"POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": \"@9,9\", \"to\": 90}", 400},
        {"POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": \"12\", \"to\": 90}", 400},
        {"POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": 12, \"lock\": [\"@0.5\"], \"to\": 90}", 400},
        {"POST", "/api/fold", NULL, "{\"drive\": 12, \"to\": 90}", 400},
        {"POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"flip\", \"edge\": 99}]}", 400},
        {"POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"flip\", \"edge\": 0}]}", 400},
        {"POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"flip\", \"edge\": 12}, {\"op\": \"flip\", \"edge\": 99}]}", 400},
        {"POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"remove\", \"edge\": 12}, {\"op\": \"flip\", \"edge\": 12}]}", 400},
        {"POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"assign\", \"edge\": 12, \"to\": \"X\"}]}", 400},
        {"POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"move\", \"edge\": 12, \"segment\": [0, 0, 1]}]}", 400},
        {"POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"move\", \"edge\": 12, \"segment\": [5, 5, 6, 6]}]}", 400},
        {"POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"remove\", \"edge\": \"@9,9\"}]}", 400},
        {"POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"remove\", \"edge\": \"@x\"}]}", 400},
        {"POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"twist\", \"edge\": 12}]}", 400},
        {"POST", "/api/edit", NULL, "{\"ops\": []}", 400},
        {"POST", "/api/edit", NULL, "{\"ops\": [7]}", 400},
        {"POST", "/api/apply", NULL, "{\"pattern\": \"nope\", \"face\": 0}", 400},
        {"POST", "/api/apply", NULL, "{\"pattern\": \"middle-h\", \"face\": \"Obj1\"}", 400},
        {"POST", "/api/apply", NULL, "{\"pattern\": \"middle-h\", \"face\": 42}", 400},
        {"POST", "/api/apply", NULL, "{\"pattern\": \"middle-h\", \"face\": \"Obj9\"}", 400},
        {"POST", "/api/apply", NULL, "{\"pattern\": {\"creases\": \"x\"}, \"face\": 0}", 400},
        {"POST", "/api/apply", NULL, "{\"pattern\": 5, \"face\": 0}", 400},
        {"POST", "/api/apply", NULL, "{\"pattern\": \"middle-h\", \"face\": 0, \"assign\": \"B\"}", 400},
        {"POST", "/api/crease", NULL, "{\"axiom\": 2, \"p1\": [0, 0], \"p2\": [0, 0], \"face\": 0}", 400},
        {"POST", "/api/crease", NULL, "{\"axiom\": 8, \"p1\": [0, 0], \"p2\": [1, 0], \"face\": 0}", 400},
        {"POST", "/api/crease", NULL, "{\"line\": [0, 0, 1, 1]}", 400},
        {"POST", "/api/crease", NULL, "{\"line\": [0, 0, 1, 1], \"all\": true, \"face\": 0}", 400},
        {"POST", "/api/crease", NULL, "{\"line\": [5, 5, 6, 5], \"all\": true}", 400},
        {"POST", "/api/crease", NULL, "{\"axiom\": 5, \"p1\": [0, 0], \"p2\": [1, 1], \"l1\": [0, 2, 1, 0], \"all\": true}", 400},
        {"POST", "/api/crease", NULL, "{\"axiom\": 5, \"p1\": [0, 0], \"p2\": [1, 1], \"l1\": [0, 2, 1, 0], \"all\": true, \"solution\": 3}", 400},
        {"POST", "/api/axiom", NULL, "{\"axiom\": 5, \"p1\": [0, 0]}", 400},
        {"POST", "/api/axiom", NULL, "{\"axiom\": 4, \"p1\": [0, 0], \"l1\": [0, 0, 0, 0]}", 400},
        {"POST", "/api/axiom", NULL, "{\"axiom\": 1, \"p1\": [0, 1e300], \"p2\": [1, 0]}", 400},
        {"POST", "/api/new", NULL, "{\"square\": -1}", 400},
        {"POST", "/api/new", NULL, "{\"square\": 1, \"rect\": [1, 2]}", 400},
        {"POST", "/api/new", NULL, "{\"polygon\": [[0, 0], [1, 1], [2, 2]]}", 400},
        {"POST", "/api/new", NULL, "{\"polygon\": [[0, 0], [1, 1], \"x\"]}", 400},
        {"POST", "/api/open", "name=x.fold", "{bad", 400},
        {"POST", "/api/open", "name=x.fold", "{\"vertices_coords\": [[0, 0]], \"edges_vertices\": [[0, 7]]}", 400},
        {"POST", "/api/open", "name=x.svg", "<svg", 400},
        {"POST", "/api/open", "name=x.cp", "2 0 0 1\n", 400},
        {"POST", "/api/open", "name=x.exe", "MZ", 400},
        {"POST", "/api/open", NULL, "{}", 400},
        {"POST", "/api/sequence", NULL, "{", 400},
        {"POST", "/api/sequence", NULL, "{\"pattern\": \"p.fold\", \"folds\": [{\"fix\": 99, \"drive\": 12, \"to\": 90}]}", 400},
        {"POST", "/api/sequence", NULL, "{\"pattern\": \"p.fold\", \"folds\": [{\"fix\": 4, \"drive\": 12, \"to\": 90, \"step\": 0.001}]}", 400},
        {"POST", "/api/sequence", NULL, "{\"pattern\": \"p.fold\", \"frame\": 3, \"folds\": [{\"fix\": 4, \"drive\": 12, \"to\": 90}]}", 400},
        {"GET", "/api/sequence/at", NULL, NULL, 400},
        {"GET", "/api/sequence/at", "t=abc", NULL, 400},
        {"GET", "/api/sequence/at", "t=5", NULL, 400},
        {"GET", "/api/sequence/at", "t=-1", NULL, 400},
        {"GET", "/api/sequence/at", "t=nan", NULL, 400},
        {"GET", "/api/sequence/at", "t=inf", NULL, 400},
        {"GET", "/api/fold/frame", "k=0", NULL, 409},
        {"GET", "/api/check", "frame=3", NULL, 400},
        {"GET", "/api/check", "frame=-1", NULL, 400},
        {"POST", "/api/dof", NULL, "{\"lock\": [99]}", 400},
        {"POST", "/api/dof", NULL, "{\"t\": 9}", 400},
        {"GET", "/api/mechanism", "fix=99", NULL, 400},
        {"GET", "/api/mechanism", "fix=0.5", NULL, 400},
        {"GET", "/api/export", "format=gif", NULL, 400},
        {"GET", "/api/export", "format=png&of=sequence", NULL, 400},
        {"GET", "/api/export", "format=png&size=0x10", NULL, 400},
        {"GET", "/api/export", "format=png&size=5000x5000", NULL, 400},
        {"GET", "/api/export", "format=png&t=1&frame=0", NULL, 400},
        {"GET", "/api/export", "format=png&view=cp&t=1", NULL, 400},
        {"GET", "/api/export", "format=png&view=3d&labels=1", NULL, 400},
        {"GET", "/api/export", "format=png&eye=0,0,1", NULL, 400},
        {"GET", "/api/export", "format=png&eye=0,0,1&up=0,0,2", NULL, 400},
        {"GET", "/api/export", "format=png&front=nocolour", NULL, 400},
        {"GET", "/api/export", "format=png&grid=maybe", NULL, 400},
        {"GET", "/api/export", "format=png&t=9", NULL, 400},
        {"GET", "/api/export", "format=png&k=0", NULL, 409},
        {"GET", "/api/export", "format=obj&thickness=-1", NULL, 400},
        {"GET", "/api/export", "format=obj&of=elsewhere", NULL, 400},
        {"GET", "/api/export", "format=glb&of=fold", NULL, 409},
        {"GET", "/api/export", "format=glb&of=sequence&thickness=1", NULL, 400},
        {"GET", "/api/export", "format=gif&of=sequence&fps=100", NULL, 400},
        {"GET", "/api/export", "format=gif&of=sequence&duration=0", NULL, 400},
        {"GET", "/api/export", "format=gif&of=sequence&view=cp", NULL, 400},
        {"GET", "/api/export", "format=png&compliant=1", NULL, 409},
        {"GET", "/api/export", "format=png&compliant=2", NULL, 400},
        {"GET", "/api/export", "format=png&compliant=1&t=1", NULL, 400},
        {"GET", "/api/export", "format=png&color=strain", NULL, 400},
        {"GET", "/api/export", "format=glb&of=compliant", NULL, 409},
        {"GET", "/api/export", "format=gif&of=compliant", NULL, 409},
        {"POST", "/api/collide", NULL, "{\"compliant\": 1}", 400},
        {"GET", "/api/export", "format=gif&of=sequence&t=1", NULL, 400},
        {"GET", "/api/check", "tolerance_deg=2", NULL, 400},
        {"GET", "/api/check", "tolerance_deg=x", NULL, 400},
        {"POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": 12, \"to\": 90, \"clearance\": -1}", 400},
        {"POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": 12, \"to\": 90, \"no_collisions\": 1}", 400},
        {"POST", "/api/sequence", "clearance=-1", "{\"pattern\": \"p.fold\", \"folds\": [{\"fix\": 4, \"drive\": 12, \"to\": 90}]}", 400},
        {"POST", "/api/sequence", "no_collisions=yes", "{\"pattern\": \"p.fold\", \"folds\": [{\"fix\": 4, \"drive\": 12, \"to\": 90}]}", 400},
        {"GET", "/api/contact", NULL, NULL, 400},
        {"GET", "/api/contact", "of=fold", NULL, 409},
        {"GET", "/api/contact", "of=sequence", NULL, 409},
        {"POST", "/api/collide", NULL, "{\"frame\": 7}", 400},
        {"POST", "/api/collide", NULL, "{\"t\": 9}", 400},
        {"POST", "/api/collide", NULL, "{\"k\": 0}", 409},
        {"POST", "/api/collide", NULL, "{\"contact\": \"fold\"}", 409},
        {"POST", "/api/collide", NULL, "{\"contact\": \"both\"}", 400},
        {"POST", "/api/collide", NULL, "{\"frame\": 0, \"t\": 1}", 400},
        {"POST", "/api/collide", NULL, "{\"clearance\": -1}", 400},
        {"POST", "/api/collide", NULL, "{\"cloud\": 0}", 400},
        {"POST", "/api/collide", NULL, "{\"witness\": true}", 400},
        {"POST", "/api/regularize", NULL, "{\"max_move\": 0}", 400},
        {"POST", "/api/regularize", NULL, "{\"rigid\": 1}", 400},
        {"POST", "/api/regularize", NULL, "{\"frame\": 1}", 400},
        {"GET", "/api/export", NULL, NULL, 400},
        {"POST", "/api/save", NULL, "{\"what\": \"x\"}", 400},
        {"POST", "/api/undo", NULL, NULL, 409},
        {"POST", "/api/redo", NULL, NULL, 409},
        {"GET", "/api/nope", NULL, NULL, 404},
        {"GET", "/api/../index.html", NULL, NULL, 404},
        {"DELETE", "/api/fold", NULL, NULL, 405},
        {"POST", "/api/session", NULL, NULL, 405},
        {"POST", "/api/actuate", NULL, "{}", 501},
    };
    char *before = document(s);
    long version = studio_version(s);
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        studio_response r = call(s, bad[i].method, bad[i].path, bad[i].query, bad[i].body);
        cr_assert_eq(r.status, bad[i].status, "%s %s %s: status %d, expected %d: %.300s", bad[i].method, bad[i].path,
                     bad[i].body ? bad[i].body : "", r.status, bad[i].status, r.body);
        assert_error_body(&r, bad[i].path);
        studio_response_free(&r);
        char *after = document(s);
        cr_assert_str_eq(after, before, "%s %s %s changed the document", bad[i].method, bad[i].path, bad[i].body);
        free(after);
        cr_assert_eq(studio_version(s), version);
    }
    // a body over the limit never reaches a handler
    size_t big = STUDIO_MAX_BODY_BYTES + 1;
    char *huge = malloc(big + 1);
    memset(huge, ' ', big);
    huge[big] = '\0';
    studio_response r = call(s, "POST", "/api/fold", NULL, huge);
    cr_assert_eq(r.status, 413);
    studio_response_free(&r);
    free(huge);
    // and the sequence that ran at start is still there
    json_t *seq = call_json(s, "GET", "/api/sequence", NULL, NULL, 200);
    cr_assert(json_is_true(json_object_get(seq, "valid")));
    json_decref(seq);
    free(before);
    studio_destroy(s);
}

// A long computation holds the job slot: another one is refused (409), progress reports it.
Test(server, one_long_computation_at_a_time)
{
    studio *s = open_studio(OPEN_CORNER);
    studio_response r;
    memset(&r, 0, sizeof r);
    cr_assert(studio_job_begin(s, "test job", &r));
    studio_response b = call(s, "POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": 12, \"lock\": [11], \"to\": 90}");
    cr_assert_eq(b.status, 409);
    cr_assert_not_null(strstr(b.body, "test job"));
    studio_response_free(&b);
    json_t *p = call_json(s, "GET", "/api/progress", NULL, NULL, 200);
    cr_assert(json_is_true(json_object_get(p, "busy")));
    cr_assert_str_eq(json_string_value(json_object_get(p, "job")), "test job");
    cr_assert_geq(json_number_value(json_object_get(p, "elapsed_s")), 0.0);
    json_decref(p);
    studio_job_end(s);
    p = call_json(s, "GET", "/api/progress", NULL, NULL, 200);
    cr_assert(json_is_false(json_object_get(p, "busy")));
    json_decref(p);
    studio_destroy(s);
}

// --- authoring ----------------------------------------------------------------------------------

static json_t *load_fold_json(const char *path)
{
    char *text = test_read_text(path);
    cr_assert_not_null(text, "%s", path);
    json_t *j = parse(text, strlen(text));
    free(text);
    return j;
}

// --- replaying a multi-frame document (GET /api/frames) ----------------------------------------

#define REPLAY_FLAP "tests/data/replay-flap-3.fold"

static double le_f64(const char *p)
{
    uint64_t u = 0;
    for (int b = 0; b < 8; ++b) u |= (uint64_t)(unsigned char)p[b] << (8 * b);
    double x;
    memcpy(&x, &u, 8);
    return x;
}

// orikin simulate -o wrote a crease pattern and three states with frame_time (seconds): the
// replay is those three states, their times and coordinates the file's (1e-12), in JSON and in
// the binary form the page reads.
Test(server, frames_replay_a_simulation_output)
{
    cr_assert_eq(chdir(ORI_SOURCE_DIR), 0);
    json_t *file = load_fold_json(REPLAY_FLAP);
    json_t *ff = json_object_get(file, "file_frames");
    cr_assert_eq(json_array_size(ff), 3);
    studio *s = open_studio(REPLAY_FLAP);
    json_t *j = call_json(s, "GET", "/api/frames", NULL, NULL, 200);
    cr_assert_str_eq(json_string_value(json_object_get(j, "unit")), "s");
    cr_assert_eq(json_integer_value(json_object_get(j, "first_frame")), 1);
    json_t *times = json_object_get(j, "times"), *coords = json_object_get(j, "vertices_coords");
    cr_assert_eq(json_array_size(times), 3);
    cr_assert_eq(json_array_size(coords), 3);
    int V = (int)json_integer_value(json_object_get(j, "vertex_count"));
    cr_assert_eq(V, (int)json_array_size(json_object_get(file, "vertices_coords")));
    studio_response r = call(s, "GET", "/api/frames", "binary=1", NULL);
    cr_assert_eq(r.status, 200);
    cr_assert_str_eq(r.content_type, "application/octet-stream");
    cr_assert_eq(r.size, 8 * (size_t)(8 + 3 + 3 * 3 * V));
    cr_assert_eq(le_f64(r.body), 3.0);
    cr_assert_eq(le_f64(r.body + 8), (double)V);
    cr_assert_eq(le_f64(r.body + 16), 1.0); // seconds
    for (size_t i = 0; i < 3; ++i) {
        json_t *fr = json_array_get(ff, i);
        double want_t = json_number_value(json_object_get(fr, "frame_time"));
        cr_assert(fabs(json_number_value(json_array_get(times, i)) - want_t) <= 1e-12);
        cr_assert(fabs(le_f64(r.body + 8 * (8 + i)) - want_t) <= 1e-12);
        json_t *vc = json_object_get(fr, "vertices_coords");
        cr_assert_eq((int)json_array_size(vc), V);
        for (int v = 0; v < V; ++v)
            for (int c = 0; c < 3; ++c) {
                json_t *p = json_array_get(json_array_get(vc, (size_t)v), (size_t)c);
                double want = p ? json_number_value(p) : 0.0; // a 2D coordinate has z = 0
                double got = json_number_value(json_array_get(json_array_get(json_array_get(coords, i), (size_t)v), (size_t)c));
                cr_assert(fabs(got - want) <= 1e-12, "frame %zu vertex %d: %.17g, file %.17g", i + 1, v, got, want);
                double bin = le_f64(r.body + 8 * (8 + 3 + (i * (size_t)V + (size_t)v) * 3 + (size_t)c));
                cr_assert(fabs(bin - want) <= 1e-12);
            }
    }
    cr_assert_eq(json_number_value(json_array_get(times, 2)), 0.006);
    studio_response_free(&r);
    json_decref(j);
    studio_destroy(s);
    json_decref(file);
}

// Frames without frame_time are one unit apart; orikin sequence's frames are timed by orikin:time
// (folds); a document of one state is that state alone.
Test(server, frames_without_times_and_a_single_state)
{
    cr_assert_eq(chdir(ORI_SOURCE_DIR), 0);
    json_t *file = load_fold_json(REPLAY_FLAP);
    json_t *ff = json_object_get(file, "file_frames");
    for (size_t i = 0; i < json_array_size(ff); ++i) json_object_del(json_array_get(ff, i), "frame_time");
    char *dir = test_tmpdir();
    char path[512];
    snprintf(path, sizeof path, "%s/untimed.fold", dir);
    cr_assert_eq(json_dump_file(file, path, JSON_REAL_PRECISION(17)), 0);
    studio *s = open_studio(path);
    json_t *j = call_json(s, "GET", "/api/frames", NULL, NULL, 200);
    cr_assert_str_eq(json_string_value(json_object_get(j, "unit")), "frame");
    for (size_t i = 0; i < 3; ++i) cr_assert_eq(json_number_value(json_array_get(json_object_get(j, "times"), i)), (double)i);
    json_decref(j);
    studio_destroy(s);
    // orikin sequence -o: its frames' orikin:time (sequence time, folds)
    char args[700], *cli_out = NULL;
    snprintf(path, sizeof path, "%s/seq.fold", dir);
    snprintf(args, sizeof args, "sequence %s -o %s", OPEN_CORNER_SEQ, path);
    cr_assert_eq(test_run_cli(args, &cli_out), 0, "%s", cli_out);
    free(cli_out);
    json_t *seq = load_fold_json(path);
    json_t *sf = json_object_get(seq, "file_frames");
    s = open_studio(path);
    j = call_json(s, "GET", "/api/frames", NULL, NULL, 200);
    cr_assert_str_eq(json_string_value(json_object_get(j, "unit")), "fold");
    cr_assert_eq(json_integer_value(json_object_get(j, "first_frame")), 1);
    json_t *st = json_object_get(j, "times");
    cr_assert_eq(json_array_size(st), json_array_size(sf));
    for (size_t i = 0; i < json_array_size(sf); ++i)
        cr_assert_eq(json_number_value(json_array_get(st, i)), json_number_value(json_object_get(json_array_get(sf, i), "orikin:time")));
    cr_assert_eq(json_number_value(json_array_get(st, json_array_size(st) - 1)), 2.0);
    json_decref(j);
    json_decref(seq);
    studio_destroy(s);
    test_tmpdir_remove(dir);
    json_decref(file);
    s = open_studio(OPEN_CORNER);
    j = call_json(s, "GET", "/api/frames", NULL, NULL, 200);
    cr_assert_eq(json_array_size(json_object_get(j, "times")), 1);
    cr_assert_str_eq(json_string_value(json_object_get(j, "unit")), "frame");
    json_decref(j);
    studio_destroy(s);
}

// The open corner built as examples/open-corner.sh builds it, through the API.
Test(server, builds_the_open_corner)
{
    studio *s = open_studio(NULL);
    json_t *j = call_json(s, "POST", "/api/new", NULL, "{\"square\": 2}", 200);
    json_decref(j);
    static const char *const steps[] = {
        "{\"pattern\": \"middle-h\", \"face\": \"Obj1\", \"assign\": \"V\"}",
        "{\"pattern\": \"middle-v\", \"face\": \"Obj11\", \"assign\": \"V\"}",
        "{\"pattern\": \"middle-v\", \"face\": \"Obj12\", \"assign\": \"V\"}",
        "{\"pattern\": \"diagonal-left\", \"face\": \"Obj121\", \"assign\": \"V\"}",
    };
    for (size_t i = 0; i < 4; ++i) json_decref(call_json(s, "POST", "/api/apply", NULL, steps[i], 200));
    j = call_json(s, "POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"assign\", \"edge\": \"@0.5,1\", \"to\": \"M\"}]}", 200);
    cr_assert_str_eq(json_string_value(json_array_get(json_object_get(j, "log"), 0)), "edge 6 (@0.5,1): V -> M");
    json_decref(j);
    studio_response r = call(s, "GET", "/api/export", "format=fold", NULL);
    cr_assert_eq(r.status, 200);
    cr_assert_str_eq(r.filename, "sheet.fold");
    json_t *built = parse(r.body, r.size), *ref = load_fold_json(OPEN_CORNER);
    static const char *const fields[] = {"vertices_coords", "edges_vertices", "edges_assignment", "faces_vertices",
                                         "orikin:faces_name", "orikin:face_tree"};
    for (size_t i = 0; i < sizeof fields / sizeof fields[0]; ++i)
        assert_same(json_object_get(built, fields[i]), json_object_get(ref, fields[i]), fields[i]);
    json_decref(built);
    json_decref(ref);
    studio_response_free(&r);
    studio_destroy(s);
}

Test(server, undo_and_redo_restore_exactly)
{
    studio *s = open_studio(OPEN_CORNER);
    char *d0 = document(s);
    json_decref(call_json(s, "POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"flip\", \"edge\": 12}]}", 200));
    char *d1 = document(s);
    cr_assert_str_neq(d0, d1);
    json_decref(call_json(s, "POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"remove\", \"edge\": 11}]}", 200));
    char *d2 = document(s);
    json_decref(call_json(s, "POST", "/api/open", "name=sheet.cp", "1 0 0 1 0\n1 1 0 1 1\n1 1 1 0 1\n1 0 1 0 0\n2 0 0 1 1\n", 200));
    json_t *info = call_json(s, "GET", "/api/info", NULL, NULL, 200);
    cr_assert_eq(json_integer_value(json_object_get(info, "edges")), 5);
    cr_assert_str_eq(json_string_value(json_object_get(info, "file")), "sheet.cp");
    json_decref(info);
    char *expect[] = {d2, d1, d0};
    for (int i = 0; i < 3; ++i) {
        json_decref(call_json(s, "POST", "/api/undo", NULL, NULL, 200));
        char *d = document(s);
        cr_assert_str_eq(d, expect[i], "undo %d", i + 1);
        free(d);
    }
    json_t *sess = call_json(s, "GET", "/api/session", NULL, NULL, 200);
    cr_assert_str_eq(json_string_value(json_object_get(sess, "file")), OPEN_CORNER);
    cr_assert_eq(json_integer_value(json_object_get(sess, "redo")), 3);
    json_decref(sess);
    json_decref(call_json(s, "POST", "/api/redo", NULL, NULL, 200));
    char *d = document(s);
    cr_assert_str_eq(d, d1);
    free(d);
    // a new edit clears what could be redone
    json_decref(call_json(s, "POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"assign\", \"edge\": 8, \"to\": \"U\"}]}", 200));
    studio_response r = call(s, "POST", "/api/redo", NULL, NULL);
    cr_assert_eq(r.status, 409);
    studio_response_free(&r);
    free(d0);
    free(d1);
    free(d2);
    studio_destroy(s);
}

Test(server, edits_follow_the_cli)
{
    char *dir = test_tmpdir();
    char args[1024], path[512];
    snprintf(path, sizeof path, "%s/edited.fold", dir);
    snprintf(args, sizeof args, "edit " OPEN_CORNER " --flip 12 --remove 11 --move 9 1,1,1.5,2 --assign @1.5,1=U -o '%s'", path);
    cr_assert_eq(test_run_cli(args, NULL), 0);
    studio *s = open_studio(OPEN_CORNER);
    json_t *j = call_json(s, "POST", "/api/edit", NULL,
                          "{\"ops\": [{\"op\": \"flip\", \"edge\": 12}, {\"op\": \"remove\", \"edge\": 11},"
                          " {\"op\": \"move\", \"edge\": 9, \"segment\": [1, 1, 1.5, 2]},"
                          " {\"op\": \"assign\", \"edge\": \"@1.5,1\", \"to\": \"U\"}]}", 200);
    cr_assert_eq(json_array_size(json_object_get(j, "log")), 4);
    json_decref(j);
    char *mine = document(s);
    json_t *a = parse(mine, strlen(mine)), *b = load_fold_json(path);
    assert_same(a, b, "edited document");
    json_decref(a);
    json_decref(b);
    free(mine);
    studio_destroy(s);
    test_tmpdir_remove(dir);
}

Test(server, crease_by_axiom_equals_cli)
{
    char *dir = test_tmpdir();
    char args[1024], path[512];
    snprintf(path, sizeof path, "%s/creased.fold", dir);
    snprintf(args, sizeof args, "crease " OPEN_CORNER " --axiom 2 --p1 2,2 --p2 1,2 --face Obj112 --assign M -o '%s'", path);
    cr_assert_eq(test_run_cli(args, NULL), 0);
    studio *s = open_studio(OPEN_CORNER);
    json_t *j = call_json(s, "POST", "/api/crease", NULL,
                          "{\"axiom\": 2, \"p1\": [2, 2], \"p2\": [1, 2], \"face\": \"Obj112\", \"assign\": \"M\"}", 200);
    cr_assert_str_eq(json_string_value(json_object_get(j, "applied_to")), "Obj112");
    cr_assert_eq(json_array_size(json_object_get(j, "new_faces")), 2);
    json_decref(j);
    char *mine = document(s);
    json_t *a = parse(mine, strlen(mine)), *b = load_fold_json(path);
    assert_same(a, b, "creased document");
    json_decref(a);
    json_decref(b);
    free(mine);
    // the axiom's solutions clipped to a face for drawing: axiom 2 on Obj111 is its diagonal
    j = call_json(s, "POST", "/api/axiom", NULL, "{\"axiom\": 2, \"p1\": [0, 2], \"p2\": [1, 1], \"face\": \"Obj111\"}", 200);
    json_t *seg = json_array_get(json_array_get(json_object_get(j, "segments"), 0), 0);
    double x0 = json_number_value(json_array_get(seg, 0)), y0 = json_number_value(json_array_get(seg, 1));
    double x1 = json_number_value(json_array_get(seg, 2)), y1 = json_number_value(json_array_get(seg, 3));
    cr_assert_float_eq(fmin(x0, x1), 0.0, 1e-12);
    cr_assert_float_eq(fmax(x0, x1), 1.0, 1e-12);
    cr_assert_float_eq(fabs(y1 - y0), 1.0, 1e-12);
    json_decref(j);
    studio_destroy(s);
    test_tmpdir_remove(dir);
}

Test(server, opens_and_exports_every_format)
{
    studio *s = open_studio(OPEN_CORNER);
    static const char *const fmts[] = {"svg", "cp", "opx"};
    for (int i = 0; i < 3; ++i) {
        char q[64], name[64];
        snprintf(q, sizeof q, "format=%s", fmts[i]);
        studio_response r = call(s, "GET", "/api/export", q, NULL);
        cr_assert_eq(r.status, 200);
        snprintf(name, sizeof name, "open-corner.%s", fmts[i]);
        cr_assert_str_eq(r.filename, name);
        // what was written opens again as the same crease pattern (counts and assignments)
        char oq[96];
        snprintf(oq, sizeof oq, "name=again.%s", fmts[i]);
        json_decref(call_json(s, "POST", "/api/open", oq, r.body, 200));
        json_t *info = call_json(s, "GET", "/api/info", NULL, NULL, 200);
        cr_assert_eq(json_integer_value(json_object_get(info, "faces")), 5, "%s", fmts[i]);
        cr_assert_eq(json_integer_value(json_object_get(json_object_get(info, "edges_by_assignment"), "M")), 1);
        cr_assert_eq(json_integer_value(json_object_get(json_object_get(info, "edges_by_assignment"), "V")), 4);
        json_decref(info);
        json_decref(call_json(s, "POST", "/api/undo", NULL, NULL, 200));
        studio_response_free(&r);
    }
    // the SVG is what the library writes
    ori_pattern *p = test_load_pattern(OPEN_CORNER, 0);
    char *svg = ori_svg_write(p, NULL);
    studio_response r = call(s, "GET", "/api/export", "format=svg", NULL);
    cr_assert_str_eq(r.body, svg);
    cr_assert_str_eq(r.content_type, "image/svg+xml");
    studio_response_free(&r);
    ori_buffer_free(svg);
    ori_pattern_destroy(p);
    studio_destroy(s);
}

Test(server, saves_back_only_to_the_command_line_file)
{
    char *dir = test_tmpdir();
    char path[512], args[1024];
    snprintf(path, sizeof path, "%s/corner.fold", dir);
    snprintf(args, sizeof args, "cp '" ORI_SOURCE_DIR "/" OPEN_CORNER "' '%s'", path);
    cr_assert_eq(system(args), 0);
    studio *s = open_studio(path);
    json_decref(call_json(s, "POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"flip\", \"edge\": 12}]}", 200));
    char *on_disk = test_read_text(path), *orig = test_read_text(OPEN_CORNER);
    cr_assert_str_eq(on_disk, orig, "nothing is written before Save");
    free(on_disk);
    json_t *j = call_json(s, "POST", "/api/save", NULL, "{}", 200);
    cr_assert_str_eq(json_string_value(json_object_get(j, "saved")), path);
    json_decref(j);
    char *doc = document(s);
    on_disk = test_read_text(path);
    cr_assert_str_eq(on_disk, doc);
    free(on_disk);
    free(doc);
    // a document opened through the page is never written over the command-line file
    json_decref(call_json(s, "POST", "/api/new", NULL, "{\"square\": 1}", 200));
    studio_response r = call(s, "POST", "/api/save", NULL, "{}");
    cr_assert_eq(r.status, 409);
    studio_response_free(&r);
    r = call(s, "POST", "/api/save", NULL, "{\"what\": \"sequence\"}");
    cr_assert_eq(r.status, 409);
    studio_response_free(&r);
    free(orig);
    studio_destroy(s);
    test_tmpdir_remove(dir);
}

Test(server, saves_the_sequence_back)
{
    char *dir = test_tmpdir();
    char args[1024], seq[512];
    snprintf(args, sizeof args, "mkdir -p '%s/patterns' && cp '" ORI_SOURCE_DIR "/" OPEN_CORNER "' '%s/patterns/' && cp '"
             ORI_SOURCE_DIR "/" OPEN_CORNER_SEQ "' '%s/'", dir, dir, dir);
    cr_assert_eq(system(args), 0);
    snprintf(seq, sizeof seq, "%s/open-corner.seq.json", dir);
    studio *s = open_studio(seq);
    // one fold only, posted by the page; saved with the file's own pattern reference
    json_decref(call_json(s, "POST", "/api/sequence", NULL,
                          "{\"pattern\": \"whatever.fold\", \"folds\": [{\"fix\": 4, \"lock\": [11], \"drive\": 12, \"to\": 120, \"step\": 20}]}", 200));
    json_decref(call_json(s, "POST", "/api/save", NULL, "{\"what\": \"sequence\"}", 200));
    json_t *saved = load_fold_json(seq);
    cr_assert_str_eq(json_string_value(json_object_get(saved, "pattern")), "patterns/open-corner.fold");
    cr_assert_eq(json_array_size(json_object_get(saved, "folds")), 1);
    cr_assert_float_eq(json_number_value(json_object_get(json_array_get(json_object_get(saved, "folds"), 0), "to")), 120.0, 0);
    json_decref(saved);
    snprintf(args, sizeof args, "sequence '%s' --json", seq);
    json_t *cli = cli_json(args, 0);
    cr_assert_eq(json_integer_value(json_object_get(cli, "duration")), 1);
    json_decref(cli);
    studio_destroy(s);
    test_tmpdir_remove(dir);
}

// --- folding manager ----------------------------------------------------------------------------

// Each output state of a fold: the fixed face stays flat where it was and every face is rigid.
Test(server, fold_frames_are_rigid_states)
{
    studio *s = open_studio(OPEN_CORNER);
    json_decref(call_json(s, "POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": 12, \"lock\": [11], \"to\": 180, \"step\": 30}", 200));
    ori_pattern *p = test_load_pattern(OPEN_CORNER, 0);
    for (int k = 0; k <= 6; ++k) {
        char q[32];
        snprintf(q, sizeof q, "k=%d", k);
        json_t *j = call_json(s, "GET", "/api/fold/frame", q, NULL, 200);
        cr_assert_eq(json_integer_value(json_object_get(j, "frame")), k);
        cr_assert_float_eq(json_number_value(json_object_get(j, "drive_deg")), 30.0 * k, 1e-9);
        json_t *c = json_object_get(j, "vertices_coords");
        for (int f = 0; f < ori_pattern_face_count(p); ++f) {
            int vs[8];
            int n = ori_pattern_face_vertices(p, f, vs, 8);
            for (int a = 0; a < n; ++a)
                for (int b = a + 1; b < n; ++b) {
                    ori_v3 pa = ori_pattern_vertex(p, vs[a]), pb = ori_pattern_vertex(p, vs[b]);
                    double d0 = ori_v3_norm(ori_v3_sub(pa, pb)), d1 = 0;
                    for (int x = 0; x < 3; ++x) {
                        double u = json_number_value(json_array_get(json_array_get(c, (size_t)vs[a]), (size_t)x)) -
                                   json_number_value(json_array_get(json_array_get(c, (size_t)vs[b]), (size_t)x));
                        d1 += u * u;
                    }
                    cr_assert_float_eq(sqrt(d1), d0, 1e-12, "frame %d face %d", k, f);
                }
        }
        json_decref(j);
    }
    // the fixed face (4: vertices 0, 8, 6) has not moved
    json_t *j = call_json(s, "GET", "/api/fold/frame", "k=6", NULL, 200);
    json_t *c = json_object_get(j, "vertices_coords");
    int fixed[3] = {0, 8, 6};
    for (int i = 0; i < 3; ++i) {
        ori_v3 p0 = ori_pattern_vertex(p, fixed[i]);
        cr_assert_float_eq(json_number_value(json_array_get(json_array_get(c, (size_t)fixed[i]), 0)), p0.x, 1e-12);
        cr_assert_float_eq(json_number_value(json_array_get(json_array_get(c, (size_t)fixed[i]), 1)), p0.y, 1e-12);
        cr_assert_float_eq(json_number_value(json_array_get(json_array_get(c, (size_t)fixed[i]), 2)), 0.0, 1e-12);
    }
    json_decref(j);
    studio_response r = call(s, "GET", "/api/fold/frame", "k=7", NULL);
    cr_assert_eq(r.status, 400);
    studio_response_free(&r);
    ori_pattern_destroy(p);
    studio_destroy(s);
}

// "Add a fold from the current state": a fold after the sequence's end continues from its
// geometry, as the same fold appended to the sequence does.
Test(server, fold_after_the_sequence_continues_it)
{
    studio *s = open_studio(OPEN_CORNER);
    json_decref(call_json(s, "POST", "/api/sequence", NULL,
                          "{\"pattern\": \"x\", \"folds\": [{\"fix\": 4, \"lock\": [11], \"drive\": 12, \"to\": 180, \"step\": 30}]}", 200));
    json_t *f = call_json(s, "POST", "/api/fold", NULL,
                          "{\"fix\": 4, \"lock\": [12], \"drive\": 11, \"to\": 90, \"step\": 30, \"after_sequence\": true}", 200);
    cr_assert(json_is_true(json_object_get(f, "valid")), "%s", json_string_value(json_object_get(f, "reason")));
    json_t *g = call_json(s, "GET", "/api/fold/frame", "k=3", NULL, 200);
    json_decref(call_json(s, "POST", "/api/sequence", NULL,
                          "{\"pattern\": \"x\", \"folds\": [{\"fix\": 4, \"lock\": [11], \"drive\": 12, \"to\": 180, \"step\": 30},"
                          " {\"fix\": 4, \"lock\": [12], \"drive\": 11, \"to\": 90, \"step\": 30}]}", 200));
    json_t *h = call_json(s, "GET", "/api/sequence/at", "t=2", NULL, 200);
    assert_close(json_object_get(g, "vertices_coords"), json_object_get(h, "vertices_coords"), 1e-9, "end of fold 2");
    assert_close(json_object_get(g, "fold_angles_deg"), json_object_get(h, "fold_angles_deg"), 1e-9, "angles");
    json_decref(f);
    json_decref(g);
    json_decref(h);
    // the sequence survives a fold; an edit drops it (its indices belong to the old pattern)
    json_decref(call_json(s, "POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"assign\", \"edge\": 8, \"to\": \"U\"}]}", 200));
    studio_response r = call(s, "GET", "/api/sequence", NULL, NULL);
    cr_assert_eq(r.status, 409);
    studio_response_free(&r);
    studio_destroy(s);
}

Test(server, mechanism_bones_and_spanning_tree)
{
    studio *s = open_studio(OPEN_CORNER);
    json_t *j = call_json(s, "GET", "/api/mechanism", "fix=4", NULL, 200);
    cr_assert_eq(json_integer_value(json_object_get(j, "faces")), 5);
    cr_assert_eq(json_integer_value(json_object_get(j, "grubler")), -1);
    cr_assert_eq(json_array_size(json_object_get(j, "joints")), 5);
    cr_assert_eq(json_array_size(json_object_get(j, "bones")), 10); // two per crease
    json_t *loops = json_object_get(j, "loops");
    cr_assert_eq(json_array_size(loops), 1);
    cr_assert_eq(json_integer_value(json_object_get(json_array_get(loops, 0), "vertex")), 6);
    json_t *tree = json_object_get(j, "spanning_tree");
    cr_assert_eq(json_integer_value(json_object_get(tree, "root")), 4);
    cr_assert_eq(json_integer_value(json_array_get(json_object_get(tree, "parent_face"), 4)), -1);
    json_decref(j);
    studio_destroy(s);
}

Test(server, blank_sheet_and_a_drawing_given_on_the_command_line)
{
    studio *s = open_studio(NULL);
    json_t *info = call_json(s, "GET", "/api/info", NULL, NULL, 200);
    cr_assert_eq(json_integer_value(json_object_get(info, "faces")), 1);
    cr_assert_eq(json_integer_value(json_object_get(info, "vertices")), 4);
    json_decref(info);
    json_t *sess = call_json(s, "GET", "/api/session", NULL, NULL, 200);
    cr_assert(json_is_null(json_object_get(sess, "save_path")));
    json_decref(sess);
    studio_destroy(s);
    // an unreadable file, and a broken one, fail with one line naming the file
    cr_assert_eq(chdir(ORI_SOURCE_DIR), 0);
    studio_def d = studio_default_def();
    char err[1024];
    d.path = "no/such/file.fold";
    cr_assert_eq(studio_create(&d, &s, err, sizeof err), 3);
    cr_assert_not_null(strstr(err, "no/such/file.fold"));
    cr_assert_null(strchr(err, '\n'));
    d.path = "README.md";
    cr_assert_eq(studio_create(&d, &s, err, sizeof err), 3);
}

// --- collisions, tolerance, regularize, pictures and meshes ------------------------------------

#define TWO_FLAPS "examples/patterns/two-flaps.fold"
#define TWO_FLAPS_SEQ "examples/two-flaps.seq.json"
#define ROUNDED_MIURA "tests/data/rounded-miura.fold"

// A fold that collides: the verdict, the located contact and the motion cut at the last clean
// step are what orikin fold --json prints; the contact state is where the faces meet.
Test(server, fold_collision_equals_cli_json)
{
    studio *s = open_studio(TWO_FLAPS);
    json_t *api = call_json(s, "POST", "/api/fold", NULL,
                            "{\"frame\": 1, \"fix\": 1, \"drive\": 8, \"lock\": [7], \"to\": 180}", 200);
    json_t *cli = cli_json("fold " TWO_FLAPS " --frame 1 --fix 1 --drive 8 --lock 7 --to 180 --json", 1);
    assert_same(api, cli, "colliding fold");
    cr_assert_str_eq(json_string_value(json_object_get(api, "verdict")), "collision");
    json_t *col = json_object_get(api, "collision");
    int step = (int)json_integer_value(json_object_get(col, "step"));
    // the flaps first touch at cos(rho) = -1/1.5 (examples/two-flaps.seq.json), located to 1e-6 deg
    cr_assert_float_eq(json_number_value(json_object_get(col, "drive_deg")), acos(-1.0 / 1.5) * 180.0 / ORI_PI, 2e-6);
    cr_assert_eq(json_array_size(json_object_get(api, "frames")), (size_t)step, "the motion stops at the last clean step");
    json_decref(cli);
    // the fold's states stop there too
    char q[32];
    snprintf(q, sizeof q, "k=%d", step - 1);
    json_decref(call_json(s, "GET", "/api/fold/frame", q, NULL, 200));
    snprintf(q, sizeof q, "k=%d", step);
    studio_response r = call(s, "GET", "/api/fold/frame", q, NULL);
    cr_assert_eq(r.status, 400);
    studio_response_free(&r);
    json_t *sess = call_json(s, "GET", "/api/session", NULL, NULL, 200);
    cr_assert_eq(json_integer_value(json_object_get(sess, "fold_frames")), step);
    cr_assert(json_is_true(json_object_get(json_object_get(sess, "features"), "collisions")));
    json_decref(sess);
    // the state at the first contact: at the located drive, and its faces collide there
    json_t *c = call_json(s, "GET", "/api/contact", "of=fold", NULL, 200);
    assert_same(json_object_get(c, "collision"), col, "contact.collision");
    cr_assert_eq(json_number_value(json_object_get(c, "drive_deg")), json_number_value(json_object_get(col, "drive_deg")));
    cr_assert_float_eq(json_number_value(json_array_get(json_object_get(c, "fold_angles_deg"), 8)),
                       json_number_value(json_object_get(col, "drive_deg")), 1e-9);
    json_decref(c);
    json_t *k = call_json(s, "POST", "/api/collide", NULL, "{\"contact\": \"fold\"}", 200);
    cr_assert(json_is_true(json_object_get(k, "collides")), "the contact state collides");
    assert_same(json_array_get(json_object_get(k, "pairs"), 0), json_object_get(col, "faces"), "colliding pair");
    cr_assert_str_eq(json_string_value(json_object_get(k, "state")), "first contact of the fold");
    json_decref(k);
    // and the last clean state does not
    snprintf(q, sizeof q, "{\"k\": %d}", step - 1);
    k = call_json(s, "POST", "/api/collide", NULL, q, 200);
    cr_assert(json_is_false(json_object_get(k, "collides")));
    json_decref(k);
    json_decref(api);
    // no_collisions and clearance as --no-collisions and --clearance
    api = call_json(s, "POST", "/api/fold", NULL,
                    "{\"frame\": 1, \"fix\": 1, \"drive\": 8, \"lock\": [7], \"to\": 180, \"no_collisions\": true}", 200);
    cli = cli_json("fold " TWO_FLAPS " --frame 1 --fix 1 --drive 8 --lock 7 --to 180 --no-collisions --json", 0);
    assert_same(api, cli, "fold --no-collisions");
    cr_assert(json_is_null(json_object_get(api, "collision")));
    json_decref(api);
    json_decref(cli);
    r = call(s, "GET", "/api/contact", "of=fold", NULL);
    cr_assert_eq(r.status, 409, "an unchecked fold has no contact");
    studio_response_free(&r);
    api = call_json(s, "POST", "/api/fold", NULL,
                    "{\"frame\": 1, \"fix\": 1, \"drive\": 8, \"lock\": [7], \"to\": 120, \"step\": 20, \"clearance\": 0.5}", 200);
    cli = cli_json("fold " TWO_FLAPS " --frame 1 --fix 1 --drive 8 --lock 7 --to 120 --step 20 --clearance 0.5 --json", 1);
    assert_same(api, cli, "fold --clearance 0.5");
    cr_assert_str_eq(json_string_value(json_object_get(api, "verdict")), "collision");
    json_decref(api);
    json_decref(cli);
    studio_destroy(s);
}

// A sequence that collides: the record, every clean instant, and the refusal after the contact
// are what orikin sequence prints.
Test(server, sequence_collision_equals_cli_json)
{
    studio *exact = open_studio_def(TWO_FLAPS_SEQ, 0);
    json_t *api = call_json(exact, "GET", "/api/sequence", NULL, NULL, 200);
    json_t *cli = cli_json("sequence " TWO_FLAPS_SEQ " --json", 1);
    assert_same(api, cli, "colliding sequence");
    cr_assert_str_eq(json_string_value(json_object_get(api, "verdict")), "collision");
    json_t *col = json_object_get(api, "collision");
    cr_assert_eq(json_integer_value(json_object_get(col, "fold")), 2);
    json_t *sess = call_json(exact, "GET", "/api/session", NULL, NULL, 200);
    double tc = json_number_value(json_object_get(json_object_get(sess, "sequence"), "collision_t"));
    json_decref(sess);
    cr_assert(tc > 1.7 && tc < 1.75, "contact at t = %g", tc);
    json_t *a = call_json(exact, "GET", "/api/sequence/at", "t=1.5", NULL, 200);
    json_t *b = cli_json("sequence " TWO_FLAPS_SEQ " --at 1.5 --json", 0);
    assert_same(a, b, "t = 1.5");
    json_decref(a);
    json_decref(b);
    char *out = NULL;
    cr_assert_eq(test_run_cli("sequence " TWO_FLAPS_SEQ " --at 1.8 --json", &out), 1);
    free(out);
    studio_response r = call(exact, "GET", "/api/sequence/at", "t=1.8", NULL);
    cr_assert_eq(r.status, 409, "t = 1.8 is after the contact");
    assert_error_body(&r, "t after the contact");
    studio_response_free(&r);
    // the contact state: at the contact time, its faces collide
    json_t *c = call_json(exact, "GET", "/api/contact", "of=sequence", NULL, 200);
    cr_assert_eq(json_number_value(json_object_get(c, "t")), tc);
    cr_assert_eq(json_integer_value(json_object_get(c, "fold")), 2);
    assert_same(json_object_get(c, "collision"), col, "contact.collision");
    json_decref(c);
    json_t *k = call_json(exact, "POST", "/api/collide", NULL, "{\"contact\": \"sequence\"}", 200);
    cr_assert(json_is_true(json_object_get(k, "collides")));
    assert_same(json_array_get(json_object_get(k, "pairs"), 0), json_object_get(col, "faces"), "colliding pair");
    json_decref(k);
    json_decref(api);
    json_decref(cli);
    // the sequence posted again without the check, as --no-collisions
    char *text = test_read_text(TWO_FLAPS_SEQ);
    studio_arg args[1] = {{"no_collisions", "1"}};
    studio_request req = {"POST", "/api/sequence", args, 1, text, strlen(text)};
    studio_handle(exact, &req, &r);
    cr_assert_eq(r.status, 200);
    api = parse(r.body, r.size);
    studio_response_free(&r);
    cli = cli_json("sequence " TWO_FLAPS_SEQ " --no-collisions --json", 0);
    json_object_set_new(cli, "sequence", json_string("studio"));
    assert_same(api, cli, "sequence --no-collisions");
    json_decref(api);
    json_decref(cli);
    free(text);
    a = call_json(exact, "GET", "/api/sequence/at", "t=1.8", NULL, 200);
    json_decref(a);
    studio_destroy(exact);
}

// One state checked for self-collision: what orikin collide --json prints (with "state" added).
Test(server, collide_equals_cli_json)
{
    studio *s = open_studio(TWO_FLAPS);
    static const struct {
        const char *body, *cli;
        int rc;
    } cases[] = {
        {"{\"frame\": 1}", "collide " TWO_FLAPS " --frame 1 --json", 0},
        {"{\"frame\": 1, \"cloud\": 0.25}", "collide " TWO_FLAPS " --frame 1 --cloud 0.25 --json", 0},
        {"{\"frame\": 1, \"clearance\": 1.5}", "collide " TWO_FLAPS " --frame 1 --clearance 1.5 --json", 1},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        json_t *api = call_json(s, "POST", "/api/collide", NULL, cases[i].body, 200);
        cr_assert_str_eq(json_string_value(json_object_get(api, "state")), "frame 1");
        json_t *cli = cli_json(cases[i].cli, cases[i].rc); // "state" too: collide names states as render does
        assert_same(api, cli, cases[i].cli);
        json_decref(api);
        json_decref(cli);
    }
    studio_destroy(s);
    // a crossing folded form as it is
    s = open_studio("tests/data/collide-flaps-crossing.fold");
    json_t *api = call_json(s, "POST", "/api/collide", NULL, "{}", 200);
    json_t *cli = cli_json("collide tests/data/collide-flaps-crossing.fold --json", 1);
    assert_same(api, cli, "crossing flaps");
    json_decref(api);
    json_decref(cli);
    studio_destroy(s);
    // an instant of the sequence: the state orikin sequence --at writes, checked as collide does
    char *dir = test_tmpdir();
    char args[1024], path[512];
    snprintf(path, sizeof path, "%s/at.fold", dir);
    snprintf(args, sizeof args, "sequence " OPEN_CORNER_SEQ " --at 1.5 -o '%s'", path);
    cr_assert_eq(test_run_cli(args, NULL), 0);
    snprintf(args, sizeof args, "collide '%s' --frame 1 --json", path);
    cli = cli_json(args, 0);
    s = open_studio_def(OPEN_CORNER_SEQ, 0);
    api = call_json(s, "POST", "/api/collide", NULL, "{\"t\": 1.5}", 200);
    cr_assert(json_is_null(json_object_get(api, "frame")));
    cr_assert(json_is_true(json_object_get(api, "posed")));
    // the contact tolerance is relative to the collider's pattern: the flat sheet here (as the
    // motion checks), the folded form there
    static const char *const differ[] = {"file", "frame", "posed", "state", "tolerance"};
    for (int i = 0; i < 5; ++i) {
        json_object_del(api, differ[i]);
        json_object_del(cli, differ[i]);
    }
    assert_close(api, cli, 1e-12, "t = 1.5");
    json_decref(api);
    json_decref(cli);
    studio_destroy(s);
    test_tmpdir_remove(dir);
}

// check with and without a tolerance on a rounded drawing: orikin check --json, hint included.
Test(server, check_tolerance_equals_cli_json)
{
    studio *s = open_studio(ROUNDED_MIURA);
    static const struct {
        const char *query, *cli;
        int rc;
    } cases[] = {
        {NULL, "check " ROUNDED_MIURA " --json", 1},
        {"tolerance_deg=0.05", "check " ROUNDED_MIURA " --tolerance 0.05 --json", 0},
        {"tolerance_deg=0", "check " ROUNDED_MIURA " --tolerance 0 --json", 1},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        json_t *api = call_json(s, "GET", "/api/check", cases[i].query, NULL, 200);
        json_t *cli = cli_json(cases[i].cli, cases[i].rc);
        assert_same(api, cli, cases[i].cli);
        json_decref(api);
        json_decref(cli);
    }
    json_t *c = call_json(s, "GET", "/api/check", NULL, NULL, 200);
    cr_assert_not_null(strstr(json_string_value(json_object_get(c, "hint")), "orikin regularize " ROUNDED_MIURA));
    json_decref(c);
    c = call_json(s, "GET", "/api/check", "tolerance_deg=0.05", NULL, 200);
    cr_assert_eq(json_integer_value(json_object_get(c, "within_tolerance_vertices")), 5);
    json_decref(c);
    studio_destroy(s);
}

// regularize replaces the document by what orikin regularize -o writes (undoable) and reports
// what orikin regularize --json prints; a refusal changes nothing.
Test(server, regularize_equals_cli)
{
    char *dir = test_tmpdir();
    char args[1024], path[512];
    const char *rigid[] = {"", " --rigid"};
    const char *body[] = {"{}", "{\"rigid\": true}"};
    for (int i = 0; i < 2; ++i) {
        snprintf(path, sizeof path, "%s/exact%d.fold", dir, i);
        snprintf(args, sizeof args, "regularize " ROUNDED_MIURA "%s -o '%s'", rigid[i], path);
        cr_assert_eq(test_run_cli(args, NULL), 0);
        snprintf(args, sizeof args, "regularize " ROUNDED_MIURA "%s --json", rigid[i]);
        json_t *cli = cli_json(args, 0);
        studio *s = open_studio(ROUNDED_MIURA);
        char *before = document(s);
        json_t *api = call_json(s, "POST", "/api/regularize", NULL, body[i], 200);
        cr_assert(json_is_true(json_object_get(api, "replaced")));
        cr_assert_eq(json_integer_value(json_object_get(api, "undo")), 1);
        static const char *const extra[] = {"replaced", "version", "undo", "redo"};
        for (int k = 0; k < 4; ++k) json_object_del(api, extra[k]);
        assert_same(api, cli, args);
        cr_assert_gt(json_number_value(json_object_get(api, "max_move_rel")), 0.0);
        char *after = document(s);
        json_t *a = parse(after, strlen(after)), *b = load_fold_json(path);
        assert_same(a, b, "regularized document");
        json_decref(a);
        json_decref(b);
        // now it checks exactly
        json_t *c = call_json(s, "GET", "/api/check", NULL, NULL, 200);
        cr_assert(json_is_true(json_object_get(c, "locally_flat_foldable")));
        json_decref(c);
        json_decref(call_json(s, "POST", "/api/undo", NULL, NULL, 200));
        char *undone = document(s);
        cr_assert_str_eq(undone, before);
        free(undone);
        free(after);
        free(before);
        json_decref(api);
        json_decref(cli);
        studio_destroy(s);
    }
    // a vertex that no small move makes flat-foldable: refused, the document unchanged
    studio *s = open_studio("examples/patterns/non-flat-foldable-vertex.fold");
    char *before = document(s);
    long version = studio_version(s);
    json_t *api = call_json(s, "POST", "/api/regularize", NULL, "{}", 200);
    cr_assert(json_is_false(json_object_get(api, "replaced")));
    for (const char *const *k = (const char *const[]){"replaced", "version", "undo", "redo", NULL}; *k; ++k)
        json_object_del(api, *k);
    json_t *cli = cli_json("regularize examples/patterns/non-flat-foldable-vertex.fold --json", 1);
    assert_same(api, cli, "refused regularize");
    char *after = document(s);
    cr_assert_str_eq(after, before);
    cr_assert_eq(studio_version(s), version);
    free(after);
    free(before);
    json_decref(api);
    json_decref(cli);
    studio_destroy(s);
    test_tmpdir_remove(dir);
}

// Blank a PDF's creation and modification dates ("(D:2026…)"): the only bytes that differ
// between two runs.
static void blank_pdf_dates(char *b, size_t n)
{
    for (size_t i = 0; i + 3 < n; ++i)
        if (b[i] == '(' && b[i + 1] == 'D' && b[i + 2] == ':')
            for (size_t k = i + 3; k < n && b[k] != ')'; ++k) b[k] = '0';
}

// Renumber Cairo's SVG identifiers (surface1, clip2, …) in order of first appearance: Cairo
// numbers them per process, so a long-running server writes "surface6" where a fresh CLI writes
// "surface1" for the same drawing. Returns the new text (malloc'd) and its size.
static char *canonical_svg_ids(const char *b, size_t n, size_t *out_n)
{
    static const char *const prefixes[] = {"surface", "clip", "pattern", "mask", "image", "source", "filter", "glyph"};
    char *out = malloc(2 * n + 64), seen[64][32];
    int nseen = 0;
    size_t o = 0;
    for (size_t i = 0; i < n;) {
        bool done = false;
        for (size_t p = 0; p < sizeof prefixes / sizeof prefixes[0] && !done; ++p) {
            size_t k = strlen(prefixes[p]);
            if (i + k >= n || strncmp(b + i, prefixes[p], k) != 0 || !(b[i + k] >= '0' && b[i + k] <= '9')) continue;
            size_t j = i + k;
            while (j < n && b[j] >= '0' && b[j] <= '9') j++;
            char tok[32];
            snprintf(tok, sizeof tok, "%.*s", (int)(j - i), b + i);
            int id = -1;
            for (int q = 0; q < nseen; ++q)
                if (strcmp(seen[q], tok) == 0) id = q;
            if (id < 0 && nseen < 64) {
                snprintf(seen[nseen], sizeof seen[nseen], "%s", tok);
                id = nseen++;
            }
            o += (size_t)sprintf(out + o, "%s#%d", prefixes[p], id);
            i = j;
            done = true;
        }
        if (!done) out[o++] = b[i++];
    }
    *out_n = o;
    return out;
}

// GET /api/export?QUERY gives the bytes the CLI writes with ARGS -o OUT (ext: the file's suffix).
static void assert_export_equals(studio *s, const char *query, const char *args, const char *ext, const char *dir)
{
    char path[512], cmd[1024];
    snprintf(path, sizeof path, "%s/out.%s", dir, ext);
    snprintf(cmd, sizeof cmd, "%s -o '%s'", args, path);
    char *log = NULL;
    int rc = test_run_cli(cmd, &log);
    cr_assert_eq(rc, 0, "orikin %s: %s", cmd, log);
    free(log);
    size_t n;
    char *want = test_read_file(path, &n);
    cr_assert_not_null(want, "%s", path);
    studio_response r = call(s, "GET", "/api/export", query, NULL);
    cr_assert_eq(r.status, 200, "%s: %d %.300s", query, r.status, r.body);
    if (strcmp(ext, "pdf") == 0) {
        blank_pdf_dates(want, n);
        blank_pdf_dates(r.body, r.size);
    }
    if (strcmp(ext, "obj") == 0) {
        // A download is one file: the CLI's OBJ but its "mtllib out.mtl" line (the library it
        // writes beside the file).
        const char *line = "mtllib out.mtl\n";
        want[n] = '\0';
        char *at = strstr(want, line);
        cr_assert(at, "the CLI's OBJ names its material library");
        memmove(at, at + strlen(line), n - (size_t)(at - want) - strlen(line) + 1);
        n -= strlen(line);
    }
    if (strcmp(ext, "svg") == 0) {
        size_t a, b;
        char *x = canonical_svg_ids(want, n, &a), *y = canonical_svg_ids(r.body, r.size, &b);
        free(want);
        free(r.body);
        want = x;
        n = a;
        r.body = y;
        r.size = b;
    }
    cr_assert_eq(r.size, n, "%s: %zu bytes, the CLI wrote %zu", query, r.size, n);
    cr_assert(memcmp(r.body, want, n) == 0, "%s: the bytes differ from orikin %s", query, args);
    free(want);
    studio_response_free(&r);
}

// Every "orikin render", "orikin export" and "orikin animate" example of the documentation whose
// file is in the repository gives the same bytes through GET /api/export (issue 22): its fold
// options become POST /api/fold (the picture or mesh of the fold's last state, or with --animate
// and animate its motion), --at T and --frame N name the state (a sequence's end without them),
// its drawing options the query's fields, and -o's suffix the format; a compliant fold's options
// become POST /api/compliant (its end compliant=1, its load steps of=compliant). A texture is the
// CLI's only (the studio draws without one): such an example is counted, not compared.
Test(server, the_docs_render_export_and_animate_examples_give_the_same_files_in_the_studio)
{
    static doc_example ex[64];
    static const char *const commands[] = {"render", "export", "animate", NULL};
    int n = doc_examples(ex, 64, commands), compared = 0, textured = 0, modes = 0, compliants = 0;
    char *dir = test_tmpdir();
    for (int i = 0; i < n; ++i) {
        doc_example *e = &ex[i];
        const char *cmd = e->tok[1], *file = e->tok[2];
        bool seq = strstr(file, ".seq.json") != NULL, animate = strcmp(cmd, "animate") == 0, skip = false, compliant = false;
        char args[1024], query[512] = "", state[64] = "", ext[16] = "";
        size_t w = (size_t)snprintf(args, sizeof args, "%s %s ", cmd, file), q = 0;
        json_t *body = json_object();
        for (int k = 3; k < e->n; ++k) {
            const char *t = e->tok[k], *v = k + 1 < e->n ? e->tok[k + 1] : "";
            char value[128];
            snprintf(value, sizeof value, "%s", v);
            if (value[0] == '\'' && strlen(value) >= 2) { // a shell-quoted colour
                memmove(value, value + 1, strlen(value));
                value[strlen(value) - 1] = '\0';
            }
            if (strcmp(t, "-o") == 0) {
                const char *dot = strrchr(v, '.');
                cr_assert(dot, "%s: %s: -o names a file with a suffix", e->where, e->text);
                snprintf(ext, sizeof ext, "%s", dot + 1);
                k++;
                continue;
            }
            if (strcmp(t, "--texture") == 0) skip = true;
            if (strcmp(t, "--compliant") == 0) { // POST /api/compliant, then its state or motion
                compliant = true;
                w += (size_t)snprintf(args + w, sizeof args - w, "%s ", t);
                continue;
            }
            if (strcmp(t, "--color") == 0) {
                q += (size_t)snprintf(query + q, sizeof query - q, "&color=%s", v);
                w += (size_t)snprintf(args + w, sizeof args - w, "%s %s ", t, v);
                k++;
                continue;
            }
            int used = seq ? 0 : compliant ? compliant_option_json(body, t, v) : fold_option_json(body, t, v);
            if (used == 0) {
                static const char *const valued[] = {"yaw", "pitch", "roll", "camera", "front", "back", "size", "view",
                                                     "fps", "duration", "thickness", "texture", NULL};
                static const char *const flags[] = {"perspective", "edges", "grid", "labels", NULL};
                const char *key = t + 2;
                for (int j = 0; valued[j] && !used; ++j)
                    if (strcmp(key, valued[j]) == 0) {
                        q += (size_t)snprintf(query + q, sizeof query - q, "&%s=%s", key, value);
                        used = 2;
                    }
                for (int j = 0; flags[j] && !used; ++j)
                    if (strcmp(key, flags[j]) == 0) {
                        q += (size_t)snprintf(query + q, sizeof query - q, "&%s=1", key);
                        used = 1;
                    }
                if (!used && strcmp(t, "--at") == 0) {
                    snprintf(state, sizeof state, "&t=%s", v);
                    used = 2;
                } else if (!used && strcmp(t, "--animate") == 0) {
                    animate = true;
                    used = 1;
                }
            }
            cr_assert(used, "%s: %s: option %s has no API field in this test", e->where, e->text, t);
            w += (size_t)snprintf(args + w, sizeof args - w, "%s %s", t, used == 2 ? v : "");
            w += (size_t)snprintf(args + w, sizeof args - w, " ");
            k += used - 1;
        }
        if (skip) {
            textured++;
            json_decref(body);
            continue;
        }
        cr_assert(ext[0], "%s: %s: the example writes a file (-o)", e->where, e->text);
        bool fold = json_object_size(body) > 0 && !(json_object_size(body) == 1 && json_object_get(body, "frame"));
        json_t *frame = json_object_get(body, "frame");
        if (!fold && frame) snprintf(state, sizeof state, "&frame=%d", (int)json_integer_value(frame));
        studio *s = open_studio(file);
        if (compliant) {
            char *b = json_dumps(body, JSON_COMPACT);
            json_decref(call_json(s, "POST", "/api/compliant", NULL, b, 200));
            free(b);
            snprintf(state, sizeof state, "&compliant=1");
            compliants++;
        } else if (fold) {
            char *b = json_dumps(body, JSON_COMPACT);
            json_t *answer = call_json(s, "POST", "/api/fold", NULL, b, 200);
            free(b);
            int frames = (int)json_array_size(json_object_get(answer, "frames"));
            cr_assert_gt(frames, 0, "%s: %s: the fold has states", e->where, e->text);
            if (!animate) snprintf(state, sizeof state, "&k=%d", frames - 1);
            modes += json_object_get(answer, "mode") != NULL;
            json_decref(answer);
        } else if (seq && !state[0] && !animate) {
            json_t *answer = call_json(s, "GET", "/api/sequence", NULL, NULL, 200);
            snprintf(state, sizeof state, "&t=%.17g", json_number_value(json_object_get(answer, "duration")));
            json_decref(answer);
        }
        const char *format = strcmp(ext, "svg") == 0 ? "svg-picture" : ext;
        char full[768];
        snprintf(full, sizeof full, "format=%s%s%s", format,
                 animate ? (compliant ? "&of=compliant" : seq ? "&of=sequence" : "&of=fold") : state, query);
        assert_export_equals(s, full, args, ext, dir);
        cr_log_info("same file: %s: orikin %s / GET /api/export?%s", e->where, args, full);
        compared++;
        json_decref(body);
        studio_destroy(s);
    }
    // (the docs hold at least these: the sequence's pictures, GLB and GIF; the open corner's fold
    // picture and crease pattern; the waterbomb base toward its targets)
    cr_assert_geq(compared, 8, "%d examples compared", compared);
    cr_assert_geq(modes, 2, "%d examples of a fold toward the targets", modes);
    cr_assert_geq(compliants, 3, "%d examples of a compliant fold", compliants);
    cr_log_info("%d examples give the same files (%d of a fold mode, %d of a compliant fold); %d with a texture not "
                "compared", compared, modes, compliants, textured);
    test_tmpdir_remove(dir);
}

// Pictures, meshes and animations of states and motions: byte for byte what orikin render,
// export and animate write for the same state and options.
Test(server, exports_equal_render_export_and_animate)
{
    char *dir = test_tmpdir();
    studio *s = open_studio(OPEN_CORNER_SEQ);
    static const struct {
        const char *query, *args, *ext;
    } cases[] = {
        {"format=png", "render " OPEN_CORNER, "png"},
        {"format=png&frame=0&labels=1", "render " OPEN_CORNER " --labels", "png"},
        {"format=png&t=1.5&yaw=30", "render " OPEN_CORNER_SEQ " --at 1.5 --yaw 30", "png"},
        {"format=png&t=1.5&camera=top&perspective=1&size=320x200", "render " OPEN_CORNER_SEQ " --at 1.5 --camera top --perspective --size 320x200", "png"},
        {"format=svg-picture&t=2&grid=1&front=#3366cc", "render " OPEN_CORNER_SEQ " --at 2 --grid --front '#3366cc'", "svg"},
        {"format=pdf&t=1&edges=1", "render " OPEN_CORNER_SEQ " --at 1 --edges", "pdf"},
        {"format=obj&t=1.5", "export " OPEN_CORNER_SEQ " --at 1.5", "obj"},
        {"format=stl&t=2&thickness=0.02", "export " OPEN_CORNER_SEQ " --at 2 --thickness 0.02", "stl"},
        {"format=ply&t=0.5", "export " OPEN_CORNER_SEQ " --at 0.5", "ply"},
        {"format=gltf&t=1.25", "export " OPEN_CORNER_SEQ " --at 1.25", "gltf"},
        {"format=glb&t=2&back=navy", "export " OPEN_CORNER_SEQ " --at 2 --back navy", "glb"},
        {"format=gltf&of=sequence", "export " OPEN_CORNER_SEQ " --animate", "gltf"},
        {"format=glb&of=sequence", "export " OPEN_CORNER_SEQ " --animate", "glb"},
        {"format=gif&of=sequence&fps=5&duration=1&size=200x150", "animate " OPEN_CORNER_SEQ " --fps 5 --duration 1 --size 200x150", "gif"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) assert_export_equals(s, cases[i].query, cases[i].args, cases[i].ext, dir);
    // the page's camera (eye direction and up) is the preset it equals
    studio_response a = call(s, "GET", "/api/export", "format=png&t=1&camera=top", NULL);
    studio_response b = call(s, "GET", "/api/export", "format=png&t=1&eye=0,0,2&up=0,3,0", NULL);
    cr_assert_eq(a.status, 200);
    cr_assert_eq(b.status, 200);
    cr_assert(a.size == b.size && memcmp(a.body, b.body, a.size) == 0, "eye 0,0,1 up 0,1,0 is the top view");
    cr_assert_str_eq(a.content_type, "image/png");
    cr_assert_str_eq(a.filename, "open-corner.png");
    studio_response_free(&a);
    studio_response_free(&b);
    // a computed fold: its last state and its whole motion
    json_decref(call_json(s, "POST", "/api/fold", NULL, "{\"fix\": 4, \"drive\": 12, \"lock\": [11], \"to\": 90, \"step\": 10}", 200));
#define FOLD_ARGS OPEN_CORNER " --fix 4 --drive 12 --lock 11 --to 90 --step 10"
    assert_export_equals(s, "format=png&k=9", "render " FOLD_ARGS, "png", dir);
    assert_export_equals(s, "format=obj&k=9", "export " FOLD_ARGS, "obj", dir);
    assert_export_equals(s, "format=glb&of=fold", "export " FOLD_ARGS " --animate", "glb", dir);
    assert_export_equals(s, "format=gif&of=fold&fps=4&duration=1&size=160x120", "animate " FOLD_ARGS " --fps 4 --duration 1 --size 160x120", "gif", dir);
#undef FOLD_ARGS
    studio_response g = call(s, "GET", "/api/export", "format=gltf&of=fold", NULL);
    cr_assert_str_eq(g.filename, "open-corner-fold.gltf");
    studio_response_free(&g);
    studio_destroy(s);
    // a fold of several degrees of freedom (toward the targets, as the studio's slider folds):
    // its last state and its whole motion, frames timed by their progress
    s = open_studio(WATERBOMB_BASE);
    json_t *mode = call_json(s, "POST", "/api/fold", NULL, "{\"percent\": 100}", 200);
    int frames = (int)json_array_size(json_object_get(mode, "frames"));
    cr_assert_geq(frames, 2, "the fold toward the targets records its states");
    cr_assert_str_eq(json_string_value(json_object_get(mode, "verdict")), "reached");
    json_decref(mode);
    char last[64];
    snprintf(last, sizeof last, "format=png&k=%d", frames - 1);
#define MODE_ARGS WATERBOMB_BASE " --percent 100"
    assert_export_equals(s, last, "render " MODE_ARGS, "png", dir);
    assert_export_equals(s, "format=glb&of=fold", "export " MODE_ARGS " --animate", "glb", dir);
    assert_export_equals(s, "format=gltf&of=fold", "export " MODE_ARGS " --animate", "gltf", dir);
    assert_export_equals(s, "format=gif&of=fold&fps=4&duration=1&size=160x120", "animate " MODE_ARGS " --fps 4 --duration 1 --size 160x120", "gif", dir);
#undef MODE_ARGS
    studio_destroy(s);
    test_tmpdir_remove(dir);
}

// The running phase's fraction reaches GET /api/progress.
Test(server, progress_reports_the_fraction)
{
    studio *s = open_studio(OPEN_CORNER);
    studio_response r;
    memset(&r, 0, sizeof r);
    cr_assert(studio_job_begin(s, "fold", &r));
    json_t *p = call_json(s, "GET", "/api/progress", NULL, NULL, 200);
    cr_assert(json_is_null(json_object_get(p, "fraction")), "no fraction before the phase reports one");
    json_decref(p);
    studio_job_phase(s, "fold: checking collisions");
    studio_job_progress(0.25, s);
    p = call_json(s, "GET", "/api/progress", NULL, NULL, 200);
    cr_assert_str_eq(json_string_value(json_object_get(p, "job")), "fold: checking collisions");
    cr_assert_eq(json_number_value(json_object_get(p, "fraction")), 0.25);
    json_decref(p);
    studio_job_end(s);
    studio_destroy(s);
}

// --- HTTP ----------------------------------------------------------------------------------------

typedef struct http_reply {
    int status;
    char headers[4096];
    char *body;
    size_t size;
} http_reply;

static int connect_to(int port)
{
    int fd = socket(AF_INET, SOCK_STREAM, 0);
    cr_assert_geq(fd, 0);
    struct sockaddr_in a;
    memset(&a, 0, sizeof a);
    a.sin_family = AF_INET;
    a.sin_port = htons((uint16_t)port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    cr_assert_eq(connect(fd, (struct sockaddr *)&a, sizeof a), 0);
    int one = 1;
    setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    return fd;
}

// Send a raw request on fd and read one response (headers, then Content-Length bytes, or up to
// the close). Returns false when the connection dropped before a status line.
static bool exchange(int fd, const char *request, size_t request_size, http_reply *r)
{
    memset(r, 0, sizeof *r);
    size_t sent = 0;
    while (sent < request_size) {
        ssize_t n = send(fd, request + sent, request_size - sent, MSG_NOSIGNAL);
        if (n <= 0) break; // the server may answer (413) and close before reading everything
        sent += (size_t)n;
    }
    size_t cap = 65536, len = 0;
    char *buf = malloc(cap);
    char *eoh = NULL;
    while (!eoh) {
        if (len + 1 >= cap) buf = realloc(buf, cap *= 2);
        ssize_t n = recv(fd, buf + len, cap - len - 1, 0);
        if (n <= 0) break;
        len += (size_t)n;
        buf[len] = '\0';
        eoh = strstr(buf, "\r\n\r\n");
    }
    if (!eoh || sscanf(buf, "HTTP/1.%*d %d", &r->status) != 1) {
        free(buf);
        return false;
    }
    size_t hlen = (size_t)(eoh - buf) + 4; // an offset: buf may move below
    snprintf(r->headers, sizeof r->headers, "%.*s", (int)hlen, buf);
    const char *cl = strcasestr(r->headers, "\r\nContent-Length:");
    long want = cl ? strtol(cl + 17, NULL, 10) : -1;
    while (want < 0 || len - hlen < (size_t)want) {
        if (len + 1 >= cap) buf = realloc(buf, cap *= 2);
        ssize_t n = recv(fd, buf + len, cap - len - 1, 0);
        if (n <= 0) break;
        len += (size_t)n;
    }
    r->size = len - hlen;
    r->body = malloc(r->size + 1);
    memcpy(r->body, buf + hlen, r->size);
    r->body[r->size] = '\0';
    free(buf);
    return true;
}

// One request on a fresh connection.
static http_reply http(int port, const char *request)
{
    int fd = connect_to(port);
    http_reply r;
    cr_assert(exchange(fd, request, strlen(request), &r), "no answer to %.80s", request);
    close(fd);
    return r;
}

#define TOKEN "0123456789abcdef0123456789abcdef"

typedef struct served {
    studio *s;
    studio_http *h;
    int port;
} served;

static served serve(const char *path)
{
    served x;
    x.s = open_studio(path);
    char err[256];
    x.h = studio_http_start(x.s, NULL, 0, TOKEN, err, sizeof err);
    cr_assert_not_null(x.h, "%s", err);
    x.port = studio_http_port(x.h);
    cr_assert_gt(x.port, 0);
    return x;
}

static void unserve(served *x)
{
    studio_http_stop(x->h);
    studio_destroy(x->s);
}

static int status_of(int port, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int status_of(int port, const char *fmt, ...)
{
    char req[2048];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(req, sizeof req, fmt, ap);
    va_end(ap);
    http_reply r = http(port, req);
    free(r.body);
    return r.status;
}

Test(server, http_refuses_foreign_hosts_and_missing_tokens)
{
    served x = serve(OPEN_CORNER);
    int p = x.port;
    const char *api = "GET /api/session HTTP/1.1\r\nHost: %s\r\n%sConnection: close\r\n\r\n";
    char host[64];
    snprintf(host, sizeof host, "127.0.0.1:%d", p);
    cr_assert_eq(status_of(p, api, host, "X-Orikin-Token: " TOKEN "\r\n"), 200);
    snprintf(host, sizeof host, "localhost:%d", p);
    cr_assert_eq(status_of(p, api, host, "X-Orikin-Token: " TOKEN "\r\n"), 200);
    // the token is required on every API request, and must be the session's
    snprintf(host, sizeof host, "127.0.0.1:%d", p);
    cr_assert_eq(status_of(p, api, host, ""), 401);
    cr_assert_eq(status_of(p, api, host, "X-Orikin-Token: 0123456789abcdef0123456789abcdee\r\n"), 401);
    cr_assert_eq(status_of(p, api, host, "X-Orikin-Token: " TOKEN "0\r\n"), 401);
    cr_assert_eq(status_of(p, api, host, "Cookie: token=" TOKEN "\r\n"), 401);
    // DNS rebinding: a page from another name reaching this port is refused, token or not
    cr_assert_eq(status_of(p, api, "evil.example", "X-Orikin-Token: " TOKEN "\r\n"), 403);
    snprintf(host, sizeof host, "evil.example:%d", p);
    cr_assert_eq(status_of(p, api, host, "X-Orikin-Token: " TOKEN "\r\n"), 403);
    snprintf(host, sizeof host, "127.0.0.1:%d", p + 1);
    cr_assert_eq(status_of(p, api, host, "X-Orikin-Token: " TOKEN "\r\n"), 403);
    snprintf(host, sizeof host, "127.0.0.2:%d", p);
    cr_assert_eq(status_of(p, api, host, "X-Orikin-Token: " TOKEN "\r\n"), 403);
    cr_assert_eq(status_of(p, "GET / HTTP/1.0\r\n\r\n"), 403);
    snprintf(host, sizeof host, "evil.example:%d", p);
    cr_assert_eq(status_of(p, "GET / HTTP/1.1\r\nHost: %s\r\nConnection: close\r\n\r\n", host), 403);
    // a cross-origin request (another site's page) is refused
    snprintf(host, sizeof host, "127.0.0.1:%d", p);
    cr_assert_eq(status_of(p, api, host, "X-Orikin-Token: " TOKEN "\r\nOrigin: http://evil.example\r\n"), 403);
    char origin[128];
    snprintf(origin, sizeof origin, "X-Orikin-Token: " TOKEN "\r\nOrigin: http://127.0.0.1:%d\r\n", p);
    cr_assert_eq(status_of(p, api, host, origin), 200);
    // methods
    cr_assert_eq(status_of(p, "PUT /api/session HTTP/1.1\r\nHost: %s\r\nX-Orikin-Token: " TOKEN "\r\nConnection: close\r\n\r\n", host), 405);
    cr_assert_eq(status_of(p, "POST / HTTP/1.1\r\nHost: %s\r\nContent-Length: 0\r\nConnection: close\r\n\r\n", host), 405);
    unserve(&x);
}

// Listening on every address (--host 0.0.0.0): any numeric Host with the port is this server,
// a name is not (DNS rebinding), and the token is still required.
Test(server, http_wildcard_host)
{
    studio *s = open_studio(OPEN_CORNER);
    char err[256];
    studio_http *h = studio_http_start(s, "0.0.0.0", 0, TOKEN, err, sizeof err);
    cr_assert_not_null(h, "%s", err);
    int p = studio_http_port(h);
    const char *api = "GET /api/session HTTP/1.1\r\nHost: %s\r\n%sConnection: close\r\n\r\n";
    char host[64];
    snprintf(host, sizeof host, "192.0.2.7:%d", p);
    cr_assert_eq(status_of(p, api, host, "X-Orikin-Token: " TOKEN "\r\n"), 200);
    cr_assert_eq(status_of(p, api, host, ""), 401);
    snprintf(host, sizeof host, "[2001:db8::1]:%d", p);
    cr_assert_eq(status_of(p, api, host, "X-Orikin-Token: " TOKEN "\r\n"), 200);
    snprintf(host, sizeof host, "studio.example:%d", p);
    cr_assert_eq(status_of(p, api, host, "X-Orikin-Token: " TOKEN "\r\n"), 403);
    studio_http_stop(h);
    studio_destroy(s);
    // a name is not an address to listen on
    cr_assert_null(studio_http_start(NULL, "localhost", 0, TOKEN, err, sizeof err));
    cr_assert_not_null(strstr(err, "numeric address"));
}

Test(server, http_serves_only_embedded_assets)
{
    served x = serve(OPEN_CORNER);
    int p = x.port;
    char host[64];
    snprintf(host, sizeof host, "127.0.0.1:%d", p);
    static const char *const outside[] = {
        "/../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd", "/..%2f..%2fetc%2fpasswd", "/%2E%2E%2F%2E%2E%2Fetc%2Fpasswd",
        "//etc/passwd", "/index.html/../../../etc/passwd", "/%252e%252e/etc/passwd", "/..%5c..%5cetc%5cpasswd",
        "/etc/passwd", "/CMakeLists.txt", "/web/index.html", "/web/src/main.js", "/cli/cmd_view.c", "/./index.html",
        "/index.html%00.js", "/app.js/", "/%2fetc%2fpasswd", "/api/../../etc/passwd",
    };
    for (size_t i = 0; i < sizeof outside / sizeof outside[0]; ++i) {
        char req[512];
        snprintf(req, sizeof req, "GET %s HTTP/1.1\r\nHost: %s\r\nX-Orikin-Token: " TOKEN "\r\nConnection: close\r\n\r\n",
                 outside[i], host);
        http_reply r = http(p, req);
        cr_assert_eq(r.status, 404, "%s: status %d", outside[i], r.status);
        cr_assert_null(strstr(r.body, "root:"), "%s served a file from disk", outside[i]);
        free(r.body);
    }
    if (studio_assets_built()) {
        char req[256];
        snprintf(req, sizeof req, "GET / HTTP/1.1\r\nHost: %s\r\nConnection: close\r\n\r\n", host);
        http_reply r = http(p, req);
        cr_assert_eq(r.status, 200);
        cr_assert_not_null(strcasestr(r.headers, "Content-Security-Policy: default-src 'self'"));
        cr_assert_not_null(strcasestr(r.headers, "Content-Type: text/html"));
        cr_assert_eq(r.size, studio_asset_find("/index.html")->size);
        free(r.body);
        snprintf(req, sizeof req, "GET /app.js HTTP/1.1\r\nHost: %s\r\nConnection: close\r\n\r\n", host);
        r = http(p, req);
        cr_assert_eq(r.status, 200);
        cr_assert_eq(r.size, studio_asset_find("/app.js")->size);
        free(r.body);
    } else {
        cr_log_warn("the web assets were not built (node_modules missing): asset serving not checked");
    }
    unserve(&x);
}

Test(server, http_limits_request_bodies)
{
    served x = serve(OPEN_CORNER);
    int p = x.port;
    char host[64];
    snprintf(host, sizeof host, "127.0.0.1:%d", p);
    // announced too large: refused before the body is read
    cr_assert_eq(status_of(p, "POST /api/fold HTTP/1.1\r\nHost: %s\r\nX-Orikin-Token: " TOKEN "\r\nContent-Length: %zu\r\n"
                              "Connection: close\r\n\r\n{",
                           host, STUDIO_MAX_BODY_BYTES + 1),
                 413);
    // chunked, growing past the limit: read, dropped, refused
    size_t n = STUDIO_MAX_BODY_BYTES + 4096, chunk = 65536;
    char *req = malloc((n / chunk + 2) * (chunk + 16) + 1024);
    int len = snprintf(req, 1024, "POST /api/fold HTTP/1.1\r\nHost: %s\r\nX-Orikin-Token: " TOKEN
                                  "\r\nTransfer-Encoding: chunked\r\nConnection: close\r\n\r\n", host);
    for (size_t sent = 0; sent < n; sent += chunk) {
        len += sprintf(req + len, "%zx\r\n", chunk);
        memset(req + len, ' ', chunk);
        len += (int)chunk;
        len += sprintf(req + len, "\r\n");
    }
    len += sprintf(req + len, "0\r\n\r\n");
    int fd = connect_to(p);
    http_reply r;
    cr_assert(exchange(fd, req, (size_t)len, &r));
    close(fd);
    cr_assert_eq(r.status, 413);
    free(r.body);
    free(req);
    // malformed JSON over HTTP: 400 with one line, and the server keeps serving
    char bad[512];
    snprintf(bad, sizeof bad, "POST /api/fold HTTP/1.1\r\nHost: %s\r\nX-Orikin-Token: " TOKEN
                              "\r\nContent-Length: 5\r\nConnection: close\r\n\r\n{\"fix",
             host);
    r = http(p, bad);
    cr_assert_eq(r.status, 400);
    cr_assert_not_null(strstr(r.body, "malformed JSON"));
    free(r.body);
    cr_assert_eq(status_of(p, "GET /api/session HTTP/1.1\r\nHost: %s\r\nX-Orikin-Token: " TOKEN "\r\nConnection: close\r\n\r\n", host), 200);
    unserve(&x);
}

// --- load: 1,000 requests over 50 keep-alive connections ----------------------------------------

#define LOAD_CONNECTIONS 50
#define LOAD_PER_CONNECTION 20

typedef struct load_worker {
    int port;
    int index;
    int errors;
    double latency[LOAD_PER_CONNECTION];
} load_worker;

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void *load_run(void *arg)
{
    load_worker *w = arg;
    int fd = connect_to(w->port);
    for (int i = 0; i < LOAD_PER_CONNECTION; ++i) {
        char req[512];
        int kind = (w->index + i) % 4;
        const char *target = kind == 0 ? "/api/session" : kind == 1 ? "/api/sequence/at?t=1.5" : kind == 2 ? "/api/document" : "/api/sequence/at?t=0.5&binary=1";
        snprintf(req, sizeof req, "GET %s HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nX-Orikin-Token: " TOKEN "\r\n\r\n", target, w->port);
        double t0 = now_s();
        http_reply r;
        bool ok = exchange(fd, req, strlen(req), &r);
        w->latency[i] = now_s() - t0;
        if (!ok || r.status != 200 || r.size == 0) w->errors++;
        if (ok) free(r.body);
        if (!ok) {
            close(fd);
            fd = connect_to(w->port);
        }
    }
    close(fd);
    return NULL;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

Test(server, load_1000_requests_over_50_connections)
{
    served x = serve(OPEN_CORNER_SEQ);
    load_worker w[LOAD_CONNECTIONS];
    pthread_t th[LOAD_CONNECTIONS];
    double t0 = now_s();
    for (int i = 0; i < LOAD_CONNECTIONS; ++i) {
        w[i].port = x.port;
        w[i].index = i;
        w[i].errors = 0;
        cr_assert_eq(pthread_create(&th[i], NULL, load_run, &w[i]), 0);
    }
    int errors = 0;
    double all[LOAD_CONNECTIONS * LOAD_PER_CONNECTION];
    for (int i = 0; i < LOAD_CONNECTIONS; ++i) {
        pthread_join(th[i], NULL);
        errors += w[i].errors;
        memcpy(all + i * LOAD_PER_CONNECTION, w[i].latency, sizeof w[i].latency);
    }
    double wall = now_s() - t0;
    int n = LOAD_CONNECTIONS * LOAD_PER_CONNECTION;
    qsort(all, (size_t)n, sizeof all[0], cmp_double);
    printf("load: %d requests over %d connections in %.3f s: %.0f requests/s, latency p50 %.2f ms, p99 %.2f ms, "
           "max %.2f ms, %d errors\n",
           n, LOAD_CONNECTIONS, wall, n / wall, 1e3 * all[n / 2], 1e3 * all[n * 99 / 100], 1e3 * all[n - 1], errors);
    fflush(stdout);
    cr_assert_eq(errors, 0);
    unserve(&x);
}

// A sequence with a fold toward the targets ("percent"): the studio loads and plays it; the
// record, the instants (restored exactly, no cache: there is no drive range to grid) and the
// contact are what orikin sequence prints, the drive null (its "drive" is the progress).
#define WATERBOMB_TARGETS_SEQ "tests/data/waterbomb-base-targets.seq.json"
#define TWO_FLAPS_PERCENT_SEQ "tests/data/two-flaps-percent.seq.json"
Test(server, percent_sequence_equals_cli_json)
{
    studio *s = open_studio(WATERBOMB_TARGETS_SEQ);
    json_t *api = call_json(s, "GET", "/api/sequence", NULL, NULL, 200);
    json_t *cli = cli_json("sequence " WATERBOMB_TARGETS_SEQ " --json", 0);
    assert_same(api, cli, "percent sequence");
    json_t *f0 = json_array_get(json_object_get(api, "folds"), 0);
    cr_assert(json_is_null(json_object_get(f0, "drive")));
    cr_assert_float_eq(json_number_value(json_object_get(f0, "percent")), 100.0, 0.0);
    json_decref(api);
    json_decref(cli);
    static const char *const times[] = {"0", "0.3", "0.75", "1"};
    for (size_t i = 0; i < sizeof times / sizeof times[0]; ++i) {
        char q[64], args[256];
        snprintf(q, sizeof q, "t=%s", times[i]);
        snprintf(args, sizeof args, "sequence " WATERBOMB_TARGETS_SEQ " --at %s --json", times[i]);
        json_t *a = call_json(s, "GET", "/api/sequence/at", q, NULL, 200);
        json_t *c = cli_json(args, 0);
        assert_same(a, c, q);
        cr_assert(json_is_null(json_object_get(a, "drive_deg")));
        json_decref(a);
        json_decref(c);
    }
    studio_response r = call(s, "GET", "/api/sequence/at", "t=0.3&binary=1", NULL);
    cr_assert_eq(r.status, 200);
    uint64_t u = 0;
    for (int b = 0; b < 8; ++b) u |= (uint64_t)(unsigned char)r.body[16 + b] << (8 * b);
    double d;
    memcpy(&d, &u, 8);
    cr_assert(isnan(d), "binary drive of a percent fold is NaN, got %g", d);
    studio_response_free(&r);
    // POSTed as the page does, the same record
    char *text = test_read_text(WATERBOMB_TARGETS_SEQ);
    api = call_json(s, "POST", "/api/sequence", NULL, text, 200);
    free(text);
    cli = cli_json("sequence " WATERBOMB_TARGETS_SEQ " --json", 0);
    json_object_set_new(cli, "sequence", json_string("studio"));
    assert_same(api, cli, "posted percent sequence");
    json_decref(api);
    json_decref(cli);
    studio_destroy(s);

    // colliding: the contact is given as the progress
    s = open_studio(TWO_FLAPS_PERCENT_SEQ);
    api = call_json(s, "GET", "/api/sequence", NULL, NULL, 200);
    cli = cli_json("sequence " TWO_FLAPS_PERCENT_SEQ " --json", 1);
    assert_same(api, cli, "colliding percent sequence");
    json_t *col = json_object_get(api, "collision");
    double p = json_number_value(json_object_get(col, "progress"));
    cr_assert(fabs(p - acos(-1.0 / 3.0) / ORI_PI) < 1e-7, "contact at progress %.10f", p);
    json_t *c = call_json(s, "GET", "/api/contact", "of=sequence", NULL, 200);
    cr_assert(json_is_null(json_object_get(c, "drive_deg")));
    assert_same(json_object_get(c, "collision"), col, "contact.collision");
    json_decref(c);
    json_decref(api);
    json_decref(cli);
    studio_destroy(s);
}

// An underdetermined fold: the studio's answer is orikin fold's, its hint naming a lock set
// (which the page shows), and that lock set makes the fold valid.
Test(server, underdetermined_fold_lock_hint_equals_cli_json)
{
    studio *s = open_studio("tests/data/kin-open-corner.fold");
    json_t *api = call_json(s, "POST", "/api/fold", NULL, "{\"fix\": 0, \"drive\": 8, \"to\": 90}", 200);
    json_t *cli = cli_json("fold tests/data/kin-open-corner.fold --fix 0 --drive 8 --to 90 --json", 1);
    assert_same(api, cli, "underdetermined fold");
    cr_assert_str_eq(json_string_value(json_object_get(api, "verdict")), "underdetermined");
    const char *hint = json_string_value(json_object_get(api, "hint"));
    cr_assert_not_null(hint);
    const char *lock = strstr(hint, "--lock ");
    cr_assert_not_null(lock, "%s", hint);
    int e = atoi(lock + strlen("--lock "));
    char body[128];
    snprintf(body, sizeof body, "{\"fix\": 0, \"drive\": 8, \"to\": 90, \"lock\": [%d]}", e);
    json_t *locked = call_json(s, "POST", "/api/fold", NULL, body, 200);
    cr_assert(json_is_true(json_object_get(locked, "valid")), "with --lock %d: %s", e,
              json_string_value(json_object_get(locked, "reason")));
    json_decref(locked);
    json_decref(api);
    json_decref(cli);
    studio_destroy(s);
}

Test(server, fold_lock_auto_equals_cli_json)
{
    // "lock": "auto" with one drive: the lock set orikin fold --lock auto computes, then the same
    // fold (the waterbomb base: several degrees of freedom)
    studio *s = open_studio("tests/data/waterbomb-base.fold");
    json_t *api = call_json(s, "POST", "/api/fold", NULL, "{\"fix\": 0, \"drive\": 8, \"to\": -60, \"step\": 10, \"lock\": \"auto\"}", 200);
    json_t *cli = cli_json("fold tests/data/waterbomb-base.fold --fix 0 --drive 8 --to -60 --step 10 --lock auto --json", 0);
    assert_same(api, cli, "lock auto");
    cr_assert_str_eq(json_string_value(json_object_get(api, "verdict")), "valid");
    cr_assert_gt(json_array_size(json_object_get(api, "locked")), 0);
    json_decref(api);
    json_decref(cli);
    // a drive that leaves no freedom to lock away: the CLI's words
    expect_refused(s, "POST", "/api/fold", "{\"fix\": 0, \"drive\": 8, \"to\": -60, \"lock\": \"nope\"}",
                   "lock: \\\"auto\\\" or an array");
    studio_destroy(s);
}

Test(server, fold_modes_equal_cli_json)
{
    // toward the targets, symmetric, several drives with lock auto: the answer orikin fold gives
    // in that mode (cli/report/modes_report.c), and its states served by /api/fold/frame
    studio *s = open_studio("tests/data/waterbomb-base.fold");
    const struct {
        const char *body, *cli;
        int rc;
    } cases[] = {
        {"{\"percent\": 60, \"step\": 10}", "--percent 60 --step 10", 0},
        {"{\"fix\": 0, \"drive\": 8, \"to\": -60, \"step\": 10, \"symmetric\": true}", "--fix 0 --drive 8 --to -60 --step 10 --symmetric", 0},
        {"{\"fix\": 0, \"drive\": [8, 12], \"to\": [-60, 30], \"step\": 10, \"lock\": \"auto\"}",
         "--fix 0 --drive 8,12 --to -60,30 --step 10 --lock auto", 1},
        {"{\"percent\": 100, \"symmetric\": true, \"no_collisions\": true}", "--percent 100 --symmetric --no-collisions", 0},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        json_t *api = call_json(s, "POST", "/api/fold", NULL, cases[i].body, 200);
        char cmd[256];
        snprintf(cmd, sizeof cmd, "fold tests/data/waterbomb-base.fold %s --json", cases[i].cli);
        json_t *cli = cli_json(cmd, cases[i].rc);
        assert_same(api, cli, cases[i].cli);
        json_t *frames = json_object_get(api, "frames");
        size_t n = json_array_size(frames);
        cr_assert_gt(n, 1, "%s", cases[i].cli);
        // the last state: the answer's angles, a closed state
        char query[64];
        snprintf(query, sizeof query, "k=%zu", n - 1);
        json_t *fr = call_json(s, "GET", "/api/fold/frame", query, NULL, 200);
        cr_assert(json_is_null(json_object_get(fr, "drive_deg")), "a mode has no drive angle");
        json_t *want = json_object_get(json_array_get(frames, n - 1), "fold_angles_deg");
        json_t *got = json_object_get(fr, "fold_angles_deg");
        cr_assert_eq(json_array_size(got), json_array_size(want));
        for (size_t e = 0; e < json_array_size(want); ++e)
            cr_assert_float_eq(json_number_value(json_array_get(got, e)), json_number_value(json_array_get(want, e)), 1e-12,
                               "%s: edge %zu", cases[i].cli, e);
        cr_assert_leq(json_number_value(json_object_get(fr, "residual")), 1e-9);
        json_decref(fr);
        json_decref(api);
        json_decref(cli);
    }
    // the mistakes orikin fold refuses, refused in the same terms
    const struct {
        const char *body, *text;
    } bad[] = {
        {"{\"percent\": 120}", "percent needs a number from 0 to 100, got 120"},
        {"{\"percent\": 50, \"drive\": 8}", "percent folds every crease toward its target: no drive or to with it"},
        {"{\"percent\": 50, \"from\": 0}", "from applies to a single drive"},
        {"{\"drive\": [8, 12], \"to\": [-60]}", "to has 1 angles for 2 driven creases"},
        {"{\"drive\": [8, 99], \"to\": [-60, 30]}", "no edge 99"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        studio_response r = call(s, "POST", "/api/fold", NULL, bad[i].body);
        cr_assert_eq(r.status, 400, "%s: %d %s", bad[i].body, r.status, r.body);
        cr_assert(strstr(r.body, bad[i].text), "%s: %s", bad[i].body, r.body);
        studio_response_free(&r);
    }
    studio_destroy(s);
}

// Host parsing is strict (issue: "Host: 127.0.0.1:+PORT" was accepted, and of two Host headers
// only the first was read): the port in decimal digits equal to ours, and one Host, Origin and
// token header each.
Test(server, http_parses_host_strictly_and_refuses_repeated_headers)
{
    served x = serve(OPEN_CORNER);
    int p = x.port;
    char req[512];
    snprintf(req, sizeof req, "GET /api/session HTTP/1.1\r\nHost: 127.0.0.1:+%d\r\nX-Orikin-Token: " TOKEN
                              "\r\nConnection: close\r\n\r\n", p);
    cr_assert_eq(status_of(p, "%s", req), 403);
    snprintf(req, sizeof req, "GET /api/session HTTP/1.1\r\nHost: 127.0.0.1:0%d\r\nX-Orikin-Token: " TOKEN
                              "\r\nConnection: close\r\n\r\n", p);
    cr_assert_eq(status_of(p, "%s", req), 403);
    snprintf(req, sizeof req, "GET /api/session HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nHost: evil.example:%d\r\n"
                              "X-Orikin-Token: " TOKEN "\r\nConnection: close\r\n\r\n", p, p);
    cr_assert_eq(status_of(p, "%s", req), 400);
    snprintf(req, sizeof req, "GET /api/session HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nX-Orikin-Token: " TOKEN
                              "\r\nX-Orikin-Token: " TOKEN "\r\nConnection: close\r\n\r\n", p);
    cr_assert_eq(status_of(p, "%s", req), 400);
    snprintf(req, sizeof req, "GET /api/session HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nX-Orikin-Token: " TOKEN
                              "\r\nOrigin: http://127.0.0.1:%d\r\nOrigin: http://evil.example\r\nConnection: close\r\n\r\n", p, p);
    cr_assert_eq(status_of(p, "%s", req), 400);
    snprintf(req, sizeof req, "GET /api/session HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nX-Orikin-Token: " TOKEN
                              "\r\nConnection: close\r\n\r\n", p);
    cr_assert_eq(status_of(p, "%s", req), 200);
    unserve(&x);
}

// A local user without the token cannot shut the studio off (issue: 256 idle connections locked
// everyone out, and a GET / with an endless body was read forever): 300 idle connections and a
// slow body later, the page and the API still answer, and a body a route does not take is
// refused before it is read.
Test(server, http_keeps_serving_under_idle_connections_and_endless_bodies)
{
    served x = serve(OPEN_CORNER);
    int p = x.port;
    char host[64];
    snprintf(host, sizeof host, "127.0.0.1:%d", p);
    enum { IDLE = 300 };
    int idle[IDLE];
    for (int i = 0; i < IDLE; ++i) idle[i] = connect_to(p);
    // a slow body: headers, one byte of the hundred announced, then nothing
    int slow = connect_to(p);
    char req[512];
    int n = snprintf(req, sizeof req, "POST /api/fold HTTP/1.1\r\nHost: %s\r\nX-Orikin-Token: " TOKEN
                                      "\r\nContent-Length: 100\r\n\r\n{", host);
    cr_assert_eq(send(slow, req, (size_t)n, MSG_NOSIGNAL), n);
    // an endless body on a page request: answered 413 at once, the body unread
    int endless = connect_to(p);
    n = snprintf(req, sizeof req, "GET / HTTP/1.1\r\nHost: %s\r\nTransfer-Encoding: chunked\r\n\r\n1000\r\n", host);
    cr_assert_eq(send(endless, req, (size_t)n, MSG_NOSIGNAL), n);
    http_reply r;
    cr_assert(exchange(endless, "", 0, &r));
    cr_assert_eq(r.status, 413);
    free(r.body);
    close(endless);
    // the page and the API answer meanwhile
    snprintf(req, sizeof req, "GET / HTTP/1.1\r\nHost: %s\r\nConnection: close\r\n\r\n", host);
    cr_assert_eq(status_of(p, "%s", req), studio_assets_built() ? 200 : 503);
    snprintf(req, sizeof req, "GET /api/session HTTP/1.1\r\nHost: %s\r\nX-Orikin-Token: " TOKEN "\r\nConnection: close\r\n\r\n", host);
    cr_assert_eq(status_of(p, "%s", req), 200);
    close(slow);
    for (int i = 0; i < IDLE; ++i) close(idle[i]);
    unserve(&x);
}

// orikin view hands the browser a page, not the URL (issue: `xdg-open URL?token=…` put the
// token on a command line, which any local user reads in /proc/PID/cmdline): a stand-in
// xdg-open records its arguments, the page's mode and its own blocked signals; the token is
// not among the arguments, the page (0600, in a 0700 directory) leads to the URL with the token,
// the launcher blocks no signal (it inherited INT, TERM and HUP blocked), and the page is gone
// when the studio stops.
Test(server, view_hands_the_browser_a_private_page_not_the_token)
{
    char *dir = test_tmpdir(), script[700], out[700], cmd[2400];
    snprintf(out, sizeof out, "%s/out", dir);
    cr_assert_eq(mkdir(out, 0700), 0);
    snprintf(script, sizeof script, "%s/xdg-open", dir);
    FILE *f = fopen(script, "w");
    cr_assert_not_null(f);
    // The mask is read first, by the shell's builtins: once the script forks (stat, cat), dash
    // blocks every signal around its vfork, and a reader racing that window saw them blocked.
    fprintf(f, "#!/bin/sh\nwhile read -r k v; do [ \"$k\" = SigBlk: ] && echo \"$k $v\" > '%s/sigblk'; done < /proc/$$/status\n"
               "stat -c %%a \"$1\" > '%s/mode'\nstat -c %%a \"$(dirname \"$1\")\" > '%s/dirmode'\n"
               "cat \"$1\" > '%s/page'\necho \"$@\" > '%s/args.tmp'\n"
               "mv '%s/args.tmp' '%s/args'\n",
            out, out, out, out, out, out, out);
    fclose(f);
    cr_assert_eq(chmod(script, 0700), 0);
    pid_t pid = fork();
    cr_assert_geq(pid, 0);
    if (pid == 0) {
        prctl(PR_SET_PDEATHSIG, SIGINT); // a failed assertion ends the test: the studio stops with it
        snprintf(cmd, sizeof cmd, "%s/url", out);
        int fd = open(cmd, O_WRONLY | O_CREAT | O_TRUNC, 0600);
        dup2(fd, STDOUT_FILENO);
        snprintf(cmd, sizeof cmd, "%s:%s", dir, getenv("PATH") ? getenv("PATH") : "/usr/bin:/bin");
        setenv("PATH", cmd, 1);
        setenv("XDG_RUNTIME_DIR", dir, 1);
        if (chdir(ORI_SOURCE_DIR) != 0) _exit(126);
        execl(ORI_CLI_PATH, "orikin", "view", "--port", "0", OPEN_CORNER, (char *)NULL);
        _exit(127);
    }
    char args_path[800], *args = NULL;
    snprintf(args_path, sizeof args_path, "%s/args", out);
    for (int i = 0; i < 200 && access(args_path, F_OK) != 0; ++i) usleep(50000);
    args = test_read_text(args_path);
    char p[800];
    snprintf(p, sizeof p, "%s/url", out);
    char *url = test_read_text(p);
    const char *tok = strstr(url, "token=");
    cr_assert_not_null(tok, "%s", url);
    char token[2 * STUDIO_TOKEN_BYTES + 1];
    snprintf(token, sizeof token, "%s", tok + 6);
    cr_assert_null(strstr(args, token), "the token is on xdg-open's command line: %s", args);
    cr_assert(strstr(args, "/open.html"), "%s", args);
    snprintf(p, sizeof p, "%s/page", out);
    char *page = test_read_text(p);
    cr_assert(strstr(page, token), "the page leads to the URL with its token");
    snprintf(p, sizeof p, "%s/mode", out);
    char *mode = test_read_text(p);
    cr_assert_str_eq(mode, "600\n");
    snprintf(p, sizeof p, "%s/dirmode", out);
    char *dirmode = test_read_text(p);
    cr_assert_str_eq(dirmode, "700\n");
    snprintf(p, sizeof p, "%s/sigblk", out);
    char *blk = test_read_text(p);
    cr_assert(strstr(blk, "0000000000000000"), "the launcher blocks signals: %s", blk);
    kill(pid, SIGINT);
    int status = 0;
    cr_assert_eq(waitpid(pid, &status, 0), pid);
    cr_assert(WIFEXITED(status) && WEXITSTATUS(status) == 0, "status %d", status);
    char page_path[800];
    snprintf(page_path, sizeof page_path, "%.*s", (int)strcspn(args, "\n"), args);
    cr_assert_neq(access(page_path, F_OK), 0, "the page is removed when the studio stops");
    free(args), free(url), free(page), free(mode), free(dirmode), free(blk);
    test_tmpdir_remove(dir);
}

// Save-back of a file changed on disk since the studio read it asks first (409 conflict), and
// writes only with "overwrite": true; a save then makes the disk's state the known one again.
Test(server, save_back_refuses_a_file_changed_on_disk_unless_told)
{
    char *dir = test_tmpdir();
    char path[512], args[1024];
    snprintf(path, sizeof path, "%s/corner.fold", dir);
    snprintf(args, sizeof args, "cp '" ORI_SOURCE_DIR "/" OPEN_CORNER "' '%s'", path);
    cr_assert_eq(system(args), 0);
    studio *s = open_studio(path);
    json_decref(call_json(s, "POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"flip\", \"edge\": 12}]}", 200));
    // someone else edits the file meanwhile (another size, so even a coarse clock sees it)
    FILE *f = fopen(path, "a");
    cr_assert_not_null(f);
    fputs("\n\n", f);
    fclose(f);
    char *theirs = test_read_text(path);
    json_t *j = call_json(s, "POST", "/api/save", NULL, "{}", 409);
    cr_assert(json_is_true(json_object_get(j, "conflict")));
    cr_assert(strstr(json_string_value(json_object_get(j, "error")), "changed on disk"), "%s",
              json_string_value(json_object_get(j, "error")));
    json_decref(j);
    char *on_disk = test_read_text(path);
    cr_assert_str_eq(on_disk, theirs, "a refused save leaves their change");
    free(on_disk);
    json_decref(call_json(s, "POST", "/api/save", NULL, "{\"overwrite\": true}", 200));
    char *doc = document(s);
    on_disk = test_read_text(path);
    cr_assert_str_eq(on_disk, doc);
    free(on_disk);
    free(doc);
    // the studio's own write is the known state: the next save needs no overwrite
    json_decref(call_json(s, "POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"flip\", \"edge\": 12}]}", 200));
    json_decref(call_json(s, "POST", "/api/save", NULL, "{}", 200));
    studio_response r = call(s, "POST", "/api/save", NULL, "{\"overwrite\": 1}");
    cr_assert_eq(r.status, 400, "overwrite is a boolean");
    studio_response_free(&r);
    free(theirs);
    studio_destroy(s);
    test_tmpdir_remove(dir);
}

// Every edit is journaled beside the file (mode 0600) until it is saved; a session that ends
// without saving leaves the journal, and the next one offers it: recover makes it the document
// (undo goes back to the file), discard removes it. Undo back to the saved state removes it too.
Test(server, unsaved_edits_survive_in_an_autosave_and_are_recovered)
{
    char *dir = test_tmpdir();
    char path[512], journal[600], args[1024];
    snprintf(path, sizeof path, "%s/corner.fold", dir);
    snprintf(journal, sizeof journal, "%s/.corner.fold.orikin-autosave", dir);
    snprintf(args, sizeof args, "cp '" ORI_SOURCE_DIR "/" OPEN_CORNER "' '%s'", path);
    cr_assert_eq(system(args), 0);
    char *orig = test_read_text(path);
    studio *s = open_studio(path);
    json_t *sess = call_json(s, "GET", "/api/session", NULL, NULL, 200);
    cr_assert(json_is_null(json_object_get(sess, "recovery")) && json_is_false(json_object_get(sess, "unsaved")));
    json_decref(sess);
    struct stat st;
    cr_assert_neq(stat(journal, &st), 0, "no journal before an edit");
    json_decref(call_json(s, "POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"flip\", \"edge\": 12}]}", 200));
    cr_assert_eq(stat(journal, &st), 0, "the edit is journaled");
    cr_assert_eq(st.st_mode & 0777, 0600);
    char *edited = document(s), *jtext = test_read_text(journal);
    cr_assert_str_eq(jtext, edited, "the journal holds the document");
    free(jtext);
    char note[1024];
    cr_assert(studio_unsaved(s, note, sizeof note));
    cr_assert_str_eq(note, journal);
    // undo to what the disk holds: nothing unsaved, no journal
    json_decref(call_json(s, "POST", "/api/undo", NULL, "{}", 200));
    cr_assert_neq(stat(journal, &st), 0);
    cr_assert(!studio_unsaved(s, note, sizeof note));
    json_decref(call_json(s, "POST", "/api/redo", NULL, "{}", 200));
    cr_assert_eq(stat(journal, &st), 0);
    studio_destroy(s); // the session ends without saving (a crash leaves the same)

    s = open_studio(path);
    cr_assert(studio_recovery_pending(s, note, sizeof note));
    sess = call_json(s, "GET", "/api/session", NULL, NULL, 200);
    cr_assert_str_eq(json_string_value(json_object_get(json_object_get(sess, "recovery"), "path")), journal);
    json_decref(sess);
    char *shown = document(s);
    cr_assert_str_neq(shown, edited, "the file is shown until the user recovers");
    free(shown);
    json_t *r = call_json(s, "POST", "/api/recover", NULL, "{\"action\": \"recover\"}", 200);
    cr_assert(json_is_true(json_object_get(r, "recovered")));
    json_decref(r);
    shown = document(s);
    cr_assert_str_eq(shown, edited, "recovered");
    free(shown);
    json_decref(call_json(s, "POST", "/api/recover", NULL, "{\"action\": \"recover\"}", 409));
    json_decref(call_json(s, "POST", "/api/save", NULL, "{}", 200));
    cr_assert_neq(stat(journal, &st), 0, "saved: the journal is gone");
    char *on_disk = test_read_text(path);
    cr_assert_str_eq(on_disk, edited);
    free(on_disk);
    // discard
    json_decref(call_json(s, "POST", "/api/edit", NULL, "{\"ops\": [{\"op\": \"flip\", \"edge\": 12}]}", 200));
    studio_destroy(s);
    s = open_studio(path);
    json_decref(call_json(s, "POST", "/api/recover", NULL, "{\"action\": \"keep\"}", 400));
    json_decref(call_json(s, "POST", "/api/recover", NULL, "{\"action\": \"discard\"}", 200));
    cr_assert_neq(stat(journal, &st), 0, "discarded");
    cr_assert(!studio_recovery_pending(s, note, sizeof note));
    studio_destroy(s);
    free(edited);
    free(orig);
    test_tmpdir_remove(dir);
}
