/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Boxes of the tangent vectors Su and Sv over every node of the patch BVH
 * (bvh.h), built once per surface handle. With the node's box of S they
 * bound (S - p).Su and (S - p).Sv over the node by interval arithmetic, so
 * that a search for every foot point of p (point/foot_points.c) skips whole
 * subtrees where one of them keeps its sign, instead of testing every patch.
 *
 * Over a Bezier patch, Su is the Bezier patch of the u-hodograph: control
 * points p (P_i+1,j - P_ij) / (u1 - u0) (The NURBS Book eq. (3.8) on a
 * Bezier span), so by the convex hull property their box bounds Su; likewise
 * Sv. A node's box is the union of its patches'. Rational surfaces get no
 * boxes (the quotient rule would need bounds of the weights too): their
 * searches test every patch.
 */
#ifndef PC_BEZIER_TANGENT_BOXES_H
#define PC_BEZIER_TANGENT_BOXES_H

#include "bezier/bezier.h"
#include "bezier/bvh.h"

typedef struct pc_tangent_boxes {
    /* 12 per BVH node: the box of Su (min xyz, max xyz), then that of Sv;
     * NULL for a rational surface */
    double *node;
} pc_tangent_boxes;

/* Statuses: OK, NO_MEMORY. A rational grid gives OK with node == NULL. */
projcurve_status pc_tangent_boxes_build(projcurve_context *ctx, pc_tangent_boxes *tb,
                                        const pc_bvh *bvh, const pc_patch_grid *grid,
                                        int rational);
void pc_tangent_boxes_free(pc_tangent_boxes *tb);

/* Whether (S - p).Su and (S - p).Sv may both vanish over BVH node k (an
 * interval enclosure of each over the node's boxes contains 0); 1 when the
 * surface has no tangent boxes. */
int pc_tangent_boxes_may_hold_foot(const pc_tangent_boxes *tb, const pc_bvh *bvh, size_t k,
                                   pc_vec3 p);

#endif /* PC_BEZIER_TANGENT_BOXES_H */
