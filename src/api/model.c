/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Public model functions: read a file or a buffer, recognise the format,
 * hand it to its reader, give access to what was read.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/error.h"
#include "io/io_model.h"

/* Files larger than this are refused rather than read into memory. */
#define PC_MAX_FILE_BYTES ((size_t)1 << 30)
#define PC_READ_CHUNK ((size_t)1 << 20)

static projcurve_status read_text(projcurve_context *ctx, const char *data, size_t len,
                                  projcurve_model **out)
{
    projcurve_model *model = pc_model_new();
    if (model == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory creating a model");
    projcurve_status st;
    switch (pc_detect_format(data, len)) {
    case PC_FORMAT_IGES: st = pc_iges_read(ctx, data, len, model); break;
    case PC_FORMAT_STEP: st = pc_step_read(ctx, data, len, model); break;
    case PC_FORMAT_GISMO: st = pc_gismo_read(ctx, data, len, model); break;
    case PC_FORMAT_TEAPOT: st = pc_teapot_read(ctx, data, len, model); break;
    default:
        st = pc_fail(ctx, PROJCURVE_ERR_PARSE,
                     "unrecognised file format (not IGES, STEP, G+Smo XML or Newell teapot text)");
    }
    if (st == PROJCURVE_OK && model->n_skipped_unlisted > 0)
        st = pc_model_note_unlisted(ctx, model);
    if (st != PROJCURVE_OK) {
        pc_model_free(model);
        return st;
    }
    *out = model;
    return PROJCURVE_OK;
}

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
    const projcurve_status st = read_text(ctx, copy, len, out);
    free(copy);
    return st;
}

projcurve_status projcurve_model_read_file(projcurve_context *ctx, const char *path,
                                           projcurve_model **out)
{
    PC_REQUIRE(ctx, out, "out");
    PC_REQUIRE(ctx, path, "path");
    FILE *fp = fopen(path, "rb");
    if (fp == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_IO, "cannot open %s: %s", path, strerror(errno));
    char *buf = NULL;
    size_t len = 0, cap = 0;
    projcurve_status st = PROJCURVE_OK;
    for (;;) {
        if (cap - len < PC_READ_CHUNK) {
            if (cap >= PC_MAX_FILE_BYTES) {
                st = pc_fail(ctx, PROJCURVE_ERR_UNSUPPORTED, "%s is larger than %zu bytes", path,
                             PC_MAX_FILE_BYTES);
                break;
            }
            const size_t fresh = cap ? 2 * cap : 4 * PC_READ_CHUNK;
            char *p = realloc(buf, fresh + 1);
            if (p == NULL) {
                st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading %s", path);
                break;
            }
            buf = p;
            cap = fresh;
        }
        errno = 0;
        const size_t got = fread(buf + len, 1, cap - len, fp);
        len += got;
        if (got == 0) {
            if (ferror(fp))
                st = pc_fail(ctx, PROJCURVE_ERR_IO, "error reading %s: %s", path,
                             strerror(errno));
            break;
        }
    }
    fclose(fp);
    if (st == PROJCURVE_OK) {
        buf[len] = '\0';
        st = read_text(ctx, buf, len, out);
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

int projcurve_model_unit(const projcurve_model *model)
{
    return model ? model->unit : PROJCURVE_UNIT_UNKNOWN;
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
