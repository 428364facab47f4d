// State selection: the options naming a state (a FOLD frame, a fold, a sequence instant), the
// posed sheet they give, and the frames of a motion. See state_args.h.
#include "state_args.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fold_compliant.h"
#include "fold_modes.h"
#include "progress.h"

// The fold options (with a value), those of the modes included; --symmetric takes none.
static const char *const fold_options[] = {"--fix",    "--drive",  "--to",     "--from",    "--step",
                                           "--lock",   "--solver", "--linear", "--percent", "--ratio",
                                           // a compliant fold's (--compliant)
                                           "--preset", "--axial",  "--facet",  "--crease",  "--damping",
                                           "--gravity", "--steps", "--threads"};

void cli_state_args_init(cli_state_args *a)
{
    memset(a, 0, sizeof *a);
    a->frame = 0;
    a->source = CLI_STATE_FRAME;
}

static bool is_fold_option(const char *o)
{
    for (size_t k = 0; k < sizeof fold_options / sizeof fold_options[0]; ++k)
        if (strcmp(o, fold_options[k]) == 0) return true;
    return false;
}

int cli_state_option(const char *cmd, int argc, char **argv, int *i, cli_state_args *a, int *rc)
{
    const char *o = argv[*i];
    *rc = CLI_EXIT_OK;
    if (strcmp(o, "--frame") == 0) {
        if (a->has_frame) {
            *rc = cli_usage(cmd, "--frame given twice");
            return -1;
        }
        if ((*rc = cli_option_frame(cmd, argc, argv, i, &a->frame)) != CLI_EXIT_OK) return -1;
        a->has_frame = true;
        return 1;
    }
    if (strcmp(o, "--at") == 0) {
        if (a->has_at) {
            *rc = cli_usage(cmd, "--at given twice");
            return -1;
        }
        const char *v = cli_option_value(cmd, argc, argv, i);
        if (!v) {
            *rc = CLI_EXIT_USAGE;
            return -1;
        }
        if (!cli_parse_double(v, &a->at) || a->at < 0.0) {
            *rc = cli_usage(cmd, "--at needs a sequence time T >= 0, got '%s'", v);
            return -1;
        }
        a->has_at = true;
        return 1;
    }
    bool flag = strcmp(o, "--symmetric") == 0 || strcmp(o, "--compliant") == 0 || strcmp(o, "--dynamic") == 0;
    if (flag || is_fold_option(o)) {
        for (int k = 2; k < a->fold_argc; ++k) // options and values: a value never starts with "--"
            if (strcmp(a->fold_argv[k], o) == 0) {
                *rc = cli_usage(cmd, "%s given twice", o);
                return -1;
            }
        if (flag) {
            if (a->fold_argc == 0) a->fold_argc = 2;
            if (a->fold_argc + 1 > CLI_STATE_MAX_FOLD_ARGS) {
                *rc = cli_usage(cmd, "too many fold options");
                return -1;
            }
            a->fold_argv[a->fold_argc++] = (char *)o;
            return 1;
        }
        const char *v = cli_option_value(cmd, argc, argv, i);
        if (!v) {
            *rc = CLI_EXIT_USAGE;
            return -1;
        }
        if (a->fold_argc == 0) a->fold_argc = 2; // [0] = command, [1] = IN, filled by finish
        if (a->fold_argc + 2 > CLI_STATE_MAX_FOLD_ARGS) {
            *rc = cli_usage(cmd, "too many fold options");
            return -1;
        }
        a->fold_argv[a->fold_argc++] = (char *)o;
        a->fold_argv[a->fold_argc++] = (char *)v;
        return 1;
    }
    if ((o[0] != '-' || o[1] == '\0') && !a->path) {
        a->path = o;
        return 1;
    }
    return 0;
}

static bool ends_with_ci(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    if (n < k) return false;
    for (size_t i = 0; i < k; ++i)
        if (tolower((unsigned char)s[n - k + i]) != suffix[i]) return false;
    return true;
}

// A fold sequence is a JSON object with "folds"; anything else goes to the FOLD reader (which
// reports what is wrong with it).
static bool is_sequence_file(const char *path)
{
    if (ends_with_ci(path, ".fold")) return false;
    json_error_t jerr;
    json_t *root = json_load_file(path, 0, &jerr);
    bool seq = root && json_is_object(root) && json_object_get(root, "folds") != NULL;
    json_decref(root);
    return seq;
}

