// orikin unfold: a polyhedral surface (OBJ, STL, FOLD) → its crease pattern when it is a folded
// flat sheet (developed without cuts), else an edge-unfolded net; both fold back.
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "progress.h"

#define CMD "unfold"

extern const cli_command cli_cmd_unfold;

static const char help[] =
    "usage: orikin unfold SHAPE [--cut | --develop] [--tries N] [--all] [-o NET.fold] [--svg NET.svg]\n"
    "                     [--json]\n"
    "\n"
    "When SHAPE is a folded form of a flat sheet (a developable surface: the face angles at every\n"
    "interior vertex sum to 360°, e.g. a FOLD foldedForm or an OBJ export of a folded state), develop\n"
    "it into the plane without cuts: the answer is its crease pattern, every interior edge a crease\n"
    "(mountain or valley from the dihedral sign, edges_foldAngle the current fold angle), the sheet's\n"
    "edge the boundary; -o writes the crease pattern as frame 0 and the folded form as frame 1, and\n"
    "the crease pattern is folded back with the kinematics to check it. A FOLD folded form that is\n"
    "planar, every face turned the same way, is a flat sheet (Origami Simulator saves its sheets as a\n"
    "foldedForm in the x-z plane): it is its own crease pattern, kept with its creases, assignments\n"
    "and fold angles and turned into the x-y plane (developing it would merge its faces).\n"
    "\n"
    "Otherwise cut the surface (SHAPE: .obj, .stl, or a .fold folded form; closed or open;\n"
    "coplanar neighbouring faces are merged) along edges into a flat net without overlap: spanning\n"
    "trees of the face graph are tried (steepest-edge, random and flattest-first trees) until one\n"
    "lays out without overlapping faces; when none does, the best is split into pieces. The net is a\n"
    "crease pattern: cut edges are boundaries (B), creases mountain or valley with edges_foldAngle\n"
    "the angles that rebuild the shape; it is folded back with orikin's kinematics and the fold\n"
    "(all creases together) is checked for self-collision. Bad shapes (non-manifold edges,\n"
    "degenerate or non-planar faces) are refused (exit 3).\n"
    "\n"
    "options:\n"
    "  --cut              always cut into a net, even when the shape develops without cuts\n"
    "  --develop          develop without cuts or fail (exit 3 naming the vertex or face that\n"
    "                     prevents it) instead of falling back to a net\n"
    "  --develop-tolerance DEG\n"
    "                     angle defect allowed at an interior vertex (default 5.7e-4°, i.e. 1e-5 rad:\n"
    "                     coordinates rounded to 6 digits); larger for relaxed or simulated forms\n"
    "  --tries N          spanning trees to try (default 50)\n"
    "  --seed N           seed of the random trees (default 1)\n"
    "  --all              enumerate every spanning tree and count the distinct nets up to rotation\n"
    "                     and reflection (implies --cut); bounded by --limit and --timeout, past which\n"
    "                     the count is a lower bound (exit 5)\n"
    "  --limit N          with --all: spanning trees to enumerate at most (default 10000000)\n"
    "  --timeout SECONDS  with --all: stop enumerating after this long (default: none)\n"
    "  -o, --output FILE  write the net as FOLD (faces_orikin:source, edges_orikin:glue); a developed\n"
    "                     crease pattern with its folded form as frame 1\n"
    "  --svg FILE         draw the net as SVG\n"
    "  --json             print {developable, cuts, pieces, faces, overlaps, max_refold_error, ...}\n"
    "                     as JSON (developed: max_angle_defect_deg, max_length_error, ...)\n"
    "\n"
    "exit codes: 0 done, 3 bad shape, 5 --all stopped at --limit or --timeout (a lower bound)\n"
    "\n"
    "examples:\n"
    "  orikin unfold tests/data/unfold/cube.obj --all -o cube-net.fold --json\n"
    "  orikin unfold tests/data/unfold/miura-folded.fold -o miura-cp.fold\n";

