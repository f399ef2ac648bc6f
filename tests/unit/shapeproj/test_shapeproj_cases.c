/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The directional rows of tests/data/cases-brep (MANIFEST.tsv): each
 * model's shapes, each curve of its .curves.igs projected with
 * projcurve_project_shape along the row's Dir. Every traced point of every
 * face piece lies inside its face's loops (projcurve_face_classify) and on
 * its ray in front of the curve; no forward ray hit is missed (rays from
 * P(t) at dense t against every face of the shape, brute force by
 * projcurve_surface_intersect_line, each hit inside a face must be matched
 * by a piece of that face over t); the connected-curve count is the one
 * the row's notes expect, and the 2x2 shell's curve is one connected curve
 * of four face pieces with no gap.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "projcurve.h"

#define MAX_POINTS 20000
#define RAY_SAMPLES 100
#define MAX_HITS 16

typedef struct expect {
    const char *name;
    size_t connected; /* over all curves and shapes of the row */
    size_t closed;    /* of them, closed (a circle projected whole) */
} expect;

/* The counts of the rows' EXPECT notes. */
static const expect expected[] = {
    {"gtest_plane_line_circle", 2, 1}, {"gtest_cylinder_line_circle", 2, 1},
    {"gtest_cone_line_circle", 2, 1},  {"shell_2x2_bspline_oblique", 1, 0},
    {"two_walls_dir", 2, 0},
};

static size_t closed_count;

static double points[4 * MAX_POINTS];

static void eval3(const projcurve_surface *s, const double uv[2], double out[3])
{
    double e[3] = {0, 0, 0};
    CHECK_OK(projcurve_surface_eval(NULL, s, uv[0], uv[1], 0, e));
    memcpy(out, e, sizeof e);
}

/* Every point of a face piece: inside its face, on its ray, in front. */
static void check_piece_points(const char *name, const projcurve_face *f,
                               const projcurve_result *r, size_t b, const projcurve_curve *c,
                               const double dir[3], double tol)
{
    size_t n = 0;
    CHECK_OK(projcurve_result_branch_points(NULL, r, b, MAX_POINTS, points, &n));
    for (size_t i = 0; i < n && i < MAX_POINTS; ++i) {
        const double *q = points + 3 * i;
        projcurve_where w = PROJCURVE_OUT;
        CHECK_OK(projcurve_face_classify(NULL, f, q[1], q[2], &w));
        double s[3], p[3];
        eval3(projcurve_face_surface(f), q + 1, s);
        CHECK_OK(projcurve_curve_eval(NULL, c, q[0], 0, p));
        const double d[3] = {s[0] - p[0], s[1] - p[1], s[2] - p[2]};
        const double x[3] = {d[1] * dir[2] - d[2] * dir[1], d[2] * dir[0] - d[0] * dir[2],
                             d[0] * dir[1] - d[1] * dir[0]};
        const double off = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
        const double along = d[0] * dir[0] + d[1] * dir[1] + d[2] * dir[2];
        if (w == PROJCURVE_OUT || off > tol || along < -tol) {
            pc_test_fail_at(__FILE__, __LINE__,
                            "%s: point %zu (t %.17g, uv %.17g %.17g): where %d, off the ray "
                            "%.3g, along %.3g (tol %.3g)",
                            name, i, q[0], q[1], q[2], (int)w, off, along, tol);
            return;
        }
    }
}

/* 1 when some face piece of face index `face` covers t and passes within
 * tol of the 3D point h. */
