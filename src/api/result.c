/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The result accessors of projcurve.h: branches, their traced polylines,
 * composed pieces, statistics, and a branch joined into one NURBS curve.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "common/error.h"
#include "trace/result.h"

static projcurve_status get_branch(projcurve_context *ctx, const projcurve_result *r,
                                   size_t branch, const pc_branch **out)
{
    PC_REQUIRE(ctx, r, "result");
    if (branch >= r->n_branches)
        return pc_fail(ctx, PROJCURVE_ERR_INDEX, "branch %zu of %zu", branch, r->n_branches);
    *out = &r->branches[branch];
    return PROJCURVE_OK;
}

size_t projcurve_result_branch_count(const projcurve_result *result)
{
    return result ? result->n_branches : 0;
}

size_t projcurve_result_failure_count(const projcurve_result *result)
{
    if (result == NULL)
        return 0;
    size_t n = result->failures_dropped;
    for (size_t i = 0; i < result->n_branches; ++i)
        n += result->branches[i].start == PROJCURVE_START_FAILED ||
             result->branches[i].end == PROJCURVE_END_FAILED;
    return n;
}

int projcurve_result_point_dim(const projcurve_result *result)
{
    return result ? result->point_dim : 0;
}

projcurve_status projcurve_result_stat(projcurve_context *ctx, const projcurve_result *result,
                                       projcurve_stat key, double *value)
{
    PC_REQUIRE(ctx, result, "result");
    PC_REQUIRE(ctx, value, "value");
    const pc_stats *s = &result->stats;
    switch (key) {
    case PROJCURVE_STAT_POINTS:
        *value = s->points;
        break;
    case PROJCURVE_STAT_STEPS:
        *value = s->steps;
        break;
    case PROJCURVE_STAT_NEWTON_ITERATIONS:
        *value = s->newton_iterations;
        break;
    case PROJCURVE_STAT_AVG_ERROR:
        *value = s->error_count > 0.0 ? s->error_sum / s->error_count : 0.0;
        break;
    case PROJCURVE_STAT_JUMPS:
        *value = s->jumps;
        break;
    case PROJCURVE_STAT_PIECES:
        *value = s->pieces;
        break;
    case PROJCURVE_STAT_TOL_DISTANCE:
        *value = s->tol_distance;
        break;
    case PROJCURVE_STAT_MAX_ERROR:
        *value = s->error_max;
        break;
    default:
        return pc_fail(ctx, PROJCURVE_ERR_UNKNOWN_OPTION, "unknown statistic %d", (int)key);
    }
    return PROJCURVE_OK;
}

projcurve_status projcurve_result_branch_info(projcurve_context *ctx,
                                              const projcurve_result *result, size_t branch,
                                              double t_range[2], projcurve_branch_start *start,
                                              projcurve_branch_end *end, size_t *n_points,
                                              size_t *n_pieces)
{
    const pc_branch *b = NULL;
    projcurve_status st = get_branch(ctx, result, branch, &b);
    if (st != PROJCURVE_OK)
        return st;
    const size_t dim = (size_t)result->point_dim;
    if (t_range) {
        t_range[0] = b->n_points ? b->points[0] : 0.0;
        t_range[1] = b->n_points ? b->points[dim * (b->n_points - 1)] : 0.0;
    }
    if (start)
        *start = b->start;
    if (end)
        *end = b->end;
    if (n_points)
        *n_points = b->n_points;
    if (n_pieces)
        *n_pieces = b->n_pieces;
    return PROJCURVE_OK;
}

projcurve_status projcurve_result_branch_points(projcurve_context *ctx,
                                                const projcurve_result *result, size_t branch,
                                                size_t capacity, double *points, size_t *count)
{
    const pc_branch *b = NULL;
    projcurve_status st = get_branch(ctx, result, branch, &b);
    if (st != PROJCURVE_OK)
        return st;
    PC_REQUIRE(ctx, count, "count");
    if (capacity > 0)
        PC_REQUIRE(ctx, points, "points");
    const size_t n = b->n_points < capacity ? b->n_points : capacity;
    if (n > 0)
        memcpy(points, b->points, n * (size_t)result->point_dim * sizeof *points);
    *count = b->n_points;
    return PROJCURVE_OK;
}

projcurve_status projcurve_result_piece(projcurve_context *ctx, const projcurve_result *result,
                                        size_t branch, size_t piece, int *degree, double *ctrl,
                                        double *weights, double range[2], double uv_range[4])
{
    const pc_branch *b = NULL;
    projcurve_status st = get_branch(ctx, result, branch, &b);
    if (st != PROJCURVE_OK)
        return st;
    if (piece >= b->n_pieces)
        return pc_fail(ctx, PROJCURVE_ERR_INDEX, "piece %zu of %zu", piece, b->n_pieces);
    const pc_piece *p = &b->pieces[piece];
    const size_t n = (size_t)p->degree + 1;
    if (degree)
        *degree = p->degree;
    if (ctrl)
        memcpy(ctrl, p->ctrl, 3 * n * sizeof *ctrl);
    if (weights)
        memcpy(weights, p->weights, n * sizeof *weights);
    if (range) {
        range[0] = p->t0;
        range[1] = p->t1;
    }
    if (uv_range)
        memcpy(uv_range, p->uv, sizeof p->uv);
    return PROJCURVE_OK;
}

