/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The curve's own spline space: where the projection is an affine image of
 * the curve P (onto a plane, along a direction or orthogonally, and P on
 * an affinely parametrised plane for the pcurve), it lies in the space of
 * P's degree, knots and weights, so a least-squares fit there is exact to
 * rounding with P's pole count: a circle stays a 9-pole rational quadratic.
 * Tried first, kept when its dense check passes.
 */
#ifndef PC_FIT_OWN_SPACE_H
#define PC_FIT_OWN_SPACE_H

#include "fit/adaptive.h"

/* The fit of dimension dim (2: pcurve, 3: 3D curve) in P's space, when P
 * is a NURBS curve over exactly the branch's range with a degree of at
 * most max_degree: *ok 1 and *out filled when it is within `limit`
 * (target: what the samples must meet). Statuses: OK, NO_MEMORY. */
projcurve_status pc_fit_own_space(projcurve_context *ctx, pc_fit_branch *fb, int dim,
                                  int max_degree, double target, double limit,
                                  pc_fit_samples *data, pc_fit_curve *out, int *ok);

#endif /* PC_FIT_OWN_SPACE_H */
