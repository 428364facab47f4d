// ORIPA crease patterns: .opx (XML written by java.beans.XMLEncoder: every
// <object class="oripa.OriLineProxy"> holds <void property="type|x0|y0|x1|y1"> with an <int> or
// <double>; absent properties keep the bean default 0) and .cp (one "type x1 y1 x2 y2" per line).
// Types: 0 aux, 1 cut/boundary → B, 2 → M, 3 → V; 4 and 9 (cut-model line, by ORIPA version;
// auxiliary in several .cp writers) are skipped. ORIPA draws y downwards: y is flipped.
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <stdio.h>

#include "../pattern/pattern_internal.h"
#include "reader_internal.h"
#include "io_internal.h"

// Type code → assignment; false for codes that are skipped (*skip) or invalid.
static bool oripa_type(double type, ori_assignment *asg, bool *skip)
{
    *skip = type == 0.0 || type == 4.0 || type == 9.0;
    if (type == 1.0) *asg = ORI_ASSIGN_BOUNDARY;
    else if (type == 2.0) *asg = ORI_ASSIGN_MOUNTAIN;
    else if (type == 3.0) *asg = ORI_ASSIGN_VALLEY;
    else return false;
    return true;
}

// Java's Double.toString of a value that is no number: "NaN", "Infinity", "-Infinity" (XMLEncoder).
static bool java_nonfinite(const char *s)
{
    size_t n = strlen(s);
    while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\n' || s[n - 1] == '\r')) --n;
    if (*s == '-' || *s == '+') ++s, --n;
    return (n == 3 && strncmp(s, "NaN", 3) == 0) || (n == 8 && strncmp(s, "Infinity", 8) == 0);
}

// "nan", "inf", "infinity" with an optional sign, any case (C's and Java's spellings), ending at
// a separator: its length, else 0.
static size_t nonfinite_word(const char *q)
{
    const char *p = q + (*q == '-' || *q == '+');
    static const char *const words[] = {"infinity", "nan", "inf"};
    for (size_t w = 0; w < 3; ++w) {
        size_t n = strlen(words[w]), i = 0;
        while (i < n && p[i] && (p[i] | 0x20) == words[w][i]) ++i;
        if (i == n && (!p[n] || p[n] == ' ' || p[n] == '\t' || p[n] == '\r')) return (size_t)(p - q) + n;
    }
    return 0;
}

static double flat_angle(ori_assignment a)
{
    return a == ORI_ASSIGN_MOUNTAIN ? -ORI_PI : a == ORI_ASSIGN_VALLEY ? ORI_PI : 0.0;
}

// --- .opx ------------------------------------------------------------------------------------

typedef struct opx_ctx {
    ori__seg_list segs;
    ori_import_stats stats;
    ori__xml_budget budget;
    ori_error *error;
} opx_ctx;

static bool attr_is(opx_ctx *c, const xmlNode *n, const char *name, const char *value)
{
    char *v = ori__xml_attr(n, name, &c->budget);
    bool eq = v && strcmp(v, value) == 0;
    ori__free(v);
    return eq;
}

static const xmlNode *first_element(const xmlNode *n)
{
    for (const xmlNode *c = n ? n->children : NULL; c; c = c->next)
        if (c->type == XML_ELEMENT_NODE) return c;
    return NULL;
}

// The limit on entity expansion (reader_internal.h), reached.
static ori_status over_budget(opx_ctx *c, const xmlNode *n)
{
    return ori__fail_pos(c->error, ORI_ERR_LIMIT, (int)xmlGetLineNo(n), 0,
                         "entity references expand to more than %d times the file's size", ORI__XML_EXPANSION_PER_BYTE);
}

