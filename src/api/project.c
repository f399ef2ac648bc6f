/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve_project_directional: validation, then the tracing engine with
 * the directional equations and seed finder (trace/), then tolerance
 * control and composition (refine/) when asked.
 */
#include "api/project.h"

#include <math.h>
#include <stdlib.h>

#include "common/error.h"
#include "fit/fit.h"
#include "refine/refine.h"
#include "trace/directional.h"
#include "trace/line_seeds.h"
#include "trace/result.h"
#include "trace/trace.h"
#include "verify/verify.h"

/* Names of the option keys for messages, indexed by key (NULL: no such
 * key; the loop below skips it). */
static const char *const pc_option_names[] = {
    [PROJCURVE_OPT_TOL_DISTANCE] = "TOL_DISTANCE",
    [PROJCURVE_OPT_TOL_ANGLE_DEG] = "TOL_ANGLE_DEG",
    [PROJCURVE_OPT_NEWTON_TOL] = "NEWTON_TOL",
    [PROJCURVE_OPT_NEWTON_MAX_ITER] = "NEWTON_MAX_ITER",
    [PROJCURVE_OPT_METHOD] = "METHOD",
    [PROJCURVE_OPT_PARAM_STEP] = "PARAM_STEP",
    [PROJCURVE_OPT_ARC_STEP_FRACTION] = "ARC_STEP_FRACTION",
    [PROJCURVE_OPT_MAX_POINTS] = "MAX_POINTS",
    [PROJCURVE_OPT_MAX_PIECES] = "MAX_PIECES",
    [PROJCURVE_OPT_COMPOSE] = "COMPOSE",
    [PROJCURVE_OPT_JUMP_DETECTION] = "JUMP_DETECTION",
    [PROJCURVE_OPT_PCURVE_DEGREE] = "PCURVE_DEGREE",
    [PROJCURVE_OPT_FOOT_POINTS] = "FOOT_POINTS",
    [PROJCURVE_OPT_TIME_LIMIT] = "TIME_LIMIT",
    [PROJCURVE_OPT_MAX_WORK] = "MAX_WORK",
    [PROJCURVE_OPT_CURVE_DEGREE] = "CURVE_DEGREE"};
#define PC_OPTION_NAME_COUNT (sizeof pc_option_names / sizeof pc_option_names[0])

projcurve_status pc_options_resolve(projcurve_context *ctx, const projcurve_options *opts,
                                    struct projcurve_options *out)
{
    if (opts == NULL) {
        pc_options_defaults(out);
        return PROJCURVE_OK;
    }
    for (int key = 0; key < (int)PC_OPTION_NAME_COUNT; ++key) {
        projcurve_option_type type;
        double lo, hi, value;
        if (pc_option_names[key] == NULL ||
            projcurve_option_info(NULL, (projcurve_option)key, &type, &lo, &hi, NULL) !=
                PROJCURVE_OK)
            continue;
        if (type == PROJCURVE_OPTION_DOUBLE) {
            projcurve_options_get_double(NULL, opts, (projcurve_option)key, &value);
        } else {
            long long iv = 0;
            projcurve_options_get_int(NULL, opts, (projcurve_option)key, &iv);
            value = (double)iv;
        }
        const char *name = pc_option_names[key];
        if (!isfinite(value))
            return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "option %s is not finite", name);
        if (value < lo || value > hi)
            return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE, "option %s = %.17g is outside [%g, %g]",
                           name, value, lo, hi);
    }
    *out = *opts;
    return PROJCURVE_OK;
}

projcurve_status pc_projection_options(projcurve_context *ctx, const projcurve_options *opts,
                                       double model_size, struct projcurve_options *out)
{
    projcurve_status st = pc_options_resolve(ctx, opts, out);
    double eps_d = 0.0;
    if (st == PROJCURVE_OK)
        st = pc_options_distance_tolerance(ctx, out, model_size > 0.0 ? model_size : 1.0,
                                           &eps_d);
    if (st == PROJCURVE_OK && out->compose && out->tol_angle_deg < PC_REFINE_MIN_ANGLE_DEG)
        st = pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE,
                     "option TOL_ANGLE_DEG: %g is below %g, the smallest joint angle the "
                     "refinement can resolve (the exact tangents are known to ~1e-6 relative)",
                     out->tol_angle_deg, PC_REFINE_MIN_ANGLE_DEG);
    if (st == PROJCURVE_OK)
        out->tol_distance = eps_d;
    return st;
}

