// The fold modes of several degrees of freedom (toward the targets, several drives, an automatic
// lock set, symmetry): solved and reported once for `orikin fold` (cli/fold_modes.c) and the
// studio's POST /api/fold.
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "report.h"

// Kawasaki misses below this (radians) look like rounded coordinates (as in cli_fold_rounding_hint).
#define MODES_NEAR_KAWASAKI_RAD 1e-3

ori_status cli_modes_solve(cli_modes *x, ori_error *err)
{
    const ori_mechanism *m = x->mech;
    int E = ori_mechanism_edge_count(m);
    x->lock_set_failed = false;
    x->hint[0] = '\0';
    if (x->symmetric) {
        x->group = malloc(sizeof(int) * (size_t)(E + 1));
        x->sym_groups = ori_mechanism_symmetry_orbits(m, x->group);
        x->sym_order = ori_mechanism_symmetries(m, NULL, 0);
    }
    x->locks = malloc(sizeof(int) * (size_t)(E + x->ngiven + 1));
    if (x->ngiven) memcpy(x->locks, x->given_locks, sizeof(int) * (size_t)x->ngiven);
    x->nlocks = x->ngiven;
    if (x->lock_auto) {
        int n = ori_mechanism_lock_set(m, x->start, x->drives, x->ndrives, x->given_locks, x->ngiven, x->group,
                                       x->locks + x->nlocks, E + 1, err);
        if (n < 0) {
            x->lock_set_failed = true;
            return err ? err->status : ORI_ERR_ARGUMENT;
        }
        x->nlocks += n;
    }
    if (x->has_percent) {
        ori_target_fold_def d = ori_default_target_fold_def();
        d.fixed_face = x->fix;
        d.fixed_pose = x->pose;
        d.start_angles_rad = x->start;
        d.fraction = x->percent / 100.0;
        d.step_rad = ori_deg_to_rad(x->step_deg);
        d.locked_edges = x->locks;
        d.locked_count = x->nlocks;
        d.edge_group = x->group;
        d.progress = x->progress;
        d.progress_user = x->progress_user;
        return ori_target_fold_solve(m, &d, &x->mf, err);
    }
    double *to = malloc(sizeof(double) * (size_t)(x->ndrives + 1));
    for (int i = 0; i < x->ndrives; ++i) to[i] = ori_deg_to_rad(x->to_deg[i]);
    ori_drives_fold_def d = ori_default_drives_fold_def();
    d.fixed_face = x->fix;
    d.fixed_pose = x->pose;
    d.start_angles_rad = x->start;
    d.driven_edges = x->drives;
    d.to_rad = to;
    d.driven_count = x->ndrives;
    d.step_rad = ori_deg_to_rad(x->step_deg);
    d.locked_edges = x->locks;
    d.locked_count = x->nlocks;
    d.edge_group = x->group;
    d.progress = x->progress;
    d.progress_user = x->progress_user;
    ori_status st = ori_drives_fold_solve(m, &d, &x->mf, err);
    free(to);
    return st;
}

void cli_modes_hint(cli_modes *x, ori_progress_fn *progress, void *user)
{
    ori_multifold_verdict v = ori_multifold_verdict_of(x->mf);
    x->hint[0] = '\0';
    if (v == ORI_MULTIFOLD_SINGULAR || v == ORI_MULTIFOLD_OVERDETERMINED) {
        // A drawing with rounded coordinates is rigid where its exact design folds: say so.
        int near = 0;
        double worst = 0.0;
        for (int i = 0; i < ori_pattern_vertex_count(x->flat); ++i) {
            if (!ori_pattern_vertex_is_interior(x->flat, i)) continue;
            ori_vertex_report vr;
            ori_flat_check_vertex(x->flat, i, &vr);
            if (vr.degree % 2 || vr.kawasaki || fabs(vr.kawasaki_rad) > MODES_NEAR_KAWASAKI_RAD) continue;
            near++;
            worst = fmax(worst, fabs(vr.kawasaki_rad));
        }
        if (near)
            snprintf(x->hint, sizeof x->hint,
                     "%d interior vertices miss Kawasaki by up to %.2g rad (rounded coordinates?): rigid folding is "
                     "exact; see orikin check --tolerance, and orikin regularize --rigid to make the drawing exact",
                     near, worst);
    }
    if (v != ORI_MULTIFOLD_UNDERDETERMINED) return;
    int cap = ori_mechanism_edge_count(x->mech) + 1;
    int *out = malloc(sizeof(int) * (size_t)cap);
    ori_error err;
    int n = ori_mechanism_lock_set_progress(x->mech, x->start, x->drives, x->ndrives, x->locks, x->nlocks, x->group,
                                            out, cap, progress, user, &err);
    if (n > 0)
        cli_lock_text(out, n, x->hint, sizeof x->hint);
    else
        snprintf(x->hint, sizeof x->hint,
                 "no lock set found (%s); or start from a folded frame (--percent first, then --frame), or use "
                 "--symmetric",
                 n == 0 ? "the search locked nothing" : err.message);
    free(out);
}

