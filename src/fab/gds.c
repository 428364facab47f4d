// GDSII stream writer (include/orikin/fab.h). The records are written directly: each is a
// big-endian 2-byte length (header included), a record type and a data type, then its data
// (2- and 4-byte integers big-endian, 8-byte excess-64 reals, ASCII padded to even length).
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <orikin/fab.h>

#include "../core/core_internal.h"
#include "../io/io_internal.h"

// Record types with their data types (type << 8 | data type).
enum {
    GDS_HEADER = 0x0002,
    GDS_BGNLIB = 0x0102,
    GDS_LIBNAME = 0x0206,
    GDS_UNITS = 0x0305,
    GDS_ENDLIB = 0x0400,
    GDS_BGNSTR = 0x0502,
    GDS_STRNAME = 0x0606,
    GDS_ENDSTR = 0x0700,
    GDS_BOUNDARY = 0x0800,
    GDS_PATH = 0x0900,
    GDS_TEXT = 0x0C00,
    GDS_LAYER = 0x0D02,
    GDS_DATATYPE = 0x0E02,
    GDS_WIDTH = 0x0F03,
    GDS_XY = 0x1003,
    GDS_ENDEL = 0x1100,
    GDS_TEXTTYPE = 0x1602,
    GDS_PRESENTATION = 0x1701,
    GDS_STRING = 0x1906,
    GDS_MAG = 0x1B05,
    GDS_PATHTYPE = 0x2102,
};

// Most points of a BOUNDARY: its XY record holds at most (65535 − 4) / 8 = 8191 points, the
// closing repetition of the first point included.
#define GDS_MAX_POLYGON_POINTS 8190
// Longest string of a record: its data, padded to even length, within the 65535 − 4 bytes after
// the record's header.
#define GDS_MAX_STRING 65530

ori_gds_def ori_default_gds_def(void)
{
    ori_gds_def d;
    d.user_unit_m = 0.0;
    d.database_unit_m = 0.0;
    d.library_name = "ORIKIN";
    d.cell_name = "DEVICE";
    d.internal_value = 1;
    return d;
}

bool ori_gds_real8(double x, unsigned char out[8])
{
    memset(out, 0, 8);
    if (!isfinite(x)) return false;
    if (x == 0.0) return true;
    int sign = x < 0.0;
    double a = fabs(x);
    int k;
    double f = frexp(a, &k); // a = f·2^k, f ∈ [0.5, 1)
    // q = ⌈k / 4⌉: a = g·16^q with g = f·2^(k − 4q) ∈ [1/16, 1), the mantissa g·2^56 exact.
    int q = k >= 0 ? (k + 3) / 4 : -((-k) / 4);
    int e = q + 64;
    if (e > 127) return false;
    if (e < 0) return true; // below the smallest normalised value: 0
    uint64_t m = (uint64_t)ldexp(f, 53) << (3 + k - 4 * q);
    out[0] = (unsigned char)((sign << 7) | e);
    for (int i = 1; i < 8; ++i) out[i] = (unsigned char)(m >> (8 * (7 - i)));
    return true;
}

typedef struct gds_buf {
    unsigned char *data;
    int len, cap;
} gds_buf;

static void put_bytes(gds_buf *b, const void *p, int n)
{
    ori__grow((void **)&b->data, &b->cap, b->len + n, 1);
    memcpy(b->data + b->len, p, (size_t)n);
    b->len += n;
}

static void put_u16(gds_buf *b, unsigned v)
{
    unsigned char c[2] = {(unsigned char)(v >> 8), (unsigned char)v};
    put_bytes(b, c, 2);
}

static void put_i32(gds_buf *b, int32_t v)
{
    uint32_t u = (uint32_t)v;
    unsigned char c[4] = {(unsigned char)(u >> 24), (unsigned char)(u >> 16), (unsigned char)(u >> 8), (unsigned char)u};
    put_bytes(b, c, 4);
}

static void record(gds_buf *b, unsigned type, int data_bytes)
{
    put_u16(b, (unsigned)(4 + data_bytes));
    put_u16(b, type);
}

