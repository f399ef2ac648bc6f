/* SPDX-License-Identifier: BSD-3-Clause */
#include "fit/joined.h"

#include <stdlib.h>

#include "common/error.h"

/* Piece p's pcurve as cubic Bezier points in increasing t: a straight
 * segment raised to degree 3 has its inner points at thirds. */
static void cubic_of(const pc_piece *p, double out[8])
{
    double c[8];
    if (p->uv_degree == 3) {
        for (int i = 0; i < 8; ++i)
            c[i] = p->uv_ctrl[i];
    } else {
        for (int i = 0; i < 4; ++i)
            for (int k = 0; k < 2; ++k)
                c[2 * i + k] = p->uv_ctrl[k] + (p->uv_ctrl[2 + k] - p->uv_ctrl[k]) * i / 3.0;
    }
    const int reversed = p->t1 < p->t0;
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 2; ++k)
            out[2 * i + k] = c[2 * (reversed ? 3 - i : i) + k];
}

projcurve_status pc_fit_joined_pcurve(projcurve_context *ctx, const pc_fit_branch *fb,
                                      pc_fit_curve *out)
{
    const size_t np = fb->b->n_pieces, n = 3 * np + 1;
    out->spline.degree = 3;
    out->spline.dim = 2;
    out->spline.n_poles = n;
    out->error = 0.0;
    out->spline.weights = NULL;
    out->spline.knots = malloc((n + 4) * sizeof *out->spline.knots);
    out->spline.poles = malloc(2 * n * sizeof *out->spline.poles);
    if (out->spline.knots == NULL || out->spline.poles == NULL) {
        pc_fit_curve_free(out);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory joining a pcurve");
    }
    for (size_t k = 0; k < np; ++k) {
        const pc_piece *p = pc_fit_piece(fb, k);
        double c[8], lo, hi;
        cubic_of(p, c);
        pc_fit_piece_range(p, &lo, &hi);
        for (size_t i = k == 0 ? 0 : 1; i < 4; ++i)
            for (size_t d = 0; d < 2; ++d)
                out->spline.poles[2 * (3 * k + i) + d] = c[2 * i + d];
        for (size_t i = 0; i < 3; ++i)
            out->spline.knots[1 + 3 * k + i] = lo;
        if (k == 0)
            out->spline.knots[0] = lo;
        if (k + 1 == np)
            for (size_t i = 0; i < 4; ++i)
                out->spline.knots[n + i] = hi;
    }
    return PROJCURVE_OK;
}
