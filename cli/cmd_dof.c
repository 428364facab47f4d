// orikin dof: degrees of freedom of a crease pattern's mechanism at a state.
#include <stdlib.h>
#include <string.h>

#include "kin_args.h"
#include "report.h"
#include "progress.h"

// The mechanism and the fold angles of --frame N as fold reads them (cli_kin_load_input): frame 0
// (or a crease-pattern --frame when frame 0 is folded) or a drawing. Prints the error and returns
// its exit code on failure, with everything released.
static int load(const char *cmd, const char *path, cli_input *in, ori_fold **doc, ori_pattern **flat,
                ori_mechanism **mech, double **angles)
{
    cli_kin k;
    int rc = cli_kin_load_input(cmd, path, in->frame, in, &k);
    if (rc != CLI_EXIT_OK) return rc;
    *doc = k.doc;
    *flat = k.flat;
    *mech = k.mech;
    *angles = k.angles;
    free(k.coords);
    return CLI_EXIT_OK;
}

static int run(int argc, char **argv)
{
    const char *cmd = "dof", *path = NULL;
    bool json = false;
    int locks[256], nlock = 0;
    const char *lock_spec = NULL;
    cli_input in;
    cli_input_init(&in);
    cli_seen seen = {0};
    for (int i = 1; i < argc; ++i) {
        int r = cli_input_option(cmd, argc, argv, &i, &in, &seen);
        if (r < 0) return -r;
        if (r > 0) continue;
        if (strcmp(argv[i], "--json") == 0) {
            if (!cli_once(cmd, &seen, "--json")) return CLI_EXIT_USAGE;
            json = true;
        } else if (strcmp(argv[i], "--angles-from-frame") == 0) {
            return cli_usage(cmd, "--angles-from-frame is now --frame N (the state to analyse)");
        } else if (strcmp(argv[i], "--lock") == 0) {
            const char *v = cli_option_once(cmd, argc, argv, &i, &seen);
            if (!v) return CLI_EXIT_USAGE;
            int n = cli_spec_edge_count(v);
            if (n > 256) return cli_usage(cmd, "--lock takes at most %d edges, got %d", 256, n);
            if (n < 0) return cli_usage(cmd, "--lock: creases are indices or @x,y, comma-separated, got '%s'", v);
            lock_spec = v; // indices and @x,y: resolved against the pattern (cli_spec_edges)
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            return cli_usage(cmd, "unknown option %s", argv[i]);
        } else if (!path) {
            path = argv[i];
        } else {
            return cli_usage(cmd, "one FILE only");
        }
    }
    if (!path) return cli_usage(cmd, "missing FILE");
    ori_fold *doc;
    ori_pattern *flat;
    ori_mechanism *mech;
    double *angles;
    int rc = load(cmd, path, &in, &doc, &flat, &mech, &angles);
    if (rc != CLI_EXIT_OK) return rc;
    if (lock_spec) {
        nlock = cli_spec_edges(cmd, path, flat, "--lock", lock_spec, true, locks, 256);
        if (nlock < 0) rc = -nlock, nlock = 0;
    }
    ori_dof_result r;
    if (rc == CLI_EXIT_OK) {
        ori_dof_def def = ori_default_dof_def();
        def.angles_rad = angles;
        def.locked_edges = locks;
        def.locked_count = nlock;
        cli_progress bar;
        cli_progress_begin(&bar, cmd, "ranking the Jacobian");
        def.progress = cli_progress_fn;
        def.progress_user = &bar;
        ori_error err;
        ori_status st = ori_mechanism_dof(mech, &def, &r, &err);
        cli_progress_end(&bar);
        if (st != ORI_OK) rc = cli_input_error(cmd, path, &err);
    }
    if (rc == CLI_EXIT_OK && json) {
        json_t *out = cli_dof_json(path, in.frame, &r, ori_mechanism_loop_count(mech));
        cli_print_json(out);
    } else if (rc == CLI_EXIT_OK) {
        printf("file               %s (state of frame %d)\n", path, in.frame);
        printf("bodies, joints     %d faces, %d creases, %d loops\n", ori_mechanism_face_count(mech),
               ori_mechanism_joint_count(mech), ori_mechanism_loop_count(mech));
        printf("Grübler-Kutzbach   %d\n", r.grubler);
        printf("Jacobian           %d equations x %d unknowns, rank %d (%s)\n", r.equations, r.unknowns, r.rank,
               r.dense ? "dense SVD" : "sparse CHOLMOD");
        printf("dof at this state  %d\n", r.dof);
        if (r.generic_dof >= 0)
            printf("dof nearby         %d%s\n", r.generic_dof, r.rigid ? " (no motion found: rigid)" : "");
        else if (r.undetermined)
            printf("dof nearby         undetermined (no motion found in %d branch combinations, none ruled out)\n",
                   r.probe_solves);
        printf("singular           %s\n", r.singular ? "yes (the state inflates the nullity, e.g. the flat sheet)"
                                          : r.undetermined ? "unknown" : "no");
        if (r.nearby_against > 0) // the probe follows the free mechanism, whatever the assignment
            printf("note: the motion nearby ignores the assignment: it folds %d crease%s against %s (crease %d, assigned "
                   "%s, to %.6g deg); the nearby dof counts motions the assignment may not admit (orikin fold judges "
                   "an assigned fold)\n",
                   r.nearby_against, r.nearby_against == 1 ? "" : "s", r.nearby_against == 1 ? "its" : "theirs",
                   r.nearby_against_edge,
                   ori_pattern_edge(flat, r.nearby_against_edge).assignment == ORI_ASSIGN_VALLEY ? "valley" : "mountain",
                   ori_rad_to_deg_output(r.nearby_against_rad));
    }
    free(angles);
    ori_mechanism_destroy(mech);
    ori_pattern_destroy(flat);
    ori_fold_destroy(doc);
    return rc;
}

