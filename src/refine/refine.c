/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Tolerance control and composition of traced branches ([SY13] s2 steps
 * 3-5, s4). For each branch:
 *   1. the traced polyline gets an exact vertex wherever it crosses a knot
 *      line of S (cells.c, split.c), so that every chord lies in one Bezier
 *      patch; these crossings and the branch ends are fixed;
 *   2. between fixed vertices, a step-controlled march along the exact
 *      projection chooses the vertices (march.c): each piece within eps_D
 *      (deviation.c) and with end tangents within eps_T / 2 of the exact
 *      ones, so that every joint is within eps_T; the traced vertices only
 *      guide the corrector (exact.c);
 *   3. where the march had to force a segment, joints beyond eps_T get
 *      vertices (angle.c);
 *   4. every segment is composed with its patch by blossoming (compose/).
 * The refined polyline replaces the branch's points: it is the pcurve of the
 * composed pieces. See docs/refine_compose.md.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "common/error.h"
#include "compose/compose.h"
#include "refine/refine.h"
#include "refine/refine_internal.h"

/* The deviation is estimated from samples; aiming a little below eps_D
 * covers the estimate's error and the difference between the two one-sided
 * distances, which agree to second order for curves this close. */
#define PC_REFINE_EPS_SAFETY 0.9
/* The same for eps_T: the exact tangent is exact, so little is needed. */
#define PC_REFINE_ANGLE_SAFETY 0.98
/* Parameter intervals shorter than this fraction of the branch are not
 * split further, and (u, v) moves below this fraction of the domain count as
 * zero: the corrector cannot resolve finer. */
#define PC_REFINE_MIN_DT_REL 1e-12
#define PC_REFINE_MIN_MOVE_REL 1e-13
/* Knot-line crossings this close to a patch corner (fraction of the domain)
 * are put on the corner: the move is far below any eps_D. */
#define PC_REFINE_SNAP_REL 1e-11
/* A knot-line crossing bracketed down to min_dt that is still this far from
 * its line (fraction of the domain) is no crossing: the curve jumps there.
 * Closer, it is put on the line (a move far below any eps_D; it allows for
 * the square-root speed of q near a fold). */
#define PC_REFINE_SNAP_FAR_REL 1e-9
#define PC_RADIANS_PER_DEGREE 0.017453292519943295769

static projcurve_status check_options(projcurve_context *ctx, const pc_params *o)
{
    if (!isfinite(o->tol_distance))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "distance tolerance is not finite");
    if (o->tol_distance < 0.0)
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE,
                       "distance tolerance %g is negative (0 is unset: automatic)",
                       o->tol_distance);
    if (!isfinite(o->tol_angle_deg))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "angle tolerance is not finite");
    if (!(o->tol_angle_deg > 0.0 && o->tol_angle_deg <= 90.0))
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE,
                       "angle tolerance %g degrees is outside (0, 90]", o->tol_angle_deg);
    if (o->max_pieces < 1)
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE, "piece limit %lld is below 1",
                       o->max_pieces);
    return PROJCURVE_OK;
}

/* The branch's points as ascending vertices (dropping repeated t), ends fixed. */
static projcurve_status load_branch(projcurve_context *ctx, const pc_branch *b,
                                    pc_vertex_list *out, int *descending)
{
    const double *p = b->points;
    const size_t n = b->n_points;
    *descending = p[0] > p[3 * (n - 1)];
    out->count = 0;
    for (size_t k = 0; k < n; ++k) {
        const double *q = p + 3 * (*descending ? n - 1 - k : k);
        const pc_rvertex v = {.t = q[0], .u = q[1], .v = q[2], .fixed = k == 0 || k + 1 == n};
        if (out->count > 0 && !(v.t > out->items[out->count - 1].t))
            continue;
        const projcurve_status st = pc_vertex_list_push(ctx, out, &v);
        if (st != PROJCURVE_OK)
            return st;
    }
    out->items[out->count - 1].fixed = 1;
    return PROJCURVE_OK;
}

/* Work lists of one call, reused from branch to branch. */
typedef struct refine_lists {
    pc_vertex_list traced, crossed, out, scratch;
} refine_lists;

static void refine_lists_free(refine_lists *l)
{
    pc_vertex_list_free(&l->traced);
    pc_vertex_list_free(&l->crossed);
    pc_vertex_list_free(&l->out);
    pc_vertex_list_free(&l->scratch);
}

