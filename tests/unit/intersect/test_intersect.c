/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Line / surface intersection on whole NURBS surfaces (BVH, clipping,
 * merging), through pc_intersect_line and the public
 * projcurve_surface_intersect_line:
 *   - bad input: every documented status;
 *   - a multi-patch plane (answers in closed form), lines through patch
 *     corners and along patch edges (reported once), domain edges (flagged);
 *   - exact spheres: hits against the quadratic |o + l d - c|^2 = r^2, and
 *     tangent lines (one hit, flagged);
 *   - exact tori: lines with four known hits, and random lines whose hits
 *     satisfy the implicit equation and match the brute-force oracle;
 *   - closed surfaces: the seams of a torus, each crossing reported once;
 *   - bumpy (also rational) and folded multi-patch surfaces against the
 *     brute-force oracle (tests/support/ray_oracle.c: dense triangulation +
 *     Newton). The real surfaces are in test_intersect_real.c.
 */
#include "check.h"
#include "intersect/intersect.h"
#include "ray_oracle.h"
#include "shapes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

/* ---- helpers ---------------------------------------------------------------- */

static projcurve_surface *make_surface(pc_shape_surface shape)
{
    projcurve_surface *s = pc_shape_surface_create(&shape);
    pc_shape_surface_free(&shape);
    CHECK(s != NULL);
    return s;
}

/* The oracle's evaluator: the public evaluation, independent of clipping. */
static void eval_surface(void *user, double u, double v, int n_deriv, double out[9])
{
    if (projcurve_surface_eval(NULL, user, u, v, n_deriv, out) != PROJCURVE_OK)
        for (int k = 0; k < 9; ++k)
            out[k] = NAN;
}

static size_t hits_of(const projcurve_surface *s, const double o[3], const double d[3],
                      int ray_only, pc_hit_list *hits)
{
    CHECK_OK(pc_intersect_line(NULL, s, vec3_load(o), vec3_load(d), ray_only, hits));
    return hits->count;
}

static void random_direction(pc_test_rng *rng, double d[3])
{
    double n2;
    do {
        for (int k = 0; k < 3; ++k)
            d[k] = pc_test_rng_uniform(rng, -1, 1);
        n2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    } while (n2 > 1.0 || n2 < 1e-4);
}

/* A random line through the surface's box grown by 20%. */
static void random_line(pc_test_rng *rng, const projcurve_surface *s, double o[3], double d[3])
{
    double box[6];
    CHECK_OK(projcurve_surface_bounds(NULL, s, box));
    for (int k = 0; k < 3; ++k) {
        const double c = 0.5 * (box[k] + box[k + 3]);
        const double h = 0.6 * (box[k + 3] - box[k]) + 1e-3 * box_diagonal(box);
        o[k] = pc_test_rng_uniform(rng, c - h, c + h);
    }
    random_direction(rng, d);
}

/* n random lines on s compared with the oracle on a cells x cells mesh. */
static void compare_random_lines(const projcurve_surface *s, const char *name, int n_lines,
                                 int cells, unsigned long long seed)
{
    double domain[4];
    CHECK_OK(projcurve_surface_domain(NULL, s, domain));
    pc_oracle_mesh mesh;
    CHECK(pc_oracle_mesh_build(&mesh, eval_surface, (void *)s, domain, cells, cells));
    pc_test_rng rng;
    pc_test_rng_seed(&rng, seed);
    pc_hit_list hits = {0};
    pc_oracle_stats st = {0};
    double *uvl = NULL;
    unsigned *flags = NULL;
    for (int k = 0; k < n_lines; ++k) {
        double o[3], d[3];
        random_line(&rng, s, o, d);
        const int ray_only = k % 3 == 0;
        const size_t n = hits_of(s, o, d, ray_only, &hits);
        uvl = realloc(uvl, sizeof *uvl * 3 * (n + 1));
        flags = realloc(flags, sizeof *flags * (n + 1));
        for (size_t h = 0; h < n; ++h) {
            uvl[3 * h] = hits.items[h].u;
            uvl[3 * h + 1] = hits.items[h].v;
            uvl[3 * h + 2] = hits.items[h].lambda;
            flags[h] = hits.items[h].flags;
        }
        pc_oracle_compare(&mesh, o, d, ray_only, n, uvl, flags, &st);
    }
    printf("%s: %ld lines, %ld hits (oracle %ld), %ld grazing hits the mesh missed\n", name,
           st.lines, st.hits, st.oracle_hits, st.grazing_extra);
    CHECK(st.hits > n_lines / 25); /* the lines do meet the surface */
    free(uvl);
    free(flags);
    pc_hit_list_free(&hits);
    pc_oracle_mesh_free(&mesh);
}

/* ---- bad input ------------------------------------------------------------- */

