// Helpers shared by the commands: help and error output, number parsing, FOLD loading.
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

bool cli_is_help(const char *arg) { return strcmp(arg, "-h") == 0 || strcmp(arg, "--help") == 0; }

int cli_print_help(const cli_command *cmd)
{
    fputs(cmd->help, stdout);
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
        return cli_input_fail(cmd, path, "frame %d does not exist (frames 0 to %d)", frame, frames - 1);
    }
    ori_build_def def = ori_default_build_def();
    def.weld = weld;
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
    return CLI_EXIT_OK;
}

void cli_print_json(json_t *value)
{
    char *raw = json_dumps(value, JSON_ENCODE_ANY | JSON_COMPACT | JSON_REAL_PRECISION(17));
    json_decref(value);
    if (!raw) return;
    char *text = ori_json_normalize(raw, false, NULL);
    free(raw);
    if (text) {
        fputs(text, stdout);
        ori_buffer_free(text);
    }
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
    if (ori_fold_set_pattern(doc, 0, p, &err) != ORI_OK) return cli_input_error(cmd, out ? out : "-", &err);
    if (!out) {
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
