/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The driver of the tracing engine (trace.h): seeds at the start of the
 * curve, one traced branch per seed, then the sweep over t of [SY13]
 * s3.4 that finds the branches born in mid-curve. A branch found by the
 * sweep is traced backwards first, to where it was born (a boundary entry,
 * a fold, or the start of the curve), then forwards to its end.
 */
#include <math.h>
#include <stdlib.h>

#include "common/array.h"
#include "common/error.h"
#include "trace/tracer.h"

/* Samples of the curve for the fallback length estimate. */
#define PC_LENGTH_SAMPLES 64
/* Most checks of the sweep: its step is at least 1 / this of the curve's
 * domain. A check costs a few microseconds (the criteria, every second one
 * a full search, the matching against the live branches), up to ~50 us on
 * a degree 6 x 10 rational surface of linkrods.step, so the sweep stays
 * within ~0.2 s; where branches move faster than ds per that step, a
 * branch born and gone within two such steps of t can be missed
 * (docs/tracing.md). (The floor was 1e-7 of the domain: 1e7 checks, 550 s
 * on linkrods curve 7 / surface 1.) */
#define PC_SWEEP_MAX_CHECKS 4096
/* A full search every this many checks (every 2 ds), whatever the jump
 * criteria say: they look at control polygons, which need not show a fold
 * of the surface inside a patch, so a branch born and gone between two
 * polygon hits would be missed; this bounds what can be missed to branches
 * shorter than about 2 ds. */
#define PC_SWEEP_FULL_EVERY 2
/* A found point may resume a failed branch whose end lies up to this many
 * sweep steps back (a full search runs every PC_SWEEP_FULL_EVERY checks). */
#define PC_RESUME_WINDOW (2.0 * PC_SWEEP_FULL_EVERY)
/* Seeds closer than this fraction of the model size on S are one point. */
#define PC_SEED_SAME 1e-9
/* The sweep checks every this fraction of the arc-length step. */
#define PC_SWEEP_STEP_FRACTION 0.5
/* With jump detection, the share of the tracing stage's progress that the
 * branches seeded at the start of the curve take; the sweep has the rest. */
#define PC_SWEEP_SHARE_START 0.5
/* The full search beside a branch end at a fold (search_beside_folds)
 * lies this fraction of the curve's domain inside the branch (at most half
 * of it): closer to the fold than the partner fold of a pair is (1e-3 of
 * the domain on linkrods.step surface 1), far enough that a branch ending
 * at the same fold covers that t. */
#define PC_FOLD_SEARCH_INSIDE 1e-4
/* A point found there within this fraction of ds on S of a branch alive
 * at its t is that branch's (search_beside_fold). */
#define PC_FOLD_SAME 1e-2
/* Most such searches per call (each 0.05 to 10 ms). */
#define PC_FOLD_SEARCHES 32
/* Floor of the length estimate the arc-length step is a fraction of,
 * relative to the model size: the step is then at least 1/64 of 1e-3 of
 * the model at the default ARC_STEP_FRACTION, a tenth of the default eps_D. */
#define PC_MIN_LENGTH 1e-3
/* Largest arc-length step in t, as a multiple of the arc-step fraction of
 * the domain: the step where the projection barely moves stays sane. */
#define PC_MAX_STEP_FACTOR 4.0

/* Length of the curve's polyline through PC_LENGTH_SAMPLES + 1 points. */
static double curve_length(const projcurve_curve *c)
{
    double len = 0.0;
    size_t hint = 0;
    pc_vec3 prev = {0, 0, 0};
    for (int i = 0; i <= PC_LENGTH_SAMPLES; ++i) {
        const double t = c->t0 + (c->t1 - c->t0) * (double)i / PC_LENGTH_SAMPLES;
        pc_vec3 p;
        if (pc_curve_eval(c, t, 0, &hint, &p) != PROJCURVE_OK)
            return 0.0;
        if (i > 0)
            len += vec3_dist(p, prev);
        prev = p;
    }
    return len;
}

