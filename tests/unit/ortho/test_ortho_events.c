/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Where branches of the orthogonal projection begin and end, against
 * analytic answers: pairs of foot points born and dying at centres of
 * curvature in mid-curve (a parabolic cylinder, whose foot points are the
 * real roots of a cubic), a foot point entering through the boundary, a
 * curve crossing the centre circle of a torus' tube, and foot points
 * crossing the seam of a closed surface given with clamped knots.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "shapes.h"
#include "unjoined.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* P(t) = c + a (cos t, sin t, 0) + t * lin. */
typedef struct path {
    double c[3], a, lin[3];
} path;

static int path_fn(void *user, double t, double out[9])
{
    const path *w = user;
    const double v[9] = {w->c[0] + w->a * cos(t) + t * w->lin[0],
                         w->c[1] + w->a * sin(t) + t * w->lin[1],
                         w->c[2] + t * w->lin[2],
                         -w->a * sin(t) + w->lin[0], w->a * cos(t) + w->lin[1], w->lin[2],
                         -w->a * cos(t), -w->a * sin(t), 0.0};
    memcpy(out, v, sizeof v);
    return 0;
}

typedef struct branch {
    double range[2];
    projcurve_branch_start start;
    projcurve_branch_end end;
    size_t n;
    double *pts; /* (t, u, v) per vertex */
} branch;

/* Projects the path and copies every branch out (caller frees). */
static size_t project_with_step(const projcurve_surface *surf, const path *w, double t0,
                                double t1, double param_step, branch *out, size_t cap)
{
    projcurve_curve *curve = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, path_fn, (void *)w, t0, t1, &curve));
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    /* far-side feet (saddles, maxima) are part of the expected answer */
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_FOOT_POINTS,
                                       PROJCURVE_FOOT_POINTS_ALL));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE, 1e-4));
    if (param_step > 0.0)
        CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_PARAM_STEP, param_step));
    projcurve_result *r = NULL;
    /* the tracer's own ends at the poles and seams, which the seam stage
     * (src/seam/, tested in tests/unit/seam/) would join */
    CHECK_OK(pc_test_project_unjoined(NULL, surf, curve, NULL, o, &r));
    size_t nb = projcurve_result_branch_count(r);
    nb = nb < cap ? nb : cap;
    for (size_t b = 0; b < nb; ++b) {
        branch *br = &out[b];
        CHECK_OK(projcurve_result_branch_info(NULL, r, b, br->range, &br->start, &br->end,
                                              &br->n, NULL));
        br->pts = malloc(3 * br->n * sizeof *br->pts);
        size_t got = 0;
        CHECK_OK(projcurve_result_branch_points(NULL, r, b, br->n, br->pts, &got));
        CHECK(got == br->n);
        printf("  branch %zu t [%.9f, %.9f] start %d end %d, %zu vertices\n", b, br->range[0],
               br->range[1], (int)br->start, (int)br->end, br->n);
    }
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(curve);
    return nb;
}

/* Arc-length steps (the default). */
static size_t project(const projcurve_surface *surf, const path *w, double t0, double t1,
                      branch *out, size_t cap)
{
    return project_with_step(surf, w, t0, t1, 0.0, out, cap);
}

static void free_branches(branch *b, size_t n)
{
    for (size_t i = 0; i < n; ++i)
        free(b[i].pts);
}

/* ---- parabolic cylinder z = K x^2 ---------------------------------------
 * Over x in [-20, 20] (x = -20 + 40 u exactly: control points at the
 * Greville abscissae), y in [-5, 5]. The foot points of P = (px, 0, H) lie
 * at y = 0 and solve (x - px) + (K x^2 - H) 2 K x = 0, i.e.
 *     2 K^2 x^3 + (1 - 2 K H) x - px = 0.
 * With K = 0.05 and H = 20: 0.005 x^3 - x - px = 0, three real roots for
 * |px| < c* = sqrt(4 / (27 * 0.005)) = 5.4433 (P inside the evolute), one
 * outside. Along px = t in [-10, 10], a pair is born at t = -c* at
 * x = +sqrt(1 / 0.015) and a pair dies at t = +c* at x = -sqrt(1 / 0.015):
 * both are centres of curvature of the profile (folds of the normal map). */
#define PARA_K 0.05
#define PARA_H 20.0
#define PARA_X 20.0

