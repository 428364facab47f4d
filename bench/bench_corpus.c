// Layer-order corpus scenario: `orikin_bench corpus [DIR] [timeout=S] [every=K] [match=TEXT]`
// counts every crease pattern of a Flat-Folder examples/ folder (DIR, default
// $ORIKIN_SHARED_PATTERNS/flat-folder-corpus or ../shared/patterns/flat-folder-corpus: grids/ and
// instagram/ with their *_data.csv, unsatisfiable/) with the library's defaults (the tolerance
// from the drawing, no limit: exact counts) and compares with the published results:
//   * a row without limit: the same number of states and the same components;
//   * a row counted with Flat-Folder's limit of 10000 per component: each exact component count,
//     capped at 10000, equals the published one (the exact total is printed);
//   * unsatisfiable/: no state.
// Files whose edges cross or overlap are planarised as the CLI reads them; their faces are
// numbered anew, so their components are compared in any order.
// Each file has a budget of S CPU seconds (default 60, set-up included; the count then stops with
// a lower bound and is reported as timed out; CPU time, as the machine may be shared). every=K takes every K-th file (a subset; default 8 when no DIR is
// given, as in a plain `make bench`), match=TEXT the files whose name contains TEXT. Prints the disagreements, the ten slowest files, and the agreement
// and times (per-file maximum, total; wall and CPU seconds of one thread).
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <orikin/layers.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "bench.h"

// One published row: states, components, whether Flat-Folder used a limit.
typedef struct row {
    bool found, limited;
    char title[128];
    char states[256];
    char comps[4096];
    double seconds;
} row;

// The row of `number` in a Flat-Folder CSV (no quoted fields: the published files have none).
static row csv_row(const char *csv, const char *number)
{
    row r;
    memset(&r, 0, sizeof r);
    FILE *f = fopen(csv, "r");
    if (!f) return r;
    static char line[16384];
    while (fgets(line, sizeof line, f)) {
        if (strncmp(line, number, strlen(number)) != 0 || line[strlen(number)] != ',') continue;
        char *field[32];
        int n = 0;
        for (char *p = line, *q; n < 32; p = q + 1) {
            field[n++] = p;
            q = strchr(p, ',');
            if (!q) {
                p[strcspn(p, "\r\n")] = '\0';
                break;
            }
            *q = '\0';
        }
        // number,author,title,vertices,edges,faces,eps,variables,taco-taco,taco-tortilla,
        // tortilla-tortilla,transitivity,reduced_trans,components,limited,states,
        // component_assignments,setup_sec,solve_sec
        if (n < 19) break;
        r.found = true;
        snprintf(r.title, sizeof r.title, "%s", field[2]);
        r.limited = strcmp(field[14], "no limit") != 0;
        snprintf(r.states, sizeof r.states, "%s", field[15]);
        snprintf(r.comps, sizeof r.comps, "%s", field[16]);
        r.seconds = atof(field[17]) + atof(field[18]);
        break;
    }
    fclose(f);
    return r;
}

typedef struct budget {
    double deadline;
} budget;

static bool until_deadline(double fraction, void *user)
{
    (void)fraction;
    return bench_cpu_now() < ((budget *)user)->deadline;
}

typedef struct result {
    bool ok, timed_out;
    char message[160];
    char states[4096];
    char comps[8192];   // |c0|c1|… exact
    char capped[8192];  // the same with every count capped at 10000 (Flat-Folder's limit)
    double wall, cpu, tolerance;
    bool from_drawing;
    bool planarized; // the file's edges crossed or overlapped: faces retraced, so numbered anew
} result;

