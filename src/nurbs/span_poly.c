/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Per-span monomial form of a surface, for the fast evaluators.
 *
 * On the span pair [u_k, u_k+1) x [v_l, v_l+1) the surface's homogeneous
 * map is a polynomial of degrees (p, q); written in powers of the local
 * offsets x = u - u_k and y = v - v_l,
 *     A(u, v) = sum_{i <= p, j <= q} C_ij x^i y^j,
 * it is evaluated with its derivatives by Horner's scheme with no basis
 * functions at all. The coefficients come from the monomial coefficients of
 * the B-spline basis functions on the span (Cox-de Boor's recurrence run on
 * polynomials), contracted with the control points. Offsets from the span
 * start keep the form as well conditioned as the B-spline form for the
 * small degrees it is used for.
 */
#include <stdlib.h>
#include <string.h>

#include "nurbs/span_poly.h"

/* coef[i][m]: coefficient of (t - knots[span])^m in N_{span-p+i}, the p + 1
 * basis functions nonzero on the span (The NURBS Book eq. 2.5 with each
 * function a polynomial on the span). */
static void span_basis_monomials(const double *knots, size_t span, int p,
                                 double coef[PC_POLY_ORDER][PC_POLY_ORDER])
{
    const double t0 = knots[span];
    memset(coef, 0, sizeof(double[PC_POLY_ORDER][PC_POLY_ORDER]));
    /* Degree 0: only N_span is 1 on the span; it sits at index p. */
    coef[p][0] = 1.0;
    for (int j = 1; j <= p; ++j) {
        /* Functions of degree j nonzero on the span: N_{span-j..span},
         * stored at indices p - j .. p. */
        for (int i = p - j; i <= p; ++i) {
            const size_t g = span - (size_t)p + (size_t)i; /* global index */
            double next[PC_POLY_ORDER] = {0};
            /* (t - U_g) / (U_{g+j} - U_g) N_{g,j-1}; t - U_g = x + (t0 - U_g). */
            if (i >= p - j + 1) {
                const double den = knots[g + (size_t)j] - knots[g];
                if (den > 0.0)
                    for (int m = 0; m < j; ++m) {
                        next[m + 1] += coef[i][m] / den;
                        next[m] += (t0 - knots[g]) * coef[i][m] / den;
                    }
            }
            /* (U_{g+j+1} - t) / (U_{g+j+1} - U_{g+1}) N_{g+1,j-1};
             * U_{g+j+1} - t = (U_{g+j+1} - t0) - x. */
            if (i + 1 <= p) {
                const double den = knots[g + (size_t)j + 1] - knots[g + 1];
                if (den > 0.0)
                    for (int m = 0; m < j; ++m) {
                        next[m] += (knots[g + (size_t)j + 1] - t0) * coef[i + 1][m] / den;
                        next[m + 1] -= coef[i + 1][m] / den;
                    }
            }
            memcpy(coef[i], next, sizeof next);
        }
    }
}

/* C_ij of one span pair, (p+1) x (q+1) homogeneous 4-vectors, i fastest. */
static void span_coefficients(const pc_nurbs_surface *s, size_t span_u, size_t span_v,
                              double *out)
{
    const int p = s->deg_u, q = s->deg_v;
    double bu[PC_POLY_ORDER][PC_POLY_ORDER], bv[PC_POLY_ORDER][PC_POLY_ORDER];
    span_basis_monomials(s->knots_u, span_u, p, bu);
    span_basis_monomials(s->knots_v, span_v, q, bv);
    const size_t first = (span_v - (size_t)q) * s->n_u + (span_u - (size_t)p);
    const size_t n = 4 * ((size_t)p + 1) * ((size_t)q + 1);
    memset(out, 0, n * sizeof(double));
    for (int b = 0; b <= q; ++b)
        for (int a = 0; a <= p; ++a) {
            const double *pt = s->cw + 4 * (first + (size_t)b * s->n_u + (size_t)a);
            for (int j = 0; j <= q; ++j)
                for (int i = 0; i <= p; ++i) {
                    const double w = bu[a][i] * bv[b][j];
                    double *c = out + 4 * ((size_t)j * ((size_t)p + 1) + (size_t)i);
                    for (int m = 0; m < 4; ++m)
                        c[m] += w * pt[m];
                }
        }
}

double *pc_span_polys_build(const pc_nurbs_surface *s, int *no_memory)
{
    *no_memory = 0;
    if (s->deg_u > PC_POLY_MAX_DEGREE || s->deg_v > PC_POLY_MAX_DEGREE)
        return NULL;
    const size_t spans_u = s->n_u - (size_t)s->deg_u, spans_v = s->n_v - (size_t)s->deg_v;
    const size_t per_span = pc_span_poly_len(s->deg_u, s->deg_v);
    const size_t total = pc_size_mul(pc_size_mul(spans_u, spans_v), per_span);
    if (total == 0 || total > PC_POLY_MAX_BYTES / sizeof(double))
        return NULL;
    double *poly = calloc(total, sizeof(double));
    if (poly == NULL) {
        *no_memory = 1;
        return NULL;
    }
    for (size_t kv = 0; kv < spans_v; ++kv) {
        const size_t span_v = kv + (size_t)s->deg_v;
        if (!(s->knots_v[span_v] < s->knots_v[span_v + 1]))
            continue; /* empty span: never evaluated */
        for (size_t ku = 0; ku < spans_u; ++ku) {
            const size_t span_u = ku + (size_t)s->deg_u;
            if (s->knots_u[span_u] < s->knots_u[span_u + 1])
                span_coefficients(s, span_u, span_v, poly + (kv * spans_u + ku) * per_span);
        }
    }
    return poly;
}

double *pc_curve_polys_build(const pc_nurbs_curve *c, int *no_memory)
{
    *no_memory = 0;
    if (c->degree > PC_POLY_MAX_DEGREE)
        return NULL;
    const int p = c->degree;
    const size_t spans = c->n_ctrl - (size_t)p, per_span = 4 * ((size_t)p + 1);
    double *poly = calloc(spans * per_span, sizeof(double));
    if (poly == NULL) {
        *no_memory = 1;
        return NULL;
    }
    for (size_t k = 0; k < spans; ++k) {
        const size_t span = k + (size_t)p;
        if (!(c->knots[span] < c->knots[span + 1]))
            continue; /* empty span: never evaluated */
        double basis[PC_POLY_ORDER][PC_POLY_ORDER];
        span_basis_monomials(c->knots, span, p, basis);
        double *out = poly + k * per_span;
        for (int a = 0; a <= p; ++a) {
            const double *pt = c->cw + 4 * (k + (size_t)a);
            for (int i = 0; i <= p; ++i)
                for (int m = 0; m < 4; ++m)
                    out[4 * i + m] += basis[a][i] * pt[m];
        }
    }
    return poly;
}