/* Real roots of the cubic, by the trigonometric form of x^3 + p x + q = 0
 * when there are three (Cardano otherwise). A double root (P on the
 * evolute) is kept double: the discriminant is clamped there. */
static int para_roots(double px, double roots[3])
{
    const double a = 2.0 * PARA_K * PARA_K;
    const double p = (1.0 - 2.0 * PARA_K * PARA_H) / a, q = -px / a;
    const double disc = q * q / 4.0 + p * p * p / 27.0;
    if (disc <= 1e-12 * (-p * p * p / 27.0)) {
        const double m = 2.0 * sqrt(-p / 3.0);
        const double c = fmax(-1.0, fmin(1.0, 3.0 * q / (p * m)));
        const double theta = acos(c) / 3.0;
        for (int k = 0; k < 3; ++k)
            roots[k] = m * cos(theta - 2.0 * M_PI * k / 3.0);
        return 3;
    }
    roots[0] = cbrt(-q / 2.0 + sqrt(disc)) + cbrt(-q / 2.0 - sqrt(disc));
    return 1;
}

/* Distance from x to the nearest root at px. */
static double root_error(double x, double px)
{
    double roots[3], best = INFINITY;
    const int n = para_roots(px, roots);
    for (int k = 0; k < n; ++k)
        best = fmin(best, fabs(x - roots[k]));
    return best;
}

static projcurve_surface *parabolic_cylinder(void)
{
    /* Quadratic Bezier in x: z = K x^2 with x linear in u has control
     * heights K a^2, K a (a + b), K (a + b)^2 for x = a + b u. */
    const double a = -PARA_X, b = 2.0 * PARA_X;
    double ctrl[3 * 3 * 2], ku[6] = {0, 0, 0, 1, 1, 1}, kv[4] = {0, 0, 1, 1};
    const double z[3] = {PARA_K * a * a, PARA_K * a * (a + b), PARA_K * (a + b) * (a + b)};
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i) {
            double *c = ctrl + 3 * (3 * j + i);
            c[0] = a + 0.5 * b * i;
            c[1] = j ? 5.0 : -5.0;
            c[2] = z[i];
        }
    const pc_shape_surface s = {2, 1, 3, 2, ctrl, NULL, ku, kv};
    return pc_shape_surface_create(&s);
}

static void test_births_at_centres(void)
{
    printf("parabolic cylinder, P(t) = (t, 0, %g), t in [-10, 10]\n", PARA_H);
    projcurve_surface *surf = parabolic_cylinder();
    const path line = {{0, 0, PARA_H}, 0.0, {1, 0, 0}};
    branch br[8];
    const size_t nb = project(surf, &line, -10.0, 10.0, br, 8);
    const double c_star = sqrt(4.0 / (27.0 * 2.0 * PARA_K * PARA_K));
    /* Three branches: the left root until the pair dies at +c*; the pair
     * born at -c* (one dies at +c*, one reaches the end). */
    CHECK(nb == 3);
    int born = 0, died = 0, whole_left = 0, to_end = 0;
    double worst_vertex = 0.0;
    /* A fold end is where |det K| reaches the engine's 1e-6: x - x* and
     * det K ~ sqrt(|t - t*|) there, so the end is within ~1e-10 in t. */
    const double t_tol = 1e-6;
    for (size_t b = 0; b < nb; ++b) {
        for (size_t i = 0; i < br[b].n; ++i) {
            const double *p = br[b].pts + 3 * i;
            worst_vertex = fmax(worst_vertex, root_error(-PARA_X + 2.0 * PARA_X * p[1], p[0]));
            CHECK_NEAR(p[2], 0.5, 1e-9);
        }
        if (br[b].start == PROJCURVE_START_SILHOUETTE && fabs(br[b].range[0] + c_star) <= t_tol)
            ++born;
        if (br[b].end == PROJCURVE_END_CURVATURE_CENTRE && fabs(br[b].range[1] - c_star) <= t_tol)
            ++died;
        if (br[b].start == PROJCURVE_START_CURVE_START && br[b].range[0] == -10.0)
            ++whole_left;
        if (br[b].end == PROJCURVE_END_CURVE_END && br[b].range[1] == 10.0)
            ++to_end;
    }
    printf("  worst vertex error %.1e, born %d, died %d\n", worst_vertex, born, died);
    CHECK(worst_vertex <= 1e-8);
    CHECK(born == 2);
    CHECK(died == 2);
    CHECK(whole_left == 1);
    CHECK(to_end == 1);
    /* Nothing missed: at 401 values of t the branches alive number the
     * analytic roots (the vertices, all on roots, show which). */
    int miscounted = 0;
    for (int i = 0; i <= 400; ++i) {
        const double t = -10.0 + 20.0 * i / 400.0;
        double roots[3];
        const int n = para_roots(t, roots);
        int alive = 0;
        for (size_t b = 0; b < nb; ++b)
            alive += br[b].range[0] <= t && t <= br[b].range[1];
        if (alive != n && fabs(fabs(t) - c_star) > t_tol) {
            if (miscounted < 5)
                printf("  t = %.4f: %d branches, %d foot points\n", t, alive, n);
            ++miscounted;
        }
    }
    CHECK(miscounted == 0);
    free_branches(br, nb);
    projcurve_surface_destroy(surf);
}

