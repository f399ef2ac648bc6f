/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The work budget of one projection call: a wall-time limit
 * (PROJCURVE_OPT_TIME_LIMIT), a deterministic work limit
 * (PROJCURVE_OPT_MAX_WORK) and the caller's progress / cancel callback
 * (projcurve_options_set_progress).
 *
 * The entry point makes one pc_budget from the options at the start of the
 * call and hands it down in the engine's parameters (pc_params.budget,
 * common/params.h); each stage polls it once per unit of its work: a
 * traced step, a check of the jump sweep, a segment of the refinement, a
 * fitted piece. A unit is a bounded
 * amount of work (one corrector call and a few evaluations, or one seed
 * search), so polling once per unit bounds the time between two polls.
 *
 * A poll is a counter increment; only every PC_BUDGET_POLL_EVERY units does
 * it read the clock and call the callback, which keeps the cost of polling
 * far below that of the work and the callback's rate bounded. Once a limit
 * or the callback stops the call, every later poll returns the same status,
 * so each stage ends the way it ends at MAX_POINTS / MAX_PIECES and the
 * result stays readable.
 *
 * Progress is the fraction of the call done: each stage owns a share of
 * [0, 1] (pc_budget_stage) and reports how far it is inside it; what the
 * callback sees never decreases and is 1 exactly once, when the call ends
 * with its work complete.
 */
#ifndef PC_COMMON_BUDGET_H
#define PC_COMMON_BUDGET_H

#include "projcurve.h"

/* Units of work between two readings of the clock and two calls of the
 * progress callback. A unit costs from ~0.1 us (a traced step on a
 * bicubic) to tens of us (a traced step or a foot-point sub-patch on a
 * rational surface of degree 6 x 8), so polls are ~20 us to ~20 ms apart:
 * the time limit is met to about that, the callback's rate is bounded,
 * and the clock's ~25 ns per read stays far below the work's cost. */
#define PC_BUDGET_POLL_EVERY 256u

typedef struct pc_budget pc_budget;

/* A clock in seconds (monotonic). Replaceable for tests of this module. */
typedef double (*pc_budget_clock_fn)(void *user);

struct pc_budget {
    projcurve_progress_fn progress; /* NULL: no callback */
    void *progress_user;
    double time_limit;              /* seconds; 0 = none */
    unsigned long long max_work;    /* units; 0 = none */
    pc_budget_clock_fn clock;       /* NULL: no time limit to watch */
    void *clock_user;
    double start;                   /* clock at the start of the call */
    unsigned long long work;        /* units polled so far */
    unsigned long long next_poll;   /* work count of the next full poll */
    double stage_lo, stage_hi;      /* the current stage's share of [0, 1] */
    double reported;                /* the last fraction given to the callback */
    projcurve_status status;        /* OK, LIMIT_REACHED or CANCELLED; sticky */
    int stopped_by;                 /* what set status: a PC_BUDGET_STOP_* */
    const char *step;               /* the named step polling now (NULL: none) */
    const char *stopped_in;         /* step at the stop, for the message */
};

enum { PC_BUDGET_STOP_NONE, PC_BUDGET_STOP_TIME, PC_BUDGET_STOP_WORK, PC_BUDGET_STOP_CANCEL };

/* The monotonic clock (CLOCK_MONOTONIC), in seconds. */
double pc_budget_monotonic(void *unused);

/* A budget for one call: time_limit seconds (0 = none), max_work units
 * (0 = none), progress callback (may be NULL). The clock is read here once
 * when a time limit is set. */
void pc_budget_init(pc_budget *b, double time_limit, unsigned long long max_work,
                    projcurve_progress_fn progress, void *progress_user);

/* The same with another clock (tests of this module). */
void pc_budget_init_clock(pc_budget *b, double time_limit, unsigned long long max_work,
                          projcurve_progress_fn progress, void *progress_user,
                          pc_budget_clock_fn clock, void *clock_user);

/* The next stage owns the fractions [lo, hi] of the call (0 <= lo <= hi <= 1). */
void pc_budget_stage(pc_budget *b, double lo, double hi);

/* The steps after tracing that poll the budget (selecting the hits,
 * verifying) name themselves for the message of a stop inside them
 * ("... was reached while <step>"); NULL when the step is over. */
void pc_budget_step(pc_budget *b, const char *step);

/* The budget b when it has not stopped yet, else NULL: a step that runs
 * on a partial result (after a stop) runs to its end, bounded by that
 * result's size, instead of stopping at its first poll. */
static inline pc_budget *pc_budget_if_running(pc_budget *b)
{
    return b != NULL && b->status == PROJCURVE_OK ? b : NULL;
}

/* The full poll behind pc_budget_check: the status of a stopped budget,
 * else the work limit, the clock, the callback. */
projcurve_status pc_budget_poll(pc_budget *b, double stage_fraction);

/* Counts one unit of work done; 1 when pc_budget_poll is due (a full
 * poll, or the budget has stopped). The hottest loops (the tracer's) call
 * this and compute the fraction for pc_budget_poll only then. b may be
 * NULL: no budget, never due. */
static inline int pc_budget_tick(pc_budget *b)
{
    return b != NULL && (b->status != PROJCURVE_OK || ++b->work >= b->next_poll);
}

/* One unit of work done; stage_fraction in [0, 1] is how far the current
 * stage is (clamped; values below an earlier one are ignored). Returns OK
 * to go on, or LIMIT_REACHED (time or work limit) or CANCELLED (the
 * callback asked to stop), and then the same at every later call.
 * b may be NULL: no budget, always OK. */
static inline projcurve_status pc_budget_check(pc_budget *b, double stage_fraction)
{
    return pc_budget_tick(b) ? pc_budget_poll(b, stage_fraction) : PROJCURVE_OK;
}

/* The status the budget stopped with (OK while it has not). */
static inline projcurve_status pc_budget_status(const pc_budget *b)
{
    return b == NULL ? PROJCURVE_OK : b->status;
}

/* Records in ctx why the budget stopped the call and returns its status
 * (OK, recording nothing, when it has not). */
projcurve_status pc_budget_fail(const pc_budget *b, projcurve_context *ctx);

/* The call's work is complete: the callback sees 1 (its return value no
 * longer matters). Not called when the call stops early. */
void pc_budget_finish(pc_budget *b);

#endif /* PC_COMMON_BUDGET_H */
