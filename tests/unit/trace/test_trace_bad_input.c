/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve_project_directional on bad or awkward input: NULL arguments,
 * zero and non-finite directions, a curve that misses the surface (an empty
 * result, not an error), degenerate patches (the collapsed pole edges of a
 * sphere, a collapsed row inside the domain), the point limit (a partial result), a failing curve callback,
 * a distance tolerance finer than double precision or the corrector can
 * deliver (for the orthogonal projections too).
 * Each gives its documented status, and nothing hangs.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "api/options.h"
#include "check.h"
#include "geom/surface.h"
#include "trace_oracle.h"
#include "trace_shapes.h"

/* Brute force at 10,000 evenly spaced t; vertices on the projection to
 * 1e-9 (issue 5). */
#define N_SAMPLES 10000
#define RESIDUAL_TOL 1e-9
/* Vertices a projection across the pinch may take: 4 x 64 arc-length steps
 * (the default ARC_STEP_FRACTION is 1/64). */
#define MAX_PINCH_VERTICES 256

static projcurve_options *trace_only(void)
{
    projcurve_options *o = NULL;
    projcurve_options_create(NULL, &o);
    projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, 0);
    return o;
}

static void test_arguments(const projcurve_surface *s, const projcurve_curve *c)
{
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    projcurve_options *o = trace_only();
    const double d[3] = {0, 0, -1};
    projcurve_result *sentinel = (projcurve_result *)&sentinel, *r = sentinel;
    CHECK_STATUS(projcurve_project_directional(ctx, NULL, c, d, o, &r), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_project_directional(ctx, s, NULL, d, o, &r), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_project_directional(ctx, s, c, NULL, o, &r), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_project_directional(ctx, s, c, d, o, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    const double zero[3] = {0, 0, 0}, tiny[3] = {0, 0, -1e-310};
    const double nan3[3] = {0, NAN, -1}, inf3[3] = {INFINITY, 0, -1};
    CHECK_STATUS(projcurve_project_directional(ctx, s, c, zero, o, &r), PROJCURVE_ERR_ZERO_DIRECTION);
    CHECK(projcurve_context_status(ctx) == PROJCURVE_ERR_ZERO_DIRECTION);
    printf("message: %s\n", projcurve_context_message(ctx));
    CHECK_STATUS(projcurve_project_directional(ctx, s, c, nan3, o, &r), PROJCURVE_ERR_NOT_FINITE);
    CHECK_STATUS(projcurve_project_directional(ctx, s, c, inf3, o, &r), PROJCURVE_ERR_NOT_FINITE);
    /* a handle holding values its setters would refuse (written directly,
     * as memory corruption would): refused with the option named */
    struct projcurve_options bad;
    pc_options_defaults(&bad);
    bad.newton_tol = 0.5;
    CHECK_STATUS(projcurve_project_directional(ctx, s, c, d, &bad, &r), PROJCURVE_ERR_OUT_OF_RANGE);
    printf("message: %s\n", projcurve_context_message(ctx));
    pc_options_defaults(&bad);
    bad.param_step = NAN;
    CHECK_STATUS(projcurve_project_directional(ctx, s, c, d, &bad, &r), PROJCURVE_ERR_NOT_FINITE);
    pc_options_defaults(&bad);
    bad.max_points = 3;
    CHECK_STATUS(projcurve_project_directional(ctx, s, c, d, &bad, &r), PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK(r == sentinel); /* outputs untouched on failure */
    /* a denormal direction is still a direction */
    CHECK_OK(projcurve_project_directional(ctx, s, c, tiny, o, &r));
    CHECK(r != sentinel && projcurve_result_branch_count(r) == 1);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_context_destroy(ctx);
}

static void test_miss(const projcurve_surface *s)
{
    const double pts[6] = {200, 200, 50, 300, 250, 50};
    projcurve_curve *c = shape_bspline_curve(1, 2, pts);
    projcurve_options *o = trace_only();
    const double d[3] = {0, 0, -1}, up[3] = {0, 0, 1};
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c, d, o, &r));
    CHECK(r != NULL && projcurve_result_branch_count(r) == 0);
    projcurve_result_destroy(r);
    /* a curve above the surface projected upwards: the hits are behind */
    const double above[6] = {20, 20, 50, 80, 80, 50};
    projcurve_curve *c2 = shape_bspline_curve(1, 2, above);
    r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c2, up, o, &r));
    CHECK(r != NULL && projcurve_result_branch_count(r) == 0);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c2);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
}

/* Over the pole of a sphere, where the u-edge collapses (Su = 0): the
 * projection through the pole must end or pass cleanly, every vertex on
 * the projection. */
