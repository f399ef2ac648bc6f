/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Helpers shared by the projection entry points (directional, orthogonal).
 */
#ifndef PC_API_PROJECT_H
#define PC_API_PROJECT_H

#include "api/handles.h"
#include "trace/projector.h"

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

/* The progress fraction where composing ends and fitting the compact
 * forms begins (fit/), in a composing projection. */
#define PC_PROJECT_FIT_FROM 0.9

/* The compact forms of r's branches (pc_fit_result), in the budget's
 * stage [PC_PROJECT_FIT_FROM, 1], after verification; st is the call's
 * status so far, returned unless the fit fails (NO_MEMORY always wins,
 * a budget stop only over OK). */
projcurve_status pc_project_fit(projcurve_context *ctx, const pc_projector *proj,
                                const struct projcurve_options *o, projcurve_result *r,
                                projcurve_status st);

/* 1 for the statuses with which a projection still returns its result:
 * OK and the partial results of LIMIT_REACHED and CANCELLED. */
static inline int pc_status_keeps_result(projcurve_status st)
{
    return st == PROJCURVE_OK || st == PROJCURVE_ERR_LIMIT_REACHED ||
           st == PROJCURVE_ERR_CANCELLED;
}

/* A curve whose image is one point within tol (model units): every
 * control point of a NURBS curve within tol of the first (the curve lies in
 * their convex hull), or for a callback curve P and (t1 - t0) P' at 33
 * evenly spread parameters. Such a curve is refused by the projections
 * with PROJCURVE_ERR_SINGULAR (its projection is that of a point, and the
 * tracer's arc-length steps are undefined on it): pc_refuse_point_curve. */
int pc_curve_is_point(const projcurve_curve *c, double tol);

/* SINGULAR with a message naming the point and the functions that project
 * it when curve is a point to the precision of a model of size model_size
 * (max(NEWTON_TOL, PC_MIN_TOL_DISTANCE) of it); OK otherwise. */
projcurve_status pc_refuse_point_curve(projcurve_context *ctx, const projcurve_curve *curve,
                                       const struct projcurve_options *o, double model_size);

#endif /* PC_API_PROJECT_H */
