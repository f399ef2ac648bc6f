/* SPDX-License-Identifier: BSD-3-Clause */
#include "ortho/ortho_projector.h"

#include <float.h>
#include <math.h>

#include "ortho/collapsed.h"
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

/* The absolute rounding of Su and Sv is about this many DBL_EPSILON of the
 * surface size (a few roundings of the control-net sums, whatever |Su| is):
 * the direction of Su is known to that / |Su|, and the tangential residual
 * of S - P cannot be resolved below |S - P| times it. Negligible at regular
 * points (1e-14 |S - P| on a sphere); it is what stops Newton near a
 * collapsed edge (collapsed.h), where |Su| -> 0. */
#define ORTHO_DIRECTION_NOISE (16.0 * DBL_EPSILON)

static double clamp(double x, double lo, double hi) { return x < lo ? lo : (x > hi ? hi : x); }

/* K of [PW96] eq. (5) and F of eq. (10) from S, Su, Sv, Suu, Suv, Svv. */
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

/* The resolution of tangential_distance at a regular point (see
 * ORTHO_DIRECTION_NOISE). */
static double residual_noise(const pc_vec3 *s, pc_vec3 p, double size)
{
    const double shortest = fmin(vec3_norm(s[PC_D3_U]), vec3_norm(s[PC_D3_V]));
    return vec3_dist(s[PC_D3_S], p) * ORTHO_DIRECTION_NOISE * size / shortest;
}

/* Length in space of the Newton step delta = -K^-1 F (delta written to
 * step_uv): the distance from S(u, v) to the foot point it converges to, to
 * first order. +inf (and a NaN step) where K is singular. */
static double step_distance(const pc_vec3 *s, const double k[4], const double f[2],
                            double step_uv[2])
{
    const double minus_f[2] = {-f[0], -f[1]};
    if (!mat2_solve(k[0], k[1], k[2], k[3], minus_f, step_uv)) {
        step_uv[0] = step_uv[1] = NAN;
        return INFINITY;
    }
    return vec3_norm(vec3_axpy(vec3_scale(s[PC_D3_U], step_uv[0]), step_uv[1], s[PC_D3_V]));
}

/* How far (u, v) is from being a foot point, in model units, where the
 * parametrisation is not collapsed: the smaller of the tangential distance
 * (backward: how far P is from the normal line at S) and the Newton step's
 * length (forward: how far S is from the foot point). Where Su is nearly
 * parallel to Sv (a fold of the parameter lines inside S: linkrods.step
 * surfaces 9 and 16, sin(Su, Sv) ~ 1e-5) the normal Su x Sv is rounding
 * and the tangential part with it (2e-5 at a point 5e-15 from its foot),
 * while K, which also holds the second derivatives, is not singular and the
 * step is exact; near a centre of curvature it is the other way round.
 * delta receives Newton's step. */
static double foot_residual(const pc_vec3 *s, const double k[4], const double f[2],
                            double delta[2])
{
    const double forward = step_distance(s, k, f, delta);
    return fmin(tangential_distance(s[PC_D3_U], s[PC_D3_V], f), forward);
}

/* Where the parametrisation is collapsed (collapsed.h), S - P split into its
 * component along the regular direction r (exact: S_r is not small) and
 * across it, along the tangent m perpendicular to S_r, with the allowance
 * for m's error. m is the collapsed derivative S_c's direction, known to
 * ORTHO_DIRECTION_NOISE size / |S_c|, or, closer to the edge, that of S_cr
 * (S_c ~ (distance to the edge in r) S_cr), known to ~|S_c| |S_crr| /
 * |S_cr|^2: whichever is the better known. s holds the order-3 partials. */
typedef struct collapsed_residual {
    double regular, across, allowed;
} collapsed_residual;

