/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The cells of docs/bad-input.md for the face, shape, shape-result, model
 * topology, STEP writer and exact-composition functions: each against
 * NULL, an index past the end, non-finite and out-of-range numbers and the
 * wrong kind of result. A failing call must give the status the page
 * documents, a message naming the problem, and leave its outputs as they
 * were; an accessor gives 0, NULL or nothing.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "projcurve.h"
#include "shapes.h"

static projcurve_context *ctx;

#define SENTINEL ((void *)&ctx)

/* A call that must fail with `expected` and a message, one containing
 * `needle`. */
#define CHECK_FAILS(call, expected, needle)                                            \
    do {                                                                               \
        projcurve_context_clear(ctx);                                                  \
        CHECK_STATUS(call, expected);                                                  \
        if (projcurve_context_message(ctx)[0] == '\0' ||                               \
            strstr(projcurve_context_message(ctx), needle) == NULL)                    \
            pc_test_fail_at(__FILE__, __LINE__, "%s: message \"%s\" lacks \"%s\"", #call, \
                            projcurve_context_message(ctx), needle);                   \
    } while (0)

/* The unit square z = 0, a line above it, and a square loop inside it. */
static const double plane_net[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
static const double line_net[] = {0.1, 0.5, 1, 0.9, 0.5, 1};
static const double knots01[] = {0, 0, 1, 1};
static const double down[3] = {0, 0, -1};

/* The loop of 4 lines around [a, b]^2, counter-clockwise. */
typedef struct square_loop {
    double ctrl[4][4];
    const double *ctrl_p[4], *knots_p[4];
    int degrees[4];
    size_t n_ctrl[4], loop_pieces[1];
} square_loop;

static void square(square_loop *L, double a, double b)
{
    const double c[5][2] = {{a, a}, {b, a}, {b, b}, {a, b}, {a, a}};
    for (int k = 0; k < 4; ++k) {
        L->ctrl[k][0] = c[k][0], L->ctrl[k][1] = c[k][1];
        L->ctrl[k][2] = c[k + 1][0], L->ctrl[k][3] = c[k + 1][1];
        L->ctrl_p[k] = L->ctrl[k];
        L->knots_p[k] = knots01;
        L->degrees[k] = 1;
        L->n_ctrl[k] = 2;
    }
    L->loop_pieces[0] = 4;
}

static projcurve_status make_face(const projcurve_surface *s, square_loop *L, double tol_uv,
                                  projcurve_face **out)
{
    return projcurve_face_create(ctx, s, 1, L->loop_pieces, L->degrees, L->n_ctrl, L->ctrl_p,
                                 NULL, L->knots_p, tol_uv, out);
}

/* A face of up to 3 square loops {u0, u1, v0, v1}, the first the outer one. */
static projcurve_status squares_face(const projcurve_surface *s, size_t n, const double sq[][4],
                                     projcurve_face **out)
{
    square_loop L[3];
    const double *ctrl[12], *knots[12];
    int degrees[12];
    size_t n_ctrl[12], pieces[3];
    for (size_t l = 0; l < n && l < 3; ++l) {
        square(&L[l], 0.0, 1.0);
        const double c[5][2] = {{sq[l][0], sq[l][2]}, {sq[l][1], sq[l][2]}, {sq[l][1], sq[l][3]},
                                {sq[l][0], sq[l][3]}, {sq[l][0], sq[l][2]}};
        for (int k = 0; k < 4; ++k) {
            L[l].ctrl[k][0] = c[k][0], L[l].ctrl[k][1] = c[k][1];
            L[l].ctrl[k][2] = c[k + 1][0], L[l].ctrl[k][3] = c[k + 1][1];
            ctrl[4 * l + k] = L[l].ctrl[k], knots[4 * l + k] = knots01;
            degrees[4 * l + k] = 1, n_ctrl[4 * l + k] = 2;
        }
        pieces[l] = 4;
    }
    return projcurve_face_create(ctx, s, n, pieces, degrees, n_ctrl, ctrl, NULL, knots, 0.0, out);
}

/* A face of one loop: the polygon p[0..3] of 4 lines. */
static projcurve_status quad_face(const projcurve_surface *s, const double p[4][2],
                                  projcurve_face **out)
{
    square_loop L;
    square(&L, 0.0, 1.0);
    for (int k = 0; k < 4; ++k) {
        L.ctrl[k][0] = p[k][0], L.ctrl[k][1] = p[k][1];
        L.ctrl[k][2] = p[(k + 1) % 4][0], L.ctrl[k][3] = p[(k + 1) % 4][1];
    }
    return make_face(s, &L, 0.0, out);
}

/* Loops that overlap, or lie outside the domain: the classifier counts
 * winding numbers, so such a face would answer IN for points outside its
 * outer loop or inside two holes. */
static void test_face_loops(const projcurve_surface *plane)
{
    projcurve_face *f = SENTINEL;
    const double outside[][4] = {{2, 3, 2, 3}};
    CHECK_FAILS(squares_face(plane, 1, outside, &f), PROJCURVE_ERR_INVALID_ARGUMENT,
                "outside the surface's domain");
    const double straddling[][4] = {{-0.5, 0.5, 0.2, 0.8}};
    CHECK_FAILS(squares_face(plane, 1, straddling, &f), PROJCURVE_ERR_INVALID_ARGUMENT,
                "outside the surface's domain");
    /* the hole's first point is inside the outer loop, its right side beyond it */
    const double crossing[][4] = {{0.2, 0.8, 0.2, 0.8}, {0.5, 0.9, 0.4, 0.6}};
    CHECK_FAILS(squares_face(plane, 2, crossing, &f), PROJCURVE_ERR_INVALID_ARGUMENT,
                "loops 0 and 1 cross");
    const double overlapping[][4] = {{0.2, 0.8, 0.2, 0.8}, {0.3, 0.6, 0.3, 0.6},
                                     {0.4, 0.7, 0.4, 0.7}};
    CHECK_FAILS(squares_face(plane, 3, overlapping, &f), PROJCURVE_ERR_INVALID_ARGUMENT,
                "loops 1 and 2 cross");
    /* a plus: no corner of either hole inside the other */
    const double plus[][4] = {{0.1, 0.9, 0.1, 0.9}, {0.2, 0.8, 0.45, 0.55},
                              {0.45, 0.55, 0.2, 0.8}};
    CHECK_FAILS(squares_face(plane, 3, plus, &f), PROJCURVE_ERR_INVALID_ARGUMENT,
                "loops 1 and 2 cross");
    const double nested[][4] = {{0.2, 0.8, 0.2, 0.8}, {0.3, 0.7, 0.3, 0.7},
                                {0.4, 0.6, 0.4, 0.6}};
    CHECK_FAILS(squares_face(plane, 3, nested, &f), PROJCURVE_ERR_INVALID_ARGUMENT,
                "inside another hole");
    const double around[][4] = {{0.2, 0.8, 0.2, 0.8}, {0.1, 0.9, 0.1, 0.9}};
    CHECK_FAILS(squares_face(plane, 2, around, &f), PROJCURVE_ERR_INVALID_ARGUMENT,
                "outside the outer loop");
    /* a figure eight of unequal lobes (its signed area is not 0): the
     * smaller lobe had winding number -1, so IN */
    const double eight[4][2] = {{0.2, 0.2}, {0.8, 0.8}, {0.8, 0.3}, {0.2, 0.6}};
    CHECK_FAILS(quad_face(plane, eight, &f), PROJCURVE_ERR_INVALID_ARGUMENT,
                "loop 0 crosses itself");
    CHECK(f == SENTINEL);
    /* a vertex on the line of its neighbours (two consecutive segments
     * collinear) is no crossing */
    const double kite[4][2] = {{0.2, 0.2}, {0.8, 0.2}, {0.8, 0.8}, {0.5, 0.5}};
    f = NULL;
    CHECK_OK(quad_face(plane, kite, &f));
    projcurve_face_destroy(f);
    /* two holes apart, and one touching the outer loop: a face, classified
     * as the squares say */
    const double apart[][4] = {{0.2, 0.8, 0.2, 0.8}, {0.3, 0.45, 0.3, 0.7},
                               {0.55, 0.8, 0.4, 0.6}};
    f = NULL;
    CHECK_OK(squares_face(plane, 3, apart, &f));
    const struct {
        double u, v;
        projcurve_where where;
    } expect[] = {{0.5, 0.5, PROJCURVE_IN},  {0.4, 0.5, PROJCURVE_OUT}, {0.7, 0.5, PROJCURVE_OUT},
                  {0.9, 0.5, PROJCURVE_OUT}, {0.25, 0.25, PROJCURVE_IN}, {0.8, 0.5, PROJCURVE_ON}};
    for (size_t k = 0; f && k < sizeof expect / sizeof expect[0]; ++k) {
        projcurve_where w = PROJCURVE_OUT;
        CHECK_OK(projcurve_face_classify(ctx, f, expect[k].u, expect[k].v, &w));
        if (w != expect[k].where)
            pc_test_fail_at(__FILE__, __LINE__, "(%g, %g) is %d, expected %d", expect[k].u,
                            expect[k].v, (int)w, (int)expect[k].where);
    }
    projcurve_face_destroy(f);
}

static void test_face_create(const projcurve_surface *plane)
{
    square_loop L;
    square(&L, 0.2, 0.8);
    projcurve_face *f = SENTINEL;
    CHECK_FAILS(make_face(plane, &L, 0.0, NULL), PROJCURVE_ERR_NULL_ARGUMENT, "out");
    CHECK_FAILS(make_face(NULL, &L, 0.0, &f), PROJCURVE_ERR_NULL_ARGUMENT, "surface");
    CHECK_FAILS(projcurve_face_create(ctx, plane, 1, NULL, L.degrees, L.n_ctrl, L.ctrl_p, NULL,
                                      L.knots_p, 0.0, &f),
                PROJCURVE_ERR_NULL_ARGUMENT, "loop_pieces");
    CHECK_FAILS(projcurve_face_create(ctx, plane, 1, L.loop_pieces, NULL, L.n_ctrl, L.ctrl_p,
                                      NULL, L.knots_p, 0.0, &f),
                PROJCURVE_ERR_NULL_ARGUMENT, "degrees");
    CHECK_FAILS(projcurve_face_create(ctx, plane, 1, L.loop_pieces, L.degrees, NULL, L.ctrl_p,
                                      NULL, L.knots_p, 0.0, &f),
                PROJCURVE_ERR_NULL_ARGUMENT, "n_ctrl");
    CHECK_FAILS(projcurve_face_create(ctx, plane, 1, L.loop_pieces, L.degrees, L.n_ctrl, NULL,
                                      NULL, L.knots_p, 0.0, &f),
                PROJCURVE_ERR_NULL_ARGUMENT, "ctrl");
    CHECK_FAILS(projcurve_face_create(ctx, plane, 1, L.loop_pieces, L.degrees, L.n_ctrl,
                                      L.ctrl_p, NULL, NULL, 0.0, &f),
                PROJCURVE_ERR_NULL_ARGUMENT, "knots");
    L.ctrl_p[2] = NULL;
    CHECK_FAILS(make_face(plane, &L, 0.0, &f), PROJCURVE_ERR_NULL_ARGUMENT, "piece 2: ctrl");
    square(&L, 0.2, 0.8);
    CHECK_FAILS(make_face(plane, &L, NAN, &f), PROJCURVE_ERR_OUT_OF_RANGE, "tol_uv");
    CHECK_FAILS(make_face(plane, &L, INFINITY, &f), PROJCURVE_ERR_OUT_OF_RANGE, "tol_uv");
    CHECK_FAILS(make_face(plane, &L, -1e-9, &f), PROJCURVE_ERR_OUT_OF_RANGE, "tol_uv");
    /* wider than the domain (1): at DBL_MAX the closing gap overflowed and
     * the centre came out OUT */
    CHECK_FAILS(make_face(plane, &L, 1.5, &f), PROJCURVE_ERR_OUT_OF_RANGE, "wider than");
    CHECK_FAILS(make_face(plane, &L, DBL_MAX, &f), PROJCURVE_ERR_OUT_OF_RANGE, "wider than");
    /* the smallest width: lines are flattened exactly, arcs not within it
     * (a limit, not a hang) */
    projcurve_face *g = NULL;
    CHECK_OK(make_face(plane, &L, 5e-324, &g));
    projcurve_face_destroy(g);
    const double arc0[6] = {0.2, 0.5, 0.5, 0.1, 0.8, 0.5}, arc1[6] = {0.8, 0.5, 0.5, 0.9, 0.2, 0.5};
    const double k2[6] = {0, 0, 0, 1, 1, 1}, *arcs[2] = {arc0, arc1}, *arc_knots[2] = {k2, k2};
    const int arc_degrees[2] = {2, 2};
    const size_t arc_n[2] = {3, 3}, arc_pieces[1] = {2};
    CHECK_FAILS(projcurve_face_create(ctx, plane, 1, arc_pieces, arc_degrees, arc_n, arcs, NULL,
                                      arc_knots, 5e-324, &f),
                PROJCURVE_ERR_LIMIT_REACHED, "piece 0");
    L.degrees[1] = 0;
    CHECK_FAILS(make_face(plane, &L, 0.0, &f), PROJCURVE_ERR_BAD_DEGREE, "piece 1");
    square(&L, 0.2, 0.8);
    L.n_ctrl[1] = 1;
    CHECK_FAILS(make_face(plane, &L, 0.0, &f), PROJCURVE_ERR_BAD_COUNT, "piece 1");
    square(&L, 0.2, 0.8);
    L.ctrl[3][1] = NAN;
    CHECK_FAILS(make_face(plane, &L, 0.0, &f), PROJCURVE_ERR_NOT_FINITE, "piece 3");
    square(&L, 0.2, 0.8);
    const double bad_knots[] = {0, 1, 0.5, 1};
    L.knots_p[0] = bad_knots;
    CHECK_FAILS(make_face(plane, &L, 0.0, &f), PROJCURVE_ERR_BAD_KNOTS, "piece 0");
    square(&L, 0.2, 0.8);
    const double zero_w[] = {1, 0}, *weights[4] = {NULL, zero_w, NULL, NULL};
    CHECK_FAILS(projcurve_face_create(ctx, plane, 1, L.loop_pieces, L.degrees, L.n_ctrl,
                                      L.ctrl_p, weights, L.knots_p, 0.0, &f),
                PROJCURVE_ERR_BAD_WEIGHT, "weight");
    L.ctrl[1][3] = 0.5; /* piece 1 ends short of piece 2's start: an open loop */
    CHECK_FAILS(make_face(plane, &L, 0.0, &f), PROJCURVE_ERR_INVALID_ARGUMENT, "open");
    square(&L, 0.2, 0.8);
    L.loop_pieces[0] = 0;
    CHECK_FAILS(make_face(plane, &L, 0.0, &f), PROJCURVE_ERR_INVALID_ARGUMENT, "no pieces");
    CHECK(f == SENTINEL);
}

static void test_face_queries(const projcurve_face *f)
{
    size_t count = 77;
    CHECK_FAILS(projcurve_face_loop_piece_count(ctx, NULL, 0, &count),
                PROJCURVE_ERR_NULL_ARGUMENT, "face");
    CHECK_FAILS(projcurve_face_loop_piece_count(ctx, f, 0, NULL), PROJCURVE_ERR_NULL_ARGUMENT,
                "count");
    CHECK_FAILS(projcurve_face_loop_piece_count(ctx, f, 1, &count), PROJCURVE_ERR_INDEX,
                "loop 1");
    CHECK(count == 77);
    int degree = 77;
    CHECK_FAILS(projcurve_face_piece_curve(ctx, NULL, 0, 0, &degree, NULL, NULL, NULL, NULL,
                                           NULL),
                PROJCURVE_ERR_NULL_ARGUMENT, "face");
    CHECK_FAILS(projcurve_face_piece_curve(ctx, f, 1, 0, &degree, NULL, NULL, NULL, NULL, NULL),
                PROJCURVE_ERR_INDEX, "loop 1");
    CHECK_FAILS(projcurve_face_piece_curve(ctx, f, 0, 4, &degree, NULL, NULL, NULL, NULL, NULL),
                PROJCURVE_ERR_INDEX, "piece 4");
    CHECK(degree == 77);
    CHECK_OK(projcurve_face_piece_curve(ctx, f, 0, 3, NULL, NULL, NULL, NULL, NULL, NULL));
    long edge = 77;
    CHECK_FAILS(projcurve_face_piece_edge(ctx, NULL, 0, 0, &edge, NULL, NULL),
                PROJCURVE_ERR_NULL_ARGUMENT, "face");
    CHECK_FAILS(projcurve_face_piece_edge(ctx, f, 0, 4, &edge, NULL, NULL), PROJCURVE_ERR_INDEX,
                "piece 4");
    CHECK_FAILS(projcurve_face_piece_edge(ctx, f, 2, 0, &edge, NULL, NULL), PROJCURVE_ERR_INDEX,
                "loop 2");
    CHECK(edge == 77);
    CHECK_OK(projcurve_face_piece_edge(ctx, f, 0, 0, NULL, NULL, NULL));
    projcurve_where where = (projcurve_where)77;
    CHECK_FAILS(projcurve_face_classify(ctx, NULL, 0.5, 0.5, &where),
                PROJCURVE_ERR_NULL_ARGUMENT, "face");
    CHECK_FAILS(projcurve_face_classify(ctx, f, 0.5, 0.5, NULL), PROJCURVE_ERR_NULL_ARGUMENT,
                "where");
    CHECK_FAILS(projcurve_face_classify(ctx, f, NAN, 0.5, &where), PROJCURVE_ERR_NOT_FINITE,
                "not finite");
    CHECK_FAILS(projcurve_face_classify(ctx, f, 0.5, -INFINITY, &where),
                PROJCURVE_ERR_NOT_FINITE, "not finite");
    CHECK(where == (projcurve_where)77);
    /* far outside the domain, and at the largest doubles: OUT */
    CHECK_OK(projcurve_face_classify(ctx, f, 1e300, -1e300, &where));
    CHECK(where == PROJCURVE_OUT);
    CHECK_OK(projcurve_face_classify(ctx, f, 1.7e308, 1.7e308, &where));
    CHECK(where == PROJCURVE_OUT);
    double box[6] = {77, 77, 77, 77, 77, 77};
    CHECK_FAILS(projcurve_face_bounds(ctx, NULL, box, box), PROJCURVE_ERR_NULL_ARGUMENT, "face");
    CHECK_FAILS(projcurve_face_tolerance(ctx, NULL, box, box), PROJCURVE_ERR_NULL_ARGUMENT,
                "face");
    int sense = 77;
    CHECK_FAILS(projcurve_face_info(ctx, NULL, &sense, NULL, NULL), PROJCURVE_ERR_NULL_ARGUMENT,
                "face");
    CHECK(box[0] == 77 && sense == 77);
    CHECK_OK(projcurve_face_bounds(ctx, f, NULL, NULL));
    CHECK_OK(projcurve_face_tolerance(ctx, f, NULL, NULL));
    CHECK_OK(projcurve_face_info(ctx, f, NULL, NULL, NULL));
    CHECK(projcurve_face_surface(NULL) == NULL && projcurve_face_loop_count(NULL) == 0);
    projcurve_face_destroy(NULL);
}

static int nan_fn(void *user, double t, double out[9])
{
    (void)user;
    (void)t;
    for (int i = 0; i < 9; ++i)
        out[i] = NAN;
    return 0;
}

static int failing_fn(void *user, double t, double out[9])
{
    (void)user;
    (void)t;
    (void)out;
    return 1;
}

/* project_face and project_shape share their argument checks: each bad
 * input of the one, then the NULL shape of the other. */
static void test_project_args(const projcurve_face *f, const projcurve_curve *line,
                              projcurve_curve *point_curve)
{
    projcurve_shape_result *r = SENTINEL;
    projcurve_curve *nan_curve = NULL, *failing_curve = NULL;
    CHECK_OK(projcurve_curve_create_callback(ctx, nan_fn, NULL, 0, 1, &nan_curve));
    CHECK_OK(projcurve_curve_create_callback(ctx, failing_fn, NULL, 0, 1, &failing_curve));
    CHECK_FAILS(projcurve_project_face(ctx, f, nan_curve, PROJCURVE_PROJECT_DIRECTIONAL, down,
                                       NULL, &r),
                PROJCURVE_ERR_CALLBACK, "");
    CHECK_FAILS(projcurve_project_face(ctx, f, failing_curve, PROJCURVE_PROJECT_ORTHOGONAL, NULL,
                                       NULL, &r),
                PROJCURVE_ERR_CALLBACK, "");
    projcurve_curve_destroy(nan_curve);
    projcurve_curve_destroy(failing_curve);
    projcurve_options *bad_opts = NULL;
    CHECK_OK(projcurve_options_create(ctx, &bad_opts));
    CHECK_OK(projcurve_options_set_double(ctx, bad_opts, PROJCURVE_OPT_TIME_LIMIT, 1e-9));
    projcurve_shape_result *partial = NULL;
    CHECK_FAILS(projcurve_project_face(ctx, f, line, PROJCURVE_PROJECT_ORTHOGONAL, NULL,
                                       bad_opts, &partial),
                PROJCURVE_ERR_LIMIT_REACHED, "time limit");
    CHECK(partial != NULL); /* the partial result is kept */
    projcurve_shape_result_destroy(partial);
    projcurve_options_destroy(bad_opts);
    const double zero[3] = {0, 0, 0}, nan_dir[3] = {0, NAN, -1}, inf_eye[3] = {INFINITY, 0, 0};
    CHECK_FAILS(projcurve_project_face(ctx, NULL, line, PROJCURVE_PROJECT_DIRECTIONAL, down,
                                       NULL, &r),
                PROJCURVE_ERR_NULL_ARGUMENT, "face");
    CHECK_FAILS(projcurve_project_face(ctx, f, NULL, PROJCURVE_PROJECT_DIRECTIONAL, down, NULL,
                                       &r),
                PROJCURVE_ERR_NULL_ARGUMENT, "curve");
    CHECK_FAILS(projcurve_project_face(ctx, f, line, PROJCURVE_PROJECT_DIRECTIONAL, down, NULL,
                                       NULL),
                PROJCURVE_ERR_NULL_ARGUMENT, "out");
    CHECK_FAILS(projcurve_project_face(ctx, f, line, PROJCURVE_PROJECT_DIRECTIONAL, NULL, NULL,
                                       &r),
                PROJCURVE_ERR_NULL_ARGUMENT, "dir");
    CHECK_FAILS(projcurve_project_face(ctx, f, line, PROJCURVE_PROJECT_CONICAL, NULL, NULL, &r),
                PROJCURVE_ERR_NULL_ARGUMENT, "eye");
    CHECK_FAILS(projcurve_project_face(ctx, f, line, PROJCURVE_PROJECT_DIRECTIONAL, nan_dir,
                                       NULL, &r),
                PROJCURVE_ERR_NOT_FINITE, "direction");
    CHECK_FAILS(projcurve_project_face(ctx, f, line, PROJCURVE_PROJECT_CONICAL, inf_eye, NULL,
                                       &r),
                PROJCURVE_ERR_NOT_FINITE, "eye");
    CHECK_FAILS(projcurve_project_face(ctx, f, line, PROJCURVE_PROJECT_DIRECTIONAL, zero, NULL,
                                       &r),
                PROJCURVE_ERR_ZERO_DIRECTION, "zero");
    CHECK_FAILS(projcurve_project_face(ctx, f, line, (projcurve_projection_kind)7, down, NULL,
                                       &r),
                PROJCURVE_ERR_INVALID_ARGUMENT, "kind 7");
    CHECK_FAILS(projcurve_project_face(ctx, f, line, (projcurve_projection_kind)-1, down, NULL,
                                       &r),
                PROJCURVE_ERR_INVALID_ARGUMENT, "kind -1");
    const double eye_on_line[3] = {0.5, 0.5, 1};
    CHECK_FAILS(projcurve_project_face(ctx, f, line, PROJCURVE_PROJECT_CONICAL, eye_on_line,
                                       NULL, &r),
                PROJCURVE_ERR_SINGULAR, "eye");
    CHECK_FAILS(projcurve_project_face(ctx, f, point_curve, PROJCURVE_PROJECT_DIRECTIONAL, down,
                                       NULL, &r),
                PROJCURVE_ERR_SINGULAR, "point");
    CHECK_FAILS(projcurve_project_shape(ctx, NULL, line, PROJCURVE_PROJECT_DIRECTIONAL, down,
                                        NULL, &r),
                PROJCURVE_ERR_NULL_ARGUMENT, "shape");
    CHECK(r == SENTINEL);
    /* orthogonal takes no vector */
    CHECK_OK(projcurve_project_face(ctx, f, line, PROJCURVE_PROJECT_ORTHOGONAL, NULL, NULL, &r));
    projcurve_shape_result_destroy(r);
}

static void test_shape_result(const projcurve_shape_result *r)
{
    CHECK(projcurve_shape_result_curve_count(r) == 1 && projcurve_shape_result_face_count(r) == 1);
    CHECK(projcurve_shape_result_curve_count(NULL) == 0 &&
          projcurve_shape_result_face_count(NULL) == 0 &&
          projcurve_shape_result_open_end_count(NULL) == 0 &&
          projcurve_shape_result_chain_tolerance(NULL) == 0.0);
    size_t n = 77;
    CHECK_FAILS(projcurve_shape_result_curve_info(ctx, NULL, 0, &n, NULL, NULL),
                PROJCURVE_ERR_NULL_ARGUMENT, "shape result");
    CHECK_FAILS(projcurve_shape_result_curve_info(ctx, r, 1, &n, NULL, NULL), PROJCURVE_ERR_INDEX,
                "connected curve 1");
    CHECK_FAILS(projcurve_shape_result_piece(ctx, NULL, 0, 0, &n, NULL, NULL, NULL, NULL, NULL),
                PROJCURVE_ERR_NULL_ARGUMENT, "shape result");
    CHECK_FAILS(projcurve_shape_result_piece(ctx, r, 1, 0, &n, NULL, NULL, NULL, NULL, NULL),
                PROJCURVE_ERR_INDEX, "connected curve 1");
    CHECK_FAILS(projcurve_shape_result_piece(ctx, r, 0, 1, &n, NULL, NULL, NULL, NULL, NULL),
                PROJCURVE_ERR_INDEX, "piece 1");
    CHECK_FAILS(projcurve_shape_result_face(ctx, NULL, 0, &n, NULL, NULL, NULL),
                PROJCURVE_ERR_NULL_ARGUMENT, "shape result");
    CHECK_FAILS(projcurve_shape_result_face(ctx, r, 1, &n, NULL, NULL, NULL), PROJCURVE_ERR_INDEX,
                "projected face 1");
    CHECK(n == 77);
    CHECK_OK(projcurve_shape_result_curve_info(ctx, r, 0, NULL, NULL, NULL));
    CHECK_OK(projcurve_shape_result_piece(ctx, r, 0, 0, NULL, NULL, NULL, NULL, NULL, NULL));
    CHECK_OK(projcurve_shape_result_face(ctx, r, 0, NULL, NULL, NULL, NULL));
    projcurve_shape_result_destroy(NULL);
}

/* A face result, its branch cut at the loop: on the face's surface, so
 * both writers take it. */
static void test_write_face_result(const projcurve_surface *plane,
                                   const projcurve_shape_result *r)
{
    const projcurve_result *fr = NULL;
    CHECK_OK(projcurve_shape_result_face(ctx, r, 0, NULL, &fr, NULL, NULL));
    projcurve_step_writer *sw = NULL;
    projcurve_iges_writer *iw = NULL;
    CHECK_OK(projcurve_step_writer_create(ctx, &sw));
    CHECK_OK(projcurve_iges_writer_create(ctx, &iw));
    CHECK_OK(projcurve_step_writer_add_result(ctx, sw, plane, fr));
    CHECK_OK(projcurve_iges_writer_add_result(ctx, iw, plane, fr));
    CHECK_OK(projcurve_iges_writer_add_result_pieces(ctx, iw, plane, fr));
    projcurve_step_writer_destroy(sw);
    projcurve_iges_writer_destroy(iw);
}

static void test_model_topology(const projcurve_model *m)
{
    CHECK(projcurve_model_face_count(NULL) == 0 && projcurve_model_shape_count(NULL) == 0 &&
          projcurve_model_unbuilt_face_count(NULL) == 0);
    CHECK(projcurve_model_face(NULL, 0) == NULL && projcurve_model_shape(NULL, 0) == NULL &&
          projcurve_model_unbuilt_face(NULL, 0) == NULL &&
          projcurve_model_unbuilt_face_kind(NULL, 0) == NULL &&
          projcurve_model_surface_kind(NULL, 0) == NULL);
    CHECK(projcurve_model_face(m, projcurve_model_face_count(m)) == NULL);
    CHECK(projcurve_model_shape(m, projcurve_model_shape_count(m)) == NULL);
    CHECK(projcurve_model_surface_kind(m, projcurve_model_surface_count(m)) == NULL);
    CHECK(projcurve_model_surface_kind(m, (size_t)-1) == NULL);
    const size_t nu = projcurve_model_unbuilt_face_count(m);
    CHECK(projcurve_model_unbuilt_face(m, nu) == NULL &&
          projcurve_model_unbuilt_face_kind(m, nu) == NULL);
    double unit = 77, precision = 77;
    CHECK(projcurve_model_length_unit(NULL, &unit) == 0 && unit == 77);
    CHECK(projcurve_model_precision(NULL, &precision) == 0 && precision == 77);
    projcurve_model_length_unit(m, NULL);
    projcurve_model_precision(m, NULL);
}

static void test_shape(const projcurve_shape *s)
{
    CHECK(projcurve_shape_face_count(NULL) == 0 && projcurve_shape_edge_count(NULL) == 0 &&
          projcurve_shape_face(NULL, 0) == NULL);
    const size_t nf = projcurve_shape_face_count(s), ne = projcurve_shape_edge_count(s);
    CHECK(nf > 0 && ne > 0);
    CHECK(projcurve_shape_face(s, nf) == NULL);
    projcurve_shape_kind kind = (projcurve_shape_kind)77;
    CHECK_FAILS(projcurve_shape_info(ctx, NULL, &kind, NULL), PROJCURVE_ERR_NULL_ARGUMENT,
                "shape");
    CHECK(kind == (projcurve_shape_kind)77);
    CHECK_OK(projcurve_shape_info(ctx, s, NULL, NULL));
    size_t index = 77;
    CHECK_FAILS(projcurve_shape_face_model_index(ctx, NULL, 0, &index),
                PROJCURVE_ERR_NULL_ARGUMENT, "shape");
    CHECK_FAILS(projcurve_shape_face_model_index(ctx, s, 0, NULL), PROJCURVE_ERR_NULL_ARGUMENT,
                "model_index");
    CHECK_FAILS(projcurve_shape_face_model_index(ctx, s, nf, &index), PROJCURVE_ERR_INDEX,
                "face");
    long id = 77;
    CHECK_FAILS(projcurve_shape_edge(ctx, NULL, 0, &id, NULL), PROJCURVE_ERR_NULL_ARGUMENT,
                "shape");
    CHECK_FAILS(projcurve_shape_edge(ctx, s, ne, &id, NULL), PROJCURVE_ERR_INDEX, "edge");
    CHECK_OK(projcurve_shape_edge(ctx, s, 0, NULL, NULL));
    size_t uses = 0;
    CHECK_OK(projcurve_shape_edge(ctx, s, 0, NULL, &uses));
    CHECK_FAILS(projcurve_shape_edge_use(ctx, NULL, 0, 0, &index, NULL, NULL, NULL),
                PROJCURVE_ERR_NULL_ARGUMENT, "shape");
    CHECK_FAILS(projcurve_shape_edge_use(ctx, s, ne, 0, &index, NULL, NULL, NULL),
                PROJCURVE_ERR_INDEX, "edge");
    CHECK_FAILS(projcurve_shape_edge_use(ctx, s, 0, uses, &index, NULL, NULL, NULL),
                PROJCURVE_ERR_INDEX, "use");
    CHECK(index == 77 && id == 77);
    CHECK_OK(projcurve_shape_edge_use(ctx, s, 0, 0, NULL, NULL, NULL, NULL));
}

/* A shape read from a STEP file, projected onto: the accessors of its
 * model, of the shape and of the result. */
static void test_shape_model(const projcurve_curve *line)
{
    projcurve_model *m = NULL;
    CHECK_OK(projcurve_model_read_file(ctx, pc_test_data_path("cases-brep/cylinder_analytic.step"),
                                       &m));
    if (m == NULL || projcurve_model_shape_count(m) == 0) {
        pc_test_fail_at(__FILE__, __LINE__, "cylinder_analytic.step gave no shape");
        projcurve_model_destroy(m);
        return;
    }
    test_model_topology(m);
    const projcurve_shape *s = projcurve_model_shape(m, 0);
    test_shape(s);
    projcurve_shape_result *r = SENTINEL;
    CHECK_FAILS(projcurve_project_shape(ctx, s, NULL, PROJCURVE_PROJECT_DIRECTIONAL, down, NULL,
                                        &r),
                PROJCURVE_ERR_NULL_ARGUMENT, "curve");
    CHECK_FAILS(projcurve_project_shape(ctx, s, line, (projcurve_projection_kind)3, down, NULL,
                                        &r),
                PROJCURVE_ERR_INVALID_ARGUMENT, "kind");
    CHECK(r == SENTINEL);
    projcurve_model_destroy(m);
}

/* The IGES writer given a result of another surface: refused like the
 * STEP writer's, traced-only results by their (u, v) leaving the domain. */
static void test_iges_other_surface(const projcurve_surface *plane,
                                    const projcurve_surface *lifted,
                                    const projcurve_surface *shifted,
                                    const projcurve_result *composed,
                                    const projcurve_result *traced)
{
    projcurve_iges_writer *w = NULL;
    CHECK_OK(projcurve_iges_writer_create(ctx, &w));
    CHECK_FAILS(projcurve_iges_writer_add_result(ctx, w, lifted, composed),
                PROJCURVE_ERR_INVALID_ARGUMENT, "not projected onto this surface");
    CHECK_FAILS(projcurve_iges_writer_add_result_pieces(ctx, w, lifted, composed),
                PROJCURVE_ERR_INVALID_ARGUMENT, "not projected onto this surface");
    CHECK_FAILS(projcurve_iges_writer_add_result(ctx, w, shifted, traced),
                PROJCURVE_ERR_INVALID_ARGUMENT, "outside the surface's domain");
    CHECK_OK(projcurve_iges_writer_add_result(ctx, w, plane, composed));
    CHECK_OK(projcurve_iges_writer_add_result(ctx, w, plane, traced));
    projcurve_iges_writer_destroy(w);
}

static void test_step_writer(const projcurve_surface *plane, const projcurve_surface *lifted,
                             const projcurve_surface *shifted, const projcurve_curve *line,
                             const projcurve_curve *callback_curve,
                             const projcurve_result *composed, const projcurve_result *traced,
                             const projcurve_result *implicit)
{
    projcurve_step_writer *w = NULL;
    CHECK_FAILS(projcurve_step_writer_create(ctx, NULL), PROJCURVE_ERR_NULL_ARGUMENT, "out");
    CHECK_OK(projcurve_step_writer_create(ctx, &w));
    CHECK_FAILS(projcurve_step_writer_add_surface(ctx, NULL, plane), PROJCURVE_ERR_NULL_ARGUMENT,
                "writer");
    CHECK_FAILS(projcurve_step_writer_add_surface(ctx, w, NULL), PROJCURVE_ERR_NULL_ARGUMENT,
                "surface");
    CHECK_FAILS(projcurve_step_writer_add_curve(ctx, NULL, line), PROJCURVE_ERR_NULL_ARGUMENT,
                "writer");
    CHECK_FAILS(projcurve_step_writer_add_curve(ctx, w, NULL), PROJCURVE_ERR_NULL_ARGUMENT,
                "curve");
    CHECK_FAILS(projcurve_step_writer_add_curve(ctx, w, callback_curve), PROJCURVE_ERR_WRONG_KIND,
                "callback");
    CHECK_FAILS(projcurve_step_writer_add_result(ctx, NULL, plane, traced),
                PROJCURVE_ERR_NULL_ARGUMENT, "writer");
    CHECK_FAILS(projcurve_step_writer_add_result(ctx, w, NULL, traced),
                PROJCURVE_ERR_NULL_ARGUMENT, "surface");
    CHECK_FAILS(projcurve_step_writer_add_result(ctx, w, plane, NULL),
                PROJCURVE_ERR_NULL_ARGUMENT, "result");
    CHECK_FAILS(projcurve_step_writer_add_result(ctx, w, plane, implicit),
                PROJCURVE_ERR_INVALID_ARGUMENT, "implicit");
    CHECK_FAILS(projcurve_step_writer_add_result(ctx, w, plane, traced),
                PROJCURVE_ERR_INVALID_ARGUMENT, "no compact forms");
    /* a result of another surface: its pcurves do not lie on this one */
    CHECK_FAILS(projcurve_step_writer_add_result(ctx, w, lifted, composed),
                PROJCURVE_ERR_INVALID_ARGUMENT, "not projected onto this surface");
    CHECK_FAILS(projcurve_step_writer_add_result(ctx, w, shifted, composed),
                PROJCURVE_ERR_INVALID_ARGUMENT, "outside the surface's domain");
    CHECK_OK(projcurve_step_writer_add_result(ctx, w, plane, composed));
    const double bad[] = {NAN, INFINITY, -INFINITY};
    for (int k = 0; k < 3; ++k) {
        CHECK_FAILS(projcurve_step_writer_set_length_unit(ctx, w, bad[k]),
                    PROJCURVE_ERR_NOT_FINITE, "not finite");
        CHECK_FAILS(projcurve_step_writer_set_uncertainty(ctx, w, bad[k]),
                    PROJCURVE_ERR_NOT_FINITE, "not finite");
    }
    CHECK_FAILS(projcurve_step_writer_set_length_unit(ctx, w, 0.0), PROJCURVE_ERR_OUT_OF_RANGE,
                "not positive");
    CHECK_FAILS(projcurve_step_writer_set_length_unit(ctx, w, -0.001), PROJCURVE_ERR_OUT_OF_RANGE,
                "not positive");
    CHECK_FAILS(projcurve_step_writer_set_uncertainty(ctx, w, 0.0), PROJCURVE_ERR_OUT_OF_RANGE,
                "not positive");
    CHECK_FAILS(projcurve_step_writer_set_length_unit(ctx, NULL, 0.001),
                PROJCURVE_ERR_NULL_ARGUMENT, "writer");
    CHECK_FAILS(projcurve_step_writer_set_uncertainty(ctx, NULL, 1e-7),
                PROJCURVE_ERR_NULL_ARGUMENT, "writer");
    CHECK_FAILS(projcurve_step_writer_write(ctx, NULL, "x.stp"), PROJCURVE_ERR_NULL_ARGUMENT,
                "writer");
    CHECK_FAILS(projcurve_step_writer_write(ctx, w, NULL), PROJCURVE_ERR_NULL_ARGUMENT, "path");
    CHECK_FAILS(projcurve_step_writer_write(ctx, w, "/nonexistent-dir/x.stp"), PROJCURVE_ERR_IO,
                "nonexistent-dir");
    projcurve_step_writer_destroy(w);
    projcurve_step_writer_destroy(NULL);
}

static void test_compact_exact(const projcurve_surface *plane, const projcurve_surface *other,
                               const projcurve_result *composed, const projcurve_result *traced,
                               const projcurve_result *implicit)
{
    projcurve_curve *c = SENTINEL;
    CHECK_FAILS(projcurve_result_branch_compact_exact(ctx, NULL, plane, 0, &c),
                PROJCURVE_ERR_NULL_ARGUMENT, "result");
    CHECK_FAILS(projcurve_result_branch_compact_exact(ctx, composed, NULL, 0, &c),
                PROJCURVE_ERR_NULL_ARGUMENT, "surface");
    CHECK_FAILS(projcurve_result_branch_compact_exact(ctx, composed, plane, 0, NULL),
                PROJCURVE_ERR_NULL_ARGUMENT, "out");
    CHECK_FAILS(projcurve_result_branch_compact_exact(ctx, composed, plane, 1, &c),
                PROJCURVE_ERR_INDEX, "branch 1");
    CHECK_FAILS(projcurve_result_branch_compact_exact(ctx, traced, plane, 0, &c),
                PROJCURVE_ERR_INVALID_ARGUMENT, "no compact forms");
    CHECK_FAILS(projcurve_result_branch_compact_exact(ctx, implicit, plane, 0, &c),
                PROJCURVE_ERR_INVALID_ARGUMENT, "implicit");
    CHECK_FAILS(projcurve_result_branch_compact_exact(ctx, composed, other, 0, &c),
                PROJCURVE_ERR_INVALID_ARGUMENT, "not projected onto this surface");
    CHECK(c == SENTINEL);
}

static int plane_fn(void *user, const double x[3], double *value, double grad[3], double hess[9])
{
    (void)user;
    *value = x[2];
    grad[0] = grad[1] = 0.0, grad[2] = 1.0;
    memset(hess, 0, 9 * sizeof(double));
    return 0;
}

int main(void)
{
    pc_test_hang_guard(60);
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    projcurve_surface *plane = NULL, *lifted = NULL, *shifted = NULL;
    projcurve_curve *line = NULL, *point_curve = NULL, *callback_curve = NULL;
    const double lifted_net[] = {0, 0, 0.5, 1, 0, 0.5, 0, 1, 0.5, 1, 1, 0.5};
    const double point_net[] = {0.5, 0.5, 1, 0.5, 0.5, 1};
    CHECK_OK(projcurve_surface_create_nurbs(ctx, 1, 1, 2, 2, plane_net, NULL, knots01, knots01,
                                            &plane));
    CHECK_OK(projcurve_surface_create_nurbs(ctx, 1, 1, 2, 2, lifted_net, NULL, knots01, knots01,
                                            &lifted));
    /* the plane over the domain [5, 6]^2: the same points, other (u, v) */
    const double knots56[] = {5, 5, 6, 6};
    CHECK_OK(projcurve_surface_create_nurbs(ctx, 1, 1, 2, 2, plane_net, NULL, knots56, knots56,
                                            &shifted));
    CHECK_OK(projcurve_curve_create_nurbs(ctx, 1, 2, line_net, NULL, knots01, &line));
    CHECK_OK(projcurve_curve_create_nurbs(ctx, 1, 2, point_net, NULL, knots01, &point_curve));
    pc_shape_line above = {{0.1, 0.5, 1}, {0.8, 0, 0}};
    CHECK_OK(projcurve_curve_create_callback(ctx, pc_shape_line_fn, &above, 0, 1,
                                             &callback_curve));
    projcurve_options *traced_opts = NULL;
    CHECK_OK(projcurve_options_create(ctx, &traced_opts));
    CHECK_OK(projcurve_options_set_int(ctx, traced_opts, PROJCURVE_OPT_COMPOSE, 0));
    projcurve_result *composed = NULL, *traced = NULL, *implicit = NULL;
    CHECK_OK(projcurve_project_directional(ctx, plane, line, down, NULL, &composed));
    CHECK_OK(projcurve_project_directional(ctx, plane, line, down, traced_opts, &traced));
    CHECK_OK(projcurve_project_orthogonal_implicit(ctx, plane_fn, NULL, 1.0, line, NULL,
                                                   &implicit));
    projcurve_options_destroy(traced_opts);
    projcurve_options_destroy(NULL);
    if (plane && line && composed && traced && implicit) {
        test_face_create(plane);
        test_face_loops(plane);
        square_loop L;
        square(&L, 0.2, 0.8);
        projcurve_face *f = NULL;
        CHECK_OK(make_face(plane, &L, 0.0, &f));
        if (f) {
            test_face_queries(f);
            test_project_args(f, line, point_curve);
            projcurve_shape_result *r = NULL;
            CHECK_OK(projcurve_project_face(ctx, f, line, PROJCURVE_PROJECT_DIRECTIONAL, down,
                                            NULL, &r));
            if (r) {
                test_shape_result(r);
                test_write_face_result(plane, r);
            }
            projcurve_shape_result_destroy(r);
        }
        projcurve_face_destroy(f);
        test_shape_model(line);
        test_step_writer(plane, lifted, shifted, line, callback_curve, composed, traced,
                         implicit);
        test_iges_other_surface(plane, lifted, shifted, composed, traced);
        test_compact_exact(plane, lifted, composed, traced, implicit);
    }
    projcurve_result_destroy(composed);
    projcurve_result_destroy(traced);
    projcurve_result_destroy(implicit);
    projcurve_curve_destroy(line);
    projcurve_curve_destroy(point_curve);
    projcurve_curve_destroy(callback_curve);
    projcurve_surface_destroy(plane);
    projcurve_surface_destroy(lifted);
    projcurve_surface_destroy(shifted);
    projcurve_context_destroy(ctx);
    return pc_test_finish("test_api_bad_input_shape");
}
