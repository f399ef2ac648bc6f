/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Composition of a polynomial parameter curve (u, v)(s), s in [0, 1], of
 * degree d (Bezier control points in (u, v)) with a tensor-product Bezier
 * patch of degree (p, q): the result S(u(s), v(s)) is a Bezier curve of
 * degree d (p + q), exactly on S (rational when the patch is: homogeneous
 * control points make it the same code). See docs/refine_compose.md.
 *
 * With local patch parameters x(s) = (u(s) - u0) / (u1 - u0) and y(s)
 * likewise, both degree-d Bernstein polynomials,
 *
 *   C(s) = sum_j [ sum_i P_ij B_i^p(x(s)) ] B_j^q(y(s)),
 *
 * and every factor is a polynomial in s kept in Bernstein form:
 * B_i^p(x) = C(p, i) x^i (1 - x)^(p - i), where x^a and (1 - x)^a come from
 * repeated Bernstein products. The product of f = sum a_i B_i^m and
 * g = sum b_j B_j^n is
 *
 *   f g = sum_k [ sum_{i+j=k} C(m, i) C(n, j) / C(m + n, k) a_i b_j ] B_k^(m+n)
 *
 * (Farouki & Rajan 1988). When the pcurve's control points lie in the
 * patch's box, x and 1 - x have non-negative Bernstein coefficients, so every
 * basis product is a sum of non-negative terms: no cancellation, and C's
 * control points are as accurate as an evaluation of the patch. For d = 1
 * this is the same curve as pc_compose_segment's blossoming.
 *
 * A rational pcurve x = X / W (X, W with Bernstein coefficients w_k x_k
 * and w_k, weights w_k > 0) composes the same way: B_i^p(x) W^p =
 * C(p, i) X^i (W - X)^(p - i), so x and 1 - x are replaced by X and
 * W - X (coefficients w_k x_k and w_k (1 - x_k), non-negative still), and
 * the homogeneous result is C times the scalar W^(p + q): the same
 * rational curve, of the same degree d (p + q).
 */
#include "compose.h"

#include "common/compiler.h"

#include "projcurve.h"

/* Largest pcurve degree and largest composed degree. */
#define PC_POLY_MAX_ORDER (PROJCURVE_MAX_DEGREE + 1)
#define PC_POLY_MAX_COEFS (2 * PROJCURVE_MAX_DEGREE + 1)
/* Patches up to this order per direction with a cubic pcurve use small stack
 * tables (bicubic is 4); the large ones cost page probes on every call. */
#define PC_POLY_SMALL_ORDER 8
#define PC_POLY_SMALL_COEFS (PC_COMPOSE_POLY_MAX_DEGREE * (PC_POLY_SMALL_ORDER - 1) + 1)


/* Scratch tables, `stride` doubles per row: pow_x and pow_1x hold x^a and
 * (1 - x)^a for a = 0..max(p, q) (degree d a), basis_u the B_i^p(x(s)) and
 * basis_v the B_j^q(y(s)); row holds one H_j(s) (4 doubles per coefficient);
 * binom is Pascal's triangle up to the composed degree, row m at
 * m (m + 1) / 2. */
typedef struct poly_scratch {
    size_t stride;
    double *pow_x, *pow_1x, *basis_u, *basis_v, *row, *binom;
} poly_scratch;

/* Size of Pascal's triangle with rows 0..n. */
#define PC_POLY_TRIANGLE(n) (((n) + 1) * ((n) + 2) / 2)

/* Rows 0..n of Pascal's triangle by additions: exact up to n = 56 (every
 * entry below 2^53), within a few ulps beyond. No divisions. */
static void pascal_triangle(int n, double *binom)
{
    binom[0] = 1.0;
    for (int m = 1; m <= n; ++m) {
        double *row = binom + m * (m + 1) / 2;
        const double *prev = binom + (m - 1) * m / 2;
        row[0] = row[m] = 1.0;
        for (int k = 1; k < m; ++k)
            row[k] = prev[k - 1] + prev[k];
    }
}

static const double *binomials(const poly_scratch *w, int n)
{
    return w->binom + n * (n + 1) / 2;
}

/* Bernstein product of scalar polynomials a (degree m) and b (degree n)
 * into out (degree m + n; must not alias a or b). */
