// Fold sequences (the folding manager): parsing with clear errors, the open corner's two folds
// as a recorded motion, exact restoration of any instant, invalid sequences, the CLI.
#define _POSIX_C_SOURCE 200809L
#include <jansson.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <orikin/arrangement.h>
#include <orikin/generate.h>
#include <orikin/sequence.h>

#include "support.h"

TestSuite(sequence, .init = test_leak_setup, .fini = test_leak_check);

#define DEG (ORI_PI / 180.0)

static char *corner_sequence_json(const test_open_corner *c, double to1, double to2, int fix2)
{
    char *buf = malloc(1024);
    snprintf(buf, 1024,
             "{\"pattern\": \"patterns/open-corner.fold\", \"folds\": ["
             "{\"name\": \"first\", \"fix\": %d, \"lock\": [%d], \"drive\": %d, \"to\": %g, \"step\": 10},"
             "{\"fix\": %d, \"lock\": [%d], \"drive\": %d, \"to\": %g, \"step\": 15}]}",
             c->t2, c->down, c->diag, to1, fix2, c->diag, c->down, to2);
    return buf;
}

static ori_sequence *parse_ok(const char *json)
{
    ori_sequence *s = NULL;
    ori_error err;
    cr_assert_eq(ori_sequence_parse(json, strlen(json), &s, &err), ORI_OK, "%s", err.message);
    return s;
}

// The open corner folded by its two-fold sequence (diag to to1, then down to to2 holding the
// triangle t2, or the square lr when asked), run successfully; free with corner_run_free.
typedef struct corner_run {
    test_open_corner c;
    char *json;
    ori_sequence *s;
    ori_record *r;
} corner_run;

static corner_run corner_run_make(double to1, double to2, bool hold_square)
{
    corner_run x;
    x.c = test_open_corner_load();
    x.json = corner_sequence_json(&x.c, to1, to2, hold_square ? x.c.lr : x.c.t2);
    x.s = parse_ok(x.json);
    x.r = NULL;
    ori_error err;
    cr_assert_eq(ori_sequence_run(x.s, x.c.m, NULL, ori_rigid_identity(), &x.r, &err), ORI_OK, "%s", err.message);
    return x;
}

static void corner_run_free(corner_run *x)
{
    ori_record_destroy(x->r);
    ori_sequence_destroy(x->s);
    free(x->json);
    test_open_corner_free(&x->c);
}

static ori_v3 face_normal(const ori_pattern *p, int face, const ori_v3 *pos)
{
    int v[8];
    ori_pattern_face_vertices(p, face, v, 8);
    return ori_v3_normalize(ori_v3_cross(ori_v3_sub(pos[v[1]], pos[v[0]]), ori_v3_sub(pos[v[2]], pos[v[0]])));
}

Test(sequence, parse_reads_folds_in_degrees_and_writes_them_back)
{
    const char *json = "{\"pattern\": \"a.fold\", \"frame\": 2, \"folds\": [{\"fix\": 1, \"drive\": 8, \"to\": 90,"
                       " \"lock\": [9, 3], \"from\": -10, \"name\": \"one\"}, {\"fix\": 0, \"drive\": 2, \"to\": -45, \"step\": 5}]}";
    ori_sequence *s = parse_ok(json);
    cr_assert_str_eq(ori_sequence_pattern_path(s), "a.fold");
    cr_assert_eq(ori_sequence_frame(s), 2);
    cr_assert_eq(ori_sequence_fold_count(s), 2);
    ori_sequence_fold f = ori_sequence_fold_at(s, 0);
    cr_assert_eq(f.fixed_face, 1);
    cr_assert_eq(f.driven_edge, 8);
    cr_assert_float_eq(f.to_rad, ORI_PI / 2, 1e-15);
    cr_assert(f.has_from);
    cr_assert_float_eq(f.from_rad, -10 * DEG, 1e-15);
    cr_assert_float_eq(f.step_rad, 10 * DEG, 1e-15); // default step
    cr_assert_eq(f.locked_count, 2);
    cr_assert_eq(f.locked[1], 3);
    cr_assert_str_eq(f.name, "one");
    f = ori_sequence_fold_at(s, 1);
    cr_assert_float_eq(f.step_rad, 5 * DEG, 1e-15);
    cr_assert_not(f.has_from);
    // round trip through the JSON form
    char *text = ori_sequence_to_json(s);
    ori_sequence *t = parse_ok(text);
    cr_assert_float_eq(ori_sequence_fold_at(t, 1).to_rad, -45 * DEG, 1e-15);
    cr_assert_eq(ori_sequence_fold_at(t, 0).locked[0], 9);
    ori_buffer_free(text);
    ori_sequence_destroy(t);
    ori_sequence_destroy(s);
}

