/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A 2x2 shell made by splitting one bicubic B-spline sheet into four faces
 * on the same surface (loops the four quarter squares of its domain, the
 * inner sides shared edges), built through the engine (brep/face.h,
 * brep/shape.h) so that edge ids are set. On it:
 *   - a U-shaped curve along an oblique Dir: one connected curve of four
 *     face pieces, each join at the same t and 3D point (the faces share
 *     the sheet, so the crossings of two faces are one root: 1e-10 of the
 *     size), no gap;
 *   - the same orthogonally (a smooth sheet: the foot points run across
 *     the edges): one connected curve of four pieces;
 *   - the same with nearest hits (the pieces meet on the shared edges with
 *     equal distances: not cut there);
 *   - the same seen from an eye above the sheet (conical; the image of
 *     the U, scaled about 1.3 times about the eye's foot, stays on the
 *     sheet): one connected curve of four pieces, all four faces selected
 *     by the cone test;
 *   - one face's inner edge moved by 1e-6 (a gap between faces, beyond the
 *     chaining tolerance of 1e-9 of the size): two connected curves, the
 *     two ends at the gap counted as open;
 *   - a closed shell with one face missing (a face the reader could not
 *     build): two connected curves, both ends at the missing face open;
 *   - a closed curve (a circle around the shell's centre, starting on face
 *     10): one closed connected curve of five pieces, the last (ending the
 *     curve) continuing into the first (starting it) on face 10;
 *   - MAX_POINTS at its smallest (16): LIMIT_REACHED with the result kept,
 *     the faces that hit it saying so with their status and message.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "brep/face.h"
#include "brep/shape.h"
#include "check.h"
#include "projcurve.h"

static projcurve_surface *sheet(void)
{
    double net[3 * 16];
    static const double z[16] = {0, 1, 0.5, 0, 1, 2, 1.5, 0.5, 0.5, 1.5, 2.5, 1, 0, 0.5, 1, 0};
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            net[3 * (4 * j + i)] = 20.0 * i / 3.0;
            net[3 * (4 * j + i) + 1] = 20.0 * j / 3.0;
            net[3 * (4 * j + i) + 2] = z[4 * j + i];
        }
    static const double knots[] = {0, 0, 0, 0, 20, 20, 20, 20};
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(NULL, 3, 3, 4, 4, net, NULL, knots, knots, &s));
    return s;
}

/* The square [u0, u1] x [v0, v1] with the edge ids of its sides (bottom,
 * right, top, left), counter-clockwise. */
static projcurve_face *quarter(const projcurve_surface *s, double u0, double u1, double v0,
                               double v1, const long ids[4])
{
    const double c[5][2] = {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}, {u0, v0}};
    double ctrl[4][4];
    static const double knots[] = {0, 0, 1, 1};
    pc_piece_input pieces[4];
    for (int k = 0; k < 4; ++k) {
        ctrl[k][0] = c[k][0];
        ctrl[k][1] = c[k][1];
        ctrl[k][2] = c[k + 1][0];
        ctrl[k][3] = c[k + 1][1];
        pieces[k] = (pc_piece_input){.degree = 1, .n_ctrl = 2, .ctrl = ctrl[k], .knots = knots,
                                     .edge = ids[k], .sense = 1, .edge_sense = 1};
    }
    const pc_loop_input loop = {.pieces = pieces, .n_pieces = 4, .outer = 1};
    const pc_face_params params = {.tol_uv = 1e-9, .tol_model = 0.0, .close_tol = 1e-9,
                                   .same_sense = 1, .id = -1, .kind = "bspline",
                                   .what = "quarter"};
    projcurve_face *f = NULL;
    CHECK_OK(pc_face_build(NULL, s, &loop, 1, &params, &f));
    return f;
}

typedef struct shell {
    projcurve_face *faces[4];
    projcurve_shape *shape;
} shell;

/* Faces 00, 10, 11, 01; `gap` moves face 10's left side (edge 5) right;
 * skip: a face left out (4: none). */
static void make_shell(const projcurve_surface *s, double gap, int skip,
                       projcurve_shape_kind kind, shell *sh)
{
    static const long ids[4][4] = {{1, 5, 7, 2}, {3, 4, 8, 5}, {8, 9, 10, 6}, {7, 6, 11, 12}};
    sh->faces[0] = quarter(s, 0, 10, 0, 10, ids[0]);
    sh->faces[1] = quarter(s, 10 + gap, 20, 0, 10, ids[1]);
    sh->faces[2] = quarter(s, 10, 20, 10, 20, ids[2]);
    sh->faces[3] = quarter(s, 0, 10, 10, 20, ids[3]);
    const projcurve_face *kept[4];
    size_t index[4], n = 0;
    for (int i = 0; i < 4; ++i)
        if (i != skip) {
            kept[n] = sh->faces[i];
            index[n] = (size_t)i;
            ++n;
        }
    sh->shape = NULL;
    CHECK_OK(pc_shape_build(NULL, kind, -1, kept, index, n, &sh->shape));
}

