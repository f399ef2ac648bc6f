/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Composition of a polynomial pcurve with a Bezier patch (compose_poly.c):
 * S(u(s), v(s)) for a cubic (u, v)(s) inside a patch is a Bezier curve of
 * degree 3 (p + q); the same for rational pcurves. Oracles: brute-force Bernstein sums of the patch at the
 * pcurve's points (power-form Bernstein polynomials, no de Casteljau, no
 * products), the blossoming composer for straight segments, an exact
 * rational cylinder, and the library's NURBS evaluation on decomposed
 * surfaces.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "compose/compose.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "shapes.h"

#define MAX_ORDER (PROJCURVE_MAX_DEGREE + 1)
#define MAX_OUT (2 * PROJCURVE_MAX_DEGREE + 1)
#define N_SAMPLES 100
/* The composition is a chain of products and sums of non-negative weights:
 * agreement to 1e-12 of the model size is what the module promises. */
#define REL_TOL 1e-12

static double binomial(int n, int k)
{
    double c = 1.0;
    for (int i = 1; i <= k; ++i)
        c = c * (double)(n - k + i) / (double)i;
    return c;
}

static double bernstein(int n, int i, double x)
{
    return binomial(n, i) * pow(x, (double)i) * pow(1.0 - x, (double)(n - i));
}

static void patch_point_h(const pc_bezier_patch *pt, double u, double v, double h[4])
{
    const double x = (u - pt->u0) / (pt->u1 - pt->u0), y = (v - pt->v0) / (pt->v1 - pt->v0);
    h[0] = h[1] = h[2] = h[3] = 0.0;
    for (int j = 0; j <= pt->deg_v; ++j)
        for (int i = 0; i <= pt->deg_u; ++i) {
            const double b = bernstein(pt->deg_u, i, x) * bernstein(pt->deg_v, j, y);
            const double *c = pt->cw + 4 * (j * (pt->deg_u + 1) + i);
            for (int k = 0; k < 4; ++k)
                h[k] += b * c[k];
        }
}

static void curve_point_h(int deg, const double *cw, double s, double h[4])
{
    h[0] = h[1] = h[2] = h[3] = 0.0;
    for (int i = 0; i <= deg; ++i) {
        const double b = bernstein(deg, i, s);
        for (int k = 0; k < 4; ++k)
            h[k] += b * cw[4 * i + k];
    }
}

/* (u, v) of the degree-d pcurve at s. */
static void pcurve_point(int d, const double *uv, double s, double out[2])
{
    out[0] = out[1] = 0.0;
    for (int i = 0; i <= d; ++i) {
        const double b = bernstein(d, i, s);
        out[0] += b * uv[2 * i];
        out[1] += b * uv[2 * i + 1];
    }
}

static double cartesian_distance(const double a[4], const double b[4])
{
    const double dx = a[0] / a[3] - b[0] / b[3], dy = a[1] / a[3] - b[1] / b[3],
                 dz = a[2] / a[3] - b[2] / b[3];
    return sqrt(dx * dx + dy * dy + dz * dz);
}

static void random_patch(pc_test_rng *rng, int p, int q, double wlo, double whi, double *cw,
                         pc_bezier_patch *pt)
{
    memset(pt, 0, sizeof *pt);
    pt->deg_u = p;
    pt->deg_v = q;
    pt->u0 = -1.5;
    pt->u1 = 2.25;
    pt->v0 = 10.0;
    pt->v1 = 10.5;
    for (int k = 0; k < (p + 1) * (q + 1); ++k) {
        const double w = wlo == whi ? wlo : pc_test_rng_uniform(rng, wlo, whi);
        for (int c = 0; c < 3; ++c)
            cw[4 * k + c] = w * pc_test_rng_uniform(rng, -0.5, 0.5);
        cw[4 * k + 3] = w;
    }
    pt->cw = cw;
}

