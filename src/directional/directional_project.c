/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * pc_directional_project: the directional equations and the line seed
 * finder handed to the tracing engine, then the stages after tracing
 * (stages/after_trace.h).
 */
#include "directional/directional_project.h"

#include <stdlib.h>

#include "common/error.h"
#include "directional/directional.h"
#include "directional/line_seeds.h"
#include "stages/after_trace.h"
#include "trace/result.h"
#include "trace/trace.h"

projcurve_status pc_directional_project(projcurve_context *ctx, const projcurve_surface *surface,
                                        const projcurve_curve *curve, pc_vec3 dir,
                                        const pc_params *p, projcurve_result **out)
{
    projcurve_status st =
        pc_curve_refuse_point(ctx, curve, pc_params_precision(p) * surface->size);
    if (st != PROJCURVE_OK)
        return st;
    pc_budget *const budget = p->budget;
    pc_budget_stage(budget, 0.0, p->compose ? 0.5 : 1.0);
    pc_projector proj;
    pc_directional_data data;
    pc_directional_cache cache;
    pc_directional_init(&proj, &data, &cache, surface, curve, dir, p->newton_tol,
                        (int)p->newton_max_iter);
    /* the bounds of the spans visited, kept for the whole call (without
     * the memory, one span's only: slower, same result) */
    const size_t slots = pc_span_bound_table_slots(&surface->nurbs);
    pc_span_bound_entry *bound_table = slots > 1 ? calloc(slots, sizeof *bound_table) : NULL;
    pc_directional_use_bound_table(&cache, bound_table, slots);
    pc_line_finder finder;
    pc_line_finder_init(&finder, &proj, dir);
    projcurve_result *r = NULL;
    st = pc_result_create(ctx, 3, &r);
    if (st == PROJCURVE_OK && p->jump_detection)
        st = pc_line_finder_bound_curve(ctx, &finder);
    if (st == PROJCURVE_OK) {
        /* the arc-length step is needed for stepping and for the jump
         * sweep; constant parameter steps without jumps do without it */
        const int need_length = p->param_step == 0.0 || p->jump_detection;
        const pc_trace_config config = {
            need_length ? pc_directional_length_estimate(&finder) : 0.0, proj.model_size, 1,
            dir};
        r->stats.tol_distance = p->tol_distance;
        st = pc_trace_branches(ctx, &proj, p, &finder.base, &config, r);
    }
    st = pc_stages_after_trace(ctx, &proj, surface, curve, p, r, st);
    if (cache.callback_failed && pc_status_keeps_result(st))
        st = pc_fail(ctx, PROJCURVE_ERR_CALLBACK, "the curve callback failed during tracing");
    if (finder.no_memory && (st == PROJCURVE_OK || st == PROJCURVE_ERR_LIMIT_REACHED))
        st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for the control-polygon hits");
    pc_line_finder_free(&finder);
    free(bound_table);
    return pc_result_hand_out(st, budget, r, out);
}
