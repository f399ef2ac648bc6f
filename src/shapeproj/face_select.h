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
 * so every face is a candidate. The shape's face BVH (brep/shape_bvh.h)
 * prunes the faces: the test holds for a node's box whenever it holds for
 * a box inside it.
 * Conical from the eye E: the faces whose box meets the cone from E over
 * the curve's box beyond the curve, {E + mu (b - E) : b in box(P), mu >=
 * 1}, which holds every ray from E through P(t) beyond P(t). For one mu
 * that set is a box whose sides are linear in mu, so per axis the face
 * box overlaps it for mu on an intersection of two half-lines; the face is
 * a candidate when the three meet [1, inf). The test is exact for the
 * cone over the box (conservative for the curve: the box holds the
 * curve), needs no bound on the shape's extent, and holds for a BVH node
 * whenever it holds for a box inside it. An eye inside the curve's box
 * makes every face a candidate (the cone is all of space).
 * Orthogonal: every face (a foot point may lie on any face).
 * The box tests themselves are geom/box_reach.h.
 */
#ifndef PC_SHAPEPROJ_FACE_SELECT_H
#define PC_SHAPEPROJ_FACE_SELECT_H

#include "faceproj/surface_projection.h"
#include "geom/box_reach.h"

/* The curve's box from its control points: 1, or 0 for a callback curve. */
int pc_curve_box(const projcurve_curve *curve, double box[6]);

#endif /* PC_SHAPEPROJ_FACE_SELECT_H */
