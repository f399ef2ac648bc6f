/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The conical projection against closed forms: a line onto a plane is a
 * line, a circle onto a plane from a point of its axis is a circle, a line
 * onto a sphere from an outside eye gives the front and the back branch, a
 * curve through the plane ends (or starts) where it crosses it, an eye on
 * the surface is allowed, and bad eyes are refused.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "conical_check.h"
#include "shapes.h"

/* eps_D of the calls, model units (the plane's size is ~3.6). */
#define EPS_D 1e-5
/* Traced vertices satisfy the equations to the corrector's tolerance
 * (1e-12 of the model size by default) plus rounding. */
#define VERTEX_TOL 1e-10
/* Collinearity of a composed line: pieces are S of straight (u, v)
 * segments, on the affine plane exact lines, to rounding. */
#define LINE_TOL 1e-12

static projcurve_curve *make_segment(const double p0[3], const double p1[3])
{
    const double ctrl[6] = {p0[0], p0[1], p0[2], p1[0], p1[1], p1[2]};
    const double knots[4] = {0.0, 0.0, 1.0, 1.0};
    projcurve_curve *c = NULL;
    if (projcurve_curve_create_nurbs(NULL, 1, 2, ctrl, NULL, knots, &c) != PROJCURVE_OK)
        return NULL;
    return c;
}

static projcurve_surface *make_plane(void)
{
    pc_shape_surface sh = pc_shape_plane(3, 3, 2, 2); /* z = 0, x [-1, 1], y [-1, 2] */
    projcurve_surface *s = pc_shape_surface_create(&sh);
    pc_shape_surface_free(&sh);
    return s;
}

/* The central image of p from eye on the plane z = 0. */
static void plane_image(const double eye[3], const double p[3], double x[3])
{
    const double mu = eye[2] / (eye[2] - p[2]);
    for (int i = 0; i < 3; ++i)
        x[i] = eye[i] + mu * (p[i] - eye[i]);
}

static void test_line_onto_plane(projcurve_surface *plane)
{
    const double eye[3] = {0.1, 0.2, 3.0};
    const double p0[3] = {-0.5, -0.3, 1.0}, p1[3] = {0.4, 0.5, 1.3};
    projcurve_curve *c = make_segment(p0, p1);
    projcurve_options *o = cc_options(EPS_D);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_conical(NULL, plane, c, eye, o, &r));
    CHECK(projcurve_result_branch_count(r) == 1);
    projcurve_branch_start start;
    projcurve_branch_end end;
    double tr[2];
    projcurve_result_branch_info(NULL, r, 0, tr, &start, &end, NULL, NULL);
    CHECK(start == PROJCURVE_START_CURVE_START && end == PROJCURVE_END_CURVE_END);
    CHECK(tr[0] == 0.0 && tr[1] == 1.0);
    double min_lambda;
    const double res = cc_vertex_ray_residual(r, plane, c, eye, &min_lambda);
    CHECK(res <= VERTEX_TOL);
    CHECK(min_lambda > 0.0);
    /* the image line through the images of the ends */
    double a[3], b[3];
    plane_image(eye, p0, a);
    plane_image(eye, p1, b);
    size_t n_pieces = 0;
    projcurve_result_branch_info(NULL, r, 0, NULL, NULL, NULL, NULL, &n_pieces);
    CHECK(n_pieces >= 1);
    double worst_line = 0.0, worst_z = 0.0;
    for (size_t k = 0; k < n_pieces; ++k) {
        int degree = 0;
        double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], w[PROJCURVE_MAX_PIECE_POINTS];
        projcurve_result_piece(NULL, r, 0, k, &degree, ctrl, w, NULL, NULL);
        for (int j = 0; j <= 8; ++j) {
            double x[3];
            pc_test_piece_point(degree, ctrl, w, j / 8.0, x);
            worst_z = fmax(worst_z, fabs(x[2]));
            worst_line = fmax(worst_line, cc_segment_dist(x, a, b));
        }
    }
    /* and the vertex at every t is the closed-form image of P(t) */
    double worst_exact = 0.0;
    size_t n = 0;
    projcurve_result_branch_info(NULL, r, 0, NULL, NULL, NULL, &n, NULL);
    double *pts = malloc(3 * n * sizeof *pts);
    projcurve_result_branch_points(NULL, r, 0, n, pts, &n);
    for (size_t k = 0; k < n; ++k) {
        double p[3], x[3], y[3];
        projcurve_curve_eval(NULL, c, pts[3 * k], 0, p);
        plane_image(eye, p, x);
        projcurve_surface_eval(NULL, plane, pts[3 * k + 1], pts[3 * k + 2], 0, y);
        worst_exact = fmax(worst_exact, cc_dist(x, y));
    }
    free(pts);
    printf("line onto plane: %zu pieces, %zu vertices, off the line %.3g, |z| %.3g, "
           "off the exact image %.3g\n",
           n_pieces, n, worst_line, worst_z, worst_exact);
    CHECK(worst_line <= LINE_TOL);
    CHECK(worst_z <= LINE_TOL);
    CHECK(worst_exact <= VERTEX_TOL);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
}

