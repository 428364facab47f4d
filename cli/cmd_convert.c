// orikin convert: rewrite a pattern in another file (format chosen by extension).
#include <string.h>

#include "cli.h"

static const char *extension(const char *path)
{
    const char *dot = strrchr(path, '.');
    const char *slash = strrchr(path, '/');
    if (!dot || (slash && dot < slash)) return "";
    return dot + 1;
}

static int run(int argc, char **argv)
{
    const char *in = NULL, *out = NULL;
    int frame = 0;
    bool weld = false;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--weld") == 0) weld = true;
        else if (strcmp(argv[i], "--frame") == 0) {
            const char *v = cli_option_value("convert", argc, argv, &i);
            if (!v) return CLI_EXIT_USAGE;
            if (!cli_parse_int(v, &frame) || frame < 0) return cli_usage("convert", "--frame needs a frame number ≥ 0");
        } else if (argv[i][0] == '-' && argv[i][1] != '\0') return cli_usage("convert", "unknown option %s", argv[i]);
        else if (!in) in = argv[i];
        else if (!out) out = argv[i];
        else return cli_usage("convert", "expected IN and OUT only");
    }
    if (!in || !out) return cli_usage("convert", "missing IN or OUT");
    if (strcmp(extension(in), "fold") != 0) return cli_usage("convert", "cannot read '.%s' files", extension(in));
    if (strcmp(extension(out), "fold") != 0) return cli_usage("convert", "cannot write '.%s' files", extension(out));

    ori_fold *doc;
    ori_pattern *p;
    int rc = cli_load_pattern("convert", in, frame, weld, &doc, &p);
    if (rc != CLI_EXIT_OK) return rc;
    ori_error err;
    ori_status st = ori_fold_set_pattern(doc, frame, p, &err);
    if (st == ORI_OK) st = ori_fold_save_file(doc, out, &err);
    ori_pattern_destroy(p);
    ori_fold_destroy(doc);
    if (st != ORI_OK) return cli_input_error("convert", out, &err);
    return CLI_EXIT_OK;
}

const cli_command cli_cmd_convert = {
    "convert",
    "rewrite a pattern (normalised FOLD; other formats by extension)",
    "usage: orikin convert IN OUT [--frame N] [--weld]\n"
    "\n"
    "Read IN, validate it and write OUT. FOLD to FOLD is a normalised rewrite: every field,\n"
    "including unknown and custom ones, is kept; indices are unchanged; computed faces are\n"
    "added when IN had none. OUT is written atomically (nothing is left on failure).\n"
    "\n"
    "options:\n"
    "  --frame N   frame whose pattern is validated and rewritten (default 0)\n"
    "  --weld      merge vertices closer than the length tolerance (renumbers vertices)\n"
    "\n"
    "example: orikin convert in.fold out.fold\n",
    run,
};
