/* SPDX-License-Identifier: BSD-3-Clause */
#include "io/io_model.h"

#include "brep/face.h"
#include "brep/shape.h"
#include "common/array.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

projcurve_model *pc_model_new(void)
{
    return calloc(1, sizeof(projcurve_model));
}

void pc_model_free(projcurve_model *model)
{
    if (model == NULL)
        return;
    for (size_t i = 0; i < model->n_surfaces; ++i)
        projcurve_surface_destroy(model->surfaces[i]);
    for (size_t i = 0; i < model->n_curves; ++i)
        projcurve_curve_destroy(model->curves[i]);
    for (size_t i = 0; i < model->n_skipped; ++i)
        free(model->skipped[i]);
    for (size_t i = 0; i < model->n_shapes; ++i)
        pc_shape_free(model->shapes[i]);
    for (size_t i = 0; i < model->n_faces; ++i)
        pc_face_free(model->faces[i]);
    for (size_t i = 0; i < model->n_unbuilt; ++i)
        free(model->unbuilt[i]);
    free(model->shapes);
    free(model->faces);
    free(model->unbuilt);
    free(model->unbuilt_kind);
    free(model->surfaces);
    free(model->surface_kinds);
    free(model->curves);
    free(model->skipped);
    free(model);
}

/* Makes room for one more element in a growing array (the common
 * array's policy, from 16); returns the array, moved or not, or NULL when
 * memory runs out (the old array and *cap are then unchanged). No context:
 * the caller records the failure with the origin of the entity. */
static void *grow(void *items, size_t n, size_t *cap, size_t elem)
{
    const projcurve_status st =
        pc_array_reserve(NULL, &items, cap, n, n + 1, elem, 16, NULL, "a model list");
    return st == PROJCURVE_OK ? items : NULL;
}

static const double *weights_or_null(const double *w, size_t n)
{
    if (w == NULL)
        return NULL;
    for (size_t i = 1; i < n; ++i)
        if (w[i] != w[0])
            return w;
    /* Equal weights cancel out, but not a bad one. */
    return (n > 0 && w[0] > 0.0) ? NULL : w;
}

/* Re-records the creation failure with the origin in front. */
static projcurve_status prefix_failure(projcurve_context *ctx, projcurve_status st,
                                       const char *origin)
{
    char inner[PC_MESSAGE_CAPACITY];
    snprintf(inner, sizeof inner, "%s", projcurve_context_message(ctx));
    return pc_fail(ctx, st, "%s: %s", origin, inner);
}

projcurve_status pc_model_add_surface_kind(projcurve_context *ctx, projcurve_model *model,
                                           const pc_io_surface *s, const char *origin,
                                           const char *kind)
{
    projcurve_surface **items = grow(model->surfaces, model->n_surfaces, &model->cap_surfaces,
                                     sizeof *items);
    if (items == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "%s: out of memory", origin);
    model->surfaces = items;
    const char **kinds = grow(model->surface_kinds, model->n_surfaces, &model->cap_kinds,
                              sizeof *kinds);
    if (kinds == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "%s: out of memory", origin);
    model->surface_kinds = kinds;
    projcurve_surface *h = NULL;
    const projcurve_status st = projcurve_surface_create_nurbs(
        ctx, s->deg_u, s->deg_v, s->n_u, s->n_v, s->ctrl, weights_or_null(s->weights, s->n_u * s->n_v),
        s->knots_u, s->knots_v, &h);
    if (st != PROJCURVE_OK)
        return prefix_failure(ctx, st, origin);
    model->surface_kinds[model->n_surfaces] = kind;
    model->surfaces[model->n_surfaces++] = h;
    return PROJCURVE_OK;
}

projcurve_status pc_model_add_surface(projcurve_context *ctx, projcurve_model *model,
                                      const pc_io_surface *s, const char *origin)
{
    return pc_model_add_surface_kind(ctx, model, s, origin, "bspline");
}

projcurve_status pc_model_add_curve(projcurve_context *ctx, projcurve_model *model,
                                    const pc_io_curve *c, const char *origin)
{
    projcurve_curve **items = grow(model->curves, model->n_curves, &model->cap_curves,
                                   sizeof *items);
    if (items == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "%s: out of memory", origin);
    model->curves = items;
    projcurve_curve *h = NULL;
    const projcurve_status st = projcurve_curve_create_nurbs(
        ctx, c->degree, c->n_ctrl, c->ctrl, weights_or_null(c->weights, c->n_ctrl), c->knots, &h);
    if (st != PROJCURVE_OK)
        return prefix_failure(ctx, st, origin);
    model->curves[model->n_curves++] = h;
    return PROJCURVE_OK;
}

projcurve_status pc_model_add_skipped(projcurve_context *ctx, projcurve_model *model,
                                      const char *fmt, ...)
{
    if (model->n_skipped >= PC_MODEL_MAX_SKIPPED_LISTED) {
        ++model->n_skipped_unlisted;
        return PROJCURVE_OK;
    }
    char **items = grow(model->skipped, model->n_skipped, &model->cap_skipped, sizeof *items);
    if (items == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory listing skipped entities");
    model->skipped = items;
    char *text = malloc(PC_MODEL_SKIPPED_TEXT);
    if (text == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory listing skipped entities");
    va_list args;
    va_start(args, fmt);
    vsnprintf(text, PC_MODEL_SKIPPED_TEXT, fmt, args);
    va_end(args);
    model->skipped[model->n_skipped++] = text;
    return PROJCURVE_OK;
}

projcurve_status pc_model_note_unlisted(projcurve_context *ctx, projcurve_model *model)
{
    const size_t more = model->n_skipped_unlisted;
    if (more == 0 || model->n_skipped == 0)
        return PROJCURVE_OK;
    /* Replace the last listed entry by the summary so the list keeps its cap. */
    snprintf(model->skipped[model->n_skipped - 1], PC_MODEL_SKIPPED_TEXT,
             "... and %zu more skipped entities", more + 1);
    (void)ctx;
    model->n_skipped_unlisted = 0;
    return PROJCURVE_OK;
}
