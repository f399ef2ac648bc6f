/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Orthogonal projection onto implicit surfaces ([PW96] s5): sphere, plane,
 * cylinder and torus given by f, grad f and Hess f, against their analytic
 * foot points; x' and x'' against finite differences of the analytic foot
 * point curve; centres of curvature; the one branch traced (the parametric
 * route finds more); bad input, among it a gradient that vanishes at one
 * point the trace runs into.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "ortho/implicit.h"
#include "projcurve.h"
#include "shapes.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* ---------------------------------------------------------------- shapes */

typedef enum shape_kind { SPHERE, PLANE, CYLINDER, TORUS } shape_kind;

typedef struct shape {
    shape_kind kind;
    double a, b;    /* sphere/cylinder radius a; torus radii a (centre circle), b (tube) */
} shape;

static int shape_fn(void *user, const double x[3], double *value, double grad[3],
                    double hess[9])
{
    const shape *s = user;
    memset(hess, 0, 9 * sizeof *hess);
    switch (s->kind) {
    case SPHERE:
        *value = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] - s->a * s->a;
        for (int i = 0; i < 3; ++i) {
            grad[i] = 2.0 * x[i];
            hess[4 * i] = 2.0;
        }
        return 0;
    case PLANE:
        *value = x[2];
        grad[0] = grad[1] = 0.0;
        grad[2] = 1.0;
        return 0;
    case CYLINDER:
        *value = x[0] * x[0] + x[1] * x[1] - s->a * s->a;
        grad[0] = 2.0 * x[0];
        grad[1] = 2.0 * x[1];
        grad[2] = 0.0;
        hess[0] = hess[4] = 2.0;
        return 0;
    case TORUS: {
        /* f = (|x|^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + y^2) */
        const double R = s->a, r = s->b;
        const double q = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + R * R - r * r;
        *value = q * q - 4.0 * R * R * (x[0] * x[0] + x[1] * x[1]);
        const double c[3] = {4.0 * R * R, 4.0 * R * R, 0.0};
        for (int i = 0; i < 3; ++i) {
            grad[i] = 4.0 * q * x[i] - 2.0 * c[i] * x[i];
            for (int j = 0; j < 3; ++j)
                hess[3 * i + j] = 8.0 * x[i] * x[j] + (i == j ? 4.0 * q - 2.0 * c[i] : 0.0);
        }
        return 0;
    }
    }
    return 1;
}

/* The analytic foot point nearest to p. */
static void shape_foot(const shape *s, const double p[3], double q[3])
{
    switch (s->kind) {
    case SPHERE: {
        const double n = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        for (int i = 0; i < 3; ++i)
            q[i] = s->a * p[i] / n;
        return;
    }
    case PLANE:
        q[0] = p[0];
        q[1] = p[1];
        q[2] = 0.0;
        return;
    case CYLINDER: {
        const double n = hypot(p[0], p[1]);
        q[0] = s->a * p[0] / n;
        q[1] = s->a * p[1] / n;
        q[2] = p[2];
        return;
    }
    case TORUS: {
        const double n = hypot(p[0], p[1]);
        const double c[3] = {s->a * p[0] / n, s->a * p[1] / n, 0.0};
        const double d[3] = {p[0] - c[0], p[1] - c[1], p[2]};
        const double dn = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (int i = 0; i < 3; ++i)
            q[i] = c[i] + s->b * d[i] / dn;
        return;
    }
    }
}

/* ---------------------------------------------------------------- curves */

/* A wavy space curve: P(t) = centre + (rad cos t, rad sin t, h sin 2t). */
typedef struct wave {
    double centre[3], rad, h;
    int fail_at_end;   /* return NaN for t > 1 (bad-input test) */
} wave;

static int wave_fn(void *user, double t, double out[9])
{
    const wave *w = user;
    if (w->fail_at_end && t > 1.0) {
        for (int i = 0; i < 9; ++i)
            out[i] = NAN;
        return 0;
    }
    const double c = cos(t), s = sin(t), c2 = cos(2 * t), s2 = sin(2 * t);
    const double v[9] = {w->centre[0] + w->rad * c, w->centre[1] + w->rad * s,
                         w->centre[2] + w->h * s2, -w->rad * s, w->rad * c, 2 * w->h * c2,
                         -w->rad * c, -w->rad * s, -4 * w->h * s2};
    memcpy(out, v, sizeof v);
    return 0;
}

