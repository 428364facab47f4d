// Hashing helpers shared by the library's open-addressing tables (edge lookup by its two
// vertices in the pattern build, the arrangement's pair map, cell hashes of point sets).
#ifndef ORI_HASH_H
#define ORI_HASH_H

#include <stdint.h>

// Finaliser of MurmurHash3 (fmix64): every input bit affects every output bit.
static inline uint64_t ori__mix64(uint64_t x)
{
    x ^= x >> 33;
    x *= 0xff51afd7ed558ccdULL;
    x ^= x >> 33;
    x *= 0xc4ceb9fe1a85ec53ULL;
    x ^= x >> 33;
    return x;
}

// Key of the unordered vertex pair {a, b} (a, b >= 0): an edge's key whatever its direction.
static inline uint64_t ori__pair_key(int a, int b)
{
    uint32_t lo = (uint32_t)(a < b ? a : b), hi = (uint32_t)(a < b ? b : a);
    return ((uint64_t)hi << 32) | lo;
}

// Power-of-two table size (at least 16) keeping the load factor of n entries at or below 1/2.
static inline int ori__hash_capacity(int n)
{
    int cap = 16;
    while (cap < 2 * n) cap *= 2;
    return cap;
}

#endif
