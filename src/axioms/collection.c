// The crease collection: built-in composites (the thesis' toolbar patterns) and user
// composites read from JSON, applied to a face through its bounding box.
#include <orikin/collection.h>

#include <stdio.h>
#include <stdlib.h>

#include "../core/json_internal.h"

// Largest composite file read, and most creases in one composite.
#define COMPOSITE_MAX_BYTES ((size_t)64 << 20)
#define COMPOSITE_MAX_CREASES 1000000

struct ori_composite {
    char name[ORI_NAME_MAX];
    ori_composite_crease *creases;
    int count, cap;
};

// The thesis' toolbar (Fig. 7-4, 10-1). The thesis writes its creases in screen coordinates
// (y pointing down): DiagonalL F1(s) = (−1, 1) + s((1, −1) − (−1, 1)) runs from the lower-left
// to the upper-right corner on screen, and the open corner (ch. 10) puts it on the lower-left
// sub-element from the sheet's centre to its corner. Here y points up, so the same creases are:
typedef struct builtin {
    const char *name;
    const char *summary;
    int count;
    double c[2][4]; // a.x, a.y, b.x, b.y in normalised coordinates
} builtin;

static const builtin builtins[] = {
    {"diagonal-left", "DiagonalL: the diagonal from the lower-left to the upper-right corner", 1, {{0, 0, 1, 1}}},
    {"diagonal-right", "DiagonalR: the diagonal from the lower-right to the upper-left corner", 1, {{1, 0, 0, 1}}},
    {"middle-h", "MiddleH: the horizontal line through the middle, left to right", 1, {{0, 0.5, 1, 0.5}}},
    {"middle-v", "MiddleV: the vertical line through the middle, bottom to top", 1, {{0.5, 0, 0.5, 1}}},
    {"cross", "middle-h, then middle-v on both halves", 2, {{0, 0.5, 1, 0.5}, {0.5, 0, 0.5, 1}}},
    {"diagonals", "diagonal-left, then diagonal-right on both halves", 2, {{0, 0, 1, 1}, {1, 0, 0, 1}}},
};
static const int builtin_count = (int)(sizeof builtins / sizeof builtins[0]);

int ori_collection_builtin_count(void) { return builtin_count; }

const char *ori_collection_builtin_name(int i)
{
    ORI_ASSERT(i >= 0 && i < builtin_count);
    return builtins[i].name;
}

const char *ori_collection_builtin_summary(int i)
{
    ORI_ASSERT(i >= 0 && i < builtin_count);
    return builtins[i].summary;
}

static const builtin *find_builtin(const char *name)
{
    for (int i = 0; i < builtin_count; ++i)
        if (strcmp(builtins[i].name, name) == 0) return &builtins[i];
    return NULL;
}

static void push_builtin(ori_composite *c, const builtin *b, bool has, ori_assignment a)
{
    for (int k = 0; k < b->count; ++k) {
        ori_composite_crease cr;
        cr.a = ori_v2_make(b->c[k][0], b->c[k][1]);
        cr.b = ori_v2_make(b->c[k][2], b->c[k][3]);
        cr.infinite = true;
        cr.has_assignment = has;
        cr.assignment = a;
        ORI__PUSH(c->creases, c->count, c->cap, cr);
    }
}

static void names_list(char *buf, size_t size)
{
    size_t k = 0;
    buf[0] = '\0';
    for (int i = 0; i < builtin_count && k + 1 < size; ++i) {
        int w = snprintf(buf + k, size - k, "%s%s", i ? ", " : "", builtins[i].name);
        if (w < 0) break;
        k += (size_t)w;
    }
}

ori_status ori_composite_builtin(const char *name, ori_composite **out, ori_error *error)
{
    ORI_ASSERT(name && out);
    *out = NULL;
    ori_error_clear(error);
    const builtin *b = find_builtin(name);
    if (!b) {
        char list[256];
        names_list(list, sizeof list);
        return ori__fail(error, ORI_ERR_NOT_FOUND, "no built-in pattern '%s' (built-ins: %s)", name, list);
    }
    ori_composite *c = ori__calloc(1, sizeof *c);
    ori__strlcpy(c->name, name, sizeof c->name);
    push_builtin(c, b, false, ORI_ASSIGN_UNASSIGNED);
    *out = c;
    return ORI_OK;
}

