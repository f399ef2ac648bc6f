/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * NURBS evaluation: exact analytic shapes, agreement of three independent
 * routes (de Boor on the user data, basis functions, Bezier patches) for
 * points and derivatives, derivatives against finite differences, exact
 * clamping of unclamped and truly periodic knot vectors, degrees 1..30,
 * copies of the user's arrays, callback curves, span lookup.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "deboor.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "shapes.h"

/* Points of exact rational shapes are computed with a few dozen roundings of
 * O(1) quantities: 1e-12 relative leaves a factor ~100 of headroom. */
#define TOL_EXACT 1e-12
/* Central differences with step h have error O(h^2 f''') ~ 1e-10 f''' at h = 1e-5
 * (f''' up to ~1e3 on the rational bumpy shape), plus rounding eps/h ~ 1e-11. */
#define FD_STEP 1e-5
#define TOL_FD 1e-6

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

static void test_circle(void)
{
    const double centre[3] = {1.5, -2.0, 0.25}, radius = 3.0;
    pc_shape_curve shape = pc_shape_circle(centre, radius);
    projcurve_curve *c = pc_shape_curve_create(&shape);
    CHECK(c != NULL);
    for (int k = 0; k <= 400; ++k) {
        const double t = k / 400.0;
        double out[12];
        CHECK_OK(projcurve_curve_eval(NULL, c, t, 3, out));
        const double r = dist3(out, centre);
        CHECK_NEAR(r, radius, TOL_EXACT * radius);
        CHECK_NEAR(out[2], centre[2], TOL_EXACT * radius);
        /* Tangent perpendicular to the radius. */
        const double dot = (out[0] - centre[0]) * out[3] + (out[1] - centre[1]) * out[4];
        CHECK_NEAR(dot, 0.0, TOL_EXACT * radius * sqrt(out[3] * out[3] + out[4] * out[4]));
    }
    projcurve_curve_destroy(c);
    pc_shape_curve_free(&shape);
}

typedef double (*implicit_fn)(const double *x);
static double g_torus_R = 2.0, g_torus_r = 0.5;
static double sphere_residual(const double *x) { return sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) - 1.25; }
static double cylinder_residual(const double *x) { return sqrt(x[0] * x[0] + x[1] * x[1]) - 0.75; }
static double torus_residual(const double *x)
{
    const double rho = sqrt(x[0] * x[0] + x[1] * x[1]) - g_torus_R;
    return sqrt(rho * rho + x[2] * x[2]) - g_torus_r;
}

static void check_on_shape(pc_shape_surface shape, implicit_fn f, double scale, const char *name)
{
    projcurve_surface *s = pc_shape_surface_create(&shape);
    CHECK(s != NULL);
    double worst = 0.0;
    for (int i = 0; i <= 60; ++i)
        for (int j = 0; j <= 60; ++j) {
            double out[3];
            CHECK_OK(projcurve_surface_eval(NULL, s, i / 60.0, j / 60.0, 0, out));
            const double e = fabs(f(out));
            if (e > worst)
                worst = e;
        }
    if (!(worst <= TOL_EXACT * scale))
        pc_test_fail_at(__FILE__, __LINE__, "%s: worst residual %.3g", name, worst);
    ++pc_test_checks;
    projcurve_surface_destroy(s);
    pc_shape_surface_free(&shape);
}

static void test_analytic_surfaces(void)
{
    const double origin[3] = {0, 0, 0};
    check_on_shape(pc_shape_sphere(origin, 1.25), sphere_residual, 1.25, "sphere");
    check_on_shape(pc_shape_cylinder(0.75, 2.0), cylinder_residual, 2.0, "cylinder");
    check_on_shape(pc_shape_torus(g_torus_R, g_torus_r), torus_residual, 2.5, "torus");
}

/* Largest coordinate magnitude of a shape's control points: the scale of
 * rounding errors in its evaluation. */
static double net_scale(const pc_shape_surface *s)
{
    double m = 0.0;
    for (size_t i = 0; i < 3 * s->n_u * s->n_v; ++i)
        m = fmax(m, fabs(s->ctrl[i]));
    return m;
}

/* Derivative order of each entry of S, Su, Sv, Suu, Suv, Svv. */
static const int k_entry_order[6] = {0, 1, 1, 2, 2, 2};

/* Scale of each derivative order over a set of oracle values (6 entries per
 * sample): the largest norm of an entry of that order, and at least the
 * scale of the order below (a plane has zero second derivatives, computed
 * from differences of first-derivative size). Rounding errors of every route
 * are relative to these. */
static void derivative_scales(const double (*ref)[18], int samples, double floor0,
                              double scale[3])
{
    scale[0] = floor0;
    scale[1] = scale[2] = 0.0;
    for (int k = 0; k < samples; ++k)
        for (int d = 0; d < 6; ++d)
            scale[k_entry_order[d]] = fmax(scale[k_entry_order[d]], sqrt(ref[k][3 * d] * ref[k][3 * d] +
                                                                       ref[k][3 * d + 1] * ref[k][3 * d + 1] +
                                                                       ref[k][3 * d + 2] * ref[k][3 * d + 2]));
    scale[1] = fmax(scale[1], scale[0]);
    scale[2] = fmax(scale[2], scale[1]);
}

/* Three routes at random parameters: de Boor on the user data (oracle, points
 * and derivatives from the differentiated control polygon), basis functions
 * (pc_nurbs_surface_eval and the public projcurve_surface_eval), the Bezier
 * patch containing (u, v). Every entry S .. Svv of every route is held to
 * tol times the scale of its derivative order. */
