/// orikin base: export macro, status codes, error record, allocator and assert hooks,
/// library-owned buffers.
///
/// Functions: ori_status_name, ori_status_message, ori_error_clear, ori_error_format,
/// ori_set_allocator, ori_set_assert_hook, ori_set_oom_hook, ori_alloc_live_count,
/// ori_alloc_live_bytes, ori_alloc_peak_bytes, ori_alloc_reset_peak, ori_buffer_free,
/// ori_file_read_all, ori_file_write_atomic, ori_file_batch_*, ori_file_remove_temporaries, ori_version_string.
#ifndef ORIKIN_BASE_H
#define ORIKIN_BASE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#if defined(_WIN32)
#  define ORI_API __declspec(dllexport)
#elif defined(__GNUC__)
#  define ORI_API __attribute__((visibility("default")))
#else
#  define ORI_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/// The index meaning "none" for vertices, edges, faces and nodes (never 0: 0 is a real index).
#define ORI_NULL_INDEX (-1)

/// Status table: X(NAME, "message"). ORI_OK is 0; every run-time failure has one entry.
#define ORI_STATUS_TABLE(X)                                                          \
    X(OK, "ok")                                                                      \
    X(ERR_NOMEM, "out of memory")                                                    \
    X(ERR_IO, "input/output error")                                                  \
    X(ERR_PARSE, "malformed input")                                                  \
    X(ERR_TYPE, "wrong type")                                                        \
    X(ERR_RANGE, "index or value out of range")                                      \
    X(ERR_DUPLICATE, "coincident vertices")                                          \
    X(ERR_DEGENERATE, "degenerate geometry")                                         \
    X(ERR_CROSSING, "edges cross without a shared vertex")                           \
    X(ERR_TOPOLOGY, "inconsistent topology")                                         \
    X(ERR_ARGUMENT, "invalid argument")                                              \
    X(ERR_NOT_FOUND, "not found")                                                    \
    X(ERR_LIMIT, "size limit exceeded")                                              \
    X(ERR_NOT_CONVERGED, "solver did not converge")                                  \
    X(ERR_UNSUPPORTED, "unsupported")                                                \
    X(ERR_INTERNAL, "internal error")

/// Status of a run-time operation. ORI_OK = 0; everything else is a failure.
typedef enum ori_status {
#define ORI__STATUS_ENUM(name, msg) ORI_##name,
    ORI_STATUS_TABLE(ORI__STATUS_ENUM)
#undef ORI__STATUS_ENUM
        ORI_STATUS_COUNT
} ori_status;

/// Symbolic name of a status ("ERR_PARSE"); static string, never NULL.
ORI_API const char *ori_status_name(ori_status status);
/// Human message of a status ("malformed input"); static string, never NULL.
ORI_API const char *ori_status_message(ori_status status);

/// Where and why a run-time operation failed. line/column are 1-based positions in a text
/// input (0 = unknown); element is the FOLD index of the offending vertex/edge/face
/// (ORI_NULL_INDEX = none) and field names the array it indexes ("edges_vertices").
typedef struct ori_error {
    ori_status status;
    int line;
    int column;
    int element;
    char field[48];
    char message[256];
} ori_error;

/// Reset an error record to "no error" (status ORI_OK, element ORI_NULL_INDEX).
ORI_API void ori_error_clear(ori_error *error);

/// Format an error as one line: "line 3, column 7: msg", "edges_vertices 12: msg" or "msg".
/// Writes at most size bytes (always NUL-terminated when size > 0); returns buf.
ORI_API char *ori_error_format(const ori_error *error, char *buf, size_t size);

/// Allocation hooks: all library heap memory goes through these. free receives what alloc
/// returned. user is passed back unchanged.
typedef struct ori_allocator {
    void *(*alloc)(size_t size, void *user);
    void (*free)(void *ptr, void *user);
    void *user;
} ori_allocator;

/// Install allocation hooks (NULL restores malloc/free). Call before creating any object.
ORI_API void ori_set_allocator(const ori_allocator *allocator);

/// Called when an ORI_ASSERT fails (programmer error). The default prints nothing and aborts.
typedef void ori_assert_fn(const char *condition, const char *file, int line);
/// Install the assert hook (NULL restores the default).
ORI_API void ori_set_assert_hook(ori_assert_fn *fn);

