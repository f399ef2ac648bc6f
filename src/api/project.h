/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * What the projection entry points (directional, orthogonal) share: the
 * resolution of the caller's options into the engine's parameters.
 */
#ifndef PC_API_PROJECT_H
#define PC_API_PROJECT_H

#include "api/options.h"
#include "common/budget.h"
#include "common/params.h"
#include "common/vec.h"

/* The parameters of a projection onto a model of size model_size (0
 * counts as 1) from opts (defaults when NULL): every value checked
 * against its bounds (pc_options_check), eps_D resolved to model units
 * (pc_params_distance_tolerance), TOL_ANGLE_DEG checked against what the
 * refinement resolves when COMPOSE is on, and *budget made from
 * TIME_LIMIT, MAX_WORK and the progress callback and set in out->budget.
 * Statuses: OK, OUT_OF_RANGE, NOT_FINITE; *out is only complete on OK. */
projcurve_status pc_projection_params(projcurve_context *ctx, const projcurve_options *opts,
                                      double model_size, pc_budget *budget, pc_params *out);

/* The unit vector along dir; statuses OK, NOT_FINITE, ZERO_DIRECTION. */
projcurve_status pc_unit_direction(projcurve_context *ctx, const double dir[3], pc_vec3 *out);

#endif /* PC_API_PROJECT_H */