static void free_shell(shell *sh)
{
    pc_shape_free(sh->shape);
    for (int i = 0; i < 4; ++i)
        pc_face_free(sh->faces[i]);
}

static projcurve_curve *u_curve(double z)
{
    const double ctrl[] = {5, 3, z, 17, 3, z, 17, 17, z, 3, 17, z};
    static const double knots[] = {0, 0, 0, 0, 1, 1, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 3, 4, ctrl, NULL, knots, &c));
    return c;
}

static void piece_end_point(const projcurve_shape *shape, const projcurve_shape_result *sr,
                            size_t curve, size_t piece, int at_end, double *t, double p[3])
{
    size_t face = 0, b = 0;
    const projcurve_result *r = NULL;
    double tr[2];
    CHECK_OK(projcurve_shape_result_piece(NULL, sr, curve, piece, &face, &r, &b, tr, NULL, NULL));
    double pts[3 * 8192];
    size_t n = 0;
    CHECK_OK(projcurve_result_branch_points(NULL, r, b, 8192, pts, &n));
    const double *q = at_end ? pts + 3 * (n - 1) : pts;
    *t = q[0];
    CHECK_NEAR(*t, at_end ? tr[1] : tr[0], 0.0);
    CHECK_OK(projcurve_surface_eval(NULL, projcurve_face_surface(projcurve_shape_face(shape, face)),
                                    q[1], q[2], 0, p));
}

/* One connected curve of four pieces on four faces, joined at one t and
 * one point (1e-10 of the size, ~28: 3e-9 in 3D, and in t over the
 * curve's speed, ~20). */
static void check_four(const projcurve_shape *shape, const projcurve_shape_result *sr)
{
    CHECK(projcurve_shape_result_curve_count(sr) == 1);
    size_t np = 0;
    int closed = 1;
    CHECK_OK(projcurve_shape_result_curve_info(NULL, sr, 0, &np, NULL, &closed));
    CHECK(np == 4);
    CHECK(closed == 0);
    CHECK(projcurve_shape_result_open_end_count(sr) == 0);
    for (size_t j = 0; j + 1 < np; ++j) {
        double ta, tb, a[3], b[3];
        piece_end_point(shape, sr, 0, j, 1, &ta, a);
        piece_end_point(shape, sr, 0, j + 1, 0, &tb, b);
        CHECK_NEAR(ta, tb, 3e-10);
        CHECK_NEAR(hypot(hypot(a[0] - b[0], a[1] - b[1]), a[2] - b[2]), 0.0, 3e-9);
    }
    size_t faces[4];
    for (size_t j = 0; j < np && j < 4; ++j)
        CHECK_OK(projcurve_shape_result_piece(NULL, sr, 0, j, &faces[j], NULL, NULL, NULL, NULL,
                                              NULL));
    /* the U runs 00 -> 10 -> 11 -> 01 */
    CHECK(np == 4 && faces[0] == 0 && faces[1] == 1 && faces[2] == 2 && faces[3] == 3);
}

static projcurve_curve *circle(void)
{
    const double cx = 10.5, cy = 9.3, r = 5.0, z = 10.0, h = sqrt(0.5);
    const double d[9][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0},
                            {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    double ctrl[27], w[9];
    for (int i = 0; i < 9; ++i) {
        ctrl[3 * i] = cx + r * d[i][0];
        ctrl[3 * i + 1] = cy + r * d[i][1];
        ctrl[3 * i + 2] = z;
        w[i] = i % 2 ? h : 1.0;
    }
    static const double knots[] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 2, 9, ctrl, w, knots, &c));
    return c;
}

static void check_closed(const projcurve_shape *shape, const double dir[3])
{
    projcurve_curve *c = circle();
    projcurve_shape_result *sr = NULL;
    CHECK_OK(projcurve_project_shape(NULL, shape, c, PROJCURVE_PROJECT_DIRECTIONAL, dir, NULL,
                                     &sr));
    CHECK(projcurve_shape_result_curve_count(sr) == 1);
    size_t np = 0;
    int closed = 0;
    CHECK_OK(projcurve_shape_result_curve_info(NULL, sr, 0, &np, NULL, &closed));
    CHECK(np == 5);
    CHECK(closed == 1);
    size_t first = 9, last = 9;
    projcurve_branch_start s;
    projcurve_branch_end e;
    CHECK_OK(projcurve_shape_result_piece(NULL, sr, 0, 0, &first, NULL, NULL, NULL, &s, NULL));
    CHECK(s == PROJCURVE_START_CURVE_START);
    CHECK_OK(projcurve_shape_result_piece(NULL, sr, 0, np - 1, &last, NULL, NULL, NULL, NULL, &e));
    CHECK(e == PROJCURVE_END_CURVE_END);
    CHECK(first == 1 && last == 1);
    projcurve_shape_result_destroy(sr);
    projcurve_curve_destroy(c);
}

