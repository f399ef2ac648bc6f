/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * pc_shape_project: select, project and clip each face, chain
 * (shapeproj/shape_project.h).
 */
#include "shapeproj/shape_project.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "brep/shape.h"
#include "common/array.h"
#include "common/error.h"
#include "faceproj/face_project.h"
#include "faceproj/loop_crossing.h"
#include "shapeproj/chain.h"
#include "shapeproj/face_select.h"
#include "shapeproj/t_ranges.h"
#include "shapeproj/reach_curve.h"
#include "geom/curve.h"
#include "shapeproj/shape_hits.h"

static const projcurve_face *face_of(const projcurve_shape *shape, const projcurve_face *face,
                                     size_t i)
{
    return shape ? shape->faces[i] : face;
}

/* The faces to project, as shape indices, in *sel (malloc'd). */
static projcurve_status select_faces(projcurve_context *ctx, const projcurve_shape *shape,
                                     const projcurve_face *face, const projcurve_curve *curve,
                                     const pc_projection_spec *spec, size_t **sel, size_t *n_sel)
{
    const size_t n = shape ? shape->n_faces : 1;
    *sel = malloc((n + 1) * sizeof **sel);
    if (*sel == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory selecting faces");
    /* the box test of the kind; none (every face) for orthogonal and for
     * a callback curve, which has no box */
    pc_swept_box sw;
    pc_cone_box cone;
    pc_box_test test = NULL;
    const void *user = NULL;
    if (spec->kind == PROJCURVE_PROJECT_DIRECTIONAL && pc_curve_box(curve, sw.curve_box)) {
        sw.dir = spec->vec;
        test = pc_swept_box_test;
        user = &sw;
    } else if (spec->kind == PROJCURVE_PROJECT_CONICAL && pc_curve_box(curve, cone.curve_box)) {
        cone.eye = spec->vec;
        test = pc_cone_box_test;
        user = &cone;
    }
    *n_sel = 0;
    if (test != NULL && shape != NULL) {
        *n_sel = pc_face_bvh_query(&shape->bvh, test, user, *sel);
        return PROJCURVE_OK;
    }
    for (size_t i = 0; i < n; ++i) {
        const double *box = shape ? shape->boxes + 6 * i : face->box;
        if (test == NULL || test(user, box))
            (*sel)[(*n_sel)++] = i;
    }
    return PROJCURVE_OK;
}

static double chain_tolerance(const projcurve_shape *shape, const projcurve_shape_result *r,
                              double model_size)
{
    double tol = PC_CHAIN_MIN_TOL * model_size;
    if (shape)
        tol = fmax(tol, shape->sew_tol);
    for (size_t i = 0; i < r->n_parts; ++i)
        tol = fmax(tol, r->parts[i].f->tol_model);
    return tol;
}

/* The message of a face projected with OK: "" or how many of its
 * crossings were not located to PC_CROSSING_TOL. */
static projcurve_status set_ok_message(projcurve_context *ctx, pc_face_part *part,
                                       size_t unrefined)
{
    char text[160] = "";
    if (unrefined > 0)
        snprintf(text, sizeof text,
                 "%zu loop crossing(s) not located to %g of the model size (kept at the best "
                 "iterate)",
                 unrefined, PC_CROSSING_TOL);
    return pc_face_part_set_message(ctx, part, text);
}

/* pc_face_project of curve onto face, or an empty result with OK when no
 * t range of the curve reaches the face's box (t_ranges.h: then the
 * untrimmed projection has no point, so neither has the clipped one). */
static projcurve_status project_if_reached(projcurve_context *ctx, const projcurve_face *face,
                                           const projcurve_curve *curve,
                                           const pc_t_ranges *ranges,
                                           const pc_projection_spec *spec, const pc_params *p,
                                           projcurve_result **out, pc_branch_trim **trims,
                                           size_t *unrefined)
{
    if (ranges->count > 0) {
        /* a short reach is projected alone: steps relative to it (reach_curve.h) */
        projcurve_curve *reach = NULL;
        projcurve_status st = pc_reach_curve(ctx, curve, ranges, &reach);
        if (st == PROJCURVE_OK)
            st = pc_face_project(ctx, face, reach ? reach : curve, spec, p, out, trims,
                                 unrefined);
        pc_curve_destroy(reach);
        return st;
    }
    projcurve_result *r = NULL;
    const projcurve_status st = pc_result_create(ctx, 3, &r);
    if (st != PROJCURVE_OK)
        return st;
    r->stats.tol_distance = p->tol_distance;
    *out = r;
    *trims = NULL;
    *unrefined = 0;
    return PROJCURVE_OK;
}

/* One face of a shape, with a context of its own so that its message is
 * kept with it. Returns NO_MEMORY (the call fails) or OK. */
static projcurve_status project_part(projcurve_context *ctx, pc_face_part *part,
                                     const projcurve_curve *curve, const pc_t_ranges *ranges,
                                     const pc_projection_spec *spec, const pc_params *p)
{
    if (pc_budget_status(p->budget) != PROJCURVE_OK) {
        part->status = pc_budget_status(p->budget);
        return pc_face_part_set_message(ctx, part,
                                        "not projected: the call's budget was spent before");
    }
    projcurve_context *fctx = NULL;
    if (projcurve_context_create(PROJCURVE_VERSION_MAJOR, &fctx) != PROJCURVE_OK)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for a face's context");
    size_t unrefined = 0;
    part->status = project_if_reached(fctx, part->f, curve, ranges, spec, p, &part->result,
                                      &part->trims, &unrefined);
    projcurve_status st = PROJCURVE_OK;
    if (part->status == PROJCURVE_ERR_NO_MEMORY)
        st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "face %zu: %s", part->face,
                     projcurve_context_message(fctx));
    else if (part->status != PROJCURVE_OK)
        st = pc_face_part_set_message(ctx, part, projcurve_context_message(fctx));
    else
        st = set_ok_message(ctx, part, unrefined);
    projcurve_context_destroy(fctx);
    return st;
}

