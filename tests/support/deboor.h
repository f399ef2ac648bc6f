/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * An independent oracle for spline evaluation: de Boor's algorithm on the
 * raw (possibly unclamped) user data, for points and, on the differentiated
 * control polygon, for derivatives. Shared by tests that need to check
 * evaluation without trusting the library's basis functions.
 */
#ifndef PC_TEST_DEBOOR_H
#define PC_TEST_DEBOOR_H

#include <stddef.h>

#include "shapes.h"

/* C(t) of a curve given as user arrays (weights may be NULL), t in
 * [knots[degree], knots[n_ctrl]]. */
void pc_deboor_curve(const pc_shape_curve *c, double t, double out[3]);

/* S(u, v) of a surface given as user arrays. */
void pc_deboor_surface(const pc_shape_surface *s, double u, double v, double out[3]);

/* Highest curve derivative order of pc_deboor_curve_ders. */
#define PC_DEBOOR_MAX_DERIV 3

/* C and its derivatives up to n_deriv (<= PC_DEBOOR_MAX_DERIV) at t:
 * out[3 k .. 3 k + 2] = C^(k)(t). */
void pc_deboor_curve_ders(const pc_shape_curve *c, double t, int n_deriv, double *out);

/* S, Su, Sv, Suu, Suv, Svv at (u, v), 3 doubles each. */
void pc_deboor_surface_ders(const pc_shape_surface *s, double u, double v, double out[18]);

#endif /* PC_TEST_DEBOOR_H */
