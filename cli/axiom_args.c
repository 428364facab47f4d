// Parsing of axiom inputs for the CLI.
#include "axiom_args.h"

#include <string.h>

static const int needs[8] = {0,
                             AXIOM_P1 | AXIOM_P2,
                             AXIOM_P1 | AXIOM_P2,
                             AXIOM_L1 | AXIOM_L2,
                             AXIOM_P1 | AXIOM_L1,
                             AXIOM_P1 | AXIOM_P2 | AXIOM_L1,
                             AXIOM_P1 | AXIOM_P2 | AXIOM_L1 | AXIOM_L2,
                             AXIOM_P1 | AXIOM_L1 | AXIOM_L2};

static const char *const summaries[8] = {
    "",
    "fold through p1 and p2",
    "fold placing p1 onto p2",
    "fold placing line l1 onto line l2",
    "fold through p1 perpendicular to l1",
    "fold through p2 placing p1 onto l1",
    "fold placing p1 onto l1 and p2 onto l2",
    "fold placing p1 onto l1, perpendicular to l2",
};

const char *axiom_summary(int axiom) { return axiom >= 1 && axiom <= 7 ? summaries[axiom] : ""; }

const char *axiom_inputs_text(int axiom)
{
    static const char *const text[8] = {"",
                                        "--p1 --p2",
                                        "--p1 --p2",
                                        "--l1 --l2",
                                        "--p1 --l1",
                                        "--p1 --p2 --l1",
                                        "--p1 --p2 --l1 --l2",
                                        "--p1 --l1 --l2"};
    return axiom >= 1 && axiom <= 7 ? text[axiom] : "";
}

int axiom_parse_option(const char *cmd, int argc, char **argv, int *i, ori_axiom_input *in, int *given)
{
    const char *a = argv[*i];
    int bit = strcmp(a, "--p1") == 0 ? AXIOM_P1 : strcmp(a, "--p2") == 0 ? AXIOM_P2
            : strcmp(a, "--l1") == 0 ? AXIOM_L1 : strcmp(a, "--l2") == 0 ? AXIOM_L2 : 0;
    if (!bit) return 0;
    if (*given & bit) return -cli_usage(cmd, "%s given twice (it takes one value)", a);
    const char *v = cli_option_value(cmd, argc, argv, i);
    if (!v) return -CLI_EXIT_USAGE;
    double x[4];
    if (bit == AXIOM_P1 || bit == AXIOM_P2) {
        if (!cli_parse_doubles(v, x, 2)) return -cli_usage(cmd, "%s needs a point x,y (got %s)", a, v);
        *(bit == AXIOM_P1 ? &in->p1 : &in->p2) = ori_v2_make(x[0], x[1]);
    } else {
        if (!cli_parse_doubles(v, x, 4))
            return -cli_usage(cmd, "%s needs a line x,y,dx,dy: a point and a direction (got %s)", a, v);
        if (x[2] == 0.0 && x[3] == 0.0) return -cli_usage(cmd, "%s: the direction dx,dy must not be zero", a);
        ori_line l = {ori_v2_make(x[0], x[1]), ori_v2_make(x[2], x[3])};
        *(bit == AXIOM_L1 ? &in->l1 : &in->l2) = l;
    }
    *given |= bit;
    return 1;
}

int axiom_check_inputs(const char *cmd, const ori_axiom_input *in, int given)
{
    int n = in->axiom;
    if (n < 1 || n > 7) return cli_usage(cmd, "the axiom is a number from 1 to 7");
    int missing = needs[n] & ~given, extra = given & ~needs[n];
    if (missing || extra)
        return cli_usage(cmd, "axiom %d (%s) takes %s%s", n, summaries[n], axiom_inputs_text(n),
                         extra ? "; other inputs were given" : "");
    return CLI_EXIT_OK;
}
