/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Options: an opaque handle of typed values, each with bounds and a default.
 *
 * One table describes every option (type, bounds, default, where it lives in
 * struct projcurve_options); the setters, getters, projcurve_option_info,
 * pc_options_defaults and pc_options_check all read it, so the bounds
 * documented in projcurve.h are stated exactly once in code (the defaults
 * of the engine's parameters come from common/params.h). A setter validates before it writes:
 * on any failure the handle is unchanged.
 */
#include "api/options.h"
#include "common/error.h"
#include "projcurve.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>

/* Largest value of the size limits: 2^40, exactly representable as double. */
#define PC_OPTION_SIZE_LIMIT 1099511627776.0
/* Upper bound of lengths in model units: finite, far above any model. */
#define PC_OPTION_LENGTH_LIMIT 1e300
/* Upper bound of the time limit, seconds (~32 years): large enough to mean
 * "none", small enough that start + limit stays exact to microseconds. */
#define PC_OPTION_TIME_LIMIT 1e9

typedef struct pc_option_desc {
    projcurve_option key;
    const char *name;           /* for messages */
    projcurve_option_type type;
    double min_value, max_value; /* inclusive unless min_exclusive */
    int min_exclusive;          /* the lower bound itself is rejected */
    double default_value;
    size_t offset;              /* of the double or long long field */
} pc_option_desc;

#define PC_FIELD(field) offsetof(struct projcurve_options, field)

static const pc_option_desc pc_option_table[] = {
    /* the default 0 is no value a caller can set: it marks eps_D as unset,
     * which the projection resolves to 1e-4 of the model size */
    {PROJCURVE_OPT_TOL_DISTANCE, "TOL_DISTANCE", PROJCURVE_OPTION_DOUBLE,
     0.0, PC_OPTION_LENGTH_LIMIT, 1, PC_DEFAULT_TOL_DISTANCE, PC_FIELD(tol_distance)},
    {PROJCURVE_OPT_TOL_ANGLE_DEG, "TOL_ANGLE_DEG", PROJCURVE_OPTION_DOUBLE,
     0.0, 90.0, 1, PC_DEFAULT_TOL_ANGLE_DEG, PC_FIELD(tol_angle_deg)},
    {PROJCURVE_OPT_NEWTON_TOL, "NEWTON_TOL", PROJCURVE_OPTION_DOUBLE,
     1e-15, 1e-3, 0, PC_DEFAULT_NEWTON_TOL, PC_FIELD(newton_tol)},
    {PROJCURVE_OPT_NEWTON_MAX_ITER, "NEWTON_MAX_ITER", PROJCURVE_OPTION_INTEGER,
     1.0, 200.0, 0, PC_DEFAULT_NEWTON_MAX_ITER, PC_FIELD(newton_max_iter)},
    {PROJCURVE_OPT_METHOD, "METHOD", PROJCURVE_OPTION_INTEGER,
     (double)PROJCURVE_METHOD_SECOND_ORDER, (double)PROJCURVE_METHOD_RK4, 0,
     (double)PC_DEFAULT_METHOD, PC_FIELD(method)},
    {PROJCURVE_OPT_PARAM_STEP, "PARAM_STEP", PROJCURVE_OPTION_DOUBLE,
     0.0, PC_OPTION_LENGTH_LIMIT, 0, PC_DEFAULT_PARAM_STEP, PC_FIELD(param_step)},
    {PROJCURVE_OPT_ARC_STEP_FRACTION, "ARC_STEP_FRACTION", PROJCURVE_OPTION_DOUBLE,
     1e-7, 1.0, 0, PC_DEFAULT_ARC_STEP_FRACTION, PC_FIELD(arc_step_fraction)},
    {PROJCURVE_OPT_MAX_POINTS, "MAX_POINTS", PROJCURVE_OPTION_INTEGER,
     16.0, PC_OPTION_SIZE_LIMIT, 0, PC_DEFAULT_MAX_POINTS, PC_FIELD(max_points)},
    {PROJCURVE_OPT_MAX_PIECES, "MAX_PIECES", PROJCURVE_OPTION_INTEGER,
     1.0, PC_OPTION_SIZE_LIMIT, 0, PC_DEFAULT_MAX_PIECES, PC_FIELD(max_pieces)},
    {PROJCURVE_OPT_COMPOSE, "COMPOSE", PROJCURVE_OPTION_INTEGER,
     0.0, 1.0, 0, PC_DEFAULT_COMPOSE, PC_FIELD(compose)},
    {PROJCURVE_OPT_JUMP_DETECTION, "JUMP_DETECTION", PROJCURVE_OPTION_INTEGER,
     0.0, 1.0, 0, PC_DEFAULT_JUMP_DETECTION, PC_FIELD(jump_detection)},
    {PROJCURVE_OPT_PCURVE_DEGREE, "PCURVE_DEGREE", PROJCURVE_OPTION_INTEGER,
     1.0, 3.0, 0, PC_DEFAULT_PCURVE_DEGREE, PC_FIELD(pcurve_degree)},
    {PROJCURVE_OPT_FOOT_POINTS, "FOOT_POINTS", PROJCURVE_OPTION_INTEGER,
     (double)PROJCURVE_FOOT_POINTS_MINIMA, (double)PROJCURVE_FOOT_POINTS_ALL, 0,
     (double)PC_DEFAULT_FOOT_POINTS, PC_FIELD(foot_points)},
    {PROJCURVE_OPT_TIME_LIMIT, "TIME_LIMIT", PROJCURVE_OPTION_DOUBLE,
     0.0, PC_OPTION_TIME_LIMIT, 0, 0.0, PC_FIELD(time_limit)},
    {PROJCURVE_OPT_MAX_WORK, "MAX_WORK", PROJCURVE_OPTION_INTEGER,
     0.0, PC_OPTION_SIZE_LIMIT, 0, 0.0, PC_FIELD(max_work)},
    {PROJCURVE_OPT_CURVE_DEGREE, "CURVE_DEGREE", PROJCURVE_OPTION_INTEGER,
     1.0, 25.0, 0, PC_DEFAULT_CURVE_DEGREE, PC_FIELD(curve_degree)},
    {PROJCURVE_OPT_HITS, "HITS", PROJCURVE_OPTION_INTEGER,
     (double)PROJCURVE_HITS_ALL, (double)PROJCURVE_HITS_NEAREST, 0, (double)PC_DEFAULT_HITS,
     PC_FIELD(hits)},
    {PROJCURVE_OPT_MAX_DISTANCE, "MAX_DISTANCE", PROJCURVE_OPTION_DOUBLE,
     0.0, PC_OPTION_LENGTH_LIMIT, 0, PC_DEFAULT_MAX_DISTANCE, PC_FIELD(max_distance)},
    /* one worker per curve at most; 1024 bounds the threads a call starts */
    {PROJCURVE_OPT_THREADS, "THREADS", PROJCURVE_OPTION_INTEGER,
     1.0, 1024.0, 0, PC_DEFAULT_THREADS, PC_FIELD(threads)},
};

/* Integer options whose bounds admit values that mean nothing: the values
 * allowed (bounds from the table above still apply). */
typedef struct pc_option_choices {
    projcurve_option key;
    long long values[2];
    size_t count;
} pc_option_choices;

static const pc_option_choices pc_option_choice_table[] = {
    {PROJCURVE_OPT_PCURVE_DEGREE, {1, 3}, 2}, /* straight or cubic Hermite pcurves */
};

/* Double options whose 0 means "no limit": their setter also takes +inf
 * for it, and stores 0. */
static const projcurve_option pc_option_infinity_is_zero[] = {PROJCURVE_OPT_MAX_DISTANCE};

static int pc_option_takes_infinity(projcurve_option key)
{
    for (size_t i = 0; i < sizeof pc_option_infinity_is_zero / sizeof *pc_option_infinity_is_zero;
         ++i)
        if (pc_option_infinity_is_zero[i] == key)
            return 1;
    return 0;
}

#define PC_OPTION_CHOICE_COUNT (sizeof pc_option_choice_table / sizeof pc_option_choice_table[0])

/* 1 when value is one of key's choices, or key has no list of choices. */
static int pc_option_value_allowed(projcurve_option key, long long value)
{
    for (size_t i = 0; i < PC_OPTION_CHOICE_COUNT; ++i) {
        const pc_option_choices *c = &pc_option_choice_table[i];
        if (c->key != key)
            continue;
        for (size_t k = 0; k < c->count; ++k)
            if (c->values[k] == value)
                return 1;
        return 0;
    }
    return 1;
}

#define PC_OPTION_COUNT (sizeof pc_option_table / sizeof pc_option_table[0])

/* The descriptor of key, or NULL (and a recorded failure) if unknown. */
static const pc_option_desc *pc_option_find(projcurve_context *ctx, projcurve_option key)
{
    for (size_t i = 0; i < PC_OPTION_COUNT; ++i)
        if (pc_option_table[i].key == key)
            return &pc_option_table[i];
    pc_fail(ctx, PROJCURVE_ERR_UNKNOWN_OPTION, "unknown option key %d", (int)key);
    return NULL;
}

static double *pc_option_double(struct projcurve_options *o, const pc_option_desc *d)
{
    return (double *)(void *)((char *)o + d->offset);
}

static long long *pc_option_int(struct projcurve_options *o, const pc_option_desc *d)
{
    return (long long *)(void *)((char *)o + d->offset);
}

static const double *pc_option_double_c(const struct projcurve_options *o,
                                        const pc_option_desc *d)
{
    return (const double *)(const void *)((const char *)o + d->offset);
}

static const long long *pc_option_int_c(const struct projcurve_options *o,
                                        const pc_option_desc *d)
{
    return (const long long *)(const void *)((const char *)o + d->offset);
}

/* Looks key up and checks that it has the expected type. */
static projcurve_status pc_option_lookup(projcurve_context *ctx, projcurve_option key,
                                         projcurve_option_type type,
                                         const pc_option_desc **out)
{
    const pc_option_desc *d = pc_option_find(ctx, key);
    if (d == NULL)
        return PROJCURVE_ERR_UNKNOWN_OPTION;
    if (d->type != type)
        return pc_fail(ctx, PROJCURVE_ERR_WRONG_KIND, "option %s is of type %s, not %s",
                       d->name, d->type == PROJCURVE_OPTION_DOUBLE ? "double" : "integer",
                       type == PROJCURVE_OPTION_DOUBLE ? "double" : "integer");
    *out = d;
    return PROJCURVE_OK;
}

void pc_options_defaults(struct projcurve_options *o)
{
    for (size_t i = 0; i < PC_OPTION_COUNT; ++i) {
        const pc_option_desc *d = &pc_option_table[i];
        if (d->type == PROJCURVE_OPTION_DOUBLE)
            *pc_option_double(o, d) = d->default_value;
        else
            *pc_option_int(o, d) = (long long)d->default_value;
    }
    o->compact = 1;
    o->progress = NULL;
    o->progress_user = NULL;
}

/* The value of option d in o, as a double (integer bounds are at most 2^40,
 * exact in a double). */
static double pc_option_value(const struct projcurve_options *o, const pc_option_desc *d)
{
    return d->type == PROJCURVE_OPTION_DOUBLE ? *pc_option_double_c(o, d)
                                              : (double)*pc_option_int_c(o, d);
}

projcurve_status pc_options_check(projcurve_context *ctx, const struct projcurve_options *o)
{
    for (size_t i = 0; i < PC_OPTION_COUNT; ++i) {
        const pc_option_desc *d = &pc_option_table[i];
        const double value = pc_option_value(o, d);
        if (!isfinite(value))
            return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "option %s is not finite", d->name);
        if (value < d->min_value || value > d->max_value)
            return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE,
                           "option %s = %.17g is outside [%g, %g]", d->name, value,
                           d->min_value, d->max_value);
    }
    return PROJCURVE_OK;
}

