/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Bezier decomposition and the patch BVH: the patches reproduce the surface,
 * their boxes contain it, the grid knows its neighbours, curve segments
 * reproduce the curve, and BVH queries find exactly the patches a brute
 * force scan of all boxes finds, also for 12,000 patches.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "shapes.h"

#define TOL_EXACT 1e-12

static void test_grid(const pc_shape_surface *shape, pc_test_rng *rng)
{
    projcurve_surface *s = pc_shape_surface_create(shape);
    CHECK(s != NULL);
    const pc_patch_grid *g = &s->grid;
    size_t spans_u = 0, spans_v = 0;
    CHECK_OK(projcurve_surface_info(NULL, s, NULL, NULL, NULL, NULL, &spans_u, &spans_v, NULL));
    CHECK(spans_u == g->spans_u && spans_v == g->spans_v);
    CHECK_NEAR(g->breaks_u[0], s->nurbs.domain[0], 0.0);
    CHECK_NEAR(g->breaks_u[g->spans_u], s->nurbs.domain[1], 0.0);
    CHECK_NEAR(g->breaks_v[g->spans_v], s->nurbs.domain[3], 0.0);
    for (size_t iv = 0; iv < g->spans_v; ++iv)
        for (size_t iu = 0; iu < g->spans_u; ++iu) {
            const pc_bezier_patch *pt = pc_patch_grid_at(g, iu, iv);
            CHECK(pt != NULL && pt->iu == iu && pt->iv == iv);
            CHECK(pt->u0 < pt->u1 && pt->v0 < pt->v1);
            const pc_bezier_patch *right = pc_patch_grid_at(g, iu + 1, iv);
            const pc_bezier_patch *up = pc_patch_grid_at(g, iu, iv + 1);
            CHECK((right == NULL) == (iu + 1 == g->spans_u));
            CHECK((up == NULL) == (iv + 1 == g->spans_v));
            if (right != NULL)
                CHECK(right->u0 == pt->u1 && right->v0 == pt->v0);
            if (up != NULL)
                CHECK(up->v0 == pt->v1 && up->u0 == pt->u0);
            /* The patch equals the surface on its box and lies in its box. */
            for (int k = 0; k < 20; ++k) {
                const double u = pc_test_rng_uniform(rng, pt->u0, pt->u1);
                const double v = pc_test_rng_uniform(rng, pt->v0, pt->v1);
                pc_vec3 a[6], b[6];
                pc_nurbs_surface_eval(&s->nurbs, u, v, 2, NULL, NULL, a);
                pc_bezier_patch_eval(pt, u, v, 2, b);
                CHECK_NEAR(vec3_dist(a[0], b[0]), 0.0, TOL_EXACT * s->size);
                const double xyz[3] = {b[0].x, b[0].y, b[0].z};
                for (int c = 0; c < 3; ++c)
                    CHECK(xyz[c] >= pt->box[c] - TOL_EXACT * s->size &&
                          xyz[c] <= pt->box[c + 3] + TOL_EXACT * s->size);
            }
            /* Corners of a Bezier patch interpolate the corner control points. */
            pc_vec3 corner;
            pc_nurbs_surface_eval(&s->nurbs, pt->u0, pt->v0, 0, NULL, NULL, &corner);
            const double w = pt->cw[3];
            CHECK_NEAR(vec3_dist(corner, vec3(pt->cw[0] / w, pt->cw[1] / w, pt->cw[2] / w)), 0.0,
                       TOL_EXACT * s->size);
        }
    projcurve_surface_destroy(s);
}

static void test_grids(void)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 3);
    const double c[3] = {0, 0, 0};
    pc_shape_surface shapes[4] = {pc_shape_sphere(c, 2.0), pc_shape_torus(3.0, 1.0),
                                  pc_shape_bumpy(1, 4, 3, 0.5, 1), pc_shape_plane(2, 5, 3, 2)};
    for (int k = 0; k < 4; ++k) {
        test_grid(&shapes[k], &rng);
        pc_shape_surface_free(&shapes[k]);
    }
    /* Interior knots of multiplicity p + 1 (a C^-1 break) in u and p in v. */
    pc_shape_surface b = pc_shape_bumpy(2, 5, 4, 0.5, 0); /* n_u = 8, n_v = 7 */
    const double ku[12] = {0, 0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1, 1};
    const double kv[11] = {0, 0, 0, 0, 0.3, 0.3, 0.3, 1, 1, 1, 1};
    memcpy(b.knots_u, ku, sizeof ku);
    memcpy(b.knots_v, kv, sizeof kv);
    test_grid(&b, &rng);
    pc_shape_surface_free(&b);
}

