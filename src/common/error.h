/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Error recording shared by every module.
 *
 * A failure is recorded once, where it is detected, with a status and a
 * message that names the offending value ("knot vector u decreases at index
 * 7"). Internal functions that can fail take the caller's context (which may
 * be NULL: then only the status travels) and return the status they record.
 */
#ifndef PC_COMMON_ERROR_H
#define PC_COMMON_ERROR_H

#include <stddef.h>

#include "projcurve.h"

#define PC_MESSAGE_CAPACITY 512

struct projcurve_context {
    unsigned magic;               /* PC_CONTEXT_MAGIC while alive */
    projcurve_status last_status; /* status of the last failure, OK if none */
    char last_message[PC_MESSAGE_CAPACITY];
    size_t max_control_points;    /* PROJCURVE_LIMIT_CONTROL_POINTS */
};

#define PC_CONTEXT_MAGIC 0x70637478u /* "pctx" */

#if defined(__GNUC__)
#define PC_PRINTF(fmt_index, arg_index) __attribute__((format(printf, fmt_index, arg_index)))
#else
#define PC_PRINTF(fmt_index, arg_index)
#endif

/* Records status and a printf-style message in ctx (if not NULL) and returns
 * status, so that error paths read `return pc_fail(ctx, ..., "...")`. */
projcurve_status pc_fail(projcurve_context *ctx, projcurve_status status,
                         const char *fmt, ...) PC_PRINTF(3, 4);

/* The PROJCURVE_LIMIT_CONTROL_POINTS of ctx (the default for a NULL or
 * invalid one). */
static inline size_t pc_context_max_control_points(const projcurve_context *ctx)
{
    return ctx != NULL && ctx->magic == PC_CONTEXT_MAGIC ? ctx->max_control_points
                                                         : (size_t)PROJCURVE_DEFAULT_MAX_CONTROL_POINTS;
}

/* Checks that a required pointer is not NULL; `what` names it in the message. */
#define PC_REQUIRE(ctx, ptr, what)                                                  \
    do {                                                                            \
        if ((ptr) == NULL)                                                          \
            return pc_fail((ctx), PROJCURVE_ERR_NULL_ARGUMENT, "%s is NULL", (what)); \
    } while (0)

#endif /* PC_COMMON_ERROR_H */
