/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Analytic shapes as exact NURBS, for tests: circles, spheres, cylinders,
 * tori (rational quadratic, exact to rounding), planes and random bumpy
 * bicubic patches. Each builder fills plain arrays (pc_shape_surface /
 * pc_shape_curve) so that a test can also feed them through its own
 * independent oracle; pc_shape_*_create makes the library handle.
 */
#ifndef PC_TEST_SHAPES_H
#define PC_TEST_SHAPES_H

#include <stddef.h>

#include "projcurve.h"

typedef struct pc_shape_surface {
    int deg_u, deg_v;
    size_t n_u, n_v;
    double *ctrl;     /* 3 * n_u * n_v, u fastest */
    double *weights;  /* n_u * n_v, or NULL for a B-spline */
    double *knots_u;  /* n_u + deg_u + 1 */
    double *knots_v;  /* n_v + deg_v + 1 */
} pc_shape_surface;

typedef struct pc_shape_curve {
    int degree;
    size_t n_ctrl;
    double *ctrl;     /* 3 * n_ctrl */
    double *weights;  /* or NULL */
    double *knots;    /* n_ctrl + degree + 1 */
} pc_shape_curve;

void pc_shape_surface_free(pc_shape_surface *s);
void pc_shape_curve_free(pc_shape_curve *c);

/* Library handles from the arrays (NULL and a message on stderr on failure). */
projcurve_surface *pc_shape_surface_create(const pc_shape_surface *s);
projcurve_curve *pc_shape_curve_create(const pc_shape_curve *c);

/* The line P(t) = p0 + t d, for projcurve_curve_create_callback with
 * pc_shape_line_fn (user: a pc_shape_line) and as its own closed form. */
typedef struct pc_shape_line {
    double p0[3], d[3];
} pc_shape_line;
int pc_shape_line_fn(void *user, double t, double out[9]);

/* Full circle of the given radius around centre in the plane z = centre[2]:
 * 9-point rational quadratic, domain [0, 1]. */
pc_shape_curve pc_shape_circle(const double centre[3], double radius);

/* Sphere of radius r around centre: u goes around the z axis ([0, 1], full
 * circle), v from the south pole to the north pole ([0, 1]). Bidegree 2. */
pc_shape_surface pc_shape_sphere(const double centre[3], double r);

/* Cylinder x^2 + y^2 = r^2, z in [0, height]: u around (quadratic, [0, 1]),
 * v along z (linear, [0, 1]). */
pc_shape_surface pc_shape_cylinder(double r, double height);

/* Cone x^2 + y^2 = z^2, z in [0, height], apex at the origin: u around
 * (quadratic, [0, 1]), v along the generators (linear, [0, 1]); the edge
 * v = 0 is collapsed to the apex (Su = 0 there). */
pc_shape_surface pc_shape_cone(double height);

/* Torus around the z axis: (sqrt(x^2 + y^2) - R)^2 + z^2 = r^2; u around the
 * axis, v around the tube, both [0, 1]. */
pc_shape_surface pc_shape_torus(double R, double r);

/* The plane z = 0 as a B-spline of degrees (deg_u, deg_v) with spans_u x
 * spans_v uniform spans over [0, 1]^2; S(u, v) = (2u - 1, 3v - 1, 0) exactly
 * (control points at the Greville abscissae). */
pc_shape_surface pc_shape_plane(int deg_u, int deg_v, size_t spans_u, size_t spans_v);

/* A bumpy bicubic B-spline graph z = f(x, y) over [0, 1]^2 (x = u, y = v at
 * the Greville abscissae) with spans x spans uniform spans and control
 * heights uniform in [-amplitude, amplitude], from a deterministic seed.
 * Rational (weights in [0.5, 2]) when rational != 0. */
pc_shape_surface pc_shape_bumpy(unsigned long long seed, size_t spans_u, size_t spans_v,
                                double amplitude, int rational);

/* A random space curve: B-spline of the given degree with n_ctrl points in
 * [-1, 1]^3 and uniform clamped knots over [0, 1]. */
pc_shape_curve pc_shape_random_curve(unsigned long long seed, int degree, size_t n_ctrl);

/* Uniform clamped knot vector of n_ctrl + degree + 1 values over [0, 1]
 * into knots. */
void pc_shape_uniform_knots(int degree, size_t n_ctrl, double *knots);

#endif /* PC_TEST_SHAPES_H */
