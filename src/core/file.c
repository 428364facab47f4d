// Whole-file read and atomic write (temporary file beside the target, then rename), so that a
// failed command never leaves a partial output.
#define _POSIX_C_SOURCE 200809L
#include "core_internal.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

ori_status ori_file_read_all(const char *path, size_t max_bytes, char **out_data,
                             size_t *out_size, ori_error *error)
{
    *out_data = NULL;
    if (out_size) *out_size = 0;
    FILE *f = fopen(path, "rb");
    if (!f) return ori__fail(error, ORI_ERR_IO, "cannot open: %s", strerror(errno));
    struct stat st;
    if (fstat(fileno(f), &st) != 0 || !S_ISREG(st.st_mode)) {
        fclose(f);
        return ori__fail(error, ORI_ERR_IO, "not a regular file");
    }
    if ((uint64_t)st.st_size > (uint64_t)max_bytes) {
        fclose(f);
        return ori__fail(error, ORI_ERR_LIMIT, "file is %lld bytes, more than the limit %zu",
                         (long long)st.st_size, max_bytes);
    }
    size_t size = (size_t)st.st_size;
    char *data = ori__alloc(size + 1);
    size_t got = size ? fread(data, 1, size, f) : 0;
    int err = ferror(f);
    fclose(f);
    if (got != size || err) {
        ori__free(data);
        return ori__fail(error, ORI_ERR_IO, "read error");
    }
    data[size] = '\0';
    *out_data = data;
    if (out_size) *out_size = size;
    return ORI_OK;
}

ori_status ori_file_write_atomic(const char *path, const void *data, size_t size, ori_error *error)
{
    size_t n = strlen(path);
    char *tmp = ori__alloc(n + 16);
    memcpy(tmp, path, n);
    memcpy(tmp + n, ".tmp.XXXXXX", 12);
    int fd = mkstemp(tmp);
    if (fd < 0) {
        ori_status s = ori__fail(error, ORI_ERR_IO, "cannot create %s: %s", tmp, strerror(errno));
        ori__free(tmp);
        return s;
    }
    FILE *f = fdopen(fd, "wb");
    bool ok = f != NULL;
    if (ok && size) ok = fwrite(data, 1, size, f) == size;
    if (ok) ok = fflush(f) == 0;
    if (f) {
        if (fclose(f) != 0) ok = false;
    } else {
        close(fd);
    }
    if (ok) {
        // mkstemp creates 0600; give the file the usual permissions.
        mode_t mask = umask(0);
        umask(mask);
        chmod(tmp, 0666 & ~mask);
        ok = rename(tmp, path) == 0;
    }
    if (!ok) {
        int e = errno;
        remove(tmp);
        ori__free(tmp);
        return ori__fail(error, ORI_ERR_IO, "cannot write: %s", strerror(e));
    }
    ori__free(tmp);
    return ORI_OK;
}