static void test_circle_onto_plane(projcurve_surface *plane)
{
    const double eye[3] = {0.0, 0.0, 3.0}, centre[3] = {0.0, 0.0, 1.0};
    pc_shape_curve sh = pc_shape_circle(centre, 0.5);
    projcurve_curve *c = pc_shape_curve_create(&sh);
    pc_shape_curve_free(&sh);
    projcurve_options *o = cc_options(EPS_D);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_conical(NULL, plane, c, eye, o, &r));
    CHECK(projcurve_result_branch_count(r) == 1);
    /* mu = 3 / (3 - 1): the image circle has radius 0.75 */
    const double radius = 0.75;
    double worst_vertex = 0.0, worst_piece = 0.0, worst_compact = 0.0;
    size_t n = 0, n_pieces = 0;
    projcurve_result_branch_info(NULL, r, 0, NULL, NULL, NULL, &n, &n_pieces);
    double *pts = malloc(3 * n * sizeof *pts);
    projcurve_result_branch_points(NULL, r, 0, n, pts, &n);
    for (size_t k = 0; k < n; ++k) {
        double x[3];
        projcurve_surface_eval(NULL, plane, pts[3 * k + 1], pts[3 * k + 2], 0, x);
        worst_vertex = fmax(worst_vertex, fabs(hypot(x[0], x[1]) - radius));
    }
    free(pts);
    for (size_t k = 0; k < n_pieces; ++k) {
        int degree = 0;
        double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], w[PROJCURVE_MAX_PIECE_POINTS];
        projcurve_result_piece(NULL, r, 0, k, &degree, ctrl, w, NULL, NULL);
        for (int j = 0; j <= 8; ++j) {
            double x[3];
            pc_test_piece_point(degree, ctrl, w, j / 8.0, x);
            worst_piece = fmax(worst_piece, fmax(fabs(hypot(x[0], x[1]) - radius), fabs(x[2])));
        }
    }
    projcurve_curve *compact = NULL;
    CHECK_OK(projcurve_result_branch_compact_curve(NULL, r, 0, &compact));
    double dom[2] = {0.0, 1.0};
    projcurve_curve_domain(NULL, compact, &dom[0], &dom[1]);
    for (int j = 0; j <= 400; ++j) {
        double x[3];
        projcurve_curve_eval(NULL, compact, dom[0] + (dom[1] - dom[0]) * j / 400.0, 0, x);
        worst_compact = fmax(worst_compact, fmax(fabs(hypot(x[0], x[1]) - radius), fabs(x[2])));
    }
    projcurve_curve_destroy(compact);
    printf("circle onto plane: %zu vertices, %zu pieces, off the circle: vertices %.3g, "
           "pieces %.3g, compact %.3g (eps_D %g)\n",
           n, n_pieces, worst_vertex, worst_piece, worst_compact, EPS_D);
    CHECK(worst_vertex <= VERTEX_TOL);
    /* the pieces and the compact curve are within eps_D of the exact image */
    CHECK(worst_piece <= EPS_D);
    CHECK(worst_compact <= EPS_D);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
}