static void tracer_setup(pc_tracer *tr, projcurve_context *ctx, const pc_projector *proj,
                         const pc_params *opts, const pc_trace_config *cfg,
                         projcurve_result *r)
{
    const projcurve_curve *c = proj->curve;
    *tr = (pc_tracer){0};
    tr->ctx = ctx;
    tr->proj = proj;
    tr->r = r;
    tr->method = (int)opts->method;
    tr->t_begin = c->t0;
    tr->t_end = c->t1;
    for (int k = 0; k < 4; ++k)
        tr->dom[k] = proj->surface->nurbs.domain[k];
    const double span = c->t1 - c->t0;
    /* ds serves arc-length stepping and the jump sweep only: constant
     * parameter steps without the sweep skip the fallback estimate (65
     * curve evaluations) */
    const int need_ds = !(opts->param_step > 0.0) || opts->jump_detection;
    double length = cfg->length_estimate > 0.0 ? cfg->length_estimate
                                               : (need_ds ? curve_length(c) : 0.0);
    if (!(length > 0.0) || !isfinite(length))
        length = cfg->model_size > 0.0 ? cfg->model_size : 1.0;
    /* The estimate can be near 0 when the projection is not (the curve
     * nearly parallel to Dir: its polyline projects onto a point of the
     * control polygons; 7e-10 on linkrods, with steps and sweep checks of
     * 1e-11 model units). Below PC_MIN_LENGTH of the model size the step
     * would resolve nothing the refinement (eps_D) needs. */
    length = fmax(length, PC_MIN_LENGTH * cfg->model_size);
    tr->ds = opts->arc_step_fraction * length;
    tr->param_step = opts->param_step;
    tr->max_step = fmin(PC_MAX_STEP_FACTOR * opts->arc_step_fraction, 1.0) * span;
    tr->min_step = PC_TRACE_MIN_STEP * span;
    tr->max_points = (size_t)opts->max_points;
    tr->criteria_only = opts->sweep_criteria_only != 0;
    tr->budget = opts->budget;
    tr->progress_hi = 1.0;
    tr->ray = cfg->ray;
    tr->jump_checks = !cfg->ray;
    tr->dir = cfg->dir;
    tr->lambda_tol = proj->newton_tol;
    tr->behind_tol = opts->tol_distance;
    /* Land on the corners of P only: at a C1 knot q' is continuous and the
     * predictor just loses order for one step, while a step cut short to
     * land there beside a fold let the corrector reach the other sheet
     * (linkrods.step surface 9, curve 100: a stretch missed). */
    pc_curve_breaks_init(&tr->breaks, c, PC_BREAK_ORDER_CORNER);
    tr->narrow_capped_at = NAN;
}

static projcurve_branch_start start_reason(projcurve_branch_end backward_end)
{
    switch (backward_end) {
    case PROJCURVE_END_BOUNDARY:
        return PROJCURVE_START_BOUNDARY;
    case PROJCURVE_END_SILHOUETTE:
        return PROJCURVE_START_SILHOUETTE;
    case PROJCURVE_END_CURVE_END:
        return PROJCURVE_START_CURVE_START;
    case PROJCURVE_END_CURVE_CROSSING:
        return PROJCURVE_START_CURVE_CROSSING;
    case PROJCURVE_END_FAILED:
        /* stalled: a gap before it unless another branch accounts for
         * it (excuse_covered_stalls, after the sweep) */
        return PROJCURVE_START_FAILED;
    default:
        return PROJCURVE_START_JUMP;
    }
}

/* Traces `back` backwards from the seed, then moves its vertices, reversed,
 * into branch bi. */
static projcurve_status trace_birth(pc_tracer *tr, const pc_seed *seed, size_t bi)
{
    pc_branch back = {0};
    projcurve_branch_end why = PROJCURVE_END_FAILED;
    projcurve_status st = pc_trace_run(tr, seed, -1, tr->t_begin, 1, &back, &why);
    pc_branch *b = &tr->r->branches[bi];
    b->start = start_reason(why);
    for (size_t k = back.n_points; st == PROJCURVE_OK && k-- > 0;)
        st = pc_branch_add_point(tr->ctx, b, 3, back.points + 3 * k);
    free(back.points);
    return st;
}

/* How a branch is started from a seed. */
typedef enum seed_kind {
    SEED_AT_START,   /* a seed at the start of the curve */
    SEED_BORN,       /* found in mid-curve: traced back to its birth first */
    SEED_RESUMED     /* continues a branch that failed: forwards only */
} seed_kind;

/* A new branch through the seed: traced forwards to its end, and first
 * backwards to its birth when it was born in mid-curve. */