static collapsed_residual split_residual(const pc_vec3 *s, pc_vec3 p, pc_collapse c, double size)
{
    const int cu = c == PC_COLLAPSE_U;
    const pc_vec3 d = vec3_sub(s[PC_D3_S], p);
    const pc_vec3 sr = cu ? s[PC_D3_V] : s[PC_D3_U];
    const pc_vec3 sc = cu ? s[PC_D3_U] : s[PC_D3_V];
    const pc_vec3 scr = s[PC_D3_UV];
    const pc_vec3 scrr = cu ? s[PC_D3_UVV] : s[PC_D3_UUV];
    const pc_vec3 er = vec3_normalize(sr);
    const double nc = vec3_norm(sc), ncr = vec3_norm(scr);
    const double e_round = nc > 0.0 ? ORTHO_DIRECTION_NOISE * size / nc : INFINITY;
    const double e_limit = ncr > 0.0 ? nc * vec3_norm(scrr) / (ncr * ncr) : INFINITY;
    pc_vec3 m = e_round <= e_limit ? sc : scr;
    m = vec3_axpy(m, -vec3_dot(m, er), er);
    const double nm = vec3_norm(m);
    collapsed_residual z;
    z.regular = fabs(vec3_dot(d, er));
    z.across = nm > 0.0 ? fabs(vec3_dot(d, m)) / nm : INFINITY;
    z.allowed = vec3_norm(d) * fmin(e_round, e_limit);
    return z;
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

/* Newton on F(., ., t) = 0 with the full Jacobian K ([PW96] eq. (14)):
 * delta = -K^-1 F. Converged when the 3D length of the step and the
 * tangential distance are both within newton_tol ([SY13] s3.3 criteria;
 * the distance within newton_tol plus its rounding floor, which matters
 * only near a collapsed edge), or when the convergence seen so far is
 * quadratic and predicts that the step just taken leaves an error far
 * below newton_tol: with steps d_k = C d_(k-1)^2, the next step would be
 * d_k^3 / d_(k-1)^2. The second test saves the evaluation that would only
 * confirm convergence (one of the usual three) where K is well
 * conditioned. Where the parametrisation is collapsed (collapsed.h) the
 * step is Newton's along the regular direction alone: the other parameter
 * is ill-determined there and stays. */
static int ortho_correct(const pc_projector *self, double t, double uv[2], int *iterations)
{
    const pc_nurbs_surface *s = &self->surface->nurbs;
    pc_ortho_cache *cache = cache_of(self);
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
        pc_vec3 sd[PC_D3_COUNT];
        double k[4], f[2], delta[2];
        pc_nurbs_surface_eval(s, uv[0], uv[1], 2, &cache->hint_u, &cache->hint_v, sd);
        const pc_collapse c = pc_collapsed_direction(sd[PC_D3_U], sd[PC_D3_V]);
        tensor_and_residual(sd, p, k, f);
        double residual;
        int close_enough;
        if (c == PC_COLLAPSE_NONE) {
            residual = foot_residual(sd, k, f, delta);
            close_enough = residual <= tol + residual_noise(sd, p, self->model_size);
        } else {
            pc_surface_eval_d3(s, uv[0], uv[1], &cache->hint_u, &cache->hint_v, sd);
            const collapsed_residual z = split_residual(sd, p, c, self->model_size);
            residual = z.regular;
            close_enough = z.regular <= tol && z.across <= tol + z.allowed;
        }
        if (!isfinite(residual))
            break;
        if (first_residual < 0.0)
            first_residual = residual;
        else if (residual > ORTHO_DIVERGENCE_FACTOR * first_residual + tol)
            break;
        if (c == PC_COLLAPSE_NONE) {
            if (!isfinite(delta[0]) || !isfinite(delta[1]))
                break;   /* K singular: foot_residual found no step */
        } else {
            const int r = c == PC_COLLAPSE_U ? 1 : 0;   /* the regular direction */
            const double krr = k[3 * r];
            if (!(fabs(krr) > 0.0))
                break;
            delta[r] = -f[r] / krr;
            delta[1 - r] = 0.0;
        }
        const double u_new = clamp(uv[0] + delta[0], s->domain[0], s->domain[1]);
        const double v_new = clamp(uv[1] + delta[1], s->domain[2], s->domain[3]);
        const int clamped = u_new != uv[0] + delta[0] || v_new != uv[1] + delta[1];
        const double step = vec3_norm(vec3_axpy(vec3_scale(sd[PC_D3_U], u_new - uv[0]),
                                                v_new - uv[1], sd[PC_D3_V]));
        uv[0] = u_new;
        uv[1] = v_new;
        const int quadratic = c == PC_COLLAPSE_NONE && !clamped && last_step > 0.0 &&
                              fabs(normalized_det(sd, k)) >= ORTHO_QUADRATIC_MIN_DET &&
                              step <= ORTHO_CONTRACTION_MAX * last_step &&
                              step * step * step <= ORTHO_PREDICTED_FRACTION * tol * last_step * last_step;
        if ((close_enough && step <= tol) || quadratic) {
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

/* The right-hand side of K q'' = ... (see the file's header). */
static void second_derivative_rhs(const pc_vec3 *s, const pc_vec3 p[3], const double qd[2],
                                  double rhs[2])
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
    /* [PW96] eq. (15) differentiated in t; see docs/orthogonal.md. */
    rhs[0] = vec3_dot(s[PC_D3_U], accel) + 2.0 * vec3_dot(a_u, slip) - vec3_dot(d, t_u);
    rhs[1] = vec3_dot(s[PC_D3_V], accel) + 2.0 * vec3_dot(a_v, slip) - vec3_dot(d, t_v);
}

int pc_ortho_second_derivative(const pc_vec3 *s, const pc_vec3 p[3], const double qd[2],
                               const double k[4], double qdd[2])
{
    double rhs[2];
    second_derivative_rhs(s, p, qd, rhs);
    return mat2_solve(k[0], k[1], k[2], k[3], rhs, qdd);
}

/* An edge collapsed to a point is a regular point of S (a pole) when the
 * regular derivative S_r(., edge), which sweeps the tangent plane there,
 * stays in the plane of S_r and S_cr: |S_ccr . n| / |S_ccr| below this.
 * At the apex of a cone S_r sweeps a cone and the ratio is of order 1; at
 * the pole of a sphere it is 0 on the edge and of order of the parameter
 * distance to it in the collapsed zone (< 1e-6). */
#define ORTHO_APEX_RATIO 1e-3

/* The two factors 1 + rho k of K's eigenvalues where the parametrisation is
 * collapsed (collapsed.h), along the regular direction r and the collapsed
 * c: f_r = K_rr / g_rr, exact. f_c = K_cc / g_cc is a ratio of two
 * quantities of order |S_c|^2 there, the first with a rounding of order
 * |S - P| DBL_EPSILON size: noise in the collapsed zone. It is replaced by
 * its limit on the edge. Near an edge point that is regular (a pole),
 * f_c -> f_r: the pole of a surface of revolution is an umbilic (taken so
 * for other poles too). Near an apex (collapsed.h's cone),
 * K_cc / g_cc ~ 1 + (S - P).S_ccr / (e |S_cr|^2), e the signed parameter
 * distance to the edge: it diverges, with the sign of (S - P).S_ccr
 * towards the interior; f_c gets that sign and the magnitude of f_r (only
 * its sign and whether it is small are used). */
static void collapsed_factors(const pc_projector *self, const pc_vec3 *sd, pc_vec3 p,
                              const double k[4], pc_collapse c, const double uv[2], double *f_r,
                              double *f_c)
{
    const int cu = c == PC_COLLAPSE_U;
    const pc_vec3 sr = cu ? sd[PC_D3_V] : sd[PC_D3_U];
    const pc_vec3 scr = sd[PC_D3_UV];
    const pc_vec3 sccr = cu ? sd[PC_D3_UUV] : sd[PC_D3_UVV];
    *f_r = k[cu ? 3 : 0] / vec3_dot(sr, sr);
    *f_c = *f_r;
    const pc_vec3 n = vec3_cross(sr, scr);
    const double nn = vec3_norm(n), nccr = vec3_norm(sccr);
    if (!(nn > 0.0) || !(fabs(vec3_dot(sccr, n)) > ORTHO_APEX_RATIO * nccr * nn))
        return;   /* a pole */
    const double *dom = self->surface->nurbs.domain;
    const double x = cu ? uv[1] : uv[0];
    const double lo = cu ? dom[2] : dom[0], hi = cu ? dom[3] : dom[1];
    const double inward = x - lo <= hi - x ? 1.0 : -1.0;
    const double a = vec3_dot(vec3_sub(sd[PC_D3_S], p), sccr) * inward;
    if (a != 0.0)
        *f_c = copysign(fabs(*f_r), a);
}

/* q', q'' and det where the parametrisation is collapsed (collapsed.h):
 * the regular row of K q' = b and of its derivative, the collapsed
 * parameter held (its rate is that of a direction at a point, and S does
 * not depend on it to first order). det K / (|Su||Sv|)^2 is 0/0 here and
 * is reported as f_r f_c (collapsed_factors): its limit at the pole of a
 * surface of revolution, its sign at an apex. Returns 0 where K_rr
 * vanishes (a centre of curvature). */
static int collapsed_derivatives(const pc_projector *self, const pc_vec3 *sd,
                                 const pc_vec3 p[3], const double k[4], pc_collapse c,
                                 pc_proj_point *out)
{
    const int r = c == PC_COLLAPSE_U ? 1 : 0;
    const pc_vec3 sr = sd[r == 1 ? PC_D3_V : PC_D3_U];
    const double krr = k[3 * r], grr = vec3_dot(sr, sr);
    const double uv[2] = {out->u, out->v};
    double f_r, f_c;
    collapsed_factors(self, sd, p[0], k, c, uv, &f_r, &f_c);
    out->det = f_r * f_c;
    if (!(fabs(out->det) > ORTHO_DET_SINGULAR) || !(fabs(f_r) > ORTHO_DET_SINGULAR))
        return 0;
    double qd[2] = {0.0, 0.0}, rhs[2];
    qd[r] = vec3_dot(p[1], sr) / krr;
    second_derivative_rhs(sd, p, qd, rhs);
    const double dd = rhs[r] / krr;
    out->du = r == 0 ? qd[0] : 0.0;
    out->dv = r == 1 ? qd[1] : 0.0;
    out->ddu = r == 0 ? dd : 0.0;
    out->ddv = r == 1 ? dd : 0.0;
    const double speed = fabs(qd[r]) * sqrt(grr);
    out->speed = speed > DBL_MIN ? speed : DBL_MIN;
    return 1;
}

static int ortho_derivatives(const pc_projector *self, double t, double u, double v,
                             pc_proj_point *out)
{
    pc_vec3 sd[PC_D3_COUNT], p[3];
    double k[4], f[2];
    pc_proj_point_start(out, t, u, v);
    pc_surface_eval_d3(&self->surface->nurbs, u, v, &cache_of(self)->hint_u,
                       &cache_of(self)->hint_v, sd);
    out->s = sd[PC_D3_S];
    if (!eval_curve(self, t, 2, p)) {
        out->p = vec3(NAN, NAN, NAN);
        return 0;
    }
    out->p = p[0];
    tensor_and_residual(sd, p[0], k, f);
    const pc_collapse c = pc_collapsed_direction(sd[PC_D3_U], sd[PC_D3_V]);
    if (c != PC_COLLAPSE_NONE)
        return collapsed_derivatives(self, sd, p, k, c, out);
    out->det = normalized_det(sd, k);

    /* [PW96] eq. (16): q' = K^-1 [P'.Su; P'.Sv]. */
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
    pc_vec3 sd[PC_D3_COUNT], p;
    double k[4], f[2];
    if (!eval_curve(self, t, 0, &p))
        return INFINITY;
    pc_nurbs_surface_eval(&self->surface->nurbs, u, v, 2, &cache_of(self)->hint_u,
                          &cache_of(self)->hint_v, sd);
    const pc_collapse c = pc_collapsed_direction(sd[PC_D3_U], sd[PC_D3_V]);
    if (c != PC_COLLAPSE_NONE) {
        pc_surface_eval_d3(&self->surface->nurbs, u, v, &cache_of(self)->hint_u,
                           &cache_of(self)->hint_v, sd);
        /* Across S_r, the part within the allowance is the error of the
         * tangent m's direction, times |S - P|, not a distance of the point
         * from its foot: ortho_correct accepts the same (the collapsed
         * parameter stays there), and a point it accepts must pass here
         * (horn.xml's tip: across 5.89156e-7, allowance 5.89105e-7). */
        const collapsed_residual z = split_residual(sd, p, c, self->model_size);
        return hypot(z.regular, fmax(0.0, z.across - z.allowed));
    }
    tensor_and_residual(sd, p, k, f);
    double delta[2];
    return foot_residual(sd, k, f, delta);
}

int pc_ortho_morse_index(const pc_projector *proj, double t, double u, double v, int *index)
{
    pc_vec3 sd[PC_D3_COUNT], p;
    double k[4], f[2];
    if (!eval_curve(proj, t, 0, &p))
        return 0;
    pc_nurbs_surface_eval(&proj->surface->nurbs, u, v, 2, &cache_of(proj)->hint_u,
                          &cache_of(proj)->hint_v, sd);
    tensor_and_residual(sd, p, k, f);
    const pc_collapse c = pc_collapsed_direction(sd[PC_D3_U], sd[PC_D3_V]);
    if (c != PC_COLLAPSE_NONE) {
        /* det K is 0/0 here: the index from the two factors */
        pc_surface_eval_d3(&proj->surface->nurbs, u, v, &cache_of(proj)->hint_u,
                           &cache_of(proj)->hint_v, sd);
        const double uv[2] = {u, v};
        double f_r, f_c;
        collapsed_factors(proj, sd, p, k, c, uv, &f_r, &f_c);
        *index = (f_r < 0.0) + (f_c < 0.0);
        return 1;
    }
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
    proj->ray_dir = NULL; /* no ray */
}