static void check_three_routes(const pc_shape_surface *shape, pc_test_rng *rng, int samples,
                               double tol)
{
    projcurve_surface *s = pc_shape_surface_create(shape);
    CHECK(s != NULL);
    if (s == NULL)
        return;
    const double *dom = s->nurbs.domain;
    double(*ref)[18] = malloc((size_t)samples * sizeof *ref);
    double(*uv)[2] = malloc((size_t)samples * sizeof *uv);
    for (int k = 0; k < samples; ++k) {
        uv[k][0] = pc_test_rng_uniform(rng, dom[0], dom[1]);
        uv[k][1] = pc_test_rng_uniform(rng, dom[2], dom[3]);
        pc_deboor_surface_ders(shape, uv[k][0], uv[k][1], ref[k]);
    }
    double scale[3];
    derivative_scales((const double(*)[18])ref, samples, net_scale(shape), scale);
    for (int k = 0; k < samples; ++k) {
        const double u = uv[k][0], v = uv[k][1];
        pc_vec3 basis[6], bez[6];
        double pub[18];
        size_t hu = 0, hv = 0;
        pc_nurbs_surface_eval(&s->nurbs, u, v, 2, &hu, &hv, basis);
        CHECK_OK(projcurve_surface_eval(NULL, s, u, v, 2, pub));
        const pc_bezier_patch *patch = &s->grid.patches[pc_patch_grid_locate(&s->grid, u, v)];
        CHECK(patch->u0 <= u && u <= patch->u1 && patch->v0 <= v && v <= patch->v1);
        pc_bezier_patch_eval(patch, u, v, 2, bez);
        for (int d = 0; d < 6; ++d) {
            const pc_vec3 r = vec3_load(ref[k] + 3 * d);
            const double e_basis = vec3_dist(basis[d], r), e_bez = vec3_dist(bez[d], r);
            const double e_pub = vec3_dist(vec3_load(pub + 3 * d), r);
            const double limit = tol * scale[k_entry_order[d]];
            if (!(e_basis <= limit && e_bez <= limit && e_pub <= limit))
                pc_test_fail_at(__FILE__, __LINE__,
                                "degrees (%d, %d) at (%.17g, %.17g), entry %d: de Boor (%.17g, "
                                "%.17g, %.17g); errors basis %.3g, Bezier %.3g, public %.3g > %.3g",
                                shape->deg_u, shape->deg_v, u, v, d, r.x, r.y, r.z, e_basis,
                                e_bez, e_pub, limit);
            ++pc_test_checks;
        }
        /* Orders 0 and 1 have evaluators of their own: same leading values. */
        for (int order = 0; order < 2; ++order) {
            pc_vec3 low[3];
            pc_nurbs_surface_eval(&s->nurbs, u, v, order, NULL, NULL, low);
            for (int d = 0; d < (order == 0 ? 1 : 3); ++d)
                CHECK_NEAR(vec3_dist(low[d], basis[d]), 0.0, tol * scale[k_entry_order[d]]);
        }
    }
    free(ref);
    free(uv);
    projcurve_surface_destroy(s);
}

static void check_fd_surface(const pc_shape_surface *shape, pc_test_rng *rng, int samples)
{
    projcurve_surface *s = pc_shape_surface_create(shape);
    CHECK(s != NULL);
    const double *dom = s->nurbs.domain;
    const double h = FD_STEP * (dom[1] - dom[0]), g = FD_STEP * (dom[3] - dom[2]);
    for (int k = 0; k < samples; ++k) {
        const double u = pc_test_rng_uniform(rng, dom[0] + 2 * h, dom[1] - 2 * h);
        const double v = pc_test_rng_uniform(rng, dom[2] + 2 * g, dom[3] - 2 * g);
        pc_vec3 c[6], pu[6], mu[6], pv[6], mv[6];
        pc_nurbs_surface_eval(&s->nurbs, u, v, 2, NULL, NULL, c);
        pc_nurbs_surface_eval(&s->nurbs, u + h, v, 2, NULL, NULL, pu);
        pc_nurbs_surface_eval(&s->nurbs, u - h, v, 2, NULL, NULL, mu);
        pc_nurbs_surface_eval(&s->nurbs, u, v + g, 2, NULL, NULL, pv);
        pc_nurbs_surface_eval(&s->nurbs, u, v - g, 2, NULL, NULL, mv);
        /* A knot between u - h and u + h breaks the smoothness the central
         * difference assumes; skip those samples. */
        if (pc_patch_grid_locate(&s->grid, u - h, v - g) != pc_patch_grid_locate(&s->grid, u + h, v + g))
            continue;
        double scale = 1.0;
        for (int d = 0; d < 6; ++d)
            scale = fmax(scale, vec3_norm(c[d]));
        const pc_vec3 fd[5] = {
            vec3_scale(vec3_sub(pu[0], mu[0]), 0.5 / h), vec3_scale(vec3_sub(pv[0], mv[0]), 0.5 / g),
            vec3_scale(vec3_sub(pu[1], mu[1]), 0.5 / h), vec3_scale(vec3_sub(pv[1], mv[1]), 0.5 / g),
            vec3_scale(vec3_sub(pv[2], mv[2]), 0.5 / g)};
        for (int d = 0; d < 5; ++d)
            CHECK_NEAR(vec3_dist(fd[d], c[d + 1]), 0.0, TOL_FD * scale);
    }
    projcurve_surface_destroy(s);
}

static void test_surface_routes(void)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 42);
    const double origin[3] = {0.5, -0.25, 2.0};
    pc_shape_surface shapes[6] = {pc_shape_sphere(origin, 1.25), pc_shape_torus(2.0, 0.5),
                                  pc_shape_cylinder(0.75, 2.0), pc_shape_bumpy(7, 5, 4, 0.3, 0),
                                  pc_shape_bumpy(8, 3, 6, 0.3, 1), pc_shape_plane(4, 2, 3, 5)};
    for (int k = 0; k < 6; ++k) {
        check_three_routes(&shapes[k], &rng, 200, TOL_EXACT);
        check_fd_surface(&shapes[k], &rng, 100);
        pc_shape_surface_free(&shapes[k]);
    }
}

/* Clamped knots over [0, 1] with random interior knots, the first two of
 * them merged into a double knot when there are at least two. */