static void wave_point(const wave *w, double t, double p[3])
{
    double v[9];
    wave_fn((void *)w, t, v);
    memcpy(p, v, 3 * sizeof *p);
}

/* ---------------------------------------------------------------- checks */

static double dist3(const double a[3], const double b[3])
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* Every vertex is the exact foot point, the pieces cover [t0, t1] without
 * gaps and each is within eps_d of the exact foot point at the same t on
 * dense samples (a pointwise bound in t bounds the Hausdorff distance). */
static void check_against_oracle(const char *what, const projcurve_result *r, const shape *s,
                                 const wave *w, double t0, double t1, double eps_d)
{
    CHECK(projcurve_result_point_dim(r) == 4);
    CHECK(projcurve_result_branch_count(r) == 1);
    projcurve_branch_start start;
    projcurve_branch_end end;
    size_t n_points = 0, n_pieces = 0;
    double range[2];
    CHECK_OK(projcurve_result_branch_info(NULL, r, 0, range, &start, &end, &n_points, &n_pieces));
    CHECK(start == PROJCURVE_START_CURVE_START);
    CHECK(end == PROJCURVE_END_CURVE_END);
    CHECK_NEAR(range[0], t0, 0.0);
    CHECK_NEAR(range[1], t1, 1e-12);
    CHECK(n_pieces + 1 == n_points);

    static double pts[4 * 20000];
    size_t count = 0;
    CHECK_OK(projcurve_result_branch_points(NULL, r, 0, 20000, pts, &count));
    double vertex_err = 0.0;
    for (size_t i = 0; i < count && i < 20000; ++i) {
        double p[3], q[3];
        wave_point(w, pts[4 * i], p);
        shape_foot(s, p, q);
        vertex_err = fmax(vertex_err, dist3(q, pts + 4 * i + 1));
    }
    double piece_err = 0.0, t_prev = t0;
    for (size_t k = 0; k < n_pieces; ++k) {
        int degree = 0;
        double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], pr[2];
        CHECK_OK(projcurve_result_piece(NULL, r, 0, k, &degree, ctrl, NULL, pr, NULL));
        CHECK(degree == 3);
        CHECK_NEAR(pr[0], t_prev, 0.0);
        t_prev = pr[1];
        for (int j = 0; j <= 64; ++j) {
            const double u = j / 64.0, v = 1.0 - u;
            const double bw[4] = {v * v * v, 3 * v * v * u, 3 * v * u * u, u * u * u};
            double b[3] = {0, 0, 0}, p[3], q[3];
            for (int c = 0; c < 4; ++c)
                for (int i = 0; i < 3; ++i)
                    b[i] += bw[c] * ctrl[3 * c + i];
            wave_point(w, pr[0] + u * (pr[1] - pr[0]), p);
            shape_foot(s, p, q);
            piece_err = fmax(piece_err, dist3(b, q));
        }
    }
    CHECK_NEAR(t_prev, t1, 1e-12);
    /* The pieces joined into one cubic B-spline parametrised by t (double
     * knots at the vertices, C1): C(t) against the exact foot point. */
    projcurve_curve *joined = NULL;
    CHECK_OK(projcurve_result_branch_curve(NULL, r, 0, &joined));
    double spline_err = 0.0;
    int degree = 0;
    CHECK_OK(projcurve_curve_nurbs_info(NULL, joined, &degree, NULL, NULL, NULL));
    CHECK(degree == 3);
    for (int j = 0; joined && j <= 2000; ++j) {
        const double t = t0 + (t1 - t0) * j / 2000.0;
        double c[3], p[3], q[3];
        CHECK_OK(projcurve_curve_eval(NULL, joined, t, 0, c));
        wave_point(w, t, p);
        shape_foot(s, p, q);
        spline_err = fmax(spline_err, dist3(c, q));
    }
    projcurve_curve_destroy(joined);
    CHECK(spline_err <= eps_d);
    printf("%-28s points %5zu pieces %5zu vertex err %.2e piece err %.2e spline err %.2e "
           "(eps_D %.1e)\n",
           what, n_points, n_pieces, vertex_err, piece_err, spline_err, eps_d);
    /* Vertices are Newton-converged foot points: 1e-12 relative Newton
     * tolerance on a model of size ~20 plus rounding. */
    CHECK(vertex_err <= 1e-9);
    CHECK(piece_err <= eps_d);
}