int cli_state_finish(const char *cmd, cli_state_args *a)
{
    if (!a->path) return cli_usage(cmd, "missing IN (a FOLD file or a fold sequence SEQ.json)");
    if (is_sequence_file(a->path)) {
        if (a->has_frame) return cli_usage(cmd, "--frame is for FOLD files (a sequence names its own start frame)");
        if (a->fold_argc) return cli_usage(cmd, "fold options are for FOLD files (a sequence lists its folds)");
        a->source = CLI_STATE_SEQUENCE;
        return CLI_EXIT_OK;
    }
    if (a->has_at) return cli_usage(cmd, "--at is for fold sequences (SEQ.json)");
    if (!a->fold_argc) {
        a->source = CLI_STATE_FRAME;
        return CLI_EXIT_OK;
    }
    // The fold options as `orikin fold` takes them (with --frame: the fold's start frame).
    a->fold_argv[0] = (char *)cmd;
    a->fold_argv[1] = (char *)a->path;
    int n = a->fold_argc;
    if (a->has_frame) {
        if (n + 2 > CLI_STATE_MAX_FOLD_ARGS) return cli_usage(cmd, "too many fold options");
        snprintf(a->frame_text, sizeof a->frame_text, "%d", a->frame);
        a->fold_argv[n++] = (char *)"--frame";
        a->fold_argv[n++] = a->frame_text;
    }
    a->fold_argc_all = n;
    int rc;
    if (cli_fold_compliant_wanted(n, a->fold_argv)) {
        // The compliant fold of `orikin fold --compliant` (fold_compliant.c), from the flat sheet.
        if (a->has_frame) return cli_usage(cmd, "--compliant folds the flat sheet of frame 0: it takes no --frame");
        cli_compliant_request_init(&a->compliant_req);
        cli_seen seen = {0};
        for (int i = 2; i < n; ++i) {
            int r = cli_compliant_option(cmd, n, a->fold_argv, &i, &a->compliant_req, &a->compliant_fix, &seen);
            if (r < 0) return -r;
            if (r == 0)
                return cli_usage(cmd, "%s is not an option of a compliant fold (--compliant takes --percent, --fix, "
                                      "--dynamic, --preset, --axial, --facet, --crease, --damping, --gravity, --steps, "
                                      "--threads)", a->fold_argv[i]);
        }
        char mistake[200];
        if (cli_compliant_request_error(&a->compliant_req, mistake, sizeof mistake)) return cli_usage(cmd, "%s", mistake);
        a->compliant_req.all_frames = true; // every load step: the motion of animate and export --animate
        a->compliant = true;
        a->source = CLI_STATE_FOLD;
        return CLI_EXIT_OK;
    }
    if (cli_fold_modes_wanted(n, a->fold_argv)) {
        // Toward the targets, several drives, --lock auto, --symmetric: `orikin fold`'s modes
        // (fold_modes.c), parsed here for the usage errors and again when loading.
        cli_fold_modes *probe = NULL;
        if ((rc = cli_fold_modes_open(cmd, n, a->fold_argv, &probe)) != CLI_EXIT_OK) return rc;
        cli_fold_modes_free(probe);
        a->modes = true;
        a->source = CLI_STATE_FOLD;
        return CLI_EXIT_OK;
    }
    rc = cli_fold_parse(cmd, n, a->fold_argv, false, &a->fold);
    if (rc != CLI_EXIT_OK) return rc;
    a->source = CLI_STATE_FOLD;
    return CLI_EXIT_OK;
}

// --- loading ----------------------------------------------------------------------------------

void cli_state_free(cli_state *s)
{
    ori_motion_destroy(s->motion);
    ori_compliant_destroy(s->compliant);
    ori_record_destroy(s->record);
    ori_sequence_destroy(s->seq);
    if (s->modes) {
        // The pattern and the mechanism belong to the modes' solve.
        cli_fold_modes_free(s->modes);
    } else if (s->has_kin) {
        // The pattern and the mechanism belong to kin.
        cli_kin_free(&s->kin);
    } else {
        ori_mechanism_destroy(s->mech);
        ori_pattern_destroy(s->pattern);
        ori_fold_destroy(s->doc);
    }
    ori_pattern_destroy(s->frame_pattern);
    free(s->pattern_path);
    free(s->positions);
    free(s->poses);
    free(s->angles);
    free(s->face_orders);
    memset(s, 0, sizeof *s);
}

ori_state_view cli_state_view(const cli_state *s)
{
    ori_state_view v = {s->pattern, s->positions, s->angles};
    return v;
}

static void *xcalloc(size_t n, size_t size) { return calloc(n ? n : 1, size); }

static bool same_topology(const ori_pattern *a, const ori_pattern *b)
{
    return ori_pattern_vertex_count(a) == ori_pattern_vertex_count(b) && ori_pattern_edge_count(a) == ori_pattern_edge_count(b) &&
           ori_pattern_face_count(a) == ori_pattern_face_count(b);
}

static bool is_flat_pattern(const ori_pattern *p) { return !ori_pattern_is_folded_form(p) && !ori_pattern_is_3d(p); }

