/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The cells of docs/bad-input.md that no other test shows: each public
 * function of the writer, model, result, curve, projection and option
 * groups against NULL, non-finite, out-of-range and wrong-kind input. Each
 * call must give the status the header documents, a message naming the
 * problem, and leave the output pointer untouched.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "common/error.h"
#include "projcurve.h"

static projcurve_context *ctx;
static projcurve_surface *plane;
static projcurve_curve *line, *callback_curve;
static projcurve_result *result, *traced_only, *implicit_result;

static const double plane_net[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
static const double line_net[] = {0.1, 0.2, 1, 0.8, 0.7, 1};
static const double knots[] = {0, 0, 1, 1};
static const double down[3] = {0, 0, -1};

#define SENTINEL ((void *)&ctx)

/* A call that must fail with `expected` and a message containing `needle`. */
#define CHECK_FAILS(call, expected, needle)                                            \
    do {                                                                               \
        projcurve_context_clear(ctx);                                                  \
        CHECK_STATUS(call, expected);                                                  \
        if (strstr(projcurve_context_message(ctx), needle) == NULL)                    \
            pc_test_fail_at(__FILE__, __LINE__, "%s: message \"%s\" lacks \"%s\"", #call, \
                            projcurve_context_message(ctx), needle);                   \
    } while (0)

static int line_fn(void *user, double t, double out[9])
{
    (void)user;
    memset(out, 0, 9 * sizeof(double));
    out[0] = t, out[1] = 0.5, out[2] = 1.0, out[3] = 1.0;
    return 0;
}

static int nan_fn(void *user, double t, double out[9])
{
    (void)user;
    (void)t;
    for (int i = 0; i < 9; ++i)
        out[i] = NAN;
    return 0;
}

/* The line of line_fn, whose callback fails past t = 0.5: the failure
 * happens in the middle of tracing. */
static int half_fn(void *user, double t, double out[9])
{
    return t > 0.5 ? 1 : line_fn(user, t, out);
}

/* The plane z = 0 as an implicit surface. */
static int plane_fn(void *user, const double x[3], double *value, double grad[3], double hess[9])
{
    (void)user;
    *value = x[2];
    grad[0] = grad[1] = 0.0, grad[2] = 1.0;
    memset(hess, 0, 9 * sizeof(double));
    return 0;
}

static void test_writer(void)
{
    projcurve_iges_writer *w = NULL;
    CHECK_STATUS(projcurve_iges_writer_create(ctx, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_OK(projcurve_iges_writer_create(ctx, &w));
    CHECK_FAILS(projcurve_iges_writer_add_surface(ctx, NULL, plane), PROJCURVE_ERR_NULL_ARGUMENT,
                "writer");
    CHECK_FAILS(projcurve_iges_writer_add_surface(ctx, w, NULL), PROJCURVE_ERR_NULL_ARGUMENT,
                "surface");
    CHECK_FAILS(projcurve_iges_writer_add_curve(ctx, w, NULL), PROJCURVE_ERR_NULL_ARGUMENT,
                "curve");
    CHECK_FAILS(projcurve_iges_writer_add_curve(ctx, w, callback_curve),
                PROJCURVE_ERR_WRONG_KIND, "callback");
    CHECK_FAILS(projcurve_iges_writer_add_result(ctx, w, plane, NULL),
                PROJCURVE_ERR_NULL_ARGUMENT, "result");
    CHECK_FAILS(projcurve_iges_writer_add_result(ctx, w, NULL, result),
                PROJCURVE_ERR_NULL_ARGUMENT, "surface");
    CHECK_FAILS(projcurve_iges_writer_add_result(ctx, w, plane, implicit_result),
                PROJCURVE_ERR_INVALID_ARGUMENT, "implicit");
    CHECK_FAILS(projcurve_iges_writer_write(ctx, w, NULL), PROJCURVE_ERR_NULL_ARGUMENT, "path");
    CHECK_FAILS(projcurve_iges_writer_write(ctx, NULL, "x.igs"), PROJCURVE_ERR_NULL_ARGUMENT,
                "writer");
    CHECK_FAILS(projcurve_iges_writer_write(ctx, w, "/nonexistent-dir/x.igs"), PROJCURVE_ERR_IO,
                "nonexistent-dir");
    CHECK_FAILS(projcurve_iges_writer_add_result_pieces(ctx, w, plane, implicit_result),
                PROJCURVE_ERR_INVALID_ARGUMENT, "implicit");
    CHECK_FAILS(projcurve_iges_writer_add_result_pieces(ctx, NULL, plane, result),
                PROJCURVE_ERR_NULL_ARGUMENT, "writer");
    CHECK_FAILS(projcurve_iges_writer_set_length_unit(ctx, NULL, 0.001),
                PROJCURVE_ERR_NULL_ARGUMENT, "writer");
    CHECK_FAILS(projcurve_iges_writer_set_length_unit(ctx, w, NAN), PROJCURVE_ERR_NOT_FINITE,
                "finite");
    CHECK_FAILS(projcurve_iges_writer_set_length_unit(ctx, w, 0.5), PROJCURVE_ERR_OUT_OF_RANGE,
                "IGES units");
    /* a result traced but not composed is written as its pcurves */
    CHECK_OK(projcurve_iges_writer_add_result(ctx, w, plane, traced_only));
    projcurve_iges_writer_destroy(w);
    projcurve_iges_writer_destroy(NULL);
}

static void test_model(void)
{
    projcurve_model *m = SENTINEL;
    CHECK_FAILS(projcurve_model_read_file(ctx, NULL, &m), PROJCURVE_ERR_NULL_ARGUMENT, "path");
    CHECK_FAILS(projcurve_model_read_file(ctx, "x.igs", NULL), PROJCURVE_ERR_NULL_ARGUMENT, "out");
    CHECK_FAILS(projcurve_model_read_file(ctx, "/nonexistent-dir/x.igs", &m), PROJCURVE_ERR_IO,
                "nonexistent-dir");
    CHECK_FAILS(projcurve_model_read_memory(ctx, NULL, 4, &m), PROJCURVE_ERR_NULL_ARGUMENT, "data");
    CHECK_FAILS(projcurve_model_read_memory(ctx, "abcd", 4, NULL), PROJCURVE_ERR_NULL_ARGUMENT,
                "out");
    CHECK_FAILS(projcurve_model_read_memory(ctx, "neither IGES nor STEP", 21, &m),
                PROJCURVE_ERR_PARSE, "unrecognised file format");
    /* refused by its length before a byte is read */
    CHECK_FAILS(projcurve_model_read_memory(ctx, "x", (size_t)1 << 31, &m),
                PROJCURVE_ERR_UNSUPPORTED, "more than");
    {
        projcurve_context_clear(ctx);
        const projcurve_status st = projcurve_model_read_file(ctx, "/", &m);
        CHECK(st == PROJCURVE_ERR_IO || st == PROJCURVE_ERR_PARSE); /* a directory */
    }
    CHECK(m == SENTINEL);
    /* accessors of a NULL model and past the end */
    CHECK(projcurve_model_surface_count(NULL) == 0 && projcurve_model_curve_count(NULL) == 0 &&
          projcurve_model_skipped_count(NULL) == 0);
    CHECK(projcurve_model_surface(NULL, 0) == NULL && projcurve_model_curve(NULL, 0) == NULL &&
          projcurve_model_skipped(NULL, 0) == NULL);
    m = NULL;
    const char *path = pc_test_data_path("cases/bumpy_bicubic_8x8_down.igs");
    CHECK_OK(projcurve_model_read_file(ctx, path, &m));
    CHECK(projcurve_model_surface(m, projcurve_model_surface_count(m)) == NULL);
    CHECK(projcurve_model_curve(m, projcurve_model_curve_count(m)) == NULL);
    CHECK(projcurve_model_skipped(m, projcurve_model_skipped_count(m)) == NULL);
    CHECK(projcurve_model_surface(m, (size_t)-1) == NULL);
    projcurve_model_destroy(m);
    projcurve_model_destroy(NULL);
}

static void test_result(void)
{
    const size_t n = projcurve_result_branch_count(result);
    double v = 0.0, t[2], pts[3];
    size_t count = 0;
    int degree = 0;
    CHECK(n == 1);
    CHECK(projcurve_result_branch_count(NULL) == 0 && projcurve_result_failure_count(NULL) == 0 &&
          projcurve_result_point_dim(NULL) == 0);
    CHECK_FAILS(projcurve_result_stat(ctx, NULL, PROJCURVE_STAT_POINTS, &v),
                PROJCURVE_ERR_NULL_ARGUMENT, "result");
    CHECK_FAILS(projcurve_result_stat(ctx, result, PROJCURVE_STAT_POINTS, NULL),
                PROJCURVE_ERR_NULL_ARGUMENT, "value");
    CHECK_FAILS(projcurve_result_stat(ctx, result, (projcurve_stat)99, &v),
                PROJCURVE_ERR_UNKNOWN_OPTION, "99");
    /* Every statistic of the line over the plane: one branch, no jump,
     * eps_D automatic = 1e-4 of the net's diagonal (sqrt 2), exact
     * projection (a line on a plane: zero estimation error). */
    double stat[PROJCURVE_STAT_MAX_ERROR + 1];
    for (int key = 0; key <= PROJCURVE_STAT_MAX_ERROR; ++key)
        CHECK_OK(projcurve_result_stat(ctx, result, (projcurve_stat)key, &stat[key]));
    CHECK(stat[PROJCURVE_STAT_POINTS] >= 2 && stat[PROJCURVE_STAT_STEPS] >= 1);
    CHECK(stat[PROJCURVE_STAT_NEWTON_ITERATIONS] >= 0 && stat[PROJCURVE_STAT_JUMPS] == 0);
    CHECK(stat[PROJCURVE_STAT_PIECES] >= 1);
    CHECK_NEAR(stat[PROJCURVE_STAT_TOL_DISTANCE], 1e-4 * sqrt(2.0), 1e-15);
    CHECK(stat[PROJCURVE_STAT_AVG_ERROR] >= 0 && stat[PROJCURVE_STAT_AVG_ERROR] <= 1e-12);
    CHECK(stat[PROJCURVE_STAT_MAX_ERROR] >= stat[PROJCURVE_STAT_AVG_ERROR] &&
          stat[PROJCURVE_STAT_MAX_ERROR] <= 1e-12);
    CHECK_FAILS(projcurve_result_branch_info(ctx, NULL, 0, t, NULL, NULL, NULL, NULL),
                PROJCURVE_ERR_NULL_ARGUMENT, "result");
    CHECK_FAILS(projcurve_result_branch_info(ctx, result, n, t, NULL, NULL, NULL, NULL),
                PROJCURVE_ERR_INDEX, "branch 1 of 1");
    CHECK_FAILS(projcurve_result_branch_points(ctx, result, 0, 1, NULL, &count),
                PROJCURVE_ERR_NULL_ARGUMENT, "points");
    CHECK_FAILS(projcurve_result_branch_points(ctx, result, 0, 1, pts, NULL),
                PROJCURVE_ERR_NULL_ARGUMENT, "count");
    CHECK_FAILS(projcurve_result_branch_points(ctx, result, n, 1, pts, &count),
                PROJCURVE_ERR_INDEX, "branch");
    size_t n_pieces = 0;
    CHECK_OK(projcurve_result_branch_info(ctx, result, 0, NULL, NULL, NULL, NULL, &n_pieces));
    CHECK_FAILS(projcurve_result_piece(ctx, result, 0, n_pieces, &degree, NULL, NULL, NULL, NULL),
                PROJCURVE_ERR_INDEX, "piece");
    CHECK_FAILS(projcurve_result_piece(ctx, result, n, 0, &degree, NULL, NULL, NULL, NULL),
                PROJCURVE_ERR_INDEX, "branch");
    CHECK_FAILS(projcurve_result_piece_pcurve(ctx, result, 0, n_pieces, &degree, NULL),
                PROJCURVE_ERR_INDEX, "piece");
    CHECK_FAILS(projcurve_result_piece_pcurve(ctx, NULL, 0, 0, &degree, NULL),
                PROJCURVE_ERR_NULL_ARGUMENT, "result");
    projcurve_curve *c = SENTINEL;
    CHECK_FAILS(projcurve_result_branch_curve(ctx, result, 0, NULL), PROJCURVE_ERR_NULL_ARGUMENT,
                "out");
    CHECK_FAILS(projcurve_result_branch_curve(ctx, result, n, &c), PROJCURVE_ERR_INDEX, "branch");
    CHECK_FAILS(projcurve_result_branch_curve(ctx, traced_only, 0, &c),
                PROJCURVE_ERR_INVALID_ARGUMENT, "COMPOSE 0");
    CHECK_FAILS(projcurve_result_branch_compact_curve(ctx, result, n, &c), PROJCURVE_ERR_INDEX,
                "branch");
    CHECK_FAILS(projcurve_result_branch_compact_pcurve(ctx, traced_only, 0, &c),
                PROJCURVE_ERR_INVALID_ARGUMENT, "COMPOSE 0");
    CHECK(projcurve_result_branch_count(implicit_result) > 0);
    CHECK_FAILS(projcurve_result_branch_compact_info(ctx, implicit_result, 0, NULL, NULL, NULL),
                PROJCURVE_ERR_INVALID_ARGUMENT, "implicit");
    CHECK_FAILS(projcurve_surface_nurbs_data(ctx, NULL, NULL, NULL, NULL, NULL),
                PROJCURVE_ERR_NULL_ARGUMENT, "surface");
    CHECK_FAILS(projcurve_result_piece(ctx, traced_only, 0, 0, &degree, NULL, NULL, NULL, NULL),
                PROJCURVE_ERR_INDEX, "piece 0 of 0");
    /* the seam records: a line over a plane crosses no seam */
    size_t seams = 99;
    CHECK_FAILS(projcurve_result_branch_seam_count(ctx, NULL, 0, &seams),
                PROJCURVE_ERR_NULL_ARGUMENT, "result");
    CHECK_FAILS(projcurve_result_branch_seam_count(ctx, result, 0, NULL),
                PROJCURVE_ERR_NULL_ARGUMENT, "count");
    CHECK_FAILS(projcurve_result_branch_seam_count(ctx, result, n, &seams), PROJCURVE_ERR_INDEX,
                "branch 1 of 1");
    CHECK(seams == 99);
    CHECK_OK(projcurve_result_branch_seam_count(ctx, result, 0, &seams));
    CHECK(seams == 0);
    double st = -1.0, du = -1.0, dv = -1.0;
    CHECK_FAILS(projcurve_result_branch_seam(ctx, result, 0, 0, &st, &du, &dv),
                PROJCURVE_ERR_INDEX, "seam 0 of 0 on branch 0");
    CHECK_FAILS(projcurve_result_branch_seam(ctx, result, n, 0, &st, &du, &dv),
                PROJCURVE_ERR_INDEX, "branch 1 of 1");
    CHECK_FAILS(projcurve_result_branch_seam(ctx, NULL, 0, 0, &st, &du, &dv),
                PROJCURVE_ERR_NULL_ARGUMENT, "result");
    CHECK(st == -1.0 && du == -1.0 && dv == -1.0);
    CHECK(c == SENTINEL);
    projcurve_result_destroy(NULL);
}

static void test_curves(void)
{
    projcurve_curve *c = SENTINEL;
    double t0 = 0.0, t1 = 0.0, p[12];
    int degree = 0;
    size_t n = 0;
    CHECK_FAILS(projcurve_curve_create_callback(ctx, NULL, NULL, 0.0, 1.0, &c),
                PROJCURVE_ERR_NULL_ARGUMENT, "fn");
    CHECK_FAILS(projcurve_curve_create_callback(ctx, line_fn, NULL, 0.0, NAN, &c),
                PROJCURVE_ERR_NOT_FINITE, "not finite");
    CHECK_FAILS(projcurve_curve_create_callback(ctx, line_fn, NULL, 1.0, 1.0, &c),
                PROJCURVE_ERR_INVALID_ARGUMENT, "domain");
    CHECK(c == SENTINEL);
    CHECK_FAILS(projcurve_curve_nurbs_info(ctx, callback_curve, &degree, &n, NULL, NULL),
                PROJCURVE_ERR_WRONG_KIND, "callback");
    CHECK_FAILS(projcurve_curve_nurbs_data(ctx, callback_curve, p, NULL, NULL),
                PROJCURVE_ERR_WRONG_KIND, "callback");
    CHECK_FAILS(projcurve_curve_domain(ctx, NULL, &t0, &t1), PROJCURVE_ERR_NULL_ARGUMENT, "curve");
    CHECK_FAILS(projcurve_curve_domain(ctx, line, NULL, &t1), PROJCURVE_ERR_NULL_ARGUMENT, "t0");
    CHECK_FAILS(projcurve_curve_eval(ctx, line, 0.5, 4, p), PROJCURVE_ERR_OUT_OF_RANGE, "4");
    CHECK_FAILS(projcurve_curve_eval(ctx, line, INFINITY, 0, p), PROJCURVE_ERR_NOT_FINITE,
                "not finite");
    CHECK_FAILS(projcurve_curve_eval(ctx, line, 1.5, 0, p), PROJCURVE_ERR_OUT_OF_DOMAIN, "1.5");
    projcurve_curve *bad = NULL;
    CHECK_OK(projcurve_curve_create_callback(ctx, nan_fn, NULL, 0.0, 1.0, &bad));
    CHECK_FAILS(projcurve_curve_eval(ctx, bad, 0.5, 0, p), PROJCURVE_ERR_CALLBACK, "");
    projcurve_result *r = SENTINEL;
    CHECK_STATUS(projcurve_project_directional(ctx, plane, bad, down, NULL, &r),
                 PROJCURVE_ERR_CALLBACK);
    CHECK(r == SENTINEL);
    projcurve_curve_destroy(bad);
    projcurve_curve *half = NULL;
    CHECK_OK(projcurve_curve_create_callback(ctx, half_fn, NULL, 0.0, 1.0, &half));
    CHECK_FAILS(projcurve_project_directional(ctx, plane, half, down, NULL, &r),
                PROJCURVE_ERR_CALLBACK, "curve evaluation failed at t = 0.5");
    CHECK_FAILS(projcurve_project_orthogonal(ctx, plane, half, NULL, &r), PROJCURVE_ERR_CALLBACK,
                "");
    CHECK(r == SENTINEL);
    projcurve_curve_destroy(half);
    projcurve_curve_destroy(NULL);
}

static void test_projections(void)
{
    projcurve_result *r = SENTINEL;
    const double nan_dir[3] = {0, NAN, -1}, zero[3] = {0, 0, 0};
    CHECK_FAILS(projcurve_project_orthogonal(ctx, NULL, line, NULL, &r),
                PROJCURVE_ERR_NULL_ARGUMENT, "surface");
    CHECK_FAILS(projcurve_project_orthogonal(ctx, plane, NULL, NULL, &r),
                PROJCURVE_ERR_NULL_ARGUMENT, "curve");
    CHECK_FAILS(projcurve_project_orthogonal(ctx, plane, line, NULL, NULL),
                PROJCURVE_ERR_NULL_ARGUMENT, "out");
    CHECK_FAILS(projcurve_project_directional(ctx, plane, line, nan_dir, NULL, &r),
                PROJCURVE_ERR_NOT_FINITE, "direction");
    CHECK_FAILS(projcurve_project_directional(ctx, plane, line, zero, NULL, &r),
                PROJCURVE_ERR_ZERO_DIRECTION, "zero");
    /* conical: the eye NULL, not finite, on the curve (the middle of
     * line_net); on the surface it is allowed (the points near it are
     * behind the curve) */
    const double nan_eye[3] = {0.5, 0.5, NAN}, inf_eye[3] = {INFINITY, 0, 2};
    const double eye_on_line[3] = {0.45, 0.45, 1}, eye_on_plane[3] = {0.5, 0.5, 0};
    CHECK_FAILS(projcurve_project_conical(ctx, plane, line, NULL, NULL, &r),
                PROJCURVE_ERR_NULL_ARGUMENT, "eye");
    CHECK_FAILS(projcurve_project_conical(ctx, NULL, line, down, NULL, &r),
                PROJCURVE_ERR_NULL_ARGUMENT, "surface");
    CHECK_FAILS(projcurve_project_conical(ctx, plane, line, down, NULL, NULL),
                PROJCURVE_ERR_NULL_ARGUMENT, "out");
    CHECK_FAILS(projcurve_project_conical(ctx, plane, line, nan_eye, NULL, &r),
                PROJCURVE_ERR_NOT_FINITE, "eye point");
    CHECK_FAILS(projcurve_project_conical(ctx, plane, line, inf_eye, NULL, &r),
                PROJCURVE_ERR_NOT_FINITE, "eye point");
    CHECK_FAILS(projcurve_project_conical(ctx, plane, line, eye_on_line, NULL, &r),
                PROJCURVE_ERR_SINGULAR, "passes through the eye");
    CHECK(r == SENTINEL);
    projcurve_result *from_plane = NULL;
    CHECK_OK(projcurve_project_conical(ctx, plane, line, eye_on_plane, NULL, &from_plane));
    /* every ray from a point of S through the line leaves S behind it */
    CHECK(from_plane != NULL && projcurve_result_branch_count(from_plane) == 0);
    projcurve_result_destroy(from_plane);
    CHECK_FAILS(projcurve_project_orthogonal_implicit(ctx, NULL, NULL, 1.0, line, NULL, &r),
                PROJCURVE_ERR_NULL_ARGUMENT, "implicit");
    CHECK_FAILS(projcurve_project_orthogonal_implicit(ctx, plane_fn, NULL, NAN, line, NULL, &r),
                PROJCURVE_ERR_NOT_FINITE, "model size");
    CHECK_FAILS(projcurve_project_orthogonal_implicit(ctx, plane_fn, NULL, -1.0, line, NULL, &r),
                PROJCURVE_ERR_INVALID_ARGUMENT, "");
    CHECK(r == SENTINEL);
    /* the point queries */
    const double nan_p[3] = {NAN, 0, 0}, p[3] = {0.5, 0.5, 1};
    double uv[2], q[3], d = 0.0, t = 0.0, hits[3];
    size_t count = 0;
    CHECK_FAILS(projcurve_surface_closest_point(ctx, plane, nan_p, uv, q, &d),
                PROJCURVE_ERR_NOT_FINITE, "not finite");
    CHECK_FAILS(projcurve_curve_closest_point(ctx, line, nan_p, &t, q, &d),
                PROJCURVE_ERR_NOT_FINITE, "not finite");
    CHECK_FAILS(projcurve_surface_foot_points(ctx, plane, p, 1, NULL, &count),
                PROJCURVE_ERR_NULL_ARGUMENT, "uv");
    CHECK_FAILS(projcurve_surface_intersect_line(ctx, plane, p, zero, 0, 1, hits, NULL, &count),
                PROJCURVE_ERR_ZERO_DIRECTION, "length 0");
    CHECK_FAILS(projcurve_surface_intersect_line(ctx, plane, nan_p, down, 0, 1, hits, NULL,
                                                 &count),
                PROJCURVE_ERR_NOT_FINITE, "origin");
    CHECK_FAILS(projcurve_surface_intersect_line(ctx, plane, p, down, 0, 1, NULL, NULL, &count),
                PROJCURVE_ERR_NULL_ARGUMENT, "hits");
}

static void test_options(void)
{
    projcurve_options *o = NULL;
    projcurve_progress_fn fn = NULL;
    void *user = NULL;
    CHECK_OK(projcurve_options_create(ctx, &o));
    CHECK_FAILS(projcurve_options_set_progress(ctx, NULL, NULL, NULL), PROJCURVE_ERR_NULL_ARGUMENT,
                "options");
    CHECK_FAILS(projcurve_options_get_progress(ctx, NULL, &fn, &user), PROJCURVE_ERR_NULL_ARGUMENT,
                "options");
    CHECK_FAILS(projcurve_options_set_int(ctx, o, PROJCURVE_OPT_TOL_DISTANCE, 1),
                PROJCURVE_ERR_WRONG_KIND, "TOL_DISTANCE");
    CHECK_FAILS(projcurve_options_set_double(ctx, o, PROJCURVE_OPT_MAX_WORK, 1.0),
                PROJCURVE_ERR_WRONG_KIND, "MAX_WORK");
    CHECK_FAILS(projcurve_options_set_double(ctx, o, PROJCURVE_OPT_TIME_LIMIT, -1.0),
                PROJCURVE_ERR_OUT_OF_RANGE, "TIME_LIMIT");
    /* options valid alone, refused by a projection: eps_D below the
     * Newton tolerance times the model size */
    CHECK_OK(projcurve_options_set_double(ctx, o, PROJCURVE_OPT_TOL_DISTANCE, 1e-300));
    projcurve_result *r = SENTINEL;
    CHECK_FAILS(projcurve_project_directional(ctx, plane, line, down, o, &r),
                PROJCURVE_ERR_OUT_OF_RANGE, "TOL_DISTANCE");
    CHECK(r == SENTINEL);
    projcurve_options_destroy(o);
    projcurve_options_destroy(NULL);
}

/* A context pointer that is not a live context records nothing. */
static void test_contexts(void)
{
    CHECK(strcmp(projcurve_context_message(NULL), "no context") == 0);
    CHECK(projcurve_context_status(NULL) == PROJCURVE_ERR_NULL_ARGUMENT);
    projcurve_context *bad = NULL;
    CHECK_STATUS(projcurve_context_create(PROJCURVE_VERSION_MAJOR + 1, &bad),
                 PROJCURVE_ERR_VERSION);
    CHECK(bad == NULL);
    CHECK_STATUS(projcurve_context_create(PROJCURVE_VERSION_MAJOR, NULL),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    projcurve_context_clear(NULL);
    projcurve_context_destroy(NULL);
    CHECK(strcmp(projcurve_status_string((projcurve_status)999), "unknown status") == 0);
    /* a destroyed context's memory (its magic cleared): refused, unchanged */
    struct projcurve_context stale;
    memset(&stale, 0, sizeof stale);
    CHECK(strcmp(projcurve_context_message(&stale), "invalid context") == 0);
    CHECK(projcurve_context_status(&stale) == PROJCURVE_ERR_INVALID_ARGUMENT);
    projcurve_curve *c = SENTINEL;
    CHECK_STATUS(projcurve_curve_create_nurbs(&stale, 0, 2, line_net, NULL, knots, &c),
                 PROJCURVE_ERR_BAD_DEGREE);
    CHECK(stale.last_status == PROJCURVE_OK && stale.last_message[0] == '\0' && c == SENTINEL);
}

int main(void)
{
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    CHECK_OK(projcurve_surface_create_nurbs(ctx, 1, 1, 2, 2, plane_net, NULL, knots, knots,
                                            &plane));
    CHECK_OK(projcurve_curve_create_nurbs(ctx, 1, 2, line_net, NULL, knots, &line));
    CHECK_OK(projcurve_curve_create_callback(ctx, line_fn, NULL, 0.0, 1.0, &callback_curve));
    CHECK_OK(projcurve_project_directional(ctx, plane, line, down, NULL, &result));
    projcurve_options *no_compose = NULL;
    CHECK_OK(projcurve_options_create(ctx, &no_compose));
    CHECK_OK(projcurve_options_set_int(ctx, no_compose, PROJCURVE_OPT_COMPOSE, 0));
    CHECK_OK(projcurve_project_directional(ctx, plane, line, down, no_compose, &traced_only));
    CHECK_OK(projcurve_project_orthogonal_implicit(ctx, plane_fn, NULL, 1.0, line, NULL,
                                                   &implicit_result));
    projcurve_options_destroy(no_compose);
    if (plane && line && callback_curve && result && traced_only && implicit_result) {
        test_writer();
        test_model();
        test_result();
        test_curves();
        test_projections();
        test_options();
        test_contexts();
    }
    projcurve_result_destroy(implicit_result);
    projcurve_result_destroy(traced_only);
    projcurve_result_destroy(result);
    projcurve_curve_destroy(callback_curve);
    projcurve_curve_destroy(line);
    projcurve_surface_destroy(plane);
    projcurve_context_destroy(ctx);
    return pc_test_finish("test_api_bad_input");
}
