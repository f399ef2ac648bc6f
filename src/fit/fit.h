/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Compact results: per composed branch, one light B-spline pcurve q(t)
 * (S o q lies exactly on S) and one 3D B-spline of a chosen degree, each
 * within eps_D of the exact projection, in place of the hundreds of Bezier
 * pieces of degree p + q. See docs/fit.md.
 */
#ifndef PC_FIT_H
#define PC_FIT_H

#include "common/params.h"
#include "trace/projector.h"
#include "trace/result.h"

/* The degree of the compact pcurve. */
#define PC_FIT_PCURVE_DEGREE 3

/* For every branch of r (a parametric result, point_dim 3) whose pieces
 * follow one another in t: its compact pcurve (fitted, or its pieces'
 * pcurves joined when the fit hits its bound) and compact 3D curve of
 * degree p->curve_degree (none when that fit hits its bound), kept in
 * the branch (pc_branch.compact*). p->budget (may be NULL) is polled
 * once per exact point and once per round of an adaptive fit; once it
 * stops, the branches left get the joined
 * pcurve and no 3D curve. Statuses: OK, NO_MEMORY, and the budget's
 * LIMIT_REACHED or CANCELLED (recorded in ctx). */
projcurve_status pc_fit_result(projcurve_context *ctx, const pc_projector *proj,
                               const pc_params *p, projcurve_result *r);

/* The progress fraction where composing ends and fitting the compact
 * forms begins, in a composing projection. */
#define PC_FIT_STAGE_FROM 0.9

/* The fitting stage of a projection driver (directional/, ortho/), after
 * verification: pc_fit_result in the budget's stage [PC_FIT_STAGE_FROM,
 * 1] when p->compose and st keeps a result (pc_status_keeps_result), and
 * p->compact (the benchmark's switch) is on. st is the call's status so
 * far, returned unless the fit fails: NO_MEMORY always wins, a budget
 * stop only over OK (the fits left get the joined pcurve). */
projcurve_status pc_fit_stage(projcurve_context *ctx, const pc_projector *proj,
                              const pc_params *p, projcurve_result *r, projcurve_status st);

#endif /* PC_FIT_H */
