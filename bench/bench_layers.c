// Layer-order scenario (global flat-foldability). Part 1: every Flat-Folder example in
// ../shared/patterns/flat-folder (or $ORIKIN_SHARED_PATTERNS/flat-folder): set-up (fold, overlap
// structure, variables, constraints, propagation, components) and solve (exact count) next to
// Flat-Folder's published seconds and counts from its CSVs, and Rabbit Ear's layer solver on the
// same files in the same run (bench/peers/rabbit_ear_layers.mjs, when node and
// node_modules/rabbit-ear exist). Part 2: generated patterns of the size of Flat-Folder's slowest
// published cases (Chilean Stag Beetle: 402k variables, 31M transitivity constraints; Spiny
// Lobster: 1.0M variables, 134M), and hard single components. Times are CPU seconds of this
// process (steady on a shared machine) and wall seconds; memory is the library's peak.
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <jansson.h>
#include <math.h>
#include <orikin/generate.h>
#include <orikin/layers.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "bench.h"

typedef struct timing {
    double setup_cpu, solve_cpu, setup_wall, solve_wall;
    int64_t peak;
    char states[96];
    char comps[4096];
    ori_layers_info info;
    bool ok;
} timing;

// Set-up and solve, repeated (best of) until about 0.2 s of CPU time has run.
static timing measure_limited(const ori_pattern *p, int threads, uint64_t limit, double budget)
{
    timing t;
    memset(&t, 0, sizeof t);
    t.setup_cpu = t.solve_cpu = t.setup_wall = t.solve_wall = 1e300;
    double spent = 0.0;
    for (int rep = 0; rep < 1000 && (rep == 0 || spent < budget); ++rep) {
        ori_layers_def def = ori_default_layers_def();
        def.threads = threads;
        def.limit = limit;
        ori_layers *L = NULL;
        ori_error err;
        int64_t base = ori_alloc_live_bytes();
        ori_alloc_reset_peak();
        double c0 = bench_cpu_now(), w0 = bench_now();
        if (ori_layers_create(p, &def, &L, &err) != ORI_OK) {
            snprintf(t.states, sizeof t.states, "error: %.80s", err.message);
            return t;
        }
        double c1 = bench_cpu_now(), w1 = bench_now();
        if (ori_layers_count(L, &err) != ORI_OK) {
            ori_layers_destroy(L);
            snprintf(t.states, sizeof t.states, "error: %.80s", err.message);
            return t;
        }
        double c2 = bench_cpu_now(), w2 = bench_now();
        t.setup_cpu = fmin(t.setup_cpu, c1 - c0);
        t.solve_cpu = fmin(t.solve_cpu, c2 - c1);
        t.setup_wall = fmin(t.setup_wall, w1 - w0);
        t.solve_wall = fmin(t.solve_wall, w2 - w1);
        spent += c2 - c0;
        if (rep == 0) {
            t.peak = ori_alloc_peak_bytes() - base;
            t.info = ori_layers_get_info(L);
            char *s = ori_layers_state_count(L);
            snprintf(t.states, sizeof t.states, "%.90s", s);
            ori_buffer_free(s);
            size_t n = 0;
            t.comps[0] = '\0';
            int nc = ori_layers_component_count(L);
            for (int c = 0; c < nc && n + 40 < sizeof t.comps && t.info.satisfiable; ++c) {
                char *x = ori_layers_component_states(L, c);
                n += (size_t)snprintf(t.comps + n, sizeof t.comps - n, "|%.20s", x);
                ori_buffer_free(x);
            }
            if (n && n + 2 < sizeof t.comps) snprintf(t.comps + n, sizeof t.comps - n, "|");
            t.ok = true;
        }
        ori_layers_destroy(L);
    }
    return t;
}

static timing measure(const ori_pattern *p, int threads)
{
    return measure_limited(p, threads, ORI_LAYERS_NO_LIMIT, 0.2);
}

// --- Flat-Folder's published rows -------------------------------------------------------------

typedef struct ff_row {
    bool found;
    uint64_t limit; // Flat-Folder's per-component limit for this row, or ORI_LAYERS_NO_LIMIT
    char title[64];
    double setup, solve;
    char states[96];
    char comps[4096];
} ff_row;

