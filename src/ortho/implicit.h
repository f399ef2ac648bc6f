/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Orthogonal projection onto an implicit surface f(x) = 0 ([PW96] s5),
 * traced in 3-space.
 *
 * With g = grad f, H its Hessian, n = g / |g| and the signed distance
 * rho = (P - x).n (eq. (21)), a foot point x(t) moves by
 *     K x' = P' - (P'.n) n,   K = I - rho B,   B = -(I - n n^T) H / |g|
 * (eq. (25)-(32)). K maps n to n plus a tangent vector, so the normal part
 * of x' is zero and det K = det of K restricted to the tangent plane
 * = (1 + rho k1)(1 + rho k2) (k1, k2 the principal curvatures, sign as f's
 * gradient): it vanishes exactly when P is a centre of curvature.
 *
 * equations (implicit_equations.c): the callback wrapper, x' (ODE (32)),
 *   x'' (central difference of x' along the trajectory: the callback gives
 *   no third derivatives of f, see docs/orthogonal.md), and the corrector.
 * tracing (implicit_trace.c): one branch from the foot point of P(t0).
 * fitting (implicit_fit.c): cubic pieces within eps_D of the exact curve.
 */
#ifndef PC_ORTHO_IMPLICIT_H
#define PC_ORTHO_IMPLICIT_H

#include "common/params.h"
#include "common/vec.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "trace/result.h"

typedef struct pc_implicit {
    projcurve_implicit_fn fn;
    void *user;
    const projcurve_curve *curve;
    double model_size;
    double newton_tol;    /* absolute, model units */
    int newton_max_iter;
    double grad_floor;    /* |grad f| at or below this is a singular point */
} pc_implicit;

/* One evaluation of f. */
typedef struct pc_implicit_eval {
    double value;
    pc_vec3 grad;
    double hess[9];       /* row-major */
} pc_implicit_eval;

/* A traced foot point: t, x, x' (ODE (32)), det K (tangential, unitless)
 * and the Morse index (morse_index.h) from det and trace of K. */
typedef struct pc_implicit_point {
    double t;
    pc_vec3 x, xd;
    double det;
    int index;
} pc_implicit_point;

/* Calls f at x. Statuses: OK; CALLBACK (nonzero return, or a non-finite
 * value, gradient or Hessian); SINGULAR (|grad f| <= imp->grad_floor).
 * Messages are recorded in ctx. */
projcurve_status pc_implicit_call(projcurve_context *ctx, const pc_implicit *imp, pc_vec3 x,
                                  pc_implicit_eval *out);

/* x' at (t, x) (x need not lie on f = 0: the field is smooth nearby,
 * which RK4 stages and the x'' difference use); det_trace (may be NULL)
 * gets det and trace of K restricted to the tangent plane. *solved is 0
 * when K is singular (then *xd is zero). Statuses as pc_implicit_call. */
projcurve_status pc_implicit_velocity(projcurve_context *ctx, const pc_implicit *imp, double t,
                                      pc_vec3 x, pc_vec3 *xd, double det_trace[2],
                                      int *solved);

/* x'' at a foot point pt (with pt->xd filled): central difference of the
 * ODE field along (x', 1). *solved as above. */
projcurve_status pc_implicit_acceleration(projcurve_context *ctx, const pc_implicit *imp,
                                          const pc_implicit_point *pt, pc_vec3 *xdd,
                                          int *solved);

/* Corrector: from the guess *x, projects onto f = 0 along the gradient,
 * then Newton on the foot-point system x - P + lambda grad f = 0, f = 0
 * (the Lagrange conditions of eq. (3) for an implicit surface), so that the
 * result is a foot point of P(t) to newton_tol. *converged is 0 when the
 * iteration hit its bound or diverged (*x then holds the last iterate);
 * *iterations (may be NULL) counts Newton steps. Statuses as
 * pc_implicit_call. */
projcurve_status pc_implicit_correct(projcurve_context *ctx, const pc_implicit *imp, double t,
                                     pc_vec3 *x, int *converged, int *iterations);

/* Fills pt (x', det, index) for the foot point x of P(t). *solved as above. */
projcurve_status pc_implicit_point_at(projcurve_context *ctx, const pc_implicit *imp, double t,
                                      pc_vec3 x, pc_implicit_point *pt, int *solved);

/* Traces one branch from the foot point of P(t0) found from P(t0) itself
 * into r (points (t, x, y, z)), and sets imp->grad_floor relative to the
 * gradient at that seed (for the fit that follows). opts->budget (may be
 * NULL) is polled once per step. Statuses: OK, LIMIT_REACHED (max_points
 * or the budget), CANCELLED (the budget's callback), CALLBACK, SINGULAR,
 * NOT_CONVERGED (no foot point found for P(t0)), NO_MEMORY. */
projcurve_status pc_implicit_trace(projcurve_context *ctx, pc_implicit *imp,
                                   const pc_params *opts, projcurve_result *r);

/* Replaces the pieces of every branch of r by cubic Bezier pieces (C1
 * Hermite in t) within eps_D of the exact foot-point curve, inserting exact
 * vertices where needed; opts->budget (may be NULL) is polled once per
 * segment tried, and pieces stop at opts->max_pieces. Statuses: OK,
 * LIMIT_REACHED (max_points, max_pieces or the budget; the branch cut ends
 * with PROJCURVE_END_LIMIT), CANCELLED, CALLBACK, SINGULAR, NO_MEMORY. */
projcurve_status pc_implicit_fit(projcurve_context *ctx, const pc_implicit *imp, double eps_d,
                                 const pc_params *opts, projcurve_result *r);

#endif /* PC_ORTHO_IMPLICIT_H */
