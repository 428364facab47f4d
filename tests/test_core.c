// Core: status table, error formatting, counted allocator, arena, math (Rodrigues, twist
// exponential), robust orientation, and files (read without blocking, atomic write through
// links, modes, long names, clean-up after a signal).
#define _DEFAULT_SOURCE
#include <dirent.h>
#include <fcntl.h>
#include <float.h>
#include <signal.h>
#include <stdio.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "core/core_internal.h"
#include "support.h"

TestSuite(core, .init = test_leak_setup, .fini = test_leak_check);

Test(core, status_table_names_and_messages)
{
    cr_assert_eq(ORI_OK, 0);
    cr_assert_str_eq(ori_status_name(ORI_ERR_PARSE), "ERR_PARSE");
    cr_assert_str_eq(ori_status_message(ORI_ERR_CROSSING), "edges cross without a shared vertex");
    cr_assert_str_eq(ori_status_name((ori_status)999), "UNKNOWN");
    for (int s = 0; s < ORI_STATUS_COUNT; ++s) cr_assert(strlen(ori_status_message((ori_status)s)) > 0);
}

Test(core, error_format_prefers_position_then_element)
{
    ori_error e;
    char buf[256];
    ori__fail_pos(&e, ORI_ERR_PARSE, 3, 7, "unexpected '}'");
    cr_assert_str_eq(ori_error_format(&e, buf, sizeof buf), "line 3, column 7: unexpected '}'");
    ori__fail_at(&e, ORI_ERR_RANGE, "edges_vertices", 12, "vertex index 99 out of range");
    cr_assert_str_eq(ori_error_format(&e, buf, sizeof buf), "edges_vertices 12: vertex index 99 out of range");
    ori__fail(&e, ORI_ERR_IO, "cannot open");
    cr_assert_str_eq(ori_error_format(&e, buf, sizeof buf), "cannot open");
    cr_assert_eq(e.element, ORI_NULL_INDEX);
}

Test(core, counted_allocator_tracks_live_and_peak)
{
    int64_t base = ori_alloc_live_bytes();
    ori_alloc_reset_peak();
    void *a = ori__alloc(1000);
    void *b = ori__alloc(24);
    cr_assert_eq(ori_alloc_live_count(), 2);
    cr_assert_eq(ori_alloc_live_bytes() - base, 1024);
    a = ori__realloc(a, 4000);
    cr_assert_eq(ori_alloc_live_bytes() - base, 4024);
    cr_assert_geq(ori_alloc_peak_bytes() - base, 5024); // old and new block briefly coexist
    ori__free(a);
    ori__free(b);
    cr_assert_eq(ori_alloc_live_bytes(), base);
}

Test(core, growable_array_and_arena)
{
    int *arr = NULL, n = 0, cap = 0;
    for (int i = 0; i < 10000; ++i) ORI__PUSH(arr, n, cap, i * 3);
    cr_assert_eq(n, 10000);
    cr_assert_eq(arr[9999], 29997);
    cr_assert_geq(cap, 10000);
    ori__free(arr);

    ori__arena arena;
    ori__arena_init(&arena, 256);
    double *x = ORI__ARENA_NEW(&arena, double, 10);
    double *y = ORI__ARENA_NEW(&arena, double, 1000); // larger than a block
    cr_assert_eq((uintptr_t)x % 16, 0);
    cr_assert_eq((uintptr_t)y % 16, 0);
    cr_assert_eq(y[999], 0.0);
    ori__arena_reset(&arena);
}

Test(core, rodrigues_rotation_is_orthonormal_and_right_handed)
{
    ori_v3 k = ori_v3_normalize(ori_v3_make(1, 1, 0));
    ori_m3 r = ori_m3_rotation(k, ORI_PI / 2);
    // (0,1,0) about (1,1,0)/√2 by 90° → (0.5, 0.5, 1/√2) (the thesis' end effector)
    ori_v3 p = ori_m3_apply(r, ori_v3_make(0, 1, 0));
    cr_assert_float_eq(p.x, 0.5, 4 * DBL_EPSILON);
    cr_assert_float_eq(p.y, 0.5, 4 * DBL_EPSILON);
    cr_assert_float_eq(p.z, 1 / sqrt(2.0), 4 * DBL_EPSILON);
    ori_m3 rt = ori_m3_mul(r, ori_m3_transpose(r));
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) cr_assert_float_eq(rt.m[i][j], i == j ? 1.0 : 0.0, 4 * DBL_EPSILON);
}

