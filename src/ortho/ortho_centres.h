/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Centres of curvature inside traced branches of the parametric orthogonal
 * projection. The tracing engine ends a branch where det K changes sign
 * ([PW96] s6); an even change of the Morse index (an umbilic, e.g. P
 * crossing the centre of a sphere: det K touches zero without changing
 * sign) can be stepped over. This pass finds such crossings between
 * consecutive vertices, locates them by bisection in t, and splits the
 * branch there: the first part ends with PROJCURVE_END_CURVATURE_CENTRE,
 * the second starts with PROJCURVE_START_SILHOUETTE (born at a centre of
 * curvature, see projcurve.h).
 */
#ifndef PC_ORTHO_CENTRES_H
#define PC_ORTHO_CENTRES_H

#include "trace/projector.h"
#include "trace/result.h"

/* Splits every branch of r (points (t, u, v)) at the centres of curvature
 * it crosses, and where consecutive vertices are not one continuous piece
 * (farther apart on S than ten times the larger end speed times their
 * parameter gap: the tracer landed on another foot point, typically where
 * two foot points annihilate at a fold); such a split ends the first part
 * at a centre of curvature (|det| < 1e-2 there) or as FAILED, and starts the
 * second with START_SILHOUETTE (|det| < 1e-2) or START_JUMP. Then names
 * the ends on creases (ortho_creases.h).
 * Statuses: OK, NO_MEMORY, CALLBACK. */
projcurve_status pc_ortho_split_at_centres(projcurve_context *ctx, const pc_projector *proj,
                                           projcurve_result *r);

#endif /* PC_ORTHO_CENTRES_H */
