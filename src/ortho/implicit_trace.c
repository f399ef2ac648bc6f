/* SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>

#include "common/error.h"
#include "ortho/implicit.h"

/* Samples of P used to estimate the length that sets the arc-length step. */
#define TRACE_LENGTH_SAMPLES 64
/* Step acceptance: |predicted - corrected| at most this fraction of the
 * step length, and x' turning by at most this angle (radians) over one
 * step. Both keep the corrector in the basin of the branch being traced
 * (a large jump would land on another foot point); accuracy of the output
 * is the fit's business, since every vertex is an exact foot point. */
#define TRACE_MAX_PREDICTOR_ERROR 0.1
#define TRACE_MAX_TURN 0.25
/* Smallest parameter step, relative to the domain: a branch that cannot
 * advance by more ends (at a centre of curvature when det K is small). */
#define TRACE_MIN_DT_REL 1e-12
/* |det K| below this where a branch stops advancing: the stop is a centre
 * of curvature (det K -> 0 like sqrt(t_c - t) at a fold of the normal map). */
#define TRACE_DET_SMALL 1e-3
/* The gradient at the seed times this is the floor below which a later
 * evaluation counts as a singular point of f (f's scale is the caller's). */
#define TRACE_GRAD_FLOOR_REL 1e-10
/* Largest number of rejected attempts in a row (each halves the step, so
 * this bounds the loop independently of TRACE_MIN_DT_REL). */
#define TRACE_MAX_REJECTS 200

static double curve_length_estimate(const projcurve_curve *c)
{
    double len = 0.0;
    pc_vec3 prev = vec3(0, 0, 0);
    for (int i = 0; i <= TRACE_LENGTH_SAMPLES; ++i) {
        pc_vec3 p;
        const double t = c->t0 + (c->t1 - c->t0) * (double)i / TRACE_LENGTH_SAMPLES;
        if (pc_curve_eval(c, t, 0, NULL, &p) != PROJCURVE_OK)
            return -1.0;
        if (i > 0)
            len += vec3_dist(p, prev);
        prev = p;
    }
    return len;
}

/* x(t + dt) predicted from pt: second-order Taylor (x'' by difference) or
 * classical RK4 on the ODE (32). *solved is 0 when a stage met a singular K. */
static projcurve_status predict(projcurve_context *ctx, const pc_implicit *imp, long long method,
                                const pc_implicit_point *pt, double dt, pc_vec3 *out,
                                int *solved)
{
    projcurve_status status;
    if (method == PROJCURVE_METHOD_RK4) {
        pc_vec3 k2 = pt->xd, k3 = pt->xd, k4 = pt->xd;
        int ok2 = 0, ok3 = 0, ok4 = 0;
        status = pc_implicit_velocity(ctx, imp, pt->t + 0.5 * dt,
                                      vec3_axpy(pt->x, 0.5 * dt, pt->xd), &k2, NULL, &ok2);
        if (status == PROJCURVE_OK)
            status = pc_implicit_velocity(ctx, imp, pt->t + 0.5 * dt,
                                          vec3_axpy(pt->x, 0.5 * dt, k2), &k3, NULL, &ok3);
        if (status == PROJCURVE_OK)
            status = pc_implicit_velocity(ctx, imp, pt->t + dt, vec3_axpy(pt->x, dt, k3), &k4,
                                          NULL, &ok4);
        const pc_vec3 sum = vec3_add(vec3_add(pt->xd, k4), vec3_scale(vec3_add(k2, k3), 2.0));
        *out = vec3_axpy(pt->x, dt / 6.0, sum);
        *solved = ok2 && ok3 && ok4;
        return status;
    }
    pc_vec3 xdd;
    status = pc_implicit_acceleration(ctx, imp, pt, &xdd, solved);
    *out = vec3_axpy(vec3_axpy(pt->x, dt, pt->xd), 0.5 * dt * dt, xdd);
    return status;
}

static double turn_angle(pc_vec3 a, pc_vec3 b)
{
    const double na = vec3_norm(a), nb = vec3_norm(b);
    if (na == 0.0 || nb == 0.0)
        return 0.0;
    const double c = vec3_dot(a, b) / (na * nb);
    return acos(c > 1.0 ? 1.0 : (c < -1.0 ? -1.0 : c));
}

static projcurve_status add_vertex(projcurve_context *ctx, pc_branch *b,
                                   const pc_implicit_point *pt)
{
    const double v[4] = {pt->t, pt->x.x, pt->x.y, pt->x.z};
    return pc_branch_add_point(ctx, b, 4, v);
}

