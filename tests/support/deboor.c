/* SPDX-License-Identifier: BSD-3-Clause */
#include "deboor.h"

#include <stdlib.h>

#define DEBOOR_MAX_ORDER (PROJCURVE_MAX_DEGREE + 1)

/* Span k with knots[k] <= t < knots[k+1] within [p, n - 1], by a plain scan
 * (deliberately unlike the library's search); t = knots[n] uses the last
 * non-empty span. */
static size_t find_span(const double *knots, size_t n, int p, double t)
{
    size_t k = (size_t)p;
    for (size_t i = (size_t)p; i < n; ++i)
        if (knots[i] <= t && knots[i] < knots[i + 1])
            k = i;
    return k;
}

/* de Boor on points of `dim` doubles (dim <= 4). */
static void deboor_dim(const double *knots, size_t n, int p, size_t dim, const double *pts,
                       double t, double *out)
{
    const size_t k = find_span(knots, n, p, t);
    double d[DEBOOR_MAX_ORDER][4];
    for (size_t j = 0; j <= (size_t)p; ++j)
        for (size_t m = 0; m < dim; ++m)
            d[j][m] = pts[dim * (k - (size_t)p + j) + m];
    for (size_t r = 1; r <= (size_t)p; ++r)
        for (size_t j = (size_t)p; j >= r; --j) {
            const size_t i = j + k - (size_t)p;
            const double alpha = (t - knots[i]) / (knots[i + (size_t)p + 1 - r] - knots[i]);
            for (size_t m = 0; m < dim; ++m)
                d[j][m] = (1.0 - alpha) * d[j - 1][m] + alpha * d[j][m];
        }
    for (size_t m = 0; m < dim; ++m)
        out[m] = d[p][m];
}

/* The k-th derivative at t of the spline of degree p with n points of `dim`
 * doubles on `knots`: the control polygon is differentiated k times (The
 * NURBS Book eq. 3.8, P^(k)_i = (p - k + 1) (P^(k-1)_{i+1} - P^(k-1)_i) /
 * (u_{i+p+1} - u_{i+k}), degree p - k on the knots without the first and
 * last k) and de Boor runs on the result. A zero knot difference belongs to
 * a derivative basis function with empty support: its point is set to 0. */
static void deboor_derivative(const double *knots, size_t n, int p, size_t dim,
                              const double *pts, int k, double t, double *out)
{
    if (k > p) {
        for (size_t m = 0; m < dim; ++m)
            out[m] = 0.0;
        return;
    }
    double *d = malloc(n * dim * sizeof(double));
    for (size_t i = 0; i < n * dim; ++i)
        d[i] = pts[i];
    for (int level = 1; level <= k; ++level)
        for (size_t i = 0; i + (size_t)level < n; ++i) {
            const double du = knots[i + (size_t)p + 1] - knots[i + (size_t)level];
            const double f = du > 0.0 ? (double)(p - level + 1) / du : 0.0;
            for (size_t m = 0; m < dim; ++m)
                d[i * dim + m] = f * (d[(i + 1) * dim + m] - d[i * dim + m]);
        }
    deboor_dim(knots + k, n - (size_t)k, p - k, dim, d, t, out);
    free(d);
}

static void homogeneous(const double *ctrl, const double *weights, size_t i, double hw[4])
{
    const double w = weights != NULL ? weights[i] : 1.0;
    hw[0] = w * ctrl[3 * i];
    hw[1] = w * ctrl[3 * i + 1];
    hw[2] = w * ctrl[3 * i + 2];
    hw[3] = w;
}

static double binomial(int n, int k)
{
    double b = 1.0;
    for (int i = 1; i <= k; ++i)
        b = b * (double)(n - k + i) / (double)i;
    return b;
}

void pc_deboor_curve_ders(const pc_shape_curve *c, double t, int n_deriv, double *out)
{
    double *hw = malloc(4 * c->n_ctrl * sizeof(double));
    for (size_t i = 0; i < c->n_ctrl; ++i)
        homogeneous(c->ctrl, c->weights, i, hw + 4 * i);
    double a[PC_DEBOOR_MAX_DERIV + 1][4];
    for (int k = 0; k <= n_deriv; ++k)
        deboor_derivative(c->knots, c->n_ctrl, c->degree, 4, hw, k, t, a[k]);
    /* Quotient rule: C^(k) = (A^(k) - sum_i binom(k, i) w^(i) C^(k-i)) / w. */
    for (int k = 0; k <= n_deriv; ++k)
        for (int m = 0; m < 3; ++m) {
            double v = a[k][m];
            for (int i = 1; i <= k; ++i)
                v -= binomial(k, i) * a[i][3] * out[3 * (k - i) + m];
            out[3 * k + m] = v / a[0][3];
        }
    free(hw);
}

void pc_deboor_curve(const pc_shape_curve *c, double t, double out[3])
{
    pc_deboor_curve_ders(c, t, 0, out);
}

void pc_deboor_surface_ders(const pc_shape_surface *s, double u, double v, double out[18])
{
    double *row = malloc(4 * s->n_u * sizeof(double));
    double *col = malloc(3 * 4 * s->n_v * sizeof(double)); /* u-derivatives 0..2 per row */
    for (size_t j = 0; j < s->n_v; ++j) {
        for (size_t i = 0; i < s->n_u; ++i)
            homogeneous(s->ctrl, s->weights, j * s->n_u + i, row + 4 * i);
        for (int a = 0; a <= 2; ++a)
            deboor_derivative(s->knots_u, s->n_u, s->deg_u, 4, row, a, u,
                              col + 4 * ((size_t)a * s->n_v + j));
    }
    /* A[k][l] = d^(k+l) A / du^k dv^l, k + l <= 2. */
    double A[3][3][4], S[3][3][3];
    for (int k = 0; k <= 2; ++k)
        for (int l = 0; k + l <= 2; ++l)
            deboor_derivative(s->knots_v, s->n_v, s->deg_v, 4, col + 4 * (size_t)k * s->n_v, l, v,
                              A[k][l]);
    /* Quotient rule for surfaces (The NURBS Book eq. 4.20). */
    for (int k = 0; k <= 2; ++k)
        for (int l = 0; k + l <= 2; ++l)
            for (int m = 0; m < 3; ++m) {
                double x = A[k][l][m];
                for (int j = 1; j <= l; ++j)
                    x -= binomial(l, j) * A[0][j][3] * S[k][l - j][m];
                for (int i = 1; i <= k; ++i) {
                    x -= binomial(k, i) * A[i][0][3] * S[k - i][l][m];
                    for (int j = 1; j <= l; ++j)
                        x -= binomial(k, i) * binomial(l, j) * A[i][j][3] * S[k - i][l - j][m];
                }
                S[k][l][m] = x / A[0][0][3];
            }
    static const int order[6][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};
    for (int d = 0; d < 6; ++d)
        for (int m = 0; m < 3; ++m)
            out[3 * d + m] = S[order[d][0]][order[d][1]][m];
    free(row);
    free(col);
}

void pc_deboor_surface(const pc_shape_surface *s, double u, double v, double out[3])
{
    double all[18];
    pc_deboor_surface_ders(s, u, v, all);
    for (int m = 0; m < 3; ++m)
        out[m] = all[m];
}
