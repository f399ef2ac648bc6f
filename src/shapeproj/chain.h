/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Chaining face pieces into connected curves.
 *
 * A piece A that ends on a loop piece with edge id e (END_TRIM) continues
 * with the piece B that starts on a loop piece of the same edge id
 * (START_TRIM; the shape's edge uses are exactly the loop pieces of one
 * id) whose start is within the chaining tolerance of A's end both in 3D
 * (S_A(end) against S_B(start)) and on the curve (P(t_A) against P(t_B));
 * of several, the nearest in 3D, then the lowest (face, branch). On a
 * closed curve (its ends within the tolerance) the piece that ends the
 * curve (END_CURVE_END) continues with the piece of the same face that
 * starts it (START_CURVE_START) at the same point. Chains
 * start at pieces no other continues into; what is left are closed loops
 * of pieces, started at their piece of smallest t. Connected curves are
 * sorted by the smallest t of their first piece, then by the distance of
 * its first point from the curve along Dir (orthogonal: the distance),
 * then by (face, branch) of that piece.
 */
#ifndef PC_SHAPEPROJ_CHAIN_H
#define PC_SHAPEPROJ_CHAIN_H

#include "faceproj/surface_projection.h"
#include "shapeproj/shape_result.h"

/* Fills r's refs and curves from its parts; shape (NULL for a lone face)
 * tells the ends with no continuation that are gaps (counted in
 * r->open_ends, see projcurve_shape_result_open_end_count) from free
 * borders and silhouettes. Statuses: OK, NO_MEMORY, CALLBACK (the curve could not be
 * evaluated). */
projcurve_status pc_chain_pieces(projcurve_context *ctx, projcurve_shape_result *r,
                                 const projcurve_shape *shape, const projcurve_curve *curve,
                                 const pc_projection_spec *spec);

#endif /* PC_SHAPEPROJ_CHAIN_H */
