/*
 * Helpers shared by the projection entry points (directional, orthogonal).
 */
#ifndef PC_API_PROJECT_H
#define PC_API_PROJECT_H

#include "api/handles.h"

/* Copies opts (defaults when NULL) into *out after checking every value
 * against the bounds projcurve_option_info tells (a handle can only hold
 * valid values; this guards against a corrupted one).
 * Statuses: OK, OUT_OF_RANGE, NOT_FINITE. */
projcurve_status pc_options_resolve(projcurve_context *ctx, const projcurve_options *opts,
                                    struct projcurve_options *out);

/* pc_options_resolve, then eps_D for a model of size model_size (0 counts
 * as 1) by pc_options_distance_tolerance, written into out->tol_distance:
 * every later stage reads the one resolved value. Statuses: those two's. */
projcurve_status pc_projection_options(projcurve_context *ctx, const projcurve_options *opts,
                                       double model_size, struct projcurve_options *out);

/* Makes the call's budget from o's TIME_LIMIT, MAX_WORK and progress
 * callback and points o->budget at it (o: the call's resolved copy). */
void pc_projection_budget(pc_budget *b, struct projcurve_options *o);

/* 1 for the statuses with which a projection still returns its result:
 * OK and the partial results of LIMIT_REACHED and CANCELLED. */
static inline int pc_status_keeps_result(projcurve_status st)
{
    return st == PROJCURVE_OK || st == PROJCURVE_ERR_LIMIT_REACHED ||
           st == PROJCURVE_ERR_CANCELLED;
}

#endif /* PC_API_PROJECT_H */
