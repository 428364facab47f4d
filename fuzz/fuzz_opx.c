// libFuzzer target for the ORIPA .opx reader (see fuzz_import.h).
#include "fuzz_import.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_import(data, size, ori_opx_read_segments, ori_opx_write, false); }
