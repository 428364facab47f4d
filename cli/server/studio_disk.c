// The studio's document against the file on disk: change detection before save-back (the file
// may have been edited elsewhere since the studio read it), and an autosave journal beside the
// file so that a crash, a kill or a closed terminal loses no edit (recovered at the next start).
#define _DEFAULT_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "studio_internal.h"

void studio_disk_remember(studio_disk *d, const char *path)
{
    struct stat st;
    memset(d, 0, sizeof *d);
    if (!path || !path[0] || stat(path, &st) != 0) return;
    d->known = true;
    d->dev = (unsigned long long)st.st_dev;
    d->ino = (unsigned long long)st.st_ino;
    d->size = (long long)st.st_size;
    d->mtime_sec = (long long)st.st_mtim.tv_sec;
    d->mtime_nsec = (long long)st.st_mtim.tv_nsec;
}

bool studio_disk_changed(const studio_disk *d, const char *path)
{
    if (!d->known) return false;
    studio_disk now;
    studio_disk_remember(&now, path);
    return !now.known || now.dev != d->dev || now.ino != d->ino || now.size != d->size ||
           now.mtime_sec != d->mtime_sec || now.mtime_nsec != d->mtime_nsec;
}

void studio_journal_path(const char *save_path, char *out, size_t size)
{
    const char *slash = strrchr(save_path, '/');
    int dir = slash ? (int)(slash - save_path + 1) : 0;
    if (snprintf(out, size, "%.*s.%s.orikin-autosave", dir, save_path, slash ? slash + 1 : save_path) >= (int)size)
        out[0] = '\0';
}

void studio_autosave(studio *s)
{
    if (!s->journal[0] || s->recovery) return;
    if (s->model == s->saved_model || !s->from_command_line) {
        // back at what the disk holds (undo to the saved state), or another document is shown:
        // the journal of the command-line file stays as long as that file has unsaved edits
        if (s->model == s->saved_model) unlink(s->journal);
        return;
    }
    char *text = ori_fold_to_string(s->doc);
    if (!text) return;
    // created private (the journal may hold a design not yet meant for others); the atomic
    // write keeps the mode of the file it replaces
    int fd = open(s->journal, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd >= 0) close(fd);
    ori_error err;
    (void)ori_file_write_atomic(s->journal, text, strlen(text), &err);
    ori_buffer_free(text);
}

void studio_mark_saved(studio *s)
{
    studio_disk_remember(&s->doc_disk, s->save_path);
    studio_model_unref(s->saved_model);
    s->saved_model = studio_model_ref(s->model);
    if (s->journal[0] && !s->recovery) unlink(s->journal);
}

bool studio_unsaved(studio *s, char *journal, size_t size)
{
    pthread_mutex_lock(&s->lock);
    bool unsaved = s->model != s->saved_model;
    snprintf(journal, size, "%s", s->journal[0] && access(s->journal, F_OK) == 0 ? s->journal : "");
    pthread_mutex_unlock(&s->lock);
    return unsaved && journal[0];
}

bool studio_recovery_pending(studio *s, char *journal, size_t size)
{
    pthread_mutex_lock(&s->lock);
    bool pending = s->recovery;
    snprintf(journal, size, "%s", s->journal);
    pthread_mutex_unlock(&s->lock);
    return pending;
}
