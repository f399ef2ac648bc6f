/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The exact points a fit is made to: a growable list kept in increasing t.
 */
#ifndef PC_FIT_SAMPLES_H
#define PC_FIT_SAMPLES_H

#include <stddef.h>

#include "fit/branch_view.h"

typedef struct pc_fit_samples {
    pc_fit_sample *items;
    size_t count, capacity;
    int unsorted;  /* appended out of order since the last pc_fit_samples_sort */
    size_t sorted; /* items[0 .. sorted) were in order at the last sort */
} pc_fit_samples;

/* Doubles from one sample to the next, for pc_lsq_fit's stride. */
#define PC_FIT_SAMPLE_STRIDE (sizeof(pc_fit_sample) / sizeof(double))

/* Statuses: OK, NO_MEMORY. */
projcurve_status pc_fit_samples_push(projcurve_context *ctx, pc_fit_samples *s,
                                     const pc_fit_sample *x);
void pc_fit_samples_sort(pc_fit_samples *s);
void pc_fit_samples_free(pc_fit_samples *s);

/* The first sample of every piece's ends and `inner` exact points inside
 * each piece (evenly in t). Returns OK with *complete 0 when an exact
 * point could not be had (budget stopped, or the corrector failed).
 * Statuses: OK, NO_MEMORY. */
projcurve_status pc_fit_samples_from_pieces(projcurve_context *ctx, pc_fit_branch *fb,
                                            int inner, pc_fit_samples *s, int *complete);

#endif /* PC_FIT_SAMPLES_H */
