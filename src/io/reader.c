// The pieces every drawing reader shares (svg.c, oripa.c, and any later reader), below them
// and below import.c, which only dispatches: the growing segment list, number scanning that
// never accepts "inf", "nan" or hexadecimal, the begin/end of a reader, and libxml2 set up
// without network access or entity substitution, keeping the first error.
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <libxml/xmlreader.h>
#include <stdlib.h>

#include "io_internal.h"
#include "reader_internal.h"

// --- segments and numbers ---------------------------------------------------------------------

void ori__seg_push(ori__seg_list *list, double ax, double ay, double bx, double by, ori_assignment asg,
                   double fold_angle_rad)
{
    if (ax == bx && ay == by) return;
    ori_segment s;
    s.a = ori_v2_make(ax, ay == 0.0 ? 0.0 : -ay);
    s.b = ori_v2_make(bx, by == 0.0 ? 0.0 : -by);
    s.assignment = asg;
    s.fold_angle_rad = fold_angle_rad;
    ORI__PUSH(list->items, list->count, list->cap, s);
}

size_t ori__scan_number(const char *s, double *out)
{
    const char *p = s;
    if (*p == '+' || *p == '-') ++p;
    const char *digits = p;
    while (*p >= '0' && *p <= '9') ++p;
    bool int_part = p > digits;
    bool frac_part = false;
    if (*p == '.') {
        const char *f = ++p;
        while (*p >= '0' && *p <= '9') ++p;
        frac_part = p > f;
    }
    if (!int_part && !frac_part) return 0;
    if (*p == 'e' || *p == 'E') {
        const char *e = p + 1;
        if (*e == '+' || *e == '-') ++e;
        if (*e >= '0' && *e <= '9') {
            while (*e >= '0' && *e <= '9') ++e;
            p = e;
        }
    }
    size_t n = (size_t)(p - s);
    char buf[128];
    if (n >= sizeof buf) return 0;
    memcpy(buf, s, n);
    buf[n] = '\0';
    double v = strtod(buf, NULL);
    if (!isfinite(v)) return 0;
    *out = v;
    return n;
}

void ori__reader_begin(ori_segment **segments, int *count, ori_import_stats *stats, ori_error *error)
{
    *segments = NULL;
    *count = 0;
    if (stats) {
        memset(stats, 0, sizeof *stats);
        stats->dangling_example = stats->part_example = ORI_NULL_INDEX;
    }
    ori_error_clear(error);
}

ori_status ori__reader_end(ori_status st, ori__seg_list *segs, ori_import_stats *found, ori_segment **segments,
                           int *count, ori_import_stats *stats)
{
    if (st != ORI_OK) {
        ori__free(segs->items);
        return st;
    }
    found->segments = segs->count;
    found->dangling_example = found->part_example = ORI_NULL_INDEX; // (set by ori_import_file)
    if (stats) *stats = *found;
    *segments = segs->items;
    *count = segs->count;
    return ORI_OK;
}

// --- XML --------------------------------------------------------------------------------------

static void keep_first_error(ori__xml_first_error *first, const xmlError *xe)
{
    if (!first || first->set || !xe || xe->level < XML_ERR_ERROR) return;
    first->set = true;
    first->line = xe->line;
    first->column = xe->int2;
    const char *m = xe->message ? xe->message : "not well-formed XML";
    while (*m == ' ' || *m == '\t' || *m == '\n' || *m == '\r' || *m == '\f') ++m;
    size_t n = strlen(m);
    while (n > 0 && (m[n - 1] == ' ' || m[n - 1] == '\t' || m[n - 1] == '\n' || m[n - 1] == '\r' || m[n - 1] == '\f'))
        --n;
    // one line: libxml2's multi-line messages ("… UTF-8, indicate encoding !\nBytes: 0xFF …")
    // joined with "; "
    size_t w = 0;
    for (size_t i = 0; i < n && w + 3 < sizeof first->message; ++i) {
        if (m[i] == '\n' || m[i] == '\r') {
            while (i + 1 < n && (m[i + 1] == '\n' || m[i + 1] == '\r' || m[i + 1] == ' ' || m[i + 1] == '\t')) ++i;
            first->message[w++] = ';';
            first->message[w++] = ' ';
        } else {
            first->message[w++] = m[i];
        }
    }
    first->message[w] = '\0';
}

void ori__xml_reader_error(void *user, xmlErrorPtr xe) { keep_first_error(user, xe); }

static void ctxt_error(void *user, xmlErrorPtr xe)
{
    xmlParserCtxt *ctxt = user;
    keep_first_error(ctxt ? ctxt->_private : NULL, xe);
}

ori_status ori__xml_error(const ori__xml_first_error *first, ori_error *error)
{
    return ori__fail_pos(error, ORI_ERR_PARSE, first->line > 0 ? first->line : 1, first->column > 0 ? first->column : 0,
                         "XML: %s", first->set ? first->message : "not well-formed XML");
}