static PC_ALWAYS_INLINE void bernstein_product(const poly_scratch *w, int m, const double *a, int n,
                              const double *b, double *out)
{
    const double *cm = binomials(w, m), *cn = binomials(w, n), *cmn = binomials(w, m + n);
    double sb[PC_POLY_MAX_COEFS];
    for (int j = 0; j <= n; ++j)
        sb[j] = cn[j] * b[j];
    for (int k = 0; k <= m + n; ++k)
        out[k] = 0.0;
    for (int i = 0; i <= m; ++i) {
        const double sa = cm[i] * a[i];
        for (int j = 0; j <= n; ++j)
            out[i + j] += sa * sb[j];
    }
    for (int k = 0; k <= m + n; ++k)
        out[k] /= cmn[k];
}

/* Bernstein coefficients of B_i^deg(x(s)), i = 0..deg, each of degree
 * d deg, into basis (row i), where x(s) has the d + 1 coefficients x and
 * 1 - x(s) the coefficients one_minus (for a rational pcurve, those of
 * X and W - X: then the rows are B_i^deg(x) W^deg). */
static PC_ALWAYS_INLINE void basis_of(int d, const double *x, const double *one_minus, int deg,
                                      poly_scratch *w, double *basis)
{
    const size_t st = w->stride;
    w->pow_x[0] = w->pow_1x[0] = 1.0;
    for (int a = 1; a <= deg; ++a) {
        bernstein_product(w, d * (a - 1), w->pow_x + (size_t)(a - 1) * st, d, x,
                          w->pow_x + (size_t)a * st);
        bernstein_product(w, d * (a - 1), w->pow_1x + (size_t)(a - 1) * st, d, one_minus,
                          w->pow_1x + (size_t)a * st);
    }
    const double *c = binomials(w, deg);
    for (int i = 0; i <= deg; ++i) {
        double *out = basis + (size_t)i * st;
        bernstein_product(w, d * i, w->pow_x + (size_t)i * st, d * (deg - i),
                          w->pow_1x + (size_t)(deg - i) * st, out);
        for (int k = 0; k <= d * deg; ++k)
            out[k] *= c[i];
    }
}

/* Cloned per instruction set: with AVX each homogeneous point is one
 * register, and the products below are one multiply-add per term. */
static PC_HOT_CLONES void compose_poly_with(const pc_bezier_patch *patch, int d,
                                            const double *uv_ctrl, const double *weights,
                                            double *cw_out, poly_scratch *w)
{
    const int p = patch->deg_u, q = patch->deg_v, nu = d * p, nv = d * q, n = nu + nv;
    const size_t st = w->stride, pu = (size_t)(p + 1);
    const double du = patch->u1 - patch->u0, dv = patch->v1 - patch->v0;
    double x[PC_COMPOSE_POLY_MAX_DEGREE + 1], y[PC_COMPOSE_POLY_MAX_DEGREE + 1];
    double x1[PC_COMPOSE_POLY_MAX_DEGREE + 1], y1[PC_COMPOSE_POLY_MAX_DEGREE + 1];
    for (int k = 0; k <= d; ++k) {
        const double wk = weights != NULL ? weights[k] : 1.0;
        const double xk = (uv_ctrl[2 * k] - patch->u0) / du;
        const double yk = (uv_ctrl[2 * k + 1] - patch->v0) / dv;
        x[k] = wk * xk;
        x1[k] = wk * (1.0 - xk);
        y[k] = wk * yk;
        y1[k] = wk * (1.0 - yk);
    }
    pascal_triangle(n, w->binom);
    basis_of(d, x, x1, p, w, w->basis_u);
    basis_of(d, y, y1, q, w, w->basis_v);

    /* C = sum_j H_j Bv_j with H_j = sum_i P_ij Bu_i: the product's binomial
     * weights split as C(nu, a) on H, C(nv, b) on Bv and 1 / C(n, k) at the
     * end, so the inner loop is plain multiply-adds. */
    const double *cu = binomials(w, nu), *cv = binomials(w, nv), *cn = binomials(w, n);
    for (int k = 0; k <= n; ++k)
        for (int c = 0; c < 4; ++c)
            cw_out[4 * k + c] = 0.0;
    for (int j = 0; j <= q; ++j) {
        const double *pj = patch->cw + 4 * pu * (size_t)j;
        for (int a = 0; a <= nu; ++a) {
            double h[4] = {0.0, 0.0, 0.0, 0.0};
            for (size_t i = 0; i < pu; ++i) {
                const double m = w->basis_u[i * st + (size_t)a];
                for (int c = 0; c < 4; ++c)
                    h[c] += m * pj[4 * i + (size_t)c];
            }
            for (int c = 0; c < 4; ++c)
                w->row[4 * a + c] = cu[a] * h[c];
        }
        const double *bv = w->basis_v + (size_t)j * st;
        double sbv[PC_POLY_MAX_COEFS];
        for (int b = 0; b <= nv; ++b)
            sbv[b] = cv[b] * bv[b];
        for (int a = 0; a <= nu; ++a) {
            /* restrict: the output never overlaps the row, so the four
             * coordinates go as one vector */
            const double *restrict h = w->row + 4 * a;
            double *restrict r = cw_out + 4 * a;
            for (int b = 0; b <= nv; ++b)
                for (int c = 0; c < 4; ++c)
                    r[4 * b + c] += sbv[b] * h[c];
        }
    }
    for (int k = 0; k <= n; ++k)
        for (int c = 0; c < 4; ++c)
            cw_out[4 * k + c] /= cn[k];
}

