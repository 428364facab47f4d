// A fold's and a sequence's --json: one builder each for `orikin fold --json`, `orikin sequence
// --json` and the studio's POST /api/fold and POST /api/sequence.
#include <math.h>
#include <stdlib.h>

#include "report.h"

// Rigid folding is exact: a crease pattern drawn with rounded coordinates usually misses
// Kawasaki by a little at many vertices, and such a sheet is rigid even though its exact
// version folds. Misses up to this size count as rounding.
#define HINT_NEAR_KAWASAKI_RAD 1e-3

static json_t *v3_json(ori_v3 v)
{
    return json_pack("[fff]", v.x, v.y, v.z);
}

static json_t *ints_json(const int *e, int n)
{
    json_t *a = json_array();
    for (int i = 0; i < n; ++i) json_array_append_new(a, json_integer(e[i]));
    return a;
}

static json_t *degrees_json(const double *a, int n)
{
    json_t *arr = json_array();
    for (int e = 0; e < n; ++e) json_array_append_new(arr, json_real(ori_rad_to_deg_output(a[e])));
    return arr;
}

static const char *solver_name(ori_motion_stats st)
{
    return st.analytic ? "analytic" : st.sweep ? "numeric-sweep" : st.sparse ? "numeric-sparse" : "numeric-dense";
}

static json_t *chain_json(const int *edges, const ori_v3 *q, const ori_v3 *w, int n)
{
    json_t *a = json_array();
    for (int i = 0; i < n; ++i)
        json_array_append_new(a, json_pack("{s:i,s:o,s:o}", "edge", edges[i], "q", v3_json(q[i]), "omega", v3_json(w[i])));
    return a;
}

bool cli_fold_rounding_hint(const ori_pattern *flat, const ori_motion *mo, char *buf, size_t size)
{
    if (ori_motion_verdict_of(mo) != ORI_MOTION_NOT_RIGIDLY_FOLDABLE) return false;
    int n = 0;
    double worst = 0.0;
    for (int v = 0; v < ori_pattern_vertex_count(flat); ++v) {
        if (!ori_pattern_vertex_is_interior(flat, v)) continue;
        ori_vertex_report r;
        ori_flat_check_vertex(flat, v, &r);
        if (r.degree % 2 || r.kawasaki || fabs(r.kawasaki_rad) > HINT_NEAR_KAWASAKI_RAD) continue;
        n++;
        worst = fmax(worst, fabs(r.kawasaki_rad));
    }
    if (n == 0) return false;
    snprintf(buf, size,
             "%d interior vertices miss Kawasaki by up to %.2g rad (rounded coordinates?): rigid folding is "
             "exact, and such a sheet is rigid even where its exact design folds; orikin check lists them",
             n, worst);
    return true;
}

