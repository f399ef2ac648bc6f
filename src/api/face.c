/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Public face functions: creation from a caller's loops, queries and
 * point classification (the engine is src/brep/).
 */
#include <math.h>
#include <stdlib.h>

#include "brep/face.h"
#include "brep/loop_overlap.h"
#include "common/error.h"

/* The default ON tolerance of a caller's face, relative to its domain, and
 * the gap its pieces may leave, relative to the ON tolerance. */
#define PC_FACE_DEFAULT_TOL_UV 1e-9
#define PC_FACE_CLOSE_FACTOR 100.0

/* The outer loop (and so the holes inside it) must lie in the surface's
 * domain d, up to the gap its pieces may leave: outside it S is not
 * defined, and a face there would only ever answer OUT and clip every
 * projection away. */
static projcurve_status check_in_domain(projcurve_context *ctx, const projcurve_face *face,
                                        const double d[4], double margin)
{
    const double *b = face->box_uv;
    if (b[0] >= d[0] - margin && b[1] <= d[1] + margin && b[2] >= d[2] - margin &&
        b[3] <= d[3] + margin)
        return PROJCURVE_OK;
    return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                   "face: the outer loop spans [%.9g, %.9g] x [%.9g, %.9g], outside the "
                   "surface's domain [%.9g, %.9g] x [%.9g, %.9g] (by more than %.3g)",
                   b[0], b[1], b[2], b[3], d[0], d[1], d[2], d[3], margin);
}

projcurve_status projcurve_face_create(projcurve_context *ctx, const projcurve_surface *surface,
                                       size_t n_loops, const size_t *loop_pieces,
                                       const int *degrees, const size_t *n_ctrl,
                                       const double *const *ctrl, const double *const *weights,
                                       const double *const *knots, double tol_uv,
                                       projcurve_face **out)
{
    PC_REQUIRE(ctx, out, "out");
    PC_REQUIRE(ctx, surface, "surface");
    if (n_loops > 0) {
        PC_REQUIRE(ctx, loop_pieces, "loop_pieces");
        PC_REQUIRE(ctx, degrees, "degrees");
        PC_REQUIRE(ctx, n_ctrl, "n_ctrl");
        PC_REQUIRE(ctx, ctrl, "ctrl");
        PC_REQUIRE(ctx, knots, "knots");
    }
    if (!(tol_uv >= 0.0) || !isfinite(tol_uv))
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE, "tol_uv %g is not a finite value >= 0",
                       tol_uv);
    double d[4];
    projcurve_surface_domain(NULL, surface, d);
    const double span = fmax(d[1] - d[0], d[3] - d[2]);
    if (tol_uv == 0.0)
        tol_uv = PC_FACE_DEFAULT_TOL_UV * span;
    /* Wider than the domain every point of it is ON, and near DBL_MAX the
     * gap allowed between pieces (PC_FACE_CLOSE_FACTOR tol_uv) overflows:
     * such a width answers no question about the face. */
    if (tol_uv > span)
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE,
                       "tol_uv %g is wider than the surface's domain (%g)", tol_uv, span);
    size_t total = 0;
    for (size_t l = 0; l < n_loops; ++l) {
        if (loop_pieces[l] > ((size_t)-1) / 2 - total)
            return pc_fail(ctx, PROJCURVE_ERR_OVERFLOW, "loop %zu: piece counts overflow", l);
        total += loop_pieces[l];
    }
    pc_piece_input *pieces = calloc(total + 1, sizeof *pieces);
    pc_loop_input *loops = calloc(n_loops + 1, sizeof *loops);
    if (pieces == NULL || loops == NULL) {
        free(pieces);
        free(loops);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory creating a face");
    }
    size_t j = 0;
    for (size_t l = 0; l < n_loops; ++l) {
        loops[l] = (pc_loop_input){.pieces = pieces + j, .n_pieces = loop_pieces[l], .outer = l == 0};
        for (size_t k = 0; k < loop_pieces[l]; ++k, ++j)
            pieces[j] = (pc_piece_input){.degree = degrees[j], .n_ctrl = n_ctrl[j],
                                         .ctrl = ctrl[j], .weights = weights ? weights[j] : NULL,
                                         .knots = knots[j], .edge = -1, .sense = 1,
                                         .edge_sense = 1};
    }
    const pc_face_params fp = {.tol_uv = tol_uv, .close_tol = PC_FACE_CLOSE_FACTOR * tol_uv,
                               .same_sense = 1, .id = -1, .kind = "bspline", .what = "face"};
    projcurve_face *face = NULL;
    projcurve_status st = pc_face_build(ctx, surface, loops, n_loops, &fp, &face);
    free(pieces);
    free(loops);
    if (st == PROJCURVE_OK)
        st = check_in_domain(ctx, face, d, fp.close_tol);
    if (st == PROJCURVE_OK)
        st = pc_face_check_loops_apart(ctx, face, "face");
    if (st != PROJCURVE_OK) {
        pc_face_free(face);
        return st;
    }
    *out = face;
    return PROJCURVE_OK;
}