static ori_status opx_line(opx_ctx *c, const xmlNode *obj)
{
    static const char *const names[5] = {"type", "x0", "y0", "x1", "y1"};
    double v[5] = {0, 0, 0, 0, 0};
    int nonfinite = -1; // the first coordinate that is NaN or ±Infinity (Java's spellings), -1: none
    const xmlNode *nonfinite_at = NULL;
    for (const xmlNode *p = obj->children; p; p = p->next) {
        if (p->type != XML_ELEMENT_NODE || strcmp((const char *)p->name, "void") != 0) continue;
        char *prop = ori__xml_attr(p, "property", &c->budget);
        int k = -1;
        for (int i = 0; prop && i < 5; ++i)
            if (strcmp(prop, names[i]) == 0) k = i;
        ori__free(prop);
        if (c->budget.exceeded) return over_budget(c, p);
        if (k < 0) continue; // other bean properties (selected, …)
        const xmlNode *val = first_element(p);
        char *text = val ? ori__xml_text(val, &c->budget) : NULL;
        if (c->budget.exceeded) return over_budget(c, val);
        const char *s = text ? text : "";
        while (*s == ' ' || *s == '\t' || *s == '\n' || *s == '\r') ++s;
        size_t n = ori__scan_number(s, &v[k]);
        const char *rest = s + n;
        while (*rest == ' ' || *rest == '\t' || *rest == '\n' || *rest == '\r') ++rest;
        bool ok = n > 0 && *rest == '\0';
        if (!ok && k > 0 && java_nonfinite(s)) {
            ok = true;
            if (nonfinite < 0) nonfinite = k, nonfinite_at = val;
        }
        ori__free(text);
        if (!ok)
            return ori__fail_pos(c->error, ORI_ERR_PARSE, (int)xmlGetLineNo(val ? val : p), 0,
                                 "line property %s: expected %s", names[k], k == 0 ? "an integer type" : "a number");
    }
    ori_assignment asg;
    bool skip;
    bool line = oripa_type(v[0], &asg, &skip);
    if (nonfinite >= 0 && skip) { // a degenerate auxiliary line: no crease, nothing lost
        c->stats.ignored_elements++;
        c->stats.degenerate_aux++;
        return ORI_OK;
    }
    if (nonfinite >= 0 && line)
        return ori__fail_pos(c->error, ORI_ERR_PARSE, (int)xmlGetLineNo(nonfinite_at), 0,
                             "line property %s is not a finite number (a crease needs its coordinates)", names[nonfinite]);
    if (!line) {
        if (skip) {
            c->stats.ignored_elements++;
            return ORI_OK;
        }
        return ori__fail_pos(c->error, ORI_ERR_PARSE, (int)xmlGetLineNo(obj), 0,
                             "line type %g is not 0 (aux), 1 (cut), 2 (mountain), 3 (valley), 4 or 9", v[0]);
    }
    ori__seg_push(&c->segs, v[1], v[2], v[3], v[4], asg, flat_angle(asg));
    return ORI_OK;
}

static ori_status opx_walk(opx_ctx *c, const xmlNode *parent, int depth)
{
    if (depth > 256) return ori__fail(c->error, ORI_ERR_LIMIT, "elements nested deeper than 256 levels");
    for (const xmlNode *n = parent->children; n; n = n->next) {
        if (n->type != XML_ELEMENT_NODE) continue;
        bool line = strcmp((const char *)n->name, "object") == 0 && attr_is(c, n, "class", "oripa.OriLineProxy");
        if (c->budget.exceeded) return over_budget(c, n);
        ori_status st = line ? opx_line(c, n) : opx_walk(c, n, depth + 1);
        if (st != ORI_OK) return st;
    }
    return ORI_OK;
}

ori_status ori_opx_read_segments(const char *text, size_t size, ori_segment **segments, int *count,
                                 ori_import_stats *stats, ori_error *error)
{
    ORI_ASSERT(text && segments && count);
    ori__reader_begin(segments, count, stats, error);
    xmlDoc *doc;
    ori_status st = ori__xml_parse(text, size, "OPX", &doc, error);
    if (st != ORI_OK) return st;
    const xmlNode *root = xmlDocGetRootElement(doc);
    opx_ctx c;
    memset(&c, 0, sizeof c);
    c.error = error;
    ori__xml_budget_init(&c.budget, size);
    if (!root || strcmp((const char *)root->name, "java") != 0)
        st = ori__fail_pos(error, ORI_ERR_PARSE, root ? (int)xmlGetLineNo(root) : 1, 0,
                           "not an ORIPA file: the root element is <%s>, not <java>", root ? (const char *)root->name : "");
    else
        st = opx_walk(&c, root, 0);
    xmlFreeDoc(doc);
    return ori__reader_end(st, &c.segs, &c.stats, segments, count, stats);
}

// --- .cp -------------------------------------------------------------------------------------

