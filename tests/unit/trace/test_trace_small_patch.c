/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A long curve passing over a small surface (issues 14, 18): the curve is
 * 100 long, the surface a planar B-spline w = 0.01 wide, so the rays of
 * P(t) meet it over a t interval (1e-4 directional, 5e-5 conical)
 * narrower than the smallest step of the jump sweep (1/4096 of the
 * domain; in practice its step is ds / |P'| / 2, 1/128 here): the sweep
 * must narrow its step where the curve piece between two checks may reach
 * a patch that neither check's ray meets, instead of stepping over it.
 * The same at w = 0.3 (intervals 3e-3, 1.5e-3, below the sweep's step but
 * not its floor) through the whole pipeline (composition, verification).
 * At w = 0.01 the tracing alone is checked (composition off): the
 * corrector's tolerance is 1e-12 of the surface's size, 1.4e-14, while
 * P(t) near t = 0.5 resolves x only to 100 ulp(0.5) = 1.1e-14, which the
 * verification of the composed pieces does not survive (a precision
 * limit of such a pair, not of the sweep).
 *
 * Oracle (analytic): the surface lies in the plane z = 0 and its sides
 * u = 0 and u = 1 are the lines x = X0 and x = X0 + w (clamped ends: the
 * first and last columns of the net), crossed by the rays of the straight
 * curve P(t) = (-50 + 100 t, w / 2, 5) where x (directional: P(t) itself;
 * conical from E: 2 P - E, the ray's point at z = 0) equals them. The
 * result must be exactly one branch from the entry to the exit, starting
 * and ending on the boundary, with every vertex on S and on its ray.
 */
#include <math.h>
#include <stdio.h>

#include "check.h"

/* The surface: x in [X0, X0 + w], y in [0, w], z = 0. X0 is not dyadic in
 * t, so no check lands on the interval by chance. */
#define X0 0.3
/* The curve's height. It runs over the middle of the surface, y = w / 2. */
#define CURVE_Z 5.0
#define HALF_LENGTH 50.0
/* Vertices on S (|z|) and on their rays (distance) to this, model units:
 * the corrector's tolerance is 1e-12 of the model size (~100). */
#define ON_RAY_TOL 1e-10
/* The branch's ends in t: a boundary exit is snapped onto the side (u
 * exact to 1e-12 of the domain), and the vertex is on its ray to
 * ON_RAY_TOL, i.e. x to 1e-10, t to 1e-12 (|P'| = 100); 1e-11 leaves a
 * factor 10 for the exit's location. */
#define END_T_TOL 1e-11

/* A planar bi-quadratic B-spline with one inner knot each way; its inner
 * columns are moved in x (not a linear parametrisation: the sides stay
 * the lines x = X0, x = X0 + w). */
static projcurve_surface *small_surface(double w)
{
    static const double knots[7] = {0, 0, 0, 0.5, 1, 1, 1};
    static const double col[4] = {0.0, 0.3, 0.8, 1.0};
    double ctrl[3 * 16];
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            double *c = ctrl + 3 * (4 * j + i);
            c[0] = X0 + w * col[i];
            c[1] = w * (double)j / 3.0;
            c[2] = 0.0;
        }
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(NULL, 2, 2, 4, 4, ctrl, NULL, knots, knots, &s));
    return s;
}

/* P(t) = (-50 + 100 t, y0, CURVE_Z) over [0, 1]: degree 1, or degree 3
 * with evenly spaced collinear control points (the same parametrisation). */
static projcurve_curve *long_line(int degree, double y0)
{
    double ctrl[3 * 4], knots[8];
    for (int i = 0; i <= degree; ++i) {
        ctrl[3 * i] = -HALF_LENGTH + 2.0 * HALF_LENGTH * (double)i / degree;
        ctrl[3 * i + 1] = y0;
        ctrl[3 * i + 2] = CURVE_Z;
        knots[i] = 0.0;
        knots[degree + 1 + i] = 1.0;
    }
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, degree, (size_t)degree + 1, ctrl, NULL, knots,
                                          &c));
    return c;
}

static double curve_x(double t)
{
    return -HALF_LENGTH + 2.0 * HALF_LENGTH * t;
}

/* Distance of x from the line through a and b. */
static double line_distance(const double a[3], const double b[3], const double x[3])
{
    const double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double w[3] = {x[0] - a[0], x[1] - a[1], x[2] - a[2]};
    const double c[3] = {d[1] * w[2] - d[2] * w[1], d[2] * w[0] - d[0] * w[2],
                         d[0] * w[1] - d[1] * w[0]};
    return sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) /
           sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

/* One branch over [t_in, t_out], from side to side, each vertex on S (the
 * plane z = 0) and on its ray: along -z (eye NULL) or from the eye. */
