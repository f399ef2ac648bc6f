/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * pc_batch_project (batch.h): a shared counter hands out the curves; each
 * worker projects them with a context of its own (the public context is
 * not thread-safe) and keeps the message of the lowest-index failure it
 * met, which the caller's context gets at the end.
 */
#include "batch/batch.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/error.h"
#include "directional/directional_project.h"
#include "ortho/ortho_project.h"

typedef struct pc_batch_job {
    const projcurve_surface *surface;
    const projcurve_curve *const *curves;
    size_t n;
    const pc_vec3 *dir;
    const pc_params *p;
    const pc_batch_budget *budget;
    projcurve_result **results;
    projcurve_status *statuses;
    size_t max_control_points;
    pthread_mutex_t lock; /* next, and the progress callback */
    size_t next;
} pc_batch_job;

typedef struct pc_batch_worker {
    pc_batch_job *job;
    size_t failed;        /* lowest failing index, job->n if none */
    projcurve_context ctx; /* the failure's message */
} pc_batch_worker;

/* The user's progress callback, one call at a time. */
static int locked_progress(void *user, double fraction)
{
    pc_batch_job *job = user;
    pthread_mutex_lock(&job->lock);
    const int go_on = job->budget->progress(job->budget->progress_user, fraction);
    pthread_mutex_unlock(&job->lock);
    return go_on;
}

static projcurve_status project_one(pc_batch_job *job, projcurve_context *ctx, size_t i)
{
    const projcurve_curve *curve = job->curves[i];
    if (curve == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NULL_ARGUMENT, "curve is NULL");
    pc_budget budget;
    const pc_batch_budget *b = job->budget;
    pc_budget_init(&budget, b->time_limit, b->max_work, b->progress ? locked_progress : NULL,
                   b->progress ? job : NULL);
    pc_params p = *job->p;
    p.budget = &budget;
    return job->dir != NULL
               ? pc_directional_project(ctx, job->surface, curve, *job->dir, &p, &job->results[i])
               : pc_ortho_project(ctx, job->surface, curve, &p, &job->results[i]);
}

static void *work(void *arg)
{
    pc_batch_worker *w = arg;
    pc_batch_job *job = w->job;
    /* at most n turns: each takes one curve */
    for (;;) {
        pthread_mutex_lock(&job->lock);
        const size_t i = job->next < job->n ? job->next++ : job->n;
        pthread_mutex_unlock(&job->lock);
        if (i == job->n)
            break;
        projcurve_context ctx = {PC_CONTEXT_MAGIC, PROJCURVE_OK, "", job->max_control_points};
        job->results[i] = NULL;
        const projcurve_status st = project_one(job, &ctx, i);
        if (job->statuses != NULL)
            job->statuses[i] = st;
        if (st != PROJCURVE_OK && i < w->failed) {
            w->failed = i;
            w->ctx = ctx;
            w->ctx.last_status = st;
        }
    }
    return NULL;
}

projcurve_status pc_batch_project(projcurve_context *ctx, const projcurve_surface *surface,
                                  const projcurve_curve *const *curves, size_t n,
                                  const pc_vec3 *dir, const pc_params *p,
                                  const pc_batch_budget *budget, projcurve_result **results,
                                  projcurve_status *statuses)
{
    pc_batch_job job = {surface, curves, n, dir, p, budget, results, statuses,
                        pc_context_max_control_points(ctx), PTHREAD_MUTEX_INITIALIZER, 0};
    size_t n_workers = p->threads > 1 ? (size_t)p->threads : 1;
    if (n_workers > n)
        n_workers = n > 0 ? n : 1;
    pc_batch_worker *workers = calloc(n_workers, sizeof *workers);
    pthread_t *threads = n_workers > 1 ? calloc(n_workers, sizeof *threads) : NULL;
    if (workers == NULL || (n_workers > 1 && threads == NULL)) {
        free(workers);
        free(threads);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for %zu workers", n_workers);
    }
    int *started = NULL;
    for (size_t k = 0; k < n_workers; ++k) {
        workers[k].job = &job;
        workers[k].failed = n;
    }
    if (n_workers > 1)
        started = calloc(n_workers, sizeof *started);
    /* worker 0 is the calling thread; a thread that cannot be started (or
     * no memory to track it) leaves its share to the others */
    for (size_t k = 1; started != NULL && k < n_workers; ++k)
        started[k] = pthread_create(&threads[k], NULL, work, &workers[k]) == 0;
    work(&workers[0]);
    for (size_t k = 1; started != NULL && k < n_workers; ++k)
        if (started[k])
            pthread_join(threads[k], NULL);
    size_t first = n, from = 0;
    for (size_t k = 0; k < n_workers; ++k)
        if (workers[k].failed < first) {
            first = workers[k].failed;
            from = k;
        }
    projcurve_status st = PROJCURVE_OK;
    if (first < n)
        st = pc_fail(ctx, workers[from].ctx.last_status, "curve %zu: %s", first,
                     workers[from].ctx.last_message);
    free(started);
    free(threads);
    free(workers);
    pthread_mutex_destroy(&job.lock);
    return st;
}
