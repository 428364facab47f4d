// Shared pieces of the actuation commands (actuate, simulate): their own options, the input
// (a FOLD file with fold options, or a fold sequence SEQ.json), the design with the
// command-line overrides, the fold or sequence run that the sizing follows.
#ifndef ORI_CLI_ACTUATION_ARGS_H
#define ORI_CLI_ACTUATION_ARGS_H

#include <orikin/actuation.h>
#include <orikin/sequence.h>

#include "kin_args.h"

// Options of the actuation commands (fold options are left to cli_fold_parse).
typedef struct act_opts {
    const char *materials;     // --materials FILE
    bool has_unit;
    double unit_m;             // --unit U
    bool has_field;
    ori_v3 field;              // --field BX,BY,BZ
    bool has_current_limit;
    double current_limit;      // --current-limit A
    int gravity;               // --gravity (1) / --no-gravity (0) / file (−1)
    int reorientations;        // --reorientations N (−1: the default)
    bool fixed_field;          // --fixed-field
    // simulate
    bool has_fix;
    int fix;                   // --fix FACE (resolved from fix_spec after loading)
    const char *fix_spec;      // --fix as given: an index, a name (Obj12) or @x,y
    bool has_current;
    double current;            // --current A
    bool has_duration;
    double duration;           // --duration S
    bool has_dt;
    double dt;                 // --dt S
    bool has_damping;
    double damping;            // --damping RATIO
    bool has_pulse;
    double pulse;              // --pulse S
    int frames;                // --frames N
    bool no_stops;             // --no-stops
    int frame;                 // --frame N
    bool json;
    const char *out;           // -o OUT.fold
    bool compliant;            // --model compliant (simulate)
} act_opts;

// Parse the command's own options (simulate: all of them) from argv; everything else is copied
// to rest (rest[0] = argv[0]) for cli_fold_parse. Returns CLI_EXIT_OK or a usage exit code.
int act_parse(const char *cmd, int argc, char **argv, bool simulate, act_opts *o, int *rest_argc, char **rest);

// The loaded input: the kinematics (FOLD file or the sequence's pattern), the sequence when
// the input is SEQ.json, and the design.
typedef struct act_input {
    const char *path;          // as given
    char *pattern_path;        // the FOLD file (the sequence's pattern, resolved)
    bool is_sequence;
    ori_sequence *seq;
    cli_kin k;
    ori_materials *materials;
    ori_design *design;
} act_input;

// True when path holds a fold sequence (a JSON object with "folds") rather than a FOLD file.
bool act_is_sequence(const char *path);
// Load the input and the design, apply the overrides of o. Prints the error and returns its exit
// code on failure (with *in released).
int act_load(const char *cmd, const char *path, const act_opts *o, act_input *in);
void act_free(act_input *in);

// Run the sequence of a SEQ.json input from its start state; prints errors.
int act_run_sequence(const char *cmd, act_input *in, ori_record **out);

// Size along a fold (motion + its driven edge) or the input's sequence run; prints errors.
int act_size(const char *cmd, act_input *in, const act_opts *o, const ori_motion *motion, int driven_edge,
             const ori_record *record, ori_sizing **out);

// simulate --model compliant (simulate_compliant.c): the quasi-static equilibria of the
// bar-and-hinge model as the wires' current ramps up and off; o parsed by act_parse, path a FILE.
int act_simulate_compliant(const char *path, const act_opts *o);
// JSON of a field schedule: [{"from_deg", "crease", "field"}].
json_t *act_schedule_json(const ori_field_change *s, int n);

#endif
