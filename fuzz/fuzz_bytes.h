// The fuzz targets' byte reader: values drawn one after another from the input, every read
// past its end 0 (so that any input, however short, decodes). Shared by fuzz_kin.h and the
// targets that decode parameters without it.
#ifndef ORI_FUZZ_BYTES_H
#define ORI_FUZZ_BYTES_H

#include <stddef.h>
#include <stdint.h>

typedef struct fk_bytes {
    const uint8_t *p;
    size_t n, at;
} fk_bytes;

static inline uint8_t fk_u8(fk_bytes *b) { return b->at < b->n ? b->p[b->at++] : 0; }
static inline uint16_t fk_u16(fk_bytes *b) { return (uint16_t)(fk_u8(b) | (fk_u8(b) << 8)); }
// A value in [lo, hi] from 16 bits.
static inline double fk_range(fk_bytes *b, double lo, double hi) { return lo + (hi - lo) * fk_u16(b) / 65535.0; }

#endif
