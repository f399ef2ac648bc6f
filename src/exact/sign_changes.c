/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Where a Bezier polynomial changes sign: the knot-line crossings of a
 * pcurve piece, f(s) = u(s) - u_k. By the variation-diminishing property
 * of the Bernstein basis, f has no more sign changes in (a, b) than its
 * coefficients there; where they have none it keeps one sign, so the
 * piece stays on one side of the knot line (touching it is no crossing).
 * Intervals whose coefficients change sign are halved by de Casteljau
 * (exact halving of the parameter, convex combinations of the
 * coefficients) down to 2^-PC_EXACT_ROOT_DEPTH, the rounding of s.
 */
#include "exact/exact.h"

/* Halvings before an interval is taken as one root: 2^-52 of [0, 1]. */
#define PC_EXACT_ROOT_DEPTH 52
#define PC_EXACT_MAX_ORDER 4

typedef struct roots_out {
    double *items;
    size_t count, cap;
    int overflow;
} roots_out;

/* Sign changes among the non-zero coefficients. */
static int variations(int d, const double *f)
{
    int v = 0, last = 0;
    for (int i = 0; i <= d; ++i) {
        const int sg = (f[i] > 0.0) - (f[i] < 0.0);
        if (sg != 0 && last != 0 && sg != last)
            ++v;
        if (sg != 0)
            last = sg;
    }
    return v;
}

/* The sign of f next to one end of its interval: that of the first
 * non-zero coefficient from the start (from = 1) or the end (from = -1). */
static int side_sign(int d, const double *f, int from)
{
    for (int k = 0; k <= d; ++k) {
        const double x = f[from > 0 ? k : d - k];
        if (x != 0.0)
            return x > 0.0 ? 1 : -1;
    }
    return 0;
}

static void push(roots_out *r, double s)
{
    if (r->count < r->cap)
        r->items[r->count++] = s;
    else
        r->overflow = 1;
}

/* The roots in (lo, hi), f the coefficients there. Recursion depth is
 * bounded by PC_EXACT_ROOT_DEPTH; once there, the interval's middle is
 * the root. */
static void find(int d, const double *f, double lo, double hi, int depth, roots_out *r)
{
    if (r->overflow || variations(d, f) == 0)
        return;
    const double mid = 0.5 * (lo + hi);
    if (depth >= PC_EXACT_ROOT_DEPTH) {
        push(r, mid);
        return;
    }
    double left[PC_EXACT_MAX_ORDER], right[PC_EXACT_MAX_ORDER], w[PC_EXACT_MAX_ORDER];
    for (int i = 0; i <= d; ++i)
        w[i] = f[i];
    for (int k = 0; k <= d; ++k) { /* de Casteljau at 1/2 */
        left[k] = w[0];
        right[d - k] = w[d - k];
        for (int i = 0; i < d - k; ++i)
            w[i] = 0.5 * (w[i] + w[i + 1]);
    }
    find(d, left, lo, mid, depth + 1, r);
    if (left[d] == 0.0 && side_sign(d, left, -1) * side_sign(d, right, 1) < 0)
        push(r, mid); /* f(mid) = 0 exactly, with a sign change there */
    find(d, right, mid, hi, depth + 1, r);
}

size_t pc_exact_sign_changes(int d, const double *f, double *roots, size_t cap)
{
    roots_out r = {roots, 0, cap, 0};
    if (d < 1 || d >= PC_EXACT_MAX_ORDER)
        return (size_t)-1;
    find(d, f, 0.0, 1.0, 0, &r);
    return r.overflow ? (size_t)-1 : r.count;
}