void ori_composite_destroy(ori_composite *c)
{
    if (!c) return;
    ori__free(c->creases);
    ori__free(c);
}

const char *ori_composite_name(const ori_composite *c)
{
    ORI_ASSERT(c);
    return c->name;
}

int ori_composite_crease_count(const ori_composite *c)
{
    ORI_ASSERT(c);
    return c->count;
}

ori_composite_crease ori_composite_crease_at(const ori_composite *c, int i)
{
    ORI_ASSERT(c && i >= 0 && i < c->count);
    return c->creases[i];
}

// --- JSON positions ---------------------------------------------------------------------------
// jansson parses and validates syntax; this small scanner finds where a value sits in the
// (syntactically valid) text, so content errors can name a line and column.

typedef struct jstep {
    const char *key; // member name, or NULL for an array index
    int index;
} jstep;

static const char *skip_ws(const char *s, const char *end)
{
    while (s < end && (*s == ' ' || *s == '\t' || *s == '\n' || *s == '\r')) ++s;
    return s;
}

static const char *skip_string(const char *s, const char *end)
{
    ++s; // opening quote
    while (s < end && *s != '"') s += (*s == '\\' && s + 1 < end) ? 2 : 1;
    return s < end ? s + 1 : end;
}

static const char *skip_value(const char *s, const char *end)
{
    s = skip_ws(s, end);
    if (s >= end) return end;
    if (*s == '"') return skip_string(s, end);
    if (*s == '{' || *s == '[') {
        int depth = 0;
        while (s < end) {
            if (*s == '"') {
                s = skip_string(s, end);
                continue;
            }
            if (*s == '{' || *s == '[') depth++;
            if (*s == '}' || *s == ']') {
                depth--;
                if (depth == 0) return s + 1;
            }
            ++s;
        }
        return end;
    }
    while (s < end && *s != ',' && *s != '}' && *s != ']' && *s != ' ' && *s != '\n' && *s != '\t' && *s != '\r') ++s;
    return s;
}

// Start of the value at path (as deep as the path can be followed).
static const char *locate(const char *s, const char *end, const jstep *path, int depth)
{
    s = skip_ws(s, end);
    for (int d = 0; d < depth && s < end; ++d) {
        const jstep *st = &path[d];
        if (st->key && *s == '{') {
            const char *p = skip_ws(s + 1, end);
            const char *found = NULL;
            while (p < end && *p == '"') {
                const char *k0 = p + 1, *k1 = skip_string(p, end) - 1;
                p = skip_ws(k1 + 1, end);
                if (p < end && *p == ':') p = skip_ws(p + 1, end);
                if ((size_t)(k1 - k0) == strlen(st->key) && memcmp(k0, st->key, (size_t)(k1 - k0)) == 0) {
                    found = p;
                    break;
                }
                p = skip_ws(skip_value(p, end), end);
                if (p < end && *p == ',') p = skip_ws(p + 1, end);
            }
            if (!found) return s;
            s = found;
        } else if (!st->key && *s == '[') {
            const char *p = skip_ws(s + 1, end);
            for (int i = 0; i < st->index && p < end && *p != ']'; ++i) {
                p = skip_ws(skip_value(p, end), end);
                if (p < end && *p == ',') p = skip_ws(p + 1, end);
            }
            if (p >= end || *p == ']') return s;
            s = p;
        } else {
            return s;
        }
    }
    return s;
}

typedef struct parse_ctx {
    const char *text;
    size_t size;
    ori_error *error;
} parse_ctx;

