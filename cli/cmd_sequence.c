// orikin sequence: the folding manager — run a fold sequence, print or write its motion
// record, or restore any instant of it.
#include <stdlib.h>
#include <string.h>

#include <orikin/sequence.h>

#include "collide_args.h"
#include "kin_args.h"
#include "progress.h"

#define MAX_COLUMNS 10

typedef struct seq_args {
    const char *path;
    bool has_at, json;
    double at;
    const char *out;
} seq_args;

// Creases whose angle changes anywhere in the record (the table's columns).
static int moving_creases(const ori_record *r, int edges, int *out, int cap)
{
    int n = 0, total = 0;
    if (ori_record_frame_count(r) == 0) return 0; // the first fold failed: nothing recorded
    for (int e = 0; e < edges; ++e) {
        double a0 = ori_record_frame_angles(r, 0)[e];
        bool moves = false;
        for (int f = 1; f < ori_record_frame_count(r) && !moves; ++f) moves = ori_record_frame_angles(r, f)[e] != a0;
        if (!moves) continue;
        if (n < cap) out[n++] = e;
        total++;
    }
    return total;
}

static json_t *angles_json(const double *a, int n)
{
    json_t *arr = json_array();
    for (int e = 0; e < n; ++e) json_array_append_new(arr, json_real(ori_rad_to_deg_output(a[e])));
    return arr;
}

static void print_record_text(const char *pattern, const ori_sequence *s, const ori_record *r, int E,
                              const cli_collision *col)
{
    int cols[MAX_COLUMNS];
    int moving = moving_creases(r, E, cols, MAX_COLUMNS);
    int nc = moving < MAX_COLUMNS ? moving : MAX_COLUMNS;
    printf("%s: %d folds\n", pattern, ori_sequence_fold_count(s));
    for (int i = 0; i < ori_sequence_fold_count(s); ++i) {
        ori_sequence_fold f = ori_sequence_fold_at(s, i);
        if (f.targets) // a fold toward the targets (fold_modes)
            printf("  fold %d%s%s%s: fix face %d%s, %g %% of the way toward the targets (step %g)", i + 1,
                   f.name[0] ? " (" : "", f.name, f.name[0] ? ")" : "", f.fixed_face,
                   f.fix_default ? " (the face at the sheet's centre)" : "", 100.0 * f.fraction,
                   ori_rad_to_deg_output(f.step_rad));
        else
        printf("  fold %d%s%s%s: fix face %d%s, drive crease %d to %g deg (step %g)", i + 1, f.name[0] ? " (" : "", f.name,
               f.name[0] ? ")" : "", f.fixed_face, f.fix_default ? " (the face at the sheet's centre)" : "", f.driven_edge,
               ori_rad_to_deg_output(f.to_rad), ori_rad_to_deg_output(f.step_rad));
        if (f.locked_count) {
            printf(", lock");
            for (int k = 0; k < f.locked_count; ++k) printf("%s%d", k ? "," : " ", f.locked[k]);
        }
        printf("\n");
    }
    printf("\n%7s %5s", "t", "fold");
    for (int i = 0; i < nc; ++i) printf("  crease %-4d", cols[i]);
    printf("  residual\n");
    for (int f = 0; f < cli_collide_frames(col, ori_record_frame_count(r)); ++f) {
        printf("%7.3f %5d", ori_record_frame_time(r, f), ori_record_frame_fold(r, f) + 1);
        for (int i = 0; i < nc; ++i) printf(" %12.6f", ori_rad_to_deg_output(ori_record_frame_angles(r, f)[cols[i]]));
        printf("  %.1e\n", ori_record_frame_residual(r, f));
    }
    if (moving > nc) printf("(%d more moving creases: see --json)\n", moving - nc);
    ori_motion_verdict v = ori_record_verdict(r);
    char hit[256];
    cli_collision_describe(col, true, hit, sizeof hit);
    if (cli_collides(col))
        printf("verdict: collision: %s, t = %.9g (the motion stops at the last clean step)\n", hit, col->ev.time);
    else if (v == ORI_MOTION_VALID)
        printf("verdict: valid: %d of %d folds completed (angles in degrees, t = sequence time)\n",
               ori_record_completed_folds(r), ori_record_fold_count(r));
    else
        printf("verdict: fold %d is %s: %s\n", ori_record_failed_fold(r) + 1, ori_motion_verdict_name(v),
               ori_record_reason(r) ? ori_record_reason(r) : "");
}