static void test_bad_input(void)
{
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    projcurve_surface *s = make_surface(pc_shape_plane(3, 3, 2, 2));
    const double o[3] = {0, 0, 1}, d[3] = {0, 0, -1};
    double hits[6];
    unsigned flags[2];
    size_t count = 99;
    CHECK_STATUS(projcurve_surface_intersect_line(ctx, NULL, o, d, 0, 2, hits, flags, &count),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_surface_intersect_line(ctx, s, NULL, d, 0, 2, hits, flags, &count),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_surface_intersect_line(ctx, s, o, NULL, 0, 2, hits, flags, &count),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_surface_intersect_line(ctx, s, o, d, 0, 2, hits, flags, NULL),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_surface_intersect_line(ctx, s, o, d, 0, 2, NULL, flags, &count),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK(count == 99); /* outputs untouched on failure */
    const double bad[][3] = {{NAN, 0, 0}, {0, INFINITY, 0}, {0, 0, -INFINITY}};
    for (int k = 0; k < 3; ++k) {
        CHECK_STATUS(projcurve_surface_intersect_line(ctx, s, bad[k], d, 0, 2, hits, flags, &count),
                     PROJCURVE_ERR_NOT_FINITE);
        CHECK_STATUS(projcurve_surface_intersect_line(ctx, s, o, bad[k], 0, 2, hits, flags, &count),
                     PROJCURVE_ERR_NOT_FINITE);
        CHECK(strlen(projcurve_context_message(ctx)) > 0);
    }
    const double zero[3] = {0, 0, 0}, minus_zero[3] = {-0.0, 0.0, -0.0};
    CHECK_STATUS(projcurve_surface_intersect_line(ctx, s, o, zero, 0, 2, hits, flags, &count),
                 PROJCURVE_ERR_ZERO_DIRECTION);
    CHECK_STATUS(projcurve_surface_intersect_line(NULL, s, o, minus_zero, 1, 2, hits, flags, &count),
                 PROJCURVE_ERR_ZERO_DIRECTION);
    CHECK(count == 99);
    /* A miss is zero hits and OK; capacity 0 with NULL arrays only counts. */
    const double away[3] = {10, 10, 1};
    CHECK_OK(projcurve_surface_intersect_line(ctx, s, away, d, 0, 2, hits, flags, &count));
    CHECK(count == 0);
    CHECK_OK(projcurve_surface_intersect_line(ctx, s, o, d, 0, 0, NULL, NULL, &count));
    CHECK(count == 1);
    /* Tiny and huge (finite) directions give the same hit, lambda scaled. */
    const double tiny[3] = {0, 0, -1e-200}, huge[3] = {0, 0, -1e200};
    CHECK_OK(projcurve_surface_intersect_line(ctx, s, o, tiny, 1, 2, hits, NULL, &count));
    CHECK(count == 1);
    CHECK_NEAR(hits[2] * 1e-200, 1.0, 1e-14);
    CHECK_OK(projcurve_surface_intersect_line(ctx, s, o, huge, 1, 2, hits, flags, &count));
    CHECK(count == 1);
    CHECK_NEAR(hits[2] * 1e200, 1.0, 1e-14);
    /* Behind the origin: found on the line, not on the ray. */
    const double up[3] = {0, 0, 1};
    CHECK_OK(projcurve_surface_intersect_line(ctx, s, o, up, 1, 2, hits, flags, &count));
    CHECK(count == 0);
    CHECK_OK(projcurve_surface_intersect_line(ctx, s, o, up, 0, 2, hits, flags, &count));
    CHECK(count == 1);
    CHECK_NEAR(hits[2], -1.0, 1e-14);
    /* pc_intersect_line_patches: an index past the end. */
    pc_hit_list list = {0};
    const size_t bad_index[1] = {4};
    CHECK_STATUS(pc_intersect_line_patches(ctx, s, bad_index, 1, vec3_load(o), vec3_load(d), 0,
                                           &list),
                 PROJCURVE_ERR_INDEX);
    pc_hit_list_free(&list);
    projcurve_surface_destroy(s);
    projcurve_context_destroy(ctx);
}

/* ---- plane -------------------------------------------------------------------- */

/* S(u, v) = (2u - 1, 3v - 1, 0) over 4 x 4 bicubic patches. */
static void test_plane(void)
{
    projcurve_surface *s = make_surface(pc_shape_plane(3, 3, 4, 4));
    pc_hit_list hits = {0};
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 1);
    for (int k = 0; k < 5000; ++k) {
        /* Points on patch corners, on patch edges, anywhere. */
        double u = pc_test_rng_uniform(&rng, 0, 1), v = pc_test_rng_uniform(&rng, 0, 1);
        if (k % 3 == 0)
            u = floor(u * 5.0) / 4.0 > 1.0 ? 1.0 : floor(u * 5.0) / 4.0;
        if (k % 3 == 0 || k % 5 == 0)
            v = floor(v * 5.0) / 4.0 > 1.0 ? 1.0 : floor(v * 5.0) / 4.0;
        double d[3];
        random_direction(&rng, d);
        if (fabs(d[2]) < 0.05)
            d[2] = 0.05;
        const double lambda = pc_test_rng_uniform(&rng, -3, 3);
        const double o[3] = {2 * u - 1 - lambda * d[0], 3 * v - 1 - lambda * d[1], -lambda * d[2]};
        const size_t n = hits_of(s, o, d, 0, &hits);
        CHECK(n == 1);
        if (n != 1) {
            printf("  plane: (u, v) = (%.17g, %.17g) gave %zu hits\n", u, v, n);
            continue;
        }
        const pc_hit *h = &hits.items[0];
        CHECK_NEAR(h->u, u, 1e-13);
        CHECK_NEAR(h->v, v, 1e-13);
        CHECK_NEAR(h->lambda, lambda, 1e-13);
        const int on_edge = u == 0.0 || u == 1.0 || v == 0.0 || v == 1.0;
        CHECK(((h->flags & PROJCURVE_HIT_BOUNDARY) != 0) == on_edge);
        CHECK((h->flags & PROJCURVE_HIT_TANGENT) == 0);
    }
    /* Parallel above the plane: nothing. In the plane: it terminates. */
    const double above[3] = {-2, 0.1, 0.5}, along[3] = {1, 0.2, 0};
    CHECK(hits_of(s, above, along, 0, &hits) == 0);
    const double in_plane[3] = {-2, 0.1, 0.0};
    hits_of(s, in_plane, along, 0, &hits);
    for (size_t h = 0; h < hits.count; ++h)
        CHECK(hits.items[h].flags & PROJCURVE_HIT_TANGENT);
    pc_hit_list_free(&hits);
    projcurve_surface_destroy(s);
}