Test(sequence, parse_errors_name_the_position_or_the_fold)
{
    const struct {
        const char *json;
        ori_status status;
        const char *text;
    } cases[] = {
        {"{\"pattern\": \"a.fold\",\n \"folds\": [}", ORI_ERR_PARSE, "line 2, column"},
        {"[1, 2]", ORI_ERR_TYPE, "a sequence must be a JSON object"},
        {"{\"folds\": [{\"fix\": 0, \"drive\": 1, \"to\": 9}]}", ORI_ERR_TYPE, "pattern: must name the FOLD file"},
        {"{\"pattern\": \"a\", \"folds\": []}", ORI_ERR_TYPE, "folds: must be a non-empty array"},
        {"{\"pattern\": \"a\", \"folds\": [{\"fix\": 0, \"drive\": 1}]}", ORI_ERR_TYPE, "folds 0: missing \"to\""},
        {"{\"pattern\": \"a\", \"folds\": [{\"fix\": 0, \"drive\": 1, \"to\": 9}, {\"fix\": -1, \"drive\": 1, \"to\": 9}]}",
         ORI_ERR_TYPE, "folds 1: \"fix\" must be a FOLD index"},
        {"{\"pattern\": \"a\", \"folds\": [{\"fix\": 0, \"drive\": 1, \"to\": 270}]}", ORI_ERR_RANGE,
         "folds 0: \"to\" = 270 is outside [-180, 180] degrees"},
        {"{\"pattern\": \"a\", \"folds\": [{\"fix\": 0, \"drive\": 1, \"to\": 9, \"step\": 0}]}", ORI_ERR_RANGE,
         "folds 0: \"step\" must be a number of degrees in (0, 360]"},
        {"{\"pattern\": \"a\", \"folds\": [{\"fix\": 0, \"drive\": 1, \"to\": 9, \"lcok\": [2]}]}", ORI_ERR_TYPE,
         "folds 0: unknown field \"lcok\""},
        {"{\"pattern\": \"a\", \"folds\": [{\"fix\": 0, \"drive\": 1, \"to\": 9, \"lock\": [\"x\"]}]}", ORI_ERR_TYPE,
         "folds 0: \"lock\" must be an array of FOLD edge indices"},
        {"{\"pattern\": \"a\", \"speed\": 3, \"folds\": [{\"fix\": 0, \"drive\": 1, \"to\": 9}]}", ORI_ERR_TYPE,
         "speed: unknown field"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        ori_sequence *s = NULL;
        ori_error err;
        char msg[512];
        ori_status st = ori_sequence_parse(cases[i].json, strlen(cases[i].json), &s, &err);
        ori_error_format(&err, msg, sizeof msg);
        cr_assert_eq(st, cases[i].status, "case %zu: %s", i, msg);
        cr_assert_null(s);
        cr_assert(strstr(msg, cases[i].text), "case %zu: '%s' lacks '%s'", i, msg, cases[i].text);
    }
}

Test(sequence, open_corner_two_folds_reach_the_corner_cube)
{
    corner_run x = corner_run_make(180, 90, false);
    test_open_corner c = x.c;
    ori_record *r = x.r;
    cr_assert_eq(ori_record_verdict(r), ORI_MOTION_VALID, "%s", ori_record_reason(r));
    cr_assert_eq(ori_record_completed_folds(r), 2);
    cr_assert_float_eq(ori_record_duration(r), 2.0, 0.0);
    // fold 1: 0..180 by 10 → 19 states; fold 2: 15..90 by 15 → 6 more (its start is not repeated)
    cr_assert_eq(ori_record_frame_count(r), 25);
    int V = ori_pattern_vertex_count(c.p);
    for (int f = 0; f < ori_record_frame_count(r); ++f) {
        cr_assert_leq(ori_record_frame_residual(r, f), 1e-10);
        if (f > 0) cr_assert_gt(ori_record_frame_time(r, f), ori_record_frame_time(r, f - 1));
        // edge lengths are preserved in every recorded state
        const ori_v3 *pos = ori_record_frame_vertices(r, f);
        for (int e = 0; e < ori_pattern_edge_count(c.p); ++e) {
            ori_edge E = ori_pattern_edge(c.p, e);
            double l0 = ori_v3_norm(ori_v3_sub(ori_pattern_vertex(c.p, E.v[0]), ori_pattern_vertex(c.p, E.v[1])));
            double l1 = ori_v3_norm(ori_v3_sub(pos[E.v[0]], pos[E.v[1]]));
            cr_assert_float_eq(l1, l0, 1e-12 * l0);
        }
    }
    cr_assert_float_eq(ori_record_frame_time(r, 9), 0.5, 1e-15); // diag at 90°
    const double *a90 = ori_record_frame_angles(r, 9);
    cr_assert_float_eq(a90[c.up] / DEG, 60.0, 1e-9);
    cr_assert_float_eq(a90[c.right] / DEG, asin(1 / sqrt(3.0)) / DEG, 1e-9);
    cr_assert_float_eq(a90[c.left] / DEG, -asin(1 / sqrt(3.0)) / DEG, 1e-9);
    // the end: diag 180, down 90, right 90, up 90, left −180 (four valleys, one mountain)
    int last = ori_record_frame_count(r) - 1;
    const double *end = ori_record_frame_angles(r, last);
    cr_assert_float_eq(end[c.diag], ORI_PI, 1e-12);
    cr_assert_float_eq(end[c.down], ORI_PI / 2, 1e-12);
    cr_assert_float_eq(end[c.right], ORI_PI / 2, 1e-9);
    cr_assert_float_eq(end[c.up], ORI_PI / 2, 1e-9);
    cr_assert_float_eq(end[c.left], -ORI_PI, 1e-9);
    const ori_v3 *pos = ori_record_frame_vertices(r, last);
    ori_v3 n1 = face_normal(c.p, c.lr, pos), n2 = face_normal(c.p, c.ur, pos), n3 = face_normal(c.p, c.ul, pos);
    cr_assert_float_eq(ori_v3_dot(n1, n2), 0.0, 1e-9);
    cr_assert_float_eq(ori_v3_dot(n2, n3), 0.0, 1e-9);
    cr_assert_float_eq(ori_v3_dot(n1, n3), 0.0, 1e-9);
    // the fixed face never moved
    int tv = test_vertex_at(c.p, 1, 0);
    cr_assert_float_eq(pos[tv].x, 1.0, 1e-15);
    cr_assert_float_eq(pos[tv].z, 0.0, 1e-15);
    (void)V;
    corner_run_free(&x);
}

Test(sequence, any_instant_is_restored_exactly)
{
    corner_run x = corner_run_make(180, 90, false);
    test_open_corner c = x.c;
    ori_record *r = x.r;
    ori_error err;
    int E = ori_pattern_edge_count(c.p), V = ori_pattern_vertex_count(c.p);
    double *ang = malloc(sizeof(double) * (size_t)E);
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)V);
    double drive, res;
    int fold;
    // a recorded instant comes back as recorded
    cr_assert_eq(ori_record_at(r, 0.5, ang, pos, &drive, &fold, &res, &err), ORI_OK);
    cr_assert_eq(fold, 0);
    cr_assert_float_eq(drive, ORI_PI / 2, 1e-15);
    for (int e = 0; e < E; ++e) cr_assert_float_eq(ang[e], ori_record_frame_angles(r, 9)[e], 1e-15);
    // between recorded states: diag at 45° (t = 0.25) solved exactly, as a direct fold gives it
    cr_assert_eq(ori_record_at(r, 0.25, ang, pos, &drive, &fold, &res, &err), ORI_OK, "%s", err.message);
    cr_assert_float_eq(drive, ORI_PI / 4, 1e-15);
    cr_assert_leq(res, 1e-10);
    ori_motion_def d = ori_default_motion_def();
    d.fixed_face = c.t2;
    d.driven_edge = c.diag;
    d.to_rad = ORI_PI / 4;
    d.step_rad = ORI_PI / 4;
    d.locked_edges = &c.down;
    d.locked_count = 1;
    ori_motion *mo = NULL;
    cr_assert_eq(ori_motion_solve(c.m, &d, &mo, &err), ORI_OK);
    const double *direct = ori_motion_frame_angles(mo, ori_motion_frame_count(mo) - 1);
    for (int e = 0; e < E; ++e) cr_assert_float_eq(ang[e], direct[e], 1e-11, "edge %d", e);
    ori_motion_destroy(mo);
    // halfway through fold 2: down at 45°, left at −135° (fold 2 is a rotation of the flap)
    cr_assert_eq(ori_record_at(r, 1.5, ang, pos, &drive, &fold, &res, &err), ORI_OK);
    cr_assert_eq(fold, 1);
    cr_assert_float_eq(ang[c.down] / DEG, 45.0, 1e-9);
    cr_assert_float_eq(ang[c.left] / DEG, -135.0, 1e-9);
    cr_assert_float_eq(ang[c.diag] / DEG, 180.0, 1e-9);
    cr_assert_leq(res, 1e-10);
    // t = 1 is the end of fold 1; t = 2 the end
    cr_assert_eq(ori_record_at(r, 1.0, ang, NULL, &drive, &fold, NULL, &err), ORI_OK);
    cr_assert_eq(fold, 0);
    cr_assert_float_eq(ang[c.diag], ORI_PI, 1e-12);
    cr_assert_float_eq(ang[c.down], 0.0, 1e-12);
    cr_assert_eq(ori_record_at(r, 2.0, ang, NULL, NULL, NULL, NULL, &err), ORI_OK);
    cr_assert_float_eq(ang[c.down], ORI_PI / 2, 1e-12);
    cr_assert_eq(ori_record_at(r, 2.5, ang, NULL, NULL, NULL, NULL, &err), ORI_ERR_RANGE);
    cr_assert_eq(ori_record_at(r, -0.1, ang, NULL, NULL, NULL, NULL, &err), ORI_ERR_RANGE);
    free(ang);
    free(pos);
    corner_run_free(&x);
}

