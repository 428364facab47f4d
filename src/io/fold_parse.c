// FOLD text → document (fold_internal.h): a strict JSON reader (RFC 8259: UTF-8 checked,
// duplicate keys refused, integers beyond 64 bits and reals beyond double refused, depth limited)
// that packs the big arrays of a frame as it reads them instead of building a node per number.
// The top level and every frame of file_frames become lists of fields; an array field made only
// of numbers, of arrays of numbers or of strings is packed; anything else becomes a jansson value.
// Errors carry the line and column (1-based, in bytes) of the offending token, with messages in
// jansson's words ("',' or ']' expected near '['").
#include <errno.h>
#include <float.h>
#include <stdlib.h>

#include "fold_internal.h"

// Nesting deeper than this is refused (as jansson does), keeping the recursion bounded.
#define MAX_DEPTH 2048

typedef struct parser {
    const char *s;
    size_t n, i;
    size_t base; // where line 1 starts (after a byte-order mark)
    int depth;
    ori_error *error;
    ori_status st; // the first failure (ORI_OK while none)
    ori__text str; // the last decoded string
} parser;

// --- errors ------------------------------------------------------------------------------------

static void position(const parser *P, size_t at, int *line, int *column)
{
    int l = 1;
    size_t start = P->base;
    for (size_t k = P->base; k < at && k < P->n; ++k)
        if (P->s[k] == '\n') l++, start = k + 1;
    *line = l;
    *column = (int)(at - start) + 1;
}

// "near 'x'": the bytes of the token at `at` (up to 16, stopping at a separator).
static void near_text(const parser *P, size_t at, char *buf, size_t size)
{
    if (at >= P->n) {
        snprintf(buf, size, "end of file");
        return;
    }
    static const char separators[] = " \t\r\n,:[]{}\"";
    size_t k = at, n = 0;
    char tok[20];
    tok[n++] = P->s[k++];
    if (!strchr(separators, tok[0]))
        while (k < P->n && n < 16 && !strchr(separators, P->s[k])) tok[n++] = P->s[k++];
    tok[n] = '\0';
    for (size_t j = 0; j < n; ++j)
        if ((unsigned char)tok[j] < 0x20 || (unsigned char)tok[j] >= 0x7f) tok[j] = '?';
    snprintf(buf, size, "'%s'", tok);
}

static bool failv(parser *P, ori_status st, size_t at, const char *fmt, ...) __attribute__((format(printf, 4, 5)));
static bool failv(parser *P, ori_status st, size_t at, const char *fmt, ...)
{
    if (P->st != ORI_OK) return false;
    char msg[200], near[40];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    near_text(P, at, near, sizeof near);
    int line, column;
    position(P, at, &line, &column);
    P->st = st;
    ori__fail_pos(P->error, st, line, column, "%s near %s", msg, near);
    return false;
}

#define FAIL(P, at, ...) failv((P), ORI_ERR_PARSE, (at), __VA_ARGS__)

// --- tokens ------------------------------------------------------------------------------------

static void ws(parser *P)
{
    while (P->i < P->n) {
        char c = P->s[P->i];
        if (c != ' ' && c != '\t' && c != '\n' && c != '\r') break;
        P->i++;
    }
}

static int peek(const parser *P) { return P->i < P->n ? (unsigned char)P->s[P->i] : -1; }

static int hex4(const char *s)
{
    int v = 0;
    for (int k = 0; k < 4; ++k) {
        char c = s[k];
        int d = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
        if (d < 0) return -1;
        v = v * 16 + d;
    }
    return v;
}

static void put_utf8(ori__text *t, unsigned cp)
{
    char b[4];
    size_t n;
    if (cp < 0x80) b[0] = (char)cp, n = 1;
    else if (cp < 0x800) b[0] = (char)(0xC0 | cp >> 6), b[1] = (char)(0x80 | (cp & 0x3F)), n = 2;
    else if (cp < 0x10000)
        b[0] = (char)(0xE0 | cp >> 12), b[1] = (char)(0x80 | ((cp >> 6) & 0x3F)), b[2] = (char)(0x80 | (cp & 0x3F)), n = 3;
    else
        b[0] = (char)(0xF0 | cp >> 18), b[1] = (char)(0x80 | ((cp >> 12) & 0x3F)), b[2] = (char)(0x80 | ((cp >> 6) & 0x3F)),
        b[3] = (char)(0x80 | (cp & 0x3F)), n = 4;
    ori__text_put(t, b, n);
}