/* ---- sphere -------------------------------------------------------------------- */

static void test_sphere(void)
{
    const double c[3] = {0.3, -0.2, 0.1}, r = 1.5;
    projcurve_surface *s = make_surface(pc_shape_sphere(c, r));
    pc_hit_list hits = {0};
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 2);
    for (int k = 0; k < 10000; ++k) {
        double o[3], d[3];
        for (int i = 0; i < 3; ++i)
            o[i] = c[i] + pc_test_rng_uniform(&rng, -2.5, 2.5);
        random_direction(&rng, d);
        const int ray_only = k % 2;
        /* |o - c + l d|^2 = r^2: a l^2 + 2 b l + e = 0. */
        const double oc[3] = {o[0] - c[0], o[1] - c[1], o[2] - c[2]};
        const double a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        const double b = oc[0] * d[0] + oc[1] * d[1] + oc[2] * d[2];
        const double e = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - r * r;
        const double disc = b * b - a * e;
        double expected[2];
        size_t n_exp = 0;
        if (disc > 1e-6) { /* clear of tangency */
            const double q = -(b + copysign(sqrt(disc), b));
            double l1 = q / a, l2 = e / q;
            if (l1 > l2) {
                const double t = l1;
                l1 = l2;
                l2 = t;
            }
            if (!ray_only || l1 > 0)
                expected[n_exp++] = l1;
            if (!ray_only || l2 > 0)
                expected[n_exp++] = l2;
        } else if (disc > -1e-6) {
            continue; /* near-tangent lines are tested below */
        }
        const size_t n = hits_of(s, o, d, ray_only, &hits);
        CHECK(n == n_exp);
        if (n != n_exp) {
            printf("  sphere: o = (%.17g, %.17g, %.17g) d = (%.17g, %.17g, %.17g): %zu hits, "
                   "expected %zu\n", o[0], o[1], o[2], d[0], d[1], d[2], n, n_exp);
            continue;
        }
        for (size_t h = 0; h < n; ++h) {
            CHECK_NEAR(hits.items[h].lambda, expected[h], 1e-12 * (1.0 + fabs(expected[h])));
            CHECK((hits.items[h].flags & PROJCURVE_HIT_TANGENT) == 0 || disc < 1e-3);
        }
    }
    /* Tangent lines: through c + r n, along a direction perpendicular to n. */
    for (int k = 0; k < 500; ++k) {
        double n[3], t[3];
        random_direction(&rng, n);
        random_direction(&rng, t);
        const double nn = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int i = 0; i < 3; ++i)
            n[i] /= nn;
        const double tn = t[0] * n[0] + t[1] * n[1] + t[2] * n[2];
        for (int i = 0; i < 3; ++i)
            t[i] -= tn * n[i];
        const double tt = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
        if (tt < 1e-3)
            continue;
        for (int i = 0; i < 3; ++i)
            t[i] /= tt;
        const double p[3] = {c[0] + r * n[0], c[1] + r * n[1], c[2] + r * n[2]};
        const double o[3] = {p[0] - 1.7 * t[0], p[1] - 1.7 * t[1], p[2] - 1.7 * t[2]};
        const size_t count = hits_of(s, o, t, 0, &hits);
        CHECK(count == 1);
        if (count != 1) {
            printf("  sphere tangent at (%.17g, %.17g, %.17g) along (%.17g, %.17g, %.17g): %zu hits\n",
                   p[0], p[1], p[2], t[0], t[1], t[2], count);
            continue;
        }
        CHECK(hits.items[0].flags & PROJCURVE_HIT_TANGENT);
        /* A double root is determined to ~sqrt(eps) along the line. */
        CHECK_NEAR(hits.items[0].lambda, 1.7, 1e-6);
        if (fabs(hits.items[0].lambda - 1.7) > 1e-6)
            printf("  sphere tangent at (%.17g, %.17g, %.17g) along (%.17g, %.17g, %.17g): "
                   "(u, v) = (%.17g, %.17g)\n", p[0], p[1], p[2], t[0], t[1], t[2],
                   hits.items[0].u, hits.items[0].v);
    }
    /* Tangent lines at points of patch edges and corners (u = k / 4 are the
     * patch edges around the axis, v = 1/2 the equator), along the edge, across
     * it and oblique: one hit, flagged. */
    for (int k = 0; k < 240; ++k) {
        const double u = (k % 4) / 4.0 + (k % 3 == 0 ? 0.0 : pc_test_rng_uniform(&rng, 0.01, 0.24));
        const double v = k % 3 == 1 ? 0.5 : (k % 3 == 0 ? pc_test_rng_uniform(&rng, 0.1, 0.9) : 0.5);
        double f[9];
        CHECK_OK(projcurve_surface_eval(NULL, s, u, v, 1, f));
        const double a = (k % 5) * 0.25 * PI;
        double t[3] = {cos(a) * f[3] / hypot(hypot(f[3], f[4]), f[5]) + sin(a) * f[6] / hypot(hypot(f[6], f[7]), f[8]),
                       cos(a) * f[4] / hypot(hypot(f[3], f[4]), f[5]) + sin(a) * f[7] / hypot(hypot(f[6], f[7]), f[8]),
                       cos(a) * f[5] / hypot(hypot(f[3], f[4]), f[5]) + sin(a) * f[8] / hypot(hypot(f[6], f[7]), f[8])};
        const double tt = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
        for (int i = 0; i < 3; ++i)
            t[i] /= tt;
        const double o[3] = {f[0] - 1.3 * t[0], f[1] - 1.3 * t[1], f[2] - 1.3 * t[2]};
        const size_t count = hits_of(s, o, t, 0, &hits);
        /* u = 0 is the seam of the closed sphere: its two sides are one
         * contact, reported once (at either side: a grazing hit is known to
         * ~1e-7 only, so it may fall just inside either). */
        const int seam = u == 0.0;
        CHECK(count == 1);
        if (count != 1) {
            printf("  sphere tangent at edge point (u, v) = (%.17g, %.17g): %zu hits\n", u, v, count);
            continue;
        }
        CHECK(hits.items[0].flags & PROJCURVE_HIT_TANGENT);
        CHECK_NEAR(hits.items[0].lambda, 1.3, 1e-6);
        CHECK_NEAR(hits.items[0].v, v, 1e-6);
        if (seam)
            CHECK(hits.items[0].u < 1e-6 || hits.items[0].u > 1.0 - 1e-6);
        else
            CHECK_NEAR(hits.items[0].u, u, 1e-6);
    }
    /* Lines through the poles, where a whole patch edge collapses to one
     * point: the pole is one hit, and the line's other hit is found. */
    for (int k = 0; k < 400; ++k) {
        const double side = k % 2 ? 1.0 : -1.0;
        const double pole[3] = {c[0], c[1], c[2] + side * r};
        double d[3];
        random_direction(&rng, d);
        if (k % 50 == 0) { /* tangent at the pole */
            d[2] = 0.0;
        } else if (fabs(d[2]) < 0.05) {
            d[2] = 0.05;
        }
        const double o[3] = {pole[0] - 0.8 * d[0], pole[1] - 0.8 * d[1], pole[2] - 0.8 * d[2]};
        /* The other root of a l^2 + 2 b l + e = 0, e = 0 at the pole: l = 0.8 and
         * l = 0.8 - 2 b' / a with b' = (pole - c) . d. */
        const double a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        const double other = 0.8 - 2.0 * side * r * d[2] / a;
        const size_t n = hits_of(s, o, d, 0, &hits);
        const size_t n_exp = d[2] == 0.0 ? 1 : 2;
        CHECK(n == n_exp);
        if (n != n_exp) {
            printf("  sphere pole %+g along (%.17g, %.17g, %.17g): %zu hits\n", side, d[0], d[1],
                   d[2], n);
            continue;
        }
        int at_pole = 0, at_other = 0;
        for (size_t h = 0; h < n; ++h) {
            at_pole += fabs(hits.items[h].lambda - 0.8) < 1e-9;
            at_other += fabs(hits.items[h].lambda - other) < 1e-9;
            if (fabs(hits.items[h].lambda - 0.8) < 1e-9) {
                CHECK_NEAR(hits.items[h].v, side > 0 ? 1.0 : 0.0, 1e-12);
                CHECK(hits.items[h].flags & PROJCURVE_HIT_BOUNDARY);
                CHECK(((hits.items[h].flags & PROJCURVE_HIT_TANGENT) != 0) == (d[2] == 0.0));
            }
        }
        CHECK(at_pole == 1);
        CHECK(at_other == 1);
    }
    pc_hit_list_free(&hits);
    projcurve_surface_destroy(s);
}

