/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The derivative bounds of a span (nurbs/span_bound.h), on which the
 * corrector's one-evaluation acceptance rests: checked against central
 * differences of the library's second derivatives sampled densely over each
 * span (the bound must hold everywhere and, from a control net, be within a
 * modest factor of the true maximum), the second-derivative bounds against
 * the evaluated second derivatives, and the cubic remainder bound against
 * the true Taylor remainder of S for random steps inside a span.
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "nurbs/span_bound.h"
#include "trace_shapes.h"

/* Samples per span side; differences step (parameter units). */
#define SAMPLES 9
#define FD_H 1e-5
/* Central differences of second derivatives err by ~h^2 |S''''| plus
 * rounding ~1e-16 |S''| / h: this relative slack covers both here. */
#define FD_SLACK 1e-4
/* A hodograph bound of these smooth nets exceeds the sampled maximum by
 * less than this factor (convex hull of a few control points). */
#define LOOSE_FACTOR 20.0

static void second(const pc_nurbs_surface *s, double u, double v, pc_vec3 out[6])
{
    pc_nurbs_surface_eval(s, u, v, 2, NULL, NULL, out);
}

/* |d^3 S / du^(3-k) dv^k| at (u, v) by central differences of S''. */
static void third_fd(const pc_nurbs_surface *s, double u, double v, double out[4])
{
    pc_vec3 up[6], um[6], vp[6], vm[6];
    second(s, u + FD_H, v, up);
    second(s, u - FD_H, v, um);
    second(s, u, v + FD_H, vp);
    second(s, u, v - FD_H, vm);
    const double k = 0.5 / FD_H;
    out[0] = vec3_norm(vec3_scale(vec3_sub(up[3], um[3]), k)); /* Suuu */
    out[1] = vec3_norm(vec3_scale(vec3_sub(vp[3], vm[3]), k)); /* Suuv */
    out[2] = vec3_norm(vec3_scale(vec3_sub(up[5], um[5]), k)); /* Suvv */
    out[3] = vec3_norm(vec3_scale(vec3_sub(vp[5], vm[5]), k)); /* Svvv */
}

static void check_spans(const projcurve_surface *surface, const char *name)
{
    const pc_nurbs_surface *s = &surface->nurbs;
    double worst_ratio = 0.0, loosest = 0.0, worst_second = 0.0;
    for (size_t su = (size_t)s->deg_u; su < s->n_u; ++su)
        for (size_t sv = (size_t)s->deg_v; sv < s->n_v; ++sv) {
            const double u0 = s->knots_u[su], u1 = s->knots_u[su + 1];
            const double v0 = s->knots_v[sv], v1 = s->knots_v[sv + 1];
            if (!(u1 > u0) || !(v1 > v0))
                continue;
            double m3[4], m2[3];
            CHECK(pc_span_third_bound(s, su, sv, m3));
            CHECK(pc_span_second_bound(s, su, sv, m2));
            double seen[4] = {0, 0, 0, 0};
            for (int i = 0; i < SAMPLES; ++i)
                for (int j = 0; j < SAMPLES; ++j) {
                    /* inside the span, away from its knots by the FD step */
                    const double u = u0 + 2 * FD_H + (u1 - u0 - 4 * FD_H) * i / (SAMPLES - 1);
                    const double v = v0 + 2 * FD_H + (v1 - v0 - 4 * FD_H) * j / (SAMPLES - 1);
                    double d3[4];
                    third_fd(s, u, v, d3);
                    pc_vec3 d2[6]; /* second derivatives: exact, must be within m2 */
                    second(s, u, v, d2);
                    for (int k = 0; k < 3; ++k) {
                        if (m2[k] > 0.0)
                            worst_second = fmax(worst_second, vec3_norm(d2[3 + k]) / m2[k]);
                        else
                            /* degree 1 in that direction: zero up to the
                             * evaluation's rounding */
                            CHECK(vec3_norm(d2[3 + k]) <= 1e-12 * (m2[0] + m2[1] + m2[2]));
                    }
                    for (int k = 0; k < 4; ++k) {
                        seen[k] = fmax(seen[k], d3[k]);
                        if (m3[k] > 0.0)
                            worst_ratio = fmax(worst_ratio, d3[k] / m3[k]);
                        else
                            CHECK(d3[k] <= 1e-6); /* a vanishing derivative */
                    }
                }
            for (int k = 0; k < 4; ++k)
                if (seen[k] > 1e-6 * (m3[0] + m3[1] + m3[2] + m3[3]))
                    loosest = fmax(loosest, m3[k] / seen[k]);
        }
    printf("%s: sampled / bound <= %.6f, bound / sampled max <= %.2f\n", name, worst_ratio,
           loosest);
    printf("%s: second derivatives / bound <= %.6f\n", name, worst_second);
    CHECK(worst_ratio <= 1.0 + FD_SLACK);
    CHECK(worst_second <= 1.0 + 1e-12);
    CHECK(loosest <= LOOSE_FACTOR);
}

