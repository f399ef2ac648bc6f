/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A loop crossing between two points of the clip's polyline: the plane
 * z = 0 over [-1, 1]^2 as a face with a hole, and the arc of radius 1/2
 * around the origin from -40 to 40 degrees (one exact rational quadratic)
 * at z = 1, projected along -z at eps_D 0.2 (7 % of the model: the
 * refinement keeps one cubic piece). The hole is the quadrilateral
 * between the angles 25 and 36 degrees and the radii 0.497 and 0.6: the
 * arc runs through it, but the piece's pcurve sampled for the polyline
 * (at a quarter of the piece apart) has its chord there 0.002 inside the
 * hole's inner edge, so the polyline meets no loop (the dip is less than
 * eps_D deep, the case faceproj/loop_crossing.h names). The side search
 * (loop_crossing_sides.c) classifies the exact projection at the
 * segments' middles, finds one in the hole and places both crossings.
 * Oracle: the projection of the arc is the arc itself on z = 0, so the
 * crossings are where it meets the hole's radial edges, at 25 and 36
 * degrees exactly, and their t is where the curve's angle is that
 * (bisection on P). Two face pieces: [0, t(25)] ending TRIM and
 * [t(36), 1] starting TRIM; every traced point on the face. Before the
 * search the face kept one piece over [0, 1] through the hole.
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "projcurve.h"

#define R 0.5
#define HALF_DEG 40.0
#define A0_DEG 25.0
#define A1_DEG 36.0
#define R_IN 0.497
#define R_OUT 0.6
#define EPS_D 0.2
/* The crossing accuracy is 1e-10 of the model size (the face's box, 2.8)
 * in 3D, and the arc moves ~1.4 per unit of t: 1e-9 bounds both. */
#define CROSS_TOL 1e-9

static const double deg = 3.14159265358979323846 / 180.0;

static projcurve_face *face_with_hole(const projcurve_surface *s)
{
    static const double outer[] = {-0.9, -0.9, 0.9, -0.9, 0.9, 0.9, -0.9, 0.9, -0.9, -0.9};
    const double a0 = A0_DEG * deg, a1 = A1_DEG * deg;
    /* clockwise: a hole */
    const double hole[] = {R_IN * cos(a0),  R_IN * sin(a0),  R_IN * cos(a1),  R_IN * sin(a1),
                           R_OUT * cos(a1), R_OUT * sin(a1), R_OUT * cos(a0), R_OUT * sin(a0),
                           R_IN * cos(a0),  R_IN * sin(a0)};
    static const double knots[] = {0, 0, 1, 2, 3, 4, 4};
    const size_t loop_pieces[] = {1, 1};
    const int degrees[] = {1, 1};
    const size_t n_ctrl[] = {5, 5};
    const double *ctrl[] = {outer, hole};
    const double *weights[] = {NULL, NULL};
    const double *kv[] = {knots, knots};
    projcurve_face *f = NULL;
    CHECK_OK(projcurve_face_create(NULL, s, 2, loop_pieces, degrees, n_ctrl, ctrl, weights, kv,
                                   0.0, &f));
    return f;
}

static projcurve_curve *arc(void)
{
    const double a = HALF_DEG * deg;
    const double ctrl[] = {R * cos(a), -R * sin(a), 1, R / cos(a), 0, 1,
                           R * cos(a), R * sin(a),  1};
    const double w[] = {1, cos(a), 1}, knots[] = {0, 0, 0, 1, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 2, 3, ctrl, w, knots, &c));
    return c;
}

/* t where the arc's angle is `angle` (increasing along it): bisection to
 * rounding. */
static double t_of_angle(const projcurve_curve *c, double angle)
{
    double lo = 0.0, hi = 1.0;
    for (int k = 0; k < 200; ++k) {
        const double m = 0.5 * (lo + hi);
        double p[3] = {0, 0, 0};
        if (m <= lo || m >= hi)
            break;
        CHECK_OK(projcurve_curve_eval(NULL, c, m, 0, p));
        if (atan2(p[1], p[0]) < angle)
            lo = m;
        else
            hi = m;
    }
    return 0.5 * (lo + hi);
}

