/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Public STEP writer: surfaces, curves and projection results, each branch
 * in its compact forms (fit/) as a SURFACE_CURVE: the compact 3D curve
 * (where its fit found none, the pieces joined) with the compact pcurve as
 * its PCURVE on the surface; a whole-shape result as one COMPOSITE_CURVE
 * per connected curve over its face pieces' 3D curves. The geometry is
 * formatted by io/step_write*.c; this file takes it from the handles and
 * the result.
 */
#include <math.h>
#include <stdlib.h>

#include "api/result_surface.h"
#include "api/shape_member.h"
#include "common/error.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "io/seam_split.h"
#include "io/step_write.h"
#include "trace/result.h"

struct projcurve_step_writer {
    pc_step_out out;
    int uncertainty_set; /* by projcurve_step_writer_set_uncertainty */
};

projcurve_status projcurve_step_writer_create(projcurve_context *ctx,
                                              projcurve_step_writer **out)
{
    PC_REQUIRE(ctx, out, "out");
    projcurve_step_writer *w = calloc(1, sizeof *w);
    if (w == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory creating a STEP writer");
    pc_step_out_init(&w->out);
    *out = w;
    return PROJCURVE_OK;
}

void projcurve_step_writer_destroy(projcurve_step_writer *writer)
{
    if (writer == NULL)
        return;
    pc_step_out_free(&writer->out);
    free(writer);
}

projcurve_status projcurve_step_writer_add_surface(projcurve_context *ctx,
                                                   projcurve_step_writer *w,
                                                   const projcurve_surface *s)
{
    PC_REQUIRE(ctx, w, "writer");
    PC_REQUIRE(ctx, s, "surface");
    const pc_step_mark mark = pc_step_out_mark(&w->out);
    long id;
    const projcurve_status st = pc_step_out_surface(ctx, &w->out, &s->nurbs, &id);
    if (st != PROJCURVE_OK)
        pc_step_out_rollback(&w->out, &mark);
    return st;
}

static pc_step_spline view_of_nurbs(const pc_nurbs_curve *c)
{
    return (pc_step_spline){.degree = c->degree, .dim = 3, .n_poles = c->n_ctrl,
                            .knots = c->knots, .poles = c->cw, .homogeneous = 1};
}

static pc_step_spline view_of_bspline(const pc_bspline *b)
{
    return (pc_step_spline){.degree = b->degree, .dim = b->dim, .n_poles = b->n_poles,
                            .knots = b->knots, .poles = b->poles, .weights = b->weights};
}

projcurve_status projcurve_step_writer_add_curve(projcurve_context *ctx,
                                                 projcurve_step_writer *w,
                                                 const projcurve_curve *c)
{
    PC_REQUIRE(ctx, w, "writer");
    PC_REQUIRE(ctx, c, "curve");
    if (c->kind != PC_CURVE_NURBS)
        return pc_fail(ctx, PROJCURVE_ERR_WRONG_KIND,
                       "a callback curve has no NURBS form to write");
    const pc_step_mark mark = pc_step_out_mark(&w->out);
    const pc_step_spline view = view_of_nurbs(&c->nurbs);
    long id;
    projcurve_status st = pc_step_out_curve(ctx, &w->out, &view, &id);
    if (st == PROJCURVE_OK)
        st = pc_step_out_add_to_set(ctx, &w->out, id);
    if (st != PROJCURVE_OK)
        pc_step_out_rollback(&w->out, &mark);
    return st;
}

/* The 3D curve of a branch: the compact one, or where its fit found none
 * the pieces joined. */
static projcurve_status add_curve3d(projcurve_context *ctx, projcurve_step_writer *w,
                                    const projcurve_result *r, size_t branch, long *id)
{
    const pc_bspline *compact = &r->branches[branch].compact_curve;
    if (compact->n_poles > 0) {
        const pc_step_spline view = view_of_bspline(compact);
        return pc_step_out_curve(ctx, &w->out, &view, id);
    }
    projcurve_curve *joined = NULL;
    projcurve_status st = projcurve_result_branch_curve(ctx, r, branch, &joined);
    if (st != PROJCURVE_OK)
        return st;
    const pc_step_spline view = view_of_nurbs(&joined->nurbs);
    st = pc_step_out_curve(ctx, &w->out, &view, id);
    projcurve_curve_destroy(joined);
    return st;
}

/* A bound on the distance between the SURFACE_CURVE's two forms: each is
 * within its measured fit error of the exact projection (eps_D where the
 * form is the verified pieces, not a fit). */
static double forms_gap(const projcurve_result *r, const pc_branch *b)
{
    const double eps = r->stats.tol_distance;
    const double q = b->compact_pcurve_error >= 0.0 ? b->compact_pcurve_error : eps;
    const double c = b->compact_curve.n_poles > 0 && b->compact_curve_error >= 0.0
                         ? b->compact_curve_error
                         : eps;
    return q + c;
}

/* One SURFACE_CURVE of the 3D curve #curve3d and the 2D curve q on the
 * surface #surface, an element of the set. */
static projcurve_status add_surface_curve(projcurve_context *ctx, projcurve_step_writer *w,
                                          long surface, long curve3d, const pc_step_spline *q)
{
    long curve2d, pcurve, surface_curve;
    projcurve_status st = pc_step_out_curve(ctx, &w->out, q, &curve2d);
    if (st == PROJCURVE_OK)
        st = pc_step_out_pcurve(ctx, &w->out, surface, curve2d, &pcurve);
    if (st == PROJCURVE_OK)
        st = pc_step_out_surface_curve(ctx, &w->out, curve3d, pcurve, &surface_curve);
    if (st == PROJCURVE_OK)
        st = pc_step_out_add_to_set(ctx, &w->out, surface_curve);
    return st;
}

static pc_step_spline view_of_segment(const pc_nurbs_curve *c, int dim)
{
    pc_step_spline v = view_of_nurbs(c);
    v.dim = dim;
    return v;
}

/* A branch joined across seams (docs/seams.md): one SURFACE_CURVE per
 * seam segment, each pcurve in the domain (io/seam_split.h). */
static projcurve_status add_seam_segments(projcurve_context *ctx, projcurve_step_writer *w,
                                          const projcurve_surface *s, long surface,
                                          const projcurve_result *r, size_t branch)
{
    const pc_branch *b = &r->branches[branch];
    projcurve_curve *q = NULL, *c = NULL;
    projcurve_status st = projcurve_result_branch_compact_pcurve(ctx, r, branch, &q);
    if (st == PROJCURVE_OK)
        st = b->compact_curve.n_poles > 0
                 ? projcurve_result_branch_compact_curve(ctx, r, branch, &c)
                 : projcurve_result_branch_curve(ctx, r, branch, &c);
    pc_seam_segment *seg = NULL;
    size_t n_seg = 0;
    if (st == PROJCURVE_OK)
        st = pc_seam_split(ctx, &q->nurbs, &c->nurbs, b->seams, b->n_seams, s->nurbs.domain,
                           &seg, &n_seg);
    for (size_t k = 0; st == PROJCURVE_OK && k < n_seg; ++k) {
        const pc_step_spline v3 = view_of_segment(&seg[k].curve, 3);
        const pc_step_spline v2 = view_of_segment(&seg[k].pcurve, 2);
        long curve3d;
        st = pc_step_out_curve(ctx, &w->out, &v3, &curve3d);
        if (st == PROJCURVE_OK)
            st = add_surface_curve(ctx, w, surface, curve3d, &v2);
    }
    pc_seam_segments_free(seg, n_seg);
    projcurve_curve_destroy(q);
    projcurve_curve_destroy(c);
    return st;
}

static projcurve_status add_branch(projcurve_context *ctx, projcurve_step_writer *w,
                                   const projcurve_surface *s, long surface,
                                   const projcurve_result *r, size_t branch)
{
    const pc_branch *b = &r->branches[branch];
    if (b->compact == PC_COMPACT_NONE || b->compact_pcurve.n_poles == 0)
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                       "branch %zu has no compact forms to write as STEP (it has no composed "
                       "pieces: PROJCURVE_OPT_COMPOSE 0, or a limit was reached before it)",
                       branch);
    if (b->n_seams > 0)
        return add_seam_segments(ctx, w, s, surface, r, branch);
    long curve3d;
    const pc_step_spline q = view_of_bspline(&b->compact_pcurve);
    const projcurve_status st = add_curve3d(ctx, w, r, branch, &curve3d);
    return st == PROJCURVE_OK ? add_surface_curve(ctx, w, surface, curve3d, &q) : st;
}