static ff_row ff_row_of(const char *csv, const char *number);

static ff_row ff_lookup(const char *dir, const char *file)
{
    ff_row r;
    memset(&r, 0, sizeof r);
    const char *set = strncmp(file, "grids_", 6) == 0 ? "grids" : strncmp(file, "instagram_", 10) == 0 ? "instagram" : NULL;
    if (!set) return r;
    char number[4] = {0};
    memcpy(number, file + strlen(set) + 1, 3);
    char path[4200];
    snprintf(path, sizeof path, "%s/%s_data.csv", dir, set);
    return ff_row_of(path, number);
}

static ff_row ff_row_of(const char *path, const char *number)
{
    ff_row r;
    memset(&r, 0, sizeof r);
    FILE *f = fopen(path, "r");
    if (!f) return r;
    char line[16384];
    while (fgets(line, sizeof line, f)) {
        char *field[64];
        int n = 0;
        for (char *p = line; n < 64;) {
            field[n++] = p;
            char *c = strchr(p, ',');
            if (!c) break;
            *c = '\0';
            p = c + 1;
        }
        if (n < 19 || strcmp(field[0], number) != 0) continue;
        int o = n - 19;
        r.found = true;
        snprintf(r.title, sizeof r.title, "%.60s", field[2]);
        r.limit = strcmp(field[14 + o], "no limit") == 0 ? ORI_LAYERS_NO_LIMIT : (uint64_t)atoll(field[14 + o]);
        snprintf(r.states, sizeof r.states, "%.90s", field[15 + o]);
        snprintf(r.comps, sizeof r.comps, "%.4000s", field[16 + o]);
        r.setup = atof(field[17 + o]);
        r.solve = atof(field[18 + o]);
        break;
    }
    fclose(f);
    return r;
}

// --- Rabbit Ear, in the same run -------------------------------------------------------------

typedef struct peer {
    char file[512];
    double setup_ms, solve_ms;
    char states[96];
    bool ok;
} peer;

static int run_rabbit_ear(char **files, int n, peer *out)
{
    if (access("node_modules/rabbit-ear/package.json", R_OK) != 0 || access("bench/peers/rabbit_ear_layers.mjs", R_OK) != 0)
        return -1;
    if (system("node --version >/dev/null 2>&1") != 0) return -1;
    size_t len = 64;
    for (int i = 0; i < n; ++i) len += strlen(files[i]) + 3;
    char *cmd = malloc(len);
    size_t k = (size_t)snprintf(cmd, len, "node bench/peers/rabbit_ear_layers.mjs");
    for (int i = 0; i < n; ++i) k += (size_t)snprintf(cmd + k, len - k, " '%s'", files[i]);
    snprintf(cmd + k, len - k, " 2>/dev/null");
    FILE *pipe = popen(cmd, "r");
    free(cmd);
    if (!pipe) return -1;
    char line[4096];
    int m = 0;
    while (m < n && fgets(line, sizeof line, pipe)) {
        json_error_t jerr;
        json_t *o = json_loads(line, 0, &jerr);
        if (!o) continue;
        memset(&out[m], 0, sizeof out[m]);
        snprintf(out[m].file, sizeof out[m].file, "%s", json_string_value(json_object_get(o, "file")));
        if (!json_object_get(o, "error")) {
            out[m].ok = true;
            out[m].setup_ms = json_number_value(json_object_get(o, "setup_ms"));
            out[m].solve_ms = json_number_value(json_object_get(o, "solve_ms"));
            snprintf(out[m].states, sizeof out[m].states, "%.90s", json_string_value(json_object_get(o, "states")));
        }
        json_decref(o);
        m++;
    }
    pclose(pipe);
    return m;
}

