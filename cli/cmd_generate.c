// orikin generate: standard tessellation crease patterns (Miura-ori, Yoshimura, waterbomb,
// square twist, Kresling) written as FOLD.
#include <math.h>
#include <orikin/formats.h>
#include <orikin/generate.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

// Options and the parameter each sets: an option applies to the tessellations that read its
// parameter (the library's table, ori_tessellation_params).
enum opt { OPT_ROWS, OPT_COLS, OPT_SIDES, OPT_ANGLE, OPT_WIDTH, OPT_HEIGHT, OPT_TWIST_SIZE, OPT_COUNT };
static const struct {
    const char *name;
    unsigned param;
} options[OPT_COUNT] = {
    {"--rows", ORI_GEN_ROWS},   {"--cols", ORI_GEN_COLS},     {"--sides", ORI_GEN_SIDES},
    {"--angle", ORI_GEN_ANGLE}, {"--width", ORI_GEN_WIDTH},   {"--height", ORI_GEN_HEIGHT},
    {"--twist-size", ORI_GEN_TWIST_SIZE},
};

static bool applies(int o, ori_tessellation kind)
{
    // Yoshimura has no height of its own: --height there gives its angle (θ = atan(2h / w)).
    if (o == OPT_HEIGHT && (ori_tessellation_params(kind) & ORI_GEN_ANGLE) && !(ori_tessellation_params(kind) & ORI_GEN_HEIGHT))
        return true;
    return (ori_tessellation_params(kind) & options[o].param) != 0;
}

static const char *option_for_field(const char *field)
{
    static char buf[80];
    snprintf(buf, sizeof buf, "--%s", strcmp(field, "twist_size") == 0 ? "twist-size" : field);
    return buf;
}


// "orikin:generator": the tessellation and the parameters it read.
static void generator_json(const ori_generate_def *def, char *buf, size_t size)
{
    unsigned reads = ori_tessellation_params(def->kind);
    int n = snprintf(buf, size, "{\"kind\":\"%s\",\"rows\":%d", ori_tessellation_name(def->kind), def->rows);
    if (reads & ORI_GEN_SIDES) n += snprintf(buf + n, size - (size_t)n, ",\"sides\":%d", def->sides);
    if (reads & ORI_GEN_COLS) n += snprintf(buf + n, size - (size_t)n, ",\"cols\":%d", def->cols);
    if (reads & ORI_GEN_ANGLE)
        n += snprintf(buf + n, size - (size_t)n, ",\"angle_deg\":%.17g", ori_rad_to_deg_output(def->angle_rad));
    n += snprintf(buf + n, size - (size_t)n, ",\"width\":%.17g", def->width);
    if ((reads & ORI_GEN_BISTABLE_HEIGHT) && def->bistable_height)
        n += snprintf(buf + n, size - (size_t)n, ",\"height\":\"bistable\"");
    else if (reads & ORI_GEN_HEIGHT)
        n += snprintf(buf + n, size - (size_t)n, ",\"height\":%.17g", def->height);
    if (reads & ORI_GEN_TWIST_SIZE) n += snprintf(buf + n, size - (size_t)n, ",\"twist_size\":%.17g", def->twist_size);
    snprintf(buf + n, size - (size_t)n, "}");
}

// "[\"straight\",\"zigzag\",…]" for orikin:edges_class.
static char *classes_json(const ori_edge_class *cls, int n)
{
    size_t cap = 16 + (size_t)n * 14, len = 0;
    char *s = malloc(cap);
    if (!s) return NULL;
    s[len++] = '[';
    for (int e = 0; e < n; ++e) {
        len += (size_t)snprintf(s + len, cap - len, "%s\"%s\"", e ? "," : "", ori_edge_class_name(cls[e]));
    }
    s[len++] = ']';
    s[len] = '\0';
    return s;
}