static ori_status fail_at_path(const parse_ctx *cx, const jstep *path, int depth, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

static ori_status fail_at_path(const parse_ctx *cx, const jstep *path, int depth, const char *fmt, ...)
{
    const char *pos = locate(cx->text, cx->text + cx->size, path, depth);
    int line = 1, col = 1;
    for (const char *s = cx->text; s < pos; ++s) {
        if (*s == '\n') {
            line++;
            col = 1;
        } else {
            col++;
        }
    }
    char where[128] = "";
    size_t k = 0;
    for (int d = 0; d < depth && k + 1 < sizeof where; ++d) {
        int w = path[d].key ? snprintf(where + k, sizeof where - k, "%s%s", d ? "." : "", path[d].key)
                            : snprintf(where + k, sizeof where - k, "[%d]", path[d].index);
        if (w < 0) break;
        k += (size_t)w;
    }
    char msg[200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return ori__fail_pos(cx->error, ORI_ERR_TYPE, line, col, "%s%s%s", where, depth ? ": " : "", msg);
}

static ori_status parse_crease(const parse_ctx *cx, json_t *obj, int index, ori_composite *c)
{
    jstep path[3] = {{"creases", 0}, {NULL, index}, {NULL, 0}};
    if (!json_is_object(obj)) return fail_at_path(cx, path, 2, "expected an object with \"line\", \"segment\" or \"pattern\"");
    const char *key;
    json_t *v;
    const char *geometry = NULL;
    json_object_foreach(obj, key, v)
    {
        path[2].key = key;
        if (strcmp(key, "line") == 0 || strcmp(key, "segment") == 0 || strcmp(key, "pattern") == 0) {
            if (geometry)
                return fail_at_path(cx, path, 3, "a crease has one of \"line\", \"segment\", \"pattern\" (also has \"%s\")",
                                    geometry);
            geometry = key;
        } else if (strcmp(key, "assignment") != 0) {
            return fail_at_path(cx, path, 3, "unknown key (expected \"line\", \"segment\", \"pattern\" or \"assignment\")");
        }
    }
    path[2].key = NULL;
    if (!geometry) return fail_at_path(cx, path, 2, "a crease needs \"line\", \"segment\" or \"pattern\"");
    bool has = false;
    ori_assignment a = ORI_ASSIGN_UNASSIGNED;
    json_t *av = json_object_get(obj, "assignment");
    if (av) {
        path[2].key = "assignment";
        const char *s = json_string_value(av);
        if (!s || strlen(s) != 1 || !ori_assignment_from_char(s[0], &a) ||
            !(ori_assignment_is_fold(a) || a == ORI_ASSIGN_FLAT))
            return fail_at_path(cx, path, 3, "expected \"M\", \"V\", \"F\" or \"U\"");
        has = true;
    }
    path[2].key = geometry;
    json_t *g = json_object_get(obj, geometry);
    if (strcmp(geometry, "pattern") == 0) {
        const builtin *b = json_is_string(g) ? find_builtin(json_string_value(g)) : NULL;
        if (!b) {
            char list[256];
            names_list(list, sizeof list);
            return fail_at_path(cx, path, 3, "expected the name of a built-in pattern (%s)", list);
        }
        push_builtin(c, b, has, a);
        return ORI_OK;
    }
    if (!json_is_array(g) || json_array_size(g) != 4)
        return fail_at_path(cx, path, 3, "expected [x1, y1, x2, y2] in the face's normalised coordinates");
    double x[4];
    for (int k = 0; k < 4; ++k) {
        json_t *num = json_array_get(g, (size_t)k);
        if (!json_is_number(num) || !isfinite(json_number_value(num))) {
            jstep p4[4] = {path[0], path[1], path[2], {NULL, k}};
            return fail_at_path(cx, p4, 4, "expected a number");
        }
        x[k] = json_number_value(num);
    }
    ori_composite_crease cr;
    cr.a = ori_v2_make(x[0], x[1]);
    cr.b = ori_v2_make(x[2], x[3]);
    double scale = fmax(fmax(fabs(x[0]), fabs(x[1])), fmax(fmax(fabs(x[2]), fabs(x[3])), 1.0));
    if (!(ori_v2_norm(ori_v2_sub(cr.b, cr.a)) > ORI_TOL_LENGTH_REL * scale))
        return fail_at_path(cx, path, 3, "the two points coincide");
    cr.infinite = strcmp(geometry, "line") == 0;
    cr.has_assignment = has;
    cr.assignment = a;
    if (c->count >= COMPOSITE_MAX_CREASES) return fail_at_path(cx, path, 2, "too many creases");
    ORI__PUSH(c->creases, c->count, c->cap, cr);
    return ORI_OK;
}

ori_status ori_composite_load_string(const char *text, size_t size, ori_composite **out, ori_error *error)
{
    ORI_ASSERT(text && out);
    *out = NULL;
    ori_error_clear(error);
    json_t *root = ori__json_parse(text, size, JSON_REJECT_DUPLICATES, error);
    if (!root) return ORI_ERR_PARSE;
    parse_ctx cx = {text, size, error};
    ori_composite *c = ori__calloc(1, sizeof *c);
    ori_status st = ORI_OK;
    jstep path[1] = {{NULL, 0}};
    if (!json_is_object(root)) {
        st = fail_at_path(&cx, path, 0, "a composite is a JSON object with \"creases\"");
    } else {
        const char *key;
        json_t *v;
        json_object_foreach(root, key, v)
        {
            path[0].key = key;
            if (strcmp(key, "orikin_composite") == 0) {
                if (!json_is_integer(v) || json_integer_value(v) != 1) {
                    st = fail_at_path(&cx, path, 1, "unsupported version (this orikin reads 1)");
                    break;
                }
            } else if (strcmp(key, "name") == 0) {
                if (!json_is_string(v) || strlen(json_string_value(v)) >= ORI_NAME_MAX) {
                    st = fail_at_path(&cx, path, 1, "expected a string of at most %d characters", ORI_NAME_MAX - 1);
                    break;
                }
                ori__strlcpy(c->name, json_string_value(v), sizeof c->name);
            } else if (strcmp(key, "description") == 0) {
                if (!json_is_string(v)) {
                    st = fail_at_path(&cx, path, 1, "expected a string");
                    break;
                }
            } else if (strcmp(key, "creases") != 0) {
                st = fail_at_path(&cx, path, 1,
                                  "unknown key (expected \"orikin_composite\", \"name\", \"description\", \"creases\")");
                break;
            }
        }
        json_t *creases = json_object_get(root, "creases");
        path[0].key = "creases";
        if (st == ORI_OK && (!json_is_array(creases) || json_array_size(creases) == 0))
            st = fail_at_path(&cx, path, creases ? 1 : 0, "expected a non-empty array of creases");
        size_t i;
        json_t *cr;
        if (st == ORI_OK) json_array_foreach(creases, i, cr)
            {
                st = parse_crease(&cx, cr, (int)i, c);
                if (st != ORI_OK) break;
            }
    }
    json_decref(root);
    if (st != ORI_OK) {
        ori_composite_destroy(c);
        return st;
    }
    *out = c;
    return ORI_OK;
}

ori_status ori_composite_load_file(const char *path, ori_composite **out, ori_error *error)
{
    ORI_ASSERT(path && out);
    *out = NULL;
    char *data;
    size_t size;
    ori_status st = ori_file_read_all(path, COMPOSITE_MAX_BYTES, &data, &size, error);
    if (st != ORI_OK) return st;
    st = ori_composite_load_string(data, size, out, error);
    ori__free(data);
    return st;
}

// --- applying -------------------------------------------------------------------------------

ori_status ori_pattern_apply_composite(ori_pattern *p, const ori_composite *c, int face, const ori_assignment *asg,
                                       ori_apply_result *out, ori_error *error)
{
    ORI_ASSERT(p && c);
    ori_error_clear(error);
    if (face < 0 || face >= ori_pattern_face_count(p))
        return ori__fail_at(error, ORI_ERR_RANGE, "faces_vertices", face, "no such face (the pattern has %d)",
                            ori_pattern_face_count(p));
    int n = ori_pattern_face_size(p, face);
    int *fv = ori__alloc(sizeof(int) * (size_t)n);
    ori_pattern_face_vertices(p, face, fv, n);
    ori_v3 lo = ori_pattern_vertex(p, fv[0]), hi = lo;
    for (int i = 1; i < n; ++i) {
        ori_v3 x = ori_pattern_vertex(p, fv[i]);
        lo.x = fmin(lo.x, x.x), lo.y = fmin(lo.y, x.y);
        hi.x = fmax(hi.x, x.x), hi.y = fmax(hi.y, x.y);
    }
    ori__free(fv);
    double w = hi.x - lo.x, h = hi.y - lo.y;
    ori_crease *cs = ori__alloc(sizeof *cs * (size_t)(c->count ? c->count : 1));
    for (int k = 0; k < c->count; ++k) {
        const ori_composite_crease *cc = &c->creases[k];
        cs[k].a = ori_v2_make(lo.x + cc->a.x * w, lo.y + cc->a.y * h);
        cs[k].b = ori_v2_make(lo.x + cc->b.x * w, lo.y + cc->b.y * h);
        cs[k].infinite = cc->infinite;
        cs[k].assignment = asg ? *asg : (cc->has_assignment ? cc->assignment : ORI_ASSIGN_UNASSIGNED);
        cs[k].fold_angle_rad = 0.0;
    }
    ori_status st = ori_pattern_apply_creases(p, cs, c->count, face, out, error);
    ori__free(cs);
    return st;
}
