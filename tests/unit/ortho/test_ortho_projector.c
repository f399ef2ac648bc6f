/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The orthogonal projector's equations alone ([PW96] s4): third surface
 * derivatives against nurbs/ and finite differences; Newton foot points on
 * a sphere against the radial answer; q', q'' against finite differences
 * of Newton-corrected foot points; det K against (1 + rho / R)^2.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "ortho/ortho_projector.h"
#include "ortho/surface_d3.h"
#include "shapes.h"

static double norm3(pc_vec3 a) { return vec3_norm(a); }

/* Derivatives up to order 2 agree with nurbs/ (same math, other code) and
 * the third ones with fourth-order central differences of the second. */
static void check_d3(const char *name, const projcurve_surface *surf, const double *samples,
                     size_t n_samples)
{
    const pc_nurbs_surface *s = &surf->nurbs;
    double worst_low = 0.0, worst_third = 0.0;
    for (size_t k = 0; k < n_samples; ++k) {
        const double u = samples[2 * k], v = samples[2 * k + 1];
        pc_vec3 d3[PC_D3_COUNT], d2[6];
        pc_surface_eval_d3(s, u, v, NULL, NULL, d3);
        pc_nurbs_surface_eval(s, u, v, 2, NULL, NULL, d2);
        double scale = 0.0;
        for (int i = 0; i < 6; ++i)
            scale = fmax(scale, norm3(d2[i]));
        for (int i = 0; i < 6; ++i)
            worst_low = fmax(worst_low, vec3_dist(d3[i], d2[i]) / scale);

        /* 4th-order differences with h = 1e-3 in parameters whose spans are
         * >= 0.2 wide: truncation ~ h^4 |S^(7)| / 30, rounding ~ 1e-16 |S''| / h,
         * both below 1e-8 of the derivative scale for these shapes. */
        const double h = 1e-3;
        pc_vec3 e[4][6];
        const double off[4] = {2 * h, h, -h, -2 * h};
        pc_vec3 fd_u[6], fd_v[6];
        for (int j = 0; j < 4; ++j)
            pc_nurbs_surface_eval(s, u + off[j], v, 2, NULL, NULL, e[j]);
        for (int i = 0; i < 6; ++i)
            fd_u[i] = vec3_scale(vec3_add(vec3_sub(e[3][i], e[0][i]),
                                          vec3_scale(vec3_sub(e[1][i], e[2][i]), 8.0)),
                                 1.0 / (12.0 * h));
        for (int j = 0; j < 4; ++j)
            pc_nurbs_surface_eval(s, u, v + off[j], 2, NULL, NULL, e[j]);
        for (int i = 0; i < 6; ++i)
            fd_v[i] = vec3_scale(vec3_add(vec3_sub(e[3][i], e[0][i]),
                                          vec3_scale(vec3_sub(e[1][i], e[2][i]), 8.0)),
                                 1.0 / (12.0 * h));
        double scale3 = scale;
        for (int i = 6; i < 10; ++i)
            scale3 = fmax(scale3, norm3(d3[i]));
        const pc_vec3 pairs[6][2] = {
            {d3[PC_D3_UUU], fd_u[PC_D3_UU]}, {d3[PC_D3_UUV], fd_v[PC_D3_UU]},
            {d3[PC_D3_UUV], fd_u[PC_D3_UV]}, {d3[PC_D3_UVV], fd_u[PC_D3_VV]},
            {d3[PC_D3_UVV], fd_v[PC_D3_UV]}, {d3[PC_D3_VVV], fd_v[PC_D3_VV]},
        };
        for (int i = 0; i < 6; ++i)
            worst_third = fmax(worst_third, vec3_dist(pairs[i][0], pairs[i][1]) / scale3);
    }
    printf("%-16s d3: orders 0-2 vs nurbs %.1e, order 3 vs differences %.1e (relative)\n", name,
           worst_low, worst_third);
    CHECK(worst_low <= 1e-13);
    CHECK(worst_third <= 1e-7);
}

/* A wavy space curve P(t) = c + (a cos t, a sin t, h sin 2t). */
typedef struct wave {
    double c[3], a, h;
} wave;

