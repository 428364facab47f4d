// Shared pieces of the kinematics commands: loading and the fold options.
#include "kin_args.h"

#include <orikin/arrangement.h>
#include <orikin/tolerance.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void cli_kin_free(cli_kin *k)
{
    ori_mechanism_destroy(k->mech);
    ori_pattern_destroy(k->flat);
    ori_fold_destroy(k->doc);
    free(k->angles);
    free(k->coords);
    memset(k, 0, sizeof *k);
}

int cli_kin_load(const char *cmd, const char *path, int frame, cli_kin *k)
{
    return cli_kin_load_input(cmd, path, frame, NULL, k);
}

static int kin_load(const char *cmd, const char *path, int frame, const cli_input *options, const char *frame_from,
                    cli_kin *k);

int cli_kin_load_input(const char *cmd, const char *path, int frame, const cli_input *options, cli_kin *k)
{
    return kin_load(cmd, path, frame, options, NULL, k);
}

int cli_kin_load_sequence(const char *cmd, const char *seq_path, const char *path, int frame, cli_kin *k)
{
    return kin_load(cmd, path, frame, NULL, seq_path, k);
}

// Neither .fold nor a drawing by its name: FOLD is JSON, so a file that does not start like JSON
// (an image, say) is named as what it is not (exit 3), rather than as a JSON syntax error.
static int not_a_pattern(const char *cmd, const char *path)
{
    FILE *fp = fopen(path, "rb");
    if (!fp) return CLI_EXIT_OK; // (the loader names the missing file)
    int c;
    do c = fgetc(fp);
    while (c == ' ' || c == '\t' || c == '\n' || c == '\r');
    fclose(fp);
    if (c != '{' && c != 0xEF && c != EOF) // 0xEF: a UTF-8 byte-order mark
        return cli_input_fail(cmd, path, "not a FOLD file or a drawing (FOLD is JSON, .fold; drawings are .svg, .opx "
                                         "or .cp)");
    return CLI_EXIT_OK;
}

