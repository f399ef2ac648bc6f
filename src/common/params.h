/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The parameters of one projection call as the engine reads them: the
 * caller's options after the entry point has checked them and resolved
 * eps_D to model units, the call's budget, and the knobs that only
 * white-box tests set. The public options handle (src/api/) is resolved
 * into this struct once per call; no stage below src/api/ sees the handle.
 */
#ifndef PC_COMMON_PARAMS_H
#define PC_COMMON_PARAMS_H

#include "common/budget.h"
#include "common/stage_clock.h"
#include "projcurve.h"

/* The defaults of the options that reach the engine (projcurve.h states
 * them; the options table of src/api/options.c reads them from here). */
#define PC_DEFAULT_TOL_DISTANCE 0.0 /* unset: automatic */
#define PC_DEFAULT_TOL_ANGLE_DEG 1.0
#define PC_DEFAULT_NEWTON_TOL 1e-12
#define PC_DEFAULT_NEWTON_MAX_ITER 20
#define PC_DEFAULT_ARC_STEP_FRACTION (1.0 / 64.0)
#define PC_DEFAULT_MAX_POINTS 100000
#define PC_DEFAULT_MAX_PIECES 50000
#define PC_DEFAULT_METHOD PROJCURVE_METHOD_SECOND_ORDER
#define PC_DEFAULT_PARAM_STEP 0.0 /* arc-length stepping */
#define PC_DEFAULT_COMPOSE 1
#define PC_DEFAULT_JUMP_DETECTION 1
#define PC_DEFAULT_PCURVE_DEGREE 3
#define PC_DEFAULT_FOOT_POINTS PROJCURVE_FOOT_POINTS_MINIMA
#define PC_DEFAULT_CURVE_DEGREE 5
#define PC_DEFAULT_HITS PROJCURVE_HITS_ALL
#define PC_DEFAULT_MAX_DISTANCE 0.0 /* no limit */
#define PC_DEFAULT_THREADS 1

/* Automatic eps_D, while TOL_DISTANCE is unset: this fraction of the model
 * size (projcurve.h). */
#define PC_AUTO_TOL_DISTANCE 1e-4
/* The smallest eps_D a projection accepts, relative to the model size: the
 * points of the exact projection carry the rounding of double-precision
 * evaluations, ~1e-15 of the size, and the refinement measures distances
 * to ~1e-13 of it; below 1e-12 it would chase rounding (and split branches
 * where it cannot follow it) rather than the curve. */
#define PC_MIN_TOL_DISTANCE 1e-12

/* The options the engine reads, X(type, field), each the value of the
 * PROJCURVE_OPT_ key of that name: the one list from which both pc_params
 * and the options handle (api/options.h) declare their fields and the
 * handle is copied into the parameters, so the two cannot drift apart. */
#define PC_PARAMS_OPTIONS(X)                                                               \
    X(double, tol_distance)      /* eps_D; 0 = unset: automatic */                         \
    X(double, tol_angle_deg)     /* eps_T */                                               \
    X(double, newton_tol)        /* relative to model size */                              \
    X(long long, newton_max_iter)                                                          \
    X(long long, method)         /* PROJCURVE_METHOD_* */                                  \
    X(double, param_step)        /* 0 = arc-length stepping */                             \
    X(double, arc_step_fraction)                                                           \
    X(long long, max_points)                                                               \
    X(long long, max_pieces)                                                               \
    X(long long, compose)                                                                  \
    X(long long, jump_detection)                                                           \
    X(long long, pcurve_degree)  /* 1 or 3 */                                              \
    X(long long, foot_points)    /* PROJCURVE_FOOT_POINTS_* */                             \
    X(long long, curve_degree)   /* of the compact 3D curve (fit/) */                      \
    X(long long, hits)           /* PROJCURVE_HITS_*: all, or the nearest (hits/) */       \
    X(double, max_distance)      /* hits within this of P(t) (hits/); 0 = no limit */      \
    X(long long, threads)        /* workers of the many-curve calls (batch/) */

#define PC_PARAMS_DECLARE_FIELD(type, field) type field;

typedef struct pc_params {
    /* tol_distance is in model units once the entry point has resolved it
     * (pc_params_distance_tolerance); 0 before. */
    PC_PARAMS_OPTIONS(PC_PARAMS_DECLARE_FIELD)
    /* The budget of the call under way, made by the entry point from
     * TIME_LIMIT, MAX_WORK and the progress callback; NULL: no budget. */
    pc_budget *budget;
    /* Not an option, for white-box tests only: 1 makes the jump sweep
     * search in full only where the criteria of [SY13] s3.4 ask (no
     * periodic full search), so that tests can show what the criteria
     * alone find. 0 in every projection a caller can ask for. */
    int sweep_criteria_only;
    /* Not an option: 0 skips the compact fits (fit/), so that the
     * benchmark can time what they add. 1 in every projection a caller
     * can ask for. */
    int compact;
    /* Not an option, for white-box tests only: 0 leaves the branches split
     * at seams and poles (seam/), the tracer's own output, so that tests
     * can show what joining changes. 1 in every projection a caller can
     * ask for. */
    int join_seams;
    /* Not an option: where set, each stage adds its CPU time here
     * (common/stage_clock.h), for the benchmark's profile. NULL in every
     * projection a caller can ask for. */
    pc_stage_clock *stages;
} pc_params;

/* Fills p with the default of every option, eps_D unset, no budget. */
void pc_params_defaults(pc_params *p);

/* eps_D for a model of size model_size (> 0): p's tol_distance, or
 * PC_AUTO_TOL_DISTANCE of the size while it is 0. A value below
 * pc_params_precision of the size cannot be met (the corrector places the
 * exact points only that closely) and is OUT_OF_RANGE, with a message
 * naming both. */
projcurve_status pc_params_distance_tolerance(projcurve_context *ctx, const pc_params *p,
                                              double model_size, double *eps_d);

/* The precision of the exact points, relative to the model size:
 * max(NEWTON_TOL, PC_MIN_TOL_DISTANCE). */
double pc_params_precision(const pc_params *p);

#endif /* PC_COMMON_PARAMS_H */