static int wave_fn(void *user, double t, double out[9])
{
    const wave *w = user;
    const double v[9] = {w->c[0] + w->a * cos(t), w->c[1] + w->a * sin(t),
                         w->c[2] + w->h * sin(2 * t), -w->a * sin(t), w->a * cos(t),
                         2 * w->h * cos(2 * t), -w->a * cos(t), -w->a * sin(t),
                         -4 * w->h * sin(2 * t)};
    memcpy(out, v, sizeof v);
    return 0;
}

/* A foot point of P(t) near the closest sample of a 64 x 64 grid (brute
 * force, independent of the library's point projection), by Newton. */
static int foot_point(const pc_projector *proj, double t, double uv[2])
{
    const pc_nurbs_surface *s = &proj->surface->nurbs;
    pc_vec3 p;
    pc_curve_eval(proj->curve, t, 0, NULL, &p);
    double best = INFINITY;
    for (int i = 0; i <= 64; ++i)
        for (int j = 0; j <= 64; ++j) {
            const double u = s->domain[0] + (s->domain[1] - s->domain[0]) * i / 64.0;
            const double v = s->domain[2] + (s->domain[3] - s->domain[2]) * j / 64.0;
            pc_vec3 q;
            pc_nurbs_surface_eval(s, u, v, 0, NULL, NULL, &q);
            const double d = vec3_dist(p, q);
            if (d < best) {
                best = d;
                uv[0] = u;
                uv[1] = v;
            }
        }
    return proj->correct(proj, t, uv, NULL);
}

/* q' and q'' against 4th-order differences of foot points q(t +- k h). */
static void check_q_derivatives(const char *name, const pc_projector *proj, double t0,
                                double t1)
{
    double worst1 = 0.0, worst2 = 0.0;
    for (int k = 0; k < 6; ++k) {
        const double t = t0 + (t1 - t0) * (k + 0.5) / 6.0;
        double uv[2];
        CHECK(foot_point(proj, t, uv));
        pc_proj_point pt;
        CHECK(proj->derivatives(proj, t, uv[0], uv[1], &pt));
        const double h = 1e-2;
        double q[5][2];
        for (int j = -2; j <= 2; ++j) {
            q[j + 2][0] = uv[0];
            q[j + 2][1] = uv[1];
            CHECK(proj->correct(proj, t + j * h, q[j + 2], NULL));
        }
        const double qd[2] = {pt.du, pt.dv}, qdd[2] = {pt.ddu, pt.ddv};
        const double scale1 = fmax(1.0, hypot(pt.du, pt.dv));
        const double scale2 = fmax(1.0, hypot(pt.ddu, pt.ddv));
        for (int i = 0; i < 2; ++i) {
            const double d1 = (q[0][i] - 8 * q[1][i] + 8 * q[3][i] - q[4][i]) / (12 * h);
            const double d2 =
                (-q[0][i] + 16 * q[1][i] - 30 * q[2][i] + 16 * q[3][i] - q[4][i]) / (12 * h * h);
            worst1 = fmax(worst1, fabs(qd[i] - d1) / scale1);
            worst2 = fmax(worst2, fabs(qdd[i] - d2) / scale2);
        }
        CHECK(proj->residual(proj, t, uv[0], uv[1]) <= 1e-10);
    }
    printf("%-16s q' vs differences %.1e, q'' vs differences %.1e (relative)\n", name, worst1,
           worst2);
    /* Truncation h^4 q^(5) / 30 with h = 1e-2 for curves of unit-order
     * derivatives, rounding 1e-12 / h^2 for q'': both near 1e-8. */
    CHECK(worst1 <= 1e-6);
    CHECK(worst2 <= 1e-5);
}

