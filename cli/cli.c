// Helpers shared by the commands: help and error output, number parsing, FOLD loading.
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <orikin/formats.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

bool cli_is_help(const char *arg) { return strcmp(arg, "-h") == 0 || strcmp(arg, "--help") == 0; }

int cli_print_help(const cli_command *cmd)
{
    fputs(cmd->help, stdout);
    if (cmd->help_more) fputs(cmd->help_more, stdout);
    return CLI_EXIT_OK;
}

int cli_usage(const char *cmd, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "orikin %s: ", cmd);
    vfprintf(stderr, fmt, ap);
    fprintf(stderr, "\nTry 'orikin %s -h'.\n", cmd);
    va_end(ap);
    return CLI_EXIT_USAGE;
}

int cli_input_error(const char *cmd, const char *file, const ori_error *error)
{
    char buf[512];
    ori_error_format(error, buf, sizeof buf);
    fprintf(stderr, "orikin %s: %s: %s\n", cmd, file, buf);
    return CLI_EXIT_INPUT;
}

int cli_input_fail(const char *cmd, const char *file, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "orikin %s: %s: ", cmd, file);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    return CLI_EXIT_INPUT;
}

bool cli_parse_double(const char *s, double *out)
{
    if (!s || !*s) return false;
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (*end != '\0' || errno == ERANGE || !isfinite(v)) return false;
    *out = v;
    return true;
}

bool cli_parse_int(const char *s, int *out)
{
    if (!s || !*s) return false;
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (*end != '\0' || errno == ERANGE || v < -2147483647L || v > 2147483647L) return false;
    *out = (int)v;
    return true;
}

int cli_option_frame(const char *cmd, int argc, char **argv, int *i, int *frame)
{
    const char *v = cli_option_value(cmd, argc, argv, i);
    if (!v) return CLI_EXIT_USAGE;
    if (!cli_parse_int(v, frame) || *frame < 0) return cli_usage(cmd, "--frame needs a frame number ≥ 0");
    return CLI_EXIT_OK;
}

bool cli_parse_crease_assignment(const char *s, ori_assignment *out)
{
    return s && strlen(s) == 1 && ori_assignment_from_char(s[0], out) &&
           (ori_assignment_is_fold(*out) || *out == ORI_ASSIGN_FLAT);
}

bool cli_parse_doubles(const char *s, double *out, int n)
{
    if (!s) return false;
    const char *p = s;
    for (int i = 0; i < n; ++i) {
        char *end;
        errno = 0;
        double v = strtod(p, &end);
        if (end == p || errno == ERANGE || !isfinite(v)) return false;
        out[i] = v;
        if (i + 1 < n) {
            if (*end != ',') return false;
            p = end + 1;
        } else if (*end != '\0') {
            return false;
        }
    }
    return true;
}

int cli_parse_int_list(const char *s, int *out, int cap)
{
    if (!s || !*s) return -1;
    int n = 0;
    const char *p = s;
    for (;;) {
        char *end;
        errno = 0;
        long v = strtol(p, &end, 10);
        if (end == p || errno == ERANGE || v < -2147483647L || v > 2147483647L) return -1;
        if (n >= cap) return -1;
        out[n++] = (int)v;
        if (*end == '\0') return n;
        if (*end != ',') return -1;
        p = end + 1;
    }
}

int cli_int_list_usage(const char *cmd, const char *opt, const char *value, int cap)
{
    int n = 1;
    for (const char *q = value; *q; ++q) n += *q == ',';
    if (n > cap) return cli_usage(cmd, "%s takes at most %d edges, got %d", opt, cap, n);
    return cli_usage(cmd, "%s needs comma-separated edge indices, got '%s'", opt, value);
}

const char *cli_option_value(const char *cmd, int argc, char **argv, int *i)
{
    if (*i + 1 >= argc) {
        cli_usage(cmd, "option %s needs a value", argv[*i]);
        return NULL;
    }
    *i += 1;
    return argv[*i];
}