json_t *cli_fold_json(const cli_fold_fields *a, const ori_pattern *flat, const ori_mechanism *m, const ori_motion *mo,
                      const cli_collision *col, const char *lock_hint)
{
    int E = ori_mechanism_edge_count(m);
    ori_motion_verdict v = ori_motion_verdict_of(mo);
    ori_motion_stats st = ori_motion_stats_of(mo);
    json_t *out = json_object();
    json_object_set_new(out, "file", json_string(a->file));
    char hit[256];
    cli_collision_describe(col, false, hit, sizeof hit);
    bool collides = cli_collides(col);
    json_object_set_new(out, "valid", json_boolean(v == ORI_MOTION_VALID && !collides));
    json_object_set_new(out, "verdict", json_string(collides ? "collision" : ori_motion_verdict_name(v)));
    const char *why = collides ? hit : ori_motion_reason(mo);
    json_object_set_new(out, "reason", why ? json_string(why) : json_null());
    json_object_set_new(out, "collision", cli_collision_json(col, false));
    char hint[512];
    const char *h = cli_fold_rounding_hint(flat, mo, hint, sizeof hint) ? hint : NULL;
    if (!h && lock_hint && lock_hint[0]) h = lock_hint; // underdetermined: a lock set (cli_lock_hint)
    json_object_set_new(out, "hint", h ? json_string(h) : json_null());
    json_object_set_new(out, "rigidly_foldable", json_boolean(v != ORI_MOTION_NOT_RIGIDLY_FOLDABLE));
    json_object_set_new(out, "dof", cli_motion_dof_json(mo));
    json_object_set_new(out, "grubler", json_integer(ori_mechanism_grubler(m)));
    json_object_set_new(out, "solver", json_string(solver_name(st)));
    json_object_set_new(out, "fixed_face", json_integer(a->fix));
    json_object_set_new(out, "drive", json_integer(a->drive));
    json_object_set_new(out, "to_deg", json_real(a->to_deg));
    json_object_set_new(out, "step_deg", json_real(a->step_deg));
    json_object_set_new(out, "locked", ints_json(a->locks, a->lock_count));
    ori_vertex_split sp;
    if (ori_motion_split(mo, &sp)) {
        json_object_set_new(out, "frame_a", ints_json(sp.frame_a, 2));
        json_object_set_new(out, "frame_b", ints_json(sp.frame_b, sp.frame_b_count));
        json_object_set_new(out, "surrounding", ints_json(sp.surrounding, sp.surrounding_count));
        json_t *s = json_object();
        json_object_set_new(s, "vertex", json_integer(sp.vertex));
        json_object_set_new(s, "end_effector_vertex", json_integer(sp.end_effector_vertex));
        json_object_set_new(s, "origin_a", v3_json(sp.origin_a));
        json_object_set_new(s, "origin_b", v3_json(sp.origin_b));
        json_object_set_new(s, "d", v3_json(sp.d));
        json_object_set_new(s, "chain_a", chain_json(sp.frame_a, sp.q_a, sp.omega_a, 2));
        json_object_set_new(s, "chain_b", chain_json(sp.frame_b, sp.q_b, sp.omega_b, sp.frame_b_count));
        json_object_set_new(out, "split", s);
    }
    json_t *off = json_array();
    for (int i = 0; i < ori_motion_violation_count(mo); ++i) {
        ori_crease_violation fv = ori_motion_violation(mo, i);
        char as[2] = {ori_assignment_to_char(fv.assignment), '\0'};
        json_array_append_new(off, json_pack("{s:i,s:s,s:f,s:f}", "edge", fv.edge, "assignment", as, "angle_deg",
                                             ori_rad_to_deg_output(fv.angle_rad), "at_drive_deg",
                                             ori_rad_to_deg_output(fv.drive_rad)));
    }
    json_object_set_new(out, "offending_edges", off);
    json_object_set_new(out, "blocked", cli_motion_block_json(mo));
    json_object_set_new(out, "partial", json_boolean(cli_motion_partial(mo, col)));
    json_t *frames = json_array();
    double *alt = malloc(sizeof(double) * (size_t)(E + 1));
    for (int f = 0; f < cli_collide_frames(col, ori_motion_frame_count(mo)); ++f) {
        json_t *fr = json_object();
        json_object_set_new(fr, "drive_deg", json_real(ori_rad_to_deg_output(ori_motion_frame_drive(mo, f))));
        json_object_set_new(fr, "fold_angles_deg", degrees_json(ori_motion_frame_angles(mo, f), E));
        json_object_set_new(fr, "residual", json_real(ori_motion_frame_residual(mo, f)));
        if (ori_motion_frame_other_branch(mo, f, alt)) json_object_set_new(fr, "other_branch_deg", degrees_json(alt, E));
        ori_v3 ea, eb;
        if (ori_motion_frame_end_effector(mo, f, &ea, &eb))
            json_object_set_new(fr, "end_effector", json_pack("{s:o,s:o}", "frame_a", v3_json(ea), "frame_b", v3_json(eb)));
        json_array_append_new(frames, fr);
    }
    free(alt);
    json_object_set_new(out, "frames", frames);
    json_object_set_new(out, "stats",
                        json_pack("{s:i,s:i,s:i,s:i,s:i,s:f}", "steps", st.steps, "rejected_steps", st.rejected_steps,
                                  "newton_iterations", st.newton_iterations, "sweep_iterations", st.sweep_iterations,
                                  "factorizations", st.factorizations, "max_residual", st.max_residual));
    return out;
}

