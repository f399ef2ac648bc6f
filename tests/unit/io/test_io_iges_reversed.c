/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * pc_iges_format_curve_reversed (the member of a composite curve the chain
 * runs along with t decreasing): written as entity 126 and read back by
 * the IGES reader, the curve is the original run backwards, R(s) =
 * C(a + b - s) over the same domain [a, b], at 101 samples to 1e-14 of its
 * size. Cases: a polynomial cubic with an interior double knot on a domain
 * not starting at 0, and a rational quarter circle (exact in the weights:
 * the reversed weights must go with the reversed points).
 */
#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "geom/curve.h"
#include "io/iges_write.h"
#include "projcurve.h"

#define N_SAMPLES 101
#define REL_TOL 1e-14

static void check_reversed(const projcurve_curve *c, double size, const char *what)
{
    pc_iges_out out = {0};
    pc_text_buf b = {0};
    pc_iges_format_curve_reversed(&b, &c->nurbs, 0);
    size_t de = 0;
    CHECK_OK(pc_iges_out_add(NULL, &out, 126, 0, PC_IGES_STATUS_INDEPENDENT, &b, &de));
    free(b.text);
    char *text = NULL;
    size_t len = 0;
    CHECK_OK(pc_iges_out_text(NULL, &out, &text, &len));
    pc_iges_out_free(&out);
    projcurve_model *m = NULL;
    CHECK_OK(projcurve_model_read_memory(NULL, text, len, &m));
    free(text);
    CHECK(projcurve_model_curve_count(m) == 1);
    if (projcurve_model_curve_count(m) == 1) {
        const projcurve_curve *r = projcurve_model_curve(m, 0);
        double a, e, ra, re;
        CHECK_OK(projcurve_curve_domain(NULL, c, &a, &e));
        CHECK_OK(projcurve_curve_domain(NULL, r, &ra, &re));
        CHECK_NEAR(ra, a, 0.0);
        CHECK_NEAR(re, e, 0.0);
        double worst = 0.0;
        for (int i = 0; i < N_SAMPLES; ++i) {
            const double s = a + (e - a) * i / (N_SAMPLES - 1.0);
            double p[3], q[3];
            CHECK_OK(projcurve_curve_eval(NULL, r, s, 0, p));
            CHECK_OK(projcurve_curve_eval(NULL, c, a + e - s, 0, q));
            worst = fmax(worst, hypot(hypot(p[0] - q[0], p[1] - q[1]), p[2] - q[2]));
        }
        if (worst > REL_TOL * size)
            pc_test_fail_at(__FILE__, __LINE__, "%s: reversed curve off by %.3g", what, worst);
        ++pc_test_checks;
    }
    projcurve_model_destroy(m);
}

int main(void)
{
    /* cubic, knots 2 .. 5 with a double knot at 3 (mirrored: 4) */
    const double ctrl[] = {0, 0, 0, 1, 2, 0, 3, 3, 1, 4, 1, 2, 6, 0, 1, 7, 2, 0};
    static const double knots[] = {2, 2, 2, 2, 3, 3, 5, 5, 5, 5};
    projcurve_curve *cubic = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 3, 6, ctrl, NULL, knots, &cubic));
    /* the quarter circle of radius 2: weights 1, 1/sqrt(2), 1 */
    const double arc[] = {2, 0, 0, 2, 2, 0, 0, 2, 0};
    const double w[] = {1, sqrt(0.5), 1};
    static const double arc_knots[] = {0, 0, 0, 1, 1, 1};
    projcurve_curve *quarter = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 2, 3, arc, w, arc_knots, &quarter));
    if (cubic != NULL)
        check_reversed(cubic, 8.0, "cubic");
    if (quarter != NULL)
        check_reversed(quarter, 2.0, "quarter circle");
    projcurve_curve_destroy(cubic);
    projcurve_curve_destroy(quarter);
    return pc_test_finish("test_io_iges_reversed");
}