int cli_load_pattern(const char *cmd, const char *path, int frame, bool weld, ori_fold **doc,
                     ori_pattern **pattern)
{
    ori_error err;
    *doc = NULL;
    *pattern = NULL;
    ori_status st = ori_fold_load_file(path, doc, &err);
    if (st != ORI_OK) return cli_input_error(cmd, path, &err);
    int frames = ori_fold_frame_count(*doc);
    if (frame < 0 || frame >= frames) {
        ori_fold_destroy(*doc);
        *doc = NULL;
        return cli_value_fail(cmd, path, "--frame", "frame %d does not exist (frames 0 to %d)", frame, frames - 1);
    }
    ori_build_def def = ori_default_build_def();
    def.weld = weld;
    def.planarize = true;
    st = ori_fold_get_pattern(*doc, frame, &def, pattern, &err);
    if (st != ORI_OK) {
        ori_fold_destroy(*doc);
        *doc = NULL;
        if (frame != 0) {
            char buf[512];
            ori_error_format(&err, buf, sizeof buf);
            fprintf(stderr, "orikin %s: %s: frame %d: %s\n", cmd, path, frame, buf);
            return CLI_EXIT_INPUT;
        }
        return cli_input_error(cmd, path, &err);
    }
    int absent = ori_pattern_absent_fold_angle_count(*pattern);
    if (absent > 0)
        fprintf(stderr, "orikin %s: %s: note: %d edge(s) have a null edges_foldAngle (e.g. Origami Simulator's boundary "
                        "edges): read as 0\n", cmd, path, absent);
    int from = ori_pattern_planarized_from(*pattern);
    if (from > 0)
        fprintf(stderr, "orikin %s: %s: note: its edges cross or overlap: planarised %d edges into %d (edge numbers are "
                        "the planarised ones; 'orikin convert' writes them)\n", cmd, path, from,
                ori_pattern_edge_count(*pattern));
    return CLI_EXIT_OK;
}

// Compact JSON of v on f, numbers by ori_format_real: the text ori_json_normalize makes of
// jansson's dump, written directly (no %.17g printing and no re-parse: a fold of 2 M angles
// prints in a fraction of the time).
static void write_json_string(FILE *f, const char *s, size_t n)
{
    putc('"', f);
    size_t run = 0; // bytes copied as they are, flushed before each escape
    for (size_t i = 0; i < n; ++i) {
        unsigned char c = (unsigned char)s[i];
        const char *esc = NULL;
        char u[8];
        switch (c) {
        case '"': esc = "\\\""; break;
        case '\\': esc = "\\\\"; break;
        case '\n': esc = "\\n"; break;
        case '\r': esc = "\\r"; break;
        case '\t': esc = "\\t"; break;
        case '\b': esc = "\\b"; break;
        case '\f': esc = "\\f"; break;
        default:
            if (c < 0x20) {
                snprintf(u, sizeof u, "\\u%04x", c);
                esc = u;
            }
        }
        if (!esc) {
            run++;
            continue;
        }
        fwrite(s + i - run, 1, run, f);
        run = 0;
        fputs(esc, f);
    }
    fwrite(s + n - run, 1, run, f);
    putc('"', f);
}

static void write_json(FILE *f, const json_t *v)
{
    char num[40];
    switch (json_typeof(v)) {
    case JSON_OBJECT: {
        putc('{', f);
        const char *key;
        json_t *val;
        bool first = true;
        json_object_foreach((json_t *)v, key, val)
        {
            if (!first) putc(',', f);
            first = false;
            write_json_string(f, key, strlen(key));
            putc(':', f);
            write_json(f, val);
        }
        putc('}', f);
        break;
    }
    case JSON_ARRAY:
        putc('[', f);
        for (size_t i = 0; i < json_array_size(v); ++i) {
            if (i) putc(',', f);
            write_json(f, json_array_get(v, i));
        }
        putc(']', f);
        break;
    case JSON_STRING: write_json_string(f, json_string_value(v), json_string_length(v)); break;
    case JSON_INTEGER: fprintf(f, "%" JSON_INTEGER_FORMAT, json_integer_value(v)); break;
    case JSON_REAL:
        ori_format_real(json_real_value(v), num, sizeof num);
        fputs(num, f);
        break;
    case JSON_TRUE: fputs("true", f); break;
    case JSON_FALSE: fputs("false", f); break;
    case JSON_NULL: fputs("null", f); break;
    }
}

void cli_print_json(json_t *value)
{
    if (!value) return;
    write_json(stdout, value);
    putchar('\n');
    json_decref(value);
}

