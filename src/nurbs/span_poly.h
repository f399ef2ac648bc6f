/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Per-span monomial form of a surface (span_poly.c) and its evaluation by
 * Horner's scheme, the fast path of pc_nurbs_surface_eval.
 */
#ifndef PC_NURBS_SPAN_POLY_H
#define PC_NURBS_SPAN_POLY_H

#include <stddef.h>

#include "nurbs/basis_impl.h"
#include "nurbs/nurbs.h"
#include "nurbs/surface_block.h"

/* The monomial form is kept for degrees up to 5 (the common CAD degrees;
 * above, conversion to monomials loses digits as 3^p) ... */
#define PC_POLY_MAX_DEGREE 5
#define PC_POLY_ORDER (PC_POLY_MAX_DEGREE + 1)
/* ... and tables up to 64 MiB (a 250 x 250-span bicubic surface); larger
 * surfaces evaluate in B-spline form. */
#define PC_POLY_MAX_BYTES ((size_t)64 << 20)

/* Doubles per span pair: (p+1) (q+1) homogeneous 4-vectors. */
static inline size_t pc_span_poly_len(int p, int q)
{
    return 4 * ((size_t)p + 1) * ((size_t)q + 1);
}

/* The table of s (spans in the order of pc_knot_inverses, u fastest; span
 * pair (k, l) at ((l - q) (n_u - p) + (k - p)) * pc_span_poly_len doubles;
 * coefficient (i, j) of x^i y^j at 4 (j (p + 1) + i) in it). malloc'd;
 * NULL when a degree exceeds PC_POLY_MAX_DEGREE or the table would exceed
 * PC_POLY_MAX_BYTES (evaluation then uses B-splines, which round
 * differently), and NULL with *no_memory = 1 when memory is short: the
 * caller must fail then, or the same surface would give other results. */
double *pc_span_polys_build(const pc_nurbs_surface *s, int *no_memory);

/* Monomial form of a curve: per span, (p + 1) homogeneous 4-vectors C_i,
 * coefficients of (t - t_k)^i; span k at (k - p) (p + 1) 4-vectors. NULL
 * when the degree exceeds PC_POLY_MAX_DEGREE, and NULL with *no_memory = 1
 * when memory is short (the caller must fail, as for surfaces). */
double *pc_curve_polys_build(const pc_nurbs_curve *c, int *no_memory);

/* Values and scaled derivatives b[d] = (1/d!) d^d f / dx^d, d <= n, of the
 * degree-P polynomial with 4-vector coefficients c[0], c[stride], ... at x:
 * Horner's scheme carried to the derivatives (each b[d] is the Horner sum
 * of the b[d-1] sequence). Zero terms are never formed, so that constant P
 * and n give straight-line code with P (n + 1) - n (n + 1) / 2 multiply-adds
 * per coordinate. */
static PC_ALWAYS_INLINE void pc_horner_ders(const double *c, size_t stride, int P, int n,
                                            double x, double b[PC_MAX_DERIV + 1][4])
{
    const double *top = c + (size_t)P * stride;
    for (int m = 0; m < 4; ++m)
        b[0][m] = top[m];
    PC_UNROLL
    for (int k = P - 1, step = 1; k >= 0; --k, ++step) {
        const double *ck = c + (size_t)k * stride;
        PC_UNROLL
        for (int d = (n < step ? n : step); d >= 1; --d)
            for (int m = 0; m < 4; ++m)
                b[d][m] = d == step ? b[d - 1][m] : b[d][m] * x + b[d - 1][m];
        for (int m = 0; m < 4; ++m)
            b[0][m] = b[0][m] * x + ck[m];
    }
    for (int d = (n < P ? n : P) + 1; d <= n; ++d)
        for (int m = 0; m < 4; ++m)
            b[d][m] = 0.0; /* derivatives above the degree */
}

/* Homogeneous derivatives A_kl (surface_block.h order) of the span pair
 * whose coefficients start at c, at offsets (x, y): Horner in x along each
 * of the q + 1 rows, then in y on each derivative order of the rows. */
static PC_ALWAYS_INLINE void pc_span_poly_eval(const double *c, int p, int q, int n_deriv,
                                               double x, double y, double a[PC_D_COUNT][4])
{
    double rows[3][PC_POLY_ORDER][4]; /* rows[d][j] = (1/d!) d^d/dx^d of row j */
    PC_UNROLL
    for (int j = 0; j <= q; ++j) {
        double b[PC_MAX_DERIV + 1][4];
        pc_horner_ders(c + 4 * (size_t)j * ((size_t)p + 1), 4, p, n_deriv, x, b);
        for (int d = 0; d <= n_deriv; ++d)
            for (int m = 0; m < 4; ++m)
                rows[d][j][m] = b[d][m];
    }
    double b[PC_MAX_DERIV + 1][4];
    pc_horner_ders(rows[0][0], 4, q, n_deriv, y, b); /* A00, A01, A02 / 2 */
    for (int m = 0; m < 4; ++m) {
        a[PC_D00][m] = b[0][m];
        if (n_deriv >= 1)
            a[PC_D01][m] = b[1][m];
        if (n_deriv >= 2)
            a[PC_D02][m] = 2.0 * b[2][m];
    }
    if (n_deriv < 1)
        return;
    pc_horner_ders(rows[1][0], 4, q, n_deriv - 1, y, b); /* A10, A11 */
    for (int m = 0; m < 4; ++m) {
        a[PC_D10][m] = b[0][m];
        if (n_deriv >= 2)
            a[PC_D11][m] = b[1][m];
    }
    if (n_deriv < 2)
        return;
    pc_horner_ders(rows[2][0], 4, q, 0, y, b); /* A20 / 2 */
    for (int m = 0; m < 4; ++m)
        a[PC_D20][m] = 2.0 * b[0][m];
}

#endif /* PC_NURBS_SPAN_POLY_H */
