/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * B-spline basis functions and derivatives: the generic instance of
 * basis_impl.h (The NURBS Book A2.2 and eq. 2.7).
 */
#include "nurbs/basis_impl.h"

void pc_basis_ders(const double *knots, size_t span, int degree, double t, int n_deriv,
                   pc_basis *out)
{
    pc_basis_ders_inline(knots, span, degree, t, n_deriv, out, NULL);
}