Test(core, twist_exponential_rotates_about_an_offset_axis)
{
    // Axis through q = (0, 1, 0) along x: the thesis' joint 2. A point on the axis is fixed;
    // (0, 2, 0) goes to (0, 1, 1) at +90° (right-hand rule).
    ori_twist xi = ori_twist_from_axis(ori_v3_make(0, 1, 0), ori_v3_make(1, 0, 0));
    ori_rigid g = ori_twist_exp(xi, ORI_PI / 2);
    ori_v3 a = ori_rigid_apply(g, ori_v3_make(5, 1, 0));
    ori_v3 b = ori_rigid_apply(g, ori_v3_make(0, 2, 0));
    cr_assert_float_eq(a.x, 5.0, 8 * DBL_EPSILON);
    cr_assert_float_eq(a.y, 1.0, 8 * DBL_EPSILON);
    cr_assert_float_eq(a.z, 0.0, 8 * DBL_EPSILON);
    cr_assert_float_eq(b.x, 0.0, 8 * DBL_EPSILON);
    cr_assert_float_eq(b.y, 1.0, 8 * DBL_EPSILON);
    cr_assert_float_eq(b.z, 1.0, 8 * DBL_EPSILON);
    // Composition with the inverse is the identity.
    ori_rigid id = ori_rigid_compose(g, ori_rigid_inverse(g));
    ori_v3 c = ori_rigid_apply(id, ori_v3_make(0.3, -2, 7));
    cr_assert_float_eq(c.y, -2.0, 16 * DBL_EPSILON);
    cr_assert_float_eq(c.z, 7.0, 16 * DBL_EPSILON);
}

Test(core, normalize_of_zero_is_zero_not_nan)
{
    ori_v3 z = ori_v3_normalize(ori_v3_make(0, 0, 0));
    cr_assert_eq(z.x, 0.0);
    cr_assert_eq(z.y, 0.0);
    cr_assert_eq(z.z, 0.0);
    ori_v2 w = ori_v2_normalize(ori_v2_make(0, 0));
    cr_assert_eq(w.x, 0.0);
    cr_assert_eq(ori_angle_ccw_v2(w, ori_v2_make(1, 0)), 0.0);
}

Test(core, orient2d_is_exact_on_nearly_collinear_points)
{
    ori_v2 a = {0.5, 0.5};
    // Points on the line y = x perturbed by one ulp: naive arithmetic loses the sign.
    for (int i = 0; i < 64; ++i) {
        double x = 0.5 + i * DBL_EPSILON;
        ori_v2 b = {12.0, 12.0}, c = {24.0, 24.0};
        ori_v2 p = {x, nextafter(x, 1.0)};
        cr_assert_eq(ori_orient2d_sign(a, b, c), 0);
        // p lies above y = x: counter-clockwise from (b → c)? orientation of (b, c, p) > 0
        cr_assert_eq(ori_orient2d_sign(b, c, p), 1, "i=%d", i);
        ori_v2 q = {x, nextafter(x, 0.0)};
        cr_assert_eq(ori_orient2d_sign(b, c, q), -1, "i=%d", i);
    }
    cr_assert_eq(ori_orient2d_sign((ori_v2){0, 0}, (ori_v2){1, 0}, (ori_v2){0, 1}), 1);
}

