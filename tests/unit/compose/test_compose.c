/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The blossoming composer (compose/): a segment of the parameter box composed
 * with a (rational) Bezier patch must be S(u(s), v(s)) exactly.
 * Oracles: brute-force Bernstein evaluation of the patch and of the composed
 * curve (power-form Bernstein polynomials, no de Casteljau), degree elevation
 * of a boundary curve, the bilinear patch's diagonal, and an exact rational
 * cylinder.
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
#define N_SAMPLES 100
/* Composition is a sequence of affine combinations: agreement to 1e-12 of the
 * model size is the accuracy promised by the module. */
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

/* Homogeneous point of the patch at surface parameters (u, v), by sums. */
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

static double cartesian_distance(const double a[4], const double b[4])
{
    const double dx = a[0] / a[3] - b[0] / b[3], dy = a[1] / a[3] - b[1] / b[3],
                 dz = a[2] / a[3] - b[2] / b[3];
    return sqrt(dx * dx + dy * dy + dz * dz);
}

/* A random patch with control points in [-size/2, size/2]^3, weights in
 * [wlo, whi] (1 = polynomial) and parameter box [u0,u1] x [v0,v1]. */
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

/* Max over N_SAMPLES parameters of |composed(s) - S(u(s), v(s))|. */
static double composition_error(const pc_bezier_patch *pt, const double uv0[2],
                                const double uv1[2])
{
    double out[4 * 2 * MAX_ORDER];
    pc_compose_segment(pt, uv0, uv1, out);
    double worst = 0.0;
    for (int k = 0; k < N_SAMPLES; ++k) {
        const double s = (double)k / (N_SAMPLES - 1);
        double a[4], b[4];
        curve_point_h(pt->deg_u + pt->deg_v, out, s, a);
        patch_point_h(pt, uv0[0] + s * (uv1[0] - uv0[0]), uv0[1] + s * (uv1[1] - uv0[1]), b);
        const double d = cartesian_distance(a, b);
        if (d > worst)
            worst = d;
    }
    return worst;
}

static void random_uv(pc_test_rng *rng, const pc_bezier_patch *pt, double uv[2])
{
    uv[0] = pc_test_rng_uniform(rng, pt->u0, pt->u1);
    uv[1] = pc_test_rng_uniform(rng, pt->v0, pt->v1);
}

static void test_random_patches(void)
{
    static const int degrees[][2] = {{1, 1}, {1, 3}, {2, 2}, {3, 3}, {3, 1}, {4, 5},
                                     {5, 5}, {2, 7}, {9, 4}, {12, 12}, {30, 30}};
    static double cw[4 * MAX_ORDER * MAX_ORDER];
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 6001);
    for (size_t d = 0; d < sizeof degrees / sizeof degrees[0]; ++d) {
        for (int rational = 0; rational <= 1; ++rational) {
            pc_bezier_patch pt;
            random_patch(&rng, degrees[d][0], degrees[d][1], rational ? 0.2 : 1.0,
                         rational ? 5.0 : 1.0, cw, &pt);
            const double size = sqrt(3.0); /* diagonal of the control-point cube */
            for (int trial = 0; trial < 8; ++trial) {
                double uv0[2], uv1[2];
                random_uv(&rng, &pt, uv0);
                random_uv(&rng, &pt, uv1);
                if (trial == 0) { /* corner to corner */
                    uv0[0] = pt.u0, uv0[1] = pt.v0, uv1[0] = pt.u1, uv1[1] = pt.v1;
                } else if (trial == 1) { /* along an edge, reversed */
                    uv0[0] = pt.u1, uv1[0] = pt.u1;
                } else if (trial == 2) { /* a point */
                    uv1[0] = uv0[0], uv1[1] = uv0[1];
                }
                const double err = composition_error(&pt, uv0, uv1);
                if (!(err <= REL_TOL * size))
                    fprintf(stderr, "degrees (%d,%d) rational %d trial %d: error %.3g\n",
                            pt.deg_u, pt.deg_v, rational, trial, err);
                CHECK(err <= REL_TOL * size);
            }
        }
    }
}

/* The edge u = u0 composed over the whole v range is the boundary curve
 * (column i = 0, degree q) elevated p times: control points
 * R_k = sum_j C(q,j) C(p,k-j) / C(p+q,k) P_0j (homogeneous). */
static void test_degree_elevation(void)
{
    static double cw[4 * MAX_ORDER * MAX_ORDER];
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 6002);
    pc_bezier_patch pt;
    random_patch(&rng, 4, 3, 0.5, 2.0, cw, &pt);
    const double uv0[2] = {pt.u0, pt.v0}, uv1[2] = {pt.u0, pt.v1};
    double out[4 * 2 * MAX_ORDER];
    pc_compose_segment(&pt, uv0, uv1, out);
    const int p = pt.deg_u, q = pt.deg_v, n = p + q;
    for (int k = 0; k <= n; ++k) {
        double expect[4] = {0, 0, 0, 0};
        for (int j = 0; j <= q; ++j) {
            if (k - j < 0 || k - j > p)
                continue;
            const double w = binomial(q, j) * binomial(p, k - j) / binomial(n, k);
            for (int c = 0; c < 4; ++c)
                expect[c] += w * cw[4 * (j * (p + 1)) + c];
        }
        for (int c = 0; c < 4; ++c)
            CHECK_NEAR(out[4 * k + c], expect[c], 1e-14);
    }
}