/// Called when an allocation fails; must not return (the default aborts).
typedef void ori_oom_fn(size_t size);
/// Install the out-of-memory hook (NULL restores the default).
ORI_API void ori_set_oom_hook(ori_oom_fn *fn);

/// Number of library allocations currently live (tests assert it returns to zero).
ORI_API int64_t ori_alloc_live_count(void);
/// Bytes currently allocated by the library.
ORI_API int64_t ori_alloc_live_bytes(void);
/// Largest value ori_alloc_live_bytes reached since start or the last reset.
ORI_API int64_t ori_alloc_peak_bytes(void);
/// Reset the peak to the current live bytes.
ORI_API void ori_alloc_reset_peak(void);

/// Free a buffer (string, array) that the library handed out. NULL is a no-op.
ORI_API void ori_buffer_free(void *buffer);

/// Read a whole file into a NUL-terminated buffer (free with ori_buffer_free). Files larger
/// than max_bytes fail with ORI_ERR_LIMIT before anything is allocated; anything but a regular
/// file (FIFO, device, directory) fails at once with ORI_ERR_IO, without blocking.
ORI_API ori_status ori_file_read_all(const char *path, size_t max_bytes, char **out_data,
                                     size_t *out_size, ori_error *error);

/// Write size bytes to path atomically: into a temporary file beside it ("NAME.tmp.XXXXXX",
/// NAME shortened when too long for the directory), then rename. On failure nothing is left at
/// path (an existing file there is untouched). A symbolic link is written through (its target
/// is replaced, the link kept); a path that is not a regular file (device, FIFO, directory) or
/// an existing file the process may not write (e.g. mode 0444) is refused with ORI_ERR_IO. The
/// new file keeps the replaced file's mode (and owner where permitted); a new file gets 0666
/// less the umask. While the temporary file exists, ori_file_remove_temporaries can remove it.
/// The data is synced before the rename and the directory after (durable across a power loss);
/// the rename breaks hard links (other links keep the old contents). In a current batch
/// (ori_file_batch) the file is staged and renamed by ori_file_batch_commit.
ORI_API ori_status ori_file_write_atomic(const char *path, const void *data, size_t size,
                                         ori_error *error);

/// A set of outputs written all or none: while a batch is current in a thread, every
/// ori_file_write_atomic of that thread (and so every writer of the library that takes a path)
/// writes and syncs its temporary file but does not rename it; ori_file_batch_commit renames
/// them all, ori_file_batch_destroy removes what was not committed. Writing a path twice keeps
/// the later contents.
typedef struct ori_file_batch ori_file_batch;
/// A new, empty batch; destroy it with ori_file_batch_destroy.
ORI_API ori_file_batch *ori_file_batch_create(void);
/// Make batch the current one of this thread (NULL: none); returns the previous one.
ORI_API ori_file_batch *ori_file_batch_set_current(ori_file_batch *batch);
/// Number of files staged in batch (0 for NULL).
ORI_API int ori_file_batch_count(const ori_file_batch *batch);
/// Rename every staged file into place and sync their directories. Call once. On a failure
/// (rare: every target was checked when staged) the remaining files are removed unrenamed.
ORI_API ori_status ori_file_batch_commit(ori_file_batch *batch, ori_error *error);
/// Remove the staged files not committed and free the batch (no longer current). NULL: no-op.
ORI_API void ori_file_batch_destroy(ori_file_batch *batch);

/// Remove the temporary files of every ori_file_write_atomic still in progress (in any thread)
/// and return how many were removed. Async-signal-safe: meant for the SIGINT/SIGTERM handler
/// of the program (the library installs none), which calls it and then ends the process, e.g.
///   static void on_signal(int sig) { ori_file_remove_temporaries(); signal(sig, SIG_DFL); raise(sig); }
/// An interrupted write then leaves neither a partial output nor its temporary file. Up to 64
/// writes at once are tracked.
ORI_API int ori_file_remove_temporaries(void);

/// Progress of a long operation: called now and then with the fraction done (0 … 1) and the
/// user pointer given with it. Return false to cancel: the operation then stops at its next
/// check and fails with ORI_ERR_LIMIT ("cancelled"). The library never prints; the CLI draws a
/// bar on stderr and the studio's server reports it to the page.
typedef bool ori_progress_fn(double fraction, void *user);

/// Library version, e.g. "0.1.0"; static string.
ORI_API const char *ori_version_string(void);

#ifdef __cplusplus
}
#endif

#endif
