/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The verification pass (issue 14): run on every projection result before it
 * is returned, independent of how the branches were made. A branch is
 * returned only where it is verified:
 *   (a) every vertex (t, u, v) of the branch satisfies the projection
 *       condition: the projector's residual is within the corrector's
 *       tolerance (verify_piece.c, pc_verify_vertex_tolerance);
 *   (b) every composed piece, sampled at interior parameters, lies within
 *       eps_D of the exact projection, whose points the corrector gives at
 *       the matching curve parameter;
 *   (c) consecutive pieces join within eps_D and every piece's pcurve lies
 *       in the surface domain.
 * A stretch that fails is cut off: the verified part before it ends with
 * PROJCURVE_END_FAILED, the verified part after it becomes a branch of its
 * own starting with PROJCURVE_START_FAILED. See docs/refine_compose.md.
 */
#ifndef PC_VERIFY_H
#define PC_VERIFY_H

#include "common/params.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "trace/projector.h"
#include "trace/result.h"

/* Verifies every branch of r, a (t, u, v) result made with proj and the
 * resolved parameters o (o->tol_distance is eps_D in model units; o->compose
 * says whether branches are to carry pieces). Cuts what fails (see above);
 * drops branches that are shorter than the model's precision (noise of the
 * seeding, not a curve) and, while composing, branches left without pieces
 * (counted in r->failures_dropped, as failures), except those a size limit
 * stopped (END_LIMIT). Each item checked (a piece or a segment) is a unit
 * of o->budget when it has not stopped on entry. Statuses: OK, NO_MEMORY,
 * LIMIT_REACHED and CANCELLED (the budget stopped the pass: the branches
 * verified so far stay, the one being checked keeps its verified runs
 * before the stop, the last ending with PROJCURVE_END_LIMIT, and the
 * branches not yet checked are dropped). */
projcurve_status pc_verify_result(projcurve_context *ctx, const pc_projector *proj,
                                  const pc_params *o, projcurve_result *r);

/* The verification a projection ends with: pc_verify_result on r when st,
 * the status so far, keeps a result (pc_status_keeps_result: a partial
 * result is verified too). Returns its status when it fails, else st. */
projcurve_status pc_verify_kept(projcurve_context *ctx, const pc_projector *proj,
                                const pc_params *o, projcurve_result *r, projcurve_status st);

#endif /* PC_VERIFY_H */
