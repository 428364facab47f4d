// Whole-file read and atomic write (temporary file beside the target, then rename), so that a
// failed command never leaves a partial output.
//
// Durability is that of SQLite and git: the temporary file is synced before the rename and the
// directory after it, so that after a power loss the path holds the old contents or the new,
// never neither. A batch (ori_file_batch) stages several outputs the same way and renames them
// all only when every one was written, so a command with several outputs writes all or none.
// The rename replaces the directory entry: other hard links to the old file keep the old
// contents (as with git and most editors' safe saves).
//
// Reading opens without blocking and checks the file type on the open descriptor before
// reading anything, so a FIFO or a device fails at once instead of waiting for a writer.
//
// Writing resolves the target first: a symbolic link is written through (the file it points to
// is replaced and the link stays), anything that is not a regular file (device, FIFO,
// directory, socket) is refused, and a file the caller may not write (a read-only 0444 file) is
// refused as a shell redirection would. The temporary file gets the existing file's mode (and
// owner, where the process may set it), else 0666 less the umask. Its name is the target's with
// ".tmp.XXXXXX" appended, the target's name shortened when the whole would exceed the
// directory's name limit. While it exists its path is in a table of writes in progress that
// ori_file_remove_temporaries (async-signal-safe) empties, so that a signal handler can remove
// it: the library itself installs no handler.
#define _POSIX_C_SOURCE 200809L
#include "core_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

static const char *file_kind(mode_t m)
{
    if (S_ISDIR(m)) return "a directory";
    if (S_ISFIFO(m)) return "a FIFO (named pipe)";
    if (S_ISCHR(m)) return "a character device";
    if (S_ISBLK(m)) return "a block device";
    if (S_ISSOCK(m)) return "a socket";
    return "not a regular file";
}

ori_status ori_file_read_all(const char *path, size_t max_bytes, char **out_data,
                             size_t *out_size, ori_error *error)
{
    ORI_ASSERT(path && out_data);
    *out_data = NULL;
    if (out_size) *out_size = 0;
    // O_NONBLOCK: opening a FIFO for reading must not wait for a writer; cleared below.
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) return ori__fail(error, ORI_ERR_IO, "cannot open: %s", strerror(errno));
    struct stat st;
    if (fstat(fd, &st) != 0) {
        int e = errno;
        close(fd);
        return ori__fail(error, ORI_ERR_IO, "cannot open: %s", strerror(e));
    }
    if (!S_ISREG(st.st_mode)) {
        close(fd);
        return ori__fail(error, ORI_ERR_IO, "%s, not a regular file", file_kind(st.st_mode));
    }
    if ((uint64_t)st.st_size > (uint64_t)max_bytes) {
        close(fd);
        return ori__fail(error, ORI_ERR_LIMIT, "file is %lld bytes, more than the limit %zu",
                         (long long)st.st_size, max_bytes);
    }
    int flags = fcntl(fd, F_GETFL);
    if (flags >= 0) fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    size_t size = (size_t)st.st_size;
    char *data = ori__alloc(size + 1);
    size_t got = 0;
    while (got < size) {
        ssize_t n = read(fd, data + got, size - got);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break; // error, or the file shrank while being read
        got += (size_t)n;
    }
    int read_errno = got < size ? errno : 0;
    close(fd);
    if (got != size) {
        ori__free(data);
        return ori__fail(error, ORI_ERR_IO, "read error%s%s", read_errno ? ": " : " (the file changed while read)",
                         read_errno ? strerror(read_errno) : "");
    }
    data[size] = '\0';
    *out_data = data;
    if (out_size) *out_size = size;
    return ORI_OK;
}

// --- memory -----------------------------------------------------------------------------------