static projcurve_options *make_options(double eps_d, long long method)
{
    projcurve_options *o = NULL;
    if (projcurve_options_create(NULL, &o) != PROJCURVE_OK)
        return NULL;
    projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE, eps_d);
    projcurve_options_set_int(NULL, o, PROJCURVE_OPT_METHOD, method);
    return o;
}

static void test_shape(const char *name, shape s, wave w, double t0, double t1)
{
    const double eps_d = 1e-5;
    projcurve_curve *curve = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, wave_fn, &w, t0, t1, &curve));
    /* Second order and RK4 with arc-length steps, then second order with a
     * constant parameter step. */
    static const char *const variants[3] = {"second-order", "rk4", "constant dt"};
    for (int variant = 0; variant < 3; ++variant) {
        projcurve_options *o = make_options(eps_d, variant == 1 ? PROJCURVE_METHOD_RK4
                                                                : PROJCURVE_METHOD_SECOND_ORDER);
        if (variant == 2)
            CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_PARAM_STEP, 0.05));
        projcurve_result *r = NULL;
        CHECK_OK(projcurve_project_orthogonal_implicit(NULL, shape_fn, &s, 20.0, curve, o, &r));
        if (r) {
            char what[64];
            snprintf(what, sizeof what, "%s %s", name, variants[variant]);
            check_against_oracle(what, r, &s, &w, t0, t1, eps_d);
        }
        projcurve_result_destroy(r);
        projcurve_options_destroy(o);
    }
    projcurve_curve_destroy(curve);
}

/* x' (ODE (32)) and x'' (difference of the field) at foot points of a
 * torus, against central differences of the analytic foot point curve. */
static void test_derivatives(void)
{
    shape s = {TORUS, 10.0, 3.0};
    wave w = {{0, 0, 1}, 11.0, 2.0, 0};
    projcurve_curve *curve = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, wave_fn, &w, 0.0, 6.0, &curve));
    pc_implicit imp = {shape_fn, &s, curve, 20.0, 1e-12 * 20.0, 30, 0.0};
    for (double t = 0.3; t < 6.0; t += 0.7) {
        double p[3], q[3], qp[3], qm[3], pp[3], pm[3], qpp[3], qmm[3];
        const double h = 1e-4;
        wave_point(&w, t, p);
        shape_foot(&s, p, q);
        wave_point(&w, t + h, pp);
        wave_point(&w, t - h, pm);
        shape_foot(&s, pp, qp);
        shape_foot(&s, pm, qm);
        wave_point(&w, t + 2 * h, pp);
        wave_point(&w, t - 2 * h, pm);
        shape_foot(&s, pp, qpp);
        shape_foot(&s, pm, qmm);
        pc_implicit_point pt;
        int solved = 0;
        CHECK_OK(pc_implicit_point_at(NULL, &imp, t, vec3_load(q), &pt, &solved));
        CHECK(solved);
        pc_vec3 xdd;
        CHECK_OK(pc_implicit_acceleration(NULL, &imp, &pt, &xdd, &solved));
        CHECK(solved);
        const double xd[3] = {pt.xd.x, pt.xd.y, pt.xd.z}, xdd3[3] = {xdd.x, xdd.y, xdd.z};
        for (int i = 0; i < 3; ++i) {
            /* Fourth-order differences: truncation h^4 |x^(5)| ~ 1e-14
             * times the curve's derivative scale, rounding 1e-15 * 10 / h. */
            const double d1 = (8 * (qp[i] - qm[i]) - (qpp[i] - qmm[i])) / (12 * h);
            const double d2 =
                (-(qpp[i] + qmm[i]) + 16 * (qp[i] + qm[i]) - 30 * q[i]) / (12 * h * h);
            CHECK_NEAR(xd[i], d1, 1e-8);
            CHECK_NEAR(xdd3[i], d2, 2e-5);
        }
    }
    projcurve_curve_destroy(curve);
}

/* A branch ends at a centre of curvature: a circle through the centre of a
 * sphere (umbilic: det K touches 0 without changing sign) and a line
 * through the axis of a cylinder (det K changes sign). */

static void check_ends_at(const char *what, projcurve_curve *curve, shape *s, double t_centre)
{
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_orthogonal_implicit(NULL, shape_fn, s, 20.0, curve, NULL, &r));
    CHECK(projcurve_result_branch_count(r) == 1);
    projcurve_branch_end end = PROJCURVE_END_CURVE_END;
    double range[2] = {0, 0};
    projcurve_result_branch_info(NULL, r, 0, range, NULL, &end, NULL, NULL);
    printf("%-28s ends at t = %.12f (centre at %.12f), end %d\n", what, range[1], t_centre,
           (int)end);
    CHECK(end == PROJCURVE_END_CURVATURE_CENTRE);
    CHECK_NEAR(range[1], t_centre, 1e-6);
    CHECK(range[1] <= t_centre);
    projcurve_result_destroy(r);
}

