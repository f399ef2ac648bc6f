/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Cutting what a branch carries at a loop crossing, exactly: a composed
 * piece (a rational Bezier curve S(uv(s)) and its pcurve uv(s)) by de
 * Casteljau subdivision of both at the same s, so that the part kept is
 * still S composed with its pcurve; a compact B-spline by knot insertion
 * (Boehm) to the kept t range.
 */
#ifndef PC_FACEPROJ_PIECE_CUT_H
#define PC_FACEPROJ_PIECE_CUT_H

#include "faceproj/loop_samples.h"
#include "trace/result.h"

/* Iterations to place a piece's cut on the loop piece. */
#define PC_CUT_MAX_ITER 30

/* The s in [0, 1] where the pcurve of piece meets loop piece `which` of s
 * near the crossing (t_cut, tau): Newton on uv(s) = c(tau) from the s of
 * t_cut, the linear guess itself when Newton does not converge. */
double pc_piece_cut_parameter(const pc_piece *piece, const pc_loop_samples *s, size_t which,
                              double t_cut, double tau);

/* The s in [0, 1] where the pcurve of piece passes nearest the point uv
 * (a cut not on a loop, e.g. where another face becomes nearer): Gauss-
 * Newton on (uv(s) - uv) . uv'(s) = 0 from the s of t_cut, at most
 * PC_CUT_MAX_ITER steps (the last iterate at the bound; the pcurve is a
 * Bezier curve of degree <= 3 near uv, so it converges in a few). */
double pc_piece_point_parameter(const pc_piece *piece, double t_cut, const double uv[2]);

/* Appends to b the part s in [s0, s1] of piece (0 <= s0 < s1 <= 1) over
 * the curve parameters [t0, t1]. Statuses: OK, NO_MEMORY. */
projcurve_status pc_piece_append_part(projcurve_context *ctx, pc_branch *b, const pc_piece *piece,
                                      double s0, double s1, double t0, double t1);

/* *out = in restricted to [a, b] inside its domain (a < b), poles and
 * weights by knot insertion; in with no poles gives none. Statuses: OK,
 * NO_MEMORY. */
projcurve_status pc_bspline_restrict(projcurve_context *ctx, const pc_bspline *in, double a,
                                     double b, pc_bspline *out);

#endif /* PC_FACEPROJ_PIECE_CUT_H */
