// Authoring through the CLI: examples/open-corner.sh reproduces the committed open corner,
// bad input writes nothing, face names survive a chain of commands.
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

#include "support.h"

TestSuite(authoring_cli, .init = test_leak_setup, .fini = test_leak_check);

static bool exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

Test(authoring_cli, open_corner_script_reproduces_the_committed_file)
{
    char *dir = test_tmpdir();
    char cmd[4096], out[2048];
    snprintf(out, sizeof out, "%s/open-corner.fold", dir);
    snprintf(cmd, sizeof cmd, "sh '%s' '%s' '%s' > /dev/null", test_repo_path("examples/open-corner.sh"), ORI_CLI_PATH,
             out);
    cr_assert_eq(system(cmd), 0, "%s", cmd);
    char *made = test_read_text(out);
    char *committed = test_read_text(test_repo_path("examples/patterns/open-corner.fold"));
    cr_assert_not_null(made);
    cr_assert_not_null(committed);
    cr_assert_str_eq(made, committed, "examples/open-corner.sh no longer reproduces examples/patterns/open-corner.fold");
    free(made);
    free(committed);
    test_tmpdir_remove(dir);
}

Test(authoring_cli, failing_commands_write_nothing)
{
    char *dir = test_tmpdir();
    char args[4096], out[2048];
    snprintf(out, sizeof out, "%s/out.fold", dir);
    // (values out of range for the file, or for what they construct, are usage errors: 2)
    const struct {
        const char *args;
        int rc;
    } bad[] = {
        {"crease examples/patterns/open-corner.fold --line 0,3,1,3 --all -o '%s'", 2},
        {"crease examples/patterns/open-corner.fold --line 0,0,1,1 --face Obj9 -o '%s'", 2},
        {"edit examples/patterns/open-corner.fold --assign 6=V --remove 0 -o '%s'", 2},
        {"apply examples/patterns/open-corner.fold --pattern tests/data/bad-composite.json --face Obj111 -o '%s'", 3},
        {"new --polygon 0,0,1,1,1,0,0,1 -o '%s'", 2},
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; ++i) {
        snprintf(args, sizeof args, bad[i].args, out);
        char *output = NULL;
        int rc = test_run_cli(args, &output);
        cr_assert_eq(rc, bad[i].rc, "%s: exit %d: %s", args, rc, output ? output : "");
        cr_assert(strchr(output, '\n') == strrchr(output, '\n'), "one-line error: %s", output);
        free(output);
        cr_assert(!exists(out), "%s wrote %s", args, out);
    }
    test_tmpdir_remove(dir);
}

Test(authoring_cli, names_follow_a_chain_of_commands)
{
    char *dir = test_tmpdir();
    char args[4096];
    char *output = NULL;
    snprintf(args, sizeof args,
             "new --rect 4 2 -o '%s/a.fold' && '%s' apply '%s/a.fold' --pattern middle-v --face Obj1 -o '%s/b.fold' && "
             "'%s' crease '%s/b.fold' --axiom 1 --p1 0,0 --p2 2,2 --face Obj11 --assign V -o '%s/c.fold' && "
             "'%s' edit '%s/c.fold' --flip @1,1 -o '%s/d.fold' && '%s' tree '%s/d.fold' --json",
             dir, ORI_CLI_PATH, dir, dir, ORI_CLI_PATH, dir, dir, ORI_CLI_PATH, dir, dir, ORI_CLI_PATH, dir);
    int rc = test_run_cli(args, &output);
    cr_assert_eq(rc, 0, "%s", output);
    // middle-v on a 4 × 2 sheet: Obj11 is the left half; the diagonal splits it in two.
    cr_assert(strstr(output, "{\"name\":\"Obj111\",\"parent\":1,\"children\":[],\"leaf\":true,\"face\":0}") != NULL, "%s",
              output);
    cr_assert(strstr(output, "\"folding_elements\":[{\"face\":0,\"name\":\"Obj111\"},{\"face\":1,\"name\":\"Obj12\"},"
                             "{\"face\":2,\"name\":\"Obj112\"}]") != NULL,
              "%s", output);
    free(output);
    // The flip made the diagonal a mountain.
    snprintf(args, sizeof args, "info '%s/d.fold' --json", dir);
    rc = test_run_cli(args, &output);
    cr_assert_eq(rc, 0);
    cr_assert(strstr(output, "\"M\":1") != NULL, "%s", output);
    cr_assert(strstr(output, "\"V\":0") != NULL, "%s", output);
    free(output);
    test_tmpdir_remove(dir);
}

Test(authoring_cli, edit_tracks_indices_across_removals)
{
    char *dir = test_tmpdir();
    char args[4096];
    char *output = NULL;
    // Remove the diagonal (12), then flip edge 11 of the input file (still 11), then remove 8
    // (the right half of the horizontal crease) which rejoins the right boundary; edge 10 of
    // the input is then edge 8.
    snprintf(args, sizeof args,
             "edit examples/patterns/open-corner.fold --remove 12 --flip 11 --remove 8 --flip 6 -o '%s/e.fold'", dir);
    int rc = test_run_cli(args, &output);
    cr_assert_eq(rc, 0, "%s", output);
    cr_assert(strstr(output, "removed edge 12: Obj1211 + Obj1212 -> Obj121 (name restored)") != NULL, "%s", output);
    cr_assert(strstr(output, "edge 11: V -> M (flipped)") != NULL, "%s", output);
    cr_assert(strstr(output, "edge 6 (now 5): M -> V (flipped)") != NULL, "%s", output);
    free(output);
    test_tmpdir_remove(dir);
}