static void test_centres(void)
{
    shape sphere = {SPHERE, 10.0, 0.0};
    wave through_centre = {{5, 0, 0}, 5.0, 0.0, 0};   /* passes the origin at t = pi */
    projcurve_curve *curve = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, wave_fn, &through_centre, 0.5 * M_PI,
                                             1.5 * M_PI, &curve));
    check_ends_at("sphere, circle via centre", curve, &sphere, M_PI);
    projcurve_curve_destroy(curve);

    shape cyl = {CYLINDER, 5.0, 0.0};
    pc_shape_line l = {{-2, -1, 0}, {1, 0.5, 0.3}}; /* meets the z axis at t = 2 */
    CHECK_OK(projcurve_curve_create_callback(NULL, pc_shape_line_fn, &l, 0.0, 4.0, &curve));
    check_ends_at("cylinder, line via axis", curve, &cyl, 2.0);
    projcurve_curve_destroy(curve);
}

/* ------------------------------------------------------------- bad input */

typedef struct bad_surface {
    int mode;   /* 0: NaN value, 1: returns -1, 2: zero gradient, 3: NaN Hessian far away */
} bad_surface;

static int bad_fn(void *user, const double x[3], double *value, double grad[3], double hess[9])
{
    const bad_surface *b = user;
    shape plane = {PLANE, 0, 0};
    shape_fn(&plane, x, value, grad, hess);
    switch (b->mode) {
    case 0:
        *value = NAN;
        return 0;
    case 1:
        return -1;
    case 2:
        grad[0] = grad[1] = grad[2] = 0.0;
        return 0;
    default:
        if (x[0] > 0.5)
            hess[4] = NAN;
        return 0;
    }
}

static void test_bad_input(void)
{
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    pc_shape_line l = {{0, 0, 1}, {1, 0, 0}};
    projcurve_curve *curve = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, pc_shape_line_fn, &l, 0.0, 1.0, &curve));
    shape plane = {PLANE, 0, 0};
    projcurve_result *r = NULL;
    CHECK_STATUS(projcurve_project_orthogonal_implicit(ctx, NULL, &plane, 1.0, curve, NULL, &r),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_project_orthogonal_implicit(ctx, shape_fn, &plane, 1.0, NULL, NULL, &r),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_project_orthogonal_implicit(ctx, shape_fn, &plane, 1.0, curve, NULL,
                                                       NULL),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_project_orthogonal_implicit(ctx, shape_fn, &plane, 0.0, curve, NULL, &r),
                 PROJCURVE_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(projcurve_project_orthogonal_implicit(ctx, shape_fn, &plane, NAN, curve, NULL, &r),
                 PROJCURVE_ERR_NOT_FINITE);
    const projcurve_status expected[4] = {PROJCURVE_ERR_CALLBACK, PROJCURVE_ERR_CALLBACK,
                                          PROJCURVE_ERR_SINGULAR, PROJCURVE_ERR_CALLBACK};
    for (int mode = 0; mode < 4; ++mode) {
        bad_surface b = {mode};
        CHECK_STATUS(projcurve_project_orthogonal_implicit(ctx, bad_fn, &b, 1.0, curve, NULL, &r),
                     expected[mode]);
        CHECK(strlen(projcurve_context_message(ctx)) > 0);
    }
    CHECK(r == NULL);

    /* A curve callback that turns to NaN halfway. */
    wave w = {{0, 0, 1}, 1.0, 0.0, 1};
    projcurve_curve *bad_curve = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, wave_fn, &w, 0.0, 2.0, &bad_curve));
    CHECK_STATUS(projcurve_project_orthogonal_implicit(ctx, shape_fn, &plane, 1.0, bad_curve, NULL,
                                                       &r),
                 PROJCURVE_ERR_CALLBACK);
    CHECK(r == NULL);

    /* The point limit: a partial result ending with END_LIMIT. */
    projcurve_options *o = make_options(1e-6, PROJCURVE_METHOD_SECOND_ORDER);
    projcurve_options_set_int(NULL, o, PROJCURVE_OPT_MAX_POINTS, 16);
    projcurve_options_set_double(NULL, o, PROJCURVE_OPT_ARC_STEP_FRACTION, 1e-3);
    shape sphere = {SPHERE, 10.0, 0.0};
    wave around = {{0, 0, 2}, 12.0, 1.0, 0};
    projcurve_curve *c2 = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, wave_fn, &around, 0.0, 3.0, &c2));
    CHECK_STATUS(projcurve_project_orthogonal_implicit(ctx, shape_fn, &sphere, 20.0, c2, o, &r),
                 PROJCURVE_ERR_LIMIT_REACHED);
    CHECK(r != NULL);
    projcurve_branch_end end = PROJCURVE_END_CURVE_END;
    projcurve_result_branch_info(NULL, r, 0, NULL, NULL, &end, NULL, NULL);
    CHECK(end == PROJCURVE_END_LIMIT);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c2);
    projcurve_curve_destroy(bad_curve);
    projcurve_curve_destroy(curve);
    projcurve_context_destroy(ctx);
}

