// Counted allocator: every library heap block carries a 16-byte header with its size so that
// live count, live bytes and the peak can be tracked (tests assert the count returns to 0).
#include "core_internal.h"

#include <stdatomic.h>
#include <stdlib.h>

typedef union header {
    size_t size;
    max_align_t align;
} header;

static void *default_alloc(size_t size, void *user)
{
    (void)user;
    return malloc(size);
}

static void default_free(void *ptr, void *user)
{
    (void)user;
    free(ptr);
}

static ori_allocator g_alloc = {default_alloc, default_free, NULL};
static _Atomic int64_t g_live_count;
static _Atomic int64_t g_live_bytes;
static _Atomic int64_t g_peak_bytes;

static void default_oom(size_t size)
{
    (void)size;
    abort();
}

static void default_assert(const char *condition, const char *file, int line)
{
    (void)condition;
    (void)file;
    (void)line;
    abort();
}

static ori_oom_fn *g_oom = default_oom;
static ori_assert_fn *g_assert = default_assert;

void ori_set_allocator(const ori_allocator *allocator)
{
    if (allocator && allocator->alloc && allocator->free)
        g_alloc = *allocator;
    else {
        g_alloc.alloc = default_alloc;
        g_alloc.free = default_free;
        g_alloc.user = NULL;
    }
}

void ori_set_assert_hook(ori_assert_fn *fn) { g_assert = fn ? fn : default_assert; }
void ori_set_oom_hook(ori_oom_fn *fn) { g_oom = fn ? fn : default_oom; }

void ori__assert_fail(const char *condition, const char *file, int line)
{
    g_assert(condition, file, line);
    abort(); // the hook must not return into an invalid state
}

int64_t ori_alloc_live_count(void) { return atomic_load(&g_live_count); }
int64_t ori_alloc_live_bytes(void) { return atomic_load(&g_live_bytes); }
int64_t ori_alloc_peak_bytes(void) { return atomic_load(&g_peak_bytes); }
void ori_alloc_reset_peak(void) { atomic_store(&g_peak_bytes, atomic_load(&g_live_bytes)); }

static void account(int64_t count, int64_t bytes)
{
    atomic_fetch_add(&g_live_count, count);
    int64_t now = atomic_fetch_add(&g_live_bytes, bytes) + bytes;
    int64_t peak = atomic_load(&g_peak_bytes);
    while (now > peak && !atomic_compare_exchange_weak(&g_peak_bytes, &peak, now)) {
    }
}

void *ori__alloc(size_t size)
{
    if (size > SIZE_MAX - sizeof(header)) {
        g_oom(size);
        abort();
    }
    header *h = g_alloc.alloc(sizeof(header) + size, g_alloc.user);
    if (!h) {
        g_oom(size);
        abort();
    }
    h->size = size;
    account(1, (int64_t)size);
    return h + 1;
}

void *ori__calloc(size_t count, size_t size)
{
    size_t total;
    if (!ori__mul_size(count, size, &total)) {
        g_oom(SIZE_MAX);
        abort();
    }
    void *p = ori__alloc(total);
    memset(p, 0, total);
    return p;
}

void ori__free(void *ptr)
{
    if (!ptr) return;
    header *h = (header *)ptr - 1;
    account(-1, -(int64_t)h->size);
    g_alloc.free(h, g_alloc.user);
}

void *ori__realloc(void *ptr, size_t size)
{
    if (!ptr) return ori__alloc(size);
    header *old = (header *)ptr - 1;
    size_t old_size = old->size;
    void *p = ori__alloc(size);
    memcpy(p, ptr, old_size < size ? old_size : size);
    ori__free(ptr);
    return p;
}

char *ori__strdup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = ori__alloc(n);
    memcpy(d, s, n);
    return d;
}

bool ori__mul_size(size_t count, size_t size, size_t *out)
{
    if (size != 0 && count > SIZE_MAX / size) return false;
    *out = count * size;
    return true;
}

void ori__grow(void **array, int *cap, int need, size_t elem)
{
    ORI_ASSERT(need >= 0);
    if (need <= *cap) return;
    int64_t ncap = *cap > 0 ? (int64_t)*cap : 8;
    while (ncap < need) ncap *= 2;
    if (ncap > INT32_MAX) ncap = INT32_MAX;
    size_t bytes;
    if (!ori__mul_size((size_t)ncap, elem, &bytes)) {
        g_oom(SIZE_MAX);
        abort();
    }
    *array = ori__realloc(*array, bytes);
    *cap = (int)ncap;
}

void ori_buffer_free(void *buffer) { ori__free(buffer); }