static void test_sphere(void)
{
    const double centre[3] = {0, 0, 0}, R = 10.0;
    pc_shape_surface shape = pc_shape_sphere(centre, R);
    projcurve_surface *surf = pc_shape_surface_create(&shape);
    wave w = {{1, 0, 2}, 13.0, 3.0};
    projcurve_curve *curve = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, wave_fn, &w, 0.0, 5.0, &curve));
    if (!surf || !curve)
        return;
    const double samples[] = {0.1, 0.2, 0.3, 0.35, 0.6, 0.7, 0.9, 0.65, 0.45, 0.8};
    check_d3("sphere", surf, samples, 5);

    pc_ortho_cache cache;
    pc_projector proj;
    pc_ortho_projector_init(&proj, &cache, surf, curve, 1e-13, 30);
    /* Foot points are radial, det K / (|Su||Sv|)^2 = (1 + rho/R)^2 since the
     * sphere's parametrisation is orthogonal (Su.Sv = 0). */
    for (int k = 0; k < 8; ++k) {
        const double t = 0.3 + 0.6 * k;
        double uv[2];
        CHECK(foot_point(&proj, t, uv));
        pc_proj_point pt;
        CHECK(proj.derivatives(&proj, t, uv[0], uv[1], &pt));
        const double dist = vec3_norm(pt.p);
        const pc_vec3 radial = vec3_scale(pt.p, R / dist);
        CHECK_NEAR(vec3_dist(pt.s, radial), 0.0, 1e-11);
        const double rho = dist - R;
        CHECK_NEAR(pt.det, (1 + rho / R) * (1 + rho / R), 1e-10);
        CHECK(pt.speed > 0.0);
    }
    check_q_derivatives("sphere", &proj, 0.2, 4.8);

    /* P at the centre: every point is a foot point and K = 0. */
    wave centre_curve = {{0, 0, 0}, 0.0, 0.0};
    projcurve_curve *still = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, wave_fn, &centre_curve, 0.0, 1.0, &still));
    pc_projector at_centre;
    pc_ortho_projector_init(&at_centre, &cache, surf, still, 1e-13, 30);
    pc_proj_point pt;
    CHECK(!at_centre.derivatives(&at_centre, 0.5, 0.3, 0.4, &pt));
    CHECK_NEAR(pt.det, 0.0, 1e-12);
    projcurve_curve_destroy(still);

    projcurve_curve_destroy(curve);
    projcurve_surface_destroy(surf);
    pc_shape_surface_free(&shape);
}

static void test_shape(const char *name, pc_shape_surface shape, wave w, double t0, double t1,
                       const double *samples, size_t n_samples)
{
    projcurve_surface *surf = pc_shape_surface_create(&shape);
    projcurve_curve *curve = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, wave_fn, &w, t0, t1, &curve));
    if (surf && curve) {
        check_d3(name, surf, samples, n_samples);
        pc_ortho_cache cache;
        pc_projector proj;
        pc_ortho_projector_init(&proj, &cache, surf, curve, 1e-13, 30);
        check_q_derivatives(name, &proj, t0, t1);
    }
    projcurve_curve_destroy(curve);
    projcurve_surface_destroy(surf);
    pc_shape_surface_free(&shape);
}

int main(void)
{
    test_sphere();
    const double samples[] = {0.1, 0.1, 0.3, 0.45, 0.55, 0.7, 0.9, 0.35, 0.6, 0.9, 0.15, 0.62};
    test_shape("torus", pc_shape_torus(10.0, 3.0), (wave){{0, 0, 1}, 11.0, 2.0}, 0.1, 1.4,
               samples, 6);
    test_shape("cylinder", pc_shape_cylinder(5.0, 10.0), (wave){{0, 0, 5}, 7.0, 3.0}, 0.1, 1.4,
               samples, 6);
    /* Single-span bumps: q'' contains third derivatives of S, which jump
     * across the knot lines of a cubic spline, so differences of q are only
     * comparable inside one span. */
    test_shape("bumpy", pc_shape_bumpy(7, 1, 1, 0.1, 0), (wave){{0.5, 0.5, 0.3}, 0.3, 0.1},
               0.0, 6.0, samples, 6);
    test_shape("bumpy rational", pc_shape_bumpy(11, 1, 1, 0.1, 1),
               (wave){{0.5, 0.5, 0.3}, 0.3, 0.1}, 0.0, 6.0, samples, 6);
    for (int rational = 0; rational <= 1; ++rational) {
        pc_shape_surface shape = pc_shape_bumpy(13, 4, 4, 0.2, rational);
        projcurve_surface *surf = pc_shape_surface_create(&shape);
        if (surf)
            check_d3(rational ? "bumpy 4x4 rat." : "bumpy 4x4", surf, samples, 6);
        projcurve_surface_destroy(surf);
        pc_shape_surface_free(&shape);
    }
    return pc_test_finish("test_ortho_projector");
}
