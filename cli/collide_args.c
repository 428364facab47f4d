// Collision checks in the CLI: one state for `orikin collide`, and the motion checks that
// `orikin fold` and `orikin sequence` run after solving.
#include "collide_args.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "progress.h"

void cli_collide_state_free(cli_collide_state *s)
{
    ori_pattern_destroy(s->pattern);
    ori_fold_destroy(s->doc);
    free(s->positions);
    memset(s, 0, sizeof *s);
}

int cli_collide_state_load(const char *cmd, const char *path, int frame, cli_collide_state *s)
{
    memset(s, 0, sizeof *s);
    s->frame = frame;
    ori_error err;
    if (ori_fold_load_file(path, &s->doc, &err) != ORI_OK) return cli_input_error(cmd, path, &err);
    int frames = ori_fold_frame_count(s->doc);
    if (frame < 0 || frame >= frames) {
        cli_collide_state_free(s);
        return cli_input_fail(cmd, path, "frame %d does not exist (frames 0 to %d)", frame, frames - 1);
    }
    ori_build_def bd = ori_default_build_def();
    bd.check_planarity = false;
    bd.compute_faces = false;
    if (ori_fold_get_pattern(s->doc, frame, &bd, &s->pattern, &err) != ORI_OK) {
        int rc = cli_input_error(cmd, path, &err);
        cli_collide_state_free(s);
        return rc;
    }
    bool folded = ori_pattern_is_3d(s->pattern) || ori_pattern_is_folded_form(s->pattern) ||
                  ori_fold_frame_is_folded_form(s->doc, frame);
    int nv = ori_pattern_vertex_count(s->pattern);
    s->positions = malloc(sizeof(ori_v3) * (size_t)(nv + 1));
    if (folded) {
        if (ori_pattern_face_count(s->pattern) == 0) {
            cli_collide_state_free(s);
            return cli_input_fail(cmd, path, "faces_vertices: frame %d is a folded form without faces", frame);
        }
        for (int v = 0; v < nv; ++v) s->positions[v] = ori_pattern_vertex(s->pattern, v);
        return CLI_EXIT_OK;
    }
    if (!ori_pattern_has_fold_angles(s->pattern)) {
        cli_collide_state_free(s);
        return cli_input_fail(cmd, path,
                              "frame %d has neither 3D vertices_coords nor edges_foldAngle: there is no folded state to check",
                              frame);
    }
    // A crease pattern with fold angles: build it as a flat sheet (faces traced when missing) and
    // pose it by forward kinematics from face 0.
    ori_pattern_destroy(s->pattern);
    s->pattern = NULL;
    if (ori_fold_get_pattern(s->doc, frame, NULL, &s->pattern, &err) != ORI_OK) {
        int rc = cli_input_error(cmd, path, &err);
        cli_collide_state_free(s);
        return rc;
    }
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = s->pattern;
    ori_mechanism *m = NULL;
    if (ori_mechanism_create(&md, &m, &err) != ORI_OK) {
        int rc = cli_input_error(cmd, path, &err);
        cli_collide_state_free(s);
        return rc;
    }
    int ne = ori_pattern_edge_count(s->pattern);
    double *angles = malloc(sizeof(double) * (size_t)(ne + 1));
    for (int e = 0; e < ne; ++e) angles[e] = ori_pattern_edge(s->pattern, e).fold_angle_rad;
    ori_status st = ori_mechanism_pose_state(m, angles, 0, ori_rigid_identity(), NULL, s->positions, NULL, &err);
    free(angles);
    ori_mechanism_destroy(m);
    if (st != ORI_OK) {
        char buf[512];
        ori_error_format(&err, buf, sizeof buf);
        cli_collide_state_free(s);
        return cli_input_fail(cmd, path, "edges_foldAngle: frame %d cannot be posed: %s", frame, buf);
    }
    s->posed = true;
    return CLI_EXIT_OK;
}

int cli_collide_option(const char *cmd, int argc, char **argv, int *i, cli_collide_opts *o)
{
    if (strcmp(argv[*i], "--no-collisions") == 0) {
        o->skip = true;
        return 1;
    }
    if (strcmp(argv[*i], "--clearance") != 0) return 0;
    if (o->has_clearance) {
        cli_usage(cmd, "--clearance given twice");
        return -1;
    }
    const char *v = cli_option_value(cmd, argc, argv, i);
    if (!v) return -1;
    if (!cli_parse_double(v, &o->clearance)) {
        cli_usage(cmd, "--clearance needs a length, got '%s'", v);
        return -1;
    }
    o->has_clearance = true;
    o->raw = v;
    return 1;
}

int cli_collide_strip(const char *cmd, int *argc, char **argv, cli_collide_opts *o)
{
    memset(o, 0, sizeof *o);
    int w = 1;
    for (int i = 1; i < *argc; ++i) {
        int r = cli_collide_option(cmd, *argc, argv, &i, o);
        if (r < 0) return CLI_EXIT_USAGE;
        if (r == 0) argv[w++] = argv[i];
    }
    *argc = w;
    argv[w] = NULL;
    return CLI_EXIT_OK;
}

static int make_collider(const char *cmd, const char *path, const cli_collide_opts *o, const ori_pattern *p,
                         ori_collider **c)
{
    ori_collider_def cd = ori_default_collider_def();
    cd.pattern = p;
    cd.clearance = o->clearance;
    ori_error err;
    if (ori_collider_create(&cd, c, &err) != ORI_OK) {
        if (err.status == ORI_ERR_RANGE) return cli_input_fail(cmd, path, "--clearance must be a length >= 0, got %s", o->raw);
        return cli_input_error(cmd, path, &err);
    }
    return CLI_EXIT_OK;
}

static int check_failed(const char *cmd, const char *path, const ori_error *err)
{
    int rc = cli_input_error(cmd, path, err);
    return err->status == ORI_ERR_NOT_CONVERGED || err->status == ORI_ERR_INTERNAL ? CLI_EXIT_INTERNAL : rc;
}

int cli_collide_motion(const char *cmd, const char *path, const cli_collide_opts *o, const ori_pattern *flat,
                       const ori_mechanism *m, const ori_motion_def *def, const ori_motion *mo, cli_collision *out)
{
    memset(out, 0, sizeof *out);
    if (o->skip) return CLI_EXIT_OK;
    ori_collider *c = NULL;
    int rc = make_collider(cmd, path, o, flat, &c);
    if (rc != CLI_EXIT_OK) return rc;
    cli_progress bar;
    cli_progress_begin(&bar, cmd, "checking collisions");
    ori_error err;
    ori_status st = cli_collision_check_motion(c, m, def, mo, cli_progress_fn, &bar, out, &err);
    cli_progress_end(&bar);
    ori_collider_destroy(c);
    return st == ORI_OK ? CLI_EXIT_OK : check_failed(cmd, path, &err);
}

int cli_collide_record(const char *cmd, const char *path, const cli_collide_opts *o, const ori_pattern *flat,
                       const ori_record *r, cli_collision *out)
{
    memset(out, 0, sizeof *out);
    if (o->skip) return CLI_EXIT_OK;
    ori_collider *c = NULL;
    int rc = make_collider(cmd, path, o, flat, &c);
    if (rc != CLI_EXIT_OK) return rc;
    cli_progress bar;
    cli_progress_begin(&bar, cmd, "checking collisions");
    ori_error err;
    ori_status st = cli_collision_check_record(c, r, cli_progress_fn, &bar, out, &err);
    cli_progress_end(&bar);
    ori_collider_destroy(c);
    return st == ORI_OK ? CLI_EXIT_OK : check_failed(cmd, path, &err);
}
