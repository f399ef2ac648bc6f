/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Conical (central) projection equations, docs/conical.md. The point P(t)
 * maps to the points S of the surface on the ray from the eye E through
 * P(t), beyond P(t): S - E = mu A with A = P - E and mu >= 1.
 *
 * At a fixed t the ray is a fixed line, so the corrector is the
 * directional one with Dir = A / |A|: Newton on G = [e1.(S - P);
 * e2.(S - P)] = 0 with (e1, e2) perpendicular to A(t), whose Jacobian J =
 * [e_i.Su, e_i.Sv] has det J = Dir.(Su x Sv) (a fold where the ray is
 * tangent to S). The frame only extracts the components perpendicular to
 * the ray at one t, so it need not vary smoothly with t: differentiating
 * S(q(t)) - E = mu(t) A(t) once and twice and dropping the A components,
 *   J q'  = mu [e_i.P']
 *   J q'' = [e_i.(2 mu' P' + mu P'' - S''[q', q'])]
 * with mu = (S - E).A / |A|^2 and mu' = A.(Su u' + Sv v' - mu P') / |A|^2
 * (the A component of the first equation).
 */
#include "conical/conical.h"

#include <math.h>

#include "trace/cusp_rate.h"
#include "trace/precision.h"

/* Newton diverges when its residual fails to decrease this many times. */
#define PC_CONICAL_MAX_NON_DECREASE 3
/* Jacobians with |det| at most this times the square of their scale are
 * singular (as the directional corrector). */
#define PC_CONICAL_SINGULAR_DET 1e-15

static const pc_conical_data *conical_data(const pc_projector *self)
{
    return (const pc_conical_data *)self->data;
}

/* P, P', P'' at t and the ray frame into the cache unless it holds them.
 * Returns 0 when the curve callback fails or P(t) is the eye. */
static int evaluate_curve(const pc_projector *self, double t)
{
    const pc_conical_data *d = conical_data(self);
    pc_conical_cache *c = d->cache;
    if (c->curve_valid && c->t == t)
        return 1;
    c->curve_valid = 0;
    if (pc_curve_eval(self->curve, t, 2, &c->hint_t, c->curve) != PROJCURVE_OK) {
        c->callback_failed = 1;
        return 0;
    }
    /* |A| scaled by its largest component first: an eye far out (1e200)
     * keeps a finite length and direction */
    const pc_vec3 a = vec3_sub(c->curve[0], d->eye);
    const double m = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
    if (!(m > 0.0) || !isfinite(m))
        return 0;
    const pc_vec3 scaled = vec3_scale(a, 1.0 / m);
    const double scaled_len = vec3_norm(scaled);
    c->dir = vec3_scale(scaled, 1.0 / scaled_len);
    c->len = m * scaled_len;
    vec3_orthonormal_pair(c->dir, &c->e1, &c->e2);
    c->t = t;
    c->curve_valid = 1;
    return 1;
}

/* S with derivatives up to order 2 at (u, v), and the curve at t, into the
 * cache, each unless it holds them. Returns 0 as evaluate_curve. */
static int evaluate(const pc_projector *self, double t, double u, double v)
{
    pc_conical_cache *c = conical_data(self)->cache;
    if (!c->surf_valid || c->u != u || c->v != v) {
        pc_nurbs_surface_eval(&self->surface->nurbs, u, v, 2, &c->hint_u, &c->hint_v, c->surf);
        c->u = u;
        c->v = v;
        c->surf_valid = 1;
    }
    return evaluate_curve(self, t);
}

int pc_conical_ray(const pc_projector *proj, double t, pc_vec3 *p, pc_vec3 *dir)
{
    if (!evaluate_curve(proj, t))
        return 0;
    const pc_conical_cache *c = conical_data(proj)->cache;
    if (p != NULL)
        *p = c->curve[0];
    *dir = c->dir;
    return 1;
}

/* J = [e_i.Su, e_i.Sv] = [a b; c d] of the cached frame. */
typedef struct jacobian {
    double a, b, c, d, det;
} jacobian;