projcurve_status pc_project_fit(projcurve_context *ctx, const pc_projector *proj,
                                const struct projcurve_options *o, projcurve_result *r,
                                projcurve_status st)
{
    pc_budget_stage(o->budget, PC_PROJECT_FIT_FROM, 1.0);
    if (!o->compact)
        return st;
    const projcurve_status fs = pc_fit_result(ctx, proj, o, r);
    return fs == PROJCURVE_ERR_NO_MEMORY || (fs != PROJCURVE_OK && st == PROJCURVE_OK) ? fs : st;
}

void pc_projection_budget(pc_budget *b, struct projcurve_options *o)
{
    pc_budget_init(b, o->time_limit, (unsigned long long)o->max_work, o->progress,
                   o->progress_user);
    o->budget = b;
}

/* Parameters sampled on a callback curve to tell a point curve. */
#define PC_POINT_CURVE_SAMPLES 33

int pc_curve_is_point(const projcurve_curve *c, double tol)
{
    if (c->kind == PC_CURVE_NURBS) {
        const double *cw = c->nurbs.cw;
        const pc_vec3 first = vec3(cw[0] / cw[3], cw[1] / cw[3], cw[2] / cw[3]);
        for (size_t k = 1; k < c->nurbs.n_ctrl; ++k) {
            const double *q = cw + 4 * k;
            if (!(vec3_dist(vec3(q[0] / q[3], q[1] / q[3], q[2] / q[3]), first) <= tol))
                return 0;
        }
        return 1;
    }
    const double span = c->t1 - c->t0;
    pc_vec3 first = vec3(0.0, 0.0, 0.0);
    for (int k = 0; k < PC_POINT_CURVE_SAMPLES; ++k) {
        pc_vec3 p[2];
        const double t = c->t0 + span * (double)k / (double)(PC_POINT_CURVE_SAMPLES - 1);
        if (pc_curve_eval(c, t, 1, NULL, p) != PROJCURVE_OK)
            return 0; /* the projection reports the failing callback */
        if (k == 0)
            first = p[0];
        if (!(vec3_dist(p[0], first) <= tol && vec3_norm(p[1]) * fabs(span) <= tol))
            return 0;
    }
    return 1;
}

projcurve_status pc_refuse_point_curve(projcurve_context *ctx, const projcurve_curve *curve,
                                       const struct projcurve_options *o, double model_size)
{
    const double tol = fmax(o->newton_tol, PC_MIN_TOL_DISTANCE) * model_size;
    if (!pc_curve_is_point(curve, tol))
        return PROJCURVE_OK;
    pc_vec3 p;
    pc_curve_eval(curve, curve->t0, 0, NULL, &p);
    return pc_fail(ctx, PROJCURVE_ERR_SINGULAR,
                   "the curve is the point (%.17g, %.17g, %.17g) to %g (the model's precision): "
                   "project it as a point (projcurve_surface_intersect_line, "
                   "projcurve_surface_foot_points)",
                   p.x, p.y, p.z, tol);
}

/* Unit direction from dir; statuses NOT_FINITE, ZERO_DIRECTION. Scaling by
 * the largest component first keeps tiny and huge vectors normalisable. */
static projcurve_status unit_direction(projcurve_context *ctx, const double dir[3],
                                       pc_vec3 *out)
{
    const pc_vec3 d = vec3_load(dir);
    if (!vec3_is_finite(d))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE,
                       "direction (%g, %g, %g) is not finite", d.x, d.y, d.z);
    const double m = fmax(fabs(d.x), fmax(fabs(d.y), fabs(d.z)));
    if (!(m > 0.0))
        return pc_fail(ctx, PROJCURVE_ERR_ZERO_DIRECTION, "direction is the zero vector");
    *out = vec3_normalize(vec3(d.x / m, d.y / m, d.z / m));
    return PROJCURVE_OK;
}

