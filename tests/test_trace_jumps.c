/*
 * Branches born and ending in mid-curve (seed 000 s3.4): a C-folded sheet
 * met once, then twice; the same curve past the fold (branches ending on
 * the silhouette) and reversed (born on it); a Z-folded sheet met three
 * times; a curve that runs off the surface and back on; a curve longer than
 * the surface at both ends. Every case is checked against dense brute force
 * and its branches' start and end reasons; boundary ends must lie exactly
 * on the domain boundary.
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "trace_oracle.h"
#include "trace_shapes.h"

#define N_SAMPLES 10000
#define RESIDUAL_TOL 1e-9

typedef struct expected_branch {
    projcurve_branch_start start;
    projcurve_branch_end end;
} expected_branch;

static projcurve_result *project(const projcurve_surface *s, const projcurve_curve *c,
                                 const double d[3], int jumps, projcurve_status *st)
{
    projcurve_options *o = NULL;
    projcurve_options_create(NULL, &o);
    projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, 0);
    projcurve_options_set_int(NULL, o, PROJCURVE_OPT_JUMP_DETECTION, jumps);
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

/* Every expected branch appears once (in any order); boundary starts and
 * ends lie on the boundary; brute force finds nothing missed. */
static void check_case(const char *name, const projcurve_surface *s, const projcurve_curve *c,
                       const double d[3], const expected_branch *ex, size_t n_ex)
{
    projcurve_status st;
    projcurve_result *r = project(s, c, d, 1, &st);
    CHECK_OK(st);
    const size_t nb = projcurve_result_branch_count(r);
    printf("%s: %zu branches\n", name, nb);
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
    trace_oracle_report rep;
    trace_oracle_check(s, c, d, r, N_SAMPLES, &rep);
    trace_oracle_print(name, &rep);
    CHECK(rep.uncovered_far == 0);
    CHECK(rep.max_residual <= RESIDUAL_TOL);
    CHECK(rep.behind == 0);
    projcurve_result_destroy(r);
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
    check_case("c-fold flat", s, c, DOWN, ex1, 2);
    /* without jump detection only the seeds at t = 0 are traced: none */
    projcurve_status st;
    projcurve_result *r = project(s, c, DOWN, 0, &st);
    CHECK_OK(st);
    CHECK(projcurve_result_branch_count(r) == 0);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);

    /* past the tip of the bend: both branches end on the silhouette */
    const double past[6] = {-10, 50, 40, 125, 50, 40};
    c = shape_bspline_curve(1, 2, past);
    const expected_branch ex2[2] = {{PROJCURVE_START_BOUNDARY, PROJCURVE_END_SILHOUETTE},
                                    {PROJCURVE_START_BOUNDARY, PROJCURVE_END_SILHOUETTE}};
    check_case("c-fold past the tip", s, c, DOWN, ex2, 2);
    projcurve_curve_destroy(c);

    /* reversed: two branches born on the silhouette in mid-curve */
    const double back[6] = {125, 50, 40, -10, 50, 40};
    c = shape_bspline_curve(1, 2, back);
    const expected_branch ex3[2] = {{PROJCURVE_START_SILHOUETTE, PROJCURVE_END_BOUNDARY},
                                    {PROJCURVE_START_SILHOUETTE, PROJCURVE_END_BOUNDARY}};
    check_case("c-fold reversed", s, c, DOWN, ex3, 2);
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
    check_case("z-fold", s, c, DOWN, ex, 3);
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
    check_case("bumpy exit and re-entry", s, c, DOWN, ex1, 2);
    projcurve_curve_destroy(c);

    /* longer than the surface at both ends */
    const double longer[12] = {-20, 30, 45, 30, 60, 50, 70, 40, 40, 120, 70, 45};
    c = shape_bspline_curve(3, 4, longer);
    const expected_branch ex2[1] = {{PROJCURVE_START_BOUNDARY, PROJCURVE_END_BOUNDARY}};
    check_case("bumpy longer at both ends", s, c, DOWN, ex2, 1);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

int main(void)
{
    test_c_fold();
    test_z_fold();
    test_bumpy_exits();
    return pc_test_finish("test_trace_jumps");
}
