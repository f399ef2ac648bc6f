/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Blossoming composer: a line segment (u, v)(s) in one Bezier patch's
 * parameter box, composed with the patch, is a Bezier curve of degree
 * deg_u + deg_v that lies exactly on the surface (rational if the patch is).
 */
#ifndef PC_COMPOSE_H
#define PC_COMPOSE_H

#include "bezier/bezier.h"

/* Control points of S(uv0 + s (uv1 - uv0)), s in [0, 1], for the segment
 * inside `patch` (both ends in its box). Writes deg_u + deg_v + 1
 * homogeneous points (4 doubles each) to cw_out. */
void pc_compose_segment(const pc_bezier_patch *patch, const double uv0[2], const double uv1[2],
                        double *cw_out);

/* Largest degree of a pcurve pc_compose_poly composes. */
#define PC_COMPOSE_POLY_MAX_DEGREE 3

/* Control points of S(u(s), v(s)), s in [0, 1], where (u, v)(s) is the
 * Bezier curve of `degree` (1..PC_COMPOSE_POLY_MAX_DEGREE) with the
 * degree + 1 (u, v) control points uv_ctrl, all inside `patch`'s box (then
 * the whole curve is). Writes degree (deg_u + deg_v) + 1 homogeneous points
 * (4 doubles each) to cw_out and returns that degree; -1 (nothing written)
 * when the degree is out of range or the result's degree would exceed
 * 2 PROJCURVE_MAX_DEGREE. */
int pc_compose_poly(const pc_bezier_patch *patch, int degree, const double *uv_ctrl,
                    double *cw_out);

/* The same for a rational (u, v) Bezier curve: Cartesian control points
 * uv_ctrl with positive weights (NULL: all 1, pc_compose_poly). The
 * composed curve has the same degree, its homogeneous points those of
 * S o (u, v) times a positive scalar polynomial. */
int pc_compose_poly_weighted(const pc_bezier_patch *patch, int degree, const double *uv_ctrl,
                             const double *weights, double *cw_out);

/* Cartesian control points (3 doubles each) and weights of a rational Bezier
 * curve given by degree + 1 homogeneous points (4 doubles each); weights must
 * be non-zero (they are positive for a NURBS patch). */
void pc_compose_to_cartesian(int degree, const double *cw, double *ctrl, double *weights);

#endif /* PC_COMPOSE_H */
