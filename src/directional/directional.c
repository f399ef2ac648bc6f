/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Directional projection equations ([SY13] s3.2-s3.3) in the frame form of
 * DESIGN.md: G(u, v, t) = [e1.(S - P); e2.(S - P)] with (e1, e2) an
 * orthonormal pair perpendicular to Dir. G = 0 is the paper's (3.1); its
 * Jacobian J = [e_i.Su, e_i.Sv] has det J = Dir.(Su x Sv), so it is singular
 * exactly where Dir is tangent to S (a fold, seen from Dir).
 *
 * This is the hot path of tracing: one surface and one curve evaluation
 * per traced point (see docs/tracing.md, "Cost"), so everything here works
 * from the cached evaluation and compares squared norms.
 */
#include "directional/directional.h"

#include <math.h>

#include "nurbs/span_bound.h"
#include "trace/cusp_rate.h"
#include "trace/precision.h"

/* Without a third-derivative bound (rational surfaces), a Newton step is in
 * the quadratic regime (its cubic remainder, and the change of the second
 * derivatives that shift_cache keeps, negligible) when its image is below
 * this fraction of the model size. */
#define PC_NEWTON_QUADRATIC_REGIME 1e-7
/* A step is accepted without a new evaluation when the bound of the
 * residual it leaves behind is below this fraction of eps1 (room for the
 * rounding of the evaluation and of the Taylor shift). */
#define PC_NEWTON_PREDICTED_SAFETY 0.25
/* Fixed-point iterations solving the quadratic model G + J d + E S''[d, d]/2
 * = 0 for the step d; each gains the factor |J^-1 S'' d| (~1e-5 for the
 * steps of tracing), so three reach rounding. */
#define PC_NEWTON_MODEL_ITER 3
/* A step is accepted without a new evaluation only when q'' computed with
 * the second derivatives from before it stays within this relative
 * distance of q'' at the point it reaches (second_drift)... */
#define PC_NEWTON_SECOND_DRIFT 1e-7
/* ... or, when the guess was predicted over a curve step h, when that
 * error moves the next prediction (h^2 q'' / 2) by at most this fraction
 * of the correction just made: the prediction error then grows by 0.1 %
 * at most, and stays the predictor's own. */
#define PC_PREDICTION_DRIFT 1e-3
/* Newton diverges when its residual fails to decrease this many times. */
#define PC_NEWTON_MAX_NON_DECREASE 3
/* Jacobians with |det| at most this times the square of their scale are
 * singular (as mat2_solve). */
#define PC_SINGULAR_DET 1e-15

static const pc_directional_data *dir_data(const pc_projector *self)
{
    return (const pc_directional_data *)self->data;
}

/* P, P', P'' at t into the cache unless it holds them. Returns 0 when the
 * curve callback fails. */
static int evaluate_curve(const pc_projector *self, double t)
{
    pc_directional_cache *c = dir_data(self)->cache;
    if (c->curve_valid && c->t == t)
        return 1;
    c->curve_valid = 0;
    if (pc_curve_eval(self->curve, t, 2, &c->hint_t, c->curve) != PROJCURVE_OK) {
        c->callback_failed = 1;
        return 0;
    }
    const pc_directional_data *d = dir_data(self);
    c->frame_d1[0] = vec3_dot(d->e1, c->curve[1]);
    c->frame_d1[1] = vec3_dot(d->e2, c->curve[1]);
    c->frame_d2[0] = vec3_dot(d->e1, c->curve[2]);
    c->frame_d2[1] = vec3_dot(d->e2, c->curve[2]);
    c->t = t;
    c->curve_valid = 1;
    return 1;
}

/* Evaluates S and P with derivatives up to order 2 at (u, v) and t into
 * the cache, each unless it already holds it. Returns 0 when the curve
 * callback fails. */
static int evaluate(const pc_projector *self, double t, double u, double v)
{
    pc_directional_cache *c = dir_data(self)->cache;
    if (!c->surf_valid || c->u != u || c->v != v) {
        pc_nurbs_surface_eval(&self->surface->nurbs, u, v, 2, &c->hint_u, &c->hint_v, c->surf);
        c->u = u;
        c->v = v;
        c->span_u = c->hint_u;
        c->span_v = c->hint_v;
        c->surf_valid = 1;
    }
    return evaluate_curve(self, t);
}