/* A sphere far from the coordinates' origin: the tolerances follow the
 * coordinates' rounding (ulps of 6e4), not only the model's size. */
static void test_far_sphere(void)
{
    const double c[3] = {3e4, -5e4, 2e4}, r = 2.0;
    const double magnitude = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    projcurve_surface *s = make_surface(pc_shape_sphere(c, r));
    pc_hit_list hits = {0};
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 4);
    for (int k = 0; k < 2000; ++k) {
        double o[3], d[3];
        for (int i = 0; i < 3; ++i)
            o[i] = c[i] + pc_test_rng_uniform(&rng, -3, 3);
        random_direction(&rng, d);
        const double oc[3] = {o[0] - c[0], o[1] - c[1], o[2] - c[2]};
        const double a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        const double b = oc[0] * d[0] + oc[1] * d[1] + oc[2] * d[2];
        const double e = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - r * r;
        const double disc = b * b - a * e;
        if (fabs(disc) < 1e-3)
            continue;
        const size_t n = hits_of(s, o, d, 0, &hits);
        CHECK(n == (disc > 0 ? 2u : 0u));
        if (n == 2) {
            /* o is known to ~1 ulp of 6e4, so lambda to ~1e-11 / |d|. */
            const double q = -(b + copysign(sqrt(disc), b));
            const double l1 = fmin(q / a, e / q), l2 = fmax(q / a, e / q);
            CHECK_NEAR(hits.items[0].lambda, l1, 1e-14 * magnitude / sqrt(a));
            CHECK_NEAR(hits.items[1].lambda, l2, 1e-14 * magnitude / sqrt(a));
        }
    }
    /* Tangent lines: one hit, flagged. */
    for (int k = 0; k < 200; ++k) {
        double n[3], t[3];
        random_direction(&rng, n);
        random_direction(&rng, t);
        const double nn = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int i = 0; i < 3; ++i)
            n[i] /= nn;
        const double tn = t[0] * n[0] + t[1] * n[1] + t[2] * n[2];
        for (int i = 0; i < 3; ++i)
            t[i] -= tn * n[i];
        const double tt = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
        if (tt < 1e-3)
            continue;
        for (int i = 0; i < 3; ++i)
            t[i] /= tt;
        const double o[3] = {c[0] + r * n[0] - t[0], c[1] + r * n[1] - t[1], c[2] + r * n[2] - t[2]};
        const size_t count = hits_of(s, o, t, 0, &hits);
        CHECK(count == 1);
        if (count == 1) {
            CHECK(hits.items[0].flags & PROJCURVE_HIT_TANGENT);
            /* ~sqrt(rounding of 6e4 x the radius) along the line */
            CHECK_NEAR(hits.items[0].lambda, 1.0, 1e-4);
        } else {
            printf("  far sphere tangent along (%.17g, %.17g, %.17g): %zu hits\n", t[0], t[1], t[2],
                   count);
            for (size_t h = 0; h < count; ++h)
                printf("    u %.17g v %.17g lambda %.17g flags %u residual %.3g\n", hits.items[h].u,
                       hits.items[h].v, hits.items[h].lambda, hits.items[h].flags,
                       hits.items[h].residual);
        }
    }
    pc_hit_list_free(&hits);
    projcurve_surface_destroy(s);
}

