// orikin fold for patterns with several degrees of freedom: toward the targets (--percent),
// several drives, an automatic lock set and symmetry. See fold_modes.h.
#include "fold_modes.h"

#include "collide_args.h"
#include "output_guard.h"
#include "progress.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MODES_MAX_LIST 256
// A crease within this of its goal counts as at its goal in the text summary (radians).
#define MODES_AT_GOAL_RAD 1e-7
// Fractions of the way closer than this are a tie for "farthest" (the lowest crease is named).
#define MODES_FRACTION_TIE 1e-9

typedef struct modes_args {
    const char *path;
    const char *fix_spec;
    int fix;
    bool fix_default; // no --fix: the face at the sheet's centre
    bool has_percent;
    double percent;
    int drives[MODES_MAX_LIST], ndrives;
    const char *drive_spec, *lock_spec; // as given (indices and @x,y): resolved after loading
    double to[MODES_MAX_LIST];
    int nto;
    double ratio[MODES_MAX_LIST];
    int nratio;
    int locks[MODES_MAX_LIST], nlocks;
    bool lock_auto, symmetric, json;
    double step_deg;
    int frame;
    const char *out;
} modes_args;

bool cli_fold_modes_wanted(int argc, char **argv)
{
    for (int i = 1; i < argc; ++i) {
        const char *o = argv[i];
        if (strcmp(o, "--percent") == 0 || strcmp(o, "--symmetric") == 0 || strcmp(o, "--ratio") == 0) return true;
        if (i + 1 < argc && strcmp(o, "--drive") == 0 && cli_spec_edge_count(argv[i + 1]) > 1) return true;
        if (i + 1 < argc && strcmp(o, "--to") == 0 && strchr(argv[i + 1], ',')) return true;
    }
    return false;
}

// A comma-separated list of numbers; returns the count or -1.
static int parse_double_list(const char *s, double *out, int cap)
{
    int n = 0;
    const char *p = s;
    for (;;) {
        const char *c = strchr(p, ',');
        size_t len = c ? (size_t)(c - p) : strlen(p);
        char buf[64];
        if (len == 0 || len >= sizeof buf || n >= cap) return -1;
        memcpy(buf, p, len);
        buf[len] = '\0';
        if (!cli_parse_double(buf, &out[n++])) return -1;
        if (!c) return n;
        p = c + 1;
    }
}

