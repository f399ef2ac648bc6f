/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The two public orthogonal projections ([PW96]), onto a NURBS surface and
 * onto an implicit surface: arguments and options checked here, the
 * projections themselves are ortho/ortho_project.h.
 */
#include <math.h>

#include "api/project.h"
#include "common/error.h"
#include "ortho/ortho_project.h"

projcurve_status projcurve_project_orthogonal(projcurve_context *ctx,
                                              const projcurve_surface *surface,
                                              const projcurve_curve *curve,
                                              const projcurve_options *opts,
                                              projcurve_result **out)
{
    PC_REQUIRE(ctx, surface, "surface");
    PC_REQUIRE(ctx, curve, "curve");
    PC_REQUIRE(ctx, out, "out");
    pc_params p;
    pc_budget budget;
    const projcurve_status st = pc_projection_params(ctx, opts, surface->size, &budget, &p);
    if (st != PROJCURVE_OK)
        return st;
    return pc_ortho_project(ctx, surface, curve, &p, out);
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
    pc_params p;
    pc_budget budget;
    const projcurve_status st = pc_projection_params(ctx, opts, model_size, &budget, &p);
    if (st != PROJCURVE_OK)
        return st;
    return pc_ortho_project_implicit(ctx, fn, user, model_size, curve, &p, out);
}