static projcurve_status start_branch(pc_tracer *tr, const pc_seed *seed, seed_kind kind)
{
    pc_branch *b = NULL;
    projcurve_status st = pc_result_add_branch(tr->ctx, tr->r, &b);
    if (st != PROJCURVE_OK)
        return st;
    const size_t bi = tr->r->n_branches - 1;
    b->start = kind == SEED_RESUMED ? PROJCURVE_START_JUMP : PROJCURVE_START_CURVE_START;
    b->end = PROJCURVE_END_FAILED;
    if (kind == SEED_BORN) {
        tr->r->stats.jumps += 1.0;
        st = trace_birth(tr, seed, bi);
        if (st != PROJCURVE_OK)
            return st;
    }
    b = &tr->r->branches[bi];
    projcurve_branch_end why = PROJCURVE_END_FAILED;
    st = pc_trace_run(tr, seed, +1, tr->t_end, b->n_points == 0, b, &why);
    b->end = why;
    /* A single vertex (a grazing seed on a fold, a seed behind the curve,
     * a ray lying in S) carries no curve: dropped at once, so that the
     * sweep, which finds it again at every check, does not pile them up
     * (each check matches against every branch). */
    if (st == PROJCURVE_OK && b->n_points < 2) {
        tr->n_points -= b->n_points;
        tr->r->stats.points -= (double)b->n_points;
        pc_result_remove_branch(tr->r, bi);
    }
    return st;
}

static int branch_covers(const pc_branch *b, double t)
{
    return b->n_points >= 2 && b->points[0] <= t && t <= b->points[3 * (b->n_points - 1)];
}

/* The current points of the branches alive at t, interpolated on their
 * polylines. */
static projcurve_status active_points(pc_tracer *tr, double t, pc_seed_list *out)
{
    out->count = 0;
    for (size_t i = 0; i < tr->r->n_branches; ++i) {
        const pc_branch *b = &tr->r->branches[i];
        if (!branch_covers(b, t))
            continue;
        const double *p = b->points + 3 * pc_branch_segment_at(b, t);
        const double w = p[3] > p[0] ? (t - p[0]) / (p[3] - p[0]) : 0.0;
        projcurve_status st = pc_seed_list_push(tr->ctx, out, t, p[1] + w * (p[4] - p[1]),
                                                p[2] + w * (p[5] - p[2]));
        if (st != PROJCURVE_OK)
            return st;
    }
    return PROJCURVE_OK;
}

/* Moves each active point (interpolated, in the order of active_points)
 * onto the exact projection at t with the corrector, so that matching does
 * not depend on how coarse the branch's steps are. A correction that moves
 * farther than the branch's segment is long is not trusted (it may have
 * found another sheet): the interpolated point stays. */
static void polish_active_points(pc_tracer *tr, double t, pc_seed_list *active)
{
    const pc_projector *proj = tr->proj;
    size_t k = 0;
    for (size_t i = 0; i < tr->r->n_branches && k < active->count; ++i) {
        const pc_branch *b = &tr->r->branches[i];
        if (!branch_covers(b, t))
            continue;
        const double *p = b->points + 3 * pc_branch_segment_at(b, t);
        const double reach = sqrt((p[4] - p[1]) * (p[4] - p[1]) + (p[5] - p[2]) * (p[5] - p[2]));
        pc_seed *a = &active->items[k++];
        double uv[2] = {a->u, a->v};
        if (proj->correct(proj, t, uv, NULL) &&
            sqrt((uv[0] - a->u) * (uv[0] - a->u) + (uv[1] - a->v) * (uv[1] - a->v)) <= reach) {
            a->u = uv[0];
            a->v = uv[1];
        }
    }
}

/* The sweep step at t: half an arc-length step ds of the fastest of the
 * branches alive (speed measured on their polylines) and the curve itself.
 * Half, so that the normal motion of a ray's hits between two checks stays
 * below the ds of the jump criteria 2 and 4. */