static void record_i16(gds_buf *b, unsigned type, int v)
{
    record(b, type, 2);
    put_u16(b, (unsigned)(v & 0xffff));
}

static void record_string(gds_buf *b, unsigned type, const char *s)
{
    int n = (int)strlen(s), padded = n + (n & 1);
    record(b, type, padded);
    put_bytes(b, s, n);
    if (n & 1) put_bytes(b, "", 1);
}

static void record_dates(gds_buf *b, unsigned type)
{
    // modification and access time: 1970-01-01 00:00:00 (year, month, day, hour, minute, second)
    record(b, type, 24);
    for (int t = 0; t < 2; ++t) {
        put_u16(b, 1970);
        put_u16(b, 1);
        put_u16(b, 1);
        for (int i = 0; i < 3; ++i) put_u16(b, 0);
    }
}

// A real of the UNITS or MAG record: false when it is not finite, beyond 16^63, or a nonzero
// value that underflows (below 16^-65 ori_gds_real8 writes 0: a zero database unit or text size).
static bool unit_real(double x, unsigned char out[8])
{
    return ori_gds_real8(x, out) && (x == 0.0 || fabs(x) >= ldexp(1.0, -260));
}

static bool quantise(double x, double scale, int32_t *out)
{
    double r = nearbyint(x * scale);
    if (!(fabs(r) <= 2147483647.0)) return false;
    *out = (int32_t)r;
    return true;
}

static ori_status put_xy(gds_buf *b, const ori_v2 *pts, int n, bool close, double scale, int shape, ori_error *error)
{
    int m = n + (close ? 1 : 0);
    record(b, GDS_XY, 8 * m);
    for (int i = 0; i < m; ++i) {
        ori_v2 p = pts[i % n];
        int32_t x, y;
        if (!quantise(p.x, scale, &x) || !quantise(p.y, scale, &y))
            return ori__fail_at(error, ORI_ERR_LIMIT, "shape", shape,
                                "a coordinate is beyond ±2^31 database units (a coarser database unit)");
        put_i32(b, x);
        put_i32(b, y);
    }
    return ORI_OK;
}

