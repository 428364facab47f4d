// orikin mv-count: Hull's number of valid mountain-valley assignments of a single vertex,
// and their list.
#include <orikin/flat.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

#define DEFAULT_MAX 100000

static json_t *count_json(ori_mv_count c)
{
    if (c.overflow || c.count > (uint64_t)INT64_MAX) return json_null();
    return json_integer((json_int_t)c.count);
}

static void print_count_line(ori_mv_count c)
{
    if (c.overflow) printf(">%llu\n", (unsigned long long)UINT64_MAX);
    else printf("%llu\n", (unsigned long long)c.count);
}

static int run(int argc, char **argv)
{
    bool list = false, json = false;
    const char *assign = NULL;
    int max = DEFAULT_MAX;
    double *deg = malloc(sizeof(double) * (size_t)(argc > 1 ? argc : 1));
    int n = 0;
    int rc = CLI_EXIT_OK;
    cli_seen seen = {0};
    for (int i = 1; i < argc && rc == CLI_EXIT_OK; ++i) {
        if (strcmp(argv[i], "--list") == 0) list = true;
        else if (strcmp(argv[i], "--json") == 0) json = true;
        else if (strcmp(argv[i], "--assign") == 0) {
            assign = cli_option_once("mv-count", argc, argv, &i, &seen);
            if (!assign) rc = CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--max") == 0) {
            const char *v = cli_option_once("mv-count", argc, argv, &i, &seen);
            if (!v) rc = CLI_EXIT_USAGE;
            else if (!cli_parse_int(v, &max) || max < 0) rc = cli_usage("mv-count", "--max needs a count ≥ 0");
        } else if (argv[i][0] == '-' && argv[i][1] == '-') {
            rc = cli_usage("mv-count", "unknown option %s", argv[i]);
        } else if (!cli_parse_double(argv[i], &deg[n])) {
            rc = cli_usage("mv-count", "'%s' is not a number (sector angles are degrees)", argv[i]);
        } else {
            n++;
        }
    }
    if (rc != CLI_EXIT_OK) {
        free(deg);
        return rc;
    }
    if (n == 0) {
        free(deg);
        return cli_usage("mv-count", "missing sector angles");
    }
    if (assign && (int)strlen(assign) != n) {
        free(deg);
        return cli_usage("mv-count", "--assign needs one letter per crease (%d), got %zu", n, strlen(assign));
    }
    ori_assignment *letters = NULL;
    if (assign) {
        letters = malloc(sizeof(ori_assignment) * (size_t)n);
        for (int i = 0; i < n; ++i) {
            ori_assignment a;
            if (!ori_assignment_from_char(assign[i], &a) ||
                (a != ORI_ASSIGN_MOUNTAIN && a != ORI_ASSIGN_VALLEY && a != ORI_ASSIGN_UNASSIGNED)) {
                free(deg);
                free(letters);
                return cli_usage("mv-count", "--assign letters must be M, V or U (got '%c')", assign[i]);
            }
            letters[i] = a;
        }
    }
    // Validate the sectors: each > 0, an even number, summing to 360.
    double *rad = malloc(sizeof(double) * (size_t)n);
    double sum = 0.0;
    for (int i = 0; i < n && rc == CLI_EXIT_OK; ++i) {
        if (!(deg[i] > 0.0)) {
            fprintf(stderr, "orikin mv-count: sector %d: %g degrees; every sector angle must be > 0\n", i + 1, deg[i]);
            rc = CLI_EXIT_INPUT;
        }
        rad[i] = ori_deg_to_rad(deg[i]);
        sum += rad[i];
    }
    if (rc == CLI_EXIT_OK && n % 2 != 0) {
        fprintf(stderr, "orikin mv-count: %d sector angles: a flat vertex has an even number of creases\n", n);
        rc = CLI_EXIT_INPUT;
    }
    if (rc == CLI_EXIT_OK && !(fabs(sum - 2.0 * ORI_PI) <= ORI_TOL_ANGLE_SUM_RAD)) {
        fprintf(stderr, "orikin mv-count: sector angles sum to %.10g degrees, not 360\n", ori_rad_to_deg(sum));
        rc = CLI_EXIT_INPUT;
    }
    if (rc != CLI_EXIT_OK) {
        free(deg);
        free(rad);
        free(letters);
        return rc;
    }

    ori_mv_count c = ori_flat_count_assignments(rad, n);
    bool kawasaki = ori_flat_kawasaki(rad, n);
    ori_mv_count completions = c;
    if (letters) completions = ori_flat_count_completions(rad, letters, n);
    bool want_rows = list || json;
    char *rows = NULL;
    int written = 0;
    bool truncated = false;
    if (want_rows && max > 0) {
        uint64_t total = letters ? completions.count : c.count;
        size_t cap_rows = (completions.overflow || c.overflow || total > (uint64_t)max) ? (size_t)max : (size_t)total;
        if (cap_rows > 0) {
            rows = malloc(cap_rows * ((size_t)n + 1));
            if (letters) written = ori_flat_enumerate_completions(rad, letters, n, rows, (int)cap_rows, &truncated);
            else written = ori_flat_enumerate(rad, n, rows, (int)cap_rows, &truncated);
        }
    } else if (want_rows) {
        truncated = (letters ? completions.count : c.count) > 0;
    }
    ori_mv_count shown = letters ? completions : c;

    if (json) {
        json_t *out = json_object();
        json_t *sd = json_array();
        for (int i = 0; i < n; ++i) json_array_append_new(sd, json_real(deg[i]));
        json_object_set_new(out, "sectors_deg", sd);
        json_object_set_new(out, "kawasaki", json_boolean(kawasaki));
        json_object_set_new(out, "count", count_json(c));
        if (c.overflow) json_object_set_new(out, "count_overflow", json_true());
        if (letters) {
            json_object_set_new(out, "assign", json_string(assign));
            json_object_set_new(out, "completions", count_json(completions));
        }
        json_t *arr = json_array();
        for (int i = 0; i < written; ++i) json_array_append_new(arr, json_string(rows + (size_t)i * ((size_t)n + 1)));
        json_object_set_new(out, "assignments", arr);
        json_object_set_new(out, "truncated", json_boolean(truncated));
        cli_print_json(out);
    } else {
        print_count_line(shown);
        if (list)
            for (int i = 0; i < written; ++i) printf("%s\n", rows + (size_t)i * ((size_t)n + 1));
    }
    if (!kawasaki)
        fprintf(stderr, "orikin mv-count: Kawasaki fails (alternating sum %.6g degrees): no assignment folds flat\n",
                ori_rad_to_deg(ori_flat_kawasaki_sum(rad, n)));
    if (list && truncated)
        fprintf(stderr, "orikin mv-count: listed the first %d assignments only (--max %d)\n", written, max);
    free(rows);
    free(deg);
    free(rad);
    free(letters);
    return (shown.count > 0 || shown.overflow) ? CLI_EXIT_OK : CLI_EXIT_NEGATIVE;
}