/* The foot point of P(t0) reached from P(t0) itself: along the gradient
 * onto f = 0, then the foot-point Newton. */
static projcurve_status find_seed(projcurve_context *ctx, const pc_implicit *imp,
                                  pc_implicit_point *seed, int *solved, int *iterations)
{
    const double t0 = imp->curve->t0;
    pc_vec3 x;
    int converged = 0;
    if (pc_curve_eval(imp->curve, t0, 0, NULL, &x) != PROJCURVE_OK)
        return pc_fail(ctx, PROJCURVE_ERR_CALLBACK, "curve callback failed at t = %.17g", t0);
    projcurve_status status = pc_implicit_correct(ctx, imp, t0, &x, &converged, iterations);
    if (status != PROJCURVE_OK)
        return status;
    if (!converged)
        return pc_fail(ctx, PROJCURVE_ERR_NOT_CONVERGED,
                       "no foot point of P(t0) found on the implicit surface near P(t0)");
    return pc_implicit_point_at(ctx, imp, t0, x, seed, solved);
}

/* Tracing state of the one branch. */
typedef struct trace_run {
    pc_implicit imp;              /* with the gradient floor set from the seed */
    const pc_params *opts;
    double dt_fixed;              /* PARAM_STEP, 0 = arc-length steps */
    double ds_nominal, dt_max, dt_min;
    pc_stats *stats;
} trace_run;

/* Outcome of one attempted step. */
typedef struct attempt {
    pc_implicit_point next;
    double err;             /* |predicted - corrected| */
    int accepted;
    int index_changed;      /* corrected, but across a centre of curvature */
} attempt;

/* Predicts and corrects from cur to t_new and decides whether to accept. */
static projcurve_status try_step(projcurve_context *ctx, trace_run *run,
                                 const pc_implicit_point *cur, double t_new, attempt *out)
{
    const pc_implicit *imp = &run->imp;
    pc_vec3 x_pred, x;
    int solved = 0, converged = 0, iterations = 0, next_solved = 0;
    out->accepted = out->index_changed = 0;
    ++run->stats->steps;
    projcurve_status status =
        predict(ctx, imp, run->opts->method, cur, t_new - cur->t, &x_pred, &solved);
    x = x_pred;
    if (status == PROJCURVE_OK && solved)
        status = pc_implicit_correct(ctx, imp, t_new, &x, &converged, &iterations);
    run->stats->newton_iterations += iterations;
    if (status == PROJCURVE_OK && converged)
        status = pc_implicit_point_at(ctx, imp, t_new, x, &out->next, &next_solved);
    if (status != PROJCURVE_OK || !converged || !next_solved)
        return status;
    out->err = vec3_dist(x, x_pred);
    /* A change of the Morse index (which includes a sign change of det K)
     * means a centre of curvature lies within the step. */
    out->index_changed = out->next.index != cur->index;
    out->accepted = !out->index_changed &&
                    out->err <= TRACE_MAX_PREDICTOR_ERROR * vec3_dist(x, cur->x) +
                                    imp->newton_tol &&
                    turn_angle(cur->xd, out->next.xd) <= TRACE_MAX_TURN;
    return PROJCURVE_OK;
}

/* The parameter step of attempt number `attempt` from cur. */
static double step_size(const trace_run *run, const pc_implicit_point *cur, double ds,
                        int attempt_no)
{
    if (run->dt_fixed > 0.0)
        return ldexp(run->dt_fixed, -attempt_no);
    const double speed = vec3_norm(cur->xd);
    /* A foot point at rest (P' along the normal) gets the largest step. */
    return speed * run->dt_max > ds ? ds / speed : run->dt_max;
}

/* One accepted step from *cur, or a reason to stop: *ended is set with
 * *end when the branch ends; otherwise *cur advances. */