/* A cone x^2 + y^2 = (1 - z)^2, z in [0, 1], as a revolved segment whose top
 * edge collapses to the apex (0, 0, 1): a line through the apex meets the
 * cone there only, once. A "surface" that is one point is met once too. */
static void test_cone_apex(void)
{
    static const double circle[9][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0},
                                        {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    static const double knots_u[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    static const double knots_v[4] = {0, 0, 1, 1};
    double ctrl[54], weights[18];
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 9; ++i) {
            double *p = ctrl + 3 * (j * 9 + i);
            p[0] = j == 0 ? circle[i][0] : 0.0;
            p[1] = j == 0 ? circle[i][1] : 0.0;
            p[2] = (double)j;
            weights[j * 9 + i] = i % 2 ? sqrt(0.5) : 1.0;
        }
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(NULL, 2, 1, 9, 2, ctrl, weights, knots_u, knots_v, &s));
    pc_hit_list hits = {0};
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 8);
    for (int k = 0; k < 300; ++k) {
        double d[3];
        random_direction(&rng, d);
        const double o[3] = {-1.3 * d[0], -1.3 * d[1], 1.0 - 1.3 * d[2]};
        const size_t n = hits_of(s, o, d, 0, &hits);
        /* |dz| = |d_xy| puts the line on the cone: keep clear of it. */
        if (fabs(fabs(d[2]) - hypot(d[0], d[1])) < 1e-3)
            continue;
        CHECK(n == 1);
        if (n == 1) {
            CHECK_NEAR(hits.items[0].lambda, 1.3, 1e-9);
            CHECK_NEAR(hits.items[0].v, 1.0, 1e-12);
            CHECK(hits.items[0].flags & PROJCURVE_HIT_BOUNDARY);
        } else {
            printf("  cone apex along (%.17g, %.17g, %.17g): %zu hits\n", d[0], d[1], d[2], n);
        }
    }
    projcurve_surface_destroy(s);
    /* Every control point the same: the surface is the point (1, 2, 3). */
    for (int k = 0; k < 18; ++k) {
        ctrl[3 * k] = 1.0;
        ctrl[3 * k + 1] = 2.0;
        ctrl[3 * k + 2] = 3.0;
    }
    if (projcurve_surface_create_nurbs(NULL, 2, 1, 9, 2, ctrl, weights, knots_u, knots_v, &s) ==
        PROJCURVE_OK) {
        const double o[3] = {0, 0, 0}, d[3] = {1, 2, 3}, away[3] = {1, 2, 3.5};
        CHECK(hits_of(s, o, d, 0, &hits) == 1);
        if (hits.count == 1)
            CHECK_NEAR(hits.items[0].lambda, 1.0, 1e-12);
        CHECK(hits_of(s, away, d, 0, &hits) == 0);
        projcurve_surface_destroy(s);
    }
    pc_hit_list_free(&hits);
}

