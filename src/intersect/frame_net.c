/* SPDX-License-Identifier: BSD-3-Clause */
#include "intersect/frame_net.h"

#include <math.h>

#include "common/compiler.h"
#include "common/vec.h"
#include "projcurve.h"

/* Newton stops when a step is this small in local parameters: a patch's
 * local parameters are O(1), so this is a few ulps. From a certified or
 * converged box it needs 1 to 5 steps; the bound only stops a wandering
 * iterate (reported as not converged). */
#define PC_NEWTON_STEP_TOL 1e-14
#define PC_NEWTON_MAX_ITER 16
/* Newton gives up when an iterate leaves the patch by more than this. */
#define PC_NEWTON_ESCAPE 0.5
/* Levenberg-Marquardt: iteration bound (near a double root each step
 * halves the distance, so 100 reach rounding from any box), damping
 * relative to trace(J^T J): first value, bound (beyond it no step lowers
 * the residual: a minimum to rounding), factor; and the step below which
 * the descent stops. */
#define PC_MIN_MAX_ITER 100
#define PC_MIN_DAMPING_START 1e-9
#define PC_MIN_DAMPING_MAX 1e12
#define PC_MIN_DAMPING_FACTOR 8.0
#define PC_MIN_STEP_TOL 1e-16

/* The evaluation is compiled once per common degree pair (constant trip
 * counts unroll the short loops) and once generically. */

/* Bernstein basis of degree n at x and its derivative (Piegl & Tiller's
 * triangle for degree n - 1, then one more step; B'_i = n (B_{i-1} - B_i)
 * at degree n - 1). */
static PC_ALWAYS_INLINE void bernstein_with_derivative(int n, double x, double *b, double *db)
{
    const double y = 1.0 - x;
    b[0] = 1.0;
    for (int k = 1; k < n; ++k) {
        double saved = 0.0;
        for (int i = 0; i < k; ++i) {
            const double tmp = b[i];
            b[i] = saved + y * tmp;
            saved = x * tmp;
        }
        b[k] = saved;
    }
    if (n == 0) {
        db[0] = 0.0;
        return;
    }
    /* b holds degree n - 1 now. */
    db[0] = -n * b[0];
    for (int i = 1; i < n; ++i)
        db[i] = n * (b[i - 1] - b[i]);
    db[n] = n * b[n - 1];
    double saved = 0.0;
    for (int i = 0; i < n; ++i) {
        const double tmp = b[i];
        b[i] = saved + y * tmp;
        saved = x * tmp;
    }
    b[n] = saved;
}

/* The first `channels` coordinates (2: X, Y; 4: all) of the net at (s, t)
 * and their partial derivatives. */
static PC_ALWAYS_INLINE void eval_net(const double *q, int m, int n, int channels, double s,
                                     double t, double *d, double *ds, double *dt)
{
    double bu[PROJCURVE_MAX_DEGREE + 1], dbu[PROJCURVE_MAX_DEGREE + 1];
    double bv[PROJCURVE_MAX_DEGREE + 1], dbv[PROJCURVE_MAX_DEGREE + 1];
    bernstein_with_derivative(m, s, bu, dbu);
    bernstein_with_derivative(n, t, bv, dbv);
    double acc[4] = {0, 0, 0, 0}, acc_s[4] = {0, 0, 0, 0}, acc_t[4] = {0, 0, 0, 0};
    for (int j = 0; j <= n; ++j) {
        const double *row = q + 4 * (size_t)j * (size_t)(m + 1);
        double r[4] = {0, 0, 0, 0}, rs[4] = {0, 0, 0, 0};
        for (int i = 0; i <= m; ++i) {
            for (int c = 0; c < channels; ++c) {
                r[c] += bu[i] * row[4 * i + c];
                rs[c] += dbu[i] * row[4 * i + c];
            }
        }
        for (int c = 0; c < channels; ++c) {
            acc[c] += bv[j] * r[c];
            acc_s[c] += bv[j] * rs[c];
            acc_t[c] += dbv[j] * r[c];
        }
    }
    for (int c = 0; c < channels; ++c) {
        d[c] = acc[c];
        if (ds) ds[c] = acc_s[c];
        if (dt) dt[c] = acc_t[c];
    }
}