/* The plane S(u, v) = (2u - 1, 3v - 1, 0): the curve starts beyond x = -1
 * and enters; its foot point is born on the boundary at t = 0.5 exactly. */
static void test_boundary_entry(void)
{
    printf("plane, foot point entering through x = -1\n");
    pc_shape_surface data = pc_shape_plane(3, 3, 2, 2);
    projcurve_surface *surf = pc_shape_surface_create(&data);
    pc_shape_surface_free(&data);
    const path line = {{-1.5, 0.5, 0.3}, 0.0, {1, 0, 0}};
    branch br[4];
    const size_t nb = project(surf, &line, 0.0, 2.0, br, 4);
    CHECK(nb == 1);
    if (nb == 1) {
        CHECK(br[0].start == PROJCURVE_START_BOUNDARY);
        CHECK_NEAR(br[0].range[0], 0.5, 1e-9);
        CHECK_NEAR(br[0].pts[1], 0.0, 1e-12);
        CHECK(br[0].end == PROJCURVE_END_CURVE_END);
    }
    free_branches(br, nb);
    projcurve_surface_destroy(surf);
}

/* Torus (R = 10, r = 3) with the seam around the tube moved from the outer
 * equator to the top (v shifted by a quarter turn: the circle's 9-point
 * net is periodic with period 2 in its weights), so that no foot point
 * below crosses a seam. The line P(t) = (0.2 t, 10 + t, 0.5 t) crosses the
 * centre circle of the tube at t = 0, a centre of curvature of every point
 * of the tube's meridian circle there (1 + rho k_tube = 0 changes sign: a
 * transversal crossing). The two foot points on that side (u = 1/4) swap
 * through it: both branches end at t = 0 and two start there; none may run
 * across. On the far side (u = 3/4) the two foot points pass undisturbed. */
static void test_torus_tube_centre(void)
{
    printf("torus, line through the tube's centre circle at t = 0\n");
    pc_shape_surface data = pc_shape_torus(10.0, 3.0);
    CHECK(data.n_v == 9);
    double *shifted = malloc(3 * data.n_u * data.n_v * sizeof *shifted);
    for (size_t j = 0; j < data.n_v; ++j)
        memcpy(shifted + 3 * j * data.n_u, data.ctrl + 3 * ((j + 2) % 8) * data.n_u,
               3 * data.n_u * sizeof *shifted);
    free(data.ctrl);
    data.ctrl = shifted;
    projcurve_surface *surf = pc_shape_surface_create(&data);
    pc_shape_surface_free(&data);
    double top[3];
    CHECK_OK(projcurve_surface_eval(NULL, surf, 0.0, 0.0, 0, top));
    CHECK_NEAR(top[2], 3.0, 1e-12);
    const path line = {{0.0, 10, 0}, 0.0, {0.2, 1, 0.5}};
    branch br[16];
    const size_t nb = project(surf, &line, -1.0, 1.0, br, 16);
    CHECK(nb == 6);
    int ended = 0, started = 0, far_whole = 0;
    /* det K vanishes linearly in t: the engine's 1e-6 stop is ~1e-6 before. */
    const double t_tol = 1e-5;
    for (size_t b = 0; b < nb; ++b) {
        const int near_side = fabs(br[b].pts[1] - 0.25) < 0.125;
        if (near_side) {
            CHECK(!(br[b].range[0] < -t_tol && br[b].range[1] > t_tol));
            if (br[b].end == PROJCURVE_END_CURVATURE_CENTRE && fabs(br[b].range[1]) <= t_tol)
                ++ended;
            if (br[b].start == PROJCURVE_START_SILHOUETTE && fabs(br[b].range[0]) <= t_tol)
                ++started;
        } else {
            far_whole += br[b].start == PROJCURVE_START_CURVE_START &&
                         br[b].end == PROJCURVE_END_CURVE_END;
        }
    }
    printf("  %d branches end at the centre, %d start there, %d far ones whole\n", ended,
           started, far_whole);
    CHECK(ended == 2);
    CHECK(started == 2);
    CHECK(far_whole == 2);
    free_branches(br, nb);
    projcurve_surface_destroy(surf);
}

