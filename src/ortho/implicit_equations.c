/* SPDX-License-Identifier: BSD-3-Clause */
#include <float.h>
#include <math.h>

#include "common/error.h"
#include "ortho/implicit.h"
#include "ortho/morse_index.h"

/* |det K| at or below this: K is singular, P(t) is a centre of curvature.
 * det K is unitless ((1 + rho k1)(1 + rho k2)), so the bound is absolute. */
#define IMPLICIT_DET_SINGULAR 1e-14

/* Relative step of the central difference for x'' (about cbrt(DBL_EPSILON),
 * which balances the O(h^2) truncation against rounding O(eps / h): x''
 * comes out with a relative error near 1e-10, far below what a predictor
 * needs since the corrector removes its error anyway). */
#define IMPLICIT_FD_REL 6e-6

/* Projections onto f = 0 along the gradient before the foot-point Newton,
 * and the largest step one of them may take (in model sizes): a guess that
 * would move further is not near the surface and is abandoned. */
#define IMPLICIT_PROJECT_MAX_ITER 50
#define IMPLICIT_MAX_STEP_SIZES 1.0

/* Gaussian elimination with partial pivoting on the n x n (n <= 4) row-major
 * matrix a; b is overwritten by the solution, *det (may be NULL) gets the
 * determinant. Returns 0 for an exactly singular matrix. */
static int solve_linear(int n, double *a, double *b, double *det)
{
    double d = 1.0;
    for (int col = 0; col < n; ++col) {
        int piv = col;
        for (int row = col + 1; row < n; ++row)
            if (fabs(a[row * n + col]) > fabs(a[piv * n + col]))
                piv = row;
        if (a[piv * n + col] == 0.0) {
            if (det)
                *det = 0.0;
            return 0;
        }
        if (piv != col) {
            for (int k = 0; k < n; ++k) {
                const double tmp = a[col * n + k];
                a[col * n + k] = a[piv * n + k];
                a[piv * n + k] = tmp;
            }
            const double tb = b[col];
            b[col] = b[piv];
            b[piv] = tb;
            d = -d;
        }
        d *= a[col * n + col];
        for (int row = col + 1; row < n; ++row) {
            const double m = a[row * n + col] / a[col * n + col];
            for (int k = col; k < n; ++k)
                a[row * n + k] -= m * a[col * n + k];
            b[row] -= m * b[col];
        }
    }
    for (int row = n - 1; row >= 0; --row) {
        double s = b[row];
        for (int k = row + 1; k < n; ++k)
            s -= a[row * n + k] * b[k];
        b[row] = s / a[row * n + row];
    }
    if (det)
        *det = d;
    return 1;
}

projcurve_status pc_implicit_call(projcurve_context *ctx, const pc_implicit *imp, pc_vec3 x,
                                  pc_implicit_eval *out)
{
    const double at[3] = {x.x, x.y, x.z};
    double grad[3] = {0, 0, 0};
    out->value = NAN;
    for (int k = 0; k < 9; ++k)
        out->hess[k] = 0.0;
    const int rc = imp->fn(imp->user, at, &out->value, grad, out->hess);
    if (rc != 0)
        return pc_fail(ctx, PROJCURVE_ERR_CALLBACK,
                       "implicit surface callback returned %d at (%.17g, %.17g, %.17g)", rc,
                       x.x, x.y, x.z);
    out->grad = vec3_load(grad);
    int finite = isfinite(out->value) && vec3_is_finite(out->grad);
    for (int k = 0; k < 9; ++k)
        finite = finite && isfinite(out->hess[k]);
    if (!finite)
        return pc_fail(ctx, PROJCURVE_ERR_CALLBACK,
                       "implicit surface callback gave a non-finite value at "
                       "(%.17g, %.17g, %.17g)", x.x, x.y, x.z);
    const double gn = vec3_norm(out->grad);
    if (!(gn > imp->grad_floor) || !(gn >= DBL_MIN))
        return pc_fail(ctx, PROJCURVE_ERR_SINGULAR,
                       "gradient of the implicit surface vanishes (|grad f| = %.3g) at "
                       "(%.17g, %.17g, %.17g)", gn, x.x, x.y, x.z);
    return PROJCURVE_OK;
}

static projcurve_status eval_curve(projcurve_context *ctx, const pc_implicit *imp, double t,
                                   int n_deriv, pc_vec3 *p)
{
    if (pc_curve_eval(imp->curve, t, n_deriv, NULL, p) != PROJCURVE_OK)
        return pc_fail(ctx, PROJCURVE_ERR_CALLBACK, "curve callback failed at t = %.17g", t);
    return PROJCURVE_OK;
}

