// libFuzzer target for the composite (crease collection) JSON reader: parse, and when it
// parses, apply the composite to a square sheet. Any crash, leak or sanitizer report is a bug.
#include <orikin/collection.h>
#include <orikin/orikin.h>
#include <stdint.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    ori_composite *c = NULL;
    ori_error err;
    if (ori_composite_load_string((const char *)data, size, &c, &err) != ORI_OK) {
        if (err.line < 1 || err.column < 1) abort(); // errors always carry a position
        return 0;
    }
    ori_v2 sq[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    ori_pattern *p = NULL;
    if (ori_pattern_create_sheet(sq, 4, &p, &err) != ORI_OK) abort();
    if (ori_composite_crease_count(c) <= 64) ori_pattern_apply_composite(p, c, 0, NULL, NULL, &err);
    ori_pattern_destroy(p);
    ori_composite_destroy(c);
    return 0;
}