/* The torus as built (seam around the tube on the outer equator), the line
 * P(t) = (10 + t, 0.2 t, 0.5 t) through the tube's centre at (10, 0, 0):
 * three events at t = 0 at once. The near-side foot points (u at the seam
 * u = 0 / 1 as well) swap through the centre of curvature, and the far
 * side's outer foot point crosses the tube's seam v = 0 / 1 at the same t.
 * This once gave a branch of 10^6 vertices at t = 0 and LIMIT_REACHED
 * (before the corrector kept its confirming evaluation near centres). */
static void test_torus_centre_on_seams(void)
{
    printf("torus, line through the tube's centre on the seams at t = 0\n");
    pc_shape_surface data = pc_shape_torus(10.0, 3.0);
    projcurve_surface *surf = pc_shape_surface_create(&data);
    pc_shape_surface_free(&data);
    const path line = {{10, 0, 0}, 0.0, {1, 0.2, 0.5}};
    branch br[16];
    const size_t nb = project(surf, &line, -1.0, 1.0, br, 16);
    CHECK(nb == 7);
    /* The near side's foot points sit on the u seam at the centre, so
     * either reason names their ends truthfully; what must hold is that
     * three branches end and three start at t = 0, each for one of them,
     * and one runs through. */
    int ended = 0, started = 0, whole = 0;
    for (size_t b = 0; b < nb; ++b) {
        CHECK(br[b].n < 1000);
        ended += (br[b].end == PROJCURVE_END_CURVATURE_CENTRE ||
                  br[b].end == PROJCURVE_END_BOUNDARY) &&
                 fabs(br[b].range[1]) <= 1e-5;
        started += (br[b].start == PROJCURVE_START_SILHOUETTE ||
                    br[b].start == PROJCURVE_START_BOUNDARY) &&
                   fabs(br[b].range[0]) <= 1e-5;
        whole += br[b].start == PROJCURVE_START_CURVE_START && br[b].end == PROJCURVE_END_CURVE_END;
    }
    printf("  %d end and %d start at t = 0, %d whole\n", ended, started, whole);
    CHECK(ended == 3 && started == 3 && whole == 1);
    free_branches(br, nb);
    projcurve_surface_destroy(surf);
}

/* Constant parameter steps far longer than the distance to a centre of
 * curvature must not step over it: a line through the axis of a cylinder
 * (R = 5) at t = 2 with steps of 0.7 (the third step would jump from 1.4 to
 * 2.1), and a circle through the centre of a sphere (R = 10) at t = pi
 * with steps of 0.3 (an umbilic: det K touches zero without a sign change,
 * so only the Morse index shows the crossing). Every branch that reaches
 * the centre ends there, none runs across. The ends are the last points
 * with |det K| / (|Su||Sv|)^2 >= 1e-6 (ortho_centres.c): at the axis det K
 * vanishes linearly (~2e-6 in t); at the umbilic quadratically, det ~
 * (d / R)^2 with d = 5 |t - pi|, so >= 1e-6 needs |t - pi| >= 2e-3, and the
 * bisection keeps a point within twice its last bracket: ~8e-3 at most. */
static void expect_cut_at(const char *name, const branch *br, size_t nb, double t_centre,
                          double t_tol)
{
    int ended = 0;
    for (size_t b = 0; b < nb; ++b) {
        CHECK(!(br[b].range[0] < t_centre - t_tol && br[b].range[1] > t_centre + t_tol));
        ended += br[b].end == PROJCURVE_END_CURVATURE_CENTRE &&
                 fabs(br[b].range[1] - t_centre) <= t_tol;
    }
    printf("  %s: %d branches end at the centre\n", name, ended);
    CHECK(ended >= 1);
}

