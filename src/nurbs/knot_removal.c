/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Knot removal (knot_removal.h). Inserting u once into the curve Q (knots
 * without one copy of u, at multiplicity s - 1) gives c's poles
 *
 *   P_i = a_i Q_i + (1 - a_i) Q_(i-1),  a_i = (u - U_i) / (U_(i+p+1) - U_i),
 *
 * for i = r - p .. r - s (U: c's knots, 0 < a_i < 1 there), P_i = Q_i
 * before the range and P_i = Q_(i-1) after it (Boehm; The NURBS Book eq.
 * (5.15)). These are p - s + 1 equations for the p - s unknowns Q_(r-p) ..
 * Q_(r-s-1): solved forward from the left end (Q_i from equation i) for
 * the first half, backward from the right end (Q_(i-1) from equation i)
 * for the second, each solve dividing by a weight of the insertion; the
 * equation left over, in the middle, tells how far the knot is needed.
 */
#include "nurbs/knot_removal.h"

#include <math.h>
#include <string.h>

static double alpha(const double *U, int p, size_t i, double u)
{
    return (u - U[i]) / (U[i + (size_t)p + 1] - U[i]);
}

/* The multiplicity of knots[r] counting down from r, or 0 when r is not
 * the last copy of an interior knot of at most multiplicity p. */
static int removable_multiplicity(const pc_knot_curve *c, size_t r)
{
    const size_t p = (size_t)c->degree;
    if (c->degree < 1 || c->n_poles < p + 2 || r <= p || r >= c->n_poles)
        return 0;
    const double *U = c->knots;
    if (!(U[r] < U[r + 1]))
        return 0;
    size_t s = 1;
    while (s <= p && U[r - s] == U[r])
        ++s;
    return s <= p && r - s >= p ? (int)s : 0;
}

/* Pole k of the curve with the knot removed, fresh holding the affected
 * range first .. last - 1. */
static const double *new_pole(const pc_knot_curve *c, size_t first, size_t last,
                              const double *fresh, size_t k)
{
    const size_t dim = (size_t)c->dim;
    if (k < first)
        return c->poles + dim * k;
    if (k >= last)
        return c->poles + dim * (k + 1);
    return fresh + dim * (k - first);
}

double pc_knot_removal_solve(const pc_knot_curve *c, size_t r, double *fresh)
{
    const int s = removable_multiplicity(c, r);
    if (s == 0)
        return INFINITY;
    const int p = c->degree;
    const size_t dim = (size_t)c->dim, first = r - (size_t)p, last = r - (size_t)s;
    const size_t m = last - first; /* unknowns */
    const size_t n_left = (m + 1) / 2;
    const double *U = c->knots, *P = c->poles, u = U[r];
    /* forward: Q_i = (P_i - (1 - a_i) Q_(i-1)) / a_i */
    for (size_t i = first; i < first + n_left; ++i) {
        const double a = alpha(U, p, i, u);
        const double *prev = new_pole(c, first, last, fresh, i - 1);
        for (size_t k = 0; k < dim; ++k)
            fresh[dim * (i - first) + k] = (P[dim * i + k] - (1.0 - a) * prev[k]) / a;
    }
    /* backward: Q_(i-1) = (P_i - a_i Q_i) / (1 - a_i) */
    for (size_t i = last; i > first + n_left; --i) {
        const double a = alpha(U, p, i, u);
        const double *next = new_pole(c, first, last, fresh, i);
        for (size_t k = 0; k < dim; ++k)
            fresh[dim * (i - 1 - first) + k] = (P[dim * i + k] - a * next[k]) / (1.0 - a);
    }
    /* every equation of the insertion, the one left over among them */
    double worst = 0.0;
    for (size_t i = first; i <= last; ++i) {
        const double a = alpha(U, p, i, u);
        const double *qi = new_pole(c, first, last, fresh, i);
        const double *qp = new_pole(c, first, last, fresh, i - 1);
        double d2 = 0.0;
        for (size_t k = 0; k < dim; ++k) {
            const double e = a * qi[k] + (1.0 - a) * qp[k] - P[dim * i + k];
            d2 += e * e;
        }
        worst = fmax(worst, sqrt(d2));
    }
    return worst == worst ? worst : INFINITY; /* a NaN pole: not removable */
}

void pc_knot_removal_apply(pc_knot_curve *c, size_t r, const double *fresh)
{
    const int s = removable_multiplicity(c, r);
    if (s == 0)
        return;
    const size_t p = (size_t)c->degree, dim = (size_t)c->dim;
    const size_t first = r - p, last = r - (size_t)s, n = c->n_poles;
    memcpy(c->poles + dim * first, fresh, dim * (last - first) * sizeof *fresh);
    memmove(c->poles + dim * last, c->poles + dim * (last + 1),
            dim * (n - last - 1) * sizeof *c->poles);
    memmove(c->knots + r, c->knots + r + 1, (n + p - r) * sizeof *c->knots);
    c->n_poles = n - 1;
}
