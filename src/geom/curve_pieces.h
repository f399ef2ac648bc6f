/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Bounds of a curve over a stretch of its parameter: the box of the
 * control points of the curve restricted to [ta, tb] (its Bezier segments
 * cut there by de Casteljau). A NURBS curve with positive weights lies in
 * the convex hull of those points, so the box holds the curve over [ta,
 * tb]; the box shrinks onto the curve as tb - ta does (unlike the box of
 * the control points whose spans cover [ta, tb], which stays that of a
 * whole segment). A callback curve, or a weight <= 0 (no convex hull
 * property), has no such bound.
 */
#ifndef PC_GEOM_CURVE_PIECES_H
#define PC_GEOM_CURVE_PIECES_H

#include "bezier/bezier.h"
#include "geom/curve.h"

typedef struct pc_curve_pieces {
    pc_bezier_curves bz;  /* n_segments 0: the curve has no bound */
} pc_curve_pieces;

/* The Bezier segments of c (none for the unbounded curves above).
 * Statuses: OK, NO_MEMORY, OVERFLOW. */
projcurve_status pc_curve_pieces_build(projcurve_context *ctx, const projcurve_curve *c,
                                       pc_curve_pieces *out);
void pc_curve_pieces_free(pc_curve_pieces *p);

/* The control-point box of the curve over [ta, tb] (ta <= tb, clamped to
 * the domain) into box, and its points at ta and tb (exactly the first and
 * last control points of the cut segments) into ends[0], ends[1]. Returns
 * 1, or 0 when the curve has no bound. No allocation; the work is one
 * de Casteljau cut per end and a box per segment in between. */
int pc_curve_pieces_box(const pc_curve_pieces *p, double ta, double tb, double box[6],
                        pc_vec3 ends[2]);

/* The range [range[0], range[1]] of value(user, c) over the cut control
 * points c of the curve over [ta, tb] (as pc_curve_pieces_box). A value
 * that is affine, or projective and positive-depth over those points,
 * bounds the curve over [ta, tb] by that range (their hull holds the
 * curve). Returns 1, or 0 when the curve has no bound. */
typedef double (*pc_piece_value_fn)(const void *user, pc_vec3 c);
int pc_curve_pieces_range(const pc_curve_pieces *p, double ta, double tb,
                          pc_piece_value_fn value, const void *user, double range[2]);

#endif /* PC_GEOM_CURVE_PIECES_H */
