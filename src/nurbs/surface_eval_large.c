/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Surface evaluation for degrees above PC_SMALL_DEGREE, and the contraction
 * of a block with given basis tables (shared with Bezier patch evaluation):
 * the generic basis routine with PC_MAX_ORDER-wide tables. Rare in practice
 * (the small path in surface_eval.c takes degrees up to 7), so written for
 * generality, not speed.
 */
#include "nurbs/basis_impl.h"
#include "nurbs/nurbs.h"
#include "nurbs/surface_block.h"
#include "nurbs/surface_eval_large.h"

void pc_surface_block_eval(const double *net, size_t stride, int p, int q, int n_deriv,
                           const pc_basis *bu, const pc_basis *bv, int rational, pc_vec3 *out)
{
    double a[PC_D_COUNT][4];
    pc_block_contract(net, stride, p, q, n_deriv, bu->d[0], bv->d[0], PC_MAX_ORDER, a);
    pc_block_finish(a, n_deriv, rational, out);
}

void pc_surface_eval_large(const pc_nurbs_surface *s, double u, double v, size_t span_u,
                           size_t span_v, int n_deriv, pc_vec3 *out)
{
    const int p = s->deg_u, q = s->deg_v;
    const double *inv_u =
        s->inv_u != NULL ? s->inv_u + (span_u - (size_t)p) * pc_knot_inverse_count(p) : NULL;
    const double *inv_v =
        s->inv_v != NULL ? s->inv_v + (span_v - (size_t)q) * pc_knot_inverse_count(q) : NULL;
    pc_basis bu, bv;
    pc_basis_ders_inline(s->knots_u, span_u, p, u, n_deriv, &bu, inv_u);
    pc_basis_ders_inline(s->knots_v, span_v, q, v, n_deriv, &bv, inv_v);
    const size_t first = (span_v - (size_t)q) * s->n_u + (span_u - (size_t)p);
    pc_surface_block_eval(s->cw + 4 * first, 4 * s->n_u, p, q, n_deriv, &bu, &bv, s->rational,
                          out);
}
