/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Internals of the tracing engine shared by the files of trace/: the state
 * of one tracing run, the single-branch tracer, the predictors and the
 * boundary exit locator. Not used outside trace/.
 */
#ifndef PC_TRACE_TRACER_H
#define PC_TRACE_TRACER_H

#include <stddef.h>

#include "trace/curve_breaks.h"
#include "trace/trace.h"

/* A corrected point farther than this fraction of the predicted step from
 * the prediction, in (u, v) and on S, is taken as a jump to another sheet,
 * and the step is cut. */
#define PC_TRACE_MAX_CORRECTION 0.5
/* A step whose corrected point lies farther on S from the current one than
 * this multiple of its first-order move h |Q'| and of the arc-length step
 * has jumped to another sheet (the predictor's second-order term grows
 * without bound near a fold, and so does the correction the test above
 * allows). */
#define PC_TRACE_MAX_MOVE 4.0
/* A step whose chord on S is longer than this multiple of h max(|Q'|) at
 * its two ends passed a peak of the speed (a pair of folds, or another
 * branch reached across them): it is cut (tracer.c, chord_beyond_speed). */
#define PC_TRACE_CHORD_SPEED 1.0
/* Ahead of a cusp of the parametrisation (tracer.c, cusp_distance) a step
 * goes at most this fraction of the way there. */
#define PC_TRACE_CUSP_FRACTION 0.5
/* A branch ends on a cusp ahead once the rest of the way there is below
 * this fraction of the model size on S (or the corrector's tolerance, if
 * larger; 1e-4 of the default eps_D): closer, |Su x Sv| is ~1e-7 of its
 * size, the square-root law that estimates the way holds no better than
 * rounding, the corrector may reach the layer beyond, and the refinement
 * could not verify the last segments (at 1e-9 on linkrods.step surface 11,
 * curve 78, a branch ended FAILED 9e-9 in t before the cusp). */
#define PC_TRACE_CUSP_REACHED 1e-8
/* A step over which the parametrisation's area element |Su x Sv| changes
 * by more than this in its logarithm (|d ln |Su x Sv| / dt| h, at either
 * end) is checked at the middle of its (u, v) chord (tracer.c,
 * chord_turns_over). */
#define PC_TRACE_AREA_CHANGE 0.25
/* Boundary exits are located until (u, v) is within this fraction of the
 * domain's width from the boundary, then snapped onto it. */
#define PC_TRACE_BOUNDARY_TOL 1e-12
/* A step that would stop short of the end of the curve by less than this
 * fraction of itself is stretched to reach it. */
#define PC_TRACE_END_SLACK 1e-6
/* Bound of consecutive step halvings (the step stays above min_step). */
#define PC_TRACE_MAX_HALVINGS 64
/* Smallest step, as a fraction of the curve's domain. */
#define PC_TRACE_MIN_STEP 1e-13

typedef struct pc_tracer {
    projcurve_context *ctx;
    const pc_projector *proj;
    projcurve_result *r;
    int method;            /* PROJCURVE_METHOD_* */
    double ds;             /* arc-length step, model units */
    double param_step;     /* constant parameter step, 0 = arc-length step */
    double max_step;       /* cap of an arc-length step in t */
    double t_begin, t_end; /* curve domain */
    double dom[4];         /* surface domain u0, u1, v0, v1 */
    double min_step;       /* steps below this end the branch */
    size_t max_points;     /* budget of vertices over all branches */
    size_t n_points;       /* vertices added so far */
    int limit_hit;         /* max_points or the budget stopped a branch */
    int criteria_only;     /* the sweep searches only where the criteria ask */
    pc_budget *budget;     /* the call's (NULL: none), polled once per step */
    /* The share [lo, hi] of the tracing stage that the branch being traced
     * covers from the start of the curve to its end: its progress. */
    double progress_lo, progress_hi;
    /* Ray projections (directional): a point of F = 0 is a projection only
     * where lambda = (S - P).dir >= 0; a branch ends where lambda reaches 0
     * (PROJCURVE_END_CURVE_CROSSING). lambda_tol is the corrector's
     * tolerance, to which the crossing is located; behind_tol (eps_D) how
     * far behind a step may land before the branch ends there: a curve
     * lying on S only to its modelling tolerance stays one branch. */
    int ray;
    pc_vec3 dir;
    double lambda_tol, behind_tol;
    /* The curve's breaks (curve_breaks.h): every step lands exactly on the
     * next one, and the branch goes on with the derivatives of its side. */
    pc_curve_breaks breaks;
    /* Checks of the sweep whose step was narrowed (sweep_narrow.c), and
     * the t where their cap stopped the narrowing (NAN: it did not). */
    size_t n_narrowed;
    double narrow_capped_at;
    /* A step's chord on S must stay within the move its end speeds allow
     * (chord_beyond_speed, PC_TRACE_CHORD_SPEED): for projections whose
     * sweep searches seldom (foot points), where a branch a step passed
     * over is not found again. Off for ray projections, whose sweep
     * searches every ds (and whose constant-parameter steps keep the
     * point counts of [SY13] Table 1). */
    int jump_checks;
} pc_tracer;

