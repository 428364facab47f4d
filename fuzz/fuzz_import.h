// The body shared by the drawing-reader fuzz targets (fuzz_svg.c, fuzz_opx.c, fuzz_cp.c): read
// segments; when they read, planarise them (small inputs), export the pattern in the same format
// and read the export back, which must succeed. Any crash, leak or sanitizer report is a bug.
#ifndef ORI_FUZZ_IMPORT_H
#define ORI_FUZZ_IMPORT_H

#include <orikin/formats.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

typedef ori_status (*fuzz_reader)(const char *text, size_t size, ori_segment **segments, int *count,
                                  ori_import_stats *stats, ori_error *error);

// write: the pattern in the reader's format (a buffer for ori_buffer_free).
static inline int fuzz_import(const uint8_t *data, size_t size, fuzz_reader read, char *(*write)(const ori_pattern *))
{
    ori_segment *segs = NULL;
    int n = 0;
    ori_error err;
    if (read((const char *)data, size, &segs, &n, NULL, &err) == ORI_OK) {
        ori_pattern *p = NULL;
        if (n <= 256 && ori_segments_to_pattern(segs, n, NULL, &p, &err) == ORI_OK) {
            char *text = write(p);
            ori_segment *again = NULL;
            int m = 0;
            if (read(text, strlen(text), &again, &m, NULL, &err) != ORI_OK) abort(); // our output must parse
            ori_buffer_free(again);
            ori_buffer_free(text);
            ori_pattern_destroy(p);
        }
        ori_buffer_free(segs);
    }
    if (ori_alloc_live_count() != 0) abort();
    return 0;
}

#endif
