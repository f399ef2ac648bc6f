/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Building the engine's surface: the spline, then its Bezier patch grid,
 * the BVH over the patches and the tangent boxes over the BVH nodes, each
 * once, so that every projection onto the surface shares them.
 */
#include "geom/surface.h"

#include <stdlib.h>

#include "common/error.h"

/* The box of the control points, and its diagonal as the model size. */
static void surface_box(projcurve_surface *s)
{
    box_empty(s->box);
    const size_t n_points = s->nurbs.n_u * s->nurbs.n_v;
    for (size_t i = 0; i < n_points; ++i) {
        const double *h = s->nurbs.cw + 4 * i;
        const double pt[3] = {h[0] / h[3], h[1] / h[3], h[2] / h[3]};
        box_add_point(s->box, pt);
    }
    s->size = box_diagonal(s->box);
}

projcurve_status pc_surface_create(projcurve_context *ctx, int deg_u, int deg_v, size_t n_u,
                                   size_t n_v, const double *ctrl, const double *weights,
                                   const double *knots_u, const double *knots_v,
                                   projcurve_surface **out)
{
    projcurve_surface *s = calloc(1, sizeof *s);
    if (s == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for a surface");
    projcurve_status st = pc_nurbs_surface_init(ctx, &s->nurbs, deg_u, deg_v, n_u, n_v, ctrl,
                                                weights, knots_u, knots_v);
    if (st != PROJCURVE_OK) {
        free(s);
        return st;
    }
    st = pc_patch_grid_build(ctx, &s->grid, &s->nurbs);
    if (st == PROJCURVE_OK)
        st = pc_bvh_build(ctx, &s->bvh, &s->grid);
    if (st == PROJCURVE_OK)
        st = pc_tangent_boxes_build(ctx, &s->tangents, &s->bvh, &s->grid, s->nurbs.rational);
    if (st != PROJCURVE_OK) {
        pc_surface_destroy(s);
        return st;
    }
    surface_box(s);
    *out = s;
    return PROJCURVE_OK;
}

void pc_surface_destroy(projcurve_surface *s)
{
    if (s == NULL)
        return;
    pc_tangent_boxes_free(&s->tangents);
    pc_bvh_free(&s->bvh);
    pc_patch_grid_free(&s->grid);
    pc_nurbs_surface_free(&s->nurbs);
    free(s);
}
