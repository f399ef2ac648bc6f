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
#include "common/array.h"
#include "io/io_model.h"

/* Room for one more of the n elements in *items (the common array's
 * policy, from 16). Statuses: OK, NO_MEMORY (recorded in ctx). */
static projcurve_status make_room(projcurve_context *ctx, void **items, size_t n, size_t *cap,
                                  size_t elem, const char *what)
{
    return pc_array_reserve(ctx, items, cap, n, n + 1, elem, 16, NULL, what);
}

projcurve_status pc_model_add_face(projcurve_context *ctx, projcurve_model *model,
                                   projcurve_face *face)
{
    void *items = model->faces;
    const projcurve_status st = make_room(ctx, &items, model->n_faces, &model->cap_faces,
                                          sizeof *model->faces, "model faces");
    if (st != PROJCURVE_OK) {
        pc_face_free(face);
        return st;
    }
    model->faces = items;
    model->faces[model->n_faces++] = face;
    return PROJCURVE_OK;
}

projcurve_status pc_model_add_shape(projcurve_context *ctx, projcurve_model *model,
                                    projcurve_shape *shape)
{
    void *items = model->shapes;
    const projcurve_status st = make_room(ctx, &items, model->n_shapes, &model->cap_shapes,
                                          sizeof *model->shapes, "model shapes");
    if (st != PROJCURVE_OK) {
        pc_shape_free(shape);
        return st;
    }
    model->shapes = items;
    model->shapes[model->n_shapes++] = shape;
    return PROJCURVE_OK;
}

projcurve_status pc_model_add_unbuilt(projcurve_context *ctx, projcurve_model *model,
                                      const char *kind, const char *fmt, ...)
{
    /* the reasons and kinds share cap_unbuilt: both grow from it to the
     * same capacity, recorded once both have it */
    size_t cap = model->cap_unbuilt;
    void *reasons = model->unbuilt, *kinds = model->unbuilt_kind;
    projcurve_status st = make_room(ctx, &reasons, model->n_unbuilt, &cap,
                                    sizeof *model->unbuilt, "unbuilt face reasons");
    if (st != PROJCURVE_OK)
        return st;
    model->unbuilt = reasons;
    cap = model->cap_unbuilt;
    st = make_room(ctx, &kinds, model->n_unbuilt, &cap, sizeof *model->unbuilt_kind,
                   "unbuilt face kinds");
    if (st != PROJCURVE_OK)
        return st;
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
