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

/* The basis of a spline space at n sample parameters, computed once for a
 * fit and the error pass after it (the knot span search and the basis
 * recurrence were half the cost of an adaptive fit when done twice):
 * sample i touches poles first[i] .. first[i] + degree, with the values
 * values[i * (degree + 1) ..]. Zero-initialise before the first fill. */
typedef struct pc_lsq_rows {
    int degree;
    size_t n;
    size_t *first;  /* cap_first entries */
    double *values; /* cap_values entries */
    size_t cap_first, cap_values;
} pc_lsq_rows;

/* Fills rows with the basis of `space` at the n parameters t, each
 * `stride` doubles after the previous, reusing the arrays of an earlier
 * fill. Statuses: OK, NO_MEMORY (rows keeps its old arrays, n = 0). */
projcurve_status pc_lsq_rows_fill(projcurve_context *ctx, const pc_lsq_space *space,
                                  const double *t, size_t stride, size_t n, pc_lsq_rows *rows);
void pc_lsq_rows_free(pc_lsq_rows *rows);

/* Value of the spline at row i's parameter, as pc_lsq_eval there. */
void pc_lsq_eval_row(const pc_lsq_rows *rows, size_t i, int dim, const double *poles,
                     double *out);

/* pc_lsq_fit over the first n_data rows (the samples' points x as there). */
projcurve_status pc_lsq_fit_rows(projcurve_context *ctx, const pc_lsq_space *space, int dim,
                                 const pc_lsq_rows *rows, const double *x, size_t stride,
                                 size_t n_data, const size_t *fixed_index,
                                 const double *fixed_value, size_t n_fixed, double *poles);

#endif /* PC_FIT_LSQ_H */
