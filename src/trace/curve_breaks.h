/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Breaks of the curve P: the interior knots of a NURBS curve where P is
 * less smooth than a given order (a polyline's vertices, the C0 knots of
 * a B-spline wire, the double knots of a cubic). The projection is
 * continuous there but its derivatives jump, so the tracer lands exactly
 * on each corner (order 1) and continues with the derivatives of the side
 * it goes to, and the refinement keeps a vertex there (docs/tracing.md, "Curves with
 * corners"). A callback curve has no known breaks.
 */
#ifndef PC_TRACE_CURVE_BREAKS_H
#define PC_TRACE_CURVE_BREAKS_H

#include "geom/curve.h"

/* P is C^order at a knot of multiplicity m of a degree-p curve when
 * p - m >= order. The tracer and the refinement use order 1 (corners; see
 * trace/branches.c for why the tracer does not land on C1 knots); order 2
 * names the knots where q'' jumps. */
#define PC_BREAK_ORDER_PREDICTOR 2
#define PC_BREAK_ORDER_CORNER 1

/* 1 when t is an interior knot of c at which c is not C^order. O(log n),
 * no allocation. */
int pc_curve_break_at(const projcurve_curve *c, double t, int order);

/* A cursor over the breaks of one curve, for a run that moves t
 * monotonically: the breaks bracketing the last query are kept, so a
 * whole run scans each knot about once. Plain data: nothing to release. */
typedef struct pc_curve_breaks {
    const pc_nurbs_curve *nurbs; /* NULL: no breaks (callback curve) */
    int order;
    double lo, hi; /* consecutive breaks (or domain ends) around the last query */
} pc_curve_breaks;

void pc_curve_breaks_init(pc_curve_breaks *b, const projcurve_curve *c, int order);

/* The nearest break strictly beyond t in the given direction (> 0:
 * increasing t), or the domain end that way when there is none. */
double pc_curve_breaks_next(pc_curve_breaks *b, double t, int direction);

/* The parameter at which to evaluate P for the derivatives on the side of
 * t that the direction points to: the neighbouring double of a break (the
 * span lookup then picks that side's polynomial piece; the point moves by
 * |P'| ulp(t)), t itself elsewhere. */
double pc_curve_break_side(const projcurve_curve *c, double t, int direction, int order);

#endif /* PC_TRACE_CURVE_BREAKS_H */