/* Hits of the ray p + lambda d (d unit) with the unit sphere, lambda > 0. */
static int sphere_hits(const double p[3], const double d[3], double lambda[2])
{
    const double b = p[0] * d[0] + p[1] * d[1] + p[2] * d[2];
    const double cc = p[0] * p[0] + p[1] * p[1] + p[2] * p[2] - 1.0;
    const double disc = b * b - cc;
    if (!(disc > 0.0))
        return 0;
    int n = 0;
    const double l0 = -b - sqrt(disc), l1 = -b + sqrt(disc);
    if (l0 > 0.0)
        lambda[n++] = l0;
    if (l1 > 0.0)
        lambda[n++] = l1;
    return n;
}

/* Every analytic ray hit at evenly spaced t within tol of the pieces;
 * returns the largest distance. */
static double sphere_missed(const projcurve_result *r, const projcurve_curve *c,
                            const double eye[3], int samples, size_t *hits)
{
    cc_pieces pieces;
    if (!cc_pieces_sample(r, &pieces))
        return INFINITY;
    double worst = 0.0;
    *hits = 0;
    for (int k = 0; k <= samples; ++k) {
        double p[3], d[3];
        projcurve_curve_eval(NULL, c, (double)k / samples, 0, p);
        double len = 0.0;
        for (int i = 0; i < 3; ++i) {
            d[i] = p[i] - eye[i];
            len += d[i] * d[i];
        }
        len = sqrt(len);
        for (int i = 0; i < 3; ++i)
            d[i] /= len;
        double lambda[2];
        const int n = sphere_hits(p, d, lambda);
        for (int j = 0; j < n; ++j) {
            const double x[3] = {p[0] + lambda[j] * d[0], p[1] + lambda[j] * d[1],
                                 p[2] + lambda[j] * d[2]};
            worst = fmax(worst, cc_pieces_dist(&pieces, x));
            ++*hits;
        }
    }
    cc_pieces_free(&pieces);
    return worst;
}

static projcurve_surface *make_sphere(void)
{
    const double origin[3] = {0.0, 0.0, 0.0};
    pc_shape_surface sh = pc_shape_sphere(origin, 1.0);
    projcurve_surface *s = pc_shape_surface_create(&sh);
    pc_shape_surface_free(&sh);
    return s;
}

static void test_sphere_front_and_back(projcurve_surface *sphere)
{
    /* every ray within the 11.5 degrees the sphere subtends, the hits at y
     * > 0 (off the seam u = 0) and away from the poles */
    const double eye[3] = {0.2, 0.1, 5.0};
    const double p0[3] = {-0.1, 0.25, 3.0}, p1[3] = {0.25, 0.4, 3.1};
    projcurve_curve *c = make_segment(p0, p1);
    projcurve_options *o = cc_options(EPS_D);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_conical(NULL, sphere, c, eye, o, &r));
    const size_t nb = projcurve_result_branch_count(r);
    CHECK(nb == 2);
    for (size_t b = 0; b < nb; ++b) {
        projcurve_branch_start start;
        projcurve_branch_end end;
        projcurve_result_branch_info(NULL, r, b, NULL, &start, &end, NULL, NULL);
        CHECK(start == PROJCURVE_START_CURVE_START && end == PROJCURVE_END_CURVE_END);
    }
    double min_lambda;
    const double res = cc_vertex_ray_residual(r, sphere, c, eye, &min_lambda);
    size_t hits = 0;
    const double missed = sphere_missed(r, c, eye, 200, &hits);
    printf("line onto sphere: %zu branches, ray residual %.3g, %zu analytic hits, "
           "farthest from the pieces %.3g\n",
           nb, res, hits, missed);
    CHECK(res <= VERTEX_TOL);
    CHECK(min_lambda > 0.0);
    CHECK(hits == 2 * 201);
    /* pieces within eps_D of the exact projection, sampled as polylines */
    CHECK(missed <= 1.01 * EPS_D);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
}

