// Shared pieces of the actuation commands: options, input, design overrides, sizing.
#include "actuation_args.h"
#include "progress.h"
#include "report.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct opt_spec {
    const char *name;
    bool value;     // takes a value
    bool simulate;  // simulate only
    bool actuate;   // actuate only
} opt_spec;

static const opt_spec specs[] = {
    {"--materials", true, false, false},      {"--unit", true, false, false},
    {"--field", true, false, false},          {"--current-limit", true, false, false},
    {"--gravity", false, false, false},       {"--no-gravity", false, false, false},
    {"--reorientations", true, false, false}, {"--fixed-field", false, false, false},
    {"--fix", true, true, false},             {"--current", true, true, false},
    {"--duration", true, true, false},        {"--dt", true, true, false},
    {"--damping", true, true, false},         {"--pulse", true, true, false},
    {"--frames", true, true, false},          {"--no-stops", false, true, false},
    {"--frame", true, true, false},           {"--json", false, true, false},
    {"-o", true, true, false},                {"--model", true, true, false},
};

static int positive(const char *cmd, const char *opt, const char *v, double *out, bool allow_zero)
{
    if (!cli_parse_double(v, out) || !(allow_zero ? *out >= 0.0 : *out > 0.0))
        return cli_usage(cmd, "%s needs a %s number, got '%s'", opt, allow_zero ? "non-negative" : "positive", v);
    return CLI_EXIT_OK;
}

int act_parse(const char *cmd, int argc, char **argv, bool simulate, act_opts *o, int *rest_argc, char **rest)
{
    memset(o, 0, sizeof *o);
    o->gravity = -1;
    o->reorientations = -1;
    o->frames = 101;
    int n = 0;
    rest[n++] = argv[0];
    char seen[sizeof specs / sizeof specs[0]] = {0};
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        int k = -1;
        for (size_t s = 0; s < sizeof specs / sizeof specs[0]; ++s)
            if (strcmp(a, specs[s].name) == 0 && (simulate || !specs[s].simulate) && (!simulate || !specs[s].actuate))
                k = (int)s;
        if (k < 0) {
            rest[n++] = argv[i];
            continue;
        }
        if (seen[k]++) return cli_usage(cmd, "%s given twice", a);
        const char *v = NULL;
        if (specs[k].value && !(v = cli_option_value(cmd, argc, argv, &i))) return CLI_EXIT_USAGE;
        int rc = CLI_EXIT_OK;
        if (strcmp(a, "--materials") == 0) o->materials = v;
        else if (strcmp(a, "--unit") == 0) {
            ori_error err;
            if (ori_unit_meters(v, &o->unit_m, &err) != ORI_OK)
                return cli_usage(cmd, "--unit is m, cm, mm, um, nm, in or pt, got '%s'", v);
            o->has_unit = true;
        } else if (strcmp(a, "--field") == 0) {
            double b[3];
            if (!cli_parse_doubles(v, b, 3)) return cli_usage(cmd, "--field needs BX,BY,BZ in teslas, got '%s'", v);
            o->field = ori_v3_make(b[0], b[1], b[2]);
            if (!(ori_v3_norm(o->field) > 0.0)) return cli_usage(cmd, "--field: the magnetic field is zero");
            o->has_field = true;
        } else if (strcmp(a, "--current-limit") == 0) {
            rc = positive(cmd, a, v, &o->current_limit, false);
            o->has_current_limit = true;
        } else if (strcmp(a, "--gravity") == 0 || strcmp(a, "--no-gravity") == 0) {
            if (o->gravity != -1) return cli_usage(cmd, "--gravity and --no-gravity exclude each other");
            o->gravity = strcmp(a, "--gravity") == 0;
        } else if (strcmp(a, "--reorientations") == 0) {
            if (!cli_parse_int(v, &o->reorientations) || o->reorientations < 0 || o->reorientations > ORI_SCHEDULE_MAX - 1)
                return cli_usage(cmd, "--reorientations needs an integer from 0 to %d, got '%s'", ORI_SCHEDULE_MAX - 1, v);
        } else if (strcmp(a, "--fixed-field") == 0) o->fixed_field = true;
        else if (strcmp(a, "--fix") == 0) {
            o->fix_spec = v; // an index, a name or @x,y: resolved against the pattern (cli_spec_face)
            o->has_fix = true;
        } else if (strcmp(a, "--current") == 0) {
            rc = positive(cmd, a, v, &o->current, true);
            o->has_current = true;
        } else if (strcmp(a, "--duration") == 0) {
            rc = positive(cmd, a, v, &o->duration, false);
            o->has_duration = true;
        } else if (strcmp(a, "--dt") == 0) {
            rc = positive(cmd, a, v, &o->dt, false);
            o->has_dt = true;
        } else if (strcmp(a, "--damping") == 0) {
            rc = positive(cmd, a, v, &o->damping, true);
            o->has_damping = true;
        } else if (strcmp(a, "--pulse") == 0) {
            rc = positive(cmd, a, v, &o->pulse, false);
            o->has_pulse = true;
        } else if (strcmp(a, "--frames") == 0) {
            if (!cli_parse_int(v, &o->frames) || o->frames < 2 || o->frames > 100000)
                return cli_usage(cmd, "--frames needs an integer from 2 to 100000, got '%s'", v);
        } else if (strcmp(a, "--no-stops") == 0) o->no_stops = true;
        else if (strcmp(a, "--frame") == 0) {
            if (!cli_parse_int(v, &o->frame) || o->frame < 0) return cli_usage(cmd, "--frame needs a frame number >= 0");
        } else if (strcmp(a, "--json") == 0) o->json = true;
        else if (strcmp(a, "-o") == 0) o->out = v;
        else if (strcmp(a, "--model") == 0) {
            if (strcmp(v, "compliant") == 0) o->compliant = true;
            else if (strcmp(v, "rigid") != 0) return cli_usage(cmd, "--model is rigid or compliant, got '%s'", v);
        }
        if (rc != CLI_EXIT_OK) return rc;
    }
    if (o->fixed_field && o->reorientations >= 0) return cli_usage(cmd, "--fixed-field and --reorientations exclude each other");
    if (o->has_dt && o->has_duration && o->dt > o->duration)
        return cli_usage(cmd, "--dt %g is larger than --duration %g", o->dt, o->duration);
    *rest_argc = n;
    rest[n] = NULL;
    return CLI_EXIT_OK;
}

