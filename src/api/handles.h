/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The layout behind the public opaque handles. Only the library sees it.
 */
#ifndef PC_API_HANDLES_H
#define PC_API_HANDLES_H

#include "bezier/bezier.h"
#include "bezier/bvh.h"
#include "bezier/tangent_boxes.h"
#include "common/budget.h"
#include "nurbs/nurbs.h"
#include "projcurve.h"

struct projcurve_surface {
    pc_nurbs_surface nurbs;
    pc_patch_grid grid;   /* Bezier patches, built at creation */
    pc_bvh bvh;           /* over grid.patches, built at creation */
    pc_tangent_boxes tangents; /* of Su, Sv over the BVH nodes, at creation */
    double box[6];        /* bounding box of the control net */
    double size;          /* its diagonal: the model scale for relative tolerances */
};

typedef enum pc_curve_kind { PC_CURVE_NURBS = 0, PC_CURVE_CALLBACK = 1 } pc_curve_kind;

struct projcurve_curve {
    pc_curve_kind kind;
    double t0, t1;
    pc_nurbs_curve nurbs;      /* PC_CURVE_NURBS */
    projcurve_curve_fn fn;     /* PC_CURVE_CALLBACK */
    void *user;
};

/* Point and derivatives up to order n_deriv (<= 2 for callbacks, <= 3 for
 * NURBS) of any curve, t clamped to the domain; out[0..n_deriv]. Returns OK,
 * or CALLBACK when a user callback fails or gives a non-finite value.
 * hint may be NULL. */
projcurve_status pc_curve_eval(const projcurve_curve *c, double t, int n_deriv, size_t *hint,
                               pc_vec3 *out);

struct projcurve_options {
    double tol_distance;       /* eps_D; 0 = unset, automatic (setters reject 0) */
    double tol_angle_deg;      /* eps_T */
    double newton_tol;         /* relative to model size */
    long long newton_max_iter;
    long long method;          /* PROJCURVE_METHOD_* */
    double param_step;         /* 0 = arc-length stepping */
    double arc_step_fraction;
    long long max_points;
    long long max_pieces;
    long long compose;
    long long jump_detection;
    long long pcurve_degree;   /* 1 or 3: PROJCURVE_OPT_PCURVE_DEGREE */
    long long foot_points;     /* PROJCURVE_FOOT_POINTS_*: PROJCURVE_OPT_FOOT_POINTS */
    double time_limit;         /* seconds per call, 0 = none: PROJCURVE_OPT_TIME_LIMIT */
    long long max_work;        /* units per call, 0 = none: PROJCURVE_OPT_MAX_WORK */
    long long curve_degree;    /* of the compact 3D curve: PROJCURVE_OPT_CURVE_DEGREE */
    projcurve_progress_fn progress; /* projcurve_options_set_progress; NULL = none */
    void *progress_user;
    /* Not an option: the budget of the call under way, made from the
     * fields above by the entry point in its resolved copy of the options
     * (pc_projection_budget), so that every stage handed the options can
     * poll it. NULL in a handle and outside a projection call: no budget. */
    pc_budget *budget;
    /* No option key, not in the public API: 1 makes the jump sweep search
     * in full only where the criteria of [SY13] s3.4 ask (no periodic
     * full search), so that tests can show what the criteria alone find.
     * 0 (the default) in every projection a caller can ask for. */
    long long sweep_criteria_only;
    /* No option key, not in the public API: 0 skips the compact fits
     * (fit/), so that the benchmark can time what they add. 1 (the
     * default) in every projection a caller can ask for. */
    long long compact;
};

/* Fills o with every default (used when the caller passes NULL options). */
void pc_options_defaults(struct projcurve_options *o);

/* Automatic eps_D, while TOL_DISTANCE is unset: this fraction of the model
 * size (projcurve.h). */
#define PC_AUTO_TOL_DISTANCE 1e-4
/* The smallest eps_D a projection accepts, relative to the model size: the
 * points of the exact projection carry the rounding of double-precision
 * evaluations, ~1e-15 of the size, and the refinement measures distances
 * to ~1e-13 of it; below 1e-12 it would chase rounding (and split branches
 * where it cannot follow it) rather than the curve. */
#define PC_MIN_TOL_DISTANCE 1e-12

/* eps_D for a model of size model_size (> 0): the caller's TOL_DISTANCE,
 * or PC_AUTO_TOL_DISTANCE of the size while unset. A caller's value below
 * max(NEWTON_TOL, PC_MIN_TOL_DISTANCE) of the size cannot be met (the
 * corrector places the exact points only that closely) and is
 * OUT_OF_RANGE, with a message naming both. */
projcurve_status pc_options_distance_tolerance(projcurve_context *ctx,
                                               const struct projcurve_options *o,
                                               double model_size, double *eps_d);

#endif /* PC_API_HANDLES_H */