static void random_knots(pc_test_rng *rng, int degree, size_t n_ctrl, double *knots)
{
    const size_t p = (size_t)degree;
    for (size_t k = 0; k <= p; ++k) {
        knots[k] = 0.0;
        knots[n_ctrl + k] = 1.0;
    }
    /* Sorted increments: knot k = sum of the first increments, normalised. */
    const size_t interior = n_ctrl - p - 1;
    double total = 0.0, inc[64];
    for (size_t k = 0; k <= interior; ++k)
        total += inc[k] = pc_test_rng_uniform(rng, 0.5, 1.5);
    double acc = 0.0;
    for (size_t k = 0; k < interior; ++k) {
        acc += inc[k];
        knots[p + 1 + k] = acc / total;
    }
    if (interior >= 2)
        knots[p + 2] = knots[p + 1];
}

/* Degrees 1..30 in both directions, random nets, non-uniform knots with an
 * interior double knot. */
static pc_shape_surface random_surface(pc_test_rng *rng, int deg_u, int deg_v, size_t n_u,
                                       size_t n_v, int rational)
{
    pc_shape_surface s = {deg_u, deg_v, n_u, n_v, malloc(3 * n_u * n_v * sizeof(double)),
                          rational ? malloc(n_u * n_v * sizeof(double)) : NULL,
                          malloc((n_u + (size_t)deg_u + 1) * sizeof(double)),
                          malloc((n_v + (size_t)deg_v + 1) * sizeof(double))};
    for (size_t i = 0; i < 3 * n_u * n_v; ++i)
        s.ctrl[i] = pc_test_rng_uniform(rng, -1.0, 1.0);
    if (rational)
        for (size_t i = 0; i < n_u * n_v; ++i)
            s.weights[i] = pc_test_rng_uniform(rng, 0.5, 2.0);
    random_knots(rng, deg_u, n_u, s.knots_u);
    random_knots(rng, deg_v, n_v, s.knots_v);
    return s;
}

static void test_degrees(void)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 99);
    /* Fixed pairs over 1..25, the limit degree in one and both directions,
     * then random pairs. */
    enum { FIXED = 15, RANDOM = 8 };
    static const int fixed[FIXED][2] = {{1, 8},   {2, 15}, {3, 22},  {4, 4},  {5, 11},
                                        {6, 18},  {10, 21}, {14, 24}, {18, 2}, {22, 5},
                                        {25, 25}, {25, 1},  {PROJCURVE_MAX_DEGREE, 1},
                                        {2, PROJCURVE_MAX_DEGREE},
                                        {PROJCURVE_MAX_DEGREE, PROJCURVE_MAX_DEGREE}};
    for (int k = 0; k < FIXED + RANDOM; ++k) {
        int p, q;
        if (k < FIXED) {
            p = fixed[k][0];
            q = fixed[k][1];
        } else {
            p = 1 + (int)pc_test_rng_uniform(&rng, 0.0, 24.999);
            q = 1 + (int)pc_test_rng_uniform(&rng, 0.0, 24.999);
        }
        pc_shape_surface s = random_surface(&rng, p, q, (size_t)p + 3, (size_t)q + 2, (p + q) % 2);
        /* Degree 30 basis values are sums of up to 31 * 31 terms and their
         * derivatives differences of such sums: allow rounding to grow with
         * the degree (worst measured: 8e-14 of the scale, on the monomial
         * form at (5, 5); 3e-15 at degree 30). */
        check_three_routes(&s, &rng, 12, TOL_EXACT * (1.0 + (p + q) / 10.0));
        pc_shape_surface_free(&s);
    }
    /* The degree pairs with evaluators of their own (monomial form), the
     * run-time-degree path just above them, polynomial and rational. */
    static const int fast[][2] = {{3, 3}, {2, 2}, {1, 1}, {3, 1}, {1, 3},
                                  {5, 5}, {5, 1}, {2, 3}, {7, 7}, {7, 4}};
    for (size_t k = 0; k < sizeof fast / sizeof *fast; ++k)
        for (int rational = 0; rational <= 1; ++rational) {
            const int p = fast[k][0], q = fast[k][1];
            pc_shape_surface s =
                random_surface(&rng, p, q, (size_t)p + 4, (size_t)q + 3, rational);
            check_three_routes(&s, &rng, 40, TOL_EXACT * (1.0 + (p + q) / 10.0));
            pc_shape_surface_free(&s);
        }
}

/* A Bezier segment of degree p (homogeneous points q[0..p]) on [a, b]: the
 * k-th derivatives of the homogeneous map from the k-th forward differences
 * (p! / (p - k)! / h^k times Delta^k q, degree p - k) by de Casteljau, then
 * the quotient rule. Independent of the library's evaluators. */