bool act_is_sequence(const char *path)
{
    json_error_t je;
    json_t *root = json_load_file(path, 0, &je);
    bool seq = json_is_object(root) && json_object_get(root, "folds") && !json_object_get(root, "vertices_coords");
    json_decref(root);
    return seq;
}

void act_free(act_input *in)
{
    ori_design_destroy(in->design);
    ori_materials_destroy(in->materials);
    cli_kin_free(&in->k);
    ori_sequence_destroy(in->seq);
    free(in->pattern_path);
    memset(in, 0, sizeof *in);
}

int act_load(const char *cmd, const char *path, const act_opts *o, act_input *in)
{
    memset(in, 0, sizeof *in);
    in->path = path;
    ori_error err;
    int rc;
    in->is_sequence = act_is_sequence(path);
    int frame = o->frame;
    if (in->is_sequence) {
        if (ori_sequence_load_file(path, &in->seq, &err) != ORI_OK) {
            rc = cli_input_error(cmd, path, &err);
            act_free(in);
            return rc;
        }
        in->pattern_path = cli_path_beside(path, ori_sequence_pattern_path(in->seq));
        frame = ori_sequence_frame(in->seq);
    } else {
        in->pattern_path = malloc(strlen(path) + 1);
        strcpy(in->pattern_path, path);
    }
    if ((rc = cli_kin_load(cmd, in->pattern_path, frame, &in->k)) != CLI_EXIT_OK) {
        free(in->pattern_path);
        ori_sequence_destroy(in->seq);
        memset(in, 0, sizeof *in);
        return rc;
    }
    if (in->seq && ori_sequence_resolve(in->seq, in->k.flat, &err) != ORI_OK) { // names and points in SEQ.json
        rc = cli_input_error(cmd, path, &err);
        act_free(in);
        return rc;
    }
    in->materials = ori_materials_create();
    if (o->materials && ori_materials_load_file(in->materials, o->materials, &err) != ORI_OK) {
        rc = cli_input_error(cmd, o->materials, &err);
        act_free(in);
        return rc;
    }
    ori_design_def dd = ori_default_design_def();
    dd.doc = in->k.doc;
    dd.pattern = in->k.flat;
    dd.materials = in->materials;
    dd.has_meters_per_unit = o->has_unit;
    dd.meters_per_unit = o->unit_m;
    if (ori_design_create(&dd, &in->design, &err) != ORI_OK) {
        if (strcmp(err.field, "frame_unit") == 0 && !o->has_unit)
            rc = cli_input_fail(cmd, in->pattern_path, "frame_unit: %s (--unit U: m, cm, mm, um, nm, in, pt)", err.message);
        else
            rc = cli_input_error(cmd, in->pattern_path, &err);
        act_free(in);
        return rc;
    }
    ori_actuation a = ori_design_actuation(in->design);
    if (o->has_field) {
        a.has_field = true;
        a.field_t = o->field;
        a.schedule_count = 0; // a field from the command line replaces the file's schedule
    }
    if (o->has_current_limit) {
        a.has_current_limit = true;
        a.current_limit_a = o->current_limit;
    }
    if (o->gravity == 1) a.gravity_m_s2 = ori_v3_make(0, 0, -9.80665);
    if (o->gravity == 0) a.gravity_m_s2 = ori_v3_make(0, 0, 0);
    if (o->has_damping) a.damping_ratio = o->damping;
    if (ori_design_set_actuation(in->design, &a, &err) != ORI_OK) {
        rc = cli_input_error(cmd, in->pattern_path, &err);
        act_free(in);
        return rc;
    }
    return CLI_EXIT_OK;
}