// frame_from: NULL when the frame is --frame, else the sequence file whose "frame" it is.
static int kin_load(const char *cmd, const char *path, int frame, const cli_input *options, const char *frame_from,
                    cli_kin *k)
{
    memset(k, 0, sizeof *k);
    k->frame = frame;
    cli_input in;
    if (options) in = *options;
    else cli_input_init(&in);
    in.frame = 0; // the mechanism; `frame` is the start state
    in.frame_given = false;
    ori_format f = ori_format_from_path(path);
    if (frame != 0 && (f == ORI_FORMAT_SVG || f == ORI_FORMAT_OPX || f == ORI_FORMAT_CP)) {
        if (frame_from)
            return cli_input_fail(cmd, frame_from, "frame: %d names a frame, but the pattern %s is a drawing (no frames)",
                                  frame, path);
        return cli_usage(cmd, "--frame applies to .fold input, not to %s", path);
    }
    if (f == ORI_FORMAT_UNKNOWN) {
        int rc = not_a_pattern(cmd, path);
        if (rc != CLI_EXIT_OK) return rc;
    }
    int rc = cli_input_load(cmd, path, &in, &k->doc, &k->flat);
    if (rc != CLI_EXIT_OK) return rc;
    if ((ori_pattern_is_folded_form(k->flat) || ori_pattern_is_3d(k->flat)) && frame != 0 &&
        frame < ori_fold_frame_count(k->doc)) {
        // Frame 0 is folded but --frame names a flat crease pattern (Rabbit Ear keeps the kabuto's
        // in frame 9): that frame alone is the document, the mechanism and the flat start.
        ori_build_def bd = ori_default_build_def();
        bd.check_planarity = false;
        ori_pattern *cp = NULL;
        ori_fold *alone = NULL;
        ori_error e;
        if (ori_fold_get_pattern(k->doc, frame, &bd, &cp, &e) == ORI_OK && !ori_pattern_is_folded_form(cp) &&
            !ori_pattern_is_3d(cp) && ori_fold_extract_frame(k->doc, frame, &alone, &e) == ORI_OK) {
            ori_pattern *flat = NULL;
            if (ori_fold_get_pattern(alone, 0, NULL, &flat, &e) == ORI_OK) {
                ori_pattern_destroy(k->flat);
                ori_fold_destroy(k->doc);
                k->flat = flat;
                k->doc = alone;
                alone = NULL;
                k->frame = frame = 0;
            }
        }
        ori_fold_destroy(alone);
        ori_pattern_destroy(cp);
    }
    if (ori_pattern_is_folded_form(k->flat) || ori_pattern_is_3d(k->flat)) {
        cli_kin_free(k);
        return cli_input_fail(cmd, path, "frame 0 is a folded form: the kinematics needs the flat crease pattern there "
                                         "(or --frame N naming a crease-pattern frame); run 'orikin unfold FILE -o cp.fold' "
                                         "to get its crease pattern (the folded state is kept as frame 1), then fold cp.fold");
    }
    ori_error err;
    // Kirigami: the cuts are boundaries inside the sheet, their two sides move apart; each side
    // gets its own vertices (ori_pattern_open_cuts), so that every folded state has one position
    // per vertex. Frame 0 (and so every -o frame) is the opened pattern.
    ori_pattern *opened = NULL;
    int added = 0;
    if (ori_pattern_open_cuts(k->flat, &opened, &added, &err) != ORI_OK) {
        cli_kin_free(k);
        return cli_input_error(cmd, path, &err);
    }
    if (added > 0) {
        ori_pattern_destroy(k->flat);
        k->flat = opened;
        fprintf(stderr, "orikin %s: %s: note: the cuts are opened (%d vertices added, one per side of a cut; indices "
                        "before them kept)\n", cmd, path, added);
    } else {
        ori_pattern_destroy(opened);
    }
    // Frame 0 as loaded, with the faces the mechanism uses (traced when the file had none), so
    // that folded frames written later inherit faces_vertices and stay readable.
    if (ori_fold_set_pattern(k->doc, 0, k->flat, &err) != ORI_OK) {
        cli_kin_free(k);
        return cli_input_error(cmd, path, &err);
    }
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = k->flat;
    if (ori_mechanism_create(&md, &k->mech, &err) != ORI_OK) {
        cli_kin_free(k);
        return cli_input_error(cmd, path, &err);
    }
    int ne = ori_pattern_edge_count(k->flat), nv = ori_pattern_vertex_count(k->flat);
    k->angles = calloc((size_t)ne + 1, sizeof(double));
    k->coords = calloc((size_t)nv + 1, sizeof(ori_v3));
    ori_pattern *state = k->flat;
    ori_pattern *other = NULL;
    if (frame != 0) {
        int frames = ori_fold_frame_count(k->doc);
        if (frame < 0 || frame >= frames) {
            cli_kin_free(k);
            if (frame_from) // the sequence file's field, not an option
                return cli_input_fail(cmd, frame_from, "frame: frame %d does not exist in %s (frames 0 to %d)", frame, path,
                                      frames - 1);
            return cli_value_fail(cmd, path, "--frame", "frame %d does not exist (frames 0 to %d)", frame, frames - 1);
        }
        ori_build_def bd = ori_default_build_def();
        bd.check_planarity = false;
        if (ori_fold_get_pattern(k->doc, frame, &bd, &other, &err) != ORI_OK) {
            char buf[512];
            ori_error_format(&err, buf, sizeof buf);
            cli_kin_free(k);
            return cli_input_fail(cmd, path, "frame %d: %s", frame, buf);
        }
        if (ori_pattern_edge_count(other) != ne || ori_pattern_vertex_count(other) != nv) {
            ori_pattern_destroy(other);
            cli_kin_free(k);
            return cli_input_fail(cmd, path, "frame %d has %s from frame 0: not a state of the same pattern", frame,
                                  "different vertices or edges");
        }
        state = other;
    }
    // A flat crease-pattern frame is the flat state whatever its edges_foldAngle says: there the
    // angles are targets (Origami Simulator, FOLD creasePattern files), not the geometry. A folded
    // frame (3D, or foldedForm) gives the start angles.
    bool folded_state = ori_pattern_is_folded_form(state) || ori_pattern_is_3d(state);
    for (int e = 0; e < ne; ++e) k->angles[e] = folded_state ? ori_pattern_edge(state, e).fold_angle_rad : 0.0;
    for (int v = 0; v < nv; ++v) k->coords[v] = ori_pattern_vertex(state, v);
    k->folded = ori_pattern_is_3d(state);
    ori_pattern_destroy(other);
    return CLI_EXIT_OK;
}