static void bezier_segment_ders(const double *q, int p, double a, double b, double t,
                                int n_deriv, double *out)
{
    const double h = b - a, s = (t - a) / h;
    double A[4][4];
    for (int k = 0; k <= n_deriv; ++k) {
        double d[PROJCURVE_MAX_DEGREE + 1][4];
        for (int i = 0; i <= p; ++i)
            for (int m = 0; m < 4; ++m)
                d[i][m] = q[4 * i + m];
        double factor = 1.0;
        for (int level = 1; level <= k && level <= p; ++level) {
            factor *= (double)(p - level + 1) / h;
            for (int i = 0; i + level <= p; ++i)
                for (int m = 0; m < 4; ++m)
                    d[i][m] = d[i + 1][m] - d[i][m];
        }
        const int deg = p - k;
        for (int m = 0; m < 4; ++m)
            A[k][m] = 0.0;
        if (deg < 0)
            continue;
        for (int r = 1; r <= deg; ++r)
            for (int i = 0; i + r <= deg; ++i)
                for (int m = 0; m < 4; ++m)
                    d[i][m] = (1.0 - s) * d[i][m] + s * d[i + 1][m];
        for (int m = 0; m < 4; ++m)
            A[k][m] = factor * d[0][m];
    }
    static const double binom[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
    for (int k = 0; k <= n_deriv; ++k)
        for (int m = 0; m < 3; ++m) {
            double x = A[k][m];
            for (int i = 1; i <= k; ++i)
                x -= binom[k][i] * A[i][3] * out[3 * (k - i) + m];
            out[3 * k + m] = x / A[0][3];
        }
}

/* Curves through three routes: de Boor on the user data (oracle, derivatives
 * from the differentiated control polygon), the library (internal and
 * public), and the Bezier segments of the curve's decomposition evaluated in
 * Bernstein form above; degrees 1..25 and the limit, non-uniform knots with
 * a double knot, rational for even degrees. Each derivative order is held
 * to TOL_EXACT times its scale (the largest norm of that order on the
 * samples, at least the order below), grown with the degree as for
 * surfaces (worst measured: 2e-15 of the scale, at every degree). */
static void test_curve_routes(void)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 17);
    enum { SAMPLES = 30 };
    for (int k_deg = 1; k_deg <= 26; ++k_deg) {
        const int p = k_deg <= 25 ? k_deg : PROJCURVE_MAX_DEGREE;
        const size_t n = (size_t)p + 2 + (size_t)(p % 4);
        pc_shape_curve shape = pc_shape_random_curve(500 + (unsigned long long)p, p, n);
        random_knots(&rng, p, n, shape.knots);
        if (p % 2 == 0) {
            shape.weights = malloc(n * sizeof(double));
            for (size_t i = 0; i < n; ++i)
                shape.weights[i] = pc_test_rng_uniform(&rng, 0.5, 2.0);
        }
        projcurve_curve *c = pc_shape_curve_create(&shape);
        CHECK(c != NULL);
        if (c == NULL) {
            pc_shape_curve_free(&shape);
            continue;
        }
        pc_bezier_curves segs;
        CHECK_OK(pc_bezier_curves_build(NULL, &segs, &c->nurbs));
        double t[SAMPLES], ref[SAMPLES][12], scale[4] = {0, 0, 0, 0};
        for (int k = 0; k < SAMPLES; ++k) {
            /* The ends and a knot are among the samples. */
            t[k] = k == 0 ? 0.0 : k == 1 ? 1.0 : k == 2 ? shape.knots[p + 1]
                                                        : pc_test_rng_uniform(&rng, 0.0, 1.0);
            pc_deboor_curve_ders(&shape, t[k], 3, ref[k]);
            for (int d = 0; d < 4; ++d)
                scale[d] = fmax(scale[d], sqrt(ref[k][3 * d] * ref[k][3 * d] +
                                               ref[k][3 * d + 1] * ref[k][3 * d + 1] +
                                               ref[k][3 * d + 2] * ref[k][3 * d + 2]));
        }
        for (int d = 1; d < 4; ++d)
            scale[d] = fmax(scale[d], scale[d - 1]);
        const double tol = TOL_EXACT * (1.0 + p / 10.0);
        for (int k = 0; k < SAMPLES; ++k) {
            double pub[12], bez[12];
            pc_vec3 lib[4];
            CHECK_OK(projcurve_curve_eval(NULL, c, t[k], 3, pub));
            pc_nurbs_curve_eval(&c->nurbs, t[k], 3, NULL, lib);
            size_t j = 0;
            while (j + 1 < segs.n_segments && t[k] >= segs.breaks[j + 1])
                ++j;
            bezier_segment_ders(segs.cw + 4 * ((size_t)p + 1) * j, p, segs.breaks[j],
                                segs.breaks[j + 1], t[k], 3, bez);
            for (int d = 0; d < 4; ++d) {
                const pc_vec3 r = vec3_load(ref[k] + 3 * d);
                const double e_lib = vec3_dist(lib[d], r), e_pub = vec3_dist(vec3_load(pub + 3 * d), r);
                const double e_bez = vec3_dist(vec3_load(bez + 3 * d), r);
                if (!(e_lib <= tol * scale[d] && e_pub <= tol * scale[d] && e_bez <= tol * scale[d]))
                    pc_test_fail_at(__FILE__, __LINE__,
                                    "degree %d at t = %.17g, order %d: de Boor (%.17g, %.17g, "
                                    "%.17g); errors library %.3g, public %.3g, Bezier %.3g > %.3g",
                                    p, t[k], d, r.x, r.y, r.z, e_lib, e_pub, e_bez, tol * scale[d]);
                ++pc_test_checks;
            }
        }
        pc_bezier_curves_free(&segs);
        projcurve_curve_destroy(c);
        pc_shape_curve_free(&shape);
    }
}

/* Curves: de Boor vs library, derivatives to order 3 vs differences. */
static void test_curves(void)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 5);
    for (int p = 1; p <= 25; p += (p < 5 ? 1 : 5)) {
        pc_shape_curve shape = pc_shape_random_curve((unsigned long long)p, p, (size_t)p + 4);
        projcurve_curve *c = pc_shape_curve_create(&shape);
        CHECK(c != NULL);
        for (int k = 0; k < 50; ++k) {
            const double t = pc_test_rng_uniform(&rng, 0.0, 1.0);
            double ref[3], out[12];
            pc_deboor_curve(&shape, t, ref);
            CHECK_OK(projcurve_curve_eval(NULL, c, t, 3, out));
            CHECK_NEAR(dist3(out, ref), 0.0, TOL_EXACT * (1.0 + p / 5.0));
            const double h = 1e-5;
            if (t < 2 * h || t > 1.0 - 2 * h || p > 8)
                continue;
            double plus[12], minus[12];
            CHECK_OK(projcurve_curve_eval(NULL, c, t + h, 3, plus));
            CHECK_OK(projcurve_curve_eval(NULL, c, t - h, 3, minus));
            double scale = 1.0;
            for (int d = 0; d < 12; ++d)
                scale = fmax(scale, fabs(out[d]));
            for (int d = 0; d < 9; ++d)
                if (p >= 3 || d < 3 * p) /* derivatives of order > p jump at knots */
                    CHECK_NEAR((plus[d] - minus[d]) / (2 * h), out[d + 3], TOL_FD * scale);
        }
        projcurve_curve_destroy(c);
        pc_shape_curve_free(&shape);
    }
}

/* Unclamped knots: uniform knots -p..n (all distinct); periodic: the
 * first p control points repeated at the end. The library clamps them
 * exactly; de Boor evaluates the raw data. */
