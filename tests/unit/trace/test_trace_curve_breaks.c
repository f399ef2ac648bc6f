/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * trace/curve_breaks.c against the knot vectors written out by hand: which
 * interior knots are breaks of each order, the cursor's next break both
 * ways (also after jumps back and forth, which must not use a stale
 * bracket), the one-sided evaluation parameter, callback curves without
 * breaks.
 */
#include <math.h>

#include "check.h"
#include "geom/curve.h"
#include "trace/curve_breaks.h"

static int unit_circle(void *user, double t, double out[9])
{
    (void)user;
    out[0] = cos(t), out[1] = sin(t), out[2] = 0.0;
    out[3] = -sin(t), out[4] = cos(t), out[5] = 0.0;
    out[6] = -cos(t), out[7] = -sin(t), out[8] = 0.0;
    return 0;
}

int main(void)
{
    /* degree 3 over [0, 5]: knot 1 simple (C2), 2 double (C1), 3 triple
     * (C0), 4 simple */
    const double knots[] = {0, 0, 0, 0, 1, 2, 2, 3, 3, 3, 4, 5, 5, 5, 5};
    const size_t n_ctrl = sizeof knots / sizeof knots[0] - 4;
    double ctrl[3 * 16];
    for (size_t k = 0; k < 3 * n_ctrl; ++k)
        ctrl[k] = (double)(k % 7);
    projcurve_curve *c = NULL;
    CHECK_OK(pc_curve_create_nurbs(NULL, 3, n_ctrl, ctrl, NULL, knots, &c));

    /* order 2 (the predictor): 2 and 3; order 1 (corners): 3 only */
    CHECK(!pc_curve_break_at(c, 1.0, PC_BREAK_ORDER_PREDICTOR));
    CHECK(pc_curve_break_at(c, 2.0, PC_BREAK_ORDER_PREDICTOR));
    CHECK(pc_curve_break_at(c, 3.0, PC_BREAK_ORDER_PREDICTOR));
    CHECK(!pc_curve_break_at(c, 2.0, PC_BREAK_ORDER_CORNER));
    CHECK(pc_curve_break_at(c, 3.0, PC_BREAK_ORDER_CORNER));
    CHECK(!pc_curve_break_at(c, 2.5, PC_BREAK_ORDER_PREDICTOR));
    CHECK(!pc_curve_break_at(c, 0.0, PC_BREAK_ORDER_CORNER)); /* the ends are no breaks */
    CHECK(!pc_curve_break_at(c, 5.0, PC_BREAK_ORDER_CORNER));

    pc_curve_breaks b;
    pc_curve_breaks_init(&b, c, PC_BREAK_ORDER_PREDICTOR);
    CHECK(pc_curve_breaks_next(&b, 0.0, 1) == 2.0);
    CHECK(pc_curve_breaks_next(&b, 1.5, 1) == 2.0);
    CHECK(pc_curve_breaks_next(&b, 2.0, 1) == 3.0); /* strictly beyond */
    CHECK(pc_curve_breaks_next(&b, 3.0, 1) == 5.0); /* none: the domain end */
    CHECK(pc_curve_breaks_next(&b, 4.5, -1) == 3.0);
    CHECK(pc_curve_breaks_next(&b, 3.0, -1) == 2.0);
    CHECK(pc_curve_breaks_next(&b, 2.0, -1) == 0.0); /* none: the domain start */
    CHECK(pc_curve_breaks_next(&b, 0.5, 1) == 2.0); /* back to the start */
    CHECK(pc_curve_breaks_next(&b, 2.5, -1) == 2.0);
    CHECK(pc_curve_breaks_next(&b, 2.5, 1) == 3.0);

    /* one-sided parameters: the neighbouring doubles at a break only */
    CHECK(pc_curve_break_side(c, 3.0, -1, PC_BREAK_ORDER_CORNER) == nextafter(3.0, 0.0));
    CHECK(pc_curve_break_side(c, 3.0, 1, PC_BREAK_ORDER_CORNER) == nextafter(3.0, 4.0));
    CHECK(pc_curve_break_side(c, 2.0, -1, PC_BREAK_ORDER_CORNER) == 2.0);
    CHECK(pc_curve_break_side(c, 2.5, -1, PC_BREAK_ORDER_PREDICTOR) == 2.5);

    /* the left and right derivatives at the C0 knot differ; the points agree */
    pc_vec3 left[2], right[2];
    CHECK_OK(pc_curve_eval(c, nextafter(3.0, 0.0), 1, NULL, left));
    CHECK_OK(pc_curve_eval(c, 3.0, 1, NULL, right));
    CHECK(vec3_dist(left[0], right[0]) <= 1e-12);
    CHECK(vec3_dist(left[1], right[1]) > 1e-3);
    pc_curve_destroy(c);

    projcurve_curve *cb = NULL;
    CHECK_OK(pc_curve_create_callback(NULL, unit_circle, NULL, 0.0, 6.0, &cb));
    CHECK(!pc_curve_break_at(cb, 3.0, PC_BREAK_ORDER_CORNER));
    pc_curve_breaks_init(&b, cb, PC_BREAK_ORDER_PREDICTOR);
    CHECK(isinf(pc_curve_breaks_next(&b, 1.0, 1)));
    pc_curve_destroy(cb);
    return pc_test_finish("test_trace_curve_breaks");
}
