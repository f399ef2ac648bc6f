/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Directional projection onto shapes whose projection is known exactly:
 * a plane (an affine map of the curve), a half cylinder and a sphere (exact
 * rational NURBS), each also checked against dense brute force.
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "trace_oracle.h"
#include "shapes.h"
#include "trace_shapes.h"

/* Samples of the brute-force oracle (the issue asks for 10,000). */
#define N_SAMPLES 10000
/* Vertices must satisfy the projection equation to this (model units). */
#define RESIDUAL_TOL 1e-9

static projcurve_result *project(const projcurve_surface *s, const projcurve_curve *c,
                                 const double d[3], projcurve_status *st)
{
    projcurve_options *o = NULL;
    projcurve_options_create(NULL, &o);
    projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, 0);
    projcurve_result *r = NULL;
    *st = projcurve_project_directional(NULL, s, c, d, o, &r);
    projcurve_options_destroy(o);
    return r;
}

static void check_oracle(const char *name, const projcurve_surface *s, const projcurve_curve *c,
                         const double d[3], const projcurve_result *r)
{
    trace_oracle_report rep;
    trace_oracle_check(s, c, d, r, N_SAMPLES, &rep);
    trace_oracle_print(name, &rep);
    CHECK(rep.hits > 0);
    CHECK(rep.uncovered_far == 0);
    CHECK(rep.max_residual <= RESIDUAL_TOL);
    CHECK(rep.behind == 0);
}

/* Plane O + u A + v B: the projection of p along d solves
 * u A + v B - lambda d = p - O, a 3x3 linear system (Cramer's rule). */
static void plane_exact(const double o[3], const double a[3], const double b[3],
                        const double d[3], const double p[3], double uv[2])
{
    const double m[3][3] = {{a[0], b[0], -d[0]}, {a[1], b[1], -d[1]}, {a[2], b[2], -d[2]}};
    const double r[3] = {p[0] - o[0], p[1] - o[1], p[2] - o[2]};
#define DET3(c0, c1, c2)                                                                      \
    ((c0)[0] * ((c1)[1] * (c2)[2] - (c1)[2] * (c2)[1]) -                                      \
     (c1)[0] * ((c0)[1] * (c2)[2] - (c0)[2] * (c2)[1]) +                                      \
     (c2)[0] * ((c0)[1] * (c1)[2] - (c0)[2] * (c1)[1]))
    const double col0[3] = {m[0][0], m[1][0], m[2][0]}, col1[3] = {m[0][1], m[1][1], m[2][1]},
                 col2[3] = {m[0][2], m[1][2], m[2][2]};
    const double det = DET3(col0, col1, col2);
    uv[0] = DET3(r, col1, col2) / det;
    uv[1] = DET3(col0, r, col2) / det;
#undef DET3
}

