/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The join knots of a composed curve reduced (exact.h): copies of each
 * join's knot removed (nurbs/knot_removal.c) while the change they make
 * stays within a bound. The bound is kept per part (the stretch between
 * two joins of the curve as composed): a removal changes the curve only
 * where the basis functions of the poles it replaces are nonzero, a run
 * of whole parts, and is taken only if the changes already made there
 * plus its own stay within tol on each of them. So at every t the curve
 * moves by at most tol from the composed one, whatever the order of the
 * removals. They go round the joins one copy at a time, so that no join
 * takes the bound of its neighbours' parts before they had a turn.
 */
#include "exact/exact.h"

#include "projcurve.h"

/* The index of value t among the sorted distinct breaks (it is one). */
static size_t break_index(const double *breaks, size_t n_breaks, double t)
{
    size_t lo = 0, hi = n_breaks - 1;
    while (lo < hi) {
        const size_t m = lo + (hi - lo) / 2;
        if (breaks[m] < t)
            lo = m + 1;
        else
            hi = m;
    }
    return lo;
}

/* Tries one copy of the knot whose last copy is knots[r] (multiplicity
 * s); removes it when the bound allows. Returns 1 when removed. */
static int try_remove(pc_knot_curve *c, size_t r, size_t s, const double *breaks,
                      size_t n_parts, double *acc, double tol)
{
    double fresh[4 * PROJCURVE_MAX_DEGREE];
    const double delta = pc_knot_removal_solve(c, r, fresh);
    if (!(delta <= tol))
        return 0;
    const size_t p = (size_t)c->degree;
    /* the change lives on (knots[r - p], knots[r - s + p + 1]) */
    const size_t lo = break_index(breaks, n_parts + 1, c->knots[r - p]);
    const size_t hi = break_index(breaks, n_parts + 1, c->knots[r - s + p + 1]);
    for (size_t j = lo; j < hi; ++j)
        if (!(acc[j] + delta <= tol))
            return 0;
    for (size_t j = lo; j < hi; ++j)
        acc[j] += delta;
    pc_knot_removal_apply(c, r, fresh);
    return 1;
}

size_t pc_exact_reduce_joins(pc_knot_curve *c, unsigned char *smooth, size_t n_parts, double tol,
                             double *scratch)
{
    if (c->degree < 1 || c->degree > PROJCURVE_MAX_DEGREE || c->dim < 1 || c->dim > 4 ||
        n_parts < 2 || !(tol > 0.0))
        return 0;
    const size_t p = (size_t)c->degree;
    double *breaks = scratch, *acc = scratch + n_parts + 1;
    size_t nb = 0;
    for (size_t i = 0; i < c->n_poles + p + 1; ++i)
        if (nb == 0 || c->knots[i] > breaks[nb - 1]) {
            if (nb == n_parts + 1)
                return 0; /* more distinct knots than parts: not a composed curve */
            breaks[nb++] = c->knots[i];
        }
    if (nb != n_parts + 1)
        return 0;
    for (size_t j = 0; j < n_parts; ++j)
        acc[j] = 0.0;
    size_t total = 0, removed = 1;
    while (removed > 0) {
        removed = 0;
        size_t r = p; /* the last copy of the knot before join k */
        for (size_t k = 0; k + 1 < n_parts; ++k) {
            size_t last = r;
            while (c->knots[last + 1] == breaks[k + 1])
                ++last;
            if (last > r && smooth[k]) {
                if (try_remove(c, last, last - r, breaks, n_parts, acc, tol)) {
                    ++removed;
                    --last;
                } else {
                    smooth[k] = 0; /* the bound only tightens: no later turn */
                }
            }
            r = last;
        }
        total += removed;
    }
    return total;
}
