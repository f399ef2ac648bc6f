/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Timing: medians of repeated runs after a warm-up, and ratios of two
 * workloads measured pair by pair in the same run.
 *
 * A workload is a function that does its work n times. Each timed run calls
 * it once with an n chosen (by doubling) so that the run lasts at least
 * `min_run_s`, which keeps the clock's resolution and the call overhead out
 * of the figure. The reported time is the median over `reps` runs of
 * (run time / n). Times are CPU time of the process, so that waiting for a
 * core on a shared machine does not count, and medians shrug off the rest
 * of the interference (caches, frequency).
 */
#ifndef PCB_TIMING_H
#define PCB_TIMING_H

#include <stddef.h>

/* Highest number of timed runs of one measurement. */
#define PCB_MAX_REPS 64

typedef struct pcb_timing {
    int warmup;        /* untimed runs before measuring */
    int reps;          /* timed runs, 1..PCB_MAX_REPS; the median is reported */
    double min_run_s;  /* each timed run lasts at least this long */
    double budget_s;   /* 0, or fewer runs (at least PCB_MIN_REPS) when the
                          runs would take longer than this in all */
} pcb_timing;

/* Fewest timed runs a time budget may leave. */
#define PCB_MIN_REPS 3

/* Does the work n times; returns 0, or nonzero on failure (then the
 * measurement stops and reports the failure). */
typedef int (*pcb_work_fn)(void *user, size_t n);

/* Seconds of CPU time used by the process (monotonic; wall time where the
 * CPU clock is missing). */
double pcb_now_s(void);

/* Median seconds per call of fn. Returns 0, or the workload's failure code. */
int pcb_time_median(const pcb_timing *timing, pcb_work_fn fn, void *user,
                    double *seconds_per_call);

/* Two workloads timed alternately, run after run: medians of each and the
 * median of the per-run ratios a / b. */
typedef struct pcb_pair {
    double a_s;    /* median seconds per call of a */
    double b_s;    /* median seconds per call of b */
    double ratio;  /* median over runs of (a / b) within the same run */
} pcb_pair;

int pcb_time_pair(const pcb_timing *timing, pcb_work_fn a, void *user_a, pcb_work_fn b,
                  void *user_b, pcb_pair *out);

/* Median of n values (n >= 1); values are reordered. */
double pcb_median(double *values, size_t n);

/* A sink that the compiler cannot see through, so that benchmarked results
 * are not optimised away. */
void pcb_consume(double value);

#endif /* PCB_TIMING_H */
