// The conventions every command follows (docs/conventions.md), checked across the commands of
// the io area and the shared helpers of cli/cli.c: a repeated single-valued option is a usage
// error; producing commands print a summary or --json; a byte-order mark is accepted in every
// input format; stdout write errors exit 3; a write killed by a signal leaves nothing; and
// everything orikin writes reads back as the same pattern.
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <jansson.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "support.h"

TestSuite(cli, .init = test_leak_setup, .fini = test_leak_check);

static const char *corner = "examples/patterns/open-corner.fold";

static int run(const char *fmt, const char *a, const char *b, char **output)
{
    char args[8192];
    snprintf(args, sizeof args, fmt, a ? a : "", b ? b : "");
    return test_run_cli(args, output);
}

static void write_file(const char *path, const char *text, size_t n)
{
    FILE *f = fopen(path, "wb");
    cr_assert_not_null(f, "%s", path);
    cr_assert_eq(fwrite(text, 1, n, f), n);
    fclose(f);
}

Test(cli, a_repeated_single_valued_option_is_a_usage_error)
{
    const char *cases[] = {
        "info examples/patterns/open-corner.fold --frame 0 --frame 0",
        "tree examples/patterns/open-corner.fold --frame 0 --frame 0",
        "convert tests/data/formats/bird.cp /tmp/never.fold --tolerance 1e-4 --tolerance 1e-4",
        "convert tests/data/formats/bird.cp /tmp/never.svg --gaps 0 --gaps auto",
        "convert examples/patterns/open-corner.fold /tmp/never.svg --labels faces --labels edges",
        "new --square 1 --square 2",
        "new --square 1 --title a --title b",
        "apply examples/patterns/open-corner.fold --pattern middle-h --face Obj111 --face Obj112",
        "edit examples/patterns/open-corner.fold --flip 8 -o /tmp/never.fold --output /tmp/never2.fold",
        "crease examples/patterns/open-corner.fold --line 0,0,1,1 --line 0,1,1,0 --all",
        "crease examples/patterns/open-corner.fold --axiom 1 --p1 0,0 --p1 1,1 --p2 2,2 --all",
        "generate miura --rows 2 --rows 3",
        "generate miura -o /tmp/never.fold -o /tmp/never2.fold",
        "mv-count 90 90 90 90 --max 1 --max 2",
        "axiom 1 --p1 0,0 --p2 1,1 --p2 2,2",
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        char *out = NULL;
        int rc = test_run_cli(cases[i], &out);
        cr_assert_eq(rc, 2, "%s: exit %d: %s", cases[i], rc, out);
        cr_assert(strstr(out, "given twice"), "%s: %s", cases[i], out);
        free(out);
    }
    // flags may repeat
    char *out = NULL;
    cr_assert_eq(test_run_cli("info examples/patterns/open-corner.fold --json --json", &out), 0, "%s", out);
    free(out);
}

// The producing commands: a one-line summary with -o, the same as one JSON object with --json,
// the FOLD text on stdout without -o, and --json without -o a usage error.
Test(cli, producing_commands_print_a_summary_or_json)
{
    char *dir = test_tmpdir();
    const char *cmds[] = {
        "new --square 2 -o '%s/a.fold'",
        "apply examples/patterns/open-corner.fold --pattern middle-h --face Obj111 -o '%s/a.fold'",
        "edit examples/patterns/open-corner.fold --flip 8 -o '%s/a.fold'",
        "crease examples/patterns/open-corner.fold --line 0,0,2,2 --all -o '%s/a.fold'",
        "convert examples/patterns/open-corner.fold '%s/a.fold'",
        "generate miura -o '%s/a.fold'",
    };
    for (size_t i = 0; i < sizeof cmds / sizeof cmds[0]; ++i) {
        char args[4096], *out = NULL, *err = NULL;
        snprintf(args, sizeof args, cmds[i], dir);
        cr_assert_eq(test_run_cli_split(args, &out, &err), 0, "%s: %s", args, err);
        cr_assert(strchr(out, '\n') == out + strlen(out) - 1, "%s: one line: %s", args, out);
        cr_assert(strstr(out, "a.fold") || strstr(out, "applied") || strstr(out, "edge"), "%s: %s", args, out);
        free(out);
        free(err);
        strcat(args, " --json");
        cr_assert_eq(test_run_cli_split(args, &out, &err), 0, "%s: %s", args, err);
        json_error_t je;
        json_t *j = json_loads(out, 0, &je);
        cr_assert_not_null(j, "%s: not JSON: %s", args, out);
        char want[2048];
        snprintf(want, sizeof want, "%s/a.fold", dir);
        cr_assert_str_eq(json_string_value(json_object_get(j, "output")), want, "%s", args);
        cr_assert(json_integer_value(json_object_get(j, "vertices")) > 0, "%s", args);
        cr_assert(json_is_object(json_object_get(j, "edges_by_assignment")), "%s", args);
        json_decref(j);
        free(out);
        free(err);
    }
    // without -o: FOLD on stdout; --json then has nowhere to go
    char *out = NULL;
    cr_assert_eq(test_run_cli("new --square 1", &out), 0);
    json_error_t je;
    json_t *j = json_loads(out, 0, &je);
    cr_assert(json_is_array(json_object_get(j, "vertices_coords")), "%s", out);
    json_decref(j);
    free(out);
    cr_assert_eq(test_run_cli("new --square 1 --json", &out), 2);
    cr_assert(strstr(out, "--json needs -o FILE"), "%s", out);
    free(out);
    test_tmpdir_remove(dir);
}