static double sweep_step(const pc_tracer *tr, double t)
{
    const pc_nurbs_surface *s = &tr->proj->surface->nurbs;
    double speed = 0.0;
    for (size_t i = 0; i < tr->r->n_branches; ++i) {
        const pc_branch *b = &tr->r->branches[i];
        if (!branch_covers(b, t))
            continue;
        const double *p = b->points + 3 * pc_branch_segment_at(b, t);
        if (!(p[3] > p[0]))
            continue;
        pc_vec3 a, c;
        pc_nurbs_surface_eval(s, p[1], p[2], 0, NULL, NULL, &a);
        pc_nurbs_surface_eval(s, p[4], p[5], 0, NULL, NULL, &c);
        speed = fmax(speed, vec3_dist(a, c) / (p[3] - p[0]));
    }
    /* a point of the projection not traced yet moves about as fast as
     * the curve (faster only where the surface is steep to Dir) */
    pc_vec3 d[2];
    if (pc_curve_eval(tr->proj->curve, t, 1, NULL, d) == PROJCURVE_OK)
        speed = fmax(speed, vec3_norm(d[1]));
    const double span = tr->t_end - tr->t_begin;
    double dt = speed > 0.0 ? PC_SWEEP_STEP_FRACTION * tr->ds / speed : tr->max_step;
    dt = fmin(dt, tr->max_step);
    return fmax(dt, span / PC_SWEEP_MAX_CHECKS);
}

/* 1 when the found point continues a branch that stopped short of t
 * without a geometric reason (the corrector failed, or the curve's end was
 * reached a rounding error early): its last vertex lies within
 * PC_RESUME_WINDOW sweep steps dt before t and within 2 ds of the point on
 * S. Such a point resumes the branch's curve instead of starting one that
 * would be traced back over it. Branches that ended on the boundary or a
 * fold are not continued: a point beyond them belongs to another branch. */
static int continues_branch(const pc_tracer *tr, const pc_seed *p, double dt)
{
    const pc_nurbs_surface *s = &tr->proj->surface->nurbs;
    pc_vec3 a;
    pc_nurbs_surface_eval(s, p->u, p->v, 0, NULL, NULL, &a);
    for (size_t i = 0; i < tr->r->n_branches; ++i) {
        const pc_branch *b = &tr->r->branches[i];
        if (b->n_points == 0 ||
            (b->end != PROJCURVE_END_FAILED && b->end != PROJCURVE_END_CURVE_END))
            continue;
        const double *last = b->points + 3 * (b->n_points - 1);
        if (last[0] > p->t || p->t - last[0] > PC_RESUME_WINDOW * dt)
            continue;
        pc_vec3 e;
        pc_nurbs_surface_eval(s, last[1], last[2], 0, NULL, NULL, &e);
        if (vec3_dist(a, e) <= 2.0 * tr->ds)
            return 1;
    }
    return 0;
}

/* Removes the seeds that coincide on S with an earlier one: the same point
 * of a closed surface's seam or of a collapsed edge found under two
 * parameters is one point of the projection. */
static void drop_coincident(const pc_tracer *tr, pc_seed_list *list)
{
    const pc_nurbs_surface *s = &tr->proj->surface->nurbs;
    const double same = PC_SEED_SAME * tr->proj->model_size;
    size_t kept = 0;
    for (size_t k = 0; k < list->count; ++k) {
        pc_vec3 a;
        pc_nurbs_surface_eval(s, list->items[k].u, list->items[k].v, 0, NULL, NULL, &a);
        int duplicate = 0;
        for (size_t i = 0; i < kept && !duplicate; ++i) {
            pc_vec3 b;
            pc_nurbs_surface_eval(s, list->items[i].u, list->items[i].v, 0, NULL, NULL, &b);
            duplicate = vec3_dist(a, b) <= same;
        }
        if (!duplicate)
            list->items[kept++] = list->items[k];
    }
    list->count = kept;
}

/* [SY13] s3.4 over the whole curve. */
/* The sweep; with a stage clock, the CPU time of the branches it starts
 * (tracing, not jump detection) is added to *births. */