static int frame_error(const char *cmd, const char *path, int frame, const ori_error *err)
{
    char buf[512];
    ori_error_format(err, buf, sizeof buf);
    return cli_input_fail(cmd, path, "frame %d: %s", frame, buf);
}

// The frame's FOLD faceOrders ([f, g, s] triples, faces of the drawn pattern, s = ±1) into
// s->face_orders; none when the frame has no faceOrders. Input error naming the triple.
static int load_face_orders(const char *cmd, const char *path, int frame, cli_state *s)
{
    char *text = ori_fold_get_custom(s->doc, frame, "faceOrders");
    if (!text) return CLI_EXIT_OK;
    json_error_t jerr;
    json_t *root = json_loads(text, 0, &jerr);
    ori_buffer_free(text);
    if (!json_is_array(root)) {
        json_decref(root);
        return cli_input_fail(cmd, path, "frame %d: faceOrders is not an array", frame);
    }
    int nf = ori_pattern_face_count(s->pattern);
    size_t n = json_array_size(root);
    s->face_orders = xcalloc(3 * n, sizeof(int));
    for (size_t i = 0; i < n; ++i) {
        json_t *t = json_array_get(root, i);
        bool ok = json_is_array(t) && json_array_size(t) == 3;
        for (size_t k = 0; ok && k < 3; ++k) {
            json_t *x = json_array_get(t, k);
            ok = json_is_integer(x) || (json_is_real(x) && json_real_value(x) == floor(json_real_value(x)) &&
                                        fabs(json_real_value(x)) < 1e9);
            if (ok) s->face_orders[3 * i + k] = json_is_integer(x) ? (int)json_integer_value(x) : (int)json_real_value(x);
        }
        if (!ok) {
            json_decref(root);
            return cli_input_fail(cmd, path, "frame %d: faceOrders %zu: not a triple of integers [f, g, s]", frame, i);
        }
        int f = s->face_orders[3 * i], g = s->face_orders[3 * i + 1], o = s->face_orders[3 * i + 2];
        if (f < 0 || f >= nf || g < 0 || g >= nf || f == g || (o != 1 && o != -1)) {
            json_decref(root);
            return cli_input_fail(cmd, path,
                                  "frame %d: faceOrders %zu: [%d, %d, %d] is not an order of two faces (0 to %d) with s = 1 "
                                  "or -1",
                                  frame, i, f, g, o, nf - 1);
        }
    }
    s->face_order_count = (int)n;
    json_decref(root);
    return CLI_EXIT_OK;
}

static int load_frame_pose(const char *cmd, const cli_state_args *a, bool need_pose, cli_state *s);

static int load_frame(const char *cmd, const cli_state_args *a, bool need_pose, cli_state *s)
{
    int rc = load_frame_pose(cmd, a, need_pose, s);
    if (rc != CLI_EXIT_OK || !s->doc || s->frame_count <= a->frame || !s->pattern) return rc;
    return load_face_orders(cmd, a->path, a->frame, s);
}

