/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve project FILE... (--dir X,Y,Z | --eye X,Y,Z | --orthogonal) [OPTION]...: the
 * options are in project_args.c; here the inputs are read, the pairs
 * picked, the projections run and the outputs written.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "curve_input.h"
#include "progress.h"
#include "project_args.h"
#include "shape_job.h"

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
        projcurve_options_set_int(ctx, *opts, PROJCURVE_OPT_PCURVE_DEGREE, a->pcurve_degree) !=
            PROJCURVE_OK)
        return cli_usage_error("--pcurve-degree: %s", projcurve_context_message(ctx));
    if (a->have_timeout && projcurve_options_set_double(ctx, *opts, PROJCURVE_OPT_TIME_LIMIT,
                                                        a->timeout) != PROJCURVE_OK)
        return cli_usage_error("--timeout: %s", projcurve_context_message(ctx));
    if (a->nearest && projcurve_options_set_int(ctx, *opts, PROJCURVE_OPT_HITS,
                                                PROJCURVE_HITS_NEAREST) != PROJCURVE_OK)
        return cli_usage_error("--nearest: %s", projcurve_context_message(ctx));
    if (a->have_max_distance &&
        projcurve_options_set_double(ctx, *opts, PROJCURVE_OPT_MAX_DISTANCE, a->max_distance) !=
            PROJCURVE_OK)
        return cli_usage_error("--max-distance: %s", projcurve_context_message(ctx));
    return CLI_EXIT_OK;
}

/* What the job projects: the surfaces and curves of the files, or the one
 * --surface / --curve picks, or the curve of --line / --points. */
typedef struct project_pick {
    projcurve_curve **given;          /* --line / --points, owned */
    size_t n_given;
    const projcurve_curve *curve_one; /* the one curve projected, if one */
    size_t surface_number, curve_number;
} project_pick;

/* "--surface 7: the files hold surfaces 0 to 4" */
static int out_of_range(const char *flag, const char *what, size_t i, size_t n)
{
    if (n == 0)
        return cli_usage_error("%s %zu: the files hold no %s", flag, i, what);
    if (n == 1)
        return cli_usage_error("%s %zu: the files hold one %s, number 0", flag, i, what);
    return cli_usage_error("%s %zu: the files hold %ss 0 to %zu", flag, i, what, n - 1);
}

/* The curves of --line or --points into pk->given (none without them). */
static int given_curves(projcurve_context *ctx, const project_args *a, project_pick *pk)
{
    if (a->points_path)
        return cli_curves_from_points(ctx, a->points_path, a->interpolate, &pk->given,
                                      &pk->n_given);
    if (!a->have_line)
        return CLI_EXIT_OK;
    pk->given = calloc(1, sizeof *pk->given);
    if (pk->given == NULL)
        return cli_usage_error("out of memory");
    pk->n_given = 1;
    return cli_curve_from_line(ctx, a->line, &pk->given[0]);
}

/* The shapes of the files (--faces). */
static size_t shape_count(const cli_inputs *in)
{
    size_t n = 0;
    for (size_t m = 0; m < in->n_models; ++m)
        n += projcurve_model_shape_count(in->models[m]);
    return n;
}

/* cin holds the curves: in, or the inputs of --curves FILE. */
static int pick(projcurve_context *ctx, const project_args *a, const cli_inputs *in,
                const cli_inputs *cin, project_pick *pk, cli_job *job)
{
    if (a->have_surface && a->surface >= in->n_surfaces)
        return out_of_range("--surface", "surface", a->surface, in->n_surfaces);
    if (a->have_curve && a->curve >= cin->n_curves)
        return out_of_range("--curve", "curve", a->curve, cin->n_curves);
    if (a->faces && shape_count(in) == 0)
        return cli_usage_error("--faces: the files hold no face or shape to project onto");
    if (in->n_surfaces == 0)
        return cli_usage_error("the files hold no surface to project onto");
    const int code = given_curves(ctx, a, pk);
    if (code != CLI_EXIT_OK)
        return code;
    if (pk->given == NULL && cin->n_curves == 0 && a->curves_path)
        return cli_usage_error("--curves %s holds no curve", a->curves_path);
    if (pk->given == NULL && cin->n_curves == 0)
        return cli_usage_error("the files hold %zu surface(s) and no curve; give one with "
                               "--line or --points",
                               in->n_surfaces);
    job->surfaces = in->surfaces;
    job->n_surfaces = in->n_surfaces;
    if (a->have_surface) {
        pk->surface_number = a->surface;
        job->surfaces = &in->surfaces[a->surface];
        job->n_surfaces = 1;
        job->surface_numbers = &pk->surface_number;
    }
    job->curves = cin->curves;
    job->n_curves = cin->n_curves;
    if (pk->given) {
        /* the segments of --points are numbered 0, 1, ...: no map */
        job->curves = (const projcurve_curve *const *)pk->given;
        job->n_curves = pk->n_given;
    } else if (a->have_curve) {
        pk->curve_one = cin->curves[a->curve];
        pk->curve_number = a->curve;
        job->curves = &pk->curve_one;
        job->n_curves = 1;
        job->curve_numbers = &pk->curve_number;
    }
    return CLI_EXIT_OK;
}