int act_run_sequence(const char *cmd, act_input *in, ori_record **out)
{
    ori_error err;
    *out = NULL;
    ori_sequence_fold first = ori_sequence_fold_at(in->seq, 0);
    for (int i = 0; i < ori_sequence_fold_count(in->seq); ++i) // folds toward the targets have no driven crease
        if (ori_sequence_fold_at(in->seq, i).targets)
            return cli_input_fail(cmd, in->path, "folds %d: a fold toward the targets (\"percent\") has no driven crease to actuate", i);
    if (first.fixed_face < 0 || first.fixed_face >= ori_mechanism_face_count(in->k.mech))
        return cli_input_fail(cmd, in->path, "folds 0: fix: face %d does not exist (%d faces)", first.fixed_face,
                              ori_mechanism_face_count(in->k.mech));
    ori_rigid pose;
    int rc = cli_kin_fixed_pose(cmd, in->pattern_path, &in->k, first.fixed_face, &pose);
    if (rc != CLI_EXIT_OK) return rc;
    if (ori_sequence_run(in->seq, in->k.mech, in->k.angles, pose, out, &err) != ORI_OK) return cli_input_error(cmd, in->path, &err);
    if (ori_record_verdict(*out) != ORI_MOTION_VALID) {
        fprintf(stderr, "orikin %s: %s: fold %d is %s: %s\n", cmd, in->path, ori_record_failed_fold(*out) + 1,
                ori_motion_verdict_name(ori_record_verdict(*out)), ori_record_reason(*out) ? ori_record_reason(*out) : "");
        ori_record_destroy(*out);
        *out = NULL;
        return CLI_EXIT_NEGATIVE;
    }
    return CLI_EXIT_OK;
}

int act_size(const char *cmd, act_input *in, const act_opts *o, const ori_motion *motion, int driven_edge,
             const ori_record *record, ori_sizing **out)
{
    ori_sizing_def sd = ori_default_sizing_def();
    sd.design = in->design;
    sd.mechanism = in->k.mech;
    sd.motion = motion;
    sd.driven_edge = driven_edge;
    sd.record = record;
    sd.sequence = record ? in->seq : NULL;
    if (o->fixed_field) sd.schedule = ORI_SCHEDULE_FIXED;
    else if (o->reorientations >= 0) {
        sd.schedule = ORI_SCHEDULE_OPTIMIZE;
        sd.reorientations = o->reorientations;
    }
    cli_progress bar;
    cli_progress_begin(&bar, cmd, "sizing");
    sd.progress = cli_progress_fn;
    sd.progress_user = &bar;
    ori_error err;
    ori_status st = ori_sizing_solve(&sd, out, &err);
    cli_progress_end(&bar);
    if (st != ORI_OK) return cli_input_error(cmd, in->is_sequence ? in->path : in->pattern_path, &err);
    return CLI_EXIT_OK;
}

json_t *act_schedule_json(const ori_field_change *s, int n)
{
    json_t *a = json_array();
    for (int i = 0; i < n; ++i)
        json_array_append_new(a, json_pack("{s:f,s:i,s:i,s:[fff]}", "from_deg", ori_rad_to_deg_output(s[i].from_rad), "crease",
                                           s[i].edge, "fold", s[i].fold + 1, "field", s[i].field_t.x, s[i].field_t.y,
                                           s[i].field_t.z));
    return a;
}
