/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The size limit a context puts on curves and surfaces
 * (PROJCURVE_LIMIT_CONTROL_POINTS): a 1000 x 1000 net used to take 5 s and
 * 1.7 GB to create with no way to refuse it. Checked: the default, the
 * setter's bounds, the exact boundary (n points accepted at a limit of n,
 * n + 1 refused) for curves and surfaces, refusal before any allocation of
 * the net's size (a refused 1000 x 1000 net returns at once, the caller's
 * output untouched), and a model read under a small limit.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "projcurve.h"

/* Ends the program if a call does not return (each takes milliseconds). */
#define HANG_GUARD_SECONDS 120

static projcurve_context *ctx;

/* A degree 1 x 1 net of n_u x n_v points on z = 0 with uniform knots. */
static projcurve_status make_sheet(size_t n_u, size_t n_v, projcurve_surface **out)
{
    double *net = malloc(3 * n_u * n_v * sizeof *net);
    double *ku = malloc((n_u + 2) * sizeof *ku), *kv = malloc((n_v + 2) * sizeof *kv);
    projcurve_status st = PROJCURVE_ERR_NO_MEMORY;
    if (net != NULL && ku != NULL && kv != NULL) {
        for (size_t j = 0; j < n_v; ++j)
            for (size_t i = 0; i < n_u; ++i) {
                double *p = net + 3 * (j * n_u + i);
                p[0] = (double)i, p[1] = (double)j, p[2] = 0.0;
            }
        for (size_t i = 0; i < n_u + 2; ++i)
            ku[i] = i == 0 ? 0.0 : i > n_u ? (double)(n_u - 1) : (double)(i - 1);
        for (size_t i = 0; i < n_v + 2; ++i)
            kv[i] = i == 0 ? 0.0 : i > n_v ? (double)(n_v - 1) : (double)(i - 1);
        st = projcurve_surface_create_nurbs(ctx, 1, 1, n_u, n_v, net, NULL, ku, kv, out);
    }
    free(net);
    free(ku);
    free(kv);
    return st;
}

/* A polyline (degree 1) of n points. */
static projcurve_status make_polyline(size_t n, projcurve_curve **out)
{
    double *pts = malloc(3 * n * sizeof *pts), *k = malloc((n + 2) * sizeof *k);
    projcurve_status st = PROJCURVE_ERR_NO_MEMORY;
    if (pts != NULL && k != NULL) {
        for (size_t i = 0; i < n; ++i)
            pts[3 * i] = (double)i, pts[3 * i + 1] = (double)(i % 2), pts[3 * i + 2] = 1.0;
        for (size_t i = 0; i < n + 2; ++i)
            k[i] = i == 0 ? 0.0 : i > n ? (double)(n - 1) : (double)(i - 1);
        st = projcurve_curve_create_nurbs(ctx, 1, n, pts, NULL, k, out);
    }
    free(pts);
    free(k);
    return st;
}

static void expect_refused(projcurve_status st)
{
    CHECK_STATUS(st, PROJCURVE_ERR_OUT_OF_RANGE);
    if (st != PROJCURVE_OK && strstr(projcurve_context_message(ctx), "CONTROL_POINTS") == NULL)
        pc_test_fail_at(__FILE__, __LINE__, "message does not name the limit: %s",
                        projcurve_context_message(ctx));
}

