/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Narrowing the jump sweep's step over small patches (tracer.h,
 * docs/tracing.md). The sweep's checks are at least 1/PC_SWEEP_MAX_CHECKS
 * of the domain apart, and in practice ds / |P'| / 2: a patch whose image
 * along the rays is crossed by the curve within less than that (a small
 * surface under a long curve) can lie wholly between two checks, neither
 * of whose rays meets it, and its branch is never found. The finder's
 * step_may_skip tells when that may be (a box test on the curve piece
 * between the checks); the step is then halved until it says no (the
 * check lands where a ray meets the patch's box, or the piece no longer
 * reaches it) or the step reaches its floor. A check so placed runs the
 * full search (branches.c).
 *
 * A patch a traced branch crosses between the checks is accounted for:
 * its hits there are on that branch (a second branch born and gone within
 * the step on the same patch is the sweep's ordinary limit, ~2 ds). So
 * the trail handed to the finder is the traced polylines over [ta, tb].
 */
#include <math.h>

#include "trace/tracer.h"

/* Liang-Barsky: narrows [*lo, *hi] to the s with p s <= q; 0 when it
 * becomes empty. */
static int clip(double p, double q, double *lo, double *hi)
{
    if (p == 0.0)
        return q >= 0.0;
    const double r = q / p;
    if (p < 0.0)
        *lo = fmax(*lo, r);
    else
        *hi = fmin(*hi, r);
    return *lo <= *hi;
}

/* 1 when the (u, v) segment a + s (b - a), s in [0, 1], meets uv. */
static int segment_meets(const double a[2], const double b[2], const double uv[4])
{
    const double du = b[0] - a[0], dv = b[1] - a[1];
    double lo = 0.0, hi = 1.0;
    return clip(-du, a[0] - uv[0], &lo, &hi) && clip(du, uv[1] - a[0], &lo, &hi) &&
           clip(-dv, a[1] - uv[2], &lo, &hi) && clip(dv, uv[3] - a[1], &lo, &hi);
}

/* The (u, v) of vertex segment p[0..5] ((t, u, v) twice) at t. */
static void uv_at(const double *p, double t, double out[2])
{
    const double w = p[3] > p[0] ? (t - p[0]) / (p[3] - p[0]) : 0.0;
    out[0] = p[1] + w * (p[4] - p[1]);
    out[1] = p[2] + w * (p[5] - p[2]);
}

/* Does branch b's polyline over [ta, tb] meet uv? Bounded by its vertices. */
static int branch_crosses(const pc_branch *b, double ta, double tb, const double uv[4])
{
    if (b->n_points < 2 || b->points[0] > tb || b->points[3 * (b->n_points - 1)] < ta)
        return 0;
    const double first = fmax(ta, b->points[0]);
    for (size_t j = pc_branch_segment_at(b, first); j + 1 < b->n_points; ++j) {
        const double *p = b->points + 3 * j;
        if (p[0] > tb)
            break;
        double a[2], c[2];
        uv_at(p, fmax(ta, p[0]), a);
        uv_at(p, fmin(tb, p[3]), c);
        if (segment_meets(a, c, uv))
            return 1;
    }
    return 0;
}

static int trail_crosses(const pc_sweep_trail *self, const double uv[4])
{
    const projcurve_result *r = self->data;
    for (size_t i = 0; i < r->n_branches; ++i)
        if (branch_crosses(&r->branches[i], self->ta, self->tb, uv))
            return 1;
    return 0;
}

double pc_sweep_narrow(pc_tracer *tr, pc_seed_finder *finder, double t, double dt,
                       int *narrowed)
{
    *narrowed = 0;
    if (finder->step_may_skip == NULL || tr->n_narrowed >= PC_SWEEP_MAX_NARROWED)
        return dt;
    const double floor_dt = ldexp(tr->t_end - tr->t_begin, -PC_SWEEP_NARROW_FLOOR_LOG2);
    pc_sweep_trail trail = {trail_crosses, tr->r, t, t};
    /* dt >= floor_dt halves at most log2(dt / floor_dt) <= 64 times (dt
     * is at most the domain, the floor 2^-24 of it) */
    for (int k = 0; k < 64 && dt > floor_dt; ++k) {
        trail.tb = t + dt >= tr->t_end ? tr->t_end : t + dt;
        if (!finder->step_may_skip(finder, t, trail.tb, &trail))
            break;
        dt = fmax(0.5 * dt, floor_dt);
        *narrowed = 1;
    }
    if (*narrowed && ++tr->n_narrowed == PC_SWEEP_MAX_NARROWED)
        tr->narrow_capped_at = t;
    return dt;
}
