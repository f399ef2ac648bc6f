/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * NURBS surfaces: creation from user arrays (validation, homogeneous copy,
 * exact clamping in u then in v).
 */
#include <stdlib.h>
#include <string.h>

#include "common/error.h"
#include "nurbs/input.h"
#include "nurbs/nurbs.h"
#include "nurbs/span_poly.h"

static double *copy_knots(const double *knots, size_t n)
{
    double *k = malloc(n * sizeof(double));
    if (k != NULL)
        memcpy(k, knots, n * sizeof(double));
    return k;
}

static projcurve_status check_surface_input(projcurve_context *ctx, int deg_u, int deg_v,
                                            size_t n_u, size_t n_v, const double *knots_u,
                                            const double *knots_v)
{
    projcurve_status st = pc_input_check_degree(ctx, "degree u", deg_u, n_u);
    if (st == PROJCURVE_OK)
        st = pc_input_check_degree(ctx, "degree v", deg_v, n_v);
    if (st == PROJCURVE_OK)
        st = pc_input_check_sizes(ctx, deg_u, n_u, deg_v, n_v);
    if (st == PROJCURVE_OK)
        st = pc_knots_validate(ctx, "knot vector u", deg_u, n_u, knots_u);
    if (st == PROJCURVE_OK)
        st = pc_knots_validate(ctx, "knot vector v", deg_v, n_v, knots_v);
    if (st == PROJCURVE_OK)
        st = pc_input_check_domain(ctx, "surface domain u", knots_u[deg_u], knots_u[n_u]);
    if (st == PROJCURVE_OK)
        st = pc_input_check_domain(ctx, "surface domain v", knots_v[deg_v], knots_v[n_v]);
    return st;
}

projcurve_status pc_nurbs_surface_init(projcurve_context *ctx, pc_nurbs_surface *s,
                                       int deg_u, int deg_v, size_t n_u, size_t n_v,
                                       const double *ctrl, const double *weights,
                                       const double *knots_u, const double *knots_v)
{
    projcurve_status st = check_surface_input(ctx, deg_u, deg_v, n_u, n_v, knots_u, knots_v);
    if (st != PROJCURVE_OK)
        return st;
    /* In u: n_v rows of n_u points; the rows are contiguous (u fastest). */
    pc_spline_batch bu = {deg_u, n_u, 4, n_v, NULL, NULL};
    pc_spline_batch bv = {deg_v, n_v, 0, 1, NULL, NULL};
    int rational = 0;
    st = pc_input_homogeneous(ctx, n_u * n_v, ctrl, weights, &bu.pts, &rational);
    if (st != PROJCURVE_OK)
        return st;
    if ((st = pc_input_check_extent(ctx, n_u * n_v, ctrl)) != PROJCURVE_OK) {
        free(bu.pts);
        return st;
    }
    bu.knots = copy_knots(knots_u, n_u + (size_t)deg_u + 1);
    bv.knots = copy_knots(knots_v, n_v + (size_t)deg_v + 1);
    if (bu.knots == NULL || bv.knots == NULL) {
        st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for the knot vectors");
        goto cleanup;
    }
    if (!pc_knots_are_clamped(bu.knots, n_u, deg_u)) {
        st = pc_spline_batch_clamp(ctx, &bu);
        if (st != PROJCURVE_OK)
            goto cleanup;
    }
    /* In v: one row whose "points" are whole rows of the net. */
    bv.dim = 4 * bu.n_ctrl;
    bv.pts = bu.pts;
    bu.pts = NULL;
    if (!pc_knots_are_clamped(bv.knots, n_v, deg_v)) {
        st = pc_spline_batch_clamp(ctx, &bv);
        if (st != PROJCURVE_OK)
            goto cleanup;
    }
    s->deg_u = deg_u;
    s->deg_v = deg_v;
    s->n_u = bu.n_ctrl;
    s->n_v = bv.n_ctrl;
    s->knots_u = bu.knots;
    s->knots_v = bv.knots;
    s->cw = bv.pts;
    s->rational = rational;
    s->domain[0] = bu.knots[deg_u];
    s->domain[1] = bu.knots[bu.n_ctrl];
    s->domain[2] = bv.knots[deg_v];
    s->domain[3] = bv.knots[bv.n_ctrl];
    s->inv_u = pc_knot_inverses(s->knots_u, s->n_u, deg_u);
    s->inv_v = pc_knot_inverses(s->knots_v, s->n_v, deg_v);
    if (s->inv_u == NULL || s->inv_v == NULL) {
        pc_nurbs_surface_free(s);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for knot tables");
    }
    /* Built whenever its size allows: evaluation must not depend on memory. */
    int no_memory;
    s->poly = pc_span_polys_build(s, &no_memory);
    if (no_memory) {
        pc_nurbs_surface_free(s);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for the span polynomials");
    }
    pc_nurbs_surface_bind(s);
    return PROJCURVE_OK;

cleanup:
    free(bu.knots);
    free(bu.pts);
    free(bv.knots);
    free(bv.pts);
    return st;
}

void pc_nurbs_surface_free(pc_nurbs_surface *s)
{
    if (s == NULL)
        return;
    free(s->knots_u);
    free(s->knots_v);
    free(s->cw);
    free(s->inv_u);
    free(s->inv_v);
    free(s->poly);
    s->knots_u = s->knots_v = s->cw = s->inv_u = s->inv_v = s->poly = NULL;
}
