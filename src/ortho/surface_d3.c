/* SPDX-License-Identifier: BSD-3-Clause */
#include "ortho/surface_d3.h"

#include "nurbs/span_poly.h"

/* Derivative order evaluated here (pc_basis_ders computes up to
 * PC_MAX_DERIV). */
#define D3_ORDER 3
_Static_assert(D3_ORDER <= PC_MAX_DERIV, "nurbs/ basis derivatives must reach order 3");

static double clamp(double x, double lo, double hi) { return x < lo ? lo : (x > hi ? hi : x); }

/* Output slot of the derivative of order (k in u, l in v), k + l <= 3. */
static int slot(int k, int l)
{
    static const int table[D3_ORDER + 1][D3_ORDER + 1] = {
        {PC_D3_S, PC_D3_V, PC_D3_VV, PC_D3_VVV},
        {PC_D3_U, PC_D3_UV, PC_D3_UVV, -1},
        {PC_D3_UU, PC_D3_UUV, -1, -1},
        {PC_D3_UUU, -1, -1, -1},
    };
    return table[k][l];
}

static double binomial3(int n, int k)
{
    static const double table[D3_ORDER + 1][D3_ORDER + 1] = {
        {1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
    return table[n][k];
}

/* Derivatives of the homogeneous surface A(u, v) = sum N_i N_j Pw_ij:
 * aw[k][l] (4 doubles) for k + l <= 3. */
static void homogeneous_derivatives(const pc_nurbs_surface *s, size_t span_u, size_t span_v,
                                    const pc_basis *nu, const pc_basis *nv,
                                    double aw[D3_ORDER + 1][D3_ORDER + 1][4])
{
    for (int k = 0; k <= D3_ORDER; ++k)
        for (int l = 0; l <= D3_ORDER; ++l)
            for (int c = 0; c < 4; ++c)
                aw[k][l][c] = 0.0;

    const size_t i0 = span_u - (size_t)s->deg_u, j0 = span_v - (size_t)s->deg_v;
    for (int i = 0; i <= s->deg_u; ++i) {
        /* Column sums along v for this u index: tmp[l] = sum_j N_j^(l) Pw_ij. */
        double tmp[D3_ORDER + 1][4] = {{0}};
        for (int j = 0; j <= s->deg_v; ++j) {
            const double *pw = s->cw + 4 * ((j0 + (size_t)j) * s->n_u + i0 + (size_t)i);
            for (int l = 0; l <= D3_ORDER; ++l)
                for (int c = 0; c < 4; ++c)
                    tmp[l][c] += nv->d[l][j] * pw[c];
        }
        for (int k = 0; k <= D3_ORDER; ++k)
            for (int l = 0; k + l <= D3_ORDER; ++l)
                for (int c = 0; c < 4; ++c)
                    aw[k][l][c] += nu->d[k][i] * tmp[l][c];
    }
}

/* Scaled x-derivatives b[d] = (1/d!) d^d f / dx^d, d <= 3, of the degree-n
 * polynomial with 4-vector coefficients c[0], c[stride], ... at x, by
 * Horner's scheme carried to the derivatives. */
static void horner_d3(const double *c, size_t stride, int n, double x,
                      double b[D3_ORDER + 1][4])
{
    for (int d = 0; d <= D3_ORDER; ++d)
        for (int m = 0; m < 4; ++m)
            b[d][m] = 0.0;
    for (int k = n; k >= 0; --k) {
        const double *ck = c + (size_t)k * stride;
        for (int d = D3_ORDER; d >= 1; --d)
            for (int m = 0; m < 4; ++m)
                b[d][m] = b[d][m] * x + b[d - 1][m];
        for (int m = 0; m < 4; ++m)
            b[0][m] = b[0][m] * x + ck[m];
    }
}

/* Homogeneous derivatives aw[k][l] (k + l <= 3) from the span pair's
 * monomial form (nurbs/span_poly.h: coefficient of x^i y^j at
 * 4 (j (p + 1) + i), x and y the offsets from the span's start): Horner in
 * x along each row, then in y on each x-derivative order. */
static void monomial_derivatives(const double *c, int p, int q, double x, double y,
                                 double aw[D3_ORDER + 1][D3_ORDER + 1][4])
{
    double rows[D3_ORDER + 1][PC_POLY_ORDER][4];
    for (int j = 0; j <= q; ++j) {
        double b[D3_ORDER + 1][4];
        horner_d3(c + 4 * (size_t)j * ((size_t)p + 1), 4, p, x, b);
        for (int d = 0; d <= D3_ORDER; ++d)
            for (int m = 0; m < 4; ++m)
                rows[d][j][m] = b[d][m];
    }
    static const double factorial[D3_ORDER + 1] = {1.0, 1.0, 2.0, 6.0};
    for (int k = 0; k <= D3_ORDER; ++k) {
        double b[D3_ORDER + 1][4];
        horner_d3(rows[k][0], 4, q, y, b);
        for (int l = 0; k + l <= D3_ORDER; ++l)
            for (int m = 0; m < 4; ++m)
                aw[k][l][m] = factorial[k] * factorial[l] * b[l][m];
    }
}

/* The quotient rule for S = A / w (The NURBS Book, algorithm A4.4), in
 * order of total degree so that every S_(k-i, l-j) used is already known. */
static void rational_derivatives(double aw[D3_ORDER + 1][D3_ORDER + 1][4],
                                 pc_vec3 out[PC_D3_COUNT])
{
    const double w = aw[0][0][3];
    for (int order = 0; order <= D3_ORDER; ++order) {
        for (int k = order; k >= 0; --k) {
            const int l = order - k;
            pc_vec3 acc = vec3(aw[k][l][0], aw[k][l][1], aw[k][l][2]);
            for (int i = 0; i <= k; ++i)
                for (int j = 0; j <= l; ++j) {
                    if (i == 0 && j == 0)
                        continue;
                    const double c = binomial3(k, i) * binomial3(l, j) * aw[i][j][3];
                    acc = vec3_axpy(acc, -c, out[slot(k - i, l - j)]);
                }
            out[slot(k, l)] = vec3_scale(acc, 1.0 / w);
        }
    }
}

void pc_surface_eval_d3(const pc_nurbs_surface *s, double u, double v, size_t *hint_u,
                        size_t *hint_v, pc_vec3 out[PC_D3_COUNT])
{
    u = clamp(u, s->domain[0], s->domain[1]);
    v = clamp(v, s->domain[2], s->domain[3]);
    const size_t span_u = pc_knot_span(s->knots_u, s->n_u, s->deg_u, u, hint_u ? *hint_u : 0);
    const size_t span_v = pc_knot_span(s->knots_v, s->n_v, s->deg_v, v, hint_v ? *hint_v : 0);
    if (hint_u)
        *hint_u = span_u;
    if (hint_v)
        *hint_v = span_v;

    double aw[D3_ORDER + 1][D3_ORDER + 1][4];
    const int p = s->deg_u, q = s->deg_v;
    if (s->poly != NULL) {
        const size_t index = (span_v - (size_t)q) * (s->n_u - (size_t)p) + (span_u - (size_t)p);
        monomial_derivatives(s->poly + index * pc_span_poly_len(p, q), p, q,
                             u - s->knots_u[span_u], v - s->knots_v[span_v], aw);
    } else {
        /* degrees above 5: the basis functions' derivatives (nurbs/) */
        pc_basis nu, nv;
        pc_basis_ders(s->knots_u, span_u, p, u, D3_ORDER, &nu);
        pc_basis_ders(s->knots_v, span_v, q, v, D3_ORDER, &nv);
        homogeneous_derivatives(s, span_u, span_v, &nu, &nv, aw);
    }
    if (s->rational) {
        rational_derivatives(aw, out);
        return;
    }
    /* Every weight is 1: S = A. */
    for (int k = 0; k <= D3_ORDER; ++k)
        for (int l = 0; k + l <= D3_ORDER; ++l)
            out[slot(k, l)] = vec3(aw[k][l][0], aw[k][l][1], aw[k][l][2]);
}
