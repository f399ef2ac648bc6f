/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Branches born and ending in mid-curve ([SY13] s3.4): a C-folded sheet
 * met once, then twice; the same curve past the fold (branches ending on
 * the silhouette) and reversed (born on it); a Z-folded sheet met three
 * times; a curve that runs off the surface and back on; a curve longer than
 * the surface at both ends. Every case is checked against dense brute force
 * and its branches' start and end reasons; boundary ends must lie exactly
 * on the domain boundary. Every case runs with both predictors (second
 * order and RK4), and the statistics are checked against what the
 * geometry implies (check_statistics), exactly on a plane.
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "exit_oracle.h"
#include "trace_oracle.h"
#include "trace_shapes.h"

#define N_SAMPLES 10000
#define RESIDUAL_TOL 1e-9
/* Boundary ends lie on the exact crossing of the projection with the
 * boundary (exit_oracle) to this fraction of the model size (issue 5:
 * the exit point located to 1e-10). */
#define EXIT_TOL 1e-10

typedef struct expected_branch {
    projcurve_branch_start start;
    projcurve_branch_end end;
} expected_branch;

static projcurve_result *project(const projcurve_surface *s, const projcurve_curve *c,
                                 const double d[3], int jumps, int method, projcurve_status *st)
{
    projcurve_options *o = NULL;
    projcurve_options_create(NULL, &o);
    projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, 0);
    projcurve_options_set_int(NULL, o, PROJCURVE_OPT_JUMP_DETECTION, jumps);
    projcurve_options_set_int(NULL, o, PROJCURVE_OPT_METHOD, method);
    projcurve_result *r = NULL;
    *st = projcurve_project_directional(NULL, s, c, d, o, &r);
    projcurve_options_destroy(o);
    return r;
}

/* 1 when (u, v) lies exactly on a side of the domain. */
static int on_boundary(const projcurve_surface *s, double u, double v)
{
    double dom[4];
    projcurve_surface_domain(NULL, s, dom);
    return u == dom[0] || u == dom[1] || v == dom[2] || v == dom[3];
}

/* The vertex at the start (first = 1) or end of branch i. */
static void branch_end_point(const projcurve_result *r, size_t i, int first, double p[3])
{
    static double buf[3 * 65536];
    size_t n = 0;
    projcurve_result_branch_points(NULL, r, i, 65536, buf, &n);
    const size_t k = first ? 0 : (n > 65536 ? 65535 : n - 1);
    p[0] = buf[3 * k];
    p[1] = buf[3 * k + 1];
    p[2] = buf[3 * k + 2];
}

/* Default NEWTON_TOL (projcurve.h): eps1 = NEWTON_TOL x model size, eps2 =
 * NEWTON_TOL. */
#define DEFAULT_NEWTON_TOL 1e-12
/* Smallest distance along Dir from the curves of these cases to S (the
 * curves run at least 20 above the highest sheet they meet). */
#define MIN_RAY_DISTANCE 20.0

/* The statistics of a result against what the geometry implies:
 * - JUMPS: the branches found by the sweep, i.e. not seeded at t0 (given);
 * - POINTS: the vertices of all branches;
 * - STEPS >= POINTS - branches: every vertex but the first of a branch
 *   comes from one accepted predictor step (rejected steps count too);
 * - 0 <= AVG_ERROR <= MAX_ERROR;
 * - on these curved (or unevenly parametrised) sheets the predictor is not
 *   exact: MAX_ERROR exceeds the error a guess may have and still pass
 *   the corrector's stopping tests without a Newton step (a sine above
 *   eps1 / distance and above eps2), so NEWTON_ITERATIONS > 0. */
