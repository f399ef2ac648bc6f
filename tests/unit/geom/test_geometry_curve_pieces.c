/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The control boxes of a curve cut to [ta, tb] (geom/curve_pieces.h), the
 * bound the jump sweep narrows its steps with: on a rational cubic with
 * uneven inner knots, for stretches inside one segment, across several,
 * at the domain's ends and of zero length, against dense samples of the
 * curve (pc_curve_eval, de Boor): every sample of [ta, tb] lies in the box
 * (to rounding, 1e-12 of the curve's size), the ends returned are P(ta)
 * and P(tb) to that, and the box shrinks onto the curve: for a stretch
 * 1e-6 of the domain it is within 1e-5 of the curve's size of the
 * samples' box (a box of the spans' control points would stay a whole
 * segment's). The chord-axis range (pc_curve_pieces_range) of a linear
 * value holds every sample's value.
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "geom/curve_pieces.h"

#define SAMPLES 2000
#define ROUND_TOL 1e-12
#define SHRINK_TOL 1e-5

static double along(const void *user, pc_vec3 c)
{
    const pc_vec3 *n = user;
    return vec3_dot(*n, c);
}

static void check_stretch(const projcurve_curve *c, const pc_curve_pieces *p, double ta,
                          double tb, double size, int shrink)
{
    double box[6], range[2];
    pc_vec3 ends[2];
    const pc_vec3 n = vec3(0.48, -0.6, 0.64);
    CHECK(pc_curve_pieces_box(p, ta, tb, box, ends) == 1);
    CHECK(pc_curve_pieces_range(p, ta, tb, along, &n, range) == 1);
    double seen[6];
    box_empty(seen);
    double worst_out = 0.0, worst_range = 0.0;
    for (int i = 0; i <= SAMPLES; ++i) {
        const double t = ta + (tb - ta) * (double)i / SAMPLES;
        pc_vec3 x;
        CHECK_OK(pc_curve_eval(c, t, 0, NULL, &x));
        const double q[3] = {x.x, x.y, x.z};
        box_add_point(seen, q);
        for (int k = 0; k < 3; ++k)
            worst_out = fmax(worst_out, fmax(box[k] - q[k], q[k] - box[k + 3]));
        const double v = vec3_dot(n, x);
        worst_range = fmax(worst_range, fmax(range[0] - v, v - range[1]));
    }
    pc_vec3 pa, pb;
    CHECK_OK(pc_curve_eval(c, ta, 0, NULL, &pa));
    CHECK_OK(pc_curve_eval(c, tb, 0, NULL, &pb));
    if (worst_out > ROUND_TOL * size)
        printf("  [%.9g, %.9g]: a sample %.3g outside the box\n", ta, tb, worst_out);
    CHECK(worst_out <= ROUND_TOL * size);
    CHECK(worst_range <= ROUND_TOL * size);
    CHECK_NEAR(vec3_dist(ends[0], pa), 0.0, ROUND_TOL * size);
    CHECK_NEAR(vec3_dist(ends[1], pb), 0.0, ROUND_TOL * size);
    if (shrink)
        for (int k = 0; k < 6; ++k)
            CHECK_NEAR(box[k], seen[k], SHRINK_TOL * size);
}

int main(void)
{
    /* a rational cubic, 7 control points, inner knots 0.1, 0.45, 0.5 */
    static const double ctrl[21] = {0, 0, 0, 1, 3, -1, 4, 2, 2, 5, -2, 0,
                                    7, 1, 3, 9, 4, -2, 12, 0, 1};
    static const double weights[7] = {1, 2, 0.5, 1, 3, 1, 0.7};
    static const double knots[11] = {0, 0, 0, 0, 0.1, 0.45, 0.5, 1, 1, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 3, 7, ctrl, weights, knots, &c));
    pc_curve_pieces p;
    CHECK_OK(pc_curve_pieces_build(NULL, c, &p));
    CHECK(p.bz.n_segments == 4);
    const double size = 15.0; /* about the control polygon's diagonal */
    static const double stretches[][2] = {
        {0.2, 0.3},   {0.05, 0.47}, {0.0, 1.0},  {0.47, 0.5}, {0.5, 0.5},
        {0.0, 0.0},   {1.0, 1.0},   {0.9, 1.0},  {0.1, 0.45}, {0.3337, 0.3337001},
    };
    for (size_t k = 0; k < sizeof stretches / sizeof stretches[0]; ++k)
        check_stretch(c, &p, stretches[k][0], stretches[k][1], size,
                      stretches[k][1] - stretches[k][0] <= 1e-6);
    pc_curve_pieces_free(&p);
    projcurve_curve_destroy(c);
    return pc_test_finish("test_geometry_curve_pieces");
}
