// Pieces shared by the sweep's files: the job of one point as parsed from its substituted JSON.
#ifndef ORI_CLI_SWEEP_INTERNAL_H
#define ORI_CLI_SWEEP_INTERNAL_H

#include "sweep.h"

#include <orikin/actuation.h>

// Format a one-line message into err; returns SWEEP_EXIT_INPUT.
int sweep_fail(char *err, size_t size, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

#define SWEEP_MAX_LOCKS 4096

// Overrides of a hinge's fields (design.hinge).
typedef struct sweep_hinge_spec {
    bool has_material, has_width, has_thickness, has_span;
    char material[ORI_MATERIAL_NAME_MAX];
    double width, thickness, span;
    int wire; // -1: as the file has it, 0: no wire ("wire": false), 1: the fields below
    bool has_wire_length, has_wire_lever;
    double wire_length, wire_lever;
    int wire_turns; // 0: as the file has it (1 for a new wire)
} sweep_hinge_spec;

// One point's job (the substituted template, parsed).
typedef struct sweep_cfg {
    // base
    bool base_is_file;
    char file[1024];
    ori_generate_def gen;
    char *base_key; // canonical text of the base: points with the same one share the pattern
    // design
    bool hinges_every;      // design.hinges "every" (default for a generated base)
    bool has_hinge;
    sweep_hinge_spec hinge;
    int wires;              // design.wires: 0 every hinge (as the hinge says), 1 the fold's driven crease only, 2 the list
    int wire_edges[SWEEP_MAX_LOCKS];
    int wire_count;
    bool has_panel, has_panel_material, has_panel_thickness;
    char panel_material[ORI_MATERIAL_NAME_MAX];
    double panel_thickness;
    bool has_unit;
    double unit_m;
    bool has_field;
    ori_v3 field;
    bool has_current_limit;
    double current_limit;
    int gravity;            // -1 file, 0 off, 1 on
    // fold
    bool fold, targets;
    double percent;
    int drive_kind;         // 0 index, 1 point, 2 "center"
    int drive;
    double drive_xy[2];
    double to_deg, from_deg, step_deg;
    bool has_from;
    int fix_kind;           // -1 the face at the sheet's centre, 0 index, 1 point
    int fix;
    double fix_xy[2];
    int locks[SWEEP_MAX_LOCKS];
    int lock_count;
    char *sequence;         // job.sequence: the folds as a sequence file's JSON, run on the base (malloc'd), or NULL
    char *fold_key;         // canonical text of base + fold + collide: points sharing it share the motion
    bool collide;
    double clearance;
    // actuate
    bool actuate;
    int reorientations;     // -1 default
    bool fixed_field;
    // simulate
    bool simulate;
    double sim_current, sim_duration, sim_dt;
    bool has_sim_dt;
    int sim_fix;            // -1: the fold's fixed face (or the face at the sheet's centre)
    // layers
    bool layers;
    uint64_t layers_limit;
} sweep_cfg;

// Parse a point's job (base, design, job sections; spec_dir resolves the base file). Returns 0,
// or SWEEP_EXIT_INPUT with "FIELD: message" in err. Free with sweep_cfg_free.
int sweep_cfg_parse(const json_t *job, const char *spec_dir, sweep_cfg *cfg, char *err, size_t err_size);
void sweep_cfg_free(sweep_cfg *cfg);

#endif
