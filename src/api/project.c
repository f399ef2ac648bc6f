/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve_project_directional, and the resolution of the options that
 * every projection entry point shares: the arguments and options are
 * checked here, the projection itself is directional/.
 */
#include "api/project.h"

#include <math.h>

#include "common/error.h"
#include "directional/directional_project.h"
#include "refine/refine.h"

projcurve_status pc_projection_params(projcurve_context *ctx, const projcurve_options *opts,
                                      double model_size, pc_budget *budget, pc_params *out)
{
    struct projcurve_options o;
    if (opts == NULL)
        pc_options_defaults(&o);
    else
        o = *opts;
    projcurve_status st = pc_options_check(ctx, &o);
    if (st != PROJCURVE_OK)
        return st;
    pc_options_to_params(&o, out);
    double eps_d = 0.0;
    st = pc_params_distance_tolerance(ctx, out, model_size > 0.0 ? model_size : 1.0, &eps_d);
    if (st == PROJCURVE_OK && out->compose && out->tol_angle_deg < PC_REFINE_MIN_ANGLE_DEG)
        st = pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE,
                     "option TOL_ANGLE_DEG: %g is below %g, the smallest joint angle the "
                     "refinement can resolve (the exact tangents are known to ~1e-6 relative)",
                     out->tol_angle_deg, PC_REFINE_MIN_ANGLE_DEG);
    if (st != PROJCURVE_OK)
        return st;
    out->tol_distance = eps_d;
    pc_budget_init(budget, o.time_limit, (unsigned long long)o.max_work, o.progress,
                   o.progress_user);
    out->budget = budget;
    return PROJCURVE_OK;
}

/* Scaling by the largest component first keeps tiny and huge vectors
 * normalisable. */
projcurve_status pc_unit_direction(projcurve_context *ctx, const double dir[3], pc_vec3 *out)
{
    const pc_vec3 d = vec3_load(dir);
    if (!vec3_is_finite(d))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE,
                       "direction (%g, %g, %g) is not finite", d.x, d.y, d.z);
    const double m = fmax(fabs(d.x), fmax(fabs(d.y), fabs(d.z)));
    if (!(m > 0.0))
        return pc_fail(ctx, PROJCURVE_ERR_ZERO_DIRECTION, "direction is the zero vector");
    *out = vec3_normalize(vec3(d.x / m, d.y / m, d.z / m));
    return PROJCURVE_OK;
}

projcurve_status projcurve_project_directional(projcurve_context *ctx,
                                               const projcurve_surface *surface,
                                               const projcurve_curve *curve,
                                               const double dir[3],
                                               const projcurve_options *opts,
                                               projcurve_result **out)
{
    PC_REQUIRE(ctx, surface, "surface");
    PC_REQUIRE(ctx, curve, "curve");
    PC_REQUIRE(ctx, dir, "dir");
    PC_REQUIRE(ctx, out, "out");
    pc_vec3 unit;
    pc_params p;
    pc_budget budget;
    projcurve_status st = pc_unit_direction(ctx, dir, &unit);
    if (st == PROJCURVE_OK)
        st = pc_projection_params(ctx, opts, surface->size, &budget, &p);
    if (st != PROJCURVE_OK)
        return st;
    return pc_directional_project(ctx, surface, curve, unit, &p, out);
}
