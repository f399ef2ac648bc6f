/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * pc_conical_project: the conical equations and the ray seed finder handed
 * to the tracing engine, then the stages after tracing
 * (stages/after_trace.h) -- pc_directional_project with other equations.
 */
#include "conical/conical_project.h"

#include "common/error.h"
#include "conical/conical.h"
#include "conical/conical_seeds.h"
#include "point/point.h"
#include "stages/after_trace.h"
#include "trace/result.h"
#include "trace/trace.h"

projcurve_status pc_conical_refuse_eye_on_curve(projcurve_context *ctx,
                                                const projcurve_curve *curve, pc_vec3 eye,
                                                double tol)
{
    double t = 0.0, dist = 0.0;
    pc_vec3 q;
    const projcurve_status st = pc_curve_closest(ctx, curve, eye, &t, &q, &dist);
    if (st != PROJCURVE_OK)
        return st;
    if (dist <= tol)
        return pc_fail(ctx, PROJCURVE_ERR_SINGULAR,
                       "the curve passes through the eye (%.17g, %.17g, %.17g) at t = %.17g "
                       "(distance %g, the model's precision is %g): the ray of that point has "
                       "no direction",
                       eye.x, eye.y, eye.z, t, dist, tol);
    return PROJCURVE_OK;
}

projcurve_status pc_conical_project(projcurve_context *ctx, const projcurve_surface *surface,
                                    const projcurve_curve *curve, pc_vec3 eye,
                                    const pc_params *p, projcurve_result **out)
{
    const double precision = pc_params_precision(p) * surface->size;
    projcurve_status st = pc_curve_refuse_point(ctx, curve, precision);
    if (st == PROJCURVE_OK)
        st = pc_conical_refuse_eye_on_curve(ctx, curve, eye, precision);
    if (st != PROJCURVE_OK)
        return st;
    pc_budget *const budget = p->budget;
    pc_budget_stage(budget, 0.0, p->compose ? 0.5 : 1.0);
    pc_projector proj;
    pc_conical_data data;
    pc_conical_cache cache;
    pc_conical_init(&proj, &data, &cache, surface, curve, eye, p->newton_tol,
                    (int)p->newton_max_iter);
    pc_cone_finder finder;
    pc_cone_finder_init(&finder, &proj, eye);
    projcurve_result *r = NULL;
    st = pc_result_create(ctx, 3, &r);
    if (st == PROJCURVE_OK && p->jump_detection)
        st = pc_cone_finder_bound_curve(ctx, &finder);
    if (st == PROJCURVE_OK) {
        const int need_length = p->param_step == 0.0 || p->jump_detection;
        /* ray 1: the tracer's lambda takes each point's own ray from
         * proj.ray_dir, the config's dir is not used */
        const pc_trace_config config = {
            need_length ? pc_conical_length_estimate(&finder) : 0.0, proj.model_size, 1,
            vec3(0.0, 0.0, 0.0)};
        r->stats.tol_distance = p->tol_distance;
        st = pc_trace_branches(ctx, &proj, p, &finder.base, &config, r);
    }
    /* the hits kept are the nearest along each ray from the eye */
    st = pc_stages_after_trace(ctx, &proj, surface, curve, p, r, st);
    if (cache.callback_failed && pc_status_keeps_result(st))
        st = pc_fail(ctx, PROJCURVE_ERR_CALLBACK, "the curve callback failed during tracing");
    if (finder.line.no_memory && (st == PROJCURVE_OK || st == PROJCURVE_ERR_LIMIT_REACHED))
        st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for the control-polygon hits");
    pc_cone_finder_free(&finder);
    return pc_result_hand_out(st, budget, r, out);
}
