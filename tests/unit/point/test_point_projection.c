/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Point projection: closest points on curves and surfaces against analytic
 * answers (spheres, tori, cylinders, circles) and against brute force
 * (dense sampling plus an independent pattern-search polish) on random
 * bumpy surfaces and random curves; points near edges and corners; points
 * with several equidistant feet; every foot point of a point; minima on
 * the boundary (analytic corner and edge minima of a paraboloid, points out
 * beyond the corners and edges of bumpy surfaces, curves whose closest
 * point is an end).
 */
#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "closest_oracle.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "shapes.h"

/* Closest points are polished by Newton to ~1e-15 relative; distances
 * from two independent methods agree to rounding of |S - p|. */
#define TOL_DIST 1e-10
/* Parameters/points of a minimum are only determined to sqrt(eps) by the
 * distance alone; the library's Newton gets them to ~1e-12, the oracles
 * below to ~1e-9. */
#define TOL_POINT 1e-7

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* The brute-force oracle of tests/support/closest_oracle.h on an 80 x 80
 * grid: fine enough for the bumps of these shapes (a few per unit). */
static double brute_surface(const projcurve_surface *s, const double *p, double uv[2])
{
    return pc_oracle_surface_closest(s, p, 80, uv);
}

static double surface_d2(const projcurve_surface *s, double u, double v, const double *p)
{
    double q[3];
    projcurve_surface_eval(NULL, s, u, v, 0, q);
    return (q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) +
           (q[2] - p[2]) * (q[2] - p[2]);
}

static void check_against_brute(const projcurve_surface *s, const double *p, const char *what)
{
    double uv[2], q[3], dist, buv[2];
    CHECK_OK(projcurve_surface_closest_point(NULL, s, p, uv, q, &dist));
    const double ref = brute_surface(s, p, buv);
    double box[6];
    projcurve_surface_bounds(NULL, s, box);
    const double size = sqrt((box[3] - box[0]) * (box[3] - box[0]) +
                             (box[4] - box[1]) * (box[4] - box[1]) +
                             (box[5] - box[2]) * (box[5] - box[2]));
    if (!(fabs(dist - ref) <= TOL_DIST * size))
        pc_test_fail_at(__FILE__, __LINE__,
                        "%s: p = (%.17g, %.17g, %.17g): library %.17g at (%.9g, %.9g), brute "
                        "force %.17g at (%.9g, %.9g)",
                        what, p[0], p[1], p[2], dist, uv[0], uv[1], ref, buv[0], buv[1]);
    ++pc_test_checks;
    /* The reported point is S(uv) and at the reported distance. */
    double s_uv[3];
    CHECK_OK(projcurve_surface_eval(NULL, s, uv[0], uv[1], 0, s_uv));
    CHECK_NEAR(dist3(s_uv, q), 0.0, 1e-14 * size);
    CHECK_NEAR(dist3(q, p), dist, 1e-14 * size);
}

