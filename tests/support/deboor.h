/*
 * An independent oracle for spline evaluation: de Boor's algorithm on the
 * raw (possibly unclamped) user data, points only. Shared by tests that need
 * to check evaluation without trusting the library's basis functions.
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

#endif /* PC_TEST_DEBOOR_H */
