// The dispatch of the orikin command line (cli_main): the command table, generated from the
// cli/cmd_<name>.c files, help, and the staged outputs of a command. main.c adds the process
// set-up; the fuzz target fuzz_cli_args calls cli_main in-process.
#include <string.h>

#include "cli.h"

#define ORI_CLI_COMMAND(id) extern const cli_command cli_cmd_##id;
#include "commands.inc"
#undef ORI_CLI_COMMAND

static const cli_command *const commands[] = {
#define ORI_CLI_COMMAND(id) &cli_cmd_##id,
#include "commands.inc"
#undef ORI_CLI_COMMAND
};
static const int command_count = (int)(sizeof commands / sizeof commands[0]);

static const cli_command *find_command(const char *name)
{
    for (int i = 0; i < command_count; ++i)
        if (strcmp(commands[i]->name, name) == 0) return commands[i];
    return NULL;
}

static void print_overview(FILE *out)
{
    fprintf(out,
            "usage: orikin <command> [options]\n"
            "\n"
            "orikin designs, verifies and simulates folding structures: crease patterns as\n"
            "closed-loop rigid multibody systems (faces = bodies, creases = revolute joints).\n"
            "Files are FOLD (JSON); angles are degrees, positive = valley, negative = mountain.\n"
            "\n"
            "commands:\n");
    for (int i = 0; i < command_count; ++i)
        fprintf(out, "  %-10s %s\n", commands[i]->name, commands[i]->summary);
    fprintf(out,
            "\n"
            "  help CMD   the help of one command (same as orikin CMD -h)\n"
            "\n"
            "exit codes: 0 ok, 1 checked and negative, 2 usage, 3 bad input, 4 internal, 5 stopped at a\n"
            "budget (--limit, --timeout): a partial answer\n"
            "example: orikin check examples/patterns/open-corner.fold\n");
}

int cli_main(int argc, char **argv)
{
    if (argc < 2) {
        print_overview(stderr);
        return CLI_EXIT_USAGE;
    }
    const char *name = argv[1];
    if (cli_is_help(name)) {
        print_overview(stdout);
        return cli_finish(CLI_EXIT_OK);
    }
    if (strcmp(name, "--version") == 0) {
        printf("orikin %s\n", ori_version_string());
        return cli_finish(CLI_EXIT_OK);
    }
    if (strcmp(name, "help") == 0) {
        if (argc < 3) {
            print_overview(stdout);
            return cli_finish(CLI_EXIT_OK);
        }
        const cli_command *cmd = find_command(argv[2]);
        if (!cmd) {
            fprintf(stderr, "orikin: unknown command '%s'; try 'orikin -h'\n", argv[2]);
            return CLI_EXIT_USAGE;
        }
        return cli_finish(cli_print_help(cmd));
    }
    const cli_command *cmd = find_command(name);
    if (!cmd) {
        fprintf(stderr, "orikin: unknown command '%s'; try 'orikin -h'\n", name);
        return CLI_EXIT_USAGE;
    }
    cli_set_command(cmd->name);
    for (int i = 2; i < argc; ++i)
        if (cli_is_help(argv[i])) return cli_finish(cli_print_help(cmd));
    // The studio saves as it serves: its writes land at once.
    if (cmd == &cli_cmd_view) return cli_finish(cmd->run(argc - 1, argv + 1));
    // A command's outputs land together: every file the library writes for it is staged and
    // renamed into place only when the command succeeds (or answers "no" with its outputs:
    // a blocked fold's partial motion, a partial count), so a failure halfway through leaves
    // every earlier output as it was.
    ori_file_batch *batch = ori_file_batch_create();
    ori_file_batch_set_current(batch);
    int rc = cmd->run(argc - 1, argv + 1);
    ori_file_batch_set_current(NULL);
    if (rc == CLI_EXIT_OK || rc == CLI_EXIT_NEGATIVE || rc == CLI_EXIT_PARTIAL) {
        ori_error err;
        if (ori_file_batch_commit(batch, &err) != ORI_OK) {
            fprintf(stderr, "orikin %s: %s\n", cmd->name, err.message);
            rc = CLI_EXIT_INPUT;
        }
    }
    ori_file_batch_destroy(batch);
    return cli_finish(rc);
}
