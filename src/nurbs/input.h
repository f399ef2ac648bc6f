/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Shared checks of user input for curve and surface creation.
 */
#ifndef PC_NURBS_INPUT_H
#define PC_NURBS_INPUT_H

#include <stddef.h>
#include <stdint.h>

#include "nurbs/nurbs.h"

/* Degree in [1, PROJCURVE_MAX_DEGREE] (BAD_DEGREE) and at least degree + 1
 * control points (BAD_COUNT). `name` is "degree", "degree u", ... */
projcurve_status pc_input_check_degree(projcurve_context *ctx, const char *name, int degree,
                                       size_t n_ctrl);

/* OVERFLOW unless every array derived from an n_u x n_v net fits in memory
 * arithmetic (curves pass n_v = 1, degree_v = 0); OUT_OF_RANGE when
 * n_u * n_v passes the context's PROJCURVE_LIMIT_CONTROL_POINTS. */
projcurve_status pc_input_check_sizes(projcurve_context *ctx, int degree_u, size_t n_u,
                                      int degree_v, size_t n_v);

/* Checks points (NOT_FINITE) and weights (BAD_WEIGHT; NULL = all 1) and
 * returns a malloc'd homogeneous copy. *rational is 0 when all weights are 1. */
projcurve_status pc_input_homogeneous(projcurve_context *ctx, size_t n_points,
                                      const double *ctrl, const double *weights, double **cw_out,
                                      int *rational);

/* Limits of what the projections compute reliably in double precision
 * (squares of derivatives and coordinates must not overflow or underflow,
 * and a domain must hold enough distinct doubles for the tracer's steps):
 * parameters at most PC_INPUT_MAX_PARAM in magnitude, a domain at least
 * PC_INPUT_MIN_WIDTH wide and at least PC_INPUT_MIN_REL_WIDTH times its
 * largest end; coordinates at most PC_INPUT_MAX_COORD in magnitude and a
 * control polygon, unless it is a single point, at least
 * PC_INPUT_MIN_EXTENT across. Outside them creation is refused. */
#define PC_INPUT_MAX_PARAM 1e30
#define PC_INPUT_MIN_WIDTH 1e-30
#define PC_INPUT_MIN_REL_WIDTH 0x1p-32
#define PC_INPUT_MAX_COORD 1e30
#define PC_INPUT_MIN_EXTENT 1e-30

/* OUT_OF_RANGE unless [t0, t1] lies within the limits above. `name` is
 * "curve domain", "surface domain u", ... */
projcurve_status pc_input_check_domain(projcurve_context *ctx, const char *name, double t0,
                                       double t1);
/* OUT_OF_RANGE unless the n_points control points (3 doubles each) lie
 * within the coordinate limits above (called after pc_input_homogeneous,
 * which reports non-finite ones). */
projcurve_status pc_input_check_extent(projcurve_context *ctx, size_t n_points,
                                       const double *ctrl);

#endif /* PC_NURBS_INPUT_H */
