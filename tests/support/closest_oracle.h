/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A brute-force oracle for the closest point of a surface: dense sampling,
 * then a pattern search from every local minimum of the samples. It uses
 * only the public evaluation (and the knot spans, to place samples), none
 * of the library's Newton, subdivision or BVH, so it checks them
 * independently.
 */
#ifndef PC_TEST_CLOSEST_ORACLE_H
#define PC_TEST_CLOSEST_ORACLE_H

#include "projcurve.h"

/* Largest grid accepted by pc_oracle_surface_closest. */
#define PC_ORACLE_MAX_GRID 200

/* Distance from p to the surface and its parameters uv: a grid of n
 * uniform intervals per direction (n <= PC_ORACLE_MAX_GRID) refined with 8
 * samples per knot span, then shrinking 3x3 stencils clamped to the domain
 * (so minima on edges and corners land on them exactly) from every sample
 * no neighbour of which is nearer. A basin narrower than the local sample
 * spacing can be missed. */
double pc_oracle_surface_closest(const projcurve_surface *s, const double p[3], int n,
                                 double uv[2]);

#endif /* PC_TEST_CLOSEST_ORACLE_H */
