/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Defaults of the engine's parameters and the resolution of eps_D.
 */
#include "common/params.h"

#include <math.h>

#include "common/error.h"

void pc_params_defaults(pc_params *p)
{
    *p = (pc_params){
        .tol_distance = PC_DEFAULT_TOL_DISTANCE,
        .tol_angle_deg = PC_DEFAULT_TOL_ANGLE_DEG,
        .newton_tol = PC_DEFAULT_NEWTON_TOL,
        .newton_max_iter = PC_DEFAULT_NEWTON_MAX_ITER,
        .method = PC_DEFAULT_METHOD,
        .param_step = PC_DEFAULT_PARAM_STEP,
        .arc_step_fraction = PC_DEFAULT_ARC_STEP_FRACTION,
        .max_points = PC_DEFAULT_MAX_POINTS,
        .max_pieces = PC_DEFAULT_MAX_PIECES,
        .compose = PC_DEFAULT_COMPOSE,
        .jump_detection = PC_DEFAULT_JUMP_DETECTION,
        .pcurve_degree = PC_DEFAULT_PCURVE_DEGREE,
        .foot_points = PC_DEFAULT_FOOT_POINTS,
        .curve_degree = PC_DEFAULT_CURVE_DEGREE,
        .hits = PC_DEFAULT_HITS,
        .max_distance = PC_DEFAULT_MAX_DISTANCE,
        .threads = PC_DEFAULT_THREADS,
        .budget = NULL,
        .sweep_criteria_only = 0,
        .compact = 1,
        .join_seams = 1,
        .stages = NULL,
    };
}

double pc_params_precision(const pc_params *p)
{
    return fmax(p->newton_tol, PC_MIN_TOL_DISTANCE);
}

projcurve_status pc_params_distance_tolerance(projcurve_context *ctx, const pc_params *p,
                                              double model_size, double *eps_d)
{
    if (!(p->tol_distance > 0.0)) {
        *eps_d = PC_AUTO_TOL_DISTANCE * model_size;
        return PROJCURVE_OK;
    }
    const double floor_rel = pc_params_precision(p);
    if (p->tol_distance < floor_rel * model_size)
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE,
                       "option TOL_DISTANCE: %g is below %g, what this model allows "
                       "(%g of its size %g: NEWTON_TOL or the rounding of double precision)",
                       p->tol_distance, floor_rel * model_size, floor_rel, model_size);
    *eps_d = p->tol_distance;
    return PROJCURVE_OK;
}
