/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Branches of the parametric orthogonal projection that carry nothing of
 * their own, removed after tracing and the split at centres of curvature:
 *  - branches of no extent in t (all vertices at one curve parameter);
 *  - branches that retrace another: every vertex is, on S, the foot point
 *    of the other branch at the same t. The engine matches new seeds to
 *    live branches, but a branch cut by ortho_centres.c where the tracer
 *    went across a fold onto another foot point keeps, as its tail, a copy
 *    of the branch it landed on; so can a curve whose foot point runs
 *    along the seam of a closed surface, where (0, v) and (1, v) are one
 *    point of S.
 */
#ifndef PC_ORTHO_DUPLICATES_H
#define PC_ORTHO_DUPLICATES_H

#include "trace/projector.h"
#include "trace/result.h"

/* Removes those branches from r (points (t, u, v)), keeping of two copies
 * the one with the larger t-range (the earlier on a tie). */
void pc_ortho_drop_duplicates(const pc_projector *proj, projcurve_result *r);

#endif /* PC_ORTHO_DUPLICATES_H */
