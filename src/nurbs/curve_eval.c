/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * NURBS curve point and derivatives up to order 3, evaluated in the tracing
 * loop for every step. Degrees up to PC_POLY_MAX_DEGREE use the per-span
 * monomial form (span_poly.h) by Horner's scheme; otherwise degrees up to
 * PC_SMALL_DEGREE use the eight-wide basis of basis_small.h, specialised per
 * degree, and higher degrees the generic basis routine. No allocation.
 */
#include "nurbs/basis_small.h"
#include "nurbs/nurbs.h"
#include "nurbs/span_poly.h"

/* Binomial coefficients up to 3 for the quotient rule. */
static const double k_binom[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};

/* Homogeneous derivatives a[k] = sum_j N_j^(k) P_j of one span's points. */
static PC_ALWAYS_INLINE void contract(const double *cw, const double *basis, int width, int p,
                                      int n_deriv, double a[PC_MAX_DERIV + 1][4])
{
    for (int k = 0; k <= n_deriv; ++k) {
        double sum[4] = {0, 0, 0, 0};
        for (int j = 0; j <= p; ++j)
            for (int m = 0; m < 4; ++m)
                sum[m] += basis[k * width + j] * cw[4 * j + m];
        for (int m = 0; m < 4; ++m)
            a[k][m] = sum[m];
    }
}

/* Derivatives up to PC_MAX_DERIV of a degree <= PC_SMALL_DEGREE span, with
 * the basis unrolled for each degree. */
PC_HOT_CLONES static void small_curve_ders(const pc_nurbs_curve *c, size_t span, double t,
                                           int n_deriv, double a[PC_MAX_DERIV + 1][4])
{
    double local[PC_SMALL_INVERSES];
    const int p = c->degree;
    const double *inv = pc_small_inverses(c->knots, span, p, NULL, local);
    pc_small_basis b;
    switch (p) {
    case 1: pc_small_basis_ders(c->knots, span, 1, t, PC_MAX_DERIV, inv, &b); break;
    case 2: pc_small_basis_ders(c->knots, span, 2, t, PC_MAX_DERIV, inv, &b); break;
    case 3: pc_small_basis_ders(c->knots, span, 3, t, PC_MAX_DERIV, inv, &b); break;
    case 4: pc_small_basis_ders(c->knots, span, 4, t, PC_MAX_DERIV, inv, &b); break;
    case 5: pc_small_basis_ders(c->knots, span, 5, t, PC_MAX_DERIV, inv, &b); break;
    case 6: pc_small_basis_ders(c->knots, span, 6, t, PC_MAX_DERIV, inv, &b); break;
    default: pc_small_basis_ders(c->knots, span, PC_SMALL_DEGREE, t, PC_MAX_DERIV, inv, &b); break;
    }
    contract(c->cw + 4 * (span - (size_t)p), b.d[0], PC_SMALL_ORDER, p, n_deriv, a);
}

/* Homogeneous derivatives from the monomial form, degree P constant. */
#define PC_CURVE_POLY(P)                                                                     \
    static void poly_ders_##P(const double *c, double x, double a[PC_MAX_DERIV + 1][4])      \
    {                                                                                        \
        pc_horner_ders(c, 4, P, PC_MAX_DERIV, x, a);                                         \
    }
PC_CURVE_POLY(1)
PC_CURVE_POLY(2)
PC_CURVE_POLY(3)
PC_CURVE_POLY(4)
PC_CURVE_POLY(5)

/* d^k A / dt^k = k! b[k] from the scaled Horner sums. */
static const double k_factorial[PC_MAX_DERIV + 1] = {1, 1, 2, 6};

PC_HOT_CLONES static void poly_curve_ders(const pc_nurbs_curve *c, size_t span, double t,
                                          double a[PC_MAX_DERIV + 1][4])
{
    const int p = c->degree;
    const double *coef = c->poly + (span - (size_t)p) * 4 * ((size_t)p + 1);
    const double x = t - c->knots[span];
    switch (p) {
    case 1: poly_ders_1(coef, x, a); break;
    case 2: poly_ders_2(coef, x, a); break;
    case 3: poly_ders_3(coef, x, a); break;
    case 4: poly_ders_4(coef, x, a); break;
    default: poly_ders_5(coef, x, a); break;
    }
    for (int k = 2; k <= PC_MAX_DERIV; ++k)
        for (int m = 0; m < 4; ++m)
            a[k][m] *= k_factorial[k];
}

void pc_nurbs_curve_eval(const pc_nurbs_curve *c, double t, int n_deriv, size_t *hint,
                         pc_vec3 *out)
{
    if (!(t >= c->t0))
        t = c->t0;
    if (t > c->t1)
        t = c->t1;
    n_deriv = n_deriv < 0 ? 0 : (n_deriv > PC_MAX_DERIV ? PC_MAX_DERIV : n_deriv);
    const size_t span = pc_knot_span(c->knots, c->n_ctrl, c->degree, t, hint ? *hint : 0);
    if (hint != NULL)
        *hint = span;
    double a[PC_MAX_DERIV + 1][4];
    if (c->poly != NULL) {
        poly_curve_ders(c, span, t, a);
    } else if (c->degree <= PC_SMALL_DEGREE) {
        small_curve_ders(c, span, t, n_deriv, a);
    } else {
        pc_basis basis;
        pc_basis_ders(c->knots, span, c->degree, t, n_deriv, &basis);
        contract(c->cw + 4 * (span - (size_t)c->degree), basis.d[0], PC_MAX_ORDER, c->degree,
                 n_deriv, a);
    }
    if (!c->rational) {
        for (int k = 0; k <= n_deriv; ++k)
            out[k] = vec3(a[k][0], a[k][1], a[k][2]);
        return;
    }
    /* Quotient rule: C^(k) = (A^(k) - sum_{i=1..k} binom(k,i) w^(i) C^(k-i)) / w
     * (The NURBS Book, eq. 4.8). */
    const double inv_w = 1.0 / a[0][3];
    for (int k = 0; k <= n_deriv; ++k) {
        pc_vec3 v = vec3(a[k][0], a[k][1], a[k][2]);
        for (int i = 1; i <= k; ++i)
            v = vec3_axpy(v, -k_binom[k][i] * a[i][3], out[k - i]);
        out[k] = vec3_scale(v, inv_w);
    }
}
