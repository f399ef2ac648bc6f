/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * NURBS curves: creation from user arrays (evaluation: curve_eval.c).
 */
#include <stdlib.h>
#include <string.h>

#include "common/error.h"
#include "nurbs/input.h"
#include "nurbs/nurbs.h"
#include "nurbs/span_poly.h"

projcurve_status pc_nurbs_curve_init(projcurve_context *ctx, pc_nurbs_curve *c, int degree,
                                     size_t n_ctrl, const double *ctrl, const double *weights,
                                     const double *knots)
{
    projcurve_status st = pc_input_check_degree(ctx, "degree", degree, n_ctrl);
    if (st == PROJCURVE_OK)
        st = pc_input_check_sizes(ctx, degree, n_ctrl, 0, 1);
    if (st == PROJCURVE_OK)
        st = pc_knots_validate(ctx, "knot vector", degree, n_ctrl, knots);
    if (st == PROJCURVE_OK)
        st = pc_input_check_domain(ctx, "curve domain", knots[degree], knots[n_ctrl]);
    pc_spline_batch b = {degree, n_ctrl, 4, 1, NULL, NULL};
    int rational = 0;
    if (st == PROJCURVE_OK)
        st = pc_input_homogeneous(ctx, n_ctrl, ctrl, weights, &b.pts, &rational);
    if (st != PROJCURVE_OK)
        return st;
    if ((st = pc_input_check_extent(ctx, n_ctrl, ctrl)) != PROJCURVE_OK) {
        free(b.pts);
        return st;
    }
    const size_t n_knots = n_ctrl + (size_t)degree + 1;
    b.knots = malloc(n_knots * sizeof(double));
    if (b.knots == NULL) {
        free(b.pts);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for %zu knots", n_knots);
    }
    memcpy(b.knots, knots, n_knots * sizeof(double));
    if (!pc_knots_are_clamped(b.knots, n_ctrl, degree)) {
        st = pc_spline_batch_clamp(ctx, &b);
        if (st != PROJCURVE_OK) {
            free(b.knots);
            free(b.pts);
            return st;
        }
    }
    c->degree = degree;
    c->n_ctrl = b.n_ctrl;
    c->knots = b.knots;
    c->cw = b.pts;
    c->rational = rational;
    c->t0 = b.knots[degree];
    c->t1 = b.knots[b.n_ctrl];
    /* Built when the degree allows: evaluation must not depend on memory. */
    int no_memory;
    c->poly = pc_curve_polys_build(c, &no_memory);
    if (no_memory) {
        pc_nurbs_curve_free(c);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for the span polynomials");
    }
    return PROJCURVE_OK;
}

void pc_nurbs_points_from_homogeneous(const double *cw, size_t n, double *ctrl,
                                      double *weights)
{
    for (size_t i = 0; i < n; ++i) {
        const double w = cw[4 * i + 3];
        if (ctrl != NULL)
            for (size_t k = 0; k < 3; ++k)
                ctrl[3 * i + k] = cw[4 * i + k] / w;
        if (weights != NULL)
            weights[i] = w;
    }
}

void pc_nurbs_curve_free(pc_nurbs_curve *c)
{
    if (c == NULL)
        return;
    free(c->knots);
    free(c->cw);
    free(c->poly);
    c->knots = NULL;
    c->cw = NULL;
    c->poly = NULL;
}
