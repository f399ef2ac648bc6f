/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Bezier decomposition of NURBS surfaces (the patch grid) and curves.
 *
 * Surfaces are extracted in u row by row (each row of the net is a curve of
 * 4-doubles), then in v with whole extracted rows as the "points"; the
 * resulting (spans_u (p+1)) x (spans_v (q+1)) net is cut into per-patch
 * contiguous nets so that a patch is one cache-friendly block.
 */
#include <stdlib.h>
#include <string.h>

#include "bezier/bezier.h"
#include "bezier/extract.h"
#include "bezier/net.h"
#include "common/error.h"

static void fill_patches(pc_patch_grid *grid, const pc_nurbs_surface *s, const double *big)
{
    const size_t p1 = (size_t)s->deg_u + 1, q1 = (size_t)s->deg_v + 1;
    const size_t big_nu = grid->spans_u * p1;
    const size_t net = 4 * p1 * q1;
    for (size_t iv = 0; iv < grid->spans_v; ++iv)
        for (size_t iu = 0; iu < grid->spans_u; ++iu) {
            const size_t index = iv * grid->spans_u + iu;
            double *dst = grid->cw + index * net;
            for (size_t j = 0; j < q1; ++j)
                memcpy(dst + 4 * p1 * j, big + 4 * ((iv * q1 + j) * big_nu + iu * p1),
                       4 * p1 * sizeof(double));
            pc_bezier_patch *patch = &grid->patches[index];
            patch->deg_u = s->deg_u;
            patch->deg_v = s->deg_v;
            patch->u0 = grid->breaks_u[iu];
            patch->u1 = grid->breaks_u[iu + 1];
            patch->v0 = grid->breaks_v[iv];
            patch->v1 = grid->breaks_v[iv + 1];
            patch->cw = dst;
            patch->iu = iu;
            patch->iv = iv;
            /* What a point query needs of the whole patch, once: the
             * subdivision walk starts from these (point/subdivide.c). */
            double *xyz = grid->xyz + index * 3 * p1 * q1;
            pc_bezier_net_cartesian(dst, p1 * q1, xyz, patch->box);
            patch->xyz = xyz;
            patch->flatness = pc_bezier_net_flatness(xyz, s->deg_u, s->deg_v, patch->box);
        }
}

/* flags[k] for the spans + 1 breaks of one direction: the ends, and the
 * knots repeated at least degree times (one pass: both lists ascend). */
static void crease_flags(const double *knots, size_t n_ctrl, int degree, const double *breaks,
                         size_t spans, unsigned char *flags)
{
    const size_t n_knots = n_ctrl + (size_t)degree + 1;
    size_t i = 0;
    for (size_t k = 0; k <= spans; ++k) {
        while (i < n_knots && knots[i] < breaks[k])
            ++i;
        size_t mult = 0;
        while (i + mult < n_knots && knots[i + mult] == breaks[k])
            ++mult;
        flags[k] = k == 0 || k == spans || mult >= (size_t)degree;
    }
}

