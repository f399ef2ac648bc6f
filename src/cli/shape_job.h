/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve project --faces: every curve projected onto every shape of the
 * files (projcurve_project_shape), the face pieces chained into connected
 * curves. The per-face results are also seen as a cli_job (the view), so
 * that the IGES, STEP and SVG writers of the surface mode write them.
 */
#ifndef PC_CLI_SHAPE_JOB_H
#define PC_CLI_SHAPE_JOB_H

#include <stdio.h>

#include "cli.h"

/* One call: curve onto shape. */
typedef struct cli_shape_run {
    size_t model, shape, curve;      /* indices into the inputs / job */
    const projcurve_shape *target;
    projcurve_status status;
    projcurve_shape_result *result; /* NULL if the call failed without one */
} cli_shape_run;

typedef struct cli_shape_job {
    const projcurve_model *const *models;
    size_t n_models;
    const projcurve_curve *const *curves;
    size_t n_curves;
    const size_t *curve_numbers; /* NULL: 0, 1, ... */
    projcurve_projection_kind kind;
    double vec[3];
    const projcurve_options *opts;
    cli_shape_run *runs; /* one per (shape, curve) after cli_shape_run_all */
    size_t n_runs;
    double time_ms;  /* time spent in projcurve_project_shape only */
    size_t failures; /* failed calls, failed faces, and the failure places
                        of the face results */
    size_t timeouts; /* calls stopped by the time limit (also failures) */
    cli_job view;    /* the face results as pairs (borrowed results) */
} cli_shape_job;

/* Runs every call and builds the view; failures are reported on stderr
 * and counted. Returns 0 only when memory runs out; cli_shape_job_free is
 * safe either way. */
int cli_shape_run_all(projcurve_context *ctx, cli_shape_job *job);
void cli_shape_job_free(cli_shape_job *job);

/* The user's number of the job's curve c. */
static inline size_t cli_shape_curve_number(const cli_shape_job *job, size_t c)
{
    return job->curve_numbers ? job->curve_numbers[c] : c;
}

/* Adds one run's shape result to a writer (IGES or STEP). */
typedef projcurve_status (*cli_add_shape_fn)(projcurve_context *ctx, void *writer,
                                             const projcurve_shape_result *result);

/* Adds every run's result to writer through add, for the --faces files: a
 * run whose pieces cannot all be written (INVALID_ARGUMENT, OUT_OF_RANGE:
 * one not composed, or too narrow) is left out with a message naming
 * path. Returns 0 on any other failure. */
int cli_add_shape_results(projcurve_context *ctx, const cli_shape_job *job, const char *path,
                          cli_add_shape_fn add, void *writer);

/* The IGES file of --faces (report_shape_iges.c): every surface of the
 * view, every NURBS input curve, then each connected curve as one
 * composite curve (projcurve_iges_writer_add_shape_result). A run whose
 * pieces cannot all be written (one not composed) is left out with a
 * message. Returns 0 on a failure to write (reported on stderr). */
int cli_write_shape_iges(projcurve_context *ctx, const cli_shape_job *job, const char *path);

/* The STEP file of --faces (report_shape_step.c), the same: every surface
 * of the view, every NURBS input curve, then each connected curve as one
 * COMPOSITE_CURVE of its face pieces' 3D curves
 * (projcurve_step_writer_add_shape_result); a run that cannot be written
 * is left out with a message. Returns 0 on a failure to write. */
int cli_write_shape_step(projcurve_context *ctx, const cli_shape_job *job, const char *path);

/* The connected curves of every run, and the k-th of them (its run and
 * index in the run's result); 0 past the end. For the SVG's paths and
 * legend. */
size_t cli_shape_connected_total(const cli_shape_job *job);
int cli_shape_connected_at(const cli_shape_job *job, size_t k, const cli_shape_run **run,
                           size_t *curve);

/* The number (as cli_shape_connected_at counts) of the connected curve
 * that face piece (face_result, branch) belongs to; SIZE_MAX for none. */
size_t cli_shape_connected_of(const cli_shape_job *job, const projcurve_result *face_result,
                              size_t branch);

/* The JSON report (report_shape_json.c) and the summary line. */
int cli_write_shape_json(projcurve_context *ctx, const cli_shape_job *job, const char *path);
void cli_print_shape_summary(const cli_shape_job *job, FILE *out);

#endif /* PC_CLI_SHAPE_JOB_H */