projcurve_status pc_implicit_velocity(projcurve_context *ctx, const pc_implicit *imp, double t,
                                      pc_vec3 x, pc_vec3 *xd, double det_trace[2],
                                      int *solved)
{
    pc_implicit_eval e;
    pc_vec3 p[2];
    *xd = vec3(0, 0, 0);
    *solved = 0;
    projcurve_status status = pc_implicit_call(ctx, imp, x, &e);
    if (status == PROJCURVE_OK)
        status = eval_curve(ctx, imp, t, 1, p);
    if (status != PROJCURVE_OK)
        return status;

    const double gn = vec3_norm(e.grad);
    const pc_vec3 n = vec3_scale(e.grad, 1.0 / gn);
    const double rho = vec3_dot(vec3_sub(p[0], x), n);   /* [PW96] eq. (21) */
    const double nv[3] = {n.x, n.y, n.z};
    /* K = I - rho B with B = (n n^T - I) H / |g| (eq. (29), (30)). */
    double k[9];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double nnh = 0.0;   /* (n n^T H)_ij */
            for (int m = 0; m < 3; ++m)
                nnh += nv[i] * nv[m] * e.hess[m * 3 + j];
            const double b_ij = (nnh - e.hess[i * 3 + j]) / gn;
            k[i * 3 + j] = (i == j ? 1.0 : 0.0) - rho * b_ij;
        }
    /* Trace of K on the tangent plane: 2 + rho (tr H - n.H n) / |g|. */
    double tr_h = 0.0, nhn = 0.0;
    for (int i = 0; i < 3; ++i) {
        tr_h += e.hess[i * 3 + i];
        for (int j = 0; j < 3; ++j)
            nhn += nv[i] * e.hess[i * 3 + j] * nv[j];
    }
    const double trace = 2.0 + rho * (tr_h - nhn) / gn;
    /* Right-hand side of eq. (31): the tangential part of P'. */
    const pc_vec3 rhs = vec3_axpy(p[1], -vec3_dot(p[1], n), n);
    double b[3] = {rhs.x, rhs.y, rhs.z};
    double d = 0.0;
    const int ok = solve_linear(3, k, b, &d);
    if (det_trace) {
        det_trace[0] = d;   /* det K = det of its tangential block (implicit.h) */
        det_trace[1] = trace;
    }
    if (!ok || !(fabs(d) > IMPLICIT_DET_SINGULAR))
        return PROJCURVE_OK;
    *xd = vec3_load(b);   /* eq. (32) */
    *solved = 1;
    return PROJCURVE_OK;
}

projcurve_status pc_implicit_point_at(projcurve_context *ctx, const pc_implicit *imp, double t,
                                      pc_vec3 x, pc_implicit_point *pt, int *solved)
{
    double det_trace[2] = {0.0, 0.0};
    pt->t = t;
    pt->x = x;
    const projcurve_status status =
        pc_implicit_velocity(ctx, imp, t, x, &pt->xd, det_trace, solved);
    pt->det = det_trace[0];
    pt->index = pc_morse_index(det_trace[0], det_trace[1]);
    return status;
}

/* x' at (x + s h x', t + s h). */
static projcurve_status field_along(projcurve_context *ctx, const pc_implicit *imp,
                                    const pc_implicit_point *pt, double s, double h,
                                    pc_vec3 *out, int *solved)
{
    return pc_implicit_velocity(ctx, imp, pt->t + s * h, vec3_axpy(pt->x, s * h, pt->xd), out,
                                NULL, solved);
}

