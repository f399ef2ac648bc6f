/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Projection onto a face with a hole: the plane z = 0 over [-1, 1]^2 with
 * a circular hole of radius 1/2 (an exact rational circle), and the line
 * (-0.9 + 1.8 t, 0.1, 1). Along -z and orthogonally alike the projection
 * is (x(t), 0.1, 0); the face keeps t in [0, t1] and [t2, 1] where
 * x(t) = -+sqrt(1/4 - 0.01): two face pieces, the first ending and the
 * second starting with a TRIM on the hole (the analytic oracle). Seen from
 * the eye E = (0.1, 0.3, 20) (conical), the ray of P(t) meets z = 0 at
 * E + mu (P - E), mu = 20 / 19: the image is the line (0.1 + mu (x(t) -
 * 0.1), 0.3 + mu (0.1 - 0.3), 0), inside the square, and the cuts are where it meets the
 * circle, x = -+sqrt(1/4 - y^2), solved for t in closed form. Then the
 * calls' bad arguments (an eye on the curve among them).
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "projcurve.h"

#define R 0.5
#define Y 0.1

static projcurve_surface *plane(void)
{
    static const double net[] = {-1, -1, 0, 1, -1, 0, -1, 1, 0, 1, 1, 0},
                        knots[] = {-1, -1, 1, 1};
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(NULL, 1, 1, 2, 2, net, NULL, knots, knots, &s));
    return s;
}

static projcurve_face *face_with_hole(const projcurve_surface *s)
{
    static const double outer[] = {-1, -1, 1, -1, 1, 1, -1, 1, -1, -1};
    static const double outer_knots[] = {0, 0, 1, 2, 3, 4, 4};
    const double h = sqrt(0.5);
    /* the circle of radius R as 4 rational quadratic arcs */
    const double circle[] = {R, 0, R, R, 0, R, -R, R, -R, 0, -R, -R, 0, -R, R, -R, R, 0};
    const double cw[] = {1, h, 1, h, 1, h, 1, h, 1};
    static const double circle_knots[] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    const size_t loop_pieces[] = {1, 1};
    const int degrees[] = {1, 2};
    const size_t n_ctrl[] = {5, 9};
    const double *ctrl[] = {outer, circle};
    const double *weights[] = {NULL, cw};
    const double *knots[] = {outer_knots, circle_knots};
    projcurve_face *f = NULL;
    CHECK_OK(projcurve_face_create(NULL, s, 2, loop_pieces, degrees, n_ctrl, ctrl, weights, knots,
                                   0.0, &f));
    return f;
}

static projcurve_curve *line(void)
{
    static const double ctrl[] = {-0.9, Y, 1, 0.9, Y, 1}, knots[] = {0, 0, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 1, 2, ctrl, NULL, knots, &c));
    return c;
}

/* The crossing accuracy is 1e-10 of the model size (the face's box, about
 * 2.9) in 3D; the line moves 1.8 per unit of t: 2e-10 bounds both. */
#define CROSS_TOL 2e-10

static void check_piece_end_on_hole(const projcurve_result *r, size_t branch, int at_end)
{
    size_t n_pieces = 0;
    CHECK_OK(projcurve_result_branch_info(NULL, r, branch, NULL, NULL, NULL, NULL, &n_pieces));
    CHECK(n_pieces > 0);
    if (n_pieces == 0)
        return;
    double uv[4], range[2];
    int degree = 0;
    double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS];
    const size_t k = at_end ? n_pieces - 1 : 0;
    CHECK_OK(projcurve_result_piece(NULL, r, branch, k, &degree, ctrl, NULL, range, uv));
    const double *e = at_end ? uv + 2 : uv;
    /* the cut piece ends on the circle: its pcurve is placed on the loop
     * curve to 1e-3 of the face's ON tolerance (~1e-12) */
    CHECK_NEAR(hypot(e[0], e[1]), R, 1e-10);
    const double *p = at_end ? ctrl + 3 * degree : ctrl;
    CHECK_NEAR(p[0], e[0], 1e-12);
    CHECK_NEAR(p[1], e[1], 1e-12);
    CHECK_NEAR(p[2], 0.0, 1e-12);
}