/* The 2x2 Jacobian J = [e_i.Su, e_i.Sv] = [a b; c d] and its inverse. */
typedef struct jacobian {
    double a, b, c, d, det, inv_det;
} jacobian;

/* Returns 0 when J is singular (|det| <= PC_SINGULAR_DET scale^2). */
static inline int jacobian_at(const pc_directional_data *dd, const pc_vec3 *s, jacobian *j)
{
    j->a = vec3_dot(dd->e1, s[1]);
    j->b = vec3_dot(dd->e1, s[2]);
    j->c = vec3_dot(dd->e2, s[1]);
    j->d = vec3_dot(dd->e2, s[2]);
    j->det = j->a * j->d - j->b * j->c;
    const double scale = fabs(j->a) + fabs(j->b) + fabs(j->c) + fabs(j->d);
    if (!(fabs(j->det) > 1e-300) || fabs(j->det) <= PC_SINGULAR_DET * scale * scale)
        return 0;
    j->inv_det = 1.0 / j->det;
    return 1;
}

/* x = J^-1 r */
static inline void jacobian_solve(const jacobian *j, const double r[2], double x[2])
{
    const double x0 = (j->d * r[0] - j->b * r[1]) * j->inv_det;
    const double x1 = (j->a * r[1] - j->c * r[0]) * j->inv_det;
    x[0] = x0;
    x[1] = x1;
}

/* |J^-1|_F^2 (|J^-1|_F bounds |J^-1 x| / |x|) */
static double jacobian_inverse_norm2(const jacobian *j)
{
    return (j->a * j->a + j->b * j->b + j->c * j->c + j->d * j->d) * j->inv_det * j->inv_det;
}

/* S''[d, d] / 2 = (Suu du^2 + 2 Suv du dv + Svv dv^2) / 2 */
static inline pc_vec3 half_second(const pc_vec3 *s, double du, double dv)
{
    return vec3_add(vec3_add(vec3_scale(s[3], 0.5 * du * du), vec3_scale(s[4], du * dv)),
                    vec3_scale(s[5], 0.5 * dv * dv));
}

/* Moves the cached evaluation to the accepted point (nu, nv) by its Taylor
 * expansion (second order for S, first for Su, Sv; Suu, Suv, Svv kept).
 * The callers bound the error this leaves in S (the corrector's
 * acceptance tests); the error in the derivatives only moves the next
 * prediction. So the derivatives at the converged point cost no
 * evaluation. */
static void shift_cache(const pc_projector *self, double nu, double nv)
{
    pc_directional_cache *c = dir_data(self)->cache;
    pc_vec3 *s = c->surf;
    const double du = nu - c->u, dv = nv - c->v;
    s[0] = vec3_add(vec3_axpy(vec3_axpy(s[0], du, s[1]), dv, s[2]), half_second(s, du, dv));
    s[1] = vec3_axpy(vec3_axpy(s[1], du, s[3]), dv, s[4]);
    s[2] = vec3_axpy(vec3_axpy(s[2], du, s[4]), dv, s[5]);
    c->u = nu;
    c->v = nv;
}

static double clamp(double x, double lo, double hi)
{
    return x < lo ? lo : (x > hi ? hi : x);
}

/* The derivative bounds of the span of the cached evaluation, or NULL
 * (rational surface): computed once per span visited. */
static const pc_span_bound_entry *span_bound(const pc_projector *self)
{
    pc_directional_cache *c = dir_data(self)->cache;
    if (c->bound_state < 0)
        return NULL;
    if (c->bound != NULL && c->bound->span_u == c->span_u && c->bound->span_v == c->span_v)
        return c->bound;
    c->bound = pc_span_bound_table_get(&c->bounds, &self->surface->nurbs, c->span_u, c->span_v);
    if (c->bound == NULL)
        c->bound_state = -1;
    return c->bound;
}

/* Whether (u + du, v + dv) lies in the span of the cached evaluation,
 * where its third-derivative bound holds (after span_bound()). */
static int in_span(const pc_projector *self, double du, double dv)
{
    const pc_directional_cache *c = dir_data(self)->cache;
    const double *box = c->bound->box;
    const double u = c->u + du, v = c->v + dv;
    return u >= box[0] && u <= box[1] && v >= box[2] && v <= box[3];
}

