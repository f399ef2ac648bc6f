/* SPDX-License-Identifier: BSD-3-Clause */
#include "error.h"

#include <stdarg.h>
#include <stdio.h>

projcurve_status pc_fail(projcurve_context *ctx, projcurve_status status,
                         const char *fmt, ...)
{
    if (ctx == NULL || ctx->magic != PC_CONTEXT_MAGIC)
        return status;
    ctx->last_status = status;
    va_list args;
    va_start(args, fmt);
    vsnprintf(ctx->last_message, sizeof ctx->last_message, fmt, args);
    va_end(args);
    return status;
}