static int hit_covered(const projcurve_shape_result *sr, size_t face, double t, const double h[3],
                       const projcurve_face *f, double tol)
{
    for (size_t k = 0; k < projcurve_shape_result_curve_count(sr); ++k) {
        size_t np = 0;
        CHECK_OK(projcurve_shape_result_curve_info(NULL, sr, k, &np, NULL, NULL));
        for (size_t j = 0; j < np; ++j) {
            size_t fi = 0, b = 0;
            const projcurve_result *r = NULL;
            double tr[2];
            CHECK_OK(projcurve_shape_result_piece(NULL, sr, k, j, &fi, &r, &b, tr, NULL, NULL));
            if (fi != face || t < fmin(tr[0], tr[1]) - 1e-9 || t > fmax(tr[0], tr[1]) + 1e-9)
                continue;
            size_t n = 0;
            CHECK_OK(projcurve_result_branch_points(NULL, r, b, MAX_POINTS, points, &n));
            /* the piece's (u, v) at t, interpolated between its points */
            for (size_t i = 0; i + 1 < n && i + 1 < MAX_POINTS; ++i) {
                const double *a = points + 3 * i, *z = a + 3;
                if (t < fmin(a[0], z[0]) - 1e-9 || t > fmax(a[0], z[0]) + 1e-9)
                    continue;
                const double w = z[0] != a[0] ? (t - a[0]) / (z[0] - a[0]) : 0.0;
                const double uv[2] = {a[1] + w * (z[1] - a[1]), a[2] + w * (z[2] - a[2])};
                double s[3];
                eval3(projcurve_face_surface(f), uv, s);
                if (fabs(s[0] - h[0]) + fabs(s[1] - h[1]) + fabs(s[2] - h[2]) <= tol)
                    return 1;
            }
        }
    }
    return 0;
}

/* Rays from P(t) along Dir at dense t against every face. */
static void check_no_hit_missed(const char *name, const projcurve_shape *shape,
                                const projcurve_shape_result *sr, const projcurve_curve *c,
                                const double dir[3], double size)
{
    double t0, t1;
    CHECK_OK(projcurve_curve_domain(NULL, c, &t0, &t1));
    size_t missed = 0, hits_in = 0;
    for (int i = 0; i <= RAY_SAMPLES; ++i) {
        const double t = t0 + (t1 - t0) * (i + 0.37) / (RAY_SAMPLES + 1.0);
        double p[3];
        CHECK_OK(projcurve_curve_eval(NULL, c, t, 0, p));
        for (size_t fi = 0; fi < projcurve_shape_face_count(shape); ++fi) {
            const projcurve_face *f = projcurve_shape_face(shape, fi);
            double hits[3 * MAX_HITS];
            size_t n = 0;
            CHECK_OK(projcurve_surface_intersect_line(NULL, projcurve_face_surface(f), p, dir, 1,
                                                      MAX_HITS, hits, NULL, &n));
            for (size_t k = 0; k < n && k < MAX_HITS; ++k) {
                projcurve_where w;
                CHECK_OK(projcurve_face_classify(NULL, f, hits[3 * k], hits[3 * k + 1], &w));
                if (w != PROJCURVE_IN)
                    continue; /* on a loop: either side may own it */
                ++hits_in;
                double h[3];
                eval3(projcurve_face_surface(f), hits + 3 * k, h);
                /* the traced points are an arc step (1/64 of the length)
                 * apart: 2 % of the size finds the nearest */
                if (!hit_covered(sr, fi, t, h, f, 0.02 * size)) {
                    if (missed++ < 3)
                        pc_test_fail_at(__FILE__, __LINE__,
                                        "%s: ray at t %.17g hits face %zu at (%g, %g, %g), no "
                                        "piece there",
                                        name, t, fi, h[0], h[1], h[2]);
                }
            }
        }
    }
    CHECK(hits_in > 0);
    CHECK(missed == 0);
}

static const expect *expected_counts(const char *name)
{
    for (size_t i = 0; i < sizeof expected / sizeof expected[0]; ++i)
        if (strcmp(expected[i].name, name) == 0)
            return &expected[i];
    return NULL;
}

