/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Properties of one Bezier control net that do not depend on any query:
 * its Cartesian points with their box, and its flatness. The patch grid
 * keeps them per patch; the subdivision walk computes them per sub-patch.
 */
#include "bezier/net.h"

void pc_bezier_net_cartesian(const double *cw, size_t n, double *xyz, double box[6])
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < n; ++i) {
        const double w = cw[4 * i + 3];
        /* Polynomial nets (w = 1, also after subdivision) skip the division. */
        const double inv_w = w == 1.0 ? 1.0 : 1.0 / w;
        for (size_t k = 0; k < 3; ++k) {
            const double x = cw[4 * i + k] * inv_w;
            xyz[3 * i + k] = x;
            /* No branch per coordinate: the comparisons are unpredictable. */
            lo[k] = x < lo[k] ? x : lo[k];
            hi[k] = x > hi[k] ? x : hi[k];
        }
    }
    for (int k = 0; k < 3; ++k) {
        box[k] = lo[k];
        box[k + 3] = hi[k];
    }
}

double pc_bezier_net_flatness(const double *xyz, int p, int q, const double box[6])
{
    const size_t n_u = (size_t)p + 1;
    const double *c00 = xyz, *c10 = xyz + 3 * (size_t)p;
    const double *c01 = xyz + 3 * (size_t)q * n_u, *c11 = c01 + 3 * (size_t)p;
    const double step_s = 1.0 / p, step_t = 1.0 / q;
    double worst = 0.0;
    for (size_t j = 0; j <= (size_t)q; ++j) {
        /* Along row j the bilinear interpolant is the segment a + s d. */
        const double t = (double)j * step_t;
        double a[3], d[3];
        for (int k = 0; k < 3; ++k) {
            a[k] = c00[k] + t * (c01[k] - c00[k]);
            d[k] = c10[k] + t * (c11[k] - c10[k]) - a[k];
        }
        const double *x = xyz + 3 * j * n_u;
        for (size_t i = 0; i <= (size_t)p; ++i, x += 3) {
            const double s = (double)i * step_s;
            const double e[3] = {x[0] - (a[0] + s * d[0]), x[1] - (a[1] + s * d[1]),
                                 x[2] - (a[2] + s * d[2])};
            const double e2 = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
            worst = e2 > worst ? e2 : worst; /* fmax would be a libm call */
        }
    }
    const double diag = box_diagonal(box);
    return diag > 0.0 ? sqrt(worst) / diag : 0.0;
}
