/* SPDX-License-Identifier: BSD-3-Clause */
#include "fit/lsq.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "common/error.h"
#include "nurbs/nurbs.h"

/* The values of the degree + 1 basis functions nonzero on `span` at t
 * (The NURBS Book, A2.2: values only, which is all a fit needs). */
static void basis_values(const double *knots, size_t span, int p, double t, double *n)
{
    double left[PC_MAX_ORDER], right[PC_MAX_ORDER];
    n[0] = 1.0;
    for (int j = 1; j <= p; ++j) {
        left[j] = t - knots[span + 1 - (size_t)j];
        right[j] = knots[span + (size_t)j] - t;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            const double den = right[r + 1] + left[j - r];
            const double temp = den != 0.0 ? n[r] / den : 0.0;
            n[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        n[j] = saved;
    }
}

/* The degree + 1 basis functions nonzero at t (rational when weighted):
 * returns the index of the first. */
static size_t basis_at(const pc_lsq_space *sp, double t, size_t *hint, double *r)
{
    const size_t span = pc_knot_span(sp->knots, sp->n_poles, sp->degree, t, hint ? *hint : 0);
    if (hint)
        *hint = span;
    double n[PC_MAX_ORDER];
    basis_values(sp->knots, span, sp->degree, t, n);
    const size_t first = span - (size_t)sp->degree;
    double sum = 0.0;
    for (int a = 0; a <= sp->degree; ++a) {
        r[a] = n[a] * (sp->weights ? sp->weights[first + (size_t)a] : 1.0);
        sum += r[a];
    }
    if (sp->weights && sum != 0.0)
        for (int a = 0; a <= sp->degree; ++a)
            r[a] /= sum;
    return first;
}

void pc_lsq_eval(const pc_lsq_space *space, int dim, const double *poles, double t,
                 size_t *hint, double *out)
{
    double r[PC_MAX_ORDER];
    const size_t first = basis_at(space, t, hint, r);
    for (int c = 0; c < dim; ++c)
        out[c] = 0.0;
    for (int a = 0; a <= space->degree; ++a)
        for (int c = 0; c < dim; ++c)
            out[c] += r[a] * poles[(first + (size_t)a) * (size_t)dim + (size_t)c];
}

/* Band storage of a symmetric matrix: row i holds A[i][i .. i + w]. */
#define BAND(a, w, i, j) (a)[(i) * ((w) + 1) + ((j) - (i))]

/* In-place Cholesky of the band (A = L L^T, L^T stored in the band);
 * 0 when a pivot is not positive. */
static int band_cholesky(double *a, size_t n, size_t w)
{
    for (size_t i = 0; i < n; ++i) {
        const size_t k0 = i > w ? i - w : 0;
        for (size_t j = i; j < n && j <= i + w; ++j) {
            double s = BAND(a, w, i, j);
            for (size_t k = (j > w ? j - w : 0) > k0 ? (j > w ? j - w : 0) : k0; k < i; ++k)
                s -= BAND(a, w, k, i) * BAND(a, w, k, j);
            if (j == i) {
                if (!(s > 0.0))
                    return 0;
                BAND(a, w, i, i) = sqrt(s);
            } else {
                BAND(a, w, i, j) = s / BAND(a, w, i, i);
            }
        }
    }
    return 1;
}

/* Solves L L^T y = b in place for one right-hand side with `stride`. */
static void band_solve(const double *a, size_t n, size_t w, double *b, size_t stride)
{
    for (size_t i = 0; i < n; ++i) {
        double s = b[i * stride];
        for (size_t k = i > w ? i - w : 0; k < i; ++k)
            s -= BAND(a, w, k, i) * b[k * stride];
        b[i * stride] = s / BAND(a, w, i, i);
    }
    for (size_t i = n; i-- > 0;) {
        double s = b[i * stride];
        for (size_t k = i + 1; k < n && k <= i + w; ++k)
            s -= BAND(a, w, i, k) * b[k * stride];
        b[i * stride] = s / BAND(a, w, i, i);
    }
}

/* Holds pole `i` at `value`: its row and column leave the system, their
 * products with the value move to the right-hand side. */
static void hold_pole(double *a, double *rhs, size_t n, size_t w, int dim, size_t i,
                      const double *value)
{
    for (size_t j = i > w ? i - w : 0; j < n && j <= i + w; ++j) {
        if (j == i)
            continue;
        double *aij = j < i ? &BAND(a, w, j, i) : &BAND(a, w, i, j);
        for (int c = 0; c < dim; ++c)
            rhs[j * (size_t)dim + (size_t)c] -= *aij * value[c];
        *aij = 0.0;
    }
    BAND(a, w, i, i) = 1.0;
    memcpy(rhs + i * (size_t)dim, value, (size_t)dim * sizeof *rhs);
}

/* Adds one sample's terms to the normal equations: the basis values r of
 * poles first .. first + w, the point xi (d coordinates). */
static void accumulate(double *a, double *rhs, size_t w, size_t d, size_t first, const double *r,
                       const double *xi)
{
    for (size_t p = 0; p <= w; ++p) {
        for (size_t q = p; q <= w; ++q)
            BAND(a, w, first + p, first + q) += r[p] * r[q];
        for (size_t c = 0; c < d; ++c)
            rhs[(first + p) * d + c] += r[p] * xi[c];
    }
}

/* Adds the ridge, holds the fixed poles and solves the normal equations
 * (band a, right-hand sides in poles) in place. */
static projcurve_status solve_normal(projcurve_context *ctx, double *a, size_t n, size_t w,
                                     int dim, const size_t *fixed_index,
                                     const double *fixed_value, size_t n_fixed, double *poles)
{
    double diag = 0.0;
    for (size_t i = 0; i < n; ++i)
        diag = fmax(diag, BAND(a, w, i, i));
    const double ridge = PC_LSQ_RIDGE * (diag > 0.0 ? diag : 1.0);
    for (size_t i = 0; i + 1 < n; ++i) { /* ridge * |P_(i+1) - P_i|^2 */
        BAND(a, w, i, i) += ridge;
        BAND(a, w, i + 1, i + 1) += ridge;
        BAND(a, w, i, i + 1) -= ridge;
    }
    for (size_t k = 0; k < n_fixed; ++k)
        hold_pole(a, poles, n, w, dim, fixed_index[k], fixed_value + k * (size_t)dim);
    if (!band_cholesky(a, n, w))
        return pc_fail(ctx, PROJCURVE_ERR_SINGULAR,
                       "the samples do not determine a fit of %zu poles", n);
    for (size_t c = 0; c < (size_t)dim; ++c)
        band_solve(a, n, w, poles + c, (size_t)dim);
    return PROJCURVE_OK;
}

projcurve_status pc_lsq_fit(projcurve_context *ctx, const pc_lsq_space *space, int dim,
                            const double *t, const double *x, size_t stride, size_t n_data,
                            const size_t *fixed_index, const double *fixed_value,
                            size_t n_fixed, double *poles)
{
    const size_t n = space->n_poles, w = (size_t)space->degree, d = (size_t)dim;
    double *a = calloc(n * (w + 1), sizeof *a);
    if (a == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for a fit of %zu poles", n);
    memset(poles, 0, n * d * sizeof *poles);
    size_t hint = 0;
    for (size_t i = 0; i < n_data; ++i) {
        double r[PC_MAX_ORDER];
        const size_t first = basis_at(space, t[i * stride], &hint, r);
        accumulate(a, poles, w, d, first, r, x + i * stride);
    }
    const projcurve_status st =
        solve_normal(ctx, a, n, w, dim, fixed_index, fixed_value, n_fixed, poles);
    free(a);
    return st;
}

projcurve_status pc_lsq_fit_rows(projcurve_context *ctx, const pc_lsq_space *space, int dim,
                                 const pc_lsq_rows *rows, const double *x, size_t stride,
                                 size_t n_data, const size_t *fixed_index,
                                 const double *fixed_value, size_t n_fixed, double *poles)
{
    const size_t n = space->n_poles, w = (size_t)space->degree, d = (size_t)dim;
    double *a = calloc(n * (w + 1), sizeof *a);
    if (a == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for a fit of %zu poles", n);
    memset(poles, 0, n * d * sizeof *poles);
    for (size_t i = 0; i < n_data && i < rows->n; ++i)
        accumulate(a, poles, w, d, rows->first[i], rows->values + i * (w + 1), x + i * stride);
    const projcurve_status st =
        solve_normal(ctx, a, n, w, dim, fixed_index, fixed_value, n_fixed, poles);
    free(a);
    return st;
}

projcurve_status pc_lsq_rows_fill(projcurve_context *ctx, const pc_lsq_space *space,
                                  const double *t, size_t stride, size_t n, pc_lsq_rows *rows)
{
    const size_t order = (size_t)space->degree + 1;
    rows->n = 0;
    const size_t n_values = n <= SIZE_MAX / sizeof(double) / order ? n * order : SIZE_MAX;
    if (n > rows->cap_first || n_values > rows->cap_values) {
        size_t *first = malloc(n * sizeof *first);
        double *values = n_values < SIZE_MAX ? malloc(n_values * sizeof *values) : NULL;
        if (first == NULL || values == NULL) {
            free(first);
            free(values);
            return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY,
                           "out of memory for the basis of %zu fit samples", n);
        }
        pc_lsq_rows_free(rows);
        rows->first = first;
        rows->values = values;
        rows->cap_first = n;
        rows->cap_values = n_values;
    }
    rows->degree = space->degree;
    size_t hint = 0;
    for (size_t i = 0; i < n; ++i)
        rows->first[i] = basis_at(space, t[i * stride], &hint, rows->values + i * order);
    rows->n = n;
    return PROJCURVE_OK;
}

void pc_lsq_rows_free(pc_lsq_rows *rows)
{
    free(rows->first);
    free(rows->values);
    rows->first = NULL;
    rows->values = NULL;
    rows->n = rows->cap_first = rows->cap_values = 0;
}

void pc_lsq_eval_row(const pc_lsq_rows *rows, size_t i, int dim, const double *poles,
                     double *out)
{
    const size_t order = (size_t)rows->degree + 1;
    const double *r = rows->values + i * order;
    const double *p = poles + rows->first[i] * (size_t)dim;
    for (int c = 0; c < dim; ++c)
        out[c] = 0.0;
    for (size_t a = 0; a < order; ++a)
        for (int c = 0; c < dim; ++c)
            out[c] += r[a] * p[a * (size_t)dim + (size_t)c];
}