/* Steps 1-3 for one branch into l->out (ascending t). */
static projcurve_status refine_branch(pc_refiner *r, const pc_branch *b, refine_lists *l,
                                      int *descending)
{
    projcurve_status st = load_branch(r->ctx, b, &l->traced, descending);
    if (st != PROJCURVE_OK)
        return st;
    for (size_t k = 0; k < l->traced.count; ++k)
        pc_refine_snap_to_knot_lines(r, &l->traced.items[k]);
    pc_refine_fix_corners(r, &l->traced);
    const pc_rvertex *tv = l->traced.items;
    const size_t nt = l->traced.count;
    l->out.count = 0; /* what store_branch finds if the budget stops step 1 */
    r->t_lo = tv[0].t;
    r->t_range = tv[nt - 1].t - tv[0].t;
    r->min_dt = PC_REFINE_MIN_DT_REL * r->t_range;
    /* 1. knot-line crossings: an intermediate list. Each crossing is an
     * output vertex below, so more crossings than the pieces left would
     * pass the piece limit anyway: the list stops at nt + that many
     * vertices (its memory is bounded before it grows) and the march
     * meets the limit where it would have without the cap. */
    const size_t budget = r->max_vertices;
    r->max_vertices = nt + budget + 1;
    r->guide = tv;
    r->n_guide = nt;
    l->crossed.count = 0;
    st = pc_vertex_list_push(r->ctx, &l->crossed, &tv[0]);
    for (size_t k = 0; k + 1 < nt && st == PROJCURVE_OK; ++k)
        st = pc_refine_split(r, &tv[k], &tv[k + 1], 0, &l->crossed);
    r->max_vertices = budget;
    const int capped = st == PROJCURVE_ERR_LIMIT_REACHED && pc_budget_status(r->budget) == PROJCURVE_OK;
    if (capped) {
        st = PROJCURVE_OK;
        r->limit_hit = 0;
    }
    if (st != PROJCURVE_OK)
        return st;
    l->crossed.items[l->crossed.count - 1].fixed = 1;
    for (size_t k = 0; k + 1 < l->crossed.count; ++k) /* a gap is a run of its own */
        if (l->crossed.items[k].gap)
            l->crossed.items[k].fixed = l->crossed.items[k + 1].fixed = 1;
    /* 2. and 3. with the crossings as the corrector's guide */
    r->guide = l->crossed.items;
    r->n_guide = l->crossed.count;
    l->out.count = 0;
    st = pc_refine_output(r, &l->out, &l->crossed.items[0]);
    r->step = 0.0;
    r->forced = 0;
    for (size_t k = 1, start = 0; k < l->crossed.count && st == PROJCURVE_OK; ++k) {
        if (!l->crossed.items[k].fixed)
            continue;
        const pc_rvertex *from = &l->crossed.items[start], *to = &l->crossed.items[k];
        if (from->gap) /* out's last vertex is that gap vertex */
            st = pc_refine_output(r, &l->out, to);
        else
            st = r->pcurve_degree == 3 ? pc_refine_march_cubic(r, from, to, &l->out)
                                       : pc_refine_march(r, from, to, &l->out);
        start = k;
    }
    if (st == PROJCURVE_OK && capped) { /* (the march always meets the limit first) */
        r->limit_hit = 1;
        return PROJCURVE_ERR_LIMIT_REACHED;
    }
    /* (the angle pass splits straight segments; cubic pieces are G1) */
    if (st == PROJCURVE_OK && r->forced > 0 && r->pcurve_degree == 1)
        st = pc_refine_angles(r, &l->out, &l->scratch);
    return st;
}

projcurve_status pc_refine_store_piece(pc_refiner *r, pc_branch *b, int n, const double *cw,
                                       int rational, const pc_rvertex *a, const pc_rvertex *e)
{
    double ctrl[3 * (PC_PIECE_MAX_DEGREE + 1)], weights[PC_PIECE_MAX_DEGREE + 1];
    if (rational) {
        pc_compose_to_cartesian(n, cw, ctrl, weights);
    } else { /* weights are 1 up to rounding: keep the polynomial form exact */
        for (int k = 0; k <= n; ++k)
            for (int c = 0; c < 3; ++c)
                ctrl[3 * k + c] = cw[4 * k + c];
    }
    const double uv[4] = {a->u, a->v, e->u, e->v};
    return pc_branch_add_piece(r->ctx, b, n, a->t, e->t, uv, ctrl, rational ? weights : NULL);
}