static int parse(const char *cmd, int argc, char **argv, modes_args *a)
{
    memset(a, 0, sizeof *a);
    a->step_deg = 10.0;
    cli_seen seen = {0};
    for (int i = 1; i < argc; ++i) {
        const char *o = argv[i];
        const char *v = NULL;
        if (strcmp(o, "--json") == 0) {
            a->json = true;
        } else if (strcmp(o, "--symmetric") == 0) {
            a->symmetric = true;
        } else if (strcmp(o, "--frame") == 0) {
            int rc = cli_option_frame_once(cmd, argc, argv, &i, &seen, &a->frame);
            if (rc != CLI_EXIT_OK) return rc;
        } else if (strcmp(o, "--fix") == 0 || strcmp(o, "--percent") == 0 || strcmp(o, "--drive") == 0 ||
                   strcmp(o, "--to") == 0 || strcmp(o, "--ratio") == 0 || strcmp(o, "--lock") == 0 ||
                   strcmp(o, "--step") == 0 || strcmp(o, "-o") == 0) {
            if (!(v = cli_option_once(cmd, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (strcmp(o, "--fix") == 0) {
                a->fix_spec = v;
            } else if (strcmp(o, "--percent") == 0) {
                if (!cli_parse_double(v, &a->percent) || a->percent < 0.0 || a->percent > 100.0)
                    return cli_usage(cmd, "--percent needs a number from 0 to 100, got '%s'", v);
                a->has_percent = true;
            } else if (strcmp(o, "--drive") == 0) {
                a->ndrives = cli_spec_edge_count(v);
                if (a->ndrives > MODES_MAX_LIST)
                    return cli_usage(cmd, "--drive takes at most %d edges, got %d", MODES_MAX_LIST, a->ndrives);
                if (a->ndrives <= 0)
                    return cli_usage(cmd, "--drive: creases are indices or @x,y, comma-separated, got '%s'", v);
                a->drive_spec = v;
            } else if (strcmp(o, "--to") == 0) {
                a->nto = parse_double_list(v, a->to, MODES_MAX_LIST);
                if (a->nto <= 0) return cli_usage(cmd, "--to needs comma-separated angles in degrees, got '%s'", v);
                for (int k = 0; k < a->nto; ++k)
                    if (!(fabs(a->to[k]) <= 180.0))
                        return cli_usage(cmd, "--to %g is outside [-180, 180] degrees", a->to[k]);
            } else if (strcmp(o, "--ratio") == 0) {
                a->nratio = parse_double_list(v, a->ratio, MODES_MAX_LIST);
                if (a->nratio <= 0) return cli_usage(cmd, "--ratio needs comma-separated numbers, got '%s'", v);
            } else if (strcmp(o, "--lock") == 0) {
                if (strcmp(v, "auto") == 0) {
                    a->lock_auto = true;
                } else {
                    a->nlocks = cli_spec_edge_count(v);
                    if (a->nlocks > MODES_MAX_LIST)
                        return cli_usage(cmd, "--lock takes at most %d edges, got %d", MODES_MAX_LIST, a->nlocks);
                    if (a->nlocks < 0)
                        return cli_usage(cmd, "--lock: creases are indices or @x,y, comma-separated, or auto, got '%s'", v);
                    a->lock_spec = v;
                }
            } else if (strcmp(o, "--step") == 0) {
                if (!cli_parse_double(v, &a->step_deg) || !(a->step_deg > 0.0))
                    return cli_usage(cmd, "--step needs a positive angle in degrees, got '%s'", v);
            } else {
                a->out = v;
            }
        } else if (strcmp(o, "--from") == 0 || strcmp(o, "--solver") == 0 || strcmp(o, "--linear") == 0) {
            return cli_usage(cmd, "%s applies to a single drive, not with --percent, several drives, --ratio or "
                                  "--symmetric", o);
        } else if (o[0] == '-' && o[1] != '\0') {
            return cli_usage(cmd, "unknown option %s", o);
        } else if (!a->path) {
            a->path = o;
        } else {
            return cli_usage(cmd, "one FILE only");
        }
    }
    if (!a->path) return cli_usage(cmd, "missing FILE");
    if (a->has_percent) {
        if (a->ndrives || a->nto || a->nratio)
            return cli_usage(cmd, "--percent folds every crease toward its target: no --drive, --to or --ratio with it");
        if (a->lock_auto) return cli_usage(cmd, "--lock auto applies to drives: --percent needs no lock set");
        return CLI_EXIT_OK;
    }
    if (!a->ndrives) return cli_usage(cmd, "missing --drive EDGE (or --percent P)");
    if (!a->nto) return cli_usage(cmd, "missing --to DEG");
    if (a->nratio) {
        if (a->nto != 1) return cli_usage(cmd, "--ratio takes one --to angle (crease Ei goes to Ri x that angle)");
        if (a->nratio != a->ndrives)
            return cli_usage(cmd, "--ratio has %d values for %d driven creases", a->nratio, a->ndrives);
        double base = a->to[0];
        for (int k = 0; k < a->ndrives; ++k) {
            a->to[k] = a->ratio[k] * base;
            if (!(fabs(a->to[k]) <= 180.0))
                return cli_usage(cmd, "--ratio %g x --to %g = %g is outside [-180, 180] degrees", a->ratio[k], base,
                                 a->to[k]);
        }
        a->nto = a->ndrives;
    } else if (a->nto != a->ndrives) {
        return cli_usage(cmd, "--to has %d angles for %d driven creases", a->nto, a->ndrives);
    }
    return CLI_EXIT_OK;
}

// The lock-set search of an underdetermined fold's hint, with a progress bar on stderr when it
// runs over a second (a large flat sheet: seconds); when it finds none, the hint says so.
static int lock_suggestion(const char *cmd, const ori_mechanism *m, const double *angles, const int *drives, int ndrives,
                           const int *locked, int nlocked, const int *group, char *buf, size_t size, json_t **locks)
{
    buf[0] = '\0';
    int cap = ori_mechanism_edge_count(m) + 1;
    int *out = malloc(sizeof(int) * (size_t)cap);
    ori_error err;
    cli_progress bar;
    cli_progress_begin(&bar, cmd, "looking for a lock set");
    int n = ori_mechanism_lock_set_progress(m, angles, drives, ndrives, locked, nlocked, group, out, cap,
                                            cli_progress_fn, &bar, &err);
    cli_progress_end(&bar);
    if (n > 0) {
        cli_lock_text(out, n, buf, size);
        if (locks) {
            *locks = json_array();
            for (int i = 0; i < n; ++i) json_array_append_new(*locks, json_integer(out[i]));
        }
    } else {
        snprintf(buf, size,
                 "no lock set found (%s); or start from a folded frame (--percent first, then --frame), or use "
                 "--symmetric",
                 n == 0 ? "the search locked nothing" : err.message);
    }
    free(out);
    return n;
}

int cli_fold_modes_suggest(const cli_kin *k, const ori_motion_def *def, char *buf, size_t size, json_t **locks)
{
    return lock_suggestion("fold", k->mech, def->start_angles_rad, &def->driven_edge, 1, def->locked_edges,
                           def->locked_count, NULL, buf, size, locks);
}

struct cli_fold_modes {
    const char *cmd;
    modes_args a;
    cli_kin k;
    cli_modes x; // the request as solved and its result (cli/report/modes_report.c)
    cli_collide_opts co;
};
typedef struct cli_fold_modes modes_run;

// Frames shown and written: all of them, or those before the first collision.
static int shown_frames(const modes_run *r) { return cli_modes_shown_frames(&r->x); }

// The creases whose angle changes (at most cap), for the text table.
static int moving_creases(const modes_run *r, int *cols, int cap, int *total)
{
    const ori_multifold *mf = r->x.mf;
    int E = ori_mechanism_edge_count(r->k.mech), F = shown_frames(r), n = 0;
    *total = 0;
    if (F < 2) return 0;
    const double *a0 = ori_multifold_frame_angles(mf, 0), *a1 = ori_multifold_frame_angles(mf, F - 1);
    for (int e = 0; e < E; ++e)
        if (fabs(a1[e] - a0[e]) > ORI_TOL_FOLD_SIGN_RAD) {
            (*total)++;
            if (n < cap) cols[n++] = e;
        }
    return n;
}

// The text summary of the rows: how many reached their goal, how many stayed at their start
// while short of it, and the moving crease farthest from its goal by fraction of its way (the
// lowest fraction; -1 when every moving crease is at its goal).
typedef struct crease_summary {
    int at, still, farthest;
} crease_summary;

static crease_summary summarize_creases(cli_modes_crease *rows, int n)
{
    crease_summary cs = {0, 0, -1};
    for (int i = 0; i < n; ++i) {
        cli_modes_crease *c = &rows[i];
        bool at = fabs(c->reached - c->goal) <= MODES_AT_GOAL_RAD;
        c->still = !at && fabs(c->reached - c->start) <= ORI_TOL_FOLD_SIGN_RAD;
        if (at) cs.at++;
        else if (c->still) cs.still++;
        else if (cs.farthest < 0 || c->fraction < rows[cs.farthest].fraction - MODES_FRACTION_TIE) cs.farthest = i;
    }
    return cs;
}

static void print_text(const modes_run *r)
{
    const modes_args *a = &r->a;
    const ori_multifold *mf = r->x.mf;
    int E = ori_mechanism_edge_count(r->k.mech), F = shown_frames(r);
    if (a->has_percent) {
        printf("%s: fold toward the targets, %g %% of the way (step %g deg), face %d fixed%s", a->path, a->percent,
               a->step_deg, a->fix, a->fix_default ? CLI_FOLD_DEFAULT_FIX_NOTE : "");
    } else {
        printf("%s: drive", a->path);
        for (int i = 0; i < a->ndrives; ++i) printf("%s crease %d to %g deg", i ? "," : "", a->drives[i], a->to[i]);
        printf(" together (step %g deg), face %d fixed%s", a->step_deg, a->fix, a->fix_default ? CLI_FOLD_DEFAULT_FIX_NOTE : "");
    }
    if (r->x.nlocks) {
        printf(", locked%s", a->lock_auto ? " (auto)" : "");
        for (int i = 0; i < r->x.nlocks; ++i) printf("%s%d", i ? "," : " ", r->x.locks[i]);
    }
    printf("\n");
    if (r->x.group)
        printf("symmetry: %d symmetries of the flat pattern; %d groups of creases kept at equal angles\n", r->x.sym_order,
               r->x.sym_groups);
    int cols[8], total;
    int nc = moving_creases(r, cols, 8, &total);
    if (F > 0) {
        printf("%9s", "progress");
        for (int i = 0; i < nc; ++i) printf(" %11s%-4d", "crease ", cols[i]);
        printf("  residual\n");
        for (int f = 0; f < F; ++f) {
            printf("%9.4f", ori_multifold_frame_progress(mf, f));
            for (int i = 0; i < nc; ++i) printf(" %15.6f", ori_rad_to_deg_output(ori_multifold_frame_angles(mf, f)[cols[i]]));
            printf("  %.1e\n", ori_multifold_frame_residual(mf, f));
        }
        if (total > nc) printf("(%d more moving creases: see --json)\n", total - nc);
    }
    ori_multifold_verdict v = ori_multifold_verdict_of(mf);
    if (cli_collides(&r->x.col)) {
        char hit[256];
        cli_collision_describe(&r->x.col, false, hit, sizeof hit);
        printf("verdict: collision: %s (the motion stops at the last clean step)\n", hit);
    } else {
        printf("verdict: %s: %s\n", ori_multifold_verdict_name(v), ori_multifold_reason(mf));
    }
    if (ori_multifold_held_count(mf))
        printf("note: %d crease%s reached 180 deg (%s target) first and %s held there\n", ori_multifold_held_count(mf),
               ori_multifold_held_count(mf) == 1 ? "" : "s", ori_multifold_held_count(mf) == 1 ? "its" : "their",
               ori_multifold_held_count(mf) == 1 ? "was" : "were");
    if (r->x.hint[0]) printf("hint: %s\n", r->x.hint);
    cli_modes_against *ag = malloc(sizeof(cli_modes_against) * (size_t)(E + 1));
    int na = cli_modes_against_assignment(&r->x, ag);
    if (na && v != ORI_MULTIFOLD_INVALID_ASSIGNMENT) { // else the verdict names them
        printf("note: %d crease%s fold%s against %s assignment:", na, na == 1 ? "" : "s", na == 1 ? "s" : "",
               na == 1 ? "its" : "their");
        for (int i = 0; i < na && i < 8; ++i)
            printf("%s crease %d (%c) to %.6g deg", i ? "," : "", ag[i].edge, ag[i].assignment,
                   ori_rad_to_deg_output(ag[i].angle));
        printf("%s\n", na > 8 ? ", ... (--json)" : "");
    }
    free(ag);
    cli_modes_crease *rows = malloc(sizeof(cli_modes_crease) * (size_t)(E + 1));
    int nr = cli_modes_creases(&r->x, rows);
    crease_summary cs = summarize_creases(rows, nr);
    if (nr > 0 && a->has_percent && a->percent < 100.0 && v == ORI_MULTIFOLD_REACHED) {
        // Part of the way: where each crease got on its way to its target.
        int lo = 0, hi = 0;
        for (int i = 1; i < nr; ++i) {
            if (rows[i].fraction < rows[lo].fraction - MODES_FRACTION_TIE) lo = i;
            if (rows[i].fraction > rows[hi].fraction + MODES_FRACTION_TIE) hi = i;
        }
        printf("creases: %d on their way to their targets, from fraction %.4f (crease %d at %.6g deg) to %.4f (crease %d "
               "at %.6g deg) (per crease: --json)\n",
               nr, rows[lo].fraction, rows[lo].edge, ori_rad_to_deg_output(rows[lo].reached), rows[hi].fraction,
               rows[hi].edge, ori_rad_to_deg_output(rows[hi].reached));
    } else if (nr > 0) {
        printf("creases: %d of %d at their goal", cs.at, nr);
        if (cs.farthest >= 0)
            printf("; farthest of the moving: crease %d at %.6g deg, goal %.6g deg (fraction %.4f)", rows[cs.farthest].edge,
                   ori_rad_to_deg_output(rows[cs.farthest].reached), ori_rad_to_deg_output(rows[cs.farthest].goal),
                   rows[cs.farthest].fraction);
        if (cs.still) {
            printf("; %d did not move from their start:", cs.still);
            for (int i = 0, k = 0; i < nr && k < 8; ++i)
                if (rows[i].still) printf("%s%d", k++ ? "," : " ", rows[i].edge);
            printf("%s (the rigid motion from this start leaves them there)", cs.still > 8 ? ",..." : "");
        }
        printf(" (per crease: --json)\n");
    }
    free(rows);
}

static int write_frames(const modes_run *r)
{
    const ori_mechanism *m = r->k.mech;
    const ori_multifold *mf = r->x.mf;
    int V = ori_mechanism_vertex_count(m), E = ori_mechanism_edge_count(m);
    bool collides = cli_collides(&r->x.col);
    bool partial = collides || ori_multifold_verdict_of(mf) != ORI_MULTIFOLD_REACHED;
    ori_v3 *pos = malloc(sizeof(ori_v3) * (size_t)(V + 1));
    for (int f = 0; f < shown_frames(r); ++f) {
        ori_multifold_frame_vertices(mf, f, pos);
        char title[160];
        snprintf(title, sizeof title, "%s: %.6g %% of the way%s%s", r->a.has_percent ? "fold toward the targets" : "drives",
                 100.0 * ori_multifold_frame_progress(mf, f), partial ? " (partial: " : "",
                 !partial ? "" : collides ? "collision" : ori_multifold_verdict_name(ori_multifold_verdict_of(mf)));
        if (partial) strncat(title, ")", sizeof title - strlen(title) - 1);
        ori_fold_append_state(r->k.doc, 0, V, pos, E, ori_multifold_frame_angles(mf, f), title);
    }
    free(pos);
    ori_error err;
    if (ori_fold_save_file(r->k.doc, r->a.out, &err) != ORI_OK) return cli_input_error("fold", r->a.out, &err);
    return CLI_EXIT_OK;
}

static int check_edge(const modes_run *r, const char *option, int e)
{
    int E = ori_mechanism_edge_count(r->k.mech);
    if (e < 0 || e >= E)
        return cli_value_fail(r->cmd, r->a.path, option, "no edge %d (the pattern has edges 0 to %d)", e, E - 1);
    return CLI_EXIT_OK;
}

static int solve(modes_run *r)
{
    const modes_args *a = &r->a;
    ori_rigid pose;
    int rc = cli_kin_fixed_pose(r->cmd, a->path, &r->k, a->fix, &pose);
    if (rc != CLI_EXIT_OK) return rc;
    for (int i = 0; i < a->nlocks; ++i)
        if ((rc = check_edge(r, "--lock", a->locks[i])) != CLI_EXIT_OK) return rc;
    for (int i = 0; i < a->ndrives; ++i)
        if ((rc = check_edge(r, "--drive", a->drives[i])) != CLI_EXIT_OK) return rc;
    cli_modes *x = &r->x;
    x->fix = a->fix;
    x->has_percent = a->has_percent;
    x->percent = a->percent;
    x->drives = a->drives;
    x->to_deg = a->to;
    x->ndrives = a->ndrives;
    x->given_locks = a->locks;
    x->ngiven = a->nlocks;
    x->lock_auto = a->lock_auto;
    x->symmetric = a->symmetric;
    x->step_deg = a->step_deg;
    x->mech = r->k.mech;
    x->flat = r->k.flat;
    x->start = r->k.angles;
    x->pose = pose;
    cli_progress bar; // a large sheet's solve may run for minutes
    cli_progress_begin(&bar, r->cmd, "solving");
    x->progress = cli_progress_fn;
    x->progress_user = &bar;
    ori_error err;
    ori_status st = cli_modes_solve(x, &err);
    cli_progress_end(&bar);
    x->progress = NULL;
    x->progress_user = NULL;
    if (st != ORI_OK) {
        if (x->lock_set_failed) return cli_input_error(r->cmd, a->path, &err);
        // A driven or locked crease the fold cannot use is a command-line value: usage error.
        for (int i = 0; i < a->ndrives && strcmp(err.field, "edges_vertices") == 0; ++i)
            if (err.element == a->drives[i]) return cli_value_fail(r->cmd, a->path, "--drive", "%s", err.message);
        rc = cli_input_error(r->cmd, a->path, &err);
        return st == ORI_ERR_NOT_CONVERGED || st == ORI_ERR_INTERNAL ? CLI_EXIT_INTERNAL : rc;
    }
    cli_progress hb; // an underdetermined fold's lock-set search (a large flat sheet: seconds)
    cli_progress_begin(&hb, r->cmd, "looking for a lock set");
    cli_modes_hint(x, cli_progress_fn, &hb);
    cli_progress_end(&hb);
    return CLI_EXIT_OK;
}

// The output guard (output_guard.h): at least the largest crease change to the goal (percent)
// or of a drive (several drives) over the step, frames; asks for --force beyond it.
static int guard_output(const modes_run *r, bool force)
{
    const modes_args *a = &r->a;
    const ori_pattern *p = r->k.flat;
    int E = ori_pattern_edge_count(p), V = ori_pattern_vertex_count(p);
    double change = 0.0;
    if (a->has_percent) {
        double *tgt = malloc(sizeof(double) * (size_t)(E + 1));
        ori_target_angles_default(p, tgt);
        for (int e = 0; e < E; ++e) change = fmax(change, fabs(a->percent / 100.0 * (tgt[e] - r->k.angles[e])));
        free(tgt);
    } else {
        for (int i = 0; i < a->ndrives && i < a->nto; ++i)
            change = fmax(change, fabs(ori_deg_to_rad(a->to[i]) - r->k.angles[a->drives[i]]));
    }
    double frames = floor(change / ori_deg_to_rad(a->step_deg)) + 1.0;
    double bytes = (a->out ? frames * (3.0 * V + E) * 20.0 : 0.0) + (a->json ? frames * E * 20.0 : 0.0);
    return cli_guard_check(r->cmd, frames, bytes, force);
}

// Load the pattern and resolve the faces and creases named.
static int load_resolve(modes_run *r)
{
    const char *cmd = r->cmd;
    int rc = cli_kin_load(cmd, r->a.path, r->a.frame, &r->k);
    if (rc != CLI_EXIT_OK) return rc;
    if (r->a.fix_spec) {
        rc = cli_spec_face(cmd, r->a.path, r->k.flat, "--fix", r->a.fix_spec, &r->a.fix);
    } else { // no --fix: the face at the sheet's centre
        r->a.fix = cli_fold_default_fix(r->k.flat);
        r->a.fix_default = true;
    }
    if (rc == CLI_EXIT_OK && r->a.drive_spec) { // the drives in order, repeats kept (refused by the solve)
        r->a.ndrives = cli_spec_edges(cmd, r->a.path, r->k.flat, "--drive", r->a.drive_spec, false, r->a.drives, MODES_MAX_LIST);
        if (r->a.ndrives < 0) rc = -r->a.ndrives;
    }
    if (rc == CLI_EXIT_OK && r->a.lock_spec) {
        r->a.nlocks = cli_spec_edges(cmd, r->a.path, r->k.flat, "--lock", r->a.lock_spec, true, r->a.locks, MODES_MAX_LIST);
        if (r->a.nlocks < 0) rc = -r->a.nlocks;
    }
    return rc;
}

int cli_fold_modes_open(const char *cmd, int argc, char **argv, cli_fold_modes **out)
{
    *out = NULL;
    modes_run *r = calloc(1, sizeof *r);
    if (!r) return cli_usage(cmd, "out of memory");
    r->cmd = cmd;
    int rc = parse(cmd, argc, argv, &r->a);
    if (rc != CLI_EXIT_OK) {
        free(r);
        return rc;
    }
    *out = r;
    return CLI_EXIT_OK;
}

int cli_fold_modes_solve(cli_fold_modes *r)
{
    int rc = load_resolve(r);
    if (rc == CLI_EXIT_OK) rc = solve(r);
    return rc;
}

const ori_multifold *cli_fold_modes_result(const cli_fold_modes *r) { return r->x.mf; }
cli_kin *cli_fold_modes_kin(cli_fold_modes *r) { return &r->k; }
int cli_fold_modes_fixed_face(const cli_fold_modes *r) { return r->a.fix; }
bool cli_fold_modes_fix_default(const cli_fold_modes *r) { return r->a.fix_default; }

const int *cli_fold_modes_locks(const cli_fold_modes *r, int *count)
{
    *count = r->x.nlocks;
    return r->x.locks;
}

void cli_fold_modes_label(const cli_fold_modes *r, char *buf, size_t size)
{
    const modes_args *a = &r->a;
    const ori_multifold *mf = r->x.mf;
    int F = mf ? ori_multifold_frame_count(mf) : 0;
    double reached = F ? 100.0 * ori_multifold_frame_progress(mf, F - 1) : 0.0;
    if (a->has_percent) {
        snprintf(buf, size, "toward the targets, %g %%", a->percent);
    } else {
        size_t w = (size_t)snprintf(buf, size, "creases");
        for (int i = 0; i < a->ndrives && w < size; ++i)
            w += (size_t)snprintf(buf + w, size - w, "%s%d", i ? "," : " ", a->drives[i]);
        if (w < size) w += (size_t)snprintf(buf + w, size - w, " to");
        for (int i = 0; i < a->ndrives && w < size; ++i)
            w += (size_t)snprintf(buf + w, size - w, "%s%g", i ? "," : " ", a->to[i]);
        if (w < size) snprintf(buf + w, size - w, " deg");
    }
    if (mf && ori_multifold_verdict_of(mf) != ORI_MULTIFOLD_REACHED) {
        size_t w = strlen(buf);
        if (w < size)
            snprintf(buf + w, size - w, " (%s at %.3g %% of the way)", ori_multifold_verdict_name(ori_multifold_verdict_of(mf)),
                     reached);
    }
}

void cli_fold_modes_free(cli_fold_modes *r)
{
    if (!r) return;
    cli_modes_free(&r->x);
    cli_kin_free(&r->k);
    free(r);
}

int cli_fold_modes_run(int argc, char **argv)
{
    modes_run r;
    memset(&r, 0, sizeof r);
    r.cmd = "fold";
    // The collision and output-guard options come out of a copy of the command line.
    char **av = malloc(sizeof(char *) * (size_t)(argc + 1));
    memcpy(av, argv, sizeof(char *) * (size_t)argc);
    av[argc] = NULL;
    int ac = argc;
    int rc = cli_collide_strip("fold", &ac, av, &r.co);
    bool force = false;
    if (rc == CLI_EXIT_OK) rc = cli_guard_strip("fold", &ac, av, &force);
    if (rc == CLI_EXIT_OK) rc = parse("fold", ac, av, &r.a);
    free(av);
    if (rc != CLI_EXIT_OK) return rc;
    rc = load_resolve(&r);
    if (rc == CLI_EXIT_OK) rc = guard_output(&r, force);
    if (rc == CLI_EXIT_OK) rc = solve(&r);
    if (rc == CLI_EXIT_OK)
        rc = cli_collide_multifold("fold", r.a.path, &r.co, r.k.flat, r.x.mf, r.x.locks, r.x.nlocks, &r.x.col);
    if (rc == CLI_EXIT_OK) {
        if (r.a.json) cli_print_json(cli_modes_json(&r.x, r.a.path));
        else print_text(&r);
        ori_multifold_verdict v = ori_multifold_verdict_of(r.x.mf);
        rc = v == ORI_MULTIFOLD_REACHED && !cli_collides(&r.x.col) ? CLI_EXIT_OK : CLI_EXIT_NEGATIVE;
        if (r.a.out && shown_frames(&r) > 0) {
            int wr = write_frames(&r);
            if (wr != CLI_EXIT_OK) rc = wr;
        }
    }
    cli_modes_free(&r.x);
    cli_kin_free(&r.k);
    return rc;
}
