/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Choosing the vertices: a march along the exact projection with step
 * control, as an adaptive ODE integrator controls its step. From the current
 * vertex, a candidate segment of parameter length h ends at the exact point
 * q(t + h); it is accepted when
 *   - its composed image is within eps_D of the exact curve (deviation.c),
 *   - each of its end tangents is within eps_T / 2 of the exact tangent
 *     there, so that at every joint the two pieces' tangents differ by at
 *     most eps_T (triangle inequality on angles: eps_T-G1, [SY13] s2
 *     step 4),
 * and the next h is predicted from how far the candidate was from the
 * bounds: the distance grows as h^2 and the tangent error as h for a smooth
 * curve. Pieces thus come out close to the longest the tolerances allow,
 * instead of being halved until they fit.
 *
 * Runs go from one fixed vertex (branch end or knot-line crossing of the
 * traced polyline) to the next; a candidate whose chord leaves the patch is
 * cut at the exact knot-line crossing. Where the corrector cannot reach the
 * exact curve down to the parameter floor, the run gets a gap (refine.c)
 * up to the next exact point known. At a knot line S may have a crease
 * (C0 knots, e.g. every knot of a degree-1 surface): the exact projection
 * then has a corner there, so each piece is held to the exact tangent on its
 * own side, and that joint keeps the corner of the exact curve.
 */
#include <math.h>

#include "refine/refine_internal.h"
#include "trace/projector.h"

/* The fold threshold of the projector contract on the normalised det J:
 * below it q' is not resolved and the tracer ends a branch there (a
 * silhouette). The refinement uses the same floor. */
#define PC_REFINE_DET_FOLD PC_PROJECTOR_DET_FOLD

#define PC_MARCH_GROW_MAX 2.0     /* largest step growth after a success */
#define PC_MARCH_SHRINK_MIN 0.1   /* largest step cut after a failure */
#define PC_MARCH_STEP_SAFETY 0.9  /* aim a little inside the bounds */
/* Rejections in a row before a candidate is taken anyway: the step has then
 * shrunk by at least PC_MARCH_SHRINK_MIN^... it never happens for a curve
 * the corrector can follow; the bound only guarantees termination. */
#define PC_MARCH_MAX_REJECTIONS 60

/* One-sided tangents by differences: the step, as a fraction of the
 * branch's t range (and at most a quarter of the segment). The angle error
 * is about curvature x step, the rounding error newton_tol / step: both far
 * below any eps_T at this size. */
#define PC_SIDE_STEP_REL 1e-6
/* ... and long enough on S that the corrector's tolerance (floored by the
 * rounding of the coordinates, which far from the origin is far above
 * 1e-12 of the model) moves the difference's direction by at most 1 /
 * PC_SIDE_STEP_ROUNDING rad: 1e-4 rad, below any eps_T. */
#define PC_SIDE_STEP_ROUNDING 1e4

/* Tangent of the exact projection at v, along increasing t (zero if the
 * projector cannot give it, e.g. at a fold: then no angle bound there). */
static pc_vec3 derivative_tangent(pc_refiner *r, const pc_rvertex *v)
{
    pc_proj_point pt;
    if (!r->proj->derivatives(r->proj, v->t, v->u, v->v, &pt) ||
        fabs(pt.det) < PC_REFINE_DET_FOLD) {
        r->last_singular = 1;
        return vec3(0.0, 0.0, 0.0);
    }
    r->last_has_d = 1;
    r->last_d[0] = pt.du;
    r->last_d[1] = pt.dv;
    pc_vec3 d[3];
    pc_nurbs_surface_eval(r->nurbs, v->u, v->v, 1, &r->hint_u, &r->hint_v, d);
    return vec3_add(vec3_scale(d[1], pt.du), vec3_scale(d[2], pt.dv));
}

pc_vec3 pc_refine_exact_tangent(pc_refiner *r, const pc_rvertex *v, const pc_rvertex *other)
{
    r->last_singular = 0;
    r->last_has_d = 0;
    if (!pc_refine_at_crease(r, v) || other->t == v->t)
        return derivative_tangent(r, v);
    double step = PC_SIDE_STEP_REL * r->t_range;
    pc_proj_point pt;
    if (r->proj->derivatives(r->proj, v->t, v->u, v->v, &pt) && pt.speed > 0.0)
        step = fmax(step, PC_SIDE_STEP_ROUNDING * r->proj->newton_tol / pt.speed);
    if (step > 0.25 * fabs(other->t - v->t))
        step = 0.25 * fabs(other->t - v->t);
    const double sign = other->t > v->t ? 1.0 : -1.0;
    pc_rvertex w;
    if (!(step > 0.0) || !pc_refine_exact_point(r, v, other, v->t + sign * step, &w))
        return derivative_tangent(r, v);
    const pc_vec3 d = vec3_sub(pc_refine_surface_point(r, w.u, w.v),
                               pc_refine_surface_point(r, v->u, v->v));
    return vec3_scale(d, sign);
}

