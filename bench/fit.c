/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Least-squares fits (see fit.h).
 */
#include "fit.h"

#include <math.h>

/* Slope and intercept of the line through (xs, ys); NaN when degenerate. */
static void fit_line(const double *xs, const double *ys, size_t n, double *intercept,
                     double *slope)
{
    *intercept = *slope = NAN;
    if (n < 2)
        return;
    double mx = 0.0, my = 0.0;
    for (size_t i = 0; i < n; ++i) {
        mx += xs[i];
        my += ys[i];
    }
    mx /= (double)n;
    my /= (double)n;
    double sxx = 0.0, sxy = 0.0;
    for (size_t i = 0; i < n; ++i) {
        sxx += (xs[i] - mx) * (xs[i] - mx);
        sxy += (xs[i] - mx) * (ys[i] - my);
    }
    if (!(sxx > 0.0))
        return;
    *slope = sxy / sxx;
    *intercept = my - *slope * mx;
}

/* Enough room for every series the benchmarks fit. */
#define PCB_FIT_MAX_POINTS 256

double pcb_fit_power(const double *x, const double *y, size_t n)
{
    double lx[PCB_FIT_MAX_POINTS], ly[PCB_FIT_MAX_POINTS];
    size_t m = 0;
    for (size_t i = 0; i < n && m < PCB_FIT_MAX_POINTS; ++i) {
        if (x[i] > 0.0 && y[i] > 0.0 && isfinite(x[i]) && isfinite(y[i])) {
            lx[m] = log(x[i]);
            ly[m] = log(y[i]);
            ++m;
        }
    }
    double intercept, slope;
    fit_line(lx, ly, m, &intercept, &slope);
    return slope;
}

void pcb_fit_log(const double *x, const double *y, size_t n, double *a, double *b)
{
    double lx[PCB_FIT_MAX_POINTS], yy[PCB_FIT_MAX_POINTS];
    size_t m = 0;
    for (size_t i = 0; i < n && m < PCB_FIT_MAX_POINTS; ++i) {
        if (x[i] > 0.0 && isfinite(x[i]) && isfinite(y[i])) {
            lx[m] = log(x[i]);
            yy[m] = y[i];
            ++m;
        }
    }
    fit_line(lx, yy, m, a, b);
}