projcurve_status pc_patch_grid_build(projcurve_context *ctx, pc_patch_grid *grid,
                                     const pc_nurbs_surface *s)
{
    memset(grid, 0, sizeof *grid);
    const size_t p1 = (size_t)s->deg_u + 1, q1 = (size_t)s->deg_v + 1;
    grid->spans_u = pc_bezier_span_count(s->knots_u, s->n_u, s->deg_u);
    grid->spans_v = pc_bezier_span_count(s->knots_v, s->n_v, s->deg_v);
    const size_t n_patches = pc_size_mul(grid->spans_u, grid->spans_v);
    const size_t big_nu = pc_size_mul(grid->spans_u, p1);
    const size_t big_nv = pc_size_mul(grid->spans_v, q1);
    const size_t n_doubles = pc_size_mul(pc_size_mul(big_nu, big_nv), 4);
    if (n_patches == 0 || big_nu == 0 || big_nv == 0 || n_doubles == 0 ||
        pc_size_mul(n_doubles, sizeof(double)) == 0 ||
        pc_size_mul(n_patches, sizeof(pc_bezier_patch)) == 0 ||
        pc_size_mul(pc_size_mul(big_nu, s->n_v), 4 * sizeof(double)) == 0)
        return pc_fail(ctx, PROJCURVE_ERR_OVERFLOW, "Bezier decomposition of a %zu x %zu net "
                       "overflows", s->n_u, s->n_v);

    double *rows_u = malloc(big_nu * s->n_v * 4 * sizeof(double)); /* after u extraction */
    double *big = malloc(n_doubles * sizeof(double));               /* after v extraction */
    grid->patches = malloc(n_patches * sizeof(pc_bezier_patch));
    grid->breaks_u = malloc((grid->spans_u + 1) * sizeof(double));
    grid->breaks_v = malloc((grid->spans_v + 1) * sizeof(double));
    grid->crease_u = malloc(grid->spans_u + 1);
    grid->crease_v = malloc(grid->spans_v + 1);
    grid->cw = malloc(n_doubles * sizeof(double));
    grid->xyz = malloc(n_doubles / 4 * 3 * sizeof(double));
    if (rows_u == NULL || big == NULL || grid->patches == NULL || grid->breaks_u == NULL ||
        grid->breaks_v == NULL || grid->crease_u == NULL || grid->crease_v == NULL ||
        grid->cw == NULL || grid->xyz == NULL) {
        free(rows_u);
        free(big);
        pc_patch_grid_free(grid);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for %zu Bezier patches",
                       n_patches);
    }
    pc_bezier_breaks(s->knots_u, s->n_u, s->deg_u, grid->breaks_u);
    pc_bezier_breaks(s->knots_v, s->n_v, s->deg_v, grid->breaks_v);
    crease_flags(s->knots_u, s->n_u, s->deg_u, grid->breaks_u, grid->spans_u, grid->crease_u);
    crease_flags(s->knots_v, s->n_v, s->deg_v, grid->breaks_v, grid->spans_v, grid->crease_v);
    for (size_t j = 0; j < s->n_v; ++j)
        pc_bezier_extract(s->knots_u, s->n_u, s->deg_u, s->cw + 4 * s->n_u * j, 4,
                          rows_u + 4 * big_nu * j);
    pc_bezier_extract(s->knots_v, s->n_v, s->deg_v, rows_u, 4 * big_nu, big);
    fill_patches(grid, s, big);
    free(rows_u);
    free(big);
    return PROJCURVE_OK;
}

void pc_patch_grid_free(pc_patch_grid *grid)
{
    if (grid == NULL)
        return;
    free(grid->patches);
    free(grid->breaks_u);
    free(grid->breaks_v);
    free(grid->crease_u);
    free(grid->crease_v);
    free(grid->cw);
    free(grid->xyz);
    memset(grid, 0, sizeof *grid);
}

projcurve_status pc_bezier_curves_build(projcurve_context *ctx, pc_bezier_curves *out,
                                        const pc_nurbs_curve *c)
{
    memset(out, 0, sizeof *out);
    const size_t n_seg = pc_bezier_span_count(c->knots, c->n_ctrl, c->degree);
    const size_t n_doubles = pc_size_mul(pc_size_mul(n_seg, (size_t)c->degree + 1), 4);
    if (n_doubles == 0 || pc_size_mul(n_doubles, sizeof(double)) == 0)
        return pc_fail(ctx, PROJCURVE_ERR_OVERFLOW, "Bezier decomposition overflows");
    out->breaks = malloc((n_seg + 1) * sizeof(double));
    out->cw = malloc(n_doubles * sizeof(double));
    if (out->breaks == NULL || out->cw == NULL) {
        pc_bezier_curves_free(out);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for %zu Bezier segments",
                       n_seg);
    }
    out->degree = c->degree;
    out->n_segments = n_seg;
    pc_bezier_breaks(c->knots, c->n_ctrl, c->degree, out->breaks);
    pc_bezier_extract(c->knots, c->n_ctrl, c->degree, c->cw, 4, out->cw);
    return PROJCURVE_OK;
}

void pc_bezier_curves_free(pc_bezier_curves *b)
{
    if (b == NULL)
        return;
    free(b->breaks);
    free(b->cw);
    memset(b, 0, sizeof *b);
}
