/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Bezier clipping of one line against hand-built Bezier patches
 * (pc_ray_patch_hits), before any surface machinery: a plane with a
 * non-uniform parametrisation (answers known), a folded bicubic and an
 * exact rational torus patch compared with the brute-force oracle (dense
 * triangulation + Newton, tests/support/ray_oracle.c), a patch split in two
 * (hits on the shared edge and corners reported once), and grazing lines
 * tangent to the torus (reported once, flagged).
 */
#include "check.h"
#include "intersect/bezier_clip.h"
#include "intersect/frame_net.h"
#include "intersect/intersect.h"
#include "intersect/ray_patch.h"
#include "ray_oracle.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define MAX_NET 64

typedef struct test_patch {
    pc_bezier_patch patch;
    double cw[4 * MAX_NET];
} test_patch;

/* ---- an independent evaluator: explicit Bernstein polynomials ---------- */

static double binomial(int n, int k)
{
    if (k < 0 || k > n || n > PROJCURVE_MAX_DEGREE)
        return 0.0;
    double r = 1.0;
    for (int i = 1; i <= k; ++i)
        r = r * (n - k + i) / i;
    return r;
}

static double bernstein(int n, int i, double x)
{
    if (i < 0 || i > n)
        return 0.0;
    return binomial(n, i) * pow(x, i) * pow(1.0 - x, n - i);
}

static double bernstein_d(int n, int i, double x)
{
    return n * (bernstein(n - 1, i - 1, x) - bernstein(n - 1, i, x));
}

/* S, Su, Sv of the patch at surface parameters (u, v) (all of them
 * whatever n_deriv: the patches are small). */
static void eval_patch(void *user, double u, double v, int n_deriv, double out[9])
{
    (void)n_deriv;
    const pc_bezier_patch *p = user;
    const double hu = p->u1 - p->u0, hv = p->v1 - p->v0;
    const double s = (u - p->u0) / hu, t = (v - p->v0) / hv;
    double a[4] = {0}, as[4] = {0}, at[4] = {0};
    for (int j = 0; j <= p->deg_v; ++j) {
        for (int i = 0; i <= p->deg_u; ++i) {
            const double *q = p->cw + 4 * (j * (p->deg_u + 1) + i);
            const double b = bernstein(p->deg_u, i, s) * bernstein(p->deg_v, j, t);
            const double bs = bernstein_d(p->deg_u, i, s) * bernstein(p->deg_v, j, t) / hu;
            const double bt = bernstein(p->deg_u, i, s) * bernstein_d(p->deg_v, j, t) / hv;
            for (int c = 0; c < 4; ++c) {
                a[c] += b * q[c];
                as[c] += bs * q[c];
                at[c] += bt * q[c];
            }
        }
    }
    for (int c = 0; c < 3; ++c) {
        out[c] = a[c] / a[3];
        out[3 + c] = (as[c] - as[3] * out[c]) / a[3];
        out[6 + c] = (at[c] - at[3] * out[c]) / a[3];
    }
}

static void patch_init(test_patch *tp, int deg_u, int deg_v, double u0, double u1, double v0,
                       double v1)
{
    memset(tp, 0, sizeof *tp);
    tp->patch.deg_u = deg_u;
    tp->patch.deg_v = deg_v;
    tp->patch.u0 = u0;
    tp->patch.u1 = u1;
    tp->patch.v0 = v0;
    tp->patch.v1 = v1;
    tp->patch.cw = tp->cw;
}

static void set_point(test_patch *tp, int i, int j, double x, double y, double z, double w)
{
    double *q = tp->cw + 4 * (j * (tp->patch.deg_u + 1) + i);
    q[0] = w * x;
    q[1] = w * y;
    q[2] = w * z;
    q[3] = w;
}

static void finish_box(test_patch *tp)
{
    const int np = (tp->patch.deg_u + 1) * (tp->patch.deg_v + 1);
    box_empty(tp->patch.box);
    for (int k = 0; k < np; ++k) {
        const double *q = tp->cw + 4 * k;
        const double p[3] = {q[0] / q[3], q[1] / q[3], q[2] / q[3]};
        box_add_point(tp->patch.box, p);
    }
}

/* ---- running the library on a set of patches ---------------------------- */

static double g_work[1 << 16];