static int write_net(const char *path, const ori_unfold_net *net, bool svg)
{
    const ori_pattern *p = ori_unfold_net_pattern(net);
    ori_fold *doc = ori_fold_create();
    ori_error err;
    ori_error_clear(&err);
    ori_fold_set_string(doc, 0, "file_creator", "orikin unfold");
    ori_status st = ori_fold_set_pattern(doc, 0, p, &err);
    if (st == ORI_OK && !svg) {
        json_t *src = json_array(), *glue = json_array();
        int buf[4096];
        for (int f = 0; f < ori_pattern_face_count(p); ++f) {
            int n = ori_unfold_net_face_source(net, f, buf, 4096);
            json_t *a = json_array();
            for (int i = 0; i < n && i < 4096; ++i) json_array_append_new(a, json_integer(buf[i]));
            json_array_append_new(src, a);
        }
        for (int e = 0; e < ori_pattern_edge_count(p); ++e) {
            int g = ori_unfold_net_glue(net, e);
            json_array_append_new(glue, g >= 0 ? json_integer(g) : json_null());
        }
        bool developed = ori_unfold_net_result(net).developed;
        char *s1 = json_dumps(src, JSON_COMPACT), *s2 = json_dumps(glue, JSON_COMPACT);
        st = ori_fold_set_custom(doc, 0, "faces_orikin:source", s1, &err);
        if (st == ORI_OK && !developed) st = ori_fold_set_custom(doc, 0, "edges_orikin:glue", s2, &err);
        if (st == ORI_OK) st = ori_fold_set_custom(doc, 0, "frame_classes", "[\"creasePattern\"]", &err);
        free(s1), free(s2);
        json_decref(src), json_decref(glue);
        if (st == ORI_OK && developed) {
            // the folded form the crease pattern was developed from, as frame 1
            int nv = ori_pattern_vertex_count(p), ne = ori_pattern_edge_count(p);
            ori_v3 *pos = malloc(((size_t)nv + 1) * sizeof *pos);
            double *ang = malloc(((size_t)ne + 1) * sizeof *ang);
            for (int v = 0; v < nv; ++v) pos[v] = ori_unfold_net_vertex_position(net, v);
            for (int e = 0; e < ne; ++e) ang[e] = ori_pattern_edge(p, e).fold_angle_rad;
            ori_fold_append_state(doc, 0, nv, pos, ne, ang, "folded form (the input)");
            free(pos), free(ang);
        }
        if (st == ORI_OK) st = ori_fold_save_file(doc, path, &err);
    }
    int rc = CLI_EXIT_OK;
    if (st != ORI_OK) rc = cli_input_error(CMD, path, &err);
    else if (svg) rc = cli_write_pattern(CMD, doc, p, path);
    ori_fold_destroy(doc);
    return rc;
}

