// orikin collide: self-collision of one folded state — penetrating and touching face pairs,
// the least clearance with its witness, and optionally the thesis' cloud of proximity.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "collide_args.h"
#include "state_args.h"

#define MAX_LISTED 20

typedef struct collide_args {
    cli_state_args state;
    bool has_clearance, has_cloud, json;
    double clearance, spacing;
    const char *clearance_raw, *cloud_raw;
} collide_args;

static int parse(int argc, char **argv, collide_args *a)
{
    memset(a, 0, sizeof *a);
    cli_state_args_init(&a->state);
    int rc;
    for (int i = 1; i < argc; ++i) {
        const char *o = argv[i];
        int took = cli_state_option("collide", argc, argv, &i, &a->state, &rc);
        if (took < 0) return rc;
        if (took) continue;
        if (strcmp(o, "--json") == 0) {
            a->json = true;
        } else if (strcmp(o, "--clearance") == 0 || strcmp(o, "--cloud") == 0) {
            bool cloud = strcmp(o, "--cloud") == 0;
            if (cloud ? a->has_cloud : a->has_clearance) return cli_usage("collide", "%s given twice", o);
            const char *v = cli_option_value("collide", argc, argv, &i);
            if (!v) return CLI_EXIT_USAGE;
            double x;
            if (!cli_parse_double(v, &x)) return cli_usage("collide", "%s needs a length, got '%s'", o, v);
            if (cloud) {
                a->spacing = x;
                a->has_cloud = true;
                a->cloud_raw = v;
            } else {
                a->clearance = x;
                a->has_clearance = true;
                a->clearance_raw = v;
            }
        } else if (o[0] == '-' && o[1] != '\0') {
            return cli_usage("collide", "unknown option %s", o);
        } else {
            return cli_usage("collide", "one IN only");
        }
    }
    rc = cli_state_finish("collide", &a->state);
    if (rc == CLI_EXIT_OK && a->state.compliant)
        return cli_usage("collide", "a compliant fold bends its faces, which collide checks as planar panels: orikin fold "
                                    "--compliant warns of the faces that pass through each other at each load step");
    return rc;
}

static void print_json(const collide_args *a, const cli_state *s, const ori_collider *c, const ori_collision_result *r,
                       const ori_cloud_result *cr, double cloud_distance)
{
    cli_print_json(cli_collide_json(s->path, s->source == CLI_STATE_FRAME ? a->state.frame : -1, s->label,
                                    s->source != CLI_STATE_FRAME || s->cp_frame, c, r, a->clearance, cr, a->spacing,
                                    cloud_distance));
}

static void list_pairs(const ori_collider *c, ori_contact_kind kind)
{
    int n = 0;
    for (int i = 0; i < ori_collider_contact_count(c); ++i) {
        ori_contact k = ori_collider_contact(c, i);
        if (k.kind != kind) continue;
        if (n < MAX_LISTED)
            printf("  faces %d and %d at (%.6g, %.6g, %.6g)%s%s\n", k.face_a, k.face_b, k.point.x, k.point.y,
                   k.point.z, k.stacked ? ", stacked layers" : "", k.adjacent ? ", away from their shared vertex" : "");
        n++;
    }
    if (n > MAX_LISTED) printf("  (%d more: see --json)\n", n - MAX_LISTED);
}

static void print_text(const collide_args *a, const cli_state *s, const ori_collider *c, const ori_collision_result *r,
                       const ori_cloud_result *cr, double cloud_distance)
{
    int nf = ori_collider_face_count(c);
    const char *how = s->source == CLI_STATE_FOLD       ? "posed by the fold"
                      : s->source == CLI_STATE_SEQUENCE ? "posed by the sequence"
                      : s->cp_frame                     ? "posed from its fold angles"
                                                        : "folded form";
    (void)a;
    printf("%s (%s): %d faces, %s\n", s->path, s->label, nf, how);
    printf("penetrating        %d pairs\n", r->penetrating);
    list_pairs(c, ORI_CONTACT_PENETRATING);
    printf("touching           %d pairs\n", r->touching);
    list_pairs(c, ORI_CONTACT_TOUCHING);
    if (a->clearance > 0.0) {
        printf("closer than %g  %d pairs\n", a->clearance, r->near);
        list_pairs(c, ORI_CONTACT_NEAR);
    }
    if (isfinite(r->min_clearance))
        printf("min clearance      %.9g between faces %d and %d, at (%.6g, %.6g, %.6g)\n", r->min_clearance,
               r->clearance_faces[0], r->clearance_faces[1],
               0.5 * (r->clearance_points[0].x + r->clearance_points[1].x),
               0.5 * (r->clearance_points[0].y + r->clearance_points[1].y),
               0.5 * (r->clearance_points[0].z + r->clearance_points[1].z));
    else
        printf("min clearance      none (every pair of faces shares a vertex)\n");
    if (cr) {
        printf("cloud of proximity %lld samples at spacing %g; %lld sample pairs closer than %g on %d face pairs",
               (long long)cr->points, a->spacing, (long long)cr->point_pairs, cloud_distance, cr->face_pairs);
        if (isfinite(cr->min_distance)) printf(", least %.6g", cr->min_distance);
        printf("\n");
    }
    printf("broad phase        %lld candidate pairs of %lld\n", (long long)r->candidate_pairs,
           (long long)nf * (nf - 1) / 2);
    printf("verdict: %s\n", r->collides ? "collision" : "clean");
}