/* PROJCURVE_OPT_HITS nearest: the back of the sphere is hidden by its
 * front along every ray from the eye, so one branch is left, each of its
 * vertices the analytic front hit (the smaller lambda). */
static void test_sphere_nearest(projcurve_surface *sphere)
{
    const double eye[3] = {0.2, 0.1, 5.0};
    const double p0[3] = {-0.1, 0.25, 3.0}, p1[3] = {0.25, 0.4, 3.1};
    projcurve_curve *c = make_segment(p0, p1);
    projcurve_options *o = cc_options(EPS_D);
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_HITS, PROJCURVE_HITS_NEAREST));
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_conical(NULL, sphere, c, eye, o, &r));
    CHECK(projcurve_result_branch_count(r) == 1);
    size_t n = 0;
    CHECK_OK(projcurve_result_branch_points(NULL, r, 0, 0, NULL, &n));
    double *pts = malloc(3 * (n ? n : 1) * sizeof *pts);
    CHECK(pts != NULL);
    if (pts == NULL)
        n = 0;
    else
        CHECK_OK(projcurve_result_branch_points(NULL, r, 0, n, pts, &n));
    double worst = 0.0;
    for (size_t j = 0; j < n; ++j) {
        double p[3], d[3], x[3], lambda[2], len = 0.0;
        projcurve_curve_eval(NULL, c, pts[3 * j], 0, p);
        for (int i = 0; i < 3; ++i) {
            d[i] = p[i] - eye[i];
            len += d[i] * d[i];
        }
        for (int i = 0; i < 3; ++i)
            d[i] /= sqrt(len);
        CHECK(sphere_hits(p, d, lambda) == 2);
        projcurve_surface_eval(NULL, sphere, pts[3 * j + 1], pts[3 * j + 2], 0, x);
        for (int i = 0; i < 3; ++i)
            worst = fmax(worst, fabs(x[i] - (p[i] + lambda[0] * d[i])));
    }
    printf("line onto sphere, nearest hits: %zu vertices, farthest from the front hit %.3g\n", n,
           worst);
    CHECK(n >= 2 && worst <= VERTEX_TOL);
    free(pts);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
}

/* The eye on the sphere, the curve inside it: each ray leaves the sphere
 * once beyond P(t); the eye itself lies behind every P(t). */
static void test_eye_on_sphere(projcurve_surface *sphere)
{
    const double eye[3] = {0.6, 0.0, 0.8};
    const double p0[3] = {-0.2, -0.3, 0.1}, p1[3] = {0.1, 0.3, -0.2};
    projcurve_curve *c = make_segment(p0, p1);
    projcurve_options *o = cc_options(EPS_D);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_conical(NULL, sphere, c, eye, o, &r));
    CHECK(projcurve_result_branch_count(r) == 1);
    double min_lambda;
    const double res = cc_vertex_ray_residual(r, sphere, c, eye, &min_lambda);
    size_t hits = 0;
    const double missed = sphere_missed(r, c, eye, 200, &hits);
    printf("eye on the sphere: %zu branches, ray residual %.3g, %zu hits, farthest %.3g\n",
           projcurve_result_branch_count(r), res, hits, missed);
    CHECK(res <= VERTEX_TOL && min_lambda > 0.0);
    CHECK(hits == 201);
    CHECK(missed <= 1.01 * EPS_D);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
}

/* A line through the plane z = 0: in front of the plane (z > 0) its rays
 * hit it beyond P(t), below it the plane lies between the eye and P(t). */