int cli_kin_fixed_pose(const char *cmd, const char *path, const cli_kin *k, int face, ori_rigid *pose)
{
    *pose = ori_rigid_identity();
    if (!k->folded) return CLI_EXIT_OK;
    ori_error err;
    if (ori_mechanism_face_pose_from_coords(k->mech, face, k->coords, pose, &err) != ORI_OK)
        return cli_input_error(cmd, path, &err);
    return CLI_EXIT_OK;
}

static int parse_angle(const char *cmd, const char *opt, const char *v, double *out)
{
    if (!cli_parse_double(v, out)) return cli_usage(cmd, "%s needs an angle in degrees, got '%s'", opt, v);
    return CLI_EXIT_OK;
}

int cli_fold_parse(const char *cmd, int argc, char **argv, bool fit, cli_fold_args *a)
{
    memset(a, 0, sizeof *a);
    a->step_deg = 10.0;
    a->solver = ORI_SOLVER_AUTO;
    a->linear = ORI_LINEAR_AUTO;
    a->degree = 4;
    a->refine = 10;
    cli_input_init(&a->input);
    cli_seen seen = {0};
    for (int i = 1; i < argc; ++i) {
        const char *o = argv[i];
        const char *v = NULL;
        int rc;
        if (strcmp(o, "--json") == 0) {
            a->json = true;
            continue;
        }
        if (strcmp(o, "--frame") != 0) { // --frame is the start state here (below)
            int r = cli_input_option(cmd, argc, argv, &i, &a->input, &seen);
            if (r < 0) return -r;
            if (r > 0) continue;
        }
        bool takes = strcmp(o, "--fix") == 0 || strcmp(o, "--drive") == 0 || strcmp(o, "--to") == 0 ||
                     strcmp(o, "--from") == 0 || strcmp(o, "--step") == 0 || strcmp(o, "--lock") == 0 ||
                     strcmp(o, "--frame") == 0 || strcmp(o, "--solver") == 0 || strcmp(o, "--linear") == 0 ||
                     strcmp(o, "-o") == 0 || (fit && (strcmp(o, "--degree") == 0 || strcmp(o, "--refine") == 0));
        if (takes) {
            v = cli_option_once(cmd, argc, argv, &i, &seen);
            if (!v) return CLI_EXIT_USAGE;
        }
        if (strcmp(o, "--fix") == 0) {
            a->fix_spec = v; // an index, a name or @x,y: cli_fold_resolve
            a->has_fix = true;
        } else if (strcmp(o, "--drive") == 0) {
            if (cli_spec_edge_count(v) != 1) return cli_usage(cmd, "--drive needs an edge index or @x,y, got '%s'", v);
            a->drive_spec = v;
            a->has_drive = true;
        } else if (strcmp(o, "--to") == 0) {
            if ((rc = parse_angle(cmd, o, v, &a->to_deg)) != CLI_EXIT_OK) return rc;
            a->has_to = true;
        } else if (strcmp(o, "--from") == 0) {
            if ((rc = parse_angle(cmd, o, v, &a->from_deg)) != CLI_EXIT_OK) return rc;
            a->has_from = true;
        } else if (strcmp(o, "--step") == 0) {
            if ((rc = parse_angle(cmd, o, v, &a->step_deg)) != CLI_EXIT_OK) return rc;
        } else if (strcmp(o, "--lock") == 0 && strcmp(v, "auto") == 0) {
            a->lock_auto = true; // cli_fold_resolve
        } else if (strcmp(o, "--lock") == 0) {
            int cap = (int)(sizeof a->locks / sizeof *a->locks), n = cli_spec_edge_count(v);
            if (n > cap) return cli_usage(cmd, "--lock takes at most %d edges, got %d", cap, n);
            if (n < 0) return cli_usage(cmd, "--lock: creases are indices or @x,y, comma-separated, got '%s'", v);
            a->lock_spec = v; // indices and @x,y: cli_fold_resolve
        } else if (strcmp(o, "--frame") == 0) {
            if (!cli_parse_int(v, &a->frame) || a->frame < 0) return cli_usage(cmd, "--frame needs a frame number >= 0");
        } else if (strcmp(o, "-o") == 0) {
            a->out = v;
        } else if (strcmp(o, "--solver") == 0) {
            if (strcmp(v, "auto") == 0) a->solver = ORI_SOLVER_AUTO;
            else if (strcmp(v, "analytic") == 0) a->solver = ORI_SOLVER_ANALYTIC;
            else if (strcmp(v, "numeric") == 0) a->solver = ORI_SOLVER_NUMERIC;
            else return cli_usage(cmd, "--solver is auto, analytic or numeric, got '%s'", v);
        } else if (strcmp(o, "--linear") == 0) {
            if (strcmp(v, "auto") == 0) a->linear = ORI_LINEAR_AUTO;
            else if (strcmp(v, "dense") == 0) a->linear = ORI_LINEAR_DENSE;
            else if (strcmp(v, "sparse") == 0) a->linear = ORI_LINEAR_SPARSE;
            else if (strcmp(v, "sweep") == 0) a->linear = ORI_LINEAR_SWEEP;
            else return cli_usage(cmd, "--linear is auto, dense, sparse or sweep, got '%s'", v);
        } else if (strcmp(o, "--degree") == 0) {
            if (!cli_parse_int(v, &a->degree)) return cli_usage(cmd, "--degree needs an integer, got '%s'", v);
        } else if (strcmp(o, "--refine") == 0) {
            if (!cli_parse_int(v, &a->refine)) return cli_usage(cmd, "--refine needs an integer, got '%s'", v);
        } else if (o[0] == '-' && o[1] != '\0') {
            return cli_usage(cmd, "unknown option %s", o);
        } else if (!a->path) {
            a->path = o;
        } else {
            return cli_usage(cmd, "one FILE only");
        }
    }
    if (!a->path) return cli_usage(cmd, "missing FILE");
    // A file that is no pattern at all is said first (orikin fold pic.png), before what is missing.
    if (ori_format_from_path(a->path) == ORI_FORMAT_UNKNOWN && not_a_pattern(cmd, a->path) != CLI_EXIT_OK) return CLI_EXIT_INPUT;
    if (!a->has_drive) return cli_usage(cmd, "missing --drive EDGE");
    if (!a->has_to) return cli_usage(cmd, "missing --to DEG");
    if (!(fabs(a->to_deg) <= 180.0)) return cli_usage(cmd, "--to %g is outside [-180, 180] degrees", a->to_deg);
    if (a->has_from && !(fabs(a->from_deg) <= 180.0))
        return cli_usage(cmd, "--from %g is outside [-180, 180] degrees", a->from_deg);
    if (!(a->step_deg > 0.0)) return cli_usage(cmd, "--step must be a positive angle in degrees, got %g", a->step_deg);
    return CLI_EXIT_OK;
}

