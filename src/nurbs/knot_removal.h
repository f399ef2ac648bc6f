/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Removal of one copy of an interior knot of a B-spline curve (the
 * inverse of Boehm's insertion; The NURBS Book, section 5.4), for poles
 * of any dimension: Cartesian, or homogeneous (x w, y w, z w, w) for a
 * rational curve. No allocation: the caller's arrays and scratch.
 */
#ifndef PC_NURBS_KNOT_REMOVAL_H
#define PC_NURBS_KNOT_REMOVAL_H

#include <stddef.h>

/* A curve in the caller's arrays: degree p, n_poles poles of dim doubles
 * each (contiguous), n_poles + p + 1 clamped knots. */
typedef struct pc_knot_curve {
    int degree, dim;
    size_t n_poles;
    double *knots;
    double *poles;
} pc_knot_curve;

/* Solves for the poles of c without one copy of the knot u = knots[r],
 * r the index of its last copy (knots[r] < knots[r + 1]), u interior
 * (knots[p] < u < knots[n_poles]) of multiplicity s <= p. The s' = p - s
 * new poles of the affected range are written to fresh (p * dim doubles
 * at most): those of the first half solved from the left end of the
 * range, the others from the right, so that the one equation left over
 * is in the middle. c is not changed.
 *
 * Returns the largest distance between a pole of c and the same pole of
 * the new curve with the knot inserted back (every equation of the
 * insertion checked, in floating point): by the partition of unity of
 * the basis, a bound of |C_new(t) - C(t)| in the poles' space, nonzero
 * for t only in (knots[r - p], knots[r - s + p + 1]). Zero to rounding
 * where C is C^(p - s + 1) at u; large where it is not. INFINITY when r
 * is not such a knot. */
double pc_knot_removal_solve(const pc_knot_curve *c, size_t r, double *fresh);

/* Commits the removal solved by pc_knot_removal_solve(c, r, fresh): the
 * affected poles replaced by fresh, the later ones and knots moved down
 * one place, c->n_poles decreased by one. */
void pc_knot_removal_apply(pc_knot_curve *c, size_t r, const double *fresh);

#endif /* PC_NURBS_KNOT_REMOVAL_H */
