/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * [SY13] s5 Example 1: the cubic curve in the plane x = 0 projected along
 * Dir = (-1, 0, 0) onto the degree 5 x 1 sheet near x = -90 (the paper's
 * stated (0, 0, -1) misses the sheet: an empty result). Both methods, with
 * the paper's constant parameter steps (Table 1: 1/dt + 1 points), against
 * brute force, and against each other.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "trace_oracle.h"
#include "trace_shapes.h"

#define N_SAMPLES 10000
#define RESIDUAL_TOL 1e-9

static projcurve_result *project(const projcurve_surface *s, const projcurve_curve *c,
                                 const double d[3], double dt, int method,
                                 projcurve_status *st)
{
    projcurve_options *o = NULL;
    projcurve_options_create(NULL, &o);
    projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, 0);
    projcurve_options_set_int(NULL, o, PROJCURVE_OPT_METHOD, method);
    projcurve_options_set_double(NULL, o, PROJCURVE_OPT_PARAM_STEP, dt);
    projcurve_result *r = NULL;
    *st = projcurve_project_directional(NULL, s, c, d, o, &r);
    projcurve_options_destroy(o);
    return r;
}

static double *branch_points(const projcurve_result *r, size_t i, size_t *n)
{
    projcurve_result_branch_points(NULL, r, i, 0, NULL, n);
    double *p = malloc(3 * (*n ? *n : 1) * sizeof *p);
    projcurve_result_branch_points(NULL, r, i, *n, p, n);
    return p;
}

static void test_arc_length(const projcurve_surface *s, const projcurve_curve *c)
{
    const double d[3] = {-1, 0, 0};
    projcurve_status st;
    projcurve_result *r = project(s, c, d, 0.0, PROJCURVE_METHOD_SECOND_ORDER, &st);
    CHECK_OK(st);
    CHECK(projcurve_result_branch_count(r) == 1);
    double range[2];
    projcurve_branch_start start;
    projcurve_branch_end end;
    CHECK_OK(projcurve_result_branch_info(NULL, r, 0, range, &start, &end, NULL, NULL));
    CHECK(start == PROJCURVE_START_CURVE_START && end == PROJCURVE_END_CURVE_END);
    CHECK(range[0] == 0.0 && range[1] == 1.0);
    trace_oracle_report rep;
    trace_oracle_check(s, c, d, r, N_SAMPLES, &rep);
    trace_oracle_print("example1 arc-length", &rep);
    CHECK(rep.hits == N_SAMPLES);
    CHECK(rep.uncovered_far == 0);
    CHECK(rep.max_residual <= RESIDUAL_TOL);
    CHECK(rep.behind == 0);
    /* constant arc length: 1/64 of the estimated length per step, so
     * about 64 steps (the estimate is from the control polygon) */
    size_t n = 0;
    double *p = branch_points(r, 0, &n);
    CHECK(n >= 40 && n <= 120);
    double lo = INFINITY, hi = 0.0;
    for (size_t k = 1; k + 1 < n; ++k) {
        double a[3], b[3];
        projcurve_surface_eval(NULL, s, p[3 * k - 2], p[3 * k - 1], 0, a);
        projcurve_surface_eval(NULL, s, p[3 * k + 1], p[3 * k + 2], 0, b);
        const double len = sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                                (a[2] - b[2]) * (a[2] - b[2]));
        lo = fmin(lo, len);
        hi = fmax(hi, len);
    }
    printf("arc-length steps: %zu points, chord %.4g .. %.4g\n", n, lo, hi);
    CHECK(hi <= 1.5 * lo); /* evenly spaced, eq. (3.7) */
    free(p);
    projcurve_result_destroy(r);
}

/* Table 1 settings: both methods give 1/dt + 1 points on the same curve. */
static void test_table1(const projcurve_surface *s, const projcurve_curve *c)
{
    const double d[3] = {-1, 0, 0};
    const double steps[4] = {1e-2, 1e-3, 1e-4, 0.25};
    const size_t expect[4] = {101, 1001, 10001, 5};
    double prev_e2 = 0.0;
    /* the last, coarse step: the jump sweep must still recognise the one
     * branch between its far-apart vertices (no duplicate) */
    for (int k = 0; k < 4; ++k) {
        projcurve_status s2, s4;
        projcurve_result *r2 = project(s, c, d, steps[k], PROJCURVE_METHOD_SECOND_ORDER, &s2);
        projcurve_result *r4 = project(s, c, d, steps[k], PROJCURVE_METHOD_RK4, &s4);
        CHECK_OK(s2);
        CHECK_OK(s4);
        CHECK(projcurve_result_branch_count(r2) == 1 && projcurve_result_branch_count(r4) == 1);
        size_t n2 = 0, n4 = 0;
        double *p2 = branch_points(r2, 0, &n2), *p4 = branch_points(r4, 0, &n4);
        CHECK(n2 == expect[k] && n4 == expect[k]);
        double worst = 0.0;
        for (size_t i = 0; i < n2 && i < n4; ++i) {
            CHECK(p2[3 * i] == p4[3 * i]);
            worst = fmax(worst, fmax(fabs(p2[3 * i + 1] - p4[3 * i + 1]),
                                     fabs(p2[3 * i + 2] - p4[3 * i + 2])));
        }
        /* both corrected to the same curve, to the Newton tolerance */
        CHECK_NEAR(worst, 0.0, 1e-10);
        double e2, e4;
        CHECK_OK(projcurve_result_stat(NULL, r2, PROJCURVE_STAT_AVG_ERROR, &e2));
        CHECK_OK(projcurve_result_stat(NULL, r4, PROJCURVE_STAT_AVG_ERROR, &e4));
        printf("dt %.0e: %zu points, avg error (3.8) second order %.3g, RK4 %.3g\n", steps[k],
               n2, e2, e4);
        /* the Taylor predictor's local error is O(dt^3), RK4's O(dt^5):
         * a decade of dt takes the second-order error down ~1000 times,
         * and RK4 stays below it */
        CHECK(e2 > 0.0 && e4 <= e2);
        if (k > 0 && k < 3)
            CHECK(e2 <= 2e-3 * prev_e2);
        prev_e2 = e2;
        free(p2);
        free(p4);
        projcurve_result_destroy(r2);
        projcurve_result_destroy(r4);
    }
}

static void test_paper_direction(const projcurve_surface *s, const projcurve_curve *c)
{
    const double d[3] = {0, 0, -1};
    projcurve_status st;
    projcurve_result *r = project(s, c, d, 0.0, PROJCURVE_METHOD_SECOND_ORDER, &st);
    CHECK_OK(st);
    CHECK(r != NULL && projcurve_result_branch_count(r) == 0);
    projcurve_result_destroy(r);
}

int main(void)
{
    projcurve_surface *s = shape_example1_surface();
    projcurve_curve *c = shape_example1_curve();
    CHECK(s != NULL && c != NULL);
    if (s && c) {
        test_arc_length(s, c);
        test_table1(s, c);
        test_paper_direction(s, c);
    }
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    return pc_test_finish("test_trace_example1");
}
