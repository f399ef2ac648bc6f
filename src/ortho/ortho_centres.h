/*
 * Centres of curvature inside traced branches of the parametric orthogonal
 * projection. The tracing engine ends a branch where det K changes sign
 * (seed 003 s6); an even change of the Morse index (an umbilic, e.g. P
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
 * it crosses. Statuses: OK, NO_MEMORY, CALLBACK. */
projcurve_status pc_ortho_split_at_centres(projcurve_context *ctx, const pc_projector *proj,
                                           projcurve_result *r);

/* Moves the ends of branches that end (or start) at a centre of curvature
 * (engine code PROJCURVE_END/START_SILHOUETTE, or set by the split) as
 * close to the centre as the corrector allows: the engine stops where
 * |det| < 1e-6, which is ~1e-5 of the domain before a transversal crossing
 * and ~1e-3 before an umbilic one. Each such end gets one more vertex, at
 * most 1e-12 of the domain from where the Morse index changes (or from
 * where the corrector stops converging at a fold). Statuses: OK, NO_MEMORY,
 * CALLBACK. */
projcurve_status pc_ortho_extend_to_centres(projcurve_context *ctx, const pc_projector *proj,
                                            projcurve_result *r);

#endif /* PC_ORTHO_CENTRES_H */
