/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The exact composition of a branch's compact pcurve q with its surface S:
 * S o q as one NURBS curve, on S to rounding (docs/fit.md, "The exact
 * composition"). q is cut at its own knots, at its seam jumps and where
 * it crosses a knot line of S; each Bezier piece, in one patch's box, is
 * composed with that patch (compose/compose_poly.c), and the pieces are
 * joined with knots of multiplicity the degree.
 */
#ifndef PC_EXACT_H
#define PC_EXACT_H

#include "geom/surface.h"
#include "trace/result.h"

/* The pieces' knots: the t of q's knots and jumps, and the parameters s in
 * (0, 1) of a Bezier piece where it crosses a knot line, closer than this
 * fraction of the piece's range to another or to its ends, are one (a
 * sliver of 1e-12 composed with the neighbouring patch is the patch's
 * polynomial continued by that much: a change far below rounding). */
#define PC_EXACT_MIN_GAP 1e-12

/* S o q for b's compact pcurve q (polynomial, degree 1..3; unwrapped
 * across b's seams, seam/seam.h) on surface s, into *out (dim 3, degree
 * deg(q) (p + q), weights NULL when S is polynomial; every knot inside
 * of multiplicity the degree). Statuses: OK, NO_MEMORY, OVERFLOW,
 * UNSUPPORTED (q rational or above cubic: the curve's own space; or a
 * degree above PROJCURVE_MAX_DEGREE), NOT_CONVERGED (more knot-line
 * crossings in one piece than a cubic has roots: not expected), each
 * recorded in ctx. */
projcurve_status pc_exact_compose(projcurve_context *ctx, const projcurve_surface *s,
                                  const pc_branch *b, pc_bspline *out);

/* Appends to roots (at most cap) the parameters s in (0, 1) where the
 * polynomial of degree d (<= 3) with Bernstein coefficients f changes
 * sign, to ~2^-52 of [0, 1], in increasing s. Returns how many, or
 * (size_t)-1 when there were more than cap. */
size_t pc_exact_sign_changes(int d, const double *f, double *roots, size_t cap);

#endif /* PC_EXACT_H */
