/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Composition of a parameter-space line segment with a tensor-product Bezier
 * patch by blossoming ([SY13] s4, its refs [6] DeRose 1988 and [7] DeRose,
 * Goldman, Hagen & Mann 1993). See docs/refine_compose.md for the derivation.
 *
 * With local patch parameters x(s) = (1-s) x0 + s x1, y(s) = (1-s) y0 + s y1
 * and the patch's bi-blossom f(x_1..x_p ; y_1..y_q), the composed curve
 * C(s) = f(x(s)^p ; y(s)^q) has degree n = p + q and control points
 *
 *   R_k = sum_{a+b=k} [C(p,a) C(q,b) / C(n,k)] f(x0^{p-a} x1^a ; y0^{q-b} y1^b).
 *
 * The bi-blossom values H[a][b] = f(x0^{p-a} x1^a ; y0^{q-b} y1^b) are the
 * control net of the patch restricted to [x0,x1] x [y0,y1]; by linearity they
 * are H = Au^T P Av with the restriction matrices of the two Bernstein bases
 * (the blossoms of the basis functions, see restriction_matrix). Every weight
 * is non-negative and each set sums to 1, so the result is a chain of convex
 * combinations of the control points: as accurate as evaluating the patch.
 * Homogeneous points make the rational case the same code.
 */
#include "compose.h"

#include "common/compiler.h"
#include "projcurve.h"

/* Largest number of control points per direction of a patch. */
#define PC_COMPOSE_MAX_ORDER (PROJCURVE_MAX_DEGREE + 1)
/* Patches up to this order per direction (bicubic is 4) use small stack
 * buffers: the large ones cost page probes and cache misses on every call. */
#define PC_COMPOSE_SMALL_ORDER 8

/*
 * Restriction matrix of the degree-p Bernstein basis to [x0, x1]:
 * A[i * (p + 1) + a] = blossom of B_i^p at (x0^{p-a}, x1^a), so that the
 * control points of a curve restricted to [x0, x1] are
 * f(x0^{p-a} x1^a) = sum_i A[i][a] b_i. The blossom of B_i^p at (t_1..t_p)
 * is the coefficient of z^i in prod_k ((1 - t_k) + t_k z): a product of
 * linear factors with non-negative coefficients for x0, x1 in [0, 1], so
 * every entry is a sum of non-negative terms and each column sums to 1.
 */
static PC_ALWAYS_INLINE void restriction_matrix(int p, double x0, double x1, double *A)
{
    const size_t order = (size_t)(p + 1);
    for (int a = 0; a <= p; ++a) {
        double poly[PC_COMPOSE_MAX_ORDER];
        int len = 1;
        poly[0] = 1.0;
        for (int k = 0; k < p; ++k, ++len) { /* multiply by (1 - x) + x z */
            const double x = k < a ? x1 : x0, r = 1.0 - x;
            poly[len] = poly[len - 1] * x;
            for (int j = len - 1; j > 0; --j)
                poly[j] = poly[j] * r + poly[j - 1] * x;
            poly[0] *= r;
        }
        for (int i = 0; i <= p; ++i)
            A[(size_t)i * order + (size_t)a] = poly[i];
    }
}

/* Binomial coefficients C(n, 0..n) by Pascal's rule: additions only, exact
 * for n <= 56, and constants once n is. */
static PC_ALWAYS_INLINE void binomial_row(int n, double *row)
{
    row[0] = 1.0;
    for (int m = 1; m <= n; ++m) {
        row[m] = 1.0;
        for (int k = m - 1; k > 0; --k)
            row[k] += row[k - 1];
    }
}

/* The composition for the patch's degrees p, q (constants in the
 * specialised callers) with caller-provided scratch: au (p+1)^2, av (q+1)^2
 * and net 4 (p+1)(q+1) doubles. */
