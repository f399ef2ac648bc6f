/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Where the curve meets S (issue 14, defects 5 and 12). The directional
 * projection holds only in front of the curve, lambda = (S - P).Dir >= 0; a
 * branch ends exactly where lambda reaches 0 (PROJCURVE_END_CURVE_CROSSING)
 * and one is born there (PROJCURVE_START_CURVE_CROSSING). Before, the tracer
 * went on through lambda = 0: a line piercing a plane gave one branch over
 * the whole line, half of it behind; a curve crossing a plane six times gave
 * one branch instead of three; on the egg, a branch ran on along the far
 * wall 25 units behind the curve; on test_pipe_out_true, 5,000 units.
 *
 * Oracles: the planes' crossings are known exactly (degree-1 curves cross
 * z = 0 at the middle of a segment); every vertex is checked for lambda >=
 * -LAMBDA_TOL and for its distance to the ray; a curve lying on S must come
 * back as itself (S(u, v) = P(t) at every vertex), on one patch or many.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "trace_oracle.h"
#include "trace_shapes.h"

/* lambda and the distance to the ray at the vertices, relative to the
 * model size: the corrector works to 1e-12 of it (NEWTON_TOL), the crossing
 * is located to that in lambda; 1e-10 leaves room for the 1 / |det| the
 * tolerance of lambda carries at the tilted directions below. */
#define LAMBDA_REL 1e-10
/* Crossing parameters, located to the corrector's tolerance in lambda:
 * |lambda'| is ~20 model units per unit t below, so 1e-9 in t is far
 * looser than what is reached. */
#define T_TOL 1e-9

typedef struct vertex_report {
    double min_lambda, max_ray, max_on_curve;
} vertex_report;

static projcurve_result *project(const projcurve_surface *s, const projcurve_curve *c,
                                 const double d[3], int compose)
{
    projcurve_options *o = NULL;
    projcurve_options_create(NULL, &o);
    projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, compose);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c, d, o, &r));
    projcurve_options_destroy(o);
    return r;
}

/* lambda, distance to the ray and |S - P| over every vertex of r. */
static vertex_report vertices(const projcurve_surface *s, const projcurve_curve *c,
                              const double d[3], const projcurve_result *r)
{
    vertex_report v = {INFINITY, 0.0, 0.0};
    const double dn = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (size_t b = 0; b < projcurve_result_branch_count(r); ++b) {
        size_t n = 0;
        projcurve_result_branch_info(NULL, r, b, NULL, NULL, NULL, &n, NULL);
        double *p = malloc(3 * (n ? n : 1) * sizeof *p);
        projcurve_result_branch_points(NULL, r, b, n, p, &n);
        for (size_t k = 0; k < n; ++k) {
            double q[3], x[3];
            projcurve_surface_eval(NULL, s, p[3 * k + 1], p[3 * k + 2], 0, q);
            projcurve_curve_eval(NULL, c, p[3 * k], 0, x);
            const double e[3] = {q[0] - x[0], q[1] - x[1], q[2] - x[2]};
            const double l = (e[0] * d[0] + e[1] * d[1] + e[2] * d[2]) / dn;
            const double dist = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
            const double cr[3] = {e[1] * d[2] - e[2] * d[1], e[2] * d[0] - e[0] * d[2],
                                  e[0] * d[1] - e[1] * d[0]};
            v.min_lambda = fmin(v.min_lambda, l);
            v.max_ray = fmax(v.max_ray, sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]) / dn);
            v.max_on_curve = fmax(v.max_on_curve, dist);
        }
        free(p);
    }
    return v;
}

static void check_vertices(const char *name, const projcurve_surface *s,
                           const projcurve_curve *c, const double d[3],
                           const projcurve_result *r, double size)
{
    const vertex_report v = vertices(s, c, d, r);
    printf("%s: %zu branches, min lambda %.3g, max distance to the ray %.3g\n", name,
           projcurve_result_branch_count(r), v.min_lambda, v.max_ray);
    CHECK(v.min_lambda >= -LAMBDA_REL * size);
    CHECK(v.max_ray <= LAMBDA_REL * size);
}

static void branch(const projcurve_result *r, size_t i, double t[2],
                   projcurve_branch_start *start, projcurve_branch_end *end)
{
    t[0] = t[1] = NAN;
    CHECK_OK(projcurve_result_branch_info(NULL, r, i, t, start, end, NULL, NULL));
}

/* A line from (10, 20, 30) to (90, 70, -30) through the plane z = 0 (100 x
 * 100) at t = 0.5: along -z the part above, along +z the part below. */
