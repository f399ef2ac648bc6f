/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Public surface functions: creation (geom/surface.h builds the spline with
 * its patch grid, BVH and tangent boxes), shape queries and evaluation.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "common/error.h"
#include "geom/surface.h"

/* Parameters this close to the domain (a fraction of its scale, 4 ulps)
 * are rounding of a point on its edge, and evaluated there. */
#define PC_DOMAIN_ROUNDING (4.0 * DBL_EPSILON)

projcurve_status projcurve_surface_create_nurbs(projcurve_context *ctx, int deg_u, int deg_v,
                                                size_t n_u, size_t n_v, const double *ctrl,
                                                const double *weights, const double *knots_u,
                                                const double *knots_v, projcurve_surface **out)
{
    PC_REQUIRE(ctx, out, "out");
    PC_REQUIRE(ctx, ctrl, "ctrl");
    PC_REQUIRE(ctx, knots_u, "knots_u");
    PC_REQUIRE(ctx, knots_v, "knots_v");
    return pc_surface_create(ctx, deg_u, deg_v, n_u, n_v, ctrl, weights, knots_u, knots_v, out);
}

void projcurve_surface_destroy(projcurve_surface *surface) { pc_surface_destroy(surface); }

projcurve_status projcurve_surface_domain(projcurve_context *ctx,
                                          const projcurve_surface *surface, double domain[4])
{
    PC_REQUIRE(ctx, surface, "surface");
    PC_REQUIRE(ctx, domain, "domain");
    for (int k = 0; k < 4; ++k)
        domain[k] = surface->nurbs.domain[k];
    return PROJCURVE_OK;
}

projcurve_status projcurve_surface_info(projcurve_context *ctx, const projcurve_surface *surface,
                                        int *deg_u, int *deg_v, size_t *n_u, size_t *n_v,
                                        size_t *spans_u, size_t *spans_v, int *rational)
{
    PC_REQUIRE(ctx, surface, "surface");
    const pc_nurbs_surface *s = &surface->nurbs;
    if (deg_u != NULL)
        *deg_u = s->deg_u;
    if (deg_v != NULL)
        *deg_v = s->deg_v;
    if (n_u != NULL)
        *n_u = s->n_u;
    if (n_v != NULL)
        *n_v = s->n_v;
    if (spans_u != NULL)
        *spans_u = surface->grid.spans_u;
    if (spans_v != NULL)
        *spans_v = surface->grid.spans_v;
    if (rational != NULL)
        *rational = s->rational;
    return PROJCURVE_OK;
}

projcurve_status projcurve_surface_eval(projcurve_context *ctx, const projcurve_surface *surface,
                                        double u, double v, int n_deriv, double *out)
{
    PC_REQUIRE(ctx, surface, "surface");
    PC_REQUIRE(ctx, out, "out");
    if (n_deriv < 0 || n_deriv > 2)
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE, "derivative order %d is outside [0, 2]",
                       n_deriv);
    if (!isfinite(u) || !isfinite(v))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "surface parameters (%g, %g) not finite",
                       u, v);
    const double *d = surface->nurbs.domain;
    /* A point of a pcurve on the domain's edge, (1 - s) a + s b with a and
     * b on it, rounds up to an ulp outside (linkrods.step surface 6: v =
     * -0.0031420979018159994 for the bound -0.0031420979018159999): within
     * a few ulps of the domain's scale a parameter is on the edge. */
    const double su = PC_DOMAIN_ROUNDING * fmax(fmax(fabs(d[0]), fabs(d[1])), d[1] - d[0]);
    const double sv = PC_DOMAIN_ROUNDING * fmax(fmax(fabs(d[2]), fabs(d[3])), d[3] - d[2]);
    if (u < d[0] - su || u > d[1] + su || v < d[2] - sv || v > d[3] + sv)
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_DOMAIN,
                       "(u, v) = (%.17g, %.17g) is outside the domain [%.17g, %.17g] x "
                       "[%.17g, %.17g]",
                       u, v, d[0], d[1], d[2], d[3]);
    /* pc_vec3 is three doubles without padding (vec.h), so the caller's
     * array takes the vectors as they are: a copy through a local array
     * costs a store-forwarding stall per vector, a third of the call */
    u = fmin(fmax(u, d[0]), d[1]);
    v = fmin(fmax(v, d[2]), d[3]);
    pc_nurbs_surface_eval(&surface->nurbs, u, v, n_deriv, NULL, NULL, (pc_vec3 *)out);
    return PROJCURVE_OK;
}

projcurve_status projcurve_surface_bounds(projcurve_context *ctx,
                                          const projcurve_surface *surface, double box[6])
{
    PC_REQUIRE(ctx, surface, "surface");
    PC_REQUIRE(ctx, box, "box");
    for (int k = 0; k < 6; ++k)
        box[k] = surface->box[k];
    return PROJCURVE_OK;
}

projcurve_status projcurve_surface_nurbs_data(projcurve_context *ctx,
                                              const projcurve_surface *surface, double *ctrl,
                                              double *weights, double *knots_u, double *knots_v)
{
    PC_REQUIRE(ctx, surface, "surface");
    const pc_nurbs_surface *s = &surface->nurbs;
    pc_nurbs_points_from_homogeneous(s->cw, s->n_u * s->n_v, ctrl, weights);
    if (knots_u != NULL)
        memcpy(knots_u, s->knots_u, (s->n_u + (size_t)s->deg_u + 1) * sizeof *knots_u);
    if (knots_v != NULL)
        memcpy(knots_v, s->knots_v, (s->n_v + (size_t)s->deg_v + 1) * sizeof *knots_v);
    return PROJCURVE_OK;
}