const cli_command cli_cmd_mv_count = {
    "mv-count",
    "number (and list) of valid mountain-valley assignments of one vertex",
    "usage: orikin mv-count A1 A2 ... A2n [--list] [--json] [--assign LETTERS] [--max N]\n"
    "\n"
    "Count the mountain-valley assignments that fold a single vertex with sector angles\n"
    "A1 ... A2n (degrees, counter-clockwise, each > 0, summing to 360) flat: C(A1 ... A2n) by\n"
    "Hull's recursion. Crease i lies between sector i-1 and sector i (crease 1 between the last\n"
    "sector and A1). Prints C; with --list also each valid assignment as a string of M and V,\n"
    "crease 1 first, in lexicographic order. Exit 0 when C > 0, 1 when no assignment folds flat\n"
    "(Kawasaki fails), 2 for arguments that are not numbers, 3 for invalid angles.\n"
    "\n"
    "options:\n"
    "  --list            print the valid assignments, one per line\n"
    "  --json            print {\"sectors_deg\", \"kawasaki\", \"count\", \"assignments\",\n"
    "                    \"truncated\"} (with --assign also \"assign\", \"completions\")\n"
    "  --assign LETTERS  a partial assignment (M, V or U per crease): count and list the ways\n"
    "                    to replace its U letters that fold flat (without U: 1 valid, 0 not)\n"
    "  --max N           list at most N assignments (default 100000)\n"
    "\n"
    "example: orikin mv-count 100 70 50 40 30 70 --list\n",
    run,
    NULL,
};