static void test_sphere_and_torus(void)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 1);
    const double c[3] = {0.5, -1.0, 2.0}, R = 1.5;
    pc_shape_surface sh = pc_shape_sphere(c, R);
    projcurve_surface *s = pc_shape_surface_create(&sh);
    for (int k = 0; k < 40; ++k) {
        double p[3], uv[2], q[3], dist;
        for (int m = 0; m < 3; ++m)
            p[m] = c[m] + pc_test_rng_uniform(&rng, -3.0, 3.0);
        const double rho = dist3(p, c);
        if (rho < 1e-3)
            continue;
        CHECK_OK(projcurve_surface_closest_point(NULL, s, p, uv, q, &dist));
        CHECK_NEAR(dist, fabs(rho - R), TOL_DIST * R);
        double expect[3];
        for (int m = 0; m < 3; ++m)
            expect[m] = c[m] + R * (p[m] - c[m]) / rho;
        CHECK_NEAR(dist3(q, expect), 0.0, TOL_POINT * R);
        /* Foot points: the nearest and the farthest point, unless p lies
         * in the seam half-plane or on the axis (then they repeat). */
        double feet[8];
        size_t count = 0;
        CHECK_OK(projcurve_surface_foot_points(NULL, s, p, 4, feet, &count));
        if (fabs(p[1] - c[1]) > 1e-3 && hypot(p[0] - c[0], p[1] - c[1]) > 1e-3) {
            if (count != 2)
                pc_test_fail_at(__FILE__, __LINE__, "sphere: %zu foot points for p = (%g, %g, %g)",
                                count, p[0], p[1], p[2]);
            ++pc_test_checks;
            if (count >= 2) {
                double f0[3], f1[3], far_pt[3];
                projcurve_surface_eval(NULL, s, feet[0], feet[1], 0, f0);
                projcurve_surface_eval(NULL, s, feet[2], feet[3], 0, f1);
                for (int m = 0; m < 3; ++m)
                    far_pt[m] = c[m] - R * (p[m] - c[m]) / rho;
                CHECK_NEAR(dist3(f0, expect), 0.0, TOL_POINT * R);
                CHECK_NEAR(dist3(f1, far_pt), 0.0, TOL_POINT * R);
            }
        }
    }
    /* The centre: every point is a foot point at distance R. */
    double cuv[2], cdist;
    CHECK_OK(projcurve_surface_closest_point(NULL, s, c, cuv, NULL, &cdist));
    CHECK_NEAR(cdist, R, TOL_DIST * R);
    size_t ccount = 0;
    CHECK_OK(projcurve_surface_foot_points(NULL, s, c, 0, NULL, &ccount));
    CHECK(ccount > 2);
    projcurve_surface_destroy(s);
    pc_shape_surface_free(&sh);

    const double TR = 2.0, tr = 0.6;
    pc_shape_surface th = pc_shape_torus(TR, tr);
    projcurve_surface *t = pc_shape_surface_create(&th);
    for (int k = 0; k < 40; ++k) {
        double p[3], uv[2], q[3], dist;
        p[0] = pc_test_rng_uniform(&rng, -3.5, 3.5);
        p[1] = pc_test_rng_uniform(&rng, -3.5, 3.5);
        p[2] = pc_test_rng_uniform(&rng, -1.5, 1.5);
        const double rho = hypot(p[0], p[1]);
        if (rho < 1e-2)
            continue;
        const double C[3] = {TR * p[0] / rho, TR * p[1] / rho, 0.0};
        const double dc = dist3(p, C);
        if (dc < 1e-2)
            continue;
        CHECK_OK(projcurve_surface_closest_point(NULL, t, p, uv, q, &dist));
        CHECK_NEAR(dist, fabs(dc - tr), TOL_DIST * TR);
        double expect[3];
        for (int m = 0; m < 3; ++m)
            expect[m] = C[m] + tr * (p[m] - C[m]) / dc;
        CHECK_NEAR(dist3(q, expect), 0.0, TOL_POINT * TR);
        /* Four foot points off the seams (y = 0, x > 0 and the outer
         * equator z = 0) and off the axis. */
        if (k % 2 == 1)
            continue; /* foot points of every other point: runtime */
        double feet[16];
        size_t count = 0;
        CHECK_OK(projcurve_surface_foot_points(NULL, t, p, 8, feet, &count));
        if (fabs(p[1]) > 1e-2 && fabs(p[2]) > 1e-2) {
            if (count != 4)
                pc_test_fail_at(__FILE__, __LINE__, "torus: %zu foot points for p = (%g, %g, %g)",
                                count, p[0], p[1], p[2]);
            ++pc_test_checks;
            for (size_t f = 0; f < count && f < 8; ++f) {
                double x[9];
                projcurve_surface_eval(NULL, t, feet[2 * f], feet[2 * f + 1], 1, x);
                const double r[3] = {x[0] - p[0], x[1] - p[1], x[2] - p[2]};
                const double rn = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
                for (int d = 1; d <= 2; ++d) {
                    const double *su = x + 3 * d;
                    const double sn = sqrt(su[0] * su[0] + su[1] * su[1] + su[2] * su[2]);
                    CHECK_NEAR((r[0] * su[0] + r[1] * su[1] + r[2] * su[2]) / (rn * sn), 0.0, 1e-9);
                }
            }
        }
    }
    projcurve_surface_destroy(t);
    pc_shape_surface_free(&th);
}