/* A random degree-d pcurve with control points in the patch's box. */
static void random_pcurve(pc_test_rng *rng, const pc_bezier_patch *pt, int d, double *uv)
{
    for (int k = 0; k <= d; ++k) {
        uv[2 * k] = pc_test_rng_uniform(rng, pt->u0, pt->u1);
        uv[2 * k + 1] = pc_test_rng_uniform(rng, pt->v0, pt->v1);
    }
}

/* Max over N_SAMPLES parameters of |composed(s) - S(uv(s))|; -1 when the
 * composer refused. */
static double composition_error(const pc_bezier_patch *pt, int d, const double *uv)
{
    double out[4 * MAX_OUT];
    const int n = pc_compose_poly(pt, d, uv, out);
    if (n != d * (pt->deg_u + pt->deg_v))
        return -1.0;
    double worst = 0.0;
    for (int k = 0; k < N_SAMPLES; ++k) {
        const double s = (double)k / (N_SAMPLES - 1);
        double a[4], b[4], q[2];
        curve_point_h(n, out, s, a);
        pcurve_point(d, uv, s, q);
        patch_point_h(pt, q[0], q[1], b);
        const double e = cartesian_distance(a, b);
        worst = e > worst ? e : worst;
    }
    return worst;
}

static void test_random_patches(void)
{
    static const int degrees[][2] = {{1, 1}, {1, 2}, {2, 2}, {2, 3}, {3, 3}, {5, 1},
                                     {1, 5}, {3, 1}, {7, 7}, {10, 10}};
    static double cw[4 * MAX_ORDER * MAX_ORDER];
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 6101);
    const double size = sqrt(3.0); /* diagonal of the control-point cube */
    for (size_t k = 0; k < sizeof degrees / sizeof degrees[0]; ++k)
        for (int rational = 0; rational <= 1; ++rational)
            for (int d = 1; d <= 3; ++d) {
                pc_bezier_patch pt;
                random_patch(&rng, degrees[k][0], degrees[k][1], rational ? 0.2 : 1.0,
                             rational ? 5.0 : 1.0, cw, &pt);
                for (int trial = 0; trial < 6; ++trial) {
                    double uv[8];
                    random_pcurve(&rng, &pt, d, uv);
                    if (trial == 0) { /* along the edge u = u1 */
                        for (int i = 0; i <= d; ++i)
                            uv[2 * i] = pt.u1;
                    } else if (trial == 1) { /* a point */
                        for (int i = 1; i <= d; ++i)
                            uv[2 * i] = uv[0], uv[2 * i + 1] = uv[1];
                    }
                    const double err = composition_error(&pt, d, uv);
                    if (!(err >= 0.0 && err <= REL_TOL * size))
                        fprintf(stderr, "degrees (%d,%d) rational %d pcurve %d: error %.3g\n",
                                pt.deg_u, pt.deg_v, rational, d, err);
                    CHECK(err >= 0.0 && err <= REL_TOL * size);
                }
            }
}

/* Rational pcurves (pc_compose_poly_weighted): random weights in [0.3, 3]
 * on pcurves of degrees 1..3 in random patches, polynomial and rational;
 * the composed curve against the patch at q(s) = sum w_i B_i uv_i /
 * sum w_i B_i. Weights all 1 give pc_compose_poly's points bit for bit. */