/* ---- torus ------------------------------------------------------------------------ */

static double torus_residual(const double p[3], double big_r, double small_r)
{
    return hypot(hypot(p[0], p[1]) - big_r, p[2]) - small_r;
}

static void test_torus(void)
{
    const double big_r = 2.0, small_r = 0.5;
    projcurve_surface *s = make_surface(pc_shape_torus(big_r, small_r));
    pc_hit_list hits = {0};
    /* Lines parallel to x at height z and offset y meet the torus where
     * sqrt(x^2 + y^2) = R -+ sqrt(r^2 - z^2) = rho_in, rho_out: four hits
     * x = -+sqrt(rho^2 - y^2), or two when |y| > rho_in (the line passes
     * beside the hole). The origin is at x = -5, so lambda = x + 5. */
    const double offsets[][2] = {{0.3, 0.2}, {-0.7, 0.1}, {0.05, -0.45}, {1.2, 0.3}, {1.9, 0.2}};
    for (size_t k = 0; k < sizeof offsets / sizeof offsets[0]; ++k) {
        const double y = offsets[k][0], z = offsets[k][1];
        const double o[3] = {-5, y, z}, d[3] = {1, 0, 0};
        const double w = sqrt(small_r * small_r - z * z);
        const double x_out = sqrt((big_r + w) * (big_r + w) - y * y);
        const double x_in = (big_r - w) * (big_r - w) > y * y ? sqrt((big_r - w) * (big_r - w) - y * y) : NAN;
        double expected[4];
        size_t n_exp = 0;
        expected[n_exp++] = 5.0 - x_out;
        if (!isnan(x_in)) {
            expected[n_exp++] = 5.0 - x_in;
            expected[n_exp++] = 5.0 + x_in;
        }
        expected[n_exp++] = 5.0 + x_out;
        const size_t n = hits_of(s, o, d, 0, &hits);
        CHECK(n == n_exp);
        for (size_t h = 0; h < n && h < n_exp; ++h)
            CHECK_NEAR(hits.items[h].lambda, expected[h], 1e-12);
    }
    /* Random lines: every hit on the torus. */
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 3);
    long total = 0;
    for (int k = 0; k < 8000; ++k) {
        double o[3], d[3];
        random_line(&rng, s, o, d);
        hits_of(s, o, d, 0, &hits);
        total += (long)hits.count;
        for (size_t h = 0; h < hits.count; ++h) {
            const double p[3] = {o[0] + hits.items[h].lambda * d[0], o[1] + hits.items[h].lambda * d[1],
                                 o[2] + hits.items[h].lambda * d[2]};
            CHECK_NEAR(torus_residual(p, big_r, small_r), 0.0, 1e-12);
            double q[3];
            CHECK_OK(projcurve_surface_eval(NULL, s, hits.items[h].u, hits.items[h].v, 0, q));
            CHECK_NEAR(q[0], p[0], 1e-12);
            CHECK_NEAR(q[1], p[1], 1e-12);
            CHECK_NEAR(q[2], p[2], 1e-12);
        }
    }
    CHECK(total > 4000);
    compare_random_lines(s, "torus", 6000, 96, 31);
    pc_hit_list_free(&hits);
    projcurve_surface_destroy(s);
}

/* A closed surface's seams: the torus is closed in u (around the axis, u = 0
 * and u = 1 on the half-plane y = 0, x > 0) and in v (around the tube, v = 0
 * and v = 1 on the outer equator). A seam crossing is one point of space
 * and is reported once, at the domain's start (u = 0 or v = 0), flagged
 * boundary. The x axis crosses the torus at x = -2.5 (v seam), -1.5 (no
 * seam), 1.5 (u seam) and 2.5 (both seams: four parameter pairs). */