projcurve_status pc_implicit_acceleration(projcurve_context *ctx, const pc_implicit *imp,
                                          const pc_implicit_point *pt, pc_vec3 *xdd,
                                          int *solved)
{
    const double span = imp->curve->t1 - imp->curve->t0;
    const double speed = vec3_norm(pt->xd);
    double h = IMPLICIT_FD_REL * span;
    if (speed * h > IMPLICIT_FD_REL * imp->model_size)
        h = IMPLICIT_FD_REL * imp->model_size / speed;
    *xdd = vec3(0, 0, 0);
    /* Central difference where t +- h is inside the domain, else the
     * one-sided three-point formula (-3 f0 + 4 f1 - f2) / 2h, which is
     * also O(h^2); the curve is never evaluated outside its domain. */
    const int room_left = pt->t - h >= imp->curve->t0;
    const int room_right = pt->t + h <= imp->curve->t1;
    pc_vec3 f1, f2;
    int ok1 = 0, ok2 = 0;
    projcurve_status status;
    if (room_left && room_right) {
        status = field_along(ctx, imp, pt, 1.0, h, &f1, &ok1);
        if (status == PROJCURVE_OK)
            status = field_along(ctx, imp, pt, -1.0, h, &f2, &ok2);
        if (status == PROJCURVE_OK && ok1 && ok2)
            *xdd = vec3_scale(vec3_sub(f1, f2), 0.5 / h);
    } else {
        const double dir = room_right ? 1.0 : -1.0;
        status = field_along(ctx, imp, pt, dir, h, &f1, &ok1);
        if (status == PROJCURVE_OK)
            status = field_along(ctx, imp, pt, 2.0 * dir, h, &f2, &ok2);
        if (status == PROJCURVE_OK && ok1 && ok2) {
            const pc_vec3 diff = vec3_axpy(vec3_axpy(vec3_scale(pt->xd, -3.0), 4.0, f1), -1.0, f2);
            *xdd = vec3_scale(diff, dir * 0.5 / h);
        }
    }
    *solved = ok1 && ok2;
    return status;
}

/* Newton along the gradient onto f = 0: x <- x - f g / |g|^2. */
static projcurve_status project_on_surface(projcurve_context *ctx, const pc_implicit *imp,
                                           pc_vec3 *x, int *ok)
{
    *ok = 0;
    for (int it = 0; it < IMPLICIT_PROJECT_MAX_ITER; ++it) {
        pc_implicit_eval e;
        const projcurve_status status = pc_implicit_call(ctx, imp, *x, &e);
        if (status != PROJCURVE_OK)
            return status;
        const double g2 = vec3_dot(e.grad, e.grad);
        const pc_vec3 step = vec3_scale(e.grad, -e.value / g2);
        const double len = vec3_norm(step);
        if (len > IMPLICIT_MAX_STEP_SIZES * imp->model_size)
            return PROJCURVE_OK;
        *x = vec3_add(*x, step);
        if (len <= imp->newton_tol) {
            *ok = 1;
            return PROJCURVE_OK;
        }
    }
    return PROJCURVE_OK;
}

projcurve_status pc_implicit_correct(projcurve_context *ctx, const pc_implicit *imp, double t,
                                     pc_vec3 *x, int *converged, int *iterations)
{
    pc_vec3 p;
    int on_surface = 0, it = 0;
    *converged = 0;
    if (iterations)
        *iterations = 0;
    projcurve_status status = eval_curve(ctx, imp, t, 0, &p);
    if (status == PROJCURVE_OK)
        status = project_on_surface(ctx, imp, x, &on_surface);
    if (status != PROJCURVE_OK || !on_surface)
        return status;

    /* Foot-point Newton on G(x, lambda) = [x - P + lambda g; f] = 0 with
     * Jacobian [[I + lambda H, g], [g^T, 0]] (singular exactly at centres
     * of curvature, like K). */
    double lambda = 0.0;
    for (; it < imp->newton_max_iter; ++it) {
        pc_implicit_eval e;
        status = pc_implicit_call(ctx, imp, *x, &e);
        if (status != PROJCURVE_OK)
            break;
        const double g2 = vec3_dot(e.grad, e.grad);
        if (it == 0)
            lambda = -vec3_dot(vec3_sub(*x, p), e.grad) / g2;
        const pc_vec3 r = vec3_axpy(vec3_sub(*x, p), lambda, e.grad);
        const double gv[3] = {e.grad.x, e.grad.y, e.grad.z};
        double a[16], b[4] = {-r.x, -r.y, -r.z, -e.value};
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j)
                a[i * 4 + j] = (i == j ? 1.0 : 0.0) + lambda * e.hess[i * 3 + j];
            a[i * 4 + 3] = gv[i];
            a[12 + i] = gv[i];
        }
        a[15] = 0.0;
        const double off = fabs(e.value) / sqrt(g2);   /* distance from f = 0 */
        if (!solve_linear(4, a, b, NULL))
            break;
        const pc_vec3 dx = vec3(b[0], b[1], b[2]);
        const double step = vec3_norm(dx);
        if (!(step <= IMPLICIT_MAX_STEP_SIZES * imp->model_size))
            break;
        *x = vec3_add(*x, dx);
        lambda += b[3];
        if (step <= imp->newton_tol && vec3_norm(r) <= imp->newton_tol &&
            off <= imp->newton_tol) {
            *converged = 1;
            ++it;
            break;
        }
    }
    if (iterations)
        *iterations = it;
    return status;
}