static int load_frame_pose(const char *cmd, const cli_state_args *a, bool need_pose, cli_state *s)
{
    ori_error err;
    ori_pattern *p0 = NULL, *pf = NULL;
    int frame = a->frame;
    ori_format fmt = ori_format_from_path(a->path);
    if (fmt == ORI_FORMAT_SVG || fmt == ORI_FORMAT_OPX || fmt == ORI_FORMAT_CP) {
        // A drawing: its crease pattern, read as every command reads it (one frame).
        if (a->has_frame) return cli_usage(cmd, "--frame applies to .fold input, not to %s", a->path);
        cli_input in;
        cli_input_init(&in);
        int rc = cli_input_load(cmd, a->path, &in, &s->doc, &p0);
        if (rc != CLI_EXIT_OK) return rc;
        s->frame_count = 1;
    } else {
        if (ori_fold_load_file(a->path, &s->doc, &err) != ORI_OK) return cli_input_error(cmd, a->path, &err);
        s->frame_count = ori_fold_frame_count(s->doc);
        if (frame >= s->frame_count)
            return cli_input_fail(cmd, a->path, "frame %d does not exist (frames 0 to %d)", frame, s->frame_count - 1);
        if (ori_fold_get_pattern(s->doc, 0, NULL, &p0, &err) != ORI_OK)
            return frame == 0 ? cli_input_error(cmd, a->path, &err) : frame_error(cmd, a->path, 0, &err);
    }
    if (frame != 0) {
        ori_build_def bd = ori_default_build_def();
        bd.check_planarity = false;
        if (ori_fold_get_pattern(s->doc, frame, &bd, &pf, &err) != ORI_OK) {
            ori_pattern_destroy(p0);
            return frame_error(cmd, a->path, frame, &err);
        }
    }
    ori_pattern *p = pf ? pf : p0;
    snprintf(s->label, sizeof s->label, "frame %d", frame);
    if (is_flat_pattern(p)) {
        // A crease-pattern frame: posed from its own fold angles.
        if (pf) ori_pattern_destroy(p0);
        s->pattern = p;
        s->has_flat = true;
        s->cp_frame = true;
        int nv = ori_pattern_vertex_count(p), ne = ori_pattern_edge_count(p), nf = ori_pattern_face_count(p);
        s->angles = xcalloc((size_t)ne, sizeof(double));
        for (int e = 0; e < ne; ++e) {
            s->angles[e] = ori_pattern_edge(p, e).fold_angle_rad;
            if (s->angles[e] != 0.0) s->folded = true;
        }
        if (!need_pose) return CLI_EXIT_OK;
        s->positions = xcalloc((size_t)nv, sizeof(ori_v3));
        s->poses = xcalloc((size_t)nf, sizeof(ori_rigid));
        if (!s->folded) {
            for (int v = 0; v < nv; ++v) s->positions[v] = ori_pattern_vertex(p, v);
            for (int f = 0; f < nf; ++f) s->poses[f] = ori_rigid_identity();
            return CLI_EXIT_OK;
        }
        ori_mechanism_def md = ori_default_mechanism_def();
        md.pattern = p;
        if (ori_mechanism_create(&md, &s->mech, &err) != ORI_OK) return frame_error(cmd, a->path, frame, &err);
        double *closed = xcalloc((size_t)ne, sizeof(double));
        ori_status st = ori_mechanism_pose_state(s->mech, s->angles, 0, ori_rigid_identity(), closed, s->positions,
                                                 s->poses, &err);
        if (st == ORI_OK) memcpy(s->angles, closed, sizeof(double) * (size_t)ne);
        free(closed);
        if (st == ORI_ERR_ARGUMENT)
            return cli_input_fail(cmd, a->path,
                                  "frame %d: its edges_foldAngle are not a folded state (the loops around the vertices do "
                                  "not close): %sfold it with --fix, --drive and --to",
                                  frame, strcmp(cmd, "render") == 0 ? "draw the crease pattern with --view cp, or " : "");
        if (st != ORI_OK) return frame_error(cmd, a->path, frame, &err);
        return CLI_EXIT_OK;
    }
    // A folded form: drawn on frame 0's crease pattern when it is a state of it.
    s->folded = true;
    int nv = ori_pattern_vertex_count(p), ne = ori_pattern_edge_count(p);
    s->positions = xcalloc((size_t)nv, sizeof(ori_v3));
    for (int v = 0; v < nv; ++v) s->positions[v] = ori_pattern_vertex(p, v);
    if (ori_pattern_has_fold_angles(p)) {
        s->angles = xcalloc((size_t)ne, sizeof(double));
        for (int e = 0; e < ne; ++e) s->angles[e] = ori_pattern_edge(p, e).fold_angle_rad;
    }
    if (pf && is_flat_pattern(p0) && same_topology(p0, pf)) {
        s->frame_pattern = pf;
        s->pattern = p0;
        s->has_flat = true;
        ori_mechanism_def md = ori_default_mechanism_def();
        md.pattern = p0;
        if (ori_mechanism_create(&md, &s->mech, &err) != ORI_OK) s->mech = NULL;
        s->poses = cli_poses_from_positions(s->mech, s->positions);
    } else {
        if (pf) ori_pattern_destroy(p0);
        s->pattern = p;
        s->has_flat = false;
    }
    return CLI_EXIT_OK;
}

// Face poses of a state of a fold in one of the modes: forward kinematics from its fixed face.
// placed where the frame's positions have it.
static void modes_poses(const cli_state *s, const double *angles, const ori_v3 *pos, ori_rigid *poses)
{
    cli_pose_faces(s->mech, cli_fold_modes_fixed_face(s->modes), angles, pos, poses);
}