static void check_result(const char *name, const projcurve_surface *s, double y0,
                         projcurve_status st, const projcurve_result *r, const double *eye,
                         double t_in, double t_out)
{
    CHECK_STATUS(st, PROJCURVE_OK);
    const size_t n = r != NULL ? projcurve_result_branch_count(r) : 0;
    if (n != 1)
        printf("  %s: %zu branches, expected 1 over t in [%.9g, %.9g]\n", name, n, t_in, t_out);
    CHECK(n == 1);
    if (n != 1)
        return;
    double range[2];
    projcurve_branch_start start;
    projcurve_branch_end end;
    CHECK_OK(projcurve_result_branch_info(NULL, r, 0, range, &start, &end, NULL, NULL));
    CHECK(start == PROJCURVE_START_BOUNDARY);
    CHECK(end == PROJCURVE_END_BOUNDARY);
    CHECK_NEAR(range[0], t_in, END_T_TOL);
    CHECK_NEAR(range[1], t_out, END_T_TOL);
    static double pts[3 * 4096];
    size_t count = 0;
    CHECK_OK(projcurve_result_branch_points(NULL, r, 0, 4096, pts, &count));
    CHECK(count >= 2 && count <= 4096);
    double worst_z = 0.0, worst_ray = 0.0;
    for (size_t k = 0; k < count && k < 4096; ++k) {
        const double t = pts[3 * k];
        double x[3];
        CHECK_OK(projcurve_surface_eval(NULL, s, pts[3 * k + 1], pts[3 * k + 2], 0, x));
        const double p[3] = {curve_x(t), y0, CURVE_Z};
        const double q[3] = {p[0], p[1], 0.0};
        worst_z = fmax(worst_z, fabs(x[2]));
        worst_ray = fmax(worst_ray, line_distance(eye != NULL ? eye : q, p, x));
    }
    CHECK_NEAR(worst_z, 0.0, ON_RAY_TOL);
    CHECK_NEAR(worst_ray, 0.0, ON_RAY_TOL);
}

/* Default options but composition, off for the tracing alone. */
static projcurve_options *options(int compose)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, compose));
    return o;
}

static void directional_case(double w, int compose, int degree)
{
    projcurve_surface *s = small_surface(w);
    projcurve_curve *c = long_line(degree, 0.5 * w);
    projcurve_options *o = options(compose);
    const double dir[3] = {0.0, 0.0, -1.0};
    projcurve_result *r = NULL;
    const projcurve_status st = projcurve_project_directional(NULL, s, c, dir, o, &r);
    /* x(t) = X0 and X0 + w */
    const double t_in = (X0 + HALF_LENGTH) / (2.0 * HALF_LENGTH);
    const double t_out = (X0 + w + HALF_LENGTH) / (2.0 * HALF_LENGTH);
    char name[96];
    snprintf(name, sizeof name, "directional, w %g, compose %d, degree %d", w, compose, degree);
    check_result(name, s, 0.5 * w, st, r, NULL, t_in, t_out);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

static void conical_case(double w, int compose, int degree)
{
    projcurve_surface *s = small_surface(w);
    projcurve_curve *c = long_line(degree, 0.5 * w);
    projcurve_options *o = options(compose);
    /* the eye twice as high as the curve: the ray through P(t) meets z = 0
     * at x = 2 P.x - E.x, on the surface for P.x in [(X0 + E.x) / 2,
     * (X0 + w + E.x) / 2] */
    const double eye[3] = {X0 + 0.5 * w, 0.5 * w, 2.0 * CURVE_Z};
    projcurve_result *r = NULL;
    const projcurve_status st = projcurve_project_conical(NULL, s, c, eye, o, &r);
    const double t_in = (0.5 * (X0 + eye[0]) + HALF_LENGTH) / (2.0 * HALF_LENGTH);
    const double t_out = (0.5 * (X0 + w + eye[0]) + HALF_LENGTH) / (2.0 * HALF_LENGTH);
    char name[96];
    snprintf(name, sizeof name, "conical, w %g, compose %d, degree %d", w, compose, degree);
    check_result(name, s, 0.5 * w, st, r, eye, t_in, t_out);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

int main(void)
{
    pc_test_hang_guard(60);
    /* {width, compose}: see the top of the file */
    static const struct {
        double w;
        int compose;
    } cases[] = {{0.01, 0}, {0.3, 1}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k)
        for (int degree = 1; degree <= 3; degree += 2) {
            directional_case(cases[k].w, cases[k].compose, degree);
            conical_case(cases[k].w, cases[k].compose, degree);
        }
    return pc_test_finish("test_trace_small_patch");
}
