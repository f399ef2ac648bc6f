/* SPDX-License-Identifier: BSD-3-Clause */
#include "ortho/ortho_duplicates.h"

#include <math.h>

/* A branch whose t-range is below this fraction of the curve domain has no
 * extent (the engine's smallest step is 1e-13 of it). */
#define DUP_MIN_EXTENT 1e-12
/* Two vertices are one point of the projection when they are closer on S
 * than this fraction of the model size: far above the corrector's accuracy
 * (newton_tol, 1e-12 by default, or the rounding floor near a collapsed
 * edge, ~1e-9), far below the distance of two different foot points of one
 * P(t) except within ~1e-7 of the fold where they merge, and a copy agrees
 * everywhere, not only there. */
#define DUP_SAME_POINT 1e-7

static double t_first(const pc_branch *b) { return b->points[0]; }
static double t_last(const pc_branch *b) { return b->points[3 * (b->n_points - 1)]; }

static pc_vec3 point_on_s(const pc_projector *proj, double u, double v)
{
    pc_vec3 x;
    pc_nurbs_surface_eval(&proj->surface->nurbs, u, v, 0, NULL, NULL, &x);
    return x;
}

/* The foot point of branch b at t (within its range): the corrector from
 * the (u, v) interpolated on b's polyline, or b's vertex at t itself.
 * Returns 0 when the corrector fails. */
static int branch_point_at(const pc_projector *proj, const pc_branch *b, double t, pc_vec3 *x)
{
    size_t j = 0;
    while (j + 2 < b->n_points && b->points[3 * (j + 1)] <= t)
        ++j;
    const double *p = b->points + 3 * j;
    if (p[0] == t) {
        *x = point_on_s(proj, p[1], p[2]);
        return 1;
    }
    if (p[3] == t) {
        *x = point_on_s(proj, p[4], p[5]);
        return 1;
    }
    const double w = p[3] > p[0] ? (t - p[0]) / (p[3] - p[0]) : 0.0;
    double uv[2] = {p[1] + w * (p[4] - p[1]), p[2] + w * (p[5] - p[2])};
    if (!proj->correct(proj, t, uv, NULL))
        return 0;
    *x = point_on_s(proj, uv[0], uv[1]);
    return 1;
}

/* 1 when every vertex of a lies on b (a's range inside b's). */
static int retraces(const pc_projector *proj, const pc_branch *a, const pc_branch *b)
{
    if (b->n_points < 2 || t_first(a) < t_first(b) || t_last(a) > t_last(b))
        return 0;
    const double same = DUP_SAME_POINT * proj->model_size;
    for (size_t i = 0; i < a->n_points; ++i) {
        const double *p = a->points + 3 * i;
        pc_vec3 x;
        if (!branch_point_at(proj, b, p[0], &x) || vec3_dist(x, point_on_s(proj, p[1], p[2])) > same)
            return 0;
    }
    return 1;
}

void pc_ortho_drop_duplicates(const pc_projector *proj, projcurve_result *r)
{
    const double min_extent = DUP_MIN_EXTENT * (proj->curve->t1 - proj->curve->t0);
    for (size_t i = r->n_branches; i-- > 0;) {
        const pc_branch *a = &r->branches[i];
        int drop = a->n_points == 0 || t_last(a) - t_first(a) <= min_extent;
        for (size_t k = 0; !drop && k < r->n_branches; ++k) {
            if (k == i)
                continue;
            const pc_branch *b = &r->branches[k];
            if (b->n_points == 0)
                continue;
            const double ext_a = t_last(a) - t_first(a), ext_b = t_last(b) - t_first(b);
            /* of two copies with the same range the earlier stays */
            if (ext_b < ext_a || (ext_b == ext_a && k > i))
                continue;
            drop = retraces(proj, a, b);
        }
        if (drop) {
            r->stats.points -= (double)a->n_points;
            pc_result_remove_branch(r, i);
        }
    }
}