// A fold in one of the modes (--percent, several drives, --lock auto, --symmetric): its last
// frame (the goal, or where the motion stopped short: said on stderr).
static int load_modes(const char *cmd, const cli_state_args *a, cli_state *s)
{
    int rc = cli_fold_modes_open(cmd, a->fold_argc_all, (char **)a->fold_argv, &s->modes);
    if (rc == CLI_EXIT_OK) rc = cli_fold_modes_solve(s->modes);
    if (rc != CLI_EXIT_OK) return rc;
    cli_kin *k = cli_fold_modes_kin(s->modes);
    s->pattern = k->flat;
    s->mech = k->mech;
    s->has_flat = true;
    s->frame_count = 1;
    const ori_multifold *mf = cli_fold_modes_result(s->modes);
    int nf = ori_multifold_frame_count(mf);
    ori_multifold_verdict v = ori_multifold_verdict_of(mf);
    if ((v != ORI_MULTIFOLD_REACHED && nf < 2) || v == ORI_MULTIFOLD_INVALID_ASSIGNMENT) {
        fprintf(stderr, "orikin %s: %s: the fold is %s: %s\n", cmd, a->path, ori_multifold_verdict_name(v),
                ori_multifold_reason(mf));
        return CLI_EXIT_NEGATIVE;
    }
    if (v != ORI_MULTIFOLD_REACHED)
        fprintf(stderr, "orikin %s: note: %s: the fold stops short (%s: %s); showing where it stops, %.3g %% of the way\n",
                cmd, a->path, ori_multifold_verdict_name(v), ori_multifold_reason(mf),
                100.0 * ori_multifold_frame_progress(mf, nf - 1));
    if (cli_fold_modes_fix_default(s->modes))
        fprintf(stderr, "orikin %s: note: face %d fixed%s\n", cmd, cli_fold_modes_fixed_face(s->modes),
                CLI_FOLD_DEFAULT_FIX_NOTE);
    int V = ori_mechanism_vertex_count(s->mech), E = ori_mechanism_edge_count(s->mech), F = ori_mechanism_face_count(s->mech);
    s->positions = xcalloc((size_t)V, sizeof(ori_v3));
    s->poses = xcalloc((size_t)F, sizeof(ori_rigid));
    s->angles = xcalloc((size_t)E, sizeof(double));
    ori_multifold_frame_vertices(mf, nf - 1, s->positions);
    memcpy(s->angles, ori_multifold_frame_angles(mf, nf - 1), sizeof(double) * (size_t)E);
    modes_poses(s, s->angles, s->positions, s->poses);
    s->folded = true;
    char what[128];
    cli_fold_modes_label(s->modes, what, sizeof what);
    snprintf(s->label, sizeof s->label, "%s", what);
    return CLI_EXIT_OK;
}

// A compliant fold (--compliant): the model's state at the end of its load steps (or where the
// explicit solver stopped), every load step kept for the motion. Its faces bend: no face poses.
static int load_compliant(const char *cmd, const cli_state_args *a, cli_state *s)
{
    cli_input in;
    cli_input_init(&in);
    int rc = cli_input_load(cmd, a->path, &in, &s->doc, &s->pattern);
    if (rc != CLI_EXIT_OK) return rc;
    s->has_flat = true;
    s->frame_count = 1;
    cli_compliant_request r = a->compliant_req;
    if (a->compliant_fix && (rc = cli_spec_face(cmd, a->path, s->pattern, "--fix", a->compliant_fix, &r.fix)) != CLI_EXIT_OK)
        return rc;
    ori_error err, why;
    bool reached = false;
    int steps = 0;
    cli_progress bar;
    cli_progress_begin(&bar, cmd, r.dynamic ? "compliant fold: explicit dynamics" : "compliant fold: static equilibrium");
    ori_status st = cli_compliant_solve(s->pattern, &r, &s->compliant, &reached, &steps, &why, &err);
    cli_progress_end(&bar);
    if (st != ORI_OK) return cli_input_error(cmd, a->path, &err);
    double fraction = ori_compliant_fraction(s->compliant);
    if (!reached)
        fprintf(stderr, "orikin %s: note: %s: the compliant fold stops short (%s); showing where it stops, %.3g %% of the way\n",
                cmd, a->path, why.message, 100.0 * fraction);
    int V = ori_pattern_vertex_count(s->pattern), E = ori_pattern_edge_count(s->pattern);
    s->positions = xcalloc((size_t)V, sizeof(ori_v3));
    s->angles = xcalloc((size_t)E, sizeof(double));
    memcpy(s->positions, ori_compliant_positions(s->compliant), sizeof(ori_v3) * (size_t)V);
    for (int e = 0; e < E; ++e) s->angles[e] = ori_compliant_fold_angle(s->compliant, e);
    s->folded = true;
    snprintf(s->label, sizeof s->label, "compliant fold, %.6g %% of the way to the targets", 100.0 * fraction);
    return CLI_EXIT_OK;
}

