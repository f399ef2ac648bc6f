/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The topology part of a model: faces, shapes and the list of faces that
 * could not be built.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "brep/face.h"
#include "brep/shape.h"
#include "io/io_model.h"

static int make_room(void **items, size_t n, size_t *cap, size_t elem)
{
    if (n < *cap)
        return 1;
    const size_t fresh = *cap ? 2 * *cap : 16;
    void *p = realloc(*items, fresh * elem);
    if (p == NULL)
        return 0;
    *items = p;
    *cap = fresh;
    return 1;
}

projcurve_status pc_model_add_face(projcurve_context *ctx, projcurve_model *model,
                                   projcurve_face *face)
{
    void *items = model->faces;
    if (!make_room(&items, model->n_faces, &model->cap_faces, sizeof *model->faces)) {
        pc_face_free(face);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory adding a face");
    }
    model->faces = items;
    model->faces[model->n_faces++] = face;
    return PROJCURVE_OK;
}

projcurve_status pc_model_add_shape(projcurve_context *ctx, projcurve_model *model,
                                    projcurve_shape *shape)
{
    void *items = model->shapes;
    if (!make_room(&items, model->n_shapes, &model->cap_shapes, sizeof *model->shapes)) {
        pc_shape_free(shape);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory adding a shape");
    }
    model->shapes = items;
    model->shapes[model->n_shapes++] = shape;
    return PROJCURVE_OK;
}

projcurve_status pc_model_add_unbuilt(projcurve_context *ctx, projcurve_model *model,
                                      const char *kind, const char *fmt, ...)
{
    size_t cap = model->cap_unbuilt;
    void *reasons = model->unbuilt, *kinds = model->unbuilt_kind;
    if (!make_room(&reasons, model->n_unbuilt, &cap, sizeof *model->unbuilt))
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory listing a face");
    model->unbuilt = reasons;
    cap = model->cap_unbuilt;
    if (!make_room(&kinds, model->n_unbuilt, &cap, sizeof *model->unbuilt_kind))
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory listing a face");
    model->unbuilt_kind = kinds;
    model->cap_unbuilt = cap;
    char *text = malloc(PC_MODEL_SKIPPED_TEXT);
    if (text == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory listing a face");
    va_list args;
    va_start(args, fmt);
    vsnprintf(text, PC_MODEL_SKIPPED_TEXT, fmt, args);
    va_end(args);
    snprintf(model->unbuilt_kind[model->n_unbuilt], PC_MODEL_KIND_TEXT, "%s", kind);
    model->unbuilt[model->n_unbuilt++] = text;
    return PROJCURVE_OK;
}