// A UTF-8 byte-order mark at the start of any input file: FOLD, SVG, OPX, CP, composite JSON.
Test(cli, a_byte_order_mark_is_accepted_in_every_input)
{
    char *dir = test_tmpdir();
    const char *files[] = {"examples/patterns/open-corner.fold", "tests/data/formats/transforms.svg",
                           "tests/data/formats/bird.cp", "examples/composites/star.json"};
    const char *names[] = {"bom.fold", "bom.svg", "bom.cp", "bom.json"};
    char path[4][1200];
    for (int k = 0; k < 4; ++k) {
        char *text = test_read_text(test_repo_path(files[k]));
        cr_assert_not_null(text);
        size_t n = strlen(text);
        char *with = malloc(n + 4);
        memcpy(with, "\xEF\xBB\xBF", 3);
        memcpy(with + 3, text, n + 1);
        snprintf(path[k], sizeof path[k], "%s/%s", dir, names[k]);
        write_file(path[k], with, n + 3);
        free(with);
        free(text);
    }
    // OPX: written by orikin from the CP drawing, then given a mark.
    char opx[1200], *out = NULL;
    snprintf(opx, sizeof opx, "%s/plain.opx", dir);
    cr_assert_eq(run("convert tests/data/formats/bird.cp '%s'", opx, NULL, &out), 0, "%s", out);
    free(out);
    char *text = test_read_text(opx);
    size_t n = strlen(text);
    char *with = malloc(n + 4);
    memcpy(with, "\xEF\xBB\xBF", 3);
    memcpy(with + 3, text, n + 1);
    snprintf(opx, sizeof opx, "%s/bom.opx", dir);
    write_file(opx, with, n + 3);
    free(with);
    free(text);
    for (int k = 0; k < 3; ++k) {
        cr_assert_eq(run("info '%s'", path[k], NULL, &out), 0, "%s: %s", path[k], out);
        free(out);
    }
    cr_assert_eq(run("info '%s'", opx, NULL, &out), 0, "%s", out);
    free(out);
    cr_assert_eq(run("apply examples/patterns/open-corner.fold --pattern '%s' --face Obj111", path[3], NULL, &out), 0, "%s",
                 out);
    free(out);
    test_tmpdir_remove(dir);
}

Test(cli, write_errors_on_stdout_exit_3)
{
    char *out = NULL, *err = NULL;
    int rc = test_run_cli_split("info examples/patterns/open-corner.fold --edges > /dev/full", &out, &err);
    cr_assert_eq(rc, 3, "%s", err);
    cr_assert(strstr(err, "orikin info: stdout: cannot write: No space left on device"), "%s", err);
    free(out);
    free(err);
    rc = test_run_cli_split("generate miura --rows 20 --cols 20 > /dev/full", &out, &err);
    cr_assert_eq(rc, 3, "%s", err);
    free(out);
    free(err);
    // and to a file that cannot be written
    rc = test_run_cli("new --square 1 -o /dev/full", &out);
    cr_assert_eq(rc, 3, "%s", out);
    cr_assert(strstr(out, "character device"), "%s", out);
    free(out);
}