// The tree parser for small documents (ORIPA files).
ori_status ori__xml_parse(const char *text, size_t size, const char *what, xmlDoc **doc, ori_error *error)
{
    *doc = NULL;
    if (size > (size_t)INT32_MAX) return ori__fail(error, ORI_ERR_LIMIT, "the %s file is too large", what);
    xmlParserCtxt *ctxt = xmlNewParserCtxt();
    if (!ctxt) return ori__fail(error, ORI_ERR_NOMEM, "cannot create the XML parser");
    ori__xml_first_error first;
    memset(&first, 0, sizeof first);
    ctxt->_private = &first;
    ctxt->sax->serror = ctxt_error;
    xmlDoc *d = xmlCtxtReadMemory(ctxt, text, (int)size, NULL, NULL, ORI__XML_OPTIONS);
    ori_status st = ORI_OK;
    if (!d || !ctxt->wellFormed) {
        keep_first_error(&first, xmlCtxtGetLastError(ctxt)); // when no callback came
        st = ori__xml_error(&first, error);
        if (d) xmlFreeDoc(d);
        d = NULL;
    }
    xmlFreeParserCtxt(ctxt);
    *doc = d;
    return st;
}

// --- attributes and text, entity references expanded within a budget --------------------------

void ori__xml_budget_init(ori__xml_budget *b, size_t input_size)
{
    b->left = ORI__XML_EXPANSION_PER_BYTE * input_size + ORI__XML_EXPANSION_MIN;
    b->exceeded = false;
}

static void expand_content(const xmlDoc *doc, const char *s, int depth, ori__xml_budget *b, ori__text *out);

// An internal general entity's replacement text, recursively (character references decoded,
// external and unknown entities left out).
static void expand_entity(const xmlDoc *doc, const xmlChar *name, int depth, ori__xml_budget *b, ori__text *out)
{
    if (b->exceeded) return;
    if (depth >= ORI__XML_ENTITY_DEPTH) {
        b->exceeded = true;
        return;
    }
    xmlEntity *ent = xmlGetDocEntity(doc, name);
    if (!ent) return;
    if (ent->etype == XML_INTERNAL_PREDEFINED_ENTITY) {
        size_t n = ent->content ? strlen((const char *)ent->content) : 0;
        if (n > b->left) {
            b->exceeded = true;
            return;
        }
        b->left -= n;
        ori__text_put(out, (const char *)ent->content, n);
        return;
    }
    if (ent->etype != XML_INTERNAL_GENERAL_ENTITY || !ent->content) return;
    expand_content(doc, (const char *)ent->content, depth + 1, b, out);
}

static void expand_content(const xmlDoc *doc, const char *s, int depth, ori__xml_budget *b, ori__text *out)
{
    while (*s && !b->exceeded) {
        const char *amp = strchr(s, '&');
        size_t n = amp ? (size_t)(amp - s) : strlen(s);
        if (n > b->left) {
            b->exceeded = true;
            return;
        }
        b->left -= n;
        ori__text_put(out, s, n);
        if (!amp) return;
        const char *semi = strchr(amp, ';');
        if (!semi) { // not a reference: the rest as it is
            s = amp + 1;
            ori__text_put(out, "&", 1);
            continue;
        }
        if (amp[1] == '#') { // a character reference
            unsigned long cp = amp[2] == 'x' ? strtoul(amp + 3, NULL, 16) : strtoul(amp + 2, NULL, 10);
            char u[5] = {0};
            if (cp < 0x80) u[0] = (char)cp;
            else if (cp < 0x800) u[0] = (char)(0xC0 | cp >> 6), u[1] = (char)(0x80 | (cp & 0x3F));
            else if (cp < 0x10000) u[0] = (char)(0xE0 | cp >> 12), u[1] = (char)(0x80 | ((cp >> 6) & 0x3F)), u[2] = (char)(0x80 | (cp & 0x3F));
            else if (cp < 0x110000)
                u[0] = (char)(0xF0 | cp >> 18), u[1] = (char)(0x80 | ((cp >> 12) & 0x3F)), u[2] = (char)(0x80 | ((cp >> 6) & 0x3F)),
                u[3] = (char)(0x80 | (cp & 0x3F));
            if (u[0]) ori__text_puts(out, u);
        } else {
            char name[128];
            size_t len = (size_t)(semi - amp - 1);
            if (len < sizeof name) {
                memcpy(name, amp + 1, len);
                name[len] = '\0';
                expand_entity(doc, (const xmlChar *)name, depth, b, out);
            }
        }
        s = semi + 1;
    }
}

// The text of a node list (text, CDATA, entity references) appended to out.
static void node_list_text(const xmlNode *list, ori__xml_budget *b, ori__text *out)
{
    for (const xmlNode *c = list; c && !b->exceeded; c = c->next) {
        if ((c->type == XML_TEXT_NODE || c->type == XML_CDATA_SECTION_NODE) && c->content)
            ori__text_puts(out, (const char *)c->content);
        else if (c->type == XML_ENTITY_REF_NODE)
            expand_entity(c->doc, c->name, 0, b, out);
    }
}

char *ori__xml_attr(const xmlNode *n, const char *name, ori__xml_budget *b)
{
    for (const xmlAttr *a = n->properties; a; a = a->next) {
        if (a->ns != NULL || strcmp((const char *)a->name, name) != 0) continue;
        ori__text out = {NULL, 0, 0};
        ori__text_reserve(&out, 0);
        node_list_text(a->children, b, &out);
        if (b->exceeded) {
            ori__free(out.data);
            return NULL;
        }
        return out.data;
    }
    return NULL;
}

char *ori__xml_text(const xmlNode *n, ori__xml_budget *b)
{
    ori__text out = {NULL, 0, 0};
    ori__text_reserve(&out, 0);
    node_list_text(n->children, b, &out);
    if (b->exceeded) {
        ori__free(out.data);
        return NULL;
    }
    return out.data;
}
