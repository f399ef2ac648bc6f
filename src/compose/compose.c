/*
 * Composition of a parameter-space line segment with a tensor-product Bezier
 * patch by blossoming (seed 000 s4, its refs [6] DeRose 1988 and [7] DeRose,
 * Goldman, Hagen & Mann 1993). See docs/refine_compose.md for the derivation.
 *
 * With local patch parameters x(s) = (1-s) x0 + s x1, y(s) = (1-s) y0 + s y1
 * and the patch's bi-blossom f(x_1..x_p ; y_1..y_q), the composed curve
 * C(s) = f(x(s)^p ; y(s)^q) has degree n = p + q and control points
 *
 *   R_k = sum_{a+b=k} [C(p,a) C(q,b) / C(n,k)] f(x0^{p-a} x1^a ; y0^{q-b} y1^b).
 *
 * The bi-blossom values H[a][b] = f(x0^{p-a} x1^a ; y0^{q-b} y1^b) are the
 * control net of the patch restricted to [x0,x1] x [y0,y1] (rows first, then
 * columns), computed with de Casteljau steps whose parameters lie in [0, 1]:
 * every operation is an affine combination, so the result is as accurate as
 * the patch evaluation itself. Homogeneous points make the rational case the
 * same code.
 */
#include "compose.h"

#include <string.h>

#include "projcurve.h"

/* Largest number of control points per direction of a patch. */
#define PC_COMPOSE_MAX_ORDER (PROJCURVE_MAX_DEGREE + 1)

/* Linear interpolation of homogeneous points: out = (1 - t) a + t b. */
static inline void lerp4(const double *a, const double *b, double t, double *out)
{
    const double s = 1.0 - t;
    for (int c = 0; c < 4; ++c)
        out[c] = s * a[c] + t * b[c];
}

/*
 * Blossom values of a degree-`deg` Bezier curve with homogeneous control
 * points in[0..deg] (point i at in + 4 * i * stride): writes
 * out[a] = f(x0^{deg-a} x1^a), a = 0..deg (at out + 4 * a * stride), i.e. the
 * control points of the curve restricted to [x0, x1]. `in` and `out` may be
 * the same array. O(deg^3), no allocation: the triangle at x1 is kept in
 * `tri` and, for each a, a second de Casteljau pass at x0 runs in `work`.
 */
static void restrict_curve(const double *in, size_t stride, int deg, double x0, double x1,
                           double *out)
{
    double tri[PC_COMPOSE_MAX_ORDER][4]; /* row a of the triangle at x1 */
    double work[PC_COMPOSE_MAX_ORDER][4];
    double result[PC_COMPOSE_MAX_ORDER][4];

    for (int i = 0; i <= deg; ++i)
        memcpy(tri[i], in + 4 * (size_t)i * stride, sizeof tri[i]);
    for (int a = 0; a <= deg; ++a) {
        /* tri[0..deg-a] is the control polygon of g(.) = f(x1^a, .), a curve
         * of degree deg - a: evaluate its blossom at x0^{deg-a}. */
        const int m = deg - a;
        memcpy(work, tri, sizeof work[0] * (size_t)(m + 1));
        for (int r = 1; r <= m; ++r)
            for (int i = 0; i <= m - r; ++i)
                lerp4(work[i], work[i + 1], x0, work[i]);
        memcpy(result[a], work[0], sizeof result[a]);
        /* Next row of the triangle: one more argument x1. */
        for (int i = 0; i < m; ++i)
            lerp4(tri[i], tri[i + 1], x1, tri[i]);
    }
    for (int a = 0; a <= deg; ++a)
        memcpy(out + 4 * (size_t)a * stride, result[a], sizeof result[a]);
}

/* Binomial coefficients C(n, 0..n) as doubles (exact for n <= 60). */
static void binomial_row(int n, double *row)
{
    row[0] = 1.0;
    for (int k = 1; k <= n; ++k)
        row[k] = row[k - 1] * (double)(n - k + 1) / (double)k;
}

void pc_compose_segment(const pc_bezier_patch *patch, const double uv0[2], const double uv1[2],
                        double *cw_out)
{
    const int p = patch->deg_u, q = patch->deg_v, n = p + q;
    const double du = patch->u1 - patch->u0, dv = patch->v1 - patch->v0;
    const double x0 = (uv0[0] - patch->u0) / du, x1 = (uv1[0] - patch->u0) / du;
    const double y0 = (uv0[1] - patch->v0) / dv, y1 = (uv1[1] - patch->v0) / dv;
    /* H[b][a] (u index fastest, as the patch net) = f(x0^{p-a} x1^a ; y0^{q-b} y1^b). */
    double net[PC_COMPOSE_MAX_ORDER * PC_COMPOSE_MAX_ORDER * 4];
    const size_t row = (size_t)(p + 1);

    memcpy(net, patch->cw, sizeof(double) * 4 * row * (size_t)(q + 1));
    for (int b = 0; b <= q; ++b)           /* restrict every u-row to [x0, x1] */
        restrict_curve(net + 4 * row * (size_t)b, 1, p, x0, x1, net + 4 * row * (size_t)b);
    for (int a = 0; a <= p; ++a)           /* then every v-column to [y0, y1] */
        restrict_curve(net + 4 * (size_t)a, row, q, y0, y1, net + 4 * (size_t)a);

    double cp[PC_COMPOSE_MAX_ORDER], cq[PC_COMPOSE_MAX_ORDER], cn[2 * PC_COMPOSE_MAX_ORDER];
    binomial_row(p, cp);
    binomial_row(q, cq);
    binomial_row(n, cn);
    for (int k = 0; k <= n; ++k) {
        double *r = cw_out + 4 * (size_t)k;
        r[0] = r[1] = r[2] = r[3] = 0.0;
        const int a_lo = k > q ? k - q : 0, a_hi = k < p ? k : p;
        for (int a = a_lo; a <= a_hi; ++a) {
            const int b = k - a;
            const double weight = cp[a] * cq[b] / cn[k];
            const double *h = net + 4 * (row * (size_t)b + (size_t)a);
            for (int c = 0; c < 4; ++c)
                r[c] += weight * h[c];
        }
    }
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
