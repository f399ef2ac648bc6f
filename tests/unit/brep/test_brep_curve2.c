/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The 2D trimming curves (brep/curve2.h):
 *   - every refusal of pc_curve2_init (NULL arrays, degree, control point
 *     count, knots that are not finite, decrease or leave an empty domain,
 *     control points that are not finite, weights <= 0 or not finite),
 *     each with its status and a message naming the piece and the fault;
 *   - a quarter of the unit circle as a rational quadratic: evaluated
 *     exactly on the circle (|p| = 1 to rounding) with its end points at
 *     the ends, clamped outside the domain, and flattened within err of the
 *     circle (every vertex on it, every chord's midpoint within err:
 *     the sagitta 1 - cos(h / 2) of each chord of angle h).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "brep/curve2.h"
#include "check.h"

static projcurve_context *ctx;

static void refuses(int degree, size_t n_ctrl, const double *ctrl, const double *weights,
                    const double *knots, projcurve_status status, const char *needle)
{
    pc_curve2 c;
    projcurve_context_clear(ctx);
    CHECK_STATUS(pc_curve2_init(ctx, &c, degree, n_ctrl, ctrl, weights, knots, "piece 7"),
                 status);
    const char *msg = projcurve_context_message(ctx);
    if (strstr(msg, "piece 7") == NULL || strstr(msg, needle) == NULL)
        pc_test_fail_at(__FILE__, __LINE__, "message \"%s\" lacks \"%s\"", msg, needle);
    ++pc_test_checks;
    CHECK(c.ctrl == NULL && c.knots == NULL && c.weights == NULL);
}

static void test_refusals(void)
{
    const double ctrl[6] = {0, 0, 1, 0, 1, 1}, knots[6] = {0, 0, 0, 1, 1, 1};
    const double w[3] = {1, 0.5, 1};
    refuses(2, 3, NULL, NULL, knots, PROJCURVE_ERR_NULL_ARGUMENT, "ctrl is NULL");
    refuses(2, 3, ctrl, NULL, NULL, PROJCURVE_ERR_NULL_ARGUMENT, "knots is NULL");
    refuses(0, 3, ctrl, NULL, knots, PROJCURVE_ERR_BAD_DEGREE, "degree 0");
    refuses(PROJCURVE_MAX_DEGREE + 1, 3, ctrl, NULL, knots, PROJCURVE_ERR_BAD_DEGREE,
            "is outside");
    refuses(2, 2, ctrl, NULL, knots, PROJCURVE_ERR_BAD_COUNT, "2 control points for degree 2");
    const double nan_knot[6] = {0, 0, 0, NAN, 1, 1};
    refuses(2, 3, ctrl, NULL, nan_knot, PROJCURVE_ERR_NOT_FINITE, "knot 3 is not finite");
    const double falling[6] = {0, 0, 0, 1, 0.5, 1};
    refuses(2, 3, ctrl, NULL, falling, PROJCURVE_ERR_BAD_KNOTS, "decreases at index 4");
    const double empty[6] = {0, 0, 1, 1, 1, 1};
    refuses(2, 3, ctrl, NULL, empty, PROJCURVE_ERR_BAD_KNOTS, "domain [1, 1] is empty");
    const double inf_ctrl[6] = {0, 0, 1, INFINITY, 1, 1};
    refuses(2, 3, inf_ctrl, NULL, knots, PROJCURVE_ERR_NOT_FINITE,
            "control point 1 is not finite");
    const double w_zero[3] = {1, 0, 1}, w_nan[3] = {1, 1, NAN};
    refuses(2, 3, ctrl, w_zero, knots, PROJCURVE_ERR_BAD_WEIGHT, "weight 1 is 0");
    refuses(2, 3, ctrl, w_nan, knots, PROJCURVE_ERR_BAD_WEIGHT, "weight 2 is");
    pc_curve2 c;
    CHECK_OK(pc_curve2_init(ctx, &c, 2, 3, ctrl, w, knots, "piece 7"));
    pc_curve2_free(&c);
}

/* The quarter circle from (1, 0) to (0, 1): control points (1, 0), (1, 1),
 * (0, 1) with weights 1, cos 45 deg, 1, over [2, 5]. */
static void test_quarter_circle(void)
{
    const double ctrl[6] = {1, 0, 1, 1, 0, 1}, knots[6] = {2, 2, 2, 5, 5, 5};
    const double w[3] = {1, sqrt(0.5), 1};
    pc_curve2 c;
    CHECK_OK(pc_curve2_init(ctx, &c, 2, 3, ctrl, w, knots, "arc"));
    double t0 = 0, t1 = 0, p[2];
    pc_curve2_domain(&c, &t0, &t1);
    CHECK(t0 == 2.0 && t1 == 5.0);
    for (int k = 0; k <= 30; ++k) {
        pc_curve2_eval(&c, 2.0 + 0.1 * k, p);
        CHECK_NEAR(hypot(p[0], p[1]), 1.0, 1e-15); /* a few roundings of ~1 */
        CHECK(p[0] >= -1e-15 && p[1] >= -1e-15);
    }
    pc_curve2_eval(&c, 2.0, p);
    CHECK_NEAR(p[0], 1.0, 1e-15);
    CHECK_NEAR(p[1], 0.0, 1e-15);
    pc_curve2_eval(&c, 9.0, p); /* clamped to the end */
    CHECK_NEAR(p[0], 0.0, 1e-15);
    CHECK_NEAR(p[1], 1.0, 1e-15);
    pc_curve2_eval(&c, 3.5, p); /* the symmetric point: 45 degrees */
    CHECK_NEAR(p[0], p[1], 1e-15);

    const double err = 1e-4;
    pc_polyline2 line = {0};
    CHECK_OK(pc_curve2_flatten(ctx, &c, err, &line, "arc"));
    CHECK_OK(pc_polyline2_push(ctx, &line, 0.0, 1.0)); /* the last vertex, left to the caller */
    /* the sagitta bound err needs chords of at most 2 acos(1 - err) ~ 0.028
     * rad: at least 55 of them over pi / 2 */
    CHECK(line.count >= 56);
    CHECK(line.count < 2000);
    CHECK_NEAR(line.xy[0], 1.0, 1e-15);
    CHECK_NEAR(line.xy[1], 0.0, 1e-15);
    for (size_t k = 0; k + 1 < line.count; ++k) {
        const double *a = line.xy + 2 * k, *b = a + 2;
        CHECK_NEAR(hypot(a[0], a[1]), 1.0, 1e-12); /* vertices on the curve */
        CHECK(atan2(b[1], b[0]) > atan2(a[1], a[0])); /* in order along it */
        const double mid = hypot(0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]));
        CHECK(1.0 - mid <= err);
    }
    printf("quarter circle within %g: %zu vertices\n", err, line.count);
    pc_polyline2_free(&line);
    pc_curve2_free(&c);
}

int main(void)
{
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    test_refusals();
    test_quarter_circle();
    projcurve_context_destroy(ctx);
    return pc_test_finish("test_brep_curve2");
}
