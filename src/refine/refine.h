/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Tolerance control ([SY13] s2 steps 3-5, s4) of traced branches, then
 * composition onto the surface. Independent of the kind of projection: the
 * exact projection curve is reached point by point through the projector.
 */
#ifndef PC_REFINE_H
#define PC_REFINE_H

#include "common/params.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "trace/projector.h"
#include "trace/result.h"

/* The smallest eps_T (degrees) a composing projection accepts. At 1e-3
 * degrees straight pieces already number ~57,000 per radian the curve
 * turns; below, their end tangents would have to be known better than the
 * refinement knows the exact ones — q' from the projector to ~1e-9, and at
 * knot lines a one-sided difference over 1e-6 of the branch, ~1e-6 of its
 * turning — and cos(eps_T) rounds to 1 near 1e-6 degrees. Below this,
 * the march met the angle nowhere and left gaps (eps_T = 1e-6: 0.1 % of
 * the projection kept, status OK). Refused by the projection with
 * OUT_OF_RANGE by the entry points (src/api/project.c). */
#define PC_REFINE_MIN_ANGLE_DEG 1e-3

/* For every branch of r (points (t, u, v)): inserts vertices until each
 * segment's image on S is within eps_D (Hausdorff, 3D) of the exact
 * projection and every joint is within eps_T, splits segments at the knot
 * lines of S, and composes each segment with its Bezier patch (compose/).
 * eps_D and eps_T come from opts (automatic eps_D = 1e-4 model size).
 * opts->budget (may be NULL) is polled once per output vertex.
 * Statuses: OK, LIMIT_REACHED (opts->max_pieces, or the budget's time or
 * work limit; the pieces made so far stay), CANCELLED (the budget's
 * progress callback; the same), NO_MEMORY. */
projcurve_status pc_refine_and_compose(projcurve_context *ctx, const pc_projector *proj,
                                       const pc_params *opts,
                                       projcurve_result *r);

#endif /* PC_REFINE_H */
