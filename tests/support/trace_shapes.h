/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Surfaces and curves with known directional projections, for the tracing
 * tests. Every builder returns NULL on failure (and the test then fails on
 * its first CHECK of the handle).
 */
#ifndef PC_TEST_TRACE_SHAPES_H
#define PC_TEST_TRACE_SHAPES_H

#include <stddef.h>

#include "projcurve.h"

/* A clamped uniform B-spline curve of the given degree through n points
 * (3 doubles each) as control points, domain [0, 1]. */
projcurve_curve *shape_bspline_curve(int degree, size_t n, const double *pts);

/* The plane O + u A + v B, (u, v) in [0, 1]^2 (bilinear patch). */
projcurve_surface *shape_plane(const double o[3], const double a[3], const double b[3]);

/* Half cylinder x^2 + z^2 = r^2, z >= 0, y in [0, len]: exact rational
 * quadratic in u (two quarter circles, from x = r to x = -r), linear in v. */
projcurve_surface *shape_half_cylinder(double r, double len);

/* Sphere of radius r about the origin (pc_shape_sphere of shapes.h): u
 * around the z axis, v the meridian from the south pole to the north pole
 * (collapsed edges at v = 0 and v = 1). */
projcurve_surface *shape_sphere(double r);

/* [SY13] s5 Example 1: the degree 5 x 1 Bezier sheet and its cubic
 * B-spline test curve. */
projcurve_surface *shape_example1_surface(void);
projcurve_curve *shape_example1_curve(void);

/* A C-folded sheet, extruded along y in [0, 100]: bottom z = 0 from x = 0
 * to 100, a bend whose tip is near x = 110 (z = 10), top z = 20 from x = 100
 * back to x = 20 (quadratic B-spline profile, linear in y). */
projcurve_surface *shape_c_fold(void);

/* A Z-folded sheet (three layers at z = 0, 20, 40, the bottom from x = 20
 * to 100, the middle from 100 back to 10, the top from 10 to about 55): a
 * ray from above meets it three times where the layers overlap. Quadratic
 * B-spline profile in the xz-plane, extruded along y in [0, 100]. */
projcurve_surface *shape_z_fold(void);

/* Two sheets meeting at a point inside the domain: biquadratic, the
 * control row at v = 0.5 collapsed to (50, 50, 10) with a double knot
 * there, so that the surface passes through it and the whole row v = 0.5
 * (the edge the two patch rows share) maps to that point (Su = 0 on it).
 * Rows at y = 0, 25 (z = 0, 5) span x in [0, 100], as do the rows at
 * y = 75, 100 (z = 5, 0); the sheet narrows to the point between them. */
projcurve_surface *shape_pinched_sheet(void);

/* A bicubic bumpy sheet over [0, 100]^2 (heights from a fixed seed, within
 * +-amp), 8 x 8 control net, domain [0, 1]^2. */
projcurve_surface *shape_bumpy(double amp, unsigned long long seed);

#endif /* PC_TEST_TRACE_SHAPES_H */
