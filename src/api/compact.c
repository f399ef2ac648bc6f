/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The compact forms of a branch (fit/) as curve handles: the pcurve as
 * points (u, v, 0), the 3D curve as it is, the pcurve composed with S
 * exactly (exact/); and what the fit measured.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "common/error.h"
#include "exact/exact.h"
#include "trace/result.h"

static projcurve_status compact_branch(projcurve_context *ctx, const projcurve_result *r,
                                       size_t branch, const pc_branch **out)
{
    PC_REQUIRE(ctx, r, "result");
    if (branch >= r->n_branches)
        return pc_fail(ctx, PROJCURVE_ERR_INDEX, "branch %zu of %zu", branch, r->n_branches);
    const pc_branch *b = &r->branches[branch];
    if (b->compact == PC_COMPACT_NONE)
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                       r->point_dim != 3 ? "a result on an implicit surface has no compact "
                                           "forms (no (u, v)); read its pieces"
                                         : "branch %zu has no compact forms: it has no "
                                           "composed pieces (PROJCURVE_OPT_COMPOSE 0, or a "
                                           "limit was reached before it)",
                       branch);
    *out = b;
    return PROJCURVE_OK;
}

/* A curve handle from a kept B-spline, 2D poles lifted to z = 0. */
static projcurve_status handle_of(projcurve_context *ctx, const pc_bspline *s,
                                  projcurve_curve **out)
{
    if (s->n_poles > SIZE_MAX / (3 * sizeof(double)))
        return pc_fail(ctx, PROJCURVE_ERR_OVERFLOW, "%zu poles overflow", s->n_poles);
    double *xyz = malloc(3 * s->n_poles * sizeof *xyz);
    if (xyz == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for a compact curve");
    const size_t dim = (size_t)s->dim;
    for (size_t i = 0; i < s->n_poles; ++i)
        for (size_t k = 0; k < 3; ++k)
            xyz[3 * i + k] = k < dim ? s->poles[dim * i + k] : 0.0;
    const projcurve_status st =
        projcurve_curve_create_nurbs(ctx, s->degree, s->n_poles, xyz, s->weights, s->knots, out);
    free(xyz);
    return st;
}

/* The compact 3D curve (curve3d) or pcurve of a branch as a handle. */
static projcurve_status compact_handle(projcurve_context *ctx, const projcurve_result *r,
                                       size_t branch, int curve3d, projcurve_curve **out)
{
    const pc_branch *b = NULL;
    projcurve_status st = compact_branch(ctx, r, branch, &b);
    if (st != PROJCURVE_OK)
        return st;
    PC_REQUIRE(ctx, out, "out");
    if (!curve3d)
        return handle_of(ctx, &b->compact_pcurve, out);
    if (b->compact_curve.n_poles == 0)
        return pc_fail(ctx, PROJCURVE_ERR_LIMIT_REACHED,
                       "branch %zu: no compact 3D curve within eps_D was found within the "
                       "fit's bounds (or the call's budget stopped it); the branch's pieces "
                       "(projcurve_result_branch_curve) and its compact pcurve are exact",
                       branch);
    return handle_of(ctx, &b->compact_curve, out);
}

projcurve_status projcurve_result_branch_compact_pcurve(projcurve_context *ctx,
                                                        const projcurve_result *result,
                                                        size_t branch, projcurve_curve **out)
{
    return compact_handle(ctx, result, branch, 0, out);
}

projcurve_status projcurve_result_branch_compact_curve(projcurve_context *ctx,
                                                       const projcurve_result *result,
                                                       size_t branch, projcurve_curve **out)
{
    return compact_handle(ctx, result, branch, 1, out);
}

projcurve_status projcurve_result_branch_compact_info(projcurve_context *ctx,
                                                      const projcurve_result *result,
                                                      size_t branch, int *pcurve_fitted,
                                                      double *pcurve_error,
                                                      double *curve_error)
{
    const pc_branch *b = NULL;
    projcurve_status st = compact_branch(ctx, result, branch, &b);
    if (st != PROJCURVE_OK)
        return st;
    if (pcurve_fitted)
        *pcurve_fitted = b->compact == PC_COMPACT_FITTED;
    if (pcurve_error)
        *pcurve_error = b->compact_pcurve_error;
    if (curve_error)
        *curve_error = b->compact_curve_error;
    return PROJCURVE_OK;
}

/* The point of b's pieces at t (an end of the first or last piece), or 0
 * when no piece ends there. */
static int piece_point_at(const pc_branch *b, double t, double x[3])
{
    for (size_t k = 0; k < 2 && b->n_pieces > 0; ++k) {
        const pc_piece *p = &b->pieces[k == 0 ? 0 : b->n_pieces - 1];
        const int at = p->t0 == t ? 0 : (p->t1 == t ? p->degree : -1);
        if (at >= 0) {
            for (int c = 0; c < 3; ++c)
                x[c] = p->ctrl[3 * at + c];
            return 1;
        }
    }
    return 0;
}

/* The surface passed must be the one projected onto: S(q(t)) at the
 * start of the branch, the exact curve's first pole, is then within the
 * pcurve's fit of the pieces' start (both within eps_D of one exact
 * point; 4 eps_D leaves room for the rounding of a loose fit), and on
 * another surface it is as far as the surfaces are apart. */
static projcurve_status check_surface(projcurve_context *ctx, const projcurve_result *r,
                                      const projcurve_surface *s, const pc_branch *b,
                                      size_t branch, const pc_bspline *exact)
{
    double x[3];
    if (!piece_point_at(b, exact->knots[0], x))
        return PROJCURVE_OK;
    const double tol = 4.0 * r->stats.tol_distance + 1e-9 * s->size;
    double d2 = 0.0;
    for (int c = 0; c < 3; ++c)
        d2 += (exact->poles[c] - x[c]) * (exact->poles[c] - x[c]);
    if (!(sqrt(d2) <= tol))
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                       "branch %zu was not projected onto this surface: its start is %g "
                       "from S(q(t)) there (more than %g)",
                       branch, sqrt(d2), tol);
    return PROJCURVE_OK;
}

projcurve_status projcurve_result_branch_compact_exact(projcurve_context *ctx,
                                                       const projcurve_result *result,
                                                       const projcurve_surface *surface,
                                                       size_t branch, projcurve_curve **out)
{
    const pc_branch *b = NULL;
    projcurve_status st = compact_branch(ctx, result, branch, &b);
    if (st != PROJCURVE_OK)
        return st;
    PC_REQUIRE(ctx, surface, "surface");
    PC_REQUIRE(ctx, out, "out");
    pc_bspline exact = {0};
    st = pc_exact_compose(ctx, surface, b, &exact);
    if (st == PROJCURVE_OK)
        st = check_surface(ctx, result, surface, b, branch, &exact);
    if (st == PROJCURVE_OK)
        st = projcurve_curve_create_nurbs(ctx, exact.degree, exact.n_poles, exact.poles,
                                          exact.weights, exact.knots, out);
    pc_bspline_free(&exact);
    return st;
}