void pc_frame_net_eval(const pc_frame_net *net, double s, double t, double d[4], double ds[4],
                       double dt[4])
{
    const int m = net->deg_u, n = net->deg_v;
    if (m == 3 && n == 3)
        eval_net(net->q, 3, 3, 4, s, t, d, ds, dt);
    else if (m == 2 && n == 2)
        eval_net(net->q, 2, 2, 4, s, t, d, ds, dt);
    else
        eval_net(net->q, m, n, 4, s, t, d, ds, dt);
}

/* (X, Y) and their derivatives only: what Newton and least squares need. */
static void eval_xy(const pc_frame_net *net, double s, double t, double d[2], double ds[2],
                    double dt[2])
{
    const int m = net->deg_u, n = net->deg_v;
    if (m == 3 && n == 3)
        eval_net(net->q, 3, 3, 2, s, t, d, ds, dt);
    else if (m == 2 && n == 2)
        eval_net(net->q, 2, 2, 2, s, t, d, ds, dt);
    else
        eval_net(net->q, m, n, 2, s, t, d, ds, dt);
}

void pc_frame_net_point(const pc_frame_net *net, double s, double t, pc_frame_root *out)
{
    double d[4], ds[4], dt[4];
    pc_frame_net_eval(net, s, t, d, ds, dt);
    const double iw = 1.0 / d[3];
    const pc_vec3 p = vec3(d[0] * iw, d[1] * iw, d[2] * iw);
    /* Quotient rule: S_s = (D_s - W_s S) / W. */
    const pc_vec3 ps = vec3_scale(vec3_axpy(vec3(ds[0], ds[1], ds[2]), -ds[3], p), iw);
    const pc_vec3 pt = vec3_scale(vec3_axpy(vec3(dt[0], dt[1], dt[2]), -dt[3], p), iw);
    const pc_vec3 normal = vec3_cross(ps, pt);
    const double nn = vec3_norm(normal);
    out->s = s;
    out->t = t;
    out->jac[0] = ds[0];
    out->jac[1] = dt[0];
    out->jac[2] = ds[1];
    out->jac[3] = dt[1];
    out->x = p.x;
    out->y = p.y;
    out->z = p.z;
    out->residual = sqrt(p.x * p.x + p.y * p.y);
    /* The frame's third axis is the line's direction. */
    out->cos_dir = nn > 0.0 ? fabs(normal.z) / nn : 0.0;
}

static inline double max2(double a, double b) { return a > b ? a : b; }

/* Squared planar length of a - b (first two coordinates). */
static inline double diff2(const double *a, const double *b)
{
    const double x = a[0] - b[0], y = a[1] - b[1];
    return x * x + y * y;
}

static PC_ALWAYS_INLINE void jacobian_bounds(const pc_frame_net *net, int m, int n,
                                            double *lipschitz, double *jac_max)
{
    const size_t row = (size_t)(m + 1);
    /* Largest squared first differences (s, t) and second differences (ss,
     * st, tt) of the (X, Y) net, each in its own branch-free loop. */
    const double *q = net->q;
    double s1 = 0.0, t1 = 0.0, ss = 0.0, st = 0.0, tt = 0.0;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i < m; ++i) {
            const double *a = q + 4 * ((size_t)j * row + (size_t)i);
            s1 = max2(s1, diff2(a + 4, a));
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i <= m; ++i) {
            const double *a = q + 4 * ((size_t)j * row + (size_t)i);
            t1 = max2(t1, diff2(a + 4 * row, a));
        }
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i + 1 < m; ++i) {
            const double *a = q + 4 * ((size_t)j * row + (size_t)i);
            const double x = a[8] - 2.0 * a[4] + a[0], y = a[9] - 2.0 * a[5] + a[1];
            ss = max2(ss, x * x + y * y);
        }
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i <= m; ++i) {
            const double *a = q + 4 * ((size_t)j * row + (size_t)i);
            const double *b = a + 4 * row, *c = a + 8 * row;
            const double x = c[0] - 2.0 * b[0] + a[0], y = c[1] - 2.0 * b[1] + a[1];
            tt = max2(tt, x * x + y * y);
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < m; ++i) {
            const double *a = q + 4 * ((size_t)j * row + (size_t)i);
            const double *b = a + 4, *c = a + 4 * row, *d = a + 4 * row + 4;
            const double x = d[0] - b[0] - c[0] + a[0], y = d[1] - b[1] - c[1] + a[1];
            st = max2(st, x * x + y * y);
        }
    /* Derivative bounds: |Q_s| <= m max|D_s Q|, |Q_ss| <= m (m - 1) max|D_ss Q|,
     * |Q_st| <= m n max|D_st Q|, ... (hull of the hodograph nets). */
    const double qss = m * (m - 1) * sqrt(ss), qst = m * n * sqrt(st), qtt = n * (n - 1) * sqrt(tt);
    *lipschitz = sqrt(qss * qss + 2.0 * qst * qst + qtt * qtt);
    const double qs = m * sqrt(s1), qt = n * sqrt(t1);
    *jac_max = sqrt(qs * qs + qt * qt);
}