static void check_shell(const projcurve_shape_result *sr)
{
    CHECK(projcurve_shape_result_curve_count(sr) == 1);
    size_t np = 0;
    int closed = 1;
    CHECK_OK(projcurve_shape_result_curve_info(NULL, sr, 0, &np, NULL, &closed));
    CHECK(np == 4);
    CHECK(closed == 0);
    CHECK(projcurve_shape_result_open_end_count(sr) == 0);
    size_t faces_seen[4] = {9, 9, 9, 9};
    for (size_t j = 0; j < np && j < 4; ++j) {
        projcurve_branch_start s;
        projcurve_branch_end e;
        double tr[2];
        CHECK_OK(projcurve_shape_result_piece(NULL, sr, 0, j, &faces_seen[j], NULL, NULL, tr, &s,
                                              &e));
        CHECK(j == 0 || s == PROJCURVE_START_TRIM);
        CHECK(j == np - 1 || e == PROJCURVE_END_TRIM);
        for (size_t i = 0; i < j; ++i)
            CHECK(faces_seen[i] != faces_seen[j]);
    }
}

/* Projects c onto shape along dir and checks the result; returns its
 * connected-curve count. */
static size_t check_pair(const char *name, const projcurve_shape *shape, const projcurve_curve *c,
                         const double dir[3], size_t *open_ends, size_t *n_pieces)
{
    double box[6] = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
    for (size_t fi = 0; fi < projcurve_shape_face_count(shape); ++fi) {
        double fb[6];
        CHECK_OK(projcurve_face_bounds(NULL, projcurve_shape_face(shape, fi), NULL, fb));
        for (int k = 0; k < 3; ++k) {
            box[k] = fmin(box[k], fb[k]);
            box[k + 3] = fmax(box[k + 3], fb[k + 3]);
        }
    }
    const double size = sqrt((box[3] - box[0]) * (box[3] - box[0]) +
                             (box[4] - box[1]) * (box[4] - box[1]) +
                             (box[5] - box[2]) * (box[5] - box[2]));
    projcurve_shape_result *sr = NULL;
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    const projcurve_status st =
        projcurve_project_shape(ctx, shape, c, PROJCURVE_PROJECT_DIRECTIONAL, dir, NULL, &sr);
    if (st != PROJCURVE_OK)
        pc_test_fail_at(__FILE__, __LINE__, "%s: %s: %s", name, projcurve_status_string(st),
                        projcurve_context_message(ctx));
    projcurve_context_destroy(ctx);
    if (sr == NULL)
        return 0;
    for (size_t k = 0; k < projcurve_shape_result_face_count(sr); ++k) {
        projcurve_status fs;
        const char *msg = NULL;
        const projcurve_result *fr = NULL;
        CHECK_OK(projcurve_shape_result_face(NULL, sr, k, NULL, &fr, &fs, &msg));
        if (fs != PROJCURVE_OK || msg[0] != '\0' || projcurve_result_failure_count(fr) != 0)
            pc_test_fail_at(__FILE__, __LINE__, "%s: face %zu: %s %s, %zu failures", name, k,
                            projcurve_status_string(fs), msg, projcurve_result_failure_count(fr));
    }
    const size_t connected = projcurve_shape_result_curve_count(sr);
    /* traced points: the corrector's 1e-12 of the size; 1e-9 is far above
     * it and far below any wrong point */
    for (size_t k = 0; k < connected; ++k) {
        size_t np = 0;
        int closed = 0;
        CHECK_OK(projcurve_shape_result_curve_info(NULL, sr, k, &np, NULL, &closed));
        closed_count += (size_t)closed;
        *n_pieces += np;
        for (size_t j = 0; j < np; ++j) {
            size_t fi = 0, b = 0;
            const projcurve_result *r = NULL;
            CHECK_OK(projcurve_shape_result_piece(NULL, sr, k, j, &fi, &r, &b, NULL, NULL, NULL));
            check_piece_points(name, projcurve_shape_face(shape, fi), r, b, c, dir, 1e-9 * size);
        }
    }
    check_no_hit_missed(name, shape, sr, c, dir, size);
    if (strcmp(name, "shell_2x2_bspline_oblique") == 0)
        check_shell(sr);
    *open_ends += projcurve_shape_result_open_end_count(sr);
    projcurve_shape_result_destroy(sr);
    return connected;
}

