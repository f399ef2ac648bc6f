/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve_project_conical: the arguments and options are checked here,
 * the projection itself is conical/.
 */
#include <math.h>

#include "api/project.h"
#include "common/error.h"
#include "conical/conical_project.h"

projcurve_status projcurve_project_conical(projcurve_context *ctx,
                                           const projcurve_surface *surface,
                                           const projcurve_curve *curve, const double eye[3],
                                           const projcurve_options *opts,
                                           projcurve_result **out)
{
    PC_REQUIRE(ctx, surface, "surface");
    PC_REQUIRE(ctx, curve, "curve");
    PC_REQUIRE(ctx, eye, "eye");
    PC_REQUIRE(ctx, out, "out");
    const pc_vec3 e = vec3_load(eye);
    if (!vec3_is_finite(e))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "eye point (%g, %g, %g) is not finite",
                       e.x, e.y, e.z);
    pc_params p;
    pc_budget budget;
    const projcurve_status st = pc_projection_params(ctx, opts, surface->size, &budget, &p);
    if (st != PROJCURVE_OK)
        return st;
    return pc_conical_project(ctx, surface, curve, e, &p, out);
}
