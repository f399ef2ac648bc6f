/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Which hits are kept (hits/, PROJCURVE_OPT_HITS and _MAX_DISTANCE):
 * - two walls, front z = 1 and back z = -1 of one U-shaped bilinear
 *   surface, seen along -z: all hits give two branches, the nearest only
 *   the front one, whole;
 * - the same walls orthogonally from a line between them: the nearest foot
 *   switches walls at the analytic t = 1/2 (equidistant);
 * - two crossing sheets z = -x and z = x / 2 (one self-intersecting
 *   surface) along -z: the nearest switches sheets at x = 0, t = 1/2
 *   exactly, located to 1e-10 of the model size (the distances differ by
 *   2.4 (t - 1/2));
 * - a bump on a plane seen at 45 degrees: the nearest projection against
 *   a brute-force ray march of the surface (first sign change of the
 *   height above it along the ray), and every cut at the birth or the end
 *   of a nearer branch of the all-hits result;
 * - a tilted plane z = x / 2 with MAX_DISTANCE: cut where the distance is
 *   D, analytically t = 1/2 along -z, and orthogonally where
 *   (2.4 - 0.8 t) / sqrt(1.25) = D.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "shapes.h"

/* Cuts located to 1e-10 of the model size in distance; the distances
 * change at >= 0.8 per unit t here, so t within 1e-9. */
#define CUT_T_TOL 1e-9

static projcurve_surface *bilinear_u(const double (*xz)[2], size_t n)
{
    /* degree 1 in u through the (x, z) profile, y in [-1, 1] along v */
    double ctrl[3 * 2 * 8], knots_u[10], knots_v[4] = {0, 0, 1, 1};
    for (size_t j = 0; j < 2; ++j)
        for (size_t i = 0; i < n; ++i) {
            double *c = ctrl + 3 * (j * n + i);
            c[0] = xz[i][0];
            c[1] = j == 0 ? -1.0 : 1.0;
            c[2] = xz[i][1];
        }
    knots_u[0] = 0;
    for (size_t i = 0; i < n; ++i)
        knots_u[i + 1] = (double)i;
    knots_u[n + 1] = (double)(n - 1);
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(NULL, 1, 1, n, 2, ctrl, NULL, knots_u, knots_v, &s));
    return s;
}

static projcurve_curve *line(const double p0[3], const double p1[3])
{
    const double ctrl[6] = {p0[0], p0[1], p0[2], p1[0], p1[1], p1[2]}, knots[4] = {0, 0, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 1, 2, ctrl, NULL, knots, &c));
    return c;
}

static projcurve_options *options(long long hits, double max_distance)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_HITS, hits));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_MAX_DISTANCE, max_distance));
    return o;
}

static projcurve_result *directional(const projcurve_surface *s, const projcurve_curve *c,
                                     const double dir[3], long long hits, double max_distance)
{
    projcurve_options *o = options(hits, max_distance);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c, dir, o, &r));
    projcurve_options_destroy(o);
    return r;
}

static void info(const projcurve_result *r, size_t b, double range[2],
                 projcurve_branch_start *start, projcurve_branch_end *end)
{
    size_t n_pieces = 0;
    CHECK_OK(projcurve_result_branch_info(NULL, r, b, range, start, end, NULL, &n_pieces));
    CHECK(n_pieces > 0); /* the kept ranges are composed */
}

/* The z of every vertex of branch b. */
static void check_branch_z(const projcurve_surface *s, const projcurve_result *r, size_t b,
                           double z)
{
    size_t n = 0;
    CHECK_OK(projcurve_result_branch_points(NULL, r, b, 0, NULL, &n));
    double *pts = malloc(3 * n * sizeof *pts);
    CHECK_OK(projcurve_result_branch_points(NULL, r, b, n, pts, &n));
    for (size_t i = 0; i < n; ++i) {
        double x[3];
        CHECK_OK(projcurve_surface_eval(NULL, s, pts[3 * i + 1], pts[3 * i + 2], 0, x));
        CHECK_NEAR(x[2], z, 1e-9);
    }
    free(pts);
}