static void test_plane(void)
{
    const double o[3] = {0, 0, 0}, a[3] = {10, 0, 1}, b[3] = {0, 10, 2};
    const double pts[18] = {2, 2, 30, 4, 3, 31, 5, 6, 29, 6, 4, 30, 7, 7, 32, 8, 8, 30};
    const double d[3] = {0.05, -0.05, -1};
    projcurve_surface *s = shape_plane(o, a, b);
    projcurve_curve *c = shape_bspline_curve(3, 6, pts);
    CHECK(s != NULL && c != NULL);
    projcurve_status st;
    projcurve_result *r = project(s, c, d, &st);
    CHECK_OK(st);
    CHECK(projcurve_result_branch_count(r) == 1);
    double range[2];
    projcurve_branch_start start;
    projcurve_branch_end end;
    size_t n = 0;
    CHECK_OK(projcurve_result_branch_info(NULL, r, 0, range, &start, &end, &n, NULL));
    CHECK(start == PROJCURVE_START_CURVE_START && end == PROJCURVE_END_CURVE_END);
    CHECK(range[0] == 0.0 && range[1] == 1.0);
    CHECK(n >= 16);
    double pts_out[3 * 4096];
    size_t count = 0;
    CHECK_OK(projcurve_result_branch_points(NULL, r, 0, 4096, pts_out, &count));
    double worst = 0.0;
    for (size_t k = 0; k < count && k < 4096; ++k) {
        double p[3], uv[2];
        projcurve_curve_eval(NULL, c, pts_out[3 * k], 0, p);
        plane_exact(o, a, b, d, p, uv);
        worst = fmax(worst, fmax(fabs(uv[0] - pts_out[3 * k + 1]), fabs(uv[1] - pts_out[3 * k + 2])));
    }
    /* Newton stops at 1e-12 of the model size (~25): (u, v) to ~1e-12 */
    CHECK_NEAR(worst, 0.0, 1e-11);
    check_oracle("plane", s, c, d, r);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

/* Half cylinder of radius R about the y axis, Dir = -z: the projection of
 * (x, y, z) is (x, y, sqrt(R^2 - x^2)). */
static void test_cylinder(void)
{
    const double R = 30.0;
    const double pts[18] = {-25, 10, 50, -10, 30, 55, 0, 40, 45, 10, 60, 50, 20, 70, 52, 25, 90, 50};
    const double d[3] = {0, 0, -1};
    projcurve_surface *s = shape_half_cylinder(R, 100.0);
    projcurve_curve *c = shape_bspline_curve(3, 6, pts);
    CHECK(s != NULL && c != NULL);
    projcurve_status st;
    projcurve_result *r = project(s, c, d, &st);
    CHECK_OK(st);
    CHECK(projcurve_result_branch_count(r) == 1);
    double pts_out[3 * 4096];
    size_t count = 0;
    CHECK_OK(projcurve_result_branch_points(NULL, r, 0, 4096, pts_out, &count));
    double worst = 0.0;
    for (size_t k = 0; k < count && k < 4096; ++k) {
        double p[3], q[3];
        projcurve_curve_eval(NULL, c, pts_out[3 * k], 0, p);
        projcurve_surface_eval(NULL, s, pts_out[3 * k + 1], pts_out[3 * k + 2], 0, q);
        const double ex[3] = {p[0], p[1], sqrt(R * R - p[0] * p[0])};
        worst = fmax(worst, sqrt((q[0] - ex[0]) * (q[0] - ex[0]) + (q[1] - ex[1]) * (q[1] - ex[1]) +
                                 (q[2] - ex[2]) * (q[2] - ex[2])));
    }
    CHECK_NEAR(worst, 0.0, RESIDUAL_TOL);
    check_oracle("cylinder", s, c, d, r);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

/* Sphere of radius 10, a line at height 20 crossing over it off centre:
 * two branches (upper and lower hemisphere), each born and ending on the
 * silhouette (the equator, where Dir = -z is tangent to the sphere). */
static void test_sphere(void)
{
    const double R = 10.0, y = 3.0;
    const double pts[6] = {-15, y, 20, 15, y, 20};
    const double d[3] = {0, 0, -1};
    projcurve_surface *s = shape_sphere(R);
    projcurve_curve *c = shape_bspline_curve(1, 2, pts);
    CHECK(s != NULL && c != NULL);
    projcurve_status st;
    projcurve_result *r = project(s, c, d, &st);
    CHECK_OK(st);
    CHECK(projcurve_result_branch_count(r) == 2);
    const double x_edge = sqrt(R * R - y * y);
    for (size_t i = 0; i < projcurve_result_branch_count(r); ++i) {
        double range[2];
        projcurve_branch_start start;
        projcurve_branch_end end;
        CHECK_OK(projcurve_result_branch_info(NULL, r, i, range, &start, &end, NULL, NULL));
        CHECK(start == PROJCURVE_START_SILHOUETTE && end == PROJCURVE_END_SILHOUETTE);
        /* the line is x = -15 + 30 t: the silhouette at x = +-sqrt(R^2 - y^2) */
        CHECK_NEAR(range[0], (15.0 - x_edge) / 30.0, 1e-5);
        CHECK_NEAR(range[1], (15.0 + x_edge) / 30.0, 1e-5);
        double pts_out[3 * 4096];
        size_t count = 0;
        CHECK_OK(projcurve_result_branch_points(NULL, r, i, 4096, pts_out, &count));
        double worst = 0.0;
        for (size_t k = 0; k < count && k < 4096; ++k) {
            double p[3], q[3];
            projcurve_curve_eval(NULL, c, pts_out[3 * k], 0, p);
            projcurve_surface_eval(NULL, s, pts_out[3 * k + 1], pts_out[3 * k + 2], 0, q);
            /* exact: the point of the sphere with the x, y of P */
            const double radius = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
            worst = fmax(worst, fmax(fabs(q[0] - p[0]), fmax(fabs(q[1] - p[1]), fabs(radius - R))));
        }
        CHECK_NEAR(worst, 0.0, RESIDUAL_TOL);
    }
    check_oracle("sphere", s, c, d, r);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

/* A rational bumpy bicubic (weights in [0.5, 2]) seen along a slanted
 * direction: brute force is the only oracle. */
static void test_rational_bumpy(void)
{
    pc_shape_surface arrays = pc_shape_bumpy(2024, 5, 5, 0.15, 1);
    projcurve_surface *s = pc_shape_surface_create(&arrays);
    pc_shape_surface_free(&arrays);
    const double pts[15] = {0.1, 0.2, 1, 0.3, 0.8, 1.2, 0.5, 0.3, 0.9, 0.7, 0.9, 1.1, 0.85, 0.6, 1};
    projcurve_curve *c = shape_bspline_curve(3, 5, pts);
    const double d[3] = {0.05, 0.02, -1};
    CHECK(s != NULL && c != NULL);
    projcurve_status st;
    projcurve_result *r = project(s, c, d, &st);
    CHECK_OK(st);
    CHECK(projcurve_result_branch_count(r) == 1);
    check_oracle("rational bumpy", s, c, d, r);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

int main(void)
{
    test_plane();
    test_cylinder();
    test_sphere();
    test_rational_bumpy();
    return pc_test_finish("test_trace_shapes");
}