/* Stores in v the q' that the last pc_refine_exact_tangent got, if any. */
static void keep_derivative(const pc_refiner *r, pc_rvertex *v)
{
    v->has_d = r->last_has_d;
    v->d[0] = r->last_d[0];
    v->d[1] = r->last_d[1];
}

/* Angle between a and b in radians; 0 when either has no direction. */
static double angle_between(pc_vec3 a, pc_vec3 b)
{
    const double na = vec3_norm(a), nb = vec3_norm(b);
    if (!(na > 0.0) || !(nb > 0.0))
        return 0.0;
    return atan2(vec3_norm(vec3_cross(a, b)), vec3_dot(a, b));
}

/* The larger angle between the composed curve's end tangents and the exact
 * tangents t0 (start) and t1 (end). */
static double end_angle(int n, const double *cw, pc_vec3 t0, pc_vec3 t1)
{
    const pc_vec3 c0 = pc_refine_end_direction(n, cw, 0);
    const pc_vec3 c1 = pc_refine_end_direction(n, cw, 1);
    const double a0 = angle_between(c0, t0), a1 = angle_between(c1, t1);
    return a0 > a1 ? a0 : a1;
}

/* How much to scale the step: from the distance ratio (error ~ h^2) and the
 * angle ratio (error ~ h). */
static double step_factor(double ratio_d, double ratio_a)
{
    const double fd = ratio_d > 0.0 ? 1.0 / sqrt(ratio_d) : PC_MARCH_GROW_MAX;
    const double fa = ratio_a > 0.0 ? 1.0 / ratio_a : PC_MARCH_GROW_MAX;
    double f = PC_MARCH_STEP_SAFETY * (fd < fa ? fd : fa);
    if (f > PC_MARCH_GROW_MAX)
        f = PC_MARCH_GROW_MAX;
    if (f < PC_MARCH_SHRINK_MIN)
        f = PC_MARCH_SHRINK_MIN;
    return f;
}

/* Restarts the march at v, the end of a gap just output: the tangent on
 * from v into *t_cur, the step of the last accepted piece, no rejection. */
static void restart_after_gap(pc_refiner *r, const pc_rvertex *v, const pc_rvertex *b,
                              pc_rvertex *cur, pc_vec3 *t_cur, double *h, double h_ok,
                              int *rejections)
{
    *cur = *v;
    *t_cur = pc_refine_exact_tangent(r, cur, b);
    keep_derivative(r, cur);
    *h = pc_refine_march_start_step(r, h_ok);
    *rejections = 0;
}

/* The ratios of the piece cur-cand in patch to its bounds: its end angles
 * to the exact tangents t_cur, t_cand over eps_T / 2 (*ratio_a), and,
 * only when that passes (the cheap test first), its distance to the exact
 * curve over eps_D (*ratio_d, else 0). */
static void measure_piece(pc_refiner *r, const pc_bezier_patch *patch, const pc_rvertex *cur,
                          const pc_rvertex *cand, pc_vec3 t_cur, pc_vec3 t_cand,
                          double *ratio_d, double *ratio_a)
{
    double cw[PC_PIECE_MAX_CW], t_far;
    const int n = pc_refine_compose(patch, cur, cand, cw);
    *ratio_a = end_angle(n, cw, t_cur, t_cand) / r->half_angle;
    *ratio_d = 0.0;
    if (*ratio_a <= 1.0)
        *ratio_d = pc_refine_deviation(r, n, cw, cur, cand, r->eps_d, &t_far) / r->eps_d;
}

/* The candidate end for a step h from cur (pc_refine_march_candidate),
 * moved onto the knot line it crosses when it leaves cur's patch. Returns
 * 1 when the corrector reached it and it advances in t. A candidate that
 * does not advance (a knot-line crossing found at cur itself) is no step:
 * accepted, it was output again and again at the same t until the piece
 * limit (linkrods.step surface 15, 1,000,000 vertices at t = 0.981287). It
 * counts as a failed correction: a shorter step, then a gap. */