/* |S(q + d) - (S + S'd + S''[d, d] / 2)| <= pc_span_cubic_remainder. */
static void check_remainder(const projcurve_surface *surface)
{
    const pc_nurbs_surface *s = &surface->nurbs;
    const size_t su = (size_t)s->deg_u + 1, sv = (size_t)s->deg_v + 1;
    const double u0 = s->knots_u[su], u1 = s->knots_u[su + 1];
    const double v0 = s->knots_v[sv], v1 = s->knots_v[sv + 1];
    double m3[4];
    CHECK(pc_span_third_bound(s, su, sv, m3));
    double worst = 0.0;
    unsigned long long state = 12345;
    for (int n = 0; n < 200; ++n) {
        double r[4];
        for (int k = 0; k < 4; ++k) { /* LCG: fixed, reproducible */
            state = state * 6364136223846793005ULL + 1442695040888963407ULL;
            r[k] = (double)(state >> 11) / 9007199254740992.0;
        }
        const double u = u0 + (u1 - u0) * r[0], v = v0 + (v1 - v0) * r[1];
        const double du = (u0 + (u1 - u0) * r[2]) - u, dv = (v0 + (v1 - v0) * r[3]) - v;
        pc_vec3 a[6], b;
        second(s, u, v, a);
        pc_nurbs_surface_eval(s, u + du, v + dv, 0, NULL, NULL, &b);
        const pc_vec3 taylor = vec3_add(
            vec3_add(vec3_axpy(vec3_axpy(a[0], du, a[1]), dv, a[2]),
                     vec3_scale(a[3], 0.5 * du * du)),
            vec3_add(vec3_scale(a[4], du * dv), vec3_scale(a[5], 0.5 * dv * dv)));
        const double actual = vec3_dist(b, taylor);
        const double bound = pc_span_cubic_remainder(m3, du, dv);
        worst = fmax(worst, actual / bound);
    }
    printf("cubic remainder: actual / bound <= %.4f\n", worst);
    CHECK(worst <= 1.0 + 1e-9);
    CHECK(worst > 0.01); /* the bound is of the right size */
}

int main(void)
{
    projcurve_surface *bumpy = shape_bumpy(8.0, 777);
    projcurve_surface *ex1 = shape_example1_surface();
    projcurve_surface *sphere = shape_sphere(10.0);
    CHECK(bumpy != NULL && ex1 != NULL && sphere != NULL);
    if (bumpy && ex1 && sphere) {
        check_spans(bumpy, "bumpy bicubic 8x8");
        check_spans(ex1, "Example 1 (degree 5 x 1)");
        check_remainder(bumpy);
        /* no bound is derived for rational surfaces */
        double m3[4] = {-1, -1, -1, -1};
        CHECK(sphere->nurbs.rational);
        CHECK(!pc_span_third_bound(&sphere->nurbs, (size_t)sphere->nurbs.deg_u,
                                   (size_t)sphere->nurbs.deg_v, m3));
        CHECK(m3[0] == -1.0);
    }
    projcurve_surface_destroy(bumpy);
    projcurve_surface_destroy(ex1);
    projcurve_surface_destroy(sphere);
    return pc_test_finish("test_trace_span_bound");
}