static void test_equidistant(void)
{
    /* On the axis of a cylinder every point of a circle is nearest. */
    pc_shape_surface sh = pc_shape_cylinder(0.75, 2.0);
    projcurve_surface *s = pc_shape_surface_create(&sh);
    const double axis[3] = {0, 0, 0.8};
    double uv[2], dist;
    CHECK_OK(projcurve_surface_closest_point(NULL, s, axis, uv, NULL, &dist));
    CHECK_NEAR(dist, 0.75, TOL_DIST);
    /* Off the end of the cylinder: the nearest points are on the rim. */
    const double beyond[3] = {0.3, 0.2, 2.5};
    CHECK_OK(projcurve_surface_closest_point(NULL, s, beyond, uv, NULL, &dist));
    CHECK_NEAR(dist, hypot(0.75 - hypot(0.3, 0.2), 0.5), TOL_DIST);
    CHECK_NEAR(uv[1], 1.0, 0.0);
    projcurve_surface_destroy(s);
    pc_shape_surface_free(&sh);

    /* Two equal bumps: a bicubic graph symmetric in x; p on the symmetry
     * plane above the valley has two mirror-image nearest points. */
    pc_shape_surface b = pc_shape_bumpy(5, 6, 6, 0.0, 0);
    for (size_t j = 0; j < b.n_v; ++j)
        for (size_t i = 0; i < b.n_u; ++i) {
            const double x = b.ctrl[3 * (j * b.n_u + i)];
            b.ctrl[3 * (j * b.n_u + i) + 2] = 0.4 * exp(-60.0 * (fabs(x - 0.5) - 0.2) * (fabs(x - 0.5) - 0.2));
        }
    projcurve_surface *bs = pc_shape_surface_create(&b);
    const double p[3] = {0.5, 0.5, 0.9};
    double q[3];
    CHECK_OK(projcurve_surface_closest_point(NULL, bs, p, uv, q, &dist));
    const double mirror[3] = {1.0 - p[0], p[1], p[2]};
    (void)mirror;
    double buv[2];
    const double ref = brute_surface(bs, p, buv);
    CHECK_NEAR(dist, ref, TOL_DIST);
    double feet[40];
    size_t count = 0;
    CHECK_OK(projcurve_surface_foot_points(NULL, bs, p, 20, feet, &count));
    int mirrored = 0; /* the two nearest feet are mirror images */
    if (count >= 2)
        mirrored = fabs(feet[0] + feet[2] - 1.0) < 1e-8 && fabs(feet[1] - feet[3]) < 1e-8;
    CHECK(mirrored);
    projcurve_surface_destroy(bs);
    pc_shape_surface_free(&b);
}

static void test_random_surfaces(void)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 77);
    for (int rational = 0; rational <= 1; ++rational) {
        pc_shape_surface sh = pc_shape_bumpy(40 + (unsigned long long)rational, 5, 4, 0.3, rational);
        projcurve_surface *s = pc_shape_surface_create(&sh);
        for (int k = 0; k < 20; ++k) {
            double p[3] = {pc_test_rng_uniform(&rng, -0.3, 1.3), pc_test_rng_uniform(&rng, -0.3, 1.3),
                           pc_test_rng_uniform(&rng, -0.6, 0.6)};
            check_against_brute(s, p, rational ? "rational bumpy" : "bumpy");
        }
        /* Near the edges and corners, just outside and just inside. */
        const double near_edges[6][3] = {{-0.01, 0.5, 0.1}, {1.001, 0.3, -0.2}, {0.5, -1e-6, 0.0},
                                         {-0.2, -0.2, 0.3}, {1.0, 1.0, 0.5},   {0.999, 0.001, 0.05}};
        for (int k = 0; k < 6; ++k)
            check_against_brute(s, near_edges[k], "near boundary");
        projcurve_surface_destroy(s);
        pc_shape_surface_free(&sh);
    }
    /* Other degrees: biquintic and bilinear nets with random heights. */
    const int degs[3][2] = {{5, 5}, {1, 1}, {2, 7}};
    for (int d = 0; d < 3; ++d) {
        pc_shape_surface sh = pc_shape_plane(degs[d][0], degs[d][1], 3, 2);
        for (size_t i = 0; i < sh.n_u * sh.n_v; ++i)
            sh.ctrl[3 * i + 2] = pc_test_rng_uniform(&rng, -0.5, 0.5);
        projcurve_surface *s = pc_shape_surface_create(&sh);
        for (int k = 0; k < 10; ++k) {
            double p[3] = {pc_test_rng_uniform(&rng, -1.2, 1.2), pc_test_rng_uniform(&rng, -1.2, 2.2),
                           pc_test_rng_uniform(&rng, -0.8, 0.8)};
            check_against_brute(s, p, "degrees");
        }
        projcurve_surface_destroy(s);
        pc_shape_surface_free(&sh);
    }
}

