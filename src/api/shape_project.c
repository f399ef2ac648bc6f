/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve_project_face, projcurve_project_shape and the shape result
 * accessors: arguments and options checked here, the engine is
 * src/faceproj/ and src/shapeproj/.
 */
#include <math.h>

#include "api/project.h"
#include "brep/shape.h"
#include "common/error.h"
#include "conical/conical_project.h"
#include "shapeproj/shape_project.h"

/* The spec of a call: kind checked, Dir made unit, the eye finite
 * (statuses NULL_ARGUMENT, NOT_FINITE, ZERO_DIRECTION, INVALID_ARGUMENT). */
static projcurve_status make_spec(projcurve_context *ctx, projcurve_projection_kind kind,
                                  const double vec[3], pc_projection_spec *spec)
{
    spec->kind = kind;
    spec->vec = vec3(0.0, 0.0, 0.0);
    switch (kind) {
    case PROJCURVE_PROJECT_ORTHOGONAL:
        return PROJCURVE_OK;
    case PROJCURVE_PROJECT_CONICAL:
        PC_REQUIRE(ctx, vec, "eye");
        spec->vec = vec3_load(vec);
        if (!vec3_is_finite(spec->vec))
            return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "eye point (%g, %g, %g) is not finite",
                           spec->vec.x, spec->vec.y, spec->vec.z);
        return PROJCURVE_OK;
    case PROJCURVE_PROJECT_DIRECTIONAL:
        break;
    default:
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT, "unknown projection kind %d",
                       (int)kind);
    }
    PC_REQUIRE(ctx, vec, "dir");
    const pc_vec3 d = vec3_load(vec);
    if (!vec3_is_finite(d))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "direction (%g, %g, %g) is not finite",
                       d.x, d.y, d.z);
    const double m = fmax(fabs(d.x), fmax(fabs(d.y), fabs(d.z)));
    if (!(m > 0.0))
        return pc_fail(ctx, PROJCURVE_ERR_ZERO_DIRECTION, "direction is the zero vector");
    spec->vec = vec3_normalize(vec3(d.x / m, d.y / m, d.z / m));
    return PROJCURVE_OK;
}

static projcurve_status project(projcurve_context *ctx, const projcurve_shape *shape,
                                const projcurve_face *face, const projcurve_curve *curve,
                                projcurve_projection_kind kind, const double vec[3],
                                const projcurve_options *opts, projcurve_shape_result **out)
{
    PC_REQUIRE(ctx, curve, "curve");
    PC_REQUIRE(ctx, out, "out");
    pc_projection_spec spec;
    projcurve_status st = make_spec(ctx, kind, vec, &spec);
    if (st != PROJCURVE_OK)
        return st;
    double box[6];
    box_empty(box);
    if (shape)
        for (size_t i = 0; i < shape->n_faces; ++i)
            box_add_box(box, shape->boxes + 6 * i);
    else
        box_add_box(box, face->box);
    const double size = shape && shape->n_faces == 0 ? 1.0 : box_diagonal(box);
    pc_params p;
    pc_budget budget;
    st = pc_projection_params(ctx, opts, size, &budget, &p);
    if (st != PROJCURVE_OK)
        return st;
    /* one budget for every face; progress is not reported (the per-face
     * stages would report 1 after the first face) */
    budget.progress = NULL;
    st = pc_curve_refuse_point(ctx, curve, pc_params_precision(&p) * size);
    /* once for the call, as projcurve_project_conical would for each face */
    if (st == PROJCURVE_OK && kind == PROJCURVE_PROJECT_CONICAL)
        st = pc_conical_refuse_eye_on_curve(ctx, curve, spec.vec,
                                            pc_params_precision(&p) * size);
    if (st != PROJCURVE_OK)
        return st;
    return pc_shape_project(ctx, shape, face, curve, &spec, &p, size, out);
}

projcurve_status projcurve_project_face(projcurve_context *ctx, const projcurve_face *face,
                                        const projcurve_curve *curve,
                                        projcurve_projection_kind kind, const double vec[3],
                                        const projcurve_options *opts,
                                        projcurve_shape_result **out)
{
    PC_REQUIRE(ctx, face, "face");
    return project(ctx, NULL, face, curve, kind, vec, opts, out);
}