static void line_through_plane(void)
{
    const double o[3] = {0, 0, 0}, a[3] = {100, 0, 0}, b[3] = {0, 100, 0};
    projcurve_surface *s = shape_plane(o, a, b);
    const double pts[6] = {10, 20, 30, 90, 70, -30};
    projcurve_curve *c = shape_bspline_curve(1, 2, pts);
    const double down[3] = {0, 0, -1}, up[3] = {0, 0, 1};
    for (int k = 0; k < 2; ++k) {
        projcurve_result *r = project(s, c, k == 0 ? down : up, 0);
        check_vertices(k == 0 ? "line, -z" : "line, +z", s, c, k == 0 ? down : up, r, 141.0);
        CHECK(projcurve_result_branch_count(r) == 1);
        if (projcurve_result_branch_count(r) == 1) {
            double t[2];
            projcurve_branch_start st;
            projcurve_branch_end en;
            branch(r, 0, t, &st, &en);
            if (k == 0) {
                CHECK(st == PROJCURVE_START_CURVE_START);
                CHECK(en == PROJCURVE_END_CURVE_CROSSING);
                CHECK_NEAR(t[0], 0.0, 0.0);
                CHECK_NEAR(t[1], 0.5, T_TOL);
            } else {
                CHECK(st == PROJCURVE_START_CURVE_CROSSING);
                CHECK(en == PROJCURVE_END_CURVE_END);
                CHECK_NEAR(t[0], 0.5, T_TOL);
                CHECK_NEAR(t[1], 1.0, 0.0);
            }
        }
        projcurve_result_destroy(r);
    }
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

/* The crossings of z(t) = 0 of c: dense sampling, then bisection to
 * rounding. Returns how many (at most max). */
static int z_crossings(const projcurve_curve *c, double *t, int max)
{
    int n = 0;
    double a = 0.0, za;
    double p[3];
    projcurve_curve_eval(NULL, c, a, 0, p);
    za = p[2];
    for (int i = 1; i <= 4000; ++i) {
        const double b = i / 4000.0;
        projcurve_curve_eval(NULL, c, b, 0, p);
        const double zb = p[2];
        if ((za < 0.0) != (zb < 0.0) && n < max) {
            double lo = a, hi = b;
            for (int k = 0; k < 80; ++k) {
                const double m = 0.5 * (lo + hi);
                projcurve_curve_eval(NULL, c, m, 0, p);
                if ((p[2] < 0.0) == (za < 0.0))
                    lo = m;
                else
                    hi = m;
            }
            t[n++] = 0.5 * (lo + hi);
        }
        a = b;
        za = zb;
    }
    return n;
}

/* A quadratic zigzag (control points at z = -10, 10, -10, ..., seven of
 * them) starting and ending below z = 0: it crosses the plane six times;
 * along a tilted -z the three parts above are three branches, each from
 * one crossing to the next. */
static void zigzag_through_plane(int compose)
{
    const double o[3] = {-50, -50, 0}, a[3] = {200, 0, 0}, b[3] = {0, 200, 0};
    projcurve_surface *s = shape_plane(o, a, b);
    double pts[21];
    for (int i = 0; i < 7; ++i) {
        pts[3 * i] = 10.0 + 13.0 * i;
        pts[3 * i + 1] = 30.0 + 5.0 * (i % 3);
        pts[3 * i + 2] = i % 2 ? 10.0 : -10.0;
    }
    projcurve_curve *c = shape_bspline_curve(2, 7, pts);
    double x[8];
    CHECK(z_crossings(c, x, 8) == 6);
    const double d[3] = {0.2, -0.1, -1.0};
    projcurve_result *r = project(s, c, d, compose);
    check_vertices(compose ? "zigzag (composed)" : "zigzag", s, c, d, r, 283.0);
    CHECK(projcurve_result_branch_count(r) == 3);
    for (size_t i = 0; i < 3 && i < projcurve_result_branch_count(r); ++i) {
        double t[2];
        projcurve_branch_start st;
        projcurve_branch_end en;
        branch(r, i, t, &st, &en);
        /* branches come in the order they were found: the hump they cover */
        int hump = 0;
        while (hump < 2 && t[0] > x[2 * hump + 1])
            ++hump;
        CHECK(st == PROJCURVE_START_CURVE_CROSSING);
        CHECK(en == PROJCURVE_END_CURVE_CROSSING);
        CHECK_NEAR(t[0], x[2 * hump], T_TOL);
        CHECK_NEAR(t[1], x[2 * hump + 1], T_TOL);
    }
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

/* A bilinear plane z = 0 over [0, 100]^2 with n x n control points (n - 1
 * spans each way: many patches when n > 2). */
static projcurve_surface *grid_plane(int n)
{
    double *ctrl = malloc(3 * (size_t)(n * n) * sizeof *ctrl);
    double *knots = malloc((size_t)(n + 2) * sizeof *knots);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            ctrl[3 * (j * n + i)] = 100.0 * i / (n - 1);
            ctrl[3 * (j * n + i) + 1] = 100.0 * j / (n - 1);
            ctrl[3 * (j * n + i) + 2] = 0.0;
        }
    knots[0] = 0.0;
    for (int i = 0; i < n; ++i)
        knots[i + 1] = (double)i / (n - 1);
    knots[n + 1] = 1.0;
    projcurve_surface *s = NULL;
    projcurve_surface_create_nurbs(NULL, 1, 1, n, n, ctrl, NULL, knots, knots, &s);
    free(ctrl);
    free(knots);
    return s;
}

/* A cubic lying in the plane: its projection (lambda = 0 counts) is the
 * curve itself, one branch over [0, 1], on one patch or 30 x 30, along the
 * normal or tilted. */
static void curve_on_plane(int n, const double d[3])
{
    projcurve_surface *s = grid_plane(n);
    const double pts[15] = {10, 15, 0, 35, 80, 0, 55, 20, 0, 75, 85, 0, 90, 40, 0};
    projcurve_curve *c = shape_bspline_curve(3, 5, pts);
    for (int compose = 0; compose <= 1; ++compose) {
        projcurve_result *r = project(s, c, d, compose);
        char name[80];
        snprintf(name, sizeof name, "curve on a %dx%d plane, Dir (%g, %g, %g)%s", n - 1, n - 1,
                 d[0], d[1], d[2], compose ? " composed" : "");
        check_vertices(name, s, c, d, r, 141.0);
        const vertex_report v = vertices(s, c, d, r);
        CHECK(v.max_on_curve <= LAMBDA_REL * 141.0);
        CHECK(projcurve_result_branch_count(r) == 1);
        if (projcurve_result_branch_count(r) == 1) {
            double t[2];
            projcurve_branch_start st;
            projcurve_branch_end en;
            branch(r, 0, t, &st, &en);
            CHECK(st == PROJCURVE_START_CURVE_START);
            CHECK(en == PROJCURVE_END_CURVE_END);
            /* the composition's ends are the curve's to rounding */
            CHECK_NEAR(t[0], 0.0, 1e-12);
            CHECK_NEAR(t[1], 1.0, 1e-12);
        }
        projcurve_result_destroy(r);
    }
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

/* A curve on the plane only to a modelling tolerance, 1e-6 above and below
 * it in turn (a CAD curve on its face; joinsurf_01 curve 7 lies on surface
 * 1 so): points behind by less than eps_D count as on the curve, so it is
 * still one branch over [0, 1], not cut at every sign change of lambda. */
static void curve_near_plane(const double d[3])
{
    projcurve_surface *s = grid_plane(11);
    const double pts[15] = {10, 15, 1e-6, 35, 80, -1e-6, 55, 20, 1e-6, 75, 85, -1e-6, 90, 40, 1e-6};
    projcurve_curve *c = shape_bspline_curve(3, 5, pts);
    projcurve_result *r = project(s, c, d, 1);
    const vertex_report v = vertices(s, c, d, r);
    printf("curve within 1e-6 of a plane: %zu branches, min lambda %.3g\n",
           projcurve_result_branch_count(r), v.min_lambda);
    CHECK(v.min_lambda >= -2e-6);
    CHECK(projcurve_result_branch_count(r) == 1);
    if (projcurve_result_branch_count(r) == 1) {
        double t[2];
        projcurve_branch_start st;
        projcurve_branch_end en;
        branch(r, 0, t, &st, &en);
        CHECK(st == PROJCURVE_START_CURVE_START);
        CHECK(en == PROJCURVE_END_CURVE_END);
        CHECK_NEAR(t[0], 0.0, 1e-12);
        CHECK_NEAR(t[1], 1.0, 1e-12);
    }
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

/* A closed surface: a cubic that dives through a sphere of radius 30 and
 * out again, along a tilted -z. Rays meet the near and the far side; where
 * the curve passes through the sphere the branch on the side it crosses
 * ends (or starts) there, the other goes on. No vertex may lie behind,
 * there must be crossings, and brute force must find nothing uncovered. */
static void curve_through_sphere(void)
{
    projcurve_surface *s = shape_sphere(30.0);
    const double pts[15] = {-50, 5, 40, -20, -5, 10, 0, 8, -45, 25, -3, 5, 55, 6, 45};
    projcurve_curve *c = shape_bspline_curve(3, 5, pts);
    const double d[3] = {0.2, 0.1, -1.0};
    projcurve_result *r = project(s, c, d, 0);
    check_vertices("curve through a sphere", s, c, d, r, 104.0);
    size_t crossings = 0;
    for (size_t i = 0; i < projcurve_result_branch_count(r); ++i) {
        double t[2];
        projcurve_branch_start st;
        projcurve_branch_end en;
        branch(r, i, t, &st, &en);
        crossings += (st == PROJCURVE_START_CURVE_CROSSING) + (en == PROJCURVE_END_CURVE_CROSSING);
    }
    CHECK(crossings >= 2); /* in and out, at least */
    trace_oracle_report rep;
    trace_oracle_check(s, c, d, r, 3000, &rep);
    trace_oracle_print("curve through a sphere", &rep);
    CHECK(rep.uncovered_far == 0);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

static projcurve_model *read_real(const char *file)
{
    char rel[256];
    snprintf(rel, sizeof rel, "real/%s", file);
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(NULL, pc_test_data_path(rel), &m) != PROJCURVE_OK) {
        pc_test_missing_data(rel);
    }
    return m;
}

/* The egg, a closed surface: a curve across it lifted 5 % of the model
 * along the normal at the middle of the domain, projected back along that
 * normal. Rays meet the near wall and then the far wall; both are in
 * front. Before, a branch went on along the far wall 25 units behind. */
static void egg_lifted(void)
{
    projcurve_model *m = read_real("egg.xml");
    if (m == NULL)
        return;
    const projcurve_surface *s = projcurve_model_surface(m, 0);
    double box[6], dom[4];
    projcurve_surface_bounds(NULL, s, box);
    projcurve_surface_domain(NULL, s, dom);
    const double size = sqrt((box[3] - box[0]) * (box[3] - box[0]) +
                             (box[4] - box[1]) * (box[4] - box[1]) +
                             (box[5] - box[2]) * (box[5] - box[2]));
    const double um = 0.5 * (dom[0] + dom[1]), vm = 0.5 * (dom[2] + dom[3]);
    double e[9];
    projcurve_surface_eval(NULL, s, um, vm, 1, e);
    double n[3] = {e[4] * e[8] - e[5] * e[7], e[5] * e[6] - e[3] * e[8],
                   e[3] * e[7] - e[4] * e[6]};
    const double nn = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int k = 0; k < 3; ++k)
        n[k] /= nn;
    /* five points of S along a diagonal through the middle, lifted */
    double pts[15];
    for (int i = 0; i < 5; ++i) {
        const double f = -0.3 + 0.15 * i;
        double q[3];
        projcurve_surface_eval(NULL, s, um + f * (dom[1] - dom[0]), vm + f * (dom[3] - dom[2]),
                               0, q);
        for (int k = 0; k < 3; ++k)
            pts[3 * i + k] = q[k] + 0.05 * size * n[k];
    }
    projcurve_curve *c = shape_bspline_curve(3, 5, pts);
    const double d[3] = {-n[0], -n[1], -n[2]};
    projcurve_result *r = project(s, c, d, 0);
    check_vertices("egg.xml, lifted curve", s, c, d, r, size);
    trace_oracle_report rep;
    trace_oracle_check(s, c, d, r, 3000, &rep);
    trace_oracle_print("egg.xml, lifted curve", &rep);
    CHECK(rep.uncovered_far == 0);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    projcurve_model_destroy(m);
}

/* test_pipe_out_true.step, surface 2 (a quarter of a pipe along z), curve
 * 2 (a loop on the pipes), Dir (0, 0, -1): a branch ran 5,000 units
 * behind its curve point at t ~ 1.083. */
static void pipe_behind(void)
{
    projcurve_model *m = read_real("test_pipe_out_true.step");
    if (m == NULL)
        return;
    const projcurve_surface *s = projcurve_model_surface(m, 2);
    const projcurve_curve *c = projcurve_model_curve(m, 2);
    CHECK(s != NULL && c != NULL);
    if (s != NULL && c != NULL) {
        const double d[3] = {0, 0, -1};
        double box[6];
        projcurve_surface_bounds(NULL, s, box);
        projcurve_result *r = project(s, c, d, 1);
        check_vertices("test_pipe_out_true.step s2 c2", s, c, d, r, 12000.0);
        projcurve_result_destroy(r);
    }
    projcurve_model_destroy(m);
}

int main(void)
{
    line_through_plane();
    zigzag_through_plane(0);
    zigzag_through_plane(1);
    const double normal[3] = {0, 0, -1}, tilted[3] = {0.3, -0.2, -1};
    curve_on_plane(2, normal);
    curve_on_plane(2, tilted);
    curve_on_plane(31, normal);
    curve_on_plane(31, tilted);
    curve_near_plane(normal);
    curve_near_plane(tilted);
    curve_through_sphere();
    egg_lifted();
    pipe_behind();
    return pc_test_finish("test_trace_crossing");
}
