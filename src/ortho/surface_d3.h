/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * NURBS surface point with every partial derivative up to total order 3.
 *
 * The orthogonal projection's second-order predictor needs q'' ([PW96]
 * eq. (16) differentiated once more), which contains the third partial
 * derivatives of S: the time derivative of the projective tensor
 * K_ij = S_i.S_j + (S - P).S_ij involves (S - P).S_ijk. nurbs/ evaluates up
 * to order 2 only, so this file evaluates order 3 exactly, instead of
 * differencing second derivatives: by Horner's scheme on the span's
 * monomial form when nurbs/ keeps one (degrees <= 5, nurbs/span_poly.h),
 * else from the homogeneous control net (basis function derivatives); then
 * the quotient rule for rational surfaces.
 */
#ifndef PC_ORTHO_SURFACE_D3_H
#define PC_ORTHO_SURFACE_D3_H

#include <stddef.h>

#include "common/vec.h"
#include "nurbs/nurbs.h"

/* Number of entries written by pc_surface_eval_d3. */
#define PC_D3_COUNT 10

/* Index of each partial derivative in the output array. */
enum {
    PC_D3_S = 0,
    PC_D3_U = 1, PC_D3_V = 2,
    PC_D3_UU = 3, PC_D3_UV = 4, PC_D3_VV = 5,
    PC_D3_UUU = 6, PC_D3_UUV = 7, PC_D3_UVV = 8, PC_D3_VVV = 9
};

/* S and its partial derivatives up to total order 3 at (u, v), clamped to
 * the domain: out[PC_D3_S .. PC_D3_VVV]. hint_u / hint_v (may be NULL) are
 * knot span hints as for pc_nurbs_surface_eval. No allocation; uses about
 * 8 KB of stack for degrees up to PROJCURVE_MAX_DEGREE. */
void pc_surface_eval_d3(const pc_nurbs_surface *s, double u, double v, size_t *hint_u,
                        size_t *hint_v, pc_vec3 out[PC_D3_COUNT]);

#endif /* PC_ORTHO_SURFACE_D3_H */
