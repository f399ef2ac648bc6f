/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Query-independent properties of a Bezier control net (net.c).
 */
#ifndef PC_BEZIER_NET_H
#define PC_BEZIER_NET_H

#include <stddef.h>

#include "common/vec.h"

/* Cartesian points (3 doubles each) of n homogeneous points and their box,
 * which contains the patch by the convex hull property (weights > 0). */
void pc_bezier_net_cartesian(const double *cw, size_t n, double *xyz, double box[6]);

/* Largest distance of a control point of the (p+1) x (q+1) Cartesian net
 * from the bilinear interpolant of its four corners, relative to the
 * diagonal of the net's box (0 for a net of one point). */
double pc_bezier_net_flatness(const double *xyz, int p, int q, const double box[6]);

#endif /* PC_BEZIER_NET_H */
