/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The generic tracing engine ([SY13] s3): it follows every branch of a
 * projection curve q(t) = (u(t), v(t)) with a predictor (second-order Taylor,
 * [SY13] eq. (3.5), or classical RK4 on q' for the first-order baseline of
 * the paper's reference [16]) and the projector's Newton corrector, with a
 * constant arc-length (or constant parameter) step. It knows nothing of the
 * kind of projection: the equations come from a pc_projector, the points
 * where branches start come from a pc_seed_finder.
 *
 * Branches are traced one at a time, forward in t, and a sweep over t then
 * looks for branches born in mid-curve ([SY13] s3.4): at each check the
 * finder's cheap test decides whether a full search is needed, every point
 * found is matched to the active branches within the arc-length step, and
 * each unmatched point starts a new branch, traced back to where it was born
 * (a boundary entry or a fold) and forward to its end.
 */
#ifndef PC_TRACE_TRACE_H
#define PC_TRACE_TRACE_H

#include <stddef.h>

#include "common/params.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "trace/projector.h"
#include "trace/result.h"

/* A point of the projection at curve parameter t: (u, v) satisfies the
 * projection equations to the corrector's tolerance. */
typedef struct pc_seed {
    double t, u, v;
} pc_seed;

/* A growable list of seeds owned by the caller (pc_seed_list_free). */
typedef struct pc_seed_list {
    pc_seed *items;
    size_t count, capacity;
} pc_seed_list;

projcurve_status pc_seed_list_push(projcurve_context *ctx, pc_seed_list *list, double t,
                                   double u, double v);
void pc_seed_list_free(pc_seed_list *list);

/* What a kind of projection tells the engine about where branches are.
 *
 * find: clears `out` and fills it with every point of the projection at
 *   curve parameter t (directional: the hits of the ray P(t) + lambda Dir,
 *   lambda > 0; orthogonal: the foot points of P(t)). Returns OK, NO_MEMORY
 *   or CALLBACK.
 *
 * may_jump (may be NULL: a full find at every check): the cheap test run at
 *   each check of the sweep, [SY13] s3.4. `active` holds the current point
 *   of every branch alive at t (n_active may be 0); ds is the arc-length
 *   step. Returns 1 when a branch may have been born (or lost) since the
 *   previous call, so that find must run at t. The finder may keep state
 *   between calls (the previous line's control-polygon hits); the engine
 *   calls it with increasing t and calls reset before a new sweep.
 *
 * reset (may be NULL): forgets the state of may_jump.
 *
 * step_may_skip (may be NULL: the sweep's steps are never narrowed): 1
 *   when the rays of the curve over [ta, tb] (ta the last check, tb the
 *   next one) may meet a patch that neither end's ray meets and that no
 *   traced branch crosses over [ta, tb] (trail): a patch the step would
 *   jump over. The sweep then halves the step (docs/tracing.md, "Small
 *   patches between two checks"). It must be cheap (box tests), keep no
 *   state, and answer 0 where it cannot bound the curve.
 */
typedef struct pc_seed_finder pc_seed_finder;

/* The traced branches over a stretch [ta, tb] of t, as the sweep shows
 * them to step_may_skip: crosses says whether some branch's polyline over
 * [ta, tb] passes through the (u, v) rectangle uv = {u0, u1, v0, v1}. */
typedef struct pc_sweep_trail pc_sweep_trail;
struct pc_sweep_trail {
    int (*crosses)(const pc_sweep_trail *self, const double uv[4]);
    const void *data;
    double ta, tb;
};

struct pc_seed_finder {
    projcurve_status (*find)(pc_seed_finder *self, projcurve_context *ctx, double t,
                             pc_seed_list *out);
    int (*may_jump)(pc_seed_finder *self, double t, const pc_seed *active, size_t n_active,
                    double ds);
    void (*reset)(pc_seed_finder *self);
    int (*step_may_skip)(pc_seed_finder *self, double ta, double tb,
                         const pc_sweep_trail *trail);
    void *state;
};

/* Settings of one tracing run, derived from the parameters by the caller. */
typedef struct pc_trace_config {
    /* Estimated total arc length of the projection ([SY13] s3.3); the
     * arc-length step is opts->arc_step_fraction times it. <= 0: the
     * engine uses the length of the curve's control polygon. */
    double length_estimate;
    /* Scale for the engine's own tolerances (surface size). */
    double model_size;
    /* ray != 0 (directional, conical): the projection's points are those
     * of F = 0 in front of the curve, (S - P).dir >= 0 with dir the unit
     * ray direction (the projector's ray_dir at each point when it has
     * one, else this dir); a branch ends where the curve meets S and one
     * is born there (PROJCURVE_END/START_CURVE_CROSSING). */
    int ray;
    pc_vec3 dir;
} pc_trace_config;

/* Traces every branch of the projection defined by proj over the whole
 * curve domain into r (points (t, u, v), r->point_dim == 3), fills
 * r->stats (points, steps, Newton iterations, estimation error (3.8),
 * jumps). Seeds at the start of the curve come from finder->find; with
 * opts->jump_detection the sweep described above adds branches born in
 * mid-curve. opts->method selects the predictor, opts->param_step the
 * constant parameter step (0 = arc-length step), opts->max_points bounds
 * the total number of vertices.
 * opts->budget (may be NULL) is polled once per step and per sweep check.
 * Statuses: OK; LIMIT_REACHED (max_points, or the budget's time or work
 * limit: the branches traced so far are kept, the one cut ends with
 * PROJCURVE_END_LIMIT; or the sweep narrowed its step at
 * PC_SWEEP_MAX_NARROWED checks and swept the rest without narrowing: all
 * branches kept, a patch smaller than a step beyond may be missed);
 * CANCELLED (the budget's progress callback, the
 * same partial result); NO_MEMORY; CALLBACK. */
projcurve_status pc_trace_branches(projcurve_context *ctx, const pc_projector *proj,
                                   const pc_params *opts,
                                   pc_seed_finder *finder, const pc_trace_config *config,
                                   projcurve_result *r);

#endif /* PC_TRACE_TRACE_H */
