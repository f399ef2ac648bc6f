/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The nearest hits across faces: the cuts of each face piece and which
 * parts are kept (shapeproj/shape_hits.h); the kept parts are built by
 * shapeproj/hits_part.c.
 */
#include "shapeproj/shape_hits.h"

#include <math.h>
#include <stdlib.h>

#include "common/array.h"
#include "common/error.h"
#include "shapeproj/hits_part.h"

typedef struct cut_list {
    double *items;
    size_t count, capacity;
} cut_list;

static projcurve_status push_cut(projcurve_context *ctx, cut_list *l, double t)
{
    projcurve_status st;
    PC_ARRAY_RESERVE(st, ctx, l, l->count + 1, 16, "the cuts of a face piece");
    if (st == PROJCURVE_OK)
        l->items[l->count++] = t;
    return st;
}

/* pc_track_distance as one unit of the call's budget (NULL: none), one
 * corrector call. */
static projcurve_status polled_distance(pc_budget *budget, const pc_track *k, double t,
                                        double uv[2], double *out)
{
    const projcurve_status st = pc_budget_check(budget, 0.0);
    return st != PROJCURVE_OK ? st : pc_track_distance(k, t, uv, out);
}

/* g(t) = d_a(t) - d_b(t) */
static projcurve_status gap_at(pc_budget *budget, const pc_track *a, const pc_track *b, double t,
                               double *g)
{
    double uv[2], da, db;
    projcurve_status st = polled_distance(budget, a, t, uv, &da);
    if (st == PROJCURVE_OK)
        st = polled_distance(budget, b, t, uv, &db);
    if (st == PROJCURVE_OK)
        *g = da - db;
    return st;
}

/* A root of g in [x0, x1] where g(x0) = g0 and g(x1) = g1 differ in sign. */
static projcurve_status locate(pc_budget *budget, const pc_track *a, const pc_track *b,
                               double x0, double g0, double x1, double g1, double tol,
                               double *out)
{
    double x = 0.5 * (x0 + x1);
    for (int it = 0; it < PC_SHAPE_HITS_MAX_ITER; ++it) {
        x = x1 - g1 * (x1 - x0) / (g1 - g0);
        if (!(x > fmin(x0, x1) && x < fmax(x0, x1)))
            x = 0.5 * (x0 + x1);
        double gx;
        const projcurve_status st = gap_at(budget, a, b, x, &gx);
        if (st != PROJCURVE_OK)
            return st;
        if (fabs(gx) <= tol || fabs(x1 - x0) <= 1e-15 * (fabs(x0) + fabs(x1) + 1e-300))
            break;
        if ((gx < 0.0) != (g1 < 0.0)) {
            x0 = x1;
            g0 = g1;
        } else {
            g0 *= 0.5; /* Illinois: the end kept twice counts half */
        }
        x1 = x;
        g1 = gx;
    }
    *out = x;
    return PROJCURVE_OK;
}

/* The next vertex time of a or b after the indices *ia, *ib. */
static double next_vertex(const pc_track *a, size_t *ia, const pc_track *b, size_t *ib)
{
    const double ta = *ia < a->b->n_points ? a->b->points[3 * *ia] : INFINITY;
    const double tb = *ib < b->b->n_points ? b->b->points[3 * *ib] : INFINITY;
    if (ta <= tb)
        ++*ia;
    else
        ++*ib;
    return fmin(ta, tb);
}

/* The crossings of d_a - d_b over [lo, hi], sampled at the vertices of
 * both there (each vertex visited once: the loop is bounded by their
 * count), pushed as cuts. */
