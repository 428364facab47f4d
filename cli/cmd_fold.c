// orikin fold: fold a crease pattern rigidly (fix a face, lock creases, drive one crease) and
// report the motion, its branch, its validity, or write it as FOLD frames.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "collide_args.h"
#include "fold_compliant.h"
#include "fold_modes.h"
#include "kin_args.h"
#include "output_guard.h"
#include "progress.h"

static void print_json(const cli_fold_args *a, const cli_kin *k, const ori_motion *mo, const cli_collision *col,
                       const char *lock_hint)
{
    cli_fold_fields f = {a->path, a->fix, a->drive, a->to_deg, a->step_deg, a->locks, a->lock_count};
    cli_print_json(cli_fold_json(&f, k->flat, k->mech, mo, col, lock_hint));
}

static void print_text(const cli_fold_args *a, const cli_kin *k, const ori_motion *mo, const cli_collision *col)
{
    const ori_mechanism *m = k->mech;
    int E = ori_mechanism_edge_count(m), F = cli_collide_frames(col, ori_motion_frame_count(mo));
    ori_motion_stats st = ori_motion_stats_of(mo);
    printf("%s: fold crease %d to %g deg (step %g deg), face %d fixed%s", a->path, a->drive, a->to_deg, a->step_deg, a->fix,
           a->fix_default ? CLI_FOLD_DEFAULT_FIX_NOTE : "");
    if (a->lock_count) {
        printf(", locked");
        for (int i = 0; i < a->lock_count; ++i) printf("%s%d", i ? "," : " ", a->locks[i]);
    }
    printf("\nsolver: %s\n", st.analytic ? "closed-form spherical 4R"
                              : st.sweep ? "continuation, sweep (block substitution along the loops; CHOLMOD fallback)"
                              : st.sparse ? "continuation, sparse (CHOLMOD)"
                                          : "continuation, dense (LAPACK)");
    ori_vertex_split sp;
    if (ori_motion_split(mo, &sp)) {
        printf("vertex %d: Frame A", sp.vertex);
        for (int i = 0; i < 2; ++i) printf(" %d", sp.frame_a[i]);
        printf(", Frame B");
        for (int i = 0; i < sp.frame_b_count; ++i) printf(" %d", sp.frame_b[i]);
        printf(", surrounding");
        for (int i = 0; i < sp.surrounding_count; ++i) printf(" %d", sp.surrounding[i]);
        if (!sp.surrounding_count) printf(" none");
        printf("; d = (%g, %g, %g)\n", sp.d.x, sp.d.y, sp.d.z);
    }
    // Columns: the creases that move (at most 8), then the residual.
    int cols[8], nc = 0, moving = 0;
    for (int e = 0; e < E && F > 0; ++e) {
        if (e == a->drive) continue;
        double lo = INFINITY, hi = -INFINITY;
        for (int f = 0; f < F; ++f) {
            double x = ori_motion_frame_angles(mo, f)[e];
            lo = fmin(lo, x);
            hi = fmax(hi, x);
        }
        if (hi - lo > ORI_TOL_FOLD_SIGN_RAD) {
            moving++;
            if (nc < 8) cols[nc++] = e;
        }
    }
    if (F > 0) {
        printf("%10s", "drive");
        for (int i = 0; i < nc; ++i) printf(" %11s%-4d", "crease ", cols[i]);
        printf("  residual\n");
        for (int f = 0; f < F; ++f) {
            printf("%10.4f", ori_rad_to_deg_output(ori_motion_frame_drive(mo, f)));
            for (int i = 0; i < nc; ++i) printf(" %15.6f", ori_rad_to_deg_output(ori_motion_frame_angles(mo, f)[cols[i]]));
            printf("  %.1e\n", ori_motion_frame_residual(mo, f));
        }
        if (moving > nc) printf("(%d more moving creases: see --json)\n", moving - nc);
    }
    ori_motion_verdict v = ori_motion_verdict_of(mo);
    char hit[256];
    cli_collision_describe(col, false, hit, sizeof hit);
    printf("verdict: %s", cli_collides(col) ? "collision" : ori_motion_verdict_name(v));
    if (cli_collides(col)) printf(": %s (the motion stops at the last clean step)", hit);
    else if (ori_motion_reason(mo)) printf(": %s", ori_motion_reason(mo));
    printf("\n");
    char hint[512];
    if (cli_fold_rounding_hint(k->flat, mo, hint, sizeof hint)) printf("note: %s\n", hint);
    if (F > 0) printf("dof at the last frame %d (Grübler-Kutzbach count %d)\n", ori_motion_dof(mo), ori_mechanism_grubler(m));
}