/* Every interior local minimum of the sampled distance, polished by the
 * oracle, must be among the foot points. */
static void test_feet_contain_local_minima(void)
{
    pc_shape_surface sh = pc_shape_bumpy(9, 4, 4, 0.25, 1);
    projcurve_surface *s = pc_shape_surface_create(&sh);
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 8);
    for (int k = 0; k < 5; ++k) {
        const double p[3] = {pc_test_rng_uniform(&rng, 0.2, 0.8), pc_test_rng_uniform(&rng, 0.2, 0.8),
                             pc_test_rng_uniform(&rng, 0.05, 0.3)};
        double feet[200];
        size_t count = 0;
        CHECK_OK(projcurve_surface_foot_points(NULL, s, p, 100, feet, &count));
        const int n = 60;
        static double d2[61][61];
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j)
                d2[i][j] = surface_d2(s, (double)i / n, (double)j / n, p);
        for (int i = 2; i < n - 1; ++i)
            for (int j = 2; j < n - 1; ++j) {
                int is_min = 1;
                for (int a = -1; a <= 1; ++a)
                    for (int b = -1; b <= 1; ++b)
                        if ((a || b) && !(d2[i][j] < d2[i + a][j + b]))
                            is_min = 0;
                if (!is_min)
                    continue;
                /* Polish locally with a pattern search. */
                double uv[2] = {(double)i / n, (double)j / n}, h = 1.0 / n, best = d2[i][j];
                for (int it = 0; it < 300 && h > 1e-14; ++it) {
                    int moved = 0;
                    for (int a = -1; a <= 1; ++a)
                        for (int b = -1; b <= 1; ++b) {
                            const double e = surface_d2(s, uv[0] + a * h, uv[1] + b * h, p);
                            if (e < best) {
                                best = e;
                                uv[0] += a * h;
                                uv[1] += b * h;
                                moved = 1;
                            }
                        }
                    if (!moved)
                        h *= 0.5;
                }
                int found = 0;
                for (size_t f = 0; f < count && f < 100; ++f)
                    found |= fabs(feet[2 * f] - uv[0]) < 1e-6 && fabs(feet[2 * f + 1] - uv[1]) < 1e-6;
                if (!found)
                    pc_test_fail_at(__FILE__, __LINE__, "local minimum (%g, %g) of p = (%g, %g, %g) "
                                    "not among %zu foot points", uv[0], uv[1], p[0], p[1], p[2], count);
                ++pc_test_checks;
            }
    }
    projcurve_surface_destroy(s);
    pc_shape_surface_free(&sh);
}

/* ---- Curves ----------------------------------------------------------- */

static double brute_curve(const projcurve_curve *c, const double *p, double *t_out)
{
    double t0, t1;
    projcurve_curve_domain(NULL, c, &t0, &t1);
    const int n = 2000;
    double best = INFINITY, bt = t0;
    for (int i = 0; i <= n; ++i) {
        double q[3];
        const double t = t0 + (t1 - t0) * i / n;
        projcurve_curve_eval(NULL, c, t, 0, q);
        const double d = dist3(q, p);
        if (d < best) {
            best = d;
            bt = t;
        }
    }
    /* Golden-section polish on the bracket around the best sample. */
    double a = fmax(t0, bt - (t1 - t0) / n), b = fmin(t1, bt + (t1 - t0) / n);
    for (int it = 0; it < 200; ++it) {
        const double m1 = b - 0.618033988749895 * (b - a), m2 = a + 0.618033988749895 * (b - a);
        double q1[3], q2[3];
        projcurve_curve_eval(NULL, c, m1, 0, q1);
        projcurve_curve_eval(NULL, c, m2, 0, q2);
        if (dist3(q1, p) < dist3(q2, p))
            b = m2;
        else
            a = m1;
    }
    double q[3];
    projcurve_curve_eval(NULL, c, 0.5 * (a + b), 0, q);
    *t_out = 0.5 * (a + b);
    return fmin(best, dist3(q, p));
}

typedef struct helix {
    double r, pitch;
    int fail_after; /* callback fails past this many calls (< 0: never) */
    int calls;
} helix;

