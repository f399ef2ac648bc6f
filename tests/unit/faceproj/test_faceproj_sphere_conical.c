/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Conical projection onto faces of the unit sphere (u around z, v from the
 * south pole to the north pole): the segment (-0.1, 0.25, 3) -> (0.25,
 * 0.4, 3.1) seen from the eye (0.2, 0.1, 5). Every ray meets the sphere
 * twice, the front hit on the north hemisphere, the back one on the south
 * (closed form: the roots of |p + lambda d|^2 = 1).
 *   - the north face (v in [1/2, 1]): all hits and nearest alike give one
 *     piece over the whole curve, each point the analytic front hit (the
 *     back hits are outside the face);
 *   - the south face (v in [0, 1/2]) with nearest: the front hemisphere is
 *     trimmed away, so it is no hit and hides nothing; one piece over the
 *     whole curve, each point the analytic back hit.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "brep/face.h"
#include "check.h"
#include "projcurve.h"
#include "shapes.h"

static projcurve_face *band(const projcurve_surface *s, double v0, double v1)
{
    const double c[5][2] = {{0, v0}, {1, v0}, {1, v1}, {0, v1}, {0, v0}};
    double ctrl[4][4];
    static const double knots[] = {0, 0, 1, 1};
    pc_piece_input pieces[4];
    for (int k = 0; k < 4; ++k) {
        ctrl[k][0] = c[k][0];
        ctrl[k][1] = c[k][1];
        ctrl[k][2] = c[k + 1][0];
        ctrl[k][3] = c[k + 1][1];
        pieces[k] = (pc_piece_input){.degree = 1, .n_ctrl = 2, .ctrl = ctrl[k], .knots = knots,
                                     .edge = k + 1, .sense = 1, .edge_sense = 1};
    }
    const pc_loop_input loop = {.pieces = pieces, .n_pieces = 4, .outer = 1};
    const pc_face_params params = {.tol_uv = 1e-9, .tol_model = 0.0, .close_tol = 1e-9,
                                   .same_sense = 1, .id = -1, .kind = "sphere",
                                   .what = "hemisphere"};
    projcurve_face *f = NULL;
    CHECK_OK(pc_face_build(NULL, s, &loop, 1, &params, &f));
    return f;
}

/* The hits of p + lambda d (d unit) with the unit sphere: 2, or 0. */
static int sphere_hits(const double p[3], const double d[3], double lambda[2])
{
    const double b = p[0] * d[0] + p[1] * d[1] + p[2] * d[2];
    const double cc = p[0] * p[0] + p[1] * p[1] + p[2] * p[2] - 1.0;
    const double disc = b * b - cc;
    if (!(disc > 0.0))
        return 0;
    lambda[0] = -b - sqrt(disc);
    lambda[1] = -b + sqrt(disc);
    return 2;
}

/* One piece over [0, 1], each point hit `which` (0 front, 1 back) of its
 * ray; returns the largest distance from it. */
static double check_one_piece(const projcurve_face *f, const projcurve_curve *c,
                              const double eye[3], int nearest, int which)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_HITS,
                                       nearest ? PROJCURVE_HITS_NEAREST : PROJCURVE_HITS_ALL));
    projcurve_shape_result *sr = NULL;
    CHECK_OK(projcurve_project_face(NULL, f, c, PROJCURVE_PROJECT_CONICAL, eye, o, &sr));
    double worst = INFINITY;
    CHECK(projcurve_shape_result_curve_count(sr) == 1);
    if (projcurve_shape_result_curve_count(sr) == 1) {
        double tr[2];
        size_t np = 0, b = 0;
        const projcurve_result *r = NULL;
        CHECK_OK(projcurve_shape_result_curve_info(NULL, sr, 0, &np, tr, NULL));
        CHECK(np == 1);
        CHECK_NEAR(tr[0], 0.0, 1e-14);
        CHECK_NEAR(tr[1], 1.0, 1e-14);
        CHECK_OK(projcurve_shape_result_piece(NULL, sr, 0, 0, NULL, &r, &b, NULL, NULL, NULL));
        size_t n = 0;
        CHECK_OK(projcurve_result_branch_points(NULL, r, b, 0, NULL, &n));
        double *pts = malloc(3 * (n ? n : 1) * sizeof *pts);
        CHECK(pts != NULL && n >= 2);
        if (pts != NULL)
            CHECK_OK(projcurve_result_branch_points(NULL, r, b, n, pts, &n));
        worst = 0.0;
        for (size_t j = 0; pts != NULL && j < n; ++j) {
            double p[3], d[3], x[3], lambda[2], len = 0.0;
            CHECK_OK(projcurve_curve_eval(NULL, c, pts[3 * j], 0, p));
            for (int i = 0; i < 3; ++i) {
                d[i] = p[i] - eye[i];
                len += d[i] * d[i];
            }
            for (int i = 0; i < 3; ++i)
                d[i] /= sqrt(len);
            CHECK(sphere_hits(p, d, lambda) == 2);
            CHECK_OK(projcurve_surface_eval(NULL, projcurve_face_surface(f), pts[3 * j + 1],
                                            pts[3 * j + 2], 0, x));
            for (int i = 0; i < 3; ++i)
                worst = fmax(worst, fabs(x[i] - (p[i] + lambda[which] * d[i])));
        }
        free(pts);
    }
    projcurve_shape_result_destroy(sr);
    projcurve_options_destroy(o);
    return worst;
}

int main(void)
{
    const double origin[3] = {0.0, 0.0, 0.0};
    pc_shape_surface sh = pc_shape_sphere(origin, 1.0);
    projcurve_surface *sphere = pc_shape_surface_create(&sh);
    pc_shape_surface_free(&sh);
    projcurve_face *north = band(sphere, 0.5, 1.0), *south = band(sphere, 0.0, 0.5);
    const double p0[3] = {-0.1, 0.25, 3.0}, p1[3] = {0.25, 0.4, 3.1};
    const double ctrl[6] = {p0[0], p0[1], p0[2], p1[0], p1[1], p1[2]};
    static const double knots[] = {0, 0, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 1, 2, ctrl, NULL, knots, &c));
    const double eye[3] = {0.2, 0.1, 5.0};
    /* traced points are exact projections: Newton to ~1e-12 of the size
     * (~3.5), each coordinate within 1e-10 */
    const double front_all = check_one_piece(north, c, eye, 0, 0);
    const double front_near = check_one_piece(north, c, eye, 1, 0);
    const double back_near = check_one_piece(south, c, eye, 1, 1);
    printf("sphere faces from an eye: front (all) %.3g, front (nearest) %.3g, back behind a "
           "trimmed-away front (nearest) %.3g\n",
           front_all, front_near, back_near);
    CHECK(front_all <= 1e-10);
    CHECK(front_near <= 1e-10);
    CHECK(back_near <= 1e-10);
    projcurve_curve_destroy(c);
    pc_face_free(north);
    pc_face_free(south);
    projcurve_surface_destroy(sphere);
    return pc_test_finish("test_faceproj_sphere_conical");
}
