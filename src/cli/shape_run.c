/* SPDX-License-Identifier: BSD-3-Clause */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "shape_job.h"

static size_t shape_total(const cli_shape_job *job)
{
    size_t n = 0;
    for (size_t m = 0; m < job->n_models; ++m)
        n += projcurve_model_shape_count(job->models[m]);
    return n;
}

/* Reports a failed face of a run and counts it; a face whose projection
 * failed is missing from the connected curves, as a failed call would be. */
static void count_faces(projcurve_context *ctx, cli_shape_job *job, const cli_shape_run *r)
{
    const size_t n = projcurve_shape_result_face_count(r->result);
    for (size_t i = 0; i < n; ++i) {
        size_t face = 0;
        const projcurve_result *fr = NULL;
        projcurve_status st = PROJCURVE_OK;
        const char *why = "";
        if (projcurve_shape_result_face(ctx, r->result, i, &face, &fr, &st, &why) !=
            PROJCURVE_OK)
            continue;
        if (st != PROJCURVE_OK) {
            fprintf(stderr, "projcurve: curve %zu onto shape %zu, face %zu: %s: %s\n",
                    cli_shape_curve_number(job, r->curve), r->shape, face,
                    projcurve_status_string(st), why);
            ++job->failures;
        }
        const size_t failed = projcurve_result_failure_count(fr);
        if (failed > 0)
            fprintf(stderr,
                    "projcurve: curve %zu onto shape %zu, face %zu: %zu place(s) where the "
                    "projection could not be followed or verified\n",
                    cli_shape_curve_number(job, r->curve), r->shape, face, failed);
        job->failures += failed;
    }
}

static void run_one(projcurve_context *ctx, cli_shape_job *job, cli_shape_run *r)
{
    const double t0 = cli_now_ms();
    r->status = projcurve_project_shape(ctx, r->target, job->curves[r->curve], job->kind,
                                        job->vec, job->opts, &r->result);
    job->time_ms += cli_now_ms() - t0;
    if (r->status != PROJCURVE_OK) {
        const char *why = projcurve_context_message(ctx);
        fprintf(stderr, "projcurve: curve %zu onto shape %zu: %s: %s\n",
                cli_shape_curve_number(job, r->curve), r->shape,
                projcurve_status_string(r->status), why);
        if (r->status == PROJCURVE_ERR_LIMIT_REACHED && strstr(why, "time limit"))
            ++job->timeouts;
        /* a partial result (a limit or a cancel) is kept and reported */
        if (r->status != PROJCURVE_ERR_LIMIT_REACHED && r->status != PROJCURVE_ERR_CANCELLED) {
            projcurve_shape_result_destroy(r->result);
            r->result = NULL;
        }
        ++job->failures;
    }
    count_faces(ctx, job, r);
}

/* The index of s in the view's surfaces, added if new (the list holds at
 * most one entry per pair, so it has room). */
static size_t view_surface(cli_job *view, const projcurve_surface **list,
                           const projcurve_surface *s)
{
    for (size_t i = 0; i < view->n_surfaces; ++i)
        if (list[i] == s)
            return i;
    list[view->n_surfaces] = s;
    return view->n_surfaces++;
}

/* The face results of every run as the pairs of job->view (borrowed). */
static int build_view(cli_shape_job *job)
{
    cli_job *view = &job->view;
    size_t n = 0;
    for (size_t i = 0; i < job->n_runs; ++i)
        n += projcurve_shape_result_face_count(job->runs[i].result);
    cli_pair *pairs = calloc(n ? n : 1, sizeof *pairs);
    const projcurve_surface **surfaces = calloc(n ? n : 1, sizeof *surfaces);
    if (pairs == NULL || surfaces == NULL) {
        free(pairs);
        free((void *)surfaces);
        return 0;
    }
    view->pairs = pairs;
    view->surfaces = surfaces;
    view->curves = job->curves;
    view->n_curves = job->n_curves;
    view->curve_numbers = job->curve_numbers;
    view->orthogonal = job->kind == PROJCURVE_PROJECT_ORTHOGONAL;
    view->conical = job->kind == PROJCURVE_PROJECT_CONICAL;
    memcpy(view->dir, job->vec, sizeof view->dir);
    memcpy(view->eye, job->vec, sizeof view->eye);
    view->opts = job->opts;
    view->time_ms = job->time_ms;
    view->failures = job->failures;
    view->timeouts = job->timeouts;
    for (size_t i = 0; i < job->n_runs; ++i) {
        const cli_shape_run *r = &job->runs[i];
        const size_t nf = projcurve_shape_result_face_count(r->result);
        for (size_t k = 0; k < nf; ++k) {
            size_t face = 0;
            const projcurve_result *fr = NULL;
            if (projcurve_shape_result_face(NULL, r->result, k, &face, &fr, NULL, NULL) !=
                    PROJCURVE_OK ||
                fr == NULL)
                continue;
            const projcurve_face *f = projcurve_shape_face(r->target, face);
            cli_pair *p = &pairs[view->n_pairs++];
            p->surface = view_surface(view, surfaces, projcurve_face_surface(f));
            p->curve = r->curve;
            p->result = (projcurve_result *)fr; /* borrowed: never destroyed here */
        }
    }
    return 1;
}