// --- naming faces and creases: one code path for every command ----------------------------------


int cli_spec_face(const char *cmd, const char *path, const ori_pattern *p, const char *option, const char *spec,
                  int *face)
{
    int idx;
    if (cli_parse_int(spec, &idx)) {
        int faces = ori_pattern_face_count(p);
        if (idx < 0 || idx >= faces)
            return cli_value_fail(cmd, path, option, "no face %d (the pattern has faces 0 to %d)", idx, faces - 1);
        *face = idx;
        return CLI_EXIT_OK;
    }
    if (spec[0] != '@') return cli_find_face_option(cmd, path, p, option, spec, face); // a name
    double xy[2];
    if (!cli_parse_doubles(spec + 1, xy, 2))
        return cli_usage(cmd, "%s: a face is an index, a name or @x,y, got '%s'", option, spec);
    bool on_edge;
    int f = ori_pattern_find_face_at(p, ori_v2_make(xy[0], xy[1]), &on_edge);
    if (f != ORI_NULL_INDEX && on_edge)
        return cli_value_fail(cmd, path, option, "(%g, %g) lies on an edge of face %d: give a point inside a face",
                              xy[0], xy[1], f);
    if (f != ORI_NULL_INDEX) {
        *face = f;
        return CLI_EXIT_OK;
    }
    return cli_value_fail(cmd, path, option, "no face contains (%g, %g) (see orikin info --faces)", xy[0], xy[1]);
}

