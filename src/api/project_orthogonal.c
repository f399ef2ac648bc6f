/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The two public orthogonal projections ([PW96]): onto a NURBS surface
 * through the shared tracing / refining / composing machinery, and onto an
 * implicit surface with the 3-space tracer of ortho/implicit.h.
 */
#include <math.h>

#include "api/project.h"
#include "common/error.h"
#include "ortho/implicit.h"
#include "ortho/ortho_centres.h"
#include "ortho/ortho_duplicates.h"
#include "ortho/ortho_minima.h"
#include "ortho/ortho_projector.h"
#include "ortho/ortho_seeds.h"
#include "refine/refine.h"
#include "trace/result.h"
#include "trace/trace.h"
#include "verify/verify.h"

/* A det K = 0 end (or start) is what the engine calls a fold; for the
 * orthogonal projection that is a centre of curvature (corollary 2.1). */
static void name_singular_ends(projcurve_result *r)
{
    for (size_t i = 0; i < r->n_branches; ++i)
        if (r->branches[i].end == PROJCURVE_END_SILHOUETTE)
            r->branches[i].end = PROJCURVE_END_CURVATURE_CENTRE;
}

projcurve_status projcurve_project_orthogonal(projcurve_context *ctx,
                                              const projcurve_surface *surface,
                                              const projcurve_curve *curve,
                                              const projcurve_options *opts,
                                              projcurve_result **out)
{
    PC_REQUIRE(ctx, surface, "surface");
    PC_REQUIRE(ctx, curve, "curve");
    PC_REQUIRE(ctx, out, "out");
    struct projcurve_options o;
    projcurve_status st = pc_projection_options(ctx, opts, surface->size, &o);
    if (st == PROJCURVE_OK)
        st = pc_refuse_point_curve(ctx, curve, &o, surface->size);
    if (st != PROJCURVE_OK)
        return st;
    pc_budget budget;
    pc_projection_budget(&budget, &o);
    pc_budget_stage(&budget, 0.0, o.compose ? 0.5 : 1.0);

    pc_ortho_cache cache;
    pc_projector proj;
    pc_ortho_projector_init(&proj, &cache, surface, curve, o.newton_tol, (int)o.newton_max_iter);
    pc_ortho_finder_state finder_state;
    pc_seed_finder finder;
    const int minima_only = o.foot_points == PROJCURVE_FOOT_POINTS_MINIMA;
    pc_ortho_finder_init(&finder, &finder_state, surface, curve, minima_only ? &proj : NULL);
    finder_state.budget = o.budget; /* a foot-point search can take long */
    const pc_trace_config config = {0.0, surface->size, 0, {0.0, 0.0, 0.0}};

    projcurve_result *r = NULL;
    projcurve_status status = pc_result_create(ctx, 3, &r);
    if (status == PROJCURVE_OK)
        status = pc_trace_branches(ctx, &proj, &o, &finder, &config, r);
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
        r->stats.tol_distance = o.tol_distance;
        if (o.compose && pc_budget_status(&budget) == PROJCURVE_OK) {
            pc_budget_stage(&budget, 0.5, PC_PROJECT_FIT_FROM);
            status = pc_refine_and_compose(ctx, &proj, &o, r);
        }
    }
    /* only verified branches are returned, also from a partial result */
    if (pc_status_keeps_result(status)) {
        const projcurve_status vs = pc_verify_result(ctx, &proj, &o, r);
        if (vs != PROJCURVE_OK)
            status = vs;
    }
    if (o.compose && pc_status_keeps_result(status))
        status = pc_project_fit(ctx, &proj, &o, r, status);
    /* The projector's functions cannot report a failed curve callback
     * themselves; it is an error wherever it happened. */
    if (cache.callback_failed && pc_status_keeps_result(status))
        status = pc_fail(ctx, PROJCURVE_ERR_CALLBACK, "a curve callback failed while tracing");
    if (status == PROJCURVE_OK)
        status = traced;
    pc_ortho_finder_free(&finder_state);
    if (status == PROJCURVE_OK)
        pc_budget_finish(&budget);
    if (!pc_status_keeps_result(status)) {
        projcurve_result_destroy(r);
        return status;
    }
    *out = r;
    return status;
}

projcurve_status projcurve_project_orthogonal_implicit(
    projcurve_context *ctx, projcurve_implicit_fn fn, void *user, double model_size,
    const projcurve_curve *curve, const projcurve_options *opts, projcurve_result **out)
{
    PC_REQUIRE(ctx, fn, "implicit surface callback");
    PC_REQUIRE(ctx, curve, "curve");
    PC_REQUIRE(ctx, out, "out");
    if (!isfinite(model_size))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "model size is not finite");
    if (!(model_size > 0.0))
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                       "model size must be positive (got %.17g)", model_size);
    struct projcurve_options o;
    projcurve_status st = pc_projection_options(ctx, opts, model_size, &o);
    if (st == PROJCURVE_OK)
        st = pc_refuse_point_curve(ctx, curve, &o, model_size);
    if (st != PROJCURVE_OK)
        return st;
    const double eps_d = o.tol_distance;
    pc_budget budget;
    pc_projection_budget(&budget, &o);
    pc_budget_stage(&budget, 0.0, o.compose ? 0.5 : 1.0);

    pc_implicit imp;
    imp.fn = fn;
    imp.user = user;
    imp.curve = curve;
    imp.model_size = model_size;
    imp.newton_tol = o.newton_tol * model_size;
    imp.newton_max_iter = (int)o.newton_max_iter;
    imp.grad_floor = 0.0;

    projcurve_result *r = NULL;
    projcurve_status status = pc_result_create(ctx, 4, &r);
    if (status == PROJCURVE_OK)
        status = pc_implicit_trace(ctx, &imp, &o, r);
    if (status == PROJCURVE_OK && o.compose) {
        pc_budget_stage(&budget, 0.5, 1.0);
        status = pc_implicit_fit(ctx, &imp, eps_d, &o, r);
    }
    if (status == PROJCURVE_OK)
        pc_budget_finish(&budget);
    if (!pc_status_keeps_result(status)) {
        projcurve_result_destroy(r);
        return status;
    }
    r->stats.tol_distance = eps_d;
    *out = r;
    return status;
}