Test(core, angles_wrap)
{
    cr_assert_float_eq(ori_wrap_angle(3 * ORI_PI), ORI_PI, 1e-15);
    cr_assert_float_eq(ori_wrap_angle(-ORI_PI / 2 - 2 * ORI_PI), -ORI_PI / 2, 1e-14);
    cr_assert_float_eq(ori_angle_ccw_v2(ori_v2_make(1, 0), ori_v2_make(0, -1)), 1.5 * ORI_PI, 1e-15);
    cr_assert_float_eq(ori_angle_between_v3(ori_v3_make(1, 0, 0), ori_v3_make(0, 0, 2)), ORI_PI / 2, 1e-15);
}

// --- files -------------------------------------------------------------------------------------

// Entries of dir whose name contains needle.
static int count_entries(const char *dir, const char *needle)
{
    DIR *d = opendir(dir);
    cr_assert_not_null(d);
    int n = 0;
    for (struct dirent *e; (e = readdir(d));) n += strstr(e->d_name, needle) != NULL;
    closedir(d);
    return n;
}

static void write_ok(const char *path, const char *text)
{
    ori_error err;
    char msg[300];
    ori_status st = ori_file_write_atomic(path, text, strlen(text), &err);
    cr_assert_eq(st, ORI_OK, "%s: %s", path, ori_error_format(&err, msg, sizeof msg));
}

Test(core, reading_a_fifo_fails_at_once_instead_of_blocking)
{
    char *dir = test_tmpdir();
    char path[600];
    snprintf(path, sizeof path, "%s/pipe.fold", dir);
    cr_assert_eq(mkfifo(path, 0600), 0);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    char *data = NULL;
    ori_error err;
    cr_assert_eq(ori_file_read_all(path, 1000, &data, NULL, &err), ORI_ERR_IO);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    cr_assert_null(data);
    cr_assert(strstr(err.message, "FIFO"), "%s", err.message);
    cr_assert_lt((double)(t1.tv_sec - t0.tv_sec), 2.0); // (it blocked forever before)
    cr_assert_eq(ori_file_read_all(dir, 1000, &data, NULL, &err), ORI_ERR_IO);
    cr_assert(strstr(err.message, "directory"), "%s", err.message);
    test_tmpdir_remove(dir);
}

Test(core, atomic_write_refuses_devices_and_directories)
{
    char *dir = test_tmpdir();
    ori_error err;
    char path[600];
    snprintf(path, sizeof path, "%s/pipe", dir);
    cr_assert_eq(mkfifo(path, 0600), 0);
    cr_assert_eq(ori_file_write_atomic(path, "x", 1, &err), ORI_ERR_IO);
    cr_assert(strstr(err.message, "FIFO"), "%s", err.message);
    struct stat st;
    cr_assert_eq(lstat(path, &st), 0);
    cr_assert(S_ISFIFO(st.st_mode)); // still the FIFO
    cr_assert_eq(ori_file_write_atomic("/dev/null", "x", 1, &err), ORI_ERR_IO);
    cr_assert(strstr(err.message, "character device"), "%s", err.message);
    cr_assert_eq(stat("/dev/null", &st), 0);
    cr_assert(S_ISCHR(st.st_mode));
    cr_assert_eq(ori_file_write_atomic(dir, "x", 1, &err), ORI_ERR_IO);
    cr_assert(strstr(err.message, "directory"), "%s", err.message);
    // A link to a device is refused as well, naming the link's target.
    snprintf(path, sizeof path, "%s/null-link", dir);
    cr_assert_eq(symlink("/dev/null", path), 0);
    cr_assert_eq(ori_file_write_atomic(path, "x", 1, &err), ORI_ERR_IO);
    cr_assert(strstr(err.message, "the link's target is a character device"), "%s", err.message);
    cr_assert_eq(count_entries(dir, ".tmp."), 0);
    test_tmpdir_remove(dir);
}

// Contents of a small file, or "" when it does not exist.
static const char *slurp(const char *path, char *buf, size_t cap)
{
    buf[0] = '\0';
    FILE *f = fopen(path, "rb");
    if (!f) return buf;
    size_t n = fread(buf, 1, cap - 1, f);
    buf[n] = '\0';
    fclose(f);
    return buf;
}