/* The exit code of a finished run (cli.h). */
static int exit_code(const cli_job *job, size_t unmeasured)
{
    if (unmeasured || job->failures > job->timeouts)
        return CLI_EXIT_PROJECTION;
    return job->timeouts ? CLI_EXIT_TIMEOUT : CLI_EXIT_OK;
}

/* Runs the job and writes the requested outputs; the exit code. */
static int run_and_write(projcurve_context *ctx, cli_job *job, const project_args *a,
                         projcurve_options *opts, const char *title)
{
    cli_progress progress;
    if (!a->quiet && cli_progress_init(&progress, stderr, job, a->progress)) {
        job->pair_started = cli_progress_pair;
        job->pair_user = &progress;
        /* fails only for NULL arguments */
        (void)projcurve_options_set_progress(ctx, opts, cli_progress_call, &progress);
    }
    const int ran = cli_run(ctx, job);
    if (job->pair_started)
        cli_progress_finish(&progress);
    if (!ran)
        return cli_usage_error("out of memory");
    const size_t unmeasured = cli_print_summary(ctx, job, a->quiet ? NULL : stdout);
    if (job->timeouts)
        fprintf(stderr,
                "projcurve: %zu projection(s) stopped by --timeout %g s; what they made is "
                "reported and written (their cut branches end 'limit')\n",
                job->timeouts, a->timeout);
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
    return exit_code(job, unmeasured);
}

/* --faces: each curve of the job onto each shape of the files; the
 * outputs are written from the connected curves (JSON; IGES and STEP: one
 * composite curve each; SVG: one path each) and from the face results (the
 * SVG's parameter panels). */
static int run_faces_and_write(projcurve_context *ctx, const cli_job *job, const cli_inputs *in,
                               const project_args *a, const char *title)
{
    cli_shape_job sj;
    memset(&sj, 0, sizeof sj);
    sj.models = (const projcurve_model *const *)in->models;
    sj.n_models = in->n_models;
    sj.curves = job->curves;
    sj.n_curves = job->n_curves;
    sj.curve_numbers = job->curve_numbers;
    sj.kind = a->orthogonal ? PROJCURVE_PROJECT_ORTHOGONAL
              : a->have_eye ? PROJCURVE_PROJECT_CONICAL
                            : PROJCURVE_PROJECT_DIRECTIONAL;
    memcpy(sj.vec, a->have_eye ? a->eye : a->dir, sizeof sj.vec);
    sj.opts = job->opts;
    if (!cli_shape_run_all(ctx, &sj)) {
        cli_shape_job_free(&sj);
        return cli_usage_error("out of memory");
    }
    sj.view.metres_per_unit = job->metres_per_unit;
    sj.view.shapes = &sj;
    if (!a->quiet)
        cli_print_shape_summary(&sj, stdout);
    if (sj.timeouts)
        fprintf(stderr,
                "projcurve: %zu projection(s) stopped by --timeout %g s; what they made is "
                "reported and written (their cut pieces end 'limit')\n",
                sj.timeouts, a->timeout);
    int ok = 1;
    if (a->iges)
        ok &= cli_is_step_path(a->iges) ? cli_write_shape_step(ctx, &sj, a->iges)
                                        : cli_write_shape_iges(ctx, &sj, a->iges);
    if (a->json)
        ok &= cli_write_shape_json(ctx, &sj, a->json);
    if (a->svg)
        ok &= cli_write_svg(ctx, &sj.view, title, a->svg);
    const int code = !ok                          ? CLI_EXIT_USAGE
                     : sj.failures > sj.timeouts ? CLI_EXIT_PROJECTION
                     : sj.timeouts               ? CLI_EXIT_TIMEOUT
                                                 : CLI_EXIT_OK;
    cli_shape_job_free(&sj);
    return code;
}

