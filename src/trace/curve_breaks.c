/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Breaks of a NURBS curve from its knot vector: the multiplicity of an
 * interior knot gives the continuity there (degree - multiplicity).
 */
#include "trace/curve_breaks.h"

#include <math.h>

/* First index k in [lo, hi) with knots[k] > t (hi when none). */
static size_t upper_bound(const double *knots, size_t lo, size_t hi, double t)
{
    while (lo < hi) { /* halves [lo, hi) each pass: at most 64 passes */
        const size_t mid = lo + (hi - lo) / 2;
        if (knots[mid] > t)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

/* Multiplicity of the knot value knots[k] among the interior knots
 * [first, end) of c, counted from the run starting at k. */
static size_t run_length(const double *knots, size_t k, size_t end)
{
    size_t m = 1;
    while (k + m < end && knots[k + m] == knots[k])
        ++m;
    return m;
}

static int is_break_multiplicity(const pc_nurbs_curve *c, size_t m, int order)
{
    return (int)m > c->degree - order;
}

int pc_curve_break_at(const projcurve_curve *c, double t, int order)
{
    if (c == NULL || c->kind != PC_CURVE_NURBS)
        return 0;
    const pc_nurbs_curve *n = &c->nurbs;
    if (!(t > n->t0 && t < n->t1))
        return 0;
    /* interior knots: indices [degree + 1, n_ctrl) */
    const size_t first = (size_t)n->degree + 1, end = n->n_ctrl;
    const size_t k = upper_bound(n->knots, first, end, t); /* one past the last <= t */
    if (k == first || n->knots[k - 1] != t)
        return 0;
    size_t start = k - 1;
    while (start > first && n->knots[start - 1] == t)
        --start;
    return is_break_multiplicity(n, k - start, order);
}

void pc_curve_breaks_init(pc_curve_breaks *b, const projcurve_curve *c, int order)
{
    b->nurbs = c != NULL && c->kind == PC_CURVE_NURBS ? &c->nurbs : NULL;
    b->order = order;
    b->lo = b->hi = NAN; /* no query yet */
}

/* Brackets t: b->lo the last break <= t (or t0), b->hi the first break
 * > t (or t1). Each pass of either scan moves past one knot value, so
 * both end within n_ctrl passes. */
static void bracket(pc_curve_breaks *b, double t)
{
    const pc_nurbs_curve *n = b->nurbs;
    const size_t first = (size_t)n->degree + 1, end = n->n_ctrl;
    const size_t k = upper_bound(n->knots, first, end, t);
    b->hi = n->t1;
    for (size_t j = k; j < end;) {
        const size_t m = run_length(n->knots, j, end);
        if (is_break_multiplicity(n, m, b->order)) {
            b->hi = n->knots[j];
            break;
        }
        j += m;
    }
    b->lo = n->t0;
    for (size_t j = k; j > first;) { /* knots[j - 1] <= t */
        size_t start = j - 1;
        while (start > first && n->knots[start - 1] == n->knots[j - 1])
            --start;
        if (is_break_multiplicity(n, j - start, b->order)) {
            b->lo = n->knots[j - 1];
            break;
        }
        j = start;
    }
}

double pc_curve_breaks_next(pc_curve_breaks *b, double t, int direction)
{
    if (b->nurbs == NULL)
        return direction > 0 ? INFINITY : -INFINITY;
    if (direction > 0) {
        if (!(b->lo <= t && t < b->hi))
            bracket(b, t);
        return b->hi > t ? b->hi : INFINITY;
    }
    /* the break strictly before t: bracket from just below t */
    if (!(b->lo < t && t <= b->hi))
        bracket(b, nextafter(t, -INFINITY));
    return b->lo < t ? b->lo : -INFINITY;
}

double pc_curve_break_side(const projcurve_curve *c, double t, int direction, int order)
{
    if (!pc_curve_break_at(c, t, order))
        return t;
    return nextafter(t, direction > 0 ? INFINITY : -INFINITY);
}