// A write killed by a signal: the file size limit (ulimit -f) sends SIGXFSZ in the middle of
// writing the output; the CLI's handler removes the temporary file and dies of the signal.
Test(cli, a_write_killed_by_a_signal_leaves_nothing_behind)
{
    char *dir = test_tmpdir();
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "sh -c 'ulimit -f 4; exec \"%s\" generate miura --rows 60 --cols 60 -o \"%s/out.fold\"' 2>/dev/null",
             ORI_CLI_PATH, dir);
    int status = system(cmd);
    cr_assert(status != 0, "the write should have been stopped by the file size limit");
    DIR *d = opendir(dir);
    int left = 0;
    for (struct dirent *e; (e = readdir(d));) left += strncmp(e->d_name, "out.fold", 8) == 0;
    closedir(d);
    cr_assert_eq(left, 0, "out.fold or its temporary file was left in %s", dir);
    test_tmpdir_remove(dir);
}

// Everything the io commands write reads back: every -o (FOLD and, by extension, SVG, CP, OPX),
// every convert direction; drawings come back as the same pattern (counts and assignments).
static ori_pattern *load_any(const char *path)
{
    ori_format f = ori_format_from_path(path);
    if (f == ORI_FORMAT_FOLD) return test_load_pattern(path, 0);
    ori_pattern *p = NULL;
    ori_error err;
    char msg[400];
    cr_assert_eq(ori_import_file(path, f, NULL, &p, NULL, &err), ORI_OK, "%s: %s", path, ori_error_format(&err, msg, sizeof msg));
    return p;
}

static void assert_same_counts(const ori_pattern *p, const ori_pattern *q, const char *what)
{
    cr_assert_eq(ori_pattern_vertex_count(q), ori_pattern_vertex_count(p), "%s", what);
    cr_assert_eq(ori_pattern_edge_count(q), ori_pattern_edge_count(p), "%s", what);
    cr_assert_eq(ori_pattern_face_count(q), ori_pattern_face_count(p), "%s", what);
    for (int a = 0; a < ORI_ASSIGN_COUNT; ++a)
        cr_assert_eq(ori_pattern_count_assignment(q, (ori_assignment)a), ori_pattern_count_assignment(p, (ori_assignment)a),
                     "%s: assignment %c", what, ori_assignment_to_char((ori_assignment)a));
}

Test(cli, everything_written_reads_back_as_the_same_pattern)
{
    char *dir = test_tmpdir();
    const char *producers[] = {
        "new --polygon 0,0,3,0,3,1,1,2 -o '%s/%s'",
        "apply examples/patterns/open-corner.fold --pattern cross --face Obj111 --assign V -o '%s/%s'",
        "edit examples/patterns/open-corner.fold --move 12 0,2,1,1 -o '%s/%s'",
        "crease examples/patterns/open-corner.fold --axiom 2 --p1 0,0 --p2 2,2 --all --assign M -o '%s/%s'",
        "generate miura --rows 3 --cols 4 -o '%s/%s'",
        "generate yoshimura --rows 2 --cols 3 -o '%s/%s'",
        "generate waterbomb --rows 2 --cols 2 -o '%s/%s'",
        "generate square-twist --rows 2 --cols 2 -o '%s/%s'",
        "generate kresling -o '%s/%s'",
        "convert tests/data/formats/bird.cp '%s/%s'",
        "convert tests/data/formats/transforms.svg '%s/%s'",
    };
    const char *exts[] = {"fold", "svg", "cp", "opx"};
    for (size_t i = 0; i < sizeof producers / sizeof producers[0]; ++i) {
        char args[4096], fold[1200], *out = NULL;
        snprintf(args, sizeof args, producers[i], dir, "p.fold");
        cr_assert_eq(test_run_cli(args, &out), 0, "%s: %s", args, out);
        free(out);
        snprintf(fold, sizeof fold, "%s/p.fold", dir);
        ori_pattern *p = load_any(fold);
        bool has_fu = ori_pattern_count_assignment(p, ORI_ASSIGN_FLAT) + ori_pattern_count_assignment(p, ORI_ASSIGN_UNASSIGNED) > 0;
        bool has_c = ori_pattern_count_assignment(p, ORI_ASSIGN_CUT) > 0;
        for (int k = 0; k < 4; ++k) {
            char name[16], path[1200];
            snprintf(name, sizeof name, "q.%s", exts[k]);
            snprintf(path, sizeof path, "%s/%s", dir, name);
            // the command's own -o in that format, and convert from its FOLD output
            snprintf(args, sizeof args, producers[i], dir, name);
            bool oripa = k >= 2;
            int rc = test_run_cli(args, &out);
            cr_assert_eq(rc, oripa && has_fu ? 3 : 0, "%s: exit %d: %s", args, rc, out);
            if (oripa && has_fu) cr_assert(strstr(out, "ORIPA has no"), "%s", out);
            free(out);
            if (rc != 0) continue;
            ori_pattern *q = load_any(path);
            if (!(oripa && has_c)) assert_same_counts(p, q, args);
            ori_pattern_destroy(q);
            snprintf(args, sizeof args, "convert '%s' '%s'", fold, path);
            cr_assert_eq(test_run_cli(args, &out), 0, "%s: %s", args, out);
            free(out);
            q = load_any(path);
            if (!(oripa && has_c)) assert_same_counts(p, q, args);
            ori_pattern_destroy(q);
        }
        ori_pattern_destroy(p);
    }
    test_tmpdir_remove(dir);
}