static void test_setter(void)
{
    size_t v = 0;
    CHECK_OK(projcurve_context_get_limit(ctx, PROJCURVE_LIMIT_CONTROL_POINTS, &v));
    CHECK(v == PROJCURVE_DEFAULT_MAX_CONTROL_POINTS);
    v = 0;
    CHECK_OK(projcurve_context_get_limit(NULL, PROJCURVE_LIMIT_CONTROL_POINTS, &v));
    CHECK(v == PROJCURVE_DEFAULT_MAX_CONTROL_POINTS);
    CHECK_STATUS(projcurve_context_get_limit(ctx, PROJCURVE_LIMIT_CONTROL_POINTS, NULL),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_context_get_limit(ctx, (projcurve_limit)7, &v),
                 PROJCURVE_ERR_UNKNOWN_OPTION);
    CHECK_STATUS(projcurve_context_set_limit(NULL, PROJCURVE_LIMIT_CONTROL_POINTS, 10),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_context_set_limit(ctx, (projcurve_limit)-1, 10),
                 PROJCURVE_ERR_UNKNOWN_OPTION);
    CHECK_STATUS(projcurve_context_set_limit(ctx, PROJCURVE_LIMIT_CONTROL_POINTS, 1),
                 PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK_STATUS(projcurve_context_set_limit(ctx, PROJCURVE_LIMIT_CONTROL_POINTS, 0),
                 PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK_OK(projcurve_context_get_limit(ctx, PROJCURVE_LIMIT_CONTROL_POINTS, &v));
    CHECK(v == PROJCURVE_DEFAULT_MAX_CONTROL_POINTS); /* unchanged by the failures */
    CHECK_OK(projcurve_context_set_limit(ctx, PROJCURVE_LIMIT_CONTROL_POINTS, 2));
    CHECK_OK(projcurve_context_set_limit(ctx, PROJCURVE_LIMIT_CONTROL_POINTS, SIZE_MAX));
    CHECK_OK(projcurve_context_get_limit(ctx, PROJCURVE_LIMIT_CONTROL_POINTS, &v));
    CHECK(v == SIZE_MAX);
}

static void test_boundary(void)
{
    projcurve_surface *s = NULL;
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_context_set_limit(ctx, PROJCURVE_LIMIT_CONTROL_POINTS, 12));
    CHECK_OK(make_sheet(4, 3, &s));
    CHECK(s != NULL);
    projcurve_surface_destroy(s);
    s = NULL;
    expect_refused(make_sheet(13, 1 + 1, &s)); /* 26 > 12 */
    expect_refused(make_sheet(5, 3, &s));      /* 15 > 12 */
    CHECK(s == NULL);
    CHECK_OK(make_polyline(12, &c));
    CHECK(c != NULL);
    projcurve_curve_destroy(c);
    c = NULL;
    expect_refused(make_polyline(13, &c));
    CHECK(c == NULL);
}

/* At the default limit the net of issue 21 is refused at once. */
static void test_default(void)
{
    CHECK_OK(projcurve_context_set_limit(ctx, PROJCURVE_LIMIT_CONTROL_POINTS,
                                         PROJCURVE_DEFAULT_MAX_CONTROL_POINTS));
    projcurve_surface *s = (projcurve_surface *)&ctx; /* must stay untouched */
    projcurve_surface *const before = s;
    expect_refused(make_sheet(1000, 1000, &s));
    CHECK(s == before);
    expect_refused(make_sheet(513, 512, &s)); /* 262,656 > 2^18 */
    projcurve_curve *c = NULL;
    expect_refused(make_polyline(PROJCURVE_DEFAULT_MAX_CONTROL_POINTS + 1, &c));
    CHECK_OK(make_polyline(PROJCURVE_DEFAULT_MAX_CONTROL_POINTS, &c));
    projcurve_curve_destroy(c);
}

/* A model whose surfaces pass the limit is not read. */
static void test_model(void)
{
    projcurve_model *m = NULL;
    const char *path = pc_test_data_path("cases/bumpy_bicubic_8x8_down.igs");
    if (access(path, R_OK) != 0)
        pc_test_missing_data(path);
    CHECK_OK(projcurve_context_set_limit(ctx, PROJCURVE_LIMIT_CONTROL_POINTS, 2));
    const projcurve_status st = projcurve_model_read_file(ctx, path, &m);
    CHECK(st != PROJCURVE_OK);
    CHECK(m == NULL);
    if (st != PROJCURVE_OK && strstr(projcurve_context_message(ctx), "CONTROL_POINTS") == NULL)
        pc_test_fail_at(__FILE__, __LINE__, "model message does not name the limit: %s",
                        projcurve_context_message(ctx));
    CHECK_OK(projcurve_context_set_limit(ctx, PROJCURVE_LIMIT_CONTROL_POINTS,
                                         PROJCURVE_DEFAULT_MAX_CONTROL_POINTS));
    CHECK_OK(projcurve_model_read_file(ctx, path, &m));
    projcurve_model_destroy(m);
}

int main(void)
{
    pc_test_hang_guard(HANG_GUARD_SECONDS);
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    test_setter();
    test_boundary();
    test_default();
    test_model();
    projcurve_context_destroy(ctx);
    return pc_test_finish("test_api_limits");
}
