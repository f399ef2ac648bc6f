/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * One branch, one direction: the loop of [SY13] s3 steps 2-4. At the
 * current point the projector gives q', q''; the step h comes from the
 * constant arc length ds (eq. (3.7), h = ds / |Q'|) or the constant
 * parameter step; the predictor (Taylor (3.5) or RK4) estimates q(t + h) and
 * Newton corrects it. A failed correction halves the step; a step never
 * passes the end of the curve, crosses a fold (a sign change of det J) or
 * leaves the domain (the exit is then located on the boundary), and never
 * passes a break of P (curve_breaks.h): it lands on it, and the branch
 * goes on from there with the derivatives of the side ahead.
 */
#include "trace/tracer.h"

#include <math.h>

#include "common/error.h"

typedef enum step_outcome { STEP_ACCEPT, STEP_REJECT, STEP_EXIT } step_outcome;

double pc_domain_margin(const double dom[4], double u, double v)
{
    const double wu = dom[1] - dom[0], wv = dom[3] - dom[2];
    const double mu = fmin(u - dom[0], dom[1] - u) / (wu > 0.0 ? wu : 1.0);
    const double mv = fmin(v - dom[2], dom[3] - v) / (wv > 0.0 ? wv : 1.0);
    return fmin(mu, mv);
}

/* (u, v) beyond a side by more than PC_TRACE_BOUNDARY_TOL of the domain's
 * width. A prediction beyond it by less is rounding, not an exit: a branch
 * running along a side (a foot point moving along the seam of a closed
 * surface) predicts points a few ulps outside at every step, and must not
 * end there. */
static int outside(const double dom[4], const double uv[2])
{
    const double mu = PC_TRACE_BOUNDARY_TOL * (dom[1] - dom[0]);
    const double mv = PC_TRACE_BOUNDARY_TOL * (dom[3] - dom[2]);
    return uv[0] < dom[0] - mu || uv[0] > dom[1] + mu || uv[1] < dom[2] - mv ||
           uv[1] > dom[3] + mv;
}

/* (u, v) within two strides (parameter length of the step) of a side. */
static int near_boundary(const double dom[4], const double uv[2], double stride)
{
    const double gap = fmin(fmin(uv[0] - dom[0], dom[1] - uv[0]),
                            fmin(uv[1] - dom[2], dom[3] - uv[1]));
    return gap <= 2.0 * stride;
}

static double clamp(double x, double lo, double hi)
{
    return x < lo ? lo : (x > hi ? hi : x);
}

static projcurve_status add_vertex(pc_tracer *tr, pc_branch *b, double t, double u, double v)
{
    if (b->n_points < b->cap_points) { /* the usual case, without a call */
        double *p = b->points + 3 * b->n_points++;
        p[0] = t;
        p[1] = u;
        p[2] = v;
    } else {
        const double p[3] = {t, u, v};
        const projcurve_status st = pc_branch_add_point(tr->ctx, b, 3, p);
        if (st != PROJCURVE_OK)
            return st;
    }
    tr->n_points++;
    tr->r->stats.points += 1.0;
    return PROJCURVE_OK;
}

int pc_tracer_budget_poll(pc_tracer *tr, double t)
{
    const double span = tr->t_end - tr->t_begin;
    const double at = span > 0.0 ? (t - tr->t_begin) / span : 0.0;
    const double f = tr->progress_lo + (tr->progress_hi - tr->progress_lo) * at;
    if (pc_budget_poll(tr->budget, f) == PROJCURVE_OK)
        return 0;
    tr->limit_hit = 1;
    return 1;
}

/* Step length in t (positive) at the current point, before halvings. */
static double nominal_step(const pc_tracer *tr, const pc_proj_point *cur)
{
    if (tr->param_step > 0.0)
        return tr->param_step;
    double speed = cur->speed;
    if (!(speed > 0.0) || !isfinite(speed))
        return tr->max_step;
    const double h = tr->ds / speed; /* [SY13] eq. (3.7) */
    return h < tr->max_step ? h : tr->max_step;
}

/* How far ahead in t (the run's direction `sign`) the branch at cur
 * reaches a cusp of the parametrisation, INFINITY when none is in sight.
 * Where a derivative of S vanishes and reverses (Sv along a v line that
 * folds back on itself: linkrods.step surface 11, docs/tracing.md
 * "Pleats"), the surface doubles back in layers, J = [e_i.Su, e_i.Sv] is
 * singular on the cusp line and two branches (a layer and the next) meet
 * and end there as at a fold; but |Su x Sv| vanishes with Sv while the
 * normalised det Dir.(Su x Sv) / |Su x Sv| does not (it jumps from about
 * -0.3 to +0.3), so neither the fold test nor the arc-length step (|Q'|
 * stays bounded) sees the end coming, and a step longer than the pleat
 * lands on the layer beyond the next, with det of the same sign. Towards
 * a cusp the branch runs like towards a fold, with the square-root law
 * |Su x Sv| ~ sqrt(t_c - t): d ln |Su x Sv| / dt = -1 / (2 (t_c - t)), so
 * t_c - t = 1 / (2 |rate|) when the area shrinks ahead. Near a fold
 * (|det| small) the fold's own handling applies instead. */
static double cusp_distance(const pc_proj_point *cur, double sign)
{
    const double rate = sign * cur->cusp_rate;
    if (!(rate < 0.0) || fabs(cur->det) < PC_PROJECTOR_DET_NEAR_FOLD)
        return INFINITY;
    return 0.5 / -rate;
}

/* The fold test: det J changes sign (or vanishes) only across a fold. */
static int crosses_fold(const pc_proj_point *a, const pc_proj_point *b)
{
    return (a->det > 0.0 && b->det < 0.0) || (a->det < 0.0 && b->det > 0.0);
}

/* Adds the estimation error of an accepted step to the statistics: the
 * projector's own measure ([SY13] eq. (3.8) for the directional kind), or
 * the residual at the guess relative to the model size. */
static void record_error(pc_tracer *tr, double residual_error)
{
    const double e = tr->proj->guess_error ? *tr->proj->guess_error : residual_error;
    tr->r->stats.error_sum += e;
    tr->r->stats.error_count += 1.0;
    if (e > tr->r->stats.error_max)
        tr->r->stats.error_max = e;
}

/* The correction from the prediction pred to uv, measured on S: farther
 * than PC_TRACE_MAX_CORRECTION times the predicted step's chord (cur to
 * pred). Asked only when the correction is long in (u, v): where S is
 * nearly degenerate (next to a collapsed edge, Su ~ 0) a long move in u is
 * a short one on S, the corrector's tolerance leaves u loose there, and the
 * (u, v) test alone would cut the step down to nothing. */
static int moved_far_on_surface(const pc_tracer *tr, const pc_proj_point *cur,
                                const double pred[2], const double uv[2])
{
    const pc_nurbs_surface *s = &tr->proj->surface->nurbs;
    pc_vec3 at_pred, at_uv;
    pc_nurbs_surface_eval(s, clamp(pred[0], tr->dom[0], tr->dom[1]),
                          clamp(pred[1], tr->dom[2], tr->dom[3]), 0, NULL, NULL, &at_pred);
    pc_nurbs_surface_eval(s, uv[0], uv[1], 0, NULL, NULL, &at_uv);
    const double noise = fmax(PC_TRACE_BOUNDARY_TOL * tr->proj->model_size, tr->proj->newton_tol);
    return vec3_dist(at_uv, at_pred) >
           PC_TRACE_MAX_CORRECTION * vec3_dist(at_pred, cur->s) + noise;
}

/* 1 when next lies farther on S from cur than PC_TRACE_MAX_MOVE times the
 * first-order move |t - cur.t| |Q'| of the step (at either end: the speed
 * grows towards a fold, and a step may end closer to one than it began), or
 * than the arc-length step ds, whichever is longer: next to a fold |Q'| is
 * the derivative of a square root and the move in a step can pass h |Q'|
 * many times while it stays within ds.
 * Near a centre of curvature on teapot surface 18 (a lifted diagonal) a
 * branch of minima, its corrector failing where the huge second-order
 * prediction made the step look near the boundary, had the exit search
 * step 1e-6 in t and 0.58 in v, onto the sheet of another branch, which it
 * then retraced; without a jump a step moves about h |Q'|. */
static int jumped_on_surface(const pc_tracer *tr, const pc_proj_point *cur,
                             const pc_proj_point *next)
{
    const double h = fabs(next->t - cur->t);
    const double speed = fmax(cur->speed, next->speed);
    const double noise = fmax(PC_TRACE_BOUNDARY_TOL * tr->proj->model_size, tr->proj->newton_tol);
    if (!isfinite(speed))
        return 0;
    return vec3_dist(next->s, cur->s) > PC_TRACE_MAX_MOVE * fmax(h * speed, tr->ds) + noise;
}

/* 1 when next lies farther on S from cur than the step can move along one
 * smooth branch: the chord is at most the arc length, the integral of the
 * speed |Q'|, so a chord longer than PC_TRACE_CHORD_SPEED times h
 * max(|Q'| at either end) means the speed peaked between the two points.
 * That happens next to a pair of folds the step passed over (a fold and
 * its partner 1e-3 apart in t, where the branch turns back and forth), so
 * the corrected point may lie on another branch of the same kind (the
 * fold test sees the sign of det twice changed, i.e. not at all): on
 * linkrods.step surface 1, curve 74, a step of 0.06 in t went from one
 * branch of foot points to another across two such pairs, and the
 * refinement could not verify the segment between. Cutting the step
 * resolves a mere bump of the speed after a few halvings (the bound
 * holds as h shrinks). */
static int chord_beyond_speed(const pc_tracer *tr, const pc_proj_point *cur,
                              const pc_proj_point *next)
{
    const double speed = fmax(cur->speed, next->speed);
    if (!(speed > 0.0) || !isfinite(speed))
        return 0;
    const double noise = fmax(PC_TRACE_BOUNDARY_TOL * tr->proj->model_size, tr->proj->newton_tol);
    return vec3_dist(next->s, cur->s) >
           PC_TRACE_CHORD_SPEED * fabs(next->t - cur->t) * speed + noise;
}

/* 1 when S seen from Dir turns over between cur and next although det
 * need not change sign: at the middle of the step's (u, v) chord det has
 * the other sign than at cur (both away from a fold, where the fold's own
 * tests apply and the sign of det is noise). Asked only where the cusp
 * rate says |Su x Sv| changes much over the step (PC_TRACE_AREA_CHANGE):
 * there the parametrisation may fold back on itself in layers
 * (docs/tracing.md, "Pleats"), and a step can pass two cusps (det
 * changing sign twice, which the fold test does not see) onto another
 * layer; cusp_distance sees a cusp ahead only once the area shrinks
 * towards it, not one behind a stretch where it first grows. On
 * linkrods.step surface 11, curve 78, a backward step from the middle
 * layer at t = 0.975 landed 0.094 before on the surface's edge, past the
 * cusp where that layer is born (t = 0.950) and across the inner layer,
 * det +0.38 at one end, +1e-5 at the other, -0.2 between. */
static int chord_turns_over(const pc_tracer *tr, const pc_proj_point *cur,
                            const pc_proj_point *next)
{
    const double h = fabs(next->t - cur->t);
    if (fabs(cur->det) < PC_PROJECTOR_DET_NEAR_FOLD ||
        !(fmax(fabs(cur->cusp_rate), fabs(next->cusp_rate)) * h > PC_TRACE_AREA_CHANGE))
        return 0;
    pc_proj_point mid;
    tr->proj->derivatives(tr->proj, 0.5 * (cur->t + next->t), 0.5 * (cur->u + next->u),
                          0.5 * (cur->v + next->v), &mid);
    return fabs(mid.det) >= PC_PROJECTOR_DET_NEAR_FOLD && (cur->det > 0.0) != (mid.det > 0.0);
}

/* 1 when the step from cur lands (nearly) on a cusp that cur did not see
 * ahead: at next the area element |Su x Sv| shrinks ahead so fast that
 * the rest of the way there (the square-root law of cusp_distance, taken
 * here also where det is small: at a cusp it is the ratio of two
 * vanishing terms) is less than PC_TRACE_CUSP_FRACTION of the step, and
 * at the middle of the step's (u, v) chord the rate says so too (towards
 * a cusp it grows as 1 / (t_c - t), there about 1 / h; at a pole it stays
 * bounded, and only at the pole itself, where Su x Sv is rounding, can it
 * be anything: a step onto the pole of a NURBS sphere is no landing on a
 * cusp). Where a branch runs between two cusps, the rate at cur tells
 * only the nearer one, and a corrector or exit locator that fails on the
 * layer beyond the other may bring the step right onto it: seen from an
 * eye 1e3 sizes above linkrods.step surface 11 (curve 78), a backward
 * step of 0.025 in t from the middle layer at t = 0.975 ended at the cusp
 * where that layer is born (t = 0.950, det 0.001) in one chord that the
 * refinement could not follow there. Cut, the step approaches that cusp
 * geometrically as cusp_distance makes the steps towards the cusp ahead. */
static int lands_on_cusp(const pc_tracer *tr, const pc_proj_point *cur,
                         const pc_proj_point *next)
{
    const double h = next->t - cur->t;
    const double limit = -0.5 / PC_TRACE_CUSP_FRACTION;
    if (fabs(cur->det) < PC_PROJECTOR_DET_NEAR_FOLD || !(next->cusp_rate * h < limit))
        return 0;
    pc_proj_point mid;
    tr->proj->derivatives(tr->proj, 0.5 * (cur->t + next->t), 0.5 * (cur->u + next->u),
                          0.5 * (cur->v + next->v), &mid);
    return mid.cusp_rate * h < PC_TRACE_CUSP_FRACTION * limit;
}

/* Predicts and corrects one step from cur to the curve parameter t. On
 * ACCEPT and EXIT, *next holds the new point (with its derivatives). */
static step_outcome try_step(pc_tracer *tr, const pc_proj_point *cur, double t,
                             pc_proj_point *next)
{
    const pc_projector *proj = tr->proj;
    const double h = t - cur->t;
    double pred[2];
    if (tr->method == PROJCURVE_METHOD_RK4) {
        if (!pc_predict_rk4(proj, cur, h, pred))
            return STEP_REJECT;
    } else {
        pc_predict_taylor(cur, h, pred);
    }
    const int left = outside(tr->dom, pred);
    double uv[2] = {clamp(pred[0], tr->dom[0], tr->dom[1]),
                    clamp(pred[1], tr->dom[2], tr->dom[3])};
    const double residual_error =
        proj->guess_error ? 0.0 : proj->residual(proj, t, uv[0], uv[1]) / proj->model_size;
    int iterations = 0;
    /* derived: 1 = *next holds the derivatives at the corrected point,
     * -1 = they failed there, 0 = not computed yet */
    int derived = 0, ok;
    if (proj->advance != NULL) {
        derived = proj->advance(proj, t, h, uv, &iterations, next);
        ok = derived != 0;
    } else {
        ok = proj->correct(proj, t, uv, &iterations);
    }
    tr->r->stats.newton_iterations += (double)iterations;
    const double su = pred[0] - cur->u, sv = pred[1] - cur->v;
    const double stride2 = su * su + sv * sv; /* squared (u, v) length of the step */
    if (!ok || (left && pc_domain_margin(tr->dom, uv[0], uv[1]) <= PC_TRACE_BOUNDARY_TOL)) {
        /* Near the boundary a failed correction most likely means the
         * branch left between the points: locate the exit rather than halve
         * the step (which would pile vertices up against the boundary). */
        if (!left && !near_boundary(tr->dom, pred, sqrt(stride2)))
            return STEP_REJECT;
        const int found = pc_locate_exit(tr, cur, h, next);
        if (found >= 0 && (jumped_on_surface(tr, cur, next) ||
                           (tr->jump_checks && chord_beyond_speed(tr, cur, next)) ||
                           chord_turns_over(tr, cur, next) || lands_on_cusp(tr, cur, next)))
            return STEP_REJECT;
        return found == 1 ? STEP_EXIT : (found == 0 ? STEP_ACCEPT : STEP_REJECT);
    }
    /* A corrector that moved far from the prediction has left for another
     * sheet of the projection: cut the step instead. (Squares first: the
     * usual correction is far below the limit.) */
    const double mu = uv[0] - pred[0], mv = uv[1] - pred[1];
    const double moved2 = mu * mu + mv * mv;
    const double limit = PC_TRACE_MAX_CORRECTION;
    if (moved2 > limit * limit * stride2) {
        const double noise =
            PC_TRACE_BOUNDARY_TOL * (tr->dom[1] - tr->dom[0] + tr->dom[3] - tr->dom[2]);
        if (sqrt(moved2) > limit * sqrt(stride2) + noise &&
            moved_far_on_surface(tr, cur, pred, uv))
            return STEP_REJECT;
    }
    if (derived == 0)
        derived = proj->derivatives(proj, t, uv[0], uv[1], next) ? 1 : -1;
    if (derived < 0 || crosses_fold(cur, next) || jumped_on_surface(tr, cur, next) ||
        (tr->jump_checks && chord_beyond_speed(tr, cur, next)) ||
        chord_turns_over(tr, cur, next) || lands_on_cusp(tr, cur, next))
        return STEP_REJECT;
    record_error(tr, residual_error);
    return STEP_ACCEPT;
}

/* Why a branch whose step cannot be made to succeed stops. */
static projcurve_branch_end stall_reason(const pc_proj_point *cur)
{
    return fabs(cur->det) < PC_PROJECTOR_DET_NEAR_FOLD ? PROJCURVE_END_SILHOUETTE
                                                   : PROJCURVE_END_FAILED;
}

/* The step from cur to next landed behind the curve (beyond the band
 * pc_trace_behind allows). The vertices this run added at the end with
 * lambda < 0 (within the band: a curve lying on S only to its modelling
 * tolerance) are taken back, down to min_keep, and the branch ends where
 * lambda reaches 0 after the last vertex in front, located to the
 * corrector's tolerance; when every vertex it may take back is behind, it
 * ends on the last one left. */
static projcurve_status end_at_crossing(pc_tracer *tr, const pc_proj_point *cur,
                                        const pc_proj_point *next, pc_branch *b,
                                        size_t min_keep, projcurve_branch_end *why)
{
    *why = PROJCURVE_END_CURVE_CROSSING;
    pc_proj_point front = *cur, back = *next;
    while (b->n_points > min_keep && pc_trace_lambda(tr, &front) < 0.0) {
        back = front;
        b->n_points--;
        tr->n_points--;
        tr->r->stats.points -= 1.0;
        const double *v = b->points + 3 * (b->n_points - 1);
        if (!tr->proj->derivatives(tr->proj, v[0], v[1], v[2], &front))
            return PROJCURVE_OK;
    }
    pc_proj_point at;
    if (pc_trace_lambda(tr, &front) < 0.0 || !pc_locate_crossing(tr, &front, &back, &at))
        return PROJCURVE_OK;
    if (tr->n_points >= tr->max_points) {
        tr->limit_hit = 1;
        *why = PROJCURVE_END_LIMIT;
        return PROJCURVE_OK;
    }
    return add_vertex(tr, b, at.t, at.u, at.v);
}

/* q', q'' and det at (t, u, v) as seen from the side of t that the run
 * goes to: at a break of P (curve_breaks.h) the curve is evaluated at the
 * neighbouring double on that side, and out->t is t again. Returns the
 * projector's derivatives() result. */
static int derive_one_sided(const pc_tracer *tr, double t, double u, double v, int direction,
                            pc_proj_point *out)
{
    const pc_projector *proj = tr->proj;
    const double at = pc_curve_break_side(proj->curve, t, direction, tr->breaks.order);
    const int ok = proj->derivatives(proj, at, u, v, out);
    out->t = t;
    return ok;
}

/* The curve parameter of the next step of length h from t: never past the
 * end t_stop (remaining away) nor past the next break of P, landing
 * exactly on either (a step within rounding of one is stretched to it, so
 * that it is never missed by a sliver). */
static double step_target(pc_tracer *tr, double t, double t_stop, double sign, double h,
                          double remaining, int *on_break)
{
    *on_break = 0;
    if (h >= remaining - PC_TRACE_END_SLACK * h)
        return t_stop;
    const double brk = pc_curve_breaks_next(&tr->breaks, t, sign > 0.0 ? 1 : -1);
    const double to_break = sign * (brk - t);
    if (to_break < remaining && h >= to_break - PC_TRACE_END_SLACK * h) {
        *on_break = 1;
        return brk;
    }
    return t + sign * h;
}

projcurve_status pc_trace_run(pc_tracer *tr, const pc_seed *seed, int direction, double t_stop,
                              int add_seed, pc_branch *b, projcurve_branch_end *why)
{
    const pc_projector *proj = tr->proj;
    const double sign = direction >= 0 ? 1.0 : -1.0;
    projcurve_status st = PROJCURVE_OK;
    /* vertices before this run's, and its seed, are never taken back */
    const size_t min_keep = b->n_points + (add_seed ? 1 : 0);
    if (add_seed) {
        if (tr->n_points >= tr->max_points) {
            tr->limit_hit = 1;
            *why = PROJCURVE_END_LIMIT;
            return PROJCURVE_OK;
        }
        st = add_vertex(tr, b, seed->t, seed->u, seed->v);
        if (st != PROJCURVE_OK)
            return st;
    }
    /* the current point and the one being tried, swapped on acceptance */
    pc_proj_point points[2];
    pc_proj_point *cur = &points[0], *next = &points[1];
    if (!derive_one_sided(tr, seed->t, seed->u, seed->v, direction, cur)) {
        *why = stall_reason(cur);
        return PROJCURVE_OK;
    }
    if (pc_trace_behind(tr, cur)) { /* not a projection: nothing to trace */
        *why = PROJCURVE_END_CURVE_CROSSING;
        return PROJCURVE_OK;
    }
    double scale = 1.0; /* halvings after failed corrections, [SY13] s3.3 */
    /* Each pass adds a vertex or halves the step. Vertices are bounded by
     * the budget, and consecutive halvings by min_step (max_step / min_step
     * < 2^60), so this bound is never the one hit. */
    const size_t max_passes = PC_TRACE_MAX_HALVINGS * (tr->max_points + 1);
    for (size_t pass = 0; pass < max_passes; ++pass) {
        /* a pass (one prediction and correction) is the budget's unit */
        if (pc_tracer_budget_spent(tr, cur->t)) {
            *why = PROJCURVE_END_LIMIT;
            return PROJCURVE_OK;
        }
        const double remaining = sign * (t_stop - cur->t);
        if (remaining <= tr->min_step) {
            *why = PROJCURVE_END_CURVE_END;
            return PROJCURVE_OK;
        }
        if (fabs(cur->det) < PC_PROJECTOR_DET_FOLD) {
            *why = PROJCURVE_END_SILHOUETTE;
            return PROJCURVE_OK;
        }
        /* a cusp ahead: the branch ends on it (J singular, as at a fold)
         * once the rest of the way on S is below PC_TRACE_CUSP_REACHED,
         * and a step goes at most PC_TRACE_CUSP_FRACTION of the way there
         * (so it never passes it: the approach is geometric, as towards a
         * fold) */
        const double cusp = cusp_distance(cur, sign);
        const double reached = fmax(proj->newton_tol, PC_TRACE_CUSP_REACHED * proj->model_size);
        if (cusp * cur->speed <= reached) {
            *why = PROJCURVE_END_SILHOUETTE;
            return PROJCURVE_OK;
        }
        double h = fmin(nominal_step(tr, cur), PC_TRACE_CUSP_FRACTION * cusp) * scale;
        /* the floor of a cut step: 1e-13 of the domain in t, and a move of
         * the projection on S (h |Q'|) no longer than the corrector's
         * tolerance, below which the points it would add cannot be told
         * apart from this one */
        if (h < tr->min_step || (scale < 1.0 && h * cur->speed <= proj->newton_tol)) {
            *why = stall_reason(cur);
            return PROJCURVE_OK;
        }
        /* never step over the end of the curve or a break of P */
        int on_break;
        const double t_next = step_target(tr, cur->t, t_stop, sign, h, remaining, &on_break);
        tr->r->stats.steps += 1.0;
        const step_outcome out = try_step(tr, cur, t_next, next);
        if (out == STEP_REJECT) {
            scale *= 0.5;
            continue;
        }
        if (pc_trace_behind(tr, next)) /* the curve passed through S */
            return end_at_crossing(tr, cur, next, b, min_keep, why);
        if (tr->n_points >= tr->max_points) {
            tr->limit_hit = 1;
            *why = PROJCURVE_END_LIMIT;
            return PROJCURVE_OK;
        }
        st = add_vertex(tr, b, next->t, next->u, next->v);
        if (st != PROJCURVE_OK)
            return st;
        if (out == STEP_EXIT) {
            *why = PROJCURVE_END_BOUNDARY;
            return PROJCURVE_OK;
        }
        /* on a break of P: go on with the derivatives of the side ahead */
        if (on_break && !derive_one_sided(tr, next->t, next->u, next->v, direction, next)) {
            *why = stall_reason(next);
            return PROJCURVE_OK;
        }
        pc_proj_point *const done = cur;
        cur = next;
        next = done;
        scale = scale < 0.5 ? 2.0 * scale : 1.0;
    }
    *why = PROJCURVE_END_FAILED;
    return PROJCURVE_OK;
}
