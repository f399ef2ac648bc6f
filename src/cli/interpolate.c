/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Global B-spline interpolation for --points --interpolate: knots averaged
 * from the parameters, then the banded collocation system solved by
 * Gaussian elimination without pivoting.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "curve_input.h"

#define INTERP_MAX_DEGREE 3

/* The knot span [knots[s], knots[s+1]) holding t, p <= s <= n - 1. */
static size_t find_span(const double *knots, size_t n, int p, double t)
{
    if (t >= knots[n])
        return n - 1;
    size_t lo = (size_t)p, hi = n;
    /* binary search: the interval halves each step, log2(n) steps */
    while (hi - lo > 1) {
        const size_t mid = lo + (hi - lo) / 2;
        if (t < knots[mid])
            hi = mid;
        else
            lo = mid;
    }
    return lo;
}

/* The p + 1 basis functions not zero on span s at t (The NURBS Book, A2.2). */
static void basis(const double *knots, size_t s, int p, double t, double *N)
{
    double left[INTERP_MAX_DEGREE + 1], right[INTERP_MAX_DEGREE + 1];
    N[0] = 1.0;
    for (int j = 1; j <= p; ++j) {
        left[j] = t - knots[s + 1 - (size_t)j];
        right[j] = knots[s + (size_t)j] - t;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            const double temp = N[r] / (right[r + 1] + left[j - r]);
            N[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        N[j] = saved;
    }
}

static void average_knots(const double *u, size_t n, int p, double *knots)
{
    for (int k = 0; k <= p; ++k) {
        knots[k] = 0.0;
        knots[n + (size_t)k] = 1.0;
    }
    for (size_t j = 1; j + (size_t)p < n; ++j) {
        double sum = 0.0;
        for (int i = 0; i < p; ++i)
            sum += u[j + (size_t)i];
        knots[j + (size_t)p] = sum / p;
    }
}

/* Fills the band (row i, column j at band[i * w + j - i + p], w = 2p + 1);
 * 0 when a row's basis functions fall outside the band (parameters that
 * break the Schoenberg-Whitney condition; not for averaged knots). */
static int fill_band(const double *u, size_t n, int p, const double *knots, double *band)
{
    const size_t w = 2 * (size_t)p + 1;
    for (size_t i = 0; i < n; ++i) {
        const size_t s = find_span(knots, n, p, u[i]);
        double N[INTERP_MAX_DEGREE + 1];
        basis(knots, s, p, u[i], N);
        for (int k = 0; k <= p; ++k) {
            const size_t j = s - (size_t)p + (size_t)k;
            if (j + (size_t)p < i || j > i + (size_t)p)
                return 0;
            band[i * w + j + (size_t)p - i] = N[k];
        }
    }
    return 1;
}

/* Solves band * x = rhs (3 columns) in place, x into rhs. */
static int solve_band(double *band, size_t n, int p, double *rhs)
{
    const size_t w = 2 * (size_t)p + 1, q = (size_t)p;
#define AT(i, j) band[(i) * w + (j) + q - (i)]
    for (size_t k = 0; k < n; ++k) {
        const double pivot = AT(k, k);
        if (!(fabs(pivot) > 0.0) || !isfinite(pivot))
            return 0;
        const size_t last = k + q < n - 1 ? k + q : n - 1;
        for (size_t i = k + 1; i <= last; ++i) {
            const double f = AT(i, k) / pivot;
            if (f == 0.0)
                continue;
            for (size_t j = k; j <= last; ++j)
                AT(i, j) -= f * AT(k, j);
            for (int c = 0; c < 3; ++c)
                rhs[3 * i + (size_t)c] -= f * rhs[3 * k + (size_t)c];
        }
    }
    for (size_t k = n; k-- > 0;) {
        const size_t last = k + q < n - 1 ? k + q : n - 1;
        for (int c = 0; c < 3; ++c) {
            double v = rhs[3 * k + (size_t)c];
            for (size_t j = k + 1; j <= last; ++j)
                v -= AT(k, j) * rhs[3 * j + (size_t)c];
            rhs[3 * k + (size_t)c] = v / AT(k, k);
            if (!isfinite(rhs[3 * k + (size_t)c]))
                return 0;
        }
    }
#undef AT
    return 1;
}

int cli_interpolate(const double *xyz, const double *u, size_t n, int degree, double *ctrl,
                    double *knots)
{
    if (degree < 1 || degree > INTERP_MAX_DEGREE || n <= (size_t)degree || n > CLI_MAX_POINTS)
        return 0;
    average_knots(u, n, degree, knots);
    double *band = calloc(n * (2 * (size_t)degree + 1), sizeof *band);
    if (band == NULL)
        return 0;
    memcpy(ctrl, xyz, 3 * n * sizeof *ctrl);
    const int ok = fill_band(u, n, degree, knots, band) && solve_band(band, n, degree, ctrl);
    free(band);
    return ok;
}