Test(core, a_batch_writes_every_output_or_none)
{
    char *dir = test_tmpdir();
    char a[600], b[600], bad[600], buf[64];
    snprintf(a, sizeof a, "%s/a.obj", dir);
    snprintf(b, sizeof b, "%s/a.mtl", dir);
    snprintf(bad, sizeof bad, "%s/sub", dir);
    write_ok(b, "mine");
    cr_assert_eq(mkdir(bad, 0700), 0);
    // One output fails (a directory): the other, already written, is not renamed into place and
    // the user's file stays as it was.
    ori_file_batch *batch = ori_file_batch_create();
    cr_assert_null(ori_file_batch_set_current(batch));
    write_ok(b, "new mtl");
    ori_error err;
    cr_assert_eq(ori_file_write_atomic(bad, "x", 1, &err), ORI_ERR_IO);
    cr_assert_eq(ori_file_batch_count(batch), 1);
    cr_assert_str_eq(slurp(b, buf, sizeof buf), "mine");
    cr_assert_eq(count_entries(dir, ".tmp."), 1); // staged, not yet in place
    cr_assert_eq(ori_file_batch_set_current(NULL), batch);
    ori_file_batch_destroy(batch);
    cr_assert_str_eq(slurp(b, buf, sizeof buf), "mine");
    cr_assert_eq(count_entries(dir, ".tmp."), 0);
    // Every output written: all appear at commit, not before; a path written twice keeps the later.
    batch = ori_file_batch_create();
    ori_file_batch_set_current(batch);
    write_ok(a, "first");
    write_ok(a, "obj");
    write_ok(b, "mtl");
    ori_file_batch_set_current(NULL);
    cr_assert_eq(ori_file_batch_count(batch), 2);
    cr_assert_str_eq(slurp(a, buf, sizeof buf), "");
    cr_assert_str_eq(slurp(b, buf, sizeof buf), "mine");
    cr_assert_eq(ori_file_batch_commit(batch, &err), ORI_OK, "%s", err.message);
    ori_file_batch_destroy(batch);
    cr_assert_str_eq(slurp(a, buf, sizeof buf), "obj");
    cr_assert_str_eq(slurp(b, buf, sizeof buf), "mtl");
    cr_assert_eq(count_entries(dir, ".tmp."), 0);
    // A write outside a batch is in place at once.
    write_ok(a, "direct");
    cr_assert_str_eq(slurp(a, buf, sizeof buf), "direct");
    ori_file_batch_destroy(NULL);
    test_tmpdir_remove(dir);
}

Test(core, a_signal_removes_the_staged_outputs_of_a_batch)
{
    char *dir = test_tmpdir();
    char a[600];
    snprintf(a, sizeof a, "%s/a.fold", dir);
    ori_file_batch *batch = ori_file_batch_create();
    ori_file_batch_set_current(batch);
    write_ok(a, "staged");
    ori_file_batch_set_current(NULL);
    cr_assert_eq(count_entries(dir, ".tmp."), 1);
    cr_assert_eq(ori_file_remove_temporaries(), 1); // what a SIGINT handler calls
    cr_assert_eq(count_entries(dir, ".tmp."), 0);
    ori_file_batch_destroy(batch);
    test_tmpdir_remove(dir);
}