static size_t line_hits(const test_patch *const *patches, int n_patches, const double o[3],
                        const double d[3], int ray_only, pc_hit_list *hits)
{
    double domain[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY};
    double box[6];
    box_empty(box);
    for (int k = 0; k < n_patches; ++k) {
        const pc_bezier_patch *p = &patches[k]->patch;
        domain[0] = fmin(domain[0], p->u0);
        domain[1] = fmax(domain[1], p->u1);
        domain[2] = fmin(domain[2], p->v0);
        domain[3] = fmax(domain[3], p->v1);
        box_add_box(box, p->box);
    }
    const double scale = box_diagonal(box);
    pc_ray_frame frame;
    pc_ray_frame_init(&frame, vec3_load(o), vec3_load(d), scale, vec3_norm(vec3_load(o)) + scale,
                      ray_only);
    hits->count = 0;
    CHECK(pc_ray_patch_work_size(patches[0]->patch.deg_u, patches[0]->patch.deg_v) <=
          sizeof g_work / sizeof g_work[0]);
    for (int k = 0; k < n_patches; ++k)
        CHECK_OK(pc_ray_patch_hits(NULL, &frame, &patches[k]->patch, g_work, hits));
    pc_hit_list_finish(hits, domain, vec3_norm(vec3_load(d)), scale, frame.tol_residual, NULL);
    return hits->count;
}

/* ---- plane ------------------------------------------------------------- */

/* z = 0, x and y bicubic in (u, v) with moved interior points: the hit of a
 * line is where it crosses z = 0, and (u, v) must map there. */
static void test_plane(void)
{
    test_patch tp;
    patch_init(&tp, 3, 3, 0.0, 1.0, 0.0, 1.0);
    for (int j = 0; j <= 3; ++j)
        for (int i = 0; i <= 3; ++i) {
            const double shift = (i == 1 || i == 2) && (j == 1 || j == 2) ? 0.1 : 0.0;
            set_point(&tp, i, j, i / 3.0 + shift, j / 3.0 - shift, 0.0, 1.0);
        }
    finish_box(&tp);
    const test_patch *patches[1] = {&tp};
    pc_hit_list hits = {0};
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 11);
    for (int k = 0; k < 2000; ++k) {
        /* A point of the surface, and a line through it. */
        const double u = pc_test_rng_uniform(&rng, 0, 1), v = pc_test_rng_uniform(&rng, 0, 1);
        double f[9];
        eval_patch(&tp.patch, u, v, 1, f);
        const double d[3] = {pc_test_rng_uniform(&rng, -1, 1), pc_test_rng_uniform(&rng, -1, 1),
                             pc_test_rng_uniform(&rng, 0.05, 1)};
        const double lambda = pc_test_rng_uniform(&rng, -2, 2);
        const double o[3] = {f[0] - lambda * d[0], f[1] - lambda * d[1], f[2] - lambda * d[2]};
        const size_t n = line_hits(patches, 1, o, d, 0, &hits);
        CHECK(n == 1);
        if (n != 1)
            continue;
        CHECK_NEAR(hits.items[0].u, u, 1e-12);
        CHECK_NEAR(hits.items[0].v, v, 1e-12);
        CHECK_NEAR(hits.items[0].lambda, lambda, 1e-12);
        CHECK((hits.items[0].flags & PROJCURVE_HIT_TANGENT) == 0);
        /* The ray form drops what lies behind the origin. */
        CHECK(line_hits(patches, 1, o, d, 1, &hits) == (lambda > 0.0 ? 1u : 0u));
    }
    /* Corners and edges of the domain: found once, flagged. */
    const double corners[][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {0.5, 0}, {1, 0.25}, {0.3, 1}};
    for (size_t k = 0; k < sizeof corners / sizeof corners[0]; ++k) {
        double f[9];
        eval_patch(&tp.patch, corners[k][0], corners[k][1], 1, f);
        const double d[3] = {0.3, -0.2, 1.0};
        const double o[3] = {f[0] - d[0], f[1] - d[1], f[2] - d[2]};
        CHECK(line_hits(patches, 1, o, d, 0, &hits) == 1);
        if (hits.count == 1) {
            CHECK_NEAR(hits.items[0].u, corners[k][0], 1e-12);
            CHECK_NEAR(hits.items[0].v, corners[k][1], 1e-12);
            CHECK(hits.items[0].flags & PROJCURVE_HIT_BOUNDARY);
        }
    }
    /* Lines that miss: beside the patch, and parallel to its plane. */
    const double o_miss[3] = {2.0, 2.0, 1.0}, d_down[3] = {0, 0, -1};
    CHECK(line_hits(patches, 1, o_miss, d_down, 0, &hits) == 0);
    const double o_par[3] = {-1.0, 0.5, 0.5}, d_par[3] = {1, 0, 0};
    CHECK(line_hits(patches, 1, o_par, d_par, 0, &hits) == 0);
    pc_hit_list_free(&hits);
}