static void test_two_walls(void)
{
    const double xz[4][2] = {{-1, 1}, {1, 1}, {1, -1}, {-1, -1}};
    projcurve_surface *s = bilinear_u(xz, 4);
    const double p0[3] = {-0.5, 0.2, 2}, p1[3] = {0.5, 0.2, 2}, dir[3] = {0, 0, -1};
    projcurve_curve *c = line(p0, p1);
    projcurve_result *all = directional(s, c, dir, PROJCURVE_HITS_ALL, 0.0);
    projcurve_result *near = directional(s, c, dir, PROJCURVE_HITS_NEAREST, 0.0);
    CHECK(projcurve_result_branch_count(all) == 2);
    CHECK(projcurve_result_branch_count(near) == 1);
    double range[2];
    projcurve_branch_start st;
    projcurve_branch_end en;
    info(near, 0, range, &st, &en);
    CHECK(st == PROJCURVE_START_CURVE_START && en == PROJCURVE_END_CURVE_END);
    CHECK_NEAR(range[0], 0.0, 0.0);
    CHECK_NEAR(range[1], 1.0, 0.0);
    check_branch_z(s, near, 0, 1.0);
    projcurve_result_destroy(all);
    projcurve_result_destroy(near);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

/* Orthogonally between the two walls: the nearest foot point switches
 * from the front wall to the back one where P(t) is equidistant, z = 0,
 * t = 1/2 (the side wall x = 1 is 1.5 away). */
static void test_walls_orthogonal(void)
{
    const double xz[4][2] = {{-1, 1}, {1, 1}, {1, -1}, {-1, -1}};
    projcurve_surface *s = bilinear_u(xz, 4);
    const double p0[3] = {-0.5, 0.2, 0.8}, p1[3] = {-0.5, 0.2, -0.8};
    projcurve_curve *c = line(p0, p1);
    projcurve_options *o = options(PROJCURVE_HITS_NEAREST, 0.0);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_orthogonal(NULL, s, c, o, &r));
    CHECK(projcurve_result_branch_count(r) == 2);
    if (projcurve_result_branch_count(r) == 2) {
        double r0[2], r1[2];
        projcurve_branch_start s0, s1;
        projcurve_branch_end e0, e1;
        info(r, 0, r0, &s0, &e0);
        info(r, 1, r1, &s1, &e1);
        const int front_first = r0[0] < r1[0];
        const double *a = front_first ? r0 : r1, *b = front_first ? r1 : r0;
        CHECK((front_first ? e0 : e1) == PROJCURVE_END_OCCLUDED);
        CHECK((front_first ? s1 : s0) == PROJCURVE_START_VISIBLE);
        CHECK_NEAR(a[0], 0.0, 0.0);
        CHECK_NEAR(a[1], 0.5, CUT_T_TOL);
        CHECK_NEAR(b[0], 0.5, CUT_T_TOL);
        CHECK_NEAR(b[1], 1.0, 0.0);
        check_branch_z(s, r, front_first ? 0 : 1, 1.0);
        check_branch_z(s, r, front_first ? 1 : 0, -1.0);
    }
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

static void test_crossing_sheets(void)
{
    /* z = -x from x = -1 to 1, a wall along the ray at x = 1 (no hit), then
     * z = x / 2 back to x = -1 */
    const double xz[4][2] = {{-1, 1}, {1, -1}, {1, 0.5}, {-1, -0.5}};
    projcurve_surface *s = bilinear_u(xz, 4);
    const double p0[3] = {-0.8, 0.2, 2}, p1[3] = {0.8, 0.2, 2}, dir[3] = {0, 0, -1};
    projcurve_curve *c = line(p0, p1);
    projcurve_result *near = directional(s, c, dir, PROJCURVE_HITS_NEAREST, 0.0);
    CHECK(projcurve_result_branch_count(near) == 2);
    if (projcurve_result_branch_count(near) == 2) {
        double r0[2], r1[2];
        projcurve_branch_start s0, s1;
        projcurve_branch_end e0, e1;
        info(near, 0, r0, &s0, &e0);
        info(near, 1, r1, &s1, &e1);
        /* branch 0 on the first sheet (traced first), kept up to t = 1/2 */
        CHECK(e0 == PROJCURVE_END_OCCLUDED && s1 == PROJCURVE_START_VISIBLE);
        CHECK_NEAR(r0[0], 0.0, 0.0);
        CHECK_NEAR(r0[1], 0.5, CUT_T_TOL);
        CHECK_NEAR(r1[0], 0.5, CUT_T_TOL);
        CHECK_NEAR(r1[1], 1.0, 0.0);
    }
    projcurve_result_destroy(near);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

static void test_max_distance(void)
{
    const double xz[2][2] = {{-1, -0.5}, {1, 0.5}};
    projcurve_surface *s = bilinear_u(xz, 2);
    const double p0[3] = {-0.8, 0.2, 2}, p1[3] = {0.8, 0.2, 2}, dir[3] = {0, 0, -1};
    projcurve_curve *c = line(p0, p1);
    /* along -z the distance is 2 - x / 2 = 2.4 - 0.8 t: D = 2 at t = 1/2 */
    projcurve_result *r = directional(s, c, dir, PROJCURVE_HITS_ALL, 2.0);
    CHECK(projcurve_result_branch_count(r) == 1);
    double range[2];
    projcurve_branch_start st;
    projcurve_branch_end en;
    info(r, 0, range, &st, &en);
    CHECK(st == PROJCURVE_START_MAX_DISTANCE && en == PROJCURVE_END_CURVE_END);
    CHECK_NEAR(range[0], 0.5, CUT_T_TOL);
    projcurve_curve *cc = NULL;
    CHECK_OK(projcurve_result_branch_compact_curve(NULL, r, 0, &cc));
    projcurve_curve_destroy(cc);
    projcurve_result_destroy(r);
    /* orthogonally: (2.4 - 0.8 t) / sqrt(1.25) = D */
    projcurve_options *o = options(PROJCURVE_HITS_NEAREST, 1.8);
    CHECK_OK(projcurve_project_orthogonal(NULL, s, c, o, &r));
    CHECK(projcurve_result_branch_count(r) == 1);
    info(r, 0, range, &st, &en);
    CHECK(st == PROJCURVE_START_MAX_DISTANCE);
    CHECK_NEAR(range[0], (2.4 - 1.8 * sqrt(1.25)) / 0.8, CUT_T_TOL);
    projcurve_result_destroy(r);
    /* nothing within D: no branch */
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_MAX_DISTANCE, 1.0));
    CHECK_OK(projcurve_project_orthogonal(NULL, s, c, o, &r));
    CHECK(projcurve_result_branch_count(r) == 0);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

/* ---- the bump ---- */

#define BUMP_N 15
#define BUMP_H 0.8

static projcurve_surface *bump_surface(void)
{
    static double ctrl[3 * BUMP_N * BUMP_N];
    double knots[BUMP_N + 4];
    pc_shape_uniform_knots(3, BUMP_N, knots);
    for (size_t j = 0; j < BUMP_N; ++j)
        for (size_t i = 0; i < BUMP_N; ++i) {
            double *c = ctrl + 3 * (j * BUMP_N + i);
            /* Greville abscissae: x = -1 + 2 u exactly (linear precision) */
            c[0] = -1.0 + 2.0 * (knots[i + 1] + knots[i + 2] + knots[i + 3]) / 3.0;
            c[1] = -1.0 + 2.0 * (knots[j + 1] + knots[j + 2] + knots[j + 3]) / 3.0;
            c[2] = (i >= 6 && i <= 8 && j >= 6 && j <= 8) ? BUMP_H : 0.0;
        }
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(NULL, 3, 3, BUMP_N, BUMP_N, ctrl, NULL, knots, knots,
                                            &s));
    return s;
}