static void test_coarse_steps(void)
{
    printf("coarse constant steps across centres of curvature\n");
    pc_shape_surface cyl_data = pc_shape_cylinder(5.0, 10.0);
    projcurve_surface *cyl = pc_shape_surface_create(&cyl_data);
    pc_shape_surface_free(&cyl_data);
    const path line = {{-2, -1, 4}, 0.0, {1, 0.5, 0.5}};
    branch br[8];
    size_t nb = project_with_step(cyl, &line, 0.0, 4.0, 0.7, br, 8);
    expect_cut_at("cylinder axis", br, nb, 2.0, 1e-5);
    free_branches(br, nb);
    projcurve_surface_destroy(cyl);

    const double centre[3] = {0, 0, 0};
    pc_shape_surface sph_data = pc_shape_sphere(centre, 10.0);
    projcurve_surface *sph = pc_shape_surface_create(&sph_data);
    pc_shape_surface_free(&sph_data);
    const path circle = {{5, 0, 0}, 5.0, {0, 0, 0}};
    nb = project_with_step(sph, &circle, 0.5 * M_PI, 1.4 * M_PI, 0.3, br, 8);
    expect_cut_at("sphere centre", br, nb, M_PI, 1e-2);
    free_branches(br, nb);
    projcurve_surface_destroy(sph);
}

/* A closed surface given with clamped knots has a seam: u = 0 and u = 1 are
 * the same points of S but the boundary of the parameter domain. A foot
 * point moving across it is two branches: one leaves through the boundary
 * at the seam, the other enters there at the same t and the same point of
 * S, and the result says so with END_BOUNDARY / START_BOUNDARY. Cylinder
 * R = 5 (seam in the plane y = 0, x > 0), the curve at radius 7 crossing
 * angle 0 at t = 0: the near foot points cross the seam, the far ones
 * (angle pi) do not. */
static void test_seam(void)
{
    printf("cylinder, near foot points crossing the seam at t = 0\n");
    pc_shape_surface data = pc_shape_cylinder(5.0, 10.0);
    projcurve_surface *surf = pc_shape_surface_create(&data);
    pc_shape_surface_free(&data);
    double s0[3], s1[3];
    CHECK_OK(projcurve_surface_eval(NULL, surf, 0.0, 0.5, 0, s0));
    CHECK_OK(projcurve_surface_eval(NULL, surf, 1.0, 0.5, 0, s1));
    CHECK(fabs(s0[1]) < 1e-12 && s0[0] > 0.0 && fabs(s1[0] - s0[0]) < 1e-12);
    const path arc = {{0, 0, 5}, 7.0, {0, 0, 0}};
    branch br[8];
    const size_t nb = project(surf, &arc, -0.5, 0.5, br, 8);
    CHECK(nb == 3);
    const branch *leaves = NULL, *enters = NULL;
    for (size_t b = 0; b < nb; ++b) {
        if (br[b].end == PROJCURVE_END_BOUNDARY)
            leaves = &br[b];
        if (br[b].start == PROJCURVE_START_BOUNDARY)
            enters = &br[b];
    }
    CHECK(leaves != NULL && enters != NULL);
    if (leaves != NULL && enters != NULL) {
        const double *a = leaves->pts + 3 * (leaves->n - 1), *b = enters->pts;
        double pa[3], pb[3];
        CHECK_OK(projcurve_surface_eval(NULL, surf, a[1], a[2], 0, pa));
        CHECK_OK(projcurve_surface_eval(NULL, surf, b[1], b[2], 0, pb));
        printf("  leaves at t %.12f u %.12f, enters at t %.12f u %.12f\n", a[0], a[1], b[0],
               b[1]);
        CHECK_NEAR(a[0], 0.0, 1e-9);
        CHECK_NEAR(b[0], 0.0, 1e-9);
        CHECK(fabs(a[1] - b[1]) == 1.0); /* opposite ends of the u domain */
        CHECK_NEAR(hypot(pa[0] - pb[0], pa[1] - pb[1]), 0.0, 1e-8);
        CHECK_NEAR(pa[2] - pb[2], 0.0, 1e-8);
    }
    free_branches(br, nb);
    projcurve_surface_destroy(surf);
}

int main(void)
{
    test_births_at_centres();
    test_boundary_entry();
    test_torus_tube_centre();
    test_torus_centre_on_seams();
    test_coarse_steps();
    test_seam();
    return pc_test_finish("test_ortho_events");
}