static void run_row(const char *name, const char *model_file, const double dir_in[3])
{
    char path[512];
    snprintf(path, sizeof path, "cases-brep/%s", model_file);
    projcurve_model *model = NULL, *curves = NULL;
    CHECK_OK(projcurve_model_read_file(NULL, pc_test_data_path(path), &model));
    snprintf(path, sizeof path, "cases-brep/%s.curves.igs", name);
    CHECK_OK(projcurve_model_read_file(NULL, pc_test_data_path(path), &curves));
    if (model == NULL || curves == NULL) {
        projcurve_model_destroy(model);
        projcurve_model_destroy(curves);
        return;
    }
    const double m = sqrt(dir_in[0] * dir_in[0] + dir_in[1] * dir_in[1] + dir_in[2] * dir_in[2]);
    const double dir[3] = {dir_in[0] / m, dir_in[1] / m, dir_in[2] / m};
    size_t connected = 0;
    closed_count = 0;
    for (size_t si = 0; si < projcurve_model_shape_count(model); ++si) {
        const projcurve_shape *shape = projcurve_model_shape(model, si);
        for (size_t ci = 0; ci < projcurve_model_curve_count(curves); ++ci) {
            size_t open = 0, pieces = 0;
            connected += check_pair(name, shape, projcurve_model_curve(curves, ci), dir, &open,
                                    &pieces);
        }
    }
    const expect *want = expected_counts(name);
    if (want != NULL && (connected != want->connected || closed_count != want->closed))
        pc_test_fail_at(__FILE__, __LINE__,
                        "%s: %zu connected curves (%zu closed), expected %zu (%zu closed)", name,
                        connected, closed_count, want->connected, want->closed);
    printf("%s: %zu connected curve(s), %zu closed\n", name, connected, closed_count);
    projcurve_model_destroy(model);
    projcurve_model_destroy(curves);
}

/* linkrods.step (a solid of 37 faces) and a line above it along x at the
 * middle of its y range, projected along -z: every point on a face, inside
 * its loops and on its ray, no forward hit missed, consecutive pieces
 * chained across the solid's edges (no gap: a closed solid). */
static void run_real(void)
{
    projcurve_model *model = NULL;
    CHECK_OK(projcurve_model_read_file(NULL, pc_test_data_path("real/linkrods.step"), &model));
    if (model == NULL || projcurve_model_shape_count(model) == 0) {
        projcurve_model_destroy(model);
        return;
    }
    static const double ctrl[] = {-4.0, 2.7, 20.0, 10.5, 2.7, 20.0}, knots[] = {0, 0, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 1, 2, ctrl, NULL, knots, &c));
    const double down[3] = {0, 0, -1};
    size_t open = 0, pieces = 0;
    const size_t connected =
        check_pair("linkrods", projcurve_model_shape(model, 0), c, down, &open, &pieces);
    printf("linkrods: %zu connected curve(s), %zu face pieces, %zu open ends\n", connected,
           pieces, open);
    CHECK(connected >= 1);
    CHECK(pieces > connected); /* some chaining happened */
    CHECK(open == 0);
    projcurve_curve_destroy(c);
    projcurve_model_destroy(model);
}

int main(void)
{
    FILE *f = fopen(pc_test_data_path("cases-brep/MANIFEST.tsv"), "r");
    if (f == NULL)
        pc_test_missing_data("cases-brep/MANIFEST.tsv");
    char line[2048];
    size_t rows = 0;
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#')
            continue;
        char name[256], mode[64], file[256];
        double a[3];
        if (sscanf(line, "%255s %63s %255s %lf %lf %lf", name, mode, file, &a[0], &a[1],
                   &a[2]) != 6 ||
            strcmp(mode, "directional") != 0)
            continue;
        run_row(name, file, a);
        ++rows;
    }
    fclose(f);
    CHECK(rows == 5);
    run_real();
    return pc_test_finish("test_shapeproj_cases");
}
