/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Which points of the projection are kept (PROJCURVE_OPT_HITS,
 * PROJCURVE_OPT_MAX_DISTANCE; docs/hits.md): at each curve parameter t
 * only the point nearest to P(t), and / or only the points within a
 * distance D of it. A stage on the traced branches, before tolerance
 * control and composition: the branches are cut exactly where another
 * becomes nearer or where their distance reaches D, and the parts dropped,
 * so that refine/, verify/ and fit/ see the kept ranges only.
 */
#ifndef PC_HITS_HITS_H
#define PC_HITS_HITS_H

#include "common/params.h"
#include "trace/projector.h"
#include "trace/result.h"

/* The cut points are located to this fraction of the model size in the
 * distance difference (or the distance minus D). */
#define PC_HITS_ROOT_TOL 1e-10

/* 1 when p asks for a selection (HITS nearest, or MAX_DISTANCE > 0). */
int pc_hits_active(const pc_params *p);

/* The distance |S(q(t)) - P(t)| of branch b (points (t, u, v), t
 * increasing, >= 2 points) at t within its range, from the exact point
 * there (the projector's corrector from the polyline's point; the polyline's
 * own point where it does not converge); (u, v) of that point into uv.
 * Returns 0 with *out set, or CALLBACK when the curve callback failed. */
projcurve_status pc_hits_distance(const pc_projector *proj, const pc_branch *b, double t,
                                  double uv[2], double *out);

/* Replaces the branches of r (a parametric result of traced polylines, no
 * pieces yet) by the parts kept under p: each part a new branch with the
 * exact points at its cuts, PROJCURVE_END_OCCLUDED / START_VISIBLE where
 * another branch becomes nearer / stops being nearer, END / START
 * MAX_DISTANCE where its distance reaches D; the original reasons at the
 * original ends. Order: by original branch, then by t. Each exact
 * distance is a unit of p->budget when it has not stopped on entry.
 * Statuses: OK, NO_MEMORY, CALLBACK (on these r is left valid: every
 * branch whole or not yet cut), LIMIT_REACHED and CANCELLED (the budget
 * stopped the selection: r holds the parts kept so far, the last ending
 * with PROJCURVE_END_LIMIT; the branches not yet selected are dropped). */
projcurve_status pc_hits_select(projcurve_context *ctx, const pc_projector *proj,
                                const pc_params *p, projcurve_result *r);

#endif /* PC_HITS_HITS_H */