// Every output frame as a folded form inheriting from frame 0.
static int write_frames(const cli_fold_args *a, const cli_kin *k, const ori_motion *mo, const cli_collision *col)
{
    const ori_mechanism *m = k->mech;
    int V = ori_mechanism_vertex_count(m), E = ori_mechanism_edge_count(m);
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)(V + 1));
    int F = cli_collide_frames(col, ori_motion_frame_count(mo));
    cli_progress bar; // the frames (half the work), then the text and the file
    cli_progress_begin(&bar, "fold", "writing frames");
    for (int f = 0; f < F; ++f) {
        cli_progress_update(&bar, 0.5 * f / F);
        ori_motion_frame_vertices(mo, f, pos);
        char title[128];
        snprintf(title, sizeof title, "fold crease %d: %g deg", a->drive, ori_rad_to_deg_output(ori_motion_frame_drive(mo, f)));
        ori_fold_append_state(k->doc, 0, V, pos, E, ori_motion_frame_angles(mo, f), title);
    }
    free(pos);
    ori_error err;
    if (cli_motion_partial(mo, col)) {
        // A top-level marker: the frames run up to the stop, not to the target.
        json_t *p = json_object();
        char hit[256];
        cli_collision_describe(col, false, hit, sizeof hit);
        bool collides = cli_collides(col);
        ori_motion_verdict v = ori_motion_verdict_of(mo);
        json_object_set_new(p, "verdict", json_string(collides ? "collision" : ori_motion_verdict_name(v)));
        const char *why = collides ? hit : ori_motion_reason(mo);
        json_object_set_new(p, "reason", json_string(why ? why : ""));
        json_object_set_new(p, "to_deg", json_real(a->to_deg));
        json_object_set_new(p, "reached_deg", F > 0 ? json_real(ori_rad_to_deg_output(ori_motion_frame_drive(mo, F - 1))) : json_null());
        json_object_set_new(p, "frames", json_integer(F));
        json_object_set_new(p, "blocked", cli_motion_block_json(mo));
        char *text = json_dumps(p, JSON_COMPACT);
        json_decref(p);
        ori_status st = ori_fold_set_custom(k->doc, 0, "orikin:partial", text, &err);
        free(text);
        if (st != ORI_OK) {
            cli_progress_end(&bar);
            return cli_input_error("fold", a->out, &err);
        }
    }
    cli_progress_update(&bar, 0.5);
    ori_status st = ori_fold_save_file(k->doc, a->out, &err);
    cli_progress_end(&bar);
    if (st != ORI_OK) return cli_input_error("fold", a->out, &err);
    return CLI_EXIT_OK;
}

// The frames a fold will output (start, one per step, the end) and the bytes they take as
// FOLD frames (-o: 3 coordinates per vertex and an angle per edge) and JSON (an angle per
// edge), about 20 characters a number: asks for --force beyond the guard (output_guard.h).
static int guard_output(const cli_fold_args *a, const cli_kin *k, const ori_motion_def *def, bool force)
{
    double from = def->has_from ? def->from_rad : def->start_angles_rad ? def->start_angles_rad[a->drive] : 0.0;
    double frames = floor(fabs(def->to_rad - from) / def->step_rad) + 2.0;
    double V = ori_mechanism_vertex_count(k->mech), E = ori_mechanism_edge_count(k->mech);
    double bytes = (a->out ? frames * (3.0 * V + E) * 20.0 : 0.0) + (a->json ? frames * E * 20.0 : 0.0);
    return cli_guard_check("fold", frames, bytes, force);
}

