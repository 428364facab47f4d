// libFuzzer target for unfolding: the first byte chooses the input kind. 0: OBJ text, 1: STL
// (ASCII or binary) — read into a surface and, when it is small, unfolded (3 tries) and folded
// back; 2: a linkage of up to 10 vertices on a small integer grid (a chain, or a polygon when the
// second byte is odd), followed to its end with at most 200 events. Any crash, leak, sanitizer
// report or a net with overlaps reported as one piece is a bug.
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <orikin/orikin.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void shape(const uint8_t *data, size_t size, const char *ext)
{
    char path[64];
    snprintf(path, sizeof path, "/tmp/orikin-fuzz-unfold-XXXXXX");
    int fd = mkstemp(path);
    if (fd < 0) return;
    if (write(fd, data, size) != (ssize_t)size) {
        close(fd);
        unlink(path);
        return;
    }
    close(fd);
    char named[80];
    snprintf(named, sizeof named, "%s%s", path, ext);
    if (rename(path, named) != 0) {
        unlink(path);
        return;
    }
    ori_mesh *m = NULL;
    ori_error err;
    if (ori_unfold_load_mesh(named, &m, &err) == ORI_OK) {
        if (ori_unfold_mesh_face_count(m) <= 40) {
            ori_unfold_def def = ori_default_unfold_def();
            def.tries = 3;
            ori_unfold_net *net = NULL;
            if (ori_unfold_solve(m, &def, &net, &err) == ORI_OK) {
                ori_unfold_result r = ori_unfold_net_result(net);
                if (r.pieces < 1 || r.overlaps != 0) abort();
                ori_unfold_net_destroy(net);
            }
        }
        ori_unfold_mesh_destroy(m);
    }
    unlink(named);
}

static void linkage(const uint8_t *data, size_t size)
{
    if (size < 2) return;
    bool closed = data[1] & 1;
    data += 2, size -= 2;
    int n = (int)(size / 2);
    if (n > 10) n = 10;
    if (n < 2) return;
    ori_v2 p[10];
    int e[20];
    for (int i = 0; i < n; ++i) p[i] = ori_v2_make((double)(data[2 * i] % 16), (double)(data[2 * i + 1] % 16));
    int m = closed ? n : n - 1;
    for (int i = 0; i < m; ++i) e[2 * i] = i, e[2 * i + 1] = (i + 1) % n;
    ori_linkage_def def = ori_default_linkage_def();
    def.coords = p, def.vertex_count = n, def.edges = e, def.edge_count = m, def.max_events = 200;
    ori_linkage_motion *mo = NULL;
    ori_error err;
    if (ori_linkage_unfold(&def, &mo, &err) == ORI_OK) {
        ori_linkage_result r = ori_linkage_motion_result(mo);
        if (r.max_length_error > 1e-6) abort();
        ori_linkage_motion_destroy(mo);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1) return 0;
    switch (data[0] % 3) {
    case 0: shape(data + 1, size - 1, ".obj"); break;
    case 1: shape(data + 1, size - 1, ".stl"); break;
    default: linkage(data, size); break;
    }
    return 0;
}
