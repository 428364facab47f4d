// libFuzzer target for the ORIPA .cp reader (see fuzz_import.h).
#include "fuzz_import.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_import(data, size, ori_cp_read_segments, ori_cp_write, false); }