static void test_curve_segments(void)
{
    const double centre[3] = {1, 2, 3};
    pc_shape_curve shape = pc_shape_circle(centre, 2.0);
    projcurve_curve *c = pc_shape_curve_create(&shape);
    pc_bezier_curves segs;
    CHECK_OK(pc_bezier_curves_build(NULL, &segs, &c->nurbs));
    CHECK(segs.n_segments == 4);
    CHECK(segs.degree == 2);
    for (size_t k = 0; k < segs.n_segments; ++k) {
        const double *cw = segs.cw + 4 * 3 * k;
        /* Segment end points are on the curve at the breaks. */
        pc_vec3 a, b;
        pc_nurbs_curve_eval(&c->nurbs, segs.breaks[k], 0, NULL, &a);
        pc_nurbs_curve_eval(&c->nurbs, segs.breaks[k + 1], 0, NULL, &b);
        CHECK_NEAR(vec3_dist(a, vec3(cw[0] / cw[3], cw[1] / cw[3], cw[2] / cw[3])), 0.0, 1e-12);
        CHECK_NEAR(vec3_dist(b, vec3(cw[8] / cw[11], cw[9] / cw[11], cw[10] / cw[11])), 0.0, 1e-12);
        /* Midpoint: rational de Casteljau at s = 1/2. */
        double h[4];
        for (int m = 0; m < 4; ++m)
            h[m] = 0.25 * cw[m] + 0.5 * cw[4 + m] + 0.25 * cw[8 + m];
        pc_vec3 mid;
        pc_nurbs_curve_eval(&c->nurbs, 0.5 * (segs.breaks[k] + segs.breaks[k + 1]), 0, NULL, &mid);
        CHECK_NEAR(vec3_dist(mid, vec3(h[0] / h[3], h[1] / h[3], h[2] / h[3])), 0.0, 1e-12);
    }
    pc_bezier_curves_free(&segs);
    projcurve_curve_destroy(c);
    pc_shape_curve_free(&shape);
}

/* ---- BVH against brute force ------------------------------------------- */

typedef struct collected {
    unsigned char *seen;
    size_t count;
} collected;

static int collect(void *user, size_t index)
{
    collected *c = user;
    c->seen[index]++;
    c->count++;
    return 0;
}

static int box_meets_line(const double box[6], pc_vec3 o, pc_vec3 d)
{
    /* Brute force: the line meets the box iff the interval of lambda for
     * which each coordinate is inside is non-empty (dense scan is too slow;
     * this is the same slab logic written independently with intervals). */
    double lo = -INFINITY, hi = INFINITY;
    const double oo[3] = {o.x, o.y, o.z}, dd[3] = {d.x, d.y, d.z};
    for (int k = 0; k < 3; ++k) {
        if (dd[k] == 0.0) {
            if (oo[k] < box[k] || oo[k] > box[k + 3])
                return 0;
            continue;
        }
        const double a = (box[k] - oo[k]) / dd[k], b = (box[k + 3] - oo[k]) / dd[k];
        lo = fmax(lo, fmin(a, b));
        hi = fmin(hi, fmax(a, b));
    }
    return lo <= hi;
}

static double box_dist(const double box[6], pc_vec3 p)
{
    const pc_vec3 q = vec3(fmin(fmax(p.x, box[0]), box[3]), fmin(fmax(p.y, box[1]), box[4]),
                           fmin(fmax(p.z, box[2]), box[5]));
    return vec3_dist(p, q);
}