/* Looks for a step d from the cached evaluation whose residual |G(q + d)|
 * is bounded by `target`, on the local quadratic model G + J d + E S''[d,
 * d] / 2 of G (E = [e1; e2]): the bound is the model's own residual plus
 * the cubic Taylor remainder of the span's bound m3. d starts as the
 * Newton step (model residual E S''[d, d] / 2); while the bound is above
 * target, d moves towards the model's zero by the fixed point
 * J d = -(G + E S''[d, d] / 2). Returns 1 when d was found (it stays in
 * the span, where m3 holds). */
static int model_step(const pc_projector *self, const double g[2], const jacobian *j,
                      const double *m3, double target, double d[2])
{
    const pc_directional_data *dd = dir_data(self);
    const pc_vec3 *s = dd->cache->surf;
    /* the model's zero lies within ~|J^-1 S'' d| |d| of the Newton step:
     * a remainder above target there is above it at the zero too */
    double room = target - pc_span_cubic_remainder(m3, d[0], d[1]);
    if (!(room >= 0.0))
        return 0;
    pc_vec3 w = half_second(s, d[0], d[1]);
    double r0 = vec3_dot(dd->e1, w), r1 = vec3_dot(dd->e2, w);
    for (int k = 0;; ++k) {
        if (!in_span(self, d[0], d[1]))
            return 0;
        /* |r| + remainder <= target, without the square root */
        if (k > 0)
            room = target - pc_span_cubic_remainder(m3, d[0], d[1]);
        if (room >= 0.0 && r0 * r0 + r1 * r1 <= room * room)
            return 1;
        if (k == PC_NEWTON_MODEL_ITER)
            return 0;
        const double rhs[2] = {-(g[0] + vec3_dot(dd->e1, w)), -(g[1] + vec3_dot(dd->e2, w))};
        jacobian_solve(j, rhs, d);
        w = half_second(s, d[0], d[1]);
        r0 = g[0] + j->a * d[0] + j->b * d[1] + vec3_dot(dd->e1, w);
        r1 = g[1] + j->c * d[0] + j->d * d[1] + vec3_dot(dd->e2, w);
    }
}

/* The square of a bound of how far q'' at the point reached by the step d
 * moves when it is computed with the second derivatives of the cached
 * evaluation (what shift_cache keeps). With M the span's third-derivative
 * bound, |S''(q + d) - S''| <= M |d| per component, and q'' = J^-1 E (P''
 * - S''[q', q']) moves by at most |J^-1|_F |dS''[q', q']|. q1 is q' at
 * the cached evaluation. */
static double second_drift2(const jacobian *j, const double *m3, const double d[2],
                            const double q1[2])
{
    const double x = fabs(d[0]), y = fabs(d[1]);
    const double duu = m3[0] * x + m3[1] * y, duv = m3[1] * x + m3[2] * y,
                 dvv = m3[2] * x + m3[3] * y;
    const double a = fabs(q1[0]), b = fabs(q1[1]);
    const double moved = duu * a * a + 2.0 * duv * a * b + dvv * b * b;
    return jacobian_inverse_norm2(j) * moved * moved;
}

/* The square of the size of the terms that make q'' at the cached
 * evaluation, (|J^-1|_F (|P''| + |S''[q', q']|))^2, the scale of
 * second_drift2. */
static double second_scale2(const pc_projector *self, const jacobian *j, const double q1[2])
{
    const pc_directional_data *dd = dir_data(self);
    const pc_vec3 acc = vec3_scale(half_second(dd->cache->surf, q1[0], q1[1]), 2.0);
    const pc_vec3 p2 = dd->cache->curve[2];
    const double size = sqrt(vec3_dot(p2, p2)) + sqrt(vec3_dot(acc, acc));
    return jacobian_inverse_norm2(j) * size * size;
}

/* The cheap form of the tests below for the small steps of fine tracing,
 * from the span's largest bounds M2, M3 and l = |du| + |dv|: the residual
 * the Newton step d leaves, E S''[d, d] / 2 + cubic remainder, is at most
 * M2 l^2 / 2 + M3 l^3 / 6, and q'' at q + d computed with the kept second
 * derivatives moves by at most |J^-1|_F M3 l (|u'| + |v'|)^2. Accepts the
 * step when the first is below target and the second within the
 * prediction budget (h != 0) or PC_NEWTON_SECOND_DRIFT of q''. */