static void test_torus_seams(void)
{
    const double big_r = 2.0, small_r = 0.5;
    projcurve_surface *s = make_surface(pc_shape_torus(big_r, small_r));
    pc_hit_list hits = {0};
    /* The parametrisation the expectations rely on. */
    const double corners[4][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    for (int k = 0; k < 4; ++k) {
        double f[3];
        CHECK_OK(projcurve_surface_eval(NULL, s, corners[k][0], corners[k][1], 0, f));
        CHECK_NEAR(f[0], big_r + small_r, 1e-15);
        CHECK_NEAR(f[1], 0.0, 1e-15);
        CHECK_NEAR(f[2], 0.0, 1e-15);
    }
    /* Both directions, so that the patches are visited in either order. */
    for (int sense = -1; sense <= 1; sense += 2) {
        const double o[3] = {-5.0 * sense, 0, 0}, d[3] = {sense, 0, 0};
        const size_t n = hits_of(s, o, d, 1, &hits);
        ++pc_test_checks;
        if (n != 4) {
            pc_test_fail_at(__FILE__, __LINE__, "x axis (sense %d) meets the torus %zu times, "
                            "expected 4", sense, n);
            for (size_t h = 0; h < n; ++h)
                printf("    u %.17g v %.17g lambda %.17g flags %u\n", hits.items[h].u,
                       hits.items[h].v, hits.items[h].lambda, hits.items[h].flags);
            continue;
        }
        /* x = -5 sense + lambda sense at lambda = 2.5, 3.5, 6.5, 7.5. */
        const double lambda[4] = {2.5, 3.5, 6.5, 7.5};
        for (int h = 0; h < 4; ++h) {
            const double x = sense * (lambda[h] - 5.0);
            /* (u, v) kept: u = 1/2 on the far side, v = 1/2 on the inner equator. */
            const double u = x > 0 ? 0.0 : 0.5, v = fabs(x) > big_r ? 0.0 : 0.5;
            const pc_hit *hit = &hits.items[h];
            CHECK_NEAR(hit->lambda, lambda[h], 1e-14);
            CHECK_NEAR(hit->u, u, 1e-14);
            CHECK_NEAR(hit->v, v, 1e-14);
            CHECK(((hit->flags & PROJCURVE_HIT_BOUNDARY) != 0) == (u == 0.0 || v == 0.0));
            CHECK(!(hit->flags & PROJCURVE_HIT_TANGENT));
        }
    }
    /* Random transversal lines through points of either seam: one hit
     * there, at u = 0 (or v = 0), flagged boundary. */
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 5);
    for (int k = 0; k < 2000; ++k) {
        const int u_seam = k % 2 == 0;
        const double a = pc_test_rng_uniform(&rng, 0, 1);
        double f[9], d[3];
        CHECK_OK(projcurve_surface_eval(NULL, s, u_seam ? 0.0 : a, u_seam ? a : 0.0, 1, f));
        random_direction(&rng, d);
        const double n[3] = {f[4] * f[8] - f[5] * f[7], f[5] * f[6] - f[3] * f[8],
                             f[3] * f[7] - f[4] * f[6]};
        const double cos_dir = fabs(n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) /
                               (sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) *
                                sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
        if (cos_dir < 0.05)
            continue; /* transversal lines only */
        const double o[3] = {f[0] - 1.1 * d[0], f[1] - 1.1 * d[1], f[2] - 1.1 * d[2]};
        hits_of(s, o, d, 0, &hits);
        int at_point = 0;
        for (size_t h = 0; h < hits.count; ++h) {
            const pc_hit *hit = &hits.items[h];
            if (fabs(hit->lambda - 1.1) > 1e-9)
                continue;
            ++at_point;
            CHECK_NEAR(u_seam ? hit->u : hit->v, 0.0, 1e-12);
            CHECK_NEAR(u_seam ? hit->v : hit->u, a, 1e-9);
            CHECK(hit->flags & PROJCURVE_HIT_BOUNDARY);
        }
        ++pc_test_checks;
        if (at_point != 1)
            pc_test_fail_at(__FILE__, __LINE__, "%s seam point at %.17g reported %d times along "
                            "(%.17g, %.17g, %.17g)", u_seam ? "u" : "v", a, at_point, d[0], d[1],
                            d[2]);
    }
    pc_hit_list_free(&hits);
    projcurve_surface_destroy(s);
}

/* ---- bumpy and folded surfaces ------------------------------------------------------ */

/* Lines through interior patch corners (four patches meet) and points of
 * interior patch edges of a curved rational surface: that hit once, at
 * its parameters, not flagged boundary. */
static void test_curved_corners(void)
{
    projcurve_surface *s = make_surface(pc_shape_bumpy(23, 6, 6, 0.3, 1));
    pc_hit_list hits = {0};
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 24);
    for (int k = 0; k < 1000; ++k) {
        const double u = (1 + k % 5) / 6.0;
        const double v = k % 2 ? (1 + (k / 5) % 5) / 6.0 : pc_test_rng_uniform(&rng, 0.05, 0.95);
        double f[9], d[3];
        CHECK_OK(projcurve_surface_eval(NULL, s, u, v, 0, f));
        random_direction(&rng, d);
        const double o[3] = {f[0] - 0.9 * d[0], f[1] - 0.9 * d[1], f[2] - 0.9 * d[2]};
        hits_of(s, o, d, 0, &hits);
        int at_point = 0;
        for (size_t h = 0; h < hits.count; ++h) {
            if (fabs(hits.items[h].u - u) < 1e-6 && fabs(hits.items[h].v - v) < 1e-6) {
                ++at_point;
                CHECK_NEAR(hits.items[h].lambda, 0.9, 1e-9);
                CHECK(!(hits.items[h].flags & PROJCURVE_HIT_BOUNDARY));
            }
        }
        ++pc_test_checks;
        if (at_point != 1)
            pc_test_fail_at(__FILE__, __LINE__, "patch corner/edge point (%.17g, %.17g) reported %d times",
                            u, v, at_point);
    }
    pc_hit_list_free(&hits);
    projcurve_surface_destroy(s);
}

