/* SPDX-License-Identifier: BSD-3-Clause */
#include "stages/after_trace.h"

#include "common/stage_clock.h"
#include "fit/fit.h"
#include "hits/hits.h"
#include "refine/refine.h"
#include "seam/seam.h"
#include "verify/verify.h"

projcurve_status pc_stages_after_trace(projcurve_context *ctx, const pc_projector *proj,
                                       const projcurve_surface *surface,
                                       const projcurve_curve *curve, const pc_params *p,
                                       projcurve_result *r, projcurve_status traced)
{
    projcurve_status st = traced;
    /* the hits kept (nearest, within MAX_DISTANCE), before composing */
    if (pc_status_keeps_result(st)) {
        const projcurve_status hs = pc_hits_select(ctx, proj, p, r);
        if (hs != PROJCURVE_OK)
            st = hs;
    }
    /* tolerance control and composition also on a result cut by
     * MAX_POINTS; not once the budget is spent (the traced polylines stay) */
    if (p->compose && (st == PROJCURVE_OK || st == PROJCURVE_ERR_LIMIT_REACHED) &&
        pc_budget_status(p->budget) == PROJCURVE_OK) {
        pc_budget_stage(p->budget, 0.5, PC_FIT_STAGE_FROM);
        const projcurve_status cs = pc_refine_and_compose(ctx, proj, p, r);
        if (cs != PROJCURVE_OK)
            st = cs;
    }
    /* only verified branches are returned, also from a partial result */
    double since = pc_stage_clock_now(p->stages);
    st = pc_verify_kept(ctx, proj, p, r, st);
    since = pc_stage_clock_lap(p->stages, PC_STAGE_VERIFICATION, since);
    st = pc_fit_stage(ctx, proj, p, r, st);
    pc_stage_clock_lap(p->stages, PC_STAGE_FITTING, since);
    return pc_seam_stage(ctx, surface, curve, p, r, st);
}
