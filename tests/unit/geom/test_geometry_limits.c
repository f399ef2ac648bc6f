/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Parameter domains and coordinate scales outside what double precision
 * carries through a projection are refused at creation with OUT_OF_RANGE
 * (they used to be accepted: a curve on [0, 1e-200] ran for minutes,
 * +-1e200 domains and coordinates scaled by 1e+-80 gave 0 branches with
 * OK). Just inside the limits the projection of a line onto a plane is
 * exact: one branch whose ends are the line's ends dropped along -z.
 */
#include <math.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "projcurve.h"

/* Ends the program if a call does not return (each takes milliseconds). */
#define HANG_GUARD_SECONDS 120

static projcurve_context *ctx;

/* A straight line from (-s/2, -s/4, s) to (s/2, s/4, s) over [t0, t1]. */
static projcurve_status make_line(double s, double t0, double t1, projcurve_curve **c)
{
    const double ctrl[6] = {-0.5 * s, -0.25 * s, s, 0.5 * s, 0.25 * s, s};
    const double knots[4] = {t0, t0, t1, t1};
    *c = NULL;
    return projcurve_curve_create_nurbs(ctx, 1, 2, ctrl, NULL, knots, c);
}

/* The plane z = 0 over [-s, s]^2, domain [u0, u1] in both directions. */
static projcurve_status make_plane(double s, double u0, double u1, projcurve_surface **p)
{
    const double ctrl[12] = {-s, -s, 0, s, -s, 0, -s, s, 0, s, s, 0};
    const double knots[4] = {u0, u0, u1, u1};
    *p = NULL;
    return projcurve_surface_create_nurbs(ctx, 1, 1, 2, 2, ctrl, NULL, knots, knots, p);
}

static void expect_out_of_range(projcurve_status st, const char *needle)
{
    CHECK(st == PROJCURVE_ERR_OUT_OF_RANGE);
    if (st != PROJCURVE_OK)
        CHECK(strstr(projcurve_context_message(ctx), needle) != NULL);
}

/* Projects the line at scale s (domain [t0, t1]) onto the plane at scale s
 * (domain [u0, u1]) along -z; the image is the line at z = 0. */
static void expect_exact(double s, double t0, double t1, double u0, double u1)
{
    projcurve_curve *c = NULL;
    projcurve_surface *p = NULL;
    CHECK_OK(make_line(s, t0, t1, &c));
    CHECK_OK(make_plane(s, u0, u1, &p));
    if (c == NULL || p == NULL) {
        projcurve_curve_destroy(c);
        projcurve_surface_destroy(p);
        return;
    }
    const double dir[3] = {0.0, 0.0, -1.0};
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(ctx, p, c, dir, NULL, &r));
    CHECK(r != NULL && projcurve_result_branch_count(r) == 1);
    /* The closest point of (0, 0, s) is the plane's centre at distance s;
     * 1e-12 relative covers the rounding of a few operations at scale s. */
    const double q[3] = {0.0, 0.0, s};
    double uv[2], foot[3], dist = 0.0;
    CHECK_OK(projcurve_surface_closest_point(ctx, p, q, uv, foot, &dist));
    CHECK_NEAR(dist / s, 1.0, 1e-12);
    CHECK_NEAR(foot[2] / s, 0.0, 1e-12);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(p);
}

static int circle_fn(void *user, double t, double out[9])
{
    (void)user;
    out[0] = cos(t), out[1] = sin(t), out[2] = 1.0;
    out[3] = -sin(t), out[4] = cos(t), out[5] = 0.0;
    out[6] = -cos(t), out[7] = -sin(t), out[8] = 0.0;
    return 0;
}

int main(void)
{
    alarm(HANG_GUARD_SECONDS);
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    projcurve_curve *c = NULL;
    projcurve_surface *p = NULL;
    /* Refused: the inputs of issue 21. */
    expect_out_of_range(make_line(1.0, 0.0, 1e-200, &c), "curve domain");
    expect_out_of_range(make_line(1.0, 1.0, nextafter(1.0, 2.0), &c), "narrower");
    expect_out_of_range(make_line(1.0, -1e200, 1e200, &c), "parameter limit");
    expect_out_of_range(make_plane(1.0, -1e200, 1e200, &p), "surface domain u");
    expect_out_of_range(make_line(1e80, 0.0, 1.0, &c), "exceeds the limit");
    expect_out_of_range(make_plane(1e-80, 0.0, 1.0, &p), "below the limit");
    expect_out_of_range(projcurve_curve_create_callback(ctx, circle_fn, NULL, 0.0, 1e-200, &c),
                        "curve domain");
    CHECK(c == NULL && p == NULL);
    /* Accepted at the limits, and exact there. */
    expect_exact(1.0, 0.0, 1.0, 0.0, 1.0);
    expect_exact(1.0, 0.0, 1e-30, 0.0, 1e-30);
    expect_exact(1.0, -1e30, 1e30, -1e30, 1e30);
    expect_exact(1.0, 1.0, 1.0 + 0x1p-31, 1.0, 1.0 + 0x1p-31);
    expect_exact(1e29, 0.0, 1.0, 0.0, 1.0);
    expect_exact(1e-29, 0.0, 1.0, 0.0, 1.0);
    projcurve_context_destroy(ctx);
    return pc_test_finish("test_geometry_limits");
}