/* Returns 0 when J is singular (|det| <= PC_CONICAL_SINGULAR_DET scale^2). */
static int jacobian_at(const pc_conical_cache *c, const pc_vec3 *s, jacobian *j)
{
    j->a = vec3_dot(c->e1, s[1]);
    j->b = vec3_dot(c->e1, s[2]);
    j->c = vec3_dot(c->e2, s[1]);
    j->d = vec3_dot(c->e2, s[2]);
    j->det = j->a * j->d - j->b * j->c;
    const double scale = fabs(j->a) + fabs(j->b) + fabs(j->c) + fabs(j->d);
    return fabs(j->det) > 1e-300 && fabs(j->det) > PC_CONICAL_SINGULAR_DET * scale * scale;
}

/* x = J^-1 r */
static void jacobian_solve(const jacobian *j, const double r[2], double x[2])
{
    const double inv = 1.0 / j->det;
    const double x0 = (j->d * r[0] - j->b * r[1]) * inv;
    const double x1 = (j->a * r[1] - j->c * r[0]) * inv;
    x[0] = x0;
    x[1] = x1;
}

/* [e1.w; e2.w] */
static void frame_components(const pc_conical_cache *c, pc_vec3 w, double out[2])
{
    out[0] = vec3_dot(c->e1, w);
    out[1] = vec3_dot(c->e2, w);
}

static double clamp(double x, double lo, double hi)
{
    return x < lo ? lo : (x > hi ? hi : x);
}

/* Newton on G = 0 at fixed t with the stopping tests of the directional
 * corrector ([SY13] s3.3): |G| <= eps1 (the distance of S from the ray's
 * line), |S - P| <= eps1, the sine |G| / |S - P| <= eps1 / size, or a step
 * whose image |du Su + dv Sv| is at most eps1. Fails on the iteration cap,
 * a singular Jacobian, a residual that stops decreasing (divergence, or a
 * solution outside the domain that the clamp holds on the boundary), or
 * P(t) = E. */
static int conical_correct(const pc_projector *self, double t, double uv[2], int *iterations)
{
    const pc_conical_data *d = conical_data(self);
    pc_conical_cache *c = d->cache;
    const double *dom = self->surface->nurbs.domain;
    const double eps1 = self->newton_tol;
    const double size2 = self->model_size * self->model_size;
    double u = uv[0], v = uv[1];
    double prev_res2 = INFINITY;
    int non_decrease = 0, converged = 0, it = 0;
    for (; it <= self->newton_max_iter; ++it) {
        if (!evaluate(self, t, u, v))
            break;
        const pc_vec3 diff = vec3_sub(c->surf[0], c->curve[0]);
        double g[2];
        frame_components(c, diff, g);
        const double res2 = g[0] * g[0] + g[1] * g[1];
        const double dist2 = vec3_dot(diff, diff);
        if (it == 0) /* the sine of the guess's angle, [SY13] eq. (3.8) */
            c->guess_error = dist2 > 0.0 ? sqrt(res2 / dist2) : 0.0;
        if (res2 <= eps1 * eps1 || dist2 <= eps1 * eps1 || res2 * size2 <= eps1 * eps1 * dist2) {
            converged = 1;
            break;
        }
        if (it == self->newton_max_iter)
            break;
        non_decrease = res2 >= prev_res2 ? non_decrease + 1 : 0;
        if (non_decrease >= PC_CONICAL_MAX_NON_DECREASE)
            break;
        prev_res2 = res2;
        jacobian j;
        if (!jacobian_at(c, c->surf, &j))
            break;
        double step[2];
        const double rhs[2] = {-g[0], -g[1]};
        jacobian_solve(&j, rhs, step);
        const double nu = clamp(u + step[0], dom[0], dom[1]);
        const double nv = clamp(v + step[1], dom[2], dom[3]);
        const pc_vec3 image = vec3_axpy(vec3_scale(c->surf[1], step[0]), step[1], c->surf[2]);
        const int last = nu == u + step[0] && nv == v + step[1] &&
                         vec3_dot(image, image) <= eps1 * eps1; /* [SY13] s3.3 test 1 */
        u = nu;
        v = nv;
        if (last) {
            converged = 1;
            ++it;
            break;
        }
    }
    if (iterations)
        *iterations = it;
    uv[0] = u;
    uv[1] = v;
    return converged;
}

/* S''[d, d] = Suu du^2 + 2 Suv du dv + Svv dv^2 */
static pc_vec3 second_form(const pc_vec3 *s, double du, double dv)
{
    return vec3_add(vec3_add(vec3_scale(s[3], du * du), vec3_scale(s[4], 2.0 * du * dv)),
                    vec3_scale(s[5], dv * dv));
}