/* The implicit route traces one branch, from the foot point nearest P(t0)
 * (projcurve.h, docs/orthogonal.md): a point outside a sphere has two foot
 * points at every t, the near one and the antipodal one, and the parametric
 * route on the exact NURBS sphere returns both; the implicit route returns
 * the near one alone, over the whole curve, with no branch found in
 * mid-curve. */
static void test_one_branch(void)
{
    const double R = 10.0, centre[3] = {0, 0, 0};
    shape sphere = {SPHERE, R, 0.0};
    wave w = {{1, 0, 2}, 13.0, 3.0, 0};
    projcurve_curve *curve = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, wave_fn, &w, 0.0, 2.0, &curve));
    projcurve_result *ri = NULL, *rp = NULL;
    CHECK_OK(projcurve_project_orthogonal_implicit(NULL, shape_fn, &sphere, 20.0, curve, NULL,
                                                   &ri));
    pc_shape_surface data = pc_shape_sphere(centre, R);
    projcurve_surface *surf = pc_shape_surface_create(&data);
    pc_shape_surface_free(&data);
    /* every foot point: the far side of the sphere (a maximum) is the
     * parametric route's second branch */
    projcurve_options *all = NULL;
    CHECK_OK(projcurve_options_create(NULL, &all));
    CHECK_OK(projcurve_options_set_int(NULL, all, PROJCURVE_OPT_FOOT_POINTS,
                                       PROJCURVE_FOOT_POINTS_ALL));
    CHECK_OK(projcurve_project_orthogonal(NULL, surf, curve, all, &rp));
    projcurve_options_destroy(all);
    const size_t ni = ri ? projcurve_result_branch_count(ri) : 0;
    const size_t np = rp ? projcurve_result_branch_count(rp) : 0;
    printf("sphere: implicit route %zu branch(es), parametric route %zu\n", ni, np);
    CHECK(np == 2);
    CHECK(ni == 1);
    if (ni == 1) {
        double range[2] = {0, 0}, jumps = -1.0, pts[4 * 512];
        size_t got = 0;
        projcurve_result_branch_info(NULL, ri, 0, range, NULL, NULL, NULL, NULL);
        CHECK_NEAR(range[0], 0.0, 1e-12);
        CHECK_NEAR(range[1], 2.0, 1e-12);
        CHECK_OK(projcurve_result_stat(NULL, ri, PROJCURVE_STAT_JUMPS, &jumps));
        CHECK(jumps == 0.0);
        CHECK_OK(projcurve_result_branch_points(NULL, ri, 0, 512, pts, &got));
        /* every vertex is the near foot point R P / |P| (to newton_tol) */
        double worst = 0.0;
        for (size_t i = 0; i < got && i < 512; ++i) {
            double p[3], q[3];
            wave_point(&w, pts[4 * i], p);
            const double n = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            for (int k = 0; k < 3; ++k)
                q[k] = R * p[k] / n;
            worst = fmax(worst, dist3(pts + 4 * i + 1, q));
        }
        CHECK(worst <= 1e-8);
    }
    projcurve_result_destroy(ri);
    projcurve_result_destroy(rp);
    projcurve_surface_destroy(surf);
    projcurve_curve_destroy(curve);
}

/* The double cone x^2 + y^2 = z^2: its gradient vanishes at the apex only. */
static int cone_fn(void *user, const double x[3], double *value, double grad[3], double hess[9])
{
    (void)user;
    *value = x[0] * x[0] + x[1] * x[1] - x[2] * x[2];
    grad[0] = 2.0 * x[0];
    grad[1] = 2.0 * x[1];
    grad[2] = -2.0 * x[2];
    memset(hess, 0, 9 * sizeof *hess);
    hess[0] = hess[4] = 2.0;
    hess[8] = -2.0;
    return 0;
}