static int run(int argc, char **argv)
{
    if (argc < 2 || argv[1][0] == '-') return cli_usage("generate", "missing KIND (miura, yoshimura, waterbomb, square-twist, kresling)");
    ori_tessellation kind;
    if (!ori_tessellation_from_name(argv[1], &kind))
        return cli_usage("generate", "unknown KIND '%s' (miura, yoshimura, waterbomb, square-twist, kresling)", argv[1]);
    ori_generate_def def = ori_default_generate_def(kind);
    const char *out = NULL;
    bool seen[OPT_COUNT] = {false}, json = false;
    double value[OPT_COUNT] = {0};
    cli_seen once = {0};
    for (int i = 2; i < argc; ++i) {
        if (strcmp(argv[i], "-o") == 0 || strcmp(argv[i], "--output") == 0) {
            if (!(out = cli_option_once("generate", argc, argv, &i, &once))) return CLI_EXIT_USAGE;
            continue;
        }
        if (strcmp(argv[i], "--json") == 0) {
            json = true;
            continue;
        }
        int o = 0;
        while (o < OPT_COUNT && strcmp(argv[i], options[o].name) != 0) ++o;
        if (o == OPT_COUNT) return cli_usage("generate", "unknown option %s", argv[i]);
        if (!applies(o, kind))
            return cli_usage("generate", "%s does not apply to %s", options[o].name, ori_tessellation_name(kind));
        const char *v = cli_option_once("generate", argc, argv, &i, &once);
        if (!v) return CLI_EXIT_USAGE;
        if (o == OPT_ROWS || o == OPT_COLS || o == OPT_SIDES) {
            // (an integer option: cli_parse_int refuses what does not fit)
            int n;
            if (!cli_parse_int(v, &n)) return cli_usage("generate", "%s needs an integer (got '%s')", options[o].name, v);
            value[o] = n;
        } else if (!cli_parse_double(v, &value[o])) {
            return cli_usage("generate", "%s needs a number (got '%s')", options[o].name, v);
        }
        seen[o] = true;
    }
    if (seen[OPT_ROWS]) def.rows = (int)value[OPT_ROWS];
    if (seen[OPT_COLS]) def.cols = (int)value[OPT_COLS];
    if (seen[OPT_SIDES]) def.sides = (int)value[OPT_SIDES];
    if (seen[OPT_ANGLE]) def.angle_rad = ori_deg_to_rad(value[OPT_ANGLE]);
    if (seen[OPT_WIDTH]) def.width = value[OPT_WIDTH];
    if (seen[OPT_TWIST_SIZE]) def.twist_size = value[OPT_TWIST_SIZE];
    if (seen[OPT_HEIGHT]) {
        if (!(ori_tessellation_params(kind) & ORI_GEN_HEIGHT)) {
            // Yoshimura's height is the strip height h; θ = atan(2h / w).
            if (seen[OPT_ANGLE]) return cli_usage("generate", "give --angle or --height for yoshimura, not both");
            if (!(value[OPT_HEIGHT] > 0.0)) return cli_usage("generate", "--height: must be a number > 0");
            def.angle_rad = atan2(2.0 * value[OPT_HEIGHT], def.width);
        } else {
            def.height = value[OPT_HEIGHT];
            def.bistable_height = false; // a height given replaces the bistable one
        }
    }

    int rc0 = cli_check_json_output("generate", out, json);
    if (rc0 != CLI_EXIT_OK) return rc0;
    ori_error err;
    ori_pattern *p = NULL;
    ori_edge_class *cls = NULL;
    ori_status st = ori_generate(&def, &p, &cls, &err);
    if (st == ORI_ERR_ARGUMENT) {
        const char *opt = err.field[0] ? option_for_field(err.field) : "";
        return cli_usage("generate", "%s%s%s", opt, *opt ? ": " : "", err.message);
    }
    if (st == ORI_ERR_LIMIT || st == ORI_ERR_RANGE || st == ORI_ERR_DEGENERATE || st == ORI_ERR_CROSSING ||
        st == ORI_ERR_DUPLICATE) {
        // The values given make a pattern orikin cannot hold (coordinates beyond ORI_COORD_MAX,
        // cells below the length tolerance, too many edges): a usage error naming the options.
        char buf[512], given[160] = "";
        for (int o = 0; o < OPT_COUNT; ++o)
            if (seen[o] && o != OPT_ANGLE)
                snprintf(given + strlen(given), sizeof given - strlen(given), "%s%s", given[0] ? ", " : "", options[o].name);
        return cli_usage("generate", "%s%sthese values give no pattern orikin can hold: %s", given,
                         given[0] ? ": " : "", ori_error_format(&err, buf, sizeof buf));
    }
    if (st != ORI_OK) {
        char buf[512];
        fprintf(stderr, "orikin generate: %s\n", ori_error_format(&err, buf, sizeof buf));
        return CLI_EXIT_INTERNAL;
    }

    // Written directly (no JSON tree): a 1000 x 1000 Miura-ori costs its text, not gigabytes.
    char title[160], title_json[200], params[512];
    snprintf(title, sizeof title, "%s, %d x %d", ori_tessellation_name(kind), def.rows,
             (ori_tessellation_params(kind) & ORI_GEN_SIDES) ? def.sides : def.cols);
    snprintf(title_json, sizeof title_json, "\"%s\"", title);
    generator_json(&def, params, sizeof params);
    char *classes = classes_json(cls, ori_pattern_edge_count(p));
    ori_fold_field extra[] = {{"file_title", title_json},
                              {"frame_classes", "[\"creasePattern\"]"},
                              {"orikin:generator", params},
                              {"orikin:edges_class", classes ? classes : "null"}};
    int n_extra = (int)(sizeof extra / sizeof extra[0]);
    int rc = CLI_EXIT_OK;
    if (!classes) {
        fprintf(stderr, "orikin generate: out of memory\n");
        rc = CLI_EXIT_INTERNAL;
    } else if (!cli_is_stdout(out)) {
        ori_format f = ori_format_from_path(out);
        if (f == ORI_FORMAT_SVG || f == ORI_FORMAT_CP || f == ORI_FORMAT_OPX) st = ori_export_file(p, f, NULL, out, &err);
        else st = ori_pattern_save_fold(p, extra, n_extra, out, &err);
        if (st != ORI_OK) {
            rc = cli_input_error("generate", out, &err);
        } else {
            json_t *o = json_object();
            json_object_set_new(o, "output", json_string(out));
            json_object_set_new(o, "title", json_string(title));
            cli_json_counts(o, p);
            json_t *gen = json_loads(params, 0, NULL);
            json_object_set_new(o, "generator", gen ? gen : json_null());
            cli_print_summary(json, o, "%s: %s, %d vertices, %d edges, %d faces", out, title, ori_pattern_vertex_count(p),
                              ori_pattern_edge_count(p), ori_pattern_face_count(p));
        }
    } else {
        char *text = ori_pattern_to_fold_text(p, extra, n_extra, NULL);
        fputs(text, stdout);
        ori_buffer_free(text);
    }
    free(classes);
    ori_buffer_free(cls);
    ori_pattern_destroy(p);
    return rc;
}

