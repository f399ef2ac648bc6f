#include "ortho/ortho_projector.h"

#include <float.h>
#include <math.h>

#include "ortho/morse_index.h"
#include "ortho/surface_d3.h"

/* A Newton iterate whose residual grew by this factor over the starting
 * residual is diverging (it is heading for another foot point far away or
 * out of the domain); the correction is abandoned so that the tracer
 * halves its step instead. */
#define ORTHO_DIVERGENCE_FACTOR 1e3

/* |det K| / (|Su| |Sv|)^2 at or below this: K is singular (P at a centre
 * of curvature). K is then made of rounding noise, which mat2_solve's test
 * relative to K's own entries cannot see; this one is relative to the
 * first fundamental form. */
#define ORTHO_DET_SINGULAR 1e-12

/* Quadratic convergence is trusted when the last step shrank at least by
 * this factor and predicts a next step below this fraction of newton_tol. */
#define ORTHO_CONTRACTION_MAX 0.1
#define ORTHO_PREDICTED_FRACTION 0.01
/* ... and only where K is well conditioned: near a centre of curvature the
 * foot point is known only to ~newton_tol / det, and the confirming
 * evaluation is kept. */
#define ORTHO_QUADRATIC_MIN_DET 1e-2

static double clamp(double x, double lo, double hi) { return x < lo ? lo : (x > hi ? hi : x); }

/* K of seed 003 eq. (5) and F of eq. (10) from S, Su, Sv, Suu, Suv, Svv. */
static void tensor_and_residual(const pc_vec3 *s, pc_vec3 p, double k[4], double f[2])
{
    const pc_vec3 d = vec3_sub(s[PC_D3_S], p);
    k[0] = vec3_dot(s[PC_D3_U], s[PC_D3_U]) + vec3_dot(d, s[PC_D3_UU]);
    k[1] = vec3_dot(s[PC_D3_U], s[PC_D3_V]) + vec3_dot(d, s[PC_D3_UV]);
    k[2] = k[1];
    k[3] = vec3_dot(s[PC_D3_V], s[PC_D3_V]) + vec3_dot(d, s[PC_D3_VV]);
    f[0] = vec3_dot(d, s[PC_D3_U]);
    f[1] = vec3_dot(d, s[PC_D3_V]);
}

/* det K / (|Su| |Sv|)^2 (unitless; 0 where the parametrisation is
 * singular). */
static double normalized_det(const pc_vec3 *s, const double k[4])
{
    const double scale = vec3_dot(s[PC_D3_U], s[PC_D3_U]) * vec3_dot(s[PC_D3_V], s[PC_D3_V]);
    return scale > 0.0 ? (k[0] * k[3] - k[1] * k[2]) / scale : 0.0;
}

/* Length of the tangential part of S - P, in model units: F holds its
 * covariant components, so |tangential|^2 = F^T g^-1 F (g the first
 * fundamental form). A degenerate g (singular parametrisation) gives +inf. */
static double tangential_distance(pc_vec3 su, pc_vec3 sv, const double f[2])
{
    const double g11 = vec3_dot(su, su), g12 = vec3_dot(su, sv), g22 = vec3_dot(sv, sv);
    double x[2];
    if (!mat2_solve(g11, g12, g12, g22, f, x))
        return INFINITY;
    const double sq = f[0] * x[0] + f[1] * x[1];
    return sqrt(sq > 0.0 ? sq : 0.0);
}

/* The cache is the mutable object behind the projector's const data. */
static pc_ortho_cache *cache_of(const pc_projector *self)
{
    return (pc_ortho_cache *)self->data;
}

/* P and its derivatives up to n_deriv (<= 2) at t. Always evaluates up to
 * order 2, so that the derivatives asked after a correction at the same t
 * cost nothing. */
static int eval_curve(const pc_projector *self, double t, int n_deriv, pc_vec3 *p)
{
    pc_ortho_cache *cache = cache_of(self);
    if (!cache->curve_known || cache->curve_t != t) {
        cache->curve_known = 0;
        if (pc_curve_eval(self->curve, t, 2, &cache->hint_t, cache->curve_p) != PROJCURVE_OK) {
            cache->callback_failed = 1;
            return 0;
        }
        cache->curve_known = 1;
        cache->curve_t = t;
    }
    for (int k = 0; k <= n_deriv; ++k)
        p[k] = cache->curve_p[k];
    return 1;
}