static const char *finishing_command = NULL;

void cli_set_command(const char *cmd) { finishing_command = cmd; }

int cli_finish(int code)
{
    errno = 0;
    if (fflush(stdout) != 0 || ferror(stdout)) {
        int e = errno;
        fprintf(stderr, "orikin%s%s: stdout: cannot write: %s\n", finishing_command ? " " : "",
                finishing_command ? finishing_command : "", e ? strerror(e) : "output error");
        return CLI_EXIT_INPUT;
    }
    return code;
}

int cli_write_pattern(const char *cmd, ori_fold *doc, const ori_pattern *p, const char *out)
{
    ori_error err;
    if (!cli_is_stdout(out)) {
        ori_format f = ori_format_from_path(out);
        if (f == ORI_FORMAT_SVG || f == ORI_FORMAT_CP || f == ORI_FORMAT_OPX) {
            if (ori_export_file(p, f, NULL, out, &err) != ORI_OK) return cli_input_error(cmd, out, &err);
            return CLI_EXIT_OK;
        }
    }
    if (ori_fold_set_pattern(doc, 0, p, &err) != ORI_OK) return cli_input_error(cmd, out ? out : "-", &err);
    if (cli_is_stdout(out)) {
        char *text = ori_fold_to_string(doc);
        fputs(text, stdout);
        ori_buffer_free(text);
        return CLI_EXIT_OK;
    }
    if (ori_fold_save_file(doc, out, &err) != ORI_OK) {
        char buf[512];
        ori_error_format(&err, buf, sizeof buf);
        fprintf(stderr, "orikin %s: %s: %s\n", cmd, out, buf);
        return CLI_EXIT_INPUT;
    }
    return CLI_EXIT_OK;
}

int cli_find_face(const char *cmd, const char *file, const ori_pattern *p, const char *spec, int *face)
{
    int idx;
    if (cli_parse_int(spec, &idx)) {
        if (idx < 0 || idx >= ori_pattern_face_count(p))
            return cli_input_fail(cmd, file, "face %d does not exist (faces 0 to %d)", idx, ori_pattern_face_count(p) - 1);
        *face = idx;
        return CLI_EXIT_OK;
    }
    idx = ori_pattern_find_face_by_name(p, spec);
    if (idx == ORI_NULL_INDEX) {
        if (ori_pattern_find_tree_node(p, spec) != ORI_NULL_INDEX)
            return cli_input_fail(cmd, file, "%s is not a folding element any more (it was split; see orikin tree)", spec);
        return cli_input_fail(cmd, file, "no face named %s (see orikin tree %s)", spec, file);
    }
    *face = idx;
    return CLI_EXIT_OK;
}

// --- conventions shared by every command ---------------------------------------------------------

static const char *canonical(const char *name) { return strcmp(name, "-o") == 0 ? "--output" : name; }

bool cli_once(const char *cmd, cli_seen *seen, const char *name)
{
    const char *c = canonical(name);
    for (int k = 0; k < seen->count; ++k)
        if (strcmp(seen->names[k], c) == 0) {
            cli_usage(cmd, "%s given twice (it takes one value)", name);
            return false;
        }
    if (seen->count < (int)(sizeof seen->names / sizeof seen->names[0])) seen->names[seen->count++] = c;
    return true;
}

const char *cli_option_once(const char *cmd, int argc, char **argv, int *i, cli_seen *seen)
{
    if (!cli_once(cmd, seen, argv[*i])) return NULL;
    return cli_option_value(cmd, argc, argv, i);
}

int cli_option_frame_once(const char *cmd, int argc, char **argv, int *i, cli_seen *seen, int *frame)
{
    if (!cli_once(cmd, seen, argv[*i])) return CLI_EXIT_USAGE;
    return cli_option_frame(cmd, argc, argv, i, frame);
}

int cli_value_fail(const char *cmd, const char *file, const char *option, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    if (file) fprintf(stderr, "orikin %s: %s: %s: ", cmd, file, option);
    else fprintf(stderr, "orikin %s: %s: ", cmd, option);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    return CLI_EXIT_USAGE;
}

