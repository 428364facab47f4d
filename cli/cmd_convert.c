// orikin convert: rewrite a pattern in another file (format chosen by extension).
#include <orikin/formats.h>
#include <string.h>

#include "cli.h"

// What the import of a drawing found (cli_input stats), for --json.
static json_t *import_json(const ori_import_stats *s)
{
    json_t *o = json_object();
    json_object_set_new(o, "segments", json_integer(s->segments));
    json_object_set_new(o, "ignored_elements", json_integer(s->ignored_elements));
    json_object_set_new(o, "unsupported_elements", json_integer(s->unsupported_elements));
    json_object_set_new(o, "stroke_width", json_real(s->stroke_width));
    json_object_set_new(o, "gap_rel", json_real(s->gap_rel));
    json_object_set_new(o, "gaps_closed", json_integer(s->gaps_closed));
    json_object_set_new(o, "short_creases_merged", json_integer(s->short_creases_merged));
    json_object_set_new(o, "largest_gap_rel", json_real(s->largest_gap_rel));
    json_object_set_new(o, "dangling", json_integer(s->dangling));
    json_object_set_new(o, "dangling_example", s->dangling_example >= 0 ? json_integer(s->dangling_example) : json_null());
    json_object_set_new(o, "parts", json_integer(s->parts));
    json_object_set_new(o, "part_example", s->part_example >= 0 ? json_integer(s->part_example) : json_null());
    return o;
}