const cli_command cli_cmd_dof = {
    "dof",
    "degrees of freedom: Grubler-Kutzbach count and loop-closure Jacobian rank",
    "usage: orikin dof FILE [--frame N] [--lock E1,E2,...] [--json]\n"
    "\n"
    "Count the mobility of the pattern's mechanism (faces = rigid bodies, creases = revolute\n"
    "joints): the Grubler-Kutzbach formula (wrong for overconstrained origami: the open corner\n"
    "gives -1) and the true DOF, the nullity of the loop-closure Jacobian by SVD (relative rank\n"
    "tolerance 1e-9; patterns beyond 4e6 Jacobian entries use a sparse CHOLMOD method with\n"
    "tolerance 1e-7). At a singular state such as the flat sheet the nullity is inflated; the\n"
    "DOF at a nearby regular state on the motion is reported beside it. That probe tries at\n"
    "most 256 branch combinations of the singular vertices; when none gives a motion and not\n"
    "all were tried, the nearby DOF is \"undetermined\" (never a guess). FILE is FOLD (the\n"
    "mechanism is frame 0) or a drawing (SVG, OPX, CP: the flat state).\n"
    "\n"
    "options:\n"
    "  --frame N          the state: fold angles of frame N (0 = top level, k = file_frames[k-1];\n"
    "                     default 0). A flat crease-pattern frame is the flat state.\n"
    "  --lock E1,...      creases held fixed (removed from the unknowns): indices or @x,y (the\n"
    "                     crease through the point; in the list an @x,y takes two fields)\n"
    "  --json             print one object: file, frame; grubler (Grubler-Kutzbach count);\n"
    "                     unknowns (unlocked creases), equations (3 per interior vertex, 6 per\n"
    "                     hole), rank and dof (= unknowns - rank) at the state; generic_dof (DOF\n"
    "                     at a nearby regular state, null when not found); singular (dof >\n"
    "                     generic_dof); rigid (no motion at all); undetermined (the probe's\n"
    "                     budget ran out: generic_dof null); probe_solves (branch combinations\n"
    "                     tried); method (dense-svd or sparse-cholmod); sigma_max, sigma_cut\n"
    "                     (largest singular value, smallest one counted in the rank); loops;\n"
    "                     nearby_against_assignment ({creases, edge, angle_deg}: the nearby\n"
    "                     motion folds creases against their assignment; null when it keeps it)\n"
    CLI_INPUT_HELP
    "\n"
    "example: orikin dof examples/patterns/open-corner.fold\n",
    run,
    NULL,
};