static result count_file(const char *path, double timeout_s)
{
    result r;
    memset(&r, 0, sizeof r);
    ori_fold *doc = NULL;
    ori_pattern *p = NULL;
    ori_error err;
    double w0 = bench_now(), c0 = bench_cpu_now();
    ori_build_def bd = ori_default_build_def();
    bd.planarize = true; // as the CLI reads them (two drawings have overlapping creases)
    if (ori_fold_load_file(path, &doc, &err) != ORI_OK || ori_fold_get_pattern(doc, 0, &bd, &p, &err) != ORI_OK) {
        snprintf(r.message, sizeof r.message, "unreadable: %.140s", err.message);
        ori_fold_destroy(doc);
        return r;
    }
    r.planarized = ori_pattern_planarized_from(p) > 0;
    budget b = {c0 + timeout_s};
    ori_layers_def def = ori_default_layers_def();
    def.progress = until_deadline;
    def.progress_user = &b;
    ori_layers *L = NULL;
    ori_status st = ori_layers_create(p, &def, &L, &err);
    if (st == ORI_OK) {
        st = ori_layers_count(L, &err);
        if (st == ORI_ERR_LIMIT) r.timed_out = true, st = ORI_OK;
    }
    if (st != ORI_OK) {
        snprintf(r.message, sizeof r.message, "refused: %.140s", err.message);
    } else {
        ori_layers_info in = ori_layers_get_info(L);
        r.tolerance = in.tolerance;
        r.from_drawing = in.tolerance_from_drawing;
        char *s = ori_layers_state_count(L);
        snprintf(r.states, sizeof r.states, "%s", s);
        ori_buffer_free(s);
        ori_layers_conflict c;
        bool unsat = ori_layers_get_conflict(L, &c);
        if (unsat) snprintf(r.message, sizeof r.message, "%.150s", c.detail);
        size_t n = 0, m = 0;
        if (!unsat || c.constraint == ORI_LAYERS_EXHAUSTED)
            for (int k = 0; k < ori_layers_component_count(L); ++k) {
                char *x = ori_layers_component_states(L, k);
                n += (size_t)snprintf(r.comps + n, sizeof r.comps - n, "|%s", x);
                bool big = strlen(x) > 5 || (strlen(x) == 5 && strcmp(x, "10000") > 0);
                m += (size_t)snprintf(r.capped + m, sizeof r.capped - m, "|%s", big ? "10000" : x);
                ori_buffer_free(x);
                if (n + 64 > sizeof r.comps || m + 64 > sizeof r.capped) break;
            }
        if (n) snprintf(r.comps + n, sizeof r.comps - n, "|");
        if (m) snprintf(r.capped + m, sizeof r.capped - m, "|");
        r.ok = true;
    }
    r.wall = bench_now() - w0;
    r.cpu = bench_cpu_now() - c0;
    ori_layers_destroy(L);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    return r;
}