static int small_step(const pc_projector *self, double h, const jacobian *j,
                      const double step[2], double target)
{
    const pc_directional_cache *c = dir_data(self)->cache;
    const double x = fabs(step[0]), y = fabs(step[1]), l = x + y;
    const double m2_max = c->bound->m2_max, m3_max = c->bound->m3_max;
    if (!(0.5 * m2_max * l * l + m3_max * l * l * l * (1.0 / 6.0) <= target) ||
        !in_span(self, step[0], step[1]))
        return 0;
    double q1[2];
    jacobian_solve(j, c->frame_d1, q1);
    const double speed = fabs(q1[0]) + fabs(q1[1]);
    const double moved = m3_max * l * speed * speed;
    const double drift2 = jacobian_inverse_norm2(j) * moved * moved;
    const double shift2 = 0.25 * h * h * h * h * drift2; /* of the next prediction */
    if (h != 0.0 && shift2 <= PC_PREDICTION_DRIFT * PC_PREDICTION_DRIFT * (x * x + y * y))
        return 1;
    return drift2 <= PC_NEWTON_SECOND_DRIFT * PC_NEWTON_SECOND_DRIFT * second_scale2(self, j, q1);
}

/* Whether the Newton step `step` from the cached evaluation ends the
 * correction without evaluating S again; *nu, *nv get the point it then
 * reaches. Accepted are: the paper's first test (s3.3), the step's image
 * |du Su + dv Sv| <= eps1; and a step d on the quadratic model
 * (model_step) whose bounded residual is below PC_NEWTON_PREDICTED_SAFETY
 * eps1 and whose second derivatives, kept from before it, leave q''
 * accurate: within PC_NEWTON_SECOND_DRIFT of its size, or, for a guess
 * predicted over the curve step h (h != 0), moving the next prediction,
 * h^2 q'' / 2, by at most PC_PREDICTION_DRIFT |d|. On a rational surface,
 * without a bound, the second test is replaced by the quadratic-regime
 * test: an image below PC_NEWTON_QUADRATIC_REGIME of the model size and
 * the residual it leaves, |S''[d, d]| / 2, below the same fraction of
 * eps1. */
static int final_step(const pc_projector *self, double h, const double g[2], const jacobian *j,
                      const double step[2], double *nu, double *nv)
{
    const pc_directional_data *dd = dir_data(self);
    const pc_directional_cache *c = dd->cache;
    const pc_vec3 *s = c->surf;
    const double eps1 = self->newton_tol;
    const double safe = PC_NEWTON_PREDICTED_SAFETY * eps1;
    const pc_vec3 image = vec3_axpy(vec3_scale(s[1], step[0]), step[1], s[2]);
    const double moved2 = vec3_dot(image, image);
    *nu = c->u + step[0];
    *nv = c->v + step[1];
    if (moved2 <= eps1 * eps1) /* [SY13] s3.3 test 1 */
        return 1;
    const pc_span_bound_entry *bound = span_bound(self);
    const double *m3 = bound != NULL ? bound->m3 : NULL;
    if (m3 != NULL && small_step(self, h, j, step, safe))
        return 1;
    if (m3 != NULL) {
        double d[2] = {step[0], step[1]};
        if (!model_step(self, g, j, m3, safe, d))
            return 0;
        double q1[2];
        jacobian_solve(j, c->frame_d1, q1);
        const double drift2 = second_drift2(j, m3, d, q1);
        const double shift2 = 0.25 * h * h * h * h * drift2; /* of the next prediction */
        const double budget2 =
            PC_PREDICTION_DRIFT * PC_PREDICTION_DRIFT * (d[0] * d[0] + d[1] * d[1]);
        const double exact2 = PC_NEWTON_SECOND_DRIFT * PC_NEWTON_SECOND_DRIFT;
        if (!(h != 0.0 && shift2 <= budget2) &&
            !(drift2 <= exact2 * second_scale2(self, j, q1)))
            return 0;
        *nu = c->u + d[0];
        *nv = c->v + d[1];
        return 1;
    }
    const double regime = PC_NEWTON_QUADRATIC_REGIME * self->model_size;
    const pc_vec3 left = half_second(s, step[0], step[1]);
    return moved2 <= regime * regime && vec3_dot(left, left) <= safe * safe;
}