/* The image of the line on z = 0: (x0 + xs t, yi, 0). */
typedef struct image {
    double x0, xs, yi;
} image;

static void check_projection(const projcurve_face *f, const projcurve_curve *c,
                             projcurve_projection_kind kind, const double *dir, image im)
{
    projcurve_shape_result *sr = NULL;
    CHECK_OK(projcurve_project_face(NULL, f, c, kind, dir, NULL, &sr));
    const double xc = sqrt(R * R - im.yi * im.yi);
    const double t1 = (-xc - im.x0) / im.xs, t2 = (xc - im.x0) / im.xs;
    CHECK(projcurve_shape_result_curve_count(sr) == 2);
    if (projcurve_shape_result_curve_count(sr) != 2) {
        projcurve_shape_result_destroy(sr);
        return;
    }
    for (size_t k = 0; k < 2; ++k) {
        size_t n = 0;
        double tr[2];
        int closed = 1;
        CHECK_OK(projcurve_shape_result_curve_info(NULL, sr, k, &n, tr, &closed));
        CHECK(n == 1);
        CHECK(closed == 0);
        const projcurve_result *r = NULL;
        size_t branch = 9, face = 9;
        projcurve_branch_start start;
        projcurve_branch_end end;
        CHECK_OK(projcurve_shape_result_piece(NULL, sr, k, 0, &face, &r, &branch, tr, &start,
                                              &end));
        CHECK(face == 0);
        double bt[2];
        CHECK_OK(projcurve_result_branch_info(NULL, r, branch, bt, NULL, NULL, NULL, NULL));
        if (k == 0) {
            CHECK_NEAR(tr[0], 0.0, 1e-14);
            CHECK_NEAR(tr[1], t1, CROSS_TOL);
            CHECK(start == PROJCURVE_START_CURVE_START);
            CHECK(end == PROJCURVE_END_TRIM);
        } else {
            CHECK_NEAR(tr[0], t2, CROSS_TOL);
            CHECK_NEAR(tr[1], 1.0, 1e-14);
            CHECK(start == PROJCURVE_START_TRIM);
            CHECK(end == PROJCURVE_END_CURVE_END);
        }
        CHECK_NEAR(bt[0], tr[0], 1e-14);
        CHECK_NEAR(bt[1], tr[1], 1e-14);
        /* every traced point: on the projection (analytic) and on the face */
        double pts[3 * 4096];
        size_t count = 0;
        CHECK_OK(projcurve_result_branch_points(NULL, r, branch, 4096, pts, &count));
        CHECK(count >= 2);
        for (size_t i = 0; i < count && i < 4096; ++i) {
            CHECK_NEAR(pts[3 * i + 1], im.x0 + im.xs * pts[3 * i], 1e-10);
            CHECK_NEAR(pts[3 * i + 2], im.yi, 1e-10);
            projcurve_where w;
            CHECK_OK(projcurve_face_classify(NULL, f, pts[3 * i + 1], pts[3 * i + 2], &w));
            CHECK(w != PROJCURVE_OUT);
        }
        check_piece_end_on_hole(r, branch, k == 0);
        /* the compact 3D curve, restricted to the kept range */
        projcurve_curve *cc = NULL;
        CHECK_OK(projcurve_result_branch_compact_curve(NULL, r, branch, &cc));
        double d0 = 0, d1 = 0, q[3];
        CHECK_OK(projcurve_curve_domain(NULL, cc, &d0, &d1));
        CHECK_NEAR(d0, tr[0], 1e-14);
        CHECK_NEAR(d1, tr[1], 1e-14);
        CHECK_OK(projcurve_curve_eval(NULL, cc, 0.5 * (d0 + d1), 0, q));
        /* within eps_D (1e-4 of the size) of the projection */
        CHECK_NEAR(q[0], im.x0 + 0.5 * im.xs * (d0 + d1), 3e-4);
        CHECK_NEAR(q[1], im.yi, 3e-4);
        projcurve_curve_destroy(cc);
    }
    projcurve_shape_result_destroy(sr);
}

