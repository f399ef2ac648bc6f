/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Many curves projected onto one surface in one call (docs/batch.md):
 * results indexed by source curve, optionally on several threads. Every
 * curve is an independent projection with its own parameters, budget and
 * context; the workers share only the read-only inputs, so the results do
 * not depend on the thread count.
 */
#ifndef PC_BATCH_BATCH_H
#define PC_BATCH_BATCH_H

#include <stddef.h>

#include "common/params.h"
#include "common/vec.h"
#include "geom/curve.h"
#include "geom/surface.h"

/* What every curve's budget is made from (pc_budget_init). */
typedef struct pc_batch_budget {
    double time_limit;
    unsigned long long max_work;
    projcurve_progress_fn progress; /* called under a lock: never concurrently */
    void *progress_user;
} pc_batch_budget;

/* Projects each curves[i] onto surface (directional along the unit dir,
 * or orthogonal when dir is NULL) with the parameters p (resolved by the
 * caller; p->budget is ignored: each curve gets its own from *budget) on
 * p->threads workers, the calling thread among them. results[i] gets the
 * result of curve i (NULL where its status keeps none), statuses[i] (may be
 * NULL) its status. A NULL curves[i] is NULL_ARGUMENT for that curve only.
 * Returns OK when every curve's status is OK, else the status of the
 * lowest-index curve whose status is not, with its message recorded in
 * ctx prefixed "curve i: ". Threads that cannot be started leave their
 * share to the others. */
projcurve_status pc_batch_project(projcurve_context *ctx, const projcurve_surface *surface,
                                  const projcurve_curve *const *curves, size_t n,
                                  const pc_vec3 *dir, const pc_params *p,
                                  const pc_batch_budget *budget, projcurve_result **results,
                                  projcurve_status *statuses);

#endif /* PC_BATCH_BATCH_H */
