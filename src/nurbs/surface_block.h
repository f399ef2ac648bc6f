/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The tensor contraction behind every surface evaluation, as always-inlined
 * functions of the degrees, the derivative order and the width of the basis
 * tables, so that each caller instantiates it with its own constants.
 */
#ifndef PC_NURBS_SURFACE_BLOCK_H
#define PC_NURBS_SURFACE_BLOCK_H

#include "nurbs/basis_impl.h"
#include "nurbs/nurbs.h"

/* Homogeneous derivatives A_{kl} = d^{k+l} (w S) / du^k dv^l, 4 doubles each,
 * in the output order S, Su, Sv, Suu, Suv, Svv. */
enum { PC_D00, PC_D10, PC_D01, PC_D20, PC_D11, PC_D02, PC_D_COUNT };

/* Contracts the (p+1) x (q+1) homogeneous net block at `net` (row stride
 * `stride` doubles) with the basis tables bu, bv (row k, the k-th
 * derivatives, at bu + k * width). Per row of the block the n_deriv + 1
 * u-sums first, then their combinations with the v basis: (p+1)(q+1)(n+1)
 * + (q+1)(n+1)(n+2)/2 four-vector multiply-adds. All four homogeneous
 * coordinates are summed even for polynomial surfaces: one 4-wide vector
 * operation costs the same as three scalar ones. */
static PC_ALWAYS_INLINE void pc_block_contract(const double *net, size_t stride, int p, int q,
                                               int n_deriv, const double *bu,
                                               const double *bv, int width,
                                               double a[PC_D_COUNT][4])
{
    const int count = n_deriv == 0 ? 1 : (n_deriv == 1 ? 3 : 6);
    for (int d = 0; d < count; ++d)
        for (int m = 0; m < 4; ++m)
            a[d][m] = 0.0;
    PC_UNROLL
    for (int j = 0; j <= q; ++j) {
        const double *row = net + (size_t)j * stride;
        double r0[4] = {0, 0, 0, 0}, r1[4] = {0, 0, 0, 0}, r2[4] = {0, 0, 0, 0};
        PC_UNROLL
        for (int i = 0; i <= p; ++i) {
            const double *pt = row + 4 * i;
            for (int m = 0; m < 4; ++m) {
                r0[m] += bu[i] * pt[m];
                if (n_deriv >= 1)
                    r1[m] += bu[width + i] * pt[m];
                if (n_deriv >= 2)
                    r2[m] += bu[2 * width + i] * pt[m];
            }
        }
        const double v0 = bv[j];
        const double v1 = n_deriv >= 1 ? bv[width + j] : 0.0;
        const double v2 = n_deriv >= 2 ? bv[2 * width + j] : 0.0;
        for (int m = 0; m < 4; ++m) {
            a[PC_D00][m] += v0 * r0[m];
            if (n_deriv >= 1) {
                a[PC_D10][m] += v0 * r1[m];
                a[PC_D01][m] += v1 * r0[m];
            }
            if (n_deriv >= 2) {
                a[PC_D20][m] += v0 * r2[m];
                a[PC_D11][m] += v1 * r1[m];
                a[PC_D02][m] += v2 * r0[m];
            }
        }
    }
}

static inline pc_vec3 pc_block_xyz(const double h[4]) { return vec3(h[0], h[1], h[2]); }

/* S and its derivatives from the homogeneous ones: copied when the surface
 * is polynomial (w = 1), else by the quotient rule for S = A / w (The NURBS
 * Book, eq. 4.20). */
static PC_ALWAYS_INLINE void pc_block_finish(double a[PC_D_COUNT][4], int n_deriv,
                                             int rational, pc_vec3 *out)
{
    if (!rational) {
        const int count = n_deriv == 0 ? 1 : (n_deriv == 1 ? 3 : 6);
        for (int d = 0; d < count; ++d)
            out[d] = pc_block_xyz(a[d]);
        return;
    }
    const double inv_w = 1.0 / a[PC_D00][3];
    const pc_vec3 s = vec3_scale(pc_block_xyz(a[PC_D00]), inv_w);
    out[0] = s;
    if (n_deriv < 1)
        return;
    const double wu = a[PC_D10][3], wv = a[PC_D01][3];
    const pc_vec3 su = vec3_scale(vec3_axpy(pc_block_xyz(a[PC_D10]), -wu, s), inv_w);
    const pc_vec3 sv = vec3_scale(vec3_axpy(pc_block_xyz(a[PC_D01]), -wv, s), inv_w);
    out[1] = su;
    out[2] = sv;
    if (n_deriv < 2)
        return;
    const pc_vec3 suu =
        vec3_axpy(vec3_axpy(pc_block_xyz(a[PC_D20]), -2.0 * wu, su), -a[PC_D20][3], s);
    const pc_vec3 suv = vec3_axpy(
        vec3_axpy(vec3_axpy(pc_block_xyz(a[PC_D11]), -wu, sv), -wv, su), -a[PC_D11][3], s);
    const pc_vec3 svv =
        vec3_axpy(vec3_axpy(pc_block_xyz(a[PC_D02]), -2.0 * wv, sv), -a[PC_D02][3], s);
    out[3] = vec3_scale(suu, inv_w);
    out[4] = vec3_scale(suv, inv_w);
    out[5] = vec3_scale(svv, inv_w);
}

#endif /* PC_NURBS_SURFACE_BLOCK_H */