static void test_degenerate_patch(void)
{
    projcurve_surface *s = shape_sphere(10.0);
    const double pts[6] = {-5, 0, 20, 5, 0, 20};
    projcurve_curve *c = shape_bspline_curve(1, 2, pts);
    projcurve_options *o = trace_only();
    const double d[3] = {0, 0, -1};
    projcurve_result *r = NULL;
    const projcurve_status st = projcurve_project_directional(NULL, s, c, d, o, &r);
    CHECK(st == PROJCURVE_OK);
    trace_oracle_report rep;
    trace_oracle_check(s, c, d, r, N_SAMPLES, &rep);
    trace_oracle_print("through the pole", &rep);
    CHECK(rep.max_residual <= RESIDUAL_TOL);
    CHECK(rep.uncovered_far == 0);
    CHECK(rep.behind == 0);
    /* two sheets (upper, lower); each runs into its pole, which is the
     * domain boundary v = 1 (v = 0), and a branch leaves it on the other
     * side, along the seam u = 0 (where the hits under u = 1 coincide and
     * are dropped): four traced branches, joined at the poles into two
     * (src/seam/: each continues through its pole) */
    CHECK(projcurve_result_branch_count(r) == 2);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

/* Where the collapsed row of shape_pinched_sheet (v = 0.5, all of it the
 * point (50, 50, 10)) lies inside the domain: lines from above running
 * across the pinch (y from 10 to 90), through it (x = 50, and a slanted one
 * through (50, 50)) or beside it (x = 53, which leaves the narrowing sheet
 * over its side u = 1 and comes back after the pinch). Whatever happens at
 * the pinch (Su = 0 there, so J is singular), the result must be defined:
 * OK, branches on both sides of it, every vertex on the projection, and
 * nothing of the brute force left uncovered beyond two steps of an end. */
static void test_collapsed_interior_row(void)
{
    projcurve_surface *s = shape_pinched_sheet();
    CHECK(s != NULL);
    const double lines[3][6] = {{50, 10, 40, 50, 90, 40},
                                {30, 10, 40, 70, 90, 40},
                                {53, 10, 40, 53, 90, 40}};
    const char *names[3] = {"through the pinch", "slanted through the pinch", "beside the pinch"};
    const double d[3] = {0, 0, -1};
    for (int k = 0; k < 3; ++k) {
        projcurve_curve *c = shape_bspline_curve(1, 2, lines[k]);
        projcurve_options *o = trace_only();
        projcurve_result *r = NULL;
        CHECK_OK(projcurve_project_directional(NULL, s, c, d, o, &r));
        const size_t nb = projcurve_result_branch_count(r);
        printf("%s: %zu branches\n", names[k], nb);
        /* the pinch is at y = 50, t = 0.5 on each line */
        int before = 0, after = 0;
        for (size_t i = 0; i < nb; ++i) {
            double range[2];
            projcurve_branch_start start;
            projcurve_branch_end end;
            CHECK_OK(projcurve_result_branch_info(NULL, r, i, range, &start, &end, NULL, NULL));
            printf("  branch %zu: t [%.9f, %.9f] start %d end %d\n", i, range[0], range[1],
                   (int)start, (int)end);
            before |= range[0] < 0.5;
            after |= range[1] > 0.5;
        }
        CHECK(before && after);
        trace_oracle_report rep;
        trace_oracle_check(s, c, d, r, N_SAMPLES, &rep);
        trace_oracle_print(names[k], &rep);
        CHECK(rep.hits > N_SAMPLES / 2);
        CHECK(rep.max_residual <= RESIDUAL_TOL);
        CHECK(rep.uncovered_far == 0);
        CHECK(rep.behind == 0);
        /* the default arc-length step is 1/64 of the projection's length
         * (about 65 vertices here); steps cut near the pinch may add some,
         * not more than the nominal count again and again */
        CHECK(rep.vertices <= MAX_PINCH_VERTICES);
        projcurve_result_destroy(r);
        projcurve_options_destroy(o);
        projcurve_curve_destroy(c);
    }
    projcurve_surface_destroy(s);
}

static void test_limit(void)
{
    projcurve_surface *s = shape_example1_surface();
    projcurve_curve *c = shape_example1_curve();
    projcurve_options *o = trace_only();
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_MAX_POINTS, 16));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_PARAM_STEP, 1e-3));
    const double d[3] = {-1, 0, 0};
    projcurve_result *r = NULL;
    CHECK_STATUS(projcurve_project_directional(NULL, s, c, d, o, &r), PROJCURVE_ERR_LIMIT_REACHED);
    CHECK(r != NULL && projcurve_result_branch_count(r) == 1);
    projcurve_branch_end end;
    size_t n = 0;
    double range[2];
    CHECK_OK(projcurve_result_branch_info(NULL, r, 0, range, NULL, &end, &n, NULL));
    CHECK(end == PROJCURVE_END_LIMIT);
    CHECK(n == 16);
    CHECK_NEAR(range[1], 15e-3, 1e-15);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

