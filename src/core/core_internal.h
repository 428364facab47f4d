// Private core services shared by every library module: counted allocation, asserts, arena,
// growable arrays, error helpers. Never included by cli/ or public headers.
#ifndef ORI_CORE_INTERNAL_H
#define ORI_CORE_INTERNAL_H

#include <orikin/base.h>
#include <orikin/tolerance.h>

#include <math.h>
#include <stdarg.h>
#include <string.h>

// Programmer errors (NULL, index out of range, def not from its default): the assert hook.
#if defined(NDEBUG) && !defined(ORI_ENABLE_ASSERT)
#  define ORI_ASSERT(cond) ((void)0)
#else
#  define ORI_ASSERT(cond) ((cond) ? (void)0 : ori__assert_fail(#cond, __FILE__, __LINE__))
#endif

// The magic set by every ori_default_*_def(); ORI_ASSERT(def->internal_value == ORI__DEF_COOKIE).
#define ORI__DEF_COOKIE 0x0B1C0DE

void ori__assert_fail(const char *condition, const char *file, int line);

// Counted allocation. ori__alloc never returns NULL (the OOM hook runs instead).
void *ori__alloc(size_t size);
void *ori__calloc(size_t count, size_t size);
void *ori__realloc(void *ptr, size_t size);
void ori__free(void *ptr);
char *ori__strdup(const char *s);
// Overflow-checked count × size; returns false on overflow.
bool ori__mul_size(size_t count, size_t size, size_t *out);

// Grow *array (element size elem) so that it holds at least need elements; *cap updated.
void ori__grow(void **array, int *cap, int need, size_t elem);
#define ORI__RESERVE(arr, cap, need) ori__grow((void **)&(arr), &(cap), (need), sizeof(*(arr)))
#define ORI__PUSH(arr, count, cap, value)                                                    \
    do {                                                                                     \
        ORI__RESERVE(arr, cap, (count) + 1);                                                 \
        (arr)[(count)++] = (value);                                                          \
    } while (0)

// Union-find: the root of x in the forest parent[] (parent[r] == r at a root), halving the path.
static inline int ori__uf_root(int *parent, int x)
{
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
}

// Arena: bump allocation for per-solve scratch; freed all at once.
typedef struct ori__arena_block ori__arena_block;
typedef struct ori__arena {
    ori__arena_block *head;
    size_t block_size;
} ori__arena;
void ori__arena_init(ori__arena *arena, size_t block_size);
void *ori__arena_alloc(ori__arena *arena, size_t size); // 16-byte aligned, zeroed
void ori__arena_reset(ori__arena *arena);               // free every block
#define ORI__ARENA_NEW(arena, type, n) ((type *)ori__arena_alloc((arena), sizeof(type) * (size_t)(n)))

// Error helpers: fill *error (may be NULL) and return status.
ori_status ori__fail(ori_error *error, ori_status status, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
ori_status ori__fail_at(ori_error *error, ori_status status, const char *field, int element,
                        const char *fmt, ...) __attribute__((format(printf, 5, 6)));
ori_status ori__fail_pos(ori_error *error, ori_status status, int line, int column,
                         const char *fmt, ...) __attribute__((format(printf, 5, 6)));

// A coordinate orikin can compute with: finite and at most ORI_COORD_MAX in magnitude.
static inline bool ori__coord_ok(double x) { return isfinite(x) && fabs(x) <= ORI_COORD_MAX; }

// vsnprintf for library messages (ori__fail*): the same conversions, except that %g without a
// precision prints a value exactly enough to read back as itself (see status.c).
void ori__vformat(char *buf, size_t size, const char *fmt, va_list ap);

// Memory the process can still use (bytes): the least of the system's available memory, the
// container's limit less its use and the process's resource limits; UINT64_MAX when unknown.
uint64_t ori__memory_available(void);
// ori_file_read_all, refused up front (ORI_ERR_LIMIT, saying how much is needed and available)
// when bytes_per_byte × the file's size exceeds ori__memory_available(): the peak memory a
// reader needs per byte of its file.
ori_status ori__file_read_within_memory(const char *path, size_t max_bytes, unsigned bytes_per_byte, char **out_data,
                                        size_t *out_size, ori_error *error);

// Bounded string copy that always terminates.
void ori__strlcpy(char *dst, const char *src, size_t size);

#endif
