/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The projcurve command: shared declarations of its parts.
 *
 * Exit codes: CLI_EXIT_OK, CLI_EXIT_PROJECTION (a projection call failed),
 * CLI_EXIT_USAGE (bad usage or input that cannot be read), CLI_EXIT_TIMEOUT
 * (the only failures were calls stopped by --timeout; their partial results
 * are reported and written).
 */
#ifndef PC_CLI_H
#define PC_CLI_H

#include <stddef.h>
#include <stdio.h>

#include "projcurve.h"

enum { CLI_EXIT_OK = 0, CLI_EXIT_PROJECTION = 1, CLI_EXIT_USAGE = 2, CLI_EXIT_TIMEOUT = 3 };

/* ---- argument helpers (args.c) ---- */
/* "X,Y,Z" -> v; 0 on a malformed or non-finite value. */
int cli_parse_vec3(const char *text, double v[3]);
/* n comma-separated finite reals -> v; 0 on anything else. */
int cli_parse_reals(const char *text, size_t n, double *v);
/* A finite real; 0 on failure. */
int cli_parse_double(const char *text, double *v);
/* A decimal index 0 <= *v < 2^53 (digits only); 0 on failure. */
int cli_parse_index(const char *text, size_t *v);
/* 1 when arg is -h or --help. */
int cli_is_help(const char *arg);
/* Prints "projcurve: message" to stderr and returns CLI_EXIT_USAGE. */
int cli_usage_error(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
/* Creates directory path if it does not exist; 0 on failure. */
int cli_make_dir(const char *path);
/* The same with its missing parents (mkdir -p); 0 on failure. */
int cli_make_dirs(const char *path);
/* Milliseconds from a monotonic-enough clock. */
double cli_now_ms(void);

/* ---- inputs (inputs.c) ---- */
typedef struct cli_inputs {
    projcurve_model **models;
    size_t n_models;
    const projcurve_surface **surfaces; /* every surface of every model, in order */
    size_t n_surfaces;
    const projcurve_curve **curves;
    size_t n_curves;
} cli_inputs;

/* Reads the files; on failure prints why and returns CLI_EXIT_USAGE. */
int cli_inputs_load(projcurve_context *ctx, const char *const *paths, size_t n, cli_inputs *in);
void cli_inputs_free(cli_inputs *in);

/* ---- projection runs (run.c) ---- */
typedef struct cli_pair {
    size_t surface, curve;       /* indices into the inputs */
    projcurve_status status;
    projcurve_result *result;    /* NULL if the call failed without one */
} cli_pair;

typedef struct cli_job {
    const projcurve_surface *const *surfaces;
    size_t n_surfaces;
    const projcurve_curve *const *curves;
    size_t n_curves;
    int orthogonal;
    int conical;   /* from the eye point eye (orthogonal 0) */
    double dir[3];
    double eye[3];
    const projcurve_options *opts;
    cli_pair *pairs; /* n_surfaces * n_curves after cli_run */
    size_t n_pairs;
    double time_ms;  /* total projection time */
    size_t failures; /* calls that failed, plus the failure places of their
                        results (projcurve_result_failure_count) */
    double metres_per_unit; /* length unit of the inputs (0: unknown, the
                               IGES file says millimetres) */
    /* The numbers the user knows the surfaces and curves by (as info and
     * --surface / --curve count them); NULL: 0, 1, ... in job order. */
    const size_t *surface_numbers, *curve_numbers;
    /* Called before each projection call with its index k of n (NULL:
     * none): the progress line. */
    void (*pair_started)(void *user, size_t k, size_t n);
    void *pair_user;
    size_t timeouts; /* calls stopped by PROJCURVE_OPT_TIME_LIMIT (also
                        counted in failures) */
    /* --faces: the shape job this job is the view of (NULL otherwise); the
     * SVG draws its connected curves, one path each, instead of a line per
     * face piece. */
    const struct cli_shape_job *shapes;
} cli_job;

/* The user's number of the job's surface s and curve c. */
static inline size_t cli_surface_number(const cli_job *job, size_t s)
{
    return job->surface_numbers ? job->surface_numbers[s] : s;
}
static inline size_t cli_curve_number(const cli_job *job, size_t c)
{
    return job->curve_numbers ? job->curve_numbers[c] : c;
}

/* Projects every curve onto every surface; failures are reported on stderr
 * and counted. Returns 0 only when memory runs out (or n_surfaces * n_curves
 * overflows); job->pairs is then NULL and job->n_pairs 0, so cli_job_free
 * is safe either way. */
int cli_run(projcurve_context *ctx, cli_job *job);
void cli_job_free(cli_job *job);

/* Quality of one branch: residual = largest violation of the projection
 * condition at the traced points (distance of S(u,v) from the line through
 * P(t) along Dir, from the ray from the eye through P(t) for conical, or the
 * tangential part of S(u,v) - P(t) for orthogonal);
 * deviation = largest distance between the composed curve and S(u,v) at
 * the traced points (negative when not composed). Returns 0 when the branch
 * could not be measured (a failed call or allocation): residual is then NaN,
 * never a 0 that would read as a perfect branch. */
typedef struct cli_branch_quality {
    double residual, deviation;
} cli_branch_quality;
int cli_branch_measure(projcurve_context *ctx, const cli_job *job, const cli_pair *pair,
                       size_t branch, cli_branch_quality *q);

const char *cli_start_name(projcurve_branch_start s);
const char *cli_end_name(projcurve_branch_end e);
/* The same in words, for pictures: "the start of the curve", ... */
const char *cli_start_words(projcurve_branch_start s);
const char *cli_end_words(projcurve_branch_end e);

/* ---- outputs ---- */
int cli_write_iges(projcurve_context *ctx, const cli_job *job, const char *path);
/* STEP (report_step.c) for -o paths ending in .step or .stp (any case). */
int cli_is_step_path(const char *path);
int cli_write_step(projcurve_context *ctx, const cli_job *job, const char *path);
int cli_write_json(projcurve_context *ctx, const cli_job *job, const char *path);
int cli_write_svg(projcurve_context *ctx, const cli_job *job, const char *title,
                  const char *path);
/* The short summary printed by project and demo (out NULL: only
 * counted, for --quiet); returns the number of branches that could not be
 * measured (the callers count them as failures: a summary that cannot be
 * computed is not a success). */
size_t cli_print_summary(projcurve_context *ctx, const cli_job *job, FILE *out);

/* ---- commands ---- */
int cli_cmd_info(int argc, char **argv);
/* The shapes, faces, loops and edges of a model (info_topology.c), as text
 * lines or as the JSON object of projcurve info --json. */
void cli_print_topology(const projcurve_model *m);
void cli_print_info_json(projcurve_context *ctx, const char *path, const projcurve_model *m);
/* Degrees, control points, spans, domain and box of each surface and
 * curve, and the model's box (info_sizes.c): text lines, or the members
 * surface_list, curve_list and box of the --json object (each line ends
 * with a comma: more members follow). */
void cli_print_sizes(projcurve_context *ctx, const projcurve_model *m);
void cli_print_sizes_json(projcurve_context *ctx, const projcurve_model *m, FILE *out);
int cli_cmd_project(int argc, char **argv);
int cli_cmd_demo(int argc, char **argv);

/* ---- demo shapes (demo_shapes.c) ---- */
/* [SY13] s5, Example 1: a degree (5, 1) sheet and a cubic curve. */
int cli_demo_example1(projcurve_context *ctx, projcurve_surface **s, projcurve_curve **c);
/* A bicubic wave surface and a cubic curve above it (Dir = -z). */
int cli_demo_freeform(projcurve_context *ctx, projcurve_surface **s, projcurve_curve **c);

#endif /* PC_CLI_H */