/* Composes the segment a-b (in one patch) and appends it to the branch. */
static projcurve_status add_piece(pc_refiner *r, pc_branch *b, const pc_bezier_patch *patch,
                                  const pc_rvertex *a, const pc_rvertex *e)
{
    double cw[PC_PIECE_MAX_CW];
    const int n = pc_refine_compose(patch, a, e, cw);
    return pc_refine_store_piece(r, b, n, cw, r->nurbs->rational, a, e);
}

/* 1 when the segment from vertex k to k + 1 is composed: no gap, one patch
 * (every stage leaves a segment in one patch or makes it a gap). */
static int segment_kept(const pc_refiner *r, const pc_vertex_list *out, size_t k)
{
    return !out->items[k].gap &&
           pc_refine_common_patch(r, &out->items[k], &out->items[k + 1]) != NULL;
}

/* Step 4 for the vertices [lo, hi] of out (ascending, every segment kept):
 * pieces and polyline of branch b, in the branch's own direction. */
static projcurve_status store_run(pc_refiner *r, pc_branch *b, const pc_vertex_list *out,
                                  size_t lo, size_t hi, int descending)
{
    const size_t n = hi - lo + 1;
    const pc_rvertex *v = out->items + lo;
    projcurve_status st = PROJCURVE_OK;
    for (size_t k = 0; k + 1 < n && st == PROJCURVE_OK; ++k) {
        const pc_rvertex *a = &v[descending ? n - 1 - k : k];
        const pc_rvertex *e = &v[descending ? n - 2 - k : k + 1];
        int done = 0;
        if (r->pcurve_degree == 3) /* the later vertex holds the segment's pcurve */
            st = pc_refine_add_cubic_piece(r, b, a, e, descending ? a : e, r->nurbs->rational,
                                           &done);
        if (st == PROJCURVE_OK && !done)
            st = add_piece(r, b, pc_refine_common_patch(r, a, e), a, e);
    }
    b->n_points = 0;
    for (size_t k = 0; k < n && st == PROJCURVE_OK; ++k) {
        const pc_rvertex *x = &v[descending ? n - 1 - k : k];
        const double point[3] = {x->t, x->u, x->v};
        st = pc_branch_add_point(r->ctx, b, 3, point);
    }
    return st;
}

/* The next run of kept segments in branch order, [*lo, *hi] ascending, at
 * or after *pos (a position in branch order, advanced past the run).
 * Returns 0 when none is left. Single vertices between gaps are no run. */
static int next_run(const pc_refiner *r, const pc_vertex_list *out, int descending,
                    size_t *pos, size_t *lo, size_t *hi, int *silhouette)
{
    const size_t n = out->count;
    *silhouette = 0;
    while (*pos + 1 < n) {
        /* ascending index of the segment at branch position *pos */
        const size_t k = descending ? n - 2 - *pos : *pos;
        if (!segment_kept(r, out, k)) {
            *silhouette |= out->items[k].gap == PC_GAP_SILHOUETTE;
            ++*pos;
            continue;
        }
        size_t first = k, last = k + 1; /* grow the run in branch order */
        while (*pos + 1 < n) {
            ++*pos;
            const size_t j = descending ? n - 2 - *pos : *pos;
            if (*pos + 1 >= n || !segment_kept(r, out, j))
                break;
            if (descending)
                first = j;
            else
                last = j + 1;
        }
        *lo = first;
        *hi = last;
        return 1;
    }
    return 0;
}

/* 1 when every vertex of out in [lo, hi] is within half of eps_D (3D) of
 * vertex `anchor`: a stretch of gaps at a branch end this short is the end
 * reached to the tolerance (typically an end on a seam or a centre that the
 * corrector resolves to rounding only), not a failure. */
static int gap_stretch_short(pc_refiner *r, const pc_vertex_list *out, size_t lo, size_t hi,
                             size_t anchor)
{
    const pc_rvertex *a = &out->items[anchor];
    const pc_vec3 x = pc_refine_surface_point(r, a->u, a->v);
    for (size_t k = lo; k <= hi; ++k) {
        const pc_rvertex *v = &out->items[k];
        if (!(vec3_dist(pc_refine_surface_point(r, v->u, v->v), x) <= 0.5 * r->eps_d))
            return 0;
    }
    return 1;
}

/* 1 when the run that next_run just returned (ending before branch
 * position pos) is a fragment of the branch's start: a later run follows,
 * and every vertex before that run stays within eps_D / 2 of its first
 * vertex (gap_stretch_short). A branch born at a fold starts with vertices
 * a few 1e-12 apart in t whose corrections fail one in two: the runs
 * between those gaps, each of a piece or two, came out as branches of
 * their own that start and end FAILED (teapot surface 18, a lifted
 * diagonal, at t = 0.8475); they are part of the start reached to the
 * tolerance, like the gaps around them. */
