/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Least-squares fits used to read growth rates off the scaling curves.
 */
#ifndef PCB_FIT_H
#define PCB_FIT_H

#include <stddef.h>

/* y ~ c * x^exponent: least squares on (ln x, ln y) over the points with
 * x > 0 and y > 0. Returns the exponent (NaN with fewer than 2 points). */
double pcb_fit_power(const double *x, const double *y, size_t n);

/* y ~ a + b * ln x: least squares over the points with x > 0; *a and *b
 * receive NaN with fewer than 2 points. */
void pcb_fit_log(const double *x, const double *y, size_t n, double *a, double *b);

#endif /* PCB_FIT_H */