static projcurve_status step(projcurve_context *ctx, trace_run *run, pc_implicit_point *cur,
                             double *ds, int *ended, projcurve_branch_end *end)
{
    const double t1 = run->imp.curve->t1;
    int centre_seen = 0;
    for (int attempt_no = 0; attempt_no < TRACE_MAX_REJECTS; ++attempt_no) {
        double dt = step_size(run, cur, *ds, attempt_no);
        if (dt > t1 - cur->t)
            dt = t1 - cur->t;
        if (dt < run->dt_min)
            break;
        const double t_new = t1 - cur->t - dt <= run->dt_min ? t1 : cur->t + dt;
        attempt a;
        const projcurve_status status = try_step(ctx, run, cur, t_new, &a);
        if (status != PROJCURVE_OK)
            return status;
        centre_seen = centre_seen || a.index_changed;
        if (a.accepted) {
            /* Estimation error relative to the model size, as the engine's
             * statistics (the analogue of [SY13] eq. (3.8)). */
            const double rel = a.err / run->imp.model_size;
            run->stats->error_sum += rel;
            run->stats->error_count += 1.0;
            if (rel > run->stats->error_max)
                run->stats->error_max = rel;
            /* Grow back only after a first-try success: near a centre of
             * curvature the step then shrinks steadily instead of
             * oscillating across it. */
            if (attempt_no == 0 && *ds < run->ds_nominal)
                *ds = fmin(run->ds_nominal, 2.0 * *ds);
            *cur = a.next;
            return PROJCURVE_OK;
        }
        *ds *= 0.5;
    }
    *ended = 1;
    *end = (centre_seen || fabs(cur->det) < TRACE_DET_SMALL) ? PROJCURVE_END_CURVATURE_CENTRE
                                                             : PROJCURVE_END_FAILED;
    return PROJCURVE_OK;
}

projcurve_status pc_implicit_trace(projcurve_context *ctx, pc_implicit *imp,
                                   const pc_params *opts, projcurve_result *r)
{
    trace_run run;
    run.imp = *imp;
    run.opts = opts;
    run.stats = &r->stats;
    const double span = imp->curve->t1 - imp->curve->t0;
    run.dt_min = TRACE_MIN_DT_REL * span;
    run.dt_fixed = opts->param_step;
    run.dt_max = opts->arc_step_fraction * span;
    const double length = curve_length_estimate(imp->curve);
    if (length < 0.0)
        return pc_fail(ctx, PROJCURVE_ERR_CALLBACK, "curve callback failed");
    run.ds_nominal = opts->arc_step_fraction * (length > 0.0 ? length : imp->model_size);

    pc_implicit_point cur;
    int solved = 0, iterations = 0;
    projcurve_status status = find_seed(ctx, &run.imp, &cur, &solved, &iterations);
    r->stats.newton_iterations += iterations;
    if (status != PROJCURVE_OK)
        return status;
    pc_implicit_eval e;
    status = pc_implicit_call(ctx, &run.imp, cur.x, &e);
    if (status != PROJCURVE_OK)
        return status;
    run.imp.grad_floor = TRACE_GRAD_FLOOR_REL * vec3_norm(e.grad);
    imp->grad_floor = run.imp.grad_floor;

    pc_branch *branch = NULL;
    status = pc_result_add_branch(ctx, r, &branch);
    if (status == PROJCURVE_OK)
        status = add_vertex(ctx, branch, &cur);
    if (status != PROJCURVE_OK)
        return status;
    branch->start = PROJCURVE_START_CURVE_START;
    branch->end = PROJCURVE_END_CURVE_END;
    r->stats.points += 1;
    if (!solved) {
        branch->end = PROJCURVE_END_CURVATURE_CENTRE;
        return PROJCURVE_OK;
    }

    double ds = run.ds_nominal;
    const long long max_points = opts->max_points;
    const double t0 = imp->curve->t0, t_span = imp->curve->t1 - t0;
    while (cur.t < imp->curve->t1) {
        /* a step (prediction and correction) is the budget's unit */
        if (pc_budget_check(opts->budget, (cur.t - t0) / t_span) != PROJCURVE_OK) {
            branch->end = PROJCURVE_END_LIMIT;
            return pc_budget_fail(opts->budget, ctx);
        }
        int ended = 0;
        projcurve_branch_end end = PROJCURVE_END_FAILED;
        status = step(ctx, &run, &cur, &ds, &ended, &end);
        if (status != PROJCURVE_OK)
            return status;
        if (ended) {
            branch->end = end;
            return PROJCURVE_OK;
        }
        if ((long long)branch->n_points >= max_points) {
            branch->end = PROJCURVE_END_LIMIT;
            return pc_fail(ctx, PROJCURVE_ERR_LIMIT_REACHED,
                           "implicit projection reached the point limit %lld", max_points);
        }
        status = add_vertex(ctx, branch, &cur);
        if (status != PROJCURVE_OK)
            return status;
        r->stats.points += 1;
    }
    return PROJCURVE_OK;
}