int cli_modes_shown_frames(const cli_modes *x) { return cli_collide_frames(&x->col, ori_multifold_frame_count(x->mf)); }

int cli_modes_creases(const cli_modes *x, cli_modes_crease *rows)
{
    const ori_mechanism *m = x->mech;
    const ori_multifold *mf = x->mf;
    int E = ori_mechanism_edge_count(m), F = cli_modes_shown_frames(x), n = 0;
    if (F == 0) return 0;
    double *target = malloc(sizeof(double) * (size_t)(E + 1));
    ori_target_angles_default(x->flat, target);
    const double *a0 = ori_multifold_frame_angles(mf, 0), *a1 = ori_multifold_frame_angles(mf, F - 1);
    const double *goal = ori_multifold_goal(mf);
    for (int e = 0; e < E; ++e) {
        int j = ori_mechanism_edge_joint(m, e);
        if (j == ORI_NULL_INDEX || ori_mechanism_joint(m, j).kind != ORI_JOINT_REVOLUTE) continue;
        // Drives: the driven creases only (the others have no goal of their own).
        if (!x->has_percent && fabs(goal[e] - a0[e]) <= ORI_TOL_TARGET_RAD) continue;
        cli_modes_crease c = {e, a0[e], x->has_percent ? target[e] : goal[e], goal[e], a1[e], 1.0, false};
        double span = c.goal - c.start;
        if (fabs(span) > ORI_TOL_TARGET_RAD) c.fraction = (c.reached - c.start) / span;
        else c.fraction = fabs(c.reached - c.start) <= ORI_TOL_FOLD_SIGN_RAD ? 1.0 : 0.0;
        rows[n++] = c;
    }
    free(target);
    return n;
}

int cli_modes_against_assignment(const cli_modes *x, cli_modes_against *rows)
{
    const ori_multifold *mf = x->mf;
    int E = ori_mechanism_edge_count(x->mech), F = cli_modes_shown_frames(x), n = 0;
    for (int e = 0; e < E; ++e) {
        ori_assignment as = ori_pattern_edge(x->flat, e).assignment;
        int sg = as == ORI_ASSIGN_VALLEY ? 1 : as == ORI_ASSIGN_MOUNTAIN ? -1 : 0;
        if (!sg) continue;
        double worst = 0.0;
        for (int f = 0; f < F; ++f) {
            double a = ori_multifold_frame_angles(mf, f)[e];
            if (a * sg < 0.0 && fabs(a) > ORI_TOL_FOLD_SIGN_RAD && fabs(a) > fabs(worst)) worst = a;
        }
        if (worst != 0.0) rows[n++] = (cli_modes_against){e, ori_assignment_to_char(as), worst};
    }
    return n;
}

static json_t *int_array(const int *v, int n)
{
    json_t *a = json_array();
    for (int i = 0; i < n; ++i) json_array_append_new(a, json_integer(v[i]));
    return a;
}

