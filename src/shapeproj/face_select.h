/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Which faces of a shape a projection can reach.
 *
 * Directional: the faces whose 3D box meets the curve's box swept along
 * +Dir, {b + lambda Dir : b in box(P), lambda >= 0}. Per axis i the two
 * boxes overlap for lambda in an interval (all lambda or none where
 * Dir_i = 0); the face is a candidate when the intersection of the three
 * intervals meets [0, inf). The curve's box is that of its control points
 * (the curve lies in their convex hull); a callback curve has no bound,
 * so every face is a candidate. The faces are a list of boxes (brep/shape.h):
 * a scan, linear in the face count (a few hundred boxes, microseconds).
 * Orthogonal: every face (a foot point may lie on any face).
 */
#ifndef PC_SHAPEPROJ_FACE_SELECT_H
#define PC_SHAPEPROJ_FACE_SELECT_H

#include "faceproj/surface_projection.h"

/* 1 when the face box (6 doubles) may hold a projection of the curve box. */
int pc_swept_box_meets(const double curve_box[6], pc_vec3 dir, const double face_box[6]);

/* The curve's box from its control points: 1, or 0 for a callback curve. */
int pc_curve_box(const projcurve_curve *curve, double box[6]);

#endif /* PC_SHAPEPROJ_FACE_SELECT_H */