/* ---- comparison with the oracle ------------------------------------------ */

/* Every oracle hit found once; every library hit real, distinct, and either
 * an oracle hit or a grazing one the mesh could not see. */
static void compare_line(const pc_oracle_mesh *mesh, const test_patch *const *patches,
                         int n_patches, const double o[3], const double d[3], int ray_only,
                         pc_oracle_stats *st)
{
    pc_hit_list hits = {0};
    const size_t n = line_hits(patches, n_patches, o, d, ray_only, &hits);
    double uvl[3 * 64];
    unsigned flags[64];
    CHECK(n <= 64);
    for (size_t k = 0; k < n && k < 64; ++k) {
        uvl[3 * k] = hits.items[k].u;
        uvl[3 * k + 1] = hits.items[k].v;
        uvl[3 * k + 2] = hits.items[k].lambda;
        flags[k] = hits.items[k].flags;
    }
    pc_oracle_compare(mesh, o, d, ray_only, n < 64 ? n : 64, uvl, flags, st);
    pc_hit_list_free(&hits);
}

/* A random line through the box (scaled up by `grow`), in a random direction. */
static void random_line(pc_test_rng *rng, const double box[6], double grow, double o[3], double d[3])
{
    for (int k = 0; k < 3; ++k) {
        const double c = 0.5 * (box[k] + box[k + 3]), h = 0.5 * grow * (box[k + 3] - box[k]) + 1e-3;
        o[k] = pc_test_rng_uniform(rng, c - h, c + h);
    }
    double n2;
    do {
        for (int k = 0; k < 3; ++k)
            d[k] = pc_test_rng_uniform(rng, -1, 1);
        n2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    } while (n2 > 1.0 || n2 < 1e-4);
}

/* A bicubic whose interior points are pulled across each other, so that the
 * patch folds over itself and a line can meet it several times. */
static void build_folded(test_patch *tp, pc_test_rng *rng)
{
    patch_init(tp, 3, 3, 2.0, 5.0, -1.0, 1.0);
    for (int j = 0; j <= 3; ++j)
        for (int i = 0; i <= 3; ++i) {
            const double fold = (i == 1 || i == 2) ? (i == 1 ? 1.2 : -1.2) : 0.0;
            set_point(tp, i, j, i / 3.0 + fold + pc_test_rng_uniform(rng, -0.1, 0.1),
                      j / 3.0 + pc_test_rng_uniform(rng, -0.1, 0.1),
                      pc_test_rng_uniform(rng, -0.6, 0.6), 1.0);
        }
    finish_box(tp);
}

/* Exact torus patch (R = 2, r = 1): quarter tube circle x quarter turn. */
static void build_torus(test_patch *tp, double big_r, double small_r)
{
    const double h = sqrt(0.5);
    const double rho[3] = {big_r + small_r, big_r + small_r, big_r};
    const double z[3] = {0.0, small_r, small_r};
    const double turn[3][2] = {{1, 0}, {1, 1}, {0, 1}};
    const double w[3] = {1.0, h, 1.0};
    patch_init(tp, 2, 2, 0.0, 1.0, 0.0, 1.0);
    for (int j = 0; j <= 2; ++j)
        for (int i = 0; i <= 2; ++i)
            set_point(tp, i, j, rho[i] * turn[j][0], rho[i] * turn[j][1], z[i], w[i] * w[j]);
    finish_box(tp);
}