int cli_find_face_option(const char *cmd, const char *file, const ori_pattern *p, const char *option, const char *spec,
                         int *face)
{
    int idx;
    if (cli_parse_int(spec, &idx)) {
        if (idx < 0 || idx >= ori_pattern_face_count(p))
            return cli_value_fail(cmd, file, option, "face %d does not exist (faces 0 to %d)", idx,
                                  ori_pattern_face_count(p) - 1);
        *face = idx;
        return CLI_EXIT_OK;
    }
    idx = ori_pattern_find_face_by_name(p, spec);
    if (idx == ORI_NULL_INDEX) {
        if (ori_pattern_find_tree_node(p, spec) != ORI_NULL_INDEX)
            return cli_value_fail(cmd, file, option, "%s is not a folding element any more (it was split; see orikin tree)",
                                  spec);
        return cli_value_fail(cmd, file, option, "no face named %s (see orikin info --faces %s)", spec, file);
    }
    *face = idx;
    return CLI_EXIT_OK;
}

// --- reading a pattern ---------------------------------------------------------------------------

void cli_input_init(cli_input *in)
{
    memset(in, 0, sizeof *in);
    in->import = ori_default_import_def();
}

int cli_input_option(const char *cmd, int argc, char **argv, int *i, cli_input *in, cli_seen *seen)
{
    const char *a = argv[*i], *v;
    if (strcmp(a, "--frame") == 0) {
        if (cli_option_frame_once(cmd, argc, argv, i, seen, &in->frame) != CLI_EXIT_OK) return -CLI_EXIT_USAGE;
        in->frame_given = true;
        return 1;
    }
    if (strcmp(a, "--weld") == 0) {
        in->weld = true;
        return 1;
    }
    if (strcmp(a, "--tolerance") == 0) {
        if (!(v = cli_option_once(cmd, argc, argv, i, seen))) return -CLI_EXIT_USAGE;
        if (!cli_parse_double(v, &in->import.weld_rel) || !(in->import.weld_rel > 0.0 && in->import.weld_rel < 1.0)) {
            cli_usage(cmd, "--tolerance needs a number in (0, 1) (a fraction of the drawing's size), got '%s'", v);
            return -CLI_EXIT_USAGE;
        }
        in->import.heal_splits = false; // (the tolerance asked for is the one used)
        if (!in->import_option) in->import_option = a;
        return 1;
    }
    if (strcmp(a, "--gaps") == 0) {
        if (!(v = cli_option_once(cmd, argc, argv, i, seen))) return -CLI_EXIT_USAGE;
        if (strcmp(v, "auto") == 0) {
            in->import.gap_rel = ORI_IMPORT_GAP_AUTO;
        } else if (!cli_parse_double(v, &in->import.gap_rel) ||
                   !(in->import.gap_rel >= 0.0 && in->import.gap_rel <= ORI_IMPORT_GAP_MAX_REL)) {
            cli_usage(cmd, "--gaps needs auto or a number in [0, %g] (a fraction of the drawing's size), got '%s'",
                      ORI_IMPORT_GAP_MAX_REL, v);
            return -CLI_EXIT_USAGE;
        }
        if (!in->import_option) in->import_option = a;
        return 1;
    }
    if (strcmp(a, "--flatten-curves") == 0) {
        if (!(v = cli_option_once(cmd, argc, argv, i, seen))) return -CLI_EXIT_USAGE;
        int n;
        if (!cli_parse_int(v, &n) || n < 1 || n > ORI_IMPORT_CURVE_SEGMENTS_MAX) {
            cli_usage(cmd, "--flatten-curves needs a whole number of segments per curve in [1, %d], got '%s'",
                      ORI_IMPORT_CURVE_SEGMENTS_MAX, v);
            return -CLI_EXIT_USAGE;
        }
        in->import.curve_segments = n;
        if (!in->import_option) in->import_option = a;
        return 1;
    }
    if (strcmp(a, "--keep-collinear") == 0 || strcmp(a, "--keep-holes") == 0) {
        if (a[7] == 'c') in->import.merge_collinear = false;
        else in->import.remove_holes = false;
        if (!in->import_option) in->import_option = a;
        return 1;
    }
    return 0;
}