void pc_options_to_params(const struct projcurve_options *o, pc_params *p)
{
    pc_params_defaults(p);
#define PC_COPY_FIELD(type, field) p->field = o->field;
    PC_PARAMS_OPTIONS(PC_COPY_FIELD)
#undef PC_COPY_FIELD
    p->compact = o->compact != 0;
}

projcurve_status projcurve_options_create(projcurve_context *ctx, projcurve_options **out)
{
    PC_REQUIRE(ctx, out, "out");
    projcurve_options *o = malloc(sizeof *o);
    if (o == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "cannot allocate options");
    pc_options_defaults(o);
    *out = o;
    return PROJCURVE_OK;
}

void projcurve_options_destroy(projcurve_options *opts) { free(opts); }

projcurve_status projcurve_option_info(projcurve_context *ctx, projcurve_option key,
                                       projcurve_option_type *type, double *min_value,
                                       double *max_value, double *default_value)
{
    const pc_option_desc *d = pc_option_find(ctx, key);
    if (d == NULL)
        return PROJCURVE_ERR_UNKNOWN_OPTION;
    if (type != NULL)
        *type = d->type;
    if (min_value != NULL)
        *min_value = d->min_value;
    if (max_value != NULL)
        *max_value = d->max_value;
    if (default_value != NULL)
        *default_value = d->default_value;
    return PROJCURVE_OK;
}