projcurve_status projcurve_project_shape(projcurve_context *ctx, const projcurve_shape *shape,
                                         const projcurve_curve *curve,
                                         projcurve_projection_kind kind, const double vec[3],
                                         const projcurve_options *opts,
                                         projcurve_shape_result **out)
{
    PC_REQUIRE(ctx, shape, "shape");
    return project(ctx, shape, NULL, curve, kind, vec, opts, out);
}

size_t projcurve_shape_result_curve_count(const projcurve_shape_result *r)
{
    return r ? r->n_curves : 0;
}

size_t projcurve_shape_result_face_count(const projcurve_shape_result *r)
{
    return r ? r->n_parts : 0;
}

size_t projcurve_shape_result_open_end_count(const projcurve_shape_result *r)
{
    return r ? r->open_ends : 0;
}

double projcurve_shape_result_chain_tolerance(const projcurve_shape_result *r)
{
    return r ? r->chain_tol : 0.0;
}

static projcurve_status get_curve(projcurve_context *ctx, const projcurve_shape_result *r,
                                  size_t curve, const pc_connected **out)
{
    PC_REQUIRE(ctx, r, "shape result");
    if (curve >= r->n_curves)
        return pc_fail(ctx, PROJCURVE_ERR_INDEX, "connected curve %zu of %zu", curve,
                       r->n_curves);
    *out = &r->curves[curve];
    return PROJCURVE_OK;
}

static const pc_branch_trim *ref_trim(const projcurve_shape_result *r, const pc_piece_ref *ref)
{
    return &r->parts[ref->part].trims[ref->branch];
}

projcurve_status projcurve_shape_result_curve_info(projcurve_context *ctx,
                                                   const projcurve_shape_result *r, size_t curve,
                                                   size_t *n_pieces, double t_range[2],
                                                   int *closed)
{
    const pc_connected *c = NULL;
    const projcurve_status st = get_curve(ctx, r, curve, &c);
    if (st != PROJCURVE_OK)
        return st;
    if (n_pieces)
        *n_pieces = c->count;
    if (t_range) {
        t_range[0] = ref_trim(r, &r->refs[c->first])->start.t;
        t_range[1] = ref_trim(r, &r->refs[c->first + c->count - 1])->end.t;
    }
    if (closed)
        *closed = c->closed;
    return PROJCURVE_OK;
}

projcurve_status projcurve_shape_result_piece(projcurve_context *ctx,
                                              const projcurve_shape_result *r, size_t curve,
                                              size_t piece, size_t *face,
                                              const projcurve_result **face_result,
                                              size_t *branch, double t_range[2],
                                              projcurve_branch_start *start,
                                              projcurve_branch_end *end)
{
    const pc_connected *c = NULL;
    const projcurve_status st = get_curve(ctx, r, curve, &c);
    if (st != PROJCURVE_OK)
        return st;
    if (piece >= c->count)
        return pc_fail(ctx, PROJCURVE_ERR_INDEX, "piece %zu of %zu of connected curve %zu",
                       piece, c->count, curve);
    const pc_piece_ref *ref = &r->refs[c->first + piece];
    const pc_face_part *part = &r->parts[ref->part];
    const pc_branch *b = &part->result->branches[ref->branch];
    if (face)
        *face = part->face;
    if (face_result)
        *face_result = part->result;
    if (branch)
        *branch = ref->branch;
    if (t_range) {
        t_range[0] = part->trims[ref->branch].start.t;
        t_range[1] = part->trims[ref->branch].end.t;
    }
    if (start)
        *start = b->start;
    if (end)
        *end = b->end;
    return PROJCURVE_OK;
}

projcurve_status projcurve_shape_result_face(projcurve_context *ctx,
                                             const projcurve_shape_result *r, size_t index,
                                             size_t *face, const projcurve_result **face_result,
                                             projcurve_status *status, const char **message)
{
    PC_REQUIRE(ctx, r, "shape result");
    if (index >= r->n_parts)
        return pc_fail(ctx, PROJCURVE_ERR_INDEX, "projected face %zu of %zu", index,
                       r->n_parts);
    const pc_face_part *part = &r->parts[index];
    if (face)
        *face = part->face;
    if (face_result)
        *face_result = part->result;
    if (status)
        *status = part->status;
    if (message)
        *message = part->message ? part->message : "";
    return PROJCURVE_OK;
}
