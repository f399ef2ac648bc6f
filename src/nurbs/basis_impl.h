/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The basis routine as an always-inlined function, so that hot callers can
 * instantiate it for a constant degree (the compiler then unrolls every loop
 * of the common cubic and quadratic cases); pc_basis_ders is the generic
 * instance.
 */
#ifndef PC_NURBS_BASIS_IMPL_H
#define PC_NURBS_BASIS_IMPL_H

#include "common/compiler.h"
#include "nurbs/nurbs.h"

/* B-spline basis functions and their derivatives.
 *
 * Cox-de Boor's triangle (The NURBS Book, A2.2) gives the functions of every
 * degree j <= p that are nonzero on the span; the derivatives then follow
 * from the lower degrees by the derivative formula (ibid. eq. 2.7)
 *     N_{i,j}^(m) = j (N_{i,j-1}^(m-1) / (U[i+j] - U[i])
 *                      - N_{i+1,j-1}^(m-1) / (U[i+j+1] - U[i+1])),
 * whose denominators are exactly those of the triangle. Taking their
 * reciprocals once makes the whole computation p (p + 1) / 2 divisions and
 * multiplications otherwise: divisions dominate the cost of this routine,
 * which sits in the innermost loop of tracing. No allocation.
 */

/* inv_table: the span's row of pc_knot_inverses, or NULL to divide here. */
static PC_ALWAYS_INLINE void pc_basis_ders_inline(const double *knots, size_t span, int degree,
                                                 double t, int n_deriv, pc_basis *out,
                                                 const double *inv_table)
{
    const int p = degree;
    const int n = n_deriv < p ? n_deriv : p; /* derivatives above p vanish */
    const int low = p - n;                   /* lowest degree needed */
    double left[PC_MAX_ORDER], right[PC_MAX_ORDER];
    double inv[PC_MAX_ORDER][PC_MAX_ORDER]; /* inv[j][r] = 1 / (U[s+r+1] - U[s+r+1-j]) */
    double cur[PC_MAX_DERIV + 1][PC_MAX_ORDER]; /* cur[jj]: functions of degree low + jj */
    double N[PC_MAX_ORDER];

    N[0] = 1.0;
    if (low == 0)
        cur[0][0] = 1.0;
    PC_UNROLL
    for (int j = 1; j <= p; ++j) {
        left[j] = t - knots[span + 1 - (size_t)j];
        right[j] = knots[span + (size_t)j] - t;
        double saved = 0.0;
        PC_UNROLL
        for (int r = 0; r < j; ++r) {
            inv[j][r] = inv_table != NULL ? inv_table[j * (j - 1) / 2 + r]
                                          : 1.0 / (right[r + 1] + left[j - r]);
            const double temp = N[r] * inv[j][r];
            N[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        N[j] = saved;
        if (j >= low) {
            PC_UNROLL
            for (int r = 0; r <= j; ++r)
                cur[j - low][r] = N[r];
        }
    }
    for (int r = 0; r <= p; ++r)
        out->d[0][r] = N[r];

    /* Order m from order m - 1, highest level first so that level jj - 1
     * still holds order m - 1 when level jj reads it. */
    PC_UNROLL
    for (int m = 1; m <= n; ++m) {
        PC_UNROLL
        for (int jj = n; jj >= m; --jj) {
            const int j = low + jj;
            const double *lower = cur[jj - 1];
            double prev = 0.0; /* lower[r - 1] * inv[j][r - 1], zero for r = 0 */
            PC_UNROLL
            for (int r = 0; r < j; ++r) {
                const double next = lower[r] * inv[j][r];
                cur[jj][r] = (double)j * (prev - next);
                prev = next;
            }
            cur[jj][j] = (double)j * prev;
        }
        for (int r = 0; r <= p; ++r)
            out->d[m][r] = cur[n][r];
    }
    for (int m = n + 1; m <= n_deriv; ++m)
        for (int r = 0; r <= p; ++r)
            out->d[m][r] = 0.0;
}

#endif /* PC_NURBS_BASIS_IMPL_H */