json_t *cli_modes_json(const cli_modes *x, const char *file)
{
    const ori_multifold *mf = x->mf;
    int E = ori_mechanism_edge_count(x->mech), F = cli_modes_shown_frames(x);
    ori_multifold_verdict v = ori_multifold_verdict_of(mf);
    json_t *out = json_object();
    json_object_set_new(out, "file", json_string(file));
    json_object_set_new(out, "mode", json_string(x->has_percent ? "targets" : "drives"));
    bool collides = cli_collides(&x->col);
    char hit[256] = "";
    if (collides) cli_collision_describe(&x->col, false, hit, sizeof hit);
    json_object_set_new(out, "valid", json_boolean(v == ORI_MULTIFOLD_REACHED && !collides));
    json_object_set_new(out, "verdict", json_string(collides ? "collision" : ori_multifold_verdict_name(v)));
    json_object_set_new(out, "reason", json_string(collides ? hit : ori_multifold_reason(mf)));
    json_object_set_new(out, "collision", cli_collision_json(&x->col, false));
    json_object_set_new(out, "hint", x->hint[0] ? json_string(x->hint) : json_null());
    int se = ori_multifold_stop_edge(mf);
    json_object_set_new(out, "stop_edge", se == ORI_NULL_INDEX ? json_null() : json_integer(se));
    json_object_set_new(out, "fixed_face", json_integer(x->fix));
    json_object_set_new(out, "percent", x->has_percent ? json_real(x->percent) : json_null());
    json_object_set_new(out, "step_deg", json_real(x->step_deg));
    if (x->group)
        json_object_set_new(out, "symmetry", json_pack("{s:i,s:i}", "order", x->sym_order, "crease_groups", x->sym_groups));
    else
        json_object_set_new(out, "symmetry", json_null());
    json_object_set_new(out, "locked", int_array(x->locks, x->nlocks));
    json_object_set_new(out, "lock_auto", json_boolean(x->lock_auto));
    json_t *dr = json_array();
    for (int i = 0; !x->has_percent && i < x->ndrives; ++i)
        json_array_append_new(dr, json_pack("{s:i,s:f}", "edge", x->drives[i], "to_deg", x->to_deg[i]));
    json_object_set_new(out, "drives", dr);
    cli_modes_crease *rows = malloc(sizeof(cli_modes_crease) * (size_t)(E + 1));
    int nr = cli_modes_creases(x, rows);
    json_t *cr = json_array();
    for (int i = 0; i < nr; ++i)
        json_array_append_new(cr, json_pack("{s:i,s:f,s:f,s:f,s:f,s:f}", "edge", rows[i].edge, "start_deg",
                                            ori_rad_to_deg_output(rows[i].start), "target_deg",
                                            ori_rad_to_deg_output(rows[i].target), "goal_deg",
                                            ori_rad_to_deg_output(rows[i].goal), "reached_deg",
                                            ori_rad_to_deg_output(rows[i].reached), "fraction", rows[i].fraction));
    free(rows);
    json_object_set_new(out, "creases", cr);
    cli_modes_against *ag = malloc(sizeof(cli_modes_against) * (size_t)(E + 1));
    int na = cli_modes_against_assignment(x, ag);
    json_t *aj = json_array();
    for (int i = 0; i < na; ++i) {
        char as[2] = {ag[i].assignment, '\0'};
        json_array_append_new(aj, json_pack("{s:i,s:s,s:f}", "edge", ag[i].edge, "assignment", as, "angle_deg",
                                            ori_rad_to_deg_output(ag[i].angle)));
    }
    free(ag);
    json_object_set_new(out, "against_assignment", aj);
    json_t *frames = json_array();
    double maxres = 0.0;
    for (int f = 0; f < F; ++f) {
        const double *ang = ori_multifold_frame_angles(mf, f);
        json_t *angs = json_array();
        for (int e = 0; e < E; ++e) json_array_append_new(angs, json_real(ori_rad_to_deg_output(ang[e])));
        double res = ori_multifold_frame_residual(mf, f);
        maxres = fmax(maxres, res);
        json_array_append_new(frames, json_pack("{s:f,s:o,s:f}", "progress", ori_multifold_frame_progress(mf, f),
                                                "fold_angles_deg", angs, "residual", res));
    }
    json_object_set_new(out, "frames", frames);
    int steps, rejected, newton;
    ori_multifold_stats(mf, &steps, &rejected, &newton);
    json_object_set_new(out, "stats", json_pack("{s:i,s:i,s:i,s:i,s:f}", "steps", steps, "rejected_steps", rejected,
                                                "newton_iterations", newton, "held_at_180", ori_multifold_held_count(mf),
                                                "max_residual", maxres));
    return out;
}

void cli_modes_free(cli_modes *x)
{
    ori_multifold_destroy(x->mf);
    free(x->group);
    free(x->locks);
    x->mf = NULL;
    x->group = NULL;
    x->locks = NULL;
    x->nlocks = 0;
}
