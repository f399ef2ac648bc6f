/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * B-spline basis functions of small degree (<= PC_SMALL_DEGREE) for the hot
 * evaluation paths: tables sized for eight functions instead of
 * PC_MAX_ORDER, so that an instance with a constant degree lives entirely in
 * registers (with 26-wide tables GCC keeps them in memory and spills), and
 * an instance with a run-time degree still touches only a few cache lines.
 */
#ifndef PC_NURBS_BASIS_SMALL_H
#define PC_NURBS_BASIS_SMALL_H

#include "nurbs/basis_impl.h"
#include "nurbs/nurbs.h"

/* Largest degree of the small paths, and their table width. */
#define PC_SMALL_DEGREE 7
#define PC_SMALL_ORDER (PC_SMALL_DEGREE + 1)
/* Reciprocal knot differences of one span: p (p + 1) / 2 <= 28. */
#define PC_SMALL_INVERSES (PC_SMALL_DEGREE * PC_SMALL_ORDER / 2)

/* The hot evaluators are compiled twice, for baseline x86-64 and with FMA
 * (PC_HOT_CLONES, common/compiler.h). */

/* d[k][j] = k-th derivative of the j-th nonzero function (as pc_basis). */
typedef struct pc_small_basis {
    double d[PC_MAX_DERIV + 1][PC_SMALL_ORDER];
} pc_small_basis;

/* The span's row of reciprocal knot differences (layout of
 * pc_knot_inverses): `table` itself when the spline has one, else computed
 * into `local`. */
static PC_ALWAYS_INLINE const double *pc_small_inverses(const double *knots, size_t span, int p,
                                                        const double *table,
                                                        double local[PC_SMALL_INVERSES])
{
    if (table != NULL)
        return table;
    for (int j = 1; j <= p; ++j)
        for (int r = 0; r < j; ++r)
            local[j * (j - 1) / 2 + r] =
                1.0 / (knots[span + (size_t)(r + 1)] - knots[span + (size_t)(r + 1 - j)]);
    return local;
}

/* The p + 1 functions N_{span-p..span} at t and their derivatives up to
 * order n_deriv (<= PC_MAX_DERIV), p <= PC_SMALL_DEGREE; inv is the span's
 * row of reciprocal knot differences, inv[j (j - 1) / 2 + r] =
 * 1 / (U[span+r+1] - U[span+r+1-j]).
 *
 * Cox-de Boor's triangle (The NURBS Book, A2.2) keeps the functions of the
 * degrees p - n .. p; the m-th derivatives then follow from degree p - m by
 * applying m times the derivative operator (ibid. eq. 2.7)
 *     D_j(f)[r] = j (f[r-1] inv[j][r-1] - f[r] inv[j][r]),
 * which maps values of degree j - 1 to derivatives of degree j. Called with
 * constants for p and n_deriv, every loop unrolls and the tables become
 * registers. Derivatives above the degree are zero. */
static PC_ALWAYS_INLINE void pc_small_basis_ders(const double *knots, size_t span, int p,
                                                 double t, int n_deriv, const double *inv,
                                                 pc_small_basis *out)
{
    const int n = n_deriv < p ? n_deriv : p;
    double left[PC_SMALL_ORDER], right[PC_SMALL_ORDER], N[PC_SMALL_ORDER];
    double level[PC_MAX_DERIV + 1][PC_SMALL_ORDER]; /* level[k]: degree p - k */
    N[0] = 1.0;
    if (p <= n)
        level[p][0] = 1.0;
    PC_UNROLL
    for (int j = 1; j <= p; ++j) {
        left[j] = t - knots[span + 1 - (size_t)j];
        right[j] = knots[span + (size_t)j] - t;
        double saved = 0.0;
        PC_UNROLL
        for (int r = 0; r < j; ++r) {
            const double temp = N[r] * inv[j * (j - 1) / 2 + r];
            N[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        N[j] = saved;
        if (p - j <= n) {
            PC_UNROLL
            for (int r = 0; r <= j; ++r)
                level[p - j][r] = N[r];
        }
    }
    PC_UNROLL
    for (int r = 0; r <= p; ++r)
        out->d[0][r] = N[r];
    PC_UNROLL
    for (int m = 1; m <= n; ++m) {
        double f[PC_SMALL_ORDER];
        PC_UNROLL
        for (int r = 0; r <= p - m; ++r)
            f[r] = level[m][r];
        PC_UNROLL
        for (int j = p - m + 1; j <= p; ++j) {
            const double *iv = inv + j * (j - 1) / 2;
            double prev = 0.0; /* f[r - 1] inv[j][r - 1], zero for r = 0 */
            PC_UNROLL
            for (int r = 0; r < j; ++r) {
                const double next = f[r] * iv[r];
                f[r] = (double)j * (prev - next);
                prev = next;
            }
            f[j] = (double)j * prev;
        }
        PC_UNROLL
        for (int r = 0; r <= p; ++r)
            out->d[m][r] = f[r];
    }
    for (int m = n + 1; m <= n_deriv; ++m)
        for (int r = 0; r <= p; ++r)
            out->d[m][r] = 0.0;
}

#endif /* PC_NURBS_BASIS_SMALL_H */
