/*
 * NURBS evaluation: exact analytic shapes, agreement of three independent
 * routes (de Boor on the user data, basis functions, Bezier patches),
 * derivatives against finite differences, exact clamping of unclamped and
 * periodic knot vectors, degrees 1..25.
 */
#include <math.h>
#include <stdlib.h>

#include "api/handles.h"
#include "check.h"
#include "deboor.h"
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

/* Three routes at random parameters: de Boor (oracle), basis functions
 * (pc_nurbs_surface_eval), the Bezier patch containing (u, v). Derivatives:
 * basis route vs Bezier route, and vs central differences. */
static void check_three_routes(const pc_shape_surface *shape, pc_test_rng *rng, int samples,
                               double tol_points)
{
    projcurve_surface *s = pc_shape_surface_create(shape);
    CHECK(s != NULL);
    if (s == NULL)
        return;
    const double *dom = s->nurbs.domain;
    const double scale = net_scale(shape);
    for (int k = 0; k < samples; ++k) {
        const double u = pc_test_rng_uniform(rng, dom[0], dom[1]);
        const double v = pc_test_rng_uniform(rng, dom[2], dom[3]);
        double ref[3];
        pc_deboor_surface(shape, u, v, ref);
        pc_vec3 basis[6], bez[6];
        size_t hu = 0, hv = 0;
        pc_nurbs_surface_eval(&s->nurbs, u, v, 2, &hu, &hv, basis);
        const pc_bezier_patch *patch = &s->grid.patches[pc_patch_grid_locate(&s->grid, u, v)];
        CHECK(patch->u0 <= u && u <= patch->u1 && patch->v0 <= v && v <= patch->v1);
        pc_bezier_patch_eval(patch, u, v, 2, bez);
        const double b[3] = {basis[0].x, basis[0].y, basis[0].z};
        const double z[3] = {bez[0].x, bez[0].y, bez[0].z};
        CHECK_NEAR(dist3(b, ref), 0.0, tol_points * scale);
        CHECK_NEAR(dist3(z, ref), 0.0, tol_points * scale);
        double dscale = 0.0;
        for (int d = 1; d < 6; ++d)
            dscale = fmax(dscale, vec3_norm(basis[d]));
        for (int d = 1; d < 6; ++d)
            CHECK_NEAR(vec3_dist(basis[d], bez[d]), 0.0, tol_points * 10.0 * (dscale + scale));
        /* Orders 0 and 1 have evaluators of their own: same leading values. */
        for (int order = 0; order < 2; ++order) {
            pc_vec3 low[3];
            pc_nurbs_surface_eval(&s->nurbs, u, v, order, NULL, NULL, low);
            for (int d = 0; d < (order == 0 ? 1 : 3); ++d)
                CHECK_NEAR(vec3_dist(low[d], basis[d]), 0.0, tol_points * (dscale + scale));
        }
    }
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

/* Degrees 1..25 in both directions, random nets, non-uniform knots with an
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
    pc_shape_uniform_knots(deg_u, n_u, s.knots_u);
    pc_shape_uniform_knots(deg_v, n_v, s.knots_v);
    return s;
}

static void test_degrees(void)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 99);
    static const int degrees[][2] = {{1, 8},  {2, 15}, {3, 22}, {4, 4},  {5, 11},  {6, 18},
                                     {10, 21}, {14, 24}, {18, 2}, {22, 5}, {25, 25}, {25, 1}};
    for (size_t k = 0; k < sizeof degrees / sizeof *degrees; ++k) {
        const int p = degrees[k][0], q = degrees[k][1];
        pc_shape_surface s = random_surface(&rng, p, q, (size_t)p + 3, (size_t)q + 2, p % 2);
        /* Degree 25 basis values are sums of up to 26 * 26 terms: allow
         * rounding to grow with the degree. */
        check_three_routes(&s, &rng, 20, TOL_EXACT * (1.0 + (p + q) / 10.0));
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

int main(void)
{
    test_span_hint();
    test_circle();
    test_analytic_surfaces();
    test_surface_routes();
    test_degrees();
    test_curves();
    test_unclamped();
    return pc_test_finish("test_nurbs_eval");
}