projcurve_status projcurve_project_directional(projcurve_context *ctx,
                                               const projcurve_surface *surface,
                                               const projcurve_curve *curve,
                                               const double dir[3],
                                               const projcurve_options *opts,
                                               projcurve_result **out)
{
    PC_REQUIRE(ctx, surface, "surface");
    PC_REQUIRE(ctx, curve, "curve");
    PC_REQUIRE(ctx, dir, "dir");
    PC_REQUIRE(ctx, out, "out");
    pc_vec3 unit;
    struct projcurve_options o;
    projcurve_status st = unit_direction(ctx, dir, &unit);
    if (st == PROJCURVE_OK)
        st = pc_projection_options(ctx, opts, surface->size, &o);
    if (st == PROJCURVE_OK)
        st = pc_refuse_point_curve(ctx, curve, &o, surface->size);
    if (st != PROJCURVE_OK)
        return st;

    pc_budget budget;
    pc_projection_budget(&budget, &o);
    pc_budget_stage(&budget, 0.0, o.compose ? 0.5 : 1.0);
    pc_projector proj;
    pc_directional_data data;
    pc_directional_cache cache;
    pc_directional_init(&proj, &data, &cache, surface, curve, unit, o.newton_tol,
                        (int)o.newton_max_iter);
    /* the bounds of the spans visited, kept for the whole call (without
     * the memory, one span's only: slower, same result) */
    const size_t slots = pc_span_bound_table_slots(&surface->nurbs);
    pc_span_bound_entry *bound_table = slots > 1 ? calloc(slots, sizeof *bound_table) : NULL;
    pc_directional_use_bound_table(&cache, bound_table, slots);
    pc_line_finder finder;
    pc_line_finder_init(&finder, &proj, unit);
    projcurve_result *r = NULL;
    st = pc_result_create(ctx, 3, &r);
    if (st == PROJCURVE_OK) {
        /* the arc-length step is needed for stepping and for the jump
         * sweep; constant parameter steps without jumps do without it */
        const int need_length = o.param_step == 0.0 || o.jump_detection;
        const pc_trace_config config = {
            need_length ? pc_directional_length_estimate(&finder) : 0.0, proj.model_size, 1,
            unit};
        r->stats.tol_distance = o.tol_distance;
        st = pc_trace_branches(ctx, &proj, &o, &finder.base, &config, r);
    }
    /* tolerance control and composition also on a result cut by
     * MAX_POINTS; not once the budget is spent (the traced polylines stay) */
    if (o.compose && (st == PROJCURVE_OK || st == PROJCURVE_ERR_LIMIT_REACHED) &&
        pc_budget_status(&budget) == PROJCURVE_OK) {
        pc_budget_stage(&budget, 0.5, PC_PROJECT_FIT_FROM);
        const projcurve_status cs = pc_refine_and_compose(ctx, &proj, &o, r);
        if (cs != PROJCURVE_OK)
            st = cs;
    }
    /* only verified branches are returned, also from a partial result */
    if (pc_status_keeps_result(st)) {
        const projcurve_status vs = pc_verify_result(ctx, &proj, &o, r);
        if (vs != PROJCURVE_OK)
            st = vs;
    }
    if (o.compose && pc_status_keeps_result(st))
        st = pc_project_fit(ctx, &proj, &o, r, st);
    if (cache.callback_failed && pc_status_keeps_result(st))
        st = pc_fail(ctx, PROJCURVE_ERR_CALLBACK, "the curve callback failed during tracing");
    if (finder.no_memory && (st == PROJCURVE_OK || st == PROJCURVE_ERR_LIMIT_REACHED))
        st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for the control-polygon hits");
    pc_line_finder_free(&finder);
    free(bound_table);
    if (st == PROJCURVE_OK)
        pc_budget_finish(&budget);
    if (!pc_status_keeps_result(st)) {
        projcurve_result_destroy(r);
        return st;
    }
    *out = r;
    return st;
}
