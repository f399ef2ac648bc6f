/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Textbook bicubic evaluation (see naive_eval.h).
 */
#include "naive_eval.h"

#define P 3      /* degree */
#define NDER 2   /* derivatives wanted */

/* A2.1: the span k with knots[k] <= t < knots[k+1], by bisection. */
static size_t find_span(const double *knots, size_t n_ctrl, double t)
{
    if (t >= knots[n_ctrl])
        return n_ctrl - 1;
    size_t lo = P, hi = n_ctrl;
    while (hi - lo > 1) {
        const size_t mid = (lo + hi) / 2;
        if (t < knots[mid])
            hi = mid;
        else
            lo = mid;
    }
    return lo;
}

/* A2.3: the P + 1 non-zero basis functions and their first NDER derivatives. */
static void basis_ders(const double *U, size_t span, double t, double ders[NDER + 1][P + 1])
{
    double ndu[P + 1][P + 1], left[P + 1], right[P + 1], a[2][P + 1];
    ndu[0][0] = 1.0;
    for (int j = 1; j <= P; ++j) {
        left[j] = t - U[span + 1 - (size_t)j];
        right[j] = U[span + (size_t)j] - t;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            ndu[j][r] = right[r + 1] + left[j - r];
            const double temp = ndu[r][j - 1] / ndu[j][r];
            ndu[r][j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    for (int j = 0; j <= P; ++j)
        ders[0][j] = ndu[j][P];
    for (int r = 0; r <= P; ++r) {
        int s1 = 0, s2 = 1;
        a[0][0] = 1.0;
        for (int k = 1; k <= NDER; ++k) {
            double d = 0.0;
            const int rk = r - k, pk = P - k;
            if (r >= k) {
                a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
                d = a[s2][0] * ndu[rk][pk];
            }
            const int j1 = rk >= -1 ? 1 : -rk;
            const int j2 = r - 1 <= pk ? k - 1 : P - r;
            for (int j = j1; j <= j2; ++j) {
                a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
                d += a[s2][j] * ndu[rk + j][pk];
            }
            if (r <= pk) {
                a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
                d += a[s2][k] * ndu[r][pk];
            }
            ders[k][r] = d;
            const int tmp = s1;
            s1 = s2;
            s2 = tmp;
        }
    }
    double factor = P;
    for (int k = 1; k <= NDER; ++k) {
        for (int j = 0; j <= P; ++j)
            ders[k][j] *= factor;
        factor *= (double)(P - k);
    }
}

void pcb_naive_eval(const pcb_naive_surface *s, double u, double v, double out[18])
{
    const size_t su = find_span(s->knots_u, s->n_u, u);
    const size_t sv = find_span(s->knots_v, s->n_v, v);
    double nu[NDER + 1][P + 1], nv[NDER + 1][P + 1];
    basis_ders(s->knots_u, su, u, nu);
    basis_ders(s->knots_v, sv, v, nv);
    /* (du, dv) order of each output: S, Su, Sv, Suu, Suv, Svv. */
    static const int order[6][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};
    for (int o = 0; o < 6; ++o) {
        const int du = order[o][0], dv = order[o][1];
        double acc[3] = {0.0, 0.0, 0.0};
        for (int l = 0; l <= P; ++l) {
            const size_t row = (sv - P + (size_t)l) * s->n_u;
            for (int k = 0; k <= P; ++k) {
                const double *pt = &s->ctrl[3 * (row + su - P + (size_t)k)];
                const double w = nu[du][k] * nv[dv][l];
                acc[0] += w * pt[0];
                acc[1] += w * pt[1];
                acc[2] += w * pt[2];
            }
        }
        out[3 * o] = acc[0];
        out[3 * o + 1] = acc[1];
        out[3 * o + 2] = acc[2];
    }
}
