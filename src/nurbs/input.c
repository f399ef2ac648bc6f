/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Validation of user control points and weights, and conversion to the
 * homogeneous form (w x, w y, w z, w) every evaluation path works on.
 */
#include <math.h>
#include <stdlib.h>

#include "common/error.h"
#include "nurbs/input.h"

projcurve_status pc_input_check_degree(projcurve_context *ctx, const char *name, int degree,
                                       size_t n_ctrl)
{
    if (degree < 1 || degree > PROJCURVE_MAX_DEGREE)
        return pc_fail(ctx, PROJCURVE_ERR_BAD_DEGREE, "%s %d is outside [1, %d]", name, degree,
                       PROJCURVE_MAX_DEGREE);
    if (n_ctrl < (size_t)degree + 1)
        return pc_fail(ctx, PROJCURVE_ERR_BAD_COUNT,
                       "%zu control points are fewer than %s + 1 = %d", n_ctrl, name,
                       degree + 1);
    return PROJCURVE_OK;
}

projcurve_status pc_input_homogeneous(projcurve_context *ctx, size_t n_points,
                                      const double *ctrl, const double *weights, double **cw_out,
                                      int *rational)
{
    for (size_t i = 0; i < n_points; ++i)
        for (int c = 0; c < 3; ++c)
            if (!isfinite(ctrl[3 * i + (size_t)c]))
                return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE,
                               "control point %zu has a non-finite coordinate %c", i, "xyz"[c]);
    *rational = 0;
    if (weights != NULL) {
        for (size_t i = 0; i < n_points; ++i) {
            if (!isfinite(weights[i]) || !(weights[i] > 0.0))
                return pc_fail(ctx, PROJCURVE_ERR_BAD_WEIGHT,
                               "weight %zu is %.17g (weights must be finite and > 0)", i,
                               weights[i]);
            if (weights[i] != 1.0)
                *rational = 1;
        }
    }
    double *cw = malloc(n_points * 4 * sizeof(double));
    if (cw == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for %zu control points",
                       n_points);
    for (size_t i = 0; i < n_points; ++i) {
        const double w = weights != NULL ? weights[i] : 1.0;
        for (size_t c = 0; c < 3; ++c) {
            cw[4 * i + c] = w * ctrl[3 * i + c];
            if (!isfinite(cw[4 * i + c])) {
                free(cw);
                return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE,
                               "control point %zu times its weight overflows", i);
            }
        }
        cw[4 * i + 3] = w;
    }
    *cw_out = cw;
    return PROJCURVE_OK;
}

projcurve_status pc_input_check_sizes(projcurve_context *ctx, int degree_u, size_t n_u,
                                      int degree_v, size_t n_v)
{
    /* Every array the library derives holds at most (n + degree + 1) knots
     * and 4 * n_u * n_v doubles (plus insertions of at most 2 * degree per
     * direction): check those products once, here. */
    const size_t pad_u = 2 * (size_t)degree_u + 2, pad_v = 2 * (size_t)degree_v + 2;
    if (n_u > SIZE_MAX - pad_u || n_v > SIZE_MAX - pad_v)
        return pc_fail(ctx, PROJCURVE_ERR_OVERFLOW, "control point count overflows");
    const size_t net = pc_size_mul(n_u + pad_u, n_v + pad_v);
    if (net == 0 || pc_size_mul(net, 4 * sizeof(double)) == 0 ||
        pc_size_mul(n_u + pad_u, sizeof(double)) == 0 ||
        pc_size_mul(n_v + pad_v, sizeof(double)) == 0)
        return pc_fail(ctx, PROJCURVE_ERR_OVERFLOW,
                       "a control net of %zu x %zu points overflows the address space", n_u,
                       n_v);
    /* The caller's size limit, once the sizes are known to be representable. */
    const size_t limit = pc_context_max_control_points(ctx);
    if (n_u * n_v > limit)
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE,
                       "%zu x %zu control points exceed the limit CONTROL_POINTS = %zu "
                       "(see projcurve_context_set_limit)",
                       n_u, n_v, limit);
    return PROJCURVE_OK;
}

projcurve_status pc_input_check_domain(projcurve_context *ctx, const char *name, double t0,
                                       double t1)
{
    const double end = fmax(fabs(t0), fabs(t1)), width = t1 - t0;
    if (!(end <= PC_INPUT_MAX_PARAM))
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE,
                       "%s [%.17g, %.17g] exceeds the parameter limit %g", name, t0, t1,
                       PC_INPUT_MAX_PARAM);
    if (!(width >= PC_INPUT_MIN_WIDTH) || !(width >= PC_INPUT_MIN_REL_WIDTH * end))
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE,
                       "%s [%.17g, %.17g] is narrower than the limit max(%g, 2^-32 * %g)", name,
                       t0, t1, PC_INPUT_MIN_WIDTH, end);
    return PROJCURVE_OK;
}

projcurve_status pc_input_check_extent(projcurve_context *ctx, size_t n_points,
                                       const double *ctrl)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < n_points; ++i)
        for (size_t c = 0; c < 3; ++c) {
            const double x = ctrl[3 * i + c];
            if (!(fabs(x) <= PC_INPUT_MAX_COORD))
                return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE,
                               "control point %zu: coordinate %c = %.17g exceeds the limit %g", i,
                               "xyz"[c], x, PC_INPUT_MAX_COORD);
            lo[c] = fmin(lo[c], x);
            hi[c] = fmax(hi[c], x);
        }
    const double extent = fmax(hi[0] - lo[0], fmax(hi[1] - lo[1], hi[2] - lo[2]));
    if (extent > 0.0 && extent < PC_INPUT_MIN_EXTENT)
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE,
                       "control points span %.17g, below the limit %g (scale the model up)",
                       extent, PC_INPUT_MIN_EXTENT);
    return PROJCURVE_OK;
}