// What the import of a drawing found, as warnings that say what would fix it.
static void import_warnings(const char *cmd, const char *path, const ori_pattern *p, const ori_import_stats *s,
                            int curve_segments)
{
    if (s->ignored_elements > 0 && s->ignored_colour[0])
        fprintf(stderr,
                "orikin %s: %s: warning: %d element(s) ignored: stroke \"%s\" (and others) is not a crease colour "
                "(#000000 B, #ff0000 M, #0000ff V, #00ff00 C, #ffff00 F, #ff00ff U)\n",
                cmd, path, s->ignored_elements, s->ignored_colour);
    else if (s->ignored_elements > 0)
        fprintf(stderr, "orikin %s: %s: warning: %d auxiliary or cut-model line(s) skipped\n", cmd, path, s->ignored_elements);
    if (s->flattened_curves > 0)
        fprintf(stderr,
                "orikin %s: %s: note: %d curve(s), arc(s) or circle(s) flattened into %d straight crease(s) each "
                "(--flatten-curves): an approximation of the drawing\n",
                cmd, path, s->flattened_curves, curve_segments);
    if (s->degenerate_aux > 0)
        fprintf(stderr, "orikin %s: %s: note: %d of them had a coordinate that is not a number (NaN or Infinity)\n", cmd,
                path, s->degenerate_aux);
    if (s->unsupported_elements > 0)
        fprintf(stderr, "orikin %s: %s: warning: %d element(s) orikin does not read (use, image, text…) skipped\n", cmd,
                path, s->unsupported_elements);
    if (!p) return;
    if (s->gaps_closed > 0)
        fprintf(stderr,
                "orikin %s: %s: note: joined %d crease end(s) that stopped short of a line by up to %.2g of the drawing's "
                "size (%.3g), within the width its lines are drawn with (%.3g): --gaps 0 keeps them apart\n",
                cmd, path, s->gaps_closed, s->largest_gap_rel, s->largest_gap_rel / s->gap_rel * s->stroke_width,
                s->stroke_width);
    if (s->short_creases_merged > 0)
        fprintf(stderr,
                "orikin %s: %s: note: merged the ends of %d crease(s) shorter than the width its lines are drawn with "
                "(%.3g): lines meeting a hair beside a vertex meet at it (--gaps 0 keeps them)\n",
                cmd, path, s->short_creases_merged, s->stroke_width);
    if (s->clipped > 0)
        fprintf(stderr,
                "orikin %s: %s: note: clipped the creases drawn past the border: %d crease piece(s) outside the sheet "
                "dropped (%d face(s))\n",
                cmd, path, s->clipped, s->clipped_faces);
    if (s->healed_weld_rel > 0.0)
        fprintf(stderr,
                "orikin %s: %s: note: lines drawn to meet missed each other and left the paper in %d pieces that no "
                "crease joined: welded points within %.2g of the drawing's size instead of %.2g (closer than the width "
                "its lines are drawn with, %.3g): --tolerance %.2g keeps them apart\n",
                cmd, path, s->healed_sheets, s->healed_weld_rel, ORI_TOL_IMPORT_WELD_REL, s->stroke_width,
                ORI_TOL_IMPORT_WELD_REL);
    if (s->split_vertex != ORI_NULL_INDEX) {
        ori_v3 x = ori_pattern_vertex(p, s->split_vertex);
        fprintf(stderr,
                "orikin %s: %s: warning: the paper is %d pieces that no crease joins (vertex %d at (%g, %g) is on one "
                "that only boundary or cut lines or corners join to the rest): the sheet falls apart when folded",
                cmd, path, s->sheets, s->split_vertex, x.x, x.y);
        if (s->split_tolerance_rel > 0.0)
            fprintf(stderr, "; lines drawn to meet miss each other: --tolerance %g joins them\n", s->split_tolerance_rel);
        else
            fprintf(stderr, "; where the paper should hang together, draw a crease (boundary and cut lines separate "
                            "it)\n");
    }
    if (s->dangling > 0) {
        ori_v3 x = ori_pattern_vertex(p, s->dangling_example);
        fprintf(stderr, "orikin %s: %s: warning: %d crease end(s) touch nothing (e.g. vertex %d at (%g, %g))", cmd, path,
                s->dangling, s->dangling_example, x.x, x.y);
        if (s->dangling_gap_rel > 0.0 && s->dangling_gap_rel * 1.05 <= ORI_IMPORT_GAP_MAX_REL)
            fprintf(stderr, "; they miss another line by up to %.2g of the drawing's size: --gaps %.2g would join them\n",
                    s->dangling_gap_rel, s->dangling_gap_rel * 1.05);
        else
            fprintf(stderr, "; no line is within %g of the drawing's size (a crease must end on another line or the "
                            "boundary)\n", ORI_IMPORT_GAP_MAX_REL);
    }
    if (s->parts > 1) {
        ori_v3 x = ori_pattern_vertex(p, s->part_example);
        fprintf(stderr,
                "orikin %s: %s: warning: the drawing is %d separate pieces (vertex %d at (%g, %g) is not connected to "
                "vertex 0); to fold it as one sheet, draw the lines that join them, or widen --tolerance or --gaps if "
                "they should touch\n",
                cmd, path, s->parts, s->part_example, x.x, x.y);
    }
}

