/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * pc_ortho_project and pc_ortho_project_implicit ([PW96]): the orthogonal
 * equations and foot-point seeds handed to the tracing engine, the
 * splitting at centres of curvature, minima and duplicates, then the
 * stages after tracing (stages/after_trace.h); and the implicit-surface
 * variant.
 */
#include "ortho/ortho_project.h"

#include "common/error.h"
#include "ortho/implicit.h"
#include "ortho/ortho_centres.h"
#include "ortho/ortho_duplicates.h"
#include "ortho/ortho_minima.h"
#include "ortho/ortho_projector.h"
#include "ortho/ortho_seeds.h"
#include "stages/after_trace.h"
#include "trace/result.h"
#include "trace/trace.h"

/* A det K = 0 end (or start) is what the engine calls a fold; for the
 * orthogonal projection that is a centre of curvature (corollary 2.1). */
static void name_singular_ends(projcurve_result *r)
{
    for (size_t i = 0; i < r->n_branches; ++i)
        if (r->branches[i].end == PROJCURVE_END_SILHOUETTE)
            r->branches[i].end = PROJCURVE_END_CURVATURE_CENTRE;
}

projcurve_status pc_ortho_project(projcurve_context *ctx, const projcurve_surface *surface,
                                  const projcurve_curve *curve, const pc_params *p,
                                  projcurve_result **out)
{
    const projcurve_status st =
        pc_curve_refuse_point(ctx, curve, pc_params_precision(p) * surface->size);
    if (st != PROJCURVE_OK)
        return st;
    pc_budget *const budget = p->budget;
    pc_budget_stage(budget, 0.0, p->compose ? 0.5 : 1.0);

    pc_ortho_cache cache;
    pc_projector proj;
    pc_ortho_projector_init(&proj, &cache, surface, curve, p->newton_tol, (int)p->newton_max_iter);
    pc_ortho_finder_state finder_state;
    pc_seed_finder finder;
    const int minima_only = p->foot_points == PROJCURVE_FOOT_POINTS_MINIMA;
    pc_ortho_finder_init(&finder, &finder_state, surface, curve, minima_only ? &proj : NULL);
    finder_state.budget = p->budget; /* a foot-point search can take long */
    const pc_trace_config config = {0.0, surface->size, 0, {0.0, 0.0, 0.0}};

    projcurve_result *r = NULL;
    projcurve_status status = pc_result_create(ctx, 3, &r);
    if (status == PROJCURVE_OK)
        status = pc_trace_branches(ctx, &proj, p, &finder, &config, r);
    /* A partial result (LIMIT_REACHED, CANCELLED) is finished like a whole
     * one, except that a spent budget leaves it uncomposed. */
    const projcurve_status traced = status;
    if (pc_status_keeps_result(status))
        status = PROJCURVE_OK;
    if (status == PROJCURVE_OK)
        status = pc_ortho_split_at_centres(ctx, &proj, r);
    if (status == PROJCURVE_OK) {
        if (minima_only)
            pc_ortho_keep_minima(&proj, r);
        pc_ortho_drop_duplicates(&proj, r);
        name_singular_ends(r);
        r->stats.tol_distance = p->tol_distance;
        /* the hits kept are the nearest foot points */
        status = pc_stages_after_trace(ctx, &proj, surface, curve, p, r, traced);
    }
    /* The projector's functions cannot report a failed curve callback
     * themselves; it is an error wherever it happened. */
    if (cache.callback_failed && pc_status_keeps_result(status))
        status = pc_fail(ctx, PROJCURVE_ERR_CALLBACK, "a curve callback failed while tracing");
    pc_ortho_finder_free(&finder_state);
    return pc_result_hand_out(status, budget, r, out);
}

projcurve_status pc_ortho_project_implicit(projcurve_context *ctx, projcurve_implicit_fn fn,
                                           void *user, double model_size,
                                           const projcurve_curve *curve, const pc_params *p,
                                           projcurve_result **out)
{
    const projcurve_status st =
        pc_curve_refuse_point(ctx, curve, pc_params_precision(p) * model_size);
    if (st != PROJCURVE_OK)
        return st;
    const double eps_d = p->tol_distance;
    pc_budget *const budget = p->budget;
    pc_budget_stage(budget, 0.0, p->compose ? 0.5 : 1.0);

    pc_implicit imp;
    imp.fn = fn;
    imp.user = user;
    imp.curve = curve;
    imp.model_size = model_size;
    imp.newton_tol = p->newton_tol * model_size;
    imp.newton_max_iter = (int)p->newton_max_iter;
    imp.grad_floor = 0.0;

    projcurve_result *r = NULL;
    projcurve_status status = pc_result_create(ctx, 4, &r);
    if (status == PROJCURVE_OK)
        status = pc_implicit_trace(ctx, &imp, p, r);
    if (status == PROJCURVE_OK && p->compose) {
        pc_budget_stage(budget, 0.5, 1.0);
        status = pc_implicit_fit(ctx, &imp, eps_d, p, r);
    }
    if (pc_status_keeps_result(status))
        r->stats.tol_distance = eps_d;
    return pc_result_hand_out(status, budget, r, out);
}
