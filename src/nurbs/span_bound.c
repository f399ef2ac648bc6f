/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Second- and third-derivative bounds of a polynomial B-spline surface over
 * one span (span_bound.h). The derivative of a degree-p B-spline with knots U and
 * control points P_i is the degree p-1 B-spline with control points
 *   P'_i = p (P_i+1 - P_i) / (U_i+p+1 - U_i+1)
 * (The NURBS Book eq. (3.8)); applied a times in u and b times in v to the
 * (p+1) x (q+1) control points that act on a span, it gives the control
 * points of d^(a+b) S / du^a dv^b there, and by the convex hull property
 * the largest of their norms bounds the derivative over the span.
 */
#include "nurbs/span_bound.h"

#include <math.h>

/* The factors of the hodograph steps r = 1..3 of one direction:
 * f[r - 1][i] = (deg - r + 1) / (U_g+deg+1 - U_g+r) with g = first + i,
 * i = 0..deg - r. The denominators are > 0: they span the (non-empty) span
 * itself. */
static void hodograph_factors(const double *knots, size_t first, int deg,
                              double f[3][PC_MAX_ORDER])
{
    for (int r = 1; r <= 3 && r <= deg; ++r)
        for (int i = 0; i <= deg - r; ++i) {
            const size_t g = first + (size_t)i;
            f[r - 1][i] = (double)(deg - r + 1) / (knots[g + (size_t)deg + 1] - knots[g + (size_t)r]);
        }
}

/* One step of the hodograph: with pts[0..deg-r+1] (stride `stride`
 * pc_vec3) the control points of the (r-1)-th derivative, makes
 * pts[0..deg-r] those of the r-th, with f the factors of step r. */
static void differentiate_once(pc_vec3 *pts, size_t stride, int deg, int r, const double *f)
{
    for (int i = 0; i <= deg - r; ++i) {
        pc_vec3 *a = &pts[(size_t)i * stride];
        *a = vec3_scale(vec3_sub(pts[(size_t)(i + 1) * stride], *a), f[i]);
    }
}

/* The largest squared norm of the (cols x rows) control points at net (row
 * stride `row`), into *out when larger. */
static void record_max2(const pc_vec3 *net, size_t row, int cols, int rows, double *out)
{
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < cols; ++i) {
            const pc_vec3 x = net[(size_t)j * row + (size_t)i];
            *out = fmax(*out, vec3_dot(x, x));
        }
}

/* m2[k] >= max |d^2 S / du^(2-k) dv^k|, m3[k] >= max |d^3 S / du^(3-k) dv^k|
 * over the span. The u-hodographs of order a = 0..3 are built one from the
 * other in `net`; each is copied to `work` and differentiated in v up to
 * the total order 3, so every mixed derivative costs one difference pass.
 * Squared norms until the end: one square root per bound. */
static void span_bounds(const pc_nurbs_surface *s, size_t span_u, size_t span_v, double m2[3],
                        double m3[4])
{
    const int p = s->deg_u, q = s->deg_v;
    const size_t first_u = span_u - (size_t)p, first_v = span_v - (size_t)q;
    const size_t row = (size_t)p + 1;
    pc_vec3 net[PC_MAX_ORDER * PC_MAX_ORDER], work[PC_MAX_ORDER * PC_MAX_ORDER];
    double fu[3][PC_MAX_ORDER], fv[3][PC_MAX_ORDER];
    hodograph_factors(s->knots_u, first_u, p, fu);
    hodograph_factors(s->knots_v, first_v, q, fv);
    for (int k = 0; k < 4; ++k) {
        if (k < 3)
            m2[k] = 0.0;
        m3[k] = 0.0; /* a derivative of an order above the degree vanishes */
    }
    for (int j = 0; j <= q; ++j)
        for (int i = 0; i <= p; ++i) {
            const double *c = s->cw + 4 * ((first_v + (size_t)j) * s->n_u + first_u + (size_t)i);
            net[(size_t)j * row + (size_t)i] = vec3(c[0], c[1], c[2]);
        }
    for (int a = 0; a <= 3 && a <= p; ++a) {
        if (a > 0)
            for (int j = 0; j <= q; ++j)
                differentiate_once(&net[(size_t)j * row], 1, p, a, fu[a - 1]);
        if (a == 2)
            record_max2(net, row, p - a + 1, q + 1, &m2[0]);
        if (a == 3)
            record_max2(net, row, p - a + 1, q + 1, &m3[0]);
        if (a == 3 || q == 0)
            continue;
        for (int j = 0; j <= q; ++j)
            for (int i = 0; i <= p - a; ++i)
                work[(size_t)j * row + (size_t)i] = net[(size_t)j * row + (size_t)i];
        for (int b = 1; a + b <= 3 && b <= q; ++b) {
            for (int i = 0; i <= p - a; ++i)
                differentiate_once(&work[i], row, q, b, fv[b - 1]);
            if (a + b == 2)
                record_max2(work, row, p - a + 1, q - b + 1, &m2[b]);
            if (a + b == 3)
                record_max2(work, row, p - a + 1, q - b + 1, &m3[b]);
        }
    }
    for (int k = 0; k < 4; ++k) {
        if (k < 3)
            m2[k] = sqrt(m2[k]);
        m3[k] = sqrt(m3[k]);
    }
}

int pc_span_bounds(const pc_nurbs_surface *s, size_t span_u, size_t span_v, double m2[3],
                   double m3[4])
{
    if (s->rational)
        return 0;
    span_bounds(s, span_u, span_v, m2, m3);
    return 1;
}

int pc_span_third_bound(const pc_nurbs_surface *s, size_t span_u, size_t span_v,
                        double m3[4])
{
    double m2[3];
    return pc_span_bounds(s, span_u, span_v, m2, m3);
}

int pc_span_second_bound(const pc_nurbs_surface *s, size_t span_u, size_t span_v,
                         double m2[3])
{
    double m3[4];
    return pc_span_bounds(s, span_u, span_v, m2, m3);
}
