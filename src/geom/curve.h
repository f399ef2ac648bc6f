/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The engine's curve: a NURBS curve or a user callback over [t0, t1], and
 * the one evaluator every stage calls. projcurve_curve in projcurve.h is
 * this struct; only the library sees its layout.
 */
#ifndef PC_GEOM_CURVE_H
#define PC_GEOM_CURVE_H

#include <stddef.h>

#include "common/vec.h"
#include "nurbs/nurbs.h"
#include "projcurve.h"

typedef enum pc_curve_kind { PC_CURVE_NURBS = 0, PC_CURVE_CALLBACK = 1 } pc_curve_kind;

struct projcurve_curve {
    pc_curve_kind kind;
    double t0, t1;
    pc_nurbs_curve nurbs;      /* PC_CURVE_NURBS */
    projcurve_curve_fn fn;     /* PC_CURVE_CALLBACK */
    void *user;
};

/* A new NURBS curve (the arguments of projcurve_curve_create_nurbs).
 * Statuses: those of pc_nurbs_curve_init, NO_MEMORY; *out untouched on
 * failure. */
projcurve_status pc_curve_create_nurbs(projcurve_context *ctx, int degree, size_t n_ctrl,
                                       const double *ctrl, const double *weights,
                                       const double *knots, projcurve_curve **out);

/* A new callback curve over [t0, t1], already checked by the caller
 * (finite, t0 < t1). Statuses: OK, NO_MEMORY. */
projcurve_status pc_curve_create_callback(projcurve_context *ctx, projcurve_curve_fn fn,
                                          void *user, double t0, double t1,
                                          projcurve_curve **out);

/* Releases c; NULL is allowed. */
void pc_curve_destroy(projcurve_curve *c);

/* Point and derivatives up to order n_deriv (<= 2 for callbacks, <= 3 for
 * NURBS) of any curve, t clamped to the domain; out[0..n_deriv]. Returns OK,
 * or CALLBACK when a user callback fails or gives a non-finite value.
 * hint may be NULL. */
projcurve_status pc_curve_eval(const projcurve_curve *c, double t, int n_deriv, size_t *hint,
                               pc_vec3 *out);

/* A curve whose image is one point within tol (model units): every
 * control point of a NURBS curve within tol of the first (the curve lies in
 * their convex hull), or for a callback curve P and (t1 - t0) P' at 33
 * evenly spread parameters. The projections refuse such a curve
 * (pc_curve_refuse_point): its projection is that of a point, and the
 * tracer's arc-length steps are undefined on it. */
int pc_curve_is_point(const projcurve_curve *c, double tol);

/* SINGULAR with a message naming the point and the functions that project
 * it when c is a point to tol (the precision of the model); OK otherwise. */
projcurve_status pc_curve_refuse_point(projcurve_context *ctx, const projcurve_curve *c,
                                       double tol);

#endif /* PC_GEOM_CURVE_H */