static void test_bumpy(void)
{
    projcurve_surface *s = make_surface(pc_shape_bumpy(17, 8, 8, 0.3, 0));
    compare_random_lines(s, "bumpy 8x8", 9000, 128, 41);
    projcurve_surface_destroy(s);
    s = make_surface(pc_shape_bumpy(18, 6, 9, 0.5, 1));
    compare_random_lines(s, "rational bumpy 6x9", 9000, 128, 42);
    projcurve_surface_destroy(s);
}

/* A bicubic B-spline whose x oscillates faster than u advances (so the
 * surface folds over itself in x) over a wavy height: lines meet it many
 * times, and nearly tangent lines are common. */
static projcurve_surface *make_folded(size_t n, double fold)
{
    pc_shape_surface shape = {3, 3, n, n, NULL, NULL, NULL, NULL};
    shape.ctrl = malloc(sizeof(double) * 3 * n * n);
    shape.knots_u = malloc(sizeof(double) * (n + 4));
    shape.knots_v = malloc(sizeof(double) * (n + 4));
    pc_shape_uniform_knots(3, n, shape.knots_u);
    pc_shape_uniform_knots(3, n, shape.knots_v);
    for (size_t j = 0; j < n; ++j)
        for (size_t i = 0; i < n; ++i) {
            const double a = (double)i / (double)(n - 1), b = (double)j / (double)(n - 1);
            double *p = shape.ctrl + 3 * (j * n + i);
            p[0] = a + fold * sin(3.0 * PI * a + b);
            p[1] = b + 0.1 * sin(2.0 * PI * a);
            p[2] = 0.3 * sin(2.0 * PI * a + 1.0) * cos(PI * b) + 0.2 * a * b;
        }
    return make_surface(shape);
}

/* A curl: a spiral in the x-z plane swept along y, so that lines through it
 * cross several turns. */
static projcurve_surface *make_curl(size_t n)
{
    pc_shape_surface shape = {3, 2, n, 4, NULL, NULL, NULL, NULL};
    shape.ctrl = malloc(sizeof(double) * 3 * n * 4);
    shape.knots_u = malloc(sizeof(double) * (n + 4));
    shape.knots_v = malloc(sizeof(double) * 7);
    pc_shape_uniform_knots(3, n, shape.knots_u);
    pc_shape_uniform_knots(2, 4, shape.knots_v);
    for (size_t j = 0; j < 4; ++j)
        for (size_t i = 0; i < n; ++i) {
            const double a = (double)i / (double)(n - 1), b = (double)j / 3.0;
            const double angle = 3.5 * PI * a, radius = 0.3 + a;
            double *p = shape.ctrl + 3 * (j * n + i);
            p[0] = radius * cos(angle) + 0.1 * b * b;
            p[1] = 2.0 * b;
            p[2] = radius * sin(angle) + 0.2 * sin(3.0 * b);
        }
    return make_surface(shape);
}

static void test_folded(void)
{
    projcurve_surface *s = make_folded(12, 0.25);
    compare_random_lines(s, "folded 9x9 patches", 8000, 160, 51);
    projcurve_surface_destroy(s);
    s = make_curl(24);
    compare_random_lines(s, "curl 21x2 patches", 8000, 192, 52);
    projcurve_surface_destroy(s);
}

/* ---- the patch-restricted form ---------------------------------------------------- */

/* Given every patch, pc_intersect_line_patches finds what pc_intersect_line
 * finds; given a repeated index, the copies are merged. */
static void test_patch_subset(void)
{
    projcurve_surface *s = make_surface(pc_shape_bumpy(5, 4, 4, 0.3, 1));
    const size_t n_patches = s->grid.spans_u * s->grid.spans_v;
    size_t *all = malloc(sizeof *all * (2 * n_patches));
    for (size_t k = 0; k < 2 * n_patches; ++k)
        all[k] = k % n_patches;
    pc_hit_list a = {0}, b = {0};
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 61);
    for (int k = 0; k < 2000; ++k) {
        double o[3], d[3];
        random_line(&rng, s, o, d);
        hits_of(s, o, d, k % 2, &a);
        CHECK_OK(pc_intersect_line_patches(NULL, s, all, 2 * n_patches, vec3_load(o), vec3_load(d),
                                           k % 2, &b));
        CHECK(a.count == b.count);
        for (size_t h = 0; h < a.count && h < b.count; ++h) {
            CHECK(a.items[h].u == b.items[h].u);
            CHECK(a.items[h].v == b.items[h].v);
            CHECK(a.items[h].lambda == b.items[h].lambda);
            CHECK(a.items[h].flags == b.items[h].flags);
        }
    }
    free(all);
    pc_hit_list_free(&a);
    pc_hit_list_free(&b);
    projcurve_surface_destroy(s);
}

int main(void)
{
    test_bad_input();
    test_plane();
    test_sphere();
    test_far_sphere();
    test_cone_apex();
    test_torus();
    test_torus_seams();
    test_curved_corners();
    test_bumpy();
    test_folded();
    test_patch_subset();
    return pc_test_finish("test_intersect");
}
