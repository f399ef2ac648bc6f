/* SPDX-License-Identifier: BSD-3-Clause */
#include "ortho/ortho_duplicates.h"

#include <math.h>
#include <string.h>

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
/* A run of this many vertices on another branch is a retraced stretch
 * (two branches that meet at a fold share one vertex at most). */
#define DUP_MIN_RUN 2

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

/* 1 when vertex p (t, u, v) is, on S, the foot point of b at its t. */
static int vertex_on(const pc_projector *proj, const pc_branch *b, const double *p)
{
    /* ends located on the boundary or at a fold by two branches agree to
     * about the engine's smallest step in t, not exactly */
    const double slack = DUP_MIN_EXTENT * (proj->curve->t1 - proj->curve->t0);
    if (b->n_points < 2 || p[0] < t_first(b) - slack || p[0] > t_last(b) + slack)
        return 0;
    const double t = p[0] < t_first(b) ? t_first(b) : (p[0] > t_last(b) ? t_last(b) : p[0]);
    pc_vec3 x;
    return branch_point_at(proj, b, t, &x) &&
           vec3_dist(x, point_on_s(proj, p[1], p[2])) <= DUP_SAME_POINT * proj->model_size;
}

/* The number of vertices at the end of a (its start if `at_start`) that
 * lie on b, counted until the first that does not. */
static size_t run_on(const pc_projector *proj, const pc_branch *a, const pc_branch *b,
                     int at_start)
{
    size_t n = 0;
    while (n < a->n_points &&
           vertex_on(proj, b, a->points + 3 * (at_start ? n : a->n_points - 1 - n)))
        ++n;
    return n;
}

/* The number of vertices of b strictly between t = a and t = c. */
static size_t vertices_between(const pc_branch *b, double a, double c)
{
    const double lo = a < c ? a : c, hi = a < c ? c : a;
    size_t n = 0;
    for (size_t i = 0; i < b->n_points; ++i)
        n += b->points[3 * i] > lo && b->points[3 * i] < hi;
    return n;
}

/* A branch whose end (or start) retraces another one over
 * DUP_MIN_RUN vertices or more, with vertices of its own before, and
 * whose step into that run passes over DUP_MIN_RUN vertices of the other
 * one or more, went
 * across a pair of folds onto that branch within one step (the fold test
 * sees det change sign twice: not at all) and followed it: it is cut at
 * the first vertex of the run and ends (starts) FAILED there, since the
 * part of it up to the fold was not followed (a search beside the folds,
 * trace/branches.c, may have found that part as a branch of its own). On
 * linkrods.step surface 1, curve 74, a branch of minima 0.02 long in t
 * stepped 0.03 past its end onto the next one. */
static void cut_retraced_runs(const pc_projector *proj, projcurve_result *r)
{
    for (size_t i = 0; i < r->n_branches; ++i)
        for (int at_start = 0; at_start <= 1; ++at_start)
            for (size_t k = 0; k < r->n_branches; ++k) {
                pc_branch *a = &r->branches[i];
                const pc_branch *b = &r->branches[k];
                if (k == i || b->n_points < 2 || a->n_points < DUP_MIN_RUN + 2)
                    continue;
                const size_t run = run_on(proj, a, b, at_start);
                if (run < DUP_MIN_RUN || run >= a->n_points)
                    continue;
                /* the step into the run passed over vertices of b: a
                 * stepped across part of b onto it (the branch that was
                 * landed on has all its vertices of its own, and its end
                 * lies on a's copy too, but no step of it passes b's) */
                const double *into = a->points + 3 * (at_start ? run - 1 : a->n_points - run);
                const double *from = at_start ? into + 3 : into - 3;
                if (vertices_between(b, from[0], into[0]) < DUP_MIN_RUN)
                    continue;
                /* the step into the run stays: the refinement verifies
                 * it, and cuts it where it is a jump (on a faceted surface
                 * it may be a step onto the crease the other branch
                 * follows: test_pipe_out_true surface 0, curve 2) */
                const size_t keep = a->n_points - run + 1;
                if (at_start) {
                    memmove(a->points, a->points + 3 * (run - 1), 3 * keep * sizeof *a->points);
                    a->start = PROJCURVE_START_FAILED;
                } else {
                    a->end = PROJCURVE_END_FAILED;
                }
                r->stats.points -= (double)(run - 1);
                a->n_points = keep;
            }
}

void pc_ortho_drop_duplicates(const pc_projector *proj, projcurve_result *r)
{
    cut_retraced_runs(proj, r);
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
