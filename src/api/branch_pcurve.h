/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The pcurve of a composed branch as one B-spline: the (u, v) curves of its
 * pieces (projcurve_result_piece_pcurve, degree 1 or 3) joined over the
 * curve parameter, as points (u, v, 0). S composed with it is the branch's
 * 3D curve (projcurve_result_branch_curve) at every t, which is what a curve
 * on surface (IGES 142) states.
 */
#ifndef PC_API_BRANCH_PCURVE_H
#define PC_API_BRANCH_PCURVE_H

#include <stddef.h>

#include "projcurve.h"

/* *out gets a curve to release with projcurve_curve_destroy.
 * Statuses: OK, INVALID_ARGUMENT (no composed pieces, or an implicit
 * result), INDEX, NO_MEMORY, and the curve creation statuses. */
projcurve_status pc_branch_pcurve(projcurve_context *ctx, const projcurve_result *r,
                                  size_t branch, projcurve_curve **out);

#endif /* PC_API_BRANCH_PCURVE_H */