// A FOLD folded form that lies in one plane with every face turned the same way is a flat sheet,
// not a fold: it is a crease pattern (Origami Simulator saves its sheets as a foldedForm in the
// x–z plane). Developing it would merge its coplanar faces and drop every crease. Returns it
// turned into the x–y plane (the faces counter-clockwise; an axis of the plane kept as x), with
// its edges, assignments and fold angles; NULL when the pattern is not planar, has a face turned
// over (a flat-folded state) or no crease. *normal: the plane's normal.
static ori_pattern *planar_crease_pattern(const ori_pattern *p, ori_v3 *normal)
{
    int nv = ori_pattern_vertex_count(p), ne = ori_pattern_edge_count(p), nf = ori_pattern_face_count(p);
    int creases = 0;
    for (int e = 0; e < ne; ++e) creases += ori_assignment_is_fold(ori_pattern_edge(p, e).assignment) ||
                                            ori_pattern_edge(p, e).assignment == ORI_ASSIGN_FLAT;
    if (nv < 3 || nf == 0 || creases == 0) return NULL;
    // Newell's normal of every face together: the sheet's orientation
    int cap = 0, *fv = NULL;
    double n[3] = {0, 0, 0};
    for (int f = 0; f < nf; ++f) {
        int k = ori_pattern_face_size(p, f);
        if (k > cap) cap = k, fv = realloc(fv, sizeof(int) * (size_t)cap);
        ori_pattern_face_vertices(p, f, fv, cap);
        for (int i = 0; i < k; ++i) {
            ori_v3 a = ori_pattern_vertex(p, fv[i]), b = ori_pattern_vertex(p, fv[(i + 1) % k]);
            n[0] += (a.y - b.y) * (a.z + b.z), n[1] += (a.z - b.z) * (a.x + b.x), n[2] += (a.x - b.x) * (a.y + b.y);
        }
    }
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0.0)) {
        free(fv);
        return NULL;
    }
    for (int i = 0; i < 3; ++i) n[i] /= len;
    for (int i = 0; i < 3; ++i) // (rounding of a sheet in a coordinate plane: exactly that plane)
        if (fabs(n[i]) < 1e-15) n[i] = 0.0;
    // u: the coordinate axis closest to the plane, projected into it; v = n × u
    int ax = fabs(n[0]) <= fabs(n[1]) && fabs(n[0]) <= fabs(n[2]) ? 0 : fabs(n[1]) <= fabs(n[2]) ? 1 : 2;
    double u[3] = {0, 0, 0}, v[3];
    u[ax] = 1.0;
    double d = u[ax] * n[ax];
    for (int i = 0; i < 3; ++i) u[i] -= d * n[i];
    double ul = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (int i = 0; i < 3; ++i) u[i] /= ul;
    v[0] = n[1] * u[2] - n[2] * u[1], v[1] = n[2] * u[0] - n[0] * u[2], v[2] = n[0] * u[1] - n[1] * u[0];
    ori_v3 o = ori_pattern_vertex(p, 0);
    double off = o.x * n[0] + o.y * n[1] + o.z * n[2], tol = ORI_TOL_PLANAR_REL * ori_pattern_diagonal(p);
    ori_pattern_def pdef = ori_default_pattern_def();
    ori_pattern *q = ori_pattern_create(&pdef);
    bool planar = true;
    for (int i = 0; i < nv && planar; ++i) {
        ori_v3 a = ori_pattern_vertex(p, i);
        planar = fabs(a.x * n[0] + a.y * n[1] + a.z * n[2] - off) <= tol;
        double x = a.x * u[0] + a.y * u[1] + a.z * u[2], y = a.x * v[0] + a.y * v[1] + a.z * v[2];
        ori_pattern_add_vertex(q, ori_v3_make(x == 0.0 ? 0.0 : x, y == 0.0 ? 0.0 : y, 0.0));
    }
    for (int f = 0; f < nf && planar; ++f) { // every face turned the same way: a sheet, not folded flat
        int k = ori_pattern_face_size(p, f);
        ori_pattern_face_vertices(p, f, fv, cap);
        double area = 0.0;
        for (int i = 0; i < k; ++i) {
            ori_v3 a = ori_pattern_vertex(q, fv[i]), b = ori_pattern_vertex(q, fv[(i + 1) % k]);
            area += a.x * b.y - a.y * b.x;
        }
        planar = area > 0.0;
        if (planar) ori_pattern_add_face(q, fv, k);
    }
    free(fv);
    if (!planar) {
        ori_pattern_destroy(q);
        return NULL;
    }
    for (int e = 0; e < ne; ++e) {
        ori_edge ed = ori_pattern_edge(p, e);
        ori_pattern_add_edge(q, ed.v[0], ed.v[1], ed.assignment, ed.fold_angle_rad);
    }
    ori_pattern_set_has_fold_angles(q, ori_pattern_has_fold_angles(p));
    ori_build_def bdef = ori_default_build_def();
    ori_error err;
    if (ori_pattern_build(q, &bdef, &err) != ORI_OK) {
        ori_pattern_destroy(q);
        return NULL;
    }
    *normal = ori_v3_make(n[0], n[1], n[2]);
    return q;
}

// unfold of a planar folded form: its crease pattern as it is (-o, --svg), said so.
static int planar_answer(const char *path, const ori_pattern *cp, ori_v3 n, const char *out, const char *svg, bool json)
{
    int nm = ori_pattern_count_assignment(cp, ORI_ASSIGN_MOUNTAIN), nvl = ori_pattern_count_assignment(cp, ORI_ASSIGN_VALLEY);
    int nfl = ori_pattern_count_assignment(cp, ORI_ASSIGN_FLAT), nu = ori_pattern_count_assignment(cp, ORI_ASSIGN_UNASSIGNED);
    int rc = CLI_EXIT_OK;
    for (int k = 0; k < 2 && rc == CLI_EXIT_OK; ++k) {
        const char *to = k == 0 ? out : svg;
        if (!to) continue;
        ori_fold *doc = ori_fold_create();
        ori_fold_set_string(doc, 0, "file_creator", "orikin unfold");
        ori_fold_set_custom(doc, 0, "frame_classes", "[\"creasePattern\"]", NULL);
        rc = cli_write_pattern(CMD, doc, cp, to);
        ori_fold_destroy(doc);
    }
    if (rc != CLI_EXIT_OK) return rc;
    if (json) {
        json_t *o = json_object();
        json_object_set_new(o, "developable", json_true());
        json_object_set_new(o, "planar", json_true());
        json_object_set_new(o, "normal", json_pack("[fff]", n.x, n.y, n.z));
        json_object_set_new(o, "cuts", json_integer(0));
        json_object_set_new(o, "pieces", json_integer(1));
        json_object_set_new(o, "faces", json_integer(ori_pattern_face_count(cp)));
        json_object_set_new(o, "creases", json_integer(nm + nvl + nfl + nu));
        json_object_set_new(o, "mountains", json_integer(nm));
        json_object_set_new(o, "valleys", json_integer(nvl));
        cli_print_json(o); // takes o
    } else {
        printf("%s: the folded form is planar (a flat sheet, normal (%.3g, %.3g, %.3g)): it is a crease pattern, kept as "
               "it is: %d creases (%d mountain, %d valley, %d flat, %d unassigned), %d faces, turned into the x-y plane\n",
               path, n.x, n.y, n.z, nm + nvl + nfl + nu, nm, nvl, nfl, nu, ori_pattern_face_count(cp));
    }
    return CLI_EXIT_OK;
}