static void test_weighted_pcurves(void)
{
    static const int degrees[][2] = {{1, 1}, {2, 2}, {3, 3}, {2, 1}, {5, 3}};
    static double cw[4 * MAX_ORDER * MAX_ORDER];
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 6104);
    const double size = sqrt(3.0);
    for (size_t k = 0; k < sizeof degrees / sizeof degrees[0]; ++k)
        for (int rational = 0; rational <= 1; ++rational)
            for (int d = 1; d <= 3; ++d) {
                pc_bezier_patch pt;
                random_patch(&rng, degrees[k][0], degrees[k][1], rational ? 0.2 : 1.0,
                             rational ? 5.0 : 1.0, cw, &pt);
                double uv[8], w[4], out[4 * MAX_OUT], plain[4 * MAX_OUT];
                random_pcurve(&rng, &pt, d, uv);
                for (int i = 0; i <= d; ++i)
                    w[i] = pc_test_rng_uniform(&rng, 0.3, 3.0);
                const int n = pc_compose_poly_weighted(&pt, d, uv, w, out);
                CHECK(n == d * (pt.deg_u + pt.deg_v));
                double worst = 0.0;
                for (int j = 0; j < N_SAMPLES && n > 0; ++j) {
                    const double t = (double)j / (N_SAMPLES - 1);
                    double a[4], b[4], q[2] = {0.0, 0.0}, den = 0.0;
                    for (int i = 0; i <= d; ++i) {
                        const double bw = bernstein(d, i, t) * w[i];
                        q[0] += bw * uv[2 * i];
                        q[1] += bw * uv[2 * i + 1];
                        den += bw;
                    }
                    curve_point_h(n, out, t, a);
                    patch_point_h(&pt, q[0] / den, q[1] / den, b);
                    worst = fmax(worst, cartesian_distance(a, b));
                }
                if (!(worst <= REL_TOL * size))
                    fprintf(stderr, "weighted: degrees (%d,%d) rational %d pcurve %d: %.3g\n",
                            pt.deg_u, pt.deg_v, rational, d, worst);
                CHECK(worst <= REL_TOL * size);
                const double ones[4] = {1.0, 1.0, 1.0, 1.0};
                CHECK(pc_compose_poly_weighted(&pt, d, uv, ones, out) == n);
                CHECK(pc_compose_poly(&pt, d, uv, plain) == n);
                CHECK(memcmp(out, plain, 4 * (size_t)(n + 1) * sizeof *out) == 0);
            }
}

/* A straight pcurve gives the blossoming composer's control points. */
static void test_matches_segment(void)
{
    static double cw[4 * MAX_ORDER * MAX_ORDER];
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 6102);
    pc_bezier_patch pt;
    random_patch(&rng, 3, 2, 0.5, 2.0, cw, &pt);
    for (int trial = 0; trial < 10; ++trial) {
        double uv[4], a[4 * MAX_OUT], b[4 * MAX_OUT];
        random_pcurve(&rng, &pt, 1, uv);
        CHECK(pc_compose_poly(&pt, 1, uv, a) == 5);
        pc_compose_segment(&pt, uv, uv + 2, b);
        for (int k = 0; k < 4 * 6; ++k)
            CHECK_NEAR(a[k], b[k], 1e-14);
    }
}

/* Degrees out of range are refused and nothing is written. */
static void test_refusals(void)
{
    static double cw[4 * MAX_ORDER * MAX_ORDER];
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 6103);
    pc_bezier_patch pt;
    double uv[8], out[4 * MAX_OUT];
    out[0] = 42.0;
    random_patch(&rng, 3, 3, 1.0, 1.0, cw, &pt);
    random_pcurve(&rng, &pt, 3, uv);
    CHECK(pc_compose_poly(&pt, 0, uv, out) == -1);
    CHECK(pc_compose_poly(&pt, 4, uv, out) == -1);
    random_patch(&rng, 11, 10, 1.0, 1.0, cw, &pt); /* 3 * 21 = 63 > 60 */
    CHECK(pc_compose_poly(&pt, 3, uv, out) == -1);
    CHECK(out[0] == 42.0);
    random_patch(&rng, 10, 10, 1.0, 1.0, cw, &pt); /* 60: the largest */
    random_pcurve(&rng, &pt, 3, uv);
    CHECK(pc_compose_poly(&pt, 3, uv, out) == 60);
}

/* Quarter cylinder x^2 + y^2 = R^2 (rational quadratic in u, linear in v):
 * every composed point lies on it, every weight is positive. */
