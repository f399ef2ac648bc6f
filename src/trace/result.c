/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Allocation helpers of the projection result (result.h). Its arrays grow
 * as every growable array does (common/array.h), so that appending a traced
 * vertex costs O(1) amortised.
 */
#include "trace/result.h"

#include <stdlib.h>
#include <string.h>

#include "common/array.h"
#include "common/error.h"

#define PC_RESULT_INITIAL_CAPACITY 16

projcurve_status pc_result_create(projcurve_context *ctx, int point_dim, projcurve_result **out)
{
    projcurve_result *r = calloc(1, sizeof *r);
    if (r == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory creating a result");
    r->point_dim = point_dim;
    *out = r;
    return PROJCURVE_OK;
}

projcurve_status pc_result_add_branch(projcurve_context *ctx, projcurve_result *r,
                                      pc_branch **branch)
{
    void *items = r->branches;
    const projcurve_status st =
        pc_array_reserve(ctx, &items, &r->cap_branches, r->n_branches, r->n_branches + 1,
                         sizeof *r->branches, PC_RESULT_INITIAL_CAPACITY, NULL, "the branches");
    r->branches = items;
    if (st != PROJCURVE_OK)
        return st;
    pc_branch *b = &r->branches[r->n_branches++];
    memset(b, 0, sizeof *b);
    *branch = b;
    return PROJCURVE_OK;
}

static projcurve_status reserve_points(projcurve_context *ctx, pc_branch *b, int point_dim,
                                       size_t n)
{
    void *items = b->points;
    const projcurve_status st =
        pc_array_reserve(ctx, &items, &b->cap_points, b->n_points, n,
                         (size_t)point_dim * sizeof *b->points, PC_RESULT_INITIAL_CAPACITY, NULL,
                         "a branch's points");
    b->points = items;
    return st;
}

projcurve_status pc_branch_add_point(projcurve_context *ctx, pc_branch *b, int point_dim,
                                     const double *point)
{
    projcurve_status st = reserve_points(ctx, b, point_dim, b->n_points + 1);
    if (st != PROJCURVE_OK)
        return st;
    const size_t dim = (size_t)point_dim;
    memcpy(b->points + b->n_points * dim, point, dim * sizeof(double));
    b->n_points++;
    return PROJCURVE_OK;
}

projcurve_status pc_branch_insert_point(projcurve_context *ctx, pc_branch *b, int point_dim,
                                        size_t at, const double *point)
{
    if (at > b->n_points)
        return pc_fail(ctx, PROJCURVE_ERR_INDEX, "insert position %zu past %zu points", at,
                       b->n_points);
    projcurve_status st = reserve_points(ctx, b, point_dim, b->n_points + 1);
    if (st != PROJCURVE_OK)
        return st;
    const size_t dim = (size_t)point_dim;
    memmove(b->points + (at + 1) * dim, b->points + at * dim,
            (b->n_points - at) * dim * sizeof(double));
    memcpy(b->points + at * dim, point, dim * sizeof(double));
    b->n_points++;
    return PROJCURVE_OK;
}

projcurve_status pc_branch_add_piece(projcurve_context *ctx, pc_branch *b, int degree,
                                     double t0, double t1, const double uv[4],
                                     const double *ctrl, const double *weights)
{
    if (degree < 0 || degree > 2 * PROJCURVE_MAX_DEGREE)
        return pc_fail(ctx, PROJCURVE_ERR_BAD_DEGREE, "piece degree %d out of range", degree);
    const size_t n = (size_t)degree + 1;
    double *c = malloc(3 * n * sizeof *c);
    double *w = malloc(n * sizeof *w);
    if (c == NULL || w == NULL) {
        free(c);
        free(w);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory adding a piece");
    }
    void *items = b->pieces;
    const projcurve_status st =
        pc_array_reserve(ctx, &items, &b->cap_pieces, b->n_pieces, b->n_pieces + 1,
                         sizeof *b->pieces, PC_RESULT_INITIAL_CAPACITY, NULL, "a branch's pieces");
    b->pieces = items;
    if (st != PROJCURVE_OK) {
        free(c);
        free(w);
        return st;
    }
    memcpy(c, ctrl, 3 * n * sizeof *c);
    for (size_t i = 0; i < n; ++i)
        w[i] = weights ? weights[i] : 1.0;
    pc_piece *pc = &b->pieces[b->n_pieces++];
    pc->degree = degree;
    pc->t0 = t0;
    pc->t1 = t1;
    memcpy(pc->uv, uv, sizeof pc->uv);
    pc->ctrl = c;
    pc->weights = w;
    pc->uv_degree = 1;
    memcpy(pc->uv_ctrl, uv, sizeof pc->uv);
    return PROJCURVE_OK;
}

void pc_branch_set_last_pcurve(pc_branch *b, int degree, const double *uv_ctrl)
{
    if (b->n_pieces == 0 || degree < 1 || degree + 1 > PROJCURVE_MAX_PCURVE_POINTS)
        return;
    pc_piece *pc = &b->pieces[b->n_pieces - 1];
    pc->uv_degree = degree;
    memcpy(pc->uv_ctrl, uv_ctrl, 2 * (size_t)(degree + 1) * sizeof *uv_ctrl);
}

void pc_branch_clear_pieces(pc_branch *b)
{
    for (size_t i = 0; i < b->n_pieces; ++i) {
        free(b->pieces[i].ctrl);
        free(b->pieces[i].weights);
    }
    b->n_pieces = 0;
}

void pc_bspline_free(pc_bspline *s)
{
    free(s->knots);
    free(s->poles);
    free(s->weights);
    memset(s, 0, sizeof *s);
}

static void branch_free(pc_branch *b)
{
    pc_bspline_free(&b->compact_pcurve);
    pc_bspline_free(&b->compact_curve);
    pc_branch_clear_pieces(b);
    free(b->pieces);
    free(b->points);
    free(b->seams);
}

void pc_result_remove_branch(projcurve_result *r, size_t i)
{
    if (r == NULL || i >= r->n_branches)
        return;
    branch_free(&r->branches[i]);
    memmove(r->branches + i, r->branches + i + 1,
            (r->n_branches - i - 1) * sizeof *r->branches);
    r->n_branches--;
}

void projcurve_result_destroy(projcurve_result *result)
{
    if (result == NULL)
        return;
    for (size_t i = 0; i < result->n_branches; ++i)
        branch_free(&result->branches[i]);
    free(result->branches);
    free(result);
}

projcurve_status pc_result_hand_out(projcurve_status st, pc_budget *budget, projcurve_result *r,
                                    projcurve_result **out)
{
    if (st == PROJCURVE_OK)
        pc_budget_finish(budget);
    if (!pc_status_keeps_result(st)) {
        projcurve_result_destroy(r);
        return st;
    }
    *out = r;
    return st;
}