static PC_ALWAYS_INLINE void compose_with(const pc_bezier_patch *patch, const int p, const int q,
                                          const double uv0[2], const double uv1[2],
                                          double *cw_out, double *au, double *av, double *net)
{
    const int n = p + q;
    const size_t pu = (size_t)(p + 1), pv = (size_t)(q + 1);
    const double du = patch->u1 - patch->u0, dv = patch->v1 - patch->v0;
    restriction_matrix(p, (uv0[0] - patch->u0) / du, (uv1[0] - patch->u0) / du, au);
    restriction_matrix(q, (uv0[1] - patch->v0) / dv, (uv1[1] - patch->v0) / dv, av);

    /* net[b][a] = H[a][b] = f(x0^{p-a} x1^a ; y0^{q-b} y1^b)
     *           = sum_j av[j][b] sum_i au[i][a] P_ij: each row j of the
     * patch is restricted in u, then spread over the H[.][b]. */
    for (size_t k = 0; k < 4 * pu * pv; ++k)
        net[k] = 0.0;
    for (size_t j = 0; j < pv; ++j) {
        const double *pj = patch->cw + 4 * pu * j;
        for (size_t a = 0; a < pu; ++a) {
            double x = 0.0, y = 0.0, z = 0.0, w = 0.0;
            for (size_t i = 0; i < pu; ++i) {
                const double m = au[i * pu + a];
                const double *c = pj + 4 * i;
                x += m * c[0];
                y += m * c[1];
                z += m * c[2];
                w += m * c[3];
            }
            for (size_t b = 0; b < pv; ++b) {
                const double m = av[j * pv + b];
                double *h = net + 4 * (pu * b + a);
                h[0] += m * x;
                h[1] += m * y;
                h[2] += m * z;
                h[3] += m * w;
            }
        }
    }

    /* R_k = sum_{a+b=k} C(p,a) C(q,b) / C(n,k) H[a][b] */
    double cp[PC_COMPOSE_MAX_ORDER], cq[PC_COMPOSE_MAX_ORDER], cn[2 * PC_COMPOSE_MAX_ORDER];
    binomial_row(p, cp);
    binomial_row(q, cq);
    binomial_row(n, cn);
    for (int k = 0; k <= n; ++k) {
        double *r = cw_out + 4 * (size_t)k;
        double x = 0.0, y = 0.0, z = 0.0, w = 0.0;
        const int a_lo = k > q ? k - q : 0, a_hi = k < p ? k : p;
        for (int a = a_lo; a <= a_hi; ++a) {
            const int b = k - a;
            const double weight = cp[a] * cq[b];
            const double *h = net + 4 * (pu * (size_t)b + (size_t)a);
            x += weight * h[0];
            y += weight * h[1];
            z += weight * h[2];
            w += weight * h[3];
        }
        const double inv = 1.0 / cn[k];
        r[0] = x * inv;
        r[1] = y * inv;
        r[2] = z * inv;
        r[3] = w * inv;
    }
}

/* The composition at constant degrees (P, Q): the loops unroll and the
 * binomial weights fold into constants. */
#define PC_COMPOSE_FIXED(P, Q)                                                               \
    static PC_HOT_CLONES void compose_##P##Q(const pc_bezier_patch *patch,                   \
                                             const double uv0[2], const double uv1[2],       \
                                             double *cw_out)                                 \
    {                                                                                        \
        double au[(P + 1) * (P + 1)], av[(Q + 1) * (Q + 1)], net[4 * (P + 1) * (Q + 1)];     \
        compose_with(patch, P, Q, uv0, uv1, cw_out, au, av, net);                            \
    }
PC_COMPOSE_FIXED(3, 3)
PC_COMPOSE_FIXED(5, 5)

/* Patches of high degree: buffers for the largest order. */
static PC_NOINLINE void compose_large(const pc_bezier_patch *patch, const double uv0[2],
                                          const double uv1[2], double *cw_out)
{
    double au[PC_COMPOSE_MAX_ORDER * PC_COMPOSE_MAX_ORDER];
    double av[PC_COMPOSE_MAX_ORDER * PC_COMPOSE_MAX_ORDER];
    double net[4 * PC_COMPOSE_MAX_ORDER * PC_COMPOSE_MAX_ORDER];
    compose_with(patch, patch->deg_u, patch->deg_v, uv0, uv1, cw_out, au, av, net);
}

/* Other small degrees: buffers of PC_COMPOSE_SMALL_ORDER. */
static PC_NOINLINE void compose_small(const pc_bezier_patch *patch, const double uv0[2],
                                          const double uv1[2], double *cw_out)
{
    double au[PC_COMPOSE_SMALL_ORDER * PC_COMPOSE_SMALL_ORDER];
    double av[PC_COMPOSE_SMALL_ORDER * PC_COMPOSE_SMALL_ORDER];
    double net[4 * PC_COMPOSE_SMALL_ORDER * PC_COMPOSE_SMALL_ORDER];
    compose_with(patch, patch->deg_u, patch->deg_v, uv0, uv1, cw_out, au, av, net);
}

void pc_compose_segment(const pc_bezier_patch *patch, const double uv0[2], const double uv1[2],
                        double *cw_out)
{
    const int p = patch->deg_u, q = patch->deg_v;
    if (p == 3 && q == 3)
        compose_33(patch, uv0, uv1, cw_out);
    else if (p == 5 && q == 5)
        compose_55(patch, uv0, uv1, cw_out);
    else if (p >= PC_COMPOSE_SMALL_ORDER || q >= PC_COMPOSE_SMALL_ORDER)
        compose_large(patch, uv0, uv1, cw_out);
    else
        compose_small(patch, uv0, uv1, cw_out);
}

void pc_compose_to_cartesian(int degree, const double *cw, double *ctrl, double *weights)
{
    for (int k = 0; k <= degree; ++k) {
        const double *h = cw + 4 * (size_t)k;
        const double w = h[3];
        ctrl[3 * k] = h[0] / w;
        ctrl[3 * k + 1] = h[1] / w;
        ctrl[3 * k + 2] = h[2] / w;
        weights[k] = w;
    }
}