static projcurve_status sweep(pc_tracer *tr, pc_seed_finder *finder, pc_stage_clock *clock,
                              double *births)
{
    pc_seed_list active = {0}, found = {0};
    unsigned char *matched = NULL;
    size_t cap_matched = 0;
    projcurve_status st = PROJCURVE_OK;
    if (finder->reset)
        finder->reset(finder);
    /* every check advances t by at least span / PC_SWEEP_MAX_CHECKS (up to
     * rounding of t), but the PC_SWEEP_MAX_NARROWED narrowed ones, so this
     * bound is reached only through rounding; the sweep then ends where it
     * got to */
    const size_t max_checks = 2 * (size_t)PC_SWEEP_MAX_CHECKS + 2 + PC_SWEEP_MAX_NARROWED;
    double t = tr->t_begin;
    for (size_t check = 0; check < max_checks && t < tr->t_end && !tr->limit_hit; ++check) {
        /* a check (criteria, and maybe a full seed search) is a unit of
         * the budget; branches born here are traced at this progress */
        tr->progress_lo = tr->progress_hi = PC_SWEEP_SHARE_START +
            (1.0 - PC_SWEEP_SHARE_START) * (t - tr->t_begin) / (tr->t_end - tr->t_begin);
        if (pc_tracer_budget_spent(tr, t))
            break;
        /* the step of the criteria (and of the resume window), then
         * narrowed where it may jump over a small patch */
        const double dt = sweep_step(tr, t);
        int narrowed = 0;
        const double step = pc_sweep_narrow(tr, finder, t, dt, &narrowed);
        t = t + step >= tr->t_end ? tr->t_end : t + step;
        st = active_points(tr, t, &active);
        if (st != PROJCURVE_OK)
            break;
        /* the criteria run at every check (they keep the previous ray);
         * every PC_SWEEP_FULL_EVERY-th check searches regardless, unless
         * the criteria alone are asked for; a narrowed check always (it
         * lands where a ray meets the small patch's box) */
        const int asked =
            (!finder->may_jump || finder->may_jump(finder, t, active.items, active.count, tr->ds)) ||
            narrowed;
        const int periodic = !tr->criteria_only &&
                             check % PC_SWEEP_FULL_EVERY == PC_SWEEP_FULL_EVERY - 1;
        if (!asked && !periodic)
            continue;
        st = finder->find(finder, tr->ctx, t, &found);
        if (st != PROJCURVE_OK)
            break;
        drop_coincident(tr, &found);
        polish_active_points(tr, t, &active);
        void *items = matched;
        st = pc_array_reserve(tr->ctx, &items, &cap_matched, 0, found.count, 1, 16, NULL,
                              "the seed matches");
        matched = items;
        if (st != PROJCURVE_OK)
            break;
        pc_match_seeds(tr->proj->surface, active.items, active.count, found.items, found.count,
                       tr->ds, matched);
        const double born_at = pc_stage_clock_now(clock);
        for (size_t k = 0; k < found.count && st == PROJCURVE_OK && !tr->limit_hit; ++k)
            if (!matched[k])
                st = start_branch(tr, &found.items[k],
                                  continues_branch(tr, &found.items[k], dt) ? SEED_RESUMED
                                                                                   : SEED_BORN);
        if (clock != NULL)
            *births += pc_stage_clock_now(clock) - born_at;
        if (st != PROJCURVE_OK)
            break;
    }
    free(matched);
    pc_seed_list_free(&active);
    pc_seed_list_free(&found);
    return st;
}

/* 1 when the found point p lies within `radius` on S of a point of the
 * list (a branch alive at its t). */
static int near_any(const pc_tracer *tr, const pc_seed *p, const pc_seed_list *points,
                    double radius)
{
    const pc_nurbs_surface *s = &tr->proj->surface->nurbs;
    pc_vec3 a;
    pc_nurbs_surface_eval(s, p->u, p->v, 0, NULL, NULL, &a);
    for (size_t i = 0; i < points->count; ++i) {
        pc_vec3 b;
        pc_nurbs_surface_eval(s, points->items[i].u, points->items[i].v, 0, NULL, NULL, &b);
        if (vec3_dist(a, b) <= radius)
            return 1;
    }
    return 0;
}

/* The full search beside the fold end (start if `at_start`) of branch bi,
 * a little inside it: each foot point found there that no branch alive at
 * that t takes (the nearest within ds, as in the sweep) and that lies
 * farther than PC_FOLD_SAME ds from all of them starts a branch. (Beside
 * a degenerate centre of curvature, a whole circle of foot points at one
 * t on a torus, the search returns clusters of points 1e-7 apart: one
 * branch takes one of them, the rest are the same foot point.) */