const cli_command cli_cmd_generate = {
    "generate",
    "tessellation crease patterns: miura, yoshimura, waterbomb, square-twist, kresling",
    "usage: orikin generate KIND [options] [-o OUT.fold [--json]]\n"
    "\n"
    "Generate a standard tessellation as a flat crease pattern with a flat-foldable mountain/\n"
    "valley assignment, fold angles 0 and faces, and write it as FOLD to OUT (or stdout). Each\n"
    "edge's family is stored in \"orikin:edges_class\" (e.g. Miura \"straight\" / \"zigzag\" /\n"
    "\"boundary\"), the parameters in \"orikin:generator\". Geometry, counts and edge index\n"
    "ranges: docs/generators.md. With -o a one-line summary is printed (--json: an object).\n"
    "\n"
    "kinds and their options (defaults in brackets):\n"
    "  miura         --rows --cols [4 4]  --angle γ: acute cell angle between zig-zag and\n"
    "                straight creases, 0 < γ < 90 [60]  --width a: straight segment [1]\n"
    "                --height b: zig-zag segment [1]\n"
    "  yoshimura     --rows --cols [4 4]  --angle θ: triangle base angle, 0 < θ ≤ 60 [30]\n"
    "                --width w: horizontal segment [1]  --height h: strip height (instead of\n"
    "                --angle: θ = atan(2h/w))\n"
    "  waterbomb     --rows --cols [4 4]  --width --height: base size [1 1], height/width ≥ 0.57735\n"
    "  square-twist  --rows --cols [4 4]  --angle α: pleat angle from the square's normal,\n"
    "                0 < α < 90 [45]  --width --height: tile size [1 1]  --twist-size f:\n"
    "                square side as a fraction of the largest that fits, 0 < f < 1 [0.5]\n"
    "  kresling      --rows: storeys [3]  --sides n ≥ 3 [6]  --angle φ: storey twist,\n"
    "                0 < φ < 90 − 180/n [30]  --width a: polygon side [1]  --height h: storey\n"
    "                height [the height at which a storey also folds flat]\n"
    "\n"
    "options:\n"
    "  -o, --output FILE   write the FOLD file here (atomically) instead of stdout (.svg, .cp,\n"
    "                      .opx: export in that format, creases drawn folded flat)\n"
    "  --json              with -o: print {output, title, vertices, edges, faces,\n"
    "                      edges_by_assignment, generator}\n"
    "\n"
    "Bad or inapplicable values exit with status 2 and the allowed range.\n"
    "\n"
    "example: orikin generate miura --rows 10 --cols 10 --angle 70 -o miura.fold\n",
    run,
    NULL,
};