static int print_at(const seq_args *a, const cli_kin *k, const ori_sequence *s, const ori_record *r)
{
    int E = ori_mechanism_edge_count(k->mech), V = ori_mechanism_vertex_count(k->mech);
    double *ang = malloc(sizeof(double) * (size_t)(E + 1));
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)(V + 1));
    double drive, residual;
    int fold;
    ori_error err;
    ori_status st = ori_record_at(r, a->at, ang, pos, &drive, &fold, &residual, &err);
    if (st != ORI_OK) {
        free(ang);
        free(pos);
        if (st == ORI_ERR_RANGE) return cli_usage("sequence", "--at: %s", err.message);
        return cli_input_error("sequence", a->path, &err);
    }
    int rc = CLI_EXIT_OK;
    if (a->json) {
        json_t *o = json_object();
        json_object_set_new(o, "t", json_real(a->at));
        json_object_set_new(o, "fold", json_integer(fold + 1));
        bool tg = ori_sequence_fold_at(s, fold).targets; // progress, not an angle
        json_object_set_new(o, "drive_deg", tg ? json_null() : json_real(ori_rad_to_deg_output(drive)));
        json_object_set_new(o, "fold_angles_deg", angles_json(ang, E));
        json_object_set_new(o, "residual", json_real(residual));
        json_t *coords = json_array();
        for (int v = 0; v < V; ++v) json_array_append_new(coords, json_pack("[fff]", pos[v].x, pos[v].y, pos[v].z));
        json_object_set_new(o, "vertices_coords", coords);
        cli_print_json(o);
    } else {
        if (ori_sequence_fold_at(s, fold).targets)
            printf("t = %g: fold %d, %.6g %% of the way to the targets, residual %.1e\n", a->at, fold + 1, 100.0 * drive,
                   residual);
        else
        printf("t = %g: fold %d, drive %.6f deg, residual %.1e\n", a->at, fold + 1, ori_rad_to_deg_output(drive), residual);
        for (int e = 0; e < E; ++e) {
            ori_edge ed = ori_pattern_edge(k->flat, e);
            if (!ori_assignment_is_fold(ed.assignment) && ed.assignment != ORI_ASSIGN_FLAT) continue;
            printf("  crease %-5d %c %12.6f\n", e, ori_assignment_to_char(ed.assignment), ori_rad_to_deg_output(ang[e]));
        }
    }
    if (a->out) {
        char title[128];
        snprintf(title, sizeof title, "t = %g (fold %d)", a->at, fold + 1);
        int fr = ori_fold_append_state(k->doc, 0, V, pos, E, ang, title);
        char t[64];
        snprintf(t, sizeof t, "%.17g", a->at);
        ori_fold_set_custom(k->doc, fr, "orikin:time", t, NULL);
        if (ori_fold_save_file(k->doc, a->out, &err) != ORI_OK) rc = cli_input_error("sequence", a->out, &err);
    }
    free(ang);
    free(pos);
    return rc;
}

static int write_record(const seq_args *a, const cli_kin *k, const ori_sequence *s, const ori_record *r,
                        const cli_collision *col)
{
    int E = ori_mechanism_edge_count(k->mech), V = ori_mechanism_vertex_count(k->mech);
    for (int f = 0; f < cli_collide_frames(col, ori_record_frame_count(r)); ++f) {
        char title[128];
        if (ori_sequence_fold_at(s, ori_record_frame_fold(r, f)).targets)
            snprintf(title, sizeof title, "t = %.4g: fold %d, %.6g %% of the way to the targets", ori_record_frame_time(r, f),
                     ori_record_frame_fold(r, f) + 1, 100.0 * ori_record_frame_drive(r, f));
        else
        snprintf(title, sizeof title, "t = %.4g: fold %d, crease %d at %g deg", ori_record_frame_time(r, f),
                 ori_record_frame_fold(r, f) + 1, ori_sequence_fold_at(s, ori_record_frame_fold(r, f)).driven_edge,
                 ori_rad_to_deg_output(ori_record_frame_drive(r, f)));
        int fr = ori_fold_append_state(k->doc, 0, V, ori_record_frame_vertices(r, f), E, ori_record_frame_angles(r, f), title);
        char t[64];
        snprintf(t, sizeof t, "%.17g", ori_record_frame_time(r, f));
        ori_fold_set_custom(k->doc, fr, "orikin:time", t, NULL);
    }
    char *json = ori_sequence_to_json(s);
    ori_error err;
    ori_fold_set_custom(k->doc, 0, "orikin:sequence", json, NULL);
    ori_buffer_free(json);
    if (cli_collides(col) || ori_record_partial_frames(r) > 0) {
        // A top-level marker: the frames run up to a stop (a blocked fold) or a contact.
        json_t *p = json_object();
        bool collides = cli_collides(col);
        char hit[256];
        cli_collision_describe(col, true, hit, sizeof hit);
        int failed = ori_record_failed_fold(r);
        json_object_set_new(p, "verdict", json_string(collides ? "collision" : ori_motion_verdict_name(ori_record_verdict(r))));
        json_object_set_new(p, "reason", json_string(collides ? hit : ori_record_reason(r) ? ori_record_reason(r) : ""));
        json_object_set_new(p, "failed_fold", !collides && failed >= 0 ? json_integer(failed + 1) : json_null());
        int F = cli_collide_frames(col, ori_record_frame_count(r));
        json_object_set_new(p, "reached_t", F > 0 ? json_real(ori_record_frame_time(r, F - 1)) : json_null());
        json_object_set_new(p, "frames", json_integer(F));
        char *text = json_dumps(p, JSON_COMPACT);
        json_decref(p);
        ori_status st = ori_fold_set_custom(k->doc, 0, "orikin:partial", text, &err);
        free(text);
        if (st != ORI_OK) return cli_input_error("sequence", a->out, &err);
    }
    if (ori_fold_save_file(k->doc, a->out, &err) != ORI_OK) return cli_input_error("sequence", a->out, &err);
    return CLI_EXIT_OK;
}