static int cmp_str(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

// Component strings "|a|b|…|" equal; in any order when unordered (components of equal size are
// ordered by their first face, and a planarised file's faces are numbered anew).
static bool same_components(const char *a, const char *b, bool unordered)
{
    if (!unordered) return strcmp(a, b) == 0;
    char *x[2] = {strdup(a), strdup(b)};
    char **tok[2] = {NULL, NULL};
    int n[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
        tok[k] = malloc(sizeof(char *) * (strlen(x[k]) + 1));
        for (char *t = strtok(x[k], "|"); t; t = strtok(NULL, "|")) tok[k][n[k]++] = t;
        qsort(tok[k], (size_t)n[k], sizeof(char *), cmp_str);
    }
    bool same = n[0] == n[1];
    for (int i = 0; same && i < n[0]; ++i) same = strcmp(tok[0][i], tok[1][i]) == 0;
    for (int k = 0; k < 2; ++k) free(tok[k]), free(x[k]);
    return same;
}

typedef struct slow {
    double wall;
    char line[300];
} slow;

static int run(void)
{
    const char *dir = NULL, *match = NULL;
    double timeout_s = 60.0;
    int every = 1;
    for (int a = 1; a < bench_argc; ++a) {
        const char *x = bench_argv[a];
        struct stat sb;
        if (strncmp(x, "timeout=", 8) == 0) timeout_s = atof(x + 8);
        else if (strncmp(x, "every=", 6) == 0) every = atoi(x + 6) > 0 ? atoi(x + 6) : 1;
        else if (strncmp(x, "match=", 6) == 0) match = x + 6;
        else if (stat(x, &sb) == 0 && S_ISDIR(sb.st_mode)) dir = x;
    }
    char dbuf[4096];
    if (!dir) {
        // `make bench` alone: a sample (every 8th file) of the shared corpus; name the folder to
        // count all of it.
        const char *root = getenv("ORIKIN_SHARED_PATTERNS");
        snprintf(dbuf, sizeof dbuf, "%s/flat-folder-corpus", root ? root : "../shared/patterns");
        dir = dbuf;
        bool given = false;
        for (int a = 1; a < bench_argc; ++a) given |= strncmp(bench_argv[a], "every=", 6) == 0;
        if (!given) {
            every = 8;
            printf("   (no folder given: every 8th file of %s; orikin_bench corpus DIR counts all)\n", dir);
        }
    }
    static const char *sets[] = {"grids", "instagram", "unsatisfiable"};
    int files = 0, agree = 0, agree_limited = 0, limited_rows = 0, differ = 0, refused = 0, timed_out = 0;
    int unsat_files = 0, unsat_zero = 0, auto_loose = 0, seen = 0, nolimit_rows = 0;
    double total_wall = 0, total_cpu = 0, max_wall = 0, ff_total = 0;
    char max_name[160] = "";
    slow top[10];
    int ntop = 0;
    for (int si = 0; si < 3; ++si) {
        char sub[4200], csv[4200];
        snprintf(sub, sizeof sub, "%s/%s", dir, sets[si]);
        snprintf(csv, sizeof csv, "%s/%s_data.csv", dir, sets[si]);
        DIR *d = opendir(sub);
        if (!d) continue;
        char **names = NULL;
        int nn = 0, cap = 0;
        struct dirent *e;
        while ((e = readdir(d))) {
            size_t l = strlen(e->d_name);
            if (l < 6 || strcmp(e->d_name + l - 5, ".fold") != 0) continue;
            if (match && !strstr(e->d_name, match)) continue;
            if (nn == cap) names = realloc(names, sizeof(char *) * (size_t)(cap = cap ? 2 * cap : 512));
            names[nn++] = strdup(e->d_name);
        }
        closedir(d);
        qsort(names, (size_t)nn, sizeof(char *), cmp_str);
        for (int i = 0; i < nn; ++i) {
            bool take = seen++ % every == 0;
            char path[8400], number[4] = {0};
            snprintf(path, sizeof path, "%s/%s", sub, names[i]);
            memcpy(number, names[i], 3);
            if (!take) {
                free(names[i]);
                continue;
            }
            bool unsat_set = si == 2;
            row pub;
            memset(&pub, 0, sizeof pub);
            if (!unsat_set) {
                pub = csv_row(csv, number);
                if (!pub.found) {
                    printf("   %s/%s: no published row\n", sets[si], names[i]);
                    free(names[i]);
                    continue;
                }
            }
            files++;
            if (unsat_set) unsat_files++;
            else if (pub.limited) limited_rows++;
            else nolimit_rows++;
            result r = count_file(path, timeout_s);
            total_wall += r.wall;
            total_cpu += r.cpu;
            ff_total += pub.seconds;
            if (r.wall > max_wall) {
                max_wall = r.wall;
                snprintf(max_name, sizeof max_name, "%s/%.100s", sets[si], names[i]);
            }
            if (r.ok && r.from_drawing && r.tolerance > ORI_TOL_LAYERS_SNAP_REL) auto_loose++;
            const char *verdict;
            if (!r.ok) {
                refused++;
                verdict = "REFUSED";
            } else if (r.timed_out) {
                timed_out++;
                verdict = "TIMED OUT";
            } else if (unsat_set) {
                bool zero = strcmp(r.states, "0") == 0;
                unsat_zero += zero;
                verdict = zero ? NULL : "DIFFERS";
                if (!zero) differ++;
            } else if (pub.limited) {
                bool ok = same_components(r.capped, pub.comps, r.planarized);
                agree_limited += ok;
                if (!ok) differ++;
                verdict = ok ? NULL : "DIFFERS";
            } else {
                bool ok = strcmp(r.states, pub.states) == 0 && same_components(r.comps, pub.comps, r.planarized);
                agree += ok;
                if (!ok) differ++;
                verdict = ok ? NULL : "DIFFERS";
            }
            if (verdict)
                printf("   %-9s %s/%.60s: %.60s %.80s (published %.60s %.80s)%s%.160s\n", verdict, sets[si], names[i],
                       r.states, r.comps, unsat_set ? "0" : pub.states, unsat_set ? "" : pub.comps,
                       r.message[0] ? ": " : "", r.message);
            if (ntop < 10 || r.wall > top[ntop - 1].wall) {
                int at = ntop < 10 ? ntop++ : 9;
                top[at].wall = r.wall;
                snprintf(top[at].line, sizeof top[at].line, "%8.2f s wall %8.2f s CPU  %s/%.50s  %.40s%s (FF %.1f s)",
                         r.wall, r.cpu, sets[si], names[i], r.states,
                         r.timed_out ? " (a lower bound: timed out)" : pub.limited ? " exact, FF limited" : "",
                         pub.seconds);
                for (int k = at; k > 0 && top[k].wall > top[k - 1].wall; --k) {
                    slow t = top[k];
                    top[k] = top[k - 1];
                    top[k - 1] = t;
                }
            }
            fflush(stdout);
            free(names[i]);
        }
        free(names);
    }
    if (files == 0) {
        printf("   %s: no Flat-Folder corpus there (grids/, instagram/, unsatisfiable/): skipped\n", dir);
        return 0;
    }
    printf("   slowest:\n");
    for (int k = 0; k < ntop; ++k) printf("   %s\n", top[k].line);
    printf("   %s: %d files (every %d%s%s), per-file budget %.0f s CPU\n", dir, files, every, match ? ", match " : "",
           match ? match : "", timeout_s);
    printf("   published without limit: %d of %d agree (states and components)\n", agree, nolimit_rows);
    printf("   published with the limit 10000: %d of %d agree (exact counts capped at 10000 per component)\n",
           agree_limited, limited_rows);
    printf("   unsatisfiable: %d of %d without a state\n", unsat_zero, unsat_files);
    printf("   differ %d, refused %d, timed out %d; tolerance from the drawing above 1e-8 on %d\n", differ, refused,
           timed_out, auto_loose);
    printf("   time: total %.1f s wall, %.1f s CPU; slowest file %.2f s (%s); Flat-Folder published %.0f s\n",
           total_wall, total_cpu, max_wall, max_name, ff_total);
    return 0;
}

const bench_scenario bench_corpus = {
    "corpus",
    "Flat-Folder's examples folder (argument DIR): every count against the published ones, times",
    run,
};
