/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Public model functions: read a file or a buffer (io/io_read.c recognises
 * the format and hands it to its reader), give access to what was read.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/error.h"
#include "io/io_file.h"
#include "io/io_model.h"

/* Files larger than this are refused rather than read into memory. */
#define PC_MAX_FILE_BYTES ((size_t)1 << 30)

projcurve_status projcurve_model_read_memory(projcurve_context *ctx, const char *data, size_t len,
                                             projcurve_model **out)
{
    PC_REQUIRE(ctx, out, "out");
    PC_REQUIRE(ctx, data, "data");
    if (len > PC_MAX_FILE_BYTES)
        return pc_fail(ctx, PROJCURVE_ERR_UNSUPPORTED, "%zu bytes is more than the %zu accepted",
                       len, PC_MAX_FILE_BYTES);
    /* The readers rely on a terminating NUL (strtod and friends). */
    char *copy = malloc(len + 1);
    if (copy == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory copying %zu bytes", len);
    memcpy(copy, data, len);
    copy[len] = '\0';
    const projcurve_status st = pc_model_read_text(ctx, copy, len, out);
    free(copy);
    return st;
}

projcurve_status projcurve_model_read_file(projcurve_context *ctx, const char *path,
                                           projcurve_model **out)
{
    PC_REQUIRE(ctx, out, "out");
    PC_REQUIRE(ctx, path, "path");
    char *buf = NULL;
    size_t len = 0;
    projcurve_status st = pc_read_file(ctx, path, PC_MAX_FILE_BYTES, &buf, &len);
    if (st == PROJCURVE_OK) {
        st = pc_model_read_text(ctx, buf, len, out);
        if (st != PROJCURVE_OK && st != PROJCURVE_ERR_NO_MEMORY) {
            /* Name the file in front of the reader's message. */
            char inner[PC_MESSAGE_CAPACITY];
            snprintf(inner, sizeof inner, "%s", projcurve_context_message(ctx));
            pc_fail(ctx, st, "%s: %s", path, inner);
        }
    }
    free(buf);
    return st;
}

void projcurve_model_destroy(projcurve_model *model)
{
    pc_model_free(model);
}

size_t projcurve_model_surface_count(const projcurve_model *model)
{
    return model ? model->n_surfaces : 0;
}

size_t projcurve_model_curve_count(const projcurve_model *model)
{
    return model ? model->n_curves : 0;
}

size_t projcurve_model_skipped_count(const projcurve_model *model)
{
    return model ? model->n_skipped : 0;
}

const projcurve_surface *projcurve_model_surface(const projcurve_model *model, size_t index)
{
    return (model && index < model->n_surfaces) ? model->surfaces[index] : NULL;
}

const projcurve_curve *projcurve_model_curve(const projcurve_model *model, size_t index)
{
    return (model && index < model->n_curves) ? model->curves[index] : NULL;
}

const char *projcurve_model_skipped(const projcurve_model *model, size_t index)
{
    return (model && index < model->n_skipped) ? model->skipped[index] : NULL;
}

const char *projcurve_model_surface_kind(const projcurve_model *model, size_t index)
{
    return (model && index < model->n_surfaces) ? model->surface_kinds[index] : NULL;
}

int projcurve_model_length_unit(const projcurve_model *model, double *metres_per_unit)
{
    if (model == NULL || !model->has_length_unit)
        return 0;
    if (metres_per_unit != NULL)
        *metres_per_unit = model->metres_per_unit;
    return 1;
}

int projcurve_model_precision(const projcurve_model *model, double *precision)
{
    if (model == NULL || !model->has_precision)
        return 0;
    if (precision != NULL)
        *precision = model->precision;
    return 1;
}