static int run(int argc, char **argv)
{
    seq_args a = {0};
    cli_collide_opts co;
    if (cli_collide_strip("sequence", &argc, argv, &co) != CLI_EXIT_OK) return CLI_EXIT_USAGE;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--json") == 0) a.json = true;
        else if (strcmp(argv[i], "--at") == 0) {
            const char *v = cli_option_value("sequence", argc, argv, &i);
            if (!v) return CLI_EXIT_USAGE;
            if (!cli_parse_double(v, &a.at) || a.at < 0) return cli_usage("sequence", "--at needs a time T ≥ 0");
            a.has_at = true;
        } else if (strcmp(argv[i], "-o") == 0) {
            if (!(a.out = cli_option_value("sequence", argc, argv, &i))) return CLI_EXIT_USAGE;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') return cli_usage("sequence", "unknown option %s", argv[i]);
        else if (!a.path) a.path = argv[i];
        else return cli_usage("sequence", "one SEQ.json only");
    }
    if (!a.path) return cli_usage("sequence", "missing SEQ.json");

    ori_sequence *s = NULL;
    ori_error err;
    if (ori_sequence_load_file(a.path, &s, &err) != ORI_OK) {
        if (ori_format_from_path(a.path) != ORI_FORMAT_UNKNOWN) // a crease pattern given for the sequence
            return cli_usage("sequence",
                             "%s is a crease pattern, not a sequence: give SEQ.json, a sequence file that names its "
                             "pattern in \"pattern\" and lists its \"folds\" (docs/sequence.md); to fold the pattern "
                             "itself, orikin fold %s",
                             a.path, a.path);
        return cli_input_error("sequence", a.path, &err);
    }
    char *pattern = cli_path_beside(a.path, ori_sequence_pattern_path(s));
    cli_kin k;
    int rc = cli_kin_load_sequence("sequence", a.path, pattern, ori_sequence_frame(s), &k);
    if (rc != CLI_EXIT_OK) {
        free(pattern);
        ori_sequence_destroy(s);
        return rc;
    }
    // Faces and creases named by name or point ("fix": "Obj12", "drive": "@x,y"): against the pattern.
    if (ori_sequence_resolve(s, k.flat, &err) != ORI_OK) {
        rc = cli_input_error("sequence", a.path, &err);
        cli_kin_free(&k);
        free(pattern);
        ori_sequence_destroy(s);
        return rc;
    }
    ori_sequence_fold first = ori_sequence_fold_at(s, 0);
    ori_rigid pose = ori_rigid_identity();
    if (first.fixed_face < 0 || first.fixed_face >= ori_mechanism_face_count(k.mech)) {
        rc = cli_input_fail("sequence", a.path, "folds 0: fix: face %d does not exist (%d faces)", first.fixed_face,
                            ori_mechanism_face_count(k.mech));
    } else {
        rc = cli_kin_fixed_pose("sequence", pattern, &k, first.fixed_face, &pose);
    }
    ori_record *r = NULL;
    if (rc == CLI_EXIT_OK) {
        cli_progress bar;
        cli_progress_begin(&bar, "sequence", "solving");
        ori_status st = ori_sequence_run_progress(s, k.mech, k.angles, pose, cli_progress_fn, &bar, &r, &err);
        cli_progress_end(&bar);
        if (st != ORI_OK) rc = cli_input_error("sequence", a.path, &err);
    }
    cli_collision col;
    memset(&col, 0, sizeof col);
    if (rc == CLI_EXIT_OK) rc = cli_collide_record("sequence", a.path, &co, k.flat, r, &col);
    if (rc == CLI_EXIT_OK) {
        int E = ori_mechanism_edge_count(k.mech);
        bool valid = ori_record_verdict(r) == ORI_MOTION_VALID;
        if (a.has_at) {
            // an instant before the first contact is still a clean state of the sequence
            bool clean = !cli_collides(&col) || a.at < col.ev.time;
            rc = valid && clean ? print_at(&a, &k, s, r) : CLI_EXIT_NEGATIVE;
            char hit[256];
            cli_collision_describe(&col, true, hit, sizeof hit);
            if (!valid)
                fprintf(stderr, "orikin sequence: %s: fold %d is %s: %s\n", a.path, ori_record_failed_fold(r) + 1,
                        ori_motion_verdict_name(ori_record_verdict(r)), ori_record_reason(r));
            else if (!clean)
                fprintf(stderr, "orikin sequence: %s: collision at t = %.9g: %s\n", a.path, col.ev.time, hit);
        } else {
            if (a.json) cli_print_json(cli_record_json(a.path, pattern, s, r, E, &col));
            else print_record_text(pattern, s, r, E, &col);
            rc = valid && !cli_collides(&col) ? CLI_EXIT_OK : CLI_EXIT_NEGATIVE;
            // A blocked fold writes the sequence up to its stop, marked "orikin:partial".
            if ((valid || ori_record_partial_frames(r) > 0) && a.out) {
                int wr = write_record(&a, &k, s, r, &col);
                if (wr != CLI_EXIT_OK) rc = wr;
            }
        }
    }
    ori_record_destroy(r);
    cli_kin_free(&k);
    free(pattern);
    ori_sequence_destroy(s);
    return rc;
}

