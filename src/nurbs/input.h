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
 * arithmetic (curves pass n_v = 1, degree_v = 0). */
projcurve_status pc_input_check_sizes(projcurve_context *ctx, int degree_u, size_t n_u,
                                      int degree_v, size_t n_v);

/* Checks points (NOT_FINITE) and weights (BAD_WEIGHT; NULL = all 1) and
 * returns a malloc'd homogeneous copy. *rational is 0 when all weights are 1. */
projcurve_status pc_input_homogeneous(projcurve_context *ctx, size_t n_points,
                                      const double *ctrl, const double *weights, double **cw_out,
                                      int *rational);

#endif /* PC_NURBS_INPUT_H */