projcurve_status projcurve_step_writer_add_result(projcurve_context *ctx,
                                                  projcurve_step_writer *w,
                                                  const projcurve_surface *s,
                                                  const projcurve_result *r)
{
    PC_REQUIRE(ctx, w, "writer");
    PC_REQUIRE(ctx, s, "surface");
    PC_REQUIRE(ctx, r, "result");
    if (r->point_dim != 3)
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                       "the result is not on a parametric surface (implicit projection): it "
                       "has no pcurves to write as STEP");
    projcurve_status st = pc_result_check_surface(ctx, r, s);
    if (st != PROJCURVE_OK)
        return st;
    /* All or nothing: a failure part of the way leaves the writer as it
     * was, not with half a result in it. */
    const pc_step_mark mark = pc_step_out_mark(&w->out);
    long surface;
    st = pc_step_out_surface(ctx, &w->out, &s->nurbs, &surface);
    double gap = 0.0;
    for (size_t b = 0; st == PROJCURVE_OK && b < r->n_branches; ++b) {
        st = add_branch(ctx, w, s, surface, r, b);
        gap = fmax(gap, forms_gap(r, &r->branches[b]));
    }
    if (st != PROJCURVE_OK) {
        pc_step_out_rollback(&w->out, &mark);
        return st;
    }
    if (!w->uncertainty_set && isfinite(gap))
        w->out.uncertainty = fmax(w->out.uncertainty, gap);
    return PROJCURVE_OK;
}