static int next_candidate(pc_refiner *r, const pc_rvertex *cur, const pc_rvertex *b, double h,
                          pc_rvertex *cand)
{
    int reached = pc_refine_march_candidate(r, cur, b, h, cand);
    if (reached && pc_refine_common_patch(r, cur, cand) == NULL)
        reached = pc_refine_knot_crossing(r, cur, cand, cand);
    return reached && cand->t > cur->t;
}

/* Outputs the piece cur-cand that the march takes: accepted (ok), or
 * forced (see PC_MARCH_MAX_REJECTIONS: then the angle pass has work to
 * do). A forced piece that cannot be measured (exact points inside out of
 * reach) or is at the step floor is a gap up to the next exact point
 * instead; a singular cand (a silhouette inside the run) ends the branch
 * there with a gap. *cand becomes the last vertex output. */
static projcurve_status output_piece(pc_refiner *r, const pc_rvertex *cur, pc_rvertex *cand,
                                     const pc_rvertex *b, int ok, double ratio_d, int singular,
                                     pc_vertex_list *out)
{
    if (!ok && (!isfinite(ratio_d) || !(cand->t - cur->t > r->min_dt))) {
        *cand = pc_refine_next_known(r, cur, b);
        return pc_refine_output_gap(r, out, cand, PC_GAP_FAILED);
    }
    r->forced += !ok;
    projcurve_status st = pc_refine_output(r, out, cand);
    if (st == PROJCURVE_OK && singular) {
        *cand = pc_refine_next_known(r, cand, b);
        st = pc_refine_output_gap(r, out, cand, PC_GAP_SILHOUETTE);
    }
    return st;
}

projcurve_status pc_refine_march(pc_refiner *r, const pc_rvertex *a, const pc_rvertex *b,
                                 pc_vertex_list *out)
{
    pc_rvertex cur = *a;
    pc_vec3 t_cur = pc_refine_exact_tangent(r, &cur, b);
    keep_derivative(r, &cur);
    double h = r->step > 0.0 ? pc_refine_march_start_step(r, r->step) : b->t - a->t;
    double h_ok = h; /* the last accepted step, to restart from after a gap */
    int rejections = 0;
    while (cur.t < b->t) {
        pc_rvertex cand;
        if (!next_candidate(r, &cur, b, h, &cand)) {
            h *= 0.5; /* the corrector failed: come closer */
            if (++rejections < PC_MARCH_MAX_REJECTIONS && h > r->min_dt)
                continue;
            /* The exact curve is out of reach from cur: a gap up to the
             * next exact point known (never a vertex off the projection). */
            cand = pc_refine_next_known(r, &cur, b);
            const projcurve_status st = pc_refine_output_gap(r, out, &cand, PC_GAP_FAILED);
            if (st != PROJCURVE_OK)
                return st;
            restart_after_gap(r, &cand, b, &cur, &t_cur, &h, h_ok, &rejections);
            continue;
        }
        const pc_bezier_patch *patch = pc_refine_common_patch(r, &cur, &cand);
        const double hh = cand.t - cur.t;
        const pc_vec3 t_cand = pc_refine_exact_tangent(r, &cand, &cur);
        const int singular = r->last_singular && cand.t < b->t;
        keep_derivative(r, &cand);
        double ratio_d, ratio_a;
        measure_piece(r, patch, &cur, &cand, t_cur, t_cand, &ratio_d, &ratio_a);
        const double f = step_factor(ratio_d, ratio_a);
        const int ok = ratio_d <= 1.0 && ratio_a <= 1.0;
        if (!ok && hh > r->min_dt && ++rejections < PC_MARCH_MAX_REJECTIONS) {
            h = hh * f;
            continue;
        }
        const projcurve_status st = output_piece(r, &cur, &cand, b, ok, ratio_d, singular, out);
        if (st != PROJCURVE_OK)
            return st;
        if (out->items[out->count - 2].gap) {
            restart_after_gap(r, &cand, b, &cur, &t_cur, &h, h_ok, &rejections);
            continue;
        }
        /* a step cut short by the run end or a knot line says nothing
         * against the old h */
        h = hh * f > h || hh >= h ? hh * f : h;
        h_ok = h;
        /* the start tangent of the next piece: the other side at a knot line */
        t_cur = cand.t < b->t && pc_refine_at_crease(r, &cand)
                    ? pc_refine_exact_tangent(r, &cand, b)
                    : t_cand;
        cur = cand;
        rejections = 0;
    }
    r->step = h;
    return PROJCURVE_OK;
}