Test(core, atomic_write_goes_through_symbolic_links)
{
    char *dir = test_tmpdir();
    char target[600], link1[600], link2[600];
    snprintf(target, sizeof target, "%s/real.fold", dir);
    snprintf(link1, sizeof link1, "%s/link1.fold", dir);
    snprintf(link2, sizeof link2, "%s/link2.fold", dir);
    write_ok(target, "old");
    cr_assert_eq(symlink("real.fold", link1), 0); // relative to the link's directory
    cr_assert_eq(symlink(link1, link2), 0);       // a chain, absolute
    write_ok(link2, "new text");
    struct stat st;
    cr_assert_eq(lstat(link1, &st), 0);
    cr_assert(S_ISLNK(st.st_mode));
    cr_assert_eq(lstat(link2, &st), 0);
    cr_assert(S_ISLNK(st.st_mode));
    char *text = test_read_text(target);
    cr_assert_str_eq(text, "new text");
    free(text);
    // A dangling link creates its target, like a shell redirection.
    snprintf(link1, sizeof link1, "%s/dangling.fold", dir);
    cr_assert_eq(symlink("created.fold", link1), 0);
    write_ok(link1, "made");
    snprintf(target, sizeof target, "%s/created.fold", dir);
    text = test_read_text(target);
    cr_assert_str_eq(text, "made");
    free(text);
    // A loop is an error, not a hang.
    snprintf(link1, sizeof link1, "%s/loop-a", dir);
    snprintf(link2, sizeof link2, "%s/loop-b", dir);
    cr_assert_eq(symlink("loop-b", link1), 0);
    cr_assert_eq(symlink("loop-a", link2), 0);
    ori_error err;
    cr_assert_eq(ori_file_write_atomic(link1, "x", 1, &err), ORI_ERR_IO);
    cr_assert(strstr(err.message, "symbolic links"), "%s", err.message);
    cr_assert_eq(count_entries(dir, ".tmp."), 0);
    test_tmpdir_remove(dir);
}

Test(core, atomic_write_keeps_the_mode_and_refuses_read_only_files)
{
    char *dir = test_tmpdir();
    char path[600];
    snprintf(path, sizeof path, "%s/private.fold", dir);
    write_ok(path, "a");
    cr_assert_eq(chmod(path, 0600), 0);
    write_ok(path, "b");
    struct stat st;
    cr_assert_eq(stat(path, &st), 0);
    cr_assert_eq(st.st_mode & 07777, 0600);
    cr_assert_eq(chmod(path, 0640), 0);
    write_ok(path, "c");
    cr_assert_eq(stat(path, &st), 0);
    cr_assert_eq(st.st_mode & 07777, 0640);
    // A new file: 0666 less the umask.
    mode_t mask = umask(022);
    snprintf(path, sizeof path, "%s/new.fold", dir);
    write_ok(path, "n");
    umask(mask);
    cr_assert_eq(stat(path, &st), 0);
    cr_assert_eq(st.st_mode & 07777, 0644);
    // Read-only: refused like `>` would be; root may write it, and the mode stays 0444.
    snprintf(path, sizeof path, "%s/readonly.fold", dir);
    write_ok(path, "r");
    cr_assert_eq(chmod(path, 0444), 0);
    ori_error err;
    ori_status s = ori_file_write_atomic(path, "w", 1, &err);
    char *text = test_read_text(path);
    if (geteuid() != 0) {
        cr_assert_eq(s, ORI_ERR_IO);
        cr_assert(strstr(err.message, "not writable"), "%s", err.message);
        cr_assert_str_eq(text, "r");
    } else {
        cr_assert_eq(s, ORI_OK);
        cr_assert_str_eq(text, "w");
    }
    free(text);
    cr_assert_eq(stat(path, &st), 0);
    cr_assert_eq(st.st_mode & 07777, 0444);
    cr_assert_eq(count_entries(dir, ".tmp."), 0);
    test_tmpdir_remove(dir);
}

Test(core, atomic_write_handles_names_at_the_length_limit)
{
    char *dir = test_tmpdir();
    long name_max = pathconf(dir, _PC_NAME_MAX);
    cr_assert_gt(name_max, 20);
    for (long len = name_max - 12; len <= name_max; len += 4) {
        char path[1200];
        int n = snprintf(path, sizeof path, "%s/", dir);
        for (long k = 0; k < len - 5; ++k) path[n++] = (char)('a' + k % 26);
        snprintf(path + n, sizeof path - (size_t)n, ".fold");
        write_ok(path, "long");
        char *text = test_read_text(path);
        cr_assert_str_eq(text, "long", "name of %ld bytes", len);
        free(text);
        write_ok(path, "again"); // replacing works as well
        cr_assert_eq(unlink(path), 0);
    }
    cr_assert_eq(count_entries(dir, ".tmp."), 0);
    test_tmpdir_remove(dir);
}