static int cmp_str(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

static int flat_folder_examples(void)
{
    const char *root = getenv("ORIKIN_SHARED_PATTERNS");
    char dir[4096];
    snprintf(dir, sizeof dir, "%s/flat-folder", root ? root : "../shared/patterns");
    DIR *d = opendir(dir);
    if (!d) {
        printf("   %s absent: Flat-Folder examples skipped\n", dir);
        return 0;
    }
    char *files[256];
    int nf = 0;
    struct dirent *e;
    while ((e = readdir(d)) && nf < 256) {
        size_t l = strlen(e->d_name);
        if (l > 5 && strcmp(e->d_name + l - 5, ".fold") == 0) {
            files[nf] = malloc(strlen(dir) + l + 2);
            sprintf(files[nf], "%s/%s", dir, e->d_name);
            nf++;
        }
    }
    closedir(d);
    qsort(files, (size_t)nf, sizeof(char *), cmp_str);
    peer *re = calloc((size_t)(nf ? nf : 1), sizeof(peer));
    int nre = run_rabbit_ear(files, nf, re);
    if (nre < 0) printf("   (node or node_modules/rabbit-ear absent: Rabbit Ear column skipped)\n");
    printf("   times in ms: orikin CPU set-up + solve (wall in brackets); Flat-Folder's published set-up +\n"
           "   solve (its machine, browser JavaScript); Rabbit Ear 0.9.32 in this run (node, wall)\n");
    printf("   %-44s %5s %6s %8s | %9s %9s %9s | %9s %9s %7s | %9s %6s\n", "pattern", "faces", "vars", "states",
           "setup", "solve", "(wall)", "FF setup", "FF solve", "speedup", "RabbitEar", "same");
    int rc = 0, same = 0, compared = 0;
    double worst = 1e300;
    for (int i = 0; i < nf; ++i) {
        const char *name = strrchr(files[i], '/') + 1;
        ori_fold *doc = NULL;
        ori_pattern *p = NULL;
        ori_error err;
        if (ori_fold_load_file(files[i], &doc, &err) != ORI_OK || ori_fold_get_pattern(doc, 0, NULL, &p, &err) != ORI_OK) {
            printf("   %-44s load failed: %s\n", name, err.message);
            ori_fold_destroy(doc);
            rc = 1;
            continue;
        }
        timing t = measure(p, 1);
        ff_row r = ff_lookup(dir, name);
        char ffs[24] = "-", ffv[24] = "-", sp[24] = "-";
        if (r.found) {
            snprintf(ffs, sizeof ffs, "%.2f", 1e3 * r.setup);
            snprintf(ffv, sizeof ffv, "%.2f", 1e3 * r.solve);
            double ours = t.setup_cpu + t.solve_cpu, theirs = r.setup + r.solve;
            snprintf(sp, sizeof sp, "%.0fx", theirs / fmax(ours, 1e-9));
            worst = fmin(worst, theirs / fmax(ours, 1e-9));
            compared++;
            bool match = strcmp(t.states, r.states) == 0 && strcmp(t.comps, r.comps) == 0;
            same += match;
            if (!match) {
                printf("   %s: states %s %s, Flat-Folder %s %s  MISMATCH\n", name, t.states, t.comps, r.states, r.comps);
                rc = 1;
            }
        }
        char rem[24] = "-", res[8] = "-";
        for (int k = 0; k < nre; ++k)
            if (strcmp(re[k].file, files[i]) == 0 && re[k].ok) {
                snprintf(rem, sizeof rem, "%.2f", re[k].setup_ms + re[k].solve_ms);
                snprintf(res, sizeof res, "%s", strcmp(re[k].states, t.states) == 0 ? "yes" : "NO");
            }
        char shortname[45];
        snprintf(shortname, sizeof shortname, "%.44s", name);
        printf("   %-44s %5d %6d %8.8s | %9.3f %9.3f %9.3f | %9s %9s %7s | %9s %6s\n", shortname, t.info.faces,
               t.info.variables, t.states, 1e3 * t.setup_cpu, 1e3 * t.solve_cpu, 1e3 * (t.setup_wall + t.solve_wall),
               ffs, ffv, sp, rem, res);
        fflush(stdout);
        ori_pattern_destroy(p);
        ori_fold_destroy(doc);
    }
    if (compared)
        printf("   %d/%d identical to Flat-Folder's published states and components; slowest speed-up %.0fx\n", same,
               compared, worst);
    for (int i = 0; i < nf; ++i) free(files[i]);
    free(re);
    return rc;
}

// --- generated patterns ---------------------------------------------------------------------

// A strip of n unit stamps, creases at x = 1 … n−1: alternately V and M (an accordion, one
// state) or all U (stamp folding: A000136 states).
static ori_pattern *strip(int n, bool unassigned)
{
    ori_pattern_def pd = ori_default_pattern_def();
    ori_pattern *p = ori_pattern_create(&pd);
    for (int i = 0; i <= n; ++i) ori_pattern_add_vertex(p, ori_v3_make(i, 0, 0));
    for (int i = 0; i <= n; ++i) ori_pattern_add_vertex(p, ori_v3_make(i, 1, 0));
    for (int i = 0; i < n; ++i) {
        ori_pattern_add_edge(p, i, i + 1, ORI_ASSIGN_BOUNDARY, 0);
        ori_pattern_add_edge(p, n + 1 + i, n + 2 + i, ORI_ASSIGN_BOUNDARY, 0);
    }
    for (int i = 0; i <= n; ++i) {
        ori_assignment a = (i == 0 || i == n) ? ORI_ASSIGN_BOUNDARY
                           : unassigned       ? ORI_ASSIGN_UNASSIGNED
                           : (i % 2)          ? ORI_ASSIGN_VALLEY
                                              : ORI_ASSIGN_MOUNTAIN;
        ori_pattern_add_edge(p, i, n + 1 + i, a, 0);
    }
    return p;
}

// An n × n map folded by a vertical accordion, then a horizontal one through all layers: every
// cell ends in one stack. Vertical creases alternate V, M by column; a horizontal crease is V
// where (row index even) XOR (column odd).
static ori_pattern *map_fold(int n)
{
    ori_pattern_def pd = ori_default_pattern_def();
    ori_pattern *p = ori_pattern_create(&pd);
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) ori_pattern_add_vertex(p, ori_v3_make(i, j, 0));
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            int v = j * (n + 1) + i;
            if (i < n) {
                ori_assignment a = (j == 0 || j == n)            ? ORI_ASSIGN_BOUNDARY
                                   : ((j % 2 == 0) != (i % 2 == 1)) ? ORI_ASSIGN_VALLEY
                                                                    : ORI_ASSIGN_MOUNTAIN;
                ori_pattern_add_edge(p, v, v + 1, a, 0);
            }
            if (j < n) {
                ori_assignment a = (i == 0 || i == n) ? ORI_ASSIGN_BOUNDARY
                                   : (i % 2)          ? ORI_ASSIGN_VALLEY
                                                      : ORI_ASSIGN_MOUNTAIN;
                ori_pattern_add_edge(p, v, v + n + 1, a, 0);
            }
        }
    return p;
}