Test(cli, info_lists_faces_and_edges)
{
    char *out = NULL;
    cr_assert_eq(test_run_cli("info examples/patterns/open-corner.fold --faces --edges --json", &out), 0);
    json_error_t je;
    json_t *j = json_loads(out, 0, &je);
    cr_assert_not_null(j, "%s", out);
    ori_pattern *p = test_load_pattern(test_repo_path(corner), 0);
    json_t *faces = json_object_get(j, "face_list"), *edges = json_object_get(j, "edge_list");
    cr_assert_eq(json_array_size(faces), (size_t)ori_pattern_face_count(p));
    cr_assert_eq(json_array_size(edges), (size_t)ori_pattern_edge_count(p));
    double area = 0.0;
    size_t i;
    json_t *f;
    json_array_foreach(faces, i, f)
    {
        area += json_number_value(json_object_get(f, "area"));
        cr_assert_str_eq(json_string_value(json_object_get(f, "name")), ori_pattern_face_name(p, (int)i));
        // the centroid of the corners lies inside the (convex) face: test_face_at finds it
        json_t *c = json_object_get(f, "centroid");
        cr_assert_eq(test_face_at(p, json_number_value(json_array_get(c, 0)), json_number_value(json_array_get(c, 1))), (int)i);
    }
    cr_assert_float_eq(area, 4.0, 1e-12); // the 2 × 2 sheet
    json_t *e;
    json_array_foreach(edges, i, e)
    {
        ori_edge ed = ori_pattern_edge(p, (int)i);
        ori_v3 a = ori_pattern_vertex(p, ed.v[0]), b = ori_pattern_vertex(p, ed.v[1]);
        cr_assert_float_eq(json_number_value(json_object_get(e, "length")), hypot(b.x - a.x, b.y - a.y), 1e-15);
        char asg[2] = {ori_assignment_to_char(ed.assignment), 0};
        cr_assert_str_eq(json_string_value(json_object_get(e, "assignment")), asg);
        int fs[2];
        ori_pattern_edge_faces(p, (int)i, fs);
        json_t *jf = json_object_get(e, "faces");
        for (int k = 0; k < 2; ++k)
            cr_assert(fs[k] < 0 ? json_is_null(json_array_get(jf, (size_t)k))
                                : json_integer_value(json_array_get(jf, (size_t)k)) == fs[k]);
    }
    ori_pattern_destroy(p);
    json_decref(j);
    free(out);
    // the text tables name faces and edges too
    cr_assert_eq(test_run_cli("info examples/patterns/open-corner.fold --faces --edges", &out), 0);
    cr_assert(strstr(out, "Obj1212"), "%s", out);
    cr_assert(strstr(out, "12    V"), "%s", out);
    free(out);
}