Test(sequence, a_new_fixed_face_stays_where_the_previous_fold_left_it)
{
    corner_run x = corner_run_make(180, 90, true); // fold 2 holds the lower-right square, not the triangle
    test_open_corner c = x.c;
    ori_record *r = x.r;
    cr_assert_eq(ori_record_verdict(r), ORI_MOTION_VALID, "%s", ori_record_reason(r));
    int end1 = 18; // t = 1
    cr_assert_float_eq(ori_record_frame_time(r, end1), 1.0, 0.0);
    int lrv[8];
    int n = ori_pattern_face_vertices(c.p, c.lr, lrv, 8);
    const ori_v3 *a = ori_record_frame_vertices(r, end1);
    for (int f = end1 + 1; f < ori_record_frame_count(r); ++f) {
        const ori_v3 *b = ori_record_frame_vertices(r, f);
        for (int k = 0; k < n; ++k) {
            cr_assert_float_eq(b[lrv[k]].x, a[lrv[k]].x, 1e-12);
            cr_assert_float_eq(b[lrv[k]].y, a[lrv[k]].y, 1e-12);
            cr_assert_float_eq(b[lrv[k]].z, a[lrv[k]].z, 1e-12);
        }
    }
    corner_run_free(&x);
}

Test(sequence, a_fold_against_the_assignment_stops_the_sequence)
{
    corner_run x = corner_run_make(180, -90, false); // fold 2 turns the down crease (a valley) towards M
    test_open_corner c = x.c;
    ori_record *r = x.r;
    cr_assert_eq(ori_record_verdict(r), ORI_MOTION_INVALID_ASSIGNMENT);
    cr_assert_eq(ori_record_failed_fold(r), 1);
    cr_assert_eq(ori_record_completed_folds(r), 1);
    cr_assert_not_null(ori_record_reason(r));
    char want[32];
    snprintf(want, sizeof want, "%d", c.down);
    cr_assert(strstr(ori_record_reason(r), want), "reason '%s' names crease %d", ori_record_reason(r), c.down);
    cr_assert_eq(ori_record_frame_count(r), 19); // fold 1 only
    corner_run_free(&x);
}