// A write interrupted by a signal: the file size limit raises SIGXFSZ in the middle of writing
// the temporary file, whose handler removes the temporaries (as the CLI's SIGINT/SIGTERM handler
// does) and exits. Nothing is left: no output, no temporary file.
static void on_xfsz(int sig)
{
    (void)sig;
    int removed = ori_file_remove_temporaries();
    _exit(removed == 1 ? 42 : 43);
}

Test(core, a_write_killed_by_a_signal_leaves_no_temporary_file)
{
    char *dir = test_tmpdir();
    char path[600];
    snprintf(path, sizeof path, "%s/out.fold", dir);
    fflush(NULL);
    pid_t pid = fork();
    cr_assert_geq(pid, 0);
    if (pid == 0) {
        signal(SIGXFSZ, on_xfsz);
        struct rlimit rl = {4096, 4096};
        setrlimit(RLIMIT_FSIZE, &rl);
        static char big[65536];
        memset(big, 'x', sizeof big);
        ori_file_write_atomic(path, big, sizeof big, NULL);
        _exit(44); // the signal did not come
    }
    int status = 0;
    cr_assert_eq(waitpid(pid, &status, 0), pid);
    cr_assert(WIFEXITED(status));
    cr_assert_eq(WEXITSTATUS(status), 42, "child exit %d (43: nothing removed, 44: no signal)", WEXITSTATUS(status));
    cr_assert_eq(count_entries(dir, "out.fold"), 0);
    // Nothing tracked is left over in this process either.
    cr_assert_eq(ori_file_remove_temporaries(), 0);
    test_tmpdir_remove(dir);
}

// Library messages print %g values exactly enough to read back (within a few ulps): a value
// just inside or outside a bound is never shown rounded onto it.
static ori_status fail_with(ori_error *e, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static ori_status fail_with(ori_error *e, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    ori__vformat(e->message, sizeof e->message, fmt, ap);
    va_end(ap);
    return ORI_ERR_RANGE;
}

Test(core, messages_print_g_values_that_read_back)
{
    ori_error e;
    ori__fail(&e, ORI_ERR_RANGE, "%g° is outside (%g°, %g°)", 89.9999999, 0.0, 90.0);
    cr_assert_str_eq(e.message, "89.9999999° is outside (0°, 90°)");
    ori__fail_at(&e, ORI_ERR_RANGE, "edges_foldAngle", 3, "fold angle %g is outside [-180, 180]", -180.00000000286695);
    cr_assert_str_eq(e.message, "fold angle -180.000000002867 is outside [-180, 180]");
    cr_assert_eq(e.element, 3);
    // A bound computed in radians shows as the round number it is within a few ulps of.
    ori__fail(&e, ORI_ERR_RANGE, "outside (0°, %g°]", ori_rad_to_deg(ORI_PI / 3));
    cr_assert_str_eq(e.message, "outside (0°, 60°]");
    // Values that %g shows exactly stay short; other conversions are untouched.
    fail_with(&e, "%g %.3g %d %s %5.1f %lld %zu %c %% %x %*g|%-8g|", 0.5, 1.0 / 3.0, -7, "str", 2.25, -5LL, (size_t)9, 'q',
              255u, 6, 1.5, 2.0);
    cr_assert_str_eq(e.message, "0.5 0.333 -7 str   2.2 -5 9 q % ff    1.5|2       |");
    volatile double big = 1e308;
    fail_with(&e, "%g, %g and %g", 0.1 + 1e-12, 0.1 + 0.2, big * 10);
    cr_assert_str_eq(e.message, "0.100000000001, 0.3 and inf"); // (0.1 + 0.2 is one ulp from 0.3)
    // Truncation at the buffer's size is safe and terminated.
    char text[300];
    memset(text, 'y', sizeof text - 1);
    text[sizeof text - 1] = '\0';
    ori__fail(&e, ORI_ERR_RANGE, "%s %g", text, 1.25);
    cr_assert_eq(strlen(e.message), sizeof e.message - 1);
}