void pc_frame_net_jacobian_bounds(const pc_frame_net *net, double *lipschitz, double *jac_max)
{
    const int m = net->deg_u, n = net->deg_v;
    if (m == 3 && n == 3)
        jacobian_bounds(net, 3, 3, lipschitz, jac_max);
    else if (m == 2 && n == 2)
        jacobian_bounds(net, 2, 2, lipschitz, jac_max);
    else
        jacobian_bounds(net, m, n, lipschitz, jac_max);
}

/* Whether the n + 1 control points from q with the given stride (in
 * points) coincide within tol at a point within tol of the line. */
static int edge_is_pole_on_line(const double *q, size_t stride, int n, double tol)
{
    const double x0 = q[0] / q[3], y0 = q[1] / q[3], z0 = q[2] / q[3];
    if (!(sqrt(x0 * x0 + y0 * y0) <= tol))
        return 0;
    for (int k = 1; k <= n; ++k) {
        const double *p = q + 4 * (size_t)k * stride;
        const double dx = p[0] / p[3] - x0, dy = p[1] / p[3] - y0, dz = p[2] / p[3] - z0;
        if (!(sqrt(dx * dx + dy * dy + dz * dz) <= tol))
            return 0;
    }
    return 1;
}

/* Whether the np control points coincide within tol. */
int pc_frame_net_is_point(const pc_frame_net *net, double tol)
{
    const size_t np = (size_t)(net->deg_u + 1) * (size_t)(net->deg_v + 1);
    const double *q = net->q;
    const double x0 = q[0] / q[3], y0 = q[1] / q[3], z0 = q[2] / q[3];
    for (size_t k = 1; k < np; ++k) {
        const double *p = q + 4 * k;
        const double dx = p[0] / p[3] - x0, dy = p[1] / p[3] - y0, dz = p[2] / p[3] - z0;
        if (!(sqrt(dx * dx + dy * dy + dz * dz) <= tol))
            return 0;
    }
    return 1;
}

unsigned pc_frame_net_poles_on_line(const pc_frame_net *net, double tol)
{
    const int m = net->deg_u, n = net->deg_v;
    const size_t row = (size_t)(m + 1);
    unsigned sides = 0;
    if (edge_is_pole_on_line(net->q, 1, m, tol))
        sides |= 1u;
    if (edge_is_pole_on_line(net->q + 4 * (size_t)n * row, 1, m, tol))
        sides |= 2u;
    if (edge_is_pole_on_line(net->q, row, n, tol))
        sides |= 4u;
    if (edge_is_pole_on_line(net->q + 4 * (size_t)m, row, n, tol))
        sides |= 8u;
    return sides;
}