static void test_unclamped(void)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 11);
    for (int p = 1; p <= 7; ++p) {
        const size_t n = (size_t)p + 5;
        pc_shape_curve shape = pc_shape_random_curve(100 + (unsigned long long)p, p, n);
        for (size_t k = 0; k < n + (size_t)p + 1; ++k)
            shape.knots[k] = (double)k * 0.5 - 1.0 + (double)(k % 3) * 0.1;
        for (size_t i = 0; i < (size_t)p; ++i) /* periodic: wrap the net */
            for (int m = 0; m < 3; ++m)
                shape.ctrl[3 * (n - (size_t)p + i) + (size_t)m] = shape.ctrl[3 * i + (size_t)m];
        shape.weights = malloc(n * sizeof(double));
        for (size_t i = 0; i < n; ++i)
            shape.weights[i] = pc_test_rng_uniform(&rng, 0.5, 2.0);
        projcurve_curve *c = pc_shape_curve_create(&shape);
        CHECK(c != NULL);
        double t0, t1;
        CHECK_OK(projcurve_curve_domain(NULL, c, &t0, &t1));
        CHECK_NEAR(t0, shape.knots[p], 0.0);
        CHECK_NEAR(t1, shape.knots[n], 0.0);
        for (int k = 0; k <= 100; ++k) {
            const double t = t0 + (t1 - t0) * k / 100.0;
            double ref[3], out[3];
            pc_deboor_curve(&shape, t, ref);
            CHECK_OK(projcurve_curve_eval(NULL, c, t, 0, out));
            CHECK_NEAR(dist3(out, ref), 0.0, TOL_EXACT);
        }
        projcurve_curve_destroy(c);
        pc_shape_curve_free(&shape);
    }
    /* Clamped with an extra knot before the start (multiplicity p + 1 at
     * the domain start, first control point outside the domain) and an
     * interior double knot. */
    {
        pc_shape_curve shape = pc_shape_random_curve(7, 3, 7);
        const double knots[11] = {-1, 0, 0, 0, 0, 0.5, 0.5, 1, 1.5, 2, 2.5};
        for (size_t k = 0; k < 11; ++k)
            shape.knots[k] = knots[k];
        projcurve_curve *c = pc_shape_curve_create(&shape);
        CHECK(c != NULL);
        double t0 = 0, t1 = 0;
        CHECK_OK(projcurve_curve_domain(NULL, c, &t0, &t1));
        CHECK(t0 == 0.0 && t1 == 1.0);
        for (int k = 0; k <= 50; ++k) {
            double ref[3], out[3];
            pc_deboor_curve(&shape, k / 50.0, ref);
            CHECK_OK(projcurve_curve_eval(NULL, c, k / 50.0, 0, out));
            CHECK_NEAR(dist3(out, ref), 0.0, TOL_EXACT);
        }
        projcurve_curve_destroy(c);
        pc_shape_curve_free(&shape);
    }
    /* A surface unclamped in both directions. */
    pc_shape_surface s = random_surface(&rng, 3, 2, 7, 6, 1);
    for (size_t k = 0; k < 11; ++k)
        s.knots_u[k] = (double)k;
    for (size_t k = 0; k < 9; ++k)
        s.knots_v[k] = (double)k * 0.25 + (k == 4 ? 0.1 : 0.0);
    projcurve_surface *h = pc_shape_surface_create(&s);
    CHECK(h != NULL);
    if (h != NULL) {
        CHECK_NEAR(h->nurbs.domain[0], 3.0, 0.0);
        CHECK_NEAR(h->nurbs.domain[1], 7.0, 0.0);
        CHECK(pc_knots_are_clamped(h->nurbs.knots_u, h->nurbs.n_u, 3));
        CHECK(pc_knots_are_clamped(h->nurbs.knots_v, h->nurbs.n_v, 2));
        check_three_routes(&s, &rng, 100, TOL_EXACT);
    }
    projcurve_surface_destroy(h);
    pc_shape_surface_free(&s);
}

/* Largest norm of each derivative order over `samples` oracle values of
 * `orders` entries of 3 doubles (entry d has order d), at least the order
 * below: the scale rounding errors are relative to. */
static void order_scales(const double *ref, int samples, int orders, double *scale)
{
    for (int d = 0; d < orders; ++d)
        scale[d] = 0.0;
    for (int k = 0; k < samples; ++k)
        for (int d = 0; d < orders; ++d)
            scale[d] = fmax(scale[d], vec3_norm(vec3_load(ref + 3 * (k * orders + d))));
    for (int d = 1; d < orders; ++d)
        scale[d] = fmax(scale[d], scale[d - 1]);
}

/* Truly periodic input: uniform knots k h + c (no end multiplicity at all)
 * and the first p control points (and weights) repeated at the end, which
 * makes C(t + (n - p) h) = C(t): the domain [knots[p], knots[n]] is one
 * period and the curve closes with C^(p-1) continuity. The library clamps
 * it by knot insertion; its points and derivatives must match de Boor on
 * the raw periodic data, and its derivatives of orders 0..min(p - 1, 3)
 * must agree at the two ends.
 *
 * Tolerance of the k-th derivative: TOL_EXACT times its scale on the
 * samples, plus TOL_CLAMPED M (p / h)^k (M the largest control point). The
 * second term is the conditioning of any clamped form: at a clamped end
 * C' = p (P_1 - P_0) / h, so the rounding of the inserted points (eps M)
 * reaches the k-th derivative magnified by (p / h)^k, 3e5 at degree 25,
 * while a high-degree periodic curve has small derivatives (it averages
 * many control points). Measured: 1.5e-16 M (p / h)^3 at degree 25, well
 * below 1e-12 of the scale at low degrees. */
#define TOL_CLAMPED 1e-14
static double clamped_scale(double m, int p, double h, int k)
{
    return m * pow((double)p / h, (double)k);
}