static int start_fragment(pc_refiner *r, const pc_vertex_list *out, int descending, size_t pos)
{
    size_t next_lo, next_hi;
    int silhouette;
    if (!next_run(r, out, descending, &pos, &next_lo, &next_hi, &silhouette))
        return 0;
    const size_t n = out->count;
    return descending ? gap_stretch_short(r, out, next_hi + 1, n - 1, next_hi)
                      : gap_stretch_short(r, out, 0, next_lo - 1, next_lo);
}

/* Step 4, and the refined polyline as the branch's points. Where out has
 * gaps, the branch is split: each run of composed segments becomes a
 * branch (the first keeps index i, the others are appended to res); the
 * ends at a gap say END_FAILED and START_FAILED (the projection could not
 * be followed there), or END_SILHOUETTE and START_SILHOUETTE at a
 * silhouette — also where gaps come before the first run or after the last
 * (the branch's own start and end are then not reached), unless those gaps
 * stay within eps_D / 2 of the run (gap_stretch_short). *pieces gets the
 * pieces made. */
static projcurve_status store_branch(pc_refiner *r, projcurve_result *res, size_t i,
                                     const pc_vertex_list *out, int descending, size_t *pieces)
{
    const projcurve_branch_end last_end = res->branches[i].end;
    const size_t n = out->count;
    size_t pos = 0, lo, hi, runs = 0, index = i, last_lo = 0, last_hi = 0;
    *pieces = 0;
    int silhouette = 0; /* the kind of the gaps before the current run */
    int at_end = 0;     /* the last run reaches the branch's end */
    while (next_run(r, out, descending, &pos, &lo, &hi, &silhouette)) {
        if (runs == 0 && start_fragment(r, out, descending, pos))
            continue;
        pc_branch *b = &res->branches[index];
        /* later runs start after a gap; the first one may after a few */
        const int at_start =
            runs == 0 && (descending ? hi + 1 == n || gap_stretch_short(r, out, hi + 1, n - 1, hi)
                                     : lo == 0 || gap_stretch_short(r, out, 0, lo - 1, lo));
        if (runs > 0) {
            projcurve_status st = pc_result_add_branch(r->ctx, res, &b);
            if (st != PROJCURVE_OK)
                return st;
            res->branches[index].end =
                silhouette ? PROJCURVE_END_SILHOUETTE : PROJCURVE_END_FAILED;
            index = res->n_branches - 1;
        }
        if (!at_start)
            b->start = silhouette ? PROJCURVE_START_SILHOUETTE : PROJCURVE_START_FAILED;
        last_lo = lo;
        last_hi = hi;
        b->end = last_end;
        const projcurve_status st = store_run(r, b, out, lo, hi, descending);
        *pieces += b->n_pieces;
        if (st != PROJCURVE_OK)
            return st;
        ++runs;
    }
    /* Whether the last run reaches the branch's end, checked once: checking
     * it after every run walked the rest of the polyline each time, O(runs
     * x vertices) after the work limit had stopped the call (5 s on a
     * fuzzed orthogonal input, tests/fuzz/corpus/project/regression-gap-runs). */
    if (runs > 0)
        at_end = descending ? last_lo == 0 || gap_stretch_short(r, out, 0, last_lo - 1, last_lo)
                            : last_hi + 1 == n ||
                                  gap_stretch_short(r, out, last_hi + 1, n - 1, last_hi);
    if (runs == 0 && last_end != PROJCURVE_END_LIMIT) /* nothing could be composed:
                                                         the traced polyline stays */
        res->branches[i].end = PROJCURVE_END_FAILED;
    else if (!at_end) /* gaps after the last run: silhouette set by next_run */
        res->branches[index].end = silhouette ? PROJCURVE_END_SILHOUETTE : PROJCURVE_END_FAILED;
    return PROJCURVE_OK;
}