static void test_bvh(size_t spans_u, size_t spans_v, int queries)
{
    pc_shape_surface shape = pc_shape_bumpy(17, spans_u, spans_v, 0.05, 0);
    projcurve_surface *s = pc_shape_surface_create(&shape);
    CHECK(s != NULL);
    const size_t n = spans_u * spans_v;
    CHECK(s->bvh.depth >= 1 && s->bvh.depth <= 64);
    /* Balanced: depth <= ceil(log2(n / 4)) + 2. */
    CHECK(s->bvh.depth <= (int)ceil(log2((double)n / 4.0 + 1.0)) + 2);
    collected c = {calloc(n, 1), 0};
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 23);
    for (int k = 0; k < queries; ++k) {
        const pc_vec3 o = vec3(pc_test_rng_uniform(&rng, -0.2, 1.2),
                               pc_test_rng_uniform(&rng, -0.2, 1.2), 1.0);
        const pc_vec3 d = vec3(pc_test_rng_uniform(&rng, -0.3, 0.3),
                               pc_test_rng_uniform(&rng, -0.3, 0.3), -1.0);
        memset(c.seen, 0, n);
        c.count = 0;
        pc_bvh_query_line(&s->bvh, o, d, -INFINITY, INFINITY, 0.0, collect, &c);
        size_t expected = 0;
        for (size_t i = 0; i < n; ++i) {
            const int meets = box_meets_line(s->grid.patches[i].box, o, d);
            expected += (size_t)meets;
            if (c.seen[i] != meets)
                pc_test_fail_at(__FILE__, __LINE__, "line query: patch %zu seen %d, meets %d", i,
                                c.seen[i], meets);
        }
        CHECK(c.count == expected);
        const double radius = pc_test_rng_uniform(&rng, 0.0, 0.2);
        const pc_vec3 p = vec3(o.x, o.y, pc_test_rng_uniform(&rng, -0.2, 0.2));
        memset(c.seen, 0, n);
        c.count = 0;
        pc_bvh_query_sphere(&s->bvh, p, radius, collect, &c);
        for (size_t i = 0; i < n; ++i) {
            const int near = box_dist(s->grid.patches[i].box, p) <= radius;
            if (c.seen[i] != near)
                pc_test_fail_at(__FILE__, __LINE__, "sphere query: patch %zu seen %d, near %d", i,
                                c.seen[i], near);
        }
    }
    free(c.seen);
    projcurve_surface_destroy(s);
    pc_shape_surface_free(&shape);
}

typedef struct nearest_log {
    unsigned char *seen;
    size_t count;
    double bound;
    int prune; /* return the least box distance seen as the bound */
} nearest_log;

static double log_visit(void *user, size_t index, double box_distance_sq)
{
    nearest_log *l = user;
    l->count++;
    l->seen[index]++;
    l->bound = fmin(l->bound, box_distance_sq);
    return l->prune ? l->bound : INFINITY;
}

/* The nearest-first walk visits each patch once; with a shrinking bound it
 * still reaches the least box distance (pruning is only by boxes at least
 * as far as the bound). */
static void test_bvh_nearest(void)
{
    pc_shape_surface shape = pc_shape_bumpy(21, 30, 20, 0.2, 0);
    projcurve_surface *s = pc_shape_surface_create(&shape);
    const size_t n = 600;
    nearest_log l = {calloc(n, 1), 0, INFINITY, 0};
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 4);
    for (int k = 0; k < 20; ++k) {
        const pc_vec3 p = vec3(pc_test_rng_uniform(&rng, -0.5, 1.5), pc_test_rng_uniform(&rng, -0.5, 1.5),
                               pc_test_rng_uniform(&rng, -1.0, 1.0));
        memset(l.seen, 0, n);
        l.count = 0;
        l.bound = INFINITY;
        l.prune = 0;
        pc_bvh_query_nearest(&s->bvh, p, log_visit, &l);
        CHECK(l.count == n);
        size_t nearest = 0;
        for (size_t i = 0; i < n; ++i) {
            CHECK(l.seen[i] == 1);
            if (box_dist(s->grid.patches[i].box, p) < box_dist(s->grid.patches[nearest].box, p))
                nearest = i;
        }
        memset(l.seen, 0, n);
        l.count = 0;
        l.bound = INFINITY;
        l.prune = 1;
        pc_bvh_query_nearest(&s->bvh, p, log_visit, &l);
        /* The least box distance met equals the least of all (ties aside,
         * the nearest patch itself). */
        CHECK_NEAR(sqrt(l.bound), box_dist(s->grid.patches[nearest].box, p), 1e-12);
        CHECK(l.count < n); /* the bound did prune */
    }
    free(l.seen);
    projcurve_surface_destroy(s);
    pc_shape_surface_free(&shape);
}

static int stop_at_first(void *user, size_t index)
{
    (void)index;
    ++*(int *)user;
    return 1;
}

static void test_bvh_stop(void)
{
    pc_shape_surface shape = pc_shape_plane(3, 3, 8, 8);
    projcurve_surface *s = pc_shape_surface_create(&shape);
    int calls = 0;
    pc_bvh_query_sphere(&s->bvh, vec3(0, 0, 0), 10.0, stop_at_first, &calls);
    CHECK(calls == 1);
    projcurve_surface_destroy(s);
    pc_shape_surface_free(&shape);
}

int main(void)
{
    test_grids();
    test_curve_segments();
    test_bvh(7, 5, 200);
    test_bvh(1, 1, 20);
    test_bvh(120, 100, 20);
    test_bvh_stop();
    test_bvh_nearest();
    return pc_test_finish("test_bezier");
}