projcurve_status projcurve_options_set_double(projcurve_context *ctx, projcurve_options *opts,
                                              projcurve_option key, double value)
{
    PC_REQUIRE(ctx, opts, "options");
    const pc_option_desc *d = NULL;
    const projcurve_status s = pc_option_lookup(ctx, key, PROJCURVE_OPTION_DOUBLE, &d);
    if (s != PROJCURVE_OK)
        return s;
    if (value == INFINITY && pc_option_takes_infinity(key))
        value = 0.0; /* "no limit", stored as its 0 */
    if (!isfinite(value))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "option %s: value %g is not finite",
                       d->name, value);
    const int below = d->min_exclusive ? value <= d->min_value : value < d->min_value;
    if (below || value > d->max_value)
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE, "option %s: %.17g is outside %c%g, %g]",
                       d->name, value, d->min_exclusive ? '(' : '[', d->min_value,
                       d->max_value);
    *pc_option_double(opts, d) = value;
    return PROJCURVE_OK;
}

projcurve_status projcurve_options_set_int(projcurve_context *ctx, projcurve_options *opts,
                                           projcurve_option key, long long value)
{
    PC_REQUIRE(ctx, opts, "options");
    const pc_option_desc *d = NULL;
    const projcurve_status s = pc_option_lookup(ctx, key, PROJCURVE_OPTION_INTEGER, &d);
    if (s != PROJCURVE_OK)
        return s;
    /* Integer bounds are at most 2^40, so comparing in long long is exact. */
    const long long lo = (long long)d->min_value, hi = (long long)d->max_value;
    if (value < lo || value > hi)
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE, "option %s: %lld is outside [%lld, %lld]",
                       d->name, value, lo, hi);
    if (!pc_option_value_allowed(key, value))
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE, "option %s: %lld is not one of the allowed values",
                       d->name, value);
    *pc_option_int(opts, d) = value;
    return PROJCURVE_OK;
}

