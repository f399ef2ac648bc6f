/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve-bench: benchmarks of libprojcurve, one subcommand per question
 * (see bench/README.md).
 *
 *   projcurve-bench <command> [--json FILE] [--svg FILE] [--quick] [--data DIR]
 *   projcurve-bench all --out DIR [--quick] [--data DIR]
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#ifndef PCB_TEST_DATA_DIR
#define PCB_TEST_DATA_DIR "tests/data"
#endif

/* Exit codes (see bench.h). */
#define PCB_EXIT_USAGE 2

typedef int (*pcb_command_fn)(const pcb_args *args);

typedef struct pcb_command {
    const char *name;
    pcb_command_fn run;
    const char *help;
} pcb_command;

static const pcb_command commands[] = {
    {"eval", pcb_cmd_eval, "ns per bicubic evaluation with 2nd derivatives, per closest point"},
    {"rays", pcb_cmd_rays, "us per ray on surfaces of 1, 100 and 10,000 patches"},
    {"table1", pcb_cmd_table1, "the paper's Table 1: RK4 vs second-order tracing on Example 1"},
    {"cases", pcb_cmd_cases, "every test case: time, branches, pieces, measured deviation"},
    {"scaling", pcb_cmd_scaling, "time against 1/eps_D, patches and curve length"},
    {"shape", pcb_cmd_shape, "curves onto whole models, ours vs BRepProj_Projection"},
    {"profile", pcb_cmd_profile, "CPU time of each case by stage, at eps_D and at Open CASCADE's"},
    {"brep", pcb_cmd_brep, "read + build of each real model, face classification ns per point"},
#ifdef PCB_HAVE_OCCT
    {"occt", pcb_cmd_occt, "the cases through Open CASCADE, side by side"},
#endif
};
#define N_COMMANDS (sizeof commands / sizeof commands[0])

static void usage(FILE *f)
{
    fputs("usage: projcurve-bench <command> [--json FILE] [--svg FILE] [--quick] "
          "[--data DIR]\n"
          "       projcurve-bench profile [--from FILE] [--case NAME] [--pcurve-degree 1|3]\n"
          "       projcurve-bench all --out DIR [--quick] [--data DIR]\n"
          "commands:\n",
          f);
    for (size_t i = 0; i < N_COMMANDS; ++i)
        fprintf(f, "  %-8s %s\n", commands[i].name, commands[i].help);
    fputs("  all      every command, writing DIR/<command>.json and .svg\n", f);
#ifndef PCB_HAVE_OCCT
    fputs("(occt: not built, Open CASCADE was not found at configure time)\n", f);
#endif
}

/* Parses the options after the command name; returns 0 or -1. */
static int parse_options(int argc, char **argv, pcb_args *args, const char **out_dir)
{
    for (int i = 2; i < argc; ++i) {
        const char *opt = argv[i];
        const int has_value = i + 1 < argc;
        if (!strcmp(opt, "--quick")) {
            args->quick = 1;
        } else if (!strcmp(opt, "--json") && has_value) {
            args->json_path = argv[++i];
        } else if (!strcmp(opt, "--svg") && has_value) {
            args->svg_path = argv[++i];
        } else if ((!strcmp(opt, "--data") || !strcmp(opt, "--shared")) && has_value) {
            args->data_dir = argv[++i];
        } else if (!strcmp(opt, "--pcurve-degree") && has_value) {
            args->pcurve_degree = atoi(argv[++i]);
        } else if (!strcmp(opt, "--case") && has_value) {
            args->only_case = argv[++i];
        } else if (!strcmp(opt, "--from") && has_value) {
            args->from_path = argv[++i];
        } else if (!strcmp(opt, "--out") && has_value) {
            *out_dir = argv[++i];
        } else {
            fprintf(stderr, "projcurve-bench: unknown or incomplete option '%s'\n", opt);
            return -1;
        }
    }
    return 0;
}

/* Runs every command; the worst exit code wins. */
static int run_all(const pcb_args *base, const char *out_dir)
{
    int worst = 0;
    for (size_t i = 0; i < N_COMMANDS; ++i) {
        char json[1024], svg[1024], name[64];
        snprintf(name, sizeof name, "%s.json", commands[i].name);
        pcb_join_path(json, sizeof json, out_dir, name);
        snprintf(name, sizeof name, "%s.svg", commands[i].name);
        pcb_join_path(svg, sizeof svg, out_dir, name);
        pcb_args args = *base;
        args.json_path = json;
        args.svg_path = svg;
        const int rc = commands[i].run(&args);
        if (rc > worst)
            worst = rc;
        fflush(stdout);
    }
    return worst;
}

int main(int argc, char **argv)
{
    if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
        usage(argc < 2 ? stderr : stdout);
        return argc < 2 ? PCB_EXIT_USAGE : 0;
    }
    /* The same override as the tests: $PROJCURVE_TEST_DATA_DIR, then --data
     * (--shared is its former spelling). */
    const char *data = getenv("PROJCURVE_TEST_DATA_DIR");
    pcb_args args = {NULL, NULL, data && data[0] ? data : PCB_TEST_DATA_DIR, 0, NULL, NULL, 0};
    const char *out_dir = NULL;
    if (parse_options(argc, argv, &args, &out_dir) != 0) {
        usage(stderr);
        return PCB_EXIT_USAGE;
    }
    if (!strcmp(argv[1], "all")) {
        if (!out_dir) {
            fputs("projcurve-bench all: --out DIR is required\n", stderr);
            return PCB_EXIT_USAGE;
        }
        return run_all(&args, out_dir);
    }
    for (size_t i = 0; i < N_COMMANDS; ++i)
        if (!strcmp(argv[1], commands[i].name))
            return commands[i].run(&args);
    fprintf(stderr, "projcurve-bench: unknown command '%s'\n", argv[1]);
    usage(stderr);
    return PCB_EXIT_USAGE;
}