int cli_shape_run_all(projcurve_context *ctx, cli_shape_job *job)
{
    job->runs = NULL;
    job->n_runs = 0;
    memset(&job->view, 0, sizeof job->view);
    const size_t n_shapes = shape_total(job);
    const size_t n = n_shapes * job->n_curves;
    if (job->n_curves != 0 && n / job->n_curves != n_shapes)
        return 0;
    cli_shape_run *runs = calloc(n ? n : 1, sizeof *runs);
    if (runs == NULL)
        return 0;
    job->runs = runs;
    job->n_runs = n;
    size_t k = 0;
    for (size_t c = 0; c < job->n_curves; ++c) {
        size_t shape = 0;
        for (size_t m = 0; m < job->n_models; ++m)
            for (size_t s = 0; s < projcurve_model_shape_count(job->models[m]); ++s, ++k) {
                cli_shape_run *r = &runs[k];
                r->model = m;
                r->shape = shape++;
                r->curve = c;
                r->target = projcurve_model_shape(job->models[m], s);
                run_one(ctx, job, r);
            }
    }
    return build_view(job);
}

void cli_shape_job_free(cli_shape_job *job)
{
    for (size_t i = 0; i < job->n_runs; ++i)
        projcurve_shape_result_destroy(job->runs[i].result);
    free(job->runs);
    /* the view's results are the runs' (borrowed): only its arrays go */
    free(job->view.pairs);
    free((void *)job->view.surfaces);
    job->runs = NULL;
    job->n_runs = 0;
    memset(&job->view, 0, sizeof job->view);
}

size_t cli_shape_connected_total(const cli_shape_job *job)
{
    size_t n = 0;
    for (size_t i = 0; i < job->n_runs; ++i)
        n += projcurve_shape_result_curve_count(job->runs[i].result);
    return n;
}

int cli_shape_connected_at(const cli_shape_job *job, size_t k, const cli_shape_run **run,
                           size_t *curve)
{
    for (size_t i = 0; i < job->n_runs; ++i) {
        const size_t n = projcurve_shape_result_curve_count(job->runs[i].result);
        if (k < n) {
            *run = &job->runs[i];
            *curve = k;
            return 1;
        }
        k -= n;
    }
    return 0;
}

size_t cli_shape_connected_of(const cli_shape_job *job, const projcurve_result *face_result,
                              size_t branch)
{
    size_t k = 0;
    for (size_t i = 0; i < job->n_runs; ++i) {
        const projcurve_shape_result *sr = job->runs[i].result;
        const size_t n = projcurve_shape_result_curve_count(sr);
        for (size_t c = 0; c < n; ++c, ++k) {
            size_t np = 0;
            if (projcurve_shape_result_curve_info(NULL, sr, c, &np, NULL, NULL) != PROJCURVE_OK)
                continue;
            for (size_t j = 0; j < np; ++j) {
                const projcurve_result *fr = NULL;
                size_t b = 0;
                if (projcurve_shape_result_piece(NULL, sr, c, j, NULL, &fr, &b, NULL, NULL,
                                                 NULL) == PROJCURVE_OK &&
                    fr == face_result && b == branch)
                    return k;
            }
        }
    }
    return SIZE_MAX;
}

int cli_add_shape_results(projcurve_context *ctx, const cli_shape_job *job, const char *path,
                          cli_add_shape_fn add, void *writer)
{
    for (size_t i = 0; i < job->n_runs; ++i) {
        const cli_shape_run *r = &job->runs[i];
        if (r->result == NULL)
            continue;
        const projcurve_status st = add(ctx, writer, r->result);
        if (st == PROJCURVE_ERR_INVALID_ARGUMENT || st == PROJCURVE_ERR_OUT_OF_RANGE)
            fprintf(stderr, "projcurve: %s: the connected curves of curve %zu onto shape %zu "
                            "are not written: %s\n",
                    path, cli_shape_curve_number(job, r->curve), r->shape,
                    projcurve_context_message(ctx));
        else if (st != PROJCURVE_OK)
            return 0;
    }
    return 1;
}
