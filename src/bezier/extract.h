/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Bezier extraction of a clamped spline (The NURBS Book, A5.6), shared by
 * curve and surface decomposition.
 */
#ifndef PC_BEZIER_EXTRACT_H
#define PC_BEZIER_EXTRACT_H

#include <stddef.h>

/* Number of non-empty knot spans of a clamped knot vector. */
size_t pc_bezier_span_count(const double *knots, size_t n_ctrl, int degree);

/* The span_count + 1 distinct knot values of the domain, into breaks. */
void pc_bezier_breaks(const double *knots, size_t n_ctrl, int degree, double *breaks);

/* Writes the Bezier control points of every span of a clamped spline with
 * n_ctrl points of `dim` doubles: segment k, point i at
 * out + (k * (degree + 1) + i) * dim. out must hold
 * span_count * (degree + 1) * dim doubles. No allocation. */
void pc_bezier_extract(const double *knots, size_t n_ctrl, int degree, const double *pts,
                       size_t dim, double *out);

#endif /* PC_BEZIER_EXTRACT_H */