/* A straight line as a callback: P(t) = A + t (B - A). It fails when
 * *(int *)user says so and t > 0.5. */
static int line_fn(void *user, double t, double out[9])
{
    const int *fail = user;
    if (*fail && t > 0.5)
        return 1;
    const double a[3] = {20, 30, 40}, b[3] = {80, 60, 40};
    for (int k = 0; k < 3; ++k) {
        out[k] = a[k] + t * (b[k] - a[k]);
        out[3 + k] = b[k] - a[k];
        out[6 + k] = 0.0;
    }
    return 0;
}

static void test_callback(void)
{
    projcurve_surface *s = shape_bumpy(8.0, 5);
    projcurve_options *o = trace_only();
    const double d[3] = {0, 0, -1};
    int fail = 0;
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, line_fn, &fail, 0.0, 1.0, &c));
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c, d, o, &r));
    CHECK(projcurve_result_branch_count(r) == 1);
    projcurve_result_destroy(r);
    fail = 1;
    r = NULL;
    CHECK_STATUS(projcurve_project_directional(NULL, s, c, d, o, &r), PROJCURVE_ERR_CALLBACK);
    CHECK(r == NULL);
    projcurve_curve_destroy(c);
    projcurve_options_destroy(o);
    projcurve_surface_destroy(s);
}

/* The plane z = 0 as an implicit surface. */
static int plane_z(void *user, const double x[3], double *value, double grad[3], double hess[9])
{
    (void)user;
    *value = x[2];
    grad[0] = grad[1] = 0.0;
    grad[2] = 1.0;
    for (int k = 0; k < 9; ++k)
        hess[k] = 0.0;
    return 0;
}

/* eps_D below max(NEWTON_TOL, 1e-12) of the model size is OUT_OF_RANGE,
 * with a message naming the option, and no result; at the floor it is
 * accepted. (1e-300 once gave an OK result whose branch had no pieces.) */
static void test_unreachable_tolerance(const projcurve_surface *s, const projcurve_curve *c)
{
    const double d[3] = {0, 0, -1};
    const double size = s->size;
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    const double too_fine[3] = {1e-300, 1e-15 * size, 0.99e-12 * size};
    for (int k = 0; k < 3; ++k) {
        CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE, too_fine[k]));
        projcurve_result *r = (projcurve_result *)o; /* a sentinel: must stay untouched */
        CHECK_STATUS(projcurve_project_directional(ctx, s, c, d, o, &r),
                     PROJCURVE_ERR_OUT_OF_RANGE);
        CHECK(r == (projcurve_result *)o);
        CHECK(strstr(projcurve_context_message(ctx), "TOL_DISTANCE") != NULL);
        CHECK_STATUS(projcurve_project_orthogonal(ctx, s, c, o, &r), PROJCURVE_ERR_OUT_OF_RANGE);
        CHECK(r == (projcurve_result *)o);
        CHECK_STATUS(projcurve_project_orthogonal_implicit(ctx, plane_z, NULL, size, c, o, &r),
                     PROJCURVE_ERR_OUT_OF_RANGE);
        CHECK(r == (projcurve_result *)o);
    }
    /* a coarser corrector raises the floor with it */
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_NEWTON_TOL, 1e-6));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE, 1e-7 * size));
    projcurve_result *r = NULL;
    CHECK_STATUS(projcurve_project_directional(ctx, s, c, d, o, &r), PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK(r == NULL);
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE, 1e-6 * size));
    CHECK_OK(projcurve_project_directional(ctx, s, c, d, o, &r));
    double used = 0.0;
    CHECK_OK(projcurve_result_stat(NULL, r, PROJCURVE_STAT_TOL_DISTANCE, &used));
    CHECK_NEAR(used, 1e-6 * size, 0.0);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_context_destroy(ctx);
}

int main(void)
{
    projcurve_surface *s = shape_bumpy(8.0, 1);
    const double pts[6] = {20, 30, 40, 80, 60, 40};
    projcurve_curve *c = shape_bspline_curve(1, 2, pts);
    CHECK(s != NULL && c != NULL);
    test_arguments(s, c);
    test_miss(s);
    test_unreachable_tolerance(s, c);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    test_degenerate_patch();
    test_collapsed_interior_row();
    test_limit();
    test_callback();
    return pc_test_finish("test_trace_bad_input");
}
