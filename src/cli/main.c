/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve: project curves onto B-spline/NURBS surfaces from the command
 * line. See docs/cli.md.
 */
#include <stdio.h>
#include <string.h>

#include "cli.h"

static void usage(FILE *out)
{
    fputs("usage: projcurve COMMAND [ARGS]\n"
          "\n"
          "Projects curves onto B-spline/NURBS surfaces (libprojcurve " PROJCURVE_VERSION_STRING
          ").\n"
          "\n"
          "commands:\n"
          "  demo [-o DIR]     project the paper's Example 1 and a freeform case;\n"
          "                    write IGES, SVG and JSON to DIR (default build-demo/demo)\n"
          "  info FILE         list the surfaces and curves of a file (sizes, boxes),\n"
          "                    its faces and the entities it skipped\n"
          "  project FILE...   project every curve onto every surface of the files, or\n"
          "                    the pairs --surface / --curve pick, or a curve given by\n"
          "                    --line / --points\n"
          "\n"
          "Run 'projcurve COMMAND --help' for the options of a command.\n"
          "Files: IGES 5.3, STEP (ISO 10303-21), G+Smo XML, Newell teapot text.\n"
          "Exit codes: 0 ok, 1 a projection failed, 2 bad usage or unreadable input,\n"
          "3 a projection stopped by project --timeout.\n",
          out);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return CLI_EXIT_USAGE;
    }
    const char *cmd = argv[1];
    if (cli_is_help(cmd)) {
        usage(stdout);
        return CLI_EXIT_OK;
    }
    if (strcmp(cmd, "--version") == 0) {
        printf("projcurve %s\n", projcurve_version_string());
        return CLI_EXIT_OK;
    }
    if (strcmp(cmd, "demo") == 0)
        return cli_cmd_demo(argc - 1, argv + 1);
    if (strcmp(cmd, "info") == 0)
        return cli_cmd_info(argc - 1, argv + 1);
    if (strcmp(cmd, "project") == 0)
        return cli_cmd_project(argc - 1, argv + 1);
    usage(stderr);
    return cli_usage_error("unknown command '%s'", cmd);
}
