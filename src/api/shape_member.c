/* SPDX-License-Identifier: BSD-3-Clause */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "api/shape_member.h"
#include "common/error.h"

projcurve_status pc_branch_curve3d(projcurve_context *ctx, const projcurve_result *r,
                                   size_t branch, int compact, projcurve_curve **c)
{
    projcurve_status st = PROJCURVE_ERR_LIMIT_REACHED;
    if (compact) /* without ctx: a missing compact form is no failure here */
        st = projcurve_result_branch_compact_curve(NULL, r, branch, c);
    if (st == PROJCURVE_ERR_NO_MEMORY)
        return pc_fail(ctx, st, "out of memory for the compact curve of branch %zu", branch);
    if (st == PROJCURVE_ERR_LIMIT_REACHED || st == PROJCURVE_ERR_INVALID_ARGUMENT)
        st = projcurve_result_branch_curve(ctx, r, branch, c);
    return st;
}

/* The curve's point at the end of its domain where t is t0 (which == 0)
 * or t1. */
static projcurve_status end_point(projcurve_context *ctx, const projcurve_curve *c, int which,
                                  double x[3])
{
    double t0 = 0.0, t1 = 0.0;
    projcurve_status st = projcurve_curve_domain(ctx, c, &t0, &t1);
    if (st == PROJCURVE_OK)
        st = projcurve_curve_eval(ctx, c, which == 0 ? t0 : t1, 0, x);
    return st;
}

projcurve_status pc_shape_member_get(projcurve_context *ctx, const projcurve_shape_result *r,
                                     size_t curve, size_t piece, pc_shape_member *m)
{
    memset(m, 0, sizeof *m);
    const projcurve_result *fr = NULL;
    size_t branch = 0;
    double t[2] = {0.0, 0.0};
    projcurve_status st =
        projcurve_shape_result_piece(ctx, r, curve, piece, NULL, &fr, &branch, t, NULL, NULL);
    if (st != PROJCURVE_OK)
        return st;
    projcurve_curve *c = NULL;
    st = pc_branch_curve3d(ctx, fr, branch, 1, &c);
    if (st == PROJCURVE_ERR_INVALID_ARGUMENT) { /* say which piece it is */
        char why[256];
        snprintf(why, sizeof why, "%s", ctx ? projcurve_context_message(ctx) : "");
        return pc_fail(ctx, st, "connected curve %zu, piece %zu: %s", curve, piece, why);
    }
    if (st != PROJCURVE_OK)
        return st;
    /* a branch traced with t decreasing is entered at its t1 end */
    const int forward = !(t[0] > t[1]);
    st = end_point(ctx, c, forward ? 0 : 1, m->first);
    if (st == PROJCURVE_OK)
        st = end_point(ctx, c, forward ? 1 : 0, m->last);
    if (st != PROJCURVE_OK) {
        projcurve_curve_destroy(c);
        memset(m, 0, sizeof *m);
        return st;
    }
    m->curve = c;
    m->forward = forward;
    return PROJCURVE_OK;
}

void pc_shape_member_free(pc_shape_member *m)
{
    projcurve_curve_destroy(m->curve);
    m->curve = NULL;
}

int pc_shape_members_meet(const pc_shape_member *a, const pc_shape_member *b, double tol)
{
    const double d[3] = {a->last[0] - b->first[0], a->last[1] - b->first[1],
                         a->last[2] - b->first[2]};
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) <= tol;
}