int cli_fold_default_fix(const ori_pattern *p) { return ori_pattern_center_face(p); }

int cli_spec_edge(const char *cmd, const char *path, const ori_pattern *p, const char *option, const char *spec,
                  int *edge)
{
    int idx;
    if (cli_parse_int(spec, &idx)) {
        int edges = ori_pattern_edge_count(p);
        if (idx < 0 || idx >= edges)
            return cli_value_fail(cmd, path, option, "no edge %d (the pattern has edges 0 to %d)", idx, edges - 1);
        *edge = idx;
        return CLI_EXIT_OK;
    }
    double xy[2];
    if (spec[0] != '@' || !cli_parse_doubles(spec + 1, xy, 2))
        return cli_usage(cmd, "%s: a crease is an index or @x,y, got '%s'", option, spec);
    int e = ori_pattern_find_edge_at(p, ori_v2_make(xy[0], xy[1]));
    if (e == ORI_NULL_INDEX)
        return cli_value_fail(cmd, path, option, "no crease passes through (%g, %g) (see orikin info --edges)", xy[0],
                              xy[1]);
    *edge = e;
    return CLI_EXIT_OK;
}

// The next item of a crease list at *q (copied into item): "@x,y" spans two comma-separated
// fields. Advances *q past the item and its comma; false on an empty or overlong item.
static bool next_item(const char **q, char *item, size_t size)
{
    const char *s = *q, *c = strchr(s, ',');
    if (*s == '@' && c) c = strchr(c + 1, ',');
    size_t len = c ? (size_t)(c - s) : strlen(s);
    if (len == 0 || len >= size) return false;
    memcpy(item, s, len);
    item[len] = '\0';
    *q = c ? c + 1 : s + len;
    return !(c && c[1] == '\0'); // a trailing comma is an empty item
}

int cli_spec_edge_count(const char *spec)
{
    const char *q = spec;
    char item[128];
    int n = 0;
    while (*q) {
        if (!next_item(&q, item, sizeof item)) return -1;
        int idx;
        double xy[2];
        if (!cli_parse_int(item, &idx) && !(item[0] == '@' && cli_parse_doubles(item + 1, xy, 2))) return -1;
        n++;
    }
    return n > 0 ? n : -1;
}

int cli_spec_edges(const char *cmd, const char *path, const ori_pattern *p, const char *option, const char *spec,
                   bool unique, int *out, int cap)
{
    int n = cli_spec_edge_count(spec);
    if (n < 0) return -cli_usage(cmd, "%s: creases are indices or @x,y, comma-separated, got '%s'", option, spec);
    if (n > cap) return -cli_usage(cmd, "%s takes at most %d edges, got %d", option, cap, n);
    const char *q = spec;
    char item[128];
    int count = 0, rc;
    while (*q) {
        next_item(&q, item, sizeof item);
        int e;
        if ((rc = cli_spec_edge(cmd, path, p, option, item, &e)) != CLI_EXIT_OK) return -rc;
        bool dup = false; // the same crease by index and by point
        for (int j = 0; unique && j < count; ++j) dup |= out[j] == e;
        if (!dup) out[count++] = e;
    }
    return count;
}

int cli_fold_resolve(const char *cmd, cli_fold_args *a, const cli_kin *k)
{
    const ori_pattern *p = k->flat;
    int rc;
    if (a->fix_spec && (rc = cli_spec_face(cmd, a->path, p, "--fix", a->fix_spec, &a->fix)) != CLI_EXIT_OK) return rc;
    if (!a->has_fix) { // no --fix: the face at the sheet's centre
        a->fix = cli_fold_default_fix(p);
        a->fix_default = true;
    }
    if (a->drive_spec && (rc = cli_spec_edge(cmd, a->path, p, "--drive", a->drive_spec, &a->drive)) != CLI_EXIT_OK)
        return rc;
    if (a->lock_spec) {
        int n = cli_spec_edges(cmd, a->path, p, "--lock", a->lock_spec, true, a->locks,
                               (int)(sizeof a->locks / sizeof *a->locks));
        if (n < 0) return -n;
        a->lock_count = n;
    }
    if (a->lock_auto) { // the lock set that leaves the drive one degree of freedom
        int E = ori_mechanism_edge_count(k->mech);
        if (a->drive < 0 || a->drive >= E)
            return cli_value_fail(cmd, a->path, "--drive", "no edge %d (the pattern has edges 0 to %d)", a->drive, E - 1);
        ori_error err;
        int n = ori_mechanism_lock_set(k->mech, k->angles, &a->drive, 1, NULL, 0, NULL, a->locks,
                                       (int)(sizeof a->locks / sizeof *a->locks), &err);
        if (n < 0) return cli_input_error(cmd, a->path, &err);
        if (n == 0) return cli_usage(cmd, "--lock auto: nothing to lock, the drive leaves no freedom");
        a->lock_count = n;
    }
    a->fix_spec = a->drive_spec = a->lock_spec = NULL; // resolved
    return CLI_EXIT_OK;
}

