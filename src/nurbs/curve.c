/*
 * NURBS curves: creation from user arrays and evaluation with derivatives.
 */
#include <stdlib.h>
#include <string.h>

#include "common/error.h"
#include "nurbs/input.h"
#include "nurbs/nurbs.h"

projcurve_status pc_nurbs_curve_init(projcurve_context *ctx, pc_nurbs_curve *c, int degree,
                                     size_t n_ctrl, const double *ctrl, const double *weights,
                                     const double *knots)
{
    projcurve_status st = pc_input_check_degree(ctx, "degree", degree, n_ctrl);
    if (st == PROJCURVE_OK)
        st = pc_input_check_sizes(ctx, degree, n_ctrl, 0, 1);
    if (st == PROJCURVE_OK)
        st = pc_knots_validate(ctx, "knot vector", degree, n_ctrl, knots);
    pc_spline_batch b = {degree, n_ctrl, 4, 1, NULL, NULL};
    int rational = 0;
    if (st == PROJCURVE_OK)
        st = pc_input_homogeneous(ctx, n_ctrl, ctrl, weights, &b.pts, &rational);
    if (st != PROJCURVE_OK)
        return st;
    const size_t n_knots = n_ctrl + (size_t)degree + 1;
    b.knots = malloc(n_knots * sizeof(double));
    if (b.knots == NULL) {
        free(b.pts);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for %zu knots", n_knots);
    }
    memcpy(b.knots, knots, n_knots * sizeof(double));
    if (!pc_knots_are_clamped(b.knots, n_ctrl, degree)) {
        st = pc_spline_batch_clamp(ctx, &b);
        if (st != PROJCURVE_OK) {
            free(b.knots);
            free(b.pts);
            return st;
        }
    }
    c->degree = degree;
    c->n_ctrl = b.n_ctrl;
    c->knots = b.knots;
    c->cw = b.pts;
    c->rational = rational;
    c->t0 = b.knots[degree];
    c->t1 = b.knots[b.n_ctrl];
    return PROJCURVE_OK;
}

void pc_nurbs_curve_free(pc_nurbs_curve *c)
{
    if (c == NULL)
        return;
    free(c->knots);
    free(c->cw);
    c->knots = NULL;
    c->cw = NULL;
}

/* Binomial coefficients up to 3 for the quotient rule. */
static const double k_binom[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};

void pc_nurbs_curve_eval(const pc_nurbs_curve *c, double t, int n_deriv, size_t *hint,
                         pc_vec3 *out)
{
    if (!(t >= c->t0))
        t = c->t0;
    if (t > c->t1)
        t = c->t1;
    const size_t span = pc_knot_span(c->knots, c->n_ctrl, c->degree, t, hint ? *hint : 0);
    if (hint != NULL)
        *hint = span;
    pc_basis basis;
    pc_basis_ders(c->knots, span, c->degree, t, n_deriv, &basis);
    double(*ders)[PC_MAX_ORDER] = basis.d;

    /* Homogeneous derivatives A^(k) (xyz) and w^(k). */
    double a[PC_MAX_DERIV + 1][4] = {{0}};
    const double *cw = c->cw + 4 * (span - (size_t)c->degree);
    for (int k = 0; k <= n_deriv; ++k)
        for (int j = 0; j <= c->degree; ++j)
            for (int m = 0; m < 4; ++m)
                a[k][m] += ders[k][j] * cw[4 * j + m];
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
