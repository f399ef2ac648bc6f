/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve project FILE... (--dir X,Y,Z | --orthogonal) [--tol D]
 *   [--angle DEG] [--pcurve-degree 1|3] [--timeout S] [-o OUT.igs] [--svg OUT.svg]
 *   [--json OUT.json]
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

static void project_usage(FILE *out)
{
    fputs("usage: projcurve project FILE... (--dir X,Y,Z | --orthogonal) [--tol D]\n"
          "                         [--angle DEG] [--pcurve-degree 1|3] [--timeout S]\n"
          "                         [-o OUT.igs] [--svg OUT.svg] [--json OUT.json]\n"
          "\n"
          "Projects every curve of the files onto every surface of the files.\n"
          "\n"
          "  --dir X,Y,Z     directional projection along (X, Y, Z)\n"
          "  --orthogonal    orthogonal projection (foot points)\n"
          "  --tol D         distance tolerance eps_D in model units (default: 1e-4 of\n"
          "                  the surface size)\n"
          "  --angle DEG     joint angle tolerance eps_T in degrees (default 1)\n"
          "  --pcurve-degree N  pieces' (u, v) curves: 1 straight (default), 3 cubic\n"
          "                  Hermite (far fewer pieces at tight eps_D)\n"
          "  --timeout S     stop each (curve, surface) projection after S seconds of\n"
          "                  wall time, keeping what it made (0: no limit, default)\n"
          "  -o OUT.igs      write surfaces, curves and branches as IGES 5.3\n"
          "                  (as STEP AP214 when OUT ends in .step or .stp)\n"
          "  --svg OUT.svg   write a picture\n"
          "  --json OUT.json write the branches as JSON (see docs/cli.md)\n"
          "\n"
          "Exit codes: 0 ok, 1 a projection failed, 2 bad usage or unreadable input.\n",
          out);
}

typedef struct project_args {
    char **files;
    size_t n_files;
    int have_dir, orthogonal;
    double dir[3];
    double tol, angle, pcurve_degree, timeout;
    int have_tol, have_angle, have_pcurve_degree, have_timeout;
    const char *iges, *svg, *json;
} project_args;

/* The value following option argv[*i]; NULL (after a message) if missing. */
static const char *value_of(int argc, char **argv, int *i)
{
    if (*i + 1 >= argc) {
        cli_usage_error("%s needs a value", argv[*i]);
        return NULL;
    }
    return argv[++*i];
}

static int parse(int argc, char **argv, project_args *a)
{
    a->files = calloc((size_t)argc, sizeof *a->files);
    if (a->files == NULL)
        return cli_usage_error("out of memory");
    for (int i = 1; i < argc; ++i) {
        const char *arg = argv[i], *v = NULL;
        if (strcmp(arg, "--dir") == 0) {
            if ((v = value_of(argc, argv, &i)) == NULL)
                return CLI_EXIT_USAGE;
            if (!cli_parse_vec3(v, a->dir))
                return cli_usage_error("--dir wants X,Y,Z, got '%s'", v);
            a->have_dir = 1;
        } else if (strcmp(arg, "--orthogonal") == 0) {
            a->orthogonal = 1;
        } else if (strcmp(arg, "--tol") == 0 || strcmp(arg, "--angle") == 0) {
            if ((v = value_of(argc, argv, &i)) == NULL)
                return CLI_EXIT_USAGE;
            double *target = arg[2] == 't' ? &a->tol : &a->angle;
            if (!cli_parse_double(v, target))
                return cli_usage_error("%s wants a number, got '%s'", arg, v);
            *(arg[2] == 't' ? &a->have_tol : &a->have_angle) = 1;
        } else if (strcmp(arg, "--timeout") == 0) {
            if ((v = value_of(argc, argv, &i)) == NULL)
                return CLI_EXIT_USAGE;
            if (!cli_parse_double(v, &a->timeout))
                return cli_usage_error("%s wants a number of seconds, got '%s'", arg, v);
            a->have_timeout = 1;
        } else if (strcmp(arg, "--pcurve-degree") == 0) {
            if ((v = value_of(argc, argv, &i)) == NULL)
                return CLI_EXIT_USAGE;
            if (!cli_parse_double(v, &a->pcurve_degree) ||
                a->pcurve_degree != floor(a->pcurve_degree) || fabs(a->pcurve_degree) > 1e9)
                return cli_usage_error("%s wants an integer, got '%s'", arg, v);
            a->have_pcurve_degree = 1;
        } else if (strcmp(arg, "-o") == 0 || strcmp(arg, "--svg") == 0 ||
                   strcmp(arg, "--json") == 0) {
            if ((v = value_of(argc, argv, &i)) == NULL)
                return CLI_EXIT_USAGE;
            *(arg[1] == 'o' ? &a->iges : arg[2] == 's' ? &a->svg : &a->json) = v;
        } else if (arg[0] == '-' && arg[1] != '\0') {
            return cli_usage_error("unknown option '%s' (see projcurve project --help)", arg);
        } else {
            a->files[a->n_files++] = argv[i];
        }
    }
    if (a->n_files == 0)
        return cli_usage_error("project needs at least one file");
    if (a->have_dir == a->orthogonal)
        return cli_usage_error("give exactly one of --dir X,Y,Z and --orthogonal");
    return CLI_EXIT_OK;
}

