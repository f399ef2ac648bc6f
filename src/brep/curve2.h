/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A curve in a surface's parameter plane: a 2D B-spline / NURBS piece of a
 * trimming loop, and its flattening into a polyline with a proven bound.
 *
 * Flattening splits the curve into Bezier segments (knot insertion) and
 * halves each segment (de Casteljau, in homogeneous coordinates) until its
 * control polygon lies within `err` of the chord. With positive weights the
 * curve is in the convex hull of its control points, so every point of the
 * segment, and the whole region swept between the segment and its chord,
 * lies within `err` of the chord: a point farther than `err` from the
 * polyline has the same winding number about the polyline as about the
 * curve.
 */
#ifndef PC_BREP_CURVE2_H
#define PC_BREP_CURVE2_H

#include <stddef.h>

#include "projcurve.h"

typedef struct pc_curve2 {
    int degree;
    size_t n_ctrl;
    double *ctrl;    /* 2 per control point (u, v) */
    double *weights; /* n_ctrl, or NULL when polynomial */
    double *knots;   /* n_ctrl + degree + 1, clamped or not */
} pc_curve2;

/* Checks and copies a piece (degree 1..PROJCURVE_MAX_DEGREE, n_ctrl >
 * degree, knots non-decreasing with a non-empty domain, finite values,
 * weights > 0). `what` names the piece in messages. Statuses: OK,
 * NULL_ARGUMENT, BAD_DEGREE, BAD_COUNT, BAD_KNOTS, NOT_FINITE, BAD_WEIGHT,
 * NO_MEMORY. */
projcurve_status pc_curve2_init(projcurve_context *ctx, pc_curve2 *c, int degree, size_t n_ctrl,
                                const double *ctrl, const double *weights, const double *knots,
                                const char *what);
void pc_curve2_free(pc_curve2 *c);

/* Domain [knots[degree], knots[n_ctrl]]. */
void pc_curve2_domain(const pc_curve2 *c, double *t0, double *t1);

/* The point at t (clamped to the domain), by de Boor's algorithm. */
void pc_curve2_eval(const pc_curve2 *c, double t, double out[2]);

/* A growing polyline of 2D points. */
typedef struct pc_polyline2 {
    double *xy;
    size_t count, capacity;
} pc_polyline2;

/* The most points one piece may be flattened into, and the deepest halving
 * of one Bezier segment: a piece that needs more is refused (LIMIT_REACHED
 * naming it) rather than flattened to a wrong bound. */
#define PC_CURVE2_MAX_POINTS ((size_t)1 << 20)
#define PC_CURVE2_MAX_DEPTH 40

/* Appends the flattening of c (every vertex but the last, so that the
 * pieces of a loop chain up) to line, within err of the curve in the sense
 * above. Statuses: OK, NO_MEMORY, LIMIT_REACHED. */
projcurve_status pc_curve2_flatten(projcurve_context *ctx, const pc_curve2 *c, double err,
                                   pc_polyline2 *line, const char *what);

projcurve_status pc_polyline2_push(projcurve_context *ctx, pc_polyline2 *line, double x,
                                   double y);
void pc_polyline2_free(pc_polyline2 *line);

#endif /* PC_BREP_CURVE2_H */
