// Arena: a chain of blocks for per-solve scratch memory, released all at once.
#include "core_internal.h"

struct ori__arena_block {
    ori__arena_block *next;
    size_t size;
    size_t used;
    max_align_t align_data[];
};

void ori__arena_init(ori__arena *arena, size_t block_size)
{
    arena->head = NULL;
    arena->block_size = block_size ? block_size : 64 * 1024;
}

void *ori__arena_alloc(ori__arena *arena, size_t size)
{
    size_t need = (size + 15u) & ~(size_t)15u;
    if (need < size) ori__assert_fail("arena size overflow", __FILE__, __LINE__);
    ori__arena_block *b = arena->head;
    if (!b || b->size - b->used < need) {
        size_t cap = need > arena->block_size ? need : arena->block_size;
        b = ori__alloc(sizeof(ori__arena_block) + cap);
        b->next = arena->head;
        b->size = cap;
        b->used = 0;
        arena->head = b;
    }
    void *p = (char *)b->align_data + b->used;
    b->used += need;
    memset(p, 0, need);
    return p;
}

void ori__arena_reset(ori__arena *arena)
{
    ori__arena_block *b = arena->head;
    while (b) {
        ori__arena_block *next = b->next;
        ori__free(b);
        b = next;
    }
    arena->head = NULL;
}
