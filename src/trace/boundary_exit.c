/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Locating where a branch leaves the surface's domain ([SY13] s3.4, the
 * boundary case of jumping). The crossing parameter solves
 * side(q(t)) = boundary value; each iteration predicts it from the
 * second-order Taylor model at the farthest point known inside (so the
 * iteration converges like Newton's on t), corrects there, and keeps a
 * bracket [inside, outside] in t: a prediction outside the bracket, or a
 * correction that fails, bisects instead.
 */
#include "trace/tracer.h"

#include <math.h>

/* Bound of the locating iteration: with bisection as a fallback, 60 halvings
 * take any bracket below PC_TRACE_MIN_STEP. */
#define PC_EXIT_MAX_ITER 60
/* A point this close (fraction of the domain width) is snapped even when the
 * iteration ran out of bracket before reaching PC_TRACE_BOUNDARY_TOL. */
#define PC_EXIT_LOOSE_TOL 1e-9

/* Smallest x in (0, xmax] with a + b x + c x^2 / 2 = 0, or -1. */
static double first_root(double a, double b, double c, double xmax)
{
    double r1 = -1.0, r2 = -1.0;
    const double qa = 0.5 * c;
    if (fabs(qa) * xmax <= 1e-14 * fabs(b)) {
        if (b != 0.0)
            r1 = -a / b;
    } else {
        const double disc = b * b - 4.0 * qa * a;
        if (disc < 0.0)
            return -1.0;
        const double q = -0.5 * (b + copysign(sqrt(disc), b));
        r1 = q / qa;
        if (q != 0.0)
            r2 = a / q;
    }
    double best = -1.0;
    if (r1 > 0.0 && r1 <= xmax)
        best = r1;
    if (r2 > 0.0 && r2 <= xmax && (best < 0.0 || r2 < best))
        best = r2;
    return best;
}

/* A branch on a side whose rate across it is below this fraction of its
 * rate along it (both relative to the domain's widths) runs along that side
 * (a foot point on the seam of a closed surface): it does not leave through
 * it, whatever the rounding of q' says. */
#define PC_EXIT_ALONG_SIDE 1e-6

/* The sides (bits 0..3: u0, u1, v0, v1) that p lies on, within
 * PC_TRACE_BOUNDARY_TOL, and runs along. Such a side is no exit of the
 * branch: it is left out of the crossings, the margin and the snap, so
 * that the exit is located on the side it does leave through. */
static unsigned sides_along(const double dom[4], const pc_proj_point *p)
{
    const double wu = dom[1] - dom[0] > 0.0 ? dom[1] - dom[0] : 1.0;
    const double wv = dom[3] - dom[2] > 0.0 ? dom[3] - dom[2] : 1.0;
    const double ru = fabs(p->du) / wu, rv = fabs(p->dv) / wv;
    const double off[4] = {(p->u - dom[0]) / wu, (dom[1] - p->u) / wu, (p->v - dom[2]) / wv,
                           (dom[3] - p->v) / wv};
    unsigned along = 0;
    for (int k = 0; k < 4; ++k) {
        const double across = k < 2 ? ru : rv, parallel = k < 2 ? rv : ru;
        if (off[k] <= PC_TRACE_BOUNDARY_TOL && across <= PC_EXIT_ALONG_SIDE * parallel)
            along |= 1u << k;
    }
    return along;
}

/* pc_domain_margin over the sides not in skip. */
static double margin_except(const double dom[4], double u, double v, unsigned skip)
{
    const double wu = dom[1] - dom[0] > 0.0 ? dom[1] - dom[0] : 1.0;
    const double wv = dom[3] - dom[2] > 0.0 ? dom[3] - dom[2] : 1.0;
    const double off[4] = {(u - dom[0]) / wu, (dom[1] - u) / wu, (v - dom[2]) / wv,
                           (dom[3] - v) / wv};
    double m = INFINITY;
    for (int k = 0; k < 4; ++k)
        if (!(skip & (1u << k)))
            m = fmin(m, off[k]);
    return m;
}

/* Where the Taylor model at p, moving in direction s, first meets a side of
 * the domain not in skip within a parameter distance gap; -1 if it does
 * not. */
static double first_crossing(const double dom[4], const pc_proj_point *p, double s, double gap,
                             unsigned skip)
{
    const double sides[4][4] = {
        /* offset from the side, first and second derivative along x = s t */
        {p->u - dom[0], s * p->du, p->ddu, 0},
        {p->u - dom[1], s * p->du, p->ddu, 0},
        {p->v - dom[2], s * p->dv, p->ddv, 0},
        {p->v - dom[3], s * p->dv, p->ddv, 0},
    };
    double best = -1.0;
    for (int k = 0; k < 4; ++k) {
        if (skip & (1u << k))
            continue;
        const double x = first_root(sides[k][0], sides[k][1], sides[k][2], gap);
        if (x > 0.0 && (best < 0.0 || x < best))
            best = x;
    }
    return best;
}

/* Puts (u, v) exactly on the nearest side not in skip. */
static void snap_to_boundary(const double dom[4], pc_proj_point *p, unsigned skip)
{
    const double d[4] = {p->u - dom[0], dom[1] - p->u, p->v - dom[2], dom[3] - p->v};
    const double w[2] = {dom[1] - dom[0], dom[3] - dom[2]};
    int side = 0;
    double best = INFINITY;
    for (int k = 0; k < 4; ++k) {
        const double rel = d[k] / (w[k / 2] > 0.0 ? w[k / 2] : 1.0);
        if (!(skip & (1u << k)) && rel < best) {
            best = rel;
            side = k;
        }
    }
    if (side < 2)
        p->u = dom[side];
    else
        p->v = dom[side];
}

static double clamp(double x, double lo, double hi)
{
    return x < lo ? lo : (x > hi ? hi : x);
}

int pc_locate_exit(pc_tracer *tr, const pc_proj_point *cur, double h, pc_proj_point *out)
{
    const pc_projector *proj = tr->proj;
    const double s = h > 0.0 ? 1.0 : -1.0;
    pc_proj_point in = *cur;
    double gap = fabs(h); /* t-distance from `in` to a parameter known outside */
    int advanced = 0;
    const unsigned along = sides_along(tr->dom, cur);
    if (along == 0xfu)
        return -1;   /* a domain of no extent */
    for (int k = 0; k < PC_EXIT_MAX_ITER && gap > tr->min_step; ++k) {
        double x = first_crossing(tr->dom, &in, s, gap, along);
        if (!(x > 0.0) || x >= gap)
            x = 0.5 * gap;
        const double t = in.t + s * x;
        double uv[2];
        pc_predict_taylor(&in, s * x, uv);
        uv[0] = clamp(uv[0], tr->dom[0], tr->dom[1]);
        uv[1] = clamp(uv[1], tr->dom[2], tr->dom[3]);
        int iterations = 0;
        const int ok = proj->correct(proj, t, uv, &iterations);
        tr->r->stats.newton_iterations += (double)iterations;
        pc_proj_point p;
        if (ok && proj->derivatives(proj, t, uv[0], uv[1], &p) &&
            !((in.det > 0.0 && p.det < 0.0) || (in.det < 0.0 && p.det > 0.0))) {
            in = p;
            advanced = 1;
            gap -= x;
            if (margin_except(tr->dom, in.u, in.v, along) <= PC_TRACE_BOUNDARY_TOL) {
                snap_to_boundary(tr->dom, &in, along);
                *out = in;
                return 1;
            }
        } else {
            gap = x;
        }
    }
    if (advanced && margin_except(tr->dom, in.u, in.v, along) <= PC_EXIT_LOOSE_TOL) {
        snap_to_boundary(tr->dom, &in, along);
        *out = in;
        return 1;
    }
    if (advanced) {
        *out = in;
        return 0;
    }
    return -1;
}