static ori_pattern *yoshimura(int n)
{
    ori_generate_def g = ori_default_generate_def(ORI_TESS_YOSHIMURA);
    g.rows = n;
    g.cols = n;
    ori_pattern *p = NULL;
    ori_error err;
    return ori_generate(&g, &p, NULL, &err) == ORI_OK ? p : NULL;
}

static int generated_one(const char *label, ori_pattern *p, const char *expect)
{
    if (!p) return 1;
    ori_error err;
    if (!ori_pattern_is_built(p) && ori_pattern_build(p, NULL, &err) != ORI_OK) {
        printf("   %s: build failed: %s\n", label, err.message);
        ori_pattern_destroy(p);
        return 1;
    }
    timing t = measure(p, 1);
    bool ok = t.ok && (!expect || strcmp(t.states, expect) == 0);
    double cons = (double)(t.info.taco_taco + t.info.taco_tortilla + t.info.tortilla_tortilla + t.info.transitivity);
    printf("   %-30s %6d faces %8d vars %10.3gM trans | set-up %7.2f s solve %7.2f s (wall %6.1f s) | %6.0f MB "
           "(%4.1f B/(var+constraint)) | states %s%s\n",
           label, t.info.faces, t.info.variables, t.info.transitivity / 1e6, t.setup_cpu, t.solve_cpu,
           t.setup_wall + t.solve_wall, t.peak / 1e6, t.peak / fmax(1.0, t.info.variables + cons), t.states,
           ok ? "" : "  UNEXPECTED");
    fflush(stdout);
    ori_pattern_destroy(p);
    return ok ? 0 : 1;
}

