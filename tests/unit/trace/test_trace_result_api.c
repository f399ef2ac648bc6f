/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The result accessors on a result built by hand: branch info, points with
 * any capacity, pieces, statistics, the errors each gives, and a branch
 * joined into one NURBS curve (pieces of mixed degree, rational) against
 * the pieces evaluated directly (de Casteljau in homogeneous coordinates).
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "trace/result.h"

/* A rational Bezier curve of degree n at s in [0, 1]. */
static void bezier_point(int n, const double *ctrl, const double *w, double s, double out[3])
{
    double h[4 * 8];
    for (int i = 0; i <= n; ++i) {
        for (int k = 0; k < 3; ++k)
            h[4 * i + k] = w[i] * ctrl[3 * i + k];
        h[4 * i + 3] = w[i];
    }
    for (int r = 1; r <= n; ++r)
        for (int i = 0; i <= n - r; ++i)
            for (int k = 0; k < 4; ++k)
                h[4 * i + k] = (1 - s) * h[4 * i + k] + s * h[4 * (i + 1) + k];
    for (int k = 0; k < 3; ++k)
        out[k] = h[k] / h[3];
}

int main(void)
{
    projcurve_result *r = NULL;
    CHECK_OK(pc_result_create(NULL, 3, &r));
    pc_branch *b = NULL;
    CHECK_OK(pc_result_add_branch(NULL, r, &b));
    b->start = PROJCURVE_START_JUMP;
    b->end = PROJCURVE_END_BOUNDARY;
    for (int k = 0; k < 5; ++k) {
        const double p[3] = {0.25 * k, 0.1 * k, 0.2 * k};
        CHECK_OK(pc_branch_add_point(NULL, b, 3, p));
    }
    const double mid[3] = {0.125, 0.05, 0.1};
    CHECK_OK(pc_branch_insert_point(NULL, b, 3, 1, mid));
    /* piece 1: quadratic, rational; piece 2: cubic, polynomial; they meet at (1, 1, 0) */
    const double c1[9] = {0, 0, 0, 1, 0, 0, 1, 1, 0};
    const double w1[3] = {1, 0.7071067811865476, 1};
    const double c2[12] = {1, 1, 0, 1, 2, 1, 2, 3, 1, 3, 3, 0};
    const double uv1[4] = {0, 0, 0.1, 0.2}, uv2[4] = {0.1, 0.2, 0.4, 0.8};
    CHECK_OK(pc_branch_add_piece(NULL, b, 2, 0.0, 0.5, uv1, c1, w1));
    CHECK_OK(pc_branch_add_piece(NULL, b, 3, 0.5, 1.0, uv2, c2, NULL));
    pc_branch *b2 = NULL;
    CHECK_OK(pc_result_add_branch(NULL, r, &b2)); /* an empty branch */
    r->stats.error_sum = 3e-10;
    r->stats.error_count = 3;
    r->stats.points = 6;

    CHECK(projcurve_result_branch_count(r) == 2);
    CHECK(projcurve_result_branch_count(NULL) == 0);
    CHECK(projcurve_result_point_dim(r) == 3 && projcurve_result_point_dim(NULL) == 0);
    double range[2];
    projcurve_branch_start start;
    projcurve_branch_end end;
    size_t np = 0, npieces = 0;
    CHECK_OK(projcurve_result_branch_info(NULL, r, 0, range, &start, &end, &np, &npieces));
    CHECK(range[0] == 0.0 && range[1] == 1.0 && np == 6 && npieces == 2);
    CHECK(start == PROJCURVE_START_JUMP && end == PROJCURVE_END_BOUNDARY);
    CHECK_OK(projcurve_result_branch_info(NULL, r, 0, NULL, NULL, NULL, NULL, NULL));
    CHECK_STATUS(projcurve_result_branch_info(NULL, r, 2, range, NULL, NULL, NULL, NULL),
                 PROJCURVE_ERR_INDEX);
    CHECK_STATUS(projcurve_result_branch_info(NULL, NULL, 0, range, NULL, NULL, NULL, NULL),
                 PROJCURVE_ERR_NULL_ARGUMENT);

    double pts[18] = {0};
    size_t count = 0;
    CHECK_OK(projcurve_result_branch_points(NULL, r, 0, 2, pts, &count));
    CHECK(count == 6 && pts[3] == 0.125 && pts[6] == 0.0); /* only 2 written */
    CHECK_OK(projcurve_result_branch_points(NULL, r, 0, 0, NULL, &count));
    CHECK(count == 6);
    CHECK_OK(projcurve_result_branch_points(NULL, r, 0, 6, pts, &count));
    CHECK(pts[15] == 1.0 && pts[17] == 0.2 * 4);
    CHECK_STATUS(projcurve_result_branch_points(NULL, r, 0, 6, NULL, &count),
                 PROJCURVE_ERR_NULL_ARGUMENT);

    int degree = 0;
    double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], w[PROJCURVE_MAX_PIECE_POINTS], uv[4];
    CHECK_OK(projcurve_result_piece(NULL, r, 0, 1, &degree, ctrl, w, range, uv));
    CHECK(degree == 3 && w[2] == 1.0 && ctrl[4] == 2.0 && range[0] == 0.5 && uv[3] == 0.8);
    CHECK_STATUS(projcurve_result_piece(NULL, r, 0, 2, &degree, ctrl, w, range, uv),
                 PROJCURVE_ERR_INDEX);

    double value = 0;
    CHECK_OK(projcurve_result_stat(NULL, r, PROJCURVE_STAT_AVG_ERROR, &value));
    CHECK_NEAR(value, 1e-10, 1e-25);
    CHECK_OK(projcurve_result_stat(NULL, r, PROJCURVE_STAT_POINTS, &value));
    CHECK(value == 6.0);
    CHECK_STATUS(projcurve_result_stat(NULL, r, (projcurve_stat)99, &value),
                 PROJCURVE_ERR_UNKNOWN_OPTION);

    /* joined: one cubic NURBS over [0, 1] equal to each piece */
    projcurve_curve *joined = NULL;
    CHECK_OK(projcurve_result_branch_curve(NULL, r, 0, &joined));
    int jdeg = 0;
    size_t jn = 0;
    CHECK_OK(projcurve_curve_nurbs_info(NULL, joined, &jdeg, &jn, NULL, NULL));
    CHECK(jdeg == 3 && jn == 7);
    double worst = 0.0;
    for (int k = 0; k <= 20; ++k) {
        const double t = k / 20.0;
        double got[3], want[3];
        CHECK_OK(projcurve_curve_eval(NULL, joined, t, 0, got));
        if (t <= 0.5)
            bezier_point(2, c1, w1, t / 0.5, want);
        else
            bezier_point(3, c2, (const double[4]){1, 1, 1, 1}, (t - 0.5) / 0.5, want);
        for (int i = 0; i < 3; ++i)
            worst = fmax(worst, fabs(got[i] - want[i]));
    }
    CHECK_NEAR(worst, 0.0, 1e-14);
    projcurve_curve_destroy(joined);
    joined = NULL;
    CHECK_STATUS(projcurve_result_branch_curve(NULL, r, 1, &joined),
                 PROJCURVE_ERR_INVALID_ARGUMENT);
    CHECK(joined == NULL);

    pc_result_remove_branch(r, 0);
    CHECK(projcurve_result_branch_count(r) == 1);
    projcurve_result_destroy(r);
    projcurve_result_destroy(NULL);
    return pc_test_finish("test_trace_result_api");
}