/* Patches of high degree: tables for the largest sizes. */
static PC_NOINLINE void compose_poly_large(const pc_bezier_patch *patch, int d,
                                           const double *uv_ctrl, const double *weights,
                                           double *cw_out)
{
    double pow_x[PC_POLY_MAX_ORDER * PC_POLY_MAX_COEFS];
    double pow_1x[PC_POLY_MAX_ORDER * PC_POLY_MAX_COEFS];
    double basis_u[PC_POLY_MAX_ORDER * PC_POLY_MAX_COEFS];
    double basis_v[PC_POLY_MAX_ORDER * PC_POLY_MAX_COEFS];
    double row[4 * PC_POLY_MAX_COEFS];
    double binom[PC_POLY_TRIANGLE(PC_POLY_MAX_COEFS - 1)];
    poly_scratch w = {PC_POLY_MAX_COEFS, pow_x, pow_1x, basis_u, basis_v, row, binom};
    compose_poly_with(patch, d, uv_ctrl, weights, cw_out, &w);
}

int pc_compose_poly(const pc_bezier_patch *patch, int degree, const double *uv_ctrl,
                    double *cw_out)
{
    return pc_compose_poly_weighted(patch, degree, uv_ctrl, NULL, cw_out);
}

int pc_compose_poly_weighted(const pc_bezier_patch *patch, int degree, const double *uv_ctrl,
                             const double *weights, double *cw_out)
{
    const int p = patch->deg_u, q = patch->deg_v;
    if (degree < 1 || degree > PC_COMPOSE_POLY_MAX_DEGREE ||
        degree * (p + q) > 2 * PROJCURVE_MAX_DEGREE)
        return -1;
    if (p >= PC_POLY_SMALL_ORDER || q >= PC_POLY_SMALL_ORDER) {
        compose_poly_large(patch, degree, uv_ctrl, weights, cw_out);
        return degree * (p + q);
    }
    double pow_x[PC_POLY_SMALL_ORDER * PC_POLY_SMALL_COEFS];
    double pow_1x[PC_POLY_SMALL_ORDER * PC_POLY_SMALL_COEFS];
    double basis_u[PC_POLY_SMALL_ORDER * PC_POLY_SMALL_COEFS];
    double basis_v[PC_POLY_SMALL_ORDER * PC_POLY_SMALL_COEFS];
    double row[4 * PC_POLY_SMALL_COEFS];
    double binom[PC_POLY_TRIANGLE(2 * (PC_POLY_SMALL_COEFS - 1))];
    poly_scratch w = {PC_POLY_SMALL_COEFS, pow_x, pow_1x, basis_u, basis_v, row, binom};
    compose_poly_with(patch, degree, uv_ctrl, weights, cw_out, &w);
    return degree * (p + q);
}
