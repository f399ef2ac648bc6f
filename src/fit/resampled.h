/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A curve known by its samples, made compact: a clamped cubic B-spline in
 * the curve's own parameter whose ends are the first and last samples
 * exactly (a loop it belongs to stays closed as it was) and whose interior
 * poles are the least-squares fit of the samples (fit/lsq.h). The caller
 * names the curve's breaks (parameters where it is not C2: a cubic across
 * one converges only as h^2); each is a triple knot, and the intervals
 * between them are cut into uniform spans. A fit is accepted when it lies
 * within tol of every sample and of the exact curve half way between
 * samples. The spans of each interval double from one while 2 samples a
 * span remain, up to PC_FIT_RESAMPLED_MAX_SPANS in all; the first fit
 * accepted is kept. Used for the pcurves the readers make by sampling
 * (mapped onto an analytic surface's NURBS, projected, inverted), which
 * are otherwise polylines of up to 4097 points.
 */
#ifndef PC_FIT_RESAMPLED_H
#define PC_FIT_RESAMPLED_H

#include <stddef.h>

#include "projcurve.h"

#define PC_FIT_RESAMPLED_MAX_SPANS 128
#define PC_FIT_RESAMPLED_MAX_BREAKS 16
#define PC_FIT_RESAMPLED_POLES (PC_FIT_RESAMPLED_MAX_SPANS + 3 * PC_FIT_RESAMPLED_MAX_BREAKS + 3)

/* The exact curve at t, dim coordinates. */
typedef void (*pc_fit_exact_fn)(const void *user, double t, double *out);

typedef struct pc_fit_resampled_input {
    int dim;
    const double *samples; /* n + 1 points of the curve at the parameters below */
    size_t n;
    double t0, t1;
    /* the n + 1 parameters, increasing from t0 to t1; NULL: uniform,
     * t0 + (t1 - t0) i / n */
    const double *t;
    const double *breaks; /* increasing, inside (t0, t1); may be NULL when none */
    size_t n_breaks;      /* at most PC_FIT_RESAMPLED_MAX_BREAKS (else no fit) */
    pc_fit_exact_fn exact;
    const void *user;
    double tol;
} pc_fit_resampled_input;

/* Fits `in`: the poles go to poles (dim * PC_FIT_RESAMPLED_POLES doubles),
 * the knots to knots (PC_FIT_RESAMPLED_POLES + 4), their count to
 * *n_poles; *n_poles is 0 when no fit is within tol (the caller keeps the
 * samples). Statuses: OK, NO_MEMORY. */
projcurve_status pc_fit_resampled_cubic(projcurve_context *ctx, const pc_fit_resampled_input *in,
                                        double *poles, double *knots, size_t *n_poles);

#endif /* PC_FIT_RESAMPLED_H */