static int run(int argc, char **argv)
{
    if (cli_fold_compliant_wanted(argc, argv)) return cli_fold_compliant_run(argc, argv);
    if (cli_fold_modes_wanted(argc, argv)) return cli_fold_modes_run(argc, argv);
    cli_collide_opts co;
    int rc = cli_collide_strip("fold", &argc, argv, &co);
    if (rc != CLI_EXIT_OK) return rc;
    bool force;
    if ((rc = cli_guard_strip("fold", &argc, argv, &force)) != CLI_EXIT_OK) return rc;
    cli_fold_args a;
    rc = cli_fold_parse("fold", argc, argv, false, &a);
    if (rc != CLI_EXIT_OK) return rc;
    cli_kin k;
    rc = cli_kin_load_input("fold", a.path, a.frame, &a.input, &k);
    if (rc == CLI_EXIT_OK && (rc = cli_fold_resolve("fold", &a, &k)) != CLI_EXIT_OK) cli_kin_free(&k);
    if (rc != CLI_EXIT_OK) return rc;
    ori_motion_def def;
    rc = cli_fold_def("fold", &a, &k, &def);
    if (rc != CLI_EXIT_OK) {
        cli_kin_free(&k);
        return rc;
    }
    rc = guard_output(&a, &k, &def, force);
    if (rc != CLI_EXIT_OK) {
        cli_kin_free(&k);
        return rc;
    }
    ori_motion *mo = NULL;
    ori_error err;
    cli_progress bar; // the solve may run for minutes on a large sheet
    cli_progress_begin(&bar, "fold", "solving");
    def.progress = cli_progress_fn;
    def.progress_user = &bar;
    ori_status st = ori_motion_solve(k.mech, &def, &mo, &err);
    cli_progress_end(&bar);
    def.progress = NULL; // the collision check re-solves states between steps: no bar of its own
    def.progress_user = NULL;
    if (st != ORI_OK) {
        rc = cli_fold_solve_error("fold", &a, st, &err);
        cli_kin_free(&k);
        return rc;
    }
    cli_collision col;
    rc = cli_collide_motion("fold", a.path, &co, k.flat, k.mech, &def, mo, &col);
    if (rc != CLI_EXIT_OK) {
        ori_motion_destroy(mo);
        cli_kin_free(&k);
        return rc;
    }
    // An underdetermined fold names a lock set that leaves one degree of freedom (fold_modes.c).
    char locks_hint[1024] = "";
    if (ori_motion_verdict_of(mo) == ORI_MOTION_UNDERDETERMINED)
        cli_fold_modes_suggest(&k, &def, locks_hint, sizeof locks_hint, NULL);
    if (a.json) print_json(&a, &k, mo, &col, locks_hint);
    else print_text(&a, &k, mo, &col);
    if (!a.json && locks_hint[0]) printf("hint: %s\n", locks_hint);
    bool valid = ori_motion_verdict_of(mo) == ORI_MOTION_VALID;
    rc = valid && !cli_collides(&col) ? CLI_EXIT_OK : CLI_EXIT_NEGATIVE;
    ori_motion_block stop;
    if (ori_motion_block_of(mo, &stop) && stop.kind == ORI_BLOCK_STEP_LIMIT) rc = CLI_EXIT_PARTIAL; // (the budget)
    // A blocked fold writes its motion up to the stop, marked "orikin:partial".
    bool blocked = ori_motion_verdict_of(mo) == ORI_MOTION_BLOCKED && ori_motion_frame_count(mo) > 0;
    if (a.out && (valid || blocked)) {
        int wr = write_frames(&a, &k, mo, &col);
        if (wr != CLI_EXIT_OK) rc = wr;
        else if (!a.json && cli_motion_partial(mo, &col))
            printf("%s: the motion up to the stop (%d frames), marked \"orikin:partial\"\n", a.out,
                   cli_collide_frames(&col, ori_motion_frame_count(mo)));
    }
    ori_motion_destroy(mo);
    cli_kin_free(&k);
    return rc;
}