// Length of the valid UTF-8 sequence at s (n bytes available), or 0 when it is not valid
// (overlong forms, surrogates and code points beyond U+10FFFF are not).
static size_t utf8_len(const unsigned char *s, size_t n)
{
    unsigned c = s[0];
    size_t len;
    unsigned cp;
    if (c < 0x80) return 1;
    if (c >= 0xC2 && c <= 0xDF) len = 2, cp = c & 0x1F;
    else if (c >= 0xE0 && c <= 0xEF) len = 3, cp = c & 0x0F;
    else if (c >= 0xF0 && c <= 0xF4) len = 4, cp = c & 0x07;
    else return 0;
    if (n < len) return 0;
    for (size_t k = 1; k < len; ++k) {
        if ((s[k] & 0xC0) != 0x80) return 0;
        cp = cp << 6 | (s[k] & 0x3F);
    }
    if ((len == 3 && cp < 0x800) || (len == 4 && (cp < 0x10000 || cp > 0x10FFFF)) || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
    return len;
}

// A string at P->i ('"'): decoded into P->str (NUL-terminated, no NUL inside).
static bool parse_string(parser *P)
{
    size_t start = P->i++;
    P->str.len = 0;
    ori__text_reserve(&P->str, 0);
    P->str.data[0] = '\0'; // (reserve terminates only when it grows: "" must not read as the last string)
    for (;;) {
        // A run of plain bytes at once.
        size_t run = P->i;
        while (run < P->n) {
            unsigned char c = (unsigned char)P->s[run];
            if (c == '"' || c == '\\' || c < 0x20 || c >= 0x80) break;
            run++;
        }
        if (run > P->i) ori__text_put(&P->str, P->s + P->i, run - P->i);
        P->i = run;
        if (P->i >= P->n) return FAIL(P, start, "premature end of input in a string");
        unsigned char c = (unsigned char)P->s[P->i];
        if (c == '"') {
            P->i++;
            return true;
        }
        if (c < 0x20) return FAIL(P, P->i, "control character 0x%x in a string", c);
        if (c >= 0x80) {
            size_t len = utf8_len((const unsigned char *)P->s + P->i, P->n - P->i);
            if (len == 0) return FAIL(P, P->i, "unable to decode byte 0x%x (not UTF-8)", c);
            ori__text_put(&P->str, P->s + P->i, len);
            P->i += len;
            continue;
        }
        // An escape.
        if (P->i + 1 >= P->n) return FAIL(P, start, "premature end of input in a string");
        char e = P->s[P->i + 1];
        const char *plain = strchr("\"\\/bfnrt", e);
        if (e && plain) {
            static const char out[] = "\"\\/\b\f\n\r\t";
            ori__text_put(&P->str, &out[plain - "\"\\/bfnrt"], 1);
            P->i += 2;
            continue;
        }
        if (e != 'u' || P->i + 6 > P->n) return FAIL(P, P->i, "invalid escape");
        int cp = hex4(P->s + P->i + 2);
        if (cp < 0) return FAIL(P, P->i, "invalid escape");
        size_t esc = P->i;
        P->i += 6;
        if (cp >= 0xD800 && cp <= 0xDBFF) { // a surrogate pair
            int lo = P->i + 6 <= P->n && P->s[P->i] == '\\' && P->s[P->i + 1] == 'u' ? hex4(P->s + P->i + 2) : -1;
            if (lo < 0xDC00 || lo > 0xDFFF) return FAIL(P, esc, "invalid Unicode '\\u%04X'", (unsigned)cp);
            cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
            P->i += 6;
        } else if (cp >= 0xDC00 && cp <= 0xDFFF) {
            return FAIL(P, esc, "invalid Unicode '\\u%04X'", (unsigned)cp);
        }
        if (cp == 0) return FAIL(P, esc, "\\u0000 is not allowed");
        put_utf8(&P->str, (unsigned)cp);
    }
}

typedef struct number {
    bool is_int;
    int64_t i;
    double d;
} number;

// A number at P->i (RFC 8259 grammar): integers within int64, reals within double.
// Clinger's fast path: a decimal m × 10^e whose digits m fit in 53 bits and with |e| ≤ 22 is
// exactly one correctly rounded multiplication or division of two exact doubles, the same double
// strtod gives (the shortest form of most coordinates, "0.8660254037844386", is such a number).
// Other decimals (17 significant digits, large exponents) go to strtod.
static const double exact_pow10[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                       1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
#define ORI__EXACT_MANTISSA (UINT64_C(1) << 53)

static inline bool is_digit(char c) { return c >= '0' && c <= '9'; }

// One pass over a JSON number: its syntax checked, its value read (integers exactly, within
// int64; reals by the fast path above where it applies, else by strtod).
static bool parse_number(parser *P, number *out)
{
    const char *s = P->s;
    size_t start = P->i, k = P->i, n = P->n;
    bool neg = k < n && s[k] == '-';
    k += neg;
    if (k >= n || !is_digit(s[k])) return FAIL(P, start, "invalid token");
    // m: the digits read so far while they fit in 53 bits (exact stays true)
    uint64_t m = 0;
    bool exact = true;
    int frac = 0;
    if (s[k] == '0') {
        k++;
    } else {
        for (; k < n && is_digit(s[k]); ++k) {
            m = m * 10 + (uint64_t)(s[k] - '0');
            if (m > ORI__EXACT_MANTISSA) exact = false, m = ORI__EXACT_MANTISSA; // keeps m from wrapping
        }
    }
    size_t int_end = k;
    bool is_int = true;
    if (k < n && s[k] == '.') {
        k++;
        if (k >= n || !is_digit(s[k])) return FAIL(P, start, "invalid token");
        for (; k < n && is_digit(s[k]); ++k, ++frac) {
            m = m * 10 + (uint64_t)(s[k] - '0');
            if (m > ORI__EXACT_MANTISSA) exact = false, m = ORI__EXACT_MANTISSA;
        }
        is_int = false;
    }
    int e = 0;
    if (k < n && (s[k] == 'e' || s[k] == 'E')) {
        k++;
        bool eneg = k < n && s[k] == '-';
        if (k < n && (s[k] == '+' || s[k] == '-')) k++;
        if (k >= n || !is_digit(s[k])) return FAIL(P, start, "invalid token");
        for (; k < n && is_digit(s[k]); ++k)
            if (e < 1000) e = e * 10 + (s[k] - '0');
        if (eneg) e = -e;
        is_int = false;
    }
    P->i = k;
    out->is_int = is_int;
    if (is_int) {
        uint64_t v = 0, limit = neg ? (uint64_t)INT64_MAX + 1u : (uint64_t)INT64_MAX;
        for (size_t j = start + neg; j < int_end; ++j) {
            unsigned d = (unsigned)(s[j] - '0');
            if (v > (limit - d) / 10) return FAIL(P, start, "too big integer");
            v = v * 10 + d;
        }
        out->i = neg ? (v == (uint64_t)INT64_MAX + 1u ? INT64_MIN : -(int64_t)v) : (int64_t)v;
        out->d = (double)out->i;
        return true;
    }
    e -= frac;
#if FLT_EVAL_METHOD == 0 // (wider intermediate precision would round twice)
    if (exact && e >= -22 && e <= 22) {
        double d = (double)m;
        d = e < 0 ? d / exact_pow10[-e] : d * exact_pow10[e];
        out->d = neg ? -d : d;
        return true;
    }
#endif
    // strtod needs a terminated copy (the text need not end after the number).
    char small[64], *buf = small;
    size_t len = k - start;
    if (len >= sizeof small) buf = ori__alloc(len + 1);
    memcpy(buf, s + start, len);
    buf[len] = '\0';
    errno = 0;
    double d = strtod(buf, NULL);
    if (buf != small) ori__free(buf);
    if (!isfinite(d)) return FAIL(P, start, "real number overflow");
    out->d = d;
    return true;
}

static bool literal(parser *P, const char *word)
{
    size_t n = strlen(word);
    if (P->n - P->i < n || memcmp(P->s + P->i, word, n) != 0) return FAIL(P, P->i, "invalid token");
    P->i += n;
    return true;
}

// --- general values (jansson) ------------------------------------------------------------------

static json_t *parse_value(parser *P);

static bool enter(parser *P)
{
    if (++P->depth > MAX_DEPTH) return FAIL(P, P->i, "maximum parsing depth reached");
    return true;
}

static json_t *parse_object(parser *P)
{
    P->i++;
    if (!enter(P)) return NULL;
    json_t *obj = json_object();
    ws(P);
    if (peek(P) == '}') {
        P->i++;
        P->depth--;
        return obj;
    }
    for (;;) {
        ws(P);
        if (peek(P) != '"') {
            FAIL(P, P->i, "string or '}' expected");
            break;
        }
        size_t key_at = P->i;
        if (!parse_string(P)) break;
        char *key = ori__strdup(P->str.data);
        ws(P);
        if (peek(P) != ':') {
            ori__free(key);
            FAIL(P, P->i, "':' expected");
            break;
        }
        P->i++;
        ws(P);
        json_t *v = parse_value(P);
        if (!v) {
            ori__free(key);
            break;
        }
        if (json_object_get(obj, key)) {
            json_decref(v);
            ori__free(key);
            FAIL(P, key_at, "duplicate object key");
            break;
        }
        json_object_set_new_nocheck(obj, key, v);
        ori__free(key);
        ws(P);
        int c = peek(P);
        P->i += c >= 0;
        if (c == '}') {
            P->depth--;
            return obj;
        }
        if (c != ',') {
            FAIL(P, P->i - (c >= 0), "'}' expected");
            break;
        }
    }
    json_decref(obj);
    return NULL;
}

static json_t *parse_array(parser *P)
{
    P->i++;
    if (!enter(P)) return NULL;
    json_t *arr = json_array();
    ws(P);
    if (peek(P) == ']') {
        P->i++;
        P->depth--;
        return arr;
    }
    for (;;) {
        ws(P);
        json_t *v = parse_value(P);
        if (!v) break;
        json_array_append_new(arr, v);
        ws(P);
        int c = peek(P);
        P->i += c >= 0;
        if (c == ']') {
            P->depth--;
            return arr;
        }
        if (c != ',') {
            FAIL(P, P->i - (c >= 0), "']' expected");
            break;
        }
    }
    json_decref(arr);
    return NULL;
}

static json_t *parse_value(parser *P)
{
    int c = peek(P);
    switch (c) {
    case '{': return parse_object(P);
    case '[': return parse_array(P);
    case '"': return parse_string(P) ? json_stringn_nocheck(P->str.data, P->str.len) : NULL;
    case 't': return literal(P, "true") ? json_true() : NULL;
    case 'f': return literal(P, "false") ? json_false() : NULL;
    case 'n': return literal(P, "null") ? json_null() : NULL;
    case -1: FAIL(P, P->i, "premature end of input"); return NULL;
    default:
        if (c == '-' || (c >= '0' && c <= '9')) {
            number num;
            if (!parse_number(P, &num)) return NULL;
            return num.is_int ? json_integer((json_int_t)num.i) : json_real(num.d);
        }
        FAIL(P, P->i, "unexpected token");
        return NULL;
    }
}

// --- packed arrays -------------------------------------------------------------------------------

typedef enum pack_result { PACK_NO, PACK_YES, PACK_ERROR } pack_result;

// A number into a packed array; false when it cannot be held exactly (an integer beyond 2^53).
static bool pack_number(ori__packed *pk, const number *num, int64_t entry)
{
    if (num->is_int) {
        if (num->i >= INT32_MIN && num->i <= INT32_MAX) ori__pk_push_int(pk, (int32_t)num->i);
        else if (num->i >= -(INT64_C(1) << 53) && num->i <= (INT64_C(1) << 53)) ori__pk_push_real(pk, (double)num->i);
        else return false;
        return true;
    }
    if (pk->first_real < 0) pk->first_real = entry;
    ori__pk_push_real(pk, num->d);
    return true;
}

// The numbers of a row (P->i just after its '['), up to and including its ']': row `entry` of
// ROWS, or (entry < 0) the entries of NUMS.
static pack_result pack_numbers(parser *P, ori__packed *pk, int64_t entry)
{
    ws(P);
    if (peek(P) == ']') {
        P->i++;
        return PACK_YES;
    }
    for (;;) {
        ws(P);
        int c = peek(P);
        if (!(c == '-' || (c >= '0' && c <= '9'))) return PACK_NO;
        number num;
        if (!parse_number(P, &num)) return PACK_ERROR;
        if (!pack_number(pk, &num, entry >= 0 ? entry : pk->count)) return PACK_NO;
        ws(P);
        c = peek(P);
        if (c == ']') {
            P->i++;
            return PACK_YES;
        }
        if (c != ',') return PACK_NO;
        P->i++;
    }
}

// An array at P->i packed into *out when it is made only of numbers, of arrays of numbers or of
// strings; PACK_NO (P->i unchanged) when it is not, for the general reader.
static pack_result try_pack(parser *P, ori__packed **out)
{
    size_t start = P->i;
    if (P->depth + 2 > MAX_DEPTH) return PACK_NO;
    P->i++;
    ws(P);
    int c = peek(P);
    ori__packed *pk;
    pack_result r = PACK_YES;
    if (c == ']' || c == '-' || (c >= '0' && c <= '9')) {
        pk = ori__pk_new(ORI__PK_NUMS, true, 0);
        r = pack_numbers(P, pk, -1);
    } else if (c == '[') {
        pk = ori__pk_new(ORI__PK_ROWS, true, 0);
        for (;;) {
            ws(P);
            if (peek(P) != '[') {
                r = PACK_NO;
                break;
            }
            P->i++;
            r = pack_numbers(P, pk, pk->count);
            if (r != PACK_YES) break;
            ori__pk_end_row(pk);
            ws(P);
            c = peek(P);
            if (c == ']') {
                P->i++;
                break;
            }
            if (c != ',') {
                r = PACK_NO;
                break;
            }
            P->i++;
        }
    } else if (c == '"') {
        pk = ori__pk_new(ORI__PK_STRS, false, 0);
        for (;;) {
            ws(P);
            if (peek(P) != '"') {
                r = PACK_NO;
                break;
            }
            if (!parse_string(P)) {
                r = PACK_ERROR;
                break;
            }
            ori__pk_push_string(pk, P->str.data, P->str.len);
            ws(P);
            c = peek(P);
            if (c == ']') {
                P->i++;
                break;
            }
            if (c != ',') {
                r = PACK_NO;
                break;
            }
            P->i++;
        }
    } else {
        P->i = start;
        return PACK_NO;
    }
    if (r != PACK_YES) {
        ori__packed_free(pk);
        P->i = start; // the general reader reads it again (and reports any error in its words)
        return r == PACK_ERROR ? PACK_ERROR : PACK_NO;
    }
    ori__pk_shrink(pk);
    *out = pk;
    return PACK_YES;
}

// A field value: packed when it can be, else general.
static bool parse_field_value(parser *P, json_t **json, ori__packed **pk)
{
    *json = NULL;
    *pk = NULL;
    if (peek(P) == '[') {
        pack_result r = try_pack(P, pk);
        if (r == PACK_YES) return true;
        if (r == PACK_ERROR) return false;
    }
    *json = parse_value(P);
    return *json != NULL;
}

// --- document ----------------------------------------------------------------------------------

typedef struct deferred {
    ori_status st;
    char field[48];
    int element;
    char message[120];
} deferred;

// The fields of a frame object (P->i at '{') into frame k; the top level (k = 0) reads
// file_frames into frames of their own.
static bool parse_frame(parser *P, ori_fold *doc, int k, deferred *later)
{
    P->i++;
    if (!enter(P)) return false;
    json_t *seen = json_object(); // keys so far (duplicates are refused)
    bool ok = false;
    ws(P);
    if (peek(P) == '}') {
        P->i++;
        ok = true;
    }
    while (!ok) {
        ws(P);
        if (peek(P) != '"') {
            FAIL(P, P->i, "string or '}' expected");
            break;
        }
        size_t key_at = P->i;
        if (!parse_string(P)) break;
        if (json_object_get(seen, P->str.data)) {
            FAIL(P, key_at, "duplicate object key");
            break;
        }
        json_object_set_new_nocheck(seen, P->str.data, json_null());
        char *key = ori__strdup(P->str.data);
        ws(P);
        if (peek(P) != ':') {
            ori__free(key);
            FAIL(P, P->i, "':' expected");
            break;
        }
        P->i++;
        ws(P);
        bool got;
        if (k == 0 && strcmp(key, "file_frames") == 0 && peek(P) == '[') {
            got = true;
            P->i++;
            ws(P);
            bool closed = peek(P) == ']';
            if (closed) P->i++;
            for (int index = 0; !closed; ++index) {
                ws(P);
                if (peek(P) == '{') {
                    int f = ori__doc_add_frame(doc);
                    if (!parse_frame(P, doc, f, later)) {
                        got = false;
                        break;
                    }
                } else {
                    json_t *v = parse_value(P);
                    if (!v) {
                        got = false;
                        break;
                    }
                    json_decref(v);
                    if (later->st == ORI_OK) {
                        later->st = ORI_ERR_TYPE;
                        snprintf(later->field, sizeof later->field, "file_frames");
                        later->element = index;
                        snprintf(later->message, sizeof later->message, "frame is not an object");
                    }
                }
                ws(P);
                int c = peek(P);
                P->i += c >= 0;
                if (c == ']') break;
                if (c != ',') {
                    got = FAIL(P, P->i - (c >= 0), "']' expected");
                    break;
                }
            }
            if (got) ori__frame_set(&doc->frames[0], key, NULL, NULL); // the marker
        } else {
            json_t *json;
            ori__packed *pk;
            got = parse_field_value(P, &json, &pk);
            if (got) ori__frame_set(&doc->frames[k], key, json, pk);
            if (got && k == 0 && strcmp(key, "file_frames") == 0 && later->st == ORI_OK) {
                // (not an array: kept as it is, refused once the text is known to be JSON)
                later->st = ORI_ERR_TYPE;
                snprintf(later->field, sizeof later->field, "file_frames");
                later->element = ORI_NULL_INDEX;
                snprintf(later->message, sizeof later->message, "not an array");
            }
        }
        ori__free(key);
        if (!got) break;
        ws(P);
        int c = peek(P);
        P->i += c >= 0;
        if (c == '}') {
            ok = true;
            break;
        }
        if (c != ',') {
            FAIL(P, P->i - (c >= 0), "'}' expected");
            break;
        }
    }
    json_decref(seen);
    P->depth--;
    return ok;
}

static void parser_init(parser *P, const char *text, size_t size, ori_error *error)
{
    memset(P, 0, sizeof *P);
    P->s = text;
    P->n = size;
    P->error = error;
    // A UTF-8 byte-order mark (some Windows editors write one) is not part of the JSON text.
    if (size >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0) P->i = P->base = 3;
}

ori_status ori__doc_parse(const char *text, size_t size, ori_fold **out, ori_error *error)
{
    ORI_ASSERT(text && out);
    *out = NULL;
    parser P;
    parser_init(&P, text, size, error);
    ws(&P);
    int c = peek(&P);
    ori_fold *doc = NULL;
    if (c == '{') {
        doc = ori__doc_new();
        deferred later = {ORI_OK, "", ORI_NULL_INDEX, ""};
        if (parse_frame(&P, doc, 0, &later)) {
            ws(&P);
            if (P.i < P.n) FAIL(&P, P.i, "end of file expected");
        }
        if (P.st == ORI_OK && later.st != ORI_OK)
            P.st = ori__fail_at(error, later.st, later.field, later.element, "%s", later.message);
    } else if (c == '[') {
        json_t *v = parse_value(&P);
        json_decref(v);
        ws(&P);
        if (P.st == ORI_OK && P.i < P.n) FAIL(&P, P.i, "end of file expected");
        if (P.st == ORI_OK) P.st = ori__fail(error, ORI_ERR_TYPE, "the top level is not a JSON object");
    } else {
        FAIL(&P, P.i, "'[' or '{' expected");
    }
    ori__free(P.str.data);
    if (P.st != ORI_OK) {
        ori_fold_destroy(doc);
        return P.st;
    }
    *out = doc;
    return ORI_OK;
}

ori_status ori__doc_parse_value(const char *text, size_t size, json_t **json, ori__packed **pk, ori_error *error)
{
    *json = NULL;
    *pk = NULL;
    parser P;
    parser_init(&P, text, size, error);
    ws(&P);
    if (parse_field_value(&P, json, pk)) {
        ws(&P);
        if (P.i < P.n) FAIL(&P, P.i, "end of file expected");
    }
    ori__free(P.str.data);
    if (P.st != ORI_OK) {
        json_decref(*json);
        ori__packed_free(*pk);
        *json = NULL;
        *pk = NULL;
        return P.st;
    }
    return ORI_OK;
}
