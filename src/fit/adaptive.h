/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The fit of one spline to the exact projection of a branch, by least
 * squares over a knot vector that grows where the error is: after each
 * fit, a span whose samples are farther than the target from the spline is
 * cut into k equal spans, k from the error's decay with the span length
 * (h^(degree + 1): k = (error / target)^(1 / (degree + 1)), 2..4). When
 * every sample is within the target, the spline is checked against fresh
 * exact points, PC_FIT_CHECK_PER_SPAN per span; the spans where a check
 * point is beyond the limit are cut in turn (the point joins the samples).
 * Bounded by PC_FIT_MAX_ROUNDS rounds and goal->max_poles poles: when
 * either is hit, or an exact point cannot be had, there is no fit.
 */
#ifndef PC_FIT_ADAPTIVE_H
#define PC_FIT_ADAPTIVE_H

#include <stddef.h>

#include "fit/samples.h"
#include "trace/result.h"

#define PC_FIT_CHECK_PER_SPAN 10
#define PC_FIT_MAX_ROUNDS 64

typedef struct pc_fit_goal {
    int degree;
    int dim;          /* 2: q(t) in (u, v), measured in 3D through S; 3: S(q(t)) */
    double target;    /* every sample within this (model units) */
    double limit;     /* every check point within this */
    size_t max_poles; /* no fit with more */
    int refine;       /* 0: the given knots only (one fit, then the check) */
} pc_fit_goal;

typedef struct pc_fit_curve {
    pc_bspline spline; /* malloc'd; weights NULL when polynomial */
    double error;      /* the largest distance the check found */
} pc_fit_curve;

/* Fits goal's spline to the samples (sorted, from t_lo to t_hi, which it
 * adds to) starting from the clamped knots (n_knots values) and weights
 * (NULL: polynomial; else fixed, one per pole, and goal->refine must be
 * 0). *ok is 1 with *out filled (release with pc_fit_curve_free), or 0.
 * Statuses: OK, NO_MEMORY. */
projcurve_status pc_fit_adaptive(projcurve_context *ctx, pc_fit_branch *fb,
                                 const pc_fit_goal *goal, const double *knots, size_t n_knots,
                                 const double *weights, pc_fit_samples *data,
                                 pc_fit_curve *out, int *ok);

void pc_fit_curve_free(pc_fit_curve *c);

#endif /* PC_FIT_ADAPTIVE_H */
