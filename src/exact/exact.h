/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The exact composition of a branch's compact pcurve q with its surface S:
 * S o q as one NURBS curve, on S to rounding (docs/fit.md, "The exact
 * composition"). q is cut at its own knots, at its seam jumps and where
 * it crosses a knot line of S; each Bezier piece, in one patch's box, is
 * composed with that patch (compose/compose_poly.c), the pieces are
 * joined with knots of multiplicity the degree, and copies of those knots
 * are removed where the curve is smoother than that to rounding
 * (join_removal.c).
 */
#ifndef PC_EXACT_H
#define PC_EXACT_H

#include "geom/surface.h"
#include "nurbs/knot_removal.h"
#include "trace/result.h"

/* The pieces' knots: the t of q's knots and jumps, and the parameters s in
 * (0, 1) of a Bezier piece where it crosses a knot line, closer than this
 * fraction of the piece's range to another or to its ends, are one (a
 * sliver of 1e-12 composed with the neighbouring patch is the patch's
 * polynomial continued by that much: a change far below rounding). */
#define PC_EXACT_MIN_GAP 1e-12

/* The change the removal of join knots may make, in ulps of the
 * composed curve's largest pole: the level of the composed poles' own
 * rounding (a few hundred ulps at degree 18, tests/api/
 * test_api_compact_exact.c), so that the curve stays on S to rounding. */
#define PC_EXACT_REMOVAL_ULPS 256.0

/* S o q for b's compact pcurve q (degree 1..3, polynomial or rational
 * with positive weights; unwrapped across b's seams, seam/seam.h) on
 * surface s, into *out (dim 3, degree deg(q) (p + q), weights NULL when S
 * and q are polynomial; the knots inside of multiplicity the degree at
 * the joins where the two sides meet only C0 by construction, lower
 * where the curve is smoother, join_removal.c; within
 * PC_EXACT_REMOVAL_ULPS of the parts as composed). Statuses: OK,
 * NO_MEMORY, OVERFLOW, UNSUPPORTED (q above cubic or with a weight <= 0:
 * the curve's own space; or a degree above PROJCURVE_MAX_DEGREE),
 * NOT_CONVERGED (more knot-line
 * crossings in one piece than a cubic has roots: not expected), each
 * recorded in ctx. */
projcurve_status pc_exact_compose(projcurve_context *ctx, const projcurve_surface *s,
                                  const pc_branch *b, pc_bspline *out);

/* Appends to roots (at most cap) the parameters s in (0, 1) where the
 * polynomial of degree d (<= 3) with Bernstein coefficients f changes
 * sign, to ~2^-52 of [0, 1], in increasing s. Returns how many, or
 * (size_t)-1 when there were more than cap. */
size_t pc_exact_sign_changes(int d, const double *f, double *roots, size_t cap);

/* Removes copies of the join knots of the composed curve c (degree n,
 * n_parts Bezier parts joined with knots of multiplicity n; poles
 * Cartesian, or homogeneous for a rational curve) while the curve moves
 * by at most tol (in the poles' space) from c as given, at every t:
 * copies of join k (between parts k and k + 1) only where smooth[k] is
 * nonzero; smooth is overwritten (zero where a removal was refused).
 * scratch: 2 n_parts + 1 doubles. No allocation. Returns the number of
 * copies removed (c->n_poles is that much smaller; the arrays keep their
 * size). Nothing is removed (0) when c is not such a curve. */
size_t pc_exact_reduce_joins(pc_knot_curve *c, unsigned char *smooth, size_t n_parts, double tol,
                             double *scratch);

#endif /* PC_EXACT_H */