static int run(int argc, char **argv)
{
    const char *cmd = "convert", *in_path = NULL, *out = NULL, *v;
    cli_input in;
    cli_input_init(&in);
    cli_seen seen = {0};
    bool full_fold = false, json = false, label_faces = false, label_edges = false, out_by_o = false;
    for (int i = 1; i < argc; ++i) {
        int r = cli_input_option(cmd, argc, argv, &i, &in, &seen);
        if (r < 0) return -r;
        if (r > 0) continue;
        if (strcmp(argv[i], "--full-fold") == 0) {
            full_fold = true;
        } else if (strcmp(argv[i], "--json") == 0) {
            json = true;
        } else if (strcmp(argv[i], "--labels") == 0) {
            if (!(v = cli_option_once(cmd, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (strcmp(v, "faces") == 0) label_faces = true;
            else if (strcmp(v, "edges") == 0) label_edges = true;
            else if (strcmp(v, "all") == 0) label_faces = label_edges = true;
            else return cli_usage(cmd, "--labels takes faces, edges or all, got '%s'", v);
        } else if (strcmp(argv[i], "-o") == 0) { // OUT as every other command takes it
            if (!(v = cli_option_once(cmd, argc, argv, &i, &seen))) return CLI_EXIT_USAGE;
            if (out) return cli_usage(cmd, "OUT given twice (as OUT and with -o)");
            out = v;
            out_by_o = true;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') {
            return cli_usage(cmd, "unknown option %s", argv[i]);
        } else if (!in_path) {
            in_path = argv[i];
        } else if (!out) {
            out = argv[i];
        } else {
            if (out_by_o) return cli_usage(cmd, "OUT given twice (as OUT and with -o)");
            return cli_usage(cmd, "expected IN and OUT only");
        }
    }
    if (!in_path || !out) return cli_usage(cmd, "missing IN or OUT");
    ori_format fin = ori_format_from_path(in_path), fout = cli_is_stdout(out) ? ORI_FORMAT_FOLD : ori_format_from_path(out);
    if (fin == ORI_FORMAT_UNKNOWN) return cli_usage(cmd, "cannot read '%s': use .fold, .svg, .opx or .cp", in_path);
    if (fout == ORI_FORMAT_UNKNOWN) return cli_usage(cmd, "cannot write '%s': use .fold, .svg, .opx or .cp", out);
    if (full_fold && fout != ORI_FORMAT_SVG) return cli_usage(cmd, "--full-fold applies to .svg output");
    if ((label_faces || label_edges) && fout != ORI_FORMAT_SVG) return cli_usage(cmd, "--labels applies to .svg output");
    int rc = cli_check_json_output(cmd, out, json);
    if (rc != CLI_EXIT_OK) return rc;

    ori_fold *doc = NULL;
    ori_pattern *p = NULL;
    rc = cli_input_load(cmd, in_path, &in, &doc, &p);
    if (rc != CLI_EXIT_OK) return rc;
    ori_error err;
    ori_status st = ORI_OK;
    if (fout == ORI_FORMAT_FOLD && !in.drawing) {
        // FOLD to FOLD: the document is kept whole and its frame rewritten; with --frame, that
        // frame alone is extracted into a document of its own.
        ori_fold *x = NULL;
        if (in.frame_given) {
            st = ori_fold_extract_frame(doc, in.frame, &x, &err);
            if (st == ORI_OK) {
                ori_fold_destroy(doc);
                doc = x;
            }
        }
        if (st == ORI_OK) st = ori_fold_set_pattern(doc, in.frame_given ? 0 : in.frame, p, &err);
        if (st == ORI_OK) {
            if (cli_is_stdout(out)) {
                char *text = ori_fold_to_string(doc);
                fputs(text, stdout);
                ori_buffer_free(text);
            } else {
                st = ori_fold_save_file(doc, out, &err);
            }
        }
    } else if (fout == ORI_FORMAT_FOLD) {
        // A drawing: written directly (no JSON tree), so a large one costs its text only.
        ori_fold_field extra[1] = {{"frame_classes", "[\"creasePattern\"]"}};
        if (cli_is_stdout(out)) {
            char *text = ori_pattern_to_fold_text(p, extra, 1, NULL);
            fputs(text, stdout);
            ori_buffer_free(text);
        } else {
            st = ori_pattern_save_fold(p, extra, 1, out, &err);
        }
    } else {
        ori_svg_write_def sdef = ori_default_svg_write_def();
        sdef.full_fold = full_fold;
        sdef.label_faces = label_faces;
        sdef.label_edges = label_edges;
        st = ori_export_file(p, fout, &sdef, out, &err);
    }
    if (st == ORI_ERR_UNSUPPORTED) rc = cli_input_error(cmd, in_path, &err);
    else if (st != ORI_OK) rc = cli_input_error(cmd, out, &err);
    if (rc == CLI_EXIT_OK && !cli_is_stdout(out)) {
        json_t *o = json_object();
        json_object_set_new(o, "input", json_string(in_path));
        json_object_set_new(o, "output", json_string(out));
        json_object_set_new(o, "format", json_string(ori_format_name(fout)));
        if (!in.drawing) json_object_set_new(o, "frame", json_integer(in.frame));
        cli_json_counts(o, p);
        if (in.drawing) json_object_set_new(o, "import", import_json(&in.stats));
        char frame[32] = "";
        if (in.frame_given) snprintf(frame, sizeof frame, ", frame %d", in.frame);
        cli_print_summary(json, o, "%s: %d vertices, %d edges, %d faces (from %s%s)", out, ori_pattern_vertex_count(p),
                          ori_pattern_edge_count(p), ori_pattern_face_count(p), in_path, frame);
    }
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    return rc;
}

const cli_command cli_cmd_convert = {
    "convert",
    "convert between FOLD, SVG, ORIPA .opx and .cp (by extension)",
    "usage: orikin convert IN OUT [options]   (or IN -o OUT)\n"
    "\n"
    "Read IN, validate it and write OUT; formats by extension: .fold, .svg (Origami Simulator\n"
    "colours), .opx and .cp (ORIPA); OUT - writes FOLD text to stdout. FOLD to FOLD is a\n"
    "normalised rewrite: every field, including unknown and custom ones, is kept; indices are\n"
    "unchanged; computed faces are added when IN had none. With --frame N it extracts that frame\n"
    "alone: a document whose top level is the frame (inherited fields resolved). SVG, OPX and CP\n"
    "drawings are planarised (crossing and overlapping lines split and merged, nearby points\n"
    "welded, crease ends that stop short of a line by less than the drawn line width joined to\n"
    "it) into a crease pattern with faces; what was joined, crease ends left dangling and\n"
    "separate pieces are reported on stderr with what would fix them. Their y axis points down\n"
    "and is flipped (docs/formats.md). ORIPA has no F or U creases: such patterns are refused\n"
    "as .cp/.opx. OUT is written atomically: nothing is written when IN is bad (exit 3). Prints\n"
    "a one-line summary (--json: an object).\n"
    "\n"
    "options:\n" CLI_INPUT_HELP
    "  -o OUT             the output, as the other commands take it (instead of the second\n"
    "                     argument)\n"
    "  --full-fold        SVG output: mountains and valleys at opacity 1 (fold flat) whatever\n"
    "                     their fold angle (creases at 0 are written at 1 anyway: no target)\n"
    "  --labels WHAT      SVG output: write faces (index and name), edges (index) or all\n"
    "  --json             print {input, output, format, frame, vertices, edges, faces,\n"
    "                     edges_by_assignment, import: {segments, ignored_elements,\n"
    "                     unsupported_elements, stroke_width, gap_rel, gaps_closed,\n"
    "                     short_creases_merged,\n"
    "                     largest_gap_rel, dangling, dangling_example, parts, part_example}}\n"
    "\n"
    "example: orikin convert birdBase.svg bird.fold\n",
    run,
    NULL,
};