static void check_statistics(const projcurve_result *r, const projcurve_surface *s,
                             double expected_jumps)
{
    double stat[8];
    for (int k = 0; k < 8; ++k)
        CHECK_OK(projcurve_result_stat(NULL, r, (projcurve_stat)k, &stat[k]));
    const double points = stat[PROJCURVE_STAT_POINTS], steps = stat[PROJCURVE_STAT_STEPS];
    const double newton = stat[PROJCURVE_STAT_NEWTON_ITERATIONS];
    const double avg = stat[PROJCURVE_STAT_AVG_ERROR], max = stat[PROJCURVE_STAT_MAX_ERROR];
    printf("  points %g steps %g newton %g avg %.3g max %.3g jumps %g\n", points, steps, newton,
           avg, max, stat[PROJCURVE_STAT_JUMPS]);
    CHECK_NEAR(stat[PROJCURVE_STAT_JUMPS], expected_jumps, 0.0);
    const size_t nb = projcurve_result_branch_count(r);
    size_t vertices = 0;
    for (size_t i = 0; i < nb; ++i) {
        size_t n = 0;
        CHECK_OK(projcurve_result_branch_info(NULL, r, i, NULL, NULL, NULL, &n, NULL));
        vertices += n;
    }
    CHECK_NEAR(points, (double)vertices, 0.0);
    CHECK(steps >= points - (double)nb);
    CHECK(avg >= 0.0 && avg <= max && isfinite(max));
    double box[6];
    CHECK_OK(projcurve_surface_bounds(NULL, s, box));
    const double size = sqrt((box[3] - box[0]) * (box[3] - box[0]) +
                             (box[4] - box[1]) * (box[4] - box[1]) +
                             (box[5] - box[2]) * (box[5] - box[2]));
    const double passes = fmax(DEFAULT_NEWTON_TOL, DEFAULT_NEWTON_TOL * size / MIN_RAY_DISTANCE);
    CHECK(max > passes);
    CHECK(newton > 0.0);
}

/* Every expected branch appears once (in any order); boundary starts and
 * ends lie on the boundary; brute force finds nothing missed. */
static void check_case_with(const char *name, const projcurve_surface *s,
                            const projcurve_curve *c, const double d[3],
                            const expected_branch *ex, size_t n_ex, double expected_jumps,
                            int method)
{
    projcurve_status st;
    projcurve_result *r = project(s, c, d, 1, method, &st);
    CHECK_OK(st);
    const size_t nb = projcurve_result_branch_count(r);
    printf("%s (%s): %zu branches\n", name,
           method == PROJCURVE_METHOD_RK4 ? "RK4" : "second order", nb);
    CHECK(nb == n_ex);
    int used[8] = {0};
    for (size_t i = 0; i < nb; ++i) {
        projcurve_branch_start start;
        projcurve_branch_end end;
        double range[2];
        CHECK_OK(projcurve_result_branch_info(NULL, r, i, range, &start, &end, NULL, NULL));
        printf("  branch %zu: t [%.6f, %.6f] start %d end %d\n", i, range[0], range[1],
               (int)start, (int)end);
        int found = 0;
        for (size_t k = 0; k < n_ex && !found; ++k)
            if (!used[k] && ex[k].start == start && ex[k].end == end)
                found = used[k] = 1;
        CHECK(found);
        double p[3];
        if (start == PROJCURVE_START_BOUNDARY) {
            branch_end_point(r, i, 1, p);
            CHECK(on_boundary(s, p[1], p[2]));
        }
        if (end == PROJCURVE_END_BOUNDARY) {
            branch_end_point(r, i, 0, p);
            CHECK(on_boundary(s, p[1], p[2]));
        }
    }
    check_statistics(r, s, expected_jumps);
    exit_oracle_report ends;
    exit_oracle_check_ends(s, c, d, r, &ends);
    exit_oracle_print(name, &ends);
    CHECK(ends.not_found == 0);
    CHECK(ends.max_dist <= EXIT_TOL);
    CHECK(ends.max_margin == 0.0);
    trace_oracle_report rep;
    trace_oracle_check(s, c, d, r, N_SAMPLES, &rep);
    trace_oracle_print(name, &rep);
    CHECK(rep.uncovered_far == 0);
    CHECK(rep.max_residual <= RESIDUAL_TOL);
    CHECK(rep.behind == 0);
    projcurve_result_destroy(r);
}

/* check_case_with for both predictors. */
static void check_case(const char *name, const projcurve_surface *s, const projcurve_curve *c,
                       const double d[3], const expected_branch *ex, size_t n_ex,
                       double expected_jumps)
{
    check_case_with(name, s, c, d, ex, n_ex, expected_jumps, PROJCURVE_METHOD_SECOND_ORDER);
    check_case_with(name, s, c, d, ex, n_ex, expected_jumps, PROJCURVE_METHOD_RK4);
}