int cli_fold_solve_error(const char *cmd, const cli_fold_args *a, ori_status st, const ori_error *err)
{
    // The driven or a locked crease that the fold cannot use is the command line's value.
    if (st == ORI_ERR_ARGUMENT && strcmp(err->field, "edges_vertices") == 0 && err->element >= 0) {
        bool locked = false;
        for (int i = 0; i < a->lock_count; ++i) locked |= a->locks[i] == err->element;
        if (locked) return cli_value_fail(cmd, a->path, "--lock", "%s", err->message);
        if (err->element == a->drive) return cli_value_fail(cmd, a->path, "--drive", "%s", err->message);
    }
    int rc = cli_input_error(cmd, a->path, err);
    return st == ORI_ERR_NOT_CONVERGED || st == ORI_ERR_INTERNAL ? CLI_EXIT_INTERNAL : rc;
}

int cli_fold_def(const char *cmd, const cli_fold_args *a, const cli_kin *k, ori_motion_def *def)
{
    const ori_mechanism *m = k->mech;
    int faces = ori_mechanism_face_count(m), edges = ori_mechanism_edge_count(m);
    const char *spec = a->fix_spec ? a->fix_spec : a->drive_spec ? a->drive_spec : a->lock_spec;
    if (spec) // a caller that does not resolve names and points (cli_fold_resolve)
        return cli_usage(cmd, "'%s': faces and creases named but not resolved (cli_fold_resolve)", spec);
    // Indices the pattern does not have are command-line values out of range (usage, exit 2).
    if (a->fix < 0 || a->fix >= faces)
        return cli_value_fail(cmd, a->path, "--fix", "no face %d (the pattern has faces 0 to %d)", a->fix, faces - 1);
    if (a->drive < 0 || a->drive >= edges)
        return cli_value_fail(cmd, a->path, "--drive", "no edge %d (the pattern has edges 0 to %d)", a->drive,
                              edges - 1);
    for (int i = 0; i < a->lock_count; ++i)
        if (a->locks[i] < 0 || a->locks[i] >= edges)
            return cli_value_fail(cmd, a->path, "--lock", "no edge %d (the pattern has edges 0 to %d)", a->locks[i],
                                  edges - 1);
    if (!(fabs(a->to_deg) <= 180.0)) return cli_usage(cmd, "--to %g is outside [-180, 180] degrees", a->to_deg);
    if (a->has_from && !(fabs(a->from_deg) <= 180.0))
        return cli_usage(cmd, "--from %g is outside [-180, 180] degrees", a->from_deg);
    if (!(a->step_deg > 0.0)) return cli_usage(cmd, "--step must be a positive angle in degrees, got %g", a->step_deg);
    *def = ori_default_motion_def();
    def->fixed_face = a->fix;
    int rc = cli_kin_fixed_pose(cmd, a->path, k, a->fix, &def->fixed_pose);
    if (rc != CLI_EXIT_OK) return rc;
    def->start_angles_rad = k->angles;
    def->driven_edge = a->drive;
    def->has_from = a->has_from;
    def->from_rad = ori_deg_to_rad(a->from_deg);
    def->to_rad = ori_deg_to_rad(a->to_deg);
    def->step_rad = ori_deg_to_rad(a->step_deg);
    def->locked_edges = a->locks;
    def->locked_count = a->lock_count;
    def->solver = a->solver;
    def->linear = a->linear;
    return CLI_EXIT_OK;
}
