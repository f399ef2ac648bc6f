/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The seam records of a branch (seam/): where its pcurve jumps.
 */
#include "common/error.h"
#include "trace/result.h"

static projcurve_status seam_branch(projcurve_context *ctx, const projcurve_result *r,
                                    size_t branch, const pc_branch **out)
{
    PC_REQUIRE(ctx, r, "result");
    if (branch >= r->n_branches)
        return pc_fail(ctx, PROJCURVE_ERR_INDEX, "branch %zu of %zu", branch, r->n_branches);
    *out = &r->branches[branch];
    return PROJCURVE_OK;
}

projcurve_status projcurve_result_branch_seam_count(projcurve_context *ctx,
                                                    const projcurve_result *result,
                                                    size_t branch, size_t *count)
{
    PC_REQUIRE(ctx, count, "count");
    const pc_branch *b = NULL;
    const projcurve_status st = seam_branch(ctx, result, branch, &b);
    if (st == PROJCURVE_OK)
        *count = b->n_seams;
    return st;
}

projcurve_status projcurve_result_branch_seam(projcurve_context *ctx,
                                              const projcurve_result *result, size_t branch,
                                              size_t k, double *t, double *du, double *dv)
{
    const pc_branch *b = NULL;
    const projcurve_status st = seam_branch(ctx, result, branch, &b);
    if (st != PROJCURVE_OK)
        return st;
    if (k >= b->n_seams)
        return pc_fail(ctx, PROJCURVE_ERR_INDEX, "seam %zu of %zu on branch %zu", k, b->n_seams,
                       branch);
    if (t != NULL)
        *t = b->seams[k].t;
    if (du != NULL)
        *du = b->seams[k].du;
    if (dv != NULL)
        *dv = b->seams[k].dv;
    return PROJCURVE_OK;
}