static void check_bad_input(const projcurve_face *f, const projcurve_curve *c)
{
    const double dir[3] = {0, 0, -1}, zero[3] = {0, 0, 0};
    projcurve_shape_result *sr = NULL;
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    /* an eye on the curve: the ray of that point has no direction */
    const double on_curve[3] = {0.3, Y, 1}, nan_eye[3] = {0, NAN, 5};
    CHECK_STATUS(projcurve_project_face(ctx, f, c, PROJCURVE_PROJECT_CONICAL, on_curve, NULL,
                                        &sr),
                 PROJCURVE_ERR_SINGULAR);
    CHECK(projcurve_context_message(ctx)[0] != '\0');
    CHECK_STATUS(projcurve_project_face(ctx, f, c, PROJCURVE_PROJECT_CONICAL, nan_eye, NULL, &sr),
                 PROJCURVE_ERR_NOT_FINITE);
    CHECK_STATUS(projcurve_project_face(ctx, f, c, PROJCURVE_PROJECT_CONICAL, NULL, NULL, &sr),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_project_face(ctx, f, c, (projcurve_projection_kind)7, dir, NULL, &sr),
                 PROJCURVE_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(projcurve_project_face(ctx, f, c, PROJCURVE_PROJECT_DIRECTIONAL, zero, NULL, &sr),
                 PROJCURVE_ERR_ZERO_DIRECTION);
    CHECK_STATUS(projcurve_project_face(ctx, f, c, PROJCURVE_PROJECT_DIRECTIONAL, NULL, NULL, &sr),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_project_face(ctx, NULL, c, PROJCURVE_PROJECT_DIRECTIONAL, dir, NULL,
                                        &sr),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_project_shape(ctx, NULL, c, PROJCURVE_PROJECT_DIRECTIONAL, dir, NULL,
                                         &sr),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK(sr == NULL);
    CHECK(projcurve_shape_result_curve_count(NULL) == 0);
    CHECK_STATUS(projcurve_shape_result_curve_info(ctx, NULL, 0, NULL, NULL, NULL),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    /* a curve that misses the face: OK, nothing */
    static const double far[] = {5, 5, 1, 6, 5, 1}, knots[] = {0, 0, 1, 1};
    projcurve_curve *miss = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 1, 2, far, NULL, knots, &miss));
    CHECK_OK(projcurve_project_face(ctx, f, miss, PROJCURVE_PROJECT_DIRECTIONAL, dir, NULL, &sr));
    CHECK(projcurve_shape_result_curve_count(sr) == 0);
    CHECK_STATUS(projcurve_shape_result_piece(ctx, sr, 0, 0, NULL, NULL, NULL, NULL, NULL, NULL),
                 PROJCURVE_ERR_INDEX);
    projcurve_shape_result_destroy(sr);
    projcurve_curve_destroy(miss);
    projcurve_shape_result_destroy(NULL);
    projcurve_context_destroy(ctx);
}

int main(void)
{
    projcurve_surface *s = plane();
    projcurve_face *f = face_with_hole(s);
    projcurve_curve *c = line();
    const double down[3] = {0, 0, -1};
    const image straight = {-0.9, 1.8, Y};
    check_projection(f, c, PROJCURVE_PROJECT_DIRECTIONAL, down, straight);
    check_projection(f, c, PROJCURVE_PROJECT_ORTHOGONAL, NULL, straight);
    const double eye[3] = {0.1, 0.3, 20}, mu = 20.0 / 19.0;
    const image seen = {0.1 + mu * (-0.9 - 0.1), mu * 1.8, 0.3 + mu * (Y - 0.3)};
    check_projection(f, c, PROJCURVE_PROJECT_CONICAL, eye, seen);
    check_bad_input(f, c);
    projcurve_curve_destroy(c);
    projcurve_face_destroy(f);
    projcurve_surface_destroy(s);
    return pc_test_finish("test_faceproj_hole");
}