/* Bilinear patch, full diagonal: S(s, s) = (1-s)^2 P00 + 2s(1-s)(P10+P01)/2 + s^2 P11. */
static void test_bilinear_diagonal(void)
{
    double cw[16] = {0, 0, 0, 1, 4, 0, 1, 1, 0, 3, -2, 1, 5, 6, 7, 1};
    pc_bezier_patch pt = {1, 1, 0.0, 1.0, 0.0, 1.0, cw, {0}, 0, 0, NULL, 0.0};
    const double uv0[2] = {0, 0}, uv1[2] = {1, 1};
    double out[12];
    pc_compose_segment(&pt, uv0, uv1, out);
    const double expect[12] = {0, 0, 0, 1, 2, 1.5, -0.5, 1, 5, 6, 7, 1};
    for (int k = 0; k < 12; ++k)
        CHECK_NEAR(out[k], expect[k], 1e-15);
}

/* Quarter cylinder x^2 + y^2 = R^2, z in [0, H]: rational quadratic in u
 * (weights 1, 1/sqrt2, 1) times linear in v. Every composed point lies on it. */
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
    pc_test_rng_seed(&rng, 6003);
    for (int trial = 0; trial < 20; ++trial) {
        double uv0[2], uv1[2], out[4 * 4];
        random_uv(&rng, &pt, uv0);
        random_uv(&rng, &pt, uv1);
        pc_compose_segment(&pt, uv0, uv1, out);
        double ctrl[12], weights[4];
        pc_compose_to_cartesian(3, out, ctrl, weights);
        for (int k = 0; k <= 3; ++k)
            CHECK(weights[k] > 0.0);
        for (int k = 0; k < N_SAMPLES; ++k) {
            double h[4];
            curve_point_h(3, out, (double)k / (N_SAMPLES - 1), h);
            const double x = h[0] / h[3], y = h[1] / h[3], z = h[2] / h[3];
            CHECK_NEAR(sqrt(x * x + y * y), R, 1e-12 * R);
            CHECK(z >= -1e-12 && z <= H + 1e-12);
        }
        /* The ends are the images of the segment ends. */
        double a[4];
        patch_point_h(&pt, uv1[0], uv1[1], a);
        CHECK_NEAR(ctrl[9], a[0] / a[3], 1e-13);
        CHECK_NEAR(ctrl[10], a[1] / a[3], 1e-13);
        CHECK_NEAR(ctrl[11], a[2] / a[3], 1e-13);
    }
}

/* The patches of real decomposed surfaces (the layout refine/ composes
 * with): random segments inside every patch of a rational bumpy surface, a
 * torus and a quintic plane, composed and compared with the library's NURBS
 * evaluation of the whole surface at 100 parameters. */
static void test_decomposed_surfaces(void)
{
    const pc_shape_surface shapes[] = {pc_shape_bumpy(6004, 4, 3, 0.4, 1), pc_shape_torus(3.0, 1.0),
                                       pc_shape_plane(5, 4, 2, 3)};
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 6005);
    for (size_t k = 0; k < sizeof shapes / sizeof shapes[0]; ++k) {
        projcurve_surface *s = pc_shape_surface_create(&shapes[k]);
        CHECK(s != NULL);
        if (s == NULL)
            continue;
        const pc_patch_grid *g = &s->grid;
        double worst = 0.0;
        for (size_t i = 0; i < g->spans_u * g->spans_v; ++i) {
            const pc_bezier_patch *pt = &g->patches[i];
            for (int trial = 0; trial < 4; ++trial) {
                double uv0[2], uv1[2], out[4 * 2 * MAX_ORDER];
                random_uv(&rng, pt, uv0);
                random_uv(&rng, pt, uv1);
                pc_compose_segment(pt, uv0, uv1, out);
                for (int j = 0; j < N_SAMPLES; ++j) {
                    const double sp = (double)j / (N_SAMPLES - 1);
                    double a[4];
                    curve_point_h(pt->deg_u + pt->deg_v, out, sp, a);
                    pc_vec3 e;
                    pc_nurbs_surface_eval(&s->nurbs, uv0[0] + sp * (uv1[0] - uv0[0]),
                                          uv0[1] + sp * (uv1[1] - uv0[1]), 0, NULL, NULL, &e);
                    const double d = vec3_dist(vec3(a[0] / a[3], a[1] / a[3], a[2] / a[3]), e);
                    worst = d > worst ? d : worst;
                }
            }
        }
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
    test_degree_elevation();
    test_bilinear_diagonal();
    test_rational_cylinder();
    test_decomposed_surfaces();
    return pc_test_finish("test_compose");
}