static void test_periodic(void)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 23);
    static const int degrees[] = {2, 3, 5, 9, 16, 25};
    for (size_t kd = 0; kd < sizeof degrees / sizeof *degrees; ++kd) {
        const int p = degrees[kd];
        const size_t distinct = 6, n = distinct + (size_t)p;
        pc_shape_curve shape = pc_shape_random_curve(700 + (unsigned long long)p, p, n);
        const double h = 0.37, c0 = -1.3;
        for (size_t k = 0; k < n + (size_t)p + 1; ++k)
            shape.knots[k] = c0 + h * (double)k;
        if (kd % 2 == 1) {
            shape.weights = malloc(n * sizeof(double));
            for (size_t i = 0; i < distinct; ++i)
                shape.weights[i] = pc_test_rng_uniform(&rng, 0.5, 2.0);
        }
        for (size_t i = distinct; i < n; ++i) {
            for (int m = 0; m < 3; ++m)
                shape.ctrl[3 * i + (size_t)m] = shape.ctrl[3 * (i - distinct) + (size_t)m];
            if (shape.weights != NULL)
                shape.weights[i] = shape.weights[i - distinct];
        }
        projcurve_curve *c = pc_shape_curve_create(&shape);
        CHECK(c != NULL);
        if (c == NULL) {
            pc_shape_curve_free(&shape);
            continue;
        }
        CHECK(pc_knots_are_clamped(c->nurbs.knots, c->nurbs.n_ctrl, p));
        const double t0 = shape.knots[p], t1 = shape.knots[n];
        enum { SAMPLES = 41 };
        double ref[SAMPLES * 4 * 3], scale[4];
        for (int k = 0; k < SAMPLES; ++k)
            pc_deboor_curve_ders(&shape, t0 + (t1 - t0) * k / (SAMPLES - 1), 3, ref + 12 * k);
        order_scales(ref, SAMPLES, 4, scale);
        double m = 0.0, limit[4];
        for (size_t i = 0; i < 3 * n; ++i)
            m = fmax(m, fabs(shape.ctrl[i]));
        for (int d = 0; d < 4; ++d)
            limit[d] = TOL_EXACT * scale[d] + TOL_CLAMPED * clamped_scale(m, p, h, d);
        for (int k = 0; k < SAMPLES; ++k) {
            const double t = t0 + (t1 - t0) * k / (SAMPLES - 1);
            double out[12];
            CHECK_OK(projcurve_curve_eval(NULL, c, t, 3, out));
            for (int d = 0; d < 4; ++d) {
                const double e = vec3_dist(vec3_load(out + 3 * d), vec3_load(ref + 12 * k + 3 * d));
                if (!(e <= limit[d]))
                    pc_test_fail_at(__FILE__, __LINE__,
                                    "periodic degree %d at t = %.17g, order %d: error %.3g > %.3g",
                                    p, t, d, e, limit[d]);
                ++pc_test_checks;
            }
        }
        double start[12], end[12];
        CHECK_OK(projcurve_curve_eval(NULL, c, t0, 3, start));
        CHECK_OK(projcurve_curve_eval(NULL, c, t1, 3, end));
        for (int d = 0; d <= (p - 1 < 3 ? p - 1 : 3); ++d) {
            const double e = vec3_dist(vec3_load(start + 3 * d), vec3_load(end + 3 * d));
            if (!(e <= 2.0 * limit[d])) /* two evaluations, each within limit */
                pc_test_fail_at(__FILE__, __LINE__,
                                "periodic degree %d: order %d at the ends differs by %.3g > %.3g",
                                p, d, e, 2.0 * limit[d]);
            ++pc_test_checks;
        }
        projcurve_curve_destroy(c);
        pc_shape_curve_free(&shape);
    }

    /* A surface periodic in both directions (degrees 25 and 3, rational):
     * every entry S .. Svv against de Boor on the raw data, and across both
     * seams the derivatives up to order 2 agree. */
    const int p = 25, q = 3;
    const double hu = 0.25, hv = 0.5;
    const size_t du = 5, dv = 4, n_u = du + (size_t)p, n_v = dv + (size_t)q;
    pc_shape_surface sh = random_surface(&rng, p, q, n_u, n_v, 1);
    for (size_t k = 0; k < n_u + (size_t)p + 1; ++k)
        sh.knots_u[k] = hu * (double)k;
    for (size_t k = 0; k < n_v + (size_t)q + 1; ++k)
        sh.knots_v[k] = 2.0 + hv * (double)k;
    for (size_t j = 0; j < n_v; ++j)
        for (size_t i = 0; i < n_u; ++i) {
            const size_t src = (j % dv) * n_u + i % du, dst = j * n_u + i;
            for (int m = 0; m < 3; ++m)
                sh.ctrl[3 * dst + (size_t)m] = sh.ctrl[3 * src + (size_t)m];
            sh.weights[dst] = sh.weights[src];
        }
    projcurve_surface *s = pc_shape_surface_create(&sh);
    CHECK(s != NULL);
    if (s != NULL) {
        const double u0 = sh.knots_u[p], u1 = sh.knots_u[n_u];
        const double v0 = sh.knots_v[q], v1 = sh.knots_v[n_v];
        enum { GRID = 7 };
        double ref[GRID * GRID * 18], scale[6];
        for (int i = 0; i < GRID; ++i)
            for (int j = 0; j < GRID; ++j)
                pc_deboor_surface_ders(&sh, u0 + (u1 - u0) * i / (GRID - 1),
                                       v0 + (v1 - v0) * j / (GRID - 1), ref + 18 * (i * GRID + j));
        order_scales(ref, GRID * GRID, 6, scale); /* entries of order 0, 1, 1, 2, 2, 2 */
        const double order_scale[3] = {scale[0], fmax(scale[1], scale[2]),
                                       fmax(scale[3], fmax(scale[4], scale[5]))};
        double m = 0.0, lim_of[6];
        for (size_t i = 0; i < 3 * n_u * n_v; ++i)
            m = fmax(m, fabs(sh.ctrl[i]));
        static const int ab[6][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};
        for (int d = 0; d < 6; ++d)
            lim_of[d] = TOL_EXACT * order_scale[k_entry_order[d]] +
                        TOL_CLAMPED * clamped_scale(m, p, hu, ab[d][0]) *
                            clamped_scale(1.0, q, hv, ab[d][1]);
        for (int i = 0; i < GRID; ++i)
            for (int j = 0; j < GRID; ++j) {
                const double u = u0 + (u1 - u0) * i / (GRID - 1), v = v0 + (v1 - v0) * j / (GRID - 1);
                double out[18];
                CHECK_OK(projcurve_surface_eval(NULL, s, u, v, 2, out));
                for (int d = 0; d < 6; ++d) {
                    const double e =
                        vec3_dist(vec3_load(out + 3 * d), vec3_load(ref + 18 * (i * GRID + j) + 3 * d));
                    if (!(e <= lim_of[d]))
                        pc_test_fail_at(__FILE__, __LINE__,
                                        "periodic surface at (%.17g, %.17g), entry %d: error %.3g > %.3g",
                                        u, v, d, e, lim_of[d]);
                    ++pc_test_checks;
                }
            }
        for (int k = 0; k < GRID; ++k) {
            const double v = v0 + (v1 - v0) * k / (GRID - 1), u = u0 + (u1 - u0) * k / (GRID - 1);
            double a[18], b[18], c[18], e[18];
            CHECK_OK(projcurve_surface_eval(NULL, s, u0, v, 2, a));
            CHECK_OK(projcurve_surface_eval(NULL, s, u1, v, 2, b));
            CHECK_OK(projcurve_surface_eval(NULL, s, u, v0, 2, c));
            CHECK_OK(projcurve_surface_eval(NULL, s, u, v1, 2, e));
            for (int d = 0; d < 6; ++d) {
                const double lim = 2.0 * lim_of[d]; /* two evaluations */
                const double seam_u = vec3_dist(vec3_load(a + 3 * d), vec3_load(b + 3 * d));
                const double seam_v = vec3_dist(vec3_load(c + 3 * d), vec3_load(e + 3 * d));
                if (!(seam_u <= lim && seam_v <= lim))
                    pc_test_fail_at(__FILE__, __LINE__,
                                    "periodic surface, entry %d: seams differ by %.3g (u) and %.3g (v) > %.3g",
                                    d, seam_u, seam_v, lim);
                ++pc_test_checks;
            }
        }
    }
    projcurve_surface_destroy(s);
    pc_shape_surface_free(&sh);
}

