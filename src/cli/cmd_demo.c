/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve demo [-o DIR]: the paper's Example 1 and a freeform case,
 * written as DIR/example1.{igs,svg,json} and DIR/freeform.{igs,svg,json};
 * DIR is DEMO_DEFAULT_DIR unless -o says otherwise (the folder ./run-demo.sh
 * writes to, when run from the source directory).
 */
#include <stdio.h>
#include <string.h>

#include "cli.h"

#define DEMO_DEFAULT_DIR "build-demo/demo"

static void demo_usage(FILE *out)
{
    fputs("usage: projcurve demo [-o DIR]\n"
          "\n"
          "Projects [SY13]'s Example 1 (a degree 5x1 sheet, a cubic curve, direction\n"
          "(-1,0,0)) and a freeform case (a bicubic wave, an S-shaped cubic, direction\n"
          "(0,0,-1)); writes example1.igs/.svg/.json and freeform.igs/.svg/.json to DIR\n"
          "(created with its parents; default: " DEMO_DEFAULT_DIR ") and prints a summary\n"
          "of each.\n",
          out);
}

typedef int (*demo_shape_fn)(projcurve_context *, projcurve_surface **, projcurve_curve **);

static int run_case(projcurve_context *ctx, const char *dir, const char *name, const char *title,
                    demo_shape_fn make, const double direction[3])
{
    projcurve_surface *s = NULL;
    projcurve_curve *c = NULL;
    if (!make(ctx, &s, &c)) {
        fprintf(stderr, "projcurve: building %s: %s\n", name, projcurve_context_message(ctx));
        return CLI_EXIT_PROJECTION;
    }
    const projcurve_surface *surfaces[1] = {s};
    const projcurve_curve *curves[1] = {c};
    cli_job job;
    memset(&job, 0, sizeof job);
    job.surfaces = surfaces;
    job.n_surfaces = 1;
    job.curves = curves;
    job.n_curves = 1;
    memcpy(job.dir, direction, sizeof job.dir);
    int code = CLI_EXIT_OK;
    if (!cli_run(ctx, &job)) {
        code = cli_usage_error("out of memory");
    } else {
        printf("%s: ", title);
        const size_t unmeasured = cli_print_summary(ctx, &job, stdout);
        char path[4096];
        int ok = 1;
        snprintf(path, sizeof path, "%s/%s.igs", dir, name);
        ok &= cli_write_iges(ctx, &job, path);
        snprintf(path, sizeof path, "%s/%s.json", dir, name);
        ok &= cli_write_json(ctx, &job, path);
        snprintf(path, sizeof path, "%s/%s.svg", dir, name);
        ok &= cli_write_svg(ctx, &job, title, path);
        if (!ok)
            code = CLI_EXIT_USAGE;
        else if (job.failures || unmeasured)
            code = CLI_EXIT_PROJECTION;
        else
            printf("  wrote %s/%s.igs, .json, .svg\n", dir, name);
    }
    cli_job_free(&job);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    return code;
}

int cli_cmd_demo(int argc, char **argv)
{
    const char *dir = DEMO_DEFAULT_DIR;
    for (int i = 1; i < argc; ++i) {
        if (cli_is_help(argv[i])) {
            demo_usage(stdout);
            return CLI_EXIT_OK;
        }
        if (strcmp(argv[i], "-o") == 0 && i + 1 < argc) {
            dir = argv[++i];
        } else {
            demo_usage(stderr);
            return cli_usage_error("unexpected argument '%s'", argv[i]);
        }
    }
    if (!cli_make_dirs(dir))
        return cli_usage_error("cannot create the directory %s", dir);
    projcurve_context *ctx = NULL;
    if (projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx) != PROJCURVE_OK)
        return cli_usage_error("cannot create a context");
    static const double example1_dir[3] = {-1.0, 0.0, 0.0}, freeform_dir[3] = {0.0, 0.0, -1.0};
    int code = run_case(ctx, dir, "example1", "Song and Yong's Example 1: projection along (-1, 0, 0)",
                        cli_demo_example1, example1_dir);
    const int code2 = run_case(ctx, dir, "freeform", "A bicubic wave: projection along (0, 0, -1)",
                               cli_demo_freeform, freeform_dir);
    projcurve_context_destroy(ctx);
    return code != CLI_EXIT_OK ? code : code2;
}