int pc_frame_net_newton(const pc_frame_net *net, double s, double t, pc_frame_root *out)
{
    int converged = 0;
    for (int it = 0; it < PC_NEWTON_MAX_ITER; ++it) {
        double d[2], ds[2], dt[2];
        eval_xy(net, s, t, d, ds, dt);
        /* The zeros of (X, Y) = W (d1, d2) are those of (d1, d2) since W > 0;
         * at a zero, the Jacobian of (X, Y) is W times that of (d1, d2). */
        const double rhs[2] = {-d[0], -d[1]};
        double step[2];
        if (!mat2_solve(ds[0], dt[0], ds[1], dt[1], rhs, step))
            break;
        s += step[0];
        t += step[1];
        if (!(fabs(s - 0.5) <= 0.5 + PC_NEWTON_ESCAPE && fabs(t - 0.5) <= 0.5 + PC_NEWTON_ESCAPE))
            break;
        if (fabs(step[0]) + fabs(step[1]) <= PC_NEWTON_STEP_TOL) {
            converged = 1;
            break;
        }
    }
    pc_frame_net_point(net, s, t, out);
    return converged;
}

static double clamp(double x, double lo, double hi) { return x < lo ? lo : (x > hi ? hi : x); }

/* X^2 + Y^2 over W^2: the squared distance to the line. */
static double squared_residual(const double d[4])
{
    return (d[0] * d[0] + d[1] * d[1]) / (d[3] * d[3]);
}

/* x is held at a bound of the search region that is not the patch's edge. */
static int held_inside(double x, double lo, double hi)
{
    return (x <= lo && lo > 0.0) || (x >= hi && hi < 1.0);
}

int pc_frame_net_minimize(const pc_frame_net *net, const double box[4], pc_frame_root *out)
{
    const double ws = box[1] - box[0], wt = box[3] - box[2];
    const double lo_s = clamp(box[0] - ws, 0.0, 1.0), hi_s = clamp(box[1] + ws, 0.0, 1.0);
    const double lo_t = clamp(box[2] - wt, 0.0, 1.0), hi_t = clamp(box[3] + wt, 0.0, 1.0);
    double s = 0.5 * (box[0] + box[1]), t = 0.5 * (box[2] + box[3]);
    double d[4], ds[4], dt[4];
    pc_frame_net_eval(net, s, t, d, ds, dt);
    double f = squared_residual(d);
    double damping = 0.0;
    for (int it = 0; it < PC_MIN_MAX_ITER && f > 0.0; ++it) {
        /* Gauss-Newton normal equations of min |(X, Y)|^2, damped. */
        const double h00 = ds[0] * ds[0] + ds[1] * ds[1];
        const double h01 = ds[0] * dt[0] + ds[1] * dt[1];
        const double h11 = dt[0] * dt[0] + dt[1] * dt[1];
        const double g[2] = {-(ds[0] * d[0] + ds[1] * d[1]), -(dt[0] * d[0] + dt[1] * d[1])};
        const double trace = h00 + h11;
        if (!(trace > 0.0))
            break;
        int accepted = 0;
        double moved = 0.0;
        while (!accepted && damping <= PC_MIN_DAMPING_MAX) {
            const double mu = damping * trace;
            double step[2];
            if (mat2_solve(h00 + mu, h01, h01, h11 + mu, g, step)) {
                const double s_new = clamp(s + step[0], lo_s, hi_s);
                const double t_new = clamp(t + step[1], lo_t, hi_t);
                double d_new[4], ds_new[4], dt_new[4];
                pc_frame_net_eval(net, s_new, t_new, d_new, ds_new, dt_new);
                const double f_new = squared_residual(d_new);
                if (f_new < f) {
                    moved = fabs(s_new - s) + fabs(t_new - t);
                    s = s_new;
                    t = t_new;
                    f = f_new;
                    for (int c = 0; c < 4; ++c) {
                        d[c] = d_new[c];
                        ds[c] = ds_new[c];
                        dt[c] = dt_new[c];
                    }
                    damping *= 1.0 / PC_MIN_DAMPING_FACTOR;
                    accepted = 1;
                    break;
                }
            }
            damping = damping > 0.0 ? damping * PC_MIN_DAMPING_FACTOR : PC_MIN_DAMPING_START;
        }
        if (!accepted || moved <= PC_MIN_STEP_TOL)
            break;
    }
    pc_frame_net_point(net, s, t, out);
    return !held_inside(s, lo_s, hi_s) && !held_inside(t, lo_t, hi_t);
}