/* The nearest hit of the ray from p along d (unit, d_y = 0) on the graph
 * z = f(x, y): the first sign change of the height above S along the ray,
 * sampled every 1e-3 and bisected. 0 when the ray misses. */
static int march(const projcurve_surface *s, const double p[3], const double d[3], double hit[3])
{
    double prev = 0.0;
    for (int k = 0; k <= 6000; ++k) {
        const double lam = 1e-3 * k, x = p[0] + lam * d[0], z = p[2] + lam * d[2];
        if (x < -1.0 || x > 1.0) {
            if (x > 1.0)
                return 0;
            continue;
        }
        double q[3];
        CHECK_OK(projcurve_surface_eval(NULL, s, 0.5 * (x + 1.0), 0.5 * (p[1] + 1.0), 0, q));
        const double h = z - q[2];
        if (h <= 0.0 && k > 0 && prev > 0.0) {
            double lo = lam - 1e-3, hi = lam;
            for (int it = 0; it < 60; ++it) {
                const double mid = 0.5 * (lo + hi), xm = p[0] + mid * d[0];
                CHECK_OK(projcurve_surface_eval(NULL, s, 0.5 * (xm + 1.0), 0.5 * (p[1] + 1.0),
                                                0, q));
                if (p[2] + mid * d[2] - q[2] > 0.0)
                    lo = mid;
                else
                    hi = mid;
            }
            for (int i = 0; i < 3; ++i)
                hit[i] = p[i] + hi * d[i];
            return 1;
        }
        prev = h;
    }
    return 0;
}

/* reversed 0: the rays sweep over the bump, whose front hides the plane
 * until their fold on its back (START_VISIBLE of the plane there);
 * reversed 1: the other way, the bump's front born at a fold hides the
 * plane (END_OCCLUDED there) */
