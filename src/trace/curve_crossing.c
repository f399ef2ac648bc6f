/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Where a branch of a ray projection meets the curve. A point q of the
 * directional projection is one only when it lies on the ray from P(t):
 * lambda(t) = (S(q(t)) - P(t)).Dir >= 0. The equations G = 0 the tracer
 * follows do not see lambda: where the curve passes through S they go on
 * smoothly to points behind it. So the tracer watches lambda's sign and,
 * when a step lands behind, the crossing lambda = 0 is located between the
 * last point in front and that step; the branch ends there
 * (PROJCURVE_END_CURVE_CROSSING), and a branch born there starts with
 * PROJCURVE_START_CURVE_CROSSING.
 */
#include "trace/tracer.h"

#include <math.h>

/* Bound of the locating iteration: bisection alone takes any step of the
 * tracer (at most the whole domain) below PC_TRACE_MIN_STEP in 45 halvings,
 * and the Illinois iteration is superlinear. */
#define PC_CROSSING_MAX_ITER 60

double pc_trace_lambda(const pc_tracer *tr, const pc_proj_point *p)
{
    const pc_vec3 dir = tr->proj->ray_dir != NULL ? tr->proj->ray_dir(tr->proj, p) : tr->dir;
    return vec3_dot(vec3_sub(p->s, p->p), dir);
}

int pc_trace_behind(const pc_tracer *tr, const pc_proj_point *p)
{
    if (!tr->ray)
        return 0;
    const double cosine = fmax(fabs(p->det), PC_PROJECTOR_DET_FOLD);
    const double band = fmax(tr->behind_tol, tr->lambda_tol * (1.0 + 1.0 / cosine));
    return pc_trace_lambda(tr, p) < -band;
}

static double clamp(double x, double lo, double hi)
{
    return x < lo ? lo : (x > hi ? hi : x);
}

/* The corrected point of the branch at t, predicted from the known point
 * `from`; 0 when the corrector or the derivatives fail there. */
static int point_at(pc_tracer *tr, const pc_proj_point *from, double t, pc_proj_point *out)
{
    const pc_projector *proj = tr->proj;
    double uv[2];
    pc_predict_taylor(from, t - from->t, uv);
    uv[0] = clamp(uv[0], tr->dom[0], tr->dom[1]);
    uv[1] = clamp(uv[1], tr->dom[2], tr->dom[3]);
    int iterations = 0;
    const int ok = proj->correct(proj, t, uv, &iterations);
    tr->r->stats.newton_iterations += (double)iterations;
    return ok && proj->derivatives(proj, t, uv[0], uv[1], out);
}

int pc_locate_crossing(pc_tracer *tr, const pc_proj_point *front, const pc_proj_point *back,
                       pc_proj_point *out)
{
    pc_proj_point a = *front; /* the farthest point known in front */
    double fa = pc_trace_lambda(tr, &a);
    const double fb = pc_trace_lambda(tr, back);
    double tb = back->t;
    double wa = fa, wb = fb; /* the secant's values, halved by Illinois */
    int bisect = !(fb < 0.0) || !(fa > fb); /* no usable secant */
    int side = 0;     /* which end moved last: +1 a, -1 b (Illinois) */
    int advanced = 0;
    for (int k = 0; k < PC_CROSSING_MAX_ITER; ++k) {
        if (fabs(fa) <= tr->lambda_tol || !(fabs(tb - a.t) > tr->min_step))
            break;
        double t = 0.5 * (a.t + tb);
        if (!bisect) {
            /* the secant's zero, when strictly inside the bracket (the
             * Illinois halving keeps it from creeping up on one end) */
            const double x = a.t + (tb - a.t) * wa / (wa - wb);
            if (x > fmin(a.t, tb) && x < fmax(a.t, tb))
                t = x;
        }
        pc_proj_point p;
        if (!point_at(tr, &a, t, &p)) {
            /* no point there: what lies beyond is unknown, so shrink the
             * bracket and go on by halving */
            tb = t;
            bisect = 1;
            continue;
        }
        const double fp = pc_trace_lambda(tr, &p);
        if (fp < 0.0) {
            tb = t;
            wb = fp;
            if (side == -1)
                wa *= 0.5;
            side = -1;
        } else {
            a = p;
            fa = wa = fp;
            advanced = 1;
            if (side == +1)
                wb *= 0.5;
            side = +1;
        }
    }
    if (!advanced)
        return 0;
    *out = a;
    return 1;
}