static int load_fold(const char *cmd, const cli_state_args *a, cli_state *s)
{
    int rc = cli_kin_load(cmd, a->fold.path, a->fold.frame, &s->kin);
    if (rc != CLI_EXIT_OK) return rc;
    s->has_kin = true;
    s->pattern = s->kin.flat;
    s->mech = s->kin.mech;
    s->has_flat = true;
    s->frame_count = 1;
    s->fold = a->fold; // names and points (--fix Obj12, --drive @x,y, --lock 3,@x,y) resolved
    if ((rc = cli_fold_resolve(cmd, &s->fold, &s->kin)) != CLI_EXIT_OK) return rc;
    ori_motion_def def;
    if ((rc = cli_fold_def(cmd, &s->fold, &s->kin, &def)) != CLI_EXIT_OK) return rc;
    ori_error err;
    ori_status st = ori_motion_solve(s->mech, &def, &s->motion, &err);
    if (st != ORI_OK) return cli_fold_solve_error(cmd, &s->fold, st, &err);
    ori_motion_verdict v = ori_motion_verdict_of(s->motion);
    int nf = ori_motion_frame_count(s->motion);
    if (v != ORI_MOTION_VALID || nf < 1) {
        const char *why = ori_motion_reason(s->motion);
        fprintf(stderr, "orikin %s: %s: the fold is %s%s%s\n", cmd, a->path, ori_motion_verdict_name(v), why ? ": " : "",
                why ? why : "");
        return CLI_EXIT_NEGATIVE;
    }
    s->start_drive_rad = s->fold.has_from ? ori_deg_to_rad(s->fold.from_deg) : s->kin.angles[s->fold.drive];
    int V = ori_mechanism_vertex_count(s->mech), E = ori_mechanism_edge_count(s->mech), F = ori_mechanism_face_count(s->mech);
    s->positions = xcalloc((size_t)V, sizeof(ori_v3));
    s->poses = xcalloc((size_t)F, sizeof(ori_rigid));
    s->angles = xcalloc((size_t)E, sizeof(double));
    ori_motion_frame_vertices(s->motion, nf - 1, s->positions);
    ori_motion_frame_face_poses(s->motion, nf - 1, s->poses);
    memcpy(s->angles, ori_motion_frame_angles(s->motion, nf - 1), sizeof(double) * (size_t)E);
    s->folded = true;
    snprintf(s->label, sizeof s->label, "crease %d folded to %g deg", s->fold.drive, s->fold.to_deg);
    return CLI_EXIT_OK;
}

// Face poses of a sequence state: forward kinematics from the fixed face of its fold, placed
// where the recorded positions have it.
static void sequence_poses(const cli_state *s, int fold, const double *angles, const ori_v3 *pos, ori_rigid *poses)
{
    cli_pose_faces(s->mech, ori_sequence_fold_at(s->seq, fold).fixed_face, angles, pos, poses);
}

static int load_sequence(const char *cmd, const cli_state_args *a, cli_state *s)
{
    ori_error err;
    if (ori_sequence_load_file(a->path, &s->seq, &err) != ORI_OK) return cli_input_error(cmd, a->path, &err);
    s->pattern_path = cli_path_beside(a->path, ori_sequence_pattern_path(s->seq));
    int rc = cli_kin_load_sequence(cmd, a->path, s->pattern_path, ori_sequence_frame(s->seq), &s->kin);
    if (rc != CLI_EXIT_OK) return rc;
    s->has_kin = true;
    s->pattern = s->kin.flat;
    s->mech = s->kin.mech;
    s->has_flat = true;
    s->frame_count = 1;
    if (ori_sequence_resolve(s->seq, s->kin.flat, &err) != ORI_OK) return cli_input_error(cmd, a->path, &err);
    ori_sequence_fold first = ori_sequence_fold_at(s->seq, 0);
    if (first.fixed_face < 0 || first.fixed_face >= ori_mechanism_face_count(s->mech))
        return cli_input_fail(cmd, a->path, "folds 0: fix: face %d does not exist (%d faces)", first.fixed_face,
                              ori_mechanism_face_count(s->mech));
    ori_rigid pose;
    if ((rc = cli_kin_fixed_pose(cmd, s->pattern_path, &s->kin, first.fixed_face, &pose)) != CLI_EXIT_OK) return rc;
    if (ori_sequence_run(s->seq, s->mech, s->kin.angles, pose, &s->record, &err) != ORI_OK)
        return cli_input_error(cmd, a->path, &err);
    if (ori_record_verdict(s->record) != ORI_MOTION_VALID) {
        const char *why = ori_record_reason(s->record);
        fprintf(stderr, "orikin %s: %s: fold %d is %s%s%s\n", cmd, a->path, ori_record_failed_fold(s->record) + 1,
                ori_motion_verdict_name(ori_record_verdict(s->record)), why ? ": " : "", why ? why : "");
        return CLI_EXIT_NEGATIVE;
    }
    double duration = ori_record_duration(s->record);
    double t = a->has_at ? a->at : duration;
    int V = ori_mechanism_vertex_count(s->mech), E = ori_mechanism_edge_count(s->mech), F = ori_mechanism_face_count(s->mech);
    s->positions = xcalloc((size_t)V, sizeof(ori_v3));
    s->poses = xcalloc((size_t)F, sizeof(ori_rigid));
    s->angles = xcalloc((size_t)E, sizeof(double));
    int fold = 0;
    ori_status st = ori_record_at(s->record, t, s->angles, s->positions, NULL, &fold, NULL, &err);
    if (st == ORI_ERR_RANGE) return cli_usage(cmd, "--at %g is outside the sequence's time, 0 to %g", t, duration);
    if (st != ORI_OK) return cli_input_error(cmd, a->path, &err);
    sequence_poses(s, fold, s->angles, s->positions, s->poses);
    s->folded = true;
    snprintf(s->label, sizeof s->label, "t = %g", t);
    return CLI_EXIT_OK;
}