static projcurve_status search_beside_fold(pc_tracer *tr, pc_seed_finder *finder, double t,
                                           pc_seed_list *active, pc_seed_list *found,
                                           unsigned char **matched, size_t *cap_matched)
{
    projcurve_status st = active_points(tr, t, active);
    if (st == PROJCURVE_OK)
        st = finder->find(finder, tr->ctx, t, found);
    if (st != PROJCURVE_OK)
        return st;
    drop_coincident(tr, found);
    polish_active_points(tr, t, active);
    void *items = *matched;
    st = pc_array_reserve(tr->ctx, &items, cap_matched, 0, found->count, 1, 16, NULL,
                          "the seed matches");
    *matched = items;
    if (st != PROJCURVE_OK)
        return st;
    pc_match_seeds(tr->proj->surface, active->items, active->count, found->items, found->count,
                   tr->ds, *matched);
    const double same = PC_FOLD_SAME * tr->ds;
    for (size_t k = 0; k < found->count && st == PROJCURVE_OK && !tr->limit_hit; ++k) {
        if ((*matched)[k] || near_any(tr, &found->items[k], active, same))
            continue;
        st = start_branch(tr, &found->items[k], SEED_BORN);
        /* the branch just traced is alive at t too */
        if (st == PROJCURVE_OK)
            st = active_points(tr, t, active);
        if (st == PROJCURVE_OK)
            polish_active_points(tr, t, active);
    }
    return st;
}

/* 1 when x lies within `radius` on S of branch b: of its polyline at t
 * (interpolated) or of one of its two ends. */
static int branch_passes_near(const pc_tracer *tr, const pc_branch *b, double t, pc_vec3 x,
                              double radius)
{
    const pc_nurbs_surface *s = &tr->proj->surface->nurbs;
    if (b->n_points < 2)
        return 0;
    pc_vec3 y;
    for (int end = 0; end < 2; ++end) {
        const double *q = b->points + (end ? 3 * (b->n_points - 1) : 0);
        pc_nurbs_surface_eval(s, q[1], q[2], 0, NULL, NULL, &y);
        if (vec3_dist(x, y) <= radius)
            return 1;
    }
    if (!branch_covers(b, t))
        return 0;
    const double *p = b->points + 3 * pc_branch_segment_at(b, t);
    const double w = p[3] > p[0] ? (t - p[0]) / (p[3] - p[0]) : 0.0;
    pc_nurbs_surface_eval(s, p[1] + w * (p[4] - p[1]), p[2] + w * (p[5] - p[2]), 0, NULL, NULL,
                          &y);
    return vec3_dist(x, y) <= radius;
}

/* A branch found in mid-curve whose backward trace stalled starts FAILED
 * (start_reason): the stretch before the stall is a gap, counted by
 * projcurve_result_failure_count, unless something else accounts for it.
 * That is the start of the curve within one step of the stall, or another
 * branch passing within eps_D of the stalled start on S (ending or
 * starting there, or alive at that t with the same point). Those start
 * JUMP: the backward trace of a line starting at a sphere's pole stalls
 * at the pole 7e-12 after the curve's start, and nothing is missing there
 * (test_refine_pole). (linkrods.step surface 9, curve 38: the
 * backward trace stalls at t = 2.6607, beside a fold pair, with no other
 * branch before it; the foot of P(2.65072) lay 707 eps_D from the result
 * and nothing was reported.) */
static void excuse_covered_stalls(const pc_tracer *tr, double eps_d)
{
    const pc_nurbs_surface *s = &tr->proj->surface->nurbs;
    const projcurve_result *r = tr->r;
    for (size_t i = 0; i < r->n_branches; ++i) {
        pc_branch *b = &r->branches[i];
        if (b->start != PROJCURVE_START_FAILED || b->n_points < 2)
            continue;
        const double t = b->points[0];
        pc_vec3 x;
        pc_nurbs_surface_eval(s, b->points[1], b->points[2], 0, NULL, NULL, &x);
        int covered = t - tr->t_begin <= tr->max_step;
        for (size_t j = 0; j < r->n_branches && !covered; ++j)
            covered = j != i && branch_passes_near(tr, &r->branches[j], t, x, eps_d);
        if (covered)
            b->start = PROJCURVE_START_JUMP;
    }
}

/* Where search_beside_folds searches beside the start (end if !at_start)
 * of b: a little inside it at a fold; a little before a stalled start
 * (START_FAILED, start_reason), where the branch the stall hides may be
 * alive (linkrods.step surface 9, curve 38: a fold pair at t = 2.6608,
 * the minima before it from t = 2.641, between two searches of the sweep).
 * NAN: no search. */
