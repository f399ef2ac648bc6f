/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Local solvers for point projection onto a surface: Newton on the foot
 * point equations G = 0, and a bound-constrained minimiser of the distance.
 *
 * With r = S - p, D = |r|^2 / 2 has gradient G = [r.Su, r.Sv] ([Ook]:
 * d(u) = R'(u).(R(u) - r), here in two parameters) and Hessian
 *     H = [[Su.Su + r.Suu, Su.Sv + r.Suv], [Su.Sv + r.Suv, Sv.Sv + r.Svv]].
 * Newton solves H delta = -G. H is singular where p is a centre of
 * curvature; the minimiser then falls back to Gauss-Newton (J^T J, the
 * first fundamental form), which is positive definite on regular surfaces.
 */
#include "point/point.h"

/* Foot point accepted when each component of G is below
 * FOOT_TOL_COS |r| |S_dir| + FOOT_TOL_ABS size |S_dir|: the angle between r
 * and the tangent plane is ~1e-10 or r is at rounding level of the model. */
#define FOOT_TOL_COS 1e-10
#define FOOT_TOL_ABS 1e-12
#define FOOT_MAX_ITER 40
/* Newton gives up beyond this many step limits from its start. */
#define FOOT_MAX_TRAVEL 4.0
#define FOOT_MAX_HALVINGS 12
#define MIN_MAX_ITER 60
#define MIN_MAX_HALVINGS 40
/* The minimiser stops when a full step would move S by less than this
 * (relative to the model size). */
#define MIN_STEP_TOL 1e-13
/* ... or when a step below this (relative) lowered |S - p|^2 by less than
 * MIN_NOISE_DECREASE relative: the minimum is reached to rounding. */
#define MIN_NOISE_STEP 1e-7
#define MIN_NOISE_DECREASE 1e-14

typedef struct local_frame {
    size_t hint_u, hint_v; /* spans of the last evaluation: steps stay near */
    pc_vec3 d[6];          /* S, Su, Sv, Suu, Suv, Svv */
    pc_vec3 r;
    double g[2];
    double h[3];  /* H11, H12, H22 */
} local_frame;

static void frame_at(const pc_nurbs_surface *s, pc_vec3 p, const double uv[2], local_frame *f)
{
    pc_nurbs_surface_eval(s, uv[0], uv[1], 2, &f->hint_u, &f->hint_v, f->d);
    f->r = vec3_sub(f->d[0], p);
    f->g[0] = vec3_dot(f->r, f->d[1]);
    f->g[1] = vec3_dot(f->r, f->d[2]);
    f->h[0] = vec3_dot(f->d[1], f->d[1]) + vec3_dot(f->r, f->d[3]);
    f->h[1] = vec3_dot(f->d[1], f->d[2]) + vec3_dot(f->r, f->d[4]);
    f->h[2] = vec3_dot(f->d[2], f->d[2]) + vec3_dot(f->r, f->d[5]);
}

static double clampd(double x, double lo, double hi) { return x < lo ? lo : (x > hi ? hi : x); }

/* A knot span at an end of the domain narrower than this fraction of the
 * domain is of rounding width (hammer.iges has [-1.2e-15, 0] in v, its
 * control rows equal): in space it is its edge curve, and its derivatives,
 * divided by that width, are noise (there Sv = 0, so a minimiser that the
 * bound clamps into it stops there, 1.4 model units from a point of S a
 * little inside). The solvers keep out of such end spans: their inner end
 * is the same curve of S, with the neighbouring span's derivatives. */
#define THIN_END_SPAN 1e-12

/* The part of [knots[deg], knots[n]] left when the end spans narrower than
 * THIN_END_SPAN of it are cut off, into bound[0..1]. */
static void solid_range(const double *knots, size_t n, int deg, double bound[2])
{
    const size_t first = (size_t)deg;
    const double thin = THIN_END_SPAN * (knots[n] - knots[first]);
    double lo = knots[first], hi = knots[n];
    /* bounded: each pass moves one knot inward */
    for (size_t k = first; k < n && knots[k + 1] - knots[k] <= thin; ++k)
        lo = knots[k + 1];
    for (size_t k = n; k > first && knots[k] - knots[k - 1] <= thin; --k)
        hi = knots[k - 1];
    bound[0] = lo < hi ? lo : knots[first];
    bound[1] = lo < hi ? hi : knots[n];
}

/* The box the solvers move in: the domain without thin end spans. */
static void solver_box(const pc_nurbs_surface *s, double dom[4])
{
    solid_range(s->knots_u, s->n_u, s->deg_u, dom);
    solid_range(s->knots_v, s->n_v, s->deg_v, dom + 2);
}

static int is_foot(const local_frame *f, double model_size)
{
    const double rn = vec3_norm(f->r);
    for (int k = 0; k < 2; ++k) {
        const double tn = vec3_norm(f->d[1 + k]);
        if (!(fabs(f->g[k]) <= (FOOT_TOL_COS * rn + FOOT_TOL_ABS * model_size) * tn))
            return 0;
    }
    return 1;
}

static double g_norm2(const local_frame *f) { return f->g[0] * f->g[0] + f->g[1] * f->g[1]; }

/* Newton on G = 0 damped by backtracking on |G|^2 (the Newton direction
 * descends |G|^2 wherever H is regular): plain Newton oscillates between
 * the sides of a strongly curved sub-patch instead of converging. */
int pc_surface_foot_newton(const pc_nurbs_surface *s, pc_vec3 p, double model_size,
                           double max_step_u, double max_step_v, double uv[2])
{
    double dom[4];
    solver_box(s, dom);
    double x[2] = {clampd(uv[0], dom[0], dom[1]), clampd(uv[1], dom[2], dom[3])};
    const double x0[2] = {x[0], x[1]};
    local_frame f;
    f.hint_u = f.hint_v = 0;
    frame_at(s, p, x, &f);
    for (int it = 0; it < FOOT_MAX_ITER; ++it) {
        if (is_foot(&f, model_size)) {
            uv[0] = x[0];
            uv[1] = x[1];
            return 1;
        }
        const double rhs[2] = {-f.g[0], -f.g[1]};
        double delta[2];
        if (!mat2_solve(f.h[0], f.h[1], f.h[1], f.h[2], rhs, delta))
            return 0;
        /* Keep Newton local: a start inside a small sub-patch must not jump
         * to a far basin in one step. */
        delta[0] = clampd(delta[0], -max_step_u, max_step_u);
        delta[1] = clampd(delta[1], -max_step_v, max_step_v);
        local_frame nf; /* no initialiser: zeroing it costs more than a step */
        nf.hint_u = f.hint_u;
        nf.hint_v = f.hint_v;
        double nx[2];
        double alpha = 1.0;
        int accepted = 0;
        for (int k = 0; k < FOOT_MAX_HALVINGS; ++k, alpha *= 0.5) {
            nx[0] = clampd(x[0] + alpha * delta[0], dom[0], dom[1]);
            nx[1] = clampd(x[1] + alpha * delta[1], dom[2], dom[3]);
            if (nx[0] == x[0] && nx[1] == x[1])
                return 0; /* stuck against the boundary: no interior foot point here */
            frame_at(s, p, nx, &nf);
            if (g_norm2(&nf) < g_norm2(&f)) {
                accepted = 1;
                break;
            }
        }
        if (!accepted)
            return 0; /* a local minimum of |G| that is not a root */
        x[0] = nx[0];
        x[1] = nx[1];
        f = nf;
        /* Wandering off: the foot point of this basin is not near the start
         * (the caller starts Newton near every candidate). */
        if (fabs(x[0] - x0[0]) > FOOT_MAX_TRAVEL * max_step_u ||
            fabs(x[1] - x0[1]) > FOOT_MAX_TRAVEL * max_step_v)
            return 0;
    }
    return 0; /* iteration cap: not converged, the caller reports nothing */
}

/* A descent direction for D on the free coordinates: Newton if H is
 * positive definite there, else Gauss-Newton, else the scaled gradient. */
static void descent_direction(const local_frame *f, const int free_dir[2], double delta[2])
{
    const double g11 = vec3_dot(f->d[1], f->d[1]), g12 = vec3_dot(f->d[1], f->d[2]);
    const double g22 = vec3_dot(f->d[2], f->d[2]);
    delta[0] = delta[1] = 0.0;
    if (free_dir[0] && free_dir[1]) {
        const double rhs[2] = {-f->g[0], -f->g[1]};
        const double det = f->h[0] * f->h[2] - f->h[1] * f->h[1];
        if (f->h[0] > 0.0 && det > 0.0 && mat2_solve(f->h[0], f->h[1], f->h[1], f->h[2], rhs, delta))
            return;
        if (mat2_solve(g11, g12, g12, g22, rhs, delta))
            return;
        const double scale = g11 + g22 > 0.0 ? 1.0 / (g11 + g22) : 0.0;
        delta[0] = -f->g[0] * scale;
        delta[1] = -f->g[1] * scale;
        return;
    }
    const int k = free_dir[0] ? 0 : 1;
    const double hk = f->h[k == 0 ? 0 : 2], gk = k == 0 ? g11 : g22;
    const double curv = hk > 0.0 ? hk : gk;
    if (curv > 0.0)
        delta[k] = -f->g[k] / curv;
}

static double minimize_masked(const pc_nurbs_surface *s, pc_vec3 p, double model_size,
                              double uv[2], const int movable[2])
{
    double dom[4];
    solver_box(s, dom);
    double x[2] = {clampd(uv[0], dom[0], dom[1]), clampd(uv[1], dom[2], dom[3])};
    /* The current frame and the trial one; an accepted step swaps them
     * (copying a frame costs more than the step's bookkeeping). */
    local_frame frames[2];
    local_frame *f = &frames[0], *nf = &frames[1];
    f->hint_u = f->hint_v = 0;
    frame_at(s, p, x, f);
    double d2 = vec3_dot(f->r, f->r);
    const double step_tol2 = (MIN_STEP_TOL * model_size) * (MIN_STEP_TOL * model_size);
    const double noise_step2 = (MIN_NOISE_STEP * model_size) * (MIN_NOISE_STEP * model_size);
    for (int it = 0; it < MIN_MAX_ITER; ++it) {
        /* Active set: a coordinate on its bound whose gradient pushes out. */
        const int free_dir[2] = {
            movable[0] && !((x[0] <= dom[0] && f->g[0] > 0.0) || (x[0] >= dom[1] && f->g[0] < 0.0)),
            movable[1] && !((x[1] <= dom[2] && f->g[1] > 0.0) || (x[1] >= dom[3] && f->g[1] < 0.0))};
        if (!free_dir[0] && !free_dir[1])
            break;
        double delta[2];
        descent_direction(f, free_dir, delta);
        if (delta[0] * f->g[0] + delta[1] * f->g[1] > 0.0)
            break; /* no descent left at rounding level */
        /* Predicted displacement of S for the full step: converged when it
         * is at rounding level of the model. */
        const pc_vec3 moved = vec3_add(vec3_scale(f->d[1], delta[0]), vec3_scale(f->d[2], delta[1]));
        const double predicted2 = vec3_dot(moved, moved); /* squared: no sqrt latency */
        if (predicted2 <= step_tol2)
            break; /* the step would move S by rounding noise: not worth an evaluation */
        double alpha = 1.0;
        int accepted = 0;
        nf->hint_u = f->hint_u;
        nf->hint_v = f->hint_v;
        double nx[2];
        for (int k = 0; k < MIN_MAX_HALVINGS; ++k, alpha *= 0.5) {
            nx[0] = clampd(x[0] + alpha * delta[0], dom[0], dom[1]);
            nx[1] = clampd(x[1] + alpha * delta[1], dom[2], dom[3]);
            frame_at(s, p, nx, nf);
            if (vec3_dot(nf->r, nf->r) <= d2) {
                accepted = 1;
                break;
            }
        }
        if (!accepted)
            break;
        const double previous = d2;
        x[0] = nx[0];
        x[1] = nx[1];
        local_frame *const previous_frame = f;
        f = nf;
        nf = previous_frame;
        d2 = vec3_dot(f->r, f->r);
        /* At rounding level the gradient is noise and Newton's step with
         * it: stop once small steps no longer lower the distance. */
        if (predicted2 <= noise_step2 && previous - d2 <= MIN_NOISE_DECREASE * previous)
            break;
    }
    /* Also after the iteration cap: the best point reached, which the
     * line search never lets get worse than the start. */
    uv[0] = x[0];
    uv[1] = x[1];
    return d2;
}

double pc_surface_minimize(const pc_nurbs_surface *s, pc_vec3 p, double model_size,
                           double uv[2])
{
    static const int both[2] = {1, 1};
    return minimize_masked(s, p, model_size, uv, both);
}

double pc_surface_minimize_along(const pc_nurbs_surface *s, pc_vec3 p, double model_size,
                                 double uv[2], int dir)
{
    const int movable[2] = {dir == 0, dir == 1};
    return minimize_masked(s, p, model_size, uv, movable);
}