int cli_state_load(const char *cmd, const cli_state_args *a, bool need_pose, cli_state *s)
{
    memset(s, 0, sizeof *s);
    s->source = a->source;
    s->path = a->path;
    s->args = a;
    int rc;
    switch (a->source) {
    case CLI_STATE_FOLD: rc = a->compliant ? load_compliant(cmd, a, s) : a->modes ? load_modes(cmd, a, s) : load_fold(cmd, a, s); break;
    case CLI_STATE_SEQUENCE: rc = load_sequence(cmd, a, s); break;
    case CLI_STATE_FRAME:
    default: rc = load_frame(cmd, a, need_pose, s); break;
    }
    if (rc != CLI_EXIT_OK) cli_state_free(s);
    return rc;
}

int cli_state_collisions(const char *cmd, const cli_state *s, const cli_collide_opts *o, cli_collision *out)
{
    memset(out, 0, sizeof *out);
    if (s->source == CLI_STATE_SEQUENCE)
        return cli_collide_record(cmd, s->path, o, s->pattern, s->record, out);
    if (s->source != CLI_STATE_FOLD || s->compliant) return CLI_EXIT_OK; // (the model warns of its own contacts)
    if (s->modes) {
        int nlocks;
        const int *locks = cli_fold_modes_locks(s->modes, &nlocks);
        return cli_collide_multifold(cmd, s->path, o, s->pattern, cli_fold_modes_result(s->modes), locks, nlocks, out);
    }
    ori_motion_def def;
    int rc = cli_fold_def(cmd, &s->fold, &s->kin, &def);
    if (rc != CLI_EXIT_OK) return rc;
    return cli_collide_motion(cmd, s->path, o, s->pattern, s->mech, &def, s->motion, out);
}

// --- motions --------------------------------------------------------------------------------

// A FOLD file's states: after a crease-pattern frame 0, its folded frames; otherwise every frame.
static int motion_of_frames(const char *cmd, cli_state *s, int samples, cli_motion *m)
{
    ori_error err;
    ori_pattern *p0 = NULL;
    if (ori_fold_get_pattern(s->doc, 0, NULL, &p0, &err) != ORI_OK) return cli_input_error(cmd, s->path, &err);
    int first = is_flat_pattern(p0) && s->frame_count > 1 ? 1 : 0;
    ori_pattern_destroy(p0);
    int n = s->frame_count - first;
    if (n < 2)
        return cli_input_fail(cmd, s->path,
                              "it holds one state: nothing to animate (give a FOLD file with several frames, a fold "
                              "sequence SEQ.json, or fold options)");
    int V = ori_pattern_vertex_count(s->pattern), E = ori_pattern_edge_count(s->pattern), F = ori_pattern_face_count(s->pattern);
    cli_motion stored;
    memset(&stored, 0, sizeof stored);
    cli_motion_alloc(&stored, n, V, F, E, s->mech != NULL, true);
    bool all_timed = true, all_angles = true;
    ori_build_def bd = ori_default_build_def();
    bd.check_planarity = false;
    for (int i = 0; i < n; ++i) {
        int k = first + i;
        ori_pattern *p = NULL;
        if (ori_fold_get_pattern(s->doc, k, &bd, &p, &err) != ORI_OK) {
            cli_motion_free(&stored);
            return frame_error(cmd, s->path, k, &err);
        }
        if (!same_topology(p, s->pattern)) {
            ori_pattern_destroy(p);
            cli_motion_free(&stored);
            return cli_input_fail(cmd, s->path, "frame %d is not a state of the same pattern (other vertices, edges or faces)", k);
        }
        for (int v = 0; v < V; ++v) stored.positions[(size_t)i * V + v] = ori_pattern_vertex(p, v);
        if (ori_pattern_has_fold_angles(p))
            for (int e = 0; e < E; ++e) stored.angles[(size_t)i * E + e] = ori_pattern_edge(p, e).fold_angle_rad;
        else all_angles = false;
        ori_pattern_destroy(p);
        // orikin sequence writes "orikin:time"; orikin simulate "frame_time" (seconds).
        char *t = ori_fold_get_custom(s->doc, k, "orikin:time");
        if (!t) t = ori_fold_get_custom(s->doc, k, "frame_time");
        double tv;
        if (t && cli_parse_double(t, &tv)) stored.times[i] = tv;
        else all_timed = false;
        ori_buffer_free(t);
        if (stored.poses) {
            ori_rigid *pp = cli_poses_from_positions(s->mech, stored.positions + (size_t)i * V);
            if (pp) {
                memcpy(stored.poses + (size_t)i * F, pp, sizeof(ori_rigid) * (size_t)F);
                free(pp);
            } else {
                free(stored.poses);
                stored.poses = NULL;
            }
        }
    }
    for (int i = 1; i < n && all_timed; ++i) all_timed = stored.times[i] > stored.times[i - 1];
    if (!all_timed)
        for (int i = 0; i < n; ++i) stored.times[i] = (double)i / (n - 1);
    if (!all_angles) {
        free(stored.angles);
        stored.angles = NULL;
    }
    stored.duration = stored.times[n - 1] - stored.times[0];
    stored.sources = xcalloc((size_t)n, sizeof(int));
    for (int i = 0; i < n; ++i) stored.sources[i] = first + i;
    if (samples < 2) {
        *m = stored;
        return CLI_EXIT_OK;
    }
    // Evenly spaced times, each showing the stored frame nearest to it.
    cli_motion_alloc(m, samples, V, F, E, stored.poses != NULL, stored.angles != NULL);
    m->duration = stored.duration;
    m->sources = xcalloc((size_t)samples, sizeof(int));
    int j = 0;
    for (int i = 0; i < samples; ++i) {
        double t = stored.times[0] + stored.duration * i / (samples - 1);
        while (j + 1 < n && fabs(stored.times[j + 1] - t) <= fabs(stored.times[j] - t)) j++;
        m->times[i] = t;
        m->sources[i] = stored.sources[j];
        memcpy(m->positions + (size_t)i * V, stored.positions + (size_t)j * V, sizeof(ori_v3) * (size_t)V);
        if (m->poses) memcpy(m->poses + (size_t)i * F, stored.poses + (size_t)j * F, sizeof(ori_rigid) * (size_t)F);
        if (m->angles) memcpy(m->angles + (size_t)i * E, stored.angles + (size_t)j * E, sizeof(double) * (size_t)E);
    }
    cli_motion_free(&stored);
    return CLI_EXIT_OK;
}