static void test_curve_crossing(projcurve_surface *plane, int upward)
{
    const double eye[3] = {0.1, 0.2, 3.0};
    const double a[3] = {-0.3, -0.2, 0.5}, b[3] = {0.4, 0.5, -0.5};
    projcurve_curve *c = upward ? make_segment(b, a) : make_segment(a, b);
    projcurve_options *o = cc_options(EPS_D);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_conical(NULL, plane, c, eye, o, &r));
    CHECK(projcurve_result_branch_count(r) == 1);
    projcurve_branch_start start = PROJCURVE_START_FAILED;
    projcurve_branch_end end = PROJCURVE_END_FAILED;
    double tr[2] = {0.0, 0.0};
    projcurve_result_branch_info(NULL, r, 0, tr, &start, &end, NULL, NULL);
    /* z(t) = 0.5 - t (down) or -0.5 + t (up): the crossing at t = 0.5,
     * located to the corrector's tolerance (lambda there ~1e-12) */
    printf("curve crossing (%s): t [%.15g, %.15g], start %d, end %d\n",
           upward ? "up" : "down", tr[0], tr[1], (int)start, (int)end);
    if (upward) {
        CHECK(start == PROJCURVE_START_CURVE_CROSSING && end == PROJCURVE_END_CURVE_END);
        CHECK_NEAR(tr[0], 0.5, 1e-9);
    } else {
        CHECK(start == PROJCURVE_START_CURVE_START && end == PROJCURVE_END_CURVE_CROSSING);
        CHECK_NEAR(tr[1], 0.5, 1e-9);
    }
    double min_lambda;
    CHECK(cc_vertex_ray_residual(r, plane, c, eye, &min_lambda) <= VERTEX_TOL);
    CHECK(min_lambda >= -VERTEX_TOL);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
}

/* An eye far out along -Dir is the directional projection in the limit:
 * the rays differ from Dir by at most ~|P| / distance (1e-7 at 1e7), so
 * every conical vertex lies within eps_D (+ that) of the directional
 * pieces; at 1e200 the ray frame is still finite (no |A|^2 formed). */
static void test_far_eye(projcurve_surface *sphere)
{
    const double dir[3] = {0.0, 0.0, -1.0};
    const double p0[3] = {-0.4, 0.3, 2.0}, p1[3] = {0.5, 0.2, 2.5};
    projcurve_curve *c = make_segment(p0, p1);
    projcurve_options *o = cc_options(EPS_D);
    projcurve_result *rd = NULL;
    CHECK_OK(projcurve_project_directional(NULL, sphere, c, dir, o, &rd));
    cc_pieces pieces;
    CHECK(cc_pieces_sample(rd, &pieces));
    const double distances[2] = {1e7, 1e200};
    for (int k = 0; k < 2; ++k) {
        const double eye[3] = {0.0, 0.0, distances[k]};
        projcurve_result *r = NULL;
        CHECK_OK(projcurve_project_conical(NULL, sphere, c, eye, o, &r));
        CHECK(projcurve_result_branch_count(r) == projcurve_result_branch_count(rd));
        double worst = 0.0;
        for (size_t b = 0; b < projcurve_result_branch_count(r); ++b) {
            size_t n = 0;
            projcurve_result_branch_info(NULL, r, b, NULL, NULL, NULL, &n, NULL);
            double *pts = malloc(3 * n * sizeof *pts);
            projcurve_result_branch_points(NULL, r, b, n, pts, &n);
            for (size_t j = 0; j < n; ++j) {
                double x[3];
                projcurve_surface_eval(NULL, sphere, pts[3 * j + 1], pts[3 * j + 2], 0, x);
                worst = fmax(worst, cc_pieces_dist(&pieces, x));
            }
            free(pts);
        }
        printf("eye at %g: %zu branches (directional %zu), vertices off the directional "
               "pieces %.3g\n",
               distances[k], projcurve_result_branch_count(r),
               projcurve_result_branch_count(rd), worst);
        CHECK(worst <= 1.01 * EPS_D + 1e-6);
        projcurve_result_destroy(r);
    }
    cc_pieces_free(&pieces);
    projcurve_result_destroy(rd);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
}

/* The options the directional projection takes work here too: the
 * cubic pcurves, the RK4 baseline, a constant parameter step, trace only,
 * and a work limit (a partial result, LIMIT_REACHED). Front and back
 * branches each time, every vertex on its ray in front of the curve. */