// convert --frame N writes that frame alone: the top level is the frame, inherited fields
// resolved, no file_frames, and it reads back as the frame did.
Test(cli, convert_frame_extracts_the_frame_alone)
{
    char *dir = test_tmpdir(), out_path[1200], *out = NULL;
    snprintf(out_path, sizeof out_path, "%s/frame1.fold", dir);
    cr_assert_eq(run("convert tests/data/frames.fold '%s' --frame 1", out_path, NULL, &out), 0, "%s", out);
    free(out);
    char *text = test_read_text(out_path);
    json_error_t je;
    json_t *j = json_loads(text, 0, &je);
    cr_assert_not_null(j, "%s", text);
    cr_assert_null(json_object_get(j, "file_frames"));
    cr_assert_null(json_object_get(j, "frame_parent"));
    cr_assert_null(json_object_get(j, "frame_inherit"));
    cr_assert_str_eq(json_string_value(json_array_get(json_object_get(j, "file_classes"), 0)), "singleModel");
    cr_assert_str_eq(json_string_value(json_array_get(json_object_get(j, "frame_classes"), 0)), "foldedForm");
    cr_assert_eq(json_array_size(json_array_get(json_object_get(j, "vertices_coords"), 0)), 3); // its own 3D coordinates
    cr_assert_eq(json_array_size(json_object_get(j, "edges_vertices")), 5);                    // inherited from frame 0
    cr_assert_not_null(json_object_get(j, "custom:answer"));                                   // likewise
    json_decref(j);
    free(text);
    ori_pattern *a = test_load_pattern(test_repo_path("tests/data/frames.fold"), 1), *b = test_load_pattern(out_path, 0);
    assert_same_counts(a, b, "frame 1");
    for (int v = 0; v < ori_pattern_vertex_count(a); ++v) {
        ori_v3 x = ori_pattern_vertex(a, v), y = ori_pattern_vertex(b, v);
        cr_assert(x.x == y.x && x.y == y.y && x.z == y.z, "vertex %d", v);
    }
    for (int e = 0; e < ori_pattern_edge_count(a); ++e)
        cr_assert_eq(ori_pattern_edge(a, e).fold_angle_rad, ori_pattern_edge(b, e).fold_angle_rad, "edge %d", e);
    ori_pattern_destroy(a);
    ori_pattern_destroy(b);
    // a frame the file does not have names the option
    cr_assert_eq(run("convert tests/data/frames.fold '%s' --frame 3", out_path, NULL, &out), 2);
    cr_assert(strstr(out, "--frame: frame 3 does not exist (frames 0 to 2)"), "%s", out);
    free(out);
    test_tmpdir_remove(dir);
}

// Imports say what went wrong, with an example and the fix.
Test(cli, imports_report_dangling_creases_and_separate_pieces)
{
    char *dir = test_tmpdir(), path[1200], *out = NULL, *err = NULL;
    // A square with a crease that stops in the middle of the sheet (nothing within 1 %), a crease
    // that stops 2 units (1 % of nothing: 0.7 % of the diagonal) short of the boundary, and a
    // second square apart from the first.
    const char *svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" stroke-width=\"0.1\">\n"
                      "<rect x=\"0\" y=\"0\" width=\"100\" height=\"100\" stroke=\"#000\" fill=\"none\"/>\n"
                      "<line x1=\"0\" y1=\"50\" x2=\"40\" y2=\"50\" stroke=\"#f00\"/>\n"
                      "<line x1=\"50\" y1=\"0\" x2=\"50\" y2=\"98\" stroke=\"#00f\"/>\n"
                      "<rect x=\"200\" y=\"0\" width=\"10\" height=\"10\" stroke=\"#000\" fill=\"none\"/>\n"
                      "</svg>\n";
    snprintf(path, sizeof path, "%s/drawing.svg", dir);
    write_file(path, svg, strlen(svg));
    char args[2400];
    snprintf(args, sizeof args, "info '%s'", path);
    cr_assert_eq(test_run_cli_split(args, &out, &err), 0, "%s", err);
    cr_assert(strstr(err, "warning: 2 crease end(s) touch nothing (e.g. vertex"), "%s", err);
    cr_assert(strstr(err, "--gaps 0.009 would join them"), "%s", err);
    cr_assert(strstr(err, "warning: the drawing is 2 separate pieces (vertex"), "%s", err);
    free(out);
    free(err);
    // the suggested gap (2 units of a 232.6 diagonal, 0.0086) joins the crease that stops short
    // (the other one has nothing near)
    snprintf(args, sizeof args, "convert '%s' '%s/out.fold' --gaps 0.009 --json", path, dir);
    cr_assert_eq(test_run_cli_split(args, &out, &err), 0, "%s", err);
    json_error_t je;
    json_t *j = json_loads(out, 0, &je);
    json_t *imp = json_object_get(j, "import");
    cr_assert_eq(json_integer_value(json_object_get(imp, "gaps_closed")), 1, "%s", out);
    cr_assert_eq(json_integer_value(json_object_get(imp, "dangling")), 1, "%s", out);
    cr_assert_eq(json_integer_value(json_object_get(imp, "parts")), 2, "%s", out);
    json_decref(j);
    free(out);
    free(err);
    test_tmpdir_remove(dir);
}

