/* SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>

#include "common/error.h"
#include "ortho/implicit.h"

/* Interior samples at which a cubic piece is compared with the exact
 * foot-point curve. The Hermite error is h^4 x''''/24 s^2 (1-s)^2 to
 * leading order, largest at s = 1/2; 1/4 and 3/4 catch a skewed error. */
static const double fit_samples[] = {0.25, 0.5, 0.75};
#define FIT_SAMPLE_COUNT (sizeof fit_samples / sizeof fit_samples[0])
/* A piece is accepted when its sampled error is within this fraction of
 * eps_D: the margin covers the error between the samples. */
#define FIT_SAFETY 0.5
/* Pieces shorter than this (relative to the domain) are accepted as they
 * are: the curve cannot be split further (next to a centre of curvature,
 * where x' is unbounded). */
#define FIT_MIN_DT_REL 1e-12

/* Cubic Hermite interpolant of a, b in Bezier form (C1 across pieces since
 * neighbours share the end point and its x'). */
static void hermite_bezier(const pc_implicit_point *a, const pc_implicit_point *b,
                           pc_vec3 ctrl[4])
{
    const double dt = b->t - a->t;
    ctrl[0] = a->x;
    ctrl[1] = vec3_axpy(a->x, dt / 3.0, a->xd);
    ctrl[2] = vec3_axpy(b->x, -dt / 3.0, b->xd);
    ctrl[3] = b->x;
}

static pc_vec3 bezier3(const pc_vec3 c[4], double s)
{
    const double r = 1.0 - s;
    pc_vec3 p = vec3_scale(c[0], r * r * r);
    p = vec3_axpy(p, 3.0 * r * r * s, c[1]);
    p = vec3_axpy(p, 3.0 * r * s * s, c[2]);
    return vec3_axpy(p, s * s * s, c[3]);
}

/* Largest distance between the piece and the exact curve at the samples
 * (+inf where the corrector fails: the piece must be split). */
static projcurve_status piece_error(projcurve_context *ctx, const pc_implicit *imp,
                                    const pc_implicit_point *a, const pc_implicit_point *b,
                                    const pc_vec3 ctrl[4], double *err)
{
    *err = 0.0;
    for (size_t i = 0; i < FIT_SAMPLE_COUNT; ++i) {
        const double s = fit_samples[i];
        const pc_vec3 guess = bezier3(ctrl, s);
        pc_vec3 x = guess;
        int converged = 0;
        const projcurve_status status =
            pc_implicit_correct(ctx, imp, a->t + s * (b->t - a->t), &x, &converged, NULL);
        if (status != PROJCURVE_OK)
            return status;
        const double d = converged ? vec3_dist(x, guess) : INFINITY;
        if (d > *err)
            *err = d;
    }
    return PROJCURVE_OK;
}

static projcurve_status point_of(projcurve_context *ctx, const pc_implicit *imp,
                                 const pc_branch *b, size_t i, pc_implicit_point *pt)
{
    const double *v = b->points + 4 * i;
    int solved = 0;
    return pc_implicit_point_at(ctx, imp, v[0], vec3(v[1], v[2], v[3]), pt, &solved);
}

/* The exact foot point halfway in t between a and b, from the Hermite
 * midpoint as guess (the straight midpoint if that fails). */
static projcurve_status midpoint(projcurve_context *ctx, const pc_implicit *imp,
                                 const pc_implicit_point *a, const pc_implicit_point *b,
                                 const pc_vec3 ctrl[4], pc_implicit_point *m, int *ok)
{
    const double tm = 0.5 * (a->t + b->t);
    pc_vec3 x = bezier3(ctrl, 0.5);
    int converged = 0, solved = 0;
    projcurve_status status = pc_implicit_correct(ctx, imp, tm, &x, &converged, NULL);
    if (status == PROJCURVE_OK && !converged) {
        x = vec3_scale(vec3_add(a->x, b->x), 0.5);
        status = pc_implicit_correct(ctx, imp, tm, &x, &converged, NULL);
    }
    if (status == PROJCURVE_OK && converged)
        status = pc_implicit_point_at(ctx, imp, tm, x, m, &solved);
    *ok = converged && solved;
    return status;
}