static void test_bump(int reversed)
{
    projcurve_surface *s = bump_surface();
    const double ends[2][3] = {{-2.4, 0.1, 1.5}, {-0.6, 0.1, 1.5}};
    const double *p0 = ends[reversed], *p1 = ends[1 - reversed];
    const double dir[3] = {sqrt(0.5), 0, -sqrt(0.5)};
    projcurve_curve *c = line(p0, p1);
    projcurve_result *all = directional(s, c, dir, PROJCURVE_HITS_ALL, 0.0);
    projcurve_result *near = directional(s, c, dir, PROJCURVE_HITS_NEAREST, 0.0);
    const size_t na = projcurve_result_branch_count(all), nn = projcurve_result_branch_count(near);
    CHECK(na == 3); /* the front hit, the pair born at the fold on the back */
    CHECK(nn == 2);
    /* every cut at an end of a branch of the all-hits result */
    int cuts = 0, expected_cuts = 0;
    for (size_t b = 0; b < nn; ++b) {
        double range[2];
        projcurve_branch_start st;
        projcurve_branch_end en;
        info(near, b, range, &st, &en);
        for (int side = 0; side < 2; ++side) {
            const int cut = side == 0 ? st == PROJCURVE_START_VISIBLE : en == PROJCURVE_END_OCCLUDED;
            if (!cut)
                continue;
            ++cuts;
            expected_cuts += side == (reversed ? 1 : 0);
            double best = INFINITY;
            for (size_t a = 0; a < na; ++a) {
                double ra[2];
                CHECK_OK(projcurve_result_branch_info(NULL, all, a, ra, NULL, NULL, NULL, NULL));
                best = fmin(best, fmin(fabs(ra[0] - range[side]), fabs(ra[1] - range[side])));
            }
            CHECK(best <= CUT_T_TOL);
        }
    }
    CHECK(cuts >= 1 && expected_cuts >= 1);
    /* against the march, away from the cuts (a ray grazing the bump there
     * is not resolved by the march's 1e-3 samples) */
    double eps_d = 0.0;
    CHECK_OK(projcurve_result_stat(NULL, near, PROJCURVE_STAT_TOL_DISTANCE, &eps_d));
    int compared = 0;
    for (int k = 0; k <= 400; ++k) {
        const double t = k / 400.0;
        double p[3], hit[3] = {0, 0, 0};
        CHECK_OK(projcurve_curve_eval(NULL, c, t, 0, p));
        const int hits = march(s, p, dir, hit);
        size_t alive = 0, which = 0, near_cut = 0;
        for (size_t b = 0; b < nn; ++b) {
            double range[2];
            CHECK_OK(projcurve_result_branch_info(NULL, near, b, range, NULL, NULL, NULL, NULL));
            if (fabs(t - range[0]) < 1e-2 || fabs(t - range[1]) < 1e-2)
                near_cut = 1;
            if (t >= range[0] && t <= range[1])
                ++alive, which = b;
        }
        if (near_cut)
            continue;
        CHECK(alive == (size_t)hits);
        if (alive == 1 && hits) {
            projcurve_curve *cc = NULL;
            CHECK_OK(projcurve_result_branch_compact_curve(NULL, near, which, &cc));
            double x[3];
            CHECK_OK(projcurve_curve_eval(NULL, cc, t, 0, x));
            const double dist = sqrt((x[0] - hit[0]) * (x[0] - hit[0]) +
                                     (x[1] - hit[1]) * (x[1] - hit[1]) +
                                     (x[2] - hit[2]) * (x[2] - hit[2]));
            /* the compact curve within eps_D; the march's bisection to 1e-15 */
            CHECK(dist <= 1.01 * eps_d);
            projcurve_curve_destroy(cc);
            ++compared;
        }
    }
    CHECK(compared > 200);
    projcurve_result_destroy(all);
    projcurve_result_destroy(near);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

static void test_options(void)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    double d = -1.0;
    long long v = -1;
    CHECK_OK(projcurve_options_get_int(NULL, o, PROJCURVE_OPT_HITS, &v));
    CHECK(v == PROJCURVE_HITS_ALL);
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_MAX_DISTANCE, INFINITY));
    CHECK_OK(projcurve_options_get_double(NULL, o, PROJCURVE_OPT_MAX_DISTANCE, &d));
    CHECK(d == 0.0);
    CHECK_STATUS(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_MAX_DISTANCE, -1.0),
                 PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK_STATUS(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_MAX_DISTANCE, NAN),
                 PROJCURVE_ERR_NOT_FINITE);
    CHECK_STATUS(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_HITS, 2),
                 PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK_STATUS(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_THREADS, 0),
                 PROJCURVE_ERR_OUT_OF_RANGE);
    projcurve_options_destroy(o);
}

int main(void)
{
    test_options();
    test_two_walls();
    test_crossing_sheets();
    test_walls_orthogonal();
    test_max_distance();
    test_bump(0);
    test_bump(1);
    return pc_test_finish("test_hits_select");
}
