/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Bezier extraction: inserting every interior knot up to multiplicity p
 * turns the spline into its Bezier segments. A5.6 does it span by span in
 * place, touching each output point O(p) times.
 */
#include "bezier/extract.h"

#include <string.h>

#include "nurbs/nurbs.h"

size_t pc_bezier_span_count(const double *knots, size_t n_ctrl, int degree)
{
    size_t count = 0;
    for (size_t k = (size_t)degree; k < n_ctrl; ++k)
        count += knots[k] < knots[k + 1];
    return count;
}

void pc_bezier_breaks(const double *knots, size_t n_ctrl, int degree, double *breaks)
{
    size_t count = 0;
    breaks[count++] = knots[degree];
    for (size_t k = (size_t)degree; k < n_ctrl; ++k)
        if (knots[k] < knots[k + 1])
            breaks[count++] = knots[k + 1];
}

void pc_bezier_extract(const double *knots, size_t n_ctrl, int degree, const double *pts,
                       size_t dim, double *out)
{
    const size_t p = (size_t)degree, m = n_ctrl + p; /* m: last knot index */
    const double *U = knots;
    const size_t seg = (p + 1) * dim; /* doubles per segment */
    double alphas[PC_MAX_ORDER];
    size_t a = p, b = p + 1, nb = 0;
    memcpy(out, pts, seg * sizeof(double));
    while (b < m) {
        const size_t first = b;
        while (b < m && U[b + 1] == U[b])
            ++b;
        const size_t mult = b - first + 1;
        double *q = out + nb * seg;
        if (mult < p) {
            const double numer = U[b] - U[a];
            for (size_t j = p; j > mult; --j)
                alphas[j - mult - 1] = numer / (U[a + j] - U[a]);
            const size_t r = p - mult;
            for (size_t j = 1; j <= r; ++j) {
                const size_t save = r - j, s = mult + j;
                for (size_t k = p; k >= s; --k) {
                    const double alpha = alphas[k - s];
                    for (size_t c = 0; c < dim; ++c)
                        q[k * dim + c] = alpha * q[k * dim + c] + (1.0 - alpha) * q[(k - 1) * dim + c];
                }
                if (b < m)
                    memcpy(q + seg + save * dim, q + p * dim, dim * sizeof(double));
            }
        }
        ++nb;
        if (b < m) {
            /* A knot of multiplicity p + 1 (a break in continuity) leaves
             * nothing to carry over: the next segment's points are all
             * original control points. */
            const size_t i0 = mult < p ? p - mult : 0;
            memcpy(out + nb * seg + i0 * dim, pts + (b - p + i0) * dim,
                   (p + 1 - i0) * dim * sizeof(double));
            a = b;
            ++b;
        }
    }
}