static int motion_of_fold(const char *cmd, cli_state *s, const cli_state_args *a, int samples, cli_motion *m)
{
    ori_motion_def def;
    int rc = cli_fold_def(cmd, &s->fold, &s->kin, &def);
    if (rc != CLI_EXIT_OK) return rc;
    ori_error err;
    if (cli_motion_of_fold(s->mech, &def, s->motion, s->start_drive_rad, samples, m, &err) != ORI_OK)
        return cli_input_error(cmd, a->path, &err);
    return CLI_EXIT_OK;
}

// A fold in one of the modes: its frames timed by their progress toward the goal (0 … 1), or
// samples states at evenly spaced progress.
static int motion_of_modes(const char *cmd, cli_state *s, int samples, cli_motion *m)
{
    int nlocks = 0;
    const int *locks = cli_fold_modes_locks(s->modes, &nlocks);
    cli_progress pr;
    cli_progress_begin(&pr, cmd, "solving frames");
    ori_error err;
    ori_status st = cli_motion_of_multifold(s->mech, cli_fold_modes_result(s->modes), locks, nlocks,
                                            cli_fold_modes_fixed_face(s->modes), samples, cli_progress_fn, &pr, m, &err);
    cli_progress_end(&pr);
    return st == ORI_OK ? CLI_EXIT_OK : cli_input_error(cmd, s->path, &err);
}

// A compliant fold: its load steps (cli_motion_of_compliant).
static int motion_of_compliant(const char *cmd, cli_state *s, int samples, cli_motion *m)
{
    ori_error err;
    if (cli_motion_of_compliant(s->compliant, samples, m, &err) != ORI_OK) return cli_input_fail(cmd, s->path, "%s", err.message);
    return CLI_EXIT_OK;
}

static int motion_of_sequence(const char *cmd, cli_state *s, int samples, cli_motion *m)
{
    cli_progress pr;
    cli_progress_begin(&pr, cmd, "solving frames");
    ori_error err;
    ori_status st = cli_motion_of_record(s->mech, s->seq, s->record, samples, cli_progress_fn, &pr, m, &err);
    cli_progress_end(&pr);
    return st == ORI_OK ? CLI_EXIT_OK : cli_input_error(cmd, s->path, &err);
}

int cli_state_motion(const char *cmd, cli_state *s, int samples, cli_motion *m)
{
    memset(m, 0, sizeof *m);
    switch (s->source) {
    case CLI_STATE_FOLD:
        return s->compliant ? motion_of_compliant(cmd, s, samples, m)
               : s->modes   ? motion_of_modes(cmd, s, samples, m)
                            : motion_of_fold(cmd, s, s->args, samples, m);
    case CLI_STATE_SEQUENCE: return motion_of_sequence(cmd, s, samples, m);
    case CLI_STATE_FRAME:
    default: return motion_of_frames(cmd, s, samples, m);
    }
}
