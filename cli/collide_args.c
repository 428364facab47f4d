// Collision checks in the CLI: the motion checks that `orikin fold` and `orikin sequence` run
// after solving (`orikin collide` names its state with state_args.h, as render and export do).
#include "collide_args.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "progress.h"

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
    if (!cli_parse_double(v, &o->clearance) || !(o->clearance >= 0.0)) { // a command-line value: usage
        cli_usage(cmd, "--clearance needs a length >= 0, got '%s'", v);
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
        if (err.status == ORI_ERR_RANGE)
            return cli_value_fail(cmd, path, "--clearance", "must be a length >= 0, got %s", o->raw);
        return cli_input_error(cmd, path, &err);
    }
    return CLI_EXIT_OK;
}

static int check_failed(const char *cmd, const char *path, const ori_error *err)
{
    // A face bent in a solved state is the solver's failure, not the file's (the flat sheet is
    // planar): a negative answer saying what could not be done, never bad input.
    if (err->status == ORI_ERR_DEGENERATE && strcmp(err->field, "faces_vertices") == 0 &&
        strstr(err->message, "not planar")) {
        fprintf(stderr,
                "orikin %s: %s: the solver's state bends face %d (%s): the fold could not be posed rigidly, so it is not "
                "judged\n",
                cmd, path, err->element, err->message);
        return CLI_EXIT_NEGATIVE;
    }
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

int cli_collide_multifold(const char *cmd, const char *path, const cli_collide_opts *o, const ori_pattern *flat,
                          const ori_multifold *mf, const int *locked, int locked_count, cli_collision *out)
{
    memset(out, 0, sizeof *out);
    if (o->skip) return CLI_EXIT_OK;
    ori_collider *c = NULL;
    int rc = make_collider(cmd, path, o, flat, &c);
    if (rc != CLI_EXIT_OK) return rc;
    cli_progress bar;
    cli_progress_begin(&bar, cmd, "checking collisions");
    ori_collision_motion_def cd = ori_default_collision_motion_def();
    cd.progress = cli_progress_fn;
    cd.progress_user = &bar;
    ori_error err;
    ori_status st = ori_collision_check_multifold(c, mf, locked, locked_count, &cd, &out->ev, &err);
    out->checked = st == ORI_OK;
    out->progress = true;
    cli_progress_end(&bar);
    ori_collider_destroy(c);
    return st == ORI_OK ? CLI_EXIT_OK : check_failed(cmd, path, &err);
}
