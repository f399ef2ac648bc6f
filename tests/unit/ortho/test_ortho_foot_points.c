/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * PROJCURVE_OPT_FOOT_POINTS: by default the orthogonal projection returns
 * only the feet where the distance to P(t) is locally smallest; with
 * PROJCURVE_FOOT_POINTS_ALL every critical foot point. The oracle is the
 * sphere's closed form: the foot points of P are c +- R (P - c) / |P - c|,
 * at distances |P - c| - R (the minimum) and |P - c| + R (the maximum).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "shapes.h"

/* Vertices are foot points to the corrector's tolerance (1e-12 of the
 * model size) plus rounding: 1e-9 of the radius is far above both and far
 * below the 2R between the two sheets. */
#define SHEET_TOL 1e-9

/* Counts the vertices of r on the near sheet (distance |P| - R) and on the
 * far one (|P| + R); *other gets the rest. */
static void count_sheets(const projcurve_result *r, const projcurve_surface *s,
                         const projcurve_curve *c, double radius, size_t *near, size_t *far,
                         size_t *other)
{
    *near = *far = *other = 0;
    for (size_t b = 0; b < projcurve_result_branch_count(r); ++b) {
        size_t n = 0;
        projcurve_result_branch_info(NULL, r, b, NULL, NULL, NULL, &n, NULL);
        double *pts = malloc(3 * (n ? n : 1) * sizeof *pts);
        CHECK_OK(projcurve_result_branch_points(NULL, r, b, n, pts, &n));
        for (size_t i = 0; i < n; ++i) {
            double p[3], x[3];
            projcurve_curve_eval(NULL, c, pts[3 * i], 0, p);
            projcurve_surface_eval(NULL, s, pts[3 * i + 1], pts[3 * i + 2], 0, x);
            const double dp = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            const double d = sqrt((x[0] - p[0]) * (x[0] - p[0]) + (x[1] - p[1]) * (x[1] - p[1]) +
                                  (x[2] - p[2]) * (x[2] - p[2]));
            if (fabs(d - (dp - radius)) <= SHEET_TOL * radius)
                ++*near;
            else if (fabs(d - (dp + radius)) <= SHEET_TOL * radius)
                ++*far;
            else
                ++*other;
        }
        free(pts);
    }
}

static void run(const char *name, long long which, const projcurve_surface *s,
                const projcurve_curve *c, double radius, int expect_far)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    if (which >= 0)
        CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_FOOT_POINTS, which));
    long long got = -1;
    CHECK_OK(projcurve_options_get_int(NULL, o, PROJCURVE_OPT_FOOT_POINTS, &got));
    CHECK(got == (which >= 0 ? which : PROJCURVE_FOOT_POINTS_MINIMA));
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_orthogonal(NULL, s, c, o, &r));
    size_t near = 0, far = 0, other = 0;
    count_sheets(r, s, c, radius, &near, &far, &other);
    printf("%s: %zu branch(es), vertices near %zu, far %zu, neither %zu\n", name,
           projcurve_result_branch_count(r), near, far, other);
    CHECK(near > 0);
    CHECK(other == 0);
    CHECK(expect_far ? far > 0 : far == 0);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
}

int main(void)
{
    const double centre[3] = {0.0, 0.0, 0.0}, radius = 1.0;
    pc_shape_surface data = pc_shape_sphere(centre, radius);
    projcurve_surface *s = pc_shape_surface_create(&data);
    pc_shape_surface_free(&data);
    /* a line over the sphere, off the seam's plane y = 0 and the poles */
    pc_shape_line line = {{-1.0, 0.2, 1.5}, {1.0, 0.0, 0.0}};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, pc_shape_line_fn, &line, 0.0, 2.0, &c));
    run("default (minima)", -1, s, c, radius, 0);
    run("PROJCURVE_FOOT_POINTS_MINIMA", PROJCURVE_FOOT_POINTS_MINIMA, s, c, radius, 0);
    run("PROJCURVE_FOOT_POINTS_ALL", PROJCURVE_FOOT_POINTS_ALL, s, c, radius, 1);
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_STATUS(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_FOOT_POINTS, 2),
                 PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK_STATUS(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_FOOT_POINTS, -1),
                 PROJCURVE_ERR_OUT_OF_RANGE);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    return pc_test_finish("test_ortho_foot_points");
}