static projcurve_status push_crossings(projcurve_context *ctx, pc_budget *budget,
                                       const pc_track *a, const pc_track *b, double lo, double hi,
                                       double tol, cut_list *cuts)
{
    size_t ia = 0, ib = 0;
    while (ia < a->b->n_points && a->b->points[3 * ia] <= lo)
        ++ia;
    while (ib < b->b->n_points && b->b->points[3 * ib] <= lo)
        ++ib;
    double t_prev = lo, g_prev;
    projcurve_status st = gap_at(budget, a, b, lo, &g_prev);
    int done = 0;
    while (st == PROJCURVE_OK && !done) {
        double t = next_vertex(a, &ia, b, &ib);
        if (!(t < hi)) {
            t = hi;
            done = 1;
        }
        if (!(t > t_prev))
            continue;
        double g;
        st = gap_at(budget, a, b, t, &g);
        if (st == PROJCURVE_OK && (g < 0.0) != (g_prev < 0.0)) {
            double root;
            st = locate(budget, a, b, t_prev, g_prev, t, g, tol, &root);
            if (st == PROJCURVE_OK)
                st = push_cut(ctx, cuts, root);
        }
        t_prev = t;
        g_prev = g;
    }
    return st;
}

static int double_order(const void *x, const void *y)
{
    const double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

/* The candidate cuts of track i, sorted. */
static projcurve_status gather_cuts(projcurve_context *ctx, pc_budget *budget,
                                    const pc_track *tracks, size_t n, size_t i, double tol,
                                    double min_len, cut_list *cuts)
{
    const pc_track *k = &tracks[i];
    projcurve_status st = push_cut(ctx, cuts, k->lo);
    if (st == PROJCURVE_OK)
        st = push_cut(ctx, cuts, k->hi);
    for (size_t j = 0; st == PROJCURVE_OK && j < n; ++j) {
        const pc_track *o = &tracks[j];
        const double a = fmax(k->lo, o->lo), c = fmin(k->hi, o->hi);
        if (j == i || o->whole || !(c - a > min_len))
            continue; /* touching: two pieces meeting on an edge */
        st = push_cut(ctx, cuts, a);
        if (st == PROJCURVE_OK)
            st = push_cut(ctx, cuts, c);
        if (st == PROJCURVE_OK)
            st = push_crossings(ctx, budget, k, o, a, c, tol, cuts);
    }
    if (st == PROJCURVE_OK && cuts->count > 0)
        qsort(cuts->items, cuts->count, sizeof *cuts->items, double_order);
    return st;
}

/* Whether track i is the nearest at t; ties within tol go to the lower
 * index. */
static projcurve_status nearest_at(pc_budget *budget, const pc_track *tracks, size_t n, size_t i,
                                   double t, double tol, int *keep)
{
    double uv[2], di, dj;
    projcurve_status st = polled_distance(budget, &tracks[i], t, uv, &di);
    *keep = st == PROJCURVE_OK;
    for (size_t j = 0; st == PROJCURVE_OK && *keep && j < n; ++j) {
        const pc_track *o = &tracks[j];
        if (j == i || o->whole || t < o->lo || t > o->hi)
            continue;
        st = polled_distance(budget, o, t, uv, &dj);
        if (st == PROJCURVE_OK && (dj < di - tol || (fabs(dj - di) <= tol && j < i)))
            *keep = 0;
    }
    return st;
}

/* Appends the run [s, e] of track k, its ends snapped to the track's own
 * ends when within min_len of them: there two pieces meet on an edge with
 * equal distances, and the rounding of that tie must not turn a TRIM end
 * (which chains) into a cut. */
static projcurve_status push_run(projcurve_context *ctx, const pc_track *k, size_t i, double s,
                                 double e, double min_len, pc_span_list *spans)
{
    if (s - k->lo <= min_len)
        s = k->lo;
    if (k->hi - e <= min_len)
        e = k->hi;
    return pc_span_push(ctx, spans, i, s, e, min_len);
}

/* The kept runs of track i appended to spans (when the budget stops it,
 * the runs appended so far are whole). */
static projcurve_status kept_runs(projcurve_context *ctx, pc_budget *budget,
                                  const pc_track *tracks, size_t n, size_t i, double tol,
                                  double min_len, pc_span_list *spans)
{
    cut_list cuts = {0};
    projcurve_status st = gather_cuts(ctx, budget, tracks, n, i, tol, min_len, &cuts);
    size_t open = cuts.count; /* the cut opening the current run; count: none */
    for (size_t k = 0; st == PROJCURVE_OK && k + 1 < cuts.count; ++k) {
        const double a = cuts.items[k], c = cuts.items[k + 1];
        if (!(c - a > min_len))
            continue;
        int keep = 0;
        st = nearest_at(budget, tracks, n, i, 0.5 * (a + c), tol, &keep);
        if (st == PROJCURVE_OK && keep && open == cuts.count)
            open = k;
        if (st == PROJCURVE_OK && !keep && open != cuts.count) {
            st = push_run(ctx, &tracks[i], i, cuts.items[open], a, min_len, spans);
            open = cuts.count;
        }
    }
    if (st == PROJCURVE_OK && open != cuts.count)
        st = push_run(ctx, &tracks[i], i, cuts.items[open], cuts.items[cuts.count - 1], min_len,
                      spans);
    PC_ARRAY_FREE(&cuts);
    return st;
}

/* After a stop at track `from` (tracks are ordered by part): the faces
 * whose tracks were not all selected say so in their status, so that a
 * caller reading one face does not take its pieces for complete. */
static projcurve_status mark_unselected(projcurve_context *ctx, projcurve_shape_result *r,
                                        const pc_track_set *set, size_t from,
                                        projcurve_status stop)
{
    projcurve_status st = PROJCURVE_OK;
    for (size_t k = from; st == PROJCURVE_OK && k < set->n_tracks; ++k) {
        pc_face_part *part = &r->parts[set->tracks[k].part];
        if (part->status != PROJCURVE_OK)
            continue;
        part->status = stop;
        st = pc_face_part_set_message(ctx, part,
                                      "the call stopped while selecting the nearest hits: "
                                      "this face's pieces not yet selected are dropped");
    }
    return st;
}

projcurve_status pc_shape_hits_select(projcurve_context *ctx, projcurve_shape_result *r,
                                      const projcurve_curve *curve,
                                      const pc_projection_spec *spec, const pc_params *p,
                                      double model_size)
{
    pc_track_set set;
    projcurve_status st = pc_track_set_build(ctx, r, curve, spec, p, &set);
    if (st != PROJCURVE_OK)
        return st;
    const double tol = PC_SHAPE_HITS_ROOT_TOL * model_size;
    const double min_len = PC_SHAPE_HITS_MIN_PART * (curve->t1 - curve->t0);
    pc_span_list spans = {0};
    /* polled only when the call still runs (a face stopped by a limit
     * gives a partial result, selected without polling: bounded by it) */
    pc_budget *const budget = pc_budget_if_running(p->budget);
    pc_budget_step(budget, "selecting the nearest hits across faces");
    size_t i = 0;
    for (; st == PROJCURVE_OK && i < set.n_tracks; ++i)
        st = set.tracks[i].whole ? pc_span_push(ctx, &spans, i, set.tracks[i].lo,
                                                set.tracks[i].hi, -1.0)
                                 : kept_runs(ctx, budget, set.tracks, set.n_tracks, i, tol,
                                             min_len, &spans);
    pc_budget_step(budget, NULL);
    /* stopped: the spans kept so far make the result, the pieces not yet
     * selected are dropped */
    const int stopped = st != PROJCURVE_OK && pc_budget_status(budget) == st;
    if (st == PROJCURVE_OK || stopped) {
        projcurve_status rs = pc_parts_rebuild(ctx, r, &set, &spans);
        if (rs == PROJCURVE_OK && stopped)
            rs = mark_unselected(ctx, r, &set, i - 1, st);
        st = rs != PROJCURVE_OK ? rs : stopped ? pc_budget_fail(budget, ctx) : st;
    }
    if (st == PROJCURVE_ERR_CALLBACK)
        st = pc_fail(ctx, st, "the curve callback failed while selecting the nearest hits");
    PC_ARRAY_FREE(&spans);
    pc_track_set_free(&set);
    return st;
}