unsigned char *ori_gds_write(const ori_fab_layout *l, const ori_gds_def *def, size_t *size, ori_error *error)
{
    ORI_ASSERT(l);
    ori_gds_def d = def ? *def : ori_default_gds_def();
    double mpu = ori_fab_layout_meters_per_unit(l);
    double user = d.user_unit_m > 0.0 ? d.user_unit_m : mpu;
    double dbu = d.database_unit_m;
    if (!(dbu > 0.0)) { // user / 1000 as the nearest double of its 15-digit decimal (1e-6 / 1000 is 1e-9 less an ulp)
        char buf[32];
        snprintf(buf, sizeof buf, "%.15g", user / 1000.0);
        dbu = strtod(buf, NULL);
    }
    double scale = mpu / dbu; // pattern units → database units
    if (size) *size = 0;
    const char *names[2] = {d.library_name ? d.library_name : "ORIKIN", d.cell_name ? d.cell_name : "DEVICE"};
    for (int k = 0; k < 2; ++k)
        if (strlen(names[k]) > GDS_MAX_STRING) {
            // (the record's 16-bit length would wrap and the stream fall apart after it)
            ori__fail_at(error, ORI_ERR_LIMIT, k ? "cell_name" : "library_name", ORI_NULL_INDEX,
                         "a %s of %zu bytes (a GDSII record holds %d)", k ? "cell name" : "library name", strlen(names[k]),
                         GDS_MAX_STRING);
            return NULL;
        }
    gds_buf b = {NULL, 0, 0};
    record_i16(&b, GDS_HEADER, 600);
    record_dates(&b, GDS_BGNLIB);
    record_string(&b, GDS_LIBNAME, names[0]);
    record(&b, GDS_UNITS, 16);
    unsigned char r[8];
    // user units per database unit: exactly 1/1000 by default (dbu / user would round to 0.001000…02)
    if (!unit_real(d.database_unit_m > 0.0 ? dbu / user : 1e-3, r) || !(dbu / user > 0.0)) goto units;
    put_bytes(&b, r, 8);
    if (!unit_real(dbu, r)) goto units;
    put_bytes(&b, r, 8);
    record_dates(&b, GDS_BGNSTR);
    record_string(&b, GDS_STRNAME, names[1]);
    for (int i = 0; i < ori_fab_shape_count(l); ++i) {
        ori_fab_shape s = ori_fab_shape_at(l, i);
        ori_status st = ORI_OK;
        if (s.kind == ORI_FAB_POLYGON) {
            if (s.point_count > GDS_MAX_POLYGON_POINTS) {
                ori__fail_at(error, ORI_ERR_LIMIT, "shape", i, "a polygon of %d points (GDSII holds %d)", s.point_count,
                             GDS_MAX_POLYGON_POINTS);
                goto fail;
            }
            record(&b, GDS_BOUNDARY, 0);
            record_i16(&b, GDS_LAYER, s.layer);
            record_i16(&b, GDS_DATATYPE, 0);
            st = put_xy(&b, s.points, s.point_count, true, scale, i, error);
        } else if (s.kind == ORI_FAB_PATH) {
            record(&b, GDS_PATH, 0);
            record_i16(&b, GDS_LAYER, s.layer);
            record_i16(&b, GDS_DATATYPE, 0);
            record_i16(&b, GDS_PATHTYPE, 0);
            int32_t w;
            if (!quantise(s.width, scale, &w)) {
                ori__fail_at(error, ORI_ERR_LIMIT, "shape", i, "a path width beyond 2^31 database units");
                goto fail;
            }
            record(&b, GDS_WIDTH, 4);
            put_i32(&b, w);
            st = put_xy(&b, s.points, s.point_count, false, scale, i, error);
        } else {
            record(&b, GDS_TEXT, 0);
            record_i16(&b, GDS_LAYER, s.layer);
            record_i16(&b, GDS_TEXTTYPE, 0);
            record_i16(&b, GDS_PRESENTATION, 0); // font 0, top-left… here: bottom, left
            record(&b, GDS_MAG, 8);
            if (!unit_real(s.width * mpu / user, r)) goto units; // text height in user units
            put_bytes(&b, r, 8);
            st = put_xy(&b, s.points, 1, false, scale, i, error);
            if (st == ORI_OK) record_string(&b, GDS_STRING, s.text);
        }
        if (st != ORI_OK) goto fail;
        record(&b, GDS_ENDEL, 0);
    }
    record(&b, GDS_ENDSTR, 0);
    record(&b, GDS_ENDLIB, 0);
    if (size) *size = (size_t)b.len;
    return b.data;
units:
    ori__fail_at(error, ORI_ERR_RANGE, "units", ORI_NULL_INDEX, "units beyond the range of GDSII reals");
fail:
    ori__free(b.data);
    return NULL;
}

char *ori_fab_layer_map(const ori_fab_layout *l)
{
    ORI_ASSERT(l);
    ori__text t = {NULL, 0, 0};
    ori__text_puts(&t, "# orikin fab layer map: GDSII LAYER/DATATYPE NAME description (docs/fabrication.md)\n");
    char unit[64];
    ori__format_double(ori_fab_layout_meters_per_unit(l), unit, sizeof unit);
    ori__text_printf(&t, "# pattern unit %s m\n", unit);
    for (int k = ORI_FAB_LAYER_FIRST; k <= ORI_FAB_LAYER_LAST; ++k) {
        int n = 0;
        for (int i = 0; i < ori_fab_shape_count(l); ++i) n += ori_fab_shape_at(l, i).layer == k;
        ori__text_printf(&t, "%d/0 %s %s (%d shape%s)\n", k, ori_fab_layer_name(k), ori_fab_layer_description(k), n,
                         n == 1 ? "" : "s");
    }
    return t.data;
}