/* Creation copies the user's arrays: a handle evaluates bit for bit the
 * same after the arrays were overwritten with NaN and freed (under ASan a
 * kept pointer would also be a use after free). Clamped and unclamped
 * input (the latter goes through the clamping copy), curves and surfaces,
 * rational. The stores go through a volatile pointer: stores into memory
 * that is freed next are otherwise dead and the compiler drops them. */
static void scribble_and_free(double *a, size_t n)
{
    volatile double *v = a;
    for (size_t i = 0; i < n; ++i)
        v[i] = NAN;
    free(a);
}

static void test_arrays_copied(void)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 31);
    for (int unclamped = 0; unclamped <= 1; ++unclamped) {
        const int p = 3;
        const size_t n = 8;
        pc_shape_curve shape = pc_shape_random_curve(900, p, n);
        shape.weights = malloc(n * sizeof(double));
        for (size_t i = 0; i < n; ++i)
            shape.weights[i] = pc_test_rng_uniform(&rng, 0.5, 2.0);
        if (unclamped)
            for (size_t k = 0; k < n + (size_t)p + 1; ++k)
                shape.knots[k] = 0.1 * (double)k;
        projcurve_curve *c = pc_shape_curve_create(&shape);
        CHECK(c != NULL);
        const double t0 = shape.knots[p], t1 = shape.knots[n];
        double before[21][12], after[21][12];
        for (int k = 0; k <= 20; ++k)
            CHECK_OK(projcurve_curve_eval(NULL, c, t0 + (t1 - t0) * k / 20.0, 3, before[k]));
        scribble_and_free(shape.ctrl, 3 * n);
        scribble_and_free(shape.weights, n);
        scribble_and_free(shape.knots, n + (size_t)p + 1);
        for (int k = 0; k <= 20; ++k)
            CHECK_OK(projcurve_curve_eval(NULL, c, t0 + (t1 - t0) * k / 20.0, 3, after[k]));
        CHECK(memcmp(before, after, sizeof before) == 0);
        double d0 = 0, d1 = 0;
        CHECK_OK(projcurve_curve_domain(NULL, c, &d0, &d1));
        CHECK(d0 == t0 && d1 == t1);
        projcurve_curve_destroy(c);

        pc_shape_surface sh = random_surface(&rng, 3, 2, 6, 5, 1);
        if (unclamped) {
            for (size_t k = 0; k < 10; ++k)
                sh.knots_u[k] = (double)k;
            for (size_t k = 0; k < 8; ++k)
                sh.knots_v[k] = 0.5 * (double)k;
        }
        projcurve_surface *s = pc_shape_surface_create(&sh);
        CHECK(s != NULL);
        double dom[4];
        CHECK_OK(projcurve_surface_domain(NULL, s, dom));
        double sb[11][11][18], sa[11][11][18], q_before[3], q_after[3], uv_before[2], uv_after[2];
        for (int i = 0; i <= 10; ++i)
            for (int j = 0; j <= 10; ++j)
                CHECK_OK(projcurve_surface_eval(NULL, s, dom[0] + (dom[1] - dom[0]) * i / 10.0,
                                                dom[2] + (dom[3] - dom[2]) * j / 10.0, 2, sb[i][j]));
        const double probe[3] = {0.1, -0.2, 1.5};
        double dist_before, dist_after;
        CHECK_OK(projcurve_surface_closest_point(NULL, s, probe, uv_before, q_before, &dist_before));
        scribble_and_free(sh.ctrl, 3 * 30);
        scribble_and_free(sh.weights, 30);
        scribble_and_free(sh.knots_u, 10);
        scribble_and_free(sh.knots_v, 8);
        for (int i = 0; i <= 10; ++i)
            for (int j = 0; j <= 10; ++j)
                CHECK_OK(projcurve_surface_eval(NULL, s, dom[0] + (dom[1] - dom[0]) * i / 10.0,
                                                dom[2] + (dom[3] - dom[2]) * j / 10.0, 2, sa[i][j]));
        CHECK(memcmp(sb, sa, sizeof sb) == 0);
        CHECK_OK(projcurve_surface_closest_point(NULL, s, probe, uv_after, q_after, &dist_after));
        CHECK(dist_before == dist_after && uv_before[0] == uv_after[0] && uv_before[1] == uv_after[1]);
        projcurve_surface_destroy(s);
    }
}

