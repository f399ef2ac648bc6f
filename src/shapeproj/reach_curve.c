/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * pc_reach_curve: the curve over the hull of a face's t ranges
 * (shapeproj/reach_curve.h).
 */
#include "shapeproj/reach_curve.h"

#include <stdlib.h>

#include "common/error.h"
#include "faceproj/piece_cut.h"
#include "geom/curve.h"

/* The NURBS curve as a Cartesian B-spline (malloc'd poles and weights). */
static projcurve_status as_bspline(projcurve_context *ctx, const pc_nurbs_curve *n,
                                   pc_bspline *out)
{
    out->degree = n->degree;
    out->dim = 3;
    out->n_poles = n->n_ctrl;
    out->knots = n->knots; /* borrowed */
    out->poles = malloc(3 * n->n_ctrl * sizeof *out->poles);
    out->weights = n->rational ? malloc(n->n_ctrl * sizeof *out->weights) : NULL;
    if (out->poles == NULL || (n->rational && out->weights == NULL)) {
        free(out->poles);
        free(out->weights);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory restricting the curve");
    }
    for (size_t i = 0; i < n->n_ctrl; ++i) {
        const double *h = n->cw + 4 * i;
        for (int k = 0; k < 3; ++k)
            out->poles[3 * i + k] = h[k] / h[3];
        if (out->weights)
            out->weights[i] = h[3];
    }
    return PROJCURVE_OK;
}

projcurve_status pc_reach_curve(projcurve_context *ctx, const projcurve_curve *curve,
                                const pc_t_ranges *ranges, projcurve_curve **out)
{
    *out = NULL;
    if (curve->kind != PC_CURVE_NURBS || ranges->count == 0)
        return PROJCURVE_OK;
    const double a = ranges->items[0].a, b = ranges->items[ranges->count - 1].b;
    const double span = curve->t1 - curve->t0;
    if (!(b - a <= PC_REACH_CURVE_MAX_SHARE * span) || !(a < b))
        return PROJCURVE_OK;
    pc_bspline whole, part;
    projcurve_status st = as_bspline(ctx, &curve->nurbs, &whole);
    if (st != PROJCURVE_OK)
        return st;
    st = pc_bspline_restrict(ctx, &whole, a, b, &part);
    free(whole.poles);
    free(whole.weights);
    if (st == PROJCURVE_OK && part.n_poles > 0)
        st = pc_curve_create_nurbs(ctx, part.degree, part.n_poles, part.poles, part.weights,
                                   part.knots, out);
    pc_bspline_free(&part);
    return st;
}