/* Options from the arguments; a rejected value is a usage error. */
static int make_options(projcurve_context *ctx, const project_args *a, projcurve_options **opts)
{
    if (projcurve_options_create(ctx, opts) != PROJCURVE_OK)
        return cli_usage_error("%s", projcurve_context_message(ctx));
    if (a->have_tol &&
        projcurve_options_set_double(ctx, *opts, PROJCURVE_OPT_TOL_DISTANCE, a->tol) != PROJCURVE_OK)
        return cli_usage_error("--tol: %s", projcurve_context_message(ctx));
    if (a->have_angle && projcurve_options_set_double(ctx, *opts, PROJCURVE_OPT_TOL_ANGLE_DEG,
                                                      a->angle) != PROJCURVE_OK)
        return cli_usage_error("--angle: %s", projcurve_context_message(ctx));
    if (a->have_pcurve_degree &&
        projcurve_options_set_int(ctx, *opts, PROJCURVE_OPT_PCURVE_DEGREE,
                                  (long long)a->pcurve_degree) != PROJCURVE_OK)
        return cli_usage_error("--pcurve-degree: %s", projcurve_context_message(ctx));
    if (a->have_timeout && projcurve_options_set_double(ctx, *opts, PROJCURVE_OPT_TIME_LIMIT,
                                                        a->timeout) != PROJCURVE_OK)
        return cli_usage_error("--timeout: %s", projcurve_context_message(ctx));
    return CLI_EXIT_OK;
}

/* Runs the job and writes the requested outputs; the exit code. */
static int run_and_write(projcurve_context *ctx, cli_job *job, const project_args *a,
                         const char *title)
{
    if (!cli_run(ctx, job))
        return cli_usage_error("out of memory");
    const size_t unmeasured = cli_print_summary(ctx, job, stdout);
    int ok = 1;
    if (a->iges)
        ok &= cli_is_step_path(a->iges) ? cli_write_step(ctx, job, a->iges)
                                        : cli_write_iges(ctx, job, a->iges);
    if (a->json)
        ok &= cli_write_json(ctx, job, a->json);
    if (a->svg)
        ok &= cli_write_svg(ctx, job, title, a->svg);
    if (!ok)
        return CLI_EXIT_USAGE;
    return job->failures || unmeasured ? CLI_EXIT_PROJECTION : CLI_EXIT_OK;
}

int cli_cmd_project(int argc, char **argv)
{
    for (int i = 1; i < argc; ++i)
        if (cli_is_help(argv[i])) {
            project_usage(stdout);
            return CLI_EXIT_OK;
        }
    project_args a;
    memset(&a, 0, sizeof a);
    int code = parse(argc, argv, &a);
    if (code != CLI_EXIT_OK) {
        free(a.files);
        return code;
    }
    projcurve_context *ctx = NULL;
    projcurve_options *opts = NULL;
    cli_inputs in;
    memset(&in, 0, sizeof in);
    cli_job job;
    memset(&job, 0, sizeof job);
    if (projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx) != PROJCURVE_OK)
        code = cli_usage_error("cannot create a context");
    if (code == CLI_EXIT_OK)
        code = cli_inputs_load(ctx, a.files, a.n_files, &in);
    if (code == CLI_EXIT_OK && (in.n_surfaces == 0 || in.n_curves == 0))
        code = cli_usage_error("the files hold %zu surface(s) and %zu curve(s); need both",
                               in.n_surfaces, in.n_curves);
    if (code == CLI_EXIT_OK)
        code = make_options(ctx, &a, &opts);
    if (code == CLI_EXIT_OK) {
        job.surfaces = in.surfaces;
        job.n_surfaces = in.n_surfaces;
        job.curves = in.curves;
        job.n_curves = in.n_curves;
        job.orthogonal = a.orthogonal;
        memcpy(job.dir, a.dir, sizeof job.dir);
        /* the unit of the first input that declares one: coordinates are
         * written as read, so the output keeps the input's size */
        for (size_t m = 0; m < in.n_models && job.metres_per_unit == 0.0; ++m)
            projcurve_model_length_unit(in.models[m], &job.metres_per_unit);
        job.opts = opts;
        char title[256];
        snprintf(title, sizeof title, "projcurve: %s projection of %s%s",
                 a.orthogonal ? "orthogonal" : "directional", a.files[0],
                 a.n_files > 1 ? " and more" : "");
        code = run_and_write(ctx, &job, &a, title);
    }
    cli_job_free(&job);
    cli_inputs_free(&in);
    projcurve_options_destroy(opts);
    projcurve_context_destroy(ctx);
    free(a.files);
    return code;
}