static int helix_fn(void *user, double t, double out[9])
{
    helix *h = user;
    if (h->fail_after >= 0 && ++h->calls > h->fail_after)
        return 1;
    out[0] = h->r * cos(t);
    out[1] = h->r * sin(t);
    out[2] = h->pitch * t;
    out[3] = -h->r * sin(t);
    out[4] = h->r * cos(t);
    out[5] = h->pitch;
    out[6] = -h->r * cos(t);
    out[7] = -h->r * sin(t);
    out[8] = 0.0;
    return 0;
}

static void test_curves(void)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 12);
    const double c[3] = {1, 2, 3}, R = 2.0;
    pc_shape_curve circ = pc_shape_circle(c, R);
    projcurve_curve *cc = pc_shape_curve_create(&circ);
    for (int k = 0; k < 100; ++k) {
        const double p[3] = {c[0] + pc_test_rng_uniform(&rng, -4, 4), c[1] + pc_test_rng_uniform(&rng, -4, 4),
                             c[2] + pc_test_rng_uniform(&rng, -1, 1)};
        const double rho = hypot(p[0] - c[0], p[1] - c[1]);
        double t, q[3], dist;
        CHECK_OK(projcurve_curve_closest_point(NULL, cc, p, &t, q, &dist));
        CHECK_NEAR(dist, hypot(rho - R, p[2] - c[2]), TOL_DIST * R);
    }
    /* On the axis: the whole circle is equidistant. */
    const double axis[3] = {1, 2, 4};
    double t, dist;
    CHECK_OK(projcurve_curve_closest_point(NULL, cc, axis, &t, NULL, &dist));
    CHECK_NEAR(dist, sqrt(R * R + 1.0), TOL_DIST);
    projcurve_curve_destroy(cc);
    pc_shape_curve_free(&circ);

    for (int deg = 1; deg <= 9; deg += 2) {
        pc_shape_curve rc = pc_shape_random_curve(300 + (unsigned long long)deg, deg, (size_t)deg + 8);
        projcurve_curve *c2 = pc_shape_curve_create(&rc);
        for (int k = 0; k < 20; ++k) {
            const double p[3] = {pc_test_rng_uniform(&rng, -1.5, 1.5), pc_test_rng_uniform(&rng, -1.5, 1.5),
                                 pc_test_rng_uniform(&rng, -1.5, 1.5)};
            double tt, q[3], d, bt;
            CHECK_OK(projcurve_curve_closest_point(NULL, c2, p, &tt, q, &d));
            const double ref = brute_curve(c2, p, &bt);
            if (!(fabs(d - ref) <= TOL_DIST * 4.0))
                pc_test_fail_at(__FILE__, __LINE__, "degree %d, p = (%.17g, %.17g, %.17g): library %.17g at t = %.9g, "
                                "brute %.17g at %.9g", deg, p[0], p[1], p[2], d, tt, ref, bt);
            ++pc_test_checks;
        }
        projcurve_curve_destroy(c2);
        pc_shape_curve_free(&rc);
    }

    helix h = {1.0, 0.2, -1, 0};
    projcurve_curve *hc = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, helix_fn, &h, 0.0, 12.0, &hc));
    for (int k = 0; k < 20; ++k) {
        const double p[3] = {pc_test_rng_uniform(&rng, -2, 2), pc_test_rng_uniform(&rng, -2, 2),
                             pc_test_rng_uniform(&rng, -0.5, 3.0)};
        double tt, d, bt;
        CHECK_OK(projcurve_curve_closest_point(NULL, hc, p, &tt, NULL, &d));
        const double ref = brute_curve(hc, p, &bt);
        CHECK_NEAR(d, ref, TOL_DIST * 4.0);
    }
    projcurve_curve_destroy(hc);
}

/* ---- Minima on the boundary ------------------------------------------- */

/* The paraboloid S(u, v) = (u, v, u^2 + v^2) over [0, 1]^2, exact as a
 * biquadratic Bezier patch: x and y at the Greville abscissae 0, 1/2, 1, z
 * from the Bernstein coefficients (0, 0, 1) of u^2. */