void projcurve_face_destroy(projcurve_face *face)
{
    pc_face_free(face);
}

const projcurve_surface *projcurve_face_surface(const projcurve_face *face)
{
    return face ? face->surface : NULL;
}

size_t projcurve_face_loop_count(const projcurve_face *face)
{
    return face ? face->n_loops : 0;
}

static projcurve_status loop_at(projcurve_context *ctx, const projcurve_face *face, size_t loop)
{
    PC_REQUIRE(ctx, face, "face");
    if (loop >= face->n_loops)
        return pc_fail(ctx, PROJCURVE_ERR_INDEX, "loop %zu of a face of %zu loops", loop,
                       face->n_loops);
    return PROJCURVE_OK;
}

static projcurve_status piece_at(projcurve_context *ctx, const projcurve_face *face, size_t loop,
                                 size_t piece, const pc_face_piece **out)
{
    projcurve_status st = loop_at(ctx, face, loop);
    if (st != PROJCURVE_OK)
        return st;
    if (piece >= face->loops[loop].n_pieces)
        return pc_fail(ctx, PROJCURVE_ERR_INDEX, "piece %zu of loop %zu of %zu pieces", piece,
                       loop, face->loops[loop].n_pieces);
    *out = &face->loops[loop].pieces[piece];
    return PROJCURVE_OK;
}

projcurve_status projcurve_face_loop_piece_count(projcurve_context *ctx,
                                                 const projcurve_face *face, size_t loop,
                                                 size_t *count)
{
    PC_REQUIRE(ctx, count, "count");
    projcurve_status st = loop_at(ctx, face, loop);
    if (st == PROJCURVE_OK)
        *count = face->loops[loop].n_pieces;
    return st;
}

projcurve_status projcurve_face_piece_curve(projcurve_context *ctx, const projcurve_face *face,
                                            size_t loop, size_t piece, int *degree,
                                            size_t *n_ctrl, const double **ctrl,
                                            const double **weights, const double **knots,
                                            int *sense)
{
    const pc_face_piece *p = NULL;
    projcurve_status st = piece_at(ctx, face, loop, piece, &p);
    if (st != PROJCURVE_OK)
        return st;
    if (degree)
        *degree = p->curve.degree;
    if (n_ctrl)
        *n_ctrl = p->curve.n_ctrl;
    if (ctrl)
        *ctrl = p->curve.ctrl;
    if (weights)
        *weights = p->curve.weights;
    if (knots)
        *knots = p->curve.knots;
    if (sense)
        *sense = p->sense;
    return PROJCURVE_OK;
}

projcurve_status projcurve_face_piece_edge(projcurve_context *ctx, const projcurve_face *face,
                                           size_t loop, size_t piece, long *edge,
                                           int *edge_sense, unsigned *flags)
{
    const pc_face_piece *p = NULL;
    projcurve_status st = piece_at(ctx, face, loop, piece, &p);
    if (st != PROJCURVE_OK)
        return st;
    if (edge)
        *edge = p->edge;
    if (edge_sense)
        *edge_sense = p->edge_sense;
    if (flags)
        *flags = p->flags;
    return PROJCURVE_OK;
}

projcurve_status projcurve_face_classify(projcurve_context *ctx, const projcurve_face *face,
                                         double u, double v, projcurve_where *where)
{
    PC_REQUIRE(ctx, face, "face");
    PC_REQUIRE(ctx, where, "where");
    if (!isfinite(u) || !isfinite(v))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "face parameters (%g, %g) not finite", u,
                       v);
    *where = (projcurve_where)pc_classify(&face->cls, u, v);
    return PROJCURVE_OK;
}

projcurve_status projcurve_face_bounds(projcurve_context *ctx, const projcurve_face *face,
                                       double box_uv[4], double box[6])
{
    PC_REQUIRE(ctx, face, "face");
    for (int k = 0; box_uv && k < 4; ++k)
        box_uv[k] = face->box_uv[k];
    for (int k = 0; box && k < 6; ++k)
        box[k] = face->box[k];
    return PROJCURVE_OK;
}

projcurve_status projcurve_face_tolerance(projcurve_context *ctx, const projcurve_face *face,
                                          double *tol_uv, double *tol_model)
{
    PC_REQUIRE(ctx, face, "face");
    if (tol_uv)
        *tol_uv = face->tol_uv;
    if (tol_model)
        *tol_model = face->tol_model;
    return PROJCURVE_OK;
}

projcurve_status projcurve_face_info(projcurve_context *ctx, const projcurve_face *face,
                                     int *same_sense, int periodic[2], const char **kind)
{
    PC_REQUIRE(ctx, face, "face");
    if (same_sense)
        *same_sense = face->same_sense;
    if (periodic)
        periodic[0] = face->periodic[0], periodic[1] = face->periodic[1];
    if (kind)
        *kind = face->kind;
    return PROJCURVE_OK;
}
