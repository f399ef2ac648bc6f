/* SPDX-License-Identifier: BSD-3-Clause */
#include "fit/resampled.h"

#include <math.h>
#include <stdlib.h>

#include "common/error.h"
#include "fit/lsq.h"

#define RESAMPLED_MAX_DIM 3

/* Clamped cubic knots: `spans` uniform spans in each interval between t0,
 * the breaks and t1, a triple knot at each break; returns the pole count. */
static size_t knots_with_breaks(const pc_fit_resampled_input *in, size_t spans, double *knots)
{
    size_t m = 0;
    for (int k = 0; k < 4; ++k)
        knots[m++] = in->t0;
    for (size_t b = 0; b <= in->n_breaks; ++b) {
        const double lo = b == 0 ? in->t0 : in->breaks[b - 1];
        const double hi = b == in->n_breaks ? in->t1 : in->breaks[b];
        for (size_t j = 1; j < spans; ++j)
            knots[m++] = lo + (hi - lo) * (double)j / (double)spans;
        for (int k = 0; b < in->n_breaks && k < 3; ++k)
            knots[m++] = hi;
    }
    for (int k = 0; k < 4; ++k)
        knots[m++] = in->t1;
    return m - 4;
}

static double dist(int dim, const double *a, const double *b)
{
    double s = 0.0;
    for (int k = 0; k < dim; ++k)
        s += (a[k] - b[k]) * (a[k] - b[k]);
    return sqrt(s);
}

/* A coordinate constant over the samples (a piece along an iso-line, a
 * seam) stays exactly that constant: least squares would give it back
 * only to rounding, off the seam by an ulp. */
static void keep_constants(const pc_fit_resampled_input *in, size_t count, double *poles)
{
    for (int k = 0; k < in->dim; ++k) {
        const double c = in->samples[k];
        size_t i = 1;
        while (i <= in->n && in->samples[(size_t)in->dim * i + (size_t)k] == c)
            ++i;
        for (size_t j = 0; i > in->n && j < count; ++j)
            poles[(size_t)in->dim * j + (size_t)k] = c;
    }
}

/* 1 when the spline of `space` is within tol of every sample and then of
 * the exact curve half way between neighbouring samples (the samples
 * first: a fit that fails costs no exact evaluation). */
static int within(const pc_fit_resampled_input *in, const pc_lsq_space *space,
                  const double *poles, const double *t)
{
    size_t hint = 0;
    double q[RESAMPLED_MAX_DIM], x[RESAMPLED_MAX_DIM];
    for (size_t i = 0; i <= in->n; ++i) {
        pc_lsq_eval(space, in->dim, poles, t[i], &hint, q);
        if (!(dist(in->dim, q, in->samples + (size_t)in->dim * i) <= in->tol))
            return 0;
    }
    hint = 0;
    for (size_t i = 0; i < in->n; ++i) {
        const double mid = 0.5 * (t[i] + t[i + 1]);
        pc_lsq_eval(space, in->dim, poles, mid, &hint, q);
        in->exact(in->user, mid, x);
        if (!(dist(in->dim, q, x) <= in->tol))
            return 0;
    }
    return 1;
}

projcurve_status pc_fit_resampled_cubic(projcurve_context *ctx, const pc_fit_resampled_input *in,
                                        double *poles, double *knots, size_t *n_poles)
{
    *n_poles = 0;
    if (in->dim < 1 || in->dim > RESAMPLED_MAX_DIM || in->n < 4 ||
        in->n_breaks > PC_FIT_RESAMPLED_MAX_BREAKS)
        return PROJCURVE_OK;
    /* rows (t_i, x_i) as pc_lsq_fit reads them, and the t_i alone */
    const size_t row = (size_t)in->dim + 1;
    double *rows = malloc((in->n + 1) * row * sizeof *rows);
    double *t = malloc((in->n + 1) * sizeof *t);
    if (rows == NULL || t == NULL) {
        free(rows);
        free(t);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory fitting a resampled curve");
    }
    for (size_t i = 0; i <= in->n; ++i) {
        t[i] = in->t != NULL ? in->t[i]
               : i == in->n ? in->t1
                            : in->t0 + (in->t1 - in->t0) * (double)i / (double)in->n;
        rows[i * row] = t[i];
        for (int k = 0; k < in->dim; ++k)
            rows[i * row + 1 + (size_t)k] = in->samples[(size_t)in->dim * i + (size_t)k];
    }
    double ends[2 * RESAMPLED_MAX_DIM];
    for (int k = 0; k < in->dim; ++k) {
        ends[k] = in->samples[k];
        ends[in->dim + k] = in->samples[(size_t)in->dim * in->n + (size_t)k];
    }
    projcurve_status st = PROJCURVE_OK;
    /* bounded: the spans of each interval double up to
     * PC_FIT_RESAMPLED_MAX_SPANS in all */
    const size_t intervals = in->n_breaks + 1;
    for (size_t spans = 1; spans * intervals <= PC_FIT_RESAMPLED_MAX_SPANS &&
                           2 * spans * intervals <= in->n;
         spans *= 2) {
        const size_t count = knots_with_breaks(in, spans, knots);
        const pc_lsq_space space = {.degree = 3, .n_poles = count, .knots = knots};
        const size_t fixed[2] = {0, count - 1};
        /* no context: a singular system only means no fit of this size,
         * which is no failure of the caller's call */
        st = pc_lsq_fit(NULL, &space, in->dim, rows, rows + 1, row, in->n + 1, fixed, ends, 2,
                        poles);
        if (st == PROJCURVE_ERR_SINGULAR) {
            st = PROJCURVE_OK;
            continue;
        }
        if (st != PROJCURVE_OK) {
            st = pc_fail(ctx, st, "out of memory fitting a resampled curve");
            break;
        }
        keep_constants(in, count, poles);
        if (within(in, &space, poles, t)) {
            *n_poles = count;
            break;
        }
    }
    free(rows);
    free(t);
    return st;
}
