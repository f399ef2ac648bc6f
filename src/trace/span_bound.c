/*
 * Third-derivative bounds of a polynomial B-spline surface over one span
 * (span_bound.h). The derivative of a degree-p B-spline with knots U and
 * control points P_i is the degree p-1 B-spline with control points
 *   P'_i = p (P_i+1 - P_i) / (U_i+p+1 - U_i+1)
 * (The NURBS Book eq. (3.8)); applied a times in u and b times in v to the
 * (p+1) x (q+1) control points that act on a span, it gives the control
 * points of d^(a+b) S / du^a dv^b there, and by the convex hull property
 * the largest of their norms bounds the derivative over the span.
 */
#include "trace/span_bound.h"

#include <math.h>

/* Replaces pts[0..deg] (stride `stride` pc_vec3) by the control points of
 * the order-th derivative, pts[0..deg-order]. knots are those of the
 * direction, first = index of the span's first active control point. The
 * denominators are > 0: they span the (non-empty) span itself. */
static void differentiate(pc_vec3 *pts, size_t stride, int deg, int order, const double *knots,
                          size_t first)
{
    for (int r = 1; r <= order; ++r) {
        const double scale = (double)(deg - r + 1);
        for (int i = 0; i <= deg - r; ++i) {
            const size_t g = first + (size_t)i;
            const double width = knots[g + (size_t)deg + 1] - knots[g + (size_t)r];
            pc_vec3 *a = &pts[(size_t)i * stride];
            *a = vec3_scale(vec3_sub(pts[(size_t)(i + 1) * stride], *a), scale / width);
        }
    }
}

int pc_span_third_bound(const pc_nurbs_surface *s, size_t span_u, size_t span_v,
                        double m3[4])
{
    if (s->rational)
        return 0;
    const int p = s->deg_u, q = s->deg_v;
    const size_t first_u = span_u - (size_t)p, first_v = span_v - (size_t)q;
    const size_t row = (size_t)p + 1;
    pc_vec3 block[PC_MAX_ORDER * PC_MAX_ORDER];
    for (int k = 0; k <= 3; ++k) {
        const int a = 3 - k, b = k; /* orders in u and v */
        m3[k] = 0.0;
        if (a > p || b > q)
            continue; /* that derivative vanishes */
        for (int j = 0; j <= q; ++j)
            for (int i = 0; i <= p; ++i) {
                const double *c = s->cw + 4 * ((first_v + (size_t)j) * s->n_u + first_u +
                                               (size_t)i);
                block[(size_t)j * row + (size_t)i] = vec3(c[0], c[1], c[2]);
            }
        for (int j = 0; j <= q; ++j)
            differentiate(&block[(size_t)j * row], 1, p, a, s->knots_u, first_u);
        for (int i = 0; i <= p - a; ++i)
            differentiate(&block[i], row, q, b, s->knots_v, first_v);
        for (int j = 0; j <= q - b; ++j)
            for (int i = 0; i <= p - a; ++i)
                m3[k] = fmax(m3[k], vec3_norm(block[(size_t)j * row + (size_t)i]));
    }
    return 1;
}