static projcurve_status add_piece(projcurve_context *ctx, pc_branch *b,
                                  const pc_implicit_point *a, const pc_implicit_point *e,
                                  const pc_vec3 ctrl[4])
{
    double c[12];
    const double uv[4] = {0, 0, 0, 0};   /* no (u, v) on an implicit surface */
    for (int k = 0; k < 4; ++k)
        vec3_store(ctrl[k], c + 3 * k);
    return pc_branch_add_piece(ctx, b, 3, a->t, e->t, uv, c, NULL);
}

/* Fits one branch left to right: a segment whose Hermite piece is not
 * within eps_D gets the exact midpoint inserted as a vertex and is tried
 * again, so the loop is bounded by the point limit. */
static projcurve_status fit_branch(projcurve_context *ctx, const pc_implicit *imp, double eps_d,
                                   const pc_params *opts, pc_branch *b,
                                   pc_stats *stats)
{
    const long long max_points = opts->max_points;
    pc_branch_clear_pieces(b);
    if (b->n_points < 2)
        return PROJCURVE_OK;
    const double dt_min = FIT_MIN_DT_REL * (imp->curve->t1 - imp->curve->t0);
    pc_implicit_point a, e;
    projcurve_status status = point_of(ctx, imp, b, 0, &a);
    size_t i = 0;
    while (status == PROJCURVE_OK && i + 1 < b->n_points) {
        /* a segment tried is the budget's unit; pieces are bounded by
         * MAX_PIECES before they are allocated */
        if (pc_budget_check(opts->budget, (double)i / (double)(b->n_points - 1)) !=
                PROJCURVE_OK ||
            stats->pieces >= (double)opts->max_pieces) {
            b->end = PROJCURVE_END_LIMIT;
            return pc_budget_status(opts->budget) != PROJCURVE_OK
                       ? pc_budget_fail(opts->budget, ctx)
                       : pc_fail(ctx, PROJCURVE_ERR_LIMIT_REACHED,
                                 "fitting the implicit projection reached the piece limit %lld",
                                 opts->max_pieces);
        }
        status = point_of(ctx, imp, b, i + 1, &e);
        if (status != PROJCURVE_OK)
            break;
        pc_vec3 ctrl[4];
        double err = 0.0;
        hermite_bezier(&a, &e, ctrl);
        status = piece_error(ctx, imp, &a, &e, ctrl, &err);
        if (status != PROJCURVE_OK)
            break;
        pc_implicit_point m;
        int split = err > FIT_SAFETY * eps_d && e.t - a.t > dt_min;
        if (split) {
            if ((long long)b->n_points >= max_points) {
                b->end = PROJCURVE_END_LIMIT;
                return pc_fail(ctx, PROJCURVE_ERR_LIMIT_REACHED,
                               "fitting the implicit projection reached the point limit %lld",
                               max_points);
            }
            status = midpoint(ctx, imp, &a, &e, ctrl, &m, &split);
        }
        if (status != PROJCURVE_OK)
            break;
        if (split) {
            const double v[4] = {m.t, m.x.x, m.x.y, m.x.z};
            status = pc_branch_insert_point(ctx, b, 4, i + 1, v);
            stats->points += 1;
            continue;
        }
        status = add_piece(ctx, b, &a, &e, ctrl);
        stats->pieces += 1;
        a = e;
        ++i;
    }
    return status;
}

projcurve_status pc_implicit_fit(projcurve_context *ctx, const pc_implicit *imp, double eps_d,
                                 const pc_params *opts, projcurve_result *r)
{
    for (size_t k = 0; k < r->n_branches; ++k) {
        const projcurve_status status =
            fit_branch(ctx, imp, eps_d, opts, &r->branches[k], &r->stats);
        if (status != PROJCURVE_OK)
            return status;
    }
    return PROJCURVE_OK;
}