/* The file name without its folders: titles stay short. */
static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

/* "Projection along (0, 0, -1): part.igs and 2 more files" */
static void make_title(const project_args *a, char *title, size_t cap)
{
    char kind[96], more[48] = "";
    if (a->orthogonal)
        snprintf(kind, sizeof kind, "Orthogonal projection");
    else if (a->have_eye)
        snprintf(kind, sizeof kind, "Projection from the eye (%g, %g, %g)", a->eye[0], a->eye[1],
                 a->eye[2]);
    else
        snprintf(kind, sizeof kind, "Projection along (%g, %g, %g)", a->dir[0], a->dir[1],
                 a->dir[2]);
    if (a->n_files > 1)
        snprintf(more, sizeof more, " and %zu more file%s", a->n_files - 1,
                 a->n_files > 2 ? "s" : "");
    if (a->have_line)
        snprintf(title, cap, "%s: a line onto %s%s", kind, base_name(a->files[0]), more);
    else if (a->points_path)
        snprintf(title, cap, "%s: the points of %s onto %s%s", kind, base_name(a->points_path),
                 base_name(a->files[0]), more);
    else
        snprintf(title, cap, "%s: %s%s", kind, base_name(a->files[0]), more);
}

int cli_cmd_project(int argc, char **argv)
{
    for (int i = 1; i < argc; ++i)
        if (cli_is_help(argv[i])) {
            project_args_usage(stdout);
            return CLI_EXIT_OK;
        }
    project_args a;
    int code = project_args_parse(argc, argv, &a);
    if (code != CLI_EXIT_OK) {
        free(a.files);
        return code;
    }
    projcurve_context *ctx = NULL;
    projcurve_options *opts = NULL;
    cli_inputs in, cin;
    memset(&in, 0, sizeof in);
    memset(&cin, 0, sizeof cin);
    cli_job job;
    memset(&job, 0, sizeof job);
    project_pick pk;
    memset(&pk, 0, sizeof pk);
    if (projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx) != PROJCURVE_OK)
        code = cli_usage_error("cannot create a context");
    if (code == CLI_EXIT_OK)
        code = cli_inputs_load(ctx, (const char *const *)a.files, a.n_files, &in);
    if (code == CLI_EXIT_OK && a.curves_path)
        code = cli_inputs_load(ctx, &a.curves_path, 1, &cin);
    if (code == CLI_EXIT_OK)
        code = make_options(ctx, &a, &opts);
    if (code == CLI_EXIT_OK)
        code = pick(ctx, &a, &in, a.curves_path ? &cin : &in, &pk, &job);
    if (code == CLI_EXIT_OK) {
        job.orthogonal = a.orthogonal;
        job.conical = a.have_eye;
        memcpy(job.dir, a.dir, sizeof job.dir);
        memcpy(job.eye, a.eye, sizeof job.eye);
        /* the unit of the first input that declares one: coordinates are
         * written as read, so the output keeps the input's size */
        for (size_t m = 0; m < in.n_models && job.metres_per_unit == 0.0; ++m)
            projcurve_model_length_unit(in.models[m], &job.metres_per_unit);
        job.opts = opts;
        char title[512];
        make_title(&a, title, sizeof title);
        code = a.faces ? run_faces_and_write(ctx, &job, &in, &a, title)
                       : run_and_write(ctx, &job, &a, opts, title);
    }
    cli_job_free(&job);
    cli_curves_free(pk.given, pk.n_given);
    cli_inputs_free(&in);
    cli_inputs_free(&cin);
    projcurve_options_destroy(opts);
    projcurve_context_destroy(ctx);
    free(a.files);
    return code;
}