projcurve_status pc_shape_project(projcurve_context *ctx, const projcurve_shape *shape,
                                  const projcurve_face *face, const projcurve_curve *curve,
                                  const pc_projection_spec *spec, const pc_params *p,
                                  double model_size, projcurve_shape_result **out)
{
    size_t *sel = NULL, n_sel = 0;
    projcurve_status st = select_faces(ctx, shape, face, curve, spec, &sel, &n_sel);
    projcurve_shape_result *r = NULL;
    if (st == PROJCURVE_OK)
        st = pc_shape_result_create(ctx, n_sel, &r);
    for (size_t i = 0; st == PROJCURVE_OK && i < n_sel; ++i) {
        r->parts[i].face = sel[i];
        r->parts[i].f = face_of(shape, face, sel[i]);
    }
    /* nearest hits are chosen across the clipped faces (shape_hits.h): each
     * face keeps every hit of its surface, MAX_DISTANCE stays per face */
    const int nearest = p->hits == PROJCURVE_HITS_NEAREST;
    pc_params face_params = *p;
    if (nearest)
        face_params.hits = PROJCURVE_HITS_ALL;
    const pc_params *fp = &face_params;
    /* a face no part of the swept curve reaches is not projected (t_ranges.h) */
    pc_curve_boxes cboxes = {0};
    pc_t_ranges ranges = {0};
    if (st == PROJCURVE_OK)
        st = pc_curve_boxes_build(ctx, curve, spec, &cboxes);
    const double pad = pc_t_range_pad(p, model_size);
    projcurve_status kept = PROJCURVE_OK; /* OK, or the partial status */
    for (size_t i = 0; st == PROJCURVE_OK && i < n_sel; ++i) {
        pc_face_part *part = &r->parts[i];
        st = pc_t_ranges_find(ctx, &cboxes, spec, part->f->box, pad, &ranges);
        if (st != PROJCURVE_OK)
            break;
        if (shape == NULL) {
            /* a lone face: its status is the call's */
            size_t unrefined = 0;
            part->status = project_if_reached(ctx, part->f, curve, &ranges, spec, fp,
                                              &part->result, &part->trims, &unrefined);
            if (!pc_status_keeps_result(part->status))
                st = part->status;
            else
                st = set_ok_message(ctx, part, unrefined);
        } else {
            st = project_part(ctx, part, curve, &ranges, spec, fp);
        }
        if (st == PROJCURVE_OK && part->status != PROJCURVE_OK &&
            pc_status_keeps_result(part->status))
            kept = part->status;
    }
    free(sel);
    pc_curve_boxes_free(&cboxes);
    PC_ARRAY_FREE(&ranges);
    if (st == PROJCURVE_OK && nearest) {
        st = pc_shape_hits_select(ctx, r, curve, spec, p, model_size);
        if (st != PROJCURVE_OK && st == pc_budget_status(p->budget)) {
            kept = st; /* stopped by the budget: the parts selected so far */
            st = PROJCURVE_OK;
        }
    }
    if (st == PROJCURVE_OK) {
        r->chain_tol = chain_tolerance(shape, r, model_size);
        st = pc_chain_pieces(ctx, r, shape, curve, spec);
    }
    if (st != PROJCURVE_OK) {
        projcurve_shape_result_destroy(r);
        return st;
    }
    if (kept != PROJCURVE_OK && shape != NULL && pc_budget_fail(p->budget, ctx) == PROJCURVE_OK)
        pc_fail(ctx, kept, "a face's projection stopped at a limit: its result is partial "
                           "(projcurve_shape_result_face tells which)");
    *out = r;
    return kept;
}