// The first number in a small text file (/proc, /sys), or false.
static bool read_number_file(const char *path, const char *after, uint64_t *out)
{
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    char buf[4096];
    ssize_t n = read(fd, buf, sizeof buf - 1);
    close(fd);
    if (n <= 0) return false;
    buf[n] = '\0';
    const char *p = buf;
    if (after) {
        p = strstr(buf, after);
        if (!p) return false;
        p += strlen(after);
    }
    while (*p == ' ' || *p == '\t') ++p;
    if (*p < '0' || *p > '9') return false; // e.g. "max": no limit
    *out = strtoull(p, NULL, 10);
    return true;
}

uint64_t ori__memory_available(void)
{
    uint64_t best = UINT64_MAX, v, used;
    if (read_number_file("/proc/meminfo", "MemAvailable:", &v)) best = v * 1024u;
    // A container's limit (cgroup v2, then v1), less what the group already uses.
    if (read_number_file("/sys/fs/cgroup/memory.max", NULL, &v)) {
        if (!read_number_file("/sys/fs/cgroup/memory.current", NULL, &used)) used = 0;
        v = v > used ? v - used : 0;
        if (v < best) best = v;
    } else if (read_number_file("/sys/fs/cgroup/memory/memory.limit_in_bytes", NULL, &v) && v < ((uint64_t)1 << 60)) {
        if (!read_number_file("/sys/fs/cgroup/memory/memory.usage_in_bytes", NULL, &used)) used = 0;
        v = v > used ? v - used : 0;
        if (v < best) best = v;
    }
    struct rlimit rl;
    if (getrlimit(RLIMIT_AS, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY && (uint64_t)rl.rlim_cur < best) best = rl.rlim_cur;
    if (getrlimit(RLIMIT_DATA, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY && (uint64_t)rl.rlim_cur < best) best = rl.rlim_cur;
    return best;
}

static void format_bytes(uint64_t b, char *buf, size_t size)
{
    if (b >= ((uint64_t)1 << 30)) snprintf(buf, size, "%.1f GB", (double)b / (double)((uint64_t)1 << 30));
    else if (b >= ((uint64_t)1 << 20)) snprintf(buf, size, "%.1f MB", (double)b / (double)((uint64_t)1 << 20));
    else snprintf(buf, size, "%llu bytes", (unsigned long long)b);
}

ori_status ori__file_read_within_memory(const char *path, size_t max_bytes, unsigned bytes_per_byte, char **out_data,
                                        size_t *out_size, ori_error *error)
{
    struct stat st;
    if (stat(path, &st) == 0 && S_ISREG(st.st_mode) && (uint64_t)st.st_size <= (uint64_t)max_bytes) {
        uint64_t need = (uint64_t)st.st_size * bytes_per_byte, have = ori__memory_available();
        if (need > have) {
            char a[32], b[32], c[32];
            format_bytes((uint64_t)st.st_size, a, sizeof a);
            format_bytes(need, b, sizeof b);
            format_bytes(have, c, sizeof c);
            *out_data = NULL;
            if (out_size) *out_size = 0;
            return ori__fail(error, ORI_ERR_LIMIT, "this %s file needs about %s of memory to load; %s is available", a, b, c);
        }
    }
    return ori_file_read_all(path, max_bytes, out_data, out_size, error);
}

// --- writes in progress ------------------------------------------------------------------------

// The temporary paths of writes in progress. A slot holds a path the library allocated; the
// writer claims a free slot (compare-exchange from NULL) before creating the file and clears it
// before freeing the path, so a signal handler that reads a slot sees either NULL or a valid,
// NUL-terminated path. More writes than slots at once are still atomic, only not cleaned up.
#define TEMP_SLOTS 64
static _Atomic(char *) temp_slots[TEMP_SLOTS];

static int temp_track(char *path)
{
    for (int i = 0; i < TEMP_SLOTS; ++i) {
        char *expected = NULL;
        if (atomic_compare_exchange_strong(&temp_slots[i], &expected, path)) return i;
    }
    return -1;
}

static void temp_untrack(int slot)
{
    if (slot >= 0) atomic_store(&temp_slots[slot], NULL);
}

int ori_file_remove_temporaries(void)
{
    int removed = 0;
    for (int i = 0; i < TEMP_SLOTS; ++i) {
        char *path = atomic_exchange(&temp_slots[i], NULL);
        if (path && unlink(path) == 0) removed++;
    }
    return removed;
}

// --- atomic write ------------------------------------------------------------------------------

// The file a write to path replaces: path itself, or where its chain of symbolic links ends
// (allocated into *target). Fails for a link that loops or is too long.
static ori_status resolve_target(const char *path, char **target, ori_error *error)
{
    char *cur = ori__strdup(path);
    for (int hops = 0;; ++hops) {
        struct stat st;
        if (lstat(cur, &st) != 0 || !S_ISLNK(st.st_mode)) break;
        if (hops >= 40) {
            ori__free(cur);
            return ori__fail(error, ORI_ERR_IO, "cannot write: too many levels of symbolic links");
        }
        size_t cap = (size_t)st.st_size > 0 ? (size_t)st.st_size + 1 : PATH_MAX;
        char *link = ori__alloc(cap + 1);
        ssize_t n = readlink(cur, link, cap);
        if (n < 0 || (size_t)n >= cap) {
            ori__free(link);
            ori__free(cur);
            return ori__fail(error, ORI_ERR_IO, "cannot write: cannot read the symbolic link");
        }
        link[n] = '\0';
        if (link[0] == '/') {
            ori__free(cur);
            cur = link;
            continue;
        }
        // A relative link is relative to the directory holding the link.
        const char *slash = strrchr(cur, '/');
        size_t dir = slash ? (size_t)(slash - cur) + 1 : 0;
        char *next = ori__alloc(dir + (size_t)n + 1);
        memcpy(next, cur, dir);
        memcpy(next + dir, link, (size_t)n + 1);
        ori__free(link);
        ori__free(cur);
        cur = next;
    }
    *target = cur;
    return ORI_OK;
}

// "<dir>/<name>.tmp.XXXXXX" beside target, the name shortened (on a byte boundary) so that the
// whole stays within the directory's limit on names.
static char *temp_template(const char *target)
{
    static const char suffix[] = ".tmp.XXXXXX";
    const char *slash = strrchr(target, '/');
    size_t dir = slash ? (size_t)(slash - target) + 1 : 0;
    size_t name = strlen(target) - dir;
    long name_max = 255;
    char *d = ori__alloc(dir + 2);
    if (dir) memcpy(d, target, dir), d[dir] = '\0';
    else d[0] = '.', d[1] = '\0';
    long m = pathconf(d, _PC_NAME_MAX);
    if (m > 0) name_max = m;
    ori__free(d);
    size_t keep = name;
    if (keep + sizeof suffix - 1 > (size_t)name_max)
        keep = (size_t)name_max > sizeof suffix - 1 ? (size_t)name_max - (sizeof suffix - 1) : 0;
    char *tmp = ori__alloc(dir + keep + sizeof suffix);
    memcpy(tmp, target, dir + keep);
    memcpy(tmp + dir + keep, suffix, sizeof suffix);
    return tmp;
}

// Create the temporary file (mode 0600, exclusive) under a fresh name in place of the X's of
// tmp, tracking the name (*slot) before the file exists, so that a signal at any point finds
// it. Returns the descriptor, or -1 with errno set (nothing tracked).
static int open_temp(char *tmp, int *slot)
{
    static const char digits[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    static atomic_uint_fast64_t counter;
    char *x = tmp + strlen(tmp) - 6;
    for (int attempt = 0; attempt < 100; ++attempt) {
        struct timespec ts;
        clock_gettime(CLOCK_REALTIME, &ts);
        uint64_t r = (uint64_t)ts.tv_nsec * 0x9E3779B97F4A7C15u ^ (uint64_t)ts.tv_sec ^ ((uint64_t)getpid() << 32) ^
                     (atomic_fetch_add(&counter, 1) * 0xBF58476D1CE4E5B9u);
        r ^= r >> 31;
        for (int k = 0; k < 6; ++k, r /= 62) x[k] = digits[r % 62];
        *slot = temp_track(tmp);
        int fd = open(tmp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
        if (fd >= 0) return fd;
        int e = errno;
        temp_untrack(*slot);
        *slot = -1;
        errno = e;
        if (e != EEXIST) return -1;
    }
    return -1;
}

static bool write_all(int fd, const char *data, size_t size)
{
    while (size > 0) {
        ssize_t n = write(fd, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        data += n;
        size -= (size_t)n;
    }
    return true;
}

// fsync the directory holding path, so that a rename into it survives a power loss (ext4 and
// XFS order a rename after the data only when asked). Best effort: a file system that cannot
// sync a directory (EINVAL) is not an error.
static bool sync_directory_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    size_t dir = slash ? (size_t)(slash - path) + (slash == path ? 1 : 0) : 0;
    char *d = ori__alloc(dir + 2);
    if (dir) memcpy(d, path, dir), d[dir] = '\0';
    else d[0] = '.', d[1] = '\0';
    bool ok = true;
    int fd = open(d, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
        if (fsync(fd) != 0 && errno != EINVAL && errno != EROFS) ok = false;
        close(fd);
    }
    ori__free(d);
    return ok;
}

// --- batches of outputs --------------------------------------------------------------------------

typedef struct staged {
    char *tmp, *target;
    int slot;
} staged;

struct ori_file_batch {
    staged *files;
    int count, capacity;
    bool committed;
};

// The batch ori_file_write_atomic stages into, per thread (ori_file_batch_set_current).
static _Thread_local ori_file_batch *current_batch;

ori_file_batch *ori_file_batch_create(void)
{
    ori_file_batch *b = ori__alloc(sizeof *b);
    memset(b, 0, sizeof *b);
    return b;
}

ori_file_batch *ori_file_batch_set_current(ori_file_batch *batch)
{
    ori_file_batch *previous = current_batch;
    current_batch = batch;
    return previous;
}

static void stage(ori_file_batch *b, char *tmp, char *target, int slot)
{
    for (int i = 0; i < b->count; ++i)
        if (strcmp(b->files[i].target, target) == 0) { // written again: the later contents win
            unlink(b->files[i].tmp);
            temp_untrack(b->files[i].slot);
            ori__free(b->files[i].tmp);
            ori__free(target);
            b->files[i].tmp = tmp;
            b->files[i].slot = slot;
            return;
        }
    if (b->count == b->capacity) {
        int cap = b->capacity ? 2 * b->capacity : 4;
        staged *f = ori__alloc((size_t)cap * sizeof *f);
        if (b->count) memcpy(f, b->files, (size_t)b->count * sizeof *f);
        ori__free(b->files);
        b->files = f;
        b->capacity = cap;
    }
    b->files[b->count++] = (staged){tmp, target, slot};
}

int ori_file_batch_count(const ori_file_batch *batch)
{
    return batch ? batch->count : 0;
}

ori_status ori_file_batch_commit(ori_file_batch *b, ori_error *error)
{
    ORI_ASSERT(b && !b->committed);
    b->committed = true;
    int e = 0, failed = -1;
    for (int i = 0; i < b->count; ++i) {
        if (e == 0 && rename(b->files[i].tmp, b->files[i].target) != 0) e = errno, failed = i;
        if (e != 0) unlink(b->files[i].tmp);
        temp_untrack(b->files[i].slot);
    }
    bool synced = true;
    for (int i = 0; i < b->count && e == 0; ++i) {
        bool seen = false; // one fsync per directory
        for (int j = 0; j < i && !seen; ++j) {
            const char *a = strrchr(b->files[i].target, '/'), *c = strrchr(b->files[j].target, '/');
            size_t la = a ? (size_t)(a - b->files[i].target) : 0, lc = c ? (size_t)(c - b->files[j].target) : 0;
            seen = la == lc && memcmp(b->files[i].target, b->files[j].target, la) == 0;
        }
        if (!seen && !sync_directory_of(b->files[i].target)) synced = false, e = errno;
    }
    if (e != 0)
        return ori__fail(error, ORI_ERR_IO, "cannot write %s: %s", failed >= 0 ? b->files[failed].target : "the outputs",
                         synced ? strerror(e) : "cannot sync the directory");
    return ORI_OK;
}

void ori_file_batch_destroy(ori_file_batch *b)
{
    if (!b) return;
    if (current_batch == b) current_batch = NULL;
    for (int i = 0; i < b->count; ++i) {
        if (!b->committed) {
            unlink(b->files[i].tmp);
            temp_untrack(b->files[i].slot);
        }
        ori__free(b->files[i].tmp);
        ori__free(b->files[i].target);
    }
    ori__free(b->files);
    ori__free(b);
}

// --- atomic write ------------------------------------------------------------------------------

ori_status ori_file_write_atomic(const char *path, const void *data, size_t size, ori_error *error)
{
    ORI_ASSERT(path && (data || size == 0));
    if (!*path) return ori__fail(error, ORI_ERR_IO, "cannot write: empty file name");
    char *target = NULL;
    ori_status s = resolve_target(path, &target, error);
    if (s != ORI_OK) return s;
    struct stat old;
    bool exists = stat(target, &old) == 0;
    if (!exists && errno != ENOENT) {
        s = ori__fail(error, ORI_ERR_IO, "cannot write: %s", strerror(errno));
        ori__free(target);
        return s;
    }
    if (exists && !S_ISREG(old.st_mode)) {
        s = ori__fail(error, ORI_ERR_IO, "cannot write: %s is %s", strcmp(target, path) == 0 ? "the path" : "the link's target",
                      file_kind(old.st_mode));
        ori__free(target);
        return s;
    }
    if (exists && access(target, W_OK) != 0) {
        s = ori__fail(error, ORI_ERR_IO, "cannot write: %s (the existing file is not writable)", strerror(errno));
        ori__free(target);
        return s;
    }
    char *tmp = temp_template(target);
    int slot = -1, fd = open_temp(tmp, &slot);
    if (fd < 0) {
        int e = errno;
        s = ori__fail(error, ORI_ERR_IO, "cannot create a temporary file beside it: %s", strerror(e));
        ori__free(tmp);
        ori__free(target);
        return s;
    }
    bool ok = write_all(fd, data, size);
    int e = ok ? 0 : errno;
    if (ok) {
        mode_t mode;
        if (exists) {
            mode = old.st_mode & 07777;
            if (fchown(fd, old.st_uid, old.st_gid) != 0) { // only root may give a file away: keep ours
            }
        } else {
            // mkstemp creates 0600; give a new file the usual permissions.
            mode_t mask = umask(0);
            umask(mask);
            mode = 0666 & ~mask;
        }
        if (fchmod(fd, mode) != 0) ok = false, e = errno;
    }
    // The data reaches the disk before the rename makes it the file (as SQLite and git do), so
    // that a power loss leaves the old file or the new one, never an empty one.
    if (ok && fsync(fd) != 0 && errno != EINVAL) ok = false, e = errno;
    if (close(fd) != 0 && ok) ok = false, e = errno;
    if (ok && current_batch) { // staged: renamed with the rest of the batch, or removed with it
        stage(current_batch, tmp, target, slot);
        return ORI_OK;
    }
    if (ok && rename(tmp, target) != 0) ok = false, e = errno;
    if (!ok) unlink(tmp);
    temp_untrack(slot);
    if (ok && !sync_directory_of(target)) ok = false, e = errno;
    ori__free(tmp);
    ori__free(target);
    if (!ok) return ori__fail(error, ORI_ERR_IO, "cannot write: %s", strerror(e ? e : EIO));
    return ORI_OK;
}
