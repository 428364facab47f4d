// Options shared by `orikin axiom` and `orikin crease`: the inputs of a Huzita–Hatori axiom.
#ifndef ORI_CLI_AXIOM_ARGS_H
#define ORI_CLI_AXIOM_ARGS_H

#include <orikin/axioms.h>

#include "cli.h"

// Which inputs were given (bit 1 p1, 2 p2, 4 l1, 8 l2).
enum { AXIOM_P1 = 1, AXIOM_P2 = 2, AXIOM_L1 = 4, AXIOM_L2 = 8 };

// Consume --p1 x,y / --p2 x,y / --l1 x,y,dx,dy / --l2 … at argv[*i]. Returns 1 when consumed,
// 0 when argv[*i] is not one of them, or an exit code < 0 negated (usage error printed).
int axiom_parse_option(const char *cmd, int argc, char **argv, int *i, ori_axiom_input *in, int *given);
// Check that exactly the inputs axiom in->axiom needs were given; prints a usage error.
int axiom_check_inputs(const char *cmd, const ori_axiom_input *in, int given);
// The inputs an axiom takes, as text ("--p1 --p2").
const char *axiom_inputs_text(int axiom);
// What an axiom constructs, as text.
const char *axiom_summary(int axiom);

#endif