static void refiner_init(pc_refiner *r, projcurve_context *ctx, const pc_projector *proj,
                         const pc_params *o, double eps)
{
    const projcurve_surface *s = proj->surface;
    const double *dom = s->nurbs.domain;
    *r = (pc_refiner){0};
    r->ctx = ctx;
    r->proj = proj;
    r->nurbs = &s->nurbs;
    r->grid = &s->grid;
    r->eps_d = PC_REFINE_EPS_SAFETY * eps;
    r->cos_eps_t = cos(o->tol_angle_deg * PC_RADIANS_PER_DEGREE);
    r->half_angle = 0.5 * PC_REFINE_ANGLE_SAFETY * o->tol_angle_deg * PC_RADIANS_PER_DEGREE;
    r->min_move = PC_REFINE_MIN_MOVE_REL * hypot(dom[1] - dom[0], dom[3] - dom[2]);
    r->snap = PC_REFINE_SNAP_REL * hypot(dom[1] - dom[0], dom[3] - dom[2]);
    r->snap_far = PC_REFINE_SNAP_FAR_REL * hypot(dom[1] - dom[0], dom[3] - dom[2]);
    /* cubic pcurves only where the composed degree 3 (p + q) is at most
     * PROJCURVE_MAX_DEGREE (projcurve.h): such pieces are as cheap as a few
     * straight ones and a branch of them joins into one NURBS curve; on
     * surfaces of degree 6 x 8 (composed degree 42) each cubic candidate
     * cost so much more that real-data calls ran past 2 s where straight
     * pieces take 0.3 s */
    const int sum = s->nurbs.deg_u + s->nurbs.deg_v;
    r->pcurve_degree = o->pcurve_degree == 3 && 3 * sum <= PROJCURVE_MAX_DEGREE ? 3 : 1;
    r->budget = o->budget;
}

projcurve_status pc_refine_and_compose(projcurve_context *ctx, const pc_projector *proj,
                                       const pc_params *opts,
                                       projcurve_result *res)
{
    PC_REQUIRE(ctx, proj, "projector");
    PC_REQUIRE(ctx, proj->surface, "projector surface");
    PC_REQUIRE(ctx, res, "result");
    pc_params defaults;
    if (opts == NULL) {
        pc_params_defaults(&defaults);
        opts = &defaults;
    }
    projcurve_status st = check_options(ctx, opts);
    if (st != PROJCURVE_OK)
        return st;
    if (res->point_dim != 3)
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                       "refinement needs (t, u, v) branches, not %d-dimensional points",
                       res->point_dim);
    if (!opts->compose)
        return PROJCURVE_OK;
    double eps;
    st = pc_params_distance_tolerance(ctx, opts, proj->model_size, &eps);
    if (st != PROJCURVE_OK)
        return st;
    res->stats.tol_distance = eps;

    pc_refiner r;
    refiner_init(&r, ctx, proj, opts, eps);
    refine_lists lists = {{0}, {0}, {0}, {0}};
    const size_t max_pieces = (size_t)opts->max_pieces;
    size_t pieces = 0;
    const size_t n_traced = res->n_branches; /* branches split at gaps are appended */
    for (size_t i = 0; i < n_traced && st == PROJCURVE_OK; ++i) {
        pc_branch *b = &res->branches[i];
        pc_branch_clear_pieces(b);
        if (r.limit_hit) {
            b->end = PROJCURVE_END_LIMIT;
            continue;
        }
        if (b->n_points < 2)
            continue;
        int descending = 0;
        r.max_vertices = max_pieces - pieces + 1;
        r.progress_lo = (double)i / (double)n_traced;
        r.progress_width = 1.0 / (double)n_traced;
        double since = pc_stage_clock_now(opts->stages);
        st = refine_branch(&r, b, &lists, &descending);
        since = pc_stage_clock_lap(opts->stages, PC_STAGE_REFINEMENT, since);
        if (st == PROJCURVE_ERR_LIMIT_REACHED) {
            b->end = PROJCURVE_END_LIMIT;
            st = PROJCURVE_OK;
        }
        size_t made = 0;
        if (st == PROJCURVE_OK)
            st = store_branch(&r, res, i, &lists.out, descending, &made);
        pc_stage_clock_lap(opts->stages, PC_STAGE_COMPOSITION, since);
        pieces += made;
        if (pieces >= max_pieces && i + 1 < n_traced)
            r.limit_hit = 1;
    }
    refine_lists_free(&lists);
    res->stats.pieces = (double)pieces;
    if (st == PROJCURVE_OK && pc_budget_status(r.budget) != PROJCURVE_OK)
        st = pc_budget_fail(r.budget, ctx);
    else if (st == PROJCURVE_OK && r.limit_hit)
        st = pc_fail(ctx, PROJCURVE_ERR_LIMIT_REACHED,
                     "the piece limit %lld was reached; the pieces made so far are kept",
                     opts->max_pieces);
    return st;
}