static double search_beside_t(const pc_tracer *tr, const pc_branch *b, int at_start)
{
    if (b->n_points < 2)
        return NAN;
    const double t0 = b->points[0], t1 = b->points[3 * (b->n_points - 1)];
    const double step = PC_FOLD_SEARCH_INSIDE * (tr->t_end - tr->t_begin);
    if (at_start && b->start == PROJCURVE_START_FAILED)
        return t0 - step > tr->t_begin ? t0 - step : NAN;
    const int at_fold = at_start ? b->start == PROJCURVE_START_SILHOUETTE
                                 : b->end == PROJCURVE_END_SILHOUETTE;
    const double inside = fmin(0.5 * (t1 - t0), step);
    if (!at_fold || !(inside > 0.0))
        return NAN;
    return at_start ? t0 + inside : t1 - inside;
}

/* Foot-point projections: a full search beside every end of a branch at a
 * centre of curvature (a fold of the projection, where two foot points
 * meet). The sweep searches for foot points only every 1/16 or 1/32 of
 * the curve's domain (ortho_seeds.h), and where P(t) passes close to the
 * focal surface, folds come in pairs 1e-3 apart in t: the minimum a
 * branch ends at such a fold hands over to was born at its partner just
 * before, beside it, so both are alive a little inside the fold's side of
 * the branch; likewise the branch a birth at a fold continues from. Both
 * can be born and gone between two searches of the sweep (linkrods.step
 * surface 1, curve 74: two branches of minima, 0.065 and 0.02 long in t,
 * between the sweep's searches 0.17 apart). A branch started here is
 * searched beside in turn, up to PC_FOLD_SEARCHES searches. Ray
 * projections need none of this: their sweep searches every ds. */
static projcurve_status search_beside_folds(pc_tracer *tr, pc_seed_finder *finder)
{
    pc_seed_list active = {0}, found = {0};
    unsigned char *matched = NULL;
    size_t cap_matched = 0, searches = 0;
    projcurve_status st = PROJCURVE_OK;
    if (finder->reset)
        finder->reset(finder);
    for (size_t i = 0; i < tr->r->n_branches && st == PROJCURVE_OK && !tr->limit_hit; ++i)
        for (int at_start = 1; at_start >= 0 && st == PROJCURVE_OK; --at_start) {
            const pc_branch *b = &tr->r->branches[i];
            const double t = search_beside_t(tr, b, at_start);
            if (isnan(t) || searches >= PC_FOLD_SEARCHES)
                continue;
            if (pc_tracer_budget_spent(tr, t))
                break;
            ++searches;
            st = search_beside_fold(tr, finder, t, &active, &found, &matched, &cap_matched);
        }
    free(matched);
    pc_seed_list_free(&active);
    pc_seed_list_free(&found);
    return st;
}

/* Branches of a single vertex (a seed on a fold, a grazing hit) carry no
 * curve: they are dropped. */
static void drop_single_points(projcurve_result *r)
{
    for (size_t i = r->n_branches; i-- > 0;)
        if (r->branches[i].n_points < 2) {
            r->stats.points -= (double)r->branches[i].n_points;
            pc_result_remove_branch(r, i);
        }
}

/* 1 when the image of b on S lies within `radius` of its first point. */
static int image_is_point(const projcurve_surface *s, const pc_branch *b, double radius)
{
    pc_vec3 first;
    pc_nurbs_surface_eval(&s->nurbs, b->points[1], b->points[2], 0, NULL, NULL, &first);
    for (size_t k = 1; k < b->n_points; ++k) {
        pc_vec3 x;
        pc_nurbs_surface_eval(&s->nurbs, b->points[3 * k + 1], b->points[3 * k + 2], 0, NULL,
                              NULL, &x);
        if (vec3_dist(x, first) > radius)
            return 0;
    }
    return 1;
}

/* 1 when the curve over the t range of b stays within `radius` of its
 * point at b's first vertex (a curve shorter than eps_D: its projection is
 * that short too). A curve that cannot be evaluated counts as moving. */
static int curve_is_point(const projcurve_curve *c, const pc_branch *b, double radius)
{
    size_t hint = 0;
    pc_vec3 first;
    if (pc_curve_eval(c, b->points[0], 0, &hint, &first) != PROJCURVE_OK)
        return 0;
    for (size_t k = 1; k < b->n_points; ++k) {
        pc_vec3 p;
        if (pc_curve_eval(c, b->points[3 * k], 0, &hint, &p) != PROJCURVE_OK ||
            vec3_dist(p, first) > radius)
            return 0;
    }
    return 1;
}

