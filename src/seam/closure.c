/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The closure of a surface, read on its control net (seam.h).
 */
#include "seam/seam.h"

#include <math.h>

/* Cartesian pole (i, j) and its weight. */
static pc_vec3 pole(const pc_nurbs_surface *s, size_t i, size_t j, double *w)
{
    const double *c = s->cw + 4 * (i + s->n_u * j);
    *w = c[3];
    return vec3(c[0] / c[3], c[1] / c[3], c[2] / c[3]);
}

/* Poles (i0 + di k, j0 + dj k), k < n, against (i1 + di k, j1 + dj k): the
 * two edge curves are the same curve. */
static int rows_equal(const pc_nurbs_surface *s, size_t n, size_t i0, size_t j0, size_t i1,
                      size_t j1, size_t di, size_t dj, double tol)
{
    double ratio0 = 0.0;
    for (size_t k = 0; k < n; ++k) {
        double wa, wb;
        const pc_vec3 a = pole(s, i0 + di * k, j0 + dj * k, &wa);
        const pc_vec3 b = pole(s, i1 + di * k, j1 + dj * k, &wb);
        if (!(vec3_norm(vec3_sub(a, b)) <= tol))
            return 0;
        const double ratio = wa / wb;
        if (k == 0)
            ratio0 = ratio;
        else if (!(fabs(ratio - ratio0) <= 1e-12 * fabs(ratio0)))
            return 0;
    }
    return 1;
}

/* Poles (i0 + di k, j0 + dj k), k < n, all within tol of the first. */
static int row_collapsed(const pc_nurbs_surface *s, size_t n, size_t i0, size_t j0, size_t di,
                         size_t dj, double tol)
{
    double w;
    const pc_vec3 first = pole(s, i0, j0, &w);
    for (size_t k = 1; k < n; ++k)
        if (!(vec3_norm(vec3_sub(pole(s, i0 + di * k, j0 + dj * k, &w), first)) <= tol))
            return 0;
    return 1;
}

void pc_surface_closure(const pc_nurbs_surface *s, double tol, pc_closure *out)
{
    const size_t nu = s->n_u, nv = s->n_v;
    out->closed_u = rows_equal(s, nv, 0, 0, nu - 1, 0, 0, 1, tol);
    out->closed_v = rows_equal(s, nu, 0, 0, 0, nv - 1, 1, 0, tol);
    out->collapsed = 0;
    if (row_collapsed(s, nv, 0, 0, 0, 1, tol))
        out->collapsed |= PC_SIDE_U0;
    if (row_collapsed(s, nv, nu - 1, 0, 0, 1, tol))
        out->collapsed |= PC_SIDE_U1;
    if (row_collapsed(s, nu, 0, 0, 1, 0, tol))
        out->collapsed |= PC_SIDE_V0;
    if (row_collapsed(s, nu, 0, nv - 1, 1, 0, tol))
        out->collapsed |= PC_SIDE_V1;
}
