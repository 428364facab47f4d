// Hash map from 64-bit keys to ints for the layer solver's pair lookups (face pairs, edge
// pairs, point pairs, grid cells): open addressing, linear probing, load kept at most 1/2.
#include "layers_internal.h"

#include "../core/hash.h"

#define EMPTY UINT64_MAX

void ori__imap_init(ori__imap *m, int64_t expected)
{
    int64_t cap = 16;
    while (cap < 2 * expected) cap *= 2;
    m->cap = cap;
    m->count = 0;
    m->keys = ori__alloc(sizeof(uint64_t) * (size_t)cap);
    m->vals = ori__alloc(sizeof(int) * (size_t)cap);
    memset(m->keys, 0xFF, sizeof(uint64_t) * (size_t)cap);
}

void ori__imap_free(ori__imap *m)
{
    ori__free(m->keys);
    ori__free(m->vals);
    m->keys = NULL;
    m->vals = NULL;
    m->cap = m->count = 0;
}

int ori__imap_get(const ori__imap *m, uint64_t key)
{
    if (key == EMPTY) return -1;
    uint64_t mask = (uint64_t)m->cap - 1;
    for (uint64_t i = ori__mix64(key) & mask;; i = (i + 1) & mask) {
        if (m->keys[i] == key) return m->vals[i];
        if (m->keys[i] == EMPTY) return -1;
    }
}

static void grow(ori__imap *m)
{
    ori__imap bigger;
    ori__imap_init(&bigger, m->cap);
    for (int64_t i = 0; i < m->cap; ++i)
        if (m->keys[i] != EMPTY) ori__imap_put(&bigger, m->keys[i], m->vals[i]);
    ori__imap_free(m);
    *m = bigger;
}

int ori__imap_put(ori__imap *m, uint64_t key, int val)
{
    ORI_ASSERT(key != EMPTY);
    if (2 * (m->count + 1) > m->cap) grow(m);
    uint64_t mask = (uint64_t)m->cap - 1;
    for (uint64_t i = ori__mix64(key) & mask;; i = (i + 1) & mask) {
        if (m->keys[i] == key) return m->vals[i];
        if (m->keys[i] == EMPTY) {
            m->keys[i] = key;
            m->vals[i] = val;
            m->count++;
            return val;
        }
    }
}
