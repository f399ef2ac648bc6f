/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Every bad input of curve and surface creation, evaluation and point
 * projection gets its own status and a message, and leaves *out untouched.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "shapes.h"

static projcurve_context *g_ctx;

/* The call failed with `expected`, left a message, and did not write out. */
#define CHECK_FAILS(call, expected)                                                  \
    do {                                                                             \
        projcurve_context_clear(g_ctx);                                              \
        CHECK_STATUS(call, expected);                                                \
        CHECK(projcurve_context_status(g_ctx) == (expected));                        \
        CHECK(strlen(projcurve_context_message(g_ctx)) > 0);                         \
    } while (0)

/* A valid cubic curve: 5 points, clamped knots over [0, 2]. */
static double g_curve_ctrl[15] = {0, 0, 0, 1, 1, 0, 2, 0, 1, 3, 1, 1, 4, 0, 0};
static double g_curve_w[5] = {1, 2, 1, 0.5, 1};
static double g_curve_knots[9] = {0, 0, 0, 0, 1, 2, 2, 2, 2};

static void test_curve_create(void)
{
    projcurve_curve *sentinel = (projcurve_curve *)(uintptr_t)0x1234;
    projcurve_curve *c = sentinel;
    const double *P = g_curve_ctrl, *W = g_curve_w, *K = g_curve_knots;
    CHECK_FAILS(projcurve_curve_create_nurbs(g_ctx, 3, 5, P, W, K, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(projcurve_curve_create_nurbs(g_ctx, 3, 5, NULL, W, K, &c), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(projcurve_curve_create_nurbs(g_ctx, 3, 5, P, W, NULL, &c), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(projcurve_curve_create_nurbs(g_ctx, 0, 5, P, W, K, &c), PROJCURVE_ERR_BAD_DEGREE);
    CHECK_FAILS(projcurve_curve_create_nurbs(g_ctx, -2, 5, P, W, K, &c), PROJCURVE_ERR_BAD_DEGREE);
    CHECK_FAILS(projcurve_curve_create_nurbs(g_ctx, PROJCURVE_MAX_DEGREE + 1, 40, P, W, K, &c),
                PROJCURVE_ERR_BAD_DEGREE);
    CHECK_FAILS(projcurve_curve_create_nurbs(g_ctx, 3, 3, P, W, K, &c), PROJCURVE_ERR_BAD_COUNT);
    CHECK_FAILS(projcurve_curve_create_nurbs(g_ctx, 3, SIZE_MAX / 2, P, W, K, &c),
                PROJCURVE_ERR_OVERFLOW);
    CHECK_FAILS(projcurve_curve_create_nurbs(g_ctx, 3, SIZE_MAX - 1, P, W, K, &c),
                PROJCURVE_ERR_OVERFLOW);
    double k[9];
    memcpy(k, K, sizeof k);
    k[5] = 0.5; /* decreasing */
    CHECK_FAILS(projcurve_curve_create_nurbs(g_ctx, 3, 5, P, W, k, &c), PROJCURVE_ERR_BAD_KNOTS);
    CHECK(strstr(projcurve_context_message(g_ctx), "index 5") != NULL);
    memcpy(k, K, sizeof k);
    k[4] = NAN;
    CHECK_FAILS(projcurve_curve_create_nurbs(g_ctx, 3, 5, P, W, k, &c), PROJCURVE_ERR_NOT_FINITE);
    k[4] = INFINITY;
    CHECK_FAILS(projcurve_curve_create_nurbs(g_ctx, 3, 5, P, W, k, &c), PROJCURVE_ERR_NOT_FINITE);
    const double flat[9] = {1, 1, 1, 1, 1, 1, 1, 1, 1}; /* empty domain */
    CHECK_FAILS(projcurve_curve_create_nurbs(g_ctx, 3, 5, P, W, flat, &c), PROJCURVE_ERR_BAD_KNOTS);
    const double too_many[9] = {0, 0, 0, 0, 0, 1, 1, 1, 1}; /* 0 five times */
    CHECK_FAILS(projcurve_curve_create_nurbs(g_ctx, 3, 5, P, W, too_many, &c),
                PROJCURVE_ERR_BAD_KNOTS);
    double p[15];
    memcpy(p, P, sizeof p);
    p[7] = NAN;
    CHECK_FAILS(projcurve_curve_create_nurbs(g_ctx, 3, 5, p, W, K, &c), PROJCURVE_ERR_NOT_FINITE);
    CHECK(strstr(projcurve_context_message(g_ctx), "control point 2") != NULL);
    p[7] = -INFINITY;
    CHECK_FAILS(projcurve_curve_create_nurbs(g_ctx, 3, 5, p, W, K, &c), PROJCURVE_ERR_NOT_FINITE);
    double w[5];
    const double bad_weights[4] = {0.0, -1.0, NAN, INFINITY};
    for (int i = 0; i < 4; ++i) {
        memcpy(w, W, sizeof w);
        w[3] = bad_weights[i];
        CHECK_FAILS(projcurve_curve_create_nurbs(g_ctx, 3, 5, P, w, K, &c), PROJCURVE_ERR_BAD_WEIGHT);
    }
    /* Weight times coordinate overflowing. */
    memcpy(w, W, sizeof w);
    memcpy(p, P, sizeof p);
    w[1] = 1e300;
    p[3] = 1e300;
    CHECK_FAILS(projcurve_curve_create_nurbs(g_ctx, 3, 5, p, w, K, &c), PROJCURVE_ERR_NOT_FINITE);
    CHECK(c == sentinel);

    /* Callback curves. */
    CHECK_FAILS(projcurve_curve_create_callback(g_ctx, NULL, NULL, 0, 1, &c),
                PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK(c == sentinel);
}

static int good_cb(void *user, double t, double out[9])
{
    (void)user;
    for (int k = 0; k < 9; ++k)
        out[k] = 0.0;
    out[0] = t;
    out[3] = 1.0;
    return 0;
}
static int failing_cb(void *user, double t, double out[9])
{
    (void)user;
    (void)t;
    (void)out;
    return -1;
}
static int nan_cb(void *user, double t, double out[9])
{
    good_cb(user, t, out);
    out[7] = NAN;
    return 0;
}

static void test_curve_eval(void)
{
    projcurve_curve *c = NULL, *sentinel = (projcurve_curve *)(uintptr_t)0x1234, *d = sentinel;
    CHECK_FAILS(projcurve_curve_create_callback(g_ctx, good_cb, NULL, NAN, 1, &d),
                PROJCURVE_ERR_NOT_FINITE);
    CHECK_FAILS(projcurve_curve_create_callback(g_ctx, good_cb, NULL, 0, INFINITY, &d),
                PROJCURVE_ERR_NOT_FINITE);
    CHECK_FAILS(projcurve_curve_create_callback(g_ctx, good_cb, NULL, 1, 1, &d),
                PROJCURVE_ERR_INVALID_ARGUMENT);
    CHECK_FAILS(projcurve_curve_create_callback(g_ctx, good_cb, NULL, 2, 1, &d),
                PROJCURVE_ERR_INVALID_ARGUMENT);
    CHECK(d == sentinel);
    CHECK_OK(projcurve_curve_create_nurbs(g_ctx, 3, 5, g_curve_ctrl, g_curve_w, g_curve_knots, &c));
    double out[12] = {0};
    CHECK_FAILS(projcurve_curve_eval(g_ctx, NULL, 0.5, 0, out), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(projcurve_curve_eval(g_ctx, c, 0.5, 0, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(projcurve_curve_eval(g_ctx, c, 0.5, 4, out), PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK_FAILS(projcurve_curve_eval(g_ctx, c, 0.5, -1, out), PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK_FAILS(projcurve_curve_eval(g_ctx, c, NAN, 0, out), PROJCURVE_ERR_NOT_FINITE);
    CHECK_FAILS(projcurve_curve_eval(g_ctx, c, 2.0000001, 0, out), PROJCURVE_ERR_OUT_OF_DOMAIN);
    CHECK_FAILS(projcurve_curve_eval(g_ctx, c, -1e-9, 0, out), PROJCURVE_ERR_OUT_OF_DOMAIN);
    CHECK_OK(projcurve_curve_eval(g_ctx, c, 2.0, 3, out));
    CHECK_OK(projcurve_curve_eval(g_ctx, c, 0.0, 3, out));
    projcurve_curve_destroy(c);

    projcurve_curve *cb = NULL;
    CHECK_OK(projcurve_curve_create_callback(g_ctx, failing_cb, NULL, 0, 1, &cb));
    CHECK_FAILS(projcurve_curve_eval(g_ctx, cb, 0.5, 0, out), PROJCURVE_ERR_CALLBACK);
    CHECK_FAILS(projcurve_curve_nurbs_info(g_ctx, cb, NULL, NULL, NULL, NULL),
                PROJCURVE_ERR_WRONG_KIND);
    CHECK_FAILS(projcurve_curve_nurbs_data(g_ctx, cb, NULL, NULL, NULL), PROJCURVE_ERR_WRONG_KIND);
    projcurve_curve_destroy(cb);
    CHECK_OK(projcurve_curve_create_callback(g_ctx, nan_cb, NULL, 0, 1, &cb));
    CHECK_OK(projcurve_curve_eval(g_ctx, cb, 0.5, 1, out)); /* NaN only in P'' */
    CHECK_FAILS(projcurve_curve_eval(g_ctx, cb, 0.5, 2, out), PROJCURVE_ERR_CALLBACK);
    CHECK_FAILS(projcurve_curve_eval(g_ctx, cb, 0.5, 3, out), PROJCURVE_ERR_OUT_OF_RANGE);
    projcurve_curve_destroy(cb);
    projcurve_curve_destroy(NULL);
}

static void test_surface_create(void)
{
    pc_shape_surface s = pc_shape_bumpy(1, 3, 2, 0.5, 1); /* 6 x 5 net, bicubic */
    projcurve_surface *sentinel = (projcurve_surface *)(uintptr_t)0x1234, *out = sentinel;
#define CREATE(du, dv, nu, nv, P, W, KU, KV, OUT) \
    projcurve_surface_create_nurbs(g_ctx, du, dv, nu, nv, P, W, KU, KV, OUT)
    CHECK_FAILS(CREATE(3, 3, 6, 5, s.ctrl, s.weights, s.knots_u, s.knots_v, NULL),
                PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(CREATE(3, 3, 6, 5, NULL, s.weights, s.knots_u, s.knots_v, &out),
                PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(CREATE(3, 3, 6, 5, s.ctrl, s.weights, NULL, s.knots_v, &out),
                PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(CREATE(3, 3, 6, 5, s.ctrl, s.weights, s.knots_u, NULL, &out),
                PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(CREATE(0, 3, 6, 5, s.ctrl, s.weights, s.knots_u, s.knots_v, &out),
                PROJCURVE_ERR_BAD_DEGREE);
    CHECK_FAILS(CREATE(3, 31, 6, 50, s.ctrl, s.weights, s.knots_u, s.knots_v, &out),
                PROJCURVE_ERR_BAD_DEGREE);
    CHECK_FAILS(CREATE(3, 3, 6, 3, s.ctrl, s.weights, s.knots_u, s.knots_v, &out),
                PROJCURVE_ERR_BAD_COUNT);
    /* 2^70 points: the product overflows before any array is read. */
    CHECK_FAILS(CREATE(3, 3, (size_t)1 << 40, (size_t)1 << 30, s.ctrl, s.weights, s.knots_u,
                       s.knots_v, &out),
                PROJCURVE_ERR_OVERFLOW);
    double ku[10];
    memcpy(ku, s.knots_u, sizeof ku);
    ku[6] = ku[4] - 0.1;
    CHECK_FAILS(CREATE(3, 3, 6, 5, s.ctrl, s.weights, ku, s.knots_v, &out), PROJCURVE_ERR_BAD_KNOTS);
    CHECK(strstr(projcurve_context_message(g_ctx), "knot vector u") != NULL);
    double kv[9];
    memcpy(kv, s.knots_v, sizeof kv);
    kv[8] = NAN;
    CHECK_FAILS(CREATE(3, 3, 6, 5, s.ctrl, s.weights, s.knots_u, kv, &out), PROJCURVE_ERR_NOT_FINITE);
    CHECK(strstr(projcurve_context_message(g_ctx), "knot vector v") != NULL);
    const double saved_c = s.ctrl[40];
    s.ctrl[40] = INFINITY;
    CHECK_FAILS(CREATE(3, 3, 6, 5, s.ctrl, s.weights, s.knots_u, s.knots_v, &out),
                PROJCURVE_ERR_NOT_FINITE);
    s.ctrl[40] = saved_c;
    const double saved_w = s.weights[17];
    s.weights[17] = 0.0;
    CHECK_FAILS(CREATE(3, 3, 6, 5, s.ctrl, s.weights, s.knots_u, s.knots_v, &out),
                PROJCURVE_ERR_BAD_WEIGHT);
    s.weights[17] = -3.0;
    CHECK_FAILS(CREATE(3, 3, 6, 5, s.ctrl, s.weights, s.knots_u, s.knots_v, &out),
                PROJCURVE_ERR_BAD_WEIGHT);
    s.weights[17] = saved_w;
    CHECK(out == sentinel);
#undef CREATE

    projcurve_surface *ok = pc_shape_surface_create(&s);
    CHECK(ok != NULL);
    double r[18], dom[4], box[6];
    CHECK_OK(projcurve_surface_domain(g_ctx, ok, dom));
    CHECK_FAILS(projcurve_surface_domain(g_ctx, NULL, dom), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(projcurve_surface_domain(g_ctx, ok, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(projcurve_surface_bounds(g_ctx, ok, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_OK(projcurve_surface_bounds(g_ctx, ok, box));
    CHECK_FAILS(projcurve_surface_info(g_ctx, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL),
                PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(projcurve_surface_eval(g_ctx, NULL, 0.5, 0.5, 0, r), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(projcurve_surface_eval(g_ctx, ok, 0.5, 0.5, 0, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(projcurve_surface_eval(g_ctx, ok, 0.5, 0.5, 3, r), PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK_FAILS(projcurve_surface_eval(g_ctx, ok, 0.5, 0.5, -1, r), PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK_FAILS(projcurve_surface_eval(g_ctx, ok, NAN, 0.5, 0, r), PROJCURVE_ERR_NOT_FINITE);
    CHECK_FAILS(projcurve_surface_eval(g_ctx, ok, 0.5, -INFINITY, 0, r), PROJCURVE_ERR_NOT_FINITE);
    CHECK_FAILS(projcurve_surface_eval(g_ctx, ok, 1.5, 0.5, 0, r), PROJCURVE_ERR_OUT_OF_DOMAIN);
    CHECK_FAILS(projcurve_surface_eval(g_ctx, ok, 0.5, -0.001, 2, r), PROJCURVE_ERR_OUT_OF_DOMAIN);
    CHECK_OK(projcurve_surface_eval(g_ctx, ok, 1.0, 1.0, 2, r));
    projcurve_surface_destroy(ok);
    projcurve_surface_destroy(NULL);
    pc_shape_surface_free(&s);
}

static void test_point_projection(void)
{
    pc_shape_surface sh = pc_shape_bumpy(3, 2, 2, 0.2, 0);
    projcurve_surface *s = pc_shape_surface_create(&sh);
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(g_ctx, 3, 5, g_curve_ctrl, g_curve_w, g_curve_knots, &c));
    const double p[3] = {0.5, 0.5, 1.0}, bad[3] = {0.5, NAN, 1.0}, inf[3] = {INFINITY, 0, 0};
    double uv[2] = {-7, -7}, q[3], dist = -7, t = -7, feet[8];
    size_t count = 99;
    CHECK_FAILS(projcurve_surface_closest_point(g_ctx, NULL, p, uv, q, &dist), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(projcurve_surface_closest_point(g_ctx, s, NULL, uv, q, &dist), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(projcurve_surface_closest_point(g_ctx, s, p, NULL, q, &dist), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(projcurve_surface_closest_point(g_ctx, s, bad, uv, q, &dist), PROJCURVE_ERR_NOT_FINITE);
    CHECK_FAILS(projcurve_surface_closest_point(g_ctx, s, inf, uv, q, &dist), PROJCURVE_ERR_NOT_FINITE);
    CHECK(uv[0] == -7 && dist == -7);
    CHECK_OK(projcurve_surface_closest_point(g_ctx, s, p, uv, NULL, NULL));
    CHECK_FAILS(projcurve_surface_foot_points(g_ctx, NULL, p, 4, feet, &count), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(projcurve_surface_foot_points(g_ctx, s, p, 4, feet, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(projcurve_surface_foot_points(g_ctx, s, p, 4, NULL, &count), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(projcurve_surface_foot_points(g_ctx, s, bad, 4, feet, &count), PROJCURVE_ERR_NOT_FINITE);
    CHECK(count == 99);
    CHECK_OK(projcurve_surface_foot_points(g_ctx, s, p, 0, NULL, &count));
    CHECK_FAILS(projcurve_curve_closest_point(g_ctx, NULL, p, &t, q, &dist), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(projcurve_curve_closest_point(g_ctx, c, NULL, &t, q, &dist), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(projcurve_curve_closest_point(g_ctx, c, p, NULL, q, &dist), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_FAILS(projcurve_curve_closest_point(g_ctx, c, bad, &t, q, &dist), PROJCURVE_ERR_NOT_FINITE);
    CHECK(t == -7);
    projcurve_curve *cb = NULL;
    CHECK_OK(projcurve_curve_create_callback(g_ctx, failing_cb, NULL, 0, 1, &cb));
    CHECK_FAILS(projcurve_curve_closest_point(g_ctx, cb, p, &t, q, &dist), PROJCURVE_ERR_CALLBACK);
    projcurve_curve_destroy(cb);
    CHECK_OK(projcurve_curve_create_callback(g_ctx, nan_cb, NULL, 0, 1, &cb));
    /* The NaN is in P'' only: sampling works, Newton needs P'' and fails. */
    CHECK_FAILS(projcurve_curve_closest_point(g_ctx, cb, p, &t, q, &dist), PROJCURVE_ERR_CALLBACK);
    CHECK(t == -7);
    projcurve_curve_destroy(cb);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    pc_shape_surface_free(&sh);
}

int main(void)
{
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &g_ctx));
    test_curve_create();
    test_curve_eval();
    test_surface_create();
    test_point_projection();
    projcurve_context_destroy(g_ctx);
    return pc_test_finish("test_geometry_bad_input");
}