/* q', q'' and det from the equations of the file comment. */
static int conical_derivatives(const pc_projector *self, double t, double u, double v,
                               pc_proj_point *out)
{
    const pc_conical_cache *c = conical_data(self)->cache;
    pc_proj_point_start(out, t, u, v);
    if (!evaluate(self, t, u, v))
        return 0;
    const pc_vec3 *s = c->surf, *p = c->curve;
    out->s = s[0];
    out->p = p[0];
    jacobian j;
    const int regular = jacobian_at(c, s, &j);
    const pc_vec3 n = vec3_cross(s[1], s[2]);
    const double area2 = vec3_dot(n, n);
    out->det = area2 > 0.0 ? j.det / sqrt(area2) : 0.0;
    if (!regular)
        return 0;
    /* mu = (S - E).A / |A|^2 and mu' as in the file comment, written
     * with D = A / |A| so that no |A|^2 overflows */
    const double mu = vec3_dot(vec3_sub(s[0], conical_data(self)->eye), c->dir) / c->len;
    double r1[2], q1[2];
    frame_components(c, vec3_scale(p[1], mu), r1);
    jacobian_solve(&j, r1, q1);
    const pc_vec3 w1 = vec3_axpy(vec3_scale(s[1], q1[0]), q1[1], s[2]); /* Su u' + Sv v' */
    const double dmu = vec3_dot(c->dir, vec3_axpy(w1, -mu, p[1])) / c->len;
    const pc_vec3 w2 = vec3_sub(vec3_add(vec3_scale(p[1], 2.0 * dmu), vec3_scale(p[2], mu)),
                                second_form(s, q1[0], q1[1]));
    double r2[2], q2[2];
    frame_components(c, w2, r2);
    jacobian_solve(&j, r2, q2);
    out->du = q1[0];
    out->dv = q1[1];
    out->ddu = q2[0];
    out->ddv = q2[1];
    out->speed = vec3_norm(w1); /* [SY13] eq. (3.6) */
    /* a cusp of the parametrisation is one of S, whatever the rays: the
     * same rate as the directional projector's (docs/conical.md) */
    out->cusp_rate = pc_cusp_rate(s, n, area2, q1);
    return isfinite(out->speed) && isfinite(out->ddu) && isfinite(out->ddv);
}

/* The distance of S(u, v) from the line through E and P(t). */
static double conical_residual(const pc_projector *self, double t, double u, double v)
{
    const pc_conical_cache *c = conical_data(self)->cache;
    if (!evaluate(self, t, u, v))
        return INFINITY;
    double g[2];
    frame_components(c, vec3_sub(c->surf[0], c->curve[0]), g);
    return sqrt(g[0] * g[0] + g[1] * g[1]);
}

/* The ray's direction at a point of the tracer: from the eye through P. */
static pc_vec3 conical_ray_dir(const pc_projector *self, const pc_proj_point *p)
{
    const pc_vec3 a = vec3_sub(p->p, conical_data(self)->eye);
    const double m = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
    if (!(m > 0.0) || !isfinite(m))
        return vec3(0.0, 0.0, 0.0); /* no ray: lambda 0 */
    return vec3_normalize(vec3_scale(a, 1.0 / m));
}

void pc_conical_init(pc_projector *proj, pc_conical_data *data, pc_conical_cache *cache,
                     const projcurve_surface *surface, const projcurve_curve *curve, pc_vec3 eye,
                     double newton_tol_rel, int newton_max_iter)
{
    *cache = (pc_conical_cache){0};
    data->eye = eye;
    data->cache = cache;
    proj->surface = surface;
    proj->curve = curve;
    proj->model_size = surface->size > 0.0 ? surface->size : 1.0;
    /* floored by the rounding of the coordinates, as the directional one */
    proj->newton_tol = fmax(newton_tol_rel * proj->model_size, pc_pair_rounding(surface, curve));
    proj->newton_max_iter = newton_max_iter;
    proj->correct = conical_correct;
    proj->advance = NULL;
    proj->derivatives = conical_derivatives;
    proj->slope = NULL; /* RK4 stages call derivatives() */
    proj->residual = conical_residual;
    proj->data = data;
    proj->guess_error = &cache->guess_error;
    proj->ray_dir = conical_ray_dir;
}
