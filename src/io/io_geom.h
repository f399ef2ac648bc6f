/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Raw spline geometry as the readers find it in files, before it becomes a
 * surface or curve handle, and the exact conversions the readers need:
 * lines and circular arcs as NURBS, affine transformations, restriction of a
 * curve to a sub-range and the joining of several curves into one.
 *
 * Every array lives in the caller's arena (one per read), so an error path
 * never has anything to free.
 */
#ifndef PC_IO_GEOM_H
#define PC_IO_GEOM_H

#include <stddef.h>

#include "analytic/analytic.h"
#include "common/arena.h"
#include "projcurve.h"

/* Raw curves and surfaces are those of the analytic module, so that its
 * exact conversions need no copy: a curve has n_ctrl points (3 doubles),
 * weights (n_ctrl, or NULL when polynomial) and n_ctrl + degree + 1 knots;
 * a surface's control net has the u index fastest. */
typedef pc_rational_curve pc_io_curve;
typedef pc_rational_surface pc_io_surface;

/* An affine map x -> R x + T stored row by row as IGES entity 124 does:
 * {R11, R12, R13, T1, R21, R22, R23, T2, R31, R32, R33, T3}. */
typedef struct pc_io_affine {
    double m[12];
} pc_io_affine;

void pc_io_affine_identity(pc_io_affine *a);
/* outer o inner: first inner, then outer. */
pc_io_affine pc_io_affine_compose(const pc_io_affine *outer, const pc_io_affine *inner);
void pc_io_affine_apply(const pc_io_affine *a, const double p[3], double out[3]);
/* Applies a to every control point (exact for NURBS: affine maps commute
 * with the rational basis because the weights sum the basis to one). */
void pc_io_affine_points(const pc_io_affine *a, double *ctrl, size_t n_points);

/* The segment p0 -> p1 as a degree-1 curve over [0, |p1 - p0|] (or [0, 1] for
 * a degenerate segment). Returns NO_MEMORY or OK. */
projcurve_status pc_io_line_curve(projcurve_context *ctx, pc_arena *arena, const double p0[3],
                                  const double p1[3], pc_io_curve *out);

/* The arc centre + r (cos a x_axis + sin a y_axis), a in [a0, a1] (a1 > a0,
 * at most one turn), as an exact rational quadratic: pc_ellipse_arc with
 * both semi-axes r (angles in radians, knots at the segment ends' angles). */
projcurve_status pc_io_arc_curve(projcurve_context *ctx, pc_arena *arena,
                                 const double centre[3], const double x_axis[3],
                                 const double y_axis[3], double radius, double a0, double a1,
                                 pc_io_curve *out);

/* The part of c over [a, b] (inside the knot domain, a < b), with clamped
 * knots, by knot insertion: exact. */
projcurve_status pc_io_curve_restrict(projcurve_context *ctx, pc_arena *arena,
                                      const pc_io_curve *c, double a, double b,
                                      pc_io_curve *out);

/* The part of s over [u0, u1] x [v0, v1] (clamped to its knot domain; a
 * direction whose range is empty or the whole domain is left as it is), by
 * restricting every row and then every column: exact. */
projcurve_status pc_io_surface_restrict(projcurve_context *ctx, pc_arena *arena,
                                        const pc_io_surface *s, double u0, double u1, double v0,
                                        double v1, pc_io_surface *out);

/* Joins curves that meet end to start into one curve: each is split into
 * Bezier segments, raised to the highest degree, and the segments are
 * chained with C0 knots; rational parts are rescaled so that the
 * homogeneous points agree at the joins. Each part keeps its own parameter
 * length. Gaps larger than gap_tol give INVALID_ARGUMENT naming the part. */
projcurve_status pc_io_curve_join(projcurve_context *ctx, pc_arena *arena,
                                  const pc_io_curve *parts, size_t n_parts, double gap_tol,
                                  pc_io_curve *out);

/* Domain [knots[degree], knots[n_ctrl]] of a raw curve. */
void pc_io_curve_domain(const pc_io_curve *c, double *t0, double *t1);

#endif /* PC_IO_GEOM_H */
