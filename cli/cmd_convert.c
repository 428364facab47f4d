// orikin convert: rewrite a pattern in another file (format chosen by extension).
#include <orikin/formats.h>
#include <string.h>

#include "cli.h"

static void warn_stats(const char *in, const ori_import_stats *s)
{
    if (s->ignored_elements > 0 && s->ignored_colour[0])
        fprintf(stderr,
                "orikin convert: %s: warning: %d element(s) ignored: stroke \"%s\" (and others) is not a crease "
                "colour (#000000 B, #ff0000 M, #0000ff V, #00ff00 C, #ffff00 F, #ff00ff U)\n",
                in, s->ignored_elements, s->ignored_colour);
    else if (s->ignored_elements > 0)
        fprintf(stderr, "orikin convert: %s: warning: %d auxiliary or cut-model line(s) skipped\n", in,
                s->ignored_elements);
    if (s->unsupported_elements > 0)
        fprintf(stderr, "orikin convert: %s: warning: %d element(s) orikin does not read (use, image, text…) skipped\n",
                in, s->unsupported_elements);
}

static int run(int argc, char **argv)
{
    const char *in = NULL, *out = NULL;
    int frame = 0;
    bool weld = false, frame_given = false, full_fold = false;
    ori_import_def idef = ori_default_import_def();
    bool import_option = false;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--weld") == 0) weld = true;
        else if (strcmp(argv[i], "--frame") == 0) {
            if (cli_option_frame("convert", argc, argv, &i, &frame) != CLI_EXIT_OK) return CLI_EXIT_USAGE;
            frame_given = true;
        } else if (strcmp(argv[i], "--tolerance") == 0) {
            const char *v = cli_option_value("convert", argc, argv, &i);
            if (!v) return CLI_EXIT_USAGE;
            if (!cli_parse_double(v, &idef.weld_rel) || !(idef.weld_rel > 0.0 && idef.weld_rel < 1.0))
                return cli_usage("convert", "--tolerance needs a number in (0, 1) (a fraction of the drawing's size)");
            import_option = true;
        } else if (strcmp(argv[i], "--keep-collinear") == 0) {
            idef.merge_collinear = false;
            import_option = true;
        } else if (strcmp(argv[i], "--keep-holes") == 0) {
            idef.remove_holes = false;
            import_option = true;
        } else if (strcmp(argv[i], "--full-fold") == 0) {
            full_fold = true;
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') return cli_usage("convert", "unknown option %s", argv[i]);
        else if (!in) in = argv[i];
        else if (!out) out = argv[i];
        else return cli_usage("convert", "expected IN and OUT only");
    }
    if (!in || !out) return cli_usage("convert", "missing IN or OUT");
    ori_format fin = ori_format_from_path(in), fout = ori_format_from_path(out);
    if (fin == ORI_FORMAT_UNKNOWN) return cli_usage("convert", "cannot read '%s': use .fold, .svg, .opx or .cp", in);
    if (fout == ORI_FORMAT_UNKNOWN) return cli_usage("convert", "cannot write '%s': use .fold, .svg, .opx or .cp", out);
    bool fold_in = fin == ORI_FORMAT_FOLD;
    if (fold_in && import_option)
        return cli_usage("convert", "--tolerance, --keep-collinear and --keep-holes apply to .svg, .opx and .cp input");
    if (!fold_in && (weld || frame_given)) return cli_usage("convert", "--frame and --weld apply to .fold input");
    if (full_fold && fout != ORI_FORMAT_SVG) return cli_usage("convert", "--full-fold applies to .svg output");

    ori_error err;
    ori_status st;
    ori_pattern *p = NULL;
    ori_fold *doc = NULL;
    if (fold_in) {
        int rc = cli_load_pattern("convert", in, frame, weld, &doc, &p);
        if (rc != CLI_EXIT_OK) return rc;
    } else {
        ori_import_stats stats;
        st = ori_import_file(in, fin, &idef, &p, &stats, &err);
        if (st == ORI_OK || st == ORI_ERR_NOT_FOUND) warn_stats(in, &stats); // why nothing was found
        if (st != ORI_OK) return cli_input_error("convert", in, &err);
    }

    if (fout == ORI_FORMAT_FOLD && doc) {
        // FOLD to FOLD: the document is kept whole, only the frame's pattern is rewritten.
        st = ori_fold_set_pattern(doc, frame, p, &err);
        if (st == ORI_OK) st = ori_fold_save_file(doc, out, &err);
    } else if (fout == ORI_FORMAT_FOLD) {
        ori_fold_field extra[1] = {{"frame_classes", "[\"creasePattern\"]"}};
        st = ori_pattern_save_fold(p, extra, 1, out, &err);
    } else {
        ori_svg_write_def sdef = ori_default_svg_write_def();
        sdef.full_fold = full_fold;
        st = ori_export_file(p, fout, &sdef, out, &err);
    }
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    if (st == ORI_ERR_UNSUPPORTED) return cli_input_error("convert", in, &err);
    if (st != ORI_OK) return cli_input_error("convert", out, &err);
    return CLI_EXIT_OK;
}

const cli_command cli_cmd_convert = {
    "convert",
    "convert between FOLD, SVG, ORIPA .opx and .cp (by extension)",
    "usage: orikin convert IN OUT [options]\n"
    "\n"
    "Read IN, validate it and write OUT; formats by extension: .fold, .svg (Origami Simulator\n"
    "colours), .opx and .cp (ORIPA). FOLD to FOLD is a normalised rewrite: every field,\n"
    "including unknown and custom ones, is kept; indices are unchanged; computed faces are\n"
    "added when IN had none. SVG, OPX and CP drawings are planarised (crossing and overlapping\n"
    "lines split and merged, nearby points welded) into a crease pattern with faces; their y\n"
    "axis points down and is flipped (docs/formats.md). OUT is written atomically: nothing is\n"
    "written when IN is bad (exit 3).\n"
    "\n"
    "options:\n"
    "  --frame N          FOLD input: frame whose pattern is converted (default 0)\n"
    "  --weld             FOLD input: merge vertices closer than the length tolerance\n"
    "  --tolerance REL    drawing input: weld points closer than REL × the drawing's diagonal\n"
    "                     (default 5e-5)\n"
    "  --keep-collinear   drawing input: keep vertices that only join two collinear edges\n"
    "  --keep-holes       drawing input: keep faces bounded only by boundary lines (holes)\n"
    "  --full-fold        SVG output: mountains and valleys at opacity 1 (fold flat) even when\n"
    "                     their fold angle is 0\n"
    "\n"
    "example: orikin convert birdBase.svg bird.fold\n",
    run,
};