// A blocked fold is recorded up to its stop (issue 7 §3): issue 14's vertex, fold 1 to −60°, fold
// 2 to −180° stops where crease 9 reaches −180° (crease 10 at −120.6797509°).
Test(sequence, a_blocked_fold_is_recorded_up_to_its_stop)
{
    ori_sequence *s = NULL;
    ori_error err;
    cr_assert_eq(ori_sequence_load_file(test_repo_path("tests/data/kin-issue14-blocked.seq.json"), &s, &err), ORI_OK, "%s",
                 err.message);
    ori_pattern *p = test_load_pattern(test_repo_path("tests/data/kin-issue14-vertex.fold"), 0);
    ori_mechanism *m = test_mechanism_of(p);
    ori_record *r = NULL;
    cr_assert_eq(ori_sequence_run(s, m, NULL, ori_rigid_identity(), &r, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_record_verdict(r), ORI_MOTION_BLOCKED);
    cr_assert_eq(ori_record_failed_fold(r), 1);
    cr_assert_eq(ori_record_completed_folds(r), 1);
    // 0, −30, −60 (fold 1), then −90, −120 and the stop (fold 2, partial)
    cr_assert_eq(ori_record_frame_count(r), 6);
    cr_assert_eq(ori_record_partial_frames(r), 3);
    int last = ori_record_frame_count(r) - 1;
    cr_assert_eq(ori_record_frame_fold(r, last), 1);
    cr_assert(fabs(ori_record_frame_drive(r, last) / DEG + 120.6797509) < 1e-6, "%.10g", ori_record_frame_drive(r, last) / DEG);
    cr_assert(fabs(ori_record_frame_angles(r, last)[9] + ORI_PI) < 1e-9);
    // times: fractions of the planned fold (−60° → −180°)
    cr_assert(fabs(ori_record_frame_time(r, last) - (1.0 + 60.6797509 / 120.0)) < 1e-8, "%.12g", ori_record_frame_time(r, last));
    for (int f = 1; f <= last; ++f) cr_assert_gt(ori_record_frame_time(r, f), ori_record_frame_time(r, f - 1));
    // the instants of the completed fold are still restored, and those of the partial fold up to
    // its stop (a sequence's collision check bisects there): t = 1.4 is the drive at −60° − 0.4 ×
    // 120° = −108°, before the stop; beyond the stop there is nothing
    double ang[16], drive = 0.0, res = 1.0;
    cr_assert_eq(ori_record_at(r, 1.0, ang, NULL, NULL, NULL, NULL, &err), ORI_OK);
    cr_assert_eq(ori_record_at(r, 1.4, ang, NULL, &drive, NULL, &res, &err), ORI_OK, "%s", err.message);
    cr_assert_float_eq(drive / DEG, -108.0, 1e-9);
    cr_assert_leq(res, ORI_TOL_RESIDUAL);
    cr_assert_eq(ori_record_at(r, ori_record_frame_time(r, last) + 1e-3, ang, NULL, NULL, NULL, NULL, &err), ORI_ERR_RANGE);
    ori_record_destroy(r);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
    ori_sequence_destroy(s);
}

Test(sequence, bad_indices_are_run_time_errors_naming_the_fold)
{
    test_open_corner c = test_open_corner_load();
    const char *json = "{\"pattern\": \"x\", \"folds\": [{\"fix\": 0, \"drive\": 8, \"to\": 10}, {\"fix\": 99, \"drive\": 8, \"to\": 20}]}";
    ori_sequence *s = parse_ok(json);
    ori_record *r = NULL;
    ori_error err;
    char msg[256];
    // fold 0 drives crease 8 with nothing locked: 2 DOF → underdetermined (a domain answer)
    cr_assert_eq(ori_sequence_run(s, c.m, NULL, ori_rigid_identity(), &r, &err), ORI_OK);
    cr_assert_eq(ori_record_verdict(r), ORI_MOTION_UNDERDETERMINED);
    ori_record_destroy(r);
    ori_sequence_destroy(s);
    const char *bad = "{\"pattern\": \"x\", \"folds\": [{\"fix\": 1, \"drive\": 99, \"to\": 10}]}";
    s = parse_ok(bad);
    cr_assert_neq(ori_sequence_run(s, c.m, NULL, ori_rigid_identity(), &r, &err), ORI_OK);
    cr_assert_null(r);
    ori_error_format(&err, msg, sizeof msg);
    cr_assert(strstr(msg, "folds 0:"), "%s", msg);
    ori_sequence_destroy(s);
    test_open_corner_free(&c);
}

Test(sequence, cli_writes_every_state_and_restores_an_instant)
{
    char *dir = test_tmpdir();
    char args[1024], *out = NULL;
    snprintf(args, sizeof args, "sequence examples/open-corner.seq.json -o %s/oc.fold", dir);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    cr_assert(strstr(out, "verdict: valid: 2 of 2 folds completed"), "%s", out);
    free(out);
    snprintf(args, sizeof args, "%s/oc.fold", dir);
    ori_fold *doc = NULL;
    ori_error err;
    cr_assert_eq(ori_fold_load_file(args, &doc, &err), ORI_OK);
    cr_assert_eq(ori_fold_frame_count(doc), 1 + 28); // 19 states of fold 1 + 9 of fold 2
    char *seq = ori_fold_get_custom(doc, 0, "orikin:sequence");
    cr_assert_not_null(seq);
    ori_buffer_free(seq);
    char *t = ori_fold_get_custom(doc, 28, "orikin:time");
    cr_assert_str_eq(t, "2");
    ori_buffer_free(t);
    ori_pattern *last = NULL;
    cr_assert_eq(ori_fold_get_pattern(doc, 28, NULL, &last, &err), ORI_OK);
    cr_assert(ori_pattern_is_folded_form(last));
    cr_assert(ori_pattern_is_3d(last));
    ori_pattern_destroy(last);
    ori_fold_destroy(doc);
    // --at with JSON
    cr_assert_eq(test_run_cli("sequence examples/open-corner.seq.json --at 1.5 --json", &out), 0);
    json_error_t je;
    json_t *o = json_loads(out, 0, &je);
    cr_assert_not_null(o, "%s", out);
    cr_assert_float_eq(json_number_value(json_object_get(o, "drive_deg")), 45.0, 1e-9);
    cr_assert_eq(json_integer_value(json_object_get(o, "fold")), 2);
    cr_assert_leq(json_number_value(json_object_get(o, "residual")), 1e-10);
    json_decref(o);
    free(out);
    // out of range and bad files
    cr_assert_eq(test_run_cli("sequence examples/open-corner.seq.json --at 7", &out), 2);
    free(out);
    snprintf(args, sizeof args, "%s/bad.json", dir);
    FILE *f = fopen(args, "w");
    fputs("{\"pattern\": \"nowhere.fold\", \"folds\": [{\"fix\": 0, \"drive\": 1, \"to\": 10}]}", f);
    fclose(f);
    snprintf(args, sizeof args, "sequence %s/bad.json -o %s/never.fold", dir, dir);
    cr_assert_eq(test_run_cli(args, &out), 3);
    cr_assert(strstr(out, "nowhere.fold: cannot open"), "%s", out);
    free(out);
    snprintf(args, sizeof args, "%s/never.fold", dir);
    cr_assert_null(fopen(args, "r"), "nothing written on bad input");
    test_tmpdir_remove(dir);
}

// --- a fold toward the targets: one engine for fold --percent and a sequence step -------------------

// P % is P % of the way along the motion toward the 100 % targets (the progress 1 − D/D₀): a
// 10 × 10 Miura-ori at 70 % and a 4 × 4 waterbomb at 60 % get there (every crease at P % of its
// target is no rigid state of them: that stopped "stationary"), the progress grows monotonically
// to exactly P, and a sequence step {"percent": P} without "fix" holds the same face (the sheet's
// centroid) and records the very same states as orikin fold --percent (ori_target_fold_solve).
Test(sequence, a_percent_step_is_the_fold_percent_motion_part_of_the_way_along_it)
{
    struct {
        ori_tessellation kind;
        int n;
        double percent;
    } cases[] = {{ORI_TESS_MIURA, 10, 70.0}, {ORI_TESS_WATERBOMB, 4, 60.0}};
    for (int c = 0; c < 2; ++c) {
        ori_generate_def g = ori_default_generate_def(cases[c].kind);
        g.rows = g.cols = cases[c].n;
        ori_pattern *p = NULL;
        ori_error err;
        cr_assert_eq(ori_generate(&g, &p, NULL, &err), ORI_OK, "%s", err.message);
        ori_mechanism *m = test_mechanism_of(p);
        int E = ori_mechanism_edge_count(m);
        ori_target_fold_def d = ori_default_target_fold_def();
        d.fixed_face = ori_pattern_center_face(p);
        d.fraction = cases[c].percent / 100.0;
        ori_multifold *mf = NULL;
        cr_assert_eq(ori_target_fold_solve(m, &d, &mf, &err), ORI_OK, "%s", err.message);
        cr_assert_eq(ori_multifold_verdict_of(mf), ORI_MULTIFOLD_REACHED, "case %d: %s", c, ori_multifold_reason(mf));
        int nf = ori_multifold_frame_count(mf);
        cr_assert_gt(nf, 3);
        cr_assert_eq(ori_multifold_frame_progress(mf, 0), 0.0);
        cr_assert_float_eq(ori_multifold_frame_progress(mf, nf - 1), d.fraction, 1e-12);
        for (int k = 1; k < nf; ++k) {
            cr_assert_geq(ori_multifold_frame_progress(mf, k), ori_multifold_frame_progress(mf, k - 1), "case %d frame %d", c, k);
            cr_assert_leq(ori_multifold_frame_residual(mf, k), ORI_TOL_RESIDUAL);
        }
        // The measure itself: 1 − |θ − θ_target| / |θ₀ − θ_target| over the creases.
        double *target = malloc(sizeof(double) * (size_t)E);
        ori_target_angles_default(p, target);
        double d0 = 0.0, d1 = 0.0;
        const double *a0 = ori_multifold_frame_angles(mf, 0), *a1 = ori_multifold_frame_angles(mf, nf - 1);
        for (int e = 0; e < E; ++e) {
            int j = ori_mechanism_edge_joint(m, e);
            if (j == ORI_NULL_INDEX || ori_mechanism_joint(m, j).kind != ORI_JOINT_REVOLUTE) continue;
            d0 += (a0[e] - target[e]) * (a0[e] - target[e]);
            d1 += (a1[e] - target[e]) * (a1[e] - target[e]);
        }
        cr_assert_float_eq(1.0 - sqrt(d1) / sqrt(d0), d.fraction, 1e-12);
        free(target);

        char json[256];
        snprintf(json, sizeof json, "{\"pattern\": \"p.fold\", \"folds\": [{\"percent\": %g}]}", cases[c].percent);
        ori_sequence *s = parse_ok(json);
        cr_assert(ori_sequence_fold_at(s, 0).fix_default);
        ori_record *r = NULL;
        cr_assert_eq(ori_sequence_run(s, m, NULL, ori_rigid_identity(), &r, &err), ORI_ERR_ARGUMENT); // fix unresolved
        cr_assert_eq(ori_sequence_resolve(s, p, &err), ORI_OK, "%s", err.message);
        cr_assert_eq(ori_sequence_fold_at(s, 0).fixed_face, d.fixed_face);
        cr_assert_eq(ori_sequence_run(s, m, NULL, ori_rigid_identity(), &r, &err), ORI_OK, "%s", err.message);
        cr_assert_eq(ori_record_verdict(r), ORI_MOTION_VALID, "%s", ori_record_reason(r));
        cr_assert_eq(ori_record_frame_count(r), nf);
        for (int k = 0; k < nf; ++k) {
            const double *x = ori_record_frame_angles(r, k), *y = ori_multifold_frame_angles(mf, k);
            for (int e = 0; e < E; ++e) cr_assert_float_eq(x[e], y[e], 1e-12, "case %d frame %d crease %d", c, k, e);
            cr_assert_float_eq(ori_record_frame_drive(r, k), ori_multifold_frame_progress(mf, k), 1e-15);
            // t = progress / fraction: the fold's own 0 … 1, its end at t = 1.
            cr_assert_float_eq(ori_record_frame_time(r, k), ori_multifold_frame_progress(mf, k) / d.fraction, 1e-12);
        }
        cr_assert_float_eq(ori_record_duration(r), 1.0, 0.0);
        ori_record_destroy(r);
        ori_sequence_destroy(s);
        ori_multifold_destroy(mf);
        ori_mechanism_destroy(m);
        ori_pattern_destroy(p);
    }
}

// A percent step that stops short (the open corner cannot reach every target: stationary) is
// blocked with the fold's own reason, as orikin fold --percent says, and recorded up to its stop
// (its frames those of the fold), each instant of it restorable (the collision check bisects
// there).
Test(sequence, a_percent_step_that_stops_short_is_blocked_and_recorded_up_to_its_stop)
{
    ori_pattern *p = test_load_pattern(test_repo_path("examples/patterns/open-corner.fold"), 0);
    ori_mechanism *m = test_mechanism_of(p);
    ori_target_fold_def d = ori_default_target_fold_def();
    d.fixed_face = ori_pattern_center_face(p);
    ori_multifold *mf = NULL;
    ori_error err;
    cr_assert_eq(ori_target_fold_solve(m, &d, &mf, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_multifold_verdict_of(mf), ORI_MULTIFOLD_STATIONARY, "%s", ori_multifold_reason(mf));
    int nf = ori_multifold_frame_count(mf);
    ori_sequence *s = parse_ok("{\"pattern\": \"p.fold\", \"folds\": [{\"percent\": 100}]}");
    cr_assert_eq(ori_sequence_resolve(s, p, &err), ORI_OK, "%s", err.message);
    ori_record *r = NULL;
    cr_assert_eq(ori_sequence_run(s, m, NULL, ori_rigid_identity(), &r, &err), ORI_OK, "%s", err.message);
    cr_assert_eq(ori_record_verdict(r), ORI_MOTION_BLOCKED);
    cr_assert_str_eq(ori_record_reason(r), ori_multifold_reason(mf));
    cr_assert_eq(ori_record_completed_folds(r), 0);
    cr_assert_eq(ori_record_partial_frames(r), nf);
    cr_assert_eq(ori_record_frame_count(r), nf);
    int E = ori_mechanism_edge_count(m);
    for (int k = 0; k < nf; ++k)
        for (int e = 0; e < E; ++e)
            cr_assert_eq(ori_record_frame_angles(r, k)[e], ori_multifold_frame_angles(mf, k)[e]);
    // Halfway between two recorded frames: a closed state between them.
    double t = 0.5 * (ori_record_frame_time(r, nf / 2) + ori_record_frame_time(r, nf / 2 + 1));
    double *a = malloc(sizeof(double) * (size_t)E);
    double res = 1.0;
    cr_assert_eq(ori_record_at(r, t, a, NULL, NULL, NULL, &res, &err), ORI_OK, "%s", err.message);
    cr_assert_leq(res, ORI_TOL_RESIDUAL);
    const double *a0 = ori_record_frame_angles(r, nf / 2), *a1 = ori_record_frame_angles(r, nf / 2 + 1);
    for (int e = 0; e < E; ++e)
        cr_assert(a[e] >= fmin(a0[e], a1[e]) - 1e-6 && a[e] <= fmax(a0[e], a1[e]) + 1e-6, "crease %d", e);
    // Beyond the stop: out of range.
    cr_assert_eq(ori_record_at(r, ori_record_frame_time(r, nf - 1) + 1e-3, a, NULL, NULL, NULL, NULL, &err), ORI_ERR_RANGE);
    free(a);
    ori_record_destroy(r);
    ori_sequence_destroy(s);
    ori_multifold_destroy(mf);
    ori_mechanism_destroy(m);
    ori_pattern_destroy(p);
}

// Origami Simulator's 6-point hypar: orikin fold --percent 50 and a sequence step {"percent": 50}
// (no fix: the same default face) used to differ (one collided at 35 %, the other was blocked at
// 0 % and at 50 % missed the collision). One engine: the same contact, at the same progress.
Test(sequence, the_hypar_folds_alike_by_fold_percent_and_by_a_sequence_step)
{
    const char *hypar = test_require_shared("origamisimulator/Origami_6ptHypar-anti.svg");
    char *dir = test_tmpdir();
    char seq[1024], args[2048];
    snprintf(seq, sizeof seq, "%s/hypar.seq.json", dir);
    FILE *f = fopen(seq, "w");
    cr_assert_not_null(f);
    fprintf(f, "{\"pattern\": \"%s\", \"folds\": [{\"percent\": 50}]}\n", hypar);
    fclose(f);
    char *a = NULL, *b = NULL;
    snprintf(args, sizeof args, "fold '%s' --percent 50", hypar);
    cr_assert_eq(test_run_cli(args, &a), 1, "%s", a);
    snprintf(args, sizeof args, "sequence '%s'", seq);
    cr_assert_eq(test_run_cli(args, &b), 1, "%s", b);
    const char *ca = strstr(a, "verdict: collision: faces "), *cb = strstr(b, "verdict: collision: faces ");
    cr_assert(ca && cb, "%s\n---\n%s", a, b);
    // "faces 7 and 25 penetrate at step 22, progress 0.347669925" / "... at fold 1, step 22, progress ..."
    char fa[64], fb[64];
    double pa = -1.0, pb = -2.0;
    cr_assert_eq(sscanf(ca, "verdict: collision: faces %63[0-9 and] penetrate", fa), 1);
    cr_assert_eq(sscanf(cb, "verdict: collision: faces %63[0-9 and] penetrate", fb), 1);
    cr_assert_str_eq(fa, fb);
    cr_assert_eq(sscanf(strstr(ca, "progress "), "progress %lf", &pa), 1);
    cr_assert_eq(sscanf(strstr(cb, "progress "), "progress %lf", &pb), 1);
    cr_assert_float_eq(pa, pb, 1e-9);
    cr_assert(pa > 0.3 && pa < 0.4, "%g", pa);
    free(a);
    free(b);
    test_tmpdir_remove(dir);
}