int cli_input_load(const char *cmd, const char *path, cli_input *in, ori_fold **doc, ori_pattern **pattern)
{
    *doc = NULL;
    *pattern = NULL;
    ori_format f = ori_format_from_path(path);
    in->drawing = f == ORI_FORMAT_SVG || f == ORI_FORMAT_OPX || f == ORI_FORMAT_CP;
    if (in->drawing && (in->frame_given || in->weld))
        return cli_usage(cmd, "%s applies to .fold input, not to %s", in->frame_given ? "--frame" : "--weld", path);
    if (!in->drawing && in->import_option)
        return cli_usage(cmd, "%s applies to drawing input (.svg, .opx, .cp), not to %s", in->import_option, path);
    if (!in->drawing) return cli_load_pattern(cmd, path, in->frame, in->weld, doc, pattern);
    ori_error err;
    ori_status st = ori_import_file(path, f, &in->import, pattern, &in->stats, &err);
    if (st == ORI_OK || st == ORI_ERR_NOT_FOUND) import_warnings(cmd, path, *pattern, &in->stats, in->import.curve_segments); // (why nothing was found)
    if (st != ORI_OK) return cli_input_error(cmd, path, &err);
    *doc = ori_fold_create();
    ori_fold_set_custom(*doc, 0, "frame_classes", "[\"creasePattern\"]", NULL);
    return CLI_EXIT_OK;
}

// --- writing a pattern and the summary -------------------------------------------------------------

bool cli_is_stdout(const char *out) { return !out || strcmp(out, "-") == 0; }

int cli_write_frame_pattern(const char *cmd, ori_fold **doc, const cli_input *in, const ori_pattern *p, const char *out)
{
    if (in->frame_given && !in->drawing) {
        ori_fold *x = NULL;
        ori_error err;
        if (ori_fold_extract_frame(*doc, in->frame, &x, &err) != ORI_OK) return cli_input_error(cmd, "-", &err);
        ori_fold_destroy(*doc);
        *doc = x;
    }
    return cli_write_pattern(cmd, *doc, p, out);
}

int cli_check_json_output(const char *cmd, const char *out, bool json)
{
    if (json && cli_is_stdout(out))
        return cli_usage(cmd, "--json needs -o FILE (without it the FOLD text goes to stdout)");
    return CLI_EXIT_OK;
}

void cli_json_counts(json_t *obj, const ori_pattern *p)
{
    json_object_set_new(obj, "vertices", json_integer(ori_pattern_vertex_count(p)));
    json_object_set_new(obj, "edges", json_integer(ori_pattern_edge_count(p)));
    json_object_set_new(obj, "faces", json_integer(ori_pattern_face_count(p)));
    json_t *by = json_object();
    for (int a = 0; a < ORI_ASSIGN_COUNT; ++a) {
        int n = ori_pattern_count_assignment(p, (ori_assignment)a);
        char key[2] = {ori_assignment_to_char((ori_assignment)a), '\0'};
        if (n) json_object_set_new(by, key, json_integer(n));
    }
    json_object_set_new(obj, "edges_by_assignment", by);
}

void cli_print_summary(bool json, json_t *obj, const char *fmt, ...)
{
    if (json) {
        cli_print_json(obj);
        return;
    }
    json_decref(obj);
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    putchar('\n');
}
