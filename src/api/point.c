/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Public point projection: closest points on curves and surfaces, and the
 * foot points of a point on a surface.
 */
#include <stdlib.h>

#include "common/error.h"
#include "point/point.h"

static projcurve_status check_point(projcurve_context *ctx, const double p[3])
{
    if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "point (%g, %g, %g) is not finite", p[0],
                       p[1], p[2]);
    return PROJCURVE_OK;
}

projcurve_status projcurve_curve_closest_point(projcurve_context *ctx,
                                               const projcurve_curve *curve, const double p[3],
                                               double *t, double q[3], double *dist)
{
    PC_REQUIRE(ctx, curve, "curve");
    PC_REQUIRE(ctx, p, "p");
    PC_REQUIRE(ctx, t, "t");
    projcurve_status st = check_point(ctx, p);
    if (st != PROJCURVE_OK)
        return st;
    double best_t;
    pc_vec3 best_q;
    double best_dist;
    st = pc_curve_closest(ctx, curve, vec3_load(p), &best_t, &best_q, &best_dist);
    if (st != PROJCURVE_OK)
        return st;
    *t = best_t;
    if (q != NULL)
        vec3_store(best_q, q);
    if (dist != NULL)
        *dist = best_dist;
    return PROJCURVE_OK;
}

projcurve_status projcurve_surface_closest_point(projcurve_context *ctx,
                                                 const projcurve_surface *surface,
                                                 const double p[3], double uv[2], double q[3],
                                                 double *dist)
{
    PC_REQUIRE(ctx, surface, "surface");
    PC_REQUIRE(ctx, p, "p");
    PC_REQUIRE(ctx, uv, "uv");
    projcurve_status st = check_point(ctx, p);
    if (st != PROJCURVE_OK)
        return st;
    pc_surface_point best;
    st = pc_surface_closest(ctx, surface, vec3_load(p), &best);
    if (st != PROJCURVE_OK)
        return st;
    uv[0] = best.u;
    uv[1] = best.v;
    if (q != NULL)
        vec3_store(best.q, q);
    if (dist != NULL)
        *dist = best.dist;
    return PROJCURVE_OK;
}

projcurve_status projcurve_surface_foot_points(projcurve_context *ctx,
                                               const projcurve_surface *surface,
                                               const double p[3], size_t capacity, double *uv,
                                               size_t *count)
{
    PC_REQUIRE(ctx, surface, "surface");
    PC_REQUIRE(ctx, p, "p");
    PC_REQUIRE(ctx, count, "count");
    if (capacity > 0 && uv == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NULL_ARGUMENT, "uv is NULL with capacity %zu",
                       capacity);
    projcurve_status st = check_point(ctx, p);
    if (st != PROJCURVE_OK)
        return st;
    return pc_surface_foot_points_uv(ctx, surface, vec3_load(p), NULL, capacity, uv, count);
}
