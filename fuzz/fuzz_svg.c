// libFuzzer target for the SVG reader (see fuzz_import.h), exporting with the default style.
#include "fuzz_import.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static char *write_svg(const ori_pattern *p) { return ori_svg_write(p, NULL); }

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_import(data, size, ori_svg_read_segments, write_svg, true); }