/* Most checks of one sweep whose step may be narrowed over a small patch
 * (sweep_narrow.c): the sweep's own bound of 4096 checks again, four
 * times. Beyond it the sweep goes on without narrowing and the call ends
 * with LIMIT_REACHED (trace.h). */
#define PC_SWEEP_MAX_NARROWED (4 * 4096)
/* A narrowed step is at least 2^-this of the curve's domain. */
#define PC_SWEEP_NARROW_FLOOR_LOG2 24

/* The sweep's step dt from the check at t, halved while the finder's
 * step_may_skip says the rays over [t, t + dt] may jump over a patch, down
 * to 2^-PC_SWEEP_NARROW_FLOOR_LOG2 of the domain (at most that many
 * halvings past the floor of the unnarrowed step). *narrowed is set to 1
 * when it was halved. Counts the narrowed checks against
 * PC_SWEEP_MAX_NARROWED; past it returns dt unchanged. */
double pc_sweep_narrow(pc_tracer *tr, pc_seed_finder *finder, double t, double dt,
                       int *narrowed);

/* Polls the call's budget in full at curve parameter t (after
 * pc_budget_tick said it is due); 1 (and limit_hit set) when the budget
 * stops the call. */
int pc_tracer_budget_poll(pc_tracer *tr, double t);

/* One unit of tracing work done at curve parameter t: 1 (and limit_hit
 * set) when the budget stops the call. */
static inline int pc_tracer_budget_spent(pc_tracer *tr, double t)
{
    return pc_budget_tick(tr->budget) && pc_tracer_budget_poll(tr, t);
}

/* Traces one branch from the seed (a corrected point) towards t_stop
 * (direction +1: forward, -1: backward), appending vertices (t, u, v) to b;
 * the seed itself is appended first when add_seed. *why tells how it
 * ended (CURVE_END: t_stop reached). Statuses: OK, NO_MEMORY. */
projcurve_status pc_trace_run(pc_tracer *tr, const pc_seed *seed, int direction, double t_stop,
                              int add_seed, pc_branch *b, projcurve_branch_end *why);

/* Second-order Taylor predictor, [SY13] eq. (3.5): q(t + h) ~ q(t) +
 * q'(t) h + q''(t) h^2 / 2. (Inline: it is a few flops per traced point.) */
static inline void pc_predict_taylor(const pc_proj_point *pt, double h, double uv[2])
{
    const double half_h2 = 0.5 * h * h;
    uv[0] = pt->u + pt->du * h + pt->ddu * half_h2;
    uv[1] = pt->v + pt->dv * h + pt->ddv * half_h2;
}

/* Classical RK4 on the first-order system q' = f(t, q) ([SY13] eq. (3.2),
 * the method of its reference [16]). Returns 0 when f cannot be evaluated. */
int pc_predict_rk4(const pc_projector *proj, const pc_proj_point *pt, double h, double uv[2]);

/* Where the branch at `cur` leaves the domain within the step h (signed):
 * returns 1 with *out the exit point, snapped exactly onto the boundary;
 * 0 when the branch is still inside at the end of the search, *out then
 * holds the farthest corrected point reached (t != cur->t); -1 when
 * nothing better than cur was found. */
int pc_locate_exit(pc_tracer *tr, const pc_proj_point *cur, double h, pc_proj_point *out);

/* Ray projections: lambda = (S - P).dir at p, in model units. */
double pc_trace_lambda(const pc_tracer *tr, const pc_proj_point *p);

/* 1 when p lies behind the curve beyond the band that still counts as on
 * it: lambda below -max(behind_tol, lambda_tol (1 + 1 / |det|)) (the
 * corrector leaves S - P off the ray by up to its tolerance, which moves
 * lambda by that over the tangent of the angle between Dir and the
 * normal). Always 0 for projections without a ray. */
int pc_trace_behind(const pc_tracer *tr, const pc_proj_point *p);

/* Where the branch from `front` (lambda >= 0) to `back` (lambda < 0, at
 * most a step of the tracer away, either direction in t) meets the curve,
 * lambda = 0:
 * regula falsi (Illinois) on t with bisection as the fallback, each
 * iterate predicted by the Taylor model at the nearer known point and
 * corrected, until |lambda| <= lambda_tol or the bracket is below
 * min_step (at most PC_CROSSING_MAX_ITER iterations). Returns 1 with *out
 * the crossing (never behind), 0 when no corrected point better than
 * `front` was found (front is then the branch's last point). */
int pc_locate_crossing(pc_tracer *tr, const pc_proj_point *front, const pc_proj_point *back,
                       pc_proj_point *out);

/* Distance of (u, v) from the nearest side of the domain, as a fraction of
 * that side's width (0 on the boundary). */
double pc_domain_margin(const double dom[4], double u, double v);

/* [SY13] s3.4 matching: each active point (a branch's current point)
 * takes the nearest found point within ds (distance on S) not taken yet;
 * matched[k] (n_found entries) is set to 1 for the found points taken, so
 * that the others start new branches. */
void pc_match_seeds(const projcurve_surface *s, const pc_seed *active, size_t n_active,
                    const pc_seed *found, size_t n_found, double ds, unsigned char *matched);

#endif /* PC_TRACE_TRACER_H */