static void test_against_oracle(const test_patch *tp, const char *name, int n_rays,
                                unsigned long long seed)
{
    pc_oracle_mesh mesh;
    const double domain[4] = {tp->patch.u0, tp->patch.u1, tp->patch.v0, tp->patch.v1};
    CHECK(pc_oracle_mesh_build(&mesh, eval_patch, (void *)&tp->patch, domain, 96, 96));
    const test_patch *patches[1] = {tp};
    pc_test_rng rng;
    pc_test_rng_seed(&rng, seed);
    pc_oracle_stats st = {0};
    for (int k = 0; k < n_rays; ++k) {
        double o[3], d[3];
        random_line(&rng, tp->patch.box, 1.2, o, d);
        compare_line(&mesh, patches, 1, o, d, k % 4 == 0, &st);
    }
    printf("%s: %ld lines, %ld hits (oracle %ld), %ld grazing hits the mesh missed\n", name,
           st.lines, st.hits, st.oracle_hits, st.grazing_extra);
    pc_oracle_mesh_free(&mesh);
}

/* Every hit of a line on the torus satisfies its implicit equation. */
static void test_torus_equation(const test_patch *tp)
{
    const test_patch *patches[1] = {tp};
    pc_hit_list hits = {0};
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 5);
    for (int k = 0; k < 2000; ++k) {
        double o[3], d[3];
        random_line(&rng, tp->patch.box, 1.0, o, d);
        line_hits(patches, 1, o, d, 0, &hits);
        for (size_t h = 0; h < hits.count; ++h) {
            double p[3];
            for (int c = 0; c < 3; ++c)
                p[c] = o[c] + hits.items[h].lambda * d[c];
            const double rho = hypot(p[0], p[1]);
            /* (rho - R)^2 + z^2 = r^2 */
            CHECK_NEAR(hypot(rho - 2.0, p[2]), 1.0, 1e-12);
        }
    }
    pc_hit_list_free(&hits);
}

/* ---- shared edges and corners ------------------------------------------- */

/* Splits a patch at local s = 0.5 in u (homogeneous de Casteljau). */
static void split_u(const test_patch *src, test_patch *lo, test_patch *hi)
{
    const pc_bezier_patch *p = &src->patch;
    const double mid = 0.5 * (p->u0 + p->u1);
    patch_init(lo, p->deg_u, p->deg_v, p->u0, mid, p->v0, p->v1);
    patch_init(hi, p->deg_u, p->deg_v, mid, p->u1, p->v0, p->v1);
    const int m = p->deg_u;
    for (int j = 0; j <= p->deg_v; ++j) {
        double tri[MAX_NET][4];
        for (int i = 0; i <= m; ++i)
            memcpy(tri[i], p->cw + 4 * (j * (m + 1) + i), sizeof tri[i]);
        for (int r = 0; r <= m; ++r) {
            memcpy(lo->cw + 4 * (j * (m + 1) + r), tri[0], sizeof tri[0]);
            memcpy(hi->cw + 4 * (j * (m + 1) + (m - r)), tri[m - r], sizeof tri[0]);
            for (int i = 0; i < m - r; ++i)
                for (int c = 0; c < 4; ++c)
                    tri[i][c] = 0.5 * (tri[i][c] + tri[i + 1][c]);
        }
    }
    finish_box(lo);
    finish_box(hi);
}

static void test_shared_edge(const test_patch *tp)
{
    test_patch lo, hi;
    split_u(tp, &lo, &hi);
    const test_patch *halves[2] = {&lo, &hi};
    pc_hit_list hits = {0};
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 21);
    const double mid = 0.5 * (tp->patch.u0 + tp->patch.u1);
    for (int k = 0; k < 500; ++k) {
        /* A line through a point of the shared edge (corners included). */
        const double v = k < 2 ? (double)k : pc_test_rng_uniform(&rng, 0.0, 1.0);
        double f[9];
        eval_patch((void *)&tp->patch, mid, v, 1, f);
        double n[3];
        n[0] = f[4] * f[8] - f[5] * f[7];
        n[1] = f[5] * f[6] - f[3] * f[8];
        n[2] = f[3] * f[7] - f[4] * f[6];
        /* Along the normal, tilted: transversal. */
        const double d[3] = {n[0] + 0.3 * f[3], n[1] + 0.3 * f[4], n[2] + 0.3 * f[5]};
        const double o[3] = {f[0] - 0.7 * d[0], f[1] - 0.7 * d[1], f[2] - 0.7 * d[2]};
        line_hits(halves, 2, o, d, 0, &hits);
        int at_point = 0;
        for (size_t h = 0; h < hits.count; ++h)
            at_point += fabs(hits.items[h].u - mid) < 1e-9 && fabs(hits.items[h].v - v) < 1e-9;
        if (at_point != 1)
            pc_test_fail_at(__FILE__, __LINE__, "edge point v = %.17g reported %d times", v,
                            at_point);
        ++pc_test_checks;
    }
    pc_hit_list_free(&hits);
}