static projcurve_surface *paraboloid(void)
{
    double ctrl[27], knots[6] = {0, 0, 0, 1, 1, 1};
    static const double g[3] = {0.0, 0.5, 1.0}, sq[3] = {0.0, 0.0, 1.0};
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) {
            double *pt = ctrl + 3 * (3 * j + i);
            pt[0] = g[i];
            pt[1] = g[j];
            pt[2] = sq[i] + sq[j];
        }
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(NULL, 2, 2, 3, 3, ctrl, NULL, knots, knots, &s));
    return s;
}

/* Library against brute force, and where the brute-force minimum lies on
 * the boundary (the oracle clamps to it exactly) the library's parameter
 * must lie on the same edge: its active set puts it there exactly. */
static void check_boundary_against_brute(const projcurve_surface *s, const double *p, const char *what)
{
    check_against_brute(s, p, what);
    double uv[2], buv[2], dist, dom[4];
    CHECK_OK(projcurve_surface_closest_point(NULL, s, p, uv, NULL, &dist));
    brute_surface(s, p, buv);
    projcurve_surface_domain(NULL, s, dom);
    for (int c = 0; c < 2; ++c)
        for (int side = 0; side < 2; ++side) {
            const double bound = dom[2 * c + side];
            if (buv[c] == bound && uv[c] != bound)
                pc_test_fail_at(__FILE__, __LINE__,
                                "%s: p = (%.17g, %.17g, %.17g): brute force on the edge %s = %g, "
                                "library at %.17g",
                                what, p[0], p[1], p[2], c == 0 ? "u" : "v", bound, uv[c]);
            ++pc_test_checks;
        }
}

static void test_surface_boundary_minima(void)
{
    projcurve_surface *s = paraboloid();
    /* p = (1.5, 1.5, 3): d|S - p|^2/du = 2 (u - 1.5) + 4 u (u^2 + v^2 - 3) < 0
     * on the whole square, and likewise in v, so the minimum is the corner
     * (1, 1) at distance sqrt(0.25 + 0.25 + 1). */
    const double corner_p[3] = {1.5, 1.5, 3.0};
    double uv[2], q[3], dist;
    CHECK_OK(projcurve_surface_closest_point(NULL, s, corner_p, uv, q, &dist));
    CHECK(uv[0] == 1.0 && uv[1] == 1.0);
    CHECK_NEAR(dist, sqrt(1.5), 1e-15);
    check_boundary_against_brute(s, corner_p, "paraboloid corner");
    /* p = (0.5, 1.6, 1): on the edge v = 1 the distance is stationary where
     * 4 u^3 + 2 u - 1 = 0 (u* = 0.3855...), and there d/dv < 0 (it pushes out
     * of the square): the minimum lies inside the edge v = 1. u* by Newton on
     * the cubic (increasing, convex for u > 0: converges from 1). */
    const double edge_p[3] = {0.5, 1.6, 1.0};
    double root = 1.0;
    for (int it = 0; it < 60; ++it)
        root -= (4 * root * root * root + 2 * root - 1) / (12 * root * root + 2);
    CHECK_OK(projcurve_surface_closest_point(NULL, s, edge_p, uv, q, &dist));
    CHECK(uv[1] == 1.0);
    /* u is fixed by a 1D minimum with f'' = 12 u*^2 + 2 ~ 3.8: the distance
     * pins it to ~sqrt(eps), Newton on the gradient to ~1e-15. */
    CHECK_NEAR(uv[0], root, 1e-12);
    const double expect = sqrt((root - 0.5) * (root - 0.5) + 0.36 + root * root * root * root);
    CHECK_NEAR(dist, expect, 1e-15);
    check_boundary_against_brute(s, edge_p, "paraboloid edge");
    projcurve_surface_destroy(s);

    /* Bumpy surfaces, polynomial and rational: points out beyond each corner
     * (diagonally, above and below) and beyond the middle of each edge. */
    for (int rational = 0; rational <= 1; ++rational) {
        pc_shape_surface sh = pc_shape_bumpy(60 + (unsigned long long)rational, 4, 5, 0.3, rational);
        projcurve_surface *b = pc_shape_surface_create(&sh);
        for (int corner = 0; corner < 4; ++corner) {
            const double cx = corner & 1, cy = corner >> 1;
            for (int k = 0; k < 3; ++k) {
                const double out = 0.1 + 0.3 * k, z = 0.5 * (k - 1);
                const double p[3] = {cx + (cx > 0 ? out : -out), cy + (cy > 0 ? out : -out), z};
                check_boundary_against_brute(b, p, rational ? "rational bumpy corner" : "bumpy corner");
            }
        }
        for (int edge = 0; edge < 4; ++edge)
            for (int k = 0; k < 3; ++k) {
                const double out = 0.05 + 0.4 * k, along = 0.3 + 0.2 * k, z = 0.4 - 0.4 * k;
                double p[3] = {along, along, z};
                p[edge / 2] = edge % 2 ? 1.0 + out : -out;
                check_boundary_against_brute(b, p, rational ? "rational bumpy edge" : "bumpy edge");
            }
        projcurve_surface_destroy(b);
        pc_shape_surface_free(&sh);
    }
}

