/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Least-squares B-spline fitting over a given knot vector: the normal
 * equations are banded (each sample touches degree + 1 poles), solved by a
 * banded Cholesky factorisation in O(n degree^2).
 */
#ifndef PC_FIT_LSQ_H
#define PC_FIT_LSQ_H

#include <stddef.h>

#include "projcurve.h"

/* The spline space: degree, n_poles, clamped knots (n_poles + degree + 1)
 * and weights (NULL: polynomial; else the rational basis
 * R_i = w_i N_i / sum_j w_j N_j, which keeps the fit linear). */
typedef struct pc_lsq_space {
    int degree;
    size_t n_poles;
    const double *knots;
    const double *weights;
} pc_lsq_space;

/* Value at t of the spline of `space` with dim coordinates per pole into
 * out[dim]; *hint (may be NULL) speeds up sequential calls. */
void pc_lsq_eval(const pc_lsq_space *space, int dim, const double *poles, double t,
                 size_t *hint, double *out);

/* Poles minimising sum_i |C(t_i) - x_i|^2 + ridge, with the poles listed in
 * fixed_index (ascending, may be empty) held at fixed_value (dim each).
 * Samples: n_data values t and points x (dim doubles), each `stride`
 * doubles after the previous. The
 * ridge, PC_LSQ_RIDGE of the largest diagonal entry times the squared
 * differences of neighbouring poles, keeps the system definite where a
 * span holds no sample; its pull on a pole is ~1e-12 of the differences.
 * Writes n_poles * dim doubles to poles. Statuses: OK, NO_MEMORY,
 * SINGULAR (the factorisation broke down: the samples do not fix the
 * poles). */
#define PC_LSQ_RIDGE 1e-12
projcurve_status pc_lsq_fit(projcurve_context *ctx, const pc_lsq_space *space, int dim,
                            const double *t, const double *x, size_t stride, size_t n_data,
                            const size_t *fixed_index, const double *fixed_value,
                            size_t n_fixed, double *poles);

#endif /* PC_FIT_LSQ_H */