ori_status ori_cp_read_segments(const char *text, size_t size, ori_segment **segments, int *count,
                                ori_import_stats *stats, ori_error *error)
{
    ORI_ASSERT(text && segments && count);
    ori__reader_begin(segments, count, stats, error);
    ori__seg_list segs = {NULL, 0, 0};
    ori_import_stats s;
    memset(&s, 0, sizeof s);
    const char *p = text, *end = text + size;
    if (size >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0) p += 3; // a UTF-8 byte-order mark
    int line = 0;
    ori_status st = ORI_OK;
    while (p < end && st == ORI_OK) {
        line++;
        const char *eol = memchr(p, '\n', (size_t)(end - p));
        if (!eol) eol = end;
        char buf[512];
        size_t n = (size_t)(eol - p);
        if (n >= sizeof buf) {
            st = ori__fail_pos(error, ORI_ERR_PARSE, line, 0, "line longer than %zu characters", sizeof buf - 1);
            break;
        }
        memcpy(buf, p, n);
        buf[n] = '\0';
        p = eol < end ? eol + 1 : end;
        if (memchr(buf, '\0', n)) {
            st = ori__fail_pos(error, ORI_ERR_PARSE, line, 0, "NUL byte (not a text file)");
            break;
        }
        double v[5];
        int k = 0;
        const char *q = buf;
        bool ok = true, nonfinite = false;
        for (;;) {
            while (*q == ' ' || *q == '\t' || *q == '\r') ++q;
            if (!*q) break;
            if (k == 5) {
                ok = false;
                break;
            }
            size_t m = ori__scan_number(q, &v[k]);
            if (!m && k > 0 && (m = nonfinite_word(q)) > 0) nonfinite = true, v[k] = 0.0;
            if (!m || (q[m] && q[m] != ' ' && q[m] != '\t' && q[m] != '\r')) {
                ok = false;
                break;
            }
            q += m;
            k++;
        }
        if (ok && k == 0) continue; // blank line
        if (!ok || k != 5) {
            st = ori__fail_pos(error, ORI_ERR_PARSE, line, 0, "expected \"type x1 y1 x2 y2\" (an integer and four numbers)");
            break;
        }
        ori_assignment asg;
        bool skip;
        bool crease = oripa_type(v[0], &asg, &skip);
        if (nonfinite && skip) { // a degenerate auxiliary line: skipped like the others, and counted
            s.ignored_elements++;
            s.degenerate_aux++;
            continue;
        }
        if (nonfinite) {
            st = ori__fail_pos(error, ORI_ERR_PARSE, line, 0,
                               "expected \"type x1 y1 x2 y2\" (an integer and four numbers): a crease needs finite coordinates");
            break;
        }
        if (!crease) {
            if (skip) s.ignored_elements++;
            else st = ori__fail_pos(error, ORI_ERR_PARSE, line, 0,
                                    "line type %g is not 0 (aux), 1 (cut), 2 (mountain), 3 (valley) or 4 (aux)", v[0]);
            continue;
        }
        ori__seg_push(&segs, v[1], v[2], v[3], v[4], asg, flat_angle(asg));
    }
    return ori__reader_end(st, &segs, &s, segments, count, stats);
}

// --- writers ---------------------------------------------------------------------------------

// ORIPA type of an assignment; -1 for edges that are left out (J).
static int oripa_code(ori_assignment a, bool opx)
{
    switch (a) {
    case ORI_ASSIGN_BOUNDARY:
    case ORI_ASSIGN_CUT: return 1;
    case ORI_ASSIGN_MOUNTAIN: return 2;
    case ORI_ASSIGN_VALLEY: return 3;
    case ORI_ASSIGN_FLAT:
    case ORI_ASSIGN_UNASSIGNED: return opx ? 0 : 4;
    default: return -1;
    }
}

char *ori_cp_write(const ori_pattern *p)
{
    ORI_ASSERT(p);
    ori__text t = {NULL, 0, 0};
    ori__text_reserve(&t, 0);
    for (int e = 0; e < p->edge_count; ++e) {
        int code = oripa_code(p->edges[e].assignment, false);
        if (code < 0) continue;
        ori_v3 u = p->vertices[p->edges[e].v[0]], w = p->vertices[p->edges[e].v[1]];
        double v[4] = {u.x, -u.y, w.x, -w.y}; // back to ORIPA's y-down frame
        ori__text_printf(&t, "%d", code);
        for (int k = 0; k < 4; ++k) {
            ori__text_puts(&t, " ");
            ori__text_real(&t, v[k]);
        }
        ori__text_puts(&t, "\n");
    }
    return t.data;
}

char *ori_opx_write(const ori_pattern *p)
{
    ORI_ASSERT(p);
    ori__text t = {NULL, 0, 0};
    int n = 0;
    for (int e = 0; e < p->edge_count; ++e) n += oripa_code(p->edges[e].assignment, true) >= 0;
    ori__text_printf(&t,
                     "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                     "<java version=\"1.5.0_02\" class=\"java.beans.XMLDecoder\">\n"
                     " <object class=\"oripa.DataSet\">\n"
                     "  <void property=\"lines\">\n"
                     "   <array class=\"oripa.OriLineProxy\" length=\"%d\">\n",
                     n);
    static const char *const names[4] = {"x0", "x1", "y0", "y1"};
    int k = 0;
    for (int e = 0; e < p->edge_count; ++e) {
        int code = oripa_code(p->edges[e].assignment, true);
        if (code < 0) continue;
        ori_v3 u = p->vertices[p->edges[e].v[0]], w = p->vertices[p->edges[e].v[1]];
        double v[4] = {u.x, w.x, -u.y, -w.y};
        ori__text_printf(&t,
                         "    <void index=\"%d\">\n"
                         "     <object class=\"oripa.OriLineProxy\">\n"
                         "      <void property=\"type\">\n       <int>%d</int>\n      </void>\n",
                         k++, code);
        for (int i = 0; i < 4; ++i) {
            ori__text_printf(&t, "      <void property=\"%s\">\n       <double>", names[i]);
            ori__text_real(&t, v[i]);
            ori__text_puts(&t, "</double>\n      </void>\n");
        }
        ori__text_puts(&t, "     </object>\n    </void>\n");
    }
    ori__text_puts(&t, "   </array>\n"
                       "  </void>\n"
                       "  <void property=\"mainVersion\">\n   <int>1</int>\n  </void>\n"
                       "  <void property=\"subVersion\">\n   <int>1</int>\n  </void>\n"
                       " </object>\n"
                       "</java>\n");
    return t.data;
}
