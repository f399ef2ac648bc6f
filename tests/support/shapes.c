/* SPDX-License-Identifier: BSD-3-Clause */
#include "shapes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"

/* The unit circle as a 9-point rational quadratic: corners of the square
 * (weight sqrt(2)/2) between the axis points (weight 1). */
static const double k_circle_xy[9][2] = {{1, 0},  {1, 1},   {0, 1},  {-1, 1}, {-1, 0},
                                         {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
static const double k_circle_knots[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
static double circle_weight(size_t i) { return i % 2 == 1 ? sqrt(0.5) : 1.0; }

/* The half circle from (0, -1) to (0, 1) through (1, 0), in (rho, z). */
static const double k_half_rz[5][2] = {{0, -1}, {1, -1}, {1, 0}, {1, 1}, {0, 1}};
static const double k_half_knots[8] = {0, 0, 0, 0.5, 0.5, 1, 1, 1};

static double *alloc_doubles(size_t n)
{
    double *p = calloc(n, sizeof(double));
    if (p == NULL) {
        fprintf(stderr, "shapes: out of memory\n");
        exit(EXIT_FAILURE);
    }
    return p;
}

static double *copy_doubles(const double *src, size_t n)
{
    double *p = alloc_doubles(n);
    for (size_t i = 0; i < n; ++i)
        p[i] = src[i];
    return p;
}

void pc_shape_surface_free(pc_shape_surface *s)
{
    free(s->ctrl);
    free(s->weights);
    free(s->knots_u);
    free(s->knots_v);
    s->ctrl = s->weights = s->knots_u = s->knots_v = NULL;
}

void pc_shape_curve_free(pc_shape_curve *c)
{
    free(c->ctrl);
    free(c->weights);
    free(c->knots);
    c->ctrl = c->weights = c->knots = NULL;
}

projcurve_surface *pc_shape_surface_create(const pc_shape_surface *s)
{
    projcurve_surface *out = NULL;
    const projcurve_status st =
        projcurve_surface_create_nurbs(NULL, s->deg_u, s->deg_v, s->n_u, s->n_v, s->ctrl,
                                       s->weights, s->knots_u, s->knots_v, &out);
    if (st != PROJCURVE_OK)
        fprintf(stderr, "shapes: surface creation failed: %s\n", projcurve_status_string(st));
    return out;
}

projcurve_curve *pc_shape_curve_create(const pc_shape_curve *c)
{
    projcurve_curve *out = NULL;
    const projcurve_status st = projcurve_curve_create_nurbs(NULL, c->degree, c->n_ctrl, c->ctrl,
                                                             c->weights, c->knots, &out);
    if (st != PROJCURVE_OK)
        fprintf(stderr, "shapes: curve creation failed: %s\n", projcurve_status_string(st));
    return out;
}

pc_shape_curve pc_shape_circle(const double centre[3], double radius)
{
    pc_shape_curve c = {2, 9, alloc_doubles(27), alloc_doubles(9), copy_doubles(k_circle_knots, 12)};
    for (size_t i = 0; i < 9; ++i) {
        c.ctrl[3 * i] = centre[0] + radius * k_circle_xy[i][0];
        c.ctrl[3 * i + 1] = centre[1] + radius * k_circle_xy[i][1];
        c.ctrl[3 * i + 2] = centre[2];
        c.weights[i] = circle_weight(i);
    }
    return c;
}

/* Surface of revolution about the z axis of a rational profile (rho_j, z_j)
 * with weights wp_j: P_ij = (rho_j X_i, rho_j Y_i, z_j), w_ij = wc_i wp_j. */
static pc_shape_surface revolve(int deg_v, size_t n_v, const double (*profile)[2],
                                const double *profile_w, const double *knots_v, size_t n_knots_v,
                                const double centre[3])
{
    pc_shape_surface s = {2, deg_v, 9, n_v, alloc_doubles(27 * n_v), alloc_doubles(9 * n_v),
                          copy_doubles(k_circle_knots, 12), copy_doubles(knots_v, n_knots_v)};
    for (size_t j = 0; j < n_v; ++j)
        for (size_t i = 0; i < 9; ++i) {
            const size_t k = j * 9 + i;
            s.ctrl[3 * k] = centre[0] + profile[j][0] * k_circle_xy[i][0];
            s.ctrl[3 * k + 1] = centre[1] + profile[j][0] * k_circle_xy[i][1];
            s.ctrl[3 * k + 2] = centre[2] + profile[j][1];
            s.weights[k] = circle_weight(i) * profile_w[j];
        }
    return s;
}

pc_shape_surface pc_shape_sphere(const double centre[3], double r)
{
    double profile[5][2], w[5];
    for (size_t j = 0; j < 5; ++j) {
        profile[j][0] = r * k_half_rz[j][0];
        profile[j][1] = r * k_half_rz[j][1];
        w[j] = j % 2 == 1 ? sqrt(0.5) : 1.0;
    }
    return revolve(2, 5, (const double(*)[2])profile, w, k_half_knots, 8, centre);
}

pc_shape_surface pc_shape_cylinder(double r, double height)
{
    const double profile[2][2] = {{r, 0}, {r, height}};
    const double w[2] = {1, 1}, knots[4] = {0, 0, 1, 1}, origin[3] = {0, 0, 0};
    return revolve(1, 2, profile, w, knots, 4, origin);
}

pc_shape_surface pc_shape_cone(double height)
{
    const double profile[2][2] = {{0, 0}, {height, height}};
    const double w[2] = {1, 1}, knots[4] = {0, 0, 1, 1}, origin[3] = {0, 0, 0};
    return revolve(1, 2, profile, w, knots, 4, origin);
}

pc_shape_surface pc_shape_torus(double R, double r)
{
    double profile[9][2], w[9];
    for (size_t j = 0; j < 9; ++j) {
        profile[j][0] = R + r * k_circle_xy[j][0];
        profile[j][1] = r * k_circle_xy[j][1];
        w[j] = circle_weight(j);
    }
    const double origin[3] = {0, 0, 0};
    return revolve(2, 9, (const double(*)[2])profile, w, k_circle_knots, 12, origin);
}

void pc_shape_uniform_knots(int degree, size_t n_ctrl, double *knots)
{
    const size_t p = (size_t)degree, spans = n_ctrl - p;
    for (size_t k = 0; k < n_ctrl + p + 1; ++k) {
        if (k <= p)
            knots[k] = 0.0;
        else if (k >= n_ctrl)
            knots[k] = 1.0;
        else
            knots[k] = (double)(k - p) / (double)spans;
    }
}

/* Greville abscissa of control point i: the mean of knots i+1 .. i+p. A
 * spline with these as coefficients reproduces the identity function. */
static double greville(const double *knots, int degree, size_t i)
{
    double sum = 0.0;
    for (size_t k = 1; k <= (size_t)degree; ++k)
        sum += knots[i + k];
    return sum / degree;
}

static pc_shape_surface grid_surface(int deg_u, int deg_v, size_t spans_u, size_t spans_v)
{
    pc_shape_surface s = {deg_u, deg_v, spans_u + (size_t)deg_u, spans_v + (size_t)deg_v,
                          NULL, NULL, NULL, NULL};
    s.ctrl = alloc_doubles(3 * s.n_u * s.n_v);
    s.knots_u = alloc_doubles(s.n_u + (size_t)deg_u + 1);
    s.knots_v = alloc_doubles(s.n_v + (size_t)deg_v + 1);
    pc_shape_uniform_knots(deg_u, s.n_u, s.knots_u);
    pc_shape_uniform_knots(deg_v, s.n_v, s.knots_v);
    return s;
}

pc_shape_surface pc_shape_plane(int deg_u, int deg_v, size_t spans_u, size_t spans_v)
{
    pc_shape_surface s = grid_surface(deg_u, deg_v, spans_u, spans_v);
    for (size_t j = 0; j < s.n_v; ++j)
        for (size_t i = 0; i < s.n_u; ++i) {
            double *pt = s.ctrl + 3 * (j * s.n_u + i);
            pt[0] = 2.0 * greville(s.knots_u, deg_u, i) - 1.0;
            pt[1] = 3.0 * greville(s.knots_v, deg_v, j) - 1.0;
            pt[2] = 0.0;
        }
    return s;
}

pc_shape_surface pc_shape_bumpy(unsigned long long seed, size_t spans_u, size_t spans_v,
                                double amplitude, int rational)
{
    pc_shape_surface s = grid_surface(3, 3, spans_u, spans_v);
    pc_test_rng rng;
    pc_test_rng_seed(&rng, seed);
    if (rational)
        s.weights = alloc_doubles(s.n_u * s.n_v);
    for (size_t j = 0; j < s.n_v; ++j)
        for (size_t i = 0; i < s.n_u; ++i) {
            const size_t k = j * s.n_u + i;
            s.ctrl[3 * k] = greville(s.knots_u, 3, i);
            s.ctrl[3 * k + 1] = greville(s.knots_v, 3, j);
            s.ctrl[3 * k + 2] = pc_test_rng_uniform(&rng, -amplitude, amplitude);
            if (rational)
                s.weights[k] = pc_test_rng_uniform(&rng, 0.5, 2.0);
        }
    return s;
}

pc_shape_curve pc_shape_random_curve(unsigned long long seed, int degree, size_t n_ctrl)
{
    pc_shape_curve c = {degree, n_ctrl, alloc_doubles(3 * n_ctrl), NULL,
                        alloc_doubles(n_ctrl + (size_t)degree + 1)};
    pc_test_rng rng;
    pc_test_rng_seed(&rng, seed);
    for (size_t i = 0; i < 3 * n_ctrl; ++i)
        c.ctrl[i] = pc_test_rng_uniform(&rng, -1.0, 1.0);
    pc_shape_uniform_knots(degree, n_ctrl, c.knots);
    return c;
}

int pc_shape_line_fn(void *user, double t, double out[9])
{
    const pc_shape_line *l = user;
    for (int i = 0; i < 3; ++i) {
        out[i] = l->p0[i] + t * l->d[i];
        out[3 + i] = l->d[i];
        out[6 + i] = 0.0;
    }
    return 0;
}
