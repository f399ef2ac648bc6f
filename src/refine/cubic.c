/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Cubic pcurves: the piece between two exact points a, b of the projection
 * q(t) = (u, v)(t) is the cubic Hermite interpolant
 *
 *   uv(s) = H(s), s = (t - a.t) / h, h = b.t - a.t,
 *   Bezier control points  a,  a + h q'(a) / 3,  b - h q'(b) / 3,  b,
 *
 * which matches q and q' at both ends, so uv(s) - q(a.t + s h) = O(h^4)
 * (the Hermite remainder h^4 s^2 (1 - s)^2 q''''(xi) / 24), against O(h^2)
 * for the chord. Composed with the Bezier patch holding it (compose_poly.c),
 * it is a Bezier curve of degree 3 (p + q) exactly on S whose end tangents
 * are Su u' + Sv v', the exact tangents of the projection: adjacent pieces
 * meet with G1 continuity wherever S is smooth. At a knot line of S, where S
 * may have a crease, q' is one-sided: S's derivatives are those of the
 * patch the piece lies in (the point is moved into the patch by one ulp,
 * which the span search of the NURBS evaluation then resolves to that
 * patch's span; the move changes q' by O(1e-16) relative).
 */
#include <math.h>

#include "compose/compose.h"
#include "refine/refine_internal.h"

/* x moved into [lo, hi] by one ulp when it sits on (or beyond) a bound. */
static double inside(double x, double lo, double hi)
{
    if (x <= lo)
        return nextafter(lo, hi);
    if (x >= hi)
        return nextafter(hi, lo);
    return x;
}

int pc_refine_uv_tangent(pc_refiner *r, const pc_rvertex *v, const pc_bezier_patch *patch,
                         double d[2])
{
    pc_proj_point pt;
    const double u = inside(v->u, patch->u0, patch->u1);
    const double w = inside(v->v, patch->v0, patch->v1);
    if (!r->proj->derivatives(r->proj, v->t, u, w, &pt))
        return 0;
    if (!isfinite(pt.du) || !isfinite(pt.dv))
        return 0;
    d[0] = pt.du;
    d[1] = pt.dv;
    return 1;
}

/* x put into [lo, hi] when outside by at most tol; 0 when farther out. */
static int clamp_near(double *x, double lo, double hi, double tol)
{
    if (*x < lo) {
        if (lo - *x > tol)
            return 0;
        *x = lo;
    } else if (*x > hi) {
        if (*x - hi > tol)
            return 0;
        *x = hi;
    }
    return 1;
}

int pc_refine_hermite(const pc_refiner *r, const pc_bezier_patch *patch, const pc_rvertex *a,
                      const pc_rvertex *b, const double d0[2], const double d1[2], double uv[8])
{
    const double third = (b->t - a->t) / 3.0;
    uv[0] = a->u;
    uv[1] = a->v;
    uv[2] = a->u + third * d0[0];
    uv[3] = a->v + third * d0[1];
    uv[4] = b->u - third * d1[0];
    uv[5] = b->v - third * d1[1];
    uv[6] = b->u;
    uv[7] = b->v;
    /* Inside the box, the curve is inside (convex hull): the composition is
     * exact. Rounding-level excursions (a curve running along a knot line)
     * are clamped: the move is far below any eps_D. */
    for (int k = 0; k < 4; ++k)
        if (!clamp_near(&uv[2 * k], patch->u0, patch->u1, r->snap) ||
            !clamp_near(&uv[2 * k + 1], patch->v0, patch->v1, r->snap))
            return 0;
    return 1;
}

projcurve_status pc_refine_add_cubic_piece(pc_refiner *r, pc_branch *b, const pc_rvertex *from,
                                           const pc_rvertex *to, const pc_rvertex *seg,
                                           int rational, int *done)
{
    *done = 0;
    const pc_rvertex *lo = seg == to ? from : to;
    const pc_bezier_patch *patch = pc_refine_common_patch(r, from, to);
    double uv[8], cw[PC_PIECE_MAX_CW];
    if (!seg->in_cubic || patch == NULL || !pc_refine_hermite(r, patch, lo, seg, seg->in_d0,
                                                              seg->in_d1, uv))
        return PROJCURVE_OK;
    if (from == seg) { /* the branch runs towards decreasing t */
        for (int k = 0; k < 2; ++k) {
            const double u = uv[2 * k], v = uv[2 * k + 1];
            uv[2 * k] = uv[6 - 2 * k];
            uv[2 * k + 1] = uv[7 - 2 * k];
            uv[6 - 2 * k] = u;
            uv[7 - 2 * k] = v;
        }
    }
    const int n = pc_compose_poly(patch, 3, uv, cw);
    if (n < 0)
        return PROJCURVE_OK;
    const projcurve_status st = pc_refine_store_piece(r, b, n, cw, rational, from, to);
    if (st == PROJCURVE_OK) {
        pc_branch_set_last_pcurve(b, 3, uv);
        *done = 1;
    }
    return st;
}