/* A gradient that vanishes in mid-trace: P(t) = (1.2 - t, 0, 1 - t) moves
 * parallel to a generator of the cone, its foot point (1.1 - t) (1, 0, 1)
 * along the generator into the apex at t = 1.1, where grad f = 0 (and the
 * cone is no regular surface). The branch ends there cleanly: status OK,
 * END_FAILED (the corrector cannot go on), measured 2e-9 before t = 1.1 and
 * 3e-9 from the apex (1e-6 allowed: where |grad f| ~ 3 |x| falls to the
 * corrector's scale the step can no longer be resolved), every vertex the
 * exact foot point, in bounded time (the ctest timeout guards against a
 * hang). A curve whose foot point starts at the apex cannot be seeded:
 * P(t0) on the cone's axis plane z = 0 projects along the gradient into
 * the apex, and the call says so with PROJCURVE_ERR_SINGULAR. */
static void test_gradient_vanishing(void)
{
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    pc_shape_line into = {{1.2, 0, 1}, {-1, 0, -1}}, from = {{-1, 0, 0}, {1, 0, 0}};
    projcurve_curve *c1 = NULL, *c2 = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, pc_shape_line_fn, &into, 0.0, 2.0, &c1));
    CHECK_OK(projcurve_curve_create_callback(NULL, pc_shape_line_fn, &from, 0.0, 2.0, &c2));
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_orthogonal_implicit(ctx, cone_fn, NULL, 2.0, c1, NULL, &r));
    if (r) {
        double range[2] = {0, 0}, pts[4 * 1024];
        projcurve_branch_end end = PROJCURVE_END_CURVE_END;
        size_t got = 0;
        CHECK(projcurve_result_branch_count(r) == 1);
        projcurve_result_branch_info(NULL, r, 0, range, NULL, &end, NULL, NULL);
        CHECK_OK(projcurve_result_branch_points(NULL, r, 0, 1024, pts, &got));
        double worst = 0.0, apex = INFINITY;
        for (size_t i = 0; i < got && i < 1024; ++i) {
            const double s = 1.1 - pts[4 * i], q[3] = {s, 0.0, s};
            worst = fmax(worst, dist3(pts + 4 * i + 1, q));
            apex = sqrt(pts[4 * i + 1] * pts[4 * i + 1] + pts[4 * i + 2] * pts[4 * i + 2] +
                        pts[4 * i + 3] * pts[4 * i + 3]);
        }
        printf("cone into the apex: end %d at t = %.12f, last vertex %.1e from the apex, "
               "vertex error %.1e\n",
               (int)end, range[1], apex, worst);
        CHECK(end == PROJCURVE_END_FAILED);
        CHECK_NEAR(range[1], 1.1, 1e-6);
        CHECK(apex <= 1e-6);
        CHECK(worst <= 1e-8);
    }
    projcurve_result_destroy(r);
    r = NULL;
    CHECK_STATUS(projcurve_project_orthogonal_implicit(ctx, cone_fn, NULL, 2.0, c2, NULL, &r),
                 PROJCURVE_ERR_SINGULAR);
    CHECK(r == NULL);
    CHECK(strstr(projcurve_context_message(ctx), "gradient") != NULL);
    projcurve_curve_destroy(c1);
    projcurve_curve_destroy(c2);
    projcurve_context_destroy(ctx);
}

int main(void)
{
    test_shape("sphere", (shape){SPHERE, 10.0, 0.0}, (wave){{1, 0, 2}, 13.0, 3.0, 0}, 0.0, 5.0);
    test_shape("plane", (shape){PLANE, 0.0, 0.0}, (wave){{0, 0, 4}, 8.0, 3.0, 0}, 0.0, 6.0);
    test_shape("cylinder", (shape){CYLINDER, 5.0, 0.0}, (wave){{0, 0, 1}, 7.0, 4.0, 0}, 0.0, 6.0);
    test_shape("torus", (shape){TORUS, 10.0, 3.0}, (wave){{0, 0, 1}, 11.0, 2.0, 0}, 0.0, 6.0);
    test_derivatives();
    test_centres();
    test_one_branch();
    test_bad_input();
    test_gradient_vanishing();
    return pc_test_finish("test_ortho_implicit");
}