const cli_command cli_cmd_sequence = {
    "sequence",
    "the folding manager: run a fold sequence, record it, restore any instant",
    "usage: orikin sequence SEQ.json [--at T] [--no-collisions] [--clearance D] [--json]\n"
    "                       [-o OUT.fold]\n"
    "\n"
    "Run the folds of SEQ.json one after the other: each fold fixes a face, locks creases at\n"
    "their current angle and drives one crease, starting from the geometry the previous fold\n"
    "left (its fold angles, and the fixed face where it is now). The whole motion is recorded\n"
    "and printed as a table of crease angles over the sequence time t: t = k + s is the\n"
    "fraction s of fold k+1 (t = 1.5 is halfway through fold 2). --at T restores the instant T\n"
    "exactly (solved, not interpolated). Stops at the first fold that is not valid (exit 1).\n"
    "Every step is checked for self-collision (orikin collide): a sequence that collides stops\n"
    "at the last clean step, with the first contact located to 1e-6 deg (verdict collision).\n"
    "\n"
    "SEQ.json: {\"pattern\": \"FILE.fold\" (relative to SEQ.json), \"frame\": N (optional start\n"
    "frame), \"folds\": [{\"fix\": FACE, \"drive\": EDGE, \"to\": DEG, \"step\": DEG (default 10),\n"
    "\"from\": DEG (optional), \"lock\": [EDGE, ...], \"name\": \"...\"}, ...]}\n"
    "\n"
    "options:\n"
    "  --at T        the state at time T (0 <= T <= number of folds): crease angles, and with\n"
    "                --json also the 3D vertices\n"
    "  --no-collisions  do not check the motion for self-collision\n"
    "  --clearance D    faces sharing no vertex closer than D collide too (a length >= 0)\n"
    "  --json        print {sequence, pattern, valid, verdict, reason, collision: {fold, step,\n"
    "                drive_deg, faces, point} | null, failed_fold, duration, partial_frames\n"
    "                (frames of a blocked fold, up to its stop), folds: [...],\n"
    "                frames: [{t, fold, drive_deg, fold_angles_deg, residual}]}\n"
    "  -o OUT.fold   write the pattern with every recorded state (or the one at --at) as a\n"
    "                folded-form frame (with \"orikin:time\"), and the sequence under\n"
    "                \"orikin:sequence\"; when every fold is valid, or up to the stop of a\n"
    "                blocked fold or the last clean step of a collision, both marked by a\n"
    "                top-level \"orikin:partial\" {verdict, reason, failed_fold, reached_t,\n"
    "                frames}\n"
    "\n"
    "example: orikin sequence examples/open-corner.seq.json -o open-corner-folded.fold\n",
    run,
    NULL,
};
