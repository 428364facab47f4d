// orikin axiom: the folds a Huzita–Hatori axiom gives for points and lines (a pure query).
#include <string.h>

#include "axiom_args.h"
#include "report.h"

static int run(int argc, char **argv)
{
    ori_axiom_input in;
    memset(&in, 0, sizeof in);
    in.axiom = 0;
    int given = 0;
    bool json = false, have_n = false;
    for (int i = 1; i < argc; ++i) {
        int r = axiom_parse_option("axiom", argc, argv, &i, &in, &given);
        if (r < 0) return -r;
        if (r == 1) continue;
        if (strcmp(argv[i], "--json") == 0) json = true;
        else if (argv[i][0] == '-' && argv[i][1] != '\0') return cli_usage("axiom", "unknown option %s", argv[i]);
        else if (!have_n) {
            if (!cli_parse_int(argv[i], &in.axiom)) return cli_usage("axiom", "the axiom is a number from 1 to 7");
            have_n = true;
        } else return cli_usage("axiom", "one axiom number only");
    }
    if (!have_n) return cli_usage("axiom", "missing the axiom number N (1 to 7)");
    int rc = axiom_check_inputs("axiom", &in, given);
    if (rc != CLI_EXIT_OK) return rc;
    ori_line_set s = ori_axiom_solve(&in);
    if (json) {
        json_t *out = cli_axiom_json(in.axiom, &s);
        cli_print_json(out);
    } else {
        printf("axiom %d (%s): %d solution%s\n", in.axiom, axiom_summary(in.axiom), s.count, s.count == 1 ? "" : "s");
        for (int k = 0; k < s.count; ++k)
            printf("  %d  point (%.17g, %.17g)  dir (%.17g, %.17g)\n", k + 1, s.lines[k].point.x, s.lines[k].point.y,
                   s.lines[k].dir.x, s.lines[k].dir.y);
    }
    return s.count > 0 ? CLI_EXIT_OK : CLI_EXIT_NEGATIVE;
}

const cli_command cli_cmd_axiom = {
    "axiom",
    "every fold line a Huzita-Hatori axiom (1-7) gives for points and lines",
    "usage: orikin axiom N [--p1 x,y] [--p2 x,y] [--l1 x,y,dx,dy] [--l2 x,y,dx,dy] [--json]\n"
    "\n"
    "Solve Huzita-Hatori axiom N and print every solution as an infinite line: a unit\n"
    "direction dir (dx > 0, or (0, 1) when vertical) and the point of the line nearest the\n"
    "origin. A line input is a point and a direction. Degenerate inputs (coincident points,\n"
    "parallel lines where they must meet, no real solution) give no solution.\n"
    "\n"
    "  1  --p1 --p2             fold through p1 and p2                         (1 solution)\n"
    "  2  --p1 --p2             fold placing p1 onto p2                        (1)\n"
    "  3  --l1 --l2             fold placing l1 onto l2                        (1 if parallel, else 2)\n"
    "  4  --p1 --l1             fold through p1 perpendicular to l1            (1)\n"
    "  5  --p1 --p2 --l1        fold through p2 placing p1 onto l1             (0-2)\n"
    "  6  --p1 --p2 --l1 --l2   fold placing p1 onto l1 and p2 onto l2         (0-3, a cubic)\n"
    "  7  --p1 --l1 --l2        fold placing p1 onto l1, perpendicular to l2   (0-1)\n"
    "\n"
    "Solutions of 5 and 6 are ordered by where p1 lands along l1's direction; axiom 3 lists\n"
    "first the bisector that maps l1's direction onto l2's.\n"
    "\n"
    "options:\n"
    "  --p1 x,y, --p2 x,y   points\n"
    "  --l1 x,y,dx,dy       line through (x, y) with direction (dx, dy); --l2 likewise\n"
    "  --json               print {\"axiom\": N, \"lines\": [{\"point\": [x, y], \"dir\": [dx, dy]}]}\n"
    "\n"
    "exit codes: 0 solutions found, 1 no solution, 2 bad command line\n"
    "example: orikin axiom 6 --p1 0,-1 --l1 0,1,1,0 --p2 2,0 --l2 -2,0,0,1   (slope = cube root of 2)\n",
    run,
    NULL,
};
