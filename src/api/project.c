/*
 * projcurve_project_directional: validation, then the tracing engine with
 * the directional equations and seed finder (trace/), then tolerance
 * control and composition (refine/) when asked.
 */
#include "api/project.h"

#include <math.h>
#include <stdlib.h>

#include "common/error.h"
#include "refine/refine.h"
#include "trace/directional.h"
#include "trace/line_seeds.h"
#include "trace/result.h"
#include "trace/trace.h"

/* Names of the option keys for messages, indexed by key. */
static const char *const pc_option_names[] = {
    "?", "TOL_DISTANCE", "TOL_ANGLE_DEG", "NEWTON_TOL", "NEWTON_MAX_ITER", "METHOD",
    "PARAM_STEP", "ARC_STEP_FRACTION", "MAX_POINTS", "MAX_PIECES", "COMPOSE",
    "JUMP_DETECTION", "PCURVE_DEGREE"};

projcurve_status pc_options_resolve(projcurve_context *ctx, const projcurve_options *opts,
                                    struct projcurve_options *out)
{
    if (opts == NULL) {
        pc_options_defaults(out);
        return PROJCURVE_OK;
    }
    for (int key = PROJCURVE_OPT_TOL_DISTANCE; key <= PROJCURVE_OPT_PCURVE_DEGREE; ++key) {
        projcurve_option_type type;
        double lo, hi, value;
        if (projcurve_option_info(NULL, (projcurve_option)key, &type, &lo, &hi, NULL) !=
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
    if (st == PROJCURVE_OK)
        out->tol_distance = eps_d;
    return st;
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
    if (st != PROJCURVE_OK)
        return st;

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
    /* tolerance control and composition also on a partial result */
    if (o.compose && (st == PROJCURVE_OK || st == PROJCURVE_ERR_LIMIT_REACHED)) {
        const projcurve_status cs = pc_refine_and_compose(ctx, &proj, &o, r);
        if (cs != PROJCURVE_OK)
            st = cs;
    }
    if (cache.callback_failed && (st == PROJCURVE_OK || st == PROJCURVE_ERR_LIMIT_REACHED))
        st = pc_fail(ctx, PROJCURVE_ERR_CALLBACK, "the curve callback failed during tracing");
    if (finder.no_memory && (st == PROJCURVE_OK || st == PROJCURVE_ERR_LIMIT_REACHED))
        st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for the control-polygon hits");
    pc_line_finder_free(&finder);
    free(bound_table);
    if (st != PROJCURVE_OK && st != PROJCURVE_ERR_LIMIT_REACHED) {
        projcurve_result_destroy(r);
        return st;
    }
    *out = r;
    return st;
}
