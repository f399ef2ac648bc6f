/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Which boxes the rays of a projection can reach from a box of the curve:
 * the exact box tests shared by the face selection of shapes
 * (shapeproj/face_select.h), the curve ranges reaching a face
 * (shapeproj/t_ranges.h) and the jump sweep's step narrowing (trace/).
 *
 * Directional: box F meets the curve's box B swept along +Dir, {b + lambda
 * Dir : b in B, lambda >= 0}. Per axis i the two boxes overlap for lambda
 * in an interval (all lambda or none where Dir_i = 0); F is reached when
 * the intersection of the three intervals meets [0, inf).
 * Conical from the eye E: F meets the cone from E over B beyond B, {E + mu
 * (b - E) : b in B, mu >= 1}, which holds every ray from E through a point
 * of B beyond that point. For one mu that set is a box whose sides are
 * linear in mu, so per axis F overlaps it for mu on an intersection of two
 * half-lines; F is reached when the three meet [1, inf). An eye inside B
 * makes every box reached (the cone is all of space).
 * Both tests are exact for the boxes (conservative for what the boxes
 * bound), and hold for a box whenever they hold for a box inside it: a
 * bounding-volume hierarchy can prune with them. A degenerate B (one
 * point, lo = hi) tests the ray of that point.
 */
#ifndef PC_GEOM_BOX_REACH_H
#define PC_GEOM_BOX_REACH_H

#include "common/vec.h"

/* 1 when box f (6 doubles: lo xyz, hi xyz) meets box b swept along +dir. */
int pc_swept_box_meets(const double b[6], pc_vec3 dir, const double f[6]);

/* The same as a pc_box_test of a BVH, user a pc_swept_box. */
typedef struct pc_swept_box {
    double curve_box[6];
    pc_vec3 dir;
} pc_swept_box;
int pc_swept_box_test(const void *user, const double box[6]);

/* 1 when box f meets the cone from eye over box b, beyond b. */
int pc_cone_box_meets(const double b[6], pc_vec3 eye, const double f[6]);

/* A pc_box_test of a BVH for the cone, user a pc_cone_box. */
typedef struct pc_cone_box {
    double curve_box[6];
    pc_vec3 eye;
} pc_cone_box;
int pc_cone_box_test(const void *user, const double box[6]);

#endif /* PC_GEOM_BOX_REACH_H */