int main(void)
{
    projcurve_surface *s = sheet();
    projcurve_curve *c = u_curve(10.0);
    const double dir[3] = {0.2, -0.1, -1.0};
    projcurve_shape_result *sr = NULL;
    shell sh;

    make_shell(s, 0.0, 4, PROJCURVE_SHAPE_OPEN_SHELL, &sh);
    CHECK_OK(projcurve_project_shape(NULL, sh.shape, c, PROJCURVE_PROJECT_DIRECTIONAL, dir, NULL,
                                     &sr));
    CHECK(projcurve_shape_result_face_count(sr) == 4);
    check_four(sh.shape, sr);
    projcurve_shape_result_destroy(sr);
    check_closed(sh.shape, dir);

    /* nearest hits: one hit per ray, and the pieces meeting on the shared
     * edges (equal distances there) are not cut: still one curve of four */
    projcurve_options *nearest = NULL;
    CHECK_OK(projcurve_options_create(NULL, &nearest));
    CHECK_OK(projcurve_options_set_int(NULL, nearest, PROJCURVE_OPT_HITS,
                                       PROJCURVE_HITS_NEAREST));
    sr = NULL;
    CHECK_OK(projcurve_project_shape(NULL, sh.shape, c, PROJCURVE_PROJECT_DIRECTIONAL, dir,
                                     nearest, &sr));
    check_four(sh.shape, sr);
    projcurve_shape_result_destroy(sr);
    projcurve_options_destroy(nearest);

    const double eye[3] = {10, 10, 40};
    sr = NULL;
    CHECK_OK(projcurve_project_shape(NULL, sh.shape, c, PROJCURVE_PROJECT_CONICAL, eye, NULL,
                                     &sr));
    CHECK(projcurve_shape_result_face_count(sr) == 4);
    check_four(sh.shape, sr);
    projcurve_shape_result_destroy(sr);

    projcurve_curve *near = u_curve(3.0);
    sr = NULL;
    CHECK_OK(projcurve_project_shape(NULL, sh.shape, near, PROJCURVE_PROJECT_ORTHOGONAL, NULL,
                                     NULL, &sr));
    check_four(sh.shape, sr);
    projcurve_shape_result_destroy(sr);
    projcurve_curve_destroy(near);
    free_shell(&sh);

    make_shell(s, 1e-6, 4, PROJCURVE_SHAPE_OPEN_SHELL, &sh);
    sr = NULL;
    CHECK_OK(projcurve_project_shape(NULL, sh.shape, c, PROJCURVE_PROJECT_DIRECTIONAL, dir, NULL,
                                     &sr));
    CHECK(projcurve_shape_result_curve_count(sr) == 2);
    CHECK(projcurve_shape_result_open_end_count(sr) == 2);
    projcurve_shape_result_destroy(sr);
    free_shell(&sh);

    make_shell(s, 0.0, 2, PROJCURVE_SHAPE_CLOSED_SHELL, &sh);
    sr = NULL;
    CHECK_OK(projcurve_project_shape(NULL, sh.shape, c, PROJCURVE_PROJECT_DIRECTIONAL, dir, NULL,
                                     &sr));
    CHECK(projcurve_shape_result_curve_count(sr) == 2);
    CHECK(projcurve_shape_result_open_end_count(sr) == 2);
    projcurve_shape_result_destroy(sr);
    free_shell(&sh);

    make_shell(s, 0.0, 4, PROJCURVE_SHAPE_OPEN_SHELL, &sh);
    projcurve_options *few = NULL;
    CHECK_OK(projcurve_options_create(NULL, &few));
    CHECK_OK(projcurve_options_set_int(NULL, few, PROJCURVE_OPT_MAX_POINTS, 16));
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    sr = NULL;
    CHECK_STATUS(projcurve_project_shape(ctx, sh.shape, c, PROJCURVE_PROJECT_DIRECTIONAL, dir, few,
                                         &sr),
                 PROJCURVE_ERR_LIMIT_REACHED);
    CHECK(projcurve_context_message(ctx)[0] != '\0');
    CHECK(sr != NULL);
    size_t limited = 0;
    for (size_t i = 0; i < projcurve_shape_result_face_count(sr); ++i) {
        projcurve_status fs = PROJCURVE_OK;
        const char *msg = NULL;
        const projcurve_result *fr = NULL;
        CHECK_OK(projcurve_shape_result_face(NULL, sr, i, NULL, &fr, &fs, &msg));
        if (fs == PROJCURVE_ERR_LIMIT_REACHED) {
            ++limited;
            CHECK(fr != NULL);
            CHECK(msg[0] != '\0');
        }
    }
    CHECK(limited > 0);
    CHECK(projcurve_shape_result_curve_count(sr) > 0);
    projcurve_shape_result_destroy(sr);
    projcurve_context_destroy(ctx);
    projcurve_options_destroy(few);
    free_shell(&sh);

    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    return pc_test_finish("test_shapeproj_split");
}
