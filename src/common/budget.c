/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The work budget of one projection call (budget.h): counting, the clock,
 * the progress callback.
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include "common/budget.h"

#include <time.h>

#include "common/error.h"

double pc_budget_monotonic(void *unused)
{
    (void)unused;
    struct timespec ts;
    if (clock_gettime(CLOCK_MONOTONIC, &ts) != 0)
        return 0.0; /* no clock: the time limit is never seen to pass */
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void pc_budget_init_clock(pc_budget *b, double time_limit, unsigned long long max_work,
                          projcurve_progress_fn progress, void *progress_user,
                          pc_budget_clock_fn clock, void *clock_user)
{
    *b = (pc_budget){0};
    b->progress = progress;
    b->progress_user = progress_user;
    b->time_limit = time_limit > 0.0 ? time_limit : 0.0;
    b->max_work = max_work;
    b->clock = b->time_limit > 0.0 ? clock : NULL;
    b->clock_user = clock_user;
    b->start = b->clock != NULL ? b->clock(clock_user) : 0.0;
    /* the first unit polls in full: a callback can stop the call before
     * any real work, and a tiny limit is seen at once */
    b->next_poll = 1;
    b->stage_hi = 1.0;
    b->status = PROJCURVE_OK;
}

void pc_budget_init(pc_budget *b, double time_limit, unsigned long long max_work,
                    projcurve_progress_fn progress, void *progress_user)
{
    pc_budget_init_clock(b, time_limit, max_work, progress, progress_user,
                         pc_budget_monotonic, NULL);
}

void pc_budget_stage(pc_budget *b, double lo, double hi)
{
    if (b == NULL)
        return;
    b->stage_lo = lo;
    b->stage_hi = hi;
}

/* The fraction of the whole call at stage_fraction of the current stage,
 * never below what the callback was already given. */
static double call_fraction(pc_budget *b, double stage_fraction)
{
    double f = stage_fraction > 0.0 ? (stage_fraction < 1.0 ? stage_fraction : 1.0) : 0.0;
    f = b->stage_lo + (b->stage_hi - b->stage_lo) * f;
    if (f > 1.0)
        f = 1.0;
    if (f > b->reported) /* also rejects NaN */
        b->reported = f;
    return b->reported;
}

void pc_budget_step(pc_budget *b, const char *step)
{
    if (b != NULL)
        b->step = step;
}

static projcurve_status stop(pc_budget *b, projcurve_status status, int why)
{
    b->status = status;
    b->stopped_by = why;
    b->stopped_in = b->step;
    return status;
}

projcurve_status pc_budget_poll(pc_budget *b, double stage_fraction)
{
    if (b->status != PROJCURVE_OK)
        return b->status;
    b->next_poll = b->work + PC_BUDGET_POLL_EVERY;
    if (b->max_work > 0) {
        if (b->work > b->max_work)
            return stop(b, PROJCURVE_ERR_LIMIT_REACHED, PC_BUDGET_STOP_WORK);
        if (b->next_poll > b->max_work + 1) /* stop at exactly max_work units */
            b->next_poll = b->max_work + 1;
    }
    if (b->clock != NULL && b->clock(b->clock_user) - b->start >= b->time_limit)
        return stop(b, PROJCURVE_ERR_LIMIT_REACHED, PC_BUDGET_STOP_TIME);
    const double f = call_fraction(b, stage_fraction);
    if (b->progress != NULL && b->progress(b->progress_user, f) != 0)
        return stop(b, PROJCURVE_ERR_CANCELLED, PC_BUDGET_STOP_CANCEL);
    return PROJCURVE_OK;
}

projcurve_status pc_budget_fail(const pc_budget *b, projcurve_context *ctx)
{
    if (b == NULL || b->status == PROJCURVE_OK)
        return PROJCURVE_OK;
    const char *in = b->stopped_in != NULL ? " while " : "";
    const char *step = b->stopped_in != NULL ? b->stopped_in : "";
    switch (b->stopped_by) {
    case PC_BUDGET_STOP_TIME:
        return pc_fail(ctx, b->status,
                       "the time limit of %g s was reached%s%s; the partial result is kept",
                       b->time_limit, in, step);
    case PC_BUDGET_STOP_WORK:
        return pc_fail(ctx, b->status,
                       "the work limit of %llu units was reached%s%s; the partial result is kept",
                       b->max_work, in, step);
    default:
        return pc_fail(ctx, b->status,
                       "the progress callback asked to stop at %.3g of the work%s%s; "
                       "the partial result is kept",
                       b->reported, in, step);
    }
}

void pc_budget_finish(pc_budget *b)
{
    if (b == NULL || b->status != PROJCURVE_OK)
        return;
    b->reported = 1.0;
    if (b->progress != NULL)
        (void)b->progress(b->progress_user, 1.0);
}
