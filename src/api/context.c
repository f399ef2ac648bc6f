/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Contexts: where the last failure of a call is recorded (status + message).
 *
 * A context holds no other state than that and its size limits, so a
 * context per thread makes every call thread-safe; nothing global is touched. Messages are written only by
 * pc_fail (src/common/error.c).
 */
#include "common/error.h"
#include "projcurve.h"

#include <stdlib.h>

projcurve_status projcurve_context_create(unsigned abi_major, projcurve_context **out)
{
    if (out == NULL)
        return PROJCURVE_ERR_NULL_ARGUMENT;
    /* A caller compiled against another major version would disagree with
     * us about the meaning of the API: refuse before handing out anything. */
    if (abi_major != (unsigned)PROJCURVE_VERSION_MAJOR)
        return PROJCURVE_ERR_VERSION;
    projcurve_context *ctx = calloc(1, sizeof *ctx);
    if (ctx == NULL)
        return PROJCURVE_ERR_NO_MEMORY;
    ctx->magic = PC_CONTEXT_MAGIC;
    ctx->last_status = PROJCURVE_OK;
    ctx->last_message[0] = '\0';
    ctx->max_control_points = PROJCURVE_DEFAULT_MAX_CONTROL_POINTS;
    *out = ctx;
    return PROJCURVE_OK;
}

void projcurve_context_destroy(projcurve_context *ctx)
{
    if (ctx == NULL)
        return;
    ctx->magic = 0; /* a stale pointer passed to pc_fail then records nothing */
    free(ctx);
}

const char *projcurve_context_message(const projcurve_context *ctx)
{
    if (ctx == NULL)
        return "no context";
    if (ctx->magic != PC_CONTEXT_MAGIC)
        return "invalid context";
    return ctx->last_message;
}

projcurve_status projcurve_context_status(const projcurve_context *ctx)
{
    if (ctx == NULL)
        return PROJCURVE_ERR_NULL_ARGUMENT;
    if (ctx->magic != PC_CONTEXT_MAGIC)
        return PROJCURVE_ERR_INVALID_ARGUMENT;
    return ctx->last_status;
}

void projcurve_context_clear(projcurve_context *ctx)
{
    if (ctx == NULL || ctx->magic != PC_CONTEXT_MAGIC)
        return;
    ctx->last_status = PROJCURVE_OK;
    ctx->last_message[0] = '\0';
}

/* The smallest limit that still lets a curve (degree 1, 2 points) exist. */
#define PC_MIN_CONTROL_POINTS_LIMIT 2

projcurve_status projcurve_context_set_limit(projcurve_context *ctx, projcurve_limit limit,
                                             size_t value)
{
    if (ctx == NULL || ctx->magic != PC_CONTEXT_MAGIC)
        return PROJCURVE_ERR_NULL_ARGUMENT;
    if (limit != PROJCURVE_LIMIT_CONTROL_POINTS)
        return pc_fail(ctx, PROJCURVE_ERR_UNKNOWN_OPTION, "unknown limit %d", (int)limit);
    if (value < PC_MIN_CONTROL_POINTS_LIMIT)
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE,
                       "limit CONTROL_POINTS: %zu is below %d (the smallest curve)", value,
                       PC_MIN_CONTROL_POINTS_LIMIT);
    ctx->max_control_points = value;
    return PROJCURVE_OK;
}

projcurve_status projcurve_context_get_limit(projcurve_context *ctx, projcurve_limit limit,
                                             size_t *value)
{
    PC_REQUIRE(ctx, value, "value");
    if (limit != PROJCURVE_LIMIT_CONTROL_POINTS)
        return pc_fail(ctx, PROJCURVE_ERR_UNKNOWN_OPTION, "unknown limit %d", (int)limit);
    *value = pc_context_max_control_points(ctx);
    return PROJCURVE_OK;
}