static int generated(void)
{
    int rc = 0;
    printf("   generated (CPU seconds, single thread):\n");
    // Set-up at the scale of the slowest published cases: every face over one cell.
    rc |= generated_one("accordion strip, 400 stamps", strip(400, false), "1");
    rc |= generated_one("accordion strip, 800 stamps", strip(800, false), "1");
    rc |= generated_one("map fold 20 x 20", map_fold(20), "1");
    rc |= generated_one("map fold 28 x 28", map_fold(28), "1");
    // Hard single components (no decomposition helps much): stamp folding (OEIS A000136) and a
    // Yoshimura tessellation whose flaps may stack in millions of ways.
    rc |= generated_one("stamp folding, 11 U creases", strip(12, true), "146376");
    rc |= generated_one("Yoshimura 7 x 7", yoshimura(7), "11362256");
    return rc;
}


// --- Flat-Folder's whole example set (optional) ----------------------------------------------

typedef struct slow_case {
    double ff, ours;
    char line[240];
} slow_case;

// With ORIKIN_FLAT_FOLDER_EXAMPLES pointing at a clone's examples/ folder (grids/, instagram/ and
// the two CSVs), every published example: the same limit as the published row, identical states
// and components required; the slowest published ones are listed, and the two slowest are also
// counted exactly (no limit).
static int flat_folder_corpus(void)
{
    const char *dir = getenv("ORIKIN_FLAT_FOLDER_EXAMPLES");
    if (!dir) {
        printf("   (set ORIKIN_FLAT_FOLDER_EXAMPLES to a Flat-Folder examples/ folder to run all 741 published "
               "examples)\n");
        return 0;
    }
    static const char *sets[] = {"grids", "instagram"};
    int matched = 0, local = 0, refused = 0, mismatched = 0, total = 0;
    double worst = 1e300, sum_ff = 0, sum_ours = 0;
    char worst_name[96] = "";
    slow_case slow[8];
    int nslow = 0;
    for (int si = 0; si < 2; ++si) {
        char sub[4200], csv[4200];
        snprintf(sub, sizeof sub, "%s/%s", dir, sets[si]);
        snprintf(csv, sizeof csv, "%s/%s_data.csv", dir, sets[si]);
        DIR *d = opendir(sub);
        if (!d) continue;
        char *files[1024];
        int nf = 0;
        struct dirent *e;
        while ((e = readdir(d)) && nf < 1024) {
            size_t l = strlen(e->d_name);
            if (l > 8 && strcmp(e->d_name + l - 5, ".fold") == 0) files[nf++] = strdup(e->d_name);
        }
        closedir(d);
        qsort(files, (size_t)nf, sizeof(char *), cmp_str);
        for (int i = 0; i < nf; ++i) {
            char number[4] = {0}, path[8400];
            memcpy(number, files[i], 3);
            snprintf(path, sizeof path, "%s/%s", sub, files[i]);
            ff_row r = ff_row_of(csv, number);
            free(files[i]);
            if (!r.found) continue;
            total++;
            ori_fold *doc = NULL;
            ori_pattern *p = NULL;
            ori_error err;
            if (ori_fold_load_file(path, &doc, &err) != ORI_OK || ori_fold_get_pattern(doc, 0, NULL, &p, &err) != ORI_OK) {
                refused++;
                ori_fold_destroy(doc);
                continue;
            }
            timing t = measure_limited(p, 1, r.limit, 0.05);
            ori_pattern_destroy(p);
            ori_fold_destroy(doc);
            if (!t.ok) {
                refused++;
                continue;
            }
            if (!t.info.satisfiable && t.info.variables == 0 && strcmp(r.states, "0") != 0) {
                local++; // not locally flat-foldable at ORI_TOL_KAWASAKI_RAD (a rounded drawing)
                continue;
            }
            if (strcmp(t.states, r.states) != 0 || strcmp(t.comps, r.comps) != 0) {
                mismatched++;
                printf("   MISMATCH %s %s: %s %s, published %s %s\n", sets[si], number, t.states, t.comps, r.states, r.comps);
                continue;
            }
            matched++;
            double ours = t.setup_cpu + t.solve_cpu, ff = r.setup + r.solve;
            if (ff < 10.0 * ours)
                printf("   under 10x: %s %s %.40s: %.4f + %.4f s against %.4f + %.4f s published (%s)\n", sets[si], number,
                       r.title, t.setup_cpu, t.solve_cpu, r.setup, r.solve, t.states);
            sum_ff += ff;
            sum_ours += ours;
            if (ff / fmax(ours, 1e-9) < worst) {
                worst = ff / fmax(ours, 1e-9);
                snprintf(worst_name, sizeof worst_name, "%s %s %.60s", sets[si], number, r.title);
            }
            // Keep the eight slowest published cases, slowest first.
            if (nslow == 8 && slow[7].ff >= ff) continue;
            int at = nslow < 8 ? nslow++ : 7;
            slow[at].ff = ff;
            slow[at].ours = ours;
            snprintf(slow[at].line, sizeof slow[at].line,
                     "%-28.28s %8d vars | FF %8.1f + %8.1f s | orikin %6.2f + %6.2f s (%5.0fx) | %s%s", r.title,
                     t.info.variables, r.setup, r.solve, t.setup_cpu, t.solve_cpu, ff / fmax(ours, 1e-9),
                     t.info.limited ? "limited " : "", t.states);
            for (int k = at; k > 0 && slow[k].ff > slow[k - 1].ff; --k) {
                slow_case tmp = slow[k];
                slow[k] = slow[k - 1];
                slow[k - 1] = tmp;
            }
        }
    }
    printf("   Flat-Folder's published examples: %d; identical states and components %d; refused as not locally\n"
           "   flat-foldable at 1e-8 rad (rounded drawings; --tolerance) %d; unreadable %d; mismatched %d\n",
           total, matched, local, refused, mismatched);
    printf("   total CPU %.1f s against %.1f s published; slowest speed-up %.0fx (%s)\n", sum_ours, sum_ff, worst,
           worst_name);
    printf("   the slowest published cases (with the published limit of 10000 states per component):\n");
    for (int k = 0; k < nslow; ++k) printf("     %s\n", slow[k].line);
    fflush(stdout);
    // The two slowest, counted exactly.
    static const char *exact[] = {"149", "300"};
    for (int k = 0; k < 2; ++k) {
        char sub[4200], csv[4200];
        snprintf(sub, sizeof sub, "%s/instagram", dir);
        snprintf(csv, sizeof csv, "%s/instagram_data.csv", dir);
        DIR *d = opendir(sub);
        if (!d) break;
        struct dirent *e;
        char path[8400] = "";
        while ((e = readdir(d)))
            if (strncmp(e->d_name, exact[k], 3) == 0) snprintf(path, sizeof path, "%s/%s", sub, e->d_name);
        closedir(d);
        ff_row r = ff_row_of(csv, exact[k]);
        ori_fold *doc = NULL;
        ori_pattern *p = NULL;
        ori_error err;
        if (!path[0] || ori_fold_load_file(path, &doc, &err) != ORI_OK || ori_fold_get_pattern(doc, 0, NULL, &p, &err) != ORI_OK) {
            ori_fold_destroy(doc);
            continue;
        }
        timing t = measure_limited(p, 1, ORI_LAYERS_NO_LIMIT, 0.0);
        printf("   %s exactly: %s states %s in %.1f + %.1f s CPU, %.0f MB (published: at least %s after %.0f + %.0f s)\n",
               r.title, t.states, t.comps, t.setup_cpu, t.solve_cpu, t.peak / 1e6, r.states, r.setup, r.solve);
        fflush(stdout);
        ori_pattern_destroy(p);
        ori_fold_destroy(doc);
    }
    return mismatched ? 1 : 0;
}

static int run(void)
{
    int rc = flat_folder_examples();
    rc |= flat_folder_corpus();
    rc |= generated();
    return rc;
}

const bench_scenario bench_layers = {"layers",
                                     "global layer orders: Flat-Folder examples vs published times and Rabbit Ear, "
                                     "generated large and hard patterns",
                                     run};