static const double DOWN[3] = {0, 0, -1};

static void test_c_fold(void)
{
    projcurve_surface *s = shape_c_fold();
    CHECK(s != NULL);
    /* over the flat parts: bottom from its edge x = 0, top from its edge
     * x = 20 (the ray meets S 0, 1, then 2 times) */
    const double flat[6] = {-10, 50, 40, 70, 50, 40};
    projcurve_curve *c = shape_bspline_curve(1, 2, flat);
    const expected_branch ex1[2] = {{PROJCURVE_START_BOUNDARY, PROJCURVE_END_CURVE_END},
                                    {PROJCURVE_START_BOUNDARY, PROJCURVE_END_CURVE_END}};
    /* no seed at t0 (x = -10 is off S): both branches are jumps */
    check_case("c-fold flat", s, c, DOWN, ex1, 2, 2.0);
    /* without jump detection only the seeds at t = 0 are traced: none */
    projcurve_status st;
    projcurve_result *r = project(s, c, DOWN, 0, PROJCURVE_METHOD_SECOND_ORDER, &st);
    CHECK_OK(st);
    CHECK(projcurve_result_branch_count(r) == 0);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);

    /* past the tip of the bend: both branches end on the silhouette */
    const double past[6] = {-10, 50, 40, 125, 50, 40};
    c = shape_bspline_curve(1, 2, past);
    const expected_branch ex2[2] = {{PROJCURVE_START_BOUNDARY, PROJCURVE_END_SILHOUETTE},
                                    {PROJCURVE_START_BOUNDARY, PROJCURVE_END_SILHOUETTE}};
    /* the same start off S: two jumps */
    check_case("c-fold past the tip", s, c, DOWN, ex2, 2, 2.0);
    projcurve_curve_destroy(c);

    /* reversed: two branches born on the silhouette in mid-curve */
    const double back[6] = {125, 50, 40, -10, 50, 40};
    c = shape_bspline_curve(1, 2, back);
    const expected_branch ex3[2] = {{PROJCURVE_START_SILHOUETTE, PROJCURVE_END_BOUNDARY},
                                    {PROJCURVE_START_SILHOUETTE, PROJCURVE_END_BOUNDARY}};
    /* x = 125 is off S at t0: two jumps */
    check_case("c-fold reversed", s, c, DOWN, ex3, 2, 2.0);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