Test(cli, huffman_drawings_import_as_one_sheet_saying_what_was_joined)
{
    const char *names[] = {"origamisimulator/Curved_huffmanTower.svg", "origamisimulator/Tessellations_huffmanWaterbomb.svg"};
    for (int k = 0; k < 2; ++k) {
        const char *path = test_require_shared(names[k]);
        char args[4096], *out = NULL, *err = NULL;
        snprintf(args, sizeof args, "info '%s' --json", path);
        cr_assert_eq(test_run_cli_split(args, &out, &err), 0, "%s", err);
        cr_assert(strstr(err, "note: joined"), "%s", err);
        cr_assert_null(strstr(err, "warning"), "%s", err);
        free(out);
        free(err);
        ori_pattern *p = NULL;
        ori_import_stats s;
        cr_assert_eq(ori_import_file(path, ORI_FORMAT_UNKNOWN, NULL, &p, &s, NULL), ORI_OK);
        cr_assert_eq(s.parts, 1, "%s", names[k]);
        cr_assert_eq(s.dangling, 0, "%s", names[k]);
        cr_assert_gt(s.gaps_closed, 10, "%s", names[k]);
        cr_assert_leq(s.largest_gap_rel, s.gap_rel, "%s", names[k]);
        ori_pattern_destroy(p);
    }
}

// A command with several outputs writes all of them or none (issue: `layers -o old.fold --svg
// nodir/x.svg` replaced old.fold, then failed on the SVG): every output is staged and renamed
// only when the command succeeds.
Test(cli, a_command_with_several_outputs_writes_all_or_none)
{
    char *dir = test_tmpdir(), old[600], svg[600], bad[600], *out = NULL;
    snprintf(old, sizeof old, "%s/old.fold", dir);
    snprintf(bad, sizeof bad, "%s/nodir/x.svg", dir);
    snprintf(svg, sizeof svg, "%s/x.svg", dir);
    write_file(old, "old\n", 4);
    char args[2000];
    snprintf(args, sizeof args, "layers examples/patterns/degree6-vertex.fold -o %s --svg %s", old, bad);
    cr_assert_eq(test_run_cli(args, &out), 3, "%s", out);
    free(out);
    char *kept = test_read_text(old);
    cr_assert_str_eq(kept, "old\n", "the first output was replaced although the second failed");
    free(kept);
    snprintf(args, sizeof args, "layers examples/patterns/degree6-vertex.fold -o %s --svg %s", old, svg);
    cr_assert_eq(test_run_cli(args, &out), 0, "%s", out);
    free(out);
    char *now = test_read_text(old), *pic = test_read_text(svg);
    cr_assert(strstr(now, "faceOrders"), "both written on success");
    cr_assert(strstr(pic, "<svg"));
    free(now), free(pic);
    test_tmpdir_remove(dir);
}

static void assert_same_file(const char *a, const char *b, const char *what)
{
    size_t na, nb;
    char *x = test_read_file(a, &na), *y = test_read_file(b, &nb);
    cr_assert(x && y, "%s and %s were written", a, b);
    cr_assert(na == nb && memcmp(x, y, na) == 0, "%s: %s (%zu bytes) and %s (%zu bytes) differ", what, a, na, b, nb);
    free(x);
    free(y);
}