static void test_options(projcurve_surface *sphere)
{
    const double eye[3] = {0.2, 0.1, 5.0};
    const double p0[3] = {-0.1, 0.25, 3.0}, p1[3] = {0.25, 0.4, 3.1};
    projcurve_curve *c = make_segment(p0, p1);
    for (int variant = 0; variant < 5; ++variant) {
        projcurve_options *o = cc_options(EPS_D);
        projcurve_status expected = PROJCURVE_OK;
        if (variant == 0)
            projcurve_options_set_int(NULL, o, PROJCURVE_OPT_PCURVE_DEGREE, 3);
        else if (variant == 1)
            projcurve_options_set_int(NULL, o, PROJCURVE_OPT_METHOD, PROJCURVE_METHOD_RK4);
        else if (variant == 2)
            projcurve_options_set_double(NULL, o, PROJCURVE_OPT_PARAM_STEP, 0.01);
        else if (variant == 3)
            projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, 0);
        else {
            projcurve_options_set_int(NULL, o, PROJCURVE_OPT_MAX_WORK, 20);
            expected = PROJCURVE_ERR_LIMIT_REACHED;
        }
        projcurve_result *r = NULL;
        CHECK_STATUS(projcurve_project_conical(NULL, sphere, c, eye, o, &r), expected);
        CHECK(r != NULL);
        if (expected == PROJCURVE_OK)
            CHECK(projcurve_result_branch_count(r) == 2);
        double min_lambda = 0.0;
        const double res = cc_vertex_ray_residual(r, sphere, c, eye, &min_lambda);
        printf("options variant %d: %zu branches, ray residual %.3g\n", variant,
               projcurve_result_branch_count(r), res);
        CHECK(res <= VERTEX_TOL);
        CHECK(projcurve_result_branch_count(r) == 0 || min_lambda > 0.0);
        projcurve_result_destroy(r);
        projcurve_options_destroy(o);
    }
    projcurve_curve_destroy(c);
}

/* A line as a callback curve that fails (mode 1) or gives NaN (mode 2)
 * beyond t = 0.6: the projection reports CALLBACK. Mode 0 never fails. */
typedef struct failing_line {
    pc_shape_line line;
    int mode;
} failing_line;

static int failing_line_fn(void *user, double t, double out[9])
{
    failing_line *f = user;
    const int rc = pc_shape_line_fn(&f->line, t, out);
    if (t > 0.6 && f->mode == 1)
        return 1;
    if (t > 0.6 && f->mode == 2)
        out[0] = NAN;
    return rc;
}

static void test_failing_callback(projcurve_surface *plane)
{
    const double eye[3] = {0.1, 0.2, 3.0};
    for (int mode = 0; mode < 3; ++mode) {
        failing_line f = {{{-0.5, -0.3, 1.0}, {0.9, 0.8, 0.3}}, mode};
        projcurve_curve *c = NULL;
        CHECK_OK(projcurve_curve_create_callback(NULL, failing_line_fn, &f, 0.0, 1.0, &c));
        projcurve_result *r = NULL;
        const projcurve_status st = projcurve_project_conical(NULL, plane, c, eye, NULL, &r);
        printf("callback curve, mode %d: %s\n", mode, projcurve_status_string(st));
        CHECK(st == (mode == 0 ? PROJCURVE_OK : PROJCURVE_ERR_CALLBACK));
        if (mode == 0)
            CHECK(projcurve_result_branch_count(r) == 1);
        projcurve_result_destroy(r);
        projcurve_curve_destroy(c);
    }
}

/* An eye just off the curve (a circle inside the sphere, the eye 1e-3 and
 * 1e-9 above one of its points): the rays of the points near it turn
 * through 180 degrees over a t interval of ~ the offset. At 1e-3 the
 * branch is followed through; at 1e-9 it may end FAILED there (counted);
 * either way every vertex returned lies on its ray, in front. */