static void test_z_fold(void)
{
    projcurve_surface *s = shape_z_fold();
    CHECK(s != NULL);
    /* from x = 90 back to x = 45: bottom and middle all along; the top
     * layer (ending near x = 55) is born at its edge in mid-curve */
    const double pts[6] = {90, 50, 60, 45, 50, 60};
    projcurve_curve *c = shape_bspline_curve(1, 2, pts);
    const expected_branch ex[3] = {{PROJCURVE_START_CURVE_START, PROJCURVE_END_CURVE_END},
                                   {PROJCURVE_START_CURVE_START, PROJCURVE_END_CURVE_END},
                                   {PROJCURVE_START_BOUNDARY, PROJCURVE_END_CURVE_END}};
    /* two seeds at t0, the top layer is the one jump */
    check_case("z-fold", s, c, DOWN, ex, 3, 1.0);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

static void test_bumpy_exits(void)
{
    projcurve_surface *s = shape_bumpy(8.0, 12345);
    CHECK(s != NULL);
    /* from x = 40 out past the x = 100 edge and back */
    const double out_back[15] = {40, 20, 45, 90, 35, 45, 125, 50, 45, 90, 65, 45, 40, 80, 45};
    projcurve_curve *c = shape_bspline_curve(3, 5, out_back);
    const expected_branch ex1[2] = {{PROJCURVE_START_CURVE_START, PROJCURVE_END_BOUNDARY},
                                    {PROJCURVE_START_BOUNDARY, PROJCURVE_END_CURVE_END}};
    /* seeded at t0, the re-entry is the one jump */
    check_case("bumpy exit and re-entry", s, c, DOWN, ex1, 2, 1.0);
    projcurve_curve_destroy(c);

    /* longer than the surface at both ends */
    const double longer[12] = {-20, 30, 45, 30, 60, 50, 70, 40, 40, 120, 70, 45};
    c = shape_bspline_curve(3, 4, longer);
    const expected_branch ex2[1] = {{PROJCURVE_START_BOUNDARY, PROJCURVE_END_BOUNDARY}};
    /* x = -20 is off S at t0: the one branch is a jump */
    check_case("bumpy longer at both ends", s, c, DOWN, ex2, 1, 1.0);
    projcurve_curve_destroy(c);

    /* inside the domain all along: no boundary to locate, so the Newton
     * iterations counted are the tracing corrector's own; no jump */
    const double inside[12] = {20, 20, 45, 50, 60, 45, 80, 30, 45, 70, 80, 45};
    c = shape_bspline_curve(3, 4, inside);
    const expected_branch ex3[1] = {{PROJCURVE_START_CURVE_START, PROJCURVE_END_CURVE_END}};
    check_case("bumpy inside", s, c, DOWN, ex3, 1, 0.0);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

/* A line over a plane with constant parameter steps: the projection is
 * affine in t, so both predictors are exact (to rounding) and the counts
 * are known: 1 / dt + 1 vertices from 1 / dt steps, no rejection, no Newton
 * iteration (the guess passes the stopping tests), no jump (the one branch
 * is seeded at t0), estimation errors at rounding level. */
static void test_plane_statistics(void)
{
    const double o[3] = {0, 0, 0}, a[3] = {100, 0, 0}, b[3] = {0, 100, 0};
    projcurve_surface *s = shape_plane(o, a, b);
    const double pts[6] = {10, 20, 30, 80, 60, 30};
    projcurve_curve *c = shape_bspline_curve(1, 2, pts);
    const int methods[2] = {PROJCURVE_METHOD_SECOND_ORDER, PROJCURVE_METHOD_RK4};
    for (int m = 0; m < 2; ++m) {
        projcurve_options *opt = NULL;
        CHECK_OK(projcurve_options_create(NULL, &opt));
        CHECK_OK(projcurve_options_set_int(NULL, opt, PROJCURVE_OPT_COMPOSE, 0));
        CHECK_OK(projcurve_options_set_int(NULL, opt, PROJCURVE_OPT_METHOD, methods[m]));
        CHECK_OK(projcurve_options_set_double(NULL, opt, PROJCURVE_OPT_PARAM_STEP, 0.01));
        projcurve_result *r = NULL;
        CHECK_OK(projcurve_project_directional(NULL, s, c, DOWN, opt, &r));
        projcurve_options_destroy(opt);
        double stat[8];
        for (int k = 0; k < 8; ++k)
            CHECK_OK(projcurve_result_stat(NULL, r, (projcurve_stat)k, &stat[k]));
        printf("plane, method %d: points %g steps %g newton %g avg %.3g max %.3g jumps %g\n",
               methods[m], stat[0], stat[1], stat[2], stat[3], stat[7], stat[4]);
        CHECK(projcurve_result_branch_count(r) == 1);
        CHECK_NEAR(stat[PROJCURVE_STAT_POINTS], 101.0, 0.0);
        CHECK_NEAR(stat[PROJCURVE_STAT_STEPS], 100.0, 0.0);
        CHECK_NEAR(stat[PROJCURVE_STAT_NEWTON_ITERATIONS], 0.0, 0.0);
        CHECK_NEAR(stat[PROJCURVE_STAT_JUMPS], 0.0, 0.0);
        /* (3.8) is a sine: rounding of coordinates ~100 over a distance 30 */
        CHECK(stat[PROJCURVE_STAT_AVG_ERROR] >= 0.0 &&
              stat[PROJCURVE_STAT_AVG_ERROR] <= stat[PROJCURVE_STAT_MAX_ERROR]);
        CHECK(stat[PROJCURVE_STAT_MAX_ERROR] <= 1e-14);
        projcurve_result_destroy(r);
    }
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

int main(void)
{
    test_plane_statistics();
    test_c_fold();
    test_z_fold();
    test_bumpy_exits();
    return pc_test_finish("test_trace_jumps");
}