projcurve_status projcurve_result_piece_pcurve(projcurve_context *ctx,
                                               const projcurve_result *result, size_t branch,
                                               size_t piece, int *degree, double *uv_ctrl)
{
    const pc_branch *b = NULL;
    projcurve_status st = get_branch(ctx, result, branch, &b);
    if (st != PROJCURVE_OK)
        return st;
    if (piece >= b->n_pieces)
        return pc_fail(ctx, PROJCURVE_ERR_INDEX, "piece %zu of %zu", piece, b->n_pieces);
    if (result->point_dim != 3)
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                       "a result on an implicit surface has no (u, v) pcurve");
    const pc_piece *p = &b->pieces[piece];
    if (degree)
        *degree = p->uv_degree;
    if (uv_ctrl)
        memcpy(uv_ctrl, p->uv_ctrl, 2 * (size_t)(p->uv_degree + 1) * sizeof *uv_ctrl);
    return PROJCURVE_OK;
}

/* Homogeneous control points (w x, w y, w z, w) of a piece raised to
 * degree `to` by repeated degree elevation:
 * Q_i = i/(n+1) P_(i-1) + (1 - i/(n+1)) P_i. hw holds 4 * (to + 1). */
static void elevated_piece(const pc_piece *p, int to, double *hw)
{
    for (int i = 0; i <= p->degree; ++i) {
        const double w = p->weights[i];
        for (int k = 0; k < 3; ++k)
            hw[4 * i + k] = w * p->ctrl[3 * i + k];
        hw[4 * i + 3] = w;
    }
    for (int n = p->degree; n < to; ++n) {
        for (int i = n + 1; i >= 0; --i) {
            const double a = (double)i / (double)(n + 1);
            for (int k = 0; k < 4; ++k) {
                const double prev = i > 0 ? hw[4 * (i - 1) + k] : 0.0;
                const double here = i <= n ? hw[4 * i + k] : 0.0;
                hw[4 * i + k] = a * prev + (1.0 - a) * here;
            }
        }
    }
}

/* Joins the pieces: pieces meet at their end points, so the B-spline has
 * n_pieces * degree + 1 control points and interior knots of multiplicity
 * degree at the joins. Each piece's weights are scaled (which leaves a
 * rational Bezier curve unchanged) so that its first weight equals the
 * previous piece's last one. */
projcurve_status projcurve_result_branch_curve(projcurve_context *ctx,
                                               const projcurve_result *result, size_t branch,
                                               projcurve_curve **out)
{
    const pc_branch *b = NULL;
    projcurve_status st = get_branch(ctx, result, branch, &b);
    if (st != PROJCURVE_OK)
        return st;
    PC_REQUIRE(ctx, out, "out");
    if (b->n_pieces == 0)
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                       b->end == PROJCURVE_END_LIMIT
                           ? "branch %zu has no composed pieces: the piece limit "
                             "(PROJCURVE_OPT_MAX_PIECES) was reached before it"
                           : "branch %zu has no composed pieces: the projection was made "
                             "with PROJCURVE_OPT_COMPOSE 0",
                       branch);
    int deg = 1;
    for (size_t i = 0; i < b->n_pieces; ++i)
        if (b->pieces[i].degree > deg)
            deg = b->pieces[i].degree;
    if (deg > PROJCURVE_MAX_DEGREE)
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                       "branch %zu: its pieces have degree %d, above the %d of a NURBS curve "
                       "(cubic pcurves on a surface of degrees p, q give 3 (p + q)); read "
                       "them one by one with projcurve_result_piece",
                       branch, deg, PROJCURVE_MAX_DEGREE);
    const size_t d = (size_t)deg, np = b->n_pieces;
    if (np > (SIZE_MAX / (3 * sizeof(double)) - 2 * d - 2) / d)
        return pc_fail(ctx, PROJCURVE_ERR_OVERFLOW, "branch %zu: %zu pieces of degree %zu overflow",
                       branch, np, d);
    const size_t n_ctrl = np * d + 1, n_knots = n_ctrl + d + 1;
    double *ctrl = malloc(3 * n_ctrl * sizeof *ctrl);
    double *weights = malloc(n_ctrl * sizeof *weights);
    double *knots = malloc(n_knots * sizeof *knots);
    double *hw = malloc(4 * (d + 1) * sizeof *hw);
    if (!ctrl || !weights || !knots || !hw) {
        st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory joining branch %zu", branch);
        goto cleanup;
    }
    double w_join = 1.0;
    for (size_t i = 0; i < np; ++i) {
        elevated_piece(&b->pieces[i], deg, hw);
        const double scale = hw[3] != 0.0 ? w_join / hw[3] : 1.0;
        for (size_t j = (i == 0 ? 0 : 1); j <= d; ++j) {
            const size_t at = i * d + j;
            const double w = hw[4 * j + 3] * scale;
            weights[at] = w;
            for (int k = 0; k < 3; ++k)
                ctrl[3 * at + (size_t)k] = hw[4 * j + (size_t)k] * scale / w;
        }
        w_join = weights[i * d + d];
    }
    for (size_t j = 0; j <= d; ++j) {
        knots[j] = b->pieces[0].t0;
        knots[n_knots - 1 - j] = b->pieces[np - 1].t1;
    }
    for (size_t i = 1; i < np; ++i)
        for (size_t j = 0; j < d; ++j)
            knots[d + 1 + (i - 1) * d + j] = b->pieces[i].t0;
    st = projcurve_curve_create_nurbs(ctx, deg, n_ctrl, ctrl, weights, knots, out);
cleanup:
    free(ctrl);
    free(weights);
    free(knots);
    free(hw);
    return st;
}
