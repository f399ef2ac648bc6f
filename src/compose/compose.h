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

/* Cartesian control points (3 doubles each) and weights of a rational Bezier
 * curve given by degree + 1 homogeneous points (4 doubles each); weights must
 * be non-zero (they are positive for a NURBS patch). */
void pc_compose_to_cartesian(int degree, const double *cw, double *ctrl, double *weights);

#endif /* PC_COMPOSE_H */