/* A callback curve: projcurve_curve_eval returns the callback's own values
 * at the same t, bit for bit, for orders 0..2 (the library has nothing to
 * compute), at the ends and inside, and writes nothing past the order. */
typedef struct recorded_curve {
    double last_t;
    int calls;
} recorded_curve;

static int wobbly_curve(void *user, double t, double out[9])
{
    recorded_curve *r = user;
    r->last_t = t;
    ++r->calls;
    const double e = exp(0.3 * t);
    out[0] = e * cos(3.0 * t);
    out[1] = t * t * t - t;
    out[2] = sin(t) / (1.0 + t * t);
    out[3] = e * (0.3 * cos(3.0 * t) - 3.0 * sin(3.0 * t));
    out[4] = 3.0 * t * t - 1.0;
    out[5] = cos(t) / (1.0 + t * t) - 2.0 * t * sin(t) / ((1.0 + t * t) * (1.0 + t * t));
    out[6] = e * (-8.91 * cos(3.0 * t) - 1.8 * sin(3.0 * t));
    out[7] = 6.0 * t;
    out[8] = 0.25 * t - 7.0; /* any value: the library passes it through */
    return 0;
}

static void test_callback_curve(void)
{
    recorded_curve rec = {0.0, 0};
    projcurve_curve *c = NULL;
    const double t0 = -1.25, t1 = 2.5;
    CHECK_OK(projcurve_curve_create_callback(NULL, wobbly_curve, &rec, t0, t1, &c));
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 41);
    for (int k = 0; k < 40; ++k) {
        const double t = k == 0 ? t0 : k == 1 ? t1 : pc_test_rng_uniform(&rng, t0, t1);
        double own[9];
        recorded_curve scratch = {0.0, 0};
        wobbly_curve(&scratch, t, own);
        for (int order = 0; order <= 2; ++order) {
            double out[12];
            for (int m = 0; m < 12; ++m)
                out[m] = -999.0;
            const int calls = rec.calls;
            CHECK_OK(projcurve_curve_eval(NULL, c, t, order, out));
            CHECK(rec.calls == calls + 1 && rec.last_t == t);
            if (memcmp(out, own, (size_t)(3 * (order + 1)) * sizeof(double)) != 0)
                pc_test_fail_at(__FILE__, __LINE__,
                                "callback at t = %.17g, order %d: got (%.17g, %.17g, %.17g), "
                                "callback (%.17g, %.17g, %.17g)",
                                t, order, out[3 * order], out[3 * order + 1], out[3 * order + 2],
                                own[3 * order], own[3 * order + 1], own[3 * order + 2]);
            ++pc_test_checks;
            CHECK(out[3 * (order + 1)] == -999.0);
        }
    }
    double d0, d1;
    CHECK_OK(projcurve_curve_domain(NULL, c, &d0, &d1));
    CHECK(d0 == t0 && d1 == t1);
    projcurve_curve_destroy(c);
}

static void test_span_hint(void)
{
    const double knots[] = {0, 0, 0, 1, 2, 2, 3, 4, 4, 4};
    const size_t n = 7;
    for (size_t hint = 0; hint < 12; ++hint) {
        CHECK(pc_knot_span(knots, n, 2, 0.0, hint) == 2);
        CHECK(pc_knot_span(knots, n, 2, 1.5, hint) == 3);
        CHECK(pc_knot_span(knots, n, 2, 2.0, hint) == 5);
        CHECK(pc_knot_span(knots, n, 2, 3.999, hint) == 6);
        CHECK(pc_knot_span(knots, n, 2, 4.0, hint) == 6);
    }
}

/* The O(1) span of near-uniform knot vectors is the searched span, for
 * every knot, its floating-point neighbours and random values; knot
 * vectors whose spans differ by more than a quarter get no scale. */
static void test_span_scaled(void)
{
    enum { N = 19, P = 3 };
    double knots[4][N + P + 1];
    for (int k = 0; k < N + P + 1; ++k) {
        const int i = k < P ? 0 : k > N ? N - P : k - P;
        knots[0][k] = i / 16.0;         /* uniform, exact */
        knots[1][k] = 0.1 * i - 0.35;   /* uniform up to rounding */
        knots[2][k] = i + (i == 5 ? 0.2 : i == 9 ? -0.2 : 0.0); /* knots moved by a fifth */
        knots[3][k] = i + (i == 5 ? 0.3 : 0.0); /* ... by more than a quarter */
    }
    const int uniform[4] = {1, 1, 1, 0};
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 3);
    for (int kv = 0; kv < 4; ++kv) {
        const double *U = knots[kv];
        const double scale = pc_knot_uniform_scale(U, N, P);
        CHECK(uniform[kv] ? scale > 0.0 : scale == 0.0);
        for (int k = 0; k < 3 * (N + P + 1) + 200; ++k) {
            double t;
            if (k < 3 * (N + P + 1))
                t = k % 3 == 0 ? U[k / 3] : nextafter(U[k / 3], k % 3 == 1 ? -INFINITY : INFINITY);
            else
                t = pc_test_rng_uniform(&rng, U[P] - 0.1, U[N] + 0.1);
            const size_t expect = pc_knot_span(U, N, P, t, 0);
            const size_t got = pc_knot_span_scaled(U, N, P, t, 0, scale);
            if (got != expect)
                pc_test_fail_at(__FILE__, __LINE__, "knot vector %d, t = %.17g: span %zu, searched %zu",
                                kv, t, got, expect);
            ++pc_test_checks;
        }
    }
}

int main(void)
{
    test_span_hint();
    test_span_scaled();
    test_circle();
    test_analytic_surfaces();
    test_surface_routes();
    test_degrees();
    test_curves();
    test_curve_routes();
    test_unclamped();
    test_periodic();
    test_arrays_copied();
    test_callback_curve();
    return pc_test_finish("test_nurbs_eval");
}
