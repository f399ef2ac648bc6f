/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Public curve functions: creation (NURBS or callback), domain, evaluation,
 * NURBS data access (the curve itself and its evaluator are geom/curve.h).
 */
#include <string.h>

#include "common/error.h"
#include "geom/curve.h"
#include "nurbs/input.h"

projcurve_status projcurve_curve_create_nurbs(projcurve_context *ctx, int degree, size_t n_ctrl,
                                              const double *ctrl, const double *weights,
                                              const double *knots, projcurve_curve **out)
{
    PC_REQUIRE(ctx, out, "out");
    PC_REQUIRE(ctx, ctrl, "ctrl");
    PC_REQUIRE(ctx, knots, "knots");
    return pc_curve_create_nurbs(ctx, degree, n_ctrl, ctrl, weights, knots, out);
}

projcurve_status projcurve_curve_create_callback(projcurve_context *ctx, projcurve_curve_fn fn,
                                                 void *user, double t0, double t1,
                                                 projcurve_curve **out)
{
    PC_REQUIRE(ctx, out, "out");
    if (fn == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NULL_ARGUMENT, "fn is NULL");
    if (!isfinite(t0) || !isfinite(t1))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "curve domain [%g, %g] is not finite", t0,
                       t1);
    if (!(t0 < t1))
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                       "curve domain [%.17g, %.17g] is empty (need t0 < t1)", t0, t1);
    const projcurve_status st = pc_input_check_domain(ctx, "curve domain", t0, t1);
    if (st != PROJCURVE_OK)
        return st;
    return pc_curve_create_callback(ctx, fn, user, t0, t1, out);
}

void projcurve_curve_destroy(projcurve_curve *curve) { pc_curve_destroy(curve); }

projcurve_status projcurve_curve_domain(projcurve_context *ctx, const projcurve_curve *curve,
                                        double *t0, double *t1)
{
    PC_REQUIRE(ctx, curve, "curve");
    PC_REQUIRE(ctx, t0, "t0");
    PC_REQUIRE(ctx, t1, "t1");
    *t0 = curve->t0;
    *t1 = curve->t1;
    return PROJCURVE_OK;
}

projcurve_status projcurve_curve_eval(projcurve_context *ctx, const projcurve_curve *curve,
                                      double t, int n_deriv, double *out)
{
    PC_REQUIRE(ctx, curve, "curve");
    PC_REQUIRE(ctx, out, "out");
    const int max_deriv = curve->kind == PC_CURVE_NURBS ? 3 : 2;
    if (n_deriv < 0 || n_deriv > max_deriv)
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE,
                       "derivative order %d is outside [0, %d] for this curve", n_deriv,
                       max_deriv);
    if (!isfinite(t))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "curve parameter t is not finite");
    if (t < curve->t0 || t > curve->t1)
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_DOMAIN,
                       "t = %.17g is outside the curve domain [%.17g, %.17g]", t, curve->t0,
                       curve->t1);
    pc_vec3 r[4];
    if (pc_curve_eval(curve, t, n_deriv, NULL, r) != PROJCURVE_OK)
        return pc_fail(ctx, PROJCURVE_ERR_CALLBACK,
                       "curve callback failed or returned a non-finite value at t = %.17g", t);
    for (int k = 0; k <= n_deriv; ++k)
        vec3_store(r[k], out + 3 * k);
    return PROJCURVE_OK;
}

projcurve_status projcurve_curve_nurbs_info(projcurve_context *ctx, const projcurve_curve *curve,
                                            int *degree, size_t *n_ctrl, size_t *n_knots,
                                            int *rational)
{
    PC_REQUIRE(ctx, curve, "curve");
    if (curve->kind != PC_CURVE_NURBS)
        return pc_fail(ctx, PROJCURVE_ERR_WRONG_KIND, "the curve is a callback curve, not NURBS");
    const pc_nurbs_curve *c = &curve->nurbs;
    if (degree != NULL)
        *degree = c->degree;
    if (n_ctrl != NULL)
        *n_ctrl = c->n_ctrl;
    if (n_knots != NULL)
        *n_knots = c->n_ctrl + (size_t)c->degree + 1;
    if (rational != NULL)
        *rational = c->rational;
    return PROJCURVE_OK;
}

projcurve_status projcurve_curve_nurbs_data(projcurve_context *ctx, const projcurve_curve *curve,
                                            double *ctrl, double *weights, double *knots)
{
    PC_REQUIRE(ctx, curve, "curve");
    if (curve->kind != PC_CURVE_NURBS)
        return pc_fail(ctx, PROJCURVE_ERR_WRONG_KIND, "the curve is a callback curve, not NURBS");
    const pc_nurbs_curve *c = &curve->nurbs;
    pc_nurbs_points_from_homogeneous(c->cw, c->n_ctrl, ctrl, weights);
    if (knots != NULL)
        memcpy(knots, c->knots, (c->n_ctrl + (size_t)c->degree + 1) * sizeof(double));
    return PROJCURVE_OK;
}