static void test_eye_near_curve(projcurve_surface *sphere)
{
    const double origin[3] = {0.0, 0.0, 0.0};
    pc_shape_curve sh = pc_shape_circle(origin, 0.5);
    projcurve_curve *c = pc_shape_curve_create(&sh);
    pc_shape_curve_free(&sh);
    double p[3];
    projcurve_curve_eval(NULL, c, 0.3, 0, p);
    const double offsets[2] = {1e-3, 1e-9};
    for (int k = 0; k < 2; ++k) {
        const double eye[3] = {p[0], p[1], p[2] + offsets[k]};
        projcurve_result *r = NULL;
        CHECK_OK(projcurve_project_conical(NULL, sphere, c, eye, NULL, &r));
        double min_lambda = 0.0;
        const double res = cc_vertex_ray_residual(r, sphere, c, eye, &min_lambda);
        printf("eye %g off the curve: %zu branches, %zu failures, ray residual %.3g\n",
               offsets[k], projcurve_result_branch_count(r), projcurve_result_failure_count(r),
               res);
        CHECK(projcurve_result_branch_count(r) >= 1);
        CHECK(res <= VERTEX_TOL && min_lambda > 0.0);
        if (k == 0)
            CHECK(projcurve_result_failure_count(r) == 0);
        projcurve_result_destroy(r);
    }
    projcurve_curve_destroy(c);
}

static void test_bad_eyes(projcurve_surface *plane)
{
    const double p0[3] = {-0.5, -0.3, 1.0}, p1[3] = {0.4, 0.5, 1.3};
    projcurve_curve *c = make_segment(p0, p1);
    projcurve_result *r = NULL;
    /* on the curve: in its interior (t = 0.37) and at its end */
    const double t = 0.37;
    const double inside[3] = {p0[0] + t * (p1[0] - p0[0]), p0[1] + t * (p1[1] - p0[1]),
                              p0[2] + t * (p1[2] - p0[2])};
    CHECK_STATUS(projcurve_project_conical(NULL, plane, c, inside, NULL, &r),
                 PROJCURVE_ERR_SINGULAR);
    CHECK(r == NULL);
    CHECK_STATUS(projcurve_project_conical(NULL, plane, c, p1, NULL, &r),
                 PROJCURVE_ERR_SINGULAR);
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    CHECK_STATUS(projcurve_project_conical(ctx, plane, c, inside, NULL, &r),
                 PROJCURVE_ERR_SINGULAR);
    printf("eye on the curve: %s\n", projcurve_context_message(ctx));
    projcurve_context_destroy(ctx);
    /* a hair off the curve (1e-6, far above the precision): projected */
    const double near[3] = {inside[0], inside[1], inside[2] + 1e-6};
    CHECK_OK(projcurve_project_conical(NULL, plane, c, near, NULL, &r));
    projcurve_result_destroy(r);
    r = NULL;
    const double nan_eye[3] = {0.0, NAN, 1.0}, inf_eye[3] = {INFINITY, 0.0, 1.0};
    CHECK_STATUS(projcurve_project_conical(NULL, plane, c, nan_eye, NULL, &r),
                 PROJCURVE_ERR_NOT_FINITE);
    CHECK_STATUS(projcurve_project_conical(NULL, plane, c, inf_eye, NULL, &r),
                 PROJCURVE_ERR_NOT_FINITE);
    CHECK_STATUS(projcurve_project_conical(NULL, plane, c, NULL, NULL, &r),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK(r == NULL);
    /* the eye on the plane, the curve above it: every ray leaves the plane */
    const double on_plane[3] = {0.1, 0.2, 0.0};
    CHECK_OK(projcurve_project_conical(NULL, plane, c, on_plane, NULL, &r));
    CHECK(projcurve_result_branch_count(r) == 0);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
}

int main(void)
{
    projcurve_surface *plane = make_plane();
    projcurve_surface *sphere = make_sphere();
    CHECK(plane != NULL && sphere != NULL);
    if (plane != NULL && sphere != NULL) {
        test_line_onto_plane(plane);
        test_circle_onto_plane(plane);
        test_sphere_front_and_back(sphere);
        test_sphere_nearest(sphere);
        test_eye_on_sphere(sphere);
        test_far_eye(sphere);
        test_options(sphere);
        test_eye_near_curve(sphere);
        test_curve_crossing(plane, 0);
        test_curve_crossing(plane, 1);
        test_bad_eyes(plane);
        test_failing_callback(plane);
    }
    projcurve_surface_destroy(plane);
    projcurve_surface_destroy(sphere);
    return pc_test_finish("test_conical_shapes");
}