/* Ray projections: where the curve runs along Dir, P(t) slides along its
 * own ray and the projection stands still. A branch whose whole image on S
 * lies within eps_D of one point is that point, not a curve: dropped (a
 * point has no tangent the composition could bound; tracing it cost a few
 * steps of max_step, composing it would not end). Where the curve itself
 * moved more than eps_D the rays of that stretch hit S at the point, so the
 * drop is counted as a failure: a result OK with nothing would claim that
 * the curve misses S. (A curve shorter than eps_D is no failure: its
 * projection is below the tolerance.) */
static void drop_point_images(const pc_tracer *tr, double eps_d, projcurve_result *r)
{
    for (size_t i = r->n_branches; i-- > 0;)
        if (image_is_point(tr->proj->surface, &r->branches[i], eps_d)) {
            r->stats.points -= (double)r->branches[i].n_points;
            if (!curve_is_point(tr->proj->curve, &r->branches[i], eps_d))
                ++r->failures_dropped;
            pc_result_remove_branch(r, i);
        }
}

projcurve_status pc_trace_branches(projcurve_context *ctx, const pc_projector *proj,
                                   const pc_params *opts,
                                   pc_seed_finder *finder, const pc_trace_config *config,
                                   projcurve_result *r)
{
    pc_tracer tr;
    tracer_setup(&tr, ctx, proj, opts, config, r);
    pc_stage_clock *const clock = opts->stages;
    double since = pc_stage_clock_now(clock);
    pc_seed_list seeds = {0};
    projcurve_status st = finder->find(finder, ctx, tr.t_begin, &seeds);
    drop_coincident(&tr, &seeds);
    since = pc_stage_clock_lap(clock, PC_STAGE_SEEDING, since);
    const double share = opts->jump_detection ? PC_SWEEP_SHARE_START : 1.0;
    for (size_t k = 0; k < seeds.count && st == PROJCURVE_OK && !tr.limit_hit; ++k) {
        tr.progress_lo = share * (double)k / (double)seeds.count;
        tr.progress_hi = share * (double)(k + 1) / (double)seeds.count;
        st = start_branch(&tr, &seeds.items[k], SEED_AT_START);
    }
    pc_seed_list_free(&seeds);
    since = pc_stage_clock_lap(clock, PC_STAGE_TRACING, since);
    if (st == PROJCURVE_OK && opts->jump_detection && !tr.limit_hit) {
        double births = 0.0;
        st = sweep(&tr, finder, clock, &births);
        if (clock != NULL) {
            clock->seconds[PC_STAGE_TRACING] += births;
            clock->seconds[PC_STAGE_JUMPS] -= births;
        }
        since = pc_stage_clock_lap(clock, PC_STAGE_JUMPS, since);
    }
    if (st == PROJCURVE_OK && opts->jump_detection && !tr.ray && !tr.limit_hit) {
        st = search_beside_folds(&tr, finder);
        since = pc_stage_clock_lap(clock, PC_STAGE_JUMPS, since);
    }
    drop_single_points(r);
    excuse_covered_stalls(&tr, opts->tol_distance > 0.0 ? opts->tol_distance : tr.ds);
    if (tr.ray && opts->tol_distance > 0.0)
        drop_point_images(&tr, opts->tol_distance, r);
    if (st == PROJCURVE_OK && pc_budget_status(tr.budget) != PROJCURVE_OK)
        st = pc_budget_fail(tr.budget, ctx);
    else if (st == PROJCURVE_OK && tr.limit_hit)
        st = pc_fail(ctx, PROJCURVE_ERR_LIMIT_REACHED,
                     "the limit of %zu traced points was reached", tr.max_points);
    else if (st == PROJCURVE_OK && !isnan(tr.narrow_capped_at))
        st = pc_fail(ctx, PROJCURVE_ERR_LIMIT_REACHED,
                     "the jump sweep narrowed its step over small patches at %d checks, its "
                     "cap, by t = %.17g; beyond it a patch smaller than a step may be missed",
                     PC_SWEEP_MAX_NARROWED, tr.narrow_capped_at);
    return st;
}
