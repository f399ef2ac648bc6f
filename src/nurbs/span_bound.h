/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Bounds of the third partial derivatives of a polynomial B-spline surface
 * over one knot span. The corrector uses them to bound the cubic Taylor
 * remainder of S, so that a Newton step taken on the local quadratic model
 * of the projection equations can be accepted without evaluating S again
 * (see docs/tracing.md, "Newton corrector").
 */
#ifndef PC_NURBS_SPAN_BOUND_H
#define PC_NURBS_SPAN_BOUND_H

#include <math.h>
#include <stddef.h>

#include "nurbs/nurbs.h"

/* m3[k] >= max |d^3 S / du^(3-k) dv^k| over the span [U_su, U_su+1] x
 * [V_sv, V_sv+1] (k = 0..3), from the control points of the derivative
 * surface (hodograph) and the convex hull property. span_u, span_v are span
 * indices as pc_knot_span returns them. Returns 0 (m3 untouched) for a
 * rational surface, for which no such bound is derived here. */
int pc_span_third_bound(const pc_nurbs_surface *s, size_t span_u, size_t span_v,
                        double m3[4]);

/* The same for the second derivatives: m2[k] >= max |d^2 S / du^(2-k)
 * dv^k| over the span (k = 0..2). Returns 0 for a rational surface. */
int pc_span_second_bound(const pc_nurbs_surface *s, size_t span_u, size_t span_v,
                         double m2[3]);

/* Both at once (the cost of one): m2 as pc_span_second_bound, m3 as
 * pc_span_third_bound. Returns 0 (both untouched) for a rational surface. */
int pc_span_bounds(const pc_nurbs_surface *s, size_t span_u, size_t span_v, double m2[3],
                   double m3[4]);

/* Bound of the cubic Taylor remainder of S for the step (du, dv) inside one
 * span: |S(q + d) - (S + S'd + S''[d, d] / 2)| <= this (Lagrange form). */
static inline double pc_span_cubic_remainder(const double m3[4], double du, double dv)
{
    const double x = fabs(du), y = fabs(dv);
    /* (1/6) sum_k C(3, k) m3[k] |du|^(3-k) |dv|^k */
    return (m3[0] * x * x * x + 3.0 * m3[1] * x * x * y + 3.0 * m3[2] * x * y * y +
            m3[3] * y * y * y) *
           (1.0 / 6.0); /* a product, not a division: this is on the hot path */
}

#endif /* PC_NURBS_SPAN_BOUND_H */