/* Newton on F(., ., t) = 0 with the full Jacobian K (seed 003 eq. (14)):
 * delta = -K^-1 F. Converged when the 3D length of the step and the
 * tangential distance are both within newton_tol (seed 000 s3.3 criteria),
 * or when the convergence seen so far is quadratic and predicts that the
 * step just taken leaves an error far below newton_tol: with steps
 * d_k = C d_(k-1)^2, the next step would be d_k^3 / d_(k-1)^2. The second
 * test saves the evaluation that would only confirm convergence (one of
 * the usual three) where K is well conditioned. */
static int ortho_correct(const pc_projector *self, double t, double uv[2], int *iterations)
{
    const pc_nurbs_surface *s = &self->surface->nurbs;
    const double tol = self->newton_tol;
    pc_vec3 p;
    int it = 0, converged = 0;
    if (!eval_curve(self, t, 0, &p)) {
        if (iterations)
            *iterations = 0;
        return 0;
    }
    double first_residual = -1.0, last_step = -1.0;
    for (; it < self->newton_max_iter; ++it) {
        pc_vec3 sd[6];
        double k[4], f[2], delta[2];
        pc_nurbs_surface_eval(s, uv[0], uv[1], 2, &cache_of(self)->hint_u,
                              &cache_of(self)->hint_v, sd);
        tensor_and_residual(sd, p, k, f);
        const double residual = tangential_distance(sd[PC_D3_U], sd[PC_D3_V], f);
        if (!isfinite(residual))
            break;
        if (first_residual < 0.0)
            first_residual = residual;
        else if (residual > ORTHO_DIVERGENCE_FACTOR * first_residual + tol)
            break;
        const double minus_f[2] = {-f[0], -f[1]};
        if (!mat2_solve(k[0], k[1], k[2], k[3], minus_f, delta))
            break;
        const double u_new = clamp(uv[0] + delta[0], s->domain[0], s->domain[1]);
        const double v_new = clamp(uv[1] + delta[1], s->domain[2], s->domain[3]);
        const int clamped = u_new != uv[0] + delta[0] || v_new != uv[1] + delta[1];
        const double step = vec3_norm(vec3_axpy(vec3_scale(sd[PC_D3_U], u_new - uv[0]),
                                                v_new - uv[1], sd[PC_D3_V]));
        uv[0] = u_new;
        uv[1] = v_new;
        const int quadratic = !clamped && last_step > 0.0 &&
                              fabs(normalized_det(sd, k)) >= ORTHO_QUADRATIC_MIN_DET &&
                              step <= ORTHO_CONTRACTION_MAX * last_step &&
                              step * step * step <= ORTHO_PREDICTED_FRACTION * tol * last_step * last_step;
        if ((residual <= tol && step <= tol) || quadratic) {
            converged = 1;
            ++it;
            break;
        }
        last_step = step;
    }
    if (iterations)
        *iterations = it;
    return converged;
}

int pc_ortho_second_derivative(const pc_vec3 *s, const pc_vec3 p[3], const double qd[2],
                               const double k[4], double qdd[2])
{
    const double du = qd[0], dv = qd[1];
    const pc_vec3 d = vec3_sub(s[PC_D3_S], p[0]);
    const pc_vec3 w = vec3_axpy(vec3_scale(s[PC_D3_U], du), dv, s[PC_D3_V]);
    const pc_vec3 a_u = vec3_axpy(vec3_scale(s[PC_D3_UU], du), dv, s[PC_D3_UV]);
    const pc_vec3 a_v = vec3_axpy(vec3_scale(s[PC_D3_UV], du), dv, s[PC_D3_VV]);
    const pc_vec3 c = vec3_axpy(vec3_axpy(vec3_scale(s[PC_D3_UU], du * du), 2.0 * du * dv,
                                          s[PC_D3_UV]),
                                dv * dv, s[PC_D3_VV]);
    const pc_vec3 t_u = vec3_axpy(vec3_axpy(vec3_scale(s[PC_D3_UUU], du * du), 2.0 * du * dv,
                                            s[PC_D3_UUV]),
                                  dv * dv, s[PC_D3_UVV]);
    const pc_vec3 t_v = vec3_axpy(vec3_axpy(vec3_scale(s[PC_D3_UUV], du * du), 2.0 * du * dv,
                                            s[PC_D3_UVV]),
                                  dv * dv, s[PC_D3_VVV]);
    const pc_vec3 accel = vec3_sub(p[2], c);   /* P'' - C */
    const pc_vec3 slip = vec3_sub(p[1], w);    /* P' - w */
    /* seed 003 eq. (15) differentiated in t; see docs/orthogonal.md. */
    const double rhs[2] = {
        vec3_dot(s[PC_D3_U], accel) + 2.0 * vec3_dot(a_u, slip) - vec3_dot(d, t_u),
        vec3_dot(s[PC_D3_V], accel) + 2.0 * vec3_dot(a_v, slip) - vec3_dot(d, t_v),
    };
    return mat2_solve(k[0], k[1], k[2], k[3], rhs, qdd);
}

