/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A bounding-volume hierarchy over the 3D boxes of a shape's faces, for
 * the queries "which faces may a set meet" (the projection onto a shape
 * asks for the faces a swept curve box can reach): a binary tree split at
 * the median of the box centres along the longest axis, leaves of at most
 * PC_FACE_BVH_LEAF faces. A query visits O(log n + k) nodes for k faces
 * found when the set is small.
 */
#ifndef PC_BREP_SHAPE_BVH_H
#define PC_BREP_SHAPE_BVH_H

#include <stddef.h>

#include "projcurve.h"

#define PC_FACE_BVH_LEAF 4

typedef struct pc_face_bvh_node {
    double box[6];
    size_t first, count; /* a leaf: order[first .. first + count) */
    size_t left, right;  /* an inner node (count 0): its children */
} pc_face_bvh_node;

typedef struct pc_face_bvh {
    pc_face_bvh_node *nodes;
    size_t n_nodes;
    size_t *order; /* face indices, leaf by leaf */
    const double *boxes; /* borrowed: the boxes it was built over */
    size_t n_faces;
} pc_face_bvh;

/* Builds the tree over n boxes (6 doubles each; borrowed, they must
 * outlive the tree). Statuses: OK, NO_MEMORY. */
projcurve_status pc_face_bvh_build(projcurve_context *ctx, pc_face_bvh *bvh, const double *boxes,
                                   size_t n);
void pc_face_bvh_free(pc_face_bvh *bvh);

/* A test on a box: 1 when the set asked about may meet it. It must hold
 * for a box whenever it holds for a box inside it (the nodes' boxes hold
 * their children's). */
typedef int (*pc_box_test)(const void *user, const double box[6]);

/* Writes to out (room for bvh->n_faces) the faces whose box passes test,
 * in increasing index order, and returns their number. */
size_t pc_face_bvh_query(const pc_face_bvh *bvh, pc_box_test test, const void *user,
                         size_t *out);

#endif /* PC_BREP_SHAPE_BVH_H */
