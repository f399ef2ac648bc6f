/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The many-curve projections: arguments and options checked here, the
 * work is batch/.
 */
#include "api/project.h"
#include "batch/batch.h"
#include "common/error.h"

static projcurve_status project_curves(projcurve_context *ctx, const projcurve_surface *surface,
                                       const projcurve_curve *const *curves, size_t n,
                                       const double *dir, const projcurve_options *opts,
                                       projcurve_result **results, projcurve_status *statuses)
{
    PC_REQUIRE(ctx, surface, "surface");
    if (n > 0) {
        PC_REQUIRE(ctx, curves, "curves");
        PC_REQUIRE(ctx, results, "results");
    }
    pc_vec3 unit = {0.0, 0.0, 0.0};
    if (dir != NULL) {
        const projcurve_status st = pc_unit_direction(ctx, dir, &unit);
        if (st != PROJCURVE_OK)
            return st;
    }
    pc_params p;
    pc_budget unused;
    const projcurve_status st = pc_projection_params(ctx, opts, surface->size, &unused, &p);
    if (st != PROJCURVE_OK)
        return st;
    struct projcurve_options o;
    if (opts == NULL)
        pc_options_defaults(&o);
    else
        o = *opts;
    const pc_batch_budget budget = {o.time_limit, (unsigned long long)o.max_work, o.progress,
                                    o.progress_user};
    return pc_batch_project(ctx, surface, curves, n, dir != NULL ? &unit : NULL, &p, &budget,
                            results, statuses);
}

projcurve_status projcurve_project_curves_directional(
    projcurve_context *ctx, const projcurve_surface *surface,
    const projcurve_curve *const *curves, size_t n, const double dir[3],
    const projcurve_options *opts, projcurve_result **results, projcurve_status *statuses)
{
    PC_REQUIRE(ctx, dir, "dir");
    return project_curves(ctx, surface, curves, n, dir, opts, results, statuses);
}

projcurve_status projcurve_project_curves_orthogonal(
    projcurve_context *ctx, const projcurve_surface *surface,
    const projcurve_curve *const *curves, size_t n, const projcurve_options *opts,
    projcurve_result **results, projcurve_status *statuses)
{
    return project_curves(ctx, surface, curves, n, NULL, opts, results, statuses);
}