static int ortho_derivatives(const pc_projector *self, double t, double u, double v,
                             pc_proj_point *out)
{
    pc_vec3 sd[PC_D3_COUNT], p[3];
    double k[4], f[2];
    out->t = t;
    out->u = u;
    out->v = v;
    out->du = out->dv = out->ddu = out->ddv = 0.0;
    out->det = 0.0;
    out->speed = 0.0;
    pc_surface_eval_d3(&self->surface->nurbs, u, v, &cache_of(self)->hint_u,
                       &cache_of(self)->hint_v, sd);
    out->s = sd[PC_D3_S];
    if (!eval_curve(self, t, 2, p)) {
        out->p = vec3(NAN, NAN, NAN);
        return 0;
    }
    out->p = p[0];
    tensor_and_residual(sd, p[0], k, f);
    out->det = normalized_det(sd, k);

    /* seed 003 eq. (16): q' = K^-1 [P'.Su; P'.Sv]. */
    const double b[2] = {vec3_dot(p[1], sd[PC_D3_U]), vec3_dot(p[1], sd[PC_D3_V])};
    double qd[2], qdd[2];
    if (!(fabs(out->det) > ORTHO_DET_SINGULAR) || !mat2_solve(k[0], k[1], k[2], k[3], b, qd))
        return 0;
    if (!pc_ortho_second_derivative(sd, p, qd, k, qdd))
        return 0;
    out->du = qd[0];
    out->dv = qd[1];
    out->ddu = qdd[0];
    out->ddv = qdd[1];
    /* A foot point at rest (P' along the normal) has speed 0, which the
     * engine would read as "unknown"; the smallest positive value says
     * "known and tiny", so the step is bounded by the engine's cap in t. */
    const double speed = vec3_norm(vec3_axpy(vec3_scale(sd[PC_D3_U], qd[0]), qd[1], sd[PC_D3_V]));
    out->speed = speed > DBL_MIN ? speed : DBL_MIN;
    return 1;
}

static double ortho_residual(const pc_projector *self, double t, double u, double v)
{
    pc_vec3 sd[6], p;
    double k[4], f[2];
    if (!eval_curve(self, t, 0, &p))
        return INFINITY;
    pc_nurbs_surface_eval(&self->surface->nurbs, u, v, 2, &cache_of(self)->hint_u,
                          &cache_of(self)->hint_v, sd);
    tensor_and_residual(sd, p, k, f);
    return tangential_distance(sd[PC_D3_U], sd[PC_D3_V], f);
}

int pc_ortho_morse_index(const pc_projector *proj, double t, double u, double v, int *index)
{
    pc_vec3 sd[6], p;
    double k[4], f[2];
    if (!eval_curve(proj, t, 0, &p))
        return 0;
    pc_nurbs_surface_eval(&proj->surface->nurbs, u, v, 2, &cache_of(proj)->hint_u,
                          &cache_of(proj)->hint_v, sd);
    tensor_and_residual(sd, p, k, f);
    *index = pc_morse_index(k[0] * k[3] - k[1] * k[2], k[0] + k[3]);
    return 1;
}

void pc_ortho_projector_init(pc_projector *proj, pc_ortho_cache *cache,
                             const projcurve_surface *surface, const projcurve_curve *curve,
                             double newton_tol_rel, int newton_max_iter)
{
    cache->hint_u = cache->hint_v = cache->hint_t = 0;
    cache->curve_known = 0;
    cache->callback_failed = 0;
    proj->surface = surface;
    proj->curve = curve;
    proj->model_size = surface->size;
    proj->newton_tol = newton_tol_rel * surface->size;
    proj->newton_max_iter = newton_max_iter;
    proj->correct = ortho_correct;
    proj->derivatives = ortho_derivatives;
    proj->advance = NULL;
    proj->slope = NULL; /* q' needs S's second derivatives here (K) */
    proj->residual = ortho_residual;
    proj->data = cache;
    proj->guess_error = NULL;
}
