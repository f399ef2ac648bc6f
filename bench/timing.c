/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Timing utilities (see timing.h).
 */
#define _POSIX_C_SOURCE 200809L

#include "timing.h"

#include <stdlib.h>
#include <time.h>

/* Calibration doubles n at most this many times (2^40 calls is far beyond
 * any workload that lasts a few milliseconds). */
#define PCB_MAX_DOUBLINGS 40

static volatile double pcb_sink;

void pcb_consume(double value) { pcb_sink = pcb_sink + value; }

double pcb_now_s(void)
{
    /* CPU time of the process, not wall time: on a machine shared with
     * other work, the time the benchmark waits for a core is not its cost.
     * The benchmarks are single-threaded (Open CASCADE's algorithms too,
     * unless asked to run in parallel), so this is the time of the work. */
    struct timespec ts;
    if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts) != 0)
        clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int compare_doubles(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double pcb_median(double *values, size_t n)
{
    qsort(values, n, sizeof *values, compare_doubles);
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/* One timed run of n calls: seconds per call. */
static int run_once(pcb_work_fn fn, void *user, size_t n, double *per_call)
{
    const double start = pcb_now_s();
    const int rc = fn(user, n);
    *per_call = (pcb_now_s() - start) / (double)n;
    return rc;
}

/* Warm-up, then the smallest power of two n whose run lasts min_run_s;
 * *run_s receives the duration of that run. */
static int calibrate(const pcb_timing *timing, pcb_work_fn fn, void *user, size_t *n_out,
                     double *run_s)
{
    for (int w = 0; w < timing->warmup; ++w) {
        const int rc = fn(user, 1);
        if (rc)
            return rc;
    }
    size_t n = 1;
    for (int k = 0; k < PCB_MAX_DOUBLINGS; ++k) {
        double per_call = 0.0;
        const int rc = run_once(fn, user, n, &per_call);
        if (rc)
            return rc;
        *run_s = per_call * (double)n;
        if (*run_s >= timing->min_run_s)
            break;
        n *= 2;
    }
    *n_out = n;
    return 0;
}

/* Timed runs to make when one run lasts run_s seconds. */
static int reps_for(const pcb_timing *timing, double run_s)
{
    int reps = timing->reps < 1 ? 1 : timing->reps > PCB_MAX_REPS ? PCB_MAX_REPS : timing->reps;
    if (timing->budget_s > 0.0 && run_s * reps > timing->budget_s) {
        const int fit = (int)(timing->budget_s / run_s);
        const int floor_reps = reps < PCB_MIN_REPS ? reps : PCB_MIN_REPS;
        reps = fit < floor_reps ? floor_reps : fit;
    }
    return reps;
}

int pcb_time_median(const pcb_timing *timing, pcb_work_fn fn, void *user,
                    double *seconds_per_call)
{
    size_t n = 1;
    double run_s = 0.0;
    int rc = calibrate(timing, fn, user, &n, &run_s);
    if (rc)
        return rc;
    const int reps = reps_for(timing, run_s);
    double runs[PCB_MAX_REPS];
    for (int r = 0; r < reps; ++r) {
        rc = run_once(fn, user, n, &runs[r]);
        if (rc)
            return rc;
    }
    *seconds_per_call = pcb_median(runs, (size_t)reps);
    return 0;
}

int pcb_time_pair(const pcb_timing *timing, pcb_work_fn a, void *user_a, pcb_work_fn b,
                  void *user_b, pcb_pair *out)
{
    size_t n_a = 1, n_b = 1;
    double run_a = 0.0, run_b = 0.0;
    int rc = calibrate(timing, a, user_a, &n_a, &run_a);
    if (!rc)
        rc = calibrate(timing, b, user_b, &n_b, &run_b);
    if (rc)
        return rc;
    const int reps = reps_for(timing, run_a + run_b);
    double runs_a[PCB_MAX_REPS], runs_b[PCB_MAX_REPS], ratios[PCB_MAX_REPS];
    for (int r = 0; r < reps; ++r) {
        /* Alternate which goes first so that neither always runs on a cold
         * cache or right after the other's frequency ramp. */
        if (r % 2 == 0) {
            rc = run_once(a, user_a, n_a, &runs_a[r]);
            if (!rc)
                rc = run_once(b, user_b, n_b, &runs_b[r]);
        } else {
            rc = run_once(b, user_b, n_b, &runs_b[r]);
            if (!rc)
                rc = run_once(a, user_a, n_a, &runs_a[r]);
        }
        if (rc)
            return rc;
        ratios[r] = runs_a[r] / runs_b[r];
    }
    out->a_s = pcb_median(runs_a, (size_t)reps);
    out->b_s = pcb_median(runs_b, (size_t)reps);
    out->ratio = pcb_median(ratios, (size_t)reps);
    return 0;
}
