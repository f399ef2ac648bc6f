/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Knot vectors: span lookup, validation of user input, size arithmetic.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "common/error.h"
#include "nurbs/nurbs.h"

size_t pc_size_mul(size_t a, size_t b)
{
    if (a != 0 && b > SIZE_MAX / a)
        return 0;
    return a * b;
}

/* The span of a clamped knot vector is searched in [degree, n_ctrl - 1]. A
 * valid hint (the span of the previous call, or its right neighbour, which
 * is where a sequential caller moves to) answers in O(1); otherwise a
 * branch-free binary search does it in O(log n). */
size_t pc_knot_span(const double *knots, size_t n_ctrl, int degree, double t, size_t hint)
{
    const size_t lo_span = (size_t)degree;
    const size_t hi_span = n_ctrl - 1;
    if (!(t < knots[n_ctrl])) {
        /* End of the domain (or beyond, or NaN): the last non-empty span. */
        size_t k = hi_span;
        while (k > lo_span && !(knots[k] < knots[k + 1]))
            --k;
        return k;
    }
    if (!(t > knots[lo_span]))
        t = knots[lo_span];
    if (hint >= lo_span && hint <= hi_span) {
        if (knots[hint] <= t && t < knots[hint + 1])
            return hint;
        if (hint < hi_span && knots[hint + 1] <= t && t < knots[hint + 2])
            return hint + 1;
    }
    /* Largest k in [lo_span, hi_span] with knots[k] <= t (then t <
     * knots[k + 1]), by halving a range without a data-dependent branch:
     * random queries would mispredict every other step of a classic
     * bisection, which cost more than the evaluation itself. */
    size_t lo = lo_span, len = n_ctrl - lo_span;
    while (len > 1) {
        const size_t half = len / 2;
        lo = knots[lo + half] <= t ? lo + half : lo;
        len -= half;
    }
    return lo;
}

projcurve_status pc_knots_validate(projcurve_context *ctx, const char *name, int degree,
                                   size_t n_ctrl, const double *knots)
{
    const size_t n_knots = n_ctrl + (size_t)degree + 1;
    size_t run = 1; /* length of the current run of equal knots */
    for (size_t k = 0; k < n_knots; ++k) {
        if (!isfinite(knots[k]))
            return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "%s: knot %zu is not finite", name, k);
        if (k == 0)
            continue;
        if (knots[k] < knots[k - 1])
            return pc_fail(ctx, PROJCURVE_ERR_BAD_KNOTS,
                           "%s is not non-decreasing at index %zu (%.17g < %.17g)", name, k,
                           knots[k], knots[k - 1]);
        run = knots[k] == knots[k - 1] ? run + 1 : 1;
        if (run > (size_t)degree + 1)
            return pc_fail(ctx, PROJCURVE_ERR_BAD_KNOTS,
                           "%s: knot %.17g at index %zu is repeated more than degree + 1 = %d "
                           "times",
                           name, knots[k], k, degree + 1);
    }
    if (!(knots[degree] < knots[n_ctrl]))
        return pc_fail(ctx, PROJCURVE_ERR_BAD_KNOTS,
                       "%s: empty domain [knots[%d], knots[%zu]] = [%.17g, %.17g]", name, degree,
                       n_ctrl, knots[degree], knots[n_ctrl]);
    return PROJCURVE_OK;
}

int pc_knots_are_clamped(const double *knots, size_t n_ctrl, int degree)
{
    const size_t last = n_ctrl + (size_t)degree;
    for (size_t k = 1; k <= (size_t)degree; ++k)
        if (knots[k] != knots[0] || knots[last - k] != knots[last])
            return 0;
    return 1;
}

double *pc_knot_inverses(const double *knots, size_t n_ctrl, int degree)
{
    const size_t per_span = pc_knot_inverse_count(degree);
    const size_t n_spans = n_ctrl - (size_t)degree;
    const size_t total = pc_size_mul(per_span, n_spans);
    if (total == 0 || pc_size_mul(total, sizeof(double)) == 0)
        return NULL;
    double *inv = calloc(total, sizeof(double));
    if (inv == NULL)
        return NULL;
    for (size_t k = (size_t)degree; k < n_ctrl; ++k) {
        if (!(knots[k] < knots[k + 1]))
            continue; /* never evaluated */
        double *row = inv + (k - (size_t)degree) * per_span;
        for (size_t j = 1; j <= (size_t)degree; ++j)
            for (size_t r = 0; r < j; ++r)
                row[j * (j - 1) / 2 + r] = 1.0 / (knots[k + r + 1] - knots[k + r + 1 - j]);
    }
    return inv;
}

double pc_knot_uniform_scale(const double *knots, size_t n_ctrl, int degree)
{
    const size_t lo = (size_t)degree, spans = n_ctrl - lo;
    const double length = knots[n_ctrl] - knots[lo], h = length / (double)spans;
    if (!(h > 0.0))
        return 0.0;
    for (size_t k = 0; k < spans; ++k) {
        const double span = knots[lo + k + 1] - knots[lo + k];
        if (!(fabs(span - h) <= 0.25 * h))
            return 0.0;
    }
    return (double)spans / length;
}