static json_t *sequence_fold_json(const ori_sequence_fold *f, int i)
{
    json_t *o = json_object();
    json_object_set_new(o, "fold", json_integer(i + 1));
    json_object_set_new(o, "name", f->name[0] ? json_string(f->name) : json_null());
    json_object_set_new(o, "fix", json_integer(f->fixed_face));
    json_object_set_new(o, "drive", f->targets ? json_null() : json_integer(f->driven_edge));
    if (f->targets) json_object_set_new(o, "percent", json_real(100.0 * f->fraction)); // a fold toward the targets
    json_object_set_new(o, "lock", ints_json(f->locked, f->locked_count));
    json_object_set_new(o, "from_deg", f->has_from ? json_real(ori_rad_to_deg_output(f->from_rad)) : json_null());
    json_object_set_new(o, "to_deg", json_real(ori_rad_to_deg_output(f->to_rad)));
    json_object_set_new(o, "step_deg", json_real(ori_rad_to_deg_output(f->step_rad)));
    return o;
}

json_t *cli_record_json(const char *sequence, const char *pattern, const ori_sequence *s, const ori_record *r, int E,
                        const cli_collision *col)
{
    json_t *o = json_object();
    char hit[256];
    cli_collision_describe(col, true, hit, sizeof hit);
    bool collides = cli_collides(col);
    json_object_set_new(o, "sequence", json_string(sequence));
    json_object_set_new(o, "pattern", json_string(pattern));
    const char *why = collides ? hit : ori_record_reason(r);
    json_object_set_new(o, "valid", json_boolean(ori_record_verdict(r) == ORI_MOTION_VALID && !collides));
    json_object_set_new(o, "verdict", json_string(collides ? "collision" : ori_motion_verdict_name(ori_record_verdict(r))));
    json_object_set_new(o, "reason", why ? json_string(why) : json_null());
    json_object_set_new(o, "collision", cli_collision_json(col, true));
    int failed = ori_record_failed_fold(r);
    json_object_set_new(o, "failed_fold", failed >= 0 ? json_integer(failed + 1) : json_null());
    json_object_set_new(o, "duration", json_integer(ori_record_completed_folds(r)));
    json_object_set_new(o, "partial_frames", json_integer(ori_record_partial_frames(r)));
    json_t *folds = json_array();
    for (int i = 0; i < ori_sequence_fold_count(s); ++i) {
        ori_sequence_fold f = ori_sequence_fold_at(s, i);
        json_array_append_new(folds, sequence_fold_json(&f, i));
    }
    json_object_set_new(o, "folds", folds);
    json_t *frames = json_array();
    for (int f = 0; f < cli_collide_frames(col, ori_record_frame_count(r)); ++f) {
        json_t *fr = json_object();
        json_object_set_new(fr, "t", json_real(ori_record_frame_time(r, f)));
        json_object_set_new(fr, "fold", json_integer(ori_record_frame_fold(r, f) + 1));
        bool tg = ori_sequence_fold_at(s, ori_record_frame_fold(r, f)).targets; // progress, not an angle
        json_object_set_new(fr, "drive_deg", tg ? json_null() : json_real(ori_rad_to_deg_output(ori_record_frame_drive(r, f))));
        json_object_set_new(fr, "fold_angles_deg", degrees_json(ori_record_frame_angles(r, f), E));
        json_object_set_new(fr, "residual", json_real(ori_record_frame_residual(r, f)));
        json_array_append_new(frames, fr);
    }
    json_object_set_new(o, "frames", frames);
    return o;
}