/* Each piece of connected curve `curve` of r as a B-spline and a segment
 * over it; segs gets n entries, the transitions from whether consecutive
 * pieces meet within the chaining tolerance. */
static projcurve_status add_segments(projcurve_context *ctx, projcurve_step_writer *w,
                                     const projcurve_shape_result *r, size_t curve, int closed,
                                     pc_step_segment *segs, size_t n)
{
    const double tol = projcurve_shape_result_chain_tolerance(r);
    pc_shape_member first = {0}, prev = {0};
    projcurve_status st = PROJCURVE_OK;
    for (size_t k = 0; st == PROJCURVE_OK && k < n; ++k) {
        pc_shape_member m;
        if ((st = pc_shape_member_get(ctx, r, curve, k, &m)) != PROJCURVE_OK)
            break;
        const pc_step_spline view = view_of_nurbs(&m.curve->nurbs);
        st = pc_step_out_curve(ctx, &w->out, &view, &segs[k].curve);
        segs[k].same_sense = m.forward;
        if (k > 0)
            segs[k - 1].continuous = pc_shape_members_meet(&prev, &m, tol);
        pc_shape_member_free(&m); /* its ends are kept, its curve is written */
        if (k == 0)
            first = m;
        prev = m;
    }
    if (st == PROJCURVE_OK) /* an open composite ends with a discontinuity */
        segs[n - 1].continuous = closed && pc_shape_members_meet(&prev, &first, tol);
    return st;
}

static projcurve_status add_connected_curve(projcurve_context *ctx, projcurve_step_writer *w,
                                            const projcurve_shape_result *r, size_t curve)
{
    size_t n = 0;
    int closed = 0;
    projcurve_status st = projcurve_shape_result_curve_info(ctx, r, curve, &n, NULL, &closed);
    if (st != PROJCURVE_OK || n == 0)
        return st;
    pc_step_segment *segs = calloc(n, sizeof *segs);
    if (segs == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY,
                       "out of memory for the %zu segments of connected curve %zu", n, curve);
    st = add_segments(ctx, w, r, curve, closed, segs, n);
    long id;
    if (st == PROJCURVE_OK)
        st = pc_step_out_composite_curve(ctx, &w->out, segs, n, &id);
    if (st == PROJCURVE_OK)
        st = pc_step_out_add_to_set(ctx, &w->out, id);
    free(segs);
    return st;
}

projcurve_status projcurve_step_writer_add_shape_result(projcurve_context *ctx,
                                                        projcurve_step_writer *w,
                                                        const projcurve_shape_result *r)
{
    PC_REQUIRE(ctx, w, "writer");
    PC_REQUIRE(ctx, r, "shape result");
    const pc_step_mark mark = pc_step_out_mark(&w->out); /* all or nothing */
    projcurve_status st = PROJCURVE_OK;
    const size_t n = projcurve_shape_result_curve_count(r);
    for (size_t c = 0; st == PROJCURVE_OK && c < n; ++c)
        st = add_connected_curve(ctx, w, r, c);
    if (st != PROJCURVE_OK)
        pc_step_out_rollback(&w->out, &mark);
    return st;
}

projcurve_status projcurve_step_writer_set_length_unit(projcurve_context *ctx,
                                                       projcurve_step_writer *w,
                                                       double metres_per_unit)
{
    PC_REQUIRE(ctx, w, "writer");
    if (!isfinite(metres_per_unit))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "length unit is not finite");
    if (!(metres_per_unit > 0.0))
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE,
                       "length unit %.17g m is not positive", metres_per_unit);
    w->out.metres_per_unit = metres_per_unit;
    return PROJCURVE_OK;
}

projcurve_status projcurve_step_writer_set_uncertainty(projcurve_context *ctx,
                                                       projcurve_step_writer *w,
                                                       double distance)
{
    PC_REQUIRE(ctx, w, "writer");
    if (!isfinite(distance))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "uncertainty is not finite");
    if (!(distance > 0.0))
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE, "uncertainty %.17g is not positive",
                       distance);
    w->out.uncertainty = distance;
    w->uncertainty_set = 1;
    return PROJCURVE_OK;
}

projcurve_status projcurve_step_writer_write(projcurve_context *ctx,
                                             const projcurve_step_writer *w, const char *path)
{
    PC_REQUIRE(ctx, w, "writer");
    PC_REQUIRE(ctx, path, "path");
    return pc_step_out_write(ctx, &w->out, path);
}