/* ---- grazing lines -------------------------------------------------------- */

/* Lines tangent to the torus at points of its outer half (both curvatures
 * of one sign: the line touches and stays outside nearby): one hit there,
 * flagged tangent. */
static void test_tangent(const test_patch *tp)
{
    const test_patch *patches[1] = {tp};
    pc_hit_list hits = {0};
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 99);
    for (int k = 0; k < 200; ++k) {
        const double u = pc_test_rng_uniform(&rng, 0.05, 0.6), v = pc_test_rng_uniform(&rng, 0.05, 0.95);
        double f[9];
        eval_patch((void *)&tp->patch, u, v, 1, f);
        const double a = pc_test_rng_uniform(&rng, 0.0, 6.283185307179586);
        const double d[3] = {cos(a) * f[3] + sin(a) * f[6], cos(a) * f[4] + sin(a) * f[7],
                             cos(a) * f[5] + sin(a) * f[8]};
        const double o[3] = {f[0] - 2.0 * d[0], f[1] - 2.0 * d[1], f[2] - 2.0 * d[2]};
        line_hits(patches, 1, o, d, 0, &hits);
        int at_point = 0;
        for (size_t h = 0; h < hits.count; ++h) {
            if (fabs(hits.items[h].lambda - 2.0) < 1e-5) {
                ++at_point;
                CHECK(hits.items[h].flags & PROJCURVE_HIT_TANGENT);
                CHECK_NEAR(hits.items[h].u, u, 1e-5);
                CHECK_NEAR(hits.items[h].v, v, 1e-5);
            }
        }
        if (at_point != 1)
            pc_test_fail_at(__FILE__, __LINE__, "tangent point (%.17g, %.17g) reported %d times",
                            u, v, at_point);
        ++pc_test_checks;
    }
    pc_hit_list_free(&hits);
}

/* ---- building blocks ---------------------------------------------------- */

/* A planar net of Q(s, t) = A (s - s0, t - t0) (affine, one root at
 * (s0, t0)) written as a degree-(m, n) Bezier net by linear precision:
 * clipping is exact for it, so one round must shrink the box around the
 * root to the padding, and further rounds converge. */
static void test_clip_affine(void)
{
    const double a[4] = {1.0, 0.4, -0.3, 0.8}, s0 = 0.37, t0 = 0.61;
    for (int m = 1; m <= 5; m += 2) {
        const int n = m + 1;
        double net[2 * 6 * 7];
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= m; ++i) {
                const double s = (double)i / m - s0, t = (double)j / n - t0;
                net[2 * (j * (m + 1) + i)] = a[0] * s + a[1] * t;
                net[2 * (j * (m + 1) + i) + 1] = a[2] * s + a[3] * t;
            }
        double box[4] = {0, 1, 0, 1};
        pc_clip_outcome out = pc_bezier_clip_step(net, m, n, 0.0, box);
        CHECK(out == PC_CLIP_PROGRESS || out == PC_CLIP_CONVERGED);
        CHECK(box[0] <= s0 && s0 <= box[1] && box[2] <= t0 && t0 <= box[3]);
        CHECK(box[1] - box[0] < 1e-5 && box[3] - box[2] < 1e-5);
        for (int k = 0; k < 4 && out == PC_CLIP_PROGRESS; ++k)
            out = pc_bezier_clip_step(net, m, n, 0.0, box);
        CHECK(out == PC_CLIP_CONVERGED);
        CHECK(box[0] <= s0 && s0 <= box[1] && box[2] <= t0 && t0 <= box[3]);
        /* Shifted away from the origin: no root, the box empties. */
        double box2[4] = {0, 1, 0, 1};
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= m; ++i) {
                const double s = (double)i / m - s0, t = (double)j / n - t0;
                net[2 * (j * (m + 1) + i)] = a[0] * s + a[1] * t + 5.0;
                net[2 * (j * (m + 1) + i) + 1] = a[2] * s + a[3] * t;
            }
        CHECK(pc_bezier_clip_step(net, m, n, 0.0, box2) == PC_CLIP_EMPTY);
    }
}

