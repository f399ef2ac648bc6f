/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The stages every surface projection runs after tracing, in order: the
 * hits kept (hits/), tolerance control and composition (refine/) when
 * asked, the verification pass (verify/), the compact forms (fit/) and the
 * branches joined across seams (seam/). The directional, conical and
 * orthogonal drivers differ only in their equations, seeds and what they do
 * to the traced branches first.
 */
#ifndef PC_STAGES_AFTER_TRACE_H
#define PC_STAGES_AFTER_TRACE_H

#include "common/params.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "trace/projector.h"
#include "trace/result.h"

/* Runs the stages on r, traced with status `traced`. A partial result
 * (LIMIT_REACHED, CANCELLED) goes through them like a whole one, except
 * that it is composed only when cut by a limit other than the budget's
 * (MAX_POINTS: the budget is not spent); only verified branches remain.
 * Returns the call's status: `traced`, or the first failure of a stage. */
projcurve_status pc_stages_after_trace(projcurve_context *ctx, const pc_projector *proj,
                                       const projcurve_surface *surface,
                                       const projcurve_curve *curve, const pc_params *p,
                                       projcurve_result *r, projcurve_status traced);

#endif /* PC_STAGES_AFTER_TRACE_H */
