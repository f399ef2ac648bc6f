/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Public shape functions and the model's faces and shapes (the engine is
 * src/brep/, the model's lists src/io/io_topology.c).
 */
#include "brep/shape.h"
#include "common/error.h"
#include "io/io_model.h"

size_t projcurve_model_face_count(const projcurve_model *model)
{
    return model ? model->n_faces : 0;
}

const projcurve_face *projcurve_model_face(const projcurve_model *model, size_t index)
{
    return (model && index < model->n_faces) ? model->faces[index] : NULL;
}

size_t projcurve_model_shape_count(const projcurve_model *model)
{
    return model ? model->n_shapes : 0;
}

const projcurve_shape *projcurve_model_shape(const projcurve_model *model, size_t index)
{
    return (model && index < model->n_shapes) ? model->shapes[index] : NULL;
}

size_t projcurve_model_unbuilt_face_count(const projcurve_model *model)
{
    return model ? model->n_unbuilt : 0;
}

const char *projcurve_model_unbuilt_face(const projcurve_model *model, size_t index)
{
    return (model && index < model->n_unbuilt) ? model->unbuilt[index] : NULL;
}

const char *projcurve_model_unbuilt_face_kind(const projcurve_model *model, size_t index)
{
    return (model && index < model->n_unbuilt) ? model->unbuilt_kind[index] : NULL;
}

projcurve_status projcurve_shape_info(projcurve_context *ctx, const projcurve_shape *shape,
                                      projcurve_shape_kind *kind, double *sew_tol)
{
    PC_REQUIRE(ctx, shape, "shape");
    if (kind)
        *kind = shape->kind;
    if (sew_tol)
        *sew_tol = shape->sew_tol;
    return PROJCURVE_OK;
}

size_t projcurve_shape_face_count(const projcurve_shape *shape)
{
    return shape ? shape->n_faces : 0;
}

const projcurve_face *projcurve_shape_face(const projcurve_shape *shape, size_t index)
{
    return (shape && index < shape->n_faces) ? shape->faces[index] : NULL;
}

projcurve_status projcurve_shape_face_model_index(projcurve_context *ctx,
                                                  const projcurve_shape *shape, size_t index,
                                                  size_t *model_index)
{
    PC_REQUIRE(ctx, shape, "shape");
    PC_REQUIRE(ctx, model_index, "model_index");
    if (index >= shape->n_faces)
        return pc_fail(ctx, PROJCURVE_ERR_INDEX, "face %zu of a shape of %zu faces", index,
                       shape->n_faces);
    *model_index = shape->face_index[index];
    return PROJCURVE_OK;
}

size_t projcurve_shape_edge_count(const projcurve_shape *shape)
{
    return shape ? shape->n_edges : 0;
}

projcurve_status projcurve_shape_edge(projcurve_context *ctx, const projcurve_shape *shape,
                                      size_t edge, long *id, size_t *n_uses)
{
    PC_REQUIRE(ctx, shape, "shape");
    if (edge >= shape->n_edges)
        return pc_fail(ctx, PROJCURVE_ERR_INDEX, "edge %zu of a shape of %zu edges", edge,
                       shape->n_edges);
    if (id)
        *id = shape->edges[edge].id;
    if (n_uses)
        *n_uses = shape->edges[edge].n_uses;
    return PROJCURVE_OK;
}

projcurve_status projcurve_shape_edge_use(projcurve_context *ctx, const projcurve_shape *shape,
                                          size_t edge, size_t use, size_t *face, size_t *loop,
                                          size_t *piece, int *sense)
{
    projcurve_status st = projcurve_shape_edge(ctx, shape, edge, NULL, NULL);
    if (st != PROJCURVE_OK)
        return st;
    if (use >= shape->edges[edge].n_uses)
        return pc_fail(ctx, PROJCURVE_ERR_INDEX, "use %zu of edge %ld of %zu uses", use,
                       shape->edges[edge].id, shape->edges[edge].n_uses);
    const pc_edge_use *u = &shape->uses[shape->edges[edge].first_use + use];
    if (face)
        *face = u->face;
    if (loop)
        *loop = u->loop;
    if (piece)
        *piece = u->piece;
    if (sense)
        *sense = u->sense;
    return PROJCURVE_OK;
}
