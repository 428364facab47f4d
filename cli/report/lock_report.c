// The lock suggestion of an underdetermined fold, as `orikin fold` and the studio's POST
// /api/fold give it in "hint" (and the fold modes name it for several drives).
#include <stdio.h>
#include <stdlib.h>

#include "report.h"

#define LOCK_EXAMPLE 12 // creases named in a lock suggestion

void cli_lock_text(const int *locks, int n, char *buf, size_t size)
{
    int w = snprintf(buf, size, "lock %d more crease%s, e.g. --lock ", n, n == 1 ? "" : "s");
    for (int i = 0; i < n && i < LOCK_EXAMPLE && w > 0 && (size_t)w < size; ++i)
        w += snprintf(buf + w, size - (size_t)w, "%s%d", i ? "," : "", locks[i]);
    if (n > LOCK_EXAMPLE && w > 0 && (size_t)w < size) snprintf(buf + w, size - (size_t)w, ",...");
    if (w > 0 && (size_t)w < size) snprintf(buf + w, size - (size_t)w, " (or --lock auto)");
}

int cli_lock_hint(const ori_mechanism *m, const ori_motion_def *def, char *buf, size_t size, json_t **locks)
{
    buf[0] = '\0';
    int cap = ori_mechanism_edge_count(m) + 1;
    int *out = malloc(sizeof(int) * (size_t)cap);
    ori_error err;
    int n = ori_mechanism_lock_set(m, def->start_angles_rad, &def->driven_edge, 1, def->locked_edges, def->locked_count,
                                   NULL, out, cap, &err);
    if (n > 0) {
        cli_lock_text(out, n, buf, size);
        if (locks) {
            *locks = json_array();
            for (int i = 0; i < n; ++i) json_array_append_new(*locks, json_integer(out[i]));
        }
    }
    free(out);
    return n;
}