static void check_end(const projcurve_result *r, size_t branch, int at_end, double angle)
{
    double pts[3 * 4096];
    size_t n = 0;
    CHECK_OK(projcurve_result_branch_points(NULL, r, branch, 4096, pts, &n));
    CHECK(n >= 2);
    if (n < 2)
        return;
    const double *e = at_end ? pts + 3 * (n - 1) : pts;
    CHECK_NEAR(e[1], R * cos(angle), CROSS_TOL);
    CHECK_NEAR(e[2], R * sin(angle), CROSS_TOL);
}

int main(void)
{
    static const double net[] = {-1, -1, 0, 1, -1, 0, -1, 1, 0, 1, 1, 0},
                        knots[] = {-1, -1, 1, 1};
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(NULL, 1, 1, 2, 2, net, NULL, knots, knots, &s));
    projcurve_face *f = face_with_hole(s);
    projcurve_curve *c = arc();
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE, EPS_D));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_ANGLE_DEG, 60.0));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_PCURVE_DEGREE, 3));
    const double down[3] = {0, 0, -1};
    /* the premise: the untrimmed projection is one branch of one piece */
    projcurve_result *u = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c, down, o, &u));
    size_t u_pieces = 0;
    CHECK(projcurve_result_branch_count(u) == 1);
    CHECK_OK(projcurve_result_branch_info(NULL, u, 0, NULL, NULL, NULL, NULL, &u_pieces));
    CHECK(u_pieces == 1);
    projcurve_result_destroy(u);

    projcurve_shape_result *sr = NULL;
    CHECK_OK(projcurve_project_face(NULL, f, c, PROJCURVE_PROJECT_DIRECTIONAL, down, o, &sr));
    const projcurve_result *r = NULL;
    CHECK_OK(projcurve_shape_result_face(NULL, sr, 0, NULL, &r, NULL, NULL));
    const size_t nb = projcurve_result_branch_count(r);
    const double t0 = t_of_angle(c, A0_DEG * deg), t1 = t_of_angle(c, A1_DEG * deg);
    printf("%zu face piece(s); the hole cuts the arc at t %.12f and %.12f\n", nb, t0, t1);
    CHECK(nb == 2);
    for (size_t b = 0; b < nb && nb == 2; ++b) {
        double tr[2];
        projcurve_branch_start start;
        projcurve_branch_end end;
        CHECK_OK(projcurve_result_branch_info(NULL, r, b, tr, &start, &end, NULL, NULL));
        printf("piece %zu: t [%.12f, %.12f], start %d, end %d\n", b, tr[0], tr[1], (int)start,
               (int)end);
        if (b == 0) {
            CHECK_NEAR(tr[0], 0.0, 1e-14);
            CHECK_NEAR(tr[1], t0, CROSS_TOL);
            CHECK(start == PROJCURVE_START_CURVE_START);
            CHECK(end == PROJCURVE_END_TRIM);
            check_end(r, b, 1, A0_DEG * deg);
        } else {
            CHECK_NEAR(tr[0], t1, CROSS_TOL);
            CHECK_NEAR(tr[1], 1.0, 1e-14);
            CHECK(start == PROJCURVE_START_TRIM);
            CHECK(end == PROJCURVE_END_CURVE_END);
            check_end(r, b, 0, A1_DEG * deg);
        }
        /* every traced point on the face */
        double pts[3 * 4096];
        size_t n = 0;
        CHECK_OK(projcurve_result_branch_points(NULL, r, b, 4096, pts, &n));
        for (size_t i = 0; i < n && i < 4096; ++i) {
            projcurve_where w = PROJCURVE_OUT;
            CHECK_OK(projcurve_face_classify(NULL, f, pts[3 * i + 1], pts[3 * i + 2], &w));
            CHECK(w != PROJCURVE_OUT);
        }
    }
    projcurve_shape_result_destroy(sr);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
    projcurve_face_destroy(f);
    projcurve_surface_destroy(s);
    return pc_test_finish("test_faceproj_missed_crossing");
}