/* Newton on G = 0 at fixed t ([SY13] s3.3, with the frame form of (3.9)),
 * for a guess predicted over the curve step h (0: any other guess).
 * Stops on any of the paper's three tests: the step's image
 * |du Su + dv Sv| <= eps1, |S - P| <= eps1, or the sine
 * |Dir x (S - P)| / |S - P| <= eps2; plus |Dir x (S - P)| <= eps1, and a
 * step on the local quadratic model whose residual is bounded below eps1
 * (final_step; the point after it is then not evaluated again:
 * shift_cache). Fails on the iteration cap, a singular Jacobian, or a
 * residual that stops decreasing (divergence, or a solution outside the
 * domain that the clamp holds on the boundary). */
static int newton(const pc_projector *self, double t, double h, double uv[2], int *iterations)
{
    const pc_directional_data *d = dir_data(self);
    const double *dom = self->surface->nurbs.domain;
    const double eps1 = self->newton_tol;
    /* the sine test res2 <= eps2^2 dist2 with eps2 = eps1 / size, as products */
    const double size2 = self->model_size * self->model_size;
    double u = uv[0], v = uv[1];
    double prev_res2 = INFINITY;
    int non_decrease = 0, converged = 0, it = 0;

    for (; it <= self->newton_max_iter; ++it) {
        if (!evaluate(self, t, u, v))
            break;
        const pc_vec3 *s = d->cache->surf;
        const pc_vec3 diff = vec3_sub(s[0], d->cache->curve[0]);
        const double g[2] = {vec3_dot(d->e1, diff), vec3_dot(d->e2, diff)};
        const double res2 = g[0] * g[0] + g[1] * g[1]; /* |Dir x (S - P)|^2 */
        const double dist2 = vec3_dot(diff, diff);
        if (it == 0) /* [SY13] eq. (3.8) */
            d->cache->guess_error = dist2 > 0.0 ? sqrt(res2 / dist2) : 0.0;
        if (res2 <= eps1 * eps1 || dist2 <= eps1 * eps1 || res2 * size2 <= eps1 * eps1 * dist2) {
            converged = 1;
            break;
        }
        if (it == self->newton_max_iter)
            break;
        non_decrease = res2 >= prev_res2 ? non_decrease + 1 : 0;
        if (non_decrease >= PC_NEWTON_MAX_NON_DECREASE)
            break;
        prev_res2 = res2;
        jacobian j;
        if (!jacobian_at(d, s, &j))
            break;
        double step[2];
        const double rhs[2] = {-g[0], -g[1]};
        jacobian_solve(&j, rhs, step);
        const double nu = clamp(u + step[0], dom[0], dom[1]);
        const double nv = clamp(v + step[1], dom[2], dom[3]);
        double fu, fv;
        if (nu == u + step[0] && nv == v + step[1] &&
            final_step(self, h, g, &j, step, &fu, &fv)) {
            shift_cache(self, fu, fv);
            u = fu;
            v = fv;
            converged = 1;
            ++it;
            break;
        }
        u = nu;
        v = nv;
    }
    if (iterations)
        *iterations = it;
    uv[0] = u;
    uv[1] = v;
    return converged;
}

static int dir_correct(const pc_projector *self, double t, double uv[2], int *iterations)
{
    return newton(self, t, 0.0, uv, iterations);
}

/* q' and q'' from differentiating G(q(t), t) = 0 once and twice:
 *   J q'  = [e_i.P']
 *   J q'' = [e_i.P''] - [e_i.(Suu u'^2 + 2 Suv u'v' + Svv v'^2)]
 * (DESIGN.md; equal to [SY13] eqs. (3.2), (3.3)). */
