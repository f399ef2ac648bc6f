/*
 * Directional projection equations (seed 000 s3.2-s3.3) in the frame form of
 * DESIGN.md: G(u, v, t) = [e1.(S - P); e2.(S - P)] with (e1, e2) an
 * orthonormal pair perpendicular to Dir. G = 0 is the paper's (3.1); its
 * Jacobian J = [e_i.Su, e_i.Sv] has det J = Dir.(Su x Sv), so it is singular
 * exactly where Dir is tangent to S (a fold, seen from Dir).
 */
#include "trace/directional.h"

#include <math.h>

/* A Newton step is in the quadratic regime (its cubic remainder, and the
 * change of the second derivatives that shift_cache keeps, negligible)
 * when its image is below this fraction of the model size; the residual it
 * leaves behind must then be below this fraction of eps1 to stop. */
#define PC_NEWTON_QUADRATIC_REGIME 1e-7
#define PC_NEWTON_PREDICTED_SAFETY 0.25
/* Newton diverges when its residual fails to decrease this many times. */
#define PC_NEWTON_MAX_NON_DECREASE 3

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
        c->surf_valid = 1;
    }
    return evaluate_curve(self, t);
}

/* After a last Newton step (du, dv) that the tests below accept, moves the
 * cached evaluation to (u + du, v + dv) by its Taylor expansion (second
 * order for S, first for Su, Sv). The errors, O(|du, dv|^3) in S and
 * O(|du, dv|^2) in its derivatives, are far below rounding for such steps,
 * and the derivatives at the converged point then cost no evaluation. */
static void shift_cache(const pc_projector *self, double du, double dv)
{
    pc_directional_cache *c = dir_data(self)->cache;
    pc_vec3 *s = c->surf;
    const pc_vec3 second = vec3_add(vec3_add(vec3_scale(s[3], 0.5 * du * du),
                                             vec3_scale(s[4], du * dv)),
                                    vec3_scale(s[5], 0.5 * dv * dv));
    s[0] = vec3_add(vec3_axpy(vec3_axpy(s[0], du, s[1]), dv, s[2]), second);
    s[1] = vec3_axpy(vec3_axpy(s[1], du, s[3]), dv, s[4]);
    s[2] = vec3_axpy(vec3_axpy(s[2], du, s[4]), dv, s[5]);
    c->u += du;
    c->v += dv;
}

static double clamp(double x, double lo, double hi)
{
    return x < lo ? lo : (x > hi ? hi : x);
}

/* Newton on G = 0 at fixed t (seed 000 s3.3, with the frame form of (3.9)).
 * Stops on any of the paper's three tests: the step's image
 * |du Su + dv Sv| <= eps1, |S - P| <= eps1, or the sine
 * |Dir x (S - P)| / |S - P| <= eps2; plus |Dir x (S - P)| <= eps1, and a
 * sharper form of the first test: a step in the quadratic regime whose
 * predicted remaining residual is below eps1 / 4 is the last one (the
 * point after it is then not evaluated again: shift_cache). Fails on
 * the iteration cap, a singular Jacobian, or a residual that stops
 * decreasing (divergence, or a solution outside the domain that the clamp
 * holds on the boundary). */
