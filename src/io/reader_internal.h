// Shared pieces of the drawing readers (reader.c), used by svg.c and oripa.c and by import.c,
// which dispatches to them: calls run one way, readers → reader.c, never back into import.c.
// The growing segment list and statistics, number scanning that never accepts "inf", "nan" or
// hexadecimal, and the XML entry points. (The writers' text buffer is in io_internal.h.)
#ifndef ORI_READER_INTERNAL_H
#define ORI_READER_INTERNAL_H

#include <orikin/formats.h>

#include "../core/core_internal.h"

typedef struct ori__seg_list {
    ori_segment *items;
    int count, cap;
} ori__seg_list;

// Append segment a→b given in drawing coordinates (y down): stored with y flipped (y up).
// Exactly coincident end points (nothing drawn) are dropped.
void ori__seg_push(ori__seg_list *list, double ax, double ay, double bx, double by, ori_assignment asg,
                   double fold_angle_rad);

// Scan a decimal number (sign, digits, fraction, exponent; no inf/nan/hex) at s. Returns the
// number of characters consumed (0 when there is no number) and the value in *out.
size_t ori__scan_number(const char *s, double *out);

// The start of a reader ori_X_read_segments: its outputs cleared (stats may be NULL).
void ori__reader_begin(ori_segment **segments, int *count, ori_import_stats *stats, ori_error *error);
// The end of a reader: on success the segments and the statistics found (their segment count
// set) are handed out; on failure the list is freed. Returns st.
ori_status ori__reader_end(ori_status st, ori__seg_list *segs, ori_import_stats *found, ori_segment **segments,
                           int *count, ori_import_stats *stats);

// libxml2 options of every reader: no network, no entity substitution or DTD loading, errors
// captured instead of printed.
#define ORI__XML_OPTIONS (XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING | XML_PARSE_BIG_LINES)

// Parse XML text into a tree with ORI__XML_OPTIONS; the first error with its line and column.
// *doc is NULL on failure; free it with xmlFreeDoc. what names the format in messages.
struct _xmlDoc;
ori_status ori__xml_parse(const char *text, size_t size, const char *what, struct _xmlDoc **doc, ori_error *error);

// The first XML error of a streaming reader (libxml2 keeps only the last one, usually a
// consequence): install ori__xml_reader_error with a zeroed record as user data
// (xmlTextReaderSetStructuredErrorHandler), then turn it into an error with ori__xml_error.
typedef struct ori__xml_first_error {
    bool set;
    int line, column;
    char message[200];
} ori__xml_first_error;
struct _xmlError;
void ori__xml_reader_error(void *user, struct _xmlError *xe);
// ORI_ERR_PARSE at the first error's line and column ("XML: message").
ori_status ori__xml_error(const ori__xml_first_error *first, ori_error *error);

// Entity references in attributes and text are expanded by orikin (never by xmlGetProp, whose
// expansion of nested entities has no bound): at most ORI__XML_EXPANSION_PER_BYTE bytes per byte
// of the document (plus ORI__XML_EXPANSION_MIN) over the whole document, and nested at most
// ORI__XML_ENTITY_DEPTH deep, so that reading stays linear in the input. External entities are
// never loaded.
#define ORI__XML_EXPANSION_PER_BYTE 8
#define ORI__XML_EXPANSION_MIN ((size_t)1 << 20)
#define ORI__XML_ENTITY_DEPTH 16
typedef struct ori__xml_budget {
    size_t left;   // bytes entity expansion may still produce
    bool exceeded; // set once a document expands beyond its budget (the reader then fails)
} ori__xml_budget;
void ori__xml_budget_init(ori__xml_budget *b, size_t input_size);
// The value of element n's attribute name (no namespace), entity references expanded within the
// budget: a string to ori__free, or NULL when absent or over budget (b->exceeded then set).
struct _xmlNode;
char *ori__xml_attr(const struct _xmlNode *n, const char *name, ori__xml_budget *b);
// The text content of n's children (text, CDATA, entity references), as ori__xml_attr.
char *ori__xml_text(const struct _xmlNode *n, ori__xml_budget *b);

#endif
