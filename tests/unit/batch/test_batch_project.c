/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Many curves at once (batch/): the results of
 * projcurve_project_curves_directional / _orthogonal are those of the
 * single-curve calls, bit for bit, with one thread and with several; a
 * NULL curve and a curve that is a point fail alone (statuses[i]), the
 * call returning the lowest-index failure with its message; the progress
 * callback is called one at a time from the workers.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "shapes.h"
#include "trace/result.h"

#define N_CURVES 10
#define NULL_CURVE 3
#define POINT_CURVE 6

static int same_doubles(const double *a, const double *b, size_t n)
{
    return n == 0 || (a != NULL && b != NULL && memcmp(a, b, n * sizeof *a) == 0);
}

static int same_spline(const pc_bspline *a, const pc_bspline *b)
{
    if (a->degree != b->degree || a->dim != b->dim || a->n_poles != b->n_poles ||
        (a->weights == NULL) != (b->weights == NULL))
        return 0;
    const size_t n = a->n_poles;
    return same_doubles(a->knots, b->knots, n ? n + (size_t)a->degree + 1 : 0) &&
           same_doubles(a->poles, b->poles, n * (size_t)a->dim) &&
           (a->weights == NULL || same_doubles(a->weights, b->weights, n));
}

/* Bit-for-bit equality of two results (everything a caller can read). */
static int same_result(const projcurve_result *a, const projcurve_result *b)
{
    if (a == NULL || b == NULL)
        return a == b;
    if (a->n_branches != b->n_branches || a->point_dim != b->point_dim)
        return 0;
    for (size_t i = 0; i < a->n_branches; ++i) {
        const pc_branch *x = &a->branches[i], *y = &b->branches[i];
        if (x->n_points != y->n_points || x->n_pieces != y->n_pieces || x->start != y->start ||
            x->end != y->end || x->compact != y->compact || x->n_seams != y->n_seams ||
            !same_doubles(x->points, y->points, x->n_points * (size_t)a->point_dim) ||
            !same_spline(&x->compact_pcurve, &y->compact_pcurve) ||
            !same_spline(&x->compact_curve, &y->compact_curve) ||
            (x->n_seams && memcmp(x->seams, y->seams, x->n_seams * sizeof *x->seams) != 0))
            return 0;
        for (size_t k = 0; k < x->n_pieces; ++k) {
            const pc_piece *p = &x->pieces[k], *q = &y->pieces[k];
            const size_t n = (size_t)p->degree + 1;
            if (p->degree != q->degree || p->t0 != q->t0 || p->t1 != q->t1 ||
                p->uv_degree != q->uv_degree || !same_doubles(p->ctrl, q->ctrl, 3 * n) ||
                !same_doubles(p->weights, q->weights, n) ||
                !same_doubles(p->uv_ctrl, q->uv_ctrl, 2 * (size_t)(p->uv_degree + 1)))
                return 0;
        }
    }
    return 1;
}

static int progress_calls;
static int count_progress(void *user, double fraction)
{
    (void)user;
    (void)fraction;
    ++progress_calls; /* not atomic: the call serialises the callback */
    return 0;
}

static void run(const projcurve_surface *s, projcurve_curve *const *curves, int orthogonal)
{
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    const double dir[3] = {0.1, -0.2, -1.0};
    projcurve_result *single[N_CURVES], *one[N_CURVES], *many[N_CURVES];
    projcurve_status st1[N_CURVES], stn[N_CURVES];
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(ctx, &o));
    for (size_t i = 0; i < N_CURVES; ++i) {
        single[i] = NULL;
        if (curves[i] != NULL && i != POINT_CURVE)
            CHECK_OK(orthogonal ? projcurve_project_orthogonal(ctx, s, curves[i], o, &single[i])
                                : projcurve_project_directional(ctx, s, curves[i], dir, o,
                                                                &single[i]));
    }
    const projcurve_curve *const *cc = (const projcurve_curve *const *)curves;
    projcurve_status st =
        orthogonal ? projcurve_project_curves_orthogonal(ctx, s, cc, N_CURVES, o, one, st1)
                   : projcurve_project_curves_directional(ctx, s, cc, N_CURVES, dir, o, one, st1);
    CHECK(st == PROJCURVE_ERR_NULL_ARGUMENT); /* the lowest failing index */
    CHECK(strncmp(projcurve_context_message(ctx), "curve 3: ", 9) == 0);
    CHECK_OK(projcurve_options_set_int(ctx, o, PROJCURVE_OPT_THREADS, 4));
    CHECK_OK(projcurve_options_set_progress(ctx, o, count_progress, NULL));
    progress_calls = 0;
    st = orthogonal ? projcurve_project_curves_orthogonal(ctx, s, cc, N_CURVES, o, many, stn)
                    : projcurve_project_curves_directional(ctx, s, cc, N_CURVES, dir, o, many,
                                                           stn);
    CHECK(st == PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK(progress_calls > 0);
    size_t branches = 0;
    for (size_t i = 0; i < N_CURVES; ++i) {
        const projcurve_status expected = i == NULL_CURVE    ? PROJCURVE_ERR_NULL_ARGUMENT
                                          : i == POINT_CURVE ? PROJCURVE_ERR_SINGULAR
                                                             : PROJCURVE_OK;
        CHECK(st1[i] == expected && stn[i] == expected);
        CHECK(same_result(single[i], one[i]));
        CHECK(same_result(single[i], many[i]));
        branches += projcurve_result_branch_count(many[i]);
        projcurve_result_destroy(single[i]);
        projcurve_result_destroy(one[i]);
        projcurve_result_destroy(many[i]);
    }
    CHECK(branches >= N_CURVES - 2); /* the comparison compared something */
    /* nothing to do; the call's own arguments */
    CHECK_OK(projcurve_project_curves_orthogonal(ctx, s, NULL, 0, o, NULL, NULL));
    CHECK_STATUS(projcurve_project_curves_directional(ctx, s, cc, N_CURVES, NULL, o, many, NULL),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_project_curves_orthogonal(ctx, NULL, cc, N_CURVES, o, many, NULL),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    const double zero[3] = {0, 0, 0};
    CHECK_STATUS(projcurve_project_curves_directional(ctx, s, cc, N_CURVES, zero, o, many, NULL),
                 PROJCURVE_ERR_ZERO_DIRECTION);
    projcurve_options_destroy(o);
    projcurve_context_destroy(ctx);
}

int main(void)
{
    pc_shape_surface ss = pc_shape_bumpy(7, 4, 4, 0.2, 0);
    projcurve_surface *s = pc_shape_surface_create(&ss);
    pc_shape_surface_free(&ss);
    projcurve_curve *curves[N_CURVES];
    for (size_t i = 0; i < N_CURVES; ++i) {
        pc_shape_curve c = pc_shape_random_curve(100 + i, 3, 6);
        for (size_t k = 0; k < c.n_ctrl; ++k) {
            double *p = c.ctrl + 3 * k;
            p[0] = 0.5 + 0.45 * p[0];
            p[1] = 0.5 + 0.45 * p[1];
            p[2] = 1.0 + 0.2 * p[2];
            if (i == POINT_CURVE)
                p[0] = 0.5, p[1] = 0.5, p[2] = 1.0;
        }
        curves[i] = i == NULL_CURVE ? NULL : pc_shape_curve_create(&c);
        pc_shape_curve_free(&c);
    }
    run(s, curves, 0);
    run(s, curves, 1);
    for (size_t i = 0; i < N_CURVES; ++i)
        projcurve_curve_destroy(curves[i]);
    projcurve_surface_destroy(s);
    return pc_test_finish("test_batch_project");
}
