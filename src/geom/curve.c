/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The engine's curve: creation and release of both kinds, the evaluator
 * of both, and the test for a curve that is one point.
 */
#include "geom/curve.h"

#include <math.h>
#include <stdlib.h>

#include "common/error.h"

/* Parameters sampled on a callback curve to tell a point curve. */
#define PC_POINT_CURVE_SAMPLES 33

projcurve_status pc_curve_create_nurbs(projcurve_context *ctx, int degree, size_t n_ctrl,
                                       const double *ctrl, const double *weights,
                                       const double *knots, projcurve_curve **out)
{
    projcurve_curve *c = calloc(1, sizeof *c);
    if (c == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for a curve");
    const projcurve_status st =
        pc_nurbs_curve_init(ctx, &c->nurbs, degree, n_ctrl, ctrl, weights, knots);
    if (st != PROJCURVE_OK) {
        free(c);
        return st;
    }
    c->kind = PC_CURVE_NURBS;
    c->t0 = c->nurbs.t0;
    c->t1 = c->nurbs.t1;
    *out = c;
    return PROJCURVE_OK;
}

projcurve_status pc_curve_create_callback(projcurve_context *ctx, projcurve_curve_fn fn,
                                          void *user, double t0, double t1,
                                          projcurve_curve **out)
{
    projcurve_curve *c = calloc(1, sizeof *c);
    if (c == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for a curve");
    c->kind = PC_CURVE_CALLBACK;
    c->t0 = t0;
    c->t1 = t1;
    c->fn = fn;
    c->user = user;
    *out = c;
    return PROJCURVE_OK;
}

void pc_curve_destroy(projcurve_curve *c)
{
    if (c == NULL)
        return;
    if (c->kind == PC_CURVE_NURBS)
        pc_nurbs_curve_free(&c->nurbs);
    free(c);
}

projcurve_status pc_curve_eval(const projcurve_curve *c, double t, int n_deriv, size_t *hint,
                               pc_vec3 *out)
{
    if (!(t >= c->t0))
        t = c->t0;
    if (t > c->t1)
        t = c->t1;
    if (c->kind == PC_CURVE_NURBS) {
        pc_nurbs_curve_eval(&c->nurbs, t, n_deriv > 3 ? 3 : n_deriv, hint, out);
        return PROJCURVE_OK;
    }
    double v[9];
    if (c->fn(c->user, t, v) != 0)
        return PROJCURVE_ERR_CALLBACK;
    const int n = n_deriv > 2 ? 2 : n_deriv;
    for (int k = 0; k <= n; ++k) {
        out[k] = vec3_load(v + 3 * k);
        if (!vec3_is_finite(out[k]))
            return PROJCURVE_ERR_CALLBACK;
    }
    return PROJCURVE_OK;
}

int pc_curve_is_point(const projcurve_curve *c, double tol)
{
    if (c->kind == PC_CURVE_NURBS) {
        const double *cw = c->nurbs.cw;
        const pc_vec3 first = vec3(cw[0] / cw[3], cw[1] / cw[3], cw[2] / cw[3]);
        for (size_t k = 1; k < c->nurbs.n_ctrl; ++k) {
            const double *q = cw + 4 * k;
            if (!(vec3_dist(vec3(q[0] / q[3], q[1] / q[3], q[2] / q[3]), first) <= tol))
                return 0;
        }
        return 1;
    }
    const double span = c->t1 - c->t0;
    pc_vec3 first = vec3(0.0, 0.0, 0.0);
    for (int k = 0; k < PC_POINT_CURVE_SAMPLES; ++k) {
        pc_vec3 p[2];
        const double t = c->t0 + span * (double)k / (double)(PC_POINT_CURVE_SAMPLES - 1);
        if (pc_curve_eval(c, t, 1, NULL, p) != PROJCURVE_OK)
            return 0; /* the projection reports the failing callback */
        if (k == 0)
            first = p[0];
        if (!(vec3_dist(p[0], first) <= tol && vec3_norm(p[1]) * fabs(span) <= tol))
            return 0;
    }
    return 1;
}

projcurve_status pc_curve_refuse_point(projcurve_context *ctx, const projcurve_curve *c,
                                       double tol)
{
    if (!pc_curve_is_point(c, tol))
        return PROJCURVE_OK;
    pc_vec3 p;
    pc_curve_eval(c, c->t0, 0, NULL, &p);
    return pc_fail(ctx, PROJCURVE_ERR_SINGULAR,
                   "the curve is the point (%.17g, %.17g, %.17g) to %g (the model's precision): "
                   "project it as a point (projcurve_surface_intersect_line, "
                   "projcurve_surface_foot_points)",
                   p.x, p.y, p.z, tol);
}