static int run(int argc, char **argv)
{
    const char *path = NULL, *out = NULL, *svg = NULL, *v;
    bool json = false, cut = false, develop_only = false;
    double dev_tol_deg = 0.0, timeout_s = 0.0;
    bool limit_given = false;
    ori_unfold_def def = ori_default_unfold_def();
    cli_seen seen = {0};
    for (int i = 1; i < argc; ++i) {
        if (cli_is_help(argv[i])) return cli_print_help(&cli_cmd_unfold);
        if (strcmp(argv[i], "--json") == 0) {
            json = true;
        } else if (strcmp(argv[i], "--all") == 0) {
            def.all = true;
        } else if (strcmp(argv[i], "--cut") == 0) {
            cut = true;
        } else if (strcmp(argv[i], "--develop") == 0) {
            develop_only = true;
        } else if (strcmp(argv[i], "--develop-tolerance") == 0) {
            if (!(v = cli_option_once(CMD, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (!cli_parse_double(v, &dev_tol_deg) || !(dev_tol_deg > 0.0) || dev_tol_deg > 10.0)
                return cli_usage(CMD, "--develop-tolerance needs degrees in (0, 10], got '%s'", v);
        } else if (strcmp(argv[i], "-o") == 0 || strcmp(argv[i], "--output") == 0) {
            if (!(out = cli_option_once(CMD, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--svg") == 0) {
            if (!(svg = cli_option_once(CMD, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
        } else if (strcmp(argv[i], "--tries") == 0) {
            if (!(v = cli_option_once(CMD, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (!cli_parse_int(v, &def.tries) || def.tries < 1 || def.tries > 1000000)
                return cli_usage(CMD, "--tries needs an integer from 1 to 1000000, got '%s'", v);
        } else if (strcmp(argv[i], "--limit") == 0) {
            double n;
            if (!(v = cli_option_once(CMD, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (!cli_parse_double(v, &n) || !(n >= 1.0) || n > 1e15 || n != floor(n))
                return cli_usage(CMD, "--limit needs a number of spanning trees from 1 to 1e15, got '%s'", v);
            def.max_trees = (long long)n;
            limit_given = true;
        } else if (strcmp(argv[i], "--timeout") == 0) {
            if (!(v = cli_option_once(CMD, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (!cli_parse_double(v, &timeout_s) || !(timeout_s > 0.0) || timeout_s > 1e9)
                return cli_usage(CMD, "--timeout needs seconds in (0, 1e9], got '%s'", v);
        } else if (strcmp(argv[i], "--seed") == 0) {
            int s;
            if (!(v = cli_option_once(CMD, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (!cli_parse_int(v, &s) || s < 0) return cli_usage(CMD, "--seed needs a non-negative integer, got '%s'", v);
            def.seed = (unsigned)s;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            return cli_usage(CMD, "unknown option %s", argv[i]);
        } else if (!path) {
            path = argv[i];
        } else {
            return cli_usage(CMD, "one SHAPE only");
        }
    }
    if (!path) return cli_usage(CMD, "missing SHAPE");
    if (develop_only && (cut || def.all)) return cli_usage(CMD, "--develop cannot be combined with %s", cut ? "--cut" : "--all");
    if ((limit_given || timeout_s > 0.0) && !def.all)
        return cli_usage(CMD, "%s bounds --all: give --all too", limit_given ? "--limit" : "--timeout");
    cli_deadline deadline;
    cli_deadline_begin(&deadline, CMD, "enumerating spanning trees", timeout_s);
    def.progress = cli_deadline_fn, def.progress_user = &deadline;
    ori_error err;
    ori_error_clear(&err);
    if (ori_format_from_path(path) == ORI_FORMAT_FOLD) {
        // (quietly: a file the pattern reader refuses is the mesh reader's to judge below)
        ori_fold *doc = NULL;
        ori_pattern *p = NULL;
        ori_v3 n;
        ori_pattern *cp = NULL;
        if (ori_fold_load_file(path, &doc, NULL) == ORI_OK && ori_fold_get_pattern(doc, 0, NULL, &p, NULL) == ORI_OK)
            cp = planar_crease_pattern(p, &n);
        ori_pattern_destroy(p);
        ori_fold_destroy(doc);
        if (cp && (cut || def.all)) { // asked for a net: said, not silently merged away
            fprintf(stderr,
                    "orikin %s: %s: note: the folded form is planar, a crease pattern of %d creases: %s merges its "
                    "coplanar faces, and the net has none of them (without it unfold keeps them)\n",
                    CMD, path, ori_pattern_edge_count(cp) - ori_pattern_count_assignment(cp, ORI_ASSIGN_BOUNDARY) -
                                   ori_pattern_count_assignment(cp, ORI_ASSIGN_CUT),
                    cut ? "--cut" : "--all");
            ori_pattern_destroy(cp);
        } else if (cp) {
            int prc = planar_answer(path, cp, n, out, svg, json);
            ori_pattern_destroy(cp);
            return prc;
        }
    }
    ori_mesh *mesh = NULL;
    if (ori_unfold_load_mesh(path, &mesh, &err) != ORI_OK) return cli_input_error(CMD, path, &err);
    ori_unfold_net *net = NULL;
    char why[sizeof err.message] = "";
    if (!cut && !def.all) {
        ori_status ds = ori_unfold_develop(mesh, dev_tol_deg * 3.14159265358979323846 / 180.0, &net, &err);
        if (ds != ORI_OK && (develop_only || ds != ORI_ERR_NOT_FOUND)) {
            ori_unfold_mesh_destroy(mesh);
            return cli_input_error(CMD, path, &err);
        }
        if (ds != ORI_OK) snprintf(why, sizeof why, "%s", err.message);
        ori_error_clear(&err);
    }
    if (!net && ori_unfold_solve(mesh, &def, &net, &err) != ORI_OK) {
        ori_unfold_mesh_destroy(mesh);
        return cli_input_error(CMD, path, &err);
    }
    cli_progress_end(&deadline.bar);
    ori_unfold_result r = ori_unfold_net_result(net);
    const ori_pattern *cp = ori_unfold_net_pattern(net);
    int nm = 0, nvl = 0, nfl = 0;
    for (int e = 0; e < ori_pattern_edge_count(cp); ++e) {
        ori_assignment a = ori_pattern_edge(cp, e).assignment;
        nm += a == ORI_ASSIGN_MOUNTAIN, nvl += a == ORI_ASSIGN_VALLEY, nfl += a == ORI_ASSIGN_FLAT;
    }
    int rc = CLI_EXIT_OK;
    if (out) rc = write_net(out, net, false);
    if (rc == CLI_EXIT_OK && svg) rc = write_net(svg, net, true);
    if (rc == CLI_EXIT_OK) {
        if (json && r.developed) {
            json_t *o = json_object();
            json_object_set_new(o, "developable", json_true());
            json_object_set_new(o, "cuts", json_integer(0));
            json_object_set_new(o, "pieces", json_integer(1));
            json_object_set_new(o, "faces", json_integer(r.faces));
            json_object_set_new(o, "input_faces", json_integer(r.input_faces));
            json_object_set_new(o, "creases", json_integer(nm + nvl + nfl));
            json_object_set_new(o, "mountains", json_integer(nm));
            json_object_set_new(o, "valleys", json_integer(nvl));
            json_object_set_new(o, "interior_vertices", json_integer(r.interior_vertices));
            json_object_set_new(o, "overlaps", json_integer(0));
            json_object_set_new(o, "max_angle_defect_deg", json_real(ori_rad_to_deg(r.max_angle_defect_rad)));
            json_object_set_new(o, "max_length_error", json_real(r.max_length_error));
            json_object_set_new(o, "max_closing_error", json_real(r.max_closing_error));
            json_object_set_new(o, "fold_residual", r.fold_residual >= 0.0 ? json_real(r.fold_residual) : json_null());
            json_object_set_new(o, "max_refold_error", r.refolded ? json_real(r.max_refold_error) : json_null());
            cli_print_json(o); // takes o
        } else if (r.developed) {
            printf("developed without cuts: a crease pattern, %d crease%s (%d mountain, %d valley%s), %d faces\n",
                   nm + nvl + nfl, nm + nvl + nfl == 1 ? "" : "s", nm, nvl, nfl ? ", some flat" : "", r.faces);
            printf("%d interior vertices, largest angle defect %.3g°, edge lengths kept within %.3g (relative)\n",
                   r.interior_vertices, ori_rad_to_deg(r.max_angle_defect_rad), r.max_length_error);
            if (r.refolded)
                printf("folded back to the shape within %.3g (relative; loop residual %.3g)\n", r.max_refold_error,
                       r.fold_residual);
        } else if (json) {
            json_t *o = json_object();
            json_object_set_new(o, "developable", json_false());
            if (why[0]) json_object_set_new(o, "develop_reason", json_string(why));
            json_object_set_new(o, "cuts", json_integer(r.cuts));
            json_object_set_new(o, "pieces", json_integer(r.pieces));
            json_object_set_new(o, "faces", json_integer(r.faces));
            json_object_set_new(o, "input_faces", json_integer(r.input_faces));
            json_object_set_new(o, "overlaps", json_integer(r.overlaps));
            json_object_set_new(o, "tries", json_integer(r.tries));
            json_object_set_new(o, "max_refold_error", r.refolded ? json_real(r.max_refold_error) : json_null());
            json_object_set_new(o, "motion_collides", r.refolded ? json_boolean(r.motion_collides) : json_null());
            static const char *orders[] = {"together", "leaves first", "root first"};
            json_object_set_new(o, "fold_order", r.fold_order >= 0 ? json_string(orders[r.fold_order]) : json_null());
            if (def.all) {
                json_object_set_new(o, "distinct_nets", r.distinct_nets >= 0 ? json_integer(r.distinct_nets) : json_null());
                json_object_set_new(o, "spanning_trees", json_integer(r.spanning_trees));
                json_object_set_new(o, "overlap_free_trees", json_integer(r.overlap_free_trees));
                json_object_set_new(o, "spanning_trees_total", json_real(r.spanning_trees_total));
                json_object_set_new(o, "complete", json_boolean(r.all_complete));
            }
            cli_print_json(o); // takes o
        } else {
            if (why[0]) printf("%s: cut into a net\n", why);
            printf("%d faces (%d in the input): %s after %d tries\n", r.faces, r.input_faces,
                   r.pieces == 1 ? "one net without overlap" : "no single net found", r.tries);
            if (r.pieces > 1) printf("split into %d pieces without overlap\n", r.pieces);
            if (r.refolded)
                printf("folded back to the shape within %.3g (relative); %s\n", r.max_refold_error,
                       r.fold_order == ORI_FOLD_ORDER_TOGETHER       ? "all creases together without collision"
                       : r.fold_order == ORI_FOLD_ORDER_LEAVES_FIRST ? "without collision one crease at a time, leaves first"
                       : r.fold_order == ORI_FOLD_ORDER_ROOT_FIRST   ? "without collision one crease at a time, root first"
                                                                     : "every fold order tried collides");
            if (def.all && r.all_complete)
                printf("%d distinct nets (up to rotation and reflection) from %lld of %lld spanning trees\n", r.distinct_nets,
                       r.overlap_free_trees, r.spanning_trees);
            else if (def.all)
                printf("at least %d distinct nets (up to rotation and reflection): stopped at %s after %lld of %.6g "
                       "spanning trees (%lld without overlap); a larger --limit or --timeout counts more\n",
                       r.distinct_nets, r.spanning_trees >= def.max_trees ? "--limit" : "--timeout", r.spanning_trees,
                       r.spanning_trees_total, r.overlap_free_trees);
        }
        if (def.all && !r.all_complete) rc = CLI_EXIT_PARTIAL;
    }
    ori_unfold_net_destroy(net);
    ori_unfold_mesh_destroy(mesh);
    return rc;
}

const cli_command cli_cmd_unfold = {"unfold", "a folded form back to its crease pattern, or any polyhedral surface into a net",
                                    help, run, NULL};
