// libFuzzer target for the SVG reader: read segments, planarise them (small inputs), export the
// pattern in the same format and read the export back, which must succeed. Any crash, leak or
// sanitizer report is a bug.
#include <orikin/formats.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    ori_segment *segs = NULL;
    int n = 0;
    ori_error err;
    if (ori_svg_read_segments((const char *)data, size, &segs, &n, NULL, &err) == ORI_OK) {
        ori_pattern *p = NULL;
        if (n <= 256 && ori_segments_to_pattern(segs, n, NULL, &p, &err) == ORI_OK) {
            char *text = ori_svg_write(p, NULL);
            ori_segment *again = NULL;
            int m = 0;
            if (ori_svg_read_segments(text, strlen(text), &again, &m, NULL, &err) != ORI_OK) abort(); // our output must parse
            ori_buffer_free(again);
            ori_buffer_free(text);
            ori_pattern_destroy(p);
        }
        ori_buffer_free(segs);
    }
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}