/* The Jacobian bounds behind certified Newton hold on samples: |J|_F <=
 * jac_max everywhere and |J(a) - J(b)|_F <= L |a - b| (checked on the
 * folded bicubic and the rational torus patch, in a random frame). */
static void test_jacobian_bounds(const test_patch *tp, unsigned long long seed)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, seed);
    const double o[3] = {0.1, -0.2, 0.3}, d[3] = {0.3, 0.5, -0.8};
    pc_ray_frame frame;
    pc_ray_frame_init(&frame, vec3_load(o), vec3_load(d), 3.0, 1.0, 0);
    double q[4 * MAX_NET], w_max, w_min;
    const int np = (tp->patch.deg_u + 1) * (tp->patch.deg_v + 1);
    /* The bounds concern the whole net: project it even if culled. */
    pc_ray_frame_project(&frame, &tp->patch, q, &w_max, &w_min);
    for (int k = 0; k < np; ++k) {
        const double *cw = tp->cw + 4 * k;
        q[4 * k + 2] = vec3_dot(frame.d, vec3(cw[0], cw[1], cw[2])) - cw[3] * frame.origin_d;
    }
    const pc_frame_net net = {tp->patch.deg_u, tp->patch.deg_v, q};
    double lipschitz, jac_max;
    pc_frame_net_jacobian_bounds(&net, &lipschitz, &jac_max);
    for (int k = 0; k < 2000; ++k) {
        const double s1 = pc_test_rng_uniform(&rng, 0, 1), t1 = pc_test_rng_uniform(&rng, 0, 1);
        const double s2 = pc_test_rng_uniform(&rng, 0, 1), t2 = pc_test_rng_uniform(&rng, 0, 1);
        double d1[4], ds1[4], dt1[4], d2[4], ds2[4], dt2[4];
        pc_frame_net_eval(&net, s1, t1, d1, ds1, dt1);
        pc_frame_net_eval(&net, s2, t2, d2, ds2, dt2);
        const double j1 = sqrt(ds1[0] * ds1[0] + ds1[1] * ds1[1] + dt1[0] * dt1[0] + dt1[1] * dt1[1]);
        CHECK(j1 <= jac_max * (1 + 1e-12));
        const double dj = sqrt((ds1[0] - ds2[0]) * (ds1[0] - ds2[0]) + (ds1[1] - ds2[1]) * (ds1[1] - ds2[1]) +
                               (dt1[0] - dt2[0]) * (dt1[0] - dt2[0]) + (dt1[1] - dt2[1]) * (dt1[1] - dt2[1]));
        CHECK(dj <= lipschitz * hypot(s1 - s2, t1 - t2) * (1 + 1e-12) + 1e-14);
        /* The evaluator's derivatives against central differences. */
        const double h = 1e-6;
        double dp[4], dm[4];
        if (s1 > h && s1 < 1 - h) {
            pc_frame_net_eval(&net, s1 + h, t1, dp, NULL, NULL);
            pc_frame_net_eval(&net, s1 - h, t1, dm, NULL, NULL);
            for (int c = 0; c < 4; ++c)
                CHECK_NEAR(ds1[c], (dp[c] - dm[c]) / (2 * h), 1e-7 * (1 + fabs(ds1[c])));
        }
    }
}

int main(void)
{
    test_clip_affine();
    test_plane();
    test_patch torus;
    build_torus(&torus, 2.0, 1.0);
    test_jacobian_bounds(&torus, 13);
    test_torus_equation(&torus);
    test_tangent(&torus);
    test_shared_edge(&torus);
    test_against_oracle(&torus, "torus patch", 4000, 7);
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 3);
    for (int k = 0; k < 4; ++k) {
        test_patch folded;
        build_folded(&folded, &rng);
        test_jacobian_bounds(&folded, 14 + (unsigned long long)k);
        test_shared_edge(&folded);
        test_against_oracle(&folded, "folded bicubic", 3000, 100 + (unsigned long long)k);
    }
    return pc_test_finish("test_ray_patch");
}