// --compliant is a state of render, export and animate as of fold (issue 23): the picture and the
// mesh are, byte for byte, those of the frame `orikin fold --compliant -o` writes; animate draws
// the load steps with one strain bar over them, as it draws the frames of --all-frames -o.
Test(cli, a_compliant_fold_is_a_state_of_render_export_and_animate)
{
    char *dir = test_tmpdir();
    char cmd[1024], *out = NULL;
#define CORNER "examples/patterns/open-corner.fold --compliant --percent 40"
    snprintf(cmd, sizeof cmd, "fold " CORNER " -o %s/bent.fold", dir);
    cr_assert_eq(test_run_cli(cmd, &out), 0, "%s", out);
    free(out);
    snprintf(cmd, sizeof cmd, "fold " CORNER " --all-frames -o %s/steps.fold", dir);
    cr_assert_eq(test_run_cli(cmd, &out), 0, "%s", out);
    free(out);
    static const char *const cases[][3] = {
        {"render %s/bent.fold --frame 1 --color strain -o %s/a.png", "render " CORNER " --color strain -o %s/b.png", "png"},
        {"render %s/bent.fold --frame 1 --yaw 30 -o %s/a.svg", "render " CORNER " --yaw 30 -o %s/b.svg", "svg"},
        {"export %s/bent.fold --frame 1 -o %s/a.glb", "export " CORNER " -o %s/b.glb", "glb"},
        {"export %s/bent.fold --frame 1 -o %s/a.stl", "export " CORNER " -o %s/b.stl", "stl"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        char a[512], b[512];
        snprintf(cmd, sizeof cmd, cases[i][0], dir, dir);
        cr_assert_eq(test_run_cli(cmd, &out), 0, "%s: %s", cmd, out);
        free(out);
        snprintf(cmd, sizeof cmd, cases[i][1], dir);
        cr_assert_eq(test_run_cli(cmd, &out), 0, "%s: %s", cmd, out);
        if (i == 2) cr_assert(strstr(out, "COLOR_0 by strain from 0 to 0.02378"), "a glTF of a compliant fold is coloured by strain: %s", out);
        free(out);
        snprintf(a, sizeof a, "%s/a.%s", dir, cases[i][2]);
        snprintf(b, sizeof b, "%s/b.%s", dir, cases[i][2]);
        assert_same_file(a, b, cmd);
    }
    // the motion: its load steps, one bar over all of them, as the frames written with --all-frames
    char *written = NULL;
    snprintf(cmd, sizeof cmd, "animate %s/steps.fold --color strain --fps 4 --duration 1 --size 80x60 -o %s/a.gif", dir, dir);
    cr_assert_eq(test_run_cli(cmd, &written), 0, "%s", written);
    snprintf(cmd, sizeof cmd, "animate " CORNER " --color strain --fps 4 --duration 1 --size 80x60 -o %s/b.gif", dir);
    cr_assert_eq(test_run_cli(cmd, &out), 0, "%s", out);
    const char *bar = "5 frames of ";
    cr_assert(strstr(out, bar) && strstr(written, bar), "%s / %s", out, written);
    const char *range = "strain of 5 faces from 0 to 0.02378 over the motion";
    cr_assert(strstr(out, range) && strstr(written, range), "one bar over the load steps: %s / %s", out, written);
    free(out);
    free(written);
    // what a compliant fold is not: planar panels to collide, a drive, a start frame
    static const char *const refused[][2] = {
        {"collide " CORNER, "a compliant fold bends its faces"},
        {"render " CORNER " --drive 3 -o %s/x.png", "--drive is not an option of a compliant fold"},
        {"render " CORNER " --frame 1 -o %s/x.png", "--compliant folds the flat sheet of frame 0"},
    };
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; ++i) {
        snprintf(cmd, sizeof cmd, refused[i][0], dir);
        cr_assert_eq(test_run_cli(cmd, &out), 2, "%s: %s", cmd, out);
        cr_assert(strstr(out, refused[i][1]), "%s: %s", cmd, out);
        free(out);
        char x[512];
        snprintf(x, sizeof x, "%s/x.glb", dir);
        cr_assert_neq(access(x, F_OK), 0, "nothing written");
    }
#undef CORNER
    test_tmpdir_remove(dir);
}