const cli_command cli_cmd_fold = {
    "fold",
    "fold rigidly: fix a face, lock creases, drive a crease; motion, branch and validity",
    "usage: orikin fold FILE [--fix FACE] --drive EDGE --to DEG [--from DEG] [--step DEG]\n"
    "                   [--lock E1,E2,...] [--frame N] [--solver S] [--linear L]\n"
    "                   [--no-collisions] [--clearance D] [--force] [--json] [-o OUT]\n"
    "\n"
    "Treat the crease pattern as a mechanism (faces = rigid bodies, creases = revolute joints),\n"
    "hold face FACE fixed and the locked creases at their current angle, and turn crease EDGE\n"
    "from its current angle (or --from) to --to degrees (positive = valley, negative =\n"
    "mountain). Every step is an exact solution of the loop-closure equations (residual below\n"
    "1e-10). Starting from the flat sheet, the branch is the one the MV assignment admits; the\n"
    "fold is invalid when every motion folds some crease against its assignment (the crease\n"
    "and the angle it would reach are named), and not rigidly foldable when no motion exists.\n"
    "A single vertex with four moving creases is solved in closed form and split into the\n"
    "thesis' Frame A, Frame B and surrounding; other patterns by numeric continuation.\n"
    "Every step is checked for self-collision (orikin collide); a motion that collides stops\n"
    "at the last clean step, with the first contact located to 1e-6 deg (verdict collision).\n"
    "A motion stops (verdict blocked) where a moving crease reaches +-180 deg (beyond, its faces\n"
    "would pass through each other) or at a singular point (the creases that can move there are\n"
    "named); no crease ever leaves [-180, 180] deg. From the flat sheet the branch is found once,\n"
    "a fixed 1 deg out: the verdict depends on neither --step nor how small --to is.\n"
    "Exit 0 valid, 1 invalid / not foldable / underdetermined / blocked / collision, 3 bad input,\n"
    "5 stopped at the budget of 50000 steps (the motion so far; beyond it, undetermined).\n"
    "\n"
    "options:\n"
    "  --fix FACE      face held fixed: FOLD index, name (Obj12) or @x,y (the face there);\n"
    "                  default: the face at the centroid of the sheet's area (named)\n"
    "  --drive EDGE    driven crease: FOLD index or @x,y (the crease through the point)\n"
    "  --to DEG        final angle of the driven crease, -180 to 180\n"
    "  --from DEG      output from this angle (reached first, silently); default: current\n"
    "  --step DEG      output spacing (> 0); default 10\n"
    "  --lock E1,...   creases held at their current angle: indices or @x,y, mixed; an @x,y\n"
    "                  item takes two fields (--lock 3,@0.5,1,9: crease 3, the one at (0.5, 1), 9)\n"
    "  --frame N       start from the fold angles (and 3D pose) of frame N; default 0\n"
    "  --weld          FOLD input: merge vertices closer than the length tolerance\n"
    "  --tolerance REL, --gaps REL|auto, --keep-collinear, --keep-holes\n"
    "                  drawing input (.svg, .opx, .cp: folded from flat), as in orikin info\n"    "  --solver S      auto (default), analytic (single vertex only) or numeric\n"
    "  --linear L      numeric solver's linear algebra: auto (default), dense, sparse or sweep\n"
    "  --no-collisions do not check the motion for self-collision\n"
    "  --clearance D   faces sharing no vertex closer than D collide too (a length >= 0)\n"
    "  --force         write even when the run would output more than 10000 frames or 1 GB\n"
    "  --json          print {file, valid, verdict, reason, collision: {step, drive_deg, faces,\n"
    "                  point} | null, hint, rigidly_foldable, dof (null without frames),\n"
    "                  grubler, solver, fixed_face, drive, to_deg, step_deg, locked, frame_a,\n"
    "                  frame_b, surrounding, split, offending_edges, blocked: {kind\n"
    "                  (crease_limit | singular), drive_deg, edge, edge_angle_deg,\n"
    "                  singular_edges} | null, partial, frames: [{drive_deg, fold_angles_deg,\n"
    "                  residual, other_branch_deg, end_effector}], stats}; every field in\n"
    "                  docs/kinematics.md\n"
    "  -o OUT.fold     write FILE with every step appended as a folded-form frame: when the\n"
    "                  fold is valid; when it is blocked, up to the stop, and when it collides,\n"
    "                  up to the last clean step, both marked by a top-level \"orikin:partial\"\n"
    "                  {verdict, reason, to_deg, reached_deg, frames, blocked}\n"
    "\n",
    run,
    CLI_FOLD_MODES_HELP
    "\n"
    CLI_FOLD_COMPLIANT_HELP
    "\n"
    "example: orikin fold examples/patterns/open-corner.fold --fix 4 --drive 12 --lock 11 --to 90\n",
};
