/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Exact conversion of unclamped (and periodic) knot vectors to clamped form
 * over the same domain, by knot insertion (Boehm; The NURBS Book A5.1).
 *
 * Over its domain [a, b] = [U[p], U[n]] a spline does not depend on how its
 * knot vector continues outside. Inserting a until it has multiplicity p
 * makes C(a) a control point; the control points and knots before it then
 * only shape the curve outside [a, b] and are dropped. The same at b. The
 * result evaluates like the input up to rounding (a few ulps per insertion).
 */
#include <stdlib.h>
#include <string.h>

#include "common/error.h"
#include "nurbs/nurbs.h"

static size_t knot_count(const pc_spline_batch *b) { return b->n_ctrl + (size_t)b->degree + 1; }

static size_t multiplicity(const double *knots, size_t n_knots, double t)
{
    size_t m = 0;
    for (size_t k = 0; k < n_knots; ++k)
        m += knots[k] == t;
    return m;
}

/* Inserts t r times, where t lies in [U[p], U[n]), has multiplicity s and
 * r + s <= p. */
static projcurve_status insert_knot(projcurve_context *ctx, pc_spline_batch *b, double t,
                                    size_t r)
{
    const size_t p = (size_t)b->degree, n = b->n_ctrl, dim = b->dim;
    const size_t n_knots = knot_count(b);
    const double *U = b->knots;
    size_t k = p; /* last index with U[k] <= t */
    while (k + 1 < n_knots && U[k + 1] <= t)
        ++k;
    const size_t s = multiplicity(U, n_knots, t);
    const size_t nq = n + r;
    const size_t row_len = pc_size_mul(nq, dim);
    const size_t total = pc_size_mul(row_len, b->rows);
    if (row_len == 0 || total == 0 || pc_size_mul(total, sizeof(double)) == 0)
        return pc_fail(ctx, PROJCURVE_ERR_OVERFLOW, "control net too large to clamp");
    double *uq = malloc((n_knots + r) * sizeof(double));
    double *q = malloc(total * sizeof(double));
    double *rw = malloc((p + 1) * dim * sizeof(double));
    if (uq == NULL || q == NULL || rw == NULL) {
        free(uq);
        free(q);
        free(rw);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory while clamping knots");
    }
    memcpy(uq, U, (k + 1) * sizeof(double));
    for (size_t j = 1; j <= r; ++j)
        uq[k + j] = t;
    memcpy(uq + k + 1 + r, U + k + 1, (n_knots - k - 1) * sizeof(double));

    for (size_t row = 0; row < b->rows; ++row) {
        const double *P = b->pts + row * n * dim;
        double *Q = q + row * nq * dim;
        memcpy(Q, P, (k - p + 1) * dim * sizeof(double));
        memcpy(Q + (k - s + r) * dim, P + (k - s) * dim, (n - k + s) * dim * sizeof(double));
        memcpy(rw, P + (k - p) * dim, (p - s + 1) * dim * sizeof(double));
        size_t L = k - p;
        for (size_t j = 1; j <= r; ++j) {
            L = k - p + j;
            for (size_t i = 0; i + j + s <= p; ++i) {
                const double alpha = (t - U[L + i]) / (U[i + k + 1] - U[L + i]);
                for (size_t c = 0; c < dim; ++c)
                    rw[i * dim + c] = alpha * rw[(i + 1) * dim + c] + (1.0 - alpha) * rw[i * dim + c];
            }
            memcpy(Q + L * dim, rw, dim * sizeof(double));
            memcpy(Q + (k + r - j - s) * dim, rw + (p - j - s) * dim, dim * sizeof(double));
        }
        for (size_t i = L + 1; i + s < k; ++i)
            memcpy(Q + i * dim, rw + (i - L) * dim, dim * sizeof(double));
    }
    free(rw);
    free(b->knots);
    free(b->pts);
    b->knots = uq;
    b->pts = q;
    b->n_ctrl = nq;
    return PROJCURVE_OK;
}

/* Keeps control points [first, first + count) of every row and knots
 * [first, first + count + p], in place. */
static void keep_range(pc_spline_batch *b, size_t first, size_t count)
{
    const size_t dim = b->dim, p = (size_t)b->degree;
    memmove(b->knots, b->knots + first, (count + p + 1) * sizeof(double));
    for (size_t row = 0; row < b->rows; ++row)
        memmove(b->pts + row * count * dim, b->pts + (row * b->n_ctrl + first) * dim,
                count * dim * sizeof(double));
    b->n_ctrl = count;
}

projcurve_status pc_spline_batch_clamp(projcurve_context *ctx, pc_spline_batch *b)
{
    const size_t p = (size_t)b->degree;
    const double a = b->knots[p], e = b->knots[b->n_ctrl];

    size_t s = multiplicity(b->knots, knot_count(b), a);
    if (s < p) {
        const projcurve_status st = insert_knot(ctx, b, a, p - s);
        if (st != PROJCURVE_OK)
            return st;
    }
    size_t last = 0; /* last index holding a */
    while (b->knots[last + 1] <= a)
        ++last;
    keep_range(b, last - p, b->n_ctrl - (last - p));
    b->knots[0] = a;

    s = multiplicity(b->knots, knot_count(b), e);
    if (s < p) {
        const projcurve_status st = insert_knot(ctx, b, e, p - s);
        if (st != PROJCURVE_OK)
            return st;
    }
    size_t first = 0; /* first index holding e */
    while (b->knots[first] < e)
        ++first;
    keep_range(b, 0, first);
    b->knots[first + p] = e;
    return PROJCURVE_OK;
}