static int run(int argc, char **argv)
{
    collide_args a;
    int rc = parse(argc, argv, &a);
    if (rc != CLI_EXIT_OK) return rc;
    const char *path = a.state.path;
    if (a.has_clearance && !(a.clearance >= 0.0))
        return cli_value_fail("collide", path, "--clearance", "must be a length >= 0, got %s", a.clearance_raw);
    if (a.has_cloud && !(a.spacing > 0.0))
        return cli_value_fail("collide", path, "--cloud", "needs a sample spacing > 0, got %s", a.cloud_raw);
    cli_state s;
    if ((rc = cli_state_load("collide", &a.state, true, &s)) != CLI_EXIT_OK) return rc;
    if (s.cp_frame && !ori_pattern_has_fold_angles(s.pattern)) {
        cli_state_free(&s);
        return cli_input_fail("collide", path,
                              "frame %d has neither 3D vertices_coords nor edges_foldAngle: there is no folded state to "
                              "check (fold it with --fix, --drive and --to)",
                              a.state.frame);
    }
    // A folded-form frame is checked on its own pattern (its size sets the tolerances), as the
    // studio's POST /api/collide does.
    const ori_pattern *checked = s.frame_pattern ? s.frame_pattern : s.pattern;
    if (ori_pattern_face_count(checked) == 0) {
        cli_state_free(&s);
        return cli_input_fail("collide", path, "faces_vertices: frame %d is a folded form without faces", a.state.frame);
    }
    ori_collider_def cd = ori_default_collider_def();
    cd.pattern = checked;
    cd.clearance = a.clearance;
    ori_collider *c = NULL;
    ori_error err;
    ori_collision_result r;
    ori_cloud_result cr;
    double cloud_distance = a.clearance > 0.0 ? a.clearance : a.spacing;
    if (ori_collider_create(&cd, &c, &err) != ORI_OK || ori_collider_check(c, s.positions, &r, &err) != ORI_OK) {
        rc = cli_input_error("collide", path, &err);
    } else if (a.has_cloud) {
        ori_cloud_def cl = ori_default_cloud_def();
        cl.spacing = a.spacing;
        cl.distance = cloud_distance;
        if (ori_collider_cloud(c, s.positions, &cl, &cr, &err) != ORI_OK) {
            if (err.status == ORI_ERR_RANGE)
                rc = cli_input_fail("collide", path, "--cloud: %s", err.message);
            else
                rc = cli_input_error("collide", path, &err);
        }
    }
    if (rc == CLI_EXIT_OK) {
        if (a.json) print_json(&a, &s, c, &r, a.has_cloud ? &cr : NULL, cloud_distance);
        else print_text(&a, &s, c, &r, a.has_cloud ? &cr : NULL, cloud_distance);
        rc = r.collides ? CLI_EXIT_NEGATIVE : CLI_EXIT_OK;
    }
    ori_collider_destroy(c);
    cli_state_free(&s);
    return rc;
}

const cli_command cli_cmd_collide = {
    "collide",
    "self-collision of a folded state: penetrating and touching faces, least clearance",
    "usage: orikin collide IN [--frame N | fold options | --at T] [--clearance D]\n"
    "                      [--cloud SPACING] [--json]\n"
    "\n"
    "Check one folded state of IN for self-collision, exactly: every pair of faces that\n"
    "penetrate, every pair that only touch (an edge or a corner on a face, layers stacked flat),\n"
    "and the least clearance between faces that share no vertex, with a witness point. Faces\n"
    "that share a vertex or a crease meet there by construction and are only checked away from\n"
    "it. The state is named as for render and export: a FOLD frame (a folded form with 3D\n"
    "vertices_coords is checked as it is; a crease pattern with edges_foldAngle is first posed\n"
    "by forward kinematics, an error when its loops do not close), the last step of a fold\n"
    "(the options of `orikin fold`), or an instant of a fold sequence SEQ.json (--at T).\n"
    "To check a whole motion, use `orikin fold` or `orikin sequence` (they check by default).\n"
    "Tolerances are relative to the pattern's size (docs/collision.md).\n"
    "Exit 0 clean, 1 collides, 3 bad input (a non-planar face, nothing to pose).\n"
    "\n"
    "options:\n"
    "  --frame N          the state in frame N of a FOLD file (default 0)\n"
    "  --fix F --drive E --to DEG [--from DEG] [--step DEG] [--lock E1,...] [--solver S]\n"
    "  [--linear L]       a fold (see orikin fold); the state is its last step. F: a face index,\n"
    "                     name (Obj12) or @x,y; E: a crease index or @x,y; --lock 3,@0.5,1,9\n"
    "  --percent P | --drive E1,E2,... --to A1,A2,... [--ratio R1,...] | --lock auto | --symmetric\n"
    "                     the modes of orikin fold: the state is where that fold ends (its goal,\n"
    "                     or where it stops short, said on stderr), and its motion is checked;\n"
    "                     --fix is optional (default: the face at the sheet's centre)\n"
    "  --at T             the instant T of a fold sequence (default: its end)\n"
    "  --clearance D      faces sharing no vertex closer than D collide too (a length >= 0;\n"
    "                     thickness-aware checks)\n"
    "  --cloud SPACING    also run the thesis' cloud of proximity: samples SPACING apart on\n"
    "                     every face, sample pairs closer than D (or SPACING without --clearance)\n"
    "  --json             print {file, frame, state, posed, faces, collides, pairs, touching,\n"
    "                     min_clearance, witness, clearance_faces, clearance, tolerance,\n"
    "                     contacts: [{faces, kind, adjacent, stacked, point, distance}],\n"
    "                     candidate_pairs, cloud: {spacing, distance, points, point_pairs,\n"
    "                     min_distance, faces: [{faces, point_pairs, distance}]} | null}\n"
    "\n"
    "example: orikin collide examples/open-corner.seq.json --at 1.5 --clearance 0.01\n",
    run,
    NULL,
};
