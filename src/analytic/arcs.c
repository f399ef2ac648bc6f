/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Lines, circles and ellipses as exact NURBS curves. Every circular arc of
 * the library is built here: an ellipse is the affine image of the unit
 * circle's arc, and affine maps keep rational parametrisations, so the
 * ellipse's parameter (STEP's t, not the polar angle) maps to the NURBS
 * parameter as the circle's angle does (angle_map.c).
 */
#include <math.h>
#include <string.h>

#include "analytic/analytic.h"
#include "common/error.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* A sweep may exceed one turn by this much (rounding of a0 + 2 pi). */
#define PC_ARC_TURN_SLACK 1e-12

static projcurve_status no_memory(projcurve_context *ctx)
{
    return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory building an analytic curve");
}

static int finite3(const double *p)
{
    return isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]);
}

projcurve_status pc_ellipse_arc(projcurve_context *ctx, pc_arena *arena, const double centre[3],
                                const double x[3], const double y[3], double a, double b,
                                double t0, double t1, pc_rational_curve *out)
{
    if (!finite3(centre) || !finite3(x) || !finite3(y) || !isfinite(a) || !isfinite(b) ||
        !isfinite(t0) || !isfinite(t1))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "an arc with a NaN or infinite value");
    const double sweep = t1 - t0;
    if (!(a > 0.0) || !(b > 0.0) || !(sweep > 0.0) || !(sweep <= 2.0 * M_PI + PC_ARC_TURN_SLACK))
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                       "arc of semi-axes %g, %g over [%g, %g] rad cannot be converted", a, b, t0,
                       t1);
    const pc_angle_map map = pc_angle_map_make(t0, t1);
    const size_t n_seg = map.n_seg, n_ctrl = 2 * n_seg + 1;
    double *ctrl = pc_arena_calloc(arena, 3 * n_ctrl, sizeof(double));
    double *w = pc_arena_calloc(arena, n_ctrl, sizeof(double));
    double *knots = pc_arena_calloc(arena, n_ctrl + 3, sizeof(double));
    if (ctrl == NULL || w == NULL || knots == NULL)
        return no_memory(ctx);
    const double step = sweep / (double)n_seg, w_mid = cos(step / 2.0);
    for (size_t s = 0; s <= n_seg; ++s) {
        const double t = (s == n_seg) ? t1 : t0 + step * (double)s;
        for (int k = 0; k < 3; ++k)
            ctrl[6 * s + (size_t)k] = centre[k] + a * cos(t) * x[k] + b * sin(t) * y[k];
        w[2 * s] = 1.0;
        if (s == n_seg)
            break;
        /* The middle point of a segment lies at 1 / cos(h) on its bisector. */
        const double tm = t + step / 2.0;
        for (int k = 0; k < 3; ++k)
            ctrl[6 * s + 3 + (size_t)k] =
                centre[k] + (a * cos(tm) * x[k] + b * sin(tm) * y[k]) / w_mid;
        w[2 * s + 1] = w_mid;
    }
    knots[0] = knots[1] = knots[2] = t0;
    for (size_t s = 1; s < n_seg; ++s)
        knots[2 * s + 1] = knots[2 * s + 2] = t0 + step * (double)s;
    knots[n_ctrl] = knots[n_ctrl + 1] = knots[n_ctrl + 2] = t1;
    *out = (pc_rational_curve){.degree = 2, .n_ctrl = n_ctrl, .ctrl = ctrl, .weights = w,
                               .knots = knots};
    return PROJCURVE_OK;
}

projcurve_status pc_line_segment(projcurve_context *ctx, pc_arena *arena, const double o[3],
                                 const double d[3], double t0, double t1,
                                 pc_rational_curve *out)
{
    if (!finite3(o) || !finite3(d) || !isfinite(t0) || !isfinite(t1))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "a line with a NaN or infinite value");
    if (!(t1 > t0))
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                       "a line segment over the empty range [%g, %g]", t0, t1);
    if (d[0] == 0.0 && d[1] == 0.0 && d[2] == 0.0)
        return pc_fail(ctx, PROJCURVE_ERR_ZERO_DIRECTION, "a line of direction zero");
    double *ctrl = pc_arena_calloc(arena, 6, sizeof(double));
    double *knots = pc_arena_calloc(arena, 4, sizeof(double));
    if (ctrl == NULL || knots == NULL)
        return no_memory(ctx);
    for (int k = 0; k < 3; ++k) {
        ctrl[k] = o[k] + t0 * d[k];
        ctrl[3 + k] = o[k] + t1 * d[k];
    }
    knots[0] = knots[1] = t0;
    knots[2] = knots[3] = t1;
    *out = (pc_rational_curve){.degree = 1, .n_ctrl = 2, .ctrl = ctrl, .weights = NULL,
                               .knots = knots};
    return PROJCURVE_OK;
}

void pc_rational_curve_eval(const pc_rational_curve *c, double t, double out[3])
{
    const size_t p = (size_t)c->degree;
    const double lo = c->knots[p], hi = c->knots[c->n_ctrl];
    t = t < lo ? lo : (t > hi ? hi : t);
    size_t k = p;
    while (k + 1 < c->n_ctrl && c->knots[k + 1] <= t)
        ++k;
    double d[PROJCURVE_MAX_DEGREE + 1][4];
    for (size_t j = 0; j <= p; ++j) {
        const size_t i = k - p + j;
        const double w = c->weights ? c->weights[i] : 1.0;
        for (int q = 0; q < 3; ++q)
            d[j][q] = w * c->ctrl[3 * i + (size_t)q];
        d[j][3] = w;
    }
    /* de Boor's triangle on the homogeneous points of the span. */
    for (size_t r = 1; r <= p; ++r)
        for (size_t j = p; j >= r; --j) {
            const size_t i = k - p + j;
            const double den = c->knots[i + p + 1 - r] - c->knots[i];
            const double alpha = den > 0.0 ? (t - c->knots[i]) / den : 0.0;
            for (int q = 0; q < 4; ++q)
                d[j][q] = (1.0 - alpha) * d[j - 1][q] + alpha * d[j][q];
        }
    for (int q = 0; q < 3; ++q)
        out[q] = d[p][q] / d[p][3];
}