static void test_rational_cylinder(void)
{
    const double R = 3.0, H = 5.0, w = sqrt(0.5);
    const double pts[3][2] = {{R, 0}, {R, R}, {0, R}};
    const double wts[3] = {1.0, w, 1.0};
    double cw[4 * 6];
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i) {
            double *c = cw + 4 * (j * 3 + i);
            c[0] = wts[i] * pts[i][0];
            c[1] = wts[i] * pts[i][1];
            c[2] = wts[i] * H * j;
            c[3] = wts[i];
        }
    pc_bezier_patch pt = {2, 1, 0.0, 1.0, 0.0, 1.0, cw, {0}, 0, 0, NULL, 0.0};
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 6104);
    for (int trial = 0; trial < 20; ++trial) {
        double uv[8], out[4 * 10];
        random_pcurve(&rng, &pt, 3, uv);
        CHECK(pc_compose_poly(&pt, 3, uv, out) == 9);
        for (int k = 0; k <= 9; ++k)
            CHECK(out[4 * k + 3] > 0.0);
        for (int k = 0; k < N_SAMPLES; ++k) {
            double h[4];
            curve_point_h(9, out, (double)k / (N_SAMPLES - 1), h);
            const double x = h[0] / h[3], y = h[1] / h[3], z = h[2] / h[3];
            CHECK_NEAR(sqrt(x * x + y * y), R, 1e-12 * R);
            CHECK(z >= -1e-12 && z <= H + 1e-12);
        }
    }
}

/* Every patch of decomposed surfaces (rational bumpy, torus, quintic x
 * linear plane): random cubic pcurves, compared with the library's NURBS
 * evaluation of the whole surface. */
static void test_decomposed_surfaces(void)
{
    const pc_shape_surface shapes[] = {pc_shape_bumpy(6105, 4, 3, 0.4, 1), pc_shape_torus(3.0, 1.0),
                                       pc_shape_plane(5, 1, 2, 3)};
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 6106);
    for (size_t k = 0; k < sizeof shapes / sizeof shapes[0]; ++k) {
        projcurve_surface *s = pc_shape_surface_create(&shapes[k]);
        CHECK(s != NULL);
        if (s == NULL)
            continue;
        const pc_patch_grid *g = &s->grid;
        double worst = 0.0;
        for (size_t i = 0; i < g->spans_u * g->spans_v; ++i) {
            const pc_bezier_patch *pt = &g->patches[i];
            for (int trial = 0; trial < 3; ++trial) {
                double uv[8], out[4 * MAX_OUT];
                random_pcurve(&rng, pt, 3, uv);
                const int n = pc_compose_poly(pt, 3, uv, out);
                CHECK(n == 3 * (pt->deg_u + pt->deg_v));
                for (int j = 0; j < N_SAMPLES && n > 0; ++j) {
                    const double sp = (double)j / (N_SAMPLES - 1);
                    double a[4], q[2];
                    curve_point_h(n, out, sp, a);
                    pcurve_point(3, uv, sp, q);
                    pc_vec3 e;
                    pc_nurbs_surface_eval(&s->nurbs, q[0], q[1], 0, NULL, NULL, &e);
                    const double d = vec3_dist(vec3(a[0] / a[3], a[1] / a[3], a[2] / a[3]), e);
                    worst = d > worst ? d : worst;
                }
            }
        }
        if (!(worst <= REL_TOL * s->size))
            fprintf(stderr, "shape %zu: error %.3g (size %.3g)\n", k, worst, s->size);
        CHECK(worst <= REL_TOL * s->size);
        projcurve_surface_destroy(s);
    }
    for (size_t k = 0; k < sizeof shapes / sizeof shapes[0]; ++k) {
        pc_shape_surface copy = shapes[k];
        pc_shape_surface_free(&copy);
    }
}

int main(void)
{
    test_random_patches();
    test_weighted_pcurves();
    test_matches_segment();
    test_refusals();
    test_rational_cylinder();
    test_decomposed_surfaces();
    return pc_test_finish("test_compose_poly");
}
