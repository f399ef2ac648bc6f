/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The patch grid: lookup by parameter or grid position, and evaluation of a
 * Bezier patch in Bernstein form (independent of the B-spline basis code,
 * which makes it a check of the decomposition as well).
 */
#include "bezier/bezier.h"

/* Index k of the interval breaks[k] <= x < breaks[k + 1] among n intervals
 * (x clamped; the last interval is closed). */
static size_t locate_break(const double *breaks, size_t n, double x)
{
    size_t lo = 0, hi = n;
    while (hi - lo > 1) {
        const size_t mid = lo + (hi - lo) / 2;
        if (x < breaks[mid])
            hi = mid;
        else
            lo = mid;
    }
    return lo;
}

size_t pc_patch_grid_locate(const pc_patch_grid *grid, double u, double v)
{
    const size_t iu = locate_break(grid->breaks_u, grid->spans_u, u);
    const size_t iv = locate_break(grid->breaks_v, grid->spans_v, v);
    return iv * grid->spans_u + iu;
}

const pc_bezier_patch *pc_patch_grid_at(const pc_patch_grid *grid, size_t iu, size_t iv)
{
    if (iu >= grid->spans_u || iv >= grid->spans_v)
        return NULL;
    return &grid->patches[iv * grid->spans_u + iu];
}

/* Bernstein polynomials of degree p at s in [0, 1] and their derivatives up
 * to order n_deriv (<= 2) with respect to x = x0 + s (x1 - x0):
 * B_i^p' = p (B_{i-1}^{p-1} - B_i^{p-1}) / h, and likewise twice. */
static void bernstein_ders(int p, double x, double x0, double x1, int n_deriv, pc_basis *out)
{
    double(*b)[PC_MAX_ORDER] = out->d;
    const double h = x1 - x0;
    /* Not clamped: outside [x0, x1] the patch's polynomial extends smoothly. */
    const double s = (x - x0) / h;
    const double t = 1.0 - s;
    double level[3][PC_MAX_ORDER + 2]; /* degrees p-2, p-1, p, padded by zeros */
    double cur[PC_MAX_ORDER];
    cur[0] = 1.0;
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < PC_MAX_ORDER + 2; ++i)
            level[k][i] = 0.0;
    for (int deg = 0; deg <= p; ++deg) {
        if (deg > 0) {
            /* de Casteljau's recurrence on the basis itself. */
            cur[deg] = s * cur[deg - 1];
            for (int i = deg - 1; i > 0; --i)
                cur[i] = t * cur[i] + s * cur[i - 1];
            cur[0] = t * cur[0];
        }
        const int slot = deg - (p - 2);
        if (slot >= 0)
            for (int i = 0; i <= deg; ++i)
                level[slot][i + 2] = cur[i]; /* offset 2: index -1, -2 read zero */
    }
    for (int i = 0; i <= p; ++i)
        b[0][i] = level[2][i + 2];
    if (n_deriv >= 1)
        for (int i = 0; i <= p; ++i)
            b[1][i] = (double)p * (level[1][i + 1] - level[1][i + 2]) / h;
    if (n_deriv >= 2)
        for (int i = 0; i <= p; ++i)
            b[2][i] = (double)p * (double)(p - 1) *
                      (level[0][i] - 2.0 * level[0][i + 1] + level[0][i + 2]) / (h * h);
}

void pc_bezier_patch_eval(const pc_bezier_patch *patch, double u, double v, int n_deriv,
                          pc_vec3 *out)
{
    if (n_deriv > 2)
        n_deriv = 2;
    if (n_deriv < 0)
        n_deriv = 0;
    pc_basis bu, bv;
    bernstein_ders(patch->deg_u, u, patch->u0, patch->u1, n_deriv, &bu);
    bernstein_ders(patch->deg_v, v, patch->v0, patch->v1, n_deriv, &bv);
    pc_surface_block_eval(patch->cw, 4 * ((size_t)patch->deg_u + 1), patch->deg_u,
                          patch->deg_v, n_deriv, &bu, &bv, 1, out);
}