static int dir_correct(const pc_projector *self, double t, double uv[2], int *iterations)
{
    const pc_directional_data *d = dir_data(self);
    const double *dom = self->surface->nurbs.domain;
    const double eps1 = self->newton_tol;
    const double eps2 = self->newton_tol / self->model_size;
    double u = uv[0], v = uv[1];
    double prev_res = INFINITY;
    int non_decrease = 0, converged = 0, it = 0;

    for (; it <= self->newton_max_iter; ++it) {
        if (!evaluate(self, t, u, v))
            break;
        const pc_vec3 *s = d->cache->surf;
        const pc_vec3 diff = vec3_sub(s[0], d->cache->curve[0]);
        const double g[2] = {vec3_dot(d->e1, diff), vec3_dot(d->e2, diff)};
        const double res = sqrt(g[0] * g[0] + g[1] * g[1]); /* = |Dir x (S - P)| */
        const double dist = vec3_norm(diff);
        if (it == 0)
            d->cache->guess_error = dist > 0.0 ? res / dist : 0.0; /* seed 000 eq. (3.8) */
        if (res <= eps1 || dist <= eps1 || res <= eps2 * dist) {
            converged = 1;
            break;
        }
        if (it == self->newton_max_iter)
            break;
        non_decrease = res >= prev_res ? non_decrease + 1 : 0;
        if (non_decrease >= PC_NEWTON_MAX_NON_DECREASE)
            break;
        prev_res = res;
        double step[2];
        const double rhs[2] = {-g[0], -g[1]};
        if (!mat2_solve(vec3_dot(d->e1, s[1]), vec3_dot(d->e1, s[2]), vec3_dot(d->e2, s[1]),
                        vec3_dot(d->e2, s[2]), rhs, step))
            break;
        const double nu = clamp(u + step[0], dom[0], dom[1]);
        const double nv = clamp(v + step[1], dom[2], dom[3]);
        const int clamped = nu != u + step[0] || nv != v + step[1];
        const double du = nu - u, dv = nv - v;
        const double moved = vec3_norm(vec3_axpy(vec3_scale(s[1], du), dv, s[2]));
        /* After a Newton step G(q + d) = d'G''d / 2 + O(|d|^3): the residual
         * the step leaves behind, bounded by |Suu du^2 + 2 Suv du dv +
         * Svv dv^2| / 2 (e1, e2 orthonormal). */
        const double left_behind =
            0.5 * vec3_norm(vec3_add(vec3_add(vec3_scale(s[3], du * du),
                                              vec3_scale(s[4], 2.0 * du * dv)),
                                     vec3_scale(s[5], dv * dv)));
        const int quadratic = moved <= PC_NEWTON_QUADRATIC_REGIME * self->model_size &&
                              left_behind <= PC_NEWTON_PREDICTED_SAFETY * eps1;
        if (!clamped && (moved <= eps1 || quadratic)) { /* seed 000 s3.3 test 1 */
            shift_cache(self, nu - u, nv - v);
            u = d->cache->u; /* the same values, as the cache holds them */
            v = d->cache->v;
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

/* q' and q'' from differentiating G(q(t), t) = 0 once and twice:
 *   J q'  = [e_i.P']
 *   J q'' = [e_i.P''] - [e_i.(Suu u'^2 + 2 Suv u'v' + Svv v'^2)]
 * (DESIGN.md; equal to seed 000 eqs. (3.2), (3.3)). */
static int dir_derivatives(const pc_projector *self, double t, double u, double v,
                           pc_proj_point *out)
{
    const pc_directional_data *d = dir_data(self);
    out->t = t;
    out->u = u;
    out->v = v;
    out->du = out->dv = out->ddu = out->ddv = 0.0;
    out->det = 0.0;
    out->speed = 0.0;
    if (!evaluate(self, t, u, v))
        return 0;
    const pc_vec3 *s = d->cache->surf;
    const pc_vec3 *p = d->cache->curve;
    out->s = s[0];
    out->p = p[0];
    const double a = vec3_dot(d->e1, s[1]), b = vec3_dot(d->e1, s[2]);
    const double c = vec3_dot(d->e2, s[1]), e = vec3_dot(d->e2, s[2]);
    const double area = vec3_norm(vec3_cross(s[1], s[2]));
    out->det = area > 0.0 ? (a * e - b * c) / area : 0.0;

    double q1[2];
    const double r1[2] = {vec3_dot(d->e1, p[1]), vec3_dot(d->e2, p[1])};
    if (!mat2_solve(a, b, c, e, r1, q1))
        return 0;
    const pc_vec3 acc = vec3_add(vec3_add(vec3_scale(s[3], q1[0] * q1[0]),
                                          vec3_scale(s[4], 2.0 * q1[0] * q1[1])),
                                 vec3_scale(s[5], q1[1] * q1[1]));
    const double r2[2] = {vec3_dot(d->e1, vec3_sub(p[2], acc)),
                          vec3_dot(d->e2, vec3_sub(p[2], acc))};
    double q2[2];
    if (!mat2_solve(a, b, c, e, r2, q2))
        return 0;
    out->du = q1[0];
    out->dv = q1[1];
    out->ddu = q2[0];
    out->ddv = q2[1];
    out->speed = vec3_norm(vec3_axpy(vec3_scale(s[1], q1[0]), q1[1], s[2])); /* eq. (3.6) */
    return isfinite(out->speed) && isfinite(out->ddu) && isfinite(out->ddv);
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
    data->dir = unit_dir;
    vec3_orthonormal_pair(unit_dir, &data->e1, &data->e2);
    data->cache = cache;
    proj->surface = surface;
    proj->curve = curve;
    proj->model_size = surface->size > 0.0 ? surface->size : 1.0;
    proj->newton_tol = newton_tol_rel * proj->model_size;
    proj->newton_max_iter = newton_max_iter;
    proj->correct = dir_correct;
    proj->derivatives = dir_derivatives;
    proj->residual = dir_residual;
    proj->data = data;
    proj->guess_error = &cache->guess_error;
}