/* Curves whose closest point is an end, on the parabola C(t) = (t, t^2, 0):
 * - over [0, 1] (one quadratic Bezier segment, knot 0.5 inserted: points
 *   (0,0), (1/4,0), (3/4,1/2), (1,1)) from p = (1.5, 1.5, 0), where
 *   d|C - p|^2/dt / 2 = 2t^3 - 2t - 1.5 < 0 on [0, 1]: the end t = 1 at
 *   distance sqrt(0.5); from p = (-1, -0.5, 0.3), where it is
 *   2t^3 + 2t + 1 > 0: the start t = 0 at distance sqrt(1.34);
 * - over [-1, 1] (points (-1,1), (-1/2,0), (1/2,0), (1,1), knot 0) from
 *   p = (+-0.1, 2, 0): the derivative 4t^3 - 6t -+ 0.2 has one zero inside
 *   (a maximum) and both ends are local minima, at squared distances 1.81
 *   and 2.21: the nearer end wins. */
static void test_curve_end_minima(void)
{
    static const double unit_ctrl[12] = {0, 0, 0, 0.25, 0, 0, 0.75, 0.5, 0, 1, 1, 0};
    static const double unit_knots[7] = {0, 0, 0, 0.5, 1, 1, 1};
    static const double wide_ctrl[12] = {-1, 1, 0, -0.5, 0, 0, 0.5, 0, 0, 1, 1, 0};
    static const double wide_knots[7] = {-1, -1, -1, 0, 1, 1, 1};
    static const struct {
        const double *ctrl, *knots;
        double p[3], t, dist;
    } cases[] = {
        {unit_ctrl, unit_knots, {1.5, 1.5, 0.0}, 1.0, 0.70710678118654752},
        {unit_ctrl, unit_knots, {-1.0, -0.5, 0.3}, 0.0, 1.1575836902790226},
        {wide_ctrl, wide_knots, {0.1, 2.0, 0.0}, 1.0, 1.3453624047073711},
        {wide_ctrl, wide_knots, {-0.1, 2.0, 0.0}, -1.0, 1.3453624047073711},
    };
    for (size_t k = 0; k < sizeof cases / sizeof *cases; ++k) {
        projcurve_curve *c = NULL;
        CHECK_OK(projcurve_curve_create_nurbs(NULL, 2, 4, cases[k].ctrl, NULL, cases[k].knots, &c));
        double t, q[3], dist;
        CHECK_OK(projcurve_curve_closest_point(NULL, c, cases[k].p, &t, q, &dist));
        /* An end minimum with a nonzero slope: the end itself, exactly. */
        if (!(t == cases[k].t && fabs(dist - cases[k].dist) <= 1e-15))
            pc_test_fail_at(__FILE__, __LINE__,
                            "case %zu, p = (%g, %g, %g): t = %.17g at distance %.17g, expected "
                            "the end %g at %.17g",
                            k, cases[k].p[0], cases[k].p[1], cases[k].p[2], t, dist, cases[k].t,
                            cases[k].dist);
        ++pc_test_checks;
        const double at_end[3] = {cases[k].t, cases[k].t * cases[k].t, 0.0};
        CHECK_NEAR(dist3(q, at_end), 0.0, 1e-15);
        double bt;
        CHECK_NEAR(brute_curve(c, cases[k].p, &bt), cases[k].dist, 1e-15);
        projcurve_curve_destroy(c);
    }
}

int main(void)
{
    test_sphere_and_torus();
    test_equidistant();
    test_random_surfaces();
    test_feet_contain_local_minima();
    test_curves();
    test_surface_boundary_minima();
    test_curve_end_minima();
    return pc_test_finish("test_point_projection");
}