projcurve_status projcurve_options_get_double(projcurve_context *ctx,
                                              const projcurve_options *opts,
                                              projcurve_option key, double *value)
{
    PC_REQUIRE(ctx, opts, "options");
    PC_REQUIRE(ctx, value, "value");
    const pc_option_desc *d = NULL;
    const projcurve_status s = pc_option_lookup(ctx, key, PROJCURVE_OPTION_DOUBLE, &d);
    if (s != PROJCURVE_OK)
        return s;
    *value = *pc_option_double_c(opts, d);
    return PROJCURVE_OK;
}

projcurve_status projcurve_options_get_int(projcurve_context *ctx,
                                           const projcurve_options *opts,
                                           projcurve_option key, long long *value)
{
    PC_REQUIRE(ctx, opts, "options");
    PC_REQUIRE(ctx, value, "value");
    const pc_option_desc *d = NULL;
    const projcurve_status s = pc_option_lookup(ctx, key, PROJCURVE_OPTION_INTEGER, &d);
    if (s != PROJCURVE_OK)
        return s;
    *value = *pc_option_int_c(opts, d);
    return PROJCURVE_OK;
}

projcurve_status projcurve_options_set_progress(projcurve_context *ctx, projcurve_options *opts,
                                                projcurve_progress_fn fn, void *user)
{
    PC_REQUIRE(ctx, opts, "options");
    opts->progress = fn;
    opts->progress_user = fn != NULL ? user : NULL;
    return PROJCURVE_OK;
}

projcurve_status projcurve_options_get_progress(projcurve_context *ctx,
                                                const projcurve_options *opts,
                                                projcurve_progress_fn *fn, void **user)
{
    PC_REQUIRE(ctx, opts, "options");
    if (fn != NULL)
        *fn = opts->progress;
    if (user != NULL)
        *user = opts->progress_user;
    return PROJCURVE_OK;
}