static int dir_derivatives(const pc_projector *self, double t, double u, double v,
                           pc_proj_point *out)
{
    const pc_directional_data *d = dir_data(self);
    pc_proj_point_start(out, t, u, v);
    if (!evaluate(self, t, u, v))
        return 0;
    const pc_vec3 *s = d->cache->surf;
    const pc_vec3 *p = d->cache->curve;
    out->s = s[0];
    out->p = p[0];
    jacobian j;
    const int regular = jacobian_at(d, s, &j);
    const pc_vec3 n = vec3_cross(s[1], s[2]);
    const double area2 = vec3_dot(n, n);
    out->det = area2 > 0.0 ? (j.a * j.d - j.b * j.c) / sqrt(area2) : 0.0;
    if (!regular)
        return 0;

    double q1[2];
    const double *d1 = d->cache->frame_d1, *d2 = d->cache->frame_d2;
    jacobian_solve(&j, d1, q1);
    const pc_vec3 acc = half_second(s, q1[0], q1[1]); /* S''[q', q'] / 2 */
    const double r2[2] = {d2[0] - 2.0 * vec3_dot(d->e1, acc), d2[1] - 2.0 * vec3_dot(d->e2, acc)};
    double q2[2];
    jacobian_solve(&j, r2, q2);
    out->du = q1[0];
    out->dv = q1[1];
    out->ddu = q2[0];
    out->ddv = q2[1];
    out->speed = vec3_norm(vec3_axpy(vec3_scale(s[1], q1[0]), q1[1], s[2])); /* eq. (3.6) */
    out->cusp_rate = pc_cusp_rate(s, n, area2, q1);
    return isfinite(out->speed) && isfinite(out->ddu) && isfinite(out->ddv);
}

/* q' alone, J q' = [e_i.P'], from S and its first derivatives evaluated
 * apart from the cache (which keeps the corrector's evaluation): the
 * stages of the RK4 baseline need nothing more. P comes from the curve
 * cache, so the last stage's evaluation at t + h serves the corrector. */
static int dir_slope(const pc_projector *self, double t, double u, double v, double dq[2])
{
    const pc_directional_data *d = dir_data(self);
    pc_directional_cache *c = d->cache;
    if (!evaluate_curve(self, t))
        return 0;
    pc_vec3 s[3];
    pc_nurbs_surface_eval(&self->surface->nurbs, u, v, 1, &c->hint_u, &c->hint_v, s);
    jacobian j;
    if (!jacobian_at(d, s, &j))
        return 0;
    jacobian_solve(&j, c->frame_d1, dq);
    return isfinite(dq[0]) && isfinite(dq[1]);
}

static int dir_advance(const pc_projector *self, double t, double h, double uv[2],
                       int *iterations, pc_proj_point *next)
{
    if (!newton(self, t, h, uv, iterations))
        return 0;
    return dir_derivatives(self, t, uv[0], uv[1], next) ? 1 : -1;
}

/* |Dir x (S - P)|: the distance of S(u, v) from the projection line. */
static double dir_residual(const pc_projector *self, double t, double u, double v)
{
    const pc_directional_data *d = dir_data(self);
    if (!evaluate(self, t, u, v))
        return INFINITY;
    const pc_vec3 diff = vec3_sub(d->cache->surf[0], d->cache->curve[0]);
    const double g1 = vec3_dot(d->e1, diff), g2 = vec3_dot(d->e2, diff);
    return sqrt(g1 * g1 + g2 * g2);
}

void pc_directional_init(pc_projector *proj, pc_directional_data *data,
                         pc_directional_cache *cache, const projcurve_surface *surface,
                         const projcurve_curve *curve, pc_vec3 unit_dir,
                         double newton_tol_rel, int newton_max_iter)
{
    *cache = (pc_directional_cache){0};
    pc_span_bound_table_init(&cache->bounds, NULL, 0);
    data->dir = unit_dir;
    vec3_orthonormal_pair(unit_dir, &data->e1, &data->e2);
    data->cache = cache;
    proj->surface = surface;
    proj->curve = curve;
    proj->model_size = surface->size > 0.0 ? surface->size : 1.0;
    /* floored by the rounding of the coordinates: far from the origin the
     * relative tolerance is below what S - P can be known to */
    proj->newton_tol = fmax(newton_tol_rel * proj->model_size, pc_pair_rounding(surface, curve));
    proj->newton_max_iter = newton_max_iter;
    proj->correct = dir_correct;
    proj->advance = dir_advance;
    proj->derivatives = dir_derivatives;
    proj->slope = dir_slope;
    proj->residual = dir_residual;
    proj->data = data;
    proj->guess_error = &cache->guess_error;
    proj->ray_dir = NULL; /* the fixed Dir of the trace configuration */
}

void pc_directional_use_bound_table(pc_directional_cache *cache, pc_span_bound_entry *storage,
                                    size_t slots)
{
    pc_span_bound_table_init(&cache->bounds, storage, slots);
    cache->bound = NULL;
}
