// Shared pieces of the kinematics commands (fold, fit, dof): loading the flat crease pattern
// of frame 0 and the start state of a frame, parsing the fold specification.
#ifndef ORI_CLI_KIN_ARGS_H
#define ORI_CLI_KIN_ARGS_H

#include <orikin/kinematics.h>

#include "cli.h"

// A loaded mechanism and a start state.
typedef struct cli_kin {
    ori_fold *doc;
    ori_pattern *flat;       // frame 0 (the crease pattern)
    ori_mechanism *mech;
    double *angles;          // start fold angles per edge (radians), from the chosen frame
    ori_v3 *coords;          // the chosen frame's vertex coordinates (3D for folded frames)
    bool folded;             // the chosen frame has 3D coordinates
    int frame;
} cli_kin;

// Load FILE: frame 0 must be a flat crease pattern (the mechanism), `frame` supplies the fold
// angles (edges_foldAngle) and, when it is 3D, the vertex coordinates. Prints the error and
// returns CLI_EXIT_INPUT on failure (with *k released), else CLI_EXIT_OK.
// FILE may also be a drawing (SVG, OPX, CP: its crease pattern, flat) read with the default
// import options.
int cli_kin_load(const char *cmd, const char *path, int frame, cli_kin *k);
// cli_kin_load with the input options a command parsed (--weld for FOLD; --tolerance, --gaps,
// --keep-* for drawings; NULL: the defaults). `frame` is the start state; the mechanism is
// always frame 0. A drawing has no frames: --frame other than 0 is a usage error.
int cli_kin_load_input(const char *cmd, const char *path, int frame, const cli_input *in, cli_kin *k);
// cli_kin_load for a sequence file: `frame` is its "frame" field, and a frame the pattern does
// not have is bad input in seq_path naming that field (exit 3), not the --frame option.
int cli_kin_load_sequence(const char *cmd, const char *seq_path, const char *path, int frame, cli_kin *k);
void cli_kin_free(cli_kin *k);

// World pose of the fixed face in the start frame: identity for a flat frame, the rigid fit of
// its 3D vertices otherwise. Prints the error and returns CLI_EXIT_INPUT on failure.
int cli_kin_fixed_pose(const char *cmd, const char *path, const cli_kin *k, int face, ori_rigid *pose);

// Naming faces and creases, one code path for every command that takes them (fold and its
// modes, fit, actuate, simulate, dof, render, animate, export, collide, crease, apply):
//   a face   is a FOLD index, a face name (Obj12) or @x,y (the face containing the point);
//   a crease is a FOLD index or @x,y (the crease through the point);
//   a list of creases is comma-separated, and an item starting with '@' takes the next item as
//   its y: "3,@0.5,1,9" is crease 3, the crease through (0.5, 1), and crease 9.
// Each prints one line naming the option and returns CLI_EXIT_USAGE for a face or crease the
// pattern does not have (an index out of range, an unknown name, a point on no face or crease)
// or a malformed spec; else CLI_EXIT_OK with the index set.
int cli_spec_face(const char *cmd, const char *path, const ori_pattern *p, const char *option, const char *spec,
                  int *face);
int cli_spec_edge(const char *cmd, const char *path, const ori_pattern *p, const char *option, const char *spec,
                  int *edge);
// The face held fixed when a fold gives no --fix: ori_pattern_center_face (the face containing
// the centroid of the sheet's area, else the face nearest to it).
int cli_fold_default_fix(const ori_pattern *p);
// What the text output appends after "face N fixed" when N is that default.
#define CLI_FOLD_DEFAULT_FIX_NOTE " (the face at the sheet's centre; --fix to choose)"
// The number of creases in a list (the syntax only, nothing resolved), or -1 when malformed.
int cli_spec_edge_count(const char *spec);
// Resolve a list of at most cap creases into out (unique: drop repeats, e.g. the same crease
// by index and by point). Returns the count, or minus the exit code after the message.
int cli_spec_edges(const char *cmd, const char *path, const ori_pattern *p, const char *option, const char *spec,
                   bool unique, int *out, int cap);
// The most creases --lock takes (a lock set that --lock auto found on a large sheet included).
#define CLI_FOLD_MAX_LOCKS 4096

// The fold specification shared by fold and fit.
typedef struct cli_fold_args {
    const char *path;
    int fix, drive;
    bool has_fix, has_drive, has_to, has_from;
    bool fix_default;     // no --fix: fix is cli_fold_default_fix (set by cli_fold_resolve)
    double to_deg, from_deg, step_deg;
    int locks[CLI_FOLD_MAX_LOCKS];
    int lock_count;
    bool lock_auto;       // --lock auto: cli_fold_resolve finds the set (ori_mechanism_lock_set)
    int frame;
    bool json;
    const char *out;
    ori_solver solver;
    ori_linear linear;
    int degree, refine;   // fit only
    cli_input input;      // --weld, and the drawing options (--tolerance, --gaps, --keep-*)
    // --fix, --drive and --lock as given (index, name, "@x,y", lists): cli_fold_resolve sets
    // fix, drive and locks from them and clears them.
    const char *fix_spec, *drive_spec, *lock_spec;
} cli_fold_args;

// Parse the fold options (fit adds --degree and --refine). Returns CLI_EXIT_OK, or the
// usage exit code after printing the message.
int cli_fold_parse(const char *cmd, int argc, char **argv, bool fit, cli_fold_args *a);

// Resolve --fix, --drive and --lock (cli_spec_face, cli_spec_edge, cli_spec_edges) against the
// loaded crease pattern, and --lock auto into the lock set that leaves the drive one degree of
// freedom at the start state (exit 3 when none is found, 2 when nothing needs locking); every
// caller of cli_fold_def resolves first. Returns CLI_EXIT_OK, or CLI_EXIT_USAGE after a message naming the option.
int cli_fold_resolve(const char *cmd, cli_fold_args *a, const cli_kin *k);

// After ori_motion_solve of a def from cli_fold_def failed: a driven or locked crease the fold
// cannot use (a boundary edge, a crease both driven and locked) is a usage error naming --drive
// or --lock (exit 2); anything else an input error (3), or internal (4) for a solver failure.
int cli_fold_solve_error(const char *cmd, const cli_fold_args *a, ori_status st, const ori_error *err);

// Check the specification against the mechanism and fill a motion def (angles from k, pose
// from the fixed face). Prints a one-line input error naming the index and returns
// CLI_EXIT_INPUT for bad indices/angles; else CLI_EXIT_OK.
int cli_fold_def(const char *cmd, const cli_fold_args *a, const cli_kin *k, ori_motion_def *def);


#endif
