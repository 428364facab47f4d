// orikin fold --compliant (fold_compliant.c): the bar-and-hinge model's fold. cmd_fold.c
// hands the command line over when --compliant is among the arguments.
#ifndef ORI_CLI_FOLD_COMPLIANT_H
#define ORI_CLI_FOLD_COMPLIANT_H

#include <stdbool.h>

#include <orikin/compliant.h>
#include <orikin/fold.h>

#include "cli.h"
#include "report.h"

// Offer argv[*i] to the compliant fold's options (--compliant, --dynamic, --percent, --fix (its
// spec in *fix, resolved by the caller), --preset, --axial, --facet, --crease, --damping,
// --gravity, --steps, --threads) into r: 1 when taken (*i past its value), 0 when not one, minus
// the exit code after printing a usage error.
int cli_compliant_option(const char *cmd, int argc, char **argv, int *i, cli_compliant_request *r, const char **fix,
                         cli_seen *seen);
// Whether --compliant is given.
bool cli_fold_compliant_wanted(int argc, char **argv);
// Run the compliant fold (argv[0] = "fold").
int cli_fold_compliant_run(int argc, char **argv);
// Append the model's frames to doc as folded-form frames ("orikin:fraction", "edges_orikin:strain",
// "faces_orikin:strain_energy", "faces_orikin:strain"; the flat first frame only with all) and
// save it to out; title_format takes the frame's percent. Prints errors (as cmd).
int cli_compliant_write_frames(const char *cmd, const char *out, ori_fold *doc, const ori_compliant *c, int E, bool all,
                               const char *title_format);

#define CLI_FOLD_COMPLIANT_HELP                                                                          \
    "compliant folding (--compliant; docs/compliant.md):\n"                                              \
    "  orikin fold FILE --compliant [--percent P] [--dynamic] [--fix FACE] [--preset NAME]\n"            \
    "                   [--axial K] [--facet K] [--crease K] [--damping Z] [--gravity G]\n"            \
    "                   [--steps N] [--threads N] [--all-frames] [--json] [-o OUT]\n"                   \
    "  Fold with a bar-and-hinge model (Origami Simulator's: faces triangulated, bars on every\n"      \
    "  edge and diagonal, creases driven to P % of their targets, facet hinges resisting panel\n"     \
    "  bending), so that patterns that are not rigidly foldable fold too, bending a little. The\n"    \
    "  static solver (default) finds the equilibrium by Newton with load steps (|grad E| <= 1e-10\n"  \
    "  of the load); --dynamic runs the explicit damped solver until it settles.\n"                   \
    "  --percent P     how far toward the targets (edges_foldAngle, else +-180 by M/V); default 100\n" \
    "  --dynamic       explicit solver (damped Verlet, stable time step), at most --steps steps\n"     \
    "  --threads N     explicit solver threads (default 1)\n"                                       \
    "  --preset NAME   origami-simulator (default: axial 20, facet 0.2, crease 0.7, damping 0.45)\n"   \
    "                  or physical (SI: 1 um silicon panels; lengths in metres)\n"                     \
    "  --axial K, --facet K, --crease K, --damping Z   the stiffnesses of the preset, replaced\n"      \
    "  --gravity G     acceleration along -z (model units or m/s^2); default 0\n"                       \
    "  --all-frames    -o writes every load step (--dynamic: the time history, with frame_time)\n"   \
    "  --json          print {file, model, solver, preset, percent, reached, reached_fraction,\n"       \
    "                  max_strain, energy, crease_error_deg, gradient_norm, load_scale, vertices,\n"  \
    "                  bars, hinges, steps | newton_iterations, load_steps, fold_angles_deg,\n"       \
    "                  strains, face_energies, face_strains, contacts [{faces, step, fraction}],\n"  \
    "                  contacts_truncated, reason}\n"                                                 \
    "  -o OUT.fold     FILE with the state(s) appended as folded-form frames, each with\n"            \
    "                  \"orikin:fraction\", \"edges_orikin:strain\" (axial strain per edge),\n"         \
    "                  \"faces_orikin:strain_energy\" and \"faces_orikin:strain\" (per face)\n"         \
    "  Faces passing through each other during the fold are warned of (the pair and the step).\n"   \
    "  Exit 0 reached, 1 no equilibrium (static), 5 not settled in --steps (dynamic), 3 bad input.\n"

#endif
